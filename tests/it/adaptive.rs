//! Adaptive sampling: the same bytes on 1 and 2 threads and from 4 merged tiles; a pixel
//! that stops at `n` samples has the uniform `n`-sample render's value; pixels stop where
//! their estimate meets the target; a time budget goes where the error is; bad settings
//! are refused, naming the setting.

use crate::scenes;
use raytrace::image::{TileHeader, merge_tiles, read_tile, write_tile};
use raytrace::prelude::*;
use raytrace::render::{Adaptive, Convergence};
use raytrace::{EnumScene, Image, Render};
use std::time::Duration;

const WIDTH: usize = 32;
const HEIGHT: usize = 16;

fn scene() -> EnumScene<f32> {
    scenes::matte_spheres().unwrap()
}

fn camera() -> ScreenCamera {
    ScreenCamera::new(WIDTH, HEIGHT).unwrap()
}

/// Renders `tile` (the whole image for `None`) to a 5 % target with seed 3.
fn adaptive(scene: &EnumScene<f32>, tile: Option<Rect>) -> Render {
    let camera = camera();
    let renderer = Renderer::new(scene, &camera)
        .max_depth(6)
        .seed(3)
        .target_error(0.05);
    match tile {
        Some(t) => renderer.tile(t).render().unwrap(),
        None => renderer.render().unwrap(),
    }
}

fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

fn bits(image: &Image) -> Vec<u64> {
    image.pixels().iter().flatten().map(|c| c.to_bits()).collect()
}

fn maps(render: &Render) -> &Convergence {
    render.convergence.as_ref().unwrap()
}

#[test]
fn the_same_bytes_on_one_and_two_threads_and_from_four_merged_tiles() {
    let scene = scene();
    let one = in_pool(1, || adaptive(&scene, None));
    let two = in_pool(2, || adaptive(&scene, None));
    assert_eq!(bits(&one.image), bits(&two.image));
    assert_eq!(maps(&one).samples(), maps(&two).samples());
    assert_eq!(maps(&one).error(), maps(&two).error());
    assert_eq!(one.stats.rays, two.stats.rays);
    // The render is adaptive: its pixels took different numbers of samples.
    let samples = maps(&one).samples();
    assert!(samples.iter().max() > samples.iter().min(), "{samples:?}");

    let dir = std::env::temp_dir().join(format!("raytrace-adaptive-tiles-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let tiles: Vec<(TileHeader, Image)> = (0..4)
        .map(|k| {
            let rect = Rect::tile(k, 4, WIDTH, HEIGHT).unwrap();
            let part = in_pool(2, || adaptive(&scene, Some(rect)));
            // A tile's maps are the whole render's rows.
            let rows = rect.y * WIDTH..(rect.y + rect.height) * WIDTH;
            assert_eq!(maps(&part).samples(), &samples[rows.clone()], "tile {k}");
            assert_eq!(maps(&part).error(), &maps(&one).error()[rows], "tile {k}");
            let header = TileHeader {
                scene: "ada".into(),
                settings: "target error 0.05".into(),
                image_width: WIDTH,
                image_height: HEIGHT,
                rect,
            };
            let path = dir.join(format!("{k}.rtile"));
            write_tile(&path, &header, &part.image).unwrap();
            read_tile(&path).unwrap()
        })
        .collect();
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(bits(&merge_tiles(&tiles).unwrap()), bits(&one.image));

    // The comparison sees a difference: another seed changes the image.
    let camera = camera();
    let other = Renderer::new(&scene, &camera)
        .max_depth(6)
        .seed(4)
        .target_error(0.05)
        .render()
        .unwrap();
    assert_ne!(bits(&other.image), bits(&one.image));
}

/// Sample `k` of a pixel is the same stream in both renderers and the sum goes in the same
/// order, so a pixel that stopped at `n` samples is the uniform render's pixel at `n` spp.
#[test]
fn a_pixel_that_stops_at_n_samples_is_the_uniform_renders_pixel() {
    let scene = scene();
    let camera = camera();
    let even = Renderer::new(&scene, &camera)
        .max_depth(6)
        .seed(3)
        .min_spp(16)
        .max_spp(16)
        .target_error(1e-9)
        .render()
        .unwrap();
    assert!(maps(&even).samples().iter().all(|&n| n == 16));
    let uniform = Renderer::new(&scene, &camera)
        .max_depth(6)
        .seed(3)
        .spp(16)
        .render()
        .unwrap();
    assert_eq!(bits(&even.image), bits(&uniform.image));

    let render = adaptive(&scene, None);
    let samples = maps(&render).samples();
    let mut counts: Vec<u32> = samples.to_vec();
    counts.sort_unstable();
    counts.dedup();
    assert!(counts.len() >= 3, "{counts:?}");
    // For each of a few sample counts, a pixel that stopped there.
    for &n in counts.iter().step_by(counts.len() / 3) {
        let i = samples.iter().position(|&m| m == n).unwrap();
        let (x, y) = (i % WIDTH, i / WIDTH);
        let one = Renderer::new(&scene, &camera)
            .max_depth(6)
            .seed(3)
            .spp(n)
            .tile(Rect {
                x,
                y,
                width: 1,
                height: 1,
            })
            .render()
            .unwrap();
        assert_eq!(
            render.image.pixel(x, y).map(f64::to_bits),
            one.image.pixel(0, 0).map(f64::to_bits),
            "pixel ({x}, {y}) at {n} samples"
        );
    }
}

#[test]
fn pixels_stop_where_their_estimate_meets_the_target_or_the_cap() {
    let scene = scene();
    let camera = camera();
    let render = Renderer::new(&scene, &camera)
        .max_depth(6)
        .seed(1)
        .target_error(0.02)
        .min_spp(16)
        .max_spp(512)
        .render()
        .unwrap();
    let c = maps(&render);
    assert_eq!((c.width(), c.height()), (WIDTH, HEIGHT));
    for (i, (&n, &e)) in c.samples().iter().zip(c.error()).enumerate() {
        assert!((16..=512).contains(&n), "pixel {i}: {n} samples");
        assert!(e <= 0.02 || n == 512, "pixel {i}: error {e} at {n} samples");
    }
    // Pixels that went on past the first round stopped near the target, not far beyond
    // it: a round at most doubles a pixel's samples, and one that falls short by little
    // takes a little more.
    let mut later: Vec<f64> = c
        .samples()
        .iter()
        .zip(c.error())
        .filter(|&(&n, _)| n > 16 && n < 512)
        .map(|(_, &e)| e)
        .collect();
    assert!(later.len() > 20, "{} pixels", later.len());
    later.sort_by(f64::total_cmp);
    let median = later[later.len() / 2];
    assert!(median > 0.02 * 0.7, "median {median} of {} pixels", later.len());
    let s = c.summary();
    assert_eq!(s.samples, c.samples().iter().map(|&n| u64::from(n)).sum::<u64>());
    assert!(s.median <= 0.02 && s.p99 >= s.median, "{s:?}");
    let line = s.to_string();
    for words in [
        "median",
        "99th percentile",
        "target 2.000 %",
        "samples",
        "per pixel",
    ] {
        assert!(line.contains(words), "{line}");
    }
}

/// With a time budget the render spends the time (rounds after the first are cut where it
/// runs out) and gives the noisiest pixels the most samples.
#[test]
fn a_time_budget_gives_the_noisiest_pixels_the_most_samples() {
    let scene = scene();
    let camera = camera();
    let budget = Duration::from_millis(400);
    // A cap no machine reaches in the budget: with the default cap a fast machine gave
    // every pixel 4096 samples, and the test could not tell noisy from calm.
    let render = Renderer::new(&scene, &camera)
        .max_depth(6)
        .seed(1)
        .time_budget(budget)
        .max_spp(1 << 30)
        .render()
        .unwrap();
    let c = maps(&render);
    assert!(c.samples().iter().all(|&n| n >= Adaptive::DEFAULT_MIN_SPP));
    assert!(c.rounds() > 1, "{} rounds", c.rounds());
    assert!(c.samples().iter().all(|&n| n < 1 << 30));
    assert!(render.stats.elapsed >= budget, "{:?}", render.stats.elapsed);
    // The pixels with the largest deviation per sample took more samples than those with
    // the smallest: the deviation is the error times √n without the pseudo-sample's 1/n².
    let mut by_deviation: Vec<(f64, u32)> = c
        .samples()
        .iter()
        .zip(c.error())
        .map(|(&n, &e)| {
            let n_f = f64::from(n);
            (((e * e - 1.0 / (n_f * n_f)) * n_f).max(0.0).sqrt(), n)
        })
        .collect();
    by_deviation.sort_by(|a, b| a.0.total_cmp(&b.0));
    let tenth = by_deviation.len() / 10;
    let mean = |part: &[(f64, u32)]| part.iter().map(|p| f64::from(p.1)).sum::<f64>() / part.len() as f64;
    let (calm, noisy) = (mean(&by_deviation[..tenth]), mean(&by_deviation[9 * tenth..]));
    assert!(noisy > 2.0 * calm, "calm {calm}, noisy {noisy}");
}

#[test]
fn bad_adaptive_settings_are_refused_naming_the_setting() {
    let scene = scene();
    let camera = camera();
    let renderer = || Renderer::new(&scene, &camera);
    let refused = |r: Renderer<'_, f32, _, _, ScreenCamera>, words: &str| {
        let err = r.render().unwrap_err().to_string();
        assert!(err.contains(words), "{err}");
    };
    refused(
        renderer().target_error(-0.01),
        "target error must be a finite number > 0 (got -0.01)",
    );
    refused(
        renderer().target_error(f64::NAN),
        "target error must be a finite number > 0 (got NaN)",
    );
    refused(
        renderer().target_error(0.0),
        "target error must be a finite number > 0 (got 0)",
    );
    refused(
        renderer().time_budget(Duration::ZERO),
        "time budget must be longer than 0 s",
    );
    refused(
        renderer().target_error(0.1).min_spp(64).max_spp(32),
        "max spp (32) must be at least min spp (64)",
    );
    refused(
        renderer().target_error(0.1).min_spp(4),
        "min spp must be at least 16 (got 4)",
    );
    refused(renderer().min_spp(32), "needs a target error or a time budget");
    let floor = Adaptive {
        error_floor: -1.0,
        ..Adaptive::target(0.1)
    };
    refused(
        renderer().adaptive(Some(floor)),
        "error floor must be a finite number > 0 (got -1)",
    );
}
