//! Preview: [`Scene`] + [`View`] → RGBA pixels (the preview's own raster,
//! raster.rs and stroke.rs, into a tiny-skia `Pixmap`), the same pixels
//! native, in Node and in the browser.
//!
//! What is drawn is the job's own data: part areas and contour outlines from
//! the contours, and the cutting program from [`crate::plan::CutPlan::moves`] — the very
//! moves the G-code is written from —, so the preview shows the program.
//!
//! | what | look |
//! |---|---|
//! | part area (even-odd: holes empty, islands filled) | fill `#cfe3f7` |
//! | outer contour | `#1f5fa8`, 2 px |
//! | hole | `#e07b00`, 2 px |
//! | open contour (not cut) | `#f2c200`, 3 px |
//! | kerf path (cutting moves on contours) | `#d62828`, 2 px, dashed 6/4 |
//! | lead-in, lead-out | `#1a9e3a`, 1.5 px |
//! | chain link / bridge (torch on through scrap) | `#8b1a1a`, 2 px |
//! | repeated edge (tool down, already cut) | `#7048e8`, 2.5 px, dashed 2/3 |
//! | rapid | `#7a7a7a`, 1 px, dashed 3/3 |
//! | pierce point | `#1a9e3a` dot, r 4 px (down to 1.5 px where they crowd: lod.rs) |
//! | invalid vertex | `#b000b0` dot, r 5 px (smaller where they crowd) |
//! | POINT (spot) | `#6a3d9a` cross, 5 px |
//! | healing fix (duplicate, overlap, gap, zero length) | `#00a0b0` diamond, 4 px |
//! | a router's milling: cleared area, paths per depth, entries | milling.rs's table |
//!
//! Sizes are CSS pixels, multiplied by [`View::pixel_ratio`].
//! The background is opaque white, so premultiplied RGBA equals the straight
//! RGBA that `ImageData` wants.

use tiny_skia::{Color, Pixmap};

mod lod;
pub mod milling;
mod pen;
mod raster;
mod stroke;
mod view;

use pen::{add_segment, cross, diamond, dots, draw_lines, path_of};
use raster::{Area, Raster};
use stroke::Polylines;
pub use view::{View, MAX_SIDE};

use crate::contour::{Contour, ContourKind};
use crate::geom::{BBox, Point, Segment};
use crate::plan::{Move, Role};
use crate::scene::Scene;

/// Above this many contours in sight the preview is an overview (no dashes).
pub const OVERVIEW_CONTOURS: usize = 2000;

/// Renders the job; None when the view is invalid.
pub fn render(out: &Scene, view: &View) -> Option<Pixmap> {
    render_culled(out, view, true)
}

/// [`render`], drawing only what can touch the image when `cull` (always,
/// but for the test that culling changes no pixel).
fn render_culled(out: &Scene, view: &View, cull: bool) -> Option<Pixmap> {
    let k = view.pixel_ratio;
    let view =
        View::new(view.width, view.height, view.center, view.scale)?.with_pixel_ratio(k as f64);
    let mut pixmap = Pixmap::new(view.width, view.height)?;
    pixmap.fill(Color::WHITE);
    // Only what can touch the image is drawn (the widest stroke or dot is
    // under 10 px at pixel ratio 1): a zoomed-in view of a big nest draws
    // few contours.
    let vis = view.visible(12.0 * k as f64);
    let seen = |b: &BBox| !cull || vis.overlaps(b, 0.0);
    let mut contours: Vec<&Contour> = out
        .contours
        .contours
        .iter()
        .filter(|c| seen(&c.bbox))
        .collect();
    // Overview: with thousands of contours in sight, dashes are sub-pixel
    // noise and cost most of the time (25k contours: 2.8 s of 5 s natively),
    // so the torch path, rapids and repeats are drawn solid, told apart by
    // their colours.
    let overview = contours.len() > OVERVIEW_CONTOURS;
    // In an overview, a contour under 3 px across is a speck: it is not
    // drawn, nor its torch path and leads (its pierce dot is). A 31k-part
    // nest fitted in 1200 px has parts of ~6 px and holes of ~2 px.
    let speck = |b: &BBox| {
        overview && (b.max.x - b.min.x).max(b.max.y - b.min.y) * view.scale < 3.0 * k as f64
    };
    let specks: Vec<bool> = if overview {
        out.contours
            .contours
            .iter()
            .map(|c| speck(&c.bbox))
            .collect()
    } else {
        Vec::new()
    };
    // A speck is still shown: a dot in its outline's colour where it is (a
    // nest of 137k contours fitted in the window is all specks, and before
    // its plan there are no pierce dots to show them).
    let speck_dots: Vec<(Point, ContourKind)> = contours
        .iter()
        .filter(|c| c.kind != ContourKind::Hole && speck(&c.bbox))
        .map(|c| (c.bbox.min.add(c.bbox.max).scale(0.5), c.kind))
        .collect();
    contours.retain(|c| !speck(&c.bbox));
    // Everything is drawn by the preview's own raster (raster.rs): an
    // overview's marks are 1 px lines on areas of a few pixels, where
    // tiny-skia's blitter ran its pipeline per span of a pixel or two (1.4 s
    // of the 1.5 s of a 125k-contour nest).
    let mut area = Area::new(view.width, view.height);
    let mut raster = Raster::new(&mut pixmap);

    // Part areas: every closed contour in one even-odd path.
    let mut fill = Polylines::default();
    for c in contours.iter().filter(|c| c.is_closed()) {
        path_of(&view, &c.segments, true, &mut fill);
    }
    raster.paint(&mut area, 0xcfe3f7, true, &|a| {
        for pl in fill.each() {
            a.polygon(pl);
        }
    });
    for (kind, hex) in [
        (ContourKind::Outer, 0x1f5fa8),
        (ContourKind::Open, 0xf2c200),
    ] {
        let at: Vec<Point> = speck_dots
            .iter()
            .filter(|(_, k)| *k == kind)
            .map(|(p, _)| *p)
            .collect();
        dots(&mut raster, &view, &at, k, hex);
    }
    // Outlines, then the program from the plan's moves: one path per look,
    // drawn in this order (later over earlier).
    let mut looks: Vec<Look> = [
        (0x1f5fa8, 2.0, None),
        (0xe07b00, 2.0, None),
        (0xf2c200, 3.0, None),
        // Rapids.
        (0x7a7a7a, 1.0, Some([3.0, 3.0])),
        // Contour, lead (in and out), link, repeat, mark, tab.
        (0xd62828, 2.0, Some([6.0, 4.0])),
        (0x1a9e3a, 1.5, None),
        (0x8b1a1a, 2.0, None),
        (0x7048e8, 2.5, Some([2.0, 3.0])),
        // Marks (scribe): teal, dotted, on the drawn line.
        (0x00897b, 2.0, Some([1.5, 2.5])),
        // Tabs: a wide amber bar over the stretch left uncut.
        (0xf08c00, 5.0, None),
    ]
    .into_iter()
    .map(|(hex, width, dash)| Look {
        hex,
        // An overview: 1 device pixel, solid (dashes are sub-pixel noise there).
        width: if overview { 1.0 } else { width * k },
        dash: dash.filter(|_| !overview).map(|d| d.map(|v| v * k)),
        lines: Polylines::default(),
    })
    .collect();
    // A router's milling, under the profiles: cleared area, paths per
    // depth, entries; its plunges dotted as pierces, its rapids as rapids.
    // The program's rapids when the scene has them (a router's relift
    // between depth passes: [`Scene::rapids`]), else the plan's and the
    // milling's own below.
    let mut program_rapids = Polylines::default();
    let rapid_lines = |pb: &mut Polylines, at: Point, p: Point| {
        let line = Segment::line(at, p);
        if seen(&line.bbox()) && !(overview && line.length() * view.scale < k as f64) {
            let (x0, y0) = view.px(at);
            let (x1, y1) = view.px(p);
            pb.move_to(x0, y0);
            pb.line_to(x1, y1);
        }
    };
    for r in out.rapids.unwrap_or_default() {
        rapid_lines(&mut looks[3].lines, r.a, r.b);
    }
    let mut pierces = Vec::new();
    if let Some(m) = &out.milling {
        let rapids = if out.rapids.is_some() {
            &mut program_rapids
        } else {
            &mut looks[3].lines
        };
        pierces = milling::draw(&mut raster, &mut area, &view, m, k, &seen, rapids);
    }
    for (i, kind) in [ContourKind::Outer, ContourKind::Hole, ContourKind::Open]
        .into_iter()
        .enumerate()
    {
        for c in contours.iter().filter(|c| c.kind == kind) {
            path_of(
                &view,
                &c.segments,
                kind != ContourKind::Open,
                &mut looks[i].lines,
            );
        }
    }
    let mut spotted = Vec::new();
    let mut at = out.plan.origin;
    for m in out.plan.moves() {
        match m {
            Move::Rapid(p) => {
                if out.rapids.is_none() {
                    rapid_lines(&mut looks[3].lines, at, p);
                }
                at = p;
            }
            Move::Pierce(_) => pierces.push(at),
            Move::Feed(s)
                if !seen(&reach(&s.segment))
                    || s.contour.is_some_and(|c| specks.get(c) == Some(&true)) =>
            {
                at = s.segment.b
            }
            Move::Feed(s) => {
                let pb = &mut looks[match s.role {
                    Role::Contour => 4,
                    Role::LeadIn | Role::LeadOut => 5,
                    Role::Link => 6,
                    Role::Repeat => 7,
                    Role::Mark => 8,
                    Role::Tab => 9,
                }]
                .lines;
                let (x, y) = view.px(s.segment.a);
                pb.move_to(x, y);
                add_segment(pb, &view, &s.segment);
                at = s.segment.b;
            }
            Move::Spot(_) => spotted.push(at),
            Move::TorchOff => {}
        }
    }
    for look in &looks {
        draw_lines(
            &mut raster,
            &mut area,
            &look.lines,
            look.hex,
            look.width,
            look.dash,
        );
    }
    pierces.retain(|p| seen(&BBox::at(*p)));
    // In an overview, dots as big as a part would hide the parts; elsewhere
    // dots that crowd are drawn smaller (lod.rs), never dropped.
    let small = |r: f32, at: &[Point]| {
        if overview {
            r.min(1.0) * k
        } else {
            let px: Vec<(f32, f32)> = at.iter().map(|p| view.px(*p)).collect();
            lod::dot_radius(&px, r * k, 1.5 * k) // 3 px across: still seen
        }
    };
    dots(&mut raster, &view, &pierces, small(4.0, &pierces), 0x1a9e3a);
    for s in out.file.spots {
        cross(&mut raster, &mut area, &view, s.at, 5.0 * k, 0x6a3d9a);
    }
    // Centre-spots of spot layers and of holes too small to cut.
    for p in spotted
        .iter()
        .filter(|p| !out.file.spots.iter().any(|s| s.at == **p))
    {
        cross(&mut raster, &mut area, &view, *p, 5.0 * k, 0x6a3d9a);
    }
    for (_, p) in &out.contours.healing.locations {
        diamond(&mut raster, &mut area, &view, *p, 4.0 * k, 0x00a0b0);
    }
    let invalid: Vec<Point> = out
        .invalid_vertices
        .iter()
        .copied()
        .filter(|p| seen(&BBox::at(*p)))
        .collect();
    dots(&mut raster, &view, &invalid, small(5.0, &invalid), 0xb000b0);
    Some(pixmap)
}

/// One look of the preview (colour, width and dash in device pixels) and
/// what is drawn with it.
struct Look {
    hex: u32,
    width: f32,
    dash: Option<[f32; 2]>,
    lines: Polylines,
}

/// Box holding everything the preview draws (contours, kerf paths, origin).
pub fn extent(out: &Scene) -> BBox {
    let mut bb = out.milling.as_ref().map_or(BBox::EMPTY, milling::extent);
    for c in &out.contours.contours {
        bb.union(&c.bbox);
    }
    for c in &out.plan.cuts {
        for s in &c.steps {
            // Most of the plan lies within the contours' box: the exact box
            // of an arc (trigonometry) only for what may reach beyond it
            // (the page's box of a 125k-contour nest: 58 -> 12 ms natively).
            if !bb.contains_box(&reach(&s.segment), 0.0) {
                bb.union(&s.segment.bbox());
            }
        }
    }
    bb
}

/// A box that holds the segment, without trigonometry: its ends' box,
/// grown for an arc (at most half a turn) by |bulge| × chord: twice its
/// sagitta, the most it bulges from its chord.
fn reach(s: &Segment) -> BBox {
    let mut bb = BBox::at(s.a);
    bb.add(s.b);
    if !s.is_line() {
        let g = s.bulge.abs() * s.a.dist(s.b);
        bb.min = Point::new(bb.min.x - g, bb.min.y - g);
        bb.max = Point::new(bb.max.x + g, bb.max.y + g);
    }
    bb
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{run, Settings};

    const PLATE: &[u8] = include_bytes!("../../shared/fixtures/seed000-plate-6-holes.dxf");

    #[test]
    fn the_quick_box_of_a_segment_holds_its_exact_box() {
        for bulge in [0.0, 0.05, -0.3, 0.7, 1.0, -1.0] {
            for (a, b) in [((0.0, 0.0), (10.0, 0.0)), ((3.0, -2.0), (-1.0, 5.0))] {
                let (a, b) = (Point::new(a.0, a.1), Point::new(b.0, b.1));
                let s = Segment { a, b, bulge };
                assert!(
                    reach(&s).contains_box(&s.bbox(), 1e-9),
                    "bulge {bulge}: {:?} in {:?}",
                    s.bbox(),
                    reach(&s)
                );
            }
        }
    }

    #[test]
    fn culling_changes_almost_no_pixel_at_any_zoom() {
        let out = run(PLATE, &Settings::new(2.0, 0.001, 2000.0).unwrap()).unwrap();
        for (cx, cy, scale) in [
            (100.0, 60.0, 4.0),
            (30.0, 30.0, 20.0),
            (0.0, 0.0, 12.0),
            (200.0, 120.0, 60.0),
        ] {
            for ratio in [1.0, 2.0] {
                let view = View::new(300, 200, Point::new(cx, cy), scale)
                    .unwrap()
                    .with_pixel_ratio(ratio);
                let culled = render_culled(&out.scene(), &view, true).unwrap();
                let all = render_culled(&out.scene(), &view, false).unwrap();
                let diff: Vec<u8> = culled
                    .data()
                    .iter()
                    .zip(all.data())
                    .map(|(a, b)| a.abs_diff(*b))
                    .collect();
                let n = diff.iter().filter(|d| **d > 0).count();
                let max = diff.iter().max().unwrap();
                // A smaller path gives tiny-skia smaller working bounds, which can
                // round the anti-aliasing of a few pixels where strokes overlap
                // differently (seen: 5 pixels of 60 000); nothing more may change.
                assert!(
                    n <= diff.len() / 1000,
                    "view at ({cx}, {cy}) ×{scale} ratio {ratio}: {n} bytes differ, max {max}"
                );
            }
        }
    }

    #[test]
    fn crowded_pierces_are_drawn_smaller_not_dropped() {
        // 35 × 35 small circles 1.5 mm apart fitted in 250 px: pierces ~7 px apart, where
        // full-size dots (r 4 px) would merge into one green mass (issue 19 item 2).
        let mut dxf = String::from("0\nSECTION\n2\nENTITIES\n");
        for i in 0..35 {
            for j in 0..35 {
                dxf += &format!(
                    "0\nCIRCLE\n10\n{}\n20\n{}\n40\n0.4\n",
                    i as f64 * 1.5,
                    j as f64 * 1.5
                );
            }
        }
        dxf += "0\nENDSEC\n0\nEOF\n";
        let out = run(dxf.as_bytes(), &Settings::new(0.2, 0.001, 2000.0).unwrap()).unwrap();
        let n = out
            .plan
            .moves()
            .filter(|m| matches!(m, Move::Pierce(_)))
            .count();
        assert_eq!(n, 35 * 35);
        let green = |p: &Pixmap| {
            p.pixels()
                .iter()
                .filter(|c| (c.red(), c.green(), c.blue()) == (0x1a, 0x9e, 0x3a))
                .count()
        };
        let fitted = render(
            &out.scene(),
            &View::fit(&extent(&out.scene()), 250, 250).unwrap(),
        )
        .unwrap();
        let g = green(&fitted);
        // Neighbouring circles' lead-ins face each other (pierces ~2 px apart): the dots
        // shrink to the smallest size, at most ~20 solid pixels each (a full dot has ~50).
        assert!(g <= n * 20, "{g} pierce pixels for {n} pierces");
        assert!(g >= n * 3, "{g} pierce pixels: the dots are still drawn");
        // Zoomed in on a few, full size again (r 4 px: ~38 pixels of solid colour each).
        let near = View::new(250, 250, Point::new(25.0, 25.0), 60.0).unwrap();
        let mut at = out.plan.origin;
        let mut in_sight = 0;
        for m in out.plan.moves() {
            match m {
                Move::Rapid(p) => at = p,
                Move::Feed(s) => at = s.segment.b,
                Move::Pierce(_) => {
                    let (x, y) = near.px(at);
                    in_sight += usize::from((5.0..245.0).contains(&x) && (5.0..245.0).contains(&y));
                }
                _ => {}
            }
        }
        assert!(in_sight >= 4, "{in_sight} pierces in sight");
        let zoomed = green(&render(&out.scene(), &near).unwrap());
        assert!(
            zoomed >= in_sight * 30,
            "{zoomed} pierce pixels for {in_sight} pierces near"
        );
    }

    #[test]
    fn thousands_of_contours_in_sight_draw_an_overview_with_small_dots() {
        // 50 × 50 circles (2500 contours): an overview; zoomed in on a few, the full look.
        let mut dxf = String::from("0\nSECTION\n2\nENTITIES\n");
        for i in 0..50 {
            for j in 0..50 {
                dxf += &format!("0\nCIRCLE\n10\n{}\n20\n{}\n40\n4\n", i * 20, j * 20);
            }
        }
        dxf += "0\nENDSEC\n0\nEOF\n";
        let out = run(dxf.as_bytes(), &Settings::new(1.0, 0.001, 2000.0).unwrap()).unwrap();
        let pierce = |p: &Pixmap| {
            p.pixels()
                .iter()
                .filter(|c| (c.red(), c.green(), c.blue()) == (0x1a, 0x9e, 0x3a))
                .count()
        };
        let whole = View::fit(&extent(&out.scene()), 600, 600).unwrap();
        let near = View::new(600, 600, Point::new(490.0, 490.0), 15.0).unwrap();
        let (a, b) = (
            render(&out.scene(), &whole).unwrap(),
            render(&out.scene(), &near).unwrap(),
        );
        // Whole: 2500 dots of radius 2 px, at most ~13 px of solid colour each.
        assert!(pierce(&a) < 2500 * 14, "{} pierce pixels", pierce(&a));
        // Near: ~9 circles in sight, dots of radius 4 px (~40 solid pixels each).
        assert!(pierce(&b) > 4 * 30, "{} pierce pixels", pierce(&b));
    }
}
