//! Sheets of several sizes, each at a price: the cheapest combination of
//! them that holds the parts (issue 44 item 3, "mixed sheet sizes use the
//! cheapest combination when a cost per sheet is given").
//!
//! The combinations of the stock (so many sheets of each size, at most
//! what is in stock) are taken cheapest first (then fewer sheets, then
//! more area), leaving out those whose usable area (each sheet less its
//! margin) is below the parts' area: no nest can hold the parts there.
//! Each is nested with a share of the budget ([`TRIAL_SHARE`]); the first
//! that holds every copy is nested again with what is left of the budget
//! (the search is the same run up to the share, so it holds them again:
//! a nest only gets better), and its sheets are filled as any `--sheet`
//! job (fewest sheets, the last shortest). When none of the first
//! [`MOST_TRIALS`] does, the whole stock is nested in the order given.
//! The cost is that of the sheets the nest uses.
//!
//! `kerfcam nest --sheet WxH:N:COST` and the page's Sheet mode (a cost per
//! sheet size) both come here: [`stock_of`] holds the rule on which costs
//! are given, [`Trials`] the trials (the CLI nests each with its threads
//! through [`nest_cheapest`]; the page with its team of workers, the
//! trials driven one at a time, or in one worker through
//! [`nest_cheapest_by`]), [`json_fields`] the report.

use super::team::nest_team;
use super::{Nest, NestError, NestJob, Progress, SheetSize, Sheets};
use crate::warning::Text;

/// A combination's trial gets this share of the evaluations and time.
const TRIAL_SHARE: u64 = 16;
/// Combinations tried before the whole stock is nested (at most half the
/// budget spent on trials that did not hold).
const MOST_TRIALS: usize = 8;
/// Most combinations listed: each size's count is also held to what
/// alone would give three times the parts' area.
const MOST_COMBINATIONS: usize = 100_000;

/// A sheet size in stock (`size.count` sheets of it) and what one costs
/// (any currency: the job's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stock {
    /// The size and how many are in stock.
    pub size: SheetSize,
    /// Price of one sheet, ≥ 0.
    pub cost: f64,
}

/// Costs given for some sheet sizes and not others, or with several
/// torches: refused, in the words of the CLI and of the page.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CostError {
    /// A cost for some sizes only: which of them are meant to be free is
    /// not guessed.
    SomeSizes,
    /// Several torches nest torch 1's band on the sheets as given.
    Torches,
}

impl CostError {
    /// What to do, in English and Portuguese.
    pub fn text(self) -> Text {
        match self {
            CostError::SomeSizes => crate::text!(
                "give a cost for every sheet size or for none";
                "informe um custo para cada tamanho de chapa ou para nenhum"),
            CostError::Torches => crate::text!(
                "a multi-torch nest takes the sheets as given (leave the costs out)";
                "um encaixe com várias tochas usa as chapas como dadas (deixe os custos em branco)"),
        }
    }
}

/// The sheet sizes as stock when costs are given (`costs[i]` for
/// `sizes[i]`): for every size, or for none (`None`: the sheets as given,
/// filled in their order). `torches`: several torches are set.
pub fn stock_of(
    sizes: &[SheetSize],
    costs: &[Option<f64>],
    torches: bool,
) -> Result<Option<Vec<Stock>>, CostError> {
    if costs.iter().all(Option::is_none) {
        return Ok(None);
    }
    if costs.len() != sizes.len() || costs.iter().any(Option::is_none) {
        return Err(CostError::SomeSizes);
    }
    if torches {
        return Err(CostError::Torches);
    }
    Ok(Some(
        sizes
            .iter()
            .zip(costs)
            .map(|(&size, c)| Stock {
                size,
                cost: c.unwrap_or(0.0),
            })
            .collect(),
    ))
}

/// `s`'s cost checked: a price ≥ 0 (not NaN, not infinite).
pub fn check_cost(s: &Stock) -> Result<(), Text> {
    let (c, w, h) = (s.cost, s.size.width, s.size.height);
    if c.is_finite() && c >= 0.0 {
        Ok(())
    } else {
        Err(crate::text!(
            "the cost {c} of a {w} × {h} sheet is not a price ≥ 0";
            "o custo {c} de uma chapa {w} × {h} não é um preço ≥ 0"))
    }
}

/// The cheapest nest found and what it costs.
#[derive(Clone, Debug)]
pub struct Cheapest {
    /// The job as nested: its sheets the combination chosen (the nest's
    /// sheet numbers refer to them).
    pub job: NestJob,
    /// The nest.
    pub nest: Nest,
    /// Per stock size, the sheets of the combination nested (the job's).
    pub counts: Vec<usize>,
    /// Per stock size, the sheets the nest uses.
    pub used: Vec<usize>,
    /// Their cost.
    pub cost: f64,
    /// Combinations nested that did not hold every copy (before the one
    /// kept; or all of the first [`MOST_TRIALS`], then the whole stock
    /// was nested).
    pub tried: usize,
}

/// `stock` checked: sizes that are sizes, counts, costs ≥ 0.
fn check(stock: &[Stock]) -> Result<(), NestError> {
    let sizes: Vec<SheetSize> = stock.iter().map(|s| s.size).collect();
    super::check_rects(&sizes)?;
    for s in stock {
        check_cost(s).map_err(|why| NestError::Setting {
            field: "sheet",
            reason: why,
        })?;
    }
    Ok(())
}

/// The combinations of `stock` (sheets of each size) whose usable area
/// (margin `margin` off every side) is at least `need`, cheapest first,
/// then fewer sheets, then more area.
fn combinations(stock: &[Stock], margin: f64, need: f64) -> Vec<Vec<usize>> {
    let usable: Vec<f64> = stock
        .iter()
        .map(|s| {
            ((s.size.width - 2.0 * margin).max(0.0)) * ((s.size.height - 2.0 * margin).max(0.0))
        })
        .collect();
    let most: Vec<usize> = stock
        .iter()
        .zip(&usable)
        .map(|(s, &a)| {
            let enough = if a > 0.0 {
                (3.0 * need / a).ceil().max(1.0)
            } else {
                0.0
            };
            s.size.count.min(enough as usize)
        })
        .collect();
    let mut out = Vec::new();
    let mut counts = vec![0; stock.len()];
    fn walk(
        i: usize,
        counts: &mut Vec<usize>,
        most: &[usize],
        usable: &[f64],
        need: f64,
        out: &mut Vec<Vec<usize>>,
    ) {
        if out.len() >= MOST_COMBINATIONS {
            return;
        }
        if i == most.len() {
            let area: f64 = counts.iter().zip(usable).map(|(&n, &a)| n as f64 * a).sum();
            if counts.iter().any(|&n| n > 0) && area >= need {
                out.push(counts.clone());
            }
            return;
        }
        for n in 0..=most[i] {
            counts[i] = n;
            walk(i + 1, counts, most, usable, need, out);
        }
        counts[i] = 0;
    }
    walk(0, &mut counts, &most, &usable, need, &mut out);
    let cost = |c: &[usize]| -> f64 { c.iter().zip(stock).map(|(&n, s)| n as f64 * s.cost).sum() };
    let area = |c: &[usize]| -> f64 { c.iter().zip(&usable).map(|(&n, &a)| n as f64 * a).sum() };
    let sheets = |c: &[usize]| -> usize { c.iter().sum() };
    out.sort_by(|a, b| {
        cost(a)
            .total_cmp(&cost(b))
            .then(sheets(a).cmp(&sheets(b)))
            .then(area(b).total_cmp(&area(a)))
            .then(a.cmp(b))
    });
    out
}

/// `job`'s sheets as `counts` of each stock size, in the stock's order.
pub fn with_sheets(job: &NestJob, stock: &[Stock], counts: &[usize]) -> NestJob {
    let sizes = stock
        .iter()
        .zip(counts)
        .filter(|(_, &n)| n > 0)
        .map(|(s, &n)| SheetSize { count: n, ..s.size })
        .collect();
    NestJob {
        sheets: Sheets::rects(sizes),
        ..job.clone()
    }
}

/// Per stock size, the sheets `nest` uses of `counts` (filled in the
/// stock's order), and their cost.
pub fn used(stock: &[Stock], counts: &[usize], nest: &Nest) -> (Vec<usize>, f64) {
    let mut left = nest.sheets.len();
    let used: Vec<usize> = counts
        .iter()
        .map(|&n| {
            let u = n.min(left);
            left -= u;
            u
        })
        .collect();
    let cost = used
        .iter()
        .zip(stock)
        .map(|(&n, s)| n as f64 * s.cost)
        .sum();
    (used, cost)
}

/// What each of a nest's first `sheets` sheets cost, the nest made on
/// `counts` of each stock size (filled in the stock's order, as
/// [`used`] counts them): the quote's material for each sheet.
pub fn sheet_costs(stock: &[Stock], counts: &[usize], sheets: usize) -> Vec<f64> {
    stock
        .iter()
        .zip(counts)
        .flat_map(|(s, &n)| std::iter::repeat_n(s.cost, n))
        .take(sheets)
        .collect()
}

/// One combination to nest, as [`nest_cheapest_by`] asks for it.
#[derive(Clone, Copy, Debug)]
pub struct Trial<'a> {
    /// The job on the combination's sheets, with the budget for this nest.
    pub job: &'a NestJob,
    /// Per stock size, the combination's sheets.
    pub counts: &'a [usize],
    /// Combinations nested before it that did not hold every copy.
    pub passed_over: usize,
}

/// Nests `job`'s parts on the cheapest combination of `stock` that holds
/// them (`job.sheets` is not read), with `searches` searches
/// ([`nest_team`]); the budget is `job`'s, trials included.
pub fn nest_cheapest(
    job: &NestJob,
    stock: &[Stock],
    searches: usize,
    clock: &(dyn Fn() -> f64 + Sync),
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Cheapest, NestError> {
    nest_cheapest_by(
        job,
        stock,
        clock,
        &mut |t, go| nest_team(t.job, searches, clock, go),
        progress,
    )
}

/// What nests one combination: the trial, and the progress to pass on
/// (it answers false to stop).
pub type NestTrial<'n> =
    dyn FnMut(Trial, &mut dyn FnMut(Progress) -> bool) -> Result<Nest, NestError> + 'n;

/// [`nest_cheapest`] with each combination nested by `nest` (the page:
/// [`super::nest`] in its worker, as `nest_team` with one search), which
/// passes its progress on to the `go` it is given (false: stop).
pub fn nest_cheapest_by(
    job: &NestJob,
    stock: &[Stock],
    clock: &dyn Fn() -> f64,
    nest: &mut NestTrial,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Cheapest, NestError> {
    let mut trials = Trials::new(job, stock, clock())?;
    let stopped = std::cell::Cell::new(false);
    let mut go = |p: Progress| {
        let go = progress(p);
        stopped.set(stopped.get() || !go);
        go
    };
    while let Some(next) = trials.next(clock()) {
        let trial = Trial {
            job: &next.job,
            counts: &next.counts,
            passed_over: next.passed_over,
        };
        let n = nest(trial, &mut go)?;
        trials.record(n, stopped.get());
    }
    // `next` answers None once a nest is kept: never the error.
    trials.finish().ok_or(NestError::Setting {
        field: "sheet",
        reason: crate::text!("no combination was nested"; "nenhuma combinação foi encaixada"),
    })
}

/// The trials of [`nest_cheapest_by`] one at a time, for a caller that
/// nests each itself and cannot be called back (the page's team of web
/// workers, www/nest-team.js): [`Trials::next`] says what to nest,
/// [`Trials::record`] takes the nest, until `next` answers None;
/// [`Trials::finish`] is then the cheapest nest. The same nests recorded
/// make the same choices as [`nest_cheapest_by`]'s.
#[derive(Clone, Debug)]
pub struct Trials {
    /// The job as given (its settings the whole budget).
    job: NestJob,
    stock: Vec<Stock>,
    /// The combinations tried before the whole stock, cheapest first.
    list: Vec<Vec<usize>>,
    /// Clock reading at the start, s.
    start: f64,
    trial_evaluations: Option<u64>,
    trial_time: f64,
    /// Combinations nested that did not hold every copy.
    failed: usize,
    phase: Phase,
}

#[derive(Clone, Debug)]
enum Phase {
    /// Nesting `list[i]` with a trial's share of the budget.
    Trial(usize),
    /// `list[i]` held every copy: nesting it again with the rest of the
    /// budget; the first nest is kept if the longer does not hold them.
    Longer(usize, Nest),
    /// No combination tried held every copy: the whole stock is nested.
    Whole,
    /// The nest kept, on these counts.
    Done(Nest, Vec<usize>),
}

/// One nest to make: a [`Trial`] that owns its job.
#[derive(Clone, Debug)]
pub struct Next {
    /// The job on the combination's sheets, with the budget for this nest.
    pub job: NestJob,
    /// Per stock size, the combination's sheets.
    pub counts: Vec<usize>,
    /// Combinations nested before it that did not hold every copy.
    pub passed_over: usize,
}

impl Trials {
    /// The trials of `job`'s parts on `stock` (`job.sheets` is not read),
    /// the budget `job`'s; `start` the clock's reading now.
    pub fn new(job: &NestJob, stock: &[Stock], start: f64) -> Result<Trials, NestError> {
        check(stock)?;
        let all: Vec<usize> = stock.iter().map(|s| s.size.count).collect();
        super::check(&with_sheets(job, stock, &all))?;
        let s = &job.settings;
        let need: f64 = job
            .parts
            .iter()
            .map(|p| p.area().max(0.0) * p.quantity as f64)
            .sum();
        // One size: the search itself needs the fewest sheets.
        let mut list = if stock.len() > 1 {
            combinations(stock, s.margin, need)
        } else {
            Vec::new()
        };
        list.truncate(MOST_TRIALS);
        Ok(Trials {
            phase: if list.is_empty() {
                Phase::Whole
            } else {
                Phase::Trial(0)
            },
            job: job.clone(),
            stock: stock.to_vec(),
            list,
            start,
            trial_evaluations: s.max_evaluations.map(|e| (e / TRIAL_SHARE).max(1)),
            trial_time: s.time_s / TRIAL_SHARE as f64,
            failed: 0,
        })
    }

    /// The next nest to make, its budget from the clock's reading `now`
    /// (what is left of the whole); None when the cheapest is found.
    pub fn next(&self, now: f64) -> Option<Next> {
        let s = &self.job.settings;
        let spent = self.failed as u64 * self.trial_evaluations.unwrap_or(0);
        let rest = s.max_evaluations.map(|e| e.saturating_sub(spent));
        let left = s.time_s - (now - self.start);
        let all = self.all();
        let (counts, max_evaluations, time_s) = match &self.phase {
            Phase::Trial(i) => (&self.list[*i], self.trial_evaluations, self.trial_time),
            // The rest of the budget for it: the same run, longer.
            Phase::Longer(i, _) => (&self.list[*i], rest, left.max(self.trial_time)),
            Phase::Whole => (&all, rest, left.max(0.0)),
            Phase::Done(..) => return None,
        };
        let mut job = with_sheets(&self.job, &self.stock, counts);
        job.settings.max_evaluations = max_evaluations;
        job.settings.time_s = time_s;
        // Each nest's phases are shared out of the whole budget: the trial
        // is the same run as its longer nest, up to the trial's share.
        job.settings.budget_s = Some(s.budget());
        Some(Next {
            job,
            counts: counts.clone(),
            passed_over: self.failed,
        })
    }

    /// The nest of the last [`Trials::next`]; `stopped`: the search was
    /// told to stop (the nest is kept, on its combination).
    pub fn record(&mut self, nest: Nest, stopped: bool) {
        let holds = nest.unplaced.is_empty();
        self.phase = match std::mem::replace(&mut self.phase, Phase::Whole) {
            Phase::Trial(i) if stopped => Phase::Done(nest, self.list[i].clone()),
            Phase::Trial(i) if holds => Phase::Longer(i, nest),
            Phase::Trial(i) => {
                self.failed += 1;
                if i + 1 < self.list.len() {
                    Phase::Trial(i + 1)
                } else {
                    Phase::Whole
                }
            }
            Phase::Longer(i, first) => {
                let kept = if holds { nest } else { first };
                Phase::Done(kept, self.list[i].clone())
            }
            Phase::Whole => Phase::Done(nest, self.all()),
            done @ Phase::Done(..) => done,
        };
    }

    /// The cheapest nest once [`Trials::next`] answers None (None before).
    pub fn finish(self) -> Option<Cheapest> {
        let Phase::Done(nest, counts) = self.phase else {
            return None;
        };
        let (used, cost) = used(&self.stock, &counts, &nest);
        Some(Cheapest {
            job: with_sheets(&self.job, &self.stock, &counts),
            nest,
            used,
            cost,
            counts,
            tried: self.failed,
        })
    }

    /// Every sheet in stock.
    fn all(&self) -> Vec<usize> {
        self.stock.iter().map(|s| s.size.count).collect()
    }
}

/// The report's fields for a nest on `stock` (`kerfcam nest --json` and
/// the page's result alike): `stock` (each size: `width`, `height`,
/// `in_stock`, `cost`, `used`), `sheet_cost` (of the sheets used) and
/// `combinations_passed_over`.
pub fn json_fields(
    stock: &[Stock],
    used: &[usize],
    cost: f64,
    passed_over: usize,
) -> [(&'static str, serde_json::Value); 3] {
    let sizes = stock
        .iter()
        .zip(used)
        .map(|(s, &used)| {
            serde_json::json!({
                "width": s.size.width,
                "height": s.size.height,
                "in_stock": s.size.count,
                "cost": s.cost,
                "used": used,
            })
        })
        .collect();
    [
        ("stock", serde_json::Value::Array(sizes)),
        ("sheet_cost", cost.into()),
        ("combinations_passed_over", passed_over.into()),
    ]
}

#[cfg(test)]
#[path = "stock_tests.rs"]
mod tests;
