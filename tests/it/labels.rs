//! Labels on nested parts (issue 42 §2) judged from outside the placer:
//! on a nest of corpus parts every label lies in its copy's material,
//! clear of the outline and the holes by the margin ([`label::check`],
//! written apart from the placer: a fine flattening and exact segment
//! distances); copies too small get none and a note; scribed labels are
//! marks, cut before the parts, that rs274 reads and that lie in the parts;
//! the nest DXF carries them on layer `LABELS`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::{rs274_errors, rs274_qtplasmac, shared};
use kerfcam::contour;
use kerfcam::dxf::{self, ReadOptions};
use kerfcam::geom::{Point, Tolerance};
use kerfcam::label::{self, check, LabelOptions, Labels, Naming};
use kerfcam::nest::{self, output, Nest, NestJob, NestSettings, Part, Sheets};

const PARTS: [(&str, usize); 8] = [
    ("cadquery/1001.dxf", 20),
    ("cadquery/vslot-2020_1.dxf", 40),
    ("openbuilds-cam/Motor NEMA23 - Sliding Mount.dxf", 4),
    ("dxf2gcode-plasma/SchlittenBack.dxf", 11),
    ("maslow-mechanics/ExtraBrackets.DXF", 10),
    ("sofle/sofle_pico_key_plate_v3.5.5.dxf", 3),
    ("dxf2gcode-plasma/1997.DXF", 5),
    ("dxf2gcode-plasma/fc_mounting.dxf", 1),
];

fn parts(scale: usize) -> Vec<Part> {
    let mut parts = Vec::new();
    for (file, qty) in PARTS {
        let bytes = std::fs::read(shared().join("corpus").join(file)).unwrap();
        let d = dxf::parse(&bytes, &ReadOptions::DEFAULT).unwrap();
        let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
        // Named as `kerfcam nest` names them: the file's stem.
        let stem = std::path::Path::new(file).file_stem().unwrap().to_string_lossy();
        let (p, _) = nest::parts_from_contours(&c, &stem, qty.div_ceil(scale));
        parts.extend(p);
    }
    parts
}

fn nest_of(parts: Vec<Part>, sheets: usize) -> (NestJob, Nest) {
    let copies = parts.iter().map(|p| p.quantity).sum::<usize>() as u64;
    let job = NestJob {
        parts,
        sheets: Sheets::Rect { width: 3000.0, height: 1500.0, count: sheets },
        settings: NestSettings {
            spacing: 2.5,
            margin: 10.0,
            tolerance: 0.05,
            time_s: 1e9,
            seed: 1,
            max_evaluations: Some(copies),
            budget_s: None,
        },
    };
    let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
    (job, n)
}

/// Every label of `labels` in its copy, `margin` clear; the least clearance.
fn assert_inside(job: &NestJob, n: &Nest, labels: &Labels, margin: f64) -> f64 {
    let mut least = f64::INFINITY;
    for l in &labels.labels {
        let p = n.placements.iter().find(|p| (p.part, p.copy) == (l.part, l.copy)).unwrap();
        let loops = output::placed_loops(job, p);
        let c = check::clearance(&loops[0], &loops[1..], &l.strokes);
        assert!(c >= margin - check::FINE, "{} on {}: {c} mm clear", l.text, job.parts[l.part].name);
        least = least.min(c);
    }
    least
}

#[test]
fn every_copy_of_a_corpus_nest_is_labelled_inside_clear_of_edges_and_holes() {
    let (job, n) = nest_of(parts(1), 3);
    assert!(n.placements.iter().any(|p| p.rotation % 180.0 != 0.0), "no copy turned a quarter");
    for naming in [Naming::Name, Naming::Code] {
        let options = LabelOptions { naming, ..LabelOptions::DEFAULT };
        let t = std::time::Instant::now();
        let labels = label::label_nest(&job, &n, &options, job.settings.tolerance);
        let s = t.elapsed().as_secs_f64();
        let least = assert_inside(&job, &n, &labels, options.margin);
        eprintln!(
            "labels ({naming:?}): {} of {} copies labelled, {} left out, in {s:.3} s; least clearance {least:.3} mm",
            labels.labels.len(),
            n.placements.len(),
            labels.left_out.len()
        );
        assert_eq!(labels.labels.len() + labels.left_out.len(), n.placements.len());
        for (i, p) in job.parts.iter().enumerate() {
            let b = kerfcam::geom::path_bbox(&p.outer);
            let got = labels.labels.iter().filter(|l| l.part == i).collect::<Vec<_>>();
            eprintln!(
                "  {}: {:.0} x {:.0} mm, {} holes, area {:.0}: {} of {} labelled{}",
                p.name, b.max.x - b.min.x, b.max.y - b.min.y, p.holes.len(), p.area(),
                got.len(), p.quantity,
                got.first().map_or(String::new(), |l| format!(", {:.1} mm high", l.height))
            );
        }
        // Names are long (ExtraBrackets#3#10): many parts have no room for
        // them at 3 mm; a short code fits in every part 40 mm wide and high
        // (the 20 mm profiles and 25 mm plates full of holes have none).
        assert!(!labels.labels.is_empty());
        if naming == Naming::Code {
            for (i, p) in job.parts.iter().enumerate() {
                let b = kerfcam::geom::path_bbox(&p.outer);
                if b.max.x - b.min.x >= 40.0 && b.max.y - b.min.y >= 40.0 {
                    assert!(!labels.left_out.iter().any(|&(q, _)| q == i), "{} unlabelled", p.name);
                }
            }
        }
        // Turned copies are labelled too (short codes fit in most parts),
        // and every label reads the right way up.
        let turned = labels.labels.iter().any(|l| {
            let p = n.placements.iter().find(|p| (p.part, p.copy) == (l.part, l.copy)).unwrap();
            p.rotation % 180.0 != 0.0
        });
        assert!(turned || naming == Naming::Name);
        assert!(labels.labels.iter().all(|l| l.angle > -90.0 && l.angle <= 90.0 + 1e-6));
        // Those left out are named in the note.
        match labels.warnings.first() {
            Some(w) => {
                for &(part, _) in &labels.left_out {
                    assert!(w.message().contains(&job.parts[part].name));
                }
            }
            None => assert!(labels.left_out.is_empty()),
        }
    }
    // The check catches a label moved off its copy's material.
    let mut labels = label::label_nest(&job, &n, &LabelOptions::DEFAULT, 0.05);
    let l = &mut labels.labels[0];
    let d = Point::new(l.height * 3.0, 0.0);
    for s in &mut l.strokes {
        for q in s.iter_mut() {
            *q = q.add(d).add(d).add(d).add(d).add(d);
        }
    }
    let caught = std::panic::catch_unwind(|| assert_inside(&job, &n, &labels, 2.0));
    assert!(caught.is_err(), "a label moved off its part passed the check");
}

#[test]
fn a_part_too_small_for_the_smallest_label_gets_none_and_a_note() {
    let (job, n) = nest_of(parts(10), 1);
    // 15 mm high at least: the small brackets and plates have no room.
    let options = LabelOptions { height_min: 15.0, height_max: 30.0, ..LabelOptions::DEFAULT };
    let labels = label::label_nest(&job, &n, &options, 0.05);
    assert!(!labels.left_out.is_empty());
    assert_eq!(labels.warnings.len(), 1);
    assert_eq!(labels.warnings[0].code, "label-no-room");
    for &(part, copy) in &labels.left_out {
        assert!(labels.warnings[0].message().contains(&job.parts[part].name));
        assert!(!labels.labels.iter().any(|l| (l.part, l.copy) == (part, copy)));
    }
    assert_inside(&job, &n, &labels, options.margin);
}

#[test]
fn scribed_labels_are_marks_before_the_cuts_that_rs274_reads_inside_the_parts() {
    let (job, n) = nest_of(parts(10), 1);
    let options = LabelOptions { naming: Naming::Code, ..LabelOptions::DEFAULT };
    let labels = label::label_nest(&job, &n, &options, 0.05);
    assert!(!labels.labels.is_empty());
    let on_sheet = labels.labels.iter().filter(|l| l.sheet == 0).count();
    for (post, name) in [(None, "labels-scribed"), (Some("qtplasmac"), "labels-scribed-qtplasmac")] {
        let mut settings = kerfcam::Settings::new(1.5, 0.001, 2000.0).unwrap();
        if let Some(p) = post {
            settings = settings.with_post(kerfcam::gcode::preset(p).unwrap()).unwrap();
        }
        let out = kerfcam::nest_cut::cut_sheet_labelled(&job, &n, 0, &settings, Some(&labels)).unwrap();
        let plain = kerfcam::nest_cut::cut_sheet(&job, &n, 0, &settings).unwrap();
        let marks: Vec<_> = out.plan.cuts.iter().filter(|c| c.is_mark()).collect();
        assert!(marks.len() >= on_sheet, "{} marks for {on_sheet} labels", marks.len());
        assert!(!plain.plan.cuts.iter().any(|c| c.is_mark()));
        // Every mark before every cut; the same cuts as without labels.
        let first_cut = out.plan.cuts.iter().position(|c| !c.is_mark()).unwrap();
        assert!(out.plan.cuts[first_cut..].iter().all(|c| !c.is_mark()));
        assert_eq!(out.plan.cuts.len() - marks.len(), plain.plan.cuts.len());
        // Each mark's path lies in one copy, the margin clear.
        for m in &marks {
            let pts: Vec<Point> = std::iter::once(m.pierce)
                .chain(m.steps.iter().map(|s| s.segment.b))
                .collect();
            let inside = n.placements.iter().filter(|p| p.sheet == 0).any(|p| {
                let loops = output::placed_loops(&job, p);
                check::clearance(&loops[0], &loops[1..], std::slice::from_ref(&pts)) >= options.margin - check::FINE
            });
            assert!(inside, "a mark from {:?} outside every part", m.pierce);
        }
        let errors = match post {
            Some(_) => {
                assert!(out.gcode.contains("M3 $1"), "the scribe's code");
                rs274_qtplasmac(&out.gcode, name)
            }
            None => rs274_errors(&out.gcode, name),
        };
        assert!(errors.is_empty(), "{errors:?}");
        // Labels are geometry, never comment text.
        for l in &labels.labels {
            assert!(!out.gcode.contains(&format!("({}", l.text)));
        }
    }
}

#[test]
fn the_nest_dxf_carries_labels_on_layer_labels_and_the_svg_a_group() {
    let (mut job, n) = nest_of(parts(10), 1);
    let codes = LabelOptions { naming: Naming::Code, ..LabelOptions::DEFAULT };
    let first = label::label_nest(&job, &n, &codes, 0.05).labels[0].clone();
    job.parts[first.part].name = "<&\">".into();
    let labels = label::label_nest(&job, &n, &LabelOptions::DEFAULT, 0.05);
    let overlays = label::output::overlays(&labels);
    let text = output::to_dxf_with(&job, &n, &overlays);
    let strokes: usize = labels.labels.iter().map(|l| l.strokes.len()).sum();
    assert!(strokes > 0);
    assert_eq!(text.matches("\n8\nLABELS\n").count(), strokes);
    let d = dxf::parse(text.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    let layer = d.layers.iter().find(|l| l.name == "LABELS").expect("layer LABELS");
    assert_eq!(layer.entities, strokes);
    // Read back, the labels are scribed, not cut.
    assert_eq!(kerfcam::process::op_by_name("LABELS"), kerfcam::process::Operation::Mark);
    // Without labels, as before.
    assert!(!output::to_dxf(&job, &n).contains("LABELS"));
    let svg = nest::svg_out::to_svg_with(&job, &n, &overlays);
    assert!(svg.contains("<g class=\"LABELS\""));
    let name = format!("data-name=\"&lt;&amp;&quot;&gt;#{}\"", first.copy + 1);
    assert!(svg.contains(&name), "{name}");
    assert!(!svg.contains("<&"));
}

#[test]
fn kerfcam_nest_labels_and_scribes_from_the_command_line() {
    let dir = common::out_dir();
    let part = shared().join("corpus").join("maslow-mechanics/ExtraBrackets.DXF");
    let (dxf_out, ngc) = (dir.join("labels-cli.dxf"), dir.join("labels-cli.ngc"));
    let run = |extra: &[&str]| {
        let mut args = vec![
            "nest".to_string(),
            format!("{}:6", part.display()),
            "--sheet".into(),
            "1000x500".into(),
            "--time".into(),
            "0".into(),
        ];
        args.extend(extra.iter().map(|s| s.to_string()));
        std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam")).args(&args).output().unwrap()
    };
    let o = run(&[
        "--labels", "code", "--label-mark", "--label-min", "2", "--json",
        "-o", dxf_out.to_str().unwrap(), "--gcode", ngc.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let placed = json["labels"].as_array().unwrap().len();
    let left = json["labels_left_out"].as_array().unwrap().len();
    assert_eq!(placed + left, json["placed"].as_u64().unwrap() as usize);
    assert!(placed > 0);
    assert_eq!(json["labels"][0]["text"].as_str().unwrap().chars().next(), Some('A'));
    assert!(std::fs::read_to_string(&dxf_out).unwrap().contains("\n8\nLABELS\n"));
    let program = std::fs::read_to_string(&ngc).unwrap();
    let errors = rs274_errors(&program, "labels-cli");
    assert!(errors.is_empty(), "{errors:?}");
    // A label height that fits nowhere is said at its flag.
    let o = run(&["--labels", "name", "--label-min", "0"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--label-min"));
}
