//! The URIs a glTF file names its buffers and images by: a `data:` URI holding the bytes
//! in base64, or a relative reference to a file beside the glTF file (percent-encoded, as
//! RFC 3986 writes `my%20mesh.bin`). Other schemes (`http:`, `file:`) are not read.

use std::path::PathBuf;

/// What a URI names.
#[derive(Debug, PartialEq)]
pub(super) enum Uri {
    /// The bytes written in the URI itself, with its media type (`image/png`; empty when
    /// the URI gives none).
    Data {
        /// The media type.
        mime: String,
        /// The decoded bytes.
        bytes: Vec<u8>,
    },
    /// A file, relative to the glTF file's folder.
    File(PathBuf),
}

/// Reads `text` as a glTF URI; the reason if it cannot be.
pub(super) fn parse(text: &str) -> Result<Uri, String> {
    if let Some(rest) = text.strip_prefix("data:") {
        let Some((head, data)) = rest.split_once(',') else {
            return Err("a data: URI without a `,` before its data".into());
        };
        let Some(mime) = head.strip_suffix(";base64") else {
            return Err(format!(
                "the data: URI `data:{}…` is not base64 (`;base64,`): only base64 data URIs are read",
                head.chars().take(40).collect::<String>()
            ));
        };
        return Ok(Uri::Data {
            mime: mime.to_string(),
            bytes: base64(data)?,
        });
    }
    // A scheme is letters, digits, `+`, `-`, `.` before a `:`, starting with a letter.
    if let Some((scheme, _)) = text.split_once(':') {
        let is_scheme = scheme.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
            && scheme
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c));
        if is_scheme && scheme.len() > 1 {
            return Err(format!(
                "the URI `{}` has the scheme `{scheme}:`: only files beside the glTF file and data: URIs are read",
                text.chars().take(80).collect::<String>()
            ));
        }
    }
    if text.is_empty() {
        return Err("an empty URI".into());
    }
    Ok(Uri::File(PathBuf::from(percent_decoded(text)?)))
}

/// `text` with each `%XX` replaced by the byte it encodes, read as UTF-8.
fn percent_decoded(text: &str) -> Result<String, String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut k = 0;
    while k < bytes.len() {
        if bytes[k] == b'%' {
            let hex = bytes
                .get(k + 1..k + 3)
                .and_then(|h| std::str::from_utf8(h).ok())
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| format!("the URI `{text}` has a `%` not followed by two hex digits"))?;
            out.push(hex);
            k += 3;
        } else {
            out.push(bytes[k]);
            k += 1;
        }
    }
    String::from_utf8(out).map_err(|_| format!("the URI `{text}` does not decode to UTF-8"))
}

/// The bytes of base64 `text` (RFC 4648's alphabet, `=` padding optional; whitespace is
/// not allowed): three bytes for every four characters.
fn base64(text: &str) -> Result<Vec<u8>, String> {
    let value = |c: u8| -> Option<u32> {
        Some(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return None,
        } as u32)
    };
    let data = text.trim_end_matches('=').as_bytes();
    if text.len() - data.len() > 2 || data.len() % 4 == 1 {
        return Err(format!(
            "the base64 data of {} characters is cut short",
            text.len()
        ));
    }
    let mut out = Vec::with_capacity(data.len() / 4 * 3 + 2);
    for (k, group) in data.chunks(4).enumerate() {
        let mut word = 0u32;
        for (j, &c) in group.iter().enumerate() {
            let v = value(c).ok_or_else(|| {
                format!(
                    "the base64 data has `{}` at character {}: not a base64 digit",
                    c.escape_ascii(),
                    4 * k + j
                )
            })?;
            word |= v << (18 - 6 * j);
        }
        // n characters carry n·6 bits: 4 → 3 bytes, 3 → 2, 2 → 1.
        let bytes = word.to_be_bytes();
        out.extend_from_slice(&bytes[1..group.len()]);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_decodes_every_length() {
        // RFC 4648's test vectors.
        for (text, plain) in [
            ("", ""),
            ("Zg==", "f"),
            ("Zm8=", "fo"),
            ("Zm9v", "foo"),
            ("Zm9vYg==", "foob"),
            ("Zm9vYmE", "fooba"),
            ("Zm9vYmFy", "foobar"),
        ] {
            assert_eq!(base64(text).unwrap(), plain.as_bytes(), "{text}");
        }
        assert!(base64("Zm9v!A").unwrap_err().contains("`!` at character 4"));
        assert!(base64("Z").unwrap_err().contains("cut short"));
    }

    #[test]
    fn uris_are_data_or_relative_files() {
        let data = parse("data:application/octet-stream;base64,AAEC").unwrap();
        assert_eq!(
            data,
            Uri::Data {
                mime: "application/octet-stream".into(),
                bytes: vec![0, 1, 2]
            }
        );
        assert_eq!(
            parse("my%20mesh.bin").unwrap(),
            Uri::File(PathBuf::from("my mesh.bin"))
        );
        assert!(
            parse("https://example.com/a.bin")
                .unwrap_err()
                .contains("scheme `https:`")
        );
        assert!(parse("data:text/plain,hello").unwrap_err().contains("not base64"));
        assert!(parse("a%2").unwrap_err().contains("two hex digits"));
    }
}
