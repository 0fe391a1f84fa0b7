//! A shape and a material of your own: a checkered disk ([`parts::Disk`],
//! [`parts::Checker`]) under a mirror ball and a glass ball. What it shows:
//! - a user shape implements [`Hittable`] and reports its hit's rounding error with
//!   [`flat_hit_error`](raytrace::shape::flat_hit_error), so rays leaving it do not hit it
//!   again (see "Reporting the rounding error" in the [`Hittable`] docs);
//! - a user material implements [`Material`], here with the library's own sampler;
//! - both go into a scene either as trait objects ([`DynScene`], `Box`/`Arc`, no other
//!   code) or as variants of the user's own enums beside the library's ([`parts::Shape`],
//!   [`parts::Surface`]), and the two paths render the same image, which this checks.
//!
//! `cargo run --release --example custom_shape` writes `output/custom_shape.ppm` and `.png`.

#[path = "../common/mod.rs"]
mod common;
mod parts;

use common::{Example, Options};
use raytrace::Render;
use raytrace::advice::Precision;
use raytrace::prelude::*;

fn main() -> std::process::ExitCode {
    let example = Example {
        name: "custom_shape",
        about: "A user's own shape (a disk) and material (a checkerboard), on both dispatch paths.",
        defaults: Options::defaults(800, 16, 20),
    };
    common::main(example, |o| match o.precision {
        Precision::F32 => both_paths::<f32>(o),
        Precision::F64 => both_paths::<f64>(o),
    })
}

/// Renders the scene through trait objects and through enums; the image if they agree.
fn both_paths<F: Float>(o: &Options) -> raytrace::Result<Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    let settings = common::settings(o)?;
    let by_trait = render(&parts::dyn_scene::<F>()?, &camera, &settings)?;
    let by_enum = render(&parts::enum_scene::<F>()?, &camera, &settings)?;
    println!("trait objects: {}", by_trait.stats);
    println!("enums:         {}", by_enum.stats);
    if by_trait.image != by_enum.image {
        return Err(Error::invalid(
            "custom_shape",
            "the two dispatch paths rendered different images",
        ));
    }
    println!("the two dispatch paths rendered identical images");
    Ok(by_enum)
}
