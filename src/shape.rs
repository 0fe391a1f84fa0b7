//! The spec's abstract object: the [`Hittable`] trait, the [`Hit`] it reports, and
//! [`ShapeKind`], the enum fast path over the concrete shapes.

mod kind;
mod mesh;
mod plane;
mod sample;
mod sphere;
mod sphere4;
mod triangle;
mod triangle4;

pub use kind::ShapeKind;
pub use mesh::Mesh;
pub use plane::Plane;
pub use sample::{SurfaceSample, area_to_solid_angle, hit_solid_angle};
pub use sphere::{Sphere, TEXTBOOK_T_MIN, textbook_sphere_hit, textbook_sphere_record, textbook_sphere_t};
// Public, hidden: only for the packet benches in benches/primitives.rs.
#[doc(hidden)]
pub use sphere4::Sphere4;
pub use triangle::Triangle;
#[doc(hidden)]
pub use triangle4::Triangle4;

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

/// Where a ray meets a shape, before the [`Hit`] record is made: the first phase of
/// [`Hittable`]'s two-phase protocol. A scene keeps the nearest of these and makes the
/// record for that one only ([`Hittable::finish`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Intersection<F> {
    /// The ray parameter, in `(0, t_max)`.
    pub t: F,
    /// Which part of the shape was hit: a mesh's triangle; 0 for a shape of one part.
    pub part: u32,
    /// Where on the part, in the part's own coordinates, for [`Hittable::finish`]: a
    /// triangle's barycentric weights of `A`, `B`, `C`. Spheres and planes leave them 0.
    pub coords: [F; 3],
}

impl<F: Float> Intersection<F> {
    /// An intersection at `t` on part 0, with no coordinates: what a sphere, a plane or a
    /// shape of the user's that needs only `t` for its record reports.
    #[inline]
    pub fn at(t: F) -> Self {
        Self {
            t,
            part: 0,
            coords: [F::zero(); 3],
        }
    }
}

/// A surface a ray can hit: the specification's abstract object.
///
/// Usable as a trait object (`Box<dyn Hittable<F>>`, the spec's vector of pointers)
/// and implemented by the enum [`ShapeKind`] for compile-time dispatch.
///
/// # Two phases
/// A ray may meet many shapes and needs the record of the nearest only, so a hit comes in
/// two steps: [`intersect`](Hittable::intersect) finds the nearest `t` and what the record
/// will need (cheap, run for every candidate), and [`finish`](Hittable::finish) makes the
/// full [`Hit`] from it (run once, for the winner). [`hit`](Hittable::hit) does both.
///
/// # Parts
/// A shape may be made of parts that a scene indexes one by one: a [`Mesh`]'s triangles.
/// Such a shape says how many ([`parts`](Hittable::parts)), bounds each
/// ([`part_bounds`](Hittable::part_bounds)) and intersects each alone
/// ([`intersect_part`](Hittable::intersect_part)); a shape of one part keeps the defaults.
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
/// # Sampling as a light
/// An emissive shape that answers [`area`](Hittable::area), [`sample`](Hittable::sample)
/// and [`pdf`](Hittable::pdf) (spheres, triangles and meshes do) is also sampled directly
/// from the surfaces it lights (next-event estimation); one that keeps the defaults is lit
/// only by rays that happen to hit it. `pdf` must be the density `sample` draws with.
///
/// An error of zero does not move the origin at all: the rounded hit point lies on
/// either side of the true surface about as often, and from the wrong side the new ray
/// hits the surface it is leaving, at a tiny `t`. The image shows it as dark speckles
/// ("shadow acne"), worse the farther the shape is from the world origin for its size,
/// where the rounding is coarser (`tests/it/custom_shape.rs` counts them).
pub trait Hittable<F: Float> {
    /// The nearest intersection with `t` in the open interval `(0, t_max)`, if any.
    ///
    /// The interval is open at 0 and no larger `t_min` is needed: secondary rays start
    /// at [`offset_ray_origin`], past the surface's rounding error.
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>>;

    /// The hit record of `hit`, an intersection this shape reported for `ray`.
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F>;

    /// The nearest hit in `(0, t_max)`, both phases at once.
    #[inline]
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
        let i = self.intersect(ray, t_max)?;
        Some(self.finish(ray, &i))
    }

    /// Whether anything blocks the ray before `t_max` (pbrt's `IntersectP`): an
    /// any-hit query for shadow rays, which may stop at the first occluder.
    #[inline]
    fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.intersect(ray, t_max).is_some()
    }

    /// A box holding the whole shape, or `None` if it is unbounded (a plane) or the
    /// implementor does not say; only bounded parts go into a scene's [`Bvh`](crate::bvh::Bvh).
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        None
    }

    /// How many parts a scene indexes this shape as (1 unless it is made of several).
    #[inline]
    fn parts(&self) -> u32 {
        1
    }

    /// A box holding part `part` (in `0..parts()`), or `None` if it is unbounded.
    #[inline]
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        let _ = part;
        self.bounds()
    }

    /// [`intersect`](Hittable::intersect) for part `part` alone; the answer's
    /// [`part`](Intersection::part) is `part`.
    #[inline]
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let _ = part;
        self.intersect(ray, t_max)
    }

    /// The surface area, if this shape can be sampled as a light; `None` (the default)
    /// otherwise.
    #[inline]
    fn area(&self) -> Option<F> {
        None
    }

    /// A point of the surface drawn for the point `from` from three uniform numbers
    /// `u ∈ [0, 1)³`, with the density of its direction from `from` per unit solid
    /// angle; `None` if this shape cannot be sampled (the default).
    #[inline]
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        let _ = (from, u);
        None
    }

    /// The density per unit solid angle with which [`sample`](Hittable::sample), called
    /// for `ray.origin`, draws the direction of `ray`, a ray that hits this shape at
    /// `hit`; 0 if this shape cannot be sampled (the default).
    #[inline]
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        let _ = (ray, hit);
        F::zero()
    }
}

macro_rules! forward_hittable {
    ($($ptr:ty),*) => {$(
        impl<F: Float, T: Hittable<F> + ?Sized> Hittable<F> for $ptr {
            #[inline]
            fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
                (**self).intersect(ray, t_max)
            }
            #[inline]
            fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
                (**self).finish(ray, hit)
            }
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
            #[inline]
            fn parts(&self) -> u32 {
                (**self).parts()
            }
            #[inline]
            fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
                (**self).part_bounds(part)
            }
            #[inline]
            fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
                (**self).intersect_part(part, ray, t_max)
            }
            #[inline]
            fn area(&self) -> Option<F> {
                (**self).area()
            }
            #[inline]
            fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
                (**self).sample(from, u)
            }
            #[inline]
            fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
                (**self).pdf(ray, hit)
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
