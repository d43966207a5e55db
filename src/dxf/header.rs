//! The HEADER section: its variables indexed by name, the code page
//! ($DWGCODEPAGE, from $ACADVER on) and the drawing units ($INSUNITS, or
//! what is assumed and said).

use super::pairs::Pair;
use super::reader::Reader;
use super::text::Decoder;
use super::Units;
use crate::text;
use crate::warning::Warning;

impl<'a, 'o> Reader<'a, 'o> {
    /// `$NAME` → index of its first value pair.
    pub fn read_header(&mut self, pre: &[Pair<'a>], from: usize, to: usize) {
        for (i, p) in pre.iter().enumerate().take(to).skip(from) {
            if p.code == 9 && i + 1 < to {
                self.header.entry(p.trimmed()).or_insert(i + 1);
            }
        }
    }

    fn header_pair(&self, pre: &[Pair<'a>], name: &str, code: i32) -> Option<Pair<'a>> {
        let i = *self.header.get(name.as_bytes())?;
        pre.get(i..)?
            .iter()
            .take_while(|p| p.code != 9 && p.code != 0)
            .find(|p| p.code == code)
            .copied()
    }

    pub(super) fn set_decoder(&mut self, pre: &[Pair<'a>]) {
        let ver = self.header_pair(pre, "$ACADVER", 1).map(|p| p.trimmed());
        let cp = self
            .header_pair(pre, "$DWGCODEPAGE", 3)
            .map(|p| p.trimmed());
        self.d.version = ver.map(|v| String::from_utf8_lossy(v).into_owned());
        self.decoder = Decoder::for_file(ver, cp).unwrap_or_else(|| {
            let name = String::from_utf8_lossy(cp.unwrap_or(b"")).into_owned();
            self.d.warnings.push(Warning::new(
                "codepage-unknown",
                text!("unknown code page '{name}': names read as Windows-1252";
                      "página de código '{name}' desconhecida: nomes lidos como Windows-1252"),
            ));
            Decoder::for_file(Some(b"AC1015"), Some(b"ANSI_1252")).unwrap_or(Decoder::Utf8)
        });
    }

    pub(super) fn set_units(&mut self, pre: &[Pair<'a>]) {
        let ins = self.header_pair(pre, "$INSUNITS", 70).and_then(|p| p.int());
        let meas = self
            .header_pair(pre, "$MEASUREMENT", 70)
            .and_then(|p| p.int());
        let from_ins = ins.and_then(Units::from_insunits);
        let (units, source) = if let Some(u) = self.options.units {
            (u, "override")
        } else if let Some(u) = from_ins {
            // $MEASUREMENT 0 beside a metric $INSUNITS is common and means
            // nothing (it names hatch and linetype files; KiCad and
            // imperial templates write it): only inches under a metric
            // $MEASUREMENT are worth a word. $INSUNITS wins either way.
            if u.to_mm == 25.4 && meas == Some(1) {
                let metric = true;
                self.d.warnings.push(Warning::new(
                    "units-contradictory",
                    text!("contradictory units: $INSUNITS says {} but $MEASUREMENT says {}; read as {} (override with the units setting)",
                        u.name, if metric { "metric" } else { "imperial" }, u.name;
                        "unidades contraditórias: $INSUNITS diz {} mas $MEASUREMENT diz {}; lido em {} (mude na configuração de unidades)",
                        u.name, if metric { "métrico" } else { "polegadas" }, u.name),
                ));
            }
            (u, "$INSUNITS")
        } else {
            if let Some(code) = ins.filter(|&c| c != 0) {
                self.d.warnings.push(Warning::new(
                    "units-not-length",
                    text!("$INSUNITS {code} is not a length unit";
                          "$INSUNITS {code} não é uma unidade de comprimento"),
                ));
            }
            // Read as mm for now; `super::assume_units` decides from the
            // drawing's size once it is read, and warns.
            self.d.measurement = meas;
            (Units::MM, "assumed")
        };
        self.d.units = Some(units);
        self.d.units_source = source;
        self.scale = units.to_mm;
    }
}
