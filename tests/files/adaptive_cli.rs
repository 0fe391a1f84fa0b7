//! `raytrace render --target-error / --time-budget / --aov` as a user runs it: the summary
//! line, the layers in the EXR or beside the image, adaptive tiles in four processes
//! merging to the whole render, and the options' mistakes as usage errors naming them.

use exr::prelude::{ReadChannels, ReadLayers};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

fn scene(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

fn folder(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-adaptive-cli-{test}-{}", std::process::id()));
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

fn expect(o: &Output, code: i32, words: &[&str]) {
    let t = text(o);
    assert_eq!(o.status.code(), Some(code), "{t}");
    for w in words {
        assert!(t.contains(w), "missing `{w}` in: {t}");
    }
}

/// The channel names of an EXR file.
fn channels(path: &Path) -> Vec<String> {
    let image = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .unwrap();
    image
        .layer_data
        .channel_data
        .list
        .iter()
        .map(|c| c.name.to_string())
        .collect()
}

#[test]
fn a_target_error_render_says_what_it_reached_and_writes_its_maps() {
    let dir = folder("target");
    let out = dir.join("cornell.exr");
    let o = run(&[
        "render",
        &scene("cornell_box.toml"),
        "--width",
        "16",
        "--target-error",
        "20%",
        "--max-spp",
        "256",
        "--aov",
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ]);
    expect(
        &o,
        0,
        &[
            "target error 0.2 (32 to 256 spp, error floor 0.01)",
            "median",
            "99th percentile",
            "(target 20.000 %, met by",
            "samples,",
            "per pixel (32 to ",
        ],
    );
    assert_eq!(
        channels(&out),
        [
            "B",
            "G",
            "R",
            "albedo.B",
            "albedo.G",
            "albedo.R",
            "depth.Z",
            "error.Y",
            "normal.X",
            "normal.Y",
            "normal.Z",
            "samples.Y"
        ]
    );

    // Another format: the layers go beside it, the colour with them.
    let png = dir.join("cornell.png");
    let o = run(&[
        "render",
        &scene("cornell_box.toml"),
        "--width",
        "16",
        "--time-budget",
        "200ms",
        "--quiet",
        "--out",
        png.to_str().unwrap(),
    ]);
    let beside = dir.join("cornell.layers.exr");
    expect(
        &o,
        0,
        &["time budget 0.2 s", "median", "cornell.layers.exr: the layers"],
    );
    assert!(png.is_file());
    assert_eq!(channels(&beside), ["B", "G", "R", "error.Y", "samples.Y"]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn adaptive_tiles_in_four_processes_merge_to_the_whole_render() {
    let dir = folder("tiles");
    let s = scene("matte_spheres.toml");
    let common = [
        "--width",
        "48",
        "--target-error",
        "0.1",
        "--max-spp",
        "128",
        "--quiet",
    ];
    let whole = dir.join("whole.ppm");
    expect(
        &run(&[&["render", &s, "--out", whole.to_str().unwrap()], &common[..]].concat()),
        0,
        &["wrote"],
    );
    let tiles: Vec<String> = (1..=4)
        .map(|k| dir.join(format!("t{k}.rtile")).to_string_lossy().into_owned())
        .collect();
    let children: Vec<_> = tiles
        .iter()
        .enumerate()
        .map(|(k, tile)| {
            let part = format!("{}/4", k + 1);
            Command::new(BIN)
                .args([&["render", &s, "--tile", &part, "--out", tile], &common[..]].concat())
                .output()
                .unwrap()
        })
        .collect();
    for o in &children {
        expect(o, 0, &["wrote", "median"]);
    }
    let merged = dir.join("merged.ppm");
    let mut args = vec!["merge", "--out", merged.to_str().unwrap()];
    args.extend(tiles.iter().map(String::as_str));
    expect(&run(&args), 0, &["4 tiles"]);
    assert_eq!(fs::read(&whole).unwrap(), fs::read(&merged).unwrap());

    // A tile of another target error does not merge with these.
    let other = dir.join("other.rtile");
    let mut changed = common;
    changed[3] = "0.2";
    let o = run(&[
        &["render", &s, "--tile", "4/4", "--out", other.to_str().unwrap()],
        &changed[..],
    ]
    .concat());
    expect(&o, 0, &["wrote"]);
    let mut args = vec!["merge", "--out", merged.to_str().unwrap()];
    args.extend(tiles[..3].iter().map(String::as_str));
    args.push(other.to_str().unwrap());
    expect(&run(&args), 1, &["tile 4 has settings", "target error 0.2"]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn mistaken_adaptive_options_are_usage_errors_naming_them() {
    let s = scene("four_mirrors.toml");
    let cases: [(&[&str], &str); 11] = [
        (
            &["--target-error", "-0.01"],
            "invalid value '-0.01' for '--target-error <E>'",
        ),
        (
            &["--target-error", "0.01", "--error-floor", "-1"],
            "invalid value '-1' for '--error-floor <Y>'",
        ),
        (
            &["--time-budget", "-5s"],
            "invalid value '-5s' for '--time-budget <T>'",
        ),
        (&["--target-error", "0"], "must be a finite number > 0"),
        (&["--time-budget", "0s"], "--time-budget"),
        (&["--time-budget", "soon"], "not a duration"),
        (&["--spp", "8", "--target-error", "0.01"], "--spp"),
        (&["--min-spp", "64"], "--min-spp"),
        (
            &["--target-error", "0.01", "--min-spp", "64", "--max-spp", "32"],
            "--max-spp 32 is below --min-spp 64",
        ),
        (&["--target-error", "0.01", "--min-spp", "8"], "--min-spp"),
        (&["--aov", "--tile", "1/2"], "--aov does not apply to --tile"),
    ];
    for (args, words) in cases {
        let o = run(&[&["render", &s, "--quiet", "--out", "/dev/null"], args].concat());
        expect(&o, 2, &[words]);
    }
}
