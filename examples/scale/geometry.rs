//! The benchmark's scenes as plain geometry in `f32`: a cloud of random spheres or a placed
//! triangle mesh. The same values build the library's scene and are exported for the Embree
//! program, so both trace exactly the same primitives.

use raytrace::mesh;
use raytrace::prelude::*;
use raytrace::rand::SeedableRng;
use raytrace::sampling::{DefaultRng, uniform, uniform_sphere};
use raytrace::scene_file::Placement;
use raytrace::{Acceleration, EnumScene};
use std::path::Path;

/// The box the sphere centres are drawn in, in front of the camera: `x ∈ [−4, 4]`,
/// `y ∈ [−2, 2]`, `z ∈ [−12, −4]`.
pub const BOX_LOW: [f64; 3] = [-4.0, -2.0, -12.0];
/// The far corner of [`BOX_LOW`]'s box.
pub const BOX_HIGH: [f64; 3] = [4.0, 2.0, -4.0];

/// The dragon's placement, the same for every resolution: 22 times its file size, turned
/// 20° about y, its middle moved to about `(0, 0, −3)` (the file's dragon stands in
/// `x ∈ [−0.11, 0.10]`, `y ∈ [0.05, 0.20]`, `z ∈ [−0.05, 0.04]`).
pub const DRAGON_SCALE: f64 = 22.0;
/// See [`DRAGON_SCALE`].
pub const DRAGON_ROTATE_DEGREES: [f64; 3] = [0.0, -20.0, 0.0];
/// See [`DRAGON_SCALE`].
pub const DRAGON_TRANSLATE: [f64; 3] = [0.094, -2.741, -2.86];

/// The primitives of one benchmark scene, every value already rounded to `f32`.
#[derive(Clone, Debug, PartialEq)]
pub enum Geometry {
    /// Spheres as `[x, y, z, radius]`.
    Spheres(Vec<[f32; 4]>),
    /// An indexed triangle mesh; every triangle has area in `f32`.
    Mesh {
        /// Vertex positions.
        vertices: Vec<[f32; 3]>,
        /// Triangles as indices into `vertices`.
        triangles: Vec<[u32; 3]>,
    },
}

impl Geometry {
    /// `n` spheres with centres uniform in the box ([`BOX_LOW`] to [`BOX_HIGH`]) and radius
    /// `r = 2·n^(−1/3)`: half the spacing `n^(−1/3)·4` a cloud of `n` would have in a cube of
    /// the box's smallest side, so the cloud's optical depth grows as `0.39·n^(1/3)` (about
    /// 1.8 at 100 spheres, 39 at a million). Drawn from `seed` with the library's generator.
    pub fn spheres(n: usize, seed: u64) -> Self {
        let mut rng = DefaultRng::seed_from_u64(seed);
        let radius = 2.0 * (n as f64).powf(-1.0 / 3.0);
        let mut coordinate = |axis: usize| {
            let (low, high) = (BOX_LOW[axis], BOX_HIGH[axis]);
            (low + (high - low) * uniform(&mut rng)) as f32
        };
        let spheres = (0..n)
            .map(|_| {
                let [x, y, z] = [0, 1, 2].map(&mut coordinate);
                [x, y, z, radius as f32]
            })
            .collect();
        Self::Spheres(spheres)
    }

    /// `n` needles: long thin triangles (length 2) with centres uniform in the spheres' box and directions uniform on the sphere, the case
    /// spatial splits are for (a diagonal needle's box is almost all empty). Each is the
    /// triangle `c ± d` and `c + w·p`, `d` its half-axis of length 1, `p ⊥ d` a unit vector,
    /// `w = 4·n^(−1/3)·0.05`. Drawn from `seed` with the library's generator.
    pub fn needles(n: usize, seed: u64) -> Self {
        let mut rng = DefaultRng::seed_from_u64(seed);
        let width = 0.2 * (n as f64).powf(-1.0 / 3.0);
        let mut vertices = Vec::with_capacity(3 * n);
        for _ in 0..n {
            let c: [f64; 3] = [0, 1, 2].map(|a| BOX_LOW[a] + (BOX_HIGH[a] - BOX_LOW[a]) * uniform(&mut rng));
            let c = Vec3::new(c[0], c[1], c[2]);
            let mut unit = || {
                let [x, y, z] = uniform_sphere([uniform(&mut rng), uniform(&mut rng)]);
                Vec3::new(x, y, z)
            };
            let d = unit();
            let p = d.cross(unit()).normalize();
            for v in [c - d, c + d, c + p * width] {
                vertices.push([v.x as f32, v.y as f32, v.z as f32]);
            }
        }
        let triangles = (0..n as u32).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
        Self::Mesh { vertices, triangles }
    }

    /// The mesh at `path` placed by [`DRAGON_SCALE`], [`DRAGON_ROTATE_DEGREES`] and
    /// [`DRAGON_TRANSLATE`] (in `f64`, then rounded to `f32`). Triangles the rounding
    /// flattens are left out, so both programs see only triangles with area.
    ///
    /// # Errors
    /// The mesh cannot be loaded.
    pub fn placed_mesh(path: &Path) -> raytrace::Result<Self> {
        let data = mesh::load(path)?;
        let placement = Placement::new([DRAGON_SCALE; 3], DRAGON_ROTATE_DEGREES, DRAGON_TRANSLATE);
        let vertices: Vec<[f32; 3]> = data
            .positions
            .iter()
            .map(|&p| placement.apply(p).to_f64().map(|c| c as f32))
            .collect();
        let corner = |i: u32| {
            let [x, y, z] = vertices[i as usize];
            Vec3::new(x, y, z)
        };
        let triangles = data
            .triangles
            .into_iter()
            .filter(|t| Triangle::new(corner(t[0]), corner(t[1]), corner(t[2])).is_ok())
            .collect();
        Ok(Self::Mesh { vertices, triangles })
    }

    /// Spheres or triangles.
    pub fn primitives(&self) -> usize {
        match self {
            Self::Spheres(s) => s.len(),
            Self::Mesh { triangles, .. } => triangles.len(),
        }
    }

    /// The library's scene of these primitives in scalar `F`: every surface Lambertian with
    /// albedo 0.5, the default sky, no lights, always through the BVH.
    ///
    /// # Errors
    /// A primitive the scalar cannot hold (never for `f32` or `f64`).
    pub fn scene<F: Float>(&self) -> raytrace::Result<EnumScene<F>> {
        let mut scene = EnumScene::<F>::new(Background::default());
        scene.set_acceleration(Acceleration::Bvh);
        // One material in the scene's table, shared by every object.
        let matte = scene.add_material(Lambertian::new(Vec3::splat(lit::<F>(0.5)))?);
        let v = |[x, y, z]: [f32; 3]| Vec3::from_f64(x.into(), y.into(), z.into());
        match self {
            Self::Spheres(spheres) => {
                for &[x, y, z, r] in spheres {
                    scene.add_object(Sphere::new(v([x, y, z]), lit(r.into()))?, matte);
                }
            }
            Self::Mesh { vertices, triangles } => {
                let vertices = vertices.iter().map(|&p| v(p)).collect();
                scene.add_object(Mesh::new(vertices, triangles.clone())?, matte);
            }
        }
        Ok(scene)
    }
}
