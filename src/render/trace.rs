//! The specification's recursive trace: what one ray brings back.

use crate::float::{Float, lit};
use crate::material::Material;
use crate::ray::Ray;
use crate::scene::Layout;
use crate::scene::Scene;
use crate::shape::{Hit, offset_ray_origin};
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

/// One bounce's outcome: the ray's colour, or the next ray with the direct light and the
/// attenuation that combine with the colour it brings back.
pub(super) enum Step<F> {
    Done(Color<F>),
    Go(Ray<F>, Color<F>, Color<F>),
}

/// Traces rays through one scene and counts them.
pub struct Tracer<'a, F, S, M> {
    pub(super) scene: &'a Scene<F, S, M>,
    max_depth: u32,
    pub(super) rays: u64,
}

impl<'a, F: Float, S: Layout<F>, M> Tracer<'a, F, S, M> {
    /// A tracer for `scene` that lets paths bounce at most `max_depth` times.
    pub fn new(scene: &'a Scene<F, S, M>, max_depth: u32) -> Self {
        Self {
            scene,
            max_depth,
            rays: 0,
        }
    }

    /// Rays traced so far (camera, scattered and shadow).
    #[must_use]
    pub fn rays(&self) -> u64 {
        self.rays
    }

    /// The colour a ray brings back, `depth` being the bounces it has already taken:
    ///
    /// - it hits nothing: the background;
    /// - it hits a surface after `max_depth` bounces: black `(0, 0, 0)`;
    /// - otherwise: the direct light `L_d` from point lights (matte surfaces only) plus
    ///   the scattered ray's colour absorbed by the albedo,
    ///   `C = L_d + A ∘ trace(scattered, depth + 1)`, or just `L_d` if the material
    ///   absorbs the ray.
    ///
    /// This recursion defines every image: [`render_reference`](super::render_reference)
    /// calls it for each sample, and the batched renderer reproduces it bit for bit.
    pub fn trace<R>(&mut self, ray: &Ray<F>, depth: u32, rng: &mut R) -> Color<F>
    where
        R: Rng + ?Sized,
        M: Material<F, R>,
    {
        self.rays += 1;
        let hit = self.scene.hit(ray, F::infinity());
        match self.shade(ray, hit, depth, rng) {
            Step::Done(colour) => colour,
            Step::Go(next, direct, attenuation) => {
                saturate(direct + attenuation * self.trace(&next, depth + 1, rng))
            }
        }
    }

    /// What a ray's hit (or miss) does: a final colour, or the ray to trace next with the
    /// direct light and attenuation to combine with what it brings back.
    #[inline(always)]
    pub(super) fn shade<R>(
        &mut self,
        ray: &Ray<F>,
        hit: Option<(Hit<F>, &M)>,
        depth: u32,
        rng: &mut R,
    ) -> Step<F>
    where
        R: Rng + ?Sized,
        M: Material<F, R>,
    {
        let Some((hit, material)) = hit else {
            return Step::Done(self.scene.background().color(ray.direction));
        };
        if depth >= self.max_depth {
            return Step::Done(Color::zero());
        }
        let direct = match material.diffuse_albedo() {
            Some(albedo) if !self.scene.lights().is_empty() => self.direct_light(&hit, albedo),
            _ => Color::zero(),
        };
        match material.scatter(ray, &hit, rng) {
            Some(s) => Step::Go(hit.spawn(s.direction), direct, s.attenuation),
            None => Step::Done(saturate(direct)),
        }
    }

    /// Light arriving straight from the point lights at a matte hit with albedo `A`:
    /// `Σ A/π · I · max(0, N·L) / d²` over the lights a shadow ray reaches unblocked.
    fn direct_light(&mut self, hit: &Hit<F>, albedo: Color<F>) -> Color<F> {
        let brdf = albedo * (F::one() / lit::<F>(std::f64::consts::PI));
        let mut sum = Color::zero();
        // Shadow rays leave on the normal's side: one offset origin serves every light.
        let origin = offset_ray_origin(hit.point, hit.error, hit.normal, hit.normal);
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
