//! The preview of a router job (issue 43 §6) is its program: the cleared
//! area and the tool paths per depth drawn from the milling toolpath the
//! router post writes. A pocket (a 60 × 40 rectangle around a round
//! island of R 8) cut 6 mm deep in 3 passes, with a 6 mm tool ramping in,
//! and a square profiled beside it. `BLESS=1` rewrites the golden image
//! (tests/golden/pocket-island-ramp.png): look at it before committing.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use kerfcam::geom::Point;
use kerfcam::mill::MillMove;
use kerfcam::preview::milling::{depth_colour, CLEARED};
use kerfcam::preview::{self, View};
use kerfcam::scene::Scene;
use kerfcam::{Output, Spec};
use std::path::PathBuf;
use tiny_skia::Pixmap;

const R: f64 = 3.0;

fn job(profile: bool) -> Output {
    let settings = Spec {
        tool_diameter: Some(2.0 * R),
        depth: Some(6.0),
        pass_depth: 2.0,
        entry: "ramp".into(),
        post: Some("grbl-router".into()),
        layer_ops: vec![
            ["POCKET".into(), "pocket".into()],
            ["PROFILE".into(), "profile".into()],
        ],
        ..Spec::default()
    }
    .build()
    .unwrap();
    kerfcam::run(&common::pocket_island_dxf(profile), &settings).unwrap()
}

/// Pixel of a drawing point in `v` (as the preview maps it).
fn px(v: &View, p: Point) -> (u32, u32) {
    let x = (p.x - v.center.x) * v.scale + v.width as f64 / 2.0;
    let y = v.height as f64 / 2.0 - (p.y - v.center.y) * v.scale;
    (x.floor() as u32, y.floor() as u32)
}

fn rgb(img: &Pixmap, (x, y): (u32, u32)) -> u32 {
    let c = img.pixel(x, y).unwrap();
    (u32::from(c.red()) << 16) | (u32::from(c.green()) << 8) | u32::from(c.blue())
}

fn luma(hex: u32) -> f64 {
    0.299 * f64::from((hex >> 16) & 0xff)
        + 0.587 * f64::from((hex >> 8) & 0xff)
        + 0.114 * f64::from(hex & 0xff)
}

/// Every cut of the toolpath below the top, each as `(a, b, z)`
/// sampled every `step` mm along it (arcs by their own parameter).
fn cut_samples(out: &Output, step: f64) -> Vec<(Point, f64, Point)> {
    let mut v = Vec::new();
    for m in &out.milled.as_ref().unwrap().toolpath.moves {
        if let MillMove::Cut { seg, z } = m {
            if *z >= 0.0 {
                continue;
            }
            let n = (seg.length() / step).ceil().max(1.0) as usize;
            for k in 0..=n {
                let t = k as f64 / n as f64;
                let p = seg.point_at(t);
                // The direction of travel there, for the cleared band's sides.
                let q = seg.point_at((t + 1e-4).min(1.0));
                let o = seg.point_at((t - 1e-4).max(0.0));
                v.push((p, *z, Point::new(q.x - o.x, q.y - o.y)));
            }
        }
    }
    v
}

#[test]
fn a_pocket_is_previewed_with_its_cleared_area_and_every_milled_move() {
    let out = job(false);
    let scene = out.scene();
    let view = View::fit(&preview::extent(&scene), 480, 320).unwrap();
    let milled = preview::render(&scene, &view).unwrap();
    // The same job without its milling drawn: what the preview showed before.
    let cutting_only = preview::render(
        &Scene {
            milling: None,
            ..scene
        },
        &view,
    )
    .unwrap();
    let n = 3;
    let ink: Vec<u32> = (0..n)
        .map(|i| depth_colour(i, n))
        .chain([CLEARED])
        .collect();
    // Inside the pocket's box, off the island.
    let inside = |img: &Pixmap| {
        let (mut count, mut cleared) = (0, 0);
        for x in 0..60 {
            for y in 0..40 {
                let p = Point::new(x as f64 + 0.5, y as f64 + 0.5);
                if p.dist(Point::new(30.0, 20.0)) < 9.0 {
                    continue;
                }
                let c = rgb(img, px(&view, p));
                // A path's pixel: as dark as the first depth's colour or
                // darker (edges are anti-aliased, centres exact).
                count += usize::from(luma(c) <= luma(ink[0]) + 5.0);
                cleared += usize::from(c == CLEARED);
            }
        }
        (count, cleared)
    };
    let (paths, cleared) = inside(&milled);
    assert_eq!(
        inside(&cutting_only),
        (0, 0),
        "nothing milled drawn without the milling"
    );
    eprintln!("pocket preview: {paths} of 2400 mm points on a depth's path, {cleared} cleared");
    assert!(paths > 200, "{paths} points of the pocket on a tool path");
    assert!(cleared > 200, "{cleared} points of the pocket cleared");
    // Every milled move is drawn where the program moves: the pixel under
    // each point of it is a path's (darker than the cleared area), and
    // four fifths of a radius to either side the tool's disc cleared it.
    let (mut missing, mut bare) = (Vec::new(), Vec::new());
    let samples = cut_samples(&out, 0.5);
    for &(p, z, d) in &samples {
        let c = rgb(&milled, px(&view, p));
        if luma(c) >= luma(CLEARED) - 15.0 {
            missing.push((p, z, c));
        }
        let l = d.x.hypot(d.y);
        if l > 0.0 {
            for side in [-1.0, 1.0] {
                let s = Point::new(
                    p.x - side * d.y / l * 0.8 * R,
                    p.y + side * d.x / l * 0.8 * R,
                );
                if rgb(&milled, px(&view, s)) == 0xffffff {
                    bare.push(s);
                }
            }
        }
    }
    assert!(samples.len() > 1000, "{} samples", samples.len());
    assert!(
        missing.is_empty(),
        "{} of {} points of milled moves not drawn, e.g. {:?}",
        missing.len(),
        samples.len(),
        &missing[..missing.len().min(5)]
    );
    assert!(
        bare.is_empty(),
        "{} points beside the tool's path not cleared, e.g. {:?}",
        bare.len(),
        &bare[..bare.len().min(5)]
    );
    // The deepest pass is drawn over the ones above it, in its own colour.
    let deepest = milled
        .pixels()
        .iter()
        .filter(|c| {
            (u32::from(c.red()) << 16) | (u32::from(c.green()) << 8) | u32::from(c.blue())
                == depth_colour(n - 1, n)
        })
        .count();
    assert!(deepest > 500, "{deepest} pixels of the deepest pass");
}

#[test]
fn pocket_preview_matches_its_golden_image() {
    let out = job(true);
    let view = View::fit(&preview::extent(&out.scene()), 480, 300).unwrap();
    let pixmap = preview::render(&out.scene(), &view).unwrap();
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/golden/pocket-island-ramp.png");
    if std::env::var("BLESS").as_deref() == Ok("1") {
        pixmap.save_png(&path).unwrap();
        return;
    }
    let want = Pixmap::load_png(&path).expect("golden PNG missing: run with BLESS=1");
    let differing = (want.data().chunks(4))
        .zip(pixmap.data().chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    if differing != 0 {
        pixmap
            .save_png(common::out_dir().join("pocket-island-ramp.png"))
            .unwrap();
    }
    assert_eq!(
        differing, 0,
        "pixels differ from the golden image (new one in tests/out)"
    );
}
