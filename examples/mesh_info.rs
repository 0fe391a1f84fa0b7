//! Loads a mesh and prints what it holds: vertex, triangle and skipped-face counts, the
//! bounding box and how long the load took.
//!
//! `cargo run --release --features studies --example mesh_info -- assets/meshes/dragon_vrip.ply`
//! (`tools/fetch_meshes.sh` fetches that one; any `.obj` or `.ply` file works).

use clap::Parser;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Prints the counts and bounds of an OBJ or PLY mesh.
#[derive(Parser)]
struct Args {
    /// The mesh file (`.obj` or `.ply`).
    path: PathBuf,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let start = Instant::now();
    let mesh = match raytrace::mesh::load(&args.path) {
        Ok(mesh) => mesh,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::FAILURE;
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    let (mut low, mut high) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &mesh.positions {
        for (axis, value) in p.to_f64().into_iter().enumerate() {
            low[axis] = low[axis].min(value);
            high[axis] = high[axis].max(value);
        }
    }
    println!("{}", args.path.display());
    println!("vertices:  {}", mesh.positions.len());
    println!("triangles: {}", mesh.triangles.len());
    println!("skipped:   {} degenerate", mesh.skipped_degenerate);
    println!("bounds:    {low:?} to {high:?}");
    println!("loaded in: {seconds:.2} s");
    ExitCode::SUCCESS
}
