//! A bounding volume hierarchy: binned surface-area-heuristic build, flat array layout,
//! ordered stack traversal of one ray ([`Bvh::traverse`]) or, inside the crate, of a whole
//! batch at once (the stream traversal). It only indexes primitives by their boxes and
//! groups them into leaves; the scene owns the primitives, lays out each leaf's as it
//! likes, and tests a whole leaf in the traversal's callback.

mod build;
mod stream;
mod wide;

pub(crate) use stream::Streams;

use crate::aabb::{Aabb, SlabRay};
use crate::float::Float;
use crate::ray::Ray;
use crate::vec3::Vec3;
use rayon::prelude::*;
use wide::{Child, Wide, width};

/// Most primitives a leaf may hold: one packet of spheres ([`crate::shape::Sphere4`]).
const MAX_LEAF: usize = crate::lanes::LANES;
/// Cost of visiting a node, relative to testing one leaf. A leaf of up to four spheres
/// is one packet test, so the SAH costs a leaf `⌈N/4⌉` and a subtree of `N` primitives
/// `N/4` (MacDonald & Booth's linear estimate, in packets). ½ rendered fastest of the
/// costs tried (figures in `docs/PERFORMANCE.md`).
const TRAVERSAL_COST: f64 = 0.5;

/// One node of the flattened binary tree the build makes (32 bytes in f32). An interior
/// node's children are the adjacent pair `nodes[offset]`, `nodes[offset + 1]`; a leaf
/// (`count > 0`) is leaf number `offset`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node<F> {
    /// `[min, max]` of the node's box.
    bounds: [Vec3<F>; 2],
    offset: u32,
    count: u16,
}

/// A bounding volume hierarchy over primitives `0..n` given by their boxes.
#[derive(Clone, Debug)]
pub struct Bvh<F: Float> {
    /// The binary tree's node count and SAH cost, for reports (the tree itself is dropped
    /// once collapsed into `wide`).
    node_count: usize,
    sah_cost: f64,
    indices: Vec<u32>,
    /// Leaf `k` holds `indices[leaves[k].0..leaves[k].1]`.
    leaves: Vec<(u32, u32)>,
    /// The same tree collapsed to eight children per node in `f32`, four in `f64`
    /// ([`Float::Node`]), which the traversal runs on.
    wide: Vec<Wide<F>>,
    /// The wide tree's root (`None` for an empty hierarchy).
    root: Option<Child>,
    /// For each wide node, its lanes near to far in each direction octant
    /// ([`Bvh::traverse_all`]).
    orders: Vec<[F::Node<u8>; 8]>,
    /// Levels below the wide root.
    wide_depth: usize,
}

impl<F: Float> Bvh<F> {
    /// Builds the hierarchy over the primitives whose boxes `bounds` yields: primitive `i`
    /// is the `i`-th.
    ///
    /// # Panics
    /// With more than `u32::MAX` primitives.
    pub fn build(bounds: impl IntoIterator<Item = Aabb<F>>) -> Self {
        let items = build::items(bounds.into_iter().map(|b| (b, 0)));
        Self::from_arrays(build::build(items, None::<fn(u32) -> Option<[Vec3<F>; 3]>>))
    }

    /// [`Bvh::build`] over primitives given as `(box, class)` by a parallel iterator (a
    /// `Vec` or a slice's `par_iter` will do), where no leaf holds two classes: a scene gives
    /// each kind of shape a class, so that a leaf is tested one way. The leaves are numbered
    /// class by class, every leaf of a lower class before any of a higher one.
    ///
    /// # Panics
    /// With more than `u32::MAX` primitives.
    pub fn build_classes<P>(prims: P) -> Self
    where
        P: IntoParallelIterator<Item = (Aabb<F>, u8)>,
        P::Iter: IndexedParallelIterator,
    {
        let items = build::items_par(prims.into_par_iter());
        Self::from_arrays(build::build(items, None::<fn(u32) -> Option<[Vec3<F>; 3]>>))
    }

    /// [`Bvh::build_classes`] with spatial splits, the quality Embree calls high: each
    /// triangle `triangle(i)` names (primitive `i`'s vertices, `None` for a primitive that
    /// is not one) whose box is mostly empty may be cut by planes into pieces, so that the
    /// tree's boxes hold parts of it rather than all of it (pre-splitting after Karras &
    /// Aila 2013; how much is cut is in `build/presplit.rs`). A cut triangle sits in more
    /// than one leaf, and a leaf may name it twice. It takes at most three references a
    /// triangle (a well-tessellated model takes almost none more) and longer to build.
    ///
    /// # Panics
    /// With more than `u32::MAX` primitives or pieces.
    pub fn build_split<P>(prims: P, triangle: impl Fn(u32) -> Option<[Vec3<F>; 3]>) -> Self
    where
        P: IntoParallelIterator<Item = (Aabb<F>, u8)>,
        P::Iter: IndexedParallelIterator,
    {
        let items = build::items_par(prims.into_par_iter());
        // As a trait object the build is compiled once, not once for every caller's closure.
        let triangle: &dyn Fn(u32) -> Option<[Vec3<F>; 3]> = &triangle;
        Self::from_arrays(build::build(items, Some(triangle)))
    }

    fn from_arrays((nodes, indices, leaves): build::Arrays<F>) -> Self {
        u32::try_from(indices.len()).expect("a BVH holds at most u32::MAX primitives");
        let mut bvh = Self {
            node_count: nodes.len(),
            sah_cost: sah_cost(&nodes),
            indices,
            leaves,
            wide: Vec::new(),
            root: None,
            orders: Vec::new(),
            wide_depth: 0,
        };
        if let Some(root) = nodes.first() {
            // Room for the most wide nodes the collapse can make, one per interior binary
            // node: it makes fewer than half as many, and pages never written are never
            // resident. A vector of aligned nodes that grew or shrank would be copied.
            bvh.wide = Vec::with_capacity(nodes.len() - bvh.leaves.len());
            bvh.root = Some(if root.count > 0 {
                Child::Leaf(root.offset)
            } else {
                Child::Node(wide::collapse(&nodes, 0, &mut bvh.wide))
            });
            bvh.wide_depth = wide::depth(&bvh.wide, bvh.root);
            bvh.orders = bvh.wide.par_iter().map(Wide::orders).collect();
        }
        bvh
    }

    /// Number of nodes of the binary tree (for tests and reports).
    pub fn node_count(&self) -> usize {
        self.node_count
    }

    /// The tree's surface-area-heuristic cost in the build's units (for tests and
    /// reports): `Σ C_t·A(n)/A(root)` over interior nodes plus `Σ ⌈N/4⌉·A(l)/A(root)` over
    /// leaves, with the build's node-visit cost `C_t` = ½; 0 for an empty tree. Lower is better.
    pub fn sah_cost(&self) -> f64 {
        self.sah_cost
    }

    /// Number of leaves; the traversal's callbacks receive leaf numbers `0..leaf_count()`.
    pub fn leaf_count(&self) -> usize {
        self.leaves.len()
    }

    /// The primitives of leaf `k` (at most four; after [`Bvh::build_split`], a cut
    /// triangle's in several leaves, and maybe twice in one).
    ///
    /// # Panics
    /// If `k >= leaf_count()`.
    pub fn leaf(&self, k: usize) -> &[u32] {
        let (start, end) = self.leaves[k];
        &self.indices[start as usize..end as usize]
    }

    /// Visits the leaves whose boxes the ray meets in `(0, t_max]`, nearer subtrees first.
    /// `visit(k, t_max)` tests the primitives of leaf `k` and returns the new, smaller
    /// `t_max` if it found a nearer hit; boxes entered beyond the current `t_max` are
    /// skipped (a box entered exactly at `t_max` is still visited, so a caller can break
    /// ties at equal distance).
    ///
    /// It runs on the wide collapse of the tree (eight children a node in `f32`, four in
    /// `f64`): at each node the ray is tested against the children's boxes at once, the
    /// ones it enters are stacked nearest on top with their entry distances, and a stacked
    /// subtree that a later hit has moved out of reach is dropped without another test.
    #[inline]
    pub fn traverse(&self, ray: &Ray<F>, t_max: F, visit: impl FnMut(usize, F) -> Option<F>) {
        self.traverse_with::<false>(ray, t_max, F::zero(), visit);
    }

    /// [`Bvh::traverse`] with every box grown by `pad ≥ 0` on every side: for primitives
    /// known only to within `pad` of their boxes (an instance's triangles, whose vertices
    /// are rounded after the transform the ray is brought back through).
    #[inline]
    pub fn traverse_padded(&self, ray: &Ray<F>, t_max: F, pad: F, visit: impl FnMut(usize, F) -> Option<F>) {
        self.traverse_with::<true>(ray, t_max, pad, visit);
    }

    #[inline]
    fn traverse_with<const PAD: bool>(
        &self,
        ray: &Ray<F>,
        t_max: F,
        pad: F,
        visit: impl FnMut(usize, F) -> Option<F>,
    ) {
        const INLINE: usize = 24;
        let need = self.stack_size();
        let ray = &SlabRay::new(ray);
        if need <= INLINE {
            let stack = &mut [(Child::Empty, F::zero()); INLINE];
            self.traverse_wide::<PAD>(self.root, stack, ray, t_max, pad, visit);
        } else {
            let stack = &mut vec![(Child::Empty, F::zero()); need];
            self.traverse_wide::<PAD>(self.root, stack, ray, t_max, pad, visit);
        }
    }

    /// The stack entries [`Bvh::traverse`] needs: each wide level stacks at most all its
    /// children, one of which is popped at once.
    fn stack_size(&self) -> usize {
        (width::<F>() - 1) * self.wide_depth + width::<F>()
    }

    /// Whether `test(k)` is true for some leaf whose box the ray meets in `(0, t_max)`;
    /// stops at the first.
    #[inline]
    pub fn any(&self, ray: &Ray<F>, t_max: F, mut test: impl FnMut(usize) -> bool) -> bool {
        let mut found = false;
        self.traverse(ray, t_max, |i, _| {
            if !found && test(i) {
                found = true;
                // Shrinking t_max to zero prunes every remaining box.
                return Some(F::zero());
            }
            None
        });
        found
    }
}

/// Bytes a node of the tree the traversal runs on takes: its boxes and children, and
/// its lanes' orders (for the tests that pin the documented memory figures).
#[cfg(test)]
pub(crate) fn wide_node_bytes<F: Float>() -> usize {
    std::mem::size_of::<Wide<F>>() + std::mem::size_of::<[F::Node<u8>; 8]>()
}

/// The alignment of a node of the tree the traversal runs on (a cache line).
#[cfg(test)]
pub(crate) fn wide_node_align<F: Float>() -> usize {
    std::mem::align_of::<Wide<F>>()
}

/// [`Bvh::sah_cost`] of the binary tree `nodes`.
fn sah_cost<F: Float>(nodes: &[Node<F>]) -> f64 {
    let area = |n: &Node<F>| Aabb::new(n.bounds[0], n.bounds[1]).surface_area().to_f64();
    let Some(root) = nodes.first() else {
        return 0.0;
    };
    let total = nodes
        .iter()
        .map(|n| {
            let weight = if n.count > 0 {
                (n.count as usize).div_ceil(MAX_LEAF) as f64
            } else {
                TRAVERSAL_COST
            };
            weight * area(n)
        })
        .sum::<f64>();
    total / area(root).max(f64::MIN_POSITIVE)
}

#[cfg(test)]
mod tests;
