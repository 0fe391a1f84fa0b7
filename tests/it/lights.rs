//! The point-light extra: shadows, the inverse-square law with the cosine factor and the
//! BRDF `A/π`, and superposition (lights add to each other and to the sky). Every test runs
//! in f32 and f64.
//!
//! Direct light is isolated exactly by [`DirectOnly`], a test material that is a
//! Lambertian for the light loop (its `eval` is `A/π·cos θ`) but scatters nothing, so a
//! traced colour is the renderer's direct-light sum and nothing else.

use crate::common::Alone;
use rand::{Rng, SeedableRng};
use raytrace::DefaultRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::sampling::lambertian_direction;
use raytrace::shape::Hit;
use raytrace::{BsdfSample, Emission, Eval, Image, Lobes, Scatter};

/// A matte surface seen only by the lights: the renderer adds `A/π · I · cos θ / d²` for each
/// visible light and, as `sample` absorbs the ray, nothing else.
#[derive(Clone, Debug)]
struct DirectOnly<F>(Lambertian<F>);

impl<F: Float> Material<F> for DirectOnly<F> {
    fn lobes(&self) -> Lobes {
        self.0.lobes()
    }
    fn reads_coordinates(&self) -> bool {
        false
    }
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        self.0.eval(hit, wo, wi)
    }
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        self.0.pdf(hit, wo, wi)
    }
    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for DirectOnly<F> {
    fn sample(&self, _hit: &Hit<F>, _wo: Vec3<F>, _rng: &mut R) -> Option<BsdfSample<F>> {
        None
    }
}

type DirectScene<F> = Scene<F, ShapeKind<F>, DirectOnly<F>>;

/// The lit sphere: centre `(0, 0, −4)`, radius 1, seen from the origin.
const CENTER: [f64; 3] = [0.0, 0.0, -4.0];
const RADIUS: f64 = 1.0;
/// The albedo `A` of every lit surface.
const ALBEDO: [f64; 3] = [0.8, 0.5, 0.2];
/// The main light, up and towards the camera from the sphere's nearest point `(0, 0, −3)`.
const LIGHT: [f64; 3] = [0.0, 3.0, -1.0];
const INTENSITY: [f64; 3] = [2.0, 3.0, 4.0];
/// A second light, to the left.
const LIGHT2: [f64; 3] = [-2.0, 1.0, -2.0];
const INTENSITY2: [f64; 3] = [5.0, 1.0, 0.5];
/// The occluder's radius.
const OCCLUDER: f64 = 0.25;

fn v<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

fn sphere<F: Float>(c: [f64; 3], r: f64) -> Sphere<F> {
    Sphere::new(v(c), lit(r)).unwrap()
}

fn light<F: Float>(p: [f64; 3], i: [f64; 3]) -> PointLight<F> {
    PointLight::new(v(p), v(i)).unwrap()
}

fn black<F: Float>() -> Background<F> {
    Background::solid(Vec3::zero()).unwrap()
}

/// The lit sphere (made of [`DirectOnly`]), the given lights, and occluders of radius
/// [`OCCLUDER`] at the given centres; black background.
fn direct_scene<F: Float>(lights: &[([f64; 3], [f64; 3])], occluders: &[[f64; 3]]) -> DirectScene<F> {
    let mut scene = DirectScene::new(black());
    scene.add(
        sphere::<F>(CENTER, RADIUS),
        DirectOnly(Lambertian::new(v(ALBEDO)).unwrap()),
    );
    for &c in occluders {
        scene.add(
            sphere::<F>(c, OCCLUDER),
            DirectOnly(Lambertian::new(v(ALBEDO)).unwrap()),
        );
    }
    for &(p, i) in lights {
        scene.add_light(light(p, i));
    }
    scene
}

/// The colour of the camera ray from the origin towards `target`, with `max_depth` 1: at the
/// first hit the direct light is added and, for [`DirectOnly`], nothing more.
fn trace_direct<F: Float>(scene: &DirectScene<F>, target: [f64; 3]) -> Color<F> {
    let ray = Ray::towards(Vec3::zero(), v(target)).unwrap();
    let mut rng = DefaultRng::seed_from_u64(0);
    Tracer::new(scene, 1).trace(&ray, 0, &mut rng)
}

/// The sphere's nearest point `(0, 0, −3)`, straight down the camera's axis.
const NEAREST: [f64; 3] = [0.0, 0.0, -3.0];

fn mix(p: [f64; 3], q: [f64; 3], s: f64) -> [f64; 3] {
    [0, 1, 2].map(|k| p[k] + s * (q[k] - p[k]))
}

macro_rules! for_f32_and_f64 {
    ($($name:ident),* $(,)?) => {
        mod f32_tests {
            $(#[test] fn $name() { super::$name::<f32>(); })*
        }
        mod f64_tests {
            $(#[test] fn $name() { super::$name::<f64>(); })*
        }
    };
}

for_f32_and_f64!(
    occluder_on_the_shadow_ray_casts_a_shadow,
    lit_value_is_the_inverse_square_law,
    two_lights_add,
    lights_add_to_the_sky,
    whole_renders_are_linear_in_the_lights,
);

/// A point behind an occluder is black; the same occluder moved beside the shadow ray, or
/// past the light, leaves the point exactly as lit as with no occluder at all.
fn occluder_on_the_shadow_ray_casts_a_shadow<F: Float>() {
    let lights = [(LIGHT, INTENSITY)];
    let midway = mix(NEAREST, LIGHT, 0.5); // (0, 1.5, −2), 1.5 from the camera's axis
    let beside = [midway[0] + 2.0 * OCCLUDER, midway[1], midway[2]]; // the segment is in x = 0
    let beyond = mix(NEAREST, LIGHT, 1.5); // on the line, past the light

    let free = trace_direct(&direct_scene::<F>(&lights, &[]), NEAREST);
    assert!(free.min_element() > F::zero(), "lit with no occluder: {free:?}");
    let shadowed = trace_direct(&direct_scene::<F>(&lights, &[midway]), NEAREST);
    assert_eq!(shadowed, Color::zero(), "in the occluder's shadow");
    let lit_beside = trace_direct(&direct_scene::<F>(&lights, &[beside]), NEAREST);
    assert_eq!(lit_beside, free, "an occluder beside the shadow ray");
    let lit_beyond = trace_direct(&direct_scene::<F>(&lights, &[beyond]), NEAREST);
    assert_eq!(
        lit_beyond, free,
        "an occluder past the light (the shadow ray stops at it)"
    );
}

/// The exact direct light at the first hit of the camera ray towards `target`:
/// `Σ A/π · I · cos θ / d²` over the lights facing the surface, in f64 from the exact
/// geometry. Also returns, per channel, the scale `Σ A/π · I / d²` over all the lights (the
/// value with every `cos θ = 1`), which bounds how much rounding can move each term, and the
/// smallest light distance.
fn expected_direct(target: [f64; 3], lights: &[([f64; 3], [f64; 3])]) -> ([f64; 3], [f64; 3], f64) {
    let d = Vec3::new(target[0], target[1], target[2]).normalize();
    let c = Vec3::new(CENTER[0], CENTER[1], CENTER[2]);
    // |tD − C|² = r²: t = D·C − √((D·C)² − |C|² + r²).
    let b = d.dot(c);
    let disc = b * b - c.length_squared() + RADIUS * RADIUS;
    assert!(
        disc > 0.0,
        "test geometry: the ray towards {target:?} misses the sphere"
    );
    let t = b - disc.sqrt();
    let p = d * t;
    let n = (p - c) / RADIUS;
    let (mut sum, mut scale, mut min_d) = ([0.0; 3], [0.0; 3], f64::INFINITY);
    for &(pos, i) in lights {
        let to = Vec3::new(pos[0], pos[1], pos[2]) - p;
        let cos = n.dot(to) / to.length();
        min_d = min_d.min(to.length());
        for k in 0..3 {
            let term = ALBEDO[k] / std::f64::consts::PI * i[k] / to.length_squared();
            scale[k] += term;
            if cos > 0.0 {
                sum[k] += term * cos;
            }
        }
    }
    (sum, scale, min_d)
}

/// The lit value is `A/π · I · cos θ / d²` (summed over two lights, one of them behind the
/// surface at some points) to within a tolerance derived from the precision of `F`.
fn lit_value_is_the_inverse_square_law<F: Float>() {
    let lights = [(LIGHT, INTENSITY), (LIGHT2, INTENSITY2)];
    let scene = direct_scene::<F>(&lights, &[]);
    let mut faced = 0;
    // All inside the sphere's silhouette, a disc of radius 3·tan(asin ¼) ≈ 0.77 at z = −3.
    for x in [-0.5, -0.2, 0.0, 0.3, 0.5] {
        for y in [-0.45, 0.0, 0.25, 0.5] {
            let target = [x, y, -3.0];
            let got = trace_direct(&scene, target).to_f64();
            let (want, scale, min_d) = expected_direct(target, &lights);
            // Each term `A/π · I · cos θ/d²` is a smooth function of the hit point, the
            // normal and the light position, varying on the length scale min(r, d); these
            // are computed from coordinates of size up to |C| + r + |L| ≈ 8.2, each to about
            // a dozen roundings of relative ε. So a term moves by at most
            // `k ε · size/min(r, d) · A/π · I/d²` with `k` = 16, also when cos θ ≈ 0 (where
            // rounding may include or drop a term, whose size is then below that bound).
            // (Measured: at most a tenth of this bound, 14 ε relative in f32.)
            let size = 4.0 + 1.0 + 3.2;
            let tol = 16.0 * F::epsilon().to_f64() * size / RADIUS.min(min_d);
            for k in 0..3 {
                let err = (got[k] - want[k]).abs();
                assert!(
                    err <= tol * scale[k],
                    "{} at {target:?} channel {k}: got {}, want {}, err {:e} > {:e}",
                    F::NAME,
                    got[k],
                    want[k],
                    err,
                    tol * scale[k]
                );
            }
            faced += usize::from(want[0] > 0.0);
        }
    }
    assert!(faced >= 10, "most points must be lit, {faced} were");
}

/// Two lights give exactly the sum of each alone: the renderer adds them in order from
/// zero, and `0 + x = x`, so the comparison is bit for bit.
fn two_lights_add<F: Float>() {
    for target in [NEAREST, [0.3, -0.2, -3.0], [-0.5, 0.4, -3.0]] {
        let one = trace_direct(&direct_scene::<F>(&[(LIGHT, INTENSITY)], &[]), target);
        let two = trace_direct(&direct_scene::<F>(&[(LIGHT2, INTENSITY2)], &[]), target);
        let both = trace_direct(
            &direct_scene::<F>(&[(LIGHT, INTENSITY), (LIGHT2, INTENSITY2)], &[]),
            target,
        );
        assert!(
            one.max_element() > F::zero() && two.max_element() > F::zero(),
            "{target:?}"
        );
        assert_eq!(both, one + two, "{} at {target:?}", F::NAME);
    }
}

/// With a sky and a real [`Lambertian`] sphere, `max_depth` 1, a camera ray's colour is the
/// direct light plus `A ∘ sky(D⁺)`, `D⁺` the scattered direction (drawn from the same
/// stream): the lights add to the sky. Bit for bit, as both sides do the same operations.
/// (It also checks that the scattered ray does not re-hit its own convex sphere: that would
/// return black at the depth limit.)
fn lights_add_to_the_sky<F: Float>() {
    let sky = Background::<F>::default();
    let mut scene = EnumScene::new(sky.clone());
    let matte = Lambertian::new(v::<F>(ALBEDO)).unwrap();
    scene.add(sphere::<F>(CENTER, RADIUS), matte);
    scene.add_light(light(LIGHT, INTENSITY));
    let direct_only = direct_scene::<F>(&[(LIGHT, INTENSITY)], &[]);
    let mut added = 0;
    for (seed, target) in [NEAREST, [0.3, -0.2, -3.0], [-0.5, 0.4, -3.0], [0.1, 0.7, -3.0]]
        .into_iter()
        .enumerate()
    {
        let ray = Ray::towards(Vec3::zero(), v::<F>(target)).unwrap();
        let mut rng = DefaultRng::seed_from_u64(seed as u64);
        let mut replay = rng.clone();
        let got = Tracer::new(&scene, 1).trace(&ray, 0, &mut rng);

        let hit = sphere::<F>(CENTER, RADIUS).hit(&ray, F::infinity()).unwrap();
        let direct = trace_direct(&direct_only, target);
        let sky_lit = v::<F>(ALBEDO) * sky.color(lambertian_direction(hit.normal, &mut replay));
        assert_eq!(got, direct + sky_lit, "{} at {target:?}", F::NAME);
        assert!(sky_lit.min_element() > F::zero());
        added += usize::from(direct.max_element() > F::zero());
    }
    assert!(added >= 3, "the light must reach most of these points");
}

fn render_lights<F: Float>(lights: &[([f64; 3], [f64; 3])], settings: &RenderSettings) -> Image {
    let mut scene = EnumScene::<F>::new(black());
    scene.add(sphere::<F>(CENTER, RADIUS), Lambertian::new(v(ALBEDO)).unwrap());
    scene.add(
        sphere::<F>([0.0, -101.0, -4.0], 100.0),
        Lambertian::new(Vec3::splat(lit(0.5))).unwrap(),
    );
    scene.add(
        sphere::<F>(mix(NEAREST, LIGHT, 0.5), OCCLUDER),
        Mirror::new(v(ALBEDO)).unwrap(),
    );
    for &(p, i) in lights {
        scene.add_light(light(p, i));
    }
    render(&scene, &ScreenCamera::new(48, 24).unwrap(), settings)
        .unwrap()
        .image
}

/// Whole renders with bounces (matte sphere, matte ground, a mirror occluder, black
/// background): with no light the image is black; the image with two lights is the sum of
/// the images with each, pixel by pixel. The scattered paths are the same in all three (the
/// lights draw no random numbers), so only rounding separates them: each path adds and
/// multiplies a few numbers per bounce and the pixel averages its samples, so the relative
/// difference is within `γ(8·(max_depth + spp))`.
fn whole_renders_are_linear_in_the_lights<F: Float>() {
    let settings = RenderSettings::new(4, 4, 99).unwrap();
    let none = render_lights::<F>(&[], &settings);
    assert!(
        none.pixels().iter().all(|p| *p == [0.0; 3]),
        "no light, no colour"
    );
    let one = render_lights::<F>(&[(LIGHT, INTENSITY)], &settings);
    let two = render_lights::<F>(&[(LIGHT2, INTENSITY2)], &settings);
    let both = render_lights::<F>(&[(LIGHT, INTENSITY), (LIGHT2, INTENSITY2)], &settings);
    let tol = F::gamma(8 * (4 + 4)).to_f64();
    let mut lit_pixels = 0;
    for ((a, b), c) in one.pixels().iter().zip(two.pixels()).zip(both.pixels()) {
        for k in 0..3 {
            let sum = a[k] + b[k];
            assert!(
                (c[k] - sum).abs() <= tol * sum,
                "{}: {c:?} vs {a:?} + {b:?}",
                F::NAME
            );
        }
        lit_pixels += usize::from(c[0] > 0.0);
    }
    assert!(
        lit_pixels > one.pixels().len() / 4,
        "only {lit_pixels} pixels lit"
    );
}
