#!/usr/bin/env python3
"""Times the example renders the report's speed table shows (stdlib only).

    python3 report/tools/speed.py [--rounds R] [--bin target/release/examples] [--out CSV]

Runs every configuration below once per round, the rounds interleaved (each run its own
process, writing its files to a temporary folder), and keeps the render time each example
prints ("render: 0.137 s, 5486510 rays, 40.05 Mrays/s on 1 thread"). Writes one row per
configuration: the median, fastest and slowest render time, the rays, and Mrays/s at the
median time. Beside it, <out>_memory.csv: the peak resident size (ru_maxrss of the child) of
a 1920×1080 render of random_spheres at 1 spp on two threads, and its image buffer's bytes.
Build first: cargo build --release --examples. Run it on an otherwise idle machine.
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import tempfile

CONFIGS = [
    # (id, example, threads, extra arguments)
    ("four_mirrors-10spp", "four_mirrors", 1, ["--spp", "10"]),
    ("random_spheres", "random_spheres", 1, []),
    ("random_spheres", "random_spheres", 2, []),
    ("matte_spheres", "matte_spheres", 2, []),
]
PRECISIONS = ["f32", "f64"]
HEAD = re.compile(r"^(\w+): (\d+)×(\d+) pixels, (\d+) spp, max depth (\d+), (\w+), seed (\d+)", re.M)
STATS = re.compile(r"render: ([\d.]+) s, (\d+) rays, ([\d.]+) Mrays/s on (\d+) threads?")


def run(binary, args, out):
    proc = subprocess.run([binary, *args, "--out", out], capture_output=True, text=True)
    stdout = proc.stdout
    if proc.returncode != 0:
        raise SystemExit(f"speed.py: {binary} {' '.join(args)} failed:\n{proc.stderr}")
    h, s = HEAD.search(stdout), STATS.search(stdout)
    if not (h and s):
        raise SystemExit(f"speed.py: cannot read the summary of {binary}:\n{stdout}")
    return h, s


def peak_kb(binary, args, out):
    """Peak resident set of one run, kB (Linux ru_maxrss)."""
    pid = os.fork()
    if pid == 0:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        os.execv(binary, [binary, *args, "--out", out])
    _, status, usage = os.wait4(pid, 0)
    if status != 0:
        raise SystemExit(f"speed.py: {binary} {' '.join(args)} failed")
    return usage.ru_maxrss


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=11)
    ap.add_argument("--bin", default="target/release/examples")
    ap.add_argument("--out", default="report/data/speed.csv")
    o = ap.parse_args()
    jobs = [(cid, ex, th, extra, p) for cid, ex, th, extra in CONFIGS for p in PRECISIONS]
    times = {j: [] for j in range(len(jobs))}
    info = {}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(o.rounds):
            for j, (cid, ex, th, extra, p) in enumerate(jobs):
                args = ["--threads", str(th), "--precision", p, *extra]
                h, s = run(os.path.join(o.bin, ex), args, tmp)
                times[j].append(float(s.group(1)))
                info[j] = (h, s, args)
            print(f"round {r + 1}/{o.rounds} done", flush=True)
        mem_args = ["--width", "1920", "--spp", "1", "--threads", "2", "--precision", "f64"]
        peak = peak_kb(os.path.join(o.bin, "random_spheres"), mem_args, tmp)
    with open(o.out, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["id", "example", "command", "width", "height", "spp", "max_depth", "precision",
                    "threads", "runs", "median_s", "min_s", "max_s", "rays", "mrays_median", "mrays_best"])
        for j, (cid, ex, th, extra, p) in enumerate(jobs):
            h, s, args = info[j]
            t = times[j]
            rays = int(s.group(2))
            med = statistics.median(t)
            w.writerow([cid, ex, f"target/release/examples/{ex} {' '.join(args)}", h.group(2), h.group(3),
                        h.group(4), h.group(5), p, th, len(t), f"{med:.4f}", f"{min(t):.4f}", f"{max(t):.4f}",
                        rays, f"{rays / med / 1e6:.2f}", f"{rays / min(t) / 1e6:.2f}"])
    with open(os.path.splitext(o.out)[0] + "_memory.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["command", "width", "height", "peak_kb", "image_bytes"])
        w.writerow(["target/release/examples/random_spheres " + " ".join(mem_args), 1920, 1080, peak,
                    1920 * 1080 * 3 * 8])
    print(f"wrote {o.out}")


if __name__ == "__main__":
    main()
