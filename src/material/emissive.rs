//! A surface that gives off light: an area light.

use super::lambertian::Diffuse;
use super::{BsdfSample, Eval, Lobes, Material, Scatter};
use crate::error::Result;
use crate::float::Float;
use crate::shape::Hit;
use crate::validate;
use crate::vec3::{Color, Vec3};
use rand::Rng;

/// The light a surface gives off: radiance `L_e` per channel, the same in every direction
/// (a diffuse emitter), from the front face only (where the shape's outward normal points)
/// or from both faces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission<F> {
    radiance: Color<F>,
    two_sided: bool,
}

impl<F: Float> Emission<F> {
    /// Radiance `L_e` from the front face; each channel must be finite and `≥ 0`.
    pub fn new(radiance: Color<F>) -> Result<Self> {
        Ok(Self {
            radiance: validate::non_negative(crate::error::Field::EmittedRadiance, radiance)?,
            two_sided: false,
        })
    }

    /// The same emission from both faces (`true`) or the front face only (`false`).
    #[must_use]
    pub fn two_sided(self, two_sided: bool) -> Self {
        Self { two_sided, ..self }
    }

    /// The radiance `L_e`.
    pub fn radiance(&self) -> Color<F> {
        self.radiance
    }

    /// Whether both faces emit.
    pub fn is_two_sided(&self) -> bool {
        self.two_sided
    }

    /// The radiance leaving the face a ray sees: `L_e` on the front face, and on the back
    /// face if the emission is two-sided; black otherwise.
    #[inline]
    pub fn toward(&self, front_face: bool) -> Color<F> {
        if front_face || self.two_sided {
            self.radiance
        } else {
            Color::zero()
        }
    }

    /// The power given off per unit area, as one number for choosing among emitters:
    /// `π·L̄·s`, `L̄` the mean of the channels and `s` the emitting faces (1 or 2). A diffuse
    /// emitter of area `A` gives off `Φ = ∫_A ∫ L_e cos θ dω dA = π·L_e·A` per face.
    pub fn power_per_area(&self) -> f64 {
        let [r, g, b] = self.radiance.to_f64();
        let faces = if self.two_sided { 2.0 } else { 1.0 };
        std::f64::consts::PI * (r + g + b) / 3.0 * faces
    }

    /// This emission in scalar `G`, rounded through `f64` and re-validated, as
    /// [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Emission<G>> {
        Ok(Emission::new(self.radiance.cast())?.two_sided(self.two_sided))
    }
}

/// A light-giving surface: it gives off its [`Emission`] `L_e` and reflects as a matte
/// surface of albedo `A` (black by default, when it absorbs every ray), so the colour a
/// ray brings back from it is `C = L_e + A ∘ C⁺`, `C⁺` the scattered ray's colour.
///
/// On a sphere, a triangle or a mesh the renderer also samples it directly from matte
/// surfaces (next-event estimation); on a plane, whose area is infinite, only rays that
/// hit it find its light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emissive<F> {
    emission: Emission<F>,
    albedo: Color<F>,
}

impl<F: Float> Emissive<F> {
    /// A black surface giving off radiance `L_e` from its front face; each channel must
    /// be finite and `≥ 0`.
    pub fn new(radiance: Color<F>) -> Result<Self> {
        Ok(Self::from(Emission::new(radiance)?))
    }

    /// The same surface emitting from both faces (`true`) or the front face (`false`).
    #[must_use]
    pub fn two_sided(self, two_sided: bool) -> Self {
        Self {
            emission: self.emission.two_sided(two_sided),
            ..self
        }
    }

    /// The same surface reflecting as a matte one of `albedo`; each channel must lie in
    /// `[0, 1]`.
    pub fn with_albedo(self, albedo: Color<F>) -> Result<Self> {
        Ok(Self {
            albedo: validate::albedo(crate::error::Field::EmissiveAlbedo, albedo)?,
            ..self
        })
    }

    /// What it gives off.
    pub fn emission(&self) -> Emission<F> {
        self.emission
    }

    /// The matte albedo `A` (black: it reflects nothing).
    pub fn albedo(&self) -> Color<F> {
        self.albedo
    }

    /// How it reflects: as a matte surface of its albedo. (Made when asked, so an emitter
    /// stores no sampler.)
    #[inline]
    fn surface(&self) -> Diffuse<F> {
        Diffuse::new(self.albedo)
    }

    /// Whether it reflects at all.
    #[inline]
    fn reflects(&self) -> bool {
        self.albedo() != Color::zero()
    }

    /// This material in scalar `G`, rounded through `f64` and re-validated.
    pub fn cast<G: Float>(&self) -> Result<Emissive<G>> {
        Emissive::from(self.emission.cast()?).with_albedo(self.albedo().cast())
    }
}

impl<F: Float> From<Emission<F>> for Emissive<F> {
    fn from(emission: Emission<F>) -> Self {
        Self {
            emission,
            albedo: Color::zero(),
        }
    }
}

impl<F: Float> Material<F> for Emissive<F> {
    /// No: it has no texture.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        false
    }

    /// None when black; otherwise a [`Lambertian`](super::Lambertian)'s.
    #[inline]
    fn lobes(&self) -> Lobes {
        if self.reflects() {
            self.surface().lobes()
        } else {
            Lobes::NONE
        }
    }

    #[inline]
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        self.reflects()
            .then(|| self.surface().eval(hit, wo, wi))
            .flatten()
    }

    #[inline]
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        if self.reflects() {
            self.surface().pdf(hit, wo, wi)
        } else {
            F::zero()
        }
    }

    #[inline]
    fn emits(&self) -> Option<Emission<F>> {
        Some(self.emission)
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Emissive<F> {
    /// Absorbs the ray when black; otherwise scatters it as a [`Lambertian`](super::Lambertian) surface
    /// with the specification's tangent-sphere sampler.
    #[inline]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        if self.reflects() {
            self.surface().sample(hit, wo, rng)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::DefaultRng;
    use crate::shape::Surface;
    use rand::SeedableRng;

    #[test]
    fn front_back_and_two_sided() {
        let e = Emission::new(Vec3::new(1.0, 2.0, 3.0)).unwrap();
        assert_eq!(e.toward(true), Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(e.toward(false), Vec3::zero());
        assert_eq!(e.two_sided(true).toward(false), Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(e.power_per_area(), 2.0 * std::f64::consts::PI);
        assert_eq!(e.two_sided(true).power_per_area(), 4.0 * std::f64::consts::PI);
    }

    #[test]
    fn black_emitters_absorb_and_grey_ones_reflect() {
        let up = Vec3::new(0.0, 1.0, 0.0);
        let hit = Hit::new(Surface::bare(1.0, Vec3::zero(), up), -up);
        let mut rng = DefaultRng::seed_from_u64(1);
        let black = Emissive::new(Vec3::splat(4.0)).unwrap();
        assert!(black.sample(&hit, up, &mut rng).is_none());
        assert_eq!(black.lobes(), Lobes::NONE);
        assert_eq!(black.eval(&hit, up, up), None);
        let grey = black.with_albedo(Vec3::splat(0.5)).unwrap();
        let s = grey.sample(&hit, up, &mut rng).unwrap();
        assert!(s.direction.dot(hit.normal) >= 0.0);
        assert_eq!(s.weight, Vec3::splat(0.5));
        assert!(grey.lobes().has_non_delta());
    }

    #[test]
    fn rejects_invalid_values() {
        let msg = Emissive::new(Vec3::new(1.0, -1.0, 0.0)).unwrap_err().to_string();
        assert!(msg.contains("emitted radiance"), "{msg}");
        assert!(Emissive::new(Vec3::new(f64::INFINITY, 0.0, 0.0)).is_err());
        assert!(
            Emissive::new(Vec3::splat(1.0))
                .unwrap()
                .with_albedo(Vec3::splat(1.5))
                .is_err()
        );
    }
}
