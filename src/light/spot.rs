//! The spot light: a point light that shines into a cone, as Mitsuba 3's `spot`.

use super::Incident;
use super::point::aim;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::validate;
use crate::vec3::{Color, Vec3};

/// A point light at `position` shining along `direction` into a cone, as Mitsuba 3's
/// `spot` emitter: the radiant intensity toward a direction at angle `θ` from the axis is
/// `I·s(θ)`,
///
/// `s(θ) = 1` for `θ ≤ β`, `(γ − θ)/(γ − β)` for `β < θ < γ`, `0` for `θ ≥ γ`,
///
/// `γ` the cutoff angle and `β` the beam width: full intensity inside the beam, a linear
/// ramp in the angle down to nothing at the cutoff. Inside the beam it is exactly a
/// [`PointLight`](super::PointLight) of intensity `I`.
///
/// Mitsuba asserts `β ≤ γ`; here a beam wider than the cutoff is an error (not clamped),
/// and so is a cutoff above 90°, which would light the half-space behind the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotLight<F> {
    position: Vec3<F>,
    /// Unit: where the cone points.
    axis: Vec3<F>,
    intensity: Color<F>,
    /// `γ` and `β` in degrees, as given.
    cutoff_angle: F,
    beam_width: F,
    /// `γ` in radians, `cos γ`, `cos β`, `1/(γ − β)` (`∞` for a hard edge, `β = γ`, where
    /// the ramp is never reached).
    cutoff: F,
    cos_cutoff: F,
    cos_beam: F,
    inv_transition: F,
}

impl<F: Float> SpotLight<F> {
    /// Mitsuba's default cutoff angle, 20°; its default beam width is ¾ of the cutoff.
    pub const DEFAULT_CUTOFF_ANGLE: f64 = 20.0;

    /// A spot light at `position` (finite) shining along `direction` (finite, non-zero,
    /// any length) with intensity `I` (finite, `≥ 0`) at the centre of the beam,
    /// `cutoff_angle` `γ ∈ (0°, 90°]` and `beam_width` `β ∈ [0°, γ]`, both in degrees.
    ///
    /// # Errors
    /// A value outside its domain, under its [`Field`].
    pub fn new(
        position: Vec3<F>,
        direction: Vec3<F>,
        intensity: Color<F>,
        cutoff_angle: F,
        beam_width: F,
    ) -> Result<Self> {
        let position = validate::finite_vec(Field::LightPosition, position)?;
        let axis = validate::direction(Field::LightDirection, direction)?;
        let intensity = validate::non_negative(Field::LightIntensity, intensity)?;
        if !(cutoff_angle > F::zero() && cutoff_angle <= lit(90.0)) {
            return Err(Error::invalid(
                Field::SpotCutoff,
                format!(
                    "must be in (0, 90] degrees (got {})",
                    validate::number(cutoff_angle)
                ),
            ));
        }
        if !(beam_width >= F::zero() && beam_width <= cutoff_angle) {
            return Err(Error::invalid(
                Field::SpotBeamWidth,
                format!(
                    "must be in [0, cutoff_angle] = [0, {}] degrees (got {})",
                    validate::number(cutoff_angle),
                    validate::number(beam_width)
                ),
            ));
        }
        let (cutoff, beam) = (cutoff_angle.to_radians(), beam_width.to_radians());
        Ok(Self {
            position,
            axis,
            intensity,
            cutoff_angle,
            beam_width,
            cutoff,
            cos_cutoff: cutoff.cos(),
            cos_beam: beam.cos(),
            inv_transition: F::one() / (cutoff - beam),
        })
    }

    /// The light's position.
    pub fn position(&self) -> Vec3<F> {
        self.position
    }

    /// The unit direction the cone points along.
    pub fn direction(&self) -> Vec3<F> {
        self.axis
    }

    /// The radiant intensity `I` in the beam.
    pub fn intensity(&self) -> Color<F> {
        self.intensity
    }

    /// The cutoff angle `γ`, in degrees.
    pub fn cutoff_angle(&self) -> F {
        self.cutoff_angle
    }

    /// The beam width `β`, in degrees.
    pub fn beam_width(&self) -> F {
        self.beam_width
    }

    /// `s(θ)` for `cos θ` (see [`SpotLight`]), with Mitsuba's tests: 0 unless
    /// `cos θ > cos γ`, 1 where `cos θ ≥ cos β`, the ramp `(γ − acos(cos θ))/(γ − β)`
    /// between, kept in `[0, 1]` where `acos` rounds past an edge.
    #[inline]
    pub fn falloff(&self, cos_theta: F) -> F {
        if cos_theta > self.cos_cutoff {
            if cos_theta >= self.cos_beam {
                F::one()
            } else {
                ((self.cutoff - cos_theta.acos()) * self.inv_transition)
                    .max(F::zero())
                    .min(F::one())
            }
        } else {
            // Past the cutoff, or NaN.
            F::zero()
        }
    }

    /// `I·s(θ)` from `d` away, falling off as `1/d²`, `θ` the angle between the axis and
    /// the way from the light to `x`; `None` at the light itself or outside the cone.
    #[inline]
    pub fn incident(&self, x: Vec3<F>) -> Option<Incident<F>> {
        let (direction, dist2) = aim(x, self.position)?;
        let s = self.falloff(-direction.dot(self.axis));
        if s <= F::zero() {
            return None;
        }
        Some(Incident {
            direction,
            distance: dist2.sqrt(),
            // `I·1` is `I` exactly: inside the beam this is the point light's arithmetic.
            intensity: self.intensity * s,
            falloff: dist2,
        })
    }

    /// This light in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<SpotLight<G>> {
        SpotLight::new(
            self.position.cast(),
            self.axis.cast(),
            self.intensity.cast(),
            G::from_f64(self.cutoff_angle.to_f64()),
            G::from_f64(self.beam_width.to_f64()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spot(cutoff: f64, beam: f64) -> Result<SpotLight<f64>> {
        let down = Vec3::new(0.0, -1.0, 0.0);
        SpotLight::new(Vec3::zero(), down, Vec3::splat(1.0), cutoff, beam)
    }

    #[test]
    fn falloff_is_mitsubas_ramp_in_the_angle() {
        let s = spot(40.0, 30.0).unwrap();
        let at = |deg: f64| s.falloff(deg.to_radians().cos());
        assert_eq!(at(0.0), 1.0);
        assert_eq!(at(29.0), 1.0);
        assert!((at(35.0) - 0.5).abs() < 1e-12);
        assert!((at(32.5) - 0.75).abs() < 1e-12);
        assert_eq!(at(40.5), 0.0);
        assert_eq!(at(120.0), 0.0);
        // A hard edge: the ramp is never reached.
        let hard = spot(40.0, 40.0).unwrap();
        assert_eq!(hard.falloff(39.9f64.to_radians().cos()), 1.0);
        assert_eq!(hard.falloff(40.1f64.to_radians().cos()), 0.0);
    }

    #[test]
    fn refuses_cutoffs_past_90_and_beams_past_the_cutoff() {
        assert!(spot(90.0, 10.0).is_ok());
        assert!(spot(20.0, 0.0).is_ok());
        for (cutoff, beam, field) in [
            (90.5, 10.0, Field::SpotCutoff),
            (0.0, 0.0, Field::SpotCutoff),
            (f64::NAN, 0.0, Field::SpotCutoff),
            (30.0, 31.0, Field::SpotBeamWidth),
            (30.0, -1.0, Field::SpotBeamWidth),
        ] {
            match spot(cutoff, beam) {
                Err(Error::InvalidValue { field: f, .. }) => assert_eq!(f, field, "{cutoff} {beam}"),
                other => panic!("{cutoff} {beam}: {other:?}"),
            }
        }
        let zero = SpotLight::new(Vec3::zero(), Vec3::zero(), Vec3::splat(1.0), 20.0, 15.0);
        assert!(matches!(
            zero,
            Err(Error::InvalidValue {
                field: Field::LightDirection,
                ..
            })
        ));
    }
}
