//! A nest as given — `kerfcam nest`'s options or the page's nest settings
//! — and the one way from it to [`NestSettings`], a torch setup, and parts
//! and sheets read from DXF files. Both front ends fill a [`NestSpec`] and
//! read their files here, so a default or a reading rule cannot drift
//! between them.

use serde::Deserialize;

use super::{parts_from_contours, sheet_from_contours, NestSettings, Part, Sheets, Unplaced};
use crate::contour;
use crate::process::Torches;
use crate::settings::{Settings, SettingsError};
use crate::text;
use crate::warning::Text;

/// Default spacing between parts beyond the kerf, mm: two kerfs never
/// touch, and a thin web is left for the plate to stay flat.
pub const SPACING_OVER_KERF: f64 = 1.0;

impl NestSettings {
    /// The defaults with parts `kerf` + [`SPACING_OVER_KERF`] apart, a
    /// 5 mm margin, 0.05 mm collision polygons, a 30 s budget, seed 1.
    pub fn for_kerf(kerf: f64) -> NestSettings {
        NestSettings {
            spacing: kerf + SPACING_OVER_KERF,
            margin: 5.0,
            tolerance: 0.05,
            time_s: 30.0,
            seed: 1,
            max_evaluations: None,
            budget_s: None,
        }
    }

    /// The budget the phases of the search are shared out of, s: the
    /// operator's ([`NestSettings::budget_s`]), else `time_s`.
    pub fn budget(&self) -> f64 {
        self.budget_s.unwrap_or(self.time_s)
    }

    /// How far two copies (or a copy and the room's edge) may reach into
    /// each other and still touch, by the exact test, mm: a ten-thousandth
    /// of the tolerance. ESICUP's checker (`check_nest.py`) calls an
    /// overlap any intersection over 1e-6 of the smaller part's area; at a
    /// thousandth (1e-7 of the strip's height on an instance) two jakobs1
    /// triangles met along a 4-unit edge 4e-6 deep, 1.3 × that share.
    pub fn touch(&self) -> f64 {
        self.tolerance * 1e-4
    }
}

/// One nest's settings as given; `None` is "not given": the default.
/// Field names are the page's wire names.
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
#[serde(default)]
pub struct NestSpec {
    /// Least distance between parts, mm (default kerf + 1).
    pub spacing: Option<f64>,
    /// Least distance to the sheet's edge, mm.
    pub margin: Option<f64>,
    /// Largest excess of the collision polygons, mm.
    pub tolerance: Option<f64>,
    /// Time budget, s.
    pub time_s: Option<f64>,
    /// Seed of the improvement.
    pub seed: Option<u64>,
    /// Stop after this many evaluations.
    pub max_evaluations: Option<u64>,
    /// The budget of the run replayed, when `time_s` is not it.
    pub budget_s: Option<f64>,
    /// Torches cutting at once across the sheet (1: one).
    pub torches: Option<usize>,
    /// Their distance along Y, mm.
    pub torch_spacing: Option<f64>,
    /// Park there and stop (M0) for the operator before the first cut.
    pub torch_park: Option<[f64; 2]>,
}

impl NestSpec {
    /// The nest's settings for parts cut with a kerf `kerf` mm wide (the
    /// job's, or its material's).
    pub fn settings(&self, kerf: f64) -> NestSettings {
        let d = NestSettings::for_kerf(kerf);
        NestSettings {
            spacing: self.spacing.unwrap_or(d.spacing),
            margin: self.margin.unwrap_or(d.margin),
            tolerance: self.tolerance.unwrap_or(d.tolerance),
            time_s: self.time_s.unwrap_or(d.time_s),
            seed: self.seed.unwrap_or(d.seed),
            max_evaluations: self.max_evaluations.or(d.max_evaluations),
            budget_s: self.budget_s,
        }
    }

    /// The torch setup, checked ([`Torches::new`]); None: one torch. A
    /// spacing without a number of torches is refused: it would be lost.
    pub fn torches(&self) -> Result<Option<Torches>, SettingsError> {
        let park = self.torch_park.map(|[x, y]| crate::geom::Point::new(x, y));
        match (self.torches, self.torch_spacing) {
            (None, None) => Ok(None),
            (None, Some(_)) => Err(SettingsError {
                field: "torch_spacing",
                reason: text!("a torch spacing needs the number of torches";
                              "a distância entre tochas precisa do número de tochas"),
            }),
            (Some(count), spacing) => Torches::new(count, spacing.unwrap_or(0.0), park),
        }
    }
}

/// The parts of one DXF file, `quantity` copies each, named after `stem`
/// (`stem#n` when it holds several, `stem/BLOCK` for a part drawn as a block:
/// [`parts_from_contours`]): read as `cutting` reads a drawing
/// (units, layers, curve chord), chained with its tolerance and gap.
/// Open outlines come back as notes.
pub fn read_parts(
    dxf: &[u8],
    stem: &str,
    quantity: usize,
    cutting: &Settings,
) -> Result<(Vec<Part>, Vec<Unplaced>), Text> {
    let contours = contours_of(dxf, cutting)?;
    Ok(parts_from_contours(&contours, stem, quantity))
}

/// The parts of a DXF or SVG file (one copy each) and the contours they
/// were read from, as [`read_parts`] reads them: what the page's part rows
/// are made of ([`super::rows::file_rows`]).
pub fn parts_and_contours(
    dxf: &[u8],
    stem: &str,
    cutting: &Settings,
) -> Result<(Vec<Part>, contour::Contours), Text> {
    let contours = contours_of(dxf, cutting)?;
    let (parts, _) = parts_from_contours(&contours, stem, 1);
    Ok((parts, contours))
}

/// The sheet drawn in a DXF file (its largest outline; holes and outlines
/// on layer DEFECT are no-go zones), read as [`read_parts`] reads parts;
/// with what was left out of the drawing.
pub fn read_sheet(dxf: &[u8], cutting: &Settings) -> Result<(Sheets, Vec<Text>), Text> {
    let contours = contours_of(dxf, cutting)?;
    sheet_from_contours(&contours).map_err(|e| e.text())
}

fn contours_of(dxf: &[u8], cutting: &Settings) -> Result<contour::Contours, Text> {
    let drawing = crate::input::read(dxf, cutting.read()).map_err(|e| e.text())?;
    // Parts crossing themselves repaired (or not) as the cut repairs them.
    Ok(contour::extract_repairing(
        &drawing,
        cutting.tolerance(),
        cutting.gap(),
        crate::par::Threads::ONE,
        cutting.repair,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;
    use crate::nest::collide::{overlaps, Shape};
    use crate::nest::shape::Polygon;

    /// Two jakobs1 triangles of a nest that `check_nest.py` refused
    /// (seed 1, 4 000 evaluations): a long edge of one 4e-6 into the
    /// other, with the instance's tolerance (height 40.004 × 1e-4, as
    /// `kerfcam nest --instance` sets it). The exact test at the touch
    /// distance must see it: the shared area, worked out here as the strip
    /// between the two edges where both triangles are, is over the
    /// checker's 1e-6 of the smaller part's area.
    #[test]
    fn the_touch_distance_sees_an_overlap_the_esicup_checker_counts() {
        let shape = |v: &[(f64, f64)]| {
            Shape::new(Polygon::new(
                v.iter().map(|&(x, y)| Point::new(x, y)).collect(),
            ))
        };
        let (y0, y1) = (28.973517620381777, 28.973521602842997);
        // Right angle at (11.88, y0), apex 7 up; right angle at (11.88, y1), 5 down.
        let upper = shape(&[(11.88, y0 + 7.0), (7.88, y0), (11.88, y0)]);
        let lower = shape(&[(11.88, y1 - 5.0), (11.88, y1), (6.88, y1)]);
        // Between y0 and y1 the upper one spans x from 7.88 (+ 4/7 of the
        // height above y0) to 11.88; the lower one all of that.
        let depth = y1 - y0;
        let shared = depth * (4.0 - 4.0 / 7.0 * depth / 2.0);
        let smaller = 0.5 * 5.0 * 5.0;
        assert!(shared > 1e-6 * smaller, "{shared}");
        let s = NestSettings {
            tolerance: 40.004 * 1e-4,
            ..NestSettings::default()
        };
        assert!(overlaps(&upper, &lower, s.touch()));
        assert!(overlaps(&lower, &upper, s.touch()));
    }

    #[test]
    fn spacing_follows_the_kerf_unless_given() {
        let s = NestSpec::default().settings(2.0);
        assert_eq!((s.spacing, s.margin, s.tolerance), (3.0, 5.0, 0.05));
        assert_eq!(NestSettings::default().spacing, 1.5 + SPACING_OVER_KERF);
        let given = NestSpec {
            spacing: Some(0.5),
            margin: Some(0.0),
            ..NestSpec::default()
        };
        assert_eq!(
            (given.settings(2.0).spacing, given.settings(2.0).margin),
            (0.5, 0.0)
        );
    }

    #[test]
    fn torches_are_checked_the_same_for_every_front_end() {
        assert_eq!(NestSpec::default().torches(), Ok(None));
        let one = NestSpec {
            torches: Some(1),
            torch_spacing: Some(0.0),
            ..NestSpec::default()
        };
        assert_eq!(one.torches(), Ok(None));
        let lost = NestSpec {
            torch_spacing: Some(500.0),
            ..NestSpec::default()
        };
        assert_eq!(lost.torches().unwrap_err().field, "torch_spacing");
        let no_spacing = NestSpec {
            torches: Some(2),
            ..NestSpec::default()
        };
        assert_eq!(no_spacing.torches().unwrap_err().field, "torch_spacing");
        let two = NestSpec {
            torches: Some(2),
            torch_spacing: Some(500.0),
            torch_park: Some([0.0, 10.0]),
            ..NestSpec::default()
        };
        assert_eq!(two.torches().unwrap().unwrap().count, 2);
    }

    #[test]
    fn parts_are_read_in_the_cutting_settings_layers_and_units() {
        // A 10 × 10 square on layer A, a 20 × 20 one beside it on layer B.
        let square = |layer: &str, x: f64, s: f64| {
            let x1 = x + s;
            format!("0\nLWPOLYLINE\n8\n{layer}\n90\n4\n70\n1\n10\n{x}\n20\n0\n10\n{x1}\n20\n0\n10\n{x1}\n20\n{s}\n10\n{x}\n20\n{s}\n")
        };
        let dxf = format!(
            "0\nSECTION\n2\nENTITIES\n{}{}0\nENDSEC\n0\nEOF\n",
            square("A", 0.0, 10.0),
            square("B", 50.0, 20.0)
        );
        let all = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let (parts, notes) = read_parts(dxf.as_bytes(), "p", 2, &all).unwrap();
        assert_eq!(parts.len(), 2);
        assert!(notes.is_empty());
        assert!(parts.iter().all(|p| p.quantity == 2));
        let b = all
            .clone()
            .with_layers(vec!["B".into()])
            .with_units(crate::dxf::Units::from_name("cm").unwrap());
        let (parts, _) = read_parts(dxf.as_bytes(), "p", 1, &b).unwrap();
        assert_eq!(parts.len(), 1);
        assert_eq!(parts[0].name, "p");
        assert!(
            (parts[0].area() - 200.0 * 200.0).abs() < 1e-6,
            "{}",
            parts[0].area()
        );
        assert!(read_parts(b"not a dxf", "p", 1, &all).is_err());
    }

    #[test]
    fn parts_are_named_after_their_layers_where_the_layers_tell_them_apart() {
        use crate::test_dxf::{file, rect};
        let on = |layer: &str, e: String| e.replace("8\n0\n", &format!("8\n{layer}\n"));
        let all = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let names = |bytes: &[u8]| -> Vec<String> {
            let (mut parts, _) = read_parts(bytes, "f", 1, &all).unwrap();
            parts.sort_by(|a, b| a.outer[0].a.x.total_cmp(&b.outer[0].a.x));
            parts.into_iter().map(|p| p.name).collect()
        };
        // FLANGE alone on its layer, two BRACKETs on theirs, one on layer 0.
        let dxf = file(&[
            on("FLANGE", rect(0.0, 0.0, 50.0, 50.0)),
            on("BRACKET", rect(100.0, 0.0, 40.0, 30.0)),
            on("BRACKET", rect(200.0, 0.0, 40.0, 30.0)),
            rect(300.0, 0.0, 20.0, 20.0),
        ]
        .concat());
        assert_eq!(names(&dxf), ["f/FLANGE", "f/BRACKET#2", "f/BRACKET#3", "f#4"]);
        // Every part on one layer (most CAD exports): the layer names none.
        let dxf = file(&[on("CUT", rect(0.0, 0.0, 50.0, 50.0)), on("CUT", rect(100.0, 0.0, 40.0, 30.0))].concat());
        assert_eq!(names(&dxf), ["f#1", "f#2"]);
        let dxf = file(&on("Layer0", rect(0.0, 0.0, 50.0, 50.0)));
        assert_eq!(names(&dxf), ["f"]);
        // A name from the file is kept as it is (escaped where shown).
        let dxf = file(&[on("<b>A&B</b>", rect(0.0, 0.0, 50.0, 50.0)), rect(100.0, 0.0, 40.0, 30.0)].concat());
        assert_eq!(names(&dxf), ["f/<b>A&B</b>", "f#2"]);
    }

    #[test]
    fn svg_parts_are_named_after_their_groups() {
        let all = Settings::new(1.5, 0.001, 2000.0).unwrap();
        let sq = |x: u32| format!(r#"<rect x="{x}" y="0" width="20" height="20"/>"#);
        // A labelled group of one part; an id'd group of two; an Inkscape
        // layer of one part in a group Inkscape numbered (g42: no name);
        // a part outside every group.
        let svg = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" width="300mm" height="100mm" viewBox="0 0 300 100" fill="none" stroke="black">
<g id="g7" inkscape:label="Gear 40T">{}</g>
<g id="key-blank">{}{}</g>
<g inkscape:groupmode="layer" inkscape:label="Plates"><g id="g42">{}</g></g>
{}</svg>"#,
            sq(0),
            sq(50),
            sq(100),
            sq(150),
            sq(200)
        );
        let (mut parts, _) = read_parts(svg.as_bytes(), "f", 1, &all).unwrap();
        parts.sort_by(|a, b| {
            let x = |p: &Part| p.outer.iter().map(|s| s.a.x).fold(f64::MAX, f64::min);
            x(a).total_cmp(&x(b))
        });
        let names: Vec<&str> = parts.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["f/Gear 40T", "f/key-blank#2", "f/key-blank#3", "f/Plates", "f#5"]);
    }
}
