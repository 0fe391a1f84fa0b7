//! Unsigned integers wider than TOML's: TOML integers are signed 64-bit, so a seed or a
//! width above `i64::MAX` is written as a string of decimal digits and read back from one.

use serde::de::{self, Deserializer, Visitor};
use serde::ser::Serializer;
use std::fmt;

/// Writes `x` as a TOML integer when it fits, else as a decimal string.
pub fn serialize<S: Serializer, T: Copy + TryInto<u64>>(x: &T, s: S) -> Result<S::Ok, S::Error> {
    let wide: u64 = (*x)
        .try_into()
        .map_err(|_| serde::ser::Error::custom("an integer wider than 64 bits"))?;
    match i64::try_from(wide) {
        Ok(small) => s.serialize_i64(small),
        Err(_) => s.serialize_str(&wide.to_string()),
    }
}

/// Reads a non-negative integer that fits in `T`: a TOML integer, or above `i64::MAX` a
/// string of decimal digits.
pub fn deserialize<'de, D: Deserializer<'de>, T: TryFrom<u64>>(d: D) -> Result<T, D::Error> {
    let wide = d.deserialize_any(Unsigned)?;
    T::try_from(wide).map_err(|_| de::Error::custom(format!("{wide} is too large")))
}

struct Unsigned;

impl Visitor<'_> for Unsigned {
    type Value = u64;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a non-negative integer")
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<u64, E> {
        u64::try_from(v).map_err(|_| E::custom(format!("must be ≥ 0 (got {v})")))
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<u64, E> {
        Ok(v)
    }

    // A string only for what a TOML integer cannot hold, so that `width = "12"` is
    // refused as `spp = "12"` is.
    fn visit_str<E: de::Error>(self, v: &str) -> Result<u64, E> {
        match v.parse::<u64>() {
            Ok(wide) if i64::try_from(wide).is_err() => Ok(wide),
            Ok(_) => Err(E::custom(format!(
                "expected an integer, got the string {v:?} (write it without quotes; a string \
                 of digits is only for values above {})",
                i64::MAX
            ))),
            Err(_) => Err(E::custom(format!(
                "expected a non-negative integer, got the string {v:?}"
            ))),
        }
    }
}
