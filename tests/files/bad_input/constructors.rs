//! The constructor properties, for f32 and f64, and the screen camera, settings and image sizes.

use super::strategies::*;
use super::verdicts::Verdict::{self, *};
use super::verdicts::*;
use super::{CASES, REGRESSIONS};
use crate::common::config;
use proptest::prelude::*;
use raytrace::{
    Background, Dielectric, Float, Image, Lambertian, LookAtCamera, Mirror, Plane, PointLight,
    RenderSettings, ScreenCamera, Sphere, Triangle, Vec3,
};

fn check_sphere<F: Float>(c: Vec3<F>, r: F) -> Result<(), TestCaseError> {
    let inputs = [
        ("sphere centre", Verdict::from_bool(finite3(c))),
        ("sphere radius", positive(r)),
    ];
    expect(&format!("Sphere::new({c:?}, {r:?})"), Sphere::new(c, r), &inputs)?;
    if let Err(e) = Sphere::new(Vec3::zero(), r) {
        // The offending value is quoted, as the library's errors document: it reads back.
        let e = e.to_string();
        let quoted = e.split("(got ").nth(1).and_then(|t| t.split(')').next());
        let back = quoted.and_then(|q| q.parse::<f64>().ok()).map(F::from_f64);
        prop_assert!(
            back == Some(r) || (r.is_nan() && quoted == Some("NaN")),
            "{e} does not quote {r}"
        );
    }
    Ok(())
}

fn check_plane<F: Float>(p: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    let normal = if finite3(n) {
        direction(scaled(exact(n)).as_ref())
    } else {
        Invalid
    };
    let inputs = [
        ("plane point", Verdict::from_bool(finite3(p))),
        ("plane normal", normal),
    ];
    expect(&format!("Plane::new({p:?}, {n:?})"), Plane::new(p, n), &inputs)
}

fn check_triangle<F: Float>([a, b, c]: [Vec3<F>; 3]) -> Result<(), TestCaseError> {
    let inputs = [("triangle", triangle(a, b, c))];
    expect(
        &format!("Triangle::new({a:?}, {b:?}, {c:?})"),
        Triangle::new(a, b, c),
        &inputs,
    )
}

fn check_materials<F: Float>(a: Vec3<F>, n: F) -> Result<(), TestCaseError> {
    expect(
        &format!("Mirror::new({a:?})"),
        Mirror::new(a),
        &[("mirror albedo", albedo(a))],
    )?;
    expect(
        &format!("Lambertian::new({a:?})"),
        Lambertian::new(a),
        &[("matte albedo", albedo(a))],
    )?;
    expect(
        &format!("Dielectric::new({n:?})"),
        Dielectric::new(n),
        &[("refractive index", positive(n))],
    )?;
    let glass = Dielectric::new(F::one()).unwrap().with_albedo(a);
    expect(
        &format!("Dielectric::with_albedo({a:?})"),
        glass,
        &[("dielectric albedo", albedo(a))],
    )
}

fn check_light_and_background<F: Float>(p: Vec3<F>, i: Vec3<F>, h: Vec3<F>) -> Result<(), TestCaseError> {
    let inputs = [
        ("light position", Verdict::from_bool(finite3(p))),
        ("light intensity", non_negative(i)),
    ];
    expect(
        &format!("PointLight::new({p:?}, {i:?})"),
        PointLight::new(p, i),
        &inputs,
    )?;
    expect(
        &format!("Background::solid({i:?})"),
        Background::solid(i),
        &[("background colour", non_negative(i))],
    )?;
    let inputs = [
        ("sky horizon colour", non_negative(h)),
        ("sky zenith colour", non_negative(i)),
    ];
    expect(
        &format!("Background::sky({h:?}, {i:?})"),
        Background::sky(h, i),
        &inputs,
    )
}

/// The look-at camera: size, then `from`, `at`, the view direction `from − at`, `up` (finite,
/// a direction, not parallel to the view), `vfov ∈ (0°, 180°)`.
fn check_look_at<F: Float>(
    (from, at, up): (Vec3<F>, Vec3<F>, Vec3<F>),
    vfov: F,
    (w, h): (usize, usize),
) -> Result<(), TestCaseError> {
    let (fits, view) = difference(from, at);
    let view_ok = if !(finite3(from) && finite3(at)) {
        Valid // not reached: from or at is already invalid
    } else {
        fits.and(direction(view.as_ref()))
    };
    let up_ok = if !finite3(up) {
        Invalid
    } else {
        let eps = F::epsilon().to_f64();
        let up_s = scaled(exact(up));
        let parallel = match (&up_s, &view) {
            (Some(u), Some(v)) => Some(sine(u, v)),
            _ => None,
        };
        let parallel = match parallel {
            None => Valid, // up is zero (judged below) or the view is (judged above)
            Some(s) if s <= 0.25 * eps => Invalid,
            Some(s) if s <= 64.0 * eps => Either,
            Some(_) => Valid,
        };
        direction(up_s.as_ref()).and(parallel)
    };
    let fov = Verdict::from_bool(vfov > F::zero() && vfov < F::from_f64(180.0));
    let inputs = [
        ("image size", Verdict::from_bool(size_ok(w, h))),
        ("camera position", Verdict::from_bool(finite3(from))),
        ("camera target", Verdict::from_bool(finite3(at))),
        ("camera view direction", view_ok),
        ("camera up vector", up_ok),
        ("camera field of view", fov),
    ];
    let call = format!("LookAtCamera::new({from:?}, {at:?}, {up:?}, {vfov:?}, {w}, {h})");
    expect(&call, LookAtCamera::new(from, at, up, vfov, w, h), &inputs)
}

fn check_screen_camera(w: usize, h: usize, eye: [f64; 3]) -> Result<(), TestCaseError> {
    let two_to_one = Verdict::from_bool(h >= 2 && w == h.wrapping_mul(2) && h <= usize::MAX / 2);
    let inputs = [
        ("2:1", two_to_one),
        ("image size", Verdict::from_bool(size_ok(w, h))),
    ];
    expect(
        &format!("ScreenCamera::new({w}, {h})"),
        ScreenCamera::new(w, h),
        &inputs,
    )?;
    if let Ok(cam) = ScreenCamera::new(w, h) {
        let finite = Verdict::from_bool(eye.iter().all(|c| c.is_finite()));
        expect(
            &format!("translated({eye:?})"),
            cam.translated(eye),
            &[("camera eye", finite)],
        )?;
    }
    Ok(())
}

fn check_settings_and_image(
    spp: u32,
    depth: u32,
    seed: u64,
    (w, h): (usize, usize),
) -> Result<(), TestCaseError> {
    let spp_ok = Verdict::from_bool(spp >= 1);
    let depth_ok = Verdict::from_bool(depth <= 1000);
    let call = format!("RenderSettings::new({spp}, {depth}, {seed})");
    expect(
        &call,
        RenderSettings::new(spp, depth, seed),
        &[("samples per pixel", spp_ok), ("max depth", depth_ok)],
    )?;
    // A valid size allocates `w·h` pixels: only small valid images are built.
    let ok = size_ok(w, h);
    if !ok || w * h <= 1 << 12 {
        let image = Image::new(w, h).map(|i| (i.width(), i.height()));
        expect(
            &format!("Image::new({w}, {h})"),
            image,
            &[("image size", Verdict::from_bool(ok))],
        )?;
    }
    Ok(())
}

macro_rules! constructor_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(CASES, $seed, REGRESSIONS))]

                #[test]
                fn sphere(c in vector::<$F>(), r in scalar::<$F>()) {
                    check_sphere(c, r)?;
                }

                #[test]
                fn plane(p in vector::<$F>(), n in prop_oneof![vector::<$F>(), magnitude::<$F>()]) {
                    check_plane(p, n)?;
                }

                #[test]
                fn triangle(v in triangle_vertices::<$F>()) {
                    check_triangle(v)?;
                }

                #[test]
                fn materials(a in color::<$F>(), n in scalar::<$F>()) {
                    check_materials(a, n)?;
                }

                #[test]
                fn light_and_background(p in vector::<$F>(), i in color::<$F>(), h in color::<$F>()) {
                    check_light_and_background(p, i, h)?;
                }

                #[test]
                fn look_at_camera(v in look_at_vectors::<$F>(), fov in vfov::<$F>(), wh in size()) {
                    check_look_at(v, fov, wh)?;
                }
            }
        }
    };
}

constructor_tests!(single, f32, 0xBAD_0032);
constructor_tests!(double, f64, 0xBAD_0064);

proptest! {
    #![proptest_config(config(CASES, 0xBAD_5123, REGRESSIONS))]

    /// Heights above `usize::MAX/2` make `ScreenCamera::new` panic (known bug 4): left out.
    #[test]
    fn screen_camera(
        (w, h) in size().prop_filter("known bug 4", |&(_, h)| h <= usize::MAX / 2),
        eye in [scalar::<f64>(), scalar::<f64>(), scalar::<f64>()],
    ) {
        check_screen_camera(w, h, eye)?;
    }

    #[test]
    fn settings_and_image(
        spp in prop_oneof![Just(0u32), Just(1u32), any::<u32>()],
        depth in prop_oneof![Just(1000u32), Just(1001u32), 0..2000u32, any::<u32>()],
        seed in any::<u64>(),
        wh in size(),
    ) {
        check_settings_and_image(spp, depth, seed, wh)?;
    }
}
