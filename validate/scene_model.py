"""This project's TOML scene files, read with the defaults of docs/SCENE_FORMAT.md.

`load(path)` returns a `Scene`: plain dictionaries with every default filled in, so the
converter never guesses. `write_toml(scene, path)` writes a scene back (our renderer is then
run on the written copy: that is how a comparison forces exact Fresnel, and how the power
checks inject a mistake into *our* side without touching any Rust).

Only what the comparison needs is checked here; `raytrace check` remains the validator.
"""

from __future__ import annotations

import copy
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

SKY_HORIZON = [1.0, 1.0, 1.0]  # src/background.rs, Background::default
SKY_ZENITH = [0.5, 0.7, 1.0]
# Mitsuba's own materials: kept as written (same keys in both renderers), converted by
# convert_materials.py.
MITSUBA_MATERIALS = ("conductor", "rough_conductor", "rough_dielectric", "thin_dielectric",
                     "plastic", "rough_plastic", "two_sided", "normal_map")


@dataclass
class Scene:
    """A scene file's content with defaults applied (keys as in SCENE_FORMAT.md)."""

    path: Path
    render: dict
    camera: dict
    background: dict
    materials: dict
    objects: list
    lights: list = field(default_factory=list)
    textures: dict = field(default_factory=dict)  # [textures.NAME], as written
    meshes: dict = field(default_factory=dict)  # [meshes.NAME], as written

    @property
    def name(self) -> str:
        return self.path.stem

    def size(self, width: int | None = None) -> tuple[int, int]:
        """The image size our renderer uses at `width` (the scene's own by default)."""
        w = int(width if width is not None else self.render["width"])
        if self.camera["type"] == "screen":
            return w, w // 2
        # src/scene_file/build.rs look_at_height: floor(w/aspect), a hair of slack so
        # that 16/9 (not exact in f64) still gives 400 x 225.
        return w, int(math.floor(w / self.camera["aspect"] * (1.0 + 1e-12)))

    def copy(self) -> "Scene":
        return copy.deepcopy(self)


def _f3(v) -> list[float]:
    return [float(x) for x in v]


def load(path: str | Path) -> Scene:
    """Reads a scene file; mesh paths become absolute (relative to the file's folder)."""
    path = Path(path).resolve()
    with open(path, "rb") as f:
        raw = tomllib.load(f)
    render = {"width": 800, "spp": 1, "max_depth": 10, "seed": 0, "precision": "f64"}
    render.update(raw.get("render", {}))

    cam = dict(raw.get("camera", {"type": "screen"}))
    cam.setdefault("type", "screen")
    if cam["type"] == "screen":
        cam["eye"] = _f3(cam.get("eye", [0, 0, 0]))
    elif cam["type"] == "look_at":
        cam["up"] = _f3(cam.get("up", [0, 1, 0]))
        cam["from"], cam["at"] = _f3(cam["from"]), _f3(cam["at"])
        cam["vfov"], cam["aspect"] = float(cam["vfov"]), float(cam["aspect"])
    else:
        raise ValueError(f"{path}: unknown camera type {cam['type']!r}")

    bg = dict(raw.get("background", {"type": "sky"}))
    bg.setdefault("type", "sky")
    if bg["type"] == "sky":
        bg["horizon"] = _f3(bg.get("horizon", SKY_HORIZON))
        bg["zenith"] = _f3(bg.get("zenith", SKY_ZENITH))
    elif bg["type"] == "solid":
        bg["color"] = _f3(bg["color"])
    elif bg["type"] == "envmap":
        bg["file"] = str((path.parent / bg["file"]).resolve())
        bg["scale"] = float(bg.get("scale", 1.0))
        bg["rotate"] = _f3(bg.get("rotate", [0, 0, 0]))
    else:
        raise ValueError(f"{path}: unknown background type {bg['type']!r}")

    materials = {}
    for name, m in raw.get("materials", {}).items():
        m = dict(m)
        if m["type"] == "dielectric":
            m["index"] = float(m["index"])
            m["albedo"] = _f3(m.get("albedo", [1, 1, 1]))
            m.setdefault("fresnel", "schlick")
        elif m["type"] in ("mirror", "lambertian"):
            # a lambertian's albedo may be a texture (its name or a table)
            m["albedo"] = _f3(m["albedo"]) if isinstance(m["albedo"], list) else m["albedo"]
        elif m["type"] == "emissive":
            m["radiance"] = _f3(m["radiance"])
            m["albedo"] = _f3(m.get("albedo", [0, 0, 0]))
            m.setdefault("two_sided", False)
        elif m["type"] not in MITSUBA_MATERIALS:
            raise ValueError(f"{path}: material {name}: unknown type {m['type']!r}")
        materials[name] = _resolve_files(m, path.parent)
    textures = {n: _resolve_files(dict(t), path.parent)
                for n, t in raw.get("textures", {}).items()}
    meshes = {n: _resolve_files(dict(t), path.parent) for n, t in raw.get("meshes", {}).items()}

    objects = []
    for o in raw.get("objects", []):
        o = dict(o)
        if o["type"] in ("mesh", "instance"):
            if o["type"] == "mesh":
                o["file"] = str((path.parent / o["file"]).resolve())
            s = o.get("scale", 1.0)
            o["scale"] = _f3(s) if isinstance(s, list) else [float(s)] * 3
            o["rotate"] = _f3(o.get("rotate", [0, 0, 0]))
            o["translate"] = _f3(o.get("translate", [0, 0, 0]))
        if o["material"] not in materials:
            raise ValueError(f"{path}: unknown material {o['material']!r}")
        objects.append(o)
    lights = []
    for l in raw.get("lights", []):
        l = dict(l)
        l.setdefault("type", "point")
        if l["type"] == "spot":  # docs/SCENE_FORMAT.md's defaults, written out
            l.setdefault("cutoff_angle", 20.0)
            l.setdefault("beam_width", 0.75 * float(l["cutoff_angle"]))
        lights.append(l)
    return Scene(path, render, cam, bg, materials, objects, lights, textures, meshes)


def missing_files(path: str | Path) -> list[str]:
    """The mesh files a scene file names that are not there (fetched meshes such as the
    dragon and the bunny: tools/fetch_meshes.sh). Such a scene is skipped, and said so."""
    s = load(path)
    files = [o["file"] for o in s.objects if o["type"] == "mesh"]
    files += [m["file"] for m in s.meshes.values()]
    return [f for f in files if not Path(f).exists()]


def _resolve_files(table: dict, folder: Path) -> dict:
    """`file` keys (of a texture, a mesh, or a texture written in place at any depth)
    made absolute: the scene is rendered from a copy written elsewhere."""
    out = {}
    for k, v in table.items():
        if k == "file" and isinstance(v, str):
            v = str((folder / v).resolve())
        elif isinstance(v, dict):
            v = _resolve_files(v, folder)
        out[k] = v
    return out


# ---- writing ------------------------------------------------------------------------

def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"not a finite number: {v}")
        return repr(v)  # shortest text that reads back to the same double
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):  # an inline table: a texture in place, two_sided's front
        return "{ " + ", ".join(_table(v)) + " }"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _table(d: dict) -> list[str]:
    return [f"{_value(k) if not k.isidentifier() else k} = {_value(v)}" for k, v in d.items()]


def to_toml(scene: Scene) -> str:
    """The scene as TOML text that our renderer reads back to the same values."""
    out = ["[render]", *_table(scene.render), "", "[camera]", *_table(scene.camera), "",
           "[background]", *_table(scene.background), ""]
    for name, t in scene.textures.items():
        out += [f"[textures.{_value(name)}]", *_table(t), ""]
    for name, t in scene.meshes.items():
        out += [f"[meshes.{_value(name)}]", *_table(t), ""]
    for name, m in scene.materials.items():
        out += [f"[materials.{_value(name)}]", *_table(m), ""]
    for o in scene.objects:
        out += ["[[objects]]", *_table(o), ""]
    for l in scene.lights:
        out += ["[[lights]]", *_table(l), ""]
    return "\n".join(out)


def write_toml(scene: Scene, path: str | Path) -> Path:
    path = Path(path)
    path.write_text(to_toml(scene))
    return path
