//! `[x, y, z]` read exactly: TOML's reader hands a three-element array type the first three
//! numbers of a longer array and drops the rest, so the length is checked here.

use super::model::Triple;
use serde::Deserializer;
use serde::de::{self, IgnoredAny, SeqAccess, Visitor};
use std::fmt;

/// Reads an array of exactly three numbers.
pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Triple, D::Error> {
    d.deserialize_seq(Exact)
}

/// Reads an optional key's array of exactly three numbers.
pub fn some<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Triple>, D::Error> {
    deserialize(d).map(Some)
}

/// The visitor of [`deserialize`], for a value that may be three numbers among other forms.
pub(super) struct Exact;

impl<'de> Visitor<'de> for Exact {
    type Value = Triple;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of three numbers")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Triple, A::Error> {
        let mut t = [0.0; 3];
        for (i, slot) in t.iter_mut().enumerate() {
            *slot = seq
                .next_element()?
                .ok_or_else(|| de::Error::invalid_length(i, &self))?;
        }
        let mut len = 3;
        while seq.next_element::<IgnoredAny>()?.is_some() {
            len += 1;
        }
        if len > 3 {
            return Err(de::Error::invalid_length(len, &self));
        }
        Ok(t)
    }
}
