//! The library's values for a scene file's entries in a scalar `G`: the constructors
//! alone, which check every value. Where an error belongs in the file is
//! [`check`](super::check)'s business.

use super::camera::FileCamera;
use super::check::vec;
use super::light::LightSpec;
use super::make_bsdf;
use super::model::{BackgroundSpec, FresnelSpec, MaterialSpec};
use super::resolve::{Inputs, TextureUse, Within};
use super::transform::Placement;
use crate::background::{Background, EnvironmentMap};
use crate::camera::{LookAtCamera, ScreenCamera};
use crate::error::Result;
use crate::float::{Float, lit};
use crate::light::{DirectionalLight, Light, PointLight, SpotLight};
use crate::material::{Dielectric, Emissive, Lambertian, MaterialKind, Mirror, NormalMap, Reflectance};
use crate::shape::{Disk, Plane, ShapeKind, Sphere, Triangle};
use crate::vec3::Vec3;
use std::sync::Arc;

/// A shape a file describes by its numbers alone (not a mesh).
#[derive(Clone, Copy, Debug)]
pub enum Solid {
    /// `type = "sphere"`.
    Sphere { center: [f64; 3], radius: f64 },
    /// `type = "plane"`.
    Plane { point: [f64; 3], normal: [f64; 3] },
    /// `type = "triangle"`.
    Triangle { a: [f64; 3], b: [f64; 3], c: [f64; 3] },
    /// `type = "disk"` by its centre, normal and radius.
    Disk {
        center: [f64; 3],
        normal: [f64; 3],
        radius: f64,
    },
    /// `type = "disk"` by a `matrix`: the unit disk's images of the origin, `x̂` and `ŷ`,
    /// facing `−(u×v)` if the map's determinant is negative.
    DiskAxes {
        center: [f64; 3],
        u: [f64; 3],
        v: [f64; 3],
        flipped: bool,
    },
}

/// The shape in `G`.
pub fn shape<G: Float>(solid: Solid) -> Result<ShapeKind<G>> {
    Ok(match solid {
        Solid::Sphere { center, radius } => Sphere::new(vec(center), lit(radius))?.into(),
        Solid::Plane { point, normal } => Plane::new(vec(point), vec(normal))?.into(),
        Solid::Triangle { a, b, c } => Triangle::new(vec(a), vec(b), vec(c))?.into(),
        Solid::Disk {
            center,
            normal,
            radius,
        } => Disk::new(vec(center), vec(normal), lit(radius))?.into(),
        Solid::DiskAxes {
            center,
            u,
            v,
            flipped,
        } => {
            let disk = Disk::with_axes(vec(center), vec(u), vec(v))?;
            (if flipped { disk.flipped() } else { disk }).into()
        }
    })
}

/// The material in `G`, with the textures and materials its keys name from `inputs`.
pub fn material<G: Float>(spec: &MaterialSpec, inputs: &mut dyn Inputs<G>) -> Result<MaterialKind<G>> {
    Ok(match *spec {
        MaterialSpec::Conductor(ref c) => make_bsdf::conductor(c, inputs)?,
        MaterialSpec::RoughConductor(ref c) => make_bsdf::rough_conductor(c, inputs)?,
        MaterialSpec::RoughDielectric(ref d) => make_bsdf::rough_dielectric(d, inputs)?,
        MaterialSpec::ThinDielectric(ref d) => make_bsdf::thin_dielectric(d, inputs)?,
        MaterialSpec::Plastic(ref p) => make_bsdf::plastic(p, inputs)?,
        MaterialSpec::RoughPlastic(ref p) => make_bsdf::rough_plastic(p, inputs)?,
        MaterialSpec::TwoSided(ref t) => {
            let front =
                material(&t.front, &mut Within(inputs, "front")).map_err(|e| inputs.blame("front", e))?;
            let back = match &t.back {
                Some(b) => {
                    Some(material(b, &mut Within(inputs, "back")).map_err(|e| inputs.blame("back", e))?)
                }
                None => None,
            };
            make_bsdf::two_sided(front, back)?
        }
        MaterialSpec::Mirror { albedo } => Mirror::new(vec(albedo))?.into(),
        MaterialSpec::Lambertian { ref albedo } => {
            Lambertian::textured(inputs.texture("albedo", albedo, TextureUse::Color)?)?.into()
        }
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
        MaterialSpec::NormalMap {
            ref normal_map,
            ref material,
        } => NormalMap::new(
            inputs.texture("normal_map", normal_map, TextureUse::NormalMap)?,
            inputs.material("material", material)?,
        )
        .into(),
    })
}

/// The background in `G`.
///
/// An environment map comes already read (`map`, read once for every scalar).
pub fn background<G: Float>(
    spec: &BackgroundSpec,
    map: Option<&Arc<EnvironmentMap>>,
) -> Result<Background<G>> {
    match (spec, map) {
        (BackgroundSpec::Sky { horizon, zenith, .. }, _) => Background::sky(vec(*horizon), vec(*zenith)),
        (BackgroundSpec::Solid { color, .. }, _) => Background::solid(vec(*color)),
        (BackgroundSpec::Envmap { rotate, .. }, Some(map)) => {
            let turn = Placement::new([1.0; 3], *rotate, [0.0; 3]);
            // Rows of R from the images of the axes (its columns).
            let [x, y, z] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
                .map(|e| turn.apply(Vec3::new(e[0], e[1], e[2])).to_f64());
            let rotation = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]];
            Background::map(Arc::clone(map), rotation)
        }
        (BackgroundSpec::Envmap { .. }, None) => Err(crate::Error::invalid(
            crate::error::Field::EnvironmentMap,
            "the image was not read",
        )),
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
