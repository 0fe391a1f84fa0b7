//! The user's side of `custom_shape`: a shape ([`Disk`], a round disk of the user's own,
//! simpler than the library's `raytrace::shape::Disk`) and a material ([`Checker`]) the
//! library does not have, the two enums that put them beside the library's on the enum
//! path, and the scene built on both dispatch paths. `tests/it/custom_shape.rs` includes this
//! file too.

use raytrace::aabb::Aabb;
use raytrace::prelude::*;
use raytrace::rand::Rng;
use raytrace::sampling::{cosine_pdf, lambertian_direction};
use raytrace::scene::Primitive;
use raytrace::shape::{Coordinates, SurfaceSample, flat_surface};
use raytrace::{BsdfSample, BsdfVisitor, Emission, Eval, Hit, Intersection, Lobes};
use std::f64::consts::PI;
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
        let t = self.plane.crossing(ray, t_max)?;
        // Inside the disk: |P − C|² ≤ r².
        let inside = (ray.at(t) - self.plane.point()).length_squared() <= self.radius * self.radius;
        inside.then(|| Intersection::at(t))
    }

    // Phase two, run once, for the nearest hit only: the record, with the box around the
    // point that holds the true plane, so spawned rays start past it.
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        let surface = flat_surface(ray, hit.t, self.plane.point(), self.plane.normal());
        Hit::new(surface, ray.direction)
    }

    // Phase three, only for a material that reads them: the plane's surface coordinates.
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        self.plane.coordinates(ray, hit, record)
    }

    /// Along axis `i` a disk reaches `r·√(1 − nᵢ²) = r·√(nⱼ² + nₖ²)` from its centre (the
    /// second form does not cancel), widened by a few roundings (`γ(8)`, with room).
    fn bounds(&self) -> Option<Aabb<F>> {
        let (c, n, r) = (self.plane.point(), self.plane.normal(), self.radius);
        let reach = Vec3::new(n.y.hypot(n.z), n.x.hypot(n.z), n.x.hypot(n.y)) * r;
        let pad = reach + (c.abs() + reach) * F::gamma(8);
        Some(Aabb::new(c - pad, c + pad))
    }

    // One part: the disk itself.
    fn parts(&self) -> u32 {
        1
    }
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        self.bounds()
    }
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }

    // Not sampled as a light: an emissive disk is found only by the rays that hit it.
    fn area(&self) -> Option<F> {
        None
    }
    fn sample(&self, _: Vec3<F>, _: [f64; 3]) -> Option<SurfaceSample<F>> {
        None
    }
    fn pdf(&self, _: &Ray<F>, _: &Hit<F>) -> F {
        F::zero()
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

impl<F: Float> Checker<F> {
    /// The albedo of the square `(⌊x/s⌋, ⌊z/s⌋)` the point lies in: even when the sum of
    /// its indices is.
    fn albedo(&self, p: Vec3<F>) -> Color<F> {
        let k = (p.x / self.size).floor() + (p.z / self.size).floor();
        if k % lit(2.0) == F::zero() {
            self.even
        } else {
            self.odd
        }
    }
}

// What the renderer asks of a material: its lobes, its BSDF times the cosine, the density
// it samples with, and whether it emits. Here a Lambertian whose albedo depends on the
// point: `(A(p)/π, cos θ)`, density `cos θ/π`.
impl<F: Float> Material<F> for Checker<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DIFFUSE
    }
    // It reads the point, not the surface coordinates.
    fn reads_coordinates(&self) -> bool {
        false
    }
    fn eval(&self, hit: &Hit<F>, _wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let cos = hit.shading_normal.dot(wi);
        (cos > F::zero()).then(|| Eval {
            colour: self.albedo(hit.point) * (F::one() / lit::<F>(PI)),
            scale: cos,
        })
    }
    fn pdf(&self, hit: &Hit<F>, _wo: Vec3<F>, wi: Vec3<F>) -> F {
        cosine_pdf(hit.shading_normal, wi)
    }
    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

// The part that draws random numbers: the spec's tangent-sphere direction, weighted by
// the square's albedo (`f·cos θ/pdf = A(p)`).
impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Checker<F> {
    fn sample(&self, hit: &Hit<F>, _wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let direction = lambertian_direction(hit.shading_normal, rng);
        Some(BsdfSample {
            direction,
            weight: self.albedo(hit.point),
            pdf: cosine_pdf(hit.shading_normal, direction),
            lobe: Lobes::REFLECTION | Lobes::DIFFUSE,
        })
    }
}

/// Every shape of the enum path: the library's and the user's.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape<F> {
    /// A sphere, plane, triangle or mesh.
    Library(ShapeKind<F>),
    /// The user's disk.
    Disk(Disk<F>),
}

/// `match` on a [`Shape`], the same call on every variant: every method passes every
/// variant on, and the trait has no defaults, so a method left out does not compile.
macro_rules! each_shape {
    ($shape:expr, $s:ident => $call:expr) => {
        match $shape {
            Shape::Library($s) => $call,
            Shape::Disk($s) => $call,
        }
    };
}

impl<F: Float> Hittable<F> for Shape<F> {
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        each_shape!(self, s => s.intersect(ray, t_max))
    }
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        each_shape!(self, s => s.finish(ray, hit))
    }
    fn coordinates(&self, ray: &Ray<F>, hit: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        each_shape!(self, s => s.coordinates(ray, hit, record))
    }
    fn bounds(&self) -> Option<Aabb<F>> {
        each_shape!(self, s => s.bounds())
    }
    // A mesh is made of parts, which the scene indexes one by one.
    fn parts(&self) -> u32 {
        each_shape!(self, s => s.parts())
    }
    fn part_bounds(&self, part: u32) -> Option<Aabb<F>> {
        each_shape!(self, s => s.part_bounds(part))
    }
    fn intersect_part(&self, part: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        each_shape!(self, s => s.intersect_part(part, ray, t_max))
    }
    // An emissive library sphere stays a light the renderer samples.
    fn area(&self) -> Option<F> {
        each_shape!(self, s => s.area())
    }
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        each_shape!(self, s => s.sample(from, u))
    }
    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        each_shape!(self, s => s.pdf(ray, hit))
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
#[derive(Clone, Debug, PartialEq)]
pub enum UserMaterial<F> {
    /// A mirror, matte, glass or emissive surface.
    Library(MaterialKind<F>),
    /// The user's checkerboard.
    Checker(Checker<F>),
}

/// `match` on a [`UserMaterial`], the same call on every variant.
macro_rules! each_material {
    ($material:expr, $m:ident => $call:expr) => {
        match $material {
            UserMaterial::Library($m) => $call,
            UserMaterial::Checker($m) => $call,
        }
    };
}

impl<F: Float> Material<F> for UserMaterial<F> {
    fn lobes(&self) -> Lobes {
        each_material!(self, m => m.lobes())
    }
    fn reads_coordinates(&self) -> bool {
        each_material!(self, m => m.reads_coordinates())
    }
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        each_material!(self, m => m.eval(hit, wo, wi))
    }
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        each_material!(self, m => m.pdf(hit, wo, wi))
    }
    // An emissive library material stays an emitter.
    fn emits(&self) -> Option<Emission<F>> {
        each_material!(self, m => m.emits())
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for UserMaterial<F> {
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        each_material!(self, m => m.sample(hit, wo, rng))
    }
    // One `match` a hit: the renderer then asks the material found, not the enum. (Left
    // out, the default hands the enum itself, and every question matches again.)
    fn resolve<V: BsdfVisitor<F, R>>(&self, hit: &Hit<F>, visitor: V) -> V::Output {
        each_material!(self, m => m.resolve(hit, visitor))
    }
}

impl<F> From<MaterialKind<F>> for UserMaterial<F> {
    fn from(m: MaterialKind<F>) -> Self {
        Self::Library(m)
    }
}

impl<F> From<Checker<F>> for UserMaterial<F> {
    fn from(c: Checker<F>) -> Self {
        Self::Checker(c)
    }
}

/// A scene on the enum path with the user's shapes and materials.
pub type UserScene<F> = Scene<F, Shape<F>, UserMaterial<F>>;

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
pub fn dyn_scene<F: Float>() -> raytrace::Result<DynScene<F>> {
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
