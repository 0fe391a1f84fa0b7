//! The specification's recursive trace: what one ray brings back.

use super::settings::LightSampling;
use crate::float::Float;
use crate::light::{Emitters, power_heuristic};
use crate::material::{Emission, Scatter};
use crate::ray::Ray;
use crate::scene::{Layout, Object, Scene};
use crate::shape::Hit;
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

/// One bounce's outcome: the ray's colour, or the ray to trace next.
pub(super) enum Step<F> {
    /// The path ends here with this colour.
    Done(Color<F>),
    /// The path goes on: the colour is `direct + weight ∘ (what ray brings back)`.
    Go {
        /// The next ray.
        ray: Ray<F>,
        /// The light this bounce adds, `L_e + L_d`.
        direct: Color<F>,
        /// The sample's weight, `f·|cos θ|/pdf` (the albedo, for the spec's materials).
        weight: Color<F>,
        /// How the next ray left this vertex.
        arrival: Arrival<F>,
    },
}

/// How a ray left the vertex before it: the per-path state the weight of the emitted
/// light it finds depends on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Arrival<F> {
    /// No emitter was sampled where it started (a camera ray, a delta lobe's direction,
    /// no emitters, [`LightSampling::Bsdf`], or the depth left no room): the light it finds
    /// counts in full.
    Unweighted,
    /// Scattered by a non-delta lobe of a surface that also sampled an emitter, with this
    /// density per unit solid angle (the material's [`pdf`](crate::Material::pdf)): the light it
    /// finds is weighted against that sample.
    Scattered(F),
}

/// Traces rays through one scene and counts them.
pub struct Tracer<'a, F, S, M> {
    pub(super) scene: &'a Scene<F, S, M>,
    max_depth: u32,
    light_sampling: LightSampling,
    pub(super) rays: u64,
}

impl<'a, F: Float, S: Layout<F>, M> Tracer<'a, F, S, M> {
    /// A tracer for `scene` that lets paths bounce at most `max_depth` times, sampling
    /// emitters with [`LightSampling::Mis`].
    pub fn new(scene: &'a Scene<F, S, M>, max_depth: u32) -> Self {
        Self {
            scene,
            max_depth,
            light_sampling: LightSampling::Mis,
            rays: 0,
        }
    }

    /// The same tracer, finding the light of emitting surfaces by `light_sampling`.
    #[must_use]
    pub fn light_sampling(self, light_sampling: LightSampling) -> Self {
        Self {
            light_sampling,
            ..self
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
    /// - it hits a surface after `max_depth` bounces: black `(0, 0, 0)`, emitter or not;
    /// - otherwise the light the surface gives off `L_e`, the direct light `L_d` (from
    ///   point lights and one sampled emitter, through the material's non-delta lobes) and
    ///   the scattered ray's colour times the sample's weight (`A`, the albedo, for the
    ///   specification's materials),
    ///
    ///   `C = L_e + L_d + w ∘ trace(scattered, depth + 1)`, `w = f·|cos θ|/pdf`,
    ///
    ///   or `L_e + L_d` if the material absorbs the ray.
    ///
    /// With emitters sampled ([`LightSampling::Mis`]), the light from an emitter reaches a
    /// surface with a non-delta lobe two ways, the sample and the scattered ray, and each
    /// is weighted by the power heuristic so the two add up to it once. The sample at depth `d` stands for the
    /// scattered ray meeting the emitter at depth `d + 1`, so it is taken only if
    /// `d + 1 < max_depth`, where that ray's light would count: both ways then render the
    /// same truncated recursion. Point lights, which no ray can hit, light every surface
    /// met before `max_depth`.
    ///
    /// This recursion defines every image: [`render_reference`](super::render_reference)
    /// calls it for each sample, and the batched renderer reproduces it bit for bit.
    pub fn trace<R>(&mut self, ray: &Ray<F>, depth: u32, rng: &mut R) -> Color<F>
    where
        R: Rng + ?Sized,
        M: Scatter<F, R>,
    {
        self.trace_from(ray, depth, Arrival::Unweighted, rng)
    }

    /// [`Tracer::trace`] for a ray that left its last vertex as `arrival` says.
    fn trace_from<R>(&mut self, ray: &Ray<F>, depth: u32, arrival: Arrival<F>, rng: &mut R) -> Color<F>
    where
        R: Rng + ?Sized,
        M: Scatter<F, R>,
    {
        self.rays += 1;
        let hit = self.scene.hit_object(ray, F::infinity());
        match self.shade(ray, hit, depth, arrival, rng) {
            Step::Done(colour) => colour,
            Step::Go {
                ray,
                direct,
                weight,
                arrival,
            } => saturate(direct + weight * self.trace_from(&ray, depth + 1, arrival, rng)),
        }
    }

    /// What a ray's hit (or miss) does: a final colour, or the ray to trace next with the
    /// light this bounce adds (`L_e + L_d`) and the weight to combine with what it brings
    /// back. Random numbers are drawn in one order: the emitter sample's four, then the
    /// material's. Only the material's [`lobes`](crate::Material::lobes), [`eval`](crate::Material::eval),
    /// [`pdf`](crate::Material::pdf), [`emits`](crate::Material::emits) and [`sample`](Scatter::sample)
    /// are asked, never what kind of material it is.
    #[inline(always)]
    pub(super) fn shade<R>(
        &mut self,
        ray: &Ray<F>,
        hit: Option<(Hit<F>, &Object<S, M>)>,
        depth: u32,
        arrival: Arrival<F>,
        rng: &mut R,
    ) -> Step<F>
    where
        R: Rng + ?Sized,
        M: Scatter<F, R>,
    {
        let Some((hit, object)) = hit else {
            return Step::Done(self.scene.background().color(ray.direction));
        };
        // The hit goes by value to the calls below that are not inlined (lights,
        // emission): a copy made in their branches keeps it out of memory on every other
        // path (+4 % instructions on the spec's scenes when it escaped by reference).
        if depth >= self.max_depth {
            return Step::Done(Color::zero());
        }
        let material = &object.material;
        let wo = -ray.direction;
        let emitters = self.scene.emitters();
        let mut direct = match material.emits() {
            Some(emission) => self.emitted(ray, hit, object, emission, arrival, emitters),
            None => Color::zero(),
        };
        // Seen from a side its shading normal faces away from, a surface reflects nothing
        // (see `Material`'s "Shading normals").
        if !hit.sides_agree(wo) {
            return Step::Done(saturate(direct));
        }
        let lit = material.lobes().has_non_delta();
        if lit && !self.scene.lights().is_empty() {
            direct = self.direct_light(&hit, material, wo) + direct;
        }
        // An emitter sample here stands for a scattered ray meeting it at depth + 1.
        let sampled = lit && self.samples_emitters(emitters, depth);
        if sampled {
            direct = direct + self.sample_emitter(hit, material, wo, emitters, rng);
        }
        match material.sample(&hit, wo, rng) {
            Some(s) if hit.sides_agree(s.direction) => Step::Go {
                ray: hit.spawn(s.direction),
                direct,
                weight: s.weight,
                arrival: if sampled && !s.lobe.is_delta() {
                    Arrival::Scattered(s.pdf)
                } else {
                    Arrival::Unweighted
                },
            },
            _ => Step::Done(saturate(direct)),
        }
    }

    /// Whether a hit at `depth` on a surface with a non-delta lobe samples an emitter:
    /// light sampling is on, there is an emitter, and a ray scattered from here would still
    /// count the light it finds.
    #[inline]
    fn samples_emitters(&self, emitters: &Emitters, depth: u32) -> bool {
        self.light_sampling == LightSampling::Mis && !emitters.is_empty() && depth + 1 < self.max_depth
    }

    /// The light an emitter gives off toward the ray that hit it: `L_e` on an emitting
    /// face, weighted, if the ray was scattered from a vertex that also sampled emitters, by
    /// `w = p_s²/(p_s² + p_e²)`: `p_s` the density the ray was scattered with and `p_e`
    /// the density with which sampling the emitters from its origin draws this direction
    /// (the emitter's probability times its shape's density).
    fn emitted(
        &self,
        ray: &Ray<F>,
        hit: Hit<F>,
        object: &Object<S, M>,
        emission: Emission<F>,
        arrival: Arrival<F>,
        emitters: &Emitters,
    ) -> Color<F> {
        let radiance = emission.toward(hit.front_face);
        match arrival {
            Arrival::Scattered(scatter_pdf) if radiance != Color::zero() => {
                let chosen = F::from_f64(emitters.probability_of(object.shape.area(), emission));
                let light_pdf = chosen * object.shape.pdf(ray, &hit);
                radiance * power_heuristic(scatter_pdf, light_pdf)
            }
            _ => radiance,
        }
    }
}
