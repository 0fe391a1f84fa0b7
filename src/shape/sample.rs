//! Points drawn on a shape for next-event estimation, and the change of density from
//! area to solid angle that sampling by area needs.

use super::Hit;
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::sampling::uniform_triangle;
use crate::vec3::Vec3;

/// A point drawn on a shape as seen from a point `from` ([`Hittable::sample`](super::Hittable::sample)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceSample<F> {
    /// The point on the surface.
    pub point: Vec3<F>,
    /// The unit outward normal there (the front face's side).
    pub normal: Vec3<F>,
    /// The part drawn: a mesh's triangle; 0 for a shape of one part.
    pub part: u32,
    /// The density of the direction from `from` to `point`, per unit solid angle.
    pub pdf: F,
}

/// A density `p_A` per unit area at `point` (unit normal `normal`) as a density per unit
/// solid angle at `from`: `p_ω = p_A·d²/|cos θ|`, `d = |point − from|`, `θ` between the
/// normal and the direction (`dA·|cos θ|/d²` is the solid angle `dA` subtends). Infinite
/// when the direction grazes the surface; NaN when `point` is `from`.
#[inline]
pub fn area_to_solid_angle<F: Float>(pdf_area: F, from: Vec3<F>, point: Vec3<F>, normal: Vec3<F>) -> F {
    let v = point - from;
    let d2 = v.length_squared();
    pdf_area * d2 * d2.sqrt() / normal.dot(v).abs()
}

/// [`area_to_solid_angle`] for the point where `ray` (unit direction) hits a surface:
/// `d = t`, `|cos θ| = |N·D|`.
#[inline]
pub fn hit_solid_angle<F: Float>(pdf_area: F, ray: &Ray<F>, hit: &Hit<F>) -> F {
    pdf_area * hit.t * hit.t / hit.normal.dot(ray.direction).abs()
}

/// The area of the triangle `[A, B, C]`: `|(B − A)×(C − A)|/2`.
#[inline]
pub(crate) fn triangle_area<F: Float>(&[a, b, c]: &[Vec3<F>; 3]) -> F {
    (b - a).cross(c - a).length() * lit::<F>(0.5)
}

/// A point of the triangle `[A, B, C]` (part `part` of its shape, unit outward normal
/// `normal`) at the uniform barycentric weights [`uniform_triangle`]`(u)` draws,
/// `b₀A + b₁B + b₂C`, its density `pdf_area` per area converted to solid angle at `from`.
#[inline]
pub(crate) fn sample_triangle<F: Float>(
    &[a, b, c]: &[Vec3<F>; 3],
    normal: Vec3<F>,
    part: u32,
    pdf_area: F,
    from: Vec3<F>,
    u: [f64; 2],
) -> SurfaceSample<F> {
    let [b0, b1, b2] = uniform_triangle(u);
    let point = a * lit::<F>(b0) + b * lit::<F>(b1) + c * lit::<F>(b2);
    SurfaceSample {
        point,
        normal,
        part,
        pdf: area_to_solid_angle(pdf_area, from, point, normal),
    }
}
