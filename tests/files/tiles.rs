//! A render split into tiles, written to tile files, read back and merged, has the bits
//! of the whole render; tiles that do not make one image are refused, saying why.

use raytrace::image::{TileHeader, merge_tiles, read_tile, write_tile};
use raytrace::prelude::*;
use raytrace::{Image, Result};
use std::path::PathBuf;

const WIDTH: usize = 26;
const HEIGHT: usize = 13;
const SCENE: &str = "cbf29ce484222325";
const SETTINGS: &str = "spp=3 max_depth=6 seed=7 precision=f64";

fn scene() -> Result<EnumScene<f64>> {
    let mut scene = EnumScene::new(Background::default());
    scene.add(
        Sphere::new(Vec3::new(0.0, 0.0, -3.0), 1.0)?,
        Mirror::new(Vec3::new(0.9, 0.6, 0.3))?,
    );
    scene.add(
        Sphere::new(Vec3::new(0.0, -101.0, -3.0), 100.0)?,
        Lambertian::new(Vec3::splat(0.5))?,
    );
    Ok(scene)
}

/// Renders `rect` of the test image (the whole image for `None`).
fn render_part(rect: Option<Rect>) -> Result<Image> {
    let scene = scene()?;
    let camera = ScreenCamera::new(WIDTH, HEIGHT)?;
    let renderer = Renderer::new(&scene, &camera).spp(3).max_depth(6).seed(7);
    Ok(match rect {
        Some(rect) => renderer.tile(rect).render()?.image,
        None => renderer.render()?.image,
    })
}

fn header(rect: Rect) -> TileHeader {
    TileHeader {
        scene: SCENE.into(),
        settings: SETTINGS.into(),
        image_width: WIDTH,
        image_height: HEIGHT,
        rect,
    }
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-tiles-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn bits(image: &Image) -> Vec<u64> {
    image.pixels().iter().flatten().map(|c| c.to_bits()).collect()
}

/// The `n` row bands of the image, each rendered, written and read back.
fn tiles(n: usize, dir: &std::path::Path) -> Result<Vec<(TileHeader, Image)>> {
    (0..n)
        .map(|k| {
            let rect = Rect::tile(k, n, WIDTH, HEIGHT)?;
            let path = dir.join(format!("tile-{}-of-{n}.rtile", k + 1));
            write_tile(&path, &header(rect), &render_part(Some(rect))?)?;
            read_tile(&path)
        })
        .collect()
}

#[test]
fn merged_tiles_have_the_bits_of_the_whole_render() -> Result<()> {
    let whole = render_part(None)?;
    let dir = temp_dir("merge");
    for n in [1, 3, 4] {
        let mut tiles = tiles(n, &dir)?;
        assert_eq!(bits(&merge_tiles(&tiles)?), bits(&whole), "{n} tiles");
        // The order of the tiles does not matter.
        tiles.reverse();
        assert_eq!(bits(&merge_tiles(&tiles)?), bits(&whole), "{n} tiles reversed");
    }
    std::fs::remove_dir_all(dir).unwrap();
    Ok(())
}

fn merge_error(tiles: &[(TileHeader, Image)]) -> String {
    merge_tiles(tiles).unwrap_err().to_string()
}

#[test]
fn tiles_that_do_not_make_one_image_are_refused() -> Result<()> {
    let dir = temp_dir("refuse");
    let good = tiles(3, &dir)?;
    std::fs::remove_dir_all(dir).unwrap();
    // Rows 0..4, 4..8, 8..13.
    assert_eq!(
        good[1].0.rect,
        Rect {
            x: 0,
            y: 4,
            width: WIDTH,
            height: 4
        }
    );

    let gap = [good[0].clone(), good[2].clone()];
    let msg = merge_error(&gap);
    assert!(msg.contains("104 pixels are in no tile, in rows 4..8"), "{msg}");

    let overlap = [good[0].clone(), good[1].clone(), good[1].clone(), good[2].clone()];
    let msg = merge_error(&overlap);
    assert!(
        msg.contains("tiles 2 and 3 overlap: both cover rows 4..8, columns 0..26"),
        "{msg}"
    );

    let mut other_scene = good.clone();
    other_scene[2].0.scene = "0123".into();
    let msg = merge_error(&other_scene);
    assert!(
        msg.contains("tile 3 is of scene 0123 but tile 1 of scene cbf29ce484222325"),
        "{msg}"
    );

    let mut other_settings = good.clone();
    other_settings[1].0.settings = "spp=4".into();
    let msg = merge_error(&other_settings);
    assert!(msg.contains("tile 2 has settings \"spp=4\""), "{msg}");

    let mut other_size = good.clone();
    other_size[1].0.image_height = 14;
    let msg = merge_error(&other_size);
    assert!(
        msg.contains("tile 2 is part of a 26×14 image but tile 1 of a 26×13 image"),
        "{msg}"
    );

    let mut wrong_image = good.clone();
    wrong_image[0].1 = Image::new(WIDTH, 3)?;
    let msg = merge_error(&wrong_image);
    assert!(
        msg.contains("tile 1's image is 26×3 but its rect 0 0 26 4 is 26×4"),
        "{msg}"
    );

    let mut outside = good;
    outside[2].0.rect.y = 10;
    let msg = merge_error(&outside);
    assert!(
        msg.contains("tile 3") && msg.contains("outside the 26×13 image"),
        "{msg}"
    );

    assert!(merge_error(&[]).contains("no tiles"));
    Ok(())
}
