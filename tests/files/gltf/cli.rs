//! `raytrace check` and `raytrace render` on glTF files, as a user runs them.

use super::write::{Gltf, folder};
use serde_json::json;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

/// A lit cube-less scene: a square, a camera, a point light, and an extension not read.
fn model() -> Gltf {
    let mut g = Gltf::new();
    g.push(
        "materials",
        json!({ "name": "paint", "pbrMetallicRoughness": { "metallicFactor": 0 } }),
    );
    let square = [
        [-1.0, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ];
    let mesh = g.mesh(&square, None, None, &[0, 1, 2, 0, 2, 3], Some(0));
    let quad = g.node(json!({ "mesh": mesh, "name": "floor" }));
    let c = g.push(
        "cameras",
        json!({ "type": "perspective", "perspective": { "yfov": 0.8, "znear": 0.1 } }),
    );
    let cam = g.node(json!({ "camera": c, "translation": [0, 0, 4] }));
    let lamp = g.light(json!({ "type": "point", "intensity": 5000 }));
    let light = g.node(
        json!({ "extensions": { "KHR_lights_punctual": { "light": lamp } }, "translation": [0, 0, 1] }),
    );
    g.scene(&[quad, cam, light]);
    g.uses("KHR_materials_sheen");
    g
}

fn run(args: &[&str]) -> (Option<i32>, String) {
    let o = Command::new(BIN).args(args).output().expect("the binary runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    (o.status.code(), text)
}

#[test]
fn check_lists_what_was_read_and_render_writes_the_image() {
    let dir = folder("cli");
    let glb = model().save_glb(&dir, "model");
    let (code, text) = run(&["check", glb.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{text}");
    for words in [
        "valid",
        "read from glTF 2.0",
        "nodes[0] 'floor': meshes[0]",
        "`paint`: rough plastic",
        "cameras[0]",
        "point, intensity 5000",
        "not as the glTF file says: extensionsUsed: KHR_materials_sheen is not read",
        "2 triangles",
    ] {
        assert!(text.contains(words), "`{words}` missing from:\n{text}");
    }
    let out = dir.join("model.png");
    let (code, text) = run(&[
        "render",
        glb.to_str().unwrap(),
        "--width",
        "16",
        "--spp",
        "1",
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains("KHR_materials_sheen"),
        "the warning is shown: {text}"
    );
    assert!(out.exists());
    // The output may not overwrite the model it renders.
    let (code, text) = run(&[
        "render",
        glb.to_str().unwrap(),
        "--quiet",
        "--out",
        glb.to_str().unwrap(),
    ]);
    assert_ne!(code, Some(0), "{text}");
    // A broken file is an error naming it.
    std::fs::write(&glb, b"glTF\x02\0\0\0\x04\0\0\0").unwrap();
    let (code, text) = run(&["check", glb.to_str().unwrap()]);
    assert_ne!(code, Some(0));
    assert!(
        text.contains("model.glb") && text.contains("declares 4 bytes"),
        "{text}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn tiles_of_a_gltf_scene_carry_the_hash_of_its_buffer_file() {
    let dir = folder("cli_tiles");
    let gltf = model().save_gltf(&dir, "model");
    let tile = |k: u32| {
        let out = dir.join(format!("t{k}.rtile"));
        let (code, text) = run(&[
            "render",
            gltf.to_str().unwrap(),
            "--width",
            "8",
            "--tile",
            &format!("{k}/2"),
            "--quiet",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(0), "{text}");
        out
    };
    let merge = |a: &std::path::Path, b: &std::path::Path| {
        let out = dir.join("merged.png");
        run(&[
            "merge",
            a.to_str().unwrap(),
            b.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let (one, two) = (tile(1), tile(2));
    assert_eq!(merge(&one, &two).0, Some(0));
    // The same glTF file over other buffer bytes (the square moved): the tiles do not merge.
    let bin = dir.join("model.bin");
    let mut bytes = std::fs::read(&bin).unwrap();
    bytes[8..12].copy_from_slice(&0.5f32.to_le_bytes());
    std::fs::write(&bin, bytes).unwrap();
    let two = tile(2);
    let (code, text) = merge(&one, &two);
    assert_ne!(code, Some(0));
    assert!(text.contains("of scene"), "{text}");
    std::fs::remove_dir_all(dir).unwrap();
}
