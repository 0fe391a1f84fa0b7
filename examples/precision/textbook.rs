//! The naive method as a shape, so the study can render whole scenes with it: a sphere
//! intersected the textbook way, and the study's shape enum that holds it beside the
//! library's shapes. The library's [`ShapeKind`] carries only the production shapes.

use raytrace::Intersection;
use raytrace::aabb::Aabb;
use raytrace::prelude::*;
use raytrace::scene::Primitive;
use raytrace::shape::{Hit, TEXTBOOK_T_MIN, textbook_sphere_record, textbook_sphere_t};

/// A sphere intersected the textbook way ([`raytrace::shape::textbook_sphere_hit`] with `t_min = 0.001`
/// and no error bound, so spawned rays start at the rounded hit point).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextbookSphere<F>(pub Sphere<F>);

impl<F: Float> Hittable<F> for TextbookSphere<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        textbook_sphere_t(&self.0, ray, lit(TEXTBOOK_T_MIN), t_max).map(Intersection::at)
    }
    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        textbook_sphere_record(&self.0, ray, hit.t)
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        self.0.bounds()
    }
}

/// The study's shapes: the library's, or a textbook sphere.
#[derive(Clone, Debug, PartialEq)]
pub enum StudyShape<F> {
    /// A production shape, intersected as the library does.
    Kind(ShapeKind<F>),
    /// A sphere intersected the textbook way.
    Textbook(TextbookSphere<F>),
}

impl<F: Float> Hittable<F> for StudyShape<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        match self {
            Self::Kind(k) => k.intersect(ray, t_max),
            Self::Textbook(s) => s.intersect(ray, t_max),
        }
    }
    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        match self {
            Self::Kind(k) => k.finish(ray, hit),
            Self::Textbook(s) => s.finish(ray, hit),
        }
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        match self {
            Self::Kind(k) => k.bounds(),
            Self::Textbook(s) => s.bounds(),
        }
    }
    #[inline]
    fn parts(&self) -> u32 {
        match self {
            Self::Kind(k) => k.parts(),
            Self::Textbook(s) => s.parts(),
        }
    }
    #[inline]
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        match self {
            Self::Kind(k) => k.part_bounds(part),
            Self::Textbook(s) => s.part_bounds(part),
        }
    }
    #[inline]
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        match self {
            Self::Kind(k) => k.intersect_part(part, ray, t_max),
            Self::Textbook(s) => s.intersect_part(part, ray, t_max),
        }
    }
}

// The library's shapes keep their lanes. A textbook sphere must not be described as a
// sphere: the scene would test it the stable way.
impl<F: Float> Layout<F> for StudyShape<F> {
    #[inline]
    fn primitive(&self, part: u32) -> Primitive<F> {
        match self {
            Self::Kind(k) => k.primitive(part),
            Self::Textbook(_) => Primitive::Other,
        }
    }
}

/// A scene of the study's shapes.
pub type StudyScene<F> = Scene<F, StudyShape<F>, MaterialKind<F>>;

/// `scene` with every sphere intersected the textbook way; other shapes, the materials,
/// lights, background and acceleration unchanged.
pub fn to_textbook<F: Float>(scene: &EnumScene<F>) -> StudyScene<F> {
    let mut out = StudyScene::new(*scene.background());
    out.set_acceleration(scene.acceleration());
    for o in scene.objects() {
        let shape = match &o.shape {
            ShapeKind::Sphere(s) => StudyShape::Textbook(TextbookSphere(*s)),
            other => StudyShape::Kind(other.clone()),
        };
        out.add(shape, o.material);
    }
    for l in scene.lights() {
        out.add_light(*l);
    }
    out
}

/// [`to_textbook`] keeps everything but the spheres' method.
#[test]
fn to_textbook_replaces_spheres_only() {
    let mut scene = EnumScene::<f64>::new(Background::default());
    let mirror = Mirror::new(Vec3::splat(0.5)).unwrap();
    scene.add(Sphere::new(Vec3::new(0.0, 0.0, -3.0), 0.5).unwrap(), mirror);
    let tri = Triangle::new(Vec3::zero(), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap();
    scene.add(tri, Dielectric::new(1.5).unwrap());
    scene.add_light(PointLight::new(Vec3::new(0.0, 5.0, 0.0), Vec3::splat(3.0)).unwrap());
    let textbook = to_textbook(&scene);
    assert!(matches!(textbook.objects()[0].shape, StudyShape::Textbook(_)));
    assert_eq!(textbook.objects()[1].shape, StudyShape::Kind(tri.into()));
    assert_eq!(textbook.lights(), scene.lights());
}
