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
//! are walked towards nests packed to the left). A change at position k
//! leaves the copies before k placed as they were: the changed order is
//! decoded from where the current one stood after them
//! ([`super::decode::decode_after`]; the same nest, 0.72–0.95 of the CPU
//! time of the phase, scripts/bench-nest.sh).
//!
//! Then, once the sequence search stalls ([`SEQUENCE_STALL`] evaluations
//! without a better nest, [`sequence_most`] in all, or the placer's work
//! reaches its share of the budget, [`sequence_work`]), the best
//! nest is shortened by overlap minimisation ([`super::separate`]:
//! sparrow's exploration and compression, Gardeyn & Wauters, EJOR 2025):
//! cut a slice from the strip, let the copies overlap, separate them by
//! guided local search on a pole-based overlap proxy, keep the shorter
//! nest when the exact test says nothing overlaps (figures: the table at
//! the top of scripts/bench-nest.sh). The switch is on evaluations, not on
//! the clock, so a run stopped at evaluation E is the run given E (the
//! page's Stop replays to it, on a longer clock). The sequence search's
//! work is a share of the operator's budget ([`super::NestSettings::budget`],
//! which the replay keeps; [`sequence_work`]). A share of the clock
//! measured 10 % best on ESICUP (0.961 of sparrow's density against 0.950
//! at 3 % and 0.955 at 30 %, 4 instances × 3 seeds at 8 s).
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
//!
//! A [`Search`] can pause at an evaluation count and go on later, or adopt
//! another search's better nest meanwhile ([`super::team`]: several
//! searches exchanging their best). A pause changes nothing: paused and
//! resumed without adopting, a search is the same run as without pauses.

use std::cell::RefCell;

use super::assemble::assemble;
use super::best::{rebuild, Best};
use super::collide::Shape;
use super::decode::{
    better, decode_after, decode_until, sheet_room, Decoded, Item, Order, SheetRoom, Trail,
};
use super::place::Variant;
use super::rng::SplitMix;
use super::separate::Improver;
use super::shape::room_polygon;
use super::simplify::nesting_polygon;
use super::{Nest, NestJob, Placement, Sheets, Unplaced};
use crate::text;
use crate::warning::{dec, Text};

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
/// may spend with a budget of [`SEQUENCE_FULL_S`] or more: about 6 s of
/// one core on this machine (1.3 × 10⁻⁸ s
/// a unit, 0.64–1.32 of that on every ESICUP and real-part instance of
/// scripts/bench-nest.sh: the exact tests are counted by their vertices,
/// [`super::place`]). The decodes per second
/// vary twentyfold between instances (fu's 12 copies against shapes0's
/// 43 of up to 13 vertices): counted in decodes, the search took 1 s of
/// fu's 60 and 17 s of shapes0's, where its last gain came by 300. A
/// tenth of the clock measured best (see the top of this file).
const SEQUENCE_WORK: u64 = 500_000_000;
/// The budget, s, from which the sequence search gets all of
/// [`SEQUENCE_WORK`]; a shorter one gets its share
/// ([`sequence_work`]).
const SEQUENCE_FULL_S: f64 = 30.0;

/// The placer's work the sequence search may spend within a budget of
/// `budget_s` s: about a fifth of it, at most [`SEQUENCE_WORK`] (from
/// [`SEQUENCE_FULL_S`]). Sized from the operator's budget, never the
/// clock, so that a replay with more time is the same run. At 10 s on the
/// real-part instances a fifth measured +0.25 points of density over a
/// tenth, and a tenth +0.16 over all of [`SEQUENCE_WORK`] (seeds 1–3);
/// at 30 s a tenth measured −0.04 (scripts/bench-nest.sh).
fn sequence_work(budget_s: f64) -> u64 {
    (SEQUENCE_WORK as f64 * (budget_s / SEQUENCE_FULL_S).clamp(0.0, 1.0)) as u64
}

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
    /// The share of all copies' area it left out, billionths (0: all placed).
    pub lost: usize,
    /// The parts of the copies it left out: found no room, and never
    /// reached by the first nest (budget, Stop); an entry a copy.
    pub left_out: (Vec<usize>, Vec<usize>),
}

impl Progress {
    /// The best nest reported, as another search (or a page's worker) adopts it.
    pub fn as_best(&self) -> Best {
        Best::from_placements(
            &self.best,
            (self.lost, self.sheets, self.length),
            self.left_out.clone(),
        )
    }
}

/// One search of a job: the first nest, the sequence search, then the
/// separation, run in slices ([`Search::run`]) that a caller may
/// interleave with [`Search::adopt`].
pub struct Search {
    job: NestJob,
    /// None when the margin leaves no room on the remnant.
    sheet: Option<SheetRoom>,
    /// The parts made ready for placing (the decoder's).
    items: Vec<Item>,
    /// Every copy, by decreasing area, none held to a turn.
    order: Order,
    unplaced: Vec<Unplaced>,
    eps: f64,
    start: Option<f64>,
    evaluations: u64,
    work: u64,
    rng: SplitMix,
    go_on: bool,
    phase: Phase,
    /// The last progress reported (the separation repeats it).
    report: Option<Progress>,
}

/// Where a search stands.
enum Phase {
    /// Nothing placed yet.
    First,
    /// The order search; `best` refers to `items`, or to the items that
    /// came with it when it was adopted.
    Sequence {
        best: Decoded,
        adopted: Option<Vec<Item>>,
        /// The current order, decoded: a change at position k is decoded
        /// from where it stood after k ([`decode_after`]).
        cur: Box<Trail>,
        last_gain: u64,
        last_better: u64,
    },
    /// The separation ([`super::separate`]).
    Separate(Box<Improver>),
    /// Nothing more to try (or the budget spent): the best and its items.
    Done(Decoded, Option<Vec<Item>>),
    /// Between two phases.
    Moving,
}

impl Search {
    /// A search of `job` (checked by [`super::nest`]'s rules first), its
    /// choices seeded by `seed`.
    pub fn new(job: &NestJob, seed: u64) -> Result<Search, super::NestError> {
        super::check(job)?;
        let job = job.clone();
        let s = &job.settings;
        let eps = s.touch();
        let mut unplaced = Vec::new();
        let sheet = sheet_room(&job);
        let mut items = Vec::new();
        if let Some(sheet) = &sheet {
            items = ready(&job, sheet, &mut unplaced);
        } else {
            // The margin leaves no room on the remnant: nothing can go on it.
            unplaced = job
                .parts
                .iter()
                .map(|p| Unplaced {
                    part: p.name.clone(),
                    copies: p.quantity,
                    reason: text!("the sheet has no room inside its margin of {} mm", s.margin;
                                  "a chapa não tem espaço dentro da margem de {} mm", dec(s.margin)),
                })
                .collect();
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
        let order: Order = order.into_iter().map(|i| (i, None)).collect();
        Ok(Search {
            sheet,
            items,
            order,
            unplaced,
            eps,
            start: None,
            evaluations: 0,
            work: 0,
            rng: SplitMix(seed),
            go_on: true,
            phase: Phase::First,
            report: None,
            job,
        })
    }

    /// Evaluations made so far.
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    /// The best decoded nest and its items (None before the first nest).
    fn best_decoded(&self) -> Option<(&Decoded, &[Item])> {
        match &self.phase {
            Phase::First | Phase::Moving => None,
            Phase::Sequence { best, adopted, .. } | Phase::Done(best, adopted) => {
                Some((best, adopted.as_deref().unwrap_or(&self.items)))
            }
            Phase::Separate(im) => Some(im.best()),
        }
    }

    /// The best nest so far (None before the first nest).
    pub fn best(&self) -> Option<Best> {
        let (d, items) = self.best_decoded()?;
        Some(Best::of(items, d, self.job.parts.len()))
    }

    /// True when the search has nothing more to do (budget spent, Stop,
    /// or nothing left to try).
    pub fn finished(&self) -> bool {
        matches!(self.phase, Phase::Done(..))
    }

    /// Takes `best` as its own best nest when it is better: the order
    /// search goes on with it as the nest to beat, the separation goes on
    /// from it; before the first nest, it is the nest, and the search is
    /// over. A nest that does not fit this job (a page's) is ignored;
    /// returns whether it was taken.
    pub fn adopt(&mut self, best: &Best) -> bool {
        let Some(sheet) = &self.sheet else {
            return false;
        };
        if let Some(mine) = self.best() {
            if !best.better_than(&mine, self.eps) {
                return false;
            }
        }
        let Some((d, items)) = rebuild(best, &self.items, &self.order, sheet, self.eps) else {
            return false;
        };
        self.phase = match std::mem::replace(&mut self.phase, Phase::Moving) {
            Phase::Sequence {
                cur,
                last_gain,
                last_better,
                ..
            } => Phase::Sequence {
                best: d,
                adopted: Some(items),
                cur,
                last_gain,
                last_better,
            },
            Phase::Separate(im) => match im.adopt(&items, d) {
                Ok(im) => Phase::Separate(Box::new(im)),
                Err(d) => Phase::Done(*d, Some(items)),
            },
            // Before its first nest: the nest to finish (the page's Stop).
            Phase::Done(..) | Phase::First | Phase::Moving => Phase::Done(d, Some(items)),
        };
        self.report = None;
        true
    }

    /// Runs until the budget is spent, Stop, nothing is left to try, or
    /// (when `until` is given) the first point past `until` evaluations
    /// where the search can pause (between two tries of the separation,
    /// every evaluation before it). True when it paused with more to do.
    pub fn run(
        &mut self,
        until: Option<u64>,
        clock: &dyn Fn() -> f64,
        progress: &mut dyn FnMut(Progress) -> bool,
    ) -> bool {
        let start = *self.start.get_or_insert_with(clock);
        let Some(sheet) = self.sheet.take() else {
            self.phase = Phase::Done(Decoded::empty(), None);
            return false;
        };
        let more = self.slice(&sheet, start, until, clock, progress);
        self.sheet = Some(sheet);
        more
    }

    fn slice(
        &mut self,
        sheet: &SheetRoom,
        start: f64,
        until: Option<u64>,
        clock: &dyn Fn() -> f64,
        progress: &mut dyn FnMut(Progress) -> bool,
    ) -> bool {
        let s = &self.job.settings;
        let eps = self.eps;
        let items = &self.items;
        let parts = self.job.parts.len();
        let report_as = |items: &[Item], d: &Decoded, evaluations: u64| Progress {
            evaluations,
            sheets: d.cost.1,
            length: d.cost.2,
            unplaced: d.unplaced.len() + d.stopped.len(),
            elapsed_s: clock() - start,
            best: super::live::placements(items, d, parts),
            lost: d.cost.0,
            left_out: (
                d.unplaced.iter().map(|&i| items[i].part).collect(),
                d.stopped.iter().map(|&i| items[i].part).collect(),
            ),
        };
        // Time and evaluations left. The phases switch on evaluations only,
        // never on the clock, so that a run stopped at evaluation E is the
        // same nest as a run given E evaluations (the page's Stop replays).
        let more = |evaluations: u64| {
            clock() - start < s.time_s && s.max_evaluations.is_none_or(|m| evaluations < m)
        };
        let paused = |evaluations: u64| until.is_some_and(|u| evaluations >= u);
        loop {
            match std::mem::replace(&mut self.phase, Phase::Moving) {
                Phase::First => {
                    let order = &self.order;
                    let report = |d: &Decoded, evaluations: u64| report_as(items, d, evaluations);
                    // The first nest counts one evaluation per copy and honours the
                    // budget and Stop between copies (a 200-copy sheet's first nest takes
                    // seconds): cut short, it is the nest of the copies placed so far, the
                    // others reported. `--time 0` asks for this nest whole.
                    let mut go_on = true;
                    let first = decode_until(items, order, sheet, eps, &mut |k, partial| {
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
                    let best = first.nest.clone();
                    self.evaluations = (order.len() - best.stopped.len()) as u64;
                    self.work = best.work;
                    if best.stopped.is_empty() {
                        go_on = progress(report(&best, self.evaluations));
                    }
                    self.go_on = go_on;
                    let e = self.evaluations;
                    self.phase = Phase::Sequence {
                        cur: Box::new(first),
                        best,
                        adopted: None,
                        last_gain: e,
                        last_better: e,
                    };
                }
                Phase::Sequence {
                    mut best,
                    mut adopted,
                    mut cur,
                    mut last_gain,
                    mut last_better,
                } => {
                    let n = self.order.len();
                    let distinct = self.order.windows(2).any(|w| w[0].0 != w[1].0);
                    let turns = items.iter().any(|it| it.variants.len() > 1);
                    let evaluations = self.evaluations;
                    if !(self.go_on
                        && n > 1
                        && (distinct || turns)
                        && more(evaluations)
                        && evaluations - last_better <= SEQUENCE_STALL
                        && evaluations < sequence_most(n)
                        && self.work < sequence_work(s.budget()))
                    {
                        // The rest of the budget: sparrow's exploration and
                        // compression on the best nest (separate/).
                        if !(self.go_on && more(evaluations)) {
                            self.phase = Phase::Done(best, adopted);
                            return false;
                        }
                        let its = adopted.as_deref().unwrap_or(items);
                        self.report = Some(report_as(its, &best, evaluations));
                        // Parts that may take any angle turn freely in the separation.
                        let free: Vec<bool> = its
                            .iter()
                            .map(|it| self.job.parts[it.part].rotations == super::Rotations::Free)
                            .collect();
                        self.phase = match Improver::new(its, &free, best, sheet.origin_x, eps) {
                            Ok(im) => Phase::Separate(Box::new(im)),
                            Err(best) => Phase::Done(*best, adopted),
                        };
                        continue;
                    }
                    if paused(evaluations) {
                        self.phase = Phase::Sequence {
                            best,
                            adopted,
                            cur,
                            last_gain,
                            last_better,
                        };
                        return true;
                    }
                    let rng = &mut self.rng;
                    let mut o = cur.order().to_vec();
                    // Long without a better nest: kick the current order by a few
                    // random swaps and take it whatever it costs (iterated local
                    // search, Lourenço, Martin & Stützle 2003).
                    let kick = evaluations - last_gain > KICK_AFTER;
                    let step = if kick {
                        last_gain = evaluations;
                        for _ in 0..KICK_SWAPS {
                            let (i, j) = (rng.below(n), rng.below(n));
                            o.swap(i, j);
                        }
                        *cur = decode_after(items, &o, sheet, eps, &cur);
                        self.evaluations += 1;
                        self.work += cur.nest.work;
                        None
                    } else {
                        let (i, j) = (rng.below(n), rng.below(n));
                        let skip = match rng.below(3) {
                            // Hold one copy to a turn, or let the placer choose again (the
                            // orientation in the genome, as Gomes & Oliveira 2002 do).
                            0 if turns => {
                                let k = items[o[i].0].variants.len();
                                let pick = rng.below(k + 1);
                                o[i].1 = (pick < k).then_some(pick);
                                false
                            }
                            _ if o[i].0 == o[j].0 => true,
                            1 => {
                                o.swap(i, j);
                                false
                            }
                            _ => {
                                let x = o.remove(i);
                                o.insert(j, x);
                                false
                            }
                        };
                        (!skip).then_some(o)
                    };
                    if let Some(o) = step {
                        let t = decode_after(items, &o, sheet, eps, &cur);
                        self.evaluations += 1;
                        self.work += t.nest.work;
                        let evaluations = self.evaluations;
                        let mut reported = false;
                        let (d, c) = (&t.nest, &cur.nest);
                        if better(d.cost, c.cost, eps)
                            || (!better(c.cost, d.cost, eps) && d.gravity <= c.gravity)
                        {
                            *cur = t;
                            if better(cur.nest.cost, best.cost, eps) {
                                last_gain = evaluations;
                                last_better = evaluations;
                                best = cur.nest.clone();
                                adopted = None;
                                self.go_on = progress(report_as(items, &best, evaluations));
                                reported = true;
                            }
                        }
                        if !reported && evaluations.is_multiple_of(64) {
                            let its = adopted.as_deref().unwrap_or(items);
                            self.go_on = progress(report_as(its, &best, evaluations));
                        }
                    }
                    self.phase = Phase::Sequence {
                        best,
                        adopted,
                        cur,
                        last_gain,
                        last_better,
                    };
                }
                Phase::Separate(mut im) => {
                    if self.go_on && paused(self.evaluations) {
                        self.phase = Phase::Separate(im);
                        return true;
                    }
                    let report = match self.report.take() {
                        Some(r) => r,
                        None => {
                            let (d, its) = im.best();
                            report_as(its, d, self.evaluations)
                        }
                    };
                    let state = RefCell::new((self.evaluations, self.go_on, report));
                    let progress = RefCell::new(&mut *progress);
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
                    let go = budget() && im.attempt(&mut self.rng, &mut budget, &mut found);
                    let (e, go_on, report) = state.into_inner();
                    self.evaluations = e;
                    self.go_on = go_on;
                    self.report = Some(report);
                    if go {
                        self.phase = Phase::Separate(im);
                    } else {
                        let (d, its) = im.into_parts();
                        self.phase = Phase::Done(d, Some(its));
                        return false;
                    }
                }
                p @ Phase::Done(..) => {
                    self.phase = p;
                    return false;
                }
                Phase::Moving => unreachable!("a phase is always put back"),
            }
        }
    }

    /// The best nest found, as a [`Nest`].
    pub fn finish(self) -> Nest {
        match self.phase {
            Phase::Done(d, adopted)
            | Phase::Sequence {
                best: d, adopted, ..
            } => {
                let items = adopted.unwrap_or(self.items);
                assemble(&self.job, &items, d, self.unplaced, self.evaluations)
            }
            Phase::Separate(im) => {
                let (d, items) = im.into_parts();
                assemble(&self.job, &items, d, self.unplaced, self.evaluations)
            }
            Phase::First | Phase::Moving => Nest {
                placements: Vec::new(),
                sheets: Vec::new(),
                unplaced: self.unplaced,
                strip_length: None,
                density: 0.0,
                evaluations: 0,
            },
        }
    }
}

/// The parts made ready for placing: each allowed turn and mirror with its
/// collision polygon and the rooms of its holes; the parts that cannot be
/// placed anywhere go to `unplaced` with the reason.
fn ready(job: &NestJob, sheet: &SheetRoom, unplaced: &mut Vec<Unplaced>) -> Vec<Item> {
    let s = &job.settings;
    let grow = s.spacing / 2.0;
    let (width, height) = job.sheets.size(0);
    let mut items = Vec::new();
    for (pi, p) in job.parts.iter().enumerate() {
        let out = |reason: Text| Unplaced {
            part: p.name.clone(),
            copies: p.quantity,
            reason,
        };
        if p.quantity == 0 {
            unplaced.push(out(
                text!("quantity 0: left out"; "quantidade 0: deixada de fora"),
            ));
            continue;
        }
        // Many-vertex outlines on fewer vertices, on the safe side.
        let Some(poly) = nesting_polygon(&p.outer, grow, s.tolerance) else {
            unplaced.push(out(
                text!("its outline encloses no area"; "o contorno não encerra área"),
            ));
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
                    .map(|r| Shape::with_core(r.placed(rotation, mirror, Default::default())))
                    .collect(),
            })
            .collect();
        if !variants.iter().any(|v| sheet.fits(v)) {
            let room = match (&job.sheets, width) {
                (Sheets::Mixed(_), _) => text!("every sheet size"; "todos os tamanhos de chapa"),
                (Sheets::Remnant { .. }, _) => {
                    let w = width.unwrap_or(0.0);
                    text!("the remnant sheet (its box {w:.1} × {height:.1} mm)";
                          "o retalho (sua caixa {:.1} × {:.1} mm)", dec(w), dec(height))
                }
                (_, Some(w)) => {
                    text!("the sheet {w} × {height} mm"; "a chapa {} × {} mm", dec(w), dec(height))
                }
                (_, None) => {
                    text!("the strip {height} mm high"; "a tira de {} mm de altura", dec(height))
                }
            };
            unplaced.push(out(text!(
                "larger than {} at every allowed rotation, with margin {} mm and spacing {} mm", room.en, s.margin, s.spacing;
                "maior que {} em todas as rotações permitidas, com margem de {} mm e espaçamento de {} mm", room.pt, dec(s.margin), dec(s.spacing)
            )));
            continue;
        }
        items.push(Item { part: pi, variants });
    }
    items
}

/// One search of `job` with the settings' seed, to the end of its budget.
pub(super) fn run(
    job: &NestJob,
    clock: &dyn Fn() -> f64,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Nest, super::NestError> {
    let mut search = Search::new(job, job.settings.seed)?;
    search.run(None, clock, progress);
    Ok(search.finish())
}
