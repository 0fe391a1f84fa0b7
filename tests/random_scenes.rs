//! Renders of randomly generated valid scenes: no NaN or
//! infinite pixel and no negative channel, ever; and energy conservation where the scene
//! has no light source brighter than 1. Each property runs for f32 and f64 with a fixed
//! proptest seed.
//!
//! # The scenes
//! One to twelve objects, intersected through `Auto`, the plain loop or a forced BVH
//! (with fewer than [`Acceleration::AUTO_THRESHOLD`] bounded objects `Auto` loops): spheres of radius `10^U(−4, 4)` through a point near the camera (from specks to
//! walls, and now and then a sphere that swallows the camera),
//! planes through any point with any normal, and triangles of size `10^U(−4, 2)`, all near
//! the camera (positions in `[−6, 6]² × [−14, 4]`). Materials: mirror, matte and glass;
//! albedo channels exactly 0, exactly 1, or uniform in `[0, 1]`; glass indices exactly 1,
//! in `[1, 3]`, or below 1 (`[0.3, 1)`, a bubble), with Schlick's or the exact Fresnel
//! reflectance. Zero to three point lights, intensity channels 0, or up to 100, anywhere —
//! including exactly on a surface (a plane's point, a sphere's pole, a triangle's vertex).
//! A solid or sky background with channels in `[0, 2]` (exactly 2 one time in three). The spec's [`ScreenCamera`]
//! (8×4 or 16×8) or a [`LookAtCamera`] (8×8, field of view 10° to 170°, anywhere, looking
//! anywhere). One to four samples per pixel, depth 0 to 12, any seed.
//!
//! # Energy conservation
//! With no point lights and a background whose channels are at most 1, a path's colour is
//! the background seen by its last ray (at most 1 per channel: a sky is a convex
//! combination of its two colours) times the albedos of the surfaces it met, each at most 1
//! per channel (the constructors enforce it), or black (absorbed or too deep); a glass
//! surface chooses reflection or refraction with probabilities summing to 1, each path
//! carrying the albedo, so no path gains energy either. Nothing in the scene emits. So
//! every sample is at most 1 per channel, and so is a pixel, their mean. In floating point
//! a product of numbers `≤ 1` rounds to at most 1 (rounding is monotone and 1 is
//! representable); the sky's weight `s = (y + 1)/2` may exceed 1 by a few ulps for a
//! direction whose `y` rounds above 1, and the mean of `n` samples adds `γ(n)`: the bound
//! is `1 + (n + 8)ε`.

mod common;

use common::{config, unit_f64};
use proptest::prelude::*;
use raytrace::material::Reflectance;
use raytrace::prelude::*;
use raytrace::shape::Hit;
use raytrace::{Acceleration, DefaultRng, Image, Scatter};
use std::sync::Arc;

const REGRESSIONS: &str = "proptest-regressions/random_scenes.txt";

/// Cases per property and scalar: a case renders at most 16×8 pixels × 4 samples × 13
/// bounces (well under a millisecond), so the file runs in a second or two.
const CASES: u32 = 3000;

#[derive(Clone, Debug)]
enum ShapeDesc {
    Sphere { c: [f64; 3], r: f64 },
    Plane { p: [f64; 3], n: [f64; 3] },
    Triangle([[f64; 3]; 3]),
}

#[derive(Clone, Debug)]
enum MaterialDesc {
    Mirror([f64; 3]),
    Matte([f64; 3]),
    Glass {
        index: f64,
        albedo: [f64; 3],
        fresnel: bool,
    },
}

#[derive(Clone, Debug)]
enum CameraDesc {
    Screen(usize),
    LookAt {
        from: [f64; 3],
        at: [f64; 3],
        up: [f64; 3],
        vfov: f64,
    },
}

#[derive(Clone, Debug)]
struct SceneDesc {
    objects: Vec<(ShapeDesc, MaterialDesc)>,
    lights: Vec<([f64; 3], [f64; 3])>,
    /// `(horizon, zenith)`; the same colour twice for a solid background.
    background: ([f64; 3], [f64; 3], bool),
    acceleration: Acceleration,
    camera: CameraDesc,
    spp: u32,
    max_depth: u32,
    seed: u64,
}

fn v<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

fn position() -> impl Strategy<Value = [f64; 3]> {
    [-6.0f64..6.0, -6.0f64..6.0, -14.0f64..4.0]
}

fn pow10(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|e| 10f64.powf(e))
}

fn shape() -> impl Strategy<Value = ShapeDesc> {
    // A sphere through a point q near the camera, its centre r away along u. Four times in
    // five u points away from the world origin (q·u ≥ 0), which keeps the spec camera's
    // eye outside even the largest spheres (they act as walls and floors); otherwise a big
    // sphere may enclose the eye.
    let sphere = (position(), unit_f64(), pow10(-4.0, 4.0), 0u8..5).prop_map(|(q, u, r, k)| {
        let outward = if k > 0 && common::dot(q, u) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let c = std::array::from_fn(|i| q[i] + outward * r * u[i]);
        ShapeDesc::Sphere { c, r }
    });
    let normal = prop_oneof![
        Just([0.0, 1.0, 0.0]),
        Just([0.0, 0.0, 1.0]),
        Just([-1.0, 0.0, 0.0]),
        unit_f64(),
    ];
    let plane = (position(), normal).prop_map(|(p, n)| ShapeDesc::Plane { p, n });
    // Two edges of length s and k·s at an angle θ ∈ [0.3, π − 0.3]: never degenerate, in
    // f32 either (the positions' rounding is below 10⁻⁶, the edges at least 10⁻⁴).
    let triangle = (
        position(),
        unit_f64(),
        unit_f64(),
        pow10(-4.0, 2.0),
        0.3f64..3.0,
        0.3f64..(std::f64::consts::PI - 0.3),
    )
        .prop_map(|(a, u, w, s, k, theta)| {
            let u = common::normalize(u);
            let perp = common::normalize(common::cross(u, w));
            let perp = if perp.iter().all(|c| c.is_finite()) {
                perp
            } else {
                common::frame(u).0
            };
            let b: [f64; 3] = std::array::from_fn(|i| a[i] + s * u[i]);
            let c: [f64; 3] =
                std::array::from_fn(|i| a[i] + k * s * (theta.cos() * u[i] + theta.sin() * perp[i]));
            ShapeDesc::Triangle([a, b, c])
        });
    prop_oneof![4 => sphere, 1 => plane, 2 => triangle]
}

/// An albedo channel: exactly 0, exactly 1, or uniform in `[0, 1]`.
fn channel() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 1 => Just(1.0), 3 => 0.0f64..=1.0]
}

fn albedo() -> impl Strategy<Value = [f64; 3]> {
    [channel(), channel(), channel()]
}

fn material() -> impl Strategy<Value = MaterialDesc> {
    let index = prop_oneof![1 => Just(1.0), 3 => 1.0f64..3.0, 1 => 0.3f64..1.0];
    prop_oneof![
        albedo().prop_map(MaterialDesc::Mirror),
        albedo().prop_map(MaterialDesc::Matte),
        (index, albedo(), any::<bool>()).prop_map(|(index, albedo, fresnel)| MaterialDesc::Glass {
            index,
            albedo,
            fresnel
        }),
    ]
}

/// A light's position: anywhere, or exactly on the surface of one of the objects.
fn light(objects: &[(ShapeDesc, MaterialDesc)]) -> impl Strategy<Value = ([f64; 3], [f64; 3])> + use<> {
    let on_surface: Vec<[f64; 3]> = objects
        .iter()
        .map(|(s, _)| match s {
            ShapeDesc::Sphere { c, r } => [c[0], c[1] + r, c[2]],
            ShapeDesc::Plane { p, .. } => *p,
            ShapeDesc::Triangle(v) => v[0],
        })
        .collect();
    let intensity = [0.0f64..100.0, 0.0f64..100.0, 0.0f64..100.0];
    let intensity = prop_oneof![1 => Just([0.0; 3]), 4 => intensity];
    (
        prop_oneof![2 => position(), 1 => prop::sample::select(on_surface)],
        intensity,
    )
}

fn camera() -> impl Strategy<Value = CameraDesc> {
    let look_at = (position(), position(), unit_f64(), 10.0f64..170.0)
        .prop_map(|(from, at, up, vfov)| CameraDesc::LookAt { from, at, up, vfov });
    prop_oneof![
        prop::sample::select(vec![8usize, 16]).prop_map(CameraDesc::Screen),
        look_at
    ]
}

/// A valid scene; `lit` says whether it may have point lights, and `max_background` bounds
/// the background's channels.
fn scene(lit: bool, max_background: f64) -> impl Strategy<Value = SceneDesc> {
    // Channels often exactly at the maximum (a white sky is where the energy bound is tight).
    let channel = move || prop_oneof![1 => Just(max_background), 2 => 0.0..=max_background];
    let colour = move || [channel(), channel(), channel()];
    let objects = prop::collection::vec((shape(), material()), 1..13);
    let acceleration =
        prop::sample::select(vec![Acceleration::Auto, Acceleration::Linear, Acceleration::Bvh]);
    (
        objects,
        (colour(), colour(), any::<bool>()),
        acceleration,
        camera(),
        (1u32..5, 0u32..13, any::<u64>()),
    )
        .prop_flat_map(
            move |(objects, background, acceleration, camera, (spp, max_depth, seed))| {
                let n_lights = if lit { 0..4 } else { 0..1 };
                let lights = prop::collection::vec(light(&objects), n_lights);
                (lights, Just(objects)).prop_map(move |(lights, objects)| SceneDesc {
                    objects,
                    lights,
                    background,
                    acceleration,
                    camera: camera.clone(),
                    spp,
                    max_depth,
                    seed,
                })
            },
        )
}

/// The scene in `F`. Every value is valid by construction, so a constructor error fails
/// the test.
fn build<F: Float>(d: &SceneDesc) -> EnumScene<F> {
    let (horizon, zenith, solid) = d.background;
    let background = if solid {
        Background::solid(v(horizon))
    } else {
        Background::sky(v(horizon), v(zenith))
    };
    let mut scene = EnumScene::<F>::new(background.unwrap());
    scene.set_acceleration(d.acceleration);
    for (s, m) in &d.objects {
        let shape: ShapeKind<F> = match s {
            ShapeDesc::Sphere { c, r } => Sphere::new(v(*c), lit(*r)).unwrap().into(),
            ShapeDesc::Plane { p, n } => Plane::new(v(*p), v(*n)).unwrap().into(),
            ShapeDesc::Triangle([a, b, c]) => Triangle::new(v(*a), v(*b), v(*c))
                .unwrap_or_else(|e| panic!("{}: {e}", F::NAME))
                .into(),
        };
        let material: MaterialKind<F> = match m {
            MaterialDesc::Mirror(a) => Mirror::new(v(*a)).unwrap().into(),
            MaterialDesc::Matte(a) => Lambertian::new(v(*a)).unwrap().into(),
            MaterialDesc::Glass {
                index,
                albedo,
                fresnel,
            } => {
                let glass = Dielectric::new(lit(*index))
                    .unwrap()
                    .with_albedo(v(*albedo))
                    .unwrap();
                let mode = if *fresnel {
                    Reflectance::Fresnel
                } else {
                    Reflectance::Schlick
                };
                glass.with_reflectance(mode).into()
            }
        };
        scene.add(shape, material);
    }
    for (p, i) in &d.lights {
        scene.add_light(PointLight::new(v(*p), v(*i)).unwrap());
    }
    scene
}

/// Renders `scene` (any dispatch path) through the described camera.
fn render_desc<F, S, M>(scene: &Scene<F, S, M>, d: &SceneDesc) -> Image
where
    F: Float,
    S: Layout<F> + Sync,
    M: Material<F, DefaultRng> + Sync,
{
    let settings = RenderSettings::new(d.spp, d.max_depth, d.seed).unwrap();
    let result = match &d.camera {
        CameraDesc::Screen(w) => render(scene, &ScreenCamera::new(*w, *w / 2).unwrap(), &settings),
        CameraDesc::LookAt { from, at, up, vfov } => {
            let camera = LookAtCamera::new(v(*from), v(*at), v::<F>(*up), lit(*vfov), 8, 8);
            // Random from/at/up can be (nearly) degenerate; then the spec's camera is used.
            match camera {
                Ok(camera) => render(scene, &camera, &settings),
                Err(_) => render(scene, &ScreenCamera::new(8, 4).unwrap(), &settings),
            }
        }
    };
    result.expect("valid settings render").image
}

/// Every pixel is finite and non-negative; with `max = Some(m)`, every channel is also at
/// most `m`.
fn check_pixels(image: &Image, max: Option<f64>) -> Result<(), TestCaseError> {
    for (k, p) in image.pixels().iter().enumerate() {
        let (x, y) = (k % image.width(), k / image.width());
        prop_assert!(p.iter().all(|c| c.is_finite()), "pixel ({x}, {y}) = {p:?}");
        prop_assert!(
            p.iter().all(|&c| c >= 0.0),
            "pixel ({x}, {y}) = {p:?} is negative"
        );
        if let Some(m) = max {
            prop_assert!(
                p.iter().all(|&c| c <= m),
                "pixel ({x}, {y}) = {p:?} exceeds {m}: energy gained"
            );
        }
    }
    Ok(())
}

/// The energy bound of the module docs: `1 + (spp + 8)ε`.
fn energy_bound<F: Float>(spp: u32) -> f64 {
    1.0 + f64::from(spp + 8) * F::epsilon().to_f64()
}

fn check_finite<F: Float>(d: &SceneDesc) -> Result<(), TestCaseError> {
    check_pixels(&render_desc(&build::<F>(d), d), None)
}

fn check_energy<F: Float>(d: &SceneDesc) -> Result<(), TestCaseError> {
    prop_assert!(d.lights.is_empty());
    check_pixels(&render_desc(&build::<F>(d), d), Some(energy_bound::<F>(d.spp)))
}

/// A test material that breaks the physics on purpose: it scatters like a mirror but
/// returns `gain` as its attenuation (more than 1, or NaN).
struct Broken<F> {
    gain: F,
}

impl<F: Float> Material<F, DefaultRng> for Broken<F> {
    fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, _rng: &mut DefaultRng) -> Option<Scatter<F>> {
        Some(Scatter {
            attenuation: Vec3::splat(self.gain),
            direction: raytrace::optics::reflect(ray.direction, hit.normal),
        })
    }
}

/// The checks have power: the same random geometry, under a white background, with every
/// material replaced by one that amplifies (gain 1.25) fails the energy check, and by one
/// whose attenuation is NaN fails the finiteness check (the scenes go through
/// [`DynScene`], the other dispatch path). A scene escapes only if no camera ray meets an
/// object (or, for the gain, every path is cut at `max_depth`).
fn checks_reject_broken_materials<F: Float>() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{RngSeed, TestRunner};
    let mut runner = TestRunner::new(ProptestConfig {
        rng_seed: RngSeed::Fixed(0xB0_4E),
        ..ProptestConfig::default()
    });
    let dyn_scene = |d: &SceneDesc, gain: F| {
        let mut scene = DynScene::<F, DefaultRng>::new(Background::solid(Vec3::splat(F::one())).unwrap());
        for o in build::<F>(d).objects() {
            let shape: Box<dyn Hittable<F> + Send + Sync> = Box::new(o.shape.clone());
            scene.add(shape, Arc::new(Broken { gain }));
        }
        scene
    };
    let (mut gained, mut nan) = (0, 0);
    for _ in 0..200 {
        let d = scene(false, 1.0).new_tree(&mut runner).unwrap().current();
        let bound = Some(energy_bound::<F>(d.spp));
        gained += usize::from(check_pixels(&render_desc(&dyn_scene(&d, lit(1.25)), &d), bound).is_err());
        nan += usize::from(check_pixels(&render_desc(&dyn_scene(&d, F::nan()), &d), None).is_err());
    }
    println!(
        "{}: of 200 scenes, {gained} gained energy and {nan} had NaN pixels",
        F::NAME
    );
    assert!(
        gained >= 100,
        "{}: the energy check caught only {gained} of 200",
        F::NAME
    );
    assert!(
        nan >= 100,
        "{}: the finiteness check caught only {nan} of 200",
        F::NAME
    );
}

/// Regression (was a bug): valid f32 scenes rendered infinite and NaN pixels.
/// A matte floor `y = 0` with a light `3·10⁻¹⁹` above it, seen from `10⁻¹³` above: the
/// shadow ray's origin (offset by the hit's error bound, `~10⁻¹⁹` this close to the world
/// origin) is `~2·10⁻¹⁹` from the light, so `A/π·I·cos θ/d²` overflows to `∞`; seen
/// through a mirror tinted `(1, 0, 1)`, the tint's `0·∞` is NaN. The random scenes have
/// coordinates of order 1 (so shadow-ray offsets of order `10⁻⁷` in f32) and never meet
/// this. The tracer now caps each colour at `F::max_value()`, so every value stays finite.
#[test]
fn regression_light_grazing_a_surface_overflows_in_f32() {
    let (h, l) = (1e-13f32, 3e-19f32);
    let floor = || Plane::new(Vec3::zero(), Vec3::new(0.0f32, 1.0, 0.0)).unwrap();
    let black = || Background::solid(Vec3::<f32>::zero()).unwrap();
    let light = || PointLight::new(Vec3::new(0.0, l, 0.0), Vec3::splat(100.0)).unwrap();
    let mut direct = EnumScene::<f32>::new(black());
    direct.add(floor(), Lambertian::new(Vec3::splat(1.0)).unwrap());
    direct.add_light(light());
    let down = LookAtCamera::new(
        Vec3::new(0.0, h, 0.0),
        Vec3::zero(),
        Vec3::new(0.0, 0.0, -1.0),
        40.0,
        1,
        1,
    );
    let image = render(&direct, &down.unwrap(), &RenderSettings::new(1, 1, 0).unwrap())
        .unwrap()
        .image;
    let mut mirrored = EnumScene::<f32>::new(black());
    mirrored.add(floor(), Lambertian::new(Vec3::splat(1.0)).unwrap());
    let ceiling = Plane::new(Vec3::new(0.0, 2.0 * h, 0.0), Vec3::new(0.0, -1.0, 0.0)).unwrap();
    mirrored.add(ceiling, Mirror::new(Vec3::new(1.0, 0.0, 1.0)).unwrap());
    mirrored.add_light(PointLight::new(Vec3::new(0.0, 5e-19, 0.0), Vec3::splat(100.0)).unwrap());
    let up = LookAtCamera::new(
        Vec3::new(0.0, h, 0.0),
        Vec3::new(0.0, 2.0 * h, 0.0),
        Vec3::new(0.0, 0.0, -1.0),
        40.0,
        1,
        1,
    );
    let through_mirror = render(&mirrored, &up.unwrap(), &RenderSettings::new(1, 3, 0).unwrap())
        .unwrap()
        .image;
    let (a, b) = (image.pixel(0, 0), through_mirror.pixel(0, 0));
    assert!(
        a.iter().chain(&b).all(|c| c.is_finite()),
        "direct {a:?}, through the tinted mirror {b:?}"
    );
}

macro_rules! scene_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(CASES, $seed, REGRESSIONS))]

                #[test]
                fn every_pixel_is_finite_and_non_negative(d in scene(true, 2.0)) {
                    check_finite::<$F>(&d)?;
                }

                #[test]
                fn no_pixel_gains_energy_without_lights(d in scene(false, 1.0)) {
                    check_energy::<$F>(&d)?;
                }
            }

            #[test]
            fn the_checks_reject_broken_materials() {
                checks_reject_broken_materials::<$F>();
            }
        }
    };
}

scene_tests!(single, f32, 0x5CE_0032);
scene_tests!(double, f64, 0x5CE_0064);
