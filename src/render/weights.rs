//! The light a ray finds by itself, the background it escapes to or the emitter it hits,
//! weighted against the light sample of the vertex it left (multiple importance sampling).

use super::trace::{Arrival, Tracer};
use crate::float::Float;
use crate::light::{Emitters, power_heuristic};
use crate::material::Emission;
use crate::ray::Ray;
use crate::scene::{Layout, Object};
use crate::shape::Hit;
use crate::vec3::Color;

impl<F: Float, S: Layout<F>, M> Tracer<'_, F, S, M> {
    /// The colour of a ray that escapes after `depth` bounces: the background's. Where the
    /// background is a light it counts only before `max_depth` bounces, and, if the ray was
    /// scattered from a vertex that also sampled lights, it is weighted by
    /// `w = p_s²/(p_s² + p_b²)`, `p_b` the density with which that vertex's light sample
    /// draws the direction (the probability of drawing the background times its density).
    #[inline]
    pub(super) fn escaped(&self, ray: &Ray<F>, depth: u32, arrival: Arrival<F>) -> Color<F> {
        let background = self.scene.background();
        if !self.scene.background_sampled() {
            return background.color(ray.direction);
        }
        if depth >= self.max_depth {
            return Color::zero();
        }
        let colour = background.color(ray.direction);
        match arrival {
            Arrival::Scattered(scatter_pdf) if self.sky > 0.0 => {
                let light_pdf = F::from_f64(self.sky) * background.pdf(ray.direction);
                colour * power_heuristic(scatter_pdf, light_pdf)
            }
            _ => colour,
        }
    }

    /// The light an emitter gives off toward the ray that hit it: `L_e` on an emitting
    /// face, weighted, if the ray was scattered from a vertex that also sampled emitters, by
    /// `w = p_s²/(p_s² + p_e²)`: `p_s` the density the ray was scattered with and `p_e`
    /// the density with which sampling the lights from its origin draws this direction
    /// (the probability of drawing an emitter at all, this emitter's, and its shape's
    /// density).
    pub(super) fn emitted(
        &self,
        ray: &Ray<F>,
        hit: Hit<F>,
        object: &Object<S>,
        emission: Emission<F>,
        arrival: Arrival<F>,
        emitters: &Emitters,
    ) -> Color<F> {
        let radiance = emission.toward(hit.front_face);
        match arrival {
            Arrival::Scattered(scatter_pdf) if radiance != Color::zero() => {
                let chosen =
                    F::from_f64((1.0 - self.sky) * emitters.probability_of(object.shape.area(), emission));
                let light_pdf = chosen * object.shape.pdf(ray, &hit);
                radiance * power_heuristic(scatter_pdf, light_pdf)
            }
            _ => radiance,
        }
    }
}
