#!/usr/bin/env python3
"""Times the README's performance renders with two builds side by side.

Each round runs every case once with each build, alternating, so both see the same load on
a shared machine; the table gives each build's median render time (as the examples print
it, files excluded) and the median of the per-round ratios.

    git worktree add --detach /tmp/base 062576b
    (cd /tmp/base && CARGO_TARGET_DIR=/tmp/base-target cargo build --release --examples)
    cargo build --release --examples
    python3 tools/speed_vs.py /tmp/base-target/release/examples target/release/examples
"""

import argparse
import re
import statistics
import subprocess
import tempfile
from pathlib import Path

CASES = [
    ("four_mirrors", "--width 800 --spp 10 --max-depth 10 --threads 1 --precision f32"),
    ("four_mirrors", "--width 800 --spp 10 --max-depth 10 --threads 1 --precision f64"),
    ("random_spheres", "--width 400 --spp 10 --max-depth 50 --threads 1 --precision f32"),
    ("random_spheres", "--width 400 --spp 10 --max-depth 50 --threads 1 --precision f64"),
    ("random_spheres", "--width 400 --spp 10 --max-depth 50 --threads 2 --precision f32"),
    ("random_spheres", "--width 400 --spp 10 --max-depth 50 --threads 2 --precision f64"),
    ("matte_spheres", "--width 800 --spp 16 --max-depth 10 --threads 2 --precision f32"),
    ("matte_spheres", "--width 800 --spp 16 --max-depth 10 --threads 2 --precision f64"),
]

RENDER = re.compile(r"render: ([0-9.]+) s, ([0-9]+) rays")


def run(exe: Path, args: str, out: str) -> tuple[float, int]:
    """One render's time in seconds and its ray count."""
    text = subprocess.run(
        [str(exe), *args.split(), "--out", out], capture_output=True, text=True, check=True
    ).stdout
    found = RENDER.search(text)
    if found is None:
        raise SystemExit(f"{exe} {args}: no 'render:' line in its output")
    return float(found.group(1)), int(found.group(2))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("base", type=Path, help="the old build's examples folder")
    parser.add_argument("new", type=Path, help="the new build's examples folder")
    parser.add_argument("--rounds", type=int, default=11, help="interleaved runs per case")
    opts = parser.parse_args()
    print("| render | base | new | new Mrays/s | new / base time |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as out:
        for name, args in CASES:
            base, new, ratios, rays = [], [], [], 0
            for _ in range(opts.rounds):
                b, _ = run(opts.base / name, args, out)
                n, rays = run(opts.new / name, args, out)
                base.append(b)
                new.append(n)
                ratios.append(n / b)
            median = statistics.median(new)
            print(
                f"| `{name} {args}` | {statistics.median(base):.3f} s | {median:.3f} s "
                f"| {rays / median / 1e6:.1f} | {statistics.median(ratios):.3f} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
