//! Bad scene files and bad meshes, through the `raytrace` binary as a user runs it. Each
//! case asserts the exit code, that the message names the file and the field (and the line
//! where the reader knows it), that it leaks nothing a user should not see (a parser's
//! internals, Rust's debug output, another file's contents), and that the folder holds
//! afterwards exactly what it held before (plus the image, when the render succeeds).
//! The helpers are this module's own.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

/// A small valid scene: one matte sphere under the default sky, 16 pixels wide.
const BASE: &str = "[render]\nwidth = 16\n\n[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n\n\
                    [[objects]]\ntype = \"sphere\"\ncenter = [0, 0, -3]\nradius = 1\nmaterial = \"m\"\n";

/// A spot light's keys but its angles, from the second line of an entry added by [`plus`]
/// (line 14).
const SPOT: &str =
    "[[lights]]\ntype = \"spot\"\nposition = [0, 2, 0]\ndirection = [0, -1, 0]\nintensity = [1, 1, 1]\n";

/// A look-at camera (aspect 2) for [`BASE`].
const LOOK_AT: &str =
    "\n[camera]\ntype = \"look_at\"\nfrom = [0, 0, 0]\nat = [0, 0, -1]\nvfov = 40\naspect = 2\n";

/// The first lines of `/etc/shadow`, as a mesh file a scene might point at.
const SECRET: &str = "root:*:19000:0:99999:7:::\ndaemon:*:19000:0:99999:7:::\n";

/// What a user should never read in a message.
const LEAKS: [&str; 12] = [
    "root:",
    "daemon",
    "Vec3 {",
    "ParseError",
    "LineCol",
    "String:",
    "internally tagged",
    "Spec",
    "struct ",
    "panicked",
    "RUST_BACKTRACE",
    "memory allocation",
];

/// A file placed beside the scene before the run.
enum Extra {
    /// A file with these bytes.
    Bytes(&'static str, Vec<u8>),
    /// A symbolic link to `target`.
    Link(&'static str, &'static str),
    /// A sparse file of `len` zero bytes.
    Sparse(&'static str, u64),
    /// A folder.
    Folder(&'static str),
    /// A FIFO (a reader that opened it would wait for a writer forever).
    Fifo(&'static str),
}

/// One run: the scene file's text, what lies beside it, the command, the exit code and the
/// words the output must hold.
struct Case {
    name: &'static str,
    scene: String,
    extras: Vec<Extra>,
    args: Vec<&'static str>,
    code: i32,
    words: Vec<String>,
    /// Words the output must not hold.
    absent: Vec<&'static str>,
}

fn case(name: &'static str, scene: String, code: i32, words: &[&str]) -> Case {
    Case {
        name,
        scene,
        extras: Vec::new(),
        args: vec!["render"],
        code,
        words: words.iter().map(|w| w.to_string()).collect(),
        absent: Vec::new(),
    }
}

impl Case {
    fn with(mut self, extra: Extra) -> Self {
        self.extras.push(extra);
        self
    }

    /// Runs `raytrace check` instead of `render`.
    fn check(mut self) -> Self {
        self.args = vec!["check"];
        self
    }

    fn without(mut self, word: &'static str) -> Self {
        self.absent.push(word);
        self
    }

    fn args(mut self, args: &[&'static str]) -> Self {
        self.args.extend(args);
        self
    }
}

/// [`BASE`] with `from` replaced by `to` (which must be there).
fn edit(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

/// [`BASE`] with an entry added.
fn plus(entry: &str) -> String {
    format!("{BASE}\n{entry}\n")
}

/// [`BASE`] with a mesh object of material `m` (the sphere stays).
fn mesh(file: &str, keys: &str) -> String {
    plus(&format!(
        "[[objects]]\ntype = \"mesh\"\nfile = \"{file}\"\nmaterial = \"m\"\n{keys}"
    ))
}

const SQUARE_OBJ: &str = "v 0 0 -3\nv 1 0 -3\nv 1 1 -3\nv 0 1 -3\nf 1 2 3\n";

fn ply(body: &str) -> Vec<u8> {
    format!(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
         element face 1\nproperty list uchar int vertex_indices\nend_header\n{body}"
    )
    .into_bytes()
}

fn cases() -> Vec<Case> {
    vec![
        // Values outside their domain: the field's path, and the value.
        case("negative radius", edit("radius = 1", "radius = -1"), 1, &["s.toml: line 11, column 10: objects[0].radius: must be > 0 (got -1)"]),
        case("NaN radius", edit("radius = 1", "radius = nan"), 1, &["objects[0].radius", "NaN"]),
        case("infinite centre", edit("[0, 0, -3]", "[0, 0, -inf]"), 1, &["objects[0].center", "finite", "[0, 0, -inf]"]),
        case("albedo above 1", edit("[0.5, 0.5, 0.5]", "[0.5, 1.5, 0.5]"), 1, &["materials.m.albedo", "[0, 1]"]),
        case("zero index", plus("[materials.g]\ntype = \"dielectric\"\nindex = 0"), 1, &["materials.g.index", "> 0"]),
        case("negative radiance", plus("[materials.e]\ntype = \"emissive\"\nradiance = [1, -1, 1]"), 1, &["materials.e.radiance"]),
        case("negative intensity", plus("[[lights]]\nposition = [0, 2, 0]\nintensity = [1, 1, -1]"), 1, &["lights[0].intensity", "≥ 0"]),
        case("infinite light", plus("[[lights]]\nposition = [0, inf, 0]\nintensity = [1, 1, 1]"), 1, &["lights[0].position", "[0, inf, 0]"]),
        case("negative background", plus("[background]\ntype = \"solid\"\ncolor = [0, -0.1, 0]"), 1, &["background.color"]),
        case("bright sky", plus("[background]\ntype = \"sky\"\nzenith = [nan, 1, 1]"), 1, &["background.zenith"]),
        case("zero normal", plus("[[objects]]\ntype = \"plane\"\npoint = [0, -1, 0]\nnormal = [0, 0, 0]\nmaterial = \"m\""), 1, &["objects[1].normal", "non-zero"]),
        case("flat triangle", plus("[[objects]]\ntype = \"triangle\"\na = [0, 0, -3]\nb = [1, 1, -3]\nc = [2, 2, -3]\nmaterial = \"m\""), 1, &["s.toml: line 14, column 1: objects[1]: ", "no area"]),
        case("unknown material", edit("material = \"m\"", "material = \"gold\""), 1, &["objects[0].material", "`gold`", "`m`"]),
        // Spot and directional lights, the thin lens, the tone map: at their line and key.
        case("cutoff past 90°", plus(&format!("{SPOT}cutoff_angle = 120")), 1, &["s.toml: line 19, column 16: lights[0].cutoff_angle: must be in (0, 90] degrees (got 120)"]),
        case("beam past the cutoff", plus(&format!("{SPOT}cutoff_angle = 40\nbeam_width = 50")), 1, &["s.toml: line 20, column 14: lights[0].beam_width: must be in [0, cutoff_angle] = [0, 40] degrees (got 50)"]),
        case("default beam, cutoff 0", plus(&format!("{SPOT}cutoff_angle = 0")), 1, &["line 19, column 16: lights[0].cutoff_angle", "(got 0)"]),
        case("zero sun direction", plus("[[lights]]\ntype = \"directional\"\ndirection = [0, 0, 0]\nirradiance = [1, 1, 1]"), 1, &["s.toml: line 16, column 13: lights[0].direction: must be a non-zero vector (got [0, 0, 0])"]),
        case("zero spot direction", plus(&SPOT.replace("[0, -1, 0]", "[0, 0, 0]")), 1, &["s.toml: line 17, column 13: lights[0].direction: must be a non-zero vector"]),
        case("negative sun", plus("[[lights]]\ntype = \"directional\"\ndirection = [0, -1, 0]\nirradiance = [1, -1, 1]"), 1, &["line 17, column 14: lights[0].irradiance", "≥ 0"]),
        case("spot without direction", plus("[[lights]]\ntype = \"spot\"\nposition = [0, 2, 0]\nintensity = [1, 1, 1]"), 1, &["s.toml: line 14, column 1: lights[0]: missing field `direction`"]),
        case("irradiance of a point light", plus("[[lights]]\nposition = [0, 2, 0]\nintensity = [1, 1, 1]\nirradiance = [1, 1, 1]"), 1, &["s.toml: line 17, column 1: lights[0]: unknown field `irradiance`, expected one of `type`, `position`, `intensity`"]),
        case("unknown light", plus("[[lights]]\ntype = \"area\"\nposition = [0, 2, 0]"), 1, &["s.toml: line 15, column 8: lights[0].type: unknown variant `area`"]),
        case("negative aperture", format!("{BASE}{LOOK_AT}aperture = -0.5\n"), 1, &["s.toml: line 20, column 12: camera.aperture: must be a finite number ≥ 0 (got -0.5)"]),
        case("negative focus", format!("{BASE}{LOOK_AT}aperture = 0.1\nfocus_distance = -2\n"), 1, &["s.toml: line 21, column 18: camera.focus_distance: must be > 0 (got -2)"]),
        case("lens on the spec's camera", format!("{BASE}\n[camera]\ntype = \"screen\"\naperture = 1\n"), 1, &["line 16, column 1: camera: unknown field `aperture`"]),
        case("exposure not a number", edit("width = 16", "width = 16\nexposure = nan"), 1, &["s.toml: line 3, column 12: render.exposure: must be a number of stops in [-64, 64] (got NaN)"]),
        case("unknown tone curve", edit("width = 16", "width = 16\ntonemap = \"filmic\""), 1, &["s.toml: line 3, column 11: render.tonemap: unknown variant `filmic`"]),
        // The camera and the image's size.
        case("zero fov", format!("{BASE}{}", LOOK_AT.replace("vfov = 40", "vfov = 0")), 1, &["camera.vfov", "(0, 180)"]),
        case("eye on target", format!("{BASE}{}", LOOK_AT.replace("at = [0, 0, -1]", "at = [0, 0, 0]")), 1, &["camera.at"]),
        case("up along view", format!("{BASE}{}\nup = [0, 0, 1]", LOOK_AT), 1, &["camera.up", "parallel"]),
        case("zero aspect", format!("{BASE}{}", LOOK_AT.replace("aspect = 2", "aspect = 0")), 1, &["camera.aspect", "> 0"]),
        case("odd width", edit("width = 16", "width = 41"), 1, &["render.width", "even"]),
        case("look-at width 1", format!("{}{LOOK_AT}", edit("width = 16", "width = 1")), 1, &["render.width", "1×0"]),
        case("zero spp", edit("width = 16", "width = 16\nspp = 0"), 1, &["render.spp", "at least 1"]),
        case("deep", edit("width = 16", "width = 16\nmax_depth = 5000"), 1, &["render.max_depth", "1000"]),
        // Types and syntax: the line and column, in the file's words.
        case("width in quotes", edit("width = 16", "width = \"16\""), 1, &["s.toml: line 2, column 9: render.width", "integer"]),
        case("spp in quotes", edit("width = 16", "width = 16\nspp = \"12\""), 1, &["line 3, column 7: render.spp", "integer"]),
        case("four numbers", plus("[[lights]]\nposition = [0, 1, 2, 3]\nintensity = [1, 1, 1]"), 1, &["lights[0].position: invalid length 4, expected an array of three numbers"]),
        case("a number for a table", plus("[materials]\nx = 3"), 1, &["materials", "a table with a `type` key"]),
        case("unknown key", edit("radius = 1", "radius = 1\nradus = 2"), 1, &["line 12, column 1: objects[0]: unknown field `radus`"]),
        case("unknown choice", edit("width = 16", "width = 16\nprecision = \"f16\""), 1, &["render.precision", "`f16`"]),
        case("endless scene", String::new(), 1, &["s.toml: the whole file: longer than"]).with(Extra::Link("s.toml", "/dev/zero")).check(),
        case("scene not UTF-8", String::new(), 1, &["s.toml: line 2, column 6: not UTF-8"]).with(Extra::Bytes("s.toml", b"[render]\n# caf\xe9\n".to_vec())),
        case("broken TOML", edit("radius = 1", "radius = = 1"), 1, &["s.toml: line 11, column 10"]),
        // Rounding: only f64 holds a radius of 1e-60.
        case("tiny radius in f32", edit("width = 16", "width = 16\nprecision = \"f32\"").replace("radius = 1", "radius = 1e-60"), 1, &["objects[0].radius", "in f32", "f64"]),
        case("tiny radius in f32, check", edit("width = 16", "width = 16\nprecision = \"f32\"").replace("radius = 1", "radius = 1e-60"), 1, &["objects[0].radius", "in f32"]).check().without("s.toml: valid"),
        case("tiny radius, auto", edit("width = 16", "width = 16\nprecision = \"auto\"").replace("radius = 1", "radius = 1e-60"), 0, &["precision auto: f64", "cannot be built in f32", "objects[0].radius", "wrote"]),
        case("tiny radius, auto, check", edit("width = 16", "width = 16\nprecision = \"auto\"").replace("radius = 1", "radius = 1e-60"), 0, &["valid", "measured: f64", "objects[0].radius"]).check(),
        // Meshes: the file field, the mesh's own element and line, never its contents.
        case("missing mesh", mesh("absent.obj", ""), 1, &["objects[1].file", "absent.obj", "cannot open"]),
        case("endless OBJ", mesh("zero.obj", ""), 1, &["objects[1].file", "regular file"]).with(Extra::Link("zero.obj", "/dev/zero")),
        case("endless PLY", mesh("zero.ply", ""), 1, &["objects[1].file", "regular file"]).with(Extra::Link("zero.ply", "/dev/zero")),
        case("FIFO", mesh("pipe.obj", ""), 1, &["objects[1].file", "regular file"]).with(Extra::Fifo("pipe.obj")),
        case("folder", mesh("dir.obj", ""), 1, &["objects[1].file", "a folder"]).with(Extra::Folder("dir.obj")),
        case("one long line", mesh("long.obj", ""), 1, &["objects[1].file", "line 1 is longer than"]).with(Extra::Sparse("long.obj", 3 << 20)),
        case("shadow as PLY", mesh("shadow.ply", ""), 1, &["objects[1].file", "not a PLY file"]).with(Extra::Bytes("shadow.ply", SECRET.into())),
        case("shadow as OBJ", mesh("shadow.obj", ""), 1, &["objects[1].file", "no faces"]).with(Extra::Bytes("shadow.obj", SECRET.into())),
        case("garbled PLY", mesh("g.ply", ""), 1, &["objects[1].file", "element vertex: line 12"]).with(Extra::Bytes("g.ply", ply("0 0 -3\n1 0 -3\n1 root:* -3\n3 0 1 2\n"))),
        case("short PLY", mesh("s.ply", ""), 1, &["objects[1].file", "element face", "ends before"]).with(Extra::Bytes("s.ply", ply("0 0 -3\n1 0 -3\n1 1 -3\n"))),
        case("index out of range", mesh("r.obj", ""), 1, &["objects[1].file", "line 6: face 2: vertex index 9"]).with(Extra::Bytes("r.obj", format!("{SQUARE_OBJ}f 1 2 9\n").into())),
        case("NaN vertex", mesh("n.obj", ""), 1, &["objects[1].file", "line 2: vertex 2: coordinate y is NaN"]).with(Extra::Bytes("n.obj", b"v 0 0 -3\nv 1 nan -3\nv 1 1 -3\nf 1 2 3\n".to_vec())),
        case("zero scale", mesh("q.obj", "scale = [1, 0, 1]"), 1, &["objects[1].scale", "non-zero"]).with(Extra::Bytes("q.obj", SQUARE_OBJ.into())),
        case("placed past f32", mesh("q.obj", "translate = [1e39, 0, 0]").replace("width = 16", "width = 16\nprecision = \"f32\""), 1, &["objects[1]: vertex 0", "[1e39, 0, -3]", "f32"]).with(Extra::Bytes("q.obj", SQUARE_OBJ.into())),
        // Valid, but probably not meant: a warning, and the render goes ahead.
        case("empty scene", "[render]\nwidth = 16\n".into(), 0, &["warning", "no [[objects]]", "wrote"]),
        case("panel facing away", "[render]\nwidth = 16\n[background]\ntype = \"solid\"\ncolor = [0, 0, 0]\n[materials.e]\ntype = \"emissive\"\nradiance = [1, 1, 1]\n[[objects]]\ntype = \"triangle\"\na = [-1, -1, -3]\nb = [-1, 1, -3]\nc = [1, -1, -3]\nmaterial = \"e\"\n".into(), 0, &["valid", "warning", "no light reaches the camera"]).check(),
        case("nothing lit", edit("width = 16", "width = 16\n[background]\ntype = \"solid\"\ncolor = [0, 0, 0]"), 0, &["warning", "nothing gives off light"]),
        // The command line's values: a usage error naming the option.
        case("look-at --width 1", format!("{BASE}{LOOK_AT}"), 2, &["'--width'", "'1'"]).args(&["--width", "1"]),
        case("look-at --width 4e9", format!("{BASE}{LOOK_AT}"), 2, &["'--width'", "4000000000"]).args(&["--width", "4000000000"]),
        case("screen --width 41", BASE.into(), 2, &["'--width'", "even"]).args(&["--width", "41"]),
    ]
}

/// What a folder holds: each path below it with its kind and bytes (a link by its target).
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, String> {
    let mut found = BTreeMap::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for entry in fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            let meta = fs::symlink_metadata(&path).unwrap();
            let what = if meta.file_type().is_symlink() {
                format!("link to {}", fs::read_link(&path).unwrap().display())
            } else if meta.is_dir() {
                todo.push(path.clone());
                "folder".into()
            } else if meta.is_file() && meta.len() < 1 << 16 {
                format!("file {:?}", fs::read(&path).unwrap())
            } else {
                format!("{:?} of {} bytes", meta.file_type(), meta.len())
            };
            found.insert(path.strip_prefix(dir).unwrap().to_path_buf(), what);
        }
    }
    found
}

/// Runs the binary in `dir`, failing the test if it takes over a minute (a hang).
fn run(dir: &Path, args: &[&str]) -> (Option<i32>, String) {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("{args:?} hung for a minute");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.code(), text)
}

fn place(dir: &Path, extra: &Extra) {
    match extra {
        Extra::Bytes(name, bytes) => fs::write(dir.join(name), bytes).unwrap(),
        Extra::Link(name, target) => {
            // In place of the scene file too.
            let _ = fs::remove_file(dir.join(name));
            std::os::unix::fs::symlink(target, dir.join(name)).unwrap();
        }
        Extra::Sparse(name, len) => fs::File::create(dir.join(name)).unwrap().set_len(*len).unwrap(),
        Extra::Folder(name) => fs::create_dir(dir.join(name)).unwrap(),
        Extra::Fifo(name) => {
            let made = Command::new("mkfifo").arg(dir.join(name)).status().unwrap();
            assert!(made.success(), "mkfifo");
        }
    }
}

#[test]
fn every_bad_scene_and_mesh_is_named_and_leaves_the_folder_as_it_was() {
    let root = std::env::temp_dir().join(format!("raytrace-adversarial-scenes-{}", std::process::id()));
    let _ = fs::remove_dir_all(&root);
    let mut failures = Vec::new();
    for (k, c) in cases().into_iter().enumerate() {
        let dir = root.join(k.to_string());
        fs::create_dir_all(dir.join("out")).unwrap();
        fs::write(dir.join("s.toml"), &c.scene).unwrap();
        fs::write(dir.join("out/keep.png"), "an earlier image").unwrap();
        for extra in &c.extras {
            place(&dir, extra);
        }
        let before = snapshot(&dir);
        let mut args = c.args.clone();
        args.push("s.toml");
        if args[0] == "render" {
            args.extend(["--quiet", "--out", "out/x.png"]);
        }
        let (code, text) = run(&dir, &args);
        let mut after = snapshot(&dir);
        let mut wrong = Vec::new();
        if code != Some(c.code) {
            wrong.push(format!("exit {code:?}, not {}", c.code));
        }
        wrong.extend(
            c.words
                .iter()
                .filter(|w| !text.contains(w.as_str()))
                .map(|w| format!("no `{w}`")),
        );
        wrong.extend(
            LEAKS
                .iter()
                .chain(&c.absent)
                .filter(|l| text.contains(*l))
                .map(|l| format!("has `{l}`")),
        );
        // A render that succeeds adds its image, and nothing else.
        if c.code == 0 && args[0] == "render" && after.remove(Path::new("out/x.png")).is_none() {
            wrong.push("no image written".into());
        }
        if after != before {
            wrong.push(format!("the folder changed: {before:?} → {after:?}"));
        }
        if !wrong.is_empty() {
            failures.push(format!(
                "{}: {}\n  output: {}",
                c.name,
                wrong.join("; "),
                text.trim_end()
            ));
        }
    }
    fs::remove_dir_all(&root).unwrap();
    assert!(
        failures.is_empty(),
        "{} cases failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
