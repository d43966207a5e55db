//! Milling layers at their own depth (issue 43 §1: each operation has its
//! depth, pass depth and direction): a sign of 18 mm board whose lettering
//! is pocketed 3 mm deep in passes of 1.5 and whose outline is profiled
//! through in passes of 6, in one program; an engraving 0.5 mm deep
//! beside a through profile. The heights read back from the program's
//! text per contour, the program through rs274, the lettering swept by
//! the independent checker of `common::mill_sweep`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::mill_sweep::{samples, sweep, Cell, Grid};
use kerfcam::{LayerDepthSpec, Spec};

/// The lettering: an `I` (20..32 × 15..45) and an `O` (R 12 round an
/// R 4 counter at 80, 30) inside the 120 × 60 OUTLINE; an ENGRAVE line.
fn dxf(outline: bool) -> Vec<u8> {
    let mut e = String::from(
        "0\nLWPOLYLINE\n8\nLETTERS\n90\n4\n70\n1\n10\n20\n20\n15\n10\n32\n20\n15\n10\n32\n20\n45\n10\n20\n20\n45\n",
    );
    e += "0\nCIRCLE\n8\nLETTERS\n10\n80\n20\n30\n40\n12\n";
    e += "0\nCIRCLE\n8\nLETTERS\n10\n80\n20\n30\n40\n4\n";
    e += "0\nLINE\n8\nENGRAVE\n10\n20\n20\n8\n11\n100\n21\n8\n";
    if outline {
        e += "0\nLWPOLYLINE\n8\nOUTLINE\n90\n4\n70\n1\n10\n0\n20\n0\n10\n120\n20\n0\n10\n120\n20\n60\n10\n0\n20\n60\n";
    }
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn in_letters(x: f64, y: f64) -> bool {
    let i = (20.0..32.0).contains(&x) && (15.0..45.0).contains(&y);
    let r = (x - 80.0).hypot(y - 30.0);
    i || (4.0..12.0).contains(&r)
}

fn letters_wall(x: f64, y: f64) -> f64 {
    if x < 50.0 {
        (x - 20.0).min(32.0 - x).min(y - 15.0).min(45.0 - y)
    } else {
        let r = (x - 80.0).hypot(y - 30.0);
        (r - 4.0).min(12.0 - r)
    }
}

fn spec(post: &str, depths: Vec<LayerDepthSpec>) -> Spec {
    Spec {
        tool_diameter: Some(6.0),
        feed: Some(2000.0),
        depth: Some(18.0),
        pass_depth: 6.0,
        post: Some(post.into()),
        origin: "drawing".into(),
        layer_ops: vec![
            ["LETTERS".into(), "pocket".into()],
            ["ENGRAVE".into(), "ignore".into()],
            ["OUTLINE".into(), "profile".into()],
        ],
        layer_depths: depths,
        verify: true,
        ..Spec::default()
    }
}

fn depth(layer: &str, h: f64, pass: Option<f64>) -> LayerDepthSpec {
    LayerDepthSpec {
        layer: layer.into(),
        depth: Some(h),
        pass_depth: pass,
        milling: None,
    }
}

/// Each flat cutting move below the top (G1/G2/G3 in X or Y at one Z) as
/// (line, x, y, z), read from the program's text (absolute, G90).
fn flat_cuts(program: &str) -> Vec<(usize, f64, f64, f64)> {
    let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
    let mut motion = 0;
    let mut out = Vec::new();
    for (i, line) in program.lines().enumerate() {
        let code = line.split([';', '(']).next().unwrap_or("");
        let mut moved = false;
        let before = z;
        for w in code.split_whitespace() {
            let (c, v) = w.split_at(1);
            let Ok(v) = v.parse::<f64>() else { continue };
            match c {
                "G" if [0.0, 1.0, 2.0, 3.0].contains(&v) => motion = v as i32,
                "X" => (x, moved) = (v, true),
                "Y" => (y, moved) = (v, true),
                "Z" => z = v,
                _ => {}
            }
        }
        if moved && z == before && motion != 0 && z < -1e-6 {
            out.push((i, x, y, z));
        }
    }
    out
}

/// The distinct heights of `cuts` where `at` holds, mm (µm-rounded).
fn heights(cuts: &[(usize, f64, f64, f64)], at: impl Fn(f64, f64) -> bool) -> Vec<f64> {
    let mut zs: Vec<f64> = (cuts.iter())
        .filter(|c| at(c.1, c.2))
        .map(|c| (c.3 * 1000.0).round() / 1000.0)
        .collect();
    zs.sort_by(|a, b| b.total_cmp(a));
    zs.dedup();
    zs
}

/// Outside the board's outline (a profile cut outside it).
fn on_outline(x: f64, y: f64) -> bool {
    !(0.5..119.5).contains(&x) || !(0.5..59.5).contains(&y)
}

#[test]
fn a_sign_pockets_its_lettering_3_mm_deep_and_profiles_its_outline_through_18() {
    let depths = vec![depth("LETTERS", 3.0, Some(1.5))];
    for post in ["linuxcnc-router", "grbl-router"] {
        let settings = spec(post, depths.clone()).build().unwrap();
        let out = kerfcam::run(&dxf(true), &settings).unwrap();
        let g = &out.gcode;
        let errors = common::rs274_errors(g, &format!("milling-depths-sign-{post}"));
        assert!(errors.is_empty(), "{post}: {errors:?}");
        let cuts = flat_cuts(g);
        let letters = heights(&cuts, in_letters);
        let outline = heights(&cuts, on_outline);
        eprintln!("{post}: lettering at {letters:?}, outline at {outline:?}");
        assert_eq!(letters, [-1.5, -3.0], "{post}");
        assert_eq!(outline, [-6.0, -12.0, -18.0], "{post}");
        // No other height anywhere; the lettering before the profile.
        assert_eq!(
            heights(&cuts, |_, _| true),
            [-1.5, -3.0, -6.0, -12.0, -18.0]
        );
        let last_letter = cuts
            .iter()
            .filter(|c| in_letters(c.1, c.2))
            .map(|c| c.0)
            .max();
        let first_outline = cuts
            .iter()
            .filter(|c| on_outline(c.1, c.2))
            .map(|c| c.0)
            .min();
        assert!(
            last_letter < first_outline,
            "{post}: the pocket before the profile"
        );
        // One tool: no change, no tool list in the report.
        assert!(
            !g.contains("tool change") && g.matches("M6").count() <= 1,
            "{post}"
        );
        let report = kerfcam::report::Report::new(&out);
        assert!(report.plan.tools.is_empty());
        // The report says each layer's depth, the job's depth the profiles'.
        let rows: Vec<(Vec<String>, f64, usize, f64, &str)> = (report.plan.layer_depths.iter())
            .map(|d| (d.layers.clone(), d.depth, d.passes, d.pass_depth, d.milling))
            .collect();
        assert_eq!(
            rows,
            [(vec!["LETTERS".to_string()], 3.0, 2, 1.5, "climb")],
            "{post}"
        );
        // The estimate is the program's moves as written, read back.
        let p = settings.post().unwrap();
        let program = crate::milling::program_time_s(
            g,
            p.header.len(),
            p.footer.len(),
            out.process.rapid,
            p.safe_height,
        );
        eprintln!(
            "{post}: estimate {:.2} s, program read back {program:.2} s",
            out.est_time_s
        );
        assert!(
            (out.est_time_s - program).abs() <= 0.06,
            "{post}: {} vs {program}",
            out.est_time_s
        );
        // --verify sweeps the lettering at its own depth.
        let own = out.milled.as_ref().unwrap().swept.clone().unwrap();
        assert_eq!(own.gouge_mm2, 0.0, "{own:?}");
    }
    // The independent sweep of the lettering (without the outline): no
    // gouge, its reachable area cleared at 3 mm.
    let settings = spec("linuxcnc-router", depths).build().unwrap();
    let out = kerfcam::run(&dxf(false), &settings).unwrap();
    let grid = Grid::new(
        (10.0, 5.0),
        (100.0, 55.0),
        0.2,
        |x, y| {
            if in_letters(x, y) {
                Cell::Pocket
            } else {
                Cell::Keep
            }
        },
        letters_wall,
    );
    let s = sweep(&grid, &samples(&out.gcode, 0.1), 3.0, -3.0, 0.05);
    let pct = 100.0 * s.cleared_mm2 / s.reachable_mm2;
    eprintln!(
        "lettering: cleared {pct:.2} % of {:.0} mm² at 3 mm, gouge {:.3} mm²",
        s.reachable_mm2, s.gouge_mm2
    );
    assert_eq!(s.gouge_mm2, 0.0, "gouge at {:?}", s.gouge_at);
    assert!(pct >= 99.0, "{pct:.2} %");
    let wide = sweep(&grid, &samples(&out.gcode, 0.1), 3.5, -3.0, 0.05);
    assert!(wide.gouge_mm2 > 0.0, "the checker misses a gouge");
}

#[test]
fn an_engraving_half_a_millimetre_deep_beside_a_through_profile() {
    let mut s = spec("linuxcnc-router", vec![depth("ENGRAVE", 0.5, None)]);
    s.layer_ops = vec![
        ["LETTERS".into(), "ignore".into()],
        ["ENGRAVE".into(), "engrave".into()],
        ["OUTLINE".into(), "profile".into()],
    ];
    let out = kerfcam::run(&dxf(true), &s.build().unwrap()).unwrap();
    let errors = common::rs274_errors(&out.gcode, "milling-depths-engrave");
    assert!(errors.is_empty(), "rs274: {errors:?}");
    let cuts = flat_cuts(&out.gcode);
    let line = |x: f64, y: f64| (y - 8.0).abs() < 1e-3 && (20.0..=100.0).contains(&x);
    assert_eq!(heights(&cuts, line), [-0.5]);
    assert_eq!(heights(&cuts, on_outline), [-6.0, -12.0, -18.0]);
    assert_eq!(heights(&cuts, |_, _| true), [-0.5, -6.0, -12.0, -18.0]);
    let report = kerfcam::report::Report::new(&out);
    assert_eq!(report.plan.layer_depths.len(), 1);
    assert_eq!(
        (
            report.plan.layer_depths[0].depth,
            report.plan.layer_depths[0].passes
        ),
        (0.5, 1)
    );
}

#[test]
fn a_layer_at_the_jobs_depth_writes_the_one_depth_program() {
    let plain = kerfcam::run(
        &dxf(true),
        &spec("linuxcnc-router", Vec::new()).build().unwrap(),
    )
    .unwrap();
    let same = spec("linuxcnc-router", vec![depth("LETTERS", 18.0, None)]);
    let same = kerfcam::run(&dxf(true), &same.build().unwrap()).unwrap();
    assert_eq!(same.gcode, plain.gcode);
    // Conventional for the lettering alone: its walls the other way.
    let mut d = depth("LETTERS", 18.0, None);
    d.milling = Some("conventional".into());
    let conv = kerfcam::run(
        &dxf(true),
        &spec("linuxcnc-router", vec![d]).build().unwrap(),
    )
    .unwrap();
    assert_ne!(conv.gcode, plain.gcode);
    // The direction alone (the page's layer whose depth is left blank): the
    // job's depth and passes, the layer's direction — the same program.
    let alone = LayerDepthSpec {
        layer: "LETTERS".into(),
        milling: Some("conventional".into()),
        ..LayerDepthSpec::default()
    };
    let alone = spec("linuxcnc-router", vec![alone]).build().unwrap();
    assert_eq!(kerfcam::run(&dxf(true), &alone).unwrap().gcode, conv.gcode);
    let profile = |g: &str| {
        g[g.rfind("T1").unwrap_or(0)..]
            .lines()
            .rev()
            .take(20)
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(
        profile(&conv.gcode),
        profile(&plain.gcode),
        "the profile as the job's"
    );
}

#[test]
fn a_bad_layer_depth_is_refused_naming_the_layer() {
    let refused = |d: LayerDepthSpec| {
        let s = spec("linuxcnc-router", vec![d]);
        let e = match s.build() {
            Err(e) => e,
            Ok(b) => match kerfcam::run(&dxf(true), &b) {
                Err(kerfcam::Error::Settings(e)) => e,
                other => panic!("not refused: {:?}", other.map(|_| ())),
            },
        };
        assert_eq!(e.field, "layer_depths");
        e.reason.en
    };
    let deep = refused(depth("LETTERS", 20.0, None));
    assert!(
        deep.contains("layer 'LETTERS'") && deep.contains("deeper than the job's 18 mm"),
        "{deep}"
    );
    let shallow = refused(depth("LETTERS", 0.0004, None));
    assert!(
        shallow.contains("layer 'LETTERS': 0.0004 mm is below the 0.001 mm"),
        "{shallow}"
    );
    let fine = refused(depth("LETTERS", 0.002, Some(0.0005)));
    assert!(
        fine.contains("layer 'LETTERS': 4 passes of 0.0005 mm are finer than the 0.001 mm"),
        "{fine}"
    );
    let zero = refused(depth("LETTERS", 0.0, None));
    assert!(zero.contains("layer 'LETTERS'"), "{zero}");
    let profile = refused(depth("OUTLINE", 6.0, None));
    assert!(
        profile.contains("layer 'OUTLINE' is cut as a profile"),
        "{profile}"
    );
    let mut d = depth("LETTERS", 3.0, None);
    d.milling = Some("upcut".into());
    assert!(refused(d).contains("'upcut' is not climb or conventional"));
    // A direction alone with no job depth to mill the layer to: refused, not dropped.
    let mut s = spec("linuxcnc-router", Vec::new());
    (s.depth, s.pass_depth) = (None, 0.0);
    s.layer_depths = vec![LayerDepthSpec {
        layer: "LETTERS".into(),
        milling: Some("conventional".into()),
        ..LayerDepthSpec::default()
    }];
    let e = match s.build() {
        Err(e) => e,
        Ok(b) => match kerfcam::run(&dxf(true), &b) {
            Err(kerfcam::Error::Settings(e)) => e,
            other => panic!("not refused: {:?}", other.map(|_| ())),
        },
    };
    assert!(
        e.reason
            .en
            .contains("layer 'LETTERS': a layer's own depth needs the job's"),
        "{}",
        e.reason.en
    );
}

#[test]
fn a_listed_tool_at_two_depths_changes_once_and_the_jobs_tool_profiles_last() {
    // T2 (3 mm) pockets the lettering 3 deep and engraves the line 0.5
    // deep: one change to it (the header), none between its two depths,
    // one back to T1 for the profile.
    let mut s = spec(
        "linuxcnc-router",
        vec![
            depth("LETTERS", 3.0, Some(1.5)),
            depth("ENGRAVE", 0.5, None),
        ],
    );
    s.layer_ops[1] = ["ENGRAVE".into(), "engrave".into()];
    s.tools = vec![kerfcam::ToolSpec {
        number: 2,
        diameter: 3.0,
        ..kerfcam::ToolSpec::default()
    }];
    s.layer_tools = vec![("LETTERS".into(), 2), ("ENGRAVE".into(), 2)];
    let out = kerfcam::run(&dxf(true), &s.build().unwrap()).unwrap();
    let g = &out.gcode;
    let errors = common::rs274_errors(g, "milling-depths-tools");
    assert!(errors.is_empty(), "rs274: {errors:?}");
    assert_eq!(
        g.matches(" M6").count(),
        2,
        "T2 in the header, T1 for the profile"
    );
    let t1 = g.lines().position(|l| l == "T1 M6").unwrap();
    let cuts = flat_cuts(g);
    let line = |x: f64, y: f64| (y - 8.0).abs() < 1e-3 && (20.0..=100.0).contains(&x);
    assert_eq!(heights(&cuts, in_letters), [-1.5, -3.0]);
    assert_eq!(heights(&cuts, line), [-0.5]);
    assert!(cuts
        .iter()
        .filter(|c| c.0 > t1)
        .all(|c| on_outline(c.1, c.2)));
    assert_eq!(heights(&cuts, on_outline), [-6.0, -12.0, -18.0]);
    let report = kerfcam::report::Report::new(&out);
    let rows: Vec<(u32, usize, usize)> = (report.plan.tools.iter())
        .map(|t| (t.number, t.pockets, t.engravings))
        .collect();
    assert_eq!(rows, [(2, 2, 1), (1, 0, 0)]);
    let depths: Vec<(u32, f64)> = (report.plan.layer_depths.iter())
        .map(|d| (d.tool, d.depth))
        .collect();
    assert_eq!(depths, [(2, 3.0), (2, 0.5)]);
    // The estimate: the program read back, and the change.
    let p = s.build().unwrap().post().unwrap().clone();
    let program = crate::milling::program_time_s(
        g,
        p.header.len(),
        p.footer.len(),
        out.process.rapid,
        p.safe_height,
    );
    let change = kerfcam::gcode::TOOL_CHANGE_S;
    assert!(
        (out.est_time_s - program - change).abs() <= 0.06,
        "{} vs {program} + {change}",
        out.est_time_s
    );
}
