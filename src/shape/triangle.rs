//! The triangle `ABC`, intersected watertight (Woop, Benthin and Wald 2013, as in
//! pbrt-v4's `IntersectTriangle`).

use super::sample::{sample_triangle, triangle_area};
use super::{Coordinates, Hit, Hittable, Intersection, Surface, SurfaceSample, hit_solid_angle};
use crate::aabb::Aabb;
use crate::error::{Error, Result};
use crate::float::Float;
use crate::ray::Ray;
use crate::validate;
use crate::vec3::Vec3;

/// A triangle with vertices `A`, `B`, `C`, hit from both sides.
///
/// Its outward normal is `(B − A)×(C − A)` normalized: the front face is the side from
/// which `A → B → C` runs counter-clockwise. Triangles sharing an edge or a vertex (a
/// mesh) are watertight: a ray through a shared edge or vertex hits at least one of
/// them ([`Triangle::intersect_watertight`]).
///
/// Its surface coordinates are Mitsuba 3's for a mesh without texture coordinates: the
/// barycentric weights of `B` and `C`, `uv = (b₁, b₂)`, with `∂p/∂u = B − A`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle<F> {
    a: Vec3<F>,
    b: Vec3<F>,
    c: Vec3<F>,
}

impl<F: Float> Triangle<F> {
    /// The triangle `ABC`.
    ///
    /// Rejects with [`Error::InvalidValue`] non-finite vertices (`Field::TriangleA`, `B`, `C`)
    /// and (`Field::Triangle`) degenerate triangles: those with `|(B − A)×(C − A)| ≤ γ(6)·|B − A|·|C − A|`, that is
    /// whose angle at `A` has a sine within `γ(6)` of zero (`3.6·10⁻⁷` in f32,
    /// `6.7·10⁻¹⁶` in f64), which includes collinear and coincident vertices.
    ///
    /// # Precision
    /// The threshold is the rounding error of the cross product: each of its components
    /// `uⱼvₖ − uₖvⱼ` (with `u = B − A`, `v = C − A` rounded) is within
    /// `γ(4)·(|uⱼvₖ| + |uₖvⱼ|)`, and the vector of those bounds has length at most
    /// `√2·γ(4)·|u||v| < γ(6)·|u||v|`. Below it the computed normal's direction is
    /// rounding noise. The test runs on `u` and `v` divided by their largest components
    /// (it is scale-free), so neither very long nor very short edges overflow it; an edge
    /// that is not finite (`B − A` overflowing) is rejected.
    pub fn new(a: Vec3<F>, b: Vec3<F>, c: Vec3<F>) -> Result<Self> {
        use crate::error::Field;
        for (field, v) in [
            (Field::TriangleA, a),
            (Field::TriangleB, b),
            (Field::TriangleC, c),
        ] {
            validate::finite_vec(field, v)?;
        }
        match unit_normal(a, b, c) {
            Ok(_) => Ok(Self { a, b, c }),
            Err(_) => Err(Error::invalid(
                Field::Triangle,
                format!(
                    "has no area in {}: its vertices {}, {}, {} are collinear or coincident \
                     (to within rounding), or an edge is too long to be finite",
                    F::NAME,
                    validate::show(a),
                    validate::show(b),
                    validate::show(c)
                ),
            )),
        }
    }

    /// The vertices `[A, B, C]`.
    pub fn vertices(&self) -> [Vec3<F>; 3] {
        [self.a, self.b, self.c]
    }

    /// The unit outward normal `(B − A)×(C − A) / |(B − A)×(C − A)|` (computed, not stored:
    /// a triangle takes three vertices of room).
    pub fn normal(&self) -> Vec3<F> {
        checked_normal(self.vertices())
    }

    /// This triangle in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains (it may become degenerate).
    pub fn cast<G: Float>(&self) -> Result<Triangle<G>> {
        Triangle::new(self.a.cast(), self.b.cast(), self.c.cast())
    }

    /// The ray parameter `t ∈ (0, t_max)` of the hit and its barycentric coordinates
    /// `[b₀, b₁, b₂]` (weights of `A`, `B`, `C`; each `≥ 0`, summing to 1 within
    /// rounding), or `None`.
    ///
    /// The watertight test of Woop, Benthin and Wald (2013), as in pbrt-v4:
    /// 1. translate the vertices by `−O` and permute the axes cyclically so that the
    ///    largest `|Dᵢ|` becomes `z` (a cyclic permutation keeps the orientation);
    /// 2. shear so that `D` becomes `(0, 0, 1)`: `x += Sₓz`, `y += S_yz` with
    ///    `Sₓ = −Dₓ/D_z`, `S_y = −D_y/D_z`, `S_z = 1/D_z` (applied to `z` later);
    /// 3. the ray is now the `z` axis; the 2-D edge functions at the origin are
    ///    `e₀ = BₓC_y − B_yCₓ`, `e₁ = CₓA_y − C_yAₓ`, `e₂ = AₓB_y − A_yBₓ`; the ray hits
    ///    iff they do not have strictly opposite signs and `det = e₀ + e₁ + e₂ ≠ 0`;
    /// 4. `t = (e₀A_z + e₁B_z + e₂C_z)·S_z / det`, compared with a finite `t_max` before
    ///    dividing;
    /// 5. `t` must exceed pbrt's bound `δt` on its own rounding error (`δz`, `δx`, `δy`,
    ///    `δe`, `δt` below), so a ray spawned off the surface never re-hits it.
    ///
    /// # Precision
    /// Why no ray slips between two triangles: each transformed vertex is computed the
    /// same way in every triangle it belongs to, and the two orders of an edge give
    /// exactly opposite values (`fl(ab) = fl(ba)`, `fl(x − y) = −fl(y − x)`). Moreover
    /// rounding is monotone, so `fl(fl(ab) − fl(cd))` has the exact sign of `ab − cd` or
    /// is zero, never the opposite sign. Spurious zeros are accepted as "on the edge" by
    /// both triangles, so the set of hit triangles can only grow over the exact
    /// orientation test of the rounded vertices, which covers every ray through the
    /// mesh's interior. pbrt also recomputes the edge functions in `f64` when one of
    /// them is exactly zero in `f32` (products of `f32` are exact in `f64`, so the signs
    /// become exact and an edge is hit by fewer duplicates); we do the same for every
    /// scalar with at most 26 significant bits (`f32`). For `f64` there is no wider type
    /// to fall back to, and none is needed for watertightness. Double-double arithmetic is
    /// not correctly rounded, so this argument does not cover it: a double-double render
    /// of a mesh was seen to miss it at a few pixels where `f64` hits.
    pub fn intersect_watertight(&self, ray: &Ray<F>, t_max: F) -> Option<(F, [F; 3])> {
        intersect_vertices(&[self.a, self.b, self.c], ray, t_max)
    }
}

/// The unit normal `(B − A)×(C − A)/|(B − A)×(C − A)|`, or, for a degenerate triangle
/// (see [`Triangle::new`]), the computed length of the scaled edges' cross product and the
/// threshold it did not exceed.
pub(crate) fn unit_normal<F: Float>(
    a: Vec3<F>,
    b: Vec3<F>,
    c: Vec3<F>,
) -> std::result::Result<Vec3<F>, (F, F)> {
    let (Some(us), Some(vs)) = (scaled_edge(b - a), scaled_edge(c - a)) else {
        return Err((F::zero(), F::zero()));
    };
    let cross = us.cross(vs);
    let (cross_len, threshold) = (cross.length(), F::gamma(6) * us.length() * vs.length());
    match cross.try_normalize() {
        Some(n) if cross_len > threshold => Ok(n),
        _ => Err((cross_len, threshold)),
    }
}

/// [`unit_normal`] of a triangle known to pass its test (a [`Triangle`]'s or a
/// [`Mesh`](super::Mesh)'s, checked when it was built): the same bits, without the test.
#[inline]
pub(crate) fn checked_normal<F: Float>([a, b, c]: [Vec3<F>; 3]) -> Vec3<F> {
    let unit = |e: Vec3<F>| e / e.abs().max_element();
    unit(b - a).cross(unit(c - a)).normalize()
}

/// The edge `e` divided by its largest component, if that is finite and not zero: the
/// degeneracy test is scale-free, so long edges (`|e|²` overflowing) and short ones are
/// judged alike.
#[inline]
fn scaled_edge<F: Float>(e: Vec3<F>) -> Option<Vec3<F>> {
    let m = e.abs().max_element();
    (m > F::zero() && m.is_finite()).then(|| e / m)
}

/// The watertight intersection of `ray` with the triangle of vertices `v`: [`Triangle::intersect_watertight`].
#[inline]
pub(crate) fn intersect_vertices<F: Float>(v: &[Vec3<F>; 3], ray: &Ray<F>, t_max: F) -> Option<(F, [F; 3])> {
    // 1. Translate to the ray origin and permute: kz = the axis of the largest |Dᵢ|.
    let o = ray.origin;
    let ad = ray.direction.abs();
    let kz = if ad.x > ad.y {
        if ad.x > ad.z { 0 } else { 2 }
    } else if ad.y > ad.z {
        1
    } else {
        2
    };
    let kx = if kz == 2 { 0 } else { kz + 1 };
    let ky = if kx == 2 { 0 } else { kx + 1 };
    let permute = |v: Vec3<F>| Vec3::new(v[kx], v[ky], v[kz]);
    let d = permute(ray.direction);
    let (a, b, c) = (permute(v[0] - o), permute(v[1] - o), permute(v[2] - o));

    // 2. Shear x and y; z is scaled by S_z only once the edge tests pass.
    let sx = -d.x / d.z;
    let sy = -d.y / d.z;
    let sz = F::one() / d.z;
    let (ax, ay) = (a.x + sx * a.z, a.y + sy * a.z);
    let (bx, by) = (b.x + sx * b.z, b.y + sy * b.z);
    let (cx, cy) = (c.x + sx * c.z, c.y + sy * c.z);

    // 3. Edge functions: twice the signed areas of the origin with each edge.
    let mut e0 = bx * cy - by * cx;
    let mut e1 = cx * ay - cy * ax;
    let mut e2 = ax * by - ay * bx;
    let zero = F::zero();
    if products_exact_in_f64::<F>() && (e0 == zero || e1 == zero || e2 == zero) {
        let edge =
            |px: F, py: F, qx: F, qy: F| F::from_f64(px.to_f64() * qy.to_f64() - py.to_f64() * qx.to_f64());
        e0 = edge(bx, by, cx, cy);
        e1 = edge(cx, cy, ax, ay);
        e2 = edge(ax, ay, bx, by);
    }
    if (e0 < zero || e1 < zero || e2 < zero) && (e0 > zero || e1 > zero || e2 > zero) {
        return None;
    }
    let det = e0 + e1 + e2;
    if det == zero {
        return None;
    }

    // 4. The scaled distance t·det, tested against (0, t_max) without dividing. An
    // infinite t_max bounds nothing here (`∞·det` is NaN in double-double); step 5 still
    // compares t with it.
    let (az, bz, cz) = (a.z * sz, b.z * sz, c.z * sz);
    let t_scaled = e0 * az + e1 * bz + e2 * cz;
    let below_max = t_max == F::infinity()
        || if det < zero {
            t_scaled > t_max * det
        } else {
            t_scaled < t_max * det
        };
    let positive = if det < zero {
        t_scaled < zero
    } else {
        t_scaled > zero
    };
    let in_range = positive && below_max;
    if !in_range {
        return None;
    }
    let inv_det = F::one() / det;
    let bary = [e0 * inv_det, e1 * inv_det, e2 * inv_det];
    let t = t_scaled * inv_det;

    // 5. pbrt-v4's conservative t > 0 (§6.8.4): bounds on the rounding of the
    // transformed z (δz), x and y (δx, δy), the edge functions (δe) and t (δt).
    let max3 = |p: F, q: F, r: F| p.abs().max(q.abs()).max(r.abs());
    let max_z = max3(az, bz, cz);
    let delta_z = F::gamma(3) * max_z;
    let max_x = max3(ax, bx, cx);
    let max_y = max3(ay, by, cy);
    let delta_x = F::gamma(5) * (max_x + max_z);
    let delta_y = F::gamma(5) * (max_y + max_z);
    let two = F::one() + F::one();
    let delta_e = two * (F::gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    let max_e = max3(e0, e1, e2);
    let three = two + F::one();
    let delta_t = three * (F::gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inv_det.abs();
    // Written positively, so a NaN anywhere means "no hit".
    (t > delta_t && t < t_max).then_some((t, bary))
}

/// The hit on the triangle of vertices `v` (unit normal `normal`) at `t` with barycentrics
/// `[b₀, b₁, b₂]`: `P = b₀A + b₁B + b₂C`. The shading normal interpolates the corners'
/// `normals` if there are any (normalised, and turned to the outward side), else it is the
/// outward normal.
///
/// # Precision
/// pbrt-v4 §6.8.5: the computed barycentrics are non-negative and sum to
/// `1 + σ` with `|σ| ≤ γ(4)`, which moves `P` off the triangle's plane by at most
/// `|σ|·|A·n̂| ≤ γ(4)·Σ|bᵢVᵢ|`; the three products and two sums add `γ(3)` per
/// component. The error bound is `γ(7)·(|b₀A| + |b₁B| + |b₂C|)`.
// Always inlined: out of line, every shape's record (a sphere's too) went through memory.
#[inline(always)]
pub(crate) fn record<F: Float>(
    v: &[Vec3<F>; 3],
    normal: Vec3<F>,
    ray: &Ray<F>,
    t: F,
    bary @ [b0, b1, b2]: [F; 3],
    normals: Option<[Vec3<F>; 3]>,
) -> Hit<F> {
    let (pa, pb, pc) = (v[0] * b0, v[1] * b1, v[2] * b2);
    let point = pa + pb + pc;
    let error = (pa.abs() + pb.abs() + pc.abs()) * F::gamma(7);
    let shading_normal = normals.and_then(|n| interpolated_normal(n, bary, normal));
    let surface = Surface {
        t,
        point,
        error,
        outward: normal,
        shading_normal,
    };
    Hit::new(surface, ray.direction)
}

/// The corner normals `n` interpolated at barycentrics `b` and normalised, turned to the
/// side of the outward `normal`; `None` if they cancel.
#[inline(never)]
fn interpolated_normal<F: Float>(
    [n0, n1, n2]: [Vec3<F>; 3],
    [b0, b1, b2]: [F; 3],
    normal: Vec3<F>,
) -> Option<Vec3<F>> {
    let n = (n0 * b0 + n1 * b1 + n2 * b2).try_normalize()?;
    Some(if n.dot(normal) < F::zero() { -n } else { n })
}

/// The surface coordinates on the triangle of vertices `v` at barycentrics `[b₀, b₁, b₂]`,
/// as Mitsuba 3's meshes have them: `uv` interpolates the corners' texture coordinates
/// `uvs` (else it is `(b₁, b₂)`), and `∂p/∂u` is the edges `eᵢ` from `A` expressed in
/// them, `(Δv₂·e₁ − Δv₁·e₂)/det`, `Δuvᵢ` the coordinates' differences (else `B − A`).
#[inline]
pub(crate) fn coordinates<F: Float>(
    v: &[Vec3<F>; 3],
    [_, b1, b2]: [F; 3],
    uvs: Option<[[F; 2]; 3]>,
) -> Coordinates<F> {
    let (e1, e2) = (v[1] - v[0], v[2] - v[0]);
    let Some([uv0, uv1, uv2]) = uvs else {
        return Coordinates {
            uv: [b1, b2],
            dpdu: e1,
        };
    };
    let d1 = [uv1[0] - uv0[0], uv1[1] - uv0[1]];
    let d2 = [uv2[0] - uv0[0], uv2[1] - uv0[1]];
    let det = d1[0] * d2[1] - d1[1] * d2[0];
    Coordinates {
        uv: [uv0[0] + d1[0] * b1 + d2[0] * b2, uv0[1] + d1[1] * b1 + d2[1] * b2],
        dpdu: if det == F::zero() {
            e1
        } else {
            (e1 * d2[1] - e2 * d1[1]) / det
        },
    }
}

/// The box of the vertices `v`, widened by one rounding of their magnitude.
#[inline]
pub(crate) fn vertex_bounds<F: Float>([a, b, c]: [Vec3<F>; 3]) -> Aabb<F> {
    let lo = a.min(b).min(c);
    let hi = a.max(b).max(c);
    let pad = lo.abs().max(hi.abs()) * F::gamma(1);
    Aabb::new(lo - pad, hi + pad)
}

/// Whether a product of two `F`s is exact in `f64` (at most 26 significant bits: `f32`),
/// so the edge functions can be recomputed there with their exact sign.
#[inline]
pub(super) fn products_exact_in_f64<F: Float>() -> bool {
    F::eps().to_f64() >= f64::EPSILON.sqrt()
}

impl<F: Float> Hittable<F> for Triangle<F> {
    /// [`Triangle::intersect_watertight`], the barycentrics kept for the record;
    /// [`Triangle4`](super::Triangle4) gives the same four triangles at a time.
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let (t, coords) = self.intersect_watertight(ray, t_max)?;
        Some(Intersection { t, part: 0, coords })
    }

    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        record(&self.vertices(), self.normal(), ray, hit.t, hit.coords, None)
    }

    fn coordinates(&self, _: &Ray<F>, hit: &Intersection<F>, _: &Hit<F>) -> Coordinates<F> {
        coordinates(&self.vertices(), hit.coords, None)
    }

    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        Some(vertex_bounds(self.vertices()))
    }

    #[inline]
    fn parts(&self) -> u32 {
        1
    }

    #[inline]
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        self.bounds()
    }

    #[inline]
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }

    /// `|(B − A)×(C − A)|/2`.
    #[inline]
    fn area(&self) -> Option<F> {
        Some(triangle_area(&self.vertices()))
    }

    /// A point uniform on the triangle (density `1/area`, converted to solid angle) from
    /// `u₀, u₁`; `u₂` is not used.
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        let pdf_area = F::one() / triangle_area(&self.vertices());
        Some(sample_triangle(
            &self.vertices(),
            self.normal(),
            0,
            pdf_area,
            from,
            [u[0], u[1]],
        ))
    }

    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        hit_solid_angle(F::one() / triangle_area(&self.vertices()), ray, hit)
    }
}

#[cfg(test)]
mod tests;
