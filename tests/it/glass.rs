//! The refraction extra: a glass ([`Dielectric`]) sphere bends rays by Snell's law at both
//! interfaces, a hollow shell renders, tiny and far spheres are really crossed (where the
//! textbook's fixed `t_min` skips them), and the reflected share matches the reflectance.
//! Every test runs in f32 and f64.

use crate::common::Alone;
use rand::SeedableRng;
use raytrace::material::{Dielectric, Reflectance};
use raytrace::optics::{fresnel, reflect, schlick_reflectance};
use raytrace::prelude::*;
use raytrace::shape::{Hit, Surface, textbook_sphere_hit};
use raytrace::{DefaultRng, Scatter};
use std::convert::Infallible;

/// *Ray Tracing in One Weekend*'s fixed lower bound on `t`, for the demonstration only.
const TEXTBOOK_T_MIN: f64 = 1e-3;

/// Standard deviations allowed in the binomial tests: two-sided normal tail
/// `P(|Z| > 6) ≈ 1.97·10⁻⁹` per comparison.
const SIGMAS: f64 = 6.0;

/// A generator that always returns the same word. `Constant(u64::MAX)` draws `u → 1⁻`, so a
/// dielectric refracts whenever it can (`R < 1`): it pins a path through the glass.
struct Constant(u64);

impl rand::TryRng for Constant {
    type Error = Infallible;
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok((self.0 >> 32) as u32)
    }
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        Ok(self.0)
    }
    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        dst.fill(self.0 as u8);
        Ok(())
    }
}

/// The refracted (never reflected, unless totally internally) scatter of `glass` at `hit`.
fn refracted<F: Float>(glass: &Dielectric<F>, ray: &Ray<F>, hit: &Hit<F>) -> Vec3<F> {
    let s = Scatter::<F, Constant>::sample(glass, hit, -ray.direction, &mut Constant(u64::MAX)).unwrap();
    s.direction
}

fn eps<F: Float>(k: f64) -> F {
    F::epsilon() * lit(k)
}

fn max_abs_diff<F: Float>(a: Vec3<F>, b: Vec3<F>) -> F {
    (a - b).abs().max_element()
}

/// `sin θ` between two unit vectors, `|a × b|`.
fn sin_between<F: Float>(a: Vec3<F>, b: Vec3<F>) -> F {
    a.cross(b).length()
}

fn sphere<F: Float>(x: f64, y: f64, z: f64, r: f64) -> Sphere<F> {
    Sphere::new(Vec3::from_f64(x, y, z), lit(r)).unwrap()
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
    normal_incidence_passes_undeflected,
    snell_holds_at_both_interfaces,
    hollow_sphere_path_obeys_snell_at_four_interfaces,
    hollow_sphere_renders_without_nan,
    inner_surface_of_a_shell_totally_reflects,
    tiny_spheres_are_crossed,
    reflected_share_matches_the_reflectance,
);

#[test]
fn far_small_sphere_is_crossed_in_f64() {
    // A 1 cm sphere 10 km away: ratio 10⁶, where the textbook discriminant keeps ~12 of 52 bits.
    cross_small_sphere::<f64>(1e-2, 1e4, false);
}

/// (a) Through the centre at normal incidence: in at `z = −2`, out at `z = −4`, undeflected.
fn normal_incidence_passes_undeflected<F: Float>() {
    let s = sphere::<F>(0.0, 0.0, -3.0, 1.0);
    let glass = Dielectric::new(lit::<F>(1.5)).unwrap();
    let down = Vec3::from_f64(0.0, 0.0, -1.0);
    let ray = Ray::new(Vec3::zero(), down);
    let tol = eps::<F>(16.0) * lit(4.0); // a few roundings at coordinates of size 4

    let h1 = s.hit(&ray, F::infinity()).unwrap();
    assert!(h1.front_face);
    assert!(
        max_abs_diff(h1.point, Vec3::from_f64(0.0, 0.0, -2.0)) <= tol,
        "{:?}",
        h1.point
    );
    let d1 = refracted(&glass, &ray, &h1);
    assert!(max_abs_diff(d1, down) <= eps(4.0), "inside: {d1:?}");

    let inside = h1.spawn(d1);
    let h2 = s.hit(&inside, F::infinity()).expect("the far side");
    assert!(!h2.front_face, "hit from inside");
    assert!(
        max_abs_diff(h2.point, Vec3::from_f64(0.0, 0.0, -4.0)) <= tol,
        "exit at {:?}",
        h2.point
    );
    assert!((h2.t - lit(2.0)).abs() <= tol, "chord {}", h2.t);
    let d2 = refracted(&glass, &inside, &h2);
    assert!(max_abs_diff(d2, down) <= eps(4.0), "out: {d2:?}");

    let out = h2.spawn(d2);
    assert!(
        out.origin.z < lit(-4.0),
        "the exit ray starts outside: {:?}",
        out.origin
    );
    assert!(s.hit(&out, F::infinity()).is_none(), "and never comes back");
}

/// (b) Off-centre rays: `sin θ₁ = 1.5 sin θ₂` going in and `1.5 sin θ₃ = sin θ₄` going out,
/// each refracted ray in the plane of incidence, and (a sphere's symmetry) `θ₃ = θ₂`.
fn snell_holds_at_both_interfaces<F: Float>() {
    let s = sphere::<F>(0.0, 0.0, -3.0, 1.0);
    let n = lit::<F>(1.5);
    let glass = Dielectric::new(n).unwrap();
    // The normals come from reprojected points (a few ε), the sines from cross products.
    let tol = eps::<F>(32.0);
    for (x, y) in [
        (0.1, 0.0),
        (0.35, 0.2),
        (-0.6, 0.3),
        (0.0, -0.9),
        (0.7, 0.68),
        (0.99, 0.0),
    ] {
        let ray = Ray::new(Vec3::from_f64(x, y, 0.0), Vec3::from_f64(0.0, 0.0, -1.0));
        let h1 = s.hit(&ray, F::infinity()).unwrap();
        let d1 = refracted(&glass, &ray, &h1);
        let (sin1, sin2) = (sin_between(ray.direction, h1.normal), sin_between(d1, h1.normal));
        assert!(
            (sin1 - n * sin2).abs() <= tol,
            "in at ({x}, {y}): sin θ₁ {sin1}, sin θ₂ {sin2}"
        );
        assert!(ray.direction.cross(h1.normal).dot(d1).abs() <= tol, "coplanar in");
        assert!(d1.dot(h1.normal) < F::zero(), "transmitted, not reflected");

        let inside = h1.spawn(d1);
        let h2 = s.hit(&inside, F::infinity()).expect("the far side");
        assert!(!h2.front_face);
        let d2 = refracted(&glass, &inside, &h2);
        let (sin3, sin4) = (sin_between(d1, h2.normal), sin_between(d2, h2.normal));
        assert!(
            (sin3 - sin2).abs() <= tol,
            "symmetric chord: θ₃ {sin3} = θ₂ {sin2}"
        );
        assert!(
            (n * sin3 - sin4).abs() <= tol,
            "out at ({x}, {y}): sin θ₃ {sin3}, sin θ₄ {sin4}"
        );
        assert!(d1.cross(h2.normal).dot(d2).abs() <= tol, "coplanar out");
        assert!(
            d2.dot(h2.normal) < F::zero(),
            "light entering a sphere always gets out"
        );
        assert!(s.hit(&h2.spawn(d2), F::infinity()).is_none());
    }
}

/// A hollow glass shell: the outer sphere glass (`n = 1.5`), the air inside modelled as an
/// inner sphere of index `1/1.5`. (Our spheres reject the book's negative-radius trick; a
/// relative index `< 1` is the same physics: at the inner surface the ray passes from glass
/// into air, `η = η₁/η₂ = 1.5`.)
fn hollow_scene<F: Float>(background: Background<F>) -> EnumScene<F> {
    let mut scene = EnumScene::new(background);
    scene.add(
        sphere::<F>(0.0, 0.0, -3.0, 1.0),
        Dielectric::new(lit::<F>(1.5)).unwrap(),
    );
    scene.add(
        sphere::<F>(0.0, 0.0, -3.0, 0.9),
        Dielectric::new(lit::<F>(1.0 / 1.5)).unwrap(),
    );
    scene
}

fn glass_of<F: Float>(m: &MaterialKind<F>) -> Dielectric<F> {
    match m {
        MaterialKind::Dielectric(g) => *g,
        other => panic!("not glass: {other:?}"),
    }
}

/// Along a pinned refracting path the ray crosses exactly four interfaces, air → glass →
/// air → glass → air, and obeys `sin θ_out = η sin θ_in` at each.
fn hollow_sphere_path_obeys_snell_at_four_interfaces<F: Float>() {
    let scene = hollow_scene::<F>(Background::solid(Vec3::zero()).unwrap());
    let (n, tol) = (1.5, eps::<F>(32.0));
    let expected_eta = [1.0 / n, n, 1.0 / n, n];
    // Inside the shell the impact parameter is b/1.5, so the inner surface sees
    // sin θ = b/(1.5·0.9) < 1/1.5 (no total internal reflection) for b < 0.9.
    for (x, y) in [(0.0, 0.0), (0.3, 0.0), (0.2, -0.4), (0.0, 0.85)] {
        let mut ray = Ray::new(Vec3::from_f64(x, y, 0.0), Vec3::from_f64(0.0, 0.0, -1.0));
        let mut etas = Vec::new();
        while let Some((hit, m)) = scene.hit(&ray, F::infinity()) {
            assert!(etas.len() < 4, "more than four interfaces at ({x}, {y})");
            let glass = glass_of(m);
            let eta = glass.eta(hit.front_face);
            let d = refracted(&glass, &ray, &hit);
            let (sin_in, sin_out) = (sin_between(ray.direction, hit.normal), sin_between(d, hit.normal));
            assert!(
                (eta * sin_in - sin_out).abs() <= tol,
                "interface {} at ({x}, {y}): η {eta}, sin {sin_in} → {sin_out}",
                etas.len()
            );
            assert!(d.dot(hit.normal) < F::zero(), "transmitted");
            etas.push(eta.to_f64());
            ray = hit.spawn(d);
        }
        assert_eq!(etas.len(), 4, "({x}, {y})");
        for (got, want) in etas.iter().zip(expected_eta) {
            assert!((got - want).abs() < 1e-6, "η sequence {etas:?}");
        }
        if (x, y) == (0.0, 0.0) {
            let exit = ray.origin.cast::<f64>();
            assert!(
                (exit.z + 4.0).abs() < 1e-5 && exit.x == 0.0 && exit.y == 0.0,
                "{exit:?}"
            );
            let down = Vec3::from_f64(0.0, 0.0, -1.0);
            assert!(
                max_abs_diff(ray.direction, down) <= eps(4.0),
                "undeflected: {:?}",
                ray.direction
            );
        }
    }
}

/// (c) The shell renders: every pixel finite and, as clear glass (albedo 1) cannot create
/// light and the sky is at most 1, within `[0, 1]`; and the shell is visible.
fn hollow_sphere_renders_without_nan<F: Float>() {
    let camera = ScreenCamera::new(64, 32).unwrap();
    let settings = RenderSettings::new(4, 30, 7).unwrap();
    let image = render(&hollow_scene::<F>(Background::default()), &camera, &settings)
        .unwrap()
        .image;
    let sky = render(&EnumScene::<F>::new(Background::default()), &camera, &settings)
        .unwrap()
        .image;
    let mut differ = 0;
    for (p, q) in image.pixels().iter().zip(sky.pixels()) {
        for c in p {
            assert!(c.is_finite() && (0.0..=1.0 + 1e-6).contains(c), "pixel {p:?}");
        }
        differ += usize::from(p != q);
    }
    // The shell (angular radius asin(1/3)) is a disc of radius ≈ 0.35/(4/63) ≈ 5.6 pixels
    // on the screen, about 98 pixels: they must differ from the empty sky.
    assert!(differ > 50, "only {differ} pixels show the shell");
}

/// At the inner surface (glass → air, `η = 1.5`) past the critical angle `asin(1/1.5)`,
/// the ray always reflects, even when the draw says "refract".
fn inner_surface_of_a_shell_totally_reflects<F: Float>() {
    let scene = hollow_scene::<F>(Background::solid(Vec3::zero()).unwrap());
    // A ray inside the glass (0.9 < |X − C| ≈ 0.94 < 1), travelling along −z at distance
    // 0.85·0.9 from the axis, so it meets the inner sphere at sin θ = 0.85 > 1/1.5.
    let origin = Vec3::from_f64(0.85 * 0.9, 0.0, -3.0 + 0.55);
    let ray = Ray::new(origin, Vec3::from_f64(0.0, 0.0, -1.0));
    let (hit, m) = scene.hit(&ray, F::infinity()).unwrap();
    assert!(hit.front_face, "the inner sphere, from its outside");
    let glass = glass_of(m);
    assert!((glass.eta(true).to_f64() - 1.5).abs() < 1e-6, "glass → air");
    let sin = sin_between(ray.direction, hit.normal).to_f64();
    assert!((sin - 0.85).abs() < 1e-5, "sin θ {sin}");
    let d = refracted(&glass, &ray, &hit);
    assert_eq!(d, reflect(ray.direction, hit.normal), "total internal reflection");
}

/// (d) Tiny spheres near the origin, radius 1e-4 and 1e-6 (coordinates scale with `r`).
fn tiny_spheres_are_crossed<F: Float>() {
    cross_small_sphere::<F>(1e-4, 3e-4, true);
    cross_small_sphere::<F>(1e-6, 3e-6, true);
}

/// A ray from the origin enters a glass sphere of radius `r` centred `dist` down −z (off
/// centre by `(0.3r, 0.2r)`), is refracted, and the refracted ray — spawned inside —
/// reaches the far side, then leaves. With `textbook` the same inner ray is also given to
/// the textbook intersection with `t_min = 0.001`, which skips a chord shorter than that.
fn cross_small_sphere<F: Float>(r: f64, dist: f64, textbook: bool) {
    let s = sphere::<F>(0.0, 0.0, -dist, r);
    let glass = Dielectric::new(lit::<F>(1.5)).unwrap();
    let ray = Ray::towards(Vec3::zero(), Vec3::from_f64(0.3 * r, 0.2 * r, -dist)).unwrap();
    let ctx = format!("{} r = {r:e} at {dist:e}", F::NAME);

    let h1 = s
        .hit(&ray, F::infinity())
        .unwrap_or_else(|| panic!("{ctx}: missed"));
    assert!(h1.front_face, "{ctx}");
    let d1 = refracted(&glass, &ray, &h1);
    let inside = h1.spawn(d1);
    let o = inside.origin.cast::<f64>() - s.center().cast::<f64>();
    assert!(o.length() < r, "{ctx}: the refracted ray starts inside");

    let h2 = s
        .hit(&inside, F::infinity())
        .unwrap_or_else(|| panic!("{ctx}: the refracted ray missed the far side"));
    assert!(!h2.front_face, "{ctx}");
    // The chord: impact parameter 0.36r outside, 0.24r inside, length ≈ 1.94r.
    let chord = (h2.point - h1.point).cast::<f64>().length();
    assert!(chord > 1.9 * r && chord < 2.0 * r, "{ctx}: chord {chord:e}");
    assert!(h2.t.to_f64() > 1.9 * r, "{ctx}: t = {}", h2.t);
    let out = h2.spawn(refracted(&glass, &inside, &h2));
    assert!(s.hit(&out, F::infinity()).is_none(), "{ctx}: left for good");

    if textbook {
        assert!(2.0 * r < TEXTBOOK_T_MIN);
        let naive = textbook_sphere_hit(&s, &inside, lit(TEXTBOOK_T_MIN), F::infinity());
        assert!(naive.is_none(), "{ctx}: t_min = 0.001 skips the whole chord");
    }
}

/// (e) Over many seeded draws, the share of rays reflected at angle θ is the reflectance `R`
/// (Schlick or Fresnel), within `SIGMAS` binomial standard deviations; past the critical
/// angle every ray reflects.
fn reflected_share_matches_the_reflectance<F: Float>() {
    const DRAWS: u32 = 100_000;
    let critical = (1.0f64 / 1.5).asin();
    let cases = [
        (true, 0.0),
        (true, 0.5),
        (true, 1.0),
        (true, 1.3),
        (true, 1.5),
        (false, 0.0),
        (false, 0.4),
        (false, 0.7),
        (false, critical - 0.01),
        (false, critical + 0.01),
        (false, 1.2),
    ];
    for mode in [Reflectance::Schlick, Reflectance::Fresnel] {
        let glass = Dielectric::new(lit::<F>(1.5)).unwrap().with_reflectance(mode);
        for (seed, &(front, theta)) in cases.iter().enumerate() {
            // The plane y = 0 at the origin; the ray comes down at θ from the vertical and
            // hits its front (outward normal +y) or its back (outward normal −y).
            let d = Vec3::from_f64(theta.sin(), -theta.cos(), 0.0);
            let outward = Vec3::from_f64(0.0, if front { 1.0 } else { -1.0 }, 0.0);
            let hit = Hit::new(Surface::bare(F::one(), Vec3::zero(), outward), d);
            let ray = Ray::new(-d, d);
            let eta = if front { 1.0 / 1.5 } else { 1.5 };
            let p = match mode {
                Reflectance::Schlick => schlick_reflectance(theta.cos(), eta),
                Reflectance::Fresnel => fresnel(theta.cos(), eta),
            };
            let mut rng = DefaultRng::seed_from_u64(1000 + seed as u64);
            let mut reflected = 0u32;
            for _ in 0..DRAWS {
                let s = Scatter::<F, DefaultRng>::sample(&glass, &hit, -ray.direction, &mut rng).unwrap();
                assert_eq!(s.weight, Vec3::splat(F::one()), "clear glass loses nothing");
                reflected += u32::from(s.direction.dot(hit.normal) > F::zero());
            }
            let ctx = format!("{} {mode:?} front {front} θ {theta:.4}: R {p:.5}", F::NAME);
            if theta > critical && !front {
                assert_eq!(p, 1.0, "{ctx}");
                assert_eq!(reflected, DRAWS, "{ctx}: total internal reflection");
                continue;
            }
            let n = f64::from(DRAWS);
            let sd = (n * p * (1.0 - p)).sqrt();
            let dev = (f64::from(reflected) - n * p).abs();
            assert!(
                dev <= SIGMAS * sd,
                "{ctx}: {reflected} of {DRAWS} reflected, {dev:.1} > {SIGMAS}σ"
            );
        }
    }
}
