use super::*;

/// The closed regular `n`-gon on the circle of centre (cx, cy) and radius
/// `r`, counter-clockwise from angle 0.
fn polygon(n: usize, r: f64, cx: f64, cy: f64) -> Vec<Segment> {
    let at = |k: usize| {
        let t = TAU * k as f64 / n as f64;
        Point::new(cx + r * t.cos(), cy + r * t.sin())
    };
    (0..n).map(|k| Segment::line(at(k), at(k + 1))).collect()
}

fn polyline(points: &[(f64, f64)]) -> Vec<Segment> {
    points
        .windows(2)
        .map(|w| Segment::line(Point::new(w[0].0, w[0].1), Point::new(w[1].0, w[1].1)))
        .collect()
}

// An independent measure (not the fitter's code): the arc's centre from
// the bulge by the sagitta, the angle tested against both end angles.
fn dist_to_piece(p: Point, s: &Segment) -> f64 {
    let (a, b) = (s.a, s.b);
    let d = (b.x - a.x, b.y - a.y);
    let l = (d.0 * d.0 + d.1 * d.1).sqrt();
    if s.bulge == 0.0 {
        let t = (((p.x - a.x) * d.0 + (p.y - a.y) * d.1) / (l * l)).clamp(0.0, 1.0);
        return ((a.x + t * d.0 - p.x).powi(2) + (a.y + t * d.1 - p.y).powi(2)).sqrt();
    }
    // Radius from chord and sagitta; centre along the chord's normal.
    let sag = s.bulge * l / 2.0;
    let r = ((l / 2.0).powi(2) + sag * sag) / (2.0 * sag.abs());
    let mid = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
    // Left normal of the chord; a ccw arc (bulge > 0) bulges to the right,
    // its centre on the left at r − |sag| from the chord.
    let nrm = (-d.1 / l, d.0 / l);
    let k = (r - sag.abs()) * s.bulge.signum();
    let c = (mid.0 + nrm.0 * k, mid.1 + nrm.1 * k);
    let ang = |x: f64, y: f64| (y - c.1).atan2(x - c.0);
    let (a0, b0, pa) = (ang(a.x, a.y), ang(b.x, b.y), ang(p.x, p.y));
    let span = if s.bulge > 0.0 {
        (b0 - a0).rem_euclid(TAU)
    } else {
        (a0 - b0).rem_euclid(TAU)
    };
    let off = if s.bulge > 0.0 {
        (pa - a0).rem_euclid(TAU)
    } else {
        (a0 - pa).rem_euclid(TAU)
    };
    if off <= span {
        (((p.x - c.0).powi(2) + (p.y - c.1).powi(2)).sqrt() - r).abs()
    } else {
        let da = ((p.x - a.x).powi(2) + (p.y - a.y).powi(2)).sqrt();
        let db = ((p.x - b.x).powi(2) + (p.y - b.y).powi(2)).sqrt();
        da.min(db)
    }
}

fn dist_to_path(p: Point, path: &[Segment]) -> f64 {
    path.iter()
        .map(|s| dist_to_piece(p, s))
        .fold(f64::INFINITY, f64::min)
}

/// The largest distance, both ways: every original vertex and move
/// midpoint to the fitted path, and points along every fitted piece to
/// the original path.
fn deviation(original: &[Segment], fitted: &[Segment]) -> f64 {
    let mut worst = 0.0_f64;
    for s in original {
        let mid = Point::new((s.a.x + s.b.x) / 2.0, (s.a.y + s.b.y) / 2.0);
        for p in [s.a, s.b, mid] {
            worst = worst.max(dist_to_path(p, fitted));
        }
    }
    for s in fitted {
        for k in 0..=64 {
            worst = worst.max(dist_to_path(s.point_at(k as f64 / 64.0), original));
        }
    }
    worst
}

/// Every fitted piece starts where the one before ended and on a vertex
/// of the original.
fn on_vertices(original: &[Segment], fitted: &[Segment]) -> bool {
    let vertex = |p: Point| original.iter().any(|s| s.a == p || s.b == p);
    fitted.windows(2).all(|w| w[0].b == w[1].a)
        && fitted.iter().all(|s| vertex(s.a) && vertex(s.b))
        && fitted.first().map(|s| s.a) == original.first().map(|s| s.a)
        && fitted.last().map(|s| s.b) == original.last().map(|s| s.b)
}

#[test]
fn a_72_gon_of_radius_10_becomes_at_most_4_arcs_within_the_tolerance() {
    // Paper 004 §5.3: the 72-gon is R 10 flattened at about 0.01 (its
    // sagitta is 0.0095).
    let tol = 0.01;
    let gon = polygon(72, 10.0, 3.0, -2.0);
    let fitted = fit_path(&gon, tol);
    assert!(fitted.len() <= 4, "{} pieces", fitted.len());
    assert!(fitted.iter().all(|s| !s.is_line() && s.bulge.abs() <= 1.0));
    assert!(on_vertices(&gon, &fitted));
    let dev = deviation(&gon, &fitted);
    assert!(dev <= tol, "deviation {dev}");
    // Clockwise, the same.
    let cw: Vec<Segment> = gon.iter().rev().map(|s| s.reversed()).collect();
    let fitted = fit_path(&cw, tol);
    assert!(fitted.len() <= 4 && fitted.iter().all(|s| s.bulge < 0.0));
    assert!(deviation(&cw, &fitted) <= tol);
}

#[test]
fn a_tolerance_below_the_polygons_sagitta_leaves_it_as_drawn() {
    let gon = polygon(72, 10.0, 0.0, 0.0);
    let fitted = fit_path(&gon, 0.001);
    assert_eq!(fitted, gon);
}

#[test]
fn collinear_moves_merge_into_one_line() {
    let pts: Vec<(f64, f64)> = (0..=1000)
        .map(|k| (k as f64 * 0.1, k as f64 * 0.05))
        .collect();
    let run = polyline(&pts);
    let fitted = fit_path(&run, 0.001);
    assert_eq!(fitted.len(), 1);
    assert!(fitted[0].is_line());
    assert_eq!(fitted[0].a, run[0].a);
    assert_eq!(fitted[0].b, run[999].b);
}

#[test]
fn a_line_that_turns_back_on_itself_is_not_merged() {
    // Forward to 10, back to 4, forward to 12, all on one line: every
    // vertex lies on the chord 0–12, but one chord would drop the way back.
    let run = polyline(&[(0.0, 0.0), (2.0, 0.0), (10.0, 0.0), (4.0, 0.0), (12.0, 0.0)]);
    let fitted = fit_path(&run, 0.01);
    assert_eq!(fitted.len(), 3, "{fitted:?}");
    let length = |p: &[Segment]| p.iter().map(|s| s.a.dist(s.b)).sum::<f64>();
    assert!((length(&fitted) - length(&run)).abs() < 1e-9);
    assert!(deviation(&run, &fitted) <= 0.01);
}

#[test]
fn a_zig_zag_wider_than_the_tolerance_is_not_fitted() {
    let pts: Vec<(f64, f64)> = (0..=200)
        .map(|k| (k as f64 * 0.5, if k % 2 == 0 { 0.0 } else { 0.05 }))
        .collect();
    let run = polyline(&pts);
    assert_eq!(fit_path(&run, 0.01), run);
}

#[test]
fn a_sharp_corner_between_an_arc_and_a_line_stays_a_corner() {
    // A quarter of R 10 in 30 moves, then a square turn into a straight
    // run of 20 moves: an arc, a line, and the corner vertex between them.
    let mut pts: Vec<(f64, f64)> = (0..=30)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_2 * k as f64 / 30.0;
            (10.0 * t.cos(), 10.0 * t.sin())
        })
        .collect();
    // The arc ends at (0, 10) heading -x; the run turns square up +y.
    let corner = *pts.last().unwrap();
    pts.extend((1..=20).map(|k| (corner.0, corner.1 + 0.5 * k as f64)));
    let run = polyline(&pts);
    let tol = 0.01;
    let fitted = fit_path(&run, tol);
    assert!(on_vertices(&run, &fitted));
    assert!(deviation(&run, &fitted) <= tol);
    let c = Point::new(corner.0, corner.1);
    assert!(
        fitted.windows(2).any(|w| w[0].b == c && w[1].a == c),
        "the corner at {c:?} is kept: {fitted:?}"
    );
    assert_eq!(fitted.len(), 2, "{fitted:?}");
}
