//! Scenes from TOML files: the format `docs/SCENE_FORMAT.md` describes.
//!
//! [`SceneFile::load`] reads and parses a file (syntax and types, reported at a line and
//! column); [`SceneFile::build`] checks every value (reported at a field path such as
//! `objects[3].radius`), loads the meshes and builds the scene, camera and settings in
//! the scalar asked for.
//!
//! ```
//! use raytrace::scene_file::SceneFile;
//! use std::path::Path;
//!
//! let text = r#"
//!     [render]
//!     width = 40
//!
//!     [materials.gold]
//!     type = "mirror"
//!     albedo = [0.95, 0.78, 0.35]
//!
//!     [[objects]]
//!     type = "sphere"
//!     center = [0.0, 0.0, -3.0]
//!     radius = 1.0
//!     material = "gold"
//! "#;
//! let file = SceneFile::parse(text, Path::new("inline.toml"))?;
//! let built = file.build::<f64>()?;
//! assert_eq!(built.summary.spheres, 1);
//! let image = raytrace::render(&built.scene, &built.camera, &built.settings)?.image;
//! assert_eq!((image.width(), image.height()), (40, 20));
//! # Ok::<(), raytrace::Error>(())
//! ```

mod assets;
mod bsdf;
mod build;
mod camera;
mod check;
mod disk;
mod integer;
mod light;
mod location;
mod make;
mod make_bsdf;
mod model;
mod mtl_spec;
mod obj_materials;
mod objects;
mod placing;
mod resolve;
mod summary;
mod texture_spec;
mod transform;
mod triple;
mod warnings;

pub use assets::Assets;
pub use bsdf::{
    ConductorSpec, DistributionSpec, IorSpec, PlasticSpec, RoughConductorSpec, RoughDielectricSpec,
    RoughPlasticSpec, RoughnessSpec, ThinDielectricSpec, TwoSidedSpec,
};
pub use build::Built;
pub use camera::FileCamera;
pub use light::LightSpec;
pub use model::{
    BackgroundSpec, CameraSpec, FilePrecision, FresnelSpec, MaterialSpec, RenderOptions, Triple,
};
pub use obj_materials::FROM_MTL;
pub use objects::{MeshDef, ObjectSpec, Scale};
pub use summary::Summary;
pub use texture_spec::{ScalarRef, TextureRef, TextureSpec, UvScale, WrapSpec};
pub use transform::Placement;
pub use warnings::Warning;

use crate::advice::{Advice, Reason, advise};
use crate::error::{Error, Result};
use crate::float::Float;
use crate::image::Tonemap;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A scene file as parsed: every section, with the defaults filled in.
///
/// The fields are the file's sections; [`SceneFile::build`] checks their values.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SceneFile {
    /// `[render]`: image width, samples, depth, seed, precision, acceleration.
    pub render: RenderOptions,
    /// `[camera]`.
    pub camera: CameraSpec,
    /// `[background]`.
    pub background: BackgroundSpec,
    /// `[textures.NAME]`: the textures colour keys may refer to by name.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub textures: BTreeMap<String, TextureSpec>,
    /// `[meshes.NAME]`: meshes read once, placed by `type = "instance"` objects.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub meshes: BTreeMap<String, MeshDef>,
    /// `[materials.NAME]`: the materials objects refer to by name.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub materials: BTreeMap<String, MaterialSpec>,
    /// `[[objects]]`, in the order they are added to the scene.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub objects: Vec<ObjectSpec>,
    /// `[[lights]]`: point, spot and directional lights.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub lights: Vec<LightSpec>,
    /// Where the file is: for messages and for mesh paths relative to its folder.
    #[serde(skip)]
    path: PathBuf,
    /// The text it was parsed from, to tell where a value refused later is written.
    #[serde(skip)]
    source: location::Source,
    /// Meshes and images an importer holds in memory, which `file` keys may name.
    #[serde(skip)]
    assets: std::sync::Arc<Assets>,
}

impl SceneFile {
    /// The widest image [`advise_precision`] renders: its reference render is slow.
    pub const ADVICE_WIDTH: usize = 160;
    /// The most samples per pixel [`advise_precision`] renders.
    pub const ADVICE_SPP: u32 = 4;

    /// The largest scene file read, in bytes (64 MiB: some hundred thousand objects; large
    /// geometry belongs in mesh files).
    pub const MAX_BYTES: u64 = 64 << 20;

    /// Reads and parses the scene file at `path`: at most [`SceneFile::MAX_BYTES`] of UTF-8
    /// text (a pipe such as `<(…)` too, so a link to `/dev/zero` stops at the bound).
    ///
    /// # Errors
    /// [`Error::Io`] if it cannot be read; [`Error::SceneFile`] for a file past the bound,
    /// one that is not UTF-8 (at the line and column of the first byte that is not), or as
    /// [`SceneFile::parse`].
    pub fn load(path: &Path) -> Result<SceneFile> {
        use std::io::Read;
        let io = |source| Error::Io {
            path: path.to_path_buf(),
            source,
        };
        let mut bytes = Vec::new();
        std::fs::File::open(path)
            .and_then(|f| f.take(Self::MAX_BYTES + 1).read_to_end(&mut bytes))
            .map_err(io)?;
        let whole = |message: String| Error::SceneFile {
            path: path.to_path_buf(),
            location: "the whole file".into(),
            message,
            field: None,
            line: None,
        };
        if bytes.len() as u64 > Self::MAX_BYTES {
            return Err(whole(format!(
                "longer than {} bytes ({} MiB), the most a scene file may have",
                Self::MAX_BYTES,
                Self::MAX_BYTES >> 20
            )));
        }
        let text = String::from_utf8(bytes).map_err(|e| {
            let good = e.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(&e.as_bytes()[..good]);
            let (line, column) = location::line_column(&text, good);
            Error::SceneFile {
                path: path.to_path_buf(),
                location: format!("line {line}, column {column}"),
                message: "not UTF-8 text: a scene file is TOML".into(),
                field: None,
                line: None,
            }
        })?;
        Self::parse(&text, path)
    }

    /// A file at `path` with nothing in it: every section at its default, no objects, to
    /// be filled in by an importer ([`crate::import`]). Paths in it are relative to
    /// `path`'s folder.
    pub fn empty(path: &Path) -> SceneFile {
        SceneFile {
            path: path.to_path_buf(),
            ..SceneFile::default()
        }
    }

    /// Parses `text`; `path` names the file in messages and is the base of relative mesh
    /// paths. Only the syntax and the types are checked here, the values by
    /// [`SceneFile::build`].
    ///
    /// # Errors
    /// [`Error::SceneFile`] at `line L, column C` for malformed TOML, an unknown key, a
    /// missing key or a value of the wrong type.
    pub fn parse(text: &str, path: &Path) -> Result<SceneFile> {
        let mut file: SceneFile = location::read(path, text)?;
        file.path = path.to_path_buf();
        file.source = location::Source::new(text);
        Ok(file)
    }

    /// The file as TOML, which [`SceneFile::parse`] reads back to an equal `SceneFile`
    /// (every `f64` is written in the shortest form that rounds back to it).
    ///
    /// # Panics
    /// Never: every value of the model has a TOML form (integers past `i64::MAX` are
    /// written as strings).
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("every scene file value has a TOML form")
    }

    /// The file's path, as given to [`SceneFile::load`] or [`SceneFile::parse`].
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The meshes and images an importer holds in memory for the file's `file` keys (none
    /// for a file parsed from TOML).
    pub fn assets(&self) -> &Assets {
        &self.assets
    }

    /// Sets the meshes and images held in memory: a `file` key naming one of them is not
    /// read from disk, and the files they came from count among [`SceneFile::input_files`].
    pub fn set_assets(&mut self, assets: Assets) {
        self.assets = std::sync::Arc::new(assets);
    }

    /// The other files the scene is made from, as [`SceneFile::build`] finds them
    /// (relative to the scene file's folder): the environment map's, each mesh's in the
    /// order of `[[objects]]`, the `[meshes]` entries' by name, then for each mesh object with
    /// `material = "mtl"` its `.mtl` libraries and their images that exist, then the
    /// textures' [images](Self::image_files), then the files the [assets](Self::assets)
    /// held in memory were read from (a name held in memory is not a file).
    pub fn input_files(&self) -> Vec<PathBuf> {
        let folder = self.path.parent().unwrap_or(Path::new(""));
        let map = match &self.background {
            BackgroundSpec::Envmap { file, .. } => Some(folder.join(file)),
            _ => None,
        };
        let meshes = self.objects.iter().filter_map(|o| match o {
            ObjectSpec::Mesh { file, .. } => Some(file),
            _ => None,
        });
        let shared = self.meshes.values().map(|m| &m.file);
        let on_disk = meshes
            .chain(shared)
            .filter(|f| !self.assets.holds(f))
            .map(|f| folder.join(f));
        let materials = self.objects.iter().flat_map(|o| match o {
            ObjectSpec::Mesh { file, .. } if obj_materials::wants_mtl(o) => {
                crate::mesh::material_files(&folder.join(file))
            }
            _ => Vec::new(),
        });
        map.into_iter()
            .chain(on_disk)
            .chain(materials)
            .chain(self.image_files())
            .chain(self.assets.sources().iter().cloned())
            .collect()
    }

    /// The image files the scene's textures read, as [`SceneFile::build`] finds them
    /// (relative to the scene file's folder): those of `[textures]` in the order of their
    /// names, then those written in place in `[materials]`, each once (not the images
    /// held in memory).
    pub fn image_files(&self) -> Vec<PathBuf> {
        let folder = self.path.parent().unwrap_or(Path::new(""));
        let inline = self
            .materials
            .values()
            .flat_map(|m| m.textures())
            .filter_map(|t| match t {
                TextureRef::Inline(spec) => Some(spec.as_ref()),
                _ => None,
            });
        let mut files: Vec<PathBuf> = Vec::new();
        for spec in self.textures.values().chain(inline) {
            if let TextureSpec::Image { file, .. } = spec {
                if self.assets.holds(file) {
                    continue;
                }
                let path = folder.join(file);
                if !files.contains(&path) {
                    files.push(path);
                }
            }
        }
        files
    }

    /// The top of the file, where a value's error is reported from.
    fn root(&self) -> location::KeyPath<'_> {
        location::KeyPath::root(&self.path).in_text(self.source.text())
    }

    /// The `[render]` options.
    pub fn render(&self) -> &RenderOptions {
        &self.render
    }

    /// The `[render]` options, to override from a command line before [`SceneFile::build`].
    pub fn render_mut(&mut self) -> &mut RenderOptions {
        &mut self.render
    }

    /// The display formats' exposure and tone curve, `[render] exposure` and `tonemap`
    /// (the float formats stay linear).
    ///
    /// # Errors
    /// [`Error::SceneFile`] at `render.exposure` for an exposure outside
    /// [`Tonemap::new`]'s range.
    pub fn tonemap(&self) -> Result<Tonemap> {
        let root = self.root();
        Tonemap::new(self.render.exposure, self.render.tonemap)
            .map_err(|e| check::blame(&root, &root.key("render"), e))
    }

    /// Checks every value, loads the meshes and builds the scene, the camera and the
    /// settings in scalar `F`. `[render] precision` is not read here: the caller chooses
    /// `F` (for `"auto"`, by [`advise_precision`]).
    ///
    /// # Errors
    /// [`Error::SceneFile`] at the field's path (`objects[3].radius`,
    /// `materials.gold.albedo`, `render.width`) for a value outside its domain, a material
    /// name no `[materials]` entry defines, a mesh that cannot be loaded (its error kept in
    /// the message) or a value that does not survive rounding to `F`.
    pub fn build<F: Float>(&self) -> Result<Built<F>> {
        build::build(self)
    }

    /// What the file alone shows its author probably did not mean:
    /// [`Warning::NoObjects`], [`Warning::NoLight`].
    pub fn warnings(&self) -> Vec<Warning> {
        warnings::static_warnings(self)
    }

    /// For each mesh object whose one `material` covers an OBJ file that names materials
    /// with `usemtl`: a note naming the object, the file and the names, which are not used
    /// (`material = "mtl"`, [`FROM_MTL`], takes them). Reads those OBJ files' text.
    pub fn unused_obj_materials(&self) -> Vec<String> {
        obj_materials::unused_usemtl(self)
    }

    /// [`Warning::DarkPreview`] if a small render of `built` (this file's scene) is black
    /// although something gives off light ([`SceneFile::warnings`] says when nothing does).
    ///
    /// # Errors
    /// If the preview cannot be rendered (its camera refuses the file's values).
    pub fn preview_warning<F: Float>(&self, built: &Built<F>) -> Result<Option<Warning>> {
        if self.warnings().contains(&Warning::NoLight) {
            return Ok(None);
        }
        Ok(warnings::dark_preview(self, built)?.then_some(Warning::DarkPreview))
    }
}

/// The scalar `[render] precision = "auto"` resolves to: [`advise`] on the scene built in
/// `f64`, rendered at most [`SceneFile::ADVICE_WIDTH`] pixels wide with at most
/// [`SceneFile::ADVICE_SPP`] samples per pixel (the reference render is about ten times
/// slower than `f64`), with the file's depth and seed. `Advice::recommended` is the answer.
///
/// A scene only `f64` can hold (a radius of `1e-60`) is advised `f64`, and
/// [`Reason::F32CannotHold`] names the file, the
/// key and the value that `f32` loses.
///
/// # Errors
/// As [`SceneFile::build`] in `f64`.
pub fn advise_precision(file: &SceneFile) -> Result<Advice> {
    let mut small = file.clone();
    let render = small.render_mut();
    render.width = render.width.min(SceneFile::ADVICE_WIDTH);
    render.spp = render.spp.min(SceneFile::ADVICE_SPP);
    let built = small.build::<f64>()?;
    let mut advice = advise(&built.scene, &built.camera, &built.settings)?;
    if let Reason::F32CannotHold(why) = &mut advice.reason
        && let Err(e) = small.build::<f32>()
    {
        // The file's own error names the key; the scene's cast could only name the value.
        *why = e.to_string();
    }
    Ok(advice)
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod field_tests;
