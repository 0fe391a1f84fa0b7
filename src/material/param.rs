//! What the materials do with their [`Texture`] parameters besides looking them up:
//! check a constant's value where it enters, change its scalar, take its mean.
//!
//! Each `match` names every kind of texture, so a kind added to [`Texture`] does not
//! compile until it says how it is checked, cast and averaged.

use crate::error::{Error, Field, Result};
use crate::float::Float;
use crate::texture::Texture;
use crate::validate::rule;
use crate::vec3::Color;

/// `texture` if its value obeys `rule` everywhere: a constant is checked here, once;
/// an image or a pattern is checked by its own constructor when it is read.
pub(super) fn checked<F: Float>(
    field: Field,
    texture: Texture<F>,
    rule: fn(Color<F>) -> std::result::Result<Color<F>, String>,
) -> Result<Texture<F>> {
    let check = |c: Color<F>| rule(c).map(|_| ()).map_err(|why| Error::invalid(field, why));
    match &texture {
        Texture::Constant(c) => check(*c)?,
        Texture::Checkerboard(c) => {
            check(c.color0())?;
            check(c.color1())?;
        }
        // Every rule is an interval per channel, so the image's smallest and largest
        // values decide for all of its pixels.
        Texture::Image(_) => {
            for end in texture.range() {
                check(Color::splat(F::from_f64(end)))?;
            }
        }
    }
    Ok(texture)
}

/// A colour in `[0, 1]` per channel (a reflectance).
pub(super) fn unit_colour<F: Float>(field: Field, texture: Texture<F>) -> Result<Texture<F>> {
    checked(field, texture, rule::albedo)
}

/// A finite, non-negative colour (an index of refraction per channel).
pub(super) fn non_negative<F: Float>(field: Field, texture: Texture<F>) -> Result<Texture<F>> {
    checked(field, texture, rule::non_negative)
}

/// A finite, strictly positive number in every channel (a roughness).
pub(super) fn positive<F: Float>(field: Field, texture: Texture<F>) -> Result<Texture<F>> {
    checked(field, texture, |c| {
        for x in [c.x, c.y, c.z] {
            rule::positive(x)?;
        }
        Ok(c)
    })
}

/// `texture` in scalar `G`, rounded through `f64` (re-checked by the caller's
/// constructor).
///
/// # Errors
/// What [`Texture::cast`] refuses: a value beyond `G`'s range.
pub(super) fn cast<F: Float, G: Float>(texture: &Texture<F>) -> Result<Texture<G>> {
    texture.cast()
}

/// The mean of the texture's channels over its whole extent, as Mitsuba's
/// `Texture::mean`: what a plastic weighs its lobes by.
pub(super) fn mean<F: Float>(texture: &Texture<F>) -> f64 {
    let of = |c: Color<F>| {
        let [r, g, b] = c.to_f64();
        (r + g + b) / 3.0
    };
    match texture {
        Texture::Constant(c) => of(*c),
        // Half of the plane is each colour.
        Texture::Checkerboard(c) => 0.5 * (of(c.color0()) + of(c.color1())),
        Texture::Image(i) => {
            let pixels = i.bitmap().pixels();
            let sum: f64 = pixels
                .iter()
                .map(|p| p.iter().map(|&x| f64::from(x)).sum::<f64>())
                .sum();
            sum / (3.0 * pixels.len() as f64)
        }
    }
}
