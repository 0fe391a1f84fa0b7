//! Four triangles side by side, intersected with one ray at once.

use super::triangle::products_exact_in_f64;
use crate::float::Float;
use crate::lanes::{F4, LANES};
use crate::ray::Ray;
use crate::vec3::Vec3;

/// Up to four triangles in structure-of-arrays layout (`vertices[v][axis].0[lane]`), so one
/// ray is tested against all four with the same instructions per lane.
///
/// The answer is bit for bit what [`Triangle::intersect_watertight`](super::Triangle::intersect_watertight) gives
/// for each triangle alone: the watertight test, operation for operation, on every lane.
#[derive(Clone, Copy, Debug)]
pub struct Triangle4<F> {
    vertices: [[F4<F>; 3]; 3],
}

/// What [`Triangle4::hits_within`] finds: each lane's `t` (`+∞` for none) and what its
/// barycentrics are made of.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TriangleHits<F> {
    /// Each lane's `t`, or `+∞` where the ray misses that triangle.
    pub(crate) t: F4<F>,
    edges: [F4<F>; 3],
    inv_det: F4<F>,
}

impl<F: Float> TriangleHits<F> {
    /// The barycentrics of lane `lane`'s hit, as the scalar test computes them.
    #[inline(always)]
    pub(crate) fn coords(&self, lane: usize) -> [F; 3] {
        self.edges.map(|e| e.0[lane] * self.inv_det.0[lane])
    }
}

impl<F: Float> Triangle4<F> {
    /// The first (up to) four of `triangles`, each given by its vertices `[A, B, C]`.
    ///
    /// Unused lanes repeat the first triangle: they answer as its lane does, and of equally
    /// near lanes the first is taken, so they add no hit. (Lanes of one point would never
    /// hit either, but their edge functions are exactly zero, which sends every test of the
    /// packet through the `f64` edge functions of step 3.)
    pub fn new(triangles: impl IntoIterator<Item = [Vec3<F>; 3]>) -> Self {
        let mut p = Self {
            vertices: [[F4::splat(F::zero()); 3]; 3],
        };
        let mut triangles = triangles.into_iter().take(LANES).peekable();
        let first = triangles.peek().copied();
        let padded = triangles.chain(std::iter::repeat_n(first, LANES).flatten());
        for (lane, t) in padded.take(LANES).enumerate() {
            for (v, vertex) in t.iter().enumerate() {
                for axis in 0..3 {
                    p.vertices[v][axis].0[lane] = vertex[axis];
                }
            }
        }
        p
    }

    /// Lane `lane`'s vertices `[A, B, C]`, as given.
    #[inline(always)]
    pub(crate) fn vertices(&self, lane: usize) -> [Vec3<F>; 3] {
        self.vertices
            .map(|v| Vec3::new(v[0].0[lane], v[1].0[lane], v[2].0[lane]))
    }

    /// Whether any lane's triangle is hit at some `t` in `(0, t_max)`.
    #[inline(always)]
    pub fn any(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.hits_within(ray, t_max).t.any_lt(t_max)
    }

    /// [`Triangle4::hits_within`] with no bound.
    #[cfg(test)]
    pub(crate) fn hits(&self, ray: &Ray<F>) -> TriangleHits<F> {
        self.hits_within(ray, F::infinity())
    }

    /// For each lane, the `t` that [`Triangle::intersect_watertight`](super::Triangle::intersect_watertight)
    /// reports with no bound (`t_max = +∞`) where it is at most `bound`, else `+∞`, with what
    /// the barycentrics are made of. The steps are the scalar test's, numbered as there.
    /// A lane beyond `bound` is dropped before pbrt's bound on `t` (step 5), the costliest
    /// step: a ray meets most packets behind the nearest hit it has already found. Packets
    /// whose lanes all fail the edge test, or all lie beyond `bound`, stop early.
    #[inline(always)]
    pub(crate) fn hits_within(&self, ray: &Ray<F>, bound: F) -> TriangleHits<F> {
        let inf = F4::splat(F::infinity());
        let zero = F::zero();
        // 1. The permutation depends on the ray alone, so every lane takes the same one.
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
        let (o, d) = (ray.origin, ray.direction);
        let origin = [F4::splat(o[kx]), F4::splat(o[ky]), F4::splat(o[kz])];
        // 2. Shear x and y.
        let shear = [F4::splat(-d[kx] / d[kz]), F4::splat(-d[ky] / d[kz])];
        let sz = F::one() / d[kz];
        // (Three calls, not `array::map`, which is not always inlined.)
        let k = [kx, ky, kz];
        let [ax, ay, a_z] = sheared(&self.vertices[0], k, &origin, &shear);
        let [bx, by, b_z] = sheared(&self.vertices[1], k, &origin, &shear);
        let [cx, cy, c_z] = sheared(&self.vertices[2], k, &origin, &shear);
        // 3. Edge functions, recomputed in f64 for a lane where one is zero in f32.
        let mut e0 = bx * cy - by * cx;
        let mut e1 = cx * ay - cy * ax;
        let mut e2 = ax * by - ay * bx;
        let z = F4::splat(zero);
        // Each mask is one comparison of the edges' least or greatest (NaNs left out), the
        // same lanes as a mask per edge: three masks joined compile to a tangle of shuffles.
        let zeros = e0.abs().least(e1.abs()).least(e2.abs()).mask_eq(zero);
        if products_exact_in_f64::<F>() && zeros != 0 {
            for k in (0..LANES).filter(|k| zeros & (1 << k) != 0) {
                let edge = |px: F4<F>, py: F4<F>, qx: F4<F>, qy: F4<F>| {
                    F::from_f64(px.0[k].to_f64() * qy.0[k].to_f64() - py.0[k].to_f64() * qx.0[k].to_f64())
                };
                (e0.0[k], e1.0[k], e2.0[k]) =
                    (edge(bx, by, cx, cy), edge(cx, cy, ax, ay), edge(ax, ay, bx, by));
            }
        }
        // Lanes as bit masks: no edge function of each sign, and a determinant that is not 0.
        let negative = F4::mask_lt(e0.least(e1).least(e2), z);
        let positive = F4::mask_lt(z, e0.greatest(e1).greatest(e2));
        let det = e0 + e1 + e2;
        let edges_pass = !(negative & positive) & !det.mask_eq(zero) & 0b1111;
        let miss = TriangleHits {
            t: inf,
            edges: [e0, e1, e2],
            inv_det: det,
        };
        if edges_pass == 0 {
            return miss;
        }
        // 4. The scaled distance, of the sign of `det` (an infinite bound bounds nothing).
        let s = F4::splat(sz);
        let (az, bz, cz) = (a_z * s, b_z * s, c_z * s);
        let t_scaled = e0 * az + e1 * bz + e2 * cz;
        // `t_scaled` of `det`'s sign, nonzero: one comparison of `±t_scaled` (negation is exact).
        let in_range = F4::mask_lt(z, F4::select_lt(det, z, -t_scaled, t_scaled));
        let inv_det = F4::splat(F::one()) / det;
        let t = t_scaled * inv_det;
        let near = edges_pass & in_range & F4::mask_le(t, F4::splat(bound));
        if near == 0 {
            return miss;
        }
        // 5. The conservative t > 0 of pbrt-v4 (§6.8.4). A NaN among the sheared
        // coordinates makes `t_scaled` NaN (each enters it, through an edge or `z`), so its
        // lane is not `near`: the maxima's NaN rule never reaches a lane that can hit.
        let max3 = |p: F4<F>, q: F4<F>, r: F4<F>| p.abs().max(q.abs()).max(r.abs());
        let gamma = |n: u32| F4::splat(F::gamma(n));
        let max_z = max3(az, bz, cz);
        let delta_z = gamma(3) * max_z;
        let (max_x, max_y) = (max3(ax, bx, cx), max3(ay, by, cy));
        let delta_x = gamma(5) * (max_x + max_z);
        let delta_y = gamma(5) * (max_y + max_z);
        let two = F::one() + F::one();
        let delta_e = F4::splat(two) * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        let max_e = max3(e0, e1, e2);
        let three = F4::splat(two + F::one());
        let delta_t = three * (gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inv_det.abs();
        let hit = near & F4::mask_lt(delta_t, t) & F4::mask_lt(t, inf);
        TriangleHits {
            t: F4::select(hit, t, inf),
            edges: [e0, e1, e2],
            inv_det,
        }
    }
}

/// Vertex `v` (per axis) translated by `−O`, permuted to `(kx, ky, kz)` and sheared:
/// `(x + Sₓz, y + S_yz, z)`, as the scalar test computes it.
#[inline(always)]
fn sheared<F: Float>(
    v: &[F4<F>; 3],
    [kx, ky, kz]: [usize; 3],
    origin: &[F4<F>; 3],
    shear: &[F4<F>; 2],
) -> [F4<F>; 3] {
    let z = v[kz] - origin[2];
    [
        v[kx] - origin[0] + shear[0] * z,
        v[ky] - origin[1] + shear[1] * z,
        z,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Triangle;
    use rand::{RngExt, SeedableRng};

    /// Every lane agrees bit for bit with the scalar triangle's `t` and barycentrics, for
    /// triangles of very different sizes and distances, rays through their edges and
    /// vertices included (where f32 falls back to f64 edge functions).
    fn lanes_match_the_scalar_triangle<F: Float>() {
        let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(4);
        let mut hits = 0;
        for round in 0..4_000 {
            let scale = 10f64.powi(rng.random_range(-3..6));
            let mut point = || {
                Vec3::<F>::from_f64(
                    rng.random_range(-2.0..2.0) * scale,
                    rng.random_range(-2.0..2.0) * scale,
                    rng.random_range(-2.0..2.0) * scale,
                )
            };
            // Some packets share vertices, as a mesh's triangles do.
            let shared = [point(), point()];
            let triangles: Vec<Triangle<F>> = (0..4)
                .filter_map(|i| {
                    let c = point();
                    if round % 2 == 0 && i % 2 == 0 {
                        Triangle::new(shared[0], shared[1], c).ok()
                    } else {
                        Triangle::new(point(), point(), c).ok()
                    }
                })
                .collect();
            if triangles.is_empty() {
                continue;
            }
            let packet = Triangle4::new(triangles.iter().map(|t| t.vertices()));
            let origin = point();
            // Aim at a vertex, an edge's midpoint, or inside.
            let [a, b, c] = triangles[round % triangles.len()].vertices();
            let half = crate::float::lit::<F>(0.5);
            let target = match round % 3 {
                0 => a,
                1 => (a + b) * half,
                _ => (a + b + c) * crate::float::lit::<F>(1.0 / 3.0),
            };
            let Some(ray) = Ray::towards(origin, target) else {
                continue;
            };
            let got = packet.hits(&ray);
            for (lane, tri) in triangles.iter().enumerate() {
                let want = tri.intersect_watertight(&ray, F::infinity());
                let t = got.t.0[lane];
                match want {
                    Some((wt, coords)) => {
                        hits += 1;
                        assert_eq!(t.to_f64().to_bits(), wt.to_f64().to_bits(), "{ray:?}");
                        let same = |x: [F; 3]| x.map(|c| c.to_f64().to_bits());
                        assert_eq!(same(got.coords(lane)), same(coords), "{ray:?}");
                        // A bound at the hit keeps it, one below drops it.
                        assert_eq!(packet.hits_within(&ray, wt).t.0[lane], wt, "{ray:?}");
                        let below = wt * crate::float::lit::<F>(0.5);
                        assert_eq!(
                            packet.hits_within(&ray, below).t.0[lane],
                            F::infinity(),
                            "{ray:?}"
                        );
                    }
                    None => assert_eq!(t, F::infinity(), "{ray:?}"),
                }
            }
            for &t in &got.t.0[triangles.len()..] {
                let first = got.t.0[0].to_f64().to_bits();
                assert_eq!(t.to_f64().to_bits(), first, "unused lanes answer as the first");
            }
        }
        assert!(hits > 1_000, "{}: only {hits} hits tested", F::NAME);
    }

    mod scalars {
        crate::float::for_each_scalar!(lanes_match_the_scalar_triangle);
    }

    #[test]
    fn lanes_match_the_scalar_triangle_double_double() {
        lanes_match_the_scalar_triangle::<crate::DoubleDouble>();
    }
}
