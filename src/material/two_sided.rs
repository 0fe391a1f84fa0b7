//! [`TwoSided`]: a one-sided material shaded alike from both faces, Mitsuba 3's
//! `twosided`.

use super::{BsdfSample, Emission, Eval, Lobes, Material, MaterialKind, Scatter};
use crate::error::{Error, Field, Result};
use crate::float::Float;
use crate::shape::Hit;
use crate::vec3::Vec3;
use rand::Rng;

/// Makes a one-sided material (a conductor, a plastic: black from the back) reflect from
/// both faces, Mitsuba 3's `twosided`: a hit on the back face is shaded as a hit on the
/// front one, by the same material or by a second one given for the back.
///
/// The renderer gives every material its hit with the normals turned toward the ray, so
/// the wrapped material only has to be told the face is the front one (`front_face =
/// true`); the directions and the frame are already those of a front-face hit. Materials
/// that transmit are refused (as Mitsuba refuses them without `allow_transmission`), and
/// so are emitters, whose faces the renderer handles itself
/// ([`Emissive::two_sided`](super::Emissive::two_sided)).
#[derive(Clone, Debug, PartialEq)]
pub struct TwoSided<F> {
    front: MaterialKind<F>,
    back: Option<MaterialKind<F>>,
}

impl<F: Float> TwoSided<F> {
    /// `material` on both faces; it must neither transmit nor emit.
    pub fn new(material: MaterialKind<F>) -> Result<Self> {
        Ok(Self {
            front: reflecting(Field::TwoSidedFront, material)?,
            back: None,
        })
    }

    /// The same with `material` on the back face instead; it must neither transmit nor
    /// emit.
    pub fn with_back(self, material: MaterialKind<F>) -> Result<Self> {
        Ok(Self {
            back: Some(reflecting(Field::TwoSidedBack, material)?),
            ..self
        })
    }

    /// The front face's material.
    pub fn front(&self) -> &MaterialKind<F> {
        &self.front
    }

    /// The back face's material, if it differs.
    pub fn back(&self) -> Option<&MaterialKind<F>> {
        self.back.as_ref()
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<TwoSided<G>> {
        let two = TwoSided::new(self.front.cast()?)?;
        match &self.back {
            Some(b) => two.with_back(b.cast()?),
            None => Ok(two),
        }
    }

    /// The material of the face `hit` is on, and the hit as one on its front face.
    #[inline]
    fn side(&self, hit: &Hit<F>) -> (&MaterialKind<F>, Hit<F>) {
        let material = match &self.back {
            Some(back) if !hit.front_face => back,
            _ => &self.front,
        };
        (
            material,
            Hit {
                front_face: true,
                ..*hit
            },
        )
    }
}

fn reflecting<F: Float>(field: Field, material: MaterialKind<F>) -> Result<MaterialKind<F>> {
    if material.lobes().contains(Lobes::TRANSMISSION) {
        return Err(Error::invalid(
            field,
            "a two-sided material cannot transmit light (it has two faces to reflect from)",
        ));
    }
    if material.emits().is_some() {
        return Err(Error::invalid(
            field,
            "an emitter cannot be wrapped: make it two-sided with its own `two_sided`",
        ));
    }
    Ok(material)
}

impl<F: Float> Material<F> for TwoSided<F> {
    fn lobes(&self) -> Lobes {
        self.front.lobes() | self.back.as_ref().map_or(Lobes::NONE, Material::lobes)
    }

    fn reads_coordinates(&self) -> bool {
        self.front.reads_coordinates() || self.back.as_ref().is_some_and(Material::reads_coordinates)
    }

    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let (m, hit) = self.side(hit);
        m.eval(&hit, wo, wi)
    }

    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        let (m, hit) = self.side(hit);
        m.pdf(&hit, wo, wi)
    }

    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for TwoSided<F> {
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let (m, hit) = self.side(hit);
        m.sample(&hit, wo, rng)
    }
}
