//! Tests of `gcode::runs`: the program written on several threads is the
//! one written on one, with every preset, on a plan of every kind of cut.

use super::super::emit::Cutter;
use super::super::{emit_post, preset, JobInfo, Post, PRESET_NAMES};
use super::*;
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};
use crate::plan::{Cut, CutPlan, Role, Step};
use crate::process::{Passes, Process, ThcLock, Torches};

fn step(a: (f64, f64), b: (f64, f64), bulge: f64, role: Role) -> Step {
    Step {
        segment: Segment {
            a: Point::new(a.0, a.1),
            b: Point::new(b.0, b.1),
            bulge,
        },
        role,
        contour: Some(0),
    }
}

/// Cut `i` of a plate of cuts of every kind, repeating every 7 cuts:
/// a square with a lead-in, a corner just before its end and a lead-out
/// (a lock window left open past the cut), a mark after it (it takes the
/// window over: the cut before a run's start is then not enough to know
/// the state), a hole of two arcs (one longer than the posts' sweep) with
/// a tab, a small hole with compensation, a spot, an open path of tiny
/// and arced steps; and kind 7, a mark 1.5 mm long (two reach past the square's window).
fn cut(i: usize, kind: usize) -> Cut {
    let (x, y) = (
        (i % 60) as f64 * 30.0 + 0.1234,
        (i / 60) as f64 * 30.0 + 0.5678,
    );
    let p = |dx: f64, dy: f64| (x + dx, y + dy);
    let (steps, kind, spot, small_hole, comp) = match kind {
        0 => (
            vec![
                step(p(-2.0, 0.0), p(0.0, 0.0), 0.0, Role::LeadIn),
                step(p(0.0, 0.0), p(20.0, 0.0), 0.0, Role::Contour),
                step(p(20.0, 0.0), p(20.0, 20.0), 0.0, Role::Contour),
                step(p(20.0, 20.0), p(0.0, 20.0), 0.0, Role::Contour),
                step(p(0.0, 20.0), p(0.0, 1.0), 0.0, Role::Contour),
                step(p(0.0, 1.0), p(1.0, 1.0), 0.0, Role::Contour),
                step(p(1.0, 1.0), p(1.0, 3.0), 0.0, Role::LeadOut),
            ],
            ContourKind::Outer,
            false,
            false,
            None,
        ),
        1 => (
            vec![
                step(p(0.0, 0.0), p(10.0, 0.3), 0.0, Role::Mark),
                step(p(10.0, 0.3), p(10.0, 5.0), 0.2, Role::Mark),
            ],
            ContourKind::Open,
            false,
            false,
            None,
        ),
        7 => (
            vec![step(p(0.0, 0.0), p(1.5, 0.0), 0.0, Role::Mark)],
            ContourKind::Open,
            false,
            false,
            None,
        ),
        2 | 5 => (
            vec![
                step(p(5.0, 5.0), p(15.0, 5.0), 1.5, Role::Contour),
                step(p(15.0, 5.0), p(14.0, 8.0), 0.0, Role::Tab),
                step(p(14.0, 8.0), p(5.0, 5.0), 0.3, Role::Contour),
            ],
            ContourKind::Hole,
            false,
            false,
            None,
        ),
        3 => (
            vec![
                step(p(8.0, 8.0), p(12.0, 8.0), 1.0, Role::Contour),
                step(p(12.0, 8.0), p(8.0, 8.0), 1.0, Role::Contour),
            ],
            ContourKind::Hole,
            false,
            true,
            Some(i.is_multiple_of(2)),
        ),
        4 => (Vec::new(), ContourKind::Open, true, false, None),
        _ => (
            vec![
                step(p(0.0, 0.0), p(0.0001, 0.0), 0.0, Role::Contour),
                step(p(0.0001, 0.0), p(7.0, 3.0), -0.7, Role::Contour),
                step(p(7.0, 3.0), p(9.0, 3.0), 0.0, Role::Contour),
            ],
            ContourKind::Open,
            false,
            false,
            None,
        ),
    };
    Cut {
        pierce: steps
            .first()
            .map_or(Point::new(p(3.0, 3.0).0, p(3.0, 3.0).1), |s| s.segment.a),
        steps,
        contours: vec![i],
        part: (!i.is_multiple_of(3)).then_some(i / 7),
        kind,
        spot,
        small_hole,
        comp,
    }
}

fn plate(n: usize) -> CutPlan {
    plate_of(n, &[0, 1, 2, 3, 4, 5, 6])
}

/// `n` cuts whose kinds repeat `kinds` (see [`cut`]).
fn plate_of(n: usize, kinds: &[usize]) -> CutPlan {
    CutPlan {
        cuts: (0..n).map(|i| cut(i, kinds[i % kinds.len()])).collect(),
        ..CutPlan::default()
    }
}

/// The program written in runs of `min_run` cuts at least, and how many
/// runs were written again (None: on one thread).
fn program(
    plan: &CutPlan,
    post: &Post,
    job: &JobInfo,
    threads: usize,
    min_run: usize,
) -> (String, Option<usize>) {
    let mut c = Cutter::new(plan, post, job);
    let redone = write_runs(&mut c, Threads::new(threads), min_run);
    if redone.is_none() {
        for i in 0..plan.cuts.len() {
            c.cut(i);
        }
    }
    (c.finish(), redone)
}

/// The jobs that change what a cut leaves: plain, corner locks with no
/// end lock (a window left open past a cut), depth passes, a pierce
/// delay and torches parked before the first cut.
fn jobs() -> Vec<JobInfo> {
    let plain = JobInfo::from_process(&Process::DEFAULT);
    vec![
        plain,
        JobInfo::from_process(&Process {
            thc_lock: ThcLock {
                corner_angle_deg: 120.0,
                corner_distance: 5.0,
                end_distance: 0.0,
            },
            ..Process::DEFAULT
        }),
        JobInfo::from_process(&Process {
            passes: Passes {
                depth: 6.0,
                pass_depth: 2.5,
            },
            ..Process::DEFAULT
        }),
        JobInfo::from_process(&Process {
            pierce_delay: 0.4,
            torches: Some(Torches {
                count: 2,
                spacing: 600.0,
                park: Some(Point::new(-10.0, -10.0)),
            }),
            ..Process::DEFAULT
        }),
    ]
}

fn posts() -> Vec<Post> {
    let mut posts: Vec<Post> = PRESET_NAMES.iter().filter_map(|n| preset(n)).collect();
    posts.push(Post {
        modal: true,
        trailing_zeros: true,
        ..Post::default()
    });
    posts
}

#[test]
fn every_preset_writes_the_same_program_on_one_two_and_three_threads() {
    let plan = plate(4000);
    let mut written = 0;
    for post in posts() {
        for job in jobs() {
            let one = emit_post(
                &plan,
                &post,
                &JobInfo {
                    threads: Threads::ONE,
                    ..job
                },
            );
            for t in [2, 3] {
                let many = emit_post(
                    &plan,
                    &post,
                    &JobInfo {
                        threads: Threads::new(t),
                        ..job
                    },
                );
                match (&one, &many) {
                    (Ok(a), Ok(b)) => assert!(a == b, "{} {job:?} on {t} threads", post.name),
                    (Err(a), Err(b)) => assert_eq!(a, b),
                    _ => panic!("{}: {one:?} / {many:?}", post.name),
                }
            }
            let Ok(one) = one else { continue };
            written += 1;
            // Many short runs: a boundary after every kind of cut.
            if post.validate().is_ok() && (post.format == super::super::Format::Gcode) {
                for t in [2, 3] {
                    let (many, _) = program(&plan, &post, &job, t, 97);
                    assert!(
                        many == one,
                        "{} {job:?} on {t} threads, short runs",
                        post.name
                    );
                }
            }
        }
    }
    assert!(written >= 30, "{written}");
}

#[test]
fn a_wrong_guess_is_written_again() {
    // The locks' job on QtPlasmaC, a square then two short marks: the
    // second mark takes over the window the square left open, so a run
    // that starts with it guesses wrong from the first mark, and is caught.
    let plan = plate_of(4000, &[0, 7, 7]);
    let post = preset("qtplasmac").unwrap();
    let job = jobs()[1];
    let (one, none) = program(&plan, &post, &job, 1, 100);
    assert_eq!(none, None);
    for t in [2, 3] {
        let (many, redone) = program(&plan, &post, &job, t, 100);
        assert!(many == one, "{t}");
        assert!(redone.is_some_and(|r| r > 0), "{redone:?}");
    }
    // Without the locks, every guess is right.
    let (_, redone) = program(&plan, &post, &jobs()[0], 3, 100);
    assert_eq!(redone, Some(0));
}

#[test]
fn one_thread_writes_few_cuts_numbered_blocks_and_a_knife() {
    let job = jobs()[0];
    for (n, name, t) in [
        (2 * MIN_RUN - 1, "linuxcnc", 3),
        (4000, "linuxcnc", 1),
        (4000, "iso6983", 3),
        (4000, "annex-h", 3),
        (4000, "knife-gcode", 3),
    ] {
        let plan = plate(n);
        let post = preset(name).unwrap();
        let mut c = Cutter::new(&plan, &post, &job);
        assert_eq!(write_cuts(&mut c, Threads::new(t)), None, "{name}");
    }
    let plan = plate(2 * MIN_RUN);
    let post = preset("linuxcnc").unwrap();
    let mut c = Cutter::new(&plan, &post, &job);
    assert_eq!(write_cuts(&mut c, Threads::new(2)), Some(0));
}

#[test]
fn runs_are_copied_in_order() {
    let parts: Vec<Vec<u8>> = (0..9u8).map(|i| vec![b'a' + i; 3 + i as usize]).collect();
    let slices: Vec<&[u8]> = parts.iter().map(Vec::as_slice).collect();
    let want = parts.concat();
    for t in 1..=4 {
        let mut dst = vec![0u8; want.len()];
        fill(&mut dst, &slices, Threads::new(t));
        assert_eq!(dst, want, "{t}");
    }
}
