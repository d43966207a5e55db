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
//!    tour gets shorter: iterated local search; 10,000–30,000, none above
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
//!    lists built once, no kicks (and so no entry re-choice after the
//!    local search: the polish makes one first), the repaired tour polished
//!    whatever its length (falling back only if the polished one is still
//!    longer than the nearest neighbour), the sites renumbered in sheet
//!    order ([`spatial`]), the polish re-choosing only the entries whose
//!    neighbours changed, the entry re-choices in blocks of 8,192 sites
//!    on the threads ([`cluster::optimise_blocks`]), and the local
//!    searches screened on the threads first (the sites without a move
//!    skipped, `search/screen.rs`). A big sheet whose relaxed
//!    construction is no shorter than the one with precedence (plates
//!    with two holes) skips relax and repair: its search starts from the
//!    latter. Tour
//!    length against time: `cargo bench --bench tsp -- --effort`.
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
mod inst;
mod repair;
mod search;
mod sites;
mod spatial;

/// The bucket grid, also for the nearest-next order of loose items
/// (`plan/nearest.rs`).
#[allow(unused_imports)]
pub(crate) use grid::Grid;
pub use sites::Sites;

use crate::geom::Point;
use crate::par::Threads;
use inst::Inst;

/// Most candidates per site the exact entry re-choice and the Or-opt
/// re-choice look at (farthest-point sample; the final refinement sees all).
pub(crate) const SPREAD: usize = 16;

/// One contour to visit. The tool enters at one of `candidates` and, a closed
/// contour being cut all round, leaves at the same point. (The benches' and
/// tests' form of a site; the planner builds [`Sites`] directly.)
#[allow(dead_code)]
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
    /// The entry point of each visit (`Site::candidates` of the visit).
    pub points: Vec<Point>,
    /// Rapid length of the nearest-neighbour construction, mm.
    pub nn_length: f64,
    /// Rapid length of the returned tour from the origin, open path, mm.
    pub length: f64,
}

/// Euclidean distance without `hypot`'s overflow care (coordinates are
/// finite millimetres): the search spends most of its time here, and
/// `f64::hypot` is several times slower than a square root.
#[inline]
pub(super) fn dist(a: Point, b: Point) -> f64 {
    let (dx, dy) = (a.x - b.x, a.y - b.y);
    (dx * dx + dy * dy).sqrt()
}

/// Rapid length of `visits` from `origin`, open path.
#[cfg(test)]
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
#[allow(dead_code)]
pub fn order(sites: &[Site], origin: Point) -> Tour {
    order_with(sites, origin, None)
}

/// [`order`] with the amount of search given (None: [`Effort::for_sites`]),
/// for the benches' tour-length-against-time tables.
#[allow(dead_code)]
pub fn order_with(sites: &[Site], origin: Point, effort: Option<Effort>) -> Tour {
    order_sites(&Sites::of(sites), origin, effort, Threads::ONE)
}

/// [`order_with`] on sites stored flat, on up to `threads` threads (the
/// same tour with any number).
pub fn order_sites(sites: &Sites, origin: Point, effort: Option<Effort>, threads: Threads) -> Tour {
    let origin = if origin.is_finite() {
        origin
    } else {
        Point::default()
    };
    // Sheets of tens of thousands of contours: sites in sheet order
    // ([`spatial`]); the search's own numbers are mapped back in `visits_of`.
    let visitable =
        (0..sites.count()).filter(|&i| sites.candidates(i).iter().any(|p| p.is_finite()));
    let inst = if visitable.count() > LARGE {
        Inst::numbered(sites, spatial::order(sites))
    } else {
        Inst::numbered(sites, Vec::new())
    };
    let effort = effort.unwrap_or_else(|| Effort::for_sites(inst.active.len()));
    let visits_of = |seq: &[usize], at: &[usize]| -> Vec<(usize, usize)> {
        seq.iter()
            .map(|&s| (inst.caller(s), inst.cand[s][at[s]] as usize))
            .collect()
    };
    let points_of = |seq: &[usize], at: &[usize]| -> Vec<Point> {
        seq.iter().map(|&s| inst.pts[s][at[s]]).collect()
    };
    // What `path_length` gives for `visits_of(seq, at)` (the same points
    // summed in the same order), read from the instance in its own order:
    // on a sheet renumbered in sheet order, not a cache miss a visit.
    let length_of = |seq: &[usize], at: &[usize]| -> f64 {
        let mut here = origin;
        let mut len = 0.0;
        for &s in seq {
            let p = inst.pts[s][at[s]];
            len += dist(here, p);
            here = p;
        }
        len
    };
    // The baseline, nearest neighbour with precedence, is built on a
    // second thread while the free tour is made (and, on a small sheet,
    // searched). Relax and repair (see `repair`): optimise with precedence
    // dropped, make the order legal, polish with precedence.
    let empty = construct::grid(&inst);
    let (empty, empty_too) = (empty.clone(), empty);
    let free = inst.relaxed();
    let (free_searched, (seq, nn_at)) = if effort.short {
        let ((fseq, fat), baseline) = crate::par::join(
            threads,
            || construct::nearest_neighbour(&free, origin, empty_too),
            || construct::nearest_neighbour(&inst, origin, empty),
        );
        // A big sheet whose relaxed construction is no shorter than the
        // one with precedence gains nothing from dropping it: the search
        // with precedence starts from the latter straight away (below).
        // Plates with two holes each (benches/pipeline.rs's nest): the
        // free construction 2,989 m against 2,696, its search 2,872 m
        // and its polished repair 2,905, longer than the baseline, so
        // the search from the baseline ran after them anyway, to 2,435
        // m (benches/tsp.rs, twelfth pass).
        if length_of(&baseline.0, &baseline.1) <= length_of(&fseq, &fat) {
            (None, baseline)
        } else {
            // The neighbour lists by site centre, on the threads.
            let lists = search::Neighbours::of_centres(&free, threads);
            let found = search::improve(&free, origin, fseq, fat, lists, effort, threads);
            (Some(found), baseline)
        }
    } else {
        let (found, baseline) = crate::par::join(
            threads,
            || {
                let (fseq, fat) = construct::nearest_neighbour(&free, origin, empty_too);
                search::improve(
                    &free,
                    origin,
                    fseq,
                    fat,
                    Default::default(),
                    effort,
                    threads,
                )
            },
            || construct::nearest_neighbour(&inst, origin, empty),
        );
        (Some(found), baseline)
    };
    let nn_length = length_of(&seq, &nn_at);
    let polished = free_searched.and_then(|f| {
        repaired_and_polished(
            &inst,
            origin,
            (f.seq, f.at),
            (f.neigh, f.settled, f.layers),
            nn_length,
            effort,
            threads,
            &length_of,
        )
    });
    let (polished_seq, polished_at, length) = match polished {
        Some(p) => p,
        None => {
            let found = search::improve(
                &inst,
                origin,
                seq.clone(),
                nn_at.clone(),
                Default::default(),
                effort,
                threads,
            );
            let len = length_of(&found.seq, &found.at);
            (found.seq, found.at, len)
        }
    };
    // Every step only accepts gains; this guards against rounding only.
    let (seq, at, length) = if length > nn_length {
        (&seq, &nn_at, nn_length)
    } else {
        (&polished_seq, &polished_at, length)
    };
    let (visits, points) = crate::par::join(threads, || visits_of(seq, at), || points_of(seq, at));
    Tour {
        visits,
        points,
        nn_length,
        length,
    }
}

/// The free search's order made legal (the shorter of the two repairs)
/// and polished with precedence ([`order_sites`] step 2 and 5), or None
/// when the full search from the baseline is to run instead.
#[allow(clippy::too_many_arguments)]
fn repaired_and_polished(
    inst: &Inst,
    origin: Point,
    (fseq, at): (Vec<usize>, Vec<usize>),
    (neigh, settled, layers): (search::Neighbours, Vec<(usize, usize)>, cluster::Layers),
    nn_length: f64,
    effort: Effort,
    threads: Threads,
    length_of: &dyn Fn(&[usize], &[usize]) -> f64,
) -> Option<(Vec<usize>, Vec<usize>, f64)> {
    // The shorter repair, by the free search's entries: the two differ only
    // inside parts, and the polish re-chooses every entry anyway (an exact
    // re-choice for each was two of the eight passes over a 60k sheet).
    // (The two repairs on two threads on a big sheet, ~5 ms each on the
    // 25 MB nest: each reads the free order only.)
    let split = if effort.short { threads } else { Threads::ONE };
    let (deferred, pulled) = crate::par::join(
        split,
        || repair::defer_parents(inst, &fseq),
        || repair::pull_children(inst, &fseq),
    );
    let mut best: Option<(f64, Vec<usize>)> = None;
    for seq in [deferred, pulled] {
        let len = length_of(&seq, &at);
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
    let (len, s) = best?;
    if len > nn_length && !effort.short {
        return None;
    }
    let moved = repair::moved(inst, &fseq, &s);
    // The full schedule builds its lists anew (the free search's were
    // made before its last entry re-choice) and re-chooses every entry;
    // the short one only those whose neighbours the kicks, the repair or
    // the polish changed.
    let (neigh, settled) = if effort.short {
        (neigh, settled)
    } else {
        (Default::default(), Vec::new())
    };
    let (seq, at) = search::polish(
        inst, origin, s, at, neigh, settled, layers, &moved, effort, threads,
    );
    let len = length_of(&seq, &at);
    (len <= nn_length || !effort.short).then_some((seq, at, len))
}

#[cfg(test)]
mod tests;
