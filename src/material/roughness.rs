//! [`Roughness`]: a rough surface's microfacet distribution and its `α`, each `α` a
//! texture, made into a [`Microfacet`] at each hit.

use super::microfacet::{Distribution, Microfacet};
use super::param;
use crate::error::{Field, Result};
use crate::float::Float;
use crate::shape::Hit;
use crate::texture::Texture;

/// The roughness of a rough conductor or dielectric: a [`Distribution`] and its `α`,
/// isotropic (one `α`) or anisotropic (`αu` along the surface's `∂p/∂u`, `αv` across),
/// as Mitsuba's `alpha` or `alpha_u`/`alpha_v`. Each `α` is a texture read as a number
/// ([`Texture::eval_scalar`]).
///
/// `α` is the RMS slope of the microfacets (Beckmann) or its GGX counterpart: `0.01` a
/// polished surface, `0.1` a slightly rough one, `0.3` and more a matte one. `α ≤ 0` and
/// NaN are refused; any `α > 0` is accepted and used from [`MIN_ALPHA`](super::microfacet::MIN_ALPHA)
/// on (a texture giving less is raised to it).
#[derive(Clone, Debug, PartialEq)]
pub struct Roughness<F> {
    distribution: Distribution,
    alpha_u: Texture<F>,
    alpha_v: Texture<F>,
    anisotropic: bool,
}

impl<F: Float> Roughness<F> {
    /// The same `α` in every direction; `α` must be finite and `> 0`.
    pub fn isotropic(distribution: Distribution, alpha: Texture<F>) -> Result<Self> {
        let alpha = param::positive(Field::Alpha, alpha)?;
        Ok(Self {
            distribution,
            alpha_u: alpha.clone(),
            alpha_v: alpha,
            anisotropic: false,
        })
    }

    /// `αu` along the tangent `∂p/∂u`, `αv` along the bitangent; each finite and `> 0`.
    pub fn anisotropic(distribution: Distribution, alpha_u: Texture<F>, alpha_v: Texture<F>) -> Result<Self> {
        Ok(Self {
            distribution,
            alpha_u: param::positive(Field::AlphaU, alpha_u)?,
            alpha_v: param::positive(Field::AlphaV, alpha_v)?,
            anisotropic: true,
        })
    }

    /// The distribution.
    pub fn distribution(&self) -> Distribution {
        self.distribution
    }

    /// `αu` (the only `α` if isotropic).
    pub fn alpha_u(&self) -> &Texture<F> {
        &self.alpha_u
    }

    /// `αv` (the only `α` if isotropic).
    pub fn alpha_v(&self) -> &Texture<F> {
        &self.alpha_v
    }

    /// Whether it was made anisotropic.
    pub fn is_anisotropic(&self) -> bool {
        self.anisotropic
    }

    /// The distribution at `hit`, its `α` looked up there.
    #[inline]
    pub fn at(&self, hit: &Hit<F>) -> Microfacet<F> {
        let alpha_u = self.alpha_u.eval_scalar(hit);
        let alpha_v = if self.anisotropic {
            self.alpha_v.eval_scalar(hit)
        } else {
            alpha_u
        };
        Microfacet::new(self.distribution, alpha_u, alpha_v)
    }

    /// Whether the hit's coordinates are needed: a textured `α` reads `uv`, an anisotropic
    /// one the tangent `∂p/∂u` its frame is built on.
    pub fn reads_coordinates(&self) -> bool {
        self.anisotropic || self.alpha_u.reads_coordinates() || self.alpha_v.reads_coordinates()
    }

    /// This roughness in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<Roughness<G>> {
        if self.anisotropic {
            Roughness::anisotropic(
                self.distribution,
                param::cast(&self.alpha_u)?,
                param::cast(&self.alpha_v)?,
            )
        } else {
            Roughness::isotropic(self.distribution, param::cast(&self.alpha_u)?)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn any_positive_alpha_is_accepted_and_nothing_else() {
        let scalar = |a: f64| Texture::scalar(a);
        for a in [1e-4, 1e-9, 0.1, 1.0, 50.0] {
            assert!(Roughness::isotropic(Distribution::Ggx, scalar(a)).is_ok(), "{a}");
        }
        for a in [0.0, -0.1, f64::NAN, f64::INFINITY] {
            let e = Roughness::isotropic(Distribution::Ggx, scalar(a)).unwrap_err();
            assert!(
                matches!(
                    e,
                    crate::Error::InvalidValue {
                        field: Field::Alpha,
                        ..
                    }
                ),
                "{a}: {e}"
            );
            let e = Roughness::anisotropic(Distribution::Beckmann, scalar(0.1), scalar(a)).unwrap_err();
            assert!(
                matches!(
                    e,
                    crate::Error::InvalidValue {
                        field: Field::AlphaV,
                        ..
                    }
                ),
                "{a}: {e}"
            );
        }
        // A colour texture must be positive in every channel it holds.
        let mixed = Texture::constant(crate::vec3::Vec3::new(0.1, 0.0, 0.1));
        assert!(Roughness::isotropic(Distribution::Ggx, mixed).is_err());
    }

    #[test]
    fn the_distribution_at_a_hit_is_made_of_its_alphas() {
        let r = Roughness::anisotropic(Distribution::Ggx, Texture::scalar(0.2f64), Texture::scalar(0.05))
            .unwrap();
        assert!(r.is_anisotropic() && r.reads_coordinates());
        let hit = Hit::new(
            crate::shape::Surface::bare(
                1.0,
                crate::vec3::Vec3::zero(),
                crate::vec3::Vec3::new(0.0, 0.0, 1.0),
            ),
            crate::vec3::Vec3::new(0.0, 0.0, -1.0),
        );
        assert_eq!(r.at(&hit).alpha(), (0.2, 0.05));
        let iso = Roughness::isotropic(Distribution::Beckmann, Texture::scalar(1e-6f64)).unwrap();
        assert!(!iso.reads_coordinates());
        assert_eq!(iso.at(&hit).alpha(), (1e-4, 1e-4), "raised to the floor");
        assert_eq!(
            iso.cast::<f32>()
                .unwrap()
                .at(&Hit::new(
                    crate::shape::Surface::bare(
                        1.0,
                        crate::vec3::Vec3::zero(),
                        crate::vec3::Vec3::new(0.0, 0.0, 1.0)
                    ),
                    crate::vec3::Vec3::new(0.0, 0.0, -1.0),
                ))
                .alpha(),
            (1e-4, 1e-4)
        );
    }
}
