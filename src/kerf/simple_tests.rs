//! Tests of `kerf::simple`: the short way against cavalier_contours' whole
//! offset and its indexed self-intersection search, bit for bit, on random
//! loops of every kind a sheet holds (and some it should not).

use super::*;
use crate::kerf::bounds::area_exceeds;
use cavalier_contours::polyline::{PlineCreation, PlineSourceMut};

use crate::test_rng::Xorshift as Rng;

fn closed(v: &[(f64, f64, f64)]) -> Polyline<f64> {
    let mut pl = Polyline::with_capacity(v.len(), true);
    for &(x, y, b) in v {
        pl.add(x, y, b);
    }
    pl
}

/// A random loop: a rectangle (the nest's parts), a circle as two
/// half-circle arcs (its holes), a slot, a convex polygon with some edges
/// bulged out, a lens or a triangle of arcs, or a star whose edges bulge
/// either way (concave, sometimes crossing itself); on round numbers or
/// not, at any start, either way round.
fn random_loop(r: &mut Rng) -> Polyline<f64> {
    let round = r.unit() < 0.5;
    let at = |v: f64| {
        if round {
            (v * 1000.0).round() / 1000.0
        } else {
            v
        }
    };
    let (cx, cy) = (r.range(-500.0, 2000.0), r.range(-500.0, 2000.0));
    let (cx, cy) = (at(cx), at(cy));
    let mut v: Vec<(f64, f64, f64)> = match r.below(7) {
        0 => {
            let (w, h) = (r.range(0.5, 150.0), r.range(0.5, 90.0));
            let (w, h) = (at(w), at(h));
            vec![
                (cx, cy, 0.0),
                (cx + w, cy, 0.0),
                (cx + w, cy + h, 0.0),
                (cx, cy + h, 0.0),
            ]
        }
        1 => {
            let rad = at(r.range(0.3, 40.0));
            let a = if r.unit() < 0.5 {
                0.0
            } else {
                r.range(0.0, std::f64::consts::TAU)
            };
            let (c, s) = (a.cos() * rad, a.sin() * rad);
            vec![(cx + c, cy + s, 1.0), (cx - c, cy - s, 1.0)]
        }
        2 => {
            let (l, h) = (r.range(1.0, 60.0), r.range(0.5, 10.0));
            vec![
                (cx, cy, 0.0),
                (cx + l, cy, 1.0),
                (cx + l, cy + h, 0.0),
                (cx, cy + h, 1.0),
            ]
        }
        3 => {
            let n = 3 + r.below(14);
            let (rx, ry) = (r.range(0.5, 80.0), r.range(0.5, 80.0));
            let mut ang: Vec<f64> = (0..n)
                .map(|_| r.range(0.0, std::f64::consts::TAU))
                .collect();
            ang.sort_by(f64::total_cmp);
            ang.iter()
                .map(|a| {
                    let b = if r.unit() < 0.3 {
                        r.range(0.0, 0.4)
                    } else {
                        0.0
                    };
                    (cx + rx * a.cos(), cy + ry * a.sin(), b)
                })
                .collect()
        }
        4 | 5 => {
            // A lens or a triangle, its sides bulged either way: raw
            // offsets whose neighbouring pieces cross, or that pass too
            // close to the other side.
            let n = 2 + r.below(2);
            let size = r.range(0.5, 20.0);
            (0..n)
                .map(|i| {
                    let a = i as f64 / n as f64 * std::f64::consts::TAU + r.range(-0.5, 0.5);
                    let b = r.range(-1.0, 1.0);
                    (cx + size * a.cos(), cy + size * a.sin(), b)
                })
                .collect()
        }
        _ => {
            let n = 3 + r.below(60);
            (0..n)
                .map(|i| {
                    let a = i as f64 / n as f64 * std::f64::consts::TAU + r.range(-0.6, 0.6);
                    let rad = r.range(0.2, 50.0);
                    let b = if r.unit() < 0.4 {
                        r.range(-1.0, 1.0)
                    } else {
                        0.0
                    };
                    (cx + rad * a.cos(), cy + rad * a.sin(), b)
                })
                .collect()
        }
    };
    let k = r.below(v.len());
    v.rotate_left(k);
    if r.unit() < 0.5 {
        // The other way round: each bulge moves to the segment's new start.
        let n = v.len();
        v = (0..n)
            .map(|i| {
                let (x, y, _) = v[n - 1 - i];
                let (_, _, b) = v[(2 * n - 2 - i) % n];
                (x, y, -b)
            })
            .collect();
    }
    closed(&v)
}

fn bits(pl: &Polyline<f64>) -> (bool, Vec<[u64; 3]>) {
    (
        pl.is_closed(),
        (0..pl.vertex_count())
            .map(|i| {
                let v = pl.at(i);
                [v.x.to_bits(), v.y.to_bits(), v.bulge.to_bits()]
            })
            .collect(),
    )
}

/// The same loops, vertex for vertex, within 1e-9 mm (and bulge): the
/// short way's raw offset is built from the geometry, not by the
/// library's arithmetic, so the two differ by rounding only.
fn near(got: &[Polyline<f64>], want: &[Polyline<f64>]) -> bool {
    got.len() == want.len()
        && got.iter().zip(want).all(|(a, b)| {
            a.is_closed() == b.is_closed()
                && a.vertex_count() == b.vertex_count()
                && (0..a.vertex_count()).all(|i| {
                    let (u, v) = (a.at(i), b.at(i));
                    (u.x - v.x).abs() <= 1e-9
                        && (u.y - v.y).abs() <= 1e-9
                        && (u.bulge - v.bulge).abs() <= 1e-9
                })
        })
}

fn options() -> PlineOffsetOptions<'static, f64> {
    PlineOffsetOptions {
        pos_equal_eps: 1e-5,
        ..Default::default()
    }
}

#[test]
fn the_short_way_gives_cavalier_contours_offset() {
    let mut r = Rng(0x5DEE_CE66_D1CE_4E5B);
    let (mut short, mut tried, mut shapes) = (0, 0, [0usize; 2]);
    // One buffer for every loop, as `kerf::offset` reuses it.
    let mut reused = Scratch::default();
    for _ in 0..6000 {
        let pl = random_loop(&mut r);
        let pl = pl.remove_repeat_pos(1e-3).unwrap_or(pl);
        if pl.vertex_count() < 2 {
            continue;
        }
        let d = r.range(0.01, 4.0) * if r.unit() < 0.5 { 1.0 } else { -1.0 };
        let want: Vec<Polyline<f64>> = pl.parallel_offset_opt(d, &options());
        tried += 1;
        if let Some(got) = short_way(&pl, d, &options()) {
            short += 1;
            shapes[usize::from(pl.vertex_count() > 4)] += 1;
            assert!(near(&got, &want), "offset {d} of {pl:?}: {got:?} {want:?}");
        }
        // As `kerf::offset` calls it: clean when nothing repeats at 1e-3.
        let clean = pl.remove_repeat_pos(1e-3).is_none();
        let into = short_way_into(&pl, d, &options(), clean, &mut reused);
        if let Some(one) = into {
            let got = if one {
                vec![reused.offset().clone()]
            } else {
                vec![]
            };
            assert!(near(&got, &want), "offset {d} of {pl:?}");
        }
        assert!(near(&offset_closed(&pl, d, &options()), &want));
    }
    // Not vacuous: most rectangles, circles and slots, and some of the
    // polygons, take the short way; the rest the library's.
    assert!(short > tried / 3 && short < tried, "{short} of {tried}");
    assert!(shapes[0] > 500 && shapes[1] > 50, "{shapes:?}");
}

#[test]
fn crossings_are_those_of_the_indexed_search() {
    let mut r = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut crossed, mut n) = (0, 0);
    for _ in 0..6000 {
        let pl = random_loop(&mut r);
        let pl = pl.remove_repeat_pos(1e-3).unwrap_or(pl);
        let mut want = Vec::new();
        let index = pl.create_aabb_index();
        pl.visit_self_intersects_opt(
            &mut |x: PlineIntersect<f64>| match x {
                PlineIntersect::Basic(b) => want.push(Point::new(b.point.x, b.point.y)),
                PlineIntersect::Overlapping(o) => {
                    want.push(Point::new(o.point1.x, o.point1.y));
                    want.push(Point::new(o.point2.x, o.point2.y));
                }
            },
            &PlineSelfIntersectOptions {
                aabb_index: Some(&index),
                pos_equal_eps: 1e-5,
                include: SelfIntersectsInclude::All,
            },
        );
        let got = crossings(&pl, 1e-5);
        let b = |v: &[Point]| -> Vec<(u64, u64)> {
            v.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
        };
        assert_eq!(b(&got), b(&want), "{pl:?}");
        crossed += usize::from(!want.is_empty());
        n += 1;
    }
    // Both answers occur: loops that cross themselves and loops that do not.
    assert!(crossed > n / 20 && crossed < n / 2, "{crossed} of {n}");
}

#[test]
fn a_loop_too_long_for_the_pair_test_goes_the_librarys_way() {
    // A 100-gon: the boxes are not compared pair by pair, the answer is the same.
    let v: Vec<(f64, f64, f64)> = (0..100)
        .map(|i| {
            let a = i as f64 / 100.0 * std::f64::consts::TAU;
            (50.0 * a.cos(), 50.0 * a.sin(), 0.0)
        })
        .collect();
    let pl = closed(&v);
    assert_eq!(short_way(&pl, -0.75, &options()).map(|v| v.len()), None);
    let got: Vec<_> = offset_closed(&pl, -0.75, &options())
        .iter()
        .map(bits)
        .collect();
    let want: Vec<_> = pl
        .parallel_offset_opt(-0.75, &options())
        .iter()
        .map(bits)
        .collect();
    assert_eq!(got, want);
    // A square takes the short way both ways.
    let sq = closed(&[
        (0.0, 0.0, 0.0),
        (10.0, 0.0, 0.0),
        (10.0, 10.0, 0.0),
        (0.0, 10.0, 0.0),
    ]);
    for d in [-0.75, 0.75] {
        assert_eq!(short_way(&sq, d, &options()).map(|v| v.len()), Some(1));
    }
}

#[test]
fn a_raw_offset_too_close_to_its_source_is_dropped_as_the_library_drops_it() {
    // A triangle of arcs (found by the random search above, 1 in ~50,000):
    // its raw offset crosses nothing, but its first vertex is nearer the
    // source than the offset, so the library keeps no slice of it.
    let pl = closed(&[
        (1202.9128589028298, 718.0444787172332, 0.32239796956231626),
        (1201.9977903320796, 716.7608017992818, 0.49440934311786755),
        (1201.596498097667, 718.5486183762346, 0.26888746792244267),
    ]);
    let d = -0.5762827557544686;
    assert!(pl.parallel_offset_opt(d, &options()).is_empty());
    assert_eq!(short_way(&pl, d, &options()).map(|v| v.len()), Some(0));
}

#[test]
fn the_area_test_without_atan_is_the_librarys() {
    // Random loops at every scale from 1e-4 to 1 of their size, so that
    // their area falls on both sides of a tolerance's square and near it,
    // and their offsets: `area_exceeds` must answer as the library's area.
    let mut r = Rng(0xD1B5_4A32_D192_ED03);
    let (mut kept, mut n) = (0, 0);
    for _ in 0..20000 {
        let pl = random_loop(&mut r);
        let k = 10f64.powf(r.range(-4.0, 0.0));
        let mut small = Polyline::<f64>::with_capacity(pl.vertex_count(), true);
        let (x0, y0) = (pl.at(0).x, pl.at(0).y);
        for i in 0..pl.vertex_count() {
            let v = pl.at(i);
            small.add(x0 + (v.x - x0) * k, y0 + (v.y - y0) * k, v.bulge);
        }
        let limit = 1e-6;
        let d = 1e-4 * if r.unit() < 0.5 { 1.0 } else { -1.0 };
        let mut loops = vec![small.clone()];
        loops.extend(small.parallel_offset_opt(d, &options()));
        for l in &loops {
            let want = l.area().abs() > limit;
            assert_eq!(area_exceeds(l, limit), want, "{l:?}");
            kept += usize::from(want);
            n += 1;
        }
    }
    // Both answers occur.
    assert!(kept > n / 10 && kept < n * 9 / 10, "{kept} of {n}");
}

#[test]
fn a_loop_of_lines_meeting_at_corners_has_no_local_crossing() {
    // Random loops with their bulges dropped (rectangles, polygons, stars
    // that cross themselves), at scales from 1e-4 to 100 and up to 1e6 mm
    // out: where `lines_meet_at_corners` holds, the library's local search
    // finds nothing, and `crossings` is the indexed search's answer.
    let mut r = Rng(0x94D0_49BB_1331_11EB);
    let (mut held, mut n) = (0, 0);
    for _ in 0..20000 {
        let pl = random_loop(&mut r);
        let k = 10f64.powf(r.range(-4.0, 2.0));
        let far = [0.0, 1e3, 1e6][r.below(3)];
        let mut lines = Polyline::<f64>::with_capacity(pl.vertex_count(), true);
        for i in 0..pl.vertex_count() {
            let v = pl.at(i);
            lines.add(far + v.x * k, far + v.y * k, 0.0);
        }
        n += 1;
        if !lines_meet_at_corners(&lines, 1e-5) {
            continue;
        }
        held += 1;
        let mut found = 0;
        lines.visit_self_intersects_opt(
            &mut |_: PlineIntersect<f64>| found += 1,
            &PlineSelfIntersectOptions {
                aabb_index: None,
                pos_equal_eps: 1e-5,
                include: SelfIntersectsInclude::Local,
            },
        );
        assert_eq!(found, 0, "{lines:?}");
        let index = lines.create_aabb_index();
        let mut want = 0;
        lines.visit_self_intersects_opt(
            &mut |x: PlineIntersect<f64>| {
                want += match x {
                    PlineIntersect::Basic(_) => 1,
                    PlineIntersect::Overlapping(_) => 2,
                }
            },
            &PlineSelfIntersectOptions {
                aabb_index: Some(&index),
                pos_equal_eps: 1e-5,
                include: SelfIntersectsInclude::All,
            },
        );
        assert_eq!(crossings(&lines, 1e-5).len(), want, "{lines:?}");
    }
    // Not vacuous, and not everything (tiny loops' corners fail the bound).
    assert!(held > n / 3 && held < n, "{held} of {n}");
}

#[path = "raw_tests.rs"]
mod raw_tests;
