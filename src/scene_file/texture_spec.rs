//! The scene file's textures: `[textures.NAME]` tables, and the value of a colour key,
//! which is a colour, a texture's name or a texture table written in place.

use super::model::Triple;
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::ser::Serializer;
use serde::{Deserialize, Serialize};
use std::fmt;

/// A texture, `[textures.NAME]` or a table in place of a colour.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum TextureSpec {
    /// Two colours in alternating squares of `uv` (Mitsuba's `checkerboard`).
    Checkerboard {
        /// The squares with the corner `uv = (0, 0)` (default `[0.4, 0.4, 0.4]`).
        #[serde(deserialize_with = "super::triple::deserialize", default = "color0")]
        color0: Triple,
        /// The other squares (default `[0.2, 0.2, 0.2]`).
        #[serde(deserialize_with = "super::triple::deserialize", default = "color1")]
        color1: Triple,
        /// `uv` is multiplied by this first: a number, or `[su, sv]` (default 1).
        #[serde(default)]
        scale: UvScale,
        /// Then this is added: `[ou, ov]` (default `[0, 0]`).
        #[serde(deserialize_with = "pair", default)]
        offset: [f64; 2],
    },
    /// An image file (Mitsuba's `bitmap`): PNG, JPEG, Radiance HDR or OpenEXR.
    Image {
        /// The file, relative to the scene file's folder.
        file: String,
        /// Outside `[0, 1]²`: `"repeat"` (the default) or `"clamp"`.
        #[serde(default)]
        wrap: WrapSpec,
        /// Whether the stored values are data, not sRGB colour (Mitsuba's `raw`); unset,
        /// `false` for a colour and `true` for a normal map.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        raw: Option<bool>,
        /// `uv` is multiplied by this first: a number, or `[su, sv]` (default 1).
        #[serde(default)]
        scale: UvScale,
        /// Then this is added: `[ou, ov]` (default `[0, 0]`).
        #[serde(deserialize_with = "pair", default)]
        offset: [f64; 2],
    },
}

fn color0() -> Triple {
    [0.4; 3]
}

fn color1() -> Triple {
    [0.2; 3]
}

/// How an image texture wraps outside `[0, 1]²`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum WrapSpec {
    /// Tile the plane.
    #[default]
    Repeat,
    /// Extend the edge pixels.
    Clamp,
}

/// A texture's `uv` scale: one factor for both axes or one per axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged, expecting = "expected a number or an array of two numbers")]
pub enum UvScale {
    /// The same factor on `u` and `v`.
    Uniform(f64),
    /// A factor per axis.
    PerAxis(#[serde(deserialize_with = "pair")] [f64; 2]),
}

impl Default for UvScale {
    fn default() -> Self {
        Self::Uniform(1.0)
    }
}

impl UvScale {
    /// The factor per axis.
    pub fn factors(self) -> [f64; 2] {
        match self {
            Self::Uniform(s) => [s; 2],
            Self::PerAxis(s) => s,
        }
    }
}

/// Reads an array of exactly two numbers.
fn pair<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 2], D::Error> {
    struct Two;
    impl<'de> Visitor<'de> for Two {
        type Value = [f64; 2];
        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("an array of two numbers")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<[f64; 2], A::Error> {
            let mut t = [0.0; 2];
            for (i, slot) in t.iter_mut().enumerate() {
                *slot = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(i, &self))?;
            }
            let mut len = 2;
            while seq.next_element::<de::IgnoredAny>()?.is_some() {
                len += 1;
            }
            if len > 2 {
                return Err(de::Error::invalid_length(len, &self));
            }
            Ok(t)
        }
    }
    d.deserialize_seq(Two)
}

/// The value of a colour key: `[r, g, b]`, the name of a `[textures.NAME]` entry, or a
/// texture table written in place (`{ type = "checkerboard", … }`).
#[derive(Clone, Debug, PartialEq)]
pub enum TextureRef {
    /// The same colour everywhere.
    Color(Triple),
    /// A `[textures.NAME]` entry.
    Named(String),
    /// A texture of this key alone.
    Inline(Box<TextureSpec>),
}

impl From<Triple> for TextureRef {
    fn from(c: Triple) -> Self {
        Self::Color(c)
    }
}

impl TextureRef {
    /// The colour, if the value is one.
    pub fn as_color(&self) -> Option<Triple> {
        match self {
            Self::Color(c) => Some(*c),
            _ => None,
        }
    }
}

impl Serialize for TextureRef {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Self::Color(c) => c.serialize(s),
            Self::Named(name) => s.serialize_str(name),
            Self::Inline(spec) => spec.serialize(s),
        }
    }
}

impl<'de> Deserialize<'de> for TextureRef {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(RefVisitor)
    }
}

struct RefVisitor;

impl<'de> Visitor<'de> for RefVisitor {
    type Value = TextureRef;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of three numbers, a texture's name or a texture table")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<TextureRef, A::Error> {
        super::triple::Exact.visit_seq(seq).map(TextureRef::Color)
    }

    fn visit_str<E: de::Error>(self, name: &str) -> Result<TextureRef, E> {
        Ok(TextureRef::Named(name.to_owned()))
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<TextureRef, A::Error> {
        let spec = TextureSpec::deserialize(de::value::MapAccessDeserializer::new(map))?;
        Ok(TextureRef::Inline(Box::new(spec)))
    }
}

/// The value of a number key that may vary over a surface (a roughness): a number, the
/// name of a `[textures.NAME]` entry or a texture table in place. A number is held as
/// the grey [`TextureRef::Color`] of it.
#[derive(Clone, Debug, PartialEq)]
pub struct ScalarRef(pub TextureRef);

impl From<f64> for ScalarRef {
    fn from(x: f64) -> Self {
        Self(TextureRef::Color([x; 3]))
    }
}

impl Serialize for ScalarRef {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match &self.0 {
            TextureRef::Color([x, y, z]) if x == y && y == z => s.serialize_f64(*x),
            other => other.serialize(s),
        }
    }
}

impl<'de> Deserialize<'de> for ScalarRef {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ScalarVisitor)
    }
}

struct ScalarVisitor;

impl<'de> Visitor<'de> for ScalarVisitor {
    type Value = ScalarRef;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number, a texture's name or a texture table")
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<ScalarRef, E> {
        Ok(x.into())
    }

    fn visit_i64<E: de::Error>(self, x: i64) -> Result<ScalarRef, E> {
        Ok((x as f64).into())
    }

    fn visit_u64<E: de::Error>(self, x: u64) -> Result<ScalarRef, E> {
        Ok((x as f64).into())
    }

    fn visit_str<E: de::Error>(self, name: &str) -> Result<ScalarRef, E> {
        RefVisitor.visit_str(name).map(ScalarRef)
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<ScalarRef, A::Error> {
        RefVisitor.visit_map(map).map(ScalarRef)
    }
}
