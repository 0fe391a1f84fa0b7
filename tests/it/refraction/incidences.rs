//! Incidences: random ones below the critical angle, and ones within a hair of it.

use crate::common::*;
use proptest::prelude::*;
use raytrace::{Float, Vec3, lit};
use std::f64::consts::{FRAC_PI_2, TAU};

/// An incident direction, a normal and a ratio of indices, rounded to `F`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Incidence<F> {
    pub(crate) d: Vec3<F>,
    pub(crate) n: Vec3<F>,
    pub(crate) eta: F,
}

/// The angle of incidence beyond which no light is transmitted: the critical angle
/// `asin(1/η)` for `η > 1`, grazing (`π/2`) otherwise.
pub(crate) fn max_angle(eta: f64) -> f64 {
    if eta > 1.0 { (1.0 / eta).asin() } else { FRAC_PI_2 }
}

/// Incidences with `θ₁` uniform in `[0, max_frac·θ_max)`, `θ_max` from [`max_angle`], at a
/// random azimuth about a random normal. With `max_frac < 1` the angle stays below the
/// critical one by a margin far above rounding; the critical angle itself is tested apart.
pub(crate) fn incidence<F: Float>(max_frac: f64) -> impl Strategy<Value = Incidence<F>> {
    (unit::<F>(), 0.4f64..2.5, 0.0..max_frac, 0.0..TAU).prop_map(|(n, eta, frac, phi)| {
        let nf = n.to_f64();
        let back = [-nf[0], -nf[1], -nf[2]];
        let d = unit_from::<F>(direction_at(back, frac * max_angle(eta), phi));
        Incidence { d, n, eta: lit(eta) }
    })
}

/// Incidences within a relative distance `10⁻¹..10⁻¹⁶` of the critical angle `θ_c`, on both
/// sides (`θ_c(1 − rel)` below, `θ_c + rel·(π/2 − θ_c)` above, so the ray never passes
/// grazing), `η ∈ (1, 2.5]` (light leaving the denser medium); in f32 the closest cases
/// fall on either side by rounding alone.
pub(crate) fn near_critical<F: Float>() -> impl Strategy<Value = Incidence<F>> {
    (unit::<F>(), 1.0001f64..2.5, 1.0f64..16.0, any::<bool>(), 0.0..TAU).prop_map(
        |(n, eta, k, above, phi)| {
            let nf = n.to_f64();
            let back = [-nf[0], -nf[1], -nf[2]];
            let crit = (1.0 / eta).asin();
            let rel = 10f64.powf(-k);
            let theta = if above {
                crit + rel * (FRAC_PI_2 - crit)
            } else {
                crit * (1.0 - rel)
            };
            let d = unit_from::<F>(direction_at(back, theta, phi));
            Incidence { d, n, eta: lit(eta) }
        },
    )
}
