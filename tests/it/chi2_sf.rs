//! The χ² survival function every χ² test decides by (`common::chi2_sf`), against closed
//! forms deep into the tail and against published critical values.

use crate::common::chi2_sf;

#[test]
fn chi2_sf_matches_tables_and_closed_forms() {
    // Even k: Q(m, y) = e^{−y} Σ_{i<m} yⁱ/i! exactly; checked deep into the tail, where
    // the χ² tests decide (relative error, so a tail of 10⁻⁵⁰ is checked as well as 0.5).
    for k in [2u32, 4, 10, 20, 50, 120] {
        for x in [0.5, 3.0, 10.0, 30.0, 100.0, 300.0] {
            let (m, y) = (k / 2, x / 2.0);
            let mut term = 1.0;
            let mut sum = 0.0;
            for i in 0..m {
                if i > 0 {
                    term *= y / f64::from(i);
                }
                sum += term;
            }
            let exact = (-y).exp() * sum;
            let got = chi2_sf(x, k);
            assert!(
                (got - exact).abs() <= 1e-12 * exact,
                "k={k} x={x}: {got:e} vs {exact:e}"
            );
        }
    }
    // Published critical values (odd and even k; NIST/SEMATECH e-Handbook table 1.3.6.7.4,
    // given to 3–4 decimals, hence the 10⁻³ relative tolerance).
    let table = [
        (1, 3.841, 0.05),
        (1, 10.828, 0.001),
        (5, 11.070, 0.05),
        (5, 0.554, 0.99),
        (9, 21.666, 0.01),
        (19, 30.144, 0.05),
        (99, 123.225, 0.05),
        (99, 148.230, 0.001),
    ];
    for (k, x, p) in table {
        let got = chi2_sf(x, k);
        assert!((got - p).abs() <= 1e-3 * p, "k={k} x={x}: {got} vs {p}");
    }
    // k = 1: Q(½, x/2) = erfc(√(x/2)); erfc(√(23.928/2)) ≈ 1.0·10⁻⁶ at the critical value
    // of the suite's significance level.
    let p = chi2_sf(23.928_127, 1);
    assert!((p - 1e-6).abs() < 1e-9, "{p:e}");
    assert_eq!(chi2_sf(0.0, 3), 1.0);
}
