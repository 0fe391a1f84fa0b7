//! Textures: lookups at known points (bilinear filtering, wrapping, the checkerboard, the
//! `uv` map), image files of every format read exactly where the format is exact (sRGB
//! decoding on known pixels), bad image files as errors, scene files with textures and
//! normal maps, and renders: both dispatch paths, a flat normal map, no light through a
//! closed surface.

mod files;
mod lookup;
mod render;
mod scene_files;
