//! [`MaterialKind`]: the enum fast path over the concrete materials.

use super::{
    BsdfSample, BsdfVisitor, Conductor, Dielectric, Emission, Emissive, Eval, Lambertian, Lobes, Material,
    Mirror, NormalMap, Plastic, RoughConductor, RoughDielectric, RoughPlastic, Scatter, ThinDielectric,
    TwoSided,
};
use crate::float::Float;
use crate::shape::Hit;
use crate::vec3::Vec3;
use rand::Rng;
use std::sync::Arc;

/// The enum fast path: every concrete material, dispatched by `match`.
///
/// The specification's materials are stored inline; the others, larger (textures, tables,
/// a wrapped material), behind an `Arc`, shared by every object that uses them, so a scene
/// of the spec's materials keeps its small objects (and the enum is `Clone`, not `Copy`: a
/// matte surface's albedo may be a texture).
// A tag of its own: without one, in f64 the kind sits in a niche of the emitter's
// `two_sided` flag and each `match` a hit decodes it with five more instructions. It costs
// a few bytes a material in the scene's table, none an object.
#[derive(Clone, Debug, PartialEq)]
#[repr(u32)]
pub enum MaterialKind<F> {
    /// A [`Mirror`].
    Mirror(Mirror<F>),
    /// A matte [`Lambertian`] surface.
    Lambertian(Lambertian<F>),
    /// A refracting [`Dielectric`] (glass).
    Dielectric(Dielectric<F>),
    /// A light-giving [`Emissive`] surface.
    Emissive(Emissive<F>),
    /// Another material under a [`NormalMap`] (behind an `Arc`: the wrapped material is
    /// one of these).
    NormalMap(Arc<NormalMap<F>>),
    /// A smooth [`Conductor`] (a polished metal).
    Conductor(Arc<Conductor<F>>),
    /// A [`RoughConductor`] (a brushed metal).
    RoughConductor(Arc<RoughConductor<F>>),
    /// A [`RoughDielectric`] (frosted glass).
    RoughDielectric(Arc<RoughDielectric<F>>),
    /// A [`ThinDielectric`] sheet (a window pane).
    ThinDielectric(Arc<ThinDielectric<F>>),
    /// A smooth [`Plastic`].
    Plastic(Arc<Plastic<F>>),
    /// A [`RoughPlastic`].
    RoughPlastic(Arc<RoughPlastic<F>>),
    /// A [`TwoSided`] wrapper.
    TwoSided(Arc<TwoSided<F>>),
}

/// `match` on a [`MaterialKind`], the same call on every variant: no arm can be left out.
///
/// With `; shared`, the materials stored behind an `Arc` all take the `shared` arm, which
/// calls one out-of-line function: the spec's materials stay inlined into the renderer's
/// loop without the others' code growing it past what the compiler inlines.
macro_rules! each_material {
    ($material:expr, $m:ident => $call:expr) => {
        match $material {
            MaterialKind::Mirror($m) => $call,
            MaterialKind::Lambertian($m) => $call,
            MaterialKind::Dielectric($m) => $call,
            MaterialKind::Emissive($m) => $call,
            MaterialKind::NormalMap($m) => $call,
            MaterialKind::Conductor($m) => $call,
            MaterialKind::RoughConductor($m) => $call,
            MaterialKind::RoughDielectric($m) => $call,
            MaterialKind::ThinDielectric($m) => $call,
            MaterialKind::Plastic($m) => $call,
            MaterialKind::RoughPlastic($m) => $call,
            MaterialKind::TwoSided($m) => $call,
        }
    };
    ($material:expr, $m:ident => $inline:expr; $shared:expr) => {
        match $material {
            MaterialKind::Mirror($m) => $inline,
            MaterialKind::Lambertian($m) => $inline,
            MaterialKind::Dielectric($m) => $inline,
            MaterialKind::Emissive($m) => $inline,
            MaterialKind::NormalMap(_)
            | MaterialKind::Conductor(_)
            | MaterialKind::RoughConductor(_)
            | MaterialKind::RoughDielectric(_)
            | MaterialKind::ThinDielectric(_)
            | MaterialKind::Plastic(_)
            | MaterialKind::RoughPlastic(_)
            | MaterialKind::TwoSided(_) => $shared,
        }
    };
}

// Dispatch always inlined for the spec's materials: a call per light and per bounce
// otherwise, with the hit in memory.
impl<F: Float> Material<F> for MaterialKind<F> {
    #[inline(always)]
    fn lobes(&self) -> Lobes {
        each_material!(self, m => m.lobes(); Shared(self).lobes())
    }
    #[inline(always)]
    fn reads_coordinates(&self) -> bool {
        each_material!(self, m => m.reads_coordinates(); Shared(self).reads_coordinates())
    }
    #[inline(always)]
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        each_material!(self, m => m.eval(hit, wo, wi); Shared(self).eval(&{ *hit }, wo, wi))
    }
    #[inline(always)]
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        each_material!(self, m => m.pdf(hit, wo, wi); Shared(self).pdf(&{ *hit }, wo, wi))
    }
    #[inline(always)]
    fn emits(&self) -> Option<Emission<F>> {
        each_material!(self, m => m.emits(); Shared(self).emits())
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for MaterialKind<F> {
    #[inline(always)]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        each_material!(self, m => m.sample(hit, wo, rng); Shared(self).sample(&{ *hit }, wo, rng))
    }

    /// One `match`: each of the specification's three materials resolves itself; the
    /// emitter and the materials behind an `Arc` are visited as one material whose every
    /// answer is an out-of-line call that matches on them, so the renderer's loop holds
    /// the shading of four kinds, not of twelve.
    // The visit is inlined for `Shared` too: out of line, it took the visitor (the hit)
    // and returned the step through memory on every path. The emitter is `Shared`'s: its
    // own shading (a second light loop, for a reflecting emitter) in the loop made the
    // spec's materials' shading around it spill more.
    #[inline(always)]
    fn resolve<V: BsdfVisitor<F, R>>(&self, hit: &Hit<F>, visitor: V) -> V::Output {
        match self {
            MaterialKind::Mirror(m) => Scatter::<F, R>::resolve(m, hit, visitor),
            MaterialKind::Lambertian(m) => Scatter::<F, R>::resolve(m, hit, visitor),
            MaterialKind::Dielectric(m) => Scatter::<F, R>::resolve(m, hit, visitor),
            MaterialKind::Emissive(_)
            | MaterialKind::NormalMap(_)
            | MaterialKind::Conductor(_)
            | MaterialKind::RoughConductor(_)
            | MaterialKind::RoughDielectric(_)
            | MaterialKind::ThinDielectric(_)
            | MaterialKind::Plastic(_)
            | MaterialKind::RoughPlastic(_)
            | MaterialKind::TwoSided(_) => visitor.visit(&Shared(self)),
        }
    }
}

/// A [`MaterialKind`] asked out of line: every method one call that matches on every
/// variant (the spec's too, so no arm is left out, though [`MaterialKind`] sends only the
/// others here). A caller in the renderer's loop passes a copy of its hit made in the
/// branch that calls: its own hit, by reference, would have to live in memory on every
/// path.
#[derive(Clone, Copy)]
struct Shared<'a, F>(&'a MaterialKind<F>);

impl<F: Float> Material<F> for Shared<'_, F> {
    #[inline(never)]
    fn lobes(&self) -> Lobes {
        each_material!(self.0, m => m.lobes())
    }
    #[inline(never)]
    fn reads_coordinates(&self) -> bool {
        each_material!(self.0, m => m.reads_coordinates())
    }
    #[inline(never)]
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        each_material!(self.0, m => m.eval(hit, wo, wi))
    }
    #[inline(never)]
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        each_material!(self.0, m => m.pdf(hit, wo, wi))
    }
    #[inline(never)]
    fn emits(&self) -> Option<Emission<F>> {
        each_material!(self.0, m => m.emits())
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Shared<'_, F> {
    #[inline(never)]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        each_material!(self.0, m => m.sample(hit, wo, rng))
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

/// `From` a material stored behind an `Arc`: the material itself or its `Arc`.
macro_rules! from_shared {
    ($($t:ident),*) => {$(
        impl<F> From<$t<F>> for MaterialKind<F> {
            fn from(m: $t<F>) -> Self {
                Self::$t(Arc::new(m))
            }
        }

        impl<F> From<Arc<$t<F>>> for MaterialKind<F> {
            fn from(m: Arc<$t<F>>) -> Self {
                Self::$t(m)
            }
        }
    )*};
}
from_shared!(
    Conductor,
    RoughConductor,
    RoughDielectric,
    ThinDielectric,
    Plastic,
    RoughPlastic,
    TwoSided,
    NormalMap
);

impl<F: Float> MaterialKind<F> {
    /// This material in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> crate::error::Result<MaterialKind<G>> {
        Ok(match self {
            Self::Mirror(m) => Mirror::new(m.albedo().cast())?.into(),
            Self::Lambertian(m) => Lambertian::textured(m.albedo().cast::<G>()?)?
                .with_sampler(m.sampler())
                .into(),
            Self::Dielectric(m) => Dielectric::new(crate::float::to(m.refractive_index()))?
                .with_albedo(m.albedo().cast())?
                .with_reflectance(m.reflectance())
                .into(),
            Self::Emissive(m) => m.cast()?.into(),
            Self::NormalMap(m) => m.cast()?.into(),
            Self::Conductor(m) => m.cast()?.into(),
            Self::RoughConductor(m) => m.cast()?.into(),
            Self::RoughDielectric(m) => m.cast()?.into(),
            Self::ThinDielectric(m) => m.cast()?.into(),
            Self::Plastic(m) => m.cast()?.into(),
            Self::RoughPlastic(m) => m.cast()?.into(),
            Self::TwoSided(m) => m.cast()?.into(),
        })
    }
}
