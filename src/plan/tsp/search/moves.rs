//! The moves of the local search around one site ([`Path::improve_site`]):
//! 2-opt (plain, and over whole families so holes stay before their outer
//! contour), Or-opt of 1–3 sites or a family either way round (a single
//! site re-choosing its entry), then Or-3opt ([`super::or3`]). Every move
//! is checked for precedence and applied only if it gains.
//!
//! Finding a move ([`Path::find`]) only reads the path; applying it
//! ([`Path::apply`]) is separate, so the sites a local search is to look
//! at can be screened on several threads first (`Path::screen`).

use super::{d, dist, Path, EPS};

/// A gaining, legal move found around a site; `delta` is the change of
/// the path's length (negative).
#[derive(Clone, Copy, Debug)]
pub(super) enum Move {
    /// 2-opt: reverse positions i..=j.
    Reverse { i: usize, j: usize, delta: f64 },
    /// 2-opt over families: reverse the order of the units of i..=j (the
    /// units in the path's scratch, `Path::units`).
    Units { i: usize, j: usize, delta: f64 },
    /// Or-opt: positions i..=j to the gap before `g`, reversed or not, the
    /// block's first site entered at its candidate `entry`.
    Shift {
        i: usize,
        j: usize,
        g: usize,
        rev: bool,
        entry: usize,
        delta: f64,
    },
    /// Or-3opt: positions j+1..=k put before i..=j.
    Exchange {
        i: usize,
        j: usize,
        k: usize,
        delta: f64,
    },
}

/// Longest stretch `reverse_units` looks at (its gain costs O(length)).
const UNITS_MAX: usize = 1000;
/// Largest family (holes + outer) moved as one block.
const FAMILY_MAX: usize = 12;
/// Or-opt looks for a gap next to a neighbour m of the block's end only
/// while that end is nearer m than this many times what taking the block
/// out saves (neighbours come nearest first): the positive-gain idea of Lin
/// and Kernighan, loosened. At 1× the tours came out 1–2 % longer; at 3×
/// they are as short as with no cut-off (within the kicks' noise) and the
/// local search takes a third of the time (benches/tsp.rs, random nests).
const OR_PRUNE: f64 = 3.0;

/// Which way round Or-opt may put a block back.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Way {
    Forward,
    Reversed,
    Both,
}

impl Path<'_> {
    /// Reversing positions i..=j, if that is legal and gains (else the
    /// same over families, [`Path::units_move`]).
    fn reverse(&self, i: usize, j: usize, units: &mut Vec<(usize, usize)>) -> Option<Move> {
        if i >= j || j >= self.seq.len() {
            return None;
        }
        let (a, b) = (self.before(i), self.at_pos(j + 1));
        let (f, l) = (self.p(self.seq[i]), self.p(self.seq[j]));
        let delta = dist(a, l) + d(f, b) - dist(a, f) - d(l, b);
        if delta > -EPS {
            return None;
        }
        let inside = |t: usize| t >= i && t <= j;
        let legal = self.seq[i..=j]
            .iter()
            .all(|&s| self.inst.up[s].is_none_or(|u| !inside(self.pos[u])));
        if !legal {
            return self.units_move(i, j, units);
        }
        Some(Move::Reverse { i, j, delta })
    }

    /// 2-opt at the level of families: reverses the order of the units of
    /// positions i..=j — a unit being a run of holes followed by their outer
    /// contour, or a single site — each unit kept in its own order, so the
    /// holes still come first. Plain 2-opt can never reverse a stretch holding
    /// a whole part with holes, which is nearly every long stretch of a nest.
    /// Legal only if the stretch splits into such units exactly and no unit's
    /// last site has its parent inside; gains are computed over every unit
    /// boundary (a unit is entered and left at different points). The
    /// units are left in `units`.
    fn units_move(&self, i: usize, j: usize, units: &mut Vec<(usize, usize)>) -> Option<Move> {
        if j + 1 - i > UNITS_MAX {
            return None;
        }
        units.clear();
        if !self.split_units(i, j, units) {
            return None;
        }
        let delta = self.units_delta(i, j, units)?;
        Some(Move::Units { i, j, delta })
    }

    /// Splits i..=j into units (see `reverse_units`); false if it cannot.
    fn split_units(&self, i: usize, j: usize, units: &mut Vec<(usize, usize)>) -> bool {
        let up = &self.inst.up;
        let mut t = i;
        while t <= j {
            let end = match up[self.seq[t]] {
                Some(u) if self.pos[u] > t && self.pos[u] <= j => {
                    let e = self.pos[u];
                    if !self.seq[t..e].iter().all(|&k| up[k] == Some(u)) {
                        return false;
                    }
                    e
                }
                _ => t,
            };
            if up[self.seq[end]].is_some_and(|u| self.pos[u] <= j) {
                return false;
            }
            units.push((t, end));
            t = end + 1;
        }
        units.len() >= 2
    }

    /// The change of length from reversing the order of `units` (None if
    /// it does not gain).
    fn units_delta(&self, i: usize, j: usize, units: &[(usize, usize)]) -> Option<f64> {
        let entry = |u: &(usize, usize)| self.p(self.seq[u.0]);
        let exit = |u: &(usize, usize)| self.p(self.seq[u.1]);
        let (first, last) = (units.first()?, units.last()?);
        let (a, b) = (self.before(i), self.at_pos(j + 1));
        let mut old = dist(a, entry(first)) + d(exit(last), b);
        let mut new = dist(a, entry(last)) + d(exit(first), b);
        for w in units.windows(2) {
            old += dist(exit(&w[0]), entry(&w[1]));
            new += dist(exit(&w[1]), entry(&w[0]));
        }
        let delta = new - old;
        (delta < -EPS).then_some(delta)
    }

    /// Moving positions i..=j to the gap before position `g` (0..=n, not
    /// in i..=j+1), either way round, if legal and gaining.
    fn shift(&self, i: usize, j: usize, g: usize, removed: f64, way: Way) -> Option<Move> {
        let n = self.seq.len();
        if j >= n || g > n || (g >= i && g <= j + 1) {
            return None;
        }
        let (f, l) = (self.seq[i], self.seq[j]);
        let (a, b) = (self.before(g), self.at_pos(g));
        let base = d(a, b);
        // Best way in: forward, reversed, and for one site every entry.
        let mut best: Option<(f64, bool, usize)> = None;
        if i == j {
            // Every candidate lies within `radius` of `centre`: a lower bound
            // on the cost of the best one, to skip hopeless gaps cheaply.
            let (c, r) = self.inst.disc[f];
            let lower = dist(a, c) + b.map_or(-r, |b| dist(c, b) - r) - r - base;
            if lower - removed > -EPS {
                return None;
            }
            let spread = self.inst.spread(f);
            for c in spread.iter().copied().chain([self.at[f]]) {
                let v = self.inst.pts[f][c];
                let add = dist(a, v) + d(v, b) - base;
                if best.is_none_or(|(x, _, _)| add < x) {
                    best = Some((add, false, c));
                }
            }
        } else {
            if way != Way::Reversed {
                let fwd = dist(a, self.p(f)) + d(self.p(l), b) - base;
                best = Some((fwd, false, self.at[f]));
            }
            if way != Way::Forward {
                let rev = dist(a, self.p(l)) + d(self.p(f), b) - base;
                if best.is_none_or(|(x, _, _)| rev < x)
                    && rev - removed < -EPS
                    && self.reversible(i, j)
                {
                    best = Some((rev, true, self.at[f]));
                }
            }
        }
        let (add, rev, entry) = best?;
        let delta = add - removed;
        if delta > -EPS {
            return None;
        }
        let up = &self.inst.up;
        let legal = if g < i {
            // Sites in g..i end up after the block: none may be a child.
            self.seq[i..=j].iter().all(|&s| {
                self.inst.kids[s]
                    .iter()
                    .all(|&k| self.pos[k] < g || self.pos[k] >= i)
            })
        } else {
            // Sites in j+1..g end up before the block: none may be a parent.
            self.seq[i..=j]
                .iter()
                .all(|&s| up[s].is_none_or(|u| self.pos[u] <= j || self.pos[u] >= g))
        };
        legal.then_some(Move::Shift {
            i,
            j,
            g,
            rev,
            entry,
            delta,
        })
    }

    /// True if positions i..=j hold no site together with its parent.
    fn reversible(&self, i: usize, j: usize) -> bool {
        self.seq[i..=j]
            .iter()
            .all(|&s| self.inst.up[s].is_none_or(|u| self.pos[u] < i || self.pos[u] > j))
    }

    /// The first gaining move around site `s`, in the order below (the
    /// units of a move over families left in `units`).
    pub(super) fn find(&self, s: usize, units: &mut Vec<(usize, usize)>) -> Option<Move> {
        let n = self.seq.len();
        let p = self.pos[s];
        // 2-opt: every reversal that creates an edge s–c with c near s.
        // Positive-gain rule (Lin & Kernighan 1973): the new edge s–c must
        // be shorter than an edge of s it replaces; neighbours come nearest first.
        let here = self.p(s);
        let longest = dist(self.before(p), here).max(d(here, self.at_pos(p + 1)));
        for k in 0..self.neigh[s].len() {
            let c = self.neigh[s][k] as usize;
            if dist(here, self.p(c)) >= longest {
                break;
            }
            let q = self.pos[c];
            let found = if q > p {
                self.reverse(p + 1, q, units)
                    .or_else(|| (p + 1 < q).then(|| self.reverse(p, q - 1, units)).flatten())
            } else {
                self.reverse(q + 1, p, units).or_else(|| {
                    (q + 1 < p && p > 0)
                        .then(|| self.reverse(q, p - 1, units))
                        .flatten()
                })
            };
            if found.is_some() {
                return found;
            }
        }
        let last = n.saturating_sub(1);
        let found = self
            .reverse(0, p, units)
            .or_else(|| self.reverse(p + 1, last, units));
        if found.is_some() {
            return found;
        }
        if let Some(m) = self.reverse(p, last, units) {
            return Some(m);
        }
        // Or-opt: blocks of 1–3 sites starting or ending at s, and the
        // whole family ending at s (its holes, then s), so a part with its
        // holes can move as one.
        let kids = self.inst.kids[s].len();
        let family = (kids > 0
            && kids < FAMILY_MAX
            && p >= kids
            && self.seq[p - kids..p]
                .iter()
                .all(|&k| self.inst.up[k] == Some(s)))
        .then(|| (p - kids, p));
        let blocks = [
            Some((p, p)),
            Some((p, p + 1)),
            Some((p, p + 2)),
            Some((p.wrapping_sub(1), p)),
            Some((p.wrapping_sub(2), p)),
            family.filter(|&(i, _)| i + 2 < p),
        ];
        for (i, j) in blocks.into_iter().flatten() {
            if i > j || j >= n {
                continue;
            }
            let (f, l) = (self.seq[i], self.seq[j]);
            let (pp, nn) = (self.before(i), self.at_pos(j + 1));
            let removed = dist(pp, self.p(f)) + d(self.p(l), nn) - d(pp, nn);
            let found = self
                .shift(i, j, 0, removed, Way::Both)
                .or_else(|| self.shift(i, j, n, removed, Way::Both));
            if found.is_some() {
                return found;
            }
            // The block's first site next to a neighbour m: after m as it
            // is, or before m reversed (a single site: both gaps, any entry).
            for k in 0..self.neigh[f].len() {
                let m = self.neigh[f][k] as usize;
                if dist(self.p(f), self.p(m)) >= OR_PRUNE * removed {
                    break;
                }
                let q = self.pos[m];
                let found = self
                    .shift(i, j, q + 1, removed, Way::Forward)
                    .or_else(|| self.shift(i, j, q, removed, Way::Reversed));
                if found.is_some() {
                    return found;
                }
            }
            if i == j {
                continue;
            }
            for k in 0..self.neigh[l].len() {
                let m = self.neigh[l][k] as usize;
                if dist(self.p(l), self.p(m)) >= OR_PRUNE * removed {
                    break;
                }
                let q = self.pos[m];
                let found = self
                    .shift(i, j, q, removed, Way::Forward)
                    .or_else(|| self.shift(i, j, q + 1, removed, Way::Reversed));
                if found.is_some() {
                    return found;
                }
            }
        }
        self.or3(s)
    }
}
