//! A small, generic, compile-time-dispatched ray tracer.
//!
//! It renders exactly what the specification asks — the eye at the origin, a 4×2 screen
//! at distance 1 measured between the outermost pixel centres, mirror and matte spheres,
//! recursion to `max_depth`, a 16-bit plain PPM — and is generic over the scalar
//! ([`Float`]: `f32`, `f64`, double-double) and over the random generator.
//!
//! The spec's abstract object and material are the traits [`Hittable`] and
//! [`Material`]. A scene can hold them as trait objects ([`DynScene`], the spec's
//! "vector of smart pointers") or as the enums [`ShapeKind`] and [`MaterialKind`]
//! ([`EnumScene`], dispatched by `match`); both go through the same renderer and give
//! the same bytes.
//!
//! ```
//! use raytrace::prelude::*;
//!
//! let mut scene = EnumScene::<f64>::new(Background::default());
//! scene.add(Sphere::new(Vec3::new(0.0, 0.0, -3.0), 1.0)?, Mirror::new(Vec3::new(0.9, 0.6, 0.3))?);
//! scene.add(Sphere::new(Vec3::new(0.0, -101.0, -3.0), 100.0)?, Lambertian::new(Vec3::splat(0.5))?);
//! let camera = ScreenCamera::new(80, 40)?;
//! let settings = RenderSettings::new(4, 10, 42)?;
//! let render = render(&scene, &camera, &settings)?;
//! let samples = render.image.to_u16(Encoding::Srgb);
//! # let dir = std::env::temp_dir();
//! write_ppm(&dir.join("doc_example.ppm"), &samples)?;
//! # Ok::<(), raytrace::Error>(())
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod aabb;
pub mod advice;
pub mod background;
pub mod bvh;
pub mod camera;
#[cfg(feature = "cli")]
pub mod cli;
pub mod double_double;
pub mod error;
pub mod float;
pub mod frame;
pub mod image;
pub mod import;
mod lanes;
pub mod light;
pub mod material;
pub mod mesh;
pub mod metrics;
pub mod optics;
pub mod ray;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod scene_file;
pub mod shape;
pub mod texture;
pub mod transform;
mod validate;
pub mod vec3;

pub use background::Background;
pub use camera::{Camera, CastCamera, LookAtCamera, ScreenCamera};
pub use double_double::DoubleDouble;
pub use error::{Error, Result};
pub use float::{Float, lit};
pub use image::{Encoding, Image, Image16};
pub use light::{DirectionalLight, Light, PointLight, SpotLight};
pub use material::{
    BsdfSample, BsdfVisitor, Dielectric, Emission, Emissive, Eval, Lambertian, Lobes, Material, MaterialKind,
    Mirror, Scatter, SharedMaterial,
};
pub use ray::Ray;
pub use render::{
    LightSampling, Rect, Render, RenderSettings, RenderStats, Renderer, render, render_reference,
};
pub use sampling::DefaultRng;
pub use scene::{Acceleration, BvhQuality, DynScene, EnumScene, Layout, MaterialId, Object, Scene};
pub use shape::{Hit, Hittable, Intersection, Mesh, Plane, ShapeKind, Sphere, Surface, Triangle};
pub use vec3::{Color, Vec3};

/// The random generators' crate, re-exported so a user's generator and `Rng` bounds name
/// the same version as the renderer's.
pub use rand;

/// Everything needed to build and render a scene.
pub mod prelude {
    pub use crate::image::{read_ppm, write_png, write_ppm};
    pub use crate::{
        Background, Camera, Color, Dielectric, DirectionalLight, DynScene, Emissive, Encoding, EnumScene,
        Error, Float, Hittable, Lambertian, Layout, Light, LightSampling, LookAtCamera, Material,
        MaterialKind, Mesh, Mirror, Plane, PointLight, Ray, Rect, RenderSettings, Renderer, Scatter, Scene,
        ScreenCamera, ShapeKind, Sphere, SpotLight, Triangle, Vec3, lit, render,
    };
}
