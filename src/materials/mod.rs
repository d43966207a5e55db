//! Cut charts: what a process does to a material of a thickness — kerf,
//! feed, pierce and cut heights, pierce delay, amps and volts — as data the
//! job reads (issue 20 §1; paper 001 asks for kerf and entry distance from a
//! table f(process, thickness)).
//!
//! A [`Library`] is a list of [`Entry`]s, kept as JSON (the page stores it,
//! the CLI reads `--materials FILE`) or read from and written to LinuxCNC
//! QtPlasmaC material files ([`qtplasmac`]). [`Library::starter`] holds a
//! few example entries, each marked `example: true` and named "(example)":
//! figures of the order the torch makers publish, to be checked against the
//! machine's own cut charts before cutting.

pub mod qtplasmac;

use serde::{Deserialize, Serialize};

use crate::text;
use crate::warning::{dec, Lang, Text};

/// The cutting process an entry is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Process {
    /// Air or oxygen plasma.
    Plasma,
    /// Oxy-fuel flame.
    OxyFuel,
    /// CO₂ or fibre laser.
    Laser,
    /// Abrasive or pure waterjet.
    Waterjet,
    /// Drag or tangential knife.
    Knife,
    /// Router bit.
    Router,
}

/// One line of a cut chart. Lengths in mm, speeds in mm/min, times in s.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    /// The name it is chosen by ("Mild steel 6 mm 45 A").
    pub name: String,
    /// The process.
    pub process: Process,
    /// The material ("mild steel", "stainless", "aluminium", "leather").
    #[serde(default)]
    pub material: String,
    /// Sheet thickness, mm.
    pub thickness: f64,
    /// Width of the cut, mm.
    pub kerf: f64,
    /// Cutting speed, mm/min.
    pub feed: f64,
    /// Time the torch waits after piercing, s.
    #[serde(default)]
    pub pierce_delay: f64,
    /// Torch height while piercing, mm.
    #[serde(default)]
    pub pierce_height: Option<f64>,
    /// Torch height while cutting, mm.
    #[serde(default)]
    pub cut_height: Option<f64>,
    /// Current (plasma, A) or power (laser, W).
    #[serde(default)]
    pub amps: Option<f64>,
    /// Arc voltage the height control holds, V.
    #[serde(default)]
    pub volts: Option<f64>,
    /// Gas pressure (bar or psi, as the machine's chart).
    #[serde(default)]
    pub gas_pressure: Option<f64>,
    /// Speed in small holes, % of `feed`.
    #[serde(default)]
    pub small_hole_speed: Option<f64>,
    /// QtPlasmaC's puddle jump height (% of pierce height) and delay (s),
    /// pause at the end (s), cut mode (1–3) and THC on/off, kept so a
    /// material file goes back out as it came in.
    #[serde(default)]
    pub puddle_jump_height: Option<f64>,
    /// See `puddle_jump_height`.
    #[serde(default)]
    pub puddle_jump_delay: Option<f64>,
    /// See `puddle_jump_height`.
    #[serde(default)]
    pub pause_at_end: Option<f64>,
    /// See `puddle_jump_height`.
    #[serde(default)]
    pub cut_mode: Option<f64>,
    /// See `puddle_jump_height`.
    #[serde(default)]
    pub thc: Option<f64>,
    /// True for the starter examples: figures to check, not to trust.
    #[serde(default)]
    pub example: bool,
    /// The controller's material number (QtPlasmaC `[MATERIAL_NUMBER_n]`,
    /// selected by `M190 Pn`), when the entry has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub number: Option<u32>,
}

/// A set of cut-chart entries.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Library {
    /// The entries, in the order shown.
    pub entries: Vec<Entry>,
    /// The QtPlasmaC material file the entries were read from, as read: its
    /// materials that are still as they came are written back line for line
    /// ([`Library::to_material_file`]), so a shop's file goes in and out of
    /// the page unchanged.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub qtplasmac: Option<String>,
}

/// A chart that cannot be used: which entry, which field, why.
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialError {
    /// The entry's name or number, when known.
    pub entry: Option<String>,
    /// The field, when known.
    pub field: Option<&'static str>,
    /// What is wrong.
    pub reason: Text,
}

impl MaterialError {
    /// The message in every language.
    pub fn text(&self) -> Text {
        let e = self.entry.as_deref().map(|e| format!("'{e}'"));
        match (&e, self.field) {
            (Some(e), Some(f)) => {
                text!("material {e}, {f}: {}", self.reason.en; "material {e}, {f}: {}", self.reason.pt)
            }
            (Some(e), None) => {
                text!("material {e}: {}", self.reason.en; "material {e}: {}", self.reason.pt)
            }
            (None, Some(f)) => {
                text!("materials, {f}: {}", self.reason.en; "materiais, {f}: {}", self.reason.pt)
            }
            (None, None) => text!("materials: {}", self.reason.en; "materiais: {}", self.reason.pt),
        }
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl std::fmt::Display for MaterialError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for MaterialError {}

/// Each numeric field's name and range (the job's own limits: kerf and
/// feed as `Settings` checks them).
fn ranges(e: &Entry) -> Vec<(&'static str, Option<f64>, f64, f64)> {
    vec![
        ("thickness", Some(e.thickness), 0.0, 1000.0),
        ("kerf", Some(e.kerf), 0.0, 100.0),
        ("feed", Some(e.feed), 1e-3, 1e6),
        ("pierce_delay", Some(e.pierce_delay), 0.0, 60.0),
        ("pierce_height", e.pierce_height, 0.0, 1000.0),
        ("cut_height", e.cut_height, 0.0, 1000.0),
        ("amps", e.amps, 0.0, 1e6),
        ("volts", e.volts, 0.0, 1e4),
        ("gas_pressure", e.gas_pressure, 0.0, 1e4),
        ("small_hole_speed", e.small_hole_speed, 1.0, 100.0),
    ]
}

impl Entry {
    /// The process this entry cuts with: its kerf, feed, delay and heights
    /// (QtPlasmaC's example heights where it gives none), the height
    /// control as it says, and small holes below 1.5 × its thickness at its
    /// small-hole speed (60 % where it gives none). `rapid` is the
    /// machine's, not the chart's.
    pub fn process(&self, rapid: f64) -> crate::process::Process {
        use crate::process::{Process, SmallHole};
        let d = Process::DEFAULT;
        Process {
            kerf: self.kerf,
            feed: self.feed,
            pierce_delay: self.pierce_delay,
            rapid,
            pierce_height: self.pierce_height.unwrap_or(d.pierce_height),
            cut_height: self.cut_height.unwrap_or(d.cut_height),
            thc: self.thc.is_none_or(|t| t != 0.0),
            small_hole: SmallHole {
                speed_pct: self.small_hole_speed.unwrap_or(SmallHole::OFF.speed_pct),
                ..SmallHole::for_thickness(self.thickness)
            },
            passes: crate::process::Passes::OFF,
            material: self.number.unwrap_or(0),
            // The gantry's setup, not the chart's.
            torches: None,
            thc_lock: crate::process::ThcLock::OFF,
            // The machine's tool, not the chart's.
            tool: crate::process::Tool::OFF,
        }
    }
    /// Checks every number; the first bad one names the entry and field.
    pub fn validate(&self) -> Result<(), MaterialError> {
        if self.name.trim().is_empty() {
            return Err(MaterialError {
                entry: None,
                field: Some("name"),
                reason: text!("an entry has no name"; "uma entrada não tem nome"),
            });
        }
        for (field, v, lo, hi) in ranges(self) {
            if let Some(v) = v {
                if !(v.is_finite() && v >= lo && v <= hi) {
                    return Err(MaterialError {
                        entry: Some(self.name.clone()),
                        field: Some(field),
                        reason: text!("{v} is not between {lo} and {hi}"; "{} não está entre {} e {}", dec(v), dec(lo), dec(hi)),
                    });
                }
            }
        }
        if let Some(n) = self.number.filter(|&n| n >= qtplasmac::NUMBER_LIMIT) {
            return Err(MaterialError {
                entry: Some(self.name.clone()),
                field: Some("number"),
                reason: text!("{n} is not below {}", qtplasmac::NUMBER_LIMIT; "{n} não é menor que {}", qtplasmac::NUMBER_LIMIT),
            });
        }
        Ok(())
    }
    /// One entry from its JSON (the page sends the chosen one), checked.
    pub fn from_json(text: &str) -> Result<Entry, MaterialError> {
        let e: Entry = serde_json::from_str(text).map_err(|e| MaterialError {
            entry: None,
            field: None,
            reason: text!("not a cut-chart entry: {e}"; "não é uma entrada de tabela de corte: {e}"),
        })?;
        e.validate()?;
        Ok(e)
    }
}

impl Library {
    /// A library from its JSON (`{"entries": [...]}`), every entry checked.
    pub fn from_json(text: &str) -> Result<Library, MaterialError> {
        let lib: Library = serde_json::from_str(text).map_err(|e| MaterialError {
            entry: None,
            field: None,
            reason: text!("not a materials file: {e}"; "não é um arquivo de materiais: {e}"),
        })?;
        for e in &lib.entries {
            e.validate()?;
        }
        Ok(lib)
    }
    /// A library from a file's text: JSON (`{"entries": …}`) or a
    /// QtPlasmaC material file.
    pub fn from_text(text: &str) -> Result<Library, MaterialError> {
        if text.trim_start().starts_with('{') {
            Library::from_json(text)
        } else {
            let mut lib = qtplasmac::MaterialFile::parse(text)?.library()?;
            lib.qtplasmac = Some(text.to_owned());
            Ok(lib)
        }
    }
    /// The plasma entries as a QtPlasmaC material file: the file they were
    /// read from, byte for byte, where they are still as read; entries
    /// changed or added since in QtPlasmaC's own layout.
    pub fn to_material_file(&self) -> String {
        qtplasmac::MaterialFile::from_library(self).write()
    }
    /// As JSON text.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
    /// The entry named `name` (case and surrounding blanks ignored).
    pub fn find(&self, name: &str) -> Result<&Entry, MaterialError> {
        let want = crate::case::lower(name.trim());
        self.entries
            .iter()
            .find(|e| crate::case::lower(e.name.trim()) == want)
            .ok_or_else(|| {
                let known: Vec<&str> = self.entries.iter().map(|e| e.name.as_str()).collect();
                let known = known.join(", ");
                MaterialError {
                    entry: Some(name.to_owned()),
                    field: None,
                    reason: text!("no such material (known: {known})"; "material inexistente (conhecidos: {known})"),
                }
            })
    }
    /// A few example entries, named "(example)" and marked `example`: of
    /// the order torch makers' charts give for a 45 A air plasma and a
    /// drag knife, to be replaced by the machine's own chart.
    pub fn starter() -> Library {
        // What every example has: nothing beyond the process's basics.
        let example = |name: &str, process, material: &str, thickness, kerf, feed| Entry {
            name: format!("{name} (example)"),
            process,
            material: material.into(),
            thickness,
            kerf,
            feed,
            pierce_delay: 0.0,
            pierce_height: None,
            cut_height: None,
            amps: None,
            volts: None,
            gas_pressure: None,
            small_hole_speed: None,
            puddle_jump_height: None,
            puddle_jump_delay: None,
            pause_at_end: None,
            cut_mode: None,
            thc: None,
            example: true,
            number: None,
        };
        let plasma = |name: &str, t, kerf, feed, delay, volts| Entry {
            pierce_delay: delay,
            pierce_height: Some(3.8),
            cut_height: Some(1.5),
            amps: Some(45.0),
            volts: Some(volts),
            small_hole_speed: Some(60.0),
            ..example(name, Process::Plasma, "mild steel", t, kerf, feed)
        };
        Library {
            entries: vec![
                plasma("Mild steel 1.5 mm 45 A", 1.5, 1.5, 5000.0, 0.2, 118.0),
                plasma("Mild steel 3 mm 45 A", 3.0, 1.5, 3300.0, 0.4, 122.0),
                plasma("Mild steel 6 mm 45 A", 6.0, 1.6, 1500.0, 0.6, 128.0),
                example(
                    "Leather 2 mm, drag knife",
                    Process::Knife,
                    "leather",
                    2.0,
                    0.0,
                    6000.0,
                ),
            ],
            qtplasmac: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_starter_chart_is_valid_labelled_and_round_trips_as_json() {
        let lib = Library::starter();
        assert!(lib
            .entries
            .iter()
            .all(|e| e.example && e.name.ends_with("(example)")));
        assert_eq!(Library::from_json(&lib.to_json()).unwrap(), lib);
        assert_eq!(
            lib.find(" mild STEEL 3 mm 45 a (example)").unwrap().feed,
            3300.0
        );
    }

    #[test]
    fn bad_charts_name_the_entry_and_field() {
        let e = Library::starter().find("x").unwrap_err();
        assert!(e.text().en.contains("no such material"), "{e}");
        assert!(e.text().en.contains("Mild steel 6 mm 45 A (example)"));
        let json =
            r#"{"entries":[{"name":"A","process":"plasma","thickness":3,"kerf":1.5,"feed":-5}]}"#;
        let e = Library::from_json(json).unwrap_err();
        assert_eq!((e.entry.as_deref(), e.field), (Some("A"), Some("feed")));
        assert_eq!(
            e.text().en,
            "material 'A', feed: -5 is not between 0.001 and 1000000"
        );
        let json =
            r#"{"entries":[{"name":"A","process":"plasma","thickness":3,"kerf":"wide","feed":5}]}"#;
        assert!(Library::from_json(json)
            .unwrap_err()
            .text()
            .en
            .contains("not a materials file"));
        assert!(Library::from_json("[1,2]").is_err());
    }
}
