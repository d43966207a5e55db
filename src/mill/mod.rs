//! Stage 4′ for a router (issue 43; paper 004 §2.6–2.8, §5.1 items 5–9):
//! the pockets, engravings and holes of the layers given a milling
//! operation ([`crate::process::layers::MillGeometry`]) → a [`Toolpath`]
//! in X, Y and Z for the job's [`Tool`].
//!
//! # Output contract
//! - A pocket is the region inside a closed contour of a pocket layer,
//!   less the closed contours directly inside it (islands); a contour
//!   inside an island is a pocket again (the counter of an `O`).
//! - The tool's centre never leaves the region inset by the tool's radius
//!   (cavalier_contours' shape offset): no move gouges a wall or an
//!   island. What the tool cannot reach (corners sharper than its radius,
//!   necks narrower than its diameter) is left and reported, in mm², with
//!   where; a pocket the tool does not fit at all is reported and not cut.
//! - Depth in n = ceil(H / d_max) passes of H / n ([`Passes`], paper 004
//!   §2.6); each depth of a pocket is cleared — roughing, then the
//!   finishing pass at the tool's radius — before the next.
//! - Zig-zag ([`zigzag`]) or contour-parallel ([`offset`], from the centre
//!   out or from the walls in) roughing at the tool radius plus the
//!   allowance; the finishing pass climb (walls on
//!   the tool's right, with a clockwise spindle) or conventional.
//! - The tool stays down between passes where the straight link stays in
//!   the tool-centre region; elsewhere it lifts to the retract height and
//!   enters again as [`Tool::entry`] says (counted: [`Toolpath::lifts`]).
//! - Engraving follows the drawn line at each depth; drilling pecks at
//!   points and at the centres of circles up to [`Tool::drill_max`].

mod entry;
mod fit;
pub mod offset;
pub mod region;
pub mod sweep;
pub mod toolpath;
pub mod tools;
pub mod zigzag;

pub use fit::fit_arcs;
pub use toolpath::{MillMove, MillStats, Toolpath};
pub use tools::{plan_tools, DepthShare, Finish, ToolShare, Work};

use crate::contour::Contour;
use crate::geom::{Point, Segment};
use crate::process::layers::{Mark, MillGeometry};
use crate::process::{Passes, PocketStrategy, Tool};
use crate::text;
use crate::warning::{dec, Warning};
use region::{Pocket, Region};
use toolpath::Builder;

/// What a pocket came to.
#[derive(Clone, Debug, PartialEq)]
pub struct PocketReport {
    /// Where it is: its outline's lowest-leftmost box corner, mm.
    pub at: Point,
    /// Area as drawn (outline less islands), mm².
    pub area: f64,
    /// Area a disc of the tool's radius can sweep, mm².
    pub reachable: f64,
    /// Times the tool lifted inside it, all depths.
    pub lifts: usize,
    /// Of them, between zig-zag chains (an island in the way).
    pub zigzag_lifts: usize,
}

/// The milling of a job.
#[derive(Clone, Debug, Default)]
pub struct Milled {
    /// The moves.
    pub toolpath: Toolpath,
    /// The toolpath's lengths, from where the tool starts at the retract
    /// height (what the report and the time estimate add to the plan's).
    pub stats: MillStats,
    /// One per pocket cut.
    pub pockets: Vec<PocketReport>,
    /// Holes drilled.
    pub holes: usize,
    /// The closed shapes of the pocket and drill layers as drawn (what the
    /// preview draws the cleared area against).
    pub drawn: Vec<Vec<Segment>>,
    /// What could not be done as asked, and where.
    pub warnings: Vec<Warning>,
    /// Cutting moves before and after arc fitting, when the job fitted
    /// them ([`Milled::fit_arcs`]).
    pub arc_fit: Option<crate::plan::ArcFit>,
    /// The engravings' V-bit cut, when a V-bit engraved.
    pub engraving: Option<Engraving>,
    /// Each pocket machined, as drawn, and where its moves are.
    pub spans: Vec<sweep::PocketSpan>,
    /// The tool swept along the pockets' moves, when the job is verified
    /// ([`Milled::verify`]).
    pub swept: Option<sweep::Swept>,
    /// With several tools ([`plan_tools`]): what each machined, in the
    /// order they work; empty for the job's one tool.
    pub tools: Vec<ToolShare>,
    /// With layers at their own depth: each depth's layers, in the order
    /// they are machined; empty when every layer is at the job's depth.
    pub depths: Vec<DepthShare>,
}

/// An engraving with a V-bit: the depth and the width at the stock's top
/// (width = 2·depth·tan(angle/2); the one given, the other following).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Engraving {
    /// The V's included angle, degrees.
    pub v_angle_deg: f64,
    /// Depth, mm.
    pub depth: f64,
    /// Width at the top, mm: the cone's, at most the tool's diameter.
    pub width: f64,
}

impl Milled {
    /// The toolpath's flat runs arc-fitted within `tol` mm ([`fit_arcs`]),
    /// its lengths counted again from the `retract` height it starts at.
    pub fn fit_arcs(&mut self, tol: f64, retract: f64) {
        self.arc_fit = Some(fit_arcs(&mut self.toolpath, tol));
        self.stats = self.toolpath.stats(self.toolpath.start, retract);
    }
}

impl Milled {
    /// Sweeps the tool's disc (radius `r`) along the pockets' moves as they
    /// are now (fitted or not), `depth` deep, from the `retract` height
    /// ([`sweep`]); a gouge or material left is said, with where.
    pub fn verify(&mut self, r: f64, depth: f64, retract: f64, tol: f64) {
        let s = sweep::sweep(&self.toolpath, &self.spans, r, depth, retract, tol);
        if let (true, Some(p)) = (s.gouge_mm2 > 0.0, s.gouge_at) {
            let (a, x, y) = (um(s.gouge_mm2), um(p.x), um(p.y));
            let (ad, xd, yd) = (dec(a), dec(x), dec(y));
            self.warnings.push(Warning::at(
                "mill-gouge",
                text!("the tool swept along the pockets' moves takes {a} mm² of what the drawing keeps (walls, islands) beyond the tolerance, the largest patch at ({x}, {y}): the program would gouge there";
                      "a ferramenta varrida ao longo dos movimentos dos bolsões tira {ad} mm² do que o desenho mantém (paredes, ilhas) além da tolerância, a maior área em ({xd}, {yd}): o programa invadiria ali"),
                p,
            ));
        }
        if let (true, Some(p)) = (s.left_mm2 > 0.0, s.left_at) {
            let (a, x, y) = (um(s.left_mm2), um(p.x), um(p.y));
            let (ad, xd, yd) = (dec(a), dec(x), dec(y));
            self.warnings.push(Warning::at(
                "mill-left",
                text!("{a} mm² inside the pockets that the tool can reach is not cleared at the full depth, the largest patch at ({x}, {y})";
                      "{ad} mm² dentro dos bolsões ao alcance da ferramenta não são limpos na profundidade total, a maior área em ({xd}, {yd})"),
                p,
            ));
        }
        self.swept = Some(s);
    }
}

/// `v` to the micron, for a message.
fn um(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}

/// How many notes `t` holds: a section's place, kept by arc fitting.
fn notes(t: &Toolpath) -> usize {
    (t.moves.iter())
        .filter(|m| matches!(m, MillMove::Note(_)))
        .count()
}

/// Heights and tolerance of the milling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Heights {
    /// Height of moves between places, above the stock's top (Z 0), mm.
    pub retract: f64,
    /// The one tolerance, mm.
    pub tolerance: f64,
}

/// A region to clear: its outline and islands (indices into the pocket contours).
struct Outline {
    outline: usize,
    islands: Vec<usize>,
}

/// Pockets of the pocket layers' contours: even-depth closed contours,
/// each with the closed contours right inside it.
fn outlines(contours: &[Contour], warnings: &mut Vec<Warning>) -> Vec<Outline> {
    let mut out: Vec<Outline> = Vec::new();
    for (i, c) in contours.iter().enumerate() {
        if !c.is_closed() {
            let layer = &c.layer;
            warnings.push(Warning::at(
                "pocket-open",
                text!("an open line on pocket layer '{layer}' encloses nothing to clear: not machined (close it, or give the layer engrave)";
                      "uma linha aberta na camada de bolsão '{layer}' não fecha região a limpar: não usinada (feche-a ou dê à camada gravar)"),
                c.start(),
            ));
            continue;
        }
        if c.depth % 2 == 0 {
            out.push(Outline {
                outline: i,
                islands: Vec::new(),
            });
        }
    }
    for (i, c) in contours.iter().enumerate() {
        if !c.is_closed() || c.depth % 2 == 0 {
            continue;
        }
        if let Some(o) = out.iter_mut().find(|o| Some(o.outline) == c.parent) {
            o.islands.push(i);
        }
    }
    out
}

/// Per pocket contour: whether it crosses another closed one (an island
/// drawn through its pocket's outline, two outlines overlapping). Which
/// region is meant cannot be told — the contour stage reads the crossing
/// island as a pocket of its own, and clearing it would cut away what was
/// to stand — so the pockets they belong to are not machined, and said.
fn crossed(contours: &[Contour], eps: f64, warnings: &mut Vec<Warning>) -> Vec<bool> {
    let mut out = vec![false; contours.len()];
    let mut by_x: Vec<usize> = (0..contours.len())
        .filter(|&i| contours[i].is_closed())
        .collect();
    crate::sort::sort_by(&mut by_x, |&i, &j| {
        contours[i].bbox.min.x.total_cmp(&contours[j].bbox.min.x)
    });
    let mut first: Option<(Point, &str)> = None;
    let mut pairs = 0usize;
    for (k, &i) in by_x.iter().enumerate() {
        let bi = &contours[i].bbox;
        for &j in &by_x[k + 1..] {
            let bj = &contours[j].bbox;
            if bj.min.x > bi.max.x + eps {
                break;
            }
            if bj.min.y > bi.max.y + eps || bi.min.y > bj.max.y + eps {
                continue;
            }
            let Some(at) = region::crossing(&contours[i].segments, &contours[j].segments, eps)
            else {
                continue;
            };
            out[i] = true;
            out[j] = true;
            pairs += 1;
            first.get_or_insert((at, &contours[i].layer));
        }
    }
    if let Some((at, layer)) = first {
        let (x, y) = (um(at.x), um(at.y));
        let (xd, yd) = (dec(x), dec(y));
        warnings.push(
            Warning::at(
            "pocket-contours-cross",
            text!("{pairs} pair(s) of closed contours on pocket layers cross each other (first at {x}, {y} on layer '{layer}'): an island must stand inside its pocket's outline, so the pockets they belong to are not machined (draw the island inside, or give it a layer of its own)";
                  "{pairs} par(es) de contornos fechados em camadas de bolsão se cruzam (o primeiro em {xd}, {yd} na camada '{layer}'): uma ilha deve ficar dentro do contorno do seu bolsão, então os bolsões a que pertencem não são usinados (desenhe a ilha dentro, ou dê a ela uma camada própria)"),
            at,
        )
        .with_loops((0..contours.len()).filter(|&i| out[i]).map(|i| contours[i].source)));
    }
    out
}

/// One piece of a depth's clearing, cut with the tool down.
enum Run {
    /// A zig-zag chain.
    Chain(Vec<Point>),
    /// A closed loop (an offset or the finishing pass).
    Loop(Vec<Segment>),
}

/// Plans the milling of `g` with `tool`, `passes` deep.
pub fn plan(g: &MillGeometry, tool: &Tool, passes: Passes, h: Heights, from: Point) -> Milled {
    let mut m = Milled::default();
    let mut b = Builder::new(from, h.retract);
    let eps = (10.0 * h.tolerance).max(1e-3);
    let chord = eps;
    let r = tool.radius();
    let n = passes.count();
    m.drawn = (g.pockets.iter().chain(&g.drill_loops))
        .filter(|c| c.is_closed())
        .map(|c| c.segments.clone())
        .collect();
    let crossed = crossed(&g.pockets, eps, &mut m.warnings);
    for o in outlines(&g.pockets, &mut m.warnings) {
        if crossed[o.outline] || o.islands.iter().any(|&i| crossed[i]) {
            continue;
        }
        let c = &g.pockets[o.outline];
        let islands: Vec<&[Segment]> = (o.islands.iter())
            .map(|&i| g.pockets[i].segments.as_slice())
            .collect();
        let pocket = Pocket::new(&c.segments, &islands, chord);
        let drawn = pocket.inset(0.0);
        let at = c.bbox.min;
        let finish = pocket.inset(r);
        if finish.is_empty() {
            let (d, layer) = (tool.diameter, &c.layer);
            m.warnings.push(Warning::at(
                "pocket-too-narrow",
                text!("a pocket on layer '{layer}' is narrower than the {d} mm tool everywhere: not machined (a smaller tool would fit)";
                      "um bolsão na camada '{layer}' é mais estreito que a ferramenta de {} mm em toda parte: não usinado (uma ferramenta menor caberia)", dec(d)),
                at,
            ));
            continue;
        }
        let reach = pocket.reachable(r);
        unreachable(&pocket, &drawn, &finish, r, tool, &c.layer, &mut m.warnings);
        let rough = if tool.allowance > 0.0 {
            pocket.inset(r + tool.allowance)
        } else {
            finish.clone()
        };
        let mut runs: Vec<Run> = Vec::new();
        match tool.pocket {
            PocketStrategy::ZigZag => {
                let chains = zigzag::chains(&rough, tool.stepover(), tool.angle_deg, eps);
                let end = chains.last().and_then(|c| c.last()).copied();
                runs.extend(chains.into_iter().map(Run::Chain));
                let loops = finish
                    .loops
                    .iter()
                    .map(|l| directed(&l.segments, tool.climb));
                let loops = nearest_next(loops.collect(), end.unwrap_or(at));
                runs.extend(loops.into_iter().map(Run::Loop));
            }
            PocketStrategy::Offset => {
                let mut levels = offset::levels(
                    &pocket,
                    r + tool.allowance,
                    tool.stepover(),
                    tool.offset_from,
                    100_000,
                );
                if tool.allowance > 0.0 {
                    levels.push(finish.loops.clone());
                }
                let mut end = at;
                for level in levels {
                    let loops = level
                        .iter()
                        .map(|l| directed(&l.segments, tool.climb))
                        .collect();
                    for l in nearest_next(loops, end) {
                        end = l.first().map_or(end, |s| s.a);
                        runs.push(Run::Loop(l));
                    }
                }
            }
        }
        let lifts_before = b.path.lifts;
        let mut zigzag_lifts = 0;
        let first_note = notes(&b.path);
        // Program comments: a decimal point whatever the language.
        b.note(format!("pocket at X{} Y{}", um(at.x), um(at.y)));
        let clear = 0.5_f64.min(h.retract);
        for k in 1..=n {
            let (z_prev, z) = (if k == 1 { 0.0 } else { passes.z(k - 1) }, passes.z(k));
            b.note(format!("depth {k} of {n}: Z{}", um(z)));
            let mut first = true;
            for run in &runs {
                let path = start_at(run, b.at, chord);
                let start = path.first().copied().unwrap_or(b.at);
                let down = b.z <= z_prev;
                if down && b.z == z && !first && finish.holds_line(b.at, start, eps) {
                    // Stay down: the link cuts only what this depth clears.
                    b.line_to(start);
                } else if first && down && finish.holds_line(b.at, start, eps) {
                    // The next depth from where the last ended, without lifting.
                    b.line_to(start);
                    let top = b.z;
                    enter_at(
                        &mut b,
                        run,
                        &path,
                        top,
                        z,
                        tool,
                        &finish,
                        eps,
                        &mut m.warnings,
                    );
                } else {
                    if !first {
                        b.path.lifts += 1;
                        zigzag_lifts += usize::from(matches!(run, Run::Chain(_)));
                    }
                    b.travel(start, z_prev + clear);
                    enter_at(
                        &mut b,
                        run,
                        &path,
                        z_prev + clear,
                        z,
                        tool,
                        &finish,
                        eps,
                        &mut m.warnings,
                    );
                }
                first = false;
                cut_run(&mut b, run, &path, z);
            }
        }
        b.up();
        m.spans.push(sweep::PocketSpan {
            loops: std::iter::once(&c.segments)
                .chain(o.islands.iter().map(|&i| &g.pockets[i].segments))
                .cloned()
                .collect(),
            first: first_note,
            end: notes(&b.path),
        });
        m.pockets.push(PocketReport {
            at,
            area: drawn.area(),
            reachable: reach.area(),
            lifts: b.path.lifts - lifts_before,
            zigzag_lifts,
        });
    }
    let engrave_passes = Passes {
        depth: tool.engrave_depth(passes.depth),
        ..passes
    };
    if let (Some(w), false) = (tool.v_width(engrave_passes.depth), g.engraves.is_empty()) {
        m.engraving = Some(v_engraving(tool, engrave_passes.depth, w, &mut m.warnings));
    }
    engrave(&mut b, &g.engraves, engrave_passes);
    drill(&mut b, &mut m, g, tool, passes);
    b.up();
    m.stats = b.path.stats(from, h.retract);
    m.toolpath = b.path;
    m
}

/// Enters at a run's start: a loop started in the cleared region by a
/// plunge when its entry cannot be had, the rest as the tool says.
#[allow(clippy::too_many_arguments)]
fn enter_at(
    b: &mut Builder,
    _run: &Run,
    path: &[Point],
    top: f64,
    z: f64,
    tool: &Tool,
    region: &Region,
    eps: f64,
    warnings: &mut Vec<Warning>,
) {
    if let Some(entry::Missed::NoHelixRoom(p)) = entry::enter(b, path, top, z, tool, region, eps) {
        let d = tool.helix();
        warnings.push(Warning::at(
            "helix-no-room",
            text!("no room for a {d} mm helix here: the tool plunged instead (a smaller --helix-diameter or --entry ramp would ramp)";
                  "sem espaço para uma hélice de {} mm aqui: a ferramenta desceu reto (um --helix-diameter menor ou --entry ramp entraria em rampa)", dec(d)),
            p,
        ));
    }
}

/// The run's path from its start nearest `at` (a loop turned to start at
/// its vertex nearest), as points: arcs within `chord` (a ramp walks
/// them; a coarser chord would cut into a convex island).
fn start_at(run: &Run, at: Point, chord: f64) -> Vec<Point> {
    match run {
        Run::Chain(pts) => pts.clone(),
        Run::Loop(segs) => {
            let k = nearest_vertex(segs, at);
            let mut pts: Vec<Point> = Vec::new();
            crate::geom::path_points(segs[k..].iter().chain(&segs[..k]), chord, &mut pts);
            pts.push(segs[k].a);
            pts
        }
    }
}

/// Loops in nearest-next order from `from`, each turned to start at its
/// vertex nearest the end of the one before (a closed loop ends where it
/// starts).
fn nearest_next(mut loops: Vec<Vec<Segment>>, from: Point) -> Vec<Vec<Segment>> {
    let mut out = Vec::with_capacity(loops.len());
    let mut at = from;
    while !loops.is_empty() {
        let d = |l: &Vec<Segment>| l.iter().map(|s| s.a.dist(at)).fold(f64::INFINITY, f64::min);
        let i = (0..loops.len())
            .min_by(|&i, &j| d(&loops[i]).total_cmp(&d(&loops[j])))
            .unwrap_or(0);
        let mut l = loops.swap_remove(i);
        let k = nearest_vertex(&l, at);
        l.rotate_left(k);
        at = l.first().map_or(at, |s| s.a);
        out.push(l);
    }
    out
}

fn nearest_vertex(segs: &[Segment], at: Point) -> usize {
    (0..segs.len())
        .min_by(|&i, &j| segs[i].a.dist(at).total_cmp(&segs[j].a.dist(at)))
        .unwrap_or(0)
}

fn cut_run(b: &mut Builder, run: &Run, path: &[Point], z: f64) {
    match run {
        Run::Chain(_) => {
            for p in &path[1..] {
                b.line_to(*p);
            }
        }
        Run::Loop(segs) => {
            let k = nearest_vertex(segs, b.at);
            for i in 0..segs.len() {
                b.cut(segs[(k + i) % segs.len()], z);
            }
        }
    }
}

/// `segs` in the milling direction: as cavalier_contours gives them
/// (outlines counter-clockwise, islands clockwise: the wall on the tool's
/// right, climb with a clockwise spindle), or reversed.
fn directed(segs: &[Segment], climb: bool) -> Vec<Segment> {
    if climb {
        segs.to_vec()
    } else {
        segs.iter().rev().map(Segment::reversed).collect()
    }
}

/// Says where the tool cannot reach: points of the walls farther than a
/// diameter from the tool-centre region (a neck, a sharp inside corner),
/// with the area left.
fn unreachable(
    pocket: &Pocket,
    drawn: &Region,
    finish: &Region,
    r: f64,
    tool: &Tool,
    layer: &str,
    warnings: &mut Vec<Warning>,
) {
    let mut far: Option<(Point, f64)> = None;
    for l in &drawn.loops {
        for s in &l.segments {
            let n = (s.length() / r.max(0.1)).ceil().clamp(1.0, 10_000.0) as usize;
            for k in 0..n {
                let p = s.point_at(k as f64 / n as f64);
                let d = finish.wall_dist(p) - r;
                if d > r && far.is_none_or(|(_, fd)| d > fd) {
                    far = Some((p, d));
                }
            }
        }
    }
    if let Some((p, _)) = far {
        let left = (drawn.area() - pocket.reachable(r).area()).max(0.0);
        let d = tool.diameter;
        warnings.push(Warning::at(
            "pocket-unreachable",
            text!("a pocket on layer '{layer}' has corners or necks the {d} mm tool cannot enter: {} mm² left standing (the worst here; never gouged)", dec(left);
                  "um bolsão na camada '{layer}' tem cantos ou gargalos onde a ferramenta de {} mm não entra: {} mm² deixados (o pior aqui; nunca invadidos)", dec(d), dec(left)),
            p,
        ));
    }
}

/// The V-bit's engraving, said as a note (and a warning where the cone is
/// wider than the tool: its shoulder cuts straight walls, the width is the
/// tool's).
fn v_engraving(tool: &Tool, depth: f64, cone: f64, warnings: &mut Vec<Warning>) -> Engraving {
    // English with a decimal point, Portuguese with a comma (`dec`).
    let (a, d) = (um(tool.v_angle_deg), um(depth));
    let width = cone.min(tool.diameter);
    let w = um(width);
    let (ad, dd, wd) = (dec(a), dec(d), dec(w));
    warnings.push(Warning::new(
        "engrave-v",
        text!("engraving with a {a}° V-bit: {d} mm deep, {w} mm wide at the top (width = 2 × depth × tan(angle/2))";
              "gravação com fresa em V de {ad}°: {dd} mm de profundidade, {wd} mm de largura no topo (largura = 2 × profundidade × tan(ângulo/2))"),
    ));
    if cone > tool.diameter * (1.0 + 1e-9) {
        let (c, big) = (um(cone), um(tool.diameter));
        let (cd, bigd) = (dec(c), dec(big));
        warnings.push(Warning::new(
            "engrave-v-too-deep",
            text!("the V-bit's cone would be {c} mm wide at {d} mm deep, more than the tool's {big} mm: the engraving is {big} mm wide with straight walls below the cone (a shallower depth or an --engrave-width keeps it a V)";
                  "o cone da fresa em V teria {cd} mm de largura a {dd} mm de profundidade, mais que os {bigd} mm da ferramenta: a gravação fica com {bigd} mm de largura e paredes retas abaixo do cone (uma profundidade menor ou --engrave-width a mantém em V)"),
        ));
    }
    Engraving {
        v_angle_deg: tool.v_angle_deg,
        depth,
        width,
    }
}

/// Engraving: each path on the line at every depth (open ones back and
/// forth, closed ones round again), from the nearer end.
fn engrave(b: &mut Builder, marks: &[Mark], passes: Passes) {
    let n = passes.count();
    for m in marks {
        let Some(first) = m.segments.first() else {
            continue;
        };
        b.note("engrave".into());
        b.travel(first.a, 0.0);
        let mut segs = m.segments.clone();
        for k in 1..=n {
            let z = passes.z(k);
            b.plunge(z);
            for s in &segs {
                b.cut(*s, z);
            }
            if !m.closed {
                segs = segs.iter().rev().map(Segment::reversed).collect();
            }
        }
        b.up();
    }
}

/// Drilling: points, and closed contours no wider than `tool.drill_max`
/// (the tool's diameter when 0) at their box's centre, in pecks.
fn drill(b: &mut Builder, m: &mut Milled, g: &MillGeometry, tool: &Tool, passes: Passes) {
    let max = if tool.drill_max > 0.0 {
        tool.drill_max
    } else {
        tool.diameter + 0.05
    };
    let mut at: Vec<Point> = g.drill_points.clone();
    for c in &g.drill_loops {
        let (w, hgt) = (c.bbox.max.x - c.bbox.min.x, c.bbox.max.y - c.bbox.min.y);
        let centre = Point::new(
            (c.bbox.min.x + c.bbox.max.x) / 2.0,
            (c.bbox.min.y + c.bbox.max.y) / 2.0,
        );
        let size = w.max(hgt);
        let layer = &c.layer;
        if !c.is_closed() || size > max {
            m.warnings.push(Warning::at(
                "drill-too-large",
                text!("a shape {} mm wide on drill layer '{layer}' is more than a drilled hole (up to {} mm): not drilled (give the layer pocket or profile)", um(size), um(max);
                      "uma forma de {} mm na camada de furação '{layer}' é mais que um furo (até {} mm): não furada (dê à camada bolsão ou perfil)", dec(um(size)), dec(um(max))),
                centre,
            ));
            continue;
        }
        if (size - tool.diameter).abs() > 0.05 {
            let d = tool.diameter;
            m.warnings.push(Warning::at(
                "drill-diameter",
                text!("a {} mm hole on layer '{layer}' is drilled with the {d} mm tool: the hole is {d} mm", um(size);
                      "um furo de {} mm na camada '{layer}' é furado com a ferramenta de {} mm: o furo fica com {} mm", dec(um(size)), dec(d), dec(d)),
                centre,
            ));
        }
        at.push(centre);
    }
    let peck = if tool.peck > 0.0 {
        tool.peck
    } else {
        passes.pass_depth.max(passes.depth)
    };
    // Nearest next from where the tool is.
    while !at.is_empty() {
        let here = b.at;
        let i = (0..at.len())
            .min_by(|&i, &j| at[i].dist(here).total_cmp(&at[j].dist(here)))
            .unwrap_or(0);
        let p = at.swap_remove(i);
        b.note("drill".into());
        b.travel(p, b.retract);
        let mut z = 0.0;
        while z > -passes.depth + 1e-9 {
            let next = (z - peck).max(-passes.depth);
            // Back down at rapid to just above the last peck's bottom.
            b.travel(p, z + 0.5_f64.min(b.retract));
            b.plunge(next);
            b.up();
            z = next;
        }
        m.holes += 1;
    }
}

#[cfg(test)]
#[path = "tests.rs"]
mod tests;
