//! An OBJ file split by material: each `usemtl` name's faces as a mesh of their own, with
//! the material its `.mtl` library (`mtllib`) defines.
//!
//! The faces are numbered as the OBJ reader numbers them (every `f` and `l` line, in the
//! file's order), so a text scan of the `mtllib`, `usemtl`, `f` and `l` lines says which
//! material each of the mesh's faces has.

use super::MeshData;
use super::mtl::{self, At, MtlLibrary, MtlMaterial};
use super::obj;
use super::source::Source;
use crate::error::{Error, Result};
use crate::vec3::Vec3;
use std::collections::HashMap;
use std::io::BufRead;
use std::path::{Path, PathBuf};

/// One material's share of an OBJ file.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjPart {
    /// The material its faces' `usemtl` names.
    pub material: MtlMaterial,
    /// Those faces, with the vertices they use (the first part also counts the file's
    /// faces skipped for having no area).
    pub mesh: MeshData,
}

/// An OBJ file read with its materials.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjParts {
    /// A part per material the faces use, in the order of their first `usemtl`; a material
    /// whose faces all lack area has none.
    pub parts: Vec<ObjPart>,
    /// The material libraries read, with the keys they hold that are not read.
    pub libraries: Vec<MtlLibrary>,
}

/// No `usemtl` before the face.
const NONE: u32 = u32::MAX;

/// What a text scan of an OBJ file finds about its materials.
#[derive(Debug, Default)]
struct Scan {
    /// The `mtllib` lines: each file named, as written.
    libraries: Vec<At<String>>,
    /// Each name `usemtl` gives, once, with its first line.
    names: Vec<At<String>>,
    /// Per face, the index of its `usemtl` name in `names`, or [`NONE`].
    faces: Vec<u32>,
    /// The first face before any `usemtl`: its number (from 1) and line.
    bare: Option<At<usize>>,
}

/// Loads the OBJ file at `path` split by the material of each face.
///
/// # Errors
/// [`Error::Mesh`] as [`load`](super::load) gives for the geometry, and, naming the file and
/// line: a face before any `usemtl`, a `usemtl` without a name or naming a material no
/// library defines, a library that cannot be read or is malformed ([`mtl::read`]'s errors,
/// naming the `.mtl` file), a material defined by two libraries, or no `mtllib` at all.
pub fn load_parts(path: &Path) -> Result<ObjParts> {
    let fail = |message: String| Error::Mesh {
        path: path.to_path_buf(),
        message,
    };
    let (mesh, starts) = obj::load_faces(path)?;
    let scan = scan(path)?;
    if let Some(At { value: face, line }) = scan.bare {
        return Err(fail(format!(
            "line {line}: face {face} comes before any `usemtl`: taking the file's materials, \
             every face needs one"
        )));
    }
    if scan.faces.len() + 1 != starts.len() {
        return Err(fail(format!(
            "the material scan found {} faces, the mesh reader {}",
            scan.faces.len(),
            starts.len() - 1
        )));
    }
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut libraries: Vec<MtlLibrary> = Vec::new();
    for At { value: name, line } in &scan.libraries {
        let file = folder.join(name.replace('\\', "/"));
        let library = mtl::read(&file).map_err(|e| match e {
            Error::Mesh { path, message } if message.starts_with("cannot open") => fail(format!(
                "line {line}: `mtllib {name}`: {}: {message}",
                path.display()
            )),
            other => other,
        })?;
        for m in &library.materials {
            if let Some(first) = libraries
                .iter()
                .find(|l| l.materials.iter().any(|n| n.name == m.name))
            {
                return Err(fail(format!(
                    "line {line}: material `{}` is defined in {} and in {}",
                    m.name,
                    first.path.display(),
                    file.display()
                )));
            }
        }
        libraries.push(library);
    }
    let find = |name: &str| {
        libraries
            .iter()
            .flat_map(|l| &l.materials)
            .find(|m| m.name == name)
    };
    let mut materials = Vec::with_capacity(scan.names.len());
    for At { value: name, line } in &scan.names {
        let Some(m) = find(name) else {
            let known: Vec<_> = libraries
                .iter()
                .flat_map(|l| &l.materials)
                .map(|m| format!("`{}`", m.name))
                .collect();
            let why = if scan.libraries.is_empty() {
                "the file names no material library (`mtllib`)".to_string()
            } else if known.is_empty() {
                "its libraries define no material".to_string()
            } else {
                format!("its libraries define {}", known.join(", "))
            };
            return Err(fail(format!(
                "line {line}: `usemtl {name}`: no such material: {why}"
            )));
        };
        materials.push(m.clone());
    }
    // Each face's triangles go to its material's part, in the file's order.
    let mut triangles: Vec<Vec<u32>> = vec![Vec::new(); materials.len()];
    for (face, &name) in scan.faces.iter().enumerate() {
        triangles[name as usize].extend(starts[face]..starts[face + 1]);
    }
    let mut parts = Vec::new();
    for (material, triangles) in materials.into_iter().zip(triangles) {
        if !triangles.is_empty() {
            let mut part = subset(&mesh, &triangles);
            if parts.is_empty() {
                part.skipped_degenerate = mesh.skipped_degenerate;
            }
            parts.push(ObjPart { material, mesh: part });
        }
    }
    Ok(ObjParts { parts, libraries })
}

/// The names the OBJ file's `usemtl` lines give, each once, in order: what a mesh object
/// that covers the file with one material leaves unused.
///
/// # Errors
/// [`Error::Mesh`] if the file cannot be read as text.
pub fn usemtl_names(path: &Path) -> Result<Vec<String>> {
    Ok(scan(path)?.names.into_iter().map(|n| n.value).collect())
}

/// The files an OBJ file's materials are read from, those that exist: its `.mtl`
/// libraries, then the images each names (`map_Kd`, `map_Bump`, `norm`), each once. For
/// the list of a scene's inputs; reading the materials reports what is missing.
pub fn material_files(path: &Path) -> Vec<PathBuf> {
    let folder = path.parent().unwrap_or(Path::new(""));
    let Ok(found) = scan(path) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = Vec::new();
    let mut add = |file: PathBuf| {
        if file.is_file() && !files.contains(&file) {
            files.push(file);
        }
    };
    for library in found.libraries {
        let file = folder.join(library.value.replace('\\', "/"));
        let Ok(read) = mtl::read(&file) else {
            continue;
        };
        add(file);
        for m in read.materials {
            for map in [m.map_kd, m.bump, m.norm].into_iter().flatten() {
                add(map.value.file);
            }
        }
    }
    files
}

/// Reads the OBJ file's `mtllib`, `usemtl`, `f` and `l` lines.
fn scan(path: &Path) -> Result<Scan> {
    let fail = |message: String| Error::Mesh {
        path: path.to_path_buf(),
        message,
    };
    let mut source = Source::open(path).map_err(fail)?;
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut found = Scan::default();
    let mut current = NONE;
    let mut text = String::new();
    loop {
        text.clear();
        let read = source.read_line(&mut text).map_err(|_| {
            fail(
                source
                    .overlong()
                    .unwrap_or_else(|| format!("line {}: cannot be read as text (UTF-8)", source.line())),
            )
        })?;
        if read == 0 {
            return Ok(found);
        }
        let line = source.line();
        let mut words = text.split_whitespace();
        match words.next() {
            Some("f" | "l") => {
                if current == NONE && found.bare.is_none() {
                    let face = found.faces.len() + 1;
                    found.bare = Some(At { value: face, line });
                }
                found.faces.push(current);
            }
            Some("usemtl") => {
                let name = words.collect::<Vec<_>>().join(" ");
                if name.is_empty() {
                    return Err(fail(format!("line {line}: `usemtl` without a name")));
                }
                current = match found.names.iter().position(|n| n.value == name) {
                    Some(k) => k as u32,
                    None => {
                        found.names.push(At { value: name, line });
                        (found.names.len() - 1) as u32
                    }
                };
            }
            Some("mtllib") => {
                // One file whose name has spaces, or several names.
                let words: Vec<&str> = words.collect();
                let whole = words.join(" ");
                let names = if words.len() > 1 && !folder.join(&whole).is_file() {
                    words.iter().map(|w| w.to_string()).collect()
                } else {
                    vec![whole]
                };
                for value in names.into_iter().filter(|n| !n.is_empty()) {
                    if !found.libraries.iter().any(|l| l.value == value) {
                        found.libraries.push(At { value, line });
                    }
                }
            }
            _ => {}
        }
    }
}

/// The mesh of `triangles` (indices into `mesh.triangles`) alone: the vertices they use,
/// in the order first used, with their normals and texture coordinates.
fn subset(mesh: &MeshData, triangles: &[u32]) -> MeshData {
    let mut index: HashMap<u32, u32> = HashMap::new();
    let mut kept: Vec<u32> = Vec::new();
    let mut renumber = |v: u32| {
        *index.entry(v).or_insert_with(|| {
            kept.push(v);
            (kept.len() - 1) as u32
        })
    };
    let part: Vec<[u32; 3]> = triangles
        .iter()
        .map(|&t| mesh.triangles[t as usize].map(&mut renumber))
        .collect();
    let pick = |all: &Vec<Vec3<f64>>| kept.iter().map(|&v| all[v as usize]).collect();
    MeshData {
        positions: pick(&mesh.positions),
        normals: mesh.normals.as_ref().map(pick),
        uvs: mesh
            .uvs
            .as_ref()
            .map(|uvs| kept.iter().map(|&v| uvs[v as usize]).collect()),
        triangles: part,
        skipped_degenerate: 0,
    }
}

#[cfg(test)]
mod tests;
