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

/// The final scene of *Ray Tracing in One Weekend*: a large matte ground sphere, three big
/// spheres (glass, matte, mirror) and a 22×22 grid of small random spheres — matte (80 %),
/// mirror (15 %) or glass (5 %) — jittered from the `seed`, skipping the spot by the
/// mirror. (The book's fuzzy metal is a plain mirror here: the spec models no fuzz.)
pub fn random_spheres<F: Float>(seed: u64) -> raytrace::Result<EnumScene<F>> {
    use rand::{RngExt, SeedableRng};
    let mut rng = raytrace::DefaultRng::seed_from_u64(seed);
    let mut scene = EnumScene::new(Background::default());
    let sphere = |x: f64, y: f64, z: f64, r: f64| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    let rgb = |r: f64, g: f64, b: f64| Vec3::from_f64(r, g, b);
    scene.add(
        sphere(0.0, -1000.0, 0.0, 1000.0)?,
        Lambertian::new(rgb(0.5, 0.5, 0.5))?,
    );
    for a in -11..11 {
        for b in -11..11 {
            let choose: f64 = rng.random();
            let (x, z) = (
                f64::from(a) + 0.9 * rng.random::<f64>(),
                f64::from(b) + 0.9 * rng.random::<f64>(),
            );
            if ((x - 4.0).powi(2) + (z).powi(2)).sqrt() <= 0.9 {
                continue;
            }
            let shape = sphere(x, 0.2, z, 0.2)?;
            if choose < 0.8 {
                let mut c = || rng.random::<f64>() * rng.random::<f64>();
                scene.add(shape, Lambertian::new(rgb(c(), c(), c()))?);
            } else if choose < 0.95 {
                let mut c = || rng.random_range(0.5..1.0);
                scene.add(shape, Mirror::new(rgb(c(), c(), c()))?);
            } else {
                scene.add(shape, Dielectric::new(lit(1.5))?);
            }
        }
    }
    scene.add(sphere(0.0, 1.0, 0.0, 1.0)?, Dielectric::new(lit(1.5))?);
    scene.add(sphere(-4.0, 1.0, 0.0, 1.0)?, Lambertian::new(rgb(0.4, 0.2, 0.1))?);
    scene.add(sphere(4.0, 1.0, 0.0, 1.0)?, Mirror::new(rgb(0.7, 0.6, 0.5))?);
    Ok(scene)
}

/// The book's camera for [`random_spheres`]: from `(13, 2, 3)` towards the origin, 20°
/// vertical field of view, 16:9.
pub fn random_spheres_camera<F: Float>(width: usize) -> raytrace::Result<LookAtCamera<F>> {
    LookAtCamera::new(
        Vec3::from_f64(13.0, 2.0, 3.0),
        Vec3::zero(),
        Vec3::from_f64(0.0, 1.0, 0.0),
        lit(20.0),
        width,
        (width * 9 / 16).max(1),
    )
}

/// Glass (the spec's refraction extra): a solid glass sphere, a hollow one (an inner
/// sphere of index 1/1.5 inside an outer one of 1.5), a mirror and matte spheres on a matte
/// ground, for the spec's camera.
pub fn glass<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let mut scene = EnumScene::new(Background::default());
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    let matte = |r, g, b| Lambertian::new(Vec3::from_f64(r, g, b));
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, matte(0.55, 0.6, 0.5)?);
    scene.add(sphere(-1.7, 0.0, -4.0, 0.8)?, Dielectric::new(lit(1.5))?);
    scene.add(sphere(0.0, 0.0, -4.0, 0.8)?, Dielectric::new(lit(1.5))?);
    scene.add(sphere(0.0, 0.0, -4.0, 0.7)?, Dielectric::new(lit(1.0 / 1.5))?);
    scene.add(
        sphere(1.7, 0.0, -4.0, 0.8)?,
        Mirror::new(Vec3::from_f64(0.8, 0.6, 0.2))?,
    );
    scene.add(sphere(-0.9, -0.55, -2.9, 0.25)?, matte(0.8, 0.2, 0.2)?);
    scene.add(sphere(0.8, -0.6, -2.7, 0.2)?, Dielectric::new(lit(1.5))?);
    scene.add(sphere(0.0, 0.1, -7.0, 0.9)?, matte(0.2, 0.3, 0.8)?);
    Ok(scene)
}

/// The new shapes: an infinite plane as the ground, a pyramid and a tetrahedron of
/// triangles, beside spheres, for the spec's camera.
pub fn plane_and_triangles<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let mut scene = EnumScene::new(Background::default());
    let p = |x, y, z| Vec3::<F>::from_f64(x, y, z);
    let matte = |r, g, b| Lambertian::new(Vec3::from_f64(r, g, b));
    let mirror = |r, g, b| Mirror::new(Vec3::from_f64(r, g, b));
    scene.add(
        Plane::new(p(0.0, -0.8, 0.0), p(0.0, 1.0, 0.0))?,
        matte(0.5, 0.5, 0.55)?,
    );
    // A square pyramid of four mirror-gold triangles (counter-clockwise seen from outside).
    let (apex, base) = (
        p(-1.4, 0.7, -4.5),
        [
            p(-2.4, -0.8, -3.5),
            p(-0.4, -0.8, -3.5),
            p(-0.4, -0.8, -5.5),
            p(-2.4, -0.8, -5.5),
        ],
    );
    for k in 0..4 {
        scene.add(
            Triangle::new(base[k], base[(k + 1) % 4], apex)?,
            mirror(0.9, 0.75, 0.4)?,
        );
    }
    // A matte tetrahedron.
    let t = [
        p(1.0, -0.8, -3.6),
        p(2.6, -0.8, -4.0),
        p(1.6, -0.8, -5.2),
        p(1.7, 0.6, -4.3),
    ];
    for (a, b, c, col) in [
        (0, 2, 1, (0.8, 0.3, 0.2)),
        (0, 1, 3, (0.2, 0.6, 0.8)),
        (1, 2, 3, (0.3, 0.7, 0.3)),
        (2, 0, 3, (0.9, 0.9, 0.4)),
    ] {
        scene.add(Triangle::new(t[a], t[b], t[c])?, matte(col.0, col.1, col.2)?);
    }
    scene.add(
        Sphere::new(p(0.3, -0.3, -3.0), lit(0.5))?,
        mirror(0.85, 0.85, 0.9)?,
    );
    scene.add(Sphere::new(p(3.5, 0.2, -6.0), lit(1.0))?, matte(0.7, 0.3, 0.6)?);
    Ok(scene)
}

/// Every way light leaves a surface, for the spec's camera: a sphere lamp, a two-sided
/// emitting triangle that also reflects, an emitting plane (which is never sampled, only
/// hit), a point light, and a mirror and a glass sphere that see the lamps only through
/// the rays they reflect and refract, on a matte ground under a dim solid background.
pub fn area_lights<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let v = |x, y, z| Vec3::<F>::from_f64(x, y, z);
    let mut scene = EnumScene::new(Background::solid(v(0.02, 0.02, 0.03))?);
    scene.add(
        Sphere::new(v(0.0, -101.0, -3.0), lit(100.0))?,
        Lambertian::new(v(0.6, 0.6, 0.5))?,
    );
    scene.add(
        Sphere::new(v(-1.2, 0.0, -3.0), lit(0.6))?,
        Mirror::new(v(0.9, 0.9, 0.9))?,
    );
    scene.add(
        Sphere::new(v(0.2, -0.4, -2.5), lit(0.5))?,
        Dielectric::new(lit(1.5))?,
    );
    scene.add(
        Sphere::new(v(1.3, 0.6, -3.5), lit(0.3))?,
        Emissive::new(v(8.0, 6.0, 3.0))?,
    );
    let panel = Triangle::new(v(-1.5, 1.5, -4.0), v(0.5, 1.5, -4.0), v(-0.5, 2.5, -3.0))?;
    let panel_light = Emissive::new(v(1.0, 2.0, 4.0))?
        .two_sided(true)
        .with_albedo(v(0.5, 0.5, 0.5))?;
    scene.add(panel, panel_light);
    scene.add(
        Plane::new(v(0.0, 0.0, -8.0), v(0.0, 0.0, 1.0))?,
        Emissive::new(v(0.2, 0.1, 0.1))?,
    );
    scene.add_light(PointLight::new(v(2.0, 3.0, -1.0), v(4.0, 4.0, 4.0))?);
    Ok(scene)
}

/// A caustic: a glass sphere on a matte floor, lit only by a small, bright spherical lamp
/// above and behind it under a near-black sky, for the spec's camera. The sphere focuses
/// the lamp into a bright spot on the floor in front of it, inside its own shadow. The
/// spot's light is found only by paths that leave the floor in a random direction,
/// cross the glass and happen to meet the lamp (a shadow ray toward the lamp is blocked by
/// the glass): rare, bright paths, the hard case for an estimate of a pixel's error.
pub fn caustic<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let v = |x, y, z| Vec3::<F>::from_f64(x, y, z);
    let mut scene = EnumScene::new(Background::solid(v(0.002, 0.002, 0.003))?);
    scene.add(
        Plane::new(v(0.0, -0.8, 0.0), v(0.0, 1.0, 0.0))?,
        Lambertian::new(v(0.7, 0.7, 0.65))?,
    );
    scene.add(
        Sphere::new(v(0.0, -0.2, -3.5), lit(0.6))?,
        Dielectric::new(lit(1.5))?,
    );
    scene.add(
        Sphere::new(v(1.6, -0.45, -4.2), lit(0.35))?,
        Lambertian::new(v(0.3, 0.45, 0.7))?,
    );
    scene.add(
        Sphere::new(v(0.7, 1.6, -4.4), lit(0.15))?,
        Emissive::new(v(300.0, 270.0, 220.0))?,
    );
    Ok(scene)
}

/// The Cornell box of `scenes/cornell_box.toml` (Mitsuba 3's), `width` pixels square, its
/// scene and camera in `F`, and its render settings.
pub fn cornell_box<F: Float>(
    width: usize,
) -> raytrace::Result<(EnumScene<F>, raytrace::scene_file::FileCamera<F>, RenderSettings)> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.toml");
    let mut file = raytrace::scene_file::SceneFile::load(&path)?;
    file.render_mut().width = width;
    let built = file.build::<F>()?;
    Ok((built.scene, built.camera, built.settings))
}
