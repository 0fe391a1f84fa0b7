//! The spec's abstract material: the [`Material`] trait, the [`Scatter`] it returns,
//! and [`MaterialKind`], the enum fast path over the concrete materials.

mod dielectric;
mod emissive;
mod lambertian;
mod mirror;

pub use dielectric::{Dielectric, Reflectance};
pub use emissive::{Emission, Emissive};
pub use lambertian::{CosineSampler, Lambertian};
pub use mirror::Mirror;

use crate::float::Float;
use crate::ray::Ray;
use crate::shape::Hit;
use crate::vec3::{Color, Vec3};
use rand::Rng;
use std::sync::Arc;

/// What a hit does to a ray: absorbs part of its colour and sends it on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scatter<F> {
    /// The albedo `A` applied to the continuing ray's colour: `C⁺ = A ∘ C⁻`.
    pub attenuation: Color<F>,
    /// The continuing ray's unit direction `D⁺`.
    pub direction: Vec3<F>,
}

/// How a surface changes a ray that hits it: the specification's abstract material.
///
/// Generic over the scalar `F` and the random generator `R`; `R` is a parameter of the
/// trait (not of the method) so `dyn Material<F, R>` is a valid trait object.
pub trait Material<F: Float, R: Rng + ?Sized> {
    /// The scattered ray's direction and attenuation, or `None` if the ray is absorbed.
    fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>>;

    /// For an ideal diffuse (Lambertian) surface, its albedo `A`: the renderer then adds
    /// direct light from point lights and from sampled emitters with the BRDF `A/π`, and
    /// weighs the light its scattered ray finds on an emitter as that of a direction drawn
    /// with density `cos θ/π` (multiple importance sampling). `None` for other surfaces,
    /// whose scattered rays count the light they find in full.
    #[inline]
    fn diffuse_albedo(&self) -> Option<Color<F>> {
        None
    }

    /// The light this surface gives off, if any (an area light, [`Emissive`]): a ray that
    /// hits it brings back `L_e` besides what it scatters. `None` (the default) for
    /// surfaces that give off no light.
    #[inline]
    fn emission(&self) -> Option<Emission<F>> {
        None
    }
}

macro_rules! forward_material {
    ($($ptr:ty),*) => {$(
        impl<F: Float, R: Rng + ?Sized, T: Material<F, R> + ?Sized> Material<F, R> for $ptr {
            #[inline]
            fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>> {
                (**self).scatter(ray, hit, rng)
            }
            #[inline]
            fn diffuse_albedo(&self) -> Option<Color<F>> {
                (**self).diffuse_albedo()
            }
            #[inline]
            fn emission(&self) -> Option<Emission<F>> {
                (**self).emission()
            }
        }
    )*};
}
forward_material!(&T, Box<T>, Arc<T>);

/// A material behind a shared pointer, as a trait object: the material type of a
/// [`DynScene`](crate::DynScene), where one material may serve many objects.
///
/// `Arc::new(my_material).into()` makes one (so `scene.add(Box::new(shape),
/// Arc::new(material))` needs no casts), and so does an `Arc<dyn Material>` already shared.
#[derive(Clone)]
pub struct SharedMaterial<F, R: ?Sized>(pub Arc<dyn Material<F, R> + Send + Sync>);

impl<F: Float, R: Rng + ?Sized, T: Material<F, R> + Send + Sync + 'static> From<Arc<T>>
    for SharedMaterial<F, R>
{
    fn from(material: Arc<T>) -> Self {
        Self(material)
    }
}

impl<F: Float, R: Rng + ?Sized> From<Arc<dyn Material<F, R> + Send + Sync>> for SharedMaterial<F, R> {
    fn from(material: Arc<dyn Material<F, R> + Send + Sync>) -> Self {
        Self(material)
    }
}

impl<F: Float, R: Rng + ?Sized> Material<F, R> for SharedMaterial<F, R> {
    #[inline]
    fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>> {
        self.0.scatter(ray, hit, rng)
    }
    #[inline]
    fn diffuse_albedo(&self) -> Option<Color<F>> {
        self.0.diffuse_albedo()
    }
    #[inline]
    fn emission(&self) -> Option<Emission<F>> {
        self.0.emission()
    }
}

impl<F, R: ?Sized> std::fmt::Debug for SharedMaterial<F, R> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SharedMaterial(dyn Material)")
    }
}

/// The enum fast path: every concrete material, dispatched by `match`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MaterialKind<F> {
    /// A [`Mirror`].
    Mirror(Mirror<F>),
    /// A matte [`Lambertian`] surface.
    Lambertian(Lambertian<F>),
    /// A refracting [`Dielectric`] (glass).
    Dielectric(Dielectric<F>),
    /// A light-giving [`Emissive`] surface.
    Emissive(Emissive<F>),
}

impl<F: Float, R: Rng + ?Sized> Material<F, R> for MaterialKind<F> {
    #[inline(always)]
    fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>> {
        match self {
            Self::Mirror(m) => Material::<F, R>::scatter(m, ray, hit, rng),
            Self::Lambertian(m) => m.scatter(ray, hit, rng),
            Self::Dielectric(m) => m.scatter(ray, hit, rng),
            Self::Emissive(m) => m.scatter(ray, hit, rng),
        }
    }
    #[inline]
    fn diffuse_albedo(&self) -> Option<Color<F>> {
        match self {
            Self::Mirror(m) => Material::<F, R>::diffuse_albedo(m),
            Self::Lambertian(m) => Material::<F, R>::diffuse_albedo(m),
            Self::Dielectric(m) => Material::<F, R>::diffuse_albedo(m),
            Self::Emissive(m) => Material::<F, R>::diffuse_albedo(m),
        }
    }
    #[inline]
    fn emission(&self) -> Option<Emission<F>> {
        match self {
            Self::Emissive(m) => Material::<F, R>::emission(m),
            _ => None,
        }
    }
}

impl<F> From<Mirror<F>> for MaterialKind<F> {
    fn from(m: Mirror<F>) -> Self {
        Self::Mirror(m)
    }
}

impl<F> From<Lambertian<F>> for MaterialKind<F> {
    fn from(m: Lambertian<F>) -> Self {
        Self::Lambertian(m)
    }
}

impl<F> From<Dielectric<F>> for MaterialKind<F> {
    fn from(m: Dielectric<F>) -> Self {
        Self::Dielectric(m)
    }
}

impl<F> From<Emissive<F>> for MaterialKind<F> {
    fn from(m: Emissive<F>) -> Self {
        Self::Emissive(m)
    }
}

impl<F: Float> MaterialKind<F> {
    /// This material in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> crate::error::Result<MaterialKind<G>> {
        Ok(match self {
            Self::Mirror(m) => Mirror::new(m.albedo().cast())?.into(),
            Self::Lambertian(m) => Lambertian::new(m.albedo().cast())?
                .with_sampler(m.sampler())
                .into(),
            Self::Dielectric(m) => Dielectric::new(crate::float::to(m.refractive_index()))?
                .with_albedo(m.albedo().cast())?
                .with_reflectance(m.reflectance())
                .into(),
            Self::Emissive(m) => m.cast()?.into(),
        })
    }
}
