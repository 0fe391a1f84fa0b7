use super::*;
use std::io::Write;

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-cli-files-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn count(dir: &Path) -> usize {
    fs::read_dir(dir).unwrap().count()
}

#[test]
fn a_finished_write_is_no_longer_registered() {
    let dir = temp_dir("registry");
    let path = dir.join("out.txt");
    let mut seen = None;
    write_atomic(&path, |w| {
        // Other tests write concurrently: look for this write's own file only.
        seen = registry()
            .temporaries
            .iter()
            .find(|p| p.starts_with(&dir))
            .cloned();
        w.write_all(b"x")
    })
    .unwrap();
    let tmp = seen.expect("the temporary file was not registered during the write");
    assert!(
        !registry().temporaries.contains(&tmp),
        "{} still registered",
        tmp.display()
    );
    assert!(!tmp.exists());
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn missing_folders_are_made_by_the_write_and_removed_if_it_fails() {
    let dir = temp_dir("folders");
    let path = dir.join("new/sub/out.txt");
    // The check makes nothing.
    check_output(&path).unwrap();
    assert_eq!(count(&dir), 0, "the check created something");
    let err = write_atomic(&path, |_| Err(io::Error::other("no space"))).unwrap_err();
    assert!(err.to_string().contains("new/sub/out.txt"), "{err}");
    assert_eq!(count(&dir), 0, "a failed write left its folders");
    write_atomic(&path, |w| w.write_all(b"x")).unwrap();
    assert_eq!(fs::read(&path).unwrap(), b"x");
    // A cleanup after a finished write keeps the folders it holds.
    remove_temporary_files();
    assert!(path.exists());
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_folder_under_a_file_is_named() {
    let dir = temp_dir("unwritable");
    // A folder under a regular file cannot exist, even for root.
    let file = dir.join("plain-file");
    fs::write(&file, "").unwrap();
    let under_file = file.join("sub/out.png");
    let err = check_output(&under_file).unwrap_err().to_string();
    assert!(err.contains("plain-file is a file, not a folder"), "{err}");
    let err = write_atomic(&under_file, |w| w.write_all(b"x"))
        .unwrap_err()
        .to_string();
    assert!(err.contains("plain-file/sub"), "{err}");
    assert_eq!(count(&dir), 1);
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_folder_as_output_is_refused_before_the_render() {
    let dir = temp_dir("folder-out");
    let err = check_output(&dir).unwrap_err().to_string();
    assert!(err.contains("a folder"), "{err}");
    fs::remove_dir_all(dir).unwrap();
}

#[cfg(unix)]
#[test]
fn read_only_folder_is_refused() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir("read-only");
    fs::set_permissions(&dir, fs::Permissions::from_mode(0o555)).unwrap();
    // Root ignores permissions: find out by trying, and skip if so.
    let root = File::create_new(dir.join("probe")).is_ok();
    let result = check_output(&dir.join("x.png"));
    fs::set_permissions(&dir, fs::Permissions::from_mode(0o755)).unwrap();
    if root {
        eprintln!("note: running as root, which may write anywhere: the read-only check is skipped");
    } else {
        let err = result.unwrap_err();
        assert!(err.to_string().contains("cannot write files into"), "{err}");
    }
    fs::remove_dir_all(dir).unwrap();
}
