//! A scene: objects (a shape with its material), point lights and a background.

use crate::background::Background;
use crate::float::Float;
use crate::light::PointLight;
use crate::material::{Material, MaterialKind};
use crate::ray::Ray;
use crate::shape::{Hit, Hittable, ShapeKind};
use std::marker::PhantomData;
use std::sync::Arc;

/// One object of a scene: a shape and the material it is made of.
#[derive(Clone, Debug, PartialEq)]
pub struct Object<S, M> {
    /// The geometry.
    pub shape: S,
    /// The material.
    pub material: M,
}

/// Objects, lights and background, generic over the shape type `S` and the material
/// type `M` so the same renderer serves both dispatch paths:
/// [`EnumScene`] (compile-time `match`) and [`DynScene`] (trait objects, the spec's
/// "vector of smart pointers").
#[derive(Clone, Debug)]
pub struct Scene<F, S, M> {
    objects: Vec<Object<S, M>>,
    lights: Vec<PointLight<F>>,
    background: Background<F>,
    _scalar: PhantomData<F>,
}

/// The fast path: shapes and materials are enums, stored inline.
pub type EnumScene<F> = Scene<F, ShapeKind<F>, MaterialKind<F>>;

/// The abstract path: boxed shapes and shared materials behind trait objects.
pub type DynScene<F, R> = Scene<F, Box<dyn Hittable<F> + Send + Sync>, Arc<dyn Material<F, R> + Send + Sync>>;

impl<F: Float, S, M> Scene<F, S, M> {
    /// An empty scene with the given background.
    pub fn new(background: Background<F>) -> Self {
        Self {
            objects: Vec::new(),
            lights: Vec::new(),
            background,
            _scalar: PhantomData,
        }
    }

    /// Adds an object made of `shape` and `material`.
    pub fn add(&mut self, shape: impl Into<S>, material: impl Into<M>) -> &mut Self {
        self.objects.push(Object {
            shape: shape.into(),
            material: material.into(),
        });
        self
    }

    /// Adds a point light.
    pub fn add_light(&mut self, light: PointLight<F>) -> &mut Self {
        self.lights.push(light);
        self
    }

    /// The objects, in the order added.
    pub fn objects(&self) -> &[Object<S, M>] {
        &self.objects
    }

    /// The point lights.
    pub fn lights(&self) -> &[PointLight<F>] {
        &self.lights
    }

    /// The background.
    pub fn background(&self) -> &Background<F> {
        &self.background
    }
}

impl<F: Float, S: Hittable<F>, M> Scene<F, S, M> {
    /// The nearest hit in `(0, t_max)` and the material hit.
    #[inline]
    pub fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<(Hit<F>, &M)> {
        let mut nearest = t_max;
        let mut found = None;
        for object in &self.objects {
            if let Some(hit) = object.shape.hit(ray, nearest) {
                nearest = hit.t;
                found = Some((hit, &object.material));
            }
        }
        found
    }

    /// Whether any object blocks the ray in `(0, t_max)`; stops at the first.
    #[inline]
    pub fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.objects.iter().any(|o| o.shape.occluded(ray, t_max))
    }
}
