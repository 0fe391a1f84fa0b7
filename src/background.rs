//! What a ray that hits nothing sees: a colour, the specification's sky, or an HDR
//! environment map; and, where a scene asks ([`Scene::light_background`](crate::Scene::set_background_sampled)),
//! a light drawn from like any other.

mod load;
mod map;

pub use map::{EnvironmentMap, luminance};

use crate::error::Result;
use crate::float::{Float, lit};
use crate::sampling::uniform_sphere;
use crate::validate;
use crate::vec3::{Color, Vec3};
use std::f64::consts::PI;
use std::sync::Arc;

/// The colour of a ray that escapes the scene.
#[derive(Clone, Debug, PartialEq)]
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
    /// An environment map, turned by `rotation` (a rotation matrix, rows; world
    /// direction = `rotation · map direction`), as Mitsuba's `envmap` with its `to_world`.
    Map {
        /// The map, shared.
        map: Arc<EnvironmentMap>,
        /// Its orientation.
        rotation: [[f64; 3]; 3],
    },
}

/// The identity rotation.
pub const NO_ROTATION: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

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

    /// An environment map turned by the rotation matrix `rotation` (rows; checked to be a
    /// rotation within `10⁻⁶`).
    ///
    /// # Errors
    /// [`Error::InvalidValue`](crate::Error::InvalidValue) ([`Field::EnvironmentRotation`](crate::error::Field::EnvironmentRotation)) for a
    /// matrix that is not a rotation.
    pub fn map(map: Arc<EnvironmentMap>, rotation: [[f64; 3]; 3]) -> Result<Self> {
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let r = rotation;
        let orthonormal =
            (0..3).all(|i| (0..3).all(|j| (dot(r[i], r[j]) - f64::from(u8::from(i == j))).abs() < 1e-6));
        let det = dot(
            r[0],
            [
                r[1][1] * r[2][2] - r[1][2] * r[2][1],
                r[1][2] * r[2][0] - r[1][0] * r[2][2],
                r[1][0] * r[2][1] - r[1][1] * r[2][0],
            ],
        );
        if !(orthonormal && (det - 1.0).abs() < 1e-6) {
            return Err(crate::Error::invalid(
                crate::error::Field::EnvironmentRotation,
                "must be a rotation (orthonormal, determinant 1)",
            ));
        }
        Ok(Self::Map { map, rotation })
    }

    /// This background in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Background<G>> {
        match self {
            Self::Solid(c) => Background::solid(c.cast()),
            Self::Sky { horizon, zenith } => Background::sky(horizon.cast(), zenith.cast()),
            Self::Map { map, rotation } => Ok(Background::Map {
                map: Arc::clone(map),
                rotation: *rotation,
            }),
        }
    }

    /// The colour seen along the unit direction `d`.
    #[inline]
    pub fn color(&self, d: Vec3<F>) -> Color<F> {
        match self {
            Self::Solid(c) => *c,
            Self::Sky { horizon, zenith } => {
                let s = (d.y + F::one()) * lit(0.5);
                *horizon * (F::one() - s) + *zenith * s
            }
            Self::Map { map, rotation } => {
                // Written into a slot of this arm's own, out of line: the solid colour's
                // and the sky's path, every escaped ray's, stays short.
                let mut c = Color::zero();
                map_color(map, rotation, d, &mut c);
                c
            }
        }
    }

    /// A direction drawn as a light from two uniform numbers, with its density per unit
    /// solid angle: by luminance for a map, uniformly over the sphere otherwise (`1/4π`).
    /// `None` if nothing is drawn (a black map).
    pub fn sample(&self, u: [f64; 2]) -> Option<(Vec3<F>, F)> {
        match self {
            Self::Map { map, rotation } => {
                let (d, pdf) = map.sample(u)?;
                let [x, y, z] = turn(rotation, d);
                Some((Vec3::from_f64(x, y, z), lit(pdf)))
            }
            _ => {
                let [x, y, z] = uniform_sphere(u);
                Some((Vec3::from_f64(x, y, z), lit(0.25 / PI)))
            }
        }
    }

    /// The density per unit solid angle with which [`Background::sample`] draws the unit
    /// direction `d`.
    pub fn pdf(&self, d: Vec3<F>) -> F {
        match self {
            Self::Map { map, rotation } => lit(map.pdf(turn_back(rotation, d.to_f64()))),
            _ => lit(0.25 / PI),
        }
    }

    /// Whether it gives off no light at all (a black colour or map): then it is not drawn
    /// from as a light.
    pub fn is_black(&self) -> bool {
        match self {
            Self::Solid(c) => *c == Color::zero(),
            Self::Sky { horizon, zenith } => *horizon == Color::zero() && *zenith == Color::zero(),
            Self::Map { map, .. } => map.is_black(),
        }
    }
}

/// `rotation · d`.
fn turn(r: &[[f64; 3]; 3], d: [f64; 3]) -> [f64; 3] {
    r.map(|row| row[0] * d[0] + row[1] * d[1] + row[2] * d[2])
}

/// The radiance of `map`, turned by `rotation`, along the unit direction `d`: what
/// [`Background::color`] gives for a map.
#[inline(never)]
fn map_color<F: Float>(map: &EnvironmentMap, rotation: &[[f64; 3]; 3], d: Vec3<F>, out: &mut Color<F>) {
    let local = turn_back(rotation, d.to_f64());
    let [r, g, b] = map.radiance_at(EnvironmentMap::coordinates(local));
    *out = Vec3::from_f64(r, g, b);
}

/// `rotationᵀ · d`, the inverse turn.
fn turn_back(r: &[[f64; 3]; 3], d: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|k| r[0][k] * d[0] + r[1][k] * d[1] + r[2][k] * d[2])
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
