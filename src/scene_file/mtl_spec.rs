//! An OBJ material (`newmtl` of a `.mtl` file) as a scene file's material: the mapping
//! `docs/SCENE_FORMAT.md` writes down ("OBJ materials"), as a [`MaterialSpec`] whose
//! image keys name the `.mtl` file's maps ([`DIFFUSE_MAP`]).

use super::bsdf::{DistributionSpec, IorSpec, RoughConductorSpec, RoughPlasticSpec, TwoSidedSpec};
use super::model::{FresnelSpec, MaterialSpec};
use super::texture_spec::{ScalarRef, TextureRef};
use crate::mesh::{At, MtlMaterial};

/// The name a mapped material's colour key gives its `map_Kd` image by.
pub const DIFFUSE_MAP: &str = "map_Kd";

/// The diffuse colour without `Kd`: Blender's default material's (the MTL format gives none).
pub const DEFAULT_KD: [f64; 3] = [0.8; 3];

/// A glass's index without `Ni`.
pub const DEFAULT_NI: f64 = 1.5;

/// The rough plastic's or metal's `α` without `Ns`: `rough_plastic`'s default.
pub const DEFAULT_ALPHA: f64 = 0.1;

/// The Beckmann roughness of a Phong exponent, `α = √(2/(Ns + 2))` (Walter et al. 2007,
/// "Microfacet models for refraction through rough surfaces", eq. 30): the lobe of the
/// same width.
pub fn alpha_of_exponent(ns: f64) -> f64 {
    (2.0 / (ns + 2.0)).sqrt()
}

/// What an MTL material maps to: the material's table and what was not carried over.
#[derive(Clone, Debug, PartialEq)]
pub struct Mapped {
    /// The material, its `map_Kd` named [`DIFFUSE_MAP`]; a normal map (`norm`, or a
    /// `map_Bump` in colour) wraps it, which the caller decides on reading the image.
    pub spec: MaterialSpec,
    /// The keys that have no effect here, each with why, for a warning.
    pub unused: Vec<(At<&'static str>, &'static str)>,
}

/// Whether any channel is above zero.
fn bright(c: [f64; 3]) -> bool {
    c.iter().any(|&x| x > 0.0)
}

/// The material `m` maps to, in this order of rules:
/// 1. `Ke` above zero: an emitter of radiance `Ke`, reflecting as matte `Kd` if given;
/// 2. `d < 1`, or `illum` 4, 6, 7 or 9 (the transparent models): a smooth dielectric of
///    index `Ni` (1.5 without it), tinted by `Tf`, with the exact Fresnel reflectance;
/// 3. `illum` 3, 5 or 8 (reflection on), `Ks` above zero and `Kd` black or absent: a
///    polished metal, a rough perfect mirror of `specular_reflectance = Ks`;
/// 4. `Ks` above zero and `illum` not 0 or 1 (highlights on): a rough plastic, its base
///    `Kd` (or `map_Kd`) under a coat reflecting `Ks` times the coat's Fresnel reflectance;
/// 5. otherwise a matte surface of albedo `Kd` (or `map_Kd`; 0.8 without either).
///
/// A metal's and a plastic's `α` is [`alpha_of_exponent`]`(Ns)` (Beckmann), and both are
/// wrapped in `two_sided`: an OBJ surface has no back that should be black.
///
/// # Errors
/// The key, its line and why, for an `Ns` below 0.
pub fn map(m: &MtlMaterial) -> Result<Mapped, (At<&'static str>, String)> {
    let value = |x: &Option<At<[f64; 3]>>| x.as_ref().map(|c| c.value);
    let at = |key: &'static str, line: u64| At { value: key, line };
    let (kd, ks, ke) = (value(&m.kd), value(&m.ks), value(&m.ke));
    let illum = m.illum.as_ref().map(|i| i.value);
    let diffuse = match &m.map_kd {
        Some(_) => TextureRef::Named(DIFFUSE_MAP.into()),
        None => TextureRef::Color(kd.unwrap_or(DEFAULT_KD)),
    };
    let alpha = match &m.ns {
        // The reader refuses a number that is not finite.
        Some(At { value, line }) if *value < 0.0 => {
            return Err((at("Ns", *line), format!("must be ≥ 0 (got {value})")));
        }
        Some(ns) => alpha_of_exponent(ns.value),
        None => DEFAULT_ALPHA,
    };
    let mut unused = Vec::new();
    let mut unused_if = |key: &'static str, line: Option<u64>, why: &'static str| {
        if let Some(line) = line {
            unused.push((at(key, line), why));
        }
    };
    let line = |x: &Option<At<[f64; 3]>>| x.as_ref().map(|c| c.line);
    let opaque = m.d.as_ref().is_none_or(|d| d.value >= 1.0);
    let glass = !opaque || matches!(illum, Some(4 | 6 | 7 | 9));
    let spec = if ke.is_some_and(bright) {
        unused_if(
            DIFFUSE_MAP,
            m.map_kd.as_ref().map(|t| t.line),
            "an emitter's albedo is `Kd` alone",
        );
        unused_if("Ks", line(&m.ks), "an emitter reflects as a matte surface");
        MaterialSpec::Emissive {
            radiance: ke.unwrap_or_default(),
            two_sided: false,
            albedo: kd,
        }
    } else if glass {
        unused_if("Kd", line(&m.kd), "glass has no diffuse colour (`Tf` tints it)");
        unused_if(
            DIFFUSE_MAP,
            m.map_kd.as_ref().map(|t| t.line),
            "glass has no diffuse colour",
        );
        MaterialSpec::Dielectric {
            index: m.ni.as_ref().map_or(DEFAULT_NI, |n| n.value),
            albedo: value(&m.tf),
            fresnel: FresnelSpec::Exact,
        }
    } else if matches!(illum, Some(3 | 5 | 8)) && ks.is_some_and(bright) && !kd.is_some_and(bright) {
        unused_if(
            DIFFUSE_MAP,
            m.map_kd.as_ref().map(|t| t.line),
            "a metal has no diffuse colour",
        );
        two_sided(MaterialSpec::RoughConductor(RoughConductorSpec {
            material: None,
            eta: None,
            k: None,
            specular_reflectance: ks.map(TextureRef::Color),
            distribution: DistributionSpec::Beckmann,
            alpha: Some(ScalarRef::from(alpha)),
            alpha_u: None,
            alpha_v: None,
        }))
    } else if ks.is_some_and(bright) && !matches!(illum, Some(0 | 1)) {
        two_sided(MaterialSpec::RoughPlastic(RoughPlasticSpec {
            diffuse_reflectance: diffuse,
            specular_reflectance: ks.map(TextureRef::Color),
            int_ior: IorSpec::Named("polypropylene".into()),
            ext_ior: IorSpec::Named("air".into()),
            nonlinear: false,
            distribution: DistributionSpec::Beckmann,
            alpha,
        }))
    } else {
        MaterialSpec::Lambertian { albedo: diffuse }
    };
    if !glass {
        unused_if("Tf", line(&m.tf), "only glass is tinted by `Tf`");
    }
    Ok(Mapped { spec, unused })
}

fn two_sided(front: MaterialSpec) -> MaterialSpec {
    MaterialSpec::TwoSided(TwoSidedSpec {
        front: Box::new(front),
        back: None,
    })
}

#[cfg(test)]
mod tests;
