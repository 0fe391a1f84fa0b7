//! What a shape reports of a hit: the [`Hit`] record every material sees, the
//! [`Surface`] a shape builds it from, and the rounding-error bounds that let secondary
//! rays leave a surface without hitting it again.

use crate::float::Float;
use crate::frame::Frame;
use crate::ray::Ray;
use crate::vec3::Vec3;

/// Where a ray meets a surface, and the surface there: what a shape's
/// [`finish`](super::Hittable::finish) reports and every material sees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit<F> {
    /// The ray parameter of the hit, in `(0, t_max)`.
    pub t: F,
    /// The hit point.
    pub point: Vec3<F>,
    /// A bound on the absolute rounding error of each component of `point`
    /// (pbrt-v4's error-bounded intersection), used to offset secondary rays.
    pub error: Vec3<F>,
    /// The unit geometric normal, on the side the ray came from (`normal·D ≤ 0`). It
    /// alone decides which side of the surface a direction is on.
    pub normal: Vec3<F>,
    /// The unit shading normal, turned with the geometric one: what materials shade
    /// with. The geometric normal itself unless the shape interpolates normals (a mesh
    /// with vertex normals) or a material perturbs it (a normal map).
    pub shading_normal: Vec3<F>,
    /// `∂p/∂u`, the direction in which `u` grows: the shading frame's first axis (not of
    /// unit length, and zero where `u` does not vary, as at a sphere's poles). Filled in
    /// only for a material that [reads the coordinates](crate::Material::reads_coordinates);
    /// zero otherwise.
    pub dpdu: Vec3<F>,
    /// The surface coordinates `(u, v)` of the point, in Mitsuba 3's conventions (each
    /// shape's docs give its own). Filled in as `dpdu` is; zero otherwise.
    pub uv: [F; 2],
    /// Whether the ray hit the side the shape's outward normal points to.
    pub front_face: bool,
    /// Whether the shading normal differs from the geometric one (a mesh's interpolated
    /// normals): only then can the two disagree about a direction ([`Hit::sides_agree`]).
    pub smooth: bool,
}

/// A hit's surface coordinates: what [`Hittable::coordinates`](super::Hittable::coordinates)
/// gives, the third and optional phase of a hit, made only for a material that reads it
/// (a texture, an anisotropic BSDF, a normal map), so a scene of plain spheres never pays
/// for a sphere's `atan2` and `acos`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Coordinates<F> {
    /// `(u, v)`.
    pub uv: [F; 2],
    /// `∂p/∂u`.
    pub dpdu: Vec3<F>,
}

/// What a shape knows of the surface at a hit, every vector on the outward side, before
/// [`Hit::new`] turns it toward the ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface<F> {
    /// The ray parameter.
    pub t: F,
    /// The point.
    pub point: Vec3<F>,
    /// Its rounding-error bound ([`Hit::error`]).
    pub error: Vec3<F>,
    /// The unit outward geometric normal.
    pub outward: Vec3<F>,
    /// The unit shading normal on the outward side (`shading_normal·outward > 0`), if the
    /// shape has one of its own; `None`: the outward normal.
    pub shading_normal: Option<Vec3<F>>,
}

impl<F: Float> Surface<F> {
    /// A bare surface point for tests and tools: no rounding-error bound (so a ray spawned
    /// from it may re-hit the surface), the unit `outward` normal as both normals.
    #[must_use]
    pub fn bare(t: F, point: Vec3<F>, outward: Vec3<F>) -> Self {
        Self {
            t,
            point,
            error: Vec3::zero(),
            outward,
            shading_normal: None,
        }
    }
}

impl<F: Float> Hit<F> {
    /// The hit on `surface` of a ray travelling along `direction`: both normals turned to
    /// face the ray; no coordinates yet ([`Hit::with`]).
    #[inline]
    pub fn new(surface: Surface<F>, direction: Vec3<F>) -> Self {
        let front_face = direction.dot(surface.outward) <= F::zero();
        let shading = surface.shading_normal.unwrap_or(surface.outward);
        let (normal, shading_normal) = if front_face {
            (surface.outward, shading)
        } else {
            (-surface.outward, -shading)
        };
        Self {
            t: surface.t,
            point: surface.point,
            error: surface.error,
            normal,
            shading_normal,
            dpdu: Vec3::zero(),
            uv: [F::zero(); 2],
            front_face,
            smooth: surface.shading_normal.is_some(),
        }
    }

    /// The same hit with its surface coordinates.
    #[must_use]
    #[inline]
    pub fn with(self, coordinates: Coordinates<F>) -> Self {
        Self {
            uv: coordinates.uv,
            dpdu: coordinates.dpdu,
            ..self
        }
    }

    /// A ray leaving the hit point along the unit `direction`, its origin moved off the
    /// surface just far enough that it cannot hit the same surface again
    /// ([`Hit::offset_origin`]).
    #[must_use]
    #[inline]
    pub fn spawn(&self, direction: Vec3<F>) -> Ray<F> {
        Ray::new(self.offset_origin(direction), direction)
    }

    /// pbrt-v4's `OffsetRayOrigin`: the hit point moved along the geometric normal `n`
    /// past the box of its rounding error, to the side `toward` points to, then one more
    /// representable value away, so the new origin lies strictly on that side of the true
    /// surface:
    ///
    /// `d = |n|·error`, `p' = p ± d·n`, each component of `p'` rounded away from `p`.
    ///
    /// This replaces the textbook's fixed `t_min = 0.001`, which is scale-blind: too large
    /// for small objects (rays skip through a tiny glass sphere) and too small far from the
    /// origin (rays re-hit their own surface, "shadow acne").
    #[must_use]
    #[inline]
    pub fn offset_origin(&self, toward: Vec3<F>) -> Vec3<F> {
        let n = self.normal;
        let d = n.abs().dot(self.error);
        let offset = if toward.dot(n) < F::zero() {
            -(n * d)
        } else {
            n * d
        };
        let po = self.point + offset;
        let [x, y, z] = F::step_toward_each([po.x, po.y, po.z], [offset.x, offset.y, offset.z]);
        Vec3::new(x, y, z)
    }

    /// The orthonormal shading frame: the shading normal as `z`, `∂p/∂u` made
    /// perpendicular to it as `x` (see [`Frame::new`]). Materials that work in local
    /// coordinates, where `cos θ = w.z`, build it once per call.
    #[inline]
    pub fn shading_frame(&self) -> Frame<F> {
        Frame::new(self.shading_normal, self.dpdu)
    }

    /// Whether the geometric and the shading normal put `w` on the same side of the
    /// surface. A direction they disagree on carries no light (see
    /// [`Material`](crate::Material)'s "Shading normals").
    #[inline]
    pub fn sides_agree(&self, w: Vec3<F>) -> bool {
        !self.smooth || same_side(self.normal, self.shading_normal, w)
    }
}

/// Whether `a` and `b` put `w` on the same side: out of line, so that a hit with one
/// normal (every sphere, plane and flat triangle) never computes the two dot products
/// (inlined, the compiler computed them branch-free for every light and every bounce).
#[inline(never)]
fn same_side<F: Float>(a: Vec3<F>, b: Vec3<F>, w: Vec3<F>) -> bool {
    (w.dot(a) > F::zero()) == (w.dot(b) > F::zero())
}

/// A flat surface's [`Surface`] at `t` along `ray`: the point `O + tD` with
/// [`flat_hit_error`]'s bound for the plane through `anchor`, the unit `outward` normal as
/// both normals. What a disk or a quad of the user's can report.
#[must_use]
#[inline]
pub fn flat_surface<F: Float>(ray: &Ray<F>, t: F, anchor: Vec3<F>, outward: Vec3<F>) -> Surface<F> {
    Surface {
        t,
        point: ray.at(t),
        error: flat_hit_error(ray, t, anchor),
        outward,
        shading_normal: None,
    }
}

/// The rounding-error bound of a hit on a flat surface: the per-component box
/// `γ(10)·(|O| + |t·D| + |A|)` around the point `O + t·D`, for a surface through the
/// stored point `A` (`anchor`) with unit normal `n`, when `t` was computed as
/// `((A − O)·n) / (D·n)` (as [`Plane::crossing`](super::Plane::crossing) does). Report it as
/// [`Hit::error`] of a disk, a quad or a plane of your own; see
/// [Reporting the rounding error](super::Hittable#reporting-the-rounding-error).
///
/// # Precision
/// The bound guarantees that the exact plane `(X − A)·n = 0` passes through the box
/// `point ± error`, which is what [`Hit::offset_origin`] needs (the point's position
/// *along* the plane is irrelevant to self-intersection and, for grazing rays, much less
/// accurate). With `N = (A − O)·n`, `Δ = D·n`, their computed values `Ñ = N + e_N`,
/// `Δ̃ = Δ + e_Δ` and `t̃ = (Ñ/Δ̃)(1 + δ)`, the exact point `O + t̃D` lies at
/// (unnormalized) distance `t̃Δ − N = e_N + δÑ − t̃e_Δ` from the plane, so
/// `|t̃Δ − N| ≤ γ(5)·Σ(|Aᵢ| + |Oᵢ|)|nᵢ| + γ(3)·Σ|t̃Dᵢ||nᵢ|`. Evaluating `Oᵢ + t̃Dᵢ` costs
/// `γ(2)·(|Oᵢ| + |t̃Dᵢ|)` per component. In total the computed point is within
/// `γ(7)·Σ|nᵢ|(|Oᵢ| + |t̃Dᵢ| + |Aᵢ|)` of the plane, so the per-component box
/// `γ(7)·(|O| + |t̃D| + |A|)` reaches the plane along `n`. We report
/// `γ(10)·(|O| + |t̃D| + |A|)`: three more roundings cover the evaluation of the bound
/// itself.
#[must_use]
#[inline]
pub fn flat_hit_error<F: Float>(ray: &Ray<F>, t: F, anchor: Vec3<F>) -> Vec3<F> {
    (ray.origin.abs() + (ray.direction * t).abs() + anchor.abs()) * F::gamma(10)
}
