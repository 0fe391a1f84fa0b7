//! The harness of the light samplers' statistical tests (`emitter_chi2.rs`,
//! `triangle_light_chi2.rs`): χ² of samples mapped to `(u, v) ∈ [0, 1)²`, χ² of a choice
//! among a few items, the z-score of a mean density, and the triangle and mesh both test.

use super::{CHI2_ALPHA, bin_of, chi2_against, chi2_equiprobable, chi2_sf, dot};
use rand::SeedableRng;
use rand::rngs::Xoshiro256PlusPlus;
use raytrace::sampling::uniform;
use raytrace::{Float, Mesh, Vec3};
use std::f64::consts::TAU;

type Rng = Xoshiro256PlusPlus;

/// Draws per χ² test.
pub const SAMPLES: usize = 1 << 20;
/// Draws per test of a mean density.
pub const MEAN_SAMPLES: usize = 1 << 18;
/// The largest |z| a correct mean may show: two-sided `p ≈ 5.7·10⁻⁷`.
pub const Z_MAX: f64 = 5.0;

/// The outcome of a χ² test on `(u, v)`.
#[derive(Debug)]
pub struct Verdict {
    /// p-values of the `u` bins, the `v` bins and the joint grid.
    pub p: [f64; 3],
    /// Samples impossible under the claimed distribution.
    pub impossible: u64,
}

impl Verdict {
    pub fn rejected(&self) -> bool {
        self.impossible > 0 || self.p.iter().any(|&p| p < CHI2_ALPHA)
    }
}

/// Draws `SAMPLES` triples of uniform numbers from a generator seeded by `seed`, maps
/// each with `map` to `(u, v)` (`None`: impossible), and tests `u`, `v` and `(u, v)`.
pub fn chi2_uv(seed: u64, mut map: impl FnMut([f64; 3]) -> Option<(f64, f64)>) -> Verdict {
    let (mut u_bins, mut v_bins, mut joint) = ([0u64; 20], [0u64; 24], [0u64; 96]);
    let mut rng = Rng::seed_from_u64(seed);
    let mut impossible = 0;
    for _ in 0..SAMPLES {
        let draw = [uniform(&mut rng), uniform(&mut rng), uniform(&mut rng)];
        let Some((u, v)) = map(draw) else {
            impossible += 1;
            continue;
        };
        u_bins[bin_of(u, 20)] += 1;
        v_bins[bin_of(v, 24)] += 1;
        joint[bin_of(u, 8) * 12 + bin_of(v, 12)] += 1;
    }
    let p = |bins: &[u64]| chi2_sf(chi2_equiprobable(bins), bins.len() as u32 - 1);
    Verdict {
        p: [p(&u_bins), p(&v_bins), p(&joint)],
        impossible,
    }
}

pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn len(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// `φ/2π ∈ [0, 1)` of `d` about the axis of the frame `(t, b)`.
pub fn azimuth(d: [f64; 3], (t, b): ([f64; 3], [f64; 3])) -> f64 {
    (dot(d, b).atan2(dot(d, t)) / TAU).rem_euclid(1.0)
}

/// `mean(1/p)` and the z-score of its difference from `want`, over `MEAN_SAMPLES` draws
/// (a draw giving `None` is an error).
pub fn mean_inverse_density(seed: u64, want: f64, mut pdf: impl FnMut([f64; 3]) -> f64) -> (f64, f64) {
    let mut rng = Rng::seed_from_u64(seed);
    let (mut sum, mut sum2) = (0.0, 0.0);
    for _ in 0..MEAN_SAMPLES {
        let x = 1.0 / pdf([uniform(&mut rng), uniform(&mut rng), uniform(&mut rng)]);
        sum += x;
        sum2 += x * x;
    }
    let n = MEAN_SAMPLES as f64;
    let mean = sum / n;
    let var = (sum2 / n - mean * mean).max(0.0) * n / (n - 1.0);
    (mean, (mean - want) / (var / n).sqrt().max(f64::MIN_POSITIVE))
}

/// Counts of which of `n` items `pick` chooses over `SAMPLES` uniform numbers, and the
/// χ² p-value against `shares`.
pub fn choice_p(seed: u64, shares: &[f64], mut pick: impl FnMut([f64; 3]) -> usize) -> f64 {
    let mut counts = vec![0u64; shares.len()];
    let mut rng = Rng::seed_from_u64(seed);
    for _ in 0..SAMPLES {
        counts[pick([uniform(&mut rng), uniform(&mut rng), uniform(&mut rng)])] += 1;
    }
    chi2_sf(chi2_against(&counts, shares), shares.len() as u32 - 1)
}

/// A triangle off every axis.
pub const TRIANGLE: [[f64; 3]; 3] = [[-1.0, 0.2, -3.0], [2.0, -0.5, -4.0], [0.3, 2.5, -3.5]];

/// Four disjoint triangles of areas 1, 2, 3 and 10 (right triangles with legs `√(2A)`).
pub fn four_triangles<F: Float>() -> (Mesh<F>, [f64; 4]) {
    let areas: [f64; 4] = [1.0, 2.0, 3.0, 10.0];
    let mut vertices = Vec::new();
    for (k, area) in areas.iter().enumerate() {
        let (x, leg) = (10.0 * k as f64, (2.0 * area).sqrt());
        vertices.extend([
            Vec3::from_f64(x, 0.0, -5.0),
            Vec3::from_f64(x + leg, 0.0, -5.0),
            Vec3::from_f64(x, leg, -5.0),
        ]);
    }
    let triangles = (0..4).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
    (Mesh::new(vertices, triangles).unwrap(), areas)
}
