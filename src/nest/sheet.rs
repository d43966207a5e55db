//! An irregular sheet (a remnant) from a drawing's contours: its outer
//! outline is the sheet; its holes and every closed contour on a layer
//! named `DEFECT` are no-go zones (issue 16, item 6).

use super::output::DEFECT_LAYER;
use super::{NestError, Sheets};
use crate::contour::{ContourKind, Contours};

/// The sheet drawn in `contours`: the largest outer outline not on
/// `DEFECT`, its holes and the closed `DEFECT` contours as no-go zones.
/// Open contours are left out (they enclose nothing); what else is drawn
/// is said in the returned notes.
pub fn sheet_from_contours(contours: &Contours) -> Result<(Sheets, Vec<String>), NestError> {
    let defect = |layer: &str| layer.eq_ignore_ascii_case(DEFECT_LAYER);
    let outer = contours
        .contours
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kind == ContourKind::Outer && !defect(&c.layer))
        .max_by(|a, b| a.1.area.abs().total_cmp(&b.1.area.abs()))
        .map(|(i, _)| i)
        .ok_or_else(|| NestError::Setting {
            field: "sheet-dxf",
            reason: "no closed outline (outside the DEFECT layer) to be the sheet".into(),
        })?;
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
        notes.push(format!(
            "{open} open contour(s) on the sheet drawing left out: an open line is no no-go zone (close it, or draw it on layer DEFECT as a closed outline)"
        ));
    }
    if other > 0 {
        notes.push(format!(
            "{other} closed contour(s) inside the sheet's holes or outside it left out (only the largest outline, its holes and layer DEFECT count)"
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
