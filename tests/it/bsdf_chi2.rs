//! χ² goodness of fit of every non-delta BSDF sampler against its own pdf, as pbrt-v4's
//! `bsdfs_test.cpp` and Mitsuba's `chi2` test them (the harness: `common/sphere_chi2.rs`).
//!
//! # Setup
//! Each run draws `2¹⁸` directions from a material's `sample` with a fixed seed and bins
//! them on a 40 × 80 `θ × φ` grid over the whole sphere, about the lobe's centre, its
//! rows crowded toward it for small `α`; the expected counts integrate the material's
//! `pdf` over each cell (adaptive Gauss–Legendre), cells expecting fewer than 5 are
//! pooled, and two more bins hold the delta lobe's draws and the absorbed ones.
//!
//! The runs cover the rough conductor, the rough dielectric (both faces, total internal
//! reflection included), the rough and the smooth plastic and the two-sided wrapper, with
//! GGX and Beckmann, isotropic and anisotropic, `α` from 0.01 to 1, incidence from normal
//! to 89.5°, in f32 and in f64, on an axis-aligned and on an oblique surface.
//!
//! # Significance
//! The family of the [`RUNS`] correct runs is tested at 0.01 with Šidák's correction: each
//! run at `1 − 0.99^(1/RUNS)`, so a correct sampler set fails with probability 0.01 over
//! a fresh choice of seeds (the seeds are fixed: a run is reproducible).
//!
//! # Power
//! The same test at the same level must reject planted mistakes: a rough dielectric whose
//! pdf lacks the Jacobian of refraction (`η²|wi·h|/(wo·h + η wi·h)²`); a rough conductor
//! that draws its normals from `D(m) cos θ_m` (all normals) while its pdf says visible
//! normals; and one whose sampler's `α` is 10 % too large.

use crate::common;

use common::bsdf::{Setup, Spec, mirror, refracted, setup};
use common::sphere_chi2::{Draw, Grid, Outcome, chi2_sphere};
use common::{dot, normalize, unit_from};
use rand::SeedableRng;
use rand::rngs::Xoshiro256PlusPlus;
use raytrace::material::{Distribution, Material, MaterialKind, Microfacet, Scatter};
use raytrace::sampling::uniform;
use raytrace::{Float, Vec3};
use std::f64::consts::TAU;

type Rng = Xoshiro256PlusPlus;

use Distribution::{Beckmann, Ggx};

/// Which scalar a run is made in.
#[derive(Clone, Copy, Debug)]
enum Scalar {
    F32,
    F64,
}

/// Where a run's grid is centred.
#[derive(Clone, Copy, Debug)]
enum Axis {
    /// The mirror direction of `wo`.
    Mirror,
    /// `wo` refracted into a medium of this relative index.
    Refracted(f64),
    /// The normal on `wo`'s side.
    Normal,
}

/// One χ² run: a material seen from `theta`, `phi` (degrees) on the `front` face or the
/// back of a surface of outward `normal`.
#[derive(Clone, Copy, Debug)]
struct Case {
    spec: Spec,
    theta: f64,
    phi: f64,
    front: bool,
    normal: [f64; 3],
    axis: Axis,
    scalar: Scalar,
}

const Z: [f64; 3] = [0.0, 0.0, 1.0];
const OBLIQUE: [f64; 3] = [0.3, -0.5, 0.8];

const fn case(spec: Spec, theta: f64, front: bool, axis: Axis, scalar: Scalar) -> Case {
    Case {
        spec,
        theta,
        phi: 30.0,
        front,
        normal: Z,
        axis,
        scalar,
    }
}

use Axis::{Mirror, Normal, Refracted};
use Scalar::{F32, F64};

#[rustfmt::skip]
const CONDUCTORS: [Case; 11] = [
    case(Spec::RoughConductor(Ggx, (0.01, 0.01), "Au"), 30.0, true, Mirror, F32),
    case(Spec::RoughConductor(Ggx, (0.1, 0.1), "Cu"), 60.0, true, Mirror, F64),
    case(Spec::RoughConductor(Ggx, (0.5, 0.5), "Al"), 85.0, true, Mirror, F32),
    case(Spec::RoughConductor(Ggx, (1.0, 1.0), "Ag"), 0.0, true, Normal, F64),
    case(Spec::RoughConductor(Ggx, (0.05, 0.4), "Cr"), 70.0, true, Mirror, F64),
    case(Spec::RoughConductor(Beckmann, (0.01, 0.01), "Au"), 80.0, true, Mirror, F64),
    case(Spec::RoughConductor(Beckmann, (0.1, 0.1), "Cu"), 0.0, true, Mirror, F32),
    case(Spec::RoughConductor(Beckmann, (0.5, 0.5), "W"), 45.0, true, Mirror, F64),
    case(Spec::RoughConductor(Beckmann, (1.0, 1.0), "Ni_palik"), 89.5, true, Mirror, F32),
    case(Spec::RoughConductor(Beckmann, (0.3, 0.08), "TiN"), 60.0, true, Mirror, F32),
    Case { normal: OBLIQUE, ..case(Spec::RoughConductor(Ggx, (0.2, 0.2), "Au"), 50.0, true, Mirror, F64) },
];

#[rustfmt::skip]
const DIELECTRICS: [Case; 10] = [
    case(Spec::RoughDielectric(Ggx, (0.01, 0.01), 1.5), 40.0, true, Refracted(1.5), F64),
    case(Spec::RoughDielectric(Ggx, (0.1, 0.1), 1.5), 70.0, true, Mirror, F32),
    case(Spec::RoughDielectric(Ggx, (0.5, 0.5), 1.5), 20.0, false, Refracted(1.0 / 1.5), F64),
    case(Spec::RoughDielectric(Ggx, (1.0, 1.0), 1.33), 89.5, true, Mirror, F32),
    case(Spec::RoughDielectric(Ggx, (0.05, 0.3), 1.5), 60.0, false, Mirror, F64),
    case(Spec::RoughDielectric(Beckmann, (0.01, 0.01), 1.5), 60.0, false, Mirror, F32),
    case(Spec::RoughDielectric(Beckmann, (0.1, 0.1), 2.4), 0.0, true, Refracted(2.4), F64),
    case(Spec::RoughDielectric(Beckmann, (0.5, 0.5), 1.5), 80.0, false, Mirror, F32),
    case(Spec::RoughDielectric(Beckmann, (1.0, 1.0), 1.5), 35.0, true, Normal, F64),
    Case { normal: OBLIQUE, ..case(Spec::RoughDielectric(Beckmann, (0.2, 0.2), 1.5), 30.0, true, Refracted(1.5), F32) },
];

#[rustfmt::skip]
const PLASTICS: [Case; 7] = [
    case(Spec::RoughPlastic(Ggx, 0.01, [0.5, 0.5, 0.5], false), 50.0, true, Mirror, F64),
    case(Spec::RoughPlastic(Ggx, 0.3, [0.9, 0.2, 0.1], true), 85.0, true, Mirror, F32),
    case(Spec::RoughPlastic(Beckmann, 0.1, [0.2, 0.4, 0.8], false), 0.0, true, Mirror, F32),
    case(Spec::RoughPlastic(Beckmann, 1.0, [0.5, 0.5, 0.5], false), 60.0, true, Normal, F64),
    case(Spec::Plastic([0.5, 0.5, 0.5], false), 0.0, true, Normal, F64),
    case(Spec::Plastic([0.1, 0.8, 0.3], true), 75.0, true, Normal, F32),
    case(Spec::TwoSidedRoughConductor(Ggx, 0.2, "Au"), 40.0, false, Mirror, F64),
];

/// The correct runs: the family the significance is corrected over.
const RUNS: usize = CONDUCTORS.len() + DIELECTRICS.len() + PLASTICS.len();

/// Each run's level: Šidák's `1 − (1 − 0.01)^(1/RUNS)`.
fn level() -> f64 {
    -((-0.01f64).ln_1p() / RUNS as f64).exp_m1()
}

/// A sampler of `material` at `s`, as the harness draws it.
fn draws<F: Float>(material: &MaterialKind<F>, s: &Setup<F>, seed: u64) -> impl FnMut() -> Draw {
    let (material, hit, wo) = (material.clone(), s.hit, s.wo);
    let mut rng = Rng::seed_from_u64(seed);
    move || match Scatter::<F, Rng>::sample(&material, &hit, wo, &mut rng) {
        None => Draw::Absorbed,
        Some(b) if b.lobe.is_delta() => Draw::Delta(b.pdf.to_f64()),
        Some(b) => Draw::Direction(normalize(b.direction.to_f64())),
    }
}

/// The grid of a case.
fn grid<F: Float>(c: &Case, s: &Setup<F>) -> Grid {
    let wo = s.wo.to_f64();
    let axis = match c.axis {
        Mirror => mirror(wo, s.facing),
        Normal => s.facing,
        Refracted(eta) => refracted(wo, s.facing, eta).unwrap_or_else(|| mirror(wo, s.facing)),
    };
    Grid::new(axis, c.spec.alpha())
}

/// One run in `F`: the outcome of the material's own sampler against its own pdf.
fn run<F: Float>(c: &Case, seed: u64) -> Outcome {
    let s = setup::<F>(c.normal, c.theta, c.phi, c.front);
    let material = c.spec.build::<F>();
    let pdf = |d: [f64; 3]| material.pdf(&s.hit, s.wo, unit_from(d)).to_f64();
    chi2_sphere(&grid(c, &s), draws(&material, &s, seed), &pdf)
}

fn run_all(name: &str, cases: &[Case]) {
    let level = level();
    for (k, c) in cases.iter().enumerate() {
        let seed = 0xB5DF_0000 + 97 * k as u64 + name.len() as u64;
        let outcome = match c.scalar {
            F32 => run::<f32>(c, seed),
            F64 => run::<f64>(c, seed),
        };
        println!("{name}[{k}] {c:?}: {outcome:?}");
        assert!(
            !outcome.rejected(level),
            "{name}[{k}] rejected at {level:.2e}: {c:?}\n{outcome:?}"
        );
    }
}

#[test]
fn rough_conductors_sample_their_pdf() {
    run_all("conductors", &CONDUCTORS);
}

#[test]
fn rough_dielectrics_sample_their_pdf() {
    run_all("dielectrics", &DIELECTRICS);
}

#[test]
fn plastics_and_two_sided_sample_their_pdf() {
    run_all("plastics", &PLASTICS);
}

#[test]
fn the_family_is_what_the_docs_say() {
    assert_eq!(RUNS, 28);
    assert!((level() - 3.589e-4).abs() < 1e-6, "{}", level());
}

/// Planted: the rough dielectric's pdf without the Jacobian of refraction, so it is a
/// density of half vectors, not of directions, where it refracts.
#[test]
fn a_missing_refraction_jacobian_is_rejected() {
    for (c, seed) in [
        (
            case(
                Spec::RoughDielectric(Ggx, (0.3, 0.3), 1.5),
                45.0,
                true,
                Refracted(1.5),
                F64,
            ),
            11,
        ),
        (
            case(
                Spec::RoughDielectric(Beckmann, (0.1, 0.1), 1.5),
                20.0,
                false,
                Refracted(1.0 / 1.5),
                F64,
            ),
            12,
        ),
    ] {
        let outcome = without_jacobian::<f64>(&c, seed);
        println!("no Jacobian {c:?}: {outcome:?}");
        assert!(outcome.rejected(level()), "accepted: {c:?}\n{outcome:?}");
    }
}

fn without_jacobian<F: Float>(c: &Case, seed: u64) -> Outcome {
    let s = setup::<F>(c.normal, c.theta, c.phi, c.front);
    let material = c.spec.build::<F>();
    let Spec::RoughDielectric(_, _, index) = c.spec else {
        unreachable!()
    };
    let eta = if c.front { index } else { 1.0 / index };
    let (wo, n) = (s.wo.to_f64(), s.facing);
    let pdf = |d: [f64; 3]| {
        let p = material.pdf(&s.hit, s.wo, unit_from(d)).to_f64();
        if dot(d, n) >= 0.0 || p == 0.0 {
            return p;
        }
        // The generalised half vector and the Jacobian the material divides by.
        let h = normalize(std::array::from_fn(|i| wo[i] + eta * d[i]));
        let (oh, ih) = (dot(wo, h), dot(d, h));
        p / (eta * eta * ih.abs() / ((oh + eta * ih) * (oh + eta * ih)))
    };
    chi2_sphere(&grid(c, &s), draws(&material, &s, seed), &pdf)
}

/// Planted: a rough conductor sampler drawing its normals from the wrong distribution,
/// `D(m) cos θ_m` (or `D` of an `α` 10 % too large), while the pdf is the material's.
#[test]
fn a_sampler_of_the_wrong_normals_is_rejected() {
    let c = case(
        Spec::RoughConductor(Ggx, (0.5, 0.5), "Au"),
        70.0,
        true,
        Mirror,
        F64,
    );
    let all = wrong_normals(&c, 21, |u| {
        // GGX's D(m) cos θ_m: tan²θ = α²u₀/(1 − u₀), φ = 2πu₁.
        let t2 = 0.25 * u[0] / (1.0 - u[0]);
        let ct = (1.0 + t2).sqrt().recip();
        let st = (1.0 - ct * ct).max(0.0).sqrt();
        let (sp, cp) = (TAU * u[1]).sin_cos();
        [st * cp, st * sp, ct]
    });
    let c2 = case(
        Spec::RoughConductor(Beckmann, (0.1, 0.1), "Au"),
        60.0,
        true,
        Mirror,
        F32,
    );
    let wider = Microfacet::new(Beckmann, 0.11, 0.11);
    let s = setup::<f64>(Z, 60.0, 30.0, true);
    let wo = s.wo;
    let rough = wrong_normals(&c2, 22, move |u| wider.sample_visible(wo, u).to_f64());
    for (name, outcome) in [("D cos θ", all), ("α 10 % too large", rough)] {
        println!("{name}: {outcome:?}");
        assert!(outcome.rejected(level()), "accepted '{name}': {outcome:?}");
    }
}

/// A run of `c` (on the z-up surface) whose sampler reflects `wo` about the normal
/// `normal(u)` (local, z up) instead of the material's.
fn wrong_normals(c: &Case, seed: u64, normal: impl Fn([f64; 2]) -> [f64; 3]) -> Outcome {
    let s = setup::<f64>(c.normal, c.theta, c.phi, c.front);
    let material = c.spec.build::<f64>();
    let wo = s.wo.to_f64();
    let mut rng = Rng::seed_from_u64(seed);
    let draw = move || {
        let m = normal([uniform(&mut rng), uniform(&mut rng)]);
        let d = mirror(wo, m);
        if d[2] > 0.0 && dot(wo, m) > 0.0 {
            Draw::Direction(d)
        } else {
            Draw::Absorbed
        }
    };
    let pdf = |d: [f64; 3]| material.pdf(&s.hit, s.wo, Vec3::new(d[0], d[1], d[2])).to_f64();
    chi2_sphere(&grid(c, &s), draw, &pdf)
}
