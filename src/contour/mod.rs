//! Stage 2: [`Drawing`] → [`Contours`].
//!
//! # Output contract
//! - Entities are chained end to end within the tolerance ([`chain`]); every
//!   segment start equals the previous segment's end exactly, and a closed
//!   contour ends exactly where it starts.
//! - Closed contours are classified by containment depth: even depth = the
//!   outer boundary of a part, odd = a hole; an island in a hole is a new
//!   part (paper 000 assumes one part per file; real files hold many).
//! - Area is exact with arcs (circular segments, not triangles), signed by
//!   the drawn direction; geometry is kept in the drawn direction.
//! - Open contours are kept, classified `Open`, and reported; they are not cut.

mod box_grid;
mod chain;
mod cross;
mod depth;
mod heal;
mod names;

pub(crate) use depth::point_in_loop;
pub use heal::{HealKind, Healing};

use crate::par::Threads;
use std::sync::Arc;

use crate::dxf::Drawing;
use crate::geom::{BBox, Point, Segment, Tolerance};
pub use crate::source::ContourRef;
use crate::text;
use crate::warning::{dec, Text, Warning};

/// What a contour is in the part it belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContourKind {
    /// Closed, even depth: the outside of a part.
    Outer,
    /// Closed, odd depth: a hole in a part.
    Hole,
    /// Not closed: shown, not cut.
    Open,
}

impl ContourKind {
    /// Name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            ContourKind::Outer => "outer",
            ContourKind::Hole => "hole",
            ContourKind::Open => "open",
        }
    }
}

/// One chain of segments.
#[derive(Clone, Debug)]
pub struct Contour {
    /// Segments end to end, in the drawn direction.
    pub segments: Vec<Segment>,
    /// Outer, hole or open.
    pub kind: ContourKind,
    /// Number of closed contours that contain this one (0 for open ones).
    pub depth: usize,
    /// Index of the smallest closed contour containing this one.
    pub parent: Option<usize>,
    /// Part number (1-based) for closed contours: its own for an outer, its
    /// outer's for a hole.
    pub part: Option<usize>,
    /// Signed area in mm² (> 0 counter-clockwise); 0 for open contours.
    pub area: f64,
    /// Length in mm.
    pub length: f64,
    /// Exact bounding box.
    pub bbox: BBox,
    /// Layer of the first entity: one shared name per layer, not a copy
    /// per contour (a sheet's 137k contours made 137k strings; issue 17).
    pub layer: Arc<str>,
    /// Indices of the drawing's entities in this contour.
    pub entities: Vec<usize>,
    /// Its part, copy and loop: what stays true through layers, healing
    /// and nesting (issue 15 §1).
    pub source: ContourRef,
    /// For a part's outer outline drawn whole by one INSERT of a block (or
    /// one named SVG group) that drew no other part: its name, the part's name in the
    /// drawing ([`names`]). None otherwise.
    pub block: Option<Arc<str>>,
    /// For a part's outer outline: the named group that holds it whole —
    /// its DXF layer (not `0`), or the innermost named SVG group or
    /// Inkscape layer ([`names`]). It names the part when the file's parts
    /// are not all in one group.
    pub group: Option<Arc<str>>,
}

impl Contour {
    /// True for a closed contour.
    pub fn is_closed(&self) -> bool {
        self.kind != ContourKind::Open
    }
    /// Start point.
    pub fn start(&self) -> Point {
        self.segments.first().map_or(Point::default(), |s| s.a)
    }
    /// End point.
    pub fn end(&self) -> Point {
        self.segments.last().map_or(Point::default(), |s| s.b)
    }
}

/// Every contour of a drawing.
#[derive(Clone, Debug, Default)]
pub struct Contours {
    /// Closed and open contours.
    pub contours: Vec<Contour>,
    /// Number of parts (outer contours).
    pub parts: usize,
    /// What healing changed before chaining, and where.
    pub healing: Healing,
    /// What was changed or doubtful.
    pub warnings: Vec<Warning>,
    /// Parts made of the faces of lines meeting at branch points, and the
    /// edges they share.
    pub shared: SharedEdges,
}

/// Parts that share edges (issue 39 §6): where lines meet at branch
/// points, the closed faces they bound are the parts ([`chain`]), and a
/// line between two faces is an edge of both.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SharedEdges {
    /// Faces made parts.
    pub faces: usize,
    /// The contours (indices) of those that share an edge with another.
    pub contours: Vec<usize>,
    /// Length of the shared edges, each counted once, mm.
    pub length: f64,
    /// A point on the first shared edge.
    pub at: Option<Point>,
}

impl SharedEdges {
    /// True when some parts share an edge: one cut there takes from both.
    pub fn any(&self) -> bool {
        !self.contours.is_empty() && self.length > 0.0
    }

    /// What cutting a kerf `kerf` mm wide once along the shared edges
    /// takes from the parts, as a warning (None when no part shares one).
    pub fn warning(&self, kerf: f64) -> Option<Warning> {
        if !self.any() {
            return None;
        }
        let (n, len) = (self.contours.len(), self.length);
        let half = if kerf.is_finite() {
            kerf.max(0.0) / 2.0
        } else {
            0.0
        };
        let text = text!("{n} parts share edges (lines drawn once where three or more meet): each shared line is cut once, on the line, so each part loses half the kerf ({half:.3} mm) from its side along the shared edges, {len:.1} mm of them in all";
                         "{n} peças compartilham arestas (linhas desenhadas uma vez onde três ou mais se encontram): cada linha compartilhada é cortada uma vez, sobre a linha, e cada peça perde metade da sangria ({:.3} mm) do seu lado ao longo das arestas compartilhadas, {:.1} mm ao todo",
                         dec(half), dec(len));
        Some(match self.at {
            Some(p) => Warning::at("parts-share-edges", text, p),
            None => Warning::new("parts-share-edges", text),
        })
    }
}

/// Open contours listed one by one in the warnings; the rest are counted.
const MAX_OPEN_WARNINGS: usize = 50;

/// Writes each contour's depth, parent, kind, part and reference in one
/// pass in index order (a sheet's 137k contours are 23 MB, read again by
/// every pass: the classification's writes in area order, the part
/// numbers, the holes' parts and the references were four; issue 17), and
/// returns the number of parts and the open contours' indices.
///
/// Outers are numbered in index order; a hole takes its parent's part as
/// it stands when the hole's turn comes (none yet for a parent later in
/// the order that is itself a hole). The reference is the one the
/// contour's entities were stamped with (`stamped`: a nested sheet, every
/// loop one entity, put in `source` when the contour was made), else the
/// part number, the hole's rank within its part, or the open contour's rank.
fn number(
    contours: &mut [Contour],
    nest: &depth::Nesting,
    stamped: &[bool],
) -> (usize, Vec<usize>) {
    let n = contours.len();
    // Parts first, on a compact array (0 = none; parts count from 1).
    let mut part = vec![0u32; n];
    let mut parts = 0u32;
    for (i, p) in part.iter_mut().enumerate() {
        if nest.kind(i) == ContourKind::Outer {
            parts += 1;
            *p = parts;
        }
    }
    for i in 0..n {
        if nest.kind(i) == ContourKind::Hole {
            let up = nest.parent[i];
            part[i] = if up == depth::NONE {
                0
            } else {
                part[up as usize]
            };
        }
    }
    let mut holes: Vec<u32> = Vec::new();
    let mut open_count = 0u32;
    let mut open = Vec::new();
    for (i, c) in contours.iter_mut().enumerate() {
        let kind = nest.kind(i);
        if kind == ContourKind::Open {
            open.push(i);
        } else {
            c.kind = kind;
            c.depth = nest.depth[i] as usize;
            let up = nest.parent[i];
            c.parent = (up != depth::NONE).then_some(up as usize);
        }
        c.part = (part[i] != 0).then_some(part[i] as usize);
        if stamped[i] {
            continue;
        }
        let part = part[i];
        let contour = match kind {
            ContourKind::Outer => 0,
            ContourKind::Hole => {
                let k = part as usize;
                if holes.len() <= k {
                    holes.resize(k + 1, 0);
                }
                holes[k] += 1;
                holes[k]
            }
            ContourKind::Open => {
                open_count += 1;
                open_count - 1
            }
        };
        c.source = ContourRef {
            part: if kind == ContourKind::Open { 0 } else { part },
            copy: 0,
            contour,
        };
    }
    (parts as usize, open)
}

/// The loops and the other chains, each in order. The larger side stays
/// where it is and the other is moved out: the chains of a sheet (or a
/// million open segments) are 100k+ structs that every copy pages in again.
fn split_loops(
    mut chains: Vec<chain::Chain>,
    is_loop: impl Fn(&chain::Chain) -> bool,
) -> (Vec<chain::Chain>, Vec<chain::Chain>) {
    let loops = chains.iter().filter(|c| is_loop(c)).count();
    if 2 * loops >= chains.len() {
        let open = chains.extract_if(.., |c| !is_loop(c)).collect();
        (chains, open)
    } else {
        let loops = chains.extract_if(.., |c| is_loop(c)).collect();
        (loops, chains)
    }
}

/// Chains as open pieces, each whole.
fn whole(chains: Vec<chain::Chain>) -> chain::Pieces {
    let n: usize = chains.iter().map(|c| c.segments.len()).sum();
    let mut pieces = chain::Pieces::with_capacity(n);
    for c in chains {
        pieces.open_segments().extend_from_slice(&c.segments);
        pieces.close_open(&c.entities);
    }
    pieces
}

/// True when a chain's two ends are farther apart than `t` (so it cannot
/// close by itself, whatever its length).
fn ends_apart(c: &chain::Chain, t: f64) -> bool {
    match (c.segments.first(), c.segments.last()) {
        // `hypot` is at least either side's length: no call for ends
        // farther apart than `t` along an axis.
        (Some(first), Some(last)) => {
            let (a, b) = (first.a, last.b);
            (a.x - b.x).abs() > t || (a.y - b.y).abs() > t || a.dist(b) > t
        }
        _ => false,
    }
}

/// Chains and classifies a drawing's entities.
///
/// Ends within `tol` are the same point; open ends up to `gap` mm apart are
/// joined afterwards (a second chaining pass), each join reported.
pub fn extract(drawing: &Drawing, tol: Tolerance, gap: f64) -> Contours {
    extract_with(drawing, tol, gap, Threads::ONE)
}

/// [`extract`] on `threads` (the contours are the same with any).
pub fn extract_with(drawing: &Drawing, tol: Tolerance, gap: f64, threads: Threads) -> Contours {
    extract_repairing(drawing, tol, gap, threads, true)
}

/// [`extract_with`]; `repair` false leaves loops that cross themselves as
/// drawn (the kerf stage refuses them), true repairs them into the
/// outline of the region they enclose ([`cross`]).
pub fn extract_repairing(
    drawing: &Drawing,
    tol: Tolerance,
    gap: f64,
    threads: Threads,
    repair: bool,
) -> Contours {
    let mut warnings = Vec::new();
    let mut healing = Healing::default();
    // Chain what was drawn; heal what did not close; chain that again; then bridge small gaps.
    let mut marks = Vec::new();
    let pieces = heal::prepare(&drawing.entities, tol, threads, &mut healing, &mut marks);
    let mut gaps = Vec::new();
    let mut faces = chain::FaceLog::default();
    let first = chain::chain_faces(
        pieces,
        tol.mm(),
        &mut gaps,
        &mut warnings,
        threads,
        &mut faces,
    );
    // A loop with no area (a line drawn there and back) is not a part: heal it as open.
    let real_loop =
        |c: &chain::Chain| c.closed && c.measure.area.abs() > tol.mm() * c.measure.length;
    // Split in place (what stays is the closed loops, in order): the chains
    // of a sheet are 100k+ structs that every copy pages in again.
    let (mut closed, open) = split_loops(first, real_loop);
    heal::drop_duplicate_loops(&mut closed, tol, &mut healing);
    let healed = heal::heal_open(&open, &closed, tol, &mut healing);
    let mut chains = closed;
    // Chained again, the loops found join the others.
    let mut again = |pieces, chains: &mut Vec<chain::Chain>| {
        let again = chain::chain_faces(
            pieces,
            tol.mm(),
            &mut gaps,
            &mut warnings,
            threads,
            &mut faces,
        );
        let (loops, open) = split_loops(again, real_loop);
        chains.extend(loops);
        open
    };
    let open = match healed {
        Some(pieces) => {
            // The healed pieces hold what is left of them: freed now, their
            // chains' vectors are what the next chaining's reuse.
            drop(open);
            again(pieces, &mut chains)
        }
        // Nothing healed, and no chain's ends meet (within the tolerance)
        // its own: chaining them again gives them back as they are, since
        // the first chaining left no end within the tolerance of another
        // chain's end (each chain ended where no unused end was near, and
        // the later chains were made of pieces unused then). Skipped: it
        // was a third of the stage on a million isolated segments.
        None if open.iter().all(|c| !c.closed && ends_apart(c, tol.mm())) => open,
        None => again(whole(open), &mut chains),
    };
    if gap > tol.mm() {
        chains.extend(chain::chain_on(
            whole(open),
            gap,
            tol.mm(),
            &mut gaps,
            &mut warnings,
            threads,
        ));
    } else {
        chains.extend(open);
    }
    for p in gaps {
        healing.add(HealKind::Gap, p);
    }
    for p in std::mem::take(&mut faces.duplicates) {
        healing.add(HealKind::Duplicate, p);
    }
    if repair {
        chains = cross::repair_chains(chains, tol, threads, &mut healing, &mut warnings);
    }
    let mut stamped = Vec::with_capacity(chains.len());
    let names: Vec<Arc<str>> = drawing
        .layers
        .iter()
        .map(|l| l.name.as_str().into())
        .collect();
    let no_layer: Arc<str> = "".into();
    // The containment search's order (closed contours by area) is sorted
    // on a second thread while the contours are made from the chains: it
    // needs only each loop's area (~7 ms of a 137k-contour sheet).
    let areas: Vec<Option<f64>> = chains
        .iter()
        .map(|c| real_loop(c).then_some(c.measure.area))
        .collect();
    let mut sharing = Vec::new();
    let make = || {
        chains
            .into_iter()
            .enumerate()
            .map(|(i, c)| {
                if c.shares_edges {
                    sharing.push(i);
                }
                let length = c.measure.length;
                // The same rule as before healing: a loop must enclose an area to be a part.
                let is_loop = real_loop(&c);
                if c.closed && !is_loop {
                    warnings.push(Warning::at(
                        "closed-no-area",
                        text!("closed contour encloses no area: treated as open";
                          "contorno fechado sem área: tratado como aberto"),
                        c.segments[0].a,
                    ));
                }
                let (area, kind) = if is_loop {
                    (c.measure.area, ContourKind::Outer)
                } else {
                    (0.0, ContourKind::Open)
                };
                // The first entity's layer and stamp from the compact marks;
                // the entity itself is read only for a stamp (a nested sheet).
                let first = c.entities.first().and_then(|&i| Some((i, *marks.get(i)?)));
                let layer = first
                    .and_then(|(_, m)| names.get((m & !heal::STAMPED) as usize))
                    .unwrap_or(&no_layer)
                    .clone();
                let source = first
                    .filter(|(_, m)| m & heal::STAMPED != 0)
                    .and_then(|(i, _)| drawing.entities.get(i)?.source);
                stamped.push(source.is_some());
                Contour {
                    bbox: c.measure.bbox,
                    segments: c.segments,
                    kind,
                    depth: 0,
                    parent: None,
                    part: None,
                    area,
                    length,
                    layer,
                    entities: c.entities,
                    source: source.unwrap_or_default(),
                    block: None,
                    group: None,
                }
            })
            .collect::<Vec<Contour>>()
    };
    let (mut contours, by_area) = crate::par::join(threads, make, || depth::by_area(&areas));
    let nesting = depth::classify(&contours, by_area, tol, threads, &mut warnings);
    let (parts, open) = number(&mut contours, &nesting, &stamped);
    names::name_parts(&mut contours, drawing);
    let open: Vec<&Contour> = open.into_iter().map(|i| &contours[i]).collect();
    if open.len() > MAX_OPEN_WARNINGS {
        let n = open.len();
        warnings.push(Warning::new(
            "open-contours",
            text!("{n} open contours are not compensated and are cut only on request (cut open contours, or the drawing order); the first {MAX_OPEN_WARNINGS} are listed";
                  "{n} contornos abertos não são compensados e só são cortados se pedido (cortar contornos abertos, ou a ordem do desenho); os primeiros {MAX_OPEN_WARNINGS} estão listados"),
        ));
    }
    for c in open.into_iter().take(MAX_OPEN_WARNINGS) {
        let (a, b) = (c.start(), c.end());
        let (n, len, gap) = (c.segments.len(), c.length, a.dist(b));
        warnings.push(Warning::at(
            "open-contour",
            text!("open contour, cut only on request ({n} segment(s), {len:.3} mm long): its ends ({:.3}, {:.3}) and ({:.3}, {:.3}) are {gap:.4} mm apart",
                  a.x, a.y, b.x, b.y;
                  "contorno aberto, cortado só se pedido ({n} segmento(s), {:.3} mm de comprimento): suas pontas ({:.3}; {:.3}) e ({:.3}; {:.3}) estão a {:.4} mm",
                  dec(len), dec(a.x), dec(a.y), dec(b.x), dec(b.y), dec(gap)),
            a,
        ));
    }
    if healing != Healing::default() {
        let Healing {
            duplicates: d,
            overlaps: o,
            gaps_closed: g,
            zero_length: z,
            ..
        } = healing;
        // Only what was done: "63 zero-length piece(s) dropped", not three zeros first.
        let done: Vec<Text> = [
            (d, text!("{d} duplicate(s) dropped"; "{d} duplicata(s) removida(s)")),
            (o, text!("{o} overlap(s) merged"; "{o} sobreposição(ões) unida(s)")),
            (g, text!("{g} gap(s) closed"; "{g} abertura(s) fechada(s)")),
            (z, text!("{z} zero-length piece(s) dropped"; "{z} trecho(s) de comprimento zero removido(s)")),
        ]
        .into_iter()
        .filter(|(n, _)| *n > 0)
        .map(|(_, t)| t)
        .collect();
        if !done.is_empty() {
            let en: Vec<&str> = done.iter().map(|t| t.en.as_str()).collect();
            let pt: Vec<&str> = done.iter().map(|t| t.pt.as_str()).collect();
            warnings.push(Warning::new(
                "healed",
                text!("healed: {}", en.join(", "); "reparado: {}", pt.join(", ")),
            ));
        }
    }
    Contours {
        contours,
        parts,
        healing,
        warnings: crate::warning::group(warnings),
        shared: SharedEdges {
            faces: faces.faces,
            contours: sharing,
            length: faces.shared_length,
            at: faces.shared_at,
        },
    }
}
