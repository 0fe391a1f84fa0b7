//! Runs of consecutive parts: how a pass over every part of a scene splits over the threads,
//! whether the parts are many objects (spheres) or one object's (a mesh's triangles).

use super::Key;
use crate::float::Float;
use crate::scene::Object;
use crate::scene::layout::Layout;

/// Parts a pass over every part takes in one go ([`runs`]).
const RUN: usize = 4096;

/// Where each run of [`RUN`] consecutive parts starts, given each object's count of parts:
/// a pass over the runs splits evenly over the threads, whether the parts are many objects
/// (spheres) or one object's (a mesh's triangles).
pub(super) fn runs(parts: impl Iterator<Item = u32>) -> Vec<Key> {
    let (mut starts, mut filled) = (Vec::new(), 0);
    for (o, n) in parts.enumerate() {
        let mut p = 0;
        while p < n {
            if filled == 0 {
                starts.push((o as u32, p));
            }
            let taken = (n - p).min((RUN - filled) as u32);
            p += taken;
            filled = (filled + taken as usize) % RUN;
        }
    }
    starts
}

/// The keys of the run that starts at `start` ([`runs`]): the next [`RUN`] parts, or as many
/// as are left.
pub(super) fn run<S: Layout<F>, M, F: Float>(
    objects: &[Object<S, M>],
    (o, p): Key,
) -> impl Iterator<Item = Key> {
    let first = move |i: usize| if i == 0 { p } else { 0 };
    objects[o as usize..]
        .iter()
        .enumerate()
        .flat_map(move |(i, object)| (first(i)..object.shape.parts()).map(move |p| (o + i as u32, p)))
        .take(RUN)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{Hittable, Mesh, ShapeKind, Sphere};
    use crate::vec3::Vec3;

    /// The runs of parts ([`runs`], [`run`]) give every part of every object once, in the
    /// objects' order, whether the parts are spread over many objects or held by one, and
    /// every run but the last holds [`RUN`] parts.
    #[test]
    fn the_runs_give_every_part_once_in_order() {
        let mesh = |faces: usize| {
            let v = (0..3 * faces)
                .map(|i| Vec3::new(i as f32, (i % 3) as f32, -1.0 - (i % 2) as f32))
                .collect::<Vec<_>>();
            let f = (0..faces as u32).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]).collect();
            ShapeKind::from(Mesh::new(v, f).unwrap())
        };
        let sphere = || ShapeKind::from(Sphere::new(Vec3::new(0.0, 0.0, -5.0), 0.3).unwrap());
        let shapes = [
            vec![],
            vec![sphere()],
            vec![mesh(2 * RUN + 5)],
            (0..RUN + 1).map(|_| sphere()).collect(),
            vec![
                sphere(),
                mesh(3),
                sphere(),
                mesh(RUN),
                mesh(RUN - 1),
                sphere(),
                mesh(7),
            ],
        ];
        for shapes in shapes {
            let objects: Vec<_> = shapes
                .into_iter()
                .map(|shape| Object { shape, material: () })
                .collect();
            let expected: Vec<Key> = (0..objects.len() as u32)
                .flat_map(|o| (0..objects[o as usize].shape.parts()).map(move |p| (o, p)))
                .collect();
            let starts = runs(objects.iter().map(|o| o.shape.parts()));
            let runs: Vec<Vec<Key>> = starts.iter().map(|&s| run(&objects, s).collect()).collect();
            assert_eq!(runs.concat(), expected);
            let (last, full) = runs.split_last().map_or((0, &[][..]), |(l, f)| (l.len(), f));
            assert!(full.iter().all(|r| r.len() == RUN) && (1..=RUN).contains(&last) || expected.is_empty());
        }
    }
}
