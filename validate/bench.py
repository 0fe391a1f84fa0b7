"""Speed beside Mitsuba 3: each scene at the same size, spp and depth, on 1 and 2 threads,
for ours (f32, f64), Mitsuba scalar_rgb and Mitsuba llvm_ad_rgb; and time-to-equal-error
charts (the RMSE each renderer reaches against its own converged reference, against time).

    validate/.venv/bin/python validate/bench.py                       # the report's figures
    validate/.venv/bin/python validate/bench.py --width 64 --spp 8 --scenes matte_spheres

Mitsuba is timed with its own C++ `perspective` sensor (the Python `spec_screen` plugin
costs several microseconds per sample in scalar mode): for the spec's camera that is the
same horizontal field of view over the film edges, so its vertical view differs by
1/(2 ny - 1), 0.13 % at 800 x 400 -- irrelevant for timing, which is all it is used for.
Times are wall clock of the render alone: ours as the binary reports it, Mitsuba's
mi.render (llvm_ad_rgb: the first call includes compiling its kernels, reported apart).
llvm_ad_rgb needs Debian's libLLVM (apt-get install -y libllvm19; drjit aborts with 14 or 15,
and picks one of those where it is installed too: then set
DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so)
and intersects spheres in float32. Machine noise: see the report's conditions.
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import ours  # noqa: E402
import scene_model  # noqa: E402
import svg_loglog  # noqa: E402

DEFAULT_SCENES = ["four_mirrors", "matte_spheres", "glass", "plane_and_triangles",
                  "point_lights", "random_spheres"]
COLOURS = {"ours f64": "#1f77b4", "ours f32": "#17becf", "mitsuba scalar_rgb": "#d62728",
           "mitsuba llvm_ad_rgb": "#ff7f0e"}


def llvm_works() -> bool:
    """In a child process: drjit aborts (not raises) when it finds an unusable libLLVM."""
    code = ("import mitsuba as mi, drjit as dr; mi.set_variant('llvm_ad_rgb'); "
            "x = dr.arange(mi.Float, 8); print(dr.sum(x * 2))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    return r.returncode == 0


def ours_time(scene, work: Path, *, width, spp, depth, threads, precision, seed=1):
    """(render seconds as the binary reports them, image)."""
    work.mkdir(parents=True, exist_ok=True)
    toml = work / f"{scene.name}.toml"
    scene_model.write_toml(ours.exact_fresnel(scene), toml)
    out = work / f"{scene.name}-{precision}-{threads}-{spp}.pfm"
    r = subprocess.run([str(ours.BINARY), "render", str(toml), "--width", str(width),
                        "--spp", str(spp), "--max-depth", str(depth), "--seed", str(seed),
                        "--precision", precision, "--threads", str(threads), "--out", str(out)],
                       check=True, capture_output=True, text=True)
    m = re.search(r"([0-9.]+) s, \d+ rays", r.stdout + r.stderr)
    return float(m.group(1)), ours.read_pfm(out)


def mitsuba_scene(scene, width, spp, depth):
    import convert
    import mitsuba as mi
    d = convert.to_mitsuba(scene, width=width, spp=spp, max_depth=depth)
    if scene.camera["type"] == "screen":
        nx, ny = scene.size(width)
        eye = scene.camera["eye"]
        d["sensor"] = {"type": "perspective", "fov_axis": "x",
                       "fov": math.degrees(2 * math.atan(2 * nx / (nx - 1))),
                       "film": d["sensor"]["film"], "sampler": d["sensor"]["sampler"],
                       "to_world": mi.ScalarTransform4f().look_at(
                           origin=eye, target=[eye[0], eye[1], eye[2] - 1], up=[0, 1, 0])}
    return mi.load_dict(d)


def mitsuba_time(mscene, spp, threads, seed=1):
    import drjit as dr
    import mitsuba as mi
    dr.set_thread_count(threads)
    t = time.perf_counter()
    img = np.array(mi.render(mscene, spp=spp, seed=seed))  # np.array waits for the JIT
    return time.perf_counter() - t, img[..., :3].astype(np.float64)


def rmse(a, b) -> float:
    return float(np.sqrt(np.mean((a - b) ** 2)))


def main() -> int:
    ap = argparse.ArgumentParser(description="time ours against Mitsuba 3")
    ap.add_argument("--scenes", nargs="*", default=DEFAULT_SCENES)
    ap.add_argument("--width", type=int, default=400)
    ap.add_argument("--spp", type=int, default=64, help="spp of the timing table")
    # The ladder starts at 2 spp: at 1 spp ours shoots through the pixel centre (the spec's
    # basic mode), a different estimator from the jittered reference.
    ap.add_argument("--ladder", type=int, default=6, help="equal-error: spp 2, 4, ... 2^n")
    ap.add_argument("--ref-spp", type=int, default=4096, help="each renderer's own reference")
    ap.add_argument("--out", type=Path, default=HERE / "results" / "bench")
    args = ap.parse_args()
    import mitsuba as mi
    variants = ["scalar_rgb"] + (["llvm_ad_rgb"] if llvm_works() else [])
    if len(variants) == 1:
        print("llvm_ad_rgb unavailable (apt-get install -y libllvm19): timing scalar_rgb only")
    work, args.out = HERE / "work" / "bench", args.out
    args.out.mkdir(parents=True, exist_ok=True)
    times, tte = [], {}
    for name in args.scenes:
        path = next(p for p in (ROOT / "scenes" / f"{name}.toml", HERE / "scenes" / f"{name}.toml",
                                Path(name)) if p.exists())
        scene = scene_model.load(path)
        depth, (nx, ny) = scene.render["max_depth"], scene.size(args.width)
        print(f"== {scene.name} {nx}x{ny}, {args.spp} spp, depth {depth}", flush=True)
        base = dict(scene=scene.name, width=nx, height=ny, spp=args.spp, max_depth=depth)
        series = {}
        for prec in ("f32", "f64"):
            for th in (1, 2):
                s, _ = ours_time(scene, work, width=args.width, spp=args.spp, depth=depth,
                                 threads=th, precision=prec)
                times.append(base | {"renderer": f"ours {prec}", "threads": th, "seconds": s,
                                     "first_call_seconds": s})
        # Equal error, on 2 threads: f64 ours against its own reference.
        ref = ours_time(scene, work, width=args.width, spp=args.ref_spp, depth=depth,
                        threads=2, precision="f64", seed=99)[1]
        pts = []
        for k in range(1, args.ladder + 1):
            s, img = ours_time(scene, work, width=args.width, spp=2**k, depth=depth, threads=2,
                               precision="f64")
            pts.append((s, rmse(img, ref)))
        series["ours f64"] = pts
        for var in variants:
            mi.set_variant(var)
            mscene = mitsuba_scene(scene, args.width, args.spp, depth)
            for th in (1, 2):
                first, _ = mitsuba_time(mscene, args.spp, th)
                again, _ = mitsuba_time(mscene, args.spp, th, seed=2)
                times.append(base | {"renderer": f"mitsuba {var}", "threads": th,
                                     "seconds": again, "first_call_seconds": first})
            _, mref = mitsuba_time(mscene, args.ref_spp, 2, seed=99)
            pts = []
            for k in range(1, args.ladder + 1):
                mitsuba_time(mscene, 2**k, 2)  # compile this spp's kernel (llvm) first
                s, img = mitsuba_time(mscene, 2**k, 2, seed=3)
                pts.append((s, rmse(img, mref)))
            series[f"mitsuba {var}"] = pts
        tte[f"{scene.name} ({nx}x{ny}, depth {depth})"] = [
            (k, COLOURS[k], "" if k.startswith("ours") else "5,3", v) for k, v in series.items()]
    with open(args.out / "bench.csv", "w", newline="") as f:
        w = csv.DictWriter(f, list(times[0].keys()))
        w.writeheader()
        w.writerows(times)
    with open(args.out / "equal_error.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "renderer", "spp", "seconds", "rmse"])
        for panel, series in tte.items():
            for label, _, _, pts in series:
                for k, (s, e) in enumerate(pts, start=1):
                    w.writerow([panel, label, 2**k, f"{s:.5f}", f"{e:.6f}"])
    svg = svg_loglog.small_multiples(
        tte, f"Time to equal error: RMSE against each renderer's own {args.ref_spp}-spp "
        "reference, 2 threads", "render time (s)", "RMSE (linear radiance)")
    (args.out / "equal_error.svg").write_text(svg)
    md = ["| scene | size | spp | depth | renderer | threads | seconds | first call |",
          "|---|---|---|---|---|---|---|---|"]
    md += [f"| {t['scene']} | {t['width']}x{t['height']} | {t['spp']} | {t['max_depth']} | "
           f"{t['renderer']} | {t['threads']} | {t['seconds']:.3f} | "
           f"{t['first_call_seconds']:.3f} |" for t in times]
    (args.out / "bench.md").write_text("\n".join(md) + "\n")
    print(f"wrote {args.out}/bench.csv, bench.md, equal_error.csv, equal_error.svg")
    return 0


if __name__ == "__main__":
    sys.exit(main())
