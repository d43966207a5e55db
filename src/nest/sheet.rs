//! An irregular sheet (a remnant) from a drawing's contours: its outer
//! outline is the sheet; its holes and every closed contour on a layer
//! named `DEFECT` are no-go zones (issue 16, item 6).

use super::output::DEFECT_LAYER;
use super::{NestError, Sheets};
use crate::contour::{ContourKind, Contours};
use crate::text;
use crate::warning::Text;

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
