//! The scenes of the accuracy study: where precision matters, and a Monte Carlo baseline.

use crate::scenes;
use raytrace::prelude::*;
use raytrace::shape::ShapeKind;

/// A camera the study can rebuild in every scalar.
#[derive(Clone, Copy, Debug)]
pub enum Cam {
    /// The spec's camera, possibly translated.
    Screen(ScreenCamera),
    /// A look-at pinhole camera (built in f64).
    LookAt(LookAtCamera<f64>),
}

/// One scene of the study.
pub struct Case {
    /// Short name, used in the CSV and the charts.
    pub name: String,
    /// What it stresses.
    pub about: &'static str,
    /// The scene, built in f64 (cast to each scalar for rendering).
    pub scene: EnumScene<f64>,
    /// The camera.
    pub camera: Cam,
    /// Samples per pixel.
    pub spp: u32,
    /// Maximum bounces.
    pub max_depth: u32,
    /// Whether the double-double reference is affordable (else the f64 stable render is the reference).
    pub dd_reference: bool,
}

/// `scene` moved by `offset` along every axis (spheres only: the study's scenes).
fn translated(scene: &EnumScene<f64>, offset: f64) -> raytrace::Result<EnumScene<f64>> {
    let mut out = EnumScene::new(scene.background().clone());
    for o in scene.objects() {
        let ShapeKind::Sphere(s) = o.shape else {
            unreachable!("the translated scenes hold spheres only")
        };
        out.add(
            Sphere::new(s.center() + Vec3::splat(offset), s.radius())?,
            scene.material(o.material).clone(),
        );
    }
    Ok(out)
}

fn mirror(r: f64, g: f64, b: f64) -> raytrace::Result<Mirror<f64>> {
    Mirror::new(Vec3::new(r, g, b))
}

/// Tiny mirror spheres 2000 units away (distance/radius 2000), through a telephoto lens.
fn tiny_far(width: usize) -> raytrace::Result<(EnumScene<f64>, Cam)> {
    let mut scene = EnumScene::new(Background::default());
    for (k, (i, j)) in (-1..=1).flat_map(|i| (-1..=1).map(move |j| (i, j))).enumerate() {
        let c = Vec3::new(
            3.0 * f64::from(i),
            3.0 * f64::from(j),
            -2000.0 - 2.0 * f64::from(i + j),
        );
        let shade = 0.35 + 0.07 * k as f64;
        scene.add(Sphere::new(c, 1.0)?, mirror(shade, 0.9 - shade / 2.0, 0.95)?);
    }
    let cam = LookAtCamera::new(
        Vec3::zero(),
        Vec3::new(0.0, 0.0, -2000.0),
        Vec3::new(0.0, 1.0, 0.0),
        0.35,
        width,
        width / 2,
    )?;
    Ok((scene, Cam::LookAt(cam)))
}

/// A mirror ground of radius 10⁶ seen at grazing angles towards the horizon.
fn grazing_huge() -> raytrace::Result<EnumScene<f64>> {
    let mut scene = EnumScene::new(Background::default());
    scene.add(
        Sphere::new(Vec3::new(0.0, -1e6 - 0.8, -4.0), 1e6)?,
        mirror(0.6, 0.6, 0.65)?,
    );
    scene.add(
        Sphere::new(Vec3::new(-1.6, 0.0, -5.0), 0.8)?,
        mirror(0.9, 0.6, 0.3)?,
    );
    scene.add(
        Sphere::new(Vec3::new(1.6, 0.0, -9.0), 0.8)?,
        mirror(0.3, 0.6, 0.9)?,
    );
    Ok(scene)
}

/// Two large facing mirrors with small spheres between: paths of up to 50 bounces.
fn deep_mirrors() -> raytrace::Result<EnumScene<f64>> {
    let mut scene = EnumScene::new(Background::default());
    scene.add(
        Sphere::new(Vec3::new(-7.0, 0.0, -6.0), 5.0)?,
        mirror(0.95, 0.95, 0.9)?,
    );
    scene.add(
        Sphere::new(Vec3::new(7.0, 0.0, -6.0), 5.0)?,
        mirror(0.9, 0.95, 0.95)?,
    );
    scene.add(
        Sphere::new(Vec3::new(0.0, -0.6, -5.0), 0.5)?,
        mirror(0.9, 0.3, 0.3)?,
    );
    scene.add(
        Sphere::new(Vec3::new(0.0, 0.6, -7.0), 0.5)?,
        mirror(0.3, 0.9, 0.3)?,
    );
    Ok(scene)
}

/// A glass sphere of radius 2·10⁻⁴ — its diameter is below the textbook's fixed
/// `t_min = 0.001`, so the textbook never finds the exit — filling a narrow view, with
/// coloured mirrors behind it.
fn small_glass(width: usize) -> raytrace::Result<(EnumScene<f64>, Cam)> {
    let mut scene = EnumScene::new(Background::default());
    scene.add(
        Sphere::new(Vec3::new(0.0, 0.0, -0.004), 2e-4)?,
        Dielectric::new(1.5)?,
    );
    scene.add(
        Sphere::new(Vec3::new(-6e-4, 2e-4, -0.01), 4e-4)?,
        mirror(0.9, 0.3, 0.2)?,
    );
    scene.add(
        Sphere::new(Vec3::new(6e-4, -2e-4, -0.01), 4e-4)?,
        mirror(0.2, 0.5, 0.9)?,
    );
    let cam = LookAtCamera::new(
        Vec3::zero(),
        Vec3::new(0.0, 0.0, -1.0),
        Vec3::new(0.0, 1.0, 0.0),
        9.0,
        width,
        width / 2,
    )?;
    Ok((scene, Cam::LookAt(cam)))
}

/// Every case at image width `width` (even, for the spec's 2:1 camera).
pub fn all(width: usize, seed: u64) -> raytrace::Result<Vec<Case>> {
    let screen = ScreenCamera::with_width(width)?;
    let case = |name: &str, about, scene, camera, spp, max_depth, dd_reference| Case {
        name: name.to_string(),
        about,
        scene,
        camera,
        spp,
        max_depth,
        dd_reference,
    };
    let mirrors = scenes::four_mirrors::<f64>()?;
    let mut cases = vec![case(
        "four_mirrors",
        "the spec's scene",
        mirrors.clone(),
        Cam::Screen(screen),
        1,
        10,
        true,
    )];
    for exp in [3, 4, 5] {
        let t = 10f64.powi(exp);
        cases.push(case(
            &format!("far_1e{exp}"),
            "the spec's scene and camera moved far from the origin",
            translated(&mirrors, t)?,
            Cam::Screen(screen.translated([t; 3])?),
            1,
            10,
            true,
        ));
    }
    let (scene, cam) = tiny_far(width)?;
    cases.push(case(
        "tiny_far",
        "small spheres far away (distance/radius 2000)",
        scene,
        cam,
        1,
        10,
        true,
    ));
    cases.push(case(
        "grazing_huge",
        "grazing rays on a sphere of radius 1e6",
        grazing_huge()?,
        Cam::Screen(screen),
        1,
        10,
        true,
    ));
    cases.push(case(
        "deep_mirrors",
        "facing mirrors, 50 bounces",
        deep_mirrors()?,
        Cam::Screen(screen),
        1,
        50,
        true,
    ));
    let (scene, cam) = small_glass(width)?;
    cases.push(case(
        "small_glass",
        "a glass sphere of radius 2e-4",
        scene,
        cam,
        8,
        20,
        true,
    ));
    let rs_cam = scenes::random_spheres_camera::<f64>(width)?;
    cases.push(case(
        "random_spheres",
        "Ray Tracing in One Weekend's final scene (Monte Carlo)",
        scenes::random_spheres::<f64>(seed)?,
        Cam::LookAt(rs_cam),
        4,
        50,
        true,
    ));
    Ok(cases)
}
