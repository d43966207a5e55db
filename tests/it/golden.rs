//! Golden files: the G-code and the preview of the fixtures, compared
//! exactly. `BLESS=1 cargo test --test it golden::` rewrites them; review the
//! diff (and look at the PNGs) before committing. A mismatch leaves the new
//! output in `tests/out/` for comparison.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::path::PathBuf;

use common::{fixture, kerf, out_dir, run};
use kerfcam::kerf::Join;
use kerfcam::preview::{self, View};
use kerfcam::Settings;
use tiny_skia::Pixmap;

fn golden_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("golden")
}

fn bless() -> bool {
    std::env::var("BLESS").as_deref() == Ok("1")
}

fn cases() -> Vec<(&'static str, &'static str, Settings)> {
    vec![
        ("plate-6-holes-k2", "seed000-plate-6-holes.dxf", kerf(2.0)),
        ("figure1-k0", "seed000-figure1.dxf", kerf(0.0)),
        (
            "p51703-k3-miter",
            "seed001-P51703.dxf",
            kerf(3.0).with_join(Join::Miter),
        ),
        ("figure4-k0", "seed002-figure4.dxf", kerf(0.0)),
        ("grid-3x2-k1.5", "seed003-grid-3x2.dxf", kerf(1.5)),
    ]
}

#[test]
fn fixture_programs_match_their_golden_files() {
    let mut changed = Vec::new();
    for (name, file, settings) in cases() {
        let out = run(&fixture(file), &settings).unwrap();
        let path = golden_dir().join(format!("{name}.ngc"));
        if bless() {
            std::fs::create_dir_all(golden_dir()).unwrap();
            std::fs::write(&path, &out.gcode).unwrap();
            continue;
        }
        let want = std::fs::read_to_string(&path).unwrap_or_default();
        if want != out.gcode {
            std::fs::write(out_dir().join(format!("{name}.ngc")), &out.gcode).unwrap();
            changed.push(name);
        }
    }
    assert!(
        changed.is_empty(),
        "programs differ from tests/golden (new ones in tests/out): {changed:?}"
    );
}

#[test]
fn plate_preview_matches_its_golden_image() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    let view = View::fit(&preview::extent(&out.scene()), 480, 300).unwrap();
    let pixmap = preview::render(&out.scene(), &view).unwrap();
    let path = golden_dir().join("plate-6-holes-k2.png");
    if bless() {
        std::fs::create_dir_all(golden_dir()).unwrap();
        pixmap.save_png(&path).unwrap();
        return;
    }
    let want = Pixmap::load_png(&path).expect("golden PNG missing: run with BLESS=1");
    let differing = want
        .data()
        .chunks(4)
        .zip(pixmap.data().chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    if differing != 0 {
        pixmap
            .save_png(out_dir().join("plate-6-holes-k2.png"))
            .unwrap();
    }
    assert_eq!(
        differing, 0,
        "pixels differ from the golden image (new one in tests/out)"
    );
}

#[test]
fn preview_shows_each_element_in_its_colour() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    let view = View::fit(&preview::extent(&out.scene()), 480, 300).unwrap();
    let pixmap = preview::render(&out.scene(), &view).unwrap();
    let count = |rgb: u32| {
        let [r, g, b] = [(rgb >> 16) as u8, (rgb >> 8) as u8, rgb as u8];
        pixmap
            .data()
            .chunks(4)
            .filter(|p| p[0] == r && p[1] == g && p[2] == b)
            .count()
    };
    for (what, rgb, min) in [
        ("part fill", 0xcfe3f7, 20_000),
        ("outer outline", 0x1f5fa8, 100),
        ("hole outline", 0xe07b00, 100),
        ("kerf path", 0xd62828, 100),
        ("pierce points", 0x1a9e3a, 7 * 20),
        ("invalid vertices", 0xb000b0, 4 * 30),
    ] {
        let n = count(rgb);
        assert!(
            n >= min,
            "{what}: {n} pixels of #{rgb:06x}, expected at least {min}"
        );
    }
    // The centre of the slot hole is empty (white), not part fill.
    let (cx, cy) = (
        ((100.0 - view.center.x) * view.scale + 240.0) as u32,
        (150.0 - (60.0 - view.center.y) * view.scale) as u32,
    );
    let px = pixmap.pixel(cx, cy).unwrap();
    assert_eq!((px.red(), px.green(), px.blue()), (255, 255, 255));
}
