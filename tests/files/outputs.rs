//! Where `raytrace` writes, when the output is not a plain new file: standard output, a
//! FIFO, a symbolic link, a name of 243 to 255 bytes, folders that do not exist yet. Each
//! writes the bytes a plain file gets, and leaves nothing else behind.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/matte_spheres.toml")
}

fn folder(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-outputs-{test}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// `raytrace render` of the scene, 24 pixels wide, 2 samples, with `args` after (run in
/// the temporary folder: a binary that took `-` for a name would leave its file there).
fn render(args: &[&str]) -> Output {
    let o = Command::new(BIN)
        .args([
            "render",
            scene().to_str().unwrap(),
            "--width",
            "24",
            "--spp",
            "2",
            "--quiet",
        ])
        .args(args)
        .current_dir(std::env::temp_dir())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    o
}

/// The bytes of a plain render into `dir/name`.
fn plain(dir: &Path, name: &str, args: &[&str]) -> Vec<u8> {
    let path = dir.join(name);
    render(&[args, &["--out", path.to_str().unwrap()]].concat());
    let bytes = fs::read(&path).unwrap();
    fs::remove_file(path).unwrap();
    bytes
}

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn standard_output_gets_the_files_bytes_and_the_summary_goes_to_stderr() {
    let dir = folder("stdout");
    for format in ["png", "ppm", "exr", "pfm"] {
        let o = render(&["--format", format, "--out", "-"]);
        let want = plain(&dir, &format!("x.{format}"), &[]);
        assert!(
            o.stdout == want,
            "{format}: standard output differs from the file"
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("wrote standard output"), "{format}: {err}");
    }
    // A tile too, which then merges.
    let o = render(&["--tile", "1/1", "--out", "-"]);
    fs::write(dir.join("t.rtile"), &o.stdout).unwrap();
    let merged = dir.join("m.png");
    let m = Command::new(BIN)
        .args([
            "merge",
            dir.join("t.rtile").to_str().unwrap(),
            "--out",
            merged.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(m.status.success(), "{}", String::from_utf8_lossy(&m.stderr));
    assert_eq!(fs::read(&merged).unwrap(), plain(&dir, "whole.png", &[]));
    fs::remove_dir_all(dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_fifo_is_streamed_into_and_stays_a_fifo() {
    use std::os::unix::fs::FileTypeExt;
    use std::time::{Duration, Instant};
    let dir = folder("fifo");
    let fifo = dir.join("pipe.png");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    // The reader is a process, so that it can be stopped if nothing ever writes into the
    // FIFO (as when a rename replaced it).
    let mut reader = Command::new("cat")
        .arg(&fifo)
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    render(&["--out", fifo.to_str().unwrap()]);
    let deadline = Instant::now() + Duration::from_secs(30);
    while reader.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            reader.kill().unwrap();
            panic!("nothing was written into the FIFO");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    let bytes = reader.wait_with_output().unwrap().stdout;
    assert!(
        fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(),
        "the FIFO was replaced"
    );
    assert_eq!(names(&dir), ["pipe.png"]);
    assert!(bytes == plain(&dir, "x.png", &[]), "the FIFO got other bytes");
    fs::remove_dir_all(dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_is_written_through_and_stays_a_link() {
    let dir = folder("symlink");
    fs::create_dir(dir.join("real")).unwrap();
    fs::write(dir.join("real/latest.png"), "old").unwrap();
    std::os::unix::fs::symlink("real/latest.png", dir.join("latest.png")).unwrap();
    render(&["--out", dir.join("latest.png").to_str().unwrap()]);
    assert!(
        fs::symlink_metadata(dir.join("latest.png"))
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(
        fs::read(dir.join("real/latest.png")).unwrap(),
        plain(&dir, "x.png", &[])
    );
    assert_eq!(names(&dir.join("real")), ["latest.png"]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn names_up_to_255_bytes_are_written() {
    let dir = folder("long");
    let want = plain(&dir, "x.png", &[]);
    for len in [243, 249, 255] {
        let name = format!("{}.png", "n".repeat(len - 4));
        render(&["--out", dir.join(&name).to_str().unwrap()]);
        assert_eq!(names(&dir), std::slice::from_ref(&name), "{len} bytes");
        assert!(fs::read(dir.join(&name)).unwrap() == want);
        fs::remove_file(dir.join(name)).unwrap();
    }
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn missing_folders_are_made_as_mkdir_p_does() {
    let dir = folder("mkdir");
    let out = dir.join("new/sub/x.png");
    render(&["--out", out.to_str().unwrap()]);
    assert_eq!(fs::read(&out).unwrap(), plain(&dir, "x.png", &[]));
    assert_eq!(names(&dir.join("new/sub")), ["x.png"]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn tiles_of_a_mesh_scene_merge_to_the_whole_render() {
    let dir = folder("mesh-tiles");
    let cornell = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.toml");
    let run = |args: &[&str]| {
        let o = Command::new(BIN)
            .args([
                "render",
                cornell.to_str().unwrap(),
                "--width",
                "16",
                "--spp",
                "2",
                "--quiet",
            ])
            .args(args)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    let whole = dir.join("whole.png");
    run(&["--out", whole.to_str().unwrap()]);
    let tiles: Vec<String> = (1..=2)
        .map(|k| {
            let t = dir.join(format!("t{k}.rtile"));
            run(&["--tile", &format!("{k}/2"), "--out", t.to_str().unwrap()]);
            t.to_string_lossy().into_owned()
        })
        .collect();
    let merged = dir.join("merged.png");
    let o = Command::new(BIN)
        .args(["merge", &tiles[0], &tiles[1], "--out", merged.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(fs::read(whole).unwrap(), fs::read(merged).unwrap());
    fs::remove_dir_all(dir).unwrap();
}

/// On a terminal (a pseudo-terminal from util-linux's `script`), the progress bar is drawn
/// before the first band of rows is done, and a spinner says what is being written.
#[cfg(unix)]
#[test]
fn a_terminal_sees_the_bar_at_once_and_the_write() {
    let dir = folder("terminal");
    let out = dir.join("x.png");
    let command = format!(
        "{BIN} render {} --width 64 --spp 2 --out {}",
        scene().display(),
        out.display()
    );
    let Ok(o) = Command::new("script")
        .args(["-qec", &command, "/dev/null"])
        .output()
    else {
        eprintln!("note: util-linux's `script` is missing: the terminal test is skipped");
        return;
    };
    let screen = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{screen}");
    let first = screen.find(" rows").expect("no progress bar");
    assert!(
        screen[..first].ends_with(" 0/32"),
        "the first bar drawn is not at 0 rows: {screen}"
    );
    assert!(
        screen.contains(&format!("writing {} (png)", out.display())),
        "{screen}"
    );
    assert!(out.exists());
    fs::remove_dir_all(dir).unwrap();
}
