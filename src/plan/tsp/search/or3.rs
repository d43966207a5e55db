//! Or-3opt: the segment exchange A B C D → A C B D, the one pure 3-opt
//! reconnection that keeps every segment's direction (so it never reverses
//! a hole–outer pair), of which Or-opt is the case |B| ≤ 3. Driven from a
//! site by its neighbour list with the positive-gain rule of Lin and
//! Kernighan (1973): the first new edge must be shorter than the edge it
//! replaces, and the partial gain must stay positive through the second.
//! Johnson and McGeoch (1997) put 2-opt + Or-opt about 4.5–5 % above the
//! Held–Karp bound on random uniform instances and 3-opt about 3 %; this
//! move is what takes the search from the first to near the second.

use super::moves::Move;
use super::{d, dist, Path, EPS};

/// Longest stretch B C an exchange rearranges (it costs O(|B| + |C|)).
const SPAN_MAX: usize = 1000;

impl Path<'_> {
    /// The first gaining segment exchange with `s` at one end of B.
    pub(super) fn or3(&self, s: usize) -> Option<Move> {
        self.or3_from_last(s).or_else(|| self.or3_from_first(s))
    }

    /// `s` is B's last site (position j): new edge s–d1 with d1 a neighbour
    /// after s (C = j+1..pos(d1)-1, or the path's end), then B's first site
    /// a neighbour of C's last site.
    fn or3_from_last(&self, s: usize) -> Option<Move> {
        let n = self.seq.len();
        let j = self.pos[s];
        if j + 1 >= n {
            return None;
        }
        let (bj, c1) = (self.p(s), self.p(self.seq[j + 1]));
        let out = dist(bj, c1);
        let m = self.neigh[s].len();
        for t in 0..=m {
            // The neighbours nearest first, then the open end of the path.
            let (k, d1) = if t < m {
                let x = self.neigh[s][t] as usize;
                let q = self.pos[x];
                let dn = dist(bj, self.p(x));
                if dn >= out {
                    continue;
                }
                if q < j + 2 {
                    continue;
                }
                (q - 1, Some(self.p(x)))
            } else {
                (n - 1, None)
            };
            if k - j > SPAN_MAX || k == j {
                continue;
            }
            let g1 = out - d(bj, d1);
            let ck_site = self.seq[k];
            let ck = self.p(ck_site);
            let g2 = g1 + d(ck, d1);
            for u in 0..self.neigh[ck_site].len() {
                let b1_site = self.neigh[ck_site][u] as usize;
                let b1 = self.p(b1_site);
                let close = dist(ck, b1);
                if close >= g2 {
                    break;
                }
                let i = self.pos[b1_site];
                if i > j || j - i > SPAN_MAX {
                    continue;
                }
                let a = self.before(i);
                let delta = dist(a, c1) + close + d(bj, d1) - dist(a, b1) - out - d(ck, d1);
                if delta < -EPS {
                    if let Some(m) = self.exchange(i, j, k, delta) {
                        return Some(m);
                    }
                }
            }
        }
        None
    }

    /// `s` is B's first site (position i): new edge ck–s with ck a
    /// neighbour after s (C ends at ck), then C's first site a neighbour
    /// of the site before s.
    fn or3_from_first(&self, s: usize) -> Option<Move> {
        let i = self.pos[s];
        if i == 0 {
            return None;
        }
        let a_site = self.seq[i - 1];
        let (a, b1) = (self.p(a_site), self.p(s));
        let inn = dist(a, b1);
        for t in 0..self.neigh[s].len() {
            let ck_site = self.neigh[s][t] as usize;
            let ck = self.p(ck_site);
            let close = dist(ck, b1);
            if close >= inn {
                break;
            }
            let k = self.pos[ck_site];
            if k <= i || k - i > SPAN_MAX {
                continue;
            }
            let g1 = inn - close;
            let d1 = self.at_pos(k + 1);
            let g2 = g1 + d(ck, d1);
            for u in 0..self.neigh[a_site].len() {
                let c1_site = self.neigh[a_site][u] as usize;
                let c1 = self.p(c1_site);
                let join = dist(a, c1);
                if join >= g2 {
                    break;
                }
                let q = self.pos[c1_site];
                if q <= i || q > k {
                    continue;
                }
                let j = q - 1;
                let bj = self.p(self.seq[j]);
                let delta = join + close + d(bj, d1) - inn - dist(bj, c1) - d(ck, d1);
                if delta < -EPS {
                    if let Some(m) = self.exchange(i, j, k, delta) {
                        return Some(m);
                    }
                }
            }
        }
        None
    }

    /// Putting positions j+1..=k before i..=j, if legal (no site of B has
    /// its parent in C); `delta` is the change of length.
    fn exchange(&self, i: usize, j: usize, k: usize, delta: f64) -> Option<Move> {
        let up = &self.inst.up;
        let legal = self.seq[i..=j]
            .iter()
            .all(|&s| up[s].is_none_or(|u| self.pos[u] <= j || self.pos[u] > k));
        legal.then_some(Move::Exchange { i, j, k, delta })
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::{Inst, Site};
    use super::super::Path;
    use crate::geom::Point;

    /// The first exchange from `s`, applied; true if there was one.
    fn try_or3(path: &mut Path, s: usize) -> bool {
        path.or3(s).map(|m| path.apply(m)).is_some()
    }

    /// Sites on the x axis at 5..=8 (B) then 1..=4 (C), origin 0: blocks
    /// of four, beyond Or-opt's three. `parent`: (child, parent) links.
    fn line(parent: &[(usize, usize)]) -> Vec<Site> {
        let mut sites: Vec<Site> = [5.0, 6.0, 7.0, 8.0, 1.0, 2.0, 3.0, 4.0]
            .iter()
            .map(|&x| Site {
                candidates: vec![Point::new(x, 0.0)],
                parent: None,
            })
            .collect();
        for &(c, p) in parent {
            sites[c].parent = Some(p);
        }
        sites
    }

    #[test]
    fn exchanges_two_blocks_of_four() {
        let sites = line(&[]);
        let inst = Inst::new(&sites);
        let mut path = Path::new(&inst, Point::default(), (0..8).collect(), vec![0; 8]);
        path.rebuild_neighbours();
        assert!((path.len - 18.0).abs() < 1e-9);
        assert!(try_or3(&mut path, 3), "B's last site finds an exchange");
        assert!(path.len < 18.0 - 1.0);
        assert!((path.length() - path.len).abs() < 1e-9);
        // Exchanges alone, to a fixed point, sort the line.
        while (0..8).any(|s| try_or3(&mut path, s)) {}
        assert_eq!(path.seq, vec![4, 5, 6, 7, 0, 1, 2, 3]);
        assert!((path.len - 8.0).abs() < 1e-9);
        assert!((path.length() - path.len).abs() < 1e-9);
    }

    #[test]
    fn never_puts_a_parent_before_its_hole() {
        // Site 0 (x = 5) must come before site 4 (x = 1): C cannot move
        // before all of B.
        let sites = line(&[(0, 4)]);
        let inst = Inst::new(&sites);
        let mut path = Path::new(&inst, Point::default(), (0..8).collect(), vec![0; 8]);
        path.rebuild_neighbours();
        for s in 0..8 {
            while try_or3(&mut path, s) {}
        }
        let at = |s: usize| path.seq.iter().position(|&x| x == s).unwrap();
        assert!(at(0) < at(4), "{:?}", path.seq);
        assert!((path.length() - path.len).abs() < 1e-9);
        assert!(path.len < 18.0, "a legal exchange still gains");
    }
}
