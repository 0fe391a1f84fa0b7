//! Rendering. The recursive [`Tracer::trace`] is the specification's formulation of a
//! path; [`render_reference`] calls it for every sample of every pixel and so defines every
//! image. [`Renderer::render`] gives the same bytes faster: the paths of a band of pixels
//! advance together, bounce by bounce (`batch`), on every core (rayon).
//!
//! A render may instead spend its samples where the error is ([`adaptive`]: to a target
//! error, or for a time budget) and report the error each pixel reached, and may add the
//! feature layers a denoiser takes ([`Aovs`]).

pub mod adaptive;
mod aov;
mod batch;
mod direct;
mod parallel;
mod progress;
mod reference;
mod seed;
mod settings;
mod shadow;
mod trace;
mod weights;

pub use crate::image::Rect;
pub use adaptive::{Adaptive, Convergence};
pub use aov::Aovs;
pub use reference::render_reference;
pub use seed::sample_seed;
pub use settings::{LightSampling, RenderSettings};
pub use trace::Tracer;

use crate::camera::Camera;
use crate::error::Result;
use crate::float::Float;
use crate::image::{ExrChannel, Image};
use crate::material::Scatter;
use crate::sampling::DefaultRng;
use crate::scene::Layout;
use crate::scene::Scene;
use batch::Batch;
use progress::Progress;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use std::fmt;
use std::marker::PhantomData;
use std::time::{Duration, Instant};

/// A finished render: the linear image and what it cost.
#[derive(Clone, Debug)]
#[must_use]
pub struct Render {
    /// The linear RGB image.
    pub image: Image,
    /// Rays traced and time taken.
    pub stats: RenderStats,
    /// Each pixel's sample count and estimated error, for an [adaptive](Renderer::adaptive)
    /// render; `None` for a uniform one.
    pub convergence: Option<Convergence>,
    /// The denoiser's feature layers, if [asked for](Renderer::aov).
    pub aov: Option<Aovs>,
}

impl Render {
    /// The render's layers beyond the colour, as EXR channels
    /// ([`write_layered_exr`](crate::image::write_layered_exr)): `samples.Y` (each pixel's
    /// sample count) and `error.Y` (its estimated relative error) for an adaptive render;
    /// `albedo.R/G/B`, `normal.X/Y/Z` and `depth.Z` if the features were rendered.
    #[must_use]
    pub fn layers(&self) -> Vec<ExrChannel> {
        let mut layers = Vec::new();
        if let Some(c) = &self.convergence {
            layers.push(ExrChannel::counts("samples.Y", c.samples().to_vec()));
            layers.push(ExrChannel::floats("error.Y", c.error().iter().copied()));
        }
        if let Some(aov) = &self.aov {
            for (k, name) in ["albedo.R", "albedo.G", "albedo.B"].into_iter().enumerate() {
                layers.push(ExrChannel::floats(name, aov.albedo().iter().map(|p| p[k])));
            }
            for (k, name) in ["normal.X", "normal.Y", "normal.Z"].into_iter().enumerate() {
                layers.push(ExrChannel::floats(name, aov.normal().iter().map(|p| p[k])));
            }
            layers.push(ExrChannel::floats("depth.Z", aov.depth().iter().copied()));
        }
        layers
    }
}

/// What a render cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderStats {
    /// Rays traced, of every kind: camera, scattered and shadow (and those of the feature
    /// layers, if asked for).
    pub rays: u64,
    /// Wall-clock time (the feature layers' included).
    pub elapsed: Duration,
    /// Worker threads used.
    pub threads: usize,
}

impl RenderStats {
    /// Million rays per second of wall time.
    #[must_use]
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

/// Renders the whole image with `settings` and the [`DefaultRng`]: shorthand for
/// `Renderer::new(scene, camera).settings(*settings).render()`.
///
/// # Errors
/// Invalid settings.
pub fn render<F, S, M, C>(scene: &Scene<F, S, M>, camera: &C, settings: &RenderSettings) -> Result<Render>
where
    F: Float,
    S: Layout<F> + Sync,
    M: Scatter<F, DefaultRng> + Sync,
    C: Camera<F> + Sync,
{
    Renderer::new(scene, camera).settings(*settings).render()
}

/// A render to run: the scene, the camera, the settings, the part of the image and the
/// random generator `R`.
///
/// ```
/// # use raytrace::prelude::*;
/// # let mut scene = EnumScene::<f32>::new(Background::default());
/// # scene.add(Sphere::new(Vec3::new(0.0, 0.0, -3.0), 1.0)?, Lambertian::new(Vec3::splat(0.5))?);
/// let camera = ScreenCamera::new(40, 20)?;
/// let top_half = Rect { x: 0, y: 0, width: 40, height: 10 };
/// let render = Renderer::new(&scene, &camera).spp(4).max_depth(10).seed(1).tile(top_half).render()?;
/// assert_eq!(render.image.height(), 10);
/// # Ok::<(), raytrace::Error>(())
/// ```
#[must_use]
pub struct Renderer<'a, F: Float, S, M, C, R = DefaultRng> {
    scene: &'a Scene<F, S, M>,
    camera: &'a C,
    settings: RenderSettings,
    tile: Option<Rect>,
    adaptive: Option<Adaptive>,
    aov: bool,
    rng: PhantomData<fn() -> R>,
}

impl<'a, F: Float, S, M, C: Camera<F>> Renderer<'a, F, S, M, C> {
    /// The whole image with the default settings ([`RenderSettings::default`]: one ray per
    /// pixel centre, depth 10, seed 0) and the [`DefaultRng`].
    pub fn new(scene: &'a Scene<F, S, M>, camera: &'a C) -> Self {
        Self {
            scene,
            camera,
            settings: RenderSettings::default(),
            tile: None,
            adaptive: None,
            aov: false,
            rng: PhantomData,
        }
    }
}

impl<'a, F: Float, S, M, C: Camera<F>, R> Renderer<'a, F, S, M, C, R> {
    /// Samples (rays) per pixel, at least 1.
    pub fn spp(mut self, samples_per_pixel: u32) -> Self {
        self.settings.samples_per_pixel = samples_per_pixel;
        self
    }

    /// The most bounces a path may take ([`RenderSettings::max_depth`]).
    pub fn max_depth(mut self, max_depth: u32) -> Self {
        self.settings.max_depth = max_depth;
        self
    }

    /// The seed every sample's random stream derives from.
    pub fn seed(mut self, seed: u64) -> Self {
        self.settings.seed = seed;
        self
    }

    /// How the light of emitting surfaces is found ([`RenderSettings::light_sampling`]).
    pub fn light_sampling(mut self, light_sampling: LightSampling) -> Self {
        self.settings.light_sampling = light_sampling;
        self
    }

    /// Shows a progress bar on stderr when it is a terminal.
    pub fn progress(mut self, progress: bool) -> Self {
        self.settings.progress = progress;
        self
    }

    /// All of the above at once.
    pub fn settings(mut self, settings: RenderSettings) -> Self {
        self.settings = settings;
        self
    }

    /// Renders only the pixels of `tile`, which equal the same pixels of the whole image.
    pub fn tile(mut self, tile: Rect) -> Self {
        self.tile = Some(tile);
        self
    }

    /// Samples adaptively, as `adaptive` says ([`adaptive`](mod@adaptive)), instead of
    /// [`spp`](Renderer::spp) samples in every pixel; `None` goes back to uniform sampling.
    pub fn adaptive(mut self, adaptive: Option<Adaptive>) -> Self {
        self.adaptive = adaptive;
        self
    }

    /// Samples each pixel until its estimated relative error (of its mean luminance, see
    /// [`adaptive`](mod@adaptive)) is at most `target_error`, with the other adaptive
    /// settings as they are (the defaults at first).
    pub fn target_error(mut self, target_error: f64) -> Self {
        self.adaptive_mut().target_error = Some(target_error);
        self
    }

    /// Samples adaptively for `budget` of wall time at most (with a target error, until
    /// every pixel meets it if that comes first). The image then depends on the time.
    pub fn time_budget(mut self, budget: Duration) -> Self {
        self.adaptive_mut().time_budget = Some(budget);
        self
    }

    /// The samples every pixel takes before its error is judged ([`Adaptive::min_spp`]).
    pub fn min_spp(mut self, min_spp: u32) -> Self {
        self.adaptive_mut().min_spp = min_spp;
        self
    }

    /// The most samples any pixel takes ([`Adaptive::max_spp`]).
    pub fn max_spp(mut self, max_spp: u32) -> Self {
        self.adaptive_mut().max_spp = max_spp;
        self
    }

    /// Also renders the feature layers a denoiser takes ([`Aovs`]).
    pub fn aov(mut self, aov: bool) -> Self {
        self.aov = aov;
        self
    }

    /// Draws from the generator `G` instead.
    pub fn rng<G: Rng + SeedableRng>(self) -> Renderer<'a, F, S, M, C, G> {
        Renderer {
            scene: self.scene,
            camera: self.camera,
            settings: self.settings,
            tile: self.tile,
            adaptive: self.adaptive,
            aov: self.aov,
            rng: PhantomData,
        }
    }

    fn adaptive_mut(&mut self) -> &mut Adaptive {
        self.adaptive.get_or_insert_with(Adaptive::empty)
    }

    fn region(&self) -> Rect {
        self.tile
            .unwrap_or_else(|| Rect::full(self.camera.width(), self.camera.height()))
    }
}

impl<F, S, M, C, R> Renderer<'_, F, S, M, C, R>
where
    F: Float,
    S: Layout<F> + Sync,
    M: Scatter<F, R> + Sync,
    C: Camera<F> + Sync,
    R: Rng + SeedableRng,
{
    /// Renders on the current rayon thread pool, bands of rows in parallel, each band's
    /// paths batched: the bytes of [`render_reference`], on any number of threads. An
    /// adaptive render ([`Renderer::adaptive`]) is the same bytes on any number of threads
    /// and in any tiling too, unless it has a time budget.
    ///
    /// # Errors
    /// Invalid settings, or a tile outside the camera's image.
    pub fn render(&self) -> Result<Render> {
        let start = Instant::now();
        let mut render = match &self.adaptive {
            Some(adaptive) => adaptive::render_adaptive(self, adaptive)?,
            None => self.render_uniform()?,
        };
        if self.aov {
            let spp = self.settings.samples_per_pixel;
            let (aov, rays) = match &render.convergence {
                Some(c) => {
                    let samples = |i: usize| c.samples()[i];
                    self.features(&samples, true)
                }
                None => self.features(&|_| spp, spp > 1),
            };
            render.aov = Some(aov);
            render.stats.rays += rays;
            render.stats.elapsed = start.elapsed();
        }
        Ok(render)
    }

    /// The feature layers, each pixel over `samples(i)` samples.
    fn features(&self, samples: &(dyn Fn(usize) -> u32 + Sync), jitter: bool) -> (Aovs, u64) {
        aov::render_aov::<R, F, S, M, C>(
            self.scene,
            self.camera,
            &self.settings,
            self.region(),
            (samples, jitter),
        )
    }

    /// [`Renderer::render`] with the same number of samples in every pixel.
    fn render_uniform(&self) -> Result<Render> {
        let (settings, camera, tile) = (&self.settings, self.camera, self.region());
        settings.validate()?;
        tile.check_inside(camera.width(), camera.height())?;
        let start = Instant::now();
        let mut image = Image::new(tile.width, tile.height)?;
        let progress = Progress::new(settings.progress, tile.height as u64);
        let (band, progress) = (BAND_ROWS * tile.width, &progress);
        let worker = || -> parallel::Job<'_, (usize, &mut [[f64; 3]])> {
            let mut batch = Batch::<F, R>::new();
            Box::new(move |(k, pixels)| {
                let mut tracer =
                    Tracer::new(self.scene, settings.max_depth).light_sampling(settings.light_sampling);
                let at = |i: usize| (tile.x + i % tile.width, tile.y + (k * band + i) / tile.width);
                batch.render(&mut tracer, camera, settings, at, pixels);
                progress.inc(pixels.len().div_ceil(tile.width) as u64);
                tracer.rays()
            })
        };
        let rays = parallel::sum(image.pixels_mut().par_chunks_mut(band).enumerate(), &worker);
        progress.finish();
        Ok(Render {
            image,
            stats: RenderStats {
                rays,
                elapsed: start.elapsed(),
                threads: rayon::current_num_threads(),
            },
            convergence: None,
            aov: None,
        })
    }

    /// Renders with [`render_reference`]: pixel by pixel on the calling thread, uniformly
    /// (the adaptive settings and the feature layers are not its business).
    ///
    /// # Errors
    /// As [`Renderer::render`].
    pub fn render_reference(&self) -> Result<Render> {
        render_reference::<R, F, S, M, C>(self.scene, self.camera, &self.settings, self.region())
    }
}

/// Rows rendered together as one batch of paths, one sample per pixel at a time.
const BAND_ROWS: usize = 4;
