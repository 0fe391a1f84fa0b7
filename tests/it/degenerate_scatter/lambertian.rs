//! The degenerate Lambertian direction: antipodal draws, the library's redraw, the textbook's failure.

use super::scripted::*;
use crate::common::*;
use proptest::prelude::*;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{Rng, SeedableRng};
use raytrace::sampling::{lambertian_direction, unit_sphere_rejection};
use raytrace::{Float, Vec3, lit};
use twofloat::TwoFloat;

/// The textbook Lambertian direction: `(N + S)/|N + S|`, no check.
pub(crate) fn textbook_direction<F: Float>(n: Vec3<F>, s: Vec3<F>) -> Vec3<F> {
    let d = n + s;
    d / d.length()
}

/// The textbook sampler: the spec's `S`, then [`textbook_direction`].
pub(crate) fn textbook_lambertian<F: Float, R: Rng + ?Sized>(n: Vec3<F>, rng: &mut R) -> Vec3<F> {
    let [x, y, z] = unit_sphere_rejection(rng);
    textbook_direction(n, Vec3::from_f64(x, y, z))
}

/// The contract of a scattered direction `d` at a surface with unit normal `n`: no NaN,
/// unit length within `4ε` (evaluated in double-double), and not below the surface,
/// `d·n ≥ 0` (exactly, in double-double; the library's accepted sums have `d·n ≈ |N + S|²/2
/// > 32ε`, far from zero).
pub(crate) fn check_direction<F: Float>(n: Vec3<F>, d: Vec3<F>) -> Result<(), TestCaseError> {
    prop_assert!(d.is_finite(), "not finite: {d:?} at n = {n:?}");
    let len = length_dd(d);
    prop_assert!(
        (len - 1.0).abs() <= 4.0 * eps::<F>(),
        "|d| − 1 = {:e} at n = {n:?}",
        len - 1.0
    );
    prop_assert!(
        dd(d).dot(dd(n)) >= TwoFloat::from(0.0),
        "below the surface: d = {d:?}, n = {n:?}"
    );
    Ok(())
}

/// A scripted draw sequence: `bad` points `X ≈ −cN` (each coordinate moved by up to 4 grid
/// steps), optionally interleaved with points the rejection sampler itself refuses (outside
/// the ball, or at the origin), then one `good` point.
#[derive(Clone, Debug)]
pub(crate) struct Antipodal<F> {
    n: Vec3<F>,
    bad: Vec<[u64; 3]>,
    good: [u64; 3],
}

impl<F: Float> Antipodal<F> {
    fn script(&self) -> Vec<u64> {
        self.bad.iter().chain([&self.good]).flatten().copied().collect()
    }
}

/// Normals: axes, random unit vectors normalized in `F`, and "unit" normals whose squared
/// length rounds above 1. Bad draws: 1 to 4 points `X = −c·N + j·2⁻⁵²` (`c ∈ [0.5, 0.999]`,
/// `jᵢ ∈ [−4, 4]`; `c < 1` keeps `X` in the ball, and the sampler normalizes it back to
/// `S ≈ −N`), with cube points the sampler rejects mixed in. The good draw is a point whose
/// `S` makes an angle of less than `acos(−0.9)` with `N`.
pub(crate) fn antipodal<F: Float>() -> impl Strategy<Value = Antipodal<F>> {
    let normal = prop_oneof![3 => unit::<F>(), 1 => inflated_unit::<F>()];
    let one_bad = (0.5f64..0.999, [-4i32..=4, -4i32..=4, -4i32..=4], 0u8..6);
    (
        normal,
        prop::collection::vec(one_bad, 1..5),
        unit_f64(),
        0.1f64..0.999,
    )
        .prop_filter_map(
            "good draw too close to −N",
            |(n, bad, g, c2): (Vec3<F>, _, _, _)| {
                let nf = n.to_f64();
                let mut script = Vec::new();
                for (c, j, extra) in bad {
                    match extra {
                        0 => script.push(words([0.9, -0.9, 0.9])), // outside the ball: redrawn
                        1 => script.push(words([0.0, 0.0, 0.0])),  // at the centre: redrawn
                        _ => {}
                    }
                    let x: [f64; 3] = std::array::from_fn(|i| -c * nf[i] + f64::from(j[i]) * GRID);
                    script.push(words(x));
                }
                let good = words(g.map(|x| x * c2));
                let s2 = sphere_point::<f64>(point(good))?;
                (s2.dot(n.cast()) > -0.9).then_some(Antipodal { n, bad: script, good })
            },
        )
}

/// The scripted bad draws really are degenerate (each is refused by the cube rejection, or
/// gives `|N + S|² ≤ 64ε` in `F`, the cancelling cap), the library draws exactly the scripted
/// words (so it redrew past every bad point and took the good one), returns the good
/// point's direction within `8ε`, and that direction meets [`check_direction`].
pub(crate) fn check_library_redraws<F: Float>(case: &Antipodal<F>) -> Result<(), TestCaseError> {
    let n = case.n;
    for &w in &case.bad {
        if let Some(s) = sphere_point::<F>(point(w)) {
            let len2 = (n + s).length_squared();
            prop_assert!(
                len2 <= F::epsilon() * lit(64.0),
                "the scripted draw is not degenerate: |N + S|² = {len2}"
            );
        }
    }
    let mut rng = Scripted::new(case.script());
    let d = lambertian_direction(n, &mut rng);
    check_direction(n, d)?;
    prop_assert_eq!(rng.drawn, rng.script.len(), "did not stop at the good draw");
    let s2 = sphere_point::<F>(point(case.good)).unwrap();
    let want = (n + s2) / (n + s2).length();
    prop_assert!(
        (dd(d) - dd(want)).length().to_f64() <= 8.0 * eps::<F>(),
        "returned {d:?}, the good draw gives {want:?}"
    );
    Ok(())
}

/// Fed the same scripted words, the textbook sampler must meet [`check_direction`] too —
/// it does not: this is the power test.
pub(crate) fn check_textbook_sampler<F: Float>(case: &Antipodal<F>) -> Result<(), TestCaseError> {
    let mut rng = Scripted::new(case.script());
    check_direction(case.n, textbook_lambertian(case.n, &mut rng))
}

/// The normals of the deterministic tests: the six axes and 200 seeded random unit
/// vectors normalized in `F`.
pub(crate) fn normals<F: Float>() -> Vec<Vec3<F>> {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(0xA7_1F0D);
    let axes = [0, 1, 2].into_iter().flat_map(|i| {
        [1.0, -1.0].map(|s| {
            let mut v = [0.0; 3];
            v[i] = s;
            Vec3::<F>::from_f64(v[0], v[1], v[2])
        })
    });
    let random = (0..200).map(|_| {
        let [x, y, z] = unit_sphere_rejection(&mut rng);
        unit_from::<F>([x, y, z])
    });
    axes.chain(random).collect()
}

/// `x` moved one representable value away from zero.
pub(crate) fn away_from_zero<F: Float>(x: F) -> F {
    if x >= F::zero() {
        x.next_up()
    } else {
        x.next_down()
    }
}

/// The textbook method fails on exactly antipodal draws: `S = −N` (the negation of the
/// rounded normal, itself a unit vector of `F`) gives `N + S = 0` and a NaN direction, and
/// `S = −N` with its largest component one ulp further from zero gives `N + S = ∓ulp·eₖ`,
/// whose direction `∓eₖ` points into the surface (`d·n = −|nₖ| ≤ −1/√3`). The library,
/// fed draws that make those `S` (then a good one), returns a valid direction every time.
pub(crate) fn textbook_fails_where_the_library_holds<F: Float>() {
    for n in normals::<F>() {
        let d = textbook_direction(n, -n);
        assert!(
            d.x.is_nan() && d.y.is_nan() && d.z.is_nan(),
            "{}: S = −N gave {d:?}",
            F::NAME
        );
        let k = (0..3)
            .max_by(|&i, &j| n[i].abs().partial_cmp(&n[j].abs()).unwrap())
            .unwrap();
        let mut s = [-n.x, -n.y, -n.z];
        s[k] = away_from_zero(s[k]);
        let s = Vec3::new(s[0], s[1], s[2]);
        assert!(
            (length_dd(s) - 1.0).abs() <= 4.0 * eps::<F>(),
            "S is a unit vector of F"
        );
        let d = textbook_direction(n, s);
        let cos = dd(d).dot(dd(n)).to_f64();
        assert!(
            cos <= -0.5,
            "{}: S = −N + 1 ulp gave d·n = {cos} at n = {n:?}",
            F::NAME
        );

        // The library, fed S = −N and S = −N + 1 ulp (as cube points scaled by 3/4, which
        // the sampler normalizes back), then a good draw.
        for s in [-n, s] {
            let x = s.to_f64().map(|c| 0.75 * c);
            let good = words([0.1, 0.2, 0.3]);
            let case = Antipodal {
                n,
                bad: vec![words(x)],
                good,
            };
            if let Err(e) = check_library_redraws(&case) {
                panic!("{}: library failed on S = {s:?} at n = {n:?}: {e}", F::NAME);
            }
        }
    }
}
