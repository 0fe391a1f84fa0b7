//! `raytrace`: renders scene files from the command line.
//!
//! ```text
//! raytrace render scenes/four_mirrors.toml --spp 16 --out four.png
//! raytrace render scenes/dragon.toml --tile 2/4 --out dragon-2.rtile
//! raytrace merge dragon-*.rtile --out dragon.exr
//! raytrace check scenes/dragon.toml
//! raytrace advise scenes/random_spheres.toml
//! ```
//!
//! Exit codes: 0 on success, 1 when the work fails (a bad scene, an unwritable file), 2 for
//! a usage error, 130 when interrupted (no temporary file is left behind).

mod args;
mod inspect;
mod output;
mod render;

use args::{Cli, Command};
use clap::error::ErrorKind;
use clap::{CommandFactory, Parser};
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Err(message) = output::check_usage(&cli.command) {
        Cli::command().error(ErrorKind::ArgumentConflict, message).exit();
    }
    let result = raytrace::image::on_interrupt_remove_temporary_files().and_then(|()| match &cli.command {
        Command::Render(args) => render::run(args),
        Command::Check { scene } => inspect::check(scene),
        Command::Advise { scene } => inspect::advise(scene),
        Command::Merge(args) => output::merge(args),
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("raytrace: error: {e}");
            ExitCode::FAILURE
        }
    }
}
