//! Reading PLY files (ascii, binary little and big endian) with `ply-rs-bw`.
//!
//! The `vertex` element gives the positions (`x y z`, float or double), and where the
//! header declares them the normals (`nx ny nz`) and texture coordinates (`u v`, `s t` or
//! `texture_u texture_v`, the names Mitsuba 3 reads), of any number type; the `face`
//! element gives the polygons (`vertex_indices` or `vertex_index`, a list of any integer
//! type). Other elements and properties are read past and ignored. Vertices and faces are
//! numbered from 0, as the file's indices count them.

use super::MeshData;
use super::check::{Problem, Triangulator, check_attributes, check_positions};
use super::source::Source;
use crate::error::{Error, Result};
use crate::vec3::Vec3;
use ply_rs_bw::parser::{ParseError, Parser, Reader};
use ply_rs_bw::ply::{ElementDef, Encoding, Header, Property, PropertyAccess, PropertyAccessResult};
use ply_rs_bw::ply::{PropertyType, ScalarType};
use std::io::ErrorKind;
use std::path::Path;

/// The names a face's index list goes by (the second is older, and still common).
const INDEX_NAMES: [&str; 2] = ["vertex_indices", "vertex_index"];

/// The texture coordinates' names, in the order they are looked for.
const UV_NAMES: [[&str; 2]; 3] = [["u", "v"], ["s", "t"], ["texture_u", "texture_v"]];

/// The names of the vertex properties read: position, normal, texture coordinates.
const VERTEX_NAMES: [&str; 12] = [
    "x",
    "y",
    "z",
    "nx",
    "ny",
    "nz",
    "u",
    "v",
    "s",
    "t",
    "texture_u",
    "texture_v",
];

/// A vertex's position, normal and texture coordinates, in the order of
/// [`VERTEX_NAMES`] (a texture coordinate under any of its names); other properties are
/// ignored.
struct Vertex([f64; 8]);

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Self([0.0; 8])
    }

    fn set_float(&mut self, name: &str, value: f32) -> PropertyAccessResult {
        self.set_double(name, f64::from(value))
    }

    fn set_double(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        match slot(name) {
            Some(i) => {
                self.0[i] = value;
                PropertyAccessResult::Set
            }
            None => PropertyAccessResult::Ignored,
        }
    }

    // Reached for the types not handled above: an integer normal or texture coordinate is
    // taken as its value; an integer position, or a list where a number belongs, is refused
    // (the header check rejects those first, with a clearer message).
    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        let value = match property {
            Property::Char(v) => f64::from(v),
            Property::UChar(v) => f64::from(v),
            Property::Short(v) => f64::from(v),
            Property::UShort(v) => f64::from(v),
            Property::Int(v) => f64::from(v),
            Property::UInt(v) => f64::from(v),
            _ => f64::NAN,
        };
        match slot(name) {
            Some(i) if i >= 3 && !value.is_nan() => {
                self.0[i] = value;
                PropertyAccessResult::Set
            }
            Some(_) => PropertyAccessResult::UnsupportedType,
            None => PropertyAccessResult::Ignored,
        }
    }
}

/// Where in a [`Vertex`] a property name goes, if it is read: `x y z` to 0–2, `nx ny nz`
/// to 3–5, a texture coordinate's first name to 6 and its second to 7.
fn slot(name: &str) -> Option<usize> {
    let i = VERTEX_NAMES.iter().position(|&a| a == name)?;
    Some(if i < 6 { i } else { 6 + (i - 6) % 2 })
}

/// A face's vertex indices, widened to `i64` so that any PLY integer type fits. A face of
/// up to four (nearly every face) is held in place: a million faces each in an allocation of
/// its own would leave their memory resident and fragmented after the load.
enum Face {
    Few(u8, [i64; 4]),
    Many(Vec<i64>),
}

impl Face {
    fn from_list<T: Copy + Into<i64>>(list: &[T]) -> Self {
        if list.len() <= 4 {
            let mut few = [0; 4];
            for (to, &from) in few.iter_mut().zip(list) {
                *to = from.into();
            }
            Self::Few(list.len() as u8, few)
        } else {
            Self::Many(list.iter().map(|&i| i.into()).collect())
        }
    }

    fn indices(&self) -> &[i64] {
        match self {
            Self::Few(len, few) => &few[..*len as usize],
            Self::Many(many) => many,
        }
    }
}

impl PropertyAccess for Face {
    fn new() -> Self {
        Self::Few(0, [0; 4])
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        if !INDEX_NAMES.contains(&name) {
            return PropertyAccessResult::Ignored;
        }
        *self = match property {
            Property::ListChar(v) => Self::from_list(&v),
            Property::ListUChar(v) => Self::from_list(&v),
            Property::ListShort(v) => Self::from_list(&v),
            Property::ListUShort(v) => Self::from_list(&v),
            Property::ListInt(v) => Self::from_list(&v),
            Property::ListUInt(v) => Self::from_list(&v),
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
    let mut reader = Reader::new(Source::open(path).map_err(fail)?);
    let header = Parser::<Skipped>::new()
        .read_header(&mut reader)
        .map_err(|e| fail(header_error(reader.get_ref(), &e)))?;
    check_header(&header).map_err(fail)?;
    if header.encoding != Encoding::Ascii {
        reader.get_mut().binary();
    }

    let (mut vertices, mut faces) = (Vec::new(), Vec::new());
    for element in header.elements.values() {
        let what = |e: ParseError, source: &Source| fail(payload_error(source, &header, element, &e));
        match element.name.as_str() {
            "vertex" => {
                vertices = Parser::<Vertex>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(|e| what(e, reader.get_ref()))?;
            }
            "face" => {
                faces = Parser::<Face>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(|e| what(e, reader.get_ref()))?;
            }
            _ => {
                Parser::<Skipped>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(|e| what(e, reader.get_ref()))?;
            }
        }
    }

    let positions: Vec<Vec3<f64>> = vertices
        .iter()
        .map(|Vertex(v)| Vec3::new(v[0], v[1], v[2]))
        .collect();
    let vertex = &header.elements["vertex"];
    let has = |name: &str| vertex.properties.contains_key(name);
    let normals = ["nx", "ny", "nz"].iter().all(|n| has(n)).then(|| {
        vertices
            .iter()
            .map(|Vertex(v)| Vec3::new(v[3], v[4], v[5]))
            .collect::<Vec<_>>()
    });
    let uv_names = UV_NAMES.into_iter().find(|pair| pair.iter().all(|n| has(n)));
    let uvs = uv_names.map(|_| vertices.iter().map(|Vertex(v)| [v[6], v[7]]).collect::<Vec<_>>());
    drop(vertices);
    let named = |problem: Problem| fail(problem.to_string());
    check_positions(&positions).map_err(named)?;
    check_attributes(
        normals.as_deref(),
        uvs.as_deref(),
        (["nx", "ny", "nz"], uv_names.unwrap_or(["u", "v"])),
    )
    .map_err(named)?;
    let mut mesh = Triangulator::new(positions);
    for (number, face) in faces.iter().enumerate() {
        mesh.add_face(number, face.indices().iter().copied())
            .map_err(named)?;
    }
    let mut mesh = mesh.finish().map_err(named)?;
    mesh.normals = normals;
    mesh.uvs = uvs;
    Ok(mesh)
}

/// Why the header could not be read, in words about the file that quote none of it (the
/// parser's own messages quote the offending line).
fn header_error(source: &Source, e: &ParseError) -> String {
    if let Some(why) = source.overlong() {
        return format!("bad PLY header: {why}");
    }
    let line = e.line().map_or(source.line(), |l| l as u64);
    match e.kind() {
        ErrorKind::UnexpectedEof => "bad PLY header: the file ends before `end_header`".into(),
        ErrorKind::InvalidData => format!("bad PLY header: line {line} is not text (UTF-8)"),
        _ if line <= 1 => "not a PLY file: the first line is not `ply`".into(),
        _ => format!(
            "bad PLY header: line {line} is not a header line (`format`, `element`, `property`, \
             `comment`, `obj_info` or `end_header`), or the format line is missing or repeated"
        ),
    }
}

/// Why `element`'s data could not be read: at a line of an ASCII file, at a byte of a
/// binary one; the file is not quoted.
fn payload_error(source: &Source, header: &Header, element: &ElementDef, e: &ParseError) -> String {
    let name = &element.name;
    if let Some(why) = source.overlong() {
        return format!("element {name}: {why}");
    }
    if e.kind() == ErrorKind::UnexpectedEof {
        let entries = if element.count == 1 { "entry" } else { "entries" };
        return format!(
            "element {name}: the file ends before the {} {entries} its header declares",
            element.count
        );
    }
    match header.encoding {
        Encoding::Ascii => format!(
            "element {name}: line {} does not hold the entry the header declares \
             (a number missing, malformed or out of its type's range)",
            source.line()
        ),
        _ => format!(
            "element {name}: malformed binary data before byte {} (a list longer than the file, \
             or a property of an unsupported type)",
            source.offset()
        ),
    }
}

/// A property's type as a PLY header writes it: `float`, `list uchar int`.
fn type_name(t: &PropertyType) -> String {
    let scalar = |s: &ScalarType| match s {
        ScalarType::Char => "char",
        ScalarType::UChar => "uchar",
        ScalarType::Short => "short",
        ScalarType::UShort => "ushort",
        ScalarType::Int => "int",
        ScalarType::UInt => "uint",
        ScalarType::Float => "float",
        ScalarType::Double => "double",
    };
    match t {
        PropertyType::Scalar(s) => scalar(s).into(),
        PropertyType::List(index, item) => format!("list {} {}", scalar(index), scalar(item)),
    }
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
                    "element vertex: property {name} is {}, not float or double",
                    type_name(other)
                ));
            }
            None => return Err(format!("element vertex: no property {name}")),
        }
    }
    // A normal's or a texture coordinate's component may be of any number type.
    for name in &VERTEX_NAMES[3..] {
        if let Some(PropertyType::List(..)) = vertex.properties.get(*name).map(|p| &p.data_type) {
            return Err(format!("element vertex: property {name} is a list, not a number"));
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
            "element face: property {} is {}, not a list of integers",
            list.name,
            type_name(other)
        )),
    }
}
