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
//! are given, [`nest_cheapest_by`] the trials (the CLI nests each with its
//! threads, the page with its one worker), [`json_fields`] the report.

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
            reason: why.en,
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
        let at = |job| Trial {
            job,
            counts,
            passed_over: failed,
        };
        let first = nest(at(&trial), &mut go)?;
        if first.unplaced.is_empty() || stopped.get() {
            // The rest of the budget for it: the same run, longer.
            let mut rest = trial.clone();
            rest.settings.max_evaluations = s
                .max_evaluations
                .map(|e| e.saturating_sub(failed as u64 * trial_evaluations.unwrap_or(0)));
            rest.settings.time_s = (s.time_s - (clock() - start)).max(trial_time);
            let kept = if stopped.get() {
                first
            } else {
                let longer = nest(at(&rest), &mut go)?;
                if longer.unplaced.is_empty() {
                    longer
                } else {
                    first
                }
            };
            let (used, cost) = used(stock, counts, &kept);
            rest.settings = job.settings.clone();
            return Ok(Cheapest {
                job: rest,
                nest: kept,
                counts: counts.clone(),
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
    let trial = Trial {
        job: &rest,
        counts: &all,
        passed_over: failed,
    };
    let kept = nest(trial, &mut go)?;
    let (used, cost) = used(stock, &all, &kept);
    Ok(Cheapest {
        job: whole,
        nest: kept,
        counts: all,
        used,
        cost,
        tried: failed,
    })
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
