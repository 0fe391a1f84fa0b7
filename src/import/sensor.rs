//! Mitsuba 3's `<sensor>` plugins as the scene file's `[camera]` and `[render]`:
//! `perspective` and `thinlens` as the `look_at` camera, their `hdrfilm` and sampler as
//! the width and the samples per pixel; and this renderer's `raytrace_screen` extension,
//! the specification's camera.

use super::convert::Importer;
use super::exact;
use super::xml::Plugin;
use crate::error::Result;
use crate::scene_file::CameraSpec;

/// Mitsuba's default focal length, 50 mm, on its 36 × 24 mm film: the field of view along
/// the film's diagonal is `2·atan(√(36² + 24²)/(2·50))`.
const FILM_DIAGONAL_MM: f64 = 43.266_615_305_567_875;

impl Importer {
    pub(super) fn sensor(&mut self, s: &Plugin) -> Result<()> {
        self.read(s);
        if s.kind == "raytrace_screen" {
            return self.screen(s);
        }
        if s.kind != "perspective" && s.kind != "thinlens" {
            return Err(self.unsupported(s, &s.kind));
        }
        let (width, height) = self.film(s)?;
        let height = height.unwrap_or(576.0);
        let m = self.to_world(s)?;
        let r = m.rows();
        let det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1])
            - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
            + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
        if det <= 0.0 {
            return Err(s.at.error(format!(
                "{}: a mirrored camera (to_world with a negative determinant) is not supported",
                s.label()
            )));
        }
        let aspect = width / height;
        let vfov = self.vertical_fov(s, aspect)?;
        let (aperture, focus_distance) = if s.kind == "thinlens" {
            // Mitsuba focuses a lens given no distance at its far clipping plane.
            let far = self.number(s, "far_clip")?.unwrap_or(1e4);
            (
                self.number(s, "aperture_radius")?.unwrap_or(0.03),
                Some(self.number(s, "focus_distance")?.unwrap_or(far)),
            )
        } else {
            (0.0, None)
        };
        // A lone `lookat` keeps its numbers: the same camera, rounded as a scene file's.
        let (from, at, up) = match exact::look_at(self.steps(s)) {
            Some([origin, target, up]) => (origin, target, up),
            None => (
                m.point([0.0; 3]),
                m.point([0.0, 0.0, 1.0]),
                m.vector([0.0, 1.0, 0.0]),
            ),
        };
        self.file.render.width = width as usize;
        self.file.camera = CameraSpec::LookAt {
            from,
            at,
            up,
            vfov,
            aspect,
            aperture,
            focus_distance,
        };
        Ok(())
    }

    /// The vertical field of view in degrees: `fov` along `fov_axis`, or Mitsuba's
    /// `focal_length` (default 50 mm) along the diagonal of a 36 × 24 mm film. A `fov`
    /// along the vertical axis is kept as written.
    fn vertical_fov(&self, s: &Plugin, aspect: f64) -> Result<f64> {
        let (fov, axis) = match self.number(s, "fov")? {
            Some(fov) => (fov, self.text(s, "fov_axis")?.unwrap_or_else(|| "x".into())),
            None => {
                let focal = self.text(s, "focal_length")?.unwrap_or_else(|| "50mm".into());
                let mm = focal
                    .strip_suffix("mm")
                    .and_then(|n| n.trim().parse::<f64>().ok())
                    .filter(|f| *f > 0.0)
                    .ok_or_else(|| {
                        s.at.error(format!(
                            "{}: focal_length `{focal}` is not like `50mm`",
                            s.label()
                        ))
                    })?;
                let fov = 2.0 * (FILM_DIAGONAL_MM / (2.0 * mm)).atan().to_degrees();
                (fov, "diagonal".into())
            }
        };
        // tan(fov/2) over this is tan(vfov/2).
        let divisor = match axis.as_str() {
            "x" => aspect,
            "y" => 1.0,
            "diagonal" => (1.0 + aspect * aspect).sqrt(),
            "smaller" | "larger" if (aspect >= 1.0) == (axis == "smaller") => 1.0,
            "smaller" | "larger" => aspect,
            other => return Err(s.at.error(format!("{}: no fov_axis `{other}`", s.label()))),
        };
        if divisor == 1.0 {
            return Ok(fov);
        }
        Ok(2.0 * ((fov.to_radians() / 2.0).tan() / divisor).atan().to_degrees())
    }

    /// The sensor's `hdrfilm` width (Mitsuba's default 768) and height, if given (the
    /// default is the camera's), and its sampler's `sample_count` as the samples per
    /// pixel; another filter or sampler is a warning.
    fn film(&mut self, s: &Plugin) -> Result<(f64, Option<f64>)> {
        let (mut width, mut height) = (768.0, None);
        for c in &s.children {
            self.read(c);
            match (c.tag.as_str(), c.kind.as_str()) {
                ("film", "hdrfilm") => {
                    width = self.number(c, "width")?.unwrap_or(width);
                    height = self.number(c, "height")?.or(height);
                    for f in c
                        .children
                        .iter()
                        .filter(|f| f.tag == "rfilter" && f.kind != "box")
                    {
                        self.warn(
                            f,
                            "rendered with a box filter (each sample counts for its own pixel)".into(),
                        );
                    }
                }
                ("sampler", kind) => {
                    if kind != "independent" {
                        self.warn(c, "rendered with independent uniform samples".into());
                    }
                    self.file.render.spp = self.number(c, "sample_count")?.unwrap_or(4.0) as u32;
                }
                _ => return Err(self.unsupported(c, &c.kind)),
            }
        }
        Ok((width, height))
    }

    /// `<sensor type="raytrace_screen">`: the specification's camera (`[camera] type =
    /// "screen"`), its eye at `eye` (default the origin); its image is `width × width/2`.
    fn screen(&mut self, s: &Plugin) -> Result<()> {
        let (width, height) = self.film(s)?;
        if let Some(height) = height.filter(|h| *h != width / 2.0) {
            return Err(s.at.error(format!(
                "{}: the screen camera's image is width × width/2, not {width} × {height}",
                s.label()
            )));
        }
        self.file.render.width = width as usize;
        self.file.camera = CameraSpec::Screen {
            eye: self.triple(s, "eye")?,
        };
        Ok(())
    }
}
