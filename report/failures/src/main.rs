//! The report's failure figures: the accuracy study's scenes where a textbook method fails,
//! rendered with the textbook method and with the library's, beside their reference.
//!
//! Writes into `report/figures/failures/` (or the folder given as the only argument):
//! - `<case>-<run>.png`: the renders the report shows (16-bit sRGB PNG), and
//!   `<case>-<run>-diff.png`: the reference dimmed to grey with every pixel off by more than
//!   one 8-bit step in red;
//! - `failures.csv`: per render, its error against the double-double reference (the study's
//!   measures); for the watertightness case, against the watertight render;
//! - `watertight.csv`: per render of the watertightness case, the pixels whose ray slipped
//!   through the mesh; `degenerate.csv`: the textbook Lambertian direction near `S = −N`.
//!
//! The cases, scenes and settings are the accuracy study's own (`examples/precision`, at
//! 400×200, seed 0, 4 spp and depth 50 for the Monte Carlo case), so the shares printed
//! here are those of `report/figures/precision.csv`; one more case, `self_hit`, renders the
//! spec's four mirrors with the textbook intersection and *no* `t_min` (rays leave from the
//! rounded hit point), which the study does not run.
//!
//! Run from the repository root:
//! `CARGO_TARGET_DIR=target cargo run --release --manifest-path report/failures/Cargo.toml`

#[path = "../../../examples/scenes/mod.rs"]
mod scenes;

#[allow(dead_code)]
#[path = "../../../examples/precision/cases.rs"]
mod cases;

// The study's third sphere (no offset) is not drawn here.
#[allow(dead_code)]
#[path = "../../../examples/precision/textbook.rs"]
mod textbook;

use cases::{Cam, Case};
use raytrace::metrics::ImageError;
use raytrace::prelude::*;
use raytrace::aabb::Aabb;
use raytrace::shape::{
    Coordinates, Hit, Surface, SurfaceSample, textbook_sphere_record, textbook_sphere_t,
};
use raytrace::{DoubleDouble, Image, Intersection, Scene};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const WIDTH: usize = 400;
const SEED: u64 = 0;

/// The textbook sphere with `t_min = 0`: the hit point is `O + tD` rounded, with no error
/// bound, so a spawned ray starts exactly there (the "shadow acne" set-up).
#[derive(Clone, Copy, Debug)]
struct NoTMinSphere<F>(Sphere<F>);

impl<F: Float> Hittable<F> for NoTMinSphere<F> {
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        textbook_sphere_t(&self.0, ray, F::zero(), t_max).map(Intersection::at)
    }
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        textbook_sphere_record(&self.0, ray, hit.t)
    }
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        self.0.coordinates(ray, hit, record)
    }
    fn bounds(&self) -> Option<Aabb<F>> {
        self.0.bounds()
    }
    fn parts(&self) -> u32 {
        1
    }
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        self.0.bounds()
    }
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }
    fn area(&self) -> Option<F> {
        self.0.area()
    }
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        self.0.sample(from, u)
    }
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        self.0.pdf(ray, hit)
    }
}

// Tested one at a time, never in the scene's packets of four.
impl<F: Float> Layout<F> for NoTMinSphere<F> {}

/// A mesh whose triangles are intersected by the textbook Möller–Trumbore test: the
/// barycentrics `u`, `v` computed with rounding and the inside test `u, v ≥ 0`,
/// `u + v ≤ 1` applied to them, so that a ray through an edge two triangles share can be
/// judged outside both.
#[derive(Clone, Debug)]
struct NaiveMesh<F> {
    triangles: Vec<[Vec3<F>; 3]>,
}

impl<F: Float> NaiveMesh<F> {
    fn moller_trumbore(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let [a, b, c] = self.triangles[part as usize];
        let (e1, e2) = (b - a, c - a);
        let p = ray.direction.cross(e2);
        let det = e1.dot(p);
        if det == F::zero() {
            return None;
        }
        let inv = F::one() / det;
        let s = ray.origin - a;
        let u = s.dot(p) * inv;
        let q = s.cross(e1);
        let v = ray.direction.dot(q) * inv;
        if u < F::zero() || v < F::zero() || u + v > F::one() {
            return None;
        }
        let t = e2.dot(q) * inv;
        (t > F::zero() && t < t_max).then_some(Intersection {
            t,
            part,
            coords: [F::one() - u - v, u, v],
        })
    }
}

impl<F: Float> Hittable<F> for NaiveMesh<F> {
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let mut best: Option<Intersection<F>> = None;
        for part in 0..self.parts() {
            let reach = best.map_or(t_max, |b| b.t);
            if let Some(h) = self.moller_trumbore(part, ray, reach) {
                best = Some(h);
            }
        }
        best
    }
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        let [a, b, c] = self.triangles[hit.part as usize];
        let point = ray.at(hit.t);
        // A generous bound on the point's rounding error, so that spawned rays never
        // re-hit: only the leaks through edges differ from the library's render.
        let error = point.map(|x| x.abs() * lit::<F>(64.0) * F::eps());
        let surface = Surface {
            t: hit.t,
            point,
            error,
            outward: (b - a).cross(c - a).normalize(),
            shading_normal: None,
        };
        Hit::new(surface, ray.direction)
    }
    fn coordinates(&self, _: &Ray<F>, _: &Intersection<F>, _: &Hit<F>) -> Coordinates<F> {
        Coordinates {
            uv: [F::zero(); 2],
            dpdu: Vec3::zero(),
        }
    }
    // Never a light: the mirror mesh emits nothing.
    fn area(&self) -> Option<F> {
        None
    }
    fn sample(&self, _: Vec3<F>, _: [f64; 3]) -> Option<SurfaceSample<F>> {
        None
    }
    fn pdf(&self, _: &Ray<F>, _: &Hit<F>) -> F {
        F::zero()
    }
    fn bounds(&self) -> Option<Aabb<F>> {
        (0..self.parts()).filter_map(|p| self.part_bounds(p)).reduce(Aabb::union)
    }
    fn parts(&self) -> u32 {
        self.triangles.len() as u32
    }
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        let [a, b, c] = self.triangles[part as usize];
        Some(Aabb::new(a, b).union(Aabb::new(c, c)))
    }
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.moller_trumbore(part, ray, t_max)
    }
}

impl<F: Float> Layout<F> for NaiveMesh<F> {}

/// One render of a case, by scalar and method.
fn render_case<F: Float>(case: &Case, textbook: bool) -> raytrace::Result<Image> {
    let scene = case.scene.cast::<F>()?;
    if textbook {
        render_scene(case, &textbook::to_textbook(&scene))
    } else {
        render_scene(case, &scene)
    }
}

/// Renders `scene`, a case's scene in scalar `F`, with the case's camera and settings.
fn render_scene<F: Float, S: Layout<F> + Sync>(
    case: &Case,
    scene: &Scene<F, S, MaterialKind<F>>,
) -> raytrace::Result<Image> {
    let settings = RenderSettings::new(case.spp, case.max_depth, SEED)?;
    Ok(match case.camera {
        Cam::Screen(c) => render(scene, &c, &settings)?.image,
        Cam::LookAt(c) => render(scene, &c.cast::<F>(), &settings)?.image,
    })
}

/// The spec's four mirrors in `F` with every sphere intersected with `t_min = 0`.
fn render_no_t_min<F: Float>(case: &Case) -> raytrace::Result<Image> {
    let scene = case.scene.cast::<F>()?;
    let mut naive: Scene<F, NoTMinSphere<F>, MaterialKind<F>> = Scene::new(scene.background().clone());
    for o in scene.objects() {
        let ShapeKind::Sphere(s) = o.shape else {
            unreachable!("four_mirrors holds spheres only")
        };
        naive.add(NoTMinSphere(s), scene.material(o.material).clone());
    }
    let Cam::Screen(camera) = case.camera else {
        unreachable!("four_mirrors uses the spec's camera")
    };
    let settings = RenderSettings::new(case.spp, case.max_depth, SEED)?;
    Ok(render(&naive, &camera, &settings)?.image)
}

/// The reference dimmed to grey, with the pixels where `image` is off by more than one
/// 8-bit step (sRGB-encoded, as the study counts them) in red.
fn diff_map(image: &Image, reference: &Image) -> Image {
    let enc = Encoding::Srgb;
    let pixels = image
        .pixels()
        .iter()
        .zip(reference.pixels())
        .map(|(p, q)| {
            let off = (0..3).any(|k| (enc.encode(p[k]) - enc.encode(q[k])).abs() > 1.0 / 255.0);
            if off {
                [0.9, 0.0, 0.0]
            } else {
                let grey = (0.2126 * q[0] + 0.7152 * q[1] + 0.0722 * q[2]).clamp(0.0, 1.0);
                [0.05 + 0.3 * grey; 3]
            }
        })
        .collect();
    Image::from_pixels(image.width(), image.height(), pixels).expect("same size")
}

/// The panels the report shows; the other renders are measured but not written.
const SHOWN: [&str; 16] = [
    "tiny_far-f32-textbook",
    "tiny_far-f32-textbook-diff",
    "tiny_far-f32-stable-diff",
    "far_1e4-f32-textbook",
    "far_1e4-f32-textbook-diff",
    "far_1e4-f32-stable-diff",
    "self_hit-f32-t_min0",
    "self_hit-f32-t_min0-diff",
    "self_hit-f64-t_min0-diff",
    "small_glass-f64-stable",
    "small_glass-f64-textbook",
    "small_glass-f64-textbook-diff",
    "watertight-f32-library",
    "watertight-f32-naive",
    "watertight-f64-library",
    "watertight-f64-naive",
];

fn save(dir: &Path, name: &str, image: &Image) -> raytrace::Result<()> {
    if !SHOWN.contains(&name) {
        return Ok(());
    }
    let path = dir.join(format!("{name}.png"));
    raytrace::image::write_png(&path, &image.to_u16(Encoding::Srgb), Encoding::Srgb)
}

fn run(dir: &Path) -> raytrace::Result<()> {
    std::fs::create_dir_all(dir).map_err(|source| raytrace::Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut cases = cases::all(WIDTH, SEED)?;
    // As the study runs them: its defaults, 4 spp and depth 50, for the Monte Carlo cases.
    for c in cases.iter_mut().filter(|c| c.spp > 1) {
        c.spp = 4;
        c.max_depth = 50;
    }
    let find = |name: &str| cases.iter().find(|c| c.name == name).expect("a study case");
    let mut csv = String::from("case,scalar,method,rmse,max_error,share_over_one_step\n");
    let mut record = |case: &str, scalar: &str, method: &str, image: &Image, reference: &Image| {
        let e = ImageError::between(image, reference, Encoding::Srgb)?;
        let _ = writeln!(
            csv,
            "{case},{scalar},{method},{:.3e},{:.3e},{:.5}",
            e.rmse, e.max, e.over_one_step
        );
        println!(
            "{case:<13} {scalar} {method:<9} {:>7.3} % of pixels off by more than one 8-bit step",
            100.0 * e.over_one_step
        );
        raytrace::Result::Ok(())
    };

    // Cancellation: small spheres far away (f32), and a tiny glass sphere (f64).
    for (name, scalar) in [("tiny_far", "f32"), ("far_1e4", "f32"), ("small_glass", "f64")] {
        let case = find(name);
        let reference = render_case::<DoubleDouble>(case, false)?;
        for textbook in [false, true] {
            let image = match scalar {
                "f32" => render_case::<f32>(case, textbook)?,
                _ => render_case::<f64>(case, textbook)?,
            };
            let method = if textbook { "textbook" } else { "stable" };
            record(name, scalar, method, &image, &reference)?;
            save(dir, &format!("{name}-{scalar}-{method}"), &image)?;
            save(
                dir,
                &format!("{name}-{scalar}-{method}-diff"),
                &diff_map(&image, &reference),
            )?;
        }
    }

    // Self-intersection: the spec's scene, rays leaving from the rounded hit point.
    let case = find("four_mirrors");
    let reference = render_case::<DoubleDouble>(case, false)?;
    for (scalar, image) in [
        ("f32", render_no_t_min::<f32>(case)?),
        ("f64", render_no_t_min::<f64>(case)?),
    ] {
        record("self_hit", scalar, "t_min=0", &image, &reference)?;
        save(dir, &format!("self_hit-{scalar}-t_min0"), &image)?;
        save(
            dir,
            &format!("self_hit-{scalar}-t_min0-diff"),
            &diff_map(&image, &reference),
        )?;
    }
    let stable = render_case::<f32>(case, false)?;
    record("self_hit", "f32", "stable", &stable, &reference)?;

    // Watertightness: a bumpy mesh every pixel ray meets exactly on an edge or a vertex.
    let mut leaks = String::from("scalar,method,pixels,leaked,share\n");
    for scalar in ["f32", "f64"] {
        let (library, naive) = match scalar {
            "f32" => watertight::<f32>()?,
            _ => watertight::<f64>()?,
        };
        record("watertight", scalar, "naive", &naive, &library)?;
        for (method, image) in [("library", &library), ("naive", &naive)] {
            // A ray that slipped through sees the background (red 1); a mirror triangle
            // reflects it dimmed (red at most 0.12).
            let leaked = image.pixels().iter().filter(|p| p[0] > 0.5).count();
            let _ = writeln!(
                leaks,
                "{scalar},{method},{},{leaked},{:.5}",
                image.pixels().len(),
                leaked as f64 / image.pixels().len() as f64
            );
            save(dir, &format!("watertight-{scalar}-{method}"), image)?;
        }
    }
    let path = dir.join("watertight.csv");
    raytrace::image::write_atomic(&path, |w| std::io::Write::write_all(w, leaks.as_bytes()))?;
    println!("wrote {}", path.display());

    let path = dir.join("degenerate.csv");
    let table = degenerate_scatter();
    raytrace::image::write_atomic(&path, |w| std::io::Write::write_all(w, table.as_bytes()))?;
    println!("wrote {}", path.display());

    let path = dir.join("failures.csv");
    raytrace::image::write_atomic(&path, |w| std::io::Write::write_all(w, csv.as_bytes()))?;
    println!("wrote {}", path.display());
    Ok(())
}

/// Watertightness: a mesh of 2·200·100 triangles whose vertices lie on the rays through
/// every other pixel centre of the spec's 400×200 camera, at distances between 94 and 106,
/// so that every pixel's ray passes exactly (in exact arithmetic) through a vertex or an
/// edge two triangles share. Mirror triangles before a bright solid background: a ray that
/// slips through the mesh shows the background. Returns the library's render (`Mesh`,
/// watertight) and the textbook Möller–Trumbore's.
fn watertight<F: Float>() -> raytrace::Result<(Image, Image)> {
    let (w, h) = (400_usize, 200_usize);
    let camera = ScreenCamera::new(w, h)?;
    let (cols, rows) = (w / 2 + 1, h / 2 + 1);
    let mut vertices: Vec<Vec3<F>> = Vec::with_capacity(cols * rows);
    for j in 0..rows {
        for i in 0..cols {
            // Pixel centre (2i, 2j) of the spec's screen, pushed out along its ray.
            let (pi, pj) = ((2 * i) as f64, (2 * j) as f64);
            let p = [-2.0 + 4.0 * pi / (w - 1) as f64, 1.0 - 2.0 * pj / (h - 1) as f64, -1.0];
            let d = 100.0 * (1.0 + 0.06 * (0.07 * pi).sin() * (0.05 * pj).cos());
            vertices.push(Vec3::from_f64(p[0] * d, p[1] * d, p[2] * d));
        }
    }
    let mut triangles = Vec::new();
    for j in 0..rows - 1 {
        for i in 0..cols - 1 {
            let v = |a: usize, b: usize| ((j + b) * cols + i + a) as u32;
            // Split along the diagonal that the odd-odd pixel's ray meets.
            triangles.push([v(0, 0), v(1, 0), v(1, 1)]);
            triangles.push([v(0, 0), v(1, 1), v(0, 1)]);
        }
    }
    let background: Background<F> = Background::solid(Vec3::from_f64(1.0, 0.85, 0.3))?;
    let mirror: Mirror<F> = Mirror::new(Vec3::from_f64(0.12, 0.16, 0.3))?;
    let settings = RenderSettings::new(1, 2, SEED)?;
    let naive = NaiveMesh {
        triangles: triangles
            .iter()
            .map(|t| t.map(|k| vertices[k as usize]))
            .collect(),
    };
    let mut library_scene = EnumScene::<F>::new(background.clone());
    library_scene.add(Mesh::new(vertices, triangles)?, mirror);
    let mut naive_scene: Scene<F, NaiveMesh<F>, MaterialKind<F>> = Scene::new(background);
    naive_scene.add(naive, mirror);
    Ok((
        render(&library_scene, &camera, &settings)?.image,
        render(&naive_scene, &camera, &settings)?.image,
    ))
}

/// Degenerate scatter: the textbook Lambertian direction `(N + S)/|N + S|` when the sphere
/// point `S` lies within `δ` of `−N`. For each `δ` (10⁻¹⁸ to 10⁻¹) and scalar, 4000 normals
/// spread over the sphere, each with `S = normalize(−N + δ·w)` for a unit `w` (computed
/// in f64 and rounded to the scalar, as the spec's sampler returns it): the share of
/// directions that are NaN or point below the surface (`d·N < 0`, evaluated in f64).
/// The library redraws every `S` with `|N + S|² ≤ 64ε`; `outside_cap` counts the failures
/// it would not redraw (it must be 0).
fn degenerate_scatter() -> String {
    fn spiral(k: usize, n: usize, twist: f64) -> [f64; 3] {
        let z = 1.0 - (2.0 * k as f64 + 1.0) / n as f64;
        let r = (1.0 - z * z).sqrt();
        let phi = k as f64 * (std::f64::consts::PI * (3.0 - 5f64.sqrt())) + twist;
        [r * phi.cos(), r * phi.sin(), z]
    }
    fn run<F: Float>(delta: f64, n: usize) -> (usize, usize, usize, usize, f64) {
        let cap = 64.0 * <F as Float>::to_f64(F::eps());
        let (mut nan, mut below, mut outside) = (0, 0, 0);
        for k in 0..n {
            let nn = spiral(k, n, 0.0);
            let w = spiral((k * 7919) % n, n, 1.0);
            let s = [-nn[0] + delta * w[0], -nn[1] + delta * w[1], -nn[2] + delta * w[2]];
            let len = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
            let n_f = Vec3::<F>::from_f64(nn[0], nn[1], nn[2]);
            let s_f = Vec3::<F>::from_f64(s[0] / len, s[1] / len, s[2] / len);
            let sum = n_f + s_f;
            let d = sum / sum.length();
            let [dx, dy, dz] = d.to_f64();
            let [nx, ny, nz] = n_f.to_f64();
            let failed = if !d.is_finite() {
                nan += 1;
                true
            } else if dx * nx + dy * ny + dz * nz < 0.0 {
                below += 1;
                true
            } else {
                false
            };
            let [sx, sy, sz] = sum.to_f64();
            if failed && sx * sx + sy * sy + sz * sz > cap {
                outside += 1;
            }
        }
        (n, nan, below, outside, cap)
    }
    let mut out = String::from("scalar,delta,cases,nan,below,outside_cap,cap\n");
    for e in 0..=68 {
        let delta = 10f64.powf(-18.0 + e as f64 / 4.0);
        for (scalar, r) in [("f32", run::<f32>(delta, 4000)), ("f64", run::<f64>(delta, 4000))] {
            let _ = writeln!(out, "{scalar},{delta:.4e},{},{},{},{},{:.4e}", r.0, r.1, r.2, r.3, r.4);
        }
    }
    out
}

fn main() -> ExitCode {
    let dir = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("report/figures/failures"), PathBuf::from);
    match run(&dir) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
