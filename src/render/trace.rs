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
    pub fn trace<R>(&mut self, ray: &Ray<F>, depth: u32, rng: &mut R) -> Color<F>
    where
        R: Rng + ?Sized,
        M: Material<F, R>,
    {
        self.rays += 1;
        let Some((hit, material)) = self.scene.hit(ray, F::infinity()) else {
            return self.scene.background().color(ray.direction);
        };
        if depth >= self.max_depth {
            return Color::zero();
        }
        let direct = match material.diffuse_albedo() {
            Some(albedo) if !self.scene.lights().is_empty() => self.direct_light(&hit, albedo),
            _ => Color::zero(),
        };
        let colour = match material.scatter(ray, &hit, rng) {
            Some(s) => direct + s.attenuation * self.trace(&hit.spawn(s.direction), depth + 1, rng),
            None => direct,
        };
        saturate(colour)
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
