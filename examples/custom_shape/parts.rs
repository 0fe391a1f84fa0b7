//! The user's side of `custom_shape`: a shape ([`Disk`]) and a material ([`Checker`]) the
//! library does not have, the two enums that put them beside the library's on the enum
//! path, and the scene built on both dispatch paths. `tests/it/custom_shape.rs` includes this
//! file too.

use raytrace::aabb::Aabb;
use raytrace::prelude::*;
use raytrace::rand::Rng;
use raytrace::sampling::lambertian_direction;
use raytrace::scene::Primitive;
use raytrace::shape::flat_hit_error;
use raytrace::{DefaultRng, Hit, Intersection, Scatter};
use std::sync::Arc;

/// A flat round disk: the points of the plane through `center` with unit normal `n` that
/// lie within `radius` of the centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk<F> {
    /// The supporting plane: it stores the centre and the unit normal, and computes `t`.
    plane: Plane<F>,
    radius: F,
}

impl<F: Float> Disk<F> {
    /// A disk; `normal` may have any non-zero length, `radius` must be finite and `> 0`.
    pub fn new(center: Vec3<F>, normal: Vec3<F>, radius: F) -> raytrace::Result<Self> {
        if !(radius > F::zero() && radius.is_finite()) {
            return Err(Error::invalid(
                "disk radius",
                format!("must be finite and > 0, got {radius}"),
            ));
        }
        let plane = Plane::new(center, normal)?;
        Ok(Self { plane, radius })
    }
}

impl<F: Float> Hittable<F> for Disk<F> {
    // Phase one, run for every disk a ray might meet: where, and nothing more.
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        // The plane's t = ((C − O)·n)/(D·n), with its conservative t > 0 test: a ray spawned
        // from this disk must not find it again through a wrongly rounded sign.
        let t = self.plane.intersect(ray, t_max)?;
        // Inside the disk: |P − C|² ≤ r².
        let inside = (ray.at(t) - self.plane.point()).length_squared() <= self.radius * self.radius;
        inside.then(|| Intersection::at(t))
    }

    // Phase two, run once, for the nearest hit only: the record.
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        let point = ray.at(hit.t);
        // The box around `point` that holds the true plane, so spawned rays start past it.
        let error = flat_hit_error(ray, hit.t, self.plane.point());
        Hit::new(hit.t, point, error, self.plane.normal(), ray.direction)
    }

    /// Along axis `i` a disk reaches `r·√(1 − nᵢ²) = r·√(nⱼ² + nₖ²)` from its centre (the
    /// second form does not cancel), widened by a few roundings (`γ(8)`, with room).
    fn bounds(&self) -> Option<Aabb<F>> {
        let (c, n, r) = (self.plane.point(), self.plane.normal(), self.radius);
        let reach = Vec3::new(n.y.hypot(n.z), n.x.hypot(n.z), n.x.hypot(n.y)) * r;
        let pad = reach + (c.abs() + reach) * F::gamma(8);
        Some(Aabb::new(c - pad, c + pad))
    }
}

/// A matte surface in a checkerboard: the albedo alternates between `even` and `odd` in
/// squares of side `size` on the hit point's `x` and `z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checker<F> {
    even: Color<F>,
    odd: Color<F>,
    size: F,
}

impl<F: Float> Checker<F> {
    /// A checkerboard; each channel of both colours in `[0, 1]`, `size` finite and `> 0`.
    pub fn new(even: Color<F>, odd: Color<F>, size: F) -> raytrace::Result<Self> {
        let albedo = |c: Color<F>| c.min_element() >= F::zero() && c.max_element() <= F::one();
        if !(albedo(even) && albedo(odd) && size > F::zero() && size.is_finite()) {
            let reason = format!("colours {even:?}, {odd:?} must lie in [0, 1], size {size} must be > 0");
            return Err(Error::invalid("checker", reason));
        }
        Ok(Self { even, odd, size })
    }
}

impl<F: Float, R: Rng + ?Sized> Material<F, R> for Checker<F> {
    fn scatter(&self, _ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>> {
        // The square (⌊x/s⌋, ⌊z/s⌋) is even when the sum of its indices is.
        let p = hit.point;
        let k = (p.x / self.size).floor() + (p.z / self.size).floor();
        let albedo = if k % lit(2.0) == F::zero() {
            self.even
        } else {
            self.odd
        };
        Some(Scatter {
            attenuation: albedo,
            direction: lambertian_direction(hit.normal, rng),
        })
    }
    // `diffuse_albedo` stays `None`: it is asked without a hit point, so it cannot pick a
    // square's colour; point lights then reach this surface only through its bounces.
}

/// Every shape of the enum path: the library's and the user's.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape<F> {
    /// A sphere, plane, triangle or mesh.
    Library(ShapeKind<F>),
    /// The user's disk.
    Disk(Disk<F>),
}

impl<F: Float> Hittable<F> for Shape<F> {
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        match self {
            Self::Library(s) => s.intersect(ray, t_max),
            Self::Disk(d) => d.intersect(ray, t_max),
        }
    }
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        match self {
            Self::Library(s) => s.finish(ray, hit),
            Self::Disk(d) => d.finish(ray, hit),
        }
    }
    fn bounds(&self) -> Option<Aabb<F>> {
        match self {
            Self::Library(s) => s.bounds(),
            Self::Disk(d) => d.bounds(),
        }
    }
    // A mesh is made of parts, which the scene indexes one by one.
    fn parts(&self) -> u32 {
        match self {
            Self::Library(s) => s.parts(),
            Self::Disk(d) => d.parts(),
        }
    }
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        match self {
            Self::Library(s) => s.part_bounds(part),
            Self::Disk(d) => d.part_bounds(part),
        }
    }
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        match self {
            Self::Library(s) => s.intersect_part(part, ray, t_max),
            Self::Disk(d) => d.intersect_part(part, ray, t_max),
        }
    }
}

// Passing the library's shapes on keeps their fast path: spheres and triangles tested four
// at a time. The disk keeps the default: tested on its own, through `intersect_part`.
impl<F: Float> Layout<F> for Shape<F> {
    fn primitive(&self, part: u32) -> Primitive<F> {
        match self {
            Self::Library(s) => s.primitive(part),
            Self::Disk(_) => Primitive::Other,
        }
    }
}

impl<F> From<ShapeKind<F>> for Shape<F> {
    fn from(s: ShapeKind<F>) -> Self {
        Self::Library(s)
    }
}

impl<F> From<Disk<F>> for Shape<F> {
    fn from(d: Disk<F>) -> Self {
        Self::Disk(d)
    }
}

/// Every material of the enum path: the library's and the user's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface<F> {
    /// A mirror, matte or glass surface.
    Library(MaterialKind<F>),
    /// The user's checkerboard.
    Checker(Checker<F>),
}

impl<F: Float, R: Rng + ?Sized> Material<F, R> for Surface<F> {
    fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>> {
        match self {
            Self::Library(m) => m.scatter(ray, hit, rng),
            Self::Checker(c) => c.scatter(ray, hit, rng),
        }
    }
    // No `R` among the arguments, so the calls name the trait's `R`.
    fn diffuse_albedo(&self) -> Option<Color<F>> {
        match self {
            Self::Library(m) => Material::<F, R>::diffuse_albedo(m),
            Self::Checker(c) => Material::<F, R>::diffuse_albedo(c),
        }
    }
}

impl<F> From<MaterialKind<F>> for Surface<F> {
    fn from(m: MaterialKind<F>) -> Self {
        Self::Library(m)
    }
}

impl<F> From<Checker<F>> for Surface<F> {
    fn from(c: Checker<F>) -> Self {
        Self::Checker(c)
    }
}

/// A scene on the enum path with the user's shapes and materials.
pub type UserScene<F> = Scene<F, Shape<F>, Surface<F>>;

/// The floor: a disk of radius 3 at `y = −0.8`, facing up.
fn floor<F: Float>() -> raytrace::Result<Disk<F>> {
    Disk::new(
        Vec3::from_f64(0.0, -0.8, -4.0),
        Vec3::from_f64(0.0, 1.0, 0.0),
        lit(3.0),
    )
}

/// Cream and slate squares half a unit wide.
fn checker<F: Float>() -> raytrace::Result<Checker<F>> {
    Checker::new(
        Vec3::from_f64(0.85, 0.82, 0.75),
        Vec3::from_f64(0.2, 0.27, 0.4),
        lit(0.5),
    )
}

/// A ball of radius 0.8 resting on the floor at `x`.
fn ball<F: Float>(x: f64) -> raytrace::Result<Sphere<F>> {
    Sphere::new(Vec3::from_f64(x, 0.0, -4.0), lit(0.8))
}

fn mirror<F: Float>() -> raytrace::Result<Mirror<F>> {
    Mirror::new(Vec3::from_f64(0.9, 0.9, 0.9))
}

fn glass<F: Float>() -> raytrace::Result<Dielectric<F>> {
    Dielectric::new(lit(1.5))
}

/// The scene on the trait-object path: every shape boxed, every material shared.
pub fn dyn_scene<F: Float>() -> raytrace::Result<DynScene<F, DefaultRng>> {
    let mut scene = DynScene::new(Background::default());
    scene.add(Box::new(floor()?), Arc::new(checker()?));
    scene.add(Box::new(ball(-1.0)?), Arc::new(mirror()?));
    scene.add(Box::new(ball(1.0)?), Arc::new(glass()?));
    Ok(scene)
}

/// The same scene on the enum path.
pub fn enum_scene<F: Float>() -> raytrace::Result<UserScene<F>> {
    let mut scene = UserScene::new(Background::default());
    scene.add(floor()?, checker()?);
    scene.add(ShapeKind::from(ball(-1.0)?), MaterialKind::from(mirror()?));
    scene.add(ShapeKind::from(ball(1.0)?), MaterialKind::from(glass()?));
    Ok(scene)
}
