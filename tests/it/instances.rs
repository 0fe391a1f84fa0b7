//! Instancing: a mesh placed many times renders the bytes of the same scene with each
//! placement's triangles copied into a mesh of their own, in f32 and f64, on both
//! dispatch paths, through the scene's BVH and without it; and an instance is hit where
//! its copy is, ray by ray.

use raytrace::Acceleration;
use raytrace::mesh::load;
use raytrace::prelude::*;
use raytrace::shape::{Instance, Prototype};
use raytrace::transform::Affine;
use std::path::Path;
use std::sync::Arc;

/// The committed icosahedron as a prototype, and its vertices and triangles.
fn icosahedron() -> (Arc<Prototype>, Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/meshes/icosahedron.ply");
    let data = load(&path).unwrap();
    let vertices: Vec<[f64; 3]> = data.positions.iter().map(|p| [p.x, p.y, p.z]).collect();
    let prototype = Prototype::new(vertices.clone(), data.triangles.clone()).unwrap();
    (Arc::new(prototype), vertices, data.triangles)
}

/// Placements: turned about skew axes, scaled unevenly, moved around the view.
fn placements() -> Vec<Affine> {
    (0..12)
        .map(|k| {
            let k = f64::from(k);
            Affine::scale([0.3 + 0.05 * k, 0.35, 0.3 - 0.01 * k])
                .then(&Affine::rotate([1.0, k, 2.0], 17.0 * k))
                .then(&Affine::translate([
                    -2.2 + 0.4 * k,
                    -0.3 + 0.25 * (k * 1.3).sin(),
                    -3.5 - 0.2 * k,
                ]))
        })
        .collect()
}

/// The scene of instances, and the same scene with each placement copied into a mesh.
fn scenes<F: Float>(acceleration: Acceleration) -> (EnumScene<F>, EnumScene<F>) {
    let (prototype, vertices, triangles) = icosahedron();
    let mut instanced = EnumScene::new(Background::default());
    let mut copied = EnumScene::new(Background::default());
    for scene in [&mut instanced, &mut copied] {
        scene.set_acceleration(acceleration);
        let floor = Plane::new(Vec3::from_f64(0.0, -0.8, 0.0), Vec3::from_f64(0.0, 1.0, 0.0)).unwrap();
        scene.add(floor, Lambertian::new(Vec3::from_f64(0.5, 0.5, 0.55)).unwrap());
        scene.add_light(PointLight::new(Vec3::from_f64(1.0, 3.0, -1.0), Vec3::splat(lit(6.0))).unwrap());
    }
    for (k, placement) in placements().into_iter().enumerate() {
        let material: MaterialKind<F> = if k % 3 == 0 {
            Mirror::new(Vec3::from_f64(0.9, 0.8, 0.6)).unwrap().into()
        } else if k % 3 == 1 {
            Dielectric::new(lit(1.5)).unwrap().into()
        } else {
            Lambertian::new(Vec3::from_f64(0.7, 0.3, 0.2)).unwrap().into()
        };
        instanced.add(
            Instance::new(Arc::clone(&prototype), placement).unwrap(),
            material.clone(),
        );
        let placed = vertices
            .iter()
            .map(|&v| {
                let [x, y, z] = placement.point(v);
                Vec3::from_f64(x, y, z)
            })
            .collect();
        let mesh = Mesh::new(placed, triangles.clone()).unwrap();
        assert_eq!(
            mesh.skipped_degenerate(),
            0,
            "the identity needs no triangle dropped"
        );
        copied.add(mesh, material);
    }
    (instanced, copied)
}

fn same_bytes<F: Float>() {
    for acceleration in [Acceleration::Auto, Acceleration::Linear, Acceleration::Bvh] {
        let (instanced, copied) = scenes::<F>(acceleration);
        let camera = ScreenCamera::new(64, 32).unwrap();
        let render = |scene: &EnumScene<F>| {
            Renderer::new(scene, &camera)
                .spp(3)
                .max_depth(6)
                .seed(4)
                .render()
                .unwrap()
        };
        let (a, b) = (render(&instanced), render(&copied));
        assert_eq!(a.image, b.image, "{} {acceleration:?}", F::NAME);
        assert_eq!(a.stats.rays, b.stats.rays, "{} {acceleration:?}", F::NAME);
        let dyn_render = Renderer::new(&instanced.to_dyn(), &camera)
            .spp(3)
            .max_depth(6)
            .seed(4)
            .render()
            .unwrap();
        assert_eq!(
            dyn_render.image,
            a.image,
            "{} {acceleration:?}: the trait-object path",
            F::NAME
        );
    }
}

#[test]
fn instances_render_the_bytes_of_copies_f32() {
    same_bytes::<f32>();
}

#[test]
fn instances_render_the_bytes_of_copies_f64() {
    same_bytes::<f64>();
}

/// Ray by ray, grazing the triangles' edges included: the same hit, record for record.
#[test]
fn instances_are_hit_where_their_copies_are() {
    use rand::{RngExt, SeedableRng};
    let (instanced, copied) = scenes::<f32>(Acceleration::Bvh);
    let mut rng = raytrace::DefaultRng::seed_from_u64(5);
    let mut hits = 0;
    for _ in 0..20_000 {
        let from = Vec3::new(
            rng.random_range(-3.0..3.0),
            rng.random_range(-1.0..2.0),
            rng.random_range(0.0..1.0),
        );
        let to = Vec3::new(
            rng.random_range(-2.5..2.5),
            rng.random_range(-0.6..0.6),
            rng.random_range(-6.0..-3.0),
        );
        let Some(ray) = Ray::towards(from, to) else {
            continue;
        };
        let a = instanced.hit(&ray, f32::INFINITY).map(|(h, m)| (h, m.clone()));
        let b = copied.hit(&ray, f32::INFINITY).map(|(h, m)| (h, m.clone()));
        assert_eq!(a, b, "{ray:?}");
        hits += usize::from(a.is_some_and(|(h, _)| h.point.y > -0.79));
        for t_max in [1.0, 3.0, 5.0] {
            assert_eq!(
                instanced.occluded(&ray, t_max),
                copied.occluded(&ray, t_max),
                "{ray:?}"
            );
        }
    }
    assert!(hits > 2000, "rays should meet the instances ({hits})");
    // Rays at the placed vertices themselves, where several triangles tie: the first wins
    // on both sides.
    let (_, vertices, _) = icosahedron();
    let mut at_vertices = 0;
    for placement in placements() {
        for &v in &vertices {
            let [x, y, z] = placement.point(v);
            for from in [Vec3::new(0.0, 0.0, 0.0), Vec3::new(-1.0, 1.5, 0.5)] {
                let Some(ray) = Ray::towards(from, Vec3::new(x as f32, y as f32, z as f32)) else {
                    continue;
                };
                let a = instanced.hit(&ray, f32::INFINITY).map(|(h, m)| (h, m.clone()));
                assert_eq!(
                    a,
                    copied.hit(&ray, f32::INFINITY).map(|(h, m)| (h, m.clone())),
                    "{ray:?}"
                );
                at_vertices += usize::from(a.is_some());
            }
        }
    }
    assert!(at_vertices > 200, "{at_vertices}");
}
