//! Tests of `backplot`.

use super::*;
use crate::gcode::backplot_web_json;

#[test]
fn backplot_web_json_as_json_wrote_it() {
    let b = backplot("G0 X1 Y2\nG1 X3 Y4 F100\nG2 X5 Y6 I1 J0\n? \"é\\\nQ1\nG1 X1e999\n");
    assert!(!b.warnings.is_empty());
    let moves = vec![0.0, 1.5, -2.25, 1e-7, f64::NAN, 3.0, 1e300];
    let bbox = [0.0, -1.0, 2.5, 1e21];
    let want =
        serde_json::json!({ "moves": moves, "warnings": b.warnings, "bbox": bbox }).to_string();
    assert_eq!(backplot_web_json(&moves, &b.warnings, bbox), want);
}

#[test]
fn reads_our_dialects() {
    let bp = backplot(
        "%\n(c)\nG21 G90 G91.1\nF100\nG0 X10 Y0\nM3 $0 S1\nG3 X-10 Y0 I-10 J0 ; half\nG1 Y5\nM5\nG20\nG1 X1\nM2\n%\n",
    );
    assert!(bp.warnings.is_empty(), "{:?}", bp.warnings);
    assert_eq!(bp.moves.len(), 4);
    match bp.moves[1] {
        BackplotMove::Arc {
            center, ccw, torch, ..
        } => {
            assert_eq!(center, Point::new(0.0, 0.0));
            assert!(ccw && torch);
        }
        m => panic!("{m:?}"),
    }
    match bp.moves[3] {
        BackplotMove::Line { to, torch, .. } => {
            assert_eq!(to, Point::new(25.4, 5.0));
            assert!(!torch);
        }
        m => panic!("{m:?}"),
    }
}

#[test]
fn annex_h_framing_and_r_arcs() {
    let bp = backplot("#\n: N10G90$\n$ PECA\n: N42G1X10Y0F1000$\n: CYC10PRAQUECIMENTOTEMPO1000$\n: N44G2X0Y-10R10$\n");
    assert_eq!(bp.moves.len(), 2);
    assert_eq!(bp.warnings.len(), 1);
    if let BackplotMove::Arc { center, .. } = bp.moves[1] {
        assert!(center.dist(Point::new(0.0, 0.0)) < 1e-9, "{center:?}");
    } else {
        panic!()
    }
}

#[test]
fn never_panics_on_any_text() {
    let mut x: u32 = 12345;
    let alphabet = b"GXYIJRM0123456789.-+ ()%;$:#\n\tNFe";
    for _ in 0..300 {
        let s: String = (0..200)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                alphabet[(x as usize) % alphabet.len()] as char
            })
            .collect();
        let _ = backplot(&s);
    }
    let _ = backplot("G1 X1e400 Y\u{e9}\u{0}(((");
}
