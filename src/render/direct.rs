//! Direct light at a surface with a non-delta lobe: from every delta light (point, spot,
//! directional), and from one sampled emitter (next-event estimation), each through the
//! material's [`eval`](Material::eval).

use super::shadow::Shadow;
use super::trace::Tracer;
use crate::float::{Float, lit};
use crate::light::{Emitters, Incident, power_heuristic};
use crate::material::{Lobes, Material};
use crate::ray::Ray;
use crate::sampling::uniform;
use crate::scene::Layout;
use crate::shape::Hit;
use crate::vec3::{Color, Vec3};
use rand::Rng;

impl<F: Float, S: Layout<F>, M: Material<F>> Tracer<'_, F, S, M> {
    /// Light arriving straight from the scene's lights at `hit`, seen from `wo`:
    /// `Σ f(wo, wi)·|cos θᵢ| · I/d²` over the lights a shadow ray reaches unblocked, each
    /// light's [`Incident`] giving `wi`, the shadow ray's length and `I/d²` (`E/1` for a
    /// light at infinity), computed as `(colour ∘ I)·(scale/d²)` from the material's
    /// [`Eval`](crate::material::Eval) (for the Lambertian `(A/π ∘ I)·(cos θ/d²)`, the
    /// specification's extra). With [`Tracer::defer`] each light's shadow ray waits in
    /// [`Tracer::shadows`] instead, with its term, and the sum is 0.
    pub(super) fn direct_light<B: Material<F> + ?Sized>(
        &mut self,
        hit: &Hit<F>,
        material: &B,
        wo: Vec3<F>,
    ) -> Color<F> {
        let mut sum = Color::zero();
        // Shadow rays leave on the normal's side; a light on the other side (seen through
        // a transmitting lobe) gets an origin on that side.
        let above = hit.offset_origin(hit.normal);
        let transmits = material.lobes().contains(Lobes::TRANSMISSION);
        for light in self.scene.lights() {
            let Some((
                origin,
                Incident {
                    direction: dir,
                    distance,
                    intensity,
                    falloff,
                },
            )) = toward(
                hit,
                above,
                transmits,
                #[inline(always)]
                |x| light.incident(x),
                |i| i.direction,
            )
            else {
                continue;
            };
            if !hit.sides_agree(dir) {
                continue;
            }
            let Some(f) = material.eval(hit, wo, dir) else {
                continue;
            };
            self.rays += 1;
            let ray = Ray::new(origin, dir);
            let light = f.colour * intensity * (f.scale / falloff);
            if self.defer {
                self.shadows.push(Shadow {
                    ray,
                    reach: distance,
                    aimed: None,
                    light,
                    sampled: false,
                });
            } else if !self.scene.occluded(&ray, distance) {
                sum = sum + light;
            }
        }
        sum
    }

    /// One sample of the light the emitters (and a background that is a light) send to
    /// `hit`, seen from `wo`, weighted against the scattered ray that could find the same
    /// light:
    ///
    /// `L = f·|cos θᵢ| · L_e · w / p_e`, `p_e = P·p_ω`, `w = p_e²/(p_e² + p_s²)`,
    ///
    /// for a light chosen with probability `P` (the background with the tracer's `sky`,
    /// else emitter `k` with `(1 − sky)·P_k`, [`Emitters::choose`]), a direction toward it
    /// drawn with density `p_ω` per solid angle ([`Hittable::sample`](crate::Hittable::sample),
    /// [`Background::sample`](crate::Background::sample)), and `p_s` the material's
    /// [`pdf`](Material::pdf) of that direction; 0 if a shadow ray finds anything in
    /// between, or an emitter shows the hit its back. The shadow ray is returned with the
    /// light, to be traced later ([`Shadow`]); `None` where no light can arrive.
    ///
    /// Always draws four numbers (one to choose, three for the point), so the random
    /// stream does not depend on decisions f32 and f64 may take differently.
    pub(super) fn sample_light<R, B>(
        &mut self,
        hit: Hit<F>,
        material: &B,
        wo: Vec3<F>,
        emitters: &Emitters,
        rng: &mut R,
    ) -> Option<Shadow<F>>
    where
        R: Rng + ?Sized,
        B: Material<F> + ?Sized,
    {
        let choice = uniform(rng);
        let u = [uniform(rng), uniform(rng), uniform(rng)];
        if choice < self.sky {
            return self.sample_background(&hit, material, wo, [u[0], u[1]]);
        }
        // The same `choice` as without a background (`sky = 0`): `(c − 0)/(1 − 0) = c`.
        let (index, chosen) = emitters.choose((choice - self.sky) / (1.0 - self.sky));
        let object = &self.scene.objects()[index];
        let emission = self.scene.material(object.material).emits()?;
        let above = hit.offset_origin(hit.normal);
        let sample = object.shape.sample(above, u)?;
        let transmits = material.lobes().contains(Lobes::TRANSMISSION);
        let aim = |x| crate::light::aim(x, sample.point).map(|(dir, _)| dir);
        let (origin, dir) = toward(&hit, above, transmits, aim, |&dir| dir)?;
        let radiance = emission.toward(dir.dot(sample.normal) < F::zero());
        let light_pdf = F::from_f64((1.0 - self.sky) * chosen) * sample.pdf;
        if radiance == Color::zero() || !(light_pdf > F::zero() && light_pdf.is_finite()) {
            return None;
        }
        let f = hit
            .sides_agree(dir)
            .then(|| material.eval(&hit, wo, dir))
            .flatten()?;
        // The shadow ray stops where the scene's own intersection meets the emitter's part
        // (bit for bit the same `t`): the open interval `(0, t)` leaves the emitter out. A
        // direction that rounding takes just past the part's edge finds no light. Where
        // the batch walks a tree, that `t` is left to the walk, which meets the part anyway
        // (`Scene::occluded_all`); the reach is then a bound a little past the point.
        let ray = Ray::new(origin, dir);
        let (reach, aimed) = if self.defer {
            let past = (sample.point - origin).length() * lit::<F>(1.0 + 1.0 / 256.0);
            (past, Some((index as u32, sample.part)))
        } else {
            let at = object.shape.intersect_part(sample.part, &ray, F::infinity())?;
            (at.t, None)
        };
        self.rays += 1;
        let weight = power_heuristic(light_pdf, material.pdf(&hit, wo, dir));
        Some(Shadow {
            ray,
            reach,
            aimed,
            light: f.colour * radiance * (f.scale * weight / light_pdf),
            sampled: true,
        })
    }

    /// [`sample_light`](Self::sample_light)'s background branch: a direction drawn from the
    /// background by its own density, the light it sends if no shadow ray to infinity is
    /// blocked.
    fn sample_background<B: Material<F> + ?Sized>(
        &mut self,
        hit: &Hit<F>,
        material: &B,
        wo: Vec3<F>,
        u: [f64; 2],
    ) -> Option<Shadow<F>> {
        let background = self.scene.background();
        let (dir, pdf) = background.sample(u)?;
        let light_pdf = F::from_f64(self.sky) * pdf;
        let transmits = material.lobes().contains(Lobes::TRANSMISSION);
        let origin = if dir.dot(hit.normal) >= F::zero() {
            hit.offset_origin(hit.normal)
        } else if transmits {
            hit.offset_origin(dir)
        } else {
            return None;
        };
        if !(light_pdf > F::zero() && light_pdf.is_finite() && hit.sides_agree(dir)) {
            return None;
        }
        let f = material.eval(hit, wo, dir)?;
        self.rays += 1;
        let weight = power_heuristic(light_pdf, material.pdf(hit, wo, dir));
        Some(Shadow {
            ray: Ray::new(origin, dir),
            reach: F::infinity(),
            aimed: None,
            light: f.colour * background.color(dir) * (f.scale * weight / light_pdf),
            sampled: true,
        })
    }
}

/// The origin of a shadow ray from `hit` and what `aim` finds from there (its direction
/// read by `direction`): from `above` (the origin offset to the normal's side) when the
/// direction found from it lies on that side, else, for a material that `transmits`, from
/// an origin offset to the other side, aimed again. `None` if `aim` finds nothing, or no
/// light can come from where it points.
#[inline(always)]
fn toward<F: Float, T>(
    hit: &Hit<F>,
    above: Vec3<F>,
    transmits: bool,
    aim: impl Fn(Vec3<F>) -> Option<T>,
    direction: impl Fn(&T) -> Vec3<F>,
) -> Option<(Vec3<F>, T)> {
    let found = aim(above)?;
    let dir = direction(&found);
    if dir.dot(hit.normal) >= F::zero() {
        Some((above, found))
    } else if transmits {
        // Always inlined: out of line the hit goes by reference, which keeps every hit in
        // memory.
        let below = hit.offset_origin(dir);
        Some((below, aim(below)?))
    } else {
        None
    }
}
