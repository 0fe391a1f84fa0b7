//! The rounds of an adaptive render: trace each pixel's share, update its statistics,
//! decide the next round.

use super::Adaptive;
use super::convergence::{Convergence, median_and_p99};
use super::schedule::{Candidate, share, toward_target};
use super::stats::PixelStats;
use crate::camera::Camera;
use crate::error::Result;
use crate::float::Float;
use crate::image::Image;
use crate::material::Scatter;
use crate::render::batch::Batch;
use crate::render::progress::{Progress, Round};
use crate::render::reference::{mean, pixel_stream};
use crate::render::{Rect, Render, RenderStats, Renderer, Tracer};
use crate::scene::Layout;
use crate::vec3::Color;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// The most samples of one round traced between two looks at the clock: the samples of
/// a slab are listed, traced in parallel, then added to their pixels in order.
const SLAB_SAMPLES: usize = 1 << 16;

/// The most paths traced together as one batch, one task of a slab: small enough that a
/// slab spreads over every thread even when one pixel holds all its samples.
const BATCH_PATHS: usize = 1024;

/// With a time budget, each round adds at most this share of the samples taken so far,
/// and no more than the time left is predicted to allow: the round the time runs out in
/// is cut short, and a short round is cut with little left undone.
const ROUND_GROWTH: f64 = 0.5;

/// Renders `renderer`'s region adaptively (see the [module docs](super)).
pub(in crate::render) fn render_adaptive<F, S, M, C, R>(
    renderer: &Renderer<'_, F, S, M, C, R>,
    adaptive: &Adaptive,
) -> Result<Render>
where
    F: Float,
    S: Layout<F> + Sync,
    M: Scatter<F, R> + Sync,
    C: Camera<F> + Sync,
    R: Rng + SeedableRng,
{
    let (settings, camera, tile) = (&renderer.settings, renderer.camera, renderer.region());
    settings.validate()?;
    adaptive.validate()?;
    tile.check_inside(camera.width(), camera.height())?;
    let start = Instant::now();
    let deadline = adaptive.time_budget.map(|b| start + b);
    let count = tile.width * tile.height;
    let mut pixels = vec![PixelStats::<F>::new(); count];
    let mut next = vec![adaptive.min_spp; count];
    let progress = Progress::rounds(settings.progress, adaptive, count as u64);
    let (mut rays, mut rounds) = (0u64, 0u32);
    let mut work = Work::default();
    loop {
        // The first round is always whole: every pixel needs an estimate. Later ones
        // stop where the time runs out.
        let out_of_time = || rounds > 0 && deadline.is_some_and(|d| Instant::now() >= d);
        let mut from = (0, 0);
        while from.0 < count && !out_of_time() {
            let stream = |x, y| pixel_stream(settings, camera, x, y);
            from = work.list(from, &pixels, &next, tile, stream);
            rays += work.trace(renderer, camera);
            for (&owner, &c) in work.owners.iter().zip(&work.colours) {
                pixels[owner].add(c);
            }
        }
        rounds += 1;
        let errors: Vec<f64> = pixels
            .iter()
            .map(|p| p.estimate(adaptive.error_floor, adaptive.estimate).error)
            .collect();
        match deadline {
            Some(deadline) => {
                plan_for_time(&pixels, &errors, adaptive, (start.elapsed(), deadline), &mut next)
            }
            None => decide_for_target(&pixels, &errors, &mut next, adaptive),
        }
        let active = next.iter().filter(|&&n| n > 0).count();
        let (median, p99) = median_and_p99(errors);
        progress.round(&Round {
            number: rounds,
            median,
            p99,
            active,
            elapsed: start.elapsed(),
        });
        if active == 0 || deadline.is_some_and(|d| Instant::now() >= d) {
            break;
        }
    }
    progress.finish();
    let mut image = Image::new(tile.width, tile.height)?;
    for (out, p) in image.pixels_mut().iter_mut().zip(&pixels) {
        *out = mean(p.sum, p.n).to_f64();
    }
    let convergence = Convergence::new(
        (tile.width, tile.height),
        pixels.iter().map(|p| p.n).collect(),
        pixels
            .iter()
            .map(|p| p.estimate(adaptive.error_floor, adaptive.estimate).error)
            .collect(),
        (adaptive.target_error, adaptive.max_spp),
        rounds,
    );
    Ok(Render {
        image,
        stats: RenderStats {
            rays,
            elapsed: start.elapsed(),
            threads: rayon::current_num_threads(),
        },
        convergence: Some(convergence),
        aov: None,
    })
}

/// One slab of a round: the samples to trace, `(x, y, stream, sample)`, the pixel each
/// belongs to, and their colours once traced.
#[derive(Default)]
struct Work<F> {
    samples: Vec<(usize, usize, u64, u32)>,
    owners: Vec<usize>,
    colours: Vec<Color<F>>,
}

impl<F: Float> Work<F> {
    /// Lists the next slab: from pixel `from.0`, whose first `from.1` samples of this
    /// round are already traced, the samples `next` asks for, pixel after pixel, until
    /// [`SLAB_SAMPLES`] are listed. Returns where the slab after it starts.
    fn list(
        &mut self,
        (mut i, mut listed): (usize, u32),
        pixels: &[PixelStats<F>],
        next: &[u32],
        tile: Rect,
        stream: impl Fn(usize, usize) -> u64,
    ) -> (usize, u32) {
        self.samples.clear();
        self.owners.clear();
        while i < pixels.len() && self.samples.len() < SLAB_SAMPLES {
            let room = (SLAB_SAMPLES - self.samples.len()) as u32;
            let take = (next[i] - listed).min(room);
            if take > 0 {
                let (x, y) = (tile.x + i % tile.width, tile.y + i / tile.width);
                let s = stream(x, y);
                // Samples 0..n are taken (those of this round's earlier slabs among
                // them, added already): these follow.
                let first = pixels[i].n;
                self.samples
                    .extend((first..first + take).map(|sample| (x, y, s, sample)));
                self.owners.extend(std::iter::repeat_n(i, take as usize));
            }
            listed += take;
            if listed == next[i] {
                (i, listed) = (i + 1, 0);
            }
        }
        (i, listed)
    }

    /// Traces the listed samples in parallel, batches of [`BATCH_PATHS`], into
    /// `colours`. Returns the rays traced.
    fn trace<S, M, C, R>(&mut self, renderer: &Renderer<'_, F, S, M, C, R>, camera: &C) -> u64
    where
        S: Layout<F> + Sync,
        M: Scatter<F, R> + Sync,
        C: Camera<F> + Sync,
        R: Rng + SeedableRng,
    {
        let settings = &renderer.settings;
        self.colours.clear();
        self.colours.resize(self.samples.len(), Color::zero());
        self.samples
            .par_chunks(BATCH_PATHS)
            .zip(self.colours.par_chunks_mut(BATCH_PATHS))
            .map_init(Batch::<F, R>::new, |batch, (samples, colours)| {
                let mut tracer =
                    Tracer::new(renderer.scene, settings.max_depth).light_sampling(settings.light_sampling);
                colours.copy_from_slice(batch.trace_samples(&mut tracer, camera, samples));
                tracer.rays()
            })
            .sum()
    }
}

/// After a round without a time budget: each pixel's next share from its own estimate
/// ([`toward_target`]), so the decision never depends on another pixel.
fn decide_for_target<F: Float>(
    stats: &[PixelStats<F>],
    errors: &[f64],
    next: &mut [u32],
    adaptive: &Adaptive,
) {
    let target = adaptive.target_error.unwrap_or(0.0);
    for ((p, &error), slot) in stats.iter().zip(errors).zip(next) {
        *slot = toward_target(p.n, error, target, adaptive.max_spp);
    }
}

/// After a round with a time budget: the next round's shares ([`share`]) of a budget of
/// new samples, [`ROUND_GROWTH`] of those taken so far, or fewer if the render's rate so
/// far says the time left allows fewer. Pixels that met the target (if
/// any) or the cap take none.
fn plan_for_time<F: Float>(
    stats: &[PixelStats<F>],
    errors: &[f64],
    adaptive: &Adaptive,
    (spent, deadline): (Duration, Instant),
    next: &mut [u32],
) {
    let target = adaptive.target_error.unwrap_or(0.0);
    let candidates: Vec<Candidate> = stats
        .iter()
        .zip(errors)
        .map(|(p, &error)| {
            let done = error <= target || p.n >= adaptive.max_spp;
            Candidate {
                n: p.n,
                deviation: p.estimate(adaptive.error_floor, adaptive.estimate).deviation,
                room: if done { 0 } else { p.n.min(adaptive.max_spp - p.n) },
            }
        })
        .collect();
    let taken: u64 = stats.iter().map(|p| u64::from(p.n)).sum();
    let left = deadline.saturating_duration_since(Instant::now());
    // Samples per second over the render so far (its first round included).
    let rate = taken as f64 / spent.as_secs_f64().max(1e-9);
    let affordable = (rate * left.as_secs_f64()) as u64;
    // At least a quarter of a sample per pixel: rounds near the deadline stay worth
    // their pass over the pixels, and the last is cut where the time runs out.
    let budget = ((taken as f64 * ROUND_GROWTH) as u64)
        .min(affordable)
        .max(stats.len() as u64 / 4 + 1);
    share(&candidates, budget, next);
}
