//! The feature layers a denoiser takes: the albedo and shading normal of the first hit
//! with a non-delta lobe (through mirrors, tinted by them), the first hit's depth, the
//! background's colour where a ray leaves the scene; and the layers' names in the EXR.

use crate::scenes;
use raytrace::prelude::*;
use raytrace::render::Aovs;
use raytrace::{EnumScene, Render};

const WIDTH: usize = 8;
const HEIGHT: usize = 4;

fn features(scene: &EnumScene<f64>, spp: u32) -> Render {
    let camera = ScreenCamera::new(WIDTH, HEIGHT).unwrap();
    Renderer::new(scene, &camera)
        .spp(spp)
        .max_depth(5)
        .aov(true)
        .render()
        .unwrap()
}

fn aov(render: &Render) -> &Aovs {
    render.aov.as_ref().unwrap()
}

/// The distance from the eye to the plane `z = −d` through pixel `(x, y)`'s centre: the
/// spec's screen point `P` lies at `z = −1`, so the hit is at `d·|P|`.
fn depth_through_centre(x: usize, y: usize, d: f64) -> f64 {
    let camera = ScreenCamera::new(WIDTH, HEIGHT).unwrap();
    let p = camera.screen_point::<f64>(x as f64, y as f64);
    d * p.length()
}

fn v(x: f64, y: f64, z: f64) -> Vec3<f64> {
    Vec3::new(x, y, z)
}

fn close(a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    a.iter().zip(b).all(|(a, b)| (a - b).abs() <= tolerance)
}

#[test]
fn a_matte_wall_gives_its_albedo_normal_and_distance() {
    let mut scene = EnumScene::new(Background::solid(v(0.3, 0.2, 0.1)).unwrap());
    scene.add(
        Plane::new(v(0.0, 0.0, -2.0), v(0.0, 0.0, 1.0)).unwrap(),
        Lambertian::new(v(0.2, 0.4, 0.6)).unwrap(),
    );
    // One sample per pixel: the ray through the pixel's centre.
    let render = features(&scene, 1);
    let f = aov(&render);
    assert_eq!((f.width(), f.height()), (WIDTH, HEIGHT));
    for (i, ((albedo, normal), &depth)) in f.albedo().iter().zip(f.normal()).zip(f.depth()).enumerate() {
        assert_eq!(*albedo, [0.2, 0.4, 0.6], "pixel {i}");
        assert_eq!(*normal, [0.0, 0.0, 1.0], "pixel {i}");
        let want = depth_through_centre(i % WIDTH, i / WIDTH, 2.0);
        assert!(
            (depth - want).abs() <= 1e-12 * want,
            "pixel {i}: {depth} vs {want}"
        );
    }
    // Jittered samples: the same albedo and normal; the nearest depth is nearer than
    // the centre's for pixels whose cell reaches closer to the middle of the wall.
    let render = features(&scene, 4);
    let f = aov(&render);
    for (i, (albedo, normal)) in f.albedo().iter().zip(f.normal()).enumerate() {
        assert!(close(*albedo, [0.2, 0.4, 0.6], 1e-15), "pixel {i}: {albedo:?}");
        assert!(close(*normal, [0.0, 0.0, 1.0], 1e-15), "pixel {i}: {normal:?}");
    }
    let corner = f.depth()[0];
    assert!(
        corner < depth_through_centre(0, 0, 2.0) && corner > 2.0,
        "{corner}"
    );
}

/// A tinted mirror shows the matte wall behind the camera: the features are the wall's,
/// its albedo times the mirror's tint, at the mirror's distance.
#[test]
fn a_mirror_shows_the_features_of_what_it_reflects_tinted() {
    let mut scene = EnumScene::new(Background::solid(v(0.0, 0.0, 0.0)).unwrap());
    scene.add(
        Plane::new(v(0.0, 0.0, -2.0), v(0.0, 0.0, 1.0)).unwrap(),
        Mirror::new(v(0.5, 0.5, 0.25)).unwrap(),
    );
    scene.add(
        Plane::new(v(0.0, 0.0, 1.0), v(0.0, 0.0, -1.0)).unwrap(),
        Lambertian::new(v(0.8, 0.8, 0.8)).unwrap(),
    );
    let render = features(&scene, 1);
    let f = aov(&render);
    for (i, ((albedo, normal), &depth)) in f.albedo().iter().zip(f.normal()).zip(f.depth()).enumerate() {
        assert!(close(*albedo, [0.4, 0.4, 0.2], 1e-15), "pixel {i}: {albedo:?}");
        assert_eq!(*normal, [0.0, 0.0, -1.0], "pixel {i}");
        let want = depth_through_centre(i % WIDTH, i / WIDTH, 2.0);
        assert!((depth - want).abs() <= 1e-12 * want, "pixel {i}");
    }
}

#[test]
fn a_ray_that_leaves_the_scene_takes_the_background_clamped() {
    let mut scene = EnumScene::new(Background::solid(v(0.3, 1.7, 0.1)).unwrap());
    // Behind the camera: no camera ray meets it.
    scene.add(
        Sphere::new(v(0.0, 0.0, 5.0), 1.0).unwrap(),
        Lambertian::new(v(0.5, 0.5, 0.5)).unwrap(),
    );
    let render = features(&scene, 2);
    let f = aov(&render);
    assert!(
        f.albedo().iter().all(|a| *a == [0.3, 1.0, 0.1]),
        "{:?}",
        f.albedo()[0]
    );
    assert!(f.normal().iter().all(|n| *n == [0.0; 3]));
    assert!(f.depth().iter().all(|d| *d == f64::INFINITY));
}

/// Glass, mirrors and matte spheres under the sky: every albedo in `[0, 1]`, every mean
/// normal at most of unit length, every depth positive.
#[test]
fn the_glass_scenes_features_are_in_range() {
    let scene = scenes::glass::<f64>().unwrap();
    let camera = ScreenCamera::new(32, 16).unwrap();
    let render = Renderer::new(&scene, &camera)
        .target_error(0.1)
        .max_spp(64)
        .aov(true)
        .render()
        .unwrap();
    let f = aov(&render);
    for (i, ((a, n), &d)) in f.albedo().iter().zip(f.normal()).zip(f.depth()).enumerate() {
        assert!(a.iter().all(|c| (0.0..=1.0).contains(c)), "pixel {i}: {a:?}");
        let length = n.iter().map(|c| c * c).sum::<f64>().sqrt();
        assert!(length <= 1.0 + 1e-12, "pixel {i}: {n:?}");
        assert!(d > 0.0, "pixel {i}: {d}");
    }
}

#[test]
fn the_layers_are_named_by_openexr_convention() {
    let scene = scenes::matte_spheres::<f64>().unwrap();
    let camera = ScreenCamera::new(8, 4).unwrap();
    let names = |render: Render| -> Vec<String> { render.layers().into_iter().map(|c| c.name).collect() };
    let uniform = Renderer::new(&scene, &camera).spp(2).aov(true).render().unwrap();
    assert_eq!(
        names(uniform),
        [
            "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z"
        ]
    );
    let adaptive = Renderer::new(&scene, &camera).target_error(0.1).render().unwrap();
    assert!(adaptive.aov.is_none());
    assert_eq!(names(adaptive), ["samples.Y", "error.Y"]);
    let plain = Renderer::new(&scene, &camera).spp(2).render().unwrap();
    assert!(plain.layers().is_empty());
}
