//! The program is the same on any number of threads (issue 17): a plate
//! of 3,840 cuts (outers, small holes, centre-spots) read, planned and
//! written on one thread and on three, then written by every preset with
//! each job option on one thread and on three (the writer splits from
//! 3,000 cuts), compared byte for byte.
#![cfg(not(target_arch = "wasm32"))]

use kerfcam::gcode::{emit_post, preset, JobInfo, PRESET_NAMES};
use kerfcam::origin::ProgramOrigin;
use kerfcam::par::Threads;
use kerfcam::process::{Passes, Process, SmallHole, ThcLock};
use kerfcam::Settings;

/// A closed LWPOLYLINE through `pts` (x, y, bulge).
fn lwpoly(s: &mut String, pts: &[(f64, f64, f64)]) {
    *s += &format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", pts.len());
    for (x, y, b) in pts {
        *s += &format!("10\n{x}\n20\n{y}\n42\n{b}\n");
    }
}

/// 40 x 32 plates of 20 x 14 mm, each with a 6 mm hole (small under the
/// rule below) and a 1 mm one (a centre-spot), a corner rounded.
fn plate() -> Vec<u8> {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
    for i in 0..40 {
        for j in 0..32 {
            let (x, y) = (i as f64 * 25.0, j as f64 * 19.0);
            lwpoly(
                &mut s,
                &[
                    (x, y, 0.0),
                    (x + 20.0, y, 0.0),
                    (x + 20.0, y + 12.0, 0.4142),
                    (x + 18.0, y + 14.0, 0.0),
                    (x, y + 14.0, 0.0),
                ],
            );
            lwpoly(&mut s, &[(x + 4.0, y + 7.0, 1.0), (x + 10.0, y + 7.0, 1.0)]);
            lwpoly(
                &mut s,
                &[(x + 14.0, y + 7.0, 1.0), (x + 15.0, y + 7.0, 1.0)],
            );
        }
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

fn settings(threads: usize) -> Settings {
    Settings::new(1.5, 0.001, 2000.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .and_then(|s| s.with_post(preset("qtplasmac").unwrap()))
        .and_then(|s| {
            s.with_small_hole(SmallHole {
                diameter: 8.0,
                speed_pct: 60.0,
                min_diameter: 1.5,
                ..Process::DEFAULT.small_hole
            })
        })
        .and_then(|s| {
            s.with_thc_lock(ThcLock {
                corner_angle_deg: 120.0,
                corner_distance: 3.0,
                end_distance: 0.0,
            })
        })
        .unwrap()
        .with_threads(Threads::new(threads))
}

#[test]
fn a_plate_is_read_planned_and_written_the_same_on_one_and_three_threads() {
    let dxf = plate();
    let one = kerfcam::run(&dxf, &settings(1)).unwrap();
    let three = kerfcam::run(&dxf, &settings(3)).unwrap();
    assert!(one.plan.cuts.len() >= 3000, "{}", one.plan.cuts.len());
    assert!(one.plan.cuts.iter().any(|c| c.spot) && one.plan.cuts.iter().any(|c| c.small_hole));
    assert_eq!(format!("{:?}", one.plan), format!("{:?}", three.plan));
    assert!(one.gcode == three.gcode);
    // Every preset, with each option that changes what a cut leaves.
    let plain = Process {
        small_hole: kerfcam::process::SmallHole {
            speed_pct: 60.0,
            ..Process::DEFAULT.small_hole
        },
        ..Process::DEFAULT
    };
    let jobs = [
        plain,
        Process {
            thc_lock: ThcLock {
                corner_angle_deg: 120.0,
                corner_distance: 3.0,
                end_distance: 2.0,
            },
            pierce_delay: 0.5,
            ..plain
        },
        Process {
            passes: Passes {
                depth: 5.0,
                pass_depth: 2.0,
            },
            ..plain
        },
    ]
    .map(|p| JobInfo::from_process(&p));
    let mut written = 0;
    for name in PRESET_NAMES {
        let post = preset(name).unwrap();
        for job in jobs {
            let a = emit_post(
                &one.plan,
                &post,
                &JobInfo {
                    threads: Threads::ONE,
                    ..job
                },
            );
            let b = emit_post(
                &one.plan,
                &post,
                &JobInfo {
                    threads: Threads::new(3),
                    ..job
                },
            );
            match (a, b) {
                (Ok(a), Ok(b)) => {
                    assert!(a == b, "{name} {job:?}");
                    written += 1;
                }
                (Err(a), Err(b)) => assert_eq!(a, b, "{name}"),
                (a, b) => panic!("{name}: {a:?} / {b:?}"),
            }
        }
    }
    assert!(written >= 25, "{written}");
}
