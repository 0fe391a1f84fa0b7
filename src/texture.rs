//! Textures: values that vary over a surface, looked up at a hit's surface coordinates
//! (or its point), a concept beside materials rather than inside them. A material's
//! colour or roughness is a [`Texture`]; a constant is the simplest one.
//!
//! A texture is cheap to clone and shared, not copied: image data sits behind an `Arc`.

use crate::float::Float;
use crate::shape::Hit;
use crate::vec3::Color;

/// A colour (or, read as a scalar, a number such as a roughness) over a surface.
#[derive(Clone, Debug, PartialEq)]
pub enum Texture<F> {
    /// The same value everywhere.
    Constant(Color<F>),
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

    /// The value at `hit` (its [`uv`](Hit::uv), filled in when a material
    /// [reads coordinates](crate::Material::reads_coordinates), or its point).
    #[inline]
    pub fn eval(&self, hit: &Hit<F>) -> Color<F> {
        let _ = hit;
        match self {
            Self::Constant(c) => *c,
        }
    }

    /// The value at `hit` as one number: the first channel (a scalar texture stores its
    /// value in every channel).
    #[inline]
    pub fn eval_scalar(&self, hit: &Hit<F>) -> F {
        self.eval(hit).x
    }

    /// The colour, if the texture is a constant.
    #[inline]
    pub fn as_constant(&self) -> Option<Color<F>> {
        match self {
            Self::Constant(c) => Some(*c),
        }
    }

    /// Whether looking the texture up needs the hit's surface coordinates: what a material
    /// answers for [`reads_coordinates`](crate::Material::reads_coordinates).
    #[inline]
    pub fn reads_coordinates(&self) -> bool {
        self.as_constant().is_none()
    }
}

impl<F> From<Color<F>> for Texture<F> {
    fn from(colour: Color<F>) -> Self {
        Self::Constant(colour)
    }
}
