//! Property tests of refraction and reflectance ([`raytrace::optics`]: `refract`, `schlick`,
//! `schlick_reflectance`, `fresnel`), each written once and run for f32 and f64 with a
//! fixed proptest seed.
//!
//! Conventions as in the library: `d` is the incident unit direction, `n` the unit normal
//! on the side `d` comes from (`d·n ≤ 0`), `η = η₁/η₂` the ratio of the refractive indices
//! on the incident and the far side. Indices range over `[1, 2.5]` (air to diamond), so
//! `η ∈ [0.4, 2.5]`.
//!
//! # Tolerances
//! Inputs are rounded to the scalar and normalized in it: `|d|², |n|² = 1 ± 3.5ε`, and the
//! library's `cos θ₁ = −d·n` is off by `≤ γ(3) ≈ 1.5ε`. Each bound below is a first-order
//! error analysis in units of `ε`, scaled by the powers of `η` that multiply the rounded
//! terms; the largest error seen in 2·10⁶ random cases is quoted beside it. Checks are
//! evaluated in double-double, whose own rounding is negligible.

mod directions;
mod incidences;
mod properties;
mod reflectance;

const REGRESSIONS: &str = "proptest-regressions/refraction.txt";
