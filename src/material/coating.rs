//! What a rough dielectric coat lets through, integrated once when a rough plastic is
//! made, as Mitsuba 3's `roughplastic` does: the share of light a rough boundary
//! transmits at each incidence, and the share it reflects back into the base under a
//! diffuse illumination from inside. Everything is in `f64`.

use super::microfacet::Microfacet;
use crate::optics::{fresnel, refract};
use crate::vec3::Vec3;

/// Entries of the transmittance table, over `cos θ` from 0 to 1 (Mitsuba's 64).
pub(super) const RESOLUTION: usize = 64;

/// The rough coat's directional transmittance `t(μ)` at `μ = k/63` (`μ = 10⁻⁶` for
/// `k = 0`), for light arriving from outside at a coat of relative index `eta`
/// (inside over outside):
///
/// `t(μ) = ∫ D_w(m)·(1 − F(w·m))·G₁(w_t, m) dm`,
///
/// `w = (√(1 − μ²), 0, μ)`, `w_t` its refraction about `m`, `F` the exact [`fresnel`]; by
/// Gauss–Legendre quadrature over the two uniform numbers of the visible-normal warp
/// (32 × 32 nodes for `eta > 1`, 128 × 128 otherwise, where total internal reflection
/// makes the integrand jump), as Mitsuba's `eval_transmittance`.
pub(super) fn transmittance(md: &Microfacet<f64>, eta: f64) -> [f64; RESOLUTION] {
    let rule = gauss_legendre(if eta > 1.0 { 32 } else { 128 });
    std::array::from_fn(|k| {
        let w = incidence(k);
        over_visible_normals(md, w, &rule, |m| {
            let f = fresnel(w.dot(m), 1.0 / eta);
            match refract(-w, m, 1.0 / eta) {
                Some(t) if t.z < 0.0 => md.g1(t, m) * (1.0 - f),
                _ => 0.0,
            }
        })
    })
}

/// The share of diffuse light from inside the base that the coat reflects back in,
/// `2∫ r(μ) μ dμ`, `r(μ)` the coat's directional reflectance seen from inside
/// (`∫ D_w(m)·F(w·m)·G₁(w_r, m) dm`, `w_r` the reflection of `w` about `m`), as Mitsuba
/// takes it: twice the mean of `r(μ)·μ` over the table's 64 values of `μ`.
///
/// # Precision
/// The quadrature takes 64 × 64 nodes for `1/eta < 1` (32 × 32 otherwise) where Mitsuba
/// takes 128 × 128, a quarter of the work (a rough plastic is made in a fraction of a
/// second, not in seconds, in a test build): for Beckmann and GGX at `α` from 0.01 to
/// 1 and `η` from 1.2 to 2, the two differ by at most `1.5·10⁻⁴`, and both from
/// 256 × 256 nodes by at most `1.2·10⁻⁴`, which moves the base's albedo
/// `ρ/(1 − R_int)` by less than 0.07 %.
pub(super) fn internal_reflectance(md: &Microfacet<f64>, eta: f64) -> f64 {
    let rule = gauss_legendre(if 1.0 / eta > 1.0 { 32 } else { 64 });
    let sum: f64 = (0..RESOLUTION)
        .map(|k| {
            let w = incidence(k);
            let r = over_visible_normals(md, w, &rule, |m| {
                let f = fresnel(w.dot(m), eta);
                let out = m * (2.0 * w.dot(m)) - w;
                if out.z > 0.0 { md.g1(out, m) * f } else { 0.0 }
            });
            r * w.z
        })
        .sum();
    2.0 * sum / RESOLUTION as f64
}

/// `table` at `μ ∈ [0, 1]`, linearly interpolated between its entries.
pub(super) fn lookup(table: &[f64; RESOLUTION], mu: f64) -> f64 {
    let x = mu.clamp(0.0, 1.0) * (RESOLUTION - 1) as f64;
    let k = (x as usize).min(RESOLUTION - 2);
    let t = x - k as f64;
    table[k] + (table[k + 1] - table[k]) * t
}

/// The direction of table entry `k`, in the `x–z` plane.
fn incidence(k: usize) -> Vec3<f64> {
    let mu = (k as f64 / (RESOLUTION - 1) as f64).max(1e-6);
    Vec3::new((1.0 - mu * mu).sqrt(), 0.0, mu)
}

/// `∫ g(m) D_w(m) dm` as the mean of `g` over visible normals drawn from the nodes of
/// `rule` in each uniform number.
fn over_visible_normals(
    md: &Microfacet<f64>,
    w: Vec3<f64>,
    rule: &[(f64, f64)],
    g: impl Fn(Vec3<f64>) -> f64,
) -> f64 {
    let mut sum = 0.0;
    for &(x0, w0) in rule {
        for &(x1, w1) in rule {
            let m = md.sample_visible(w, [0.5 * (x0 + 1.0), 0.5 * (x1 + 1.0)]);
            sum += g(m) * w0 * w1;
        }
    }
    // The weights sum to 2 on [−1, 1] in each number: 4 in all.
    0.25 * sum
}

/// The `n` nodes and weights of Gauss–Legendre quadrature on `[−1, 1]`: the roots of the
/// Legendre polynomial `P_n` by Newton's method from Chebyshev's guesses, weights
/// `2/((1 − x²) P_n'(x)²)`.
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = -(std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            for _ in 0..100 {
                let (p, dp) = legendre(n, x);
                let step = p / dp;
                x -= step;
                if step.abs() <= 4.0 * f64::EPSILON * x.abs().max(1e-3) {
                    break;
                }
            }
            let (_, dp) = legendre(n, x);
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// `(P_n(x), P_n'(x))` by Bonnet's recurrence `(k + 1)P_{k+1} = (2k + 1)x P_k − k P_{k−1}`.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 1..n {
        let p2 = ((2 * k + 1) as f64 * x * p1 - k as f64 * p0) / (k + 1) as f64;
        p0 = p1;
        p1 = p2;
    }
    // P_n' = n (x P_n − P_{n−1})/(x² − 1).
    (p1, n as f64 * (x * p1 - p0) / (x * x - 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::microfacet::Distribution;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        for n in [3, 32, 128] {
            let rule = gauss_legendre(n);
            let w: f64 = rule.iter().map(|r| r.1).sum();
            assert!((w - 2.0).abs() < 1e-13, "n = {n}: Σw = {w}");
            // ∫ x⁴ = 2/5 on [−1, 1].
            let x4: f64 = rule.iter().map(|(x, w)| w * x.powi(4)).sum();
            assert!((x4 - 0.4).abs() < 1e-13, "n = {n}: {x4}");
        }
    }

    /// Nearly smooth, the coat transmits `1 − F` and reflects back the diffuse Fresnel
    /// reflectance (the fit [`fresnel_diffuse_reflectance`](crate::optics::fresnel_diffuse_reflectance)).
    #[test]
    fn a_nearly_smooth_coat_is_fresnels() {
        let md = Microfacet::new(Distribution::Ggx, 1e-3, 1e-3);
        let t = transmittance(&md, 1.5);
        for k in [10, 40, 63] {
            let mu = incidence(k).z;
            let want = 1.0 - fresnel(mu, 1.0 / 1.5);
            assert!((t[k] - want).abs() < 1e-3, "μ = {mu}: {} vs {want}", t[k]);
        }
        let r = internal_reflectance(&md, 1.5);
        let want = crate::optics::fresnel_diffuse_reflectance(1.0 / 1.5);
        assert!((r - want).abs() < 0.02, "{r} vs {want}");
        assert_eq!(lookup(&t, 1.0), t[63]);
    }
}
