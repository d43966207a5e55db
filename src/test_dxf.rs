//! The unit tests' drawings: closed outlines as DXF LWPOLYLINEs on layer
//! 0, in a file whose units are mm ($INSUNITS 4), so that tests of any
//! stage build their input one way.

/// One closed LWPOLYLINE through `pts`, mm.
pub(crate) fn outline(pts: &[(f64, f64)]) -> String {
    let mut e = format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", pts.len());
    for (x, y) in pts {
        e.push_str(&format!("10\n{x}\n20\n{y}\n"));
    }
    e
}

/// The closed rectangle `(x, y)` to `(x + w, y + h)`, counter-clockwise.
pub(crate) fn rect(x: f64, y: f64, w: f64, h: f64) -> String {
    outline(&[(x, y), (x + w, y), (x + w, y + h), (x, y + h)])
}

/// A DXF file in mm with `entities` as its ENTITIES section.
pub(crate) fn file(entities: &str) -> Vec<u8> {
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n")
        .into_bytes()
}
