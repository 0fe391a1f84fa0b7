//! What a ray that hits nothing sees.

use crate::error::Result;
use crate::float::{Float, lit};
use crate::validate;
use crate::vec3::{Color, Vec3};

/// The colour of a ray that escapes the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Background<F> {
    /// The same colour in every direction.
    Solid(Color<F>),
    /// A sky gradient by the direction's `y`: `(1 − s)·horizon + s·zenith` with
    /// `s = (y + 1)/2`, so straight down is `horizon` and straight up is `zenith`.
    Sky {
        /// The colour at `y = −1` (blending to `zenith` through the horizon).
        horizon: Color<F>,
        /// The colour at `y = +1`.
        zenith: Color<F>,
    },
}

impl<F: Float> Background<F> {
    /// A plain background; channels must be finite and `≥ 0`.
    pub fn solid(color: Color<F>) -> Result<Self> {
        Ok(Self::Solid(validate::non_negative(
            crate::error::Field::BackgroundColor,
            color,
        )?))
    }

    /// A sky gradient; channels must be finite and `≥ 0`.
    pub fn sky(horizon: Color<F>, zenith: Color<F>) -> Result<Self> {
        Ok(Self::Sky {
            horizon: validate::non_negative(crate::error::Field::SkyHorizon, horizon)?,
            zenith: validate::non_negative(crate::error::Field::SkyZenith, zenith)?,
        })
    }

    /// This background in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Background<G>> {
        match self {
            Self::Solid(c) => Background::solid(c.cast()),
            Self::Sky { horizon, zenith } => Background::sky(horizon.cast(), zenith.cast()),
        }
    }

    /// The colour seen along the unit direction `d`.
    #[inline]
    pub fn color(&self, d: Vec3<F>) -> Color<F> {
        match *self {
            Self::Solid(c) => c,
            Self::Sky { horizon, zenith } => {
                let s = (d.y + F::one()) * lit(0.5);
                horizon * (F::one() - s) + zenith * s
            }
        }
    }
}

/// The book's sky: white below, `(0.5, 0.7, 1.0)` blue above.
impl<F: Float> Default for Background<F> {
    fn default() -> Self {
        Self::Sky {
            horizon: Vec3::splat(F::one()),
            zenith: Vec3::from_f64(0.5, 0.7, 1.0),
        }
    }
}
