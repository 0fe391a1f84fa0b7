//! The committed test meshes (tests/data/meshes) are what the tests that place them
//! assume: closed polyhedra, wound outward, of the volume their edge gives.

use raytrace::mesh::{MeshData, load};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Counts, for every edge, the triangles that cross it in each direction; a closed mesh wound
/// consistently crosses each edge once each way.
fn assert_closed(mesh: &MeshData) {
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for &[a, b, c] in &mesh.triangles {
        for edge in [(a, b), (b, c), (c, a)] {
            *edges.entry(edge).or_default() += 1;
        }
    }
    for (&(a, b), &count) in &edges {
        assert_eq!(count, 1, "edge {a}-{b} is crossed {count} times the same way");
        assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}-{b} has one side only");
    }
}

/// The enclosed volume, positive when the triangles are wound outward (divergence theorem).
fn volume(mesh: &MeshData) -> f64 {
    let p = |i: u32| mesh.positions[i as usize];
    let sixfold: f64 = mesh
        .triangles
        .iter()
        .map(|&[a, b, c]| p(a).dot(p(b).cross(p(c))))
        .sum();
    sixfold / 6.0
}

fn committed(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/meshes")
        .join(name)
}

#[test]
fn the_committed_meshes_are_closed_polyhedra() {
    let tetrahedron = load(&committed("tetrahedron.obj")).unwrap();
    assert_eq!((tetrahedron.positions.len(), tetrahedron.triangles.len()), (4, 4));
    assert_closed(&tetrahedron);
    // Edge 2√2: V = a³/(6√2) = 8/3.
    approx::assert_relative_eq!(volume(&tetrahedron), 8.0 / 3.0, epsilon = 1e-12);

    let icosahedron = load(&committed("icosahedron.ply")).unwrap();
    assert_eq!(
        (icosahedron.positions.len(), icosahedron.triangles.len()),
        (12, 20)
    );
    assert_eq!(icosahedron.skipped_degenerate, 0);
    assert_closed(&icosahedron);
    // Edge 2: V = 5(3 + √5)/12 · a³.
    let expected = 5.0 * (3.0 + 5f64.sqrt()) / 12.0 * 8.0;
    approx::assert_relative_eq!(volume(&icosahedron), expected, epsilon = 1e-12);
}

#[test]
fn the_closedness_check_sees_a_missing_or_flipped_face() {
    let mut mesh = load(&committed("tetrahedron.obj")).unwrap();
    mesh.triangles[0].swap(1, 2);
    assert!(std::panic::catch_unwind(|| assert_closed(&mesh)).is_err());
    mesh.triangles.remove(0);
    assert!(std::panic::catch_unwind(|| assert_closed(&mesh)).is_err());
}
