//! The shop's prices ([`CostModel`]), read from JSON (the CLI's `--cost`
//! file, the page's Cost panel) and checked field by field: a value that
//! is negative, not a number or missing is refused naming its field,
//! never taken as 0. The currency is a label the quote shows, never
//! converted.

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::text;
use crate::warning::{Lang, Text};

/// What the material of a copy is taken to be.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MaterialShare {
    /// The part's own area (its outline less its holes): the skeleton and
    /// the remnant are not charged (default).
    #[default]
    Area,
    /// Its share, by area, of the sheet used (the whole sheet, or up to the
    /// crop line when a remnant is kept): the skeleton is charged, and
    /// credited back as scrap when a scrap price is given.
    Sheet,
}

impl MaterialShare {
    /// The name used in the JSON and the CSV.
    pub fn name(self) -> &'static str {
        match self {
            MaterialShare::Area => "area",
            MaterialShare::Sheet => "sheet",
        }
    }
}

/// A shop's prices. Every money figure is in `currency`; lengths in mm,
/// areas in m², masses in kg.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CostModel {
    /// The currency's label (EUR, R$…), shown beside every figure.
    pub currency: String,
    /// Machine and operator rate, per hour of the estimated machine time.
    pub machine_per_hour: f64,
    /// Consumables per pierce (a plasma electrode wears most at the pierce).
    pub per_pierce: f64,
    /// Consumables per metre cut with the tool on (contours, leads, links).
    pub per_metre: f64,
    /// Material price per kg (needs `density_g_cm3` and `thickness_mm`);
    /// give this or `material_per_m2`.
    #[serde(default)]
    pub material_per_kg: Option<f64>,
    /// Material price per m² of sheet; give this or `material_per_kg`.
    #[serde(default)]
    pub material_per_m2: Option<f64>,
    /// Density of the material, g/cm³ (steel 7.85, aluminium 2.70).
    #[serde(default)]
    pub density_g_cm3: Option<f64>,
    /// Sheet thickness, mm.
    #[serde(default)]
    pub thickness_mm: Option<f64>,
    /// What the scrap merchant pays per kg of skeleton (with `material_share`
    /// "sheet"); none: no credit.
    #[serde(default)]
    pub scrap_per_kg: Option<f64>,
    /// Setting up one sheet (loading, zeroing, unloading).
    pub setup_per_sheet: f64,
    /// Added to the cost, %.
    pub markup_percent: f64,
    /// What a copy's material is ([`MaterialShare::Area`] when not given).
    #[serde(default)]
    pub material_share: MaterialShare,
}

/// A cost model refused, naming the field.
#[derive(Clone, Debug, PartialEq)]
pub struct QuoteError {
    /// The field (`per_pierce`, `density_g_cm3`…; `json` when the text is
    /// not a cost model at all).
    pub field: String,
    /// What is wrong, in every language.
    pub reason: Text,
}

impl QuoteError {
    fn new(field: &str, reason: Text) -> QuoteError {
        QuoteError {
            field: field.to_string(),
            reason,
        }
    }
    /// The message in every language.
    pub fn text(&self) -> Text {
        let (field, r) = (&self.field, &self.reason);
        text!("cost field '{field}': {}", r.en; "campo '{field}' do custo: {}", r.pt)
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl fmt::Display for QuoteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for QuoteError {}

/// `v` finite and ≥ 0 (> 0 when `positive`), else the error naming `field`.
fn check(field: &str, v: f64, positive: bool) -> Result<(), QuoteError> {
    if !v.is_finite() {
        return Err(QuoteError::new(
            field,
            text!("{v} is not a number"; "{v} não é um número"),
        ));
    }
    if v < 0.0 || (positive && v == 0.0) {
        let (en, pt) = if positive {
            ("must be more than 0", "deve ser maior que 0")
        } else {
            ("must not be negative", "não pode ser negativo")
        };
        return Err(QuoteError::new(field, text!("{v}: {en}"; "{v}: {pt}")));
    }
    Ok(())
}

impl CostModel {
    /// Reads and checks a cost model.
    pub fn from_json(json: &str) -> Result<CostModel, QuoteError> {
        let m: CostModel = serde_json::from_str(json).map_err(|e| {
            // serde names a missing or unknown field in its message; the
            // field given is the one it names when it names one.
            let msg = e.to_string();
            let field = msg
                .split('`')
                .nth(1)
                .filter(|_| msg.contains("field"))
                .unwrap_or("json")
                .to_string();
            QuoteError {
                field,
                reason: text!("{msg}"; "{msg}"),
            }
        })?;
        m.validate()?;
        Ok(m)
    }

    /// Every field in range; `material_per_kg` with its density and
    /// thickness, exactly one material price, a scrap price per kg with the
    /// density and thickness that turn area into mass.
    pub fn validate(&self) -> Result<(), QuoteError> {
        if self.currency.trim().is_empty() {
            return Err(QuoteError::new(
                "currency",
                text!("say which currency the prices are in (EUR, USD, R$…)";
                      "diga em que moeda estão os preços (EUR, USD, R$…)"),
            ));
        }
        for (field, v) in [
            ("machine_per_hour", self.machine_per_hour),
            ("per_pierce", self.per_pierce),
            ("per_metre", self.per_metre),
            ("setup_per_sheet", self.setup_per_sheet),
            ("markup_percent", self.markup_percent),
        ] {
            check(field, v, false)?;
        }
        for (field, v) in [
            ("material_per_kg", self.material_per_kg),
            ("material_per_m2", self.material_per_m2),
            ("scrap_per_kg", self.scrap_per_kg),
        ] {
            if let Some(v) = v {
                check(field, v, false)?;
            }
        }
        for (field, v) in [
            ("density_g_cm3", self.density_g_cm3),
            ("thickness_mm", self.thickness_mm),
        ] {
            if let Some(v) = v {
                check(field, v, true)?;
            }
        }
        match (self.material_per_kg, self.material_per_m2) {
            (Some(_), Some(_)) => {
                return Err(QuoteError::new(
                    "material_per_m2",
                    text!("give the material's price per kg or per m², not both";
                          "dê o preço do material por kg ou por m², não os dois"),
                ))
            }
            (None, None) => {
                return Err(QuoteError::new(
                    "material_per_kg",
                    text!("give the material's price per kg or per m² (0 for material the customer supplies)";
                          "dê o preço do material por kg ou por m² (0 para material do cliente)"),
                ))
            }
            _ => {}
        }
        if self.material_per_kg.is_some() || self.scrap_per_kg.is_some() {
            let why = if self.material_per_kg.is_some() {
                ("material_per_kg", "material_per_kg")
            } else {
                ("scrap_per_kg", "scrap_per_kg")
            };
            for (field, v) in [
                ("density_g_cm3", self.density_g_cm3),
                ("thickness_mm", self.thickness_mm),
            ] {
                if v.is_none() {
                    let (en, pt) = why;
                    return Err(QuoteError::new(
                        field,
                        text!("needed with {en} (area to mass)"; "necessário com {pt} (área para massa)"),
                    ));
                }
            }
        }
        Ok(())
    }

    /// Mass of `area_mm2` of the sheet, kg, when the density and thickness
    /// are known (mm² × mm = mm³; /1000 cm³; × g/cm³; /1000 kg).
    pub fn mass_kg(&self, area_mm2: f64) -> Option<f64> {
        Some(area_mm2 * self.thickness_mm? * self.density_g_cm3? / 1e6)
    }

    /// Price of `area_mm2` of material.
    pub fn material_cost(&self, area_mm2: f64) -> f64 {
        match (self.material_per_kg, self.material_per_m2) {
            (Some(per_kg), _) => self.mass_kg(area_mm2).unwrap_or(0.0) * per_kg,
            (None, Some(per_m2)) => area_mm2 / 1e6 * per_m2,
            (None, None) => 0.0,
        }
    }
}
