//! Textures: values that vary over a surface, looked up at a hit's surface coordinates, a
//! concept beside materials rather than inside them. A material's colour or roughness is a
//! [`Texture`]; a constant is the simplest one.
//!
//! The kinds are Mitsuba 3's: a constant, a [`Checkerboard`] (its `checkerboard`) and an
//! [`ImageTexture`] (its `bitmap`: PNG, JPEG, Radiance HDR or OpenEXR, filtered bilinearly,
//! repeated or clamped), each looked up at `uv` mapped by a [`UvMap`] (Mitsuba's `to_uv`
//! as a scale and an offset). A texture is cheap to clone and shared, not copied: the
//! checkerboard and the image texture sit behind an `Arc`, and an image's pixels
//! ([`Bitmap`]) behind another, so materials that use one file hold one copy of it.

mod bitmap;
mod checkerboard;
mod image_texture;
mod load;
mod rgbe;
mod uv;

pub use bitmap::{Bitmap, Decode, MAX_TEXTURE_PIXELS, srgb_to_linear};
pub use checkerboard::Checkerboard;
pub use image_texture::{ImageTexture, Wrap};
pub use uv::UvMap;

use crate::float::Float;
use crate::shape::Hit;
use crate::vec3::Color;
use std::sync::Arc;

/// A colour (or, read as a scalar, a number such as a roughness) over a surface.
///
/// Two words in `f32` (a colour or a pointer, and the kind), so materials can embed one.
#[derive(Clone, Debug, PartialEq)]
pub enum Texture<F> {
    /// The same value everywhere.
    Constant(Color<F>),
    /// Two colours in alternating squares of the `uv` plane.
    Checkerboard(Arc<Checkerboard<F>>),
    /// An image, filtered bilinearly.
    Image(Arc<ImageTexture<F>>),
}

impl<F: Float> Texture<F> {
    /// The same colour everywhere.
    pub fn constant(colour: Color<F>) -> Self {
        Self::Constant(colour)
    }

    /// The same number everywhere, in every channel.
    pub fn scalar(value: F) -> Self {
        Self::Constant(Color::splat(value))
    }

    /// The value at `hit`: at its [`uv`](Hit::uv), which the scene fills in when a
    /// material [reads coordinates](crate::Material::reads_coordinates).
    #[inline(always)]
    pub fn eval(&self, hit: &Hit<F>) -> Color<F> {
        match self {
            Self::Constant(c) => *c,
            _ => {
                // Written into a slot of this arm's own: returned, the value came back
                // through the slot the constant's path shares, in memory on every path.
                let mut value = Color::zero();
                self.eval_varying(hit.uv, &mut value);
                value
            }
        }
    }

    /// [`Texture::eval`] of the kinds that vary, out of line and given `uv` alone: the
    /// constant's path stays short, and a caller's hit need not be in memory.
    #[inline(never)]
    fn eval_varying(&self, uv: [F; 2], value: &mut Color<F>) {
        *value = match self {
            Self::Constant(c) => *c,
            Self::Checkerboard(c) => c.eval(uv),
            Self::Image(i) => i.eval(uv),
        };
    }

    /// The value at `hit` as one number: a constant's or a checkerboard's first channel (a
    /// scalar texture stores its value in every channel); an image's grey value, or for a
    /// colour image its luminance (`0.212671 R + 0.715160 G + 0.072169 B`), as Mitsuba 3's
    /// `eval_1` of a bitmap.
    #[inline]
    pub fn eval_scalar(&self, hit: &Hit<F>) -> F {
        match self {
            Self::Image(i) => i.eval_scalar(hit.uv),
            _ => self.eval(hit).x,
        }
    }

    /// The colour, if the texture is a constant.
    #[inline]
    pub fn as_constant(&self) -> Option<Color<F>> {
        match self {
            Self::Constant(c) => Some(*c),
            _ => None,
        }
    }

    /// Whether looking the texture up needs the hit's surface coordinates: what a material
    /// answers for [`reads_coordinates`](crate::Material::reads_coordinates).
    #[inline]
    pub fn reads_coordinates(&self) -> bool {
        self.as_constant().is_none()
    }

    /// The smallest and the largest value any channel can take anywhere (NaN never:
    /// every kind refuses it), for a material to check its range.
    pub fn range(&self) -> [f64; 2] {
        let of = |c: Color<F>| {
            let [r, g, b] = c.to_f64();
            [r.min(g).min(b), r.max(g).max(b)]
        };
        match self {
            Self::Constant(c) => of(*c),
            Self::Checkerboard(c) => {
                let ([lo0, hi0], [lo1, hi1]) = (of(c.color0()), of(c.color1()));
                [lo0.min(lo1), hi0.max(hi1)]
            }
            Self::Image(i) => i.bitmap().range().map(f64::from),
        }
    }

    /// This texture in scalar `G`: the colours and the `uv` map rounded through `f64`, an
    /// image's pixels shared, not copied.
    ///
    /// # Errors
    /// [`Error::InvalidValue`](crate::Error::InvalidValue) if a value does not survive the
    /// rounding (a colour beyond `G`'s range).
    pub fn cast<G: Float>(&self) -> crate::error::Result<Texture<G>> {
        Ok(match self {
            Self::Constant(c) => Texture::Constant(c.cast()),
            Self::Checkerboard(c) => Texture::Checkerboard(Arc::new(c.cast()?)),
            Self::Image(i) => Texture::Image(Arc::new(i.cast()?)),
        })
    }
}

impl<F> From<Color<F>> for Texture<F> {
    fn from(colour: Color<F>) -> Self {
        Self::Constant(colour)
    }
}

impl<F> From<Checkerboard<F>> for Texture<F> {
    fn from(c: Checkerboard<F>) -> Self {
        Self::Checkerboard(Arc::new(c))
    }
}

impl<F> From<ImageTexture<F>> for Texture<F> {
    fn from(i: ImageTexture<F>) -> Self {
        Self::Image(Arc::new(i))
    }
}
