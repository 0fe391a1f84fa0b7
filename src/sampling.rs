//! Random sampling, drawn in `f64` whatever the scalar.
//!
//! Every random number is drawn as an `f64` and only then rounded to `F`, so renders
//! in f32, f64 and double-double consume one random stream and differ only where
//! precision changes a path. The warps that turn uniform numbers into directions are
//! pure functions of those numbers, testable without an RNG.

mod piecewise;

pub use piecewise::{Distribution1D, Distribution2D};

use crate::float::{Float, lit};
use crate::vec3::Vec3;
use rand::Rng;

/// The default random generator: xoshiro256++, a fixed, documented algorithm, so a seed
/// gives the same image on every machine and every version of this crate.
pub type DefaultRng = rand::rngs::Xoshiro256PlusPlus;

/// A uniform `f64` in `[0, 1)`: 53 random bits `k`, `k·2⁻⁵³` (exact), as `rand`'s
/// `random::<f64>()` draws it.
#[inline]
pub fn uniform<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// `2u − 1` for `u` the next [`uniform`], a uniform `f64` in `[−1, 1)`: `k·2⁻⁵² − 1`. The
/// same value bit for bit as `2.0 * uniform(rng) - 1.0` (both `k·2⁻⁵³` and its double are
/// exact, so only the subtraction rounds, the same way), one operation fewer.
#[inline]
fn signed_uniform<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 52) as f64) - 1.0
}

/// The specification's uniform point on the unit sphere: draw `X` with each coordinate
/// uniform in `[−1, 1]`, redraw while `|X| > 1`, return `X/|X|`.
///
/// The acceptance rate is the ball's share of the cube, `π/6 ≈ 0.524`. Points with
/// `|X|² < 1e-12` are also redrawn, so the division is always well conditioned; that
/// excludes a ball of measure `~10⁻¹⁸`, whose directions are uniform anyway, so the
/// distribution is unchanged.
///
/// # Precision
/// Computed in `f64`; the result is unit length within `2.5·2⁻⁵²` (first-order bound `2.25·2⁻⁵²`) and exactly reproducible.
pub fn unit_sphere_rejection<R: Rng + ?Sized>(rng: &mut R) -> [f64; 3] {
    loop {
        let x = signed_uniform(rng);
        let y = signed_uniform(rng);
        let z = signed_uniform(rng);
        let len2 = x * x + y * y + z * z;
        if len2 <= 1.0 && len2 > 1e-12 {
            let inv = 1.0 / len2.sqrt();
            return [x * inv, y * inv, z * inv];
        }
    }
}

/// The specification's Lambertian direction at a surface with unit normal `n`: the unit
/// vector from the hit point `P` to a point `S` uniform on the unit sphere centred at
/// `P + N` (tangent to the surface at `P`): `D = (N + X)/|N + X|`, `X` from
/// [`unit_sphere_rejection`]. Its density is `cos θ / π` (the tangent-sphere construction).
///
/// # Precision
/// When `X ≈ −N` the sum cancels and its direction is rounding noise. Such draws are
/// redrawn: the rejected cap `|N + X|² < 64ε` maps to directions within `~4√ε` of the
/// tangent plane, where the cosine density is itself `~4√ε`, so the rejected
/// probability is `< 16ε` (`2·10⁻⁶` in f32): no NaN, no direction below the surface,
/// and no bias a test could detect.
pub fn lambertian_direction<F: Float, R: Rng + ?Sized>(n: Vec3<F>, rng: &mut R) -> Vec3<F> {
    let tiny = F::eps() * lit(64.0);
    loop {
        let [x, y, z] = unit_sphere_rejection(rng);
        let d = n + Vec3::new(lit(x), lit(y), lit(z));
        let len2 = d.length_squared();
        if len2 > tiny {
            return d / len2.sqrt();
        }
    }
}

/// A cosine-distributed unit direction about the unit normal `n` in closed form, from
/// two uniform numbers instead of the spec's rejection loop: with `u₁, u₂ ∈ [0, 1)`,
///
/// `cos θ = √(1 − u₁)`, `sin θ = √u₁`, `φ = 2πu₂`, `D = sin θ cos φ·t + sin θ sin φ·b + cos θ·n`,
///
/// `(t, b, n)` the orthonormal frame of [`orthonormal_basis`]. Same density `cos θ/π` as
/// [`lambertian_direction`] (the tests check both with one χ² harness), always exactly
/// two draws, no division that can cancel.
pub fn cosine_direction<F: Float, R: Rng + ?Sized>(n: Vec3<F>, rng: &mut R) -> Vec3<F> {
    let (u1, u2) = (uniform(rng), uniform(rng));
    let sin_t = u1.sqrt();
    let cos_t = (1.0 - u1).sqrt();
    let (sin_p, cos_p) = (std::f64::consts::TAU * u2).sin_cos();
    let (t, b) = orthonormal_basis(n);
    t * lit::<F>(sin_t * cos_p) + b * lit::<F>(sin_t * sin_p) + n * lit::<F>(cos_t)
}

/// The density of a cosine-distributed direction `d` about the unit normal `n`,
/// `max(0, n·d)/π`: what [`lambertian_direction`] and [`cosine_direction`] draw with.
#[inline]
pub fn cosine_pdf<F: Float>(n: Vec3<F>, d: Vec3<F>) -> F {
    n.dot(d).max(F::zero()) * F::from_f64(std::f64::consts::FRAC_1_PI)
}

/// Two unit vectors `t`, `b` completing the unit `n` to a right-handed orthonormal frame
/// `(t, b, n)`, without branches on small components (Duff et al. 2017, "Building an
/// Orthonormal Basis, Revisited"): with `s = sign(n_z)`, `a = −1/(s + n_z)`, `c = n_x n_y a`,
/// `t = (1 + s n_x² a, s c, −s n_x)`, `b = (c, s + n_y² a, −n_y)`.
pub fn orthonormal_basis<F: Float>(n: Vec3<F>) -> (Vec3<F>, Vec3<F>) {
    let s = if n.z >= F::zero() { F::one() } else { -F::one() };
    let a = -F::one() / (s + n.z);
    let c = n.x * n.y * a;
    let t = Vec3::new(F::one() + s * n.x * n.x * a, s * c, -s * n.x);
    let b = Vec3::new(c, s + n.y * n.y * a, -n.y);
    (t, b)
}

/// A uniform point of a triangle from `u ∈ [0, 1)²`, as barycentric weights `[b₀, b₁, b₂]`
/// of its vertices (pbrt-v4's `SampleUniformTriangle`, Heitz's low-distortion map): if
/// `u₀ < u₁`, `b₀ = u₀/2`, `b₁ = u₁ − b₀`, else `b₁ = u₁/2`, `b₀ = u₀ − b₁`; `b₂ = 1 − b₀ − b₁`.
/// Each half of the square maps affinely onto half of the triangle, so the density is
/// uniform (`1/area`), with no square root.
#[inline]
pub fn uniform_triangle(u: [f64; 2]) -> [f64; 3] {
    let (b0, b1) = if u[0] < u[1] {
        let b0 = u[0] / 2.0;
        (b0, u[1] - b0)
    } else {
        let b1 = u[1] / 2.0;
        (u[0] - b1, b1)
    };
    [b0, b1, 1.0 - b0 - b1]
}

/// A uniform unit vector from `u ∈ [0, 1)²` (Archimedes: the height is uniform):
/// `z = 1 − 2u₀`, `φ = 2πu₁`, `(√(1 − z²) cos φ, √(1 − z²) sin φ, z)`; density `1/4π`.
#[inline]
pub fn uniform_sphere(u: [f64; 2]) -> [f64; 3] {
    let z = 1.0 - 2.0 * u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin_p, cos_p) = (std::f64::consts::TAU * u[1]).sin_cos();
    [r * cos_p, r * sin_p, z]
}

/// A cosine-distributed unit vector about `+z` from `u ∈ [0, 1)²`:
/// `cos θ = √(1 − u₀)`, `sin θ = √u₀`, `φ = 2πu₁`, `(sin θ cos φ, sin θ sin φ, cos θ)`;
/// density `cos θ/π`. The local form of [`cosine_direction`], for materials that work in
/// their shading frame.
#[inline]
pub fn cosine_hemisphere(u: [f64; 2]) -> [f64; 3] {
    let r = u[0].sqrt();
    let (sin_p, cos_p) = (std::f64::consts::TAU * u[1]).sin_cos();
    [r * cos_p, r * sin_p, (1.0 - u[0]).sqrt()]
}

/// A uniform point of the unit disk from `u ∈ [0, 1)²` by Shirley and Chiu's concentric
/// map (1997), which keeps neighbouring `u` neighbours on the disk: with `a = 2u₀ − 1`,
/// `b = 2u₁ − 1`, `(r, φ) = (a, π/4·b/a)` where `|a| > |b|`, else `(b, π/2 − π/4·a/b)`;
/// the point is `(r cos φ, r sin φ)`, the centre for `a = b = 0`. Each square ring maps
/// onto the disk's ring of the same relative area, so the density is uniform, `1/π`.
#[inline]
pub fn uniform_disk_concentric(u: [f64; 2]) -> [f64; 2] {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};
    let (a, b) = (2.0 * u[0] - 1.0, 2.0 * u[1] - 1.0);
    if a == 0.0 && b == 0.0 {
        return [0.0, 0.0];
    }
    let (r, phi) = if a.abs() > b.abs() {
        (a, FRAC_PI_4 * (b / a))
    } else {
        (b, FRAC_PI_2 - FRAC_PI_4 * (a / b))
    };
    let (sin_p, cos_p) = phi.sin_cos();
    [r * cos_p, r * sin_p]
}

/// The offset of a jittered sample inside its pixel: a uniform point of
/// `[−½, ½)²`, in pixel units.
#[inline]
pub fn pixel_jitter<R: Rng + ?Sized>(rng: &mut R) -> (f64, f64) {
    (uniform(rng) - 0.5, uniform(rng) - 0.5)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::rngs::Xoshiro256PlusPlus;
    use rand::{RngExt, SeedableRng};

    /// `uniform` is `rand`'s `f64`, and `signed_uniform` is `2u − 1` of it, bit for bit.
    #[test]
    fn uniform_draws_are_rands_own() {
        let mut a = Xoshiro256PlusPlus::seed_from_u64(1);
        let mut b = a.clone();
        let mut c = a.clone();
        for _ in 0..100_000 {
            let want = b.random::<f64>();
            assert_eq!(uniform(&mut a).to_bits(), want.to_bits());
            assert_eq!(signed_uniform(&mut c).to_bits(), (2.0 * want - 1.0).to_bits());
        }
    }

    #[test]
    fn rejection_points_are_unit() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
        for _ in 0..10_000 {
            let [x, y, z] = unit_sphere_rejection(&mut rng);
            assert!(((x * x + y * y + z * z) - 1.0).abs() < 4.0 * f64::EPSILON);
        }
    }

    #[test]
    fn lambertian_stays_above_the_surface() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(11);
        let n = Vec3::new(0.0f32, 0.6, 0.8);
        for _ in 0..10_000 {
            let d = lambertian_direction(n, &mut rng);
            assert!(d.dot(n) >= 0.0 && (d.length() - 1.0).abs() < 1e-6);
        }
    }

    #[test]
    fn basis_is_orthonormal() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(5);
        for _ in 0..1000 {
            let [x, y, z] = unit_sphere_rejection(&mut rng);
            let n = Vec3::new(x, y, z);
            let (t, b) = orthonormal_basis(n);
            for (u, v) in [(t, b), (t, n), (b, n)] {
                assert!(u.dot(v).abs() < 1e-14);
            }
            assert!((t.length() - 1.0).abs() < 1e-14 && (b.length() - 1.0).abs() < 1e-14);
            assert!((t.cross(b) - n).length() < 1e-14, "right-handed");
            let d = cosine_direction(n, &mut rng);
            assert!(d.dot(n) >= 0.0 && (d.length() - 1.0).abs() < 1e-14);
        }
    }

    #[test]
    fn triangle_and_sphere_points_are_valid() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(9);
        for _ in 0..10_000 {
            let u = [uniform(&mut rng), uniform(&mut rng)];
            let b = uniform_triangle(u);
            assert!(b.iter().all(|&x| x >= 0.0) && (b.iter().sum::<f64>() - 1.0).abs() < 1e-15);
            let [x, y, z] = uniform_sphere(u);
            assert!(((x * x + y * y + z * z) - 1.0).abs() < 4.0 * f64::EPSILON);
        }
        assert_eq!(uniform_triangle([0.0, 0.0]), [0.0, 0.0, 1.0]);
    }

    #[test]
    fn concentric_disk_points_are_uniform_on_the_disk() {
        assert_eq!(uniform_disk_concentric([0.5, 0.5]), [0.0, 0.0]);
        // The square's edge is the circle; its corners and mid-edges land where expected.
        let [x, y] = uniform_disk_concentric([1.0, 0.5]);
        assert!((x - 1.0).abs() < 1e-15 && y.abs() < 1e-15);
        let [x, y] = uniform_disk_concentric([1.0, 1.0]);
        assert!((x - y).abs() < 1e-15 && (x.hypot(y) - 1.0).abs() < 1e-15);
        // Area fractions: r < ½ holds a quarter of the disk, each quadrant a quarter.
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(11);
        let n = 40_000;
        let (mut inner, mut first_quadrant) = (0, 0);
        for _ in 0..n {
            let [x, y] = uniform_disk_concentric([uniform(&mut rng), uniform(&mut rng)]);
            let r = x.hypot(y);
            assert!(r <= 1.0 + 1e-15);
            inner += usize::from(r < 0.5);
            first_quadrant += usize::from(x > 0.0 && y > 0.0);
        }
        // 5σ of a binomial with p = ¼: 5·√(n·p·(1 − p)) ≈ 433.
        for count in [inner, first_quadrant] {
            assert!((count as f64 - n as f64 / 4.0).abs() < 433.0, "{count}");
        }
    }

    #[test]
    fn same_stream_for_every_scalar() {
        let n64 = Vec3::new(0.0f64, 1.0, 0.0);
        let n32 = Vec3::new(0.0f32, 1.0, 0.0);
        let mut a = Xoshiro256PlusPlus::seed_from_u64(3);
        let mut b = Xoshiro256PlusPlus::seed_from_u64(3);
        for _ in 0..1000 {
            let d64 = lambertian_direction(n64, &mut a);
            let d32 = lambertian_direction(n32, &mut b);
            assert!((d64 - d32.cast()).length() < 1e-6);
        }
    }
}
