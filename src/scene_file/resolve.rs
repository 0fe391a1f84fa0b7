//! What a material's keys name: textures (`[textures.NAME]` or in place, their images
//! loaded once per file) and, for a material that wraps another, that material.

use super::SceneFile;
use super::check::{blame, checked, vec};
use super::location::KeyPath;
use super::make;
use super::texture_spec::{TextureRef, TextureSpec, UvScale, WrapSpec};
use crate::error::{Error, Result};
use crate::float::{Float, lit};
use crate::material::MaterialKind;
use crate::texture::{Bitmap, Checkerboard, Decode, ImageTexture, Texture, UvMap, Wrap};
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// What a texture is used as, which decides how an image in it is read when its `raw` is
/// unset: sRGB-decoded for a colour, as data for a normal map.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureUse {
    /// A colour (an albedo).
    Color,
    /// A normal map.
    NormalMap,
}

/// The textures and materials a material's keys refer to, made on request.
pub trait Inputs<G: Float> {
    /// The texture `value` of the key `key`, used as `usage`.
    fn texture(&mut self, key: &str, value: &TextureRef, usage: TextureUse) -> Result<Texture<G>>;
    /// The material named by the value of the key `key`.
    fn material(&mut self, key: &str, name: &str) -> Result<MaterialKind<G>>;
    /// `e`, an error of what the table at the key `key` made, placed at that table (a
    /// library error at its field's own key there).
    fn blame(&self, key: &str, e: Error) -> Error;
}

/// The inputs of the table at the key `.0` inside a material's entry (a two-sided
/// material's `front`): every key it names is under that one.
pub struct Within<'i, G>(pub &'i mut dyn Inputs<G>, pub &'static str);

impl<G: Float> Inputs<G> for Within<'_, G> {
    fn texture(&mut self, key: &str, value: &TextureRef, usage: TextureUse) -> Result<Texture<G>> {
        self.0.texture(&format!("{}.{key}", self.1), value, usage)
    }

    fn material(&mut self, key: &str, name: &str) -> Result<MaterialKind<G>> {
        self.0.material(&format!("{}.{key}", self.1), name)
    }

    fn blame(&self, key: &str, e: Error) -> Error {
        self.0.blame(&format!("{}.{key}", self.1), e)
    }
}

/// Makes a file's materials and their textures, each image file read once.
pub struct Resolver<'a> {
    file: &'a SceneFile,
    root: KeyPath<'a>,
    folder: &'a Path,
    bitmaps: HashMap<(PathBuf, Decode), Arc<Bitmap>>,
}

impl<'a> Resolver<'a> {
    /// A resolver for `file`, whose paths are relative to `folder`.
    pub fn new(file: &'a SceneFile, folder: &'a Path) -> Self {
        Self {
            file,
            root: KeyPath::root(file.path()),
            folder,
            bitmaps: HashMap::new(),
        }
    }

    /// Every `[textures]` entry made once in `G`, used or not, so that a broken one is
    /// reported either way.
    pub fn check_textures<G: Float>(&mut self) -> Result<()> {
        for (name, spec) in &self.file.textures {
            let at = self.root.key("textures").key(name);
            self.made::<G>(&at, spec, TextureUse::Color)?;
        }
        Ok(())
    }

    /// Every `[materials]` entry in `G`, by name.
    pub fn materials<G: Float>(&mut self) -> Result<BTreeMap<&'a str, MaterialKind<G>>> {
        let mut made = BTreeMap::new();
        for name in self.file.materials.keys() {
            made.insert(name.as_str(), self.material::<G>(name, &mut Vec::new())?);
        }
        Ok(made)
    }

    /// The material `name` in `G`, checked in `f64` first; `within` names the materials
    /// that wrap it, outermost first (a name among them is a circle).
    fn material<G: Float>(&mut self, name: &str, within: &mut Vec<String>) -> Result<MaterialKind<G>> {
        let file = self.file;
        let spec = &file.materials[name];
        let at = self.root.key("materials").key(name);
        within.push(name.to_owned());
        let exact = make::material::<f64>(spec, &mut Named(self, &at, within));
        let rounded = make::material::<G>(spec, &mut Named(self, &at, within));
        within.pop();
        checked::<G, _>(&self.root, &at, exact, rounded)
    }

    /// The texture `value` at `at` in `G`.
    fn texture<G: Float>(
        &mut self,
        at: &KeyPath,
        value: &TextureRef,
        usage: TextureUse,
    ) -> Result<Texture<G>> {
        match value {
            // A colour is checked by the material that takes it.
            TextureRef::Color(c) => Ok(Texture::Constant(vec(*c))),
            TextureRef::Named(name) => {
                let Some(spec) = self.file.textures.get(name) else {
                    return Err(at.error(unknown("texture", name, self.file.textures.keys(), "textures")));
                };
                let entry = self.root.key("textures").key(name);
                self.made::<G>(&entry, spec, usage)
            }
            TextureRef::Inline(spec) => self.made::<G>(at, spec, usage),
        }
    }

    /// The texture `spec`, written at `at`, in `G`, its values checked in `f64` first.
    fn made<G: Float>(&mut self, at: &KeyPath, spec: &TextureSpec, usage: TextureUse) -> Result<Texture<G>> {
        match spec {
            TextureSpec::Checkerboard {
                color0,
                color1,
                scale,
                offset,
            } => {
                let exact = checkerboard::<f64>(*color0, *color1, *scale, *offset);
                let rounded = checkerboard::<G>(*color0, *color1, *scale, *offset);
                checked::<G, _>(&self.root, at, exact, rounded).map(Texture::from)
            }
            TextureSpec::Image {
                file,
                wrap,
                raw,
                scale,
                offset,
            } => {
                let raw = raw.unwrap_or(usage == TextureUse::NormalMap);
                let decode = if raw { Decode::Raw } else { Decode::Color };
                let bitmap = self.bitmap(at, file, decode)?;
                let exact = image::<f64>(&bitmap, *wrap, *scale, *offset);
                let rounded = image::<G>(&bitmap, *wrap, *scale, *offset);
                checked::<G, _>(&self.root, at, exact, rounded).map(Texture::from)
            }
        }
    }

    /// The pixels of `file`: an image held in memory ([`Assets`](super::Assets)) as it is,
    /// else the file (relative to the scene file's folder) read as `decode` says, loaded
    /// the first time and shared after.
    fn bitmap(&mut self, at: &KeyPath, file: &str, decode: Decode) -> Result<Arc<Bitmap>> {
        // An importer's image is held decoded already.
        if let Some(held) = self.file.assets().image(file) {
            return Ok(Arc::clone(held));
        }
        let path = self.folder.join(file);
        let key = (path, decode);
        if let Some(b) = self.bitmaps.get(&key) {
            return Ok(Arc::clone(b));
        }
        let bitmap = Arc::new(Bitmap::load(&key.0, decode).map_err(|e| at.key("file").wrap(e))?);
        self.bitmaps.insert(key, Arc::clone(&bitmap));
        Ok(bitmap)
    }
}

/// The checkerboard of a file's numbers in `G`.
fn checkerboard<G: Float>(
    color0: [f64; 3],
    color1: [f64; 3],
    scale: UvScale,
    offset: [f64; 2],
) -> Result<Checkerboard<G>> {
    Ok(Checkerboard::new(vec(color0), vec(color1))?.with_uv_map(uv_map(scale, offset)?))
}

/// The image texture of `bitmap` with a file's wrap, scale and offset in `G`.
fn image<G: Float>(
    bitmap: &Arc<Bitmap>,
    wrap: WrapSpec,
    scale: UvScale,
    offset: [f64; 2],
) -> Result<ImageTexture<G>> {
    let wrap = match wrap {
        WrapSpec::Repeat => Wrap::Repeat,
        WrapSpec::Clamp => Wrap::Clamp,
    };
    Ok(ImageTexture::new(Arc::clone(bitmap))
        .with_wrap(wrap)
        .with_uv_map(uv_map(scale, offset)?))
}

fn uv_map<G: Float>(scale: UvScale, offset: [f64; 2]) -> Result<UvMap<G>> {
    UvMap::new(scale.factors().map(lit), offset.map(lit))
}

/// `no KIND named `NAME` (the file defines `a`, `b`)`, or that the file defines none.
pub fn unknown<'k>(kind: &str, name: &str, known: impl Iterator<Item = &'k String>, section: &str) -> String {
    let names: Vec<_> = known.map(|k| format!("`{k}`")).collect();
    if names.is_empty() {
        format!("no {kind} named `{name}`: the file defines no [{section}]")
    } else {
        format!("no {kind} named `{name}` (the file defines {})", names.join(", "))
    }
}

/// A resolver at the material entry `at`, inside the wrappers `within`.
struct Named<'r, 'a, 'k>(&'r mut Resolver<'a>, &'r KeyPath<'k>, &'r mut Vec<String>);

impl<G: Float> Inputs<G> for Named<'_, '_, '_> {
    fn texture(&mut self, key: &str, value: &TextureRef, usage: TextureUse) -> Result<Texture<G>> {
        self.0.texture::<G>(&self.1.key(key), value, usage)
    }

    fn material(&mut self, key: &str, name: &str) -> Result<MaterialKind<G>> {
        let at = self.1.key(key);
        let file = self.0.file;
        if !file.materials.contains_key(name) {
            return Err(at.error(unknown("material", name, file.materials.keys(), "materials")));
        }
        if let Some(start) = self.2.iter().position(|n| n == name) {
            let circle: Vec<_> = self.2[start..].iter().map(|n| format!("`{n}`")).collect();
            return Err(at.error(format!(
                "the materials {} → `{name}` wrap one another in a circle",
                circle.join(" → ")
            )));
        }
        self.0.material::<G>(name, self.2)
    }

    fn blame(&self, key: &str, e: Error) -> Error {
        blame(&self.0.root, &self.1.key(key), e)
    }
}
