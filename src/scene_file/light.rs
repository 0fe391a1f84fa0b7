//! The `[[lights]]` entries: point, spot and directional lights, a point light when the
//! entry has no `type` (as every file had before there were other kinds).

use super::model::Triple;
use serde::{Deserialize, Serialize};

/// One `[[lights]]` entry.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "LightFields", into = "LightFields")]
pub enum LightSpec {
    /// `type = "point"`, or no `type`: an isotropic point light.
    Point {
        /// Where it is.
        position: Triple,
        /// Its radiant intensity per channel, `≥ 0`.
        intensity: Triple,
    },
    /// `type = "spot"`: a point light shining into a cone.
    Spot {
        /// Where it is.
        position: Triple,
        /// Where the cone points (any non-zero length).
        direction: Triple,
        /// Its radiant intensity per channel in the beam, `≥ 0`.
        intensity: Triple,
        /// Degrees from the axis beyond which it is dark, in `(0, 90]` (default 20).
        cutoff_angle: f64,
        /// Degrees from the axis within which it has its full intensity, in
        /// `[0, cutoff_angle]` (default ¾ of the cutoff).
        beam_width: Option<f64>,
    },
    /// `type = "directional"`: a light at infinity (the sun).
    Directional {
        /// The way the light travels (any non-zero length).
        direction: Triple,
        /// The irradiance per channel on a surface facing it, `≥ 0`.
        irradiance: Triple,
    },
}

impl LightSpec {
    /// The spot light's cutoff angle when the file gives none: Mitsuba 3's, 20°.
    pub const DEFAULT_CUTOFF_ANGLE: f64 = 20.0;

    /// The light's colour: its intensity, or a directional light's irradiance.
    pub fn color(&self) -> Triple {
        match *self {
            Self::Point { intensity, .. } | Self::Spot { intensity, .. } => intensity,
            Self::Directional { irradiance, .. } => irradiance,
        }
    }

    /// A spot light's beam width: as written, else ¾ of the cutoff angle (Mitsuba 3's
    /// default).
    pub fn default_beam_width(cutoff_angle: f64) -> f64 {
        cutoff_angle * 0.75
    }
}

/// The kinds of light, under the names the file uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
enum LightKind {
    #[default]
    Point,
    Spot,
    Directional,
}

/// Every key any light may have, read as a plain table (so a wrong type is found at its
/// element, `lights[0].position[2]`) and then checked against the kind.
#[derive(Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LightFields {
    #[serde(rename = "type", default)]
    kind: LightKind,
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    position: Option<Triple>,
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    direction: Option<Triple>,
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    intensity: Option<Triple>,
    #[serde(
        deserialize_with = "super::triple::some",
        default,
        skip_serializing_if = "Option::is_none"
    )]
    irradiance: Option<Triple>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    cutoff_angle: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    beam_width: Option<f64>,
}

/// The keys each kind takes, in the order messages list them.
const POINT: &[&str] = &["position", "intensity"];
const SPOT: &[&str] = &["position", "direction", "intensity", "cutoff_angle", "beam_width"];
const DIRECTIONAL: &[&str] = &["direction", "irradiance"];

impl TryFrom<LightFields> for LightSpec {
    type Error = String;

    /// A key the kind does not take is refused first, in the reader's words
    /// (`unknown field …, expected one of …`), so it is reported at that key; then a
    /// missing one, at the entry.
    fn try_from(f: LightFields) -> Result<Self, String> {
        let (name, takes) = match f.kind {
            LightKind::Point => ("point", POINT),
            LightKind::Spot => ("spot", SPOT),
            LightKind::Directional => ("directional", DIRECTIONAL),
        };
        let given = [
            ("position", f.position.is_some()),
            ("direction", f.direction.is_some()),
            ("intensity", f.intensity.is_some()),
            ("irradiance", f.irradiance.is_some()),
            ("cutoff_angle", f.cutoff_angle.is_some()),
            ("beam_width", f.beam_width.is_some()),
        ];
        if let Some((key, _)) = given.iter().find(|(k, set)| *set && !takes.contains(k)) {
            let expected: Vec<_> = takes.iter().map(|k| format!("`{k}`")).collect();
            return Err(format!(
                "unknown field `{key}`, expected one of `type`, {} (a {name} light's keys)",
                expected.join(", ")
            ));
        }
        let need = |key: &str, v: Option<Triple>| v.ok_or_else(|| format!("missing field `{key}`"));
        Ok(match f.kind {
            LightKind::Point => Self::Point {
                position: need("position", f.position)?,
                intensity: need("intensity", f.intensity)?,
            },
            LightKind::Spot => Self::Spot {
                position: need("position", f.position)?,
                direction: need("direction", f.direction)?,
                intensity: need("intensity", f.intensity)?,
                cutoff_angle: f.cutoff_angle.unwrap_or(Self::DEFAULT_CUTOFF_ANGLE),
                beam_width: f.beam_width,
            },
            LightKind::Directional => Self::Directional {
                direction: need("direction", f.direction)?,
                irradiance: need("irradiance", f.irradiance)?,
            },
        })
    }
}

impl From<LightSpec> for LightFields {
    fn from(spec: LightSpec) -> Self {
        match spec {
            LightSpec::Point { position, intensity } => Self {
                kind: LightKind::Point,
                position: Some(position),
                intensity: Some(intensity),
                ..Self::default()
            },
            LightSpec::Spot {
                position,
                direction,
                intensity,
                cutoff_angle,
                beam_width,
            } => Self {
                kind: LightKind::Spot,
                position: Some(position),
                direction: Some(direction),
                intensity: Some(intensity),
                cutoff_angle: Some(cutoff_angle),
                beam_width,
                ..Self::default()
            },
            LightSpec::Directional {
                direction,
                irradiance,
            } => Self {
                kind: LightKind::Directional,
                direction: Some(direction),
                irradiance: Some(irradiance),
                ..Self::default()
            },
        }
    }
}
