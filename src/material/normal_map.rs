//! A tangent-space normal map over another material, Mitsuba 3's `normalmap`.

use super::{BsdfSample, Emission, Eval, Lobes, Material, MaterialKind, Scatter};
use crate::float::Float;
use crate::frame::Frame;
use crate::shape::Hit;
use crate::texture::Texture;
use crate::vec3::Vec3;
use rand::Rng;

/// Another material shaded with normals from a map: the wrapped material sees the hit with
/// its shading normal replaced by the map's, as Mitsuba 3's `normalmap` BSDF
/// (`src/bsdfs/normalmap.cpp`) perturbs the shading frame.
///
/// At a hit, the map's colour `c` (an RGB texture, its image read as data: `raw`) gives the
/// normal in the surface's shading frame,
///
/// `n_local = normalize(2·c − 1)`, `n = n_local.x·s + n_local.y·t + n_local.z·n_s`,
///
/// `(s, t, n_s)` the frame of the outward shading normal `n_s` and `∂p/∂u` (`s` along
/// `∂p/∂u` made perpendicular to `n_s`, `t = n_s × s`, [`Frame::new`]), the frame Mitsuba's
/// `sh_frame` is. So the map's blue channel leans the normal along `n_s`, red along the
/// direction `u` grows, green along `t`; a flat map `(½, ½, 1)` leaves the normal as it
/// was, bit for bit. The normal is a property of the surface, the same seen from either
/// side; like the hit's own normals it is then turned to the side the ray came from and,
/// as pbrt-v4 does (`FaceForward`), to the geometric normal's side.
///
/// Where the perturbed normal and the geometric one disagree about `wo` or `wi`, no light
/// goes through (see [`Material`]'s "Shading normals"): `eval` is `None`, `pdf` 0, and
/// `sample` absorbs the ray. Mitsuba's `normalmap` instead mirrors such a normal toward
/// the viewer (`flip_invalid_normals`) and multiplies in a shadowing term
/// (`use_shadowing_function`); a cross-check sets both to `false` and uses a map whose
/// normals lean less than the view and light directions do.
#[derive(Clone, Debug, PartialEq)]
pub struct NormalMap<F, M = MaterialKind<F>> {
    map: Texture<F>,
    material: M,
}

impl<F: Float, M> NormalMap<F, M> {
    /// `material` shaded with the normals of `map`.
    pub fn new(map: impl Into<Texture<F>>, material: M) -> Self {
        Self {
            map: map.into(),
            material,
        }
    }

    /// The map.
    pub fn map(&self) -> &Texture<F> {
        &self.map
    }

    /// The material it perturbs.
    pub fn material(&self) -> &M {
        &self.material
    }

    /// `hit` with its shading normal from the map (and `smooth` where that differs from
    /// the geometric normal, so that the two are checked against each other).
    #[inline]
    pub fn perturbed(&self, hit: &Hit<F>) -> Hit<F> {
        let outward = if hit.front_face {
            hit.shading_normal
        } else {
            -hit.shading_normal
        };
        let c = self.map.eval(hit);
        let (one, two) = (F::one(), F::one() + F::one());
        let local = Vec3::new(c.x * two - one, c.y * two - one, c.z * two - one);
        // Straight up, the normal stays as it is, bit for bit (the frame's sum would turn a
        // −0 component into +0); of zero length, the map says nothing.
        let up = local.x == F::zero() && local.y == F::zero() && local.z > F::zero();
        let Some(local) = local.try_normalize().filter(|_| !up) else {
            return *hit;
        };
        let n = Frame::new(outward, hit.dpdu).to_world(local);
        let n = if hit.front_face { n } else { -n };
        let n = if n.dot(hit.normal) < F::zero() { -n } else { n };
        Hit {
            shading_normal: n,
            smooth: hit.smooth || n != hit.normal,
            ..*hit
        }
    }
}

impl<F: Float, M: Material<F>> Material<F> for NormalMap<F, M> {
    #[inline]
    fn lobes(&self) -> Lobes {
        self.material.lobes()
    }

    /// Yes: the map is looked up at `uv`, in the frame of `∂p/∂u`.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        true
    }

    /// The wrapped material's, at the perturbed hit; `None` where the perturbed and the
    /// geometric normal disagree about `wo` or `wi`.
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let p = self.perturbed(hit);
        (p.sides_agree(wo) && p.sides_agree(wi))
            .then(|| self.material.eval(&p, wo, wi))
            .flatten()
    }

    /// The wrapped material's, at the perturbed hit; 0 where `eval` is `None` for the
    /// normals' disagreeing (`sample` never returns such a direction).
    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        let p = self.perturbed(hit);
        if p.sides_agree(wo) && p.sides_agree(wi) {
            self.material.pdf(&p, wo, wi)
        } else {
            F::zero()
        }
    }

    #[inline]
    fn emits(&self) -> Option<Emission<F>> {
        self.material.emits()
    }
}

impl<F: Float, R: Rng + ?Sized, M: Scatter<F, R>> Scatter<F, R> for NormalMap<F, M> {
    /// The wrapped material's sample at the perturbed hit; absorbed where the perturbed
    /// and the geometric normal disagree about `wo` or the drawn direction.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let p = self.perturbed(hit);
        if !p.sides_agree(wo) {
            return None;
        }
        self.material
            .sample(&p, wo, rng)
            .filter(|s| p.sides_agree(s.direction))
    }
}

impl<F: Float> NormalMap<F, MaterialKind<F>> {
    /// This material in scalar `G`, as [`MaterialKind::cast`].
    ///
    /// # Errors
    /// As the map's and the wrapped material's casts.
    pub fn cast<G: Float>(&self) -> crate::error::Result<NormalMap<G, MaterialKind<G>>> {
        Ok(NormalMap::new(self.map.cast::<G>()?, self.material.cast()?))
    }
}
