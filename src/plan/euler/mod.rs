//! Order "eulerian" (paper 003, Vidal Filho, Moscato, Segenreich), made a
//! thermal cutter's common-line cutting (issue 14): one graph of every cut
//! path, paths shared by neighbouring parts cut once, and the fewest extra
//! moves that let few continuous paths cut everything, none through a part.
//!
//! - Graph ([`graph`]): the kerf-compensated paths (arcs kept) of every
//!   closed contour, and with `cut_open` the drawn open contours, shared and
//!   partly overlapping pieces merged within the tolerance. Parts nested with
//!   a spacing of exactly the kerf have coinciding paths between them: that
//!   line is cut once and both parts keep their drawn size. With kerf 0 the
//!   paths are the drawn lines: paper 003's knife on fabric.
//! - Groups: paths joined by shared pieces. In mode "repeat", groups of
//!   parts' outlines lying side by side (same enclosing contour) are joined by
//!   straight bridges ([`paths::bridges`]) travelled there and back, but only
//!   where the bridge runs through scrap ([`Scrap::line_ok`]) and is no longer
//!   than the longest link; other groups are separate circuits, one pierce
//!   each. A hole is never bridged to its part (the bridge would cut the part).
//! - Odd vertices of each group are paired by an exact minimum-weight perfect
//!   matching ([`matching`], Edmonds' blossom; greedy above
//!   [`matching::EXACT_MAX`]):
//!   - mode "repeat" (the tool stays down): on shortest-path distances
//!     through the group; each pair's path is travelled again (the
//!     Chinese-postman tour). Re-travelling a cut path removes nothing new.
//!   - mode "rapid": on straight distances; each pair becomes a rapid, and
//!     the group's circuit is cut in trails between the rapids.
//! - Euler circuit by Hierholzer ([`circuit`]), preferring to go straight on;
//!   circuits sequenced nearest first, holes before their part ([`sequence`]).
//!
//! Roles in the plan: the first pass over a path is [`Role::Contour`], any
//! later pass [`Role::Repeat`]; both passes over a bridge are [`Role::Link`]
//! (they cut scrap), so [`super::PlanStats`] counts bridges in `lead_length`
//! and `repeated_length` is the paths cut again only.

mod circuit;
mod leads;
mod matching;
mod next;
mod paths;
mod sequence;
mod spacing;
mod touching;

use crate::geom::graph::{self, Graph};
use circuit::Link;
use paths::{Net, Parts};

use super::clearance::Obstacles;
use super::scrap::Scrap;
use super::{CutPlan, EulerMode, Order, PlanInput, PlanOptions, Role, Step};
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::{dec, Warning};

/// What a link of the walked multigraph stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A path piece (index into the graph's edges).
    Edge(usize),
    /// A straight bridge between groups, torch on.
    Bridge,
    /// A paired rapid (mode "rapid").
    Rapid,
}

/// Plans the Eulerian (Chinese-postman) order.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    plan_only(input, options, None)
}

/// [`plan`] of the closed contours marked in `only` (all with None): the
/// others are neither cut nor met on a common edge, but stay obstacles
/// (the faces that share edges in another order, `super::shared`).
pub fn plan_only(input: &PlanInput, options: &PlanOptions, only: Option<&[bool]>) -> CutPlan {
    let contours = &input.contours.contours;
    let cut = |c: usize| only.is_none_or(|m| m.get(c).copied().unwrap_or(false));
    let kerf = if input.process.kerf.is_finite() {
        input.process.kerf.max(0.0)
    } else {
        0.0
    };
    let tol = input.tolerance;
    let open = contours
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kind == ContourKind::Open && options.cut_open)
        .flat_map(|(i, c)| c.segments.iter().map(move |s| (*s, i)));
    let obstacles = Obstacles::new(input.contours, tol);
    let scrap = Scrap::new(&obstacles, input.contours, kerf, tol);
    let segments: Vec<(Segment, usize)> = if kerf > 0.0 {
        // Parts drawn touching share one cut on their common edge.
        let touching = touching::common_edges(input, &scrap, kerf, tol, &cut);
        let replaced = |c: usize| touching.as_ref().is_some_and(|t| t.replaced.contains(&c));
        // Open contours are cut on the line (markings, welds): they have no side.
        let paths = input
            .kerf
            .paths
            .iter()
            .filter(|p| cut(p.contour) && !replaced(p.contour))
            .flat_map(|p| p.segments.iter().map(move |s| (*s, p.contour)));
        let common = touching.iter().flat_map(|t| t.segments.iter().copied());
        paths.chain(common).chain(open).collect()
    } else {
        contours
            .iter()
            .enumerate()
            .filter(|&(i, c)| c.is_closed() && cut(i))
            .flat_map(|(i, c)| c.segments.iter().map(move |s| (*s, i)))
            .chain(open)
            .collect()
    };
    let g = graph::build(&segments, tol);
    let mut warnings = spacing::warnings(input.contours, kerf, tol);
    let mut links: Vec<Link> = Vec::new();
    let mut kinds: Vec<Kind> = Vec::new();
    for (i, e) in g.edges.iter().enumerate() {
        links.push(Link {
            u: e.u,
            v: e.v,
            seg: e.seg,
        });
        kinds.push(Kind::Edge(i));
    }
    let nv = g.vertices.len();
    let mut parts = Parts::new(nv);
    for e in &g.edges {
        parts.union(e.u, e.v);
    }
    // The contour each vertex lies on (the first path through it).
    let on: Vec<Option<usize>> = (0..nv)
        .map(|v| {
            g.edges_at(v)
                .first()
                .and_then(|&e| g.edges.get(e as usize))
                .map(|e| e.contour)
        })
        .collect();
    if options.euler_mode == EulerMode::Repeat {
        // Bridges join outlines of parts lying side by side, through scrap.
        let outer = |v: usize| {
            on[v]
                .and_then(|c| contours.get(c))
                .filter(|c| c.kind == ContourKind::Outer)
        };
        let can: Vec<usize> = (0..nv).filter(|&v| outer(v).is_some()).collect();
        let mut ok = |a: usize, b: usize| {
            let same_place = match (outer(a), outer(b)) {
                (Some(x), Some(y)) => x.parent == y.parent,
                _ => false,
            };
            same_place && scrap.line_ok(g.vertices[a], g.vertices[b])
        };
        let bridges = paths::bridges(&g.vertices, &can, &mut parts, options.max_link, &mut ok);
        for &(a, b) in &bridges {
            // Once in the path network, twice in the circuit: there and back.
            for _ in 0..2 {
                links.push(Link {
                    u: a,
                    v: b,
                    seg: Segment::line(g.vertices[a], g.vertices[b]),
                });
                kinds.push(Kind::Bridge);
            }
        }
    }
    // Groups: one per set of joined vertices that some path touches.
    let mut group_of = vec![usize::MAX; nv];
    let mut members: Vec<Vec<usize>> = Vec::new();
    let mut root_group: crate::fx::FxMap<usize, usize> = Default::default();
    for v in (0..nv).filter(|&v| g.degree(v) > 0) {
        let r = parts.find(v);
        let k = *root_group.entry(r).or_insert_with(|| {
            members.push(Vec::new());
            members.len() - 1
        });
        group_of[v] = k;
        members[k].push(v);
    }
    augment(
        &g,
        &mut links,
        &mut kinds,
        &members,
        options.euler_mode,
        &mut warnings,
    );
    let starts: Vec<usize> = members.iter().map(|m| m[0]).collect();
    let circuits = circuit::circuits(&links, nv, &starts);
    let (after, depth) = precedence(input, &g, &group_of, members.len());
    // circuits() skips a start with nothing left; every group here has an
    // edge, so circuits line up with groups unless a walk was empty.
    let trails = if circuits.len() == members.len() {
        sequence::order(&circuits, &after, &depth, &links, &kinds, options.origin)
    } else {
        let none = vec![Vec::new(); circuits.len()];
        sequence::order(&circuits, &none, &[], &links, &kinds, options.origin)
    };
    // A router's lead arcs (a quarter turn in and out of every depth pass,
    // `super::router_lead`) are a loop's, and a trail here runs over many
    // loops' pieces: they are not cut, and said (`router_arcs_not_cut`),
    // never replaced by this order's straight lead-in.
    let router_arcs = input.process.tool.on() && options.leads.kind == super::LeadKind::Arc;
    let mut leads = options.leads;
    if router_arcs {
        leads.kind = super::LeadKind::None;
    }
    let ends = leads::Ends {
        scrap: &scrap,
        obstacles: &obstacles,
        contours: input.contours,
        leads,
        kerf,
        tol,
    };
    let wants_leads = kerf > tol && leads.kind != super::LeadKind::None;
    let mut on_path = 0;
    let mut common = Vec::new();
    let mut cut_once = vec![false; g.edges.len()];
    let cuts: Vec<super::Cut> = trails
        .into_iter()
        .filter(|t| !t.is_empty())
        .map(|t| {
            let (t, pierce) = ends.enter(t, &links, &kinds, &g);
            let mut cut =
                sequence::to_cut(&t, &links, &kinds, &g, input, &mut cut_once, &mut common);
            let contour = cut.contours.first().copied();
            let path: Vec<Segment> = cut.steps.iter().map(|s| s.segment).collect();
            let over = ends.overcut(&path);
            cut.steps.extend(over.into_iter().map(|segment| Step {
                segment,
                role: Role::LeadOut,
                contour,
            }));
            match pierce {
                Some(q) => {
                    cut.steps.insert(
                        0,
                        Step {
                            segment: Segment::line(q, cut.pierce),
                            role: Role::LeadIn,
                            contour,
                        },
                    );
                    cut.pierce = q;
                }
                None if wants_leads => on_path += 1,
                None => {}
            }
            cut
        })
        .collect();
    if router_arcs {
        warnings.extend(router_arcs_not_cut(&cuts, input));
    }
    if on_path > 0 {
        warnings.push(Warning::new(
            "eulerian-pierce-on-path",
            text!("eulerian order: {on_path} cut(s) pierce on the path: no lead-in fits in the scrap there";
                  "ordem euleriana: {on_path} corte(s) perfuram sobre o caminho: nenhuma entrada cabe na sucata ali"),
        ));
    }
    CutPlan {
        origin: options.origin,
        order: Order::Eulerian,
        cuts,
        warnings,
        tour: None,
        common_line: common,
        arc_fit: None,
    }
}

/// The warning that the router's lead arcs asked for are not cut on
/// `cuts` (the Eulerian order's), naming their contours: the tool goes
/// down onto the path at each cut's start on every depth pass and comes
/// up where it ends.
fn router_arcs_not_cut(cuts: &[super::Cut], input: &PlanInput) -> Option<Warning> {
    let first = cuts.first()?;
    let n = cuts.len();
    let um = |v: f64| (v * 1000.0).round() / 1000.0;
    let (x, y) = (um(first.pierce.x), um(first.pierce.y));
    let (xd, yd) = (dec(x), dec(y));
    let loops = (cuts.iter())
        .flat_map(|c| &c.contours)
        .filter_map(|&k| input.contours.contours.get(k))
        .map(|c| c.source);
    Some(
        Warning::at(
            "router-arcs-not-cut",
            text!("the router's lead arcs are not cut on the {n} cut(s) of the eulerian order (which also cuts parts that share edges): its cuts follow the graph of all the paths, not one loop each, so the tool goes straight down onto the path where it starts and up where it ends, on every depth pass (first at {x}, {y}); parts apart, in the contour or chained order, get the arcs";
                  "os arcos de entrada da fresadora não são cortados nos {n} corte(s) da ordem euleriana (que também corta peças que compartilham arestas): seus cortes seguem o grafo de todos os caminhos, não um contorno cada, então a ferramenta desce direto sobre o caminho onde ele começa e sobe onde termina, em cada passe de profundidade (o primeiro em {xd}, {yd}); peças afastadas, na ordem por contorno ou encadeada, recebem os arcos"),
            first.pierce,
        )
        .with_loops(loops),
    )
}

/// Makes every vertex of each group even: mode "repeat" re-travels the
/// shortest paths between paired odd vertices, mode "rapid" pairs them by
/// rapids. Pairs never leave their group.
fn augment(
    g: &Graph,
    links: &mut Vec<Link>,
    kinds: &mut Vec<Kind>,
    members: &[Vec<usize>],
    mode: EulerMode,
    warnings: &mut Vec<Warning>,
) {
    let base: Vec<Link> = links.clone();
    let net = Net::new(&base, g.vertices.len());
    // Degrees over the edges and bridges.
    let mut degree = vec![0usize; g.vertices.len()];
    for l in &base {
        degree[l.u] += 1;
        degree[l.v] += 1;
    }
    for m in members {
        let odd: Vec<usize> = m.iter().copied().filter(|&v| degree[v] % 2 == 1).collect();
        if odd.is_empty() {
            continue;
        }
        match mode {
            EulerMode::Repeat => {
                let cost = |odd: &[usize]| {
                    let n = odd.len();
                    let mut c = vec![0.0; n * n];
                    for (i, &s) in odd.iter().enumerate() {
                        let (d, _) = net.dijkstra(s, odd);
                        for (j, &t) in odd.iter().enumerate() {
                            c[i * n + j] = d[t];
                        }
                    }
                    c
                };
                for (a, b) in pair(g, &odd, cost, warnings) {
                    for l in net.path(a, b) {
                        links.push(base[l]);
                        kinds.push(kinds[l]);
                    }
                }
            }
            EulerMode::Rapid => {
                let cost = |odd: &[usize]| {
                    let n = odd.len();
                    (0..n * n)
                        .map(|k| g.vertices[odd[k / n]].dist(g.vertices[odd[k % n]]))
                        .collect()
                };
                for (a, b) in pair(g, &odd, cost, warnings) {
                    links.push(Link {
                        u: a,
                        v: b,
                        seg: Segment::line(g.vertices[a], g.vertices[b]),
                    });
                    kinds.push(Kind::Rapid);
                }
            }
        }
    }
}

/// For each group, the groups that must be cut before it: those holding a
/// contour whose nearest enclosing cut contour is in this group (a hole
/// before its part, an island before its hole); and each group's deepest
/// contour containment depth.
fn precedence(
    input: &PlanInput,
    g: &Graph,
    group_of: &[usize],
    n: usize,
) -> (Vec<Vec<usize>>, Vec<usize>) {
    let contours = &input.contours.contours;
    let mut group_of_contour = vec![None; contours.len()];
    for e in &g.edges {
        if let (Some(slot), Some(&k)) = (group_of_contour.get_mut(e.contour), group_of.get(e.u)) {
            if slot.is_none() && k < n {
                *slot = Some(k);
            }
        }
    }
    let mut after = vec![Vec::new(); n];
    let mut depth = vec![0; n];
    for (c, k) in group_of_contour.iter().enumerate() {
        let Some(k) = *k else { continue };
        depth[k] = depth[k].max(contours[c].depth);
        // The nearest enclosing contour that is cut (a hole that vanished
        // under the kerf passes its islands on to the part).
        let mut up = contours[c].parent;
        let mut guard = 0;
        while let Some(p) = up {
            if guard > contours.len() {
                break;
            }
            guard += 1;
            if let Some(Some(pk)) = group_of_contour.get(p) {
                if *pk != k && !after[*pk].contains(&k) {
                    after[*pk].push(k);
                }
                break;
            }
            up = contours.get(p).and_then(|c| c.parent);
        }
    }
    (after, depth)
}

/// Pairs the odd vertices `odd` on the `n × n` cost matrix made by `cost`,
/// exactly up to the limit, greedily by straight distance above it.
fn pair(
    g: &Graph,
    odd: &[usize],
    cost: impl Fn(&[usize]) -> Vec<f64>,
    warnings: &mut Vec<Warning>,
) -> Vec<(usize, usize)> {
    let n = odd.len();
    let mate = if n <= matching::EXACT_MAX {
        matching::exact(&cost(odd), n)
    } else {
        None
    };
    let mate = mate.unwrap_or_else(|| {
        let max = matching::EXACT_MAX;
        warnings.push(Warning::new(
            "odd-vertices-greedy",
            text!("eulerian order: {n} odd vertices, more than {max} matched exactly: paired greedily by nearest neighbour";
                  "ordem euleriana: {n} vértices ímpares, mais que os {max} pareados exatamente: pareados pelo vizinho mais próximo"),
        ));
        let pts: Vec<Point> = odd.iter().map(|&v| g.vertices[v]).collect();
        matching::greedy(&pts)
    });
    (0..n)
        .filter_map(|i| {
            let j = *mate.get(i)?;
            (i < j && j < n).then(|| (odd[i], odd[j]))
        })
        .collect()
}
