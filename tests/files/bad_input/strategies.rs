//! Strategies: scalars, vectors, colours, triangles, sizes and look-at inputs that break validation.

use proptest::prelude::*;
use raytrace::{Float, Vec3};

/// Values that break naive validation: NaN, ±∞, ±0, ±1, the extremes of `F`, the smallest
/// normal and subnormal values, neighbours of 0 and 1, `√max` and `√min_positive` (where
/// squares overflow and underflow), and the field-of-view limits.
pub(crate) fn specials<F: Float>() -> Vec<F> {
    let tiny = F::min_positive_value();
    let lit = F::from_f64;
    vec![
        F::nan(),
        F::infinity(),
        F::neg_infinity(),
        F::zero(),
        -F::zero(),
        F::one(),
        -F::one(),
        F::max_value(),
        F::min_value(),
        tiny,
        -tiny,
        F::zero().next_up(),
        F::zero().next_down(),
        F::one().next_up(),
        F::one().next_down(),
        F::epsilon(),
        F::max_value().sqrt(),
        F::max_value().sqrt().next_up(),
        tiny.sqrt(),
        tiny.sqrt().next_down(),
        lit(0.5),
        lit(180.0),
        lit(180.0).next_down(),
        lit(-3.5),
    ]
}

/// Any scalar: specials, any `f64` rounded to `F` (every class: NaN, ∞, subnormal, …),
/// ordinary values in `[−4, 4]`, and signed magnitudes log-uniform over the whole range
/// of `F` (and a little beyond, where they round to 0 or ∞).
pub(crate) fn scalar<F: Float>() -> impl Strategy<Value = F> {
    let lo = F::zero().next_up().to_f64().log10() - 2.0;
    let hi = F::max_value().to_f64().log10() + 1.0;
    prop_oneof![
        3 => prop::sample::select(specials::<F>()),
        2 => any::<f64>().prop_map(F::from_f64),
        3 => (-4.0f64..4.0).prop_map(F::from_f64),
        3 => (any::<bool>(), lo..hi).prop_map(|(neg, e)| F::from_f64(if neg { -1.0 } else { 1.0 } * 10f64.powf(e))),
    ]
}

/// A vector: ordinary (all components in `[−4, 4]`), or any three scalars.
pub(crate) fn vector<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    let ordinary = [-4.0f64..4.0, -4.0f64..4.0, -4.0f64..4.0].prop_map(|[x, y, z]| Vec3::from_f64(x, y, z));
    let any3 = [scalar::<F>(), scalar::<F>(), scalar::<F>()].prop_map(|[x, y, z]| Vec3::new(x, y, z));
    prop_oneof![1 => ordinary, 2 => any3]
}

/// A colour channel near `[0, 1]`: uniform in it, its ends and their neighbours, or any
/// scalar.
pub(crate) fn channel<F: Float>() -> impl Strategy<Value = F> {
    let edges = vec![
        F::zero(),
        -F::zero(),
        F::one(),
        F::one().next_up(),
        F::one().next_down(),
        F::zero().next_down(),
    ];
    prop_oneof![
        2 => (0.0f64..=1.0).prop_map(F::from_f64),
        2 => prop::sample::select(edges),
        1 => (0.0f64..100.0).prop_map(F::from_f64),
        2 => scalar::<F>(),
    ]
}

pub(crate) fn color<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    [channel::<F>(), channel::<F>(), channel::<F>()].prop_map(|[x, y, z]| Vec3::new(x, y, z))
}

/// A vector scaled by `10^U` over the range of `F`: tiny to huge but usually finite.
pub(crate) fn magnitude<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    let lo = F::zero().next_up().to_f64().log10() - 1.0;
    let hi = F::max_value().to_f64().log10() + 0.5;
    (crate::common::unit_f64(), lo..hi).prop_map(|(u, e)| {
        let s = 10f64.powf(e);
        Vec3::from_f64(u[0] * s, u[1] * s, u[2] * s)
    })
}

/// Triangles: three arbitrary vectors; a vertex repeated; nearly collinear (`C` on the
/// line `AB` moved off it by `10^U(−20, 0)·|B − A|`); ordinary triangles scaled over the
/// whole range of `F`; and long thin ones (an edge of length `10^U(h − 2, 2h − 0.5)`, the
/// other `10^U(−h, 0)`, `h = log₁₀√max`).
pub(crate) fn triangle_vertices<F: Float>() -> impl Strategy<Value = [Vec3<F>; 3]> {
    let any = [vector::<F>(), vector::<F>(), vector::<F>()];
    let repeated = (vector::<F>(), vector::<F>(), 0usize..3).prop_map(|(a, b, i)| match i {
        0 => [a, a, b],
        1 => [a, b, a],
        _ => [b, a, a],
    });
    let collinear = (
        [-4.0f64..4.0, -4.0f64..4.0, -4.0f64..4.0],
        crate::common::unit_f64(),
        -3.0f64..3.0,
        crate::common::unit_f64(),
        -20.0f64..0.0,
    )
        .prop_map(|(a, dir, k, off, e)| {
            let b: [f64; 3] = std::array::from_fn(|i| a[i] + dir[i]);
            let c: [f64; 3] = std::array::from_fn(|i| a[i] + k * dir[i] + 10f64.powf(e) * off[i]);
            [a, b, c].map(|p| Vec3::from_f64(p[0], p[1], p[2]))
        });
    let scaled = (
        [
            crate::common::unit_f64(),
            crate::common::unit_f64(),
            crate::common::unit_f64(),
        ],
        magnitude::<F>(),
        (F::zero().next_up().to_f64().log10() - 1.0)..(F::max_value().to_f64().log10() + 0.5),
    )
        .prop_map(|(u, centre, e)| {
            let s = 10f64.powf(e);
            u.map(|p| centre + Vec3::from_f64(p[0] * s, p[1] * s, p[2] * s))
        });
    // Long and thin: an edge up to the largest finite length, the other short enough that
    // |u×v| may still fit (where known bug 2 lives).
    let half = F::max_value().to_f64().log10() / 2.0;
    let long = (
        crate::common::unit_f64(),
        crate::common::unit_f64(),
        (half - 2.0)..(2.0 * half - 0.5),
        -half..0.0,
    )
        .prop_map(|(u, v, e_long, e_short)| {
            let (l, s) = (10f64.powf(e_long), 10f64.powf(e_short));
            [
                Vec3::zero(),
                Vec3::from_f64(u[0] * l, u[1] * l, u[2] * l),
                Vec3::from_f64(v[0] * s, v[1] * s, v[2] * s),
            ]
        });
    prop_oneof![2 => any, 1 => repeated, 2 => collinear, 2 => scaled, 1 => long]
}

/// An image size: small (valid or not), the spec's 2:1 sizes, near the pixel limit, or
/// any pair of `usize`.
pub(crate) fn size() -> impl Strategy<Value = (usize, usize)> {
    let side = 1usize << 14; // 2¹⁴ × 2¹⁴ = MAX_PIXELS
    prop_oneof![
        3 => (0usize..12, 0usize..12),
        2 => (0usize..2000).prop_map(|h| (2 * h, h)),
        1 => (side - 2..side + 2, side - 2..side + 2),
        1 => (any::<usize>(), 0usize..4),
        1 => (any::<usize>(), any::<usize>()),
        1 => any::<usize>().prop_map(|h| (h.wrapping_mul(2), h)),
    ]
}

/// Look-at inputs: arbitrary vectors; `at == from`; `up` exactly parallel to `at − from`
/// (`from = 0`, `up = ±2ʲ·at`) or nearly so; and a short `up`.
pub(crate) fn look_at_vectors<F: Float>() -> impl Strategy<Value = (Vec3<F>, Vec3<F>, Vec3<F>)> {
    let arbitrary = (vector::<F>(), vector::<F>(), vector::<F>());
    let same = (vector::<F>(), vector::<F>()).prop_map(|(p, up)| (p, p, up));
    let parallel = (vector::<F>(), -4i32..4, any::<bool>()).prop_map(|(at, j, neg)| {
        let s = F::from_f64(if neg { -1.0 } else { 1.0 } * 2f64.powi(j));
        (Vec3::zero(), at, at * s)
    });
    let nearly = (vector::<F>(), vector::<F>(), -20.0f64..0.0)
        .prop_map(|(at, off, e)| (Vec3::zero(), at, at + off * F::from_f64(10f64.powf(e))));
    let short = (vector::<F>(), vector::<F>(), magnitude::<F>()).prop_map(|(from, at, up)| (from, at, up));
    prop_oneof![3 => arbitrary, 1 => same, 1 => parallel, 1 => nearly, 1 => short]
}

pub(crate) fn vfov<F: Float>() -> impl Strategy<Value = F> {
    prop_oneof![
        2 => (0.0f64..180.0).prop_map(F::from_f64),
        1 => prop::sample::select(vec![
            F::zero(),
            F::from_f64(180.0),
            F::from_f64(180.0).next_down(),
            F::from_f64(180.0).next_up(),
            F::zero().next_up(),
        ]),
        2 => scalar::<F>(),
    ]
}
