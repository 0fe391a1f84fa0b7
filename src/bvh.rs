//! A bounding volume hierarchy: binned surface-area-heuristic build, flat array layout,
//! ordered stack traversal of one ray ([`Bvh::traverse`]) or, inside the crate, of a whole
//! batch at once (the stream traversal). It only indexes primitives by their boxes and
//! groups them into leaves; the scene owns the primitives, lays out each leaf's as it
//! likes, and tests a whole leaf in the traversal's callback.

mod stream;
mod wide;

pub(crate) use stream::Streams;

use crate::aabb::Aabb;
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::vec3::Vec3;
use wide::{Child, Wide};

/// Most primitives a leaf may hold: one packet of spheres ([`crate::shape::Sphere4`]).
const MAX_LEAF: usize = crate::lanes::LANES;
/// Centroid bins per axis for the SAH sweep.
const BINS: usize = 16;
/// Depth from which nodes split at the median instead of by SAH, so the tree's depth,
/// and the traversal stack, stay below `MEDIAN_DEPTH + 32` whatever the input.
const MEDIAN_DEPTH: usize = 40;
/// Cost of visiting a node, relative to testing one leaf. A leaf of up to four spheres
/// is one packet test, so the SAH costs a leaf `⌈N/4⌉` and a subtree of `N` primitives
/// `N/4` (MacDonald & Booth's linear estimate, in packets). On the random-spheres scene ½
/// was fastest, ¼ and 1 within 3 % (`docs/PERFORMANCE.md`).
const TRAVERSAL_COST: f64 = 0.5;

/// One node of the flattened binary tree the build makes (32 bytes in f32). An interior
/// node's children are the adjacent pair `nodes[offset]`, `nodes[offset + 1]`; a leaf
/// (`count > 0`) is leaf number `offset`.
#[derive(Clone, Copy, Debug)]
struct Node<F> {
    /// `[min, max]` of the node's box.
    bounds: [Vec3<F>; 2],
    offset: u32,
    count: u16,
}

/// A bounding volume hierarchy over primitives `0..n` given by their boxes.
#[derive(Clone, Debug)]
pub struct Bvh<F> {
    nodes: Vec<Node<F>>,
    indices: Vec<u32>,
    /// Leaf `k` holds `indices[leaves[k].0..leaves[k].1]`.
    leaves: Vec<(u32, u32)>,
    /// The same tree collapsed to four children per node, which the traversal runs on.
    wide: Vec<Wide<F>>,
    /// The wide tree's root (`None` for an empty hierarchy).
    root: Option<Child>,
    /// For each wide node, its lanes near to far in each direction octant
    /// ([`Bvh::traverse_all`]).
    orders: Vec<[[u8; 4]; 8]>,
    /// Levels below the wide root.
    wide_depth: usize,
}

struct Item<F> {
    bounds: Aabb<F>,
    centroid: Vec3<F>,
    index: u32,
}

impl<F: Float> Bvh<F> {
    /// Builds the hierarchy over `bounds[i]`, the box of primitive `i`.
    ///
    /// # Panics
    /// With more than `u32::MAX` primitives.
    pub fn build(bounds: &[Aabb<F>]) -> Self {
        let count = u32::try_from(bounds.len()).expect("a BVH holds at most u32::MAX primitives");
        let mut items: Vec<Item<F>> = (0..count)
            .map(|i| {
                let b = bounds[i as usize];
                Item {
                    bounds: b,
                    centroid: b.centroid(),
                    index: i,
                }
            })
            .collect();
        let mut bvh = Self {
            nodes: Vec::with_capacity(2 * bounds.len()),
            indices: Vec::with_capacity(bounds.len()),
            leaves: Vec::new(),
            wide: Vec::new(),
            root: None,
            orders: Vec::new(),
            wide_depth: 0,
        };
        if !items.is_empty() {
            bvh.nodes.push(Node {
                bounds: Aabb::empty().corners(),
                offset: 0,
                count: 0,
            });
            bvh.build_node(0, &mut items, 0);
            let root = bvh.nodes[0];
            bvh.root = Some(if root.count > 0 {
                Child::Leaf(root.offset)
            } else {
                Child::Node(wide::collapse(&bvh.nodes, 0, &mut bvh.wide))
            });
            bvh.wide_depth = wide::depth(&bvh.wide, bvh.root);
            bvh.orders = bvh.wide.iter().map(Wide::orders).collect();
        }
        bvh
    }

    /// Number of nodes of the binary tree (for tests and reports).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Number of leaves; the traversal's callbacks receive leaf numbers `0..leaf_count()`.
    pub fn leaf_count(&self) -> usize {
        self.leaves.len()
    }

    /// The primitives of leaf `k` (at most four).
    ///
    /// # Panics
    /// If `k >= leaf_count()`.
    pub fn leaf(&self, k: usize) -> &[u32] {
        let (start, end) = self.leaves[k];
        &self.indices[start as usize..end as usize]
    }

    /// Fills the (already allocated) node `me` with the subtree over `items`.
    fn build_node(&mut self, me: usize, items: &mut [Item<F>], depth: usize) {
        let bounds = items.iter().fold(Aabb::empty(), |b, it| b.union(it.bounds));
        self.nodes[me].bounds = bounds.corners();
        let split = if depth < MEDIAN_DEPTH {
            self.split(items, &bounds)
        } else {
            median_split(items)
        };
        match split {
            Some((_axis, mid)) => {
                let left = self.nodes.len();
                let empty = Node {
                    bounds: Aabb::empty().corners(),
                    offset: 0,
                    count: 0,
                };
                self.nodes.extend([empty, empty]);
                self.nodes[me].offset = left as u32;
                let (l, r) = items.split_at_mut(mid);
                self.build_node(left, l, depth + 1);
                self.build_node(left + 1, r, depth + 1);
            }
            None => {
                let start = self.indices.len() as u32;
                self.indices.extend(items.iter().map(|it| it.index));
                self.nodes[me].offset = self.leaves.len() as u32;
                self.nodes[me].count = items.len() as u16;
                self.leaves.push((start, self.indices.len() as u32));
            }
        }
    }

    /// The SAH split `(axis, mid)` partitioning `items` in place, or `None` for a leaf.
    ///
    /// Centroids are binned along each of the three axes; the cheapest bin boundary wins.
    /// Cost of a split: `C_t + (A_L·N_L + A_R·N_R)/(4A)`, of a leaf: `⌈N/4⌉` (see
    /// [`TRAVERSAL_COST`]).
    fn split(&self, items: &mut [Item<F>], bounds: &Aabb<F>) -> Option<(usize, usize)> {
        let n = items.len();
        if n <= 1 {
            return None;
        }
        let cb = items.iter().fold(Aabb::empty(), |b, it| {
            b.union(Aabb::new(it.centroid, it.centroid))
        });
        let area = bounds.surface_area().to_f64().max(f64::MIN_POSITIVE);
        // (cost, axis, last bin of the left side)
        let mut best: Option<(f64, usize, usize)> = None;
        for axis in 0..3 {
            let (lo, hi) = (cb.min[axis], cb.max[axis]);
            if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            let bin_of = binner(lo, hi);
            let mut bins = [(Aabb::empty(), 0usize); BINS];
            for it in items.iter() {
                let b = &mut bins[bin_of(it.centroid[axis])];
                b.0 = b.0.union(it.bounds);
                b.1 += 1;
            }
            // Sweep from the right for the right-hand areas and counts, then from the left.
            let mut right = [(0.0f64, 0usize); BINS];
            let (mut acc, mut cnt) = (Aabb::empty(), 0usize);
            for i in (1..BINS).rev() {
                acc = acc.union(bins[i].0);
                cnt += bins[i].1;
                right[i] = (acc.surface_area().to_f64(), cnt);
            }
            let (mut acc, mut cnt) = (Aabb::empty(), 0usize);
            for i in 0..BINS - 1 {
                acc = acc.union(bins[i].0);
                cnt += bins[i].1;
                let (ra, rc) = right[i + 1];
                if cnt == 0 || rc == 0 {
                    continue;
                }
                let packets = |n: usize| n.div_ceil(MAX_LEAF) as f64;
                let cost =
                    TRAVERSAL_COST + (acc.surface_area().to_f64() * packets(cnt) + ra * packets(rc)) / area;
                if best.is_none_or(|(c, _, _)| cost < c) {
                    best = Some((cost, axis, i));
                }
            }
        }
        match best {
            // Every centroid coincides: no plane separates them.
            None => (n > MAX_LEAF).then_some((0, n / 2)),
            Some((cost, _, _)) if n <= MAX_LEAF && cost >= 1.0 => None,
            Some((_, axis, last)) => {
                let bin_of = binner(cb.min[axis], cb.max[axis]);
                let mid = partition(items, |it| bin_of(it.centroid[axis]) <= last);
                Some((axis, mid))
            }
        }
    }

    /// Visits the leaves whose boxes the ray meets in `(0, t_max]`, nearer subtrees first.
    /// `visit(k, t_max)` tests the primitives of leaf `k` and returns the new, smaller
    /// `t_max` if it found a nearer hit; boxes entered beyond the current `t_max` are
    /// skipped (a box entered exactly at `t_max` is still visited, so a caller can break
    /// ties at equal distance).
    ///
    /// It runs on the 4-wide collapse of the tree: at each node the ray is tested against
    /// the four children's boxes at once, the ones it enters are stacked nearest on top with
    /// their entry distances, and a stacked subtree that a later hit has moved out of reach
    /// is dropped without another test.
    #[inline]
    pub fn traverse(&self, ray: &Ray<F>, t_max: F, visit: impl FnMut(usize, F) -> Option<F>) {
        const INLINE: usize = 24;
        let need = self.stack_size();
        if need <= INLINE {
            self.traverse_wide(
                self.root,
                &mut [(Child::Empty, F::zero()); INLINE],
                ray,
                t_max,
                visit,
            );
        } else {
            self.traverse_wide(
                self.root,
                &mut vec![(Child::Empty, F::zero()); need],
                ray,
                t_max,
                visit,
            );
        }
    }

    /// The stack entries [`Bvh::traverse`] needs: each wide level stacks at most four
    /// children, one of which is popped at once.
    fn stack_size(&self) -> usize {
        3 * self.wide_depth + 4
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

/// The bin of a centroid coordinate in `[lo, hi]`, `lo < hi`.
fn binner<F: Float>(lo: F, hi: F) -> impl Fn(F) -> usize {
    let scale = lit::<F>(BINS as f64) / (hi - lo);
    move |c: F| ((c - lo) * scale).to_f64().clamp(0.0, (BINS - 1) as f64) as usize
}

/// Splits at the median centroid along the longest axis (a leaf for `MAX_LEAF` or fewer).
fn median_split<F: Float>(items: &mut [Item<F>]) -> Option<(usize, usize)> {
    if items.len() <= MAX_LEAF {
        return None;
    }
    let cb = items.iter().fold(Aabb::empty(), |b, it| {
        b.union(Aabb::new(it.centroid, it.centroid))
    });
    let axis = cb.longest_axis();
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        a.centroid[axis]
            .partial_cmp(&b.centroid[axis])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    Some((axis, mid))
}

/// Moves the items satisfying `left` to the front; returns how many there are.
fn partition<T>(items: &mut [T], left: impl Fn(&T) -> bool) -> usize {
    let mut mid = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(i, mid);
            mid += 1;
        }
    }
    mid
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
        let bvh = Bvh::build(&boxes);
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
        let bvh = Bvh::build(&boxes);
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

    #[test]
    fn empty_and_single() {
        let none = Bvh::<f32>::build(&[]);
        let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
        assert!(!none.any(&ray, f32::INFINITY, |_| true));
        let one = Bvh::build(&[Aabb::new(Vec3::new(-1.0, -1.0, -3.0), Vec3::new(1.0, 1.0, -2.0))]);
        assert_eq!((one.leaf_count(), one.leaf(0)), (1, &[0u32][..]));
        assert!(one.any(&ray, f32::INFINITY, |k| k == 0));
    }
}
