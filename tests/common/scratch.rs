//! A scratch folder for a test's files (images, meshes, materials), removed on drop.

use std::path::PathBuf;

/// A scratch folder for one test, named by the process and the test; removed on drop.
pub struct Scratch(pub PathBuf);

impl Scratch {
    pub fn new(test: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("raytrace-scratch-{}-{test}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    /// The path of `name` in the folder.
    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// Writes `bytes` to the file `name` in the folder and returns its path.
    pub fn file(&self, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
        let path = self.path(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }

    /// Writes an 8-bit RGB PNG of `w × h` pixels, row by row from the top.
    pub fn png8(&self, name: &str, w: u32, h: u32, rgb: &[[u8; 3]]) -> PathBuf {
        let data = rgb.iter().flatten().copied().collect();
        let path = self.path(name);
        image::RgbImage::from_raw(w, h, data)
            .unwrap()
            .save_with_format(&path, image::ImageFormat::Png)
            .unwrap();
        path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
