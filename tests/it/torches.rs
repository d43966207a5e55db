//! Several torches on one gantry (issue 18 §7, paper 001 §6.5): the nest of
//! torch 1's band, the copies every other torch cuts, the program that
//! drives torch 1 only and says so. The copies are checked here by sampled
//! distances (arcs evaluated from their bulge by `common::sweep`), not by
//! the engine's collision code.

use crate::common;

use common::sampled::{least_distance, sampled};
use common::{fixture, rs274_errors};
use kerfcam::contour;
use kerfcam::dxf::{self, ReadOptions};
use kerfcam::geom::{Point, Segment, Tolerance};
use kerfcam::nest::torches::{all_copies, nest_torches, TorchNest};
use kerfcam::nest::{self, output, NestError, NestJob, NestSettings, Part, Sheets};
use kerfcam::process::Torches;

fn plates(quantity: usize) -> Vec<Part> {
    let bytes = std::fs::read(fixture("seed000-plate-6-holes.dxf")).unwrap();
    let d = dxf::parse(&bytes, &ReadOptions::DEFAULT).unwrap();
    let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
    nest::parts_from_contours(&c, "plate", quantity).0
}

fn job(parts: Vec<Part>, width: f64, height: f64) -> NestJob {
    NestJob {
        parts,
        sheets: Sheets::Rect {
            width,
            height,
            count: 1,
        },
        settings: NestSettings {
            spacing: 2.5,
            margin: 5.0,
            tolerance: 0.05,
            time_s: 1e9,
            seed: 3,
            max_evaluations: Some(20),
            budget_s: None,
        },
    }
}

fn two_at_500() -> Torches {
    Torches::new(2, 500.0, Some(Point::new(0.0, 1200.0)))
        .unwrap()
        .unwrap()
}

fn run(job: &NestJob, t: &Torches) -> Result<TorchNest, NestError> {
    nest_torches(job, t, &|| 0.0, &mut |_| true)
}

#[test]
fn torch_ones_band_is_nested_and_every_torchs_copies_keep_the_spacing() {
    let j = job(plates(5), 1500.0, 1000.0);
    let tn = run(&j, &two_at_500()).unwrap();
    // 5 asked on 2 torches: 3 under torch 1, 6 made.
    assert_eq!(tn.made, [(5, 3)]);
    assert_eq!(tn.nest.placements.len(), 3);
    assert!(tn.nest.unplaced.is_empty(), "{:?}", tn.nest.unplaced);
    // The last torch's band ends at the top margin: 1000 − 10 − 500.
    assert!((tn.band - 490.0).abs() < 1e-9);
    let copies: Vec<Vec<Point>> = all_copies(&tn)
        .iter()
        .map(|(_, p)| sampled(&output::placed_loops(&j, p)[0]))
        .collect();
    assert_eq!(copies.len(), 6);
    for (k, (torch, p)) in all_copies(&tn).iter().enumerate() {
        let ys = copies[k].iter().map(|q| q.y);
        let (lo, hi) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
            (l.min(y), h.max(y))
        });
        // Torch 1's copies in its band, every copy on the sheet.
        if *torch == 0 {
            assert!(lo >= 5.0 - 1e-6 && hi <= 495.0 + 1e-6, "{p:?}: {lo}..{hi}");
        }
        assert!(lo >= 5.0 - 1e-6 && hi <= 995.0 + 1e-6, "{p:?}: {lo}..{hi}");
        for (l, other) in copies.iter().enumerate().skip(k + 1) {
            let d = least_distance(&copies[k], other);
            assert!(d >= 2.5 - 0.01, "copies {k} and {l} are {d} mm apart");
        }
    }
    // Paper 001 §6.3 on the whole sheet: six plates over 1000 × crop.
    let s = &tn.nest.sheets[0];
    assert_eq!((s.parts, s.height), (6, 1000.0));
    let area = 6.0 * j.parts[0].area();
    let useful = 1000.0 * s.crop_x.unwrap();
    assert!((s.utilisation - area / useful).abs() < 1e-9);
    // The nest DXF draws torch 2's copies on NULL, which is never cut.
    let dxf = kerfcam::nest::torches::to_dxf(&j, &tn);
    let d = dxf::parse(dxf.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    let null = d.layers.iter().position(|l| l.name == "NULL").unwrap();
    let on_null = d
        .entities
        .iter()
        .filter(|e| e.layer as usize == null)
        .count();
    assert_eq!(on_null, 3 * (1 + j.parts[0].holes.len()));
    let json = kerfcam::nest::torches::to_json(&j, &tn, 0.0, kerfcam::warning::Lang::En);
    assert_eq!(json["torches"]["parts"][0]["made"], 6);
}

/// The rapid end points and the line before each `M3`, in program order.
fn lines(program: &str) -> Vec<&str> {
    program.lines().map(str::trim).collect()
}

#[test]
fn the_program_drives_torch_one_names_the_setup_and_stops_for_it() {
    let j = job(plates(5), 1500.0, 1000.0);
    let tn = run(&j, &two_at_500()).unwrap();
    let settings = kerfcam::Settings::new(1.5, 0.001, 2000.0)
        .unwrap()
        .with_torches(2, 500.0, Some(Point::new(0.0, 1200.0)))
        .unwrap();
    let out = kerfcam::nest_cut::cut_sheet(&j, &tn.nest, 0, &settings).unwrap();
    let errors = rs274_errors(&out.gcode, "torches-2x500");
    assert!(errors.is_empty(), "{errors:?}");
    let l = lines(&out.gcode);
    let comment = l
        .iter()
        .position(|x| x.contains("2 torches 500 mm apart"))
        .unwrap();
    let park = l.iter().position(|x| *x == "G0 X0 Y1200").unwrap();
    let stop = l.iter().position(|x| *x == "M0").unwrap();
    let first_on = l.iter().position(|x| x.starts_with("M3")).unwrap();
    assert!(
        comment < park && park < stop && stop < first_on,
        "{comment} {park} {stop} {first_on}"
    );
    assert_eq!(l.iter().filter(|x| **x == "M0").count(), 1);
    // Single path: torch 1's three plates (outer + holes each) and the
    // crop line, nothing of torch 2.
    let pierces = l.iter().filter(|x| x.starts_with("M3")).count();
    assert_eq!(pierces, 3 * (1 + j.parts[0].holes.len()) + 1);
    // The crop line is cut by torch 1 from y = 1000 − 500 down, so torch 2
    // ends it on the sheet's top edge and no torch cuts past it.
    let crop = tn.nest.sheets[0].crop_x.unwrap();
    let last_rapid = l.iter().rev().find(|x| x.starts_with("G0 X")).unwrap();
    assert_eq!(*last_rapid, format!("G0 X{crop} Y500"));
    // One torch: the same sheet's program has none of it.
    let one = kerfcam::Settings::new(1.5, 0.001, 2000.0).unwrap();
    let plain = kerfcam::nest_cut::cut_sheet(&j, &tn.nest, 0, &one)
        .unwrap()
        .gcode;
    assert!(!plain.contains("torches") && !plain.lines().any(|x| x.trim() == "M0"));
    // A post that is not G-code cannot say it: refused.
    let knife = settings
        .clone()
        .with_post(kerfcam::gcode::preset("point-list").unwrap())
        .unwrap();
    let err = kerfcam::nest_cut::cut_sheet(&j, &tn.nest, 0, &knife).unwrap_err();
    assert!(err.to_string().contains("torches"), "{err}");
}

#[test]
fn parts_too_tall_for_the_band_and_impossible_setups_are_said() {
    // A 600 mm tall bar that may not turn: no band of 497.5 mm holds it.
    let bar = Part {
        name: "bar".into(),
        outer: [(0.0, 0.0), (50.0, 0.0), (50.0, 600.0), (0.0, 600.0)]
            .iter()
            .zip([(50.0, 0.0), (50.0, 600.0), (0.0, 600.0), (0.0, 0.0)])
            .map(|(&a, b)| Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1)))
            .collect(),
        holes: Vec::new(),
        quantity: 4,
        rotations: nest::Rotations::None,
        mirror: false,
    };
    let mut parts = plates(2);
    parts.push(bar);
    let j = job(parts, 1500.0, 1100.0);
    let tn = run(&j, &two_at_500()).unwrap();
    assert_eq!(tn.made, [(2, 1), (4, 0)]);
    let u = &tn.nest.unplaced;
    assert_eq!(u.len(), 1, "{u:?}");
    assert_eq!((u[0].part.as_str(), u[0].copies), ("bar", 4));
    assert!(
        u[0].reason.en.contains("under each torch"),
        "{}",
        u[0].reason
    );
    // Three torches 500 mm apart do not fit on 1000 mm.
    let err = run(
        &job(plates(3), 1500.0, 1000.0),
        &Torches::new(3, 500.0, None).unwrap().unwrap(),
    )
    .unwrap_err();
    assert!(err.to_string().contains("3 torches 500 mm apart"), "{err}");
    // Torches closer than the part spacing.
    let err = run(
        &job(plates(3), 1500.0, 1000.0),
        &Torches::new(2, 2.0, None).unwrap().unwrap(),
    )
    .unwrap_err();
    assert!(err.to_string().contains("no room"), "{err}");
}

#[test]
fn the_cli_nests_for_torches_and_writes_a_program_rs274_accepts() {
    let dir = common::out_dir();
    let ngc = dir.join("cli-torches.ngc");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .arg("nest")
        .arg(format!(
            "{}:5",
            fixture("seed000-plate-6-holes.dxf").display()
        ))
        .args([
            "--sheet",
            "1500x1000",
            "--torches",
            "2",
            "--torch-spacing",
            "500",
        ])
        .args(["--torch-park", "0,1200", "--time", "0", "--json", "--gcode"])
        .arg(&ngc)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(json["torches"]["count"], 2);
    assert_eq!(json["torches"]["parts"][0]["per_torch"], 3);
    assert_eq!(json["sheets"][0]["parts"], 6);
    let program = std::fs::read_to_string(&ngc).unwrap();
    assert!(program.contains("(2 torches 500 mm apart"));
    assert_eq!(rs274_errors(&program, "cli-torches"), Vec::<String>::new());
    for bad in [
        vec!["--torch-spacing", "500"],
        vec!["--torches", "2"],
        vec!["--torches", "40", "--torch-spacing", "10"],
        vec![
            "--torches",
            "2",
            "--torch-spacing",
            "500",
            "--torch-park",
            "x",
        ],
    ] {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
            .arg("nest")
            .arg(fixture("seed000-plate-6-holes.dxf"))
            .args(["--sheet", "1500x1000", "--time", "0"])
            .args(&bad)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success() && err.contains("torch"),
            "{bad:?}: {err}"
        );
    }
}
