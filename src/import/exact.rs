//! Placements read in the scene file's own words where a `<transform>` says them: a
//! mesh's `to_world` of a scale, turns about x, y and z and a translation (each optional,
//! in that order) as its `scale`, `rotate` and `translate`; a sensor's lone `<lookat>` as
//! the camera's `from`, `at` and `up`; an envmap's turns about x, y and z as its `rotate`.
//! The map is the same as the matrix's; the rounding is the scene file's, so the XML twin
//! of a TOML scene renders the same bytes.

use super::convert::Importer;
use super::xml::{Plugin, Step, Value};
use crate::scene_file::Scale;

/// A mesh's placement, in the scene file's keys.
pub(super) struct Placed {
    /// `scale`.
    pub scale: Scale,
    /// `rotate`, degrees about x, then y, then z.
    pub rotate: [f64; 3],
    /// `translate`.
    pub translate: [f64; 3],
    /// `matrix`, where the steps are not the four above in their order.
    pub matrix: Option<[[f64; 4]; 3]>,
}

impl Importer {
    /// The steps of `p`'s `to_world`, none if it has none (or it is not a transform: the
    /// map's own reader says so).
    pub(super) fn steps<'p>(&self, p: &'p Plugin) -> &'p [Step] {
        match self.property(p, "to_world").map(|q| &q.value) {
            Some(Value::Transform(t)) => &t.steps,
            _ => &[],
        }
    }

    /// The placement of the mesh `p`: its keys where its steps are a scale, turns about
    /// x, y, z and a translation in that order, else its matrix.
    pub(super) fn placed(&self, p: &Plugin) -> crate::Result<Placed> {
        if let Some((scale, rotate, translate)) = scale_turn_move(self.steps(p)) {
            let scale = match scale {
                [x, y, z] if x == y && y == z => Scale::Uniform(x),
                per_axis => Scale::PerAxis(per_axis),
            };
            return Ok(Placed {
                scale,
                rotate,
                translate,
                matrix: None,
            });
        }
        Ok(Placed {
            scale: Scale::default(),
            rotate: [0.0; 3],
            translate: [0.0; 3],
            matrix: Some(self.to_world(p)?.rows()),
        })
    }
}

/// The origin, target and up of `steps` that are one `<lookat>`.
pub(super) fn look_at(steps: &[Step]) -> Option<[[f64; 3]; 3]> {
    match steps {
        [Step::LookAt(o_t_u)] => Some(*o_t_u),
        _ => None,
    }
}

/// The turns about x, y and z of `steps` that only turn, about those axes in that order.
pub(super) fn turns(steps: &[Step]) -> Option<[f64; 3]> {
    let only_turns = steps.iter().all(|s| matches!(s, Step::Rotate(..)));
    scale_turn_move(steps).filter(|_| only_turns).map(|(_, r, _)| r)
}

/// `(scale, rotate, translate)` of steps that are, each at most once and in this order, a
/// scale, a turn about x, about y, about z and a translation.
fn scale_turn_move(steps: &[Step]) -> Option<([f64; 3], [f64; 3], [f64; 3])> {
    let (mut scale, mut rotate, mut translate) = ([1.0; 3], [0.0; 3], [0.0; 3]);
    // The stage each step fills: 0 scale, 1–3 the turns, 4 the translation.
    let mut next = 0;
    for step in steps {
        let stage = match step {
            Step::Scale(s) => {
                scale = *s;
                0
            }
            Step::Rotate(axis, angle) => {
                // A turn about x, y or z only for a unit axis: Mitsuba does not normalise
                // one of another length (its map then stretches too: `transform.rs`).
                let along = axis.iter().position(|a| *a == 1.0)?;
                if axis.iter().enumerate().any(|(i, a)| i != along && *a != 0.0) {
                    return None;
                }
                rotate[along] = *angle;
                1 + along
            }
            Step::Translate(t) => {
                translate = *t;
                4
            }
            Step::Matrix(_) | Step::LookAt(_) => return None,
        };
        if stage < next {
            return None;
        }
        next = stage + 1;
    }
    Some((scale, rotate, translate))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_in_the_scene_files_order_are_its_keys() {
        let steps = [
            Step::Scale([2.0; 3]),
            Step::Rotate([1.0, 0.0, 0.0], 90.0),
            Step::Rotate([0.0, 0.0, 1.0], -17.0),
            Step::Translate([1.0, 2.0, 3.0]),
        ];
        assert_eq!(
            scale_turn_move(&steps),
            Some(([2.0; 3], [90.0, 0.0, -17.0], [1.0, 2.0, 3.0]))
        );
        assert_eq!(scale_turn_move(&[]), Some(([1.0; 3], [0.0; 3], [0.0; 3])));
    }

    #[test]
    fn any_other_order_or_axis_keeps_the_matrix() {
        let x = Step::Rotate([1.0, 0.0, 0.0], 10.0);
        let y = Step::Rotate([0.0, 1.0, 0.0], 10.0);
        let t = Step::Translate([1.0; 3]);
        let s = Step::Scale([2.0; 3]);
        for steps in [
            vec![y.clone(), x.clone()],
            vec![t.clone(), s.clone()],
            vec![x.clone(), x.clone()],
            vec![Step::Rotate([1.0, 1.0, 0.0], 10.0)],
            vec![Step::Rotate([-1.0, 0.0, 0.0], 10.0)],
            vec![Step::Rotate([0.0, 3.0, 0.0], 10.0)],
            vec![Step::LookAt([[0.0; 3], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]])],
        ] {
            assert_eq!(scale_turn_move(&steps), None, "{steps:?}");
        }
        assert_eq!(turns(&[x.clone(), y.clone()]), Some([10.0, 10.0, 0.0]));
        assert_eq!(turns(&[s, x]), None);
    }
}
