//! How a scene file's keys place a mesh or an instance (`scale`, `rotate`, `translate` or
//! `matrix`), every number checked.

use super::check::{blame, vec};
use super::location::KeyPath;
use super::model::Triple;
use super::objects::Scale;
use super::transform::Placement;
use crate::error::{Error, Result};
use crate::transform::Affine;
use crate::validate::{rule, show};

/// A mesh object's placement: its `matrix`, or its `scale`, `rotate` and `translate`.
pub(super) fn mesh_placement(
    (root, at): (&KeyPath, &KeyPath),
    scale: Scale,
    rotate: Triple,
    translate: Triple,
    matrix: Option<[[f64; 4]; 3]>,
) -> Result<Placement> {
    match matrix {
        Some(rows) => {
            only_matrix(at, scale, rotate, translate)?;
            let map = Affine::from_rows(rows).map_err(|e| blame(root, &at.key("matrix"), e))?;
            Placement::map(map).map_err(|e| blame(root, &at.key("matrix"), e))
        }
        None => placement(at, scale.factors(), rotate, translate),
    }
}

/// An instance's map from its mesh's space to the scene's: scale, rotate about x, then y,
/// then z, translate, as a mesh object's [`Placement`] (every number finite, no factor
/// zero), composed as one [`Affine`].
pub(super) fn affine(at: &KeyPath, scale: Triple, rotate: Triple, translate: Triple) -> Result<Affine> {
    placement(at, scale, rotate, translate)?;
    let [rx, ry, rz] = rotate;
    Ok(Affine::scale(scale)
        .then(&Affine::rotate([1.0, 0.0, 0.0], rx))
        .then(&Affine::rotate([0.0, 1.0, 0.0], ry))
        .then(&Affine::rotate([0.0, 0.0, 1.0], rz))
        .then(&Affine::translate(translate)))
}

/// A `matrix` is the whole placement: no `scale`, `rotate` or `translate` beside it.
pub(super) fn only_matrix(at: &KeyPath, scale: Scale, rotate: Triple, translate: Triple) -> Result<()> {
    if scale.factors() != [1.0; 3] || rotate != [0.0; 3] || translate != [0.0; 3] {
        return Err(at
            .key("matrix")
            .error("give either `matrix` or `scale`, `rotate` and `translate`, not both"));
    }
    Ok(())
}

/// A mesh's placement: every number finite, no scale factor zero.
fn placement(at: &KeyPath, scale: Triple, rotate: Triple, translate: Triple) -> Result<Placement> {
    let finite = |key: &str, t: Triple| {
        rule::finite(vec::<f64>(t)).map_err(|why| at.key(key).error(why))?;
        Ok::<_, Error>(t)
    };
    let factors = finite("scale", scale)?;
    if factors.contains(&0.0) {
        return Err(at.key("scale").error(format!(
            "every factor must be non-zero (got {})",
            show(vec::<f64>(factors))
        )));
    }
    Ok(Placement::new(
        factors,
        finite("rotate", rotate)?,
        finite("translate", translate)?,
    ))
}
