//! The search's best decoded nest as a [`Nest`]: placements numbered per
//! part (sheet copies first, then copies in holes, a host before its
//! guests), each sheet's figures (used length, crop line, utilisation per
//! paper 001 §6.3) and the copies left out with the reason.

use super::decode::{Decoded, Item};
use super::{remnant, Nest, NestJob, SheetUse, Sheets, Unplaced};
use crate::geom::{path_bbox, transform_segments};
use crate::text;

pub(super) fn assemble(
    job: &NestJob,
    items: &[Item],
    best: Decoded,
    mut unplaced: Vec<Unplaced>,
    evaluations: u64,
) -> Nest {
    let tol = job.settings.tolerance;
    // Numbered as the live display numbers them (one piece of code).
    let placements = super::live::placements(items, &best, job.parts.len());
    let mut sheets = Vec::new();
    let (mut area_all, mut used_all) = (0.0, 0.0);
    let origin_x = job.sheets.origin_x();
    let n_sheets = best.bins.len();
    for k in 0..n_sheets {
        let one = job.sheets.sheet(k);
        let (width, height) = one.size(0);
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
            remnant::crop_x(&one, right, job.settings.margin)
        } else {
            None
        };
        let utilisation = remnant::sheet_utilisation(&one, area, height, used, crop, tol);
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
    // Copies the first nest never reached: the budget or Stop came first.
    let mut stopped = vec![0usize; job.parts.len()];
    for &it in &best.stopped {
        stopped[items[it].part] += 1;
    }
    for (pi, &m) in stopped.iter().enumerate() {
        if m > 0 {
            unplaced.push(Unplaced {
                part: job.parts[pi].name.clone(),
                copies: m,
                reason: text!("the time budget ran out (or Stop came) before the first nest reached it";
                              "o tempo acabou (ou veio o Parar) antes de o primeiro encaixe chegar a estas cópias"),
            });
        }
    }
    for (pi, &m) in missing.iter().enumerate() {
        if m > 0 {
            let n = job.sheets.count();
            unplaced.push(Unplaced {
                part: job.parts[pi].name.clone(),
                copies: m,
                reason: text!("no room left on the {n} sheet(s)"; "sem espaço restante em {n} chapa(s)"),
            });
        }
    }
    Nest {
        placements,
        strip_length: matches!(job.sheets, Sheets::Strip { .. })
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
