//! The scenes, built in code, shared by the examples, the benches and the accuracy study.
//! The library holds no scenes.

#![allow(dead_code)]

use raytrace::prelude::*;

/// The specification's minimum scene: four mirror spheres with different albedos
/// (gold, rose, green, steel blue) above a dim mirror floor, for the spec's camera.
pub fn four_mirrors<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let mut scene = EnumScene::new(Background::default());
    let mirror = |r, g, b| Mirror::new(Vec3::from_f64(r, g, b));
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    // Four mirrors, left to right: gold, rose, green, steel blue.
    scene.add(sphere(-2.7, 0.0, -4.0, 0.8)?, mirror(0.95, 0.78, 0.35)?);
    scene.add(sphere(-0.9, -0.2, -3.2, 0.6)?, mirror(0.92, 0.45, 0.45)?);
    scene.add(sphere(0.9, 0.0, -4.0, 0.8)?, mirror(0.45, 0.85, 0.5)?);
    scene.add(sphere(2.7, 0.2, -4.8, 1.0)?, mirror(0.5, 0.65, 0.95)?);
    // A dim mirror floor: a sphere so large it reads as a plane at y = −0.8.
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, mirror(0.55, 0.55, 0.6)?);
    Ok(scene)
}

/// The extension scene: matte and mirror spheres on a matte ground, for the spec's camera.
pub fn matte_spheres<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let mut scene = EnumScene::new(Background::default());
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    let matte = |r, g, b| Lambertian::new(Vec3::from_f64(r, g, b));
    let mirror = |r, g, b| Mirror::new(Vec3::from_f64(r, g, b));
    scene.add(sphere(-2.6, 0.0, -4.0, 0.8)?, matte(0.8, 0.3, 0.3)?);
    scene.add(sphere(-0.9, 0.0, -4.0, 0.8)?, mirror(0.9, 0.9, 0.9)?);
    scene.add(sphere(0.9, 0.0, -4.0, 0.8)?, matte(0.3, 0.5, 0.85)?);
    scene.add(sphere(2.6, 0.0, -4.0, 0.8)?, mirror(0.95, 0.75, 0.4)?);
    scene.add(sphere(0.0, -0.55, -2.6, 0.25)?, matte(0.9, 0.9, 0.9)?);
    // A matte ground: a sphere so large it reads as a plane at y = −0.8.
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, matte(0.5, 0.55, 0.45)?);
    Ok(scene)
}

/// Matte spheres lit by three coloured point lights under a dim sky, for the spec's camera.
pub fn point_lights<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let dim = |r, g, b| Vec3::from_f64(r, g, b);
    let mut scene = EnumScene::new(Background::sky(dim(0.02, 0.02, 0.025), dim(0.04, 0.05, 0.08))?);
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    let matte = |r, g, b| Lambertian::new(Vec3::from_f64(r, g, b));
    scene.add(sphere(-1.8, -0.1, -4.2, 0.7)?, matte(0.85, 0.85, 0.85)?);
    scene.add(sphere(0.0, 0.1, -4.6, 0.9)?, matte(0.8, 0.6, 0.4)?);
    scene.add(sphere(1.8, -0.1, -4.2, 0.7)?, matte(0.85, 0.85, 0.85)?);
    scene.add(
        sphere(0.9, 0.3, -3.0, 0.25)?,
        Mirror::new(Vec3::from_f64(0.9, 0.9, 0.9))?,
    );
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, matte(0.6, 0.6, 0.6)?);
    let light = |x, y, z, r, g, b| PointLight::new(Vec3::from_f64(x, y, z), Vec3::from_f64(r, g, b));
    scene.add_light(light(-3.0, 3.0, -2.0, 36.0, 15.0, 9.0)?);
    scene.add_light(light(3.0, 2.5, -2.5, 9.0, 18.0, 36.0)?);
    scene.add_light(light(0.0, 4.0, -6.0, 15.0, 15.0, 15.0)?);
    Ok(scene)
}
