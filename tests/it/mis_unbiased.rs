//! Next-event estimation with MIS is unbiased: it renders the image that scattered rays
//! alone render, within noise, on the Cornell box and on a scene with every kind of light
//! (`area_lights`: a sphere lamp, a two-sided reflecting panel, an emitting plane, a point
//! light, a mirror and a glass sphere).
//!
//! # Method
//! Each scene is rendered small (24 pixels wide) with 1024 jittered samples per pixel by
//! each technique, from independent seeds, calling the spec's recursive `Tracer::trace`
//! once per sample, and the samples of each block of pixels (8 × 8 on the Cornell box,
//! 6 × 6 on the other) are pooled: their mean `m` and variance `s²` per channel. For each
//! block and channel, `z = (m₁ − m₂)/√(s₁²/n + s₂²/n)` (`n` samples per block and
//! technique). Pooling a block's pixels treats its samples as draws from the mixture of its
//! pixels, whose variance is at least that of the stratified mean, so `z` is conservative.
//!
//! # Significance
//! The techniques agree if every `|z| ≤ 5`: two-sided `p ≈ 5.7·10⁻⁷` per block and channel,
//! at most `5·10⁻⁵` over the 2 × 27 + 24 values compared (the Cornell box at the scene's
//! max depth 8 and at 3, the other scene at 6). The same test must see a light 20 % too
//! bright, and a render one bounce short (max depth 2 against 3: the off-by-one the depth
//! rule for sampled light guards against): some `|z| > 5` for each. (A smaller error can
//! hide in the noise of scattered rays alone, which find the Cornell box's light on few
//! paths: a light 10 % too bright reached `|z| = 3.3` at 512 samples per pixel.) Run with
//! `--nocapture` to see the largest `|z|` of each comparison.

use crate::scenes;

use rand::SeedableRng;
use raytrace::prelude::*;
use raytrace::render::{Tracer, sample_seed};
use raytrace::sampling::pixel_jitter;
use raytrace::{DefaultRng, Emissive};

const SPP: u64 = 1024;

/// Per block and channel: the sum and the sum of squares of the samples, and their count.
struct Blocks {
    sum: Vec<[f64; 3]>,
    sum2: Vec<[f64; 3]>,
    n: Vec<u64>,
}

/// Renders `scene` through `camera`, `SPP` samples per pixel drawn from `seed`, and pools
/// the samples by `block × block` pixels.
fn blocks<S, M, C>(
    scene: &Scene<f64, S, M>,
    camera: &C,
    max_depth: u32,
    sampling: LightSampling,
    seed: u64,
    block: usize,
) -> Blocks
where
    S: Layout<f64>,
    M: Scatter<f64, DefaultRng>,
    C: Camera<f64>,
{
    let (w, h) = (camera.width(), camera.height());
    let (bw, bh) = (w.div_ceil(block), h.div_ceil(block));
    let mut out = Blocks {
        sum: vec![[0.0; 3]; bw * bh],
        sum2: vec![[0.0; 3]; bw * bh],
        n: vec![0; bw * bh],
    };
    let mut tracer = Tracer::new(scene, max_depth).light_sampling(sampling);
    for y in 0..h {
        for x in 0..w {
            let b = (y / block) * bw + x / block;
            for sample in 0..SPP {
                let mut rng = DefaultRng::seed_from_u64(sample_seed(seed, (y * w + x) as u64, sample));
                let (dx, dy) = pixel_jitter(&mut rng);
                let ray = camera.ray(x as f64 + dx, y as f64 + dy);
                let c = tracer.trace(&ray, 0, &mut rng).to_f64();
                for (k, c) in c.into_iter().enumerate() {
                    out.sum[b][k] += c;
                    out.sum2[b][k] += c * c;
                }
                out.n[b] += 1;
            }
        }
    }
    out
}

/// The z-scores of the difference of the block means of `a` and `b`, every block and channel.
fn z_scores(a: &Blocks, b: &Blocks) -> Vec<f64> {
    let stats = |s: &Blocks, i: usize, k: usize| {
        let n = s.n[i] as f64;
        let mean = s.sum[i][k] / n;
        let var = (s.sum2[i][k] / n - mean * mean).max(0.0) * n / (n - 1.0);
        (mean, var / n)
    };
    let mut z = Vec::new();
    for i in 0..a.n.len() {
        for k in 0..3 {
            let ((ma, va), (mb, vb)) = (stats(a, i, k), stats(b, i, k));
            z.push(if va + vb > 0.0 {
                (ma - mb) / (va + vb).sqrt()
            } else {
                0.0
            });
        }
    }
    z
}

fn largest(z: &[f64]) -> f64 {
    z.iter().fold(0.0f64, |m, z| m.max(z.abs()))
}

/// `scene` with its emissive materials' radiance scaled by `factor`.
fn brighter(scene: &EnumScene<f64>, factor: f64) -> EnumScene<f64> {
    let mut out = EnumScene::new(scene.background().clone());
    out.set_acceleration(scene.acceleration());
    for o in scene.objects() {
        let material = match scene.material(o.material) {
            MaterialKind::Emissive(e) => {
                let emission = e.emission();
                let light = Emissive::new(emission.radiance() * factor).unwrap();
                light
                    .two_sided(emission.is_two_sided())
                    .with_albedo(e.albedo())
                    .unwrap()
                    .into()
            }
            m => m.clone(),
        };
        out.add(o.shape.clone(), material);
    }
    out
}

#[test]
fn mis_and_scattered_rays_agree_on_the_cornell_box() {
    let (scene, camera, settings) = scenes::cornell_box::<f64>(24).unwrap();
    let depth = settings.max_depth;
    let mis = blocks(&scene, &camera, depth, LightSampling::Mis, 1, 8);
    let bsdf = blocks(&scene, &camera, depth, LightSampling::Bsdf, 2, 8);
    let z = z_scores(&mis, &bsdf);
    println!(
        "Cornell box, MIS against scattered rays: largest |z| = {:.2} of {}",
        largest(&z),
        z.len()
    );
    assert!(largest(&z) <= 5.0, "{z:?}");
    let too_bright = blocks(&brighter(&scene, 1.2), &camera, depth, LightSampling::Bsdf, 3, 8);
    let z = z_scores(&mis, &too_bright);
    println!(
        "Cornell box, against a light 20 % too bright: largest |z| = {:.2}",
        largest(&z)
    );
    assert!(largest(&z) > 5.0, "{z:?}");
}

#[test]
fn mis_and_scattered_rays_agree_at_a_small_depth_and_see_one_bounce_fewer() {
    let (scene, camera, _) = scenes::cornell_box::<f64>(24).unwrap();
    let mis = blocks(&scene, &camera, 3, LightSampling::Mis, 7, 8);
    let bsdf = blocks(&scene, &camera, 3, LightSampling::Bsdf, 8, 8);
    let z = z_scores(&mis, &bsdf);
    println!(
        "Cornell box at depth 3, MIS against scattered rays: largest |z| = {:.2}",
        largest(&z)
    );
    assert!(largest(&z) <= 5.0, "{z:?}");
    let short = blocks(&scene, &camera, 2, LightSampling::Bsdf, 9, 8);
    let z = z_scores(&mis, &short);
    println!(
        "Cornell box at depth 3, against depth 2: largest |z| = {:.2}",
        largest(&z)
    );
    assert!(largest(&z) > 5.0, "{z:?}");
}

#[test]
fn mis_and_scattered_rays_agree_on_every_kind_of_light() {
    let scene = scenes::area_lights::<f64>().unwrap();
    let camera = ScreenCamera::new(24, 12).unwrap();
    let mis = blocks(&scene, &camera, 6, LightSampling::Mis, 5, 6);
    let bsdf = blocks(&scene, &camera, 6, LightSampling::Bsdf, 6, 6);
    let z = z_scores(&mis, &bsdf);
    println!(
        "area lights, MIS against scattered rays: largest |z| = {:.2} of {}",
        largest(&z),
        z.len()
    );
    assert!(largest(&z) <= 5.0, "{z:?}");
}

/// The background as a light among the others: `area_lights` under an environment map
/// with a sun (a bright texel), made a light, renders the same with MIS as with scattered
/// rays alone; and a sun 20 % brighter is seen.
#[test]
fn mis_and_scattered_rays_agree_with_an_environment_light() {
    use raytrace::background::{EnvironmentMap, NO_ROTATION};
    let sky = |sun: f32| {
        let (w, h) = (32, 16);
        let texels = (0..w * h)
            .map(|k| {
                if k == 5 * w + 20 {
                    [sun, 0.8 * sun, 0.6 * sun]
                } else {
                    [0.2, 0.3, 0.5]
                }
            })
            .collect();
        let map = EnvironmentMap::new(w, h, texels, 1.0).unwrap();
        Background::map(std::sync::Arc::new(map), NO_ROTATION).unwrap()
    };
    let with_sky = |sun: f32| {
        let base = scenes::area_lights::<f64>().unwrap();
        let mut scene = EnumScene::new(sky(sun));
        scene.set_background_sampled(true);
        for o in base.objects() {
            scene.add(o.shape.clone(), base.material(o.material).clone());
        }
        for &l in base.lights() {
            scene.add_light(l);
        }
        scene
    };
    let scene = with_sky(200.0);
    let camera = ScreenCamera::new(24, 12).unwrap();
    let mis = blocks(&scene, &camera, 6, LightSampling::Mis, 11, 6);
    let bsdf = blocks(&scene, &camera, 6, LightSampling::Bsdf, 12, 6);
    let z = z_scores(&mis, &bsdf);
    println!(
        "environment and every other light, MIS against scattered rays: largest |z| = {:.2} of {}",
        largest(&z),
        z.len()
    );
    assert!(largest(&z) <= 5.0, "{z:?}");
    let brighter = blocks(&with_sky(240.0), &camera, 6, LightSampling::Mis, 13, 6);
    let z = z_scores(&mis, &brighter);
    println!("against a sun 20 % brighter: largest |z| = {:.2}", largest(&z));
    assert!(largest(&z) > 5.0, "{z:?}");
}
