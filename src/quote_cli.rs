//! `--cost FILE.json` and `--quote FILE.csv`, shared by `kerfcam FILE`
//! and `kerfcam nest`: the cost model read and checked, the quote written
//! as CSV and summed up on standard error.

use std::path::PathBuf;

use anyhow::{anyhow, bail, Context, Result};
use kerfcam::quote::{self, CostModel, Quote, SheetInput};
use kerfcam::warning::Lang;

/// The two options, as given.
#[derive(Default)]
pub struct QuoteArgs {
    /// The cost model's file.
    pub cost: Option<PathBuf>,
    /// Where to write the CSV.
    pub csv: Option<PathBuf>,
    /// Its convention (`--quote-locale`; RFC 4180 when not given).
    pub locale: Option<quote::Convention>,
}

impl QuoteArgs {
    /// Takes `opt` when it is one of ours. Ok(false): it is not.
    pub fn take(
        &mut self,
        opt: &str,
        value: &mut dyn FnMut(&str) -> Result<String>,
    ) -> Result<bool> {
        match opt {
            "--cost" => self.cost = Some(value(opt)?.into()),
            "--quote" => self.csv = Some(value(opt)?.into()),
            "--quote-locale" => {
                let v = value(opt)?;
                self.locale = Some(quote::Convention::from_name(&v).ok_or_else(|| {
                    anyhow!("--quote-locale: '{v}' is not en or pt-BR")
                })?);
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// The cost model, when one is given; `--quote` without it refused.
    pub fn model(&self, lang: Lang) -> Result<Option<CostModel>> {
        let Some(path) = &self.cost else {
            if self.csv.is_some() {
                bail!("--quote needs a cost model: --cost FILE.json (see docs/quote.md)");
            }
            if self.locale.is_some() {
                bail!("--quote-locale needs --quote FILE.csv and --cost FILE.json");
            }
            return Ok(None);
        };
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("--cost: cannot read {}", path.display()))?;
        let m = CostModel::from_json(&text)
            .map_err(|e| anyhow!("--cost {}: {}", path.display(), e.message(lang)))?;
        Ok(Some(m))
    }
}

/// The quote of `sheets`, refused with the model's field in `lang`.
pub fn make(
    m: &CostModel,
    sheets: &[SheetInput],
    name: &dyn Fn(u32) -> String,
    lang: Lang,
) -> Result<Quote> {
    quote::quote(m, sheets, name).map_err(|e| anyhow!("--cost: {}", e.message(lang)))
}

/// Writes the CSV when asked, and says the totals unless `quiet`.
pub fn write(q: &Quote, args: &QuoteArgs, quiet: bool, lang: Lang) -> Result<()> {
    if let Some(path) = &args.csv {
        let c = args.locale.unwrap_or(quote::Convention::Rfc4180);
        std::fs::write(path, quote::to_csv_in(q, c))
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    if !quiet {
        let j = &q.job;
        let (copies, sheets, cur) = (q.copies.len(), q.sheets.len(), &q.currency);
        let minutes = j.time_s / 60.0;
        match lang {
            Lang::En => eprintln!(
                "quote: {copies} copies on {sheets} sheet(s), {minutes:.1} min, cost {:.2} {cur}, price {:.2} {cur} (material by {})",
                j.cost, j.price, q.material_share.replace('_', " ")
            ),
            Lang::PtBr => eprintln!(
                "orçamento: {copies} cópias em {sheets} chapa(s), {} min, custo {} {cur}, preço {} {cur} (material por {})",
                kerfcam::warning::dec(format!("{minutes:.1}")),
                kerfcam::warning::dec(format!("{:.2}", j.cost)),
                kerfcam::warning::dec(format!("{:.2}", j.price)),
                match q.material_share {
                    "area" => "área",
                    "sheet_cost" => "custo da chapa",
                    _ => "chapa",
                }
            ),
        }
        for n in &q.notes {
            eprintln!("  {}", n.get(lang));
        }
    }
    Ok(())
}
