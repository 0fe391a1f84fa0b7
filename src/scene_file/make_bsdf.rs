//! The library's values for a scene file's Mitsuba materials in a scalar `G`: the
//! constructors alone, which check every value (and the few rules only the file has:
//! `material` or `eta`/`k`, `alpha` or `alpha_u`/`alpha_v`).

use super::bsdf::{
    ConductorSpec, DistributionSpec, IorSpec, PlasticSpec, RoughConductorSpec, RoughDielectricSpec,
    RoughPlasticSpec, RoughnessSpec, ThinDielectricSpec,
};
use super::check::vec;
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
    material: &Option<String>,
    eta: Option<[f64; 3]>,
    k: Option<[f64; 3]>,
    specular: Option<[f64; 3]>,
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
        Some(s) => metal.with_specular_reflectance(colour(s)),
        None => Ok(metal),
    }
}

/// `alpha` (default 0.1), or `alpha_u` with `alpha_v`.
fn roughness<G: Float>(r: RoughnessSpec) -> Result<Roughness<G>> {
    let d = distribution(r.distribution);
    let scalar = |a: f64| Texture::scalar(lit::<G>(a));
    match (r.alpha, r.alpha_u, r.alpha_v) {
        (Some(_), Some(_), _) | (Some(_), _, Some(_)) => Err(Error::invalid(
            Field::Alpha,
            "give either `alpha` or `alpha_u` and `alpha_v`, not both",
        )),
        (_, Some(u), Some(v)) => Roughness::anisotropic(d, scalar(u), scalar(v)),
        (_, Some(_), None) => Err(Error::invalid(Field::AlphaV, "`alpha_u` needs `alpha_v`")),
        (_, None, Some(_)) => Err(Error::invalid(Field::AlphaU, "`alpha_v` needs `alpha_u`")),
        (alpha, None, None) => Roughness::isotropic(d, scalar(alpha.unwrap_or(0.1))),
    }
}

/// `type = "conductor"`.
pub fn conductor<G: Float>(c: &ConductorSpec) -> Result<MaterialKind<G>> {
    Ok(Conductor::new(metal(&c.material, c.eta, c.k, c.specular_reflectance)?).into())
}

/// `type = "rough_conductor"`.
pub fn rough_conductor<G: Float>(c: &RoughConductorSpec) -> Result<MaterialKind<G>> {
    let metal = metal(&c.material, c.eta, c.k, c.specular_reflectance)?;
    Ok(RoughConductor::new(metal, roughness(c.roughness())?).into())
}

/// `type = "rough_dielectric"`.
pub fn rough_dielectric<G: Float>(d: &RoughDielectricSpec) -> Result<MaterialKind<G>> {
    let mut m = RoughDielectric::new(roughness(d.roughness())?, ior(&d.int_ior), ior(&d.ext_ior))?;
    if let Some(s) = d.specular_reflectance {
        m = m.with_specular_reflectance(colour(s))?;
    }
    if let Some(t) = d.specular_transmittance {
        m = m.with_specular_transmittance(colour(t))?;
    }
    Ok(m.into())
}

/// `type = "thin_dielectric"`.
pub fn thin_dielectric<G: Float>(d: &ThinDielectricSpec) -> Result<MaterialKind<G>> {
    let mut m = ThinDielectric::new(ior(&d.int_ior), ior(&d.ext_ior))?;
    if let Some(s) = d.specular_reflectance {
        m = m.with_specular_reflectance(colour(s))?;
    }
    if let Some(t) = d.specular_transmittance {
        m = m.with_specular_transmittance(colour(t))?;
    }
    Ok(m.into())
}

fn coated<G: Float>(
    diffuse: [f64; 3],
    specular: Option<[f64; 3]>,
    (int, ext): (&IorSpec, &IorSpec),
    nonlinear: bool,
) -> Result<Coated<G>> {
    let mut c = Coated::new(colour(diffuse), ior(int), ior(ext))?;
    if let Some(s) = specular {
        c = c.with_specular_reflectance(colour(s))?;
    }
    Ok(c.nonlinear(nonlinear))
}

/// `type = "plastic"`.
pub fn plastic<G: Float>(p: &PlasticSpec) -> Result<MaterialKind<G>> {
    let c = coated(
        p.diffuse_reflectance,
        p.specular_reflectance,
        (&p.int_ior, &p.ext_ior),
        p.nonlinear,
    )?;
    Ok(Plastic::new(c).into())
}

/// `type = "rough_plastic"`.
pub fn rough_plastic<G: Float>(p: &RoughPlasticSpec) -> Result<MaterialKind<G>> {
    let c = coated(
        p.diffuse_reflectance,
        p.specular_reflectance,
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
