//! Per-sample random streams.

/// The seed of sample `sample` of pixel `pixel`'s generator: SplitMix64 (Steele et al.
/// 2014) of the render seed, mixed with `pixel` Weyl steps and again with `sample` Weyl
/// steps, so neighbouring pixels, samples and render seeds get unrelated streams.
///
/// Every sample has a stream of its own, so a sample's value is the recursion over that
/// sample alone: samples can be traced in any order, batch or thread and give the same
/// bits.
#[inline]
#[must_use]
pub fn sample_seed(seed: u64, pixel: u64, sample: u64) -> u64 {
    seed_in_stream(pixel_stream(seed, pixel), sample)
}

/// The first half of [`sample_seed`], the same for all of a pixel's samples.
#[inline]
pub(super) fn pixel_stream(seed: u64, pixel: u64) -> u64 {
    splitmix64(splitmix64(seed) ^ pixel.wrapping_mul(WEYL))
}

/// The second half of [`sample_seed`]: sample `sample` of the pixel with `stream`.
#[inline]
pub(super) fn seed_in_stream(stream: u64, sample: u64) -> u64 {
    splitmix64(stream ^ sample.wrapping_mul(WEYL))
}

/// The golden-ratio increment of SplitMix64's Weyl sequence, `⌊2⁶⁴/φ⌋` made odd.
const WEYL: u64 = 0x9E37_79B9_7F4A_7C15;

/// One SplitMix64 output for state `x`.
#[inline]
fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(WEYL);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_differ_and_are_stable() {
        // Pinned values: a change here changes every image rendered from a seed.
        assert_eq!(splitmix64(0), 0xE220_A839_7B1D_CDAF);
        assert_eq!(sample_seed(0, 0, 0), 0x2382_75BC_38FC_BE91);
        let seeds = [
            sample_seed(0, 0, 0),
            sample_seed(0, 0, 1),
            sample_seed(0, 1, 0),
            sample_seed(1, 0, 0),
            sample_seed(0, 1, 1),
        ];
        for (i, a) in seeds.iter().enumerate() {
            for b in &seeds[i + 1..] {
                assert_ne!(a, b);
            }
        }
    }
}
