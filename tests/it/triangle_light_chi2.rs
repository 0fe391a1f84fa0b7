//! Statistical tests of the samplers next-event estimation draws triangle lights with: a
//! point uniform on a triangle, a mesh's triangle in proportion to its area, and the change
//! of density from area to solid angle. Spheres and the choice among emitters are in
//! `emitter_chi2.rs`; the harness is `tests/common/draws.rs`.
//!
//! # The χ² harness
//! As in `lambertian_chi2.rs`: each sampled point is mapped through its barycentrics `b` to
//! `u = 1 − (1 − b₀)²` (the density of `b₀` is `2(1 − b₀)`) and `v = b₁/(1 − b₀)` (uniform
//! given `b₀`), independent and uniform under the correct distribution, and Pearson's χ² is
//! computed on 20 bins of `u`, 24 of `v` and the 8 × 12 joint grid from `2²⁰` samples. A
//! mesh's choice of triangles is tested against their shares of the area (3 degrees of
//! freedom). Every χ² test rejects at `p < 10⁻⁶` ([`CHI2_ALPHA`]); a point off the
//! triangle rejects outright.
//!
//! # Densities
//! The estimate `mean(1/p_ω)` over `2¹⁸` samples must equal the solid angle the triangle
//! subtends (`E[1/p] = ∫ dω`; Van Oosterom and Strackee's closed form), within 5 standard
//! errors (two-sided `p ≈ 5.7·10⁻⁷`), from three points; each mesh sample's density must be
//! the mesh's `1/A` converted.
//!
//! # Power
//! The same tests reject `b₀` uniform on a triangle, a mesh's triangles chosen uniformly,
//! and the area-to-solid-angle factor `d/|cos|` instead of `d²/|cos|`. With these seeds
//! every correct sampler gives `p > 10⁻³` and every twin `p < 10⁻²⁰` or `|z| > 200` (run
//! with `--nocapture` to see them).

use crate::common;

use common::draws::*;
use common::*;
use raytrace::{Float, Hittable, Triangle, Vec3};

/// The barycentrics of `p` in the triangle `v` (least squares, in `f64`).
fn barycentrics(v: [[f64; 3]; 3], p: [f64; 3]) -> [f64; 3] {
    let (e1, e2, q) = (sub(v[1], v[0]), sub(v[2], v[0]), sub(p, v[0]));
    let (a, b, c) = (dot(e1, e1), dot(e1, e2), dot(e2, e2));
    let (d, e) = (dot(q, e1), dot(q, e2));
    let det = a * c - b * b;
    let s = (c * d - b * e) / det;
    let t = (a * e - b * d) / det;
    [1.0 - s - t, s, t]
}

/// `(u, v)` of a point with barycentrics `b`, or `None` if it is off the triangle.
fn triangle_uv(b: [f64; 3], tol: f64) -> Option<(f64, f64)> {
    if b.iter().any(|&x| x < -tol) {
        return None;
    }
    let rest = (1.0 - b[0]).max(f64::MIN_POSITIVE);
    Some((1.0 - rest * rest, (b[1] / rest).clamp(0.0, 1.0)))
}

fn triangles_are_sampled_uniformly<F: Float>() {
    let v = TRIANGLE.map(|p| Vec3::<F>::from_f64(p[0], p[1], p[2]));
    let triangle = Triangle::new(v[0], v[1], v[2]).unwrap();
    let at = Vec3::<F>::zero();
    let tol = 64.0 * eps::<F>();
    let verdict = chi2_uv(31, |u| {
        let s = triangle.sample(at, u)?;
        triangle_uv(barycentrics(TRIANGLE, s.point.to_f64()), tol)
    });
    println!("triangle {}: {verdict:?}", F::NAME);
    assert!(!verdict.rejected(), "{}: {verdict:?}", F::NAME);
}

#[test]
fn triangles_are_sampled_uniformly_f32() {
    triangles_are_sampled_uniformly::<f32>();
}

#[test]
fn triangles_are_sampled_uniformly_f64() {
    triangles_are_sampled_uniformly::<f64>();
}

/// The wrong twin: `b₀` uniform, `b₁` uniform on what is left.
#[test]
fn the_triangle_test_rejects_a_wrong_sampler() {
    let verdict = chi2_uv(32, |u| {
        triangle_uv([u[0], (1.0 - u[0]) * u[1], (1.0 - u[0]) * (1.0 - u[1])], 0.0)
    });
    println!("b₀ uniform: {verdict:?}");
    assert!(verdict.rejected());
}

/// The solid angle of the triangle `v` seen from `p` (Van Oosterom and Strackee 1983):
/// `tan(Ω/2) = |a·(b×c)| / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|)`.
fn solid_angle(v: [[f64; 3]; 3], p: [f64; 3]) -> f64 {
    let [a, b, c] = v.map(|x| sub(x, p));
    let (la, lb, lc) = (len(a), len(b), len(c));
    let num = dot(a, cross(b, c)).abs();
    let den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    2.0 * num.atan2(den)
}

fn triangle_density_is_per_solid_angle<F: Float>() {
    let v = TRIANGLE.map(|p| Vec3::<F>::from_f64(p[0], p[1], p[2]));
    let triangle = Triangle::new(v[0], v[1], v[2]).unwrap();
    for (k, from) in [[0.0, 0.0, 0.0], [0.5, 0.8, -2.5], [5.0, -3.0, 1.0]]
        .into_iter()
        .enumerate()
    {
        let at = Vec3::<F>::from_f64(from[0], from[1], from[2]);
        let want = solid_angle(TRIANGLE, from);
        let (mean, z) = mean_inverse_density(40 + k as u64, want, |u| {
            triangle.sample(at, u).unwrap().pdf.to_f64()
        });
        println!(
            "triangle {} from {from:?}: mean 1/p = {mean}, Ω = {want}, z = {z}",
            F::NAME
        );
        assert!(z.abs() < Z_MAX, "{} from {from:?}: z = {z}", F::NAME);
    }
}

#[test]
fn triangle_density_is_per_solid_angle_f32() {
    triangle_density_is_per_solid_angle::<f32>();
}

#[test]
fn triangle_density_is_per_solid_angle_f64() {
    triangle_density_is_per_solid_angle::<f64>();
}

/// The wrong conversion, `p_A·d/|cos|`, is seen by the same test.
#[test]
fn the_solid_angle_test_rejects_a_wrong_conversion() {
    let v = TRIANGLE.map(|p| Vec3::<f64>::from_f64(p[0], p[1], p[2]));
    let triangle = Triangle::new(v[0], v[1], v[2]).unwrap();
    let from = [0.5, 0.8, -2.5];
    let at = Vec3::from_f64(from[0], from[1], from[2]);
    let (_, z) = mean_inverse_density(41, solid_angle(TRIANGLE, from), |u| {
        let s = triangle.sample(at, u).unwrap();
        s.pdf / (s.point - at).length()
    });
    println!("d/|cos|: z = {z}");
    assert!(z.abs() > Z_MAX);
}

fn mesh_triangles_are_chosen_by_area<F: Float>() {
    let (mesh, areas) = four_triangles::<F>();
    let total: f64 = areas.iter().sum();
    let shares = areas.map(|a| a / total);
    assert!((mesh.area().unwrap().to_f64() - total).abs() < 1e-5 * total);
    let at = Vec3::<F>::from_f64(1.0, 2.0, 3.0);
    let p = choice_p(51, &shares, |u| {
        let s = mesh.sample(at, u).unwrap();
        // The density is the whole mesh's, 1/A, converted.
        let v = s.point - at;
        let want =
            v.length_squared().to_f64() / (s.normal.dot(v).abs().to_f64() / v.length().to_f64()) / total;
        assert!(
            (s.pdf.to_f64() / want - 1.0).abs() < 1e3 * eps::<F>(),
            "{}",
            F::NAME
        );
        s.part as usize
    });
    println!("mesh parts {}: p = {p}", F::NAME);
    assert!(p >= CHI2_ALPHA, "{}: p = {p}", F::NAME);
}

#[test]
fn mesh_triangles_are_chosen_by_area_f32() {
    mesh_triangles_are_chosen_by_area::<f32>();
}

#[test]
fn mesh_triangles_are_chosen_by_area_f64() {
    mesh_triangles_are_chosen_by_area::<f64>();
}

#[test]
fn the_choice_test_rejects_a_uniform_choice_of_triangles() {
    let shares = [1.0, 2.0, 3.0, 10.0].map(|a| a / 16.0);
    let p = choice_p(52, &shares, |u| ((u[0] * 4.0) as usize).min(3));
    println!("uniform triangles: p = {p}");
    assert!(p < CHI2_ALPHA);
}
