//! Ray–sphere intersection where the textbook method fails: small spheres far away, near
//! and far roots, origins inside, tangent rays — in f32 and f64, each test written once.
//!
//! The textbook quadratic ([`textbook_sphere_hit`], *Ray Tracing in One Weekend*) computes
//! the discriminant as `b² − 4ac`, two numbers of size `~|f|²` (`f = O − C`) whose
//! difference is `~r²`: its relative error is `~ε(|f|/r)²`. [`Sphere::hit`] computes it as
//! `r² − |f − (f·D)D|²`, the squared distance from the centre to the ray's line, picks the
//! root without cancellation, and reprojects the hit point onto the sphere with an error
//! bound (`Hit::error`). Every check here is made against exact geometry: the rounded `F`
//! inputs are converted exactly to double-double and the reference roots, distances and
//! points computed there.
//!
//! # Criteria
//! - **On the surface:** a hit point is within `‖hit.error‖` of the sphere
//!   (`| |P − C| − r | ≤ ‖error‖`, the Euclidean length of the per-component bound).
//! - **At the right place:** the hit point is within `8ε(|O| + |C| + r)` of the exact
//!   intersection `O + t*·D` (first order: `f`, `b = f·D`, the perpendicular `f − bD`, the
//!   discriminant and the Vieta root each carry a few `ε` of `|f|`, amplified by at most
//!   `|l|/√Δ ≈ 2` for rays passing within `0.9r` of the centre; `O + tD` and the
//!   reprojection add `ε/2·|P|` and `γ(5)r`; largest seen: `3.2ε(|O| + |C| + r)`).
//! - **Visibly wrong** (for the textbook method): a miss, or a point more than `10⁻³r` off
//!   the surface (a thousandth of the radius: a pixel on a sphere 1000 pixels wide).

mod cases;
mod far_spheres;
mod properties;
// The study's third sphere (the stable roots spawning the textbook way) is not used here.
#[allow(dead_code)]
#[path = "../../../examples/precision/textbook.rs"]
mod textbook;

const REGRESSIONS: &str = "proptest-regressions/sphere_stability.txt";
