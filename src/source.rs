//! Where a contour came from (issue 15 §1): which part, which copy of it
//! and which of its loops. Contour indices change with every setting that
//! changes the drawing (layers, healing, a nest); a reference does not, so
//! twelve copies of one part on a sheet each know which copy they are, and
//! the report, the inspector and the page can name a cut's part and copy.
//!
//! On a nested sheet the nest stage stamps each placed loop's entity with
//! its reference ([`crate::nest::output::sheet_drawing`]) and the contour
//! stage carries it through chaining; in a single drawing the contour stage
//! numbers the parts it finds.

use serde::Serialize;

/// A contour's part, copy and loop.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct ContourRef {
    /// The part, 1-based: on a nested sheet the nest job's part (its
    /// index + 1), in one drawing the part number the contour stage gave;
    /// 0 for an open contour, which belongs to no part.
    pub part: u32,
    /// Which copy of the part (0-based; 0 in a single drawing).
    pub copy: u32,
    /// Which loop of the part: 0 its outer outline, k its k-th hole; for
    /// an open contour, its place among the open ones (0-based).
    pub contour: u32,
}

impl ContourRef {
    /// True for a part's outer outline.
    pub fn is_outer(&self) -> bool {
        self.part > 0 && self.contour == 0
    }
}

#[cfg(test)]
mod tests {
    use super::ContourRef;

    fn square(x: f64, y: f64, side: f64) -> String {
        format!(
            "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n{x}\n20\n{y}\n10\n{}\n20\n{y}\n10\n{}\n20\n{}\n10\n{x}\n20\n{}\n",
            x + side,
            x + side,
            y + side,
            y + side
        )
    }
    fn circle(x: f64, y: f64, r: f64) -> String {
        format!("0\nCIRCLE\n8\n0\n10\n{x}\n20\n{y}\n40\n{r}\n")
    }

    #[test]
    fn a_drawing_numbers_parts_holes_and_open_contours() {
        let body = [
            square(0.0, 0.0, 100.0),
            circle(30.0, 50.0, 10.0),
            circle(70.0, 50.0, 10.0),
            square(200.0, 0.0, 50.0),
            circle(225.0, 25.0, 5.0),
            "0\nLINE\n8\n0\n10\n0\n20\n200\n11\n50\n21\n200\n".into(),
        ]
        .concat();
        let dxf = format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n");
        let s = crate::Settings::new(0.0, 0.001, 1000.0).unwrap();
        let out = crate::run(dxf.as_bytes(), &s).unwrap();
        let mut refs: Vec<ContourRef> = out.contours.contours.iter().map(|c| c.source).collect();
        refs.sort();
        let r = |part, contour| ContourRef {
            part,
            copy: 0,
            contour,
        };
        assert_eq!(refs, [r(0, 0), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1)]);
        for c in &out.contours.contours {
            // The reference's part is the part number the contour stage gave.
            assert_eq!(c.source.part as usize, c.part.unwrap_or(0));
            assert_eq!(
                c.source.is_outer(),
                c.kind == crate::contour::ContourKind::Outer
            );
        }
    }
}
