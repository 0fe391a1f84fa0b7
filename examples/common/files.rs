//! Writing an example's two files, the PPM and then the PNG.

use raytrace::cli::write_file;
use raytrace::image::{Encoding, write_png, write_ppm};
use raytrace::{Error, Image16, Result};
use std::io;
use std::path::Path;

/// Writes `samples` to `ppm` and then to `png` (each atomically, missing folders made as
/// `raytrace::cli::write_file` does). If the PNG fails after the PPM was written, the error
/// says so, so the user knows which file exists.
pub fn write_both(ppm: &Path, png: &Path, samples: &Image16, encoding: Encoding) -> Result<()> {
    write_file(ppm, |p| write_ppm(p, samples))?;
    write_file(png, |p| write_png(p, samples, encoding)).map_err(|e| match e {
        Error::Io { path, source } => Error::Io {
            path,
            source: io::Error::new(source.kind(), format!("{source} ({} was written)", ppm.display())),
        },
        other => other,
    })
}
