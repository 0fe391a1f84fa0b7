//! Named optical constants: the indices of refraction of common dielectrics, and the
//! complex indices (`η + ik`) of Mitsuba 3's named conductors, so a scene can say `"bk7"`
//! or `"Au"` and mean what Mitsuba means.
//!
//! # Sources
//! - Dielectrics: Mitsuba 3's table (`include/mitsuba/render/ior.h`), itself from Hecht,
//!   *Optics* (4th edition), measured at 0–20 °C near 589 nm, under Mitsuba's names. Three
//!   names are added: `acrylic` (Mitsuba's `acrylic glass`, 1.49), `glass` (1.5, pbrt-v4's
//!   default dielectric index) and `polycarbonate` (1.585, its index at the sodium D line
//!   as measured by Sultanova, Kasarova and Nikolov, *Acta Physica Polonica A* 116 (2009)).
//!   Names are matched ignoring case, as Mitsuba does.
//! - Conductors: see the table's own module (`ior/metals.rs`): Mitsuba 3.9.1's RGB values
//!   of its spectral data. Names are matched exactly (`Au`, `Cu_palik`, `d-C`).

mod metals;

use crate::error::{Error, Field, Result};

/// `(name, index)`: Mitsuba's table in its order, then the three added names.
const DIELECTRICS: [(&str, f64); 26] = [
    ("vacuum", 1.0),
    ("helium", 1.000036),
    ("hydrogen", 1.000132),
    ("air", 1.000277),
    ("carbon dioxide", 1.00045),
    ("water", 1.3330),
    ("acetone", 1.36),
    ("ethanol", 1.361),
    ("carbon tetrachloride", 1.461),
    ("glycerol", 1.4729),
    ("benzene", 1.501),
    ("silicone oil", 1.52045),
    ("bromine", 1.661),
    ("water ice", 1.31),
    ("fused quartz", 1.458),
    ("pyrex", 1.470),
    ("acrylic glass", 1.49),
    ("polypropylene", 1.49),
    ("bk7", 1.5046),
    ("sodium chloride", 1.544),
    ("amber", 1.55),
    ("pet", 1.5750),
    ("diamond", 2.419),
    ("acrylic", 1.49),
    ("glass", 1.5),
    ("polycarbonate", 1.585),
];

/// A conductor's complex index of refraction `η + ik`, per channel `[r, g, b]`: `η` the
/// real index, `k` the extinction coefficient.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComplexIor {
    /// The real part `η`.
    pub eta: [f64; 3],
    /// The imaginary part `k`.
    pub k: [f64; 3],
}

/// The named conductor's complex index (see the module's sources), if the name is one.
pub fn conductor(name: &str) -> Option<ComplexIor> {
    metals::METALS
        .iter()
        .find(|(n, ..)| *n == name)
        .map(|&(_, eta, k)| ComplexIor { eta, k })
}

/// Every conductor name [`conductor`] knows.
pub fn conductor_names() -> impl Iterator<Item = &'static str> {
    metals::METALS.iter().map(|(n, ..)| *n)
}

/// The named dielectric's index of refraction, the name's case ignored.
pub fn dielectric(name: &str) -> Option<f64> {
    DIELECTRICS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|&(_, v)| v)
}

/// Every dielectric name [`dielectric`] knows.
pub fn dielectric_names() -> impl Iterator<Item = &'static str> {
    DIELECTRICS.iter().map(|(n, _)| *n)
}

/// The named conductor's index, or an error at `field` naming every known conductor.
pub(crate) fn conductor_named(field: Field, name: &str) -> Result<ComplexIor> {
    conductor(name).ok_or_else(|| unknown(field, "conductor", name, conductor_names()))
}

fn unknown<'a>(field: Field, what: &str, name: &str, known: impl Iterator<Item = &'a str>) -> Error {
    let known: Vec<_> = known.map(|n| format!("`{n}`")).collect();
    Error::invalid(
        field,
        format!("no {what} is named `{name}` (known: {})", known.join(", ")),
    )
}

/// An index of refraction as a scene gives it: a number, or the name of a medium
/// ([`dielectric`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Ior {
    /// The index itself.
    Value(f64),
    /// A medium's name (`"bk7"`, `"water"`).
    Named(String),
}

impl Ior {
    /// The index: the number, or the named medium's; an unknown name is an error at
    /// `field` naming every known medium. (The number's domain is the constructor's to
    /// check.)
    pub fn value(&self, field: Field) -> Result<f64> {
        match self {
            Self::Value(v) => Ok(*v),
            Self::Named(name) => {
                dielectric(name).ok_or_else(|| unknown(field, "medium", name, dielectric_names()))
            }
        }
    }
}

impl From<f64> for Ior {
    fn from(v: f64) -> Self {
        Self::Value(v)
    }
}

impl From<&str> for Ior {
    fn from(name: &str) -> Self {
        Self::Named(name.to_owned())
    }
}

impl From<String> for Ior {
    fn from(name: String) -> Self {
        Self::Named(name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_resolve_and_unknown_ones_list_the_known() {
        assert_eq!(dielectric("BK7"), Some(1.5046));
        assert_eq!(dielectric("Acrylic Glass"), Some(1.49));
        let gold = conductor("Au").unwrap();
        assert_eq!(gold.eta, [0.14303598, 0.37530708, 1.4420453]);
        assert_eq!(conductor("au"), None, "conductor names are exact");
        let e = Ior::from("unobtainium")
            .value(Field::Custom("index"))
            .unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.contains("`unobtainium`") && msg.contains("`bk7`") && msg.contains("`diamond`"),
            "{msg}"
        );
        let e = conductor_named(Field::Custom("metal"), "Fe")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("`Fe`") && e.contains("`Au`") && e.contains("`none`"),
            "{e}"
        );
    }

    #[test]
    fn every_name_is_unique_and_every_value_physical() {
        let mut seen = std::collections::HashSet::new();
        for n in dielectric_names() {
            assert!(seen.insert(n.to_lowercase()), "{n} twice");
            assert!(dielectric(n).unwrap() >= 1.0);
        }
        for n in conductor_names() {
            assert!(seen.insert(n.to_owned()), "{n} twice");
            let c = conductor(n).unwrap();
            assert!(
                c.eta.iter().chain(&c.k).all(|v| v.is_finite() && *v >= 0.0),
                "{n}"
            );
        }
    }
}
