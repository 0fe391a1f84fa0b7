//! Self-intersection: a ray spawned at a hit must not hit the surface it leaves (reflection),
//! and must reach the far side when it goes in (refraction), at every scene scale. The
//! error-bounded hit and [`Hit::spawn`] (pbrt-v4's `OffsetRayOrigin`) pass this with zero
//! failures; the textbook method (origin at the hit point, `t_min = 0`, or the book's fixed
//! `t_min = 0.001`) fails, which the last tests measure — so the harness is shown to have
//! the power to see the failure it guards against.
//!
//! Scenes are scaled as a whole: the sphere's centre and radius (and the rays' origins)
//! grow with the scale, so the geometry is the same and only the floating-point grid moves.

use crate::common::Alone;
use rand::SeedableRng;
use raytrace::DefaultRng;
use raytrace::optics::{reflect, refract};
use raytrace::prelude::*;
use raytrace::sampling::{uniform, unit_sphere_rejection};
use raytrace::shape::{Hit, textbook_sphere_hit};
use twofloat::TwoFloat;

/// Rays per scale.
const RAYS: usize = 20_000;
/// Glass, so rays that enter a sphere always get out (the inner angle stays below critical).
const INDEX: f64 = 1.5;
/// The textbook's fixed lower bound on `t` (*Ray Tracing in One Weekend*), for comparison.
const TEXTBOOK_T_MIN: f64 = 1e-3;

/// The sphere of a scene at `scale`: centre `scale·(0.3, −0.2, −2)`, radius `scale/2`.
fn scaled_sphere<F: Float>(scale: f64) -> Sphere<F> {
    Sphere::new(
        Vec3::from_f64(0.3 * scale, -0.2 * scale, -2.0 * scale),
        lit(0.5 * scale),
    )
    .unwrap()
}

/// `n` seeded rays that hit `s` from outside: each starts on the sphere of radius `3r`
/// about the centre and aims at a point within `0.99r` of the centre (so the impact
/// parameter is below `0.99r` and light entering the glass always gets out again).
fn rays_at<F: Float>(s: &Sphere<F>, n: usize, seed: u64) -> Vec<Ray<F>> {
    let mut rng = DefaultRng::seed_from_u64(seed);
    let c = s.center().cast::<f64>();
    let r = s.radius().to_f64();
    (0..n)
        .map(|_| {
            let [x, y, z] = unit_sphere_rejection(&mut rng);
            let origin = c + Vec3::new(x, y, z) * (3.0 * r);
            let [x, y, z] = unit_sphere_rejection(&mut rng);
            let target = c + Vec3::new(x, y, z) * (0.99 * r * uniform(&mut rng).cbrt());
            Ray::towards(origin.cast::<F>(), target.cast::<F>()).unwrap()
        })
        .collect()
}

/// `|p − C|² − r²` in double-double: its sign says, exactly enough, on which side of the
/// true sphere the point `p` of an f32 or f64 scene lies (`> 0` outside).
fn side<F: Float>(s: &Sphere<F>, p: Vec3<F>) -> TwoFloat {
    let d = p.cast::<TwoFloat>() - s.center().cast::<TwoFloat>();
    let r = TwoFloat::from(s.radius().to_f64());
    d.length_squared() - r * r
}

/// Our method at one scale, over `n` rays: every assertion is a hard failure.
fn spawned_rays_behave<F: Float>(scale: f64, n: usize, seed: u64) {
    let s = scaled_sphere::<F>(scale);
    let r = s.radius();
    let eta = lit::<F>(INDEX);
    let ctx = format!("{} scale {scale:e}", F::NAME);
    for (i, ray) in rays_at(&s, n, seed).iter().enumerate() {
        let h = s
            .hit(ray, F::infinity())
            .unwrap_or_else(|| panic!("{ctx} ray {i}: missed"));
        assert!(h.front_face, "{ctx} ray {i}: hit from outside");

        // Reflected: starts outside the true sphere and never hits it again.
        let out = h.spawn(reflect(ray.direction, h.normal));
        assert!(
            side(&s, out.origin) > TwoFloat::from(0.0),
            "{ctx} ray {i}: reflected origin inside"
        );
        assert!(
            s.hit(&out, F::infinity()).is_none(),
            "{ctx} ray {i}: reflected ray re-hit its sphere: {:?}",
            s.hit(&out, F::infinity())
        );

        // Refracted: starts inside, reaches the far side (a chord ≥ 2r·cos(asin(0.99/1.5)) ≈ 1.5r).
        let d_in = refract(ray.direction, h.normal, eta.recip()).expect("entering never reflects totally");
        let inside = h.spawn(d_in);
        assert!(
            side(&s, inside.origin) < TwoFloat::from(0.0),
            "{ctx} ray {i}: refracted origin outside"
        );
        let far = s
            .hit(&inside, F::infinity())
            .unwrap_or_else(|| panic!("{ctx} ray {i}: no far side"));
        assert!(
            !far.front_face && far.t > r,
            "{ctx} ray {i}: far side at t = {} (r = {r})",
            far.t
        );

        // Reflected inside at the far side: stays inside and meets the sphere again, far away.
        let back = far.spawn(reflect(inside.direction, far.normal));
        assert!(
            side(&s, back.origin) < TwoFloat::from(0.0),
            "{ctx} ray {i}: inner reflection outside"
        );
        let again = s.hit(&back, F::infinity());
        assert!(
            again.is_some_and(|a| !a.front_face && a.t > r),
            "{ctx} ray {i}: inner reflection {again:?}"
        );

        // Out through the far side: starts outside and leaves for good.
        let d_out = refract(inside.direction, far.normal, eta).expect("leaves the glass");
        let exit = far.spawn(d_out);
        assert!(
            side(&s, exit.origin) > TwoFloat::from(0.0),
            "{ctx} ray {i}: exit origin inside"
        );
        assert!(
            s.hit(&exit, F::infinity()).is_none(),
            "{ctx} ray {i}: exit ray re-hit"
        );
    }
}

#[test]
fn spawned_rays_behave_at_every_scale_f32() {
    for scale in [1.0, 1e3, 1e4] {
        spawned_rays_behave::<f32>(scale, RAYS, 17);
    }
}

#[test]
fn spawned_rays_behave_at_every_scale_f64() {
    for scale in [1.0, 1e4, 1e8] {
        spawned_rays_behave::<f64>(scale, RAYS, 17);
    }
}

/// pbrt-v4's `TestReintersectConvex` sweep: 100 scales drawn log-uniformly, `10^±4` in f32
/// and `10^±8` in f64, a thousand rays each.
fn log_uniform_scales<F: Float>(max_exp: f64) {
    let mut rng = DefaultRng::seed_from_u64(2024);
    for k in 0..100 {
        let scale = 10f64.powf(max_exp * (2.0 * uniform(&mut rng) - 1.0));
        spawned_rays_behave::<F>(scale, 1000, k);
    }
}

#[test]
fn spawned_rays_behave_at_log_uniform_scales_f32() {
    log_uniform_scales::<f32>(4.0);
}

#[test]
fn spawned_rays_behave_at_log_uniform_scales_f64() {
    log_uniform_scales::<f64>(8.0);
}

/// What the textbook method does at one scale: the share of reflected rays that hit their
/// own sphere again (origin at the unreprojected hit point, no offset) with `t_min = 0` and
/// with `t_min = 0.001`, and the share of refracted rays whose first hit is not the far
/// side (a "hit" at `t < r`, the entry surface again) with `t_min = 0`.
#[derive(Debug)]
struct NaiveRates {
    reflect_t0: f64,
    reflect_fixed: f64,
    refract_t0: f64,
    /// Control: our error-bounded hit, but the reflected ray starts at the hit point itself.
    reflect_ours_unoffset: f64,
}

fn naive_rates<F: Float>(scale: f64) -> NaiveRates {
    let s = scaled_sphere::<F>(scale);
    let (zero, inf, fixed) = (F::zero(), F::infinity(), lit::<F>(TEXTBOOK_T_MIN));
    let (mut reflect_t0, mut reflect_fixed, mut refract_t0, mut unoffset) = (0, 0, 0, 0);
    let rays = rays_at(&s, RAYS, 17);
    for ray in &rays {
        let h: Hit<F> = textbook_sphere_hit(&s, ray, zero, inf).expect("the textbook hit");
        let out = Ray::new(h.point, reflect(ray.direction, h.normal));
        reflect_t0 += usize::from(textbook_sphere_hit(&s, &out, zero, inf).is_some());
        reflect_fixed += usize::from(textbook_sphere_hit(&s, &out, fixed, inf).is_some());
        let d_in = refract(ray.direction, h.normal, lit::<F>(INDEX).recip()).unwrap();
        let inside = Ray::new(h.point, d_in);
        let first = textbook_sphere_hit(&s, &inside, zero, inf);
        refract_t0 += usize::from(first.is_none_or(|f| f.t < s.radius()));
        let ours = s.hit(ray, inf).expect("our hit");
        let out = Ray::new(ours.point, reflect(ray.direction, ours.normal));
        unoffset += usize::from(s.hit(&out, inf).is_some());
    }
    let share = |k: usize| k as f64 / rays.len() as f64;
    NaiveRates {
        reflect_t0: share(reflect_t0),
        reflect_fixed: share(reflect_fixed),
        refract_t0: share(refract_t0),
        reflect_ours_unoffset: share(unoffset),
    }
}

/// Rounded hit points land inside the sphere about half the time, so with `t_min = 0` a
/// reflected ray re-hits its own sphere (and a refracted one "hits" the entry point instead
/// of the far side) for about half the rays — at every scale, in both precisions (measured:
/// 42–47 % reflected, 47–51 % refracted). The assertion asks for more than 30 %: with
/// 20 000 rays the binomial standard deviation of a share near ½ is 0.35 %, so 30 % is over
/// 30 standard deviations below what is seen, yet an offset-free method cannot get near it.
///
/// The control keeps our stable, reprojected hit and drops only the offset: 17–30 % of the
/// reflected rays then re-hit (asserted > 10 %, 20 deviations below), so it is the offset of
/// [`Hit::spawn`] that makes the zero failures above, not the better quadratic.
fn textbook_t_min_zero_fails<F: Float>(scales: [f64; 3]) {
    for scale in scales {
        let rates = naive_rates::<F>(scale);
        eprintln!("{} scale {scale:e}: {rates:?}", F::NAME);
        assert!(rates.reflect_t0 > 0.3, "{} scale {scale:e}: {rates:?}", F::NAME);
        assert!(rates.refract_t0 > 0.3, "{} scale {scale:e}: {rates:?}", F::NAME);
        assert!(
            rates.reflect_ours_unoffset > 0.1,
            "{} scale {scale:e}: {rates:?}",
            F::NAME
        );
    }
}

#[test]
fn textbook_t_min_zero_fails_f32() {
    textbook_t_min_zero_fails::<f32>([1.0, 1e3, 1e4]);
}

#[test]
fn textbook_t_min_zero_fails_f64() {
    textbook_t_min_zero_fails::<f64>([1.0, 1e4, 1e8]);
}

/// The book's fixed `t_min = 0.001` is scale-blind: it hides the re-hits at scale 1, where the
/// rounding error (~10⁻⁷) is far below it, but not in f32 at scale 10⁴, where the hit point's
/// rounding error (`ε·|P| ≈ 10⁻³`) reaches it (measured: 0 % at 1, 0.3 % at 10³, 26 % at
/// 10⁴; in f64 0 % up to 10⁸). At 10⁴ the assertion asks for more than 10 %, 45 binomial
/// standard deviations (0.3 %) below the measured share.
#[test]
fn textbook_fixed_t_min_fails_far_away_in_f32() {
    let at_one = naive_rates::<f32>(1.0);
    assert_eq!(at_one.reflect_fixed, 0.0, "{at_one:?}");
    let far = naive_rates::<f32>(1e4);
    assert!(far.reflect_fixed > 0.1, "{far:?}");
    for scale in [1.0, 1e4, 1e8] {
        let rates = naive_rates::<f64>(scale);
        assert_eq!(rates.reflect_fixed, 0.0, "f64 scale {scale:e}: {rates:?}");
    }
}
