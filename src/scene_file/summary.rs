//! What a built scene holds: [`Summary`], counted from the scene once it is built.

use crate::aabb::Aabb;
use crate::float::Float;
use crate::material::{Material, MaterialKind};
use crate::scene::EnumScene;
use crate::shape::{Hittable, ShapeKind};

/// What a built scene holds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Summary {
    /// Spheres.
    pub spheres: usize,
    /// Planes.
    pub planes: usize,
    /// Disks.
    pub disks: usize,
    /// Triangles, those of meshes included.
    pub triangles: usize,
    /// Mesh objects.
    pub meshes: usize,
    /// Placements of shared meshes (their triangles count among the triangles, once per
    /// placement).
    pub instances: usize,
    /// Lights (point, spot, directional).
    pub lights: usize,
    /// Objects that give off light (of an emissive material).
    pub emitters: usize,
    /// Of those, the ones sampled as lights (spheres, disks, triangles and meshes; not planes).
    pub sampled_emitters: usize,
    /// Mesh faces left out for having no area: those the mesh reader skipped and those
    /// the placement (or the rounding to the render's scalar) made degenerate.
    pub skipped_degenerate: usize,
    /// The box around every bounded object (all but planes), if there is one.
    pub bounds: Option<Aabb<f64>>,
    /// Whether the scene intersects through a BVH.
    pub uses_bvh: bool,
    /// The references the BVH sorts, if there is one: more than its parts where spatial
    /// splits (`bvh_quality = "high"`) cut triangles into pieces.
    pub bvh_references: Option<usize>,
    /// What was read but has no effect, each naming its file and line: the keys and image
    /// options of an OBJ file's `.mtl` materials that are not read or that their mapping
    /// leaves unused, and a height map given as `map_Bump`.
    pub notes: Vec<String>,
}

/// Fills in the counts, the bounds and whether a BVH is used.
pub(super) fn count<F: Float>(scene: &EnumScene<F>, summary: &mut Summary) {
    let mut bounds: Option<Aabb<f64>> = None;
    for o in scene.objects() {
        match &o.shape {
            ShapeKind::Sphere(_) => summary.spheres += 1,
            ShapeKind::Plane(_) => summary.planes += 1,
            ShapeKind::Triangle(_) => summary.triangles += 1,
            ShapeKind::Disk(_) => summary.disks += 1,
            ShapeKind::Mesh(m) => summary.triangles += m.parts() as usize,
            ShapeKind::Instance(i) => {
                summary.instances += 1;
                summary.triangles += i.prototype().triangles().len();
            }
        }
        if let Some(b) = o.shape.bounds() {
            let b = Aabb::new(b.min.cast::<f64>(), b.max.cast::<f64>());
            bounds = Some(bounds.map_or(b, |all| all.union(b)));
        }
    }
    summary.lights = scene.lights().len();
    // Asked of the material, not its kind: a normal map over an emitter still emits.
    let emits = |m: &MaterialKind<F>| m.emits().is_some();
    summary.emitters = scene
        .objects()
        .iter()
        .filter(|o| emits(scene.material(o.material)))
        .count();
    summary.sampled_emitters = scene.emitters().len();
    summary.bounds = bounds;
    summary.uses_bvh = scene.uses_bvh();
    summary.bvh_references = scene.bvh_references();
}
