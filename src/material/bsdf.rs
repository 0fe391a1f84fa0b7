//! What a material's BSDF answers: which lobes it has ([`Lobes`]), its value for a pair
//! of directions ([`Eval`]), and a direction it draws ([`BsdfSample`]).

use crate::float::Float;
use crate::vec3::{Color, Vec3};
use std::fmt;
use std::ops::BitOr;

/// Which kinds of scattering a material's lobes do (pbrt-v4's `BxDFFlags`): a set of
/// [`REFLECTION`](Lobes::REFLECTION), [`TRANSMISSION`](Lobes::TRANSMISSION) and one of
/// [`DIFFUSE`](Lobes::DIFFUSE), [`GLOSSY`](Lobes::GLOSSY) or [`DELTA`](Lobes::DELTA)
/// per lobe.
///
/// The renderer asks it one question: does some lobe spread light over directions
/// ([`Lobes::has_non_delta`])? Only then are lights sampled at the surface; a delta lobe
/// (a perfect mirror, smooth glass) is reached only by the direction it samples.
#[derive(Clone, Copy, Default, PartialEq, Eq)]
pub struct Lobes(u8);

impl Lobes {
    /// No lobe: the surface absorbs everything (a black emitter).
    pub const NONE: Self = Self(0);
    /// Light stays on the side it came from.
    pub const REFLECTION: Self = Self(1);
    /// Light passes to the other side.
    pub const TRANSMISSION: Self = Self(2);
    /// Spread over the whole hemisphere (Lambertian).
    pub const DIFFUSE: Self = Self(4);
    /// Spread about a direction (a rough metal).
    pub const GLOSSY: Self = Self(8);
    /// A single direction, a Dirac delta (a mirror, smooth glass).
    pub const DELTA: Self = Self(16);

    /// Whether every lobe of `other` is in `self`.
    #[inline]
    pub const fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// Whether some lobe is diffuse or glossy, so sampling lights toward it pays.
    #[inline]
    pub const fn has_non_delta(self) -> bool {
        self.0 & (Self::DIFFUSE.0 | Self::GLOSSY.0) != 0
    }

    /// Whether this is (or includes) a delta lobe.
    #[inline]
    pub const fn is_delta(self) -> bool {
        self.contains(Self::DELTA)
    }
}

impl BitOr for Lobes {
    type Output = Self;
    #[inline]
    fn bitor(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }
}

impl fmt::Debug for Lobes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = [
            (Self::REFLECTION, "REFLECTION"),
            (Self::TRANSMISSION, "TRANSMISSION"),
            (Self::DIFFUSE, "DIFFUSE"),
            (Self::GLOSSY, "GLOSSY"),
            (Self::DELTA, "DELTA"),
        ];
        let set: Vec<_> = names
            .iter()
            .filter(|(l, _)| self.contains(*l))
            .map(|(_, n)| *n)
            .collect();
        if set.is_empty() {
            f.write_str("Lobes(NONE)")
        } else {
            write!(f, "Lobes({})", set.join(" | "))
        }
    }
}

/// The BSDF times the cosine, `f(wo, wi)·|cos θᵢ|`, kept as a colour and a scalar whose
/// product it is: `value = colour·scale`.
///
/// The renderer multiplies the light's colour into `colour` first and the scalar
/// factors (the cosine, `1/d²`, a MIS weight over a density) into `scale`, so each
/// material splits the product where its arithmetic is exact. The Lambertian gives
/// `(A/π, cos θᵢ)`, which keeps the point lights' `A/π · I · cos θ/d²` of the
/// specification's extra bit for bit; a microfacet BSDF gives its whole value and 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eval<F> {
    /// The colour factor.
    pub colour: Color<F>,
    /// The scalar factor.
    pub scale: F,
}

impl<F: Float> Eval<F> {
    /// `colour·scale`.
    #[inline]
    pub fn value(&self) -> Color<F> {
        self.colour * self.scale
    }
}

/// A direction a material drew for a ray leaving its surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample<F> {
    /// The unit direction `wi` the new ray leaves along (world space).
    pub direction: Vec3<F>,
    /// What the new ray's colour is multiplied by: `f·|cos θᵢ|/pdf`, which for the
    /// specification's three materials is their albedo `A` exactly (`C⁺ = A ∘ C⁻`).
    pub weight: Color<F>,
    /// The density `direction` was drawn with, per unit solid angle; for a delta lobe,
    /// the probability of choosing that lobe instead (not a density: no light sampling
    /// can draw the direction, so it is never weighed against one).
    pub pdf: F,
    /// The lobe drawn.
    pub lobe: Lobes,
}
