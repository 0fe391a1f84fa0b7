//! Directional (sun) and spot lights against their closed forms, in f32 and f64:
//!
//! - a sun of irradiance `E` lights a Lambertian plane of albedo `A` with exactly
//!   `A/π·E·cos θ` at every point (no falloff), nothing once a shadow ray toward it meets an
//!   occluder however far, nothing from below;
//! - a spot light equals a point light of the same intensity bit for bit inside its beam,
//!   gives nothing past its cutoff, and between them Mitsuba 3's ramp
//!   `(γ − θ)/(γ − β)`, checked against `A/π·I·s(θ)·cos θₛ/d²` from the geometry alone.
//!
//! A camera ray with `max_depth = 1` brings back exactly the direct light at its hit: the
//! scattered ray finds the black background (or, past the depth, black), so `L_d + A∘0`.

use rand::SeedableRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::{DefaultRng, DirectionalLight, SpotLight};
use std::f64::consts::PI;

const ALBEDO: [f64; 3] = [0.8, 0.5, 0.2];

fn v<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

/// The floor `y = 0` (matte, albedo [`ALBEDO`]), under a black sky.
fn floor<F: Float>() -> EnumScene<F> {
    let mut scene = EnumScene::new(Background::solid(Vec3::zero()).unwrap());
    scene.add(
        Plane::new(Vec3::zero(), v([0.0, 1.0, 0.0])).unwrap(),
        Lambertian::new(v(ALBEDO)).unwrap(),
    );
    scene
}

/// The light arriving at the camera from the floor's point `p`, seen from `p + (0, 1, 1)`.
fn seen<F: Float>(scene: &EnumScene<F>, p: [f64; 3]) -> Color<F> {
    let eye = [p[0], p[1] + 1.0, p[2] + 1.0];
    let ray = Ray::towards(v(eye), v(p)).unwrap();
    let mut rng = DefaultRng::seed_from_u64(1);
    Tracer::new(scene, 1).trace(&ray, 0, &mut rng)
}

/// The floor's points the tests look at.
const POINTS: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [3.0, 0.0, -2.0],
    [-40.0, 0.0, 17.5],
    [1e3, 0.0, 1e3],
];

fn close(got: f64, want: f64, tol: f64) -> bool {
    (got - want).abs() <= tol * want.abs().max(1e-30)
}

fn sun_lights_a_plane_with_a_over_pi_e_cos<F: Float>() {
    let e = [3.0, 2.0, 1.5];
    // From 60° off the zenith, cos θ = ½; and from straight above.
    for (direction, cos) in [([0.0, -0.5, -0.75f64.sqrt()], 0.5), ([0.0, -2.0, 0.0], 1.0)] {
        let sun = DirectionalLight::new(v::<F>(direction), v(e)).unwrap();
        let mut scene = floor::<F>();
        scene.add_light(sun);
        // The renderer's own arithmetic: (A·(1/π) ∘ E)·(cos θ/1), cos θ = N·(−d̂) in F.
        let cos_f = -sun.direction().y;
        let exact = v::<F>(ALBEDO) * (F::one() / lit::<F>(PI)) * v(e) * cos_f;
        for p in POINTS {
            let got = seen(&scene, p);
            assert_eq!(got, exact, "{}: {direction:?} at {p:?}", F::NAME);
            for k in 0..3 {
                let want = ALBEDO[k] / PI * e[k] * cos;
                assert!(
                    close(got[k].to_f64(), want, 8.0 * F::epsilon().to_f64()),
                    "{}: {} against {want}",
                    F::NAME,
                    got[k].to_f64()
                );
            }
        }
    }
}

fn sun_is_blocked_at_any_distance_and_lights_nothing_from_below<F: Float>() {
    let e = [1.0, 1.0, 1.0];
    let mut scene = floor::<F>();
    scene.add_light(DirectionalLight::new(v::<F>([0.0, -1.0, 0.0]), v(e)).unwrap());
    let lit_point = seen(&scene, [0.0, 0.0, 0.0]);
    assert!(lit_point.x > F::zero());
    // A small sphere a thousand units up blocks the sun; one to the side does not.
    scene.add(
        Sphere::new(v([0.0, 1000.0, 0.0]), lit(1.0)).unwrap(),
        Lambertian::new(v(ALBEDO)).unwrap(),
    );
    scene.add(
        Sphere::new(v([10.0, 1000.0, 0.0]), lit(1.0)).unwrap(),
        Lambertian::new(v(ALBEDO)).unwrap(),
    );
    assert_eq!(seen(&scene, [0.0, 0.0, 0.0]), Color::zero(), "{}", F::NAME);
    assert_eq!(seen(&scene, [5.0, 0.0, 0.0]), lit_point, "{}", F::NAME);
    // A sun shining upward lights the floor's underside only.
    let mut below = floor::<F>();
    below.add_light(DirectionalLight::new(v::<F>([0.3, 1.0, 0.0]), v(e)).unwrap());
    assert_eq!(seen(&below, [0.0, 0.0, 0.0]), Color::zero(), "{}", F::NAME);
}

/// The spot above the origin, pointing down, cutoff 40°, beam 20°.
const SPOT_AT: [f64; 3] = [0.0, 2.0, 0.0];
const INTENSITY: [f64; 3] = [20.0, 10.0, 5.0];
const CUTOFF: f64 = 40.0;
const BEAM: f64 = 20.0;

fn spot_scene<F: Float>() -> EnumScene<F> {
    let mut scene = floor::<F>();
    let spot = SpotLight::new(
        v(SPOT_AT),
        v([0.0, -1.0, 0.0]),
        v(INTENSITY),
        lit(CUTOFF),
        lit(BEAM),
    );
    scene.add_light(spot.unwrap());
    scene
}

fn point_scene<F: Float>() -> EnumScene<F> {
    let mut scene = floor::<F>();
    scene.add_light(PointLight::new(v(SPOT_AT), v(INTENSITY)).unwrap());
    scene
}

/// The floor's point at angle `theta` (degrees) from the spot's axis, in the direction `phi`.
fn at_angle(theta: f64, phi: f64) -> [f64; 3] {
    let r = SPOT_AT[1] * theta.to_radians().tan();
    [r * phi.cos(), 0.0, r * phi.sin()]
}

fn spot_is_a_point_light_in_its_beam_and_dark_past_its_cutoff<F: Float>() {
    let (spot, point) = (spot_scene::<F>(), point_scene::<F>());
    for (theta, phi) in [(0.0, 0.0), (5.0, 1.0), (12.0, 2.5), (19.5, -2.0)] {
        let p = at_angle(theta, phi);
        let got = seen(&spot, p);
        assert!(got.x > F::zero());
        assert_eq!(got, seen(&point, p), "{}: θ = {theta}°", F::NAME);
    }
    for (theta, phi) in [(40.5, 0.0), (45.0, 1.0), (70.0, 3.0), (89.0, -1.0)] {
        let p = at_angle(theta, phi);
        assert!(seen(&point, p).x > F::zero());
        assert_eq!(seen(&spot, p), Color::zero(), "{}: θ = {theta}°", F::NAME);
    }
}

fn spot_falls_off_between_as_mitsubas_ramp<F: Float>() {
    let scene = spot_scene::<F>();
    let tol = if F::NAME == "f32" { 2e-5 } else { 1e-10 };
    for (theta, phi) in [(21.0, 0.0), (25.0, 0.7), (30.0, 2.0), (35.0, -1.3), (39.0, 3.0)] {
        let p = at_angle(theta, phi);
        // Mitsuba's falloff, then the point light's law: A/π·I·s·cos θₛ/d², where the
        // floor's cosine to the light is cos θ (the spot points straight down) and
        // d = 2/cos θ.
        let s = (CUTOFF - theta) / (CUTOFF - BEAM);
        let cos = theta.to_radians().cos();
        let d2 = (SPOT_AT[1] / cos).powi(2);
        let got = seen(&scene, p);
        for k in 0..3 {
            let want = ALBEDO[k] / PI * INTENSITY[k] * s * cos / d2;
            assert!(
                close(got[k].to_f64(), want, tol),
                "{}: θ = {theta}°: {} against {want}",
                F::NAME,
                got[k].to_f64()
            );
        }
    }
}

macro_rules! for_f32_and_f64 {
    ($($name:ident),* $(,)?) => {
        mod f32_tests {
            $(#[test] fn $name() { super::$name::<f32>(); })*
        }
        mod f64_tests {
            $(#[test] fn $name() { super::$name::<f64>(); })*
        }
    };
}

for_f32_and_f64!(
    sun_lights_a_plane_with_a_over_pi_e_cos,
    sun_is_blocked_at_any_distance_and_lights_nothing_from_below,
    spot_is_a_point_light_in_its_beam_and_dark_past_its_cutoff,
    spot_falls_off_between_as_mitsubas_ramp,
);
