use super::*;
use proptest::prelude::*;
use proptest::test_runner::{FileFailurePersistence, RngSeed};

fn header() -> TileHeader {
    TileHeader {
        scene: "00ff1234abcd".into(),
        settings: "spp=4 max_depth=10 seed=0 precision=f64 a = b".into(),
        image_width: 3,
        image_height: 4,
        rect: Rect {
            x: 1,
            y: 2,
            width: 2,
            height: 1,
        },
    }
}

fn image() -> Image {
    // Values no f32 holds, and one above 1, to show nothing is rounded.
    Image::from_pixels(
        2,
        1,
        vec![[0.1, 1e300, -0.0], [f64::MIN_POSITIVE, 7.25, 1.0 / 3.0]],
    )
    .unwrap()
}

fn temp_path(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("raytrace-tile-{}-{name}", std::process::id()))
}

/// The file `write_tile` makes for `header()` and `image()` (written once: the tests
/// run in parallel).
fn file_bytes() -> Vec<u8> {
    static BYTES: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    BYTES
        .get_or_init(|| {
            let path = temp_path("bytes.rtile");
            write_tile(&path, &header(), &image()).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            std::fs::remove_file(path).unwrap();
            bytes
        })
        .clone()
}

/// The header's text (through the empty line) and the pixel bytes.
fn split() -> (String, Vec<u8>) {
    let bytes = file_bytes();
    let end = bytes.windows(2).position(|w| w == b"\n\n").unwrap() + 2;
    (
        String::from_utf8(bytes[..end].to_vec()).unwrap(),
        bytes[end..].to_vec(),
    )
}

/// FNV-1a 64, written out again from its definition.
fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x100_0000_01b3);
    }
    h
}

/// `head` with its `pixels` key made the checksum of `data`, then `data`: a file whose
/// pixels were changed by someone who also fixed the checksum.
fn resummed(head: &str, data: &[u8]) -> Vec<u8> {
    let start = head.find("pixels = ").unwrap() + 9;
    let head = format!("{}{:016x}{}", &head[..start], fnv1a(data), &head[start + 16..]);
    [head.as_bytes(), data].concat()
}

#[test]
fn writes_the_documented_format() {
    let mut data = Vec::new();
    for c in image().pixels().iter().flatten() {
        data.extend_from_slice(&c.to_le_bytes());
    }
    let mut want = format!(
        "raytrace-tile 2\nscene = 00ff1234abcd\n\
         settings = spp=4 max_depth=10 seed=0 precision=f64 a = b\n\
         image = 3 4\nrect = 1 2 2 1\npixels = {:016x}\n\n",
        fnv1a(&data)
    )
    .into_bytes();
    want.extend(data);
    assert_eq!(file_bytes(), want);
}

#[test]
fn round_trips_bit_for_bit() {
    let path = temp_path("round.rtile");
    write_tile(&path, &header(), &image()).unwrap();
    let (h, img) = read_tile(&path).unwrap();
    std::fs::remove_file(path).unwrap();
    assert_eq!(h, header());
    let bits = |i: &Image| {
        i.pixels()
            .iter()
            .flatten()
            .map(|c| c.to_bits())
            .collect::<Vec<_>>()
    };
    assert_eq!(bits(&img), bits(&image()));
}

#[test]
fn keys_may_come_in_any_order() {
    let (head, data) = split();
    let moved =
        head.replacen("scene = 00ff1234abcd\n", "", 1)
            .replacen("rect =", "scene = 00ff1234abcd\nrect =", 1);
    assert_eq!(
        parse_tile(&[moved.as_bytes(), &data].concat()).unwrap().0,
        header()
    );
}

#[test]
fn bad_files_are_refused_with_a_reason() {
    let (head, data) = split();
    let (head, data) = (head.as_str(), data.as_slice());
    let with = |head: &str, data: &[u8]| [head.as_bytes(), data].concat();
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (b"P6\n".to_vec(), "not a raytrace tile file"),
        (
            with(&head.replace("tile 2", "tile 1"), data),
            "unsupported tile format version \"1\"",
        ),
        (
            with(&head.replacen("pixels = ", "pixels = 0", 1), data),
            "\"pixels\" must be 16 hexadecimal digits",
        ),
        (
            with(&head.replace("scene = 00ff1234abcd\n", ""), data),
            "\"scene\" is missing",
        ),
        (
            with(&head.replace("rect = 1 2 2 1\n", ""), data),
            "\"rect\" is missing",
        ),
        (
            with(&head.replace("image = 3 4\n", "image = 3 4\nimage = 3 4\n"), data),
            "given twice",
        ),
        (
            with(&head.replace("image =", "colour ="), data),
            "unknown header key \"colour\"",
        ),
        (
            with(&head.replace("image = 3 4", "image 3 4"), data),
            "not `key = value`",
        ),
        (
            with(&head.replace("image = 3 4", "image = 3 x"), data),
            "must be `width height`",
        ),
        (
            with(&head.replace("rect = 1 2 2 1", "rect = 1 2 2"), data),
            "`x y width height`",
        ),
        (
            with(&head.replace("rect = 1 2 2 1", "rect = 2 2 2 1"), data),
            "outside the 3×4 image",
        ),
        (
            with(&head.replace("scene = 00ff", "scene = zz"), data),
            "hexadecimal",
        ),
        (
            with(head, &data[..47]),
            "truncated: a 2×1 tile needs 48 bytes of pixels, found 47",
        ),
        (with(head, &[data, &[0]].concat()), "trailing bytes"),
        (head.as_bytes()[..30].to_vec(), "file ends inside the header"),
    ];
    for (bytes, want) in cases {
        let msg = parse_tile(&bytes).unwrap_err().to_string();
        assert!(msg.contains(want), "{:?}: {msg}", String::from_utf8_lossy(&bytes));
    }
}

#[test]
fn damaged_pixels_are_refused() {
    let (head, data) = split();
    // Every single flipped bit of the pixels is caught by the checksum.
    for at in 0..data.len() {
        for bit in 0..8 {
            let mut bad = data.clone();
            bad[at] ^= 1 << bit;
            let msg = parse_tile(&[head.as_bytes(), &bad].concat())
                .unwrap_err()
                .to_string();
            assert!(msg.contains("changed or damaged"), "byte {at} bit {bit}: {msg}");
        }
    }
    // A NaN or a negative value with a checksum that matches is refused too.
    let nan = [&data[..8], &f64::NAN.to_le_bytes(), &data[16..]].concat();
    let msg = parse_tile(&resummed(&head, &nan)).unwrap_err().to_string();
    assert!(msg.contains("pixel (0, 0)") && msg.contains("NaN"), "{msg}");
    let negative = [&data[..40], &(-2.5f64).to_le_bytes()].concat();
    let msg = parse_tile(&resummed(&head, &negative)).unwrap_err().to_string();
    assert!(msg.contains("pixel (1, 0)") && msg.contains("-2.5"), "{msg}");
    // The helper makes a file that reads when the values are good.
    assert!(parse_tile(&resummed(&head, &data)).is_ok());
    let missing = head
        .lines()
        .filter(|l| !l.starts_with("pixels"))
        .collect::<Vec<_>>()
        .join("\n");
    let msg = parse_tile(&[format!("{missing}\n\n").as_bytes(), &data].concat())
        .unwrap_err()
        .to_string();
    assert!(msg.contains("\"pixels\" is missing"), "{msg}");
}

#[test]
fn read_errors_name_the_file() {
    let path = temp_path("garbage.rtile");
    std::fs::write(&path, "hello\n").unwrap();
    let msg = read_tile(&path).unwrap_err().to_string();
    std::fs::remove_file(&path).unwrap();
    assert!(
        msg.contains("garbage.rtile") && msg.contains("not a raytrace tile"),
        "{msg}"
    );
}

#[test]
fn writing_checks_the_header_and_the_size() {
    let path = temp_path("never.rtile");
    let mut h = header();
    h.settings = "two\nlines".into();
    let msg = write_tile(&path, &h, &image()).unwrap_err().to_string();
    assert!(msg.contains("control characters"), "{msg}");
    let msg = write_tile(&path, &header(), &Image::new(1, 1).unwrap())
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("the image is 1×1 but the rect 1 2 2 1 is 2×1"),
        "{msg}"
    );
    let nan = Image::from_pixels(2, 1, vec![[0.0; 3], [0.0, f64::NAN, 0.0]]).unwrap();
    let msg = write_tile(&path, &header(), &nan).unwrap_err().to_string();
    assert!(msg.contains("pixel (1, 0)") && msg.contains("NaN"), "{msg}");
    assert!(!path.exists());
}

proptest! {
    // Seeded, so every run tries the same inputs; failures are kept for re-running.
    #![proptest_config(ProptestConfig {
        cases: 1000,
        rng_seed: RngSeed::Fixed(0x711e),
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct("proptest-regressions/image_tile.txt"))),
        ..ProptestConfig::default()
    })]
    #[test]
    fn never_panics_on_arbitrary_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        let _ = parse_tile(&bytes);
    }

    #[test]
    fn never_panics_on_a_damaged_file(at in 0usize..200, byte in any::<u8>(), cut in 0usize..200) {
        let mut bytes = file_bytes();
        let n = bytes.len();
        bytes[at % n] = byte;
        bytes.truncate(n - cut % n);
        let _ = parse_tile(&bytes);
    }

    /// A tile with one byte changed anywhere is refused, or reads as the tile written
    /// (a changed header value that still parses, such as the scene hash, is for the
    /// merge to catch).
    #[test]
    fn a_changed_pixel_byte_never_reads(at in 0usize..48, byte in any::<u8>()) {
        let (head, data) = split();
        let mut bad = data.clone();
        bad[at] = byte;
        let read = parse_tile(&[head.as_bytes(), &bad].concat());
        prop_assert_eq!(read.is_ok(), byte == data[at]);
    }
}
