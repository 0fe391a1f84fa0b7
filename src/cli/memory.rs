//! Whether the machine has the memory for an image, checked before a long render
//! allocates it rather than failing (or swapping) partway.

use crate::error::{Error, Result};
use crate::image::check_size;

/// Bytes a render of one pixel holds at its peak: the linear `[f64; 3]` (24 bytes) and
/// its 16-bit copy for PPM or PNG (6 bytes).
pub const BYTES_PER_PIXEL: u64 = 24 + 6;

/// Checks that a `width × height` image is possible ([`check_size`]) and that its
/// [`BYTES_PER_PIXEL`] per pixel fit in the memory the system reports available
/// (`MemAvailable` in `/proc/meminfo`). Where that cannot be read (not Linux, no
/// `/proc`), only the size is checked.
///
/// # Errors
/// [`Error::InvalidSettings`] for an impossible size, or one needing more bytes than
/// are available; the message gives both numbers.
pub fn check_memory(width: usize, height: usize) -> Result<()> {
    check_memory_against(width, height, available_memory())
}

/// [`check_memory`] against `available` bytes (`None`: unknown, not checked).
fn check_memory_against(width: usize, height: usize, available: Option<u64>) -> Result<()> {
    check_size(width, height)?;
    // check_size bounds the pixels by MAX_PIXELS = 2²⁸, so the product fits in u64.
    let needed = width as u64 * height as u64 * BYTES_PER_PIXEL;
    match available {
        Some(available) if needed > available => Err(Error::InvalidSettings(format!(
            "a {width}×{height} image needs {needed} bytes of memory ({} MiB) but only \
             {available} bytes ({} MiB) are available",
            needed >> 20,
            available >> 20
        ))),
        _ => Ok(()),
    }
}

/// The system's available memory in bytes, if it says.
fn available_memory() -> Option<u64> {
    parse_mem_available(&std::fs::read_to_string("/proc/meminfo").ok()?)
}

/// The `MemAvailable:  123456 kB` line of `/proc/meminfo`, in bytes.
fn parse_mem_available(meminfo: &str) -> Option<u64> {
    let line = meminfo.lines().find_map(|l| l.strip_prefix("MemAvailable:"))?;
    let mut words = line.split_whitespace();
    let kib: u64 = words.next()?.parse().ok()?;
    // The kernel has always written kB here (meaning KiB); anything else is not understood.
    (words.next() == Some("kB")).then(|| kib.saturating_mul(1024))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_mem_available() {
        let text = "MemTotal:       24683584 kB\nMemFree:        23683336 kB\n\
                    MemAvailable:   24342908 kB\nBuffers:           1 kB\n";
        assert_eq!(parse_mem_available(text), Some(24_342_908 * 1024));
        assert_eq!(parse_mem_available("MemTotal: 5 kB\n"), None);
        assert_eq!(parse_mem_available("MemAvailable: lots\n"), None);
        assert_eq!(parse_mem_available("MemAvailable: 5 MB\n"), None);
    }

    #[test]
    fn refuses_what_does_not_fit_and_says_how_much() {
        // 1000 × 1000 pixels need 30 000 000 bytes.
        check_memory_against(1000, 1000, Some(30_000_000)).unwrap();
        check_memory_against(1000, 1000, None).unwrap();
        let msg = check_memory_against(1000, 1000, Some(29_999_999))
            .unwrap_err()
            .to_string();
        assert!(msg.contains("needs 30000000 bytes"), "{msg}");
        assert!(msg.contains("only 29999999 bytes"), "{msg}");
    }

    #[test]
    fn the_size_limit_still_applies() {
        assert!(check_memory_against(0, 10, None).is_err());
        assert!(check_memory_against(1 << 15, 1 << 15, Some(u64::MAX)).is_err());
    }

    #[test]
    fn this_machine_can_hold_a_small_image() {
        check_memory(16, 16).unwrap();
    }
}
