//! Parts that share edges (issue 39 §6) in the contour and chained orders.
//! Cut one contour at a time, each part's kerf path would run half a kerf
//! inside its neighbour: the shared line cut twice, a kerf apart, and a
//! whole kerf taken from each part. What a shop expects of lines drawn
//! once is common-line cutting: each shared line cut once, on the line
//! (half the kerf from each side), and the outline round the group on its
//! kerf path. That is what the Eulerian order does for touching parts
//! ([`super::euler`]), so the faces that share edges are cut by it, and
//! every other contour in the order asked, as it would be without them:
//!
//! 1. the other contours that do not enclose a face (holes in the faces
//!    among them: a hole before its part);
//! 2. the faces, in the Eulerian order, from where those ended;
//! 3. the contours that enclose faces (a hole round a nest, a sheet's
//!    frame), in the order asked.
//!
//! When such a contour lies itself in a face (a hole in a panel with faces
//! inside it), no three steps keep every hole before its part: the whole
//! drawing is then cut in the Eulerian order, which orders its circuits so.

use super::{euler, CutPlan, PlanInput, PlanOptions};
use crate::contour::Contours;
use crate::kerf::KerfPaths;
use crate::text;
use crate::warning::Warning;

/// Per contour: whether it is a face that shares an edge.
fn faces(contours: &Contours) -> Vec<bool> {
    let mut face = vec![false; contours.contours.len()];
    for &c in &contours.shared.contours {
        if let Some(f) = face.get_mut(c) {
            *f = true;
        }
    }
    face
}

/// True when `input` has kerf paths of faces that share edges to cut.
pub(super) fn cuts_faces(input: &PlanInput) -> bool {
    if !input.contours.shared.any() {
        return false;
    }
    let face = faces(input.contours);
    (input.kerf.paths.iter()).any(|p| face.get(p.contour).copied().unwrap_or(false))
}

/// The plan of `input` (whose faces share edges, [`cuts_faces`]): the faces
/// in the Eulerian order, the rest by `rest` (the order asked), which is
/// given the kerf paths of everything but the faces.
pub(super) fn plan(
    input: &PlanInput,
    options: &PlanOptions,
    rest: impl FnOnce(&PlanInput, &PlanOptions) -> CutPlan,
) -> CutPlan {
    let contours = &input.contours.contours;
    let face = faces(input.contours);
    // Contours round a face: cut after it.
    let mut encloses = vec![false; contours.len()];
    for &c in &input.contours.shared.contours {
        let mut up = contours.get(c).and_then(|c| c.parent);
        while let Some(p) = up {
            // Nesting has no cycles; the mark also stops a walk that met it.
            if encloses.get(p).is_none_or(|&e| e) {
                break;
            }
            encloses[p] = true;
            up = contours[p].parent;
        }
    }
    let in_face = |c: usize| {
        let mut up = contours.get(c).and_then(|c| c.parent);
        let mut guard = 0;
        while let Some(p) = up.filter(|_| guard <= contours.len()) {
            if face[p] {
                return true;
            }
            guard += 1;
            up = contours[p].parent;
        }
        false
    };
    if (0..contours.len()).any(|c| encloses[c] && !face[c] && in_face(c)) {
        let mut plan = euler::plan(input, options);
        plan.warnings.push(Warning::new(
            "shared-edges-eulerian",
            text!("parts that share edges lie in holes of parts that share edges: the whole drawing is cut in the eulerian order, which keeps every hole before its part";
                  "peças que compartilham arestas estão em furos de peças que compartilham arestas: o desenho todo é cortado na ordem euleriana, que mantém cada furo antes da sua peça"),
        ));
        return plan;
    }
    let paths = |faces: bool| KerfPaths {
        paths: (input.kerf.paths.iter())
            .filter(|p| face.get(p.contour).copied().unwrap_or(false) == faces)
            .cloned()
            .collect(),
        ..KerfPaths::default()
    };
    let (others, shared) = (paths(false), paths(true));
    let mut plan = rest(
        &PlanInput {
            kerf: &others,
            ..*input
        },
        options,
    );
    let (after, before): (Vec<_>, Vec<_>) = std::mem::take(&mut plan.cuts)
        .into_iter()
        .partition(|c| c.contours.iter().any(|&k| encloses.get(k) == Some(&true)));
    let mut from = options.clone();
    from.origin = before.last().map_or(options.origin, |c| c.end());
    // Open contours are the order asked's, cut with the others.
    from.cut_open = false;
    let faces = euler::plan_only(
        &PlanInput {
            kerf: &shared,
            ..*input
        },
        &from,
        Some(&face),
    );
    plan.cuts = before;
    plan.cuts.extend(faces.cuts);
    plan.cuts.extend(after);
    // The spacing of the other parts is not the order asked's to report;
    // the faces' own is `parts-share-edges`.
    plan.warnings
        .extend((faces.warnings.into_iter()).filter(|w| w.code != "parts-closer-than-kerf"));
    plan.warnings = crate::warning::group(plan.warnings);
    plan.common_line = faces.common_line;
    plan
}
