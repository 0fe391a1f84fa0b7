"""Mitsuba 3's own materials and textures, as this project's scene files name them.

| ours (docs/SCENE_FORMAT.md)                | Mitsuba 3                                            |
|--------------------------------------------|------------------------------------------------------|
| conductor, rough_conductor                 | conductor, roughconductor (same keys; material or    |
|                                            | eta/k, default material "none")                      |
| rough_dielectric, thin_dielectric          | roughdielectric, thindielectric (index names as      |
|                                            | Mitsuba's, lower case)                               |
| plastic, rough_plastic (nonlinear)         | plastic, roughplastic                                |
| two_sided (front, back = front)            | twosided with one or two nested bsdfs                |
| normal_map (normal_map, material)          | normalmap, flip_invalid_normals = false,             |
|                                            | use_shadowing_function = false (our docs' handling)  |
| checkerboard texture, colour key           | checkerboard, color0/color1 as written, to_uv        |
| checkerboard texture, scalar key (alpha)   | checkerboard with color0 and color1 SWAPPED: Mitsuba's|
|                                            | eval_1 swaps them (test_textures.py); each made grey |
|                                            | of its first channel (ours reads that, eval_1 the    |
|                                            | mean)                                                |
| image texture (wrap, raw, scale, offset)   | bitmap, wrap_mode, raw, bilinear, to_uv              |
| texture scale s, offset o: (s u + o)       | to_uv = translate(o) . scale(s)                      |

The materials are Mitsuba's definitions in our renderer, under Mitsuba's parameter names, so
most keys pass through; what needs a decision is said where it is made.
"""

from __future__ import annotations

import mitsuba as mi

# Keys that hold a colour or a colour texture, and those that hold a scalar (alpha).
COLOUR_KEYS = ("specular_reflectance", "specular_transmittance", "diffuse_reflectance")
ALPHA_KEYS = ("alpha", "alpha_u", "alpha_v")
MITSUBA_TYPE = {"conductor": "conductor", "rough_conductor": "roughconductor",
                "rough_dielectric": "roughdielectric", "thin_dielectric": "thindielectric",
                "plastic": "plastic", "rough_plastic": "roughplastic"}
# Our documented defaults where they must be written out for Mitsuba.
IOR_DEFAULTS = {"rough_dielectric": ("bk7", "air"), "thin_dielectric": ("bk7", "air"),
                "plastic": ("polypropylene", "air"), "rough_plastic": ("polypropylene", "air")}


def rgb(v) -> dict:
    return {"type": "rgb", "value": [float(x) for x in v]}


def to_uv(t: dict) -> mi.ScalarTransform3f:
    """Our lookup at (s_u u + o_u, s_v v + o_v): scale first, then the offset."""
    s = t.get("scale", 1.0)
    s = [float(s), float(s)] if not isinstance(s, list) else [float(x) for x in s]
    o = [float(x) for x in t.get("offset", [0.0, 0.0])]
    return mi.ScalarTransform3f().translate(o).scale(s)


def texture(value, textures: dict, scalar: bool = False, normal_map: bool = False):
    """A colour key's value (a colour, a texture's name, or a table in place) for Mitsuba.
    `scalar`: the key is read through Mitsuba's eval_1 (alpha); `normal_map`: an image is
    data unless it says raw = false."""
    if isinstance(value, (int, float)):
        return float(value)
    if isinstance(value, list):
        return rgb(value)
    t = textures[value] if isinstance(value, str) else value
    if t["type"] == "checkerboard":
        c0, c1 = t.get("color0", [0.4] * 3), t.get("color1", [0.2] * 3)
        if scalar:
            # Mitsuba's scalar lookup (eval_1) returns color1 where its colour lookup
            # returns color0; ours does not swap (docs/SCENE_FORMAT.md). Swapping here makes
            # both renderers give the same alpha at every uv (test_textures.py).
            # And its eval_1 of an RGB colour is the channels' mean, where ours reads the
            # first channel: grey colours of that channel give both the same number.
            c0, c1 = [float(c1[0])] * 3, [float(c0[0])] * 3
        return {"type": "checkerboard", "color0": rgb(c0), "color1": rgb(c1), "to_uv": to_uv(t)}
    if t["type"] == "image":
        return {"type": "bitmap", "filename": t["file"], "raw": bool(t.get("raw", normal_map)),
                "wrap_mode": t.get("wrap", "repeat"), "filter_type": "bilinear",
                "to_uv": to_uv(t)}
    raise ValueError(f"unknown texture type {t['type']!r}")


def _ior(v):
    return v.lower() if isinstance(v, str) else float(v)


def mitsuba_bsdf(m: dict, textures: dict, materials: dict, plain_bsdf) -> dict:
    """One of Mitsuba's own materials. `plain_bsdf(m)` converts any material (the
    converter's bsdf, for normal_map's and two_sided's nested ones)."""
    kind = m["type"]
    if kind == "two_sided":
        front = plain_bsdf(m["front"])
        out = {"type": "twosided", "bsdf_0": front}
        if "back" in m:  # Mitsuba: the first nested bsdf faces front, the second back
            out["bsdf_1"] = plain_bsdf(m["back"])
        return out
    if kind == "normal_map":
        return {"type": "normalmap",
                "normalmap": texture(m["normal_map"], textures, normal_map=True),
                "bsdf": plain_bsdf(materials[m["material"]]),
                # Our handling of a normal that faces away (docs/SCENE_FORMAT.md): no
                # mirroring toward the viewer, no extra shadowing factor.
                "flip_invalid_normals": False, "use_shadowing_function": False}
    out = {"type": MITSUBA_TYPE[kind]}
    if kind in ("conductor", "rough_conductor"):
        if "eta" in m or "k" in m:  # our defaults for the one not given
            out["eta"] = rgb(m.get("eta", [0.0, 0.0, 0.0]))
            out["k"] = rgb(m.get("k", [1.0, 1.0, 1.0]))
        else:
            out["material"] = m.get("material", "none")
    if kind in IOR_DEFAULTS:
        out["int_ior"] = _ior(m.get("int_ior", IOR_DEFAULTS[kind][0]))
        out["ext_ior"] = _ior(m.get("ext_ior", IOR_DEFAULTS[kind][1]))
    if kind.startswith("rough_"):
        out["distribution"] = m.get("distribution", "beckmann")
        alphas = [k for k in ALPHA_KEYS if k in m] or ["alpha"]
        for k in alphas:
            out[k] = texture(m.get(k, 0.1), textures, scalar=True)
    for k in COLOUR_KEYS:
        if k in m:
            out[k] = texture(m[k], textures)
    if kind in ("plastic", "rough_plastic"):
        out["nonlinear"] = bool(m.get("nonlinear", False))
        out.setdefault("diffuse_reflectance", rgb([0.5, 0.5, 0.5]))
    return out
