//! The stream traversal: a whole batch of rays walks the wide tree together, each node
//! tested against every ray that reached it in one tight loop.
//!
//! One ray's walk is a chain of dependent steps (node load, slab test, mask, next node)
//! broken by branches no predictor guesses, so the processor mostly waits. Here the
//! iterations of a node's loop belong to different rays and do not depend on each
//! other: they overlap. The price is the order: all the rays of a stream visit a node's
//! children in one order, the near-to-far order along their common direction octant
//! (the batch is split by octant first), not each ray's own; a ray whose nearest hit so
//! far has moved before a child's box still reaches that child's node, but goes no
//! deeper.
//!
//! The answer does not depend on the order: a leaf's hits update each ray's nearest
//! `(t, object)` by the same rule whatever came first, and a box is entered only when it
//! starts within that `t`, as in [`Bvh::traverse`].

use super::Bvh;
use super::wide::{Child, width};
use crate::aabb::{SlabRay, slab_test};
use crate::float::Float;
use crate::ray::Ray;

/// A node reached by this many rays or fewer is searched by each ray alone, nearest
/// child first (the stream's overhead per node outweighs its overlap).
const FEW_RAYS: usize = 4;

/// A ray of the batch that has reached a node is listed by its index in the batch alone
/// (`u32`, called `RayIndex` below).
///
/// No entry distance goes with it. A ray whose nearest hit has moved before a box it
/// entered still reaches that box's node, but enters none of its children: their boxes
/// lie inside the node's, so they start no nearer, and each test is clipped to the ray's
/// reach. Without the distances a node writes half as much per ray.
pub(crate) type RayIndex = u32;

/// Buffers for [`Bvh::traverse_all`], kept from batch to batch.
#[derive(Clone, Debug, Default)]
pub(crate) struct Streams<F> {
    prepared: Vec<SlabRay<F>>,
    /// The rays of each direction octant: the first `counts[o]` of `octants[o]`.
    octants: [Vec<RayIndex>; 8],
    counts: [usize; 8],
    /// One for each level of the tree.
    levels: Vec<Level>,
    /// The stack of a ray searching a subtree alone.
    stack: Vec<(Child, F)>,
}

/// Rays a node tests at once: a longer list is taken in chunks of this many.
const CHUNK: usize = 64;

/// A level's buffers: the rays of a chunk entering each of the node's children.
#[derive(Clone, Debug)]
struct Level {
    children: [[RayIndex; CHUNK]; MAX_WIDTH],
}

/// The most children a wide node has ([`Float::Node`](crate::Float::Node)).
const MAX_WIDTH: usize = 8;

impl Default for Level {
    fn default() -> Self {
        Self {
            children: [[0; CHUNK]; MAX_WIDTH],
        }
    }
}

impl<F: Float> Bvh<F> {
    /// Calls `leaf(k, rays, t_max)` for each leaf `k` with the indices in `rays` of the
    /// rays whose boxes lead to it; `t_max[i]` is ray `i`'s current reach, which the
    /// callback lowers as it finds hits. A leaf's callback gets the rays whose entry into
    /// its box was within reach when the leaf's parent was tested: a ray may since have
    /// found a hit nearer than the box, and the callback must keep the nearer hit.
    pub(crate) fn traverse_all(
        &self,
        rays: &[Ray<F>],
        t_max: &mut [F],
        streams: &mut Streams<F>,
        mut leaf: impl FnMut(usize, &[RayIndex], &mut [F]),
    ) {
        debug_assert_eq!(rays.len(), t_max.len());
        let Some(root) = self.root else { return };
        let Streams {
            prepared,
            octants,
            counts,
            levels,
            stack,
        } = streams;
        prepare(rays, prepared, octants, counts);
        let lists = || octants.iter().zip(*counts).map(|(list, n)| &list[..n]);
        let Child::Node(root) = root else {
            // A tree of one leaf: every ray goes to it.
            for list in lists() {
                if !list.is_empty() {
                    leaf(0, list, t_max);
                }
            }
            return;
        };
        levels.resize_with(levels.len().max(self.wide_depth + 1), Default::default);
        stack.resize(stack.len().max(self.stack_size()), (Child::Empty, F::zero()));
        let mut walk = Walk {
            bvh: self,
            prepared,
            stack,
            t_max,
            leaf: &mut leaf,
        };
        for (octant, list) in lists().enumerate() {
            if !list.is_empty() {
                walk.node(root, list, octant, levels);
            }
        }
    }
}

/// Each ray's [`SlabRay`] in `prepared`, and its index in the list of its direction octant
/// (the first `counts[o]` of `octants[o]`).
///
/// One loop (two were slower, `docs/PERFORMANCE.md`); `prepared` filled by `extend`, which
/// checks its room once, not once a ray. The lists are written by index into arrays that
/// only grow: a `push` that may reallocate is a call in the loop, and the loop's values
/// then went through the stack, at a cost that changed with the caller's stack alignment.
/// Out of line: inlined, it changed how the shading around the walk compiles, in scenes
/// that never walk a tree.
#[inline(never)]
fn prepare<F: Float>(
    rays: &[Ray<F>],
    prepared: &mut Vec<SlabRay<F>>,
    octants: &mut [Vec<RayIndex>; 8],
    counts: &mut [usize; 8],
) {
    prepared.clear();
    for list in octants.iter_mut().filter(|list| list.len() < rays.len()) {
        list.resize(rays.len(), 0);
    }
    *counts = [0; 8];
    prepared.extend(rays.iter().enumerate().map(|(i, ray)| {
        let r = SlabRay::new(ray);
        let o = r.octant();
        octants[o][counts[o]] = i as u32;
        counts[o] += 1;
        r
    }));
}

/// One stream's walk down the tree.
struct Walk<'w, F: Float, L> {
    bvh: &'w Bvh<F>,
    prepared: &'w [SlabRay<F>],
    stack: &'w mut [(Child, F)],
    t_max: &'w mut [F],
    leaf: &'w mut L,
}

impl<F: Float, L: FnMut(usize, &[RayIndex], &mut [F])> Walk<'_, F, L> {
    /// Tests wide node `i` against the rays `list` of direction octant `octant`, then
    /// walks its children near to far along the octant with the rays entering each.
    ///
    /// No branch depends on a ray: a ray out of reach is tested anyway and enters
    /// nothing, and each child's rays are gathered by writing every ray to its list and
    /// counting only those whose lane's comparison holds. (Branching on each ray's lanes
    /// mispredicts about half of them.)
    fn node(&mut self, i: u32, list: &[RayIndex], octant: usize, levels: &mut [Level]) {
        if list.len() <= FEW_RAYS {
            for &r in list {
                let ri = r as usize;
                let (leaf, t_max) = (&mut *self.leaf, &mut *self.t_max);
                let start = Some(Child::Node(i));
                self.bvh.traverse_wide::<false>(
                    start,
                    self.stack,
                    &self.prepared[ri],
                    t_max[ri],
                    F::zero(),
                    |k, _| {
                        leaf(k, &[r], t_max);
                        Some(t_max[ri])
                    },
                );
            }
            return;
        }
        let n = &self.bvh.wide[i as usize];
        let (near, far) = n.faces(octant);
        let (here, deeper) = levels.split_first_mut().expect("levels cover the tree's depth");
        for chunk in list.chunks(CHUNK) {
            // Each ray is written to all the children's lists and kept (its list's count
            // moved on) where it enters; the indices are masked to the lists' fixed size
            // (one vector operation for all), so there is no bounds check either.
            let mut counts = [0u32; MAX_WIDTH];
            // `prepared` cut to `t_max`'s length: one bounds check serves both.
            let prepared = &self.prepared[..self.t_max.len()];
            for &r in chunk {
                let reach = self.t_max[r as usize];
                let (t0, t1) = slab_test(&near, &far, &prepared[r as usize], reach);
                let at = counts.map(|c| c as usize & (CHUNK - 1));
                for lane in 0..width::<F>() {
                    here.children[lane][at[lane]] = r;
                    // One comparison per lane added to its count, not a bit mask: the
                    // counts stay one vector, where a mask's bits are pulled out one by one.
                    counts[lane] += u32::from(t0[lane] <= t1[lane]);
                }
            }
            for &lane in self.bvh.orders[i as usize][octant].as_ref() {
                let lane = lane as usize;
                let children = &here.children[lane][..counts[lane] as usize];
                if children.is_empty() {
                    continue;
                }
                match n.child(lane) {
                    Child::Node(c) => self.node(c, children, octant, deeper),
                    Child::Leaf(k) => (self.leaf)(k as usize, children, self.t_max),
                    Child::Empty => {}
                }
            }
        }
    }
}
