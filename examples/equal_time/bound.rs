//! The most any allocation of samples over pixels could gain: the bound the adaptive
//! renderer is measured against.

use super::{Case, uniform};
use raytrace::Image;
use raytrace::render::adaptive::luminance;

/// Independent renders the per-pixel deviations are estimated from.
const RENDERS: u64 = 24;
/// Samples per pixel of each.
const SPP: u32 = 16;

/// The ratio of uniform's relative squared error to the least any allocation of the same
/// number of samples could reach, `N·Σv²/(Σv)²`, where `v_i` is pixel `i`'s per-sample
/// relative deviation of luminance (its standard deviation over `max(Ȳ, 0.01)`, `Ȳ` from
/// the references, as `rel_mse` measures it).
///
/// A pixel given `n_i` samples has squared relative error `v_i²/n_i`; with `Σn_i = N·n`
/// fixed, the sum is least at `n_i ∝ v_i` (equal marginal gain), where it is
/// `(Σv_i)²/(N·n)`, against `Σv_i²/n` for uniform sampling. The deviations come from
/// [`RENDERS`] renders of [`SPP`] samples with seeds of their own (each image a mean of
/// `SPP` samples, so a sample's variance is `SPP` times the images'). It assumes every
/// sample of every pixel costs the same; the renderer's allocation also weighs the cost.
pub fn bound(case: &Case, r1: &Image, r2: &Image) -> raytrace::Result<f64> {
    let images = (0..RENDERS)
        .map(|k| uniform(case, SPP, 2_000_001 + k).map(|r| r.image))
        .collect::<raytrace::Result<Vec<Image>>>()?;
    let (mut s1, mut s2) = (0.0, 0.0);
    for (i, (a, b)) in r1.pixels().iter().zip(r2.pixels()).enumerate() {
        let ys: Vec<f64> = images.iter().map(|im| luminance(im.pixels()[i])).collect();
        let mean = ys.iter().sum::<f64>() / RENDERS as f64;
        // The images' variance (unbiased, two passes), times SPP: one sample's.
        let variance =
            ys.iter().map(|y| (y - mean).powi(2)).sum::<f64>() / (RENDERS - 1) as f64 * f64::from(SPP);
        let v = variance.sqrt() / (0.5 * (luminance(*a) + luminance(*b))).max(0.01);
        s1 += v;
        s2 += v * v;
    }
    let n = r1.pixels().len() as f64;
    Ok(if s1 > 0.0 { n * s2 / (s1 * s1) } else { 1.0 })
}
