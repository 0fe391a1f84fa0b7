//! The spec's abstract object: the [`Hittable`] trait, the [`Hit`] it reports, and
//! [`ShapeKind`], the enum fast path over the concrete shapes.

mod disk;
mod hit;
mod instance;
mod kind;
mod mesh;
mod plane;
mod sample;
mod sphere;
mod sphere4;
mod triangle;
mod triangle4;

pub use disk::Disk;
pub use hit::{Coordinates, Hit, Surface, flat_hit_error, flat_surface};
pub use instance::{Instance, Prototype};
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
/// and implemented by the enum [`ShapeKind`] for compile-time dispatch. No method has a
/// default: a shape of your own, or an enum that wraps the library's shapes, says every
/// answer, so a wrapper that forgets to pass one on does not compile.
///
/// # Two phases, and a third
/// A ray may meet many shapes and needs the record of the nearest only, so a hit comes in
/// two steps: [`intersect`](Hittable::intersect) finds the nearest `t` and what the record
/// will need (cheap, run for every candidate), and [`finish`](Hittable::finish) makes the
/// [`Hit`] from it (run once, for the winner). [`hit`] does both, for a shape alone. The
/// surface coordinates, `uv` and `∂p/∂u`, come third ([`coordinates`](Hittable::coordinates)),
/// only for a material that reads them.
///
/// # Parts
/// A shape may be made of parts that a scene indexes one by one: a [`Mesh`]'s triangles.
/// It says how many ([`parts`](Hittable::parts)), bounds each
/// ([`part_bounds`](Hittable::part_bounds)) and intersects each alone
/// ([`intersect_part`](Hittable::intersect_part)). A shape of one part answers `1`, its
/// [`bounds`](Hittable::bounds) and its [`intersect`](Hittable::intersect).
///
/// # Reporting the rounding error
/// A secondary ray starts at [`Hit::offset_origin`], just past the box `point ± error`
/// that [`Hit::error`] claims holds the true surface. A shape of your own must make that
/// claim true:
/// - **Flat surfaces** (a disk, a quad, a plane): compute `t = ((A − O)·n)/(D·n)` for a
///   stored point `A` of the surface and its unit normal `n` — [`Plane::crossing`] does,
///   with a conservative `t > 0` test a spawned ray needs, so a flat shape can keep a
///   [`Plane`] and call it — then report [`flat_hit_error`]`(ray, t, A)` (or the whole
///   [`flat_surface`]).
/// - **Curved surfaces**: move the point back onto the surface and bound what is left, as
///   `Sphere`'s hit record does (`p ← C + (p − C)·r/|p − C|`, then `γ(6)|p − C| + γ(2)|p|`
///   per component, pbrt-v4 §6.8.5).
///
/// An error of zero does not move the origin at all: the rounded hit point lies on
/// either side of the true surface about as often, and from the wrong side the new ray
/// hits the surface it is leaving, at a tiny `t`. The image shows it as dark speckles
/// ("shadow acne"), worse the farther the shape is from the world origin for its size,
/// where the rounding is coarser (`tests/it/custom_shape.rs` counts them).
///
/// # Sampling as a light
/// An emissive shape that answers [`area`](Hittable::area), [`sample`](Hittable::sample)
/// and [`pdf`](Hittable::pdf) (spheres, disks, triangles and meshes do) is also sampled directly
/// from the surfaces it lights (next-event estimation); one that answers `None`, `None`
/// and `0` is lit only by rays that happen to hit it. `pdf` must be the density `sample`
/// draws with.
pub trait Hittable<F: Float> {
    /// The nearest intersection with `t` in the open interval `(0, t_max)`, if any.
    ///
    /// The interval is open at 0 and no larger `t_min` is needed: secondary rays start
    /// at [`Hit::offset_origin`], past the surface's rounding error.
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>>;

    /// The hit record of `hit`, an intersection this shape reported for `ray`: point,
    /// error bound and normals, without coordinates.
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F>;

    /// The surface coordinates at `hit` (an intersection this shape reported for `ray`,
    /// whose record is `record`), in the shape's documented parameterisation.
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F>;

    /// A box holding the whole shape, or `None` if it is unbounded (a plane); only
    /// bounded parts go into a scene's [`Bvh`](crate::bvh::Bvh).
    fn bounds(&self) -> Option<Aabb<F>>;

    /// How many parts a scene indexes this shape as (1 unless it is made of several).
    fn parts(&self) -> u32;

    /// A box holding part `part` (in `0..parts()`), or `None` if it is unbounded.
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>>;

    /// [`intersect`](Hittable::intersect) for part `part` alone. The answer's
    /// [`part`](Intersection::part) is what [`finish`](Hittable::finish) needs: `part`
    /// itself, but for a shape that finds its own sub-parts (an [`Instance`]'s triangle).
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>>;

    /// The surface area, if this shape can be sampled as a light; `None` otherwise.
    fn area(&self) -> Option<F>;

    /// A point of the surface drawn for the point `from` from three uniform numbers
    /// `u ∈ [0, 1)³`, with the density of its direction from `from` per unit solid
    /// angle; `None` if this shape cannot be sampled.
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>>;

    /// The density per unit solid angle with which [`sample`](Hittable::sample), called
    /// for `ray.origin`, draws the direction of `ray`, a ray that hits this shape at
    /// `hit`; 0 if this shape cannot be sampled.
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F;
}

/// The nearest hit of `shape` alone in `(0, t_max)`: all three phases at once. (A scene
/// asks every shape for [`Hittable::intersect`], only the nearest for its record, and its
/// coordinates only for a material that reads them.)
#[inline]
pub fn hit<F: Float, S: Hittable<F> + ?Sized>(shape: &S, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
    let i = shape.intersect(ray, t_max)?;
    let record = shape.finish(ray, &i);
    Some(record.with(shape.coordinates(ray, &i, &record)))
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
            fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
                (**self).coordinates(ray, hit, record)
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

/// Both phases at once and the any-hit query, on a shape alone: for the unit tests.
#[cfg(test)]
pub(crate) trait Alone<F: Float>: Hittable<F> {
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
        hit(self, ray, t_max)
    }
    fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.intersect(ray, t_max).is_some()
    }
}

#[cfg(test)]
impl<F: Float, S: Hittable<F> + ?Sized> Alone<F> for S {}
