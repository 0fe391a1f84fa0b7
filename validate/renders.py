"""Both renderers behind one cached call, and the record of what each render cost.

A render is stored in the work folder under a key made of everything it depends on (the
scene's text, the settings, the seed, and for Mitsuba its version and the converter's own
source), so a repeated run, or a power check that reuses a reference, renders nothing twice.
"""

from __future__ import annotations

import hashlib
import time
from functools import partial
from pathlib import Path

import mitsuba as mi
import numpy as np

import convert
import ours
from scene_model import Scene, to_toml

HERE = Path(__file__).resolve().parent
_CONVERTER_SOURCES = [HERE / "convert.py", HERE / "convert_materials.py", HERE / "convert_more.py",
                      HERE / "spec_sensor.py", HERE / "meshio.py"]
TIMES: list[dict] = []  # one entry per render actually made: who, scene, seconds


def _converter_hash() -> str:
    h = hashlib.sha256(mi.__version__.encode())
    for p in _CONVERTER_SOURCES:
        h.update(p.read_bytes())
    return h.hexdigest()[:12]


def mitsuba(scene: Scene, work: Path, *, seed: int, width: int, spp: int, max_depth: int,
            shift: float = 0.0, depth_map=None) -> np.ndarray:
    """Mitsuba's image of `scene` (scalar_rgb), float64 (h, w, 3)."""
    key = f"{to_toml(scene)}|{seed}|{width}|{spp}|{max_depth}|{shift}|" \
          f"{(depth_map or partial(convert.scene_depth, scene))(max_depth)}|{mi.variant()}|{_converter_hash()}"
    path = work / "mitsuba" / f"{scene.name}-{hashlib.sha256(key.encode()).hexdigest()[:16]}.npy"
    if path.exists():
        return np.load(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    t = time.perf_counter()
    img = convert.render(scene, seed=seed, width=width, spp=spp, max_depth=max_depth,
                         shift=shift, depth_map=depth_map)
    TIMES.append({"renderer": f"mitsuba {mi.variant()}", "scene": scene.name,
                  "seconds": time.perf_counter() - t, "width": width, "spp": spp})
    np.save(path, img)
    return img


def ours_image(scene: Scene, work: Path, *, seed: int, width: int, spp: int, max_depth: int,
               precision: str) -> np.ndarray:
    """Our image of `scene` exactly as given (see ours.exact_fresnel), float64 (h, w, 3)."""
    img, seconds = ours.render(scene, work / "ours", width=width, spp=spp,
                               max_depth=max_depth, seed=seed, precision=precision)
    if seconds == seconds:  # not NaN: rendered now, not read from the cache
        TIMES.append({"renderer": f"ours {precision}", "scene": scene.name,
                      "seconds": seconds, "width": width, "spp": spp})
    return img
