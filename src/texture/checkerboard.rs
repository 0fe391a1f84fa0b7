//! [`Checkerboard`]: two colours in alternating squares, Mitsuba 3's `checkerboard`.

use super::UvMap;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::validate;
use crate::vec3::Color;

/// Two colours in alternating squares of the `uv` plane, as Mitsuba 3's `checkerboard`
/// texture (`src/textures/checkerboard.cpp`): at `(u, v) = map(uv)`, with
/// `m_u = frac(u) > ½` and `m_v = frac(v) > ½` (`frac(x) = x − ⌊x⌋`), the value is
/// `color0` where `m_u = m_v` and `color1` where they differ. So one period of `uv`
/// holds four squares, `color0` in the corner at `(0, 0)`.
///
/// Mitsuba's defaults are `color0 = 0.4` and `color1 = 0.2`. (Its scalar lookup,
/// `eval_1`, picks the two the other way round; this texture's
/// [`eval_scalar`](super::Texture::eval_scalar) follows the colour lookup, so a
/// cross-check of a checkerboard used as a roughness swaps the two in the Mitsuba file.)
#[derive(Clone, Debug, PartialEq)]
pub struct Checkerboard<F> {
    color0: Color<F>,
    color1: Color<F>,
    map: UvMap<F>,
}

impl<F: Float> Checkerboard<F> {
    /// Mitsuba's default colours, 0.4 and 0.2 in every channel.
    pub fn mitsuba_default() -> Self {
        Self {
            color0: Color::splat(lit(0.4)),
            color1: Color::splat(lit(0.2)),
            map: UvMap::default(),
        }
    }

    /// The checkerboard of `color0` and `color1`, each channel finite, at `uv` unmapped.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] (`Field::CheckerboardColor0`, `Field::CheckerboardColor1`)
    /// for a channel that is not finite.
    pub fn new(color0: Color<F>, color1: Color<F>) -> Result<Self> {
        for (field, c) in [
            (Field::CheckerboardColor0, color0),
            (Field::CheckerboardColor1, color1),
        ] {
            if !c.is_finite() {
                return Err(Error::invalid(
                    field,
                    format!("each channel must be finite (got {})", validate::show(c)),
                ));
            }
        }
        Ok(Self {
            color0,
            color1,
            map: UvMap::default(),
        })
    }

    /// The same checkerboard looked up at `map(uv)`.
    #[must_use]
    pub fn with_uv_map(self, map: UvMap<F>) -> Self {
        Self { map, ..self }
    }

    /// The colour of the squares with the corner `(0, 0)`.
    pub fn color0(&self) -> Color<F> {
        self.color0
    }

    /// The colour of the other squares.
    pub fn color1(&self) -> Color<F> {
        self.color1
    }

    /// The map applied to `uv`.
    pub fn uv_map(&self) -> UvMap<F> {
        self.map
    }

    /// The colour at `uv`.
    #[inline]
    pub fn eval(&self, uv: [F; 2]) -> Color<F> {
        let half = lit::<F>(0.5);
        let [u, v] = self.map.apply(uv);
        let (mu, mv) = (u - u.floor() > half, v - v.floor() > half);
        if mu == mv { self.color0 } else { self.color1 }
    }

    /// This checkerboard in scalar `G`, re-checked.
    ///
    /// # Errors
    /// As [`Checkerboard::new`] and [`UvMap::new`], for a value beyond `G`'s range.
    pub fn cast<G: Float>(&self) -> Result<Checkerboard<G>> {
        Ok(Checkerboard::new(self.color0.cast(), self.color1.cast())?.with_uv_map(self.map.cast()?))
    }
}
