//! Bad glTF files, each a clear error naming the file and the place (a JSON path, or the
//! line and column of malformed JSON), never a panic, and never an allocation the file's
//! bytes do not back: an accessor out of range, a buffer shorter than it declares, a huge
//! declared count, a missing buffer or image file, malformed JSON, a broken `.glb`.

use super::write::{Gltf, folder};
use raytrace::Error;
use serde_json::json;
use std::path::Path;

/// A good file: one textured triangle, its image a file beside it.
fn good() -> Gltf {
    let mut g = Gltf::new();
    let image = g.push("images", json!({ "uri": "texture.png" }));
    let texture = g.texture(image);
    g.push(
        "materials",
        json!({ "pbrMetallicRoughness": { "baseColorTexture": { "index": texture } } }),
    );
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
    g
}

/// The error importing `path` gives, as text; panics if it imports.
fn error_of(path: &Path) -> String {
    match raytrace::import::gltf(path) {
        Ok(_) => panic!("{} was read", path.display()),
        Err(e @ (Error::SceneFile { .. } | Error::Image { .. })) => e.to_string(),
        Err(other) => panic!("not a file error: {other:?}"),
    }
}

fn assert_has(text: &str, words: &[&str]) {
    for w in words {
        assert!(text.contains(w), "`{w}` missing from: {text}");
    }
}

#[test]
fn a_good_file_is_read_and_each_edit_of_it_is_refused_at_its_place() {
    let dir = folder("bad");
    std::fs::write(dir.join("texture.png"), {
        let mut g = Gltf::new();
        g.png(1, 1, &[[200, 100, 50]]);
        g.bin
    })
    .unwrap();
    let path = good().save_gltf(&dir, "good");
    let imported = raytrace::import::gltf(&path).unwrap();
    imported.file.build::<f64>().unwrap();
    // The image file is among the scene's inputs.
    assert!(imported.file.input_files().contains(&dir.join("texture.png")));

    // An accessor whose count runs past its buffer view.
    let mut g = good();
    g.json["accessors"][0]["count"] = json!(4);
    assert_has(
        &error_of(&g.save_gltf(&dir, "e")),
        &["meshes[0].primitives[0]", "POSITION", "run past bufferView"],
    );
    // A huge declared count: refused before anything is allocated for it.
    g.json["accessors"][0]["count"] = json!(1u64 << 40);
    assert_has(
        &error_of(&g.save_glb(&dir, "e")),
        &["1099511627776 elements", "run past"],
    );
    // A buffer view past its buffer.
    let mut g = good();
    g.json["bufferViews"][1]["byteOffset"] = json!(1000);
    assert_has(
        &error_of(&g.save_gltf(&dir, "e")),
        &["bufferView 1", "runs past its buffer"],
    );
    // An index past the vertices.
    let mut g = good();
    let at = g.bin.len() - 4;
    g.bin[at..].copy_from_slice(&7u32.to_le_bytes());
    assert_has(
        &error_of(&g.save_glb(&dir, "e")),
        &["meshes[0].primitives[0]", "vertex index 7 out of range"],
    );
    // A reference to an accessor that does not exist.
    let mut g = good();
    g.json["meshes"][0]["primitives"][0]["indices"] = json!(99);
    assert_has(
        &error_of(&g.save_glb(&dir, "e")),
        &["meshes[0].primitives[0].indices", "invalid glTF"],
    );
    // A buffer shorter than it declares.
    let g = good();
    let path = g.save_gltf(&dir, "short");
    let bin = std::fs::read(dir.join("short.bin")).unwrap();
    std::fs::write(dir.join("short.bin"), &bin[..bin.len() - 5]).unwrap();
    assert_has(&error_of(&path), &["buffers[0]", "declares byteLength"]);
    // A missing buffer file, a missing image file.
    std::fs::remove_file(dir.join("short.bin")).unwrap();
    assert_has(&error_of(&path), &["buffers[0].uri", "short.bin", "cannot open"]);
    std::fs::remove_file(dir.join("texture.png")).unwrap();
    assert_has(
        &error_of(&good().save_glb(&dir, "e")),
        &["texture.png", "cannot open the image"],
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn malformed_json_is_reported_at_its_line_and_column() {
    let dir = folder("json");
    let path = dir.join("broken.gltf");
    std::fs::write(
        &path,
        "{\n  \"asset\": { \"version\": \"2.0\" },\n  \"nodes\": [ { \"mesh\": 0, } ]\n}\n",
    )
    .unwrap();
    assert_has(
        &error_of(&path),
        &["broken.gltf", "line 3, column", "not glTF JSON"],
    );
    std::fs::write(&path, "").unwrap();
    assert_has(&error_of(&path), &["line 1, column 0"]);
    // JSON, but not glTF: no asset.
    std::fs::write(&path, "{}").unwrap();
    assert_has(&error_of(&path), &["not glTF JSON", "asset"]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_broken_glb_container_is_refused_whole() {
    let dir = folder("glb");
    let glb = good().glb();
    let path = dir.join("b.glb");
    let mut cases: Vec<(Vec<u8>, &str)> = vec![
        (glb[..10].to_vec(), "shorter than its 12-byte header"),
        (glb[..glb.len() - 4].to_vec(), "declares"),
    ];
    // A declared length below the header's own 12 bytes (which the gltf crate's own
    // reader would underflow on).
    let mut tiny = glb.clone();
    tiny[8..12].copy_from_slice(&4u32.to_le_bytes());
    cases.push((tiny, "declares 4 bytes"));
    let mut version = glb.clone();
    version[4] = 1;
    cases.push((version, "version 1"));
    // A JSON chunk longer than the file.
    let mut chunk = glb.clone();
    chunk[12..16].copy_from_slice(&u32::MAX.to_le_bytes());
    cases.push((chunk, "JSON chunk declares"));
    for (bytes, words) in cases {
        std::fs::write(&path, &bytes).unwrap();
        assert_has(&error_of(&path), &["b.glb", "the whole file", words]);
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_node_reached_twice_is_an_error_not_an_endless_walk() {
    let dir = folder("cycle");
    let mut g = Gltf::new();
    let a = g.node(json!({ "children": [1] }));
    g.node(json!({ "children": [a] }));
    g.scene(&[a]);
    assert_has(&error_of(&g.save_glb(&dir, "c")), &["nodes[0]", "reached twice"]);
    std::fs::remove_dir_all(dir).unwrap();
}
