//! Bad tiles, bad command lines and bad outputs, run through the `raytrace` binary. Every
//! case asserts the exit code, that the message names the option or the file at fault,
//! and that the case's folder (its inputs and its outputs) holds afterwards exactly what
//! it held before: the same names, kinds and bytes, no temporary file, no new folder.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod folder;

use folder::{edit_pixel, mknod, snapshot, symlink};

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

/// A small scene with a mesh, rendered 16 pixels wide.
const SCENE: &str = r#"
[render]
width = 16
spp = 1
max_depth = 4

[materials.m]
type = "lambertian"
albedo = [0.5, 0.5, 0.5]

[[objects]]
type = "mesh"
file = "mesh.obj"
translate = [0, 0, -3]
material = "m"

[[objects]]
type = "sphere"
center = [0, -101, -3]
radius = 100
material = "m"
"#;

const MESH: &str = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";
/// The same mesh with its top vertex moved.
const OTHER_MESH: &str = "v -1 -1 0\nv 1 -1 0\nv 0 1.5 0\nf 1 2 3\n";

fn run(dir: &Path, args: &[String]) -> Output {
    Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the binary runs")
}

/// The folder every case copies its tiles from: `t1.rtile` and `t2.rtile` of [`SCENE`],
/// and `other2.rtile`, the second tile rendered from [`OTHER_MESH`]; removed on drop.
struct Tiles(PathBuf);

impl Tiles {
    fn render() -> Self {
        let dir = std::env::temp_dir().join(format!("raytrace-adversarial-tiles-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let tiles = Self(dir);
        let dir = &tiles.0;
        fs::write(dir.join("s.toml"), SCENE).unwrap();
        let render = |mesh: &str, tile: &str, out: &str| {
            fs::write(dir.join("mesh.obj"), mesh).unwrap();
            let args = ["render", "s.toml", "--quiet", "--tile", tile, "--out", out].map(String::from);
            let o = run(dir, &args);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        };
        render(OTHER_MESH, "2/2", "other2.rtile");
        render(MESH, "1/2", "t1.rtile");
        render(MESH, "2/2", "t2.rtile");
        tiles
    }
}

impl Drop for Tiles {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

/// One bad input: how to prepare the folder, the command, the exit code and the words
/// the message must hold.
struct Case {
    name: &'static str,
    /// Prepares the case's folder (which already holds `s.toml`, `mesh.obj` and the
    /// tiles); returns false if the case cannot run here (it then says why).
    setup: fn(&Path) -> bool,
    args: &'static [&'static str],
    code: i32,
    words: &'static [&'static str],
}

fn nothing(_: &Path) -> bool {
    true
}

const CASES: &[Case] = &[
    // Bad tiles.
    Case {
        name: "a flipped byte in the pixels",
        setup: |d| {
            let mut bytes = fs::read(d.join("t2.rtile")).unwrap();
            let n = bytes.len();
            bytes[n - 5] ^= 0x10;
            fs::write(d.join("t2.rtile"), bytes).unwrap();
            true
        },
        args: &["merge", "t1.rtile", "t2.rtile", "--out", "x.png"],
        code: 1,
        words: &["t2.rtile", "changed or damaged"],
    },
    Case {
        name: "a NaN with a matching checksum",
        setup: |d| {
            edit_pixel(d, "t1.rtile", 8, f64::NAN);
            true
        },
        args: &["merge", "t1.rtile", "t2.rtile", "--out", "x.exr"],
        code: 1,
        words: &["t1.rtile", "NaN"],
    },
    Case {
        name: "a negative value with a matching checksum",
        setup: |d| {
            edit_pixel(d, "t2.rtile", 24, -1.0);
            true
        },
        args: &["merge", "t1.rtile", "t2.rtile", "--out", "x.pfm"],
        code: 1,
        words: &["t2.rtile", "pixel (1, 0)", "negative"],
    },
    Case {
        name: "a truncated tile",
        setup: |d| {
            let bytes = fs::read(d.join("t1.rtile")).unwrap();
            fs::write(d.join("t1.rtile"), &bytes[..bytes.len() - 24]).unwrap();
            true
        },
        args: &["merge", "t1.rtile", "t2.rtile", "--out", "x.png"],
        code: 1,
        words: &["t1.rtile", "truncated"],
    },
    Case {
        name: "a tile rendered from another mesh",
        setup: nothing,
        args: &["merge", "t1.rtile", "other2.rtile", "--out", "x.png"],
        code: 1,
        words: &["tile 2 is of scene"],
    },
    Case {
        name: "a tile of format version 1",
        setup: |d| {
            let bytes = fs::read(d.join("t1.rtile")).unwrap();
            fs::write(
                d.join("t1.rtile"),
                [b"raytrace-tile 1".as_slice(), &bytes[15..]].concat(),
            )
            .unwrap();
            true
        },
        args: &["merge", "t1.rtile", "t2.rtile", "--out", "x.png"],
        code: 1,
        words: &["t1.rtile", "version \"1\""],
    },
    Case {
        name: "a tile given twice",
        setup: nothing,
        args: &["merge", "t1.rtile", "t1.rtile", "--out", "x.png"],
        code: 1,
        words: &["overlap"],
    },
    Case {
        name: "a tile missing",
        setup: nothing,
        args: &["merge", "t2.rtile", "--out", "x.png"],
        code: 1,
        words: &["in no tile"],
    },
    Case {
        name: "a scene file as a tile",
        setup: nothing,
        args: &["merge", "t1.rtile", "s.toml", "--out", "x.png"],
        code: 1,
        words: &["s.toml", "not a raytrace tile"],
    },
    Case {
        name: "a merge into one of its tiles",
        setup: nothing,
        args: &[
            "merge", "t1.rtile", "t2.rtile", "--format", "png", "--out", "t1.rtile",
        ],
        code: 1,
        words: &["t1.rtile: --out names t1.rtile", "refusing to overwrite an input"],
    },
    // Bad command lines.
    Case {
        name: "a render over its scene file",
        setup: nothing,
        args: &["render", "s.toml", "--format", "png", "--out", "s.toml"],
        code: 1,
        words: &["s.toml: --out names s.toml", "refusing to overwrite an input"],
    },
    Case {
        name: "a render over its mesh",
        setup: nothing,
        args: &["render", "s.toml", "--format", "ppm", "--out", "./mesh.obj"],
        code: 1,
        words: &["mesh.obj", "refusing to overwrite an input"],
    },
    Case {
        name: "a render over a link to its scene",
        setup: |d| symlink("s.toml", &d.join("view.png")),
        args: &["render", "s.toml", "--out", "view.png"],
        code: 1,
        words: &["view.png: --out names s.toml"],
    },
    Case {
        name: "a bad value with new folders in --out",
        setup: nothing,
        args: &["render", "s.toml", "--width", "0", "--out", "new/sub/x.png"],
        code: 2,
        words: &["--width"],
    },
    Case {
        name: "a value the scene refuses, with new folders in --out",
        setup: nothing,
        args: &["render", "s.toml", "--width", "15", "--out", "new/sub/x.png"],
        code: 2,
        words: &["--width", "even"],
    },
    Case {
        name: "a scene that fails to build, with new folders in --out",
        setup: |d| {
            fs::write(d.join("mesh.obj"), "v 0 0 0\nf 1 2 3\n").unwrap();
            true
        },
        args: &["render", "s.toml", "--out", "new/sub/x.png"],
        code: 1,
        words: &["mesh.obj"],
    },
    Case {
        name: "a thread count out of range",
        setup: nothing,
        args: &["render", "s.toml", "--threads", "0", "--out", "x.png"],
        code: 2,
        words: &["--threads", "from 1 to 256"],
    },
    Case {
        name: "a format the name contradicts",
        setup: nothing,
        args: &["render", "s.toml", "--format", "exr", "--out", "x.png"],
        code: 2,
        words: &["--format"],
    },
    Case {
        name: "a tile written under an image's name",
        setup: nothing,
        args: &["render", "s.toml", "--tile", "1/2", "--out", "x.png"],
        code: 2,
        words: &["--tile", ".rtile"],
    },
    // Bad outputs.
    Case {
        name: "a folder under a file",
        setup: |d| {
            fs::write(d.join("a-file"), "x").unwrap();
            true
        },
        args: &["render", "s.toml", "--out", "a-file/sub/x.png"],
        code: 1,
        words: &["a-file/sub/x.png", "a-file is a file, not a folder"],
    },
    Case {
        name: "a folder as the output",
        setup: |d| {
            fs::create_dir(d.join("out.png")).unwrap();
            true
        },
        args: &["render", "s.toml", "--out", "out.png"],
        code: 1,
        words: &["out.png", "a folder"],
    },
    Case {
        name: "a link to nothing",
        setup: |d| symlink("missing.png", &d.join("x.png")),
        args: &["render", "s.toml", "--out", "x.png"],
        code: 1,
        words: &["x.png", "link to nothing"],
    },
    Case {
        name: "a block device",
        setup: |d| mknod(&d.join("disk.png"), &["b", "7", "0"]),
        args: &["render", "s.toml", "--out", "disk.png"],
        code: 1,
        words: &["disk.png", "block device"],
    },
    Case {
        name: "a character device (as /dev/null: streamed into, kept)",
        setup: |d| mknod(&d.join("null.png"), &["c", "1", "3"]),
        args: &["render", "s.toml", "--out", "null.png"],
        code: 0,
        words: &["wrote null.png"],
    },
    Case {
        name: "a full character device (as /dev/full)",
        setup: |d| mknod(&d.join("full.ppm"), &["c", "1", "7"]),
        args: &["merge", "t1.rtile", "t2.rtile", "--out", "full.ppm"],
        code: 1,
        words: &["full.ppm"],
    },
];

#[cfg(unix)]
#[test]
fn bad_files_fail_clearly_and_change_nothing() {
    let tiles = Tiles::render();
    let mut failures = Vec::new();
    for (i, case) in CASES.iter().enumerate() {
        let dir = std::env::temp_dir().join(format!("raytrace-adversarial-{}-{i}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        for name in ["s.toml", "mesh.obj", "t1.rtile", "t2.rtile", "other2.rtile"] {
            fs::copy(tiles.0.join(name), dir.join(name)).unwrap();
        }
        if !(case.setup)(&dir) {
            fs::remove_dir_all(&dir).unwrap();
            continue;
        }
        let before = snapshot(&dir);
        let args: Vec<String> = case.args.iter().map(|a| a.to_string()).collect();
        let o = run(&dir, &args);
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        );
        if o.status.code() != Some(case.code) {
            failures.push(format!(
                "{}: exit {:?}, not {}: {text}",
                case.name,
                o.status.code(),
                case.code
            ));
        }
        for w in case.words {
            if !text.contains(w) {
                failures.push(format!("{}: `{w}` missing from: {text}", case.name));
            }
        }
        let after = snapshot(&dir);
        if after != before {
            let changed: Vec<_> = before
                .keys()
                .chain(after.keys())
                .filter(|k| before.get(*k) != after.get(*k))
                .collect();
            failures.push(format!("{}: the folder changed at {changed:?}", case.name));
        }
        fs::remove_dir_all(&dir).unwrap();
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
