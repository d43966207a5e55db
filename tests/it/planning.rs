#![cfg(not(target_arch = "wasm32"))]
//! Cut planning (issue 4): leads in scrap, directions, holes first, chained
//! links, over the fixtures, the corpus and generated nests.

use crate::common;

use kerfcam::contour::ContourKind;
use kerfcam::geom::{loop_area, Segment};
use kerfcam::plan::{CutPlan, LeadKind, Order, Role};
use kerfcam::{run, Output, Settings};

/// A sheet of `nx` × `ny` 40 × 30 rectangles, `gap` mm apart, each with two Ø8 holes.
fn nest(nx: usize, ny: usize, gap: f64) -> Vec<u8> {
    let mut s = String::from(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n",
    );
    for i in 0..nx {
        for j in 0..ny {
            let (x, y) = (i as f64 * (40.0 + gap), j as f64 * (30.0 + gap));
            s += "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n";
            for (px, py) in [(x, y), (x + 40.0, y), (x + 40.0, y + 30.0), (x, y + 30.0)] {
                s += &format!("10\n{px}\n20\n{py}\n");
            }
            for cx in [x + 10.0, x + 30.0] {
                s += &format!("0\nCIRCLE\n8\n0\n10\n{cx}\n20\n{}\n40\n4\n", y + 15.0);
            }
        }
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

/// Checks every contract of a contour or chained plan.
fn check_plan(out: &Output, tol: f64) {
    let plan: &CutPlan = &out.plan;
    // Faces that share edges are cut along their common lines, each line
    // once (issue 39 §6, tests/it/shared_edges.rs), not loop by loop: over
    // several trails, and a line two faces share under one's name.
    let face = |k: usize| out.contours.shared.contours.contains(&k);
    let mut cut_at = vec![usize::MAX; out.contours.contours.len()];
    let mut times_cut = vec![0usize; out.contours.contours.len()];
    for (i, c) in plan.cuts.iter().enumerate() {
        // Continuous from the pierce on.
        let mut at = c.pierce;
        for s in &c.steps {
            assert!(
                s.segment.a.dist(at) < 1e-6,
                "cut {i}: a gap before {:?}",
                s.segment
            );
            at = s.segment.b;
        }
        for &k in &c.contours {
            cut_at[k] = i;
            times_cut[k] += 1;
        }
        // Each contour's own steps form its closed loop, in the set direction.
        for &k in &c.contours {
            let segs: Vec<Segment> = c
                .steps
                .iter()
                .filter(|s| s.role == Role::Contour && s.contour == Some(k))
                .map(|s| s.segment)
                .collect();
            let kind = out.contours.contours[k].kind;
            if kind == ContourKind::Open || face(k) {
                continue;
            }
            assert!(segs.first().unwrap().a.dist(segs.last().unwrap().b) < 1e-6);
            let area = loop_area(&segs);
            match kind {
                ContourKind::Outer => assert!(area < 0.0, "outer contour {k} cut clockwise"),
                ContourKind::Hole => assert!(area > 0.0, "hole {k} cut counter-clockwise"),
                ContourKind::Open => {}
            }
        }
    }
    let cut: std::collections::HashSet<usize> = out.kerf.paths.iter().map(|p| p.contour).collect();
    for (k, c) in out.contours.contours.iter().enumerate() {
        if cut.contains(&k) && !face(k) {
            assert_eq!(times_cut[k], 1, "contour {k} cut once");
        }
        // Everything inside a contour is cut before it.
        if let Some(p) = c.parent {
            // Between two faces it is the Eulerian order's precedence.
            let faces = face(k) && (face(p) || cut_at[k] == usize::MAX);
            if cut.contains(&k) && cut.contains(&p) && !faces {
                assert!(cut_at[k] <= cut_at[p], "contour {k} before its parent {p}");
            }
        }
    }
    // Leads: a lead-in ends on its contour's start and its pierce point is in scrap.
    for c in &plan.cuts {
        if let Some(first) = c.steps.first() {
            if first.role == Role::LeadIn {
                assert!(first.segment.a.dist(c.pierce) < tol);
            }
        }
    }
}

#[test]
fn fixtures_and_corpus_give_plans_that_keep_every_contract() {
    let mut files: Vec<_> = common::corpus_files();
    for f in [
        "seed000-plate-6-holes.dxf",
        "seed001-P51703.dxf",
        "seed003-grid-3x2.dxf",
    ] {
        files.push(common::fixture(f));
    }
    // The corpus must be there (55 files): an empty folder would pass nothing.
    assert!(files.len() > 50, "corpus missing: {} files", files.len());
    let check = |name: &str, out: &Output| {
        // Faces that share edges in holes of faces: the whole drawing
        // in the Eulerian order (plan/shared.rs), whose contracts are
        // tests/eulerian.rs's.
        if out.plan.order == Order::Eulerian {
            assert!(
                out.warnings().any(|w| w.code == "shared-edges-eulerian"),
                "{name}"
            );
            return;
        }
        check_plan(out, 1e-6);
    };
    // The contour order at 1.5 mm: the corpus's shared run (issue 40: it
    // was run here once more), and the fixtures.
    for r in common::corpus_runs() {
        // Every corpus file reads: a failure is a failure, not a skip.
        let out = r.out.as_ref().unwrap_or_else(|e| panic!("{}: {e}", r.name));
        check(&r.name, out);
    }
    let corpus = files.len() - 3;
    for (k, f) in files.iter().enumerate() {
        let bytes = std::fs::read(f).unwrap();
        for order in [Order::Contour, Order::Chained] {
            if k < corpus && order == Order::Contour {
                continue;
            }
            let s = common::kerf(1.5).map_plan(|p| p.order = order).unwrap();
            let out = run(&bytes, &s).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
            check(&f.display().to_string(), &out);
        }
    }
}

#[test]
fn every_lead_kind_and_both_directions_keep_the_contracts_and_pass_rs274() {
    let bytes = std::fs::read(common::fixture("seed000-plate-6-holes.dxf")).unwrap();
    for kind in [
        LeadKind::Perpendicular,
        LeadKind::Tangential,
        LeadKind::Bisector,
        LeadKind::Arc,
        LeadKind::None,
    ] {
        let mut s = Settings::new(2.0, 0.001, 2000.0).unwrap();
        s = s.map_plan(|p| p.leads.kind = kind).unwrap();
        s = s.map_plan(|p| p.leads.overcut = 2.0).unwrap();
        let out = run(&bytes, &s).unwrap();
        check_plan(&out, 1e-6);
        let st = out.plan.stats();
        if kind == LeadKind::None {
            assert!((st.lead_length - 7.0 * 2.0).abs() < 1e-9, "overcuts only");
        } else {
            assert!(st.lead_length > 7.0 * 2.0, "{kind:?}: leads cut");
        }
        let errors = common::rs274_errors(&out.gcode, &format!("plate-{}", kind.name()));
        assert!(errors.is_empty(), "{kind:?}: {errors:?}");
    }
    // Reversed directions: G2 and G3 swap.
    let count = |g: &str, w: &str| g.lines().filter(|l| l.starts_with(w)).count();
    let mut s = Settings::new(2.0, 0.001, 2000.0).unwrap();
    s = s.map_plan(|p| p.leads.kind = LeadKind::None).unwrap();
    let a = run(&bytes, &s).unwrap().gcode;
    s = s.map_plan(|p| p.outer_ccw = true).unwrap();
    s = s.map_plan(|p| p.hole_ccw = false).unwrap();
    let b = run(&bytes, &s).unwrap().gcode;
    assert_eq!(count(&a, "G2 "), count(&b, "G3 "));
    assert_eq!(count(&a, "G3 "), count(&b, "G2 "));
}

#[test]
fn chained_order_saves_pierces_on_a_nest_and_its_links_are_short_and_clear() {
    let bytes = nest(5, 4, 10.0);
    let mut s = Settings::new(1.5, 0.001, 2000.0).unwrap();
    let single = run(&bytes, &s).unwrap();
    check_plan(&single, 1e-6);
    assert_eq!(single.plan.pierces(), 20 * 3);
    s = s.map_plan(|p| p.order = Order::Chained).unwrap();
    s = s.map_plan(|p| p.max_link = 30.0).unwrap();
    let chained = run(&bytes, &s).unwrap();
    check_plan(&chained, 1e-6);
    let st = chained.plan.stats();
    // Every hole keeps its own pierce; the 20 outers share a few.
    assert!(st.pierces < 60 && st.pierces > 40, "pierces {}", st.pierces);
    assert!(st.chains >= 1);
    for c in &chained.plan.cuts {
        for l in c.steps.iter().filter(|s| s.role == Role::Link) {
            assert!(l.segment.length() <= 30.0 + 1e-9);
        }
    }
    let errors = common::rs274_errors(&chained.gcode, "nest-chained");
    assert!(errors.is_empty(), "{errors:?}");
    // Nothing is linked when links may not be longer than the gaps between parts.
    s = s.map_plan(|p| p.max_link = 1.0).unwrap();
    assert_eq!(run(&bytes, &s).unwrap().plan.pierces(), 60);
}

#[test]
fn open_contours_are_cut_on_the_line_first_when_asked() {
    let bytes = std::fs::read(common::fixture("seed000-figure1.dxf")).unwrap();
    let mut s = Settings::new(0.0, 0.001, 2000.0).unwrap();
    let without = run(&bytes, &s).unwrap();
    s = s.map_plan(|p| p.cut_open = true).unwrap();
    let with = run(&bytes, &s).unwrap();
    assert_eq!(with.plan.pierces(), without.plan.pierces() + 1);
    assert_eq!(with.plan.cuts[0].kind, ContourKind::Open);
    let open_len: f64 = with.plan.cuts[0]
        .steps
        .iter()
        .map(|s| s.segment.length())
        .sum();
    let k = with.plan.cuts[0].contours[0];
    assert!((open_len - with.contours.contours[k].length).abs() < 1e-6);
}
