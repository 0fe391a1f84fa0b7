//! How many samples each pixel takes in the next round.

/// The most a pixel's sample count grows in one round: it doubles. A pixel never commits
/// to more new samples than the estimate it has was made from.
const MOST_GROWTH: f64 = 2.0;

/// The least it grows when it goes on at all, a quarter: a pixel just short of its target
/// does not creep towards it a few samples a round.
const LEAST_GROWTH: f64 = 1.25;

/// The samples a pixel with `n` samples and estimated error `error` takes next to reach
/// `target`, at most `max_spp` in all; 0 once it has met the target or the cap.
///
/// The standard error of a mean falls as `1/√n`, so the pixel needs about
/// `n' = n·(error/target)²` samples in all; it takes that many, within
/// `[1.25 n, 2 n]`. The answer depends on this pixel's numbers only.
#[must_use]
pub(super) fn toward_target(n: u32, error: f64, target: f64, max_spp: u32) -> u32 {
    if error <= target || n >= max_spp {
        return 0;
    }
    let nf = f64::from(n);
    let need = nf * (error / target).powi(2);
    // NaN (a broken material's sample) compares false: the largest step.
    let total = if need.is_nan() {
        nf * MOST_GROWTH
    } else {
        need.clamp(nf * LEAST_GROWTH, nf * MOST_GROWTH)
    };
    // The ceiling of a value at most 2·u32::MAX fits in u64.
    let total = (total.ceil() as u64).min(u64::from(max_spp)) as u32;
    total.saturating_sub(n).max(1)
}

/// One pixel as the time budget's allocation sees it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Candidate {
    /// Samples taken.
    pub n: u32,
    /// The per-sample relative deviation ([`Estimate::deviation`](super::stats::Estimate)).
    pub deviation: f64,
    /// What a sample costs, in rays (at least 1).
    pub cost: f64,
    /// The most samples it may take next (0 once it has met the target or the cap).
    pub room: u32,
}

/// Shares about `budget` new samples among `pixels`, writing each one's share into
/// `next`: a pixel's total grows to `λ·v/√c` (`v` its deviation, `c` its cost; never
/// shrinks, at most by its room), `λ` chosen by bisection so the shares add up to the
/// budget, or to all the room there is if that is less.
///
/// Why `n ∝ v/√c`: a pixel with per-sample relative deviation `v` has squared relative
/// error `v²/n` and its `n` samples take time `∝ c·n`, so for a given time the sum
/// `Σ v²/n` is least when every pixel's gain per unit of time, `v²/(c·n²)`, is the same,
/// that is when `n ∝ v/√c`. Each round moves the totals towards that allocation, so the
/// time goes first where it lowers the error most.
pub(super) fn share(pixels: &[Candidate], budget: u64, next: &mut [u32]) {
    // `(v/√c, n, room)` once: the bisection below passes over every pixel sixty times,
    // so nothing in its loop divides or takes a root.
    let pixels: Vec<[f64; 3]> = pixels
        .iter()
        .map(|p| {
            [
                p.deviation / p.cost.max(1.0).sqrt(),
                f64::from(p.n),
                f64::from(p.room),
            ]
        })
        .collect();
    // `⌈λ·v/√c⌉ − n` within `[0, room]`, rounded up by a cast (`f64::ceil` is a call
    // where the target has no rounding instruction). NaN casts to 0: it takes nothing.
    let take = |lambda: f64, &[w, n, room]: &[f64; 3]| -> u64 {
        let x = (lambda * w - n).clamp(0.0, room);
        let floor = x as u64;
        floor + u64::from((floor as f64) < x)
    };
    let total = |lambda: f64| -> u64 { pixels.iter().map(|p| take(lambda, p)).sum() };
    // Large enough for every pixel with any deviation to fill its room.
    let mut hi = pixels
        .iter()
        .filter(|&&[w, _, room]| w > 0.0 && room > 0.0)
        .map(|&[w, n, room]| (n + room) / w)
        .fold(0.0f64, f64::max);
    let mut lo = 0.0f64;
    if total(hi) > budget {
        // Each halving is a pass over every pixel: stop once the shares come within
        // 1/256 of the budget (a round that much short costs nothing), or after sixty,
        // λ then within 2⁻⁶⁰ of the answer.
        let enough = budget - budget / 256;
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            let shares = total(mid);
            if shares > budget {
                hi = mid;
            } else {
                lo = mid;
                if shares >= enough {
                    break;
                }
            }
        }
        hi = lo;
    }
    for (slot, p) in next.iter_mut().zip(&pixels) {
        // At most the room, a `u32`.
        *slot = take(hi, p) as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pixel_takes_what_it_needs_within_the_growth_bounds() {
        assert_eq!(toward_target(32, 0.009, 0.01, 4096), 0);
        assert_eq!(toward_target(4096, 0.5, 0.01, 4096), 0);
        // Needs (0.011/0.01)² = 1.21 times as many: at least a quarter more.
        assert_eq!(toward_target(32, 0.011, 0.01, 4096), 8);
        // Needs 2.25 times as many: at most twice.
        assert_eq!(toward_target(32, 0.015, 0.01, 4096), 32);
        // Needs 1.69 times: 54.08 → 55 in all.
        assert_eq!(toward_target(32, 0.013, 0.01, 4096), 23);
        // Never past the cap.
        assert_eq!(toward_target(3000, 1.0, 0.01, 4096), 1096);
        assert_eq!(toward_target(32, f64::NAN, 0.01, 4096), 32);
        assert_eq!(toward_target(32, f64::INFINITY, 0.01, 4096), 32);
    }

    #[test]
    fn the_budget_goes_where_the_deviation_is() {
        let p = |n, deviation, room| Candidate {
            n,
            deviation,
            cost: 1.0,
            room,
        };
        let pixels = [p(32, 1.0, 32), p(32, 4.0, 32), p(32, 0.0, 32), p(32, 2.0, 0)];
        let mut next = [0; 4];
        share(&pixels, 24, &mut next);
        assert_eq!(next, [0, 24, 0, 0]);
        // More than the room there is: everyone with a deviation fills its room.
        share(&pixels, 1000, &mut next);
        assert_eq!(next, [32, 32, 0, 0]);
        // Totals end in proportion to the deviations where the room allows it.
        let pixels = [p(16, 1.0, 1000), p(16, 3.0, 1000)];
        share(&pixels, 128, &mut next[..2]);
        let totals = [16 + next[0], 16 + next[1]];
        assert!(next[0] + next[1] <= 128 && next[0] + next[1] >= 126, "{next:?}");
        assert!(
            (f64::from(totals[1]) / f64::from(totals[0]) - 3.0).abs() < 0.1,
            "{totals:?}"
        );
    }
}
