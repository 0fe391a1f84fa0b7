//! The library's values for a scene file's Mitsuba materials in a scalar `G`: the
//! constructors alone, which check every value (and the few rules only the file has:
//! `material` or `eta`/`k`, `alpha` or `alpha_u`/`alpha_v`).

use super::bsdf::{
    ConductorSpec, DistributionSpec, IorSpec, PlasticSpec, RoughConductorSpec, RoughDielectricSpec,
    RoughPlasticSpec, RoughnessSpec, ThinDielectricSpec,
};
use super::check::vec;
use super::resolve::{Inputs, TextureUse};
use super::texture_spec::{ScalarRef, TextureRef};
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::material::{
    Coated, Conductor, Distribution, Ior, MaterialKind, Metal, Plastic, RoughConductor, RoughDielectric,
    RoughPlastic, Roughness, ThinDielectric, TwoSided,
};
use crate::texture::Texture;

/// A colour as a constant texture.
fn colour<G: Float>(t: [f64; 3]) -> Texture<G> {
    Texture::constant(vec(t))
}

/// The texture of the colour key `key`.
fn texture<G: Float>(inputs: &mut dyn Inputs<G>, key: &str, value: &TextureRef) -> Result<Texture<G>> {
    inputs.texture(key, value, TextureUse::Color)
}

/// The texture of the number key `key` (a roughness), read as Mitsuba reads one.
fn scalar<G: Float>(inputs: &mut dyn Inputs<G>, key: &str, value: &ScalarRef) -> Result<Texture<G>> {
    inputs.texture(key, &value.0, TextureUse::Color)
}

fn distribution(d: DistributionSpec) -> Distribution {
    match d {
        DistributionSpec::Beckmann => Distribution::Beckmann,
        DistributionSpec::Ggx => Distribution::Ggx,
    }
}

fn ior(spec: &IorSpec) -> Ior {
    match spec {
        IorSpec::Value(v) => Ior::Value(*v),
        IorSpec::Named(name) => Ior::Named(name.clone()),
    }
}

/// The metal of a conductor's keys: `material` (default `none`), or `eta` (default 0)
/// and `k` (default 1), not both.
fn metal<G: Float>(
    inputs: &mut dyn Inputs<G>,
    material: &Option<String>,
    eta: Option<[f64; 3]>,
    k: Option<[f64; 3]>,
    specular: Option<&TextureRef>,
) -> Result<Metal<G>> {
    let metal = match (material, eta.is_some() || k.is_some()) {
        (Some(_), true) => {
            return Err(Error::invalid(
                Field::ConductorName,
                "give either a named `material` or its `eta` and `k`, not both",
            ));
        }
        (Some(name), false) => Metal::named(name)?,
        (None, true) => Metal::new(colour(eta.unwrap_or([0.0; 3])), colour(k.unwrap_or([1.0; 3])))?,
        (None, false) => Metal::named("none")?,
    };
    match specular {
        Some(s) => metal.with_specular_reflectance(texture(inputs, "specular_reflectance", s)?),
        None => Ok(metal),
    }
}

/// `alpha` (default 0.1), or `alpha_u` with `alpha_v`.
fn roughness<G: Float>(inputs: &mut dyn Inputs<G>, r: RoughnessSpec) -> Result<Roughness<G>> {
    let d = distribution(r.distribution);
    match (&r.alpha, &r.alpha_u, &r.alpha_v) {
        (Some(_), Some(_), _) | (Some(_), _, Some(_)) => Err(Error::invalid(
            Field::Alpha,
            "give either `alpha` or `alpha_u` and `alpha_v`, not both",
        )),
        (_, Some(u), Some(v)) => {
            let u = scalar(inputs, "alpha_u", u)?;
            Roughness::anisotropic(d, u, scalar(inputs, "alpha_v", v)?)
        }
        (_, Some(_), None) => Err(Error::invalid(Field::AlphaV, "`alpha_u` needs `alpha_v`")),
        (_, None, Some(_)) => Err(Error::invalid(Field::AlphaU, "`alpha_v` needs `alpha_u`")),
        (Some(alpha), None, None) => Roughness::isotropic(d, scalar(inputs, "alpha", alpha)?),
        (None, None, None) => Roughness::isotropic(d, Texture::scalar(lit::<G>(0.1))),
    }
}

/// `type = "conductor"`.
pub fn conductor<G: Float>(c: &ConductorSpec, inputs: &mut dyn Inputs<G>) -> Result<MaterialKind<G>> {
    let metal = metal(inputs, &c.material, c.eta, c.k, c.specular_reflectance.as_ref())?;
    Ok(Conductor::new(metal).into())
}

/// `type = "rough_conductor"`.
pub fn rough_conductor<G: Float>(
    c: &RoughConductorSpec,
    inputs: &mut dyn Inputs<G>,
) -> Result<MaterialKind<G>> {
    let metal = metal(inputs, &c.material, c.eta, c.k, c.specular_reflectance.as_ref())?;
    Ok(RoughConductor::new(metal, roughness(inputs, c.roughness())?).into())
}

/// `type = "rough_dielectric"`.
pub fn rough_dielectric<G: Float>(
    d: &RoughDielectricSpec,
    inputs: &mut dyn Inputs<G>,
) -> Result<MaterialKind<G>> {
    let mut m = RoughDielectric::new(
        roughness(inputs, d.roughness())?,
        ior(&d.int_ior),
        ior(&d.ext_ior),
    )?;
    if let Some(s) = &d.specular_reflectance {
        m = m.with_specular_reflectance(texture(inputs, "specular_reflectance", s)?)?;
    }
    if let Some(t) = &d.specular_transmittance {
        m = m.with_specular_transmittance(texture(inputs, "specular_transmittance", t)?)?;
    }
    Ok(m.into())
}

/// `type = "thin_dielectric"`.
pub fn thin_dielectric<G: Float>(
    d: &ThinDielectricSpec,
    inputs: &mut dyn Inputs<G>,
) -> Result<MaterialKind<G>> {
    let mut m = ThinDielectric::new(ior(&d.int_ior), ior(&d.ext_ior))?;
    if let Some(s) = &d.specular_reflectance {
        m = m.with_specular_reflectance(texture(inputs, "specular_reflectance", s)?)?;
    }
    if let Some(t) = &d.specular_transmittance {
        m = m.with_specular_transmittance(texture(inputs, "specular_transmittance", t)?)?;
    }
    Ok(m.into())
}

fn coated<G: Float>(
    inputs: &mut dyn Inputs<G>,
    (diffuse, specular): (&TextureRef, Option<&TextureRef>),
    (int, ext): (&IorSpec, &IorSpec),
    nonlinear: bool,
) -> Result<Coated<G>> {
    let diffuse = texture(inputs, "diffuse_reflectance", diffuse)?;
    let mut c = Coated::new(diffuse, ior(int), ior(ext))?;
    if let Some(s) = specular {
        c = c.with_specular_reflectance(texture(inputs, "specular_reflectance", s)?)?;
    }
    Ok(c.nonlinear(nonlinear))
}

/// `type = "plastic"`.
pub fn plastic<G: Float>(p: &PlasticSpec, inputs: &mut dyn Inputs<G>) -> Result<MaterialKind<G>> {
    let c = coated(
        inputs,
        (&p.diffuse_reflectance, p.specular_reflectance.as_ref()),
        (&p.int_ior, &p.ext_ior),
        p.nonlinear,
    )?;
    Ok(Plastic::new(c).into())
}

/// `type = "rough_plastic"`.
pub fn rough_plastic<G: Float>(p: &RoughPlasticSpec, inputs: &mut dyn Inputs<G>) -> Result<MaterialKind<G>> {
    let c = coated(
        inputs,
        (&p.diffuse_reflectance, p.specular_reflectance.as_ref()),
        (&p.int_ior, &p.ext_ior),
        p.nonlinear,
    )?;
    Ok(RoughPlastic::new(c, distribution(p.distribution), lit(p.alpha))?.into())
}

/// `type = "two_sided"` of the materials made of its `front` and `back` tables.
pub fn two_sided<G: Float>(front: MaterialKind<G>, back: Option<MaterialKind<G>>) -> Result<MaterialKind<G>> {
    let two = TwoSided::new(front)?;
    Ok(match back {
        Some(back) => two.with_back(back)?,
        None => two,
    }
    .into())
}
