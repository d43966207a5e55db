//! Turning one contour into one [`Cut`]: its direction, its start point,
//! its lead-in in scrap, the loop, its overcut.

use super::clearance::Obstacles;
use super::lead::{self, Entry, LeadSite};
use super::router_lead;
use super::LeadKind;
use super::{Cut, PlanInput, PlanOptions, Role, Step};
use crate::contour::{point_in_loop, ContourKind};
use crate::geom::{nearest_param, path_bbox, Point, Segment};
use crate::kerf::Side;
use crate::text;
use crate::warning::{dec, Warning};

/// What a builder's leads had to give way to (see [`Builder::warnings`]).
#[derive(Debug, Default)]
pub struct GaveWay {
    shortened: Vec<Point>,
    on_contour: Vec<(usize, Point)>,
    uncompensated: Vec<(usize, Point)>,
    no_arc: Vec<NoArc>,
}

/// A router profile's lead arc that would gouge: the contour, where, and
/// which of its arcs (in, out) could not be cut.
#[derive(Clone, Copy, Debug)]
struct NoArc {
    contour: usize,
    at: Point,
    lead_in: bool,
    lead_out: bool,
}

/// Builds cuts and remembers what had to give way.
pub struct Builder<'a> {
    input: &'a PlanInput<'a>,
    options: &'a PlanOptions,
    /// The operator's start points: (contour, point on it).
    starts: &'a [(usize, Point)],
    /// Parts and holes as drawn: what leads and links must not cross.
    obstacles: &'a Obstacles,
    /// How far pierce points keep from parts, mm.
    pub clearance: f64,
    shortened: Vec<Point>,
    on_contour: Vec<(usize, Point)>,
    /// Contours left uncompensated: no lead-in line long enough for the
    /// controller to take up the offset on.
    uncompensated: Vec<(usize, Point)>,
    /// Router profiles whose lead arcs had no room ([`router_lead`]).
    no_arc: Vec<NoArc>,
    /// The loop of the cut being built (reused from cut to cut).
    scratch: Vec<Segment>,
}

impl<'a> Builder<'a> {
    /// A builder for one plan.
    pub fn new(
        input: &'a PlanInput<'a>,
        options: &'a PlanOptions,
        starts: &'a [(usize, Point)],
        obstacles: &'a Obstacles,
    ) -> Builder<'a> {
        Builder {
            input,
            options,
            starts,
            obstacles,
            // The pierce hole is about two kerfs wide: its edge must not reach
            // the part. Never less than ten tolerances.
            clearance: input.process.kerf.max(10.0 * input.tolerance),
            shortened: Vec::new(),
            on_contour: Vec::new(),
            uncompensated: Vec::new(),
            no_arc: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// Reads kerf paths `ks` (record, loop's ends) all at once, for
    /// [`Builder::contour_cut`] to find them in cache: in tour order a cut
    /// read its record, then its loop, two cache misses one after the
    /// other (over half its time on the 25 MB nest, perf); here none waits.
    pub fn warm(&self, ks: impl Iterator<Item = usize>) {
        let mut seen = 0u64;
        for p in ks.filter_map(|k| self.input.kerf.paths.get(k)) {
            if let (Some(a), Some(b)) = (p.segments.first(), p.segments.last()) {
                seen ^= a.a.x.to_bits() ^ b.b.y.to_bits();
            }
        }
        // Kept, or the reads would be optimised away.
        std::hint::black_box(seen);
    }

    /// True when kerf path `k` is cut counter-clockwise.
    fn ccw(&self, kind: ContourKind) -> bool {
        if kind == ContourKind::Hole {
            self.options.hole_ccw
        } else {
            self.options.outer_ccw
        }
    }

    /// Kerf path `k` in its cutting direction into `out`, from its vertex
    /// nearest `near` (the first of equals along the oriented path), or
    /// from its first vertex. Written rotated in
    /// place: the oriented copy, then its rotation, were a copy and a move
    /// of every cut's loop (and an allocation) on a 137k-contour sheet.
    fn oriented_into(&self, k: usize, near: Option<Point>, out: &mut Vec<Segment>) {
        out.clear();
        let Some(p) = self.input.kerf.paths.get(k) else {
            return;
        };
        let (segs, n) = (&p.segments, p.segments.len());
        // Kerf paths are counter-clockwise; a profile the operator put
        // inside an outer is cut as a hole is (its waste inside), and so on.
        let ccw = self.ccw(p.side.waste_kind(p.kind));
        let seg = |i: usize| {
            if ccw {
                segs[i]
            } else {
                segs[n - 1 - i].reversed()
            }
        };
        // The tour's entry is one of the path's vertices: the first vertex
        // equal to it is the first nearest (a distance of +0, the least
        // there is), found without a distance a vertex (`hypot`, ~550k
        // calls on the 25 MB nest). Any other point: the nearest by distance.
        let v = near.map_or(0, |q| {
            (0..n).find(|&i| seg(i).a == q).unwrap_or_else(|| {
                (0..n)
                    .min_by(|&i, &j| seg(i).a.dist(q).total_cmp(&seg(j).a.dist(q)))
                    .unwrap_or(0)
            })
        });
        out.extend((v..n).chain(0..v).map(seg));
    }

    /// The cut of kerf path `k` starting at its vertex nearest `near` (or at
    /// the user's start point for that contour): lead-in, the loop, overcut.
    pub fn contour_cut(&mut self, k: usize, near: Point) -> Option<Cut> {
        let p = self.input.kerf.paths.get(k)?;
        let (contour, part, kind, side) = (p.contour, p.part, p.kind, p.side);
        let user = self
            .starts
            .iter()
            .rev()
            .find(|(c, _)| *c == contour)
            .map(|(_, at)| *at);
        // The loop in the builder's buffer (taken, and given back below
        // once its segments are the cut's steps).
        let mut segs = std::mem::take(&mut self.scratch);
        self.oriented_into(k, user.is_none().then_some(near), &mut segs);
        if segs.is_empty() {
            self.scratch = segs;
            return None;
        }
        if let Some(at) = user {
            segs = split_loop_at(&segs, at);
        }
        if kind == ContourKind::Hole && side == Side::Inside && self.small(contour) {
            return Some(self.small_hole_cut(segs, contour, part));
        }
        // Outer: scrap outside, on the left when cutting clockwise.
        // Hole: scrap (the slug) inside, on the left when counter-clockwise.
        // A profile's chosen side: the waste is on that side.
        let waste = side.waste_kind(kind);
        let hole = waste == ContourKind::Hole;
        let scrap_left = hole == self.ccw(waste);
        let router = self.input.process.tool.on() && self.options.leads.kind == LeadKind::Arc;
        let (mut entry, exit) = if router {
            self.router_arcs(&mut segs, contour, scrap_left, user.is_some(), side)
        } else {
            let site = LeadSite {
                path: &segs,
                scrap_left,
                hole,
            };
            let e = lead::lead_in(&site, &self.options.leads, self.obstacles, self.clearance);
            (e, None)
        };
        if !router && entry.lead.is_none() && entry.changed && user.is_none() {
            // No room here: try up to 16 other vertices spread around the loop
            // (a narrow hole is often wide enough at one end).
            let n = segs.len();
            let step = n.div_ceil(16).max(1);
            for v in (step..n).step_by(step) {
                let mut other = segs.clone();
                other.rotate_left(v);
                let site = LeadSite {
                    path: &other,
                    scrap_left,
                    hole,
                };
                let e = lead::lead_in(&site, &self.options.leads, self.obstacles, self.clearance);
                if e.lead.is_some() {
                    entry = Entry { changed: true, ..e };
                    segs = other;
                    break;
                }
            }
        }
        if entry.lead.is_none() && entry.changed {
            self.on_contour.push((contour, entry.pierce));
        } else if entry.changed {
            self.shortened.push(entry.pierce);
        }
        let tag = |role: Role| {
            move |segment: Segment| Step {
                segment,
                role,
                contour: Some(contour),
            }
        };
        let over = lead::overcut(&segs, self.options.leads.overcut);
        // Sized once: grown from the lead's length, each cut's steps were
        // copied again (the cuts' allocations were a quarter of their time
        // on a 137k-contour sheet, perf).
        let mut steps: Vec<Step> =
            Vec::with_capacity(usize::from(entry.lead.is_some()) + segs.len() + over.len() + 1);
        steps.extend(entry.lead.into_iter().map(tag(Role::LeadIn)));
        steps.extend(segs.drain(..).map(tag(Role::Contour)));
        steps.extend(over.into_iter().map(tag(Role::LeadOut)));
        if let Some(out) = exit {
            // From where the loop (or its overcut) ends, tangent to it.
            let last = steps[steps.len() - 1].segment;
            let arc = router_lead::arc_out(last.b, last.tangent_at(1.0), scrap_left, out);
            steps.push(tag(Role::LeadOut)(arc));
        }
        self.scratch = segs;
        let comp = self.options.controller_comp.then_some(()).and_then(|_| {
            // The controller needs a straight entry longer than the tool's
            // radius (LinuxCNC refuses a shorter one, or an arc).
            let first = steps.first()?;
            let ok = first.role == Role::LeadIn
                && first.segment.is_line()
                && first.segment.length() > self.input.process.kerf / 2.0 + self.input.tolerance;
            if !ok {
                self.uncompensated.push((contour, entry.pierce));
            }
            // The tool goes to the scrap side.
            ok.then_some(scrap_left)
        });
        Some(Cut {
            pierce: entry.pierce,
            steps,
            contours: vec![contour],
            part,
            kind,
            spot: false,
            small_hole: false,
            comp,
        })
    }

    /// A router profile's lead arcs (`--lead arc` with a tool,
    /// [`router_lead`]): the lead-in as an [`Entry`], and the lead-out's
    /// radius when it has room. `segs` is the loop from its start; without
    /// the operator's start point, when an arc has no room there, the
    /// loop is started at one of up to 16 vertices spread around it where
    /// both have, else at the middle of one of its longest edges. An arc
    /// with no room anywhere is not cut, and said.
    fn router_arcs(
        &mut self,
        segs: &mut Vec<Segment>,
        contour: usize,
        waste_left: bool,
        user: bool,
        side: Side,
    ) -> (Entry, Option<f64>) {
        let radius = self.input.process.tool.lead_arc();
        let keep = self.input.process.kerf / 2.0;
        let slack = 10.0 * self.input.tolerance.max(1e-6);
        // On the line the profile itself cuts half the tool into either
        // side: its arcs are kept in its waste (the side its kind leaves,
        // sampled every 1/16 of the arc) and from crossing a drawn line
        // (they touch their own where they meet it).
        let drawn = self.input.contours.contours.get(contour);
        let waste_inside = drawn.is_some_and(|c| c.kind == ContourKind::Hole);
        let in_waste = |arc: &Segment| {
            drawn.is_some_and(|c| {
                (1..16).all(|k| {
                    point_in_loop(arc.point_at(k as f64 / 16.0), &c.segments) == waste_inside
                })
            })
        };
        let clear = |arc: &Segment, at: Point| {
            if side == Side::On {
                in_waste(arc)
                    && self
                        .obstacles
                        .path_is_clear(std::slice::from_ref(arc), &[at])
            } else {
                router_lead::swept_clear(self.obstacles, arc, keep, slack)
            }
        };
        let over = self.options.leads.overcut;
        let fits = |segs: &[Segment]| {
            let first = segs[0];
            let lead_in = router_lead::arc_in(first.a, first.tangent_at(0.0), waste_left, radius);
            let tail = lead::overcut(segs, over);
            let last = tail.last().or(segs.last()).copied().unwrap_or(first);
            let lead_out = router_lead::arc_out(last.b, last.tangent_at(1.0), waste_left, radius);
            (
                clear(&lead_in, first.a).then_some(lead_in),
                clear(&lead_out, last.b),
            )
        };
        let (mut lead_in, mut lead_out) = fits(segs);
        let mut both = lead_in.is_some() && lead_out;
        if !both && !user {
            let n = segs.len();
            let step = n.div_ceil(16).max(1);
            for v in (step..n).step_by(step) {
                let mut other = segs.clone();
                other.rotate_left(v);
                if let (Some(i), true) = fits(&other) {
                    (lead_in, lead_out, both) = (Some(i), true, true);
                    *segs = other;
                    break;
                }
            }
        }
        if !both && !user {
            // A loop of corners only (a rectangular hole, or any loop cut
            // on the line) has no room at a vertex: each arc, tangent to
            // one edge there, runs across the other. Mid-edge it has, on
            // the longest edges first (up to 8 of them).
            let mut longest: Vec<usize> = (0..segs.len()).collect();
            crate::sort::sort_by(&mut longest, |&i, &j| {
                segs[j].length().total_cmp(&segs[i].length())
            });
            for &i in longest.iter().take(8) {
                let other = split_loop_at(segs, segs[i].point_at(0.5));
                if let (Some(a), true) = fits(&other) {
                    (lead_in, lead_out) = (Some(a), true);
                    *segs = other;
                    break;
                }
            }
        }
        let start = segs[0].a;
        if lead_in.is_none() || !lead_out {
            self.no_arc.push(NoArc {
                contour,
                at: start,
                lead_in: lead_in.is_none(),
                lead_out: !lead_out,
            });
        }
        let entry = Entry {
            pierce: lead_in.map_or(start, |s| s.a),
            lead: lead_in,
            changed: false,
        };
        (entry, lead_out.then_some(radius))
    }

    /// True when drawn contour `c` is a hole narrower than the small-hole
    /// diameter (its bounding box's smaller side: a circle's diameter, a
    /// slot's width).
    fn small(&self, c: usize) -> bool {
        let rule = &self.input.process.small_hole;
        rule.diameter > 0.0
            && self.input.contours.contours.get(c).is_some_and(|k| {
                let b = k.bbox;
                (b.max.x - b.min.x).min(b.max.y - b.min.y) < rule.diameter
            })
    }

    /// A small hole (issue 20 §3, ProNest's "True Hole" and QtPlasmaC's
    /// hole cutting): pierced at the centre, where the slug drops out, a
    /// straight lead-in to the loop, the loop, an overcut past the start,
    /// no lead-out; written at the reduced speed with the height control
    /// locked (the post's `small_hole_on` and `thc_lock`).
    fn small_hole_cut(&self, segs: Vec<Segment>, contour: usize, part: Option<usize>) -> Cut {
        let b = path_bbox(&segs);
        let centre = b.centre();
        let tag = |role: Role| {
            move |segment: Segment| Step {
                segment,
                role,
                contour: Some(contour),
            }
        };
        let over = lead::overcut(&segs, self.input.process.small_hole.overcut);
        let mut steps = Vec::with_capacity(segs.len() + over.len() + 1);
        if centre.dist(segs[0].a) > self.input.tolerance {
            steps.push(tag(Role::LeadIn)(Segment::line(centre, segs[0].a)));
        }
        steps.extend(segs.into_iter().map(tag(Role::Contour)));
        steps.extend(over.into_iter().map(tag(Role::LeadOut)));
        Cut {
            pierce: steps[0].segment.a,
            steps,
            contours: vec![contour],
            part,
            kind: ContourKind::Hole,
            spot: false,
            small_hole: true,
            comp: None,
        }
    }

    /// What the leads of this builder's cuts gave way to, for
    /// [`Builder::absorb`] (a builder per thread, joined in cut order).
    pub fn into_gave_way(self) -> GaveWay {
        GaveWay {
            shortened: self.shortened,
            on_contour: self.on_contour,
            uncompensated: self.uncompensated,
            no_arc: self.no_arc,
        }
    }

    /// Takes on what another builder's cuts, cut after this one's so
    /// far, gave way to: the warnings are as if this builder had built
    /// them.
    pub fn absorb(&mut self, mut g: GaveWay) {
        self.shortened.append(&mut g.shortened);
        self.on_contour.append(&mut g.on_contour);
        self.uncompensated.append(&mut g.uncompensated);
        self.no_arc.append(&mut g.no_arc);
    }

    /// What the leads had to give way to, as warnings.
    pub fn warnings(&self) -> Vec<Warning> {
        let mut w = Vec::new();
        if let Some((c, p)) = self.uncompensated.first() {
            let (n, c, r) = (self.uncompensated.len(), c + 1, self.input.process.kerf / 2.0);
            w.push(Warning::at(
                "comp-no-lead",
                text!("{n} contour(s) have no straight lead-in longer than the tool radius {r:.3} mm for the controller's compensation (contour {c} first): they are written on the drawn line, uncompensated";
                      "{n} contorno(s) sem entrada reta mais longa que o raio da ferramenta {} mm para a compensação do controlador (o contorno {c} primeiro): escritos sobre a linha desenhada, sem compensação", dec(r)),
                *p,
            ));
        }
        if let Some(first) = self.no_arc.first() {
            let n = self.no_arc.len();
            let r = self.input.process.tool.lead_arc();
            let rd = dec(r);
            let c = first.contour + 1;
            let (en, pt) = match (first.lead_in, first.lead_out) {
                (true, true) => ("goes straight down onto its contour and straight up from it", "desce reto sobre o contorno e sobe reto dele"),
                (true, false) => ("goes straight down onto its contour", "desce reto sobre o contorno"),
                _ => ("goes straight up from its contour", "sobe reto do contorno"),
            };
            w.push(Warning::at(
                "lead-arc-no-room",
                text!("{n} profile(s) have no room for the {r} mm lead arc: the tool would gouge the part or a neighbour; there (contour {c} first) the tool {en} (a smaller --lead-radius may fit)";
                      "{n} perfil(is) sem espaço para o arco de entrada/saída de {rd} mm: a ferramenta invadiria a peça ou uma vizinha; ali (o contorno {c} primeiro) a ferramenta {pt} (um --lead-radius menor pode caber)"),
                first.at,
            ));
        }
        if let Some(p) = self.shortened.first() {
            let (n, c) = (self.shortened.len(), self.clearance);
            w.push(Warning::at(
                "leads-shortened",
                text!("{n} lead-in(s) shortened, turned or moved to a hole's centre: the asked lead \
                       would have crossed a part or pierced within {c:.3} mm of one";
                      "{n} entrada(s) encurtada(s), girada(s) ou levada(s) ao centro do furo: a entrada pedida \
                       cruzaria uma peça ou perfuraria a menos de {:.3} mm dela", dec(c)),
                *p,
            ));
        }
        if let Some((_, p)) = self.on_contour.first() {
            let list: Vec<String> = self
                .on_contour
                .iter()
                .take(12)
                .map(|(c, _)| (c + 1).to_string())
                .collect();
            let more = if self.on_contour.len() > 12 {
                ", …"
            } else {
                ""
            };
            let (n, list) = (self.on_contour.len(), list.join(", "));
            w.push(Warning::at(
                "no-room-for-lead",
                text!("{n} contour(s) have no room for a lead-in in the scrap around them and are \
                       pierced on their start point: contour(s) {list}{more}";
                      "{n} contorno(s) sem espaço para a entrada na sucata em volta; a perfuração \
                       é feita no ponto inicial: contorno(s) {list}{more}"),
                *p,
            ));
        }
        w
    }
}

/// The loop started at the point of it nearest `at` (a segment is split
/// there unless `at` is nearest one of its ends).
pub fn split_loop_at(segs: &[Segment], at: Point) -> Vec<Segment> {
    let mut best = (f64::INFINITY, 0usize, 0.0f64);
    for (i, s) in segs.iter().enumerate() {
        let t = nearest_param(s, at);
        let d = s.point_at(t).dist(at);
        if d < best.0 {
            best = (d, i, t);
        }
    }
    let (_, i, t) = best;
    let mut out = segs.to_vec();
    if t <= 1e-9 || t >= 1.0 - 1e-9 || segs.is_empty() {
        let v = if t >= 1.0 - 1e-9 { i + 1 } else { i };
        out.rotate_left(v % segs.len().max(1));
        return out;
    }
    let s = segs[i];
    let head = lead::prefix(&s, t);
    let tail = lead::prefix(&s.reversed(), 1.0 - t).reversed();
    out[i] = head;
    out.insert(i + 1, tail);
    out.rotate_left(i + 1);
    out
}

#[cfg(test)]
#[path = "cuts_tests.rs"]
mod tests;
