//! Affine transforms of 3-D space, in `f64`: placing meshes and instances, turning an
//! environment map, and reading the transforms of scenes made elsewhere.

use crate::error::{Error, Field, Result};

/// An affine map `p ↦ L·p + t`, stored as the three rows `[L | t]` of its 4×4 matrix.
///
/// Every point and vector goes through [`Affine::point`] and [`Affine::vector`], one
/// rounding order for all: a mesh placed by a transform and the same mesh instanced under
/// it get the same vertices, bit for bit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine {
    rows: [[f64; 4]; 3],
}

impl Default for Affine {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Affine {
    /// The identity.
    pub const IDENTITY: Self = Self {
        rows: [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]],
    };

    /// The map of the rows `[L | t]`.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::Transform`]) for a value that is not finite or a
    /// linear part that cannot be inverted (it flattens space).
    pub fn from_rows(rows: [[f64; 4]; 3]) -> Result<Self> {
        let map = Self { rows };
        if !rows.iter().flatten().all(|x| x.is_finite()) {
            return Err(Error::invalid(Field::Transform, "every entry must be finite"));
        }
        if map.inverse().is_none() {
            return Err(Error::invalid(
                Field::Transform,
                "its linear part must be invertible (it may not flatten space)",
            ));
        }
        Ok(map)
    }

    /// The rows `[L | t]`.
    pub fn rows(&self) -> [[f64; 4]; 3] {
        self.rows
    }

    /// Moving by `t`.
    pub fn translate(t: [f64; 3]) -> Self {
        let mut m = Self::IDENTITY;
        for (row, x) in m.rows.iter_mut().zip(t) {
            row[3] = x;
        }
        m
    }

    /// Scaling each axis by its factor.
    pub fn scale(s: [f64; 3]) -> Self {
        let mut m = Self::IDENTITY;
        for (i, x) in s.into_iter().enumerate() {
            m.rows[i][i] = x;
        }
        m
    }

    /// Turning by `degrees` about the unit `axis`, counter-clockwise looking down it toward
    /// the origin (the right-hand rule; Rodrigues' formula).
    pub fn rotate(axis: [f64; 3], degrees: f64) -> Self {
        let len = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        let [x, y, z] = axis.map(|a| a / len);
        let (s, c) = degrees.to_radians().sin_cos();
        let k = 1.0 - c;
        Self {
            rows: [
                [c + x * x * k, x * y * k - z * s, x * z * k + y * s, 0.0],
                [y * x * k + z * s, c + y * y * k, y * z * k - x * s, 0.0],
                [z * x * k - y * s, z * y * k + x * s, c + z * z * k, 0.0],
            ],
        }
    }

    /// A camera's frame, as Mitsuba's `lookat`: the origin at `from`, local `+z` toward
    /// `to`, local `+x = up × z` (normalised) and `+y = z × x`, as near `up` as it can be.
    /// `None` if `from = to` or `up` is along the view.
    pub fn look_at(from: [f64; 3], to: [f64; 3], up: [f64; 3]) -> Option<Self> {
        let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let cross = |a: [f64; 3], b: [f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let unit = |a: [f64; 3]| {
            let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
            (l > 0.0 && l.is_finite()).then(|| a.map(|c| c / l))
        };
        let z = unit(sub(to, from))?;
        let x = unit(cross(unit(up)?, z))?;
        let y = cross(z, x);
        Some(Self {
            rows: [0, 1, 2].map(|i| [x[i], y[i], z[i], from[i]]),
        })
    }

    /// `next ∘ self`: this map, then `next`.
    #[must_use]
    pub fn then(&self, next: &Self) -> Self {
        let (a, b) = (&next.rows, &self.rows);
        let mut rows = [[0.0; 4]; 3];
        for i in 0..3 {
            for j in 0..4 {
                let translate = if j == 3 { a[i][3] } else { 0.0 };
                rows[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + translate;
            }
        }
        Self { rows }
    }

    /// The inverse map, if the linear part is invertible (its determinant, relative to
    /// the size of its entries, is not below `10⁻¹²`).
    pub fn inverse(&self) -> Option<Self> {
        let m = &self.rows;
        let cof = |r0: usize, r1: usize, c0: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
        // The adjugate's columns are the cofactors of the rows.
        let adj = [
            [cof(1, 2, 1, 2), -cof(0, 2, 1, 2), cof(0, 1, 1, 2)],
            [-cof(1, 2, 0, 2), cof(0, 2, 0, 2), -cof(0, 1, 0, 2)],
            [cof(1, 2, 0, 1), -cof(0, 2, 0, 1), cof(0, 1, 0, 1)],
        ];
        let det = m[0][0] * adj[0][0] + m[0][1] * adj[1][0] + m[0][2] * adj[2][0];
        let size = m.iter().flat_map(|r| &r[..3]).fold(0.0f64, |s, x| s.max(x.abs()));
        let invertible = det.abs() > 1e-12 * size * size * size && det.is_finite();
        if !invertible {
            return None;
        }
        let mut rows = [[0.0; 4]; 3];
        for i in 0..3 {
            for j in 0..3 {
                rows[i][j] = adj[i][j] / det;
            }
            rows[i][3] = -(rows[i][0] * m[0][3] + rows[i][1] * m[1][3] + rows[i][2] * m[2][3]);
        }
        Some(Self { rows })
    }

    /// The image of the point `p`: `L·p + t`.
    #[inline]
    pub fn point(&self, p: [f64; 3]) -> [f64; 3] {
        self.rows.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3])
    }

    /// The image of the vector `v`: `L·v`.
    #[inline]
    pub fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        self.rows.map(|r| r[0] * v[0] + r[1] * v[1] + r[2] * v[2])
    }

    /// The largest absolute row sum of the linear part, `‖L‖∞`: how much the map can
    /// stretch a vector, in the maximum norm.
    pub fn stretch(&self) -> f64 {
        self.rows
            .iter()
            .map(|r| r[0].abs() + r[1].abs() + r[2].abs())
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    #[test]
    fn composes_inverts_and_turns_by_the_right_hand_rule() {
        let turn = Affine::rotate([0.0, 0.0, 1.0], 90.0);
        assert!(close(turn.point([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]));
        let m = Affine::scale([2.0, 3.0, 4.0])
            .then(&Affine::rotate([1.0, 2.0, 3.0], 40.0))
            .then(&Affine::translate([5.0, -1.0, 2.0]));
        let inv = m.inverse().unwrap();
        for p in [[1.0, 2.0, 3.0], [-4.0, 0.5, 9.0]] {
            assert!(close(inv.point(m.point(p)), p));
        }
        assert!(close(m.point([0.0; 3]), [5.0, -1.0, 2.0]));
        assert!(Affine::scale([1.0, 0.0, 1.0]).inverse().is_none());
        assert!(
            Affine::from_rows([
                [1.0, 0.0, 0.0, f64::NAN],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0]
            ])
            .is_err()
        );
    }

    #[test]
    fn look_at_faces_its_target() {
        let m = Affine::look_at([1.0, 2.0, 3.0], [1.0, 2.0, 10.0], [0.0, 1.0, 0.0]).unwrap();
        assert!(close(m.point([0.0; 3]), [1.0, 2.0, 3.0]));
        assert!(close(m.vector([0.0, 0.0, 1.0]), [0.0, 0.0, 1.0]));
        assert!(close(m.vector([0.0, 1.0, 0.0]), [0.0, 1.0, 0.0]));
        assert!(Affine::look_at([0.0; 3], [0.0; 3], [0.0, 1.0, 0.0]).is_none());
    }
}
