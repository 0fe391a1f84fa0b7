//! A glTF scene's camera, `KHR_lights_punctual` lights and background.
//!
//! - The camera is the first perspective camera met walking the scene's nodes: at its
//!   node's origin, looking down the node's `−z` with `+y` up, `yfov` its vertical field
//!   of view and `aspectRatio` (4:3 if unset; the ratio of small integers it rounds from
//!   as f32, if any) its image's width over height. `znear` and
//!   `zfar` are not read (a path tracer clips nothing).
//! - With none, a camera frames the scene: it looks down `−z` at the centre of the box
//!   around every placed vertex, from the distance `r / sin(20°)` at which the box's
//!   bounding sphere (radius `r`, half its diagonal) just fills a 40° vertical field of
//!   view, 4:3.
//! - Lights: glTF's photometric units become the renderer's radiometric ones at 683 lm/W
//!   (what Blender's exporter multiplies by): a point or spot light's candela `I` gives
//!   the radiant intensity `I/683` W/sr, a directional light's lux `E` the irradiance
//!   `E/683` W/m², each times the light's colour. A spot's `innerConeAngle` and
//!   `outerConeAngle` are the renderer's beam width and cutoff.
//! - Background: black when the scene has a light or an emitting surface (glTF has no
//!   environment), else the renderer's default sky as a light, so a bare model is seen.

use super::convert::Importer;
use super::nodes::Rows;
use crate::error::Result;
use crate::scene_file::{BackgroundSpec, CameraSpec, LightSpec};
use ::gltf::camera::Projection;
use ::gltf::khr_lights_punctual::Kind;

/// Lumens per watt: the luminous efficacy that relates glTF's photometric light units to
/// radiometric ones.
pub const LUMENS_PER_WATT: f64 = 683.0;

/// The aspect ratio of a camera that gives none, and of the camera made when the file
/// has none: 4:3.
pub const DEFAULT_ASPECT: f64 = 4.0 / 3.0;

/// The vertical field of view of the camera made when the file has none, in degrees.
pub const DEFAULT_VFOV: f64 = 40.0;

fn point(m: &Rows, p: [f64; 3]) -> [f64; 3] {
    m.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3])
}

fn vector(m: &Rows, v: [f64; 3]) -> [f64; 3] {
    m.map(|r| r[0] * v[0] + r[1] * v[1] + r[2] * v[2])
}

/// `a`, an aspect ratio read as `f32`, as the ratio `p/q` of small integers (`q ≤ 64`)
/// it rounds from, if one is within `f32`'s rounding (`2⁻²³` relative): `4/3` is stored
/// as `1.3333334`, which would make an 800-pixel-wide image 599 rows high.
fn snapped(a: f64) -> f64 {
    (1..=64u32)
        .map(|q| (f64::from(q) * a).round() / f64::from(q))
        .find(|r| *r > 0.0 && ((r - a) / a).abs() <= f64::from(f32::EPSILON))
        .unwrap_or(a)
}

impl Importer<'_> {
    /// The camera of node `at` (placed by `world`), if it is a perspective one; an
    /// orthographic one is a warning, and the walk goes on to the next camera.
    pub(super) fn camera(&mut self, c: &::gltf::Camera, at: &str, world: &Rows) -> Result<bool> {
        let owner = format!("cameras[{}]", c.index());
        let Projection::Perspective(p) = c.projection() else {
            self.warn(
                &owner,
                "an orthographic camera is not read: the next perspective camera is, else one framing \
                 the scene"
                    .into(),
            );
            return Ok(false);
        };
        let yfov = f64::from(p.yfov());
        if !(yfov > 0.0 && yfov < std::f64::consts::PI) {
            return Err(self.error(
                format!("{owner}.perspective.yfov"),
                format!("{yfov} radians: a field of view is in (0, π)"),
            ));
        }
        let aspect = match p.aspect_ratio().map(f64::from) {
            Some(a) if a > 0.0 && a.is_finite() => snapped(a),
            Some(a) => {
                return Err(self.error(
                    format!("{owner}.perspective.aspectRatio"),
                    format!("{a}: an aspect ratio is finite and > 0"),
                ));
            }
            None => DEFAULT_ASPECT,
        };
        if super::nodes::determinant(world) < 0.0 {
            return Err(self.error(at, "a camera mirrored by its node's map is not rendered"));
        }
        let name = c.name().map(|n| format!(" '{n}'")).unwrap_or_default();
        self.read.push(format!(
            "{owner}{name} at {at}: perspective, yfov {:.4}°, aspect {aspect:.4}{}",
            yfov.to_degrees(),
            if p.aspect_ratio().is_none() {
                " (unset: 4:3)"
            } else {
                ""
            }
        ));
        self.file.camera = CameraSpec::LookAt {
            from: point(world, [0.0; 3]),
            at: point(world, [0.0, 0.0, -1.0]),
            up: vector(world, [0.0, 1.0, 0.0]),
            vfov: yfov.to_degrees(),
            aspect,
            aperture: 0.0,
            focus_distance: None,
        };
        Ok(true)
    }

    /// The light of node `at` (placed by `world`).
    pub(super) fn light(
        &mut self,
        l: &::gltf::khr_lights_punctual::Light,
        at: &str,
        world: &Rows,
    ) -> Result<()> {
        let owner = format!("KHR_lights_punctual.lights[{}]", l.index());
        let scale = f64::from(l.intensity()) / LUMENS_PER_WATT;
        let colour = l.color().map(|c| f64::from(c) * scale);
        let position = point(world, [0.0; 3]);
        let direction = vector(world, [0.0, 0.0, -1.0]);
        if l.range().is_some() {
            self.warn(
                &owner,
                "its range is not read: its light falls off as 1/d² without end".into(),
            );
        }
        let aims = !matches!(l.kind(), Kind::Point);
        let length = direction.iter().map(|x| x * x).sum::<f64>().sqrt();
        if aims && !(length > 0.0 && length.is_finite()) {
            self.warn(&owner, format!("its node {at} flattens its direction: left out"));
            return Ok(());
        }
        let (spec, kind) = match l.kind() {
            Kind::Point => (
                LightSpec::Point {
                    position,
                    intensity: colour,
                },
                "point",
            ),
            Kind::Spot {
                inner_cone_angle,
                outer_cone_angle,
            } => {
                self.warn(
                    &owner,
                    "between its cones it dims linearly in the angle (Mitsuba's spot), not as glTF's smooth ramp"
                        .into(),
                );
                let spot = LightSpec::Spot {
                    position,
                    direction,
                    intensity: colour,
                    cutoff_angle: f64::from(outer_cone_angle).to_degrees(),
                    beam_width: Some(f64::from(inner_cone_angle).to_degrees()),
                };
                (spot, "spot")
            }
            Kind::Directional => (
                LightSpec::Directional {
                    direction,
                    irradiance: colour,
                },
                "directional",
            ),
        };
        let name = l.name().map(|n| format!(" '{n}'")).unwrap_or_default();
        self.read.push(format!(
            "{owner}{name} at {at}: {kind}, intensity {} (÷ {LUMENS_PER_WATT} lm/W → {colour:?})",
            l.intensity()
        ));
        self.file.lights.push(spec);
        Ok(())
    }

    /// The camera that frames the scene when the file has none.
    pub(super) fn default_camera(&mut self) {
        let (centre, radius) = match self.bounds {
            Some(b) => {
                let c = (b.min + b.max) * 0.5;
                let r = (b.max - b.min).length() * 0.5;
                ([c.x, c.y, c.z], if r > 0.0 { r } else { 1.0 })
            }
            None => ([0.0; 3], 1.0),
        };
        let distance = radius / (DEFAULT_VFOV.to_radians() / 2.0).sin();
        self.read.push(format!(
            "no camera: framing the scene from +z, {DEFAULT_VFOV}° vertical field of view, 4:3"
        ));
        self.file.camera = CameraSpec::LookAt {
            from: [centre[0], centre[1], centre[2] + distance],
            at: centre,
            up: [0.0, 1.0, 0.0],
            vfov: DEFAULT_VFOV,
            aspect: DEFAULT_ASPECT,
            aperture: 0.0,
            focus_distance: None,
        };
    }

    /// Black behind a lit scene; the default sky, as a light, behind one with no light.
    pub(super) fn background(&mut self) {
        self.file.background = if self.file.lights.is_empty() && !self.emitters {
            self.read
                .push("no lights and no emitting surfaces: lit by the renderer's default sky".into());
            match BackgroundSpec::default() {
                BackgroundSpec::Sky { horizon, zenith, .. } => BackgroundSpec::Sky {
                    horizon,
                    zenith,
                    light: true,
                },
                other => other,
            }
        } else {
            BackgroundSpec::Solid {
                color: [0.0; 3],
                light: false,
            }
        };
    }
}

#[cfg(test)]
mod tests {
    use super::snapped;

    #[test]
    fn an_f32_aspect_ratio_is_read_as_the_ratio_it_rounds_from() {
        for (p, q) in [(4.0, 3.0), (16.0, 9.0), (3.0, 2.0), (1.0, 1.0), (21.0, 9.0)] {
            let stored = f64::from((p / q) as f32);
            assert_eq!(snapped(stored), p / q, "{p}/{q}");
            assert_eq!((800.0 / snapped(stored)).floor(), (800.0 * q / p).floor());
        }
        // A ratio of no small integers stays as it is.
        let odd = f64::from(1.2345678f32);
        assert_eq!(snapped(odd), odd);
    }
}
