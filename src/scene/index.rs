//! How a scene finds what a ray hits.
//!
//! Every part of every shape (a sphere, a plane, a mesh's triangle) sits in a packet of up
//! to four parts of one kind, and every packet answers one question the same way: the
//! nearest intersection of each lane, offered to the ray's nearest so far by one tie rule
//! ([`Found::offer`]). Only the nearest's hit record is made, once, by its shape
//! ([`Hittable::finish`]). The packets are tested by every ray (a plain loop), or, once
//! there are enough parts, sit in the leaves of a BVH: leaf `k` holds the packets
//! `leaves[k]..leaves[k + 1]`, one for a leaf of one kind.

mod packet;

use super::layout::Layout;
use super::{Acceleration, Object};
use crate::aabb::Aabb;
use crate::bvh::{Bvh, Streams};
use crate::float::Float;
use crate::ray::Ray;
use crate::shape::Hit;
pub(crate) use packet::Found;
use packet::{Key, NONE, Packer, Packet};

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
pub(super) struct Index<F> {
    /// The packets every ray tests (`..looped`: all parts, or with a BVH the unbounded and
    /// the huge ones), then the BVH leaves' packets.
    packets: Vec<Packet<F>>,
    looped: usize,
    /// Leaf `k`'s packets are `packets[leaves[k]..leaves[k + 1]]`.
    leaves: Vec<u32>,
    bvh: Option<Bvh<F>>,
}

impl<F: Float> Index<F> {
    /// Packs the parts of `objects` for `acceleration`.
    pub(super) fn build<S: Layout<F>, M>(objects: &[Object<S, M>], acceleration: Acceleration) -> Self {
        let keys = || {
            let parts =
                |(o, object): (usize, &Object<S, M>)| (0..object.shape.parts()).map(move |p| (o as u32, p));
            objects.iter().enumerate().flat_map(parts)
        };
        let bounds = |&(o, p): &Key| objects[o as usize].shape.part_bounds(p);
        let whole = keys().filter_map(|k| bounds(&k)).fold(Aabb::empty(), Aabb::union);
        let bounded = keys().filter(|k| bounds(k).is_some()).count();
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
        let (mut packer, mut packets) = (Packer::new(), Vec::new());
        let mut looped: Vec<Key> = keys().filter(|k| !in_tree(k)).collect();
        packer.pack(&mut looped, objects, &mut packets);
        let mut index = Self {
            looped: packets.len(),
            packets,
            leaves: Vec::new(),
            bvh: None,
        };
        if !wanted {
            return index;
        }
        let (tree_keys, boxes): (Vec<Key>, Vec<Aabb<F>>) = keys()
            .filter(in_tree)
            .map(|k| (k, bounds(&k).unwrap_or(whole)))
            .unzip();
        let bvh = Bvh::build(&boxes);
        drop(boxes);
        let mut leaf_keys = Vec::new();
        for k in 0..bvh.leaf_count() {
            index.leaves.push(index.packets.len() as u32);
            leaf_keys.clear();
            leaf_keys.extend(bvh.leaf(k).iter().map(|&i| tree_keys[i as usize]));
            packer.pack(&mut leaf_keys, objects, &mut index.packets);
        }
        index.leaves.push(index.packets.len() as u32);
        drop(tree_keys);
        index.bvh = Some(bvh);
        index
    }

    /// Whether a BVH is used.
    pub(super) fn uses_bvh(&self) -> bool {
        self.bvh.is_some()
    }

    /// The packets of BVH leaf `k`.
    #[inline(always)]
    fn leaf(&self, k: usize) -> &[Packet<F>] {
        &self.packets[self.leaves[k] as usize..self.leaves[k + 1] as usize]
    }

    /// The nearest hit in `(0, t_max)` and the object hit; at equal distance, the part
    /// that comes first.
    #[inline]
    pub(super) fn hit<'a, S: Layout<F>, M>(
        &self,
        objects: &'a [Object<S, M>],
        ray: &Ray<F>,
        t_max: F,
    ) -> Option<(Hit<F>, &'a Object<S, M>)> {
        let (mut nearest, mut found) = (t_max, Found::none());
        for p in &self.packets[..self.looped] {
            p.offer(objects, ray, &mut nearest, &mut found);
        }
        if let Some(bvh) = &self.bvh {
            bvh.traverse(ray, nearest, |k, _| {
                let mut changed = false;
                for p in self.leaf(k) {
                    changed |= p.offer(objects, ray, &mut nearest, &mut found);
                }
                changed.then_some(nearest)
            });
        }
        // A part offered at exactly `t_max` may hold the place of nothing found.
        (nearest < t_max).then(|| Self::record(objects, ray, nearest, &found))
    }

    /// [`Index::hit`] with no bound for each of `rays`, handed to `each(i, hit)` in the
    /// rays' order. The loop's packets are tested one packet over all the rays at a time
    /// (independent iterations the processor overlaps, where one ray's tests would wait on
    /// each other), then the tree is walked by the whole batch at once.
    #[inline]
    pub(super) fn hit_all<'a, S: Layout<F>, M>(
        &self,
        objects: &'a [Object<S, M>],
        rays: &[Ray<F>],
        near: &mut Nearests<F>,
        mut each: impl FnMut(usize, Option<(Hit<F>, &'a Object<S, M>)>),
    ) {
        let Nearests { t, found, streams } = near;
        t.clear();
        t.resize(rays.len(), F::infinity());
        found.clear();
        found.resize(rays.len(), Found::none());
        for p in &self.packets[..self.looped] {
            for ((ray, t), found) in rays.iter().zip(t.iter_mut()).zip(found.iter_mut()) {
                p.offer(objects, ray, t, found);
            }
        }
        if let Some(bvh) = &self.bvh {
            bvh.traverse_all(rays, t, streams, |k, reached, t| {
                // All cut to one length: one bounds check serves the three.
                let (rays, found) = (&rays[..t.len()], &mut found[..t.len()]);
                for p in self.leaf(k) {
                    for &r in reached {
                        let r = r as usize;
                        p.offer(objects, &rays[r], &mut t[r], &mut found[r]);
                    }
                }
            });
        }
        for (i, ray) in rays.iter().enumerate() {
            let hit = (found[i].key.0 != NONE).then(|| Self::record(objects, ray, t[i], &found[i]));
            each(i, hit);
        }
    }

    /// The record of the nearest hit, at `t`, described by `found`, and the object hit.
    #[inline(always)]
    fn record<'a, S: Layout<F>, M>(
        objects: &'a [Object<S, M>],
        ray: &Ray<F>,
        t: F,
        found: &Found<F>,
    ) -> (Hit<F>, &'a Object<S, M>) {
        let object = &objects[found.key.0 as usize];
        (object.shape.finish(ray, &found.intersection(t)), object)
    }

    /// Whether any part blocks the ray in `(0, t_max)`; stops at the first.
    #[inline]
    pub(super) fn occluded<S: Layout<F>, M>(&self, objects: &[Object<S, M>], ray: &Ray<F>, t_max: F) -> bool {
        let blocks = |packets: &[Packet<F>]| packets.iter().any(|p| p.any(objects, ray, t_max));
        blocks(&self.packets[..self.looped])
            || self
                .bvh
                .as_ref()
                .is_some_and(|bvh| bvh.any(ray, t_max, |k| blocks(self.leaf(k))))
    }
}

#[cfg(test)]
mod tests;
