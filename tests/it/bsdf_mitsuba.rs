//! The materials are Mitsuba 3's: their `eval` and `pdf` equal the values Mitsuba 3.9.1
//! gives for the same material and directions (`bsdf_mitsuba/values.rs`, printed by
//! `tools/mitsuba_bsdf_values.py`: eleven materials, three viewers, one of them inside or
//! behind, five lights each, reflected and transmitted).
//!
//! The tolerances are Mitsuba's own departures from the exact model, each for a stated
//! reason ([`Agreement`]): it computes in f32 (`10⁻⁵` relative); for Beckmann's
//! distribution its masking `G₁` is a rational fit "within 0.35 %" of the exact Smith
//! function this crate uses, two per value (`10⁻²`); and it integrates the rough plastic's
//! coat in f32 sums of 32² (and 128²) terms, good to `~10⁻⁴`, which the lobe probability
//! amplifies by `(1 − p_s)/(1 − t)`, up to 13 for polypropylene near normal incidence
//! (`2·10⁻³`; this crate's integrals are within `2·10⁻⁵` of the converged ones). A value
//! below `10⁻⁶` of its material's largest is compared absolutely at that level (the f32
//! rounding of a vanishing value).
//!
//! With these seeds of directions the largest departures are `7·10⁻⁷` (GGX, smooth
//! plastic, two-sided), `2.8·10⁻³` (Beckmann) and `7.9·10⁻⁴` (rough plastic).

mod values;

use raytrace::material::{
    Coated, Distribution, Material, MaterialKind, Metal, Plastic, RoughConductor, RoughDielectric,
    RoughPlastic, Roughness, TwoSided,
};
use raytrace::shape::{Coordinates, Surface};
use raytrace::texture::Texture;
use raytrace::{Color, Hit, Vec3};
use values::MITSUBA;

use Distribution::{Beckmann, Ggx};

fn colour(c: [f64; 3]) -> Texture<f64> {
    Texture::constant(Color::new(c[0], c[1], c[2]))
}

fn iso(d: Distribution, alpha: f64) -> Roughness<f64> {
    Roughness::isotropic(d, Texture::scalar(alpha)).unwrap()
}

/// How closely a material must agree with Mitsuba's (see the module's docs).
#[derive(Clone, Copy, Debug)]
enum Agreement {
    /// To Mitsuba's f32 rounding.
    Exact,
    /// Within Mitsuba's fit of Beckmann's masking.
    BeckmannFit,
    /// Within Mitsuba's f32 integrals of the rough coat.
    CoatIntegrals,
}

impl Agreement {
    fn tolerance(self) -> f64 {
        match self {
            Agreement::Exact => 1e-5,
            Agreement::BeckmannFit => 1e-2,
            Agreement::CoatIntegrals => 2e-3,
        }
    }
}

use Agreement::{BeckmannFit, CoatIntegrals, Exact};

/// The script's materials, in its order, with how closely each must agree.
fn materials() -> Vec<(MaterialKind<f64>, Agreement)> {
    let gold = || RoughConductor::new(Metal::named("Au").unwrap(), iso(Ggx, 0.2));
    let red = || Coated::new(colour([0.6, 0.1, 0.1]), "polypropylene", "air").unwrap();
    let anisotropic = Roughness::anisotropic(Ggx, Texture::scalar(0.05), Texture::scalar(0.3)).unwrap();
    let tinted = Metal::new(colour([0.2, 0.9, 1.1]), colour([3.9, 2.4, 2.1]))
        .unwrap()
        .with_specular_reflectance(colour([0.9, 0.8, 0.7]))
        .unwrap();
    let red_coat = red().with_specular_reflectance(colour([0.5; 3])).unwrap();
    let blue = Coated::new(colour([0.1, 0.2, 0.6]), "polypropylene", "air").unwrap();
    let grey = Coated::new(colour([0.5; 3]), "polypropylene", "air").unwrap();
    vec![
        (gold().into(), Exact),
        (
            RoughConductor::new(Metal::named("Cu").unwrap(), iso(Beckmann, 0.3)).into(),
            BeckmannFit,
        ),
        (
            RoughConductor::new(Metal::named("Al").unwrap(), anisotropic).into(),
            Exact,
        ),
        (RoughConductor::new(tinted, iso(Ggx, 0.1)).into(), Exact),
        (
            RoughDielectric::new(iso(Ggx, 0.2), "bk7", "air").unwrap().into(),
            Exact,
        ),
        (
            RoughDielectric::new(iso(Beckmann, 0.3), 1.33, 1.0)
                .unwrap()
                .into(),
            BeckmannFit,
        ),
        (Plastic::new(red()).into(), Exact),
        (Plastic::new(red_coat.nonlinear(true)).into(), Exact),
        (RoughPlastic::new(blue, Ggx, 0.3).unwrap().into(), CoatIntegrals),
        (
            RoughPlastic::new(grey.nonlinear(true), Beckmann, 0.2)
                .unwrap()
                .into(),
            CoatIntegrals,
        ),
        (TwoSided::new(gold().into()).unwrap().into(), Exact),
    ]
}

fn direction([theta, phi]: [f64; 2]) -> Vec3<f64> {
    let (t, p) = (theta.to_radians(), phi.to_radians());
    Vec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

#[test]
fn eval_and_pdf_are_mitsubas() {
    let materials = materials();
    let largest: Vec<f64> = (0..materials.len())
        .map(|k| {
            MITSUBA
                .iter()
                .filter(|row| row.0 == k)
                .flat_map(|row| row.3.into_iter().chain([row.4]))
                .fold(0.0, f64::max)
        })
        .collect();
    let mut compared = 0;
    for &(k, view, light, want, want_pdf) in &MITSUBA {
        let (material, agreement) = &materials[k];
        let (wo, wi) = (direction(view), direction(light));
        let surface = Surface::bare(1.0, Vec3::zero(), Vec3::new(0.0, 0.0, 1.0));
        let hit = Hit::new(surface, -wo).with(Coordinates {
            uv: [0.5, 0.5],
            dpdu: Vec3::new(1.0, 0.0, 0.0),
        });
        let got = material
            .eval(&hit, wo, wi)
            .map_or([0.0; 3], |e| e.value().to_f64());
        let got_pdf = material.pdf(&hit, wo, wi);
        let tol = agreement.tolerance();
        let floor = 1e-6 * largest[k];
        let close = |a: f64, b: f64| (a - b).abs() <= tol * a.abs().max(b.abs()).max(floor);
        let what = format!("material {k}, viewer {view:?}, light {light:?}");
        for c in 0..3 {
            assert!(close(got[c], want[c]), "{what}: eval {got:?}, Mitsuba {want:?}");
        }
        assert!(
            close(got_pdf, want_pdf),
            "{what}: pdf {got_pdf}, Mitsuba {want_pdf}"
        );
        compared += usize::from(want_pdf > 0.0);
    }
    // 75 of the 165 pairs carry light (the rest check that both agree on none: a light
    // behind a one-sided material, a viewer behind one).
    assert!(compared >= 70, "{compared}");
}
