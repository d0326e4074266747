//! Deserialises a scene's maps (`points`, `branches`, `guess`) refusing a key given
//! twice. serde's map types keep the last value silently, so a scene with
//! `"B": (1.0, 0.0), "B": (2.0, 0.0)` would load as something its author did not
//! write.

use std::fmt;
use std::marker::PhantomData;

use indexmap::IndexMap;
use serde::de::{self, Deserialize, Deserializer, MapAccess, Visitor};

/// `#[serde(deserialize_with = "unique_map::deserialize")]` for `IndexMap<String, V>`.
///
/// # Errors
/// The deserializer's own errors, and a duplicated key, named with the ordinal of
/// both entries (the parser adds the line and column where the second one ends).
pub fn deserialize<'de, D, V>(deserializer: D) -> Result<IndexMap<String, V>, D::Error>
where
    D: Deserializer<'de>,
    V: Deserialize<'de>,
{
    deserializer.deserialize_map(UniqueVisitor(PhantomData))
}

struct UniqueVisitor<V>(PhantomData<V>);

impl<'de, V: Deserialize<'de>> Visitor<'de> for UniqueVisitor<V> {
    type Value = IndexMap<String, V>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a map with unique keys")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut access: A) -> Result<Self::Value, A::Error> {
        let mut out = IndexMap::with_capacity(access.size_hint().unwrap_or(0).min(256));
        while let Some((key, value)) = access.next_entry::<String, V>()? {
            if let Some(first) = out.get_index_of(&key) {
                return Err(de::Error::custom(format!(
                    "key \"{key}\" is given twice, as entry {} and entry {} of this map; keep one",
                    first + 1,
                    out.len() + 1
                )));
            }
            out.insert(key, value);
        }
        Ok(out)
    }
}
