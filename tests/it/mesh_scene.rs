//! A small mesh scene for the reference and value-stability tests: the committed
//! icosahedron (PLY) and tetrahedron (OBJ) of tests/data/meshes, each placed three times as
//! an indexed [`Mesh`], beside a sphere, on a floor plane. Its 73 bounded parts (72
//! triangles and the sphere) put it on the BVH, with triangle and sphere packets.

use raytrace::mesh::load;
use raytrace::prelude::*;
use std::path::Path;

/// The committed mesh `name`, scaled by `scale` and moved to `at`, as a [`Mesh`] in `F`.
fn placed<F: Float>(name: &str, scale: f64, at: [f64; 3]) -> Mesh<F> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/meshes")
        .join(name);
    let data = load(&path).unwrap();
    let vertices = data
        .positions
        .iter()
        .map(|p| Vec3::from_f64(p.x * scale + at[0], p.y * scale + at[1], p.z * scale + at[2]))
        .collect();
    Mesh::new(vertices, data.triangles).unwrap()
}

/// The scene, on the enum path; `to_dyn` gives the trait-object path.
pub fn meshes<F: Float>() -> EnumScene<F> {
    let mut scene = EnumScene::new(Background::default());
    let floor = Plane::new(Vec3::from_f64(0.0, -0.8, 0.0), Vec3::from_f64(0.0, 1.0, 0.0)).unwrap();
    scene.add(floor, Lambertian::new(Vec3::from_f64(0.5, 0.5, 0.55)).unwrap());
    let mirror = || Mirror::new(Vec3::from_f64(0.9, 0.8, 0.6)).unwrap();
    let matte = || Lambertian::new(Vec3::from_f64(0.7, 0.3, 0.2)).unwrap();
    // The icosahedron's circumradius is 1.90, the tetrahedron's 1.73: both rest near the floor.
    for (k, x) in [-2.4, 0.0, 2.4].into_iter().enumerate() {
        let ico = placed::<F>("icosahedron.ply", 0.4, [x, -0.04, -4.5]);
        let tet = placed::<F>("tetrahedron.obj", 0.35, [x + 1.2, -0.2, -3.6]);
        if k % 2 == 0 {
            scene.add(ico, mirror()).add(tet, matte());
        } else {
            scene
                .add(ico, Dielectric::new(lit(1.5)).unwrap())
                .add(tet, mirror());
        }
    }
    scene.add(
        Sphere::new(Vec3::from_f64(-1.2, -0.4, -3.2), lit(0.4)).unwrap(),
        matte(),
    );
    scene
}
