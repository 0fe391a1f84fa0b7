//! A scene: objects (a shape with its material), lights (point, spot, directional) and a
//! background.

mod index;
mod layout;
mod plain;

use crate::background::Background;
use crate::float::Float;
use crate::light::{Emitters, Light};
use crate::material::{Material, MaterialKind, SharedMaterial};
use crate::ray::Ray;
use crate::shape::{Hit, Hittable, ShapeKind};
pub use index::HitOn;
use index::Index;
pub(crate) use index::Nearests;
pub use layout::{Layout, Primitive};
use std::marker::PhantomData;
use std::sync::{Arc, OnceLock};

/// One object of a scene: a shape and the material it is made of, by default the
/// material's place in the scene's table ([`Scene::material`]), so that objects made of
/// one material share it (an object is 32 bytes in f32, where
/// a copy of the material made it 72).
#[derive(Clone, Debug, PartialEq)]
pub struct Object<S, M = MaterialId> {
    /// The geometry.
    pub shape: S,
    /// The material.
    pub material: M,
}

/// A material in a scene's table: what [`Scene::add_material`] returns and
/// [`Scene::add_object`] takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct MaterialId(u32);

impl MaterialId {
    /// Its place in [`Scene::materials`].
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// Objects, lights and background, generic over the shape type `S` and the material
/// type `M` so the same renderer serves both dispatch paths:
/// [`EnumScene`] (compile-time `match`) and [`DynScene`] (trait objects, the spec's
/// "vector of smart pointers").
///
/// Intersection is a plain loop over the shapes' parts (a mesh's triangles) until there
/// are enough of them for a bounding volume hierarchy to pay ([`Acceleration::Auto`]); the
/// hierarchy holds only the parts with [bounds](Hittable::part_bounds) (planes and
/// unbounded shapes stay in the loop). Either way, the parts its shape type's [`Layout`]
/// calls spheres and triangles (the enum fast path's, not trait objects) are tested four
/// at a time, and only the nearest hit's record is made. The structure is built on the
/// first query after a change.
///
/// The materials are a table of their own and each object holds its material's place in
/// it ([`MaterialId`]): [`Scene::add`] adds a material for each object, while
/// [`Scene::add_material`] and [`Scene::add_object`] let many objects share one.
#[derive(Clone, Debug)]
pub struct Scene<F: Float, S, M> {
    objects: Vec<Object<S>>,
    materials: Vec<M>,
    lights: Vec<Light<F>>,
    background: Background<F>,
    background_sampled: bool,
    acceleration: Acceleration,
    bvh_quality: BvhQuality,
    index: OnceLock<Index<F>>,
    emitters: OnceLock<Emitters>,
    _scalar: PhantomData<F>,
}

/// Whether a scene intersects through a BVH.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Acceleration {
    /// A BVH once the scene has at least [`Acceleration::AUTO_THRESHOLD`] bounded parts.
    #[default]
    Auto,
    /// Always the plain loop (spheres still four at a time).
    Linear,
    /// Always a BVH over the bounded parts.
    Bvh,
}

impl Acceleration {
    /// The bounded-part count from which [`Acceleration::Auto`] builds a BVH.
    ///
    /// Chosen by the `render` bench's `bvh-threshold-160x80-2spp` group: the plain loop
    /// is faster up to 12 random small spheres, the BVH from 16; on the spec's scenes
    /// (`bvh-or-loop-spec-scenes-160x80-2spp`) the loop wins, so they pay nothing for a
    /// hierarchy. The figures are in `docs/PERFORMANCE.md`.
    pub const AUTO_THRESHOLD: usize = 16;
}

/// How much work a scene's BVH build does for a faster trace (the names are Embree's).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BvhQuality {
    /// The binned surface-area-heuristic build over whole primitives.
    #[default]
    Medium,
    /// The same build after spatial splits: long and diagonal triangles, whose boxes are
    /// mostly empty, are cut into pieces first ([`Bvh::build_split`](crate::bvh::Bvh::build_split)).
    /// Triangles only; it takes longer to build and more memory, and pays off where large
    /// triangles overlap (architecture, a room), little on a finely tessellated model.
    High,
}

/// The fast path: shapes and materials are enums, stored inline.
pub type EnumScene<F> = Scene<F, ShapeKind<F>, MaterialKind<F>>;

/// The abstract path: boxed shapes and shared materials behind trait objects, the spec's
/// "vector of smart pointers". `scene.add(Box::new(shape), Arc::new(material))` adds any
/// shape and material, the user's own included.
pub type DynScene<F> = Scene<F, Box<dyn Hittable<F> + Send + Sync>, SharedMaterial<F>>;

impl<F: Float> EnumScene<F> {
    /// The same scene on the abstract path: every shape boxed, every material shared
    /// behind a trait object. It renders to the same bytes, only slower.
    #[must_use]
    pub fn to_dyn(&self) -> DynScene<F> {
        let mut scene = DynScene::new(self.background.clone());
        scene.set_background_sampled(self.background_sampled);
        scene.set_acceleration(self.acceleration);
        scene.set_bvh_quality(self.bvh_quality);
        for m in &self.materials {
            let material: SharedMaterial<F> = match m {
                MaterialKind::Mirror(m) => Arc::new(*m).into(),
                MaterialKind::Lambertian(m) => Arc::new(m.clone()).into(),
                MaterialKind::Dielectric(m) => Arc::new(*m).into(),
                MaterialKind::Emissive(m) => Arc::new(*m).into(),
                MaterialKind::NormalMap(m) => Arc::clone(m).into(),
                MaterialKind::Conductor(m) => Arc::clone(m).into(),
                MaterialKind::RoughConductor(m) => Arc::clone(m).into(),
                MaterialKind::RoughDielectric(m) => Arc::clone(m).into(),
                MaterialKind::ThinDielectric(m) => Arc::clone(m).into(),
                MaterialKind::Plastic(m) => Arc::clone(m).into(),
                MaterialKind::RoughPlastic(m) => Arc::clone(m).into(),
                MaterialKind::TwoSided(m) => Arc::clone(m).into(),
            };
            scene.add_material(material);
        }
        for o in &self.objects {
            let shape: Box<dyn Hittable<F> + Send + Sync> = match &o.shape {
                ShapeKind::Sphere(s) => Box::new(*s),
                ShapeKind::Plane(p) => Box::new(**p),
                ShapeKind::Triangle(t) => Box::new(**t),
                ShapeKind::Disk(d) => Box::new(Arc::clone(d)),
                ShapeKind::Mesh(m) => Box::new(Arc::clone(m)),
                ShapeKind::Instance(i) => Box::new(Arc::clone(i)),
            };
            scene.add_object(shape, o.material);
        }
        for &light in &self.lights {
            scene.add_light(light);
        }
        scene
    }
}

impl<F: Float, S, M> Scene<F, S, M> {
    /// An empty scene with the given background.
    pub fn new(background: Background<F>) -> Self {
        Self {
            objects: Vec::new(),
            materials: Vec::new(),
            lights: Vec::new(),
            background,
            background_sampled: false,
            acceleration: Acceleration::Auto,
            bvh_quality: BvhQuality::Medium,
            index: OnceLock::new(),
            emitters: OnceLock::new(),
            _scalar: PhantomData,
        }
    }

    /// How the scene is intersected.
    pub fn acceleration(&self) -> Acceleration {
        self.acceleration
    }

    /// Chooses how the scene is intersected (the default is [`Acceleration::Auto`]).
    pub fn set_acceleration(&mut self, acceleration: Acceleration) -> &mut Self {
        self.acceleration = acceleration;
        self.index = OnceLock::new();
        self
    }

    /// How much work the scene's BVH build does.
    pub fn bvh_quality(&self) -> BvhQuality {
        self.bvh_quality
    }

    /// Chooses how much work the BVH build does (the default is [`BvhQuality::Medium`]).
    pub fn set_bvh_quality(&mut self, quality: BvhQuality) -> &mut Self {
        self.bvh_quality = quality;
        self.index = OnceLock::new();
        self
    }

    /// Adds an object made of `shape` and `material`, a material of its own: objects
    /// that share one take less room added by [`Scene::add_object`].
    pub fn add(&mut self, shape: impl Into<S>, material: impl Into<M>) -> &mut Self {
        let material = self.add_material(material);
        self.add_object(shape, material)
    }

    /// Adds `material` to the table of materials, for objects to be made of.
    ///
    /// # Panics
    /// With more than `u32::MAX` materials.
    pub fn add_material(&mut self, material: impl Into<M>) -> MaterialId {
        let id = u32::try_from(self.materials.len()).expect("a scene holds at most u32::MAX materials");
        self.materials.push(material.into());
        MaterialId(id)
    }

    /// Adds an object made of `shape` and the material `material` of this scene's table.
    ///
    /// # Panics
    /// If `material` is not in the table (a [`MaterialId`] of another scene).
    pub fn add_object(&mut self, shape: impl Into<S>, material: MaterialId) -> &mut Self {
        assert!(
            material.index() < self.materials.len(),
            "{material:?} is not in this scene's table of {} materials",
            self.materials.len()
        );
        self.objects.push(Object {
            shape: shape.into(),
            material,
        });
        self.index = OnceLock::new();
        self.emitters = OnceLock::new();
        self
    }

    /// The material `id` of the table.
    ///
    /// # Panics
    /// If `id` is not in the table.
    #[inline(always)]
    pub fn material(&self, id: MaterialId) -> &M {
        &self.materials[id.index()]
    }

    /// The table of materials, in the order added.
    pub fn materials(&self) -> &[M] {
        &self.materials
    }

    /// Adds a light: a [`PointLight`](crate::PointLight), a
    /// [`SpotLight`](crate::light::SpotLight), a
    /// [`DirectionalLight`](crate::light::DirectionalLight) or a [`Light`].
    pub fn add_light(&mut self, light: impl Into<Light<F>>) -> &mut Self {
        self.lights.push(light.into());
        self
    }

    /// The objects, in the order added.
    pub fn objects(&self) -> &[Object<S>] {
        &self.objects
    }

    /// The lights, in the order added.
    pub fn lights(&self) -> &[Light<F>] {
        &self.lights
    }

    /// The background.
    pub fn background(&self) -> &Background<F> {
        &self.background
    }

    /// Makes the background a light (`true`) or only what escaping rays see (`false`, the
    /// default: the specification's sky). As a light it is drawn from at every surface
    /// that can be lit (next-event estimation, weighed against the scattered ray by
    /// multiple importance sampling) and, like every light then, counts on paths of at
    /// most `max_depth` segments: a ray escaping after `max_depth` bounces brings back
    /// black, and point lights too are sampled only where a ray from there would still
    /// count. Emitters, point lights and the background then all follow one rule, which is
    /// also Mitsuba 3's `max_depth`.
    pub fn set_background_sampled(&mut self, sampled: bool) -> &mut Self {
        self.background_sampled = sampled;
        self
    }

    /// Whether the background is a light ([`Scene::set_background_sampled`]).
    pub fn background_sampled(&self) -> bool {
        self.background_sampled
    }
}

impl<F: Float, S: Layout<F>, M> Scene<F, S, M> {
    /// Whether intersection goes through a BVH (building it if it is due).
    pub fn uses_bvh(&self) -> bool {
        self.index().uses_bvh()
    }

    /// How many references the scene's BVH sorts into its leaves (building it if it is
    /// due): one for each part in the tree, and more where the high-quality build cut
    /// triangles into pieces ([`BvhQuality::High`]); `None` without a BVH.
    pub fn bvh_references(&self) -> Option<usize> {
        self.index().bvh_references()
    }

    #[inline]
    fn index(&self) -> &Index<F> {
        self.index
            .get_or_init(|| Index::build(&self.objects, self.acceleration, self.bvh_quality))
    }

    /// Whether any part blocks the ray in `(0, t_max)`; stops at the first.
    #[inline]
    pub fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.index().occluded(&self.objects, ray, t_max)
    }

    /// [`Scene::occluded`] of each of `rays` in `(0, reach[i])`, set in `blocked`: the same
    /// answers, found for the whole batch at once (`near` is scratch space). A ray
    /// `aimed[i]` at part `(object, part)` stops where the scene's intersection meets that
    /// part, not at `reach[i]` (a bound past it, which only saves work); one that does not
    /// meet it is blocked, and counted in the number returned.
    pub(crate) fn occluded_all(
        &self,
        rays: &[Ray<F>],
        reach: &[F],
        aimed: &[Option<(u32, u32)>],
        near: &mut Nearests<F>,
        blocked: &mut Vec<bool>,
    ) -> usize {
        self.index()
            .occluded_all(&self.objects, rays, reach, aimed, near, blocked)
    }
}

impl<F: Float, S: Layout<F>, M: Material<F>> Scene<F, S, M> {
    /// The nearest hit in `(0, t_max)` and the material hit. At equal distance the part
    /// that comes first wins (the object added first; of a mesh's triangles, the first),
    /// so the answer never depends on the acceleration structure. The hit carries its
    /// surface coordinates if the material [reads them](Material::reads_coordinates).
    #[inline]
    pub fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<(Hit<F>, &M)> {
        let (hit, _, material) = self.hit_object(ray, t_max)?;
        Some((hit, material))
    }

    /// [`Scene::hit`] with the object hit: the hit, the object (its shape and its
    /// material's place in the table) and its material.
    #[inline]
    pub fn hit_object(&self, ray: &Ray<F>, t_max: F) -> Option<HitOn<'_, F, S, M>> {
        self.index().hit(&self.objects, &self.materials, ray, t_max)
    }

    /// [`Scene::hit_object`] with no bound for each of `rays`, handed to `each(i, hit)` in
    /// the rays' order: the same answers, found for the whole batch at once (`near` is
    /// scratch space).
    #[inline]
    pub(crate) fn hit_all<'s>(
        &'s self,
        rays: &[Ray<F>],
        near: &mut Nearests<F>,
        each: impl FnMut(usize, Option<HitOn<'s, F, S, M>>),
    ) {
        self.index()
            .hit_all(&self.objects, &self.materials, rays, near, each);
    }

    /// The objects that give off light and are sampled as lights, with the probability of
    /// each ([`Emitters`]); built on the first call after a change.
    #[inline]
    pub fn emitters(&self) -> &Emitters {
        self.emitters
            .get_or_init(|| Emitters::new(self.objects.iter().map(|o| (&o.shape, self.material(o.material)))))
    }
}

impl<F: Float> EnumScene<F> {
    /// The same scene in scalar `G` (objects, lights, background, acceleration, BVH quality): build a
    /// scene once (in `f64`, say) and render it in `f32`, `f64` or double-double.
    ///
    /// Every value is rounded through `f64` and re-validated by its constructor, so a value
    /// that does not survive the rounding (a radius that underflows to 0, a triangle that
    /// becomes degenerate) is an error, not a silently different scene. The `cast` of each
    /// part (shapes, materials, lights, background) works the same way.
    pub fn cast<G: Float>(&self) -> crate::error::Result<EnumScene<G>> {
        let mut out = EnumScene::new(self.background.cast()?);
        out.set_background_sampled(self.background_sampled);
        out.set_acceleration(self.acceleration);
        out.set_bvh_quality(self.bvh_quality);
        for m in &self.materials {
            out.add_material(m.cast()?);
        }
        for o in &self.objects {
            out.add_object(o.shape.cast()?, o.material);
        }
        for l in &self.lights {
            out.add_light(l.cast()?);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests;
