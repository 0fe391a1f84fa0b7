//! The scene file's model of Mitsuba 3's materials (`conductor`, `roughconductor`,
//! `roughdielectric`, `thindielectric`, `plastic`, `roughplastic`, `twosided`): one table
//! type each, under Mitsuba's parameter names and defaults.

use super::model::{MaterialSpec, Triple};
use super::texture_spec::{ScalarRef, TextureRef};
use serde::{Deserialize, Serialize};

/// A microfacet distribution's name.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DistributionSpec {
    /// Beckmann's (Mitsuba's default).
    #[default]
    Beckmann,
    /// GGX (Trowbridge–Reitz).
    Ggx,
}

/// An index of refraction: a number or a medium's name (`"bk7"`, `"water"`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged, expecting = "expected a number or the name of a medium")]
pub enum IorSpec {
    /// The index itself.
    Value(f64),
    /// A named medium.
    Named(String),
}

fn bk7() -> IorSpec {
    IorSpec::Named("bk7".into())
}

fn air() -> IorSpec {
    IorSpec::Named("air".into())
}

fn polypropylene() -> IorSpec {
    IorSpec::Named("polypropylene".into())
}

fn half() -> TextureRef {
    TextureRef::Color([0.5; 3])
}

/// What a conductor is made of: a named one (`material`) or its index (`eta`, `k`),
/// not both; neither is Mitsuba's `none`, a perfect mirror.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConductorSpec {
    /// A named conductor (`"Au"`, `"Cu"`, …).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<String>,
    /// The real index per channel (default 0 when `k` is given).
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub eta: Option<Triple>,
    /// The extinction per channel (default 1 when `eta` is given).
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub k: Option<Triple>,
    /// A factor on the reflection, in `[0, 1]`: a colour or a texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_reflectance: Option<TextureRef>,
}

/// A rough conductor: a [`ConductorSpec`]'s keys and a roughness.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoughConductorSpec {
    /// A named conductor.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<String>,
    /// The real index per channel.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub eta: Option<Triple>,
    /// The extinction per channel.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub k: Option<Triple>,
    /// A factor on the reflection, in `[0, 1]`: a colour or a texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_reflectance: Option<TextureRef>,
    /// `"beckmann"` (default) or `"ggx"`.
    #[serde(default)]
    pub distribution: DistributionSpec,
    /// The isotropic `α`, a number or a texture (default 0.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<ScalarRef>,
    /// `α` along the tangent (with `alpha_v`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_u: Option<ScalarRef>,
    /// `α` along the bitangent (with `alpha_u`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_v: Option<ScalarRef>,
}

/// A roughness as a rough conductor or dielectric gives it: `distribution` and `alpha`,
/// or `alpha_u` and `alpha_v`.
#[derive(Clone, Debug, PartialEq)]
pub struct RoughnessSpec {
    /// The distribution.
    pub distribution: DistributionSpec,
    /// `alpha`.
    pub alpha: Option<ScalarRef>,
    /// `alpha_u`.
    pub alpha_u: Option<ScalarRef>,
    /// `alpha_v`.
    pub alpha_v: Option<ScalarRef>,
}

macro_rules! roughness_of {
    ($($t:ty),*) => {$(
        impl $t {
            /// Its roughness keys.
            pub fn roughness(&self) -> RoughnessSpec {
                RoughnessSpec {
                    distribution: self.distribution,
                    alpha: self.alpha.clone(),
                    alpha_u: self.alpha_u.clone(),
                    alpha_v: self.alpha_v.clone(),
                }
            }
        }
    )*};
}
roughness_of!(RoughConductorSpec, RoughDielectricSpec);

/// A rough dielectric.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoughDielectricSpec {
    /// The index inside (default `"bk7"`).
    #[serde(default = "bk7")]
    pub int_ior: IorSpec,
    /// The index outside (default `"air"`).
    #[serde(default = "air")]
    pub ext_ior: IorSpec,
    /// A factor on the reflection, in `[0, 1]`: a colour or a texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_reflectance: Option<TextureRef>,
    /// A factor on the transmission, in `[0, 1]`: a colour or a texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_transmittance: Option<TextureRef>,
    /// `"beckmann"` (default) or `"ggx"`.
    #[serde(default)]
    pub distribution: DistributionSpec,
    /// The isotropic `α`, a number or a texture (default 0.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<ScalarRef>,
    /// `α` along the tangent (with `alpha_v`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_u: Option<ScalarRef>,
    /// `α` along the bitangent (with `alpha_u`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_v: Option<ScalarRef>,
}

/// A thin dielectric sheet.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThinDielectricSpec {
    /// The sheet's index (default `"bk7"`).
    #[serde(default = "bk7")]
    pub int_ior: IorSpec,
    /// The index around it (default `"air"`).
    #[serde(default = "air")]
    pub ext_ior: IorSpec,
    /// A factor on the reflection, in `[0, 1]`: a colour or a texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_reflectance: Option<TextureRef>,
    /// A factor on the transmission, in `[0, 1]`: a colour or a texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_transmittance: Option<TextureRef>,
}

/// A smooth plastic.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlasticSpec {
    /// The base's reflectance, in `[0, 1]`: a colour or a texture (default `[0.5, 0.5, 0.5]`).
    #[serde(default = "half")]
    pub diffuse_reflectance: TextureRef,
    /// A factor on the coat's reflection, in `[0, 1]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_reflectance: Option<TextureRef>,
    /// The coat's index (default `"polypropylene"`).
    #[serde(default = "polypropylene")]
    pub int_ior: IorSpec,
    /// The index outside (default `"air"`).
    #[serde(default = "air")]
    pub ext_ior: IorSpec,
    /// Whether the base's bounces are summed nonlinearly (default `false`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub nonlinear: bool,
}

/// A rough plastic: a [`PlasticSpec`]'s keys, a distribution and one `α`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RoughPlasticSpec {
    /// The base's reflectance, in `[0, 1]`: a colour or a texture (default `[0.5, 0.5, 0.5]`).
    #[serde(default = "half")]
    pub diffuse_reflectance: TextureRef,
    /// A factor on the coat's reflection, in `[0, 1]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular_reflectance: Option<TextureRef>,
    /// The coat's index (default `"polypropylene"`).
    #[serde(default = "polypropylene")]
    pub int_ior: IorSpec,
    /// The index outside (default `"air"`).
    #[serde(default = "air")]
    pub ext_ior: IorSpec,
    /// Whether the base's bounces are summed nonlinearly (default `false`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub nonlinear: bool,
    /// `"beckmann"` (default) or `"ggx"`.
    #[serde(default)]
    pub distribution: DistributionSpec,
    /// The coat's `α` (default 0.1).
    #[serde(default = "default_alpha")]
    pub alpha: f64,
}

fn default_alpha() -> f64 {
    0.1
}

/// A two-sided wrapper: a material for the front face and, if they differ, one for the
/// back, each an inline table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TwoSidedSpec {
    /// The material of both faces (or of the front one).
    pub front: Box<MaterialSpec>,
    /// The back face's material, if it differs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub back: Option<Box<MaterialSpec>>,
}
