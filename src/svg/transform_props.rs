//! Property test (issue 41 §1): a circle or a rect under a random stack of
//! nested `<g transform>` lists (matrix, translate, scale, rotate about the
//! origin or a point, skewX, skewY) reads as the shape mapped by the
//! product of those matrices, computed here by hand from SVG's definitions
//! (SVG 1.1 §7.15.3), not by [`super::transform`]: every point of the exact
//! shape lies on what was read, every point read lies on the exact shape,
//! and the areas agree (a circle under a shear or an uneven scale is an
//! ellipse of area |det|·πr²).

use super::*;
use crate::geom::{dist_to_segment, Point, Segment};
use crate::test_rng::unit;

/// `[a, b, c, d, e, f]`: x' = a·x + c·y + e, y' = b·x + d·y + f.
type M = [f64; 6];

/// `m` then `n` applied after it is `n · m`; SVG's `transform="A B"` maps
/// a point by A·B·p, so a list is folded left to right with `mul(acc, t)`.
fn mul(m: M, n: M) -> M {
    [
        m[0] * n[0] + m[2] * n[1],
        m[1] * n[0] + m[3] * n[1],
        m[0] * n[2] + m[2] * n[3],
        m[1] * n[2] + m[3] * n[3],
        m[0] * n[4] + m[2] * n[5] + m[4],
        m[1] * n[4] + m[3] * n[5] + m[5],
    ]
}

fn apply(m: &M, p: Point) -> Point {
    Point::new(
        m[0] * p.x + m[2] * p.y + m[4],
        m[1] * p.x + m[3] * p.y + m[5],
    )
}

/// One random transform: its SVG text and its matrix.
fn one(r: &mut impl FnMut() -> f64) -> (String, M) {
    let span = |r: &mut dyn FnMut() -> f64, lo: f64, hi: f64| lo + (hi - lo) * r();
    let t = |a: f64| a.to_radians().tan();
    match (r() * 7.0) as usize {
        0 => {
            let (x, y) = (span(r, -20.0, 20.0), span(r, -20.0, 20.0));
            (format!("translate({x} {y})"), [1.0, 0.0, 0.0, 1.0, x, y])
        }
        1 => {
            let (x, y) = (span(r, 0.4, 2.5), span(r, 0.4, 2.5));
            (format!("scale({x},{y})"), [x, 0.0, 0.0, y, 0.0, 0.0])
        }
        2 => {
            let a = span(r, -180.0, 180.0);
            let (s, c) = a.to_radians().sin_cos();
            (format!("rotate({a})"), [c, s, -s, c, 0.0, 0.0])
        }
        3 => {
            // rotate(a cx cy) = translate(cx cy) rotate(a) translate(−cx −cy).
            let (a, cx, cy) = (
                span(r, -180.0, 180.0),
                span(r, -30.0, 30.0),
                span(r, -30.0, 30.0),
            );
            let (s, c) = a.to_radians().sin_cos();
            let m = mul(
                mul([1.0, 0.0, 0.0, 1.0, cx, cy], [c, s, -s, c, 0.0, 0.0]),
                [1.0, 0.0, 0.0, 1.0, -cx, -cy],
            );
            (format!("rotate({a} {cx} {cy})"), m)
        }
        4 => {
            let a = span(r, -40.0, 40.0);
            (format!("skewX({a})"), [1.0, 0.0, t(a), 1.0, 0.0, 0.0])
        }
        5 => {
            let a = span(r, -40.0, 40.0);
            (format!("skewY({a})"), [1.0, t(a), 0.0, 1.0, 0.0, 0.0])
        }
        _ => loop {
            let m = [
                span(r, -2.0, 2.0),
                span(r, -2.0, 2.0),
                span(r, -2.0, 2.0),
                span(r, -2.0, 2.0),
                span(r, -20.0, 20.0),
                span(r, -20.0, 20.0),
            ];
            if (m[0] * m[3] - m[1] * m[2]).abs() > 0.2 {
                let [a, b, c, d, e, f] = m;
                break (format!("matrix({a} {b} {c} {d} {e} {f})"), m);
            }
        },
    }
}

#[test]
fn random_transform_stacks_map_circles_and_rects_as_their_matrices_say() {
    let mut r = unit(0x005e_ed41);
    for case in 0..300 {
        let mut svg = String::from(
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="400mm" height="400mm" viewBox="0 0 400 400">"#,
        );
        let mut m: M = [1.0, 0.0, 0.0, 1.0, 200.0, 200.0];
        svg.push_str(r#"<g transform="translate(200 200)">"#);
        let depth = 1 + (r() * 3.0) as usize;
        for _ in 0..depth {
            let n = 1 + (r() * 2.0) as usize;
            let mut list = Vec::new();
            for _ in 0..n {
                let (text, t) = one(&mut r);
                list.push(text);
                m = mul(m, t);
            }
            svg.push_str(&format!(r#"<g transform="{}">"#, list.join(" ")));
        }
        let circle = r() < 0.5;
        let (cx, cy) = (r() * 10.0 - 5.0, r() * 10.0 - 5.0);
        let (w, h) = (2.0 + r() * 10.0, 2.0 + r() * 10.0);
        // The exact outline, densely sampled, in the page's user space.
        let exact: Vec<Point> = if circle {
            svg.push_str(&format!(r#"<circle cx="{cx}" cy="{cy}" r="{w}"/>"#));
            (0..256)
                .map(|k| {
                    let a = std::f64::consts::TAU * k as f64 / 256.0;
                    Point::new(cx + w * a.cos(), cy + w * a.sin())
                })
                .collect()
        } else {
            svg.push_str(&format!(
                r#"<rect x="{cx}" y="{cy}" width="{w}" height="{h}"/>"#
            ));
            let c = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h), (0.0, 0.0)];
            c.windows(2)
                .flat_map(|e| {
                    (0..32).map(move |k| {
                        let t = k as f64 / 32.0;
                        Point::new(
                            cx + e[0].0 + (e[1].0 - e[0].0) * t,
                            cy + e[0].1 + (e[1].1 - e[0].1) * t,
                        )
                    })
                })
                .collect()
        };
        svg.push_str(&"</g>".repeat(depth + 1));
        svg.push_str("</svg>");
        // Page (mm, y down from the top of a 400 mm page) to drawing (y up).
        let to_mm = |p: Point| {
            let q = apply(&m, p);
            Point::new(q.x, 400.0 - q.y)
        };
        let want: Vec<Point> = exact.iter().map(|&p| to_mm(p)).collect();
        let d = parse(svg.as_bytes(), &ReadOptions::DEFAULT).unwrap();
        let got: Vec<Segment> = all_segments(&d).copied().collect();
        assert!(!got.is_empty(), "case {case}: nothing read\n{svg}");
        // Within the chord tolerance the reader fits ellipses to.
        let tol = 2.0 * ReadOptions::DEFAULT.chord;
        for p in &want {
            let e = got
                .iter()
                .map(|s| dist_to_segment(*p, s))
                .fold(f64::INFINITY, f64::min);
            assert!(
                e < tol,
                "case {case}: {p:?} is {e} mm off what was read\n{svg}"
            );
        }
        // Each point read is near the exact outline: mapped back by the
        // inverse matrix, its distance to the shape there, times the
        // matrix's smallest stretch, is at most its distance on the page.
        let det = m[0] * m[3] - m[1] * m[2];
        let inv = |p: Point| {
            let (x, y) = (p.x - m[4], (400.0 - p.y) - m[5]);
            Point::new((m[3] * x - m[2] * y) / det, (-m[1] * x + m[0] * y) / det)
        };
        let t = m[..4].iter().map(|v| v * v).sum::<f64>();
        let sigma_min = ((t - (t * t - 4.0 * det * det).max(0.0).sqrt()) / 2.0).sqrt();
        let off_shape = |q: Point| {
            if circle {
                (q.dist(Point::new(cx, cy)) - w).abs()
            } else {
                let (ox, oy) = ((q.x - cx).min(cx + w - q.x), (q.y - cy).min(cy + h - q.y));
                if ox >= 0.0 && oy >= 0.0 {
                    ox.min(oy)
                } else {
                    (-ox).max(0.0).hypot((-oy).max(0.0))
                }
            }
        };
        for s in &got {
            for k in 0..4 {
                let p = s.point_at(k as f64 / 4.0);
                let e = off_shape(inv(p)) * sigma_min;
                assert!(
                    e < tol,
                    "case {case}: read {p:?} is {e} mm off the shape\n{svg}"
                );
            }
        }
        let area = if circle {
            std::f64::consts::PI * w * w
        } else {
            w * h
        } * det.abs();
        // Outlines within `tol` of each other differ in area by at most
        // about their length × `tol`.
        let read: f64 = got.iter().map(Segment::area_term).sum::<f64>().abs();
        let length: f64 = got.iter().map(Segment::length).sum();
        assert!(
            (read - area).abs() < length * tol,
            "case {case}: area {read}, want {area}\n{svg}"
        );
    }
}
