//! Reading `[[objects]]`, `[[lights]]` and `[materials.NAME]` one entry at a time, so an
//! error inside an entry names it (`objects[3]: unknown field ...`): serde reads a typed
//! table through a buffer that has no position of its own, and the TOML reader can then
//! only point at the start of the whole array.

use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use std::collections::BTreeMap;
use std::fmt;
use std::marker::PhantomData;

/// Reads the array `name`, prefixing each entry's error with `name[i]: `.
pub fn array<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
    d: D,
    name: &'static str,
) -> Result<Vec<T>, D::Error> {
    d.deserialize_seq(Entries::<Vec<T>>(name, PhantomData))
}

/// Reads the table `name` of named entries, prefixing each entry's error with `name.KEY: `.
pub fn table<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
    d: D,
    name: &'static str,
) -> Result<BTreeMap<String, T>, D::Error> {
    d.deserialize_map(Entries::<BTreeMap<String, T>>(name, PhantomData))
}

struct Entries<T>(&'static str, PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for Entries<Vec<T>> {
    type Value = Vec<T>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "an array of tables `[[{}]]`", self.0)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<T>, A::Error> {
        let mut out = Vec::new();
        loop {
            match seq.next_element::<T>() {
                Ok(Some(entry)) => out.push(entry),
                Ok(None) => return Ok(out),
                Err(e) => return Err(de::Error::custom(format!("{}[{}]: {e}", self.0, out.len()))),
            }
        }
    }
}

impl<'de, T: Deserialize<'de>> Visitor<'de> for Entries<BTreeMap<String, T>> {
    type Value = BTreeMap<String, T>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "a table of named tables `[{}.NAME]`", self.0)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<BTreeMap<String, T>, A::Error> {
        let mut out = BTreeMap::new();
        while let Some(key) = map.next_key::<String>()? {
            let value = map
                .next_value::<T>()
                .map_err(|e| de::Error::custom(format!("{}.{key}: {e}", self.0)))?;
            out.insert(key, value);
        }
        Ok(out)
    }
}
