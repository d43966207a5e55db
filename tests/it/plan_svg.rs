//! The cut plan written as SVG (issue 41 §5) reads back, through our own
//! SVG reader, into the plan's geometry: every kerf-path, lead and drawn
//! segment of each part, on that part's layer, within a micrometre; part
//! names are written as data (escaped), and the command line writes the
//! SVG when -o names an .svg file.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use kerfcam::contour::Contours;
use kerfcam::dxf::{Drawing, ReadOptions};
use kerfcam::geom::{dist_to_segment, BBox, Point, Segment};
use kerfcam::plan::Role;
use kerfcam::svg::plan::{to_svg, SheetPlan};

const EPS: f64 = 1e-5;

/// The segments read on the layer named `layer`.
fn on_layer<'a>(d: &'a Drawing, layer: &str) -> Vec<&'a Segment> {
    let Some(k) = d.layers.iter().position(|l| l.name == layer) else {
        return Vec::new();
    };
    d.entities
        .iter()
        .filter(|e| e.layer as usize == k)
        .flat_map(|e| e.segments.iter())
        .collect()
}

/// The box of segments (exact, arcs included).
fn bbox<'a>(segs: impl IntoIterator<Item = &'a Segment>) -> BBox {
    let mut bb = BBox::EMPTY;
    for s in segs {
        bb.union(&s.bbox());
    }
    bb
}

/// `a` and `b` (read back, shifted by `shift`) are the same lines and
/// arcs: as long, and every point sampled on either within [`EPS`] of the
/// other (the reader splits arcs into quarter turns: segments differ).
fn same_geometry(want: &[Segment], got: &[&Segment], shift: Point, what: &str) {
    let len = |v: &mut dyn Iterator<Item = &Segment>| v.map(Segment::length).sum::<f64>();
    let (lw, lg) = (len(&mut want.iter()), len(&mut got.iter().copied()));
    assert!(
        (lw - lg).abs() < 1e-4,
        "{what}: length {lw} written, {lg} read"
    );
    assert_eq!(want.is_empty(), got.is_empty(), "{what}");
    let moved: Vec<Segment> = want
        .iter()
        .map(|s| Segment {
            a: s.a.sub(shift),
            b: s.b.sub(shift),
            bulge: s.bulge,
        })
        .collect();
    let on = |p: Point, set: &mut dyn Iterator<Item = &Segment>| {
        set.map(|s| dist_to_segment(p, s))
            .fold(f64::INFINITY, f64::min)
            < EPS
    };
    for s in &moved {
        for k in 0..=8 {
            let p = s.point_at(k as f64 / 8.0);
            assert!(
                on(p, &mut got.iter().copied()),
                "{what}: {p:?} of {s:?} not read back"
            );
        }
    }
    for s in got {
        for k in 0..=8 {
            let p = s.point_at(k as f64 / 8.0);
            assert!(
                on(p, &mut moved.iter()),
                "{what}: {p:?} of {s:?} read, not written"
            );
        }
    }
}

/// The part (1-based) of contour `i`.
fn part_of(c: &Contours, i: usize) -> u32 {
    c.contours[i].source.part
}

#[test]
fn the_plan_svg_reads_back_as_the_plans_kerf_paths_leads_and_drawing() {
    let settings = common::kerf(1.5);
    let out = common::run(&common::fixture("seed000-plate-6-holes.dxf"), &settings).unwrap();
    let rapids = kerfcam::animation::rapids(&out.scene(), &out.process, settings.post());
    let svg = to_svg(&[SheetPlan {
        label: "plate",
        scene: out.scene(),
        names: &[],
        rapids: &rapids,
    }]);
    let back = kerfcam::svg::parse(svg.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    assert!(
        !back.warnings.iter().any(|w| w.code == "units-assumed"),
        "the page is in mm: {:?}",
        back.warnings
    );
    // The reader puts the page's lower-left corner at 0,0: the shift is
    // where the drawing's contours were against where they are read.
    let drawn: Vec<Segment> = out
        .contours
        .contours
        .iter()
        .filter(|c| c.source.part > 0)
        .flat_map(|c| c.segments.iter().copied())
        .collect();
    let parts = out.contours.parts as u32;
    assert!(parts >= 1);
    let read_drawn: Vec<&Segment> = (1..=parts)
        .flat_map(|p| on_layer(&back, &format!("plate/part {p}/drawing")))
        .collect();
    let shift = bbox(&drawn).min.sub(bbox(read_drawn.iter().copied()).min);
    same_geometry(&drawn, &read_drawn, shift, "drawing");
    let mut kerf_total = 0;
    for p in 1..=parts {
        let steps = |roles: &[Role]| -> Vec<Segment> {
            out.plan
                .cuts
                .iter()
                .flat_map(|c| c.steps.iter().map(move |s| (c, s)))
                .filter(|(c, s)| {
                    let i = s.contour.or(c.contours.first().copied());
                    roles.contains(&s.role) && i.is_some_and(|i| part_of(&out.contours, i) == p)
                })
                .map(|(_, s)| s.segment)
                .collect()
        };
        let kerf = steps(&[Role::Contour, Role::Repeat]);
        kerf_total += kerf.len();
        let got = on_layer(&back, &format!("plate/part {p}/kerf path"));
        same_geometry(&kerf, &got, shift, &format!("part {p} kerf path"));
        let leads = steps(&[Role::LeadIn, Role::LeadOut, Role::Link]);
        let got = on_layer(&back, &format!("plate/part {p}/leads"));
        same_geometry(&leads, &got, shift, &format!("part {p} leads"));
    }
    assert!(kerf_total > 0, "the plate has kerf paths");
    // The kerf paths are offset from the drawing: the test would not pass
    // with the drawn contours written in their place.
    assert!(
        bbox(&drawn).min.dist(
            bbox(
                out.plan
                    .cuts
                    .iter()
                    .flat_map(|c| &c.steps)
                    .filter(|s| s.role == Role::Contour)
                    .map(|s| &s.segment)
            )
            .min
        ) > 0.5
    );
    // One pierce dot per pierce, numbered.
    let texts = svg.matches("<text ").count();
    assert_eq!(texts, out.plan.pierces());
    // Arcs as SVG arcs, at true size.
    assert!(svg.contains(" A6 6 0 0 0 "), "the holes' arcs, as drawn");
    assert!(
        svg.contains(" A5.25 5.25 0 0 0 "),
        "and offset by half the kerf"
    );
    assert!(svg.contains("mm\" height=\""));
}

#[test]
fn part_names_are_written_as_data() {
    let settings = common::kerf(0.0);
    let out = common::run(&common::fixture("seed000-plate-6-holes.dxf"), &settings).unwrap();
    let name = "a <b> & \"c\" 'd'".to_string();
    let names = [name.clone()];
    let rapids = kerfcam::animation::rapids(&out.scene(), &out.process, settings.post());
    let svg = to_svg(&[SheetPlan {
        label: "sheet <1> & \"x\"",
        scene: out.scene(),
        names: &names,
        rapids: &rapids,
    }]);
    assert!(!svg.contains("<b>") && !svg.contains("<1>"), "{svg}");
    assert!(svg.contains("a &lt;b&gt; &amp; &quot;c&quot; &apos;d&apos; #1"));
    // Read back, the labels are the names as given.
    let back = kerfcam::svg::parse(svg.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    let want = format!("sheet <1> & \"x\"/{name} #1/kerf path");
    assert!(
        back.layers.iter().any(|l| l.name == want),
        "{want} in {:?}",
        back.layers.iter().map(|l| &l.name).collect::<Vec<_>>()
    );
}

#[test]
fn the_command_line_writes_the_plan_as_svg_for_an_svg_output() {
    let dir = common::out_dir().join("plan-svg");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("plate.svg");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .arg(common::fixture("seed000-plate-6-holes.dxf"))
        .args(["-q", "-o"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.starts_with("<?xml") && svg.contains("inkscape:groupmode=\"layer\""));
    assert!(!svg.contains("G21"), "not the program");
    let back = kerfcam::svg::parse(svg.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    assert!(back
        .layers
        .iter()
        .any(|l| l.name.ends_with("/part 1/kerf path")));
}
