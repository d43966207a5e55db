//! What is previewed is what is downloaded, for a router job (issue 43):
//! the page's Play list (`Job::moves`, [`kerfcam::animation::moves`]) and
//! the plan SVG (Save SVG, [`kerfcam::svg::plan`]) trace the very path
//! the program cuts and travels in X and Y, read back from the program's
//! text by this test's own reader ([`common::program_xy`]). A pocket (a 60
//! × 40 rectangle around a round island of R 8) 6 mm deep in 3 passes
//! with a 6 mm tool, and a square profiled beside it.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::program_xy::{farthest, read, XyMove};
use kerfcam::animation::kind;
use kerfcam::{Output, Settings, Spec};

/// The job, its moves arc-fitted (`--fit-arcs`, tolerance 0.01 mm) or
/// not, with the profile's `lead` kind ("arc": a router's lead arcs, cut
/// on every pass; "tab-bridges": straight leads and tabs leaving a
/// bridge). Fitted, the island is drawn as a polyline of 144 short lines
/// (as drawing tools export circles): what the fitting turns back into arcs.
fn job_led(
    entry: &str,
    pocket: &str,
    profile: bool,
    fit_arcs: bool,
    lead: &str,
) -> (Output, Settings) {
    let bridges = lead == "tab-bridges";
    let mut spec = Spec {
        lead: if bridges { "perpendicular".into() } else { lead.into() },
        tabs: if bridges { 2 } else { 0 },
        tab_width: 6.0,
        tab_height: if bridges { 3.0 } else { 0.0 },
        fit_arcs,
        tool_diameter: Some(6.0),
        depth: Some(6.0),
        pass_depth: 2.0,
        entry: entry.into(),
        pocket: pocket.into(),
        post: Some("grbl-router".into()),
        layer_ops: vec![
            ["POCKET".into(), "pocket".into()],
            ["PROFILE".into(), "profile".into()],
        ],
        ..Spec::default()
    };
    let mut dxf = String::from_utf8(common::pocket_island_dxf(profile)).unwrap();
    if fit_arcs {
        spec.tolerance = 0.01;
        let circle = "0\nCIRCLE\n8\nPOCKET\n10\n30\n20\n20\n40\n8\n";
        let mut gon = "0\nLWPOLYLINE\n8\nPOCKET\n90\n144\n70\n1\n".to_string();
        for k in 0..144 {
            let a = k as f64 * std::f64::consts::TAU / 144.0;
            gon += &format!("10\n{}\n20\n{}\n", 30.0 + 8.0 * a.cos(), 20.0 + 8.0 * a.sin());
        }
        assert!(dxf.contains(circle));
        dxf = dxf.replace(circle, &gon);
    }
    let settings = spec.build().unwrap();
    (kerfcam::run(dxf.as_bytes(), &settings).unwrap(), settings)
}

/// The Play list's moves in X and Y (Z moves in place left out): rapids,
/// and every move the tool cuts along.
fn play(m: &[f64]) -> Vec<XyMove> {
    let mut out = Vec::new();
    for v in m.chunks(kind::STRIDE) {
        let k = v[0];
        if [kind::PIERCE, kind::SPOT, kind::Z].contains(&k) {
            continue;
        }
        let (a, b, bulge) = ((v[1], v[2]), (v[3], v[4]), v[5]);
        let arc = (bulge != 0.0).then(|| {
            let s = kerfcam::geom::Segment {
                a: kerfcam::geom::Point::new(a.0, a.1),
                b: kerfcam::geom::Point::new(b.0, b.1),
                bulge,
            };
            let (c, _) = s.arc_center().unwrap();
            ((c.x, c.y), bulge > 0.0)
        });
        out.push(XyMove::new(k == kind::RAPID, a, b, arc));
    }
    out
}

/// The program's X/Y moves, rapids or not; moves in Z alone left out.
fn split(moves: &[XyMove], rapid: bool) -> Vec<XyMove> {
    (moves.iter())
        .filter(|m| m.rapid == rapid && m.length() > 0.0)
        .copied()
        .collect()
}

fn length(moves: &[XyMove]) -> f64 {
    moves.iter().map(XyMove::length).sum()
}

/// Both ways within `tol` mm, and the same length cut (a pass left out
/// of the picture lies on the ones drawn: only the length says it).
fn same_path(what: &str, pic: &[XyMove], program: &[XyMove], tol: f64, lengths: bool) {
    let (d, at) = farthest(pic, program, 0.25);
    assert!(d <= tol, "{what}: drawn {d:.4} mm off the program at {at:?}");
    let (d, at) = farthest(program, pic, 0.25);
    assert!(d <= tol, "{what}: the program {d:.4} mm off the picture at {at:?}");
    if lengths {
        let (a, b) = (length(pic), length(program));
        assert!((a - b).abs() <= 1e-4 * b, "{what}: drawn {a:.3} mm, program {b:.3} mm");
    }
}

const TOL: f64 = 0.005;

#[test]
fn play_moves_are_the_programs_path_and_time() {
    for (entry, pocket, fit, lead) in [
        ("ramp", "zigzag", false, "perpendicular"),
        ("helix", "offset", false, "perpendicular"),
        ("plunge", "zigzag", false, "perpendicular"),
        ("ramp", "zigzag", true, "perpendicular"),
        ("helix", "offset", true, "perpendicular"),
        // The profile's lead arcs on every pass, the tool up and across
        // between passes.
        ("plunge", "zigzag", false, "arc"),
        ("ramp", "offset", true, "arc"),
        // Tabs leaving a 3 mm bridge (passes 2 and 3 of 3 go over it).
        ("plunge", "zigzag", false, "tab-bridges"),
    ] {
        let (out, settings) = job_led(entry, pocket, true, fit, lead);
        let what = format!("{entry}/{pocket}{} {lead}", if fit { " fitted" } else { "" });
        if lead == "arc" {
            let arcs = (out.plan.cuts.iter().flat_map(|c| &c.steps))
                .filter(|s| matches!(s.role, kerfcam::plan::Role::LeadIn | kerfcam::plan::Role::LeadOut))
                .filter(|s| s.segment.bulge != 0.0)
                .count();
            assert_eq!(arcs, 2, "{what}: the square's lead-in and lead-out arcs");
        }
        if fit {
            // The milling's runs of short moves are fitted too: the
            // passes round the 144-gon island.
            let mill = out.milled.as_ref().and_then(|m| m.arc_fit).unwrap();
            let all = out.arc_fit().unwrap();
            assert!(mill.lines_after < mill.lines_before, "{what}: {mill:?}");
            assert!(all.lines_before >= mill.lines_before, "{what}: {all:?}");
            eprintln!("{what}: milling {mill:?}; program {all:?}");
        }
        let post = settings.post().unwrap();
        let program = read(&out.gcode, post.safe_height);
        let m = kerfcam::animation::moves(&out.scene(), &out.process, settings.post());
        let pic = play(&m);
        let (feed, rapids) = (split(&program, false), split(&program, true));
        assert!(length(&feed) > 1000.0, "{what}: {} mm", length(&feed));
        same_path(&format!("{what} feed"), &split(&pic, false), &feed, TOL, true);
        same_path(&format!("{what} rapids"), &split(&pic, true), &rapids, TOL, true);
        // Ramps and helices are their own kind, and only they.
        let entries: f64 = (m.chunks(kind::STRIDE))
            .filter(|v| v[0] == kind::MILL_ENTRY)
            .map(|v| (v[3] - v[1]).hypot(v[4] - v[2]))
            .sum();
        assert_eq!(entries > 0.0, entry != "plunge", "{what}: entries {entries}");
        // The Play list ends at the program's estimated time.
        let t = m[m.len() - 1];
        assert!((t - out.est_time_s).abs() < 1e-6, "{what}: {t} vs {}", out.est_time_s);
        eprintln!(
            "{what}: {} Play moves, program {} moves; feed {:.1} mm, rapids {:.1} mm; {t:.2} s",
            m.len() / kind::STRIDE,
            program.len(),
            length(&feed),
            length(&rapids)
        );
    }
}

/// The plan SVG's paths in drawing coordinates, by what they are: the
/// drawing, rapids, and what the tool cuts (every other layer).
struct SvgPaths {
    drawing: Vec<XyMove>,
    rapids: Vec<XyMove>,
    cuts: Vec<XyMove>,
    /// The milling layer's depth sublayers' `data-z`.
    depths: Vec<f64>,
    /// Length of the paths by the label of the layer right around them.
    by_layer: std::collections::BTreeMap<String, f64>,
}

/// Reads the `<g inkscape:label>` nesting and the `d` of each `<path>`
/// (M, L, A and Z commands, as the plan SVG writes them), Y flipped back
/// with the drawing's lowest-leftmost point at (0, 0).
fn svg_paths(svg: &str) -> SvgPaths {
    let attr = |tag: &str, name: &str| -> Option<String> {
        let k = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(tag[k..k + tag[k..].find('"')?].to_string())
    };
    let mut stack: Vec<String> = Vec::new();
    let mut raw: Vec<(String, Vec<XyMove>)> = Vec::new();
    let mut depths = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        let j = rest[i..].find('>').unwrap() + i;
        let tag = &rest[i..=j];
        rest = &rest[j + 1..];
        if tag.starts_with("</g") {
            stack.pop();
        } else if tag.starts_with("<g") {
            stack.push(attr(tag, "inkscape:label").unwrap_or_default());
            if let Some(z) = attr(tag, "data-z") {
                depths.push(z.parse().unwrap());
            }
        } else if tag.starts_with("<path") {
            let d = attr(tag, "d").unwrap();
            let what = if stack.iter().any(|l| l == "drawing") {
                "drawing"
            } else if stack.iter().any(|l| l == "rapids") {
                "rapids"
            } else {
                "cuts"
            };
            raw.push((format!("{what}\t{}", stack.last().unwrap()), path_moves(&d)));
        }
    }
    // SVG y down: the drawing's (0, 0) is its lowest-leftmost point.
    let pts = || raw.iter().filter(|(w, _)| w.starts_with("drawing\t")).flat_map(|(_, m)| m.iter().flat_map(|m| [m.a, m.b]));
    let x0 = pts().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let y0 = pts().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    let back = |p: (f64, f64)| (p.0 - x0, y0 - p.1);
    let mut out = SvgPaths {
        drawing: Vec::new(),
        rapids: Vec::new(),
        cuts: Vec::new(),
        depths,
        by_layer: Default::default(),
    };
    for (key, moves) in raw {
        let (what, layer) = key.split_once('\t').unwrap();
        *out.by_layer.entry(layer.to_string()).or_default() += moves.iter().map(XyMove::length).sum::<f64>();
        for m in moves {
            let (a, b) = (back(m.a), back(m.b));
            // Y flipped: a clockwise arc on the page turns counter-clockwise in the drawing.
            let arc = m.arc.map(|(c, ccw)| (back(c), !ccw));
            let m = XyMove::new(what == "rapids", a, b, arc);
            match what {
                "drawing" => out.drawing.push(m),
                "rapids" => out.rapids.push(m),
                _ => out.cuts.push(m),
            }
        }
    }
    out
}

/// A path's `d` as moves in the page's coordinates (`arc`'s flag: the
/// page's sweep flag 1).
fn path_moves(d: &str) -> Vec<XyMove> {
    let mut nums: Vec<&str> = Vec::new();
    let mut cmds: Vec<(char, Vec<f64>)> = Vec::new();
    let flush = |cmds: &mut Vec<(char, Vec<f64>)>, nums: &mut Vec<&str>| {
        if let Some(c) = cmds.last_mut() {
            c.1.extend(nums.drain(..).map(|n| n.parse::<f64>().unwrap()));
        }
    };
    for tok in d.split_whitespace() {
        let c = tok.chars().next().unwrap();
        if c.is_ascii_alphabetic() {
            flush(&mut cmds, &mut nums);
            cmds.push((c, Vec::new()));
            if tok.len() > 1 {
                nums.push(&tok[1..]);
            }
        } else {
            nums.push(tok);
        }
    }
    flush(&mut cmds, &mut nums);
    let (mut at, mut start) = ((0.0, 0.0), (0.0, 0.0));
    let mut out = Vec::new();
    for (c, v) in cmds {
        match c {
            'M' => {
                at = (v[0], v[1]);
                start = at;
            }
            'L' => {
                out.push(XyMove::new(false, at, (v[0], v[1]), None));
                at = (v[0], v[1]);
            }
            'A' => {
                let (r, large, sweep, b) = (v[0], v[3] != 0.0, v[4] != 0.0, (v[5], v[6]));
                let (dx, dy) = (b.0 - at.0, b.1 - at.1);
                let chord = dx.hypot(dy);
                let h = (r * r - chord * chord / 4.0).max(0.0).sqrt();
                // Sweep flag 1: the positive angle direction; the centre on
                // the chord's left for it with the small arc.
                let s = if sweep != large { 1.0 } else { -1.0 };
                let c = (
                    (at.0 + b.0) / 2.0 - s * h * dy / chord,
                    (at.1 + b.1) / 2.0 + s * h * dx / chord,
                );
                out.push(XyMove::new(false, at, b, Some((c, sweep))));
                at = b;
            }
            'Z' => {
                if at != start {
                    out.push(XyMove::new(false, at, start, None));
                }
                at = start;
            }
            other => panic!("path command {other}"),
        }
    }
    out
}

#[test]
fn the_plan_svg_draws_the_programs_path() {
    for (entry, pocket, profile, fit, lead) in [
        ("ramp", "zigzag", true, false, "perpendicular"),
        ("helix", "offset", true, false, "perpendicular"),
        ("ramp", "offset", false, false, "perpendicular"),
        ("helix", "zigzag", false, false, "perpendicular"),
        ("ramp", "zigzag", false, true, "perpendicular"),
        // The square's lead arcs cut on each of the 3 passes: between
        // passes the tool goes up where the lead-out ends and across to
        // the lead-in's start at rapid, which the SVG draws too.
        ("plunge", "zigzag", true, false, "arc"),
        ("ramp", "offset", true, true, "arc"),
    ] {
        let (out, settings) = job_led(entry, pocket, profile, fit, lead);
        let what = format!("{entry}/{pocket}{} {lead}", if fit { " fitted" } else { "" });
        let post = settings.post().unwrap();
        let program = read(&out.gcode, post.safe_height);
        let play_rapids = kerfcam::animation::rapids(&out.scene(), &out.process, settings.post());
        let svg = kerfcam::svg::plan::to_svg(&[kerfcam::svg::plan::SheetPlan {
            label: "sign",
            scene: out.scene(),
            names: &[],
            rapids: &play_rapids,
        }]);
        let s = svg_paths(&svg);
        assert!(!s.drawing.is_empty(), "{what}: the drawing");
        // The passes lie on one another: the SVG draws each path once.
        same_path(&format!("{what} SVG feed"), &s.cuts, &split(&program, false), TOL, false);
        // The rapids are drawn as often as the program makes them: the
        // same length (a rapid repeated between passes lies on itself).
        let rapids = split(&program, true);
        same_path(&format!("{what} SVG rapids"), &s.rapids, &rapids, TOL, true);
        if profile {
            // The square's lead-out end (its loop's end with a straight
            // lead-in and no lead-out) to its lead-in start, once between
            // each two of its 3 passes: a router goes down in the waste on
            // every pass, whether its leads are arcs or straight.
            let arc = lead == "arc";
            let square = (out.plan.cuts.iter())
                .find(|c| c.steps.iter().any(|s| s.role == kerfcam::plan::Role::LeadIn && (s.segment.bulge != 0.0) == arc))
                .unwrap_or_else(|| panic!("{what}: a profile with a lead-in"));
            let (from, to) = (square.end(), square.pierce);
            let across = |m: &&XyMove| {
                let near = |p: (f64, f64), q: kerfcam::geom::Point| (p.0 - q.x).hypot(p.1 - q.y) < TOL;
                near(m.a, from) && near(m.b, to)
            };
            assert_eq!(rapids.iter().filter(across).count(), 2, "{what}: the program's rapids between passes");
            assert_eq!(s.rapids.iter().filter(across).count(), 2, "{what}: the SVG's rapids between passes");
        }
        assert_eq!(s.depths, [-2.0, -4.0, -6.0], "{what}: a sublayer per depth");
        if profile {
            continue;
        }
        // The milling alone: each depth's sublayer and the entries hold
        // what the program cuts there (the entries lie on paths drawn
        // anyway: only their length tells them apart).
        let feed = split(&program, false);
        let mut want: std::collections::BTreeMap<String, f64> = Default::default();
        for m in &feed {
            let layer = if m.z.0 != m.z.1 {
                "entries".to_string()
            } else {
                format!("Z {}", m.z.1)
            };
            *want.entry(layer).or_default() += m.length();
        }
        for (layer, l) in &want {
            let got = s.by_layer.get(layer).copied().unwrap_or(0.0);
            assert!((got - l).abs() <= 1e-4 * l, "{what}: '{layer}' drawn {got:.3} mm, program {l:.3} mm");
        }
        eprintln!("{what}: SVG by layer {:?}", s.by_layer);
    }
}

/// G91 for a router (issue 43 §5): the same job written in incremental
/// coordinates reads back, move by move, as the absolute program — X, Y
/// and Z carried on the post's grid, so no rounding accumulates over the
/// thousands of moves — and rs274 reads both.
#[test]
fn a_router_job_in_g91_reads_back_as_its_g90_program() {
    for (entry, pocket, post, fit_arcs) in [
        ("ramp", "zigzag", "grbl-router", false),
        ("helix", "offset", "linuxcnc-router", true),
    ] {
        let what = format!("{entry}/{pocket} {post}");
        let run = |incremental: bool| {
            let settings = Spec {
                tool_diameter: Some(6.0),
                depth: Some(6.0),
                pass_depth: 2.0,
                entry: entry.into(),
                pocket: pocket.into(),
                post: Some(post.into()),
                incremental,
                fit_arcs,
                tabs: 2,
                layer_ops: vec![
                    ["POCKET".into(), "pocket".into()],
                    ["PROFILE".into(), "profile".into()],
                ],
                ..Spec::default()
            }
            .build()
            .unwrap();
            let out = kerfcam::run(&common::pocket_island_dxf(true), &settings).unwrap();
            (out, settings.post().unwrap().clone())
        };
        let ((abs, post), (rel, _)) = (run(false), run(true));
        assert!(!abs.gcode.lines().any(|l| l.starts_with("G91 ")), "{what}");
        let g91 = rel.gcode.lines().filter(|l| l.starts_with("G91 ")).count();
        assert!(g91 > 2, "{what}: {g91} blocks set G91");
        for (name, text) in [("g90", &abs.gcode), ("g91", &rel.gcode)] {
            let errors = common::rs274_errors(text, &format!("milling-{name}-{entry}"));
            assert!(errors.is_empty(), "{what} {name}: {errors:?}");
        }
        let (a, b) = (read(&abs.gcode, post.safe_height), read(&rel.gcode, post.safe_height));
        assert_eq!(a.len(), b.len(), "{what}: moves");
        assert!(a.len() > 200, "{what}: {} moves", a.len());
        // Sums of the increments, in f64: equal to far within the grid's
        // half step (planted: an increment from the unrounded position
        // drifts by up to half a step a move, caught).
        let half = 0.5 * 10f64.powi(-(post.decimals as i32));
        let mut worst: f64 = 0.0;
        for (m, n) in a.iter().zip(&b) {
            assert_eq!((m.rapid, m.arc.is_some()), (n.rapid, n.arc.is_some()), "{what}");
            for (u, v) in [(m.b.0, n.b.0), (m.b.1, n.b.1), (m.z.1, n.z.1)] {
                worst = worst.max((u - v).abs());
            }
        }
        assert!(worst <= 1e-6 * half, "{what}: {worst} mm apart");
        let last = (a.last().unwrap().b, b.last().unwrap().b);
        eprintln!("{what}: {} moves, {g91} G91 blocks, worst {worst:.2e} mm; ends {:?} / {:?}", a.len(), last.0, last.1);
    }
}

/// The page's canvas preview draws the rapids the program makes (issue
/// 43 §6): with a router's post, [`kerfcam::animation::preview_rapids`]
/// — the walk Play and the plan SVG draw from — so a profile with lead
/// arcs shows the tool going up where its lead-out ends and across to
/// its lead-in between depth passes, which one rapid per cut missed.
#[test]
fn the_preview_draws_the_programs_rapids() {
    use kerfcam::preview::{self, View};
    for (entry, pocket, fit) in [("plunge", "zigzag", false), ("ramp", "offset", true)] {
        let (out, settings) = job_led(entry, pocket, true, fit, "arc");
        let what = format!("{entry}/{pocket}{} arc", if fit { " fitted" } else { "" });
        let post = settings.post().unwrap();
        let scene = out.scene();
        let walk = kerfcam::animation::rapids(&scene, &out.process, Some(post));
        let given = kerfcam::animation::preview_rapids(&scene, &out.process, Some(post))
            .unwrap_or_else(|| panic!("{what}: a router's preview is given its rapids"));
        assert_eq!(given, walk, "{what}");
        // They are the program's, read back from its text.
        let drawn: Vec<XyMove> = (given.iter())
            .map(|s| XyMove::new(true, (s.a.x, s.a.y), (s.b.x, s.b.y), None))
            .collect();
        let program = read(&out.gcode, post.safe_height);
        same_path(&format!("{what} preview rapids"), &drawn, &split(&program, true), TOL, true);
        // And drawn: grey pixels along the square's rapids between passes.
        let square = (out.plan.cuts.iter())
            .find(|c| c.steps.iter().any(|s| s.role == kerfcam::plan::Role::LeadIn && s.segment.bulge != 0.0))
            .unwrap_or_else(|| panic!("{what}: a profile with a lead-in arc"));
        let (from, to) = (square.end(), square.pierce);
        assert!(from.dist(to) > 5.0, "{what}: {from:?} -> {to:?}");
        let with = kerfcam::scene::Scene {
            rapids: Some(&given),
            ..scene
        };
        let view = View::fit(&preview::extent(&scene), 800, 600).unwrap();
        let grey_along = |sc: &kerfcam::scene::Scene| {
            let img = preview::render(sc, &view).unwrap();
            (6..=14)
                .filter(|k| {
                    let p = from.add(to.sub(from).scale(*k as f64 / 20.0));
                    let x = (p.x - view.center.x) * view.scale + view.width as f64 / 2.0;
                    let y = view.height as f64 / 2.0 - (p.y - view.center.y) * view.scale;
                    (-1..=1).any(|dx: i32| {
                        (-1..=1).any(|dy: i32| {
                            let c = img.pixel((x as i32 + dx) as u32, (y as i32 + dy) as u32).unwrap();
                            let (r, g, b) = (c.red() as i32, c.green() as i32, c.blue() as i32);
                            (r - g).abs() < 12 && (g - b).abs() < 12 && r < 235
                        })
                    })
                })
                .count()
        };
        let (now, before) = (grey_along(&with), grey_along(&scene));
        eprintln!("{what}: rapid pixels along the relift {now} of 9, one rapid per cut {before}");
        assert!(now >= 3, "{what}: the preview misses the rapid between passes ({now} of 9)");
        assert_eq!(before, 0, "{what}: one rapid per cut drew it already?");
    }
}
