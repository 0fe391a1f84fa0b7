//! The disk: Mitsuba 3's unit disk in the `xy` plane, placed by an affine map.

use super::triangle::unit_normal;
use super::{
    Coordinates, Hit, Hittable, Intersection, Plane, SurfaceSample, area_to_solid_angle, flat_surface,
    hit_solid_angle,
};
use crate::aabb::Aabb;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::sampling::{orthonormal_basis, uniform_disk_concentric};
use crate::validate;
use crate::vec3::Vec3;
use std::f64::consts::{PI, TAU};

/// A flat disk: the points `C + a·U + b·V` with `a² + b² ≤ 1`.
///
/// This is Mitsuba 3's `disk`, the unit disk of the `xy` plane (radius 1, centre 0,
/// normal `+z`) placed by a `to_world` map `M`: `C = M·0`, `U = M·x̂`, `V = M·ŷ`. With `U`
/// and `V` perpendicular and of length `r` it is a round disk of radius `r`; any other
/// (non-parallel) pair makes an ellipse, as a non-uniform scale or a shear of Mitsuba's does.
///
/// Its outward normal is `n = (U×V)/|U×V|`, or `−n` for a [`flipped`](Disk::flipped) disk
/// (what a `to_world` with a negative determinant, or Mitsuba's `flip_normals`, makes: a
/// normal goes by `M⁻ᵀ`, and `M⁻ᵀẑ = (U×V)/det M`). It is hit from both sides.
///
/// Its surface coordinates are Mitsuba's: `uv = (ρ, φ/2π)` with `ρ = √(a² + b²)` and
/// `φ = atan2(b, a)` in `[0, 2π)`, and `∂p/∂u = cos φ·U + sin φ·V` (the radial direction;
/// `U` at the centre).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk<F> {
    /// The supporting plane: through `C`, with the outward normal.
    plane: Plane<F>,
    u: Vec3<F>,
    v: Vec3<F>,
    /// The dual basis: `(X − C)·du = a` and `(X − C)·dv = b` for `X = C + aU + bV`.
    du: Vec3<F>,
    dv: Vec3<F>,
    flipped: bool,
}

impl<F: Float> Disk<F> {
    /// The round disk of `radius` about `center`, facing `normal` (any non-zero length).
    /// Its `U` and `V` are `radius` times the frame `(s, t)` of the unit normal that
    /// [`orthonormal_basis`] gives (`x̂` and `ŷ` for `+z`: Mitsuba's disk scaled by
    /// `radius` and moved to `center`).
    ///
    /// # Errors
    /// [`Error::InvalidValue`] for a centre that is not finite ([`Field::DiskCenter`]), a
    /// normal that is zero or not finite ([`Field::DiskNormal`]) or a radius that is not
    /// finite and `> 0` ([`Field::DiskRadius`]).
    pub fn new(center: Vec3<F>, normal: Vec3<F>, radius: F) -> Result<Self> {
        validate::finite_vec(Field::DiskCenter, center)?;
        let n = validate::direction(Field::DiskNormal, normal)?;
        let r = validate::positive(Field::DiskRadius, radius)?;
        let (s, t) = orthonormal_basis(n);
        Self::with_axes(center, s * r, t * r).map_err(|_| {
            let why = format!("is too small for {} (got {})", F::NAME, validate::number(r));
            Error::invalid(Field::DiskRadius, why)
        })
    }

    /// The disk `C + a·U + b·V`, `a² + b² ≤ 1`, facing `U×V`: Mitsuba's disk under a map
    /// with `M·0 = center`, `M·x̂ = u`, `M·ŷ = v` and a positive determinant.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] for a centre that is not finite ([`Field::DiskCenter`]), or
    /// axes that are not finite or (to within rounding, as [`Triangle::new`](super::Triangle::new)
    /// judges a triangle's edges) parallel ([`Field::DiskAxes`]).
    pub fn with_axes(center: Vec3<F>, u: Vec3<F>, v: Vec3<F>) -> Result<Self> {
        validate::finite_vec(Field::DiskCenter, center)?;
        let degenerate = || {
            Error::invalid(
                Field::DiskAxes,
                format!(
                    "has no area in {}: its axes {} and {} are parallel, zero or not finite",
                    F::NAME,
                    validate::show(u),
                    validate::show(v)
                ),
            )
        };
        if !(u.is_finite() && v.is_finite()) {
            return Err(degenerate());
        }
        let n = unit_normal(Vec3::zero(), u, v).map_err(|_| degenerate())?;
        // The dual basis, with n = (U×V)/|U×V|: du = (V×n)/|U×V|, dv = (n×U)/|U×V|, so that
        // U·du = V·dv = 1 and V·du = U·dv = 0 (|U×V|², which overflows sooner, is not formed).
        let area = u.cross(v).dot(n);
        let (du, dv) = (v.cross(n) / area, n.cross(u) / area);
        if !(area > F::zero() && area.is_finite() && du.is_finite() && dv.is_finite()) {
            return Err(degenerate());
        }
        Ok(Self {
            plane: Plane::new(center, n)?,
            u,
            v,
            du,
            dv,
            flipped: false,
        })
    }

    /// The same disk facing the other way (`−(U×V)`), with the same surface coordinates.
    #[must_use]
    pub fn flipped(self) -> Self {
        let plane = Plane::new(self.center(), -self.plane.normal()).unwrap_or(self.plane);
        Self {
            plane,
            flipped: !self.flipped,
            ..self
        }
    }

    /// The centre `C`.
    pub fn center(&self) -> Vec3<F> {
        self.plane.point()
    }

    /// The axes `[U, V]`: where the map takes `x̂` and `ŷ`.
    pub fn axes(&self) -> [Vec3<F>; 2] {
        [self.u, self.v]
    }

    /// The unit outward normal.
    pub fn normal(&self) -> Vec3<F> {
        self.plane.normal()
    }

    /// Whether the disk faces `−(U×V)` ([`Disk::flipped`]).
    pub fn is_flipped(&self) -> bool {
        self.flipped
    }

    /// This disk in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Disk<G>> {
        let disk = Disk::with_axes(self.center().cast(), self.u.cast(), self.v.cast())?;
        Ok(if self.flipped { disk.flipped() } else { disk })
    }

    /// The disk's coordinates `(a, b)` of a point `p` of its plane.
    #[inline]
    fn local(&self, p: Vec3<F>) -> (F, F) {
        let d = p - self.center();
        (d.dot(self.du), d.dot(self.dv))
    }

    /// `π|U×V|`: the unit disk's area `π` times the map's area factor in the plane.
    fn surface_area(&self) -> F {
        lit::<F>(PI) * self.u.cross(self.v).length()
    }
}

impl<F: Float> Hittable<F> for Disk<F> {
    /// The plane's conservative crossing ([`Plane::crossing`]), kept if the point lies
    /// in the disk, `a² + b² ≤ 1`; `(a, b)` are kept for the record.
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let t = self.plane.crossing(ray, t_max)?;
        let (a, b) = self.local(ray.at(t));
        (a * a + b * b <= F::one()).then_some(Intersection {
            t,
            part: 0,
            coords: [a, b, F::zero()],
        })
    }

    /// The point `O + tD` with the flat-surface error bound ([`flat_surface`]): `t` is
    /// the plane's `((C − O)·n)/(D·n)`.
    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        Hit::new(
            flat_surface(ray, hit.t, self.center(), self.normal()),
            ray.direction,
        )
    }

    /// Mitsuba's `(ρ, φ/2π)` and `∂p/∂u = cos φ·U + sin φ·V` (see [`Disk`]).
    fn coordinates(&self, _: &Ray<F>, hit: &Intersection<F>, _: &Hit<F>) -> Coordinates<F> {
        let [a, b, _] = hit.coords;
        let rho = (a * a + b * b).sqrt();
        let two_pi = lit::<F>(TAU);
        let phi = b.atan2(a);
        let phi = if phi < F::zero() { phi + two_pi } else { phi };
        let (cos, sin) = if rho > F::zero() {
            (a / rho, b / rho)
        } else {
            (F::one(), F::zero())
        };
        Coordinates {
            // φ/2π rounds up to 1 for the tiniest negative angles: [0, 1) as Mitsuba's.
            uv: [rho, (phi / two_pi).min(F::one().next_down())],
            dpdu: self.u * cos + self.v * sin,
        }
    }

    /// `C ± e` with `eᵢ = √(Uᵢ² + Vᵢ²)`, the largest `aUᵢ + bVᵢ` over `a² + b² ≤ 1`,
    /// widened by `γ(8)·(|C| + e)` for the roundings of the bound and of the inside test.
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        let (u, v, c) = (self.u, self.v, self.center());
        let e = Vec3::new(
            (u.x * u.x + v.x * v.x).sqrt(),
            (u.y * u.y + v.y * v.y).sqrt(),
            (u.z * u.z + v.z * v.z).sqrt(),
        );
        let reach = e + (c.abs() + e) * F::gamma(8);
        Some(Aabb::new(c - reach, c + reach))
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

    /// `π|U×V|`.
    fn area(&self) -> Option<F> {
        Some(self.surface_area())
    }

    /// A point uniform on the disk (density `1/area`, converted to solid angle): the
    /// concentric map's point `(x, y)` of the unit disk from `u₀, u₁` taken to
    /// `C + xU + yV` (an affine map keeps a uniform density uniform), as Mitsuba's
    /// `sample_position`; `u₂` is not used.
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        let [x, y] = uniform_disk_concentric([u[0], u[1]]);
        let point = self.center() + self.u * lit::<F>(x) + self.v * lit::<F>(y);
        let normal = self.normal();
        Some(SurfaceSample {
            point,
            normal,
            part: 0,
            pdf: area_to_solid_angle(F::one() / self.surface_area(), from, point, normal),
        })
    }

    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        hit_solid_angle(F::one() / self.surface_area(), ray, hit)
    }
}

#[cfg(test)]
mod tests;
