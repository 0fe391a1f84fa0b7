//! Scenes made elsewhere: Mitsuba 3's XML scene format and glTF 2.0 ([`gltf()`]) read
//! into a [`SceneFile`], so that everything a scene file gets (checked values, errors at
//! their place, tiles, precision advice) holds for them too.
//!
//! Read (scene versions 2 and 3, and 0.x upgraded as Mitsuba 3 upgrades it: `upgrade.rs`):
//! `<default>` and `$name` (and `-D name=value`), `<include>`, `<path>`, `id` and `<ref>`
//! (to a plugin defined before or after it); transforms (`lookat`, `translate`, `rotate`,
//! `scale`, `matrix`); shapes `obj`, `ply`, `sphere`, `disk`, `rectangle`, `cube`,
//! `shapegroup` (of those) and `instance`; every BSDF this renderer has (`diffuse`,
//! `conductor`, `roughconductor`, `dielectric`, `roughdielectric`, `thindielectric`,
//! `plastic`, `roughplastic`, `twosided`, `normalmap`); textures `bitmap` and
//! `checkerboard`; emitters `area` (on a shape, or declared apart and referred to),
//! `point`, `constant`, `envmap`, `directional`, `spot`; sensors `perspective` and
//! `thinlens` (`fov`, `fov_axis`); `hdrfilm`, the `independent` sampler and the `path`,
//! `direct` (as `path` of depth 2) and `moment` (as the integrator it holds) integrators.
//! A mesh whose file has no normals gets Mitsuba's smooth ones (`smooth.rs`); a `diffuse`
//! is one-sided, as Mitsuba's (black behind). Anything else is an error naming the plugin,
//! its file and line; what is rendered with a difference (another reconstruction filter,
//! an unbounded depth) is a warning naming it, and so is a parameter of a plugin read that
//! nothing reads (unknown, or misspelt): the render is as if it were absent.
//!
//! Mitsuba counts path segments in `max_depth`, this renderer bounces: a scene lit only by
//! point-like lights and a non-emitting background renders with one bounce fewer, one with
//! an area light or an environment emitter with the same number (the renderer's rule for
//! such scenes is Mitsuba's).
//!
//! A transform that says what a scene file says (a mesh's scale, turns about x, y, z and
//! translation; a sensor's lone `lookat`) is read as the scene file's keys, rounded alike;
//! a few `raytrace_` extensions say what Mitsuba cannot (the spec's screen camera, the sky,
//! planes, lone triangles, the mirror, Schlick's Fresnel, precision, exposure, tone curve).
//! So every scene file has an XML twin that renders its bytes (`scenes/*.xml`; the
//! extensions and the twins in `docs/SCENE_FORMAT.md`).

mod bsdf;
mod convert;
mod exact;
mod extension;
pub mod gltf;
mod integrator;
mod sensor;
mod shading;
mod shape;
mod smooth;
mod transform;
mod upgrade;
pub mod xml;

pub use convert::Imported;

use crate::error::Result;
use crate::scene_file::SceneFile;
use std::collections::BTreeMap;
use std::path::Path;

/// The Mitsuba 3 XML scene at `path` as a scene file, with `defines` (`-D name=value`)
/// overriding its `<default>`s.
///
/// # Errors
/// [`Error::SceneFile`](crate::Error::SceneFile) naming the file and line of malformed XML,
/// a plugin or a parameter this importer does not read, or a value of the wrong type.
pub fn mitsuba(path: &Path, defines: &BTreeMap<String, String>) -> Result<Imported> {
    let document = xml::read(path, defines)?;
    let mut importer = convert::Importer::new(SceneFile::empty(path), document.folders);
    importer.render_defaults(&document.defines, path)?;
    importer.run(&document.plugins)
}

/// The glTF 2.0 file at `path` (`.gltf` JSON or `.glb` binary, told apart by its first
/// bytes) as a scene file, its meshes and images held in memory
/// ([`SceneFile::assets`]); [`Imported::read`] lists what was read, and
/// [`Imported::warnings`] what renders differently from the file (an extension not read,
/// a material property averaged, alpha). `docs/SCENE_FORMAT.md` states the mapping.
///
/// # Errors
/// [`Error::SceneFile`](crate::Error::SceneFile) naming the file and the JSON path
/// (`meshes[0].primitives[1].attributes.POSITION`), or the line and column of malformed
/// JSON: a truncated or malformed file, an index or accessor out of range, a buffer
/// shorter than it declares, a missing buffer or image file, a required extension not
/// read. [`Error::Image`](crate::Error::Image) for an image that cannot be decoded.
pub fn gltf(path: &Path) -> Result<Imported> {
    gltf::import(path)
}

/// Whether `path` names a glTF file (by its extension, `.gltf` or `.glb`).
pub fn is_gltf(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

/// Whether `path` names a Mitsuba XML scene (by its extension, `.xml`).
pub fn is_mitsuba(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}
