//! No bytes make the glTF importer panic: arbitrary bytes, and edits (byte changes and
//! truncations) of a real `.gltf` and `.glb` holding every part the importer reads, are
//! either imported (and then built, or refused by the build) or refused with an error.
//! Fixed seeds, so every run tries the same cases.

use super::write::{Gltf, folder};
use proptest::prelude::*;
use serde_json::json;
use std::path::Path;

/// An asset with every part the importer reads: a textured, normal-mapped triangle mesh
/// under a parent node, a camera, a point and a spot light, an emitter.
fn asset() -> Gltf {
    let mut g = Gltf::new();
    let image = g.png(2, 2, &[[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]]);
    let texture = g.texture(image);
    g.push(
        "materials",
        json!({ "pbrMetallicRoughness": { "baseColorTexture": { "index": texture },
                "metallicRoughnessTexture": { "index": texture } },
                "normalTexture": { "index": texture }, "doubleSided": true }),
    );
    g.push("materials", json!({ "emissiveFactor": [1, 1, 1] }));
    let square = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let normals = [[0.0, 0.0, 1.0]; 4];
    let uv = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let mesh = g.mesh(&square, Some(&normals), Some(&uv), &[0, 1, 2, 0, 2, 3], Some(0));
    let lamp = g.mesh(&square, None, None, &[0, 1, 2], Some(1));
    let child = g.node(json!({ "mesh": mesh, "scale": [1, 2, 1] }));
    let parent =
        g.node(json!({ "children": [child], "rotation": [0, 0.6, 0, 0.8], "translation": [0, 0, -3] }));
    let emitter = g.node(json!({ "mesh": lamp, "translation": [0, 3, -3] }));
    let c = g.push(
        "cameras",
        json!({ "type": "perspective", "perspective": { "yfov": 0.7, "znear": 0.1 } }),
    );
    let cam = g.node(json!({ "camera": c }));
    let point = g.light(json!({ "type": "point", "intensity": 100 }));
    let spot = g.light(json!({ "type": "spot", "spot": { "innerConeAngle": 0.2, "outerConeAngle": 0.5 } }));
    let l1 = g.node(
        json!({ "extensions": { "KHR_lights_punctual": { "light": point } }, "translation": [1, 1, 0] }),
    );
    let l2 = g.node(json!({ "extensions": { "KHR_lights_punctual": { "light": spot } } }));
    g.scene(&[parent, emitter, cam, l1, l2]);
    g
}

/// Imports `path` and, if that succeeds, builds it small: neither may panic.
fn read_and_build(path: &Path) {
    if let Ok(mut imported) = raytrace::import::gltf(path) {
        imported.file.render.width = 8;
        let _ = imported.file.build::<f64>();
    }
}

/// `bytes` with each `(position, value)` edit applied (positions taken modulo the length),
/// then cut to `keep` of its length (1.0: whole).
fn edited(bytes: &[u8], edits: &[(usize, u8)], keep: f64) -> Vec<u8> {
    let mut out = bytes.to_vec();
    for &(at, value) in edits {
        let n = out.len();
        out[at % n] = value;
    }
    out.truncate((out.len() as f64 * keep) as usize);
    out
}

/// The JSON pointer of every number in `v`, under `at`.
fn pointers(v: &serde_json::Value, at: String, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Number(_) => out.push(at),
        serde_json::Value::Array(a) => {
            for (k, x) in a.iter().enumerate() {
                pointers(x, format!("{at}/{k}"), out);
            }
        }
        serde_json::Value::Object(o) => {
            for (k, x) in o {
                pointers(x, format!("{at}/{k}"), out);
            }
        }
        _ => {}
    }
}

#[test]
fn the_asset_the_edits_start_from_is_read() {
    let dir = folder("fuzz_base");
    let g = asset();
    for path in [g.save_glb(&dir, "a"), g.save_embedded(&dir, "a")] {
        let imported = super::import(&path);
        let built = imported.file.build::<f64>().unwrap();
        assert_eq!(built.summary.lights, 2);
        assert_eq!(built.summary.emitters, 1);
    }
    std::fs::remove_dir_all(dir).unwrap();
}

proptest! {
    #![proptest_config(crate::common::config(128, 0x91F7_0B1D, "proptest-regressions/gltf_import.txt"))]

    #[test]
    fn arbitrary_bytes_are_refused_or_read_without_panicking(
        bytes in proptest::collection::vec(any::<u8>(), 0..600),
        glb_header in any::<bool>(),
    ) {
        let dir = folder("fuzz_bytes");
        let mut bytes = bytes;
        if glb_header {
            // Past the magic, so the container's own checks are reached.
            let mut with = b"glTF\x02\0\0\0".to_vec();
            with.extend_from_slice(&bytes);
            bytes = with;
        }
        for name in ["x.glb", "x.gltf"] {
            std::fs::write(dir.join(name), &bytes).unwrap();
            read_and_build(&dir.join(name));
        }
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn numbers_of_a_real_file_changed_are_refused_or_read_without_panicking(
        edits in proptest::collection::vec((any::<usize>(), prop_oneof![
            Just(json!(0)), Just(json!(1)), Just(json!(2)), Just(json!(3)), Just(json!(-1)),
            Just(json!(4_294_967_295u64)), Just(json!(1e30)), Just(json!(0.5)), Just(json!(-0.0)),
            Just(json!(5126)), Just(json!(5121)), Just(json!(5123)), (0..64u32).prop_map(|n| json!(n)),
        ]), 1..5),
        binary in any::<bool>(),
    ) {
        // Indices, counts, offsets, strides, factors and transforms are all numbers: each
        // edit sets one of them, so the file stays JSON and often valid glTF.
        let dir = folder("fuzz_numbers");
        let mut g = asset();
        let mut numbers = Vec::new();
        pointers(&g.json, String::new(), &mut numbers);
        for (k, value) in edits {
            let at = &numbers[k % numbers.len()];
            *g.json.pointer_mut(at).unwrap() = value;
        }
        let path = if binary { g.save_glb(&dir, "n") } else { g.save_embedded(&dir, "n") };
        read_and_build(&path);
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn edits_of_a_real_file_are_refused_or_read_without_panicking(
        edits in proptest::collection::vec((any::<usize>(), any::<u8>()), 0..6),
        keep in prop_oneof![Just(1.0), 0.0..1.0f64],
        binary in any::<bool>(),
    ) {
        let dir = folder("fuzz_edits");
        let g = asset();
        let (name, bytes) = if binary {
            ("e.glb", g.glb())
        } else {
            let text = g.json_text(Some(&format!(
                "data:application/octet-stream;base64,{}",
                super::write::base64(&g.bin)
            )));
            ("e.gltf", text.into_bytes())
        };
        std::fs::write(dir.join(name), edited(&bytes, &edits, keep)).unwrap();
        read_and_build(&dir.join(name));
        std::fs::remove_dir_all(dir).unwrap();
    }
}
