//! [`SharedMaterial`]: any material behind a shared trait object, the material type of
//! the spec's "vector of smart pointers".

use super::{BsdfSample, Emission, Eval, Lobes, Material, Scatter};
use crate::float::Float;
use crate::shape::Hit;
use crate::vec3::Vec3;
use rand::Rng;
use std::sync::Arc;

/// A material behind a shared pointer, as a trait object: the material type of a
/// [`DynScene`](crate::DynScene), where one material may serve many objects.
///
/// It draws through `&mut dyn Rng`, so one trait object serves every generator and the
/// scene's type does not name one. `Arc::new(my_material).into()` makes one (so
/// `scene.add(Box::new(shape), Arc::new(material))` needs no casts), and so does an
/// `Arc<dyn Scatter<F, dyn Rng>>` already shared.
#[derive(Clone)]
pub struct SharedMaterial<F>(pub Arc<dyn Scatter<F, dyn Rng> + Send + Sync>);

impl<F: Float, T: Scatter<F, dyn Rng> + Send + Sync + 'static> From<Arc<T>> for SharedMaterial<F> {
    fn from(material: Arc<T>) -> Self {
        Self(material)
    }
}

impl<F: Float> From<Arc<dyn Scatter<F, dyn Rng> + Send + Sync>> for SharedMaterial<F> {
    fn from(material: Arc<dyn Scatter<F, dyn Rng> + Send + Sync>) -> Self {
        Self(material)
    }
}

impl<F: Float> Material<F> for SharedMaterial<F> {
    #[inline]
    fn lobes(&self) -> Lobes {
        self.0.lobes()
    }
    #[inline]
    fn reads_coordinates(&self) -> bool {
        self.0.reads_coordinates()
    }
    #[inline]
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        self.0.eval(hit, wo, wi)
    }
    #[inline]
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        self.0.pdf(hit, wo, wi)
    }
    #[inline]
    fn emits(&self) -> Option<Emission<F>> {
        self.0.emits()
    }
}

impl<F: Float, R: Rng + 'static> Scatter<F, R> for SharedMaterial<F> {
    #[inline]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        self.0.sample(hit, wo, rng as &mut dyn Rng)
    }
}

impl<F> std::fmt::Debug for SharedMaterial<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SharedMaterial(dyn Scatter)")
    }
}
