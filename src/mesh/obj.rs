//! Reading Wavefront OBJ files with `tobj`.
//!
//! Positions, faces, normals (`vn`) and texture coordinates (`vt`) are read, through
//! `tobj`'s single-index loading: each distinct `v/vt/vn` triple a face uses becomes one
//! vertex. Materials (`mtllib`, `usemtl`) are dropped here, so a missing `.mtl` file is no
//! error; [`super::obj_parts`] reads them when asked. Every object and group of the file
//! goes into one mesh. `l` lines count as
//! faces, as `tobj` reads them.

use super::MeshData;
use super::check::{Problem, Triangulator, check_attributes, check_positions};
use super::source::Source;
use crate::error::{Error, Result};
use crate::vec3::Vec3;
use std::io::BufRead;
use std::path::Path;

/// Loads an OBJ mesh.
pub(super) fn load(path: &Path) -> Result<MeshData> {
    load_faces(path).map(|(mesh, _)| mesh)
}

/// Loads an OBJ mesh, with where each face's triangles start: face `k` (the `k`-th `f` or
/// `l` line, from 0) became the triangles `starts[k]..starts[k + 1]` (none if degenerate).
pub(super) fn load_faces(path: &Path) -> Result<(MeshData, Vec<u32>)> {
    let fail = |message: String| Error::Mesh {
        path: path.to_path_buf(),
        message,
    };
    let mut source = Source::open(path).map_err(fail)?;
    // Faces are kept whole (no `triangulate`) so that they can be checked and numbered as in
    // the file, then split into fans by the same code as PLY's.
    let options = tobj::LoadOptions {
        triangulate: false,
        single_index: true,
        ignore_points: false,
        ignore_lines: false,
    };
    let no_materials = |_: &Path| Ok(Default::default());
    let (models, _) = tobj::load_obj_buf(&mut source, &options, no_materials).map_err(|e| match e {
        tobj::LoadError::FaceVertexOutOfBounds => fail(locate(path, &e.to_string())),
        // tobj reads line by line and stops at the line it cannot take: the source's line.
        tobj::LoadError::ReadError => fail(
            source
                .overlong()
                .unwrap_or_else(|| format!("line {}: cannot be read as text (UTF-8)", source.line())),
        ),
        _ => fail(format!("line {}: cannot parse ({e})", source.line())),
    })?;

    // tobj keeps, per model, the vertices its faces use, in the order they are first used; the
    // models' vertices are put one after the other and their indices offset to match.
    let mut positions = Vec::new();
    let (mut normals, mut uvs) = (Attribute::new(Vec3::zero()), Attribute::new([0.0; 2]));
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for model in &models {
        let mesh = &model.mesh;
        let offset = u32::try_from(positions.len()).map_err(|_| fail(too_many()))?;
        let count = mesh.positions.len() / 3;
        positions.extend(
            mesh.positions
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0], p[1], p[2])),
        );
        let partial = |what: &str| {
            fail(format!(
                "object `{}`: some of its faces' vertices have {what} and others have none; \
                 give every vertex of an object one, or none",
                model.name
            ))
        };
        normals
            .extend(offset as usize, count, &mesh.normals, 3, |n| {
                Vec3::new(n[0], n[1], n[2])
            })
            .map_err(|()| partial("normals (`vn`)"))?;
        uvs.extend(offset as usize, count, &mesh.texcoords, 2, |t| [t[0], t[1]])
            .map_err(|()| partial("texture coordinates (`vt`)"))?;
        let arities = if mesh.face_arities.is_empty() {
            vec![3; mesh.indices.len() / 3]
        } else {
            mesh.face_arities.clone()
        };
        let mut rest = mesh.indices.as_slice();
        for arity in arities {
            let (face, tail) = rest.split_at(arity as usize);
            faces.push(face.iter().map(|&i| i + offset).collect());
            rest = tail;
        }
    }
    if u32::try_from(positions.len()).is_err() {
        return Err(fail(too_many()));
    }
    let (normals, uvs) = (normals.finish(positions.len()), uvs.finish(positions.len()));

    // tobj's numbering of vertices is not the file's, so a problem is located in the text.
    let located = |problem: Problem| fail(locate(path, &problem.to_string()));
    check_positions(&positions).map_err(located)?;
    check_attributes(
        normals.as_deref(),
        uvs.as_deref(),
        (["vn x", "vn y", "vn z"], ["vt u", "vt v"]),
    )
    .map_err(located)?;
    let mut mesh = Triangulator::new(positions);
    let mut starts = Vec::with_capacity(faces.len() + 1);
    for (number, face) in faces.into_iter().enumerate() {
        starts.push(mesh.triangles());
        mesh.add_face(number, face.into_iter().map(i64::from))
            .map_err(located)?;
    }
    starts.push(mesh.triangles());
    let mut mesh = mesh.finish().map_err(|p| fail(p.to_string()))?;
    mesh.normals = normals;
    mesh.uvs = uvs;
    Ok((mesh, starts))
}

/// The message for a mesh whose vertices cannot be indexed by `u32`.
fn too_many() -> String {
    format!("more than {} vertices", u32::MAX)
}

/// Finds the first line of the OBJ file at `path` with a non-finite coordinate (of a
/// position, a normal or a texture coordinate), a face of
/// fewer than three vertices or a vertex index out of range, and describes it with its line
/// number and the file's numbering (from 1, as OBJ indices count); `fallback` if none is found.
fn locate(path: &Path, fallback: &str) -> String {
    let Ok(source) = Source::open(path) else {
        return fallback.to_owned();
    };
    let lines: Vec<String> = source.lines().map_while(|l| l.ok()).collect();
    let vertices = lines
        .iter()
        .filter(|l| l.split_whitespace().next() == Some("v"))
        .count();
    let (mut vertex, mut face) = (0, 0);
    for (number, line) in lines.iter().enumerate() {
        let mut words = line.split_whitespace();
        let line = number + 1;
        match words.next() {
            Some("v") => {
                vertex += 1;
                for (axis, word) in ['x', 'y', 'z'].into_iter().zip(words) {
                    if let Ok(value) = word.parse::<f64>()
                        && !value.is_finite()
                    {
                        let problem = Problem::NonFinite { vertex, axis, value };
                        return format!("line {line}: {problem}");
                    }
                }
            }
            Some(kind @ ("vn" | "vt")) => {
                let what = if kind == "vn" {
                    "normal"
                } else {
                    "texture coordinate"
                };
                if let Some(value) = words
                    .filter_map(|w| w.parse::<f64>().ok())
                    .find(|v| !v.is_finite())
                {
                    return format!("line {line}: a {what} ({kind}) is {value}: not finite");
                }
            }
            Some("f" | "l") => {
                face += 1;
                let problem = face_problem(words, face, vertex, vertices);
                if let Some(problem) = problem {
                    return format!("line {line}: {problem}");
                }
            }
            _ => {}
        }
    }
    fallback.to_owned()
}

/// What is wrong with face number `face`, whose vertex references are `words`, when
/// `defined` vertices precede it (negative indices count back from there) and the file has
/// `vertices`.
fn face_problem<'a>(
    words: impl Iterator<Item = &'a str>,
    face: usize,
    defined: usize,
    vertices: usize,
) -> Option<Problem> {
    let indices: Vec<i64> = words.filter_map(|w| w.split('/').next()?.parse().ok()).collect();
    if indices.len() < 3 {
        return Some(Problem::TooFewVertices {
            face,
            count: indices.len(),
        });
    }
    let defined = i64::try_from(defined).unwrap_or(i64::MAX);
    let vertices_i = i64::try_from(vertices).unwrap_or(i64::MAX);
    indices.into_iter().find_map(|index| {
        let resolved = if index < 0 { defined + index + 1 } else { index };
        (!(1..=vertices_i).contains(&resolved)).then_some(Problem::IndexOutOfRange {
            face,
            index,
            vertices,
        })
    })
}

/// A per-vertex attribute (normals, texture coordinates) gathered model after model: a
/// model without any gets zeros if another has some (as Mitsuba 3's OBJ reader gives
/// zeros to a vertex without them).
struct Attribute<T> {
    values: Vec<T>,
    zero: T,
    /// Whether any model had the attribute.
    seen: bool,
}

impl<T: Copy> Attribute<T> {
    fn new(zero: T) -> Self {
        Self {
            values: Vec::new(),
            zero,
            seen: false,
        }
    }

    /// Adds a model's `count` vertices, which start at vertex `start`: from `flat`, `width`
    /// numbers each, or nothing if it has none; `Err` if it has some but not one per
    /// vertex.
    fn extend(
        &mut self,
        start: usize,
        count: usize,
        flat: &[f64],
        width: usize,
        make: impl Fn(&[f64]) -> T,
    ) -> Result<(), ()> {
        if flat.is_empty() {
            return Ok(());
        }
        if flat.len() != count * width {
            return Err(());
        }
        self.seen = true;
        self.values.resize(start, self.zero);
        self.values.extend(flat.chunks_exact(width).map(make));
        Ok(())
    }

    /// The values of all `vertices` (zeros for the models that had none); `None` if no
    /// model had any.
    fn finish(mut self, vertices: usize) -> Option<Vec<T>> {
        self.values.resize(vertices, self.zero);
        self.seen.then_some(self.values)
    }
}
