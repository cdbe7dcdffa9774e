//! A long ladder folded into columns side by side, like lines of text, so
//! that every block stays in the picture at a readable size. Movies (the
//! `auto` camera) and filmstrips share it.
//!
//! Segments start at even blocks, so the parity (−1)ⁿ of every block, which
//! sets its zig-zag (`model::ladder::orientation`), is the same in its
//! column as in the whole ladder; neighbouring segments overlap by one
//! block, so every spring is drawn. Every column shows the same spans (one
//! scale), its first block at the top.

use super::snapshot::{Region, View};
use crate::model::Ladder;
use crate::model::ladder::nodes;

/// Gap between the columns of a folded ladder, pixels.
pub const COLUMN_GAP: f32 = 8.0;

/// Room along the ladder, in s, that a column's window adds to the extent
/// of its blocks' ends (the fitted window's pads and the pin support), for
/// choosing a fold; the fold itself uses the exact windows.
const ROOM: f64 = 1.0;

/// One column of a folded ladder: blocks `start..start + len` (zero-based),
/// seen through `view`.
#[derive(Clone, Debug)]
pub struct Segment {
    /// Zero-based index of the first block (even).
    pub start: usize,
    /// The segment as a ladder of its own (its number of blocks).
    pub ladder: Ladder,
    /// The column's window in model units.
    pub view: View,
}

impl Segment {
    /// Number of blocks in the column.
    pub fn len(&self) -> usize {
        self.ladder.n()
    }

    /// Never true: a column holds at least two blocks.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The part of the whole ladder's state `q` drawn in this column.
    pub fn state<'a>(&self, q: &'a [f64]) -> &'a [f64] {
        &q[3 * self.start..3 * (self.start + self.len())]
    }
}

/// A ladder folded into columns.
#[derive(Clone, Debug)]
pub struct Fold {
    /// Blocks from the top of one column to the top of the next (even).
    pub stride: usize,
    /// The columns, left to right.
    pub segments: Vec<Segment>,
    /// Length of every column's window along the ladder, in s.
    pub along: f64,
    /// Width of every column's window across the ladder, in s.
    pub across: f64,
}

/// The strides worth trying and their numbers of columns, fewest columns
/// first: for each number of columns the shortest even stride that gives
/// it (a longer one only makes the columns longer).
fn candidates(n: usize, max_columns: usize) -> Vec<(usize, usize)> {
    let links = n.saturating_sub(1).max(1);
    let mut out: Vec<(usize, usize)> = Vec::new();
    for c in 1..=max_columns.max(1) {
        let stride = links.div_ceil(c).next_multiple_of(2).max(2);
        let cols = links.div_ceil(stride).max(1);
        if out.last().is_none_or(|&(_, last)| cols > last) {
            out.push((stride, cols));
        }
        if stride == 2 {
            break;
        }
    }
    out
}

/// The extent of the blocks' ends along the ladder (model x), block by
/// block, over all `states`: (lowest, highest).
fn extents(states: &[&[f64]], n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut lo = vec![f64::INFINITY; n];
    let mut hi = vec![f64::NEG_INFINITY; n];
    for q in states {
        for i in 0..n.min(q.len() / 3) {
            let (a, b) = nodes(q, i);
            for x in [a[0], b[0]] {
                if x.is_finite() {
                    lo[i] = lo[i].min(x);
                    hi[i] = hi[i].max(x);
                }
            }
        }
    }
    (lo, hi)
}

/// The estimated window length along the ladder of a fold at `stride`:
/// the longest of its segments' extents, plus [`ROOM`].
fn estimated_along(lo: &[f64], hi: &[f64], stride: usize) -> f64 {
    let n = lo.len();
    let cols = n.saturating_sub(1).div_ceil(stride).max(1);
    let mut along: f64 = 0.0;
    for j in 0..cols {
        let (start, end) = (j * stride, (j * stride + stride + 1).min(n));
        let l = lo[start..end].iter().copied().fold(f64::INFINITY, f64::min);
        let h = hi[start..end]
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max);
        if h >= l {
            along = along.max(h - l);
        }
    }
    along + ROOM
}

impl Fold {
    /// The fold of `ladder` at `stride` (even), with windows that hold
    /// every block of every state: each column's window starts at its
    /// first block and is as long as the longest column needs.
    pub fn with_stride(ladder: &Ladder, states: &[&[f64]], stride: usize) -> Fold {
        let n = ladder.n();
        let stride = stride.max(2);
        let whole = View::fit(states);
        let across = (whole.y.1 - whole.y.0).max(1e-9);
        let y_mid = 0.5 * (whole.y.0 + whole.y.1);
        let cols = n.saturating_sub(1).div_ceil(stride).max(1);
        let mut fits = Vec::with_capacity(cols);
        for j in 0..cols {
            let start = j * stride;
            let end = (start + stride + 1).min(n);
            let seg: Vec<&[f64]> = states
                .iter()
                .filter(|q| q.len() >= 3 * end)
                .map(|q| &q[3 * start..3 * end])
                .collect();
            fits.push((start, end, View::fit(&seg)));
        }
        let along = fits
            .iter()
            .map(|(_, _, f)| f.x.1 - f.x.0)
            .fold(1e-9, f64::max);
        let segments = fits
            .into_iter()
            .map(|(start, end, fit)| Segment {
                start,
                ladder: Ladder::new(crate::model::Params {
                    n: end - start,
                    ..ladder.params
                }),
                view: View::window(
                    (fit.x.0, fit.x.0 + along),
                    (y_mid - 0.5 * across, y_mid + 0.5 * across),
                ),
            })
            .collect();
        Fold {
            stride,
            segments,
            along,
            across,
        }
    }

    /// The fold that draws the blocks largest in `region` (pixels), with
    /// `gap` pixels between columns: the movies' `auto` camera.
    pub fn best_in(ladder: &Ladder, states: &[&[f64]], region: Region, gap: f32) -> Fold {
        let n = ladder.n();
        let whole = View::fit(states);
        let across = (whole.y.1 - whole.y.0).max(1e-9);
        let (lo, hi) = extents(states, n);
        // Columns narrower than a pixel draw nothing.
        let max_columns = ((region.w + gap) / (gap + 1.0)).floor().max(1.0) as usize;
        let mut best = (2, f64::NEG_INFINITY);
        for (stride, cols) in candidates(n, max_columns) {
            let w = (region.w - gap * (cols as f32 - 1.0)) / cols as f32;
            if w <= 0.0 {
                break;
            }
            let along = estimated_along(&lo, &hi, stride);
            let scale = (region.h as f64 / along).min(w as f64 / across);
            if scale > best.1 {
                best = (stride, scale);
            }
        }
        Fold::with_stride(ladder, states, best.0)
    }

    /// The fold with the fewest columns whose blocks are at least
    /// `min_scale` pixels long when a column's window is `height` pixels
    /// tall (columns are then as wide as that scale needs): the filmstrips.
    /// With none within `max_columns` columns, the one with the most.
    pub fn readable(
        ladder: &Ladder,
        states: &[&[f64]],
        height: f64,
        min_scale: f64,
        max_columns: usize,
    ) -> Fold {
        let n = ladder.n();
        let (lo, hi) = extents(states, n);
        let mut last = 2;
        for (stride, _) in candidates(n, max_columns) {
            last = stride;
            if height / estimated_along(&lo, &hi, stride) >= min_scale {
                let fold = Fold::with_stride(ladder, states, stride);
                if fold.scale_along(height) >= min_scale {
                    return fold;
                }
            }
        }
        Fold::with_stride(ladder, states, last)
    }

    /// Number of columns.
    pub fn columns(&self) -> usize {
        self.segments.len()
    }

    /// Pixels per s when a column's window is `height` pixels tall.
    pub fn scale_along(&self, height: f64) -> f64 {
        height / self.along
    }

    /// The columns' regions side by side in `region`, `gap` pixels apart.
    pub fn regions(&self, region: Region, gap: f32) -> Vec<Region> {
        let cols = self.columns() as f32;
        let w = (region.w - gap * (cols - 1.0)) / cols;
        (0..self.columns())
            .map(|j| Region {
                x: (region.x + j as f32 * (w + gap)).round(),
                y: region.y,
                w: w.floor().max(1.0),
                h: region.h,
            })
            .collect()
    }

    /// The column that shows the point `at` blocks along the ladder (1 is
    /// the centre of block 1), and where it is in that column's blocks.
    pub fn locate(&self, at: f64) -> (usize, f64) {
        let last = self.columns() - 1;
        let j = if at.is_finite() && at > 1.0 {
            (((at - 1.0) / self.stride as f64).floor() as usize).min(last)
        } else {
            0
        };
        (j, at - self.segments[j].start as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Params;

    fn ladder(n: usize) -> Ladder {
        Ladder::new(Params {
            n,
            ..Params::paper(60.0).unwrap()
        })
    }

    #[test]
    fn candidates_are_even_strides_with_ever_more_columns() {
        assert_eq!(candidates(2, 10), vec![(2, 1)]);
        let c = candidates(200, 50);
        assert_eq!(c[0], (200, 1));
        assert!(
            c.iter()
                .all(|&(s, cols)| s % 2 == 0 && (cols - 1) * s < 199)
        );
        assert!(c.windows(2).all(|w| w[1].1 > w[0].1 && w[1].0 < w[0].0));
        assert!(candidates(200, 3).iter().all(|&(_, cols)| cols <= 3));
    }

    #[test]
    fn every_block_is_in_some_column_and_inside_its_window() {
        for n in [2, 3, 10, 41, 200] {
            let l = ladder(n);
            let q = l.ground_state();
            let states = [q.as_slice()];
            for stride in [2, 4, 10, 40] {
                let f = Fold::with_stride(&l, &states, stride);
                let mut seen = vec![false; n];
                for s in &f.segments {
                    assert!(s.start % 2 == 0 && s.len() >= 2.min(n));
                    for i in 0..s.len() {
                        seen[s.start + i] = true;
                        let (a, b) = nodes(s.state(&q), i);
                        for p in [a, b] {
                            assert!(p[0] >= s.view.x.0 && p[0] <= s.view.x.1);
                            assert!(p[1] >= s.view.y.0 && p[1] <= s.view.y.1);
                        }
                    }
                }
                assert!(seen.iter().all(|&v| v), "N = {n}, stride {stride}");
                // Neighbours share a block: every spring is drawn.
                for w in f.segments.windows(2) {
                    assert_eq!(w[0].start + w[0].len() - 1, w[1].start);
                }
            }
        }
    }

    #[test]
    fn readable_fold_reaches_the_scale_with_the_fewest_columns() {
        let l = ladder(200);
        let q = l.ground_state();
        let states = [q.as_slice()];
        let f = Fold::readable(&l, &states, 800.0, 14.0, 100);
        assert!(f.scale_along(800.0) >= 14.0);
        let fewer = candidates(200, f.columns() - 1).last().unwrap().0;
        let g = Fold::with_stride(&l, &states, fewer);
        assert!(g.scale_along(800.0) < 14.0, "{} columns", g.columns());
        // Capped: the most columns allowed.
        assert_eq!(Fold::readable(&l, &states, 800.0, 14.0, 2).columns(), 2);
    }

    #[test]
    fn locate_picks_the_column_of_a_block() {
        let l = ladder(41);
        let q = l.ground_state();
        let f = Fold::with_stride(&l, &[q.as_slice()], 10);
        assert_eq!(f.columns(), 4);
        assert_eq!(f.locate(1.0), (0, 1.0));
        assert_eq!(f.locate(10.5), (0, 10.5));
        assert_eq!(f.locate(11.5), (1, 1.5));
        assert_eq!(f.locate(41.0), (3, 11.0));
    }
}
