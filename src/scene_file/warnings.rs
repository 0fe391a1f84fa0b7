//! What a valid scene file probably did not mean: a scene with nothing in it, or one whose
//! image can only be black. Worth a word before a long render.

use super::SceneFile;
use super::build::Built;
use super::make;
use super::model::{BackgroundSpec, CameraSpec, MaterialSpec};
use crate::error::Result;
use crate::float::Float;
use crate::render::{RenderSettings, render};
use std::fmt;

/// A valid scene that will not render what its author probably meant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Warning {
    /// No `[[objects]]`: the image is the background alone.
    NoObjects,
    /// Nothing gives off light: a black background, no light with any intensity or irradiance and
    /// no object of an emissive material with any radiance. The image is black.
    NoLight,
    /// A small preview render ([`Warning::PREVIEW_WIDTH`] pixels wide, [`Warning::PREVIEW_SPP`]
    /// samples per pixel) is black although something gives off light: no path the preview
    /// found carries it to the camera, as from an emissive panel facing away.
    DarkPreview,
}

impl Warning {
    /// The width of the preview render behind [`Warning::DarkPreview`].
    pub const PREVIEW_WIDTH: usize = 64;
    /// Its samples per pixel.
    pub const PREVIEW_SPP: u32 = 4;
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoObjects => f.write_str("the scene has no [[objects]]: the image is the background alone"),
            Self::NoLight => f.write_str(
                "nothing gives off light (the background is black, no [[lights]] entry has an \
                 intensity or irradiance, no object's material emits): the image will be black",
            ),
            Self::DarkPreview => write!(
                f,
                "no light reaches the camera in a preview render ({} pixels wide, {} samples per \
                 pixel): check which way the emitters and lights face; the image will likely be black",
                Self::PREVIEW_WIDTH,
                Self::PREVIEW_SPP
            ),
        }
    }
}

/// What [`SceneFile::warnings`] finds without rendering.
pub(super) fn static_warnings(file: &SceneFile) -> Vec<Warning> {
    let mut found = Vec::new();
    if file.objects.is_empty() {
        found.push(Warning::NoObjects);
    }
    let bright = |c: [f64; 3]| c.iter().any(|&x| x > 0.0);
    let background = match &file.background {
        BackgroundSpec::Sky { horizon, zenith, .. } => bright(*horizon) || bright(*zenith),
        BackgroundSpec::Solid { color, .. } => bright(*color),
        // An environment map's texels are read when the scene is built: assume light.
        BackgroundSpec::Envmap { scale, .. } => *scale > 0.0,
    };
    let lights = file.lights.iter().any(|l| bright(l.color()));
    // An OBJ file's own materials are read when the scene is built: assume light.
    let emitters = file.objects.iter().any(|o| {
        super::obj_materials::wants_mtl(o)
            || matches!(
                file.materials.get(o.material()),
                Some(MaterialSpec::Emissive { radiance, .. }) if bright(*radiance)
            )
    });
    if !(background || lights || emitters) {
        found.push(Warning::NoLight);
    }
    found
}

/// Whether a preview of `built` (the scene of `file`) is black in every pixel.
pub(super) fn dark_preview<F: Float>(file: &SceneFile, built: &Built<F>) -> Result<bool> {
    let width = Warning::PREVIEW_WIDTH;
    let camera = match file.camera {
        CameraSpec::Screen { eye } => make::screen::<F>(width, eye)?,
        CameraSpec::LookAt {
            from,
            at,
            up,
            vfov,
            aspect,
            aperture,
            focus_distance,
        } => {
            // The file's aspect, at most 64 rows and at least one.
            let height = (super::build::look_at_height(width, aspect) as usize).clamp(1, width);
            make::look_at::<F>(&make::LookAt {
                from,
                at,
                up,
                vfov,
                aperture,
                focus_distance,
                size: (width, height),
            })?
        }
    };
    let settings = RenderSettings {
        samples_per_pixel: Warning::PREVIEW_SPP,
        ..built.settings
    };
    let image = render(&built.scene, &camera, &settings)?.image;
    Ok(image.pixels().iter().all(|p| *p == [0.0; 3]))
}
