//! An environment map: an equirectangular (latitude–longitude) HDR image around the
//! scene, in Mitsuba 3's `envmap` conventions, importance-sampled by its luminance.

use crate::error::{Error, Field, Result};
use crate::sampling::Distribution2D;
use std::f64::consts::{PI, TAU};

/// Mitsuba's (and Rec. 709's) luminance of a linear RGB colour.
#[inline]
pub fn luminance([r, g, b]: [f64; 3]) -> f64 {
    0.212671 * r + 0.715160 * g + 0.072169 * b
}

/// The radiance around the scene as an image of `width × height` linear RGB texels, and
/// the distribution its directions are drawn from.
///
/// # Conventions (Mitsuba 3's `envmap`)
/// A direction `d` (in the map's own frame, before its rotation) has coordinates
/// `u = atan2(d_x, −d_z)/2π` (wrapped into `[0, 1)`) and `v = acos(d_y)/π`: `+y` is the
/// top row, and `u = 0` looks down `−z`. Columns are texel-centred, column `i` at
/// `u = (i + ½)/W`, periodic in `u`; rows are corner-aligned, row `j` at
/// `θ = πj/(H − 1)`, clamped at the poles. The radiance is the bilinear interpolation
/// of the four texels around `(u·W − ½, v·(H − 1))`, times the map's scale.
///
/// # Sampling
/// The square `[0, 1)²` of `(u, v)` is cut into `W × H` equal cells, each weighted by the
/// largest luminance among the texels its bilinear lookups reach times `sin θ` at its
/// centre, and sampled piecewise-constant ([`Distribution2D`]): the density of a direction
/// is `p(u, v)/(2π²·sin θ)` per unit solid angle, the Jacobian of `(u, v) ↦ d`. Taking the
/// largest luminance of the texels keeps the density positive wherever the radiance is.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvironmentMap {
    width: usize,
    height: usize,
    texels: Vec<[f32; 3]>,
    scale: f64,
    distribution: Option<Distribution2D>,
}

impl EnvironmentMap {
    /// The largest map accepted, in texels (2²⁸, 3 GiB of `f32` RGB).
    pub const MAX_TEXELS: usize = 1 << 28;

    /// A map of `width × height` texels, row by row from the top (`+y`), scaled by
    /// `scale`.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::EnvironmentMap`]) if the image is not 2:1, is
    /// smaller than 2×1 texels or larger than [`EnvironmentMap::MAX_TEXELS`], holds a
    /// texel that is negative or not finite, or the scale is not finite and `≥ 0`.
    pub fn new(width: usize, height: usize, texels: Vec<[f32; 3]>, scale: f64) -> Result<Self> {
        let invalid = |reason: String| Error::invalid(Field::EnvironmentMap, reason);
        if width < 2 || height < 1 || width != 2 * height {
            return Err(invalid(format!(
                "an environment map must be twice as wide as it is high (got {width}×{height})"
            )));
        }
        if width
            .checked_mul(height)
            .is_none_or(|n| n > Self::MAX_TEXELS || n != texels.len())
        {
            return Err(invalid(format!(
                "{width}×{height} texels: at most {} and exactly the image's ({} given)",
                Self::MAX_TEXELS,
                texels.len()
            )));
        }
        if let Some(k) = texels
            .iter()
            .position(|t| t.iter().any(|c| !(c.is_finite() && *c >= 0.0)))
        {
            return Err(invalid(format!(
                "texel {} of row {} is not a finite non-negative colour",
                k % width,
                k / width
            )));
        }
        if !(scale.is_finite() && scale >= 0.0) {
            return Err(Error::invalid(
                Field::EnvironmentScale,
                format!("must be finite and ≥ 0 (got {scale})"),
            ));
        }
        let mut map = Self {
            width,
            height,
            texels,
            scale,
            distribution: None,
        };
        map.distribution = Distribution2D::new(&map.cell_weights(), width);
        Ok(map)
    }

    /// The size in texels, `(W, H)`.
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The scale every texel is multiplied by.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Whether the map gives off no light at all (then it is not sampled).
    pub fn is_black(&self) -> bool {
        self.distribution.is_none()
    }

    fn texel(&self, column: usize, row: usize) -> [f64; 3] {
        self.texels[row * self.width + column].map(f64::from)
    }

    /// The weight of each sampling cell, row by row: the largest luminance of the texels
    /// its lookups reach (columns `i − 1 ..= i + 1`, rows `⌊r₀⌋ ..= ⌈r₁⌉`), times
    /// `sin θ` at its centre.
    fn cell_weights(&self) -> Vec<f64> {
        let (w, h) = (self.width, self.height);
        let column_max: Vec<Vec<f64>> = (0..h)
            .map(|row| {
                (0..w)
                    .map(|i| {
                        [(i + w - 1) % w, i, (i + 1) % w]
                            .map(|c| luminance(self.texel(c, row)))
                            .into_iter()
                            .fold(0.0, f64::max)
                    })
                    .collect()
            })
            .collect();
        let span = (h - 1) as f64;
        let mut weights = Vec::with_capacity(w * h);
        for j in 0..h {
            let (r0, r1) = (j as f64 * span / h as f64, (j + 1) as f64 * span / h as f64);
            let rows = (r0.floor() as usize)..=(r1.ceil() as usize).min(h - 1);
            let sin_theta = (PI * (j as f64 + 0.5) / h as f64).sin();
            weights.extend((0..w).map(|i| {
                let lum = rows.clone().map(|r| column_max[r][i]).fold(0.0, f64::max);
                lum * sin_theta
            }));
        }
        weights
    }

    /// The radiance at the map coordinates `(u, v)`: bilinear, periodic in `u`, clamped
    /// in `v`, times the scale.
    pub fn radiance_at(&self, [u, v]: [f64; 2]) -> [f64; 3] {
        let (w, h) = (self.width, self.height);
        let u = u - u.floor();
        let c = u * w as f64 - 0.5;
        let r = v.clamp(0.0, 1.0) * (h - 1) as f64;
        let (c0, r0) = (c.floor(), r.floor());
        let (fc, fr) = (c - c0, r - r0);
        let col = |k: f64| ((k as isize).rem_euclid(w as isize)) as usize;
        let (ca, cb) = (col(c0), col(c0 + 1.0));
        let (ra, rb) = ((r0 as usize).min(h - 1), (r0 as usize + 1).min(h - 1));
        let lerp = |a: [f64; 3], b: [f64; 3], t: f64| [0, 1, 2].map(|k| a[k] * (1.0 - t) + b[k] * t);
        let top = lerp(self.texel(ca, ra), self.texel(cb, ra), fc);
        let bottom = lerp(self.texel(ca, rb), self.texel(cb, rb), fc);
        lerp(top, bottom, fr).map(|x| x * self.scale)
    }

    /// The map coordinates of the unit direction `d` in the map's frame.
    pub fn coordinates([x, y, z]: [f64; 3]) -> [f64; 2] {
        let u = x.atan2(-z) / TAU;
        [u - u.floor(), y.clamp(-1.0, 1.0).acos() / PI]
    }

    /// The unit direction (in the map's frame) of the coordinates `(u, v)`, and `sin θ`:
    /// `(sin φ sin θ, cos θ, −cos φ sin θ)`, `φ = 2πu`, `θ = πv`.
    pub fn direction([u, v]: [f64; 2]) -> ([f64; 3], f64) {
        let (sin_t, cos_t) = (PI * v).sin_cos();
        let (sin_p, cos_p) = (TAU * u).sin_cos();
        ([sin_p * sin_t, cos_t, -cos_p * sin_t], sin_t)
    }

    /// A direction (in the map's frame) drawn by luminance from `u ∈ [0, 1)²`, with its
    /// density per unit solid angle; `None` for a black map or a draw at a pole.
    pub fn sample(&self, u: [f64; 2]) -> Option<([f64; 3], f64)> {
        let (uv, p) = self.distribution.as_ref()?.sample(u);
        let (d, sin_t) = Self::direction(uv);
        (sin_t > 0.0).then(|| (d, p / (2.0 * PI * PI * sin_t)))
    }

    /// The density per unit solid angle with which [`EnvironmentMap::sample`] draws the
    /// unit direction `d` (in the map's frame).
    pub fn pdf(&self, d: [f64; 3]) -> f64 {
        let Some(distribution) = &self.distribution else {
            return 0.0;
        };
        let uv = Self::coordinates(d);
        let sin_t = (1.0 - d[1] * d[1]).max(0.0).sqrt();
        if sin_t <= 0.0 {
            return 0.0;
        }
        distribution.pdf(uv) / (2.0 * PI * PI * sin_t)
    }
}
