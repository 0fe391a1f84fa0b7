//! An indexed triangle mesh: vertices stored once, triangles as indices into them.

use super::sample::{sample_triangle, triangle_area};
use super::triangle::{checked_normal, coordinates, intersect_vertices, record, unit_normal, vertex_bounds};
use super::{Coordinates, Hit, Hittable, Intersection, SurfaceSample, hit_solid_angle};
use crate::aabb::Aabb;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::vec3::Vec3;
use std::sync::OnceLock;

/// A triangle mesh: shared vertex positions and triangles indexing them, all of one
/// material in a scene.
///
/// A scene indexes it by its triangles, its [parts](Hittable::parts): each enters the BVH
/// on its own and is intersected exactly as a [`Triangle`](super::Triangle) with the same
/// vertices (watertight across shared edges, the same error-bounded hit points), while
/// each vertex is stored once instead of in every triangle around it.
///
/// A mesh may also carry, per vertex, a normal ([`Mesh::with_normals`]) that its hits
/// interpolate into a smooth shading normal, and texture coordinates
/// ([`Mesh::with_uvs`]); without them its surface coordinates are each triangle's
/// barycentric ones, as a [`Triangle`](super::Triangle)'s.
#[derive(Clone, Debug)]
pub struct Mesh<F> {
    vertices: Vec<Vec3<F>>,
    triangles: Vec<[u32; 3]>,
    normals: Option<Vec<Vec3<F>>>,
    uvs: Option<Vec<[F; 2]>>,
    skipped: usize,
    /// Built the first time the mesh is sampled as a light, never for other meshes.
    areas: OnceLock<Areas<F>>,
}

/// A mesh's triangle areas, for drawing a triangle in proportion to its area, and the
/// triangles' normals, which every point drawn needs (made once: six divisions each).
#[derive(Clone, Debug)]
struct Areas<F> {
    /// `cumulative[k]`: the areas of triangles `0..=k` summed, in `f64`.
    cumulative: Vec<f64>,
    /// The whole area.
    total: F,
    /// Triangle `k`'s unit normal, [`checked_normal`]'s.
    normals: Vec<Vec3<F>>,
}

/// Two meshes are equal when their geometry and attributes are (whether they were sampled
/// yet is not part of it).
impl<F: PartialEq> PartialEq for Mesh<F> {
    fn eq(&self, other: &Self) -> bool {
        (
            &self.vertices,
            &self.triangles,
            &self.normals,
            &self.uvs,
            self.skipped,
        ) == (
            &other.vertices,
            &other.triangles,
            &other.normals,
            &other.uvs,
            other.skipped,
        )
    }
}

impl<F: Float> Mesh<F> {
    /// The mesh of `triangles` (indices into `vertices`, counter-clockwise seen from the
    /// front as for [`Triangle`](super::Triangle)).
    ///
    /// Triangles that are degenerate in `F` (see [`Triangle::new`](super::Triangle::new))
    /// are left out and counted ([`Mesh::skipped_degenerate`]): rounding a mesh's vertices
    /// to `F` can flatten a thin face, which a file's author cannot have meant as an error.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] (`Field::Mesh`), naming the element, for a vertex that is
    /// not finite, an index past the vertices, more than `u32::MAX` triangles, or no
    /// triangle left with area.
    pub fn new(vertices: Vec<Vec3<F>>, mut triangles: Vec<[u32; 3]>) -> Result<Self> {
        if let Some(k) = vertices.iter().position(|v| !v.is_finite()) {
            let v = crate::validate::show(vertices[k]);
            return Err(Error::invalid(
                Field::Mesh,
                format!("vertex {k} is not finite: {v}"),
            ));
        }
        if let Some(k) = triangles
            .iter()
            .position(|t| t.iter().any(|&i| i as usize >= vertices.len()))
        {
            let [a, b, c] = triangles[k];
            return Err(Error::invalid(
                Field::Mesh,
                format!(
                    "triangle {k} indexes a vertex past the {} vertices: [{a}, {b}, {c}]",
                    vertices.len()
                ),
            ));
        }
        if u32::try_from(triangles.len()).is_err() {
            return Err(Error::invalid(
                Field::Mesh,
                format!("{} triangles; at most u32::MAX", triangles.len()),
            ));
        }
        let before = triangles.len();
        triangles.retain(|t| {
            let [a, b, c] = t.map(|i| vertices[i as usize]);
            unit_normal(a, b, c).is_ok()
        });
        if triangles.is_empty() {
            return Err(Error::invalid(
                Field::Mesh,
                format!("none of its {before} triangles has an area in {}", F::NAME),
            ));
        }
        Ok(Self {
            skipped: before - triangles.len(),
            vertices,
            triangles,
            normals: None,
            uvs: None,
            areas: OnceLock::new(),
        })
    }

    /// The same mesh with a normal per vertex, which its hits interpolate into the shading
    /// normal: each of any length, normalised; a zero normal (a file's vertex without one)
    /// is kept as zero and adds nothing to the interpolation, and where a triangle's
    /// corners' normals cancel its hits shade with the face's normal.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] (`what = "mesh normals"`) for a count other than the
    /// vertices' or a normal that is not finite.
    pub fn with_normals(self, normals: Vec<Vec3<F>>) -> Result<Self> {
        self.check_count("mesh normals", normals.len())?;
        let normals = normals
            .into_iter()
            .enumerate()
            .map(|(k, n)| {
                if !n.is_finite() {
                    return Err(Error::invalid(
                        "mesh normals",
                        format!("the normal of vertex {k} is not finite"),
                    ));
                }
                Ok(n.try_normalize().unwrap_or(Vec3::zero()))
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Self {
            normals: Some(normals),
            ..self
        })
    }

    /// The same mesh with texture coordinates `(u, v)` per vertex.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] (`what = "mesh texture coordinates"`) for a count other
    /// than the vertices' or a coordinate that is not finite.
    pub fn with_uvs(self, uvs: Vec<[F; 2]>) -> Result<Self> {
        self.check_count("mesh texture coordinates", uvs.len())?;
        if let Some(k) = uvs
            .iter()
            .position(|uv| !(uv[0].is_finite() && uv[1].is_finite()))
        {
            return Err(Error::invalid(
                "mesh texture coordinates",
                format!("the coordinates of vertex {k} are not finite"),
            ));
        }
        Ok(Self {
            uvs: Some(uvs),
            ..self
        })
    }

    fn check_count(&self, what: &'static str, n: usize) -> Result<()> {
        if n == self.vertices.len() {
            Ok(())
        } else {
            Err(Error::invalid(
                what,
                format!("{n} given for {} vertices", self.vertices.len()),
            ))
        }
    }

    /// The unit vertex normals, if the mesh has them.
    pub fn normals(&self) -> Option<&[Vec3<F>]> {
        self.normals.as_deref()
    }

    /// The vertices' texture coordinates, if the mesh has them.
    pub fn uvs(&self) -> Option<&[[F; 2]]> {
        self.uvs.as_deref()
    }

    /// Triangle `k`'s corner normals, if the mesh has normals.
    #[inline]
    fn corner_normals(&self, k: u32) -> Option<[Vec3<F>; 3]> {
        let index = self.triangles[k as usize];
        self.normals.as_ref().map(|n| index.map(|i| n[i as usize]))
    }

    /// [`Hittable::finish`] of `hit` on its triangle, whose vertices are `v`.
    #[inline(always)]
    pub(crate) fn finish_vertices(&self, ray: &Ray<F>, hit: &Intersection<F>, v: &[Vec3<F>; 3]) -> Hit<F> {
        let normals = self.corner_normals(hit.part);
        record(v, checked_normal(*v), ray, hit.t, hit.coords, normals)
    }

    /// The vertex positions.
    pub fn vertices(&self) -> &[Vec3<F>] {
        &self.vertices
    }

    /// The triangles, as indices into [`Mesh::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The vertices `[A, B, C]` of triangle `k`.
    ///
    /// # Panics
    /// If `k` is not below the number of triangles.
    #[inline]
    pub fn triangle(&self, k: u32) -> [Vec3<F>; 3] {
        self.triangles[k as usize].map(|i| self.vertices[i as usize])
    }

    /// The triangle areas, summed up once.
    fn areas(&self) -> &Areas<F> {
        self.areas.get_or_init(|| {
            let mut sum = 0.0;
            let cumulative: Vec<f64> = (0..self.parts())
                .map(|k| {
                    sum += triangle_area(&self.triangle(k)).to_f64();
                    sum
                })
                .collect();
            Areas {
                cumulative,
                total: lit(sum),
                normals: (0..self.parts())
                    .map(|k| checked_normal(self.triangle(k)))
                    .collect(),
            }
        })
    }

    /// The triangles [`Mesh::new`] left out for having no area in `F`.
    pub fn skipped_degenerate(&self) -> usize {
        self.skipped
    }

    /// This mesh in scalar `G`, rounded through `f64` and re-validated, as
    /// [`EnumScene::cast`](crate::EnumScene::cast) explains (triangles degenerate in `G`
    /// are left out, so a triangle's number may change).
    pub fn cast<G: Float>(&self) -> Result<Mesh<G>> {
        let mut mesh = Mesh::new(
            self.vertices.iter().map(|v| v.cast()).collect(),
            self.triangles.clone(),
        )?;
        if let Some(normals) = &self.normals {
            mesh = mesh.with_normals(normals.iter().map(|n| n.cast()).collect())?;
        }
        if let Some(uvs) = &self.uvs {
            mesh = mesh.with_uvs(uvs.iter().map(|uv| uv.map(crate::float::to)).collect())?;
        }
        Ok(Mesh {
            skipped: mesh.skipped + self.skipped,
            ..mesh
        })
    }
}

impl<F: Float> Hittable<F> for Mesh<F> {
    /// The nearest of all the triangles (of equally near ones, the first), tested one by one:
    /// for a mesh used alone. A scene tests only the triangles the ray's path through its
    /// BVH leads to ([`Hittable::intersect_part`]).
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let mut nearest: Option<Intersection<F>> = None;
        for part in 0..self.parts() {
            // No bound inside the test (it could turn away a hit nearer by an ulp); the
            // comparison keeps the first of equally near triangles.
            let bound = nearest.map_or(t_max, |n| n.t);
            match self.intersect_part(part, ray, F::infinity()) {
                Some(i) if i.t < bound => nearest = Some(i),
                _ => {}
            }
        }
        nearest
    }

    // Always inlined: out of line it returns the record through memory, which keeps
    // every shape's record (a sphere's too) in memory.
    #[inline(always)]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        self.finish_vertices(ray, hit, &self.triangle(hit.part))
    }

    /// As a [`Triangle`](super::Triangle)'s, from the corners' texture coordinates if the
    /// mesh has them.
    fn coordinates(&self, _: &Ray<F>, hit: &Intersection<F>, _: &Hit<F>) -> Coordinates<F> {
        let index = self.triangles[hit.part as usize];
        let uvs = self.uvs.as_ref().map(|uv| index.map(|i| uv[i as usize]));
        coordinates(&self.triangle(hit.part), hit.coords, uvs)
    }

    fn bounds(&self) -> Option<Aabb<F>> {
        (0..self.parts())
            .filter_map(|k| self.part_bounds(k))
            .reduce(Aabb::union)
    }

    #[inline]
    fn parts(&self) -> u32 {
        self.triangles.len() as u32
    }

    #[inline]
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        Some(vertex_bounds(self.triangle(part)))
    }

    #[inline]
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let (t, coords) = intersect_vertices(&self.triangle(part), ray, t_max)?;
        Some(Intersection { t, part, coords })
    }

    /// The sum of the triangles' areas.
    fn area(&self) -> Option<F> {
        Some(self.areas().total)
    }

    /// A point uniform over the whole surface: a triangle drawn in proportion to its area
    /// by `u₀` (a binary search of the running sums of the areas), then a point uniform on
    /// it by `u₁, u₂`. The density is `1/area` of the mesh everywhere (`A_k/A · 1/A_k`),
    /// converted to solid angle.
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        let areas = self.areas();
        let target = u[0] * areas.cumulative.last()?;
        let k = areas.cumulative.partition_point(|&c| c <= target);
        let k = k.min(areas.cumulative.len() - 1) as u32;
        let v = self.triangle(k);
        let pdf_area = F::one() / areas.total;
        Some(sample_triangle(
            &v,
            areas.normals[k as usize],
            k,
            pdf_area,
            from,
            [u[1], u[2]],
        ))
    }

    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        hit_solid_angle(F::one() / self.areas().total, ray, hit)
    }
}

#[cfg(test)]
mod tests;
