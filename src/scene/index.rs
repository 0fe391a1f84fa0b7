//! How a scene finds what a ray hits.
//!
//! Every part of every shape (a sphere, a plane, a mesh's triangle) sits in a packet of up
//! to four parts of one kind, and every packet answers one question the same way: the
//! nearest intersection of each lane, offered to the ray's nearest so far by one tie rule
//! ([`Found::offer`]). Only the nearest's hit record is made, once, by its shape
//! ([`Hittable::finish`]). The packets are tested by every ray (a plain loop), or, once
//! there are enough parts, are the leaves of a BVH whose leaves never mix kinds: leaf `k`
//! is packet `k`. Where no part can go in lanes and no BVH is wanted (or the scene asks
//! for [`Acceleration::Linear`]), the index is the plain loop over the objects instead
//! ([`super::plain`]), the same answers read as the specification states them.

mod packet;
mod runs;

use super::layout::{Layout, Primitive};
use super::{Acceleration, BvhQuality, Object, plain};
use crate::aabb::Aabb;
use crate::bvh::{Bvh, Streams};
use crate::float::Float;
use crate::material::Material;
use crate::ray::Ray;
use crate::shape::{Coordinates, Hit, Intersection};
use crate::vec3::Vec3;
pub(crate) use packet::Found;
use packet::{Key, Looped, NONE, Packer, Packet, Packets, kind};
use rayon::prelude::*;
use runs::{run, runs};
use std::hint::black_box;

/// A hit's record, the object hit and its material.
pub type HitOn<'a, F, S, M> = (Hit<F>, &'a Object<S>, &'a M);

/// Each ray's nearest hit so far in a batch ([`Index::hit_all`]), with the stream
/// traversal's buffers; kept from batch to batch.
#[derive(Clone, Debug, Default)]
pub(crate) struct Nearests<F> {
    t: Vec<F>,
    found: Vec<Found<F>>,
    streams: Streams<F>,
}

/// A scene's intersection structure, built from its objects on the first query.
#[derive(Clone, Debug)]
pub(super) struct Index<F: Float> {
    /// Every query is the plain loop over the objects ([`plain`]); nothing below is used.
    plain: bool,
    /// The packets every ray tests: all the parts, or with a BVH the unbounded and the
    /// huge ones.
    looped: Vec<Looped<F>>,
    /// With a BVH, leaf `k`'s parts: one kind, one packet.
    leaves: Packets<F>,
    bvh: Option<Bvh<F>>,
}

/// The bytes of objects beyond which an object hit is rarely still cached: about a core's
/// second-level cache.
const CACHED: usize = 1 << 20;

impl<F: Float> Index<F> {
    /// Packs the parts of `objects` for `acceleration`, a BVH built at `quality`. The passes
    /// over every part and the packing of the leaves run on any threads, in the order a
    /// sequential build gives.
    pub(super) fn build<S: Layout<F>, M: Sync>(
        objects: &[Object<S, M>],
        acceleration: Acceleration,
        quality: BvhQuality,
    ) -> Self {
        let runs = runs(objects.iter().map(|object| object.shape.parts()));
        let keys = || runs.par_iter().flat_map_iter(|&start| run(objects, start));
        let shape = |&(o, _): &Key| &objects[o as usize].shape;
        let bounds = |k: &Key| shape(k).part_bounds(k.1);
        // The union of boxes is exact, so it does not depend on the order of the reduction.
        let (whole, bounded) = keys()
            .filter_map(|k| bounds(&k))
            .map(|b| (b, 1usize))
            .reduce(|| (Aabb::empty(), 0), |(a, m), (b, n)| (a.union(b), m + n));
        let wanted = match acceleration {
            Acceleration::Auto => bounded >= Acceleration::AUTO_THRESHOLD,
            Acceleration::Linear => false,
            Acceleration::Bvh => true,
        };
        // With a BVH the loop keeps the unbounded parts (planes) and the huge ones: a part
        // whose box covers half the scene's (by surface area: a ground sphere) is entered by
        // nearly every ray that enters the tree, so the tree gains nothing on it, and its
        // box would inflate every node above it.
        let half = 0.5 * whole.surface_area().to_f64();
        let in_tree = |k: &Key| wanted && bounds(k).is_some_and(|b| b.surface_area().to_f64() < half);
        let mut packer = Packer::new();
        let lanes = |k: Key| !matches!(shape(&k).primitive(k.1), Primitive::Other);
        let plain = acceleration == Acceleration::Linear || (!wanted && !keys().any(lanes));
        let mut index = Self {
            plain,
            looped: Vec::new(),
            leaves: Packets::default(),
            bvh: None,
        };
        if plain {
            return index;
        }
        let (tree_keys, mut looped): (Vec<Key>, Vec<Key>) = keys().partition(in_tree);
        let mut packets = Packets::default();
        packer.pack(&mut looped, objects, &mut packets);
        index.looped = packets.iter().map(Looped::new).collect();
        if !wanted {
            return index;
        }
        let class = |k: &Key| kind(&shape(k).primitive(k.1));
        // Through a trait object, so that the build's parallel collection is compiled once,
        // not once for every shape type.
        let prim = |i: usize| (bounds(&tree_keys[i]).unwrap_or(whole), class(&tree_keys[i]));
        let prim: &(dyn Fn(usize) -> (Aabb<F>, u8) + Sync) = &prim;
        let prims = (0..tree_keys.len()).into_par_iter().map(prim);
        let bvh = match quality {
            BvhQuality::Medium => Bvh::build_classes(prims),
            BvhQuality::High => Bvh::build_split(prims, |i| {
                let k = &tree_keys[i as usize];
                match shape(k).primitive(k.1) {
                    Primitive::Triangle(t) => Some(t),
                    _ => None,
                }
            }),
        };
        let leaf_class = |k: usize| class(&tree_keys[bvh.leaf(k)[0] as usize]);
        let counts = (0..bvh.leaf_count()).into_par_iter().map(|k| {
            let mut count = [0; 3];
            count[usize::from(leaf_class(k))] = 1;
            count
        });
        let counts = counts.reduce(|| [0; 3], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2]]);
        index.leaves.pack_leaves(counts, objects, |k, keys| {
            keys.clear();
            keys.extend(bvh.leaf(k).iter().map(|&i| tree_keys[i as usize]));
            // Pieces of one cut triangle may share a leaf: it is tested once.
            dedup(keys);
        });
        index.bvh = Some(bvh);
        index
    }

    /// Whether a BVH is used.
    pub(super) fn uses_bvh(&self) -> bool {
        self.bvh.is_some()
    }

    /// The references in the BVH's leaves, a cut triangle's pieces counted apart.
    pub(super) fn bvh_references(&self) -> Option<usize> {
        let bvh = self.bvh.as_ref()?;
        Some((0..bvh.leaf_count()).map(|k| bvh.leaf(k).len()).sum())
    }

    /// The nearest hit in `(0, t_max)` and the object hit; at equal distance, the part
    /// that comes first.
    #[inline]
    pub(super) fn hit<'a, S: Layout<F>, M: Material<F>>(
        &self,
        objects: &'a [Object<S>],
        materials: &'a [M],
        ray: &Ray<F>,
        t_max: F,
    ) -> Option<HitOn<'a, F, S, M>> {
        if self.plain {
            let (hit, o) = plain::nearest(objects, ray, t_max)?;
            return Some(self.record(objects, materials, ray, &hit, (o, NONE)));
        }
        let (mut nearest, mut found) = ([t_max], [Found::none()]);
        let rays = std::slice::from_ref(ray);
        for p in &self.looped {
            p.packet().offer(objects, rays, [0], &mut nearest, &mut found);
        }
        if let Some(bvh) = &self.bvh {
            bvh.traverse(ray, nearest[0], |k, _| {
                let before = nearest[0];
                self.leaves
                    .get(k)
                    .offer(objects, rays, [0], &mut nearest, &mut found);
                (nearest[0] < before).then_some(nearest[0])
            });
        }
        // A part offered at exactly `t_max` may hold the place of nothing found.
        (nearest[0] < t_max).then(|| {
            let hit = found[0].intersection(nearest[0]);
            self.record(objects, materials, ray, &hit, (found[0].key.0, found[0].lane))
        })
    }

    /// [`Index::hit`] with no bound for each of `rays`, handed to `each(i, hit)` in the
    /// rays' order. The loop's packets are tested one packet over all the rays at a time
    /// (independent iterations the processor overlaps, where one ray's tests would wait on
    /// each other), then the tree is walked by the whole batch at once.
    #[inline]
    pub(super) fn hit_all<'a, S: Layout<F>, M: Material<F>>(
        &self,
        objects: &'a [Object<S>],
        materials: &'a [M],
        rays: &[Ray<F>],
        near: &mut Nearests<F>,
        mut each: impl FnMut(usize, Option<HitOn<'a, F, S, M>>),
    ) {
        let Nearests { t, found, streams } = near;
        t.clear();
        t.resize(rays.len(), F::infinity());
        // Read only where a part was found (`t < ∞`), so left as the last batch left it.
        if found.len() < rays.len() {
            found.resize(rays.len(), Found::none());
        }
        if self.plain {
            for (i, ray) in rays.iter().enumerate() {
                if let Some((hit, o)) = plain::nearest(objects, ray, F::infinity()) {
                    found[i].offer_part(&mut t[i], hit.t, (o, hit.part), hit.part, NONE, || hit.coords);
                }
            }
        }
        for p in &self.looped {
            p.packet().offer(objects, rays, 0..rays.len(), t, found);
        }
        if let Some(bvh) = &self.bvh {
            bvh.traverse_all(rays, t, streams, |k, reached, t| {
                let reached = reached.iter().map(|&r| r as usize);
                self.leaves.get(k).offer(objects, rays, reached, t, found);
            });
        }
        // In a large scene a hit's object is rarely cached, and read at its shading it waits
        // on memory alone. There every hit object is read first, in a loop of its own whose
        // reads overlap, and the shading finds it cached (10⁶ spheres: 1.1× the trace rate).
        // Nothing uses what this loop reads: `black_box` keeps the reads.
        if size_of_val(objects) > CACHED {
            read_ahead(objects, &found[..rays.len()]);
        }
        for (i, ray) in rays.iter().enumerate() {
            let hit = (t[i] < F::infinity()).then(|| {
                self.record(
                    objects,
                    materials,
                    ray,
                    &found[i].intersection(t[i]),
                    (found[i].key.0, found[i].lane),
                )
            });
            each(i, hit);
        }
    }

    /// The record of the intersection `hit` with object `o`, found in the lanes at `lane`
    /// ([`Found::lane`]), the object and its material.
    #[inline(always)]
    fn record<'a, S: Layout<F>, M: Material<F>>(
        &self,
        objects: &'a [Object<S>],
        materials: &'a [M],
        ray: &Ray<F>,
        hit: &Intersection<F>,
        (o, lane): (u32, u32),
    ) -> HitOn<'a, F, S, M> {
        let object = &objects[o as usize];
        let material = &materials[object.material.index()];
        let vertices = || self.leaves.triangle(lane);
        (record(object, material, ray, hit, vertices), object, material)
    }

    /// Whether any part blocks the ray in `(0, t_max)`; stops at the first.
    #[inline]
    pub(super) fn occluded<S: Layout<F>, M>(&self, objects: &[Object<S, M>], ray: &Ray<F>, t_max: F) -> bool {
        if self.plain {
            return plain::any(objects, ray, t_max);
        }
        self.looped.iter().any(|p| p.packet().any(objects, ray, t_max))
            || self
                .bvh
                .as_ref()
                .is_some_and(|bvh| bvh.any(ray, t_max, |k| self.leaves.get(k).any(objects, ray, t_max)))
    }

    /// [`Index::occluded`] of each of `rays` in `(0, reach[i])`, set in `blocked`: the same
    /// answers, the tree walked by the whole batch at once. A ray found blocked stops: its
    /// reach drops to `−∞`, which no box starts within.
    ///
    /// A ray `aimed[i]` at a part looks for its nearest hit within `reach[i]` instead. If
    /// that is the part, nothing is nearer and the ray is clear: the part's own test gave
    /// the distance the exact reach would be. Otherwise (something nearer, or nothing
    /// within the bound) the part is asked for that distance, as the shading would have,
    /// and the answer follows from it; a ray that misses the part is blocked and counted in
    /// the number returned.
    pub(super) fn occluded_all<S: Layout<F>, M>(
        &self,
        objects: &[Object<S, M>],
        rays: &[Ray<F>],
        reach: &[F],
        aimed: &[Option<Key>],
        near: &mut Nearests<F>,
        blocked: &mut Vec<bool>,
    ) -> usize {
        let gone = F::neg_infinity();
        let Nearests { t, found, streams } = near;
        t.clear();
        t.extend_from_slice(reach);
        // Read only where a part was found (`t < reach`).
        if found.len() < rays.len() {
            found.resize(rays.len(), Found::none());
        }
        let aimed = &aimed[..rays.len()];
        let test = |p: Packet<'_, F>, r: usize, t: &mut [F], found: &mut [Found<F>]| {
            if aimed[r].is_some() {
                p.offer(objects, rays, [r], t, found);
            } else if t[r] != gone && p.any(objects, &rays[r], t[r]) {
                t[r] = gone;
            }
        };
        if !self.plain {
            for r in 0..rays.len() {
                for p in &self.looped {
                    test(p.packet(), r, t, found);
                }
            }
        }
        if let Some(bvh) = &self.bvh {
            bvh.traverse_all(rays, t, streams, |k, reached, t| {
                let leaf = self.leaves.get(k);
                for &r in reached {
                    test(leaf, r as usize, t, found);
                }
            });
        }
        let mut missed = 0;
        blocked.clear();
        blocked.extend((0..rays.len()).map(|r| {
            let ray = &rays[r];
            let Some((object, part)) = aimed[r] else {
                return if self.plain {
                    plain::any(objects, ray, t[r])
                } else {
                    t[r] == gone
                };
            };
            let hit = t[r] < reach[r] && !self.plain;
            if hit && found[r].key == (object, part) {
                return false;
            }
            let shape = &objects[object as usize].shape;
            let Some(at) = shape.intersect_part(part, ray, F::infinity()) else {
                missed += 1;
                return true;
            };
            // The nearest hit is before the part's (nothing is nearer), or nothing was found
            // within the bound, which may fall short of the part.
            if hit {
                t[r] < at.t
            } else {
                self.occluded(objects, ray, at.t)
            }
        }));
        missed
    }
}

/// The hit record of `object`'s intersection `hit`: the shape's [`finish`](crate::Hittable::finish),
/// and its [`coordinates`](crate::Hittable::coordinates) if its material reads them.
#[inline(always)]
fn record<F: Float, S: Layout<F>, M: Material<F>>(
    object: &Object<S>,
    material: &M,
    ray: &Ray<F>,
    hit: &Intersection<F>,
    vertices: impl FnOnce() -> Option<[Vec3<F>; 3]>,
) -> Hit<F> {
    let record = object.shape.finish_with(ray, hit, vertices);
    if material.reads_coordinates() {
        record.with(coordinates(&object.shape, ray, hit))
    } else {
        record
    }
}

/// The shape's coordinates at `hit`: out of line, so the path of materials that read none
/// stays as short as it was. It finishes its own copy of the record (the same, bit for
/// bit) and returns the coordinates alone: a record passed to a call or returned from one
/// would be kept in memory on every path.
#[inline(never)]
fn coordinates<F: Float, S: Layout<F>>(shape: &S, ray: &Ray<F>, hit: &Intersection<F>) -> Coordinates<F> {
    shape.coordinates(ray, hit, &shape.finish(ray, hit))
}

/// Reads the object of each of `found` (see [`Index::hit_all`]). Out of line: inlined, it
/// changed how the shading around it compiles, for scenes that never call it. (Reading
/// the part's data too, a mesh's vertices, gained nothing on the full dragon.)
#[inline(never)]
fn read_ahead<F, S>(objects: &[Object<S>], found: &[Found<F>]) {
    for f in found {
        black_box(objects.get(f.key.0 as usize).map(|o| o.material));
    }
}

/// `keys` with each key only at its first place (a leaf's at most four: no sort needed).
fn dedup(keys: &mut Vec<Key>) {
    let mut kept = 0;
    for i in 0..keys.len() {
        if !keys[..kept].contains(&keys[i]) {
            keys[kept] = keys[i];
            kept += 1;
        }
    }
    keys.truncate(kept);
}

#[cfg(test)]
mod tests;
