//! Mitsuba 3's `<transform>`: its steps (`translate`, `rotate`, `scale`, `matrix`,
//! `lookat`), each applied after the ones before it, as one [`Affine`], with the steps
//! kept as written (a placement the scene file can say in its own words renders the
//! same bytes as the scene file: see `exact.rs`).

use super::xml::At;
use crate::error::Result;
use crate::transform::Affine;

/// A `<transform>`: its map and the steps it was written as.
#[derive(Clone, Debug, PartialEq)]
pub struct Transform {
    /// `Mₙ·…·M₁` for the steps `M₁ … Mₙ`.
    pub map: Affine,
    /// The steps in document order.
    pub steps: Vec<Step>,
}

/// One step of a `<transform>`, its numbers as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// `<translate>`.
    Translate([f64; 3]),
    /// `<scale>`, a factor per axis.
    Scale([f64; 3]),
    /// `<rotate>`: the axis, the angle in degrees.
    Rotate([f64; 3], f64),
    /// `<matrix>`.
    Matrix(Affine),
    /// `<lookat>`: origin, target, up.
    LookAt([[f64; 3]; 3]),
}

/// The `<transform>` element `node`: its map `Mₙ·…·M₁` for its steps `M₁ … Mₙ` in
/// document order, and the steps. Attribute values pass through `substitute` (`$name`).
pub fn transform(
    node: roxmltree::Node,
    at: &At,
    substitute: &dyn Fn(&str) -> Result<String>,
) -> Result<Transform> {
    let mut map = Affine::IDENTITY;
    let mut steps = Vec::new();
    for step in node.children().filter(roxmltree::Node::is_element) {
        let tag = step.tag_name().name();
        let attribute = |name: &str| step.attribute(name).map(substitute).transpose();
        let numbers = |name: &str| -> Result<Option<Vec<f64>>> {
            let Some(text) = attribute(name)? else {
                return Ok(None);
            };
            text.split(|c: char| c == ',' || c.is_whitespace())
                .filter(|s| !s.is_empty())
                .map(|s| {
                    s.parse::<f64>()
                        .map_err(|_| at.error(format!("<{tag} {name}=…>: `{s}` is not a number")))
                })
                .collect::<Result<Vec<_>>>()
                .map(Some)
        };
        let triple = |name: &str| -> Result<[f64; 3]> {
            match numbers(name)?.as_deref() {
                Some(&[x, y, z]) => Ok([x, y, z]),
                Some(_) => Err(at.error(format!("<{tag} {name}=…> needs three numbers"))),
                None => Err(at.error(format!("<{tag}> needs `{name}`"))),
            }
        };
        // `x`, `y`, `z` attributes, each `default` when absent; or `value`.
        let xyz = |default: f64| -> Result<[f64; 3]> {
            if let Some(v) = numbers("value")? {
                return match v[..] {
                    [s] => Ok([s; 3]),
                    [x, y, z] => Ok([x, y, z]),
                    _ => Err(at.error(format!("<{tag} value=…> needs one or three numbers"))),
                };
            }
            let one = |a: &str| -> Result<f64> {
                Ok(numbers(a)?.and_then(|v| v.first().copied()).unwrap_or(default))
            };
            Ok([one("x")?, one("y")?, one("z")?])
        };
        let (next, step) = match tag {
            "translate" => {
                let t = xyz(0.0)?;
                (Affine::translate(t), Step::Translate(t))
            }
            "scale" => {
                let s = xyz(1.0)?;
                (Affine::scale(s), Step::Scale(s))
            }
            "rotate" => {
                let angle = numbers("angle")?
                    .and_then(|v| v.first().copied())
                    .ok_or_else(|| at.error("<rotate> needs an `angle` in degrees"))?;
                let axis = xyz(0.0)?;
                if axis == [0.0; 3] || !axis.iter().all(|a| a.is_finite()) {
                    return Err(at.error("<rotate> needs a finite, non-zero axis"));
                }
                (rotate_as_written(axis, angle), Step::Rotate(axis, angle))
            }
            "matrix" => {
                let v = numbers("value")?.unwrap_or_default();
                if v.len() != 16 && v.len() != 9 {
                    return Err(at.error("<matrix value=…> needs 16 numbers (4×4, row by row) or 9 (3×3)"));
                }
                let rows = if v.len() == 16 {
                    if v[12..16] != [0.0, 0.0, 0.0, 1.0] {
                        return Err(
                            at.error("<matrix>: a projective matrix (last row not 0 0 0 1) places nothing")
                        );
                    }
                    [0, 1, 2].map(|i| [v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]])
                } else {
                    [0, 1, 2].map(|i| [v[3 * i], v[3 * i + 1], v[3 * i + 2], 0.0])
                };
                let m = Affine::from_rows(rows).map_err(|e| at.error(format!("<matrix>: {e}")))?;
                (m, Step::Matrix(m))
            }
            "lookat" => {
                let up = if step.attribute("up").is_some() {
                    triple("up")?
                } else {
                    [0.0, 1.0, 0.0]
                };
                let (origin, target) = (triple("origin")?, triple("target")?);
                let m = Affine::look_at(origin, target, up).ok_or_else(|| {
                    at.error("<lookat>: the origin is the target, or `up` is along the view")
                })?;
                (m, Step::LookAt([origin, target, up]))
            }
            other => return Err(at.error(format!("<{other}> is not a step of a <transform>"))),
        };
        map = map.then(&next);
        steps.push(step);
    }
    Ok(Transform { map, steps })
}

/// Mitsuba's `<rotate>`: Rodrigues' formula of the axis as written, not normalised (Mitsuba
/// 3.9.1 gives `<rotate x="0" y="1" z="1" angle="15"/>` a map that turns and stretches: its
/// `[1][1]` is 1, not cos 15°). For a unit axis it is the turn [`Affine::rotate`] makes;
/// for another the importer warns (`convert.rs`).
fn rotate_as_written([x, y, z]: [f64; 3], degrees: f64) -> Affine {
    if x * x + y * y + z * z == 1.0 {
        return Affine::rotate([x, y, z], degrees);
    }
    let (s, c) = degrees.to_radians().sin_cos();
    let k = 1.0 - c;
    let rows = [
        [c + x * x * k, x * y * k - z * s, x * z * k + y * s, 0.0],
        [y * x * k + z * s, c + y * y * k, y * z * k - x * s, 0.0],
        [z * x * k - y * s, z * y * k + x * s, c + z * z * k, 0.0],
    ];
    // Singular only for contrived axes; then the rotation of the unit axis, which the
    // warning about the axis still names.
    Affine::from_rows(rows).unwrap_or_else(|_| Affine::rotate([x, y, z], degrees))
}
