//! Writes each example's scene, as built in code, to `scenes/<example>.toml` (or to the
//! folder given as the argument), with the example's camera and default settings.
//!
//! `cargo run --example scene_to_toml` regenerates the committed files; every `f64` is
//! written in the shortest form that reads back to the same bits, so a scene built from
//! its file renders the same image as the code (`tests/files/scene_files.rs` checks it).

mod scenes;

use raytrace::material::Reflectance;
use raytrace::prelude::*;
use raytrace::scene_file::{
    BackgroundSpec, CameraSpec, FresnelSpec, LightSpec, MaterialSpec, ObjectSpec, RenderOptions, SceneFile,
    TextureRef,
};
use std::path::PathBuf;
use std::process::ExitCode;

/// One example: its name, what it shows, its scene, camera and default settings.
struct Example {
    name: &'static str,
    about: &'static str,
    scene: EnumScene<f64>,
    camera: CameraSpec,
    width: usize,
    spp: u32,
    max_depth: u32,
}

fn examples() -> raytrace::Result<Vec<Example>> {
    let screen = || CameraSpec::Screen { eye: None };
    let spec = |name, about, scene, spp, max_depth| Example {
        name,
        about,
        scene,
        camera: screen(),
        width: 800,
        spp,
        max_depth,
    };
    Ok(vec![
        spec(
            "four_mirrors",
            "Four mirror spheres above a dim mirror floor (the specification's minimum scene).",
            scenes::four_mirrors()?,
            1,
            10,
        ),
        spec(
            "matte_spheres",
            "Matte and mirror spheres on a matte ground (the specification's extension).",
            scenes::matte_spheres()?,
            16,
            10,
        ),
        spec(
            "glass",
            "Solid and hollow glass spheres beside mirror and matte ones.",
            scenes::glass()?,
            32,
            20,
        ),
        spec(
            "plane_and_triangles",
            "An infinite plane, a mirror pyramid and a matte tetrahedron of triangles, beside spheres.",
            scenes::plane_and_triangles()?,
            32,
            20,
        ),
        spec(
            "point_lights",
            "Matte spheres lit by three coloured point lights under a dim sky.",
            scenes::point_lights()?,
            16,
            10,
        ),
        Example {
            name: "random_spheres",
            about: "Ray Tracing in One Weekend's final scene, generated from seed 0: about 480 random spheres.",
            scene: scenes::random_spheres(0)?,
            // scenes::random_spheres_camera: from (13, 2, 3) at the origin, 20°, 16:9.
            camera: CameraSpec::LookAt {
                from: [13.0, 2.0, 3.0],
                at: [0.0; 3],
                up: [0.0, 1.0, 0.0],
                vfov: 20.0,
                aspect: 16.0 / 9.0,
                aperture: 0.0,
                focus_distance: None,
            },
            width: 400,
            spp: 10,
            max_depth: 50,
        },
    ])
}

/// The scene file describing `e`; materials are named by kind and numbered, one entry
/// per distinct material. A mesh is an error: its triangles come from a file this
/// program has no name for.
fn to_file(e: &Example) -> raytrace::Result<SceneFile> {
    let mut file = SceneFile::default();
    *file.render_mut() = RenderOptions {
        width: e.width,
        spp: e.spp,
        max_depth: e.max_depth,
        ..RenderOptions::default()
    };
    file.camera = e.camera.clone();
    let light = e.scene.background_sampled();
    file.background = match e.scene.background() {
        Background::Solid(c) => BackgroundSpec::Solid {
            color: c.to_f64(),
            light,
        },
        Background::Sky { horizon, zenith } => BackgroundSpec::Sky {
            horizon: horizon.to_f64(),
            zenith: zenith.to_f64(),
            light,
        },
        Background::Map { .. } => {
            return Err(raytrace::Error::invalid(
                raytrace::error::Field::EnvironmentMap,
                "an environment map's image has no file name here",
            ));
        }
    };
    let mut named: Vec<(MaterialKind<f64>, String)> = Vec::new();
    for o in e.scene.objects() {
        let m = e.scene.material(o.material);
        let material = match named.iter().find(|(known, _)| known == m) {
            Some((_, name)) => name.clone(),
            None => {
                let (kind, spec) = material(m).ok_or_else(|| {
                    let why = format!(
                        "{}: only the specification's materials and emitters are written",
                        e.name
                    );
                    raytrace::Error::InvalidSettings(why)
                })?;
                let name = format!("{kind}_{}", named.len());
                file.materials.insert(name.clone(), spec);
                named.push((m.clone(), name.clone()));
                name
            }
        };
        file.objects.push(match &o.shape {
            ShapeKind::Sphere(s) => ObjectSpec::Sphere {
                center: s.center().to_f64(),
                radius: s.radius(),
                material,
            },
            ShapeKind::Plane(p) => ObjectSpec::Plane {
                point: p.point().to_f64(),
                normal: p.normal().to_f64(),
                material,
            },
            ShapeKind::Triangle(t) => {
                let [a, b, c] = t.vertices().map(|v| v.to_f64());
                ObjectSpec::Triangle { a, b, c, material }
            }
            ShapeKind::Disk(d) => {
                // The unit disk's map: its axes, then a third column on the side of the
                // front face (a negative determinant flips it, as in Mitsuba).
                let ([u, v], c) = (d.axes().map(|a| a.to_f64()), d.center().to_f64());
                let w = d.normal().to_f64();
                ObjectSpec::Disk {
                    center: [0.0; 3],
                    normal: [0.0, 0.0, 1.0],
                    radius: 1.0,
                    matrix: Some(std::array::from_fn(|i| [u[i], v[i], w[i], c[i]])),
                    material,
                }
            }
            ShapeKind::Mesh(_) | ShapeKind::Instance(_) => {
                let why = format!("{}: a mesh cannot be written without its file", e.name);
                return Err(raytrace::Error::InvalidSettings(why));
            }
        });
    }
    for l in e.scene.lights() {
        file.lights.push(match l {
            Light::Point(l) => LightSpec::Point {
                position: l.position().to_f64(),
                intensity: l.intensity().to_f64(),
            },
            Light::Spot(l) => LightSpec::Spot {
                position: l.position().to_f64(),
                direction: l.direction().to_f64(),
                intensity: l.intensity().to_f64(),
                cutoff_angle: l.cutoff_angle(),
                beam_width: Some(l.beam_width()),
            },
            Light::Directional(l) => LightSpec::Directional {
                direction: l.direction().to_f64(),
                irradiance: l.irradiance().to_f64(),
            },
        });
    }
    Ok(file)
}

/// The file's entry for one of the specification's materials or an emitter (the examples
/// use no other); `None` for the others.
fn material(m: &MaterialKind<f64>) -> Option<(&'static str, MaterialSpec)> {
    Some(match m {
        MaterialKind::Mirror(m) => (
            "mirror",
            MaterialSpec::Mirror {
                albedo: m.albedo().to_f64(),
            },
        ),
        MaterialKind::Lambertian(m) => (
            "matte",
            MaterialSpec::Lambertian {
                albedo: match m.albedo().as_constant() {
                    Some(c) => TextureRef::Color(c.to_f64()),
                    None => unimplemented!("the examples' matte surfaces are of one colour"),
                },
            },
        ),
        MaterialKind::Dielectric(m) => (
            "glass",
            MaterialSpec::Dielectric {
                index: m.refractive_index(),
                albedo: (m.albedo() != Vec3::splat(1.0)).then(|| m.albedo().to_f64()),
                fresnel: match m.reflectance() {
                    Reflectance::Schlick => FresnelSpec::Schlick,
                    Reflectance::Fresnel => FresnelSpec::Exact,
                },
            },
        ),
        MaterialKind::Emissive(m) => (
            "light",
            MaterialSpec::Emissive {
                radiance: m.emission().radiance().to_f64(),
                two_sided: m.emission().is_two_sided(),
                albedo: (m.albedo() != Vec3::zero()).then(|| m.albedo().to_f64()),
            },
        ),
        MaterialKind::NormalMap(_)
        | MaterialKind::Conductor(_)
        | MaterialKind::RoughConductor(_)
        | MaterialKind::RoughDielectric(_)
        | MaterialKind::ThinDielectric(_)
        | MaterialKind::Plastic(_)
        | MaterialKind::RoughPlastic(_)
        | MaterialKind::TwoSided(_) => return None,
    })
}

fn run() -> raytrace::Result<()> {
    let out = std::env::args_os()
        .nth(1)
        .map_or_else(|| PathBuf::from("scenes"), PathBuf::from);
    std::fs::create_dir_all(&out).map_err(|source| raytrace::Error::Io {
        path: out.clone(),
        source,
    })?;
    for e in examples()? {
        let path = out.join(format!("{}.toml", e.name));
        let text = format!(
            "# {}\n# Written by `cargo run --example scene_to_toml` from examples/scenes/mod.rs.\n\n{}",
            e.about,
            to_file(&e)?.to_toml()
        );
        std::fs::write(&path, text).map_err(|source| raytrace::Error::Io {
            path: path.clone(),
            source,
        })?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
