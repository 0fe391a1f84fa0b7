//! The node hierarchy of the scene a glTF file shows: every node reached from the scene's
//! roots, with its map to the world, `world = parent · local`, where `local` is the node's
//! `matrix` or `T · R · S` of its `translation`, `rotation` (a unit quaternion) and
//! `scale`.

use ::gltf::scene::Transform;

/// An affine map's rows `[L | t]`: `p ↦ L·p + t`.
pub(super) type Rows = [[f64; 4]; 3];

/// The identity map.
pub(super) const IDENTITY: Rows = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]];

/// A node of the scene and its map to the world.
pub(super) struct Placed {
    /// The node's index.
    pub node: usize,
    /// Its map to the world.
    pub world: Rows,
}

/// The scene shown: the file's `scene`, else its first; with none, every node that is
/// no node's child. Its nodes in depth-first order, each with its world map, and how the
/// scene was chosen.
///
/// # Errors
/// Naming the node (`nodes[3]`): a node reached twice (a node has at most one parent: a
/// cycle or a shared child), or a transform that is not finite, a `matrix` whose last
/// row is not `(0, 0, 0, 1)`, or a `rotation` that is not a quaternion of length 1.
pub(super) fn walk(doc: &::gltf::Document) -> Result<(Vec<Placed>, String), (String, String)> {
    let (roots, chosen): (Vec<::gltf::Node>, String) =
        match doc.default_scene().or_else(|| doc.scenes().next()) {
            Some(s) => {
                let how = if doc.default_scene().is_some() {
                    "the file's scene"
                } else {
                    "the first scene"
                };
                let name = s.name().map(|n| format!(" '{n}'")).unwrap_or_default();
                (
                    s.nodes().collect(),
                    format!("scenes[{}]{name} ({how})", s.index()),
                )
            }
            None => {
                let mut child = vec![false; doc.nodes().len()];
                for n in doc.nodes() {
                    for c in n.children() {
                        child[c.index()] = true;
                    }
                }
                let roots = doc.nodes().filter(|n| !child[n.index()]).collect();
                (roots, "no scenes: every node that is no node's child".to_string())
            }
        };
    let mut seen = vec![false; doc.nodes().len()];
    let mut placed = Vec::new();
    // Depth first, children in their order: the stack holds them reversed.
    let mut stack: Vec<(::gltf::Node, Rows)> = roots.into_iter().rev().map(|n| (n, IDENTITY)).collect();
    while let Some((node, parent)) = stack.pop() {
        let at = format!("nodes[{}]", node.index());
        if std::mem::replace(&mut seen[node.index()], true) {
            return Err((
                at,
                "reached twice from the scene: a node has at most one parent (the hierarchy has a cycle or \
                 a shared child)"
                    .into(),
            ));
        }
        let world = then(&local(&node.transform()).map_err(|why| (at, why))?, &parent);
        for c in node.children().collect::<Vec<_>>().into_iter().rev() {
            stack.push((c, world));
        }
        placed.push(Placed {
            node: node.index(),
            world,
        });
    }
    Ok((placed, chosen))
}

/// `b ∘ a`: the map `a`, then `b`.
pub(super) fn then(a: &Rows, b: &Rows) -> Rows {
    let mut out = [[0.0; 4]; 3];
    for i in 0..3 {
        for j in 0..4 {
            let t = if j == 3 { b[i][3] } else { 0.0 };
            out[i][j] = b[i][0] * a[0][j] + b[i][1] * a[1][j] + b[i][2] * a[2][j] + t;
        }
    }
    out
}

/// The determinant of the linear part: negative for a map that mirrors space.
pub(super) fn determinant(m: &Rows) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// The map of a node's own transform.
fn local(t: &Transform) -> Result<Rows, String> {
    match *t {
        Transform::Matrix { matrix: m } => {
            // Column-major: m[column][row].
            let all: Vec<f64> = m.iter().flatten().map(|&x| f64::from(x)).collect();
            if !all.iter().all(|x| x.is_finite()) {
                return Err("`matrix` has an entry that is not finite".into());
            }
            if m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0 {
                return Err(format!(
                    "`matrix`'s last row is ({}, {}, {}, {}): an affine map's is (0, 0, 0, 1)",
                    m[0][3], m[1][3], m[2][3], m[3][3]
                ));
            }
            Ok([0, 1, 2].map(|i| [0, 1, 2, 3].map(|j| f64::from(m[j][i]))))
        }
        Transform::Decomposed {
            translation,
            rotation,
            scale,
        } => {
            let [t, q, s] = [&translation[..], &rotation[..], &scale[..]];
            if !t.iter().chain(q).chain(s).all(|x| x.is_finite()) {
                return Err("`translation`, `rotation` or `scale` has a value that is not finite".into());
            }
            let q = rotation.map(f64::from);
            let length = q.iter().map(|x| x * x).sum::<f64>().sqrt();
            // The specification asks for unit quaternions; writers round them to f32.
            if (length - 1.0).abs() > 1e-3 {
                return Err(format!(
                    "`rotation` {q:?} has length {length}: a rotation is a unit quaternion (x, y, z, w)"
                ));
            }
            let [x, y, z, w] = q.map(|c| c / length);
            // The rotation matrix of the unit quaternion (x, y, z, w).
            let r = [
                [
                    1.0 - 2.0 * (y * y + z * z),
                    2.0 * (x * y - z * w),
                    2.0 * (x * z + y * w),
                ],
                [
                    2.0 * (x * y + z * w),
                    1.0 - 2.0 * (x * x + z * z),
                    2.0 * (y * z - x * w),
                ],
                [
                    2.0 * (x * z - y * w),
                    2.0 * (y * z + x * w),
                    1.0 - 2.0 * (x * x + y * y),
                ],
            ];
            let s = scale.map(f64::from);
            // T · R · S: the columns of R scaled, then moved.
            Ok([0, 1, 2].map(|i| {
                [
                    r[i][0] * s[0],
                    r[i][1] * s[1],
                    r[i][2] * s[2],
                    f64::from(translation[i]),
                ]
            }))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trs_is_translation_after_rotation_after_scale() {
        // A quarter turn about y: x goes to −z.
        let h = std::f32::consts::FRAC_1_SQRT_2;
        let m = local(&Transform::Decomposed {
            translation: [1.0, 2.0, 3.0],
            rotation: [0.0, h, 0.0, h],
            scale: [2.0, 1.0, 1.0],
        })
        .unwrap();
        let p = [1.0, 0.0, 0.0];
        let image: Vec<f64> = m
            .iter()
            .map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3])
            .collect();
        for (got, want) in image.iter().zip([1.0, 2.0, 1.0]) {
            assert!((got - want).abs() < 1e-6, "{image:?}");
        }
    }

    #[test]
    fn a_matrix_is_read_column_by_column() {
        let mut m = [[0.0f32; 4]; 4];
        for (i, col) in m.iter_mut().enumerate() {
            col[i] = 1.0;
        }
        m[3] = [5.0, 6.0, 7.0, 1.0];
        let rows = local(&Transform::Matrix { matrix: m }).unwrap();
        assert_eq!(rows[0], [1.0, 0.0, 0.0, 5.0]);
        assert_eq!(rows[2], [0.0, 0.0, 1.0, 7.0]);
        m[0][3] = 1.0;
        assert!(
            local(&Transform::Matrix { matrix: m })
                .unwrap_err()
                .contains("last row")
        );
    }

    #[test]
    fn composition_applies_the_child_first() {
        let parent = [[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]];
        let child = [[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]];
        // The child moves by +x, then the parent turns +x to +y.
        let w = then(&child, &parent);
        assert_eq!([w[0][3], w[1][3], w[2][3]], [0.0, 1.0, 0.0]);
        assert_eq!(determinant(&w), 1.0);
    }
}
