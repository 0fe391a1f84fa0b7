//! Mitsuba 3's `<integrator>` plugins as the path tracer's depth: `path` (`max_depth`),
//! `direct` (direct illumination: Mitsuba's `max_depth` of 2, the light seen and the
//! light reflected once) and `moment` (the image of the integrator it holds).

use super::convert::Importer;
use super::xml::Plugin;
use crate::error::Result;

/// Mitsuba's depth for direct illumination: the emitter seen, then one reflection.
const DIRECT_DEPTH: f64 = 2.0;

impl Importer {
    /// The `max_depth` of the integrator `p` as Mitsuba counts it (`None`: its default,
    /// unbounded).
    pub(super) fn integrator(&mut self, p: &Plugin) -> Result<Option<f64>> {
        self.read(p);
        match p.kind.as_str() {
            "path" => self.number(p, "max_depth"),
            "direct" => {
                // Each strategy's sample count changes the noise, not the mean, unless it
                // is zero: then Mitsuba leaves out what only that strategy finds.
                for (name, what) in [
                    ("emitter_samples", "point, spot and directional lights"),
                    ("bsdf_samples", "emitters seen in mirrors and through glass"),
                ] {
                    if self.number(p, name)? == Some(0.0) {
                        self.warn(
                            p,
                            format!(
                                "`{name}` 0: Mitsuba leaves out what only that strategy finds ({what}); \
                                 here every path reflected once is traced"
                            ),
                        );
                    }
                }
                if let Some(n) = self.number(p, "emitter_samples")?.filter(|n| *n > 1.0) {
                    // direct.cpp gives a delta emitter's sample the weight 1, not 1/n.
                    self.warn(
                        p,
                        format!(
                            "`emitter_samples` {n}: Mitsuba 3.9.1 counts each point, spot and directional light \
                             that many times (its image is {n} times as bright where they light); here once"
                        ),
                    );
                }
                Ok(Some(DIRECT_DEPTH))
            }
            "moment" => {
                let inner: Vec<&Plugin> = p.children.iter().filter(|c| c.tag == "integrator").collect();
                let [inner] = inner[..] else {
                    return Err(p.at.error(format!("{}: holds one <integrator>", p.label())));
                };
                self.warn(
                    p,
                    "rendered as the integrator it holds: its image, without the second moments".into(),
                );
                self.integrator(inner)
            }
            other => Err(self.unsupported(p, other)),
        }
    }
}
