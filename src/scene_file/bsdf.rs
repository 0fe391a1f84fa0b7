//! The scene file's model of Mitsuba 3's materials (`conductor`, `roughconductor`,
//! `roughdielectric`, `thindielectric`, `plastic`, `roughplastic`, `twosided`): one table
//! type each, under Mitsuba's parameter names and defaults.

use super::model::{MaterialSpec, Triple};
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

fn half() -> Triple {
    [0.5; 3]
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
    /// A factor on the reflection, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_reflectance: Option<Triple>,
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
    /// A factor on the reflection, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_reflectance: Option<Triple>,
    /// `"beckmann"` (default) or `"ggx"`.
    #[serde(default)]
    pub distribution: DistributionSpec,
    /// The isotropic `α` (default 0.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    /// `α` along the tangent (with `alpha_v`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_u: Option<f64>,
    /// `α` along the bitangent (with `alpha_u`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_v: Option<f64>,
}

/// A roughness as a rough conductor or dielectric gives it: `distribution` and `alpha`,
/// or `alpha_u` and `alpha_v`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughnessSpec {
    /// The distribution.
    pub distribution: DistributionSpec,
    /// `alpha`.
    pub alpha: Option<f64>,
    /// `alpha_u`.
    pub alpha_u: Option<f64>,
    /// `alpha_v`.
    pub alpha_v: Option<f64>,
}

macro_rules! roughness_of {
    ($($t:ty),*) => {$(
        impl $t {
            /// Its roughness keys.
            pub fn roughness(&self) -> RoughnessSpec {
                RoughnessSpec {
                    distribution: self.distribution,
                    alpha: self.alpha,
                    alpha_u: self.alpha_u,
                    alpha_v: self.alpha_v,
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
    /// A factor on the reflection, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_reflectance: Option<Triple>,
    /// A factor on the transmission, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_transmittance: Option<Triple>,
    /// `"beckmann"` (default) or `"ggx"`.
    #[serde(default)]
    pub distribution: DistributionSpec,
    /// The isotropic `α` (default 0.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    /// `α` along the tangent (with `alpha_v`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_u: Option<f64>,
    /// `α` along the bitangent (with `alpha_u`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_v: Option<f64>,
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
    /// A factor on the reflection, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_reflectance: Option<Triple>,
    /// A factor on the transmission, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_transmittance: Option<Triple>,
}

/// A smooth plastic.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlasticSpec {
    /// The base's reflectance, in `[0, 1]` (default `[0.5, 0.5, 0.5]`).
    #[serde(deserialize_with = "super::triple::deserialize", default = "half")]
    pub diffuse_reflectance: Triple,
    /// A factor on the coat's reflection, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_reflectance: Option<Triple>,
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
    /// The base's reflectance, in `[0, 1]` (default `[0.5, 0.5, 0.5]`).
    #[serde(deserialize_with = "super::triple::deserialize", default = "half")]
    pub diffuse_reflectance: Triple,
    /// A factor on the coat's reflection, in `[0, 1]`.
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    pub specular_reflectance: Option<Triple>,
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
