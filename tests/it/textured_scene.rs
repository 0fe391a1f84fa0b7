//! A small scene of every texture kind and a normal map, built in code from images made in
//! memory, for the reference, dispatch and value-stability tests: a checkerboard floor, a
//! sphere under a colour image (repeated, scaled), a sphere under a normal map, and a mesh
//! with texture coordinates and vertex normals under a clamped image, lit by the sky and a
//! point light.

use raytrace::material::NormalMap;
use raytrace::prelude::*;
use raytrace::texture::{Bitmap, Checkerboard, ImageTexture, UvMap, Wrap};
use std::sync::Arc;

/// A 5 × 3 colour image whose every pixel differs, values in `[0.05, 0.95]`.
pub fn colour_bitmap() -> Arc<Bitmap> {
    let (w, h) = (5, 3);
    let pixels = (0..w * h)
        .map(|k| {
            let (x, y) = ((k % w) as f32, (k / w) as f32);
            [0.05 + 0.2 * x, 0.95 - 0.4 * y, 0.05 + 0.06 * (x + y)]
        })
        .collect();
    Arc::new(Bitmap::from_rgb(w, h, pixels).unwrap())
}

/// A 4 × 4 tangent-space normal map of bumps: the colours `(n + 1)/2` of normals leaning
/// up to 35° in a ring pattern, as a raw image stores them.
pub fn bumps_bitmap() -> Arc<Bitmap> {
    let n = 4;
    let pixels = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f32 - 1.5, (k / n) as f32 - 1.5);
            let lean = 0.35 * (x + 0.5 * y).sin();
            let (nx, ny) = (lean, 0.5 * lean * (y - x).cos());
            let nz = (1.0 - nx * nx - ny * ny).sqrt();
            [(nx + 1.0) / 2.0, (ny + 1.0) / 2.0, (nz + 1.0) / 2.0]
        })
        .collect();
    Arc::new(Bitmap::from_rgb(n, n, pixels).unwrap())
}

/// A unit quad in `x, y` with texture coordinates past `[0, 1]` (so clamping shows) and
/// vertex normals leaning outward, as a two-triangle mesh at `centre`.
fn quad<F: Float>(centre: [f64; 3]) -> Mesh<F> {
    let v = |x: f64, y: f64| Vec3::from_f64(centre[0] + x, centre[1] + y, centre[2]);
    let vertices = vec![v(-0.5, -0.5), v(0.5, -0.5), v(0.5, 0.5), v(-0.5, 0.5)];
    let normals = [(-0.4, -0.4), (0.4, -0.4), (0.4, 0.4), (-0.4, 0.4)]
        .map(|(x, y)| Vec3::from_f64(x, y, 1.0))
        .to_vec();
    let uvs = [[-0.2, 1.3], [1.2, 1.3], [1.2, -0.3], [-0.2, -0.3]]
        .map(|uv: [f64; 2]| uv.map(F::from_f64))
        .to_vec();
    Mesh::new(vertices, vec![[0, 1, 2], [0, 2, 3]])
        .unwrap()
        .with_normals(normals)
        .unwrap()
        .with_uvs(uvs)
        .unwrap()
}

/// The scene, on the enum path; `to_dyn` gives the trait-object path.
pub fn textured<F: Float>() -> EnumScene<F> {
    let c = Vec3::from_f64;
    let mut scene = EnumScene::new(Background::sky(c(0.3, 0.3, 0.35), c(0.5, 0.6, 0.8)).unwrap());
    let uv = |s: [f64; 2], o: [f64; 2]| UvMap::new(s.map(lit), o.map(lit)).unwrap();

    let checks = Checkerboard::new(c(0.8, 0.8, 0.75), c(0.15, 0.2, 0.3))
        .unwrap()
        .with_uv_map(uv([0.5, 0.5], [0.25, 0.0]));
    let floor = Plane::new(c(0.0, -0.8, 0.0), c(0.0, 1.0, 0.0)).unwrap();
    scene.add(floor, Lambertian::textured(checks).unwrap());

    let image = ImageTexture::new(colour_bitmap()).with_uv_map(uv([2.0, 1.0], [0.1, 0.0]));
    let ball = Sphere::new(c(-1.0, -0.1, -3.2), lit(0.7)).unwrap();
    scene.add(ball, Lambertian::textured(image).unwrap());

    let grey = Lambertian::new(c(0.7, 0.7, 0.7)).unwrap();
    let bumps = ImageTexture::new(bumps_bitmap()).with_uv_map(uv([6.0, 3.0], [0.0, 0.0]));
    let bumpy = Sphere::new(c(0.9, -0.1, -3.4), lit(0.7)).unwrap();
    scene.add(bumpy, NormalMap::new(bumps, MaterialKind::from(grey)));

    let clamped = ImageTexture::new(colour_bitmap()).with_wrap(Wrap::Clamp);
    scene.add(
        quad::<F>([0.0, 0.1, -4.2]),
        Lambertian::textured(clamped).unwrap(),
    );
    scene.add_light(PointLight::new(c(-2.0, 3.0, -1.0), c(6.0, 6.0, 6.0)).unwrap());
    scene
}
