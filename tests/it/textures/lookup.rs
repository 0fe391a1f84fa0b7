//! Lookups at known points: bilinear filtering between known texels, the image's v axis,
//! repeat and clamp, the `uv` map, Mitsuba's checkerboard squares; the type's size.

use raytrace::material::Material;
use raytrace::prelude::*;
use raytrace::texture::{Bitmap, Checkerboard, ImageTexture, Texture, UvMap, Wrap};
use std::sync::Arc;

/// A 2 × 2 image: `[top left, top right, bottom left, bottom right]`, values whose
/// averages are exact in binary.
fn two_by_two() -> Arc<Bitmap> {
    let pixels = vec![
        [0.0, 0.25, 1.0],
        [1.0, 0.5, 0.0],
        [0.5, 0.75, 0.25],
        [0.25, 1.0, 0.5],
    ];
    Arc::new(Bitmap::from_rgb(2, 2, pixels).unwrap())
}

fn rgb<F: Float>(p: [f32; 3]) -> Color<F> {
    Vec3::from_f64(p[0].into(), p[1].into(), p[2].into())
}

fn at<F: Float>(t: &ImageTexture<F>, u: f64, v: f64) -> Color<F> {
    t.eval([lit(u), lit(v)])
}

fn texel_centres_give_the_texels_and_between_them_the_bilinear_mean<F: Float>() {
    let b = two_by_two();
    let t = ImageTexture::<F>::new(Arc::clone(&b));
    let p = b.pixels();
    // Pixel (i, j)'s centre is ((i + ½)/W, (j + ½)/H); row 0 is the top of the image.
    assert_eq!(at(&t, 0.25, 0.25), rgb(p[0]));
    assert_eq!(at(&t, 0.75, 0.25), rgb(p[1]));
    assert_eq!(at(&t, 0.25, 0.75), rgb(p[2]));
    assert_eq!(at(&t, 0.75, 0.75), rgb(p[3]));
    // The centre of the image: the mean of the four, exact for these values.
    let mean = (rgb::<F>(p[0]) + rgb(p[1]) + rgb(p[2]) + rgb(p[3])) * lit::<F>(0.25);
    assert_eq!(at(&t, 0.5, 0.5), mean);
    // Halfway along the top row.
    assert_eq!(at(&t, 0.5, 0.25), (rgb::<F>(p[0]) + rgb(p[1])) * lit::<F>(0.5));
}

#[test]
fn texel_centres_and_means() {
    texel_centres_give_the_texels_and_between_them_the_bilinear_mean::<f32>();
    texel_centres_give_the_texels_and_between_them_the_bilinear_mean::<f64>();
}

#[test]
fn a_point_between_texels_weighs_them_as_the_formula_says() {
    // 4 × 2: x = u·4 − ½, y = v·2 − ½; at (0.3, 0.6): x = 0.7, y = 0.7.
    let pixels: Vec<[f32; 3]> = (0..8)
        .map(|k| [k as f32 / 8.0, 0.0, 1.0 - k as f32 / 8.0])
        .collect();
    let t = ImageTexture::<f64>::new(Arc::new(Bitmap::from_rgb(4, 2, pixels.clone()).unwrap()));
    let p = |i: usize, j: usize| f64::from(pixels[j * 4 + i][0]);
    let (a, b) = (0.3 * 4.0 - 0.5, 0.6 * 2.0 - 0.5);
    let want = (1.0 - b) * ((1.0 - a) * p(0, 0) + a * p(1, 0)) + b * ((1.0 - a) * p(0, 1) + a * p(1, 1));
    let got = at(&t, 0.3, 0.6).x;
    assert!((got - want).abs() < 1e-15, "{got} vs {want}");
    // Rows swapped (v counted from the bottom) would give another value.
    let flipped = (1.0 - b) * ((1.0 - a) * p(0, 1) + a * p(1, 1)) + b * ((1.0 - a) * p(0, 0) + a * p(1, 0));
    assert!((got - flipped).abs() > 0.1);
}

#[test]
fn repeat_tiles_and_clamp_extends_the_edges() {
    let b = two_by_two();
    let p = b.pixels();
    let repeat = ImageTexture::<f64>::new(Arc::clone(&b));
    let clamp = ImageTexture::<f64>::new(Arc::clone(&b)).with_wrap(Wrap::Clamp);
    for (u, v) in [(0.25, 0.25), (0.625, 0.125), (0.875, 0.625), (0.0, 0.5)] {
        for (du, dv) in [(1.0, 0.0), (-3.0, 2.0), (5.0, -7.0)] {
            assert_eq!(
                at(&repeat, u + du, v + dv),
                at(&repeat, u, v),
                "({u}, {v}) + ({du}, {dv})"
            );
        }
    }
    // At u = 0 the filter reads column −1: the last column when repeating, column 0 clamped.
    assert_eq!(at(&repeat, 0.0, 0.25), (rgb::<f64>(p[1]) + rgb(p[0])) * 0.5);
    assert_eq!(at(&clamp, 0.0, 0.25), rgb(p[0]));
    // Far outside, clamping gives the nearest corner pixel.
    assert_eq!(at(&clamp, 5.0, -3.0), rgb(p[1]));
    assert_eq!(at(&clamp, -2.0, 9.0), rgb(p[2]));
    // Inside, the two agree.
    assert_eq!(at(&clamp, 0.6, 0.4), at(&repeat, 0.6, 0.4));
}

#[test]
fn the_uv_map_scales_then_offsets() {
    let b = two_by_two();
    let map = UvMap::new([2.0, 3.0], [0.25, -0.5]).unwrap();
    let mapped = ImageTexture::<f64>::new(Arc::clone(&b)).with_uv_map(map);
    let plain = ImageTexture::<f64>::new(b);
    for (u, v) in [(0.1, 0.2), (0.4, 0.9), (-1.3, 0.05)] {
        assert_eq!(at(&mapped, u, v), at(&plain, 2.0 * u + 0.25, 3.0 * v - 0.5));
    }
    assert!(UvMap::<f64>::new([f64::NAN, 1.0], [0.0; 2]).is_err());
    assert!(UvMap::<f64>::new([1.0, 1.0], [0.0, f64::INFINITY]).is_err());
    // 1e39 is finite in f64, not in f32.
    let wide = UvMap::<f64>::new([1.0, 1.0], [1e39, 0.0]).unwrap();
    assert!(wide.cast::<f32>().is_err());
}

#[test]
fn a_lookup_at_any_uv_is_finite_and_never_panics() {
    let t = ImageTexture::<f32>::new(two_by_two());
    let c = ImageTexture::<f32>::new(two_by_two()).with_wrap(Wrap::Clamp);
    for uv in [
        [f32::NAN, 0.5],
        [f32::INFINITY, f32::NEG_INFINITY],
        [1e30, -1e30],
        [f32::MAX, f32::MIN_POSITIVE],
    ] {
        assert!(t.eval(uv).is_finite(), "{uv:?}");
        assert!(c.eval(uv).is_finite(), "{uv:?}");
    }
}

#[test]
fn the_checkerboard_has_mitsubas_squares() {
    let (c0, c1) = (Vec3::new(0.9, 0.8, 0.7), Vec3::new(0.1, 0.2, 0.3));
    let board = Checkerboard::<f64>::new(c0, c1).unwrap();
    // colour0 where frac(u) > ½ and frac(v) > ½ agree, colour1 where they differ.
    for (u, v, want) in [
        (0.25, 0.25, c0),
        (0.75, 0.25, c1),
        (0.25, 0.75, c1),
        (0.75, 0.75, c0),
        // ½ itself is not past ½.
        (0.5, 0.5, c0),
        (0.5, 0.75, c1),
        // Negative coordinates: frac(−0.25) = 0.75.
        (-0.25, 0.25, c1),
        (-0.25, -0.25, c0),
        (3.25, 7.75, c1),
    ] {
        assert_eq!(board.eval([u, v]), want, "({u}, {v})");
    }
    let fine = board
        .clone()
        .with_uv_map(UvMap::new([4.0, 4.0], [0.0; 2]).unwrap());
    assert_eq!(fine.eval([0.1, 0.1]), c0);
    assert_eq!(fine.eval([0.15, 0.1]), c1);
    let default = Checkerboard::<f64>::mitsuba_default();
    assert_eq!(
        (default.color0(), default.color1()),
        (Vec3::splat(0.4), Vec3::splat(0.2))
    );
    assert!(Checkerboard::<f64>::new(Vec3::new(f64::NAN, 0.0, 0.0), c1).is_err());
}

#[test]
fn a_scalar_is_the_grey_value_or_the_luminance() {
    let grey = Arc::new(Bitmap::from_rgb(1, 1, vec![[0.3; 3]]).unwrap());
    let colour = Arc::new(Bitmap::from_rgb(1, 1, vec![[1.0, 0.5, 0.25]]).unwrap());
    assert!(grey.is_grey() && !colour.is_grey());
    let g = ImageTexture::<f64>::new(grey);
    let c = ImageTexture::<f64>::new(colour);
    assert_eq!(g.eval_scalar([0.5, 0.5]), f64::from(0.3f32));
    let luminance = 0.212671 * 1.0 + 0.715160 * 0.5 + 0.072169 * 0.25;
    assert!((c.eval_scalar([0.5, 0.5]) - luminance).abs() < 1e-15);
}

#[test]
fn a_texture_is_two_words_and_shares_its_pixels() {
    assert_eq!(std::mem::size_of::<Texture<f32>>(), 16);
    assert_eq!(std::mem::size_of::<Texture<f64>>(), 32);
    let t: Texture<f64> = ImageTexture::new(two_by_two()).into();
    let (Texture::Image(a), Ok(Texture::Image(b))) = (&t, t.cast::<f32>()) else {
        panic!("an image stays an image")
    };
    assert!(Arc::ptr_eq(a.bitmap(), b.bitmap()), "cast copies no pixels");
    let clone = t.clone();
    let (Texture::Image(a), Texture::Image(b)) = (&t, &clone) else {
        unreachable!()
    };
    assert!(Arc::ptr_eq(a, b), "a clone is a pointer");
}

#[test]
fn a_textured_matte_surface_reads_coordinates_and_checks_its_range() {
    let plain = Lambertian::<f64>::new(Vec3::splat(0.5)).unwrap();
    assert!(!plain.reads_coordinates());
    assert_eq!(Lambertian::textured(Vec3::splat(0.5)).unwrap(), plain);
    let image = Lambertian::<f64>::textured(ImageTexture::new(two_by_two())).unwrap();
    assert!(image.reads_coordinates());
    let bright = Arc::new(Bitmap::from_rgb(1, 2, vec![[0.5; 3], [0.2, 1.5, 0.1]]).unwrap());
    let e = Lambertian::<f64>::textured(ImageTexture::new(bright)).unwrap_err();
    assert!(e.to_string().contains("reach from 0.1 to 1.5"), "{e}");
    let board = Checkerboard::new(Vec3::splat(0.5), Vec3::new(0.0, -0.1, 0.0)).unwrap();
    assert!(Lambertian::<f64>::textured(board).is_err());
}

#[test]
fn a_bitmap_refuses_what_is_not_an_image() {
    assert!(Bitmap::from_rgb(0, 3, vec![]).is_err());
    assert!(Bitmap::from_rgb(2, 2, vec![[0.0; 3]; 3]).is_err());
    let e = Bitmap::from_rgb(2, 1, vec![[0.0; 3], [0.0, f32::NAN, 0.0]]).unwrap_err();
    assert!(e.to_string().contains("pixel (1, 0)"), "{e}");
    let e = Bitmap::from_rgb(1 << 15, 1 << 14, vec![]).unwrap_err();
    assert!(e.to_string().contains("too large for memory"), "{e}");
}
