#!/usr/bin/env python3
"""The scaling benchmark: this crate's renderer against an Embree 3 path tracer doing the same
work, on sphere clouds of 10^2..10^6 spheres and the Stanford dragon at four resolutions
(and, when asked, on `needles:N`, N long thin triangles every way oriented).

Builds both programs, exports every scene once (examples/scale --export, read by
bench/embree/scale.cpp), then for each scene runs every program R rounds, interleaved, each
run in its own process, and keeps the median of each figure. Writes
  <results>/scale.csv       the medians: scene,primitives,program,threads,build_s,mrays_s,rays,peak_mb
  <results>/scale_runs.csv  every run
  <results>/scale.md        the medians as a Markdown table, with the conditions
  <figure>                  Mrays/s against primitive count on the first thread count (SVG,
                            log x axis); <figure stem>_<n>threads.svg for the others

    python3 bench/scale.py                 # the full comparison (default settings)
    python3 bench/scale.py --quick         # a smoke test at 40x20, 1 spp, into /tmp
    python3 bench/scale.py --bvh-quality both --threads 1 --scenes needles:100000,dragon:full \
        --results bench/results/split --figure bench/results/split/split.svg
                                           # our medium and high (spatial splits) builds
No dependencies beyond Python 3.8.
"""

import argparse
import csv
import datetime
import os
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from svg_chart import Series, line_chart  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
OURS = ROOT / "target" / "release" / "examples" / "scale"
EMBREE = ROOT / "bench" / "embree" / "build" / "scale"
SCENE_DIR = ROOT / "bench" / "build" / "scenes"
ALL_SCENES = [f"spheres:{10 ** k}" for k in range(2, 7)] + [
    f"dragon:{r}" for r in ("res4", "res3", "res2", "full")
]
# Both programs run with glibc's mmap threshold fixed at its default of 128 KiB. Left
# dynamic, glibc raises it to the size of each large block freed (up to 32 MiB), after which
# freed blocks stay resident: our build's temporaries then kept up to 42 MB more resident on
# the full dragon. Embree allocates its large blocks itself and is unaffected.
ALLOCATOR = {"MALLOC_MMAP_THRESHOLD_": "131072"}
COLUMNS = ["scene", "primitives", "program", "threads", "build_s", "mrays_s", "rays", "peak_mb"]
COLORS = {"raytrace-f32": "#d62728", "raytrace-f64": "#ff9896", "embree-medium": "#1f77b4",
          "embree-high": "#2ca02c", "raytrace-f32-high": "#9467bd", "raytrace-f64-high": "#c5b0d5"}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--rounds", type=int, default=3, help="runs of each program per scene (median kept)")
    p.add_argument("--threads", default="1,2", help="comma-separated thread counts, for every program")
    p.add_argument("--width", type=int, default=400, help="image width (height = width/2)")
    p.add_argument("--spp", type=int, default=8, help="samples per pixel")
    p.add_argument("--max-depth", type=int, default=10)
    p.add_argument("--scenes", default=",".join(ALL_SCENES), help="comma-separated scene names")
    p.add_argument("--precision", default="f32", choices=["f32", "f64"], help="our renderer's scalar")
    p.add_argument("--bvh-quality", default="medium", choices=["medium", "high", "both"],
                   help="our BVH build: medium, high (spatial splits) or both, as two programs")
    p.add_argument("--glibc-default", action="store_true",
                   help="run both programs with glibc's default, dynamic mmap threshold")
    p.add_argument("--results", type=Path, default=ROOT / "bench" / "results")
    p.add_argument("--figure", type=Path, default=ROOT / "report" / "figures" / "scale.svg")
    p.add_argument("--no-build", action="store_true", help="use the programs as already built")
    p.add_argument("--quick", action="store_true",
                   help="smoke test: 40x20, 1 spp, spheres:100 and dragon:res4, 1 round, into /tmp/scale-smoke")
    a = p.parse_args()
    if a.quick:
        a.width, a.spp, a.rounds, a.scenes = 40, 1, 1, "spheres:100,dragon:res4"
        smoke = Path("/tmp/scale-smoke")
        a.results, a.figure = smoke, smoke / "scale.svg"
    a.threads = [int(t) for t in a.threads.split(",")]
    a.scenes = [s for s in a.scenes.split(",") if s]
    return a


def run(cmd, **kw):
    """Runs `cmd` from the repository root, echoing it; stops the benchmark if it fails."""
    print("+", " ".join(str(c) for c in cmd), file=sys.stderr, flush=True)
    result = subprocess.run([str(c) for c in cmd], cwd=ROOT, text=True, **kw)
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(str(c) for c in cmd)}\n{result.stderr or ''}")
    return result


def build():
    run(["cargo", "build", "--release", "--example", "scale"])
    run(["bash", "bench/embree/build.sh"])


def scene_file(scene):
    return SCENE_DIR / (scene.replace(":", "_") + ".bin")


def programs(args, scene):
    """(program name, threads, command printing one CSV line) for every run of a round."""
    common = ["--width", args.width, "--spp", args.spp, "--max-depth", args.max_depth, "--csv"]
    out = []
    for t in args.threads:
        for quality in ("medium", "high"):
            if args.bvh_quality in (quality, "both"):
                suffix = "-high" if quality == "high" else ""
                out.append((f"raytrace-{args.precision}{suffix}", t,
                            [OURS, "--scene", scene, "--threads", t, "--precision", args.precision,
                             "--bvh-quality", quality] + common))
        for quality in ("medium", "high"):
            out.append((f"embree-{quality}", t, [EMBREE, "--scene", scene_file(scene), "--name", scene,
                                                 "--threads", t, "--quality", quality] + common))
    return out


def measure(cmd, env):
    """One run under `env`: the CSV line it printed, as a dict of typed values."""
    line = run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE).stdout.strip().splitlines()[-1]
    values = next(csv.reader([line]))
    if len(values) != len(COLUMNS):
        sys.exit(f"unexpected output from {cmd[0]}: {line!r}")
    row = dict(zip(COLUMNS, values))
    for k in ("primitives", "threads", "rays"):
        row[k] = int(row[k])
    for k in ("build_s", "mrays_s", "peak_mb"):
        row[k] = float(row[k])
    return row


def medians(runs):
    """One row per (scene, program, threads): the median of each measured figure."""
    groups = {}
    for r in runs:
        groups.setdefault((r["scene"], r["program"], r["threads"]), []).append(r)
    rows = []
    for (scene, program, threads), rs in groups.items():
        row = {"scene": scene, "primitives": rs[0]["primitives"], "program": program, "threads": threads}
        for k in ("build_s", "mrays_s", "peak_mb"):
            row[k] = statistics.median(r[k] for r in rs)
        row["rays"] = int(statistics.median(r["rays"] for r in rs))
        rows.append(row)
    return rows


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{r[k]:.6g}" if isinstance(r[k], float) else r[k]) for k in COLUMNS})


def conditions(args):
    cpu = "unknown CPU"
    try:
        cpu = next(line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, text=True,
                            stdout=subprocess.PIPE).stdout.strip()
    return (f"{datetime.date.today()}, commit `{commit}`, {cpu} ({os.cpu_count()} logical cores), "
            f"{args.width}x{args.width // 2}, {args.spp} spp, max depth {args.max_depth}, "
            f"median of {args.rounds} interleaved round(s), each run its own process, "
            + ("glibc's default allocator settings" if args.glibc_default
               else "both programs with `MALLOC_MMAP_THRESHOLD_=131072`"))


def write_markdown(path, rows, args):
    # The rays are compared with our first program's (the medium build where there is one).
    ours = {}
    for r in sorted(rows, key=lambda r: r["program"]):
        if r["program"].startswith("raytrace"):
            ours.setdefault((r["scene"], r["threads"]), r)
    lines = [
        "# Scaling: this crate against Embree 3", "",
        conditions(args), "",
        "| scene | primitives | program | threads | build s | Mrays/s | ns/ray | rays | rays vs ours | peak MB |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        base = ours.get((r["scene"], r["threads"]))
        diff = f"{100 * (r['rays'] / base['rays'] - 1):+.2f} %" if base and base["rays"] else "–"
        ns = 1e3 / r["mrays_s"] if r["mrays_s"] > 0 else float("nan")
        lines.append(f"| {r['scene']} | {r['primitives']} | {r['program']} | {r['threads']} | "
                     f"{r['build_s']:.4f} | {r['mrays_s']:.2f} | {ns:.0f} | {r['rays']} | {diff} | {r['peak_mb']:.1f} |")
    path.write_text("\n".join(lines) + "\n")


def write_figure(path, rows, threads):
    """Mrays/s against primitives for the runs on `threads` threads: a colour per program,
    solid lines for the sphere clouds, dashed for the dragon."""
    series = []
    for program in sorted({r["program"] for r in rows}):
        for family, dash in (("spheres", ""), ("dragon", "6 4"), ("needles", "2 3")):
            pts = [(r["primitives"], r["mrays_s"]) for r in rows if r["program"] == program
                   and r["threads"] == threads and r["scene"].startswith(family)]
            if pts:
                series.append(Series(f"{program}, {family}", COLORS.get(program, "#7f7f7f"), dash, pts))
    path.parent.mkdir(parents=True, exist_ok=True)
    title = f"Path tracing speed against scene size, {threads} thread{'s' if threads > 1 else ''}"
    path.write_text(line_chart(series, title, "primitives (spheres or triangles)", "Mrays/s"))


def figure_path(figure, threads, first):
    """The figure for the first thread count is `figure`; others get `_<n>threads` added."""
    return figure if threads == first else figure.with_name(f"{figure.stem}_{threads}threads{figure.suffix}")


def main():
    args = parse_args()
    if not args.no_build:
        build()
    SCENE_DIR.mkdir(parents=True, exist_ok=True)
    for scene in args.scenes:
        run([OURS, "--scene", scene, "--export", scene_file(scene)], stdout=subprocess.DEVNULL)
    env = dict(os.environ) if args.glibc_default else {**os.environ, **ALLOCATOR}
    runs = []
    for scene in args.scenes:
        for _ in range(args.rounds):
            for program, threads, cmd in programs(args, scene):
                row = measure(cmd, env)
                runs.append(row)
                print(f"  {scene} {program} {threads}t: build {row['build_s']:.4f} s, "
                      f"{row['mrays_s']:.2f} Mrays/s, {row['rays']} rays, {row['peak_mb']:.1f} MB", flush=True)
    rows = medians(runs)
    args.results.mkdir(parents=True, exist_ok=True)
    write_csv(args.results / "scale_runs.csv", runs)
    write_csv(args.results / "scale.csv", rows)
    write_markdown(args.results / "scale.md", rows, args)
    figures = [figure_path(args.figure, t, args.threads[0]) for t in args.threads]
    for threads, figure in zip(args.threads, figures):
        write_figure(figure, rows, threads)
    print((args.results / "scale.md").read_text())
    print(f"wrote {args.results}/scale.csv, scale_runs.csv, scale.md and", ", ".join(map(str, figures)))


if __name__ == "__main__":
    main()
