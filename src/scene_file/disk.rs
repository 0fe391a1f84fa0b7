//! A `type = "disk"` object's shape: by its centre, normal and radius, or by a `matrix`
//! placing Mitsuba's unit disk.

use super::check::blame;
use super::location::KeyPath;
use super::make::Solid;
use super::model::Triple;
use super::transform::Placement;
use crate::error::{Error, Result};
use crate::transform::Affine;

/// The disk the object at `at` describes: `center`, `normal` and `radius`, or, instead of
/// them (they must then be at their defaults), the unit disk placed by `matrix`.
pub(super) fn solid(
    (root, at): (&KeyPath, &KeyPath),
    center: Triple,
    normal: Triple,
    radius: f64,
    matrix: Option<[[f64; 4]; 3]>,
) -> Result<Solid> {
    let Some(rows) = matrix else {
        return Ok(Solid::Disk {
            center,
            normal,
            radius,
        });
    };
    if center != [0.0; 3] || normal != [0.0, 0.0, 1.0] || radius != 1.0 {
        return Err(at
            .key("matrix")
            .error("give either `matrix` or `center`, `normal` and `radius`, not both"));
    }
    // The map's own errors at `matrix` itself, where the mistake is written.
    let at_matrix = |e: Error| match e {
        Error::InvalidValue { field, reason } => at.key("matrix").error_about(Some(field), reason),
        other => blame(root, &at.key("matrix"), other),
    };
    let map = Affine::from_rows(rows).map_err(at_matrix)?;
    // Refused as a mesh's map is: a map that flattens space has no normal (M⁻ᵀẑ).
    Placement::map(map).map_err(at_matrix)?;
    Ok(by_map(&map))
}

/// The unit disk placed by `map`: its centre `M·0`, axes `M·x̂` and `M·ŷ`, flipped when
/// `det M < 0` (a normal goes by `M⁻ᵀ`, and `M⁻ᵀẑ = (M·x̂ × M·ŷ)/det M`).
pub(super) fn by_map(map: &Affine) -> Solid {
    let r = map.rows();
    let column = |j: usize| [r[0][j], r[1][j], r[2][j]];
    let [u, v, w] = [column(0), column(1), column(2)];
    let cross = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let det = cross[0] * w[0] + cross[1] * w[1] + cross[2] * w[2];
    Solid::DiskAxes {
        center: column(3),
        u,
        v,
        flipped: det < 0.0,
    }
}
