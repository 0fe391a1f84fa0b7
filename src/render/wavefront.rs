//! The breadth-first form of the tracer: the paths of a whole row of pixels advance
//! together, one bounce at a time.
//!
//! Traced one by one, a path is a single chain of dependent steps (hit, shade, next
//! hit), so the processor spends most of its time waiting on latencies and mispredicted
//! branches. A row's paths are independent of each other: intersected and shaded as a
//! batch, consecutive iterations overlap instead of waiting.
//!
//! The answer is bit for bit the recursive [`Tracer::trace_pair`]'s:
//! - each pixel keeps its own generator and draws in the same order as the recursion
//!   (pair `k`'s two jitters, then at every bounce the first path's draws before the
//!   second's, then pair `k + 1`), so interleaving pixels changes no draw;
//! - each bounce's `(direct, attenuation)` is logged, and once every path has ended the
//!   logs are folded back from the last bounce, `c ← saturate(direct + attenuation ∘ c)`,
//!   the recursion's own arithmetic in its own order for each path.

use super::trace::{Step, Tracer, saturate};
use crate::camera::Camera;
use crate::float::{Float, lit};
use crate::material::Material;
use crate::ray::Ray;
use crate::scene::Nearests;
use crate::shape::Hittable;
use crate::vec3::Color;
use rand::Rng;

/// A bounce a path went on from: its slot, the direct light and the attenuation that
/// combine with the colour the next ray brings back.
type Bounce<F> = (u32, Color<F>, Color<F>);

/// The buffers of one row's paths, kept from row to row.
pub(super) struct Row<F, R> {
    /// Each pixel's generator.
    rngs: Vec<R>,
    /// Each pixel's coordinates `(x, y)`.
    centres: Vec<(F, F)>,
    /// Each pixel's sum of sample colours.
    sums: Vec<Color<F>>,
    /// The rays still travelling, and the slot of each one's path (`pixel · paths + j`).
    rays: Vec<Ray<F>>,
    slots: Vec<u32>,
    next_rays: Vec<Ray<F>>,
    next_slots: Vec<u32>,
    near: Nearests<F>,
    /// For each bounce, the paths that went on from it, in the rays' order.
    logs: Vec<Vec<Bounce<F>>>,
    /// Each path's colour where it ended (background, black, or its last direct light).
    ends: Vec<Color<F>>,
}

impl<F: Float, R: Rng> Row<F, R> {
    /// Empty buffers.
    pub(super) fn new() -> Self {
        Self {
            rngs: Vec::new(),
            centres: Vec::new(),
            sums: Vec::new(),
            rays: Vec::new(),
            slots: Vec::new(),
            next_rays: Vec::new(),
            next_slots: Vec::new(),
            near: Nearests::default(),
            logs: Vec::new(),
            ends: Vec::new(),
        }
    }

    /// Renders pixels into `out`, `out[i]` being pixel `at(i) = (x, y)` of the image and
    /// drawing from `rng(x, y)`: with one sample through the pixel centre, otherwise the
    /// mean of `spp` jittered samples, traced in pairs (and the last alone if `spp` is odd).
    pub(super) fn render<S, M, C>(
        &mut self,
        tracer: &mut Tracer<'_, F, S, M>,
        camera: &C,
        at: impl Fn(usize) -> (usize, usize),
        spp: u32,
        rng: impl Fn(usize, usize) -> R,
        out: &mut [[f64; 3]],
    ) where
        S: Hittable<F>,
        M: Material<F, R>,
        C: Camera<F>,
    {
        let width = out.len();
        self.rngs.clear();
        self.centres.clear();
        for i in 0..width {
            let (x, y) = at(i);
            self.rngs.push(rng(x, y));
            self.centres.push((lit(x as f64), lit(y as f64)));
        }
        let centres = std::mem::take(&mut self.centres);
        let px = |i: usize| centres[i];
        if spp == 1 {
            self.start(1, |i, _, _| {
                let (x, y) = px(i);
                camera.ray(x, y)
            });
            self.trace(tracer);
            for (o, &c) in out.iter_mut().zip(&self.ends) {
                *o = c.to_f64();
            }
            self.centres = centres;
            return;
        }
        let jittered = |i: usize, rng: &mut R| {
            let (dx, dy) = crate::sampling::pixel_jitter(rng);
            let (x, y) = px(i);
            camera.ray(x + lit(dx), y + lit(dy))
        };
        self.sums.clear();
        self.sums.resize(width, Color::zero());
        for paths in std::iter::repeat_n(2, spp as usize / 2).chain((spp % 2 == 1).then_some(1)) {
            self.start(paths, |i, _, rng| jittered(i, rng));
            self.trace(tracer);
            for (sum, ends) in self.sums.iter_mut().zip(self.ends.chunks(paths)) {
                for &c in ends {
                    *sum = *sum + c;
                }
            }
        }
        self.centres = centres;
        // Each sample is finite, but their sum may overflow: cap the mean again.
        let n = lit::<F>(f64::from(spp));
        for (o, &sum) in out.iter_mut().zip(&self.sums) {
            *o = saturate(sum / n).to_f64();
        }
    }

    /// Starts `paths` paths per pixel, path `j` of pixel `i` on `ray(i, j, rng_i)`, drawn
    /// pixel by pixel and in each pixel path by path.
    fn start(&mut self, paths: usize, mut ray: impl FnMut(usize, usize, &mut R) -> Ray<F>) {
        let slots = self.rngs.len() * paths;
        self.rays.clear();
        self.slots.clear();
        for (i, rng) in self.rngs.iter_mut().enumerate() {
            for j in 0..paths {
                self.rays.push(ray(i, j, rng));
                self.slots.push((i * paths + j) as u32);
            }
        }
        self.ends.clear();
        self.ends.resize(slots, Color::zero());
    }

    /// Traces the live paths to their ends and leaves each path's colour in `ends`.
    fn trace<S, M>(&mut self, tracer: &mut Tracer<'_, F, S, M>)
    where
        S: Hittable<F>,
        M: Material<F, R>,
    {
        // Paths per pixel (one or two): the pixel of slot `s` is `s >> shift`.
        let shift = (self.ends.len() / self.rngs.len().max(1)).trailing_zeros();
        let scene = tracer.scene;
        let mut depth = 0;
        while !self.rays.is_empty() {
            if self.logs.len() == depth {
                self.logs.push(Vec::new());
            }
            let log = &mut self.logs[depth];
            log.clear();
            tracer.rays += self.rays.len() as u64;
            self.next_rays.clear();
            self.next_slots.clear();
            // Each ray is shaded as soon as its hit is known, in the rays' order.
            let (rays, slots) = (&self.rays, &self.slots);
            scene.hit_all(rays, &mut self.near, |i, hit| {
                let slot = slots[i];
                let rng = &mut self.rngs[(slot >> shift) as usize];
                match tracer.shade(&rays[i], hit, depth as u32, rng) {
                    Step::Done(colour) => self.ends[slot as usize] = colour,
                    Step::Go(next, direct, attenuation) => {
                        log.push((slot, direct, attenuation));
                        self.next_rays.push(next);
                        self.next_slots.push(slot);
                    }
                }
            });
            std::mem::swap(&mut self.rays, &mut self.next_rays);
            std::mem::swap(&mut self.slots, &mut self.next_slots);
            depth += 1;
        }
        // Each path's bounces fold back from its last: bounce by bounce from the deepest,
        // each entry updating its path's colour.
        for log in self.logs[..depth].iter().rev() {
            for &(slot, direct, attenuation) in log {
                let end = &mut self.ends[slot as usize];
                *end = saturate(direct + attenuation * *end);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{DefaultRng, RenderSettings, pixel_seed, render};
    use crate::scene::{Acceleration, EnumScene};
    use crate::shape::{Plane, Sphere, Triangle};
    use crate::vec3::Vec3;
    use crate::{Background, Dielectric, Lambertian, Mirror, PointLight, ScreenCamera};
    use rand::{RngExt, SeedableRng};

    /// The mean colour of `spp` samples of pixel `(x, y)`, path by path with the recursive
    /// [`Tracer::trace_pair`]: the form the row's render must reproduce bit for bit.
    fn sample_pixel<R, F, S, M, C>(
        tracer: &mut Tracer<'_, F, S, M>,
        camera: &C,
        x: usize,
        y: usize,
        spp: u32,
        rng: &mut R,
    ) -> Color<F>
    where
        R: Rng + ?Sized,
        F: Float,
        S: Hittable<F>,
        M: Material<F, R>,
        C: Camera<F>,
    {
        let (px, py) = (lit::<F>(x as f64), lit::<F>(y as f64));
        if spp == 1 {
            return tracer.trace(&camera.ray(px, py), 0, rng);
        }
        let jittered = |rng: &mut R| {
            let (dx, dy) = crate::sampling::pixel_jitter(rng);
            camera.ray(px + lit(dx), py + lit(dy))
        };
        let mut sum = Color::zero();
        // Samples in pairs, traced side by side (the second's jitter drawn before the first's path).
        for _ in 0..spp / 2 {
            let (a, b) = (jittered(rng), jittered(rng));
            let (ca, cb) = tracer.trace_pair(&a, &b, 0, rng);
            sum = sum + ca + cb;
        }
        if spp % 2 == 1 {
            let ray = jittered(rng);
            sum = sum + tracer.trace(&ray, 0, rng);
        }
        // Each sample is finite, but their sum may overflow: cap the mean again.
        saturate(sum / lit(f64::from(spp)))
    }

    /// Matte, mirror and glass spheres (`n` of them, at random), a plane, a triangle and two
    /// point lights: every kind of bounce, absorbed paths, shadow rays, and with enough
    /// spheres a BVH.
    fn scene(n: usize) -> EnumScene<f64> {
        let mut rng = DefaultRng::seed_from_u64(n as u64);
        let mut scene = EnumScene::new(Background::default());
        for i in 0..n {
            let c = Vec3::new(
                rng.random_range(-2.5..2.5),
                rng.random_range(-1.0..1.0),
                rng.random_range(-6.0..-3.0),
            );
            let s = Sphere::new(c, rng.random_range(0.1..0.6)).unwrap();
            let a = Vec3::new(rng.random_range(0.0..1.0), rng.random_range(0.0..1.0), 0.7);
            match i % 3 {
                0 => scene.add(s, Lambertian::new(a).unwrap()),
                1 => scene.add(s, Mirror::new(a).unwrap()),
                _ => scene.add(s, Dielectric::new(1.5).unwrap()),
            };
        }
        let p = |x, y, z| Vec3::new(x, y, z);
        scene.add(
            Plane::new(p(0.0, -1.0, 0.0), p(0.0, 1.0, 0.0)).unwrap(),
            Lambertian::new(p(0.5, 0.5, 0.5)).unwrap(),
        );
        scene.add(
            Triangle::new(p(-1.0, -1.0, -4.0), p(1.0, -1.0, -4.5), p(0.0, 1.2, -5.0)).unwrap(),
            Mirror::new(p(0.9, 0.8, 0.6)).unwrap(),
        );
        scene.add_light(PointLight::new(p(-2.0, 3.0, -2.0), p(9.0, 8.0, 7.0)).unwrap());
        scene.add_light(PointLight::new(p(2.0, 2.0, -1.0), p(3.0, 4.0, 5.0)).unwrap());
        scene
    }

    /// The row by row, bounce by bounce render gives the recursive per-pixel render's
    /// pixels bit for bit and the same ray count, with one sample (the pixel centre), even
    /// and odd sample counts, a depth limit that cuts paths short, through the plain loop
    /// and through a BVH. (Any change to the order of draws, the fold of a path's bounces,
    /// or a path's slot fails it.)
    #[test]
    fn rows_render_what_the_recursion_renders() {
        let cam = ScreenCamera::new(24, 12).unwrap();
        for (n, spp, depth) in [(6, 1, 8), (6, 2, 8), (6, 5, 3), (40, 3, 8), (40, 4, 50)] {
            let scene = scene(n);
            assert_eq!(scene.uses_bvh(), n >= Acceleration::AUTO_THRESHOLD);
            let settings = RenderSettings::new(spp, depth, 7).unwrap();
            let got = render(&scene, &cam, &settings).unwrap();
            let mut tracer = Tracer::new(&scene, depth);
            let mut want = Vec::new();
            for y in 0..12 {
                for x in 0..24 {
                    let mut rng = DefaultRng::seed_from_u64(pixel_seed(7, (y * 24 + x) as u64));
                    want.push(sample_pixel(&mut tracer, &cam, x, y, spp, &mut rng).to_f64());
                }
            }
            let first_difference = got
                .image
                .pixels()
                .iter()
                .zip(&want)
                .position(|(a, b)| a.map(f64::to_bits) != b.map(f64::to_bits));
            assert_eq!(first_difference, None, "{n} spheres, {spp} spp, depth {depth}");
            assert_eq!(got.stats.rays, tracer.rays());
        }
    }
}
