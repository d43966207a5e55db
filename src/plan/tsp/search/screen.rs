//! The screen of a local search's queue (issue 17): every queued site
//! looked at once, on the threads, before the search proper, which then
//! skips the sites the screen found no move around.
//!
//! Why: on a sheet's tour nearly every site a search looks at has no move
//! (the 25 MB nest: 1,234 gains in 140k sites looked at by the free
//! search, 377 in 137k by the polish), and looking, one site after the
//! other, is what the search spends its time on. On two threads the free
//! search's local search went from ~39 to ~30 ms and the polish's from
//! ~38 to ~26 (the screens ~22 ms each), the plan stage 283 -> 261 ms,
//! with the tours and the nests' programs unchanged, and one thread no
//! slower. A tour still being made is not screened (see [`Path::screen`]):
//! on the bench nests the free search's start gains at a third of its
//! sites, and there the screen was no faster and moved the tours by
//! 0.1-0.3 % (benches/tsp.rs, eighth pass).

use super::Path;

/// Fewest queued sites a thread screens (a look is ~0.3 us).
const SCREEN_CHUNK: usize = 4096;
/// Queued sites screened first, to tell whether the rest is worth it.
const SAMPLE: usize = 8192;
/// Screen on only if at most one sampled site in this many has a move.
const BUSY: usize = 8;

impl Path<'_> {
    /// Looks for a move around every queued site at once, on the threads,
    /// the path as it is, and marks those without one idle: the search
    /// skips them when their turn comes unless a move changed their
    /// neighbourhood meanwhile ([`Path::still`]). Not quite the search
    /// without the screen (a site skipped might have gained from a change
    /// further out), but the same with any number of threads: what the
    /// screen finds depends on the path alone. The don't-look bits of
    /// Bentley (1992) make the same bet: a site is looked at again only
    /// when the tour changes around it.
    ///
    /// The first [`SAMPLE`] queued sites are screened first: if more than
    /// one in [`BUSY`] has a move, the tour is still being made (a
    /// nearest-neighbour tour on the bench nests gains at a third of its
    /// sites), the screen's findings would go stale as fast as they are
    /// made, and the search runs unscreened, as it would without (the
    /// sample's cost aside).
    pub(super) fn screen(&mut self) {
        let n = self.inst.pts.len();
        self.idle.clear();
        self.stirred.clear();
        let (a, b) = self.queue.as_slices();
        let this = &*self;
        let site = |k: usize| if k < a.len() { a[k] } else { b[k - a.len()] };
        let look = |r: std::ops::Range<usize>| {
            crate::par::map_ranges(r.len(), this.threads, SCREEN_CHUNK, |q| {
                let mut units = Vec::new();
                (r.start + q.start..r.start + q.end)
                    .map(site)
                    .filter(|&s| this.find(s, &mut units).is_none())
                    .collect::<Vec<usize>>()
            })
        };
        let queued = a.len() + b.len();
        let sample = SAMPLE.min(queued);
        let mut idle = look(0..sample);
        let still: usize = idle.iter().map(Vec::len).sum();
        if (sample - still) * BUSY > sample {
            return;
        }
        idle.extend(look(sample..queued));
        self.idle.resize(n, false);
        for s in idle.into_iter().flatten() {
            self.idle[s] = true;
        }
        self.stirred.resize(n, false);
    }

    /// True if no move since the screen changed the tour neighbours of
    /// `s` or of a site in its neighbour list: what a look around `s`
    /// reads first, so the screen's finding still stands (nearly: Or-opt
    /// and Or-3opt also read the lists of the sites next to `s`).
    pub(super) fn still(&self, s: usize) -> bool {
        !self.stirred[s] && self.neigh[s].iter().all(|&c| !self.stirred[c as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::{Inst, Site};
    use super::super::Path;
    use crate::geom::Point;
    use crate::par::Threads;

    /// Sites scattered over a 1,000 x 600 mm sheet, one candidate each,
    /// by a fixed generator; every fifth a hole of the site after it.
    fn scattered(n: usize) -> Vec<Site> {
        let mut f = crate::test_rng::unit(0x2545_F491_4F6C_DD1D);
        (0..n)
            .map(|i| Site {
                candidates: vec![Point::new(f() * 1000.0, f() * 600.0)],
                parent: (i % 5 == 0 && i + 1 < n).then_some(i + 1),
            })
            .collect()
    }

    /// The path through `inst` in site order (legal: holes come first).
    fn path(inst: &Inst, threads: Threads) -> Path<'_> {
        let n = inst.pts.len();
        let mut p = Path::new(inst, Point::default(), (0..n).collect(), vec![0; n]);
        p.threads = threads;
        p.rebuild_neighbours();
        p
    }

    #[test]
    fn a_local_optimum_is_all_idle_and_left_as_it_is() {
        let sites = scattered(3000);
        let inst = Inst::new(&sites);
        let mut p = path(&inst, Threads::ONE);
        // A queue run empty is not quite an optimum (a site is looked at
        // again only when its own tour edges change): to a fixed point, a
        // whole pass over the sites with no move made.
        while (0..3000).fold(false, |moved, s| p.improve_site(s) | moved) {}
        let (seq, len) = (p.seq.clone(), p.len);
        p.screen = true;
        p.queue_all();
        p.screen();
        assert!(
            (0..3000).all(|s| p.idle[s]),
            "no site of an optimum has a move"
        );
        p.local_search();
        assert_eq!(p.seq, seq);
        assert_eq!(p.len, len);
    }

    #[test]
    fn moves_far_apart_are_all_made() {
        // Sites on a line, two pairs swapped far apart: the screen finds
        // both, and neither move disturbs the other.
        let mut order: Vec<usize> = (0..200).collect();
        order.swap(5, 6);
        order.swap(150, 151);
        let sites: Vec<Site> = order
            .iter()
            .map(|&x| Site {
                candidates: vec![Point::new(x as f64 + 1.0, 0.0)],
                parent: None,
            })
            .collect();
        let inst = Inst::new(&sites);
        let mut p = path(&inst, Threads::ONE);
        p.queue_all();
        p.screen();
        let idle = p.idle.iter().filter(|&&i| i).count();
        assert!(idle > 180, "{idle} sites idle");
        p.screen = true;
        p.local_search();
        assert!((p.len - 200.0).abs() < 1e-9, "{}", p.len);
        assert!((p.length() - p.len).abs() < 1e-9);
    }

    #[test]
    fn a_site_whose_neighbourhood_moved_is_looked_at() {
        let sites = scattered(500);
        let inst = Inst::new(&sites);
        let mut p = path(&inst, Threads::ONE);
        while (0..500).any(|s| p.improve_site(s)) {}
        p.queue_all();
        p.screen();
        let s = 7;
        assert!(p.still(s));
        let c = p.neigh[s][0] as usize;
        p.push(c);
        assert!(!p.still(s), "a neighbour's tour edges changed");
        let t = (0..500)
            .find(|&t| p.still(t) && !p.neigh[t].contains(&(s as u32)) && t != s)
            .expect("a site far away");
        p.push(s);
        assert!(p.still(t));
        assert!(!p.still(s));
    }

    #[test]
    fn the_same_search_on_one_and_on_two_threads() {
        // Enough sites for the screen to split (2 x SCREEN_CHUNK): a
        // searched tour, then every 500th site swapped with the next.
        let sites = scattered(12_000);
        let inst = Inst::new(&sites);
        let mut p = path(&inst, Threads::ONE);
        p.queue_all();
        p.local_search();
        let mut seq = p.seq.clone();
        for i in (0..seq.len() - 1).step_by(500) {
            seq.swap(i, i + 1);
        }
        let at = p.at.clone();
        let run = |threads: Threads| {
            let n = inst.pts.len();
            let mut p = Path::new(&inst, Point::default(), seq.clone(), at.clone());
            p.threads = threads;
            p.rebuild_neighbours();
            let before = p.len;
            p.queue_all();
            p.screen();
            let idle = p.idle.iter().filter(|&&i| i).count();
            assert!(idle > n / 2, "screened: {idle} idle of {n}");
            p.screen = true;
            p.local_search();
            assert!(p.len < before, "the swaps were undone");
            assert!((p.length() - p.len).abs() < 1e-6 * p.len);
            (p.seq, p.len)
        };
        assert_eq!(run(Threads::ONE), run(Threads::new(2)));
    }

    #[test]
    fn a_tour_still_being_made_is_not_screened() {
        // Sites in drawing order, scattered: most have a move.
        let sites = scattered(12_000);
        let inst = Inst::new(&sites);
        let mut p = path(&inst, Threads::new(2));
        p.queue_all();
        p.screen();
        assert!(p.idle.is_empty() && p.stirred.is_empty());
        p.screen = true;
        p.local_search();
        assert!((p.length() - p.len).abs() < 1e-6 * p.len);
    }
}
