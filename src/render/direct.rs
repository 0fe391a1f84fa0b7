//! Direct light at a matte hit: from every point light, and from one sampled emitter
//! (next-event estimation).

use super::trace::{Tracer, cosine_pdf};
use crate::float::{Float, lit};
use crate::light::{Emitters, power_heuristic};
use crate::material::Material;
use crate::ray::Ray;
use crate::sampling::uniform;
use crate::scene::Layout;
use crate::shape::{Hit, offset_ray_origin};
use crate::vec3::Color;
use rand::Rng;
use std::f64::consts::FRAC_1_PI;

impl<F: Float, S: Layout<F>, M> Tracer<'_, F, S, M> {
    /// Light arriving straight from the point lights at a matte hit with albedo `A`:
    /// `Σ A/π · I · max(0, N·L) / d²` over the lights a shadow ray reaches unblocked.
    pub(super) fn direct_light(&mut self, hit: &Hit<F>, albedo: Color<F>) -> Color<F> {
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

    /// One sample of the light the emitters send to a matte hit with albedo `A`, weighted
    /// against the scattered ray that could find the same light:
    ///
    /// `L = A/π · L_e · cos θ · w / p_e`, `p_e = P_k·p_ω`, `w = p_e²/(p_e² + p_s²)`,
    ///
    /// for emitter `k` chosen with probability `P_k` ([`Emitters::choose`]), a point of it
    /// drawn with density `p_ω` per solid angle ([`Hittable::sample`]), `θ` the angle at
    /// the hit and `p_s = cos θ/π` the density of a scattered ray in that direction; 0 if
    /// a shadow ray finds anything in between, or the emitter shows the hit its back.
    ///
    /// Always draws four numbers (one to choose, three for the point), so the random
    /// stream does not depend on decisions f32 and f64 may take differently.
    pub(super) fn sample_emitter<R>(
        &mut self,
        hit: &Hit<F>,
        albedo: Color<F>,
        emitters: &Emitters,
        rng: &mut R,
    ) -> Color<F>
    where
        R: Rng + ?Sized,
        M: Material<F, R>,
    {
        let choice = uniform(rng);
        let u = [uniform(rng), uniform(rng), uniform(rng)];
        let (index, chosen) = emitters.choose(choice);
        let object = &self.scene.objects()[index];
        let Some(emission) = object.material.emission() else {
            return Color::zero();
        };
        let origin = offset_ray_origin(hit.point, hit.error, hit.normal, hit.normal);
        let Some(sample) = object.shape.sample(origin, u) else {
            return Color::zero();
        };
        let Some(dir) = (sample.point - origin).try_normalize() else {
            return Color::zero();
        };
        let cos = hit.normal.dot(dir);
        let radiance = emission.toward(dir.dot(sample.normal) < F::zero());
        let light_pdf = F::from_f64(chosen) * sample.pdf;
        if cos <= F::zero() || radiance == Color::zero() || !(light_pdf > F::zero() && light_pdf.is_finite())
        {
            return Color::zero();
        }
        // The shadow ray stops where the scene's own intersection meets the emitter's part
        // (bit for bit the same `t`): the open interval `(0, t)` leaves the emitter out. A
        // direction that rounding takes just past the part's edge finds no light.
        let shadow = Ray::new(origin, dir);
        let Some(at) = object.shape.intersect_part(sample.part, &shadow, F::infinity()) else {
            return Color::zero();
        };
        self.rays += 1;
        if self.scene.occluded(&shadow, at.t) {
            return Color::zero();
        }
        let weight = power_heuristic(light_pdf, cosine_pdf(hit.normal, dir));
        albedo * radiance * (cos * F::from_f64(FRAC_1_PI) * weight / light_pdf)
    }
}
