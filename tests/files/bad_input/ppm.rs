//! The PPM reader: no panic on arbitrary bytes, token soup or edited files; what it accepts round-trips.

use super::REGRESSIONS;
use crate::common::config;
use proptest::prelude::*;
use raytrace::Image16;
use raytrace::image::{parse_ppm, write_ppm_to};

/// A valid 16-bit image, up to 5×5, with a random maximum value and samples up to it.
fn image16() -> impl Strategy<Value = Image16> {
    let max = prop_oneof![Just(65535u16), Just(255u16), Just(1u16), 1u16..=65535];
    (1usize..6, 1usize..6, max).prop_flat_map(|(width, height, max_value)| {
        prop::collection::vec(0..=max_value, 3 * width * height).prop_map(move |samples| Image16 {
            width,
            height,
            max_value,
            samples,
        })
    })
}

fn ppm_bytes(image: &Image16) -> Vec<u8> {
    let mut out = Vec::new();
    write_ppm_to(&mut out, image).expect("writing to a Vec cannot fail");
    out
}

/// Numbers that break naive parsers: beyond `u16`, `u32`, `u64`, the pixel limit, zero.
const HUGE: [&str; 10] = [
    "99999999999999999999999",
    "18446744073709551616",
    "18446744073709551615",
    "4294967296",
    "268435457",
    "65536",
    "65535",
    "16385",
    "0",
    "00000000000000000000000000001",
];

/// An edit of a PPM file.
#[derive(Clone, Debug)]
enum Edit {
    Truncate(prop::sample::Index),
    Delete(prop::sample::Index),
    /// Overwrite a byte with a digit.
    Digit(prop::sample::Index, u8),
    /// Insert a byte (a digit, separator, comment mark, sign, letter or any byte).
    Insert(prop::sample::Index, u8),
    /// Insert one of [`HUGE`], surrounded by spaces or not.
    Number(prop::sample::Index, &'static str, bool),
    /// Duplicate a slice of the file in place.
    Repeat(prop::sample::Index, prop::sample::Index),
}

fn edit() -> impl Strategy<Value = Edit> {
    let byte = prop_oneof![
        (b'0'..=b'9'),
        prop::sample::select(b" \n\t\r#-+eEP3x".to_vec()),
        any::<u8>(),
    ];
    let index = any::<prop::sample::Index>;
    prop_oneof![
        index().prop_map(Edit::Truncate),
        index().prop_map(Edit::Delete),
        (index(), b'0'..=b'9').prop_map(|(i, d)| Edit::Digit(i, d)),
        (index(), byte).prop_map(|(i, b)| Edit::Insert(i, b)),
        (index(), prop::sample::select(HUGE.to_vec()), any::<bool>())
            .prop_map(|(i, s, pad)| Edit::Number(i, s, pad)),
        (index(), index()).prop_map(|(i, j)| Edit::Repeat(i, j)),
    ]
}

fn apply(bytes: &mut Vec<u8>, e: &Edit) {
    let at = |i: &prop::sample::Index, len: usize| i.index(len + 1);
    match e {
        Edit::Truncate(i) => bytes.truncate(at(i, bytes.len())),
        Edit::Delete(i) if !bytes.is_empty() => {
            bytes.remove(i.index(bytes.len()));
        }
        Edit::Delete(_) => {}
        Edit::Digit(i, d) if !bytes.is_empty() => {
            let k = i.index(bytes.len());
            bytes[k] = *d;
        }
        Edit::Digit(..) => {}
        Edit::Insert(i, b) => bytes.insert(at(i, bytes.len()), *b),
        Edit::Number(i, s, pad) => {
            let k = at(i, bytes.len());
            let text = if *pad { format!(" {s} ") } else { s.to_string() };
            bytes.splice(k..k, text.bytes());
        }
        Edit::Repeat(i, j) => {
            let (a, b) = (at(i, bytes.len()), at(j, bytes.len()));
            let (a, b) = (a.min(b), a.max(b).min(a.min(b) + 64));
            let chunk = bytes[a..b].to_vec();
            bytes.splice(b..b, chunk);
        }
    }
}

/// Text made of PPM-like tokens: magic numbers, numbers of every size, comments, signs,
/// exponents, any character, joined by any whitespace (or none).
fn token_soup() -> impl Strategy<Value = Vec<u8>> {
    let token = prop_oneof![
        2 => Just("P3".to_string()),
        1 => Just("P6".to_string()),
        3 => (0u32..70000).prop_map(|n| n.to_string()),
        1 => any::<u64>().prop_map(|n| n.to_string()),
        1 => prop::sample::select(HUGE.to_vec()).prop_map(String::from),
        1 => prop::sample::select(vec!["#", "# comment\n", "-1", "+1", "1e3", "0x10", "1.5", "٣"]).prop_map(String::from),
        1 => any::<char>().prop_map(String::from),
    ];
    let sep = prop::sample::select(vec![" ", "\n", "\t", "\r\n", "", "#c\n", "\u{b}", "\u{c}"]);
    (any::<bool>(), prop::collection::vec((token, sep), 0..40)).prop_map(|(magic, parts)| {
        let mut s = if magic { "P3\n".to_string() } else { String::new() };
        for (t, sep) in parts {
            s.push_str(&t);
            s.push_str(sep);
        }
        s.into_bytes()
    })
}

/// What [`parse_ppm`] accepts is a consistent image — at least 1×1, `3·w·h` samples, a
/// maximum value in `1..=65535` that bounds every sample — and writing it back and parsing
/// again gives the same image. (Errors are fine; a panic fails the property.)
fn check_parse(bytes: &[u8]) -> Result<(), TestCaseError> {
    let Ok(img) = parse_ppm(bytes) else {
        return Ok(());
    };
    prop_assert!(img.width >= 1 && img.height >= 1, "{}×{}", img.width, img.height);
    prop_assert_eq!(img.samples.len(), 3 * img.width * img.height);
    prop_assert!(img.max_value >= 1);
    prop_assert!(
        img.samples.iter().all(|&s| s <= img.max_value),
        "a sample exceeds {}",
        img.max_value
    );
    let again = parse_ppm(&ppm_bytes(&img));
    prop_assert!(
        again.is_ok(),
        "the written file does not parse: {:?}",
        again.err()
    );
    prop_assert_eq!(again.unwrap(), img);
    Ok(())
}

proptest! {
    #![proptest_config(config(10_000, 0xBAD_9916, REGRESSIONS))]

    #[test]
    fn ppm_round_trips(img in image16()) {
        prop_assert_eq!(parse_ppm(&ppm_bytes(&img)).ok(), Some(img));
    }

    #[test]
    fn ppm_reader_survives_arbitrary_bytes(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
        check_parse(&bytes)?;
    }

    #[test]
    fn ppm_reader_survives_token_soup(bytes in token_soup()) {
        check_parse(&bytes)?;
    }

    #[test]
    fn ppm_reader_survives_edited_files(img in image16(), edits in prop::collection::vec(edit(), 1..5)) {
        let mut bytes = ppm_bytes(&img);
        for e in &edits {
            apply(&mut bytes, e);
        }
        check_parse(&bytes)?;
    }
}
