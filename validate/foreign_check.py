"""Scenes this project has never seen: Mitsuba XML files written by others (Mitsuba's
documentation scenes, its test suite, its sample scenes, a point-cloud figure script's
scene; validate/foreign/README.md says where each comes from and what was edited), read by Mitsuba (`mi.load_file`) and by this
renderer (`raytrace render scene.xml`) from the same file and compared within noise by
stats.py, as the project's own XML files are (xml_check.py).

Each scene takes its size and spp as $-defaults (the originals' values, or an edit that
made them so: the README lists it); each mode passes them with -D to both renderers.
A scene this renderer refuses (an import error) is a row of its own, `not read`, with the
message: the report says so rather than stopping.
"""

from __future__ import annotations

import csv
import subprocess
import time
from pathlib import Path

import mitsuba as mi

import images
import renders
import report
import stats
import xml_check

HERE = Path(__file__).resolve().parent
FOREIGN = HERE / "foreign"
# Per scene: its file, and the size and spp each mode renders it at (its aspect is the
# file's). The spp are high where the light is small or seen through mirrors.
SCENES = {
    "cbox_rgb": ("mitsuba-data/scenes/cbox/cbox-rgb.xml",
                 {"quick": dict(res=48, spp=128), "full": dict(res=128, spp=512)}),
    "veach_mis": ("mitsuba-data/docs/scenes/integrator_direct_both.xml",
                  {"quick": dict(width=72, height=48, spp=128),
                   "full": dict(width=192, height=128, spp=512)}),
    "hello": ("mitsuba-data/scenes/hello.xml",
              {"quick": dict(width=64, height=48, spp=64), "full": dict(width=128, height=96, spp=256)}),
    # The same with emitter_samples 1 in both: Mitsuba's direct integrator counts a point
    # light emitter_samples times (README.md), so this is what the rest of hello is checked by.
    "hello_emitter_samples_1": ("mitsuba-data/scenes/hello.xml",
                                {"quick": dict(width=64, height=48, spp=64, emitter_samples=1),
                                 "full": dict(width=128, height=96, spp=256, emitter_samples=1)}),
    "floating_sphere": ("mitsuba-data/tests/scenes/floating_sphere/test_directional_direct.xml",
                        {"quick": dict(width=48, height=48, spp=128),
                         "full": dict(width=96, height=96, spp=512)}),
    "instancing": ("mitsuba-data/tests/scenes/instancing/test_instancing_path.xml",
                   {"quick": dict(width=64, height=64, spp=128),
                    "full": dict(width=128, height=128, spp=512)}),
    "infinite_mirrors": ("mitsuba-data/tests/scenes/infinite_mirrors/scene_path.xml",
                         {"quick": dict(width=32, height=32, spp=128),
                          "full": dict(width=96, height=96, spp=512)}),
    "twosided_cbox": ("mitsuba-data/docs/scenes/bsdf_twosided_cbox.xml",
                      {"quick": dict(res=48, spp=128), "full": dict(res=128, spp=512)}),
    "twosided_cbox_onesided": ("mitsuba-data/docs/scenes/bsdf_twosided_cbox_onesided.xml",
                               {"quick": dict(res=48, spp=128), "full": dict(res=128, spp=512)}),
    "pointcloud": ("pointcloud/pointcloud.xml",
                   {"quick": dict(width=96, height=54, spp=128),
                    "full": dict(width=192, height=108, spp=512)}),
}


def run(mode: str, work: Path, rows, pngs, times, errors: list) -> None:
    """Every foreign scene at `mode`'s size; a scene either renderer refuses goes into
    `errors` as (name, message)."""
    for name, (rel, sizes) in SCENES.items():
        print(f"== foreign/{name}", flush=True)
        try:
            xml_check.compare(FOREIGN / rel, sizes[mode], work, rows, pngs, times,
                              xml_check.PRECISIONS[mode], name=f"foreign/{name}")
        except subprocess.CalledProcessError as e:
            errors.append((name, "this renderer: " + (e.stderr or b"").decode().strip()))
        except Exception as e:  # noqa: BLE001 -- Mitsuba's loader refuses what it cannot read
            errors.append((name, f"Mitsuba: {e}"))


def write(out: Path, mode: str, rows, pngs, errors, times, elapsed: float) -> bool:
    """comparison.csv, comparison.md and the difference images of the foreign scenes."""
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "comparison.csv", "w", newline="") as f:
        w = csv.DictWriter(f, report.COLUMNS)
        w.writeheader()
        w.writerows(rows)
    for name, o, m, v in pngs:
        if not name.endswith("-f32"):
            images.comparison_png(out / "png" / f"{name}.png", o[0], o[1], m[0], m[1],
                                  v.block_t, stats.BLOCK, report._t_star(v), 2)
    ok = not errors and all(r["verdict"] == "pass" for r in rows)
    cols = ["scene", "precision", "size", "spp", "max_depth", "t_r", "t_g", "t_b",
            "block_t_max", "blocks", "p_min", "p_threshold", "rmse_ratio", "verdict"]
    md = [f"# Scenes from elsewhere against Mitsuba {mi.__version__} ({mode} mode): "
          f"{'PASS' if ok else 'FAIL'}", "",
          f"Commit `{report._commit()}`, Mitsuba `{mi.variant()}`, {elapsed:.0f} s in all. "
          "Each file is read by both renderers as it is (validate/foreign/README.md: where "
          "each comes from, what was edited); seeds 1 and 2 each; the test of "
          "validate/stats.py (blocks of 8x8 pixels, Bonferroni at 0.1 % per comparison). "
          "`max_depth` is the file's, as Mitsuba counts it.", ""]
    md += _md(rows, cols)
    if errors:
        md += ["", "## Not read", ""] + [f"- `{n}`: {msg}" for n, msg in errors]
    total: dict[str, float] = {}
    for t in times:
        total[t["renderer"]] = total.get(t["renderer"], 0.0) + t["seconds"]
    md += ["", "## Render times (wall clock, this machine, shared)", ""]
    md += [f"- {k}: {v:.1f} s over {sum(1 for t in times if t['renderer'] == k)} renders"
           for k, v in sorted(total.items())]
    md += ["", "Difference images: `png/` (ours | Mitsuba | difference / noise | block |t|)."]
    (out / "comparison.md").write_text("\n".join(md) + "\n")
    return ok


def _md(rows, cols) -> list[str]:
    out = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    return out + ["| " + " | ".join(str(r[c]) for c in cols) + " |" for r in rows]


def main_foreign(mode: str, work: Path, out: Path) -> bool:
    """The foreign set alone (compare.py --foreign)."""
    start = time.perf_counter()
    rows, pngs, errors = [], [], []
    run(mode, work, rows, pngs, renders.TIMES, errors)
    ok = write(out, mode, rows, pngs, errors, renders.TIMES, time.perf_counter() - start)
    print(f"{'PASS' if ok else 'FAIL'}: results in {out}")
    return ok
