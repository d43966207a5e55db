//! The job a [`Nester`]'s parts and the page's settings make: its sheets
//! (a W × H, a list of sizes, a strip or a remnant drawn in a DXF) and,
//! when every sheet size has a cost, the stock the cheapest combination
//! is taken from (issue 44 item 3, as `kerfcam nest --sheet WxH:N:COST`).

use wasm_bindgen::prelude::*;

use super::nest_result::Priced;
use super::nest_settings::{WebCost, WebNest};
use super::{say, Nester};
use crate::nest::stock;
use crate::nest::{NestJob, SheetSize, Sheets};
use crate::process::Torches;
use crate::text;

fn err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

impl Nester {
    /// The torch setup of the settings (None: one torch).
    pub(super) fn torches(&self, settings: &JsValue) -> Result<Option<Torches>, JsError> {
        WebNest::of(settings)?
            .spec()
            .torches()
            .map_err(|e| say(self.lang, e.text()))
    }

    /// The job these parts and settings make (as `nest` reads them), and
    /// its sheets' costs when every size has one: its sheets
    /// then the `combination` given, else the whole stock (`nest` finds
    /// the cheapest). The costs as `kerfcam nest --sheet WxH:N:COST` takes
    /// them ([`stock::stock_of`]), each checked naming its size.
    pub(super) fn priced_job(
        &self,
        settings: JsValue,
    ) -> Result<(NestJob, Option<Priced>), JsError> {
        let w = WebNest::of(&settings)?;
        let lang = self.lang;
        let list = w.sheet_list.as_deref().unwrap_or_default();
        let mut costs = Vec::with_capacity(list.len());
        for (i, s) in list.iter().enumerate() {
            let n = i + 1;
            costs.push(match &s.cost {
                None => None,
                Some(WebCost::Number(c)) => Some(*c),
                Some(WebCost::Text(t)) => {
                    return Err(say(
                        lang,
                        text!("sheet size {n}: the cost '{t}' is not a number";
                              "tamanho de chapa {n}: o custo '{t}' não é um número"),
                    ))
                }
            });
        }
        let sizes: Vec<SheetSize> = list
            .iter()
            .map(|s| SheetSize {
                width: s.width,
                height: s.height,
                count: s.count,
            })
            .collect();
        let torches = w
            .spec()
            .torches()
            .map_err(|e| say(lang, e.text()))?
            .is_some();
        let stock = stock::stock_of(&sizes, &costs, torches).map_err(|e| {
            let t = e.text();
            say(
                lang,
                text!("sheet costs: {}", t.en; "custos das chapas: {}", t.pt),
            )
        })?;
        if let Some(stock) = &stock {
            for (i, s) in stock.iter().enumerate() {
                let n = i + 1;
                stock::check_cost(s).map_err(|t| {
                    say(
                        lang,
                        text!("sheet size {n}: {}", t.en; "tamanho de chapa {n}: {}", t.pt),
                    )
                })?;
            }
        }
        let sheets = match (w.sheet_width, w.sheet_height, w.strip_height, &self.sheet) {
            _ if !sizes.is_empty() => Sheets::rects(sizes.clone()),
            (Some(width), Some(height), None, _) => Sheets::Rect {
                width,
                height,
                count: w.sheet_count.unwrap_or(1),
            },
            (None, None, Some(height), _) => Sheets::Strip { height },
            (None, None, None, Some(s)) => s.clone(),
            _ => return Err(err(
                "nest settings: give sheet_width and sheet_height, or strip_height, or a sheet DXF",
            )),
        };
        let mut job = NestJob {
            parts: self.parts.clone(),
            sheets,
            settings: w.spec().settings(self.cutting()?.process().kerf),
        };
        let priced = match stock {
            None => None,
            Some(stock) => {
                let counts = match &w.combination {
                    Some(c) => {
                        let fits = c.len() == stock.len()
                            && c.iter().zip(&stock).all(|(&n, s)| n <= s.size.count)
                            && c.iter().any(|&n| n > 0);
                        if !fits {
                            return Err(say(
                                lang,
                                text!("nest settings: the combination {c:?} is not sheets of the stock's sizes";
                                      "configurações do encaixe: a combinação {c:?} não é de chapas dos tamanhos em estoque"),
                            ));
                        }
                        job = stock::with_sheets(&job, &stock, c);
                        c.clone()
                    }
                    None => stock.iter().map(|s| s.size.count).collect(),
                };
                Some(Priced {
                    stock,
                    counts,
                    passed_over: w.passed_over.unwrap_or(0),
                })
            }
        };
        Ok((job, priced))
    }
}
