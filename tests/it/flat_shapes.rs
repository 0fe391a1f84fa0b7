//! The error bounds of [`Plane`], [`Triangle`] and [`Disk`] hits, and pbrt's
//! `TestReintersectConvex` invariant for them: a ray spawned from a hit never hits the same
//! shape again.
//!
//! For random shapes at scales 1, 10³, 10⁴ (f32) and up to 10⁸ (f64) — random position,
//! orientation and (for triangles and disks) size and shape, half of them with a vertex (a
//! disk's centre) next to the world origin — seeded rays are aimed at random points of the
//! shape (for triangles, half of them very close to a vertex) from random origins. For
//! every hit:
//! 1. the exact surface (evaluated in double-double) passes through the box
//!    `point ± error` the hit reports;
//! 2. rays spawned with [`Hit::spawn`](raytrace::Hit::spawn) along the mirror
//!    direction, straight through (the transmitted direction of an index-matched
//!    interface), along 8 uniform random directions on either side and along 5 grazing
//!    directions (in the surface, or tilted off it by `±ε`, `±100ε`), never hit that
//!    shape again (`hit` is `None` and `occluded` is false);
//! 3. every spawned origin lies strictly on the side of the exact surface its direction
//!    points to (checked when that side is not itself within rounding, `|w·n| ≥ 10⁻³`);
//! 4. rays whose `t > 0` is within rounding — starting on the surface (within rounding,
//!    on either side) in random directions, or anywhere in grazing directions — never
//!    report a hit that lies behind their origin in exact arithmetic: the `t > 0` test
//!    is conservative.
//!
//! These are invariants, not statistics: a single violation fails the test.

use crate::common::Alone;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use raytrace::optics::reflect;
use raytrace::sampling::unit_sphere_rejection;
use raytrace::shape::{Disk, Plane, Triangle};
use raytrace::{Float, Hittable, Ray, Vec3, lit};
use twofloat::TwoFloat;

/// Shapes per scale, and primary rays per shape.
const SHAPES: usize = 2000;
const RAYS_PER_SHAPE: usize = 4;
const SCALES_F32: [f64; 3] = [1.0, 1e3, 1e4];
const SCALES_F64: [f64; 5] = [1.0, 1e3, 1e4, 1e6, 1e8];

type Dd = Vec3<TwoFloat>;

fn uniform(rng: &mut Xoshiro256PlusPlus, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * rng.random::<f64>()
}

/// A point uniform in the cube `[−s, s]³`, in f64.
fn in_cube(rng: &mut Xoshiro256PlusPlus, s: f64) -> [f64; 3] {
    std::array::from_fn(|_| uniform(rng, -s, s))
}

fn to_vec<F: Float>(p: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(p[0], p[1], p[2])
}

/// A flat shape under test, with its exact supporting plane.
trait Flat<F: Float>: Hittable<F> + Sized {
    const NAME: &'static str;
    /// A random shape at `scale`, or `None` if the draw was degenerate.
    fn random(rng: &mut Xoshiro256PlusPlus, scale: f64) -> Option<Self>;
    /// A random point of the shape (within rounding) to aim at.
    fn target(&self, rng: &mut Xoshiro256PlusPlus, scale: f64) -> Vec3<F>;
    /// A point of the exact supporting plane and a (not necessarily unit) normal of it,
    /// in double-double.
    fn exact_plane(&self) -> (Dd, Dd);
    /// The unit normal of the supporting plane, rounded to `G`.
    fn exact_plane_normal_in<G: Float>(&self) -> Vec3<G> {
        let n = self.exact_plane().1;
        (n / n.dot(n).sqrt()).cast()
    }
}

impl<F: Float> Flat<F> for Plane<F> {
    const NAME: &'static str = "plane";
    fn random(rng: &mut Xoshiro256PlusPlus, scale: f64) -> Option<Self> {
        let point = to_vec(in_cube(rng, scale));
        Plane::new(point, to_vec(unit_sphere_rejection(rng))).ok()
    }
    fn target(&self, rng: &mut Xoshiro256PlusPlus, scale: f64) -> Vec3<F> {
        // A random point projected onto the plane in f64: q − ((q − P₀)·n)n.
        let q = in_cube(rng, scale);
        let (p0, n) = (self.point().to_f64(), self.normal().to_f64());
        let s: f64 = (0..3).map(|i| (q[i] - p0[i]) * n[i]).sum();
        to_vec(std::array::from_fn(|i| q[i] - s * n[i]))
    }
    fn exact_plane(&self) -> (Dd, Dd) {
        // The plane *is* the set (X − P₀)·n = 0 for the stored, rounded P₀ and n.
        (self.point().cast(), self.normal().cast())
    }
}

impl<F: Float> Flat<F> for Triangle<F> {
    const NAME: &'static str = "triangle";
    fn random(rng: &mut Xoshiro256PlusPlus, scale: f64) -> Option<Self> {
        // Anywhere in the cube, of any size from 1 % of the scale to the scale itself.
        let centre = in_cube(rng, scale);
        let size = scale * 10f64.powf(uniform(rng, -2.0, 0.0));
        let [mut a, b, c] = std::array::from_fn(|_| {
            let d = in_cube(rng, size);
            std::array::from_fn(|i| centre[i] + d[i])
        });
        // Half of them with vertex A next to the world origin: hits near A then have a
        // tiny error bound while the other vertices are large, the case where the t > 0
        // test must be conservative (pbrt-v4 §6.8.4).
        if rng.random::<bool>() {
            let near = scale * 10f64.powf(uniform(rng, -8.0, -2.0));
            a = in_cube(rng, near);
        }
        Triangle::new(to_vec(a), to_vec(b), to_vec(c)).ok()
    }
    fn target(&self, rng: &mut Xoshiro256PlusPlus, _scale: f64) -> Vec3<F> {
        // Half uniform on the triangle (b₁ = 1 − √u₁, b₂ = u₂√u₁), half log-uniformly
        // close to vertex A (b₁, b₂ down to 1000ε, where rounding the aimed-at point to F
        // does not yet move it off the triangle); in f64.
        let (u1, u2) = (rng.random::<f64>(), rng.random::<f64>());
        let b = if rng.random::<bool>() {
            [1.0 - u1.sqrt(), u2 * u1.sqrt()]
        } else {
            let closest = (1e3 * F::epsilon().to_f64()).log10();
            let near = 10f64.powf(uniform(rng, closest, -1.0));
            [u1 * near, u2 * near]
        };
        let [a, p, q] = self.vertices().map(|v| v.to_f64());
        to_vec(std::array::from_fn(|i| {
            a[i] + b[0] * (p[i] - a[i]) + b[1] * (q[i] - a[i])
        }))
    }
    fn exact_plane(&self) -> (Dd, Dd) {
        let [a, b, c] = self.vertices().map(|v| v.cast::<TwoFloat>());
        (a, (b - a).cross(c - a))
    }
}

impl<F: Float> Flat<F> for Disk<F> {
    const NAME: &'static str = "disk";
    fn random(rng: &mut Xoshiro256PlusPlus, scale: f64) -> Option<Self> {
        // Any two axes (an ellipse, often long and thin) of 1 % to 100 % of the scale,
        // about a centre anywhere or (half of them) next to the world origin.
        let size = scale * 10f64.powf(uniform(rng, -2.0, 0.0));
        let centre = if rng.random::<bool>() {
            let near = scale * 10f64.powf(uniform(rng, -8.0, -2.0));
            in_cube(rng, near)
        } else {
            in_cube(rng, scale)
        };
        let (u, v) = (in_cube(rng, size), in_cube(rng, size));
        let disk = Disk::with_axes(to_vec(centre), to_vec(u), to_vec(v)).ok()?;
        Some(if rng.random::<bool>() {
            disk.flipped()
        } else {
            disk
        })
    }
    fn target(&self, rng: &mut Xoshiro256PlusPlus, _scale: f64) -> Vec3<F> {
        // C + aU + bV for (a, b) uniform in the unit disk, in f64.
        let (r, phi) = (
            rng.random::<f64>().sqrt(),
            std::f64::consts::TAU * rng.random::<f64>(),
        );
        let (a, b) = (r * phi.cos(), r * phi.sin());
        let c = self.center().to_f64();
        let [u, v] = self.axes().map(|x| x.to_f64());
        to_vec(std::array::from_fn(|i| c[i] + a * u[i] + b * v[i]))
    }
    fn exact_plane(&self) -> (Dd, Dd) {
        // The disk's plane is the set (X − C)·n = 0 for the stored centre and unit normal.
        (self.center().cast(), self.normal().cast())
    }
}

/// What one configuration saw.
#[derive(Debug, Default)]
struct Tally {
    primaries: usize,
    hits: usize,
    spawned: usize,
    /// The largest `distance / reach` over the hits: how tight the error bound is (≤ 1).
    tightest: f64,
}

fn check<F: Float, S: Flat<F>>(scale: f64, seed: u64) -> Tally {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    let mut tally = Tally::default();
    let ctx = |what: &str| format!("{} {} at scale {scale}: {what}", F::NAME, S::NAME);
    for _ in 0..SHAPES {
        let Some(shape) = S::random(&mut rng, scale) else {
            continue;
        };
        let (p0, n) = shape.exact_plane();
        for _ in 0..RAYS_PER_SHAPE {
            let origin = to_vec::<F>(in_cube(&mut rng, 3.0 * scale));
            let target = shape.target(&mut rng, scale);
            let Some(ray) = Ray::towards(origin, target) else {
                continue;
            };
            tally.primaries += 1;
            let Some(hit) = shape.hit(&ray, F::infinity()) else {
                continue;
            };
            tally.hits += 1;

            // 1. The exact plane passes through the error box: |(P − P₀)·n| ≤ Σ|nᵢ|errᵢ.
            let distance = (hit.point.cast::<TwoFloat>() - p0).dot(n).abs();
            let reach = n.abs().dot(hit.error.cast());
            assert!(
                distance <= reach,
                "{}",
                ctx(&format!(
                    "{hit:?} is {distance:?} off the plane, bound reaches {reach:?}"
                ))
            );
            if reach > TwoFloat::from(0.0) {
                tally.tightest = tally.tightest.max((distance / reach).to_f64());
            }

            // 2 and 3. Spawned rays never come back, and start on their own side.
            let mut directions = vec![reflect(ray.direction, hit.normal), ray.direction];
            directions.extend((0..8).map(|_| to_vec::<F>(unit_sphere_rejection(&mut rng))));
            // Grazing: along the surface, tilted off it by at most ~100 ε either way.
            let tangent = hit.normal.cross(to_vec(unit_sphere_rejection(&mut rng)));
            if let Some(tangent) = tangent.try_normalize() {
                for tilt in [0.0, 1.0, -1.0, 100.0, -100.0] {
                    let w = tangent + hit.normal * (F::epsilon() * lit(tilt));
                    directions.extend(w.try_normalize());
                }
            }
            for w in directions {
                let spawned = hit.spawn(w);
                tally.spawned += 1;
                let again = shape.hit(&spawned, F::infinity());
                assert!(
                    again.is_none() && !shape.occluded(&spawned, F::infinity()),
                    "{}",
                    ctx(&format!(
                        "ray {spawned:?} spawned from {hit:?} hit again: {again:?}"
                    ))
                );
                let w_dd = w.cast::<TwoFloat>();
                let cos = w_dd.dot(n) / n.dot(n).sqrt();
                if cos.abs() >= TwoFloat::from(1e-3) {
                    let side = (spawned.origin.cast::<TwoFloat>() - p0).dot(n);
                    assert!(
                        side * cos > TwoFloat::from(0.0),
                        "{}",
                        ctx(&format!(
                            "origin of {spawned:?} (from {hit:?}) is on the wrong side"
                        ))
                    );
                }
            }
        }

        // 4. Rays whose t > 0 is within rounding: starting on the surface (a point of it
        // rounded to F, so within rounding on either side) in random directions, and
        // starting anywhere in grazing directions (in the surface, or tilted off it by
        // ±ε). A reported hit must lie ahead in exact arithmetic,
        // t = ((P₀ − O)·n)/(D·n) > 0.
        let unit = shape.exact_plane_normal_in::<F>();
        for k in 0..2 * RAYS_PER_SHAPE {
            let ray = if k % 2 == 0 {
                Ray::new(
                    shape.target(&mut rng, scale),
                    to_vec(unit_sphere_rejection(&mut rng)),
                )
            } else {
                let tangent = unit.cross(to_vec(unit_sphere_rejection(&mut rng)));
                let tilt = F::epsilon() * lit([0.0, 1.0, -1.0][k / 2 % 3]);
                let Some(d) = (tangent + unit * tilt).try_normalize() else {
                    continue;
                };
                Ray::new(to_vec(in_cube(&mut rng, 3.0 * scale)), d)
            };
            if let Some(hit) = shape.hit(&ray, F::infinity()) {
                let ahead = (p0 - ray.origin.cast()).dot(n) * ray.direction.cast().dot(n);
                assert!(
                    ahead > TwoFloat::from(0.0),
                    "{}",
                    ctx(&format!("{ray:?} hit behind its origin: {hit:?}"))
                );
            }
        }
    }
    // Rays are aimed inside the shape; only the conservative rejections may miss.
    assert!(
        tally.hits * 100 >= tally.primaries * 95,
        "{}",
        ctx(&format!(
            "only {} of {} aimed rays hit",
            tally.hits, tally.primaries
        ))
    );
    println!(
        "{} {:<8} scale {scale:>5e}: {} / {} hits, {} spawned rays, max distance/bound {:.3}",
        F::NAME,
        S::NAME,
        tally.hits,
        tally.primaries,
        tally.spawned,
        tally.tightest
    );
    tally
}

fn check_all<F: Float, S: Flat<F>>(scales: &[f64], seed: u64) {
    for (i, &scale) in scales.iter().enumerate() {
        let tally = check::<F, S>(scale, seed + i as u64);
        assert!(tally.spawned > 0);
    }
}

#[test]
fn plane_hits_are_bounded_and_never_reintersect_f32() {
    check_all::<f32, Plane<f32>>(&SCALES_F32, 100);
}

#[test]
fn plane_hits_are_bounded_and_never_reintersect_f64() {
    check_all::<f64, Plane<f64>>(&SCALES_F64, 200);
}

#[test]
fn triangle_hits_are_bounded_and_never_reintersect_f32() {
    check_all::<f32, Triangle<f32>>(&SCALES_F32, 300);
}

#[test]
fn triangle_hits_are_bounded_and_never_reintersect_f64() {
    check_all::<f64, Triangle<f64>>(&SCALES_F64, 400);
}

#[test]
fn disk_hits_are_bounded_and_never_reintersect_f32() {
    check_all::<f32, Disk<f32>>(&SCALES_F32, 500);
}

#[test]
fn disk_hits_are_bounded_and_never_reintersect_f64() {
    check_all::<f64, Disk<f64>>(&SCALES_F64, 600);
}
