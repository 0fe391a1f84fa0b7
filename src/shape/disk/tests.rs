//! The disk's tests: hits inside and misses outside, both faces, Mitsuba's surface
//! coordinates, an ellipse's shape and area, bounds, and refused input.

use super::*;
use crate::shape::Alone;

fn v<F: Float>(x: f64, y: f64, z: f64) -> Vec3<F> {
    Vec3::from_f64(x, y, z)
}

fn down<F: Float>(x: f64, y: f64) -> Ray<F> {
    Ray::new(v(x, y, 0.0), v(0.0, 0.0, -1.0))
}

/// The disk of radius 2 about `(1, 0, −5)` facing `+z`.
fn round<F: Float>() -> Disk<F> {
    Disk::new(v(1.0, 0.0, -5.0), v(0.0, 0.0, 3.0), lit(2.0)).unwrap()
}

fn hits_inside_and_misses_outside<F: Float>() {
    let d = round::<F>();
    assert_eq!(d.axes(), [v(2.0, 0.0, 0.0), v(0.0, 2.0, 0.0)], "{}", F::NAME);
    let h = d.hit(&down(2.5, 0.9), F::infinity()).unwrap();
    assert_eq!(h.t, lit(5.0), "{}", F::NAME);
    assert!(h.front_face && h.normal == v(0.0, 0.0, 1.0), "{}", F::NAME);
    assert!(h.error.min_element() > F::zero(), "{}", F::NAME);
    // |(1.5, 0.9)| = 1.749 < 2; |(1.7, 1.1)| = 2.02 > 2; behind; t_max exclusive.
    assert!(d.hit(&down(2.7, 1.1), F::infinity()).is_none(), "{}", F::NAME);
    assert!(d.hit(&down(-1.0, 0.0), F::infinity()).is_some(), "{}", F::NAME);
    assert!(d.hit(&down(-1.1, 0.0), F::infinity()).is_none(), "{}", F::NAME);
    assert!(d.hit(&down(1.0, 0.0), lit(5.0)).is_none(), "{}", F::NAME);
    assert!(d.occluded(&down(1.0, 0.0), lit::<F>(5.0).next_up()));
    let away = Ray::new(v(1.0, 0.0, 0.0), v(0.0, 0.0, 1.0));
    assert!(d.hit(&away, F::infinity()).is_none());
    // From below: the other face.
    let up = Ray::new(v(1.0, 0.0, -9.0), v(0.0, 0.0, 1.0));
    let h = d.hit(&up, F::infinity()).unwrap();
    assert!(!h.front_face && h.normal == v(0.0, 0.0, -1.0), "{}", F::NAME);
}

/// Mitsuba's `(ρ, φ/2π)` and `∂p/∂u = cos φ·U + sin φ·V`.
fn coordinates_are_mitsubas<F: Float>() {
    let d = round::<F>();
    let tol = lit::<F>(16.0) * F::eps();
    // (a, b) = (0.5, 0.5): ρ = √½, φ = π/4.
    for ((x, y), (rho, v_want)) in [
        ((2.0, 1.0), (0.5f64.sqrt(), 0.125)),
        ((1.0, -1.0), (0.5, 0.75)),
        ((0.0, 0.0), (0.5, 0.5)),
    ] {
        let h = d.hit(&down(x, y), F::infinity()).unwrap();
        assert!((h.uv[0] - lit(rho)).abs() <= tol, "{}: {:?}", F::NAME, h.uv);
        assert!((h.uv[1] - lit(v_want)).abs() <= tol, "{}: {:?}", F::NAME, h.uv);
        let radial = (h.point - d.center()).normalize() * lit::<F>(2.0);
        assert!(
            (h.dpdu - radial).abs().max_element() <= tol * lit(4.0),
            "{}",
            F::NAME
        );
    }
    let centre = d.hit(&down(1.0, 0.0), F::infinity()).unwrap();
    assert_eq!((centre.uv, centre.dpdu), ([F::zero(); 2], v(2.0, 0.0, 0.0)));
}

/// An ellipse (a non-uniform scale and a shear): its points, area and bounds.
fn an_affine_map_makes_an_ellipse<F: Float>() {
    let (u, w) = (v::<F>(3.0, 0.0, 0.0), v(1.0, 1.0, 0.0));
    let d = Disk::with_axes(v(0.0, 0.0, -2.0), u, w).unwrap();
    // C + 0.9U lies in it, C + 1.1U not; along V likewise.
    assert!(d.hit(&down(2.7, 0.0), F::infinity()).is_some(), "{}", F::NAME);
    assert!(d.hit(&down(3.3, 0.0), F::infinity()).is_none(), "{}", F::NAME);
    assert!(d.hit(&down(0.9, 0.9), F::infinity()).is_some(), "{}", F::NAME);
    assert!(d.hit(&down(1.1, 1.1), F::infinity()).is_none(), "{}", F::NAME);
    // (0, 1.0): a = −1/3, b = 1, outside; (0, 0.9): a = −0.3, b = 0.9, inside.
    assert!(d.hit(&down(0.0, 1.0), F::infinity()).is_none(), "{}", F::NAME);
    assert!(d.hit(&down(0.0, 0.9), F::infinity()).is_some(), "{}", F::NAME);
    let area = d.area().unwrap().to_f64();
    assert!(
        (area - 3.0 * std::f64::consts::PI).abs() < 1e-5,
        "{}: {area}",
        F::NAME
    );
    // Extents √(3² + 1²) along x, 1 along y, 0 along z.
    let b = d.bounds().unwrap();
    let [lo, hi] = b.corners().map(|c| c.to_f64());
    assert!((hi[0] - 10f64.sqrt()).abs() < 1e-5 && (lo[1] + 1.0).abs() < 1e-5);
    assert!((hi[2] + 2.0).abs() < 1e-5 && hi[2] >= -2.0 && lo[2] <= -2.0);
}

fn flipping_turns_the_front_face<F: Float>() {
    let d = round::<F>().flipped();
    assert!(d.is_flipped());
    assert_eq!(d.normal(), v(0.0, 0.0, -1.0), "{}", F::NAME);
    let h = d.hit(&down(1.0, 0.0), F::infinity()).unwrap();
    assert!(!h.front_face, "{}", F::NAME);
    let back = d.cast::<f64>().unwrap();
    assert!(back.is_flipped() && back.normal() == v(0.0, 0.0, -1.0));
    assert_eq!(d.flipped().normal(), v(0.0, 0.0, 1.0));
}

fn samples_lie_on_the_disk<F: Float>() {
    let d = round::<F>();
    let from = v::<F>(0.0, 3.0, 1.0);
    let area = lit::<F>(4.0 * std::f64::consts::PI);
    for u in [[0.1, 0.2, 0.0], [0.99, 0.5, 0.3], [0.5, 0.5, 0.9]] {
        let s = d.sample(from, u).unwrap();
        let (a, b) = d.local(s.point);
        assert!(a * a + b * b <= lit(1.0 + 1e-5), "{}", F::NAME);
        assert!((s.point.z - lit(-5.0)).abs() <= lit::<F>(8.0) * F::eps());
        // The density the ray to it reports is the one drawn.
        let ray = Ray::towards(from, s.point).unwrap();
        let h = d.hit(&ray, F::infinity()).unwrap();
        let pdf = d.pdf(&ray, &h);
        assert!(((pdf - s.pdf) / s.pdf).abs() <= lit(1e-4), "{}", F::NAME);
        let want = area_to_solid_angle(F::one() / area, from, s.point, s.normal);
        assert!(((want - s.pdf) / s.pdf).abs() <= lit(1e-4), "{}", F::NAME);
    }
}

fn refuses_bad_input<F: Float>() {
    let o = Vec3::<F>::zero();
    let z = v::<F>(0.0, 0.0, 1.0);
    let field = |r: Result<Disk<F>>| match r {
        Err(Error::InvalidValue { field, .. }) => Some(field),
        _ => None,
    };
    assert_eq!(field(Disk::new(o, z, F::zero())), Some(Field::DiskRadius));
    assert_eq!(field(Disk::new(o, z, F::nan())), Some(Field::DiskRadius));
    assert_eq!(field(Disk::new(o, o, F::one())), Some(Field::DiskNormal));
    assert_eq!(
        field(Disk::new(v(F::nan().to_f64(), 0.0, 0.0), z, F::one())),
        Some(Field::DiskCenter)
    );
    let x = v::<F>(1.0, 0.0, 0.0);
    assert_eq!(
        field(Disk::with_axes(o, x, x * lit::<F>(2.0))),
        Some(Field::DiskAxes)
    );
    assert_eq!(field(Disk::with_axes(o, x, o)), Some(Field::DiskAxes));
    assert_eq!(
        field(Disk::with_axes(o, x, v(0.0, F::infinity().to_f64(), 0.0))),
        Some(Field::DiskAxes)
    );
    let msg = Disk::with_axes(o, x, x).unwrap_err().to_string();
    assert!(msg.contains("disk axes") && msg.contains("parallel"), "{msg}");
}

mod scalars {
    use crate::float::for_each_scalar;

    for_each_scalar!(
        hits_inside_and_misses_outside,
        coordinates_are_mitsubas,
        an_affine_map_makes_an_ellipse,
        flipping_turns_the_front_face,
        samples_lie_on_the_disk,
        refuses_bad_input
    );
}
