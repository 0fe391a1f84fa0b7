//! Nothing half-written is left behind: removing the registered temporary files makes a
//! write in progress fail cleanly, and SIGINT, SIGTERM and SIGHUP during a write leave no
//! temporary file, exit with 128 + the signal and say what was stopped. The library's
//! side runs in a child process (this test binary again, running one test), because
//! `remove_temporary_files` and the handler act on the whole process and would break
//! the other tests' writes; the binary's side runs `raytrace render` and `merge`.

use raytrace::cli::{remove_temporary_files, write_atomic};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-interrupt-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// The names of the temporary files in `dir`.
fn temporaries(dir: &Path) -> Vec<String> {
    names(dir).into_iter().filter(|n| n.ends_with(".tmp")).collect()
}

/// Set in the child process that [`removal_during_a_write_leaves_nothing`] starts.
const CHILD_REGISTRY: &str = "RAYTRACE_TEST_REGISTRY_CHILD";

#[test]
fn removal_during_a_write_leaves_nothing() {
    let status = Command::new(std::env::current_exe().unwrap())
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
    // A folder the write makes is removed with its temporary file.
    let path = dir.join("new/out.txt");
    let err = write_atomic(&path, |w| {
        w.write_all(b"first half")?;
        w.flush()?;
        assert_eq!(
            temporaries(&dir.join("new")).len(),
            1,
            "the write has no temporary file"
        );
        remove_temporary_files();
        assert_eq!(names(&dir), Vec::<String>::new());
        w.write_all(b"second half")
    })
    .unwrap_err();
    assert!(err.to_string().contains("out.txt"), "{err}");
    assert_eq!(names(&dir), Vec::<String>::new(), "something was left behind");

    // A write after that works, and is not undone by a later removal.
    write_atomic(&path, |w| w.write_all(b"whole")).unwrap();
    remove_temporary_files();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "whole");
    std::fs::remove_dir_all(dir).unwrap();
}

/// Set in the child process [`signals_leave_no_temporary_file`] starts: the folder that
/// [`child_writes_until_signalled`] writes into.
const CHILD_DIR: &str = "RAYTRACE_TEST_INTERRUPT_DIR";

/// Only does anything as a child of [`signals_leave_no_temporary_file`]: installs the
/// handler, then writes a 12 MB PFM over and over (through the library's own writer, which
/// the handler's registry tracks) until a signal stops it.
#[test]
fn child_writes_until_signalled() {
    let Some(dir) = std::env::var_os(CHILD_DIR) else {
        return;
    };
    raytrace::cli::clean_up_on_signals("writer").unwrap();
    raytrace::cli::set_activity("writing big.pfm");
    let image = raytrace::Image::new(1000, 1000).unwrap();
    let path = Path::new(&dir).join("big.pfm");
    loop {
        raytrace::image::write_pfm(&path, &image).unwrap();
    }
}

/// Sends `signal` (`INT`, `TERM`, `HUP`) to `child`.
fn send(child: &Child, signal: &str) {
    let kill = Command::new("kill")
        .args([&format!("-{signal}"), &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success(), "kill -{signal} failed: {kill}");
}

/// Waits until `ready()` holds, failing if `child` exits first or 120 s pass.
fn wait_for(child: &mut Child, what: &str, ready: impl Fn() -> bool) -> Result<(), String> {
    let deadline = Instant::now() + Duration::from_secs(120);
    while !ready() {
        if let Some(status) = child.try_wait().unwrap() {
            return Err(format!("exited ({status}) before {what}"));
        }
        if Instant::now() > deadline {
            child.kill().unwrap();
            panic!("no {what} in 120 s");
        }
        std::thread::sleep(Duration::from_millis(1));
    }
    Ok(())
}

/// Asserts that `out` is the exit of a program stopped by `signal` (number `n`) with the
/// message saying so.
fn stopped(out: &Output, signal: &str, n: i32, words: &[&str]) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(128 + n),
        "not stopped by the handler: {}: {err}",
        out.status
    );
    for w in [&format!("stopped by SIG{signal}"), "nothing was left behind"]
        .into_iter()
        .chain(words.iter().copied())
    {
        assert!(err.contains(w), "missing `{w}` in: {err}");
    }
}

#[cfg(unix)]
#[test]
fn signals_leave_no_temporary_file() {
    for (signal, n) in [("INT", 2), ("TERM", 15), ("HUP", 1)] {
        let dir = temp_dir(&format!("sig{signal}"));
        // This test binary again, running only the writer.
        let mut child = Command::new(std::env::current_exe().unwrap())
            .args([
                "--exact",
                "interrupt::child_writes_until_signalled",
                "--test-threads=1",
                "--nocapture",
            ])
            .env(CHILD_DIR, &dir)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Signal only once a write is under way: its temporary file exists.
        wait_for(&mut child, "a temporary file", || !temporaries(&dir).is_empty()).unwrap();
        send(&child, signal);
        let out = child.wait_with_output().unwrap();
        stopped(
            &out,
            signal,
            n,
            &["writer:", "while writing big.pfm", "removed the unfinished"],
        );
        assert_eq!(
            temporaries(&dir),
            Vec::<String>::new(),
            "SIG{signal}: temporary file left behind"
        );
        std::fs::remove_dir_all(dir).unwrap();
    }
}

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

/// Whether process `pid` catches SIGTERM (bit 15 of `SigCgt` in `/proc/PID/status`): its
/// handler is installed.
fn catches_sigterm(pid: u32) -> bool {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("SigCgt:"))
        .and_then(|mask| u64::from_str_radix(mask.trim(), 16).ok())
        .is_some_and(|mask| mask & (1 << 14) != 0)
}

/// How many threads process `pid` runs.
fn threads(pid: u32) -> usize {
    std::fs::read_dir(format!("/proc/{pid}/task")).map_or(0, Iterator::count)
}

#[cfg(target_os = "linux")]
#[test]
fn a_render_stopped_by_a_signal_leaves_nothing_and_says_so() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/matte_spheres.toml");
    for (signal, n) in [("TERM", 15), ("HUP", 1), ("INT", 2)] {
        let dir = temp_dir(&format!("render-{signal}"));
        let out = dir.join("new/sub/x.png");
        // A render of minutes, stopped once it renders: its handler is in place, and the
        // worker threads (more than the main thread and the handler's) have started.
        let mut child = Command::new(BIN)
            .args([
                "render",
                scene.to_str().unwrap(),
                "--spp",
                "5000",
                "--width",
                "800",
            ])
            .arg("--out")
            .arg(&out)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let pid = child.id();
        wait_for(&mut child, "the render", || {
            catches_sigterm(pid) && threads(pid) > 2
        })
        .unwrap();
        send(&child, signal);
        let output = child.wait_with_output().unwrap();
        stopped(
            &output,
            signal,
            n,
            &["raytrace:", "while rendering", "matte_spheres.toml", "x.png"],
        );
        assert_eq!(
            names(&dir),
            Vec::<String>::new(),
            "SIG{signal}: folders or a file were left"
        );
        std::fs::remove_dir_all(dir).unwrap();
    }
}

/// Writes two tiles of a `width × height` image of noise, for a merge that takes a while
/// to write as a plain PPM.
fn big_tiles(dir: &Path, width: usize, height: usize) -> Vec<PathBuf> {
    use raytrace::image::{TileHeader, write_tile};
    (0..2)
        .map(|k| {
            let rect = raytrace::Rect::tile(k, 2, width, height).unwrap();
            let pixels = (0..rect.width * rect.height)
                .map(|i| [(i % 997) as f64 / 997.0, (i % 13) as f64 / 13.0, 0.5])
                .collect();
            let image = raytrace::Image::from_pixels(rect.width, rect.height, pixels).unwrap();
            let header = TileHeader {
                scene: "abc".into(),
                settings: "test".into(),
                image_width: width,
                image_height: height,
                rect,
            };
            let path = dir.join(format!("t{k}.rtile"));
            write_tile(&path, &header, &image).unwrap();
            path
        })
        .collect()
}

#[cfg(unix)]
#[test]
fn a_merge_stopped_while_writing_leaves_nothing_and_says_so() {
    for (signal, n) in [("HUP", 1), ("TERM", 15), ("INT", 2)] {
        let (dir, tiles) = (
            temp_dir(&format!("merge-{signal}")),
            temp_dir(&format!("merge-{signal}-tiles")),
        );
        merge_until_signalled(&dir, &tiles, signal, n);
        std::fs::remove_dir_all(dir).unwrap();
        std::fs::remove_dir_all(tiles).unwrap();
    }
}

/// Merges tiles into `dir/x.ppm`, sends `signal` once the image's temporary file exists,
/// and checks the exit and that nothing is left. A write so quick that it ends before the
/// poll sees its file is tried again, larger.
fn merge_until_signalled(dir: &Path, tiles: &Path, signal: &str, n: i32) {
    for height in [600, 1200, 2400] {
        let paths = big_tiles(tiles, 2 * height, height);
        let mut child = Command::new(BIN)
            .args(["merge", "--out"])
            .arg(dir.join("x.ppm"))
            .args(&paths)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // The image's own temporary file, not the probe that checks the folder is writable.
        let writing = || temporaries(dir).iter().any(|n| n.starts_with(".x.ppm."));
        if wait_for(&mut child, "the image's temporary file", writing).is_err() {
            std::fs::remove_file(dir.join("x.ppm")).unwrap();
            continue;
        }
        send(&child, signal);
        let output = child.wait_with_output().unwrap();
        if output.status.success() {
            // The write ended between the poll and the signal (a loaded machine): the
            // image is whole; try again, larger.
            std::fs::remove_file(dir.join("x.ppm")).unwrap();
            continue;
        }
        stopped(
            &output,
            signal,
            n,
            &["while writing", "x.ppm", "removed the unfinished"],
        );
        assert_eq!(names(dir), Vec::<String>::new(), "SIG{signal}: a file was left");
        return;
    }
    panic!("SIG{signal}: every merge finished before its temporary file was seen");
}
