//! Torch-height lock before sharp corners and near a contour's end (issue
//! 20 item 4): the post's `thc_lock`/`thc_unlock` (QtPlasmaC's synchronised
//! `M62 P2`/`M63 P2`) written where the rule says, read back from the
//! program text; every program through `rs274`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::{rs274_errors, rs274_qtplasmac};
use kerfcam::gcode::preset;
use kerfcam::origin::ProgramOrigin;
use kerfcam::process::ThcLock;
use kerfcam::Settings;

fn polygon(points: &[(f64, f64)]) -> Vec<u8> {
    let mut s = format!(
        "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n",
        points.len()
    );
    for (x, y) in points {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

fn program(dxf: &[u8], post: &str, rule: ThcLock) -> String {
    let s = Settings::new(1.5, 0.001, 2000.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .and_then(|s| s.with_post(preset(post).unwrap()))
        .and_then(|s| s.with_thc_lock(rule))
        .unwrap();
    kerfcam::run(dxf, &s).unwrap().gcode
}

/// Where the machine is at each `code` line: the last X and Y words before it.
fn at(g: &str, code: &str) -> Vec<(f64, f64)> {
    let (mut x, mut y) = (f64::NAN, f64::NAN);
    let mut out = Vec::new();
    for l in g.lines() {
        if l == code {
            out.push((x, y));
        }
        for w in l.split(' ') {
            if let Some(v) = w.strip_prefix('X').and_then(|v| v.parse().ok()) {
                x = v;
            }
            if let Some(v) = w.strip_prefix('Y').and_then(|v| v.parse().ok()) {
                y = v;
            }
        }
    }
    out
}

#[test]
fn a_square_plate_locks_5_mm_before_each_corner_and_10_mm_before_its_end() {
    let square = polygon(&[(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)]);
    let rule = ThcLock {
        corner_angle_deg: 120.0,
        corner_distance: 5.0,
        end_distance: 10.0,
    };
    let g = program(&square, "qtplasmac", rule);
    // The kerf path (1.5 mm kerf) runs 0.75 mm outside the square,
    // clockwise from the lead-in's end at (0, -0.75): up the left side,
    // right along the top, down, left along the bottom.
    let locks = at(&g, "M62 P2");
    let releases = at(&g, "M63 P2");
    assert_eq!(
        locks,
        [
            (0.0, -5.75), // at the pierce: the lead-in ends 5 mm before the first corner
            (-0.75, 95.0),
            (95.0, 100.75),
            (100.75, 5.0),
            (10.0, -0.75), // the end
        ],
        "{g}"
    );
    assert_eq!(
        releases,
        [
            (-0.75, 5.0),
            (5.0, 100.75),
            (100.75, 95.0),
            (95.0, -0.75),
            (0.0, -0.75), // after the torch is off
        ],
        "{g}"
    );
    let errors = rs274_qtplasmac(&g, "thc-square");
    assert!(errors.is_empty(), "{errors:?}");
    // Off by default: no lock on a plate with no overcut and no small hole.
    let plain = program(&square, "qtplasmac", ThcLock::OFF);
    assert!(!plain.contains("M62 P2"), "{plain}");
    // A post without lock codes writes none (and the same program).
    let linuxcnc = program(&square, "linuxcnc", rule);
    assert_eq!(linuxcnc, program(&square, "linuxcnc", ThcLock::OFF));
    assert_eq!(
        rs274_errors(&linuxcnc, "thc-linuxcnc"),
        Vec::<String>::new()
    );
}

#[test]
fn only_corners_sharper_than_the_angle_are_locked() {
    // A regular hexagon: 120° corners.
    let hex: Vec<(f64, f64)> = (0..6)
        .map(|k| {
            let a = std::f64::consts::PI / 3.0 * k as f64;
            (50.0 + 40.0 * a.cos(), 50.0 + 40.0 * a.sin())
        })
        .collect();
    let hex = polygon(&hex);
    let rule = |angle| ThcLock {
        corner_angle_deg: angle,
        corner_distance: 3.0,
        end_distance: 0.0,
    };
    let blunt = program(&hex, "qtplasmac", rule(110.0));
    assert_eq!(blunt.matches("M62 P2").count(), 0, "{blunt}");
    let sharp = program(&hex, "qtplasmac", rule(130.0));
    // Six corners, each locked and released (the last release after the
    // torch goes off when a window reaches the contour's end).
    assert!(
        (5..=6).contains(&sharp.matches("M62 P2").count()),
        "{sharp}"
    );
    assert_eq!(
        sharp.matches("M62 P2").count(),
        sharp.matches("M63 P2").count()
    );
    let errors = rs274_qtplasmac(&sharp, "thc-hexagon");
    assert!(errors.is_empty(), "{errors:?}");
}

#[test]
fn out_of_range_rules_name_the_field() {
    let s = Settings::new(1.5, 0.001, 2000.0).unwrap();
    let e = s
        .clone()
        .with_thc_lock(ThcLock {
            corner_angle_deg: 200.0,
            ..ThcLock::OFF
        })
        .unwrap_err();
    assert_eq!(e.field, "thc_corner_angle");
    let e = s
        .with_thc_lock(ThcLock {
            end_distance: -1.0,
            ..ThcLock::OFF
        })
        .unwrap_err();
    assert_eq!(e.field, "thc_end_distance");
}
