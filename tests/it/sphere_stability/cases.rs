//! A sphere and a ray: the exact geometry of the case, the check of a stable hit, and its construction.

use crate::common::*;
use proptest::prelude::*;
use raytrace::{Float, Hit, Ray, Sphere, Vec3, lit};
use twofloat::TwoFloat;

/// A sphere and a ray in `F`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Case<F> {
    pub(crate) sphere: Sphere<F>,
    pub(crate) ray: Ray<F>,
}

/// The exact geometry of a case, computed in double-double from its rounded `F` values
/// (with the ray's direction normalized exactly).
pub(crate) struct Exact {
    /// `|f|`, `f = O − C`.
    pub(crate) dist: f64,
    /// The perpendicular distance from `C` to the ray's line.
    pub(crate) perp: f64,
    /// Both roots, nearer first, when the line meets the sphere.
    pub(crate) roots: Option<(f64, f64)>,
    /// `|O| + |C| + r`: the scale of the rounding errors.
    pub(crate) scale: f64,
}

impl<F: Float> Case<F> {
    pub(crate) fn exact(&self) -> Exact {
        let o = dd(self.ray.origin);
        let d = dd(self.ray.direction);
        let d = d / d.length();
        let f = o - dd(self.sphere.center());
        let r = dd1(self.sphere.radius());
        let b = f.dot(d);
        let l = f - d * b;
        let disc = r * r - l.length_squared();
        let roots = (disc >= TwoFloat::from(0.0)).then(|| {
            let s = disc.sqrt();
            ((-b - s).to_f64(), (-b + s).to_f64())
        });
        Exact {
            dist: f.length().to_f64(),
            perp: l.length().to_f64(),
            roots,
            scale: length_dd(self.ray.origin) + length_dd(self.sphere.center()) + r.to_f64(),
        }
    }

    /// `| |P − C| − r |`: how far `p` is from the sphere's surface.
    pub(crate) fn off_surface(&self, p: Vec3<F>) -> f64 {
        ((dd(p) - dd(self.sphere.center())).length() - dd1(self.sphere.radius()))
            .to_f64()
            .abs()
    }

    /// How far `p` is from the exact point of the ray at `t`.
    fn off_ray(&self, p: Vec3<F>, t: f64) -> f64 {
        let d = dd(self.ray.direction);
        let exact = dd(self.ray.origin) + d / d.length() * TwoFloat::from(t);
        (dd(p) - exact).length().to_f64()
    }

    /// Checks a hit of the stable method at the exact root `t_exact`: on the surface within
    /// its error bound, at the right place, finite, with a unit normal facing the ray.
    pub(crate) fn check_hit(&self, h: &Hit<F>, t_exact: f64, scale: f64) -> Result<(), TestCaseError> {
        prop_assert!(
            h.t.is_finite() && h.point.is_finite() && h.error.is_finite(),
            "{h:?}"
        );
        let off = self.off_surface(h.point);
        let bound = length_dd(h.error);
        prop_assert!(
            off <= bound,
            "{:?}: {off:e} off the surface, bound {bound:e}",
            self
        );
        let pos = self.off_ray(h.point, t_exact);
        prop_assert!(
            pos <= 8.0 * eps::<F>() * scale,
            "hit {:e} from the exact point = {:.2}ε·scale",
            pos,
            pos / eps::<F>() / scale
        );
        prop_assert!(
            (length_dd(h.normal) - 1.0).abs() <= 4.0 * eps::<F>(),
            "normal {:?}",
            h.normal
        );
        prop_assert!(h.normal.dot(self.ray.direction) <= F::zero(), "normal faces away");
        Ok(())
    }
}

/// Builds a case from `f64` geometry: centre at distance `dist·r` from the origin `O` along
/// `axis`; the ray's line passes through `C + side·r·(cos ψ·t + sin ψ·b)`, `(t, b)` a frame
/// perpendicular to `axis`, and its direction is along `axis` tilted towards that point
/// (`tangent = false`: the ray aims at it from `O`) or exactly along `axis` (`tangent =
/// true`: `O` is moved sideways so the line's distance from `C` is exactly `side·r`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn build<F: Float>(
    r: f64,
    dist: f64,
    axis: [f64; 3],
    origin: [f64; 3],
    side: f64,
    psi: f64,
    tangent: bool,
    backwards: bool,
) -> Case<F> {
    let (t, b) = frame(axis);
    let o = origin.map(|x| x * r);
    let c: [f64; 3] = std::array::from_fn(|i| o[i] + dist * r * axis[i]);
    let q: [f64; 3] = std::array::from_fn(|i| c[i] + side * r * (psi.cos() * t[i] + psi.sin() * b[i]));
    let (o, dir) = if tangent {
        // O = Q − dist·r·axis: the line {Q + s·axis} is at distance side·r from C.
        (std::array::from_fn(|i| q[i] - dist * r * axis[i]), axis)
    } else {
        (o, std::array::from_fn(|i| q[i] - o[i]))
    };
    let dir = if backwards { dir.map(|x| -x) } else { dir };
    Case {
        sphere: Sphere::new(Vec3::from_f64(c[0], c[1], c[2]), lit(r)).unwrap(),
        ray: Ray::new(Vec3::from_f64(o[0], o[1], o[2]), unit_from(dir)),
    }
}
