//! The naive method as a shape, so the study can render whole scenes with it: a sphere
//! intersected the textbook way, and the study's shape enum that holds it beside the
//! library's shapes. The library's [`ShapeKind`] carries only the production shapes.

use raytrace::aabb::Aabb;
use raytrace::prelude::*;
use raytrace::shape::{Hit, TEXTBOOK_T_MIN, textbook_sphere_hit};

/// A sphere intersected the textbook way ([`textbook_sphere_hit`] with `t_min = 0.001`
/// and no error bound, so spawned rays start at the rounded hit point).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextbookSphere<F>(pub Sphere<F>);

impl<F: Float> Hittable<F> for TextbookSphere<F> {
    #[inline]
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
        textbook_sphere_hit(&self.0, ray, lit(TEXTBOOK_T_MIN), t_max)
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        self.0.bounds()
    }
}

/// The study's shapes: the library's, or a textbook sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StudyShape<F> {
    /// A production shape, intersected as the library does.
    Kind(ShapeKind<F>),
    /// A sphere intersected the textbook way.
    Textbook(TextbookSphere<F>),
}

impl<F: Float> Hittable<F> for StudyShape<F> {
    #[inline]
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
        match self {
            Self::Kind(k) => k.hit(ray, t_max),
            Self::Textbook(s) => s.hit(ray, t_max),
        }
    }
    #[inline]
    fn occluded(&self, ray: &Ray<F>, t_max: F) -> bool {
        match self {
            Self::Kind(k) => k.occluded(ray, t_max),
            Self::Textbook(s) => s.occluded(ray, t_max),
        }
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        match self {
            Self::Kind(k) => k.bounds(),
            Self::Textbook(s) => s.bounds(),
        }
    }
    // A textbook sphere must not answer: the scene would test it the stable way.
    #[inline]
    fn as_sphere(&self) -> Option<&Sphere<F>> {
        match self {
            Self::Kind(k) => k.as_sphere(),
            Self::Textbook(_) => None,
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
        let shape = match o.shape {
            ShapeKind::Sphere(s) => StudyShape::Textbook(TextbookSphere(s)),
            other => StudyShape::Kind(other),
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
