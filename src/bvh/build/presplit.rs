//! Spatial splits by pre-splitting: before the build, a triangle whose box is mostly empty (a
//! long or diagonal one, or a large one among small ones) is cut along planes of a fixed
//! grid over the scene into pieces, each a reference to the whole triangle with the box of
//! its part. The binned build then sorts the pieces like any primitive, so a node's box need
//! not hold the whole triangle. A triangle is still tested whole in every leaf it lands in.
//!
//! After Karras & Aila 2013 ("Fast Parallel Construction of High-Quality Bounding Volume
//! Hierarchies", §4): their grid, planes at `min + extent·m/2^l` over the scene's box, and a
//! piece always cut at the coarsest plane crossing it (where the build is likeliest to split).
//! Not their fixed share of cuts (`0.3·N`, handed out by priority), which cuts well-shaped
//! triangles too, to no gain (`docs/PERFORMANCE.md`, "Spatial splits"). Here a piece is worth
//! cutting by how much of its box is empty, its *excess* `A_box − A_ideal` (`A_ideal` is the
//! area its boxes would have if it were cut into infinitely many pieces), and only while that
//! is large against the triangles' own size (the median `A_ideal`); the pieces are cut
//! greedily, the largest excess first, within a budget.

use super::Item;
use crate::aabb::Aabb;
use crate::float::Float;
use crate::vec3::Vec3;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// The most cuts, as a multiple of the triangles: references at most triple. A cap on memory
/// for scenes that would take cuts without end (long needles every way), not reached by
/// most (figures in `docs/PERFORMANCE.md`).
const BUDGET: f64 = 2.0;
/// A piece is cut while its excess is above this many times the median triangle's `A_ideal`:
/// high enough that a scanned model's ordinary triangles are left whole (the values tried are
/// in `docs/PERFORMANCE.md`).
const WORTH: f64 = 16.0;
/// The finest grid level cut at: planes `2^−24` of the scene apart.
const LEVELS: u32 = 24;
/// How far, relative to a triangle's largest coordinate, a piece's box is grown: far more
/// than the rounding of the clipping (done in `f64`) and of the box's conversion to `F`,
/// so the pieces' boxes hold every point of the triangle a ray can hit.
const PAD: f64 = 1.0 / (1u64 << 20) as f64;

/// A box in `f64`, where the clipping is done.
type Box64 = Aabb<f64>;

/// A part of triangle `items[at]`: its box and excess; `seq` orders the pieces of one
/// triangle as they were made.
#[derive(Clone, Copy)]
struct Piece {
    excess: f64,
    at: u32,
    seq: u32,
    bounds: Box64,
}

impl Piece {
    /// The greedy's order: the largest excess first, then the earlier item and piece.
    fn key(&self) -> (f64, std::cmp::Reverse<(u32, u32)>) {
        (self.excess, std::cmp::Reverse((self.at, self.seq)))
    }
}

impl PartialEq for Piece {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Piece {}
impl PartialOrd for Piece {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Piece {
    fn cmp(&self, o: &Self) -> Ordering {
        let (a, b) = (self.key(), o.key());
        a.0.total_cmp(&b.0).then(a.1.cmp(&b.1))
    }
}

/// The references the build sorts for `items`: each triangle (`triangle(index)` is `Some`)
/// worth cutting is replaced by its pieces, every other item is kept; in the items' order,
/// so the result depends on the input alone.
pub(super) fn presplit<F: Float>(
    items: Vec<Item<F>>,
    triangle: impl Fn(u32) -> Option<[Vec3<F>; 3]>,
) -> Vec<Item<F>> {
    let tri = |at: u32| triangle(items[at as usize].index).map(|t| t.map(wide));
    let scene = items
        .iter()
        .fold(Box64::empty(), |b, it| b.union(widen(&it.bounds)));
    let grid = Grid::new(&scene);
    let mut ideals: Vec<f64> = (0..items.len() as u32)
        .filter_map(|at| tri(at).map(|t| ideal(&t)))
        .collect();
    if ideals.is_empty() {
        return items;
    }
    let middle = ideals.len() / 2;
    let threshold = WORTH * *ideals.select_nth_unstable_by(middle, f64::total_cmp).1;
    let budget = (BUDGET * ideals.len() as f64) as usize;
    drop(ideals);
    let mut seq = 0;
    let mut piece = |at: u32, t: &[Vec3<f64>; 3], region: &Box64| {
        seq += 1;
        clip(t, region).map(|(bounds, ideal)| Piece {
            excess: bounds.surface_area() - ideal,
            at,
            seq,
            bounds,
        })
    };
    // A whole triangle is its own piece: its box, no clipping.
    let mut heap: BinaryHeap<Piece> = (0..items.len() as u32)
        .filter_map(|at| {
            let bounds = widen(&items[at as usize].bounds);
            let excess = bounds.surface_area() - ideal(&tri(at)?);
            (excess > threshold).then_some(Piece {
                excess,
                at,
                seq: 0,
                bounds,
            })
        })
        .collect();
    let mut done = Vec::new();
    for _ in 0..budget {
        if heap.peek().is_none_or(|p| p.excess <= threshold) {
            break;
        }
        let p = heap.pop().expect("peeked");
        let t = tri(p.at).expect("only triangles are pieces");
        let Some((axis, at)) = grid.plane(&p.bounds) else {
            done.push(p);
            continue;
        };
        let (mut left, mut right) = (p.bounds, p.bounds);
        left.max = set(left.max, axis, at);
        right.min = set(right.min, axis, at);
        heap.extend(
            [piece(p.at, &t, &left), piece(p.at, &t, &right)]
                .into_iter()
                .flatten(),
        );
    }
    done.extend(heap);
    done.sort_unstable_by_key(|p| (p.at, p.seq));
    let mut out = Vec::with_capacity(items.len() + done.len());
    let mut pieces = done.into_iter().peekable();
    for (at, it) in items.iter().enumerate() {
        if pieces.peek().is_none_or(|p| p.at as usize != at) {
            out.push(*it);
            continue;
        }
        let t = tri(at as u32).expect("only triangles are pieces");
        let pad = PAD
            * t.iter()
                .fold(0.0, |m: f64, v| m.max(v.x.abs()).max(v.y.abs()).max(v.z.abs()));
        while let Some(p) = pieces.next_if(|p| p.at as usize == at) {
            out.push(Item {
                bounds: narrow(&p.bounds, pad, &it.bounds),
                ..*it
            });
        }
    }
    out
}

/// The area of the boxes of a flat polygon cut into infinitely many pieces: twice its
/// projections on the three axis planes, `|N_x| + |N_y| + |N_z|` for the polygon's area
/// vector `N` doubled (`Σ p_i × p_{i+1}`, Newell's formula; for a triangle `(b − a) × (c − a)`).
fn ideal(polygon: &[Vec3<f64>]) -> f64 {
    let n = (0..polygon.len()).fold(Vec3::zero(), |n, i| {
        n + polygon[i].cross(polygon[(i + 1) % polygon.len()])
    });
    n.x.abs() + n.y.abs() + n.z.abs()
}

/// The planes `min + extent·m/2^l` over the scene's box.
struct Grid {
    min: [f64; 3],
    extent: [f64; 3],
}

impl Grid {
    fn new(scene: &Box64) -> Self {
        let axes = |v: Vec3<f64>| [v.x, v.y, v.z];
        let (min, max) = (axes(scene.min), axes(scene.max));
        Self {
            min,
            extent: [0, 1, 2].map(|a| max[a] - min[a]),
        }
    }

    /// The coarsest plane strictly inside `b`, as `(axis, position)`; at equal levels the
    /// first axis. `None` if no plane of level ≤ [`LEVELS`] crosses it.
    fn plane(&self, b: &Box64) -> Option<(usize, f64)> {
        let mut best: Option<(usize, u32, f64)> = None;
        for axis in 0..3 {
            let e = self.extent[axis];
            if e.is_nan() || e <= 0.0 {
                continue;
            }
            let lo = (b.min[axis] - self.min[axis]) / e;
            let coarser = |l: u32| best.is_none_or(|(_, level, _)| l < level);
            // The first plane of level `l` above `b`'s low side: `m/2^l` with
            // `m = ⌊lo·2^l⌋ + 1`, or the next if rounding put it on that side (`b` may have
            // been cut there).
            let found = (1..=LEVELS).take_while(|&l| coarser(l)).find_map(|l| {
                let cells = (1u64 << l) as f64;
                let at = |m: f64| self.min[axis] + e * (m / cells);
                let m = (lo * cells).floor() + 1.0;
                let m = if at(m) <= b.min[axis] { m + 1.0 } else { m };
                (at(m) < b.max[axis]).then(|| (l, at(m)))
            });
            if let Some((level, at)) = found {
                best = Some((axis, level, at));
            }
        }
        best.map(|(axis, _, at)| (axis, at))
    }
}

/// The box and [`ideal`] area of the part of triangle `t` inside `region`
/// (Sutherland–Hodgman clipping against the region's six planes; a point on a plane is
/// kept), `None` if nothing is left.
fn clip(t: &[Vec3<f64>; 3], region: &Box64) -> Option<(Box64, f64)> {
    let mut poly: Vec<Vec3<f64>> = t.to_vec();
    let mut next = Vec::with_capacity(9);
    for axis in 0..3 {
        for (bound, keep_below) in [(region.max[axis], true), (region.min[axis], false)] {
            // Signed distance inside the half-space: ≥ 0 is kept.
            let inside = |p: &Vec3<f64>| {
                if keep_below {
                    bound - p[axis]
                } else {
                    p[axis] - bound
                }
            };
            next.clear();
            for (i, p) in poly.iter().enumerate() {
                let q = &poly[(i + 1) % poly.len()];
                let (dp, dq) = (inside(p), inside(q));
                if dp >= 0.0 {
                    next.push(*p);
                }
                if (dp >= 0.0) != (dq >= 0.0) {
                    let s = dp / (dp - dq);
                    next.push(set(*p + (*q - *p) * s, axis, bound));
                }
            }
            std::mem::swap(&mut poly, &mut next);
            if poly.is_empty() {
                return None;
            }
        }
    }
    Some((bounds(&poly), ideal(&poly)))
}

/// `v` with coordinate `axis` replaced by `value`.
fn set(v: Vec3<f64>, axis: usize, value: f64) -> Vec3<f64> {
    match axis {
        0 => Vec3::new(value, v.y, v.z),
        1 => Vec3::new(v.x, value, v.z),
        _ => Vec3::new(v.x, v.y, value),
    }
}

/// The box of `points`.
fn bounds(points: &[Vec3<f64>]) -> Box64 {
    points
        .iter()
        .fold(Box64::empty(), |b, &p| b.union(Aabb { min: p, max: p }))
}

fn wide<F: Float>(v: Vec3<F>) -> Vec3<f64> {
    Vec3::new(v.x.to_f64(), v.y.to_f64(), v.z.to_f64())
}

fn widen<F: Float>(b: &Aabb<F>) -> Box64 {
    Aabb {
        min: wide(b.min),
        max: wide(b.max),
    }
}

/// `piece` grown by `pad` on every side, in `F`, within the whole triangle's box `whole`
/// (which holds the triangle exactly).
fn narrow<F: Float>(piece: &Box64, pad: f64, whole: &Aabb<F>) -> Aabb<F> {
    let f = |v: Vec3<f64>| Vec3::new(F::from_f64(v.x), F::from_f64(v.y), F::from_f64(v.z));
    Aabb {
        min: f(piece.min - Vec3::splat(pad)).max(whole.min),
        max: f(piece.max + Vec3::splat(pad)).min(whole.max),
    }
}
