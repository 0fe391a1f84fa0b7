//! The `raytrace` binary as a user runs it: renders, tiles in separate processes, and every
//! kind of bad input, each with its exit code and a message that says what is wrong.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

/// A fresh folder for one test.
fn folder(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-cli-{test}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("the binary runs")
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

/// Asserts the exit code and that the output contains every one of `words`.
fn expect(o: &Output, code: i32, words: &[&str]) {
    let t = text(o);
    assert_eq!(o.status.code(), Some(code), "{t}");
    for w in words {
        assert!(t.contains(w), "missing `{w}` in: {t}");
    }
}

#[test]
fn four_tiles_in_four_processes_merge_to_the_whole_render() {
    let dir = folder("tiles");
    let s = scene("matte_spheres.toml");
    let s = s.to_str().unwrap();
    let common = ["--width", "64", "--spp", "3", "--quiet"];
    let whole = dir.join("whole.ppm");
    let o = run(&[&["render", s, "--out", whole.to_str().unwrap()], &common[..]].concat());
    expect(&o, 0, &["wrote"]);
    let children: Vec<_> = (1..=4)
        .map(|k| {
            let tile = dir.join(format!("t{k}.rtile"));
            let tile_arg = format!("{k}/4");
            let args = [
                &["render", s, "--tile", &tile_arg, "--out", tile.to_str().unwrap()],
                &common[..],
            ]
            .concat();
            Command::new(BIN).args(&args).output().expect("a tile renders")
        })
        .collect();
    for o in &children {
        expect(o, 0, &["wrote"]);
    }
    let merged = dir.join("merged.ppm");
    // The tiles in another order than rendered: the merge places them by their rectangles.
    let tiles: Vec<String> = [3, 1, 4, 2]
        .iter()
        .map(|k| dir.join(format!("t{k}.rtile")).to_string_lossy().into_owned())
        .collect();
    let mut args = vec!["merge", "--out", merged.to_str().unwrap()];
    args.extend(tiles.iter().map(String::as_str));
    expect(&run(&args), 0, &["4 tiles"]);
    assert_eq!(fs::read(&whole).unwrap(), fs::read(&merged).unwrap());

    // Three of four tiles do not make the image.
    let mut args = vec!["merge", "--out", merged.to_str().unwrap()];
    args.extend(tiles[..3].iter().map(String::as_str));
    expect(&run(&args), 1, &["tiles"]);
    // Nor do tiles of another seed.
    let other = dir.join("other.rtile");
    let o = run(&[
        &[
            "render",
            s,
            "--tile",
            "2/4",
            "--seed",
            "9",
            "--out",
            other.to_str().unwrap(),
        ],
        &common[..],
    ]
    .concat());
    expect(&o, 0, &[]);
    let mut args = vec![
        "merge",
        "--out",
        merged.to_str().unwrap(),
        &tiles[0],
        &tiles[1],
        &tiles[2],
    ];
    args.push(other.to_str().unwrap());
    expect(&run(&args), 1, &["tiles"]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn every_format_is_written_and_names_carry_the_settings() {
    let dir = folder("formats");
    let s = scene("four_mirrors.toml");
    for ext in ["ppm", "png", "exr", "pfm"] {
        let out = dir.join(format!("a.{ext}"));
        let o = run(&[
            "render",
            s.to_str().unwrap(),
            "--width",
            "32",
            "--quiet",
            "--out",
            out.to_str().unwrap(),
        ]);
        expect(&o, 0, &["wrote"]);
        assert!(fs::metadata(&out).unwrap().len() > 0);
    }
    // Without --out the name says what was rendered, in the current folder.
    let o = Command::new(BIN)
        .args([
            "render",
            s.to_str().unwrap(),
            "--width",
            "32",
            "--spp",
            "2",
            "--quiet",
        ])
        .current_dir(&dir)
        .output()
        .unwrap();
    expect(&o, 0, &["four_mirrors-w32-2spp"]);
    let names: Vec<String> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        names
            .iter()
            .any(|n| n.starts_with("four_mirrors-w32-2spp") && n.ends_with(".png")),
        "{names:?}"
    );
    assert!(!names.iter().any(|n| n.ends_with(".tmp")), "{names:?}");
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn check_and_advise_describe_the_scene() {
    let s = scene("plane_and_triangles.toml");
    expect(
        &run(&["check", s.to_str().unwrap()]),
        0,
        &["valid", "planes", "triangles", "acceleration", "emitters: none"],
    );
    let s = scene("cornell_box.toml");
    expect(
        &run(&["check", s.to_str().unwrap()]),
        0,
        &[
            "valid",
            "36 triangles (meshes: 8)",
            "emitters: 1 objects give off light, 1 of them sampled",
        ],
    );
    let dir = folder("cornell");
    let out = dir.join("cornell.png");
    let args = [
        "render",
        s.to_str().unwrap(),
        "--width",
        "16",
        "--spp",
        "2",
        "--quiet",
        "--out",
    ];
    expect(&run(&[&args[..], &[out.to_str().unwrap()]].concat()), 0, &[]);
    assert!(out.exists());
    fs::remove_dir_all(dir).unwrap();
    let s = scene("four_mirrors.toml");
    expect(&run(&["advise", s.to_str().unwrap()]), 0, &["advice: f32"]);
    expect(&run(&["--version"]), 0, &[env!("CARGO_PKG_VERSION")]);
}

#[test]
fn bad_input_is_a_clear_error_with_the_right_exit_code() {
    let dir = folder("bad");
    let s = scene("four_mirrors.toml");
    let s = s.to_str().unwrap();
    // Usage errors: 2.
    expect(&run(&["render", s, "--threads", "100000"]), 2, &["--threads"]);
    expect(&run(&["render", s, "--threads", "0"]), 2, &["--threads"]);
    expect(&run(&["render", s, "--width", "0"]), 2, &["--width"]);
    expect(&run(&["render", s, "--tile", "5/4"]), 2, &["--tile"]);
    expect(&run(&["render"]), 2, &["SCENE"]);
    // Failures: 1, naming what failed.
    let missing = dir.join("missing.toml");
    expect(&run(&["render", missing.to_str().unwrap()]), 1, &["missing.toml"]);
    let broken = dir.join("broken.toml");
    fs::write(&broken, "[render]\nwidth = 10\nspp = [\n").unwrap();
    expect(
        &run(&["check", broken.to_str().unwrap()]),
        1,
        &["broken.toml", "line"],
    );
    let unknown = dir.join("unknown.toml");
    fs::write(&unknown, "[render]\nwidht = 10\n").unwrap();
    expect(
        &run(&["check", unknown.to_str().unwrap()]),
        1,
        &["unknown.toml", "widht"],
    );
    // An unwritable output fails before the render (a folder under a regular file cannot
    // exist, for root too).
    let file = dir.join("a-file");
    fs::write(&file, "").unwrap();
    let out = file.join("x.png");
    expect(
        &run(&["render", s, "--out", out.to_str().unwrap()]),
        1,
        &["a-file"],
    );
    // An image too large for memory is refused before allocating, not aborted.
    expect(
        &run(&["render", s, "--width", "1000000", "--quiet"]),
        1,
        &["pixels"],
    );
    // A format the name contradicts is a usage error.
    let png = dir.join("x.png");
    expect(
        &run(&["render", s, "--format", "exr", "--out", png.to_str().unwrap()]),
        2,
        &["--format"],
    );
    let left: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 3, "only the test's own three files remain: {left:?}");
    fs::remove_dir_all(dir).unwrap();
}
