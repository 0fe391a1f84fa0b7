//! Reading Wavefront material libraries (`.mtl`): each `newmtl` entry's keys as written,
//! with the line of each, for the scene file to map onto its materials.
//!
//! Read: `Kd`, `Ks`, `Ke`, `Tf` (one number or three), `Ns`, `Ni`, `d` (and `Tr`, as
//! `d = 1 − Tr`), `illum`, and the images `map_Kd`, `map_Bump` (or `bump`) and `norm`, with
//! their options `-s`, `-o` and `-clamp` (`-bm` is kept for a warning). Every other key
//! and option is listed in [`MtlLibrary::ignored`] with its line, for a warning. The file is
//! read through the meshes' bounded [`Source`]: a regular file, no line past
//! [`MAX_LINE_BYTES`](super::MAX_LINE_BYTES).

use super::source::Source;
use crate::error::{Error, Result};
use std::io::BufRead;
use std::path::{Path, PathBuf};

/// A value as an MTL file writes it, with its line (1-based).
#[derive(Clone, Debug, PartialEq)]
pub struct At<T> {
    /// The value.
    pub value: T,
    /// The line it is written on.
    pub line: u64,
}

/// An image an MTL key names, with the options read from before its name.
#[derive(Clone, Debug, PartialEq)]
pub struct MtlMap {
    /// The image file, relative names taken from the `.mtl` file's folder (a backslash
    /// read as a folder separator, as a file written on Windows has it).
    pub file: PathBuf,
    /// `-s u v`: the texture coordinates are multiplied by this (default `[1, 1]`).
    pub scale: [f64; 2],
    /// `-o u v`: then this is added (default `[0, 0]`).
    pub offset: [f64; 2],
    /// `-clamp on`: the image's edge is extended instead of repeated.
    pub clamp: bool,
    /// `-bm m`: a bump map's strength, if given.
    pub bump_multiplier: Option<f64>,
}

/// One `newmtl` entry: the keys this renderer reads, as written.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MtlMaterial {
    /// The name `usemtl` refers to it by.
    pub name: String,
    /// The `.mtl` file it is defined in.
    pub library: PathBuf,
    /// The line of its `newmtl`.
    pub line: u64,
    /// `Kd`: the diffuse colour.
    pub kd: Option<At<[f64; 3]>>,
    /// `Ks`: the specular colour.
    pub ks: Option<At<[f64; 3]>>,
    /// `Ke`: the emitted radiance.
    pub ke: Option<At<[f64; 3]>>,
    /// `Tf`: the transmission filter (a glass's tint).
    pub tf: Option<At<[f64; 3]>>,
    /// `Ns`: the specular exponent.
    pub ns: Option<At<f64>>,
    /// `Ni`: the index of refraction.
    pub ni: Option<At<f64>>,
    /// `d` (or `1 − Tr`): the opacity, 1 opaque.
    pub d: Option<At<f64>>,
    /// `illum`: the illumination model, 0–10.
    pub illum: Option<At<u32>>,
    /// `map_Kd`: the diffuse colour's image.
    pub map_kd: Option<At<MtlMap>>,
    /// `map_Bump` or `bump`: a bump map, which may be a normal map.
    pub bump: Option<At<MtlMap>>,
    /// `norm`: a tangent-space normal map.
    pub norm: Option<At<MtlMap>>,
}

/// A `.mtl` file as read.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MtlLibrary {
    /// The file.
    pub path: PathBuf,
    /// Its materials, in the file's order, each name once.
    pub materials: Vec<MtlMaterial>,
    /// The keys and options read but not used, with their lines (`Ka`, `map_Ks`, `-mm`).
    pub ignored: Vec<At<String>>,
}

/// Reads the material library at `path`.
///
/// # Errors
/// [`Error::Mesh`] naming the file and the line: a file that cannot be read (missing, not
/// a regular file, a line past the bound, not UTF-8), a key before any `newmtl`, a name
/// defined twice, a colour or number that is missing, malformed or not finite, a colour
/// given as a spectrum (`spectral`, `xyz`), an `illum` outside 0–10, or an image key
/// without a file name.
pub fn read(path: &Path) -> Result<MtlLibrary> {
    let fail = |message: String| Error::Mesh {
        path: path.to_path_buf(),
        message,
    };
    let mut source = Source::open(path).map_err(fail)?;
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut library = MtlLibrary {
        path: path.to_path_buf(),
        ..MtlLibrary::default()
    };
    let mut text = String::new();
    loop {
        text.clear();
        let read = source.read_line(&mut text).map_err(|_| {
            fail(
                source
                    .overlong()
                    .unwrap_or_else(|| format!("line {}: cannot be read as text (UTF-8)", source.line())),
            )
        })?;
        if read == 0 {
            break;
        }
        let line = source.line();
        let at = |message: String| fail(format!("line {line}: {message}"));
        let mut words = text.split_whitespace();
        let Some(key) = words.next() else { continue };
        if key.starts_with('#') {
            continue;
        }
        let rest: Vec<&str> = words.collect();
        if key == "newmtl" {
            let name = rest.join(" ");
            if name.is_empty() {
                return Err(at("`newmtl` without a name".into()));
            }
            if let Some(first) = library.materials.iter().find(|m| m.name == name) {
                return Err(at(format!(
                    "material `{name}` is defined twice (first on line {})",
                    first.line
                )));
            }
            library.materials.push(MtlMaterial {
                name,
                library: path.to_path_buf(),
                line,
                ..MtlMaterial::default()
            });
            continue;
        }
        let Some(material) = library.materials.last_mut() else {
            return Err(at(format!("`{key}` comes before any `newmtl`")));
        };
        match key.to_ascii_lowercase().as_str() {
            "kd" => material.kd = on(color(key, &rest).map_err(at)?, line),
            "ks" => material.ks = on(color(key, &rest).map_err(at)?, line),
            "ke" => material.ke = on(color(key, &rest).map_err(at)?, line),
            "tf" => material.tf = on(color(key, &rest).map_err(at)?, line),
            "ns" => material.ns = on(number(key, &rest).map_err(at)?, line),
            "ni" => material.ni = on(number(key, &rest).map_err(at)?, line),
            "d" => {
                let (halo, rest) = match rest.split_first() {
                    Some((&"-halo", rest)) => (true, rest),
                    _ => (false, &rest[..]),
                };
                if halo {
                    library.ignored.push(At {
                        value: "d -halo".into(),
                        line,
                    });
                }
                material.d = on(number(key, rest).map_err(at)?, line);
            }
            "tr" => material.d = on(1.0 - number(key, &rest).map_err(at)?, line),
            "illum" => {
                let n = number(key, &rest).map_err(at)?;
                if !(n.fract() == 0.0 && (0.0..=10.0).contains(&n)) {
                    return Err(at(format!("illum must be an integer from 0 to 10 (got {n})")));
                }
                material.illum = on(n as u32, line);
            }
            "map_kd" => {
                material.map_kd = on(
                    map(key, &rest, folder, line, &mut library.ignored).map_err(at)?,
                    line,
                )
            }
            "map_bump" | "bump" => {
                material.bump = on(
                    map(key, &rest, folder, line, &mut library.ignored).map_err(at)?,
                    line,
                );
            }
            "norm" => {
                material.norm = on(
                    map(key, &rest, folder, line, &mut library.ignored).map_err(at)?,
                    line,
                )
            }
            _ => library.ignored.push(At {
                value: key.to_string(),
                line,
            }),
        }
    }
    Ok(library)
}

/// `value`, written on `line`.
fn on<T>(value: T, line: u64) -> Option<At<T>> {
    Some(At { value, line })
}

/// A number, finite.
fn parse(key: &str, word: &str) -> Result<f64, String> {
    match word.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(x) => Err(format!("`{key}`: {x} is not finite")),
        Err(_) => Err(format!("`{key}`: `{word}` is not a number")),
    }
}

/// The one number of `key`.
fn number(key: &str, words: &[&str]) -> Result<f64, String> {
    match words {
        [x] => parse(key, x),
        _ => Err(format!("`{key}` takes one number (got {})", words.len())),
    }
}

/// The colour of `key`: three numbers, or one for all three channels.
fn color(key: &str, words: &[&str]) -> Result<[f64; 3], String> {
    match words {
        [first, ..] if matches!(*first, "spectral" | "xyz") => Err(format!(
            "`{key} {first}`: a colour given as a spectrum or in XYZ is not read; give `{key} r g b`"
        )),
        [x] => parse(key, x).map(|x| [x; 3]),
        [r, g, b] => Ok([parse(key, r)?, parse(key, g)?, parse(key, b)?]),
        _ => Err(format!(
            "`{key}` takes three numbers, r g b (got {})",
            words.len()
        )),
    }
}

/// How many numbers each texture option takes (at most; `-s`, `-o` and `-t` take one to
/// three).
fn option_arity(option: &str) -> Option<usize> {
    Some(match option {
        "-blendu" | "-blendv" | "-bm" | "-boost" | "-cc" | "-clamp" | "-imfchan" | "-texres" | "-type" => 1,
        "-mm" => 2,
        "-o" | "-s" | "-t" => 3,
        _ => return None,
    })
}

/// The image of `key`: its options, then its file name (which may hold spaces).
fn map(
    key: &str,
    words: &[&str],
    folder: &Path,
    line: u64,
    ignored: &mut Vec<At<String>>,
) -> Result<MtlMap, String> {
    let mut m = MtlMap {
        file: PathBuf::new(),
        scale: [1.0; 2],
        offset: [0.0; 2],
        clamp: false,
        bump_multiplier: None,
    };
    let mut k = 0;
    while let Some(option) = words.get(k).filter(|w| w.starts_with('-')) {
        let Some(most) = option_arity(option) else {
            return Err(format!("`{key}`: unknown option `{option}`"));
        };
        // Up to `most` arguments; the numeric options stop at the first word that is not a number.
        let numeric = !matches!(
            *option,
            "-blendu" | "-blendv" | "-cc" | "-clamp" | "-imfchan" | "-type"
        );
        let mut args = Vec::new();
        while args.len() < most
            && let Some(w) = words.get(k + 1 + args.len())
            && (!numeric || w.parse::<f64>().is_ok())
        {
            args.push(*w);
        }
        if args.is_empty() {
            return Err(format!("`{key}`: option `{option}` needs a value"));
        }
        let numbers = || {
            args.iter()
                .map(|a| parse(key, a))
                .collect::<Result<Vec<f64>, String>>()
        };
        match *option {
            "-s" => {
                let n = numbers()?;
                m.scale = [n[0], *n.get(1).unwrap_or(&1.0)];
            }
            "-o" => {
                let n = numbers()?;
                m.offset = [n[0], *n.get(1).unwrap_or(&0.0)];
            }
            "-clamp" => m.clamp = args[0] == "on",
            "-bm" => m.bump_multiplier = Some(numbers()?[0]),
            _ => ignored.push(At {
                value: format!("{key} {option}"),
                line,
            }),
        }
        k += 1 + args.len();
    }
    let name = words[k.min(words.len())..].join(" ").replace('\\', "/");
    if name.is_empty() {
        return Err(format!("`{key}` names no image file"));
    }
    m.file = folder.join(name);
    Ok(m)
}

#[cfg(test)]
mod tests;
