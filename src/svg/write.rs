//! What the SVG writers share (the nest, [`crate::nest::svg_out`], and the
//! cut plan, [`super::plan`]): text escaped as data, and lines and arcs as
//! path data on a page in mm whose y runs down. Plain string writing, no
//! XML library: outside the feature "svg", so the page's cutting core can
//! write SVG without the reader's crates.

use std::fmt::{self, Write};

use crate::geom::{Point, Segment};

/// The XML declaration and the `<svg>` start tag of a page `w` × `h` mm
/// (width/height in mm and a viewBox of the same numbers: one user unit is
/// one mm, so Inkscape opens it at true size), with Inkscape's namespace
/// for layers; sizes written with `decimals` ([`Num`]).
pub fn header(w: f64, h: f64, title: &str, decimals: Option<i32>) -> String {
    let (w, h) = (Num(w, decimals), Num(h, decimals));
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" \
         width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">\n\
         <title>{}</title>\n",
        escape(title)
    )
}

/// `&`, `<`, `>`, `"` and `'` escaped, control characters made spaces:
/// names are data from the user's files, written as XML text or attribute.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if c.is_control() => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// A number as SVG takes it: rounded to `.1` decimals (None: every digit,
/// the shortest text that reads back as the same f64), no "-0".
#[derive(Clone, Copy, Debug)]
pub struct Num(pub f64, pub Option<i32>);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = match self.1 {
            // The f64 nearest k·10⁻ⁿ prints as that decimal (Rust writes the
            // shortest round-tripping text).
            Some(n) => {
                let k = 10f64.powi(n);
                (self.0 * k).round() / k
            }
            None => self.0,
        };
        write!(f, "{}", v + 0.0)
    }
}

/// Where drawing points (mm, y up) go on the page (mm, y down): x + `dx`,
/// `top` − y, written with `decimals` ([`Num`]).
#[derive(Clone, Copy, Debug)]
pub struct PageMap {
    /// Added to x.
    pub dx: f64,
    /// The drawing's y at the page's top edge.
    pub top: f64,
    /// Decimals written (None: exact).
    pub decimals: Option<i32>,
}

impl PageMap {
    /// The page coordinates of a drawing point.
    pub fn at(&self, p: Point) -> (Num, Num) {
        (
            Num(p.x + self.dx, self.decimals),
            Num(self.top - p.y, self.decimals),
        )
    }
}

/// Path data of a chain of lines and arcs on the page: arcs as SVG arcs
/// (exact; a counter-clockwise arc, seen from above, turns the negative-
/// angle way in y-down axes: sweep flag 0). Appended to `d`.
pub fn chain_data(d: &mut String, segs: &[Segment], map: &PageMap, closed: bool) {
    let Some(first) = segs.first() else { return };
    if !d.is_empty() {
        d.push(' ');
    }
    let (x, y) = map.at(first.a);
    let _ = write!(d, "M{x} {y}");
    for s in segs {
        let (x, y) = map.at(s.b);
        match s.arc_center() {
            Some((_, r)) => {
                let r = Num(r, map.decimals);
                let large = u8::from(s.bulge.abs() > 1.0);
                let sweep = u8::from(s.bulge < 0.0);
                let _ = write!(d, " A{r} {r} 0 {large} {sweep} {x} {y}");
            }
            None => {
                let _ = write!(d, " L{x} {y}");
            }
        }
    }
    if closed {
        d.push_str(" Z");
    }
}

/// [`chain_data`] of one chain, as a new string.
pub fn path_data(segs: &[Segment], map: &PageMap, closed: bool) -> String {
    let mut d = String::new();
    chain_data(&mut d, segs, map, closed);
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_rounded_without_minus_zero() {
        assert_eq!(Num(5.000_000_000_1, Some(6)).to_string(), "5");
        assert_eq!(Num(-0.000_000_1, Some(6)).to_string(), "0");
        assert_eq!(Num(0.1 + 0.2, None).to_string(), "0.30000000000000004");
        assert_eq!(Num(12.345_678_9, Some(6)).to_string(), "12.345679");
    }

    #[test]
    fn names_are_escaped_as_data() {
        assert_eq!(
            escape("a<b & \"c\"\n'"),
            "a&lt;b &amp; &quot;c&quot; &apos;"
        );
    }

    #[test]
    fn a_ccw_arc_has_sweep_flag_0_on_the_page() {
        let s = Segment {
            a: Point::new(0.0, 0.0),
            b: Point::new(10.0, 0.0),
            bulge: 1.0,
        };
        let map = PageMap {
            dx: 0.0,
            top: 10.0,
            decimals: Some(3),
        };
        assert_eq!(path_data(&[s], &map, false), "M0 10 A5 5 0 0 0 10 10");
        assert_eq!(
            path_data(&[s.reversed()], &map, true),
            "M10 10 A5 5 0 0 1 0 10 Z"
        );
    }
}
