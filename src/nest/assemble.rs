//! The search's best decoded nest as a [`Nest`]: placements numbered per
//! part (sheet copies first, then copies in holes, a host before its
//! guests), each sheet's figures (used length, crop line, utilisation per
//! paper 001 §6.3) and the copies left out with the reason.

use super::decode::{At, Decoded, Item};
use super::place::Placed;
use super::{remnant, Nest, NestJob, Placement, SheetUse, Sheets, Unplaced};
use crate::geom::{path_bbox, transform_segments};

pub(super) fn assemble(
    job: &NestJob,
    items: &[Item],
    best: Decoded,
    mut unplaced: Vec<Unplaced>,
    width: Option<f64>,
    height: f64,
    evaluations: u64,
) -> Nest {
    let tol = job.settings.tolerance;
    let mut copies = vec![0usize; job.parts.len()];
    let mut placements = Vec::new();
    // Sheet copies first, then hole copies in the order their holes were
    // opened (a host always before its guests): (part, copy) of each.
    let mut id_sheet: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut id_hole: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut place = |p: &Placed, sheet: usize, host: Option<(usize, usize)>| {
        let item = &items[p.item];
        let v = &item.variants[p.variant];
        let part = item.part;
        let pl = Placement {
            part,
            copy: copies[part],
            sheet,
            rotation: v.rotation,
            mirror: v.mirror,
            translation: p.t,
            in_hole_of: host,
        };
        copies[part] += 1;
        placements.push(pl);
        (part, pl.copy)
    };
    for (k, bin) in best.bins.iter().enumerate() {
        id_sheet.push(bin.placed.iter().map(|p| place(p, k, None)).collect());
    }
    for h in &best.holes {
        let host = match h.host {
            At::Sheet(b, i) => id_sheet[b][i],
            At::Hole(j, i) => id_hole[j][i],
        };
        id_hole.push(
            h.bin
                .placed
                .iter()
                .map(|p| place(p, h.sheet, Some(host)))
                .collect(),
        );
    }
    let mut sheets = Vec::new();
    let (mut area_all, mut used_all) = (0.0, 0.0);
    let origin_x = match &job.sheets {
        Sheets::Remnant { outline, .. } => path_bbox(outline).min.x,
        _ => 0.0,
    };
    let n_sheets = best.bins.len();
    for k in 0..n_sheets {
        let (mut right, mut area, mut count) = (origin_x, 0.0, 0);
        for pl in placements.iter().filter(|p| p.sheet == k) {
            let mut segs = Vec::new();
            transform_segments(&job.parts[pl.part].outer, &pl.affine(), tol, &mut segs);
            right = right.max(path_bbox(&segs).max.x);
            area += job.parts[pl.part].area();
            count += 1;
        }
        let used = right - origin_x;
        let crop = if k + 1 == n_sheets {
            remnant::crop_x(&job.sheets, right, job.settings.margin)
        } else {
            None
        };
        let utilisation = match job.sheets {
            Sheets::Strip { .. } if used > 0.0 => area / (height * used),
            Sheets::Strip { .. } => 0.0,
            _ => {
                let (sheet, rem) = remnant::areas(&job.sheets, crop, tol);
                remnant::utilisation(area, sheet, rem)
            }
        };
        sheets.push(SheetUse {
            width: width.unwrap_or(used),
            height,
            parts: count,
            used_length: used,
            utilisation,
            crop_x: crop,
        });
        area_all += area;
        used_all += height * used;
    }
    let mut missing = vec![0usize; job.parts.len()];
    for &it in &best.unplaced {
        missing[items[it].part] += 1;
    }
    for (pi, &m) in missing.iter().enumerate() {
        if m > 0 {
            let n = match job.sheets {
                Sheets::Rect { count, .. } => count,
                _ => 1,
            };
            unplaced.push(Unplaced {
                part: job.parts[pi].name.clone(),
                copies: m,
                reason: format!("no room left on the {n} sheet(s)"),
            });
        }
    }
    Nest {
        placements,
        strip_length: width
            .is_none()
            .then(|| sheets.first().map_or(0.0, |s| s.used_length)),
        sheets,
        unplaced,
        density: if used_all > 0.0 {
            area_all / used_all
        } else {
            0.0
        },
        evaluations,
    }
}
