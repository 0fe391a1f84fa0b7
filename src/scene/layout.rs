//! Which parts of a scene's shapes the scene may test four at a time.

use crate::float::Float;
use crate::ray::Ray;
use crate::shape::{Disk, Hit, Hittable, Intersection, Mesh, Plane, ShapeKind, Sphere, Triangle};
use crate::vec3::Vec3;

/// What a part of a shape is, as far as a scene's index can use it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive<F> {
    /// This sphere: tested four at a time in SIMD lanes.
    Sphere(Sphere<F>),
    /// The triangle with these vertices `[A, B, C]`: tested four at a time in SIMD lanes.
    Triangle([Vec3<F>; 3]),
    /// Anything else: tested on its own through [`Hittable::intersect_part`].
    Other,
}

/// How a scene's shape type lays out for intersection: which of a shape's parts are
/// spheres and triangles, which the scene then tests four at a time in SIMD lanes (each
/// lane bit for bit that shape's own `intersect`) and records through
/// [`Hittable::finish`] like any other part.
///
/// This is the scene's business, not the abstract object's: a trait object cannot say
/// what it is, so [`DynScene`](crate::DynScene)'s shapes keep the default, and every part
/// is tested through [`Hittable::intersect_part`]. A shape type of your own (an enum over
/// the library's shapes and yours, say) needs an `impl`; the empty one,
/// `impl<F: Float> Layout<F> for MyShape<F> {}`, is always correct, and forwarding the
/// library's variants to [`ShapeKind`]'s keeps their fast path.
///
/// A scene's shapes are `Sync`: the threads that render a scene share them, and so do
/// those that build its index.
pub trait Layout<F: Float>: Hittable<F> + Sync {
    /// What part `part` of this shape is. A part described as a [`Primitive::Sphere`] or
    /// [`Primitive::Triangle`] must intersect exactly as that sphere or triangle does:
    /// the scene tests the description, and asks the shape only for the record.
    #[inline]
    fn primitive(&self, part: u32) -> Primitive<F> {
        let _ = part;
        Primitive::Other
    }

    /// [`Hittable::finish`] of `hit`, where `vertices()` gives the part's vertices as
    /// [`Layout::primitive`] describes them if the part is a [`Primitive::Triangle`] the
    /// scene has at hand: the same record, made from vertices the ray's test has just read
    /// rather than from the shape's own store, which it has not. The default asks
    /// [`Hittable::finish`].
    #[inline(always)]
    fn finish_with(
        &self,
        ray: &Ray<F>,
        hit: &Intersection<F>,
        vertices: impl FnOnce() -> Option<[Vec3<F>; 3]>,
    ) -> Hit<F> {
        let _ = vertices;
        self.finish(ray, hit)
    }
}

impl<F: Float> Layout<F> for ShapeKind<F> {
    #[inline(always)]
    fn finish_with(
        &self,
        ray: &Ray<F>,
        hit: &Intersection<F>,
        vertices: impl FnOnce() -> Option<[Vec3<F>; 3]>,
    ) -> Hit<F> {
        // One match: the other arms as `Hittable::finish` has them.
        match self {
            Self::Mesh(m) => m.finish_with(ray, hit, vertices),
            Self::Sphere(s) => s.finish(ray, hit),
            Self::Plane(p) => p.finish(ray, hit),
            Self::Triangle(t) => t.finish(ray, hit),
            Self::Disk(d) => d.finish(ray, hit),
            Self::Instance(i) => i.finish(ray, hit),
        }
    }

    #[inline]
    fn primitive(&self, part: u32) -> Primitive<F> {
        match self {
            Self::Sphere(s) => s.primitive(part),
            Self::Plane(p) => p.primitive(part),
            Self::Triangle(t) => t.primitive(part),
            Self::Disk(d) => Disk::primitive(d, part),
            Self::Mesh(m) => m.primitive(part),
            // Tested whole, through its own BVH.
            Self::Instance(_) => Primitive::Other,
        }
    }
}

impl<F: Float> Layout<F> for Sphere<F> {
    #[inline]
    fn primitive(&self, _: u32) -> Primitive<F> {
        Primitive::Sphere(*self)
    }
}

impl<F: Float> Layout<F> for Triangle<F> {
    #[inline]
    fn primitive(&self, _: u32) -> Primitive<F> {
        Primitive::Triangle(self.vertices())
    }
}

impl<F: Float> Layout<F> for Mesh<F> {
    #[inline]
    fn primitive(&self, part: u32) -> Primitive<F> {
        Primitive::Triangle(self.triangle(part))
    }

    #[inline(always)]
    fn finish_with(
        &self,
        ray: &Ray<F>,
        hit: &Intersection<F>,
        vertices: impl FnOnce() -> Option<[Vec3<F>; 3]>,
    ) -> Hit<F> {
        let v = vertices().unwrap_or_else(|| self.triangle(hit.part));
        self.finish_vertices(ray, hit, &v)
    }
}

impl<F: Float> Layout<F> for Plane<F> {}

impl<F: Float> Layout<F> for Disk<F> {}

impl<F: Float> Layout<F> for Box<dyn Hittable<F> + Send + Sync> {}
