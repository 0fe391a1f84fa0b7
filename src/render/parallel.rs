//! The render's parallel loops, each written once for every scene type.
//!
//! A closure carries every type parameter of the function it is written in, so a rayon loop
//! written inside the generic render is compiled again, with all of rayon's splitting and
//! joining, for every scalar, shape, material, camera and generator it renders with (the
//! figures: `docs/PERFORMANCE.md`, "What the test build compiles"). These loops take their
//! work as trait objects instead. Rayon is compiled once (once per scalar where the items hold one), and the work,
//! called once a band, a task or a pixel, stays monomorphic inside its closure.

use rayon::prelude::*;

/// A worker's job: it does one item of a loop and returns the rays it traced. Each piece of
/// work rayon splits off makes its own ([`sum`]) and keeps its buffers from item to item.
pub(super) type Job<'a, T> = Box<dyn FnMut(T) -> u64 + 'a>;

/// Does `job(item)` for each of `items` in parallel, each worker's job made by `worker()`,
/// and returns the sum of the rays traced.
pub(super) fn sum<'a, I: IntoParallelIterator>(
    items: I,
    worker: &(dyn Fn() -> Job<'a, I::Item> + Sync),
) -> u64 {
    items
        .into_par_iter()
        .map_init(worker, |job, item| job(item))
        .sum()
}

/// `each(i)` for every `i` in `0..count`, in parallel, collected in order.
pub(super) fn each<T: Send>(count: usize, each: &(dyn Fn(usize) -> T + Sync)) -> Vec<T> {
    (0..count).into_par_iter().map(each).collect()
}
