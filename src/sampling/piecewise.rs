//! Piecewise-constant distributions in one and two dimensions (pbrt-v4's
//! `PiecewiseConstant1D`/`2D`): draw a cell in proportion to its weight, then a point
//! uniformly inside it. What an environment map is importance-sampled with.

/// A piecewise-constant density on `[0, 1)` of `n` equal cells, cell `i` drawn with
/// probability `wᵢ/Σw`: the density is `n·wᵢ/Σw` inside it.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution1D {
    /// `cdf[i]`: the weights of cells `0..i` summed, over `Σw` (`cdf[0] = 0`, `cdf[n] = 1`).
    cdf: Vec<f64>,
    /// `Σw`, before normalising.
    total: f64,
}

impl Distribution1D {
    /// The distribution of `weights` (each finite and `≥ 0`; anything else counts as 0).
    /// All zero (or none): `None`, there is nothing to draw.
    pub fn new(weights: &[f64]) -> Option<Self> {
        let mut cdf = Vec::with_capacity(weights.len() + 1);
        let mut sum = 0.0;
        cdf.push(0.0);
        for &w in weights {
            sum += if w.is_finite() && w > 0.0 { w } else { 0.0 };
            cdf.push(sum);
        }
        if !(sum > 0.0 && sum.is_finite()) {
            return None;
        }
        for c in &mut cdf {
            *c /= sum;
        }
        Some(Self { cdf, total: sum })
    }

    /// The number of cells.
    pub fn len(&self) -> usize {
        self.cdf.len() - 1
    }

    /// Whether there are no cells (never: [`Distribution1D::new`] refuses that).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The weights' sum `Σw`.
    pub fn total(&self) -> f64 {
        self.total
    }

    /// The probability of cell `i`, `wᵢ/Σw`.
    pub fn probability(&self, i: usize) -> f64 {
        self.cdf[i + 1] - self.cdf[i]
    }

    /// The cell `u ∈ [0, 1)` falls in by the cumulative weights (the last cell whose
    /// running sum starts at or below `u` and has a weight), with its probability and
    /// where in it `u` lies, in `[0, 1)`: so one uniform number draws the cell and then a
    /// point in it.
    pub fn sample(&self, u: f64) -> (usize, f64, f64) {
        // The first `i` with cdf[i + 1] > u; a cell of zero weight is never chosen.
        let i = self.cdf[1..].partition_point(|&c| c <= u).min(self.len() - 1);
        let p = self.probability(i);
        let within = if p > 0.0 {
            ((u - self.cdf[i]) / p).clamp(0.0, 1.0 - f64::EPSILON / 2.0)
        } else {
            0.0
        };
        (i, p, within)
    }
}

/// A piecewise-constant density on `[0, 1)²` of `nx × ny` equal cells: a row drawn by its
/// total weight (the marginal), then a cell in it (the conditional).
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution2D {
    rows: Vec<Option<Distribution1D>>,
    marginal: Distribution1D,
    nx: usize,
}

impl Distribution2D {
    /// The distribution of `weights`, row by row (`weights[y·nx + x]`); `None` if every
    /// weight is 0 or `nx` is 0.
    pub fn new(weights: &[f64], nx: usize) -> Option<Self> {
        if nx == 0 || weights.is_empty() || !weights.len().is_multiple_of(nx) {
            return None;
        }
        let rows: Vec<_> = weights.chunks(nx).map(Distribution1D::new).collect();
        let row_weights: Vec<f64> = rows
            .iter()
            .map(|r| r.as_ref().map_or(0.0, Distribution1D::total))
            .collect();
        let marginal = Distribution1D::new(&row_weights)?;
        Some(Self { rows, marginal, nx })
    }

    /// The cells across and down.
    pub fn size(&self) -> (usize, usize) {
        (self.nx, self.rows.len())
    }

    /// A point of `[0, 1)²` from two uniform numbers, with its density (per unit area of
    /// the square): `nx·ny·w/Σw` in its cell.
    pub fn sample(&self, u: [f64; 2]) -> ([f64; 2], f64) {
        let (y, py, v) = self.marginal.sample(u[1]);
        let row = self.rows[y]
            .as_ref()
            .expect("a row of zero weight is never drawn");
        let (x, px, w) = row.sample(u[0]);
        let (nx, ny) = (self.nx as f64, self.rows.len() as f64);
        ([(x as f64 + w) / nx, (y as f64 + v) / ny], px * py * nx * ny)
    }

    /// The density of the point `(s, t)` of `[0, 1)²` (0 outside, or in a cell of weight 0).
    pub fn pdf(&self, [s, t]: [f64; 2]) -> f64 {
        if !((0.0..1.0).contains(&s) && (0.0..1.0).contains(&t)) {
            return 0.0;
        }
        let ny = self.rows.len();
        let (x, y) = (
            ((s * self.nx as f64) as usize).min(self.nx - 1),
            ((t * ny as f64) as usize).min(ny - 1),
        );
        match &self.rows[y] {
            Some(row) => self.marginal.probability(y) * row.probability(x) * (self.nx * ny) as f64,
            None => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_in_proportion_and_points_within() {
        let d = Distribution1D::new(&[1.0, 0.0, 3.0]).unwrap();
        assert_eq!(d.probability(0), 0.25);
        assert_eq!(d.probability(1), 0.0);
        assert_eq!(d.probability(2), 0.75);
        assert_eq!(d.sample(0.0), (0, 0.25, 0.0));
        assert_eq!(d.sample(0.125).0, 0);
        assert!((d.sample(0.125).2 - 0.5).abs() < 1e-15);
        // The boundary belongs to the next cell with weight: the empty one is skipped.
        assert_eq!(d.sample(0.25).0, 2);
        assert_eq!(d.sample(1.0 - 1e-17).0, 2);
        assert!(Distribution1D::new(&[0.0, f64::NAN, -1.0]).is_none());
        assert!(Distribution1D::new(&[]).is_none());
    }

    #[test]
    fn the_2d_density_integrates_to_one_and_matches_its_samples() {
        let w = [0.0, 1.0, 2.0, 4.0, 0.0, 0.0, 1.0, 0.5, 0.0];
        let d = Distribution2D::new(&w, 3).unwrap();
        let total: f64 = (0..9)
            .map(|k| d.pdf([(k % 3) as f64 / 3.0 + 0.1, (k / 3) as f64 / 3.0 + 0.1]) / 9.0)
            .sum();
        assert!((total - 1.0).abs() < 1e-12, "{total}");
        for &(u0, u1) in &[(0.3, 0.7), (0.99, 0.01), (0.0, 0.5)] {
            let (p, pdf) = d.sample([u0, u1]);
            assert_eq!(d.pdf(p), pdf, "{p:?}");
            assert!(pdf > 0.0);
        }
        assert_eq!(d.pdf([0.5, 0.5]), 0.0, "the empty middle row");
        assert!(Distribution2D::new(&[0.0; 4], 2).is_none());
    }
}
