//! Atomic file writes: a temporary file beside the target, then a rename; and the
//! process-wide list of temporary files still alive, so that an interrupted program can
//! remove them ([`remove_temporary_files`]).

use crate::error::{Error, Result};
use std::fs::{self, File};
use std::io::{self, BufWriter};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The temporary files this process has made and not yet renamed or removed.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The registry, even if a thread panicked holding it (a list of paths cannot be left
/// half-updated by a panic).
fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

/// `.<name>.<pid>.<n>.tmp` beside `path`: unique within the process (the counter) and
/// between processes (the pid), and hidden from a plain `ls`.
fn temporary_path(path: &Path) -> io::Result<PathBuf> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file path"))?;
    Ok(path.with_file_name(format!(
        ".{}.{}.{}.tmp",
        name.to_string_lossy(),
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    )))
}

/// Creates `tmp` and registers it, under the registry's lock: an interrupt handler
/// holding the lock then sees the file either not yet made or made and listed.
fn create_registered(tmp: &Path) -> io::Result<File> {
    let mut live = live();
    let file = File::create_new(tmp)?;
    live.push(tmp.to_path_buf());
    Ok(file)
}

/// Removes `tmp` from the registry after running `finish` (a rename or a removal) under
/// the registry's lock, so that an interrupt sees the step either done or not begun.
fn finish_registered<T>(tmp: &Path, finish: impl FnOnce() -> io::Result<T>) -> io::Result<T> {
    let mut live = live();
    let result = finish();
    live.retain(|p| p != tmp);
    result
}

/// Writes `path` atomically: `write` fills a buffered temporary file in the same folder,
/// which is flushed, synced and renamed over `path` only if everything succeeded.
///
/// A failure at any step removes the temporary file and leaves `path` as it was (absent,
/// or its previous content); the error names `path`. While it exists the temporary file
/// is listed for [`remove_temporary_files`].
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> Result<()> {
    let io_err = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let tmp = temporary_path(path).map_err(io_err)?;
    let file = create_registered(&tmp).map_err(io_err)?;
    let mut out = BufWriter::with_capacity(1 << 16, file);
    let result = write(&mut out)
        .and_then(|()| out.into_inner().map_err(io::IntoInnerError::into_error))
        .and_then(|file| file.sync_all())
        .and_then(|()| finish_registered(&tmp, || fs::rename(&tmp, path)));
    if let Err(e) = result {
        // The temporary may already be gone (removed by an interrupt); either way
        // nothing is left behind.
        let _ = finish_registered(&tmp, || fs::remove_file(&tmp));
        return Err(io_err(e));
    }
    Ok(())
}

/// Deletes every temporary file that [`write_atomic`] has open in this process, for a
/// program about to exit early. A write in progress then fails (its rename finds no
/// file) and leaves its target as it was.
pub fn remove_temporary_files() {
    remove_all(&mut live());
}

fn remove_all(live: &mut Vec<PathBuf>) {
    for tmp in live.drain(..) {
        // Already gone is fine: the goal is that it does not exist.
        let _ = fs::remove_file(tmp);
    }
}

/// Installs a Ctrl-C handler (SIGINT on Unix; SIGTERM is left alone) that calls
/// [`remove_temporary_files`] and exits with status 130, the shell's code for a
/// program ended by SIGINT.
///
/// The handler keeps the registry locked until the process has exited, so no write can
/// create a new temporary file or finish a rename after the cleanup.
///
/// # Errors
/// [`Error::Interrupt`] if a handler is already installed or the system refuses one.
#[cfg(feature = "cli")]
pub fn on_interrupt_remove_temporary_files() -> Result<()> {
    ctrlc::set_handler(|| {
        let mut live = live();
        remove_all(&mut live);
        std::process::exit(130);
    })
    .map_err(|e| Error::Interrupt(e.to_string()))
}

/// Checks that files can be written in `dir` before a long render: creates the folder
/// (and its parents) if missing, then creates and removes an empty probe file there.
///
/// # Errors
/// [`Error::Io`] naming `dir` if the folder cannot be made or written to.
pub fn check_writable(dir: &Path) -> Result<()> {
    let io_err = |source: io::Error| Error::Io {
        path: dir.to_path_buf(),
        source: io::Error::new(
            source.kind(),
            format!("cannot write files into this folder: {source}"),
        ),
    };
    fs::create_dir_all(dir).map_err(io_err)?;
    let probe = temporary_path(&dir.join("write-probe")).map_err(io_err)?;
    create_registered(&probe).map_err(io_err)?;
    finish_registered(&probe, || fs::remove_file(&probe)).map_err(io_err)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("raytrace-atomic-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn failed_write_leaves_nothing_and_keeps_the_old_file() {
        let dir = temp_dir("fail");
        let path = dir.join("out.txt");
        fs::write(&path, "old").unwrap();
        let err = write_atomic(&path, |w| {
            w.write_all(b"partial")?;
            Err(io::Error::other("disk full"))
        })
        .unwrap_err();
        assert!(err.to_string().contains("out.txt"), "{err}");
        assert_eq!(fs::read_to_string(&path).unwrap(), "old");
        assert_eq!(
            fs::read_dir(&dir).unwrap().count(),
            1,
            "temporary file left behind"
        );
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn success_replaces_and_missing_folder_is_named() {
        let dir = temp_dir("ok");
        let path = dir.join("out.txt");
        write_atomic(&path, |w| w.write_all(b"new")).unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "new");
        let missing = dir.join("no/such/folder/x.ppm");
        let err = write_atomic(&missing, |w| w.write_all(b"x")).unwrap_err();
        assert!(err.to_string().contains("no/such/folder/x.ppm"), "{err}");
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_finished_write_is_no_longer_registered() {
        let dir = temp_dir("registry");
        let path = dir.join("out.txt");
        let mut seen = None;
        write_atomic(&path, |w| {
            // Other tests write concurrently: look for this write's own file only.
            seen = live().iter().find(|p| p.starts_with(&dir)).cloned();
            w.write_all(b"x")
        })
        .unwrap();
        let tmp = seen.expect("the temporary file was not registered during the write");
        assert!(!live().contains(&tmp), "{} still registered", tmp.display());
        assert!(!tmp.exists());
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn writable_folder_is_created_and_left_clean() {
        let dir = temp_dir("writable").join("new/sub");
        check_writable(&dir).unwrap();
        assert!(dir.is_dir());
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 0, "probe file left behind");
        fs::remove_dir_all(dir.parent().unwrap().parent().unwrap()).unwrap();
    }

    #[test]
    fn unwritable_folder_is_named() {
        let dir = temp_dir("unwritable");
        // A folder under a regular file cannot exist, even for root.
        let file = dir.join("plain-file");
        fs::write(&file, "").unwrap();
        let under_file = file.join("out");
        let err = check_writable(&under_file).unwrap_err();
        assert!(err.to_string().contains("plain-file/out"), "{err}");
        fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn read_only_folder_is_refused() {
        use std::os::unix::fs::PermissionsExt;
        let dir = temp_dir("read-only");
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o555)).unwrap();
        // Root ignores permissions: find out by trying, and skip if so.
        let root = File::create_new(dir.join("probe")).is_ok();
        let result = check_writable(&dir);
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o755)).unwrap();
        if !root {
            let err = result.unwrap_err();
            assert!(err.to_string().contains("raytrace-atomic-read-only"), "{err}");
        }
        fs::remove_dir_all(dir).unwrap();
    }
}
