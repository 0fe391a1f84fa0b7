#!/usr/bin/env python3
"""Writes the XML twin of each scene file: scenes/NAME.toml -> scenes/NAME.xml, a Mitsuba 3
scene that `raytrace render` renders to the same bytes (tests/files/xml_twins.rs proves it).

    python3 tools/xml_twins.py            # every scenes/*.toml
    python3 tools/xml_twins.py --check    # exit 1 if a twin is missing or out of date

Standard library only. What Mitsuba has no word for is written with this renderer's
`raytrace_` extensions (docs/SCENE_FORMAT.md, "Extensions"): the spec's screen camera, the
sky, infinite planes, lone triangles, the spec's mirror, Schlick's Fresnel, and the
`[render]` keys Mitsuba has no place for (as `<default name="raytrace_...">`). Numbers are
written in Python's shortest round-trip form, so the importer reads the file's own doubles.
A feature with no exact twin stops the script with its reason.
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "scenes"


class NoTwin(Exception):
    """The scene uses something the XML cannot say exactly."""


def num(x) -> str:
    return repr(float(x)) if isinstance(x, float) else str(x)


def nums(v) -> str:
    return ", ".join(num(x) for x in v)


class Writer:
    def __init__(self, scene: dict):
        self.scene = scene
        self.lines: list[str] = []
        self.depth = 1
        self.compact = False  # one line per top-level element

    def put(self, text: str, closing: bool = False):
        if self.compact and (self.depth > 1 or closing):
            self.lines[-1] += text
        else:
            self.lines.append("    " * self.depth + text)

    def open(self, text: str):
        self.put(text)
        self.depth += 1

    def close(self, text: str):
        self.depth -= 1
        opening = text[2:-1]  # "</bsdf>" -> "bsdf"
        last = self.lines[-1]
        if last.lstrip().startswith(f"<{opening} ") and last.endswith('">') and \
                last.count("<") == 1:
            self.lines[-1] = last[:-1] + "/>"  # an element with nothing in it
        else:
            self.put(text, closing=True)

    # -- values ---------------------------------------------------------------------------

    def colour(self, name: str, value, scalar=False):
        """A colour key: a colour, a texture's name or a texture table (a scalar key's
        checkerboard is written as Mitsuba reads it: see texture)."""
        if isinstance(value, (int, float)):
            self.put(f'<float name="{name}" value="{num(value)}"/>')
        elif isinstance(value, list):
            self.put(f'<rgb name="{name}" value="{nums(value)}"/>')
        else:
            spec = self.scene["textures"][value] if isinstance(value, str) else value
            self.texture(name, spec, scalar)

    def texture(self, name: str, t: dict, scalar: bool):
        kind = {"checkerboard": "checkerboard", "image": "bitmap"}[t["type"]]
        self.open(f'<texture type="{kind}" name="{name}">')
        if kind == "checkerboard":
            c0, c1 = t.get("color0", [0.4] * 3), t.get("color1", [0.2] * 3)
            if scalar:  # Mitsuba's scalar lookup swaps the colours (the importer swaps back)
                c0, c1 = c1, c0
            self.put(f'<rgb name="color0" value="{nums(c0)}"/>')
            self.put(f'<rgb name="color1" value="{nums(c1)}"/>')
        else:
            self.put(f'<string name="filename" value="{t["file"]}"/>')
            if t.get("wrap", "repeat") != "repeat":
                self.put(f'<string name="wrap_mode" value="{t["wrap"]}"/>')
            # Unset, a scene file reads a normal map's image as data; Mitsuba never does.
            raw = t.get("raw", name == "normalmap")
            if raw:
                self.put('<boolean name="raw" value="true"/>')
        scale, offset = t.get("scale", 1), t.get("offset", [0, 0])
        scale = scale if isinstance(scale, list) else [scale, scale]
        if scale != [1, 1] or offset != [0, 0]:
            self.open('<transform name="to_uv">')
            self.put(f'<scale x="{num(scale[0])}" y="{num(scale[1])}"/>')
            if offset != [0, 0]:
                self.put(f'<translate x="{num(offset[0])}" y="{num(offset[1])}"/>')
            self.close("</transform>")
        self.close("</texture>")

    # -- materials ------------------------------------------------------------------------

    def bsdf(self, m: dict, id_: str | None = None, face: bool = False):
        """A material; `face`: one face of a `twosided`."""
        ident = f' id="{id_}"' if id_ else ""
        kind = m["type"]
        plain = {"conductor": "conductor", "rough_conductor": "roughconductor",
                 "rough_dielectric": "roughdielectric", "thin_dielectric": "thindielectric",
                 "plastic": "plastic", "rough_plastic": "roughplastic"}
        if kind == "lambertian" and not face:
            # Mitsuba's diffuse is one-sided, the matte material reflects from both faces.
            self.open(f'<bsdf type="twosided"{ident}>')
            self.bsdf(m, face=True)
        elif kind == "lambertian":
            self.open(f'<bsdf type="diffuse"{ident}>')
            self.colour("reflectance", m["albedo"])
        elif kind == "mirror":
            self.open(f'<bsdf type="raytrace_mirror"{ident}>')
            self.put(f'<rgb name="albedo" value="{nums(m["albedo"])}"/>')
        elif kind == "dielectric":
            self.open(f'<bsdf type="dielectric"{ident}>')
            # index = int_ior / ext_ior, exactly, with ext_ior = 1.
            self.put(f'<float name="int_ior" value="{num(float(m["index"]))}"/>')
            self.put('<float name="ext_ior" value="1"/>')
            if "albedo" in m:
                for key in ("specular_reflectance", "specular_transmittance"):
                    self.put(f'<rgb name="{key}" value="{nums(m["albedo"])}"/>')
            if m.get("fresnel", "schlick") == "schlick":
                self.put('<string name="raytrace_fresnel" value="schlick"/>')
        elif kind in plain:
            self.open(f'<bsdf type="{plain[kind]}"{ident}>')
            for key, value in m.items():
                if key == "type":
                    continue
                if key in ("material", "distribution"):
                    self.put(f'<string name="{key}" value="{value}"/>')
                elif key in ("int_ior", "ext_ior"):
                    tag = "string" if isinstance(value, str) else "float"
                    self.put(f'<{tag} name="{key}" value="{num(value)}"/>')
                elif key == "nonlinear":
                    self.put(f'<boolean name="{key}" value="{str(value).lower()}"/>')
                elif key in ("eta", "k"):
                    self.put(f'<rgb name="{key}" value="{nums(value)}"/>')
                else:
                    self.colour(key, value, scalar=key.startswith("alpha"))
        elif kind == "two_sided":
            self.open(f'<bsdf type="twosided"{ident}>')
            self.bsdf(m["front"], face=True)
            if "back" in m:
                self.bsdf(m["back"], face=True)
        elif kind == "normal_map":
            self.open(f'<bsdf type="normalmap"{ident}>')
            # The scene file's normal map, in Mitsuba's words (its defaults are true).
            self.put('<boolean name="use_shadowing_function" value="false"/>')
            self.put('<boolean name="flip_invalid_normals" value="false"/>')
            self.colour("normalmap", m["normal_map"])
            self.put(f'<ref id="{m["material"]}"/>')
        else:
            raise NoTwin(f"a `{kind}` material")
        self.close("</bsdf>")

    # -- objects --------------------------------------------------------------------------

    def material_of(self, o: dict):
        name = o["material"]
        m = self.scene["materials"][name]
        if m["type"] != "emissive":
            self.put(f'<ref id="{name}"/>')
            return
        if m.get("two_sided") or "albedo" not in m:
            raise NoTwin("an emitter that is two-sided or reflects nothing (Mitsuba's area "
                         "emitter is one-sided; its diffuse reflects)")
        self.open('<emitter type="area">')
        self.put(f'<rgb name="radiance" value="{nums(m["radiance"])}"/>')
        self.close("</emitter>")
        self.open('<bsdf type="diffuse">')
        self.put(f'<rgb name="reflectance" value="{nums(m["albedo"])}"/>')
        self.close("</bsdf>")

    def object(self, o: dict):
        kind = o["type"]
        if kind == "sphere":
            self.open('<shape type="sphere">')
            self.put(f'<point name="center" value="{nums(o["center"])}"/>')
            self.put(f'<float name="radius" value="{num(o["radius"])}"/>')
        elif kind == "plane":
            self.open('<shape type="raytrace_plane">')
            self.put(f'<point name="point" value="{nums(o["point"])}"/>')
            self.put(f'<vector name="normal" value="{nums(o["normal"])}"/>')
        elif kind == "triangle":
            self.open('<shape type="raytrace_triangle">')
            for key in "abc":
                self.put(f'<point name="{key}" value="{nums(o[key])}"/>')
        elif kind == "disk" and "matrix" in o:  # by center, normal, radius it has no twin
            self.open('<shape type="disk">')
            self.placement({"matrix": o["matrix"]})
        elif kind == "mesh":
            ext = o["file"].rsplit(".", 1)[-1].lower()
            self.open(f'<shape type="{ext}">')
            self.put(f'<string name="filename" value="{o["file"]}"/>')
            # A file without normals is shaded with its faces' normals; Mitsuba's words for
            # that are face_normals = true (it would shade it smooth).
            flat = o.get("face_normals", False) or not has_normals(SCENES / o["file"])
            if flat:
                self.put('<boolean name="face_normals" value="true"/>')
            if "flip_tex_coords" in o:
                self.put(f'<boolean name="flip_tex_coords" value="{str(o["flip_tex_coords"]).lower()}"/>')
            self.placement(o)
        else:
            raise NoTwin(f"a `{kind}` object")
        self.material_of(o)
        self.close("</shape>")

    def placement(self, o: dict):
        """scale, rotate about x, y, z, translate: the importer reads these steps back as
        the scene file's own keys; a matrix as its rows."""
        steps = []
        if "matrix" in o:
            rows = o["matrix"] + [[0, 0, 0, 1]]
            steps.append(f'<matrix value="{"  ".join(nums(r) for r in rows)}"/>')
        scale = o.get("scale", 1)
        if isinstance(scale, list):
            steps.append(f'<scale x="{num(scale[0])}" y="{num(scale[1])}" z="{num(scale[2])}"/>')
        elif scale != 1:
            steps.append(f'<scale value="{num(scale)}"/>')
        for axis, angle in zip("xyz", o.get("rotate", [0, 0, 0])):
            if angle != 0:
                steps.append(f'<rotate {axis}="1" angle="{num(angle)}"/>')
        t = o.get("translate", [0, 0, 0])
        if t != [0, 0, 0]:
            steps.append(f'<translate x="{num(t[0])}" y="{num(t[1])}" z="{num(t[2])}"/>')
        if steps:
            self.open('<transform name="to_world">')
            for s in steps:
                self.put(s)
            self.close("</transform>")

    def light(self, light: dict):
        kind = light.get("type", "point")
        if kind == "point":
            self.open('<emitter type="point">')
            self.put(f'<point name="position" value="{nums(light["position"])}"/>')
            self.put(f'<rgb name="intensity" value="{nums(light["intensity"])}"/>')
        elif kind == "directional":
            self.open('<emitter type="directional">')
            self.put(f'<vector name="direction" value="{nums(light["direction"])}"/>')
            self.put(f'<rgb name="irradiance" value="{nums(light["irradiance"])}"/>')
        else:
            raise NoTwin(f"a `{kind}` light (Mitsuba's spot is placed by a to_world, whose "
                         "direction does not round back to the file's)")
        self.close("</emitter>")


def has_normals(path: Path) -> bool:
    """Whether a mesh file holds vertex normals (an OBJ's vn lines, a PLY's nx)."""
    if not path.exists():
        raise NoTwin(f"{path} is missing (bash tools/fetch_meshes.sh): whether it has normals "
                     "decides the twin's face_normals")
    with open(path, "rb") as f:
        if path.suffix.lower() == ".obj":
            return any(line.startswith((b"vn ", b"vn\t")) for line in f)
        for line in f:
            words = line.split()
            if words[:1] == [b"end_header"]:
                return False
            if len(words) == 3 and words[0] == b"property" and words[2] == b"nx":
                return True
    return False


def lit_like_mitsuba(scene: dict) -> bool:
    """Whether Mitsuba's max_depth counts as ours: an emitting surface or a lit background."""
    bg = scene.get("background", {"type": "sky"})
    emits = any(m["type"] == "emissive" for m in scene.get("materials", {}).values())
    return emits or bg["type"] == "envmap" or bg.get("light", False)


def twin(toml_path: Path) -> str:
    text = toml_path.read_text()
    scene = tomllib.loads(text)
    scene.setdefault("textures", {})
    scene.setdefault("materials", {})
    w = Writer(scene)
    r = scene.get("render", {})
    width, spp, depth = r.get("width", 800), r.get("spp", 1), r.get("max_depth", 10)
    if r.get("seed", 0) != 0 or r.get("acceleration", "auto") != "auto":
        raise NoTwin("a seed or an acceleration other than the defaults")
    for key in ("precision", "exposure", "tonemap"):
        default = {"precision": "f64", "exposure": 0, "tonemap": "none"}[key]
        if r.get(key, default) != default:
            w.put(f'<default name="raytrace_{key}" value="{num(r[key])}"/>')

    w.open('<integrator type="path">')
    w.put(f'<integer name="max_depth" value="{depth if lit_like_mitsuba(scene) else depth + 1}"/>')
    w.close("</integrator>")

    cam = scene.get("camera", {"type": "screen"})
    if cam["type"] == "screen":
        w.open('<sensor type="raytrace_screen">')
        if "eye" in cam:
            w.put(f'<point name="eye" value="{nums(cam["eye"])}"/>')
        height = width // 2
    else:
        aperture = cam.get("aperture", 0)
        height = int(width / cam["aspect"])
        if width / height != cam["aspect"]:
            raise NoTwin(f"aspect {cam['aspect']} is not {width}/{height} exactly")
        if aperture and "focus_distance" not in cam:
            raise NoTwin("a lens focused on `at` (Mitsuba's focuses at its far clip)")
        w.open(f'<sensor type="{"thinlens" if aperture else "perspective"}">')
        w.put(f'<float name="fov" value="{num(cam["vfov"])}"/>')
        w.put('<string name="fov_axis" value="y"/>')
        if aperture:
            w.put(f'<float name="aperture_radius" value="{num(aperture)}"/>')
            w.put(f'<float name="focus_distance" value="{num(cam["focus_distance"])}"/>')
        up = cam.get("up", [0, 1, 0])
        w.open('<transform name="to_world">')
        w.put(f'<lookat origin="{nums(cam["from"])}" target="{nums(cam["at"])}" up="{nums(up)}"/>')
        w.close("</transform>")
    w.open('<film type="hdrfilm">')
    w.put(f'<integer name="width" value="{width}"/>')
    w.put(f'<integer name="height" value="{height}"/>')
    w.put('<rfilter type="box"/>')
    w.close("</film>")
    w.open('<sampler type="independent">')
    w.put(f'<integer name="sample_count" value="{spp}"/>')
    w.close("</sampler>")
    w.close("</sensor>")

    bg = scene.get("background", {"type": "sky"})
    if bg["type"] == "sky":
        w.open('<emitter type="raytrace_sky">')
        for key in ("horizon", "zenith"):
            if key in bg:
                w.put(f'<rgb name="{key}" value="{nums(bg[key])}"/>')
        if bg.get("light"):
            w.put('<boolean name="light" value="true"/>')
        w.close("</emitter>")
    elif bg["type"] == "solid" and bg.get("light"):
        w.open('<emitter type="constant">')
        w.put(f'<rgb name="radiance" value="{nums(bg["color"])}"/>')
        w.close("</emitter>")
    elif bg["type"] == "solid" and any(bg["color"]):
        raise NoTwin("a coloured background that is not a light")
    elif bg["type"] == "envmap":
        w.open('<emitter type="envmap">')
        w.put(f'<string name="filename" value="{bg["file"]}"/>')
        if bg.get("scale", 1) != 1:
            w.put(f'<float name="scale" value="{num(bg["scale"])}"/>')
        turns = [(a, x) for a, x in zip("xyz", bg.get("rotate", [0, 0, 0])) if x != 0]
        if turns:
            w.open('<transform name="to_world">')
            for axis, angle in turns:
                w.put(f'<rotate {axis}="1" angle="{num(angle)}"/>')
            w.close("</transform>")
        w.close("</emitter>")

    if scene.get("meshes"):
        raise NoTwin("[meshes] and instances (an instance is placed by its matrix)")
    # A scene of hundreds of objects gets one line per material and per object.
    w.compact = len(scene.get("objects", [])) > 50
    for name, m in scene["materials"].items():
        if m["type"] != "emissive":
            w.bsdf(m, name)
    for o in scene.get("objects", []):
        w.object(o)
    for light in scene.get("lights", []):
        w.light(light)

    comment = [line[1:].strip() for line in text.splitlines()
               if line.startswith("#") and "Written by" not in line]
    head = [f"The XML twin of {toml_path.name}: `raytrace render` renders both to the same bytes",
            "(tests/files/xml_twins.rs). Written by tools/xml_twins.py; the `raytrace_` names are",
            "this renderer's extensions (docs/SCENE_FORMAT.md). The scene file says:", ""]
    body = "\n".join("     " + c if c else "" for c in head + comment).replace("--", "-")
    return f'<!--\n{body}\n-->\n<scene version="3.0.0">\n' + "\n".join(w.lines) + "\n</scene>\n"


def main() -> int:
    check = "--check" in sys.argv[1:]
    stale = []
    for toml_path in sorted(SCENES.glob("*.toml")):
        try:
            text = twin(toml_path)
        except NoTwin as why:
            print(f"{toml_path.name}: no exact twin: {why}", file=sys.stderr)
            return 1
        out = toml_path.with_suffix(".xml")
        if check:
            if not out.exists() or out.read_text() != text:
                stale.append(out.name)
        else:
            out.write_text(text)
            print(f"wrote {out.relative_to(ROOT)}")
    if stale:
        print("missing or out of date (run python3 tools/xml_twins.py): " + ", ".join(stale),
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
