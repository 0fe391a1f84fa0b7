//! The high-quality build ([`BvhQuality::High`]) cuts long triangles into pieces, one
//! triangle in several leaves; the scene must still answer exactly as the plain loop does:
//! the same nearest hits and shadow queries for rays aimed at the cut planes themselves,
//! and the same image bytes.

use rand::{RngExt, SeedableRng};
use raytrace::prelude::*;
use raytrace::{Acceleration, BvhQuality, DefaultRng};

/// Half the side of the scene's box on x and y; on z it is `[−2H, 0]` shifted by ½.
const H: f64 = 10.5;

/// Needles (long thin triangles, every way oriented) among small triangles and spheres, all
/// inside two small corner spheres that fix the tree's box to `[−H, H]² × [−2H, 0] − ½`.
/// Returns the scene and its needles' corners.
fn scene<F: Float>(acceleration: Acceleration, quality: BvhQuality) -> (EnumScene<F>, Vec<[Vec3<F>; 3]>) {
    let mut rng = DefaultRng::seed_from_u64(41);
    let mut v = |s: f64| {
        Vec3::<f64>::new(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    let f = |p: Vec3<f64>| Vec3::from_f64(p.x, p.y, p.z);
    let mut scene = EnumScene::<F>::new(Background::default());
    let matte = scene.add_material(Lambertian::new(Vec3::from_f64(0.5, 0.6, 0.7)).unwrap());
    let mirror = scene.add_material(Mirror::new(Vec3::from_f64(0.9, 0.8, 0.7)).unwrap());
    let mut needles = Vec::new();
    for i in 0..400 {
        let c = v(8.0) + Vec3::new(0.0, 0.0, -10.0);
        let m = if i % 5 == 0 { mirror } else { matte };
        if i % 8 == 0 {
            let d = v(4.0);
            let t = [c - d, c + d, c + v(0.1)].map(f);
            needles.push(t);
            scene.add_object(Triangle::new(t[0], t[1], t[2]).unwrap(), m);
        } else if i % 2 == 0 {
            let t = [c + v(0.5), c + v(0.5), c + v(0.5)].map(f);
            scene.add_object(Triangle::new(t[0], t[1], t[2]).unwrap(), m);
        } else {
            scene.add_object(Sphere::new(f(c), lit(0.3)).unwrap(), m);
        }
    }
    for corner in [Vec3::new(-10.0, -10.0, -20.0), Vec3::new(10.0, 10.0, 0.0)] {
        scene.add_object(Sphere::new(f(corner), lit(0.5)).unwrap(), matte);
    }
    scene.add_light(PointLight::new(Vec3::from_f64(0.0, 8.0, -8.0), Vec3::splat(lit(50.0))).unwrap());
    scene.set_acceleration(acceleration);
    scene.set_bvh_quality(quality);
    (scene, needles)
}

/// Points of the needles: random ones, and points on the grid's coarse planes
/// (`min + extent·m/8`, where the cuts are made) inside each needle, so that rays meet
/// the pieces' boxes at their common faces.
fn targets<F: Float>(needles: &[[Vec3<F>; 3]], rng: &mut DefaultRng) -> Vec<Vec3<f64>> {
    let (min, extent) = ([-H, -H, -2.0 * H - 0.5], [2.0 * H, 2.0 * H, 2.0 * H]);
    let mut out = Vec::new();
    for t in needles {
        let [a, b, c] = t.map(|p| Vec3::new(p.x.to_f64(), p.y.to_f64(), p.z.to_f64()));
        for _ in 0..20 {
            let (s, u) = (rng.random_range(0.0..1.0), rng.random_range(0.0..1.0));
            let (s, u) = if s + u > 1.0 { (1.0 - s, 1.0 - u) } else { (s, u) };
            out.push(a + (b - a) * s + (c - a) * u);
        }
        for axis in 0..3 {
            for m in 1..8 {
                let plane = min[axis] + extent[axis] * (m as f64 / 8.0);
                // Where the plane meets edge `x → y`, if it does.
                let meet = |x: Vec3<f64>, y: Vec3<f64>| {
                    let s = (plane - x[axis]) / (y[axis] - x[axis]);
                    (s > 0.0 && s < 1.0).then(|| x + (y - x) * s)
                };
                if let Some(p) = meet(a, b)
                    && let Some(q) = meet(a, c).or_else(|| meet(b, c))
                {
                    for k in 1..4 {
                        out.push(p + (q - p) * (k as f64 / 4.0));
                    }
                }
            }
        }
    }
    out
}

fn same_queries<F: Float>() {
    let (linear, needles) = scene::<F>(Acceleration::Linear, BvhQuality::Medium);
    let (high, _) = scene::<F>(Acceleration::Bvh, BvhQuality::High);
    assert!(high.uses_bvh() && !linear.uses_bvh());
    let (medium, _) = scene::<F>(Acceleration::Bvh, BvhQuality::Medium);
    let (parts, references) = (medium.bvh_references().unwrap(), high.bvh_references().unwrap());
    assert!(
        references > parts + 100,
        "the needles cut: {references} references for {parts} parts"
    );
    let mut rng = DefaultRng::seed_from_u64(43);
    let targets = targets(&needles, &mut rng);
    assert!(targets.len() > 1100, "{} targets", targets.len());
    let mut hits = 0;
    for target in targets {
        let o = Vec3::from_f64(rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0), 0.0);
        let ray = Ray::towards(o, Vec3::from_f64(target.x, target.y, target.z)).unwrap();
        let a = linear.hit(&ray, F::infinity()).map(|(h, m)| (h, m.clone()));
        let b = high.hit(&ray, F::infinity()).map(|(h, m)| (h, m.clone()));
        assert_eq!(a, b, "{} {ray:?}", F::NAME);
        hits += usize::from(a.is_some());
        let t_max = lit(rng.random_range(1.0..25.0));
        assert_eq!(
            linear.occluded(&ray, t_max),
            high.occluded(&ray, t_max),
            "{ray:?} to {t_max:?}"
        );
    }
    assert!(hits > 1000, "the rays should mostly hit something ({hits})");
}

#[test]
fn cut_triangles_answer_like_the_loop_f32() {
    same_queries::<f32>();
}

#[test]
fn cut_triangles_answer_like_the_loop_f64() {
    same_queries::<f64>();
}

#[test]
fn cut_triangles_render_the_same_bytes() {
    let cam = ScreenCamera::new(48, 24).unwrap();
    let s = RenderSettings::new(2, 6, 1).unwrap();
    let (linear, _) = scene::<f32>(Acceleration::Linear, BvhQuality::Medium);
    let (medium, _) = scene::<f32>(Acceleration::Bvh, BvhQuality::Medium);
    let (high, _) = scene::<f32>(Acceleration::Bvh, BvhQuality::High);
    let a = render(&linear, &cam, &s).unwrap();
    for other in [&medium, &high] {
        let b = render(other, &cam, &s).unwrap();
        assert_eq!((&a.image, a.stats.rays), (&b.image, b.stats.rays));
    }
}
