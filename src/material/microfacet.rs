//! Microfacet distributions: Beckmann and GGX (Trowbridge–Reitz), isotropic or not, with
//! Smith's masking and the sampling of visible normals, as Mitsuba 3's
//! `MicrofacetDistribution` defines them. The rough conductor, the rough dielectric and
//! the rough plastic share it.
//!
//! Every vector is in the local shading frame: `z` the normal, `x` the tangent along which
//! the roughness is `αu`, `y` the one of `αv`.

mod beckmann;

use crate::float::{Float, lit};
use crate::vec3::Vec3;
use std::f64::consts::{PI, TAU};

/// Which distribution of microfacet normals a rough surface has.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Distribution {
    /// Beckmann's, from Gaussian random surfaces (Mitsuba's default).
    #[default]
    Beckmann,
    /// GGX (Trowbridge–Reitz): a longer tail, so a glow about highlights.
    Ggx,
}

/// The smallest roughness a distribution uses: smaller `α` (and `α ≤ 0` or NaN from a
/// texture) are raised to it, as in Mitsuba. At `10⁻⁴` a highlight is already a point.
pub const MIN_ALPHA: f64 = 1e-4;

/// A microfacet distribution of normals `m` with roughness `αu` along `x` and `αv` along
/// `y` (`αu = αv`: isotropic):
///
/// - Beckmann: `D(m) = exp(−(m_x²/αu² + m_y²/αv²)/m_z²) / (π αu αv m_z⁴)`;
/// - GGX: `D(m) = 1 / (π αu αv (m_x²/αu² + m_y²/αv² + m_z²)²)`;
///
/// both `0` for `m_z ≤ 0`, normalised so that `∫ D(m) m_z dm = 1`. Smith's masking of a
/// direction `w` is `G₁(w, m) = 1/(1 + Λ(w))` where `(w·m)·w_z > 0`, else `0`, with
/// `a = 1/(α_w tan θ_w)`, `α_w² = (αu² w_x² + αv² w_y²)/sin²θ_w`:
///
/// - Beckmann: `Λ = (e^{−a²}/(a√π) − erfc(a))/2`;
/// - GGX: `Λ = (√(1 + 1/a²) − 1)/2`;
///
/// and the shadowing–masking of a pair, `G(wo, wi, m) = G₁(wo, m)·G₁(wi, m)` (the
/// separable form, Mitsuba's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Microfacet<F> {
    distribution: Distribution,
    alpha_u: F,
    alpha_v: F,
}

impl<F: Float> Microfacet<F> {
    /// The `distribution` with roughness `αu` along `x` and `αv` along `y`, each raised to
    /// [`MIN_ALPHA`] if smaller or NaN (constructors refuse `α ≤ 0` and NaN; this is for
    /// what a texture gives).
    pub fn new(distribution: Distribution, alpha_u: F, alpha_v: F) -> Self {
        // `max` returns the number when the other argument is NaN.
        let floor = |a: F| a.max(lit(MIN_ALPHA));
        Self {
            distribution,
            alpha_u: floor(alpha_u),
            alpha_v: floor(alpha_v),
        }
    }

    /// The distribution.
    pub fn distribution(&self) -> Distribution {
        self.distribution
    }

    /// `(αu, αv)`.
    pub fn alpha(&self) -> (F, F) {
        (self.alpha_u, self.alpha_v)
    }

    /// The density of normals `D(m)` per unit solid angle of `m` (see the type's docs).
    #[inline]
    pub fn d(&self, m: Vec3<F>) -> F {
        if m.z <= F::zero() {
            return F::zero();
        }
        let (sx, sy) = (m.x / self.alpha_u, m.y / self.alpha_v);
        let pi_ab = lit::<F>(PI) * self.alpha_u * self.alpha_v;
        match self.distribution {
            Distribution::Beckmann => {
                let cos2 = m.z * m.z;
                (-(sx * sx + sy * sy) / cos2).exp() / (pi_ab * cos2 * cos2)
            }
            Distribution::Ggx => {
                let e = sx * sx + sy * sy + m.z * m.z;
                F::one() / (pi_ab * e * e)
            }
        }
    }

    /// Smith's `Λ(w)` (see the type's docs): `0` at normal incidence, `∞` in the tangent
    /// plane.
    #[inline]
    pub fn lambda(&self, w: Vec3<F>) -> F {
        let (ax, ay) = (self.alpha_u * w.x, self.alpha_v * w.y);
        // α_w² tan²θ = 1/a².
        let xy = ax * ax + ay * ay;
        if xy == F::zero() {
            return F::zero();
        }
        let z2 = w.z * w.z;
        match self.distribution {
            Distribution::Beckmann => F::from_f64(beckmann::lambda((z2 / xy).sqrt().to_f64())),
            Distribution::Ggx => {
                let t = xy / z2;
                // (√(1 + t) − 1)/2 without the cancellation for small t.
                lit::<F>(0.5) * t / ((F::one() + t).sqrt() + F::one())
            }
        }
    }

    /// Smith's masking `G₁(w, m)`: the share of microfacets of normal `m` seen from `w`.
    #[inline]
    pub fn g1(&self, w: Vec3<F>, m: Vec3<F>) -> F {
        // `w` must be on the same side of the facet as of the surface: a facet is not
        // seen from its back (and, below the surface, only from its back's side).
        if w.dot(m) * w.z <= F::zero() {
            return F::zero();
        }
        F::one() / (F::one() + self.lambda(w))
    }

    /// The shadowing–masking of a pair, `G₁(wo, m)·G₁(wi, m)`.
    #[inline]
    pub fn g(&self, wo: Vec3<F>, wi: Vec3<F>, m: Vec3<F>) -> F {
        self.g1(wo, m) * self.g1(wi, m)
    }

    /// The density of the normals visible from `wo` (`wo_z > 0`), per unit solid angle of
    /// `m`: `D_wo(m) = G₁(wo, m)·max(0, wo·m)·D(m)/wo_z` (Heitz 2014). It integrates to
    /// 1 over `m`; [`Microfacet::sample_visible`] draws from it.
    #[inline]
    pub fn visible_pdf(&self, wo: Vec3<F>, m: Vec3<F>) -> F {
        let cos = wo.dot(m);
        if cos <= F::zero() || wo.z <= F::zero() {
            return F::zero();
        }
        self.g1(wo, m) * cos * self.d(m) / wo.z
    }

    /// A normal drawn with density [`Microfacet::visible_pdf`] from `u ∈ [0, 1)²`, for
    /// `wo` with `wo_z > 0`. Both distributions stretch `wo` to the surface of `α = 1`
    /// (`(αu wo_x, αv wo_y, wo_z)`), draw a visible normal there, and unstretch it:
    ///
    /// - GGX, Heitz 2018 ("Sampling the GGX Distribution of Visible Normals"): the visible
    ///   part of the unit hemisphere projects onto a disk, a half of it squashed by
    ///   `s = (1 + cos θ)/2`: with `r = √u₀`, `φ = 2πu₁`, `t₁ = r cos φ`,
    ///   `t₂ = (1 − s)√(1 − t₁²) + s·r sin φ` in a frame `(T₁, T₂, V)` about the
    ///   stretched `V`, `N = t₁T₁ + t₂T₂ + √(1 − t₁² − t₂²)V`, `m ∝ (αu N_x, αv N_y, N_z)`;
    /// - Beckmann, Mitsuba's method (Jakob 2014): the visible slopes of the unit surface
    ///   by numerical inversion (`microfacet/beckmann.rs`), rotated to the
    ///   stretched azimuth, scaled by `(αu, αv)`; `m ∝ (−x̃, −ỹ, 1)`.
    pub fn sample_visible(&self, wo: Vec3<F>, u: [f64; 2]) -> Vec3<F> {
        match self.distribution {
            Distribution::Ggx => self.sample_ggx(wo, u),
            Distribution::Beckmann => self.sample_beckmann(wo, u),
        }
    }

    fn sample_ggx(&self, wo: Vec3<F>, u: [f64; 2]) -> Vec3<F> {
        let (au, av) = (self.alpha_u, self.alpha_v);
        let v = Vec3::new(au * wo.x, av * wo.y, wo.z).normalize();
        let len2 = v.x * v.x + v.y * v.y;
        let t1 = if len2 > F::zero() {
            Vec3::new(-v.y, v.x, F::zero()) / len2.sqrt()
        } else {
            Vec3::new(F::one(), F::zero(), F::zero())
        };
        let t2 = v.cross(t1);
        let r = lit::<F>(u[0].sqrt());
        let (sin_p, cos_p) = (TAU * u[1]).sin_cos();
        let p1 = r * lit(cos_p);
        let s = lit::<F>(0.5) * (F::one() + v.z);
        let p2 = (F::one() - s) * (F::one() - p1 * p1).max(F::zero()).sqrt() + s * r * lit(sin_p);
        let pz = (F::one() - p1 * p1 - p2 * p2).max(F::zero()).sqrt();
        let n = t1 * p1 + t2 * p2 + v * pz;
        Vec3::new(au * n.x, av * n.y, n.z.max(F::zero())).normalize()
    }

    fn sample_beckmann(&self, wo: Vec3<F>, u: [f64; 2]) -> Vec3<F> {
        let (au, av) = (self.alpha_u.to_f64(), self.alpha_v.to_f64());
        let [x, y, z] = wo.to_f64();
        let (sx, sy, sz) = (au * x, av * y, z);
        let len = (sx * sx + sy * sy + sz * sz).sqrt();
        let r = (sx * sx + sy * sy).sqrt();
        let (sin_p, cos_p) = if r > 0.0 { (sy / r, sx / r) } else { (0.0, 1.0) };
        // The unit surface's slopes, with x toward the stretched `wo`.
        let [tx, ty] = beckmann::visible_slopes(sz / len, u);
        let slope_x = (cos_p * tx - sin_p * ty) * au;
        let slope_y = (sin_p * tx + cos_p * ty) * av;
        Vec3::from_f64(-slope_x, -slope_y, 1.0).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(x: f64, y: f64, z: f64) -> Vec3<f64> {
        Vec3::new(x, y, z).normalize()
    }

    /// `∫ D(m) m_z dm = 1` and `∫ D_wo(m) dm = 1`, by a midpoint rule over the hemisphere
    /// in `(cos θ, φ)` fine enough for α ≥ 0.2.
    #[test]
    fn distributions_are_normalised() {
        let (nt, np) = (2000, 200);
        for distribution in [Distribution::Beckmann, Distribution::Ggx] {
            for (au, av) in [(0.2, 0.2), (0.5, 0.25), (1.0, 0.7)] {
                let md = Microfacet::new(distribution, au, av);
                let wo = unit(0.5, -0.3, 0.6);
                let (mut projected, mut visible) = (0.0, 0.0);
                for i in 0..nt {
                    // cos θ = t², which crowds nodes toward the grazing end.
                    let t = (i as f64 + 0.5) / nt as f64;
                    let (c, dc) = (t * t, 2.0 * t / nt as f64);
                    let s = (1.0 - c * c).sqrt();
                    for j in 0..np {
                        let p = TAU * (j as f64 + 0.5) / np as f64;
                        let m = Vec3::new(s * p.cos(), s * p.sin(), c);
                        let dw = dc * TAU / np as f64;
                        projected += md.d(m) * c * dw;
                        visible += md.visible_pdf(wo, m) * dw;
                    }
                }
                let what = format!("{distribution:?} ({au}, {av})");
                assert!((projected - 1.0).abs() < 2e-3, "{what}: ∫D cos = {projected}");
                assert!((visible - 1.0).abs() < 2e-3, "{what}: ∫D_wo = {visible}");
            }
        }
    }

    #[test]
    fn masking_is_one_at_normal_incidence_and_zero_from_behind() {
        let md = Microfacet::new(Distribution::Ggx, 0.3f64, 0.3);
        let n = Vec3::new(0.0, 0.0, 1.0);
        assert_eq!(md.g1(n, n), 1.0);
        let w = unit(1.0, 0.0, 1.0);
        assert_eq!(md.g1(w, unit(-1.0, 0.0, 0.1)), 0.0, "back of the facet");
        let below = unit(1.0, 0.0, -1.0);
        assert_eq!(
            md.g1(below, unit(1.0, 0.0, 0.1)),
            0.0,
            "below, on the facet's front side"
        );
        assert!(
            md.g1(below, n) > 0.0,
            "below, on the facet's back side: transmission"
        );
        // GGX: Λ = (√(1 + α² tan²θ) − 1)/2 at 45°, α = 0.3.
        let want = ((1.0f64 + 0.09).sqrt() - 1.0) / 2.0;
        assert!((md.lambda(w) - want).abs() < 1e-15);
    }

    #[test]
    fn tiny_and_invalid_alphas_are_raised_to_the_floor() {
        let md = Microfacet::new(Distribution::Beckmann, 1e-9f32, f32::NAN);
        assert_eq!(md.alpha(), (1e-4, 1e-4));
    }

    #[test]
    fn sampled_normals_face_the_direction() {
        for distribution in [Distribution::Beckmann, Distribution::Ggx] {
            let md = Microfacet::new(distribution, 0.6f64, 0.1);
            let wo = unit(0.9, 0.2, 0.05);
            for k in 0..100 {
                let u = [(k as f64 + 0.5) / 100.0, ((k * 37) % 100) as f64 / 100.0];
                let m = md.sample_visible(wo, u);
                assert!((m.length() - 1.0).abs() < 1e-12 && m.z >= 0.0, "{m:?}");
                assert!(md.visible_pdf(wo, m) > 0.0, "{distribution:?} {u:?} {m:?}");
            }
        }
    }
}
