//! The batched form of the reference renderer: the paths of a band of pixels advance
//! together, one bounce at a time.
//!
//! Traced one by one, a path is a single chain of dependent steps (hit, shade, next
//! hit), so the processor spends most of its time waiting on latencies and mispredicted
//! branches. The paths of different pixels are independent: intersected and shaded as a
//! batch, consecutive iterations overlap instead of waiting.
//!
//! The answer is bit for bit [`render_reference`](super::render_reference)'s:
//! - each sample draws from its own generator ([`sample_rng`]), so tracing the samples
//!   of many pixels side by side changes no draw;
//! - each bounce's direct light and weight are logged, and once every path has ended the
//!   logs are folded back from the last bounce, `c ← saturate(direct + weight ∘ c)`:
//!   the recursion's own arithmetic, in its own order, for each path;
//! - each ray travels with the state the recursion passes down with it (how it left its
//!   last vertex, for the weight of the emitted light it finds);
//! - where there is a tree to walk, each bounce's shadow rays wait, and those of a depth
//!   are traced together, as its rays are; the light that arrives is added as the
//!   recursion adds it, before the bounce's light is folded. A ray to a point drawn on an
//!   emitter looks for its nearest hit there: where that is the emitter's part, the part's
//!   own test has given the exact reach the recursion asks the part for, and nothing is
//!   nearer; only otherwise is the part asked (`Scene::occluded_all`);
//! - each pixel's samples are summed in the reference's order, sample 0 first.

use super::RenderSettings;
use super::reference::{camera_ray, mean, pixel_stream, sample_rng};
use super::shadow::{Shadow, arrive};
use super::trace::{Arrival, Step, Tracer, saturate};
use crate::camera::Camera;
use crate::float::Float;
use crate::material::Scatter;
use crate::ray::Ray;
use crate::scene::Layout;
use crate::scene::Nearests;
use crate::vec3::Color;
use rand::{Rng, SeedableRng};

/// A bounce a path went on from: what combines with the colour the next ray brings back,
/// and what that ray travels with.
#[derive(Clone, Copy)]
struct Bounce<F> {
    /// The path's pixel, in the band.
    pixel: u32,
    /// The light the bounce adds.
    direct: Color<F>,
    /// The sample's weight.
    weight: Color<F>,
    /// How the next ray left the bounce.
    arrival: Arrival<F>,
}

impl<F: Float> Bounce<F> {
    /// Where a camera ray starts: pixel `pixel`'s path, nothing to add yet.
    fn camera(pixel: u32) -> Self {
        Self {
            pixel,
            direct: Color::zero(),
            weight: Color::zero(),
            arrival: Arrival::Unweighted,
        }
    }
}

/// Where the light of a bounce's waiting shadow rays goes once they are traced.
#[derive(Clone, Copy)]
enum Waiting {
    /// To the bounce at this place in the depth's log.
    Bounce(u32),
    /// To the path's colour at its end: the pixel's.
    End(u32),
}

/// The buffers of one band's paths, kept from band to band.
pub(super) struct Batch<F, R> {
    /// Each pixel's generator for the sample being traced.
    rngs: Vec<R>,
    /// Each pixel's coordinates in the image and its random stream.
    pixels_at: Vec<(usize, usize, u64)>,
    /// Each pixel's sum of sample colours.
    sums: Vec<Color<F>>,
    /// The rays still travelling; ray `i` of depth `d` left `logs[d][i]`.
    rays: Vec<Ray<F>>,
    next_rays: Vec<Ray<F>>,
    near: Nearests<F>,
    /// Where each travelling ray came from: `logs[0]` the camera's, one entry a path (its
    /// pixel), and `logs[d + 1]` the bounces at depth `d` that went on, in the rays' order.
    logs: Vec<Vec<Bounce<F>>>,
    /// Each path's colour where it ended (background, black, or its last direct light).
    ends: Vec<Color<F>>,
    /// A depth's shadow rays waiting to be traced, with their light: for each bounce that
    /// left some, where the light goes and how many of `shadows` are its (in order); their
    /// rays and reaches, and which of the rays are blocked.
    waiting: Vec<(Waiting, u32)>,
    shadows: Vec<Shadow<F>>,
    shadow_rays: Vec<Ray<F>>,
    reaches: Vec<F>,
    aimed: Vec<Option<(u32, u32)>>,
    blocked: Vec<bool>,
    /// The bounces the last trace took (the logs beyond `logs[depth]` are stale).
    depth: usize,
    /// For [`Batch::trace_samples`] only: each path's bounces.
    bounces: Vec<u32>,
}

impl<F: Float, R: Rng + SeedableRng> Batch<F, R> {
    /// Empty buffers.
    pub(super) fn new() -> Self {
        Self {
            rngs: Vec::new(),
            pixels_at: Vec::new(),
            sums: Vec::new(),
            rays: Vec::new(),
            next_rays: Vec::new(),
            near: Nearests::default(),
            logs: Vec::new(),
            ends: Vec::new(),
            waiting: Vec::new(),
            shadows: Vec::new(),
            shadow_rays: Vec::new(),
            reaches: Vec::new(),
            aimed: Vec::new(),
            blocked: Vec::new(),
            depth: 0,
            bounces: Vec::new(),
        }
    }

    /// Renders pixels into `out`, `out[i]` being pixel `at(i) = (x, y)` of the image: for
    /// each sample in turn, one path per pixel, all traced together.
    pub(super) fn render<S, M, C>(
        &mut self,
        tracer: &mut Tracer<'_, F, S, M>,
        camera: &C,
        settings: &RenderSettings,
        at: impl Fn(usize) -> (usize, usize),
        out: &mut [[f64; 3]],
    ) where
        S: Layout<F>,
        M: Scatter<F, R>,
        C: Camera<F>,
    {
        let spp = settings.samples_per_pixel;
        self.sums.clear();
        self.sums.resize(out.len(), Color::zero());
        self.pixels_at.clear();
        self.pixels_at.extend((0..out.len()).map(|i| {
            let (x, y) = at(i);
            (x, y, pixel_stream(settings, camera, x, y))
        }));
        for sample in 0..spp {
            // All generators first, then all rays: two short loops keep more pixels in
            // flight than one long chain of dependent steps per pixel.
            self.rngs.clear();
            let seeded = self
                .pixels_at
                .iter()
                .map(|&(_, _, stream)| sample_rng(stream, sample));
            self.rngs.extend(seeded);
            self.rays.clear();
            let rays = self.pixels_at.iter().zip(&mut self.rngs);
            self.rays
                .extend(rays.map(|(&(x, y, _), rng)| camera_ray(camera, x, y, spp > 1, rng)));
            self.trace(tracer);
            for (sum, &c) in self.sums.iter_mut().zip(&self.ends) {
                *sum = *sum + c;
            }
        }
        for (o, &sum) in out.iter_mut().zip(&self.sums) {
            *o = mean(sum, spp).to_f64();
        }
    }

    /// Traces one sample of each of `samples`, `(x, y, stream, sample)`: sample `sample`
    /// of the pixel at `(x, y)` with random stream `stream`, its camera ray jittered in
    /// the pixel. Returns their colours, in the same order (each the colour the reference
    /// renderer's recursion gives that sample), and the bounces each path took: what a
    /// sample of that pixel costs.
    pub(super) fn trace_samples<S, M, C>(
        &mut self,
        tracer: &mut Tracer<'_, F, S, M>,
        camera: &C,
        samples: &[(usize, usize, u64, u32)],
    ) -> (&[Color<F>], &[u32])
    where
        S: Layout<F>,
        M: Scatter<F, R>,
        C: Camera<F>,
    {
        self.rngs.clear();
        self.rngs.extend(
            samples
                .iter()
                .map(|&(_, _, stream, sample)| sample_rng(stream, sample)),
        );
        self.rays.clear();
        let rays = samples.iter().zip(&mut self.rngs);
        self.rays
            .extend(rays.map(|(&(x, y, _, _), rng)| camera_ray(camera, x, y, true, rng)));
        self.trace(tracer);
        self.bounces.clear();
        self.bounces.resize(samples.len(), 0);
        for log in &self.logs[1..=self.depth] {
            for b in log {
                self.bounces[b.pixel as usize] += 1;
            }
        }
        (&self.ends, &self.bounces)
    }

    /// Traces the camera rays `rays` (ray `i` pixel `i`'s) to their paths' ends and leaves
    /// each pixel's colour in `ends`.
    fn trace<S, M>(&mut self, tracer: &mut Tracer<'_, F, S, M>)
    where
        S: Layout<F>,
        M: Scatter<F, R>,
    {
        // Not cleared: every path writes its end once (where it is done or lit), over
        // whatever the last trace left.
        self.ends.resize(self.rays.len(), Color::zero());
        let scene = tracer.scene;
        // Where there is a tree, a depth's shadow rays are walked down it together.
        tracer.defer = scene.uses_bvh();
        if self.logs.is_empty() {
            self.logs.push(Vec::new());
        }
        self.logs[0].clear();
        self.logs[0].extend((0..self.rays.len() as u32).map(Bounce::camera));
        let mut depth = 0;
        while !self.rays.is_empty() {
            if self.logs.len() == depth + 1 {
                self.logs.push(Vec::new());
            }
            let (done, to_come) = self.logs.split_at_mut(depth + 1);
            let (from, log) = (&done[depth], &mut to_come[0]);
            log.clear();
            tracer.rays += self.rays.len() as u64;
            self.next_rays.clear();
            self.waiting.clear();
            self.shadows.clear();
            // Each ray is shaded as soon as its hit is known, in the rays' order. Inlined
            // whatever its size: called, it takes the hit through memory.
            let rays = &self.rays;
            scene.hit_all(
                rays,
                &mut self.near,
                #[inline(always)]
                |i, hit| {
                    let Bounce { pixel, arrival, .. } = from[i];
                    let rng = &mut self.rngs[pixel as usize];
                    match tracer.shade(&rays[i], hit, depth as u32, arrival, rng) {
                        Step::Done(colour) => self.ends[pixel as usize] = colour,
                        Step::Lit(direct) if tracer.shadows.is_empty() => {
                            self.ends[pixel as usize] = saturate(direct);
                        }
                        Step::Lit(direct) => {
                            self.ends[pixel as usize] = direct;
                            let n = tracer.shadows.len() as u32;
                            self.waiting.push((Waiting::End(pixel), n));
                            self.shadows.append(&mut tracer.shadows);
                        }
                        Step::Go {
                            ray,
                            direct,
                            weight,
                            arrival,
                        } => {
                            if !tracer.shadows.is_empty() {
                                let n = tracer.shadows.len() as u32;
                                self.waiting.push((Waiting::Bounce(log.len() as u32), n));
                                self.shadows.append(&mut tracer.shadows);
                            }
                            log.push(Bounce {
                                pixel,
                                direct,
                                weight,
                                arrival,
                            });
                            self.next_rays.push(ray);
                        }
                    }
                },
            );
            self.trace_shadows(tracer, depth);
            std::mem::swap(&mut self.rays, &mut self.next_rays);
            depth += 1;
        }
        self.depth = depth;
        tracer.defer = false;
        // Each path's bounces fold back from its last: bounce by bounce from the deepest,
        // each entry updating its path's colour.
        for log in self.logs[1..=depth].iter().rev() {
            for b in log {
                let end = &mut self.ends[b.pixel as usize];
                *end = saturate(b.direct + b.weight * *end);
            }
        }
    }

    /// Traces the shadow rays the bounces at `depth` left waiting, and adds the light of
    /// those that arrive to their bounce's logged light ([`arrive`]), or to the colour of
    /// the path that ended there (then saturated, as the recursion's end is).
    fn trace_shadows<S, M>(&mut self, tracer: &mut Tracer<'_, F, S, M>, depth: usize)
    where
        S: Layout<F>,
        M: Scatter<F, R>,
    {
        if self.shadows.is_empty() {
            return;
        }
        self.shadow_rays.clear();
        self.shadow_rays.extend(self.shadows.iter().map(|s| s.ray));
        self.reaches.clear();
        self.reaches.extend(self.shadows.iter().map(|s| s.reach));
        self.aimed.clear();
        self.aimed.extend(self.shadows.iter().map(|s| s.aimed));
        let (rays, reaches, aimed) = (&self.shadow_rays, &self.reaches, &self.aimed);
        // A ray aimed at a part it does not meet finds no light and is not a ray traced.
        let missed = tracer
            .scene
            .occluded_all(rays, reaches, aimed, &mut self.near, &mut self.blocked);
        tracer.rays -= missed as u64;
        let mut start = 0;
        for &(waiting, n) in &self.waiting {
            let range = start..start + n as usize;
            start = range.end;
            let (shadows, blocked) = (&self.shadows[range.clone()], &self.blocked[range]);
            let arrived = |direct| arrive(direct, shadows, |i| blocked[i]);
            match waiting {
                Waiting::Bounce(k) => {
                    let bounce = &mut self.logs[depth + 1][k as usize];
                    bounce.direct = arrived(bounce.direct);
                }
                Waiting::End(pixel) => {
                    let end = &mut self.ends[pixel as usize];
                    *end = saturate(arrived(*end));
                }
            }
        }
    }
}
