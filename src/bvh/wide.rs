//! The 4-wide layout the traversal runs on: each node holds the boxes of up to four
//! children side by side (structure of arrays), so one ray is tested against four boxes
//! with the same few instructions per lane, which the compiler turns into SIMD.

use super::{Bvh, Node};
use crate::float::Float;
use crate::ray::Ray;
use crate::vec3::Vec3;

/// What a lane of a wide node points to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Child {
    /// No child: the lane's box is empty and never hit.
    Empty,
    /// Another wide node.
    Node(u32),
    /// Primitives `indices[first..first + count]`.
    Leaf { first: u32, count: u16 },
}

/// Four children's boxes: `min[axis][lane]`, `max[axis][lane]`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Wide<F> {
    min: [[F; 4]; 3],
    max: [[F; 4]; 3],
    child: [Child; 4],
}

/// Collapses the binary tree under binary node `at` into wide nodes appended to `out`;
/// returns the index of the wide node made for `at` (which must be interior).
pub(super) fn collapse<F: Float>(nodes: &[Node<F>], at: usize, out: &mut Vec<Wide<F>>) -> u32 {
    // Open the children of `at`, then repeatedly open the interior child with the largest
    // box (the likeliest to be entered) until there are four.
    let children = |i: usize| {
        let l = nodes[i].offset as usize;
        [l, l + 1]
    };
    let mut lanes: Vec<usize> = children(at).to_vec();
    while lanes.len() < 4 {
        let area = |i: usize| {
            let [lo, hi] = nodes[i].bounds;
            let d = hi - lo;
            (d.x * d.y + d.y * d.z + d.z * d.x).to_f64()
        };
        let open = lanes
            .iter()
            .enumerate()
            .filter(|&(_, &i)| nodes[i].count == 0)
            .max_by(|a, b| area(*a.1).total_cmp(&area(*b.1)));
        let Some((k, &i)) = open else { break };
        lanes.splice(k..=k, children(i));
    }
    let me = out.len();
    let empty = Wide {
        min: [[F::infinity(); 4]; 3],
        max: [[F::neg_infinity(); 4]; 3],
        child: [Child::Empty; 4],
    };
    out.push(empty);
    let mut node = empty;
    for (lane, &i) in lanes.iter().enumerate() {
        let [lo, hi] = nodes[i].bounds;
        for axis in 0..3 {
            node.min[axis][lane] = lo[axis];
            node.max[axis][lane] = hi[axis];
        }
        node.child[lane] = if nodes[i].count > 0 {
            Child::Leaf {
                first: nodes[i].offset,
                count: nodes[i].count,
            }
        } else {
            Child::Node(collapse(nodes, i, out))
        };
    }
    out[me] = node;
    me as u32
}

/// Levels below `root` in the wide tree.
pub(super) fn depth<F>(wide: &[Wide<F>], root: Option<Child>) -> usize {
    match root {
        Some(Child::Node(i)) => {
            1 + wide[i as usize]
                .child
                .iter()
                .map(|&c| depth(wide, Some(c)))
                .max()
                .unwrap_or(0)
        }
        _ => 0,
    }
}

/// A ray prepared for the 4-wide slab test.
struct WideRay<F> {
    origin: [F; 3],
    inv_d: [F; 3],
    neg: [bool; 3],
    grow: F,
}

impl<F: Float> WideRay<F> {
    fn new(ray: &Ray<F>) -> Self {
        let inv: Vec3<F> = ray.direction.map(|d| F::one() / d);
        Self {
            origin: [ray.origin.x, ray.origin.y, ray.origin.z],
            inv_d: [inv.x, inv.y, inv.z],
            neg: [inv.x < F::zero(), inv.y < F::zero(), inv.z < F::zero()],
            grow: F::one() + F::gamma(3) * crate::float::lit(2.0),
        }
    }

    /// The entry distance into each of the node's four boxes, or +∞ where the ray misses
    /// it in `(0, t_max)`. Same slab test as [`crate::aabb::RayBoxTest::entry`], one
    /// axis at a time over the four lanes; `max`/`min` ignore the NaN of a ray lying in
    /// a slab's plane.
    #[inline(always)]
    fn entries(&self, n: &Wide<F>, t_max: F) -> [F; 4] {
        let mut t0 = [F::zero(); 4];
        let mut t1 = [t_max; 4];
        for axis in 0..3 {
            let (near, far) = if self.neg[axis] {
                (&n.max[axis], &n.min[axis])
            } else {
                (&n.min[axis], &n.max[axis])
            };
            let (o, inv) = (self.origin[axis], self.inv_d[axis]);
            for lane in 0..4 {
                t0[lane] = t0[lane].max((near[lane] - o) * inv);
                t1[lane] = t1[lane].min((far[lane] - o) * inv * self.grow);
            }
        }
        let mut out = [F::infinity(); 4];
        for lane in 0..4 {
            if t0[lane] <= t1[lane] {
                out[lane] = t0[lane];
            }
        }
        out
    }
}

impl<F: Float> Bvh<F> {
    /// The wide traversal behind [`Bvh::traverse`]; `stack` holds at least
    /// `3·wide_depth + 1` entries.
    #[inline]
    pub(super) fn traverse_wide(
        &self,
        stack: &mut [(Child, F)],
        ray: &Ray<F>,
        mut t_max: F,
        mut visit: impl FnMut(usize, F) -> Option<F>,
    ) {
        let r = WideRay::new(ray);
        let mut top = 0;
        let mut current = match self.root {
            Some(root) => root,
            None => return,
        };
        loop {
            match current {
                Child::Node(i) => {
                    let n = &self.wide[i as usize];
                    let t = r.entries(n, t_max);
                    // Push the hit lanes so that the stack stays sorted farthest-first among
                    // them (an insertion sort on the stack's top: usually one or two lanes),
                    // and the nearest comes off next.
                    let base = top;
                    for (&child, &tl) in n.child.iter().zip(&t) {
                        if tl < F::infinity() {
                            let mut k = top;
                            while k > base && stack[k - 1].1 < tl {
                                stack[k] = stack[k - 1];
                                k -= 1;
                            }
                            stack[k] = (child, tl);
                            top += 1;
                        }
                    }
                }
                Child::Leaf { first, count } => {
                    let start = first as usize;
                    for &i in &self.indices[start..start + count as usize] {
                        if let Some(t) = visit(i as usize, t_max) {
                            t_max = t;
                        }
                    }
                }
                Child::Empty => {}
            }
            // Pop the next stacked child still within reach.
            loop {
                if top == 0 {
                    return;
                }
                top -= 1;
                let (next, t_entry) = stack[top];
                if t_entry <= t_max {
                    current = next;
                    break;
                }
            }
        }
    }
}
