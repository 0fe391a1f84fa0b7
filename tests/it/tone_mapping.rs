//! Exposure and the ACES tone curve of the display formats: the curve's values at known
//! inputs (Narkowicz's fit, worked out by hand), its shape, one stop doubling every value,
//! the identity leaving the specification's samples alone, and, through the binary, PNG and
//! PPM changed by `--exposure`/`--tonemap` while EXR and PFM keep their linear bytes.

use raytrace::Image;
use raytrace::image::{Encoding, ToneCurve, Tonemap, aces_narkowicz};
use std::fs;
use std::path::Path;
use std::process::Command;

#[test]
fn the_aces_curve_at_known_inputs() {
    // x(2.51x + 0.03)/(x(2.43x + 0.59) + 0.14), by hand.
    for (x, want) in [
        (0.0, 0.0),
        (0.01, 0.000_551 / 0.146_143),
        (0.18, 0.086_724 / 0.324_932),
        (0.5, 0.6425 / 1.0425),
        (1.0, 2.54 / 3.16),
        (2.0, 10.1 / 11.04),
        (4.0, 40.28 / 41.38),
        (7.0, 123.2 / 123.34),
        // Past (0.56 + √0.3584)/0.16 ≈ 7.24 the fit exceeds 1 and is clamped.
        (8.0, 1.0),
        (1e6, 1.0),
    ] {
        let got = aces_narkowicz(x);
        assert!((got - want).abs() < 1e-14, "f({x}) = {got}, want {want}");
        assert_eq!(ToneCurve::Aces.apply(x), got);
    }
    // 1 maps to about 0.8, as Narkowicz pre-exposed it.
    assert!((aces_narkowicz(1.0) - 0.8).abs() < 0.004);
}

#[test]
fn the_aces_curve_rises_from_0_to_1() {
    let mut prev = 0.0;
    for i in 0..=2000 {
        let x = f64::from(i) / 100.0;
        let y = aces_narkowicz(x);
        assert!((0.0..=1.0).contains(&y) && y >= prev, "f({x}) = {y} after {prev}");
        prev = y;
    }
    // A toe: darker than the identity below about 0.1 …
    assert!(aces_narkowicz(0.05) < 0.05);
    // … and a shoulder: values the identity clips stay apart.
    assert!(aces_narkowicz(1.5) < aces_narkowicz(3.0));
}

#[test]
fn each_stop_doubles_every_value() {
    for stops in [-3.0, -1.0, 0.0, 0.5, 2.0, 7.25] {
        let this = Tonemap::new(stops, ToneCurve::None).unwrap();
        let next = Tonemap::new(stops + 1.0, ToneCurve::None).unwrap();
        for c in [1e-9, 0.0123, 0.5, 1.0, 37.0, 1e12] {
            let (a, b) = (this.apply(c), next.apply(c));
            assert!(
                (b - 2.0 * a).abs() <= 2.0 * f64::EPSILON * b,
                "{stops} stops, {c}: {a} then {b}"
            );
        }
    }
    // Whole stops are powers of two, exactly.
    assert_eq!(Tonemap::new(3.0, ToneCurve::None).unwrap().apply(0.3), 0.3 * 8.0);
    assert_eq!(Tonemap::new(-2.0, ToneCurve::None).unwrap().apply(0.3), 0.3 / 4.0);
    // The curve comes after the exposure.
    let both = Tonemap::new(1.0, ToneCurve::Aces).unwrap();
    assert_eq!(both.apply(0.5), aces_narkowicz(1.0));
}

#[test]
fn no_tone_map_leaves_the_samples_alone() {
    let pixels = vec![[0.0, 0.5, 1.0], [2.0, 1e-4, 0.18], [f64::NAN, -1.0, 7.0]];
    let image = Image::from_pixels(3, 1, pixels).unwrap();
    for e in [Encoding::Srgb, Encoding::Linear] {
        assert_eq!(image.to_u16_tonemapped(Tonemap::NONE, e), image.to_u16(e));
    }
    // With the curve, a value the identity clips is kept below white.
    let aces = Tonemap::new(0.0, ToneCurve::Aces).unwrap();
    let mapped = image.to_u16_tonemapped(aces, Encoding::Linear);
    assert_eq!(image.to_u16(Encoding::Linear).samples[3], 65535);
    assert_eq!(mapped.samples[3], (aces_narkowicz(2.0) * 65535.0).round() as u16);
}

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

/// The bytes `raytrace render` writes for the matte spheres in `format`, with `extra` options.
fn rendered(dir: &Path, format: &str, extra: &[&str]) -> Vec<u8> {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/matte_spheres.toml");
    let out = dir.join(format!("image-{}.{format}", extra.join("_")));
    let args = [
        &[
            "render",
            scene.to_str().unwrap(),
            "--width",
            "32",
            "--quiet",
            "--out",
        ],
        &[out.to_str().unwrap()][..],
        extra,
    ]
    .concat();
    let o = Command::new(BIN).args(&args).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    fs::read(out).unwrap()
}

#[test]
fn float_formats_stay_linear_and_display_formats_are_tone_mapped() {
    let dir = std::env::temp_dir().join(format!("raytrace-tonemap-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let mapped = ["--exposure", "1.5", "--tonemap", "aces"];
    for format in ["exr", "pfm"] {
        assert_eq!(
            rendered(&dir, format, &[]),
            rendered(&dir, format, &mapped),
            "{format} keeps the linear values"
        );
    }
    for format in ["png", "ppm"] {
        let plain = rendered(&dir, format, &[]);
        assert_eq!(
            plain,
            rendered(&dir, format, &["--exposure", "0", "--tonemap", "none"])
        );
        assert_ne!(plain, rendered(&dir, format, &mapped), "{format}");
        assert_ne!(plain, rendered(&dir, format, &["--exposure", "-1"]), "{format}");
    }
    fs::remove_dir_all(dir).unwrap();
}
