//! The files a command reads: hashed into a tile's header, so that tiles of different
//! inputs never merge; and never overwritten by the command's output.

use raytrace::scene_file::SceneFile;
use raytrace::{Error, Result};
use std::fs::{self, File};
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};

/// FNV-1a (64-bit), fed as a writer.
struct Fnv(u64);

impl Write for Fnv {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// The hash a tile carries of everything its image depends on: FNV-1a 64 of the scene as
/// rendered (the file after the command line's overrides, as TOML), then of each mesh and
/// texture image file it names, its path and its bytes. Tiles rendered from different
/// scene files, settings, mesh or image contents differ in it.
///
/// A file is read only up to the length the system gives it (a device or a pipe named
/// as a mesh adds nothing here; loading it is the build's concern).
///
/// # Errors
/// [`Error::Io`] naming a mesh or image file that cannot be read.
pub fn scene_hash(file: &SceneFile) -> Result<String> {
    let mut hash = Fnv(0xcbf2_9ce4_8422_2325);
    // Writing into the hash never fails.
    let _ = hash.write_all(file.to_toml().as_bytes());
    for input in file.input_files() {
        let io_err = |source| Error::Io {
            path: input.clone(),
            source,
        };
        // Each name ends in a 0 byte, which no path holds: names and contents cannot shift.
        let _ = hash.write_all(input.to_string_lossy().as_bytes());
        let _ = hash.write_all(&[0]);
        let f = File::open(&input).map_err(io_err)?;
        let len = f.metadata().map_err(io_err)?.len();
        io::copy(&mut f.take(len), &mut hash).map_err(io_err)?;
    }
    Ok(format!("{:016x}", hash.0))
}

/// The files `raytrace render` reads: the scene file and every mesh and image it names.
pub fn of_scene(file: &SceneFile) -> Vec<PathBuf> {
    std::iter::once(file.path().to_path_buf())
        .chain(file.input_files())
        .collect()
}

/// The input that `out` is, if any: the same file, links followed (two names of one file
/// count as one).
pub fn overwritten<'a>(out: &Path, inputs: &'a [PathBuf]) -> Option<&'a Path> {
    inputs
        .iter()
        .find(|input| same_file(out, input))
        .map(PathBuf::as_path)
}

/// Whether `a` and `b` name one existing file.
#[cfg(unix)]
fn same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    let id = |p: &Path| fs::metadata(p).map(|m| (m.dev(), m.ino()));
    matches!((id(a), id(b)), (Ok(a), Ok(b)) if a == b)
}

/// Whether `a` and `b` name one existing file (without inode numbers: the same real path).
#[cfg(not(unix))]
fn same_file(a: &Path, b: &Path) -> bool {
    matches!((fs::canonicalize(a), fs::canonicalize(b)), (Ok(a), Ok(b)) if a == b)
}
