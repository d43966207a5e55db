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

use super::team::nest_team;
use super::{Nest, NestError, NestJob, Progress, SheetSize, Sheets};

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

/// The cheapest nest found and what it costs.
#[derive(Clone, Debug)]
pub struct Cheapest {
    /// The job as nested: its sheets the combination chosen (the nest's
    /// sheet numbers refer to them).
    pub job: NestJob,
    /// The nest.
    pub nest: Nest,
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
        if !(s.cost.is_finite() && s.cost >= 0.0) {
            return Err(NestError::Setting {
                field: "sheet",
                reason: format!(
                    "the cost {} of a {} × {} sheet is not a price ≥ 0",
                    s.cost, s.size.width, s.size.height
                ),
            });
        }
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
fn with_sheets(job: &NestJob, stock: &[Stock], counts: &[usize]) -> NestJob {
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
fn used(stock: &[Stock], counts: &[usize], nest: &Nest) -> (Vec<usize>, f64) {
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
    check(stock)?;
    let all: Vec<usize> = stock.iter().map(|s| s.size.count).collect();
    let whole = with_sheets(job, stock, &all);
    super::check(&whole)?;
    let s = &job.settings;
    let start = clock();
    let need: f64 = job
        .parts
        .iter()
        .map(|p| p.area().max(0.0) * p.quantity as f64)
        .sum();
    let trial_evaluations = s.max_evaluations.map(|e| (e / TRIAL_SHARE).max(1));
    let trial_time = s.time_s / TRIAL_SHARE as f64;
    let mut failed = 0;
    let stopped = std::cell::Cell::new(false);
    let mut go = |p: Progress| {
        let go = progress(p);
        stopped.set(stopped.get() || !go);
        go
    };
    // One size: the search itself needs the fewest sheets.
    let list = if stock.len() > 1 {
        combinations(stock, s.margin, need)
    } else {
        Vec::new()
    };
    for counts in list.iter().take(MOST_TRIALS) {
        let mut trial = with_sheets(job, stock, counts);
        trial.settings.max_evaluations = trial_evaluations;
        trial.settings.time_s = trial_time;
        let nest = nest_team(&trial, searches, clock, &mut go)?;
        if nest.unplaced.is_empty() || stopped.get() {
            // The rest of the budget for it: the same run, longer.
            let mut rest = trial.clone();
            rest.settings.max_evaluations = s
                .max_evaluations
                .map(|e| e.saturating_sub(failed as u64 * trial_evaluations.unwrap_or(0)));
            rest.settings.time_s = (s.time_s - (clock() - start)).max(trial_time);
            let nest = if stopped.get() {
                nest
            } else {
                let longer = nest_team(&rest, searches, clock, &mut go)?;
                if longer.unplaced.is_empty() {
                    longer
                } else {
                    nest
                }
            };
            let (used, cost) = used(stock, counts, &nest);
            rest.settings = job.settings.clone();
            return Ok(Cheapest {
                job: rest,
                nest,
                used,
                cost,
                tried: failed,
            });
        }
        failed += 1;
    }
    let mut rest = whole.clone();
    rest.settings.max_evaluations = s
        .max_evaluations
        .map(|e| e.saturating_sub(failed as u64 * trial_evaluations.unwrap_or(0)));
    rest.settings.time_s = (s.time_s - (clock() - start)).max(0.0);
    let nest = nest_team(&rest, searches, clock, &mut go)?;
    let (used, cost) = used(stock, &all, &nest);
    Ok(Cheapest {
        job: whole,
        nest,
        used,
        cost,
        tried: failed,
    })
}

#[cfg(test)]
#[path = "stock_tests.rs"]
mod tests;
