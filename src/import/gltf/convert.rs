//! A glTF file's scene as a [`SceneFile`]: each node's mesh primitives as mesh objects
//! (held in memory, placed by the node's world map), a mesh several nodes place as
//! instances of one `[meshes]` entry where that renders the same, materials by
//! [`material`](super::material), the camera and lights by [`view`](super::view).

use super::container::Opened;
use super::geometry::{self, Read};
use super::images::{Derive, Images};
use super::nodes::{self, Placed, Rows};
use crate::aabb::Aabb;
use crate::error::{Error, Result};
use crate::import::Imported;
use crate::scene_file::{Assets, MaterialSpec, MeshDef, ObjectSpec, Scale, SceneFile, TextureRef};
use crate::transform::Affine;
use crate::vec3::Vec3;
use std::collections::{BTreeMap, BTreeSet};

/// Builds the scene file from an opened glTF file.
pub(super) struct Importer<'g> {
    pub(super) g: &'g Opened,
    pub(super) file: SceneFile,
    pub(super) assets: Assets,
    pub(super) images: Images<'g>,
    /// The glTF file's name, the start of every name held in memory.
    pub(super) file_name: String,
    pub(super) read: Vec<String>,
    pub(super) warnings: Vec<String>,
    /// Each glTF material's name in the scene file (`None`: the default material).
    pub(super) materials: BTreeMap<Option<usize>, String>,
    /// The materials that read no texture coordinates and give off no light: a mesh of
    /// one may be instanced.
    pub(super) plain_materials: BTreeSet<String>,
    /// Each primitive read, by mesh, primitive and whether wound the other way: its name
    /// in memory and whether its normals are its faces' (`None`: points or lines).
    primitives: BTreeMap<(usize, usize, bool), Option<(String, bool)>>,
    /// The box around every placed vertex, for a camera to frame.
    pub(super) bounds: Option<Aabb<f64>>,
    /// Whether any object gives off light.
    pub(super) emitters: bool,
    /// Triangles of meshes placed as objects of their own, counted toward
    /// [`MAX_COPIED_TRIANGLES`].
    copied: usize,
    /// The primitives shared because copies would pass the bound (warned about once).
    bounded: BTreeSet<(usize, usize, bool)>,
    /// Each primitive's box in its own space, for the bounds.
    boxes: BTreeMap<String, Aabb<f64>>,
}

/// The most triangles placed as mesh objects of their own (2²⁶, some 67 million, several
/// GiB once built): past it, a mesh placed by several nodes is shared as instances even
/// where that shades differently, with a warning.
pub const MAX_COPIED_TRIANGLES: usize = 1 << 26;

impl<'g> Importer<'g> {
    pub(super) fn new(g: &'g Opened) -> Self {
        let file_name = g
            .path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        Self {
            g,
            file: SceneFile::empty(&g.path),
            assets: Assets::default(),
            images: Images::new(g, file_name.clone()),
            file_name,
            read: Vec::new(),
            warnings: Vec::new(),
            materials: BTreeMap::new(),
            plain_materials: BTreeSet::new(),
            primitives: BTreeMap::new(),
            bounds: None,
            emitters: false,
            copied: 0,
            bounded: BTreeSet::new(),
            boxes: BTreeMap::new(),
        }
    }

    /// An error at `location` of the glTF file.
    pub(super) fn error(&self, location: impl Into<String>, message: impl Into<String>) -> Error {
        super::container::error(&self.g.path, location, message)
    }

    /// A warning about what `owner` (`materials[2]`, `nodes[0]`) renders differently.
    pub(super) fn warn(&mut self, owner: &str, what: String) {
        self.warnings.push(format!("{owner}: {what}"));
    }

    /// The texture of `info` as `derive` makes it, for the key `role` of `owner`.
    pub(super) fn texture(
        &mut self,
        info: &::gltf::texture::Info,
        derive: Derive,
        at: (&str, &str),
    ) -> Result<TextureRef> {
        let used = (&info.texture(), info.tex_coord(), info.texture_transform());
        self.images
            .texture(used, derive, at, &mut self.assets, &mut self.warnings)
    }

    /// Every node of the scene: its meshes, camera and light.
    pub(super) fn run(mut self) -> Result<Imported> {
        let doc = &self.g.doc;
        let (placed, chosen) = nodes::walk(doc).map_err(|(at, why)| self.error(at, why))?;
        self.read.push(format!("{chosen}: {} nodes", placed.len()));
        // How many nodes place each mesh, as it is or mirrored: one placed by several may
        // be instanced.
        let mut uses = BTreeMap::new();
        for p in &placed {
            if let Some(m) = doc.nodes().nth(p.node).and_then(|n| n.mesh()) {
                *uses
                    .entry((m.index(), nodes::determinant(&p.world) < 0.0))
                    .or_insert(0) += 1;
            }
        }
        let mut camera_set = false;
        for p in &placed {
            let Some(node) = doc.nodes().nth(p.node) else {
                continue;
            };
            let at = format!("nodes[{}]", p.node);
            if let Some(mesh) = node.mesh() {
                let shared = uses[&(mesh.index(), nodes::determinant(&p.world) < 0.0)];
                self.mesh(&node, &mesh, p, shared)?;
            }
            if node.skin().is_some() {
                self.warn(
                    &at,
                    "its skin is not applied: the mesh is rendered as its vertices lie".into(),
                );
            }
            if let Some(c) = node.camera()
                && !camera_set
            {
                camera_set = self.camera(&c, &at, &p.world)?;
            }
            if let Some(light) = node.light() {
                self.light(&light, &at, &p.world)?;
            }
        }
        if doc.animations().len() > 0 {
            let n = doc.animations().len();
            self.warnings.push(format!(
                "{n} animations are not played: the scene is rendered as the nodes stand"
            ));
        }
        if !camera_set {
            self.default_camera();
        }
        self.background();
        for s in &self.g.sources {
            self.assets.add_source(s);
        }
        let mut file = self.file;
        file.set_assets(self.assets);
        Ok(Imported {
            file,
            read: self.read,
            warnings: self.warnings,
        })
    }

    /// The primitives of `mesh`, placed by node `p`: an object each, or an instance of a
    /// shared mesh when the mesh is placed by several nodes and renders the same so (its
    /// material reads no texture and gives off no light, its normals are its faces').
    fn mesh(&mut self, node: &::gltf::Node, mesh: &::gltf::Mesh, p: &Placed, uses: usize) -> Result<()> {
        let at = format!("nodes[{}]", p.node);
        let Ok(map) = Affine::from_rows(p.world) else {
            self.warn(
                &at,
                "its map to the world flattens space (a scale of 0) or is not finite: its mesh is left out"
                    .into(),
            );
            return Ok(());
        };
        let mirrored = nodes::determinant(&p.world) < 0.0;
        let morphs = node
            .weights()
            .or(mesh.weights())
            .is_some_and(|w| w.iter().any(|&x| x != 0.0));
        if morphs {
            self.warn(
                &at,
                "its morph targets are not applied: the mesh is rendered at its base shape".into(),
            );
        }
        let mut how = Vec::new();
        for primitive in mesh.primitives() {
            let key = (mesh.index(), primitive.index(), mirrored);
            let Some((name, flat)) = self.primitive(mesh, &primitive, mirrored)? else {
                continue;
            };
            let material = self.material(&primitive.material())?;
            if self.assets.mesh(&name).is_some_and(|m| !m.triangles.is_empty()) {
                self.grow_bounds(&name, &p.world);
            }
            let lossless = flat && self.plain_materials.contains(&material);
            let triangles = self.assets.mesh(&name).map_or(0, |m| m.triangles.len());
            // Copies past the bound are shared anyway: a file of a few bytes may place a
            // large mesh a hundred thousand times.
            let over = uses > 1 && !lossless && self.copied + triangles > MAX_COPIED_TRIANGLES;
            if over && !self.bounded.contains(&key) {
                self.bounded.insert(key);
                self.warn(
                    &format!("meshes[{}].primitives[{}]", key.0, key.1),
                    format!(
                        "placed {uses} times, past {MAX_COPIED_TRIANGLES} copied triangles: shared as instances, \
                         which shade with their faces' normals, read no texture coordinates and are not \
                         sampled as lights"
                    ),
                );
            }
            let shared = uses > 1 && (lossless || over);
            if !shared {
                self.copied += triangles;
            }
            let matrix = (p.world != nodes::IDENTITY).then_some(p.world);
            let object = if shared {
                self.file
                    .meshes
                    .entry(name.clone())
                    .or_insert(MeshDef { file: name.clone() });
                ObjectSpec::Instance {
                    mesh: name,
                    scale: Scale::default(),
                    rotate: [0.0; 3],
                    translate: [0.0; 3],
                    matrix: Some(map.rows()),
                    material,
                }
            } else {
                if let Some(MaterialSpec::Emissive { .. }) = self.file.materials.get(&material) {
                    self.emitters = true;
                }
                ObjectSpec::Mesh {
                    file: name,
                    scale: Scale::default(),
                    rotate: [0.0; 3],
                    translate: [0.0; 3],
                    material,
                    face_normals: false,
                    flip_tex_coords: Some(false),
                    matrix,
                }
            };
            how.push(format!(
                "primitives[{}] {}",
                key.1,
                if shared { "as an instance" } else { "as a mesh" }
            ));
            self.file.objects.push(object);
        }
        let name = node.name().map(|n| format!(" '{n}'")).unwrap_or_default();
        let side = if mirrored {
            ", mirrored (faces wound the other way)"
        } else {
            ""
        };
        self.read.push(format!(
            "{at}{name}: meshes[{}]: {}{side}",
            mesh.index(),
            if how.is_empty() {
                "nothing with area".to_string()
            } else {
                how.join(", ")
            }
        ));
        Ok(())
    }

    /// Primitive `primitive` of `mesh` held in memory (wound the other way if `mirrored`):
    /// its name and whether its normals are its faces'; `None` for points and lines.
    fn primitive(
        &mut self,
        mesh: &::gltf::Mesh,
        primitive: &::gltf::Primitive,
        mirrored: bool,
    ) -> Result<Option<(String, bool)>> {
        let key = (mesh.index(), primitive.index(), mirrored);
        if let Some(known) = self.primitives.get(&key) {
            return Ok(known.clone());
        }
        let at = format!("meshes[{}].primitives[{}]", key.0, key.1);
        let made =
            match geometry::read(primitive, &self.g.buffers, mirrored).map_err(|why| self.error(&at, why))? {
                Read::NoArea(mode) => {
                    self.warn(&at, format!("mode {mode} has no area: left out"));
                    None
                }
                Read::Mesh(data) => {
                    let name = format!(
                        "{}#{at}{}",
                        self.file_name,
                        if mirrored { "/mirrored" } else { "" }
                    );
                    let flat = geometry::normals_are_flat(&data);
                    let attributes = [("normals", data.normals.is_some()), ("uv", data.uvs.is_some())]
                        .iter()
                        .filter(|(_, has)| *has)
                        .map(|(n, _)| *n)
                        .collect::<Vec<_>>()
                        .join(", ");
                    self.read.push(format!(
                        "{at}: {} vertices, {} triangles{}{}",
                        data.positions.len(),
                        data.triangles.len(),
                        if attributes.is_empty() {
                            String::new()
                        } else {
                            format!(", {attributes}")
                        },
                        match data.skipped_degenerate {
                            0 => String::new(),
                            n => format!(" ({n} without area skipped)"),
                        }
                    ));
                    if primitive.morph_targets().len() > 0 && !mirrored {
                        self.read.push(format!(
                            "{at}: {} morph targets, not applied",
                            primitive.morph_targets().len()
                        ));
                    }
                    self.assets.insert_mesh(name.clone(), data);
                    Some((name, flat))
                }
            };
        self.primitives.insert(key, made.clone());
        Ok(made)
    }

    /// Grows the bounds by the corners of the box around the mesh held as `name`, placed
    /// by `world` (the box is made once per mesh: a mesh placed many times costs eight
    /// points a placement).
    fn grow_bounds(&mut self, name: &str, world: &Rows) {
        if !self.boxes.contains_key(name) {
            let Some(mesh) = self.assets.mesh(name) else {
                return;
            };
            let b = mesh
                .positions
                .iter()
                .fold(Aabb::empty(), |b, &p| b.union(Aabb::new(p, p)));
            self.boxes.insert(name.to_string(), b);
        }
        let b = self.boxes[name];
        let mut all = self.bounds.unwrap_or_else(Aabb::empty);
        for k in 0..8 {
            let pick = |bit: usize, lo: f64, hi: f64| if k >> bit & 1 == 0 { lo } else { hi };
            let c = [
                pick(0, b.min.x, b.max.x),
                pick(1, b.min.y, b.max.y),
                pick(2, b.min.z, b.max.z),
            ];
            let q = world.map(|r| r[0] * c[0] + r[1] * c[1] + r[2] * c[2] + r[3]);
            let q = Vec3::new(q[0], q[1], q[2]);
            all = all.union(Aabb::new(q, q));
        }
        self.bounds = Some(all);
    }
}
