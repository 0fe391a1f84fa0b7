//! `max_depth`: exact on a five-bounce corridor, and the deepest recursion allowed fits on the stack.

use super::scene::*;
use rand::SeedableRng;
use raytrace::aabb::Aabb;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::shape::{Coordinates, Hit, Surface, SurfaceSample};
use raytrace::{DefaultRng, Intersection};

/// A test double: two facing mirrors, the planes `y = 0` and `y = 1`, that exist only for
/// `x < 5`. A ray from `(0, ½, 0)` along `(1, 1, 0)/√2` bounces at `x = ½, 3/2, 5/2, 7/2, 9/2`
/// — exactly five times — and then escapes below.
struct Corridor;

impl Hittable<f64> for Corridor {
    fn intersect(&self, ray: &Ray<f64>, t_max: f64) -> Option<Intersection<f64>> {
        let mut best: Option<Intersection<f64>> = None;
        for wall in [0.0, 1.0] {
            let t = (wall - ray.origin.y) / ray.direction.y;
            if t > 1e-9 && t < best.map_or(t_max, |h| h.t) && ray.at(t).x < 5.0 {
                best = Some(Intersection::at(t));
            }
        }
        best
    }

    fn finish(&self, ray: &Ray<f64>, hit: &Intersection<f64>) -> Hit<f64> {
        let p = ray.at(hit.t);
        let wall = p.y.round();
        let normal = Vec3::new(0.0, 1.0, 0.0);
        Hit::new(
            Surface::bare(hit.t, Vec3::new(p.x, wall, p.z), normal),
            ray.direction,
        )
    }

    fn coordinates(&self, _: &Ray<f64>, _: &Intersection<f64>, _: &Hit<f64>) -> Coordinates<f64> {
        Coordinates::default()
    }

    fn bounds(&self) -> Option<Aabb<f64>> {
        None
    }
    fn parts(&self) -> u32 {
        1
    }
    fn part_bounds(&self, _: u32) -> Option<Aabb<f64>> {
        None
    }
    fn intersect_part(&self, _: u32, ray: &Ray<f64>, t_max: f64) -> Option<Intersection<f64>> {
        self.intersect(ray, t_max)
    }
    fn area(&self) -> Option<f64> {
        None
    }
    fn sample(&self, _: Vec3<f64>, _: [f64; 3]) -> Option<SurfaceSample<f64>> {
        None
    }
    fn pdf(&self, _: &Ray<f64>, _: &Hit<f64>) -> f64 {
        0.0
    }
}

// Not packed in lanes: every query goes through the two methods above.
impl Layout<f64> for Corridor {}

#[test]
fn max_depth_is_exact() {
    let mut scene: Scene<f64, Corridor, Mirror<f64>> =
        Scene::new(Background::solid(Vec3::splat(1.0)).unwrap());
    scene.add(Corridor, Mirror::new(Vec3::splat(1.0)).unwrap());
    let ray = Ray::new(Vec3::new(0.0, 0.5, 0.0), Vec3::new(1.0, 1.0, 0.0).normalize());
    let mut rng = DefaultRng::seed_from_u64(0);
    let mut colour = |depth| Tracer::new(&scene, depth).trace(&ray, 0, &mut rng);
    assert_eq!(colour(5), Vec3::splat(1.0), "five bounces fit in max_depth = 5");
    assert_eq!(colour(50), Vec3::splat(1.0));
    assert_eq!(colour(4), Vec3::zero(), "the fifth bounce is past max_depth = 4");
    assert_eq!(colour(0), Vec3::zero());
    let mut tracer = Tracer::new(&scene, 5);
    tracer.trace(&ray, 0, &mut rng);
    assert_eq!(tracer.rays(), 6, "camera ray + five bounces");
}

/// The deepest recursion allowed fits on a worker thread's stack in every scalar, even for
/// paths that never escape (the eye inside a mirror sphere): the reference renderer really
/// recurses, one stack frame per bounce, and the batched renderer agrees with it. One more
/// bounce is a typed error, not a stack overflow.
#[test]
fn the_deepest_recursion_allowed_fits_on_the_stack() {
    fn trapped<F: Float>() {
        let mut scene = EnumScene::<F>::new(Background::default());
        scene.add(
            Sphere::new(Vec3::zero(), lit(10.0)).unwrap(),
            Mirror::new(Vec3::splat(lit(0.99))).unwrap(),
        );
        let cam = ScreenCamera::new(4, 2).unwrap();
        let deepest = RenderSettings::new(2, RenderSettings::MAX_DEPTH, 0).unwrap();
        let renderer = Renderer::new(&scene, &cam).settings(deepest);
        let reference = in_pool(2, || renderer.render_reference().unwrap());
        // Every camera ray bounces until the limit: 8 pixels × 2 samples × 1001 rays.
        assert_eq!(
            reference.stats.rays,
            8 * 2 * u64::from(RenderSettings::MAX_DEPTH + 1)
        );
        let fast = in_pool(2, || renderer.render().unwrap());
        assert_eq!(fast.stats.rays, reference.stats.rays);
        assert_eq!(bytes(&fast.image), bytes(&reference.image));
        let too_deep = renderer.max_depth(RenderSettings::MAX_DEPTH + 1);
        let err = too_deep.render().unwrap_err().to_string();
        assert!(err.contains("max depth"), "{err}");
        let err = too_deep.render_reference().unwrap_err().to_string();
        assert!(err.contains("max depth"), "{err}");
    }
    trapped::<f32>();
    trapped::<f64>();
    trapped::<raytrace::DoubleDouble>();
}
