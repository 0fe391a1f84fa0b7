//! What one run measured, printed in the format the Embree program prints too.

/// One run's figures.
pub struct Measurement {
    /// The scene's name, `spheres:N` or `dragon:RES`.
    pub scene: String,
    /// Spheres or triangles in it.
    pub primitives: usize,
    /// Which program and scalar: `raytrace-f32`, `raytrace-f64`.
    pub program: String,
    /// Render threads.
    pub threads: usize,
    /// Seconds to build the acceleration structure.
    pub build_s: f64,
    /// Seconds to render.
    pub render_s: f64,
    /// Rays traced.
    pub rays: u64,
    /// The process's peak resident memory in MB (10⁶ bytes).
    pub peak_mb: f64,
}

impl Measurement {
    /// Million rays per second of the render's wall time.
    pub fn mrays_s(&self) -> f64 {
        self.rays as f64 / self.render_s.max(1e-9) / 1e6
    }

    /// The readable summary, and with `csv` also the CSV line
    /// `scene,primitives,program,threads,build_s,mrays_s,rays,peak_mb` (the CSV on stdout,
    /// the summary on stderr).
    pub fn print(&self, csv: bool) {
        let summary = format!(
            "{}: {} primitives, {} on {} thread(s)\n  build:  {:.6} s\n  render: {:.3} s, {} rays, {:.3} Mrays/s\n  peak:   {:.1} MB (VmHWM)",
            self.scene,
            self.primitives,
            self.program,
            self.threads,
            self.build_s,
            self.render_s,
            self.rays,
            self.mrays_s(),
            self.peak_mb
        );
        if csv {
            eprintln!("{summary}");
            println!(
                "{},{},{},{},{:.6},{:.4},{},{:.1}",
                self.scene,
                self.primitives,
                self.program,
                self.threads,
                self.build_s,
                self.mrays_s(),
                self.rays,
                self.peak_mb
            );
        } else {
            println!("{summary}");
        }
    }
}

/// The process's peak resident set (`VmHWM` in `/proc/self/status`) in MB, or NaN where that
/// file does not exist (not Linux).
pub fn peak_mb() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|line| line.strip_prefix("VmHWM:"))
        .and_then(|rest| rest.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(f64::NAN, |kb| kb * 1024.0 / 1e6)
}
