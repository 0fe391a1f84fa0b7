//! A Mitsuba 3 scene's plugins as a [`SceneFile`]: sensors, film, sampler and integrator
//! as `[render]` and `[camera]`, shapes as objects, emitters as lights and backgrounds.
//! What has no counterpart is an error naming the plugin, its file and line; what is read
//! with a difference (another reconstruction filter) is a warning naming it.

use super::xml::{Plugin, Value};
use crate::error::{Error, Result};

use crate::scene_file::{Assets, BackgroundSpec, LightSpec, SceneFile};
use crate::transform::Affine;
use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;
use std::rc::Rc;

/// What an import gives: the scene, what it read and how it differs.
#[derive(Debug)]
pub struct Imported {
    /// The scene, ready for [`SceneFile::build`].
    pub file: SceneFile,
    /// Every plugin read, as `<shape type="obj"> (scene.xml, line 12)`.
    pub read: Vec<String>,
    /// Where the render differs from Mitsuba's, each naming the plugin, file and line.
    pub warnings: Vec<String>,
}

/// The properties asked for, as `(file, line, name)`.
#[derive(Clone, Default)]
pub(super) struct Asked(Rc<RefCell<BTreeSet<(PathBuf, u32, String)>>>);

impl Asked {
    /// The property `name` of `p`, noted as asked for.
    pub(super) fn property<'p>(&self, p: &'p Plugin, name: &str) -> Option<&'p super::xml::Property> {
        let q = p.properties.get(name)?;
        let key = (q.at.file.clone(), q.at.line, name.to_string());
        self.0.borrow_mut().insert(key);
        Some(q)
    }
}

/// Builds the scene file from the plugins.
pub(super) struct Importer {
    pub(super) file: SceneFile,
    folders: Vec<PathBuf>,
    read: Vec<String>,
    warnings: Vec<String>,
    /// Every property of a plugin read, as `(file, line, name)`, with its plugin's label: what
    /// [`Importer::property`] never asks for is reported, so nothing is left out unsaid.
    offered: Vec<((PathBuf, u32, String), String)>,
    /// The properties asked for (shared with closures that read a plugin's properties
    /// while the importer is borrowed mutably).
    pub(super) asked: Asked,
    /// Set by an area emitter, the sampled environment: Mitsuba's `max_depth` then counts
    /// as the renderer's does.
    pub(super) lights_on_surfaces: bool,
    /// Each `shapegroup` by id: its shapes, each placed by every instance of the group.
    pub(super) groups: BTreeMap<String, Vec<super::shape::Part>>,
    /// Meshes held in memory: those given Mitsuba's smooth normals (`smooth.rs`).
    pub(super) assets: Assets,
    /// How many meshes were smoothed: each gets its own name.
    pub(super) smoothed: usize,
}

impl Importer {
    pub(super) fn new(file: SceneFile, folders: Vec<PathBuf>) -> Self {
        Self {
            file,
            folders,
            read: Vec::new(),
            warnings: Vec::new(),
            offered: Vec::new(),
            asked: Asked::default(),
            lights_on_surfaces: false,
            groups: BTreeMap::new(),
            assets: Assets::default(),
            smoothed: 0,
        }
    }

    /// Every top-level plugin converted, and the render options set.
    pub(super) fn run(mut self, plugins: &[Plugin]) -> Result<Imported> {
        // Mitsuba's scene without an emitter at infinity is black beyond the objects.
        self.file.background = BackgroundSpec::Solid {
            color: [0.0; 3],
            light: false,
        };
        let mut max_depth = None;
        for p in plugins {
            match p.tag.as_str() {
                "sensor" => self.sensor(p)?,
                "shape" => self.shape(p)?,
                // Made where a shape refers to it by its id, as Mitsuba makes it.
                "emitter" if p.kind == "area" && p.id.is_some() => {}
                "emitter" => self.emitter(p)?,
                "bsdf" => {
                    self.named_material(p)?;
                }
                "texture" => {
                    self.read(p);
                }
                "integrator" => max_depth = self.integrator(p)?,
                _ => return Err(self.unsupported(p, &p.kind)),
            }
        }
        // Mitsuba counts path segments; a path here takes `max_depth` bounces, one segment
        // more, unless a light sits on a surface or is the sampled environment.
        let depth = max_depth.unwrap_or(-1.0);
        self.file.render.max_depth = if depth < 0.0 {
            self.warnings
                .push("the path integrator's max_depth is unbounded (-1): rendered with 64".into());
            64
        } else if self.lights_on_surfaces {
            depth as u32
        } else {
            (depth as u32).saturating_sub(1)
        };
        let lit_background = match self.file.background {
            BackgroundSpec::Solid { light, .. } | BackgroundSpec::Sky { light, .. } => light,
            BackgroundSpec::Envmap { .. } => true,
        };
        if self.lights_on_surfaces && !lit_background && !self.file.lights.is_empty() {
            // A point-like light's shadow ray is one segment more than the bounces here.
            self.warnings.push(
                "point, spot and directional lights beside area emitters, with no emitter at infinity: \
                 here they light paths of up to max_depth + 1 segments, in Mitsuba max_depth"
                    .into(),
            );
        }
        self.unread();
        self.file.set_assets(std::mem::take(&mut self.assets));
        Ok(Imported {
            file: self.file,
            read: self.read,
            warnings: self.warnings,
        })
    }

    pub(super) fn read(&mut self, p: &Plugin) {
        for (name, q) in &p.properties {
            let key = (q.at.file.clone(), q.at.line, name.clone());
            self.offered.push((key, p.label()));
            if let Value::Transform(t) = &q.value
                && t.steps.iter().any(|s| matches!(s, super::xml::Step::Rotate(a, _) if a[0] * a[0] + a[1] * a[1] + a[2] * a[2] != 1.0))
            {
                let what = format!(
                    "`{name}` turns about an axis whose length is not 1: as in Mitsuba, the axis is used as \
                     written (not normalised), so the map stretches as it turns"
                );
                self.warnings.push(format!("{} ({}, line {}): {what}", p.label(), q.at.file.display(), q.at.line));
            }
        }
        self.read.push(format!(
            "{} ({}, line {})",
            p.label(),
            p.at.file.display(),
            p.at.line
        ));
    }

    pub(super) fn warn(&mut self, p: &Plugin, what: String) {
        let where_ = format!("{}, line {}", p.at.file.display(), p.at.line);
        self.warnings.push(format!("{} ({where_}): {what}", p.label()));
    }

    pub(super) fn unsupported(&self, p: &Plugin, kind: &str) -> Error {
        p.at.error(format!(
            "<{} type=\"{kind}\"> is not supported by this importer",
            p.tag
        ))
    }

    /// A file name as the scene file keeps it, relative to the XML's folder (as a scene
    /// file's are to its own): found there or in a `<path>`.
    pub(super) fn path_of(&self, name: &str) -> String {
        let path = self.located(name);
        let relative = path.strip_prefix(&self.folders[0]).unwrap_or(&path);
        relative.to_string_lossy().into_owned()
    }

    /// Where the file `name` is: in the XML's folder or a `<path>` (else where it would be).
    pub(super) fn located(&self, name: &str) -> PathBuf {
        let found = self.folders.iter().map(|f| f.join(name)).find(|p| p.exists());
        found.unwrap_or_else(|| self.folders[0].join(name))
    }

    /// The property `name` of `p`, noted as asked for.
    pub(super) fn property<'p>(&self, p: &'p Plugin, name: &str) -> Option<&'p super::xml::Property> {
        self.asked.property(p, name)
    }

    /// A warning for each property of a plugin read that nothing asked for (a parameter
    /// this importer does not know, or misspelt): the render is as if it were absent.
    fn unread(&mut self) {
        let asked = self.asked.0.take();
        let mut told = BTreeSet::new();
        for (key, label) in std::mem::take(&mut self.offered) {
            if !asked.contains(&key) && told.insert(key.clone()) {
                let (file, line, name) = key;
                self.warnings.push(format!(
                    "{label} ({}, line {line}): `{name}` is not read by this importer: rendered as if it were absent",
                    file.display()
                ));
            }
        }
    }

    pub(super) fn number(&self, p: &Plugin, name: &str) -> Result<Option<f64>> {
        match self.property(p, name).map(|q| (&q.value, &q.at)) {
            None => Ok(None),
            Some((Value::Number(x), _)) => Ok(Some(*x)),
            Some((_, at)) => Err(at.error(format!("{}: `{name}` is a number", p.label()))),
        }
    }

    pub(super) fn boolean(&self, p: &Plugin, name: &str) -> Result<Option<bool>> {
        match self.property(p, name).map(|q| (&q.value, &q.at)) {
            None => Ok(None),
            Some((Value::Bool(b), _)) => Ok(Some(*b)),
            Some((_, at)) => Err(at.error(format!("{}: `{name}` is a boolean", p.label()))),
        }
    }

    pub(super) fn text(&self, p: &Plugin, name: &str) -> Result<Option<String>> {
        match self.property(p, name).map(|q| (&q.value, &q.at)) {
            None => Ok(None),
            Some((Value::Text(s), _)) => Ok(Some(s.clone())),
            Some((_, at)) => Err(at.error(format!("{}: `{name}` is a string", p.label()))),
        }
    }

    /// A colour, point or vector; a number is grey.
    pub(super) fn triple(&self, p: &Plugin, name: &str) -> Result<Option<[f64; 3]>> {
        match self.property(p, name).map(|q| (&q.value, &q.at)) {
            None => Ok(None),
            Some((Value::Triple(t), _)) => Ok(Some(*t)),
            Some((Value::Number(x), _)) => Ok(Some([*x; 3])),
            Some((_, at)) => Err(at.error(format!("{}: `{name}` is a colour or a point", p.label()))),
        }
    }

    pub(super) fn to_world(&self, p: &Plugin) -> Result<Affine> {
        match self.property(p, "to_world").map(|q| (&q.value, &q.at)) {
            None => Ok(Affine::IDENTITY),
            Some((Value::Transform(t), _)) => Ok(t.map),
            Some((_, at)) => Err(at.error(format!("{}: `to_world` is a <transform>", p.label()))),
        }
    }

    /// The material of `b`, under its `id` or a name made up for it; its name.
    pub(super) fn named_material(&mut self, b: &Plugin) -> Result<String> {
        let name =
            b.id.clone()
                .unwrap_or_else(|| format!("{}_line{}", b.kind, b.at.line));
        if !self.file.materials.contains_key(&name) {
            let spec = self.material(b)?;
            self.file.materials.insert(name.clone(), spec);
        }
        Ok(name)
    }

    fn emitter(&mut self, e: &Plugin) -> Result<()> {
        self.read(e);
        let m = self.to_world(e)?;
        let colour =
            |me: &Self, name: &str| -> Result<[f64; 3]> { Ok(me.triple(e, name)?.unwrap_or([1.0; 3])) };
        match e.kind.as_str() {
            "point" => {
                let position = self.triple(e, "position")?.unwrap_or(m.point([0.0; 3]));
                self.file.lights.push(LightSpec::Point {
                    position,
                    intensity: colour(self, "intensity")?,
                });
            }
            "spot" => self.file.lights.push(LightSpec::Spot {
                position: m.point([0.0; 3]),
                direction: m.vector([0.0, 0.0, 1.0]),
                intensity: colour(self, "intensity")?,
                cutoff_angle: self.number(e, "cutoff_angle")?.unwrap_or(20.0),
                beam_width: self.number(e, "beam_width")?,
            }),
            "directional" => {
                let direction = self.triple(e, "direction")?.unwrap_or(m.vector([0.0, 0.0, 1.0]));
                self.file.lights.push(LightSpec::Directional {
                    direction,
                    irradiance: colour(self, "irradiance")?,
                });
            }
            "constant" => {
                self.lights_on_surfaces = true;
                self.file.background = BackgroundSpec::Solid {
                    color: colour(self, "radiance")?,
                    light: true,
                };
            }
            "envmap" => {
                self.lights_on_surfaces = true;
                let file = self
                    .text(e, "filename")?
                    .ok_or_else(|| e.at.error("<emitter type=\"envmap\"> needs a `filename`"))?;
                // Turns about x, y, z as written keep their angles; another map is solved for them.
                let rotate = match super::exact::turns(self.steps(e)) {
                    Some(turns) => turns,
                    None => {
                        euler_xyz(&m).ok_or_else(|| e.at.error("envmap: `to_world` may only turn the map"))?
                    }
                };
                self.file.background = BackgroundSpec::Envmap {
                    file: self.path_of(&file),
                    scale: self.number(e, "scale")?.unwrap_or(1.0),
                    rotate,
                };
            }
            "raytrace_sky" => self.sky(e)?,
            other => return Err(self.unsupported(e, other)),
        }
        Ok(())
    }
}

/// The turns about x, then y, then z, in degrees, of a map that only turns (`R = Rz·Ry·Rx`).
fn euler_xyz(m: &Affine) -> Option<[f64; 3]> {
    if super::shape::uniform_scale(m).is_none_or(|s| (s - 1.0).abs() > 1e-9) {
        return None;
    }
    let r = m.rows();
    let y = (-r[2][0]).clamp(-1.0, 1.0).asin();
    let (x, z) = if r[2][0].abs() < 1.0 - 1e-12 {
        (r[2][1].atan2(r[2][2]), r[1][0].atan2(r[0][0]))
    } else {
        // Gimbal lock: the x and z turns are about one axis; put it all in x.
        ((-r[1][2]).atan2(r[1][1]), 0.0)
    };
    Some([x, y, z].map(f64::to_degrees))
}
