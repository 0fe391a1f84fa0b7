//! [`ImageTexture`]: an image looked up at `uv` with bilinear filtering, Mitsuba 3's
//! `bitmap` texture.

use super::{Bitmap, UvMap};
use crate::error::Result;
use crate::float::{Float, lit};
use crate::vec3::Color;
use std::sync::Arc;

/// What a lookup outside `[0, 1]²` sees (Mitsuba 3's `wrap_mode`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Wrap {
    /// The image tiles the plane (the default).
    #[default]
    Repeat,
    /// The edge pixels extend without end.
    Clamp,
}

/// An image over the surface, as Mitsuba 3's `bitmap` texture with its default
/// `filter_type = "bilinear"` (`src/textures/bitmap.cpp`, which looks up through Dr.Jit's
/// `Texture`, `include/drjit/texture_impl.h`'s `tex_eval` and `tex_wrap`):
///
/// - `(u, v) = map(uv)` ([`UvMap`], its `to_uv`);
/// - `u` runs along a row from the left edge (`u = 0`) to the right (`u = 1`), and `v`
///   down the image from its top row as the file stores it (`v = 0`) to its bottom
///   (`v = 1`): row 0 of the file is `v ∈ [0, 1/H)`. A mesh's texture coordinates read
///   from an OBJ file are flipped (`v ↦ 1 − v`) by Mitsuba's default, so there `vt`'s
///   `v = 0` is the image's bottom, as OBJ means it;
/// - pixel `(i, j)`'s centre sits at `((i + ½)/W, (j + ½)/H)`: with `x = u·W − ½`,
///   `y = v·H − ½`, `i = ⌊x⌋`, `j = ⌊y⌋`, `a = x − i`, `b = y − j`, the value is
///   `(1 − b)·((1 − a)·p(i, j) + a·p(i + 1, j)) + b·((1 − a)·p(i, j + 1) + a·p(i + 1, j + 1))`,
///   each index first wrapped: [`Wrap::Repeat`] takes it modulo the size (`i mod W`, in
///   `[0, W)`), [`Wrap::Clamp`] clamps it to `[0, W − 1]`.
///
/// The pixels are shared ([`Bitmap`] behind an `Arc`); the texture itself is small.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageTexture<F> {
    bitmap: Arc<Bitmap>,
    wrap: Wrap,
    map: UvMap<F>,
}

impl<F: Float> ImageTexture<F> {
    /// The image of `bitmap`, repeated, at `uv` unmapped.
    pub fn new(bitmap: Arc<Bitmap>) -> Self {
        Self {
            bitmap,
            wrap: Wrap::Repeat,
            map: UvMap::default(),
        }
    }

    /// The same texture wrapping as `wrap` says.
    #[must_use]
    pub fn with_wrap(self, wrap: Wrap) -> Self {
        Self { wrap, ..self }
    }

    /// The same texture looked up at `map(uv)`.
    #[must_use]
    pub fn with_uv_map(self, map: UvMap<F>) -> Self {
        Self { map, ..self }
    }

    /// The pixels.
    pub fn bitmap(&self) -> &Arc<Bitmap> {
        &self.bitmap
    }

    /// How lookups outside `[0, 1]²` wrap.
    pub fn wrap(&self) -> Wrap {
        self.wrap
    }

    /// The map applied to `uv`.
    pub fn uv_map(&self) -> UvMap<F> {
        self.map
    }

    /// The filtered colour at `uv`.
    #[inline(never)]
    pub fn eval(&self, uv: [F; 2]) -> Color<F> {
        let [(i0, i1, a), (j0, j1, b)] = self.corners(uv);
        let p = |i, j| {
            let [r, g, b] = self.bitmap.texel(i, j);
            Color::from_f64(f64::from(r), f64::from(g), f64::from(b))
        };
        // `x + t·(y − x)`: equal neighbours give their value exactly, whatever the weight.
        let lerp = |x: Color<F>, y: Color<F>, t: F| x + (y - x) * t;
        lerp(lerp(p(i0, j0), p(i1, j0), a), lerp(p(i0, j1), p(i1, j1), a), b)
    }

    /// The filtered value at `uv` as one number: the grey value of a grey image, else the
    /// luminance `0.212671 R + 0.715160 G + 0.072169 B` (Mitsuba 3's `luminance` of linear
    /// sRGB, what its bitmap's `eval_1` gives).
    pub fn eval_scalar(&self, uv: [F; 2]) -> F {
        let c = self.eval(uv);
        if self.bitmap.is_grey() {
            c.x
        } else {
            c.x * lit(0.212671) + c.y * lit(0.715160) + c.z * lit(0.072169)
        }
    }

    /// The two columns and two rows bilinear filtering reads at `uv`, each wrapped, and
    /// the weights `a`, `b` of the second of each.
    #[inline]
    fn corners(&self, uv: [F; 2]) -> [(usize, usize, F); 2] {
        let [u, v] = self.map.apply(uv);
        let half = lit::<F>(0.5);
        let axis = |t: F, size: usize| {
            let x = t * F::from_f64(size as f64) - half;
            let floor = x.floor();
            // NaN and values past i64's range saturate; the wrap brings any into range.
            let i = floor.to_f64() as i64;
            let weight = x - floor;
            let weight = if weight.is_finite() { weight } else { F::zero() };
            (
                self.wrapped(i, size),
                self.wrapped(i.saturating_add(1), size),
                weight,
            )
        };
        [axis(u, self.bitmap.width()), axis(v, self.bitmap.height())]
    }

    /// Index `i` of an axis of `size` pixels, wrapped into `[0, size)`.
    #[inline]
    fn wrapped(&self, i: i64, size: usize) -> usize {
        let n = size as i64;
        let k = match self.wrap {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::Clamp => i.clamp(0, n - 1),
        };
        k as usize
    }

    /// This texture in scalar `G`: the same pixels, the map rounded.
    ///
    /// # Errors
    /// As [`UvMap::cast`].
    pub fn cast<G: Float>(&self) -> Result<ImageTexture<G>> {
        Ok(ImageTexture {
            bitmap: Arc::clone(&self.bitmap),
            wrap: self.wrap,
            map: self.map.cast()?,
        })
    }
}
