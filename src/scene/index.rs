//! How a scene finds what a ray hits: its objects in groups, spheres four at a time and
//! the other shapes one by one, and a BVH over the groups once there are enough objects.

use super::{Acceleration, Object};
use crate::aabb::Aabb;
use crate::bvh::{Bvh, Streams};
use crate::float::Float;
use crate::ray::Ray;
use crate::shape::{Hit, Hittable, LANES, Sphere, Sphere4};

/// Four spheres and the objects they belong to.
#[derive(Clone, Copy, Debug)]
struct Packet<F> {
    spheres: Sphere4<F>,
    /// Object index of each lane (unused lanes hold an empty sphere and `u32::MAX`).
    ids: [u32; LANES],
}

/// Objects in the form they are tested in, one or more groups one after another.
#[derive(Clone, Debug, Default)]
struct Lists<F> {
    packets: Vec<Packet<F>>,
    /// Spheres left over after a group's packets of four, tested one by one, with their
    /// object indices (see [`Lists::push_group`]).
    singles: Vec<(Sphere<F>, u32)>,
    /// Objects that are not (known to be) spheres, by object index.
    others: Vec<u32>,
}

/// No object: the `id` of a ray that has hit nothing yet.
const NONE: u32 = u32::MAX;

/// Each ray's nearest hit so far in a batch ([`Index::hit_all`]): `t`, the object `id`
/// (or [`NONE`]), and for another shape than a sphere the bound it was found with; kept
/// from batch to batch, with the stream traversal's buffers.
#[derive(Clone, Debug, Default)]
pub(crate) struct Nearests<F> {
    t: Vec<F>,
    id: Vec<u32>,
    /// For a ray whose nearest hit is another shape's, the bound it was found with:
    /// the same query again gives the same record.
    bound: Vec<F>,
    streams: Streams<F>,
}

impl<F: Float> Nearests<F> {
    /// Nothing found yet for `n` rays; bounds are kept only if `others`.
    fn reset(&mut self, n: usize, others: bool) {
        self.t.clear();
        self.t.resize(n, F::infinity());
        self.id.clear();
        self.id.resize(n, NONE);
        self.bound.clear();
        if others {
            self.bound.resize(n, F::zero());
        }
    }

    /// Ray `i`'s nearest hit so far, as [`Nearest`] (its record still to be made).
    fn take(&self, i: usize) -> Nearest<F> {
        let (t, id) = (self.t[i], self.id[i]);
        Nearest {
            t,
            id: if id == NONE { 0 } else { id },
            found: if id == NONE {
                Found::Nothing
            } else {
                Found::Pending
            },
        }
    }

    /// The bound to query ray `i`'s nearest object with again, if it is not a sphere.
    fn bound(&self, i: usize, t: F) -> F {
        self.bound.get(i).copied().unwrap_or_else(|| t.next_up())
    }
}

/// Where one group lies in its [`Lists`]: `packets[packets.0..packets.1]`,
/// `singles[singles.0..singles.1]`, `others[others.0..others.1]`.
#[derive(Clone, Copy, Debug)]
struct Group {
    packets: (u32, u32),
    singles: (u32, u32),
    others: (u32, u32),
}

/// The objects of one group, borrowed from its [`Lists`].
#[derive(Clone, Copy)]
struct Members<'a, F> {
    packets: &'a [Packet<F>],
    singles: &'a [(Sphere<F>, u32)],
    others: &'a [u32],
}

/// Where the objects of each BVH leaf lie in [`Index::in_tree`].
#[derive(Clone, Debug)]
enum Leaves {
    /// Every leaf holds up to four spheres and nothing else, so leaf `k` is exactly
    /// packet `k`: a leaf's visit goes straight to its packet, with no group to look up.
    Packets,
    /// Leaf `k`'s objects are the group `groups[k]`.
    Groups(Vec<Group>),
}

/// A scene's intersection structure, built from its objects on the first query.
///
/// The loop group holds every object tested by the plain loop: all of them, or with a BVH
/// the unbounded ones (planes) and the huge ones (see [`Index::build`]). Every ray tests
/// it, so it has lists of its own, read whole. With a BVH, the objects of its leaves lie
/// in the shared lists `in_tree`, as `leaves` says.
#[derive(Clone, Debug)]
pub(super) struct Index<F> {
    looped: Lists<F>,
    in_tree: Lists<F>,
    leaves: Leaves,
    bvh: Option<Bvh<F>>,
}

impl<F> Lists<F> {
    /// All the objects, as one group.
    #[inline(always)]
    fn all(&self) -> Members<'_, F> {
        Members {
            packets: &self.packets,
            singles: &self.singles,
            others: &self.others,
        }
    }

    /// Packet `k` alone, as a group.
    #[inline(always)]
    fn packet(&self, k: usize) -> Members<'_, F> {
        Members {
            packets: std::slice::from_ref(&self.packets[k]),
            singles: &[],
            others: &[],
        }
    }

    /// The objects of group `g`.
    #[inline(always)]
    fn group(&self, g: Group) -> Members<'_, F> {
        Members {
            packets: &self.packets[g.packets.0 as usize..g.packets.1 as usize],
            singles: &self.singles[g.singles.0 as usize..g.singles.1 as usize],
            others: &self.others[g.others.0 as usize..g.others.1 as usize],
        }
    }
}

/// The nearest hit found so far: `t` and the object `id`, with its record made or still
/// to be made.
///
/// A hit at the same `t` as the held one wins when its object comes first, so the answer
/// is the loop's over the objects in order, whatever order the groups are visited in.
struct Nearest<F> {
    t: F,
    id: u32,
    found: Found<F>,
}

/// What [`Nearest`] holds: nothing yet; a hit whose record is still to be made, once, for
/// the nearest (a sphere's, or another shape's found in a batch, queried again); or
/// another shape's record.
enum Found<F> {
    Nothing,
    Pending,
    Other(Hit<F>),
}

impl<F: Float> Nearest<F> {
    /// Nothing found yet in `(0, t_max)`. (With nothing found, `id = 0` makes no tie win:
    /// a hit must then lie strictly below `t_max`.)
    fn new(t_max: F) -> Self {
        Self {
            t: t_max,
            id: 0,
            found: Found::Nothing,
        }
    }

    fn found(&self) -> bool {
        !matches!(self.found, Found::Nothing)
    }

    /// The exclusive bound below which a hit of object `id` can still win.
    #[inline]
    fn bound_for(&self, id: u32) -> F {
        if self.found() && id < self.id {
            self.t.next_up()
        } else {
            self.t
        }
    }

    /// Whether a hit of object `id` at `t` is nearer, or as near and of an earlier object.
    #[inline]
    fn beaten_by(&self, t: F, id: u32) -> bool {
        t < self.t || (t == self.t && id < self.id)
    }
}

impl<F: Float> Lists<F> {
    /// How many spheres left over after a group's packets of four are tested one by one
    /// rather than in a packet with empty lanes: one in f32, where four lanes fill one SSE
    /// register; up to two in wider scalars, where a packet takes two or more (measured:
    /// `docs/PERFORMANCE.md`).
    const SINGLES: usize = if std::mem::size_of::<F>() <= 4 { 1 } else { 2 };

    /// Appends a group of the objects `ids`, testing up to `alone` leftover spheres one by
    /// one; where it lies.
    ///
    /// The ids are put in increasing order first: a packet's lanes must follow the objects'
    /// order, since of equally near lanes it answers with the first. (A BVH leaf lists its
    /// objects in the order its build's partitions left them: in `random_spheres`, 92 of
    /// 144 leaves out of order.)
    fn push_group<S: Hittable<F>, M>(
        &mut self,
        ids: impl Iterator<Item = u32>,
        objects: &[Object<S, M>],
        alone: usize,
    ) -> Group {
        let first = (
            self.packets.len() as u32,
            self.singles.len() as u32,
            self.others.len() as u32,
        );
        let mut ids: Vec<u32> = ids.collect();
        ids.sort_unstable();
        let mut spheres = Vec::new();
        for id in ids {
            match objects[id as usize].shape.as_sphere() {
                Some(s) => spheres.push((id, *s)),
                None => self.others.push(id),
            }
        }
        let left = spheres.len() % LANES;
        if left <= alone {
            for (id, s) in spheres.drain(spheres.len() - left..) {
                self.singles.push((s, id));
            }
        }
        for chunk in spheres.chunks(LANES) {
            let mut ids = [u32::MAX; LANES];
            for (lane, &(id, _)) in chunk.iter().enumerate() {
                ids[lane] = id;
            }
            let shapes: Vec<_> = chunk.iter().map(|&(_, s)| s).collect();
            self.packets.push(Packet {
                spheres: Sphere4::new(&shapes),
                ids,
            });
        }
        Group {
            packets: (first.0, self.packets.len() as u32),
            singles: (first.1, self.singles.len() as u32),
            others: (first.2, self.others.len() as u32),
        }
    }
}

impl<F: Float> Index<F> {
    /// Groups `objects` for `acceleration`.
    pub(super) fn build<S: Hittable<F>, M>(objects: &[Object<S, M>], acceleration: Acceleration) -> Self {
        let mut index = Self {
            looped: Lists::default(),
            in_tree: Lists::default(),
            leaves: Leaves::Packets,
            bvh: None,
        };
        let boxes: Vec<Option<Aabb<F>>> = objects.iter().map(|o| o.shape.bounds()).collect();
        let bounded = boxes.iter().flatten().count();
        let wanted = match acceleration {
            Acceleration::Auto => bounded >= Acceleration::AUTO_THRESHOLD,
            Acceleration::Linear => false,
            Acceleration::Bvh => true,
        };
        if !wanted {
            index
                .looped
                .push_group(0..objects.len() as u32, objects, Lists::<F>::SINGLES);
            return index;
        }
        // The loop keeps the unbounded objects (planes) and the huge ones: an object whose
        // box covers half the scene's (by surface area: a ground sphere) is entered by
        // nearly every ray that enters the tree, so the tree gains nothing on it, and its
        // box would inflate every node above it.
        let whole = boxes
            .iter()
            .flatten()
            .fold(Aabb::empty(), |a, b| a.union(*b))
            .surface_area();
        let small = |b: &Aabb<F>| b.surface_area().to_f64() < 0.5 * whole.to_f64();
        let in_tree = |i: u32| boxes[i as usize].filter(small).map(|b| (i, b));
        let ids = 0..objects.len() as u32;
        index.looped.push_group(
            ids.clone().filter(|&i| in_tree(i).is_none()),
            objects,
            Lists::<F>::SINGLES,
        );
        let (bounded, boxes): (Vec<u32>, Vec<Aabb<F>>) = ids.filter_map(in_tree).unzip();
        let bvh = Bvh::build(&boxes);
        let leaf = |k: usize| bvh.leaf(k).iter().map(|&p| bounded[p as usize]);
        // Leaves of up to four spheres (all of them, in a scene of spheres) become one
        // packet each, a lone sphere included: no group to look up on each visit outweighs
        // the empty lanes.
        let one_packet = (0..bvh.leaf_count()).all(|k| {
            bvh.leaf(k).len() <= LANES && leaf(k).all(|i| objects[i as usize].shape.as_sphere().is_some())
        });
        let alone = if one_packet { 0 } else { Lists::<F>::SINGLES };
        let groups = (0..bvh.leaf_count())
            .map(|k| index.in_tree.push_group(leaf(k), objects, alone))
            .collect();
        if one_packet {
            debug_assert_eq!(
                index.in_tree.packets.len(),
                bvh.leaf_count(),
                "leaf k is packet k"
            );
        } else {
            index.leaves = Leaves::Groups(groups);
        }
        index.bvh = Some(bvh);
        index
    }

    /// Whether a BVH is used.
    pub(super) fn uses_bvh(&self) -> bool {
        self.bvh.is_some()
    }

    /// The nearest hit in `(0, t_max)` and the object hit; at equal distance, the object
    /// added first.
    #[inline]
    pub(super) fn hit<'a, S: Hittable<F>, M>(
        &self,
        objects: &'a [Object<S, M>],
        ray: &Ray<F>,
        t_max: F,
    ) -> Option<(Hit<F>, &'a Object<S, M>)> {
        let mut best = Nearest::new(t_max);
        Self::nearest_in(self.looped.all(), objects, ray, &mut best);
        if let Some(bvh) = &self.bvh {
            match &self.leaves {
                Leaves::Packets => bvh.traverse(ray, best.t, |k, _| {
                    Self::nearest_in(self.in_tree.packet(k), objects, ray, &mut best).then_some(best.t)
                }),
                Leaves::Groups(groups) => bvh.traverse(ray, best.t, |k, _| {
                    Self::nearest_in(self.in_tree.group(groups[k]), objects, ray, &mut best).then_some(best.t)
                }),
            }
        }
        let t = best.t;
        Self::record(objects, ray, best, || t.next_up())
    }

    /// [`Index::hit`] with no bound for each of `rays`, handed to `each(i, hit)` in the
    /// rays' order (`near` holds each ray's nearest `t` and object so far). The loop
    /// group's objects are tested one object over all the rays at a time (independent
    /// iterations the processor overlaps, where one ray's tests would wait on each other);
    /// then a tree of packets is walked by the whole batch at once, another tree by each
    /// ray alone.
    #[inline]
    pub(super) fn hit_all<'a, S: Hittable<F>, M>(
        &self,
        objects: &'a [Object<S, M>],
        rays: &[Ray<F>],
        near: &mut Nearests<F>,
        mut each: impl FnMut(usize, Option<(Hit<F>, &'a M)>),
    ) {
        let g = self.looped.all();
        near.reset(rays.len(), !g.others.is_empty());
        let (ts, ids) = (&mut near.t, &mut near.id);
        for p in g.packets {
            for ((ray, t), id) in rays.iter().zip(ts.iter_mut()).zip(ids.iter_mut()) {
                if let Some(nearer) = Self::beats(p, ray, *t, *id) {
                    (*t, *id) = nearer;
                }
            }
        }
        for &(sphere, lane) in g.singles {
            for ((ray, t), id) in rays.iter().zip(ts.iter_mut()).zip(ids.iter_mut()) {
                if let Some(s) = sphere.nearest_t(ray)
                    && (s < *t || (s == *t && lane < *id))
                {
                    (*t, *id) = (s, lane);
                }
            }
        }
        for &other in g.others {
            let rays = rays.iter().zip(ts.iter_mut()).zip(ids.iter_mut());
            for (((ray, t), id), found_with) in rays.zip(near.bound.iter_mut()) {
                let bound = if *id != NONE && other < *id {
                    t.next_up()
                } else {
                    *t
                };
                if let Some(hit) = objects[other as usize].shape.hit(ray, bound)
                    && (hit.t < *t || (hit.t == *t && other < *id))
                {
                    (*t, *id, *found_with) = (hit.t, other, bound);
                }
            }
        }
        // A tree of packets alone is searched by the whole batch at once.
        let streamed = match (&self.bvh, &self.leaves) {
            (Some(bvh), Leaves::Packets) => {
                let (ts, ids) = (&mut near.t, &mut near.id);
                bvh.traverse_all(rays, ts, &mut near.streams, |k, reached, ts| {
                    let p = &self.in_tree.packets[k];
                    // All cut to one length: one bounds check serves the three.
                    let (rays, ids) = (&rays[..ts.len()], &mut ids[..ts.len()]);
                    for &r in reached {
                        let r = r as usize;
                        if let Some(nearer) = Self::beats(p, &rays[r], ts[r], ids[r]) {
                            (ts[r], ids[r]) = nearer;
                        }
                    }
                });
                true
            }
            _ => false,
        };
        for (i, ray) in rays.iter().enumerate() {
            let mut best = near.take(i);
            if let Some(bvh) = self.bvh.as_ref().filter(|_| !streamed) {
                match &self.leaves {
                    Leaves::Packets => bvh.traverse(ray, best.t, |k, _| {
                        Self::nearest_in(self.in_tree.packet(k), objects, ray, &mut best).then_some(best.t)
                    }),
                    Leaves::Groups(groups) => bvh.traverse(ray, best.t, |k, _| {
                        Self::nearest_in(self.in_tree.group(groups[k]), objects, ray, &mut best)
                            .then_some(best.t)
                    }),
                }
            }
            let t = best.t;
            let hit = Self::record(objects, ray, best, || near.bound(i, t));
            each(i, hit.map(|(hit, object)| (hit, &object.material)));
        }
    }

    /// The record of the nearest hit `best` found for `ray`, and the object hit. A shape
    /// that is not a sphere and whose record is not held is queried again with `bound()`
    /// (worked out only then: a sphere's record needs no bound).
    #[inline(always)]
    fn record<'a, S: Hittable<F>, M>(
        objects: &'a [Object<S, M>],
        ray: &Ray<F>,
        best: Nearest<F>,
        bound: impl FnOnce() -> F,
    ) -> Option<(Hit<F>, &'a Object<S, M>)> {
        let object = objects.get(best.id as usize)?;
        let hit = match best.found {
            Found::Nothing => return None,
            Found::Other(hit) => hit,
            // Only the nearest sphere's record is made. (A shape that is not a sphere
            // answers the query it answered before.)
            Found::Pending => match object.shape.as_sphere() {
                Some(s) => s.hit_at(ray, best.t),
                None => object.shape.hit(ray, bound())?,
            },
        };
        Some((hit, object))
    }

    /// Updates `best` with packet `p`; whether it changed.
    #[inline(always)]
    fn nearest_in_packet(p: &Packet<F>, ray: &Ray<F>, best: &mut Nearest<F>) -> bool {
        let Some((t, id)) = Self::beats(p, ray, best.t, best.id) else {
            return false;
        };
        (best.t, best.id, best.found) = (t, id, Found::Pending);
        true
    }

    /// Packet `p`'s nearest hit of `ray` and its object, if it is nearer than `t`, or as
    /// near and of an object before `id`.
    #[inline(always)]
    fn beats(p: &Packet<F>, ray: &Ray<F>, t: F, id: u32) -> Option<(F, u32)> {
        let hits = p.spheres.hits(ray);
        let nearest = hits.min_lane();
        // Most packets hold nothing nearer. Lanes follow the objects' order, so of
        // equally near lanes the first is the packet's answer.
        if nearest < F::infinity() && nearest <= t {
            let lane = p.ids[hits.mask_eq(nearest).trailing_zeros() as usize];
            if nearest < t || lane < id {
                return Some((nearest, lane));
            }
        }
        None
    }

    /// Updates `best` with the objects of group `g`; whether it changed.
    #[inline(always)]
    fn nearest_in<S: Hittable<F>, M>(
        g: Members<'_, F>,
        objects: &[Object<S, M>],
        ray: &Ray<F>,
        best: &mut Nearest<F>,
    ) -> bool {
        let mut changed = false;
        for p in g.packets {
            changed |= Self::nearest_in_packet(p, ray, best);
        }
        for &(sphere, id) in g.singles {
            if let Some(t) = sphere.nearest_t(ray)
                && best.beaten_by(t, id)
            {
                (best.t, best.id, best.found) = (t, id, Found::Pending);
                changed = true;
            }
        }
        for &id in g.others {
            if let Some(hit) = objects[id as usize].shape.hit(ray, best.bound_for(id))
                && best.beaten_by(hit.t, id)
            {
                (best.t, best.id, best.found) = (hit.t, id, Found::Other(hit));
                changed = true;
            }
        }
        changed
    }

    /// Whether any object blocks the ray in `(0, t_max)`; stops at the first.
    #[inline]
    pub(super) fn occluded<S: Hittable<F>, M>(
        &self,
        objects: &[Object<S, M>],
        ray: &Ray<F>,
        t_max: F,
    ) -> bool {
        let blocks = |g: Members<'_, F>| {
            g.packets.iter().any(|p| p.spheres.any(ray, t_max))
                || g.singles
                    .iter()
                    .any(|(s, _)| s.nearest_t(ray).is_some_and(|t| t < t_max))
                || g.others
                    .iter()
                    .any(|&id| objects[id as usize].shape.occluded(ray, t_max))
        };
        blocks(self.looped.all())
            || self.bvh.as_ref().is_some_and(|bvh| match &self.leaves {
                Leaves::Packets => bvh.any(ray, t_max, |k| blocks(self.in_tree.packet(k))),
                Leaves::Groups(groups) => bvh.any(ray, t_max, |k| blocks(self.in_tree.group(groups[k]))),
            })
    }
}

#[cfg(test)]
mod tests;
