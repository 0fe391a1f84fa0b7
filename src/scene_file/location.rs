//! Where in a scene file something is wrong: TOML errors as line and column, value
//! errors as the path of the field.

use crate::error::Error;
use std::path::Path;

/// The 1-based line and column (in characters) of byte `offset` of `text`; an offset
/// past the end or inside a character counts as the end or that character.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut end = offset.min(text.len());
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    let before = &text[..end];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[line_start..].chars().count() + 1)
}

/// A TOML syntax or type error as [`Error::SceneFile`] at its line and column.
pub fn toml_error(path: &Path, text: &str, e: &toml::de::Error) -> Error {
    let message = e.message().trim_end();
    let Some(span) = e.span() else {
        return Error::SceneFile {
            path: path.to_path_buf(),
            location: "the whole file".into(),
            message: message.to_string(),
        };
    };
    let message = message.replace('\n', " ");
    let start = refine(text, span.start, &message);
    let (line, column) = line_column(text, start);
    // A wrong value's message names only the type; the key is what precedes it.
    let message = match key_before(text, start) {
        Some(key) if !message.contains(&format!("`{key}`")) => match message.split_once(": ") {
            Some((entry, rest)) if !entry.contains(' ') => format!("{entry}.{key}: {rest}"),
            _ => format!("`{key}`: {message}"),
        },
        _ => message,
    };
    Error::SceneFile {
        path: path.to_path_buf(),
        location: format!("line {line}, column {column}"),
        message,
    }
}

/// A better start for an error inside an entry (`objects[3]: ...`,
/// `materials.gold: ...`), which the TOML reader places at the start of the whole section:
/// the entry's own header line and, for an unknown or wrong key named in the message,
/// that key's line. Falls back to `offset` when the entry is not written with a header.
fn refine(text: &str, offset: usize, message: &str) -> usize {
    let Some((entry, rest)) = message.split_once(": ") else {
        return offset;
    };
    let header = match entry.split_once('[') {
        Some((name, index)) => index
            .strip_suffix(']')
            .and_then(|i| i.parse::<usize>().ok())
            .map(|i| (format!("[[{name}]]"), i)),
        None => entry.contains('.').then(|| (format!("[{entry}]"), 0)),
    };
    let Some((header, nth)) = header else {
        return offset;
    };
    let lines = || {
        text.split_inclusive('\n').scan(0, |at, line| {
            let start = *at;
            *at += line.len();
            Some((start, line.trim()))
        })
    };
    let Some(entry_start) = lines()
        .filter(|(_, line)| line.starts_with(&header))
        .nth(nth)
        .map(|(start, _)| start)
    else {
        return offset;
    };
    // The key the message names: `unknown field `k``, or `in `k`` after a bad value.
    let named = rest
        .strip_prefix("unknown field `")
        .or_else(|| rest.rsplit_once("in `").map(|(_, k)| k))
        .and_then(|k| k.split_once('`'))
        .map(|(k, _)| k);
    let key_line = named.and_then(|k| {
        lines()
            .skip_while(|&(start, _)| start <= entry_start)
            .take_while(|(_, line)| !line.starts_with('['))
            .find(|(_, line)| {
                line.strip_prefix(k)
                    .is_some_and(|r| r.trim_start().starts_with('='))
            })
            .map(|(start, _)| start)
    });
    // A value of the wrong type: the line whose value is the one the message shows.
    let shown = rest
        .strip_prefix("invalid type: ")
        .and_then(|r| r.split_once(", expected"))
        .and_then(|(r, _)| r.split_once(' '))
        .map(|(_, v)| v.trim_matches('`'));
    let value = shown.and_then(|v| {
        lines()
            .skip_while(|&(start, _)| start <= entry_start)
            .take_while(|(_, line)| !line.starts_with('['))
            .find_map(|(start, _)| {
                let line = text[start..].lines().next()?;
                let (_, after) = line.split_once('=')?;
                (after.trim() == v).then(|| start + line.len() - after.trim_start().len())
            })
    });
    key_line.or(value).unwrap_or(entry_start)
}

/// The key of `key = value` when `offset` is where the value starts on its line.
fn key_before(text: &str, offset: usize) -> Option<&str> {
    let line_start = text.get(..offset)?.rfind('\n').map_or(0, |i| i + 1);
    let key = text[line_start..offset].trim_end().strip_suffix('=')?.trim();
    let bare = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-' || c == '.';
    (!key.is_empty() && key.chars().all(bare)).then_some(key)
}

/// A field path such as `objects[3].radius`, built up as the builder walks the file.
#[derive(Clone, Debug)]
pub struct Field<'a> {
    file: &'a Path,
    path: String,
}

impl<'a> Field<'a> {
    /// The top of the file.
    pub fn root(file: &'a Path) -> Self {
        Self {
            file,
            path: String::new(),
        }
    }

    /// The key `name` below this field.
    pub fn key(&self, name: &str) -> Self {
        let path = if self.path.is_empty() {
            name.to_string()
        } else {
            format!("{}.{name}", self.path)
        };
        Self {
            file: self.file,
            path,
        }
    }

    /// Entry `i` of the array at this field.
    pub fn index(&self, i: usize) -> Self {
        Self {
            file: self.file,
            path: format!("{}[{i}]", self.path),
        }
    }

    /// An [`Error::SceneFile`] at this field.
    pub fn error(&self, message: impl Into<String>) -> Error {
        Error::SceneFile {
            path: self.file.to_path_buf(),
            location: self.path.clone(),
            message: message.into(),
        }
    }

    /// A library error (a constructor's [`Error::InvalidValue`], a mesh that cannot be
    /// loaded) as an [`Error::SceneFile`] at this field, keeping its message.
    pub fn wrap(&self, e: Error) -> Error {
        self.error(e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_become_lines_and_columns() {
        let text = "a = 1\nbé = 2\n\nc";
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, 4), (1, 5));
        assert_eq!(line_column(text, 6), (2, 1));
        // 'é' is two bytes but one column.
        assert_eq!(line_column(text, 9), (2, 3));
        assert_eq!(line_column(text, 8), (2, 2), "inside a character counts as it");
        assert_eq!(line_column(text, 15), (4, 1));
        assert_eq!(line_column(text, 99), (4, 2), "past the end is the end");
    }

    #[test]
    fn field_paths_read_like_the_file() {
        let p = Path::new("s.toml");
        let f = Field::root(p).key("objects").index(3).key("radius");
        let Error::SceneFile { location, .. } = f.error("x") else {
            panic!()
        };
        assert_eq!(location, "objects[3].radius");
    }
}
