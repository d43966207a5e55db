//! The remnant: after the last part, a straight crop line across the sheet
//! at the used length plus the margin, cut last, that separates the piece
//! of sheet to keep from the part of it cut; the kept piece as an outline
//! that can be given back as a sheet; utilisation per paper 001 §6.3
//! (`../shared/seeds/notes-001-ebisui-1993.md`): the parts' area over the
//! sheet's *useful* area, the remnant excluded ("aproveitamento = área
//! ocupada pelas peças / área útil da chapa", after a remnant line is drawn
//! only the non-remnant area counts).
//!
//! Only the last sheet gets a crop line (the objective leaves the largest
//! clean remnant there); a remnant narrower than the margin is scrap, not
//! kept. Arcs of an irregular sheet's outline are flattened inside the
//! outline within the tolerance for the areas and the remnant outline
//! (which is then never larger than the true piece).

use super::shape::{room_polygon, signed_area};
use super::Sheets;
use crate::geom::{path_bbox, Point, Segment};

/// Utilisation, 0..1: part area over the useful area (sheet less remnant).
pub fn utilisation(part_area: f64, sheet_area: f64, remnant_area: f64) -> f64 {
    let useful = sheet_area - remnant_area;
    if useful > 0.0 {
        part_area / useful
    } else {
        0.0
    }
}

/// The sheet's outline and no-go zones as polygons (counter-clockwise),
/// arcs flattened inside within `tol`. A rectangle is exact.
///
/// Every function here reads one sheet: for a list of sizes, pass
/// [`Sheets::sheet`]`(k)` of the sheet meant (given the list, the first).
fn polygons(sheets: &Sheets, tol: f64) -> (Vec<Point>, Vec<Vec<Point>>) {
    match sheets {
        Sheets::Mixed(_) => polygons(&sheets.sheet(0), tol),
        Sheets::Rect { width, height, .. } => (
            vec![
                Point::new(0.0, 0.0),
                Point::new(*width, 0.0),
                Point::new(*width, *height),
                Point::new(0.0, *height),
            ],
            Vec::new(),
        ),
        Sheets::Strip { .. } => (Vec::new(), Vec::new()),
        Sheets::Remnant { outline, no_go } => (
            room_polygon(outline, 0.0, tol).map_or(Vec::new(), |p| p.pts),
            no_go
                .iter()
                .filter_map(|z| room_polygon(z, 0.0, tol).map(|p| p.pts))
                .collect(),
        ),
    }
}

/// The part of polygon `pts` on one side of the line x = `c`: left when
/// `left` (Sutherland & Hodgman, CACM 1974, one clipping edge; the pieces
/// of a concave polygon stay joined along the line, which adds no area).
pub fn clip_x(pts: &[Point], c: f64, left: bool) -> Vec<Point> {
    let keep = |p: Point| if left { p.x <= c } else { p.x >= c };
    let n = pts.len();
    let mut out = Vec::with_capacity(n + 2);
    for i in 0..n {
        let (a, b) = (pts[i], pts[(i + 1) % n]);
        if keep(a) {
            out.push(a);
        }
        if keep(a) != keep(b) && a.x != b.x {
            let t = (c - a.x) / (b.x - a.x);
            out.push(Point::new(c, a.y + t * (b.y - a.y)));
        }
    }
    out.dedup();
    out
}

/// Where the crop line goes on a sheet whose rightmost part reaches
/// `right` (sheet coordinates): `right + margin`, when the remnant beyond
/// it is wider than the margin. None for a strip.
pub fn crop_x(sheets: &Sheets, right: f64, margin: f64) -> Option<f64> {
    let end = match sheets {
        Sheets::Rect { width, .. } => *width,
        Sheets::Mixed(_) => return crop_x(&sheets.sheet(0), right, margin),
        Sheets::Strip { .. } => return None,
        Sheets::Remnant { outline, .. } => path_bbox(outline).max.x,
    };
    let c = right + margin;
    (end - c > margin.max(1e-9)).then_some(c)
}

/// Utilisation of one sheet holding `part_area`: on a strip, over the
/// strip's used rectangle (`height` × `used`); on a sheet, paper 001's
/// part area over the useful area, the remnant beyond `crop` excluded.
pub fn sheet_utilisation(
    sheets: &Sheets,
    part_area: f64,
    height: f64,
    used: f64,
    crop: Option<f64>,
    tol: f64,
) -> f64 {
    match sheets {
        Sheets::Strip { .. } if used > 0.0 => part_area / (height * used),
        Sheets::Strip { .. } => 0.0,
        _ => {
            let (sheet, rem) = areas(sheets, crop, tol);
            utilisation(part_area, sheet, rem)
        }
    }
}

/// (sheet area, remnant area) of one sheet with its crop at `crop`: the
/// no-go zones are not sheet.
pub fn areas(sheets: &Sheets, crop: Option<f64>, tol: f64) -> (f64, f64) {
    let (outline, no_go) = polygons(sheets, tol);
    let area = |c: Option<(f64, bool)>| {
        let a = |p: &[Point]| match c {
            Some((x, left)) => signed_area(&clip_x(p, x, left)).abs(),
            None => signed_area(p).abs(),
        };
        a(&outline) - no_go.iter().map(|z| a(z)).sum::<f64>()
    };
    let sheet = area(None);
    let remnant = crop.map_or(0.0, |x| area(Some((x, false))));
    (sheet, remnant)
}

/// The crop line at x = `crop`: the stretches of the line inside the
/// sheet, each from its upper end (on the sheet's edge) down.
pub fn crop_line(sheets: &Sheets, crop: f64, tol: f64) -> Vec<Segment> {
    let (outline, _) = polygons(sheets, tol);
    let n = outline.len();
    let mut ys: Vec<f64> = (0..n)
        .filter_map(|i| {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            ((a.x > crop) != (b.x > crop)).then(|| a.y + (crop - a.x) * (b.y - a.y) / (b.x - a.x))
        })
        .collect();
    ys.sort_by(|a, b| b.total_cmp(a));
    ys.chunks_exact(2)
        .map(|w| Segment::line(Point::new(crop, w[0]), Point::new(crop, w[1])))
        .collect()
}

/// The remnant to keep: the sheet right of x = `crop` (its outline, then
/// the no-go zones that reach into it, each clipped), polygons.
pub fn remnant(sheets: &Sheets, crop: f64, tol: f64) -> (Vec<Point>, Vec<Vec<Point>>) {
    let (outline, no_go) = polygons(sheets, tol);
    (
        clip_x(&outline, crop, false),
        no_go
            .iter()
            .map(|z| clip_x(z, crop, false))
            .filter(|z| z.len() >= 3)
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utilisation_on_the_thesis_numbers_is_73_68_percent() {
        // Paper 001 §6.3/§6.7: sheet 12000 × 2440, the remnant's RET
        // polygon (Annex F), parts 15.2752 m².
        let ret = [
            (8630.00, 2440.00),
            (8630.00, 1373.37),
            (8380.52, 1246.25),
            (8380.52, 0.00),
            (12000.00, 0.00),
            (12000.00, 2440.00),
        ]
        .map(|(x, y)| Point::new(x, y));
        let remnant = signed_area(&ret).abs();
        assert!((remnant / 1e6 - 8.5496).abs() < 5e-5, "{}", remnant / 1e6);
        let u = utilisation(15.2752e6, 12000.0 * 2440.0, remnant);
        assert!((u * 100.0 - 73.68).abs() < 0.005, "{}", u * 100.0);
    }

    #[test]
    fn a_rect_sheet_is_cropped_at_the_used_length_plus_margin() {
        let sheets = Sheets::Rect {
            width: 1000.0,
            height: 500.0,
            count: 1,
        };
        assert_eq!(crop_x(&sheets, 600.0, 10.0), Some(610.0));
        // A remnant narrower than the margin is scrap.
        assert_eq!(crop_x(&sheets, 985.0, 10.0), None);
        let (sheet, rem) = areas(&sheets, Some(610.0), 0.01);
        assert!((sheet - 500_000.0).abs() < 1e-6 && (rem - 390.0 * 500.0).abs() < 1e-6);
        let line = crop_line(&sheets, 610.0, 0.01);
        assert_eq!(
            line,
            vec![Segment::line(
                Point::new(610.0, 500.0),
                Point::new(610.0, 0.0)
            )]
        );
        let (outline, _) = remnant(&sheets, 610.0, 0.01);
        assert!((signed_area(&outline).abs() - 390.0 * 500.0).abs() < 1e-6);
    }

    #[test]
    fn a_u_remnant_is_cropped_where_it_is_sheet_and_its_defects_are_not_area() {
        // A U open at the top: x 0..300, y 0..200, notch x 100..200, y 100..200.
        let p = [
            (0.0, 0.0),
            (300.0, 0.0),
            (300.0, 200.0),
            (200.0, 200.0),
            (200.0, 100.0),
            (100.0, 100.0),
            (100.0, 200.0),
            (0.0, 200.0),
        ]
        .map(|(x, y)| Point::new(x, y));
        let segs = |p: &[Point]| -> Vec<Segment> {
            (0..p.len())
                .map(|i| Segment::line(p[i], p[(i + 1) % p.len()]))
                .collect()
        };
        let defect =
            [(10.0, 10.0), (30.0, 10.0), (30.0, 30.0), (10.0, 30.0)].map(|(x, y)| Point::new(x, y));
        let sheets = Sheets::Remnant {
            outline: segs(&p),
            no_go: vec![segs(&defect)],
        };
        assert_eq!(
            crop_line(&sheets, 150.0, 0.01),
            vec![Segment::line(
                Point::new(150.0, 100.0),
                Point::new(150.0, 0.0)
            )]
        );
        assert_eq!(crop_line(&sheets, 50.0, 0.01).len(), 1);
        let (sheet, rem) = areas(&sheets, Some(50.0), 0.01);
        assert!((sheet - (50_000.0 - 400.0)).abs() < 1e-6, "{sheet}");
        assert!((rem - (50_000.0 - 50.0 * 200.0)).abs() < 1e-6, "{rem}");
    }
}
