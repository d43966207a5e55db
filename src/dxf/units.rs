//! Drawing units: `$INSUNITS` (DXF reference, HEADER section, group 70) and
//! the factor that scales them to millimetres.

use serde::Serialize;

use crate::geom::BBox;
use crate::text;
use crate::warning::{Text, Warning};

/// The unit the drawing's coordinates were written in.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Units {
    /// Name as reported ("mm", "in", …).
    pub name: &'static str,
    /// Millimetres per drawing unit.
    pub to_mm: f64,
}

impl Units {
    /// Millimetres, the default for an unset or unitless `$INSUNITS`.
    pub const MM: Units = Units {
        name: "mm",
        to_mm: 1.0,
    };
    /// Inches.
    pub const INCH: Units = Units {
        name: "in",
        to_mm: 25.4,
    };

    /// The CSS px, 96 per inch (an SVG's px and unitless lengths).
    pub const PX: Units = Units {
        name: "px",
        to_mm: 25.4 / 96.0,
    };
    /// The px at 72 per inch (Illustrator's legacy reading of an SVG).
    pub const PX72: Units = Units {
        name: "px72",
        to_mm: 25.4 / 72.0,
    };

    /// A unit by its name (as given on the command line): mm, cm, m, in,
    /// ft, …, and px (96 per inch) and px72 (72 per inch) for SVG files.
    pub fn from_name(name: &str) -> Option<Units> {
        match name {
            "px" => return Some(Units::PX),
            "px72" => return Some(Units::PX72),
            _ => {}
        }
        let name = if name == "inch" { "in" } else { name };
        (1..=16)
            .filter_map(Units::from_insunits)
            .find(|u| u.name == name)
    }

    /// The unit of an `$INSUNITS` code, or None for codes that are not
    /// lengths we can scale (0 = unitless is handled by the caller).
    pub fn from_insunits(code: i64) -> Option<Units> {
        let (name, to_mm) = match code {
            1 => ("in", 25.4),
            2 => ("ft", 304.8),
            3 => ("mi", 1_609_344.0),
            4 => ("mm", 1.0),
            5 => ("cm", 10.0),
            6 => ("m", 1000.0),
            7 => ("km", 1e6),
            8 => ("µin", 25.4e-6),
            9 => ("mil", 0.0254),
            10 => ("yd", 914.4),
            11 => ("Å", 1e-7),
            12 => ("nm", 1e-6),
            13 => ("µm", 1e-3),
            14 => ("dm", 100.0),
            15 => ("dam", 1e4),
            16 => ("hm", 1e5),
            _ => return None,
        };
        Some(Units { name, to_mm })
    }
}

/// Largest side, mm, below which a drawing read as millimetres is too small
/// to be the cutting job it claims (a whole drawing under a centimetre
/// across): when the file does not state its units, such a drawing is read
/// as inches. Whole drawings for a cutting table are parts of centimetres to
/// metres; a part drawn in inches reads, taken as mm, 25.4 × too small — a
/// 6 × 4 in bracket becomes 6 × 4 mm. Between 10 mm and a sheet both
/// readings are possible and millimetres wins (the world's default and every
/// metric writer's), always with a `units-assumed` warning showing both
/// sizes, and the unit one click away. Over the corpus this reads as inches
/// only drawings of 1–3 units across (a slide plate of 1.6 × 2.2 units,
/// OpenSCAD's 1 × 1 test shape, a point-cloud outline), and as mm every file
/// whose size is known (the 80 mm fan grille, the NEMA 23 mount, DRAAK).
pub const INCH_IF_MM_SIDE_BELOW: f64 = 10.0;

/// Why a unit was assumed for a file that does not state it by `$INSUNITS`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Evidence {
    /// `$MEASUREMENT = 1` (metric).
    MeasurementMetric,
    /// The drawing read as mm is under [`INCH_IF_MM_SIDE_BELOW`] across,
    /// while in inches it is a normal part.
    TooSmallForMm,
    /// Nothing points to inches: the default (mm).
    Default,
}

/// The unit to assume for a file without `$INSUNITS`, from `$MEASUREMENT`
/// (0 imperial, 1 metric) and the largest side of the drawing read as mm.
///
/// `$MEASUREMENT` only tells which hatch-pattern and linetype files the CAD
/// program uses, and many programs write 0 whatever the drawing's units
/// (KiCad, AutoCAD's imperial templates): 0 is no evidence of inches.
pub fn assume(measurement: Option<i64>, side_as_mm: f64) -> (Units, Evidence) {
    if measurement == Some(1) {
        (Units::MM, Evidence::MeasurementMetric)
    } else if side_as_mm > 0.0 && side_as_mm < INCH_IF_MM_SIDE_BELOW {
        (Units::INCH, Evidence::TooSmallForMm)
    } else {
        (Units::MM, Evidence::Default)
    }
}

/// A size "134 × 92 mm" or "3.40 × 2.34 m", in every language (decimal comma in Portuguese).
pub fn size_text(w: f64, h: f64) -> Text {
    let (scale, unit) = if w.max(h) >= 1000.0 {
        (1e-3, "m")
    } else {
        (1.0, "mm")
    };
    let one = |v: f64| {
        let v = v * scale;
        let decimals = if unit == "m" || v < 10.0 {
            2
        } else if v < 100.0 {
            1
        } else {
            0
        };
        let s = format!("{v:.decimals$}");
        // "92.0" reads better as "92"; "0.50 m" keeps its width.
        match s.strip_suffix(".0") {
            Some(whole) if unit == "mm" => whole.to_owned(),
            _ => s,
        }
    };
    let (a, b) = (one(w), one(h));
    text!("{a} × {b} {unit}"; "{} × {} {unit}", a.replace('.', ","), b.replace('.', ","))
}

/// The `units-assumed` warning: the unit taken, the evidence, and the
/// drawing's size in both readings (`as_mm`: its box read as mm).
pub fn assumed_warning(evidence: Evidence, measurement: Option<i64>, as_mm: &BBox) -> Warning {
    let (w, h) = if as_mm.is_empty() {
        (0.0, 0.0)
    } else {
        (as_mm.max.x - as_mm.min.x, as_mm.max.y - as_mm.min.y)
    };
    let mm = size_text(w, h);
    let inch = size_text(w * 25.4, h * 25.4);
    let meas = match measurement {
        Some(m) => text!("$MEASUREMENT = {m}"; "$MEASUREMENT = {m}"),
        None => text!("no $MEASUREMENT"; "sem $MEASUREMENT"),
    };
    let t = match evidence {
        Evidence::MeasurementMetric => text!(
            "units assumed: the file has no $INSUNITS; {} (metric): read as mm, {} (as inches it would be {})", meas.en, mm.en, inch.en;
            "unidades supostas: o arquivo não tem $INSUNITS; {} (métrico): lido em mm, {} (em polegadas seria {})", meas.pt, mm.pt, inch.pt),
        Evidence::TooSmallForMm => text!(
            "units assumed: the file has no $INSUNITS ({}); read as mm it would be only {}, so it is read as inches: {}", meas.en, mm.en, inch.en;
            "unidades supostas: o arquivo não tem $INSUNITS ({}); em mm mediria só {}, então é lido em polegadas: {}", meas.pt, mm.pt, inch.pt),
        Evidence::Default if measurement == Some(0) => text!(
            "units assumed: the file has no $INSUNITS; $MEASUREMENT = 0 suggests inches, but the drawing would then be {}; read as mm: {}", inch.en, mm.en;
            "unidades supostas: o arquivo não tem $INSUNITS; $MEASUREMENT = 0 sugere polegadas, mas então o desenho mediria {}; lido em mm: {}", inch.pt, mm.pt),
        Evidence::Default => text!(
            "units assumed: the file does not state its units (no $INSUNITS, {}); read as mm: {} (as inches it would be {})", meas.en, mm.en, inch.en;
            "unidades supostas: o arquivo não informa suas unidades (sem $INSUNITS, {}); lido em mm: {} (em polegadas seria {})", meas.pt, mm.pt, inch.pt),
    };
    Warning::new("units-assumed", t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn assumed_units_follow_the_evidence() {
        // A 134 × 92 keyboard plate with $MEASUREMENT 0 (KiCad): mm.
        assert_eq!(assume(Some(0), 134.0), (Units::MM, Evidence::Default));
        // A 2 × 1 drawing: inches.
        assert_eq!(assume(Some(0), 2.0), (Units::INCH, Evidence::TooSmallForMm));
        assert_eq!(assume(None, 2.0).0, Units::INCH);
        // Metric says metric, however small.
        assert_eq!(
            assume(Some(1), 2.0),
            (Units::MM, Evidence::MeasurementMetric)
        );
        // Nothing drawn: nothing to go by.
        assert_eq!(assume(None, 0.0).0, Units::MM);
        assert_eq!(assume(None, f64::NAN).0, Units::MM);
    }

    #[test]
    fn the_warning_gives_both_sizes() {
        let bb = BBox {
            min: crate::geom::Point::new(0.0, 0.0),
            max: crate::geom::Point::new(134.0, 92.0),
        };
        let w = assumed_warning(Evidence::Default, Some(0), &bb);
        assert_eq!(w.code, "units-assumed");
        assert_eq!(
            w.text.en,
            "units assumed: the file has no $INSUNITS; $MEASUREMENT = 0 suggests inches, but the drawing would then be 3.40 × 2.34 m; read as mm: 134 × 92 mm"
        );
        assert!(w.text.pt.contains("3,40 × 2,34 m"), "{}", w.text.pt);
        assert_eq!(size_text(2.0, 1.0).en, "2.00 × 1.00 mm");
        assert_eq!(size_text(50.8, 25.4).en, "50.8 × 25.4 mm");
        assert_eq!(size_text(92.0, 20.04).en, "92 × 20 mm");
    }

    #[test]
    fn inch_code_scales_by_25_4() {
        assert_eq!(Units::from_insunits(1).unwrap().to_mm, 25.4);
        assert_eq!(Units::from_insunits(6).unwrap().name, "m");
        assert!(Units::from_insunits(0).is_none());
        assert!(Units::from_insunits(99).is_none());
    }
}
