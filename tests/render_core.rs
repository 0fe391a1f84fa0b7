//! The core renderer's contracts: both dispatch paths give the same bytes, a seed fixes
//! the image on any number of threads, tiles equal the whole, every scalar renders, and
//! `max_depth` is exact.

use rand::SeedableRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::shape::Hit;
use raytrace::{DefaultRng, Image, Intersection, SharedMaterial};
use std::sync::Arc;
use twofloat::TwoFloat;

/// The materials of the test scene, kept concrete so each path can wrap them its own way.
enum Part<F> {
    Mirror(Mirror<F>),
    Matte(Lambertian<F>),
}

/// A small scene with every core material: mirror, matte, and a matte ground.
fn parts<F: Float>() -> Vec<(Sphere<F>, Part<F>)> {
    let s = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r)).unwrap();
    vec![
        (
            s(-1.2, 0.0, -3.0, 0.8),
            Part::Mirror(Mirror::new(Vec3::from_f64(0.9, 0.7, 0.4)).unwrap()),
        ),
        (
            s(1.0, 0.0, -3.5, 0.8),
            Part::Matte(Lambertian::new(Vec3::from_f64(0.3, 0.5, 0.8)).unwrap()),
        ),
        (
            s(0.0, -100.8, -3.0, 100.0),
            Part::Matte(Lambertian::new(Vec3::from_f64(0.5, 0.5, 0.5)).unwrap()),
        ),
    ]
}

/// The fast path: enums stored inline.
fn enum_scene<F: Float>() -> EnumScene<F> {
    let mut scene = EnumScene::new(Background::default());
    for (shape, part) in parts::<F>() {
        let material: MaterialKind<F> = match part {
            Part::Mirror(m) => m.into(),
            Part::Matte(m) => m.into(),
        };
        scene.add(shape, material);
    }
    scene
}

/// The spec's path: a vector of smart pointers to trait objects.
fn dyn_scene<F: Float>() -> DynScene<F, DefaultRng> {
    let mut scene = DynScene::new(Background::default());
    for (shape, part) in parts::<F>() {
        let material: SharedMaterial<F, DefaultRng> = match part {
            Part::Mirror(m) => Arc::new(m).into(),
            Part::Matte(m) => Arc::new(m).into(),
        };
        scene.add(Box::new(shape), material);
    }
    scene
}

fn bytes(image: &Image) -> Vec<u8> {
    let mut out = Vec::new();
    raytrace::image::write_ppm_to(&mut out, &image.to_u16(Encoding::Srgb)).unwrap();
    out
}

fn settings(spp: u32, seed: u64) -> RenderSettings {
    RenderSettings::new(spp, 10, seed).unwrap()
}

fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

#[test]
fn trait_objects_and_enums_give_identical_bytes() {
    let cam = ScreenCamera::new(64, 32).unwrap();
    let a = render(&enum_scene::<f64>(), &cam, &settings(4, 9)).unwrap();
    let b = render(&dyn_scene::<f64>(), &cam, &settings(4, 9)).unwrap();
    assert_eq!(a.image, b.image);
    assert_eq!(bytes(&a.image), bytes(&b.image));
    assert_eq!(a.stats.rays, b.stats.rays);
    let a = render(&enum_scene::<f32>(), &cam, &settings(4, 9)).unwrap();
    let b = render(&dyn_scene::<f32>(), &cam, &settings(4, 9)).unwrap();
    assert_eq!(bytes(&a.image), bytes(&b.image));
}

#[test]
fn a_seed_fixes_the_image_on_any_number_of_threads() {
    let cam = ScreenCamera::new(64, 32).unwrap();
    let scene = enum_scene::<f32>();
    let one = in_pool(1, || render(&scene, &cam, &settings(3, 5)).unwrap());
    let two = in_pool(2, || render(&scene, &cam, &settings(3, 5)).unwrap());
    let many = in_pool(7, || render(&scene, &cam, &settings(3, 5)).unwrap());
    assert_eq!(one.stats.threads, 1);
    assert_eq!(bytes(&one.image), bytes(&two.image));
    assert_eq!(bytes(&one.image), bytes(&many.image));
    let other = render(&scene, &cam, &settings(3, 6)).unwrap();
    assert_ne!(
        one.image, other.image,
        "a different seed must change a matte scene"
    );
}

#[test]
fn a_tile_equals_the_same_pixels_of_the_whole_image() {
    let cam = ScreenCamera::new(64, 32).unwrap();
    let scene = enum_scene::<f64>();
    let whole = render(&scene, &cam, &settings(2, 1)).unwrap().image;
    for tile in [
        Rect {
            x: 5,
            y: 3,
            width: 17,
            height: 9,
        },
        Rect {
            x: 63,
            y: 31,
            width: 1,
            height: 1,
        },
    ] {
        let part = Renderer::new(&scene, &cam)
            .settings(settings(2, 1))
            .tile(tile)
            .render()
            .unwrap()
            .image;
        for y in 0..tile.height {
            for x in 0..tile.width {
                assert_eq!(part.pixel(x, y), whole.pixel(tile.x + x, tile.y + y));
            }
        }
    }
    let outside = Rect {
        x: 60,
        y: 0,
        width: 5,
        height: 1,
    };
    let outside = Renderer::new(&scene, &cam).tile(outside);
    assert!(outside.render().is_err());
    assert!(outside.render_reference().is_err());
}

#[test]
fn any_seedable_generator_works() {
    let cam = ScreenCamera::new(16, 8).unwrap();
    let scene = enum_scene::<f64>();
    let std_rng = Renderer::new(&scene, &cam)
        .settings(settings(2, 3))
        .rng::<rand::rngs::StdRng>();
    let a = std_rng.render().unwrap();
    assert_eq!(a.image, std_rng.render().unwrap().image);
    assert_eq!(a.image, std_rng.render_reference().unwrap().image);
    let default = render(&scene, &cam, &settings(2, 3)).unwrap();
    assert_ne!(a.image, default.image, "another generator draws other numbers");
}

#[test]
fn every_scalar_renders_and_follows_one_random_stream() {
    let cam = ScreenCamera::new(32, 16).unwrap();
    let s = settings(2, 4);
    let dd = render(&enum_scene::<raytrace::DoubleDouble>(), &cam, &s)
        .unwrap()
        .image;
    let tf = render(&enum_scene::<TwoFloat>(), &cam, &s).unwrap().image;
    assert!(tf.pixels().iter().flatten().all(|c| c.is_finite() && *c >= 0.0));
    let f64_ = render(&enum_scene::<f64>(), &cam, &s).unwrap().image;
    let f32_ = render(&enum_scene::<f32>(), &cam, &s).unwrap().image;
    // Same draws: the images agree almost everywhere; a path can differ only where
    // rounding flips a decision, so compare the median pixel difference.
    let median_diff = |a: &Image, b: &Image| {
        let mut d: Vec<f64> = a
            .pixels()
            .iter()
            .zip(b.pixels())
            .map(|(p, q)| (0..3).map(|k| (p[k] - q[k]).abs()).fold(0.0, f64::max))
            .collect();
        d.sort_by(f64::total_cmp);
        d[d.len() / 2]
    };
    assert!(median_diff(&dd, &f64_) < 1e-12, "{}", median_diff(&dd, &f64_));
    assert!(median_diff(&f64_, &f32_) < 1e-5, "{}", median_diff(&f64_, &f32_));
    assert!(dd.pixels().iter().flatten().all(|c| c.is_finite() && *c >= 0.0));
}

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
            hit.t,
            Vec3::new(p.x, wall, p.z),
            Vec3::zero(),
            normal,
            ray.direction,
        )
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

#[test]
fn invalid_values_are_rejected_with_typed_errors() {
    let v = Vec3::<f64>::splat(0.5);
    let bad_albedos = [
        Vec3::new(1.1, 0.5, 0.5),
        Vec3::new(-0.1, 0.5, 0.5),
        Vec3::new(f64::NAN, 0.5, 0.5),
    ];
    for a in bad_albedos {
        assert!(matches!(
            Mirror::new(a),
            Err(Error::InvalidValue {
                what: "mirror albedo",
                ..
            })
        ));
        assert!(matches!(
            Lambertian::new(a),
            Err(Error::InvalidValue {
                what: "matte albedo",
                ..
            })
        ));
    }
    assert!(matches!(
        Sphere::new(v, -1.0),
        Err(Error::InvalidValue {
            what: "sphere radius",
            ..
        })
    ));
    assert!(matches!(Sphere::new(v, 0.0), Err(Error::InvalidValue { .. })));
    assert!(matches!(
        Sphere::new(Vec3::new(0.0, f64::INFINITY, 0.0), 1.0),
        Err(Error::InvalidValue { .. })
    ));
    assert!(PointLight::new(v, Vec3::new(1.0, -1.0, 1.0)).is_err());
    assert!(Background::solid(Vec3::new(0.0, f64::NAN, 0.0)).is_err());
    assert!(matches!(
        RenderSettings::new(0, 10, 0),
        Err(Error::InvalidSettings(_))
    ));
    assert!(matches!(ScreenCamera::new(0, 0), Err(Error::InvalidSettings(_))));
    assert!(Image::new(0, 5).is_err());
    assert!(Image::new(usize::MAX, 2).is_err());
    let cam = ScreenCamera::new(4, 2).unwrap();
    let zero_spp = RenderSettings {
        samples_per_pixel: 0,
        ..RenderSettings::default()
    };
    assert!(render(&enum_scene::<f64>(), &cam, &zero_spp).is_err());
}

#[test]
fn the_spec_ppm_round_trips_through_the_reader() {
    let cam = ScreenCamera::new(20, 10).unwrap();
    let image = render(&enum_scene::<f64>(), &cam, &settings(1, 0)).unwrap().image;
    let text = bytes(&image);
    let lines: Vec<&str> = std::str::from_utf8(&text).unwrap().lines().collect();
    assert_eq!(&lines[..3], &["P3", "20 10", "65535"]);
    assert_eq!(lines.len(), 3 + 200, "one pixel per line");
    let parsed = raytrace::image::parse_ppm(&text).unwrap();
    assert_eq!(parsed, image.to_u16(Encoding::Srgb));
    // Top-left first: the first pixel looks up-left into the sky, the last down into the ground.
    let first = image.pixel(0, 0);
    assert_eq!(
        lines[3],
        format!(
            "{} {} {}",
            Encoding::Srgb.quantize(first[0]),
            Encoding::Srgb.quantize(first[1]),
            Encoding::Srgb.quantize(first[2])
        )
    );
    assert!(first[2] > first[0], "top-left pixel should be sky blue");
}

/// Objects hit at exactly the same distance: the one added first wins, through the plain
/// loop (spheres packed four at a time; the leftover one, and in f64 two, tested alone),
/// the BVH, and the trait objects alike.
#[test]
fn ties_go_to_the_object_added_first_on_every_path() {
    use raytrace::Acceleration;
    let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
    for (n, first) in [9usize, 10]
        .into_iter()
        .flat_map(|n| [0, 3, 5, n - 2, n - 1].map(|f| (n, f)))
    {
        // `n` spheres; two of them, `first` and the last, are the same sphere in front.
        let build = || {
            (0..n).map(move |i| {
                let c = if i == first || i == n - 1 {
                    Vec3::new(0.0, 0.0, -4.0)
                } else {
                    Vec3::new(i as f64, 3.0, -4.0)
                };
                (
                    Sphere::new(c, 1.0).unwrap(),
                    Mirror::new(Vec3::splat(0.01 * i as f64)).unwrap(),
                )
            })
        };
        for acceleration in [Acceleration::Linear, Acceleration::Bvh] {
            let mut scene = EnumScene::<f64>::new(Background::default());
            let mut dyn_scene = DynScene::<f64, DefaultRng>::new(Background::default());
            for (s, m) in build() {
                scene.add(s, m);
                dyn_scene.add(Box::new(s), Arc::new(m));
            }
            scene.set_acceleration(acceleration);
            dyn_scene.set_acceleration(acceleration);
            let (hit, material) = scene.hit(&ray, f64::INFINITY).unwrap();
            assert_eq!(hit.t, 3.0);
            let want = Mirror::new(Vec3::splat(0.01 * first as f64)).unwrap();
            assert_eq!(
                *material,
                MaterialKind::from(want),
                "{acceleration:?}, {n} spheres, first {first}"
            );
            let (dyn_hit, dyn_material) = dyn_scene.hit(&ray, f64::INFINITY).unwrap();
            assert_eq!(dyn_hit, hit);
            let probe = Hit::new(
                1.0,
                Vec3::zero(),
                Vec3::zero(),
                Vec3::new(0.0, 0.0, 1.0),
                ray.direction,
            );
            let mut rng = DefaultRng::seed_from_u64(0);
            let got = dyn_material.scatter(&ray, &probe, &mut rng).unwrap().attenuation;
            assert_eq!(
                got,
                want.albedo(),
                "dyn {acceleration:?}, {n} spheres, first {first}"
            );
        }
    }
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
