//! Every constructor error reaches its own key: routed by the error's typed field, so a
//! constructor's message can change without moving it.

use super::check::{blame, key};
use super::location::KeyPath;
use super::*;
use crate::error::Field;

mod cases;

use cases::{Case, case, material};

/// Every field but those no scene file can get wrong (a user's own, a rotation matrix). A
/// field added to [`Field`] needs a case in the `match` above to compile, and belongs here
/// too.
const FIELDS: [Field; 60] = [
    Field::SphereCenter,
    Field::SphereRadius,
    Field::PlanePoint,
    Field::PlaneNormal,
    Field::TriangleA,
    Field::TriangleB,
    Field::TriangleC,
    Field::Triangle,
    Field::Mesh,
    Field::DiskCenter,
    Field::DiskNormal,
    Field::DiskRadius,
    Field::DiskAxes,
    Field::MirrorAlbedo,
    Field::MatteAlbedo,
    Field::RefractiveIndex,
    Field::DielectricAlbedo,
    Field::EmittedRadiance,
    Field::EmissiveAlbedo,
    Field::CheckerboardColor0,
    Field::CheckerboardColor1,
    Field::TextureScale,
    Field::TextureOffset,
    Field::ConductorEta,
    Field::ConductorK,
    Field::ConductorName,
    Field::SpecularReflectance,
    Field::SpecularTransmittance,
    Field::DiffuseReflectance,
    Field::Alpha,
    Field::AlphaU,
    Field::AlphaV,
    Field::InteriorIndex,
    Field::ExteriorIndex,
    Field::TwoSidedFront,
    Field::TwoSidedBack,
    Field::LightPosition,
    Field::LightIntensity,
    Field::LightDirection,
    Field::LightIrradiance,
    Field::SpotCutoff,
    Field::SpotBeamWidth,
    Field::BackgroundColor,
    Field::SkyHorizon,
    Field::SkyZenith,
    Field::EnvironmentMap,
    Field::EnvironmentScale,
    Field::CameraFrom,
    Field::CameraAt,
    Field::CameraView,
    Field::CameraUp,
    Field::CameraVfov,
    Field::CameraAperture,
    Field::CameraFocusDistance,
    Field::CameraEye,
    Field::ImageWidth,
    Field::ImageSize,
    Field::SamplesPerPixel,
    Field::MaxDepth,
    Field::Exposure,
];

/// The file's error: the key, the field and the message.
fn failure(c: &Case) -> (String, Option<Field>, String) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/t.toml");
    let file = SceneFile::parse(&c.text, &path).unwrap_or_else(|e| panic!("{e}\n{}", c.text));
    let built = if c.f32 {
        file.build::<f32>().map(drop)
    } else {
        file.build::<f64>().map(drop)
    };
    match built {
        Err(Error::SceneFile {
            location,
            field,
            message,
            ..
        }) => (location, field, message),
        other => panic!(
            "{:?}: expected a scene file error, got {other:?}\n{}",
            c.field, c.text
        ),
    }
}

#[test]
fn the_fields_are_listed_once() {
    let mut seen = std::collections::HashSet::new();
    for field in FIELDS {
        assert!(seen.insert(field), "{field:?} twice");
        assert!(case(field).is_some(), "{field:?}");
    }
}

#[test]
fn every_constructor_error_reaches_its_own_key() {
    for field in FIELDS {
        let c = case(field).expect("every field but a user's has a case");
        let (location, got, message) = failure(&c);
        assert_eq!(
            (location.as_str(), got),
            (c.at, Some(field)),
            "{message}\n{}",
            c.text
        );
        if c.f32 {
            assert!(
                message.contains("in f32"),
                "{field:?}: a value lost in rounding says so: {message}"
            );
            let f64_case = Case { f32: false, ..c };
            let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/t.toml");
            let file = SceneFile::parse(&f64_case.text, &path).unwrap();
            assert!(
                file.build::<f64>().is_ok(),
                "{field:?}: the f32 case is valid in f64"
            );
        }
    }
}

#[test]
fn the_key_follows_the_field_not_the_message() {
    let file = Path::new("t.toml");
    let root = KeyPath::root(file);
    let entry = root.key("objects").index(2);
    for field in FIELDS {
        let at = |reason: &str| match blame(&root, &entry, Error::invalid(field, reason)) {
            Error::SceneFile { location, field, .. } => (location, field),
            other => panic!("{other:?}"),
        };
        // Another constructor's words, or none, reach the same key.
        let words = at("sphere centre radius albedo render.width");
        assert_eq!(words, at(""), "{field:?}");
        assert_eq!(words.1, Some(field));
        let Error::SceneFile { location, .. } = key(&root, &entry, field).error("") else {
            unreachable!()
        };
        assert_eq!(words.0, location);
    }
}

/// A two-sided material's own materials report their errors at their own keys, however
/// deep.
#[test]
fn nested_materials_errors_are_at_their_own_keys() {
    for (keys, at, field) in [
        (
            "front = { type = \"rough_conductor\", alpha = -1 }",
            "materials.x.front.alpha",
            Field::Alpha,
        ),
        (
            "front = { type = \"plastic\" }\nback = { type = \"two_sided\", front = { type = \"conductor\", material = \"Xx\" } }",
            "materials.x.back.front.material",
            Field::ConductorName,
        ),
    ] {
        let c = Case {
            text: material("two_sided", keys),
            f32: false,
            field,
            at,
        };
        let (location, got, message) = failure(&c);
        assert_eq!((location.as_str(), got), (at, Some(field)), "{message}");
    }
}
