//! Atomic file writes: a temporary file beside the target, then a rename; and the rules for
//! targets that are not regular files.
//!
//! What [`write_atomic`] does with each kind of target (symbolic links followed):
//!
//! | target | what happens |
//! |---|---|
//! | nothing, or a regular file | a temporary file beside it, renamed over it when complete |
//! | a symbolic link | written through: the file it points to is replaced as above, the link stays |
//! | a character device or a FIFO (`/dev/null`, a named pipe) | streamed into, in place: never replaced |
//! | a link to nothing, a folder, a block device, a socket | refused, nothing written |
//!
//! A stream cannot be taken back: if writing fails halfway, its reader has seen part of the
//! file. Opening a FIFO waits, as for any program, until something reads from it.
//!
//! The library keeps no list of its temporary files. A program that uses the `cli` module
//! has that module's registry hooked in here ([`TRACKER`]), which removes them when a
//! signal stops the program.

use crate::error::{Error, Result};
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

/// The longest file name most file systems take (Linux's `NAME_MAX`), in bytes.
const NAME_MAX: usize = 255;

/// `.<name>.<pid>.<n>.tmp` beside `path`: unique within the process (the counter) and
/// between processes (the pid), and hidden from a plain `ls`. The name is shortened so
/// that the whole stays within [`NAME_MAX`] bytes: a legal target name gives a legal
/// temporary name.
pub(crate) fn temporary_path(path: &Path) -> io::Result<PathBuf> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file path"))?;
    let suffix = format!(
        ".{}.{}.tmp",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    );
    let name = name.to_string_lossy();
    let mut keep = name.len().min(NAME_MAX - 1 - suffix.len());
    while !name.is_char_boundary(keep) {
        keep -= 1;
    }
    Ok(path.with_file_name(format!(".{}{suffix}", &name[..keep])))
}

/// Where the bytes of a write to some path go.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Destination {
    /// A regular file, or nothing yet, at this path (symbolic links resolved): replaced
    /// atomically.
    Replace(PathBuf),
    /// A character device or a FIFO: written in place, as a stream.
    Stream,
}

/// An error for a target [`write_atomic`] refuses.
fn refuse(what: &str) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("{what}: refusing to write an image there"),
    )
}

/// What writing to `path` does (see the module's table).
///
/// # Errors
/// For a target that is refused, saying what it is; or if `path` cannot be examined.
pub(crate) fn destination(path: &Path) -> io::Result<Destination> {
    let link = match fs::symlink_metadata(path) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Destination::Replace(path.into())),
        Err(e) => return Err(e),
        Ok(m) => m,
    };
    if !link.file_type().is_symlink() {
        return classify(&link, path.to_path_buf());
    }
    match fs::metadata(path) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Err(refuse("a symbolic link to nothing")),
        Err(e) => Err(e),
        Ok(target) => classify(&target, fs::canonicalize(path)?),
    }
}

/// A target of this type, at `resolved` (its real path).
fn classify(m: &fs::Metadata, resolved: PathBuf) -> io::Result<Destination> {
    let t = m.file_type();
    if t.is_file() {
        return Ok(Destination::Replace(resolved));
    }
    if t.is_dir() {
        return Err(refuse("a folder"));
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_char_device() || t.is_fifo() {
            return Ok(Destination::Stream);
        }
        if t.is_block_device() {
            return Err(refuse("a block device"));
        }
        if t.is_socket() {
            return Err(refuse("a socket"));
        }
    }
    Err(refuse("not a regular file"))
}

/// How an atomic write tells someone who tracks temporary files (the `cli` module's
/// registry) about its own: each step runs inside the tracker's call, so that a cleanup
/// that holds the tracker sees it either done or not begun.
pub(crate) trait Temporaries: Sync {
    /// Runs `create`, which makes the temporary file `tmp`, and remembers `tmp`.
    fn create(&self, tmp: &Path, create: &mut dyn FnMut() -> io::Result<File>) -> io::Result<File>;
    /// Runs `finish`, which renames or removes `tmp`, and forgets `tmp`.
    fn finish(&self, tmp: &Path, finish: &mut dyn FnMut() -> io::Result<()>) -> io::Result<()>;
}

/// Who tracks the temporary files of every [`write_atomic`] in this process, if anyone:
/// set once by the `cli` module when a program uses it; unset, nothing is tracked.
pub(crate) static TRACKER: OnceLock<&'static dyn Temporaries> = OnceLock::new();

/// No tracking.
struct Untracked;

impl Temporaries for Untracked {
    fn create(&self, _: &Path, create: &mut dyn FnMut() -> io::Result<File>) -> io::Result<File> {
        create()
    }
    fn finish(&self, _: &Path, finish: &mut dyn FnMut() -> io::Result<()>) -> io::Result<()> {
        finish()
    }
}

/// Writes `path` atomically: `write` fills a buffered temporary file in the same folder,
/// which is flushed, synced and renamed over `path` only if everything succeeded. A
/// symbolic link is followed, and a character device or FIFO is written as a stream
/// (the module's table says what is refused).
///
/// A failure at any step removes the temporary file and leaves `path` as it was (absent,
/// or its previous content); the error names `path`. The folder must exist.
///
/// # Errors
/// [`Error::Io`] naming `path`: a refused target, or any failure to write.
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> Result<()> {
    let temps = TRACKER.get().copied().unwrap_or(&Untracked);
    let io_err = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    match destination(path).map_err(io_err)? {
        Destination::Stream => stream(path, write).map_err(io_err),
        Destination::Replace(target) => replace(path, &target, temps, write).map_err(io_err),
    }
}

/// Writes into the device or FIFO at `path`, in place.
fn stream(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> io::Result<()> {
    let file = OpenOptions::new().write(true).open(path)?;
    // Made a regular file since it was examined: writing in place would leave it half old.
    if file.metadata()?.is_file() {
        return Err(refuse("changed into a regular file while being opened"));
    }
    let mut out = BufWriter::with_capacity(1 << 16, file);
    write(&mut out)?;
    // No sync: a device or a pipe has nothing to sync, and some refuse the call.
    out.into_inner().map_err(io::IntoInnerError::into_error).map(drop)
}

/// Writes a temporary file beside `target` (`path` with its links resolved) and renames
/// it over `target`.
fn replace(
    path: &Path,
    target: &Path,
    temps: &dyn Temporaries,
    write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> io::Result<()> {
    let tmp = temporary_path(target)?;
    let file = temps.create(&tmp, &mut || File::create_new(&tmp))?;
    let mut out = BufWriter::with_capacity(1 << 16, file);
    let result = write(&mut out)
        .and_then(|()| out.into_inner().map_err(io::IntoInnerError::into_error))
        .and_then(|file| file.sync_all())
        .and_then(|()| {
            temps.finish(&tmp, &mut || {
                // Looked at again just before the rename: the write may have taken minutes,
                // and a rename must never replace anything but a regular file.
                match destination(path)? {
                    Destination::Replace(now) if now == target => fs::rename(&tmp, target),
                    _ => Err(refuse("changed into something other than a regular file")),
                }
            })
        });
    if let Err(e) = result {
        // The temporary may already be gone (removed by a signal's cleanup); either way
        // nothing is left behind.
        let _ = temps.finish(&tmp, &mut || fs::remove_file(&tmp));
        return Err(e);
    }
    Ok(())
}

#[cfg(test)]
mod tests;
