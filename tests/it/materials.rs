//! Cut charts on the command line (issue 20 §1): `--materials` reads a
//! LinuxCNC QtPlasmaC material file or kerfcam's JSON, `--material` sets
//! kerf, feed and pierce delay, and the program (read back by rs274) says so.

use crate::common;

use common::{fixture, out_dir, rs274_errors};

fn kerfcam(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .args(args)
        .output()
        .unwrap()
}

const QTPLASMAC: &str = "# plasmac material file\n[MATERIAL_NUMBER_3]\nNAME               = Mild 4mm 65A\n\
KERF_WIDTH         = 1.7\nPIERCE_HEIGHT      = 4\nPIERCE_DELAY       = 0.5\nCUT_HEIGHT         = 1.5\n\
CUT_SPEED          = 2700\nCUT_AMPS           = 65\n\n";

#[test]
fn a_qtplasmac_material_sets_kerf_feed_and_pierce_delay() {
    let chart = out_dir().join("materials-test_material.cfg");
    std::fs::write(&chart, QTPLASMAC).unwrap();
    let plate = fixture("seed000-plate-6-holes.dxf");
    let out = kerfcam(&[
        plate.to_str().unwrap(),
        "--materials",
        chart.to_str().unwrap(),
        "--material",
        "mild 4MM 65a",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let program = String::from_utf8(out.stdout).unwrap();
    assert!(
        program.contains("kerf 1.7 mm, feed 2700 mm/min"),
        "{program}"
    );
    assert!(program.contains("F2700"));
    assert!(program.contains("G4 P0.5"), "the pierce delay dwells");
    assert_eq!(
        rs274_errors(&program, "material-qtplasmac"),
        Vec::<String>::new()
    );
    // The same job with an explicit feed: the command line wins.
    let out = kerfcam(&[
        plate.to_str().unwrap(),
        "--materials",
        chart.to_str().unwrap(),
        "--material",
        "Mild 4mm 65A",
        "--feed",
        "1000",
    ]);
    let program = String::from_utf8(out.stdout).unwrap();
    assert!(
        program.contains("kerf 1.7 mm, feed 1000 mm/min"),
        "{program}"
    );
    // With QtPlasmaC's post the controller is told the file's material
    // number, [MATERIAL_NUMBER_3].
    let out = kerfcam(&[
        plate.to_str().unwrap(),
        "--materials",
        chart.to_str().unwrap(),
        "--material",
        "Mild 4mm 65A",
        "--post",
        "qtplasmac",
    ]);
    let program = String::from_utf8(out.stdout).unwrap();
    assert!(program.contains("M190 P3"), "{program}");
}

#[test]
fn unknown_materials_and_broken_charts_are_clear_errors() {
    let plate = fixture("seed000-plate-6-holes.dxf");
    let out = kerfcam(&[plate.to_str().unwrap(), "--material", "Unobtainium"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("material 'Unobtainium': no such material"),
        "{err}"
    );
    let chart = out_dir().join("materials-broken_material.cfg");
    std::fs::write(
        &chart,
        "[MATERIAL_NUMBER_1]\nNAME = A\nPIERCE_HEIGHT = 3\nPIERCE_DELAY = 0\nCUT_HEIGHT = 1\n",
    )
    .unwrap();
    let out = kerfcam(&[
        plate.to_str().unwrap(),
        "--materials",
        chart.to_str().unwrap(),
        "--material",
        "A",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("material 'A', CUT_SPEED: missing"), "{err}");
}
