use super::*;
use std::io::Write;

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-atomic-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn failed_write_leaves_nothing_and_keeps_the_old_file() {
    let dir = temp_dir("fail");
    let path = dir.join("out.txt");
    fs::write(&path, "old").unwrap();
    let err = write_atomic(&path, |w| {
        w.write_all(b"partial")?;
        Err(io::Error::other("disk full"))
    })
    .unwrap_err();
    assert!(err.to_string().contains("out.txt"), "{err}");
    assert_eq!(fs::read_to_string(&path).unwrap(), "old");
    assert_eq!(names(&dir), ["out.txt"], "temporary file left behind");
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn success_replaces_and_missing_folder_is_named() {
    let dir = temp_dir("ok");
    let path = dir.join("out.txt");
    write_atomic(&path, |w| w.write_all(b"new")).unwrap();
    assert_eq!(fs::read_to_string(&path).unwrap(), "new");
    let missing = dir.join("no/such/folder/x.ppm");
    let err = write_atomic(&missing, |w| w.write_all(b"x")).unwrap_err();
    assert!(err.to_string().contains("no/such/folder/x.ppm"), "{err}");
    assert!(!dir.join("no").exists(), "the library creates no folders");
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_longest_legal_name_is_written() {
    let dir = temp_dir("long-name");
    for len in [243, 250, 255] {
        // Multi-byte characters too: the temporary name is cut at a character boundary.
        let name = format!("{}é.ppm", "a".repeat(len - 6));
        assert_eq!(name.len(), len);
        let path = dir.join(&name);
        write_atomic(&path, |w| w.write_all(b"x")).unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"x", "{len} bytes");
        let tmp = temporary_path(&path).unwrap();
        assert!(tmp.file_name().unwrap().len() <= NAME_MAX, "{}", tmp.display());
        fs::remove_file(path).unwrap();
    }
    assert_eq!(names(&dir), Vec::<String>::new());
    fs::remove_dir_all(dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_is_written_through() {
    let dir = temp_dir("symlink");
    let (target, link) = (dir.join("real.txt"), dir.join("link.txt"));
    fs::write(&target, "old").unwrap();
    std::os::unix::fs::symlink("real.txt", &link).unwrap();
    write_atomic(&link, |w| w.write_all(b"new")).unwrap();
    assert!(
        fs::symlink_metadata(&link).unwrap().file_type().is_symlink(),
        "the link was replaced"
    );
    assert_eq!(fs::read_to_string(&target).unwrap(), "new");
    assert_eq!(names(&dir), ["link.txt", "real.txt"]);
    // A link to nothing is refused, and creates nothing.
    let dangling = dir.join("dangling.txt");
    std::os::unix::fs::symlink("missing.txt", &dangling).unwrap();
    let err = write_atomic(&dangling, |w| w.write_all(b"x"))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("dangling.txt") && err.contains("link to nothing"),
        "{err}"
    );
    assert_eq!(names(&dir), ["dangling.txt", "link.txt", "real.txt"]);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_folder_is_refused() {
    let dir = temp_dir("folder");
    let err = write_atomic(&dir, |w| w.write_all(b"x")).unwrap_err().to_string();
    assert!(err.contains("a folder"), "{err}");
    fs::remove_dir_all(dir).unwrap();
}

/// Makes the device node `path` with `mknod`, or says why not (no `mknod`, not root).
#[cfg(unix)]
fn mknod(path: &Path, kind: &str, major: u32, minor: u32) -> bool {
    let made = std::process::Command::new("mknod")
        .arg(path)
        .args([kind, &major.to_string(), &minor.to_string()])
        .status()
        .is_ok_and(|s| s.success());
    if !made {
        eprintln!("note: mknod is not permitted here; the device test is skipped");
    }
    made
}

#[cfg(unix)]
#[test]
fn a_device_is_streamed_into_never_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let dir = temp_dir("device");
    // /dev/null's numbers: writes vanish.
    let null = dir.join("null.png");
    if mknod(&null, "c", 1, 3) {
        write_atomic(&null, |w| w.write_all(&[7; 100_000])).unwrap();
        assert!(fs::symlink_metadata(&null).unwrap().file_type().is_char_device());
        // /dev/full's: the failure is reported, and the node stays.
        let full = dir.join("full.png");
        assert!(mknod(&full, "c", 1, 7));
        let err = write_atomic(&full, |w| w.write_all(&[7; 100_000])).unwrap_err();
        assert!(err.to_string().contains("full.png"), "{err}");
        assert!(fs::symlink_metadata(&full).unwrap().file_type().is_char_device());
        // A block device is refused (a loop device's numbers; it is never opened).
        let block = dir.join("disk.png");
        assert!(mknod(&block, "b", 7, 0));
        let err = write_atomic(&block, |w| w.write_all(b"x"))
            .unwrap_err()
            .to_string();
        assert!(err.contains("block device"), "{err}");
        assert!(
            fs::symlink_metadata(&block)
                .unwrap()
                .file_type()
                .is_block_device()
        );
        assert_eq!(names(&dir), ["disk.png", "full.png", "null.png"]);
    }
    fs::remove_dir_all(dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_fifo_is_streamed_into() {
    use std::os::unix::fs::FileTypeExt;
    use std::process::{Command, Stdio};
    let dir = temp_dir("fifo");
    let fifo = dir.join("pipe.ppm");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    // A process, which can be stopped if nothing ever writes into the FIFO.
    let mut reader = Command::new("cat")
        .arg(&fifo)
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let result = write_atomic(&fifo, |w| w.write_all(b"P3\n1 1\n65535\n0 0 0\n"));
    if result.is_err() || !fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo() {
        reader.kill().unwrap();
    }
    result.unwrap();
    assert_eq!(
        reader.wait_with_output().unwrap().stdout,
        b"P3\n1 1\n65535\n0 0 0\n"
    );
    assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    assert_eq!(names(&dir), ["pipe.ppm"]);
    fs::remove_dir_all(dir).unwrap();
}
