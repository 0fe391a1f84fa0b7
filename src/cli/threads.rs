//! The worker threads: the `--threads` option's limit and parser, and the pool.

use crate::error::{Error, Result};

/// Most worker threads accepted: far more than the cores of any machine this runs on,
/// while starting many thousands would take minutes or exhaust the system.
pub const MAX_THREADS: usize = 256;

/// Parses a thread count, a whole number from 1 to [`MAX_THREADS`] (a clap value parser).
///
/// # Errors
/// A message saying the range, for anything else.
pub fn parse_threads(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if (1..=MAX_THREADS).contains(&n) => Ok(n),
        _ => Err(format!("expected a whole number from 1 to {MAX_THREADS}")),
    }
}

/// A pool of `threads` worker threads, or one per core for `None`.
///
/// # Errors
/// [`Error::InvalidSettings`] if the system cannot start them.
pub fn pool(threads: Option<usize>) -> Result<rayon::ThreadPool> {
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(t) = threads {
        pool = pool.num_threads(t);
    }
    pool.build().map_err(|e| {
        let threads = threads.map_or_else(|| "a thread per core".into(), |t| format!("{t} threads"));
        Error::InvalidSettings(format!("cannot start {threads}: {e}"))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thread_counts_parse_within_the_limit() {
        assert_eq!(parse_threads("1"), Ok(1));
        assert_eq!(parse_threads("256"), Ok(MAX_THREADS));
        for bad in ["0", "257", "-1", "x", "", " 2"] {
            assert!(parse_threads(bad).unwrap_err().contains("from 1 to 256"), "{bad}");
        }
    }

    #[test]
    fn the_pool_has_the_threads_asked_for() {
        assert_eq!(pool(Some(3)).unwrap().current_num_threads(), 3);
        assert!(pool(None).unwrap().current_num_threads() >= 1);
    }
}
