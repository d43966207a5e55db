//! The cut plan as an SVG drawing (issue 41 §5): what the program cuts,
//! drawn over the drawing, at true size in mm (`kerfcam FILE -o OUT.svg`,
//! the page's Save SVG).
//!
//! One Inkscape layer per sheet (a drawing is one sheet; a nest's sheets
//! lie side by side, bottoms aligned), holding the rapids (the program's,
//! as Play walks them: a router's up-and-across between depth passes
//! too), then one layer per part and copy, labelled with the part's name,
//! holding sublayers: `drawing` (the contours as drawn), `kerf path` (the kerf-compensated
//! tool path: contour and repeated edges), `leads` (lead-ins, lead-outs,
//! links), `tabs` (crossed with the tool off), `marks` (marked on the line,
//! spots) and `pierces` (a dot and the pierce's number in cutting order).
//! What belongs to no part (open contours, a sheet's crop line) is in a
//! last layer, "not in a part". A router's milling (issue 43), cut
//! before the profiles, is a layer of its own, "milling": the toolpath the
//! router post writes, the pockets' and drilled shapes as drawn
//! ("drawing"), a sublayer per depth ("Z -2", `data-z`), ramps and
//! helices in "entries", plunges as dots in "plunges"; its rapids are the
//! sheet's first. Arcs are SVG arcs; numbers have 6 decimals
//! (a nanometre), so the file reads back ([`super::parse`]) into the plan's
//! geometry.

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::fmt::Write;

use super::write::{chain_data, escape, header, Num, PageMap};
use crate::geom::{BBox, Point, Segment};
use crate::mill::{MillMove, Toolpath};
use crate::plan::Role;
use crate::scene::Scene;

/// Margin around what is drawn on each sheet, mm.
pub const MARGIN_MM: f64 = 5.0;
/// Gap between sheets, mm.
const SHEET_GAP_MM: f64 = 20.0;
/// Decimals written: 1 nm, far below any cutting tolerance.
const DECIMALS: i32 = 6;
/// The radius of a pierce's dot, mm.
const PIERCE_DOT_MM: f64 = 1.0;

/// One sheet of the plan: its label and the job cut on it.
#[derive(Clone, Copy, Debug)]
pub struct SheetPlan<'a> {
    /// The sheet layer's label (data from the user: escaped when written).
    pub label: &'a str,
    /// The contours and the plan.
    pub scene: Scene<'a>,
    /// Part names, by part number − 1 (a nest's parts, labelled "name
    /// #copy"); a part without a name is "part N".
    pub names: &'a [String],
    /// The program's rapids in X and Y, in order: what
    /// [`crate::animation::rapids`] gives for the job's process and post
    /// (Play's walk: a router's milling first, its lifts between depth
    /// passes included). Given, not made here: the plan SVG knows no post.
    pub rapids: &'a [Segment],
}

/// The sublayers of a part, in drawing order (the tool path over the
/// drawing): label, stroke colour, stroke width mm.
const LAYERS: [(&str, &str, f64); 6] = [
    ("drawing", "#7a7a7a", 0.2),
    ("kerf path", "#d62828", 0.3),
    ("leads", "#1a9e3a", 0.3),
    ("tabs", "#f08c00", 0.3),
    ("marks", "#7048e8", 0.3),
    ("pierces", "none", 0.0),
];
const DRAWING: usize = 0;
const KERF: usize = 1;
const LEADS: usize = 2;
const TABS: usize = 3;
const MARKS: usize = 4;
const PIERCES: usize = 5;

/// Who a path belongs to: a part and copy (a [`crate::source::ContourRef`]'s
/// `part` and `copy`), or none.
type Owner = Option<(u32, u32)>;

/// What one owner holds: chains of segments per sublayer, and dots (the
/// pierces with their numbers, the spots).
#[derive(Default)]
struct Group<'a> {
    chains: [Vec<(Cow<'a, [Segment]>, bool)>; 6],
    pierces: Vec<(Point, usize)>,
    spots: Vec<Point>,
}

impl Group<'_> {
    /// Adds `s` to sublayer `layer`, continuing the last chain when it
    /// ends where `s` starts.
    fn push(&mut self, layer: usize, s: Segment) {
        match self.chains[layer].last_mut() {
            Some((chain, false)) if chain.last().is_some_and(|l| l.b == s.a) => {
                chain.to_mut().push(s)
            }
            _ => self.chains[layer].push((Cow::Owned(vec![s]), false)),
        }
    }
}

/// The page area of a sheet: everything drawn and the tool's start, with
/// the margin, to whole mm.
fn frame(scene: &Scene) -> BBox {
    let mut bb = crate::preview::extent(scene);
    bb.add(scene.plan.origin);
    if let Some(m) = scene.milling {
        bb.add(m.toolpath.start);
    }
    for c in &scene.plan.cuts {
        bb.add(c.pierce);
    }
    if bb.is_empty() || !bb.min.is_finite() || !bb.max.is_finite() {
        bb = BBox::at(Point::new(0.0, 0.0));
    }
    BBox {
        min: Point::new(
            (bb.min.x - MARGIN_MM).floor(),
            (bb.min.y - MARGIN_MM).floor(),
        ),
        max: Point::new((bb.max.x + MARGIN_MM).ceil(), (bb.max.y + MARGIN_MM).ceil()),
    }
}

/// The plan of every sheet as one SVG document.
pub fn to_svg(sheets: &[SheetPlan<'_>]) -> String {
    let frames: Vec<BBox> = sheets.iter().map(|s| frame(&s.scene)).collect();
    let h = frames.iter().map(|f| f.max.y - f.min.y).fold(1.0, f64::max);
    let mut x = 0.0;
    let mut offsets = Vec::with_capacity(frames.len());
    for f in &frames {
        offsets.push(x);
        x += f.max.x - f.min.x + SHEET_GAP_MM;
    }
    let w = (x - SHEET_GAP_MM).max(1.0);
    let mut out = header(w, h, "kerfcam cut plan", Some(DECIMALS));
    for (k, (s, f)) in sheets.iter().zip(&frames).enumerate() {
        let map = PageMap {
            dx: offsets[k] - f.min.x,
            top: f.min.y + h,
            decimals: Some(DECIMALS),
        };
        sheet(&mut out, k + 1, s, &map);
    }
    out.push_str("</svg>\n");
    out
}

/// The owner of contour `i`.
fn owner_of(scene: &Scene, i: usize) -> Owner {
    let r = scene.contours.contours.get(i)?.source;
    (r.part > 0).then_some((r.part, r.copy))
}

/// Sheet `n`'s layer.
fn sheet(out: &mut String, n: usize, s: &SheetPlan<'_>, map: &PageMap) {
    let scene = &s.scene;
    let mut groups: BTreeMap<Owner, Group> = BTreeMap::new();
    for (i, c) in scene.contours.contours.iter().enumerate() {
        groups.entry(owner_of(scene, i)).or_default().chains[DRAWING]
            .push((Cow::Borrowed(&c.segments), c.is_closed()));
    }
    let rapids = s.rapids;
    for (number, c) in scene.plan.cuts.iter().enumerate() {
        let first = c.contours.first().and_then(|&i| owner_of(scene, i));
        let group = groups.entry(first).or_default();
        if c.spot {
            group.spots.push(c.pierce);
            continue;
        }
        if !c.is_mark() {
            group.pierces.push((c.pierce, number + 1));
        }
        for step in &c.steps {
            let layer = match step.role {
                Role::Contour | Role::Repeat => KERF,
                Role::LeadIn | Role::LeadOut | Role::Link => LEADS,
                Role::Tab => TABS,
                Role::Mark => MARKS,
            };
            let owner = step.contour.map_or(first, |i| owner_of(scene, i));
            groups.entry(owner).or_default().push(layer, step.segment);
        }
    }
    let milled = scene.milling.map(|m| Milling::of(m.toolpath, m.drawn));
    let label = escape(s.label);
    let _ = writeln!(
        out,
        "<g id=\"sheet-{n}\" inkscape:groupmode=\"layer\" inkscape:label=\"{label}\">"
    );
    if !rapids.is_empty() {
        let mut d = String::new();
        for r in rapids {
            chain_data(&mut d, std::slice::from_ref(r), map, false);
        }
        let _ = writeln!(
            out,
            "<g inkscape:groupmode=\"layer\" inkscape:label=\"rapids\" fill=\"none\" stroke=\"#0078a0\" \
             stroke-width=\"0.2\" stroke-dasharray=\"2 2\">\n<path d=\"{d}\"/>\n</g>"
        );
    }
    if let Some(m) = &milled {
        m.write(out, map);
    }
    for (owner, g) in &groups {
        match owner {
            Some((part, copy)) => {
                let name = match s.names.get(*part as usize - 1) {
                    Some(name) => format!("{} #{}", escape(name), copy + 1),
                    None => format!("part {part}"),
                };
                let _ = writeln!(
                    out,
                    "<g class=\"part\" inkscape:groupmode=\"layer\" inkscape:label=\"{name}\" \
                     data-part=\"{part}\" data-copy=\"{}\">",
                    copy + 1
                );
            }
            None => {
                out.push_str("<g inkscape:groupmode=\"layer\" inkscape:label=\"not in a part\">\n")
            }
        }
        group(out, g, map);
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n");
}

/// A part's sublayers, the empty ones left out.
fn group(out: &mut String, g: &Group, map: &PageMap) {
    for (k, (label, colour, width)) in LAYERS.iter().enumerate() {
        let dots = match k {
            PIERCES => !g.pierces.is_empty(),
            MARKS => !g.spots.is_empty(),
            _ => false,
        };
        if g.chains[k].is_empty() && !dots {
            continue;
        }
        let _ = writeln!(
            out,
            "<g inkscape:groupmode=\"layer\" inkscape:label=\"{label}\" fill=\"none\" \
             stroke=\"{colour}\" stroke-width=\"{width}\">"
        );
        // One path per closed contour (a part's holes stay loops of their
        // own), the open chains of a sublayer together.
        let mut open = String::new();
        for (chain, closed) in &g.chains[k] {
            if *closed {
                let mut d = String::new();
                chain_data(&mut d, chain, map, true);
                let _ = writeln!(out, "<path d=\"{d}\"/>");
            } else {
                chain_data(&mut open, chain, map, false);
            }
        }
        if !open.is_empty() {
            let _ = writeln!(out, "<path d=\"{open}\"/>");
        }
        let r = Num(PIERCE_DOT_MM, None);
        if k == MARKS {
            for &p in &g.spots {
                let (x, y) = map.at(p);
                let _ = writeln!(
                    out,
                    "<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" fill=\"#7048e8\" stroke=\"none\"/>"
                );
            }
        }
        if k == PIERCES {
            for &(p, number) in &g.pierces {
                let (x, y) = map.at(p);
                let (tx, ty) = map.at(Point::new(p.x + 1.5, p.y + 1.5));
                let _ = writeln!(
                    out,
                    "<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" fill=\"#1a9e3a\"/>\
                     <text x=\"{tx}\" y=\"{ty}\" font-size=\"4\" fill=\"#1a9e3a\">{number}</text>"
                );
            }
        }
        out.push_str("</g>\n");
    }
}

/// A router's milling toolpath (issue 43) as drawn: the very moves
/// `gcode::emit_router` writes, in X and Y.
struct Milling<'a> {
    /// The pockets' and drilled shapes' outlines as drawn.
    drawn: &'a [Vec<Segment>],
    /// Cuts at one height, chained, per height (deepest last).
    depths: Vec<(f64, Vec<Vec<Segment>>)>,
    /// Cuts along which Z changes (ramps, helices).
    entries: Vec<Vec<Segment>>,
    /// Where the tool went straight down into the material.
    plunges: Vec<Point>,
}

/// Heights closer than this are one depth, mm.
const SAME_Z: f64 = 1e-6;

/// Adds `s` to `chains`, continuing the last when it ends where `s` starts.
fn chain_on(chains: &mut Vec<Vec<Segment>>, s: Segment) {
    match chains.last_mut() {
        Some(c) if c.last().is_some_and(|l| l.b == s.a) => c.push(s),
        _ => chains.push(vec![s]),
    }
}

impl<'a> Milling<'a> {
    fn of(t: &Toolpath, drawn: &'a [Vec<Segment>]) -> Milling<'a> {
        let mut m = Milling {
            drawn,
            depths: Vec::new(),
            entries: Vec::new(),
            plunges: Vec::new(),
        };
        let (mut at, mut z) = (t.start, f64::INFINITY);
        for mv in &t.moves {
            match mv {
                MillMove::ToolChange(_) => {}
                MillMove::Rapid(p) => at = *p,
                MillMove::RapidZ(h) => z = *h,
                MillMove::Plunge(h) => {
                    if *h < 0.0 && m.plunges.last() != Some(&at) {
                        m.plunges.push(at);
                    }
                    z = *h;
                }
                MillMove::Cut { seg, z: h } => {
                    if (h - z).abs() > SAME_Z {
                        chain_on(&mut m.entries, *seg);
                    } else {
                        let k = match m.depths.iter().position(|(d, _)| (d - h).abs() <= SAME_Z) {
                            Some(k) => k,
                            None => {
                                m.depths.push((*h, Vec::new()));
                                m.depths.len() - 1
                            }
                        };
                        chain_on(&mut m.depths[k].1, *seg);
                    }
                    at = seg.b;
                    z = *h;
                }
                MillMove::Note(_) => {}
            }
        }
        m.depths.sort_by(|a, b| b.0.total_cmp(&a.0));
        m
    }

    /// The "milling" layer: the shapes as drawn ("drawing"), a sublayer
    /// per depth ("Z -2"), coloured as the preview colours them, then
    /// "entries" and "plunges".
    fn write(&self, out: &mut String, map: &PageMap) {
        out.push_str("<g inkscape:groupmode=\"layer\" inkscape:label=\"milling\">\n");
        if !self.drawn.is_empty() {
            let (_, colour, width) = LAYERS[DRAWING];
            let _ = writeln!(
                out,
                "<g inkscape:groupmode=\"layer\" inkscape:label=\"drawing\" fill=\"none\" \
                 stroke=\"{colour}\" stroke-width=\"{width}\">"
            );
            for segs in self.drawn {
                let mut d = String::new();
                chain_data(&mut d, segs, map, true);
                let _ = writeln!(out, "<path d=\"{d}\"/>");
            }
            out.push_str("</g>\n");
        }
        let n = self.depths.len();
        let path = |out: &mut String, chains: &[Vec<Segment>]| {
            let mut d = String::new();
            for c in chains {
                chain_data(&mut d, c, map, false);
            }
            let _ = writeln!(out, "<path d=\"{d}\"/>");
        };
        for (i, (z, chains)) in self.depths.iter().enumerate() {
            let colour = crate::preview::milling::depth_colour(i, n);
            let _ = writeln!(
                out,
                "<g inkscape:groupmode=\"layer\" inkscape:label=\"Z {}\" data-z=\"{}\" fill=\"none\" \
                 stroke=\"#{colour:06x}\" stroke-width=\"0.3\">",
                Num(*z, Some(3)),
                Num(*z, Some(DECIMALS)),
            );
            path(out, chains);
            out.push_str("</g>\n");
        }
        if !self.entries.is_empty() {
            out.push_str(
                "<g inkscape:groupmode=\"layer\" inkscape:label=\"entries\" fill=\"none\" \
                 stroke=\"#1a9e3a\" stroke-width=\"0.3\">\n",
            );
            path(out, &self.entries);
            out.push_str("</g>\n");
        }
        if !self.plunges.is_empty() {
            out.push_str("<g inkscape:groupmode=\"layer\" inkscape:label=\"plunges\">\n");
            let r = Num(PIERCE_DOT_MM / 2.0, None);
            for &p in &self.plunges {
                let (x, y) = map.at(p);
                let _ = writeln!(
                    out,
                    "<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" fill=\"#1a9e3a\" stroke=\"none\"/>"
                );
            }
            out.push_str("</g>\n");
        }
        out.push_str("</g>\n");
    }
}
