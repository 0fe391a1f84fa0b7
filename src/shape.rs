//! The spec's abstract object: the [`Hittable`] trait, the [`Hit`] it reports, and
//! [`ShapeKind`], the enum fast path over the concrete shapes.

mod plane;
mod sphere;
mod sphere4;
mod triangle;

pub use plane::Plane;
pub use sphere::{Sphere, TEXTBOOK_T_MIN, textbook_sphere_hit};
pub(crate) use sphere4::LANES;
// Public, hidden: only for the packet bench in benches/primitives.rs.
#[doc(hidden)]
pub use sphere4::Sphere4;
pub use triangle::Triangle;

use crate::aabb::Aabb;
use crate::float::Float;
use crate::ray::Ray;
use crate::vec3::Vec3;
use std::sync::Arc;

/// Where a ray meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit<F> {
    /// The ray parameter of the hit, in `(0, t_max)`.
    pub t: F,
    /// The hit point.
    pub point: Vec3<F>,
    /// A bound on the absolute rounding error of each component of `point`
    /// (pbrt-v4's error-bounded intersection), used to offset secondary rays.
    pub error: Vec3<F>,
    /// The unit surface normal, on the side the ray came from (`normal·D ≤ 0`).
    pub normal: Vec3<F>,
    /// Whether the ray hit the side the shape's outward normal points to.
    pub front_face: bool,
}

impl<F: Float> Hit<F> {
    /// A hit whose normal is turned to face the incoming `direction`.
    #[inline]
    pub fn new(t: F, point: Vec3<F>, error: Vec3<F>, outward: Vec3<F>, direction: Vec3<F>) -> Self {
        let front_face = direction.dot(outward) <= F::zero();
        let normal = if front_face { outward } else { -outward };
        Self {
            t,
            point,
            error,
            normal,
            front_face,
        }
    }

    /// A ray leaving the hit point along the unit `direction`, its origin moved off the
    /// surface just far enough that it cannot hit the same surface again
    /// ([`offset_ray_origin`]).
    #[must_use]
    #[inline]
    pub fn spawn(&self, direction: Vec3<F>) -> Ray<F> {
        Ray::new(
            offset_ray_origin(self.point, self.error, self.normal, direction),
            direction,
        )
    }
}

/// pbrt-v4's `OffsetRayOrigin`: moves `p` along the normal `n` past the box of its
/// rounding error `err`, to the side `w` points to, then one more representable value
/// away, so the new origin lies strictly on that side of the true surface:
///
/// `d = |n|·err`, `p' = p ± d·n`, each component of `p'` rounded away from `p`.
///
/// This replaces the textbook's fixed `t_min = 0.001`, which is scale-blind: too large
/// for small objects (rays skip through a tiny glass sphere) and too small far from the
/// origin (rays re-hit their own surface, "shadow acne").
#[must_use]
#[inline]
pub fn offset_ray_origin<F: Float>(p: Vec3<F>, err: Vec3<F>, n: Vec3<F>, w: Vec3<F>) -> Vec3<F> {
    let d = n.abs().dot(err);
    let offset = if w.dot(n) < F::zero() { -(n * d) } else { n * d };
    let po = p + offset;
    let [x, y, z] = F::step_toward_each([po.x, po.y, po.z], [offset.x, offset.y, offset.z]);
    Vec3::new(x, y, z)
}

/// The rounding-error bound of a hit on a flat surface: the per-component box
/// `γ(10)·(|O| + |t·D| + |A|)` around the point `O + t·D`, for a surface through the
/// stored point `A` (`anchor`) with unit normal `n`, when `t` was computed as
/// `((A − O)·n) / (D·n)` (as [`Plane::intersect`] does). Report it as [`Hit::error`] of a
/// disk, a quad or a plane of your own; see [Reporting the rounding error](Hittable#reporting-the-rounding-error).
///
/// # Precision
/// The bound guarantees that the exact plane `(X − A)·n = 0` passes through the box
/// `point ± error`, which is what [`offset_ray_origin`] needs (the point's position
/// *along* the plane is irrelevant to self-intersection and, for grazing rays, much less
/// accurate). With `N = (A − O)·n`, `Δ = D·n`, their computed values `Ñ = N + e_N`,
/// `Δ̃ = Δ + e_Δ` and `t̃ = (Ñ/Δ̃)(1 + δ)`, the exact point `O + t̃D` lies at
/// (unnormalized) distance `t̃Δ − N = e_N + δÑ − t̃e_Δ` from the plane, so
/// `|t̃Δ − N| ≤ γ(5)·Σ(|Aᵢ| + |Oᵢ|)|nᵢ| + γ(3)·Σ|t̃Dᵢ||nᵢ|`. Evaluating `Oᵢ + t̃Dᵢ` costs
/// `γ(2)·(|Oᵢ| + |t̃Dᵢ|)` per component. In total the computed point is within
/// `γ(7)·Σ|nᵢ|(|Oᵢ| + |t̃Dᵢ| + |Aᵢ|)` of the plane, so the per-component box
/// `γ(7)·(|O| + |t̃D| + |A|)` reaches the plane along `n`. We report
/// `γ(10)·(|O| + |t̃D| + |A|)`: three more roundings cover the evaluation of the bound
/// itself.
#[must_use]
#[inline]
pub fn flat_hit_error<F: Float>(ray: &Ray<F>, t: F, anchor: Vec3<F>) -> Vec3<F> {
    (ray.origin.abs() + (ray.direction * t).abs() + anchor.abs()) * F::gamma(10)
}

/// A surface a ray can hit: the specification's abstract object.
///
/// Usable as a trait object (`Box<dyn Hittable<F>>`, the spec's vector of pointers)
/// and implemented by the enum [`ShapeKind`] for compile-time dispatch.
///
/// # Reporting the rounding error
/// A secondary ray starts at [`offset_ray_origin`]`(point, error, normal, direction)`,
/// just past the box `point ± error` that [`Hit::error`] claims holds the true surface.
/// A shape of your own must make that claim true:
/// - **Flat surfaces** (a disk, a quad, a plane): compute `t = ((A − O)·n)/(D·n)` for a
///   stored point `A` of the surface and its unit normal `n` — [`Plane::intersect`] does,
///   with a conservative `t > 0` test a spawned ray needs, so a flat shape can keep a
///   [`Plane`] and call it — then report [`flat_hit_error`]`(ray, t, A)`.
/// - **Curved surfaces**: move the point back onto the surface and bound what is left, as
///   `Sphere`'s hit record does (`p ← C + (p − C)·r/|p − C|`, then `γ(6)|p − C| + γ(2)|p|`
///   per component, pbrt-v4 §6.8.5).
///
/// An error of zero does not move the origin at all: the rounded hit point lies on
/// either side of the true surface about as often, and from the wrong side the new ray
/// hits the surface it is leaving, at a tiny `t`. The image shows it as dark speckles
/// ("shadow acne"), worse the farther the shape is from the world origin for its size,
/// where the rounding is coarser (`tests/custom_shape.rs` counts them).
pub trait Hittable<F: Float> {
    /// The nearest hit with `t` in the open interval `(0, t_max)`, if any.
    ///
    /// The interval is open at 0 and no larger `t_min` is needed: secondary rays start
    /// at [`offset_ray_origin`], past the surface's rounding error.
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>>;

    /// Whether anything blocks the ray before `t_max` (pbrt's `IntersectP`): an
    /// any-hit query for shadow rays, which may stop at the first occluder.
    #[inline]
    fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.hit(ray, t_max).is_some()
    }

    /// A box holding the whole shape, or `None` if it is unbounded (a plane) or the
    /// implementor does not say; only bounded shapes go into a scene's [`Bvh`](crate::bvh::Bvh).
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        None
    }

    /// The sphere this shape is, if it is exactly a [`Sphere`]: a scene packs those four
    /// to a packet and tests them at once (SIMD lanes), and builds the full [`Hit`] only
    /// for the nearest.
    ///
    /// Only a concrete type can answer (`where Self: Sized` keeps the method out of the
    /// vtable): a trait object hides what it is, so a scene of `Box<dyn Hittable>` tests
    /// each shape through its own [`hit`](Hittable::hit). This layout is what the enum
    /// fast path buys beyond the `match` itself.
    ///
    /// An implementor that answers `Some(s)` promises that its `hit` is `s.hit`: the scene
    /// then tests `s` instead.
    #[inline]
    fn as_sphere(&self) -> Option<&Sphere<F>>
    where
        Self: Sized,
    {
        None
    }
}

macro_rules! forward_hittable {
    ($($ptr:ty),*) => {$(
        impl<F: Float, T: Hittable<F> + ?Sized> Hittable<F> for $ptr {
            #[inline]
            fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
                (**self).hit(ray, t_max)
            }
            #[inline]
            fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
                (**self).occluded(ray, t_max)
            }
            #[inline]
            fn bounds(&self) -> Option<Aabb<F>> {
                (**self).bounds()
            }
        }
    )*};
}
forward_hittable!(&T, Box<T>, Arc<T>);

/// `Box::new(my_shape)` is a shape of a [`DynScene`](crate::DynScene) as it is, with no
/// `as Box<dyn Hittable<F> + Send + Sync>`.
impl<F: Float, T: Hittable<F> + Send + Sync + 'static> From<Box<T>> for Box<dyn Hittable<F> + Send + Sync> {
    fn from(shape: Box<T>) -> Self {
        shape
    }
}

/// The enum fast path: every concrete shape, dispatched by `match` (no vtable, no box).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShapeKind<F> {
    /// A [`Sphere`].
    Sphere(Sphere<F>),
    /// An infinite [`Plane`].
    Plane(Plane<F>),
    /// A [`Triangle`].
    Triangle(Triangle<F>),
}

impl<F: Float> Hittable<F> for ShapeKind<F> {
    #[inline]
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
        match self {
            Self::Sphere(s) => s.hit(ray, t_max),
            Self::Plane(p) => p.hit(ray, t_max),
            Self::Triangle(t) => t.hit(ray, t_max),
        }
    }
    #[inline]
    fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        match self {
            Self::Sphere(s) => s.occluded(ray, t_max),
            Self::Plane(p) => p.occluded(ray, t_max),
            Self::Triangle(t) => t.occluded(ray, t_max),
        }
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        match self {
            Self::Sphere(s) => s.bounds(),
            Self::Plane(p) => p.bounds(),
            Self::Triangle(t) => t.bounds(),
        }
    }
    #[inline]
    fn as_sphere(&self) -> Option<&Sphere<F>> {
        match self {
            Self::Sphere(s) => Some(s),
            _ => None,
        }
    }
}

impl<F> From<Sphere<F>> for ShapeKind<F> {
    fn from(s: Sphere<F>) -> Self {
        Self::Sphere(s)
    }
}

impl<F> From<Plane<F>> for ShapeKind<F> {
    fn from(p: Plane<F>) -> Self {
        Self::Plane(p)
    }
}

impl<F> From<Triangle<F>> for ShapeKind<F> {
    fn from(t: Triangle<F>) -> Self {
        Self::Triangle(t)
    }
}

impl<F: Float> ShapeKind<F> {
    /// This shape in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> crate::error::Result<ShapeKind<G>> {
        Ok(match self {
            Self::Sphere(s) => s.cast()?.into(),
            Self::Plane(p) => p.cast()?.into(),
            Self::Triangle(t) => t.cast()?.into(),
        })
    }
}
