//! What a command-line program built on the library needs and the library does not: the
//! worker threads, a memory check before a long render, and output files that no signal
//! leaves half-written. Behind the `cli` feature (on by default).
//!
//! The `raytrace` binary and the examples are such programs, and both use this module:
//! the same thread limit and pool, the same checks, the same cleanup. It lives in the
//! library, not in the binary, because the examples cannot import from a binary; and it
//! lives apart from [`image`](crate::image) because what it holds is process-wide (a list
//! of temporary files and folders, a signal handler, a look at `/proc/meminfo`), which a
//! library used inside someone else's program must not impose.
//!
//! - [`pool`], [`parse_threads`], [`MAX_THREADS`]: the `--threads` option and its pool.
//! - [`check_memory`]: whether the machine has the memory for an image.
//! - [`check_output`], then [`write_file`] or [`write_atomic`]: the output checked before
//!   the render, then written atomically (by the library's writers), with missing folders
//!   created (`mkdir -p`) and removed again if the write fails.
//! - [`clean_up_on_signals`]: SIGINT, SIGTERM and SIGHUP remove every temporary file and
//!   every still-empty folder the program made, say what was stopped, and exit with
//!   128 + the signal's number.

mod files;
mod memory;
mod signals;
mod threads;

pub use files::{check_output, remove_temporary_files, write_atomic, write_file};
pub use memory::{BYTES_PER_PIXEL, check_memory};
pub use signals::{clean_up_on_signals, set_activity};
pub use threads::{MAX_THREADS, parse_threads, pool};
