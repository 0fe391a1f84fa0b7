//! Where a node of the build splits: the binned SAH sweep, the middle centroid below a depth, and
//! the split by class that keeps leaves of one class.

use super::super::{MAX_LEAF, TRAVERSAL_COST};
use super::{Item, Span, fold, grow, union};
use crate::aabb::Aabb;
use crate::float::{Float, lit};
use rayon::prelude::*;

/// Most centroid bins per axis for the SAH sweep.
const BINS: usize = 16;

/// Bins per axis for a node of `n` primitives: `4 + n/20`, at most [`BINS`] (Embree's
/// count). A small node's split needs few candidates, and each bin costs its sweep whatever
/// it holds.
fn bins_for(n: usize) -> usize {
    (4 + n / 20).min(BINS)
}

/// Depth from which nodes split at the middle centroid instead of by SAH, so the tree's depth,
/// and the traversal stack, stay below `MEDIAN_DEPTH + 32` whatever the input.
const MEDIAN_DEPTH: usize = 40;
/// Primitives from which a node bins in chunks of `CHUNK`, the chunks as separate tasks.
const PAR_BIN: usize = 1 << 15;
/// Primitives per binning chunk of a large node.
const CHUNK: usize = 1 << 13;

/// One bin of the SAH sweep: the union of its primitives' boxes and their number.
#[derive(Clone, Copy)]
struct Bin<F> {
    bounds: Aabb<F>,
    count: u32,
}

/// Maps a centroid coordinate in `[lo, hi]` to its bin; all to bin 0 if `lo = hi` (or
/// either is not finite), which leaves that axis no split.
#[derive(Clone, Copy)]
struct Binner<F> {
    lo: F,
    scale: F,
    /// Bins in use, at most [`BINS`].
    count: usize,
}

impl<F: Float> Binner<F> {
    fn new(lo: F, hi: F, count: usize) -> Self {
        let scale = if hi > lo {
            lit::<F>(count as f64) / (hi - lo)
        } else {
            F::zero()
        };
        Self { lo, scale, count }
    }

    /// `⌊(c − lo)·scale⌋` clamped to the bins (a NaN to bin 0).
    ///
    /// Converted to `u8`, which saturates (below 0 and NaN to 0) by clamping in the float
    /// unit, without a branch: the bins are at most 16, and a conversion to `usize` needs
    /// comparisons and a branch around it.
    #[inline(always)]
    fn bin(&self, c: F) -> usize {
        let x = (c - self.lo) * self.scale;
        usize::from(x.to_f64() as u8).min(self.count - 1)
    }

    /// Whether `c` falls in bin `last` or before: `bin(c) <= last` in one comparison,
    /// for the partition, which asks it of every item.
    ///
    /// For `last` below the last bin the clamp changes nothing, and the conversion to
    /// `u8` (truncation, below 1 and NaN to 0, saturating at 255) gives at most `last`
    /// exactly when `x < last + 1` or `x` is NaN.
    #[inline(always)]
    fn left_of(&self, c: F, last: usize) -> bool {
        debug_assert!(last + 1 < self.count, "a split leaves a bin to the right");
        let x = ((c - self.lo) * self.scale).to_f64();
        x < (last + 1) as f64 || x.is_nan()
    }
}

/// The bins of `items` along the three axes, in one pass.
fn bin<F: Float>(items: &[Item<F>], binners: &[Binner<F>; 3]) -> [[Bin<F>; BINS]; 3] {
    let mut bins = [[Bin {
        bounds: Aabb::empty(),
        count: 0,
    }; BINS]; 3];
    for it in items {
        let c = it.centroid();
        for (axis, bins) in bins.iter_mut().enumerate() {
            let b = &mut bins[binners[axis].bin(c[axis])];
            b.bounds = union(b.bounds, it.bounds);
            b.count += 1;
        }
    }
    bins
}

/// [`bin`] over a large node, in chunks on any threads, the chunks' bins merged left to
/// right so that the merge's order does not depend on the scheduling.
fn bin_in_chunks<F: Float>(items: &[Item<F>], binners: &[Binner<F>; 3]) -> [[Bin<F>; BINS]; 3] {
    let chunks: Vec<_> = items.par_chunks(CHUNK).map(|c| bin(c, binners)).collect();
    let mut all = chunks[0];
    for c in &chunks[1..] {
        for (mine, theirs) in all.iter_mut().zip(c) {
            for (a, b) in mine.iter_mut().zip(theirs) {
                a.bounds = union(a.bounds, b.bounds);
                a.count += b.count;
            }
        }
    }
    all
}

/// The cheapest split found by the sweep.
struct Best<F> {
    cost: f64,
    axis: usize,
    /// Last bin of the left side.
    last: usize,
    left: Aabb<F>,
    right: Aabb<F>,
}

/// The split of `items` (with span `span`, at depth `depth`): partitions `items` in place
/// and returns where the right half starts and the halves' spans, or `None` for a leaf.
///
/// By position ([`split_by_position`]); a node that would be a leaf but holds more than one
/// class is split by class instead (the first item's class to the left), so that every
/// leaf holds one class.
pub(super) fn split<F: Float>(
    items: &mut [Item<F>],
    span: &Span<F>,
    depth: usize,
) -> Option<(usize, Span<F>, Span<F>)> {
    let by_position = split_by_position(items, span, depth);
    let class = items.first()?.class;
    if by_position.is_some() || items.iter().all(|it| it.class == class) {
        return by_position;
    }
    let mut mid = 0;
    for i in 0..items.len() {
        if items[i].class == class {
            items.swap(i, mid);
            mid += 1;
        }
    }
    Some((mid, fold(&items[..mid]), fold(&items[mid..])))
}

/// The split of `items` by the position of their centroids, or `None` for a leaf.
///
/// By SAH above [`MEDIAN_DEPTH`]: centroids are binned along each of the three axes and
/// the cheapest bin boundary wins. Cost of a split: `C_t + (A_L·⌈N_L/4⌉ + A_R·⌈N_R/4⌉)/A`,
/// of a leaf: `⌈N/4⌉` (see [`TRAVERSAL_COST`]).
fn split_by_position<F: Float>(
    items: &mut [Item<F>],
    span: &Span<F>,
    depth: usize,
) -> Option<(usize, Span<F>, Span<F>)> {
    let n = items.len();
    if n <= 1 {
        return None;
    }
    if depth >= MEDIAN_DEPTH {
        return median_split(items);
    }
    let cb = &span.centroids;
    let count = bins_for(n);
    let binners = [0, 1, 2].map(|axis| Binner::new(cb.min[axis], cb.max[axis], count));
    let bins = if n >= PAR_BIN {
        bin_in_chunks(items, &binners)
    } else {
        bin(items, &binners)
    };
    let area = span.bounds.surface_area().to_f64().max(f64::MIN_POSITIVE);
    let mut best: Option<Best<F>> = None;
    for (axis, bins) in bins.iter().enumerate() {
        sweep(axis, &bins[..count], area, &mut best);
    }
    match best {
        // Every centroid coincides: no plane separates them.
        None if n > MAX_LEAF => {
            let mid = n / 2;
            Some((mid, fold(&items[..mid]), fold(&items[mid..])))
        }
        None => None,
        Some(b) if n <= MAX_LEAF && b.cost >= 1.0 => None,
        Some(b) => {
            let binner = binners[b.axis];
            let (mut mid, mut lc, mut rc) = (0, Aabb::empty(), Aabb::empty());
            for i in 0..n {
                let c = items[i].centroid();
                if binner.left_of(c[b.axis], b.last) {
                    lc = grow(lc, c);
                    items.swap(i, mid);
                    mid += 1;
                } else {
                    rc = grow(rc, c);
                }
            }
            let half = |bounds, centroids| Span { bounds, centroids };
            Some((mid, half(b.left, lc), half(b.right, rc)))
        }
    }
}

/// Updates `best` with the cheapest boundary between the bins of `axis`.
///
/// Only boundaries right after a non-empty bin, with primitives on both sides, are
/// costed: one after an empty bin costs what the boundary before it costs, and the earlier
/// boundary wins a tie, so skipping it changes nothing.
fn sweep<F: Float>(axis: usize, bins: &[Bin<F>], area: f64, best: &mut Option<Best<F>>) {
    // From the right for the right-hand boxes and counts, then from the left.
    let mut right = [(Aabb::empty(), 0u32); BINS];
    let (mut acc, mut cnt) = (Aabb::empty(), 0u32);
    for j in (1..bins.len()).rev() {
        acc = union(acc, bins[j].bounds);
        cnt += bins[j].count;
        right[j] = (acc, cnt);
    }
    let packets = |n: u32| n.div_ceil(MAX_LEAF as u32) as f64;
    let (mut acc, mut cnt) = (Aabb::empty(), 0u32);
    for j in 0..bins.len() - 1 {
        acc = union(acc, bins[j].bounds);
        cnt += bins[j].count;
        let (rb, rc) = right[j + 1];
        if bins[j].count == 0 || rc == 0 {
            continue;
        }
        let cost = TRAVERSAL_COST + (full_area(acc) * packets(cnt) + full_area(rb) * packets(rc)) / area;
        if best.as_ref().is_none_or(|b| cost < b.cost) {
            *best = Some(Best {
                cost,
                axis,
                last: j,
                left: acc,
                right: rb,
            });
        }
    }
}

/// [`Aabb::surface_area`] of a box known to hold something, without its test for the empty
/// box: the same value.
#[inline(always)]
fn full_area<F: Float>(b: Aabb<F>) -> f64 {
    let d = b.max - b.min;
    ((d.x * d.y + d.y * d.z + d.z * d.x) * lit::<F>(2.0)).to_f64()
}

/// Splits at the middle centroid (half the items on each side) along the longest axis (a
/// leaf for `MAX_LEAF` or fewer).
fn median_split<F: Float>(items: &mut [Item<F>]) -> Option<(usize, Span<F>, Span<F>)> {
    if items.len() <= MAX_LEAF {
        return None;
    }
    let axis = fold(items).centroids.longest_axis();
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        a.centroid()[axis]
            .partial_cmp(&b.centroid()[axis])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    Some((mid, fold(&items[..mid]), fold(&items[mid..])))
}

#[cfg(test)]
mod tests {
    use super::Binner;

    /// `left_of` answers as `bin(c) <= last` for every split a sweep can choose, at the
    /// bins' edges, between them, outside the range and for NaN.
    #[test]
    fn left_of_agrees_with_the_bins() {
        let binner = Binner::<f32>::new(-3.0, 5.0, 16);
        let edge = |k: i32| -3.0 + k as f32 * 0.5;
        let mut values = vec![f32::NAN, f32::NEG_INFINITY, f32::INFINITY, -1e30, 1e30];
        for k in -2..=18 {
            let e = edge(k);
            values.extend([e, e.next_down(), e.next_up(), e + 0.25]);
        }
        for last in 0..15 {
            for &c in &values {
                assert_eq!(
                    binner.left_of(c, last),
                    binner.bin(c) <= last,
                    "c = {c}, last = {last}"
                );
            }
        }
    }
}
