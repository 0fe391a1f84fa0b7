//! Spot and directional lights, the thin lens and the tone map as scene files write them:
//! the format page's example for them builds to what it says (three kinds of light, the lens
//! and its focus, the exposure and curve) and renders the same bits on both renderers; a
//! light without `type` is still a point light; the page's numbers for its focus hold.

use raytrace::image::ToneCurve;
use raytrace::prelude::*;
use raytrace::scene_file::{FileCamera, LightSpec, SceneFile};
use std::path::Path;

/// The first `toml` block of the format page under the heading `heading`.
fn page_example(heading: &str) -> String {
    let page = include_str!("../../docs/SCENE_FORMAT.md");
    let section = &page[page.find(heading).expect("the page has the heading")..];
    let block = section
        .split("```toml\n")
        .nth(1)
        .expect("the section has an example");
    block.split_once("```").unwrap().0.to_string()
}

#[test]
fn the_pages_lights_lens_and_tone_example_builds_as_described() {
    let text = page_example("## Lights, lens and tone, by example");
    assert!(text.contains("type = \"spot\""), "the lights example");
    let file = SceneFile::parse(&text, Path::new("docs/lights.toml")).unwrap();
    assert!(
        matches!(file.lights[2], LightSpec::Point { .. }),
        "no type: a point light"
    );
    let built = file.build::<f64>().unwrap();
    let kinds: Vec<_> = built
        .scene
        .lights()
        .iter()
        .map(|l| match l {
            Light::Directional(_) => "directional",
            Light::Spot(_) => "spot",
            Light::Point(_) => "point",
        })
        .collect();
    assert_eq!(kinds, ["directional", "spot", "point"]);
    let Light::Spot(spot) = built.scene.lights()[1] else {
        unreachable!()
    };
    assert_eq!((spot.cutoff_angle(), spot.beam_width()), (25.0, 15.0));
    assert_eq!(
        (built.tonemap.exposure(), built.tonemap.curve()),
        (-0.5, ToneCurve::Aces)
    );
    let FileCamera::LookAt(camera) = built.camera else {
        panic!("a look-at camera")
    };
    assert!(camera.has_lens());
    assert_eq!((camera.aperture(), camera.focus_distance()), (0.08, 5.0));
    // The page's numbers: `at` 5.02 along the view; the near sphere 2.04, blurred over
    // 0.08·|2.04 − 5|/2.04 ≈ 0.12.
    let (from, at) = (Vec3::<f64>::new(0.0, 1.0, 4.0), Vec3::new(0.0, 0.5, -1.0));
    let axis = (at - from).normalize();
    assert!(((at - from).dot(axis) - 5.02).abs() < 0.005);
    let z = (Vec3::new(1.5, 0.5, 2.0) - from).dot(axis);
    assert!((z - 2.04).abs() < 0.005, "{z}");
    assert!((0.08 * (z - 5.0).abs() / z - 0.12).abs() < 0.005);
}

#[test]
fn the_pages_example_renders_the_same_bits_on_both_renderers() {
    let mut file = SceneFile::parse(
        &page_example("## Lights, lens and tone, by example"),
        Path::new("docs/lights.toml"),
    )
    .unwrap();
    file.render_mut().width = 24;
    file.render_mut().spp = 2;
    let built = file.build::<f32>().unwrap();
    let renderer = Renderer::new(&built.scene, &built.camera).settings(built.settings);
    let (fast, reference) = (renderer.render().unwrap(), renderer.render_reference().unwrap());
    assert_eq!(fast.image, reference.image);
    // Something is lit, and nothing is NaN.
    let pixels = reference.image.pixels();
    assert!(pixels.iter().flatten().all(|c| c.is_finite() && *c >= 0.0));
    assert!(pixels.iter().flatten().any(|c| *c > 0.05));
}

#[test]
fn every_toml_block_of_the_page_parses() {
    let page = include_str!("../../docs/SCENE_FORMAT.md");
    let blocks: Vec<&str> = page
        .split("```toml\n")
        .skip(1)
        .map(|b| b.split_once("```").unwrap().0)
        .collect();
    assert!(blocks.len() >= 2);
    for (n, block) in blocks.iter().enumerate() {
        SceneFile::parse(block, Path::new("docs/page.toml")).unwrap_or_else(|e| panic!("block {n}: {e}"));
    }
}
