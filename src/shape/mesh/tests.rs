//! The mesh's tests.

use super::*;
use crate::shape::Triangle;

/// A unit square in the plane `z = −2` as two triangles, and a stray vertex.
fn square() -> (Vec<Vec3<f64>>, Vec<[u32; 3]>) {
    let v = |x, y| Vec3::new(x, y, -2.0);
    (
        vec![v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0), v(5.0, 5.0)],
        vec![[0, 1, 2], [0, 2, 3]],
    )
}

#[test]
fn triangles_are_the_triangle_shapes_bit_for_bit() {
    let (vertices, triangles) = square();
    let mesh = Mesh::new(vertices.clone(), triangles.clone()).unwrap();
    let shapes: Vec<Triangle<f64>> = triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| vertices[i as usize]);
            Triangle::new(a, b, c).unwrap()
        })
        .collect();
    for (x, y) in [(0.7, 0.2), (0.2, 0.7), (0.5, 0.5), (0.1, 0.0), (0.95, 0.9)] {
        let ray = Ray::new(Vec3::new(x, y, 0.0), Vec3::new(-0.05, 0.02, -1.0).normalize());
        let got = crate::shape::hit(&mesh, &ray, f64::INFINITY).unwrap();
        let want = shapes
            .iter()
            .filter_map(|s| crate::shape::hit(s, &ray, f64::INFINITY));
        let want = want.reduce(|a, b| if b.t < a.t { b } else { a }).unwrap();
        assert_eq!(got, want, "({x}, {y})");
    }
    assert_eq!(mesh.parts(), 2);
    assert_eq!(mesh.part_bounds(1), shapes[1].bounds());
}

#[test]
fn degenerate_triangles_are_left_out_and_bad_input_is_an_error() {
    let (vertices, mut triangles) = square();
    triangles.push([0, 1, 1]);
    triangles.push([0, 2, 0]);
    let mesh = Mesh::new(vertices.clone(), triangles).unwrap();
    assert_eq!((mesh.parts(), mesh.skipped_degenerate()), (2, 2));

    let err = |v: Vec<Vec3<f64>>, t: Vec<[u32; 3]>| Mesh::new(v, t).unwrap_err().to_string();
    assert!(err(vertices.clone(), vec![[0, 1, 9]]).contains("triangle 0 indexes a vertex past the 5"));
    assert!(err(vertices.clone(), vec![[0, 1, 1]]).contains("none of its 1 triangles"));
    let mut nan = vertices;
    nan[2].y = f64::NAN;
    assert!(err(nan, vec![[0, 1, 3]]).contains("vertex 2 is not finite"));
}
