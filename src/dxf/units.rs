//! Drawing units: `$INSUNITS` (DXF reference, HEADER section, group 70) and
//! the factor that scales them to millimetres.

use serde::Serialize;

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

    /// A unit by its name (as given on the command line): mm, cm, m, in, ft, …
    pub fn from_name(name: &str) -> Option<Units> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inch_code_scales_by_25_4() {
        assert_eq!(Units::from_insunits(1).unwrap().to_mm, 25.4);
        assert_eq!(Units::from_insunits(6).unwrap().name, "m");
        assert!(Units::from_insunits(0).is_none());
        assert!(Units::from_insunits(99).is_none());
    }
}
