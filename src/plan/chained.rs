//! Order "chained": parts' outer contours linked one to the next through
//! scrap with the torch on, one pierce per chain.
//!
//! Paper 001 §6.4 ("encadeamento", L461, L1261, L2138–L2143) chains outer
//! contours to save pierces — long preheats on thick plate that also wear
//! tips — and cuts the inner cut-outs of every chained part first (the MTX
//! lists `INSERT … INTERNO` records before the chain polyline, L2704–L2715).
//! Paper 002 keeps the torch on while consecutive entities touch. So: holes
//! stay where the contour order put them, but every hole of a chain's parts
//! is cut before the chain starts; a link from one outer's end to the next
//! outer's pierce point is cut only when it is no longer than the maximum
//! link, crosses no part, and keeps half the kerf from every part (issue 14:
//! a link is a torch-on move like any other, [`Scrap::line_ok`]).

use super::clearance::Obstacles;
use super::scrap::Scrap;
use super::{Cut, Role, Step};
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};

/// Whether `c` can be a link in a chain: an outer contour of a part lying
/// on the sheet itself (not in another part's hole).
fn chainable(c: &Cut, top_level: &dyn Fn(usize) -> bool) -> bool {
    c.kind == ContourKind::Outer
        && !c.spot
        && c.contours.len() == 1
        && c.contours.first().is_some_and(|&k| top_level(k))
}

/// Regroups contour-order cuts into chains. `top_level(contour)` says
/// whether a contour lies on the sheet itself; `replan(cut, near)` plans an
/// outer contour's cut again starting nearest `near` (so the next part of a
/// chain is entered on the side facing the previous one).
pub fn chain(
    cuts: Vec<Cut>,
    max_link: f64,
    obstacles: &Obstacles,
    scrap: &Scrap,
    top_level: &dyn Fn(usize) -> bool,
    replan: &mut dyn FnMut(&Cut, Point) -> Option<Cut>,
) -> Vec<Cut> {
    let mut out: Vec<Cut> = Vec::with_capacity(cuts.len());
    // Cuts waiting for the current chain to be written (holes, islands, open contours).
    let mut waiting: Vec<Cut> = Vec::new();
    // The chain being built, and the part numbers in it.
    let mut chain: Option<(Cut, Vec<usize>)> = None;
    for mut c in cuts {
        if !chainable(&c, top_level) {
            waiting.push(c);
            continue;
        }
        if let Some((ch, parts)) = chain.as_mut() {
            let from = ch.end();
            let linkable = |c: &Cut| {
                from.dist(c.pierce) <= max_link
                    && obstacles.line_is_clear(from, c.pierce, &[from])
                    && scrap.line_ok(from, c.pierce)
            };
            // Entered nearest the chain's end if that links, else as planned if that does.
            let linked = match replan(&c, from).filter(|r| linkable(r)) {
                Some(r) => Ok(r),
                None if linkable(&c) => Ok(c),
                None => Err(c),
            };
            match linked {
                Err(unlinked) => c = unlinked,
                Ok(c) => {
                    ch.steps.push(Step {
                        segment: Segment::line(from, c.pierce),
                        role: Role::Link,
                        contour: None,
                    });
                    ch.steps.extend(c.steps);
                    ch.contours.extend(c.contours);
                    parts.extend(c.part);
                    continue;
                }
            }
        }
        if let Some((done, parts)) = chain.take() {
            flush(&mut out, &mut waiting, done, &parts);
        }
        let parts = c.part.into_iter().collect();
        chain = Some((c, parts));
    }
    if let Some((done, parts)) = chain.take() {
        flush(&mut out, &mut waiting, done, &parts);
    }
    out.append(&mut waiting);
    out
}

/// Writes the waiting cuts up to the last one that belongs to one of the
/// chain's parts (everything before it too, so no precedence is broken),
/// then the chain; later parts' holes keep waiting.
fn flush(out: &mut Vec<Cut>, waiting: &mut Vec<Cut>, chain: Cut, parts: &[usize]) {
    if let Some(i) = waiting
        .iter()
        .rposition(|w| w.part.is_some_and(|p| parts.contains(&p)))
    {
        let rest = waiting.split_off(i + 1);
        out.append(waiting);
        *waiting = rest;
    }
    out.push(chain);
}
