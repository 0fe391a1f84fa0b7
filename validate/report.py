"""The comparison's table (CSV and Markdown) and its difference images."""

from __future__ import annotations

import csv
import math
import platform
import subprocess
from pathlib import Path

import mitsuba as mi

import convert
import images
import stats
from scene_model import Scene

COLUMNS = ["kind", "scene", "precision", "injection", "size", "spp", "max_depth",
           "mitsuba_max_depth", "mean_ours", "mean_mitsuba", "t_r", "t_g", "t_b",
           "block_t_max", "blocks", "tests", "p_min", "p_threshold", "rmse", "rmse_noise",
           "rmse_ratio", "verdict"]


def _rgb(v) -> str:
    return " ".join(f"{x:.4f}" for x in v)


def row(kind, scene: Scene, precision, injection, width, shape, spp, depth, v: stats.Verdict) -> dict:
    return row_named(kind, scene.name, convert.scene_depth(scene, depth), precision, injection,
                     shape, spp, depth, v)


def row_named(kind, name: str, mitsuba_depth, precision, injection, shape, spp, depth,
              v: stats.Verdict) -> dict:
    """A row of the table for the scene `name`, Mitsuba's max_depth given."""
    if kind == "agreement":
        verdict = "pass" if v.passed else "FAIL"
    elif kind == "power":
        verdict = "rejected" if not v.passed else "NOT REJECTED"
    else:  # informational: what the file's Schlick reflectance changes
        verdict = "differs" if not v.passed else "within noise"
    return {"kind": kind, "scene": name, "precision": precision, "injection": injection,
            "size": f"{shape[1]}x{shape[0]}", "spp": spp, "max_depth": depth,
            "mitsuba_max_depth": mitsuba_depth,
            "mean_ours": _rgb(v.mean_ours), "mean_mitsuba": _rgb(v.mean_mitsuba),
            "t_r": f"{v.z_channel[0]:.2f}", "t_g": f"{v.z_channel[1]:.2f}",
            "t_b": f"{v.z_channel[2]:.2f}", "block_t_max": f"{v.block_t_max:.2f}",
            "blocks": v.blocks, "tests": v.tests, "p_min": f"{v.p_min:.3g}",
            "p_threshold": f"{v.threshold_p:.3g}", "rmse": f"{v.rmse:.5f}",
            "rmse_noise": f"{v.rmse_noise:.5f}", "rmse_ratio": f"{v.rmse_ratio:.3f}",
            "verdict": verdict}


def _md_table(rows: list[dict], cols: list[str]) -> list[str]:
    out = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    out += ["| " + " | ".join(str(r[c]) for c in cols) + " |" for r in rows]
    return out


def _commit() -> str:
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write(out: Path, mode: str, cfg: dict, rows, pngs, furnace, probe, times, elapsed,
          skipped: list) -> bool:
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "comparison.csv", "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS)
        w.writeheader()
        w.writerows(rows)
    probe_cols = list(probe[0].keys())
    with open(out / "fresnel_probe.csv", "w", newline="") as f:
        w = csv.DictWriter(f, probe_cols)
        w.writeheader()
        w.writerows(probe)
    with open(out / "furnace.csv", "w", newline="") as f:
        w = csv.DictWriter(f, list(furnace[0].keys()))
        w.writeheader()
        w.writerows(furnace)
    scale = 4 if mode == "quick" else 2
    for name, o, m, v in pngs:
        if name.endswith("-f32"):
            continue  # the f64 picture of the same scene looks the same
        t_star = _t_star(v)
        images.comparison_png(out / "png" / f"{name}.png", o[0], o[1], m[0], m[1],
                              v.block_t, stats.BLOCK, t_star, scale)

    agree = [r for r in rows if r["kind"] == "agreement"]
    power = [r for r in rows if r["kind"] == "power"]
    schl = [r for r in rows if r["kind"] == "schlick"]
    ok = all(r["verdict"] == "pass" for r in agree) and \
        all(r["verdict"] == "rejected" for r in power) and \
        all(r["passed"] for r in furnace) and all(r["passed"] for r in probe)
    cols = ["scene", "precision", "size", "spp", "max_depth", "mitsuba_max_depth", "t_r",
            "t_g", "t_b", "block_t_max", "blocks", "p_min", "p_threshold", "rmse_ratio",
            "verdict"]
    md = [f"# Cross-check against Mitsuba {mi.__version__} ({mode} mode): "
          f"{'PASS' if ok else 'FAIL'}", "",
          f"Commit `{_commit()}`, Mitsuba `{mi.variant()}`, {platform.machine()}, "
          f"{elapsed:.0f} s in all. Every converted scene's image {cfg['width']} px wide at "
          f"{cfg['spp']} spp (an XML file's: as its row says), "
          f"seeds {', '.join(map(str, (1, 2)))} for each renderer; blocks of "
          f"{stats.BLOCK}x{stats.BLOCK} pixels. A comparison fails when any of its "
          f"whole-image or block tests has p below {stats.ALPHA:g} / (its number of tests) "
          "(Bonferroni): at most a 0.1 % chance that a correct converter fails it. "
          "`t_r, t_g, t_b`: whole-image t per channel; `rmse_ratio`: RMSE of the difference "
          "over the RMSE noise alone would give (about 1 when they agree). "
          "Method: validate/stats.py; conventions: validate/convert.py. Scenes named "
          "`xml/NAME` are one Mitsuba XML file (validate/xml/) read by both renderers, no "
          "converter between: their `max_depth` is the file's, as both read it.", ""]
    if skipped:
        md += [f"Skipped, their meshes not fetched (`bash tools/fetch_meshes.sh`): "
               f"{', '.join(skipped)}.", ""]
    md += ["## Agreement", ""] + _md_table(agree, cols) + [""]
    if schl:
        md += ["## What Schlick's approximation changes", "",
               "These scenes ask for Schlick's reflectance; the agreement rows above render "
               "them with exact Fresnel (Mitsuba has no Schlick). Rendered as written:", ""]
        md += _md_table(schl, cols) + [""]
    if power:
        md += ["## Power: injected mistakes must be rejected", ""]
        md += _md_table(power, ["scene", "injection", "t_r", "t_g", "t_b", "block_t_max",
                                "p_min", "p_threshold", "rmse_ratio", "verdict"]) + [""]
    md += ["## White furnace", "", "A Lambertian sphere, albedo a = (0.9, 0.6, 0.3), under a "
           "solid background L = 0.8: the pixels wholly inside it must show a*L "
           "(ours: exactly, up to the f32 rounding of the PFM file; Mitsuba: in the mean).", ""]
    for r in furnace:
        r2 = dict(r, measured=_rgb(r["measured"]), expected=_rgb(r["expected"]),
                  stat=f"{r['stat']:.3g}", passed="pass" if r["passed"] else "FAIL")
        md += [f"- {r2['renderer']}: expected {r2['expected']}, measured {r2['measured']}; "
               f"{r2['stat_name']} {r2['stat']} ({r2['criterion']}): {r2['passed']}"]
    md += ["", "## Fresnel probe", "",
           f"Reflectance of a glass plane at incidence theta, measured as the mean of "
           f"{8 * 4 * 4096} Bernoulli samples; z against the formula each should follow "
           f"(|z| < {probe[0]['z_star']:.2f}: alpha 1e-3 over {3 * len(probe)} tests). "
           "`z schlick vs exact` is the Schlick render against the exact reflectance: "
           "the measured Schlick error.", ""]
    pcols = ["index", "theta", "R_exact", "R_schlick", "mitsuba", "ours f64",
             "ours f64 schlick", "z mitsuba", "z ours f64", "z ours f64 schlick",
             "z schlick vs exact"]
    md += _md_table([{c: (f"{r[c]:.4f}" if isinstance(r[c], float) else r[c]) for c in pcols}
                     for r in probe], pcols) + [""]
    md += ["## Render times (wall clock, this machine, shared)", ""]
    total: dict[str, float] = {}
    for t in times:
        total[t["renderer"]] = total.get(t["renderer"], 0.0) + t["seconds"]
    md += [f"- {k}: {v:.1f} s over {sum(1 for t in times if t['renderer'] == k)} renders"
           for k, v in sorted(total.items())]
    md += ["", "Difference images: `png/` (ours | Mitsuba | difference / noise | block |t|)."]
    (out / "comparison.md").write_text("\n".join(md) + "\n")
    return ok


def _t_star(v: stats.Verdict) -> float:
    """The |t| a block needs to fail, read as a normal quantile (for the picture only)."""
    lo, hi = 0.0, 40.0
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if stats.normal_two_sided(mid) > v.threshold_p else (lo, mid)
    return hi if math.isfinite(hi) else 5.0
