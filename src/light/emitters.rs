//! The scene's emitting surfaces as lights to sample, chosen in proportion to their power.

use crate::float::Float;
use crate::material::{Emission, Material};
use crate::shape::Hittable;

/// The objects of a scene that give off light and can be sampled (an emissive sphere,
/// triangle or mesh), for next-event estimation: emitter `k` is chosen with probability
/// `P_k = Φ_k/Σ Φ`, its power `Φ_k = π·L̄·s·A` (`L̄` the mean radiance of the channels, `s`
/// the emitting faces, `A` the area; [`Emission::power_per_area`]), so bright and large
/// lights get the shadow rays they deserve.
///
/// Emitters that cannot be sampled (a plane, a shape of the user's without
/// [`Hittable::sample`]) or give off nothing are left out: rays that hit them still bring
/// their light back, in full. A scene without emitters has an empty table and pays for
/// nothing but the check that it is empty.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Emitters {
    /// The emitters' objects, as indices into the scene's objects, in the scene's order.
    objects: Vec<u32>,
    /// `P_k`.
    probability: Vec<f64>,
    /// `Φ_0 + … + Φ_k`.
    cumulative: Vec<f64>,
    /// `Σ Φ`.
    total: f64,
}

impl Emitters {
    /// The emitters among a scene's objects, given as `(shape, material)` in the scene's
    /// order. If their powers sum to more than `f64` holds, none is sampled (the light is
    /// still found by the rays that hit it).
    pub(crate) fn new<'a, F, S, M>(objects: impl Iterator<Item = (&'a S, &'a M)>) -> Self
    where
        F: Float,
        S: Hittable<F> + 'a,
        M: Material<F> + 'a,
    {
        let mut table = Self::default();
        let mut powers = Vec::new();
        for (i, (shape, material)) in objects.enumerate() {
            // The emission first: a mesh sums its areas only when it is asked to.
            let Some(emission) = material.emits() else {
                continue;
            };
            if let Some(p) = power(shape.area(), emission) {
                table.total += p;
                table.objects.push(i as u32);
                table.cumulative.push(table.total);
                powers.push(p);
            }
        }
        if !table.total.is_finite() {
            return Self::default();
        }
        table.probability = powers.iter().map(|p| p / table.total).collect();
        table
    }

    /// How many emitters are sampled.
    pub fn len(&self) -> usize {
        self.objects.len()
    }

    /// Whether no emitter is sampled (then no light is sampled either).
    pub fn is_empty(&self) -> bool {
        self.objects.is_empty()
    }

    /// The emitters' objects, as indices into the scene's objects.
    pub fn objects(&self) -> &[u32] {
        &self.objects
    }

    /// The probability `P_k` of each emitter, in the order of [`Emitters::objects`].
    pub fn probabilities(&self) -> &[f64] {
        &self.probability
    }

    /// The emitter `u ∈ [0, 1)` chooses, as the index of its object and its probability:
    /// the first `k` whose running sum of powers exceeds `u·ΣΦ` (a binary search).
    ///
    /// # Panics
    /// If there are no emitters.
    #[inline]
    pub fn choose(&self, u: f64) -> (usize, f64) {
        let target = u * self.total;
        let k = self.cumulative.partition_point(|&c| c <= target);
        let k = k.min(self.objects.len() - 1);
        (self.objects[k] as usize, self.probability[k])
    }

    /// The probability that [`Emitters::choose`] picks an object of this area and emission:
    /// the same number it returns for it (the same arithmetic), 0 if it is not sampled.
    #[inline]
    pub fn probability_of<F: Float>(&self, area: Option<F>, emission: Emission<F>) -> f64 {
        match power(area, emission) {
            Some(p) if !self.is_empty() => p / self.total,
            _ => 0.0,
        }
    }
}

/// `Φ = π·L̄·s·A`, if the shape can be sampled and `Φ` is finite and positive.
fn power<F: Float>(area: Option<F>, emission: Emission<F>) -> Option<f64> {
    let p = emission.power_per_area() * area?.to_f64();
    (p.is_finite() && p > 0.0).then_some(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::{Emissive, Lambertian, MaterialKind};
    use crate::shape::{Plane, ShapeKind, Sphere, Triangle};
    use crate::vec3::Vec3;

    /// A scene's object, as `Emitters::new` sees it.
    type Object = (ShapeKind<f64>, MaterialKind<f64>);

    fn object(shape: impl Into<ShapeKind<f64>>, material: impl Into<MaterialKind<f64>>) -> Object {
        (shape.into(), material.into())
    }

    fn table(objects: &[Object]) -> Emitters {
        Emitters::new::<f64, _, _>(objects.iter().map(|(s, m)| (s, m)))
    }

    #[test]
    fn chosen_by_power_and_only_what_can_be_sampled() {
        let light = |l: f64| Emissive::new(Vec3::splat(l)).unwrap();
        let sphere = |r: f64| Sphere::new(Vec3::zero(), r).unwrap();
        let unit = Triangle::new(Vec3::zero(), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
        let objects = [
            object(sphere(1.0), Lambertian::new(Vec3::splat(0.5)).unwrap()),
            object(sphere(1.0), light(1.0)),
            object(
                Plane::new(Vec3::zero(), Vec3::new(0.0, 1.0, 0.0)).unwrap(),
                light(1.0),
            ),
            object(unit, light(2.0).two_sided(true)),
            object(sphere(2.0), light(0.0)),
        ];
        let e = table(&objects);
        assert_eq!(e.objects(), &[1, 3]);
        // Φ = π·L·s·A: the sphere π·1·1·4π, the triangle π·2·2·½.
        let (sphere_power, triangle_power) = (4.0 * std::f64::consts::PI, 2.0);
        let p = sphere_power / (sphere_power + triangle_power);
        assert!((e.probabilities()[0] - p).abs() < 1e-15);
        assert_eq!(e.choose(0.0), (1, e.probabilities()[0]));
        assert_eq!(e.choose(p * 0.999), (1, e.probabilities()[0]));
        assert_eq!(e.choose(p * 1.001).0, 3);
        assert_eq!(e.choose(1.0 - 1e-16).0, 3);
        let emission = |o: &Object| Material::<f64>::emits(&o.1).unwrap();
        for (k, &i) in e.objects().iter().enumerate() {
            let o = &objects[i as usize];
            assert_eq!(e.probability_of(o.0.area(), emission(o)), e.probabilities()[k]);
        }
        assert_eq!(e.probability_of(objects[2].0.area(), emission(&objects[2])), 0.0);
        let none = table(&objects[..1]);
        assert!(none.is_empty());
    }
}
