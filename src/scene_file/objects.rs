//! The scene file's `[[objects]]` and `[meshes.NAME]`: each shape with the name of its
//! material, and a mesh's placement.

use super::model::Triple;
use serde::{Deserialize, Serialize};

/// One `[[objects]]` entry: a shape and the name of its material.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ObjectSpec {
    /// A sphere.
    Sphere {
        /// The centre.
        #[serde(deserialize_with = "super::triple::deserialize")]
        center: Triple,
        /// The radius, `> 0`.
        radius: f64,
        /// The material's name.
        material: String,
    },
    /// An infinite plane.
    Plane {
        /// A point on the plane.
        #[serde(deserialize_with = "super::triple::deserialize")]
        point: Triple,
        /// The normal (any non-zero length), pointing to the front face.
        #[serde(deserialize_with = "super::triple::deserialize")]
        normal: Triple,
        /// The material's name.
        material: String,
    },
    /// A triangle, front face where `a → b → c` runs counter-clockwise.
    Triangle {
        /// The first vertex.
        #[serde(deserialize_with = "super::triple::deserialize")]
        a: Triple,
        /// The second vertex.
        #[serde(deserialize_with = "super::triple::deserialize")]
        b: Triple,
        /// The third vertex.
        #[serde(deserialize_with = "super::triple::deserialize")]
        c: Triple,
        /// The material's name.
        material: String,
    },
    /// A flat disk: Mitsuba's unit disk (radius 1 about the origin, facing `+z`) unless
    /// `center`, `normal` and `radius` say otherwise, or a `matrix` places it.
    Disk {
        /// The centre (default the origin).
        #[serde(deserialize_with = "super::triple::deserialize", default)]
        center: Triple,
        /// The normal (any non-zero length), pointing to the front face (default `+z`).
        #[serde(deserialize_with = "super::triple::deserialize", default = "z_up")]
        normal: Triple,
        /// The radius, `> 0` (default 1).
        #[serde(default = "one")]
        radius: f64,
        /// Instead of `center`, `normal` and `radius`: the rows `[L | t]` of an invertible
        /// affine map of the unit disk (a Mitsuba scene's `to_world`).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        matrix: Option<[[f64; 4]; 3]>,
        /// The material's name.
        material: String,
    },
    /// A triangle mesh from an OBJ or PLY file, scaled, then rotated, then translated.
    Mesh {
        /// The mesh file, relative to the scene file's folder.
        file: String,
        /// A factor for every axis, or one per axis.
        #[serde(default)]
        scale: Scale,
        /// Degrees about x, then y, then z.
        #[serde(deserialize_with = "super::triple::deserialize", default)]
        rotate: Triple,
        /// Added last.
        #[serde(deserialize_with = "super::triple::deserialize", default)]
        translate: Triple,
        /// The material's name.
        material: String,
        /// Whether the file's vertex normals are dropped, so the mesh shades with its
        /// faces' normals (Mitsuba's `face_normals`; default `false`).
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        face_normals: bool,
        /// Whether the texture coordinates' `v` is flipped, `v ↦ 1 − v` (Mitsuba's
        /// `flip_tex_coords`); unset, Mitsuba's default: `true` for OBJ, `false` for PLY.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        flip_tex_coords: Option<bool>,
        /// Instead of `scale`, `rotate` and `translate`: the rows `[L | t]` of any
        /// invertible affine map (a Mitsuba scene's `to_world`).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        matrix: Option<[[f64; 4]; 3]>,
    },
    /// A placement of a `[meshes.NAME]` mesh: the mesh read once, however often placed.
    Instance {
        /// The `[meshes]` entry placed.
        mesh: String,
        /// A factor for every axis, or one per axis.
        #[serde(default)]
        scale: Scale,
        /// Degrees about x, then y, then z.
        #[serde(deserialize_with = "super::triple::deserialize", default)]
        rotate: Triple,
        /// Added last.
        #[serde(deserialize_with = "super::triple::deserialize", default)]
        translate: Triple,
        /// Instead of `scale`, `rotate` and `translate`: the rows `[L | t]` of any
        /// invertible affine map.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        matrix: Option<[[f64; 4]; 3]>,
        /// The material's name.
        material: String,
    },
}

/// A `[meshes.NAME]` entry: a mesh file read once, for `type = "instance"` objects to
/// place many times.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshDef {
    /// The mesh file (OBJ or PLY), relative to the scene file's folder.
    pub file: String,
}

impl ObjectSpec {
    /// The name of the object's material.
    pub fn material(&self) -> &str {
        match self {
            Self::Sphere { material, .. }
            | Self::Plane { material, .. }
            | Self::Triangle { material, .. }
            | Self::Disk { material, .. }
            | Self::Mesh { material, .. }
            | Self::Instance { material, .. } => material,
        }
    }
}

fn z_up() -> Triple {
    [0.0, 0.0, 1.0]
}

fn one() -> f64 {
    1.0
}

/// A mesh's scale: one factor for all axes (`scale = 2`) or one per axis (`[1, 2, 1]`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged, expecting = "expected a number or an array of three numbers")]
pub enum Scale {
    /// The same factor on every axis.
    Uniform(f64),
    /// A factor per axis.
    PerAxis(#[serde(deserialize_with = "super::triple::deserialize")] Triple),
}

impl Default for Scale {
    fn default() -> Self {
        Self::Uniform(1.0)
    }
}

impl Scale {
    /// The factor per axis.
    pub fn factors(self) -> Triple {
        match self {
            Self::Uniform(s) => [s; 3],
            Self::PerAxis(s) => s,
        }
    }
}
