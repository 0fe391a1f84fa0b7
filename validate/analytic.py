"""Two checks against closed forms rather than against each other.

White furnace. A convex Lambertian sphere of albedo a under a solid background L: every
scattered ray escapes, so every sample that hits the sphere is exactly a*L (ours: to the
last bits; Mitsuba's MIS estimator is noisy, so its mean is tested against a*L).

Fresnel probe. An infinite glass plane (y = 0) over a black floor (y = -1) under a white
solid background: a camera ray at incidence theta is reflected with probability R(theta)
(then it sees 1) or refracted (then it meets the black floor: 0), so a pixel's expected
value is R(theta), each sample a Bernoulli draw. A look-at camera with a 0.01 degree field of
view fixes theta to within 1e-4 rad. Index 1.5 probes air -> glass; index 1/1.5 probes
glass -> air (total reflection beyond 41.8 degrees) and the 1/n convention of hollow shells.

Both use the same significance as the comparison: alpha = 1e-3 over all tests of the check,
Bonferroni, fixed seeds.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import renders
import scene_model
import stats
from scene_model import Scene

# Incidence angles per index: from glass to air (1/1.5) reflection is total beyond 41.8.
ANGLES = {1.5: [0.0, 30.0, 45.0, 60.0, 70.0, 80.0, 85.0],
          1.0 / 1.5: [0.0, 20.0, 30.0, 35.0, 40.0, 41.0, 60.0]}


def fresnel(cos_i: float, eta: float) -> float:
    """Exact unpolarised reflectance, eta = eta_1/eta_2 (1 under total reflection)."""
    sin2_t = eta * eta * (1.0 - cos_i * cos_i)
    if sin2_t >= 1.0:
        return 1.0
    cos_t = math.sqrt(1.0 - sin2_t)
    rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    return 0.5 * (rs * rs + rp * rp)


def schlick(cos_i: float, eta: float) -> float:
    """Schlick at the angle in the rarer medium, as src/optics.rs schlick_reflectance."""
    sin2_t = eta * eta * (1.0 - cos_i * cos_i)
    if sin2_t >= 1.0:
        return 1.0
    c = math.sqrt(1.0 - sin2_t) if eta > 1.0 else cos_i
    r0 = ((1.0 - eta) / (1.0 + eta)) ** 2
    return r0 + (1.0 - r0) * (1.0 - c) ** 5


def _scene(path: Path, text: str) -> Scene:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return scene_model.load(path)


def furnace_scene(work: Path, albedo, light) -> Scene:
    return _scene(work / "furnace.toml", f"""
[camera]
type = "screen"
[background]
type = "solid"
color = {list(light)}
[materials.matte]
type = "lambertian"
albedo = {list(albedo)}
[[objects]]
type = "sphere"
center = [0, 0, -2.5]
radius = 1.6
material = "matte"
""")


def _inside_pixels(nx: int, ny: int, center, radius) -> np.ndarray:
    """Pixels whose whole cell (all four corners' rays, a convex cell inside a convex
    silhouette) sees the sphere: the screen camera's cells span x +- 1/2 pixel."""
    c = np.asarray(center, float)
    ok = np.ones((ny, nx), bool)
    for dx in (-0.5, 0.5):
        for dy in (-0.5, 0.5):
            x = -2 + 4 * (np.arange(nx) + dx) / (nx - 1)
            y = 1 - 2 * (np.arange(ny) + dy) / (ny - 1)
            d = np.stack(np.broadcast_arrays(x[None, :], y[:, None], -1.0), axis=-1)
            d /= np.linalg.norm(d, axis=-1, keepdims=True)
            b = d @ c
            ok &= b * b - (c @ c - radius * radius) > 1e-6
    return ok


def furnace(work: Path, width: int, spp: int) -> list[dict]:
    """Rows: ours f32, ours f64 (largest relative error over the inside pixels) and Mitsuba
    (mean over the inside pixels against a*L, with its two-seed standard error)."""
    albedo, light = [0.9, 0.6, 0.3], [0.8, 0.8, 0.8]
    scene = furnace_scene(work / "analytic", albedo, light)
    expect = np.array(albedo) * np.array(light)
    nx, ny = scene.size(width)
    inside = _inside_pixels(nx, ny, [0, 0, -2.5], 1.6)
    kw = dict(width=width, spp=spp, max_depth=10)
    rows = []
    for prec in ("f32", "f64"):
        img = renders.ours_image(scene, work, seed=1, precision=prec, **kw)
        err = np.abs(img[inside] - expect) / expect
        # f64: exact but for the file's f32 rounding (half an ulp, 2^-24 relative); f32: a
        # few ulps of the f32 mean of identical samples.
        tol = 1e-6 if prec == "f32" else 2.0**-24
        rows.append({"check": "furnace", "renderer": f"ours {prec}", "expected": expect.tolist(),
                     "measured": img[inside].mean(0).tolist(), "stat": float(err.max()),
                     "stat_name": "max relative error", "passed": bool(err.max() <= tol),
                     "criterion": f"every inside pixel within {tol:g} of a*L"})
    m1, m2 = (renders.mitsuba(scene, work, seed=s, **kw) for s in (1, 2))
    mean = (m1 + m2)[inside].mean(0) / 2
    se = np.sqrt((((m1 - m2) ** 2)[inside] / 4).sum(0)) / inside.sum()
    z = (mean - expect) / np.maximum(se, 1e-12)
    z_star = _z_threshold(stats.ALPHA / 3)
    rows.append({"check": "furnace", "renderer": "mitsuba", "expected": expect.tolist(),
                 "measured": mean.tolist(), "stat": float(np.abs(z).max()),
                 "stat_name": "max |z| over channels",
                 "passed": bool(np.abs(z).max() < z_star),
                 "criterion": f"|z| < {z_star:.2f} (alpha 1e-3, Bonferroni over 3 channels)"})
    return rows


def _z_threshold(p_two_sided: float) -> float:
    lo, hi = 0.0, 40.0  # bisection on the normal tail: no scipy needed
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if stats.normal_two_sided(mid) > p_two_sided else (lo, mid)
    return hi


def probe_scene(work: Path, theta: float, index: float, mode: str) -> Scene:
    t = math.radians(theta)
    eye = [5 * math.sin(t), 5 * math.cos(t), 0.0]
    return _scene(work / f"probe-{theta:g}-{index:.4f}-{mode}.toml", f"""
[camera]
type = "look_at"
from = {eye}
at = [0, 0, 0]
up = [0, 0, -1]
vfov = 0.01
aspect = 2
[background]
type = "solid"
color = [1, 1, 1]
[materials.glass]
type = "dielectric"
index = {index!r}
fresnel = "{mode}"
[materials.black]
type = "lambertian"
albedo = [0, 0, 0]
[[objects]]
type = "plane"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "glass"
[[objects]]
type = "plane"
point = [0, -1, 0]
normal = [0, 1, 0]
material = "black"
""")


def fresnel_probe(work: Path, width: int = 8, spp: int = 4096) -> list[dict]:
    """Rows per angle and index: R exact, R Schlick, and what ours (exact), ours (Schlick)
    and Mitsuba measure, each with its z against the formula it should follow."""
    rows, n_tests = [], 3 * sum(len(a) for a in ANGLES.values())
    z_star = _z_threshold(stats.ALPHA / n_tests)
    probe_seed = 0
    for index, angles in ANGLES.items():
        for theta in angles:
            probe_seed += 1  # a stream of its own per probe: their errors are independent
            cos_i = math.cos(math.radians(theta))
            r_exact, r_schlick = fresnel(cos_i, 1 / index), schlick(cos_i, 1 / index)
            kw = dict(seed=probe_seed, width=width, spp=spp, max_depth=2)
            exact_scene = probe_scene(work / "analytic", theta, index, "exact")
            measured = {
                "ours f64": renders.ours_image(exact_scene, work, precision="f64", **kw),
                "ours f64 schlick": renders.ours_image(
                    probe_scene(work / "analytic", theta, index, "schlick"), work,
                    precision="f64", **kw),
                "mitsuba": renders.mitsuba(exact_scene, work, **kw),
            }
            row = {"index": index, "theta": theta, "R_exact": r_exact, "R_schlick": r_schlick,
                   "z_star": z_star}
            passed = True
            for who, img in measured.items():
                r = float(img[..., 0].mean())
                target = r_schlick if "schlick" in who else r_exact
                n = img.shape[0] * img.shape[1] * spp
                se = math.sqrt(max(target * (1 - target), 1e-12) / n)
                z = (r - target) / se
                row[who] = r
                row[f"z {who}"] = z
                passed &= abs(z) < z_star
                if "schlick" in who:  # the Schlick render against the exact reflectance
                    se_e = math.sqrt(max(r_exact * (1 - r_exact), 1e-12) / n)
                    row["z schlick vs exact"] = (r - r_exact) / se_e
            row["passed"] = passed
            rows.append(row)
    return rows
