//! Order "eulerian" (paper 003, Vidal Filho, Moscato, Segenreich): one graph
//! of all drawn edges, edges shared by touching parts cut once, and the
//! fewest extra moves that let one continuous path cut everything.
//!
//! - Graph ([`graph`]): the drawn segments of every closed contour (and of
//!   open ones with `cut_open`), shared and partly overlapping edges merged.
//! - Odd vertices are paired by an exact minimum-weight perfect matching
//!   ([`matching`], Edmonds' blossom; greedy above [`matching::EXACT_MAX`]):
//!   - mode "repeat" (a knife that must stay down): on shortest-path
//!     distances through the graph; each pair's path is travelled again
//!     (the Chinese-postman tour). Separate groups of edges are first joined
//!     by straight bridges ([`paths::bridges`]) travelled there and back.
//!   - mode "rapid": on straight distances; each pair becomes a rapid, and
//!     the circuit of each group is cut in trails between the rapids.
//! - Euler circuit by Hierholzer ([`circuit`]), preferring to go straight on.
//!
//! Roles in the plan: the first pass over a drawn edge is [`Role::Contour`],
//! any later pass [`Role::Repeat`]; both passes over a bridge are
//! [`Role::Link`] (they cut scrap, not a drawn edge), so [`super::PlanStats`]
//! counts bridges in `lead_length` and `repeated_length` is the drawn edges
//! cut again only. This order cuts on the drawn lines, not the kerf paths.

mod circuit;
mod graph;
mod matching;
mod paths;

use circuit::{hierholzer, Link};
use graph::Graph;
use paths::{Net, Parts};

use super::{Cut, CutPlan, EulerMode, Order, PlanInput, PlanOptions, Role, Step};
use crate::contour::ContourKind;
use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::{dec, Warning};

/// What a link of the walked multigraph stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A drawn edge (index into the graph's edges).
    Edge(usize),
    /// A straight bridge between groups, torch on.
    Bridge,
    /// A paired rapid (mode "rapid").
    Rapid,
}

/// Plans the Eulerian (Chinese-postman) order.
pub fn plan(input: &PlanInput, options: &PlanOptions) -> CutPlan {
    let contours = &input.contours.contours;
    let segments: Vec<(Segment, usize)> = contours
        .iter()
        .enumerate()
        .filter(|(_, c)| c.is_closed() || options.cut_open)
        .flat_map(|(i, c)| c.segments.iter().map(move |s| (*s, i)))
        .collect();
    let g = graph::build(&segments, input.tolerance);
    let mut warnings = Vec::new();
    if input.kerf_width > 0.0 && !g.edges.is_empty() {
        let w = input.kerf_width;
        warnings.push(Warning::new(
            "kerf-not-compensated",
            text!("eulerian order cuts on the drawn lines: the kerf of {w} mm is not compensated, shared edges are cut on the line";
                  "a ordem euleriana corta sobre as linhas desenhadas: a sangria de {} mm não é compensada, arestas comuns são cortadas sobre a linha", dec(w)),
        ));
    }
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
    let cuts = match options.euler_mode {
        EulerMode::Repeat => repeat(&g, &mut links, &mut kinds, options.origin, &mut warnings),
        EulerMode::Rapid => rapid(&g, &mut links, &mut kinds, options.origin, &mut warnings),
    };
    let mut cut_once = vec![false; g.edges.len()];
    let cuts = cuts
        .into_iter()
        .filter(|t| !t.is_empty())
        .map(|t| to_cut(&t, &links, &kinds, &g, input, &mut cut_once))
        .collect();
    CutPlan {
        origin: options.origin,
        order: Order::Eulerian,
        cuts,
        warnings,
        tour: None,
    }
}

/// Vertices that some edge touches.
fn used_vertices(g: &Graph) -> Vec<usize> {
    (0..g.vertices.len()).filter(|&v| g.degree(v) > 0).collect()
}

/// The vertex of `among` nearest `p`.
fn nearest(g: &Graph, among: &[usize], p: Point) -> Option<usize> {
    among
        .iter()
        .copied()
        .min_by(|&a, &b| g.vertices[a].dist(p).total_cmp(&g.vertices[b].dist(p)))
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

/// Mode "repeat": bridges, repeated shortest paths, one circuit from the
/// vertex nearest the origin. Returns one trail (a list of (link, forward)).
fn repeat(
    g: &Graph,
    links: &mut Vec<Link>,
    kinds: &mut Vec<Kind>,
    origin: Point,
    warnings: &mut Vec<Warning>,
) -> Vec<Vec<(usize, bool)>> {
    let used = used_vertices(g);
    let mut parts = Parts::new(g.vertices.len());
    for e in &g.edges {
        parts.union(e.u, e.v);
    }
    let bridges = paths::bridges(&g.vertices, &used, &mut parts);
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
    let odd = g.odd_vertices();
    let base: Vec<Link> = links.clone();
    let net = Net::new(&base, g.vertices.len());
    let cost = |odd: &[usize]| {
        let n = odd.len();
        let mut m = vec![0.0; n * n];
        for (i, &s) in odd.iter().enumerate() {
            let (d, _) = net.dijkstra(s, odd);
            for (j, &t) in odd.iter().enumerate() {
                m[i * n + j] = d[t];
            }
        }
        m
    };
    let pairs = pair(g, &odd, cost, warnings);
    for (a, b) in pairs {
        for l in net.path(a, b) {
            links.push(base[l]);
            kinds.push(kinds[l]);
        }
    }
    let Some(start) = nearest(g, &used, origin) else {
        return Vec::new();
    };
    vec![hierholzer(links, g.vertices.len(), start)]
}

/// Mode "rapid": odd vertices paired by straight rapids; each group's
/// circuit is cut in trails between its rapids, the one rapid saved by
/// starting after it and ending before it; groups in nearest-first order.
fn rapid(
    g: &Graph,
    links: &mut Vec<Link>,
    kinds: &mut Vec<Kind>,
    origin: Point,
    warnings: &mut Vec<Warning>,
) -> Vec<Vec<(usize, bool)>> {
    let odd = g.odd_vertices();
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
    let nv = g.vertices.len();
    let mut parts = Parts::new(nv);
    for l in links.iter() {
        parts.union(l.u, l.v);
    }
    // One circuit per group, from its first vertex.
    let mut seen = vec![false; nv];
    let mut starts = Vec::new();
    for v in used_vertices(g) {
        let r = parts.find(v);
        if !seen[r] {
            seen[r] = true;
            starts.push(v);
        }
    }
    let circuits = circuit::circuits(links, nv, &starts);
    let entries: Vec<Vec<Entry>> = circuits.iter().map(|c| entries(c, links, kinds)).collect();
    let mut left: Vec<usize> = (0..circuits.len()).collect();
    let mut trails = Vec::new();
    let mut at = origin;
    while !left.is_empty() {
        // The group and the way in that cost the least: the approach minus
        // the rapid that starting there saves.
        let mut best: Option<(f64, usize, Entry)> = None;
        for (li, &ci) in left.iter().enumerate() {
            for e in &entries[ci] {
                let score = at.dist(e.start) - e.saved;
                if best.as_ref().is_none_or(|b| score < b.0) {
                    best = Some((score, li, *e));
                }
            }
        }
        let Some((_, li, e)) = best else {
            break;
        };
        let ci = left.swap_remove(li);
        let Some(c) = circuits.get(ci) else {
            break;
        };
        let mut walk: Vec<(usize, bool)> = if e.reversed {
            c.iter().rev().map(|&(l, f)| (l, !f)).collect()
        } else {
            c.clone()
        };
        if e.drop {
            walk.rotate_left(e.k + 1);
            walk.pop();
        } else {
            walk.rotate_left(e.k);
        }
        let mut trail = Vec::new();
        for step in walk {
            if kinds[step.0] == Kind::Rapid {
                trails.push(std::mem::take(&mut trail));
            } else {
                trail.push(step);
            }
        }
        if let Some(&(l, f)) = trail.last() {
            at = links[l].oriented(f).b;
        }
        trails.push(trail);
    }
    trails
}

/// A way into a closed circuit: where the walk starts, the rapid it saves.
#[derive(Clone, Copy, Debug)]
struct Entry {
    start: Point,
    saved: f64,
    reversed: bool,
    /// Index in the (possibly reversed) circuit: of the rapid dropped
    /// (`drop`), or of the first step.
    k: usize,
    drop: bool,
}

/// Most ways into a circuit without rapids that are weighed (evenly spaced
/// vertices): enough for a near start, few enough that sequencing a
/// thousand groups stays a matter of milliseconds.
const MAX_ENTRIES: usize = 64;

/// The ways into circuit `c`: with rapids, either direction starting just
/// after one of them (that rapid is then never made); without, from one of
/// its vertices.
fn entries(c: &[(usize, bool)], links: &[Link], kinds: &[Kind]) -> Vec<Entry> {
    let n = c.len();
    let rapids: Vec<usize> = (0..n).filter(|&k| kinds[c[k].0] == Kind::Rapid).collect();
    if rapids.is_empty() {
        let step = n.div_ceil(MAX_ENTRIES).max(1);
        return (0..n)
            .step_by(step)
            .map(|k| Entry {
                start: links[c[k].0].oriented(c[k].1).a,
                saved: 0.0,
                reversed: false,
                k,
                drop: false,
            })
            .collect();
    }
    let mut out = Vec::with_capacity(2 * rapids.len());
    for &k in &rapids {
        let (l, f) = c[k];
        let seg = links[l].oriented(f);
        let saved = seg.length();
        // Forward: the walk starts at the rapid's end. Reversed, the same
        // rapid sits at n-1-k and is walked the other way.
        out.push(Entry {
            start: seg.b,
            saved,
            reversed: false,
            k,
            drop: true,
        });
        out.push(Entry {
            start: seg.a,
            saved,
            reversed: true,
            k: n - 1 - k,
            drop: true,
        });
    }
    out
}

/// One trail as a cut. The first pass over a drawn edge (per `cut_once`)
/// is [`Role::Contour`], later ones [`Role::Repeat`].
fn to_cut(
    trail: &[(usize, bool)],
    links: &[Link],
    kinds: &[Kind],
    g: &Graph,
    input: &PlanInput,
    cut_once: &mut [bool],
) -> Cut {
    let mut steps = Vec::with_capacity(trail.len());
    let mut touched: Vec<usize> = Vec::new();
    for &(l, f) in trail {
        let segment = links[l].oriented(f);
        let (role, contour) = match kinds.get(l) {
            Some(&Kind::Edge(e)) => {
                let again = cut_once.get(e).copied().unwrap_or(true);
                if let Some(c) = cut_once.get_mut(e) {
                    *c = true;
                }
                let role = if again { Role::Repeat } else { Role::Contour };
                (role, g.edges.get(e).map(|e| e.contour))
            }
            _ => (Role::Link, None),
        };
        if let Some(c) = contour {
            if !touched.contains(&c) {
                touched.push(c);
            }
        }
        steps.push(Step {
            segment,
            role,
            contour,
        });
    }
    let first = touched
        .first()
        .and_then(|&c| input.contours.contours.get(c));
    Cut {
        pierce: steps.first().map_or(Point::default(), |s| s.segment.a),
        steps,
        contours: touched,
        part: first.and_then(|c| c.part),
        kind: first.map_or(ContourKind::Outer, |c| c.kind),
        spot: false,
    }
}
