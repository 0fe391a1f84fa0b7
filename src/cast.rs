//! Changing a scene's scalar: build a scene once (in `f64`, say) and render it in `f32`,
//! `f64` or double-double. Every value is rounded through `f64` and re-validated, so a
//! value that does not survive the rounding (a radius that underflows to 0, a triangle that
//! becomes degenerate) is an error, not a silently different scene.

use crate::background::Background;
use crate::error::Result;
use crate::float::Float;
use crate::light::PointLight;
use crate::material::{Dielectric, Lambertian, MaterialKind, Mirror};
use crate::scene::EnumScene;
use crate::shape::{Plane, ShapeKind, Sphere, Triangle};

/// A scalar for `x` rounded through `f64`.
fn to<F: Float, G: Float>(x: F) -> G {
    G::from_f64(x.to_f64())
}

impl<F: Float> Sphere<F> {
    /// This sphere in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<Sphere<G>> {
        Sphere::new(self.center().cast(), to(self.radius()))
    }
}

impl<F: Float> Plane<F> {
    /// This plane in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<Plane<G>> {
        Plane::new(self.point().cast(), self.normal().cast())
    }
}

impl<F: Float> Triangle<F> {
    /// This triangle in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<Triangle<G>> {
        let [a, b, c] = self.vertices();
        Triangle::new(a.cast(), b.cast(), c.cast())
    }
}

impl<F: Float> ShapeKind<F> {
    /// This shape in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<ShapeKind<G>> {
        Ok(match self {
            Self::Sphere(s) => s.cast()?.into(),
            Self::Plane(p) => p.cast()?.into(),
            Self::Triangle(t) => t.cast()?.into(),
        })
    }
}

impl<F: Float> MaterialKind<F> {
    /// This material in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<MaterialKind<G>> {
        Ok(match self {
            Self::Mirror(m) => Mirror::new(m.albedo().cast())?.into(),
            Self::Lambertian(m) => Lambertian::new(m.albedo().cast())?
                .with_sampler(m.sampler())
                .into(),
            Self::Dielectric(m) => Dielectric::new(to(m.refractive_index()))?
                .with_albedo(m.albedo().cast())?
                .with_reflectance(m.reflectance())
                .into(),
        })
    }
}

impl<F: Float> Background<F> {
    /// This background in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<Background<G>> {
        match self {
            Self::Solid(c) => Background::solid(c.cast()),
            Self::Sky { horizon, zenith } => Background::sky(horizon.cast(), zenith.cast()),
        }
    }
}

impl<F: Float> PointLight<F> {
    /// This light in scalar `G`.
    pub fn cast<G: Float>(&self) -> Result<PointLight<G>> {
        PointLight::new(self.position().cast(), self.intensity().cast())
    }
}

impl<F: Float> EnumScene<F> {
    /// The same scene in scalar `G` (objects, lights, background, acceleration).
    pub fn cast<G: Float>(&self) -> Result<EnumScene<G>> {
        self.try_map(|s| s.cast(), |m| m.cast())
    }

    fn try_map<G: Float>(
        &self,
        shape: impl Fn(&ShapeKind<F>) -> Result<ShapeKind<G>>,
        material: impl Fn(&MaterialKind<F>) -> Result<MaterialKind<G>>,
    ) -> Result<EnumScene<G>> {
        let mut out = EnumScene::new(self.background().cast()?);
        out.set_acceleration(self.acceleration());
        for o in self.objects() {
            out.add(shape(&o.shape)?, material(&o.material)?);
        }
        for l in self.lights() {
            out.add_light(l.cast()?);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vec3::Vec3;

    #[test]
    fn round_trip_and_rounding_failures() {
        let mut scene = EnumScene::<f64>::new(Background::default());
        scene.add(
            Sphere::new(Vec3::new(0.1, 0.2, -3.0), 0.5).unwrap(),
            Mirror::new(Vec3::splat(0.5)).unwrap(),
        );
        scene.add(
            Triangle::new(Vec3::zero(), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap(),
            Dielectric::new(1.5).unwrap(),
        );
        scene.add_light(PointLight::new(Vec3::new(0.0, 5.0, 0.0), Vec3::splat(3.0)).unwrap());
        let single: EnumScene<f32> = scene.cast().unwrap();
        let back: EnumScene<f64> = single.cast().unwrap();
        assert_eq!(back.objects().len(), 2);
        assert_eq!(back.lights().len(), 1);
        let ShapeKind::Sphere(s) = back.objects()[0].shape else {
            panic!()
        };
        assert_eq!(s.radius(), 0.5);
        assert_eq!(s.center().x, f64::from(0.1f32));

        let mut tiny = EnumScene::<f64>::new(Background::default());
        tiny.add(
            Sphere::new(Vec3::zero(), 1e-50).unwrap(),
            Mirror::new(Vec3::splat(0.5)).unwrap(),
        );
        assert!(
            tiny.cast::<f32>().is_err(),
            "a radius that underflows in f32 is an error"
        );
    }
}
