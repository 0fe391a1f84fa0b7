//! Random valid scenes: their descriptions, the strategies that draw them, and their construction in `F`.

use crate::common::{self, unit_f64};
use proptest::prelude::*;
use raytrace::Acceleration;
use raytrace::material::Reflectance;
use raytrace::prelude::*;

#[derive(Clone, Debug)]
pub(crate) enum ShapeDesc {
    Sphere { c: [f64; 3], r: f64 },
    Plane { p: [f64; 3], n: [f64; 3] },
    Triangle([[f64; 3]; 3]),
}

#[derive(Clone, Debug)]
pub(crate) enum MaterialDesc {
    Mirror([f64; 3]),
    Matte([f64; 3]),
    Glass {
        index: f64,
        albedo: [f64; 3],
        fresnel: bool,
    },
}

#[derive(Clone, Debug)]
pub(crate) enum CameraDesc {
    Screen(usize),
    LookAt {
        from: [f64; 3],
        at: [f64; 3],
        up: [f64; 3],
        vfov: f64,
    },
}

#[derive(Clone, Debug)]
pub(crate) struct SceneDesc {
    pub(crate) objects: Vec<(ShapeDesc, MaterialDesc)>,
    pub(crate) lights: Vec<([f64; 3], [f64; 3])>,
    /// `(horizon, zenith)`; the same colour twice for a solid background.
    pub(crate) background: ([f64; 3], [f64; 3], bool),
    pub(crate) acceleration: Acceleration,
    pub(crate) camera: CameraDesc,
    pub(crate) spp: u32,
    pub(crate) max_depth: u32,
    pub(crate) seed: u64,
}

pub(crate) fn v<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

pub(crate) fn position() -> impl Strategy<Value = [f64; 3]> {
    [-6.0f64..6.0, -6.0f64..6.0, -14.0f64..4.0]
}

pub(crate) fn pow10(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|e| 10f64.powf(e))
}

pub(crate) fn shape() -> impl Strategy<Value = ShapeDesc> {
    // A sphere through a point q near the camera, its centre r away along u. Four times in
    // five u points away from the world origin (q·u ≥ 0), which keeps the spec camera's
    // eye outside even the largest spheres (they act as walls and floors); otherwise a big
    // sphere may enclose the eye.
    let sphere = (position(), unit_f64(), pow10(-4.0, 4.0), 0u8..5).prop_map(|(q, u, r, k)| {
        let outward = if k > 0 && common::dot(q, u) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let c = std::array::from_fn(|i| q[i] + outward * r * u[i]);
        ShapeDesc::Sphere { c, r }
    });
    let normal = prop_oneof![
        Just([0.0, 1.0, 0.0]),
        Just([0.0, 0.0, 1.0]),
        Just([-1.0, 0.0, 0.0]),
        unit_f64(),
    ];
    let plane = (position(), normal).prop_map(|(p, n)| ShapeDesc::Plane { p, n });
    // Two edges of length s and k·s at an angle θ ∈ [0.3, π − 0.3]: never degenerate, in
    // f32 either (the positions' rounding is below 10⁻⁶, the edges at least 10⁻⁴).
    let triangle = (
        position(),
        unit_f64(),
        unit_f64(),
        pow10(-4.0, 2.0),
        0.3f64..3.0,
        0.3f64..(std::f64::consts::PI - 0.3),
    )
        .prop_map(|(a, u, w, s, k, theta)| {
            let u = common::normalize(u);
            let perp = common::normalize(common::cross(u, w));
            let perp = if perp.iter().all(|c| c.is_finite()) {
                perp
            } else {
                common::frame(u).0
            };
            let b: [f64; 3] = std::array::from_fn(|i| a[i] + s * u[i]);
            let c: [f64; 3] =
                std::array::from_fn(|i| a[i] + k * s * (theta.cos() * u[i] + theta.sin() * perp[i]));
            ShapeDesc::Triangle([a, b, c])
        });
    prop_oneof![4 => sphere, 1 => plane, 2 => triangle]
}

/// An albedo channel: exactly 0, exactly 1, or uniform in `[0, 1]`.
pub(crate) fn channel() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 1 => Just(1.0), 3 => 0.0f64..=1.0]
}

pub(crate) fn albedo() -> impl Strategy<Value = [f64; 3]> {
    [channel(), channel(), channel()]
}

pub(crate) fn material() -> impl Strategy<Value = MaterialDesc> {
    let index = prop_oneof![1 => Just(1.0), 3 => 1.0f64..3.0, 1 => 0.3f64..1.0];
    prop_oneof![
        albedo().prop_map(MaterialDesc::Mirror),
        albedo().prop_map(MaterialDesc::Matte),
        (index, albedo(), any::<bool>()).prop_map(|(index, albedo, fresnel)| MaterialDesc::Glass {
            index,
            albedo,
            fresnel
        }),
    ]
}

/// A light's position: anywhere, or exactly on the surface of one of the objects.
pub(crate) fn light(
    objects: &[(ShapeDesc, MaterialDesc)],
) -> impl Strategy<Value = ([f64; 3], [f64; 3])> + use<> {
    let on_surface: Vec<[f64; 3]> = objects
        .iter()
        .map(|(s, _)| match s {
            ShapeDesc::Sphere { c, r } => [c[0], c[1] + r, c[2]],
            ShapeDesc::Plane { p, .. } => *p,
            ShapeDesc::Triangle(v) => v[0],
        })
        .collect();
    let intensity = [0.0f64..100.0, 0.0f64..100.0, 0.0f64..100.0];
    let intensity = prop_oneof![1 => Just([0.0; 3]), 4 => intensity];
    (
        prop_oneof![2 => position(), 1 => prop::sample::select(on_surface)],
        intensity,
    )
}

pub(crate) fn camera() -> impl Strategy<Value = CameraDesc> {
    let look_at = (position(), position(), unit_f64(), 10.0f64..170.0)
        .prop_map(|(from, at, up, vfov)| CameraDesc::LookAt { from, at, up, vfov });
    prop_oneof![
        prop::sample::select(vec![8usize, 16]).prop_map(CameraDesc::Screen),
        look_at
    ]
}

/// A valid scene; `lit` says whether it may have point lights, and `max_background` bounds
/// the background's channels.
pub(crate) fn scene(lit: bool, max_background: f64) -> impl Strategy<Value = SceneDesc> {
    // Channels often exactly at the maximum (a white sky is where the energy bound is tight).
    let channel = move || prop_oneof![1 => Just(max_background), 2 => 0.0..=max_background];
    let colour = move || [channel(), channel(), channel()];
    let objects = prop::collection::vec((shape(), material()), 1..13);
    let acceleration =
        prop::sample::select(vec![Acceleration::Auto, Acceleration::Linear, Acceleration::Bvh]);
    (
        objects,
        (colour(), colour(), any::<bool>()),
        acceleration,
        camera(),
        (1u32..5, 0u32..13, any::<u64>()),
    )
        .prop_flat_map(
            move |(objects, background, acceleration, camera, (spp, max_depth, seed))| {
                let n_lights = if lit { 0..4 } else { 0..1 };
                let lights = prop::collection::vec(light(&objects), n_lights);
                (lights, Just(objects)).prop_map(move |(lights, objects)| SceneDesc {
                    objects,
                    lights,
                    background,
                    acceleration,
                    camera: camera.clone(),
                    spp,
                    max_depth,
                    seed,
                })
            },
        )
}

/// The scene in `F`. Every value is valid by construction, so a constructor error fails
/// the test.
pub(crate) fn build<F: Float>(d: &SceneDesc) -> EnumScene<F> {
    let (horizon, zenith, solid) = d.background;
    let background = if solid {
        Background::solid(v(horizon))
    } else {
        Background::sky(v(horizon), v(zenith))
    };
    let mut scene = EnumScene::<F>::new(background.unwrap());
    scene.set_acceleration(d.acceleration);
    for (s, m) in &d.objects {
        let shape: ShapeKind<F> = match s {
            ShapeDesc::Sphere { c, r } => Sphere::new(v(*c), lit(*r)).unwrap().into(),
            ShapeDesc::Plane { p, n } => Plane::new(v(*p), v(*n)).unwrap().into(),
            ShapeDesc::Triangle([a, b, c]) => Triangle::new(v(*a), v(*b), v(*c))
                .unwrap_or_else(|e| panic!("{}: {e}", F::NAME))
                .into(),
        };
        let material: MaterialKind<F> = match m {
            MaterialDesc::Mirror(a) => Mirror::new(v(*a)).unwrap().into(),
            MaterialDesc::Matte(a) => Lambertian::new(v(*a)).unwrap().into(),
            MaterialDesc::Glass {
                index,
                albedo,
                fresnel,
            } => {
                let glass = Dielectric::new(lit(*index))
                    .unwrap()
                    .with_albedo(v(*albedo))
                    .unwrap();
                let mode = if *fresnel {
                    Reflectance::Fresnel
                } else {
                    Reflectance::Schlick
                };
                glass.with_reflectance(mode).into()
            }
        };
        scene.add(shape, material);
    }
    for (p, i) in &d.lights {
        scene.add_light(PointLight::new(v(*p), v(*i)).unwrap());
    }
    scene
}
