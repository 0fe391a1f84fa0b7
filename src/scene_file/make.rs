//! The library's values for a scene file's entries in a scalar `G`: the constructors
//! alone, which check every value. Where an error belongs in the file is
//! [`check`](super::check)'s business.

use super::camera::FileCamera;
use super::check::vec;
use super::light::LightSpec;
use super::model::{BackgroundSpec, FresnelSpec, MaterialSpec};
use crate::background::Background;
use crate::camera::{LookAtCamera, ScreenCamera};
use crate::error::Result;
use crate::float::{Float, lit};
use crate::light::{DirectionalLight, Light, PointLight, SpotLight};
use crate::material::{Dielectric, Emissive, Lambertian, MaterialKind, Mirror, Reflectance};
use crate::shape::{Plane, ShapeKind, Sphere, Triangle};

/// A shape a file describes by its numbers alone (not a mesh).
#[derive(Clone, Copy, Debug)]
pub enum Solid {
    /// `type = "sphere"`.
    Sphere { center: [f64; 3], radius: f64 },
    /// `type = "plane"`.
    Plane { point: [f64; 3], normal: [f64; 3] },
    /// `type = "triangle"`.
    Triangle { a: [f64; 3], b: [f64; 3], c: [f64; 3] },
}

/// The shape in `G`.
pub fn shape<G: Float>(solid: Solid) -> Result<ShapeKind<G>> {
    Ok(match solid {
        Solid::Sphere { center, radius } => Sphere::new(vec(center), lit(radius))?.into(),
        Solid::Plane { point, normal } => Plane::new(vec(point), vec(normal))?.into(),
        Solid::Triangle { a, b, c } => Triangle::new(vec(a), vec(b), vec(c))?.into(),
    })
}

/// The material in `G`.
pub fn material<G: Float>(spec: &MaterialSpec) -> Result<MaterialKind<G>> {
    Ok(match *spec {
        MaterialSpec::Mirror { albedo } => Mirror::new(vec(albedo))?.into(),
        MaterialSpec::Lambertian { albedo } => Lambertian::new(vec(albedo))?.into(),
        MaterialSpec::Dielectric {
            index,
            albedo,
            fresnel,
        } => {
            let mut glass = Dielectric::new(lit(index))?;
            if let Some(albedo) = albedo {
                glass = glass.with_albedo(vec(albedo))?;
            }
            glass
                .with_reflectance(match fresnel {
                    FresnelSpec::Schlick => Reflectance::Schlick,
                    FresnelSpec::Exact => Reflectance::Fresnel,
                })
                .into()
        }
        MaterialSpec::Emissive {
            radiance,
            two_sided,
            albedo,
        } => {
            let mut light = Emissive::new(vec(radiance))?.two_sided(two_sided);
            if let Some(albedo) = albedo {
                light = light.with_albedo(vec(albedo))?;
            }
            light.into()
        }
    })
}

/// The background in `G`.
pub fn background<G: Float>(spec: &BackgroundSpec) -> Result<Background<G>> {
    match *spec {
        BackgroundSpec::Sky { horizon, zenith } => Background::sky(vec(horizon), vec(zenith)),
        BackgroundSpec::Solid { color } => Background::solid(vec(color)),
    }
}

/// The light in `G`.
pub fn light<G: Float>(spec: &LightSpec) -> Result<Light<G>> {
    Ok(match *spec {
        LightSpec::Point { position, intensity } => PointLight::new(vec(position), vec(intensity))?.into(),
        LightSpec::Spot {
            position,
            direction,
            intensity,
            cutoff_angle,
            beam_width,
        } => {
            let beam_width = beam_width.unwrap_or(LightSpec::default_beam_width(cutoff_angle));
            SpotLight::new(
                vec(position),
                vec(direction),
                vec(intensity),
                lit(cutoff_angle),
                lit(beam_width),
            )?
            .into()
        }
        LightSpec::Directional {
            direction,
            irradiance,
        } => DirectionalLight::new(vec(direction), vec(irradiance))?.into(),
    })
}

/// The spec's camera for an image `width` pixels wide, its eye moved to `eye`.
pub fn screen<G: Float>(width: usize, eye: Option<[f64; 3]>) -> Result<FileCamera<G>> {
    let camera = ScreenCamera::with_width(width)?;
    Ok(FileCamera::Screen(match eye {
        Some(eye) => camera.translated(eye)?,
        None => camera,
    }))
}

/// A look-at camera (the numbers as the file writes them) for a `width × height` image.
pub struct LookAt {
    /// The eye.
    pub from: [f64; 3],
    /// The point at the centre of the image.
    pub at: [f64; 3],
    /// Roughly up.
    pub up: [f64; 3],
    /// Vertical field of view, degrees.
    pub vfov: f64,
    /// The lens radius (0: a pinhole).
    pub aperture: f64,
    /// The distance in focus, if not `|at − from|`.
    pub focus_distance: Option<f64>,
    /// The image's size.
    pub size: (usize, usize),
}

/// The look-at camera in `G`.
pub fn look_at<G: Float>(c: &LookAt) -> Result<FileCamera<G>> {
    let (width, height) = c.size;
    LookAtCamera::new(vec(c.from), vec(c.at), vec(c.up), lit(c.vfov), width, height)?
        .with_lens(lit(c.aperture), c.focus_distance.map(lit))
        .map(FileCamera::LookAt)
}
