//! A library constructor's error at the key its field is written under.
//!
//! The values are checked by the constructors alone (`validate.rs`), once in `f64` on the
//! numbers as written and once in the render's scalar: a refusal in `f64` is the value's
//! fault, one only in the render's scalar is the rounding's, and the message says which.
//! The error's [`Field`] picks the key, never its text.

use super::location::KeyPath;
use super::model::Triple;
use crate::error::{Error, Field, Result};
use crate::float::Float;
use crate::vec3::Vec3;

/// `t` in scalar `F`, each component rounded to nearest.
pub fn vec<F: Float>(t: Triple) -> Vec3<F> {
    Vec3::from_f64(t[0], t[1], t[2])
}

/// The key `field` is written under, when `entry` is the table being built
/// (`objects[3]`, `materials.gold`, `camera`, …) and `root` the top of the file. Every
/// field is named: a new one without its key does not compile.
pub fn key<'a>(root: &KeyPath<'a>, entry: &KeyPath<'a>, field: Field) -> KeyPath<'a> {
    let render = |name| root.key("render").key(name);
    let own = |name| entry.key(name);
    match field {
        Field::SphereCenter => own("center"),
        Field::SphereRadius => own("radius"),
        Field::PlanePoint => own("point"),
        Field::PlaneNormal => own("normal"),
        Field::TriangleA => own("a"),
        Field::TriangleB => own("b"),
        Field::TriangleC => own("c"),
        // No area: all three vertices together, so the entry.
        Field::Triangle => entry.clone(),
        Field::Mesh => own("file"),
        Field::DiskCenter => own("center"),
        Field::DiskNormal => own("normal"),
        Field::DiskRadius => own("radius"),
        // The axes come only from a disk's `matrix`.
        Field::DiskAxes => own("matrix"),
        Field::MirrorAlbedo | Field::MatteAlbedo | Field::DielectricAlbedo | Field::EmissiveAlbedo => {
            own("albedo")
        }
        Field::RefractiveIndex => own("index"),
        Field::EmittedRadiance => own("radiance"),
        Field::CheckerboardColor0 => own("color0"),
        Field::CheckerboardColor1 => own("color1"),
        Field::TextureScale => own("scale"),
        Field::TextureOffset => own("offset"),
        Field::ConductorEta => own("eta"),
        Field::ConductorK => own("k"),
        Field::ConductorName => own("material"),
        Field::SpecularReflectance => own("specular_reflectance"),
        Field::SpecularTransmittance => own("specular_transmittance"),
        Field::DiffuseReflectance => own("diffuse_reflectance"),
        Field::Alpha => own("alpha"),
        Field::AlphaU => own("alpha_u"),
        Field::AlphaV => own("alpha_v"),
        Field::InteriorIndex => own("int_ior"),
        Field::ExteriorIndex => own("ext_ior"),
        Field::TwoSidedFront => own("front"),
        Field::TwoSidedBack => own("back"),
        Field::LightPosition => own("position"),
        Field::LightIntensity => own("intensity"),
        Field::LightDirection => own("direction"),
        Field::LightIrradiance => own("irradiance"),
        Field::SpotCutoff => own("cutoff_angle"),
        Field::SpotBeamWidth => own("beam_width"),
        Field::BackgroundColor => own("color"),
        Field::SkyHorizon => own("horizon"),
        Field::SkyZenith => own("zenith"),
        Field::EnvironmentMap => own("file"),
        Field::EnvironmentScale => own("scale"),
        Field::EnvironmentRotation => own("rotate"),
        Field::Transform => own("transform"),
        Field::CameraFrom => own("from"),
        // `from == at` gives no view direction: the target is the one to move.
        Field::CameraAt | Field::CameraView => own("at"),
        Field::CameraUp => own("up"),
        Field::CameraVfov => own("vfov"),
        Field::CameraAperture => own("aperture"),
        Field::CameraFocusDistance => own("focus_distance"),
        Field::CameraEye => own("eye"),
        // The camera makes the image's size from `[render] width`.
        Field::ImageWidth | Field::ImageSize => render("width"),
        Field::SamplesPerPixel => render("spp"),
        Field::MaxDepth => render("max_depth"),
        Field::Exposure => render("exposure"),
        // No file builds a user's own type; were one to, its entry is the place.
        Field::Custom(_) => entry.clone(),
    }
}

/// A library error at the key of its field, with the constructor's reason; any other
/// error at `entry`, with its whole message.
pub fn blame(root: &KeyPath, entry: &KeyPath, e: Error) -> Error {
    blame_with(root, entry, e, "")
}

fn blame_with(root: &KeyPath, entry: &KeyPath, e: Error, tail: &str) -> Error {
    match e {
        Error::InvalidValue { field, reason } => {
            key(root, entry, field).error_about(Some(field), format!("{reason}{tail}"))
        }
        // Already at its place: a texture or a material the entry names.
        located @ Error::SceneFile { .. } => located,
        other => entry.error(format!("{other}{tail}")),
    }
}

/// `rounded`, the value made in scalar `F`, or the error at its field's key. `exact` is
/// the same value made in `f64` from the numbers as written: its error comes first, and
/// an error only `rounded` has says that rounding to `F` lost the value.
pub fn checked<F: Float, T>(
    root: &KeyPath,
    entry: &KeyPath,
    exact: Result<impl Sized>,
    rounded: Result<T>,
) -> Result<T> {
    if let Err(e) = exact {
        return Err(blame(root, entry, e));
    }
    rounded.map_err(|e| {
        let tail = format!(
            " in {0}: the value as written is valid in f64, but not once rounded to {0} \
             (precision = \"f64\" keeps it)",
            F::NAME
        );
        blame_with(root, entry, e, &tail)
    })
}
