//! The Beckmann distribution's visible slopes, drawn as Mitsuba 3 draws them (Jakob 2014,
//! "An Improved Visible Normal Sampling Routine for the Beckmann Distribution"), and the
//! inverse error function it needs. Everything here is in `f64`: `erf` is `libm`'s.

use std::f64::consts::PI;

/// `1/√π`.
const INV_SQRT_PI: f64 = 0.564_189_583_547_756_3;

/// The slopes `(x̃, ỹ)` of a normal visible from a direction at `cos θᵢ` (in the `x–z`
/// plane, `x` toward it) on the Beckmann surface of `α = 1`, from `u ∈ [0, 1)²`.
///
/// The slopes of that surface are Gaussian, `P₂₂(x̃, ỹ) = e^{−x̃²−ỹ²}/π`; seen from `θᵢ`
/// each is weighted by its projected area, `∝ max(0, 1 − x̃ tan θᵢ)`, so `ỹ` stays
/// Gaussian (`ỹ = erf⁻¹(2u₁ − 1)`) and `x̃` has the cumulative distribution
///
/// `C(x̃) ∝ 1 + erf(x̃) + tan θᵢ/√π · e^{−x̃²}`, `x̃ ≤ cot θᵢ`.
///
/// As in Mitsuba, `C(x̃) = u₀·C(cot θᵢ)` is solved for `ξ = erf(x̃)`, where `C` is nearly
/// linear (`dC/dξ = 1 − x̃ tan θᵢ`), starting from the exact solution at grazing
/// incidence. Mitsuba takes three Newton steps; here Newton steps run, kept inside a
/// bracket by bisection, until the step is below `10⁻¹⁴` (or `C` is met exactly), so the draw follows the
/// distribution the density [`Microfacet::visible_pdf`](super::Microfacet::visible_pdf)
/// states to `f64`'s precision, not to the last step's.
///
/// # Precision
/// `u` is kept `10⁻¹⁵` inside `(0, 1)`: the tails cut off (slopes beyond `~5.6`) hold
/// `~10⁻¹⁵` of the probability.
pub(super) fn visible_slopes(cos_i: f64, u: [f64; 2]) -> [f64; 2] {
    let clamp = |x: f64| x.clamp(1e-15, 1.0 - 1e-15);
    let (u0, u1) = (clamp(u[0]), clamp(u[1]));
    let y = erfinv(2.0 * u1 - 1.0);
    let sin_i = (1.0 - cos_i * cos_i).max(0.0).sqrt();
    // At normal incidence every slope is seen alike: the plain Gaussian.
    if sin_i <= 1e-12 {
        return [erfinv(2.0 * u0 - 1.0), y];
    }
    let (tan_i, cot_i) = (sin_i / cos_i, cos_i / sin_i);
    let top = libm::erf(cot_i);
    let cdf = |xi: f64, slope: f64| 1.0 + xi + tan_i * INV_SQRT_PI * (-slope * slope).exp();
    let target = u0 * cdf(top, cot_i);
    // The solution at θᵢ = π/2, where C is most curved, as the first guess.
    let mut xi = top - (top + 1.0) * libm::erf((-u0.ln()).sqrt());
    let (mut lo, mut hi) = (-1.0, top);
    for _ in 0..60 {
        let slope = erfinv(xi);
        let value = cdf(xi, slope) - target;
        if value == 0.0 {
            break;
        } else if value > 0.0 {
            hi = xi;
        } else {
            lo = xi;
        }
        let derivative = 1.0 - slope * tan_i;
        let newton = xi - value / derivative;
        let next = if derivative > 0.0 && newton >= lo && newton <= hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let step = (next - xi).abs();
        xi = next;
        if step <= 1e-14 {
            break;
        }
    }
    [erfinv(xi), y]
}

/// The Beckmann `Λ` for `a = 1/(α tan θ)`, exactly (Mitsuba uses a rational fit, within
/// 0.35 %): `Λ(a) = (e^{−a²}/(a√π) − erfc(a))/2`, `0` for `a = ∞` (normal incidence).
pub(super) fn lambda(a: f64) -> f64 {
    if a == f64::INFINITY {
        return 0.0;
    }
    (0.5 * ((-a * a).exp() * INV_SQRT_PI / a - libm::erfc(a))).max(0.0)
}

/// The inverse error function, `erf⁻¹(y)` for `y ∈ (−1, 1)` (`±∞` at `±1`): Giles' (2010)
/// single-precision approximation, then Newton steps on `erf(x) − y` (written
/// `(1 − y) − erfc(x)` for `y > ½`, where `1 − y` is exact and `erf` has no digits left).
pub(super) fn erfinv(y: f64) -> f64 {
    let a = y.abs();
    if a >= 1.0 {
        return if a == 1.0 { y * f64::INFINITY } else { f64::NAN };
    }
    let w = -((1.0 - a) * (1.0 + a)).ln();
    let mut x = if w < 5.0 {
        let w = w - 2.5;
        [
            2.810_226_36e-08,
            3.432_739_39e-07,
            -3.523_387_7e-06,
            -4.391_506_54e-06,
            0.000_218_580_87,
            -0.001_253_725_03,
            -0.004_177_681_64,
            0.246_640_727,
            1.501_409_41,
        ]
        .iter()
        .fold(0.0, |p, c| p * w + c)
    } else {
        let w = w.sqrt() - 3.0;
        [
            -0.000_200_214_257,
            0.000_100_950_558,
            0.001_349_343_22,
            -0.003_673_428_44,
            0.005_739_507_73,
            -0.007_622_461_3,
            0.009_438_870_47,
            1.001_674_06,
            2.832_976_82,
        ]
        .iter()
        .fold(0.0, |p, c| p * w + c)
    } * a;
    // The first guess is within ~10⁻⁸ of the root for `|y| < 1 − 2⁻²⁴`, where two quadratic
    // steps reach f64's precision; further out (Giles' fit is for single precision) a few
    // more steps are needed.
    for _ in 0..8 {
        let residual = if a > 0.5 {
            (1.0 - a) - libm::erfc(x)
        } else {
            libm::erf(x) - a
        };
        let step = residual / (2.0 / PI.sqrt() * (-x * x).exp());
        x -= step;
        if step.abs() <= 1e-15 * x {
            break;
        }
    }
    x.copysign(y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn erfinv_inverts_erf() {
        for x in [-4.5, -3.0, -1.0, -0.3, 0.0, 1e-9, 0.2, 0.7, 1.5, 2.5, 4.0] {
            let back = erfinv(libm::erf(x));
            // erf(x) is rounded by half an ulp of 1 at most, which erf⁻¹ magnifies by its
            // slope (√π/2)·e^{x²}.
            let tol = 2e-16 * (x * x).exp() + 4e-16 * x.abs();
            assert!((back - x).abs() <= tol, "{x}: {back}");
        }
        // Near 1, `y = 1 − δ` with `δ = 1 − y` exact: erfc(x) must be δ.
        let y = 1.0 - 1e-12;
        let (x, delta) = (erfinv(y), 1.0 - y);
        assert!((libm::erfc(x) - delta).abs() < 1e-14 * delta, "{x}");
        assert_eq!(erfinv(1.0), f64::INFINITY);
        assert_eq!(erfinv(-1.0), f64::NEG_INFINITY);
    }

    #[test]
    fn lambda_vanishes_at_normal_incidence_and_grows_toward_grazing() {
        assert_eq!(lambda(f64::INFINITY), 0.0);
        assert!(lambda(10.0) < 1e-40);
        // Λ(1) = (e⁻¹/√π − erfc 1)/2, from tabulated erfc(1) = 0.157299207050285.
        let want = 0.5 * ((-1.0f64).exp() / PI.sqrt() - 0.157_299_207_050_285);
        assert!((lambda(1.0) - want).abs() < 1e-15);
        assert!(lambda(0.1) > lambda(0.5) && lambda(0.5) > lambda(1.0));
    }

    /// The slope's cumulative distribution at the drawn slope is the uniform number.
    #[test]
    fn visible_slopes_invert_their_distribution() {
        for cos_i in [1.0, 0.9, 0.5, 0.1, 1e-3] {
            let sin_i = (1.0f64 - cos_i * cos_i).sqrt();
            let tan_i = sin_i / cos_i;
            let c = |s: f64| {
                if sin_i == 0.0 {
                    0.5 * (1.0 + libm::erf(s))
                } else {
                    let cot = cos_i / sin_i;
                    let f = |s: f64| 1.0 + libm::erf(s) + tan_i * INV_SQRT_PI * (-s * s).exp();
                    f(s) / f(cot)
                }
            };
            for u in [0.001, 0.2, 0.5, 0.8, 0.999] {
                let [x, _] = visible_slopes(cos_i, [u, 0.5]);
                assert!((c(x) - u).abs() < 1e-12, "cos θ = {cos_i}, u = {u}: C = {}", c(x));
            }
        }
    }
}
