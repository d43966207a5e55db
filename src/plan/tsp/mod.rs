//! Rapid-path optimisation of the contour-at-a-time order (issue 4 §3).
//!
//! The problem: visit every contour once, entering at one of its candidate
//! points (vertices) and leaving at the same point (a closed contour is cut
//! all round), starting from the machine origin, with no return; every
//! contour must come before the contour around it (a hole before its part's
//! outer contour, paper 000 "Sequence", paper 001 §3). That is a generalised
//! TSP (one point per cluster) with precedence constraints, open path.
//!
//! Method (why each step; measured figures in `benches/tsp.rs`):
//! 1. [`construct`]: nearest neighbour over all candidate points of the sites
//!    whose children are done: the plain construction, the baseline
//!    reported as [`Tour::nn_length`].
//! 2. Relax and repair ([`repair`]): the same search is first run with
//!    precedence dropped, then the order is made legal (outer contours
//!    deferred after their holes, or holes pulled before their outer; the
//!    shorter kept). Holes lie inside their part, so this costs almost
//!    nothing (≤ 0.1 % on LKH's own tours), whereas a search checking
//!    precedence on every move stalled 5–10 % above LKH: no long reversal
//!    is legal once a part with holes lies inside it.
//! 3. [`search`]: local search with neighbour lists (10 nearest sites from a
//!    grid) and a work queue ("don't-look bits", Bentley 1992): 2-opt,
//!    2-opt over whole families (holes + outer kept in order), Or-opt
//!    (1–3 sites or a whole family, either way round, re-choosing the entry
//!    of a single moved site), Or-3opt (segment exchange, any lengths), then
//!    a fixed number of kicks (a local double bridge, kept only if the
//!    tour gets shorter: iterated local search; 10,000–30,000, 3,000 above
//!    20k sites). With precedence, every move is checked.
//! 4. [`cluster`]: for the fixed sequence, the entry points are re-chosen
//!    exactly by a shortest path through the layered candidate graph (the
//!    GTSP "cluster optimisation" of Fischetti, Salazar, Toth 1997), on at
//!    most [`SPREAD`] well-spread candidates per site plus the current one,
//!    then refined over all candidates one site at a time; between rounds
//!    of 3.
//! 5. The shorter repair gets a last local search with precedence, started
//!    at the sites the repair moved. If it is longer than the
//!    nearest-neighbour tour (precedence between far-apart sites: not a
//!    nest) the full search runs from the latter instead.
//! 6. Above [`LARGE`] sites (sheets of tens of thousands of contours) the
//!    short schedule ([`Effort`]): one local search round, the neighbour
//!    lists built once, 3,000 kicks, and the repaired tour polished
//!    whatever its length (falling back only if the polished one is still
//!    longer than the nearest neighbour). Tour length against time:
//!    `cargo bench --bench tsp -- --effort`.
//!
//! A space-filling-curve start (Hilbert order of the sites) instead of the
//! nearest neighbour was tried: 2–4 % longer tours after the same search on
//! the random nests, for 70 ms saved at 60k contours; not taken.
//!
//! The result is never longer than the nearest-neighbour tour (checked at
//! the end). Deterministic: a fixed-seed generator, a fixed amount of work
//! (no clocks, which wasm lacks).

mod cluster;
mod construct;
mod grid;
mod repair;
mod search;

use crate::geom::Point;

/// Most candidates per site the exact entry re-choice and the Or-opt
/// re-choice look at (farthest-point sample; the final refinement sees all).
pub(crate) const SPREAD: usize = 16;

/// One contour to visit. The tool enters at one of `candidates` and, a closed
/// contour being cut all round, leaves at the same point.
#[derive(Clone, Debug, Default)]
pub struct Site {
    /// Possible entry points. Non-finite points are ignored; a site with no
    /// finite candidate is not visited (see [`order`]).
    pub candidates: Vec<Point>,
    /// The site that must be visited AFTER this one (a hole's outer contour,
    /// an island's hole). Out-of-range or self references are ignored; a
    /// cycle is broken (one of its links ignored).
    pub parent: Option<usize>,
}

/// A visiting order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tour {
    /// (site, candidate index) in order; every visitable site exactly once.
    pub visits: Vec<(usize, usize)>,
    /// Rapid length of the nearest-neighbour construction, mm.
    pub nn_length: f64,
    /// Rapid length of the returned tour from the origin, open path, mm.
    pub length: f64,
}

/// The cleaned instance every step works on.
pub(super) struct Inst {
    /// Finite candidates of each site: (index in `Site::candidates`, point).
    pub pts: Vec<Vec<(usize, Point)>>,
    /// Indices into `pts[s]` of at most [`SPREAD`] well-spread candidates.
    pub spread: Vec<Vec<usize>>,
    /// A disc holding every candidate of each site: (centre, radius).
    pub disc: Vec<(Point, f64)>,
    /// Nearest visitable proper ancestor: must come after the site.
    pub up: Vec<Option<usize>>,
    /// Visitable sites whose `up` is this site.
    pub kids: Vec<Vec<usize>>,
    /// Visitable sites (with at least one finite candidate), ascending.
    pub active: Vec<usize>,
}

impl Inst {
    /// Cleans `sites`: drops non-finite candidates, ignores bad parent
    /// links, breaks cycles, and links each visitable site to its nearest
    /// visitable ancestor — so a hole that vanished (no candidates) still
    /// keeps its islands before the part's outer contour.
    pub(super) fn new(sites: &[Site]) -> Inst {
        let n = sites.len();
        let pts: Vec<Vec<(usize, Point)>> = sites
            .iter()
            .map(|s| {
                s.candidates
                    .iter()
                    .copied()
                    .enumerate()
                    .filter(|(_, p)| p.is_finite())
                    .collect()
            })
            .collect();
        let visitable: Vec<bool> = pts.iter().map(|p| !p.is_empty()).collect();
        let mut par: Vec<Option<usize>> = sites
            .iter()
            .enumerate()
            .map(|(i, s)| s.parent.filter(|&p| p < n && p != i))
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
        let mut kids = vec![Vec::new(); n];
        for &s in &active {
            if let Some(u) = up[s] {
                kids[u].push(s);
            }
        }
        let spread = pts.iter().map(|p| spread_sample(p, SPREAD)).collect();
        let disc = pts.iter().map(|p| disc(p)).collect();
        Inst {
            pts,
            spread,
            disc,
            up,
            kids,
            active,
        }
    }
}

/// Euclidean distance without `hypot`'s overflow care (coordinates are
/// finite millimetres): the search spends most of its time here, and
/// `f64::hypot` is several times slower than a square root.
#[inline]
pub(super) fn dist(a: Point, b: Point) -> f64 {
    let (dx, dy) = (a.x - b.x, a.y - b.y);
    (dx * dx + dy * dy).sqrt()
}

impl Inst {
    /// The same sites with no precedence at all.
    pub(super) fn relaxed(&self) -> Inst {
        Inst {
            pts: self.pts.clone(),
            spread: self.spread.clone(),
            disc: self.disc.clone(),
            up: vec![None; self.up.len()],
            kids: vec![Vec::new(); self.kids.len()],
            active: self.active.clone(),
        }
    }
}

/// Centre of the candidates' box and the largest distance from it.
fn disc(pts: &[(usize, Point)]) -> (Point, f64) {
    let (mut lo, mut hi) = (
        Point::new(f64::MAX, f64::MAX),
        Point::new(f64::MIN, f64::MIN),
    );
    for (_, p) in pts {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    let c = lo.add(hi).scale(0.5);
    let r = pts.iter().map(|(_, p)| dist(*p, c)).fold(0.0, f64::max);
    (c, r * (1.0 + 1e-12) + 1e-12)
}

/// Farthest-point sample of at most `k` candidates: indices into `pts`.
fn spread_sample(pts: &[(usize, Point)], k: usize) -> Vec<usize> {
    if pts.len() <= k {
        return (0..pts.len()).collect();
    }
    let mut chosen = vec![0];
    let mut gap: Vec<f64> = pts.iter().map(|(_, p)| dist(*p, pts[0].1)).collect();
    while chosen.len() < k {
        let Some((far, _)) = gap.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)) else {
            break;
        };
        chosen.push(far);
        for (g, (_, p)) in gap.iter_mut().zip(pts) {
            *g = g.min(dist(*p, pts[far].1));
        }
    }
    chosen
}

/// Rapid length of `visits` from `origin`, open path.
pub(super) fn path_length(sites: &[Site], origin: Point, visits: &[(usize, usize)]) -> f64 {
    let mut at = origin;
    let mut len = 0.0;
    for &(s, c) in visits {
        if let Some(p) = sites.get(s).and_then(|s| s.candidates.get(c)) {
            len += dist(at, *p);
            at = *p;
        }
    }
    len
}

/// How much search a tour gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Effort {
    /// Kicks of the iterated local search ([`search`]).
    pub kicks: usize,
    /// The short schedule of sheets with tens of thousands of contours: one
    /// local search round, the neighbour lists built once, the repaired
    /// tour always polished (see [`order`]).
    pub short: bool,
}

/// Above this many visitable sites a tour gets the short schedule (the
/// full one is what the LKH-3 comparisons measure, up to 5,000 parts =
/// 15k sites).
pub const LARGE: usize = 20_000;

impl Effort {
    /// The schedule [`order`] uses for `n` visitable sites.
    pub fn for_sites(n: usize) -> Effort {
        Effort {
            kicks: search::kick_count(n),
            short: n > LARGE,
        }
    }
}

/// A short rapid path through `sites` from `origin`, every site before its
/// parent. Sites without a finite candidate are left out of the tour (their
/// children still come before their visitable ancestors). A non-finite
/// origin is taken as (0, 0).
pub fn order(sites: &[Site], origin: Point) -> Tour {
    order_with(sites, origin, None)
}

/// [`order`] with the amount of search given (None: [`Effort::for_sites`]),
/// for the benches' tour-length-against-time tables.
pub fn order_with(sites: &[Site], origin: Point, effort: Option<Effort>) -> Tour {
    let origin = if origin.is_finite() {
        origin
    } else {
        Point::default()
    };
    let inst = Inst::new(sites);
    let effort = effort.unwrap_or_else(|| Effort::for_sites(inst.active.len()));
    let visits_of = |seq: &[usize], at: &[usize]| -> Vec<(usize, usize)> {
        seq.iter().map(|&s| (s, inst.pts[s][at[s]].0)).collect()
    };
    // The baseline: nearest neighbour with precedence.
    let (seq, nn_at) = construct::nearest_neighbour(&inst, origin);
    let nn_visits = visits_of(&seq, &nn_at);
    let nn_length = path_length(sites, origin, &nn_visits);
    // Relax and repair (see `repair`): optimise with precedence dropped,
    // make the order legal, polish with precedence.
    let free = inst.relaxed();
    let (fseq, fat) = construct::nearest_neighbour(&free, origin);
    let (fseq, at, neigh) = search::improve(&free, origin, fseq, fat, effort);
    // The shorter repair, by the free search's entries: the two differ only
    // inside parts, and the polish re-chooses every entry anyway (an exact
    // re-choice for each was two of the eight passes over a 60k sheet).
    let mut best: Option<(f64, Vec<usize>)> = None;
    for seq in [
        repair::defer_parents(&inst, &fseq),
        repair::pull_children(&inst, &fseq),
    ] {
        let len = path_length(sites, origin, &visits_of(&seq, &at));
        if best.as_ref().is_none_or(|(l, _)| len < *l) {
            best = Some((len, seq));
        }
    }
    // Then a local search with precedence from the repaired order, started
    // only at the sites whose place the repair changed (the rest is the
    // free search's local optimum already) or, if that is longer than the
    // nearest-neighbour tour (precedence between far-apart sites, not a
    // nest), the full search from the latter. The short schedule polishes
    // the repaired order whatever its length and falls back only if the
    // polished one is still longer: on the 25 MB nest (plates with one
    // hole in the middle) the free tour runs along the plates' corners
    // and back along their holes, its repair is 1.8 × the
    // nearest-neighbour tour, and Or-opt moving each hole next to its
    // plate brings it to the free tour's length in a tenth of the time of
    // a full search.
    let mut polished = None;
    if let Some((len, s)) = best {
        if len <= nn_length || effort.short {
            let moved = repair::moved(&inst, &fseq, &s);
            // The full schedule builds its lists anew (the free search's
            // were made before its last entry re-choice).
            let neigh = if effort.short { neigh } else { Vec::new() };
            let (seq, at) = search::polish(&inst, origin, s, at, neigh, &moved);
            let len = path_length(sites, origin, &visits_of(&seq, &at));
            if len <= nn_length || !effort.short {
                polished = Some((seq, at));
            }
        }
    }
    let (seq, at) = match polished {
        Some(p) => p,
        None => {
            let (seq, at, _) = search::improve(&inst, origin, seq, nn_at, effort);
            (seq, at)
        }
    };
    let visits = visits_of(&seq, &at);
    let length = path_length(sites, origin, &visits);
    // Every step only accepts gains; this guards against rounding only.
    if length > nn_length {
        return Tour {
            visits: nn_visits,
            nn_length,
            length: nn_length,
        };
    }
    Tour {
        visits,
        nn_length,
        length,
    }
}

#[cfg(test)]
mod tests;
