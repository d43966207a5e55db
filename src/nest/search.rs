//! The first nest and its improvement within the time budget.
//!
//! First nest: copies by decreasing area (the usual first-fit-decreasing
//! order of constructive nesting), each placed by [`super::place`].
//! Improvement: a local search over the order in which copies are placed
//! and the turn each is held to (the sequence-based search of Gomes &
//! Oliveira, EJOR 2002, and Burke et al., Operations Research 2006: swap
//! or move one copy in the sequence, or hold it to one turn or free it,
//! decode again with the same placer, keep the change when the nest is no
//! worse; ties are broken by Σ (right edge)², so plateaus of equal length
//! are walked towards nests packed to the left).
//!
//! Then, once the sequence search stalls ([`SEQUENCE_STALL`] evaluations
//! without a better nest, [`sequence_most`] in all, or the placer's work
//! reaches [`SEQUENCE_WORK`]), the best
//! nest is shortened by overlap minimisation ([`super::separate`]:
//! sparrow's exploration and compression, Gardeyn & Wauters, EJOR 2025):
//! cut a slice from the strip, let the copies overlap, separate them by
//! guided local search on a pole-based overlap proxy, keep the shorter
//! nest when the exact test says nothing overlaps (figures: the table at
//! the top of scripts/bench-nest.sh). The switch is on evaluations, not on
//! the clock, so a run stopped at evaluation E is the run given E (the
//! page's Stop replays to it). A share of the clock measured about the
//! same (10 % of it for the sequence search: 0.961 of sparrow's density
//! against 0.950 at 3 % and 0.955 at 30 %, 4 instances × 3 seeds at 8 s)
//! but broke that replay.
//!
//! Measured and dropped: shortening the strip by ruin and recreate (with a
//! repair that never overlaps) gained nothing on the 7 instances at 10 s,
//! and a separation by guided local search with box-intersection
//! penalties did not converge (the penetration-depth proxy is what it
//! needs, and snapping to exact contacts, [`super::separate::sample`]).
//! sparrow's disruption of a failed separation (two large copies swapped)
//! measured no better than trying again from the failed layout at 8 s (3
//! seeds × 4 instances: 0.949 of sparrow's density either way); at the
//! fixed counts of a 60 s run, with sparrow's pool of failed layouts to
//! disrupt, it is what frees the stalled seeds ([`super::separate`]).
//!
//! Every choice comes from one generator seeded by the settings, so a run
//! with the same seed and number of evaluations is the same nest.

use super::assemble::assemble;
use super::collide::Shape;
use super::decode::{better, decode, decode_until, sheet_room, Decoded, Item};
use super::place::Variant;
use super::rng::SplitMix;
use super::shape::{collision_polygon, room_polygon};
use super::{separate, Nest, NestJob, Placement, Sheets, Unplaced};

/// Evaluations without a better nest before the current order is kicked.
const KICK_AFTER: u64 = 1000;
/// Random swaps of a kick.
const KICK_SWAPS: usize = 4;
/// The sequence search ends after this many evaluations without a better
/// nest, or [`sequence_most`] in all; the rest of the budget separates.
const SEQUENCE_STALL: u64 = KICK_AFTER;

/// The first nest reports its progress every this many copies.
const FIRST_REPORT: u64 = 8;

/// The placer's work ([`super::place::Bin::work`]) the sequence search
/// may spend in all: about 6 s of one core on this machine (1.0–1.6 ×
/// 10⁻⁸ s per unit on the 7 ESICUP instances). The decodes per second
/// vary twentyfold between instances (fu's 12 copies against shapes0's
/// 43 of up to 13 vertices): counted in decodes, the search took 1 s of
/// fu's 60 and 17 s of shapes0's, where its last gain came by 300. A
/// tenth of the clock measured best (see the top of this file).
const SEQUENCE_WORK: u64 = 500_000_000;

/// The sequence search's evaluations for `n` copies: a decode costs about
/// n², so this is about the same time whatever the job (about 1 s for
/// the 25 copies of jakobs1 on this machine).
fn sequence_most(n: usize) -> u64 {
    (2_000_000 / (n * n).max(1) as u64).clamp(100, 5_000)
}

/// How the nest stands, for a progress display.
#[derive(Clone, Debug, PartialEq)]
pub struct Progress {
    /// Nests tried so far.
    pub evaluations: u64,
    /// Sheets used by the best nest.
    pub sheets: usize,
    /// Length used on its last sheet (or of the strip), mm.
    pub length: f64,
    /// Copies it could not place.
    pub unplaced: usize,
    /// Seconds since the start.
    pub elapsed_s: f64,
    /// The best nest's placements (drawn live by the page).
    pub best: Vec<Placement>,
}

pub(super) fn run(
    job: &NestJob,
    clock: &dyn Fn() -> f64,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Nest {
    let start = clock();
    let s = &job.settings;
    let grow = s.spacing / 2.0;
    let eps = s.tolerance * 1e-3;
    let mut unplaced = Vec::new();
    let Some(sheet) = sheet_room(job) else {
        // The margin leaves no room on the remnant: nothing can go on it.
        let unplaced = job
            .parts
            .iter()
            .map(|p| Unplaced {
                part: p.name.clone(),
                copies: p.quantity,
                reason: format!("the sheet has no room inside its margin of {} mm", s.margin),
            })
            .collect();
        return Nest {
            placements: Vec::new(),
            sheets: Vec::new(),
            unplaced,
            strip_length: None,
            density: 0.0,
            evaluations: 0,
        };
    };
    let (width, height) = job.sheets.size(0);
    let mut items = Vec::new();
    for (pi, p) in job.parts.iter().enumerate() {
        let out = |reason: String| Unplaced {
            part: p.name.clone(),
            copies: p.quantity,
            reason,
        };
        if p.quantity == 0 {
            unplaced.push(out("quantity 0: left out".into()));
            continue;
        }
        let Some(poly) = collision_polygon(&p.outer, grow, s.tolerance) else {
            unplaced.push(out("its outline encloses no area".into()));
            continue;
        };
        let mirrors: &[bool] = if p.mirror { &[false, true] } else { &[false] };
        let rooms: Vec<_> = p
            .holes
            .iter()
            .filter_map(|h| room_polygon(h, grow, s.tolerance))
            .collect();
        let variants: Vec<Variant> = mirrors
            .iter()
            .flat_map(|&m| {
                p.rotations
                    .angles_for(&p.outer, m)
                    .into_iter()
                    .map(move |a| (a, m))
            })
            .map(|(rotation, mirror)| Variant {
                rotation,
                mirror,
                shape: Shape::with_core(poly.placed(rotation, mirror, Default::default())),
                holes: rooms
                    .iter()
                    .map(|r| Shape::new(r.placed(rotation, mirror, Default::default())))
                    .collect(),
            })
            .collect();
        if !variants.iter().any(|v| sheet.fits(v)) {
            let room = match (&job.sheets, width) {
                (Sheets::Mixed(_), _) => "every sheet size".to_string(),
                (Sheets::Remnant { .. }, _) => {
                    format!(
                        "the remnant sheet (its box {:.1} × {height:.1} mm)",
                        width.unwrap_or(0.0)
                    )
                }
                (_, Some(w)) => format!("the sheet {w} × {height} mm"),
                (_, None) => format!("the strip {height} mm high"),
            };
            unplaced.push(out(format!(
                "larger than {room} at every allowed rotation, with margin {} mm and spacing {} mm",
                s.margin, s.spacing
            )));
            continue;
        }
        items.push(Item { part: pi, variants });
    }
    // Copies by decreasing area of their collision polygon.
    let mut order: Vec<usize> = items
        .iter()
        .enumerate()
        .flat_map(|(i, it)| std::iter::repeat_n(i, job.parts[it.part].quantity))
        .collect();
    let area = |i: usize| items[i].variants[0].shape.poly.area();
    order.sort_by(|&a, &b| area(b).total_cmp(&area(a)).then(a.cmp(&b)));
    // Each copy may be held to one turn (None: the placer chooses).
    let order: Vec<(usize, Option<usize>)> = order.into_iter().map(|i| (i, None)).collect();
    let report_as = |items: &[Item], d: &Decoded, evaluations: u64| Progress {
        evaluations,
        sheets: d.cost.1,
        length: d.cost.2,
        unplaced: d.unplaced.len() + d.stopped.len(),
        elapsed_s: clock() - start,
        best: super::live::placements(items, d, job.parts.len()),
    };
    let report = |d: &Decoded, evaluations: u64| report_as(&items, d, evaluations);
    // The first nest counts one evaluation per copy and honours the
    // budget and Stop between copies (a 200-copy sheet's first nest takes
    // seconds): cut short, it is the nest of the copies placed so far, the
    // others reported. `--time 0` asks for this nest whole.
    let mut go_on = true;
    let mut best = decode_until(&items, &order, &sheet, eps, &mut |k, partial| {
        let k = k as u64;
        if (s.time_s > 0.0 && clock() - start >= s.time_s)
            || s.max_evaluations.is_some_and(|m| k >= m)
        {
            return false;
        }
        if k.is_multiple_of(FIRST_REPORT) {
            go_on = progress(report(&partial(), k));
        }
        go_on
    });
    let mut evaluations = (order.len() - best.stopped.len()) as u64;
    let mut work = best.work;
    if best.stopped.is_empty() {
        go_on = progress(report(&best, evaluations));
    }
    let mut rng = SplitMix(s.seed);
    // Time and evaluations left. The phases switch on evaluations only,
    // never on the clock, so that a run stopped at evaluation E is the
    // same nest as a run given E evaluations (the page's Stop replays).
    let more = |evaluations: u64| {
        clock() - start < s.time_s && s.max_evaluations.is_none_or(|m| evaluations < m)
    };
    // The whole budget: the order of placing and the turns held.
    let distinct = order.windows(2).any(|w| w[0].0 != w[1].0);
    let mut cur = (order.clone(), best.cost, best.gravity);
    let n = order.len();
    let turns = items.iter().any(|it| it.variants.len() > 1);
    let mut last_gain = evaluations;
    let mut last_better = evaluations;
    while go_on
        && n > 1
        && (distinct || turns)
        && more(evaluations)
        && evaluations - last_better <= SEQUENCE_STALL
        && evaluations < sequence_most(n)
        && work < SEQUENCE_WORK
    {
        let mut o = cur.0.clone();
        // Long without a better nest: kick the current order by a few
        // random swaps and take it whatever it costs (iterated local
        // search, Lourenço, Martin & Stützle 2003).
        let kick = evaluations - last_gain > KICK_AFTER;
        if kick {
            last_gain = evaluations;
            for _ in 0..KICK_SWAPS {
                let (i, j) = (rng.below(n), rng.below(n));
                o.swap(i, j);
            }
            let d = decode(&items, &o, &sheet, eps);
            evaluations += 1;
            work += d.work;
            cur = (o, d.cost, d.gravity);
            continue;
        }
        let (i, j) = (rng.below(n), rng.below(n));
        match rng.below(3) {
            // Hold one copy to a turn, or let the placer choose again (the
            // orientation in the genome, as Gomes & Oliveira 2002 do).
            0 if turns => {
                let k = items[o[i].0].variants.len();
                let pick = rng.below(k + 1);
                o[i].1 = (pick < k).then_some(pick);
            }
            _ if o[i].0 == o[j].0 => continue,
            1 => o.swap(i, j),
            _ => {
                let x = o.remove(i);
                o.insert(j, x);
            }
        }
        let d = decode(&items, &o, &sheet, eps);
        evaluations += 1;
        work += d.work;
        if better(d.cost, cur.1, eps) || (!better(cur.1, d.cost, eps) && d.gravity <= cur.2) {
            cur = (o, d.cost, d.gravity);
            if better(d.cost, best.cost, eps) {
                last_gain = evaluations;
                last_better = evaluations;
                best = d;
                go_on = progress(report(&best, evaluations));
                continue;
            }
        }
        if evaluations.is_multiple_of(64) {
            go_on = progress(report(&best, evaluations));
        }
    }
    // The rest of the budget: sparrow's exploration and compression on
    // the best nest (separate/). Its moves count as evaluations.
    if go_on && more(evaluations) {
        let state = std::cell::RefCell::new((evaluations, go_on, report(&best, evaluations)));
        let progress = std::cell::RefCell::new(progress);
        // A stop asked at evaluation k takes effect after move k, as a
        // replay given k evaluations stops there.
        let mut budget = || {
            let mut st = state.borrow_mut();
            if !st.1 || !more(st.0) {
                return false;
            }
            st.0 += 1;
            if st.0 % 64 == 0 {
                let mut p = st.2.clone();
                p.evaluations = st.0;
                p.elapsed_s = clock() - start;
                st.1 = (progress.borrow_mut())(p);
            }
            true
        };
        let mut found = |d: &Decoded, items: &[Item]| {
            let mut st = state.borrow_mut();
            st.2 = report_as(items, d, st.0);
            st.1 = (progress.borrow_mut())(st.2.clone());
            st.1
        };
        // Parts that may take any angle turn freely in the separation.
        let free: Vec<bool> = items
            .iter()
            .map(|it| job.parts[it.part].rotations == super::Rotations::Free)
            .collect();
        let (b, turned) = separate::improve(
            &items,
            &free,
            best,
            sheet.origin_x,
            eps,
            &mut rng,
            &mut budget,
            &mut found,
        );
        best = b;
        evaluations = state.borrow().0;
        return assemble(job, &turned, best, unplaced, evaluations);
    }
    assemble(job, &items, best, unplaced, evaluations)
}
