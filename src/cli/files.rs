//! Output files for a program that signals may stop: the process-wide list of temporary
//! files and created folders still alive, so that [`remove_temporary_files`] (and the
//! signal handler) can remove them. Once any function here has run, every
//! [`image::write_atomic`](crate::image::write_atomic) in the process (and so every
//! `image::write_*`) lists its temporary file here.

use crate::error::{Error, Result};
use crate::image::atomic::{Destination, TRACKER, Temporaries, destination, temporary_path};
use std::fs::{self, File};
use std::io::{self, BufWriter};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// What this process has made and may have to remove.
pub(super) struct Registry {
    /// Temporary files not yet renamed or removed.
    temporaries: Vec<PathBuf>,
    /// Folders created, in the order they were made: removed again (if still empty) when
    /// the write they were made for fails, or on a signal.
    folders: Vec<PathBuf>,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry {
    temporaries: Vec::new(),
    folders: Vec::new(),
});

/// The registry, even if a thread panicked holding it (a list of paths cannot be left
/// half-updated by a panic).
pub(super) fn registry() -> MutexGuard<'static, Registry> {
    REGISTRY.lock().unwrap_or_else(PoisonError::into_inner)
}

impl Registry {
    /// Removes every temporary file, then every created folder that is empty, deepest
    /// first. Returns the temporary files removed.
    pub(super) fn clean(&mut self) -> Vec<PathBuf> {
        let removed: Vec<PathBuf> = self
            .temporaries
            .drain(..)
            // Already gone is fine: the goal is that it does not exist.
            .filter(|tmp| fs::remove_file(tmp).is_ok())
            .collect();
        for folder in self.folders.drain(..).rev() {
            // A folder something was written into stays.
            let _ = fs::remove_dir(folder);
        }
        removed
    }
}

/// Each step of an atomic write under the registry's lock: a cleanup holding the lock sees
/// the temporary file either not yet made or made and listed, renamed or not.
struct Tracked;

/// Hooks the registry into every atomic write of the process (once; later calls do nothing).
pub(super) fn track() {
    static TRACKED: Tracked = Tracked;
    let _ = TRACKER.set(&TRACKED);
}

impl Temporaries for Tracked {
    fn create(&self, tmp: &Path, create: &mut dyn FnMut() -> io::Result<File>) -> io::Result<File> {
        let mut registry = registry();
        let file = create()?;
        registry.temporaries.push(tmp.to_path_buf());
        Ok(file)
    }

    fn finish(&self, tmp: &Path, finish: &mut dyn FnMut() -> io::Result<()>) -> io::Result<()> {
        let mut registry = registry();
        let result = finish();
        registry.temporaries.retain(|p| p != tmp);
        result
    }
}

/// Writes `path` atomically, as [`crate::image::write_atomic`] does (the same rules for
/// links, devices and FIFOs), listed for [`remove_temporary_files`] while unfinished.
/// Missing folders on the way to `path` are created first, as `mkdir -p` would; if the
/// write fails they are removed again.
///
/// # Errors
/// [`Error::Io`] naming `path`, or the folder that could not be created.
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> Result<()> {
    write_file(path, |path| crate::image::write_atomic(path, write))
}

/// Runs `write`, which writes `path` with one of the library's writers (`image::write_png`,
/// `write_tile`, …), after creating the missing folders on the way to `path` (`mkdir -p`),
/// which are removed again if `write` fails. The writer's temporary file is listed for
/// [`remove_temporary_files`] while unfinished.
///
/// # Errors
/// `write`'s error, or [`Error::Io`] naming the folder that could not be created.
pub fn write_file(path: &Path, write: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    track();
    let created = create_folders(folder(path))?;
    let result = write(path);
    if result.is_err() {
        let mut registry = registry();
        for f in created.iter().rev() {
            let _ = fs::remove_dir(f);
        }
        registry.folders.retain(|f| !created.contains(f));
    }
    result
}

/// Creates the folders missing on the way to `dir`, listing each under the registry's
/// lock; returns them, outermost first.
fn create_folders(dir: &Path) -> Result<Vec<PathBuf>> {
    let missing: Vec<&Path> = dir
        .ancestors()
        .take_while(|a| !a.as_os_str().is_empty() && fs::symlink_metadata(a).is_err())
        .collect();
    let mut created = Vec::new();
    for folder in missing.into_iter().rev() {
        let mut registry = registry();
        match fs::create_dir(folder) {
            Ok(()) => {
                registry.folders.push(folder.to_path_buf());
                created.push(folder.to_path_buf());
            }
            // Made meanwhile by someone else: theirs, not ours to remove.
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
            Err(source) => {
                for f in created.iter().rev() {
                    let _ = fs::remove_dir(f);
                }
                registry.folders.retain(|f| !created.contains(f));
                return Err(Error::Io {
                    path: folder.to_path_buf(),
                    source: io::Error::new(source.kind(), format!("cannot create this folder: {source}")),
                });
            }
        }
    }
    Ok(created)
}

/// Checks, before a long render, that [`write_atomic`] can write `path`: the target is one
/// it writes (not a folder, a block device, a socket or a link to nothing), and the
/// nearest existing folder on the way to it is a folder where files can be made (a probe
/// file is created there and removed). Creates no folder: [`write_atomic`] does that
/// once there is something to write.
///
/// # Errors
/// [`Error::Io`] naming `path` and saying what is in the way.
pub fn check_output(path: &Path) -> Result<()> {
    track();
    let io_err = |source: io::Error| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    // The folders first: under a file, the target's own error would be a bare "Not a
    // directory".
    let existing = folder(path)
        .ancestors()
        .find(|a| a.as_os_str().is_empty() || fs::symlink_metadata(a).is_ok())
        .map(|a| {
            if a.as_os_str().is_empty() {
                Path::new(".")
            } else {
                a
            }
        })
        .unwrap_or(Path::new("."));
    let in_the_way = |what: String| io_err(io::Error::new(io::ErrorKind::NotADirectory, what));
    match fs::metadata(existing) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => {
            return Err(in_the_way(format!(
                "{} is a file, not a folder",
                existing.display()
            )));
        }
        Err(e) => return Err(in_the_way(format!("{}: {e}", existing.display()))),
    }
    let probe_in = match destination(path).map_err(io_err)? {
        Destination::Stream => return Ok(()),
        // A link may lead into another folder: that is where the file is made.
        Destination::Replace(target) if target != path => folder(&target).to_path_buf(),
        Destination::Replace(_) => existing.to_path_buf(),
    };
    let probe = temporary_path(&probe_in.join("write-probe")).map_err(io_err)?;
    let cannot = |e: io::Error| {
        io_err(io::Error::new(
            e.kind(),
            format!("cannot write files into {}: {e}", probe_in.display()),
        ))
    };
    Tracked
        .create(&probe, &mut || File::create_new(&probe))
        .map_err(cannot)?;
    Tracked
        .finish(&probe, &mut || fs::remove_file(&probe))
        .map_err(cannot)
}

/// Deletes every temporary file that [`write_atomic`] has open in this process, and every
/// folder it created that is still empty, for a program about to exit early. A write in
/// progress then fails (its rename finds no file) and leaves its target as it was.
pub fn remove_temporary_files() {
    track();
    registry().clean();
}

/// The folder a file goes into (`.` for a bare name).
fn folder(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

#[cfg(test)]
mod tests;
