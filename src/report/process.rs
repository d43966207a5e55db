//! The report's `process` section: the values the job was cut with, after
//! a cut-chart entry chose its own (what the job sheet prints, not what
//! the form said).

use serde::Serialize;

use crate::process::Process;
use crate::MaterialUsed;

/// The process the plan, the program and the time estimate used.
#[derive(Clone, Debug, Serialize)]
pub struct ProcessReport {
    /// Kerf width, mm.
    pub kerf: f64,
    /// Cutting feed, mm/min.
    pub feed: f64,
    /// Dwell after the torch comes on, s.
    pub pierce_delay: f64,
    /// Rapid traverse of the time estimate, mm/min.
    pub rapid: f64,
    /// Torch height while piercing, mm (Z posts).
    pub pierce_height: f64,
    /// Torch height while cutting, mm (Z posts).
    pub cut_height: f64,
    /// The height control may run.
    pub thc: bool,
    /// Holes narrower than this are small, mm (0: no small-hole rule).
    pub small_hole_diameter: f64,
    /// Their speed, % of the feed.
    pub small_hole_speed: f64,
    /// The controller's material number (QtPlasmaC `M190 Pn`), 0: none.
    pub material_number: u32,
    /// The cut-chart entry the values came from, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub material: Option<MaterialReport>,
}

/// A cut-chart entry named in the report.
#[derive(Clone, Debug, Serialize)]
pub struct MaterialReport {
    /// The entry's name.
    pub name: String,
    /// A starter example, to check against the machine's own chart.
    pub example: bool,
}

impl ProcessReport {
    /// The section of `p`, from the entry `material`.
    pub fn of(p: &Process, material: Option<&MaterialUsed>) -> ProcessReport {
        ProcessReport {
            kerf: p.kerf,
            feed: p.feed,
            pierce_delay: p.pierce_delay,
            rapid: p.rapid,
            pierce_height: p.pierce_height,
            cut_height: p.cut_height,
            thc: p.thc,
            small_hole_diameter: p.small_hole.diameter,
            small_hole_speed: p.small_hole.speed_pct,
            material_number: p.material,
            material: material.map(|m| MaterialReport {
                name: m.name.clone(),
                example: m.example,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::report::Report;
    use crate::Spec;

    const CIRCLE: &[u8] =
        b"0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n50\n20\n50\n40\n10\n0\nENDSEC\n0\nEOF\n";

    fn process_of(spec: &Spec) -> serde_json::Value {
        let s = spec.build().unwrap();
        let out = crate::run(CIRCLE, &s).unwrap();
        let json: serde_json::Value = serde_json::from_str(&Report::new(&out).to_json()).unwrap();
        json["process"].clone()
    }

    #[test]
    fn the_report_says_the_values_a_cut_chart_entry_applied() {
        let p = process_of(&Spec {
            material_name: Some("Mild steel 6 mm 45 A (example)".into()),
            rapid: Some(8000.0),
            ..Spec::default()
        });
        assert_eq!(
            (&p["kerf"], &p["feed"], &p["pierce_delay"], &p["rapid"]),
            (&1.6.into(), &1500.0.into(), &0.6.into(), &8000.0.into()),
            "{p}"
        );
        assert_eq!(p["material"]["name"], "Mild steel 6 mm 45 A (example)");
        assert_eq!(p["material"]["example"], true);
        assert_eq!(p["small_hole_diameter"], 9.0);
        // The page's entry wins over the numbers typed beside it.
        let lib = crate::materials::Library::starter();
        let entry = serde_json::to_string(lib.find("Mild steel 6 mm 45 A (example)").unwrap());
        let entry = entry.unwrap();
        let p = process_of(&Spec {
            kerf: Some(2.5),
            feed: Some(3000.0),
            material: Some(entry),
            ..Spec::default()
        });
        assert_eq!(
            (&p["kerf"], &p["feed"]),
            (&1.6.into(), &1500.0.into()),
            "{p}"
        );
        // No entry: the values given, and no `material`.
        let p = process_of(&Spec {
            kerf: Some(2.5),
            ..Spec::default()
        });
        assert_eq!(
            (&p["kerf"], &p["feed"], &p["rapid"]),
            (&2.5.into(), &2000.0.into(), &10000.0.into())
        );
        assert!(p.get("material").is_none(), "{p}");
    }
}
