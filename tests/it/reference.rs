//! The fast renderer gives the reference renderer's bytes: every example scene (the
//! `custom_shape` example's user shape and material among them), a scene of meshes on the
//! BVH, and scenes lit by emitting surfaces (the Cornell box, and spheres, a triangle and
//! a plane giving off light beside a point light, mirror and glass, also on a BVH with a
//! second point light), in f32 and f64, through
//! both dispatch paths, at 1, 2 and 3 samples per pixel, on 1 and 2 threads, with emitters
//! sampled or not, whole and in tiles. The reference renderer calls the spec's recursive
//! `trace` once per sample, so this is the test that the batched, parallel renderer renders
//! the spec.

use crate::mesh_scene;
use crate::parts;
use crate::scenes;
use crate::textured_scene;

use raytrace::prelude::*;
use raytrace::{DefaultRng, Image};

/// Each example's scene in scalar `F`, with a small camera of its own kind.
type Built<F> = (EnumScene<F>, Box<dyn Camera<F> + Sync>);

fn examples<F: Float>() -> Vec<(&'static str, Built<F>)> {
    let spec = |scene: raytrace::Result<EnumScene<F>>| -> Built<F> {
        (scene.unwrap(), Box::new(ScreenCamera::new(36, 18).unwrap()))
    };
    vec![
        ("four_mirrors", spec(scenes::four_mirrors())),
        ("matte_spheres", spec(scenes::matte_spheres())),
        ("glass", spec(scenes::glass())),
        ("plane_and_triangles", spec(scenes::plane_and_triangles())),
        ("point_lights", spec(scenes::point_lights())),
        (
            "random_spheres",
            (
                scenes::random_spheres(0).unwrap(),
                Box::new(scenes::random_spheres_camera(32).unwrap()),
            ),
        ),
        (
            "meshes",
            (mesh_scene::meshes(), Box::new(ScreenCamera::new(36, 18).unwrap())),
        ),
    ]
}

/// The scenes lit by emitting surfaces, small: the Cornell box from its scene file, and
/// spheres, a triangle and a plane giving off light; the latter again on a BVH with a
/// second point light, where the fast renderer traces the shadow rays of the point lights
/// and of the light sample of many paths together and adds their light afterwards.
fn emissive<F: Float>() -> Vec<(&'static str, Built<F>)> {
    let (cornell, camera, _) = scenes::cornell_box::<F>(20).unwrap();
    let mut lit_tree = scenes::area_lights::<F>().unwrap();
    let v = |x, y, z| Vec3::<F>::from_f64(x, y, z);
    lit_tree.add_light(PointLight::new(v(-2.0, 2.5, -1.5), v(2.0, 3.0, 1.0)).unwrap());
    lit_tree.set_acceleration(raytrace::Acceleration::Bvh);
    assert!(lit_tree.uses_bvh());
    vec![
        ("cornell_box", (cornell, Box::new(camera))),
        ("area_lights", spec_camera(scenes::area_lights())),
        (
            "area_lights on a BVH, two point lights",
            spec_camera(Ok(lit_tree)),
        ),
    ]
}

fn spec_camera<F: Float>(scene: raytrace::Result<EnumScene<F>>) -> Built<F> {
    (scene.unwrap(), Box::new(ScreenCamera::new(36, 18).unwrap()))
}

fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

/// The index of the first pixel whose bits differ, if any.
fn first_difference(a: &Image, b: &Image) -> Option<usize> {
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    a.pixels()
        .iter()
        .zip(b.pixels())
        .position(|(p, q)| p.map(f64::to_bits) != q.map(f64::to_bits))
}

/// The fast render of `scene` equals the reference render bit for bit, with the same ray
/// count, on 1 and 2 threads.
fn check<F: Float, S, M>(name: &str, scene: &Scene<F, S, M>, camera: &(dyn Camera<F> + Sync), spp: u32)
where
    S: Layout<F> + Sync,
    M: Scatter<F, DefaultRng> + Sync,
{
    check_with(name, scene, camera, spp, LightSampling::Mis);
}

/// [`check`] with emitters' light found by `light_sampling`.
fn check_with<F: Float, S, M>(
    name: &str,
    scene: &Scene<F, S, M>,
    camera: &(dyn Camera<F> + Sync),
    spp: u32,
    light_sampling: LightSampling,
) where
    S: Layout<F> + Sync,
    M: Scatter<F, DefaultRng> + Sync,
{
    let renderer = Renderer::new(scene, &camera)
        .spp(spp)
        .max_depth(12)
        .seed(7)
        .light_sampling(light_sampling);
    let reference = renderer.render_reference().unwrap();
    for threads in [1, 2] {
        let fast = in_pool(threads, || renderer.render().unwrap());
        let at = first_difference(&fast.image, &reference.image);
        assert_eq!(
            at,
            None,
            "{name}, {}, {spp} spp, {threads} threads, {light_sampling:?}",
            F::NAME
        );
        assert_eq!(
            fast.stats.rays,
            reference.stats.rays,
            "{name}, {}, {spp} spp",
            F::NAME
        );
    }
}

fn every_example<F: Float>() {
    for (name, (scene, camera)) in examples::<F>() {
        for spp in [1, 2, 3] {
            check(name, &scene, &*camera, spp);
            check(name, &scene.to_dyn(), &*camera, spp);
        }
    }
    // The user's own shape and material, through the user's enums and through trait objects.
    let camera = ScreenCamera::new(36, 18).unwrap();
    for spp in [1, 2, 3] {
        check("custom_shape", &parts::enum_scene::<F>().unwrap(), &camera, spp);
        check("custom_shape", &parts::dyn_scene::<F>().unwrap(), &camera, spp);
    }
}

/// The mesh scene is what it is meant to test: triangles of indexed meshes in a BVH.
#[test]
fn the_mesh_scene_puts_mesh_triangles_on_the_bvh() {
    let scene = mesh_scene::meshes::<f32>();
    let triangles: u32 = scene
        .objects()
        .iter()
        .filter_map(|o| match &o.shape {
            ShapeKind::Mesh(m) => Some(m.parts()),
            _ => None,
        })
        .sum();
    assert_eq!(triangles, 3 * 20 + 3 * 4);
    assert!(scene.uses_bvh());
    assert!(scene.to_dyn().uses_bvh());
}

#[test]
fn the_fast_renderer_gives_the_references_bytes_in_f32() {
    every_example::<f32>();
}

#[test]
fn the_fast_renderer_gives_the_references_bytes_in_f64() {
    every_example::<f64>();
}

fn every_emissive_scene<F: Float>() {
    for (name, (scene, camera)) in emissive::<F>() {
        assert!(!scene.emitters().is_empty(), "{name} samples emitters");
        for spp in [1, 2, 3] {
            check(name, &scene, &*camera, spp);
            check(name, &scene.to_dyn(), &*camera, spp);
        }
        check_with(name, &scene, &*camera, 2, LightSampling::Bsdf);
        check_with(name, &scene.to_dyn(), &*camera, 2, LightSampling::Bsdf);
    }
}

#[test]
fn the_fast_renderer_gives_the_references_bytes_with_emitters_in_f32() {
    every_emissive_scene::<f32>();
}

#[test]
fn the_fast_renderer_gives_the_references_bytes_with_emitters_in_f64() {
    every_emissive_scene::<f64>();
}

/// A tile of the fast render is the same pixels of the reference's whole image.
#[test]
fn tiles_are_the_references_pixels() {
    let (scene, camera) = examples::<f32>().swap_remove(1).1;
    let camera = &*camera;
    let whole = Renderer::new(&scene, &camera)
        .spp(3)
        .seed(2)
        .render_reference()
        .unwrap();
    for tile in [
        Rect {
            x: 0,
            y: 0,
            width: 36,
            height: 1,
        },
        Rect {
            x: 7,
            y: 5,
            width: 11,
            height: 9,
        },
        Rect {
            x: 35,
            y: 17,
            width: 1,
            height: 1,
        },
    ] {
        let part = Renderer::new(&scene, &camera)
            .spp(3)
            .seed(2)
            .tile(tile)
            .render()
            .unwrap();
        for y in 0..tile.height {
            for x in 0..tile.width {
                let (a, b) = (part.image.pixel(x, y), whole.image.pixel(tile.x + x, tile.y + y));
                assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "{tile:?} at ({x}, {y})");
            }
        }
    }
}

/// The check above can fail: a render with another seed, or one bounce fewer, differs
/// from the reference somewhere.
#[test]
fn the_comparison_sees_a_different_image() {
    let (scene, camera) = examples::<f64>().swap_remove(1).1;
    let camera = &*camera;
    let reference = Renderer::new(&scene, &camera)
        .spp(2)
        .seed(7)
        .max_depth(3)
        .render_reference()
        .unwrap();
    let other_seed = Renderer::new(&scene, &camera).spp(2).seed(8).render().unwrap();
    assert!(first_difference(&other_seed.image, &reference.image).is_some());
    let shallower = Renderer::new(&scene, &camera)
        .spp(2)
        .seed(7)
        .max_depth(2)
        .render()
        .unwrap();
    assert!(first_difference(&shallower.image, &reference.image).is_some());
}

/// With emitters, the comparison sees the other way of finding their light.
#[test]
fn the_comparison_sees_light_found_another_way() {
    let (scene, camera) = emissive::<f32>().swap_remove(0).1;
    let camera = &*camera;
    let renderer = Renderer::new(&scene, &camera).spp(2).seed(7);
    let mis = renderer.render_reference().unwrap();
    let bsdf = Renderer::new(&scene, &camera)
        .spp(2)
        .seed(7)
        .light_sampling(LightSampling::Bsdf)
        .render()
        .unwrap();
    assert!(first_difference(&bsdf.image, &mis.image).is_some());
}

/// The textured scene (every texture kind, a normal map, a mesh with texture coordinates and
/// vertex normals): the fast renderer gives the reference's bytes on both dispatch paths.
fn textured<F: Float>() {
    let scene = textured_scene::textured::<F>();
    let camera = ScreenCamera::new(36, 18).unwrap();
    for spp in [1, 3] {
        check("textured", &scene, &camera, spp);
        check("textured (dyn)", &scene.to_dyn(), &camera, spp);
    }
}

#[test]
fn the_textured_scene_renders_as_the_reference() {
    textured::<f32>();
    textured::<f64>();
}
