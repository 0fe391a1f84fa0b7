//! Rendering: the recursive [`trace`](Tracer::trace), the specification's formulation of a
//! path; the breadth-first form the drivers run, which advances the paths of two rows at a
//! time bounce by bounce and gives the recursion's image bit for bit (`wavefront`); and the
//! parallel, deterministic drivers [`render`] and [`render_tile`].

mod seed;
mod settings;
mod trace;
mod wavefront;

pub use seed::pixel_seed;
pub use settings::{Rect, RenderSettings};
pub use trace::Tracer;

use crate::camera::Camera;
use crate::error::Result;
use crate::float::Float;
use crate::image::Image;
use crate::material::Material;
use crate::scene::Scene;
use crate::shape::Hittable;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use std::fmt;
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// The default random generator: xoshiro256++, a fixed, documented algorithm, so a seed
/// gives the same image on every machine and every version of this crate.
pub type DefaultRng = rand::rngs::Xoshiro256PlusPlus;

/// A finished render: the linear image and what it cost.
#[derive(Clone, Debug)]
pub struct Render {
    /// The linear RGB image.
    pub image: Image,
    /// Rays traced and time taken.
    pub stats: RenderStats,
}

/// What a render cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderStats {
    /// Rays traced, of every kind: camera, scattered and shadow.
    pub rays: u64,
    /// Wall-clock time.
    pub elapsed: Duration,
    /// Worker threads used.
    pub threads: usize,
}

impl RenderStats {
    /// Million rays per second of wall time.
    pub fn mrays_per_second(&self) -> f64 {
        self.rays as f64 / self.elapsed.as_secs_f64().max(1e-9) / 1e6
    }
}

/// The one-line summary every render ends with.
impl fmt::Display for RenderStats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:.3} s, {} rays, {:.2} Mrays/s on {} thread{}",
            self.elapsed.as_secs_f64(),
            self.rays,
            self.mrays_per_second(),
            self.threads,
            if self.threads == 1 { "" } else { "s" }
        )
    }
}

/// Renders the whole image with the [`DefaultRng`]. See [`render_tile`].
pub fn render<F, S, M, C>(scene: &Scene<F, S, M>, camera: &C, settings: &RenderSettings) -> Result<Render>
where
    F: Float,
    S: Hittable<F> + Sync,
    M: Material<F, DefaultRng> + Sync,
    C: Camera<F> + Sync,
{
    render_with::<DefaultRng, F, S, M, C>(scene, camera, settings)
}

/// Renders the whole image with the random generator `R`. See [`render_tile`].
pub fn render_with<R, F, S, M, C>(
    scene: &Scene<F, S, M>,
    camera: &C,
    settings: &RenderSettings,
) -> Result<Render>
where
    R: Rng + SeedableRng,
    F: Float,
    S: Hittable<F> + Sync,
    M: Material<F, R> + Sync,
    C: Camera<F> + Sync,
{
    let full = Rect::full(camera.width(), camera.height());
    render_tile::<R, F, S, M, C>(scene, camera, settings, full)
}

/// Renders the pixels of `tile`, in parallel on the current rayon thread pool.
///
/// Each pixel draws from its own generator, seeded from the render seed and the pixel's
/// index in the **whole** image ([`pixel_seed`]), never from a thread: the result is
/// bit-identical for any number of threads, and a tile equals the same pixels of the
/// whole image, so tiles can be rendered anywhere and stitched.
///
/// With one sample per pixel the ray goes through the pixel centre (the specification's
/// basic mode); with more, each sample goes through a uniform random point of the pixel's
/// cell and the pixel is their mean.
///
/// # Errors
/// Invalid settings, or a tile outside the camera's image.
pub fn render_tile<R, F, S, M, C>(
    scene: &Scene<F, S, M>,
    camera: &C,
    settings: &RenderSettings,
    tile: Rect,
) -> Result<Render>
where
    R: Rng + SeedableRng,
    F: Float,
    S: Hittable<F> + Sync,
    M: Material<F, R> + Sync,
    C: Camera<F> + Sync,
{
    settings.validate()?;
    tile.check_inside(camera.width(), camera.height())?;
    let start = Instant::now();
    let mut image = Image::new(tile.width, tile.height)?;
    let progress = progress_bar(settings.progress, tile.height as u64);
    let band = BAND_ROWS * tile.width;
    let rays: u64 = image
        .pixels_mut()
        .par_chunks_mut(band)
        .enumerate()
        .map_init(wavefront::Row::new, |paths, (k, pixels)| {
            let mut tracer = Tracer::new(scene, settings.max_depth);
            let at = |i: usize| (tile.x + i % tile.width, tile.y + (k * band + i) / tile.width);
            let rng = |x: usize, y: usize| {
                R::seed_from_u64(pixel_seed(settings.seed, (y * camera.width() + x) as u64))
            };
            paths.render(&mut tracer, camera, at, settings.samples_per_pixel, rng, pixels);
            progress.inc(pixels.len().div_ceil(tile.width) as u64);
            tracer.rays()
        })
        .sum();
    progress.finish_and_clear();
    Ok(Render {
        image,
        stats: RenderStats {
            rays,
            elapsed: start.elapsed(),
            threads: rayon::current_num_threads(),
        },
    })
}

/// Rows rendered together as one batch of paths ([`wavefront`]). Bands of one or two rows
/// ran `four_mirrors` about 2 % faster than bands of four (the batch's rays stay in the
/// first-level cache), `random_spheres` the same.
const BAND_ROWS: usize = 2;

/// A progress bar on stderr (work done, rate, time left), hidden unless asked for and
/// stderr is a terminal.
fn progress_bar(wanted: bool, rows: u64) -> ProgressBar {
    if !wanted || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(rows), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} rows  {per_sec}  eta {eta}") {
        bar.set_style(style);
    }
    bar
}
