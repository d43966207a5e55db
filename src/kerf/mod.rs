//! Stage 3: [`Contours`] → [`KerfPaths`]: kerf compensation done in software
//! (paper 000 "CRC", paper 001 §5), so the program needs no G41/G42.
//!
//! # Output contract
//! - Every closed contour is offset by `kerf/2` to its scrap side: outward for
//!   an outer, inward for a hole. Arcs stay arcs (cavalier_contours offsets
//!   bulge polylines exactly); convex corners get round joins (what a round
//!   kerf really cuts) or, with [`Join::Miter`], sharp mitres as in paper 001.
//! - Paper 000's *invalid vertices* are reported: a corner that turns towards
//!   the scrap side cannot be cut sharp (the kerf leaves a fillet of radius
//!   kerf/2), nor can an arc that bends towards the scrap side with a radius
//!   under kerf/2. This geometric rule covers the paper's line-arc and
//!   arc-arc cases exactly instead of by its angle heuristics.
//! - A hole that vanishes or splits under the offset is reported and not cut.
//! - Kerf 0 cuts on the line. Open contours get no path.
//! - Paths are counter-clockwise; the planner chooses the cutting direction.

use cavalier_contours::polyline::{
    PlineCreation, PlineOffsetOptions, PlineSource, PlineSourceMut, Polyline,
};

use crate::contour::{ContourKind, Contours};
use crate::geom::{Point, Segment, Tolerance};
use crate::par::Threads;
use crate::text;
use crate::warning::{dec, Warning};

/// How convex corners of the offset path are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Join {
    /// An arc of radius kerf/2 around the corner (shortest path; the default).
    Round,
    /// The neighbouring lines extended to meet (paper 001's compensated
    /// vertices); falls back to round when the mitre would exceed 4 × kerf/2.
    Miter,
}

/// The kerf compensation settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kerf {
    /// Kerf width in mm (≥ 0).
    pub width: f64,
    /// Convex corner joins.
    pub join: Join,
    /// Threads that may offset the contours (the paths are the same with any).
    pub threads: Threads,
}

/// Where the tool's centre goes from a closed contour (issue 43 §1: a
/// router profile outside, inside or on the line). Without a choice an
/// outer is cut outside and a hole inside: the scrap side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Offset outwards by half the kerf (the waste outside).
    Outside,
    /// Offset inwards by half the kerf (the waste inside).
    Inside,
    /// On the drawn line: half the tool on either side.
    On,
}

impl Side {
    /// Every side.
    pub const ALL: [Side; 3] = [Side::Outside, Side::Inside, Side::On];
    /// The name used by the CLI, the page and the report.
    pub fn name(self) -> &'static str {
        match self {
            Side::Outside => "outside",
            Side::Inside => "inside",
            Side::On => "on",
        }
    }
    /// The side called `name`.
    pub fn from_name(name: &str) -> Option<Side> {
        Side::ALL.into_iter().find(|s| s.name() == name.trim())
    }
    /// The kind of contour whose scrap side this is (the waste's side for
    /// the direction, leads and corners): an outer's outside, a hole's
    /// inside; on the line, `kind`'s own.
    pub fn waste_kind(self, kind: ContourKind) -> ContourKind {
        match self {
            Side::Outside => ContourKind::Outer,
            Side::Inside => ContourKind::Hole,
            Side::On => kind,
        }
    }
    /// The scrap side of a contour of `kind`: outside an outer, inside a hole.
    pub fn of(kind: ContourKind) -> Side {
        if kind == ContourKind::Hole {
            Side::Inside
        } else {
            Side::Outside
        }
    }
}

/// One compensated contour, ready to be planned.
#[derive(Clone, Debug)]
pub struct KerfPath {
    /// Index of the source contour.
    pub contour: usize,
    /// Outer or hole.
    pub kind: ContourKind,
    /// Where the path is from its contour: [`Side::of`] its kind unless
    /// the operator chose otherwise ([`offset_sided`]).
    pub side: Side,
    /// Part number of the source contour.
    pub part: Option<usize>,
    /// Closed, counter-clockwise loop of segments (|bulge| ≤ 1).
    pub segments: Vec<Segment>,
}

/// All compensated contours.
#[derive(Clone, Debug, Default)]
pub struct KerfPaths {
    /// One path per cuttable closed contour.
    pub paths: Vec<KerfPath>,
    /// Corners the kerf cannot reproduce (paper 000), in mm.
    pub invalid_vertices: Vec<Point>,
    /// Holes not cut, degenerate contours, …
    pub warnings: Vec<Warning>,
}

/// Largest mitre length, in offsets, before a mitre falls back to round (as SVG's default limit).
const MITER_LIMIT: f64 = 4.0;

/// `segs` as a closed polyline in `pl` (a buffer reused from loop to loop).
fn fill_pline(pl: &mut Polyline<f64>, segs: &[Segment]) {
    pl.clear();
    pl.set_is_closed(true);
    pl.reserve(segs.len());
    for s in segs {
        pl.add(s.a.x, s.a.y, s.bulge);
    }
}

/// A closed cavalier polyline as our segments (each vertex's bulge on the
/// segment it starts); also the router's pockets' ([`crate::mill`]).
pub(crate) fn from_pline(pl: &Polyline<f64>) -> Vec<Segment> {
    let n = pl.vertex_count();
    (0..n)
        .map(|i| {
            let v = pl.at(i);
            let w = pl.at((i + 1) % n);
            Segment {
                a: Point::new(v.x, v.y),
                b: Point::new(w.x, w.y),
                bulge: v.bulge,
            }
        })
        .collect()
}

/// Compensates every closed contour.
pub fn offset(contours: &Contours, kerf: Kerf, tol: Tolerance) -> KerfPaths {
    offset_sided(contours, kerf, tol, &[])
}

/// [`offset`], contour `i` to `sides[i]` where that is given (the
/// operator's choice for a router profile, [`crate::plan::choice::sides`]),
/// else to its scrap side.
pub fn offset_sided(
    contours: &Contours,
    kerf: Kerf,
    tol: Tolerance,
    sides: &[Option<Side>],
) -> KerfPaths {
    let half = kerf.width / 2.0;
    // Each contour is offset on its own: ranges of contours on the
    // threads, their paths and warnings joined in contour order.
    let n = contours.contours.len();
    let mut parts = crate::par::map_ranges(n, kerf.threads, 1024, |r| {
        offset_range(contours, r, kerf, tol, sides)
    });
    let mut out = if parts.len() == 1 {
        parts.pop().unwrap_or_default()
    } else {
        let mut out = KerfPaths {
            paths: Vec::with_capacity(parts.iter().map(|p| p.paths.len()).sum()),
            ..KerfPaths::default()
        };
        for p in parts {
            out.paths.extend(p.paths);
            out.invalid_vertices.extend(p.invalid_vertices);
            out.warnings.extend(p.warnings);
        }
        out
    };
    out.warnings = crate::warning::group(std::mem::take(&mut out.warnings));
    if !out.invalid_vertices.is_empty() {
        let (n, w) = (out.invalid_vertices.len(), kerf.width);
        out.warnings.push(Warning::at(
            "invalid-vertices",
            text!("{n} sharp corner(s) on the scrap side that a {w} mm kerf rounds, leaving material in the corner (paper 000's invalid vertices; add fillets of at least {half} mm if the corner must be sharp)";
                  "{n} canto(s) vivo(s) do lado da sucata que uma sangria de {} mm arredonda, deixando material no canto (vértices inválidos do artigo 000; acrescente raios de pelo menos {} mm se o canto precisa ser vivo)", dec(w), dec(half)),
            out.invalid_vertices[0],
        ));
    }
    out
}

/// [`offset`] of the contours in `range`, their warnings not yet grouped.
fn offset_range(
    contours: &Contours,
    range: std::ops::Range<usize>,
    kerf: Kerf,
    tol: Tolerance,
    sides: &[Option<Side>],
) -> KerfPaths {
    let mut out = KerfPaths {
        paths: Vec::with_capacity(range.len()),
        ..KerfPaths::default()
    };
    // Buffers reused from loop to loop: the drawn loop, its offset's.
    let (mut drawn, mut scratch) = (Polyline::<f64>::empty(), simple::Scratch::default());
    let corners = bounds::Corners::new(kerf.width / 2.0, tol.mm());
    for i in range {
        let c = &contours.contours[i];
        if !c.is_closed() {
            continue;
        }
        // The contour's area is its loop area (contour::extract): counter-clockwise
        // as drawn, borrowed; clockwise, reversed.
        let segs: std::borrow::Cow<[Segment]> = if c.area < 0.0 {
            c.segments.iter().rev().map(Segment::reversed).collect()
        } else {
            std::borrow::Cow::Borrowed(&c.segments)
        };
        let center = Point::new(
            (c.bbox.min.x + c.bbox.max.x) / 2.0,
            (c.bbox.min.y + c.bbox.max.y) / 2.0,
        );
        let (name, nome) = if c.kind == ContourKind::Hole {
            ("hole", "furo")
        } else {
            ("outer contour", "contorno externo")
        };
        let part = c.part.unwrap_or(0);
        let side = sides.get(i).copied().flatten().unwrap_or(Side::of(c.kind));
        // On the line nothing is offset (and no corner is on one side).
        let half = if side == Side::On {
            0.0
        } else {
            kerf.width / 2.0
        };
        let scrap_left = side == Side::Inside;
        if half > 0.0 && !corners.none_invalid(&segs, scrap_left, half) {
            out.invalid_vertices.extend(invalid_vertices(
                &segs,
                side.waste_kind(c.kind),
                half,
                tol,
            ));
        }
        let path = if half > 0.0 {
            // None means nothing was repeated: the loop as it is.
            fill_pline(&mut drawn, &segs);
            let cleaned = drawn.remove_repeat_pos(tol.mm());
            let pl = cleaned.as_ref().unwrap_or(&drawn);
            if pl.vertex_count() < 2 {
                out.warnings.push(
                    Warning::at(
                        "contour-degenerate",
                        text!("part {part}: degenerate {name} not cut";
                          "peça {part}: {nome} degenerado não cortado"),
                        center,
                    )
                    .of_kind(
                        text!("degenerate {name} not cut"; "{nome} degenerado não cortado"),
                        text!("part {part}"; "peça {part}"),
                    ),
                );
                continue;
            }
            // A loop that crosses itself has no inside to offset from.
            let crossings = simple::crossings(pl, tol.mm().min(1e-5));
            if let Some(x) = crossings.first() {
                let n = crossings.len();
                out.warnings.push(Warning::at(
                    "self-crossing",
                    text!("part {part}: {name} crosses itself ({n} crossing(s)): it cannot be kerf-compensated and is not cut";
                          "peça {part}: {nome} cruza a si mesmo ({n} cruzamento(s)): não pode ter a sangria compensada e não é cortado"),
                    *x,
                ).of_kind(
                    text!("{name} crosses itself: not kerf-compensated, not cut";
                          "{nome} cruza a si mesmo: sangria não compensada, não cortado"),
                    text!("part {part}"; "peça {part}"),
                ).with_loops([c.source]));
                continue;
            }
            let options = PlineOffsetOptions {
                pos_equal_eps: tol.mm().min(1e-5),
                ..Default::default()
            };
            // Positive offsets go to the left of a counter-clockwise loop: inwards.
            let d = if side == Side::Inside { half } else { -half };
            let keep = |r: &Polyline<f64>| {
                r.vertex_count() >= 2 && bounds::area_exceeds(r, tol.mm() * tol.mm())
            };
            let mut results = Vec::new();
            // Nothing repeated at the tolerance: nothing at the narrower
            // pos_equal_eps either (the short way need not look again).
            let clean = cleaned.is_none() && options.pos_equal_eps <= tol.mm();
            let short = simple::short_way_into(pl, d, &options, clean, &mut scratch);
            let offset = scratch.offset();
            let n = match short {
                Some(one) => usize::from(one && keep(offset)),
                None => {
                    results = pl.parallel_offset_opt(d, &options);
                    results.retain(keep);
                    results.len()
                }
            };
            // The one loop kept, or the largest (sorted first below).
            let first = |results: &[Polyline<f64>]| {
                if short.is_some() {
                    from_pline(offset)
                } else {
                    from_pline(&results[0])
                }
            };
            match n {
                0 => {
                    let w = kerf.width;
                    out.warnings.push(Warning::at(
                        "kerf-vanishes",
                            text!("part {part}: {name} is too small for the kerf ({w} mm) and vanishes: not cut";
                              "peça {part}: {nome} é pequeno demais para a sangria ({} mm) e desaparece: não cortado", dec(w)),
                        center,
                    ).of_kind(
                        text!("{name} too small for the kerf ({w} mm), not cut";
                              "{nome} pequeno demais para a sangria ({} mm), não cortado", dec(w)),
                        text!("part {part}"; "peça {part}"),
                    ).with_loops([c.source]));
                    continue;
                }
                1 => first(&results),
                n if side == Side::Inside && c.kind == ContourKind::Outer => {
                    let w = kerf.width;
                    out.warnings.push(Warning::at(
                        "inside-splits",
                        text!("part {part}: the outer contour cut inside splits into {n} pieces under the kerf (a neck narrower than {w} mm): not cut";
                              "peça {part}: o contorno externo cortado por dentro se divide em {n} pedaços com a sangria (um estreitamento menor que {} mm): não cortado", dec(w)),
                        center,
                    ).with_loops([c.source]));
                    continue;
                }
                n if side == Side::Inside => {
                    let w = kerf.width;
                    out.warnings.push(Warning::at(
                        "hole-splits",
                        text!("part {part}: hole splits into {n} pieces under the kerf (a neck narrower than {w} mm): not cut";
                              "peça {part}: o furo se divide em {n} pedaços com a sangria (um estreitamento menor que {} mm): não cortado", dec(w)),
                        center,
                    ).with_loops([c.source]));
                    continue;
                }
                n => {
                    let bays = n - 1;
                    out.warnings.push(Warning::at(
                        "bays-closed",
                        text!("part {part}: the kerf closes {bays} narrow bay(s) of the outer contour; they cannot be reached and are left uncut";
                              "peça {part}: a sangria fecha {bays} reentrância(s) estreita(s) do contorno externo; não podem ser alcançadas e ficam sem corte"),
                        center,
                    ));
                    crate::sort::sort_by(&mut results, |a, b| {
                        b.area().abs().total_cmp(&a.area().abs())
                    });
                    first(&results)
                }
            }
        } else {
            segs.into_owned()
        };
        let path = if kerf.join == Join::Miter && half > 0.0 {
            miter_joins(path, half, tol)
        } else {
            path
        };
        out.paths.push(KerfPath {
            contour: i,
            kind: c.kind,
            side,
            part: c.part,
            segments: path,
        });
    }
    out
}

/// Replaces round joins between two lines by mitres (paper 001's sharp
/// compensated vertices), within [`MITER_LIMIT`].
fn miter_joins(segs: Vec<Segment>, half: f64, tol: Tolerance) -> Vec<Segment> {
    let n = segs.len();
    if n < 3 {
        return segs;
    }
    // The mitre point replacing join arc i, if segment i is one.
    let mitre: Vec<Option<Point>> = (0..n)
        .map(|i| {
            let s = &segs[i];
            let (prev, next) = (&segs[(i + n - 1) % n], &segs[(i + 1) % n]);
            let (center, r) = s.arc_center()?;
            if (r - half).abs() > tol.mm() || !prev.is_line() || !next.is_line() {
                return None;
            }
            let (d1, d2) = (prev.b.sub(prev.a), next.b.sub(next.a));
            let den = d1.cross(d2);
            if den.abs() <= f64::EPSILON * d1.norm() * d2.norm() {
                return None;
            }
            let x = prev.a.add(d1.scale(next.a.sub(prev.a).cross(d2) / den));
            (x.dist(center) <= MITER_LIMIT * half).then_some(x)
        })
        .collect();
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        if mitre[i].is_some() {
            continue;
        }
        let mut s = segs[i];
        if let Some(x) = mitre[(i + n - 1) % n] {
            s.a = x;
        }
        if let Some(x) = mitre[(i + 1) % n] {
            s.b = x;
        }
        out.push(s);
    }
    out
}

mod bounds;
mod raw;
mod simple;
mod vertices;
use vertices::invalid_vertices;

#[cfg(test)]
mod tests;
