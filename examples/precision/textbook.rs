//! The naive method as a shape, so the study can render whole scenes with it: a sphere
//! intersected the textbook way, and the study's shape enum that holds it beside the
//! library's shapes. The library's [`ShapeKind`] carries only the production shapes.

use raytrace::Intersection;
use raytrace::aabb::Aabb;
use raytrace::prelude::*;
use raytrace::scene::Primitive;
use raytrace::shape::{
    Coordinates, Hit, SurfaceSample, TEXTBOOK_T_MIN, textbook_sphere_record, textbook_sphere_t,
};

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
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        self.0.coordinates(ray, hit, record)
    }
    // The rest as the sphere: one part, its box, and sampled as a light the same way.
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        self.0.bounds()
    }
    #[inline]
    fn parts(&self) -> u32 {
        1
    }
    #[inline]
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        self.0.bounds()
    }
    #[inline]
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }
    fn area(&self) -> Option<F> {
        self.0.area()
    }
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        self.0.sample(from, u)
    }
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        self.0.pdf(ray, hit)
    }
}

/// The library's sphere with the textbook's spawn: the stable roots and the point put back
/// on the surface, but no error bound, so a spawned ray leaves from the point itself and only
/// `t > 0.001` keeps it off its own surface. Between the two methods, it isolates what the
/// stable method's spawn offset does to the error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnoffsetSphere<F>(pub Sphere<F>);

impl<F: Float> Hittable<F> for UnoffsetSphere<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let (t0, t1) = self.0.roots(ray)?;
        let t_min = lit(TEXTBOOK_T_MIN);
        [t0, t1]
            .into_iter()
            .find(|&t| t > t_min && t < t_max)
            .map(Intersection::at)
    }
    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        Hit {
            error: Vec3::zero(),
            ..self.0.finish(ray, hit)
        }
    }
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        self.0.coordinates(ray, hit, record)
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        self.0.bounds()
    }
    #[inline]
    fn parts(&self) -> u32 {
        1
    }
    #[inline]
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        self.0.bounds()
    }
    #[inline]
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }
    fn area(&self) -> Option<F> {
        self.0.area()
    }
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        self.0.sample(from, u)
    }
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        self.0.pdf(ray, hit)
    }
}

/// The study's shapes: the library's, a textbook sphere, or a stable one spawning the
/// textbook way.
#[derive(Clone, Debug, PartialEq)]
pub enum StudyShape<F> {
    /// A production shape, intersected as the library does.
    Kind(ShapeKind<F>),
    /// A sphere intersected the textbook way.
    Textbook(TextbookSphere<F>),
    /// A stable sphere whose spawned rays start at the hit point, kept off by `t_min`.
    Unoffset(UnoffsetSphere<F>),
}

/// `match` on a [`StudyShape`], the same call on every variant.
macro_rules! each_shape {
    ($shape:expr, $s:ident => $call:expr) => {
        match $shape {
            StudyShape::Kind($s) => $call,
            StudyShape::Textbook($s) => $call,
            StudyShape::Unoffset($s) => $call,
        }
    };
}

impl<F: Float> Hittable<F> for StudyShape<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        each_shape!(self, s => s.intersect(ray, t_max))
    }
    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        each_shape!(self, s => s.finish(ray, hit))
    }
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        each_shape!(self, s => s.coordinates(ray, hit, record))
    }
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        each_shape!(self, s => s.bounds())
    }
    #[inline]
    fn parts(&self) -> u32 {
        each_shape!(self, s => s.parts())
    }
    #[inline]
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        each_shape!(self, s => s.part_bounds(part))
    }
    #[inline]
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        each_shape!(self, s => s.intersect_part(part, ray, t_max))
    }
    fn area(&self) -> Option<F> {
        each_shape!(self, s => s.area())
    }
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        each_shape!(self, s => s.sample(from, u))
    }
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        each_shape!(self, s => s.pdf(ray, hit))
    }
}

// The library's shapes keep their lanes. A textbook sphere must not be described as a
// sphere: the scene would test it the stable way.
impl<F: Float> Layout<F> for StudyShape<F> {
    #[inline]
    fn primitive(&self, part: u32) -> Primitive<F> {
        match self {
            Self::Kind(k) => k.primitive(part),
            Self::Textbook(_) | Self::Unoffset(_) => Primitive::Other,
        }
    }
}

/// A scene of the study's shapes.
pub type StudyScene<F> = Scene<F, StudyShape<F>, MaterialKind<F>>;

/// `scene` with every sphere intersected the textbook way; other shapes, the materials,
/// lights, background and acceleration unchanged.
pub fn to_textbook<F: Float>(scene: &EnumScene<F>) -> StudyScene<F> {
    replace_spheres(scene, |s| StudyShape::Textbook(TextbookSphere(s)))
}

/// `scene` with every sphere a [`UnoffsetSphere`]; the rest unchanged.
pub fn to_unoffset<F: Float>(scene: &EnumScene<F>) -> StudyScene<F> {
    replace_spheres(scene, |s| StudyShape::Unoffset(UnoffsetSphere(s)))
}

fn replace_spheres<F: Float>(
    scene: &EnumScene<F>,
    sphere: impl Fn(Sphere<F>) -> StudyShape<F>,
) -> StudyScene<F> {
    let mut out = StudyScene::new(scene.background().clone());
    out.set_acceleration(scene.acceleration());
    for o in scene.objects() {
        let shape = match &o.shape {
            ShapeKind::Sphere(s) => sphere(*s),
            other => StudyShape::Kind(other.clone()),
        };
        out.add(shape, scene.material(o.material).clone());
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
