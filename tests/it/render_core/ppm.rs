//! The spec's PPM: its layout, top-left first, and a round trip through the reader.

use super::scene::*;
use raytrace::prelude::*;

#[test]
fn the_spec_ppm_round_trips_through_the_reader() {
    let cam = ScreenCamera::new(20, 10).unwrap();
    let image = render(&enum_scene::<f64>(), &cam, &settings(1, 0)).unwrap().image;
    let text = bytes(&image);
    let lines: Vec<&str> = std::str::from_utf8(&text).unwrap().lines().collect();
    assert_eq!(&lines[..3], &["P3", "20 10", "65535"]);
    assert_eq!(lines.len(), 3 + 200, "one pixel per line");
    let parsed = raytrace::image::parse_ppm(&text).unwrap();
    assert_eq!(parsed, image.to_u16(Encoding::Srgb));
    // Top-left first: the first pixel looks up-left into the sky, the last down into the ground.
    let first = image.pixel(0, 0);
    assert_eq!(
        lines[3],
        format!(
            "{} {} {}",
            Encoding::Srgb.quantize(first[0]),
            Encoding::Srgb.quantize(first[1]),
            Encoding::Srgb.quantize(first[2])
        )
    );
    assert!(first[2] > first[0], "top-left pixel should be sky blue");
}
