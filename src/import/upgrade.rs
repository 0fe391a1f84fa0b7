//! Scenes of Mitsuba 0.x (a `<scene version>` below 2), read as Mitsuba 3 reads them: each
//! property's camelCase name in snake_case (`toWorld` → `to_world`, `intIOR` → `int_ior`), a
//! `diffuse`'s `diffuse_reflectance` as its `reflectance`, and a texture's `uoffset`,
//! `voffset`, `uscale`, `vscale` as its `to_uv` (scale after offset). Such files are still
//! written today: point-cloud figure scripts print version 0.6.0 scenes for Mitsuba 3.

use super::transform::{Step, Transform};
use super::xml::{Plugin, Property, Value};
use crate::transform::Affine;

/// Whether the `version` attribute `version` (`0.6.0`) is below 2: the file takes the
/// upgrade. A missing or unreadable version is Mitsuba 3's.
pub(super) fn below_2(version: Option<&str>) -> bool {
    let major = version
        .and_then(|v| v.split('.').next())
        .and_then(|m| m.trim().parse::<u32>().ok());
    major.is_some_and(|m| m < 2)
}

/// `name` as Mitsuba 3 renames a 0.x property: an underscore before each capital that
/// follows a small letter, and that capital and the capitals right after it made small
/// (`toWorld` → `to_world`, `intIOR` → `int_ior`, `sampleCount` → `sample_count`).
pub(super) fn snake_case(name: &str) -> String {
    let chars: Vec<char> = name.chars().collect();
    let mut out = String::with_capacity(name.len() + 4);
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if i > 0 && chars[i - 1].is_ascii_lowercase() && c.is_ascii_uppercase() {
            out.push('_');
            out.push(c.to_ascii_lowercase());
            while i + 1 < chars.len() && chars[i + 1].is_ascii_uppercase() {
                i += 1;
                out.push(chars[i].to_ascii_lowercase());
            }
        } else {
            out.push(c);
        }
        i += 1;
    }
    out
}

/// The properties of `plugin`, read from a 0.x file, and the names under which it holds
/// nested plugins, as Mitsuba 3 upgrades them.
pub(super) fn upgrade(plugin: &mut Plugin) {
    let old = std::mem::take(&mut plugin.properties);
    for (name, property) in old {
        plugin.properties.insert(snake_case(&name), property);
    }
    let diffuse = plugin.kind == "diffuse";
    for child in &mut plugin.children {
        child.name = child.name.as_deref().map(snake_case);
        if diffuse && child.name.as_deref() == Some("diffuse_reflectance") {
            child.name = Some("reflectance".into());
        }
    }
    if diffuse && let Some(p) = plugin.properties.remove("diffuse_reflectance") {
        plugin.properties.insert("reflectance".into(), p);
    }
    let mut number = |name: &str| match plugin.properties.remove(name) {
        Some(Property {
            value: Value::Number(x),
            at,
        }) => Some((x, at)),
        Some(other) => {
            // Not a number: left under its name, to be reported as not read.
            plugin.properties.insert(name.into(), other);
            None
        }
        None => None,
    };
    let (uo, vo, us, vs) = (
        number("uoffset"),
        number("voffset"),
        number("uscale"),
        number("vscale"),
    );
    let Some(at) = [&uo, &vo, &us, &vs]
        .into_iter()
        .flatten()
        .map(|(_, at)| at.clone())
        .next()
    else {
        return;
    };
    let value = |v: &Option<(f64, _)>, default: f64| v.as_ref().map_or(default, |(x, _)| *x);
    let offset = [value(&uo, 0.0), value(&vo, 0.0), 0.0];
    let scale = [value(&us, 1.0), value(&vs, 1.0), 1.0];
    let map = Affine::translate(offset).then(&Affine::scale(scale));
    let steps = vec![Step::Translate(offset), Step::Scale(scale)];
    let value = Value::Transform(Transform { map, steps });
    plugin.properties.insert("to_uv".into(), Property { value, at });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_mitsubas_snake_case() {
        for (old, new) in [
            ("toWorld", "to_world"),
            ("intIOR", "int_ior"),
            ("sampleCount", "sample_count"),
            ("diffuseReflectance", "diffuse_reflectance"),
            ("maxDepth", "max_depth"),
            ("radius", "radius"),
            ("IOR", "IOR"),
            ("fovAxis", "fov_axis"),
        ] {
            assert_eq!(snake_case(old), new);
        }
    }

    #[test]
    fn versions_below_2_are_upgraded() {
        assert!(below_2(Some("0.6.0")) && below_2(Some("1.0")));
        assert!(!below_2(Some("2.1.0")) && !below_2(Some("3.0.0")) && !below_2(None) && !below_2(Some("x")));
    }
}
