//! Renders of randomly generated valid scenes: no NaN or
//! infinite pixel and no negative channel, ever; and energy conservation where the scene
//! has no light source brighter than 1. Each property runs for f32 and f64 with a fixed
//! proptest seed.
//!
//! # The scenes
//! One to twelve objects, intersected through `Auto`, the plain loop or a forced BVH
//! (with fewer than [`Acceleration::AUTO_THRESHOLD`] bounded objects `Auto` loops): spheres of radius `10^U(−4, 4)` through a point near the camera (from specks to
//! walls, and now and then a sphere that swallows the camera),
//! planes through any point with any normal, and triangles of size `10^U(−4, 2)`, all near
//! the camera (positions in `[−6, 6]² × [−14, 4]`). Materials: mirror, matte and glass;
//! albedo channels exactly 0, exactly 1, or uniform in `[0, 1]`; glass indices exactly 1,
//! in `[1, 3]`, or below 1 (`[0.3, 1)`, a bubble), with Schlick's or the exact Fresnel
//! reflectance. Zero to three point lights, intensity channels 0, or up to 100, anywhere —
//! including exactly on a surface (a plane's point, a sphere's pole, a triangle's vertex).
//! A solid or sky background with channels in `[0, 2]` (exactly 2 one time in three). The spec's [`ScreenCamera`]
//! (8×4 or 16×8) or a [`LookAtCamera`] (8×8, field of view 10° to 170°, anywhere, looking
//! anywhere). One to four samples per pixel, depth 0 to 12, any seed.
//!
//! # Energy conservation
//! With no point lights and a background whose channels are at most 1, a path's colour is
//! the background seen by its last ray (at most 1 per channel: a sky is a convex
//! combination of its two colours) times the albedos of the surfaces it met, each at most 1
//! per channel (the constructors enforce it), or black (absorbed or too deep); a glass
//! surface chooses reflection or refraction with probabilities summing to 1, each path
//! carrying the albedo, so no path gains energy either. Nothing in the scene emits. So
//! every sample is at most 1 per channel, and so is a pixel, their mean. In floating point
//! a product of numbers `≤ 1` rounds to at most 1 (rounding is monotone and 1 is
//! representable); the sky's weight `s = (y + 1)/2` may exceed 1 by a few ulps for a
//! direction whose `y` rounds above 1, and the mean of `n` samples adds `γ(n)`: the bound
//! is `1 + (n + 8)ε`.

mod properties;
mod regression;
mod scenes;

const REGRESSIONS: &str = "proptest-regressions/random_scenes.txt";

/// Cases per property and scalar: a case renders at most 16×8 pixels × 4 samples × 13
/// bounces (well under a millisecond), so the file runs in a second or two.
const CASES: u32 = 3000;
