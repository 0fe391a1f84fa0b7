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
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    /// The primitives whose boxes `ray` meets, found through the BVH's leaves and by brute
    /// force, each sorted.
    fn through_bvh_and_brute_force<F: Float>(
        bvh: &Bvh<F>,
        boxes: &[Aabb<F>],
        ray: &Ray<F>,
    ) -> (Vec<usize>, Vec<usize>) {
        let meets = |i: usize| boxes[i].hit(ray, F::infinity());
        let mut got = Vec::new();
        bvh.traverse(ray, F::infinity(), |k, _| {
            got.extend(bvh.leaf(k).iter().map(|&i| i as usize).filter(|&i| meets(i)));
            None
        });
        got.sort();
        (got, (0..boxes.len()).filter(|&i| meets(i)).collect())
    }

    /// Random little boxes; every ray's BVH answer must equal brute force.
    #[test]
    fn matches_brute_force() {
        let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(1);
        let boxes: Vec<Aabb<f64>> = (0..300)
            .map(|_| {
                let c = Vec3::new(
                    rng.random_range(-10.0..10.0),
                    rng.random_range(-10.0..10.0),
                    rng.random_range(-10.0..10.0),
                );
                Aabb::new(c - Vec3::splat(0.3), c + Vec3::splat(rng.random_range(0.01..0.6)))
            })
            .collect();
        let bvh = Bvh::build(boxes.iter().copied());
        assert!(bvh.node_count() < 2 * boxes.len());
        for _ in 0..2000 {
            let o = Vec3::new(
                rng.random_range(-15.0..15.0),
                rng.random_range(-15.0..15.0),
                rng.random_range(-15.0..15.0),
            );
            let Some(d) = Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
            .try_normalize() else {
                continue;
            };
            let ray = Ray::new(o, d);
            let (got, want) = through_bvh_and_brute_force(&bvh, &boxes, &ray);
            assert_eq!(got, want);
            let any_box = |k: usize| {
                bvh.leaf(k)
                    .iter()
                    .any(|&i| boxes[i as usize].hit(&ray, f64::INFINITY))
            };
            assert_eq!(bvh.any(&ray, f64::INFINITY, any_box), !want.is_empty());
        }
    }

    /// Axis-aligned rays (zero direction components, infinite reciprocals) along the
    /// faces and edges of boxes: the wide traversal must agree with the single-box test.
    #[test]
    fn axis_aligned_rays_on_faces() {
        let boxes: Vec<Aabb<f32>> = (0..40)
            .map(|i| {
                let c = Vec3::new((i % 5) as f32, ((i / 5) % 4) as f32, -((i / 20) as f32) - 3.0);
                Aabb::new(c, c + Vec3::splat(0.5))
            })
            .collect();
        let bvh = Bvh::build(boxes.iter().copied());
        for x in [0.0f32, 0.25, 0.5, 1.0, 2.5] {
            for y in [0.0f32, 0.5, 1.0, 3.5] {
                for d in [
                    Vec3::new(0.0, 0.0, -1.0),
                    Vec3::new(0.0, 0.0, 1.0),
                    Vec3::new(1.0, 0.0, 0.0),
                ] {
                    let ray = Ray::new(Vec3::new(x, y, if d.z > 0.0 { -10.0 } else { 1.0 }), d);
                    let (got, want) = through_bvh_and_brute_force(&bvh, &boxes, &ray);
                    assert_eq!(got, want, "{ray:?}");
                }
            }
        }
    }

    /// Random boxes: `n` little ones in a cube of side 100.
    fn random_boxes(n: usize, seed: u64) -> Vec<Aabb<f32>> {
        let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(seed);
        (0..n)
            .map(|_| {
                let c = Vec3::new(
                    rng.random_range(-50.0..50.0),
                    rng.random_range(-50.0..50.0),
                    rng.random_range(-50.0..50.0),
                );
                Aabb::new(c, c + Vec3::splat(rng.random_range(0.1..2.0)))
            })
            .collect()
    }

    /// Pools of one, two and three threads build the same tree, bit for bit (the node
    /// arrays, leaves, primitive order and the wide tree). 100 000 boxes, so the top
    /// nodes bin in chunks and the subtrees are built as separate tasks.
    #[test]
    fn same_tree_on_any_number_of_threads() {
        let boxes = random_boxes(100_000, 7);
        let on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build();
            pool.expect("a thread pool")
                .install(|| Bvh::build(boxes.iter().copied()))
        };
        let one = on(1);
        for threads in [2, 3] {
            let other = on(threads);
            assert_eq!(one.node_count, other.node_count, "nodes on {threads} threads");
            assert_eq!(one.leaves, other.leaves, "leaves on {threads} threads");
            assert_eq!(one.indices, other.indices, "primitives on {threads} threads");
            assert_eq!(format!("{one:?}"), format!("{other:?}"), "{threads} threads");
        }
    }

    /// No leaf mixes classes, even where boxes of both classes overlap exactly, and the
    /// leaves are numbered class by class.
    #[test]
    fn leaves_hold_one_class() {
        let boxes = random_boxes(2_000, 3);
        let class = |i: usize| (i % 3) as u8;
        let prims = boxes
            .iter()
            .enumerate()
            .flat_map(|(i, &b)| [(b, class(i)), (b, class(i + 1))])
            .collect::<Vec<_>>();
        let bvh = Bvh::build_classes(prims);
        let mut last = 0;
        for k in 0..bvh.leaf_count() {
            let classes: Vec<u8> = bvh
                .leaf(k)
                .iter()
                .map(|&p| class(p as usize / 2 + p as usize % 2))
                .collect();
            assert!(classes.windows(2).all(|w| w[0] == w[1]), "leaf {k}: {classes:?}");
            assert!(
                classes[0] >= last,
                "leaf {k} of class {} after class {last}",
                classes[0]
            );
            last = classes[0];
        }
        assert_eq!(last, 2, "all three classes seen");
    }

    #[test]
    fn empty_and_single() {
        let none = Bvh::<f32>::build([]);
        let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
        assert!(!none.any(&ray, f32::INFINITY, |_| true));
        let one = Bvh::build([Aabb::new(Vec3::new(-1.0, -1.0, -3.0), Vec3::new(1.0, 1.0, -2.0))]);
        assert_eq!((one.leaf_count(), one.leaf(0)), (1, &[0u32][..]));
        assert!(one.any(&ray, f32::INFINITY, |k| k == 0));
    }
}
