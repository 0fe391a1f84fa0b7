//! A mesh file opened for reading with bounds a hostile or broken file cannot get past:
//! only a regular file, at most [`MAX_MESH_BYTES`] and never more than its size when
//! opened, and (while it is text) no line longer than [`MAX_LINE_BYTES`]. A file that
//! never ends (a link to `/dev/zero`) or one line of gigabytes is then an error, not an
//! allocation that aborts the process. It counts lines and bytes as they are read, so an
//! error can say where it happened without quoting the file.

use std::fs::File;
use std::io::{self, BufRead, BufReader, Read, Take};
use std::path::Path;

/// The largest mesh file read, in bytes (4 GiB: the largest of the Stanford scans, Lucy,
/// is 0.5 GB as PLY).
pub const MAX_MESH_BYTES: u64 = 4 << 30;

/// The longest line of a text mesh (OBJ, an ASCII PLY or any PLY header), in bytes: far
/// above any real face or vertex line, far below memory.
pub const MAX_LINE_BYTES: u64 = 1 << 20;

/// A mesh file being read: a buffered reader that counts and bounds what it hands out.
pub(super) struct Source {
    inner: BufReader<Take<File>>,
    /// Newlines consumed so far.
    newlines: u64,
    /// Bytes consumed since the last newline.
    line_bytes: u64,
    /// Bytes consumed so far.
    offset: u64,
    /// Whether a line longer than [`MAX_LINE_BYTES`] is refused (text, not binary data).
    text: bool,
    /// Whether reading stopped at a line that was too long.
    overlong: bool,
}

impl Source {
    /// Opens `path` if it is a regular file of at most [`MAX_MESH_BYTES`]; the reason if not.
    pub(super) fn open(path: &Path) -> Result<Self, String> {
        // Asked before opening: opening a FIFO would wait for a writer.
        let meta = std::fs::metadata(path).map_err(|e| format!("cannot open: {e}"))?;
        if !meta.is_file() {
            let kind = if meta.is_dir() {
                "a folder"
            } else {
                "a device, a FIFO or a socket"
            };
            return Err(format!("cannot read {kind}: a mesh must be a regular file"));
        }
        let size = meta.len();
        if size > MAX_MESH_BYTES {
            return Err(format!(
                "the file has {size} bytes; a mesh file may have at most {MAX_MESH_BYTES} ({} GiB)",
                MAX_MESH_BYTES >> 30
            ));
        }
        let file = File::open(path).map_err(|e| format!("cannot open: {e}"))?;
        // The size when asked: a file growing while read is read no further.
        Ok(Self {
            inner: BufReader::new(file.take(size)),
            newlines: 0,
            line_bytes: 0,
            offset: 0,
            text: true,
            overlong: false,
        })
    }

    /// From here on, binary data: no line length bound.
    pub(super) fn binary(&mut self) {
        self.text = false;
    }

    /// The 1-based line of the last byte read (line 1 before any).
    pub(super) fn line(&self) -> u64 {
        if self.line_bytes == 0 && self.newlines > 0 {
            self.newlines
        } else {
            self.newlines + 1
        }
    }

    /// Bytes read so far.
    pub(super) fn offset(&self) -> u64 {
        self.offset
    }

    /// Why reading stopped, if it was a line past [`MAX_LINE_BYTES`]: `line N is longer
    /// than … bytes`.
    pub(super) fn overlong(&self) -> Option<String> {
        self.overlong.then(|| {
            format!(
                "line {} is longer than {MAX_LINE_BYTES} bytes: not a mesh file of this format",
                self.line()
            )
        })
    }
}

impl Read for Source {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = {
            let available = self.fill_buf()?;
            let n = available.len().min(buf.len());
            buf[..n].copy_from_slice(&available[..n]);
            n
        };
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for Source {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        if self.text && self.line_bytes > MAX_LINE_BYTES {
            self.overlong = true;
            return Err(io::Error::new(io::ErrorKind::InvalidData, "line too long"));
        }
        self.inner.fill_buf()
    }

    fn consume(&mut self, n: usize) {
        let taken = &self.inner.buffer()[..n];
        match taken.iter().rposition(|&b| b == b'\n') {
            Some(last) => {
                self.newlines += taken.iter().filter(|&&b| b == b'\n').count() as u64;
                self.line_bytes = (n - last - 1) as u64;
            }
            None => self.line_bytes += n as u64,
        }
        self.offset += n as u64;
        self.inner.consume(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    /// A file of `bytes` in a folder of its own, removed on drop.
    struct Temp(std::path::PathBuf);

    impl Drop for Temp {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(self.0.parent().unwrap());
        }
    }

    fn temp(name: &str, bytes: &[u8]) -> Temp {
        let dir = std::env::temp_dir().join(format!("raytrace-source-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::File::create(&path).unwrap().write_all(bytes).unwrap();
        Temp(path)
    }

    #[test]
    fn lines_are_counted_as_read() {
        let mut s = Source::open(&temp("lines.obj", b"a\nbb\n\nccc").0).unwrap();
        let mut line = String::new();
        assert_eq!(s.line(), 1);
        s.read_line(&mut line).unwrap();
        assert_eq!((s.line(), s.offset()), (1, 2), "the newline ends line 1");
        s.read_line(&mut line).unwrap();
        s.read_line(&mut line).unwrap();
        assert_eq!(s.line(), 3);
        s.read_to_string(&mut line).unwrap();
        assert_eq!((s.line(), s.offset()), (4, 9));
    }

    #[test]
    fn a_line_past_the_bound_stops_text_but_not_binary() {
        let long = vec![b'x'; MAX_LINE_BYTES as usize + 100_000];
        let file = temp("long.obj", &long);
        let path = &file.0;
        let mut s = Source::open(path).unwrap();
        let mut line = String::new();
        assert!(s.read_line(&mut line).is_err());
        assert!(
            s.overlong().unwrap().starts_with("line 1 is longer"),
            "{:?}",
            s.overlong()
        );
        assert!(line.len() as u64 <= MAX_LINE_BYTES + 8192 * 2);
        let mut s = Source::open(path).unwrap();
        s.binary();
        let mut all = Vec::new();
        s.read_to_end(&mut all).unwrap();
        assert_eq!(all.len(), long.len());
    }

    #[test]
    fn only_regular_files_are_read() {
        let err = Source::open(Path::new("/dev/zero")).err().unwrap();
        assert!(err.contains("regular file"), "{err}");
        let err = Source::open(&std::env::temp_dir()).err().unwrap();
        assert!(err.contains("a folder"), "{err}");
        let err = Source::open(Path::new("/no/such/mesh.obj")).err().unwrap();
        assert!(err.starts_with("cannot open"), "{err}");
    }
}
