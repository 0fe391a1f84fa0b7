//! Instancing: a mesh defined once ([`Prototype`]) and placed many times ([`Instance`]),
//! each placement costing its record, not its mesh. A scene's BVH holds the instances;
//! each instance walks its prototype's own BVH (two levels).

use super::triangle::{checked_normal, coordinates, intersect_vertices, record};
use super::{Coordinates, Hit, Hittable, Intersection, SurfaceSample};
use crate::aabb::Aabb;
use crate::bvh::Bvh;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::transform::Affine;
use crate::vec3::Vec3;
use std::sync::Arc;

/// A triangle mesh in its own space, to be placed by [`Instance`]s: its vertices (in
/// `f64`, as read), its triangles, and a BVH over them built once for all placements.
#[derive(Debug)]
pub struct Prototype {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
    bvh: Bvh<f64>,
    bounds: Aabb<f64>,
}

impl Prototype {
    /// The mesh of `triangles` (indices into `vertices`, counter-clockwise seen from the
    /// front as for [`Triangle`](super::Triangle)).
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::Mesh`]) for a vertex that is not finite, an index
    /// past the vertices, or no triangle at all.
    pub fn new(vertices: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>) -> Result<Self> {
        if let Some(k) = vertices.iter().position(|v| !v.iter().all(|c| c.is_finite())) {
            return Err(Error::invalid(Field::Mesh, format!("vertex {k} is not finite")));
        }
        if let Some(k) = triangles
            .iter()
            .position(|t| t.iter().any(|&i| i as usize >= vertices.len()))
        {
            return Err(Error::invalid(
                Field::Mesh,
                format!(
                    "triangle {k} indexes a vertex past the {} vertices",
                    vertices.len()
                ),
            ));
        }
        if triangles.is_empty() || u32::try_from(triangles.len()).is_err() {
            return Err(Error::invalid(
                Field::Mesh,
                format!("{} triangles: at least one and at most u32::MAX", triangles.len()),
            ));
        }
        let boxes = triangles.iter().map(|t| {
            let [a, b, c] = t.map(|i| {
                Vec3::new(
                    vertices[i as usize][0],
                    vertices[i as usize][1],
                    vertices[i as usize][2],
                )
            });
            Aabb::new(a.min(b).min(c), a.max(b).max(c))
        });
        let boxes: Vec<Aabb<f64>> = boxes.collect();
        let bounds = boxes.iter().copied().fold(Aabb::empty(), Aabb::union);
        Ok(Self {
            bvh: Bvh::build(boxes),
            vertices,
            triangles,
            bounds,
        })
    }

    /// The triangles, as indices into the vertices.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The vertices, in the mesh's own space.
    pub fn vertices(&self) -> &[[f64; 3]] {
        &self.vertices
    }
}

/// A [`Prototype`] placed in the scene by the affine map `to_world`.
///
/// Its triangle `k` is the triangle whose vertices are `to_world.point(v)` rounded to `F`,
/// computed when a ray is tested against it: bit for bit the triangle of a
/// [`Mesh`](super::Mesh) made from the same transformed vertices, so a scene of instances
/// renders the bytes of the same scene with each mesh copied (where the copy drops no
/// triangle as degenerate in `F`). A ray is taken into the mesh's space to walk its BVH,
/// whose boxes are grown by the rounding of the vertices so the walk misses nothing; the
/// triangles themselves are tested in the scene's space. Surface coordinates are each
/// triangle's barycentric ones. An instance is not sampled as a light: an emissive one is
/// found by the rays that hit it.
#[derive(Clone, Debug)]
pub struct Instance<F> {
    prototype: Arc<Prototype>,
    to_world: Affine,
    to_object: Affine,
    bounds: Aabb<F>,
    /// The largest coordinate of the placed mesh, for the rounding it suffers.
    reach: f64,
}

/// Two instances are equal when they place the same prototype (the same shared mesh) by
/// the same map.
impl<F> PartialEq for Instance<F> {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.prototype, &other.prototype) && self.to_world == other.to_world
    }
}

impl<F: Float> Instance<F> {
    /// `prototype` placed by `to_world`.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::Transform`]) for a map that cannot be inverted,
    /// or that takes the mesh beyond the range of `F`.
    pub fn new(prototype: Arc<Prototype>, to_world: Affine) -> Result<Self> {
        let to_object = to_world
            .inverse()
            .ok_or_else(|| Error::invalid(Field::Transform, "must be invertible"))?;
        let [lo, hi] = [prototype.bounds.min, prototype.bounds.max];
        let corners = (0..8).map(|k| {
            let pick = |axis: usize, a: f64, b: f64| if (k >> axis) & 1 == 0 { a } else { b };
            to_world.point([pick(0, lo.x, hi.x), pick(1, lo.y, hi.y), pick(2, lo.z, hi.z)])
        });
        let (mut min, mut max) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for c in corners {
            for axis in 0..3 {
                min[axis] = min[axis].min(c[axis]);
                max[axis] = max[axis].max(c[axis]);
            }
        }
        let reach = min.iter().chain(&max).fold(0.0f64, |m, x| m.max(x.abs()));
        if !(reach.is_finite() && reach < F::max_value().to_f64() / 4.0) {
            return Err(Error::invalid(
                Field::Transform,
                format!("places the mesh beyond the range of {}", F::NAME),
            ));
        }
        // Rounding each bound to F, and each vertex's rounding inside them.
        let pad = Vec3::splat(lit::<F>(reach) * F::gamma(2));
        let bounds = Aabb::new(
            Vec3::from_f64(min[0], min[1], min[2]) - pad,
            Vec3::from_f64(max[0], max[1], max[2]) + pad,
        );
        Ok(Self {
            prototype,
            to_world,
            to_object,
            bounds,
            reach,
        })
    }

    /// The mesh placed.
    pub fn prototype(&self) -> &Arc<Prototype> {
        &self.prototype
    }

    /// The map from the mesh's space to the scene's.
    pub fn to_world(&self) -> &Affine {
        &self.to_world
    }

    /// This instance in scalar `G` (the same prototype, shared).
    pub fn cast<G: Float>(&self) -> Result<Instance<G>> {
        Instance::new(Arc::clone(&self.prototype), self.to_world)
    }

    /// Triangle `k` in the scene's space, in `F`.
    #[inline]
    pub fn triangle(&self, k: u32) -> [Vec3<F>; 3] {
        self.prototype.triangles[k as usize].map(|i| {
            let [x, y, z] = self.to_world.point(self.prototype.vertices[i as usize]);
            Vec3::from_f64(x, y, z)
        })
    }

    /// The nearest of its triangles the ray meets in `(0, t_max)`, of equally near ones
    /// the first: the answer a [`Mesh`](super::Mesh) of the same triangles gives.
    fn nearest(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let [o, d] = [ray.origin.to_f64(), ray.direction.to_f64()];
        let ([ox, oy, oz], [dx, dy, dz]) = (self.to_object.point(o), self.to_object.vector(d));
        // Not normalised: a distance along it is the same `t` as along the ray.
        let local = Ray {
            origin: Vec3::new(ox, oy, oz),
            direction: Vec3::new(dx, dy, dz),
        };
        // How far a rounded vertex's preimage may lie from its triangle's box: the
        // rounding to F of a coordinate up to `reach`, and f64's in taking the ray across,
        // stretched by the inverse map.
        let size = self.reach + o.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let pad = self.to_object.stretch() * (4.0 * F::eps().to_f64() + 1e-13) * size;
        let mut best: Option<Intersection<F>> = None;
        let bound = |t: F| t.to_f64() * (1.0 + 1e-12) + f64::MIN_POSITIVE;
        self.prototype
            .bvh
            .traverse_padded(&local, bound(t_max), pad, |leaf, _| {
                let before = best.map(|b| (b.t, b.part));
                for &k in self.prototype.bvh.leaf(leaf) {
                    // Asked with no bound, as the scene's lanes are: a bound enters the
                    // test before its division and could turn away a tie.
                    let Some((t, coords)) = intersect_vertices(&self.triangle(k), ray, F::infinity()) else {
                        continue;
                    };
                    if t < t_max && best.is_none_or(|b| t < b.t || (t == b.t && k < b.part)) {
                        best = Some(Intersection { t, part: k, coords });
                    }
                }
                let after = best.map(|b| (b.t, b.part));
                (after != before).then(|| bound(best.map_or(t_max, |b| b.t)))
            });
        best
    }
}

impl<F: Float> Hittable<F> for Instance<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.nearest(ray, t_max)
    }

    // Always inlined: out of line it returns the record through memory, which keeps
    // every shape's record (a sphere's too) in memory.
    #[inline(always)]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        let v = self.triangle(hit.part);
        record(&v, checked_normal(v), ray, hit.t, hit.coords, None)
    }

    fn coordinates(&self, _: &Ray<F>, hit: &Intersection<F>, _: &Hit<F>) -> Coordinates<F> {
        coordinates(&self.triangle(hit.part), hit.coords, None)
    }

    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        Some(self.bounds)
    }

    /// One part for the scene: the instance walks its own triangles.
    #[inline]
    fn parts(&self) -> u32 {
        1
    }

    #[inline]
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        Some(self.bounds)
    }

    /// The nearest triangle; the answer's [`part`](Intersection::part) is the triangle's
    /// number, which [`finish`](Hittable::finish) needs.
    #[inline]
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.nearest(ray, t_max)
    }

    fn area(&self) -> Option<F> {
        None
    }

    fn sample(&self, _: Vec3<F>, _: [f64; 3]) -> Option<SurfaceSample<F>> {
        None
    }

    fn pdf(&self, _: &Ray<F>, _: &Hit<F>) -> F {
        F::zero()
    }
}
