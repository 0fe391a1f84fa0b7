//! The crate's error type.

mod field;

pub use field::Field;

use std::fmt;
use std::path::PathBuf;

/// Everything that can go wrong building a scene, rendering it or writing it out.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// A scene value outside its domain (NaN, a radius ≤ 0, an albedo outside `[0, 1]`, …).
    InvalidValue {
        /// The constructor's parameter that was rejected.
        field: Field,
        /// Why, with the value itself: `must be > 0 (got -1)`.
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
        /// Where in it: `line 3, column 7`, or a field's path such as `objects[3].radius`
        /// (then `line` says where that value is written).
        location: String,
        /// What is wrong there.
        message: String,
        /// The library's field behind the error, when a constructor (or its check) refused
        /// a value: how a caller tells which value it was without reading `location`.
        field: Option<Field>,
        /// Where the value is written, `(line, column)` (1-based, columns in characters),
        /// when `location` is a field's path and the file's text is known: an invalid value
        /// found as the scene is built.
        line: Option<(usize, usize)>,
    },
    /// A mesh file that cannot be loaded.
    Mesh {
        /// The mesh file.
        path: PathBuf,
        /// What is wrong, naming the element (`face 12`, `vertex 3`, `line 40`, …).
        message: String,
    },
    /// An image file (a texture) that cannot be loaded.
    Image {
        /// The image file.
        path: PathBuf,
        /// What is wrong: missing, not an image, malformed, too large, a value not finite.
        message: String,
    },
    /// Image tiles that do not make one image (or a tile file that cannot be read).
    Tiles(String),
    /// A malformed PFM file.
    Pfm(String),
}

impl Error {
    /// An [`Error::InvalidValue`] for `field` (a [`Field`], or a user type's parameter by
    /// its name).
    pub fn invalid(field: impl Into<Field>, reason: impl Into<String>) -> Self {
        Self::InvalidValue {
            field: field.into(),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidValue { field, reason } => write!(f, "invalid {field}: {reason}"),
            Self::InvalidSettings(reason) => write!(f, "invalid render settings: {reason}"),
            Self::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Self::Ppm(reason) => write!(f, "malformed PPM: {reason}"),
            Self::SceneFile {
                path,
                location,
                message,
                line: Some((line, column)),
                ..
            } => write!(
                f,
                "{}: line {line}, column {column}: {location}: {message}",
                path.display()
            ),
            Self::SceneFile {
                path,
                location,
                message,
                ..
            } => write!(f, "{}: {location}: {message}", path.display()),
            Self::Mesh { path, message } | Self::Image { path, message } => {
                write!(f, "{}: {message}", path.display())
            }
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
