//! Where copies go ([`Sheets`]): rectangles of one size or a list of
//! sizes, a strip, or an irregular sheet (a remnant) read from a drawing's
//! contours: its outer outline is the sheet; its holes and every closed
//! contour on a layer named `DEFECT` are no-go zones (issue 16, item 6).

use super::NestError;
use crate::contour::{ContourKind, Contours};
use crate::geom::{path_bbox, Segment};
use crate::text;
use crate::warning::Text;

/// Layer of no-go zones (defects) on a sheet DXF, read and written.
pub const DEFECT_LAYER: &str = "DEFECT";

/// The sheet drawn in `contours`: the largest outer outline not on
/// `DEFECT`, its holes and the closed `DEFECT` contours as no-go zones.
/// Open contours are left out (they enclose nothing); what else is drawn
/// is said in the returned notes (in English and Portuguese: the page
/// shows them in its language, the CLI in English).
pub fn sheet_from_contours(contours: &Contours) -> Result<(Sheets, Vec<Text>), NestError> {
    let defect = |layer: &str| layer.eq_ignore_ascii_case(DEFECT_LAYER);
    let outer = contours
        .contours
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kind == ContourKind::Outer && !defect(&c.layer))
        .max_by(|a, b| a.1.area.abs().total_cmp(&b.1.area.abs()))
        .map(|(i, _)| i)
        .ok_or(NestError::NoSheetOutline)?;
    let sheet = &contours.contours[outer];
    let mut no_go = Vec::new();
    let mut notes = Vec::new();
    let (mut open, mut other) = (0, 0);
    for (i, c) in contours.contours.iter().enumerate() {
        if i == outer {
            continue;
        }
        if c.kind == ContourKind::Open {
            open += 1;
        } else if defect(&c.layer) || (c.kind == ContourKind::Hole && c.parent == Some(outer)) {
            no_go.push(c.segments.clone());
        } else {
            other += 1;
        }
    }
    if open > 0 {
        notes.push(text!(
            "{open} open contour(s) on the sheet drawing left out: an open line is no no-go zone (close it, or draw it on layer DEFECT as a closed outline)";
            "{open} contorno(s) aberto(s) no desenho da chapa deixado(s) de fora: uma linha aberta não é zona proibida (feche-a, ou desenhe-a na camada DEFECT como contorno fechado)"
        ));
    }
    if other > 0 {
        notes.push(text!(
            "{other} closed contour(s) inside the sheet's holes or outside it left out (only the largest outline, its holes and layer DEFECT count)";
            "{other} contorno(s) fechado(s) dentro dos furos da chapa ou fora dela deixado(s) de fora (só contam o maior contorno, seus furos e a camada DEFECT)"
        ));
    }
    Ok((
        Sheets::Remnant {
            outline: sheet.segments.clone(),
            no_go,
        },
        notes,
    ))
}

/// Where copies go.
#[derive(Clone, Debug, PartialEq)]
pub enum Sheets {
    /// `count` rectangles `width` × `height`, mm.
    Rect {
        /// Along x.
        width: f64,
        /// Along y.
        height: f64,
        /// How many.
        count: usize,
    },
    /// Rectangles of several sizes, filled in the order listed: all of
    /// the first size, then the next (issue 16 item 6, "a list"). A copy
    /// goes on the next sheet in that order or on none: no sheet is
    /// skipped, so sheet k of a nest is always the k-th of the list.
    Mixed(Vec<SheetSize>),
    /// One strip of `height`, unbounded along x.
    Strip {
        /// Along y.
        height: f64,
    },
    /// One irregular sheet (a remnant), in its drawing's coordinates.
    Remnant {
        /// Its outer outline, closed.
        outline: Vec<Segment>,
        /// Where no part may go: its holes, defects.
        no_go: Vec<Vec<Segment>>,
    },
}

/// `count` rectangles `width` × `height`, mm: one entry of
/// [`Sheets::Mixed`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SheetSize {
    /// Along x.
    pub width: f64,
    /// Along y.
    pub height: f64,
    /// How many.
    pub count: usize,
}

impl Sheets {
    /// How many sheets there are (a strip and a remnant are one).
    pub fn count(&self) -> usize {
        match self {
            Sheets::Rect { count, .. } => *count,
            Sheets::Mixed(v) => v.iter().map(|s| s.count).sum(),
            Sheets::Strip { .. } | Sheets::Remnant { .. } => 1,
        }
    }

    /// Sheet `k` alone, as a sheet of its own (count 1 for rectangles):
    /// what the figures, the crop line and the remnant of one sheet are
    /// computed on. Past the last sheet, the last.
    pub fn sheet(&self, k: usize) -> Sheets {
        match self {
            Sheets::Rect { width, height, .. } => Sheets::Rect {
                width: *width,
                height: *height,
                count: 1,
            },
            Sheets::Mixed(v) => {
                let mut left = k;
                let s = v
                    .iter()
                    .find(|s| {
                        let here = left < s.count;
                        left = left.saturating_sub(s.count);
                        here
                    })
                    .or(v.last())
                    .copied()
                    .unwrap_or(SheetSize {
                        width: 0.0,
                        height: 0.0,
                        count: 0,
                    });
                Sheets::Rect {
                    width: s.width,
                    height: s.height,
                    count: 1,
                }
            }
            other => other.clone(),
        }
    }

    /// Sheet `k`'s box: (width, height); no width for a strip.
    pub fn size(&self, k: usize) -> (Option<f64>, f64) {
        match self.sheet(k) {
            Sheets::Rect { width, height, .. } => (Some(width), height),
            Sheets::Strip { height } => (None, height),
            Sheets::Remnant { outline, .. } => {
                let b = path_bbox(&outline);
                (Some(b.max.x - b.min.x), b.max.y - b.min.y)
            }
            // sheet() gives no Mixed.
            Sheets::Mixed(_) => (Some(0.0), 0.0),
        }
    }

    /// Where the sheets start along x (lengths are measured from here):
    /// 0, or a remnant's leftmost point.
    pub fn origin_x(&self) -> f64 {
        match self {
            Sheets::Remnant { outline, .. } => path_bbox(outline).min.x,
            _ => 0.0,
        }
    }

    /// A list of rectangle sizes: one entry is a `Rect`, more a `Mixed`.
    pub fn rects(sizes: Vec<SheetSize>) -> Sheets {
        match sizes.as_slice() {
            [s] => Sheets::Rect {
                width: s.width,
                height: s.height,
                count: s.count,
            },
            _ => Sheets::Mixed(sizes),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sheet_k_of_a_list_is_its_size_in_the_order_given() {
        let size = |width, height, count| SheetSize {
            width,
            height,
            count,
        };
        let s = Sheets::Mixed(vec![size(300.0, 200.0, 2), size(500.0, 100.0, 1)]);
        assert_eq!(s.count(), 3);
        let sizes: Vec<_> = (0..5).map(|k| s.size(k)).collect();
        assert_eq!(
            sizes,
            [
                (Some(300.0), 200.0),
                (Some(300.0), 200.0),
                (Some(500.0), 100.0),
                // Past the last sheet: the last.
                (Some(500.0), 100.0),
                (Some(500.0), 100.0),
            ]
        );
        assert_eq!(
            s.sheet(2),
            Sheets::Rect {
                width: 500.0,
                height: 100.0,
                count: 1
            }
        );
        assert_eq!(Sheets::rects(vec![size(1.0, 2.0, 4)]).count(), 4);
        assert_eq!(Sheets::Strip { height: 5.0 }.size(7), (None, 5.0));
    }
}
