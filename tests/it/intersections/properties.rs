//! The properties, for f32 and f64, and the checks' power against wrong methods.

use super::planes::*;
use super::power::*;
use super::spheres::*;
use super::triangles::*;
use super::{CASES, HARNESS_SEED, REGRESSIONS};
use crate::common::Alone;
use crate::common::*;
use proptest::prelude::*;
use raytrace::shape::textbook_sphere_hit;

macro_rules! intersection_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(CASES, $seed, REGRESSIONS))]

                #[test]
                fn sphere_hits_lie_on_the_sphere_within_the_error_bound(case in sphere_case::<$F>()) {
                    check_sphere_surface(&case, |s, r, t_max| s.hit(r, t_max))?;
                }

                #[test]
                fn sphere_hit_is_the_smallest_positive_root(case in sphere_case::<$F>()) {
                    check_sphere_roots(&case)?;
                }

                #[test]
                fn plane_hits_lie_on_the_plane_and_decide_like_exact_t(case in plane_case::<$F>()) {
                    check_plane(&case)?;
                }

                #[test]
                fn triangle_hits_and_misses_follow_exact_barycentrics(case in tri_case::<$F>()) {
                    check_triangle_decision(&case, |t, r| t.intersect_watertight(r, <$F>::INFINITY).map(|x| x.0))?;
                }

                #[test]
                fn triangle_hits_lie_on_the_triangle_within_the_error_bound(case in tri_case::<$F>()) {
                    check_triangle_hit(&case)?;
                }
            }

            /// The harness has power: the textbook sphere (no reprojection, zero error
            /// bound) fails the surface check, and Möller–Trumbore with a crack-closing
            /// tolerance, or a too strict one, fails the barycentric decision check.
            #[test]
            fn the_checks_reject_wrong_methods() {
                assert!(
                    harness_rejects(sphere_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_sphere_surface(&c, |s, r, t_max| textbook_sphere_hit(s, r, 0.0, t_max))
                    }),
                    "the textbook sphere passed the surface check"
                );
                assert!(
                    harness_rejects(tri_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_triangle_decision(&c, moller_trumbore_lenient)
                    }),
                    "a lenient Möller–Trumbore passed the decision check"
                );
                assert!(
                    harness_rejects(tri_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_triangle_decision(&c, moller_trumbore_strict)
                    }),
                    "a strict Möller–Trumbore passed the decision check"
                );
                // The plain Möller–Trumbore is inexact only at the edges, inside the margins:
                // the decision check accepts it, so it tests decisions, not watertightness.
                assert!(
                    !harness_rejects(tri_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_triangle_decision(&c, |t, r| moller_trumbore(t, r, 0.0))
                    }),
                    "the plain Möller–Trumbore failed the decision check"
                );
            }

            #[test]
            fn the_strategies_reach_the_decisive_cases() {
                check_coverage::<$F>();
            }
        }
    };
}

intersection_tests!(single, f32, 0x1_5EC7_0032);
intersection_tests!(double, f64, 0x1_5EC7_0064);
