//! The core renderer's contracts: both dispatch paths give the same bytes, a seed fixes
//! the image on any number of threads, tiles equal the whole, every scalar renders, and
//! `max_depth` is exact.

mod depth;
mod determinism;
mod errors;
mod ppm;
mod scene;
mod ties;
