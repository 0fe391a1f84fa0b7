//! Scripted draws: a generator that replays chosen words, and the words that make chosen points.

use rand::rngs::Xoshiro256PlusPlus;
use rand::{Rng, SeedableRng, TryRng};
use raytrace::{Float, Vec3};
use std::convert::Infallible;

/// A generator that replays `script` word by word, then continues with a seeded
/// xoshiro256++ stream; it counts the words it has handed out.
pub(crate) struct Scripted {
    pub(crate) script: Vec<u64>,
    pub(crate) drawn: usize,
    rest: Xoshiro256PlusPlus,
}

impl Scripted {
    pub(crate) fn new(script: Vec<u64>) -> Self {
        Self {
            script,
            drawn: 0,
            rest: Xoshiro256PlusPlus::seed_from_u64(0x5C_217),
        }
    }
}

impl TryRng for Scripted {
    type Error = Infallible;
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok((self.try_next_u64()? >> 32) as u32)
    }
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        let w = match self.script.get(self.drawn) {
            Some(&w) => w,
            None => self.rest.next_u64(),
        };
        self.drawn += 1;
        Ok(w)
    }
    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        for chunk in dst.chunks_mut(8) {
            let w = self.try_next_u64()?.to_le_bytes();
            chunk.copy_from_slice(&w[..chunk.len()]);
        }
        Ok(())
    }
}

/// `2⁻⁵²`: the grid of scriptable coordinates.
pub(crate) const GRID: f64 = f64::EPSILON;

/// The word that makes the spec's sampler draw the coordinate nearest `x ∈ [−1, 1)` on the
/// grid `k·2⁻⁵² − 1` (see the module docs).
pub(crate) fn word_for(x: f64) -> u64 {
    let k = ((x + 1.0) / GRID).round().clamp(0.0, (1u64 << 53) as f64 - 1.0) as u64;
    k << 11
}

/// The coordinate the sampler draws from word `w`: `2u − 1`, `u = (w >> 11)·2⁻⁵³`, as
/// rand 0.10 and [`raytrace::sampling::uniform`] compute it.
pub(crate) fn coordinate(w: u64) -> f64 {
    2.0 * ((w >> 11) as f64 * (GRID / 2.0)) - 1.0
}

/// The unit vector `S` the spec's rejection sampler makes of the point `X` (`None` if it
/// rejects `X`), rounded to `F`, computed as [`unit_sphere_rejection`] does.
pub(crate) fn sphere_point<F: Float>(x: [f64; 3]) -> Option<Vec3<F>> {
    let len2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    (len2 <= 1.0 && len2 > 1e-12).then(|| {
        let inv = 1.0 / len2.sqrt();
        Vec3::from_f64(x[0] * inv, x[1] * inv, x[2] * inv)
    })
}

/// The three words of a scripted point `X`.
pub(crate) fn words(x: [f64; 3]) -> [u64; 3] {
    x.map(word_for)
}

/// The point `X` the three words `w` make.
pub(crate) fn point(w: [u64; 3]) -> [f64; 3] {
    w.map(coordinate)
}
