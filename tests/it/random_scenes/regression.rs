//! A regression: a light grazing a surface overflowed to infinite and NaN pixels in f32.

use raytrace::prelude::*;

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
