//! Issue 14: common-line cutting on kerf-compensated paths, and no torch-on
//! move through a part in any order. The checks here are independent of the
//! planner: parts as flattened polygons and the kerf disc swept along every
//! feed move (`common::sweep`), the postman's length of a kerf-spaced grid
//! from a graph built here from the grid's own geometry, and every program
//! through LinuxCNC's interpreter.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::collections::HashMap;

use common::sweep::{uncut_edges, worst_reach, Parts, SLACK};
use common::{fixture, kerf, rs274_errors, run};
use kerfcam::plan::{EulerMode, Order, Role};
use kerfcam::{Output, Settings};

const KERF: f64 = 1.5;

fn with_order(order: Order, width: f64) -> Settings {
    let mut s = kerf(width);
    s = s.map_plan(|p| p.order = order).unwrap();
    s = s.map_plan(|p| p.euler_mode = EulerMode::Repeat).unwrap();
    s
}

/// One closed LWPOLYLINE: (x, y, bulge to the next vertex).
fn lwpolyline(d: &mut String, v: &[(f64, f64, f64)]) {
    *d += &format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", v.len());
    for (x, y, b) in v {
        *d += &format!("10\n{x}\n20\n{y}\n42\n{b}\n");
    }
}

fn circle(d: &mut String, x: f64, y: f64, r: f64) {
    *d += &format!("0\nCIRCLE\n8\n0\n10\n{x}\n20\n{y}\n40\n{r}\n");
}

fn dxf(body: &str) -> Vec<u8> {
    format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n").into_bytes()
}

/// `cols × rows` rectangles `w × h`, spaced by `gap`.
fn grid(cols: usize, rows: usize, w: f64, h: f64, gap: f64) -> Vec<u8> {
    let mut d = String::new();
    for i in 0..cols {
        for j in 0..rows {
            let (x, y) = (i as f64 * (w + gap), j as f64 * (h + gap));
            lwpolyline(
                &mut d,
                &[
                    (x, y, 0.0),
                    (x + w, y, 0.0),
                    (x + w, y + h, 0.0),
                    (x, y + h, 0.0),
                ],
            );
        }
    }
    dxf(&d)
}

/// A 10 × 6 nest of 60 parts 50 × 40 spaced by `gap`, three kinds in turn:
/// a plate with a round hole, a plate with R6 corners and two holes, an L
/// (a 20 × 15 notch, concave corner) with a hole.
fn nest(gap: f64) -> Vec<u8> {
    let q = (std::f64::consts::PI / 8.0).tan(); // bulge of a quarter circle
    let mut d = String::new();
    for k in 0..60 {
        let (x, y) = (
            (k % 10) as f64 * (50.0 + gap),
            (k / 10) as f64 * (40.0 + gap),
        );
        match k % 3 {
            0 => {
                lwpolyline(
                    &mut d,
                    &[
                        (x, y, 0.0),
                        (x + 50.0, y, 0.0),
                        (x + 50.0, y + 40.0, 0.0),
                        (x, y + 40.0, 0.0),
                    ],
                );
                circle(&mut d, x + 25.0, y + 20.0, 8.0);
            }
            1 => {
                let r = 6.0;
                lwpolyline(
                    &mut d,
                    &[
                        (x + r, y, 0.0),
                        (x + 50.0 - r, y, q),
                        (x + 50.0, y + r, 0.0),
                        (x + 50.0, y + 40.0 - r, q),
                        (x + 50.0 - r, y + 40.0, 0.0),
                        (x + r, y + 40.0, q),
                        (x, y + 40.0 - r, 0.0),
                        (x, y + r, q),
                    ],
                );
                circle(&mut d, x + 15.0, y + 20.0, 4.0);
                circle(&mut d, x + 35.0, y + 20.0, 4.0);
            }
            _ => {
                lwpolyline(
                    &mut d,
                    &[
                        (x, y, 0.0),
                        (x + 50.0, y, 0.0),
                        (x + 50.0, y + 25.0, 0.0),
                        (x + 30.0, y + 25.0, 0.0),
                        (x + 30.0, y + 40.0, 0.0),
                        (x, y + 40.0, 0.0),
                    ],
                );
                circle(&mut d, x + 15.0, y + 15.0, 5.0);
            }
        }
    }
    dxf(&d)
}

/// The independent sweep check, for one order's output.
fn assert_no_cut_into_parts(out: &Output, width: f64, what: &str) {
    let parts = Parts::new(&out.contours);
    let (depth, at) = worst_reach(&out.plan, &parts, width);
    assert!(
        depth <= SLACK,
        "{what}: a torch-on move reaches {depth:.4} mm into a part at {at:?}"
    );
}

fn cases() -> Vec<(String, Vec<u8>)> {
    let file = |n: &str| std::fs::read(fixture(n)).unwrap();
    vec![
        ("plate".into(), file("seed000-plate-6-holes.dxf")),
        ("P51703".into(), file("seed001-P51703.dxf")),
        ("nest-60-gap6".into(), nest(6.0)),
        ("nest-60-kerf-spaced".into(), nest(KERF)),
    ]
}

#[test]
fn no_order_cuts_into_a_part_and_every_program_reads_in_rs274() {
    for (name, bytes) in cases() {
        for order in [Order::Contour, Order::Chained, Order::Eulerian] {
            let out = kerfcam::run(&bytes, &with_order(order, KERF)).unwrap();
            let what = format!("{name} {}", order.name());
            assert_no_cut_into_parts(&out, KERF, &what);
            // Sharp corners on the scrap side are rounded by any kerf (paper 000's invalid vertices).
            let uncut: Vec<_> = uncut_edges(&out.plan, &out.contours, KERF)
                .into_iter()
                .filter(|p| out.kerf.invalid_vertices.iter().all(|v| v.dist(*p) > KERF))
                .collect();
            assert!(
                uncut.is_empty(),
                "{what}: {} drawn points not cut to size, e.g. {:?}",
                uncut.len(),
                uncut.first()
            );
            let errors = rs274_errors(&out.gcode, &format!("common-line-{name}-{}", order.name()));
            assert!(errors.is_empty(), "{what}: {errors:?}");
            // The planner's own check agrees.
            let cmp = kerfcam::compare_orders(&out, &with_order(order, KERF), &[order]);
            assert!(
                !cmp[0].intrusion.cuts_parts(),
                "{what}: {:?}",
                cmp[0].intrusion
            );
        }
    }
}

#[test]
fn the_plate_is_cut_hole_by_hole_then_the_outline_with_no_link_through_it() {
    let out = run(
        &fixture("seed000-plate-6-holes.dxf"),
        &with_order(Order::Eulerian, KERF),
    )
    .unwrap();
    let st = out.plan.stats();
    assert_eq!((st.pierces, st.repeated_length), (7, 0.0), "{st:?}");
    // Each pierce in scrap with a lead-in (5 mm outside, 3 mm in the holes), no link.
    let roles: Vec<Role> = out
        .plan
        .cuts
        .iter()
        .flat_map(|c| c.steps.iter().map(|s| s.role))
        .collect();
    assert_eq!(roles.iter().filter(|r| **r == Role::LeadIn).count(), 7);
    assert!(!roles.contains(&Role::Link));
    assert!((st.lead_length - 23.0).abs() < 1e-9, "{st:?}");
    let last = out.plan.cuts.last().unwrap();
    assert_eq!(
        out.contours.contours[last.contours[0]].parent, None,
        "the outline is cut last"
    );
    // An overcut ends each closed circuit past its start, still in nothing but the path.
    let mut over = with_order(Order::Eulerian, KERF);
    over = over.map_plan(|p| p.leads.overcut = 2.0).unwrap();
    let o = run(&fixture("seed000-plate-6-holes.dxf"), &over).unwrap();
    assert!(
        (o.plan.stats().lead_length - (23.0 + 7.0 * 2.0)).abs() < 1e-9,
        "{:?}",
        o.plan.stats()
    );
    assert!(o
        .plan
        .cuts
        .iter()
        .all(|c| c.steps.last().is_some_and(|s| s.role == Role::LeadOut)));
    assert_no_cut_into_parts(&o, KERF, "plate with overcut");
    // The job header counts the contours cut, not the pierces.
    assert!(
        out.gcode.contains("cuts 7: outer 1, holes 6"),
        "{}",
        &out.gcode[..300]
    );
}

/// The kerf paths of a `cols × rows` grid of `w × h` rectangles spaced by
/// the kerf, built here: each part's path is 4 lines and 4 quarter arcs
/// (radius kerf/2) round it; coinciding lines between neighbours are one
/// edge. Returns (unique length, postman length) by brute-force matching.
fn postman_of_grid(cols: usize, rows: usize, w: f64, h: f64) -> (f64, f64) {
    let r = KERF / 2.0;
    let key = |x: f64, y: f64| ((x * 1e4).round() as i64, (y * 1e4).round() as i64);
    // (end, end, is an arc) → length.
    type Key = ((i64, i64), (i64, i64), i64);
    let mut edges: HashMap<Key, f64> = HashMap::new();
    let mut add = |a: (f64, f64), b: (f64, f64), arc: bool| {
        let (ka, kb) = (key(a.0, a.1), key(b.0, b.1));
        let (ka, kb) = if ka <= kb { (ka, kb) } else { (kb, ka) };
        let len = if arc {
            std::f64::consts::FRAC_PI_2 * r
        } else {
            ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
        };
        edges.insert((ka, kb, arc as i64), len);
    };
    for i in 0..cols {
        for j in 0..rows {
            let (x0, y0) = (i as f64 * (w + KERF), j as f64 * (h + KERF));
            let (x1, y1) = (x0 + w, y0 + h);
            add((x0, y0 - r), (x1, y0 - r), false);
            add((x1 + r, y0), (x1 + r, y1), false);
            add((x1, y1 + r), (x0, y1 + r), false);
            add((x0 - r, y1), (x0 - r, y0), false);
            add((x1, y0 - r), (x1 + r, y0), true);
            add((x1 + r, y1), (x1, y1 + r), true);
            add((x0, y1 + r), (x0 - r, y1), true);
            add((x0 - r, y0), (x0, y0 - r), true);
        }
    }
    let unique: f64 = edges.values().sum();
    let mut ids: HashMap<(i64, i64), usize> = HashMap::new();
    let mut list = Vec::new();
    for (&(a, b, _), &l) in &edges {
        let n = ids.len();
        let ia = *ids.entry(a).or_insert(n);
        let n = ids.len();
        let ib = *ids.entry(b).or_insert(n);
        list.push((ia, ib, l));
    }
    let n = ids.len();
    let mut dist = vec![vec![f64::INFINITY; n]; n];
    let mut degree = vec![0; n];
    for (i, row) in dist.iter_mut().enumerate() {
        row[i] = 0.0;
    }
    for &(a, b, l) in &list {
        degree[a] += 1;
        degree[b] += 1;
        dist[a][b] = dist[a][b].min(l);
        dist[b][a] = dist[b][a].min(l);
    }
    for k in 0..n {
        for i in 0..n {
            for j in 0..n {
                if dist[i][k] + dist[k][j] < dist[i][j] {
                    dist[i][j] = dist[i][k] + dist[k][j];
                }
            }
        }
    }
    let odd: Vec<usize> = (0..n).filter(|&v| degree[v] % 2 == 1).collect();
    let m = odd.len();
    assert!(m <= 20, "{m} odd vertices: too many for the brute force");
    // Minimum perfect matching over subsets: best[mask] pairs the odd vertices in mask.
    let mut best = vec![f64::INFINITY; 1 << m];
    best[0] = 0.0;
    for mask in 1usize..(1 << m) {
        if mask.count_ones() % 2 == 1 {
            continue;
        }
        let i = mask.trailing_zeros() as usize;
        for j in i + 1..m {
            if mask & (1 << j) != 0 {
                let rest = mask & !(1 << i) & !(1 << j);
                best[mask] = best[mask].min(best[rest] + dist[odd[i]][odd[j]]);
            }
        }
    }
    (unique, unique + best[(1 << m) - 1])
}

#[test]
fn a_kerf_spaced_grid_cuts_each_shared_path_once_at_the_postman_length() {
    for (cols, rows) in [(2, 1), (3, 2), (2, 3)] {
        let (w, h) = (300.0, 400.0);
        let out = kerfcam::run(
            &grid(cols, rows, w, h, KERF),
            &with_order(Order::Eulerian, KERF),
        )
        .unwrap();
        let what = format!("grid {cols}×{rows}");
        let st = out.plan.stats();
        let (unique, postman) = postman_of_grid(cols, rows, w, h);
        assert!(
            (st.cut_length - unique).abs() < 1e-6,
            "{what}: cut {} vs {unique}",
            st.cut_length
        );
        assert!(
            (st.cut_length + st.repeated_length - postman).abs() < 1e-6,
            "{what}: cut + repeated {} vs postman {postman}",
            st.cut_length + st.repeated_length
        );
        // One pierce, outside the grid, with the 5 mm lead-in; no link.
        assert_eq!((st.pierces, st.lead_length), (1, 5.0), "{what}: {st:?}");
        assert!(
            out.plan.warnings.is_empty(),
            "{what}: {:?}",
            out.plan.warnings
        );
        // Every part its drawn size: cut all round at half the kerf, never into.
        assert_no_cut_into_parts(&out, KERF, &what);
        assert!(
            uncut_edges(&out.plan, &out.contours, KERF).is_empty(),
            "{what}"
        );
        let errors = rs274_errors(&out.gcode, &format!("common-line-grid-{cols}x{rows}"));
        assert!(errors.is_empty(), "{what}: {errors:?}");
        // Against the contour order: each shared path cut twice there.
        let contour = kerfcam::run(
            &grid(cols, rows, w, h, KERF),
            &with_order(Order::Contour, KERF),
        )
        .unwrap();
        let cs = contour.plan.stats();
        let t = out.process;
        println!(
            "{what} kerf-spaced: eulerian cut {:.0} + repeated {:.0} + rapid {:.0} mm, {} pierce(s), {:.0} s; contour cut {:.0} + leads {:.0} + rapid {:.0} mm, {} pierces, {:.0} s",
            st.cut_length, st.repeated_length, st.rapid_length, st.pierces, st.est_time_s(&t),
            cs.cut_length, cs.lead_length, cs.rapid_length, cs.pierces, cs.est_time_s(&t)
        );
        assert!(
            st.cut_length + st.repeated_length <= cs.cut_length + 1e-6,
            "{what}"
        );
        assert!(st.est_time_s(&t) < cs.est_time_s(&t), "{what}");
    }
}

#[test]
fn the_report_lists_each_common_path_with_its_cut_direction_and_the_part_on_its_right() {
    let out = kerfcam::run(
        &grid(2, 1, 300.0, 400.0, KERF),
        &with_order(Order::Eulerian, KERF),
    )
    .unwrap();
    let part_at = |x: f64, y: f64| {
        out.contours
            .contours
            .iter()
            .find(|c| {
                c.parent.is_none()
                    && c.bbox.min.x <= x
                    && x <= c.bbox.max.x
                    && c.bbox.min.y <= y
                    && y <= c.bbox.max.y
            })
            .and_then(|c| c.part)
            .unwrap()
    };
    let (left, right) = (part_at(150.0, 200.0), part_at(450.0, 200.0));
    let report = kerfcam::report::Report::new(&out);
    let common = &report.plan.common_line;
    assert_eq!(common.len(), 1, "{common:?}");
    let c = &common[0];
    assert!(
        (c.length - 400.0).abs() < 1e-3 && (report.plan.common_line_length - 400.0).abs() < 1e-3,
        "{c:?}"
    );
    assert_eq!((c.from[0], c.to[0]), (300.75, 300.75));
    let mut parts = c.parts;
    parts.sort();
    assert_eq!(parts, {
        let mut p = [left, right];
        p.sort();
        p
    });
    // Going up x = 300.75, the right-hand side is the right part; going down, the left one.
    assert_eq!(
        c.right,
        if c.to[1] > c.from[1] { right } else { left },
        "{c:?}"
    );
    // The touching grid: its 2500 mm of common edges, each listed once.
    let touching = run(
        &fixture("seed003-grid-3x2.dxf"),
        &with_order(Order::Eulerian, KERF),
    )
    .unwrap();
    let r = kerfcam::report::Report::new(&touching);
    assert!(
        (r.plan.common_line_length - 2500.0).abs() < 1e-3,
        "{}",
        r.plan.common_line_length
    );
    assert!(r
        .plan
        .common_line
        .iter()
        .all(|c| c.right != 0 && c.parts[0] != c.parts[1]));
}

#[test]
fn touching_parts_are_warned_about_by_name_and_loss() {
    let out = run(
        &fixture("seed003-grid-3x2.dxf"),
        &with_order(Order::Eulerian, KERF),
    )
    .unwrap();
    let close: Vec<String> = out
        .plan
        .warnings
        .iter()
        .filter(|w| w.code == "parts-closer-than-kerf")
        .map(|w| w.message().to_string())
        .collect();
    // What the cuts take, summed over every order's cuts (issue 45 §1):
    // all six parts lose material along the shared edges.
    let (summary, close): (Vec<String>, Vec<String>) = close
        .into_iter()
        .partition(|m| m.starts_with("the cuts take"));
    assert_eq!(summary.len(), 1, "{summary:?}");
    assert!(
        summary[0].contains("6 part(s) (1, 2, 3, 4, 5, 6)"),
        "{summary:?}"
    );
    // The full sweep is named as the page's button and the CLI's flag.
    assert!(
        summary[0].contains("(Verify, or --verify, sweeps"),
        "{summary:?}"
    );
    // 7 shared edges, and 4 pairs meeting at a corner only.
    assert_eq!(close.len(), 11, "{close:?}");
    assert_eq!(
        close.iter().filter(|m| m.contains("share an edge")).count(),
        7,
        "{close:?}"
    );
    assert!(
        close
            .iter()
            .any(|m| m.contains("parts 1 and 2 share an edge: each loses 0.75 mm there")),
        "{close:?}"
    );
    // What is cut: the common edges once on the drawn line (2500 mm), the
    // kerf path round the outside of the grid, and a connector of half a
    // kerf from each of the 6 ends of common edges on the outside to it.
    let r = KERF / 2.0;
    let outside = 2.0 * (900.0 + 800.0) + 2.0 * std::f64::consts::PI * r;
    let st = out.plan.stats();
    assert!(
        (st.cut_length - (outside + 2500.0 + 6.0 * r)).abs() < 1e-6,
        "{st:?}"
    );
    assert_eq!(st.pierces, 1, "{st:?}");
    // Each part loses half the kerf along its common edges, and nothing more
    // anywhere (no third part cut into).
    let (depth, at) = worst_reach(&out.plan, &Parts::new(&out.contours), KERF);
    assert!((depth - r).abs() <= SLACK, "{depth} at {at:?}");
    assert!(uncut_edges(&out.plan, &out.contours, KERF).is_empty());
    let errors = rs274_errors(&out.gcode, "common-line-touching-grid");
    assert!(errors.is_empty(), "{errors:?}");
    // A partly common edge (x = 100, y 50 to 100), and a part touching only
    // a corner: never more than half the kerf taken, every edge cut.
    let mut d = String::new();
    lwpolyline(
        &mut d,
        &[
            (0.0, 0.0, 0.0),
            (100.0, 0.0, 0.0),
            (100.0, 100.0, 0.0),
            (0.0, 100.0, 0.0),
        ],
    );
    lwpolyline(
        &mut d,
        &[
            (100.0, 50.0, 0.0),
            (200.0, 50.0, 0.0),
            (200.0, 150.0, 0.0),
            (100.0, 150.0, 0.0),
        ],
    );
    lwpolyline(
        &mut d,
        &[
            (200.0, 150.0, 0.0),
            (250.0, 150.0, 0.0),
            (250.0, 200.0, 0.0),
            (200.0, 200.0, 0.0),
        ],
    );
    let partly = kerfcam::run(&dxf(&d), &with_order(Order::Eulerian, KERF)).unwrap();
    let (depth, at) = worst_reach(&partly.plan, &Parts::new(&partly.contours), KERF);
    assert!(depth <= KERF + SLACK, "{depth} at {at:?}");
    assert!(uncut_edges(&partly.plan, &partly.contours, KERF).is_empty());
    let m: Vec<&str> = partly.plan.warnings.iter().map(|w| w.message()).collect();
    assert!(
        m.iter()
            .any(|m| m.contains("parts 1 and 2 share an edge: each loses 0.75 mm")),
        "{m:?}"
    );
    assert!(
        m.iter()
            .any(|m| m.contains("parts 2 and 3 touch at a corner: each loses 1.5 mm")),
        "{m:?}"
    );
    // Spaced by the kerf: no warning; by less: the gap and the loss.
    let spaced = kerfcam::run(
        &grid(2, 1, 100.0, 100.0, KERF),
        &with_order(Order::Eulerian, KERF),
    )
    .unwrap();
    assert!(
        spaced.plan.warnings.is_empty(),
        "{:?}",
        spaced.plan.warnings
    );
    let near = kerfcam::run(
        &grid(2, 1, 100.0, 100.0, 1.0),
        &with_order(Order::Eulerian, KERF),
    )
    .unwrap();
    let m: Vec<String> = near
        .plan
        .warnings
        .iter()
        .map(|w| w.message().to_string())
        .collect();
    assert!(
        m.iter()
            .any(|m| m.contains("parts 1 and 2 are 1 mm apart") && m.contains("each loses 0.5 mm")),
        "{m:?}"
    );
    // And Compare says that every order cuts into those parts.
    let cmp = kerfcam::compare_orders(&out, &with_order(Order::Eulerian, KERF), &Order::ALL[..3]);
    for o in &cmp {
        assert!(o.intrusion.cuts_parts(), "{:?}", o);
    }
}

#[test]
fn kerf_spaced_nest_savings_against_the_contour_order() {
    let bytes = nest(KERF);
    let e = kerfcam::run(&bytes, &with_order(Order::Eulerian, KERF)).unwrap();
    let c = kerfcam::run(&bytes, &with_order(Order::Contour, KERF)).unwrap();
    let (es, cs) = (e.plan.stats(), c.plan.stats());
    let t = e.process;
    let feed = |s: &kerfcam::plan::PlanStats| s.cut_length + s.lead_length + s.repeated_length;
    println!(
        "nest 60 kerf-spaced: eulerian feed {:.0} mm (cut {:.0}, repeated {:.0}, links {:.0}), rapid {:.0} mm, {} pierces, {:.0} s; contour feed {:.0} mm, rapid {:.0} mm, {} pierces, {:.0} s",
        feed(&es), es.cut_length, es.repeated_length, es.lead_length, es.rapid_length, es.pierces, es.est_time_s(&t),
        feed(&cs), cs.rapid_length, cs.pierces, cs.est_time_s(&t)
    );
    assert!(es.cut_length < cs.cut_length);
    assert!(es.est_time_s(&t) < cs.est_time_s(&t));
    // Holes (60 + 20 of them) are each their own pierce.
    assert!(es.pierces >= 80, "{es:?}");
}
