//! The recursive ray colour computation.

use crate::float::{Float, lit};
use crate::material::Material;
use crate::ray::Ray;
use crate::scene::Scene;
use crate::shape::{Hit, Hittable};
use crate::vec3::Color;
use rand::Rng;

/// Caps each channel at the largest finite value. A light almost touching a surface can
/// make `I·cos θ/d²` overflow (in f32 from `d ≈ 10⁻¹⁹`); an infinite channel would then
/// turn into NaN at the next zero albedo (`0·∞`). Capped, it stays finite and simply
/// saturates the pixel. A NaN (which only a broken user material can make) is kept, not
/// hidden: the comparison fails for it.
#[inline]
pub(crate) fn saturate<F: Float>(c: Color<F>) -> Color<F> {
    c.map(|x| if x > F::max_value() { F::max_value() } else { x })
}

/// Most rays a [`Tracer`] traces together ([`Tracer::trace_batch`]).
pub const BATCH: usize = 4;

/// Traces rays through one scene and counts them.
pub struct Tracer<'a, F, S, M> {
    scene: &'a Scene<F, S, M>,
    max_depth: u32,
    rays: u64,
}

impl<'a, F: Float, S: Hittable<F>, M> Tracer<'a, F, S, M> {
    /// A tracer for `scene` that lets paths bounce at most `max_depth` times.
    pub fn new(scene: &'a Scene<F, S, M>, max_depth: u32) -> Self {
        Self {
            scene,
            max_depth,
            rays: 0,
        }
    }

    /// Rays traced so far (camera, scattered and shadow).
    pub fn rays(&self) -> u64 {
        self.rays
    }

    /// The colour a ray brings back, `depth` being the bounces it has already taken:
    ///
    /// - it hits nothing: the background;
    /// - it hits a surface after `max_depth` bounces: black `(0, 0, 0)`;
    /// - otherwise: the direct light from point lights (matte surfaces only) plus
    ///   `A ∘ trace(scattered, depth + 1)`, or black if the material absorbs the ray.
    ///
    /// The same as [`Tracer::trace_batch`] on this one ray.
    pub fn trace<R>(&mut self, ray: &Ray<F>, depth: u32, rng: &mut R) -> Color<F>
    where
        R: Rng + ?Sized,
        M: Material<F, R>,
    {
        self.trace_batch(std::slice::from_ref(ray), depth, &mut [rng], &[0])[0]
    }

    /// [`trace`](Tracer::trace) for up to [`BATCH`] independent rays at once: ray `i` draws
    /// only from `rngs[slots[i]]`, so its colour is exactly the one `trace` gives it alone.
    ///
    /// The recursion is the same, one batch at a time: every ray of the batch is
    /// intersected, then shaded, and the rays that scatter are traced, together, one
    /// bounce deeper. Why batch: a path is one long chain of dependent steps (hit point,
    /// direction, next hit), so tracing one ray leaves the processor waiting on latencies;
    /// several independent rays side by side fill those waits.
    ///
    /// # Panics
    /// If there are more than [`BATCH`] rays, or fewer slots than rays.
    pub fn trace_batch<R>(
        &mut self,
        rays: &[Ray<F>],
        depth: u32,
        rngs: &mut [&mut R],
        slots: &[usize],
    ) -> [Color<F>; BATCH]
    where
        R: Rng + ?Sized,
        M: Material<F, R>,
    {
        let n = rays.len();
        assert!(
            n <= BATCH && slots.len() >= n,
            "a batch holds at most {BATCH} rays"
        );
        self.rays += n as u64;
        let scene = self.scene;
        // Intersect every ray first: the searches are independent, so they overlap.
        let hits: [_; BATCH] = std::array::from_fn(|i| rays.get(i).and_then(|r| scene.hit(r, F::infinity())));
        let mut colours = [Color::zero(); BATCH];
        // The rays that go on: where from (`from[k]`), their direct light and attenuation.
        let (mut next, mut from, mut m) = ([rays[0]; BATCH], [0usize; BATCH], 0);
        let (mut direct, mut attenuation) = ([Color::zero(); BATCH], [Color::zero(); BATCH]);
        for (i, hit) in hits.into_iter().enumerate().take(n) {
            let ray = &rays[i];
            let Some((hit, material)) = hit else {
                colours[i] = scene.background().color(ray.direction);
                continue;
            };
            if depth >= self.max_depth {
                continue;
            }
            let light = match material.diffuse_albedo() {
                Some(albedo) if !scene.lights().is_empty() => self.direct_light(&hit, albedo),
                _ => Color::zero(),
            };
            match material.scatter(ray, &hit, &mut *rngs[slots[i]]) {
                Some(s) => {
                    (next[m], from[m]) = (hit.spawn(s.direction), i);
                    (direct[m], attenuation[m]) = (light, s.attenuation);
                    m += 1;
                }
                None => colours[i] = saturate(light),
            }
        }
        if m > 0 {
            let next_slots: [usize; BATCH] = std::array::from_fn(|k| slots[from[k]]);
            let incoming = self.trace_batch(&next[..m], depth + 1, rngs, &next_slots[..m]);
            for k in 0..m {
                colours[from[k]] = saturate(direct[k] + attenuation[k] * incoming[k]);
            }
        }
        colours
    }

    /// Light arriving straight from the point lights at a matte hit with albedo `A`:
    /// `Σ A/π · I · max(0, N·L) / d²` over the lights a shadow ray reaches unblocked.
    fn direct_light(&mut self, hit: &Hit<F>, albedo: Color<F>) -> Color<F> {
        let brdf = albedo * (F::one() / lit::<F>(std::f64::consts::PI));
        let mut sum = Color::zero();
        // Shadow rays leave on the normal's side: one offset origin serves every light.
        let origin = crate::shape::offset_ray_origin(hit.point, hit.error, hit.normal, hit.normal);
        for light in self.scene.lights() {
            let to_light = light.position() - origin;
            let dist2 = to_light.length_squared();
            let Some(dir) = to_light.try_normalize() else {
                continue;
            };
            let cos = hit.normal.dot(dir);
            if cos <= F::zero() {
                continue;
            }
            self.rays += 1;
            if !self.scene.occluded(&Ray::new(origin, dir), dist2.sqrt()) {
                sum = sum + brdf * light.intensity() * (cos / dist2);
            }
        }
        sum
    }
}
