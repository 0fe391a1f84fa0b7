//! Packets of up to four parts of one kind, and the rule that keeps a ray's nearest hit.

use super::super::Object;
use crate::float::Float;
use crate::lanes::{F4, LANES};
use crate::ray::Ray;
use crate::scene::layout::Layout;
use crate::shape::{Hittable, Intersection, Sphere, Sphere4, Triangle4};
use crate::vec3::Vec3;

mod pack;
pub(super) use pack::{Packer, kind};

/// A part of an object: `(object, part)`, both numbered as the scene holds them.
pub(super) type Key = (u32, u32);

/// The object of no part: an empty lane.
pub(super) const NONE: u32 = u32::MAX;

/// What a ray's nearest hit so far needs besides its `t` for the record: which part, and
/// where on it. Nothing is found while the nearest `t` is still the query's bound (`∞` in
/// a batch): the one "no hit" encoding, so a `Found` is read only once a part was offered.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Found<F> {
    pub(super) key: Key,
    /// What the shape's intersection called the part, for [`Hittable::finish`]: the key's
    /// part, but for a shape that finds its own parts (an instance's triangle).
    pub(super) part: u32,
    pub(super) coords: [F; 3],
    /// Where the part's lanes are: `4k + lane` in leaf packet `k`, or [`NONE`] (a packet of
    /// the loop, or a part tested alone). A triangle's record is made from its packet's
    /// vertices, which the ray has just read, not from its mesh's, which it has not.
    pub(super) lane: u32,
}

impl<F: Float> Found<F> {
    /// No part yet.
    pub(super) fn none() -> Self {
        Self {
            key: (NONE, 0),
            part: 0,
            coords: [F::zero(); 3],
            lane: NONE,
        }
    }

    /// The intersection at `t` this describes, for [`Hittable::finish`].
    pub(super) fn intersection(&self, t: F) -> Intersection<F> {
        Intersection {
            t,
            part: self.part,
            coords: self.coords,
        }
    }

    /// Offers part `key`'s intersection at `t` to the ray's nearest `(nearest, self)`: it
    /// takes its place if it is nearer, or as near and of a part that comes first (the
    /// objects in the order added, a shape's parts in order). Whatever order the parts are
    /// offered in, the nearest ends the same: the answer of a loop over all the parts.
    #[inline(always)]
    pub(super) fn offer(&mut self, nearest: &mut F, t: F, key: Key, coords: impl FnOnce() -> [F; 3]) {
        self.offer_part(nearest, t, key, key.1, NONE, coords);
    }

    /// [`Found::offer`] of an intersection whose shape names the part `part` itself, from
    /// the lanes at `lane` ([`Found::lane`]).
    #[inline(always)]
    pub(super) fn offer_part(
        &mut self,
        nearest: &mut F,
        t: F,
        key: Key,
        part: u32,
        lane: u32,
        coords: impl FnOnce() -> [F; 3],
    ) {
        if t < *nearest || (t == *nearest && key < self.key) {
            *nearest = t;
            *self = Self {
                key,
                part,
                coords: coords(),
                lane,
            };
        }
    }
}

/// [`Packet::first_lane`] of leaf packet `k` (no leaf count reaches `2³⁰`).
fn first_lane(k: usize) -> u32 {
    (k * LANES) as u32
}

/// Up to four parts of one kind, tested together; lanes hold parts in [`Key`] order and
/// unused lanes the key `(NONE, 0)`. A view into [`Packets`].
#[derive(Clone, Copy, Debug)]
pub(super) struct Packet<'a, F> {
    lanes: Lanes<'a, F>,
    keys: &'a [Key; LANES],
    /// `4k` for leaf packet `k`, [`NONE`] for a packet of the loop ([`Found::lane`]).
    first_lane: u32,
}

/// A packet's parts, as they are tested.
#[derive(Clone, Copy, Debug)]
enum Lanes<'a, F> {
    /// Spheres, in SIMD lanes.
    Spheres(&'a Sphere4<F>),
    /// A lone sphere, tested alone: cheaper than lanes left empty.
    Sphere(&'a Sphere<F>),
    /// Triangles, in SIMD lanes.
    Triangles(&'a Triangle4<F>),
    /// Other parts, each through its shape's [`Hittable::intersect_part`].
    Others,
}

/// Lanes of one kind with their parts.
#[derive(Clone, Copy, Debug)]
struct Keyed<T> {
    lanes: T,
    keys: [Key; LANES],
}

/// A packet of spheres.
#[derive(Clone, Copy, Debug)]
enum Spheres<F> {
    /// Up to four, in SIMD lanes.
    Four(Sphere4<F>),
    /// A lone sphere, tested alone: cheaper than lanes left empty.
    One(Sphere<F>),
}

/// Packets numbered in the order made, each kind in an array of its own, so that a packet
/// of spheres (64 bytes of lanes in f32) takes no more room than it needs, where one array
/// of packets would give each the room of four triangles' (144). The kinds come in order
/// (every packet of spheres before any of triangles, those before the others'), as a BVH
/// numbers its leaves ([`Bvh::build_classes`](crate::bvh::Bvh::build_classes)), so packet
/// `k`'s kind and place follow from `k` and the arrays' lengths, with no table to read.
#[derive(Clone, Debug, Default)]
pub(super) struct Packets<F> {
    spheres: Vec<Keyed<Spheres<F>>>,
    triangles: Vec<Keyed<Triangle4<F>>>,
    others: Vec<[Key; LANES]>,
}

/// The bytes of a packet of spheres and of one of triangles, lanes and keys.
#[cfg(test)]
pub(super) fn packet_bytes<F>() -> [usize; 2] {
    [size_of::<Keyed<Spheres<F>>>(), size_of::<Keyed<Triangle4<F>>>()]
}

impl<F: Float> Packets<F> {
    /// How many packets there are.
    pub(super) fn len(&self) -> usize {
        self.spheres.len() + self.triangles.len() + self.others.len()
    }

    /// Packet `k`.
    #[inline(always)]
    pub(super) fn get(&self, k: usize) -> Packet<'_, F> {
        if let Some(p) = self.spheres.get(k) {
            let lanes = match &p.lanes {
                Spheres::Four(s) => Lanes::Spheres(s),
                Spheres::One(s) => Lanes::Sphere(s),
            };
            return Packet {
                lanes,
                keys: &p.keys,
                first_lane: first_lane(k),
            };
        }
        let first = first_lane(k);
        let k = k - self.spheres.len();
        if let Some(p) = self.triangles.get(k) {
            return Packet {
                lanes: Lanes::Triangles(&p.lanes),
                keys: &p.keys,
                first_lane: first,
            };
        }
        Packet {
            lanes: Lanes::Others,
            keys: &self.others[k - self.triangles.len()],
            first_lane: first,
        }
    }

    /// The vertices of the triangle at `lane` ([`Found::lane`]), if a packet of
    /// triangles holds it.
    #[inline(always)]
    pub(super) fn triangle(&self, lane: u32) -> Option<[Vec3<F>; 3]> {
        let k = (lane / LANES as u32) as usize;
        let p = self.triangles.get(k.wrapping_sub(self.spheres.len()))?;
        Some(p.lanes.vertices(lane as usize % LANES))
    }

    /// Every packet, in order.
    pub(super) fn iter(&self) -> impl Iterator<Item = Packet<'_, F>> {
        (0..self.len()).map(|k| self.get(k))
    }
}

impl<F: Float> Packet<'_, F> {
    /// Offers each lane's intersection with each ray `rays[r]`, for `r` in `which`, to that
    /// ray's nearest `(nearest[r], found[r])`. A lane is asked with no bound, so the
    /// answer cannot depend on the order packets are visited in.
    #[inline(always)]
    pub(super) fn offer<S: Layout<F>, M>(
        &self,
        objects: &[Object<S, M>],
        rays: &[Ray<F>],
        which: impl IntoIterator<Item = usize>,
        nearest: &mut [F],
        found: &mut [Found<F>],
    ) {
        // All cut to one length: one bounds check serves the three.
        let (rays, found) = (&rays[..nearest.len()], &mut found[..nearest.len()]);
        // The kind is matched once for all the rays.
        match self.lanes {
            Lanes::Spheres(s) => {
                for r in which {
                    let t = s.hits(&rays[r]);
                    // Not `first_lane`: a sphere's record is its object's.
                    self.offer_lanes(t, NONE, |_| [F::zero(); 3], &mut nearest[r], &mut found[r]);
                }
            }
            Lanes::Sphere(s) => {
                for r in which {
                    if let Some(i) = s.intersect(&rays[r], F::infinity()) {
                        found[r].offer(&mut nearest[r], i.t, self.keys[0], || i.coords);
                    }
                }
            }
            Lanes::Triangles(tri) => {
                for r in which {
                    let hits = tri.hits_within(&rays[r], nearest[r]);
                    let (first, coords) = (self.first_lane, |lane| hits.coords(lane));
                    self.offer_lanes(hits.t, first, coords, &mut nearest[r], &mut found[r]);
                }
            }
            Lanes::Others => {
                for r in which {
                    for &(object, part) in self.keys.iter().take_while(|k| k.0 != NONE) {
                        let shape = &objects[object as usize].shape;
                        if let Some(i) = shape.intersect_part(part, &rays[r], F::infinity()) {
                            found[r]
                                .offer_part(&mut nearest[r], i.t, (object, part), i.part, NONE, || i.coords);
                        }
                    }
                }
            }
        }
    }

    /// Offers the nearest lane of `t` (`+∞` for a miss), found at `first + lane` (or
    /// [`NONE`]: [`Found::lane`]); of equally near lanes the first, whose part comes first.
    #[inline(always)]
    fn offer_lanes(
        &self,
        t: F4<F>,
        first: u32,
        coords: impl Fn(usize) -> [F; 3],
        nearest: &mut F,
        found: &mut Found<F>,
    ) {
        let min = t.min_lane();
        // Most packets hold nothing nearer: one comparison before a lane is looked up.
        if min < F::infinity() && min <= *nearest {
            let lane = t.mask_eq(min).trailing_zeros() as usize;
            let key = self.keys[lane];
            let at = first.saturating_add(lane as u32);
            found.offer_part(nearest, min, key, key.1, at, || coords(lane));
        }
    }

    /// The lanes' parts.
    #[cfg(test)]
    pub(super) fn keys(&self) -> &[Key; LANES] {
        self.keys
    }

    /// Whether a lane's part blocks `ray` in `(0, t_max)`.
    #[inline(always)]
    pub(super) fn any<S: Layout<F>, M>(&self, objects: &[Object<S, M>], ray: &Ray<F>, t_max: F) -> bool {
        match self.lanes {
            Lanes::Spheres(s) => s.any(ray, t_max),
            Lanes::Sphere(s) => s.intersect(ray, F::infinity()).is_some_and(|i| i.t < t_max),
            Lanes::Triangles(t) => t.any(ray, t_max),
            // Asked with no bound too, as the lanes are: the same answer on both paths.
            Lanes::Others => self
                .keys
                .iter()
                .take_while(|k| k.0 != NONE)
                .any(|&(object, part)| {
                    let shape = &objects[object as usize].shape;
                    shape
                        .intersect_part(part, ray, F::infinity())
                        .is_some_and(|i| i.t < t_max)
                }),
        }
    }
}

/// A packet of a scene's loop, its lanes inline: the loop's packets are few and every ray
/// tests them all, so they sit in one array in order, where a BVH's leaves, many and visited
/// one by one, are [`Packets`] stored by kind.
#[derive(Clone, Copy, Debug)]
pub(super) struct Looped<F> {
    lanes: Inline<F>,
    keys: [Key; LANES],
}

/// [`Lanes`] held inline.
#[derive(Clone, Copy, Debug)]
enum Inline<F> {
    Spheres(Spheres<F>),
    Triangles(Triangle4<F>),
    Others,
}

impl<F: Float> Looped<F> {
    /// `packet` held inline.
    pub(super) fn new(packet: Packet<'_, F>) -> Self {
        let lanes = match packet.lanes {
            Lanes::Spheres(s) => Inline::Spheres(Spheres::Four(*s)),
            Lanes::Sphere(s) => Inline::Spheres(Spheres::One(*s)),
            Lanes::Triangles(t) => Inline::Triangles(*t),
            Lanes::Others => Inline::Others,
        };
        Self {
            lanes,
            keys: *packet.keys,
        }
    }

    /// The packet it holds.
    #[inline(always)]
    pub(super) fn packet(&self) -> Packet<'_, F> {
        let lanes = match &self.lanes {
            Inline::Spheres(Spheres::Four(s)) => Lanes::Spheres(s),
            Inline::Spheres(Spheres::One(s)) => Lanes::Sphere(s),
            Inline::Triangles(t) => Lanes::Triangles(t),
            Inline::Others => Lanes::Others,
        };
        Packet {
            lanes,
            keys: &self.keys,
            first_lane: NONE,
        }
    }
}
