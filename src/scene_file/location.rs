//! Where in a scene file something is wrong: TOML errors as line and column, value
//! errors as the path of the field.

use crate::error::{Error, Field};
use serde::Deserialize;
use serde_path_to_error::Segment;
use std::ops::Range;
use std::path::Path;
use std::sync::Arc;
use toml::Spanned;
use toml::de::{DeString, DeTable, DeValue};

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

/// Reads `text` into `T`: a syntax error is reported at its line and column; a wrong type,
/// an unknown key or a missing key at the field's path (`camera.vfov`, `objects[3]`) and
/// the line and column of the offending value (or key, or table).
pub fn read<'i, T: Deserialize<'i>>(file: &Path, text: &'i str) -> Result<T, Error> {
    let doc = DeTable::parse(text).map_err(|e| error_at(file, text, e.span(), e.message(), &[]))?;
    let doc = Spanned::new(doc.span(), DeValue::Table(doc.into_inner()));
    let (mut at, message, mut span) = match deserialize::<T>(doc.clone()) {
        Ok(value) => return Ok(value),
        Err(failure) => failure,
    };
    if let Some(node) = lookup(&doc, &at) {
        span = Some(node.span());
        if let DeValue::Table(table) = node.get_ref()
            && !message.starts_with("missing field")
            && let Some((key, value)) = culprit::<T>(&doc, &at, table, &message)
        {
            if message.starts_with("unknown field") {
                span = Some(key.span());
            } else {
                span = Some(value.span());
                at.push(Step::Key(key.get_ref().to_string()));
            }
        }
    }
    Err(error_at(file, text, span, &message, &at))
}

/// One step of a field path: a key of a table or an index of an array.
#[derive(Clone, Debug, PartialEq)]
enum Step {
    Key(String),
    Index(usize),
}

/// Where reading failed: the path serde reached, the message, the span the TOML reader gave.
type Failure = (Vec<Step>, String, Option<Range<usize>>);

/// Deserializes the document `doc` (a table), keeping the path to a failure.
fn deserialize<'i, T: Deserialize<'i>>(doc: Spanned<DeValue<'i>>) -> Result<T, Failure> {
    let span = doc.span();
    let DeValue::Table(table) = doc.into_inner() else {
        unreachable!("a document is a table")
    };
    let reader = toml::Deserializer::from(Spanned::new(span, table));
    serde_path_to_error::deserialize(reader).map_err(|e| {
        let mut steps = e
            .path()
            .iter()
            .filter_map(|s| match s {
                Segment::Map { key } => Some(Step::Key(key.clone())),
                Segment::Seq { index } => Some(Step::Index(*index)),
                Segment::Enum { .. } | Segment::Unknown => None,
            })
            .collect::<Vec<_>>();
        let e = e.into_inner();
        let message = e.message().trim_end().replace('\n', " ");
        // An unknown key is its table's mistake (the path of a tagged entry ends at the
        // table too), so the key leaves the path.
        if let Some(Step::Key(k)) = steps.last()
            && message.starts_with(&format!("unknown field `{k}`"))
        {
            steps.pop();
        }
        (steps, message, e.span())
    })
}

/// The value at `at`, if the document has one there.
fn lookup<'a, 'i>(doc: &'a Spanned<DeValue<'i>>, at: &[Step]) -> Option<&'a Spanned<DeValue<'i>>> {
    at.iter()
        .try_fold(doc, |node, step| match (node.get_ref(), step) {
            (DeValue::Table(t), Step::Key(k)) => t.get(k.as_str()),
            (DeValue::Array(a), Step::Index(i)) => a.get(*i),
            _ => None,
        })
}

fn lookup_mut<'a, 'i>(
    doc: &'a mut Spanned<DeValue<'i>>,
    at: &[Step],
) -> Option<&'a mut Spanned<DeValue<'i>>> {
    at.iter()
        .try_fold(doc, |node, step| match (node.get_mut(), step) {
            (DeValue::Table(t), Step::Key(k)) => t.get_mut(k.as_str()),
            (DeValue::Array(a), Step::Index(i)) => a.get_mut(*i),
            _ => None,
        })
}

/// The key of `table` (at `at`) that the error is about. Serde's path stops at a table it
/// reads through a buffer (a `type`-tagged entry: `camera`, `objects[3]`), so the key is
/// found by reading the file again with the table cut to its first keys, `type` first and
/// the others in the order they are read: the shortest cut that fails the same way ends
/// with the culprit.
fn culprit<'a, 'i, T: Deserialize<'i>>(
    doc: &Spanned<DeValue<'i>>,
    at: &[Step],
    table: &'a DeTable<'i>,
    message: &str,
) -> Option<(&'a Spanned<DeString<'i>>, &'a Spanned<DeValue<'i>>)> {
    let tag = table.get_key_value("type");
    let keys: Vec<_> = tag
        .into_iter()
        .chain(table.iter().filter(|(k, _)| k.get_ref() != "type"))
        .collect();
    let fails_the_same = |n: usize| {
        let mut cut = doc.clone();
        if let Some(DeValue::Table(t)) = lookup_mut(&mut cut, at).map(Spanned::get_mut) {
            *t = keys[..n].iter().map(|&(k, v)| (k.clone(), v.clone())).collect();
        }
        matches!(deserialize::<T>(cut), Err((p, m, _)) if p == at && m == message)
    };
    let shortest = (usize::from(tag.is_some())..=keys.len()).find(|&n| fails_the_same(n))?;
    keys.get(shortest.checked_sub(1)?).copied()
}

/// An [`Error::SceneFile`] at the line and column where `span` starts, the field path
/// `at` (if any) leading the message.
fn error_at(file: &Path, text: &str, span: Option<Range<usize>>, message: &str, at: &[Step]) -> Error {
    let message = plain(&message.trim_end().replace('\n', " "));
    let message = match path_text(at) {
        path if path.is_empty() => message,
        path => format!("{path}: {message}"),
    };
    let location = match span {
        Some(span) => {
            let (line, column) = line_column(text, span.start);
            format!("line {line}, column {column}")
        }
        None => "the whole file".into(),
    };
    Error::SceneFile {
        path: file.to_path_buf(),
        location,
        message,
        field: None,
        line: None,
    }
}

/// The reader's words for what it expected, in the file's terms instead of the model's
/// Rust types (`expected internally tagged enum MaterialSpec`, `expected u32`), and the
/// value it quotes as short as the file would write it.
fn plain(message: &str) -> String {
    const WORDS: [(&str, &str); 11] = [
        ("internally tagged enum CameraSpec", "a table with a `type` key"),
        (
            "internally tagged enum BackgroundSpec",
            "a table with a `type` key",
        ),
        ("internally tagged enum MaterialSpec", "a table with a `type` key"),
        ("internally tagged enum ObjectSpec", "a table with a `type` key"),
        ("internally tagged enum TextureSpec", "a table with a `type` key"),
        ("expected struct RenderOptions", "expected a table"),
        ("expected struct LightFields", "expected a table"),
        ("expected variant identifier", "expected a string naming the type"),
        (
            "wanted string or table",
            "expected a string naming one of the choices",
        ),
        ("expected u32", "expected an integer from 0 to 4294967295"),
        ("expected f64", "expected a number"),
    ];
    let mut message = message
        .replace("expected a sequence", "expected an array")
        .replace(
            "expected string or map",
            "expected a string naming one of the choices",
        );
    for (rust, file) in WORDS {
        message = message.replace(rust, file);
    }
    // serde writes a float in full (`1000…0.0`, hundreds of digits); the file's way is shorter.
    const FLOAT: &str = "floating point `";
    if let Some(start) = message.find(FLOAT).map(|i| i + FLOAT.len())
        && let Some(len) = message[start..].find('`')
        && let Ok(x) = message[start..start + len].parse::<f64>()
    {
        message.replace_range(start..start + len, &crate::validate::number(x));
    }
    message
}

/// `objects[3].radius`, as [`KeyPath`] writes paths.
fn path_text(at: &[Step]) -> String {
    let mut text = String::new();
    for step in at {
        match step {
            Step::Key(k) if text.is_empty() => text.push_str(k),
            Step::Key(k) => {
                text.push('.');
                text.push_str(k);
            }
            Step::Index(i) => text.push_str(&format!("[{i}]")),
        }
    }
    text
}

/// The text a scene file was parsed from, kept to find where a value is written when it
/// is refused. It is not part of the file's value: two files equal in every section are
/// equal whatever text they came from.
#[derive(Clone, Default)]
pub struct Source(Option<Arc<str>>);

impl Source {
    /// The text `text`.
    pub fn new(text: &str) -> Self {
        Self(Some(text.into()))
    }

    /// The text, if the file was parsed from one (not built in code).
    pub fn text(&self) -> Option<&str> {
        self.0.as_deref()
    }
}

impl PartialEq for Source {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// Not the text (up to 64 MiB), and nothing that tells two texts apart: as for equality,
/// the source is not part of the file's value.
impl std::fmt::Debug for Source {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Source(..)")
    }
}

/// A key's path such as `objects[3].radius`, built up as the builder walks the file, with
/// the file's text (if known) to say on which line its value is.
#[derive(Clone, Debug)]
pub struct KeyPath<'a> {
    file: &'a Path,
    path: String,
    steps: Vec<Step>,
    text: Option<&'a str>,
}

impl<'a> KeyPath<'a> {
    /// The top of the file.
    pub fn root(file: &'a Path) -> Self {
        Self {
            file,
            path: String::new(),
            steps: Vec::new(),
            text: None,
        }
    }

    /// The same path in a file whose text is `text`: its errors also say where the value
    /// (or, for one not written, the nearest table around it) is.
    pub fn in_text(self, text: Option<&'a str>) -> Self {
        Self { text, ..self }
    }

    /// The key `name` below this one.
    pub fn key(&self, name: &str) -> Self {
        let path = if self.path.is_empty() {
            name.to_string()
        } else {
            format!("{}.{name}", self.path)
        };
        self.down(path, Step::Key(name.to_string()))
    }

    /// Entry `i` of the array at this key.
    pub fn index(&self, i: usize) -> Self {
        self.down(format!("{}[{i}]", self.path), Step::Index(i))
    }

    fn down(&self, path: String, step: Step) -> Self {
        let mut steps = self.steps.clone();
        steps.push(step);
        Self {
            file: self.file,
            path,
            steps,
            text: self.text,
        }
    }

    /// The line and column of this key's value in the text, or of the nearest table
    /// around it that is written (a key left at its default has no line of its own);
    /// `None` without a text, or at the top of the file.
    fn line(&self) -> Option<(usize, usize)> {
        let text = self.text?;
        let doc = DeTable::parse(text).ok()?;
        let doc = Spanned::new(doc.span(), DeValue::Table(doc.into_inner()));
        (1..=self.steps.len())
            .rev()
            .find_map(|n| lookup(&doc, &self.steps[..n]))
            .map(|node| line_column(text, node.span().start))
    }

    /// An [`Error::SceneFile`] at this key.
    pub fn error(&self, message: impl Into<String>) -> Error {
        self.error_about(None, message)
    }

    /// An [`Error::SceneFile`] at this key, about the library's `field` if there is one.
    pub fn error_about(&self, field: Option<Field>, message: impl Into<String>) -> Error {
        Error::SceneFile {
            path: self.file.to_path_buf(),
            location: self.path.clone(),
            message: message.into(),
            field,
            line: self.line(),
        }
    }

    /// A library error (a mesh that cannot be loaded) as an [`Error::SceneFile`] at this
    /// key, keeping its message.
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
        let f = KeyPath::root(p).key("objects").index(3).key("radius");
        let Error::SceneFile { location, .. } = f.error("x") else {
            panic!()
        };
        assert_eq!(location, "objects[3].radius");
    }
}
