//! What the BSDF tests (`bsdf_chi2.rs`, `bsdf_consistency.rs`, `bsdf_energy.rs`) share:
//! the materials under test by their constructors' arguments, and the hit and the
//! direction `wo` they are seen from, made independently of the library's frames.

use super::{frame, normalize, unit_from};
use raytrace::material::{
    Coated, Conductor, Distribution, MaterialKind, Metal, Plastic, RoughConductor, RoughDielectric,
    RoughPlastic, Roughness, ThinDielectric, TwoSided,
};
use raytrace::shape::{Coordinates, Surface};
use raytrace::texture::Texture;
use raytrace::{Color, Float, Hit, Vec3, lit};

/// A material under test, by its constructor's arguments (in `f64`, made in any scalar).
#[derive(Clone, Copy, Debug)]
pub enum Spec {
    /// A rough conductor of a named metal, `(αu, αv)` (equal: isotropic).
    RoughConductor(Distribution, (f64, f64), &'static str),
    /// A rough dielectric of `(αu, αv)` and interior index (in vacuum).
    RoughDielectric(Distribution, (f64, f64), f64),
    /// A rough plastic of `α`, diffuse reflectance, nonlinear or not.
    RoughPlastic(Distribution, f64, [f64; 3], bool),
    /// A smooth plastic of diffuse reflectance, nonlinear or not.
    Plastic([f64; 3], bool),
    /// A two-sided rough conductor.
    TwoSidedRoughConductor(Distribution, f64, &'static str),
    /// A smooth conductor of a named metal.
    Conductor(&'static str),
    /// A thin sheet of interior index.
    ThinDielectric(f64),
}

impl Spec {
    /// The material in scalar `F`.
    pub fn build<F: Float>(&self) -> MaterialKind<F> {
        let scalar = |a: f64| Texture::scalar(lit::<F>(a));
        let colour = |c: [f64; 3]| Texture::constant(Color::from_f64(c[0], c[1], c[2]));
        let roughness = |d, (au, av): (f64, f64)| {
            if au == av {
                Roughness::isotropic(d, scalar(au)).unwrap()
            } else {
                Roughness::anisotropic(d, scalar(au), scalar(av)).unwrap()
            }
        };
        match *self {
            Spec::RoughConductor(d, alpha, metal) => {
                RoughConductor::new(Metal::named(metal).unwrap(), roughness(d, alpha)).into()
            }
            Spec::RoughDielectric(d, alpha, eta) => RoughDielectric::new(roughness(d, alpha), eta, "vacuum")
                .unwrap()
                .into(),
            Spec::RoughPlastic(d, alpha, diffuse, nonlinear) => {
                let coated = Coated::new(colour(diffuse), "polypropylene", "air")
                    .unwrap()
                    .nonlinear(nonlinear);
                RoughPlastic::new(coated, d, lit(alpha)).unwrap().into()
            }
            Spec::Plastic(diffuse, nonlinear) => {
                let coated = Coated::new(colour(diffuse), "polypropylene", "air")
                    .unwrap()
                    .nonlinear(nonlinear);
                Plastic::new(coated).into()
            }
            Spec::TwoSidedRoughConductor(d, alpha, metal) => {
                let inner = RoughConductor::new(Metal::named(metal).unwrap(), roughness(d, (alpha, alpha)));
                TwoSided::new(inner.into()).unwrap().into()
            }
            Spec::Conductor(metal) => Conductor::new(Metal::named(metal).unwrap()).into(),
            Spec::ThinDielectric(eta) => ThinDielectric::new(eta, "vacuum").unwrap().into(),
        }
    }

    /// The smallest roughness, to shape a χ² grid by (1 for the smooth ones).
    pub fn alpha(&self) -> f64 {
        match *self {
            Spec::RoughConductor(_, (u, v), _) | Spec::RoughDielectric(_, (u, v), _) => u.min(v),
            Spec::RoughPlastic(_, a, ..) | Spec::TwoSidedRoughConductor(_, a, _) => a,
            _ => 1.0,
        }
    }
}

/// Where a material is seen from: the hit, `wo`, and the shading normal facing the ray.
pub struct Setup<F> {
    /// The hit at the origin.
    pub hit: Hit<F>,
    /// The direction toward the viewer.
    pub wo: Vec3<F>,
    /// The unit normal on `wo`'s side (`f64`).
    pub facing: [f64; 3],
}

/// A hit at the origin on a surface of unit outward normal `normal`, seen from `wo` at
/// `theta` degrees from the normal on the side `front` says, at azimuth `phi` degrees
/// about it; `∂p/∂u` is the first axis of the test's own frame about `normal`.
pub fn setup<F: Float>(normal: [f64; 3], theta: f64, phi: f64, front: bool) -> Setup<F> {
    let n = normalize(normal);
    let (t, b) = frame(n);
    let facing = if front { n } else { n.map(|x| -x) };
    let (st, ct) = theta.to_radians().sin_cos();
    let (sp, cp) = phi.to_radians().sin_cos();
    let wo: Vec3<F> = unit_from(std::array::from_fn(|i| {
        ct * facing[i] + st * (cp * t[i] + sp * b[i])
    }));
    let surface = Surface::bare(F::one(), Vec3::zero(), unit_from(n));
    let hit = Hit::new(surface, -wo).with(Coordinates {
        uv: [lit(0.25), lit(0.5)],
        dpdu: unit_from(t),
    });
    assert_eq!(hit.front_face, front, "θ = {theta}");
    Setup { hit, wo, facing }
}

/// `d` reflected about the unit `n`, in `f64`.
pub fn mirror(d: [f64; 3], n: [f64; 3]) -> [f64; 3] {
    let c = 2.0 * super::dot(d, n);
    std::array::from_fn(|i| c * n[i] - d[i])
}

/// `wo` (pointing away from a surface of unit normal `n` on its side) refracted into a
/// medium of relative index `eta` (far over near), in `f64`; `None` under total internal
/// reflection.
pub fn refracted(wo: [f64; 3], n: [f64; 3], eta: f64) -> Option<[f64; 3]> {
    let c = super::dot(wo, n);
    let s2 = (1.0 - c * c) / (eta * eta);
    (s2 < 1.0).then(|| {
        let ct = (1.0 - s2).sqrt();
        std::array::from_fn(|i| -wo[i] / eta + (c / eta - ct) * n[i])
    })
}
