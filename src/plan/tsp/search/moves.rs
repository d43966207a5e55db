//! The moves of the local search around one site ([`Path::improve_site`]):
//! 2-opt (plain, and over whole families so holes stay before their outer
//! contour), Or-opt of 1–3 sites or a family either way round (a single
//! site re-choosing its entry), then Or-3opt ([`super::or3`]). Every move
//! is checked for precedence and applied only if it gains.

use super::{d, dist, Path, EPS};

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
    /// Reverses positions i..=j if that is legal and gains; true if done.
    fn try_reverse(&mut self, i: usize, j: usize) -> bool {
        if i >= j || j >= self.seq.len() {
            return false;
        }
        let (a, b) = (self.before(i), self.at_pos(j + 1));
        let (f, l) = (self.p(self.seq[i]), self.p(self.seq[j]));
        let delta = dist(a, l) + d(f, b) - dist(a, f) - d(l, b);
        if delta > -EPS {
            return false;
        }
        let inside = |t: usize| t >= i && t <= j;
        let legal = self.seq[i..=j]
            .iter()
            .all(|&s| self.inst.up[s].is_none_or(|u| !inside(self.pos[u])));
        if !legal {
            return self.reverse_units(i, j);
        }
        self.seq[i..=j].reverse();
        self.touch(i, j);
        self.len += delta;
        for t in [i.wrapping_sub(1), i, j, j + 1] {
            self.push_pos(t);
        }
        true
    }

    /// 2-opt at the level of families: reverses the order of the units of
    /// positions i..=j — a unit being a run of holes followed by their outer
    /// contour, or a single site — each unit kept in its own order, so the
    /// holes still come first. Plain 2-opt can never reverse a stretch holding
    /// a whole part with holes, which is nearly every long stretch of a nest.
    /// Legal only if the stretch splits into such units exactly and no unit's
    /// last site has its parent inside; gains are computed over every unit
    /// boundary (a unit is entered and left at different points). True if done.
    fn reverse_units(&mut self, i: usize, j: usize) -> bool {
        if j + 1 - i > UNITS_MAX {
            return false;
        }
        let mut units = std::mem::take(&mut self.units);
        units.clear();
        let done = self.split_units(i, j, &mut units) && self.apply_units(i, j, &units);
        self.units = units;
        done
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

    /// Reverses the units if that gains.
    fn apply_units(&mut self, i: usize, j: usize, units: &[(usize, usize)]) -> bool {
        let entry = |u: &(usize, usize)| self.p(self.seq[u.0]);
        let exit = |u: &(usize, usize)| self.p(self.seq[u.1]);
        let (Some(first), Some(last)) = (units.first(), units.last()) else {
            return false;
        };
        let (a, b) = (self.before(i), self.at_pos(j + 1));
        let mut old = dist(a, entry(first)) + d(exit(last), b);
        let mut new = dist(a, entry(last)) + d(exit(first), b);
        for w in units.windows(2) {
            old += dist(exit(&w[0]), entry(&w[1]));
            new += dist(exit(&w[1]), entry(&w[0]));
        }
        let delta = new - old;
        if delta > -EPS {
            return false;
        }
        let mut out = Vec::with_capacity(j + 1 - i);
        for &(x, y) in units.iter().rev() {
            out.extend_from_slice(&self.seq[x..=y]);
        }
        self.seq[i..=j].copy_from_slice(&out);
        self.touch(i, j);
        self.len += delta;
        for t in [i.wrapping_sub(1), i, j, j + 1] {
            self.push_pos(t);
        }
        true
    }

    /// Moves positions i..=j to the gap before position `g` (0..=n, not in
    /// i..=j+1), either way round, if legal and gaining; true if done.
    fn try_move(&mut self, i: usize, j: usize, g: usize, removed: f64, way: Way) -> bool {
        let n = self.seq.len();
        if j >= n || g > n || (g >= i && g <= j + 1) {
            return false;
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
                return false;
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
        let Some((add, rev, entry)) = best else {
            return false;
        };
        let delta = add - removed;
        if delta > -EPS {
            return false;
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
        if !legal {
            return false;
        }
        let len = j - i + 1;
        let (lo, hi, at) = if g < i {
            self.seq[g..=j].rotate_right(len);
            (g, j, g)
        } else {
            self.seq[i..g].rotate_left(len);
            (i, g - 1, g - len)
        };
        if rev {
            self.seq[at..at + len].reverse();
        }
        self.at[f] = entry;
        self.cur[f] = self.inst.pts[f][entry];
        self.touch(lo, hi);
        self.len += delta;
        for t in [
            i.wrapping_sub(1),
            i,
            at.wrapping_sub(1),
            at,
            at + len - 1,
            at + len,
        ] {
            self.push_pos(t);
        }
        // The block's old successor, now joined to its old predecessor.
        if g < i {
            self.push_pos(j + 1);
        }
        true
    }

    /// True if positions i..=j hold no site together with its parent.
    fn reversible(&self, i: usize, j: usize) -> bool {
        self.seq[i..=j]
            .iter()
            .all(|&s| self.inst.up[s].is_none_or(|u| self.pos[u] < i || self.pos[u] > j))
    }

    /// Tries the moves around site `s`; true on the first gain.
    pub(super) fn improve_site(&mut self, s: usize) -> bool {
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
            let done = if q > p {
                self.try_reverse(p + 1, q) || (p + 1 < q && self.try_reverse(p, q - 1))
            } else {
                self.try_reverse(q + 1, p) || (q + 1 < p && p > 0 && self.try_reverse(q, p - 1))
            };
            if done {
                return true;
            }
        }
        if self.try_reverse(0, p) || self.try_reverse(p + 1, n.saturating_sub(1)) {
            return true;
        }
        if self.try_reverse(p, n.saturating_sub(1)) {
            return true;
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
            if self.try_move(i, j, 0, removed, Way::Both)
                || self.try_move(i, j, n, removed, Way::Both)
            {
                return true;
            }
            // The block's first site next to a neighbour m: after m as it
            // is, or before m reversed (a single site: both gaps, any entry).
            for k in 0..self.neigh[f].len() {
                let m = self.neigh[f][k] as usize;
                if dist(self.p(f), self.p(m)) >= OR_PRUNE * removed {
                    break;
                }
                let q = self.pos[m];
                if self.try_move(i, j, q + 1, removed, Way::Forward)
                    || self.try_move(i, j, q, removed, Way::Reversed)
                {
                    return true;
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
                if self.try_move(i, j, q, removed, Way::Forward)
                    || self.try_move(i, j, q + 1, removed, Way::Reversed)
                {
                    return true;
                }
            }
        }
        self.try_or3(s)
    }
}
