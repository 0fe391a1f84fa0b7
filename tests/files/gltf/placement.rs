//! Where glTF's nodes put their meshes: a child's map composed under its parent's (`TRS`
//! and `matrix`), a mesh several nodes place shared as instances when that renders the
//! same, a mirroring node keeping its faces' fronts, and the three ways of storing a
//! buffer giving one scene.

use super::write::{Gltf, folder};
use super::{apply, import, matrix_of};
use raytrace::scene_file::ObjectSpec;
use serde_json::json;

const TRIANGLE: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6)
}

#[test]
fn a_nodes_map_puts_each_vertex_where_its_parents_and_its_own_transform_say() {
    let mut g = Gltf::new();
    let mesh = g.mesh(&TRIANGLE, None, None, &[0, 1, 2], None);
    // The child moves by +5 along z (a column-major matrix); the parent scales by 2, turns
    // a quarter about z (x → y, y → −x) and moves by (1, 2, 3).
    let child = g.node(json!({ "mesh": mesh, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1] }));
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let parent = g.node(json!({
        "children": [child], "translation": [1, 2, 3], "rotation": [0, 0, h, h], "scale": [2, 2, 2]
    }));
    g.scene(&[parent]);
    let dir = folder("transforms");
    let imported = import(&g.save_gltf(&dir, "t"));
    let objects = &imported.file.objects;
    assert_eq!(objects.len(), 1, "{objects:?}");
    let m = matrix_of(&objects[0]);
    // By hand: v + (0, 0, 5), ×2, (x, y) → (−y, x), + (1, 2, 3).
    for (v, want) in [
        ([0.0, 0.0, 0.0], [1.0, 2.0, 13.0]),
        ([1.0, 0.0, 0.0], [1.0, 4.0, 13.0]),
        ([0.0, 1.0, 0.0], [-1.0, 2.0, 13.0]),
    ] {
        assert!(
            close(apply(&m, v), want),
            "{v:?} → {:?}, not {want:?}",
            apply(&m, v)
        );
    }
    // Built, the mesh lands there: its bounds are the placed vertices'.
    let built = imported.file.build::<f64>().unwrap();
    let b = built.summary.bounds.unwrap();
    assert!(close([b.min.x, b.min.y, b.min.z], [-1.0, 2.0, 13.0]), "{b:?}");
    assert!(close([b.max.x, b.max.y, b.max.z], [1.0, 4.0, 13.0]), "{b:?}");
    assert_eq!(built.summary.triangles, 1);
    std::fs::remove_dir_all(dir).unwrap();
}

/// A unit square at z = 0 facing +z, with the given normals, placed by two nodes.
fn twice_placed(normals: Option<&[[f32; 3]]>) -> Gltf {
    let mut g = Gltf::new();
    let square = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let material = g.push(
        "materials",
        json!({ "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0 } }),
    );
    let mesh = g.mesh(&square, normals, None, &[0, 1, 2, 0, 2, 3], Some(material));
    let a = g.node(json!({ "mesh": mesh, "translation": [-2, 0, 0] }));
    let b = g.node(json!({ "mesh": mesh, "translation": [2, 0, 0], "scale": [1, 3, 1] }));
    g.scene(&[a, b]);
    g
}

#[test]
fn a_mesh_placed_by_two_nodes_is_one_shared_mesh_when_that_renders_the_same() {
    let dir = folder("instances");
    let flat = [[0.0, 0.0, 1.0]; 4];
    for (normals, shared) in [(None, true), (Some(&flat[..]), true)] {
        let imported = import(&twice_placed(normals).save_glb(&dir, "twice"));
        let f = &imported.file;
        assert_eq!(f.meshes.len(), 1, "{:?}", f.meshes);
        assert!(f.objects.iter().all(|o| matches!(o, ObjectSpec::Instance { .. })) == shared);
        let built = f.build::<f64>().unwrap();
        assert_eq!((built.summary.instances, built.summary.triangles), (2, 4));
        let b = built.summary.bounds.unwrap();
        // The second placement stretches y by 3 and moves by +2 in x.
        assert!(close([b.min.x, b.max.x, b.max.y], [-2.0, 3.0, 3.0]), "{b:?}");
    }
    // Smooth normals that are not the faces': instances would shade with the faces'
    // normals, so each node gets its own copy of the mesh.
    let bent = [
        [0.0, 0.6, 0.8],
        [0.0, 0.6, 0.8],
        [0.0, -0.6, 0.8],
        [0.0, -0.6, 0.8],
    ];
    let imported = import(&twice_placed(Some(&bent)).save_glb(&dir, "bent"));
    let f = &imported.file;
    assert!(f.meshes.is_empty());
    assert!(f.objects.iter().all(|o| matches!(o, ObjectSpec::Mesh { .. })));
    let built = f.build::<f64>().unwrap();
    assert_eq!((built.summary.meshes, built.summary.instances), (2, 0));
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_mirroring_node_winds_its_faces_the_other_way_so_their_fronts_stay_outside() {
    let mut g = Gltf::new();
    let mesh = g.mesh(&TRIANGLE, None, None, &[0, 1, 2], None);
    let plain = g.node(json!({ "mesh": mesh }));
    let mirrored = g.node(json!({ "mesh": mesh, "scale": [-1, 1, 1] }));
    g.scene(&[plain, mirrored]);
    let dir = folder("mirrored");
    let imported = import(&g.save_gltf(&dir, "m"));
    // Each placement is the only one of its winding: a mesh object each.
    let names: Vec<&String> = imported
        .file
        .objects
        .iter()
        .map(|o| match o {
            ObjectSpec::Mesh { file, .. } => file,
            other => panic!("{other:?}"),
        })
        .collect();
    let assets = imported.file.assets();
    let [a, b] = [0, 1].map(|k| assets.mesh(names[k]).unwrap().triangles.clone());
    assert_eq!(a, vec![[0, 1, 2]]);
    assert_eq!(
        b,
        vec![[0, 2, 1]],
        "the mirrored placement's triangle is wound the other way"
    );
    // Placed, the mirrored triangle's front (b − a) × (c − a) faces +z, as the plain one's.
    let m = matrix_of(&imported.file.objects[1]);
    let p = b[0].map(|i| apply(&m, TRIANGLE[i as usize].map(f64::from)));
    let (u, v) = (
        [0, 1, 2].map(|k| p[1][k] - p[0][k]),
        [0, 1, 2].map(|k| p[2][k] - p[0][k]),
    );
    assert!(u[0] * v[1] - u[1] * v[0] > 0.0, "{p:?}");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_glb_an_embedded_buffer_and_a_buffer_file_give_one_scene() {
    let mut g = Gltf::new();
    let uv = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    let normals = [[0.0, 0.0, 1.0]; 3];
    let mesh = g.mesh(&TRIANGLE, Some(&normals), Some(&uv), &[0, 1, 2], None);
    let node = g.node(json!({ "mesh": mesh, "translation": [0.5, 0, -1] }));
    g.scene(&[node]);
    let dir = folder("three_ways");
    let paths = [
        g.save_glb(&dir, "a"),
        g.save_embedded(&dir.join("embedded"), "a"),
        g.save_gltf(&dir, "a"),
    ];
    let meshes: Vec<_> = paths
        .iter()
        .map(|p| {
            let imported = import(p);
            let f = &imported.file;
            let ObjectSpec::Mesh { file, .. } = &f.objects[0] else {
                panic!()
            };
            let mesh = f.assets().mesh(file).unwrap().as_ref().clone();
            (mesh, matrix_of(&f.objects[0]), f.input_files())
        })
        .collect();
    assert_eq!(meshes[0].0, meshes[1].0);
    assert_eq!(meshes[0].0, meshes[2].0);
    assert_eq!(
        meshes[0].0.uvs,
        Some(uv.iter().map(|t| t.map(f64::from)).collect())
    );
    assert_eq!(meshes[0].1, meshes[2].1);
    // The files the scene depends on, hashed into a tile: the glTF file and its buffer
    // file, never the names of what is held in memory.
    assert_eq!(meshes[0].2, vec![paths[0].clone()]);
    assert_eq!(meshes[2].2, vec![paths[2].clone(), dir.join("a.bin")]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn points_and_lines_are_left_out_with_a_warning() {
    let mut g = Gltf::new();
    let position = g.floats(&TRIANGLE);
    let mesh = g.push(
        "meshes",
        json!({ "primitives": [
            { "attributes": { "POSITION": position }, "mode": 0 },
            { "attributes": { "POSITION": position }, "mode": 4 }
        ] }),
    );
    let node = g.node(json!({ "mesh": mesh }));
    g.scene(&[node]);
    let dir = folder("points");
    let imported = import(&g.save_glb(&dir, "p"));
    assert_eq!(imported.file.objects.len(), 1);
    let warned = imported
        .warnings
        .iter()
        .any(|w| w.contains("primitives[0]") && w.contains("POINTS"));
    assert!(warned, "{:?}", imported.warnings);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn quantized_attributes_are_read_as_the_specification_scales_them() {
    use super::write::UNSIGNED_SHORT;
    let mut g = Gltf::new();
    g.uses("KHR_mesh_quantization");
    g.json["extensionsRequired"] = json!(["KHR_mesh_quantization"]);
    // Positions as signed shorts, not normalized: their values as they are.
    let shorts: Vec<u8> = [0i16, 0, 0, 0, 300, 0, 0, 0, 0, 0, -2, 0]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let view = g.view(&shorts);
    let position = g.push(
        "accessors",
        json!({ "bufferView": view, "componentType": 5122, "count": 3, "type": "VEC3",
                "min": [0, 0, -2], "max": [300, 0, 0], "byteStride": 8 }),
    );
    // byteStride belongs to the view: 4 shorts per vertex (the fourth is padding).
    g.json["bufferViews"][view]["byteStride"] = json!(8);
    g.json["accessors"][position]
        .as_object_mut()
        .unwrap()
        .remove("byteStride");
    // Texture coordinates as normalized unsigned shorts: c / 65535.
    let uv: Vec<u8> = [0u16, 65535, 32768, 0, 65535, 13107]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let view = g.view(&uv);
    let uv = g.push(
        "accessors",
        json!({ "bufferView": view, "componentType": UNSIGNED_SHORT, "normalized": true, "count": 3, "type": "VEC2" }),
    );
    let mesh = g.push(
        "meshes",
        json!({ "primitives": [{ "attributes": { "POSITION": position, "TEXCOORD_0": uv } }] }),
    );
    let node = g.node(json!({ "mesh": mesh }));
    g.scene(&[node]);
    let dir = folder("quantized");
    let imported = import(&g.save_glb(&dir, "q"));
    let ObjectSpec::Mesh { file, .. } = &imported.file.objects[0] else {
        panic!()
    };
    let mesh = imported.file.assets().mesh(file).unwrap();
    let p: Vec<[f64; 3]> = mesh.positions.iter().map(|v| [v.x, v.y, v.z]).collect();
    assert_eq!(p, vec![[0.0, 0.0, 0.0], [300.0, 0.0, 0.0], [0.0, 0.0, -2.0]]);
    let want = [[0.0, 1.0], [32768.0 / 65535.0, 0.0], [1.0, 13107.0 / 65535.0]];
    assert_eq!(mesh.uvs.as_deref(), Some(&want[..]));
    std::fs::remove_dir_all(dir).unwrap();
}
