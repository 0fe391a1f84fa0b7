//! Multiple importance sampling: one weight per technique, summing to 1 for every path.

use crate::float::{Float, lit};

/// Veach's power heuristic (β = 2): the weight of a sample drawn with density `p` by one
/// technique when another could have drawn it with density `q`,
///
/// `w = p²/(p² + q²) = 1/(1 + (q/p)²)`,
///
/// written with the ratio so no square overflows (a small far light has a huge `p`). The
/// two weights of a path, `w(p, q)` and `w(q, p)`, sum to 1, which keeps the combined
/// estimate unbiased; each favours the technique that draws the path more often, which
/// keeps it from being noisy where the other one is (Veach 1997, §9.2).
///
/// `w = 0` when `p = 0` (or NaN), `w = 1` when `q = 0`, and `½` when both are infinite.
#[inline]
pub fn power_heuristic<F: Float>(p: F, q: F) -> F {
    if p.is_nan() || p <= F::zero() {
        return F::zero();
    }
    let r = q / p;
    if r.is_nan() {
        return lit(0.5);
    }
    F::one() / (F::one() + r * r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one_and_never_overflow() {
        for (p, q) in [
            (1.0f32, 2.0),
            (3.0, 0.5),
            (1e30, 1e-30),
            (1e-30, 1e30),
            (5.0, 5.0),
        ] {
            let sum = power_heuristic(p, q) + power_heuristic(q, p);
            assert!((sum - 1.0).abs() < 1e-6, "{p} {q}: {sum}");
        }
        assert_eq!(power_heuristic(1.0f64, 2.0), 0.2);
        assert_eq!(power_heuristic(0.0f64, 2.0), 0.0);
        assert_eq!(power_heuristic(2.0f64, 0.0), 1.0);
        assert_eq!(power_heuristic(f64::INFINITY, 1.0), 1.0);
        assert_eq!(power_heuristic(1.0, f64::INFINITY), 0.0);
        assert_eq!(power_heuristic(f64::INFINITY, f64::INFINITY), 0.5);
        assert_eq!(power_heuristic(f64::NAN, 1.0), 0.0);
    }
}
