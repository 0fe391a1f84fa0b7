//! The study's Markdown table.

use super::bound::Bounds;
use super::{Plan, Run};
use std::fmt::Write as _;

/// The table: each scene's ratios uniform/adaptive at each budget, squared errors at equal
/// time (above 1: adaptive is better).
pub fn table(
    runs: &[Run],
    bounds: &[(&str, Bounds)],
    plan: &Plan,
    loads: (&str, &str),
    threads: usize,
) -> String {
    let mut md = String::from("# Adaptive against uniform sampling at equal time\n\n");
    let _ = writeln!(
        md,
        "`cargo run --release --features studies --example equal_time` on {threads} threads, f32, {} pixels wide \
         (the Cornell box {c}×{c}), seed 1, references 2 × {} spp. Load average (1, 5, 15 min) \
         before: {}; after: {}. Each figure is the mean of {} seeds, each an adaptive render \
         given the time the uniform render just before it took.\n",
        plan.width,
        plan.reference_spp,
        loads.0,
        loads.1,
        plan.repeats,
        c = plan.width * 3 / 5,
    );
    md.push_str(
        "Squared error of uniform over adaptive at the same time (above 1: adaptive is lower), \
         for the time uniform sampling takes at each spp: relative (`rel_mse`, the renderer's \
         own measure), as displayed (`display_mse`, sRGB in [0, 1]) and linear (`mse`); and \
         the relative error at equal rays, which the machine's load does not disturb \
         (uniform's error scaled by its rays over adaptive's, as error ∝ 1/work). The last \
         two columns are the most any allocation of samples over the pixels could gain in \
         relative error: at equal samples, `N·Σv²/(Σv)²` from each pixel's per-sample relative \
         deviation `v` (24 renders of 16 spp), and at equal rays, `Σv²·Σc/(Σv√c)²` with `c` \
         the rays a sample of the pixel costs, shadow rays included (each pixel rendered alone, 32 spp), the bound \
         for the column \"rel, equal rays\" (examples/equal_time/bound.rs):\n\n",
    );
    md.push_str("| scene |");
    for level in &plan.adaptive {
        let _ = write!(md, " {level} spp: rel | display | linear | rel, equal rays |");
    }
    md.push_str(" bound, samples | bound, rays |\n|---|");
    md.push_str(&"---|---|---|---|".repeat(plan.adaptive.len()));
    md.push_str("---|---|\n");
    let mut scenes: Vec<&str> = runs.iter().map(|r| r.scene).collect();
    scenes.dedup();
    for scene in scenes {
        let _ = write!(md, "| {scene} |");
        for &level in &plan.adaptive {
            let find = |m| {
                runs.iter()
                    .find(|r| r.scene == scene && r.method == m && r.level == level)
            };
            match (find("uniform"), find("adaptive")) {
                (Some(u), Some(a)) => {
                    let _ = write!(
                        md,
                        " {:.2} | {:.2} | {:.2} | {:.2} |",
                        u.rel_mse / a.rel_mse,
                        u.display_mse / a.display_mse,
                        u.mse / a.mse,
                        u.rel_mse * u.rays / a.rays / a.rel_mse
                    );
                }
                _ => md.push_str(" – | – | – | – |"),
            }
        }
        match bounds.iter().find(|(name, _)| *name == scene) {
            Some((_, b)) => _ = writeln!(md, " {:.2} | {:.2} |", b.samples, b.rays),
            None => md.push_str(" – | – |\n"),
        }
    }
    md
}
