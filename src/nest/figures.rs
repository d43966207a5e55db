//! The figures of a nest as its placements now stand (after a hand edit,
//! [`super::edit`]): used length, utilisation per paper 001 §6.3 and the
//! crop line, computed as the search computes them for the nest it found,
//! and where the operator may move the crop line (never into a part and
//! its margin, never leaving a remnant narrower than the margin).

use super::{remnant, NestJob, Placement, SheetUse, Sheets};
use crate::geom::{path_bbox, transform_segments};

/// The crop line of sheet `k` may go from the rightmost part plus the margin
/// to the sheet's end less the margin (a narrower remnant is scrap): that
/// range, None when it is empty (or for a strip).
pub fn crop_range(job: &NestJob, placements: &[Placement], k: usize) -> Option<(f64, f64)> {
    let m = job.settings.margin;
    if matches!(job.sheets, Sheets::Strip { .. }) {
        return None;
    }
    let x0 = job.sheets.origin_x();
    let end = x0 + job.sheets.size(k).0?;
    let right = right_of(job, placements, k).unwrap_or(x0);
    let lo = right + m;
    let hi = end - m.max(1e-9);
    (lo < hi).then_some((lo, hi))
}

/// The rightmost x of the parts on sheet `k`, None when it has none.
fn right_of(job: &NestJob, placements: &[Placement], k: usize) -> Option<f64> {
    placements
        .iter()
        .filter(|p| p.sheet == k)
        .filter_map(|p| {
            let mut segs = Vec::new();
            transform_segments(
                &job.parts.get(p.part)?.outer,
                &p.affine(),
                job.settings.tolerance,
                &mut segs,
            );
            Some(path_bbox(&segs).max.x)
        })
        .reduce(f64::max)
}

/// The figures of `sheets` sheets holding `placements`, as the search's
/// (used length, utilisation per paper 001 §6.3, the crop line on the last
/// sheet), and the density of them all. `crop`: where the operator put the
/// last sheet's crop line, kept when it is in [`crop_range`] (else moved
/// into it); `Some(None)`: no crop line (no remnant kept).
pub fn figures(
    job: &NestJob,
    placements: &[Placement],
    sheets: usize,
    crop: Option<Option<f64>>,
) -> (Vec<SheetUse>, f64) {
    let tol = job.settings.tolerance;
    let origin_x = job.sheets.origin_x();
    let (mut out, mut area_all, mut used_all) = (Vec::new(), 0.0, 0.0);
    for k in 0..sheets {
        let one = job.sheets.sheet(k);
        let (width, height) = one.size(0);
        let on: Vec<&Placement> = placements.iter().filter(|p| p.sheet == k).collect();
        let area: f64 = on
            .iter()
            .filter_map(|p| job.parts.get(p.part))
            .map(|p| p.area())
            .sum();
        let used = right_of(job, placements, k)
            .unwrap_or(origin_x)
            .max(origin_x)
            - origin_x;
        let crop_x = if k + 1 == sheets {
            let range = crop_range(job, placements, k);
            match crop {
                Some(None) => None,
                Some(Some(x)) => range.map(|(lo, hi)| x.clamp(lo, hi)),
                None => {
                    range.and_then(|_| remnant::crop_x(&one, origin_x + used, job.settings.margin))
                }
            }
        } else {
            None
        };
        let utilisation = remnant::sheet_utilisation(&one, area, height, used, crop_x, tol);
        out.push(SheetUse {
            width: width.unwrap_or(used),
            height,
            parts: on.len(),
            used_length: used,
            utilisation,
            crop_x,
        });
        area_all += area;
        used_all += height * used;
    }
    (
        out,
        if used_all > 0.0 {
            area_all / used_all
        } else {
            0.0
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::edit::tests::{at, job};

    #[test]
    fn figures_follow_the_placements_and_the_crop_line_stays_clear_of_the_parts() {
        let job = job();
        let ps = [at(0, 0, 10.0, 10.0), at(0, 1, 114.0, 10.0)];
        let (s, _) = figures(&job, &ps, 1, None);
        assert_eq!(s[0].used_length, 214.0);
        assert_eq!(s[0].crop_x, Some(224.0));
        assert_eq!(crop_range(&job, &ps, 0), Some((224.0, 390.0)));
        let area = 2.0 * (5000.0 - 1800.0);
        assert!((s[0].utilisation - area / (224.0 * 200.0)).abs() < 1e-9);
        // Moved right by the operator, then too far left: held at the parts.
        assert_eq!(
            figures(&job, &ps, 1, Some(Some(300.0))).0[0].crop_x,
            Some(300.0)
        );
        assert_eq!(
            figures(&job, &ps, 1, Some(Some(100.0))).0[0].crop_x,
            Some(224.0)
        );
        assert_eq!(figures(&job, &ps, 1, Some(None)).0[0].crop_x, None);
        let u = figures(&job, &ps, 1, Some(None)).0[0].utilisation;
        assert!((u - area / 80_000.0).abs() < 1e-9);
    }
}
