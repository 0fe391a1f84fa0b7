//! The scene file the Embree program reads (`bench/embree/scale.cpp`), all little-endian:
//!
//! ```text
//! 8 bytes  "RTSCALE1"
//! u32      kind: 1 = spheres, 2 = triangles
//! u32      0 (reserved)
//! spheres:   u64 n, then n × (f32 x, f32 y, f32 z, f32 radius)
//! triangles: u64 vertices, u64 triangles, then vertices × (f32 x, y, z),
//!            then triangles × (u32 a, b, c) indexing the vertices from 0
//! ```

use crate::geometry::Geometry;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// The file's first eight bytes.
pub const MAGIC: &[u8; 8] = b"RTSCALE1";

/// Writes `geometry` to `path` in the format above.
///
/// # Errors
/// The file cannot be created or written.
pub fn write(geometry: &Geometry, path: &Path) -> std::io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    out.write_all(MAGIC)?;
    match geometry {
        Geometry::Spheres(spheres) => {
            header(&mut out, 1, &[spheres.len()])?;
            for s in spheres {
                floats(&mut out, s)?;
            }
        }
        Geometry::Mesh { vertices, triangles } => {
            header(&mut out, 2, &[vertices.len(), triangles.len()])?;
            for v in vertices {
                floats(&mut out, v)?;
            }
            for t in triangles {
                for i in t {
                    out.write_all(&i.to_le_bytes())?;
                }
            }
        }
    }
    out.flush()
}

fn header(out: &mut impl Write, kind: u32, counts: &[usize]) -> std::io::Result<()> {
    out.write_all(&kind.to_le_bytes())?;
    out.write_all(&0u32.to_le_bytes())?;
    for &n in counts {
        out.write_all(&(n as u64).to_le_bytes())?;
    }
    Ok(())
}

fn floats(out: &mut impl Write, values: &[f32]) -> std::io::Result<()> {
    values.iter().try_for_each(|v| out.write_all(&v.to_le_bytes()))
}
