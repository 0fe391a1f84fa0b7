//! The χ² harness of the BSDF samplers (`bsdf_chi2.rs`), as pbrt-v4's `bsdfs_test.cpp`
//! and Mitsuba's `chi2` do it: the sampled directions are binned on a `θ × φ` grid over
//! the whole sphere, the expected count of each cell is the sample count times the
//! integral of the material's pdf over the cell (adaptive quadrature), cells expecting
//! fewer than 5 are pooled, and Pearson's statistic is compared with the χ² distribution.
//!
//! Besides the grid, two more bins: draws of a delta lobe (expected: the probability the
//! sampler reports for it) and draws that give no direction (expected: what the pdf and
//! the delta lobe leave, `1 − ∫pdf − P_δ`), so a pdf whose mass is wrong is caught too.
//!
//! # The grid
//! `θ` is measured from an axis the test chooses (the lobe's centre: the mirror or the
//! refracted direction), `φ` about it. Rows are not equal in `θ`: the edges are
//! `θ_k = π·(e^{λk/n} − 1)/(e^λ − 1)`, `λ = max(0, 1.2 ln(1/α))`, so a lobe of roughness
//! `α` as small as 0.01 still spreads over about ten rows near the axis, while `α = 1`
//! gets equal rows. The whole sphere is covered in every case.

use super::{chi2_sf, cross, dot, normalize};
use std::f64::consts::{PI, TAU};

/// Rows of the grid (in `θ`).
pub const ROWS: usize = 40;
/// Columns of the grid (in `φ`).
pub const COLUMNS: usize = 80;
/// Draws per χ² test.
pub const SAMPLES: usize = 1 << 18;

/// What one draw of a sampler gave.
pub enum Draw {
    /// A direction of a non-delta lobe (unit, world space).
    Direction([f64; 3]),
    /// A delta lobe's direction, with the probability the sampler reports for the lobe.
    Delta(f64),
    /// Nothing: the sampler absorbed the ray.
    Absorbed,
}

/// The `θ × φ` grid about an axis.
pub struct Grid {
    axis: [f64; 3],
    t: [f64; 3],
    b: [f64; 3],
    lambda: f64,
}

/// The outcome of one χ² test.
#[derive(Debug)]
pub struct Outcome {
    /// Pearson's statistic.
    pub chi2: f64,
    /// Its degrees of freedom (bins after pooling, less one).
    pub dof: usize,
    /// The p-value.
    pub p: f64,
    /// `∫pdf` over the sphere.
    pub pdf_mass: f64,
    /// Draws in cells where the pdf integrates to 0 (pooled, and reported).
    pub in_empty_cells: u64,
}

impl Outcome {
    /// Rejected at `level`, or with a pdf integrating to more than 1 (beyond the
    /// quadrature's `10⁻³`).
    pub fn rejected(&self, level: f64) -> bool {
        self.p < level || self.pdf_mass > 1.0 + 1e-3
    }
}

impl Grid {
    /// The grid about the unit `axis`, its rows crowded toward it for roughness `alpha`.
    pub fn new(axis: [f64; 3], alpha: f64) -> Self {
        let axis = normalize(axis);
        let helper = if axis[0].abs() < 0.9 {
            [1.0, 0.0, 0.0]
        } else {
            [0.0, 1.0, 0.0]
        };
        let t = normalize(cross(helper, axis));
        let b = cross(axis, t);
        Self {
            axis,
            t,
            b,
            lambda: (1.2 * (1.0 / alpha).ln()).max(0.0),
        }
    }

    /// `θ` at the fraction `s ∈ [0, 1]` of the rows.
    fn theta(&self, s: f64) -> f64 {
        if self.lambda == 0.0 {
            PI * s
        } else {
            PI * (self.lambda * s).exp_m1() / self.lambda.exp_m1()
        }
    }

    /// The fraction of the rows at `θ`.
    fn fraction(&self, theta: f64) -> f64 {
        if self.lambda == 0.0 {
            theta / PI
        } else {
            (theta / PI * self.lambda.exp_m1()).ln_1p() / self.lambda
        }
    }

    /// The cell of the unit direction `d`.
    pub fn cell(&self, d: [f64; 3]) -> usize {
        let theta = dot(d, self.axis).clamp(-1.0, 1.0).acos();
        let row = ((self.fraction(theta) * ROWS as f64) as usize).min(ROWS - 1);
        let phi = dot(d, self.b).atan2(dot(d, self.t)).rem_euclid(TAU);
        let column = ((phi / TAU * COLUMNS as f64) as usize).min(COLUMNS - 1);
        row * COLUMNS + column
    }

    /// The unit direction at `(θ, φ)`.
    fn direction(&self, theta: f64, phi: f64) -> [f64; 3] {
        let (s, c) = theta.sin_cos();
        let (sp, cp) = phi.sin_cos();
        std::array::from_fn(|i| c * self.axis[i] + s * (cp * self.t[i] + sp * self.b[i]))
    }

    /// `∫ pdf dω` over every cell, `dω = sin θ dθ dφ`: on each cell a 4 × 4
    /// Gauss–Legendre rule and the same on its four quarters; where they differ by more
    /// than `max(10⁻⁴·I, tol)`, each quarter is refined the same way, to 7 levels.
    pub fn integrate(&self, pdf: &dyn Fn([f64; 3]) -> f64, tol: f64) -> Vec<f64> {
        let mut out = Vec::with_capacity(ROWS * COLUMNS);
        for row in 0..ROWS {
            let (t0, t1) = (
                self.theta(row as f64 / ROWS as f64),
                self.theta((row + 1) as f64 / ROWS as f64),
            );
            for column in 0..COLUMNS {
                let (p0, p1) = (
                    TAU * column as f64 / COLUMNS as f64,
                    TAU * (column + 1) as f64 / COLUMNS as f64,
                );
                let coarse = self.rule(pdf, [t0, t1], [p0, p1]);
                out.push(self.adapt(pdf, [t0, t1], [p0, p1], coarse, tol, 0));
            }
        }
        out
    }

    fn adapt(
        &self,
        pdf: &dyn Fn([f64; 3]) -> f64,
        t: [f64; 2],
        p: [f64; 2],
        coarse: f64,
        tol: f64,
        depth: u32,
    ) -> f64 {
        let (tm, pm) = (0.5 * (t[0] + t[1]), 0.5 * (p[0] + p[1]));
        let quarters = [
            ([t[0], tm], [p[0], pm]),
            ([t[0], tm], [pm, p[1]]),
            ([tm, t[1]], [p[0], pm]),
            ([tm, t[1]], [pm, p[1]]),
        ];
        let parts = quarters.map(|(t, p)| self.rule(pdf, t, p));
        let fine: f64 = parts.iter().sum();
        if (fine - coarse).abs() <= (1e-4 * fine.abs()).max(tol) || depth >= 7 {
            return fine;
        }
        quarters
            .iter()
            .zip(parts)
            .map(|(&(t, p), part)| self.adapt(pdf, t, p, part, tol, depth + 1))
            .sum()
    }

    /// The 4 × 4 Gauss–Legendre rule on `[t₀, t₁] × [p₀, p₁]`.
    fn rule(&self, pdf: &dyn Fn([f64; 3]) -> f64, t: [f64; 2], p: [f64; 2]) -> f64 {
        const X: [f64; 4] = [
            -0.861_136_311_594_052_6,
            -0.339_981_043_584_856_3,
            0.339_981_043_584_856_3,
            0.861_136_311_594_052_6,
        ];
        const W: [f64; 4] = [
            0.347_854_845_137_453_9,
            0.652_145_154_862_546_1,
            0.652_145_154_862_546_1,
            0.347_854_845_137_453_9,
        ];
        let (tc, th) = (0.5 * (t[0] + t[1]), 0.5 * (t[1] - t[0]));
        let (pc, ph) = (0.5 * (p[0] + p[1]), 0.5 * (p[1] - p[0]));
        let mut sum = 0.0;
        for (xi, wi) in X.iter().zip(W) {
            let theta = tc + th * xi;
            let sin = theta.sin();
            for (xj, wj) in X.iter().zip(W) {
                sum += wi * wj * pdf(self.direction(theta, pc + ph * xj)) * sin;
            }
        }
        sum * th * ph
    }
}

/// Draws `SAMPLES` times, bins the draws and tests them against `pdf` (see the module's
/// docs). A sampler claiming different probabilities for its delta lobe is rejected.
pub fn chi2_sphere(grid: &Grid, mut draw: impl FnMut() -> Draw, pdf: &dyn Fn([f64; 3]) -> f64) -> Outcome {
    let n = SAMPLES as f64;
    let mut counts = vec![0u64; ROWS * COLUMNS];
    let (mut delta, mut absorbed) = (0u64, 0u64);
    let mut delta_probability: Option<f64> = None;
    let mut consistent = true;
    for _ in 0..SAMPLES {
        match draw() {
            Draw::Direction(d) => counts[grid.cell(d)] += 1,
            Draw::Delta(p) => {
                delta += 1;
                let first = *delta_probability.get_or_insert(p);
                consistent &= (p - first).abs() <= 1e-6 * first;
            }
            Draw::Absorbed => absorbed += 1,
        }
    }
    let integrals = grid.integrate(pdf, 1e-3 / n);
    let pdf_mass: f64 = integrals.iter().sum();
    let p_delta = delta_probability.unwrap_or(0.0);
    let mut bins: Vec<(f64, f64)> = Vec::with_capacity(integrals.len() + 2);
    let (mut pooled_o, mut pooled_e, mut in_empty_cells) = (0.0, 0.0, 0);
    for (&o, &i) in counts.iter().zip(&integrals) {
        if i <= 0.0 {
            in_empty_cells += o;
        }
        bins.push((o as f64, n * i.max(0.0)));
    }
    bins.push((delta as f64, n * p_delta));
    bins.push((absorbed as f64, (n * (1.0 - pdf_mass - p_delta)).max(0.0)));
    let mut kept: Vec<(f64, f64)> = Vec::new();
    for (o, e) in bins {
        if e < 5.0 {
            pooled_o += o;
            pooled_e += e;
        } else {
            kept.push((o, e));
        }
    }
    if pooled_e >= 5.0 || kept.is_empty() {
        kept.push((pooled_o, pooled_e));
    } else if let Some(smallest) = kept.iter_mut().min_by(|a, b| a.1.total_cmp(&b.1)) {
        smallest.0 += pooled_o;
        smallest.1 += pooled_e;
    }
    let chi2: f64 = kept
        .iter()
        .map(|&(o, e)| {
            if e > 0.0 {
                (o - e) * (o - e) / e
            } else if o > 0.0 {
                f64::INFINITY
            } else {
                0.0
            }
        })
        .sum();
    let dof = kept.len().saturating_sub(1).max(1);
    let p = if consistent && chi2.is_finite() {
        chi2_sf(chi2, dof as u32)
    } else {
        0.0
    };
    Outcome {
        chi2,
        dof,
        p,
        pdf_mass,
        in_empty_cells,
    }
}
