//! Reading PLY files (ascii, binary little and big endian) with `ply-rs-bw`.
//!
//! The `vertex` element gives the positions (`x y z`, float or double) and the `face`
//! element the polygons (`vertex_indices` or `vertex_index`, a list of any integer type);
//! other elements and properties are read past and ignored. Vertices and faces are
//! numbered from 0, as the file's indices count them.

use super::MeshData;
use super::check::{Problem, Triangulator, check_positions};
use crate::error::{Error, Result};
use crate::vec3::Vec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{ElementDef, Header, Property, PropertyAccess, PropertyAccessResult};
use ply_rs_bw::ply::{PropertyType, ScalarType};
use std::fs::File;
use std::io::BufReader;
use std::path::Path;

/// The names a face's index list goes by (the second is older, and still common).
const INDEX_NAMES: [&str; 2] = ["vertex_indices", "vertex_index"];

/// A vertex's position; properties other than `x y z` are ignored.
struct Vertex([f64; 3]);

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Self([0.0; 3])
    }

    fn set_float(&mut self, name: &str, value: f32) -> PropertyAccessResult {
        self.set_double(name, f64::from(value))
    }

    fn set_double(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        match axis(name) {
            Some(i) => {
                self.0[i] = value;
                PropertyAccessResult::Set
            }
            None => PropertyAccessResult::Ignored,
        }
    }

    // Reached for the types not handled above: only an integer `x`, `y` or `z` is refused
    // (the header check rejects those first, with a clearer message).
    fn set_property(&mut self, name: &str, _: Property) -> PropertyAccessResult {
        match axis(name) {
            Some(_) => PropertyAccessResult::UnsupportedType,
            None => PropertyAccessResult::Ignored,
        }
    }
}

/// The coordinate a property name sets, if any.
fn axis(name: &str) -> Option<usize> {
    ["x", "y", "z"].iter().position(|&a| a == name)
}

/// A face's vertex indices, widened to `i64` so that any PLY integer type fits.
struct Face(Vec<i64>);

impl PropertyAccess for Face {
    fn new() -> Self {
        Self(Vec::new())
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        if !INDEX_NAMES.contains(&name) {
            return PropertyAccessResult::Ignored;
        }
        self.0 = match property {
            Property::ListChar(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUChar(v) => v.into_iter().map(i64::from).collect(),
            Property::ListShort(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUShort(v) => v.into_iter().map(i64::from).collect(),
            Property::ListInt(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUInt(v) => v.into_iter().map(i64::from).collect(),
            _ => return PropertyAccessResult::UnsupportedType,
        };
        PropertyAccessResult::Set
    }
}

/// An element of no interest, read only to get past it.
struct Skipped;

impl PropertyAccess for Skipped {
    fn new() -> Self {
        Self
    }
}

/// Loads a PLY mesh.
pub(super) fn load(path: &Path) -> Result<MeshData> {
    let fail = |message: String| Error::Mesh {
        path: path.to_path_buf(),
        message,
    };
    let file = File::open(path).map_err(|e| fail(format!("cannot open: {e}")))?;
    let mut reader = Reader::new(BufReader::new(file));
    let header = Parser::<Skipped>::new()
        .read_header(&mut reader)
        .map_err(|e| fail(format!("bad PLY header: {e}")))?;
    check_header(&header).map_err(fail)?;

    let (mut vertices, mut faces) = (Vec::new(), Vec::new());
    for element in header.elements.values() {
        let what = |e| fail(format!("element {}: {e}", element.name));
        match element.name.as_str() {
            "vertex" => {
                vertices = Parser::<Vertex>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(what)?;
            }
            "face" => {
                faces = Parser::<Face>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(what)?;
            }
            _ => {
                Parser::<Skipped>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(what)?;
            }
        }
    }

    let positions: Vec<Vec3<f64>> = vertices
        .into_iter()
        .map(|Vertex([x, y, z])| Vec3::new(x, y, z))
        .collect();
    let named = |problem: Problem| fail(problem.to_string());
    check_positions(&positions).map_err(named)?;
    let mut mesh = Triangulator::new(positions);
    for (number, Face(indices)) in faces.into_iter().enumerate() {
        mesh.add_face(number, indices.into_iter()).map_err(named)?;
    }
    mesh.finish().map_err(named)
}

/// Checks that the header declares the vertex and face elements with properties of the
/// types this reader takes, so that a wrong file fails with the reason rather than later.
fn check_header(header: &Header) -> std::result::Result<(), String> {
    let element = |name: &str| -> std::result::Result<&ElementDef, String> {
        header
            .elements
            .get(name)
            .ok_or_else(|| format!("the file has no {name} element"))
    };
    let vertex = element("vertex")?;
    for name in ["x", "y", "z"] {
        match vertex.properties.get(name).map(|p| &p.data_type) {
            Some(PropertyType::Scalar(ScalarType::Float | ScalarType::Double)) => {}
            Some(other) => {
                return Err(format!(
                    "element vertex: property {name} is {other:?}, not float or double"
                ));
            }
            None => return Err(format!("element vertex: no property {name}")),
        }
    }
    let face = element("face")?;
    let list = INDEX_NAMES
        .iter()
        .find_map(|&name| face.properties.get(name))
        .ok_or("element face: no property vertex_indices (or vertex_index)")?;
    match &list.data_type {
        PropertyType::List(_, item) if !matches!(item, ScalarType::Float | ScalarType::Double) => Ok(()),
        other => Err(format!(
            "element face: property {} is {other:?}, not a list of integers",
            list.name
        )),
    }
}
