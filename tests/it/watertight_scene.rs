//! Watertightness where it renders: rays through a mesh's shared edges and vertices, traced
//! by a [`Mesh`] in a scene (the four-lane triangle packets, on the BVH and on the plain
//! loop, one ray at a time and in the renderer's batches), in f32 and f64.
//!
//! `watertight.rs` aims rays at edges from random directions, through the scalar
//! [`Triangle`](raytrace::shape::Triangle) test; such rays almost never make an edge function
//! exactly 0, so a test that mishandles an exact 0 passes them. Here every ray runs along
//! a coordinate axis through a point of a triangulated grid whose coordinates are dyadic:
//! the shear is 0, every product in an edge function is exact, and a ray through an edge
//! makes that edge's function exactly 0 in both of the triangles that share it (two or more
//! at a vertex). In exact arithmetic every ray hits the grid (a height field, crossed once
//! by every ray along its axis); so must every ray here, from either side, along each of
//! the three axes, at scales 1, 2⁷ and 2¹⁴.
//!
//! Counting an exact 0 as negative in `shape/triangle4.rs` (so that a lane with a zero and
//! two positive edge functions fails) makes every such ray miss both triangles of an edge
//! where the triangles, projected along the ray, wind counter-clockwise (positive edge
//! functions, whichever way the ray goes); counting it as positive, where they wind
//! clockwise. So the grid is traced with both windings, and either mistake fails every
//! configuration.

use raytrace::Acceleration;
use raytrace::prelude::*;

/// Squares per side of the grid.
const N: usize = 6;
/// Points per unit along an edge (dyadic: exact in f32 at every scale here).
const STEPS: usize = 8;
const SCALES: [f64; 3] = [1.0, 128.0, 16384.0];
/// How far above (and below) the grid the rays start, in grid units.
const FROM: f64 = 10.0;

/// The grid's height at vertex `(i, j)`, a multiple of 1/8: slopes below 1.
fn height(i: usize, j: usize) -> f64 {
    ((7 * i + 3 * j) % 5) as f64 / 8.0
}

/// Whether square `(i, j)` is split along its diagonal from `(i, j)` to `(i + 1, j + 1)`
/// (else along the other one).
fn main_diagonal(i: usize, j: usize) -> bool {
    (i + j).is_multiple_of(2)
}

/// The points the rays pass through, `(x, y)` in grid units, and the grid's height there:
/// every interior vertex, and points of every interior edge (grid lines and diagonals).
fn targets() -> Vec<(f64, f64, f64)> {
    let mut out = Vec::new();
    let lerp = |a: f64, b: f64, s: f64| a + (b - a) * s;
    for i in 0..N {
        for j in 0..N {
            if i > 0 && j > 0 {
                out.push((i as f64, j as f64, height(i, j)));
            }
            for k in 1..STEPS {
                let s = k as f64 / STEPS as f64;
                // Along x on the line y = j, and along y on x = i (interior lines only).
                if j > 0 {
                    out.push((i as f64 + s, j as f64, lerp(height(i, j), height(i + 1, j), s)));
                }
                if i > 0 {
                    out.push((i as f64, j as f64 + s, lerp(height(i, j), height(i, j + 1), s)));
                }
                // The square's diagonal.
                if main_diagonal(i, j) {
                    let z = lerp(height(i, j), height(i + 1, j + 1), s);
                    out.push((i as f64 + s, j as f64 + s, z));
                } else {
                    let z = lerp(height(i + 1, j), height(i, j + 1), s);
                    out.push((i as f64 + 1.0 - s, j as f64 + s, z));
                }
            }
        }
    }
    out
}

/// Grid coordinates `(x, y, z)` in the world: scaled, moved by a dyadic offset and turned
/// so that the grid's normal is world axis `(axis + 2) % 3` (a permutation: exact).
fn world(axis: usize, scale: f64, [x, y, z]: [f64; 3]) -> [f64; 3] {
    let offset = [0.5, -1.25, 2.0];
    let mut p = [0.0; 3];
    for (k, c) in [x, y, z].into_iter().enumerate() {
        p[(axis + k) % 3] = (c + offset[k]) * scale;
    }
    p
}

/// The grid as a [`Mesh`] in `F`, its triangles wound one way or, `flipped`, the other.
fn grid<F: Float>(axis: usize, scale: f64, flipped: bool) -> Mesh<F> {
    let index = |i: usize, j: usize| (i * (N + 1) + j) as u32;
    let vertices = (0..=N)
        .flat_map(|i| (0..=N).map(move |j| (i, j)))
        .map(|(i, j)| {
            let [x, y, z] = world(axis, scale, [i as f64, j as f64, height(i, j)]);
            Vec3::from_f64(x, y, z)
        })
        .collect();
    let mut triangles = Vec::new();
    for i in 0..N {
        for j in 0..N {
            let (a, b, c, d) = (index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
            // One winding for all: every triangle faces the same way.
            if main_diagonal(i, j) {
                triangles.extend([[a, b, c], [a, c, d]]);
            } else {
                triangles.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    if flipped {
        triangles.iter_mut().for_each(|t| t.reverse());
    }
    Mesh::new(vertices, triangles).unwrap()
}

/// The rays: through each target along the grid's normal axis, from above and from below,
/// each with the distance at which it meets the grid.
fn rays<F: Float>(axis: usize, scale: f64) -> Vec<(Ray<F>, f64)> {
    let mut out = Vec::new();
    for (x, y, z) in targets() {
        for side in [1.0, -1.0] {
            let from = world(axis, scale, [x, y, side * FROM]);
            let to = world(axis, scale, [x, y, 0.0]);
            let origin = Vec3::from_f64(from[0], from[1], from[2]);
            let direction = Vec3::from_f64(to[0] - from[0], to[1] - from[1], to[2] - from[2]);
            let ray = Ray::new(origin, direction.normalize());
            out.push((ray, (FROM - side * z) * scale));
        }
    }
    out
}

/// Every axis, scale and winding: `(axis, scale, flipped)`.
fn configurations() -> impl Iterator<Item = (usize, f64, bool)> {
    (0..3).flat_map(|axis| {
        SCALES
            .into_iter()
            .flat_map(move |s| [(axis, s, false), (axis, s, true)])
    })
}

/// One scene per configuration, on `acceleration`: every ray must hit at its distance and
/// be occluded, one at a time.
fn each_ray_alone<F: Float>(acceleration: Acceleration) {
    for (axis, scale, flipped) in configurations() {
        let mut scene = EnumScene::<F>::new(Background::default());
        scene.set_acceleration(acceleration);
        scene.add(
            grid::<F>(axis, scale, flipped),
            Lambertian::new(Vec3::zero()).unwrap(),
        );
        assert_eq!(scene.uses_bvh(), acceleration == Acceleration::Bvh);
        let rays = rays::<F>(axis, scale);
        let leaks = rays
            .iter()
            .filter(|(ray, _)| scene.hit_object(ray, F::infinity()).is_none())
            .count();
        let unoccluded = rays
            .iter()
            .filter(|(ray, _)| !scene.occluded(ray, F::infinity()))
            .count();
        assert_eq!(
            (leaks, unoccluded),
            (0, 0),
            "{} {acceleration:?}, axis {axis}, scale {scale}, flipped {flipped}: of {} rays, {leaks} slipped \
             through and {unoccluded} were not occluded",
            F::NAME,
            rays.len()
        );
        for (ray, distance) in &rays {
            let (hit, _, _) = scene.hit_object(ray, F::infinity()).unwrap();
            let t = hit.t.to_f64();
            assert!(
                (t - distance).abs() <= distance * F::epsilon().to_f64().sqrt(),
                "{} axis {axis} scale {scale}: hit at {t}, the grid is at {distance}",
                F::NAME
            );
        }
    }
}

/// A camera whose pixel `k` (of one row) is the `k`-th ray, wherever in the pixel the
/// sample falls: the renderer's own batches trace exactly these rays.
struct Rays<F>(Vec<Ray<F>>);

impl<F: Float> Camera<F> for Rays<F> {
    fn width(&self) -> usize {
        self.0.len()
    }
    fn height(&self) -> usize {
        1
    }
    fn ray(&self, x: F, _: F) -> Ray<F> {
        self.0[(x.to_f64() as usize).min(self.0.len() - 1)]
    }
}

/// The renderer's batched path: a black grid before a white background. A pixel that is not
/// black saw the background through the grid.
fn in_the_renderer<F: Float>() {
    for (axis, scale, flipped) in configurations() {
        let mut scene = EnumScene::<F>::new(Background::solid(Vec3::from_f64(1.0, 1.0, 1.0)).unwrap());
        scene.set_acceleration(Acceleration::Bvh);
        scene.add(
            grid::<F>(axis, scale, flipped),
            Lambertian::new(Vec3::zero()).unwrap(),
        );
        let camera = Rays(rays::<F>(axis, scale).into_iter().map(|(r, _)| r).collect());
        let render = Renderer::new(&scene, &camera)
            .spp(2)
            .max_depth(1)
            .render()
            .unwrap();
        let leaks = render.image.pixels().iter().filter(|p| **p != [0.0; 3]).count();
        assert_eq!(
            leaks,
            0,
            "{} axis {axis}, scale {scale}, flipped {flipped}: {leaks} of {} rays saw the background",
            F::NAME,
            camera.0.len()
        );
    }
}

#[test]
fn rays_through_exact_edges_hit_a_mesh_in_a_scene_f32() {
    each_ray_alone::<f32>(Acceleration::Bvh);
    each_ray_alone::<f32>(Acceleration::Linear);
    in_the_renderer::<f32>();
}

#[test]
fn rays_through_exact_edges_hit_a_mesh_in_a_scene_f64() {
    each_ray_alone::<f64>(Acceleration::Bvh);
    each_ray_alone::<f64>(Acceleration::Linear);
    in_the_renderer::<f64>();
}
