//! The wide layout the traversal runs on: each node holds the boxes of up to eight children
//! (`f32`) or four (`f64`, [`Float::Node`]) side by side (structure of arrays), so one ray is
//! tested against all of them with the same few instructions per lane, which the compiler
//! turns into SIMD.

use super::{Bvh, Node};
use crate::aabb::{SlabRay, slab_test};
use crate::float::{Float, Lanes};

/// Children of a wide node: eight for `f32`, four for `f64` ([`Float::Node`]).
#[inline(always)]
pub(super) fn width<F: Float>() -> usize {
    <F::Node<u8> as Lanes<u8>>::N
}

/// One face of each of a node's boxes, per axis: the near or the far ones.
pub(super) type Faces<F> = [<F as Float>::Node<F>; 3];

/// What a lane of a wide node points to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Child {
    /// No child: the lane's box is empty and never hit.
    Empty,
    /// Another wide node.
    Node(u32),
    /// Leaf number `k` of the hierarchy.
    Leaf(u32),
}

/// The children's boxes, one set of lanes per side and axis: `sides[0][axis][lane]` is the
/// low face, `sides[1][axis][lane]` the high one.
///
/// Aligned to a cache line, so that a node of 256 bytes (f32) spans four lines, not five.
#[derive(Clone, Copy, Debug)]
#[repr(align(64))]
pub(super) struct Wide<F: Float> {
    sides: [[F::Node<F>; 3]; 2],
    child: F::Node<Child>,
}

impl<F: Float> Wide<F> {
    /// The boxes' faces as a ray of direction octant `octant` (bit `a` set where
    /// the direction's axis `a` is negative) meets them, per axis: `(near, far)`.
    ///
    /// The sides are picked by index, not by branch: the octant changes from stream to
    /// stream, and a branch on it mispredicted (cachegrind, `random_spheres`).
    #[inline(always)]
    pub(super) fn faces(&self, octant: usize) -> (Faces<F>, Faces<F>) {
        let side = |axis: usize| (octant >> axis) & 1;
        (
            std::array::from_fn(|axis| self.sides[side(axis)][axis]),
            std::array::from_fn(|axis| self.sides[side(axis) ^ 1][axis]),
        )
    }

    /// What lane `lane` points to.
    #[inline(always)]
    pub(super) fn child(&self, lane: usize) -> Child {
        self.child[lane]
    }

    /// For each direction octant (bit `a` set where the direction's axis `a` is
    /// negative), the node's lanes near to far along the octant's diagonal: by the
    /// centres of their boxes projected on it, empty lanes last.
    pub(super) fn orders(&self) -> [F::Node<u8>; 8] {
        // The centres times two: the same order, and each made once, not once a comparison.
        let centres = F::Node::<[f64; 3]>::from_fn(|lane| {
            std::array::from_fn(|axis| (self.sides[0][axis][lane] + self.sides[1][axis][lane]).to_f64())
        });
        std::array::from_fn(|octant| {
            let keys = F::Node::<f64>::from_fn(|lane| {
                if self.child[lane] == Child::Empty {
                    return f64::INFINITY;
                }
                (0..3)
                    .map(|axis| match octant & (1 << axis) {
                        0 => centres[lane][axis],
                        _ => -centres[lane][axis],
                    })
                    .sum()
            });
            let mut lanes = F::Node::<u8>::from_fn(|k| k as u8);
            lanes
                .as_mut()
                .sort_by(|&a, &b| keys[usize::from(a)].total_cmp(&keys[usize::from(b)]));
            lanes
        })
    }
}

/// Collapses the binary tree under binary node `at` into wide nodes appended to `out`;
/// returns the index of the wide node made for `at` (which must be interior).
pub(super) fn collapse<F: Float>(nodes: &[Node<F>], at: usize, out: &mut Vec<Wide<F>>) -> u32 {
    // Open the children of `at`, then repeatedly open the interior child with the largest
    // box (the likeliest to be entered) until the node is full.
    let children = |i: usize| {
        let l = nodes[i].offset as usize;
        [l, l + 1]
    };
    let (mut lanes, mut len) = (F::Node::<usize>::from_fn(|_| 0), 2);
    let lanes = lanes.as_mut();
    lanes[..2].copy_from_slice(&children(at));
    while len < width::<F>() {
        let area = |i: usize| {
            let [lo, hi] = nodes[i].bounds;
            let d = hi - lo;
            (d.x * d.y + d.y * d.z + d.z * d.x).to_f64()
        };
        let open = lanes[..len]
            .iter()
            .enumerate()
            .filter(|&(_, &i)| nodes[i].count == 0)
            .max_by(|a, b| area(*a.1).total_cmp(&area(*b.1)));
        let Some((k, &i)) = open else { break };
        // Lane `k` gives way to the two children, the lanes after it move up one.
        lanes.copy_within(k + 1..len, k + 2);
        lanes[k..k + 2].copy_from_slice(&children(i));
        len += 1;
    }
    let me = out.len();
    let empty = Wide {
        sides: [
            [Lanes::from_fn(|_| F::infinity()); 3],
            [Lanes::from_fn(|_| F::neg_infinity()); 3],
        ],
        child: Lanes::from_fn(|_| Child::Empty),
    };
    out.push(empty);
    let mut node = empty;
    for (lane, &i) in lanes[..len].iter().enumerate() {
        let [lo, hi] = nodes[i].bounds;
        for axis in 0..3 {
            node.sides[0][axis][lane] = lo[axis];
            node.sides[1][axis][lane] = hi[axis];
        }
        node.child[lane] = if nodes[i].count > 0 {
            Child::Leaf(nodes[i].offset)
        } else {
            Child::Node(collapse(nodes, i, out))
        };
    }
    out[me] = node;
    me as u32
}

/// Levels below `root` in the wide tree.
pub(super) fn depth<F: Float>(wide: &[Wide<F>], root: Option<Child>) -> usize {
    match root {
        Some(Child::Node(i)) => {
            1 + wide[i as usize]
                .child
                .as_ref()
                .iter()
                .map(|&c| depth(wide, Some(c)))
                .max()
                .unwrap_or(0)
        }
        _ => 0,
    }
}

/// The entry distance into each of node `n`'s boxes, and the mask of the boxes the ray
/// `r` (of direction octant `octant`) meets in `(0, t_max]`: [`slab_test`]. With `PAD`,
/// every box is first grown by the pad whose near-face shift (per axis, toward the ray's
/// origin) is `shift`: the far faces move the other way.
#[inline(always)]
fn entries<F: Float, const PAD: bool>(
    r: &SlabRay<F>,
    octant: usize,
    n: &Wide<F>,
    t_max: F,
    shift: &[F; 3],
) -> (F::Node<F>, u32) {
    let (mut near, mut far) = n.faces(octant);
    if PAD {
        for axis in 0..3 {
            near[axis] = Lanes::from_fn(|k| near[axis][k] + shift[axis]);
            far[axis] = Lanes::from_fn(|k| far[axis][k] - shift[axis]);
        }
    }
    let (t0, t1) = slab_test(&near, &far, r, t_max);
    (t0, mask_le::<F, _>(&t0, &t1))
}

/// The bits `k` where `a[k] ≤ b[k]`.
#[inline(always)]
fn mask_le<F: Float, L: Lanes<F>>(a: &L, b: &L) -> u32 {
    (0..L::N).fold(0, |m, k| m | (u32::from(a[k] <= b[k]) << k))
}

impl<F: Float> Bvh<F> {
    /// The wide traversal behind [`Bvh::traverse`] of the prepared ray `r`, from the
    /// subtree `start` (the root for the whole tree); `stack` holds at least
    /// `3·wide_depth + 1` entries. With `PAD`, every box is grown by `pad` on every side
    /// ([`Bvh::traverse_padded`]).
    #[inline]
    pub(super) fn traverse_wide<const PAD: bool>(
        &self,
        start: Option<Child>,
        stack: &mut [(Child, F)],
        r: &SlabRay<F>,
        mut t_max: F,
        pad: F,
        mut visit: impl FnMut(usize, F) -> Option<F>,
    ) {
        let octant = r.octant();
        // Toward the origin: down the axis where the direction is positive (the near face
        // is the low one).
        let shift = [0, 1, 2].map(|axis| if r.negative(axis) { pad } else { -pad });
        let mut top = 0;
        let mut current = match start {
            Some(start) => start,
            None => return,
        };
        loop {
            match current {
                Child::Node(i) => {
                    let n = &self.wide[i as usize];
                    let (t, mut entered) = entries::<F, PAD>(r, octant, n, t_max, &shift);
                    if entered.count_ones() == 1 {
                        // One child entered (the common case): go straight down.
                        current = n.child[entered.trailing_zeros() as usize];
                        continue;
                    }
                    // Push the entered lanes so that the stack stays sorted farthest-first
                    // among them (an insertion sort on the stack's top) and the nearest
                    // comes off next.
                    let base = top;
                    while entered != 0 {
                        let lane = entered.trailing_zeros() as usize;
                        entered &= entered - 1;
                        let tl = t[lane];
                        let mut k = top;
                        while k > base && stack[k - 1].1 < tl {
                            stack[k] = stack[k - 1];
                            k -= 1;
                        }
                        stack[k] = (n.child[lane], tl);
                        top += 1;
                    }
                }
                Child::Leaf(k) => {
                    if let Some(t) = visit(k as usize, t_max) {
                        t_max = t;
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
