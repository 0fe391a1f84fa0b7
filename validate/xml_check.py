"""The cross-check with no converter: one Mitsuba 3 XML file, read by Mitsuba
(`mi.load_file`) and by this renderer (`raytrace render scene.xml`), compared within noise by
the same test as the converted scenes (stats.py).

The scenes (validate/xml/*.xml, README.md says what each covers) take their size and spp as
$-defaults; each mode passes them with -D to both renderers (`load_file(**defines)` and
`raytrace render -D`). A power check passes one more -D to this renderer only (an albedo,
the environment's scale): the comparison must reject it. Any other XML file given on the
command line is compared with its own settings.
"""

from __future__ import annotations

import hashlib
import subprocess
import time
from pathlib import Path

import mitsuba as mi
import numpy as np

import ours
import report
import stats

HERE = Path(__file__).resolve().parent
XML = HERE / "xml"
SEEDS = (1, 2)
# Per scene: the size each mode renders it at (its aspect is the file's).
SCENES = {
    "room": {"quick": dict(width=64, height=64, spp=128), "full": dict(width=128, height=128, spp=512)},
    "outdoor": {"quick": dict(width=64, height=32, spp=128), "full": dict(width=128, height=64, spp=512)},
    "lights": {"quick": dict(width=64, height=32, spp=128), "full": dict(width=128, height=64, spp=512)},
}
# Each must be rejected: (scene, its -D for this renderer only, what it is, the modes).
# The room's walls (under one area light: noisy) are found only at the full mode's size.
POWER = [
    ("room", {"rough0": "0.45", "rough1": "0.05"},
     "the gem's roughness checkerboard unswapped (-D rough0, rough1, ours only: the importer "
     "before it followed Mitsuba's scalar lookup)", ("quick", "full")),
    ("lights", {"floor": "0.612, 0.612, 0.612"}, "the floor's albedo x 1.02 (-D floor, ours only)",
     ("quick", "full")),
    ("outdoor", {"env_scale": "0.98"}, "the environment's scale x 0.98 (-D env_scale, ours only)",
     ("quick", "full")),
    ("room", {"wall": "0.714, 0.6936, 0.6324"}, "the walls' albedo x 1.02 (-D wall, ours only)",
     ("full",)),
]
# Ours in both precisions in the full mode; f64 only in the quick one (CI's time).
PRECISIONS = {"quick": ("f64",), "full": ("f32", "f64")}


def _key(path: Path, defines: dict, *extra) -> str:
    """A cache key of the scene's text (and every XML file beside it or below: includes),
    the defines and the rest."""
    h = hashlib.sha256()
    for p in sorted(path.parent.rglob("*.xml")):
        h.update(p.read_bytes())
    h.update(repr((str(path), sorted(defines.items()), extra)).encode())
    return h.hexdigest()[:16]


def mitsuba_image(path: Path, defines: dict, seed: int, work: Path, times: list) -> np.ndarray:
    """Mitsuba's render of the XML file with `defines`, float64 (h, w, 3)."""
    out = work / "xml-mitsuba" / f"{path.stem}-{_key(path, defines, seed, mi.__version__, mi.variant())}.npy"
    if out.exists():
        return np.load(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    t = time.perf_counter()
    scene = mi.load_file(str(path), **{k: str(v) for k, v in defines.items()})
    img = np.array(mi.render(scene, seed=seed), dtype=np.float64)[..., :3]
    times.append({"renderer": f"mitsuba {mi.variant()}", "scene": f"xml/{path.stem}",
                  "seconds": time.perf_counter() - t})
    np.save(out, img)
    return img


def ours_image(path: Path, defines: dict, seed: int, precision: str, work: Path,
               times: list) -> np.ndarray:
    """This renderer's render of the XML file with `defines`, float64 (h, w, 3)."""
    binary = ours.BINARY
    key = _key(path, defines, seed, precision, binary.stat().st_mtime_ns)
    out = work / "xml-ours" / f"{path.stem}-{key}.pfm"
    if not out.exists():
        out.parent.mkdir(parents=True, exist_ok=True)
        cmd = [str(binary), "render", str(path), "--seed", str(seed), "--precision", precision,
               "--format", "pfm", "--out", str(out), "--quiet"]
        for k, v in defines.items():
            cmd += ["-D", f"{k}={v}"]
        t = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        times.append({"renderer": f"ours {precision}", "scene": f"xml/{path.stem}",
                      "seconds": time.perf_counter() - t})
    return ours.read_pfm(out)


def _max_depth(path: Path, defines: dict) -> str:
    """The file's max_depth as written (both renderers read the same number): in it or in
    an XML file beside it or below (an include), a $name resolved by `defines` or its
    <default>; `direct` is 2."""
    import xml.etree.ElementTree as ET
    roots = [ET.parse(p).getroot() for p in [path, *sorted(path.parent.rglob("*.xml"))]]
    defaults = {n.get("name"): n.get("value") for r in roots for n in r.iter("default")}
    def resolved(value: str) -> str:
        name = value[1:]
        return str(defines.get(name, defaults.get(name, value))) if value.startswith("$") else value

    for root in roots:
        for node in root.iter():
            if node.tag == "integrator" and resolved(node.get("type", "")) == "direct":
                return "2"
            if node.tag == "integer" and node.get("name") == "max_depth":
                return resolved(node.get("value", ""))
    return "-1"


def compare(path: Path, defines: dict, work: Path, rows, pngs, times, precisions=("f32", "f64"),
            name: str | None = None):
    """Both renderers on one XML file, each precision of ours against Mitsuba; the rows
    (named `name`, default `xml/STEM`) and the difference images go into the report.
    Returns Mitsuba's two images."""
    m = [mitsuba_image(path, defines, s, work, times) for s in SEEDS]
    name, depth = name or f"xml/{path.stem}", _max_depth(path, defines)
    for prec in precisions:
        o = [ours_image(path, defines, s, prec, work, times) for s in SEEDS]
        v = stats.compare(o[0], o[1], m[0], m[1])
        rows.append(report.row_named("agreement", name, depth, prec, "", o[0].shape,
                                     defines.get("spp", "file's"), depth, v))
        pngs.append((f"{name.replace('/', '-')}-{prec}", o, m, v))
    return m


def run(mode: str, work: Path, rows, pngs, times, power: bool = True):
    """Every XML scene in `mode`'s size, then the power checks."""
    refs = {}
    for name, sizes in SCENES.items():
        print(f"== xml/{name}", flush=True)
        refs[name] = compare(XML / f"{name}.xml", sizes[mode], work, rows, pngs, times,
                             PRECISIONS[mode])
    if not power:
        return
    print("== xml power checks", flush=True)
    for name, wrong, what, modes in POWER:
        if mode not in modes:
            continue
        path, defines = XML / f"{name}.xml", SCENES[name][mode]
        o = [ours_image(path, defines | wrong, s, "f64", work, times) for s in SEEDS]
        m = refs[name]
        v = stats.compare(o[0], o[1], m[0], m[1])
        depth = _max_depth(path, defines)
        rows.append(report.row_named("power", f"xml/{name}", depth, "f64", what, o[0].shape,
                                     defines["spp"], depth, v))
        pngs.append((f"power-xml-{name}-{'-'.join(wrong)}", o, m, v))
