//! This renderer's extensions of Mitsuba 3's format: what a TOML scene file can say and
//! Mitsuba cannot, so that every scene file has an XML twin that renders the same bytes.
//! Each name starts with `raytrace_`, which no Mitsuba plugin or parameter does, and each
//! takes the scene file's own keys:
//!
//! - `<sensor type="raytrace_screen">` (`eye`): the specification's camera;
//! - `<emitter type="raytrace_sky">` (`horizon`, `zenith`, `light`): the sky gradient;
//! - `<shape type="raytrace_plane">` (`point`, `normal`) and `<shape
//!   type="raytrace_triangle">` (`a`, `b`, `c`): the infinite plane and the lone triangle;
//! - `<bsdf type="raytrace_mirror">` (`albedo`): the specification's mirror;
//! - `<string name="raytrace_fresnel" value="schlick"/>` in a `dielectric`: Schlick's
//!   reflectance instead of the exact one;
//! - `<default name="raytrace_precision">`, `raytrace_exposure`, `raytrace_tonemap`: the
//!   `[render]` keys Mitsuba has no place for. Mitsuba ignores a `<default>` no `$name`
//!   uses, so a scene that needs only these still loads in Mitsuba; `-D` sets them too.
//!
//! (The sensor is in `sensor.rs`, with the others.)

use super::convert::Importer;
use super::xml::Plugin;
use crate::error::{Error, Result};
use crate::image::ToneCurve;
use crate::scene_file::{BackgroundSpec, FilePrecision, FresnelSpec, MaterialSpec, ObjectSpec};
use std::collections::BTreeMap;
use std::path::Path;

impl Importer {
    /// `<emitter type="raytrace_sky">`: the `sky` background; as a light (`light`), it
    /// counts `max_depth` as an environment emitter does.
    pub(super) fn sky(&mut self, e: &Plugin) -> Result<()> {
        let light = self.boolean(e, "light")?.unwrap_or(false);
        self.lights_on_surfaces |= light;
        // The scene file's defaults: white below, sky blue above.
        self.file.background = BackgroundSpec::Sky {
            horizon: self.triple(e, "horizon")?.unwrap_or([1.0; 3]),
            zenith: self.triple(e, "zenith")?.unwrap_or([0.5, 0.7, 1.0]),
            light,
        };
        Ok(())
    }

    /// `<shape type="raytrace_plane">` and `<shape type="raytrace_triangle">`, placed by
    /// their points as written (not by a `to_world`).
    pub(super) fn flat_shape(&mut self, s: &Plugin, material: String) -> Result<()> {
        if self.property(s, "to_world").is_some() {
            return Err(s.at.error(format!(
                "{}: is placed by its points, not by a `to_world`",
                s.label()
            )));
        }
        let point = |me: &Self, name: &str| {
            me.triple(s, name)?
                .ok_or_else(|| s.at.error(format!("{}: needs `{name}`", s.label())))
        };
        let object = if s.kind == "raytrace_plane" {
            ObjectSpec::Plane {
                point: point(self, "point")?,
                normal: point(self, "normal")?,
                material,
            }
        } else {
            ObjectSpec::Triangle {
                a: point(self, "a")?,
                b: point(self, "b")?,
                c: point(self, "c")?,
                material,
            }
        };
        self.file.objects.push(object);
        Ok(())
    }

    /// `<bsdf type="raytrace_mirror">`: the specification's mirror, `albedo` (default
    /// white).
    pub(super) fn mirror(&self, b: &Plugin) -> Result<MaterialSpec> {
        Ok(MaterialSpec::Mirror {
            albedo: self.triple(b, "albedo")?.unwrap_or([1.0; 3]),
        })
    }

    /// A `dielectric`'s `raytrace_fresnel`: `exact` (Mitsuba's, the default) or `schlick`.
    pub(super) fn fresnel(&self, b: &Plugin) -> Result<FresnelSpec> {
        match self.text(b, "raytrace_fresnel")?.as_deref() {
            None | Some("exact") => Ok(FresnelSpec::Exact),
            Some("schlick") => Ok(FresnelSpec::Schlick),
            Some(other) => Err(b.at.error(format!(
                "{}: raytrace_fresnel `{other}` is neither exact nor schlick",
                b.label()
            ))),
        }
    }

    /// The `[render]` keys set by `raytrace_precision`, `raytrace_exposure` and
    /// `raytrace_tonemap` among the scene's `<default>`s and `-D` values.
    pub(super) fn render_defaults(&mut self, defines: &BTreeMap<String, String>, file: &Path) -> Result<()> {
        let bad = |name: &str, value: &str, want: &str| Error::SceneFile {
            path: file.to_path_buf(),
            location: format!("<default name=\"{name}\"> (or -D {name}=…)"),
            message: format!("`{value}` is not {want}"),
            field: None,
            line: None,
        };
        let render = &mut self.file.render;
        if let Some(v) = defines.get("raytrace_precision") {
            render.precision = match v.as_str() {
                "f32" => FilePrecision::F32,
                "f64" => FilePrecision::F64,
                "auto" => FilePrecision::Auto,
                _ => return Err(bad("raytrace_precision", v, "f32, f64 or auto")),
            };
        }
        if let Some(v) = defines.get("raytrace_exposure") {
            render.exposure = v
                .trim()
                .parse()
                .map_err(|_| bad("raytrace_exposure", v, "a number of stops"))?;
        }
        if let Some(v) = defines.get("raytrace_tonemap") {
            render.tonemap = match v.as_str() {
                "none" => ToneCurve::None,
                "aces" => ToneCurve::Aces,
                _ => return Err(bad("raytrace_tonemap", v, "none or aces")),
            };
        }
        Ok(())
    }
}
