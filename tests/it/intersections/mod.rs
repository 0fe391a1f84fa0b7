//! Intersections checked against exact geometry, as property tests
//! written once and run for f32 and f64 with fixed proptest seeds.
//!
//! Every reference value is computed in double-double ([`TwoFloat`], ~106 bits) from the
//! *rounded* inputs the library sees (the sphere's stored centre and radius, the plane's
//! stored point and unit normal, the triangle's vertices, the ray's `F` origin and
//! direction), so the only error left in a comparison is the library's own.
//!
//! This file complements `sphere_stability/` (spheres near the world origin, far small
//! spheres) and `flat_shapes.rs` (seeded re-intersection loops): here the sphere is placed
//! up to `10⁵` radii from the world origin, so the `|P|` term of the error bound matters;
//! the sphere's hit is checked for *exact* agreement with
//! [`Sphere::roots`] and random `t_max`; and a triangle's hit/miss decision is checked
//! against barycentric coordinates computed independently from the exact geometry.
//!
//! # Margins
//! - **Sphere discriminant.** With `f = O − C` (exact), the computed perpendicular distance
//!   of the line from the centre is within `~4ε(|f| + r)` of the exact one (see
//!   `sphere_stability/`), so the decision "the line meets the sphere" is only checked
//!   outside the band `| |l| − r | ≤ 8ε(|f| + r)`, and the root only outside `8ε(|f| + r)`
//!   of `t = 0`.
//! - **Triangle edge functions.** The watertight test computes the three edge functions
//!   `eᵢ` in a translated, permuted and sheared frame; with `M` the largest coordinate of
//!   `Vᵢ − O`, pbrt-v4's bound on their rounding is `δe ≤ 83εM²` (each sheared coordinate
//!   is at most `2M`, off by `≤ γ(5)(2 + √3)M`; two products and a difference). The exact
//!   edge functions are the triple products `Tᵢ = D·((Vⱼ − O)×(Vₖ − O))` divided by the
//!   largest component of `D` (`≤ 1`), so `|Tᵢ| > 128εM²` fixes the sign of the computed
//!   `eᵢ`. In barycentric units (`bᵢ = Tᵢ/ΣT`, `ΣT = D·N`) the margin is
//!   `mᵢ = 128εM²/|D·N|`: it widens for far origins (large `M`) and grazing rays (small
//!   `D·N`), exactly where the barycentrics are ill-conditioned. The ray's `t` must exceed
//!   pbrt's `δt`, which is below `t_m = 32εM(1 + 32M²/|D·N|)` for a clearly inside ray.

mod planes;
mod power;
mod properties;
mod spheres;
mod triangles;

use proptest::prelude::*;
use raytrace::{Float, Vec3};
use twofloat::TwoFloat;

/// The fixed seed of the power checks (`common::harness_rejects`).
const HARNESS_SEED: u64 = 0x1DE5;

const REGRESSIONS: &str = "proptest-regressions/intersections.txt";

/// Cases per property and scalar: all checks are a few hundred flops, so 20 000 cases of the
/// five properties take about a second in the optimised test profile.
const CASES: u32 = 20_000;

/// `10^e`, `e` uniform in `[lo, hi)`: log-uniform magnitudes.
fn pow10(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|e| 10f64.powf(e))
}

/// `a + s·b` in `f64`.
fn axpy(a: [f64; 3], s: f64, b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] + s * b[i])
}

fn vec<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

fn zero() -> TwoFloat {
    TwoFloat::from(0.0)
}

/// `F::gamma(n)` as an `f64`.
fn gamma<F: Float>(n: u32) -> f64 {
    F::gamma(n).to_f64()
}
