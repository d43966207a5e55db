//! The operator's choices on a drawing (start points, tabs: issue 39 §1;
//! a router profile's side: issue 43 §1),
//! kept by what they were set on, never by a contour number. Contour
//! numbers change with every setting that changes the drawing (a layer
//! switched off, the units, the gap, healing, a nest edit); a choice made
//! on one loop must never land on another.
//!
//! A [`Pick`] is a point on the loop, in program coordinates, and, when
//! the page made it, the loop's [`LoopKey`]: its reference and its shape
//! (area, length, box size: what renumbering does not change). Each
//! plan matches every pick again ([`place`]): the closed contour passing
//! through the point whose shape is the key's. A pick whose loop is not
//! there (its layer off, healed away) is kept by whoever holds it and not
//! applied, and the plan says so ([`not_applied`]). A pick without a key
//! (the CLI's `--start X,Y`) takes the loop nearest its point within its
//! reach.

use serde::Serialize;

use crate::contour::{Contour, Contours};
use crate::geom::{nearest_param, BBox, Point};
use crate::kerf::Side;
use crate::source::ContourRef;
use crate::text;
use crate::warning::{dec, Warning};

/// Nearest a keyed pick's point is to its loop for the loop to be its
/// own, at least (mm): the page stores the point projected onto the loop,
/// rounded to micrometres, and rebased in micrometres when the origin or
/// the unit changes; healing may move a corner a little.
const ON_LOOP_MM: f64 = 0.05;

/// How far a pick without a key may be from its loop, mm (the CLI's).
pub const REACH_MM: f64 = 1.0;

/// What a choice was set on: the loop's reference and its shape.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LoopKey {
    /// Its part, copy and loop when it was set.
    pub source: ContourRef,
    /// Area enclosed, mm² (unsigned).
    pub area: f64,
    /// Length, mm.
    pub length: f64,
    /// Width and height of its box, mm.
    pub size: [f64; 2],
    /// Its layer (for the message when it is not cut).
    pub layer: String,
}

impl LoopKey {
    /// The key of `c`.
    pub fn of(c: &Contour) -> LoopKey {
        LoopKey {
            source: c.source,
            area: c.area.abs(),
            length: c.length,
            size: [c.bbox.max.x - c.bbox.min.x, c.bbox.max.y - c.bbox.min.y],
            layer: c.layer.to_string(),
        }
    }

    /// True when `c` has this shape, within `eps` mm (areas and lengths
    /// also within a thousandth: a unit change rebases them in floats).
    fn fits(&self, c: &Contour, eps: f64) -> bool {
        let near = |a: f64, b: f64, abs: f64| (a - b).abs() <= abs + 1e-3 * a.abs().max(b.abs());
        let k = LoopKey::of(c);
        near(self.length, k.length, 4.0 * eps)
            && near(self.area, k.area, 4.0 * eps * self.length.max(k.length))
            && near(self.size[0], k.size[0], 2.0 * eps)
            && near(self.size[1], k.size[1], 2.0 * eps)
    }
}

/// A choice's place: a point on a loop, program coordinates, mm, and the
/// loop it was set on when known.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Pick {
    /// The point.
    pub at: Point,
    /// The loop, when the pick was made on one ([`pick_at`]).
    pub on: Option<LoopKey>,
    /// For a pick without a key: how far its loop may be, mm.
    pub reach: f64,
}

impl Pick {
    /// A pick at `at` for the loop nearest it within `reach` mm.
    pub fn near(at: Point, reach: f64) -> Pick {
        Pick {
            at,
            on: None,
            reach,
        }
    }
    /// How far its loop may be from its point, mm: a keyed pick's is on
    /// it ([`ON_LOOP_MM`] or ten tolerances), another's its reach.
    pub fn reach_at(&self, tolerance: f64) -> f64 {
        if self.on.is_some() {
            ON_LOOP_MM.max(10.0 * tolerance)
        } else {
            self.reach.max(0.0)
        }
    }
}

/// The closed contour passing nearest `p` within `reach` mm, as a pick:
/// the point moved onto the loop, with the loop's key.
pub fn pick_at(contours: &Contours, p: Point, reach: f64) -> Option<(usize, Pick)> {
    let (i, q, _) = nearest(contours, p, reach, |_| true)?;
    let c = &contours.contours[i];
    let q = Point::new(micro(q.x), micro(q.y));
    Some((
        i,
        Pick {
            at: q,
            on: Some(LoopKey::of(c)),
            reach: 0.0,
        },
    ))
}

fn micro(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}

/// The closed contour (one `keep` accepts) passing nearest `p` within
/// `reach`: its index, its point nearest `p`, the distance. Ties go to
/// the smaller loop (a point on an edge two faces share names the inner).
fn nearest(
    contours: &Contours,
    p: Point,
    reach: f64,
    keep: impl Fn(&Contour) -> bool,
) -> Option<(usize, Point, f64)> {
    let mut best: Option<(usize, Point, f64)> = None;
    for (i, c) in contours.contours.iter().enumerate() {
        if !c.is_closed() || !c.bbox.overlaps(&BBox::at(p), reach) || !keep(c) {
            continue;
        }
        for s in &c.segments {
            let q = s.point_at(nearest_param(s, p));
            let d = q.dist(p);
            if d > reach {
                continue;
            }
            let better = match best {
                None => true,
                Some((j, _, bd)) => {
                    d < bd - 1e-9
                        || (d <= bd + 1e-9
                            && j != i
                            && c.area.abs() < contours.contours[j].area.abs())
                }
            };
            if better {
                best = Some((i, q, d));
            }
        }
    }
    best
}

/// The contour each of `picks` is on now, if any. A keyed pick takes the
/// closed contour through its point (within [`ON_LOOP_MM`] or ten
/// tolerances) whose shape is its key's, the one with its reference
/// first; never another.
pub fn place(picks: &[Pick], contours: &Contours, tolerance: f64) -> Vec<Option<usize>> {
    let eps = ON_LOOP_MM.max(10.0 * tolerance);
    picks
        .iter()
        .map(|pick| {
            if !pick.at.is_finite() {
                return None;
            }
            match &pick.on {
                None => nearest(contours, pick.at, pick.reach.max(0.0), |_| true).map(|b| b.0),
                Some(key) => {
                    let same = nearest(contours, pick.at, eps, |c| {
                        c.source == key.source && key.fits(c, eps)
                    });
                    same.or_else(|| nearest(contours, pick.at, eps, |c| key.fits(c, eps)))
                        .map(|b| b.0)
                }
            }
        })
        .collect()
}

/// The picks of `placed` (as [`place`] gave) that found a contour, as
/// (contour, point) pairs in order.
pub fn applied(picks: &[Pick], placed: &[Option<usize>]) -> Vec<(usize, Point)> {
    picks
        .iter()
        .zip(placed)
        .filter_map(|(p, c)| c.map(|c| (c, p.at)))
        .collect()
}

/// Why a pick was not applied.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unapplied {
    /// No loop it was set on is cut now.
    Gone,
    /// Its loop is there but this order chooses its own entries.
    Order,
    /// Its loop is there but has no room for it (a tab on a short or small
    /// loop, a start on a loop not cut as a loop).
    NoRoom,
    /// A side on a loop that is not a router profile: without a tool the
    /// kerf goes to the scrap side.
    NotProfile,
    /// A side on an open contour: it has no inside or outside.
    Open,
    /// A side where the controller's compensation or the Eulerian order
    /// sets the tool's side itself.
    OwnSide,
}

/// A router profile's side chosen on a loop (issue 43 §1): the tool's
/// centre outside, inside or on the line of that loop alone.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SidePick {
    /// Where it was set.
    pub pick: Pick,
    /// The side.
    #[serde(serialize_with = "side_name")]
    pub side: Side,
}

fn side_name<S: serde::Serializer>(side: &Side, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(side.name())
}

/// The side picks matched to the contours ([`sides`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sided {
    /// Contour `i`'s chosen side, if any (empty when none is applied).
    pub sides: Vec<Option<Side>>,
    /// The picks not applied: their index in the picks, and why.
    pub missed: Vec<(usize, Unapplied)>,
}

/// Matches side `picks` to `contours` ([`place`]; the last on a loop
/// wins). `profiles`: the closed contours are a router's profiles (a
/// tool is given); `own_side`: the controller's compensation or the
/// order sets the side. A pick on no closed loop but near an open
/// contour is [`Unapplied::Open`]; nothing is moved to another loop.
pub fn sides(
    picks: &[SidePick],
    contours: &Contours,
    tolerance: f64,
    profiles: bool,
    own_side: bool,
) -> Sided {
    let mut out = Sided::default();
    if picks.is_empty() {
        return out;
    }
    let only: Vec<Pick> = picks.iter().map(|p| p.pick.clone()).collect();
    let placed = place(&only, contours, tolerance);
    out.sides = vec![None; contours.contours.len()];
    for (k, (sp, c)) in picks.iter().zip(placed).enumerate() {
        let why = match c {
            None => {
                if near_open(contours, sp.pick.at, sp.pick.reach_at(tolerance)) {
                    Some(Unapplied::Open)
                } else {
                    Some(Unapplied::Gone)
                }
            }
            Some(_) if !profiles => Some(Unapplied::NotProfile),
            Some(_) if own_side => Some(Unapplied::OwnSide),
            Some(c) => {
                out.sides[c] = Some(sp.side);
                None
            }
        };
        out.missed.extend(why.map(|w| (k, w)));
    }
    if out.sides.iter().all(Option::is_none) {
        out.sides.clear();
    }
    out
}

/// True when an open contour passes within `reach` of `p`.
fn near_open(contours: &Contours, p: Point, reach: f64) -> bool {
    p.is_finite()
        && contours.contours.iter().any(|c| {
            !c.is_closed()
                && c.bbox.overlaps(&BBox::at(p), reach)
                && c.segments
                    .iter()
                    .any(|s| s.point_at(nearest_param(s, p)).dist(p) <= reach)
        })
}

/// The warning naming the side picks ([`sides`]) not applied, or none.
pub fn sides_not_applied(
    picks: &[SidePick],
    missed: &[(usize, Unapplied)],
    contours: &Contours,
) -> Option<Warning> {
    if missed.is_empty() {
        return None;
    }
    let n = missed.len();
    let what = text!("{n} profile side(s)"; "{n} lado(s) de perfil");
    let list: Vec<(&Pick, Unapplied)> = (missed.iter())
        .filter_map(|&(k, why)| picks.get(k).map(|p| (&p.pick, why)))
        .collect();
    Some(listed("sides-not-applied", what, &list, contours))
}

/// The warning naming the picks that were not applied, or none: `starts`
/// and `tabs` are each (pick, why).
pub fn not_applied(
    starts: &[(&Pick, Unapplied)],
    tabs: &[(&Pick, Unapplied)],
    contours: &Contours,
) -> Option<Warning> {
    if starts.is_empty() && tabs.is_empty() {
        return None;
    }
    let all: Vec<(&Pick, Unapplied)> = starts.iter().chain(tabs).copied().collect();
    let what = match (starts.len(), tabs.len()) {
        (s, 0) => text!("{s} start point(s)"; "{s} ponto(s) de entrada"),
        (0, t) => text!("{t} tab(s)"; "{t} ponte(s)"),
        (s, t) => {
            text!("{s} start point(s) and {t} tab(s)"; "{s} ponto(s) de entrada e {t} ponte(s)")
        }
    };
    Some(listed("choices-not-applied", what, &all, contours))
}

/// The warning `code` saying that `what`, set on the drawing, is kept
/// but not applied, naming each pick's place and why.
fn listed(
    code: &'static str,
    what: crate::warning::Text,
    picks: &[(&Pick, Unapplied)],
    contours: &Contours,
) -> Warning {
    // The layers that have no contour in the plan now: switched off.
    let cut_layers: std::collections::BTreeSet<&str> =
        contours.contours.iter().map(|c| &*c.layer).collect();
    let mut places = Vec::new();
    for (pick, why) in picks {
        if places.len() == 5 {
            places.push(text!("…"; "…"));
            break;
        }
        // English with a decimal point, Portuguese with a comma.
        let um = |v: f64| (v * 1000.0).round() / 1000.0;
        let (x, y) = (um(pick.at.x), um(pick.at.y));
        let (xd, yd) = (dec(x), dec(y));
        let layer = pick.on.as_ref().map(|k| k.layer.as_str()).unwrap_or("");
        places.push(match why {
            Unapplied::Gone if !layer.is_empty() && !cut_layers.contains(layer) => text!(
                "({x}, {y}): layer {layer} is not cut now";
                "({xd}; {yd}): a camada {layer} não é cortada agora"),
            Unapplied::Gone => text!(
                "({x}, {y}): the loop it was set on is not in the drawing now";
                "({xd}; {yd}): o contorno em que foi posto não está no desenho agora"),
            Unapplied::Order => text!(
                "({x}, {y}): this cut order chooses its own entries";
                "({xd}; {yd}): esta ordem de corte escolhe as próprias entradas"),
            Unapplied::NoRoom => text!(
                "({x}, {y}): no room on its loop (too short, or not cut as a loop)";
                "({xd}; {yd}): sem espaço no seu contorno (curto demais, ou não cortado como contorno)"),
            Unapplied::NotProfile => text!(
                "({x}, {y}): not a router profile (no tool diameter: the kerf goes to the scrap side)";
                "({xd}; {yd}): não é um perfil de fresadora (sem diâmetro de ferramenta: a sangria vai para o lado da sucata)"),
            Unapplied::Open => text!(
                "({x}, {y}): an open contour has no inside or outside";
                "({xd}; {yd}): um contorno aberto não tem lado de dentro nem de fora"),
            Unapplied::OwnSide => text!(
                "({x}, {y}): the controller's compensation or the Eulerian order sets the side";
                "({xd}; {yd}): a compensação do controlador ou a ordem euleriana define o lado"),
        });
    }
    let en: Vec<&str> = places.iter().map(|t| t.en.as_str()).collect();
    let pt: Vec<&str> = places.iter().map(|t| t.pt.as_str()).collect();
    Warning::new(
        code,
        text!("{} set on the drawing are kept but not applied: {}", what.en, en.join("; ");
              "{} definidos no desenho foram guardados mas não aplicados: {}", what.pt, pt.join("; ")),
    )
}

#[cfg(test)]
#[path = "choice_tests.rs"]
mod tests;
