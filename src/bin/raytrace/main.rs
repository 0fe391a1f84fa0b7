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
//! a usage error (an option's value the scene cannot take included: `--width 41` for the
//! spec's 2:1 camera), 128 + the signal's number when SIGINT (130), SIGTERM (143) or
//! SIGHUP (129) stops it (no temporary file is left behind; `raytrace::cli`).

mod args;
mod inputs;
mod inspect;
mod layers;
mod names;
mod output;
mod render;
mod usage;

use args::{Cli, Command};
use clap::error::ErrorKind;
use clap::{CommandFactory, Parser};
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Err(message) = usage::check_usage(&cli.command) {
        Cli::command().error(ErrorKind::ArgumentConflict, message).exit();
    }
    if let Err(e) = raytrace::cli::clean_up_on_signals("raytrace") {
        eprintln!("raytrace: error: cannot handle signals (SIGINT, SIGTERM, SIGHUP): {e}");
        return ExitCode::FAILURE;
    }
    let result = match &cli.command {
        Command::Render(args) => render::run(args),
        Command::Check { scene, define } => inspect::check(scene, define).map_err(Failure::from),
        Command::Advise { scene } => inspect::advise(scene).map_err(Failure::from),
        Command::Merge(args) => output::merge(args).map_err(Failure::from),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(message)) => Cli::command().error(ErrorKind::ValueValidation, message).exit(),
        Err(Failure::Work(e)) => {
            eprintln!("raytrace: error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Why a command did not succeed: the user asked for something it cannot do (exit 2), or
/// the work failed (exit 1).
pub enum Failure {
    /// A mistake on the command line that clap cannot see, naming the option.
    Usage(String),
    /// The work failed.
    Work(raytrace::Error),
}

impl From<raytrace::Error> for Failure {
    fn from(e: raytrace::Error) -> Self {
        Self::Work(e)
    }
}
