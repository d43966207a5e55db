//! The basic shapes (SVG 1.1 §9) as subpaths: `<rect>` (rounded too),
//! `<circle>`, `<ellipse>`, `<line>`, `<polyline>`, `<polygon>`, in user
//! units. Their lengths may carry units ("10mm") and percentages of the
//! viewport.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use svgtypes::PointsParser;

use super::document::attr_length;
use super::path::{Piece, Subpath};
use crate::geom::Point;

/// What a shape element is, or why it draws nothing.
pub enum Shape {
    Paths(Vec<Subpath>),
    /// Nothing to draw (a zero size, no points): SVG does not render it.
    Empty,
}

/// The viewport (user units) for percentages and one px in mm.
#[derive(Clone, Copy)]
pub struct Lengths {
    pub viewport: (f64, f64),
    pub px_mm: f64,
}

impl Lengths {
    fn x(&self, n: roxmltree::Node, name: &str) -> Option<f64> {
        attr_length(n, name, self.px_mm, self.viewport.0)
    }
    fn y(&self, n: roxmltree::Node, name: &str) -> Option<f64> {
        attr_length(n, name, self.px_mm, self.viewport.1)
    }
    /// A length along neither axis: percentages of the normalised
    /// diagonal (SVG 1.1 §7.10).
    fn r(&self, n: roxmltree::Node, name: &str) -> Option<f64> {
        let (w, h) = self.viewport;
        attr_length(n, name, self.px_mm, (w * w + h * h).sqrt() / 2f64.sqrt())
    }
}

/// A full ellipse: centre, semi-axes along x and y.
fn ellipse(c: Point, rx: f64, ry: f64) -> Subpath {
    let p = |t: f64| c.add(Point::new(rx * t.cos(), ry * t.sin()));
    Subpath {
        pieces: vec![Piece::Arc {
            c,
            major: Point::new(rx, 0.0),
            minor: Point::new(0.0, ry),
            t0: 0.0,
            sweep: TAU,
            from: p(0.0),
            to: p(0.0),
        }],
        closed: true,
    }
}

/// A quarter of an ellipse (rounded corner) from angle `t0`, positive turn.
fn corner(c: Point, rx: f64, ry: f64, t0: f64) -> Piece {
    let p = |t: f64| c.add(Point::new(rx * t.cos(), ry * t.sin()));
    Piece::Arc {
        c,
        major: Point::new(rx, 0.0),
        minor: Point::new(0.0, ry),
        t0,
        sweep: FRAC_PI_2,
        from: p(t0),
        to: p(t0 + FRAC_PI_2),
    }
}

/// The shape `node` (by its tag name) as subpaths.
pub fn shape(node: roxmltree::Node, tag: &str, l: &Lengths) -> Shape {
    match tag {
        "rect" => rect(node, l),
        "circle" => {
            let c = Point::new(
                l.x(node, "cx").unwrap_or(0.0),
                l.y(node, "cy").unwrap_or(0.0),
            );
            match l.r(node, "r") {
                Some(r) if r > 0.0 => Shape::Paths(vec![ellipse(c, r, r)]),
                _ => Shape::Empty,
            }
        }
        "ellipse" => {
            let c = Point::new(
                l.x(node, "cx").unwrap_or(0.0),
                l.y(node, "cy").unwrap_or(0.0),
            );
            // SVG 2: an rx or ry left out (or auto) takes the other's value.
            let (rx, ry) = match (l.x(node, "rx"), l.y(node, "ry")) {
                (Some(rx), Some(ry)) => (rx, ry),
                (Some(r), None) | (None, Some(r)) => (r, r),
                (None, None) => (0.0, 0.0),
            };
            if rx > 0.0 && ry > 0.0 {
                Shape::Paths(vec![ellipse(c, rx, ry)])
            } else {
                Shape::Empty
            }
        }
        "line" => {
            let a = Point::new(
                l.x(node, "x1").unwrap_or(0.0),
                l.y(node, "y1").unwrap_or(0.0),
            );
            let b = Point::new(
                l.x(node, "x2").unwrap_or(0.0),
                l.y(node, "y2").unwrap_or(0.0),
            );
            if a == b {
                return Shape::Empty;
            }
            Shape::Paths(vec![Subpath {
                pieces: vec![Piece::Line(a, b)],
                closed: false,
            }])
        }
        _ => poly(node, tag == "polygon"),
    }
}

fn rect(node: roxmltree::Node, l: &Lengths) -> Shape {
    let (x, y) = (l.x(node, "x").unwrap_or(0.0), l.y(node, "y").unwrap_or(0.0));
    let (w, h) = (
        l.x(node, "width").unwrap_or(0.0),
        l.y(node, "height").unwrap_or(0.0),
    );
    if !(w > 0.0 && h > 0.0) {
        return Shape::Empty;
    }
    // SVG 1.1 §9.2: one radius given stands for both; each at most half the side.
    let (rx, ry) = match (
        l.x(node, "rx").filter(|v| *v >= 0.0),
        l.y(node, "ry").filter(|v| *v >= 0.0),
    ) {
        (Some(rx), Some(ry)) => (rx, ry),
        (Some(r), None) | (None, Some(r)) => (r, r),
        (None, None) => (0.0, 0.0),
    };
    let (rx, ry) = (rx.min(w / 2.0), ry.min(h / 2.0));
    let pt = Point::new;
    let mut pieces = Vec::with_capacity(8);
    if rx > 0.0 && ry > 0.0 {
        // Clockwise on a y-down screen, as a browser draws it: top edge,
        // top-right corner, right edge, …
        let edge = |pieces: &mut Vec<Piece>, a: Point, b: Point| {
            if a != b {
                pieces.push(Piece::Line(a, b));
            }
        };
        edge(&mut pieces, pt(x + rx, y), pt(x + w - rx, y));
        pieces.push(corner(pt(x + w - rx, y + ry), rx, ry, -FRAC_PI_2));
        edge(&mut pieces, pt(x + w, y + ry), pt(x + w, y + h - ry));
        pieces.push(corner(pt(x + w - rx, y + h - ry), rx, ry, 0.0));
        edge(&mut pieces, pt(x + w - rx, y + h), pt(x + rx, y + h));
        pieces.push(corner(pt(x + rx, y + h - ry), rx, ry, FRAC_PI_2));
        edge(&mut pieces, pt(x, y + h - ry), pt(x, y + ry));
        pieces.push(corner(pt(x + rx, y + ry), rx, ry, PI));
    } else {
        let c = [pt(x, y), pt(x + w, y), pt(x + w, y + h), pt(x, y + h)];
        pieces.extend((0..4).map(|i| Piece::Line(c[i], c[(i + 1) % 4])));
    }
    Shape::Paths(vec![Subpath {
        pieces,
        closed: true,
    }])
}

fn poly(node: roxmltree::Node, closed: bool) -> Shape {
    let pts: Vec<Point> = PointsParser::from(node.attribute("points").unwrap_or(""))
        .map(|(x, y)| Point::new(x, y))
        .collect();
    if pts.len() < 2 {
        return Shape::Empty;
    }
    let mut pieces: Vec<Piece> = pts.windows(2).map(|w| Piece::Line(w[0], w[1])).collect();
    let (first, last) = (pts[0], pts[pts.len() - 1]);
    if closed && first != last {
        pieces.push(Piece::Line(last, first));
    }
    Shape::Paths(vec![Subpath {
        pieces,
        closed: closed || first == last,
    }])
}

#[cfg(test)]
mod tests {
    use super::*;

    const L: Lengths = Lengths {
        viewport: (200.0, 100.0),
        px_mm: 25.4 / 96.0,
    };

    fn shape_of(xml: &str) -> Shape {
        let doc = roxmltree::Document::parse(xml).unwrap();
        let n = doc.root_element();
        shape(n, n.tag_name().name(), &L)
    }

    fn paths(s: Shape) -> Vec<Subpath> {
        match s {
            Shape::Paths(p) => p,
            Shape::Empty => panic!("empty"),
        }
    }

    #[test]
    fn a_rect_is_four_lines_and_a_rounded_one_has_quarter_corners() {
        let p = paths(shape_of(r#"<rect x="1" y="2" width="10" height="20"/>"#));
        assert_eq!(p[0].pieces.len(), 4);
        assert_eq!(
            p[0].pieces[1],
            Piece::Line(Point::new(11.0, 2.0), Point::new(11.0, 22.0))
        );
        // rx alone: ry = rx; each radius beyond half its side is cut to it
        // (SVG 1.1 §9.2: rx 8 → 5 on the 10 side, ry 8 stays on the 20 side).
        let p = paths(shape_of(r#"<rect width="10" height="20" rx="8"/>"#));
        let arcs: Vec<_> = p[0]
            .pieces
            .iter()
            .filter(|p| matches!(p, Piece::Arc { .. }))
            .collect();
        assert_eq!(arcs.len(), 4);
        let Piece::Arc {
            major,
            minor,
            from,
            to,
            ..
        } = arcs[0]
        else {
            panic!()
        };
        assert_eq!((major.x, minor.y), (5.0, 8.0));
        // Top-right corner from the top edge down to the right edge.
        assert!(from.dist(Point::new(5.0, 0.0)) < 1e-12 && to.dist(Point::new(10.0, 8.0)) < 1e-12);
        // Lines and corners join end to end.
        let ends: Vec<(Point, Point)> = p[0]
            .pieces
            .iter()
            .map(|p| match *p {
                Piece::Line(a, b) => (a, b),
                Piece::Arc { from, to, .. } => (from, to),
                _ => panic!(),
            })
            .collect();
        for i in 0..ends.len() {
            assert!(
                ends[i].1.dist(ends[(i + 1) % ends.len()].0) < 1e-12,
                "{ends:?}"
            );
        }
    }

    #[test]
    fn units_and_percentages_in_shape_lengths() {
        // 10mm is 37.795… px; 50% of a 200-wide viewport is 100.
        let p = paths(shape_of(r#"<rect x="50%" width="10mm" height="1in"/>"#));
        let Piece::Line(a, b) = p[0].pieces[0] else {
            panic!()
        };
        assert!((a.x - 100.0).abs() < 1e-9 && (b.x - a.x - 10.0 * 96.0 / 25.4).abs() < 1e-9);
    }

    #[test]
    fn circles_ellipses_lines_and_polys() {
        let p = paths(shape_of(r#"<circle cx="5" cy="5" r="2"/>"#));
        assert!(p[0].closed);
        let p = paths(shape_of(r#"<ellipse cx="5" cy="5" rx="3"/>"#));
        let Piece::Arc { minor, .. } = p[0].pieces[0] else {
            panic!()
        };
        assert_eq!(minor.y, 3.0);
        assert!(matches!(shape_of(r#"<circle r="0"/>"#), Shape::Empty));
        assert!(matches!(
            shape_of(r#"<rect width="0" height="3"/>"#),
            Shape::Empty
        ));
        let p = paths(shape_of(r#"<polygon points="0,0 10,0 10,10"/>"#));
        assert!(p[0].closed && p[0].pieces.len() == 3);
        let p = paths(shape_of(r#"<polyline points="0,0 10,0 10,10 7"/>"#));
        assert!(!p[0].closed && p[0].pieces.len() == 2);
        let p = paths(shape_of(r#"<line x2="3"/>"#));
        assert_eq!(
            p[0].pieces[0],
            Piece::Line(Point::new(0.0, 0.0), Point::new(3.0, 0.0))
        );
    }
}
