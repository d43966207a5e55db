//! What a parts file holds, part by part, before anything is nested (issue
//! 42 §1): each part's size, area and holes, whether the nester can place
//! it at all (by the nester's own test), and what makes the file suspect —
//! an open outer outline whose holes would be listed as parts, or a swarm
//! of tiny parts. The page shows one row per part from this, greyed where a
//! part cannot be nested, so the operator sees the drawing before the nest.

use super::shape::collision_polygon;
use super::Part;
use crate::contour::{ContourKind, Contours};
use crate::text;
use crate::warning::{dec, Text};

/// One part of a file as its row shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct PartRow {
    /// The nest's name of the part: the file stem, `/BLOCK` for a part
    /// drawn as a block, `#n` for a file of several not told apart by
    /// their blocks ([`super::parts_from_contours`]).
    pub name: String,
    /// The layer its outline is drawn on.
    pub layer: String,
    /// Its outline's box, mm: lower-left corner and size.
    pub x: f64,
    pub y: f64,
    pub width: f64,
    pub height: f64,
    /// Net area (outline less holes), mm².
    pub area: f64,
    /// Holes inside it.
    pub holes: usize,
    /// Why the nester cannot place it (None: it can).
    pub not_nestable: Option<Text>,
}

/// The rows of one file and what makes the file suspect.
#[derive(Clone, Debug, PartialEq)]
pub struct FileRows {
    /// One per part, in the file's part order (the order `quantities`
    /// follow).
    pub rows: Vec<PartRow>,
    /// Open contours: cut on the line or not at all, never nested.
    pub open: usize,
    /// What an operator should look at before nesting this file.
    pub suspect: Vec<Text>,
}

/// At least this many parts, most of them under [`TINY_SHARE`] of the
/// largest's area, is a swarm: a part's holes or engraving read as parts.
const SWARM: usize = 20;
const TINY_SHARE: f64 = 0.01;

/// The rows of `parts` read from `contours`; `tol` is the nest's
/// tolerance and `grow` half its spacing: the nester's own test of a
/// placeable outline is its collision polygon, the outline grown by half
/// the spacing ([`super::search`]). Grown, not as drawn: an outline whose
/// polygon is there ungrown may have none grown (a loop whose offset
/// vanishes), and the nest would leave it out.
pub fn file_rows(parts: &[Part], contours: &Contours, tol: f64, grow: f64) -> FileRows {
    let outers = contours
        .contours
        .iter()
        .filter(|c| c.kind == ContourKind::Outer);
    let rows: Vec<PartRow> = parts
        .iter()
        .zip(outers)
        .map(|(p, c)| PartRow {
            name: p.name.clone(),
            layer: c.layer.to_string(),
            x: c.bbox.min.x,
            y: c.bbox.min.y,
            width: c.bbox.max.x - c.bbox.min.x,
            height: c.bbox.max.y - c.bbox.min.y,
            area: p.area(),
            holes: p.holes.len(),
            not_nestable: collision_polygon(&p.outer, grow, tol).is_none().then(|| {
                text!("its outline encloses no area: not nestable";
                      "o contorno não encerra área: não pode ser encaixada")
            }),
        })
        .collect();
    let open = contours
        .contours
        .iter()
        .filter(|c| c.kind == ContourKind::Open)
        .count();
    let mut suspect = Vec::new();
    if open > 0 && !rows.is_empty() {
        suspect.push(text!("{open} open contour(s) beside {} part(s): if a part's outline is one of them, its holes are listed as parts; close it in the drawing (or raise the gap) before nesting", rows.len();
                           "{open} contorno(s) aberto(s) ao lado de {} peça(s): se o contorno de uma peça é um deles, os furos dela aparecem como peças; feche-o no desenho (ou aumente a folga) antes de encaixar", rows.len()));
    }
    let largest = rows.iter().map(|r| r.area).fold(0.0, f64::max);
    let tiny = rows
        .iter()
        .filter(|r| r.area < TINY_SHARE * largest)
        .count();
    if rows.len() >= SWARM && 2 * tiny > rows.len() {
        let share = 100.0 * TINY_SHARE;
        let shared = dec(share);
        suspect.push(text!("{tiny} of {} parts are under {share} % of the largest's area: holes, text or hatching read as parts?", rows.len();
                           "{tiny} de {} peças têm menos de {shared} % da área da maior: furos, textos ou hachuras lidos como peças?", rows.len()));
    }
    FileRows {
        rows,
        open,
        suspect,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::spec::parts_and_contours;
    use crate::test_dxf::{file, outline, rect};
    use crate::Settings;

    fn rows_of(body: &str) -> FileRows {
        let cutting = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let (parts, contours) = parts_and_contours(&file(body), "f", &cutting).unwrap();
        file_rows(&parts, &contours, 0.05, 1.25)
    }

    #[test]
    fn each_part_is_a_row_with_its_size_area_and_holes() {
        let body = [
            rect(0.0, 0.0, 100.0, 50.0),
            rect(10.0, 10.0, 20.0, 20.0),
            rect(200.0, 0.0, 30.0, 40.0),
        ]
        .concat();
        let f = rows_of(&body);
        assert_eq!(f.rows.len(), 2, "{f:?}");
        let a = &f.rows[0];
        assert_eq!((a.name.as_str(), a.width, a.height, a.holes), ("f#1", 100.0, 50.0, 1));
        assert!((a.area - (5000.0 - 400.0)).abs() < 1e-6, "{}", a.area);
        assert!(a.not_nestable.is_none());
        assert_eq!((f.rows[1].width, f.rows[1].holes), (30.0, 0));
        assert!(f.suspect.is_empty() && f.open == 0);
    }

    #[test]
    fn an_outline_the_nester_cannot_grow_is_greyed() {
        // A 20 × 10 rectangle whose right side is an arc of bulge −3 (it
        // sweeps back across the rectangle): the contour stage repairs it
        // into a loop of 6.8 mm², which the nester's grown collision
        // polygon loses.
        let body = "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n20\n20\n0\n42\n-3\n10\n20\n20\n10\n10\n0\n20\n10\n"
            .to_string()
            + &rect(100.0, 0.0, 30.0, 20.0);
        let f = rows_of(&body);
        assert_eq!(f.rows.len(), 2, "{f:?}");
        let grey: Vec<bool> = f.rows.iter().map(|r| r.not_nestable.is_some()).collect();
        assert_eq!(grey.iter().filter(|&&g| g).count(), 1, "{f:?}");
        let bad = f.rows.iter().find(|r| r.not_nestable.is_some()).unwrap();
        assert!(bad.area > 1.0 && bad.width < 25.0, "{bad:?}");
        // The nester itself leaves it out for the same reason.
        let cutting = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let (parts, _) = parts_and_contours(&file(&body), "f", &cutting).unwrap();
        let job = crate::nest::NestJob {
            parts,
            sheets: crate::nest::Sheets::Rect { width: 300.0, height: 200.0, count: 1 },
            settings: crate::nest::NestSettings { spacing: 2.5, time_s: 0.0, ..Default::default() },
        };
        let n = crate::nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
        assert_eq!(n.placements.len(), 1, "{:?}", n.unplaced);
        assert!(n.unplaced.iter().any(|u| u.part == bad.name && u.reason.en.contains("encloses no area") && u.reason.pt.contains("não encerra área")), "{:?}", n.unplaced);
    }

    #[test]
    fn an_open_outline_around_slots_makes_the_file_suspect() {
        // A grille: the outline drawn open (three sides), its slots closed.
        let mut body = outline(&[(0.0, 0.0), (300.0, 0.0), (300.0, 200.0), (0.0, 200.0)])
            .replace("70\n1\n", "70\n0\n");
        for k in 0..5 {
            body += &rect(20.0 + 50.0 * k as f64, 50.0, 10.0, 100.0);
        }
        let f = rows_of(&body);
        assert_eq!((f.rows.len(), f.open), (5, 1), "{f:?}");
        assert_eq!(f.suspect.len(), 1);
        assert!(f.suspect[0].get(crate::warning::Lang::En).contains("holes are listed as parts"));
    }

    #[test]
    fn a_swarm_of_tiny_parts_is_said() {
        let mut body = rect(0.0, 0.0, 500.0, 500.0);
        for k in 0..25 {
            body += &rect(600.0 + 10.0 * k as f64, 0.0, 3.0, 3.0);
        }
        let f = rows_of(&body);
        assert_eq!(f.rows.len(), 26);
        assert_eq!(f.suspect.len(), 1, "{f:?}");
        // 25 of 26 tiny: said; 5 tiny among 5 large: not.
        let mut body = String::new();
        for k in 0..20 {
            body += &rect(60.0 * k as f64, 0.0, 50.0, 50.0);
        }
        for k in 0..5 {
            body += &rect(60.0 * k as f64, 100.0, 3.0, 3.0);
        }
        assert!(rows_of(&body).suspect.is_empty());
    }
}
