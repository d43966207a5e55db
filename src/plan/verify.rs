//! kerfcam checks its own cut (issue 20 §9, paper 004's swept-envelope
//! verification): the kerf disc (radius w/2) swept along every cutting move
//! of the plan, compared with the drawn parts.
//!
//! - **Overcut**: where the swept disc takes a part's material. Its area is
//!   counted on a raster of cells (w/8 wide, 0.02–0.5 mm) stamped only
//!   around the moves that reach into a part, so a clean plan costs no
//!   raster at all; its depth (how far the disc reaches past the drawn edge)
//!   is exact at samples at most a cell apart.
//! - **Parts not freed**: a part is free when the disc reaches every point
//!   of its outline; a stretch of outline no cutting move comes within w/2
//!   of (a missing cut, a tab) leaves it attached to the sheet.
//!
//! Marks (scribing) cut nothing and are left out; so are spots. What counts
//! as reaching is the geometry's rounding: ten tolerances.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// A multiply-rotate hash for grid cells (the standard SipHash spent a
/// third of the sweep's time on millions of cell keys; these keys come
/// from our own arithmetic, not from an adversary).
#[derive(Default)]
struct CellHasher(u64);

impl Hasher for CellHasher {
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(b as u64);
        }
    }
    fn write_i64(&mut self, v: i64) {
        self.write_u64(v as u64);
    }
    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

use super::clearance::Obstacles;
use super::{CutPlan, PlanInput, Role};
use crate::contour::{point_in_loop, ContourKind};
use crate::geom::{dist_to_segment, BBox, Point, Segment};

/// What the swept kerf does to the parts.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Verification {
    /// Area of part material inside the swept kerf, mm².
    pub overcut_mm2: f64,
    /// Parts whose outline the kerf does not reach all round (not counting
    /// those held only by their tabs).
    pub parts_not_freed: usize,
    /// Parts that would be free but for their tabs (issue 20 §6): held on
    /// purpose, not a missing cut.
    pub parts_held_by_tabs: usize,
    /// Deepest reach of the kerf past a drawn edge into a part, mm.
    pub max_overcut_mm: f64,
    /// The first part not freed (1-based), for the warning.
    pub first_not_freed: Option<usize>,
    /// Where the deepest overcut is.
    pub deepest_at: Option<Point>,
    /// The raster `overcut_mm2` counts (the preview's heat map): each cell
    /// of part material the kerf takes, its centre and the depth of the
    /// deepest disc that took it, mm, in raster order.
    pub overcut_cells: Vec<(Point, f64)>,
    /// The raster's cell side, mm.
    pub cell: f64,
    /// Points of the outlines of parts not freed that no cutting move
    /// reaches, about a cell apart: where they stay attached to the sheet
    /// (at most [`ATTACHED_MAX`]).
    pub attached: Vec<Point>,
}

/// The most attachment points kept for the preview.
pub const ATTACHED_MAX: usize = 100_000;

/// Every closed contour's segments filed by horizontal bands, for the
/// even-odd test of part material: a point is in a part when a ray to its
/// right crosses the drawn closed contours an odd number of times (the sum
/// of each contour's parity), and only the segments of its band can cross.
struct Material<'a> {
    y0: f64,
    height: f64,
    bands: Vec<Vec<(f64, &'a Segment)>>,
}

impl<'a> Material<'a> {
    fn new(contours: &'a crate::contour::Contours, height: f64) -> Material<'a> {
        let closed = || contours.contours.iter().filter(|c| c.is_closed());
        let mut ext = BBox::EMPTY;
        for c in closed() {
            ext.union(&c.bbox);
        }
        if ext.is_empty() {
            return Material {
                y0: 0.0,
                height: 1.0,
                bands: Vec::new(),
            };
        }
        let height = height.max((ext.max.y - ext.min.y) / 100_000.0).max(1e-6);
        let n = (((ext.max.y - ext.min.y) / height).ceil() as usize + 1).max(1);
        let mut bands: Vec<Vec<(f64, &Segment)>> = vec![Vec::new(); n];
        for c in closed() {
            for s in &c.segments {
                let b = s.bbox();
                let lo = (((b.min.y - ext.min.y) / height).floor().max(0.0) as usize).min(n - 1);
                let hi = (((b.max.y - ext.min.y) / height).floor().max(0.0) as usize).min(n - 1);
                for band in &mut bands[lo..=hi] {
                    band.push((b.max.x, s));
                }
            }
        }
        Material {
            y0: ext.min.y,
            height,
            bands,
        }
    }
    /// True when `p` lies in a part's material.
    fn contains(&self, p: Point) -> bool {
        // Nudged off chords and vertices, as `Scrap::in_material`.
        let p = Point::new(p.x + 0.754_877_666e-7, p.y + 0.569_840_291e-7);
        let k = (p.y - self.y0) / self.height;
        if !(k >= 0.0 && (k as usize) < self.bands.len()) {
            return false;
        }
        self.bands[k as usize]
            .iter()
            .filter(|(max_x, s)| *max_x >= p.x && point_in_loop(p, std::slice::from_ref(*s)))
            .count()
            % 2
            == 1
    }
}

/// The cutting moves of `plan` (no marks, no spots, no tabs: the torch is
/// off over them), and the tabs too when `tabs` (to ask whether a part
/// would be free but for its tabs).
fn cutting(plan: &CutPlan, tabs: bool) -> impl Iterator<Item = &Segment> {
    plan.cuts
        .iter()
        .filter(|c| !c.spot)
        .flat_map(|c| c.steps.iter())
        .filter(move |s| s.role != Role::Mark && (tabs || s.role != Role::Tab))
        .map(|s| &s.segment)
}

/// Sweeps the plan's kerf over the parts of `input`.
pub fn verify(input: &PlanInput, plan: &CutPlan) -> Verification {
    let tol = input.tolerance.max(1e-6);
    let r = (input.kerf_width / 2.0).max(0.0);
    let slack = 10.0 * tol;
    let cell = (r / 4.0).clamp(0.02, 0.5);
    let obstacles = Obstacles::new(input.contours, input.tolerance);
    let material_index = Material::new(input.contours, 2.0 * cell);
    let mut out = Verification::default();
    // Cells stamped by an overcutting disc: whether each is part material,
    // and the deepest disc's depth.
    let mut material: HashMap<(i64, i64), (bool, f64), BuildHasherDefault<CellHasher>> =
        HashMap::default();
    let key = |v: f64| (v / cell).floor().clamp(-1e12, 1e12) as i64;
    for cut in plan.cuts.iter().filter(|c| !c.spot) {
        // Whether the torch is inside a part, while known: it changes only
        // where a move crosses a drawn edge (d = 0), and d changes no faster
        // than the torch moves (the same reasoning as `scrap::intrusion`).
        let mut inside: Option<bool> = None;
        let mut last_d = 0.0_f64;
        for s in cut
            .steps
            .iter()
            .filter(|s| s.role != Role::Mark && s.role != Role::Tab)
        {
            let s = &s.segment;
            let len = s.length();
            if !len.is_finite() {
                continue;
            }
            let n = ((len / cell).ceil() as usize).clamp(1, 200_000);
            for k in 0..=n {
                let p = s.point_at(k as f64 / n as f64);
                let d = obstacles.distance(p, r + cell + slack);
                let d = if d.is_finite() { d } else { r + cell + slack };
                if last_d + d <= cell {
                    inside = None;
                }
                last_d = d;
                let depth = if r <= slack && d <= slack {
                    // No kerf, on a drawn line: takes nothing from either side.
                    0.0
                } else if *inside.get_or_insert_with(|| material_index.contains(p)) {
                    r + d
                } else {
                    (r - d).max(0.0)
                };
                if depth <= slack {
                    continue;
                }
                if depth > out.max_overcut_mm {
                    out.max_overcut_mm = depth;
                    out.deepest_at = Some(p);
                }
                // Stamp the disc: the cells of part material it covers,
                // column by column (the column's chord of the disc).
                for i in key(p.x - r)..=key(p.x + r) {
                    let dx = (i as f64 + 0.5) * cell - p.x;
                    let half = r * r - dx * dx;
                    if half < 0.0 {
                        continue;
                    }
                    let half = half.sqrt();
                    let lo = ((p.y - half) / cell - 0.5).ceil() as i64;
                    let hi = ((p.y + half) / cell - 0.5).floor() as i64;
                    for j in lo..=hi {
                        let c = Point::new((i as f64 + 0.5) * cell, (j as f64 + 0.5) * cell);
                        let m = material
                            .entry((i, j))
                            .or_insert_with(|| (material_index.contains(c), 0.0));
                        m.1 = m.1.max(depth);
                    }
                }
            }
        }
    }
    let mut cells: Vec<((i64, i64), f64)> = material
        .into_iter()
        .filter(|(_, (m, _))| *m)
        .map(|(k, (_, d))| (k, d))
        .collect();
    crate::sort::sort_cells(&mut cells);
    out.overcut_mm2 = cells.len() as f64 * cell * cell;
    out.cell = cell;
    out.overcut_cells = cells
        .into_iter()
        .map(|((i, j), d)| {
            let c = Point::new((i as f64 + 0.5) * cell, (j as f64 + 0.5) * cell);
            (c, d)
        })
        .collect();
    let (held, _) = not_freed(input, plan, r, cell, slack, false);
    let has_tabs = plan
        .cuts
        .iter()
        .any(|c| c.steps.iter().any(|s| s.role == Role::Tab));
    let (still, attached) = if has_tabs && !held.is_empty() {
        not_freed(input, plan, r, cell, slack, true)
    } else {
        // Again for where they are attached, only when some are.
        match held.is_empty() {
            true => (held.clone(), Vec::new()),
            false => not_freed(input, plan, r, cell, slack, false),
        }
    };
    out.attached = attached;
    out.parts_held_by_tabs = held.iter().filter(|c| !still.contains(c)).count();
    out.parts_not_freed = still.len();
    out.first_not_freed = still
        .iter()
        .find_map(|&c| input.contours.contours.get(c).and_then(|c| c.part));
    out
}

/// Parts (their outer contours' indices) whose outline some point of which
/// no cutting move reaches, and the points of their outlines (`cell`
/// apart) that none reaches; with `tabs`, the moves over tabs count as cuts.
fn not_freed(
    input: &PlanInput,
    plan: &CutPlan,
    r: f64,
    cell: f64,
    slack: f64,
    tabs: bool,
) -> (Vec<usize>, Vec<Point>) {
    // Cutting moves filed by the cells of a grid their boxes (grown by the
    // reach) cover.
    let reach = r + slack;
    let g = (4.0 * reach).max(1.0);
    let key = |v: f64| (v / g).floor().clamp(-1e12, 1e12) as i64;
    let moves: Vec<&Segment> = cutting(plan, tabs).collect();
    let mut grid: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
    for (m, s) in moves.iter().enumerate() {
        // Filed along the move (a long diagonal's box would cover a whole
        // sheet): the cells within the reach of points half a cell apart.
        let n = ((s.length() / (g / 2.0)).ceil() as usize).clamp(1, 1_000_000);
        let mut last = None;
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            // Reach plus the quarter cell to the nearest sample, rounded up.
            let pad = reach + g / 2.0;
            let cells = (
                key(p.x - pad),
                key(p.x + pad),
                key(p.y - pad),
                key(p.y + pad),
            );
            if last == Some(cells) {
                continue;
            }
            last = Some(cells);
            for i in cells.0..=cells.1 {
                for j in cells.2..=cells.3 {
                    let v = grid.entry((i, j)).or_default();
                    if v.last() != Some(&(m as u32)) {
                        v.push(m as u32);
                    }
                }
            }
        }
    }
    let reached = |q: Point| {
        grid.get(&(key(q.x), key(q.y))).is_some_and(|ms| {
            ms.iter()
                .any(|&m| dist_to_segment(q, moves[m as usize]) <= reach)
        })
    };
    let near = |b: &BBox| -> Vec<usize> {
        let mut v: Vec<usize> = Vec::new();
        if (key(b.max.x) - key(b.min.x) + 1).saturating_mul(key(b.max.y) - key(b.min.y) + 1)
            > 4_000_000
        {
            return (0..moves.len()).collect();
        }
        for i in key(b.min.x)..=key(b.max.x) {
            for j in key(b.min.y)..=key(b.max.y) {
                if let Some(ms) = grid.get(&(i, j)) {
                    v.extend(ms.iter().map(|&m| m as usize));
                }
            }
        }
        crate::sort::sort_indices(&mut v);
        v.dedup();
        v
    };
    let mut out = Vec::new();
    let mut attached = Vec::new();
    for (k, c) in input.contours.contours.iter().enumerate() {
        if c.kind != ContourKind::Outer {
            continue;
        }
        let b = c.bbox;
        let size = (b.max.x - b.min.x).max(b.max.y - b.min.y);
        // Cells at most 0.4 kerf: a kerf band is then at least five cells
        // wide and seals; a part too big for such a raster (or no kerf) is
        // checked by its outline: every point of it reached.
        let h = (r / 2.5).max(size / 1500.0).max(0.01);
        let free = if h <= r / 2.5 + 1e-12 && r > slack {
            sealed(c, &moves, &near, r, h)
        } else {
            c.segments.iter().all(|s| {
                let n = ((s.length() / cell).ceil() as usize).clamp(1, 100_000);
                (0..=n).all(|k| reached(s.point_at(k as f64 / n as f64)))
            })
        };
        if !free {
            out.push(k);
            for s in &c.segments {
                let n = ((s.length() / cell).ceil() as usize).clamp(1, ATTACHED_MAX);
                for k in 0..=n {
                    let q = s.point_at(k as f64 / n as f64);
                    if attached.len() < ATTACHED_MAX && !reached(q) {
                        attached.push(q);
                    }
                }
            }
        }
    }
    (out, attached)
}

/// True when the kerf swept by `moves` seals part `c` off from the sheet:
/// on a raster of `h` cells over its box (grown by a kerf and two cells),
/// no path of unswept cells leads from the raster's edge into the part.
/// A notch narrower than the kerf (a corner the kerf cannot reproduce)
/// stays with the part; a tab or a missing cut lets the sheet in.
fn sealed(
    c: &crate::contour::Contour,
    moves: &[&Segment],
    near: &dyn Fn(&BBox) -> Vec<usize>,
    r: f64,
    h: f64,
) -> bool {
    let margin = 2.0 * r + 2.0 * h;
    let (x0, y0) = (c.bbox.min.x - margin, c.bbox.min.y - margin);
    let nx = (((c.bbox.max.x - c.bbox.min.x) + 2.0 * margin) / h).ceil() as usize + 1;
    let ny = (((c.bbox.max.y - c.bbox.min.y) + 2.0 * margin) / h).ceil() as usize + 1;
    let centre =
        |i: usize, j: usize| Point::new(x0 + (i as f64 + 0.5) * h, y0 + (j as f64 + 0.5) * h);
    let mut swept = vec![false; nx * ny];
    let grown = BBox {
        min: Point::new(x0, y0),
        max: Point::new(x0 + nx as f64 * h, y0 + ny as f64 * h),
    };
    for m in near(&grown) {
        // Discs at most a cell apart along the move, stamped column by column.
        let s = moves[m];
        let n = ((s.length() / h).ceil() as usize).clamp(1, 1_000_000);
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            let lo_i = ((p.x - r - x0) / h - 0.5).ceil().max(0.0) as usize;
            let hi_i = (((p.x + r - x0) / h - 0.5).floor() + 1.0).max(0.0) as usize;
            for i in lo_i..hi_i.min(nx) {
                let dx = x0 + (i as f64 + 0.5) * h - p.x;
                let half = r * r - dx * dx;
                if half < 0.0 {
                    continue;
                }
                let half = half.sqrt();
                let lo_j = ((p.y - half - y0) / h - 0.5).ceil().max(0.0) as usize;
                let hi_j = (((p.y + half - y0) / h - 0.5).floor() + 1.0).max(0.0) as usize;
                for j in lo_j..hi_j.min(ny) {
                    swept[j * nx + i] = true;
                }
            }
        }
    }
    // The part, row by row: even-odd crossings of its outline (arcs as
    // chords within a tenth of a cell).
    let mut edges: Vec<(Point, Point)> = Vec::new();
    for s in &c.segments {
        match s.arc_center() {
            Some((_, rad)) => {
                let n = crate::geom::flatten_count(rad, s.sweep().abs(), h / 10.0).max(1);
                let mut a = s.a;
                for k in 1..=n {
                    let b = if k == n {
                        s.b
                    } else {
                        s.point_at(k as f64 / n as f64)
                    };
                    edges.push((a, b));
                    a = b;
                }
            }
            None => edges.push((s.a, s.b)),
        }
    }
    let mut inside = vec![false; nx * ny];
    let mut xs: Vec<f64> = Vec::new();
    for j in 0..ny {
        let y = centre(0, j).y;
        xs.clear();
        for (a, b) in &edges {
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
            }
        }
        crate::sort::sort_floats(&mut xs);
        for pair in xs.chunks(2) {
            if let [xa, xb] = pair {
                let lo = ((xa - x0) / h - 0.5).ceil().max(0.0) as usize;
                let hi = (((xb - x0) / h - 0.5).floor() + 1.0).max(0.0) as usize;
                for i in lo..hi.min(nx) {
                    inside[j * nx + i] = true;
                }
            }
        }
    }
    // The sheet: every unswept cell reachable from the raster's edge.
    let mut seen = vec![false; nx * ny];
    let mut stack: Vec<usize> = Vec::new();
    for i in 0..nx {
        stack.push(i);
        stack.push((ny - 1) * nx + i);
    }
    for j in 0..ny {
        stack.push(j * nx);
        stack.push(j * nx + nx - 1);
    }
    while let Some(k) = stack.pop() {
        if seen[k] || swept[k] {
            continue;
        }
        if inside[k] {
            return false;
        }
        seen[k] = true;
        let (i, j) = (k % nx, k / nx);
        if i > 0 {
            stack.push(k - 1);
        }
        if i + 1 < nx {
            stack.push(k + 1);
        }
        if j > 0 {
            stack.push(k - nx);
        }
        if j + 1 < ny {
            stack.push(k + nx);
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use crate::plan::Order;

    fn square_with_hole() -> Vec<u8> {
        let sq = "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n60\n10\n0\n20\n60\n";
        let hole = "0\nCIRCLE\n8\n0\n10\n50\n20\n30\n40\n10\n";
        format!("0\nSECTION\n2\nENTITIES\n{sq}{hole}0\nENDSEC\n0\nEOF\n").into_bytes()
    }

    fn check(order: Order) -> super::Verification {
        let mut s = crate::Settings::new(2.0, 0.001, 1000.0).unwrap();
        s.plan.order = order;
        let out = crate::run(&square_with_hole(), &s).unwrap();
        let input = crate::plan::PlanInput {
            drawing: &out.drawing,
            contours: &out.contours,
            kerf: &out.kerf,
            tolerance: 0.001,
            kerf_width: 2.0,
        };
        super::verify(&input, &out.plan)
    }

    #[test]
    fn a_compensated_plan_passes_and_one_on_the_lines_is_flagged() {
        let v = check(Order::Contour);
        assert_eq!(v.overcut_mm2, 0.0, "{v:?}");
        assert_eq!(v.max_overcut_mm, 0.0);
        assert_eq!(v.parts_not_freed, 0);
        // The drawing order cuts on the drawn lines: half the kerf (1 mm) is
        // taken all round the outline (320 mm) and the hole (62.8 mm).
        let v = check(Order::Drawing);
        assert!((v.max_overcut_mm - 1.0).abs() < 0.01, "{v:?}");
        let want = 320.0 + 20.0 * std::f64::consts::PI;
        assert!(
            (v.overcut_mm2 - want).abs() < 0.1 * want,
            "{} vs {want}",
            v.overcut_mm2
        );
        assert_eq!(v.parts_not_freed, 0);
    }
}
