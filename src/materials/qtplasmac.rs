//! LinuxCNC QtPlasmaC material files (`<machine>_material.cfg`): sections
//! `[MATERIAL_NUMBER_n]` of `KEY = value` lines — NAME, KERF_WIDTH, THC,
//! PIERCE_HEIGHT, PIERCE_DELAY, PUDDLE_JUMP_HEIGHT, PUDDLE_JUMP_DELAY,
//! CUT_HEIGHT, CUT_SPEED, CUT_AMPS, CUT_VOLTS, PAUSE_AT_END, GAS_PRESSURE,
//! CUT_MODE — with `#` comments. QtPlasmaC needs PIERCE_HEIGHT, PIERCE_DELAY,
//! CUT_HEIGHT and CUT_SPEED in every material and takes numbers below
//! 1 000 000 (LinuxCNC 2.9, `qtplasmac_handler.py`, load_material_file);
//! values are in the machine's units (mm here).
//!
//! A file read here keeps every line as it was, so writing it back gives the
//! same bytes: a shop's file goes through kerfcam unchanged.

use super::{Entry, Library, MaterialError, Process};
use crate::text;

/// Keys in QtPlasmaC's own order, for files written from a [`Library`].
const KEYS: [&str; 14] = [
    "NAME",
    "KERF_WIDTH",
    "THC",
    "PIERCE_HEIGHT",
    "PIERCE_DELAY",
    "PUDDLE_JUMP_HEIGHT",
    "PUDDLE_JUMP_DELAY",
    "CUT_HEIGHT",
    "CUT_SPEED",
    "CUT_AMPS",
    "CUT_VOLTS",
    "PAUSE_AT_END",
    "GAS_PRESSURE",
    "CUT_MODE",
];

/// What QtPlasmaC refuses a material without.
const REQUIRED: [&str; 4] = ["PIERCE_HEIGHT", "PIERCE_DELAY", "CUT_HEIGHT", "CUT_SPEED"];

/// Largest material number QtPlasmaC accepts, plus one.
pub const NUMBER_LIMIT: u32 = 1_000_000;

/// One `[MATERIAL_NUMBER_n]` section.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Its number.
    pub number: u32,
    /// `KEY = value` pairs, values as written.
    pub fields: Vec<(String, String)>,
    /// Every line of the section as read (header included), each with its
    /// line end; empty for a section made from a [`Library`].
    lines: Vec<String>,
}

/// A whole material file.
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialFile {
    /// Lines before the first section (comments), with their line ends.
    preamble: Vec<String>,
    /// The sections, in file order.
    pub materials: Vec<Material>,
}

impl Material {
    fn get(&self, key: &str) -> Option<&str> {
        self.fields
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
            .filter(|v| !v.is_empty())
    }
    fn name(&self) -> String {
        self.get("NAME")
            .map_or_else(|| format!("Material {}", self.number), str::to_owned)
    }
    fn num(&self, key: &'static str) -> Result<Option<f64>, MaterialError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        // QtPlasmaC drops blanks inside CUT_AMPS ("4 5" is 45).
        let v = v.replace(' ', "");
        match v.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(Some(x)),
            _ => Err(MaterialError {
                entry: Some(self.name()),
                field: Some(key),
                reason: text!("'{v}' is not a number"; "'{v}' não é um número"),
            }),
        }
    }
    /// The cut-chart entry it stands for (process plasma, thickness unknown: 0).
    pub fn entry(&self) -> Result<Entry, MaterialError> {
        for key in REQUIRED {
            if self.get(key).is_none() {
                return Err(MaterialError {
                    entry: Some(self.name()),
                    field: Some(key),
                    reason: text!("missing (QtPlasmaC needs it)"; "ausente (o QtPlasmaC exige)"),
                });
            }
        }
        let req = |key| -> Result<f64, MaterialError> { Ok(self.num(key)?.unwrap_or(0.0)) };
        let e = Entry {
            name: self.name(),
            process: Process::Plasma,
            material: String::new(),
            thickness: 0.0,
            kerf: self.num("KERF_WIDTH")?.unwrap_or(0.0),
            feed: req("CUT_SPEED")?,
            pierce_delay: req("PIERCE_DELAY")?,
            pierce_height: Some(req("PIERCE_HEIGHT")?),
            cut_height: Some(req("CUT_HEIGHT")?),
            amps: self.num("CUT_AMPS")?,
            volts: self.num("CUT_VOLTS")?,
            gas_pressure: self.num("GAS_PRESSURE")?,
            small_hole_speed: None,
            puddle_jump_height: self.num("PUDDLE_JUMP_HEIGHT")?,
            puddle_jump_delay: self.num("PUDDLE_JUMP_DELAY")?,
            pause_at_end: self.num("PAUSE_AT_END")?,
            cut_mode: self.num("CUT_MODE")?,
            thc: self.num("THC")?,
            example: false,
            number: Some(self.number),
        };
        e.validate()?;
        Ok(e)
    }
}

fn bad_line(line: &str) -> MaterialError {
    let line = line.trim();
    MaterialError {
        entry: None,
        field: None,
        reason: text!("line '{line}' is not a QtPlasmaC material line"; "a linha '{line}' não é uma linha de material do QtPlasmaC"),
    }
}

impl MaterialFile {
    /// Reads a material file; a line that is neither a comment, a blank, a
    /// section header nor `KEY = value` is an error naming it.
    pub fn parse(text: &str) -> Result<MaterialFile, MaterialError> {
        let mut file = MaterialFile {
            preamble: Vec::new(),
            materials: Vec::new(),
        };
        for raw in text.split_inclusive('\n') {
            let line = raw.trim_end_matches(['\n', '\r']);
            let t = line.trim();
            if let Some(n) = t
                .strip_prefix("[MATERIAL_NUMBER_")
                .and_then(|r| r.strip_suffix(']'))
            {
                let number: u32 = n.trim().parse().ok().filter(|&n| n < NUMBER_LIMIT).ok_or_else(|| MaterialError {
                    entry: Some(t.to_owned()),
                    field: None,
                    reason: text!("material numbers are whole numbers below {NUMBER_LIMIT}"; "números de material são inteiros menores que {NUMBER_LIMIT}"),
                })?;
                if file.materials.iter().any(|m| m.number == number) {
                    return Err(MaterialError {
                        entry: Some(t.to_owned()),
                        field: None,
                        reason: text!("the number is used twice"; "o número aparece duas vezes"),
                    });
                }
                file.materials.push(Material {
                    number,
                    fields: Vec::new(),
                    lines: vec![raw.to_owned()],
                });
                continue;
            }
            let Some(m) = file.materials.last_mut() else {
                if t.is_empty() || t.starts_with('#') {
                    file.preamble.push(raw.to_owned());
                    continue;
                }
                return Err(bad_line(line));
            };
            m.lines.push(raw.to_owned());
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            let (k, v) = t.split_once('=').ok_or_else(|| bad_line(line))?;
            let key = k.trim();
            if !key.chars().all(|c| c.is_ascii_uppercase() || c == '_') || key.is_empty() {
                return Err(bad_line(line));
            }
            m.fields.push((key.to_owned(), v.trim().to_owned()));
        }
        Ok(file)
    }

    /// The file's text: as read, byte for byte, or in QtPlasmaC's layout.
    pub fn write(&self) -> String {
        let mut out: String = self.preamble.concat();
        for m in &self.materials {
            // A section read last, without a line end, is no longer last.
            if !out.is_empty() && !out.ends_with('\n') {
                out.push('\n');
            }
            if m.lines.is_empty() {
                out += &format!("[MATERIAL_NUMBER_{}]\n", m.number);
                for (k, v) in &m.fields {
                    out += &format!("{k:<18} = {v}\n");
                }
                out.push('\n');
            } else {
                out += &m.lines.concat();
            }
        }
        out
    }

    /// Every material as a cut-chart entry.
    pub fn library(&self) -> Result<Library, MaterialError> {
        let entries = self
            .materials
            .iter()
            .map(Material::entry)
            .collect::<Result<_, _>>()?;
        Ok(Library {
            entries,
            qtplasmac: None,
        })
    }

    /// The plasma entries of `lib` as a material file (QtPlasmaC is plasma
    /// only), each under its own number, or the next free one from 1. An
    /// entry still as it was read from `lib.qtplasmac` keeps its lines as
    /// read, and the file its header comments: an unchanged library writes
    /// back the very file it came from.
    pub fn from_library(lib: &Library) -> MaterialFile {
        let source = lib
            .qtplasmac
            .as_deref()
            .and_then(|t| MaterialFile::parse(t).ok());
        let plasma: Vec<&Entry> = lib
            .entries
            .iter()
            .filter(|e| e.process == Process::Plasma)
            .collect();
        let own: std::collections::HashSet<u32> = plasma.iter().filter_map(|e| e.number).collect();
        let mut used = std::collections::HashSet::new();
        let mut next = 1;
        let mut materials = Vec::new();
        for e in plasma {
            let number = match e.number {
                Some(n) if used.insert(n) => n,
                _ => {
                    while own.contains(&next) || used.contains(&next) {
                        next += 1;
                    }
                    used.insert(next);
                    next
                }
            };
            let kept = source.as_ref().and_then(|f| {
                f.materials
                    .iter()
                    .find(|m| m.number == number && m.entry().is_ok_and(|x| as_in_file(&x, e)))
            });
            materials.push(match kept {
                Some(m) => m.clone(),
                None => Material {
                    number,
                    fields: fields_of(e),
                    lines: Vec::new(),
                },
            });
        }
        MaterialFile {
            preamble: source.map_or_else(
                || vec!["# plasma material file, written by kerfcam\n".into()],
                |f| f.preamble,
            ),
            materials,
        }
    }
}

/// True when `e` says what `read` (an entry read from a material file)
/// says, in the fields a material file holds.
fn as_in_file(read: &Entry, e: &Entry) -> bool {
    let e = Entry {
        process: read.process,
        material: read.material.clone(),
        thickness: read.thickness,
        small_hole_speed: read.small_hole_speed,
        example: read.example,
        number: read.number,
        ..e.clone()
    };
    e == *read
}

/// An entry's `KEY = value` pairs in QtPlasmaC's order.
fn fields_of(e: &Entry) -> Vec<(String, String)> {
    let num = |v: f64| format!("{v}");
    let mut fields = Vec::new();
    for key in KEYS {
        let v = match key {
            // One line: a name is data, never a second line of the file.
            "NAME" => Some(e.name.replace(['\n', '\r'], " ")),
            "KERF_WIDTH" => Some(num(e.kerf)),
            "THC" => e.thc.map(num),
            "PIERCE_HEIGHT" => Some(num(e.pierce_height.unwrap_or(0.0))),
            "PIERCE_DELAY" => Some(num(e.pierce_delay)),
            "PUDDLE_JUMP_HEIGHT" => e.puddle_jump_height.map(num),
            "PUDDLE_JUMP_DELAY" => e.puddle_jump_delay.map(num),
            "CUT_HEIGHT" => Some(num(e.cut_height.unwrap_or(0.0))),
            "CUT_SPEED" => Some(num(e.feed)),
            "CUT_AMPS" => e.amps.map(num),
            "CUT_VOLTS" => e.volts.map(num),
            "PAUSE_AT_END" => e.pause_at_end.map(num),
            "GAS_PRESSURE" => e.gas_pressure.map(num),
            _ => e.cut_mode.map(num),
        };
        if let Some(v) = v {
            fields.push((key.to_owned(), v));
        }
    }
    fields
}

#[cfg(test)]
#[path = "qtplasmac_tests.rs"]
mod tests;
