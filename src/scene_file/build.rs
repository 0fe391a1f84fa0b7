//! Building a scene file's scene, camera and settings, every value checked on the way.

use super::camera::FileCamera;
use super::check::{self, blame, vec};
use super::location::Field;
use super::model::{BackgroundSpec, CameraSpec, FresnelSpec, LightSpec, MaterialSpec, ObjectSpec};
use super::transform::Placement;
use super::{RenderOptions, SceneFile};
use crate::aabb::Aabb;
use crate::background::Background;
use crate::camera::{LookAtCamera, ScreenCamera};
use crate::error::Result;
use crate::float::{Float, lit};
use crate::light::PointLight;
use crate::material::{Dielectric, Emissive, Lambertian, MaterialKind, Mirror, Reflectance};
use crate::render::RenderSettings;
use crate::scene::EnumScene;
use crate::shape::{Hittable, Mesh, Plane, ShapeKind, Sphere, Triangle};
use std::collections::BTreeMap;
use std::path::Path;

/// What a scene file builds: everything a render needs, and a summary to report.
#[derive(Clone, Debug)]
pub struct Built<F> {
    /// The scene.
    pub scene: EnumScene<F>,
    /// The camera, sized by `[render] width`.
    pub camera: FileCamera<F>,
    /// Samples per pixel, depth and seed (no progress bar).
    pub settings: RenderSettings,
    /// What the scene holds.
    pub summary: Summary,
}

/// What a built scene holds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Summary {
    /// Spheres.
    pub spheres: usize,
    /// Planes.
    pub planes: usize,
    /// Triangles, those of meshes included.
    pub triangles: usize,
    /// Mesh objects.
    pub meshes: usize,
    /// Point lights.
    pub lights: usize,
    /// Objects that give off light (of an emissive material).
    pub emitters: usize,
    /// Of those, the ones sampled as lights (spheres, triangles and meshes; not planes).
    pub sampled_emitters: usize,
    /// Mesh faces left out for having no area: those the mesh reader skipped and those
    /// the placement (or the rounding to the render's scalar) made degenerate.
    pub skipped_degenerate: usize,
    /// The box around every bounded object (all but planes), if there is one.
    pub bounds: Option<Aabb<f64>>,
    /// Whether the scene intersects through a BVH.
    pub uses_bvh: bool,
}

/// Builds `file` in scalar `F`.
pub(super) fn build<F: Float>(file: &SceneFile) -> Result<Built<F>> {
    let root = Field::root(file.path());
    let settings = settings(&root.key("render"), file.render())?;
    let camera = camera::<F>(&root, &file.camera, file.render().width)?;
    let mut scene = EnumScene::new(background::<F>(&root.key("background"), &file.background)?);
    scene.set_acceleration(file.render().acceleration);

    let mut materials = BTreeMap::new();
    for (name, m) in &file.materials {
        materials.insert(name.as_str(), material::<F>(&root.key("materials").key(name), m)?);
    }
    let folder = file.path().parent().unwrap_or(Path::new(""));
    let mut summary = Summary::default();
    for (i, object) in file.objects.iter().enumerate() {
        let at = root.key("objects").index(i);
        let Some(&m) = materials.get(object.material()) else {
            return Err(at
                .key("material")
                .error(unknown_material(object.material(), &materials)));
        };
        add_object(&mut scene, &mut summary, &at, object, m, folder)?;
    }
    for (i, light) in file.lights.iter().enumerate() {
        scene.add_light(point_light(&root.key("lights").index(i), light)?);
    }
    count(&scene, &mut summary);
    Ok(Built {
        scene,
        camera,
        settings,
        summary,
    })
}

fn unknown_material(name: &str, known: &BTreeMap<&str, MaterialKind<impl Float>>) -> String {
    if known.is_empty() {
        format!("no material named `{name}`: the file defines no [materials]")
    } else {
        let names: Vec<_> = known.keys().map(|k| format!("`{k}`")).collect();
        format!(
            "no material named `{name}` (the file defines {})",
            names.join(", ")
        )
    }
}

fn settings(at: &Field, r: &RenderOptions) -> Result<RenderSettings> {
    if r.width == 0 {
        return Err(at.key("width").error("must be > 0 (got 0)"));
    }
    if r.spp == 0 {
        return Err(at.key("spp").error("must be at least 1 (got 0)"));
    }
    if r.max_depth > RenderSettings::MAX_DEPTH {
        return Err(at.key("max_depth").error(format!(
            "must be at most {} (got {})",
            RenderSettings::MAX_DEPTH,
            r.max_depth
        )));
    }
    RenderSettings::new(r.spp, r.max_depth, r.seed).map_err(|e| at.wrap(e))
}

fn camera<F: Float>(root: &Field, spec: &CameraSpec, width: usize) -> Result<FileCamera<F>> {
    let at = root.key("camera");
    let width_at = root.key("render").key("width");
    match *spec {
        CameraSpec::Screen { eye } => {
            if width < 4 || !width.is_multiple_of(2) {
                return Err(width_at.error(format!(
                    "the screen camera needs an even width of at least 4, for a 2:1 image (got {width})"
                )));
            }
            let camera = ScreenCamera::with_width(width).map_err(|e| width_at.wrap(e))?;
            Ok(FileCamera::Screen(match eye {
                Some(eye) => {
                    let eye_at = at.key("eye");
                    camera
                        .translated(check::finite(&eye_at, eye)?)
                        .map_err(|e| eye_at.wrap(e))?
                }
                None => camera,
            }))
        }
        CameraSpec::LookAt {
            from,
            at: target,
            up,
            vfov,
            aspect,
        } => {
            check::finite(&at.key("from"), from)?;
            check::finite(&at.key("at"), target)?;
            check::direction(&at.key("up"), up)?;
            if !(vfov > 0.0 && vfov < 180.0) {
                return Err(at
                    .key("vfov")
                    .error(format!("must be in (0, 180) degrees (got {vfov})")));
            }
            let height = look_at_height(width, check::positive(&at.key("aspect"), aspect)?);
            if height < 1.0 {
                return Err(at.key("aspect").error(format!(
                    "makes the image less than one pixel high ({width}/{aspect})"
                )));
            }
            let camera =
                LookAtCamera::new(vec(from), vec(target), vec(up), lit(vfov), width, height as usize);
            camera.map(FileCamera::LookAt).map_err(|e| {
                blame::<F>(
                    &at,
                    e,
                    &[
                        ("camera position", "from"),
                        ("camera target", "at"),
                        ("camera view direction (from − at)", "at"),
                        ("camera up vector", "up"),
                        ("camera field of view", "vfov"),
                    ],
                )
            })
        }
    }
}

/// `⌊width/aspect⌋`, taken as the next integer when within `10⁻¹²` (relative) of it, so
/// a ratio such as `16/9`, which `f64` cannot hold exactly, still gives `400 × 225`.
pub(super) fn look_at_height(width: usize, aspect: f64) -> f64 {
    (width as f64 / aspect * (1.0 + 1e-12)).floor()
}

fn background<F: Float>(at: &Field, spec: &BackgroundSpec) -> Result<Background<F>> {
    let made = match *spec {
        BackgroundSpec::Sky { horizon, zenith } => Background::sky(
            vec(check::non_negative(&at.key("horizon"), horizon)?),
            vec(check::non_negative(&at.key("zenith"), zenith)?),
        ),
        BackgroundSpec::Solid { color } => {
            Background::solid(vec(check::non_negative(&at.key("color"), color)?))
        }
    };
    made.map_err(|e| blame::<F>(at, e, &[]))
}

fn material<F: Float>(at: &Field, spec: &MaterialSpec) -> Result<MaterialKind<F>> {
    let albedo_at = at.key("albedo");
    let wrap = |e| {
        blame::<F>(
            at,
            e,
            &[("refractive index", "index"), ("emitted radiance", "radiance")],
        )
    };
    Ok(match *spec {
        MaterialSpec::Mirror { albedo } => Mirror::new(vec(check::albedo(&albedo_at, albedo)?))
            .map_err(wrap)?
            .into(),
        MaterialSpec::Lambertian { albedo } => Lambertian::new(vec(check::albedo(&albedo_at, albedo)?))
            .map_err(wrap)?
            .into(),
        MaterialSpec::Dielectric {
            index,
            albedo,
            fresnel,
        } => {
            let mut glass = Dielectric::new(lit(check::positive(&at.key("index"), index)?)).map_err(wrap)?;
            if let Some(albedo) = albedo {
                glass = glass
                    .with_albedo(vec(check::albedo(&albedo_at, albedo)?))
                    .map_err(wrap)?;
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
            let radiance = check::non_negative(&at.key("radiance"), radiance)?;
            let mut light = Emissive::new(vec(radiance)).map_err(wrap)?.two_sided(two_sided);
            if let Some(albedo) = albedo {
                light = light
                    .with_albedo(vec(check::albedo(&albedo_at, albedo)?))
                    .map_err(wrap)?;
            }
            light.into()
        }
    })
}

fn add_object<F: Float>(
    scene: &mut EnumScene<F>,
    summary: &mut Summary,
    at: &Field,
    spec: &ObjectSpec,
    material: MaterialKind<F>,
    folder: &Path,
) -> Result<()> {
    match spec {
        ObjectSpec::Sphere { center, radius, .. } => {
            let center = check::finite(&at.key("center"), *center)?;
            let radius = check::positive(&at.key("radius"), *radius)?;
            let sphere = Sphere::new(vec(center), lit(radius)).map_err(|e| {
                blame::<F>(at, e, &[("sphere centre", "center"), ("sphere radius", "radius")])
            })?;
            scene.add(sphere, material);
        }
        ObjectSpec::Plane { point, normal, .. } => {
            let point = check::finite(&at.key("point"), *point)?;
            let normal = check::direction(&at.key("normal"), *normal)?;
            let plane = Plane::new(vec(point), vec(normal))
                .map_err(|e| blame::<F>(at, e, &[("plane point", "point"), ("plane normal", "normal")]))?;
            scene.add(plane, material);
        }
        ObjectSpec::Triangle { a, b, c, .. } => {
            let [a, b, c] = [("a", a), ("b", b), ("c", c)].map(|(k, v)| check::finite(&at.key(k), *v));
            let triangle = Triangle::new(vec(a?), vec(b?), vec(c?)).map_err(|e| blame::<F>(at, e, &[]))?;
            scene.add(triangle, material);
        }
        ObjectSpec::Mesh {
            file,
            scale,
            rotate,
            translate,
            ..
        } => {
            let factors = check::finite(&at.key("scale"), scale.factors())?;
            if factors.contains(&0.0) {
                return Err(at.key("scale").error(format!(
                    "every factor must be non-zero (got {})",
                    check::show(factors)
                )));
            }
            let placement = Placement::new(
                factors,
                check::finite(&at.key("rotate"), *rotate)?,
                check::finite(&at.key("translate"), *translate)?,
            );
            let mesh = crate::mesh::load(&folder.join(file)).map_err(|e| at.key("file").wrap(e))?;
            let mut vertices = Vec::with_capacity(mesh.positions.len());
            for (k, &p) in mesh.positions.iter().enumerate() {
                let placed = placement.apply(p);
                let v = vec::<F>(placed.to_f64());
                if !v.is_finite() {
                    return Err(at.error(format!(
                        "vertex {k} of the mesh is placed at {placed:?}, which is not finite in {}",
                        F::NAME
                    )));
                }
                vertices.push(v);
            }
            // Placement and rounding can flatten a face: the mesh leaves it out and counts it.
            let shape = Mesh::new(vertices, mesh.triangles).map_err(|e| at.key("file").wrap(e))?;
            summary.skipped_degenerate += shape.skipped_degenerate();
            scene.add(shape, material);
            summary.meshes += 1;
            summary.skipped_degenerate += mesh.skipped_degenerate;
        }
    }
    Ok(())
}

fn point_light<F: Float>(at: &Field, spec: &LightSpec) -> Result<PointLight<F>> {
    let position = check::finite(&at.key("position"), spec.position)?;
    let intensity = check::non_negative(&at.key("intensity"), spec.intensity)?;
    PointLight::new(vec(position), vec(intensity)).map_err(|e| {
        blame::<F>(
            at,
            e,
            &[("light position", "position"), ("light intensity", "intensity")],
        )
    })
}

/// Fills in the counts, the bounds and whether a BVH is used.
fn count<F: Float>(scene: &EnumScene<F>, summary: &mut Summary) {
    let mut bounds: Option<Aabb<f64>> = None;
    for o in scene.objects() {
        match &o.shape {
            ShapeKind::Sphere(_) => summary.spheres += 1,
            ShapeKind::Plane(_) => summary.planes += 1,
            ShapeKind::Triangle(_) => summary.triangles += 1,
            ShapeKind::Mesh(m) => summary.triangles += m.parts() as usize,
        }
        if let Some(b) = o.shape.bounds() {
            let b = Aabb::new(b.min.cast::<f64>(), b.max.cast::<f64>());
            bounds = Some(bounds.map_or(b, |all| all.union(b)));
        }
    }
    summary.lights = scene.lights().len();
    let emits = |m: &MaterialKind<F>| matches!(m, MaterialKind::Emissive(_));
    summary.emitters = scene.objects().iter().filter(|o| emits(&o.material)).count();
    summary.sampled_emitters = scene.emitters().len();
    summary.bounds = bounds;
    summary.uses_bvh = scene.uses_bvh();
}
