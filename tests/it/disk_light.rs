//! The disk as a light: its points are drawn uniformly by area, their density is converted
//! to solid angle, and an emissive disk lights a floor with the irradiance the closed form
//! gives.
//!
//! # Uniform by area (χ²)
//! A point `C + aU + bV` of a disk is uniform over its area iff `(a, b)` is uniform over the
//! unit disk (an affine map keeps densities uniform), iff `u = a² + b²` and `v = φ/2π`
//! (`φ = atan2(b, a)`) are independent and uniform on `[0, 1)`. `(a, b)` is recovered from
//! the sampled point in `f64`, and Pearson's χ² runs on 20 bins of `u`, 24 of `v` and the
//! 8 × 12 joint grid from `2²⁰` samples (the harness of `triangle_light_chi2.rs`); it rejects
//! at `p < 10⁻⁶`, and a point off the disk or off its plane rejects outright. The disk is an
//! ellipse, its axes neither perpendicular nor of one length. The wrong twin, the radius
//! `√u₀` drawn as `u₀`, is rejected.
//!
//! # Density
//! `mean(1/p_ω)` over `2¹⁸` samples must equal the solid angle the disk subtends, which for
//! a round disk of radius `r` seen on its axis from a distance `h` is `2π(1 − h/√(h² + r²))`,
//! within 5 standard errors (two-sided `p ≈ 5.7·10⁻⁷`); the conversion `p_A·d/|cos|`
//! instead of `p_A·d²/|cos|` is rejected.
//!
//! # Irradiance
//! A disk of radiance `L` and radius `r`, parallel to a matte floor at height `h` and
//! facing it, its axis `ρ` from a floor point, gives that point the irradiance
//! `E = πL·½(1 − (h² + ρ² − r²)/√((h² + ρ² + r²)² − 4r²ρ²))` (the configuration factor
//! of a disk to a parallel element; `πL·r²/(h² + r²)` on the axis, `ρ = 0`), so the floor of
//! albedo `A` returns `A/π·E`. The renderer's mean of `2¹⁶` samples (one seed each) must
//! match per channel within 5 standard errors, with sampled emitters (NEE + MIS) and with
//! scattered rays alone; the same check rejects a lamp 2 % too bright.

use crate::common;

use common::draws::*;
use common::*;
use rand::SeedableRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::shape::Disk;
use raytrace::{DefaultRng, Hittable};
use std::f64::consts::{PI, TAU};

fn v<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

/// An ellipse off every axis: centre `C`, axes `U` and `V` at 70° of lengths 1.5 and 0.6.
const C: [f64; 3] = [0.4, -0.3, -3.0];
const U: [f64; 3] = [1.2, 0.6, -0.6];
const V: [f64; 3] = [0.1, 0.5, 0.3];

/// `(a, b)` with `p = C + aU + bV` and the distance of `p` from that plane, in `f64`.
fn local(p: [f64; 3]) -> ((f64, f64), f64) {
    let q = sub(p, C);
    let (uu, uv, vv) = (dot(U, U), dot(U, V), dot(V, V));
    let (qu, qv) = (dot(q, U), dot(q, V));
    let det = uu * vv - uv * uv;
    let (a, b) = ((vv * qu - uv * qv) / det, (uu * qv - uv * qu) / det);
    let off = dot(q, normalize(cross(U, V)));
    ((a, b), off)
}

/// `(a² + b², φ/2π)` of a sampled point, or `None` if it is off the disk or its plane.
fn disk_uv(p: [f64; 3], tol: f64) -> Option<(f64, f64)> {
    let ((a, b), off) = local(p);
    let r2 = a * a + b * b;
    (r2 <= 1.0 + tol && off.abs() <= tol * 8.0).then(|| (r2.min(1.0), (b.atan2(a) / TAU).rem_euclid(1.0)))
}

fn disks_are_sampled_uniformly_by_area<F: Float>() {
    let disk = Disk::with_axes(v::<F>(C), v(U), v(V)).unwrap();
    let tol = 64.0 * eps::<F>();
    let from = v::<F>([0.0, 0.0, 0.0]);
    let verdict = chi2_uv(61, |u| disk_uv(disk.sample(from, u)?.point.to_f64(), tol));
    println!("disk {}: {verdict:?}", F::NAME);
    assert!(!verdict.rejected(), "{}: {verdict:?}", F::NAME);
    let area = disk.area().unwrap().to_f64();
    assert!((area - PI * len(cross(U, V))).abs() < 1e-5 * area, "{area}");
}

#[test]
fn disks_are_sampled_uniformly_by_area_f32() {
    disks_are_sampled_uniformly_by_area::<f32>();
}

#[test]
fn disks_are_sampled_uniformly_by_area_f64() {
    disks_are_sampled_uniformly_by_area::<f64>();
}

/// The wrong twin: the radius drawn uniformly, which crowds the centre.
#[test]
fn the_disk_test_rejects_a_radius_drawn_uniformly() {
    let verdict = chi2_uv(62, |u| {
        let (r, phi) = (u[0], TAU * u[1]);
        let (a, b) = (r * phi.cos(), r * phi.sin());
        let p: [f64; 3] = std::array::from_fn(|i| C[i] + a * U[i] + b * V[i]);
        disk_uv(p, 1e-9)
    });
    println!("radius uniform: {verdict:?}");
    assert!(verdict.rejected());
}

/// The round disk of radius 0.8 about `(0, 2, 0)` facing down, seen from `(0, 2 − h, 0)`.
fn on_axis<F: Float>() -> Disk<F> {
    Disk::new(v([0.0, 2.0, 0.0]), v([0.0, -1.0, 0.0]), lit(0.8)).unwrap()
}

fn disk_density_is_per_solid_angle<F: Float>() {
    let disk = on_axis::<F>();
    for (k, h) in [0.3, 2.0, 40.0].into_iter().enumerate() {
        let at = v::<F>([0.0, 2.0 - h, 0.0]);
        let want = TAU * (1.0 - h / (h * h + 0.64f64).sqrt());
        let (mean, z) =
            mean_inverse_density(70 + k as u64, want, |u| disk.sample(at, u).unwrap().pdf.to_f64());
        println!(
            "disk {} from h = {h}: mean 1/p = {mean}, Ω = {want}, z = {z}",
            F::NAME
        );
        assert!(z.abs() < Z_MAX, "{} h = {h}: z = {z}", F::NAME);
    }
}

#[test]
fn disk_density_is_per_solid_angle_f32() {
    disk_density_is_per_solid_angle::<f32>();
}

#[test]
fn disk_density_is_per_solid_angle_f64() {
    disk_density_is_per_solid_angle::<f64>();
}

/// The wrong conversion, `p_A·d/|cos|`, is seen by the same test.
#[test]
fn the_solid_angle_test_rejects_a_wrong_conversion() {
    let disk = on_axis::<f64>();
    let at = v::<f64>([0.0, 0.0, 0.0]);
    let want = TAU * (1.0 - 2.0 / 4.64f64.sqrt());
    let (_, z) = mean_inverse_density(73, want, |u| {
        let s = disk.sample(at, u).unwrap();
        s.pdf / (s.point - at).length()
    });
    println!("d/|cos|: z = {z}");
    assert!(z.abs() > Z_MAX);
}

/// Samples per irradiance check.
const N: u64 = 1 << 16;
const ALBEDO: [f64; 3] = [0.8, 0.5, 0.3];
const RADIANCE: [f64; 3] = [3.0, 2.0, 1.0];

/// A disk lamp of radius `r` facing down at height `h`, its axis `rho` from the origin of a
/// matte floor `y = 0`.
struct Lamp {
    r: f64,
    h: f64,
    rho: f64,
}

impl Lamp {
    fn scene<F: Float>(&self, radiance: [f64; 3]) -> (EnumScene<F>, Ray<F>) {
        let mut scene = EnumScene::new(Background::solid(Vec3::zero()).unwrap());
        scene.add(
            Plane::new(Vec3::zero(), v([0.0, 1.0, 0.0])).unwrap(),
            Lambertian::new(v(ALBEDO)).unwrap(),
        );
        let lamp = Disk::new(v([self.rho, self.h, 0.0]), v([0.0, -1.0, 0.0]), lit(self.r)).unwrap();
        scene.add(lamp, Emissive::new(v(radiance)).unwrap());
        // From below the lamp's plane, on the side away from it, down to the origin.
        let ray = Ray::towards(v([-1.0, 0.5 * self.h, 0.3]), Vec3::zero()).unwrap();
        (scene, ray)
    }

    /// `A/π·E` with the configuration factor of the module's documentation.
    fn expected(&self) -> [f64; 3] {
        let (r2, h2, p2) = (self.r * self.r, self.h * self.h, self.rho * self.rho);
        let s = h2 + p2 + r2;
        let factor = 0.5 * (1.0 - (h2 + p2 - r2) / (s * s - 4.0 * r2 * p2).sqrt());
        std::array::from_fn(|k| ALBEDO[k] * RADIANCE[k] * factor)
    }
}

const LAMPS: [Lamp; 3] = [
    Lamp {
        r: 0.5,
        h: 1.5,
        rho: 0.0,
    },
    Lamp {
        r: 1.0,
        h: 0.8,
        rho: 1.5,
    },
    Lamp {
        r: 0.2,
        h: 3.0,
        rho: 0.7,
    },
];

/// The mean and standard error per channel of `ray`'s colour over `N` seeds, two bounces.
fn estimate<F: Float>(scene: &EnumScene<F>, ray: &Ray<F>, sampling: LightSampling) -> [(f64, f64); 3] {
    let mut tracer = Tracer::new(scene, 2).light_sampling(sampling);
    let (mut sum, mut sum2) = ([0.0; 3], [0.0; 3]);
    for seed in 0..N {
        let c = tracer
            .trace(ray, 0, &mut DefaultRng::seed_from_u64(seed))
            .to_f64();
        for k in 0..3 {
            sum[k] += c[k];
            sum2[k] += c[k] * c[k];
        }
    }
    let n = N as f64;
    std::array::from_fn(|k| {
        let mean = sum[k] / n;
        (mean, ((sum2[k] / n - mean * mean).max(0.0) / (n - 1.0)).sqrt())
    })
}

/// Whether every channel is within `Z_MAX` standard errors of `want`.
fn agrees(got: [(f64, f64); 3], want: [f64; 3], what: &str) -> bool {
    got.iter().zip(want).all(|(&(mean, se), want)| {
        let z = (mean - want) / se;
        println!("{what}: mean {mean:.6}, expected {want:.6}, z = {z:.2}");
        z.abs() <= Z_MAX
    })
}

fn irradiance_from_a_disk<F: Float>() {
    for lamp in &LAMPS {
        let (scene, ray) = lamp.scene::<F>(RADIANCE);
        assert_eq!(scene.emitters().len(), 1, "the disk is sampled as a light");
        for sampling in [LightSampling::Mis, LightSampling::Bsdf] {
            let what = format!(
                "{} r = {} h = {} ρ = {} {sampling:?}",
                F::NAME,
                lamp.r,
                lamp.h,
                lamp.rho
            );
            assert!(
                agrees(estimate(&scene, &ray, sampling), lamp.expected(), &what),
                "{what}"
            );
        }
    }
}

#[test]
fn irradiance_from_a_disk_f32() {
    irradiance_from_a_disk::<f32>();
}

#[test]
fn irradiance_from_a_disk_f64() {
    irradiance_from_a_disk::<f64>();
}

/// The check has the power to see a lamp 2 % too bright with sampled emitters.
#[test]
fn the_irradiance_check_sees_a_wrong_lamp() {
    let lamp = &LAMPS[0];
    let (scene, ray) = lamp.scene::<f64>(RADIANCE.map(|l| l * 1.02));
    let got = estimate(&scene, &ray, LightSampling::Mis);
    assert!(!agrees(got, lamp.expected(), "1.02× as bright, MIS"));
}
