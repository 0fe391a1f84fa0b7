//! The crate's error type.

use std::fmt;
use std::path::PathBuf;

/// Everything that can go wrong building a scene, rendering it or writing it out.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// A scene value outside its domain (NaN, a radius ≤ 0, an albedo outside `[0, 1]`, …).
    InvalidValue {
        /// What was being built, e.g. `"sphere radius"`.
        what: &'static str,
        /// Why the value was rejected, with the value itself.
        reason: String,
    },
    /// Render settings that cannot work (zero samples, an image size the camera rejects, …).
    InvalidSettings(String),
    /// An I/O failure, naming the file it concerns.
    Io {
        /// The file being read or written.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// A malformed PPM file.
    Ppm(String),
    /// A scene file that does not describe a scene.
    SceneFile {
        /// The scene file.
        path: PathBuf,
        /// Where in it: `line 3, column 7`, or a field's path such as `objects[3].radius`.
        location: String,
        /// What is wrong there.
        message: String,
    },
    /// A mesh file that cannot be loaded.
    Mesh {
        /// The mesh file.
        path: PathBuf,
        /// What is wrong, naming the element (`face 12`, `vertex 3`, `line 40`, …).
        message: String,
    },
    /// Image tiles that do not make one image (or a tile file that cannot be read).
    Tiles(String),
    /// A malformed PFM file.
    Pfm(String),
}

impl Error {
    /// An [`Error::InvalidValue`] for `what`.
    pub fn invalid(what: &'static str, reason: impl Into<String>) -> Self {
        Self::InvalidValue {
            what,
            reason: reason.into(),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidValue { what, reason } => write!(f, "invalid {what}: {reason}"),
            Self::InvalidSettings(reason) => write!(f, "invalid render settings: {reason}"),
            Self::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Self::Ppm(reason) => write!(f, "malformed PPM: {reason}"),
            Self::SceneFile {
                path,
                location,
                message,
            } => write!(f, "{}: {location}: {message}", path.display()),
            Self::Mesh { path, message } => write!(f, "{}: {message}", path.display()),
            Self::Tiles(reason) => write!(f, "tiles: {reason}"),
            Self::Pfm(reason) => write!(f, "malformed PFM: {reason}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

/// The crate's result type.
pub type Result<T, E = Error> = std::result::Result<T, E>;
