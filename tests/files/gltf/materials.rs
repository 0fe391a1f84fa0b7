//! glTF's metallic-roughness materials as the renderer's BSDFs, by the mapping the scene
//! format's documentation states: metal or plastic by `metallicFactor`, `α = roughness²`,
//! transmission as a thin or solid dielectric, `doubleSided` and normal maps as
//! wrappers; what cannot be rendered as written is a warning naming the material.

use super::import;
use super::write::{Gltf, folder};
use raytrace::scene_file::{IorSpec, MaterialSpec, ScalarRef, TextureRef, TextureSpec};
use serde_json::{Value, json};

/// One triangle per material, each placed by a node of its own.
fn scene_of(materials: &[Value]) -> Gltf {
    let mut g = Gltf::new();
    let mut roots = Vec::new();
    for (k, m) in materials.iter().enumerate() {
        let index = g.push("materials", m.clone());
        let x = k as f32 * 2.0;
        let tri = [[x, 0.0, 0.0], [x + 1.0, 0.0, 0.0], [x, 1.0, 0.0]];
        let uv = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let mesh = g.mesh(&tri, None, Some(&uv), &[0, 1, 2], Some(index));
        roots.push(g.node(json!({ "mesh": mesh })));
    }
    g.scene(&roots);
    g
}

fn pbr(metallic: f32, roughness: f32) -> Value {
    json!({ "pbrMetallicRoughness": {
        "baseColorFactor": [0.9, 0.5, 0.1, 1.0], "metallicFactor": metallic, "roughnessFactor": roughness } })
}

/// `x` squared in f64, as glTF's f32 becomes it.
fn squared(x: f32) -> f64 {
    f64::from(x) * f64::from(x)
}

#[test]
fn metal_plastic_and_glass_map_as_documented() {
    let base = TextureRef::Color([0.9f32, 0.5, 0.1].map(f64::from));
    let mut glass = json!({ "pbrMetallicRoughness": { "roughnessFactor": 0.0 },
        "extensions": { "KHR_materials_transmission": { "transmissionFactor": 1.0 },
                        "KHR_materials_ior": { "ior": 1.33 } } });
    let mut solid = glass.clone();
    solid["extensions"]["KHR_materials_volume"] = json!({ "thicknessFactor": 1.0 });
    let mut two_sided = pbr(0.0, 0.3);
    two_sided["doubleSided"] = json!(true);
    glass["name"] = json!("water sheet");
    let mut g = scene_of(&[
        pbr(1.0, 0.4),
        pbr(1.0, 0.0),
        pbr(0.0, 0.0),
        pbr(0.0, 0.3),
        glass,
        solid,
        two_sided,
    ]);
    for e in [
        "KHR_materials_transmission",
        "KHR_materials_ior",
        "KHR_materials_volume",
    ] {
        g.uses(e);
    }
    let dir = folder("mapping");
    let imported = import(&g.save_glb(&dir, "m"));
    let m = &imported.file.materials;
    let MaterialSpec::RoughConductor(c) = &m["material 0"] else {
        panic!("{:?}", m["material 0"])
    };
    assert_eq!(c.specular_reflectance.as_ref(), Some(&base));
    assert_eq!(c.alpha, Some(ScalarRef::from(squared(0.4))));
    assert!(
        c.material.is_none() && c.eta.is_none(),
        "a perfect mirror's Fresnel times the base colour"
    );
    assert!(
        matches!(&m["material 1"], MaterialSpec::Conductor(c) if c.specular_reflectance == Some(base.clone()))
    );
    let MaterialSpec::Plastic(p) = &m["material 2"] else {
        panic!()
    };
    assert_eq!(
        (&p.diffuse_reflectance, &p.int_ior),
        (&base, &IorSpec::Value(1.5))
    );
    let MaterialSpec::RoughPlastic(p) = &m["material 3"] else {
        panic!()
    };
    assert_eq!((p.alpha, &p.ext_ior), (squared(0.3), &IorSpec::Value(1.0)));
    // Without KHR_materials_volume, glTF's transmission is a thin wall.
    let MaterialSpec::ThinDielectric(t) = &m["water sheet"] else {
        panic!("{m:?}")
    };
    assert_eq!(t.int_ior, IorSpec::Value(f64::from(1.33f32)));
    assert!(
        matches!(&m["material 5"], MaterialSpec::Dielectric { index, .. } if *index == f64::from(1.33f32))
    );
    let MaterialSpec::TwoSided(two) = &m["material 6"] else {
        panic!()
    };
    assert!(matches!(*two.front, MaterialSpec::RoughPlastic(_)));
    let built = imported.file.build::<f64>().unwrap();
    assert_eq!(built.summary.triangles, 7);
    assert!(imported.warnings.is_empty(), "{:?}", imported.warnings);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn what_cannot_be_rendered_as_written_is_a_warning_naming_the_material() {
    let mut blend = pbr(0.0, 0.5);
    blend["alphaMode"] = json!("BLEND");
    let mut g = scene_of(&[pbr(0.3, 0.5), blend]);
    g.uses("KHR_materials_clearcoat");
    let dir = folder("warnings");
    let imported = import(&g.save_glb(&dir, "w"));
    let w = imported.warnings.join("\n");
    for words in [
        ["materials[0]", "metallic 0.300"],
        ["materials[1]", "alphaMode Blend"],
        ["extensionsUsed", "KHR_materials_clearcoat"],
    ] {
        assert!(
            w.lines().any(|l| words.iter().all(|x| l.contains(x))),
            "{words:?} in {w}"
        );
    }
    // Required, an extension not read is an error naming it.
    g.json["extensionsRequired"] = json!(["KHR_materials_clearcoat"]);
    let e = raytrace::import::gltf(&g.save_glb(&dir, "r"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("extensionsRequired[0]") && e.contains("KHR_materials_clearcoat"),
        "{e}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_metallic_roughness_image_gives_alpha_from_green_and_metal_from_blue() {
    let mut g = Gltf::new();
    // Green 0, 51, 255 (roughness 0, 0.2, 1 times the factor 0.5); blue 255: metal.
    let image = g.png(3, 1, &[[0, 0, 255], [0, 51, 255], [0, 255, 255]]);
    let texture = g.texture(image);
    let normal_image = g.png(1, 1, &[[255, 128, 255]]);
    let normal = g.texture(normal_image);
    let m = json!({
        "pbrMetallicRoughness": { "metallicRoughnessTexture": { "index": texture }, "roughnessFactor": 0.5 },
        "normalTexture": { "index": normal, "scale": 0.5 } });
    g.push("materials", m);
    let tri = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let mesh = g.mesh(
        &tri,
        None,
        Some(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
        &[0, 1, 2],
        Some(0),
    );
    let node = g.node(json!({ "mesh": mesh }));
    g.scene(&[node]);
    let dir = folder("metal_roughness");
    let imported = import(&g.save_gltf(&dir, "mr"));
    let f = &imported.file;
    let MaterialSpec::NormalMap { normal_map, material } = &f.materials["material 0"] else {
        panic!()
    };
    let MaterialSpec::RoughConductor(c) = &f.materials[material] else {
        panic!("{:?}", f.materials)
    };
    let held = |t: &TextureRef| match t {
        TextureRef::Inline(spec) => match spec.as_ref() {
            TextureSpec::Image { file, .. } => f.assets().image(file).unwrap().clone(),
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}"),
    };
    let alpha = held(&c.alpha.as_ref().unwrap().0);
    // α = (factor · G/255)², at least the renderer's smallest α, 1e-4.
    let want = [0.0f64, 0.2, 1.0].map(|r| ((r * 0.5) * (r * 0.5)).max(1e-4) as f32);
    let got: Vec<f32> = alpha.pixels().iter().map(|p| p[1]).collect();
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-6, "{got:?} vs {want:?}");
    }
    // The normal (1, 0.0039, 1) with x and y halved: normalize(0.5, 0.002, 1), stored as (n + 1)/2.
    let n = held(normal_map).pixels()[0];
    let raw: [f64; 3] = [1.0, 128.0 / 255.0 * 2.0 - 1.0, 1.0];
    let v = [raw[0] * 0.5, raw[1] * 0.5, raw[2]];
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    for k in 0..3 {
        assert!((f64::from(n[k]) - (v[k] / len + 1.0) / 2.0).abs() < 1e-6, "{n:?}");
    }
    f.build::<f64>().unwrap();
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn materials_of_one_name_stay_apart() {
    let named = |n: &str| json!({ "name": n, "pbrMetallicRoughness": { "metallicFactor": 0 } });
    let unnamed = json!({ "pbrMetallicRoughness": { "metallicFactor": 1 } });
    let g = scene_of(&[named("material 2"), named("paint"), unnamed, named("paint")]);
    let dir = folder("names");
    let imported = import(&g.save_glb(&dir, "n"));
    let used: Vec<&str> = imported.file.objects.iter().map(|o| o.material()).collect();
    assert_eq!(used, ["material 2", "paint", "material 2 (2)", "paint (3)"]);
    assert!(matches!(
        imported.file.materials["material 2 (2)"],
        MaterialSpec::RoughConductor(_)
    ));
    std::fs::remove_dir_all(dir).unwrap();
}
