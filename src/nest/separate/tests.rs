//! The separation phase on a small strip of rectangles, judged by boxes
//! (for unturned rectangles the box is the shape: a check that does not
//! use the engine's collision test).

use super::*;
use crate::geom::Segment;
use crate::nest::collide::Shape;
use crate::nest::decode::{decode, sheet_room, SheetRoom};
use crate::nest::place::Variant;
use crate::nest::shape::Polygon;
use crate::nest::{NestJob, Part, Rotations, Sheets};

const RECTS: [(f64, f64); 9] = [
    (7.0, 3.0),
    (3.0, 7.0),
    (5.0, 5.0),
    (4.0, 6.0),
    (6.0, 4.0),
    (2.0, 8.0),
    (8.0, 2.0),
    (3.0, 3.0),
    (4.0, 4.0),
];
const HEIGHT: f64 = 10.0;

fn rect(w: f64, h: f64) -> Vec<Point> {
    vec![
        Point::new(0.0, 0.0),
        Point::new(w, 0.0),
        Point::new(w, h),
        Point::new(0.0, h),
    ]
}

fn job() -> NestJob {
    let parts = RECTS
        .iter()
        .enumerate()
        .map(|(i, &(w, h))| {
            let p = rect(w, h);
            Part {
                name: format!("r{i}"),
                outer: (0..4)
                    .map(|k| Segment::line(p[k], p[(k + 1) % 4]))
                    .collect(),
                holes: Vec::new(),
                quantity: 1,
                rotations: Rotations::None,
                mirror: false,
            }
        })
        .collect();
    NestJob::touching(parts, Sheets::Strip { height: HEIGHT })
}

/// The constructive nest (copies by decreasing area) and the items.
fn constructive() -> (Vec<Item>, Decoded) {
    let items: Vec<Item> = RECTS
        .iter()
        .enumerate()
        .map(|(i, &(w, h))| Item {
            part: i,
            variants: vec![Variant {
                rotation: 0.0,
                mirror: false,
                shape: Shape::new(Polygon::new(rect(w, h))),
                holes: Vec::new(),
            }],
        })
        .collect();
    let sheet = sheet_room(&job()).unwrap();
    let d = decode(&items, &by_area(), &sheet, 1e-9);
    (items, d)
}

/// The rectangles by decreasing area, as a decode order.
fn by_area() -> Vec<(usize, Option<usize>)> {
    let mut order: Vec<usize> = (0..RECTS.len()).collect();
    order.sort_by(|&a, &b| {
        let area = |i: usize| RECTS[i].0 * RECTS[i].1;
        area(b).total_cmp(&area(a))
    });
    order.into_iter().map(|i| (i, None)).collect()
}

/// The rectangles' job on `count` fixed sheets `width` × [`HEIGHT`].
fn on_sheets(width: f64, count: usize) -> SheetRoom {
    let mut j = job();
    j.sheets = Sheets::Rect {
        width,
        height: HEIGHT,
        count,
    };
    sheet_room(&j).unwrap()
}

/// `start` shortened by [`improve`] for `moves` moves (seed 7, no free
/// turns), every better nest accepted.
fn improved(items: &[Item], start: Decoded, moves: u64) -> Decoded {
    let mut made = 0u64;
    let mut budget = || {
        made += 1;
        made < moves
    };
    let free = vec![false; items.len()];
    let (after, _) = improve(
        items,
        &free,
        start,
        0.0,
        1e-9,
        &mut SplitMix(7),
        &mut budget,
        &mut |_, _| true,
    );
    after
}

/// Every rectangle where the nest says, inside the strip, no two boxes
/// sharing area; returns the length used.
fn check(items: &[Item], d: &Decoded) -> f64 {
    assert_eq!(d.bins.len(), 1);
    let boxes: Vec<(f64, f64, f64, f64)> = d.bins[0]
        .placed
        .iter()
        .map(|p| {
            let (w, h) = RECTS[items[p.item].part];
            (p.t.x, p.t.y, p.t.x + w, p.t.y + h)
        })
        .collect();
    assert_eq!(boxes.len(), RECTS.len());
    let e = 1e-6;
    for (i, a) in boxes.iter().enumerate() {
        assert!(a.0 >= -e && a.1 >= -e && a.3 <= HEIGHT + e, "{a:?}");
        for b in &boxes[i + 1..] {
            let apart = a.2 <= b.0 + e || b.2 <= a.0 + e || a.3 <= b.1 + e || b.3 <= a.1 + e;
            assert!(apart, "{a:?} overlaps {b:?}");
        }
    }
    let len = boxes.iter().map(|b| b.2).fold(0.0, f64::max);
    assert!((len - d.cost.2).abs() < 1e-9, "{len} {:?}", d.cost);
    len
}

#[test]
fn separation_shortens_the_constructive_strip_and_stays_valid() {
    let (items, start) = constructive();
    let before = check(&items, &start);
    let mut moves = 0u64;
    let mut budget = || {
        moves += 1;
        moves < 20_000
    };
    let mut shorter = 0;
    let mut found = |_: &Decoded, _: &[Item]| {
        shorter += 1;
        true
    };
    let mut rng = SplitMix(7);
    let free = vec![false; items.len()];
    let (after, _) = improve(
        &items,
        &free,
        start,
        0.0,
        1e-9,
        &mut rng,
        &mut budget,
        &mut found,
    );
    let len = check(&items, &after);
    // Area 172 on a strip 10 high: no nest is shorter than 17.2.
    assert!(len >= 17.2 - 1e-9);
    assert!(shorter > 0 && len < before - 0.1, "{before} → {len}");
}

#[test]
fn a_layout_with_no_room_is_not_called_separated() {
    // Two 5 × 5 squares in a 10 × 5 room fit only side by side; in a
    // 9 × 5 room the separator must give up and say so.
    let (items, _) = constructive();
    let sq = 2;
    let mut kit = Kit::new(&items, vec![false; items.len()], 1e-9);
    kit.size = vec![10.0; items.len()];
    kit.pen = vec![5.0; items.len()];
    let piece = |x: f64| Piece {
        item: sq,
        variant: 0,
        t: Point::new(x, 0.0),
        shape: items[sq].variants[0].shape.moved(Point::new(x, 0.0)),
        turn: false,
    };
    let room = |x1: f64| crate::nest::place::Container {
        x0: 0.0,
        y0: 0.0,
        x1,
        y1: 5.0,
    };
    let mut rng = SplitMix(3);
    let mut lay = Layout {
        pieces: vec![piece(0.0), piece(4.0)],
        room: room(9.0),
        bays: Vec::new(),
    };
    let mut n = 0;
    let mut budget = || {
        n += 1;
        n < 2_000
    };
    assert!(!separate(&mut kit, &mut lay, &mut rng, &mut budget, 40).0);
    let mut lay = Layout {
        pieces: vec![piece(0.0), piece(4.0)],
        room: room(10.0),
        bays: Vec::new(),
    };
    let mut n = 0;
    let mut budget = || {
        n += 1;
        n < 2_000
    };
    assert!(separate(&mut kit, &mut lay, &mut rng, &mut budget, 40).0);
    assert!(feasible(&kit, &lay));
    let xs: Vec<f64> = lay.pieces.iter().map(|p| p.t.x).collect();
    assert!((xs[0] - xs[1]).abs() >= 5.0 - 1e-9, "{xs:?}");
}

#[test]
fn a_copy_in_a_hole_moves_with_its_host() {
    use crate::nest::decode::HoleBin;
    use crate::nest::place::{Bin, Container, Placed};
    let (items, _) = constructive();
    let placed = |item: usize, t: Point| Placed {
        item,
        variant: 0,
        t,
        shape: items[item].variants[0].shape.moved(t),
    };
    let mut sheet = Bin::new(Container {
        x0: 0.0,
        y0: 0.0,
        x1: f64::INFINITY,
        y1: HEIGHT,
    });
    sheet.placed = vec![
        placed(2, Point::new(0.0, 0.0)),
        placed(8, Point::new(5.0, 0.0)),
    ];
    sheet.right = 9.0;
    // A guest (the 3 × 3) "in a hole" of the 5 × 5, and one in a hole
    // of that guest: both go where the 5 × 5 goes.
    let hole = |host: At, t: Point| HoleBin {
        bin: {
            let mut b = Bin::new(Container::EVERYWHERE);
            b.placed = vec![placed(7, t)];
            b
        },
        sheet: 0,
        host,
    };
    let d = Decoded {
        bins: vec![sheet],
        holes: vec![
            hole(At::Sheet(0, 0), Point::new(1.0, 1.0)),
            hole(At::Hole(0, 0), Point::new(1.5, 1.5)),
            hole(At::Sheet(0, 1), Point::new(6.0, 1.0)),
        ],
        unplaced: Vec::new(),
        stopped: Vec::new(),
        work: 0,
        cost: (0, 1, 9.0),
        gravity: 0.0,
    };
    let mut lay = layout(&d, 0);
    // The 5 × 5 holds copies: it keeps its turn; so does the 4 × 4.
    assert!(!lay.pieces[0].turn && !lay.pieces[1].turn);
    let dt = Point::new(9.0, 2.0);
    lay.pieces[0].t = lay.pieces[0].t.add(dt);
    lay.pieces[0].shape = lay.pieces[0].shape.moved(dt);
    lay.room.x1 = 14.0;
    let e = decoded(d, 0, &lay, 0.0);
    assert_eq!(e.holes[0].bin.placed[0].t, Point::new(10.0, 3.0));
    assert_eq!(e.holes[1].bin.placed[0].t, Point::new(10.5, 3.5));
    assert_eq!(e.holes[2].bin.placed[0].t, Point::new(6.0, 1.0));
    assert_eq!(
        e.holes[0].bin.placed[0].shape.bbox().min,
        Point::new(10.0, 3.0)
    );
    assert_eq!(e.cost.2, 14.0);
    assert_eq!(e.bins[0].right, 14.0);
}

#[test]
fn a_run_that_still_cuts_the_overlap_is_no_strike() {
    // 2 % less overlap or more: the count starts again.
    assert_eq!(strikes_after(2, 10.0, 9.7), 0);
    assert_eq!(strikes_after(0, 1.0, 0.0), 0);
    // Less than that (or none): one strike more.
    assert_eq!(strikes_after(0, 10.0, 9.9), 1);
    assert_eq!(strikes_after(2, 10.0, 10.0), 3);
}

/// A layout of the test's rectangles `which`, at the translations `at`,
/// in a room `x1` long.
fn rect_layout(items: &[Item], which: &[(usize, f64, f64)], x1: f64) -> Layout {
    Layout {
        pieces: which
            .iter()
            .map(|&(item, x, y)| {
                let t = Point::new(x, y);
                Piece {
                    item,
                    variant: 0,
                    t,
                    shape: items[item].variants[0].shape.moved(t),
                    turn: true,
                }
            })
            .collect(),
        room: crate::nest::place::Container {
            x0: 0.0,
            y0: 0.0,
            x1,
            y1: HEIGHT,
        },
        bays: Vec::new(),
    }
}

#[test]
fn the_pool_keeps_the_least_overlapping_and_picks_them_most() {
    let (items, _) = constructive();
    let mut pool = explore::Pool::new(3);
    assert!(pool.pick(&mut SplitMix(1)).is_none());
    // Layouts told apart by the x of their one copy; overlaps 4, 1, 3, 2.
    for (x, o) in [(4.0, 4.0), (1.0, 1.0), (3.0, 3.0), (2.0, 2.0)] {
        pool.add(o, &rect_layout(&items, &[(2, x, 0.0)], 20.0));
    }
    let mut seen = [0usize; 5];
    let mut rng = SplitMix(5);
    for _ in 0..3000 {
        let x = pool.pick(&mut rng).unwrap().pieces[0].t.x;
        seen[x as usize] += 1;
    }
    // The worst (4) is not kept; the better, the more often picked.
    assert_eq!(seen[4], 0);
    assert!(
        seen[1] > seen[2] && seen[2] > seen[3] && seen[3] > 0,
        "{seen:?}"
    );
    assert_eq!(pool.layouts_mut().count(), 3);
    pool.clear();
    assert!(pool.pick(&mut rng).is_none());
}

#[test]
fn a_swap_exchanges_two_large_copies_of_different_parts_inside_the_room() {
    let (items, _) = constructive();
    let kit = Kit::new(&items, vec![false; items.len()], 1e-9);
    // Areas 25, 24, 21, 21, 16, 16, 16, 9: the copy at the three-quarter
    // mark is the 4 × 6 (24), so the large ones are it and the 5 × 5.
    let all: Vec<(usize, f64, f64)> = [2, 3, 0, 1, 8, 6, 5, 7]
        .iter()
        .map(|&i| (i, 0.0, 0.0))
        .collect();
    let lay = rect_layout(&items, &all, 18.0);
    assert_eq!(explore::large_copies(&kit, &lay.pieces), vec![0, 1]);
    // The 5 × 5 goes where the 4 × 6's centre was, (16, 7), pushed in by
    // the room's right wall; the 4 × 6 to (2.5, 2.5), pushed up by the
    // floor. The 4 × 4 stays.
    let mut lay = rect_layout(
        &items,
        &[(2, 0.0, 0.0), (8, 5.0, 0.0), (3, 14.0, 4.0)],
        18.0,
    );
    assert!(explore::swap_large(&mut lay, &[0, 2], &mut SplitMix(9)));
    let t: Vec<Point> = lay.pieces.iter().map(|p| p.t).collect();
    assert_eq!(
        t,
        vec![
            Point::new(13.0, 4.5),
            Point::new(5.0, 0.0),
            Point::new(0.5, 0.0)
        ]
    );
    for (k, p) in lay.pieces.iter().enumerate() {
        assert_eq!(p.shape.bbox().min, p.t);
        assert!(!kit.outside(&lay, k));
    }
    // Copies of one part only: nothing to swap.
    let mut same = rect_layout(&items, &[(2, 0.0, 0.0), (2, 6.0, 0.0)], 18.0);
    assert!(!explore::swap_large(&mut same, &[0, 1], &mut SplitMix(9)));
    assert_eq!(same.pieces[1].t, Point::new(6.0, 0.0));
}

/// Issue 44 item 3: the nine rectangles (area 172) on sheets 20.5 × 10
/// (area 205): one sheet is the least any nest can use (the area bound),
/// and the first nest, filling sheets in order, takes two. The sheets
/// shortened as bays of one strip (bays.rs): the copies of the second
/// cross into the first, and one sheet is left, every box apart and
/// inside it.
#[test]
fn the_copies_of_the_last_sheet_move_onto_the_earlier_one_down_to_the_area_bound() {
    let (items, _) = constructive();
    let start = decode(&items, &by_area(), &on_sheets(20.5, 3), 1e-9);
    let area: f64 = RECTS.iter().map(|r| r.0 * r.1).sum();
    let bound = (area / (20.5 * HEIGHT)).ceil() as usize;
    assert_eq!(bound, 1);
    assert!(
        start.bins.len() > bound,
        "the first nest already has {}",
        start.bins.len()
    );
    let after = improved(&items, start, 30_000);
    assert_eq!(after.bins.len(), bound, "sheets: {:?}", after.cost);
    assert_eq!(after.cost.1, bound);
    let len = check(&items, &after);
    assert!(len <= 20.5 + 1e-9, "{len}");
}

/// The nine rectangles of the test above on one sheet 20.5 × 10 only:
/// the first nest leaves copies out (it took two sheets above), and the
/// separation drops them onto the sheet until every copy is on it.
#[test]
fn copies_left_out_of_the_first_nest_are_separated_onto_the_sheets() {
    let (items, _) = constructive();
    let start = decode(&items, &by_area(), &on_sheets(20.5, 1), 1e-9);
    assert!(
        !start.unplaced.is_empty(),
        "the first nest placed every copy"
    );
    assert!(start.cost.0 > 0);
    let after = improved(&items, start, 30_000);
    assert!(after.unplaced.is_empty(), "left out: {:?}", after.unplaced);
    assert_eq!(after.cost.0, 0);
    assert_eq!(after.bins.len(), 1);
    let placed: usize = after.bins.iter().map(|b| b.placed.len()).sum();
    assert_eq!(placed, RECTS.len());
    let len = check(&items, &after);
    assert!(len <= 20.5 + 1e-9, "{len}");
}

/// Fixed sheets 20 × 10: the first holds seven 5 × 5 squares and a gap of
/// one more at its top right; the last holds a 3 × 3 and, right of it, a
/// 4 × 4 that fits the gap. The first thing the exploration does is offer
/// the last sheet's copies, the one furthest right first, to the earlier
/// sheets (relocate.rs): the 4 × 4 goes into the gap, in one placer call,
/// and the last sheet is 3 long. (The exploration alone, a move at a time,
/// needs far more than the two evaluations allowed here.)
#[test]
fn a_copy_of_the_last_sheet_goes_into_a_gap_of_an_earlier_one() {
    let (items, _) = constructive();
    let order: Vec<(usize, Option<usize>)> = [2, 2, 2, 2, 2, 2, 2, 8, 7]
        .into_iter()
        .map(|i| (i, None))
        .collect();
    let mut start = decode(&items, &order, &on_sheets(20.0, 3), 1e-9);
    // The 4 × 4 went into the gap: moved to the last sheet, right of the 3 × 3.
    assert_eq!(start.bins.len(), 2);
    assert_eq!(start.bins[0].placed.len(), 8);
    let mut four = start.bins[0].placed.pop().unwrap();
    assert_eq!(four.item, 8);
    let gap = four.t;
    let to = Point::new(3.0, 0.0);
    four.shape = four.shape.moved(to.sub(four.t));
    four.t = to;
    start.bins[1].placed.push(four);
    start.bins[1].right = 7.0;
    start.cost.2 = 7.0;
    let after = improved(&items, start, 3);
    assert_eq!(after.cost, (0, 2, 3.0));
    // Every box apart and inside its sheet; the 4 × 4 in the gap.
    for bin in &after.bins {
        let boxes: Vec<(f64, f64, f64, f64)> = bin
            .placed
            .iter()
            .map(|p| {
                let (w, h) = RECTS[items[p.item].part];
                (p.t.x, p.t.y, p.t.x + w, p.t.y + h)
            })
            .collect();
        let e = 1e-6;
        for (i, a) in boxes.iter().enumerate() {
            assert!(
                a.0 >= -e && a.1 >= -e && a.2 <= 20.0 + e && a.3 <= HEIGHT + e,
                "{a:?}"
            );
            for b in &boxes[i + 1..] {
                let apart = a.2 <= b.0 + e || b.2 <= a.0 + e || a.3 <= b.1 + e || b.3 <= a.1 + e;
                assert!(apart, "{a:?} overlaps {b:?}");
            }
        }
    }
    let four = after.bins[0].placed.iter().find(|p| p.item == 8).unwrap();
    assert!(
        (four.t.x - gap.x).abs() <= 1.0 && (four.t.y - gap.y).abs() <= 1.0,
        "{:?}",
        four.t
    );
    assert_eq!(after.bins[1].placed.len(), 1);
}

/// Fixed sheets: a cut starts in the last sheet or in the one before it
/// ([`bays::Bays::x0_back`]), so whichever the cut, the copies of the
/// sheets before those two stay as they are, and the strip is closed at
/// the length tried.
#[test]
fn a_cut_on_fixed_sheets_leaves_the_sheets_before_the_last_two_as_they_are() {
    let (items, _) = constructive();
    let d = decode(&items, &by_area(), &on_sheets(8.5, 6), 1e-9);
    let last = d.bins.len() - 1;
    assert!(last >= 2, "{} sheets", d.bins.len());
    let bays = bays::Bays::of(&d).unwrap();
    let lay = bays.layout(&d);
    let len = length(&lay);
    let rooms = bays.rooms();
    assert_eq!(bays.x0_back(len, 0), rooms[last].x0);
    assert_eq!(bays.x0_back(len, 1), rooms[last - 1].x0);
    assert_eq!(bays.x0_back(len, last + 3), rooms[0].x0);
    let wall = rooms[last - 1].x0;
    let before = lay
        .pieces
        .iter()
        .filter(|p| p.shape.bbox().max.x <= wall)
        .count();
    assert!(before > 0);
    for seed in 0..20 {
        let mut work = lay.clone();
        let target = len - 0.2 * (len - rooms[last].x0);
        shrink(&mut work, target, bays.x0_back(len, 1), &mut SplitMix(seed));
        for (a, b) in lay.pieces.iter().zip(&work.pieces) {
            if a.shape.bbox().max.x <= wall {
                assert_eq!(a.t, b.t, "seed {seed}");
            }
        }
        assert!(length(&work) <= target + 1e-9, "seed {seed}");
    }
}
