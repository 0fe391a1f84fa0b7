//! Making packets: the parts of a list of keys sorted by kind, four to a packet, and a BVH's
//! leaves packed in parallel, one packet each.

use super::{Key, Keyed, LANES, NONE, Packets, Spheres};
use crate::float::Float;
use crate::scene::Object;
use crate::scene::layout::{Layout, Primitive};
use crate::shape::{Sphere, Sphere4, Triangle4};
use crate::vec3::Vec3;
use rayon::prelude::*;

/// The kind of a part as a number, the BVH's class for it: a leaf holds one kind, so it
/// is one packet.
pub(in crate::scene::index) fn kind<F>(primitive: &Primitive<F>) -> u8 {
    match primitive {
        Primitive::Sphere(_) => 0,
        Primitive::Triangle(_) => 1,
        Primitive::Other => 2,
    }
}

/// A worker's buffers for packing leaves: its packer, and the keys of the leaf at hand.
type Buffers<F> = (Packer<F>, Vec<Key>);

/// Packs parts into packets, with buffers kept from call to call.
pub(in crate::scene::index) struct Packer<F> {
    spheres: Vec<(Key, Sphere<F>)>,
    triangles: Vec<(Key, [Vec3<F>; 3])>,
    others: Vec<Key>,
}

impl<F: Float> Packer<F> {
    pub(in crate::scene::index) fn new() -> Self {
        Self {
            spheres: Vec::new(),
            triangles: Vec::new(),
            others: Vec::new(),
        }
    }

    /// Sorts `keys` and their parts into the buffers, kind by kind, in key order (the
    /// order the lanes' tie needs).
    fn sort<S: Layout<F>, M>(&mut self, keys: &mut [Key], objects: &[Object<S, M>]) {
        keys.sort_unstable();
        self.spheres.clear();
        self.triangles.clear();
        self.others.clear();
        for &key in keys.iter() {
            match objects[key.0 as usize].shape.primitive(key.1) {
                Primitive::Sphere(s) => self.spheres.push((key, s)),
                Primitive::Triangle(v) => self.triangles.push((key, v)),
                Primitive::Other => self.others.push(key),
            }
        }
    }

    /// Appends to `out` the packets of the parts `keys`: spheres, then triangles, then the
    /// others, each kind four to a packet in key order. Parts of one kind, four at most (a
    /// BVH leaf's), make one packet.
    pub(in crate::scene::index) fn pack<S: Layout<F>, M>(
        &mut self,
        keys: &mut [Key],
        objects: &[Object<S, M>],
        out: &mut Packets<F>,
    ) {
        self.sort(keys, objects);
        assert!(
            out.triangles.is_empty() && out.others.is_empty() || self.spheres.is_empty(),
            "packets come kind by kind"
        );
        out.spheres.extend(self.spheres.chunks(LANES).map(sphere_packet));
        assert!(
            out.others.is_empty() || self.triangles.is_empty(),
            "packets come kind by kind"
        );
        out.triangles
            .extend(self.triangles.chunks(LANES).map(triangle_packet));
        out.others
            .extend(self.others.chunks(LANES).map(|c| keys_of(c.iter().copied())));
    }
}

impl<F: Float> Packets<F> {
    /// Appends the packets of a BVH's leaves, one each, made on any threads: `counts[c]`
    /// leaves of kind `c`, numbered kind by kind, and `leaf(k, keys)` fills `keys` with leaf
    /// `k`'s parts (of one kind, four at most). Each packet depends on its leaf alone and
    /// lands at its leaf's place, so the packets are the same on any number of threads.
    pub(in crate::scene::index) fn pack_leaves<S, M>(
        &mut self,
        counts: [usize; 3],
        objects: &[Object<S, M>],
        leaf: impl Fn(usize, &mut Vec<Key>) + Sync,
    ) where
        S: Layout<F>,
        M: Sync,
    {
        let sorted = |(packer, keys): &mut Buffers<F>, k: usize| {
            leaf(k, keys);
            packer.sort(keys, objects);
            let kinds = [packer.spheres.len(), packer.triangles.len(), packer.others.len()];
            debug_assert!(
                keys.len() <= LANES && kinds.iter().filter(|&&n| n > 0).count() == 1,
                "a leaf is one packet"
            );
        };
        self.pack_sorted(counts, &sorted);
    }

    /// [`Packets::pack_leaves`]' parallel loops, `sorted(buffers, k)` sorting leaf `k`'s
    /// parts into the buffers' packer. Apart, with the leaves' work as a trait object, they
    /// are compiled once, not once for every shape type.
    fn pack_sorted(&mut self, counts: [usize; 3], sorted: &(dyn Fn(&mut Buffers<F>, usize) + Sync)) {
        assert!(self.len() == 0, "a BVH's leaves are packed into no other packets");
        let start = [0, counts[0], counts[0] + counts[1]];
        let range = |c: usize| start[c]..start[c] + counts[c];
        let init = || (Packer::new(), Vec::new());
        self.spheres
            .par_extend(range(0).into_par_iter().map_init(init, |buffers, k| {
                sorted(buffers, k);
                sphere_packet(&buffers.0.spheres)
            }));
        self.triangles
            .par_extend(range(1).into_par_iter().map_init(init, |buffers, k| {
                sorted(buffers, k);
                triangle_packet(&buffers.0.triangles)
            }));
        self.others
            .par_extend(range(2).into_par_iter().map_init(init, |buffers, k| {
                sorted(buffers, k);
                keys_of(buffers.0.others.iter().copied())
            }));
    }
}

/// The packet of up to four spheres: a lone one is tested alone.
fn sphere_packet<F: Float>(chunk: &[(Key, Sphere<F>)]) -> Keyed<Spheres<F>> {
    let lanes = match *chunk {
        [(_, lone)] => Spheres::One(lone),
        _ => Spheres::Four(Sphere4::new(chunk.iter().map(|&(_, s)| s))),
    };
    Keyed {
        lanes,
        keys: keys_of(chunk.iter().map(|&(k, _)| k)),
    }
}

/// The packet of up to four triangles.
fn triangle_packet<F: Float>(chunk: &[(Key, [Vec3<F>; 3])]) -> Keyed<Triangle4<F>> {
    Keyed {
        lanes: Triangle4::new(chunk.iter().map(|&(_, v)| v)),
        keys: keys_of(chunk.iter().map(|&(k, _)| k)),
    }
}

/// Up to four keys in lanes, the unused ones `(NONE, 0)`.
fn keys_of(chunk: impl Iterator<Item = Key>) -> [Key; LANES] {
    let mut keys = [(NONE, 0); LANES];
    for (lane, key) in chunk.enumerate() {
        keys[lane] = key;
    }
    keys
}
