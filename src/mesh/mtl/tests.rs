//! The MTL reader's tests: keys and their lines, map options, and malformed files named at
//! their line.

use super::*;

/// `text` written as `NAME.mtl` in a folder of this process and test, `NAME`.
fn file(name: &str, text: impl AsRef<[u8]>) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-mtl-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.mtl"));
    std::fs::write(&path, text).unwrap();
    path
}

/// Removes the folder `file` made for `path`.
fn clean(path: &Path) {
    std::fs::remove_dir_all(path.parent().unwrap()).unwrap();
}

fn error(name: &str, text: &[u8]) -> String {
    let path = file(name, text);
    let got = read(&path);
    clean(&path);
    match got {
        Err(Error::Mesh { message, .. }) => message,
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn keys_are_read_with_their_lines() {
    let path = file(
        "keys",
        "# Blender\nnewmtl red paint\nNs 250\nKa 1 1 1\nKd 0.8 0.1 0.1\r\nKs 0.5\nKe 0 0 0\nNi 1.45\nd 1\nillum 2\n\n\
         newmtl glass\nTr 0.25\nTf 0.9 1 0.9\nmap_Kd -s 2 3 -o 0.5 0 0 -clamp on -mm 0 1 tex\\wood grain.png\n\
         map_Bump -bm 0.5 bump.png\nnorm normals.png\n",
    );
    let lib = read(&path).unwrap();
    clean(&path);
    let [red, glass] = &lib.materials[..] else {
        panic!("{lib:?}")
    };
    assert_eq!(
        (red.name.as_str(), red.line, red.library.as_path()),
        ("red paint", 2, path.as_path())
    );
    assert_eq!(
        red.kd,
        Some(At {
            value: [0.8, 0.1, 0.1],
            line: 5
        })
    );
    assert_eq!(
        red.ks,
        Some(At {
            value: [0.5; 3],
            line: 6
        })
    );
    assert_eq!(red.ke.as_ref().map(|k| k.value), Some([0.0; 3]));
    assert_eq!(red.ns.as_ref().map(|n| (n.value, n.line)), Some((250.0, 3)));
    assert_eq!(red.ni.as_ref().map(|n| n.value), Some(1.45));
    assert_eq!(red.d.as_ref().map(|d| d.value), Some(1.0));
    assert_eq!(red.illum.as_ref().map(|i| (i.value, i.line)), Some((2, 10)));
    assert_eq!(glass.d.as_ref().map(|d| (d.value, d.line)), Some((0.75, 13)));
    assert_eq!(glass.tf.as_ref().map(|t| t.value), Some([0.9, 1.0, 0.9]));
    let map = &glass.map_kd.as_ref().unwrap().value;
    let folder = path.parent().unwrap();
    assert_eq!(map.file, folder.join("tex/wood grain.png"));
    assert_eq!((map.scale, map.offset, map.clamp), ([2.0, 3.0], [0.5, 0.0], true));
    let bump = glass.bump.as_ref().unwrap();
    assert_eq!((bump.line, bump.value.bump_multiplier), (16, Some(0.5)));
    assert_eq!(
        glass.norm.as_ref().unwrap().value.file,
        folder.join("normals.png")
    );
    let ignored: Vec<_> = lib.ignored.iter().map(|i| (i.value.as_str(), i.line)).collect();
    assert_eq!(ignored, [("Ka", 4), ("map_Kd -mm", 15)]);
}

#[test]
fn malformed_files_are_named_at_their_line() {
    for (name, text, words) in [
        ("orphan", "Kd 1 1 1\n", "line 1: `Kd` comes before any `newmtl`"),
        ("unnamed", "newmtl\n", "line 1: `newmtl` without a name"),
        (
            "twice",
            "newmtl a\nnewmtl b\n\nnewmtl a\n",
            "line 4: material `a` is defined twice (first on line 1)",
        ),
        ("two", "newmtl a\nKd 1 1\n", "line 2: `Kd` takes three numbers"),
        (
            "word",
            "newmtl a\nNs shiny\n",
            "line 2: `Ns`: `shiny` is not a number",
        ),
        ("nan", "newmtl a\nKs 1 nan 1\n", "line 2: `Ks`: NaN is not finite"),
        (
            "spectral",
            "newmtl a\nKd spectral red.rfl\n",
            "line 2: `Kd spectral`",
        ),
        (
            "illum",
            "newmtl a\nillum 12\n",
            "line 2: illum must be an integer from 0 to 10",
        ),
        (
            "nofile",
            "newmtl a\nmap_Kd -s 2 2\n",
            "line 2: `map_Kd` names no image file",
        ),
        (
            "option",
            "newmtl a\nmap_Kd -zoom 2 a.png\n",
            "line 2: `map_Kd`: unknown option `-zoom`",
        ),
    ] {
        let message = error(name, text.as_bytes());
        assert!(message.contains(words), "{name}: {message}");
    }
    for (name, text, words) in [
        (
            "binary",
            &b"newmtl a\nKd \xff\xfe\n"[..],
            "line 2: cannot be read as text",
        ),
        ("long", vec![b'#'; 2 << 20].as_slice(), "line 1 is longer than"),
    ] {
        let message = error(name, text);
        assert!(message.contains(words), "{name}: {message}");
    }
    let missing = read(Path::new("/no/such/file.mtl")).unwrap_err().to_string();
    assert!(
        missing.contains("/no/such/file.mtl") && missing.contains("cannot open"),
        "{missing}"
    );
}
