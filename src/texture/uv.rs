//! [`UvMap`]: where in a texture a surface point's `uv` looks, Mitsuba 3's `to_uv` as a
//! scale and an offset.

use crate::error::{Error, Field, Result};
use crate::float::{Float, to};

/// The map `uv ↦ (s_u·u + o_u, s_v·v + o_v)` a texture applies to a hit's `uv` before
/// looking it up: a scale `s`, then an offset `o`. It is Mitsuba 3's `to_uv` transform
/// written `translate(o)·scale(s)` (in its XML, `<scale …/>` then `<translate …/>`): a
/// scale of 4 repeats a texture four times across `[0, 1]`, an offset of ½ moves it by half
/// its period.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvMap<F> {
    scale: [F; 2],
    offset: [F; 2],
}

impl<F: Float> Default for UvMap<F> {
    /// The identity: scale 1, offset 0.
    fn default() -> Self {
        Self {
            scale: [F::one(); 2],
            offset: [F::zero(); 2],
        }
    }
}

impl<F: Float> UvMap<F> {
    /// The map with `scale` and `offset` per axis, each finite (a scale of zero is
    /// allowed: the texture's value at `offset` everywhere along that axis).
    ///
    /// # Errors
    /// [`Error::InvalidValue`] (`Field::TextureScale`, `Field::TextureOffset`) for a value
    /// that is not finite.
    pub fn new(scale: [F; 2], offset: [F; 2]) -> Result<Self> {
        for (field, pair) in [(Field::TextureScale, scale), (Field::TextureOffset, offset)] {
            if !pair.iter().all(|x| x.is_finite()) {
                return Err(Error::invalid(
                    field,
                    format!("must be finite (got [{}, {}])", pair[0], pair[1]),
                ));
            }
        }
        Ok(Self { scale, offset })
    }

    /// The scale `s`.
    pub fn scale(&self) -> [F; 2] {
        self.scale
    }

    /// The offset `o`.
    pub fn offset(&self) -> [F; 2] {
        self.offset
    }

    /// `(s_u·u + o_u, s_v·v + o_v)`.
    #[inline]
    pub fn apply(&self, [u, v]: [F; 2]) -> [F; 2] {
        [
            self.scale[0] * u + self.offset[0],
            self.scale[1] * v + self.offset[1],
        ]
    }

    /// The map in scalar `G`, re-checked.
    ///
    /// # Errors
    /// As [`UvMap::new`], for a value beyond `G`'s range.
    pub fn cast<G: Float>(&self) -> Result<UvMap<G>> {
        UvMap::new(self.scale.map(to), self.offset.map(to))
    }
}
