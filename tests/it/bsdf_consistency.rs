//! Per-sample consistency of the BSDFs' three answers, in f32 and f64: a drawn direction's
//! weight is `eval/pdf` and its density is `pdf`; reflection is reciprocal,
//! `f(wo, wi) = f(wi, wo)`, and refraction through a rough dielectric obeys the
//! generalised reciprocity of radiance, `f(wo, wi)/η_o² = f(wi, wo)/η_i²`; the delta
//! lobes give no value to any direction, and the thin sheet picks its two deltas with the
//! probabilities it reports. (That each pdf integrates to at most 1 is
//! checked by every χ² run, `bsdf_chi2.rs`, over the whole sphere.)

use crate::common;

use common::bsdf::{Spec, setup};
use common::{dot, normalize, unit_from};
use rand::SeedableRng;
use rand::rngs::Xoshiro256PlusPlus;
use raytrace::material::{Distribution, Material, MaterialKind, Scatter};
use raytrace::sampling::{uniform, uniform_sphere};
use raytrace::shape::{Coordinates, Surface};
use raytrace::{Float, Hit, Vec3, lit};

type Rng = Xoshiro256PlusPlus;

use Distribution::{Beckmann, Ggx};

/// Every material with a non-delta lobe, at roughness from 0.01 to 1.
const GLOSSY: [Spec; 12] = [
    Spec::RoughConductor(Ggx, (0.01, 0.01), "Au"),
    Spec::RoughConductor(Ggx, (0.3, 0.3), "Cu"),
    Spec::RoughConductor(Beckmann, (1.0, 1.0), "Al"),
    Spec::RoughConductor(Beckmann, (0.05, 0.5), "Cr"),
    Spec::RoughDielectric(Ggx, (0.01, 0.01), 1.5),
    Spec::RoughDielectric(Beckmann, (0.2, 0.2), 1.33),
    Spec::RoughDielectric(Ggx, (0.5, 0.1), 2.4),
    Spec::RoughPlastic(Ggx, 0.05, [0.8, 0.3, 0.2], false),
    Spec::RoughPlastic(Beckmann, 0.6, [0.5, 0.5, 0.5], true),
    Spec::Plastic([0.2, 0.6, 0.9], false),
    Spec::Plastic([1.0, 1.0, 1.0], true),
    Spec::TwoSidedRoughConductor(Ggx, 0.1, "Ag"),
];

/// Incidences (degrees from the normal), both faces.
const VIEWS: [(f64, bool); 5] = [
    (0.0, true),
    (35.0, true),
    (75.0, false),
    (88.0, true),
    (89.9, false),
];

/// `|a − b| ≤ tol·max(|a|, |b|)` (and both 0 or both not).
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs())
}

/// The relative tolerance of two computations of a BSDF's answers from directions
/// rounded to `F` by `~ε`. A sample computes its weight and pdf from the microfacet normal
/// `m` it drew; `eval` and `pdf` from the half vector `h` recomputed from the returned
/// direction (rounded to world space and back). Where `wo` and `wi` nearly cancel
/// (grazing on a smooth surface), that moves `h` by `~ε/c`, `c = min(|wo·h|, |wi·h|)`,
/// so the factors `wo·h`, `wi·h` (and `1 − F` near the critical angle, through
/// `cos²θ_t = (wo·h)²`) by `~ε/c²` relative and `D` by `~4ε/(α c)`; grazing directions
/// move the masking `G₁` by `~ε/|cos θ|`. So two computations can agree only to
/// `1e-9 + 8ε(1/c² + 4/(α c) + 1/|cos θₒ| + 1/|cos θᵢ|)` (a few % in f32 at `α = 0.01`,
/// 0.1° from grazing; `~10⁻⁹` in f64), which is what is required. `c` and the cosines are
/// computed here in f64, with the half vector of the material's definition.
fn tolerance<F: Float>(spec: &Spec, front: bool, wo: [f64; 3], wi: [f64; 3], n: [f64; 3]) -> f64 {
    let index = match spec {
        Spec::RoughDielectric(_, _, eta) if front => *eta,
        Spec::RoughDielectric(_, _, eta) => 1.0 / eta,
        _ => 1.0,
    };
    let eta = if dot(wi, n) * dot(wo, n) > 0.0 { 1.0 } else { index };
    let h = normalize(std::array::from_fn(|k| wo[k] + eta * wi[k]));
    let c = dot(wo, h).abs().min(dot(wi, h).abs()).max(1e-300);
    let cosines = 1.0 / dot(wo, n).abs().max(1e-300) + 1.0 / dot(wi, n).abs().max(1e-300);
    let eps = F::eps().to_f64();
    1e-9 + 8.0 * eps * (1.0 / (c * c) + 4.0 / (spec.alpha() * c) + cosines)
}

fn samples_agree_with_eval_and_pdf<F: Float>() {
    let mut rng = Rng::seed_from_u64(0xC0_5157);
    let mut tolerances = Vec::new();
    for spec in GLOSSY {
        let material = spec.build::<F>();
        for (theta, front) in VIEWS {
            let s = setup::<F>([0.3, -0.5, 0.8], theta, 20.0, front);
            for _ in 0..500 {
                let Some(b) = Scatter::<F, Rng>::sample(&material, &s.hit, s.wo, &mut rng) else {
                    continue;
                };
                let what = format!("{} {spec:?} θ = {theta} front = {front}: {b:?}", F::NAME);
                assert!((b.direction.length().to_f64() - 1.0).abs() < 1e-5, "{what}");
                let w = b.weight.to_f64();
                assert!(w.iter().all(|x| x.is_finite() && *x >= 0.0), "{what}");
                if b.lobe.is_delta() {
                    assert!(b.pdf > F::zero() && b.pdf <= F::one(), "{what}");
                    continue;
                }
                let n = normalize(s.hit.shading_normal.to_f64());
                let d = normalize(b.direction.to_f64());
                let tol = tolerance::<F>(&spec, front, s.wo.to_f64(), d, n);
                tolerances.push(tol);
                let pdf = material.pdf(&s.hit, s.wo, b.direction).to_f64();
                assert!(close(b.pdf.to_f64(), pdf, tol), "{what}: pdf {pdf}");
                let value = material
                    .eval(&s.hit, s.wo, b.direction)
                    .map_or([0.0; 3], |e| e.value().to_f64());
                for (wc, vc) in w.iter().zip(value) {
                    assert!(close(wc * b.pdf.to_f64(), vc, tol), "{what}: eval {value:?}");
                }
            }
        }
    }
    // The check has teeth: most samples are held to near the scalar's precision (the
    // half vector's conditioning is good away from grazing).
    tolerances.sort_by(f64::total_cmp);
    let median = tolerances[tolerances.len() / 2];
    println!(
        "{}: {} samples, median tolerance {median:e}",
        F::NAME,
        tolerances.len()
    );
    assert!(tolerances.len() > 20_000, "{}", tolerances.len());
    assert!(
        median < 2e-9 + 1e3 * F::eps().to_f64(),
        "median tolerance {median:e}"
    );
}

/// A hit at the origin on the z-up surface seen from `wo` (above or below), its tangent
/// `x`.
fn hit_from<F: Float>(wo: [f64; 3]) -> (Hit<F>, Vec3<F>) {
    let wo: Vec3<F> = unit_from(wo);
    let surface = Surface::bare(F::one(), Vec3::zero(), Vec3::new(F::zero(), F::zero(), F::one()));
    let hit = Hit::new(surface, -wo).with(Coordinates {
        uv: [lit(0.25), lit(0.5)],
        dpdu: Vec3::new(F::one(), F::zero(), F::zero()),
    });
    (hit, wo)
}

/// `f(wo, wi)` without the cosine (its green channel).
fn f<F: Float>(material: &MaterialKind<F>, wo: [f64; 3], wi: [f64; 3]) -> f64 {
    let (hit, o) = hit_from::<F>(wo);
    let i: Vec3<F> = unit_from(wi);
    let value = material.eval(&hit, o, i).map_or(0.0, |e| e.value().to_f64()[1]);
    value / i.z.abs().to_f64()
}

/// Reciprocity holds to the rounding of the pair ([`tolerance`]: both sides are computed
/// from the same two vectors rounded to `F`, each with its own frame and half vector).
fn reciprocity<F: Float>() {
    let mut rng = Rng::seed_from_u64(0x2EC1);
    let mut pairs = 0;
    for spec in GLOSSY {
        let material = spec.build::<F>();
        for _ in 0..400 {
            let draw = |rng: &mut Rng| uniform_sphere([uniform(rng), uniform(rng)]);
            let (mut a, b) = (draw(&mut rng), draw(&mut rng));
            // Keep `a` on the front side (the one-sided materials' only one); the rough
            // dielectric is seen from both.
            let dielectric = matches!(spec, Spec::RoughDielectric(..));
            if a[2] < 0.0 && !dielectric {
                a = a.map(|x| -x);
            }
            if a[2].abs() < 1e-3 || b[2].abs() < 1e-3 {
                continue;
            }
            let (ab, ba) = (f(&material, a, b), f(&material, b, a));
            // η_side: 1 above; the interior index below, for the rough dielectric.
            let index = match spec {
                Spec::RoughDielectric(_, _, eta) => eta,
                _ => 1.0,
            };
            let side = |w: [f64; 3]| if w[2] > 0.0 { 1.0 } else { index };
            let (left, right) = (ab / (side(a) * side(a)), ba / (side(b) * side(b)));
            let front = a[2] > 0.0;
            let tol = tolerance::<F>(&spec, front, a, b, [0.0, 0.0, if front { 1.0 } else { -1.0 }]);
            let what = format!("{} {spec:?} a = {a:?} b = {b:?}: {ab} vs {ba}", F::NAME);
            assert!(close(left, right, tol) || left.max(right) < 1e-30, "{what}");
            pairs += usize::from(left > 0.0);
        }
    }
    assert!(pairs > 1500, "{pairs} pairs with light between them");
}

fn deltas_have_no_value<F: Float>() {
    let mut rng = Rng::seed_from_u64(0xDE17A);
    for spec in [Spec::Conductor("Au"), Spec::ThinDielectric(1.5)] {
        let material = spec.build::<F>();
        assert!(material.lobes().is_delta() && !material.lobes().has_non_delta());
        let s = setup::<F>([0.0, 0.0, 1.0], 40.0, 0.0, true);
        for _ in 0..100 {
            let d = normalize(uniform_sphere([uniform(&mut rng), uniform(&mut rng)]));
            let wi: Vec3<F> = unit_from(d);
            assert_eq!(material.eval(&s.hit, s.wo, wi), None, "{spec:?}");
            assert_eq!(material.pdf(&s.hit, s.wo, wi), F::zero(), "{spec:?}");
            let b = Scatter::<F, Rng>::sample(&material, &s.hit, s.wo, &mut rng).unwrap();
            let out = b.direction.to_f64();
            let wo = s.wo.to_f64();
            // The mirror direction, or (the sheet) straight through.
            let mirrored = dot(out, [0.0, 0.0, 1.0]) > 0.0;
            assert!(mirrored || (dot(out, wo) + 1.0).abs() < 1e-6, "{spec:?}: {out:?}");
        }
    }
}

/// The thin sheet reflects with the probability it reports, `R' = 2R/(1 + R)`: over `2¹⁶`
/// draws at each incidence, the count of reflections is within `4.89` standard deviations
/// of `N·R'` (two-sided significance `10⁻⁶`, the suite's level), and a sheet reflecting
/// with `R` instead (no inner bounces) would be more than 20 away at 60°.
fn thin_sheet_reflects_with_its_probability<F: Float>() {
    let material = Spec::ThinDielectric(1.5).build::<F>();
    let mut rng = Rng::seed_from_u64(0x7417);
    let n = 1 << 16;
    for theta in [0.0, 30.0, 60.0, 85.0] {
        let s = setup::<F>([0.0, 0.0, 1.0], theta, 0.0, true);
        let mut reflected = 0u32;
        let mut claimed = 0.0;
        for _ in 0..n {
            let b = Scatter::<F, Rng>::sample(&material, &s.hit, s.wo, &mut rng).unwrap();
            if b.lobe.contains(raytrace::material::Lobes::REFLECTION) {
                reflected += 1;
                claimed = b.pdf.to_f64();
            }
        }
        let r = raytrace::optics::fresnel(theta.to_radians().cos(), 1.0 / 1.5);
        let want = 2.0 * r / (1.0 + r);
        assert!((claimed - want).abs() < 1e-6, "{theta}: {claimed} vs {want}");
        let sd = (n as f64 * want * (1.0 - want)).sqrt();
        let z = (f64::from(reflected) - n as f64 * want) / sd;
        let z_single = (f64::from(reflected) - n as f64 * r) / sd;
        println!(
            "{} θ = {theta}: R' = {want:.4}, z = {z:.2} (against R: {z_single:.1})",
            F::NAME
        );
        assert!(z.abs() <= common::Z_ALPHA, "{theta}: z = {z}");
        if theta == 60.0 {
            assert!(z_single > 20.0, "{z_single}");
        }
    }
}

macro_rules! for_each_scalar {
    ($($name:ident),*) => {$(
        #[test]
        fn $name() {
            super::$name::<f32>();
            super::$name::<f64>();
        }
    )*};
}

mod f32_and_f64 {
    for_each_scalar!(
        samples_agree_with_eval_and_pdf,
        reciprocity,
        deltas_have_no_value,
        thin_sheet_reflects_with_its_probability
    );
}
