use super::*;

const HEADER: &str = "#?RADIANCE\n# made by hand\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n";

/// The file of `header`, then `resolution`, then `data`.
fn file(resolution: &str, data: &[u8]) -> Vec<u8> {
    let mut bytes = format!("{HEADER}{resolution}\n").into_bytes();
    bytes.extend(data);
    bytes
}

fn decode(bytes: &[u8]) -> Result<(usize, usize, Vec<[f32; 3]>), String> {
    read(bytes)
}

#[test]
fn a_pixel_is_its_mantissas_times_two_to_the_exponent_less_136() {
    assert_eq!(radiance([128, 64, 32, 129]), [1.0, 0.5, 0.25]);
    assert_eq!(radiance([255, 1, 0, 136]), [255.0, 1.0, 0.0]);
    assert_eq!(radiance([200, 200, 200, 0]), [0.0; 3], "e = 0 is black");
    // The extremes are exact: 2^-135 is an f32 subnormal, 255 · 2^119 below f32::MAX.
    assert_eq!(
        radiance([1, 3, 0, 1]),
        [2f32.powi(-135), 3.0 * 2f32.powi(-135), 0.0]
    );
    assert_eq!(radiance([255, 0, 0, 255])[0], 255.0 * 2f32.powi(119));
    assert!(radiance([255, 0, 0, 255])[0].is_finite());
}

/// Two scanlines of eight pixels, the same values in the three encodings.
#[test]
fn run_length_flat_and_old_runs_read_alike() {
    let row = |y: u8| -> Vec<[u8; 4]> {
        (0..8u8)
            .map(|x| {
                if x < 5 {
                    [10 + y, 20, 30, 130]
                } else {
                    [x, y, 99, 128 + x]
                }
            })
            .collect()
    };
    let want: Vec<[f32; 3]> = (0..2).flat_map(row).map(radiance).collect();
    // Per channel: a run of five, then three literals.
    let mut rle = Vec::new();
    for y in 0..2 {
        let r = row(y);
        rle.extend([2, 2, 0, 8]);
        for c in 0..4 {
            let channel: Vec<u8> = r.iter().map(|p| p[c]).collect();
            rle.extend([128 + 5, channel[0], 3]);
            rle.extend(&channel[5..]);
        }
    }
    let flat: Vec<u8> = (0..2).flat_map(row).flatten().collect();
    // The first pixel, then (1, 1, 1, 4): four more of it.
    let mut old = Vec::new();
    for y in 0..2 {
        let r = row(y);
        old.extend(r[0]);
        old.extend([1, 1, 1, 4]);
        old.extend(r[5..].iter().flatten());
    }
    for data in [rle, flat, old] {
        assert_eq!(decode(&file("-Y 2 +X 8", &data)), Ok((8, 2, want.clone())));
    }
}

#[test]
fn a_second_run_marker_shifts_its_count_by_eight_bits() {
    // 1 + 2 + (1 << 8) · 1 = 259 pixels of the first.
    let data = [[7, 7, 7, 130], [1, 1, 1, 2], [1, 1, 1, 1]].concat();
    let (w, h, pixels) = decode(&file("-Y 1 +X 259", &data)).unwrap();
    assert_eq!((w, h), (259, 1));
    assert!(pixels.iter().all(|&p| p == radiance([7, 7, 7, 130])));
}

#[test]
fn a_bad_file_is_an_error_saying_why() {
    let cases: [(Vec<u8>, &str); 9] = [
        (b"RADIANCE\n\n-Y 1 +X 1\n".to_vec(), "does not start with `#?`"),
        (
            b"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n".to_vec(),
            "`32-bit_rle_xyze` is not read",
        ),
        (file("+Y 1 +X 1", &[0; 4]), "not `-Y height +X width`"),
        (file("-Y one +X 1", &[0; 4]), "not two sizes"),
        (file("-Y 1 +X 2", &[1, 1, 1, 1, 0, 0, 0, 0]), "starts with a run"),
        (
            file("-Y 1 +X 2", &[5, 5, 5, 5, 1, 1, 1, 2]),
            "past the end of its scanline",
        ),
        (file("-Y 1 +X 8", &[2, 2, 0, 9]), "9 pixels wide, not 8"),
        (
            file("-Y 1 +X 8", &[2, 2, 0, 8, 128 + 9, 1]),
            "past the end of its scanline",
        ),
        (
            file("-Y 2 +X 1", &[1, 2, 3, 4]),
            "cannot decode the Radiance HDR pixels",
        ),
    ];
    for (bytes, words) in cases {
        let message = decode(&bytes).unwrap_err();
        assert!(message.contains(words), "{words}: {message}");
    }
    assert!(
        decode(&file("-Y 1 +X 8", &[2, 2, 0, 8, 0]))
            .unwrap_err()
            .contains("empty run")
    );
    let long = format!("#?RADIANCE\n{}\n", "x".repeat(5000));
    assert!(decode(long.as_bytes()).unwrap_err().contains("line too long"));
    assert!(
        decode(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n")
            .unwrap_err()
            .contains("ends early")
    );
}

#[test]
fn the_size_is_checked_before_any_pixel_is_read() {
    let message = decode(&file("-Y 70000 +X 70000", &[])).unwrap_err();
    assert!(message.contains("too large for memory"), "{message}");
}
