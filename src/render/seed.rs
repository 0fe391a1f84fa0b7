//! Per-pixel random streams.

/// The seed of pixel `index`'s generator: SplitMix64 (Steele et al. 2014) applied to the
/// render seed plus `index` Weyl steps, then once more, so neighbouring pixels and
/// neighbouring render seeds get unrelated streams.
#[inline]
pub fn pixel_seed(seed: u64, index: u64) -> u64 {
    splitmix64(splitmix64(seed) ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15))
}

/// One SplitMix64 output for state `x`.
#[inline]
fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
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
        assert_ne!(pixel_seed(0, 0), pixel_seed(0, 1));
        assert_ne!(pixel_seed(0, 1), pixel_seed(1, 0));
        assert_eq!(pixel_seed(42, 7), pixel_seed(42, 7));
    }
}
