//! A grid of square cells, for the checks that stamp a swept tool on a
//! raster and compare it with what was drawn: the cut plan's freed-part
//! check (`plan::verify::freed`) and the router's pocket sweep
//! (`mill::sweep`), after paper 004 §2.6's envelope swept over a grid.
//!
//! A cell stands for its centre: it is inside a region when its centre
//! is, and a disc reaches it when the disc reaches its centre. Columns
//! and rows are looked up by [`floor`]/[`ceil`] (no libm call a cell).

use super::{ceil, floor, Point};

/// `nx` × `ny` square cells of side `cell` from `(x0, y0)`, row-major
/// (cell `(i, j)` is `j * nx + i`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub x0: f64,
    pub y0: f64,
    pub cell: f64,
    pub nx: usize,
    pub ny: usize,
}

impl Grid {
    /// The centre of cell `(i, j)`.
    pub fn centre(&self, i: usize, j: usize) -> Point {
        Point::new(
            self.x0 + (i as f64 + 0.5) * self.cell,
            self.y0 + (j as f64 + 0.5) * self.cell,
        )
    }

    /// The first column whose centre is at or right of `x` (`nx` if none).
    pub fn col_from(&self, x: f64) -> usize {
        first_index(x, self.x0, self.cell, self.nx)
    }

    /// One past the last column whose centre is at or left of `x`.
    pub fn col_to(&self, x: f64) -> usize {
        past_index(x, self.x0, self.cell, self.nx)
    }

    /// The first row whose centre is at or above `y` (`ny` if none).
    pub fn row_from(&self, y: f64) -> usize {
        first_index(y, self.y0, self.cell, self.ny)
    }

    /// One past the last row whose centre is at or below `y`.
    pub fn row_to(&self, y: f64) -> usize {
        past_index(y, self.y0, self.cell, self.ny)
    }

    /// Calls `f` with each of cell `k`'s 4-connected neighbours: left,
    /// right, below, above.
    pub fn neighbours(&self, k: usize, mut f: impl FnMut(usize)) {
        let (i, j) = (k % self.nx, k / self.nx);
        if i > 0 {
            f(k - 1);
        }
        if i + 1 < self.nx {
            f(k + 1);
        }
        if j > 0 {
            f(k - self.nx);
        }
        if j + 1 < self.ny {
            f(k + self.nx);
        }
    }

    /// Calls `run(j, first, past)` for each run of cells of row `j` whose
    /// centres lie inside the closed loops made of `edges`, by the
    /// even-odd rule (loops may nest: a part and its holes, a pocket and
    /// its islands). `xs` is a buffer for the row's crossings.
    pub fn inside_runs(
        &self,
        edges: &[(Point, Point)],
        xs: &mut Vec<f64>,
        mut run: impl FnMut(usize, usize, usize),
    ) {
        for j in 0..self.ny {
            let y = self.centre(0, j).y;
            xs.clear();
            for &(a, b) in edges {
                // Half-open in y: a vertex on the row counts once.
                if (a.y > y) != (b.y > y) {
                    xs.push(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
                }
            }
            crate::sort::sort_floats(xs);
            for pair in xs.chunks_exact(2) {
                let (lo, hi) = (self.col_from(pair[0]), self.col_to(pair[1]));
                if lo < hi {
                    run(j, lo, hi);
                }
            }
        }
    }
}

fn first_index(v: f64, origin: f64, cell: f64, n: usize) -> usize {
    (ceil((v - origin) / cell - 0.5).max(0.0) as usize).min(n)
}

fn past_index(v: f64, origin: f64, cell: f64, n: usize) -> usize {
    ((floor((v - origin) / cell - 0.5) + 1.0).max(0.0) as usize).min(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x0: f64, y0: f64, s: f64) -> Vec<(Point, Point)> {
        let p = [
            Point::new(x0, y0),
            Point::new(x0 + s, y0),
            Point::new(x0 + s, y0 + s),
            Point::new(x0, y0 + s),
        ];
        (0..4).map(|k| (p[k], p[(k + 1) % 4])).collect()
    }

    #[test]
    fn columns_and_rows_are_the_cells_whose_centre_is_in_range() {
        let r = Grid {
            x0: -1.0,
            y0: 2.0,
            cell: 0.5,
            nx: 10,
            ny: 4,
        };
        for k in 0..400 {
            let x = -3.0 + k as f64 * 0.0173;
            let want_from = (0..r.nx).find(|&i| r.centre(i, 0).x >= x).unwrap_or(r.nx);
            let want_to = (0..r.nx)
                .filter(|&i| r.centre(i, 0).x <= x)
                .map(|i| i + 1)
                .max();
            assert_eq!(r.col_from(x), want_from, "x {x}");
            assert_eq!(r.col_to(x), want_to.unwrap_or(0), "x {x}");
            let y = 1.0 + k as f64 * 0.0091;
            let want_from = (0..r.ny).find(|&j| r.centre(0, j).y >= y).unwrap_or(r.ny);
            assert_eq!(r.row_from(y), want_from, "y {y}");
        }
    }

    /// A square with a square hole, against each cell centre tested on
    /// its own (point in the outer, not in the hole).
    #[test]
    fn inside_runs_fill_by_the_even_odd_rule() {
        let r = Grid {
            x0: 0.0,
            y0: 0.0,
            cell: 0.3,
            nx: 40,
            ny: 37,
        };
        let mut edges = square(1.07, 1.1, 9.0);
        edges.extend(square(3.0, 4.0, 2.5));
        let mut got = vec![false; r.nx * r.ny];
        r.inside_runs(&edges, &mut Vec::new(), |j, lo, hi| {
            for i in lo..hi {
                got[j * r.nx + i] = true;
            }
        });
        let within = |p: Point, x0: f64, y0: f64, s: f64| {
            p.x > x0 && p.x < x0 + s && p.y > y0 && p.y < y0 + s
        };
        for j in 0..r.ny {
            for i in 0..r.nx {
                let c = r.centre(i, j);
                let want = within(c, 1.07, 1.1, 9.0) && !within(c, 3.0, 4.0, 2.5);
                assert_eq!(got[j * r.nx + i], want, "cell {i},{j}");
            }
        }
    }
}
