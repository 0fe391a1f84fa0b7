//! Scenes made elsewhere: Mitsuba 3's XML scene format read into a [`SceneFile`], so
//! that everything a scene file gets (checked values, errors at their place, tiles,
//! precision advice) holds for it too.
//!
//! Read: `<default>` and `$name` (and `-D name=value`), `<include>`, `<path>`, `id` and
//! `<ref>`; transforms (`lookat`, `translate`, `rotate`, `scale`, `matrix`); shapes `obj`,
//! `ply`, `sphere`, `disk`, `rectangle`, `cube`, `shapegroup` (of `obj` and `ply`) and `instance`;
//! every BSDF this renderer has (`diffuse`,
//! `conductor`, `roughconductor`, `dielectric`, `roughdielectric`, `thindielectric`,
//! `plastic`, `roughplastic`, `twosided`, `normalmap`); textures `bitmap` and
//! `checkerboard`; emitters `area`, `point`, `constant`, `envmap`, `directional`, `spot`;
//! sensors `perspective` and `thinlens` (`fov`, `fov_axis`); `hdrfilm`, the `independent`
//! sampler and the `path` integrator. Anything else is an error naming the plugin, its
//! file and line; what is rendered with a difference (another reconstruction filter, an
//! unbounded depth) is a warning naming it.
//!
//! Mitsuba counts path segments in `max_depth`, this renderer bounces: a scene lit only by
//! point-like lights and a non-emitting background renders with one bounce fewer, one with
//! an area light or an environment emitter with the same number (the renderer's rule for
//! such scenes is Mitsuba's).

mod bsdf;
mod convert;
mod shape;
mod transform;
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
    let (plugins, folders) = xml::read(path, defines)?;
    convert::Importer::new(SceneFile::empty(path), folders).run(&plugins)
}

/// Whether `path` names a Mitsuba XML scene (by its extension, `.xml`).
pub fn is_mitsuba(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}
