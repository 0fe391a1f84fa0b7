//! The layers of a render beyond its colour (an adaptive render's sample-count and error
//! maps, a denoiser's features): inside the EXR, or beside an image of another format.

use raytrace::Image;
use raytrace::Result;
use raytrace::cli::write_file;
use raytrace::image::{ExrChannel, write_layered_exr};
use std::path::{Path, PathBuf};

/// Where the layers of an image written to `image` go when its format holds no layers:
/// beside it, `NAME.layers.exr` for `NAME.png` (or `NAME.ppm`, …).
pub fn beside(image: &Path) -> PathBuf {
    let stem = image
        .file_stem()
        .map_or_else(|| "render".into(), |s| s.to_string_lossy().into_owned());
    image.with_file_name(format!("{stem}.layers.exr"))
}

/// Writes the layers file [`beside`] `image`: the colour (linear) and the layers, one
/// multi-layer EXR.
pub fn write_beside(image_path: &Path, image: &Image, layers: &[ExrChannel]) -> Result<PathBuf> {
    let path = beside(image_path);
    write_file(&path, |p| write_layered_exr(p, image, layers))?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_layers_file_is_named_after_the_image() {
        assert_eq!(
            beside(Path::new("out/dragon.png")),
            Path::new("out/dragon.layers.exr")
        );
        assert_eq!(beside(Path::new("a.b.ppm")), Path::new("a.b.layers.exr"));
        assert_eq!(beside(Path::new("image")), Path::new("image.layers.exr"));
    }
}
