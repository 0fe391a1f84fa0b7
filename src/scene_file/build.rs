//! Building a scene file's scene, camera and settings, every value checked on the way.

use super::SceneFile;
use super::assets::Assets;
use super::camera::FileCamera;
use super::check::{blame, checked, vec};
use super::location::KeyPath;
use super::make::{self, Solid};
use super::model::{BackgroundSpec, CameraSpec};
use super::objects::ObjectSpec;
use super::placing::{affine, mesh_placement, only_matrix};
use super::resolve::Resolver;
use super::summary::{Summary, count};
use super::transform::Placement;
use crate::background::EnvironmentMap;
use crate::error::{Error, Field, Result};
use crate::float::Float;
use crate::image::Tonemap;
use crate::material::MaterialKind;
use crate::mesh::MeshData;
use crate::render::RenderSettings;
use crate::scene::{EnumScene, MaterialId};
use crate::shape::{Instance, Mesh, Prototype, ShapeKind};
use crate::transform::Affine;
use crate::validate::{number, rule, show};
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

/// What a scene file builds: everything a render needs, and a summary to report.
#[derive(Clone, Debug)]
pub struct Built<F: Float> {
    /// The scene.
    pub scene: EnumScene<F>,
    /// The camera, sized by `[render] width`.
    pub camera: FileCamera<F>,
    /// Samples per pixel, depth and seed (no progress bar).
    pub settings: RenderSettings,
    /// How the display formats (PNG, PPM) expose and tone map the image.
    pub tonemap: Tonemap,
    /// What the scene holds.
    pub summary: Summary,
}

/// Builds `file` in scalar `F`.
pub(super) fn build<F: Float>(file: &SceneFile) -> Result<Built<F>> {
    let root = file.root();
    let r = file.render();
    let settings =
        RenderSettings::new(r.spp, r.max_depth, r.seed).map_err(|e| blame(&root, &root.key("render"), e))?;
    let tonemap = file.tonemap()?;
    let camera = camera::<F>(&root, &file.camera, r.width)?;
    let at = root.key("background");
    let folder = file.path().parent().unwrap_or(Path::new(""));
    let map = match &file.background {
        BackgroundSpec::Envmap { file, scale, .. } => Some(Arc::new(
            EnvironmentMap::load(&folder.join(file), *scale).map_err(|e| blame(&root, &at, e))?,
        )),
        _ => None,
    };
    let background = checked::<F, _>(
        &root,
        &at,
        make::background::<f64>(&file.background, map.as_ref()),
        make::background::<F>(&file.background, map.as_ref()),
    )?;
    let mut scene = EnumScene::new(background);
    scene.set_acceleration(r.acceleration);
    scene.set_bvh_quality(r.bvh_quality);
    scene.set_background_sampled(match &file.background {
        BackgroundSpec::Sky { light, .. } | BackgroundSpec::Solid { light, .. } => *light,
        BackgroundSpec::Envmap { .. } => true,
    });

    let folder = file.path().parent().unwrap_or(Path::new(""));
    let mut resolver = Resolver::new(file, folder);
    resolver.check_textures::<F>()?;
    let materials = resolver.materials::<F>()?;
    let mut summary = Summary::default();
    let prototypes = prototypes(&root, file, folder)?;
    let mut ids = BTreeMap::new();
    for (i, object) in file.objects.iter().enumerate() {
        let at = root.key("objects").index(i);
        if super::obj_materials::wants_mtl(object) {
            super::obj_materials::add(
                &mut scene,
                &mut summary,
                (&root, &at),
                object,
                (folder, &materials),
            )?;
            continue;
        }
        let Some(m) = materials.get(object.material()) else {
            return Err(at
                .key("material")
                .error(unknown_material(object.material(), &materials)));
        };
        // Objects of one named material share its place in the scene's table.
        let m = *ids
            .entry(object.material())
            .or_insert_with(|| scene.add_material(m.clone()));
        add_object(
            &mut scene,
            &mut summary,
            (&root, &at),
            object,
            m,
            (folder, file.assets(), &prototypes),
        )?;
    }
    for (i, light) in file.lights.iter().enumerate() {
        let at = root.key("lights").index(i);
        scene.add_light(checked::<F, _>(
            &root,
            &at,
            make::light::<f64>(light),
            make::light::<F>(light),
        )?);
    }
    count(&scene, &mut summary);
    Ok(Built {
        scene,
        camera,
        settings,
        tonemap,
        summary,
    })
}

/// The material `spec` at `at`: a two-sided one's materials at the keys `front` and
/// `back`, so their errors are reported there.
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

fn camera<F: Float>(root: &KeyPath, spec: &CameraSpec, width: usize) -> Result<FileCamera<F>> {
    let at = root.key("camera");
    match *spec {
        CameraSpec::Screen { eye } => checked::<F, _>(
            root,
            &at,
            make::screen::<f64>(width, eye),
            make::screen::<F>(width, eye),
        ),
        CameraSpec::LookAt {
            from,
            at: target,
            up,
            vfov,
            aspect,
            aperture,
            focus_distance,
        } => {
            let aspect = rule::positive(aspect).map_err(|why| at.key("aspect").error(why))?;
            let height = look_at_height(width, aspect);
            // A height past usize saturates, and the camera refuses it as too many pixels.
            let spec = make::LookAt {
                from,
                at: target,
                up,
                vfov,
                aperture,
                focus_distance,
                size: (width, height as usize),
            };
            let mut made = checked::<F, _>(root, &at, make::look_at::<f64>(&spec), make::look_at::<F>(&spec));
            if let Err(Error::SceneFile {
                message,
                field: Some(Field::ImageSize),
                ..
            }) = &mut made
            {
                message.push_str(&format!(
                    ": the image is width × ⌊width / camera.aspect⌋ = {width} × ⌊{width}/{}⌋",
                    number(aspect)
                ));
            }
            made
        }
    }
}

/// `⌊width/aspect⌋`, taken as the next integer when within `10⁻¹²` (relative) of it, so
/// a ratio such as `16/9`, which `f64` cannot hold exactly, still gives `400 × 225`.
pub(super) fn look_at_height(width: usize, aspect: f64) -> f64 {
    (width as f64 / aspect * (1.0 + 1e-12)).floor()
}

fn add_object<F: Float>(
    scene: &mut EnumScene<F>,
    summary: &mut Summary,
    (root, at): (&KeyPath, &KeyPath),
    spec: &ObjectSpec,
    material: MaterialId,
    (folder, assets, prototypes): (&Path, &Assets, &BTreeMap<&str, Arc<Prototype>>),
) -> Result<()> {
    let solid = match *spec {
        ObjectSpec::Sphere { center, radius, .. } => Solid::Sphere { center, radius },
        ObjectSpec::Plane { point, normal, .. } => Solid::Plane { point, normal },
        ObjectSpec::Triangle { a, b, c, .. } => Solid::Triangle { a, b, c },
        ObjectSpec::Disk {
            center,
            normal,
            radius,
            matrix,
            ..
        } => super::disk::solid((root, at), center, normal, radius, matrix)?,
        ObjectSpec::Mesh {
            ref file,
            scale,
            rotate,
            translate,
            face_normals,
            flip_tex_coords,
            matrix,
            ..
        } => {
            let placement = mesh_placement((root, at), scale, rotate, translate, matrix)?;
            let path = folder.join(file);
            let attributes = Attributes::new(&path, face_normals, flip_tex_coords);
            let data = load_mesh(assets, folder, file).map_err(|e| at.key("file").wrap(e))?;
            let shape = mesh::<F>(root, at, &data, &placement, attributes, summary)?;
            scene.add_object(shape, material);
            return Ok(());
        }
        ObjectSpec::Instance {
            ref mesh,
            scale,
            rotate,
            translate,
            matrix,
            ..
        } => {
            let Some(prototype) = prototypes.get(mesh.as_str()) else {
                let known: Vec<String> = prototypes.keys().map(|k| k.to_string()).collect();
                let why = super::resolve::unknown("mesh", mesh, known.iter(), "meshes");
                return Err(at.key("mesh").error(why));
            };
            let to_world = match matrix {
                Some(rows) => {
                    only_matrix(at, scale, rotate, translate)?;
                    Affine::from_rows(rows).map_err(|e| blame(root, &at.key("matrix"), e))?
                }
                None => affine(at, scale.factors(), rotate, translate)?,
            };
            let instance = Instance::new(Arc::clone(prototype), to_world).map_err(|e| blame(root, at, e))?;
            scene.add_object(ShapeKind::from(instance), material);
            return Ok(());
        }
    };
    let shape = checked::<F, _>(root, at, make::shape::<f64>(solid), make::shape::<F>(solid))?;
    scene.add_object(shape, material);
    Ok(())
}

/// Every `[meshes]` entry read once, by name, for the instances to share.
fn prototypes<'f>(
    root: &KeyPath,
    file: &'f SceneFile,
    folder: &Path,
) -> Result<BTreeMap<&'f str, Arc<Prototype>>> {
    let mut made = BTreeMap::new();
    for (name, def) in &file.meshes {
        let at = root.key("meshes").key(name).key("file");
        let mesh = load_mesh(file.assets(), folder, &def.file).map_err(|e| at.wrap(e))?;
        let vertices = mesh.positions.iter().map(|p| p.to_f64()).collect();
        let prototype = Prototype::new(vertices, mesh.triangles.clone()).map_err(|e| at.wrap(e))?;
        made.insert(name.as_str(), Arc::new(prototype));
    }
    Ok(made)
}

/// The mesh a `file` key names: one held in memory ([`Assets`]), else the mesh file at
/// that path relative to `folder`.
fn load_mesh(assets: &Assets, folder: &Path, file: &str) -> Result<Arc<MeshData>> {
    match assets.mesh(file) {
        Some(mesh) => Ok(Arc::clone(mesh)),
        None => crate::mesh::load(&folder.join(file)).map(Arc::new),
    }
}

/// Which of a mesh file's vertex attributes a mesh takes, and how.
#[derive(Clone, Copy, Debug)]
pub(super) struct Attributes {
    /// Whether its normals are kept (not `face_normals`).
    normals: bool,
    /// Whether its texture coordinates' `v` is flipped, `v ↦ 1 − v`.
    pub(super) flip_v: bool,
}

impl Attributes {
    /// A mesh object's `face_normals` and `flip_tex_coords` (unset: the default for the
    /// format of the file at `path`).
    pub(super) fn new(path: &Path, face_normals: bool, flip_tex_coords: Option<bool>) -> Self {
        Self {
            normals: !face_normals,
            flip_v: flip_tex_coords.unwrap_or_else(|| crate::mesh::flips_tex_coords(path)),
        }
    }
}

/// The mesh `mesh`, placed and rounded to `F`, with its normals (placed as normals are)
/// and texture coordinates as `attributes` say; its skipped faces are counted in
/// `summary`.
pub(super) fn mesh<F: Float>(
    root: &KeyPath,
    at: &KeyPath,
    mesh: &MeshData,
    placement: &Placement,
    attributes: Attributes,
    summary: &mut Summary,
) -> Result<Mesh<F>> {
    let mut vertices = Vec::with_capacity(mesh.positions.len());
    for (k, &p) in mesh.positions.iter().enumerate() {
        let placed = placement.apply(p);
        let v = vec::<F>(placed.to_f64());
        if !v.is_finite() {
            return Err(at.error(format!(
                "vertex {k} of the mesh lands at {} once scaled, rotated and translated, which is \
                 not finite in {}",
                show(placed),
                F::NAME
            )));
        }
        vertices.push(v);
    }
    // Placement and rounding can flatten a face: the mesh leaves it out and counts it.
    let mut shape = Mesh::new(vertices, mesh.triangles.clone()).map_err(|e| blame(root, at, e))?;
    if let Some(normals) = mesh.normals.as_ref().filter(|_| attributes.normals) {
        // Each normal's direction, rounded to F once it is of unit length (a normal placed
        // by a tiny scale may not be finite in F before).
        let placed = normals.iter().map(|&n| {
            let n = placement.apply_normal(n);
            vec::<F>(n.try_normalize().unwrap_or(n).to_f64())
        });
        shape = shape
            .with_normals(placed.collect())
            .map_err(|e| blame(root, at, e))?;
    }
    if let Some(uvs) = &mesh.uvs {
        let flip = |[u, v]: [f64; 2]| [u, if attributes.flip_v { 1.0 - v } else { v }];
        let uvs = uvs.iter().map(|&uv| flip(uv).map(F::from_f64)).collect();
        shape = shape.with_uvs(uvs).map_err(|e| blame(root, at, e))?;
    }
    summary.skipped_degenerate += shape.skipped_degenerate() + mesh.skipped_degenerate;
    summary.meshes += 1;
    Ok(shape)
}
