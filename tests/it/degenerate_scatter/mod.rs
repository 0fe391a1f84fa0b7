//! Where scattering directions cancel or graze: the degenerate
//! Lambertian direction and grazing mirror reflection, in f32 and f64.
//!
//! # The degenerate Lambertian direction
//! The spec's matte scatter is `D = (N + S)/|N + S|`, `S` a uniform point on the unit
//! sphere. When `S` is drawn at (or within rounding of) `−N` the sum cancels: exactly `−N`
//! gives `0/0 = NaN`, and `−N` one ulp off gives a vector of rounding noise whose
//! direction can point anywhere — the tests below construct one that points straight into
//! the surface. [`lambertian_direction`] redraws such `S` (the cap `|N + S|² ≤ 64ε`).
//!
//! To feed it chosen draws, [`Scripted`] replays `u64` words and then continues from a
//! seeded stream. rand 0.10 turns a word `w` into the `f64` `u = (w >> 11)·2⁻⁵³` (the 53
//! high bits), and the spec's sampler maps `u` to the coordinate `x = 2u − 1`, so the word
//! `k << 11` yields exactly `x = k·2⁻⁵² − 1`: every coordinate on the grid `2⁻⁵²` in
//! `[−1, 1)` can be scripted exactly ([`word_for`]).
//!
//! # Grazing mirror reflection
//! `r = d − 2(d·n)n` for `d` within `10⁻³⁰` to `10⁻¹` radians of the surface (or in it):
//! `r` stays finite and unit, and on the side the normal faces (see
//! [`check_reflection`] for the bound and why it is not exactly `r·n ≥ 0`).

mod grazing;
mod lambertian;
mod properties;
mod scripted;

/// The fixed seed of the power checks (`common::harness_rejects`).
const HARNESS_SEED: u64 = 0xDE6E;

const REGRESSIONS: &str = "proptest-regressions/degenerate_scatter.txt";

/// Cases per property and scalar (each is one sampler or reflection call).
const CASES: u32 = 10_000;
