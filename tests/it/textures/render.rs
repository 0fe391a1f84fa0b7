//! Textured renders: the same bytes through both dispatch paths, a flat normal map the same
//! image as none, and no light through a closed surface whatever its shading normals say.

use crate::textured_scene;
use rand::{RngExt, SeedableRng};
use raytrace::material::{BsdfSample, Emission, Eval, Lobes, NormalMap};
use raytrace::prelude::*;
use raytrace::shape::Hit;
use raytrace::texture::{Bitmap, ImageTexture, Texture};
use raytrace::{DefaultRng, Image};
use std::path::Path;
use std::sync::Arc;

fn bits(image: &Image) -> Vec<[u64; 3]> {
    image.pixels().iter().map(|p| p.map(f64::to_bits)).collect()
}

fn textured_paths_agree<F: Float>() {
    let scene = textured_scene::textured::<F>();
    let camera = ScreenCamera::new(32, 16).unwrap();
    let by_enum = Renderer::new(&scene, &camera)
        .spp(2)
        .max_depth(6)
        .seed(3)
        .render()
        .unwrap();
    let dyn_scene = scene.to_dyn();
    let by_trait = Renderer::new(&dyn_scene, &camera)
        .spp(2)
        .max_depth(6)
        .seed(3)
        .render()
        .unwrap();
    assert_eq!(bits(&by_enum.image), bits(&by_trait.image), "{}", F::NAME);
    assert_eq!(by_enum.stats.rays, by_trait.stats.rays);
    // The textures show: the image is not the one of plain colours.
    let mut plain = EnumScene::new(scene.background().clone());
    for o in scene.objects() {
        plain.add(o.shape.clone(), Lambertian::new(Vec3::splat(lit(0.5))).unwrap());
    }
    let flat = Renderer::new(&plain, &camera)
        .spp(2)
        .max_depth(6)
        .seed(3)
        .render()
        .unwrap();
    assert_ne!(bits(&by_enum.image), bits(&flat.image));
}

#[test]
fn checkerboard_and_image_textures_render_alike_through_both_paths() {
    textured_paths_agree::<f32>();
    textured_paths_agree::<f64>();
}

/// A sphere, a mesh with vertex normals, a plane and a triangle, of matte and mirror
/// materials each wrapped by `wrap`, lit by the sky and a point light.
fn shapes<F: Float>(wrap: &dyn Fn(MaterialKind<F>) -> MaterialKind<F>) -> EnumScene<F> {
    let c = Vec3::from_f64;
    let mut scene = EnumScene::new(Background::default());
    let matte = |r, g, b| wrap(Lambertian::new(c(r, g, b)).unwrap().into());
    scene.add(
        Plane::new(c(0.0, -0.8, 0.0), c(0.0, 1.0, 0.0)).unwrap(),
        matte(0.5, 0.5, 0.5),
    );
    scene.add(
        Sphere::new(c(-0.9, 0.0, -3.0), lit(0.7)).unwrap(),
        matte(0.8, 0.3, 0.2),
    );
    scene.add(
        Sphere::new(c(0.9, 0.0, -3.0), lit(0.6)).unwrap(),
        wrap(Mirror::new(c(0.9, 0.9, 0.8)).unwrap().into()),
    );
    let v = vec![c(-0.5, -0.7, -4.0), c(0.5, -0.7, -4.0), c(0.0, 0.6, -4.3)];
    let normals = vec![c(-0.5, 0.0, 1.0), c(0.5, 0.0, 1.0), c(0.0, 0.5, 1.0)];
    let mesh = Mesh::new(v, vec![[0, 1, 2]])
        .unwrap()
        .with_normals(normals)
        .unwrap();
    scene.add(mesh, matte(0.3, 0.7, 0.4));
    scene.add_light(PointLight::new(c(2.0, 3.0, 0.0), c(5.0, 5.0, 5.0)).unwrap());
    scene
}

fn render<F: Float>(scene: &EnumScene<F>) -> Image {
    let camera = ScreenCamera::new(32, 16).unwrap();
    Renderer::new(scene, &camera)
        .spp(3)
        .max_depth(6)
        .seed(11)
        .render()
        .unwrap()
        .image
}

fn a_flat_map_changes_nothing<F: Float>() {
    let none = render(&shapes::<F>(&|m| m));
    // (½, ½, 1) exactly: a constant, and an image of those values (a float image holds
    // them; an 8-bit one cannot, 128/255 ≠ ½).
    let flat_image = Arc::new(Bitmap::from_rgb(2, 2, vec![[0.5, 0.5, 1.0]; 4]).unwrap());
    let maps: [Texture<F>; 2] = [
        Texture::constant(Vec3::from_f64(0.5, 0.5, 1.0)),
        ImageTexture::new(flat_image).into(),
    ];
    for map in maps {
        let wrapped = render(&shapes::<F>(&|m| NormalMap::new(map.clone(), m).into()));
        assert_eq!(bits(&wrapped), bits(&none), "{}, {map:?}", F::NAME);
    }
    // A map that leans the normals changes the image: the comparison can fail.
    let leaning = Texture::constant(Vec3::from_f64(0.7, 0.5, 0.9));
    let bumped = render(&shapes::<F>(&|m| NormalMap::new(leaning.clone(), m).into()));
    assert_ne!(bits(&bumped), bits(&none));
}

#[test]
fn a_flat_normal_map_is_no_normal_map() {
    a_flat_map_changes_nothing::<f32>();
    a_flat_map_changes_nothing::<f64>();
}

/// The committed icosahedron around the origin, each vertex given a normal drawn at random
/// from the whole sphere (seeded): shading normals that have nothing to do with the
/// surface. `open` leaves out its first triangle.
fn wild_icosahedron(open: bool) -> Mesh<f64> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/meshes/icosahedron.ply");
    let data = raytrace::mesh::load(&path).unwrap();
    let n = data.positions.len() as f64;
    let centre = data.positions.iter().fold(Vec3::zero(), |s, p| s + *p) / n;
    let vertices = data.positions.iter().map(|p| *p - centre).collect();
    let triangles = data.triangles[usize::from(open)..].to_vec();
    let mut rng = DefaultRng::seed_from_u64(9);
    let normals = (0..data.positions.len())
        .map(|_| {
            let (z, phi): (f64, f64) = (
                rng.random_range(-1.0..1.0),
                rng.random_range(0.0..std::f64::consts::TAU),
            );
            let s = (1.0 - z * z).sqrt();
            Vec3::new(s * phi.cos(), s * phi.sin(), z)
        })
        .collect();
    Mesh::new(vertices, triangles)
        .unwrap()
        .with_normals(normals)
        .unwrap()
}

/// What a camera at the centre of `mesh` (of `material`) sees, the scene lit only from
/// outside: the bright default sky, a point light and a glowing sphere.
fn seen_from_inside(mesh: Mesh<f64>, material: MaterialKind<f64>) -> Image {
    let c = Vec3::new;
    let mut scene = EnumScene::new(Background::default());
    scene.add(mesh, material);
    scene.add(
        Sphere::new(c(4.0, 1.0, -3.0), 1.0).unwrap(),
        Emissive::new(Vec3::splat(20.0)).unwrap(),
    );
    scene.add_light(PointLight::new(c(-3.0, 4.0, 2.0), Vec3::splat(50.0)).unwrap());
    let camera = LookAtCamera::new(
        c(0.0, 0.0, 0.0),
        c(0.3, 0.1, -1.0),
        c(0.0, 1.0, 0.0),
        100.0,
        32,
        16,
    )
    .unwrap();
    Renderer::new(&scene, &camera)
        .spp(6)
        .max_depth(10)
        .seed(5)
        .render()
        .unwrap()
        .image
}

fn lit_pixels(image: &Image) -> usize {
    image.pixels().iter().filter(|p| **p != [0.0; 3]).count()
}

/// A bumpy map, leaning normals up to about 80°, as a raw image would hold it.
fn wild_map() -> Texture<f64> {
    let mut rng = DefaultRng::seed_from_u64(4);
    let pixels = (0..64)
        .map(|_| {
            [
                rng.random_range(0.0..1.0f32),
                rng.random_range(0.0..1.0f32),
                rng.random_range(0.55..1.0f32),
            ]
        })
        .collect();
    ImageTexture::new(Arc::new(Bitmap::from_rgb(8, 8, pixels).unwrap())).into()
}

/// The planted mistake: a normal map that perturbs the shading normal but says the two
/// normals agree (`smooth = false`), so nothing checks a direction against the geometry.
struct UncheckedNormalMap(NormalMap<f64>);

impl UncheckedNormalMap {
    fn hit(&self, hit: &Hit<f64>) -> Hit<f64> {
        Hit {
            smooth: false,
            ..self.0.perturbed(hit)
        }
    }
}

impl Material<f64> for UncheckedNormalMap {
    fn lobes(&self) -> Lobes {
        self.0.lobes()
    }
    fn reads_coordinates(&self) -> bool {
        true
    }
    fn eval(&self, hit: &Hit<f64>, wo: Vec3<f64>, wi: Vec3<f64>) -> Option<Eval<f64>> {
        self.0.material().eval(&self.hit(hit), wo, wi)
    }
    fn pdf(&self, hit: &Hit<f64>, wo: Vec3<f64>, wi: Vec3<f64>) -> f64 {
        self.0.material().pdf(&self.hit(hit), wo, wi)
    }
    fn emits(&self) -> Option<Emission<f64>> {
        None
    }
}

impl<R: rand::Rng + ?Sized> Scatter<f64, R> for UncheckedNormalMap {
    fn sample(&self, hit: &Hit<f64>, wo: Vec3<f64>, rng: &mut R) -> Option<BsdfSample<f64>> {
        self.0.material().sample(&self.hit(hit), wo, rng)
    }
}

#[test]
fn no_light_leaks_into_a_closed_mesh_whatever_its_normals() {
    let matte: MaterialKind<f64> = Lambertian::new(Vec3::splat(0.8)).unwrap().into();
    // Wild vertex normals, and a wild normal map over them.
    let closed = seen_from_inside(wild_icosahedron(false), matte.clone());
    assert_eq!(lit_pixels(&closed), 0, "vertex normals let light in");
    let mapped = NormalMap::new(wild_map(), matte.clone());
    let closed = seen_from_inside(wild_icosahedron(false), mapped.clone().into());
    assert_eq!(lit_pixels(&closed), 0, "a normal map lets light in");
    // The detector works: through a missing face the light comes in.
    let open = seen_from_inside(wild_icosahedron(true), matte);
    assert!(lit_pixels(&open) > 0);
    // And it catches the leak a normal map that checks nothing makes.
    let mut scene = EnumScene::<f64>::new(Background::default()).to_dyn();
    scene.add(
        Box::new(wild_icosahedron(false)),
        Arc::new(UncheckedNormalMap(mapped)),
    );
    scene.add_light(PointLight::new(Vec3::new(-3.0, 4.0, 2.0), Vec3::splat(50.0)).unwrap());
    let camera = LookAtCamera::new(
        Vec3::zero(),
        Vec3::new(0.3, 0.1, -1.0),
        Vec3::new(0.0, 1.0, 0.0),
        100.0,
        32,
        16,
    )
    .unwrap();
    let leaky = Renderer::new(&scene, &camera)
        .spp(6)
        .max_depth(10)
        .seed(5)
        .render()
        .unwrap()
        .image;
    assert!(lit_pixels(&leaky) > 0, "the unchecked normal map leaks");
}
