//! `raytrace check` and `raytrace advise`: what a scene file holds and what it needs.

use raytrace::advice::Advice;
use raytrace::import::Imported;
use raytrace::scene_file::{FilePrecision, SceneFile, advise_precision};
use raytrace::{Camera, Result};
use std::collections::BTreeMap;
use std::path::Path;

/// The scene file at `path`: TOML, a Mitsuba 3 XML scene (by its `.xml` extension)
/// imported with `defines` for its `$NAME`s, or a glTF 2.0 file (`.gltf`, `.glb`), with
/// what the import read and its warnings.
pub fn load(path: &Path, defines: &[(String, String)]) -> Result<(SceneFile, Option<Imported>)> {
    let mut imported = if raytrace::import::is_mitsuba(path) {
        let defines: BTreeMap<String, String> = defines.iter().cloned().collect();
        raytrace::import::mitsuba(path, &defines)?
    } else if raytrace::import::is_gltf(path) {
        raytrace::import::gltf(path)?
    } else {
        return Ok((SceneFile::load(path)?, None));
    };
    let file = std::mem::replace(&mut imported.file, SceneFile::empty(path));
    Ok((file, Some(imported)))
}

/// Validates the scene (every value, every mesh, in the scalar it renders in) and prints
/// what it holds and what it probably does not mean. Everything is checked before
/// "valid" is printed.
pub fn check(path: &Path, defines: &[(String, String)]) -> Result<()> {
    let (file, imported) = load(path, defines)?;
    let built = file.build::<f64>()?;
    let precision = match file.render().precision {
        FilePrecision::F32 => {
            file.build::<f32>()?;
            "f32".to_string()
        }
        FilePrecision::F64 => "f64".to_string(),
        FilePrecision::Auto => {
            let advice = advise_precision(&file)?;
            format!("auto, measured: {} ({})", advice.recommended, advice.reason)
        }
    };
    let mut warnings = file.warnings();
    warnings.extend(file.preview_warning(&built)?);

    let s = &built.summary;
    let r = file.render();
    println!("{}: valid", path.display());
    if let Some(imported) = &imported {
        if raytrace::import::is_gltf(path) {
            println!("  read from glTF 2.0:");
        } else {
            println!("  read from Mitsuba 3 XML: {} plugins", imported.read.len());
        }
        for plugin in &imported.read {
            println!("    {plugin}");
        }
        for warning in &imported.warnings {
            println!("  {}: {warning}", differs(path));
        }
    }
    println!(
        "  objects: {} spheres, {} planes, {} disks, {} triangles (meshes: {}, instances: {}), {} lights",
        s.spheres, s.planes, s.disks, s.triangles, s.meshes, s.instances, s.lights
    );
    if s.emitters > 0 {
        println!(
            "  emitters: {} objects give off light, {} of them sampled as lights",
            s.emitters, s.sampled_emitters
        );
    } else {
        println!("  emitters: none");
    }
    if s.skipped_degenerate > 0 {
        println!("  skipped: {} faces without area", s.skipped_degenerate);
    }
    match &s.bounds {
        Some(b) => println!(
            "  bounds of the bounded objects: {} to {}",
            point(b.min),
            point(b.max)
        ),
        None => println!("  bounds: no bounded objects"),
    }
    match s.bvh_references {
        Some(n) => {
            let quality = match r.bvh_quality {
                raytrace::BvhQuality::Medium => "medium",
                raytrace::BvhQuality::High => "high, with spatial splits",
            };
            println!("  acceleration: BVH of {n} references ({quality})");
        }
        None => println!("  acceleration: a loop over the objects"),
    }
    let image = (built.camera.width(), built.camera.height());
    println!(
        "  render: {}×{} pixels, {} spp, max depth {}, seed {}",
        image.0, image.1, r.spp, r.max_depth, r.seed
    );
    println!("  precision: {precision}");
    for w in warnings {
        eprintln!("warning: {}: {w}", path.display());
    }
    for note in file.unused_obj_materials() {
        eprintln!("warning: {}: {note}", path.display());
    }
    for note in &s.notes {
        eprintln!("warning: {note}");
    }
    Ok(())
}

/// How a warning of an import of `path` starts: what the render differs from.
pub fn differs(path: &Path) -> &'static str {
    if raytrace::import::is_gltf(path) {
        "not as the glTF file says"
    } else {
        "differs from Mitsuba"
    }
}

/// Prints the measured precision advice.
pub fn advise(path: &Path) -> Result<()> {
    let (file, _) = load(path, &[])?;
    let advice = advise_precision(&file)?;
    print(path, &advice);
    Ok(())
}

/// A point as `(x, y, z)`, to four significant digits.
fn point(p: raytrace::Vec3<f64>) -> String {
    format!("({:.4}, {:.4}, {:.4})", p.x, p.y, p.z)
}

fn print(path: &Path, a: &Advice) {
    println!("{}: against a double-double reference render", path.display());
    for (name, t) in [("f32", a.f32.as_ref()), ("f64", Some(&a.f64))] {
        match t {
            Some(t) => println!(
                "  {name}: RMSE {:.2e}, {:.3} % of pixels more than one 8-bit step off, {:.3} s",
                t.error.rmse,
                100.0 * t.error.over_one_step,
                t.time.as_secs_f64()
            ),
            None => println!("  {name}: not rendered"),
        }
    }
    println!("  advice: {} ({})", a.recommended, a.reason);
}
