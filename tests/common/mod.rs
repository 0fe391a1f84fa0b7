//! Shared helpers of the optics, sampling and stability tests: proptest configuration and
//! strategies (unit vectors, normals whose squared length rounds above 1), scalar-generic
//! helpers, a double-double reference, a counting RNG, and ([`chi2`]) Pearson's χ² with its
//! p-value.
//!
//! Every strategy draws in `f64` and rounds to the scalar under test, so the f32 and f64
//! instances of a test see the same geometry (as the library's own sampling does).

// Each test binary includes this module and uses only part of it.
#![allow(dead_code)]

pub mod bsdf;
mod chi2;
pub mod draws;
mod scratch;
pub mod sphere_chi2;

pub use chi2::*;
pub use scratch::Scratch;

use proptest::prelude::*;
use proptest::test_runner::{FileFailurePersistence, RngSeed, TestRunner};
use rand::TryRng;
use raytrace::{Float, Vec3};
use std::convert::Infallible;
use std::f64::consts::TAU;
use twofloat::TwoFloat;

/// A proptest configuration with a fixed seed, so every run tests the same cases, and with
/// failures persisted under `proptest-regressions/` (`file` is the path from the package
/// root, e.g. `"proptest-regressions/reflection.txt"`; integration tests run there).
pub fn config(cases: u32, seed: u64, file: &'static str) -> ProptestConfig {
    ProptestConfig {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(file))),
        ..ProptestConfig::default()
    }
}

/// Whether a property run fails: the power checks run a test against a deliberately
/// wrong method and require this. Fixed `seed`, no shrinking, no regression file.
pub fn harness_rejects<S: Strategy>(
    strategy: S,
    cases: u32,
    seed: u64,
    test: impl Fn(S::Value) -> Result<(), TestCaseError>,
) -> bool {
    let mut runner = TestRunner::new(ProptestConfig {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        max_shrink_iters: 0,
        ..ProptestConfig::default()
    });
    runner.run(&strategy, test).is_err()
}

/// The scalar's machine epsilon (`2⁻²³` for f32, `2⁻⁵²` for f64) as an `f64`.
pub fn eps<F: Float>() -> f64 {
    F::epsilon().to_f64()
}

/// A vector converted exactly to double-double (exact for f32 and f64 components).
pub fn dd<F: Float>(v: Vec3<F>) -> Vec3<TwoFloat> {
    v.cast()
}

/// A scalar converted exactly to double-double.
pub fn dd1<F: Float>(x: F) -> TwoFloat {
    TwoFloat::from(x.to_f64())
}

/// `|v|` evaluated in double-double, as an `f64`: a reference length whose own rounding
/// (~10⁻³²) is negligible against the f64 errors under test.
pub fn length_dd<F: Float>(v: Vec3<F>) -> f64 {
    dd(v).length().to_f64()
}

/// A uniformly distributed unit vector in `f64` (Archimedes: `z` uniform in `[−1, 1]`).
pub fn unit_f64() -> impl Strategy<Value = [f64; 3]> {
    (-1.0f64..=1.0, 0.0f64..TAU).prop_map(|(z, phi)| {
        let s = (1.0 - z * z).max(0.0).sqrt();
        [s * phi.cos(), s * phi.sin(), z]
    })
}

/// The six axis directions `±x, ±y, ±z`, where components are exactly 0 and 1.
pub fn axis<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    (0usize..3, any::<bool>()).prop_map(|(i, neg)| {
        let mut v = [0.0; 3];
        v[i] = if neg { -1.0 } else { 1.0 };
        Vec3::from_f64(v[0], v[1], v[2])
    })
}

/// A unit vector of `F`: one of the axes (1 case in 8) or a uniformly random direction
/// rounded to `F` and normalized in `F` (so `| |v| − 1 |` is a few `ε`, as for the
/// normals a renderer computes).
pub fn unit<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    prop_oneof![
        1 => axis::<F>(),
        7 => unit_f64().prop_map(|[x, y, z]| Vec3::<F>::from_f64(x, y, z).normalize()),
    ]
}

/// `n` with its largest component moved away from zero one representable value at a time
/// until `|n|²`, *as computed in `F`*, is above 1: a "unit" normal whose squared length
/// rounds above 1, the input that makes `1 − cos²θ` negative in unclamped code.
pub fn inflate<F: Float>(mut n: Vec3<F>) -> Vec3<F> {
    while n.length_squared() <= F::one() {
        let (ax, ay, az) = (n.x.abs(), n.y.abs(), n.z.abs());
        let away = |c: F| {
            if c >= F::zero() {
                c.next_up()
            } else {
                c.next_down()
            }
        };
        if ax >= ay && ax >= az {
            n.x = away(n.x);
        } else if ay >= az {
            n.y = away(n.y);
        } else {
            n.z = away(n.z);
        }
    }
    n
}

/// A unit normal of `F` whose squared length, computed in `F`, exceeds 1 (see [`inflate`]).
pub fn inflated_unit<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    unit::<F>().prop_map(inflate)
}

/// An orthonormal frame `(t, b)` completing the unit `n` (computed here, in `f64`, by
/// Gram–Schmidt against the axis least aligned with `n`, independently of the library's
/// `orthonormal_basis`).
pub fn frame(n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let a = if n[0].abs() <= n[1].abs() && n[0].abs() <= n[2].abs() {
        [1.0, 0.0, 0.0]
    } else if n[1].abs() <= n[2].abs() {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let an = dot(a, n);
    let t = normalize([a[0] - an * n[0], a[1] - an * n[1], a[2] - an * n[2]]);
    let b = cross(n, t);
    (t, b)
}

/// `a·b` in `f64`.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a×b` in `f64`.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a/|a|` in `f64`.
pub fn normalize(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

/// The unit direction at polar angle `theta` from the unit `n` and azimuth `phi` in the
/// frame of [`frame`], in `f64`: `cos θ·n + sin θ (cos φ·t + sin φ·b)`.
pub fn direction_at(n: [f64; 3], theta: f64, phi: f64) -> [f64; 3] {
    let (t, b) = frame(n);
    let (s, c) = theta.sin_cos();
    let (sp, cp) = phi.sin_cos();
    std::array::from_fn(|i| c * n[i] + s * (cp * t[i] + sp * b[i]))
}

/// A vector of `F` from `f64` components, normalized in `F`.
pub fn unit_from<F: Float>(v: [f64; 3]) -> Vec3<F> {
    Vec3::<F>::from_f64(v[0], v[1], v[2]).normalize()
}

/// A random number generator that counts the words it hands out, to measure how many
/// draws a sampler consumes (e.g. the acceptance rate of a rejection loop).
pub struct CountingRng<R> {
    /// The wrapped generator.
    pub inner: R,
    /// `next_u64` calls (one per `f64` draw with rand's `StandardUniform`).
    pub u64s: u64,
    /// `next_u32` and `fill_bytes` calls: expected to stay 0 for the samplers tested.
    pub others: u64,
}

impl<R> CountingRng<R> {
    /// Wraps `inner` with zeroed counters.
    pub fn new(inner: R) -> Self {
        Self {
            inner,
            u64s: 0,
            others: 0,
        }
    }
}

impl<R: rand::Rng> TryRng for CountingRng<R> {
    type Error = Infallible;
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        self.others += 1;
        Ok(self.inner.next_u32())
    }
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        self.u64s += 1;
        Ok(self.inner.next_u64())
    }
    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        self.others += 1;
        self.inner.fill_bytes(dst);
        Ok(())
    }
}

/// The nearest `t` and its record at once, and the any-hit query, on a shape alone (the
/// trait asks the scene's questions only). No surface coordinates: the record a scene makes
/// for a material that reads none.
pub trait Alone<F: Float>: raytrace::Hittable<F> {
    fn hit(&self, ray: &raytrace::Ray<F>, t_max: F) -> Option<raytrace::Hit<F>> {
        let i = self.intersect(ray, t_max)?;
        Some(self.finish(ray, &i))
    }
    fn occluded(&self, ray: &raytrace::Ray<F>, t_max: F) -> bool {
        self.intersect(ray, t_max).is_some()
    }
}

impl<F: Float, S: raytrace::Hittable<F> + ?Sized> Alone<F> for S {}
