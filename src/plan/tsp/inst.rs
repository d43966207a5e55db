//! The cleaned instance every step of the tour works on: finite candidates,
//! precedence as nearest visitable ancestors, and (above [`super::LARGE`]
//! sites) the sites in sheet order ([`super::spatial`]). Per-site lists
//! are stored flat ([`Lists`]): one allocation each instead of one per
//! site (137k sites on the 25 MB nest; per-site vectors lay wherever the
//! heap had room after the earlier stages, and the entry re-choice spent
//! most of its time in cache misses reading them).

use super::{dist, Sites, SPREAD};
use crate::geom::Point;
use std::ops::Index;
use std::sync::Arc;

/// The cleaned instance every step works on. The candidates and what is
/// read from them are shared ([`Arc`]: the tour may search the two on two
/// threads) with the instance's [`Inst::relaxed`] copy: cloned, they were
/// ~25 MB of fresh pages on a 137k-site sheet, each zeroed by the kernel
/// on first touch.
pub(super) struct Inst {
    /// Finite candidates of each site (16 bytes each: the entry
    /// re-choices read them for every site, several times a tour).
    pub pts: Arc<Lists<Point>>,
    /// Index in `Site::candidates` of each of `pts` (read once, at the end).
    pub cand: Arc<Lists<u32>>,
    /// The sample of [`Inst::spread`] for sites with more than [`SPREAD`]
    /// candidates (empty for the others).
    far: Arc<Lists<usize>>,
    /// A disc holding every candidate of each site: (centre, radius).
    pub disc: Arc<Vec<(Point, f64)>>,
    /// Nearest visitable proper ancestor: must come after the site.
    pub up: Vec<Option<usize>>,
    /// Visitable sites whose `up` is this site.
    pub kids: Lists<usize>,
    /// Visitable sites (with at least one finite candidate), ascending.
    pub active: Vec<usize>,
    /// The caller's site number of each site (empty: the same numbers; see
    /// [`spatial`]).
    pub order: Vec<usize>,
}

impl Inst {
    /// Cleans `sites`: drops non-finite candidates, ignores bad parent
    /// links, breaks cycles, and links each visitable site to its nearest
    /// visitable ancestor — so a hole that vanished (no candidates) still
    /// keeps its islands before the part's outer contour.
    #[cfg(test)]
    pub(super) fn new(sites: &[super::Site]) -> Inst {
        Inst::numbered(&Sites::of(sites), Vec::new())
    }

    /// [`Inst::new`] with the sites renumbered: site `i` of the instance
    /// is `sites[order[i]]` (`order` a permutation; empty: as given).
    pub(super) fn numbered(sites: &Sites, order: Vec<usize>) -> Inst {
        let n = sites.count();
        let order = if order.len() == n { order } else { Vec::new() };
        let mut inv = Vec::new();
        if !order.is_empty() {
            inv = vec![0; n];
            for (i, &o) in order.iter().enumerate() {
                inv[o] = i;
            }
        }
        let site = |i: usize| order.get(i).copied().unwrap_or(i);
        let finite = |j: usize| {
            sites
                .candidates(j)
                .iter()
                .enumerate()
                .filter(|(_, p)| p.is_finite())
        };
        // Both lists sized up front (grown by doubling, the 137k-site
        // sheet's lists were copied and their pages touched several times
        // over) and filled in the caller's order, each site's candidates
        // written where its new number puts them: the reads one after the
        // other, the writes anywhere but never waited on. (Read in the new
        // order, each site's candidates were a cache miss on a big sheet.)
        let count: Vec<u32> = (0..n).map(|j| finite(j).count() as u32).collect();
        let mut first = Vec::with_capacity(n + 1);
        first.push(0);
        for i in 0..n {
            first.push(first[i] + count[site(i)] as usize);
        }
        drop(count);
        let total = first[n];
        let mut pts = Lists {
            first: first.clone(),
            items: vec![Point::default(); total],
        };
        let mut cand = Lists {
            first,
            items: vec![0u32; total],
        };
        for j in 0..n {
            let i = inv.get(j).copied().unwrap_or(j);
            let at = pts.first[i];
            for (t, (c, p)) in finite(j).enumerate() {
                pts.items[at + t] = *p;
                cand.items[at + t] = c as u32;
            }
        }
        let visitable: Vec<bool> = pts.iter().map(|p| !p.is_empty()).collect();
        let mut par: Vec<Option<usize>> = (0..n)
            .map(|i| {
                let p = sites.parent(site(i)).filter(|&p| p < n);
                p.map(|p| inv.get(p).copied().unwrap_or(p))
                    .filter(|&p| p != i)
            })
            .collect();
        // Walk each chain up with an explicit stack (no recursion); a node met
        // again on the current chain closes a cycle: cut the link that closed it.
        const NEW: u8 = 0;
        const OPEN: u8 = 1;
        const DONE: u8 = 2;
        let mut state = vec![NEW; n];
        let mut up: Vec<Option<usize>> = vec![None; n];
        let mut chain = Vec::new();
        for s in 0..n {
            let mut x = s;
            loop {
                if state[x] == DONE {
                    break;
                }
                if state[x] == OPEN {
                    if let Some(&last) = chain.last() {
                        par[last] = None;
                    }
                    break;
                }
                state[x] = OPEN;
                chain.push(x);
                match par[x] {
                    Some(p) => x = p,
                    None => break,
                }
            }
            while let Some(y) = chain.pop() {
                up[y] = par[y].and_then(|p| if visitable[p] { Some(p) } else { up[p] });
                state[y] = DONE;
            }
        }
        let active: Vec<usize> = (0..n).filter(|&s| visitable[s]).collect();
        let kids = Lists::grouped(n, active.iter().filter_map(|&s| Some((up[s]?, s))));
        // Sites with few candidates (nearly all) take them all: nothing
        // stored for them, and nothing to read ([`Inst::spread`]).
        let far = Lists::of(
            pts.iter().map(|p| {
                if p.len() <= SPREAD {
                    Vec::new()
                } else {
                    spread_sample(p, SPREAD)
                }
            }),
            (n, 0),
        );
        let disc = Arc::new(pts.iter().map(disc).collect());
        Inst {
            pts: Arc::new(pts),
            cand: Arc::new(cand),
            far: Arc::new(far),
            disc,
            up,
            kids,
            active,
            order,
        }
    }

    /// Indices into `pts[s]` of at most [`SPREAD`] well-spread candidates:
    /// all of them for a site with no more than that.
    #[inline]
    pub(super) fn spread(&self, s: usize) -> &[usize] {
        const ALL: [usize; SPREAD] = {
            let mut all = [0; SPREAD];
            let mut i = 0;
            while i < SPREAD {
                all[i] = i;
                i += 1;
            }
            all
        };
        let n = self.pts[s].len();
        if n <= SPREAD {
            &ALL[..n]
        } else {
            &self.far[s]
        }
    }

    /// The caller's number of site `s`.
    pub(super) fn caller(&self, s: usize) -> usize {
        self.order.get(s).copied().unwrap_or(s)
    }
}

impl Inst {
    /// The same sites with no precedence at all.
    pub(super) fn relaxed(&self) -> Inst {
        Inst {
            pts: Arc::clone(&self.pts),
            cand: Arc::clone(&self.cand),
            far: Arc::clone(&self.far),
            disc: Arc::clone(&self.disc),
            up: vec![None; self.up.len()],
            kids: Lists::grouped(self.kids.len(), std::iter::empty()),
            active: self.active.clone(),
            order: Vec::new(),
        }
    }
}

/// Centre of the candidates' box and the largest distance from it.
fn disc(pts: &[Point]) -> (Point, f64) {
    let (mut lo, mut hi) = (
        Point::new(f64::MAX, f64::MAX),
        Point::new(f64::MIN, f64::MIN),
    );
    for p in pts {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    let c = lo.add(hi).scale(0.5);
    let r = pts.iter().map(|p| dist(*p, c)).fold(0.0, f64::max);
    (c, r * (1.0 + 1e-12) + 1e-12)
}

/// Farthest-point sample of at most `k` candidates: indices into `pts`.
fn spread_sample(pts: &[Point], k: usize) -> Vec<usize> {
    if pts.len() <= k {
        return (0..pts.len()).collect();
    }
    let mut chosen = vec![0];
    let mut gap: Vec<f64> = pts.iter().map(|p| dist(*p, pts[0])).collect();
    while chosen.len() < k {
        let Some((far, _)) = gap.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)) else {
            break;
        };
        chosen.push(far);
        for (g, p) in gap.iter_mut().zip(pts) {
            *g = g.min(dist(*p, pts[far]));
        }
    }
    chosen
}

/// One list per site, stored flat: list `s` is `items[first[s]..first[s + 1]]`.
#[derive(Clone, Debug, Default)]
pub(super) struct Lists<T> {
    first: Vec<usize>,
    items: Vec<T>,
}

impl<T> Lists<T> {
    /// The lists in order; `(lists, items)`: room to make first.
    fn of<L: IntoIterator<Item = T>>(
        lists: impl Iterator<Item = L>,
        (n, total): (usize, usize),
    ) -> Lists<T> {
        let mut out = Lists::with_capacity(n, total);
        for l in lists {
            out.items.extend(l);
            out.first.push(out.items.len());
        }
        out
    }

    /// No lists yet, with room for `n` lists of `total` items in all.
    fn with_capacity(n: usize, total: usize) -> Lists<T> {
        let mut first = Vec::with_capacity(n + 1);
        first.push(0);
        Lists {
            first,
            items: Vec::with_capacity(total),
        }
    }

    /// `n` lists from (list, item) pairs, each list's items in the pairs'
    /// order (a counting sort).
    fn grouped(n: usize, pairs: impl Iterator<Item = (usize, T)> + Clone) -> Lists<T>
    where
        T: Copy + Default,
    {
        let mut first = vec![0; n + 1];
        for (l, _) in pairs.clone() {
            first[l + 1] += 1;
        }
        for l in 0..n {
            first[l + 1] += first[l];
        }
        let mut items = vec![T::default(); first[n]];
        let mut next = first.clone();
        for (l, x) in pairs {
            items[next[l]] = x;
            next[l] += 1;
        }
        Lists { first, items }
    }

    /// How many lists.
    pub(super) fn len(&self) -> usize {
        self.first.len() - 1
    }

    /// Every list's items, list after list.
    pub(super) fn items(&self) -> &[T] {
        &self.items
    }

    /// Where each list starts in [`Lists::items`], and the end last.
    pub(super) fn offsets(&self) -> &[usize] {
        &self.first
    }

    /// The lists in order.
    pub(super) fn iter(&self) -> impl Iterator<Item = &[T]> + '_ {
        (0..self.len()).map(|s| &self[s])
    }
}

impl<T> Index<usize> for Lists<T> {
    type Output = [T];
    #[inline]
    fn index(&self, s: usize) -> &[T] {
        &self.items[self.first[s]..self.first[s + 1]]
    }
}
