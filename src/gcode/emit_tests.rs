//! Tests of `gcode::emit`.

use super::super::runs::gcode;
use super::*;
use crate::gcode::ArcMode;
use crate::geom::{Point, Segment};
use crate::plan::{Cut, Role, Step};

fn half_circle_plan() -> CutPlan {
    let s = Segment {
        a: Point::new(10.0, 0.0),
        b: Point::new(-10.0, 0.0),
        bulge: 1.0,
    };
    CutPlan {
        common_line: Vec::new(),
        arc_fit: None,
        cuts: vec![Cut {
            pierce: s.a,
            steps: vec![Step {
                segment: s,
                role: Role::Contour,
                contour: Some(0),
            }],
            contours: vec![0],
            part: Some(1),
            kind: ContourKind::Outer,
            spot: false,
            small_hole: false,
            comp: None,
        }],
        ..CutPlan::default()
    }
}

fn body(post: &Post) -> Vec<String> {
    let job = JobInfo::from_process(&crate::process::Process {
        feed: 1000.0,
        kerf: 0.0,
        ..crate::process::Process::DEFAULT
    });
    gcode(&half_circle_plan(), post, &job)
        .lines()
        .filter(|l| ["G1 ", "G2 ", "G3 ", "X"].iter().any(|w| l.starts_with(w)))
        .map(String::from)
        .collect()
}

#[test]
fn the_stats_variables_are_filled_in_when_a_template_asks() {
    // The writer computes the plan's stats only for these two.
    let post = Post {
        header: vec!["(time {est_time_s} s, {pierces} pierces, again {pierces})".into()],
        ..Post::default()
    };
    let job = JobInfo::from_process(&crate::process::Process::DEFAULT);
    let plan = half_circle_plan();
    let time = Grid::new(post.decimals).fmt_mm(super::super::est_time_s(&plan, &job));
    assert_ne!(time, "0");
    let want = format!("(time {time} s, 1 pierces, again 1)");
    assert!(
        gcode(&plan, &post, &job).lines().any(|l| l == want),
        "{want}"
    );
}

#[test]
fn a_half_circle_is_one_g3_with_a_consistent_centre() {
    assert_eq!(body(&Post::default()), ["G3 X-10 Y0 I-10 J0"]);
}

#[test]
fn arcs_split_at_the_posts_sweep_and_written_as_r_or_absolute_centres() {
    let r = Post {
        arcs: ArcMode::R,
        max_arc_sweep_deg: 90.0,
        ..Post::default()
    };
    assert_eq!(body(&r), ["G3 X0 Y10 R10", "G3 X-10 Y0 R10"]);
    let abs = Post {
        arcs: ArcMode::IjAbsolute,
        modal: true,
        max_arc_sweep_deg: 90.0,
        ..Post::default()
    };
    assert_eq!(body(&abs), ["G3 X0 Y10 I0 J0", "X-10 Y0 I0 J0"]);
}
