//! Same bytes everywhere: both dispatch paths, any number of threads, tiles, generators, scalars.

use super::scene::*;
use raytrace::Image;
use raytrace::prelude::*;
use twofloat::TwoFloat;

#[test]
fn trait_objects_and_enums_give_identical_bytes() {
    let cam = ScreenCamera::new(64, 32).unwrap();
    let a = render(&enum_scene::<f64>(), &cam, &settings(4, 9)).unwrap();
    let b = render(&dyn_scene::<f64>(), &cam, &settings(4, 9)).unwrap();
    assert_eq!(a.image, b.image);
    assert_eq!(bytes(&a.image), bytes(&b.image));
    assert_eq!(a.stats.rays, b.stats.rays);
    let a = render(&enum_scene::<f32>(), &cam, &settings(4, 9)).unwrap();
    let b = render(&dyn_scene::<f32>(), &cam, &settings(4, 9)).unwrap();
    assert_eq!(bytes(&a.image), bytes(&b.image));
}

#[test]
fn a_seed_fixes_the_image_on_any_number_of_threads() {
    let cam = ScreenCamera::new(64, 32).unwrap();
    let scene = enum_scene::<f32>();
    let one = in_pool(1, || render(&scene, &cam, &settings(3, 5)).unwrap());
    let two = in_pool(2, || render(&scene, &cam, &settings(3, 5)).unwrap());
    let many = in_pool(7, || render(&scene, &cam, &settings(3, 5)).unwrap());
    assert_eq!(one.stats.threads, 1);
    assert_eq!(bytes(&one.image), bytes(&two.image));
    assert_eq!(bytes(&one.image), bytes(&many.image));
    let other = render(&scene, &cam, &settings(3, 6)).unwrap();
    assert_ne!(
        one.image, other.image,
        "a different seed must change a matte scene"
    );
}

#[test]
fn a_tile_equals_the_same_pixels_of_the_whole_image() {
    let cam = ScreenCamera::new(64, 32).unwrap();
    let scene = enum_scene::<f64>();
    let whole = render(&scene, &cam, &settings(2, 1)).unwrap().image;
    for tile in [
        Rect {
            x: 5,
            y: 3,
            width: 17,
            height: 9,
        },
        Rect {
            x: 63,
            y: 31,
            width: 1,
            height: 1,
        },
    ] {
        let part = Renderer::new(&scene, &cam)
            .settings(settings(2, 1))
            .tile(tile)
            .render()
            .unwrap()
            .image;
        for y in 0..tile.height {
            for x in 0..tile.width {
                assert_eq!(part.pixel(x, y), whole.pixel(tile.x + x, tile.y + y));
            }
        }
    }
    let outside = Rect {
        x: 60,
        y: 0,
        width: 5,
        height: 1,
    };
    let outside = Renderer::new(&scene, &cam).tile(outside);
    assert!(outside.render().is_err());
    assert!(outside.render_reference().is_err());
}

#[test]
fn any_seedable_generator_works() {
    let cam = ScreenCamera::new(16, 8).unwrap();
    let scene = enum_scene::<f64>();
    let std_rng = Renderer::new(&scene, &cam)
        .settings(settings(2, 3))
        .rng::<rand::rngs::StdRng>();
    let a = std_rng.render().unwrap();
    assert_eq!(a.image, std_rng.render().unwrap().image);
    assert_eq!(a.image, std_rng.render_reference().unwrap().image);
    let default = render(&scene, &cam, &settings(2, 3)).unwrap();
    assert_ne!(a.image, default.image, "another generator draws other numbers");
}

#[test]
fn every_scalar_renders_and_follows_one_random_stream() {
    let cam = ScreenCamera::new(32, 16).unwrap();
    let s = settings(2, 4);
    let dd = render(&enum_scene::<raytrace::DoubleDouble>(), &cam, &s)
        .unwrap()
        .image;
    let tf = render(&enum_scene::<TwoFloat>(), &cam, &s).unwrap().image;
    assert!(tf.pixels().iter().flatten().all(|c| c.is_finite() && *c >= 0.0));
    let f64_ = render(&enum_scene::<f64>(), &cam, &s).unwrap().image;
    let f32_ = render(&enum_scene::<f32>(), &cam, &s).unwrap().image;
    // Same draws: the images agree almost everywhere; a path can differ only where
    // rounding flips a decision, so compare the median pixel difference.
    let median_diff = |a: &Image, b: &Image| {
        let mut d: Vec<f64> = a
            .pixels()
            .iter()
            .zip(b.pixels())
            .map(|(p, q)| (0..3).map(|k| (p[k] - q[k]).abs()).fold(0.0, f64::max))
            .collect();
        d.sort_by(f64::total_cmp);
        d[d.len() / 2]
    };
    assert!(median_diff(&dd, &f64_) < 1e-12, "{}", median_diff(&dd, &f64_));
    assert!(median_diff(&f64_, &f32_) < 1e-5, "{}", median_diff(&f64_, &f32_));
    assert!(dd.pixels().iter().flatten().all(|c| c.is_finite() && *c >= 0.0));
}
