//! The properties, for f32 and f64.

use super::REGRESSIONS;
use super::directions::*;
use super::incidences::*;
use super::reflectance::*;
use crate::common::*;
use proptest::prelude::*;
use raytrace::lit;

macro_rules! refraction_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(10_000, $seed, REGRESSIONS))]

                #[test]
                fn refracted_direction_is_unit(i in incidence::<$F>(0.999)) {
                    check_unit_length(i)?;
                }

                #[test]
                fn obeys_snells_law(i in incidence::<$F>(0.999)) {
                    check_snell(i)?;
                }

                #[test]
                fn stays_in_the_plane_of_incidence(i in incidence::<$F>(0.999)) {
                    check_coplanar(i)?;
                }

                #[test]
                fn reverses(i in incidence::<$F>(0.99)) {
                    check_reversal(i)?;
                }

                #[test]
                fn total_internal_reflection_exactly_past_the_critical_angle(i in near_critical::<$F>()) {
                    check_critical_angle(i)?;
                }

                #[test]
                fn no_nan_with_normals_longer_than_one(
                    n in inflated_unit::<$F>(),
                    d in unit::<$F>(),
                    eta in 0.4f64..2.5,
                ) {
                    check_inflated_normal(n, d, lit::<$F>(eta))?;
                }

                #[test]
                fn reflectance_plus_transmittance_is_one(c in -0.01f64..=1.01, eta in 0.4f64..2.5) {
                    check_energy(lit::<$F>(c), lit::<$F>(eta))?;
                }

                #[test]
                fn fresnel_matches_the_angle_form(frac in 0.0f64..=1.0, eta in 0.4f64..2.5) {
                    check_angle_form(frac, lit::<$F>(eta))?;
                }

                #[test]
                fn normal_incidence_reflectance(n1 in 1.0f64..2.5, n2 in 1.0f64..2.5) {
                    check_normal_incidence(lit::<$F>(n1), lit::<$F>(n2))?;
                }

                #[test]
                fn reflectance_tends_to_one_at_grazing(k in 0.0f64..12.0, eta in 0.4f64..2.5) {
                    check_grazing(lit::<$F>(10f64.powf(-k)), lit::<$F>(eta))?;
                }

                #[test]
                fn reflectance_grows_with_the_angle(
                    a in 0.0f64..=1.0,
                    gap in prop_oneof![0.0f64..1.0, (1.0f64..12.0).prop_map(|k| 10f64.powf(-k))],
                    eta in 0.4f64..2.5,
                ) {
                    let (lo, hi) = (a, (a + gap).min(1.0));
                    check_monotone(lit::<$F>(lo), lit::<$F>(hi), lit::<$F>(eta))?;
                }
            }

            #[test]
            fn schlick_error_against_fresnel_is_bounded() {
                check_schlick_error::<$F>();
            }
        }
    };
}

refraction_tests!(single, f32, 0x5EF2_AC71);
refraction_tests!(double, f64, 0x5EF2_AC72);
