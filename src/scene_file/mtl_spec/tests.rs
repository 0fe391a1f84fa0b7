//! The mapping's rules, one case each, and the keys it reports as unused.

use super::*;
use crate::mesh::MtlMap;
use std::path::PathBuf;

fn color(c: [f64; 3], line: u64) -> Option<At<[f64; 3]>> {
    Some(At { value: c, line })
}

fn number<T>(x: T, line: u64) -> Option<At<T>> {
    Some(At { value: x, line })
}

fn material() -> MtlMaterial {
    MtlMaterial {
        name: "m".into(),
        library: PathBuf::from("lib.mtl"),
        line: 1,
        ..MtlMaterial::default()
    }
}

fn front(spec: MaterialSpec) -> MaterialSpec {
    match spec {
        MaterialSpec::TwoSided(TwoSidedSpec { front, back: None }) => *front,
        other => panic!("not two-sided: {other:?}"),
    }
}

#[test]
fn kd_alone_is_matte_and_nothing_is_blenders_grey() {
    let m = MtlMaterial {
        kd: color([0.2, 0.4, 0.6], 2),
        ..material()
    };
    let want = MaterialSpec::Lambertian {
        albedo: TextureRef::Color([0.2, 0.4, 0.6]),
    };
    assert_eq!(map(&m).unwrap().spec, want);
    let bare = MaterialSpec::Lambertian {
        albedo: TextureRef::Color(DEFAULT_KD),
    };
    assert_eq!(map(&material()).unwrap().spec, bare);
    // Highlights off (illum 1): Ks has no effect.
    let off = MtlMaterial {
        ks: color([0.5; 3], 3),
        illum: number(1, 4),
        ..m.clone()
    };
    assert_eq!(map(&off).unwrap().spec, want);
    // A map_Kd replaces Kd.
    let textured = MtlMaterial {
        map_kd: number(
            MtlMap {
                file: "wood.png".into(),
                scale: [1.0; 2],
                offset: [0.0; 2],
                clamp: false,
                bump_multiplier: None,
            },
            5,
        ),
        ..m
    };
    let MaterialSpec::Lambertian { albedo } = map(&textured).unwrap().spec else {
        panic!()
    };
    assert_eq!(albedo, TextureRef::Named(DIFFUSE_MAP.into()));
}

#[test]
fn kd_and_ks_are_a_rough_plastic_with_alpha_from_ns() {
    let m = MtlMaterial {
        kd: color([0.6, 0.1, 0.1], 2),
        ks: color([0.5; 3], 3),
        ns: number(98.0, 4),
        illum: number(2, 5),
        ..material()
    };
    let MaterialSpec::RoughPlastic(p) = front(map(&m).unwrap().spec) else {
        panic!()
    };
    // √(2/(98 + 2)) = √0.02.
    assert_eq!(p.alpha, 0.02f64.sqrt());
    assert_eq!(p.distribution, DistributionSpec::Beckmann);
    assert_eq!(p.diffuse_reflectance, TextureRef::Color([0.6, 0.1, 0.1]));
    assert_eq!(p.specular_reflectance, Some(TextureRef::Color([0.5; 3])));
    assert_eq!(
        (alpha_of_exponent(0.0), alpha_of_exponent(1000.0)),
        (1.0, (2.0f64 / 1002.0).sqrt())
    );
    let no_ns = MtlMaterial {
        ns: None,
        ..m.clone()
    };
    let MaterialSpec::RoughPlastic(p) = front(map(&no_ns).unwrap().spec) else {
        panic!()
    };
    assert_eq!(p.alpha, DEFAULT_ALPHA);
    let negative = MtlMaterial {
        ns: number(-3.0, 4),
        ..m
    };
    let (key, why) = map(&negative).unwrap_err();
    assert_eq!((key.value, key.line), ("Ns", 4));
    assert!(why.contains("≥ 0"), "{why}");
}

#[test]
fn see_through_is_glass_of_index_ni() {
    let half = MtlMaterial {
        kd: color([0.8; 3], 2),
        d: number(0.5, 3),
        ni: number(1.33, 4),
        ..material()
    };
    let mapped = map(&half).unwrap();
    assert_eq!(
        mapped.spec,
        MaterialSpec::Dielectric {
            index: 1.33,
            albedo: None,
            fresnel: FresnelSpec::Exact,
        }
    );
    assert_eq!(mapped.unused.len(), 1);
    assert_eq!((mapped.unused[0].0.value, mapped.unused[0].0.line), ("Kd", 2));
    for illum in [4, 6, 7, 9] {
        let glass = MtlMaterial {
            illum: number(illum, 2),
            tf: color([0.9, 1.0, 0.9], 3),
            ..material()
        };
        let MaterialSpec::Dielectric { index, albedo, .. } = map(&glass).unwrap().spec else {
            panic!("illum {illum}")
        };
        assert_eq!((index, albedo), (DEFAULT_NI, Some([0.9, 1.0, 0.9])));
    }
}

#[test]
fn ke_is_an_emitter_and_reflection_without_diffuse_a_metal() {
    let lamp = MtlMaterial {
        kd: color([0.5; 3], 2),
        ke: color([4.0, 3.0, 2.0], 3),
        d: number(0.5, 4),
        ..material()
    };
    assert_eq!(
        map(&lamp).unwrap().spec,
        MaterialSpec::Emissive {
            radiance: [4.0, 3.0, 2.0],
            two_sided: false,
            albedo: Some([0.5; 3]),
        }
    );
    // Ke of zero (what exporters write for every material) is no emitter.
    let dark = MtlMaterial {
        ke: color([0.0; 3], 3),
        ..material()
    };
    assert!(matches!(
        map(&dark).unwrap().spec,
        MaterialSpec::Lambertian { .. }
    ));
    let chrome = MtlMaterial {
        kd: color([0.0; 3], 2),
        ks: color([0.9; 3], 3),
        ns: number(1000.0, 4),
        illum: number(3, 5),
        ..material()
    };
    let MaterialSpec::RoughConductor(c) = front(map(&chrome).unwrap().spec) else {
        panic!()
    };
    assert_eq!((c.material, c.eta, c.k), (None, None, None));
    assert_eq!(c.specular_reflectance, Some(TextureRef::Color([0.9; 3])));
    assert_eq!(c.alpha, Some(ScalarRef::from(alpha_of_exponent(1000.0))));
    // With a diffuse colour, reflection on is a plastic.
    let coloured = MtlMaterial {
        kd: color([0.3; 3], 2),
        ..chrome
    };
    assert!(matches!(
        front(map(&coloured).unwrap().spec),
        MaterialSpec::RoughPlastic(_)
    ));
}
