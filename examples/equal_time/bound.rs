//! The most any allocation of samples over pixels could gain: the bound the adaptive
//! renderer is measured against.

use super::{Case, uniform};
use raytrace::prelude::*;
use raytrace::render::adaptive::luminance;
use raytrace::{Image, Rect};

/// Independent renders the per-pixel deviations are estimated from.
const RENDERS: u64 = 24;
/// Samples per pixel of each.
const SPP: u32 = 16;

/// Samples per pixel of the renders that measure each pixel's cost.
const COST_SPP: u32 = 32;

/// The most any allocation could gain: at equal samples, and at equal rays.
#[derive(Clone, Copy, Debug)]
pub struct Bounds {
    /// `N·Σv²/(Σv)²`.
    pub samples: f64,
    /// `Σv²·Σc/(Σv√c)²`.
    pub rays: f64,
}

/// The ratio of uniform's relative squared error to the least any allocation could reach:
/// of the same number of samples, `N·Σv²/(Σv)²`, and of the same number of rays,
/// `Σv²·Σc/(Σv·√c)²`, where `v_i` is pixel `i`'s per-sample relative deviation of luminance
/// (its standard deviation over `max(Ȳ, 0.01)`, `Ȳ` from the references, as `rel_mse`
/// measures it) and `c_i` the rays a sample of it costs.
///
/// A pixel given `n_i` samples has squared relative error `v_i²/n_i`. With `Σn_i = N·n`
/// fixed, the sum is least at `n_i ∝ v_i` (equal marginal gain), where it is
/// `(Σv_i)²/(N·n)`, against `Σv_i²/n` for uniform sampling. With the rays `R = Σc_i·n_i`
/// fixed instead, it is least at `n_i ∝ v_i/√c_i`, where it is `(Σv_i√c_i)²/R`, against
/// `Σv_i²·Σc_i/R`: a pixel that needs samples but whose samples cost most gains less. The
/// deviations come from [`RENDERS`] renders of [`SPP`] samples with seeds of their own (each
/// image a mean of `SPP` samples, so a sample's variance is `SPP` times the images'); each
/// pixel's cost from a render of it alone ([`cost`]).
pub fn bound(case: &Case, r1: &Image, r2: &Image) -> raytrace::Result<Bounds> {
    let images = (0..RENDERS)
        .map(|k| uniform(case, SPP, 2_000_001 + k).map(|r| r.image))
        .collect::<raytrace::Result<Vec<Image>>>()?;
    let width = r1.width();
    let (mut s1, mut s2, mut sc, mut svc) = (0.0, 0.0, 0.0, 0.0);
    for (i, (a, b)) in r1.pixels().iter().zip(r2.pixels()).enumerate() {
        let c = cost(case, i % width, i / width)?;
        let ys: Vec<f64> = images.iter().map(|im| luminance(im.pixels()[i])).collect();
        let mean = ys.iter().sum::<f64>() / RENDERS as f64;
        // The images' variance (unbiased, two passes), times SPP: one sample's.
        let variance =
            ys.iter().map(|y| (y - mean).powi(2)).sum::<f64>() / (RENDERS - 1) as f64 * f64::from(SPP);
        let v = variance.sqrt() / (0.5 * (luminance(*a) + luminance(*b))).max(0.01);
        s1 += v;
        s2 += v * v;
        sc += c;
        svc += v * c.sqrt();
    }
    let n = r1.pixels().len() as f64;
    Ok(Bounds {
        samples: if s1 > 0.0 { n * s2 / (s1 * s1) } else { 1.0 },
        rays: if svc > 0.0 { s2 * sc / (svc * svc) } else { 1.0 },
    })
}

/// The rays a sample of pixel `(x, y)` costs, shadow rays included: a render of that
/// pixel alone, [`COST_SPP`] samples, its rays counted.
fn cost(case: &Case, x: usize, y: usize) -> raytrace::Result<f64> {
    let camera = &*case.camera;
    let render = Renderer::new(&case.scene, &camera)
        .max_depth(case.max_depth)
        .seed(3_000_001)
        .spp(COST_SPP)
        .tile(Rect {
            x,
            y,
            width: 1,
            height: 1,
        })
        .render()?;
    Ok(render.stats.rays as f64 / f64::from(COST_SPP))
}
