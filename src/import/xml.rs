//! Mitsuba 3's XML scene format read into a tree of plugins: `<default>` and `$name`
//! substitution (with values given on the command line first), `<include>`, `<path>`,
//! `id` and `<ref>`, and each property typed. What the plugins mean is the converter's
//! business.

use super::transform::transform;
pub use super::transform::{Step, Transform};
use crate::error::{Error, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The most bytes a scene file (or an included one) may have: the TOML reader's bound.
const MAX_BYTES: u64 = 64 << 20;
/// The deepest `<include>` may nest: beyond, a file includes itself.
const MAX_INCLUDES: usize = 16;
/// The deepest plugins may nest once each `<ref>` is replaced by the plugin it names:
/// beyond, a plugin holds itself.
const MAX_REF_DEPTH: usize = 16;
/// The most `<ref>`s resolved in one scene (each a copy of the plugin it names).
const MAX_REFS: usize = 1 << 16;

/// Where a plugin or a property is written.
#[derive(Clone, Debug, PartialEq)]
pub struct At {
    /// The file.
    pub file: PathBuf,
    /// Its line, from 1.
    pub line: u32,
}

impl At {
    /// An [`Error::SceneFile`] here.
    pub fn error(&self, message: impl Into<String>) -> Error {
        Error::SceneFile {
            path: self.file.clone(),
            location: format!("line {}", self.line),
            message: message.into(),
            field: None,
            line: None,
        }
    }
}

/// A property's value, as its tag types it.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// `<float>`, `<integer>`.
    Number(f64),
    /// `<boolean>`.
    Bool(bool),
    /// `<string>`.
    Text(String),
    /// `<rgb>`, `<point>`, `<vector>`, and a `<spectrum>` of one value (grey).
    Triple([f64; 3]),
    /// `<transform>`.
    Transform(Transform),
}

/// A property: its value and where it is written.
#[derive(Clone, Debug, PartialEq)]
pub struct Property {
    /// The value.
    pub value: Value,
    /// Where.
    pub at: At,
}

/// A plugin: `<shape type="sphere">`, its properties by name and its nested plugins.
#[derive(Clone, Debug, PartialEq)]
pub struct Plugin {
    /// The tag: `shape`, `bsdf`, `emitter`, `sensor`, `texture`, `film`, …
    pub tag: String,
    /// The `type` attribute: `sphere`, `diffuse`, …
    pub kind: String,
    /// The `id` attribute, if any.
    pub id: Option<String>,
    /// The `name` attribute under which it is nested, if any (`reflectance`).
    pub name: Option<String>,
    /// Its properties.
    pub properties: BTreeMap<String, Property>,
    /// Its nested plugins, in order.
    pub children: Vec<Plugin>,
    /// Where it is written.
    pub at: At,
}

impl Plugin {
    /// What a message calls it: `<shape type="sphere">`.
    pub fn label(&self) -> String {
        format!("<{} type=\"{}\">", self.tag, self.kind)
    }
}

/// A scene file as read: its plugins, where its file names are looked for, its `$name`s.
#[derive(Clone, Debug, PartialEq)]
pub struct Document {
    /// The top-level plugins, in order (those of an include where it is included).
    pub plugins: Vec<Plugin>,
    /// The scene's folder, then each `<path>` folder.
    pub folders: Vec<PathBuf>,
    /// Every `$name`'s value: `-D`'s, else the last `<default>`'s.
    pub defines: BTreeMap<String, String>,
}

/// The scene file at `path` as the list of its top-level plugins (and the folders file
/// names are looked for in, and its `$name`s' values), with `defines` (`-D name=value`)
/// overriding its `<default>`s.
///
/// # Errors
/// [`Error::SceneFile`] naming the file and line of a malformed document, an unknown tag,
/// a `$name` nothing defines, a `<ref>` to an unknown id, an include that cannot be read or
/// nests too deep, or a value that is not of its tag's type.
pub fn read(path: &Path, defines: &BTreeMap<String, String>) -> Result<Document> {
    let mut reader = Reader {
        defines: defines.clone(),
        fixed: defines.keys().cloned().collect(),
        ids: BTreeMap::new(),
        folders: vec![path.parent().unwrap_or(Path::new("")).to_path_buf()],
        upgrade: false,
    };
    let mut plugins = Vec::new();
    reader.file(path, 0, &mut plugins)?;
    reader.link(&mut plugins, 0, &mut 0)?;
    Ok(Document {
        plugins,
        folders: reader.folders,
        defines: reader.defines,
    })
}

struct Reader {
    defines: BTreeMap<String, String>,
    /// The names given on the command line: a `<default>` does not replace them.
    fixed: Vec<String>,
    ids: BTreeMap<String, Plugin>,
    /// Where relative file names are looked for: the scene's folder, then each `<path>`.
    folders: Vec<PathBuf>,
    /// Whether the file being read is of Mitsuba 0.x, its names upgraded (`upgrade.rs`).
    upgrade: bool,
}

impl Reader {
    fn file(&mut self, path: &Path, depth: usize, out: &mut Vec<Plugin>) -> Result<()> {
        let whole = |message: String| Error::SceneFile {
            path: path.to_path_buf(),
            location: "the whole file".into(),
            message,
            field: None,
            line: None,
        };
        let meta = std::fs::metadata(path).map_err(|e| whole(format!("cannot read it: {e}")))?;
        if !meta.is_file() || meta.len() > MAX_BYTES {
            return Err(whole(format!(
                "a scene file must be a regular file of at most {} MiB",
                MAX_BYTES >> 20
            )));
        }
        let text = std::fs::read_to_string(path).map_err(|e| whole(format!("cannot read it: {e}")))?;
        let doc = roxmltree::Document::parse(&text).map_err(|e| {
            let p = e.pos();
            Error::SceneFile {
                path: path.to_path_buf(),
                location: format!("line {}, column {}", p.row, p.col),
                message: format!("not well-formed XML: {e}"),
                field: None,
                line: None,
            }
        })?;
        let root = doc.root_element();
        let at = |n: roxmltree::Node| At {
            file: path.to_path_buf(),
            line: doc.text_pos_at(n.range().start).row,
        };
        if root.tag_name().name() != "scene" {
            return Err(at(root).error("the document's element must be <scene>"));
        }
        let outer = std::mem::replace(
            &mut self.upgrade,
            super::upgrade::below_2(root.attribute("version")),
        );
        for node in root.children().filter(roxmltree::Node::is_element) {
            let here = at(node);
            match node.tag_name().name() {
                "default" => {
                    let name = self.attribute(node, "name", &here)?;
                    let value = self.attribute(node, "value", &here)?;
                    if !self.fixed.contains(&name) {
                        self.defines.insert(name, value);
                    }
                }
                "include" => {
                    let name = self.attribute(node, "filename", &here)?;
                    if depth >= MAX_INCLUDES {
                        return Err(here.error(format!("includes nest deeper than {MAX_INCLUDES}")));
                    }
                    let included = self.resolve(&name);
                    self.file(&included, depth + 1, out)?;
                }
                "path" => {
                    let value = self.attribute(node, "value", &here)?;
                    let folder = self.folders[0].join(&value);
                    // Mitsuba refuses a folder that is not there: so does this reader.
                    if !folder.is_dir() {
                        return Err(here.error(format!("<path>: no folder `{value}` beside the scene")));
                    }
                    self.folders.push(folder);
                }
                _ => {
                    let plugin = self.plugin(node, &at)?;
                    out.push(plugin);
                }
            }
        }
        self.upgrade = outer;
        Ok(())
    }

    /// A file name as Mitsuba finds it: in the scene's folder, else in a `<path>` folder.
    pub fn resolve(&self, name: &str) -> PathBuf {
        let candidates = self.folders.iter().map(|f| f.join(name));
        candidates
            .clone()
            .find(|p| p.exists())
            .unwrap_or_else(|| self.folders[0].join(name))
    }

    /// The attribute `name` with every `$name` substituted.
    fn attribute(&self, node: roxmltree::Node, name: &str, at: &At) -> Result<String> {
        let raw = node
            .attribute(name)
            .ok_or_else(|| at.error(format!("<{}> needs a `{name}` attribute", node.tag_name().name())))?;
        self.substitute(raw, at)
    }

    fn substitute(&self, raw: &str, at: &At) -> Result<String> {
        let mut out = String::new();
        let mut rest = raw;
        while let Some(i) = rest.find('$') {
            out.push_str(&rest[..i]);
            let tail = &rest[i + 1..];
            let end = tail
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(tail.len());
            let name = &tail[..end];
            let value = self.defines.get(name).ok_or_else(|| {
                at.error(format!(
                    "`${name}` is not defined (no <default name=\"{name}\"> and no -D {name}=…)"
                ))
            })?;
            out.push_str(value);
            rest = &tail[end..];
        }
        out.push_str(rest);
        Ok(out)
    }

    fn plugin(&mut self, node: roxmltree::Node, at: &impl Fn(roxmltree::Node) -> At) -> Result<Plugin> {
        let here = at(node);
        let tag = node.tag_name().name();
        if tag == "ref" {
            // Kept as it is until the whole scene is read: Mitsuba lets a `<ref>` name a
            // plugin defined after it (its Cornell box puts the lamp's emitter last).
            return Ok(Plugin {
                tag: "ref".into(),
                kind: String::new(),
                id: Some(self.attribute(node, "id", &here)?),
                name: node.attribute("name").map(str::to_owned),
                properties: BTreeMap::new(),
                children: Vec::new(),
                at: here,
            });
        }
        const PLUGINS: [&str; 11] = [
            "shape",
            "bsdf",
            "texture",
            "emitter",
            "sensor",
            "film",
            "sampler",
            "integrator",
            "rfilter",
            "medium",
            "phase",
        ];
        if !PLUGINS.contains(&tag) {
            return Err(here.error(format!("<{tag}> is not a Mitsuba 3 plugin tag here")));
        }
        let mut plugin = Plugin {
            tag: tag.to_owned(),
            kind: self.attribute(node, "type", &here)?,
            id: node
                .attribute("id")
                .map(|s| self.substitute(s, &here))
                .transpose()?,
            name: node.attribute("name").map(str::to_owned),
            properties: BTreeMap::new(),
            children: Vec::new(),
            at: here,
        };
        for child in node.children().filter(roxmltree::Node::is_element) {
            let child_at = at(child);
            let child_tag = child.tag_name().name();
            if PLUGINS.contains(&child_tag) || child_tag == "ref" {
                let nested = self.plugin(child, at)?;
                plugin.children.push(nested);
                continue;
            }
            let name = self.attribute(child, "name", &child_at)?;
            let value = self.value(child, &child_at)?;
            plugin.properties.insert(name, Property { value, at: child_at });
        }
        if self.upgrade {
            super::upgrade::upgrade(&mut plugin);
        }
        if let Some(id) = &plugin.id {
            self.ids.insert(id.clone(), plugin.clone());
        }
        Ok(plugin)
    }

    /// Each `<ref>` among `plugins` (and the plugins they hold) replaced by a copy of the
    /// plugin of its id, under the ref's `name`; `count` counts the copies made.
    fn link(&self, plugins: &mut [Plugin], depth: usize, count: &mut usize) -> Result<()> {
        for p in plugins {
            if p.tag == "ref" {
                let id = p.id.clone().unwrap_or_default();
                let mut target = self.ids.get(&id).cloned().ok_or_else(|| {
                    p.at.error(format!("<ref id=\"{id}\"> names no plugin of the scene"))
                })?;
                *count += 1;
                if depth >= MAX_REF_DEPTH || *count > MAX_REFS {
                    return Err(p.at.error(format!(
                        "<ref id=\"{id}\">: plugins nest deeper than {MAX_REF_DEPTH} or references number \
                         more than {MAX_REFS} (a plugin that holds itself?)"
                    )));
                }
                target.name = p.name.take();
                *p = target;
            }
            self.link(&mut p.children, depth + 1, count)?;
        }
        Ok(())
    }

    fn value(&self, node: roxmltree::Node, at: &At) -> Result<Value> {
        let tag = node.tag_name().name();
        let number = |s: &str| {
            s.trim()
                .parse::<f64>()
                .map_err(|_| at.error(format!("<{tag}>: `{s}` is not a number")))
        };
        Ok(match tag {
            "float" | "integer" => Value::Number(number(&self.attribute(node, "value", at)?)?),
            "boolean" => match self.attribute(node, "value", at)?.as_str() {
                "true" => Value::Bool(true),
                "false" => Value::Bool(false),
                other => return Err(at.error(format!("<boolean>: `{other}` is neither true nor false"))),
            },
            "string" => Value::Text(self.attribute(node, "value", at)?),
            "rgb" | "spectrum" | "point" | "vector" => {
                let triple = if let Some(v) = node.attribute("value") {
                    let v = self.substitute(v, at)?;
                    let parts: Vec<f64> = v
                        .split(|c: char| c == ',' || c.is_whitespace())
                        .filter(|s| !s.is_empty())
                        .map(number)
                        .collect::<Result<_>>()?;
                    match parts[..] {
                        [x] if tag != "point" && tag != "vector" => [x; 3],
                        [x, y, z] if tag != "spectrum" => [x, y, z],
                        _ => {
                            return Err(at.error(format!(
                                "<{tag}>: expected {} numbers",
                                if tag == "spectrum" { "one" } else { "three" }
                            )));
                        }
                    }
                } else {
                    let axis = |a: &str| {
                        node.attribute(a)
                            .map_or(Ok(0.0), |s| number(&self.substitute(s, at)?))
                    };
                    [axis("x")?, axis("y")?, axis("z")?]
                };
                Value::Triple(triple)
            }
            "transform" => Value::Transform(transform(node, at, &|s| self.substitute(s, at))?),
            other => return Err(at.error(format!("<{other}> is not a property tag Mitsuba 3 reads here"))),
        })
    }
}
