#!/usr/bin/env python3
"""The spec's random_spheres beside the C++ of *Ray Tracing: The Next Week*, whole process.

Builds our example (cargo build --release --example random_spheres) and the book's C++
(bench/book/build.sh: fetched at a pinned commit, edited so its scene is ours, see
bench/book/README.md), then runs every program R rounds, interleaved (the order rotates each
round), each run its own process on one thread, and keeps the median of each figure:
  ours-f32, ours-f64   target/release/examples/random_spheres --threads 1 --precision f32|f64
  book-native          the book's C++, g++ -O3 -march=native (ours is built native too)
  book-release         the book's C++, g++ -O3 (its CMake Release flags, no -march)
Wall time is the whole process (start, scene, BVH, render, files); user and system CPU come
from the kernel (wait4), peak memory from GNU time (/usr/bin/time, if present). Once more after
the timed rounds, untimed, our summary line and a counting build of the book's C++ give the rays
each traced. Writes
  <results>/book.csv       the medians: program,rounds,width,height,spp,max_depth,wall_s,user_s,
                           sys_s,peak_mb,rays,mrays_per_wall_s,speedup_vs_<each book build>
  <results>/book_runs.csv  every run
  <results>/book.md        the table, the ratios, the machine, the load and the commit

    python3 bench/book.py                  # the comparison: 400x225, 10 spp, depth 50, 7 rounds
    python3 bench/book.py --quick          # a smoke test: 64x36, 1 spp, 1 round, into /tmp/book-smoke
    BOOK_REPO=/path/to/clone python3 bench/book.py   # the book's sources from a local clone
Run it on an otherwise idle machine. Not run in CI. No dependencies beyond Python 3.8.
"""

import argparse
import csv
import datetime
import os
import re
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OURS = ROOT / "target" / "release" / "examples" / "random_spheres"
BOOK = ROOT / "bench" / "book" / "build"
PROGRAMS = ["ours-f32", "ours-f64", "book-native", "book-release"]
FIGURES = ["wall_s", "user_s", "sys_s", "peak_mb"]
# GNU time reports the program's own peak memory. wait4's ru_maxrss would not: Linux carries
# the spawning Python's resident size into the child's maximum across exec.
GNU_TIME = "/usr/bin/time"


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--rounds", type=int, default=7, help="runs of each program (median kept)")
    p.add_argument("--width", type=int, default=400, help="image width (height = width*9/16)")
    p.add_argument("--spp", type=int, default=10, help="samples per pixel")
    p.add_argument("--programs", default=",".join(PROGRAMS), help="comma-separated, of " + ",".join(PROGRAMS))
    p.add_argument("--cpu", type=int, help="pin every run to this CPU (taskset -c)")
    p.add_argument("--results", type=Path, default=ROOT / "bench" / "results")
    p.add_argument("--no-build", action="store_true", help="use the programs as already built")
    p.add_argument("--quick", action="store_true", help="smoke test: 64x36, 1 spp, 1 round, into /tmp/book-smoke")
    a = p.parse_args()
    if a.quick:
        a.width, a.spp, a.rounds, a.results = 64, 1, 1, Path("/tmp/book-smoke")
    if a.rounds < 1:
        p.error("--rounds must be at least 1")
    a.programs = [x for x in a.programs.split(",") if x]
    unknown = set(a.programs) - set(PROGRAMS)
    if unknown:
        p.error(f"unknown programs {sorted(unknown)}; known: {PROGRAMS}")
    if a.width * 9 % 16:
        # The book's height is int(width / (16/9)), ours width*9/16 (integer division): they
        # agree whenever width*9/16 is whole.
        p.error("--width must be a multiple of 16, so that both programs make the same height")
    return a


def run(cmd, **kw):
    """Runs `cmd` from the repository root, echoing it; stops the benchmark if it fails."""
    print("+", " ".join(str(c) for c in cmd), file=sys.stderr, flush=True)
    result = subprocess.run([str(c) for c in cmd], cwd=ROOT, text=True, **kw)
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(str(c) for c in cmd)}\n{result.stderr or ''}")
    return result


def build():
    run(["cargo", "build", "--release", "--example", "random_spheres"])
    run(["bash", "bench/book/build.sh"])


def command(args, program, out):
    """(command, file its stdout goes to) for one run of `program`, its image in `out`."""
    if program.startswith("ours-"):
        return [OURS, "--threads", 1, "--precision", program[5:], "--width", args.width,
                "--spp", args.spp, "--max-depth", 50, "--seed", 0, "--out", out], os.devnull
    binary = BOOK / ("book-count" if program == "count" else program)
    # The book writes its image to stdout: a file, not a terminal or a pipe to us.
    return [binary, args.width, args.spp], out / f"{program}.ppm"


def timed(cmd, stdout, stderr, cpu):
    """Runs `cmd` once: (wall s, user s, sys s, peak MB); the times from wait4's rusage
    (GNU time's own share is a millisecond, the same for every program), the peak from GNU
    time (NaN without it)."""
    cmd = [str(c) for c in cmd]
    if cpu is not None:
        cmd = ["taskset", "-c", str(cpu)] + cmd
    peak_file = Path(stderr).with_name("peak_kib")
    if os.access(GNU_TIME, os.X_OK):
        cmd = [GNU_TIME, "-f", "%M", "-o", str(peak_file)] + cmd
    with open(stdout, "wb") as out, open(stderr, "wb") as err:
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=ROOT, stdout=out, stderr=err)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
    if status != 0:  # the raw wait status: nonzero for an error exit or a signal
        sys.exit(f"failed (wait status {status}): {' '.join(cmd)}\n{Path(stderr).read_text(errors='replace')}")
    # KiB; MB of 10^6 bytes as bench/scale.py reports.
    peak = int(peak_file.read_text().split()[-1]) * 1024 / 1e6 if cmd[0] == GNU_TIME else float("nan")
    return wall, usage.ru_utime, usage.ru_stime, peak


def ppm_size(path):
    """(width, height) from a PPM's header (P3 or P6)."""
    tokens = re.sub(rb"#[^\n]*", b"", path.read_bytes()[:200]).split()
    return int(tokens[1]), int(tokens[2])


def count_rays(args, out):
    """Rays traced per program, from runs outside the timing: our summary line
    ("render: ... N rays ...") and the book's counting build ("rays N" on stderr)."""
    rays = {}
    for program in args.programs:
        if program.startswith("ours-"):
            cmd, _ = command(args, program, out / program)
            text = run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout
            rays[program] = int(re.search(r"render: .*?(\d+) rays", text).group(1))
    if any(p.startswith("book-") for p in args.programs):
        cmd, ppm = command(args, "count", out)
        with open(ppm, "wb") as image:
            text = run(cmd, stdout=image, stderr=subprocess.PIPE).stderr
        n = int(re.search(r"^rays (\d+)", text, re.M).group(1))
        for program in args.programs:
            if program.startswith("book-"):
                rays[program] = n  # the same code and random numbers: the same rays
    return rays


def machine():
    model = "unknown"
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            model = line.split(":", 1)[1].strip()
            break
    return model, os.cpu_count()


def versions():
    def first_line(cmd):
        try:
            return subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT).stdout.splitlines()[0]
        except (OSError, IndexError):
            return "unknown"
    commit = first_line(["git", "rev-parse", "--short", "HEAD"])
    # Only changes to what is built and run count (the report's data may be mid-edit).
    status = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--", "src", "examples",
                             "bench/book.py", "bench/book", "Cargo.toml", "Cargo.lock", ".cargo"],
                            capture_output=True, text=True, cwd=ROOT).stdout
    if status.strip():
        commit += " (with uncommitted changes)"
    book = (BOOK / "stamp").read_text().split()[0] if (BOOK / "stamp").exists() else "unknown"
    compiler = (BOOK / "compiler").read_text().strip() if (BOOK / "compiler").exists() else "unknown"
    return {"commit": commit, "rustc": first_line(["rustc", "--version"]),
            "rustflags": os.environ.get("RUSTFLAGS", "-C target-cpu=native (.cargo/config.toml)"),
            "book_commit": book, "cxx": compiler}


def write(args, runs, rays, load, info):
    args.results.mkdir(parents=True, exist_ok=True)
    columns = ["round", "program"] + FIGURES
    with open(args.results / "book_runs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, columns)
        w.writeheader()
        w.writerows(runs)
    med = {}
    for program in args.programs:
        mine = [r for r in runs if r["program"] == program]
        med[program] = {k: statistics.median(r[k] for r in mine) for k in FIGURES}
        med[program]["rays"] = rays[program]
    books = [p for p in args.programs if p.startswith("book-")]
    rows = []
    for program in args.programs:
        m = med[program]
        row = {"program": program, "rounds": args.rounds, "width": args.width,
               "height": args.width * 9 // 16, "spp": args.spp, "max_depth": 50,
               **{k: f"{m[k]:.4f}" for k in FIGURES}, "rays": m["rays"],
               "mrays_per_wall_s": f"{m['rays'] / m['wall_s'] / 1e6:.3f}"}
        for b in books:  # how many times faster than each build of the book, by wall time
            row[f"speedup_vs_{b}"] = f"{med[b]['wall_s'] / m['wall_s']:.3f}"
        rows.append(row)
    with open(args.results / "book.csv", "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    model, cores = machine()
    lines = [
        "# random_spheres: this crate against the C++ of *Ray Tracing: The Next Week*", "",
        f"Written by `python3 bench/book.py{' --quick' if args.quick else ''}` on "
        f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC.", "",
        f"- Machine: {model}, {cores} logical CPUs; load average (1, 5, 15 min) "
        f"{'/'.join(f'{x:.2f}' for x in load[0])} before, {'/'.join(f'{x:.2f}' for x in load[1])} after."
        + (f" Every run pinned to CPU {args.cpu}." if args.cpu is not None else ""),
        f"- Ours: commit {info['commit']}, {info['rustc']}, RUSTFLAGS {info['rustflags']}, "
        "`--threads 1`.",
        f"- The book: commit {info['book_commit'][:12]} of RayTracing/raytracing.github.io edited by "
        f"`bench/book/next_week.patch`, {info['cxx']}; `book-native` `-std=c++11 -O3 -DNDEBUG "
        "-march=native`, `book-release` the same without `-march` (single-threaded).",
        f"- Work: {args.width}×{args.width * 9 // 16} pixels, {args.spp} spp, max depth 50 "
        f"({args.width * (args.width * 9 // 16) * args.spp} paths each); the layouts come from different "
        "generators, so the images agree only statistically and the ray counts differ a little.",
        f"- Median of {args.rounds} interleaved rounds, each run its own process: wall time of the "
        "whole process, user and system CPU, peak resident memory (MB of 10⁶ bytes).", "",
        "| program | wall s | user s | sys s | peak MB | rays | Mrays / wall s | "
        + " | ".join(f"× vs {b}" for b in books) + " |",
        "|---" * (7 + len(books)) + "|",
    ]
    for row in rows:
        m = med[row["program"]]
        lines.append(f"| {row['program']} | {m['wall_s']:.3f} | {m['user_s']:.3f} | {m['sys_s']:.3f} | "
                     f"{m['peak_mb']:.1f} | {row['rays']} | {row['mrays_per_wall_s']} | "
                     + " | ".join(row[f"speedup_vs_{b}"] for b in books) + " |")
    lines += ["", "`× vs book-…` is the book's median wall time over the program's: above 1, faster "
              "than the book. The issue's goal is ours ≥ 5× `book-native` in f32 and f64."]
    (args.results / "book.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    args = parse_args()
    if not args.no_build:
        build()
    for program in args.programs:
        binary = command(args, program, Path("/tmp"))[0][0]
        if not Path(binary).exists():
            sys.exit(f"{binary} is missing: run without --no-build (or bash bench/book/build.sh)")
    scratch = Path(os.environ.get("TMPDIR", "/tmp")) / f"book-bench-{os.getpid()}"
    scratch.mkdir(parents=True)
    try:
        load_before = os.getloadavg()
        runs = []
        for r in range(args.rounds):
            # Rotating the order evens out what each program follows (a warm cache, a turbo
            # state) over the rounds.
            k = r % len(args.programs)
            for program in args.programs[k:] + args.programs[:k]:
                out = scratch / program
                out.mkdir(exist_ok=True)
                cmd, stdout = command(args, program, out)
                wall, user, system, peak = timed(cmd, stdout, scratch / "stderr", args.cpu)
                print(f"round {r + 1}/{args.rounds} {program}: {wall:.3f} s wall, {user:.3f} s user",
                      file=sys.stderr, flush=True)
                runs.append({"round": r + 1, "program": program, "wall_s": round(wall, 4),
                             "user_s": round(user, 4), "sys_s": round(system, 4), "peak_mb": round(peak, 2)})
        load_after = os.getloadavg()
        # Both images have the size asked for: the same pixels and samples were traced.
        expected = (args.width, args.width * 9 // 16)
        for program in args.programs:
            ppm = scratch / program / ("random_spheres.ppm" if program.startswith("ours-") else f"{program}.ppm")
            if ppm_size(ppm) != expected:
                sys.exit(f"{program} made a {ppm_size(ppm)} image, not {expected}")
        rays = count_rays(args, scratch)
        write(args, runs, rays, (load_before, load_after), versions())
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
