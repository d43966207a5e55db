//! Tests of `kerf::raw`: the raw offset built from the geometry
//! against the library's, and the local search it lets the short way skip.

use super::*;

#[test]
fn the_raw_offset_from_the_geometry_is_the_librarys() {
    // Random loops both ways, offsets out and in, through one reused
    // buffer as `kerf::offset` does; where the raw offset from the geometry
    // takes the loop (smooth meetings and outer corners only) it must be
    // `create_raw_offset`'s polyline up to rounding, with no segment
    // marked invalid.
    let mut r = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut raw, mut out) = (raw::RawOffset::default(), Polyline::<f64>::new());
    let (mut taken, mut tried, mut kinds) = (0, 0, [0usize; 2]);
    for _ in 0..20000 {
        let pl = random_loop(&mut r);
        let pl = pl.remove_repeat_pos(1e-3).unwrap_or(pl);
        if pl.vertex_count() < 2 {
            continue;
        }
        let d = r.range(0.01, 4.0) * if r.unit() < 0.5 { 1.0 } else { -1.0 };
        tried += 1;
        if raw.closed_into(&pl, d, 1e-5, &mut out) {
            taken += 1;
            let arcs = (0..pl.vertex_count()).any(|i| pl.at(i).bulge != 0.0);
            kinds[usize::from(arcs)] += 1;
            let want: RawOffsetResult<Polyline<f64>> = create_raw_offset(&pl, d, 1e-5);
            assert!(want.invalid_segment_indexes.is_empty(), "{d} {pl:?}");
            let (got, want) = ([out.clone()], [want.polyline]);
            assert!(near(&got, &want), "offset {d} of {pl:?}: {got:?} {want:?}");
        }
    }
    // Not vacuous: rectangles outwards, circles both ways, convex polygons
    // outwards; and not everything (inner joins go the library's way).
    assert!(taken > tried / 4 && taken < tried, "{taken} of {tried}");
    assert!(kinds[0] > 1000 && kinds[1] > 1000, "{kinds:?}");
}

/// A convex polygon of lines, counter-clockwise: a rectangle (thin or
/// not), or `n` points on an ellipse (up to 48, their corners nearly
/// straight), anywhere up to 1e5 mm out, sizes from 0.02 to 5,000 mm.
fn convex_polygon(r: &mut Rng) -> Polyline<f64> {
    let far = [1.0, 1e3, 1e5][r.below(3)];
    let (cx, cy) = (r.range(-far, far), r.range(-far, far));
    let size = |r: &mut Rng| 10f64.powf(r.range(-1.7, 3.7));
    let v: Vec<(f64, f64, f64)> = if r.unit() < 0.4 {
        let (w, h) = (size(r), size(r));
        vec![
            (cx, cy, 0.0),
            (cx + w, cy, 0.0),
            (cx + w, cy + h, 0.0),
            (cx, cy + h, 0.0),
        ]
    } else {
        let n = 3 + r.below(46);
        let (rx, ry) = (size(r), size(r));
        let mut ang: Vec<f64> = (0..n)
            .map(|_| r.range(0.0, std::f64::consts::TAU))
            .collect();
        ang.sort_by(f64::total_cmp);
        ang.iter()
            .map(|a| (cx + rx * a.cos(), cy + ry * a.sin(), 0.0))
            .collect()
    };
    let mut pl = closed(&v);
    if pl.area() < 0.0 {
        pl.invert_direction_mut();
    }
    pl
}

#[test]
fn a_raw_offset_of_lines_and_rounded_corners_has_no_local_crossing() {
    // `RawOffset::no_local_crossing` lets the short way skip the library's
    // local search: on every raw offset it accepts, that search (on this
    // raw offset and on the library's own) must find nothing, and the
    // short way's answer must still be the library's whole offset.
    let mut r = Rng(0x2545_F491_4F6C_DD1D);
    let (mut raw, mut out) = (raw::RawOffset::default(), Polyline::<f64>::new());
    let (mut skipped, mut tried) = (0, 0);
    let local = |pl: &Polyline<f64>| {
        let mut found = 0;
        pl.visit_self_intersects_opt(
            &mut |_: PlineIntersect<f64>| found += 1,
            &PlineSelfIntersectOptions {
                aabb_index: None,
                pos_equal_eps: 1e-5,
                include: SelfIntersectsInclude::Local,
            },
        );
        found
    };
    for _ in 0..20000 {
        let pl = convex_polygon(&mut r);
        let pl = pl.remove_repeat_pos(1e-3).unwrap_or(pl);
        if pl.vertex_count() < 3 {
            continue;
        }
        // Outwards (to the right of a counter-clockwise loop): kerfs from
        // 0.002 to 8 mm.
        let d = -10f64.powf(r.range(-3.0, 0.6));
        tried += 1;
        if !(raw.closed_into(&pl, d, 1e-5, &mut out) && raw.no_local_crossing()) {
            continue;
        }
        skipped += 1;
        assert_eq!(local(&out), 0, "offset {d} of {pl:?}");
        let lib: RawOffsetResult<Polyline<f64>> = create_raw_offset(&pl, d, 1e-5);
        assert_eq!(local(&lib.polyline), 0, "offset {d} of {pl:?}");
        let want = pl.parallel_offset_opt(d, &options());
        if let Some(got) = short_way(&pl, d, &options()) {
            assert!(near(&got, &want), "offset {d} of {pl:?}: {got:?} {want:?}");
        }
    }
    // Not vacuous: most of these loops are skipped.
    assert!(skipped > tried / 2, "{skipped} of {tried}");
}
