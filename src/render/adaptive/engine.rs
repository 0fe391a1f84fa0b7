//! The rounds of an adaptive render: trace each pixel's share, update its statistics,
//! decide the next round.

use super::Adaptive;
use super::convergence::{Convergence, median_and_p99};
use super::schedule::{Candidate, share, toward_target};
use super::stats::{Estimate, PixelStats};
use crate::camera::Camera;
use crate::error::Result;
use crate::float::Float;
use crate::image::Image;
use crate::material::Scatter;
use crate::render::batch::Batch;
use crate::render::parallel;
use crate::render::progress::{Progress, Round};
use crate::render::reference::{mean, pixel_stream};
use crate::render::{Render, RenderStats, Renderer, Tracer};
use crate::scene::Layout;
use rand::{Rng, SeedableRng};
use std::time::{Duration, Instant};

/// About the most samples of one round handed to a worker as one task: the task traces,
/// then adds to its pixels, the samples of a run of consecutive pixels (one pixel alone
/// may ask for more). Small enough that a round spreads over every thread, large enough
/// that a task's batches hold a thousand paths.
const TASK_SAMPLES: usize = 4096;

/// The most paths traced together as one batch.
const BATCH_PATHS: usize = 1024;

/// With a time budget, each round adds at most this share of the samples taken so far,
/// and no more than the time left is predicted to allow: the round the time runs out in
/// is cut short, and a short round is cut with little left undone. A pixel at most
/// doubles in a round, so the smaller the rounds the further the samples can gather where
/// they are needed: a quarter did better than a half at equal rays on most gallery scenes
/// and budgets (measured in the commit that chose it).
const ROUND_GROWTH: f64 = 0.25;

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
    loop {
        // The first round is always whole: every pixel needs an estimate. Later ones
        // stop where the time runs out.
        let out_of_time = || rounds > 0 && deadline.is_some_and(|d| Instant::now() >= d);
        rays += trace_round(renderer, &mut pixels, &next, &out_of_time);
        rounds += 1;
        let estimate = |i: usize| pixels[i].estimate(adaptive.error_floor, adaptive.estimate);
        let estimates: Vec<Estimate> = parallel::each(pixels.len(), &estimate);
        let errors: Vec<f64> = estimates.iter().map(|e| e.error).collect();
        match deadline {
            Some(deadline) => plan_for_time(
                &pixels,
                &estimates,
                adaptive,
                (start.elapsed(), deadline),
                &mut next,
            ),
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

/// Traces a round: for each pixel `i`, `next[i]` more samples, added to `pixels[i]` in
/// sample order. Runs of consecutive pixels with about [`TASK_SAMPLES`] samples are the
/// tasks, in parallel; each traces its samples in batches and adds them to its own pixels.
/// Between batches a task stops if `stop()`: a pixel keeps what it has (its samples are
/// still `0..n`). Returns the rays traced.
fn trace_round<F, S, M, C, R>(
    renderer: &Renderer<'_, F, S, M, C, R>,
    pixels: &mut [PixelStats<F>],
    next: &[u32],
    stop: &(impl Fn() -> bool + Sync),
) -> u64
where
    F: Float,
    S: Layout<F> + Sync,
    M: Scatter<F, R> + Sync,
    C: Camera<F> + Sync,
    R: Rng + SeedableRng,
{
    let mut tasks = Vec::new();
    let (mut rest, mut first) = (pixels, 0);
    while !rest.is_empty() {
        let mut len = 1;
        let mut samples = next[first] as usize;
        while first + len < next.len() && samples + (next[first + len] as usize) <= TASK_SAMPLES {
            samples += next[first + len] as usize;
            len += 1;
        }
        let (task, tail) = std::mem::take(&mut rest).split_at_mut(len);
        if samples > 0 {
            tasks.push((first, task));
        }
        (rest, first) = (tail, first + len);
    }
    let (settings, camera, tile) = (&renderer.settings, renderer.camera, renderer.region());
    let worker = || -> parallel::Job<'_, (usize, &mut [PixelStats<F>])> {
        let (mut batch, mut work) = (Batch::<F, R>::new(), Work::default());
        Box::new(move |(first, stats)| {
            let mut tracer =
                Tracer::new(renderer.scene, settings.max_depth).light_sampling(settings.light_sampling);
            let wanted = &next[first..first + stats.len()];
            let (mut i, mut listed) = (0, 0);
            while i < stats.len() && !stop() {
                let pixel = |k: usize| {
                    let k = first + k;
                    let (x, y) = (tile.x + k % tile.width, tile.y + k / tile.width);
                    (x, y, pixel_stream(settings, camera, x, y))
                };
                (i, listed) = work.list((i, listed), stats, wanted, pixel);
                let (colours, bounces) = batch.trace_samples(&mut tracer, camera, &work.samples);
                for ((&owner, &c), &b) in work.owners.iter().zip(colours).zip(bounces) {
                    stats[owner].add(c, b);
                }
            }
            tracer.rays()
        })
    };
    parallel::sum(tasks, &worker)
}

/// A task's batch: the samples to trace, `(x, y, stream, sample)`, and the pixel of the
/// task each belongs to.
#[derive(Default)]
struct Work {
    samples: Vec<(usize, usize, u64, u32)>,
    owners: Vec<usize>,
}

impl Work {
    /// Lists the next batch: from pixel `from.0`, whose first `from.1` samples of this
    /// round are traced already, the samples `wanted` asks for, pixel after pixel, until
    /// [`BATCH_PATHS`] are listed. `pixel(i)` is pixel `i`'s `(x, y, stream)`. Returns
    /// where the batch after it starts.
    fn list<F: Float>(
        &mut self,
        (mut i, mut listed): (usize, u32),
        stats: &[PixelStats<F>],
        wanted: &[u32],
        pixel: impl Fn(usize) -> (usize, usize, u64),
    ) -> (usize, u32) {
        self.samples.clear();
        self.owners.clear();
        while i < stats.len() && self.samples.len() < BATCH_PATHS {
            let room = (BATCH_PATHS - self.samples.len()) as u32;
            let take = (wanted[i] - listed).min(room);
            if take > 0 {
                let (x, y, stream) = pixel(i);
                // Samples 0..n are taken (this round's earlier batches among them,
                // added already): these follow.
                let first = stats[i].n;
                self.samples
                    .extend((first..first + take).map(|sample| (x, y, stream, sample)));
                self.owners.extend(std::iter::repeat_n(i, take as usize));
            }
            listed += take;
            if listed == wanted[i] {
                (i, listed) = (i + 1, 0);
            }
        }
        (i, listed)
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
    estimates: &[Estimate],
    adaptive: &Adaptive,
    (spent, deadline): (Duration, Instant),
    next: &mut [u32],
) {
    let target = adaptive.target_error.unwrap_or(0.0);
    let candidates: Vec<Candidate> = stats
        .iter()
        .zip(estimates)
        .map(|(p, e)| {
            let done = e.error <= target || p.n >= adaptive.max_spp;
            Candidate {
                n: p.n,
                deviation: e.deviation,
                cost: p.cost(),
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
