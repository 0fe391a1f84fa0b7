//! Where the results go: file names, formats, writing (to a file or to standard output),
//! merging tiles.

use crate::args::{Format, MergeArgs, RenderArgs};
use crate::inputs;
use crate::layers;
use crate::names::{adaptive_of, default_name};
use crate::usage::{choose_format, encoding, merge_tonemap, usage};
use raytrace::advice::Precision;
use raytrace::cli::{check_output, set_activity, write_file};
use raytrace::image::{
    Encoding, ExrChannel, TileHeader, Tonemap, merge_tiles, read_tile, write_exr, write_exr_to,
    write_layered_exr, write_layered_exr_to, write_pfm, write_pfm_to, write_png, write_png_to, write_ppm,
    write_ppm_to, write_tile, write_tile_to,
};
use raytrace::scene_file::SceneFile;
use raytrace::{Error, Image, Result};
use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};

pub use raytrace::cli::pool;

/// A file to write and how.
pub struct Target {
    /// The file; `-` for standard output.
    pub path: PathBuf,
    /// Its image format; `None` for a tile file.
    format: Option<Format>,
    encoding: Encoding,
    /// The exposure and tone curve of PPM and PNG files.
    tonemap: Tonemap,
    /// The files the command reads, which the output must not replace.
    inputs: Vec<PathBuf>,
    /// Where the render's layers go beside an image whose format holds none.
    layers: Option<PathBuf>,
    /// Show a spinner on stderr while writing (when it is a terminal).
    spinner: bool,
}

impl Target {
    /// The output of `raytrace render`: `--out`, or [`default_name`](crate::names::default_name).
    pub fn for_render(args: &RenderArgs, file: &SceneFile, precision: Precision) -> Result<Self> {
        let encoding = encoding(args.encoding);
        let tonemap = file.tonemap()?;
        let format = match args.tile {
            Some(_) => None,
            None => Some(choose_format(args.format, args.out.as_deref(), Format::Png)?),
        };
        let path = args
            .out
            .clone()
            .unwrap_or_else(|| default_name(args, file, precision, format, tonemap));
        let has_layers = adaptive_of(args).is_some() || args.aov;
        let layers = (has_layers && !matches!(format, None | Some(Format::Exr)) && path != Path::new("-"))
            .then(|| layers::beside(&path));
        set_activity(format!(
            "rendering {} for {}",
            file.path().display(),
            shown(&path)
        ));
        Ok(Self {
            path,
            format,
            encoding,
            tonemap,
            inputs: inputs::of_scene(file),
            layers,
            spinner: !args.quiet,
        })
    }

    /// Fails now, before any render, if the output cannot be written: it is one of the
    /// inputs, a folder or a device it may not replace, or its folder is not writable
    /// (standard output: a terminal, which cannot show an image).
    pub fn check_writable(&self) -> Result<()> {
        let refuse = |message: String| Error::Io {
            path: shown(&self.path).into(),
            source: io::Error::new(io::ErrorKind::InvalidInput, message),
        };
        let out = if self.is_stdout() {
            if io::stdout().is_terminal() {
                return Err(refuse(
                    "--out - writes the image here, and it is a terminal: redirect it to a file or a pipe"
                        .into(),
                ));
            }
            // Standard output redirected into an input would destroy it as surely.
            Path::new("/dev/stdout")
        } else {
            check_output(&self.path)?;
            &self.path
        };
        if let Some(input) = inputs::overwritten(out, &self.inputs) {
            return Err(refuse(format!(
                "--out names {}, which this command reads: refusing to overwrite an input",
                input.display()
            )));
        }
        if let Some(beside) = &self.layers {
            check_output(beside)?;
            if let Some(input) = inputs::overwritten(beside, &self.inputs) {
                return Err(Error::Io {
                    path: beside.clone(),
                    source: io::Error::new(
                        io::ErrorKind::InvalidInput,
                        format!(
                            "the layers file beside --out would be {}, which this command reads",
                            input.display()
                        ),
                    ),
                });
            }
        }
        Ok(())
    }

    /// Writes `image` in the target's format, and its `layers` (if any) into the same EXR
    /// or [beside](layers::beside) an image of another format. Returns the layers file
    /// written beside it, if one was.
    pub fn write_image(&self, image: &Image, layers: &[ExrChannel]) -> Result<Option<PathBuf>> {
        let format = self
            .format
            .ok_or_else(|| usage("a tile target holds a tile, not an image"))?;
        // Exposure and tone curve only where the image is made a picture: EXR and PFM keep
        // the linear values.
        let samples = || image.to_u16_tonemapped(self.tonemap, self.encoding);
        let e = self.encoding;
        self.write(format.extension(), |out| match (format, out) {
            (Format::Ppm, Out::File(p)) => write_ppm(p, &samples()),
            (Format::Png, Out::File(p)) => write_png(p, &samples(), e),
            (Format::Exr, Out::File(p)) if !layers.is_empty() => write_layered_exr(p, image, layers),
            (Format::Exr, Out::Stdout(w)) if !layers.is_empty() => {
                let mut bytes = io::Cursor::new(Vec::new());
                stdout(
                    write_layered_exr_to(&mut bytes, image, layers)
                        .and_then(|()| w.write_all(bytes.get_ref())),
                )
            }
            (Format::Exr, Out::File(p)) => write_exr(p, image),
            (Format::Pfm, Out::File(p)) => write_pfm(p, image),
            (Format::Ppm, Out::Stdout(w)) => stdout(write_ppm_to(w, &samples())),
            (Format::Png, Out::Stdout(w)) => stdout(write_png_to(w, &samples(), e)),
            (Format::Exr, Out::Stdout(w)) => {
                // EXR ends in a table of offsets: made in memory, where it can seek.
                let mut bytes = io::Cursor::new(Vec::new());
                stdout(write_exr_to(&mut bytes, image).and_then(|()| w.write_all(bytes.get_ref())))
            }
            (Format::Pfm, Out::Stdout(w)) => stdout(write_pfm_to(w, image)),
        })?;
        match &self.layers {
            Some(_) if !layers.is_empty() => {
                set_activity(format!("writing the layers beside {}", shown(&self.path)));
                layers::write_beside(&self.path, image, layers).map(Some)
            }
            _ => Ok(None),
        }
    }

    /// Writes a tile file.
    pub fn write_tile(&self, header: &TileHeader, image: &Image) -> Result<()> {
        self.write("tile", |out| match out {
            Out::File(p) => write_tile(p, header, image),
            Out::Stdout(w) => stdout(write_tile_to(w, header, image)),
        })
    }

    /// Prints `line` where the user reads it: stdout, or stderr when the image goes to
    /// stdout.
    pub fn say(&self, line: &str) {
        if self.is_stdout() {
            eprintln!("{line}");
        } else {
            println!("{line}");
        }
    }

    /// The output's name for messages (`standard output` for `-`).
    pub fn name(&self) -> String {
        shown(&self.path)
    }

    fn is_stdout(&self) -> bool {
        self.path == Path::new("-")
    }

    /// Runs `write` on the file (missing folders made, and removed again on failure) or
    /// on standard output, with a spinner saying what is being written.
    fn write(&self, what: &str, write: impl FnOnce(Out) -> Result<()>) -> Result<()> {
        set_activity(format!("writing {}", shown(&self.path)));
        let spinner = Spinner::start(self.spinner, &format!("writing {} ({what})", shown(&self.path)));
        let result = if self.is_stdout() {
            let mut out = io::BufWriter::new(io::stdout().lock());
            write(Out::Stdout(&mut out)).and_then(|()| stdout(out.flush()))
        } else {
            write_file(&self.path, |p| write(Out::File(p)))
        };
        spinner.finish();
        result
    }
}

/// Where [`Target::write`] writes.
enum Out<'a> {
    File(&'a Path),
    Stdout(&'a mut io::BufWriter<io::StdoutLock<'static>>),
}

/// A failure to write standard output, named.
fn stdout(result: io::Result<()>) -> Result<()> {
    result.map_err(|source| Error::Io {
        path: "standard output".into(),
        source,
    })
}

/// `path` for messages: `-` is standard output.
fn shown(path: &Path) -> String {
    if path == Path::new("-") {
        "standard output".into()
    } else {
        path.display().to_string()
    }
}

/// A spinner on stderr while an image is encoded and written (a large PNG takes seconds),
/// shown only on a terminal.
struct Spinner(Option<indicatif::ProgressBar>);

impl Spinner {
    fn start(wanted: bool, message: &str) -> Self {
        if !wanted || !io::stderr().is_terminal() {
            return Self(None);
        }
        let bar = indicatif::ProgressBar::new_spinner().with_message(message.to_string());
        // Drawn now, not at the first tick: a write faster than a tick still says so.
        bar.tick();
        bar.enable_steady_tick(std::time::Duration::from_millis(100));
        Self(Some(bar))
    }

    fn finish(self) {
        if let Some(bar) = self.0 {
            bar.finish_and_clear();
        }
    }
}

/// `raytrace merge`: reads the tiles, checks they make one image, writes it.
pub fn merge(args: &MergeArgs) -> Result<()> {
    let format = choose_format(args.format, Some(&args.out), Format::Png)?;
    let tonemap = merge_tonemap(args).map_err(|e| usage(&e))?;
    let target = Target {
        path: args.out.clone(),
        format: Some(format),
        encoding: encoding(args.encoding),
        tonemap,
        inputs: args.tiles.clone(),
        layers: None,
        spinner: !args.quiet,
    };
    set_activity(format!(
        "merging {} tiles for {}",
        args.tiles.len(),
        shown(&target.path)
    ));
    target.check_writable()?;
    let tiles = args
        .tiles
        .iter()
        .map(|p| read_tile(p))
        .collect::<Result<Vec<_>>>()?;
    let image = merge_tiles(&tiles)?;
    target.write_image(&image, &[])?;
    target.say(&format!(
        "wrote {}: {}×{} pixels from {} tiles",
        shown(&target.path),
        image.width(),
        image.height(),
        tiles.len()
    ));
    Ok(())
}

pub use inputs::scene_hash;
