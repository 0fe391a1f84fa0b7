//! The look-at camera's thin lens, against the thin-lens geometry worked out here in `f64`
//! from the camera's description alone:
//!
//! - a point on the plane of focus projects to the same pixel from every point of the lens
//!   (it is sharp), and the camera's ray through that pixel from each lens point passes
//!   through it; the same check rejects a focus distance 2 % off;
//! - a point at depth `z` is spread over the circle of confusion `A·|z − f|/z` (on the
//!   plane of focus; `A·|z − f|/z · n_y/(f·h)` pixels, `h = 2·tan(vfov/2)`), reached from
//!   the rim of the lens;
//! - an aperture of 0 is the pinhole, ray for ray and image for image;
//! - the batched renderer gives the reference renderer's bits with depth of field on, on
//!   1 and 2 threads, in f32 and f64.

use crate::common::{cross, dot, normalize};
use crate::scenes;
use raytrace::Image;
use raytrace::prelude::*;

const FROM: [f64; 3] = [1.0, 2.0, 3.0];
const AT: [f64; 3] = [0.0, 0.5, -4.0];
const UP: [f64; 3] = [0.0, 1.0, 0.0];
const VFOV: f64 = 30.0;
const NX: usize = 64;
const NY: usize = 40;
const APERTURE: f64 = 0.25;
const FOCUS: f64 = 5.0;

fn v(a: [f64; 3]) -> Vec3<f64> {
    Vec3::new(a[0], a[1], a[2])
}

fn a(p: Vec3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}

fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

fn along(p: [f64; 3], d: [f64; 3], t: f64) -> [f64; 3] {
    [p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2]]
}

fn pinhole() -> LookAtCamera<f64> {
    LookAtCamera::new(v(FROM), v(AT), v(UP), VFOV, NX, NY).unwrap()
}

fn lens(focus: f64) -> LookAtCamera<f64> {
    pinhole().with_lens(APERTURE, Some(focus)).unwrap()
}

/// The camera's frame as the thin-lens model has it: the view axis `f̂`, the unit right
/// `u` and up `v`, the viewport's height `h` per unit of depth.
struct Frame {
    axis: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
    h: f64,
}

fn frame() -> Frame {
    let w = normalize(sub(FROM, AT));
    let u = normalize(cross(UP, w));
    Frame {
        axis: w.map(|x| -x),
        u,
        v: cross(w, u),
        h: 2.0 * (VFOV.to_radians() / 2.0).tan(),
    }
}

/// The pixel coordinates at which the point `q` appears through the lens point `l`: the
/// ray from `l` through `q` meets the plane of focus (depth `f` along the axis from the
/// eye) at a point, whose pinhole pixel it is.
fn project(l: [f64; 3], q: [f64; 3]) -> [f64; 2] {
    let fr = frame();
    let dq = sub(q, l);
    let on_plane = along(l, dq, (FOCUS - dot(sub(l, FROM), fr.axis)) / dot(dq, fr.axis));
    let d = sub(on_plane, FROM).map(|x| x / FOCUS);
    let s = dot(d, fr.u) / (fr.h * NX as f64 / NY as f64);
    let t = dot(d, fr.v) / fr.h;
    [(s + 0.5) * NX as f64 - 0.5, (0.5 - t) * NY as f64 - 0.5]
}

/// The point at depth `z` along the axis on the pinhole ray through pixel `p`.
fn at_depth(p: [f64; 2], z: f64) -> [f64; 3] {
    let d = a(pinhole().ray(p[0], p[1]).direction);
    along(FROM, d, z / dot(d, frame().axis))
}

/// The distance from `q` to the ray.
fn miss(ray: Ray<f64>, q: [f64; 3]) -> f64 {
    let to = sub(q, a(ray.origin));
    let d = a(ray.direction);
    let t = dot(to, d);
    let closest = along(a(ray.origin), d, t);
    dot(sub(q, closest), sub(q, closest)).sqrt()
}

/// Lens samples: a grid over `[0, 1)²`, its first row and column on the rim.
fn lens_samples() -> impl Iterator<Item = [f64; 2]> {
    (0..16).flat_map(|i| (0..16).map(move |j| [i as f64 / 16.0, j as f64 / 16.0]))
}

/// The pixel the tests look through, off the image's centre.
const PIXEL: [f64; 2] = [20.3, 11.7];

#[test]
fn a_point_on_the_plane_of_focus_is_sharp() {
    let camera = lens(FOCUS);
    assert!(camera.has_lens());
    assert_eq!((camera.aperture(), camera.focus_distance()), (APERTURE, FOCUS));
    let p = at_depth(PIXEL, FOCUS);
    let mut widest: f64 = 0.0;
    for u in lens_samples() {
        let l = a(camera.ray_through_lens(0.0, 0.0, u).origin);
        widest = widest.max(dot(sub(l, FROM), sub(l, FROM)).sqrt());
        let seen = project(l, p);
        assert!(
            (seen[0] - PIXEL[0]).hypot(seen[1] - PIXEL[1]) < 1e-9,
            "{u:?}: {seen:?}"
        );
        let ray = camera.ray_through_lens(PIXEL[0], PIXEL[1], u);
        assert!(miss(ray, p) < 1e-12 * 8.0, "{u:?}: {}", miss(ray, p));
        // Focused 2 % too far, the rays through the pixel miss the point.
        if dot(sub(l, FROM), sub(l, FROM)).sqrt() > 0.5 * APERTURE {
            let off = lens(FOCUS * 1.02).ray_through_lens(PIXEL[0], PIXEL[1], u);
            assert!(miss(off, p) > 1e-3, "{u:?}: {}", miss(off, p));
        }
    }
    // The lens points fill the aperture's disk, rim included.
    assert!((widest - APERTURE).abs() < 1e-12, "{widest}");
}

#[test]
fn a_point_off_the_plane_blurs_by_the_circle_of_confusion() {
    let camera = lens(FOCUS);
    let fr = frame();
    for z in [2.0, 3.5, 9.0, 40.0] {
        let q = at_depth(PIXEL, z);
        // A·|z − f|/z on the plane of focus, in pixels of size f·h/n_y there.
        let radius = APERTURE * (z - FOCUS).abs() / z * NY as f64 / (FOCUS * fr.h);
        let mut widest: f64 = 0.0;
        for u in lens_samples() {
            let l = a(camera.ray_through_lens(0.0, 0.0, u).origin);
            let seen = project(l, q);
            let off = (seen[0] - PIXEL[0]).hypot(seen[1] - PIXEL[1]);
            assert!(off <= radius * (1.0 + 1e-9), "z = {z}, {u:?}: {off} > {radius}");
            widest = widest.max(off);
            // The camera agrees: its ray through that pixel from that lens point meets q.
            let ray = camera.ray_through_lens(seen[0], seen[1], u);
            assert!(miss(ray, q) < 1e-10 * z, "z = {z}, {u:?}: {}", miss(ray, q));
        }
        assert!(
            (widest - radius).abs() < 1e-9 * radius,
            "z = {z}: {widest} against {radius}"
        );
    }
}

#[test]
fn no_aperture_is_the_pinhole_bit_for_bit() {
    let camera = pinhole().with_lens(0.0, Some(3.0)).unwrap();
    assert!(!camera.has_lens());
    assert_eq!(camera.aperture(), 0.0);
    for (x, y) in [(0.0, 0.0), (PIXEL[0], PIXEL[1]), (63.4, 39.5)] {
        assert_eq!(camera.ray(x, y), pinhole().ray(x, y));
        assert_eq!(camera.ray_through_lens(x, y, [0.9, 0.1]), pinhole().ray(x, y));
    }
    let scene = scenes::random_spheres::<f32>(0).unwrap();
    let pin = scenes::random_spheres_camera::<f32>(32).unwrap();
    let zero = pin.with_lens(0.0, None).unwrap();
    let image = |c: &LookAtCamera<f32>| Renderer::new(&scene, c).spp(2).seed(3).render().unwrap().image;
    assert_eq!(bits(&image(&zero)), bits(&image(&pin)));
}

#[test]
fn negative_apertures_and_focus_distances_are_refused() {
    for (aperture, focus) in [
        (-0.1, None),
        (f64::NAN, None),
        (f64::INFINITY, None),
        (0.1, Some(0.0)),
        (0.1, Some(-2.0)),
    ] {
        assert!(
            pinhole().with_lens(aperture, focus).is_err(),
            "{aperture} {focus:?}"
        );
    }
}

fn bits(image: &Image) -> Vec<[u64; 3]> {
    image.pixels().iter().map(|p| p.map(f64::to_bits)).collect()
}

fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

fn batched_equals_reference_with_depth_of_field<F: Float>() {
    let scene = scenes::random_spheres::<F>(0).unwrap();
    let pin = scenes::random_spheres_camera::<F>(32).unwrap();
    // Focused on the middle sphere, at (0, 1, 0): the rest is blurred.
    let camera = pin.with_lens(lit(0.3), Some(lit(13.5))).unwrap();
    for spp in [1, 3] {
        let renderer = Renderer::new(&scene, &camera).spp(spp).max_depth(8).seed(11);
        let reference = renderer.render_reference().unwrap();
        for threads in [1, 2] {
            let fast = in_pool(threads, || renderer.render().unwrap());
            assert_eq!(
                bits(&fast.image),
                bits(&reference.image),
                "{}, {spp} spp, {threads} threads",
                F::NAME
            );
            assert_eq!(fast.stats.rays, reference.stats.rays);
        }
        let sharp = Renderer::new(&scene, &pin)
            .spp(spp)
            .max_depth(8)
            .seed(11)
            .render_reference()
            .unwrap();
        assert_ne!(
            bits(&sharp.image),
            bits(&reference.image),
            "the lens changes the image"
        );
    }
}

#[test]
fn batched_equals_reference_with_depth_of_field_f32() {
    batched_equals_reference_with_depth_of_field::<f32>();
}

#[test]
fn batched_equals_reference_with_depth_of_field_f64() {
    batched_equals_reference_with_depth_of_field::<f64>();
}
