//! The examples' output (`examples/common/files.rs`): when the second file cannot be
//! written, the error names it and says the first one exists.

use crate::files;

use raytrace::Image;
use raytrace::image::Encoding;
use std::fs;

#[test]
fn a_failed_png_says_the_ppm_was_written() {
    let dir = std::env::temp_dir().join(format!("raytrace-example-files-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let (ppm, png) = (dir.join("x.ppm"), dir.join("x.png"));
    // A folder where the PNG should go: renaming the finished file onto it fails.
    fs::create_dir(&png).unwrap();
    fs::write(png.join("keep"), "").unwrap();
    let samples = Image::new(4, 2).unwrap().to_u16(Encoding::Srgb);
    let err = files::write_both(&ppm, &png, &samples, Encoding::Srgb)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("x.png") && err.contains("x.ppm was written"),
        "{err}"
    );
    assert!(ppm.is_file());
    let left: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 2, "no temporary file is left: {left:?}");
    // Both written when nothing is in the way.
    fs::remove_dir_all(&png).unwrap();
    files::write_both(&ppm, &png, &samples, Encoding::Srgb).unwrap();
    assert!(png.is_file());
    fs::remove_dir_all(dir).unwrap();
}
