//! The specification's recursive trace: what one ray brings back.

use super::settings::LightSampling;
use super::shadow::{Shadow, arrive};
use crate::float::Float;
use crate::light::Emitters;
use crate::material::{BsdfVisitor, Material, Scatter};
use crate::ray::Ray;
use crate::scene::{HitOn, Layout, Object, Scene};
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
    /// The path ends here with the light this bounce adds, `L_e + L_d`, saturated
    /// ([`saturate`]): this, and the light of the shadow rays left waiting in
    /// [`Tracer::shadows`] that arrive.
    Lit(Color<F>),
    /// The path goes on: the colour is `direct + weight ∘ (what ray brings back)`.
    Go {
        /// The next ray.
        ray: Ray<F>,
        /// The light this bounce adds, `L_e + L_d`, but that of the shadow rays left
        /// waiting in [`Tracer::shadows`], which adds to it where they arrive.
        direct: Color<F>,
        /// The sample's weight, `f·|cos θ|/pdf` (the albedo, for the spec's materials).
        weight: Color<F>,
        /// How the next ray left this vertex.
        arrival: Arrival<F>,
    },
}

/// What the recursion does after a bounce: end with a colour, or combine the light the
/// bounce adds with what the next ray brings back, `saturate(direct + weight ∘ …)`.
enum Next<F> {
    End(Color<F>),
    Go {
        ray: Ray<F>,
        direct: Color<F>,
        weight: Color<F>,
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
pub struct Tracer<'a, F: Float, S, M> {
    pub(super) scene: &'a Scene<F, S, M>,
    pub(super) max_depth: u32,
    light_sampling: LightSampling,
    /// The probability that a light sample draws the background (0 unless the scene makes
    /// it a light, [`Scene::set_background_sampled`]); an emitter otherwise.
    pub(super) sky: f64,
    pub(super) rays: u64,
    /// Whether shading leaves its shadow rays waiting in [`Tracer::shadows`] (the batch's
    /// choice where it walks a tree) rather than tracing each at once.
    pub(super) defer: bool,
    /// The shadow rays the bounce last shaded ([`Tracer::shade`]) left waiting, with the
    /// light each brings; whoever shades empties it. Kept here, not in the [`Step`], so
    /// that the steps stay as small as they were.
    pub(super) shadows: Vec<Shadow<F>>,
}

impl<'a, F: Float, S: Layout<F>, M: Material<F>> Tracer<'a, F, S, M> {
    /// A tracer for `scene` that lets paths bounce at most `max_depth` times, sampling
    /// emitters with [`LightSampling::Mis`].
    ///
    /// A background the scene makes a light is drawn with probability ½ when there are
    /// emitters too (each kind then has the samples it needs wherever the other is dim),
    /// and always when there are none.
    pub fn new(scene: &'a Scene<F, S, M>, max_depth: u32) -> Self {
        let sky = match (
            scene.background_sampled() && !scene.background().is_black(),
            scene.emitters().is_empty(),
        ) {
            (false, _) => 0.0,
            (true, true) => 1.0,
            (true, false) => 0.5,
        };
        Self {
            scene,
            max_depth,
            light_sampling: LightSampling::Mis,
            sky,
            rays: 0,
            defer: false,
            shadows: Vec::new(),
        }
    }
}

impl<'a, F: Float, S: Layout<F>, M> Tracer<'a, F, S, M> {
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
    /// - it hits nothing: the background (where the scene makes the background a light,
    ///   only before `max_depth` bounces, and weighted against the background's sample as
    ///   an emitter's light is);
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
    /// met before `max_depth` (where the background is a light, as every light then, only
    /// where `d + 1 < max_depth`).
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
        match self.bounce(ray, depth, arrival, rng) {
            Next::End(colour) => colour,
            Next::Go {
                ray,
                direct,
                weight,
                arrival,
            } => saturate(direct + weight * self.trace_from(&ray, depth + 1, arrival, rng)),
        }
    }

    /// One bounce of [`Tracer::trace_from`], any shadow rays it left waiting traced. Out of
    /// line, so that each level of the recursion keeps only what crosses it on the stack
    /// ([`Next`]), not the shading's state: the deepest recursion allowed must fit on a
    /// worker thread's stack.
    #[inline(never)]
    fn bounce<R>(&mut self, ray: &Ray<F>, depth: u32, arrival: Arrival<F>, rng: &mut R) -> Next<F>
    where
        R: Rng + ?Sized,
        M: Scatter<F, R>,
    {
        self.rays += 1;
        let hit = self.scene.hit_object(ray, F::infinity());
        let step = self.shade(ray, hit, depth, arrival, rng);
        match step {
            Step::Done(colour) => Next::End(colour),
            Step::Lit(direct) => Next::End(saturate(self.arrived(direct))),
            Step::Go {
                ray,
                direct,
                weight,
                arrival,
            } => Next::Go {
                ray,
                direct: self.arrived(direct),
                weight,
                arrival,
            },
        }
    }

    /// `direct` with the light of the shadow rays left waiting ([`Tracer::shadows`]) that
    /// arrive, each traced now; none wait unless [`Tracer::defer`] is set.
    fn arrived(&mut self, direct: Color<F>) -> Color<F> {
        if self.shadows.is_empty() {
            return direct;
        }
        let scene = self.scene;
        let shadows = &self.shadows;
        let direct = arrive(direct, shadows, |i| {
            scene.occluded(&shadows[i].ray, shadows[i].reach)
        });
        self.shadows.clear();
        direct
    }

    /// What a ray's hit (or miss) does: a final colour, or the ray to trace next with the
    /// light this bounce adds (`L_e + L_d`) and the weight to combine with what it brings
    /// back; with [`Tracer::defer`], the light of every shadow ray waits in
    /// [`Tracer::shadows`]. Random
    /// numbers are drawn in one order: the light sample's four, then the material's. Only the material's [`lobes`](crate::Material::lobes), [`eval`](crate::Material::eval),
    /// [`pdf`](crate::Material::pdf), [`emits`](crate::Material::emits) and [`sample`](Scatter::sample)
    /// are asked, of the material it [resolves](Scatter::resolve) to at the hit, never what
    /// kind of material it is.
    #[inline(always)]
    pub(super) fn shade<R>(
        &mut self,
        ray: &Ray<F>,
        hit: Option<HitOn<'_, F, S, M>>,
        depth: u32,
        arrival: Arrival<F>,
        rng: &mut R,
    ) -> Step<F>
    where
        R: Rng + ?Sized,
        M: Scatter<F, R>,
    {
        let Some((hit, object, material)) = hit else {
            return Step::Done(self.escaped(ray, depth, arrival));
        };
        if depth >= self.max_depth {
            return Step::Done(Color::zero());
        }
        let vertex = Vertex {
            tracer: self,
            ray,
            hit,
            object,
            depth,
            arrival,
            rng,
        };
        material.resolve(&hit, vertex)
    }

    /// [`Tracer::shade`] of a hit on `object` below `max_depth`, asking `material`, the
    /// object's material [resolved](Scatter::resolve) at the hit: static calls, one
    /// `match` on the material's kind a hit.
    // The hit goes by value to the calls below that are not inlined (emission, the light
    // sample): a copy made in their branches keeps it out of memory on every other path
    // (docs/PERFORMANCE.md).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn shade_with<R, B>(
        &mut self,
        material: &B,
        ray: &Ray<F>,
        hit: Hit<F>,
        object: &Object<S>,
        depth: u32,
        arrival: Arrival<F>,
        rng: &mut R,
    ) -> Step<F>
    where
        R: Rng + ?Sized,
        M: Material<F>,
        B: Scatter<F, R> + ?Sized,
    {
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
        // Where the background is a light, every light counts on the same paths: a point
        // light's sample at depth d stands for a segment d + 2, as an emitter's does.
        let points_count = !self.scene.background_sampled() || depth + 1 < self.max_depth;
        if lit && points_count && !self.scene.lights().is_empty() {
            direct = self.direct_light(&hit, material, wo) + direct;
        }
        // A light sample here stands for a scattered ray meeting the light at depth + 1.
        let sampled = lit && self.samples_lights(emitters, depth);
        if sampled && let Some(s) = self.sample_light(hit, material, wo, emitters, rng) {
            if self.defer {
                self.shadows.push(s);
            } else if !self.scene.occluded(&s.ray, s.reach) {
                direct = direct + s.light;
            }
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
            _ => Step::Lit(direct),
        }
    }

    /// Whether a hit at `depth` on a surface with a non-delta lobe samples a light:
    /// light sampling is on, there is an emitter or a background that is a light, and a ray
    /// scattered from here would still count the light it finds.
    #[inline]
    fn samples_lights(&self, emitters: &Emitters, depth: u32) -> bool {
        self.light_sampling == LightSampling::Mis
            && (!emitters.is_empty() || self.sky > 0.0)
            && depth + 1 < self.max_depth
    }
}

/// A hit waiting for its material: [`Tracer::shade`]'s state handed to
/// [`Scatter::resolve`], which visits it with the material that answers there.
struct Vertex<'t, 'a, F: Float, S, M, R: ?Sized> {
    tracer: &'t mut Tracer<'a, F, S, M>,
    ray: &'t Ray<F>,
    hit: Hit<F>,
    object: &'t Object<S>,
    depth: u32,
    arrival: Arrival<F>,
    rng: &'t mut R,
}

impl<F: Float, S: Layout<F>, M: Material<F>, R: Rng + ?Sized> BsdfVisitor<F, R>
    for Vertex<'_, '_, F, S, M, R>
{
    type Output = Step<F>;

    // Always inlined, whatever its size: called, it would take the hit through memory.
    #[inline(always)]
    fn visit<B: Scatter<F, R> + ?Sized>(self, material: &B) -> Step<F> {
        let Self {
            tracer,
            ray,
            hit,
            object,
            depth,
            arrival,
            rng,
        } = self;
        tracer.shade_with(material, ray, hit, object, depth, arrival, rng)
    }
}
