//! Iterated local search: a kick is a local segment swap (a "double
//! bridge" confined to nearby positions, the usual perturbation of
//! Lin–Kernighan style iterated search, Johnson & McGeoch 1997), followed by
//! a local search around it; kept only if the tour gets shorter.

use super::{d, dist, Path, EPS};

/// Longest block a kick swaps.
const KICK_MAX: usize = 10;

/// Small deterministic generator (xorshift64*): same input, same tour.
struct Rng(u64);
impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let r = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        ((r >> 33) % n.max(1) as u64) as usize
    }
}

/// Iterated local search: swap two short adjacent blocks, re-optimise
/// around them, keep the result only if shorter.
pub(super) fn kicks(path: &mut Path, iterations: usize) {
    let n = path.seq.len();
    if n < 8 || iterations == 0 {
        return;
    }
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut best_seq = path.seq.clone();
    let mut best_at = path.at.clone();
    let mut best_len = path.len;
    let patience = patience(n);
    let mut last_better = 0;
    for kick in 0..iterations {
        if kick - last_better >= patience {
            break;
        }
        path.dirty = (usize::MAX, 0);
        let l1 = 1 + rng.below(KICK_MAX.min(n / 4));
        let l2 = 1 + rng.below(KICK_MAX.min(n / 4));
        let p = rng.below(n - l1 - l2 + 1);
        let (b, c, e) = (p, p + l1, p + l1 + l2);
        // C moves before B: illegal if a site of B has its parent in C.
        let legal = path.seq[b..c]
            .iter()
            .all(|&s| path.inst.up[s].is_none_or(|u| path.pos[u] < c || path.pos[u] >= e));
        if !legal {
            continue;
        }
        let pt = |path: &Path, i: usize| path.at_pos(i);
        let before = path.before(b);
        let (fb, lb) = (path.p(path.seq[b]), path.p(path.seq[c - 1]));
        let (fc, lc) = (path.p(path.seq[c]), path.p(path.seq[e - 1]));
        let next = pt(path, e);
        let old = dist(before, fb) + dist(lb, fc) + d(lc, next);
        let new = dist(before, fc) + dist(lc, fb) + d(lb, next);
        path.seq[b..e].rotate_left(l1);
        path.touch(b, e - 1);
        path.len += new - old;
        for t in [b.wrapping_sub(1), b, b + l2 - 1, b + l2, e - 1, e] {
            path.push_pos(t);
        }
        path.local_search();
        let (lo, hi) = path.dirty;
        if lo > hi {
            continue;
        }
        let hi = hi.min(n - 1);
        if path.len < best_len - EPS {
            last_better = kick;
            best_len = path.len;
            best_seq[lo..=hi].copy_from_slice(&path.seq[lo..=hi]);
            for &s in &path.seq[lo..=hi] {
                best_at[s] = path.at[s];
            }
        } else {
            path.seq[lo..=hi].copy_from_slice(&best_seq[lo..=hi]);
            for t in lo..=hi {
                let s = path.seq[t];
                path.at[s] = best_at[s];
                path.cur[s] = path.inst.pts[s][best_at[s]];
                path.pos[s] = t;
            }
            path.len = best_len;
        }
    }
}

/// Kicks in all: fixed work, so the result is reproducible. A kick costs
/// 5–10 µs on hundreds of sites and ~15 µs on 60k (its local search stays
/// local; the copy-back of what it touched grows a little). Up to
/// [`KICKS_UNTIL`] sites [`KICKS_PER_SITE`] a site, at least [`KICKS_MIN`]
/// and at most [`KICKS`]: 10,000 on a 100-part nest (33 a site: within
/// 0.1 % of LKH-3 there, 2.5 % above with one a site), 30,000 on 5,000
/// parts (15k sites, 0.3 s in all: 1.9 % above LKH-3, 3.1 % with 10,000).
/// Above, on sheets of tens of thousands of contours (the short schedule,
/// `Effort`), [`KICKS_LARGE`], none: at 60k sites 10,000
/// took ~100 ms more than 3,000 for 0.5–0.8 %, and 3,000 ~30–40 ms
/// (a sixth of the tour) more than none for 0.3 % on the bench nests and
/// ±0.03 % on the 4, 11 and 25 MB sheets (`cargo bench --bench tsp --
/// --effort`; issue 17 asks for 60k sites in 200 ms within 5 % of a long
/// search: 1.027 and 1.042 of it without kicks). Measured in benches/tsp.rs. 30 a site (tried first) made a 1,162-contour nest plan
/// in 350 ms instead of 50.
const KICKS: usize = 30_000;
/// Fewest kicks (small instances).
const KICKS_MIN: usize = 10_000;
/// Kicks a site between [`KICKS_MIN`] and [`KICKS`].
const KICKS_PER_SITE: usize = 2;
/// Largest instance that gets [`KICKS`]; larger ones get [`KICKS_LARGE`].
const KICKS_UNTIL: usize = 20_000;
/// Kicks above [`KICKS_UNTIL`] sites.
const KICKS_LARGE: usize = 0;

/// Kicks in a row without a shorter tour after which a tour of `n` sites
/// stops: [`PATIENCE_PER_SITE`] a site, at least [`PATIENCE_MIN`]. The
/// kicks are the same stream either way, so a stop after the last kick that
/// would have helped leaves the same tour. On the corpus (37 plans of 8 to
/// 639 sites, 2026-11-30) the longest run of useless kicks before a better
/// tour was 943 on 21 sites, 2,846 on 40 and 3,726 on 408: 100 a site
/// stops none of them early (the programs byte-identical) and ends the
/// tours of up to 36 sites, most plans of a small file, after 1,000 to
/// 3,600 kicks instead of 10,000.
fn patience(n: usize) -> usize {
    (PATIENCE_PER_SITE * n).max(PATIENCE_MIN)
}
/// See [`patience`].
const PATIENCE_PER_SITE: usize = 100;
/// See [`patience`].
const PATIENCE_MIN: usize = 1_000;

/// How many kicks a tour of `n` sites gets (see [`KICKS`]).
pub(crate) fn count(n: usize) -> usize {
    if n <= KICKS_UNTIL {
        (KICKS_PER_SITE * n).clamp(KICKS_MIN, KICKS)
    } else {
        KICKS_LARGE
    }
}
