//! Nothing half-written is left behind: removing the registered temporary files makes a
//! write in progress fail cleanly, and (with feature `cli`) Ctrl-C during a write leaves
//! no temporary file. Both run in a child process (this test binary again, running one
//! test), because `remove_temporary_files` acts on the whole process and would break the
//! other tests' writes.

use raytrace::image::{remove_temporary_files, write_atomic};
use std::io::Write;
use std::path::{Path, PathBuf};

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-interrupt-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The names of the temporary files in `dir`.
fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".tmp"))
        .collect()
}

/// Set in the child process that [`removal_during_a_write_leaves_nothing`] starts.
const CHILD_REGISTRY: &str = "RAYTRACE_TEST_REGISTRY_CHILD";

#[test]
fn removal_during_a_write_leaves_nothing() {
    let status = std::process::Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "interrupt::child_removes_during_a_write",
            "--test-threads=1",
        ])
        .env(CHILD_REGISTRY, "1")
        .output()
        .unwrap();
    assert!(
        status.status.success() && String::from_utf8_lossy(&status.stdout).contains("1 passed"),
        "the child failed: {}\n{}",
        String::from_utf8_lossy(&status.stdout),
        String::from_utf8_lossy(&status.stderr)
    );
}

/// Only does anything as the child of [`removal_during_a_write_leaves_nothing`].
#[test]
fn child_removes_during_a_write() {
    if std::env::var_os(CHILD_REGISTRY).is_none() {
        return;
    }
    let dir = temp_dir("registry");
    let path = dir.join("out.txt");
    let err = write_atomic(&path, |w| {
        w.write_all(b"first half")?;
        w.flush()?;
        assert_eq!(temporaries(&dir).len(), 1, "the write has no temporary file");
        remove_temporary_files();
        assert_eq!(temporaries(&dir), Vec::<String>::new());
        w.write_all(b"second half")
    })
    .unwrap_err();
    assert!(err.to_string().contains("out.txt"), "{err}");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "something was left behind"
    );

    // A write after that works, and is not undone by a later removal.
    write_atomic(&path, |w| w.write_all(b"whole")).unwrap();
    remove_temporary_files();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "whole");
    std::fs::remove_dir_all(dir).unwrap();
}

/// Set in the child process [`ctrl_c_leaves_no_temporary_file`] starts: the folder that
/// [`child_writes_until_interrupted`] writes into.
#[cfg(feature = "cli")]
const CHILD_DIR: &str = "RAYTRACE_TEST_INTERRUPT_DIR";

/// Only does anything as the child of [`ctrl_c_leaves_no_temporary_file`]: installs the
/// handler, then writes a 12 MB PFM over and over until interrupted.
#[cfg(feature = "cli")]
#[test]
fn child_writes_until_interrupted() {
    let Some(dir) = std::env::var_os(CHILD_DIR) else {
        return;
    };
    raytrace::image::on_interrupt_remove_temporary_files().unwrap();
    let image = raytrace::Image::new(1000, 1000).unwrap();
    let path = Path::new(&dir).join("big.pfm");
    loop {
        raytrace::image::write_pfm(&path, &image).unwrap();
    }
}

#[cfg(all(feature = "cli", unix))]
#[test]
fn ctrl_c_leaves_no_temporary_file() {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let dir = temp_dir("sigint");
    // This test binary again, running only the writer.
    let mut child = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "interrupt::child_writes_until_interrupted",
            "--test-threads=1",
        ])
        .env(CHILD_DIR, &dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Signal only once a write is under way: its temporary file exists.
    let deadline = Instant::now() + Duration::from_secs(120);
    while temporaries(&dir).is_empty() {
        if let Some(status) = child.try_wait().unwrap() {
            panic!("the writer exited before writing: {status}");
        }
        if Instant::now() > deadline {
            child.kill().unwrap();
            panic!("the writer made no temporary file in 120 s");
        }
        std::thread::sleep(Duration::from_millis(1));
    }
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success(), "kill -INT failed: {kill}");
    let status = child.wait().unwrap();
    assert_eq!(
        status.code(),
        Some(130),
        "the writer did not exit through the handler: {status}"
    );
    assert_eq!(
        temporaries(&dir),
        Vec::<String>::new(),
        "temporary file left behind"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
