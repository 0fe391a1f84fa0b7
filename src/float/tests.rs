//! The steps to the neighbouring values against their definition, `γ(n)` and literals.

use super::*;
use twofloat::TwoFloat;

fn check_neighbours<F: Float>() {
    for x in [lit::<F>(1.0), lit(-3.5), lit(1e-3), lit(0.0)] {
        assert!(x.next_up() > x, "{}: next_up({x})", F::NAME);
        assert!(x.next_down() < x, "{}: next_down({x})", F::NAME);
    }
}

/// The three-lane steps agree with the definition (the branches of the trait's
/// default) on every value kind, infinities and NaN included, in any lane.
fn steps_each_as_defined<F: Float>() {
    let values = [
        0.0,
        -0.0,
        1.0,
        -2.5,
        1e-300,
        -1e-40,
        3e38,
        f64::MAX,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let defined = |x: F, s: F| {
        if !x.is_finite() {
            x
        } else if s > F::zero() {
            x.next_up()
        } else if s < F::zero() {
            x.next_down()
        } else {
            x
        }
    };
    let bits = |v: F| v.to_f64().to_bits();
    for (i, &x) in values.iter().enumerate() {
        for (j, &s) in values.iter().enumerate() {
            let (y, t) = (values[(i + 3) % values.len()], values[(j + 5) % values.len()]);
            let p = [lit::<F>(x), lit(y), lit(-x)];
            let d = [lit::<F>(s), lit(-s), lit(t)];
            let got = F::step_toward_each(p, d);
            for k in 0..3 {
                assert_eq!(
                    bits(got[k]),
                    bits(defined(p[k], d[k])),
                    "{}: {:?} {:?}",
                    F::NAME,
                    p,
                    d
                );
                assert_eq!(bits(p[k].step_toward(d[k])), bits(got[k]));
            }
        }
    }
}

#[test]
fn steps_each_as_defined_f32_f64() {
    steps_each_as_defined::<f32>();
    steps_each_as_defined::<f64>();
}

/// The branch-free steps agree with `next_up`/`next_down` on every finite value kind.
#[test]
fn step_toward_matches_next_up_and_down() {
    let xs = [
        0.0f32,
        -0.0,
        1.0,
        -1.0,
        1e-45,
        -1e-45,
        f32::MAX,
        -f32::MAX,
        f32::MIN_POSITIVE,
        3.7e-39,
        -2.5,
    ];
    for x in xs {
        for s in [
            1.0f32,
            -1.0,
            0.0,
            -0.0,
            f32::NAN,
            -f32::NAN,
            1e-40,
            -3e30,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ] {
            let want = |up: f32, down: f32| {
                if s > 0.0 {
                    up
                } else if s < 0.0 {
                    down
                } else {
                    x
                }
            };
            let got = Float::step_toward(x, s);
            assert_eq!(
                got.to_bits(),
                want(x.next_up(), x.next_down()).to_bits(),
                "{x} {s}"
            );
            let y = f64::from(x);
            let got = Float::step_toward(y, f64::from(s));
            assert_eq!(
                got.to_bits(),
                (if s > 0.0 {
                    y.next_up()
                } else if s < 0.0 {
                    y.next_down()
                } else {
                    y
                })
                .to_bits(),
                "{y} {s}"
            );
        }
    }
    for x in [f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(Float::step_toward(x, 1.0), x);
    }
    assert!(Float::step_toward(f64::NAN, 1.0).is_nan());
}

#[test]
fn next_up_and_down_move_strictly() {
    check_neighbours::<f32>();
    check_neighbours::<f64>();
    check_neighbours::<TwoFloat>();
    check_neighbours::<crate::DoubleDouble>();
}

#[test]
fn gamma_matches_its_definition() {
    let u = f64::EPSILON / 2.0;
    assert_eq!(<f64 as Float>::gamma(3), 3.0 * u / (1.0 - 3.0 * u));
    assert!(<f32 as Float>::gamma(5) > 5.0 * f32::EPSILON / 2.0);
    let g = <TwoFloat as Float>::gamma(5).to_f64();
    assert!(
        g > 1e-31 && g < 1e-29,
        "double-double γ(5) = {g}: its epsilon must be ~2⁻¹⁰⁰, not twofloat's MIN_POSITIVE"
    );
}

#[test]
fn literals_round_to_nearest() {
    assert_eq!(lit::<f32>(0.1), 0.1f32);
    assert_eq!(lit::<f64>(0.1), 0.1f64);
    assert_eq!(lit::<TwoFloat>(0.1).to_f64(), 0.1);
}
