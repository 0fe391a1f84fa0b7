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

/// The files `raytrace render SCENE ARGS…` writes without `--out`, in a fresh folder.
fn default_names(test: &str, runs: &[&[&str]]) -> Vec<String> {
    let dir = folder(test);
    let s = scene("matte_spheres.toml");
    for args in runs {
        let o = Command::new(BIN)
            .args(
                [
                    &[
                        "render",
                        s.to_str().unwrap(),
                        "--width",
                        "24",
                        "--spp",
                        "2",
                        "--quiet",
                    ],
                    *args,
                ]
                .concat(),
            )
            .current_dir(&dir)
            .output()
            .unwrap();
        expect(&o, 0, &["wrote"]);
    }
    let mut names: Vec<String> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    fs::remove_dir_all(dir).unwrap();
    names
}

#[test]
fn default_names_carry_the_precision_and_a_linear_encoding() {
    let names = default_names(
        "names",
        &[
            &["--precision", "f32"],
            &["--encoding", "linear"],
            &[],
            &["--format", "exr", "--encoding", "linear"],
            &["--tile", "1/2", "--precision", "f32"],
        ],
    );
    assert_eq!(
        names,
        [
            "matte_spheres-w24-2spp-d10-seed0-f32-tile1of2.rtile",
            "matte_spheres-w24-2spp-d10-seed0-f32.png",
            "matte_spheres-w24-2spp-d10-seed0-f64-linear.png",
            "matte_spheres-w24-2spp-d10-seed0-f64.exr",
            "matte_spheres-w24-2spp-d10-seed0-f64.png",
        ],
        "five renders, five files: none overwrote another"
    );
}

#[test]
fn default_names_carry_the_exposure_and_tone_curve_of_pictures_only() {
    let names = default_names(
        "tonemap-names",
        &[
            &[],
            &["--exposure", "1.5"],
            &["--tonemap", "aces"],
            &["--exposure", "-2", "--tonemap", "aces", "--format", "ppm"],
            // EXR stays linear: its name, like its bytes, ignores both.
            &["--exposure", "1.5", "--tonemap", "aces", "--format", "exr"],
        ],
    );
    assert_eq!(
        names,
        [
            "matte_spheres-w24-2spp-d10-seed0-f64-aces.png",
            "matte_spheres-w24-2spp-d10-seed0-f64-ev-2-aces.ppm",
            "matte_spheres-w24-2spp-d10-seed0-f64-ev1.5.png",
            "matte_spheres-w24-2spp-d10-seed0-f64.exr",
            "matte_spheres-w24-2spp-d10-seed0-f64.png",
        ]
    );
}

#[test]
fn a_bad_exposure_is_a_usage_error_naming_the_option() {
    let s = scene("matte_spheres.toml");
    let s = s.to_str().unwrap();
    expect(
        &run(&["render", s, "--exposure", "65"]),
        2,
        &["--exposure", "[-64, 64]"],
    );
    expect(&run(&["render", s, "--exposure", "nan"]), 2, &["--exposure"]);
    expect(&run(&["render", s, "--tonemap", "reinhard"]), 2, &["--tonemap"]);
    // Merging too, before any tile is read.
    expect(
        &run(&["merge", "--exposure", "99", "--out", "x.png", "missing.rtile"]),
        2,
        &["invalid value '99' for '--exposure'"],
    );
}

/// `--bvh-quality high` reaches the scene: the render's bytes are the medium build's (the
/// spatial splits change the tree, never the image), and an unknown quality is a usage error.
#[test]
fn the_bvh_quality_option_renders_the_same_bytes() {
    let s = scene("cornell_box.toml");
    let dir = folder("bvh-quality");
    let render = |quality: &str| {
        let out = dir.join(format!("{quality}.png"));
        let args = [
            "render",
            s.to_str().unwrap(),
            "--width",
            "24",
            "--spp",
            "2",
            "--quiet",
        ];
        let quality = ["--bvh-quality", quality, "--out", out.to_str().unwrap()];
        expect(&run(&[&args[..], &quality[..]].concat()), 0, &[]);
        fs::read(out).unwrap()
    };
    assert_eq!(render("medium"), render("high"));
    let bad = ["render", s.to_str().unwrap(), "--bvh-quality", "ultra"];
    expect(&run(&bad), 2, &["--bvh-quality", "ultra"]);
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
            "36 triangles (meshes: 8, instances: 0)",
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
    // Values the scene cannot take, given on the command line, name the option.
    expect(
        &run(&["render", s, "--max-depth", "1001"]),
        2,
        &["--max-depth", "1000"],
    );
    expect(&run(&["render", s, "--width", "41"]), 2, &["--width", "even"]);
    let o = run(&["render", s, "--width", "41"]);
    assert!(!text(&o).contains("render.width"), "{}", text(&o));
    // A tile is not an image: its file says so, and nothing is written under another name.
    let image = dir.join("t.png");
    expect(
        &run(&["render", s, "--tile", "1/2", "--out", image.to_str().unwrap()]),
        2,
        &["--tile", ".rtile"],
    );
    assert!(!image.exists());
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
    // An image too large for memory is refused before allocating, not aborted: a usage
    // error when the command line asked for it, a failure when the file did.
    expect(
        &run(&["render", s, "--width", "1000000", "--quiet"]),
        2,
        &["--width", "pixels"],
    );
    let huge = dir.join("huge.toml");
    fs::write(&huge, "[render]\nwidth = 1000000\n").unwrap();
    expect(
        &run(&["render", huge.to_str().unwrap(), "--quiet"]),
        1,
        &["huge.toml", "render.width", "pixels"],
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
    assert_eq!(left.len(), 4, "only the test's own four files remain: {left:?}");
    fs::remove_dir_all(dir).unwrap();
}
