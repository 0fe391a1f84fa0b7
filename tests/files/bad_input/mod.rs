//! Bad input: every constructor of a scene value, given arbitrary values
//! — NaN, ±∞, ±0, negatives, subnormals, the largest finite values, and random ones —
//! returns `Ok` exactly when the input is valid and otherwise an error naming what was
//! wrong, and never panics; the PPM reader never panics on arbitrary bytes and what it
//! accepts is self-consistent and round-trips. Scalar constructors run for f32 and f64.
//! (The examples' command line is tested in `tests/example_options.rs`.)
//!
//! # The validity predicates
//! Written here from the documented contracts, computed independently of the library
//! (exactly, in `f64` or double-double, from the values passed in):
//! - positions, centres, points: every component finite;
//! - radius, refractive index: finite and `> 0`;
//! - albedo channels: in `[0, 1]` (`−0` included); light intensity and background
//!   channels: finite and `≥ 0`;
//! - directions (a plane's normal, a camera's view direction `from − at` and up vector):
//!   finite and not zero ([`Vec3::try_normalize`] scales tiny and huge vectors first) —
//!   and, for the view direction, `from − at` itself finite;
//! - a triangle: finite vertices, edges `u = B − A`, `v = C − A` finite, and not collinear:
//!   `|u×v| > γ(6)|u||v|` (documented; judged on the edges scaled by their largest
//!   components, so long and tiny triangles are judged alike). Rounding of `u`, `v` and the
//!   cross product moves `|u×v|/(|u||v|)` by up to `(1 + √2·γ(2)/ε)ε ≈ 2.4ε` either side of
//!   the library's `3ε` threshold, so exact sines `≤ ε/4` are invalid, `> 8ε` valid, and in
//!   between either answer is accepted;
//! - the up vector must not be parallel to the view direction: exact `sin θ ≤ ε/4`
//!   invalid, `> 64ε` valid;
//! - field of view in `(0°, 180°)`; image sizes at least 1×1 and at most `MAX_PIXELS`
//!   pixels; the spec's camera 2:1 and at least 4×2; at least one sample per pixel.
//!
//! Within a relative `10⁻⁵` of an underflow or overflow threshold either answer is
//! accepted (the library decides on rounded values). An error must name (in its message)
//! one of the invalid inputs.
//!
//! # Regressions
//! This suite found four library bugs, now fixed; the `regression_*` tests pin the input
//! that showed each: a huge plane normal rejected (`|n|²` overflowed), a long thin
//! triangle rejected (`|u|²` overflowed in the threshold), a look-at camera accepting an up
//! vector parallel to the view and rejecting a short one, and `ScreenCamera::new`
//! overflowing on `2·height`.

mod constructors;
mod power;
mod ppm;
mod strategies;
mod verdicts;

const REGRESSIONS: &str = "proptest-regressions/bad_input.txt";

/// Cases per constructor property and scalar: each case is a constructor call.
const CASES: u32 = 10_000;
