//! The cheapest combination of stock sizes, on jobs whose answer is
//! provable by hand.

use super::*;
use crate::geom::{Point, Segment};
use crate::nest::{NestSettings, Part, Rotations};

fn square(side: f64) -> Vec<Segment> {
    let c = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)].map(|(x, y)| Point::new(x, y));
    (0..4)
        .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
        .collect()
}

fn job(side: f64, quantity: usize) -> NestJob {
    NestJob {
        parts: vec![Part {
            name: "square".into(),
            outer: square(side),
            holes: Vec::new(),
            quantity,
            rotations: Rotations::Quarter,
            mirror: false,
        }],
        // Not read: the stock is.
        sheets: Sheets::Strip { height: 1.0 },
        settings: NestSettings {
            spacing: 2.0,
            margin: 0.0,
            tolerance: 0.01,
            time_s: 1e9,
            seed: 3,
            max_evaluations: Some(320),
            budget_s: None,
        },
    }
}

fn stock(width: f64, height: f64, count: usize, cost: f64) -> Stock {
    Stock {
        size: SheetSize {
            width,
            height,
            count,
        },
        cost,
    }
}

fn cheapest(job: &NestJob, stock: &[Stock]) -> Result<Cheapest, NestError> {
    nest_cheapest(job, stock, 1, &|| 0.0, &mut |_| true)
}

/// Five 90 mm squares (92 mm grown by the spacing) on 200 × 200 sheets at
/// 7 and 100 × 100 sheets at 2: a 100 sheet holds one square, a 200
/// sheet four (2 × 92 ≤ 200 < 3 × 92), and five squares' area (40 500)
/// is more than one 200 sheet's (40 000). So b big and s small sheets
/// hold them only when 4b + s ≥ 5: b = 0 costs 10 (s = 5), b = 1 costs 9
/// (s = 1), b = 2 costs 14. The cheapest is one of each, 9.
#[test]
fn one_big_and_one_small_sheet_are_the_cheapest_that_hold_five_squares() {
    let stock = [stock(200.0, 200.0, 2, 7.0), stock(100.0, 100.0, 5, 2.0)];
    let c = cheapest(&job(90.0, 5), &stock).unwrap();
    assert!(c.nest.unplaced.is_empty(), "{:?}", c.nest.unplaced);
    assert_eq!(c.nest.placements.len(), 5);
    assert_eq!(c.used, [1, 1]);
    assert_eq!(c.cost, 9.0);
    // The job nested is that combination: its sheets and the nest's.
    assert_eq!(c.job.sheets.count(), 2);
    assert_eq!(c.nest.sheets.len(), 2);
    assert_eq!(c.tried, 0);
}

/// Four 60 mm squares (62 grown): a 120 × 120 sheet at 5 holds one (two
/// need 124 mm side by side, and only quarter turns are allowed), as a
/// 70 × 70 sheet at 2 does. Four sheets are needed, and four small ones
/// (8) are the cheapest four. Cheaper or as cheap by the area bound but
/// too few sheets: one big (5; area 14 400, exactly the squares'), three
/// small (6), one big and one small (7): each nested first, none holds.
#[test]
fn combinations_that_pass_the_area_bound_but_hold_too_few_squares_are_passed_over() {
    let stock = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let c = cheapest(&job(60.0, 4), &stock).unwrap();
    assert!(c.nest.unplaced.is_empty(), "{:?}", c.nest.unplaced);
    assert_eq!(c.used, [0, 4]);
    assert_eq!(c.cost, 8.0);
    assert_eq!(c.tried, 3);
    // The same job and seed: the same choice and nest.
    let again = cheapest(&job(60.0, 4), &stock).unwrap();
    assert_eq!(again.nest.placements, c.nest.placements);
}

#[test]
fn a_negative_cost_or_a_sheet_of_no_size_is_a_clear_error() {
    let j = job(60.0, 4);
    let e = cheapest(
        &j,
        &[stock(120.0, 120.0, 3, -5.0), stock(70.0, 70.0, 6, 2.0)],
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "sheet: the cost -5 of a 120 × 120 sheet is not a price ≥ 0"
    );
    let e = cheapest(&j, &[stock(0.0, 120.0, 3, 5.0)]).unwrap_err();
    assert_eq!(e.to_string(), "sheet: 0 × 120 is not a sheet size");
    let e = cheapest(&j, &[stock(120.0, 120.0, 0, 5.0)]).unwrap_err();
    assert!(e.to_string().contains("at least one of each size"), "{e}");
    assert!(cheapest(&j, &[stock(120.0, 120.0, 1, f64::NAN)]).is_err());
}

#[test]
fn combinations_come_cheapest_first_and_none_below_the_area_bound() {
    let s = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let list = combinations(&s, 0.0, 4.0 * 3600.0);
    let cost = |c: &Vec<usize>| 5.0 * c[0] as f64 + 2.0 * c[1] as f64;
    assert_eq!(list[..4], [vec![1, 0], vec![0, 3], vec![1, 1], vec![0, 4]]);
    assert!(list.windows(2).all(|w| cost(&w[0]) <= cost(&w[1])));
    assert!(list
        .iter()
        .all(|c| c[0] as f64 * 14_400.0 + c[1] as f64 * 4_900.0 >= 14_400.0));
}

/// The page nests each combination with `nest` in its one worker, the CLI
/// with `nest_team` (one search: `nest` itself): the same trials in the
/// same order, the same choice and the same nest.
#[test]
fn the_pages_route_and_the_clis_choose_the_same_combination_and_nest() {
    let stock = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let j = job(60.0, 4);
    let cli = cheapest(&j, &stock).unwrap();
    let mut trials = Vec::new();
    let page = nest_cheapest_by(
        &j,
        &stock,
        &|| 0.0,
        &mut |t, go| {
            trials.push((t.counts.to_vec(), t.passed_over));
            crate::nest::nest(t.job, &|| 0.0, go)
        },
        &mut |_| true,
    )
    .unwrap();
    assert_eq!(
        (
            page.counts.clone(),
            page.used.clone(),
            page.cost,
            page.tried
        ),
        (cli.counts.clone(), cli.used.clone(), cli.cost, cli.tried)
    );
    assert_eq!(page.nest.placements, cli.nest.placements);
    assert_eq!(page.job.sheets.count(), cli.job.sheets.count());
    // Three combinations passed over, then the fourth nested and given the
    // rest of the budget.
    let four = vec![0, 4];
    assert_eq!(
        trials,
        [
            (vec![1, 0], 0),
            (vec![0, 3], 1),
            (vec![1, 1], 2),
            (four.clone(), 3),
            (four, 3)
        ]
    );
}

/// Stopped in a trial: that trial's best nest is kept, on its combination.
#[test]
fn a_stop_keeps_the_combination_under_trial() {
    let stock = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let c = nest_cheapest(&job(60.0, 4), &stock, 1, &|| 0.0, &mut |_| false).unwrap();
    assert_eq!(c.counts, [1, 0]);
    assert_eq!(c.job.sheets.count(), 1);
    assert_eq!(c.tried, 0);
}

#[test]
fn costs_are_given_for_every_size_or_for_none() {
    let sizes = [
        stock(120.0, 120.0, 3, 0.0).size,
        stock(70.0, 70.0, 6, 0.0).size,
    ];
    assert_eq!(stock_of(&sizes, &[None, None], false), Ok(None));
    assert_eq!(stock_of(&sizes, &[], false), Ok(None));
    assert_eq!(
        stock_of(&sizes, &[Some(5.0), None], false),
        Err(CostError::SomeSizes)
    );
    assert_eq!(
        stock_of(&sizes, &[Some(5.0), Some(2.0)], true),
        Err(CostError::Torches)
    );
    let s = stock_of(&sizes, &[Some(5.0), Some(0.0)], false)
        .unwrap()
        .unwrap();
    assert_eq!(s[1].cost, 0.0);
    assert_eq!(s[0].size, sizes[0]);
    assert_eq!(
        CostError::SomeSizes.text().en,
        "give a cost for every sheet size or for none"
    );
    assert!(check_cost(&stock(1.0, 1.0, 1, f64::INFINITY)).is_err());
    assert!(check_cost(&stock(1.0, 1.0, 1, 0.0)).is_ok());
}

/// The page's team of workers drives the trials one at a time
/// ([`Trials`]), each nested by the team's searches: with two searches it
/// makes the CLI's choice and nest with two threads (`nest_cheapest`),
/// and it tells the same combinations in the same order.
#[test]
fn trials_one_at_a_time_make_the_clis_cheapest_nest_with_two_searches() {
    let stock = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let j = job(60.0, 4);
    let cli = nest_cheapest(&j, &stock, 2, &|| 0.0, &mut |_| true).unwrap();
    let mut trials = Trials::new(&j, &stock, 0.0).unwrap();
    let mut told = Vec::new();
    while let Some(next) = trials.next(0.0) {
        told.push((next.counts.clone(), next.passed_over));
        let n = crate::nest::team::nest_team(&next.job, 2, &|| 0.0, &mut |_| true).unwrap();
        trials.record(n, false);
    }
    let page = trials.finish().unwrap();
    assert_eq!(
        (
            page.counts.clone(),
            page.used.clone(),
            page.cost,
            page.tried
        ),
        (cli.counts.clone(), cli.used.clone(), cli.cost, cli.tried)
    );
    assert_eq!(page.nest.placements, cli.nest.placements);
    assert_eq!(
        page.job.settings.max_evaluations,
        j.settings.max_evaluations
    );
    assert_eq!(told.last(), Some(&(vec![0, 4], 3)));
    assert_eq!(told.len(), 5);
}

/// Before the last nest is recorded there is no cheapest nest yet.
#[test]
fn trials_have_no_cheapest_nest_before_their_nests() {
    let stock = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let trials = Trials::new(&job(60.0, 4), &stock, 0.0).unwrap();
    assert!(trials.next(0.0).is_some());
    assert!(trials.finish().is_none());
}

/// A trial gets a share of the clock, and the longer nest what is left of
/// it, but both share their phases out of the whole budget: up to the
/// trial's share they are the same run, so the longer nest holds the
/// copies again.
#[test]
fn every_nest_of_the_trials_shares_its_phases_out_of_the_whole_budget() {
    let stock = [stock(120.0, 120.0, 3, 5.0), stock(70.0, 70.0, 6, 2.0)];
    let mut j = job(60.0, 4);
    j.settings.time_s = 32.0;
    let mut trials = Trials::new(&j, &stock, 0.0).unwrap();
    let mut told = Vec::new();
    while let Some(next) = trials.next(0.0) {
        let s = &next.job.settings;
        told.push((s.time_s, s.budget_s));
        let n = crate::nest::nest(&next.job, &|| 0.0, &mut |_| true).unwrap();
        trials.record(n, false);
    }
    assert!(told.contains(&(2.0, Some(32.0))), "{told:?}");
    assert!(told.contains(&(32.0, Some(32.0))), "{told:?}");
    assert!(told.iter().all(|t| t.1 == Some(32.0)), "{told:?}");
}
