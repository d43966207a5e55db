#![cfg(not(target_arch = "wasm32"))]
//! The plan is the same with any number of threads (issue 17, src/par.rs):
//! a sheet big enough for every split of the plan stage (the cuts in
//! ranges of 4,096 visits, the tour's neighbour lists in ranges of 8,192
//! sites, the short schedule above 20,000 sites) planned with one thread
//! and with three (uneven chunks), compared field by field. Chunks joined
//! out of order, a builder's warnings lost or a different tour all show.

use kerfcam::contour::Contours;
use kerfcam::kerf::KerfPaths;
use kerfcam::par::Threads;
use kerfcam::plan::{self, CutPlan, FileOrder, Order, PlanInput, PlanOptions, Tabs};
use kerfcam::process::SmallHole;
use kerfcam::Settings;

/// `n` × `n` 40 × 30 plates 1 mm apart (little room for leads: some are
/// shortened or pierced on the contour), each with two Ø8 holes, a Ø3
/// hole (small) and a 2 × 20 slot; a marking line every 16th plate.
fn sheet(n: usize) -> Vec<u8> {
    let mut s = String::from(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n",
    );
    let poly = |s: &mut String, pts: &[(f64, f64)]| {
        *s += &format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", pts.len());
        for (x, y) in pts {
            *s += &format!("10\n{x}\n20\n{y}\n");
        }
    };
    for i in 0..n {
        for j in 0..n {
            let (x, y) = (i as f64 * 41.0, j as f64 * 31.0);
            poly(
                &mut s,
                &[(x, y), (x + 40.0, y), (x + 40.0, y + 30.0), (x, y + 30.0)],
            );
            for (cx, r) in [(x + 9.0, 4.0), (x + 31.0, 4.0), (x + 20.0, 1.5)] {
                s += &format!("0\nCIRCLE\n8\n0\n10\n{cx}\n20\n{}\n40\n{r}\n", y + 15.0);
            }
            let (sx, sy) = (x + 19.0, y + 5.0);
            poly(
                &mut s,
                &[
                    (sx, sy),
                    (sx + 2.0, sy),
                    (sx + 2.0, sy + 3.5),
                    (sx, sy + 3.5),
                ],
            );
            if (i * n + j).is_multiple_of(16) {
                s += &format!(
                    "0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
                    x + 2.0,
                    y + 25.0,
                    x + 12.0,
                    y + 25.0
                );
            }
        }
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

/// The plans of `options` with 1 and with 3 threads, equal field by field.
fn same_with_threads(
    c: &Contours,
    k: &KerfPaths,
    d: &kerfcam::dxf::Drawing,
    s: &Settings,
    options: &PlanOptions,
) -> CutPlan {
    let input = PlanInput {
        file: FileOrder::of(d),
        contours: c,
        kerf: k,
        tolerance: s.tolerance().mm(),
        process: s.process(),
    };
    let with = |t: usize| {
        let mut o = options.clone();
        o.threads = Threads::new(t);
        plan::plan(&input, &o)
    };
    let (one, three) = (with(1), with(3));
    assert_eq!(one.cuts.len(), three.cuts.len());
    for (i, (a, b)) in one.cuts.iter().zip(&three.cuts).enumerate() {
        assert_eq!(a.pierce, b.pierce, "cut {i}");
        assert_eq!(a.steps, b.steps, "cut {i}");
        assert_eq!(a.contours, b.contours, "cut {i}");
        assert_eq!(
            (a.part, a.kind, a.spot, a.small_hole, a.comp),
            (b.part, b.kind, b.spot, b.small_hole, b.comp),
            "cut {i}"
        );
    }
    assert_eq!(
        format!("{:?}", one.warnings),
        format!("{:?}", three.warnings)
    );
    assert_eq!(one.tour, three.tour);
    assert_eq!((one.origin, one.order), (three.origin, three.order));
    assert_eq!(one.common_line, three.common_line);
    one
}

#[test]
fn plans_are_the_same_with_one_and_three_threads() {
    let s = Settings::new(1.5, 0.001, 2000.0).expect("settings");
    let bytes = sheet(64);
    let d = kerfcam::dxf::parse(&bytes, s.read()).expect("parse");
    let c = kerfcam::contour::extract(&d, s.tolerance(), s.gap());
    let k = kerfcam::kerf::offset(&c, s.kerf(), s.tolerance());
    assert!(
        k.paths.len() > 20_000,
        "{} paths: too few to split",
        k.paths.len()
    );
    let s = s
        .with_small_hole(SmallHole {
            diameter: 5.0,
            speed_pct: 60.0,
            min_diameter: 0.0,
            overcut: 1.0,
        })
        .expect("small holes");
    let mut o = s.plan().clone();
    o.tabs = Tabs {
        count: 2,
        width: 1.0,
        holes: false,
    };
    o.cut_open = true;
    o.controller_comp = true;
    let p = same_with_threads(&c, &k, &d, &s, &o);
    // The sheet exercised what it is for: small holes, tabs, open cuts,
    // leads that gave way.
    let st = p.stats();
    assert!(st.small_holes > 0 && st.tabs > 0, "{st:?}");
    assert!(p
        .cuts
        .iter()
        .any(|c| c.kind == kerfcam::contour::ContourKind::Open));
    assert!(!p.warnings.is_empty());
    o.order = Order::Chained;
    o.controller_comp = false;
    let p = same_with_threads(&c, &k, &d, &s, &o);
    assert!(p.stats().chains > 0);
}
