//! The binned-SAH build of the binary tree, parallel and deterministic: every decision
//! depends on the input alone (never on the number of threads or on scheduling), so any
//! pool gives the same node arrays, bit for bit.
//!
//! Large nodes bin their primitives in fixed-size chunks, each chunk on any thread, and
//! merge the chunks' bins left to right; large subtrees are built on both sides of a
//! `rayon::join`, each into its own arrays, which are concatenated afterwards in the
//! order the sequential build writes them.

mod presplit;
mod split;

use super::Node;
use crate::aabb::Aabb;
use crate::float::Float;
use crate::vec3::Vec3;
use rayon::prelude::*;
use split::split;

/// Primitives from which a subtree's two halves are built as separate tasks; smaller
/// subtrees are built in one go into one set of arrays.
const TASK: usize = 4096;

/// A binary tree's `(nodes, indices, leaves)` as [`super::Bvh`] stores them.
pub(super) type Arrays<F> = (Vec<Node<F>>, Vec<u32>, Vec<(u32, u32)>);

/// The items of the primitives that `prims` yields as `(box, class)`, numbered in that order.
pub(super) fn items<F: Float>(prims: impl IntoIterator<Item = (Aabb<F>, u8)>) -> Vec<Item<F>> {
    prims.into_iter().enumerate().map(Item::new).collect()
}

/// [`items`] from a parallel iterator: the same items, made on any threads.
pub(super) fn items_par<F: Float>(prims: impl IndexedParallelIterator<Item = (Aabb<F>, u8)>) -> Vec<Item<F>> {
    prims.enumerate().map(Item::new).collect()
}

/// The binary tree over `items` ([`items`]; empty for none); no leaf holds two classes,
/// and the leaves are numbered class by class (see [`group_by_class`]). With `triangle`,
/// the triangles it names (`triangle(i)` gives primitive `i`'s vertices) are first cut into
/// pieces ([`presplit::presplit`]), so a triangle may sit in more than one leaf.
pub(super) fn build<F: Float, T>(mut items: Vec<Item<F>>, triangle: Option<T>) -> Arrays<F>
where
    T: Fn(u32) -> Option<[Vec3<F>; 3]>,
{
    if let Some(triangle) = triangle {
        items = presplit::presplit(items, triangle);
    }
    if items.is_empty() {
        return (Vec::new(), Vec::new(), Vec::new());
    }
    let span = fold(&items);
    let tree = subtree(&mut items, 0, span, 0);
    // The partitions left the primitives in leaf order; the items go before the nodes are
    // laid out, so the two are never held at once.
    let indices = items.par_iter().map(|it| it.index).collect();
    let classes: Vec<u8> = items.par_iter().map(|it| it.class).collect();
    drop(items);
    let (mut nodes, mut leaves) = (
        Vec::with_capacity(tree.nodes()),
        Vec::with_capacity(tree.leaves()),
    );
    nodes.push(empty_node());
    tree.flatten(0, &mut nodes, &mut leaves);
    group_by_class(&mut nodes, &mut leaves, &classes);
    (nodes, indices, leaves)
}

/// Renumbers the leaves class by class (every leaf of class 0 first), in the order built
/// within a class, so that a user keeping each class's leaves in an array of its own finds
/// leaf `k`'s from `k` alone. A tree of one class is left as it is.
fn group_by_class<F: Float>(nodes: &mut [Node<F>], leaves: &mut Vec<(u32, u32)>, classes: &[u8]) {
    let class = |leaf: &(u32, u32)| classes[leaf.0 as usize];
    if leaves.windows(2).all(|w| class(&w[0]) <= class(&w[1])) {
        return;
    }
    let mut order: Vec<u32> = (0..leaves.len() as u32).collect();
    order.sort_by_key(|&k| class(&leaves[k as usize]));
    let mut place = vec![0; leaves.len()];
    for (new, &old) in order.iter().enumerate() {
        place[old as usize] = new as u32;
    }
    for node in nodes.iter_mut().filter(|n| n.count > 0) {
        node.offset = place[node.offset as usize];
    }
    *leaves = order.iter().map(|&k| leaves[k as usize]).collect();
}

/// What the build reads of a primitive, copied once into one compact array (32 bytes in
/// f32: the centroid is recomputed, not stored, which saves more memory than time); a
/// piece of a cut triangle is an item of its own, with the triangle's index.
#[derive(Clone, Copy)]
pub(super) struct Item<F> {
    bounds: Aabb<F>,
    index: u32,
    class: u8,
}

impl<F: Float> Item<F> {
    /// Primitive `i`'s item.
    fn new((i, (bounds, class)): (usize, (Aabb<F>, u8))) -> Self {
        Self {
            bounds,
            index: i as u32,
            class,
        }
    }

    #[inline(always)]
    fn centroid(&self) -> Vec3<F> {
        self.bounds.centroid()
    }
}

/// A node's box and the box of its primitives' centroids, handed down by the parent's
/// split so that no node folds over its primitives again.
#[derive(Clone, Copy)]
struct Span<F> {
    bounds: Aabb<F>,
    centroids: Aabb<F>,
}

/// The span of `items` (only where a node's span was not handed down: the root, middle-centroid
/// splits).
fn fold<F: Float>(items: &[Item<F>]) -> Span<F> {
    items.iter().fold(Span::empty(), |s, it| s.add(it))
}

impl<F: Float> Span<F> {
    fn empty() -> Self {
        Self {
            bounds: Aabb::empty(),
            centroids: Aabb::empty(),
        }
    }

    fn add(self, it: &Item<F>) -> Self {
        Self {
            bounds: union(self.bounds, it.bounds),
            centroids: grow(self.centroids, it.centroid()),
        }
    }
}

/// `b` grown to hold the point `p`.
#[inline(always)]
fn grow<F: Float>(b: Aabb<F>, p: Vec3<F>) -> Aabb<F> {
    union(b, Aabb { min: p, max: p })
}

/// [`Aabb::union`] by plain comparisons, one instruction each where `f32::min`'s NaN rule
/// takes three; as there, a NaN in `b` is ignored.
#[inline(always)]
fn union<F: Float>(a: Aabb<F>, b: Aabb<F>) -> Aabb<F> {
    let lo = |a: F, b: F| if b < a { b } else { a };
    let hi = |a: F, b: F| if b > a { b } else { a };
    Aabb {
        min: Vec3::new(lo(a.min.x, b.min.x), lo(a.min.y, b.min.y), lo(a.min.z, b.min.z)),
        max: Vec3::new(hi(a.max.x, b.max.x), hi(a.max.y, b.max.y), hi(a.max.z, b.max.z)),
    }
}

/// The nodes and leaves of a subtree laid out as the sequential build lays out a whole
/// tree (its root first, then its root's descendants), with offsets local to it; leaf
/// ranges index the whole array of primitives.
struct Part<F> {
    nodes: Vec<Node<F>>,
    leaves: Vec<(u32, u32)>,
}

/// A subtree built in parallel: one part, or a split whose halves were built apart.
enum Subtree<F> {
    Part(Part<F>),
    Split {
        bounds: Aabb<F>,
        halves: Box<(Subtree<F>, Subtree<F>)>,
    },
}

/// Builds the subtree over `items`, which sit at `first` in the whole array.
fn subtree<F: Float>(items: &mut [Item<F>], first: usize, span: Span<F>, depth: usize) -> Subtree<F> {
    if items.len() < TASK {
        // Room for the most a subtree can need (`2n − 1` nodes, `n` leaves): grown by
        // doubling, the parts left their old blocks scattered over the heap, resident.
        let mut part = Part {
            nodes: Vec::with_capacity(2 * items.len()),
            leaves: Vec::with_capacity(items.len()),
        };
        part.nodes.push(empty_node());
        part.grow(0, items, first, span, depth);
        return Subtree::Part(part);
    }
    let (mid, left, right) =
        split(items, &span, depth).expect("a node of more than MAX_LEAF primitives splits");
    let (l, r) = items.split_at_mut(mid);
    let halves = rayon::join(
        || subtree(l, first, left, depth + 1),
        || subtree(r, first + mid, right, depth + 1),
    );
    Subtree::Split {
        bounds: span.bounds,
        halves: Box::new(halves),
    }
}

fn empty_node<F: Float>() -> Node<F> {
    Node {
        bounds: Aabb::empty().corners(),
        offset: 0,
        count: 0,
    }
}

impl<F: Float> Part<F> {
    /// Fills the (already allocated) node `me` with the subtree over `items`.
    fn grow(&mut self, me: usize, items: &mut [Item<F>], first: usize, span: Span<F>, depth: usize) {
        self.nodes[me].bounds = span.bounds.corners();
        match split(items, &span, depth) {
            Some((mid, left, right)) => {
                let at = self.nodes.len();
                self.nodes.extend([empty_node(), empty_node()]);
                self.nodes[me].offset = at as u32;
                let (l, r) = items.split_at_mut(mid);
                self.grow(at, l, first, left, depth + 1);
                self.grow(at + 1, r, first + mid, right, depth + 1);
            }
            None => {
                self.nodes[me].offset = self.leaves.len() as u32;
                self.nodes[me].count = items.len() as u16;
                self.leaves.push((first as u32, (first + items.len()) as u32));
            }
        }
    }
}

impl<F: Float> Subtree<F> {
    /// How many nodes [`Subtree::flatten`] lays out, its root included.
    fn nodes(&self) -> usize {
        match self {
            Subtree::Part(part) => part.nodes.len(),
            Subtree::Split { halves, .. } => 1 + halves.0.nodes() + halves.1.nodes(),
        }
    }

    /// How many leaves it holds.
    fn leaves(&self) -> usize {
        match self {
            Subtree::Part(part) => part.leaves.len(),
            Subtree::Split { halves, .. } => halves.0.leaves() + halves.1.leaves(),
        }
    }

    /// Writes this subtree's root into the allocated `nodes[at]` and appends its
    /// descendants and leaves, in the order the sequential build writes them.
    fn flatten(self, at: usize, nodes: &mut Vec<Node<F>>, leaves: &mut Vec<(u32, u32)>) {
        match self {
            Subtree::Part(part) => {
                // Local node `j ≥ 1` lands at `nodes.len() + j - 1`, local leaf `k` at
                // `leaves.len() + k`.
                let (shift, leaf_base) = (nodes.len() as u32 - 1, leaves.len() as u32);
                let place = |n: &Node<F>| Node {
                    offset: n.offset + if n.count > 0 { leaf_base } else { shift },
                    ..*n
                };
                let mut placed = part.nodes.iter().map(place);
                nodes[at] = placed.next().expect("a part holds its root");
                nodes.extend(placed);
                leaves.extend(part.leaves);
            }
            Subtree::Split { bounds, halves } => {
                let children = nodes.len();
                nodes[at] = Node {
                    bounds: bounds.corners(),
                    offset: children as u32,
                    count: 0,
                };
                nodes.extend([empty_node(), empty_node()]);
                let (l, r) = *halves;
                l.flatten(children, nodes, leaves);
                r.flatten(children + 1, nodes, leaves);
            }
        }
    }
}
