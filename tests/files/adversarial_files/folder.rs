//! The folder tools of the adversarial cases: what a folder holds, and the edits and
//! special files the cases prepare.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// What a folder holds: each path under it, with its kind and, for a file, its bytes.
pub(super) fn snapshot(dir: &Path) -> BTreeMap<PathBuf, String> {
    let mut all = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            let meta = fs::symlink_metadata(&path).unwrap();
            let t = meta.file_type();
            let what = if t.is_symlink() {
                format!("link to {}", fs::read_link(&path).unwrap().display())
            } else if t.is_dir() {
                stack.push(path.clone());
                "folder".into()
            } else if t.is_file() {
                format!("file {:?}", fs::read(&path).unwrap())
            } else {
                format!("special {t:?}")
            };
            all.insert(path.strip_prefix(dir).unwrap().to_path_buf(), what);
        }
    }
    all
}

/// Replaces the pixel bytes `at..at + 8` of tile `name` with `value`, and the checksum
/// with the new pixels' (an edit by someone who knew the format).
pub(super) fn edit_pixel(dir: &Path, name: &str, at: usize, value: f64) {
    let bytes = fs::read(dir.join(name)).unwrap();
    let end = bytes.windows(2).position(|w| w == b"\n\n").unwrap() + 2;
    let (head, mut data) = (
        String::from_utf8(bytes[..end].to_vec()).unwrap(),
        bytes[end..].to_vec(),
    );
    data[at..at + 8].copy_from_slice(&value.to_le_bytes());
    let sum = data.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    });
    let start = head.find("pixels = ").unwrap() + 9;
    let head = format!("{}{sum:016x}{}", &head[..start], &head[start + 16..]);
    fs::write(dir.join(name), [head.as_bytes(), &data].concat()).unwrap();
}

/// Makes a node with `mknod`; false (with a note) where that is not permitted.
pub(super) fn mknod(path: &Path, args: &[&str]) -> bool {
    let ok = Command::new("mknod")
        .arg(path)
        .args(args)
        .status()
        .is_ok_and(|s| s.success());
    if !ok {
        eprintln!("note: mknod is not permitted here: {} skipped", path.display());
    }
    ok
}

#[cfg(unix)]
pub(super) fn symlink(target: &str, link: &Path) -> bool {
    std::os::unix::fs::symlink(target, link).unwrap();
    true
}
