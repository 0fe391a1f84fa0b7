//! A bounding volume hierarchy: binned surface-area-heuristic build, flat array layout,
//! ordered stack traversal. It only indexes primitives by their boxes; the scene owns
//! the primitives and tests them in the callbacks.

use crate::aabb::Aabb;
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::vec3::Vec3;

/// Most primitives a leaf may hold.
const MAX_LEAF: usize = 4;
/// Centroid bins per axis for the SAH sweep.
const BINS: usize = 12;
/// Depth from which nodes split at the median instead of by SAH, so the tree's depth,
/// and the traversal stack, stay below `MEDIAN_DEPTH + 32` whatever the input.
const MEDIAN_DEPTH: usize = 40;
/// Traversal stack size: deeper than any tree [`Bvh::build`] makes.
const STACK: usize = MEDIAN_DEPTH + 34;
/// Cost of visiting a node, relative to one primitive test (pbrt uses ⅛–1; this was
/// measured on the random-spheres scene, where it hardly matters between ⅛ and ½).
const TRAVERSAL_COST: f64 = 0.25;

/// One node of the flattened tree. An interior node's left child follows it directly;
/// `offset` is its right child. A leaf holds `indices[offset..offset + count]`.
#[derive(Clone, Copy, Debug)]
struct Node<F> {
    bounds: Aabb<F>,
    offset: u32,
    count: u16,
    axis: u8,
}

/// A bounding volume hierarchy over primitives `0..n` given by their boxes.
#[derive(Clone, Debug)]
pub struct Bvh<F> {
    nodes: Vec<Node<F>>,
    indices: Vec<u32>,
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
        };
        if !items.is_empty() {
            bvh.build_node(&mut items, 0);
        }
        bvh
    }

    /// Number of nodes (for tests and reports).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    fn build_node(&mut self, items: &mut [Item<F>], depth: usize) -> usize {
        let bounds = items.iter().fold(Aabb::empty(), |b, it| b.union(it.bounds));
        let me = self.nodes.len();
        self.nodes.push(Node {
            bounds,
            offset: 0,
            count: 0,
            axis: 0,
        });
        let split = if depth < MEDIAN_DEPTH {
            self.split(items, &bounds)
        } else {
            median_split(items)
        };
        match split {
            Some((axis, mid)) => {
                self.build_node(&mut items[..mid], depth + 1);
                let right = self.build_node(&mut items[mid..], depth + 1);
                self.nodes[me].offset = right as u32;
                self.nodes[me].axis = axis as u8;
            }
            None => {
                self.nodes[me].offset = self.indices.len() as u32;
                self.nodes[me].count = items.len() as u16;
                self.indices.extend(items.iter().map(|it| it.index));
            }
        }
        me
    }

    /// The SAH split `(axis, mid)` partitioning `items` in place, or `None` for a leaf.
    ///
    /// Cost of a split: `C_t + (A_L·N_L + A_R·N_R)/A`, of a leaf: `N` (MacDonald & Booth).
    fn split(&self, items: &mut [Item<F>], bounds: &Aabb<F>) -> Option<(usize, usize)> {
        let n = items.len();
        if n <= 1 {
            return None;
        }
        let cb = items.iter().fold(Aabb::empty(), |b, it| {
            b.union(Aabb::new(it.centroid, it.centroid))
        });
        let axis = cb.longest_axis();
        let (lo, hi) = (cb.min[axis], cb.max[axis]);
        if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
            // All centroids coincide: no split can separate them.
            return (n > MAX_LEAF).then_some((axis, n / 2));
        }
        let scale = lit::<F>(BINS as f64) / (hi - lo);
        let bin_of = |c: F| ((c - lo) * scale).to_f64().clamp(0.0, (BINS - 1) as f64) as usize;
        let mut bins = [(Aabb::empty(), 0usize); BINS];
        for it in items.iter() {
            let b = &mut bins[bin_of(it.centroid[axis])];
            b.0 = b.0.union(it.bounds);
            b.1 += 1;
        }
        // Sweep from the right to get the right-hand areas, then from the left.
        let mut right_area = [0.0f64; BINS];
        let (mut acc, mut cnt) = (Aabb::empty(), 0usize);
        let mut right_count = [0usize; BINS];
        for i in (1..BINS).rev() {
            acc = acc.union(bins[i].0);
            cnt += bins[i].1;
            right_area[i] = acc.surface_area().to_f64();
            right_count[i] = cnt;
        }
        let area = bounds.surface_area().to_f64().max(f64::MIN_POSITIVE);
        let (mut best, mut best_cost) = (0, f64::INFINITY);
        let (mut acc, mut cnt) = (Aabb::empty(), 0usize);
        for i in 0..BINS - 1 {
            acc = acc.union(bins[i].0);
            cnt += bins[i].1;
            let cost = TRAVERSAL_COST
                + (acc.surface_area().to_f64() * cnt as f64 + right_area[i + 1] * right_count[i + 1] as f64)
                    / area;
            if cnt > 0 && right_count[i + 1] > 0 && cost < best_cost {
                best = i;
                best_cost = cost;
            }
        }
        if n <= MAX_LEAF && best_cost >= n as f64 {
            return None;
        }
        if !best_cost.is_finite() {
            return (n > MAX_LEAF).then_some((axis, n / 2));
        }
        let mid = partition(items, |it| bin_of(it.centroid[axis]) <= best);
        Some((axis, mid))
    }

    /// Visits the primitives whose boxes the ray meets in `(0, t_max)`, nearer subtrees
    /// first. `visit(i, t_max)` tests primitive `i` and returns the new, smaller `t_max`
    /// if it found a nearer hit; boxes beyond the current `t_max` are skipped.
    #[inline]
    pub fn traverse(&self, ray: &Ray<F>, mut t_max: F, mut visit: impl FnMut(usize, F) -> Option<F>) {
        if self.nodes.is_empty() {
            return;
        }
        let inv_d = ray.direction.map(|d| F::one() / d);
        let neg = [inv_d.x < F::zero(), inv_d.y < F::zero(), inv_d.z < F::zero()];
        let mut stack = [0u32; STACK];
        let mut top = 0;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.bounds.hit(ray, inv_d, t_max) {
                if n.count > 0 {
                    let start = n.offset as usize;
                    for &i in &self.indices[start..start + n.count as usize] {
                        if let Some(t) = visit(i as usize, t_max) {
                            t_max = t;
                        }
                    }
                } else if neg[n.axis as usize] {
                    stack[top] = node as u32 + 1;
                    top += 1;
                    node = n.offset as usize;
                    continue;
                } else {
                    stack[top] = n.offset;
                    top += 1;
                    node += 1;
                    continue;
                }
            }
            if top == 0 {
                return;
            }
            top -= 1;
            node = stack[top] as usize;
        }
    }

    /// Whether `test(i)` is true for some primitive whose box the ray meets in
    /// `(0, t_max)`; stops at the first.
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
            let inv = d.map(|x| 1.0 / x);
            let mut want: Vec<usize> = (0..boxes.len())
                .filter(|&i| boxes[i].hit(&ray, inv, f64::INFINITY))
                .collect();
            let mut got = Vec::new();
            bvh.traverse(&ray, f64::INFINITY, |i, _| {
                got.push(i);
                None
            });
            got.sort();
            want.sort();
            assert_eq!(got, want);
            assert_eq!(bvh.any(&ray, f64::INFINITY, |_| true), !want.is_empty());
        }
    }

    #[test]
    fn empty_and_single() {
        let none = Bvh::<f32>::build(&[]);
        let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
        assert!(!none.any(&ray, f32::INFINITY, |_| true));
        let one = Bvh::build(&[Aabb::new(Vec3::new(-1.0, -1.0, -3.0), Vec3::new(1.0, 1.0, -2.0))]);
        assert!(one.any(&ray, f32::INFINITY, |i| i == 0));
    }
}
