//! [`ShapeKind`]: the enum fast path over the concrete shapes.

use super::{
    Coordinates, Disk, Hit, Hittable, Instance, Intersection, Mesh, Plane, Sphere, SurfaceSample, Triangle,
};
use crate::aabb::Aabb;
use crate::float::Float;
use crate::ray::Ray;
use crate::vec3::Vec3;
use std::sync::Arc;

/// The enum fast path: every concrete shape, dispatched by `match` (no vtable, no box).
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeKind<F> {
    /// A [`Sphere`].
    Sphere(Sphere<F>),
    /// An infinite [`Plane`], shared: inline, it or the triangle would be the largest
    /// variant and make every sphere's object 48 bytes in `f32` instead of 32.
    Plane(Arc<Plane<F>>),
    /// A [`Triangle`], shared for the same reason (a mesh's triangles are not objects).
    Triangle(Arc<Triangle<F>>),
    /// A [`Disk`], shared: inline it would be the largest variant and grow every object of
    /// every scene (72 to 112 bytes in `f32`) for a shape few scenes have.
    Disk(Arc<Disk<F>>),
    /// A triangle [`Mesh`], shared: cloning the shape does not copy its buffers.
    Mesh(Arc<Mesh<F>>),
    /// A placement of a shared mesh ([`Instance`]).
    Instance(Arc<Instance<F>>),
}

/// `match` on a [`ShapeKind`], the same call on every variant.
macro_rules! each_shape {
    ($shape:expr, $s:ident => $call:expr) => {
        match $shape {
            ShapeKind::Sphere($s) => $call,
            ShapeKind::Plane($s) => $call,
            ShapeKind::Triangle($s) => $call,
            ShapeKind::Disk($s) => $call,
            ShapeKind::Mesh($s) => $call,
            ShapeKind::Instance($s) => $call,
        }
    };
}

impl<F: Float> Hittable<F> for ShapeKind<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        each_shape!(self, s => s.intersect(ray, t_max))
    }
    // Always inlined: out of line, every hit's record went through memory (+5 % on the
    // spec's scenes).
    #[inline(always)]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        each_shape!(self, s => s.finish(ray, hit))
    }
    #[inline]
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        each_shape!(self, s => s.coordinates(ray, hit, record))
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        each_shape!(self, s => s.bounds())
    }
    #[inline]
    fn parts(&self) -> u32 {
        each_shape!(self, s => s.parts())
    }
    #[inline]
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        each_shape!(self, s => s.part_bounds(part))
    }
    #[inline]
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        each_shape!(self, s => s.intersect_part(part, ray, t_max))
    }
    #[inline]
    fn area(&self) -> Option<F> {
        each_shape!(self, s => s.area())
    }
    #[inline]
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        each_shape!(self, s => s.sample(from, u))
    }
    #[inline]
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        each_shape!(self, s => s.pdf(ray, hit))
    }
}

impl<F> From<Sphere<F>> for ShapeKind<F> {
    fn from(s: Sphere<F>) -> Self {
        Self::Sphere(s)
    }
}

impl<F> From<Plane<F>> for ShapeKind<F> {
    fn from(p: Plane<F>) -> Self {
        Self::Plane(Arc::new(p))
    }
}

impl<F> From<Triangle<F>> for ShapeKind<F> {
    fn from(t: Triangle<F>) -> Self {
        Self::Triangle(Arc::new(t))
    }
}

impl<F> From<Disk<F>> for ShapeKind<F> {
    fn from(d: Disk<F>) -> Self {
        Self::Disk(Arc::new(d))
    }
}

impl<F> From<Mesh<F>> for ShapeKind<F> {
    fn from(m: Mesh<F>) -> Self {
        Self::Mesh(Arc::new(m))
    }
}

impl<F> From<Instance<F>> for ShapeKind<F> {
    fn from(i: Instance<F>) -> Self {
        Self::Instance(Arc::new(i))
    }
}

impl<F> From<Arc<Mesh<F>>> for ShapeKind<F> {
    fn from(m: Arc<Mesh<F>>) -> Self {
        Self::Mesh(m)
    }
}

impl<F: Float> ShapeKind<F> {
    /// This shape in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> crate::error::Result<ShapeKind<G>> {
        Ok(match self {
            Self::Sphere(s) => s.cast()?.into(),
            Self::Plane(p) => p.cast()?.into(),
            Self::Triangle(t) => t.cast()?.into(),
            Self::Disk(d) => d.cast()?.into(),
            Self::Mesh(m) => m.cast()?.into(),
            Self::Instance(i) => i.cast()?.into(),
        })
    }
}
