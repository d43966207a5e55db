//! How much two placed shapes overlap, as a number to minimise, and the
//! table of overlaps and guided-local-search weights of every pair.
//!
//! Whether two shapes overlap is always decided by the exact test
//! ([`crate::nest::collide::overlaps`], spacing held in f64); the proxy
//! only says *how much*, for pairs the exact test found overlapping. It is
//! sparrow's (Gardeyn & Wauters, EJOR 2025, §4.2) idea in our own form:
//! over every pair of poles (inscribed circles, [`super::poles`]), the
//! penetration depth `d = r₁ + r₂ − |c₁ − c₂|`, weighted by the smaller
//! radius (a deep overlap of two big circles matters more than of two
//! small ones), summed. Pole pairs that do not touch still count a little,
//! `ε² / (2ε − d)`, which decays with the distance and joins `d` smoothly
//! at `d = ε`: shapes that overlap only where no pole reaches (a corner
//! the poles do not cover) still have a positive value that falls as they
//! move apart. So the value is 0 exactly when the exact test says clear,
//! positive otherwise, and grows with the penetration.
//!
//! The separator takes the square root of that sum (it grows about as the
//! square of the depth) times √(√area₁ · √area₂) of the two parts
//! ([`super::sample`]): an overlap with a large part costs more, so small
//! parts move out of the way of large ones, and a shallow overlap is not
//! so cheap that it is traded for a deep one. Measured (4 instances × 3
//! seeds, 8 s): 0.955 of sparrow's density against 0.940 for the bare sum.
//!
//! The weights are guided local search's (Voudouris & Tsang 1999, as
//! sparrow uses them): after each pass of the separator, a pair still
//! overlapping has its weight raised (more for the worse overlaps), a
//! clear pair's weight decays back towards 1. Pairs that keep overlapping
//! become expensive, so the moves stop trading one overlap for another.

#[cfg(test)]
use super::poles::Pole;
use super::poles::{PoleSet, MAX_POLES};
use crate::geom::{fmax, fmin, Point};

/// The penetration of two pole sets moved by `ta` and `tb` (> 0).
#[cfg(test)]
pub fn proxy(a: &[Pole], ta: Point, b: &[Pole], tb: Point, eps: f64) -> f64 {
    let (a, b) = (PoleSet::new(a), PoleSet::new(b));
    let mut near = Near::default();
    let mut w = Walk::new(&a, ta, &b, tb, eps, f64::INFINITY, &mut near);
    w.rows(a.n, f64::INFINITY);
    w.value()
}

/// [`proxy`] walked row by row (a row: one pole of `a` against `b`'s),
/// given up once the sum passes a limit (then some value above it), and
/// whether some pole pair goes deeper than `deep` (then the shapes overlap
/// for sure: the poles lie inside them). The separator walks the first
/// rows (the largest poles) before it decides whether the exact test is
/// needed at all ([`super::sample`]); walked to the end, in any number of
/// steps, the same pairs are summed in the same order.
///
/// A pole pair counts only while its centres are within twice their
/// reach, so before the pairs are walked each set is cut down to the
/// poles that can reach the other set's box at all (the box of its
/// centres, grown by twice the reach of its largest pole and of the pole
/// asked): two parts overlapping in a sliver leave most pole pairs out.
/// The poles come largest first, so a sample far worse than the best one
/// (most of them) is given up after the first few rows (sparrow's
/// fail-fast, Gardeyn & Wauters 2025 §4.3). Under the limit the value is
/// the same as over every pair.
///
/// A row is walked in two loops: the first only marks the pairs within
/// reach, without a branch (six in seven pairs are out of reach, and a
/// branch taken at random was much of a row's time), the second sums the
/// marked ones in order, so the sum is the one the pairs give one by one,
/// bit for bit.
///
/// The poles kept live in a [`Near`] the caller lends, one for all the
/// pairs of a position: filled anew for each pair, never cleared (only
/// the entries kept are read), and not moved with the walk (a walk
/// holding them, made and returned for every pair, was a twentieth of a
/// separation in memset and memcpy, perf, shapes0).
pub struct Walk<'a> {
    a: &'a PoleSet,
    near: &'a mut Near,
    dt: Point,
    blo: Point,
    bhi: Point,
    br: f64,
    m: usize,
    eps: f64,
    deep: f64,
    /// The next row; past the end once given up.
    row: usize,
    s: f64,
    hit: bool,
}

/// b's poles that may reach a pole of a (in b's frame), and a row's
/// squared distances: a walk's working room.
#[derive(Clone, Debug)]
pub struct Near {
    x: [f64; MAX_POLES],
    y: [f64; MAX_POLES],
    r: [f64; MAX_POLES],
    d2s: [f64; MAX_POLES],
}

impl Default for Near {
    fn default() -> Near {
        Near {
            x: [0.0; MAX_POLES],
            y: [0.0; MAX_POLES],
            r: [0.0; MAX_POLES],
            d2s: [0.0; MAX_POLES],
        }
    }
}

impl<'a> Walk<'a> {
    /// Nothing walked yet.
    #[inline]
    pub fn new(
        a: &'a PoleSet,
        ta: Point,
        b: &PoleSet,
        tb: Point,
        eps: f64,
        deep: f64,
        near: &'a mut Near,
    ) -> Walk<'a> {
        let dt = ta.sub(tb);
        // a's box moved by dt: the least (greatest) centre moved is the
        // least (greatest) moved centre, bit for bit (rounding is monotone).
        let (alo, ahi, ar) = (a.lo.add(dt), a.hi.add(dt), a.rmax);
        let mut m = 0;
        for j in 0..b.n {
            let (x, y, r) = (b.x[j], b.y[j], b.r[j]);
            (near.x[m], near.y[m], near.r[m]) = (x, y, r);
            m += within(Point::new(x, y), alo, ahi, 2.0 * (r + ar)) as usize;
        }
        Walk {
            a,
            near,
            dt,
            blo: b.lo,
            bhi: b.hi,
            br: b.rmax,
            m,
            eps,
            deep,
            row: 0,
            s: 0.0,
            hit: false,
        }
    }

    /// Walks on to row `upto` (or a's last), given up once the sum passes
    /// `limit`.
    pub fn rows(&mut self, upto: usize, limit: f64) {
        let (a, dt, eps, m) = (self.a, self.dt, self.eps, self.m);
        let (mut s, mut hit) = (self.s, self.hit);
        let near = &mut *self.near;
        while self.row < upto.min(a.n) {
            let i = self.row;
            self.row += 1;
            let c = Point::new(a.x[i] + dt.x, a.y[i] + dt.y);
            let pr = a.r[i];
            if !within(c, self.blo, self.bhi, 2.0 * (pr + self.br)) {
                continue;
            }
            let mut mark = mark_row(c, pr, (&near.x, &near.y, &near.r), m, &mut near.d2s);
            while mark != 0 {
                let j = mark.trailing_zeros() as usize;
                mark &= mark - 1;
                let d = (pr + near.r[j]) - near.d2s[j].sqrt();
                hit |= d > self.deep;
                // Both sides worked out and one kept without a jump: which
                // one follows the root just taken, and a jump that waited
                // on it, taken at random, was much of a row. (A plain `if`
                // is made a jump by the compiler, the division sunk into it.)
                let decayed = eps * eps / (2.0 * eps - d);
                let f = std::hint::select_unpredictable(d >= eps, d, decayed);
                s += f * fmin(pr, near.r[j]);
            }
            if s > limit {
                self.row = usize::MAX;
            }
        }
        (self.s, self.hit) = (s, hit);
    }

    /// True when some pair walked went deeper than `deep`.
    pub fn deep(&self) -> bool {
        self.hit
    }

    /// The sum so far; positive even when every pole pair is far (only
    /// asked of shapes that do overlap).
    pub fn value(&self) -> f64 {
        fmax(self.s, self.eps * self.eps * 1e-3)
    }
}

// A row's marks are packed four at a time into a u32 ([`mark_row`]).
const _: () = assert!(MAX_POLES.is_multiple_of(4) && MAX_POLES < 32);

/// b's near poles (x, y, r), as the rows read them.
type Kept<'n> = (
    &'n [f64; MAX_POLES],
    &'n [f64; MAX_POLES],
    &'n [f64; MAX_POLES],
);

/// The row of the pole at `c` (radius `pr`): bit `j` set when near pole
/// `j` (of the first `m`) is within twice their reach, its squared
/// distance in `d2s[j]`, without a branch. Far pairs add less than
/// ε²/(2·reach): left out.
fn mark_row(c: Point, pr: f64, (nx, ny, nr): Kept, m: usize, d2s: &mut [f64; MAX_POLES]) -> u32 {
    // In blocks of four, each bit at a place fixed in its block, so that
    // a block's tests are packed into the mask at once (a bit shifted by
    // the running index was worked out lane by lane, through a float's
    // exponent, SSE2). The entries of the last block past `m` are stale:
    // their bits are cleared at the end.
    let mut mark = 0u32;
    let blocks = nx
        .chunks_exact(4)
        .zip(ny.chunks_exact(4))
        .zip(nr.chunks_exact(4))
        .zip(d2s.chunks_exact_mut(4))
        .take(m.div_ceil(4));
    for (k, (((bx, by), br), bd)) in blocks.enumerate() {
        let mut bits = 0u32;
        for l in 0..4 {
            let (dx, dy) = (c.x - bx[l], c.y - by[l]);
            let reach = pr + br[l];
            let d2 = dx * dx + dy * dy;
            bd[l] = d2;
            // (Not `d2 <= …`: a NaN distance is marked, as it always was.)
            bits |= (((d2 > 4.0 * reach * reach) as u32) ^ 1) << l;
        }
        mark |= bits << (4 * k);
    }
    mark & ((1u32 << m) - 1)
}

/// True when `c` is within `g` of the box `lo`–`hi` along both axes.
fn within(c: Point, lo: Point, hi: Point, g: f64) -> bool {
    c.x >= lo.x - g && c.x <= hi.x + g && c.y >= lo.y - g && c.y <= hi.y + g
}

/// Raise on a pair that still overlaps (× between LOW and HIGH, by its
/// share of the worst overlap); decay of a clear pair's weight.
const LOW: f64 = 1.2;
const HIGH: f64 = 2.0;
const DECAY: f64 = 0.95;

/// The overlap of every pair (0 when clear) and its weight.
#[derive(Clone, Debug)]
pub struct Table {
    n: usize,
    ov: Vec<f64>,
    w: Vec<f64>,
}

impl Table {
    /// `n` shapes, no overlap yet, every weight 1.
    pub fn new(n: usize) -> Table {
        Table {
            n,
            ov: vec![0.0; n * n],
            w: vec![1.0; n * n],
        }
    }
    /// Sets the overlap of `i` and `j`.
    pub fn set(&mut self, i: usize, j: usize, v: f64) {
        self.ov[i * self.n + j] = v;
        self.ov[j * self.n + i] = v;
    }
    /// The weight of `i` and `j`.
    pub fn weight(&self, i: usize, j: usize) -> f64 {
        self.w[i * self.n + j]
    }
    /// True when `i` overlaps something.
    pub fn colliding(&self, i: usize) -> bool {
        self.ov[i * self.n..(i + 1) * self.n]
            .iter()
            .any(|&v| v > 0.0)
    }
    /// Σ overlap over pairs (unweighted).
    pub fn total(&self) -> f64 {
        let mut s = 0.0;
        for i in 0..self.n {
            for j in i + 1..self.n {
                s += self.ov[i * self.n + j];
            }
        }
        s
    }
    /// After a pass: raise the weights of pairs still overlapping, decay
    /// the others towards 1.
    pub fn update_weights(&mut self) {
        let worst = self.ov.iter().cloned().fold(0.0, f64::max);
        for k in 0..self.n * self.n {
            let v = self.ov[k];
            self.w[k] = if v > 0.0 {
                self.w[k] * (LOW + (HIGH - LOW) * v / worst)
            } else {
                fmax(self.w[k] * DECAY, 1.0)
            };
        }
    }
}

#[cfg(test)]
#[path = "overlap_tests.rs"]
mod tests;
