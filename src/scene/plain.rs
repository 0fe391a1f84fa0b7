//! The specification's "vector of pointers" as it reads: every object asked in turn.
//!
//! A scene with [`Acceleration::Linear`](super::Acceleration::Linear), or one whose shapes
//! the index cannot pack in lanes (a [`DynScene`](crate::DynScene) of a few trait objects),
//! finds its hits with these two loops. They give the packet index's answers bit for bit:
//! the nearest `t`, and of equally near parts the one that comes first, the objects in the
//! order added and a shape's parts in order (`tests` in `index` checks every query).

use super::Object;
use crate::float::Float;
use crate::ray::Ray;
use crate::shape::{Hittable, Intersection};

/// The nearest intersection in `(0, t_max)` and the index of the object it is on: each
/// part of each object asked with no bound (as the index's lanes are: a bound can enter a
/// shape's test before its last rounding and turn away a hit nearer by an ulp), then
/// kept if strictly nearer than the nearest so far, so a later part at the same `t`
/// never replaces an earlier one.
pub(super) fn nearest<F: Float, S: Hittable<F>, M>(
    objects: &[Object<S, M>],
    ray: &Ray<F>,
    t_max: F,
) -> Option<(Intersection<F>, u32)> {
    let mut best: Option<(Intersection<F>, u32)> = None;
    for (o, object) in objects.iter().enumerate() {
        for part in 0..object.shape.parts() {
            let bound = best.map_or(t_max, |(hit, _)| hit.t);
            match object.shape.intersect_part(part, ray, F::infinity()) {
                Some(hit) if hit.t < bound => best = Some((hit, o as u32)),
                _ => {}
            }
        }
    }
    best
}

/// Whether any part of any object meets the ray in `(0, t_max)`; stops at the first.
#[inline]
pub(super) fn any<F: Float, S: Hittable<F>, M>(objects: &[Object<S, M>], ray: &Ray<F>, t_max: F) -> bool {
    objects.iter().any(|object| {
        (0..object.shape.parts()).any(|part| {
            let hit = object.shape.intersect_part(part, ray, F::infinity());
            hit.is_some_and(|h| h.t < t_max)
        })
    })
}
