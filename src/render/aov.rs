//! The feature layers a denoiser takes with the colour: albedo and shading normal (the
//! auxiliary images of Intel Open Image Denoise), and the depth of the first hit.

use super::reference::{camera_ray, pixel_stream, sample_rng};
use super::{Rect, RenderSettings, parallel};
use crate::camera::Camera;
use crate::float::Float;
use crate::material::Scatter;
use crate::ray::Ray;
use crate::scene::{Layout, Scene};
use crate::vec3::{Color, Vec3};
use rand::{Rng, SeedableRng};

/// Per-pixel features of a render, row by row from the top-left of the rendered region.
///
/// Each pixel's albedo and normal are the means over the same samples (the same camera
/// rays, jittered alike) as its colour, so they are filtered as the colour is, as Open
/// Image Denoise asks. A sample follows the delta lobes it meets (a mirror, smooth glass)
/// with the directions its own random stream draws, the colour path's own, to the
/// **first hit with a non-delta lobe**, and records there:
///
/// - **albedo**: the weight `f·|cos θ|/pdf` of one direction the material's
///   [`sample`](Scatter::sample) draws, which is the directional albedo in expectation and
///   exactly the albedo `A` of the specification's materials, times the weights of the
///   delta bounces on the way (a tinted mirror tints what it shows); each channel clamped
///   to `[0, 1]`. A sample that leaves the scene takes the background's colour in its
///   direction (clamped so), and one absorbed on the way takes black. No material is
///   asked what kind it is: only [`lobes`](crate::Material::lobes) and `sample`.
/// - **normal**: the world-space shading normal there, turned toward the ray (not
///   normalised after averaging, in `[−1, 1]`); zero for a sample that leaves the scene.
///
/// **depth** is the distance along the camera ray to the first surface it hits, the
/// nearest over the pixel's samples (a mean would invent a surface between an edge and
/// what lies behind it); `+∞` if no sample hits anything.
#[derive(Clone, Debug, PartialEq)]
pub struct Aovs {
    width: usize,
    height: usize,
    albedo: Vec<[f64; 3]>,
    normal: Vec<[f64; 3]>,
    depth: Vec<f64>,
}

impl Aovs {
    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Each pixel's albedo, linear RGB in `[0, 1]`.
    pub fn albedo(&self) -> &[[f64; 3]] {
        &self.albedo
    }

    /// Each pixel's mean world-space shading normal, `x y z` in `[−1, 1]`.
    pub fn normal(&self) -> &[[f64; 3]] {
        &self.normal
    }

    /// Each pixel's first-hit distance, `+∞` where nothing is hit.
    pub fn depth(&self) -> &[f64] {
        &self.depth
    }
}

/// What one sample records.
struct Feature {
    albedo: [f64; 3],
    normal: [f64; 3],
    depth: f64,
    rays: u64,
}

/// The features of `tile`, each pixel averaged over its samples `0..samples(i)` (`i` its
/// index in the tile), their camera rays jittered if `jitter`. Also returns the rays
/// traced.
pub(super) fn render_aov<R, F, S, M, C>(
    scene: &Scene<F, S, M>,
    camera: &C,
    settings: &RenderSettings,
    tile: Rect,
    (samples, jitter): (&(dyn Fn(usize) -> u32 + Sync), bool),
) -> (Aovs, u64)
where
    R: Rng + SeedableRng,
    F: Float,
    S: Layout<F> + Sync,
    M: Scatter<F, R> + Sync,
    C: Camera<F> + Sync,
{
    let count = tile.width * tile.height;
    let pixel = |i: usize| {
        let (x, y) = (tile.x + i % tile.width, tile.y + i / tile.width);
        let stream = pixel_stream(settings, camera, x, y);
        let n = samples(i);
        let (mut albedo, mut normal, mut depth, mut rays) = ([0.0; 3], [0.0; 3], f64::INFINITY, 0);
        for sample in 0..n {
            let mut rng: R = sample_rng(stream, sample);
            let ray = camera_ray(camera, x, y, jitter, &mut rng);
            let f = feature(scene, ray, settings.max_depth, &mut rng);
            for k in 0..3 {
                albedo[k] += f.albedo[k];
                normal[k] += f.normal[k];
            }
            depth = depth.min(f.depth);
            rays += f.rays;
        }
        let n = f64::from(n.max(1));
        (albedo.map(|a| a / n), normal.map(|v| v / n), depth, rays)
    };
    let per_pixel = parallel::each(count, &pixel);
    let rays = per_pixel.iter().map(|p| p.3).sum();
    let aovs = Aovs {
        width: tile.width,
        height: tile.height,
        albedo: per_pixel.iter().map(|p| p.0).collect(),
        normal: per_pixel.iter().map(|p| p.1).collect(),
        depth: per_pixel.iter().map(|p| p.2).collect(),
    };
    (aovs, rays)
}

/// One sample's features: the delta chain from `ray` to its first hit with a non-delta
/// lobe, at most `max_depth` bounces.
fn feature<R, F, S, M>(scene: &Scene<F, S, M>, mut ray: Ray<F>, max_depth: u32, rng: &mut R) -> Feature
where
    R: Rng,
    F: Float,
    S: Layout<F>,
    M: Scatter<F, R>,
{
    let clamped = |c: Color<F>| {
        c.to_f64()
            .map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) })
    };
    let mut throughput = Color::splat(F::one());
    let mut depth = f64::INFINITY;
    for bounce in 0..=max_depth {
        let rays = u64::from(bounce) + 1;
        let Some((hit, _, material)) = scene.hit_object(&ray, F::infinity()) else {
            return Feature {
                albedo: clamped(throughput * scene.background().color(ray.direction)),
                normal: [0.0; 3],
                depth,
                rays,
            };
        };
        if bounce == 0 {
            depth = hit.t.to_f64();
        }
        let wo = -ray.direction;
        // The direction the material draws, if light can come back along it.
        let drawn = material
            .sample(&hit, wo, rng)
            .filter(|s| hit.sides_agree(s.direction));
        let here = |weight: Color<F>| Feature {
            albedo: clamped(throughput * weight),
            normal: hit.shading_normal.to_f64(),
            depth,
            rays,
        };
        match drawn {
            // The first non-delta hit (or the last the depth allows): its albedo.
            Some(s) if material.lobes().has_non_delta() || bounce == max_depth => return here(s.weight),
            Some(s) => {
                throughput = throughput * s.weight;
                ray = hit.spawn(s.direction);
            }
            None => return here(Vec3::zero()),
        }
    }
    unreachable!("the loop returns at bounce max_depth")
}
