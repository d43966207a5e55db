//! Tests of [`super`]: curves against their exact geometry.

use super::*;
use crate::dxf::ellipse::{ellipse, EllipseCurve};
use crate::test_rng::unit;

fn pairs(src: &[(i32, &'static str)]) -> Vec<Pair<'static>> {
    crate::dxf::pairs::text_pairs(src)
}

#[test]
fn quarter_circle_as_rational_quadratic_spline_stays_on_the_circle() {
    let w = std::f64::consts::FRAC_1_SQRT_2.to_string();
    let w: &'static str = Box::leak(w.into_boxed_str());
    let p = pairs(&[
        (70, "4"),
        (71, "2"),
        (40, "0"),
        (40, "0"),
        (40, "0"),
        (40, "1"),
        (40, "1"),
        (40, "1"),
        (41, "1"),
        (41, w),
        (41, "1"),
        (10, "10"),
        (20, "0"),
        (10, "10"),
        (20, "10"),
        (10, "0"),
        (20, "10"),
    ]);
    let (segs, closed, note) = spline(&p, 0.001).unwrap();
    assert!(!closed && note.is_none());
    // Arcs of the circle itself: a few, where lines took dozens.
    assert!(segs.len() <= 8, "{}", segs.len());
    for s in &segs {
        let (c, r) = s.arc_center().unwrap();
        assert!(c.norm() < 1e-6 && (r - 10.0).abs() < 1e-6, "{c:?} {r}");
    }
    let len: f64 = segs.iter().map(Segment::length).sum();
    assert!((len - std::f64::consts::FRAC_PI_2 * 10.0).abs() < 1e-6);
}

#[test]
fn full_ellipse_is_closed_and_has_the_right_perimeter() {
    let p = pairs(&[
        (10, "5"),
        (20, "5"),
        (11, "20"),
        (21, "0"),
        (40, "0.5"),
        (41, "0"),
        (42, "6.283185307179586"),
    ]);
    let (segs, closed) = ellipse(&p, 0.001).unwrap();
    assert!(closed);
    // Lines within 0.001 took about 300 segments (chord 2·√(2ρ·tol), ρ 5 to 40).
    assert!(segs.len() < 120, "{}", segs.len());
    assert_eq!(segs.first().unwrap().a, segs.last().unwrap().b);
    let area = crate::geom::loop_area(&segs);
    assert!(
        (area - std::f64::consts::PI * 20.0 * 10.0).abs() / area < 1e-4,
        "{area}"
    );
}

#[test]
fn a_tilted_ellipse_is_projected_onto_xy() {
    // A circle of radius 10 in a plane tilted 60° about X: from above, an
    // ellipse with semi-axes 10 (along X) and 10·cos 60° = 5.
    let (s, c) = 60f64.to_radians().sin_cos();
    let text = |v: f64| -> &'static str { Box::leak(v.to_string().into_boxed_str()) };
    let p = pairs(&[
        (10, "0"),
        (20, "0"),
        (11, "10"),
        (21, "0"),
        (31, "0"),
        (40, "1"),
        (210, "0"),
        (220, text(-s)),
        (230, text(c)),
    ]);
    let (segs, closed) = ellipse(&p, 0.001).unwrap();
    assert!(closed);
    let area = crate::geom::loop_area(&segs);
    assert!((area - std::f64::consts::PI * 50.0).abs() < 0.05, "{area}");
    let top = segs.iter().map(|s| s.a.y).fold(f64::MIN, f64::max);
    assert!((top - 5.0).abs() < 1e-3, "{top}");
}

#[test]
fn fit_point_spline_passes_through_its_fit_points() {
    let p = pairs(&[
        (71, "3"),
        (11, "0"),
        (21, "0"),
        (11, "10"),
        (21, "5"),
        (11, "20"),
        (21, "0"),
    ]);
    let (segs, _, note) = spline(&p, 0.001).unwrap();
    assert!(note.is_some());
    assert!(segs.iter().any(|s| s.a.dist(Point::new(10.0, 5.0)) < 1e-9));
    assert_eq!(segs.last().unwrap().b, Point::new(20.0, 0.0));
}

/// Largest distance from dense points of `f` on [t0, t1] to `segs`, and
/// from dense points of `segs` to the dense polyline of `f`.
fn deviation(f: &dyn Fn(f64) -> Point, t0: f64, t1: f64, segs: &[Segment]) -> f64 {
    let n = 4000;
    let curve: Vec<Point> = (0..=n)
        .map(|k| f(t0 + (t1 - t0) * k as f64 / n as f64))
        .collect();
    let near = |q: Point, segs: &[Segment]| {
        segs.iter()
            .map(|s| crate::geom::dist_to_segment(q, s))
            .fold(f64::MAX, f64::min)
    };
    let poly: Vec<Segment> = curve
        .windows(2)
        .map(|w| Segment::line(w[0], w[1]))
        .collect();
    let there = curve.iter().map(|&q| near(q, segs)).fold(0.0, f64::max);
    let back = segs
        .iter()
        .flat_map(|s| (0..8).map(move |k| s.point_at(k as f64 / 8.0)))
        .map(|q| near(q, &poly))
        .fold(0.0, f64::max);
    there.max(back)
}

#[test]
fn random_ellipses_stay_within_the_chord_as_few_arcs() {
    let mut r = unit(0x9e37_79b9_7f4a_7c15);
    for _ in 0..30 {
        let (a, ratio, rot) = (1.0 + 200.0 * r(), 0.05 + 0.95 * r(), r() * 6.0);
        let (t0, sweep) = (r() * 6.0, 0.3 + r() * 6.0);
        let tol = [0.001, 0.01, 0.1][(r() * 3.0) as usize];
        let major = Point::new(a * rot.cos(), a * rot.sin());
        let minor = major.perp().scale(ratio);
        let f = |t: f64| major.scale(t.cos()).add(minor.scale(t.sin()));
        let text = |v: f64| -> &'static str { Box::leak(v.to_string().into_boxed_str()) };
        let p = pairs(&[
            (10, "0"),
            (20, "0"),
            (11, text(major.x)),
            (21, text(major.y)),
            (40, text(ratio)),
            (41, text(t0)),
            (42, text(t0 + sweep)),
        ]);
        let (segs, _) = ellipse(&p, tol).unwrap();
        let dev = deviation(&f, t0, t0 + sweep, &segs);
        assert!(
            dev <= tol * 1.01,
            "deviation {dev} > {tol} (a {a}, ratio {ratio})"
        );
    }
}

#[test]
fn random_splines_stay_within_the_chord_and_closed_ones_close() {
    let mut r = unit(0x2545_f491_4f6c_dd1d);
    for case in 0..30 {
        let n = 4 + (r() * 8.0) as usize;
        let degree = 2 + case % 2;
        let closed = case % 3 == 0;
        let mut ctrl: Vec<Point> = (0..n)
            .map(|_| Point::new(r() * 100.0, r() * 100.0))
            .collect();
        if closed {
            ctrl.push(ctrl[0]);
        }
        let knots = clamped_uniform(ctrl.len(), degree);
        let curve = Nurbs {
            degree,
            knots: knots.clone(),
            ctrl: ctrl.iter().map(|q| [q.x, q.y, 1.0]).collect(),
        };
        let text = |v: f64| -> &'static str { Box::leak(v.to_string().into_boxed_str()) };
        let mut src = vec![
            (70, if closed { "1" } else { "0" }),
            (71, text(degree as f64)),
        ];
        src.extend(knots.iter().map(|&k| (40, text(k))));
        for q in &ctrl {
            src.push((10, text(q.x)));
            src.push((20, text(q.y)));
        }
        let tol = 0.01;
        let (segs, closes, _) = spline(&pairs(&src), tol).unwrap();
        let (lo, hi) = curve.domain();
        let dev = deviation(&|u| curve.eval(u), lo, hi, &segs);
        assert!(dev <= tol * 1.01, "case {case}: deviation {dev}");
        assert_eq!(closes, closed, "case {case}");
        if closed {
            assert_eq!(segs[0].a, segs[segs.len() - 1].b);
        }
        for w in segs.windows(2) {
            assert_eq!(w[0].b, w[1].a, "case {case}: a gap");
        }
    }
}

#[test]
fn bezier_pieces_and_their_velocity_agree_with_de_boor() {
    use crate::dxf::biarc::Curve;
    let mut r = unit(0x9e37_79b9_7f4a_7c15);
    for case in 0..60 {
        let degree = 1 + case % 5;
        let n = degree + 1 + (r() * 6.0) as usize;
        // Uneven knots with a repeated inner one (a corner) now and then.
        let mut knots: Vec<f64> = (0..n + degree + 1).map(|_| r() * 10.0).collect();
        knots.sort_by(f64::total_cmp);
        if case % 4 == 0 {
            knots[degree + 1] = knots[degree + 2];
        }
        let ctrl: Vec<[f64; 3]> = (0..n)
            .map(|_| {
                let w = 0.2 + r() * 3.0;
                [r() * 100.0 * w, r() * 100.0 * w, w]
            })
            .collect();
        let curve = Nurbs {
            degree,
            knots,
            ctrl,
        };
        for k in degree..n {
            let (a, b) = (curve.knots[k], curve.knots[k + 1]);
            if b - a < 1e-6 {
                continue;
            }
            let piece = curve.bezier_span(k);
            for i in 0..=10 {
                let u = a + (b - a) * (0.05 + 0.09 * i as f64);
                let (got, v) = piece.at_with_velocity(u);
                let want = curve.eval(u);
                assert!(
                    got.dist(want) < 1e-9 * (1.0 + want.norm()),
                    "case {case}: {got:?} {want:?}"
                );
                let h = (b - a) * 1e-6;
                let fd = curve.eval(u + h).sub(curve.eval(u - h)).scale(0.5 / h);
                let v = v.unwrap();
                assert!(
                    v.dist(fd) < 1e-4 * (1.0 + fd.norm()),
                    "case {case}: {v:?} {fd:?}"
                );
            }
        }
    }
}

#[test]
fn ellipse_velocity_is_the_derivative() {
    use crate::dxf::biarc::Curve;
    let e = EllipseCurve {
        c: Point::new(3.0, -2.0),
        major: Point::new(20.0, 5.0),
        minor: Point::new(-2.0, 8.0),
    };
    for i in 0..50 {
        let t = i as f64 * 0.13 - 1.0;
        let (p, v) = e.at_with_velocity(t);
        assert_eq!(p, e.at(t));
        let h = 1e-6;
        let fd = e.at(t + h).sub(e.at(t - h)).scale(0.5 / h);
        assert!(v.unwrap().dist(fd) < 1e-6 * (1.0 + fd.norm()));
    }
}

#[test]
fn absurd_splines_give_bounded_output_or_an_error() {
    let text = |v: f64| -> &'static str { Box::leak(format!("{v:e}").into_boxed_str()) };
    /// Knots, control points and weights.
    type Case = (Vec<f64>, Vec<(f64, f64)>, Vec<f64>);
    // At the edges of f64.
    let cases: Vec<Case> = vec![
        (
            vec![0.0, 0.0, 0.0, 1e-320, 2e-320, 2e-320, 2e-320],
            vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
            vec![],
        ),
        (
            vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
            vec![(1e300, 0.0), (-1e300, 1e300), (1.0, 1.0), (0.0, -1e300)],
            vec![],
        ),
        (
            vec![-1e300, -1e300, -1e300, 0.0, 1e300, 1e300, 1e300],
            vec![(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)],
            vec![1e-300, 1e300, 1e-300, 1e300],
        ),
        (
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            vec![(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (0.0, 0.0)],
            vec![],
        ),
    ];
    for (i, (knots, ctrl, weights)) in cases.into_iter().enumerate() {
        let mut src = vec![(70, if weights.is_empty() { "0" } else { "4" }), (71, "2")];
        src.extend(knots.iter().map(|&k| (40, text(k))));
        src.extend(weights.iter().map(|&w| (41, text(w))));
        for (x, y) in ctrl {
            src.push((10, text(x)));
            src.push((20, text(y)));
        }
        if let Ok((segs, _, _)) = spline(&pairs(&src), 0.001) {
            // Each of the 8 fits may finish its pending halvings (≤ 24 deep) past the cap.
            assert!(
                segs.len() <= MAX_LINES + 8 * 48,
                "case {i}: {} segments",
                segs.len()
            );
        }
    }
}
