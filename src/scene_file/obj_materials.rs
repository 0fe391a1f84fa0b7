//! A mesh object with `material = "mtl"`: an OBJ file's faces shaded with the materials of
//! its `.mtl` libraries, one mesh per material ([`crate::mesh::load_parts`]), each material
//! mapped as [`mtl_spec::map`] says and built with its images.

use super::SceneFile;
use super::build::{Attributes, mesh};
use super::check::vec;
use super::location::KeyPath;
use super::make;
use super::mtl_spec::{self, DIFFUSE_MAP};
use super::objects::ObjectSpec;
use super::placing::mesh_placement;
use super::resolve::{Inputs, TextureUse};
use super::summary::Summary;
use super::texture_spec::TextureRef;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::material::{MaterialKind, NormalMap};
use crate::mesh::{At, MtlMap, MtlMaterial};
use crate::scene::EnumScene;
use crate::texture::{Bitmap, Decode, ImageTexture, Texture, UvMap, Wrap};
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The `material` of a mesh object that takes its OBJ file's own materials.
pub const FROM_MTL: &str = "mtl";

/// Whether `object` is a mesh that takes its OBJ file's materials.
pub(super) fn wants_mtl(object: &ObjectSpec) -> bool {
    matches!(object, ObjectSpec::Mesh { material, .. } if material == FROM_MTL)
}

/// Adds the mesh object `object` (at `at`, with `material = "mtl"`) to `scene`: a mesh per
/// material its OBJ file's faces use, placed as the object says. `materials` are the
/// file's own, whose names must not include [`FROM_MTL`].
pub(super) fn add<F: Float>(
    scene: &mut EnumScene<F>,
    summary: &mut Summary,
    (root, at): (&KeyPath, &KeyPath),
    object: &ObjectSpec,
    (folder, materials): (&Path, &BTreeMap<&str, MaterialKind<F>>),
) -> Result<()> {
    let ObjectSpec::Mesh {
        file,
        scale,
        rotate,
        translate,
        face_normals,
        flip_tex_coords,
        matrix,
        ..
    } = object
    else {
        return Err(at
            .key("material")
            .error("only a mesh object takes its file's materials"));
    };
    if materials.contains_key(FROM_MTL) {
        return Err(at.key("material").error(format!(
            "`{FROM_MTL}` is both a [materials] entry and the name that takes an OBJ file's own \
             materials: rename the entry"
        )));
    }
    let path = folder.join(file);
    if !is_obj(&path) {
        return Err(at.key("material").error(format!(
            "`material = \"{FROM_MTL}\"` takes the materials an OBJ file's `usemtl` lines name; \
             {} is not an OBJ file",
            path.display()
        )));
    }
    let placement = mesh_placement((root, at), *scale, *rotate, *translate, *matrix)?;
    let attributes = Attributes::new(&path, *face_normals, *flip_tex_coords);
    let read = crate::mesh::load_parts(&path).map_err(|e| at.key("file").wrap(e))?;
    for library in &read.libraries {
        summary.notes.extend(not_read(&library.path, &library.ignored));
    }
    let mut bitmaps = HashMap::new();
    for part in read.parts {
        let made = Maps::read(&part.material, &mut bitmaps, &mut summary.notes)
            .and_then(|maps| material::<F>(&part.material, &maps, attributes.flip_v, &mut summary.notes))
            .map_err(|e| at.key("material").wrap(e))?;
        let mesh = mesh::<F>(root, at, &part.mesh, &placement, attributes, summary)?;
        scene.add(mesh, made);
    }
    Ok(())
}

/// Whether `path` names an OBJ file (by its extension, in any case).
fn is_obj(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}

/// The note for a library's keys that are not read: `a.mtl: not read: `Ka` (lines 3, 9)`.
fn not_read(library: &Path, ignored: &[At<String>]) -> Option<String> {
    let mut keys: Vec<(&str, Vec<String>)> = Vec::new();
    for At { value, line } in ignored {
        match keys.iter_mut().find(|(k, _)| k == value) {
            Some((_, lines)) => lines.push(line.to_string()),
            None => keys.push((value, vec![line.to_string()])),
        }
    }
    let listed: Vec<String> = keys
        .iter()
        .map(|(k, lines)| {
            let s = if lines.len() > 1 { "s" } else { "" };
            format!("`{k}` (line{s} {})", lines.join(", "))
        })
        .collect();
    (!listed.is_empty()).then(|| format!("{}: not read: {}", library.display(), listed.join(", ")))
}

/// The images a material uses, read once per file: its `map_Kd` as colour, its normal map
/// (`norm`, or a `map_Bump` in colour) as data.
struct Maps {
    diffuse: Option<(MtlMap, Arc<Bitmap>)>,
    normal: Option<(MtlMap, Arc<Bitmap>)>,
}

/// An error about the key `key` (on `line`) of the material `m`, naming its library.
fn mtl_error(m: &MtlMaterial, key: &str, line: u64, why: impl std::fmt::Display) -> Error {
    Error::Mesh {
        path: m.library.clone(),
        message: format!("line {line}: material `{}`: `{key}`: {why}", m.name),
    }
}

impl Maps {
    fn read(
        m: &MtlMaterial,
        bitmaps: &mut HashMap<(PathBuf, Decode), Arc<Bitmap>>,
        notes: &mut Vec<String>,
    ) -> Result<Self> {
        let mut load = |key: &str, map: &At<MtlMap>, decode| {
            let id = (map.value.file.clone(), decode);
            if let Some(b) = bitmaps.get(&id) {
                return Ok((map.value.clone(), Arc::clone(b)));
            }
            let bitmap = Arc::new(Bitmap::load(&id.0, decode).map_err(|e| mtl_error(m, key, map.line, e))?);
            bitmaps.insert(id, Arc::clone(&bitmap));
            Ok::<_, Error>((map.value.clone(), bitmap))
        };
        let note = |key: &str, line: u64, why: String| {
            format!(
                "{}: line {line}: material `{}`: `{key}` {why}",
                m.library.display(),
                m.name
            )
        };
        let diffuse = m
            .map_kd
            .as_ref()
            .map(|t| load("map_Kd", t, Decode::Color))
            .transpose()?;
        let normal = match (&m.norm, &m.bump) {
            (Some(norm), bump) => {
                if let Some(b) = bump {
                    notes.push(note(
                        "map_Bump",
                        b.line,
                        "is not used: `norm` gives the normal map".into(),
                    ));
                }
                Some(load("norm", norm, Decode::Raw)?)
            }
            (None, Some(bump)) => {
                let read = load("map_Bump", bump, Decode::Raw)?;
                if read.1.is_grey() {
                    // A height map: its slopes would perturb the normal, which this renderer does not do.
                    let why =
                        "is a height map (one channel), not a normal map: not used (no bump mapping here)";
                    notes.push(note("map_Bump", bump.line, why.into()));
                    None
                } else {
                    Some(read)
                }
            }
            (None, None) => None,
        };
        for t in [&m.norm, &m.bump].into_iter().flatten() {
            if let Some(bm) = t.value.bump_multiplier.filter(|&bm| bm != 1.0) {
                notes.push(note(
                    "-bm",
                    t.line,
                    format!("{bm} is not applied: a normal map bends at full strength"),
                ));
            }
        }
        Ok(Self { diffuse, normal })
    }
}

/// The material of `m` in `G`, its values checked in `f64` first (an error says which key
/// of the `.mtl` file, and whether only the rounding to `G` refused it).
fn material<G: Float>(
    m: &MtlMaterial,
    maps: &Maps,
    flip_v: bool,
    notes: &mut Vec<String>,
) -> Result<MaterialKind<G>> {
    let mapped = mtl_spec::map(m).map_err(|(key, why)| mtl_error(m, key.value, key.line, why))?;
    for (key, why) in &mapped.unused {
        notes.push(format!(
            "{}: line {}: material `{}`: `{}` is not used: {why}",
            m.library.display(),
            key.line,
            m.name,
            key.value
        ));
    }
    if let Err(e) = build_in::<f64>(&mapped.spec, maps, flip_v) {
        return Err(located(m, maps, e, ""));
    }
    build_in::<G>(&mapped.spec, maps, flip_v).map_err(|e| {
        let tail = format!(
            " in {0}: the value as written is valid in f64, but not once rounded to {0}",
            G::NAME
        );
        located(m, maps, e, &tail)
    })
}

/// A constructor's error at the `.mtl` key its field comes from.
fn located(m: &MtlMaterial, maps: &Maps, e: Error, tail: &str) -> Error {
    let Error::InvalidValue { field, reason } = e else {
        return e;
    };
    let line = |x: Option<u64>| x.unwrap_or(m.line);
    let of = |x: &Option<At<[f64; 3]>>| line(x.as_ref().map(|c| c.line));
    let (key, at) = match field {
        Field::MatteAlbedo | Field::DiffuseReflectance | Field::EmissiveAlbedo => match &m.map_kd {
            Some(t) if maps.diffuse.is_some() && field != Field::EmissiveAlbedo => ("map_Kd", t.line),
            _ => ("Kd", of(&m.kd)),
        },
        Field::SpecularReflectance => ("Ks", of(&m.ks)),
        Field::EmittedRadiance => ("Ke", of(&m.ke)),
        Field::DielectricAlbedo => ("Tf", of(&m.tf)),
        Field::RefractiveIndex | Field::InteriorIndex => ("Ni", line(m.ni.as_ref().map(|n| n.line))),
        Field::Alpha | Field::AlphaU | Field::AlphaV => ("Ns", line(m.ns.as_ref().map(|n| n.line))),
        // Every other field is the material's as a whole.
        _ => ("newmtl", m.line),
    };
    mtl_error(m, key, at, format!("{reason}{tail}"))
}

/// The mapped material `spec` in `G`, wrapped in the normal map if there is one.
fn build_in<G: Float>(
    spec: &super::model::MaterialSpec,
    maps: &Maps,
    flip_v: bool,
) -> Result<MaterialKind<G>> {
    let diffuse = match &maps.diffuse {
        Some((map, bitmap)) => Some(Texture::from(image::<G>(bitmap, map, flip_v)?)),
        None => None,
    };
    let base = make::material::<G>(spec, &mut MapInputs { diffuse })?;
    Ok(match &maps.normal {
        Some((map, bitmap)) => NormalMap::new(image::<G>(bitmap, map, flip_v)?, base).into(),
        None => base,
    })
}

/// The image texture of an MTL map: `-clamp`, and `-s`, `-o` as the MTL format means them,
/// for `v` counted up the image. With `flip_v` (an OBJ mesh's default) the mesh's `v'` is
/// `1 − v`, so the image is looked up at `s·v' + (1 − s − o)` down from its top row.
fn image<G: Float>(bitmap: &Arc<Bitmap>, map: &MtlMap, flip_v: bool) -> Result<ImageTexture<G>> {
    let ([su, sv], [ou, ov]) = (map.scale, map.offset);
    let ov = if flip_v { 1.0 - sv - ov } else { ov };
    let uv = UvMap::new([lit(su), lit(sv)], [lit(ou), lit(ov)])?;
    let wrap = if map.clamp { Wrap::Clamp } else { Wrap::Repeat };
    Ok(ImageTexture::new(Arc::clone(bitmap))
        .with_wrap(wrap)
        .with_uv_map(uv))
}

/// What a mapped material's keys name: colours, and its `map_Kd` by [`DIFFUSE_MAP`].
struct MapInputs<G> {
    diffuse: Option<Texture<G>>,
}

impl<G: Float> Inputs<G> for MapInputs<G> {
    fn texture(&mut self, key: &str, value: &TextureRef, _: TextureUse) -> Result<Texture<G>> {
        match (value, &self.diffuse) {
            (TextureRef::Color(c), _) => Ok(Texture::Constant(vec(*c))),
            (TextureRef::Named(name), Some(t)) if name == DIFFUSE_MAP => Ok(t.clone()),
            _ => Err(Error::invalid(
                Field::Custom("OBJ material"),
                format!("`{key}` names no image of the material"),
            )),
        }
    }

    fn material(&mut self, key: &str, name: &str) -> Result<MaterialKind<G>> {
        Err(Error::invalid(
            Field::Custom("OBJ material"),
            format!("`{key}` names `{name}`: an OBJ material names no other"),
        ))
    }

    fn blame(&self, _: &str, e: Error) -> Error {
        e
    }
}

/// For every mesh object whose one material covers an OBJ file that names materials with
/// `usemtl`: which object, which names, and how to use them.
pub(super) fn unused_usemtl(file: &SceneFile) -> Vec<String> {
    let folder = file.path().parent().unwrap_or(Path::new(""));
    let mut found = Vec::new();
    for (i, object) in file.objects.iter().enumerate() {
        let ObjectSpec::Mesh {
            file: mesh, material, ..
        } = object
        else {
            continue;
        };
        let path = folder.join(mesh);
        if material == FROM_MTL || !is_obj(&path) {
            continue;
        }
        // A file that cannot be read is the build's to report.
        let Ok(names) = crate::mesh::usemtl_names(&path) else {
            continue;
        };
        if !names.is_empty() {
            let named: Vec<String> = names.iter().take(8).map(|n| format!("`{n}`")).collect();
            let more = if names.len() > 8 { ", …" } else { "" };
            found.push(format!(
                "objects[{i}]: {} names {} material{} with `usemtl` ({}{more}), not used: \
                 `material = \"{material}\"` covers every face (`material = \"{FROM_MTL}\"` takes them)",
                path.display(),
                names.len(),
                if names.len() > 1 { "s" } else { "" },
                named.join(", ")
            ));
        }
    }
    found
}
