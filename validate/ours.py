"""Running this project's `raytrace` binary on a scene and reading its linear output.

Renders go through a written copy of the scene (scene_model.write_toml), so the comparison
can set fresnel = "exact" and the power checks can inject mistakes without touching Rust.
The output is PFM: linear 32-bit floats, rows stored bottom to top.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import time
from pathlib import Path

import numpy as np

from scene_model import Scene, to_toml

ROOT = Path(__file__).resolve().parent.parent
BINARY = Path(os.environ.get("RAYTRACE_BIN", ROOT / "target" / "release" / "raytrace"))


def read_pfm(path: str | Path) -> np.ndarray:
    """A colour PFM as a float64 (height, width, 3) array, top row first."""
    data = Path(path).read_bytes()
    tokens, pos = [], 0
    while len(tokens) < 4:  # magic, width, height, scale: each ends in one whitespace byte
        end = pos
        while data[end:end + 1] not in (b" ", b"\n", b"\r", b"\t"):
            end += 1
        if end > pos:
            tokens.append(data[pos:end].decode())
        pos = end + 1
    magic, w, h, scale = tokens[0], int(tokens[1]), int(tokens[2]), float(tokens[3])
    if magic != "PF":
        raise ValueError(f"{path}: not a colour PFM ({magic})")
    dtype = "<f4" if scale < 0 else ">f4"
    img = np.frombuffer(data, dtype=dtype, count=w * h * 3, offset=pos).reshape(h, w, 3)
    return img[::-1].astype(np.float64)  # PFM rows run bottom to top


def exact_fresnel(scene: Scene) -> Scene:
    """A copy with every dielectric on the exact Fresnel equations (Mitsuba has no Schlick)."""
    s = scene.copy()
    for m in s.materials.values():
        if m["type"] == "dielectric":
            m["fresnel"] = "exact"
    return s


def render(scene: Scene, workdir: Path, *, width: int, spp: int, max_depth: int,
           seed: int, precision: str, threads: int | None = None) -> tuple[np.ndarray, float]:
    """Renders `scene` (as given: call exact_fresnel first for a comparison) and returns
    (image, seconds of wall time of the whole process). Cached by content: the same
    scene text and settings are rendered once per work folder."""
    workdir.mkdir(parents=True, exist_ok=True)
    text = to_toml(scene)
    key = hashlib.sha256(f"{text}|{width}|{spp}|{max_depth}|{seed}|{precision}".encode())
    stem = f"{scene.name}-{key.hexdigest()[:16]}"
    toml, out = workdir / f"{stem}.toml", workdir / f"{stem}.pfm"
    if out.exists():
        return read_pfm(out), float("nan")
    toml.write_text(text)
    cmd = [str(BINARY), "render", str(toml), "--width", str(width), "--spp", str(spp),
           "--max-depth", str(max_depth), "--seed", str(seed), "--precision", precision,
           "--format", "pfm", "--out", str(out), "--quiet"]
    if threads:
        cmd += ["--threads", str(threads)]
    t = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return read_pfm(out), time.perf_counter() - t
