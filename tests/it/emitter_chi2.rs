//! Statistical tests of the samplers next-event estimation draws lights with, for
//! spheres and for the choice among emitters: a sphere's cone of directions (seen from
//! outside) and its surface (seen from inside), an emitter chosen in proportion to its
//! power, and, for every shape, the density a scattered ray's MIS weight uses. Triangles
//! and meshes are in `triangle_light_chi2.rs`; the harness is `tests/common/draws.rs`.
//!
//! # The χ² harness
//! As in `lambertian_chi2.rs`: each sample is mapped to `(u, v) ∈ [0, 1)²`, independent
//! and uniform under the correct distribution, and Pearson's χ² is computed on 20 bins of
//! `u`, 24 of `v` and the 8 × 12 joint grid from `2²⁰` samples:
//! - the cone from outside, about the axis `w` towards the centre: `u = (1 − cos θ)/(1 −
//!   cos θ_max)` (a direction uniform in solid angle over the cone has `cos θ` uniform on
//!   `[cos θ_max, 1]`) and `v = φ/2π`;
//! - the sphere from inside: `u = (1 + n·a)/2` and `v = φ/2π` of the sampled normal `n`
//!   about an axis `a` (Archimedes).
//!
//! The choice among emitters is tested with χ² against their expected shares (`k − 1`
//! degrees of freedom). Every χ² test rejects at `p < 10⁻⁶` ([`CHI2_ALPHA`]). A sample
//! that is impossible under the claimed distribution (a point off the sphere or hidden from
//! `from`, a direction outside the cone, a density other than the one claimed) rejects
//! outright.
//!
//! # Densities
//! What MIS needs besides the distribution is its density. For the cone it is checked
//! exactly (it is constant); from inside, `mean(1/p_ω)` over `2¹⁸` samples must equal `4π`,
//! the solid angle the sphere covers (`E[1/p] = ∫ dω`), within 5 standard errors
//! (two-sided `p ≈ 5.7·10⁻⁷`). And for every sampled point of a sphere, a triangle or a
//! mesh, the density the shape reports for a ray that hits it there (`Hittable::pdf`, what
//! a scattered ray's weight uses) must be the one `sample` returned.
//!
//! # Power
//! Each harness also runs a wrong twin and must reject it: the visible cap sampled
//! uniformly by area instead of the cone by solid angle, the cone's angle (not its cosine)
//! uniform, and emitters chosen uniformly. With these seeds every correct sampler gives
//! `p > 10⁻³` and every twin `p < 10⁻²⁰` (run with `--nocapture` to see them).

use crate::common;

use common::draws::*;
use common::*;
use rand::SeedableRng;
use rand::rngs::Xoshiro256PlusPlus;
use raytrace::sampling::uniform;
use raytrace::shape::SurfaceSample;
use raytrace::{Background, Emissive, Lambertian, Plane};
use raytrace::{EnumScene, Float, Hittable, Sphere, Triangle, Vec3, lit};
use std::f64::consts::{PI, TAU};

/// A sphere of radius `r` whose centre lies `ratio·r` from `from` along a skew axis.
fn sphere_seen_from<F: Float>(from: [f64; 3], ratio: f64, r: f64) -> (Sphere<F>, [f64; 3]) {
    let axis = normalize([1.0, -2.0, 0.5]);
    let c: [f64; 3] = std::array::from_fn(|i| from[i] + ratio * r * axis[i]);
    (Sphere::new(Vec3::from_f64(c[0], c[1], c[2]), lit(r)).unwrap(), c)
}

/// The cone test: `(u, v)` of the direction from `from` to a sampled point of a sphere of
/// radius `r` centred at `c`, or `None` if the point is off the sphere, hidden from
/// `from`, outside the cone, or its density is not the cone's.
fn cone_uv(from: [f64; 3], c: [f64; 3], r: f64, s: SurfaceSample<f64>, tol: f64) -> Option<(f64, f64)> {
    let d = len(sub(c, from));
    let w = normalize(sub(c, from));
    let p = s.point.to_f64();
    let sin2_max = (r / d) * (r / d);
    let one_minus_cos_max = sin2_max / (1.0 + (1.0 - sin2_max).sqrt());
    let on_sphere = (len(sub(p, c)) - r).abs() <= tol * (r + len(c));
    let n = s.normal.to_f64();
    let faces_from = dot(n, normalize(sub(from, p))) >= -tol.sqrt();
    let pdf_ok = (s.pdf.to_f64() * TAU * one_minus_cos_max - 1.0).abs() <= tol;
    let dir = normalize(sub(p, from));
    let x = cross(dir, w);
    let u = dot(x, x) / (1.0 + dot(dir, w)) / one_minus_cos_max;
    (on_sphere && faces_from && pdf_ok && u <= 1.0 + 1e3 * tol).then(|| (u.min(1.0), azimuth(dir, frame(w))))
}

fn cone_sampling_is_uniform_in_solid_angle<F: Float>() {
    let from = [0.1, 0.2, 0.3];
    let tol = 64.0 * eps::<F>();
    for (k, ratio) in [1.05, 2.0, 30.0, 3000.0].into_iter().enumerate() {
        let r = 0.7;
        let (sphere, c) = sphere_seen_from::<F>(from, ratio, r);
        let at = Vec3::<F>::from_f64(from[0], from[1], from[2]);
        let verdict = chi2_uv(100 + k as u64, |u| {
            let s = sphere.sample(at, u)?;
            let s64 = SurfaceSample {
                point: s.point.cast(),
                normal: s.normal.cast(),
                part: s.part,
                pdf: s.pdf.to_f64(),
            };
            cone_uv(from, c, r, s64, tol)
        });
        println!("cone {} d/r = {ratio}: {verdict:?}", F::NAME);
        assert!(!verdict.rejected(), "{} d/r = {ratio}: {verdict:?}", F::NAME);
    }
}

#[test]
fn cone_sampling_is_uniform_in_solid_angle_f32() {
    cone_sampling_is_uniform_in_solid_angle::<f32>();
}

#[test]
fn cone_sampling_is_uniform_in_solid_angle_f64() {
    cone_sampling_is_uniform_in_solid_angle::<f64>();
}

/// The wrong twins of the cone: the cap visible from `from` uniform by area, and the
/// cone's angle uniform instead of its cosine. Both give points on the sphere seen from
/// `from`, with the cone's density claimed.
#[test]
fn the_cone_test_rejects_wrong_samplers() {
    let (from, r) = ([0.1, 0.2, 0.3], 0.7);
    let (sphere, c) = sphere_seen_from::<f64>(from, 2.0, r);
    let w = normalize(sub(c, from));
    let d = len(sub(c, from));
    let claimed = sphere
        .sample(Vec3::from_f64(from[0], from[1], from[2]), [0.5; 3])
        .unwrap()
        .pdf;
    let (t, b) = frame(w);
    // The point at angle α from the centre's direction to `from`, azimuth φ.
    let at_angle = |cos_a: f64, phi: f64| {
        let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
        let n: [f64; 3] =
            std::array::from_fn(|i| -cos_a * w[i] + sin_a * (phi.cos() * t[i] + phi.sin() * b[i]));
        let point = Vec3::from_f64(c[0] + r * n[0], c[1] + r * n[1], c[2] + r * n[2]);
        SurfaceSample {
            point,
            normal: Vec3::from_f64(n[0], n[1], n[2]),
            part: 0,
            pdf: claimed,
        }
    };
    let cap = chi2_uv(7, |u| {
        // The visible cap: cos α from r/d to 1, uniform in area.
        let cos_a = 1.0 - u[0] * (1.0 - r / d);
        cone_uv(from, c, r, at_angle(cos_a, TAU * u[1]), 1e-12)
    });
    let theta_max = (r / d).asin();
    let angle = chi2_uv(8, |u| {
        // θ uniform in [0, θ_max], then the nearer intersection (pbrt's cos α).
        let (sin_t, cos_t) = (u[0] * theta_max).sin_cos();
        let sin_max = r / d;
        let cos_a =
            sin_t * sin_t / sin_max + cos_t * (1.0 - sin_t * sin_t / (sin_max * sin_max)).max(0.0).sqrt();
        cone_uv(from, c, r, at_angle(cos_a, TAU * u[1]), 1e-12)
    });
    println!("cap by area: {cap:?}\nangle uniform: {angle:?}");
    assert!(cap.rejected() && angle.rejected());
}

fn sphere_from_inside_is_uniform_by_area<F: Float>() {
    let (c, r) = ([0.3, -0.2, 0.5], 2.0);
    let sphere = Sphere::<F>::new(Vec3::from_f64(c[0], c[1], c[2]), lit(r)).unwrap();
    let from = [c[0] + 0.6, c[1] - 0.5, c[2] + 0.4];
    let at = Vec3::<F>::from_f64(from[0], from[1], from[2]);
    let a = normalize([0.3, 1.0, -0.2]);
    let tol = 64.0 * eps::<F>();
    let verdict = chi2_uv(21, |u| {
        let s = sphere.sample(at, u)?;
        let n = s.normal.to_f64();
        let on_sphere = (len(sub(s.point.to_f64(), c)) - r).abs() <= tol * (r + len(c));
        on_sphere.then(|| ((1.0 + dot(n, a)) / 2.0, azimuth(n, frame(a))))
    });
    println!("inside {}: {verdict:?}", F::NAME);
    assert!(!verdict.rejected(), "{}: {verdict:?}", F::NAME);
    let (mean, z) = mean_inverse_density(22, 4.0 * PI, |u| sphere.sample(at, u).unwrap().pdf.to_f64());
    println!(
        "inside {}: mean 1/p = {mean} (4π = {}), z = {z}",
        F::NAME,
        4.0 * PI
    );
    assert!(z.abs() < Z_MAX, "{}: z = {z}", F::NAME);
}

#[test]
fn sphere_from_inside_is_uniform_by_area_f32() {
    sphere_from_inside_is_uniform_by_area::<f32>();
}

#[test]
fn sphere_from_inside_is_uniform_by_area_f64() {
    sphere_from_inside_is_uniform_by_area::<f64>();
}

/// Five sampled emitters of different powers, and two that are not sampled (a plane, and
/// a black sphere), among matte objects.
fn emitters_scene() -> (EnumScene<f64>, Vec<f64>) {
    let v = Vec3::new;
    let mut scene = EnumScene::new(Background::default());
    let matte = Lambertian::new(Vec3::splat(0.5)).unwrap();
    let light = |l: f64| Emissive::new(Vec3::new(l, 0.5 * l, 0.25 * l)).unwrap();
    let sphere = |x: f64, r: f64| Sphere::new(v(x, 0.0, -5.0), r).unwrap();
    scene.add(sphere(0.0, 1.0), matte);
    scene.add(sphere(3.0, 0.5), light(4.0));
    scene.add(sphere(6.0, 1.0), light(1.0));
    scene.add(
        Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0)).unwrap(),
        light(1.0),
    );
    scene.add(sphere(9.0, 2.0), light(0.0));
    let tri = Triangle::new(v(0.0, 3.0, -5.0), v(2.0, 3.0, -5.0), v(0.0, 5.0, -5.0)).unwrap();
    scene.add(tri, light(3.0).two_sided(true));
    scene.add(four_triangles::<f64>().0, light(0.5));
    scene.add(sphere(12.0, 0.2), light(20.0));
    // Φ = π·L̄·s·A, L̄ = (1 + ½ + ¼)/3·l.
    let mean = |l: f64| l * 1.75 / 3.0;
    let powers = [
        PI * mean(4.0) * 4.0 * PI * 0.25,
        PI * mean(1.0) * 4.0 * PI,
        PI * mean(3.0) * 2.0 * 2.0,
        PI * mean(0.5) * 16.0,
        PI * mean(20.0) * 4.0 * PI * 0.04,
    ];
    (scene, powers.to_vec())
}

#[test]
fn emitters_are_chosen_by_power() {
    let (scene, powers) = emitters_scene();
    let emitters = scene.emitters();
    assert_eq!(emitters.objects(), &[1, 2, 5, 6, 7]);
    let total: f64 = powers.iter().sum();
    for (got, want) in emitters.probabilities().iter().zip(&powers) {
        assert!((got - want / total).abs() < 1e-12, "{got} vs {}", want / total);
    }
    let shares = emitters.probabilities().to_vec();
    let index = |object: usize| {
        emitters
            .objects()
            .iter()
            .position(|&o| o as usize == object)
            .unwrap()
    };
    let p = choice_p(61, &shares, |u| {
        let (object, probability) = emitters.choose(u[0]);
        assert_eq!(probability, shares[index(object)]);
        index(object)
    });
    println!("emitters: p = {p}");
    assert!(p >= CHI2_ALPHA, "p = {p}");
    let uniform_choice = choice_p(62, &shares, |u| ((u[0] * 5.0) as usize).min(4));
    println!("emitters chosen uniformly: p = {uniform_choice}");
    assert!(uniform_choice < CHI2_ALPHA);
}

/// What a scattered ray's MIS weight uses: for a ray from `from` that hits the shape at a
/// sampled point, `Hittable::pdf` is the density `sample` returned for it.
fn density_of_a_hit_is_the_sampled_one<F: Float>() {
    let (mesh, _) = four_triangles::<F>();
    let v = TRIANGLE.map(|p| Vec3::<F>::from_f64(p[0], p[1], p[2]));
    let triangle = Triangle::new(v[0], v[1], v[2]).unwrap();
    let (outside, _) = sphere_seen_from::<F>([0.1, 0.2, 0.3], 3.0, 0.7);
    let big = Sphere::new(Vec3::from_f64(0.3, -0.2, 0.5), lit(2.0)).unwrap();
    let shapes: [(&str, &dyn Hittable<F>, [f64; 3]); 4] = [
        ("sphere from outside", &outside, [0.1, 0.2, 0.3]),
        ("sphere from inside", &big, [0.9, -0.7, 0.9]),
        ("triangle", &triangle, [0.5, 0.8, -2.5]),
        ("mesh", &mesh, [1.0, 2.0, 3.0]),
    ];
    let tol = 1e3 * eps::<F>();
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(71);
    for (name, shape, from) in shapes {
        let at = Vec3::<F>::from_f64(from[0], from[1], from[2]);
        let mut missed = 0;
        for _ in 0..10_000 {
            let s = shape
                .sample(at, [uniform(&mut rng), uniform(&mut rng), uniform(&mut rng)])
                .unwrap();
            let ray = raytrace::Ray::new(at, (s.point - at).normalize());
            let Some(hit) = shape.hit(&ray, F::infinity()) else {
                missed += 1;
                continue;
            };
            // Rounding moves the cosine at the emitter by ~ε, relatively ε/|cos|.
            let cos = hit.normal.dot(ray.direction).abs().to_f64();
            let ratio = shape.pdf(&ray, &hit).to_f64() / s.pdf.to_f64();
            assert!(
                (ratio - 1.0).abs() < tol / cos.min(1.0),
                "{name} in {}: {ratio}",
                F::NAME
            );
        }
        assert!(
            missed <= 10,
            "{name} in {}: {missed} rays missed their sampled point",
            F::NAME
        );
    }
}

#[test]
fn density_of_a_hit_is_the_sampled_one_f32() {
    density_of_a_hit_is_the_sampled_one::<f32>();
}

#[test]
fn density_of_a_hit_is_the_sampled_one_f64() {
    density_of_a_hit_is_the_sampled_one::<f64>();
}
