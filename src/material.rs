//! The spec's abstract material as a BSDF: the [`Material`] and [`Scatter`] traits,
//! what they answer ([`Lobes`], [`Eval`], [`BsdfSample`]), the concrete materials, and
//! [`MaterialKind`], the enum fast path over them.
//!
//! Besides the specification's three materials and the emitter, the materials of
//! Mitsuba 3 that scenes use most, each defined as Mitsuba defines it so that the two
//! renderers can be compared: [`Conductor`] and [`RoughConductor`] (metals, [`Metal`]),
//! [`RoughDielectric`], [`ThinDielectric`], [`Plastic`] and [`RoughPlastic`]
//! ([`Coated`]), and the [`TwoSided`] wrapper. The rough ones share a [`microfacet`]
//! distribution ([`Roughness`]); [`ior`] names the media and metals.

mod bsdf;
mod coating;
mod conductor;
mod dielectric;
mod emissive;
mod interface;
pub mod ior;
mod kind;
mod lambertian;
pub mod microfacet;
mod mirror;
mod normal_map;
mod param;
mod plastic;
mod rough_conductor;
mod rough_dielectric;
mod rough_plastic;
mod roughness;
mod shared;
mod thin_dielectric;
mod two_sided;

pub use bsdf::{BsdfSample, Eval, Lobes};
pub use conductor::{Conductor, Metal};
pub use dielectric::{Dielectric, Reflectance};
pub use emissive::{Emission, Emissive};
pub use interface::Interface;
pub use ior::Ior;
pub use kind::MaterialKind;
pub use lambertian::{CosineSampler, Lambertian};
pub use microfacet::{Distribution, Microfacet};
pub use mirror::Mirror;
pub use normal_map::NormalMap;
pub use plastic::{Coated, Plastic};
pub use rough_conductor::RoughConductor;
pub use rough_dielectric::RoughDielectric;
pub use rough_plastic::RoughPlastic;
pub use roughness::Roughness;
pub use shared::SharedMaterial;
pub use thin_dielectric::ThinDielectric;
pub use two_sided::TwoSided;

use crate::float::Float;
use crate::shape::Hit;
use crate::vec3::Vec3;
use rand::Rng;
use std::sync::Arc;

/// How a surface reflects, transmits and gives off light: the specification's abstract
/// material, as a BSDF at a hit.
///
/// The renderer asks a material only these questions and [`Scatter::sample`], never what
/// kind it is: point lights and sampled emitters light every material with a
/// [non-delta](Lobes::has_non_delta) lobe through [`eval`](Material::eval), and weigh
/// that light against the direction `sample` could have drawn through
/// [`pdf`](Material::pdf) (multiple importance sampling). It asks them of the material
/// that [`Scatter::resolve`] hands it at the hit: for an enum, the variant, found once a
/// hit. Adding a material is a type that answers them, and an arm in [`MaterialKind`]
/// (`docs/ADDING_A_MATERIAL.md`).
///
/// No method has a default, so an enum that wraps the library's materials must pass on
/// every answer or it does not compile (only [`Scatter::resolve`] has one, which is
/// right for any material, and which an enum overrides to be fast). No method here draws random numbers, so none
/// carries the generator's type: that is [`Scatter`]'s.
///
/// # Directions and frames
/// Every direction is a world-space unit vector pointing away from the surface: `wo`
/// toward where the ray came from (`wo = −D`), `wi` toward the light or the next
/// vertex. The [`Hit`] carries the shading normal, `∂p/∂u` and `uv`; a material that works
/// in local coordinates builds [`Hit::shading_frame`] (`cos θ = w.z` there), while the
/// specification's three materials keep its world-space formulas bit for bit.
///
/// # Shading normals
/// The geometric normal decides which side of the surface a direction is on; the shading
/// normal ([`Hit::shading_normal`], interpolated from a mesh's vertex normals or perturbed
/// by a normal map) is the one the BSDF shades with. As pbrt-v4 does, the shading normal
/// is turned to the geometric normal's side. Where the two still disagree about a
/// direction ([`Hit::sides_agree`]), the renderer lets no light through: a light the
/// geometry hides is not evaluated, a sampled direction that would cross the surface ends
/// the path, and a surface seen from a direction its shading normal faces away from
/// reflects nothing. So no light leaks through a closed surface, at the price of a little
/// energy at grazing angles.
pub trait Material<F: Float> {
    /// Every lobe the material may scatter into.
    fn lobes(&self) -> Lobes;

    /// Whether the material reads the hit's surface coordinates ([`Hit::uv`],
    /// [`Hit::dpdu`]): a texture, an anisotropic lobe, a normal map. Only then does the
    /// scene compute them (a sphere's `atan2` and `acos`); otherwise they are zero.
    fn reads_coordinates(&self) -> bool;

    /// `f(wo, wi)·|cos θᵢ|` of the non-delta lobes at `hit`, `θᵢ` the angle between `wi`
    /// and the shading normal; `None` when no light goes from `wi` to `wo` (`wi` below a
    /// reflecting surface, a delta lobe only), so the renderer traces no shadow ray.
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>>;

    /// The density per unit solid angle with which [`Scatter::sample`] draws `wi` for
    /// `wo` among its non-delta lobes (including the probability of choosing them); 0
    /// for a direction it never draws.
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F;

    /// The light the surface gives off, if it is an emitter ([`Emissive`]): a ray that
    /// hits it brings back `L_e` besides what it scatters.
    fn emits(&self) -> Option<Emission<F>>;
}

/// How a material draws the direction a ray leaves in: the one part of a material that
/// needs random numbers, so the one that carries the generator's type `R`. `R` is a
/// parameter of the trait, not of the method, so `dyn Scatter<F, R>` is a valid trait
/// object ([`SharedMaterial`] uses `R = dyn Rng`; [`resolve`](Scatter::resolve), generic,
/// is not part of it).
pub trait Scatter<F: Float, R: Rng + ?Sized>: Material<F> {
    /// A direction for the ray that arrived from `wo`, with its weight
    /// `f·|cos θᵢ|/pdf`, its density and its lobe; `None` if the surface absorbs the
    /// ray.
    ///
    /// It draws from `rng` as the method needs: a fixed count of uniform numbers for a
    /// closed-form warp (the pure warps take the numbers, as pbrt's do, and are tested
    /// without a generator), or as many as the specification's rejection method takes.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>>;

    /// Hands `visitor` the material that answers at `hit`, as a concrete type: the
    /// renderer asks it every question of one hit (emission, lobes, `eval` per light,
    /// `pdf`, `sample`) through static calls, where an enum would otherwise `match` on
    /// its kind for each (as pbrt-v4's `GetBSDF` resolves a material once a hit).
    ///
    /// The material handed must answer every question at `hit` exactly as `self` does.
    /// The default hands `self`, which is right for every material. An enum of materials
    /// ([`MaterialKind`]) overrides it with one `match` that passes each variant on; a
    /// material may also hand a simpler one (a [`Lambertian`] hands a matte surface of
    /// its albedo looked up at `hit`, so a texture is read once a hit).
    #[inline(always)]
    fn resolve<V: BsdfVisitor<F, R>>(&self, hit: &Hit<F>, visitor: V) -> V::Output
    where
        Self: Sized,
    {
        let _ = hit;
        visitor.visit(self)
    }
}

/// What [`Scatter::resolve`] calls with the material that answers at a hit: the
/// renderer's shading of that hit, monomorphised for each material it meets, so that
/// adding a material never touches the renderer.
pub trait BsdfVisitor<F: Float, R: Rng + ?Sized> {
    /// What the visit gives back (the renderer's next step).
    type Output;

    /// Shades with `material`, whose answers at the hit are the resolved material's.
    fn visit<B: Scatter<F, R> + ?Sized>(self, material: &B) -> Self::Output;
}

macro_rules! forward_material {
    ($($ptr:ty),*) => {$(
        impl<F: Float, T: Material<F> + ?Sized> Material<F> for $ptr {
            #[inline]
            fn lobes(&self) -> Lobes {
                (**self).lobes()
            }
            #[inline]
            fn reads_coordinates(&self) -> bool {
                (**self).reads_coordinates()
            }
            #[inline]
            fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
                (**self).eval(hit, wo, wi)
            }
            #[inline]
            fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
                (**self).pdf(hit, wo, wi)
            }
            #[inline]
            fn emits(&self) -> Option<Emission<F>> {
                (**self).emits()
            }
        }

        impl<F: Float, R: Rng + ?Sized, T: Scatter<F, R> + ?Sized> Scatter<F, R> for $ptr {
            #[inline]
            fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
                (**self).sample(hit, wo, rng)
            }
        }
    )*};
}
forward_material!(&T, Box<T>, Arc<T>);
