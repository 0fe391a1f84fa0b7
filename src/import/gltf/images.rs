//! A glTF material's textures as the renderer's image textures: each image decoded once
//! (an embedded one from its buffer view or `data:` URI, a file beside the glTF file),
//! then, where the material asks for more than the image itself, a bitmap derived from
//! it (the base colour times its factor, `α = (roughness·G)²` of the metallic-roughness
//! image's green channel, a normal map's `scale`), held in memory under a name the
//! material's texture keys give.

use super::container::{Opened, error};
use super::uri::{self, Uri};
use crate::error::Result;
use crate::material::microfacet::MIN_ALPHA;
use crate::scene_file::{Assets, TextureRef, TextureSpec, UvScale, WrapSpec};
use crate::texture::{Bitmap, Decode};
use ::gltf::texture::{TextureTransform, WrappingMode};
use std::collections::BTreeMap;
use std::sync::Arc;

/// What a material makes of an image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Derive {
    /// A colour (sRGB-decoded) times a factor per channel.
    Color([f64; 3]),
    /// A roughness `α = max((f·G)², α_min)`, `G` the green channel as data and `f` the
    /// roughness factor; grey.
    Alpha(f64),
    /// A tangent-space normal map (data), its `x` and `y` scaled by `s` as glTF's
    /// `normalTexture.scale` says: `n = normalize((2c − 1)·(s, s, 1))`, stored back as
    /// `(n + 1)/2`.
    Normal(f64),
}

/// The images of a glTF file, decoded on request and kept.
pub(super) struct Images<'g> {
    g: &'g Opened,
    /// The file's name, the start of every held image's name.
    file_name: String,
    /// Each image decoded, by its index and whether as data (`raw`).
    decoded: BTreeMap<(usize, bool), Arc<Bitmap>>,
}

impl<'g> Images<'g> {
    /// The images of `g`.
    pub(super) fn new(g: &'g Opened, file_name: String) -> Self {
        Self {
            g,
            file_name,
            decoded: BTreeMap::new(),
        }
    }

    /// Image `index` decoded as colour or (`raw`) data: read the first time, kept after.
    pub(super) fn decoded(&mut self, index: usize, raw: bool, sources: &mut Assets) -> Result<Arc<Bitmap>> {
        if let Some(b) = self.decoded.get(&(index, raw)) {
            return Ok(Arc::clone(b));
        }
        let decode = if raw { Decode::Raw } else { Decode::Color };
        let g = self.g;
        let at = format!("images[{index}]");
        let name = std::path::PathBuf::from(format!("{}#{at}", g.path.display()));
        let Some(image) = g.doc.images().nth(index) else {
            return Err(error(&g.path, at, "no such image"));
        };
        let bitmap = match image.source() {
            ::gltf::image::Source::View { view, .. } => {
                let buffer = &g.buffers[view.buffer().index()];
                let bytes = view
                    .offset()
                    .checked_add(view.length())
                    .and_then(|end| buffer.get(view.offset()..end))
                    .ok_or_else(|| {
                        error(
                            &g.path,
                            format!("{at}.bufferView"),
                            format!(
                                "bufferView {} runs past its buffer's {} bytes",
                                view.index(),
                                buffer.len()
                            ),
                        )
                    })?;
                Bitmap::decode(bytes, decode, &name)?
            }
            ::gltf::image::Source::Uri { uri, .. } => match uri::parse(uri) {
                Ok(Uri::Data { bytes, .. }) => Bitmap::decode(&bytes, decode, &name)?,
                Ok(Uri::File(relative)) => {
                    let file = g.path.parent().unwrap_or(std::path::Path::new("")).join(relative);
                    sources.add_source(&file);
                    Bitmap::load(&file, decode)?
                }
                Err(why) => return Err(error(&g.path, format!("{at}.uri"), why)),
            },
        };
        let bitmap = Arc::new(bitmap);
        self.decoded.insert((index, raw), Arc::clone(&bitmap));
        Ok(bitmap)
    }

    /// The texture of `texture` (read at texture coordinate set `set`, through `transform`)
    /// as `derive` makes it, for the key `role` of material `owner` (`materials[2]`): a texture in place naming a bitmap held in `assets`, with the
    /// sampler's wrap and the `KHR_texture_transform` scale and offset. What it cannot
    /// render as written (a mirrored wrap, a rotation, another texture coordinate set) is
    /// a warning naming it.
    pub(super) fn texture(
        &mut self,
        (texture, set, transform): (&::gltf::Texture, u32, Option<TextureTransform>),
        derive: Derive,
        (owner, role): (&str, &str),
        assets: &mut Assets,
        warnings: &mut Vec<String>,
    ) -> Result<TextureRef> {
        let image = texture.source().index();
        let raw = !matches!(derive, Derive::Color(_));
        let plain = self.decoded(image, raw, assets)?;
        let as_is = derive == Derive::Color([1.0; 3]) || derive == Derive::Normal(1.0);
        let name = match as_is {
            true => {
                let name = format!(
                    "{}#images/{image}{}",
                    self.file_name,
                    if raw { "/raw" } else { "" }
                );
                assets.insert_image(name.clone(), plain);
                name
            }
            false => {
                let name = format!("{}#{owner}/{role}", self.file_name);
                assets.insert_image(name.clone(), Arc::new(derived(&plain, derive)?));
                name
            }
        };
        let mut note = |what: String| warnings.push(format!("{owner}.{role}: {what}"));
        let sampler = texture.sampler();
        let wrap = match (sampler.wrap_s(), sampler.wrap_t()) {
            (WrappingMode::Repeat, WrappingMode::Repeat) => WrapSpec::Repeat,
            (WrappingMode::ClampToEdge, WrappingMode::ClampToEdge) => WrapSpec::Clamp,
            (s, t) => {
                note(format!(
                    "the sampler wraps {s:?} × {t:?}: rendered with Repeat on both axes"
                ));
                WrapSpec::Repeat
            }
        };
        let mut set = set;
        let (mut scale, mut offset) = ([1.0, 1.0], [0.0, 0.0]);
        if let Some(t) = transform {
            scale = t.scale().map(f64::from);
            offset = t.offset().map(f64::from);
            if t.rotation() != 0.0 {
                note(format!(
                    "KHR_texture_transform turns uv by {} rad: the turn is left out (scale and offset kept)",
                    t.rotation()
                ));
            }
            set = t.tex_coord().unwrap_or(set);
        }
        if set != 0 {
            note(format!(
                "reads TEXCOORD_{set}: TEXCOORD_0 is used (the only set read)"
            ));
        }
        Ok(TextureRef::Inline(Box::new(TextureSpec::Image {
            file: name,
            wrap,
            raw: Some(true),
            scale: UvScale::PerAxis(scale),
            offset,
        })))
    }
}

/// The bitmap `derive` makes of `plain`.
fn derived(plain: &Bitmap, derive: Derive) -> Result<Bitmap> {
    let map: Box<dyn Fn([f32; 3]) -> [f32; 3]> = match derive {
        Derive::Color(f) => Box::new(move |c: [f32; 3]| [0, 1, 2].map(|k| (f64::from(c[k]) * f[k]) as f32)),
        Derive::Alpha(f) => Box::new(move |c: [f32; 3]| {
            let r = f64::from(c[1]) * f;
            [(r * r).max(MIN_ALPHA) as f32; 3]
        }),
        Derive::Normal(s) => Box::new(move |c: [f32; 3]| {
            let n = [0, 1, 2].map(|k| (2.0 * f64::from(c[k]) - 1.0) * if k < 2 { s } else { 1.0 });
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            // A zero normal stays the map's "no change" (0.5, 0.5, 1) rather than NaN.
            if len > 0.0 && len.is_finite() {
                n.map(|x| ((x / len + 1.0) / 2.0) as f32)
            } else {
                [0.5, 0.5, 1.0]
            }
        }),
    };
    let pixels = plain.pixels().iter().map(|&c| map(c)).collect();
    Bitmap::from_rgb(plain.width(), plain.height(), pixels)
}

/// The mean of each channel of `bitmap` (linear), as the renderer reads it.
pub(super) fn mean(bitmap: &Bitmap) -> [f64; 3] {
    let mut sum = [0.0f64; 3];
    for p in bitmap.pixels() {
        for k in 0..3 {
            sum[k] += f64::from(p[k]);
        }
    }
    let n = bitmap.pixels().len().max(1) as f64;
    sum.map(|s| s / n)
}
