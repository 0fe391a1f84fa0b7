//! Reading a glTF accessor's elements out of its buffer view, every range checked first:
//! the view inside its buffer, the last element inside the view. Nothing is allocated
//! before the bytes it is read from are known to be there, so a huge declared `count`
//! is an error, not an allocation.
//!
//! Integer components are read as the glTF specification says: a normalized one as
//! `max(c / (2ᵇ⁻¹ − 1), −1)` (signed) or `c / (2ᵇ − 1)` (unsigned), `b` its bits; one not
//! normalized as its value (`KHR_mesh_quantization`).

use ::gltf::accessor::{Accessor, DataType, Dimensions};

/// How an accessor's elements are laid out in its buffer, checked against the bytes.
struct Layout<'b> {
    /// The buffer view's bytes.
    bytes: &'b [u8],
    /// Where the first element starts, in `bytes`.
    offset: usize,
    /// Bytes from one element to the next.
    stride: usize,
    /// How many elements.
    count: usize,
}

/// The bytes of a component type.
fn size(t: DataType) -> usize {
    match t {
        DataType::I8 | DataType::U8 => 1,
        DataType::I16 | DataType::U16 => 2,
        DataType::U32 | DataType::F32 => 4,
    }
}

/// The components of an element of `d`.
fn components(d: Dimensions) -> usize {
    match d {
        Dimensions::Scalar => 1,
        Dimensions::Vec2 => 2,
        Dimensions::Vec3 => 3,
        Dimensions::Vec4 | Dimensions::Mat2 => 4,
        Dimensions::Mat3 => 9,
        Dimensions::Mat4 => 16,
    }
}

/// The elements of `a` as they lie in `buffers`, every range checked; why not, if they do
/// not all lie there.
fn layout<'b>(a: &Accessor, buffers: &'b [Vec<u8>]) -> Result<Layout<'b>, String> {
    if a.sparse().is_some() {
        return Err("a sparse accessor: not read".into());
    }
    let Some(view) = a.view() else {
        return Err("an accessor without a bufferView (all zeros): not read".into());
    };
    let buffer = &buffers[view.buffer().index()];
    let v = view.index();
    let bytes = view
        .offset()
        .checked_add(view.length())
        .and_then(|end| buffer.get(view.offset()..end))
        .ok_or_else(|| {
            format!(
                "bufferView {v} (byteOffset {} + byteLength {}) runs past its buffer's {} bytes",
                view.offset(),
                view.length(),
                buffer.len()
            )
        })?;
    let element = size(a.data_type()) * components(a.dimensions());
    let stride = view.stride().unwrap_or(element);
    if stride < element {
        return Err(format!(
            "bufferView {v}'s byteStride {stride} is less than an element's {element} bytes"
        ));
    }
    let count = a.count();
    // The last element's end: offset + stride·(count − 1) + element.
    let end = match count.checked_sub(1) {
        None => Some(a.offset()),
        Some(last) => stride
            .checked_mul(last)
            .and_then(|x| x.checked_add(a.offset()))
            .and_then(|x| x.checked_add(element)),
    };
    match end {
        Some(end) if end <= bytes.len() => Ok(Layout {
            bytes,
            offset: a.offset(),
            stride,
            count,
        }),
        _ => Err(format!(
            "{count} elements of {element} bytes (byteOffset {}, stride {stride}) run past bufferView {v}'s \
             {} bytes",
            a.offset(),
            bytes.len()
        )),
    }
}

/// Component `j` of the element starting at `at`, as the specification reads its type.
fn component(bytes: &[u8], at: usize, t: DataType, normalized: bool, j: usize) -> f64 {
    let k = at + j * size(t);
    let two = |k: usize| [bytes[k], bytes[k + 1]];
    let four = |k: usize| [bytes[k], bytes[k + 1], bytes[k + 2], bytes[k + 3]];
    match (t, normalized) {
        (DataType::F32, _) => f64::from(f32::from_le_bytes(four(k))),
        (DataType::I8, false) => f64::from(bytes[k] as i8),
        (DataType::U8, false) => f64::from(bytes[k]),
        (DataType::I16, false) => f64::from(i16::from_le_bytes(two(k))),
        (DataType::U16, false) => f64::from(u16::from_le_bytes(two(k))),
        (DataType::U32, false) => f64::from(u32::from_le_bytes(four(k))),
        (DataType::I8, true) => (f64::from(bytes[k] as i8) / 127.0).max(-1.0),
        (DataType::U8, true) => f64::from(bytes[k]) / 255.0,
        (DataType::I16, true) => (f64::from(i16::from_le_bytes(two(k))) / 32767.0).max(-1.0),
        (DataType::U16, true) => f64::from(u16::from_le_bytes(two(k))) / 65535.0,
        (DataType::U32, true) => f64::from(u32::from_le_bytes(four(k))) / 4294967295.0,
    }
}

/// The elements of `a`, each of `N` components, as numbers: `a` must be of that many
/// components and not of 32-bit unsigned integers (which no vertex attribute is).
pub(super) fn vectors<const N: usize>(a: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<[f64; N]>, String> {
    let n = components(a.dimensions());
    if n != N || matches!(a.dimensions(), Dimensions::Mat2) {
        return Err(format!(
            "accessor {} is of type {:?}: {N} components are read here",
            a.index(),
            a.dimensions()
        ));
    }
    if a.data_type() == DataType::U32 {
        return Err(format!(
            "accessor {} holds unsigned 32-bit integers: a vertex attribute is float or a smaller integer",
            a.index()
        ));
    }
    let l = layout(a, buffers).map_err(|why| format!("accessor {}: {why}", a.index()))?;
    let (t, normalized) = (a.data_type(), a.normalized());
    let mut out = Vec::with_capacity(l.count);
    for e in 0..l.count {
        let at = l.offset + e * l.stride;
        out.push(std::array::from_fn(|j| component(l.bytes, at, t, normalized, j)));
    }
    Ok(out)
}

/// The indices of accessor `a`: scalars of unsigned bytes, shorts or ints, not normalized.
pub(super) fn indices(a: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<u32>, String> {
    let integer = matches!(a.data_type(), DataType::U8 | DataType::U16 | DataType::U32);
    if a.dimensions() != Dimensions::Scalar || !integer || a.normalized() {
        return Err(format!(
            "accessor {} ({:?} of {:?}{}) cannot hold indices: they are scalar unsigned integers",
            a.index(),
            a.dimensions(),
            a.data_type(),
            if a.normalized() { ", normalized" } else { "" }
        ));
    }
    let l = layout(a, buffers).map_err(|why| format!("accessor {}: {why}", a.index()))?;
    let t = a.data_type();
    let mut out = Vec::with_capacity(l.count);
    for e in 0..l.count {
        // An integer of at most 32 bits is exact in f64.
        out.push(component(l.bytes, l.offset + e * l.stride, t, false, 0) as u32);
    }
    Ok(out)
}
