//! Which copy each move of a sheet's cut plan is charged to: the plan's
//! lengths and counts ([`PlanStats`]) split by copy, so that each copy's
//! time comes from the same estimate as the sheet's
//! ([`PlanStats::est_time_s`], linear in every length and count: the
//! copies' times sum to the sheet's).
//!
//! The rules, move by move:
//! - a cut (its rapid in, its pierce, its feed moves) belongs to the copy
//!   of the first contour it cuts: the rapid into a pierce is that copy's;
//! - a feed move on a contour (lead-in, the contour, lead-out, a tab) is
//!   that contour's copy's;
//! - a link through scrap (a chain, an Eulerian bridge) belongs to the
//!   copy whose contour it leads into;
//! - a common-line cut (one cut separating two parts, issue 14) is split
//!   equally between the two copies it separates;
//! - what belongs to no copy (a nest's crop line, open contours, markings
//!   of no part) is the sheet's own, and the quote shares it equally among
//!   the copies on the sheet.

use std::collections::{BTreeMap, HashMap};

use crate::geom::Segment;
use crate::plan::{PlanStats, Role};
use crate::Output;

/// A copy on a sheet: (part, copy) of its contours' [`crate::source::ContourRef`].
pub type CopyKey = (u32, u32);

/// A sheet's plan stats, by copy.
#[derive(Clone, Debug, Default)]
pub struct Split {
    /// Every copy whose outline is on the sheet (cut or not), with what is
    /// charged to it and its own area (outline less holes, mm²).
    pub copies: BTreeMap<CopyKey, (PlanStats, f64)>,
    /// What belongs to no copy.
    pub sheet: PlanStats,
}

/// Bit pattern of a segment, to find a step's common-line cut again: the
/// planner records the step's own segment ([`crate::plan::CommonCut`]).
fn seg_key(s: &Segment) -> [u64; 5] {
    [s.a.x, s.a.y, s.b.x, s.b.y, s.bulge].map(f64::to_bits)
}

/// `out`'s plan stats split by copy (see the module's rules).
pub fn split(out: &Output) -> Split {
    let contours = &out.contours.contours;
    let mut sp = Split::default();
    // Every copy on the sheet, its area; the drawing's part numbers (what
    // common-line cuts name) to copies.
    let mut by_part: HashMap<usize, CopyKey> = HashMap::new();
    for c in contours
        .iter()
        .filter(|c| c.is_closed() && c.source.part > 0)
    {
        let key = (c.source.part, c.source.copy);
        let e = sp.copies.entry(key).or_default();
        e.1 += if c.source.contour == 0 {
            c.area.abs()
        } else {
            -c.area.abs()
        };
        if let (Some(p), true) = (c.part, c.source.contour == 0) {
            by_part.insert(p, key);
        }
    }
    let owner = |k: Option<usize>| -> Option<CopyKey> {
        let c = contours.get(k?)?;
        (c.source.part > 0).then_some((c.source.part, c.source.copy))
    };
    let common: HashMap<[u64; 5], (Option<CopyKey>, Option<CopyKey>)> = out
        .plan
        .common_line
        .iter()
        .map(|cc| {
            let copy = |p: Option<usize>| p.and_then(|p| by_part.get(&p).copied());
            (seg_key(&cc.segment), (copy(cc.parts.0), copy(cc.parts.1)))
        })
        .collect();
    let mut at = out.plan.origin;
    for c in &out.plan.cuts {
        let first = c
            .contours
            .first()
            .copied()
            .or_else(|| c.steps.iter().find_map(|s| s.contour));
        let cut_owner = owner(first);
        {
            let st = charged(&mut sp, cut_owner);
            st.rapid_length += at.dist(c.pierce);
            if c.spot {
                st.spots += 1;
            } else {
                st.pierces += 1;
                st.small_holes += usize::from(c.small_hole);
                st.chains += usize::from(c.contours.len() > 1);
            }
        }
        at = c.end();
        if c.spot {
            continue;
        }
        // The copy each link leads into: the next step's on a contour.
        let mut next: Option<CopyKey> = None;
        let mut into = vec![None; c.steps.len()];
        for (i, s) in c.steps.iter().enumerate().rev() {
            if let Some(o) = owner(s.contour) {
                next = Some(o);
            }
            into[i] = next;
        }
        for (s, into) in c.steps.iter().zip(into) {
            let l = s.segment.length();
            let shared = matches!(s.role, Role::Contour | Role::Repeat)
                .then(|| common.get(&seg_key(&s.segment)))
                .flatten();
            match shared {
                Some(&(Some(a), Some(b))) if a != b => {
                    charged(&mut sp, Some(a)).add_step(s.role, l / 2.0, c.small_hole);
                    charged(&mut sp, Some(b)).add_step(s.role, l / 2.0, c.small_hole);
                }
                _ => {
                    let who = match (s.role, s.contour) {
                        (_, Some(_)) => owner(s.contour),
                        (Role::Link, None) => into.or(cut_owner),
                        (_, None) => cut_owner,
                    };
                    charged(&mut sp, who).add_step(s.role, l, c.small_hole);
                }
            }
        }
    }
    sp
}

/// The stats `who` is charged in: its copy's, or the sheet's own when it
/// is no copy on the sheet.
fn charged(sp: &mut Split, who: Option<CopyKey>) -> &mut PlanStats {
    match who.filter(|k| sp.copies.contains_key(k)) {
        Some(k) => &mut sp.copies.entry(k).or_default().0,
        None => &mut sp.sheet,
    }
}
