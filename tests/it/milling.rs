//! Routers and mills (issue 43): a sign plate — a rectangular pocket with
//! four raised shapes standing in it (an I, an O whose counter is
//! pocketed too, an L, a triangle) and its outline profiled — machined
//! with a 6 mm end mill, each program read by rs274 and swept by the
//! independent checker of `common::mill_sweep`: no gouge, and at least
//! 99 % of what a 6 mm disc can reach cleared at full depth.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::mill_sweep::{samples, sweep, Cell, Grid};
use kerfcam::Spec;

const R: f64 = 3.0;
const DEPTH: f64 = 6.0;

fn lw(layer: &str, pts: &[(f64, f64)]) -> String {
    let mut s = format!("0\nLWPOLYLINE\n8\n{layer}\n90\n{}\n70\n1\n", pts.len());
    for (x, y) in pts {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s
}

const I: [(f64, f64); 4] = [(40.0, 40.0), (55.0, 40.0), (55.0, 110.0), (40.0, 110.0)];
const L: [(f64, f64); 6] = [
    (160.0, 40.0),
    (200.0, 40.0),
    (200.0, 55.0),
    (175.0, 55.0),
    (175.0, 110.0),
    (160.0, 110.0),
];
const TRI: [(f64, f64); 3] = [(220.0, 40.0), (270.0, 40.0), (245.0, 110.0)];
const OUTLINE: [(f64, f64); 4] = [(10.0, 10.0), (290.0, 10.0), (290.0, 140.0), (10.0, 140.0)];
const O: (f64, f64, f64, f64) = (110.0, 75.0, 30.0, 14.0);

fn sign() -> Vec<u8> {
    let mut e = lw(
        "PROFILE",
        &[(0.0, 0.0), (300.0, 0.0), (300.0, 150.0), (0.0, 150.0)],
    );
    e += &lw("POCKET", &OUTLINE);
    e += &lw("POCKET", &I);
    for r in [O.2, O.3] {
        e += &format!("0\nCIRCLE\n8\nPOCKET\n10\n{}\n20\n{}\n40\n{r}\n", O.0, O.1);
    }
    e += &lw("POCKET", &L);
    e += &lw("POCKET", &TRI);
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn inside(poly: &[(f64, f64)], x: f64, y: f64) -> bool {
    let mut c = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.1 > y) != (b.1 > y) && x < a.0 + (y - a.1) / (b.1 - a.1) * (b.0 - a.0) {
            c = !c;
        }
    }
    c
}

fn edge_dist(poly: &[(f64, f64)], x: f64, y: f64) -> f64 {
    (0..poly.len())
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let t = (((x - a.0) * dx + (y - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
            (x - a.0 - t * dx).hypot(y - a.1 - t * dy)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The part's cells from the shapes above (not from kerfcam's contours).
fn grid(cell: f64) -> Grid {
    let class = |x: f64, y: f64| {
        if !(0.0..=300.0).contains(&x) || !(0.0..=150.0).contains(&y) {
            return Cell::Outside;
        }
        let d = (x - O.0).hypot(y - O.1);
        let island =
            inside(&I, x, y) || inside(&L, x, y) || inside(&TRI, x, y) || (d < O.2 && d > O.3);
        if inside(&OUTLINE, x, y) && !island {
            Cell::Pocket
        } else {
            Cell::Keep
        }
    };
    let wall = |x: f64, y: f64| {
        let d = (x - O.0).hypot(y - O.1);
        [
            edge_dist(&OUTLINE, x, y),
            edge_dist(&I, x, y),
            edge_dist(&L, x, y),
            edge_dist(&TRI, x, y),
            (d - O.2).abs(),
            (d - O.3).abs(),
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min)
    };
    Grid::new((-5.0, -5.0), (305.0, 155.0), cell, class, wall)
}

fn spec(extra: impl FnOnce(&mut Spec)) -> Spec {
    let mut s = Spec {
        tool_diameter: Some(2.0 * R),
        depth: Some(DEPTH),
        pass_depth: 3.0,
        post: Some("grbl-router".into()),
        layer_ops: vec![
            ["POCKET".into(), "pocket".into()],
            ["PROFILE".into(), "profile".into()],
        ],
        ..Spec::default()
    };
    extra(&mut s);
    s
}

#[test]
fn a_sign_plate_is_cleared_around_its_letters_without_a_gouge_in_every_strategy() {
    let g = grid(0.25);
    type Variant = (&'static str, fn(&mut Spec));
    let variants: [Variant; 4] = [
        ("zigzag-plunge", |_| {}),
        ("offset-helix", |s| {
            s.pocket = "offset".into();
            s.entry = "helix".into();
            s.post = Some("linuxcnc-router".into());
        }),
        ("zigzag-ramp-30deg-allowance", |s| {
            s.entry = "ramp".into();
            s.pocket_angle = 30.0;
            s.allowance = 0.5;
        }),
        // Arc fitting: the runs of short moves as lines and arcs within
        // the tolerance, checked by the same sweep.
        ("offset-ramp-fitted", |s| {
            s.pocket = "offset".into();
            s.entry = "ramp".into();
            s.fit_arcs = true;
        }),
    ];
    for (name, set) in variants {
        let settings = spec(|s| {
            set(s);
            s.verify = true;
        })
        .build()
        .unwrap();
        let out = kerfcam::run(&sign(), &settings).unwrap();
        let errors = common::rs274_errors(&out.gcode, &format!("milling-{name}"));
        assert!(errors.is_empty(), "{name}: {errors:?}");
        let m = out.milled.as_ref().unwrap();
        let s = sweep(&g, &samples(&out.gcode, 0.1), R, -DEPTH, 0.05);
        let pct = 100.0 * s.cleared_mm2 / s.reachable_mm2;
        let lifts: Vec<usize> = m.pockets.iter().map(|p| p.lifts).collect();
        eprintln!(
            "{name}: {} lines, cleared {pct:.2} % of {:.0} mm² reachable ({:.0} mm² drawn), gouge {:.2} mm², lifts per pocket {lifts:?} (zig-zag {:?}), warnings {:?}",
            out.gcode.lines().count(),
            s.reachable_mm2,
            s.pocket_mm2,
            s.gouge_mm2,
            m.pockets.iter().map(|p| p.zigzag_lifts).collect::<Vec<_>>(),
            out.warnings().map(|w| w.code).collect::<Vec<_>>()
        );
        assert_eq!(s.gouge_mm2, 0.0, "{name}: gouge at {:?}", s.gouge_at);
        assert!(pct >= 99.0, "{name}: cleared {pct:.2} %");
        // kerfcam's own --verify sweep agrees: no gouge, nothing the tool
        // reaches left; what it cannot reach is the 5 inside corners (the
        // outline's 4, the L's 1), r² (1 − π/4) each. (The checker's own
        // figure for it is coarser: its reach is judged at cell centres.)
        let own = m.swept.as_ref().unwrap();
        eprintln!("{name}: --verify {own:?}");
        assert_eq!(own.gouge_mm2, 0.0, "{name}: --verify gouge at {:?}", own.gouge_at);
        assert_eq!(own.left_mm2, 0.0, "{name}: --verify left at {:?}", own.left_at);
        let corners = 5.0 * R * R * (1.0 - std::f64::consts::FRAC_PI_4);
        assert!((own.unreachable_mm2 - corners).abs() < 0.5, "{name}: {} vs {corners}", own.unreachable_mm2);
        assert!(!out.warnings().any(|w| w.code == "mill-gouge" || w.code == "mill-left"));
        let report = kerfcam::report::Report::new(&out);
        let milling = report.verification.unwrap().milling.unwrap();
        assert_eq!((milling.gouge_mm2, milling.left_mm2), (0.0, 0.0), "{name}");
        // Two pockets: the plate's (four islands) and the O's counter (none).
        assert_eq!(m.pockets.len(), 2, "{name}");
        let counter = m.pockets.iter().find(|p| p.area < 1000.0).unwrap();
        assert_eq!(
            counter.lifts, 0,
            "{name}: a pocket without islands never lifts"
        );
        let plate = m.pockets.iter().find(|p| p.area > 1000.0).unwrap();
        // Only islands block the zig-zag: at most one lift per island and depth.
        assert!(
            plate.zigzag_lifts <= 4 * 2,
            "{name}: {} zig-zag lifts",
            plate.zigzag_lifts
        );
        // Planted faults: a wider disc than the tool gouges the islands;
        // a narrower one leaves the walls standing.
        let wide = sweep(&g, &samples(&out.gcode, 0.1), R + 0.5, -DEPTH, 0.05);
        assert!(wide.gouge_mm2 > 0.0, "{name}: the checker misses a gouge");
        let narrow = sweep(&g, &samples(&out.gcode, 0.1), R - 1.0, -DEPTH, 0.05);
        assert!(
            narrow.cleared_mm2 / s.reachable_mm2 < 0.99,
            "{name}: the checker misses material left"
        );
    }
}

#[test]
fn milling_without_a_router_post_a_tool_or_a_depth_is_refused_by_name() {
    let no_post = spec(|s| s.post = None).build().unwrap();
    let e = kerfcam::run(&sign(), &no_post).unwrap_err();
    assert!(e.to_string().contains("router post"), "{e}");
    let no_tool = spec(|s| {
        s.tool_diameter = None;
        s.kerf = Some(6.0);
    })
    .build()
    .unwrap();
    let e = kerfcam::run(&sign(), &no_tool).unwrap_err();
    assert!(e.to_string().contains("tool"), "{e}");
    let plasma = spec(|s| s.post = Some("grbl-plasma".into()))
        .build()
        .unwrap();
    let e = kerfcam::run(&sign(), &plasma).unwrap_err();
    assert!(e.to_string().contains("router"), "{e}");
    assert!(spec(|s| s.stepover = 0.0).build().is_err());
    assert!(spec(|s| s.stepover = 120.0).build().is_err());
    // Depths finer than the program's heights (the post's 3 decimals):
    // refused by name, not cut at Z0 or in passes at one height.
    let field = |depth: f64, pass: f64| {
        spec(|s| {
            s.depth = Some(depth);
            s.pass_depth = pass;
        })
        .build()
        .map(|_| ())
        .map_err(|e| e.field)
    };
    assert_eq!(field(0.0004, 0.0002), Err("depth"));
    assert_eq!(field(0.5, 0.0005), Err("pass_depth"));
    assert_eq!(field(0.5, 0.001), Ok(()));
    // The program's own comments keep a decimal point (1.5 mm passes).
    let out = kerfcam::run(&sign(), &spec(|s| s.pass_depth = 1.6).build().unwrap()).unwrap();
    assert!(out.gcode.contains("; depth 1 of 4: Z-1.5"), "{}", &out.gcode[..600]);
}

#[test]
fn a_neck_narrower_than_the_tool_is_left_and_said_never_gouged() {
    // Two 40 mm squares joined by a 4 mm wide, 20 mm long channel.
    let neck: [(f64, f64); 12] = [
        (0.0, 0.0),
        (40.0, 0.0),
        (40.0, 18.0),
        (60.0, 18.0),
        (60.0, 0.0),
        (100.0, 0.0),
        (100.0, 40.0),
        (60.0, 40.0),
        (60.0, 22.0),
        (40.0, 22.0),
        (40.0, 40.0),
        (0.0, 40.0),
    ];
    let dxf = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{}0\nENDSEC\n0\nEOF\n",
        lw("POCKET", &neck)
    );
    let settings = spec(|s| {
        s.layer_ops.truncate(1);
        s.verify = true;
    })
    .build()
    .unwrap();
    let out = kerfcam::run(dxf.as_bytes(), &settings).unwrap();
    assert_eq!(common::rs274_errors(&out.gcode, "milling-neck"), Vec::<String>::new());
    let w: Vec<_> = out
        .warnings()
        .filter(|w| w.code == "pocket-unreachable")
        .collect();
    assert_eq!(w.len(), 1, "the neck is said");
    let at = w[0].at.unwrap();
    assert!((36.0..=64.0).contains(&at.x), "said where: {at:?}");
    let class = |x: f64, y: f64| {
        if inside(&neck, x, y) {
            Cell::Pocket
        } else {
            Cell::Keep
        }
    };
    let g = Grid::new((-5.0, -5.0), (105.0, 45.0), 0.25, class, |x, y| {
        edge_dist(&neck, x, y)
    });
    let s = sweep(&g, &samples(&out.gcode, 0.1), R, -DEPTH, 0.05);
    let pct = 100.0 * s.cleared_mm2 / s.reachable_mm2;
    eprintln!(
        "neck: cleared {pct:.2} % of {:.0} mm² reachable, {:.0} mm² drawn, gouge {:.2} mm²",
        s.reachable_mm2, s.pocket_mm2, s.gouge_mm2
    );
    assert_eq!(s.gouge_mm2, 0.0, "gouge at {:?}", s.gouge_at);
    assert!(pct >= 99.0, "cleared {pct:.2} %");
    assert!(
        s.pocket_mm2 - s.reachable_mm2 > 60.0,
        "the channel is out of reach"
    );
    // --verify: the channel is out of the tool's reach, not left by the
    // program; no gouge. Out of reach: the 4 × 20 channel less the two
    // circular segments a disc pokes into its mouths (its centre √5 from
    // the mouth's corners), and the 8 right-angled corners.
    let own = out.milled.as_ref().unwrap().swept.clone().unwrap();
    assert_eq!((own.gouge_mm2, own.left_mm2), (0.0, 0.0), "{own:?}");
    let d = 5.0_f64.sqrt();
    let mouth = R * R * (d / R).acos() - d * (R * R - d * d).sqrt();
    let out_of_reach = 80.0 - 2.0 * mouth + 8.0 * R * R * (1.0 - std::f64::consts::FRAC_PI_4);
    assert!((own.unreachable_mm2 - out_of_reach).abs() < 1.0, "{own:?} vs {out_of_reach}");
}

/// Time of the program, s, read from the text alone: its moves between
/// its header and footer — G0 at `rapid`, G1/G2/G3 at the modal F
/// (mm/min), arcs (I, J from the start) with their Z as a helix; from (0,
/// 0, `z0`) — and every dwell (G4 P, seconds), the header's too.
pub(crate) fn program_time_s(text: &str, header: usize, footer: usize, rapid: f64, z0: f64) -> f64 {
    let blocks: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && *l != "%" && !l.starts_with(';') && !l.starts_with('('))
        .collect();
    let (mut x, mut y, mut z, mut f, mut g) = (0.0, 0.0, z0, 0.0, 0);
    let mut t = 0.0;
    for (i, b) in blocks.iter().enumerate() {
        let word = |c: char| {
            b.split_whitespace()
                .find(|w| w.starts_with(c))
                .map(|w| w[1..].parse::<f64>().unwrap())
        };
        if word('G') == Some(4.0) {
            t += word('P').unwrap();
            continue;
        }
        if i < header || i >= blocks.len() - footer {
            continue;
        }
        if let Some(v) = word('G') {
            g = v as i32;
        }
        if let Some(v) = word('F') {
            f = v;
        }
        let (nx, ny, nz) = (
            word('X').unwrap_or(x),
            word('Y').unwrap_or(y),
            word('Z').unwrap_or(z),
        );
        let len = match g {
            2 | 3 => {
                let (cx, cy) = (x + word('I').unwrap_or(0.0), y + word('J').unwrap_or(0.0));
                let r = f64::hypot(x - cx, y - cy);
                let (a0, a1) = (f64::atan2(y - cy, x - cx), f64::atan2(ny - cy, nx - cx));
                let mut sweep = if g == 3 { a1 - a0 } else { a0 - a1 };
                while sweep <= 1e-9 {
                    sweep += std::f64::consts::TAU;
                }
                (r * sweep).hypot(nz - z)
            }
            _ => ((nx - x).hypot(ny - y)).hypot(nz - z),
        };
        t += 60.0 * len / if g == 0 { rapid } else { f };
        (x, y, z) = (nx, ny, nz);
    }
    t
}

#[test]
fn the_time_of_a_router_job_in_its_header_report_and_quote_is_the_programs() {
    // The sign without its profile (the program is the milling alone), and
    // with it: the profile's passes, plunges and retracts after the pockets,
    // reached from where the pockets ended.
    let with_profile = String::from_utf8(sign()).unwrap();
    let profile = lw(
        "PROFILE",
        &[(0.0, 0.0), (300.0, 0.0), (300.0, 150.0), (0.0, 150.0)],
    );
    let pockets_only = with_profile.replace(&profile, "");
    type Variant<'a> = (&'static str, &'a str, fn(&mut Spec));
    let variants: [Variant; 6] = [
        ("zigzag-plunge", &pockets_only, |_| {}),
        ("offset-helix", &pockets_only, |s| {
            s.pocket = "offset".into();
            s.entry = "helix".into();
            s.post = Some("linuxcnc-router".into());
        }),
        ("zigzag-ramp+profile", &with_profile, |s| {
            s.entry = "ramp".into()
        }),
        // Each tab crossed on every pass: up, across, down again.
        ("offset+profile-tabs", &with_profile, |s| {
            s.pocket = "offset".into();
            s.tabs = 4;
            s.tab_width = 8.0;
        }),
        // The profile's lead arcs cut on every pass, the tool up from
        // each pass's depth and across to the lead-in between them.
        ("zigzag+profile-lead-arcs", &with_profile, |s| {
            s.lead = "arc".into();
            s.lead_radius = 5.0;
        }),
        // Tabs leaving a 2 mm bridge: the first pass (Z -3) cuts through,
        // the second goes up to Z -4 over each, across, and down again.
        ("zigzag+profile-tab-bridges", &with_profile, |s| {
            s.tabs = 4;
            s.tab_width = 8.0;
            s.tab_height = 2.0;
        }),
    ];
    for (name, dxf, set) in variants {
        let settings = spec(set).build().unwrap();
        let out = kerfcam::run(dxf.as_bytes(), &settings).unwrap();
        assert_eq!(out.plan.cuts.is_empty(), dxf == pockets_only, "{name}");
        if name.contains("tab") {
            assert_eq!(out.plan.stats().tabs, 4, "{name}");
        }
        let mut post = settings.post().unwrap().clone();
        let p = &out.process;
        // From the safe height the header leaves the tool at: the first
        // move down to the retract height is counted too.
        let program = program_time_s(
            &out.gcode,
            post.header.len(),
            post.footer.len(),
            p.rapid,
            post.safe_height,
        );
        let report = kerfcam::report::Report::new(&out).plan.est_time_s;
        // The post's header says the time it was written with.
        post.header.push("(time {est_time_s} s)".into());
        let m = out.milled.as_ref().unwrap();
        let job = kerfcam::gcode::JobInfo::from_process(p);
        let text = kerfcam::gcode::emit_router(&out.plan, &m.toolpath, &post, &job).unwrap();
        let header: f64 = (text.lines())
            .find_map(|l| l.strip_prefix("(time ")?.strip_suffix(" s)")?.parse().ok())
            .unwrap();
        let model = kerfcam::quote::CostModel {
            currency: "EUR".into(),
            machine_per_hour: 60.0,
            per_pierce: 0.0,
            per_metre: 0.0,
            material_per_kg: None,
            material_per_m2: Some(0.0),
            density_g_cm3: None,
            thickness_mm: None,
            scrap_per_kg: None,
            setup_per_sheet: 0.0,
            markup_percent: 0.0,
            material_share: kerfcam::quote::MaterialShare::Area,
        };
        let sheet = kerfcam::quote::SheetInput {
            out: &out,
            used_area_mm2: None,
            cost: None,
        };
        let q = kerfcam::quote::quote(&model, &[sheet], &|n| format!("{n}")).unwrap();
        let quoted = q.job.time_s;
        let parts: f64 = q.copies.iter().map(|c| c.figures.time_s).sum();
        eprintln!(
            "{name}: program {program:.2} s, report {report} s, header {header} s, quote {quoted:.2} s (copies {parts:.2} s)"
        );
        assert!(program > 60.0, "{name}: {program}");
        for (what, t) in [("report", report), ("header", header), ("quote", quoted)] {
            assert!(
                (t - program).abs() <= 0.06,
                "{name}: {what} {t} s, program {program} s"
            );
        }
        if !out.plan.cuts.is_empty() {
            assert!((parts - program).abs() <= 0.06, "{name}: copies {parts} s");
        }
    }
}

/// A V-bit engraves as wide as its cone at the depth (issue 43 §1): the
/// width given sets the depth (width / (2 tan(angle/2))), or the depth
/// the width; said in the report and as a note; a bad angle or a width
/// without an angle refused by name.
#[test]
fn a_v_bit_engraving_takes_its_depth_from_the_width_or_its_width_from_the_depth() {
    let engrave = |set: fn(&mut Spec)| {
        spec(|s| {
            s.layer_ops = vec![
                ["POCKET".into(), "ignore".into()],
                ["PROFILE".into(), "engrave".into()],
            ];
            s.depth = Some(3.0);
            s.pass_depth = 1.0;
            set(s);
        })
        .build()
    };
    // 90°, 2 mm wide: 1 mm deep (one pass of the 1 mm deepest pass).
    let settings = engrave(|s| {
        s.v_angle = 90.0;
        s.engrave_width = 2.0;
    })
    .unwrap();
    let out = kerfcam::run(&sign(), &settings).unwrap();
    let r = kerfcam::report::Report::new(&out);
    let e = r.plan.engraving.unwrap();
    assert_eq!((e.v_angle, e.depth, e.width), (90.0, 1.0, 2.0));
    let lowest = |text: &str| {
        (text.lines())
            .flat_map(|l| l.split_whitespace())
            .filter_map(|w| w.strip_prefix('Z')?.parse::<f64>().ok())
            .fold(f64::INFINITY, f64::min)
    };
    assert_eq!(lowest(&out.gcode), -1.0);
    assert!(out.warnings().any(|w| w.code == "engrave-v"));
    assert_eq!(common::rs274_errors(&out.gcode, "milling-vbit"), Vec::<String>::new());
    // 60°, the job's 3 mm: 2·3·tan 30° = 3.464 mm wide, 3 passes.
    let out = kerfcam::run(&sign(), &engrave(|s| s.v_angle = 60.0).unwrap()).unwrap();
    let e = kerfcam::report::Report::new(&out).plan.engraving.unwrap();
    assert_eq!((e.depth, e.width), (3.0, 3.464));
    assert_eq!(lowest(&out.gcode), -3.0);
    // 90°, its own 1.5 mm depth (not the job's 3): 3 mm wide, 2 passes.
    let out = kerfcam::run(
        &sign(),
        &engrave(|s| {
            s.v_angle = 90.0;
            s.engrave_depth = 1.5;
        })
        .unwrap(),
    )
    .unwrap();
    let e = kerfcam::report::Report::new(&out).plan.engraving.unwrap();
    assert_eq!((e.depth, e.width), (1.5, 3.0));
    // Said with a decimal point in English, a comma in Portuguese.
    let said = out.warnings().find(|w| w.code == "engrave-v").unwrap();
    assert!(said.text.en.contains("1.5 mm deep, 3 mm wide"), "{}", said.text.en);
    assert!(said.text.pt.contains("1,5 mm de profundidade, 3 mm de largura"), "{}", said.text.pt);
    assert_eq!(lowest(&out.gcode), -1.5);
    assert_eq!(common::rs274_errors(&out.gcode, "milling-vbit-depth"), Vec::<String>::new());
    // A flat end mill: no engraving figures.
    let out = kerfcam::run(&sign(), &engrave(|_| {}).unwrap()).unwrap();
    assert!(kerfcam::report::Report::new(&out).plan.engraving.is_none());
    // Refused by name.
    for (set, field) in [
        ((|s: &mut Spec| s.v_angle = 180.0) as fn(&mut Spec), "v_angle"),
        (|s: &mut Spec| s.v_angle = -30.0, "v_angle"),
        (|s: &mut Spec| s.engrave_width = 2.0, "engrave_width"),
        (
            |s: &mut Spec| {
                s.v_angle = 90.0;
                s.engrave_width = 7.0;
            },
            "engrave_width",
        ),
        (|s: &mut Spec| s.engrave_depth = 1.0, "engrave_depth"),
        (
            |s: &mut Spec| {
                s.v_angle = 90.0;
                s.engrave_width = 2.0;
                s.engrave_depth = 1.0;
            },
            "engrave_depth",
        ),
        (
            |s: &mut Spec| {
                s.v_angle = 90.0;
                s.engrave_depth = -1.0;
            },
            "engrave_depth",
        ),
    ] {
        let e = engrave(set).err().unwrap();
        assert_eq!(e.field, field);
    }
}

/// Bad pocket input (issue 43 §7), each said by name and place, nothing
/// else skipped: an island drawn through its pocket's outline (either way
/// round: the contour stage then reads it as a pocket of its own, and
/// clearing it would cut away what was to stand), and an open line on a
/// pocket layer. An island standing on its pocket's wall at one point
/// crosses nothing: that pocket is machined.
#[test]
fn an_island_across_its_pockets_outline_or_an_open_pocket_line_is_said_and_not_cut() {
    let open = "0\nLWPOLYLINE\n8\nPOCKET\n90\n2\n70\n0\n10\n0\n20\n60\n10\n40\n20\n60\n";
    // The diamond's left corner stands on the right pocket's wall at (100, 20).
    let touching: [(f64, f64); 4] = [(100.0, 20.0), (110.0, 10.0), (120.0, 20.0), (110.0, 30.0)];
    let crossing: [[(f64, f64); 4]; 2] = [
        [(50.0, 10.0), (70.0, 10.0), (70.0, 30.0), (50.0, 30.0)],
        [(70.0, 10.0), (70.0, 30.0), (40.0, 30.0), (40.0, 10.0)],
    ];
    for (k, island) in crossing.iter().enumerate() {
        let body = [
            lw("POCKET", &[(0.0, 0.0), (60.0, 0.0), (60.0, 40.0), (0.0, 40.0)]),
            lw("POCKET", island),
            lw("POCKET", &[(90.0, 0.0), (140.0, 0.0), (140.0, 40.0), (90.0, 40.0)]),
            lw("POCKET", &touching),
            open.to_string(),
        ]
        .concat();
        let dxf = format!(
            "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n"
        );
        let settings = spec(|s| s.layer_ops.truncate(1)).build().unwrap();
        let out = kerfcam::run(dxf.as_bytes(), &settings).unwrap();
        let what = format!("crossing {k}");
        assert_eq!(
            common::rs274_errors(&out.gcode, &format!("milling-cross-{k}")),
            Vec::<String>::new()
        );
        let said: Vec<_> = (out.warnings())
            .filter(|w| w.code == "pocket-contours-cross")
            .collect();
        assert_eq!(said.len(), 1, "{what}: {:?}", out.warnings().map(|w| w.code).collect::<Vec<_>>());
        assert!(said[0].text.en.starts_with("1 pair(s)"), "{what}: {}", said[0].text.en);
        assert!(said[0].text.en.contains("layer 'POCKET'"), "{}", said[0].text.en);
        let at = said[0].at.unwrap();
        assert!((at.x - 60.0).abs() < 1e-6 && [10.0, 30.0].iter().any(|y| (at.y - y).abs() < 1e-6), "{what}: {at:?}");
        assert!(out.warnings().any(|w| w.code == "pocket-open"), "{what}: the open line");
        // Nothing cut below the top on the crossing pair; the pocket with
        // the diamond standing in it is cleared around it.
        let cut = samples(&out.gcode, 0.5);
        let below = |x0: f64, x1: f64| cut.iter().filter(|p| p.z < 0.0 && (x0..=x1).contains(&p.x)).count();
        assert_eq!(below(-5.0, 75.0), 0, "{what}: the crossing pair is not machined");
        assert!(below(90.0, 140.0) > 100, "{what}: the other pocket is");
        let notes = out.gcode.lines().filter(|l| l.contains("pocket at")).collect::<Vec<_>>();
        assert_eq!(notes, ["; pocket at X90 Y0"], "{what}");
        let in_diamond = cut.iter().filter(|p| p.z < 0.0 && (p.x - 110.0).abs() + (p.y - 20.0).abs() < 10.0 + 3.0 - 0.01);
        assert_eq!(in_diamond.count(), 0, "{what}: the diamond stands");
    }
}

/// Drilling (issue 43 §1): a point and the circles up to the largest
/// drilled (here the tool's diameter) are drilled at their centre in
/// pecks of `--peck`, the tool up to clear the chips between them; a
/// circle of another size is drilled at the tool's and said; a circle
/// larger than a drilled hole is not drilled, and said.
#[test]
fn points_and_small_circles_are_drilled_at_their_centre_in_pecks() {
    let circle = |x: f64, d: f64| format!("0\nCIRCLE\n8\nDRILL\n10\n{x}\n20\n10\n40\n{}\n", d / 2.0);
    let body = [
        "0\nPOINT\n8\nDRILL\n10\n10\n20\n10\n".to_string(),
        circle(30.0, 6.0),
        circle(50.0, 4.0),
        circle(80.0, 20.0),
    ]
    .concat();
    let dxf = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n"
    );
    let settings = spec(|s| {
        s.layer_ops = vec![["DRILL".into(), "drill".into()]];
        s.peck = 2.0;
    })
    .build()
    .unwrap();
    let out = kerfcam::run(dxf.as_bytes(), &settings).unwrap();
    assert_eq!(common::rs274_errors(&out.gcode, "milling-drill"), Vec::<String>::new());
    assert_eq!(out.milled.as_ref().unwrap().holes, 3);
    // The program's moves into the stock, read from its text: (x, y, z)
    // of each Z-only feed move going down.
    let (mut x, mut y, mut z) = (0.0, 0.0, 15.0);
    let mut downs: Vec<(f64, f64, f64)> = Vec::new();
    for line in out.gcode.lines().filter(|l| !l.starts_with(';')) {
        let word = |c: char| {
            (line.split_whitespace())
                .find_map(|w| w.strip_prefix(c)?.parse::<f64>().ok())
        };
        let (nx, ny, nz) = (word('X').unwrap_or(x), word('Y').unwrap_or(y), word('Z').unwrap_or(z));
        if line.starts_with("G1") && (nx, ny) == (x, y) && nz < z && nz < 0.0 {
            downs.push((nx, ny, nz));
        }
        (x, y, z) = (nx, ny, nz);
    }
    let at = |cx: f64| -> Vec<f64> {
        (downs.iter())
            .filter(|d| (d.0 - cx).abs() < 1e-9 && (d.1 - 10.0).abs() < 1e-9)
            .map(|d| d.2)
            .collect()
    };
    for cx in [10.0, 30.0, 50.0] {
        assert_eq!(at(cx), [-2.0, -4.0, -6.0], "the hole at X{cx}, in 2 mm pecks");
    }
    assert!(at(80.0).is_empty(), "the 20 mm circle is not drilled");
    assert_eq!(downs.len(), 9, "{downs:?}");
    // Between two pecks the tool comes up out of the hole.
    let text: Vec<&str> = out.gcode.lines().collect();
    let pecks: Vec<usize> = (0..text.len()).filter(|&i| text[i].starts_with("G1 Z-")).collect();
    for w in pecks.windows(2) {
        assert!(text[w[0] + 1..w[1]].iter().any(|l| l.starts_with("G0 Z")), "no lift between pecks at lines {w:?}");
    }
    let said = |code: &str| out.warnings().filter(|w| w.code == code).count();
    assert_eq!((said("drill-diameter"), said("drill-too-large")), (1, 1));
}

/// The LinuxCNC and Mach3 routers change to the job's tool by its number
/// and take its length offset (issue 43 §5: `T… M6`, `G43 H…`); GRBL has
/// no tool change. rs274 reads the change and the offset.
#[test]
fn the_linuxcnc_and_mach3_routers_change_to_the_tool_by_its_number() {
    for post in ["linuxcnc-router", "mach3-router", "grbl-router"] {
        let settings = spec(|s| {
            s.post = Some(post.into());
            s.tool_number = 3;
        })
        .build()
        .unwrap();
        let out = kerfcam::run(&sign(), &settings).unwrap();
        let name = format!("milling-tool-{post}");
        assert!(common::rs274_errors(&out.gcode, &name).is_empty(), "{post}");
        let lines: Vec<&str> = out.gcode.lines().collect();
        if post == "grbl-router" {
            assert!(!out.gcode.contains("M6"), "{post}");
            continue;
        }
        let change = lines.iter().position(|l| *l == "T3 M6").expect(post);
        assert_eq!(lines[change + 1], "G43 H3", "{post}");
        let spindle = lines.iter().position(|l| l.starts_with("M3 S")).unwrap();
        assert!(change < spindle, "{post}: the tool is changed before the spindle starts");
        if let Some(text) = common::rs274_output(&out.gcode, &name) {
            assert!(text.contains("CHANGE_TOOL(3)"), "{post}");
            assert!(text.contains("USE_TOOL_LENGTH_OFFSET"), "{post}");
        }
    }
    let e = spec(|s| s.tool_number = 0).build().unwrap_err();
    assert_eq!(e.field, "tool_number");
}
