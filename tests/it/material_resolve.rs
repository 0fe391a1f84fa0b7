//! `Scatter::resolve`: the material each kind hands the renderer at a hit answers every
//! question there bit for bit as the kind itself does. The renderer asks only the resolved
//! material, so this is what keeps its images those the questions define, for the
//! specification's materials (inline arms), a textured Lambertian (its albedo looked up
//! once) and every material behind an `Arc` (the `Shared` arm).

use raytrace::material::{BsdfSample, BsdfVisitor, Emission, Eval, Lobes, MaterialKind};
use raytrace::prelude::*;
use raytrace::rand::SeedableRng;
use raytrace::sampling::DefaultRng;
use raytrace::shape::{Coordinates, Hit, Surface};
use raytrace::texture::Checkerboard;

/// Everything a material answers at one hit for one pair of directions, and its sample
/// from a seeded generator.
// The fields are read through `Debug`, which the dead-code lint does not count.
#[allow(dead_code)]
#[derive(Debug)]
struct Answers {
    lobes: Lobes,
    emits: Option<Emission<f64>>,
    reads_coordinates: bool,
    eval: Option<Eval<f64>>,
    pdf: f64,
    sample: Option<BsdfSample<f64>>,
}

/// A question: the hit, `wo`, `wi` and the sample's seed.
#[derive(Clone, Copy)]
struct Question {
    hit: Hit<f64>,
    wo: Vec3<f64>,
    wi: Vec3<f64>,
    seed: u64,
}

fn ask<B: Scatter<f64, DefaultRng> + ?Sized>(material: &B, q: Question) -> Answers {
    let mut rng = DefaultRng::seed_from_u64(q.seed);
    Answers {
        lobes: material.lobes(),
        emits: material.emits(),
        reads_coordinates: material.reads_coordinates(),
        eval: material.eval(&q.hit, q.wo, q.wi),
        pdf: material.pdf(&q.hit, q.wo, q.wi),
        sample: material.sample(&q.hit, q.wo, &mut rng),
    }
}

/// The visitor: asks whatever material `resolve` hands it.
struct Ask(Question);

impl BsdfVisitor<f64, DefaultRng> for Ask {
    type Output = Answers;
    fn visit<B: Scatter<f64, DefaultRng> + ?Sized>(self, material: &B) -> Answers {
        ask(material, self.0)
    }
}

/// Every answer as text: `Debug` prints each number so that it reads back exactly, so
/// equal texts are equal bits (NaN included).
fn text(a: &Answers) -> String {
    format!("{a:?}")
}

/// Hits on a unit sphere at the origin seen from outside and from inside, at several
/// surface coordinates, with incoming and outgoing directions above, below and grazing.
fn questions() -> Vec<Question> {
    let mut out = Vec::new();
    let mut seed = 0;
    for (n, uv) in [
        (Vec3::new(0.0, 1.0, 0.0), [0.1, 0.2]),
        (Vec3::new(0.6, 0.0, 0.8), [0.7, 0.3]),
        (Vec3::new(-0.48, 0.6, 0.64), [0.45, 0.95]),
    ] {
        for inside in [false, true] {
            let ray_dir = if inside { n } else { -n };
            let tilted = (ray_dir + Vec3::new(0.3, -0.2, 0.1)).normalize();
            let surface = Surface::bare(1.0, n, n);
            let coordinates = Coordinates {
                uv,
                dpdu: Vec3::new(-n.y, n.x, 0.0) + Vec3::new(0.0, 0.0, 0.5),
            };
            let hit = Hit::new(surface, tilted).with(coordinates);
            let up = hit.normal;
            for wi in [
                (up + Vec3::new(0.2, 0.1, -0.3)).normalize(),
                (-up + Vec3::new(0.1, 0.2, 0.1)).normalize(),
                (up * 0.01 + Vec3::new(up.y - up.z, up.z - up.x, up.x - up.y)).normalize(),
            ] {
                seed += 1;
                out.push(Question {
                    hit,
                    wo: -tilted,
                    wi,
                    seed,
                });
            }
        }
    }
    out
}

/// The specification's materials, a textured Lambertian, a reflecting emitter, and every
/// material of the BSDF scene file (the ones behind an `Arc`).
fn materials() -> Vec<(String, MaterialKind<f64>)> {
    let colour = Vec3::new(0.8, 0.5, 0.2);
    let checker = Checkerboard::new(Vec3::new(0.9, 0.1, 0.1), Vec3::new(0.1, 0.1, 0.9)).unwrap();
    let mut all: Vec<(String, MaterialKind<f64>)> = vec![
        ("mirror".into(), Mirror::new(colour).unwrap().into()),
        ("lambertian".into(), Lambertian::new(colour).unwrap().into()),
        (
            "checker lambertian".into(),
            Lambertian::textured(checker).unwrap().into(),
        ),
        ("glass".into(), Dielectric::new(1.5).unwrap().into()),
        (
            "reflecting emitter".into(),
            Emissive::new(Vec3::new(2.0, 2.0, 2.0))
                .unwrap()
                .with_albedo(colour)
                .unwrap()
                .into(),
        ),
    ];
    let file =
        raytrace::scene_file::SceneFile::parse(crate::bsdf_scenes::SCENE, std::path::Path::new("bsdfs.toml"))
            .unwrap();
    let built = file.build::<f64>().unwrap();
    for (k, object) in built.scene.objects().iter().enumerate() {
        all.push((
            format!("scene file object {k}"),
            built.scene.material(object.material).clone(),
        ));
    }
    all
}

#[test]
fn every_kind_resolves_to_a_material_answering_as_it_does() {
    let questions = questions();
    let mut checked = 0;
    for (name, material) in materials() {
        for &q in &questions {
            let direct = ask(&material, q);
            let resolved = material.resolve(&q.hit, Ask(q));
            // A resolved material answers for this hit only; it need not read coordinates
            // again (a textured Lambertian's albedo is already looked up).
            let resolved = Answers {
                reads_coordinates: direct.reads_coordinates,
                ..resolved
            };
            assert_eq!(text(&resolved), text(&direct), "{name}");
            checked += 1;
        }
    }
    assert!(checked >= 14 * 18, "{checked} answers compared");
}

/// The comparison sees a wrong material: the checkerboard Lambertian's answers at two
/// hits of different colour differ, and so do a mirror's and a Lambertian's.
#[test]
fn the_comparison_sees_a_wrong_material() {
    let all = materials();
    let by_name = |n: &str| &all.iter().find(|(name, _)| name == n).unwrap().1;
    let q = questions();
    let checker = by_name("checker lambertian");
    let (a, b) = (ask(checker, q[0]), ask(checker, q[6]));
    assert_ne!(a.eval.map(|e| e.colour), b.eval.map(|e| e.colour));
    assert_ne!(
        text(&ask(by_name("mirror"), q[0])),
        text(&ask(by_name("lambertian"), q[0]))
    );
}
