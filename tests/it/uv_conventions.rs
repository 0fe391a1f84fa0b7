//! Surface coordinates at known points of each shape, in Mitsuba 3's conventions: a
//! sphere's `(φ/2π, θ/π)`, a triangle's `(b₁, b₂)`, a mesh's interpolated texture
//! coordinates; the plane's own; and a scene fills them in only for a material that reads
//! them.

use raytrace::prelude::*;
use raytrace::sampling::orthonormal_basis;
use raytrace::shape::{Hit, hit};
use raytrace::texture::{Checkerboard, Texture};

/// The hit of the ray from `from` toward `to`.
fn hit_toward<S: Hittable<f64>>(shape: &S, from: Vec3<f64>, to: Vec3<f64>) -> Hit<f64> {
    let ray = Ray::new(from, (to - from).normalize());
    hit(shape, &ray, f64::INFINITY).expect("the ray hits")
}

fn close(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12
}

#[test]
fn a_sphere_has_mitsubas_spherical_coordinates() {
    let (c, r) = (Vec3::new(1.0, -2.0, 3.0), 2.0);
    let sphere = Sphere::new(c, r).unwrap();
    // The point in direction d from the centre, seen from outside along d.
    let at = |d: Vec3<f64>| hit_toward(&sphere, c + d * 10.0, c + d * r);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    for (d, uv) in [
        // u = φ/2π from +x counter-clockwise about +z; v = θ/π from +z.
        (Vec3::new(1.0, 0.0, 0.0), [0.0, 0.5]),
        (Vec3::new(0.0, 1.0, 0.0), [0.25, 0.5]),
        (Vec3::new(-1.0, 0.0, 0.0), [0.5, 0.5]),
        (Vec3::new(0.0, -1.0, 0.0), [0.75, 0.5]),
        (Vec3::new(s, s, 0.0), [0.125, 0.5]),
        (Vec3::new(s, 0.0, s), [0.0, 0.25]),
        (Vec3::new(0.0, -s, -s), [0.75, 0.75]),
    ] {
        let h = at(d);
        assert!(close(h.uv, uv), "{d:?}: {:?}, want {uv:?}", h.uv);
        // ∂p/∂u = 2πr·(−y, x, 0) of the unit direction.
        let want = Vec3::new(-d.y, d.x, 0.0) * (std::f64::consts::TAU * r);
        assert!((h.dpdu - want).length() < 1e-9, "{d:?}: {:?}", h.dpdu);
    }
    // Seen from inside, the same point has the same coordinates.
    let d = Vec3::new(0.0, 1.0, 0.0);
    let inside = hit_toward(&sphere, c, c + d * r);
    assert!(
        !inside.front_face && close(inside.uv, [0.25, 0.5]),
        "{:?}",
        inside.uv
    );
}

#[test]
fn a_plane_measures_lengths_from_its_point() {
    let (p0, n) = (Vec3::new(0.5, -1.0, 2.0), Vec3::new(0.0, 1.0, 0.0));
    let plane = Plane::new(p0, n).unwrap();
    let (s, t) = orthonormal_basis(n);
    let x = p0 + s * 2.0 + t * -3.5;
    let h = hit_toward(&plane, x + n * 4.0, x);
    assert!(close(h.uv, [2.0, -3.5]), "{:?}", h.uv);
    assert_eq!(h.dpdu, s);
}

#[test]
fn a_triangle_has_the_barycentric_weights_of_b_and_c() {
    let (a, b, c) = (
        Vec3::new(0.0, 0.0, -2.0),
        Vec3::new(2.0, 0.0, -2.0),
        Vec3::new(0.0, 1.0, -2.0),
    );
    let triangle = Triangle::new(a, b, c).unwrap();
    let o = Vec3::new(0.3, 0.2, 0.0);
    let h = |p: Vec3<f64>| hit_toward(&triangle, o, p);
    assert!(close(h((a + b + c) / 3.0).uv, [1.0 / 3.0, 1.0 / 3.0]));
    assert!(close(h(a * 0.5 + b * 0.5).uv, [0.5, 0.0]));
    assert!(close(h(a * 0.25 + c * 0.75).uv, [0.0, 0.75]));
    assert!(close(h(a * 0.5 + b * 0.25 + c * 0.25).uv, [0.25, 0.25]));
    assert_eq!(h(a * 0.5 + b * 0.25 + c * 0.25).dpdu, b - a);
}

#[test]
fn a_mesh_interpolates_its_texture_coordinates() {
    let v = |x, y| Vec3::new(x, y, -2.0);
    let vertices = vec![v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
    let triangles = vec![[0, 1, 2], [0, 2, 3]];
    let o = Vec3::new(0.1, 0.1, 0.0);
    let bare = Mesh::new(vertices.clone(), triangles.clone()).unwrap();
    // Without texture coordinates, a triangle's own: at (0.75, 0.25) of triangle 0,
    // b = (0.25, 0.5, 0.25).
    let h = hit_toward(&bare, o, v(0.75, 0.25));
    assert!(close(h.uv, [0.5, 0.25]), "{:?}", h.uv);
    // With them: u = 2x, v = 3 − 3y over the square, so ∂p/∂u = (½, 0, 0).
    let uvs = vec![[0.0, 3.0], [2.0, 3.0], [2.0, 0.0], [0.0, 0.0]];
    let mesh = bare.with_uvs(uvs).unwrap();
    for (x, y) in [(0.75, 0.25), (0.25, 0.75), (0.5, 0.5), (0.9, 0.05)] {
        let h = hit_toward(&mesh, o, v(x, y));
        assert!(close(h.uv, [2.0 * x, 3.0 - 3.0 * y]), "({x}, {y}): {:?}", h.uv);
        assert!(
            (h.dpdu - Vec3::new(0.5, 0.0, 0.0)).length() < 1e-12,
            "{:?}",
            h.dpdu
        );
    }
}

#[test]
fn a_scene_computes_coordinates_only_for_a_material_that_reads_them() {
    let sphere = || Sphere::new(Vec3::new(0.0, 0.0, -3.0), 1.0).unwrap();
    let ray = Ray::new(Vec3::zero(), Vec3::new(0.1, 0.2, -1.0).normalize());
    let board = Checkerboard::new(Vec3::splat(0.2), Vec3::splat(0.8)).unwrap();
    for (material, reads) in [
        (Lambertian::new(Vec3::splat(0.5)).unwrap(), false),
        (Lambertian::textured(Texture::from(board)).unwrap(), true),
    ] {
        let mut scene = EnumScene::<f64>::new(Background::default());
        scene.add(sphere(), material);
        let (h, _) = scene.hit(&ray, f64::INFINITY).unwrap();
        let alone = hit(&sphere(), &ray, f64::INFINITY).unwrap();
        if reads {
            assert_eq!((h.uv, h.dpdu), (alone.uv, alone.dpdu));
            assert!(h.uv != [0.0; 2]);
        } else {
            assert_eq!((h.uv, h.dpdu), ([0.0; 2], Vec3::zero()));
        }
    }
}
