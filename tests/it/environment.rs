//! The environment as a light: the map's sampler against its own density (χ²), the
//! conventions it reads the image in, a white furnace under a constant environment, and
//! the byte-identity of a background that is not a light.
//!
//! # χ²
//! Directions are drawn from the map (`2¹⁸` of them, a fixed seed), binned on a 32 × 16
//! grid of the map's coordinates `(u, v)`, and compared with the counts the density
//! `Background::pdf` claims: each bin's probability is `∫ pdf dω` over it, integrated in
//! `(u, v)` with `dω = 2π² sin θ du dv` (a 4 × 4 midpoint rule per bin, exact here: the
//! density times `sin θ` is constant on each sampling cell, and the bins are unions of
//! cells). Bins expected to hold fewer than 5 are pooled. The test rejects at `p < 10⁻⁶`
//! ([`CHI2_ALPHA`]). It runs on a smooth map, a map with one bright texel (a sun), and a
//! nearly black one, each also rotated; and it must reject a sampler that leaves the
//! `sin θ` out of its weights while the density keeps it.

use crate::common::{CHI2_ALPHA, chi2_sf};
use rand::SeedableRng;
use raytrace::background::{EnvironmentMap, NO_ROTATION, luminance};
use raytrace::prelude::*;
use raytrace::sampling::{Distribution2D, uniform};
use raytrace::{DefaultRng, Image};
use std::f64::consts::PI;
use std::sync::Arc;

const SAMPLES: usize = 1 << 18;
const BU: usize = 32;
const BV: usize = 16;

/// A 64 × 32 map: a smooth sky, one bright texel, or a faint one.
fn map(kind: &str) -> EnvironmentMap {
    let (w, h) = (64, 32);
    let texels = (0..w * h)
        .map(|k| {
            let (x, y) = ((k % w) as f32, (k / w) as f32);
            match kind {
                "smooth" => [0.2 + x / 64.0, 1.0 - y / 40.0, 0.5 + 0.4 * (x / 10.0).sin()],
                "sun" if (x, y) == (40.0, 9.0) => [5e4, 4e4, 3e4],
                "sun" => [0.05, 0.07, 0.1],
                _ => [1e-9 * (1.0 + x), 1e-9, 2e-9],
            }
        })
        .collect();
    EnvironmentMap::new(w, h, texels, 1.0).unwrap()
}

/// A rotation of 30° about a skew axis (Rodrigues), as rows.
fn turned() -> [[f64; 3]; 3] {
    let a = [1.0 / 3f64.sqrt(); 3];
    let (s, c) = (PI / 6.0).sin_cos();
    let k = [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let kk: f64 = (0..3).map(|m| k[i][m] * k[m][j]).sum();
            f64::from(u8::from(i == j)) + s * k[i][j] + (1.0 - c) * kk
        })
    })
}

/// The map's coordinates of the world direction `d` under `rotation`.
fn uv_of(rotation: &[[f64; 3]; 3], d: Vec3<f64>) -> [f64; 2] {
    let d = d.to_f64();
    let local = [0, 1, 2].map(|k| rotation[0][k] * d[0] + rotation[1][k] * d[1] + rotation[2][k] * d[2]);
    EnvironmentMap::coordinates(local)
}

/// The p-value of the counts of `draw`'s directions against `background`'s density.
fn p_value(
    background: &Background<f64>,
    rotation: &[[f64; 3]; 3],
    mut draw: impl FnMut([f64; 2]) -> Option<Vec3<f64>>,
) -> f64 {
    let mut rng = DefaultRng::seed_from_u64(7);
    let mut counts = vec![0u64; BU * BV];
    for _ in 0..SAMPLES {
        let Some(d) = draw([uniform(&mut rng), uniform(&mut rng)]) else {
            continue;
        };
        let [u, v] = uv_of(rotation, d);
        counts[((v * BV as f64) as usize).min(BV - 1) * BU + ((u * BU as f64) as usize).min(BU - 1)] += 1;
    }
    // Each bin's probability, ∫ pdf dω with dω = 2π² sin θ du dv.
    let mut expected = vec![0.0; BU * BV];
    for (b, e) in expected.iter_mut().enumerate() {
        let (bu, bv) = (b % BU, b / BU);
        for (i, j) in (0..16).map(|k| (k % 4, k / 4)) {
            let (u, v) = (
                (bu as f64 + (i as f64 + 0.5) / 4.0) / BU as f64,
                (bv as f64 + (j as f64 + 0.5) / 4.0) / BV as f64,
            );
            let (local, sin_t) = EnvironmentMap::direction([u, v]);
            let w = [0, 1, 2].map(|r| (0..3).map(|k| rotation[r][k] * local[k]).sum::<f64>());
            let pdf = background.pdf(Vec3::new(w[0], w[1], w[2]));
            *e += pdf * 2.0 * PI * PI * sin_t / (16.0 * (BU * BV) as f64);
        }
    }
    let total: u64 = counts.iter().sum();
    let (mut chi2, mut dof, mut pooled) = (0.0, 0u32, (0u64, 0.0));
    for (&o, &p) in counts.iter().zip(&expected) {
        let e = p * total as f64;
        if e < 5.0 {
            pooled = (pooled.0 + o, pooled.1 + e);
        } else {
            chi2 += (o as f64 - e).powi(2) / e;
            dof += 1;
        }
    }
    if pooled.1 > 0.0 {
        chi2 += (pooled.0 as f64 - pooled.1).powi(2) / pooled.1.max(1e-300);
        dof += 1;
    }
    chi2_sf(chi2, dof - 1)
}

#[test]
fn the_map_samples_by_its_density() {
    for kind in ["smooth", "sun", "faint"] {
        for rotation in [NO_ROTATION, turned()] {
            let background = Background::<f64>::map(Arc::new(map(kind)), rotation).unwrap();
            let p = p_value(&background, &rotation, |u| background.sample(u).map(|(d, _)| d));
            println!("{kind}: p = {p:.3e}");
            assert!(
                p > CHI2_ALPHA,
                "{kind}, rotated {}: p = {p:e}",
                rotation != NO_ROTATION
            );
            // The density a sample carries is the one `pdf` gives for its direction.
            let mut rng = DefaultRng::seed_from_u64(3);
            for _ in 0..1000 {
                if let Some((d, pdf)) = background.sample([uniform(&mut rng), uniform(&mut rng)]) {
                    assert!(
                        (pdf / background.pdf(d) - 1.0).abs() < 1e-9,
                        "{kind}: {pdf} at {d:?}"
                    );
                }
            }
        }
    }
}

/// The power of the test: a sampler weighting the cells by luminance alone (no `sin θ`),
/// judged against the true density, is rejected.
#[test]
fn a_sampler_without_sin_theta_is_rejected() {
    let m = map("smooth");
    let (w, h) = m.size();
    let weights: Vec<f64> = (0..w * h)
        .map(|k| {
            luminance(m.radiance_at([
                ((k % w) as f64 + 0.5) / w as f64,
                ((k / w) as f64 + 0.5) / h as f64,
            ]))
        })
        .collect();
    let wrong = Distribution2D::new(&weights, w).unwrap();
    let background = Background::<f64>::map(Arc::new(m), NO_ROTATION).unwrap();
    let p = p_value(&background, &NO_ROTATION, |u| {
        let (d, _) = EnvironmentMap::direction(wrong.sample(u).0);
        Some(Vec3::new(d[0], d[1], d[2]))
    });
    println!("without sin θ: p = {p:.3e}");
    assert!(p < CHI2_ALPHA, "p = {p:e}");
}

/// Mitsuba 3's conventions: `+y` is the top row, `u = 0` looks down `−z`, columns are
/// texel-centred and periodic, rows corner-aligned; the lookup is bilinear.
#[test]
fn the_map_reads_its_image_in_mitsubas_conventions() {
    let (w, h) = (8, 4);
    let texels: Vec<[f32; 3]> = (0..w * h)
        .map(|k| [(k % w) as f32, (k / w) as f32, 1.0])
        .collect();
    let m = EnvironmentMap::new(w, h, texels, 2.0).unwrap();
    let at = |d: [f64; 3]| m.radiance_at(EnvironmentMap::coordinates(d));
    // Straight up: row 0; straight down: the last row; scaled by 2.
    assert_eq!(at([0.0, 1.0, 0.0])[1], 0.0);
    assert_eq!(at([0.0, -1.0, 0.0])[1], 2.0 * 3.0);
    // Down −z (u = 0) sits between the last column and the first: their mean.
    assert_eq!(at([0.0, 0.0, -1.0])[0], 2.0 * 3.5);
    // The centre of column 2 is at u = 2.5/8: φ = 2π·2.5/8 from −z toward +x.
    let phi = 2.0 * PI * 2.5 / 8.0;
    let c = at([phi.sin(), 0.0, -phi.cos()]);
    assert!((c[0] - 4.0).abs() < 1e-12, "{c:?}");
    // Row 1 is at θ = π/3, corner-aligned.
    let d = [0.0, (PI / 3.0).cos(), -(PI / 3.0).sin()];
    assert!((at(d)[1] - 2.0).abs() < 1e-12);
    // Refused: not 2:1, a negative texel, a negative scale.
    assert!(EnvironmentMap::new(4, 4, vec![[1.0; 3]; 16], 1.0).is_err());
    assert!(EnvironmentMap::new(2, 1, vec![[1.0, -1.0, 0.0]; 2], 1.0).is_err());
    assert!(EnvironmentMap::new(2, 1, vec![[1.0; 3]; 2], -1.0).is_err());
}

/// A white furnace: under a constant environment of radiance 1 that is a light, a convex
/// matte sphere of albedo `a` reflects exactly `a` (every scattered ray escapes), and the
/// render's mean over the sphere must say so within 5 standard errors (two-sided
/// `p ≈ 5.7·10⁻⁷`); the background pixels are exactly 1.
#[test]
fn a_white_furnace_under_a_constant_environment() {
    for albedo in [1.0, 0.5] {
        let mut scene = EnumScene::<f64>::new(Background::solid(Vec3::splat(1.0)).unwrap());
        scene.set_background_sampled(true);
        scene.add(
            Sphere::new(Vec3::new(0.0, 0.0, -3.0), 1.2).unwrap(),
            Lambertian::new(Vec3::splat(albedo)).unwrap(),
        );
        let camera = ScreenCamera::new(32, 16).unwrap();
        let render = Renderer::new(&scene, &camera)
            .spp(64)
            .max_depth(5)
            .seed(9)
            .render()
            .unwrap();
        let (mut sum, mut sum2, mut n) = (0.0, 0.0, 0.0);
        for (i, p) in render.image.pixels().iter().enumerate() {
            let (x, y) = ((i % 32) as f64, (i / 32) as f64);
            // A pixel whose cell the sphere covers wholly, or misses wholly.
            let corners = [(-0.5, -0.5), (0.5, 0.5), (-0.5, 0.5), (0.5, -0.5)];
            let hits = corners
                .iter()
                .filter(|(dx, dy)| scene.hit(&camera.ray(x + dx, y + dy), f64::INFINITY).is_some())
                .count();
            if hits == 4 {
                sum += p[0];
                sum2 += p[0] * p[0];
                n += 1.0;
            } else if hits == 0 {
                assert_eq!(*p, [1.0; 3], "pixel {i} sees only the environment");
            }
        }
        let mean = sum / n;
        let se = ((sum2 / n - mean * mean).max(1e-30) / n).sqrt();
        println!("albedo {albedo}: mean {mean:.5} ± {se:.2e}");
        assert!(
            (mean - albedo).abs() <= 5.0 * se.max(1e-12) + 1e-12,
            "albedo {albedo}: {mean} ± {se}"
        );
    }
}

/// The default background is no light: a scene that does not ask renders as it always
/// has, and one that asks draws the background (more rays) yet agrees within noise.
#[test]
fn a_background_becomes_a_light_only_when_asked() {
    let mut scene = EnumScene::<f64>::new(Background::default());
    scene.add(
        Sphere::new(Vec3::new(0.0, -100.5, -1.0), 100.0).unwrap(),
        Lambertian::new(Vec3::splat(0.5)).unwrap(),
    );
    let camera = ScreenCamera::new(16, 8).unwrap();
    let plain = Renderer::new(&scene, &camera)
        .spp(4)
        .max_depth(6)
        .seed(1)
        .render()
        .unwrap();
    let reference = raytrace::render_reference::<DefaultRng, _, _, _, _>(
        &scene,
        &camera,
        &RenderSettings::new(4, 6, 1).unwrap(),
        raytrace::Rect::full(16, 8),
    )
    .unwrap();
    assert_eq!(plain.image, reference.image);
    let mut lit = scene.clone();
    lit.set_background_sampled(true);
    let sampled = Renderer::new(&lit, &camera)
        .spp(4)
        .max_depth(6)
        .seed(1)
        .render()
        .unwrap();
    assert!(sampled.stats.rays > plain.stats.rays, "the background is sampled");
    let _: &Image = &sampled.image;
}

/// A map read from a file: the same texels as a Radiance HDR file (values its shared
/// exponent holds exactly) and as an OpenEXR file give the same map, scaled; a file that
/// is missing, not an image or not 2:1 is an error naming it at the map's field.
#[test]
fn a_map_reads_from_radiance_hdr_and_openexr_alike() {
    use raytrace::error::{Error, Field};
    let scratch = crate::common::Scratch::new("envmap");
    let dir = scratch.0.clone();
    let texels = [
        [0.5f32, 1.0, 0.25],
        [2.0, 4.0, 1.0],
        [0.0, 0.0, 0.0],
        [8.0, 0.5, 2.0],
    ];
    let hdr = scratch.hdr("map.hdr", 2, 1, &texels[..2]);
    let exr = dir.join("map.exr");
    let pixels = texels[..2].iter().map(|t| t.map(f64::from)).collect();
    raytrace::image::write_exr(&exr, &Image::from_pixels(2, 1, pixels).unwrap()).unwrap();
    let want = EnvironmentMap::new(2, 1, texels[..2].to_vec(), 3.0).unwrap();
    for file in [&hdr, &exr] {
        let got = EnvironmentMap::load(file, 3.0).unwrap();
        for uv in [[0.25, 0.5], [0.75, 0.5], [0.1, 0.9], [0.6, 0.2]] {
            assert_eq!(got.radiance_at(uv), want.radiance_at(uv), "{}", file.display());
        }
    }
    let square = dir.join("square.exr");
    let pixels = texels.iter().map(|t| t.map(f64::from)).collect();
    raytrace::image::write_exr(&square, &Image::from_pixels(2, 2, pixels).unwrap()).unwrap();
    let not_an_image = dir.join("notes.hdr");
    std::fs::write(&not_an_image, "not an image").unwrap();
    for bad in [dir.join("missing.exr"), not_an_image, square] {
        match EnvironmentMap::load(&bad, 1.0) {
            Err(Error::InvalidValue {
                field: Field::EnvironmentMap,
                reason,
            }) => assert!(reason.contains(&bad.display().to_string()), "{reason}"),
            other => panic!("{}: {other:?}", bad.display()),
        }
    }
}
