//! Invalid values are rejected with typed errors, by every constructor and by `render`.

use super::scene::*;
use raytrace::Image;
use raytrace::error::Field;
use raytrace::prelude::*;

#[test]
fn invalid_values_are_rejected_with_typed_errors() {
    let v = Vec3::<f64>::splat(0.5);
    let bad_albedos = [
        Vec3::new(1.1, 0.5, 0.5),
        Vec3::new(-0.1, 0.5, 0.5),
        Vec3::new(f64::NAN, 0.5, 0.5),
    ];
    for a in bad_albedos {
        assert!(matches!(
            Mirror::new(a),
            Err(Error::InvalidValue {
                field: Field::MirrorAlbedo,
                ..
            })
        ));
        assert!(matches!(
            Lambertian::new(a),
            Err(Error::InvalidValue {
                field: Field::MatteAlbedo,
                ..
            })
        ));
    }
    assert!(matches!(
        Sphere::new(v, -1.0),
        Err(Error::InvalidValue {
            field: Field::SphereRadius,
            ..
        })
    ));
    assert!(matches!(Sphere::new(v, 0.0), Err(Error::InvalidValue { .. })));
    assert!(matches!(
        Sphere::new(Vec3::new(0.0, f64::INFINITY, 0.0), 1.0),
        Err(Error::InvalidValue { .. })
    ));
    assert!(PointLight::new(v, Vec3::new(1.0, -1.0, 1.0)).is_err());
    assert!(Background::solid(Vec3::new(0.0, f64::NAN, 0.0)).is_err());
    assert!(matches!(
        RenderSettings::new(0, 10, 0),
        Err(Error::InvalidValue {
            field: Field::SamplesPerPixel,
            ..
        })
    ));
    assert!(matches!(
        ScreenCamera::new(0, 0),
        Err(Error::InvalidValue {
            field: Field::ImageSize,
            ..
        })
    ));
    assert!(Image::new(0, 5).is_err());
    assert!(Image::new(usize::MAX, 2).is_err());
    let cam = ScreenCamera::new(4, 2).unwrap();
    let zero_spp = RenderSettings {
        samples_per_pixel: 0,
        ..RenderSettings::default()
    };
    assert!(render(&enum_scene::<f64>(), &cam, &zero_spp).is_err());
}
