//! Chaining in strips gives the one-thread chains, gaps and warnings.

use super::super::{chain_on, Chain, Piece, Pieces};
use super::super::{grid::EndGrid, walk::Open, walk::Walker};
use super::{labels, FROM, MIXED};
use crate::geom::{Point, Segment};
use crate::par::Threads;
use crate::warning::Warning;

use crate::test_rng::Xorshift as Rng;

fn line(a: Point, b: Point, entity: usize) -> Piece {
    Piece {
        segments: vec![Segment::line(a, b)],
        closed: false,
        entities: vec![entity],
        measure: None,
    }
}

/// Squares of four lines on a 1,000 mm sheet, the lines shuffled and some
/// reversed, some corners opened by more than the tolerance (gaps), some
/// with a fifth line from a corner (branch points), and long lines across
/// the sheet touching squares at their ends (groups across every strip).
fn sheet(squares: usize) -> Vec<Piece> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut pieces = Vec::new();
    let side = (squares as f64).sqrt().ceil() as usize;
    let pitch = 1000.0 / side as f64;
    for k in 0..squares {
        let (x, y) = ((k % side) as f64 * pitch, (k / side) as f64 * pitch);
        let s = pitch * 0.6;
        let c = [
            Point::new(x, y),
            Point::new(x + s, y),
            Point::new(x + s, y + s),
            Point::new(x, y + s),
        ];
        for e in 0..4 {
            let (a, mut b) = (c[e], c[(e + 1) % 4]);
            if k % 13 == 0 && e == 1 {
                // A corner opened by 0.05 mm: closed in the gap pass only.
                b.x += 0.05;
            }
            let (a, b) = if k % 3 == e % 2 { (b, a) } else { (a, b) };
            pieces.push(line(a, b, pieces.len()));
        }
        if k % 17 == 0 {
            pieces.push(line(c[0], Point::new(x - 1.0, y - 1.0), pieces.len()));
        }
        if k % 97 == 0 {
            // Across the sheet, from this square's corner to a far one's.
            let far = Point::new(1000.0 - x, y + s);
            pieces.push(line(c[3], far, pieces.len()));
        }
    }
    for i in (1..pieces.len()).rev() {
        let j = (rng.unit() * (i + 1) as f64) as usize;
        pieces.swap(i, j.min(i));
    }
    pieces
}

fn pieces(ps: &[Piece]) -> Pieces {
    let mut out = Pieces::default();
    for p in ps {
        out.push(p.clone());
    }
    out
}

type Chained = (Vec<Chain>, Vec<Point>, Vec<Warning>);

fn run(ps: &[Piece], t: f64, threads: usize) -> Chained {
    let (mut gaps, mut warnings) = (Vec::new(), Vec::new());
    let chains = chain_on(
        pieces(ps),
        t,
        1e-3,
        &mut gaps,
        &mut warnings,
        Threads::new(threads),
    );
    (chains, gaps, warnings)
}

fn same(a: &Chained, b: &Chained) {
    assert_eq!(a.0.len(), b.0.len());
    for (x, y) in a.0.iter().zip(&b.0) {
        assert_eq!(x.segments, y.segments);
        assert_eq!(x.entities, y.entities);
        assert_eq!(x.closed, y.closed);
    }
    assert_eq!(a.1, b.1, "gaps");
    assert_eq!(a.2, b.2, "warnings");
}

#[test]
fn a_sheet_chains_the_same_on_one_two_and_three_threads() {
    let ps = sheet(9000);
    assert!(ps.len() > FROM);
    for t in [1e-3, 0.1] {
        let one = run(&ps, t, 1);
        assert!(one.0.iter().filter(|c| c.closed).count() > 8000);
        assert!(!one.2.is_empty(), "branch points met");
        if t > 0.01 {
            assert!(!one.1.is_empty(), "gaps bridged");
        }
        same(&one, &run(&ps, t, 2));
        same(&one, &run(&ps, t, 3));
    }
}

#[test]
fn one_mesh_across_the_sheet_is_walked_whole() {
    // A comb: every tooth joins the spine, so everything is one group
    // (the strips give up and one walk does it all).
    let mut ps = Vec::new();
    let teeth = FROM;
    for k in 0..teeth {
        let x = k as f64;
        ps.push(line(Point::new(x, 0.0), Point::new(x + 1.0, 0.0), ps.len()));
        ps.push(line(Point::new(x, 0.0), Point::new(x, 5.0), ps.len()));
    }
    ps.reverse();
    let one = run(&ps, 1e-3, 1);
    same(&one, &run(&ps, 1e-3, 2));
}

#[test]
fn a_piece_within_twice_the_tolerance_of_a_border_is_mixed() {
    // Cuts at x = 0 and x = 10, tolerance 1 um: ends 1.5 um from a cut
    // are mixed, 2.5 um inside are not; a piece across a cut is mixed.
    let t = 1e-3;
    let at = |x0: f64, x1: f64| line(Point::new(x0, 0.0), Point::new(x1, 1.0), 0);
    let ps = [
        at(-5.0, -0.0025),
        at(-5.0, -0.0015),
        at(0.0025, 9.9975),
        at(0.0015, 5.0),
        at(5.0, 10.0015),
        at(-1.0, 1.0),
        at(10.0025, 20.0),
    ];
    let p = pieces(&ps);
    let open = Open {
        segs: &p.segs,
        ents: &p.ents,
        ends: &p.ends,
    };
    let grid = EndGrid::of(2 * open.len(), |k| open.end(k), t, crate::par::Threads::ONE);
    let w = Walker {
        open,
        grid: &grid,
        t,
        report_above: t,
    };
    assert_eq!(
        labels(&w, &[0.0, 10.0]),
        vec![0, MIXED, 1, MIXED, MIXED, MIXED, 2]
    );
}
