//! The scene file's data model: what TOML deserializes into, one type per section.
//!
//! Only the shape and the types of values are checked here; their domains (a radius > 0,
//! an albedo in `[0, 1]`, a material that exists) are checked when the scene is built.

use super::bsdf::{
    ConductorSpec, PlasticSpec, RoughConductorSpec, RoughDielectricSpec, RoughPlasticSpec,
    ThinDielectricSpec, TwoSidedSpec,
};
use super::texture_spec::{ScalarRef, TextureRef};
use crate::image::ToneCurve;
use crate::scene::{Acceleration, BvhQuality};
use serde::{Deserialize, Serialize};

/// A point, a direction or a colour: `[x, y, z]` or `[r, g, b]`.
pub type Triple = [f64; 3];

/// The `[render]` section: image size and how to render it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct RenderOptions {
    /// Image width in pixels (the height follows from the camera).
    #[serde(with = "super::integer")]
    pub width: usize,
    /// Samples (rays) per pixel, at least 1.
    pub spp: u32,
    /// The most bounces a path may take.
    pub max_depth: u32,
    /// The seed of every pixel's random stream.
    #[serde(with = "super::integer")]
    pub seed: u64,
    /// The scalar to render in.
    pub precision: FilePrecision,
    /// How the scene is intersected.
    #[serde(with = "AccelerationName")]
    pub acceleration: Acceleration,
    /// How much work the BVH build does: `"high"` adds spatial splits.
    #[serde(with = "BvhQualityName", default, skip_serializing_if = "is_medium")]
    pub bvh_quality: BvhQuality,
    /// Stops of exposure for the display formats (PNG, PPM): `+1` doubles every value
    /// before the tone curve.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub exposure: f64,
    /// The tone curve for the display formats.
    #[serde(with = "ToneCurveName", default, skip_serializing_if = "is_no_curve")]
    pub tonemap: ToneCurve,
}

fn is_medium(q: &BvhQuality) -> bool {
    *q == BvhQuality::Medium
}

fn is_no_curve(c: &ToneCurve) -> bool {
    *c == ToneCurve::None
}

/// 800 pixels wide, 1 sample per pixel, depth 10, seed 0, `f64`, automatic acceleration,
/// no exposure change and no tone curve: the specification's minimum render.
impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            width: 800,
            spp: 1,
            max_depth: 10,
            seed: 0,
            precision: FilePrecision::F64,
            acceleration: Acceleration::Auto,
            bvh_quality: BvhQuality::Medium,
            exposure: 0.0,
            tonemap: ToneCurve::None,
        }
    }
}

/// The library's [`ToneCurve`] under the names the file uses.
#[derive(Serialize, Deserialize)]
#[serde(remote = "ToneCurve", rename_all = "lowercase")]
enum ToneCurveName {
    None,
    Aces,
}

/// The scalar a scene file asks to be rendered in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FilePrecision {
    /// Single precision.
    F32,
    /// Double precision (the default).
    #[default]
    F64,
    /// Whichever [`advise_precision`](super::advise_precision) measures to be enough.
    Auto,
}

/// The library's [`Acceleration`] under the names the file uses.
#[derive(Serialize, Deserialize)]
#[serde(remote = "Acceleration", rename_all = "lowercase")]
enum AccelerationName {
    Auto,
    #[serde(alias = "list")]
    Linear,
    Bvh,
}

/// The library's [`BvhQuality`] under the names the file uses.
#[derive(Serialize, Deserialize)]
#[serde(remote = "BvhQuality", rename_all = "lowercase")]
enum BvhQualityName {
    Medium,
    High,
}

/// The `[camera]` section.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum CameraSpec {
    /// The specification's camera: the eye at the origin (or at `eye`), looking down −z
    /// at a 4×2 screen at distance 1; the image is `width × width/2`.
    Screen {
        /// Where the eye is moved to (the screen moves with it).
        #[serde(
            deserialize_with = "super::triple::some",
            default,
            skip_serializing_if = "Option::is_none"
        )]
        eye: Option<Triple>,
    },
    /// A camera at `from` looking at `at`: a pinhole, or with `aperture > 0` a thin lens.
    LookAt {
        /// The eye.
        #[serde(deserialize_with = "super::triple::deserialize")]
        from: Triple,
        /// The point seen at the centre of the image.
        #[serde(deserialize_with = "super::triple::deserialize")]
        at: Triple,
        /// Roughly up (default `[0, 1, 0]`).
        #[serde(deserialize_with = "super::triple::deserialize", default = "y_up")]
        up: Triple,
        /// The vertical field of view in degrees, in `(0, 180)`.
        vfov: f64,
        /// Width over height: the image is `width × ⌊width/aspect⌋` pixels.
        aspect: f64,
        /// The lens radius, `≥ 0`; 0 (the default) is a pinhole.
        #[serde(default, skip_serializing_if = "is_zero")]
        aperture: f64,
        /// The distance along the view axis that is sharp, `> 0` (default `|at − from|`).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        focus_distance: Option<f64>,
    },
}

/// Whether an optional number is at its default, 0 (`-0` is written: it reads back as `-0`).
fn is_zero(x: &f64) -> bool {
    *x == 0.0 && x.is_sign_positive()
}

fn y_up() -> Triple {
    [0.0, 1.0, 0.0]
}

impl Default for CameraSpec {
    fn default() -> Self {
        Self::Screen { eye: None }
    }
}

/// The `[background]` section: what a ray that hits nothing sees.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum BackgroundSpec {
    /// A gradient from `horizon` (straight down) to `zenith` (straight up).
    Sky {
        /// The colour straight down (default white).
        #[serde(deserialize_with = "super::triple::deserialize", default = "white")]
        horizon: Triple,
        /// The colour straight up (default `[0.5, 0.7, 1.0]`).
        #[serde(deserialize_with = "super::triple::deserialize", default = "sky_blue")]
        zenith: Triple,
        /// Whether the sky is a light the renderer samples (default `false`: only what
        /// escaping rays see, the specification's sky).
        #[serde(default, skip_serializing_if = "is_false")]
        light: bool,
    },
    /// One colour in every direction.
    Solid {
        /// The colour.
        #[serde(deserialize_with = "super::triple::deserialize")]
        color: Triple,
        /// Whether the colour is a light the renderer samples (default `false`).
        #[serde(default, skip_serializing_if = "is_false")]
        light: bool,
    },
    /// An HDR environment map (OpenEXR or Radiance HDR), in Mitsuba 3's `envmap` conventions: always a
    /// light.
    Envmap {
        /// The image, relative to the scene file's folder.
        file: String,
        /// What every texel is multiplied by (default 1).
        #[serde(default = "one")]
        scale: f64,
        /// Rotations about x, then y, then z, in degrees, as a mesh's (default none).
        #[serde(deserialize_with = "super::triple::deserialize", default)]
        rotate: Triple,
    },
}

fn is_false(b: &bool) -> bool {
    !*b
}

fn one() -> f64 {
    1.0
}

fn white() -> Triple {
    [1.0; 3]
}

fn sky_blue() -> Triple {
    [0.5, 0.7, 1.0]
}

/// The library's default sky ([`Background::default`](crate::Background)).
impl Default for BackgroundSpec {
    fn default() -> Self {
        Self::Sky {
            horizon: white(),
            zenith: sky_blue(),
            light: false,
        }
    }
}

/// A named material, `[materials.NAME]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum MaterialSpec {
    /// A perfect mirror.
    Mirror {
        /// Each channel in `[0, 1]`.
        #[serde(deserialize_with = "super::triple::deserialize")]
        albedo: Triple,
    },
    /// A matte surface.
    Lambertian {
        /// Each channel in `[0, 1]`: a colour, or a texture (by name or in place).
        albedo: TextureRef,
    },
    /// Glass-like: reflects or refracts.
    Dielectric {
        /// The refractive index relative to the outside, `> 0`.
        index: f64,
        /// The tint, each channel in `[0, 1]` (default white: clear).
        #[serde(
            deserialize_with = "super::triple::some",
            default,
            skip_serializing_if = "Option::is_none"
        )]
        albedo: Option<Triple>,
        /// How the reflectance is computed.
        #[serde(default)]
        fresnel: FresnelSpec,
    },
    /// A surface that gives off light (an area light), and may also reflect as a matte one.
    Emissive {
        /// The emitted radiance per channel, finite and `≥ 0`.
        #[serde(deserialize_with = "super::triple::deserialize")]
        radiance: Triple,
        /// Whether the back face emits too (default: the front face only).
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        two_sided: bool,
        /// The matte albedo, each channel in `[0, 1]` (default black: it reflects nothing).
        #[serde(
            deserialize_with = "super::triple::some",
            default,
            skip_serializing_if = "Option::is_none"
        )]
        albedo: Option<Triple>,
    },
    /// Another material, shaded with normals from a tangent-space normal map (Mitsuba's
    /// `normalmap`).
    NormalMap {
        /// The map: an RGB texture (by name or in place), `n = 2·rgb − 1` in the shading
        /// frame; an image in it is read as data (`raw = true`) unless it says otherwise.
        normal_map: TextureRef,
        /// The name of the material it perturbs, a `[materials]` entry.
        material: String,
    },
    /// A smooth conductor (Mitsuba's `conductor`).
    Conductor(ConductorSpec),
    /// A rough conductor (Mitsuba's `roughconductor`).
    RoughConductor(RoughConductorSpec),
    /// A rough dielectric (Mitsuba's `roughdielectric`).
    RoughDielectric(RoughDielectricSpec),
    /// A thin dielectric sheet (Mitsuba's `thindielectric`).
    ThinDielectric(ThinDielectricSpec),
    /// A smooth plastic (Mitsuba's `plastic`).
    Plastic(PlasticSpec),
    /// A rough plastic (Mitsuba's `roughplastic`).
    RoughPlastic(RoughPlasticSpec),
    /// A one-sided material shaded alike from both faces (Mitsuba's `twosided`).
    TwoSided(TwoSidedSpec),
}

impl MaterialSpec {
    /// The textures its keys hold (a colour counts as a constant texture), a two-sided
    /// material's included: the `match` names every kind, so a kind added with a texture
    /// key must say so.
    pub fn textures(&self) -> Vec<&TextureRef> {
        match self {
            Self::Lambertian { albedo } => vec![albedo],
            Self::NormalMap { normal_map, .. } => vec![normal_map],
            Self::Mirror { .. } | Self::Dielectric { .. } | Self::Emissive { .. } => Vec::new(),
            Self::Conductor(c) => c.specular_reflectance.iter().collect(),
            Self::RoughConductor(c) => c
                .specular_reflectance
                .iter()
                .chain(alphas([&c.alpha, &c.alpha_u, &c.alpha_v]))
                .collect(),
            Self::RoughDielectric(d) => [&d.specular_reflectance, &d.specular_transmittance]
                .into_iter()
                .flatten()
                .chain(alphas([&d.alpha, &d.alpha_u, &d.alpha_v]))
                .collect(),
            Self::ThinDielectric(d) => [&d.specular_reflectance, &d.specular_transmittance]
                .into_iter()
                .flatten()
                .collect(),
            Self::Plastic(p) => std::iter::once(&p.diffuse_reflectance)
                .chain(&p.specular_reflectance)
                .collect(),
            Self::RoughPlastic(p) => std::iter::once(&p.diffuse_reflectance)
                .chain(&p.specular_reflectance)
                .collect(),
            Self::TwoSided(t) => {
                let mut all = t.front.textures();
                if let Some(back) = &t.back {
                    all.extend(back.textures());
                }
                all
            }
        }
    }
}

/// The textures of a roughness's keys that are given.
fn alphas(a: [&Option<ScalarRef>; 3]) -> impl Iterator<Item = &TextureRef> {
    a.into_iter().flatten().map(|r| &r.0)
}

/// How a dielectric computes its reflectance.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FresnelSpec {
    /// Schlick's approximation (the default).
    #[default]
    Schlick,
    /// The exact Fresnel equations for unpolarised light.
    Exact,
}
