//! [`Interface`]: the two indices of refraction either side of a dielectric boundary, as
//! Mitsuba's `int_ior` and `ext_ior`.

use super::ior::Ior;
use crate::error::{Error, Field, Result};
use crate::float::{Float, to};
use crate::validate;

/// A boundary between two dielectrics: the index inside (`int_ior`, where the shape's
/// outward normal points away from) and outside (`ext_ior`), each a number or a named
/// medium ([`Ior`]). Its relative index is `η = η_int/η_ext`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interface<F> {
    interior: F,
    exterior: F,
}

impl<F: Float> Interface<F> {
    /// The boundary from `exterior` into `interior`, each finite and `> 0`; with
    /// `differ`, the two must differ (a rough interface between equal indices would
    /// divide by zero, and Mitsuba refuses it).
    pub fn new(interior: impl Into<Ior>, exterior: impl Into<Ior>, differ: bool) -> Result<Self> {
        let index = |field, ior: Ior| validate::positive(field, F::from_f64(ior.value(field)?));
        let interior = index(Field::InteriorIndex, interior.into())?;
        let exterior = index(Field::ExteriorIndex, exterior.into())?;
        if differ && interior == exterior {
            return Err(Error::invalid(
                Field::InteriorIndex,
                format!(
                    "must differ from the exterior index (both are {})",
                    validate::number(interior)
                ),
            ));
        }
        Ok(Self { interior, exterior })
    }

    /// The index inside.
    pub fn interior(&self) -> F {
        self.interior
    }

    /// The index outside.
    pub fn exterior(&self) -> F {
        self.exterior
    }

    /// `η = η_int/η_ext`.
    #[inline]
    pub fn eta(&self) -> F {
        self.interior / self.exterior
    }

    /// The index of the side away from the ray over the index of its own side: `η` if
    /// it arrives at the `front_face`, `1/η` from inside.
    #[inline]
    pub fn eta_toward(&self, front_face: bool) -> F {
        if front_face {
            self.eta()
        } else {
            self.exterior / self.interior
        }
    }

    /// This interface in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self, differ: bool) -> Result<Interface<G>> {
        Interface::new(to::<F, f64>(self.interior), to::<F, f64>(self.exterior), differ)
    }
}
