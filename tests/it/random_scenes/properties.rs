//! The properties, for f32 and f64: finite pixels, energy conservation, and the checks' power.

use super::scenes::*;
use super::{CASES, REGRESSIONS};
use crate::common::config;
use proptest::prelude::*;
use raytrace::prelude::*;
use raytrace::shape::Hit;
use raytrace::{BsdfSample, DefaultRng, Emission, Eval, Image, Lobes, Scatter};
use std::sync::Arc;

/// Renders `scene` (any dispatch path) through the described camera.
fn render_desc<F, S, M>(scene: &Scene<F, S, M>, d: &SceneDesc) -> Image
where
    F: Float,
    S: Layout<F> + Sync,
    M: Scatter<F, DefaultRng> + Sync,
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

impl<F: Float> Material<F> for Broken<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DELTA
    }
    fn reads_coordinates(&self) -> bool {
        false
    }
    fn eval(&self, _: &Hit<F>, _: Vec3<F>, _: Vec3<F>) -> Option<Eval<F>> {
        None
    }
    fn pdf(&self, _: &Hit<F>, _: Vec3<F>, _: Vec3<F>) -> F {
        F::zero()
    }
    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: rand::Rng + ?Sized> Scatter<F, R> for Broken<F> {
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, _rng: &mut R) -> Option<BsdfSample<F>> {
        Some(BsdfSample {
            direction: raytrace::optics::reflect(-wo, hit.normal),
            weight: Vec3::splat(self.gain),
            pdf: F::one(),
            lobe: Lobes::REFLECTION | Lobes::DELTA,
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
        let mut scene = DynScene::<F>::new(Background::solid(Vec3::splat(F::one())).unwrap());
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
