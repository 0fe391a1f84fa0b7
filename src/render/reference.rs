//! The reference renderer: every pixel, every sample, one recursion at a time. It is slow
//! and short on purpose. It defines every image this crate makes: the fast renderer
//! ([`Renderer::render`](super::Renderer::render)) is tested to give its bytes.

#[cfg(doc)]
use super::sample_seed;
use super::trace::{Tracer, saturate};
use super::{Rect, Render, RenderSettings, RenderStats, seed};
use crate::camera::Camera;
use crate::error::Result;
use crate::float::{Float, lit};
use crate::image::Image;
use crate::material::Scatter;
use crate::ray::Ray;
use crate::sampling::{pixel_jitter, uniform};
use crate::scene::Layout;
use crate::scene::Scene;
use crate::vec3::Color;
use rand::{Rng, SeedableRng};
use std::time::Instant;

/// Renders the pixels of `tile` one after another on the calling thread, each the mean of
/// its samples, each sample one call of the recursive [`Tracer::trace`].
///
/// # Errors
/// Invalid settings, or a tile outside the camera's image.
pub fn render_reference<R, F, S, M, C>(
    scene: &Scene<F, S, M>,
    camera: &C,
    settings: &RenderSettings,
    tile: Rect,
) -> Result<Render>
where
    R: Rng + SeedableRng,
    F: Float,
    S: Layout<F>,
    M: Scatter<F, R>,
    C: Camera<F>,
{
    settings.validate()?;
    tile.check_inside(camera.width(), camera.height())?;
    let start = Instant::now();
    let mut image = Image::new(tile.width, tile.height)?;
    let mut tracer = Tracer::new(scene, settings.max_depth).light_sampling(settings.light_sampling);
    for (i, out) in image.pixels_mut().iter_mut().enumerate() {
        let (x, y) = (tile.x + i % tile.width, tile.y + i / tile.width);
        let stream = pixel_stream(settings, camera, x, y);
        let mut sum = Color::zero();
        for sample in 0..settings.samples_per_pixel {
            let mut rng: R = sample_rng(stream, sample);
            let ray = camera_ray(camera, x, y, settings.samples_per_pixel > 1, &mut rng);
            sum = sum + tracer.trace(&ray, 0, &mut rng);
        }
        *out = mean(sum, settings.samples_per_pixel).to_f64();
    }
    Ok(Render {
        image,
        stats: RenderStats {
            rays: tracer.rays(),
            elapsed: start.elapsed(),
            threads: 1,
        },
        convergence: None,
        aov: None,
    })
}

/// The random stream of pixel `(x, y)`, from the render seed and the pixel's index in the
/// **whole** image: never from a thread or a tile, so any split of the work gives the same
/// image. Each of its samples seeds a generator of its own ([`sample_rng`]).
#[inline]
pub(super) fn pixel_stream<F: Float>(
    settings: &RenderSettings,
    camera: &impl Camera<F>,
    x: usize,
    y: usize,
) -> u64 {
    seed::pixel_stream(settings.seed, (y * camera.width() + x) as u64)
}

/// The generator of sample `sample` of the pixel with `stream`: together with
/// [`pixel_stream`], seeded from [`sample_seed`]`(seed, pixel, sample)`.
#[inline]
pub(super) fn sample_rng<R: SeedableRng>(stream: u64, sample: u32) -> R {
    R::seed_from_u64(seed::seed_in_stream(stream, u64::from(sample)))
}

/// A sample's camera ray: through a uniform random point of the pixel's cell if
/// `jitter` (more than one sample per pixel), else through the pixel centre (the spec's
/// basic mode, one sample per pixel); from a uniform point of the lens for a camera that
/// [has one](Camera::has_lens).
///
/// The sample's generator gives, in this order, the pixel jitter's two numbers (if
/// `jitter`), then the lens's two (with a lens), then the path's: a pinhole camera draws
/// exactly what it always has.
#[inline]
pub(super) fn camera_ray<F: Float, R: Rng + ?Sized>(
    camera: &impl Camera<F>,
    x: usize,
    y: usize,
    jitter: bool,
    rng: &mut R,
) -> Ray<F> {
    let (x, y) = (lit::<F>(x as f64), lit::<F>(y as f64));
    let (x, y) = if jitter {
        let (dx, dy) = pixel_jitter(rng);
        (x + lit(dx), y + lit(dy))
    } else {
        (x, y)
    };
    if camera.has_lens() {
        let lens = [uniform(rng), uniform(rng)];
        camera.ray_through_lens(x, y, lens)
    } else {
        camera.ray(x, y)
    }
}

/// A pixel's colour from the sum of its `spp` sample colours: their mean. Each sample is
/// finite, but the sum may overflow: the mean is capped again.
#[inline]
pub(super) fn mean<F: Float>(sum: Color<F>, spp: u32) -> Color<F> {
    saturate(sum / lit(f64::from(spp)))
}
