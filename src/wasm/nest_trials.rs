//! Sheets at a cost nested by a team of web workers (issue 44 items 2
//! and 3): the cheapest combination's trials ([`crate::nest::stock::Trials`],
//! the CLI's) held in the engine's worker, each trial nested by the whole
//! team as any team nest ([`super::NestSearch`]). The page's main thread
//! asks for the next trial, runs the team on it and hands the engine's
//! search back (www/nest-team.js):
//!
//! ```js
//! const trials = nester.trials(settings, clock);    // settings with a cost per sheet size
//! for (let t; (t = trials.next(clock)); ) {          // {combination, passed_over, max_evaluations, time_s, budget_s}
//!   // every worker: nester.search({ ...settings, ...t }, k), run and adopt as a team nest
//!   trials.record(search0, teamEvaluations);         // search 0's best: the team's
//! }
//! const result = trials.finish(seconds);              // a NestResult, as `nest` gives it
//! ```
//!
//! With an evaluation budget the nest is the same for the same seed and
//! worker count, and it is the CLI's `kerfcam nest --threads N` one (the
//! same trials, each a team of N searches exchanging at the same counts).

use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::nest_progress::js_clock;
use super::nest_result::NestResult;
use super::nest_settings::combination_given;
use super::{say, NestSearch, Nester};
use crate::nest::stock::{Stock, Trials};
use crate::nest::Unplaced;
use crate::text;
use crate::warning::Lang;

/// The trials of a nest at a cost, one at a time.
#[wasm_bindgen]
pub struct NestTrials {
    lang: Lang,
    notes: Vec<Unplaced>,
    stock: Vec<Stock>,
    trials: Option<Trials>,
}

/// What the team nests next: the settings to add to the nest's own.
#[derive(Serialize)]
struct WebNext {
    combination: Vec<usize>,
    passed_over: usize,
    max_evaluations: Option<u64>,
    time_s: f64,
    budget_s: Option<f64>,
}

fn err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

#[wasm_bindgen]
impl Nester {
    /// The trials of these parts on the sheet sizes of `settings`, each
    /// with a cost (as `nest` takes them, no `combination`); `clock()` as
    /// `nest`'s, read now for the budget's start. Throws for settings
    /// out of range, or sheets without costs.
    pub fn trials(
        &self,
        settings: JsValue,
        clock: js_sys::Function,
    ) -> Result<NestTrials, JsError> {
        let given = combination_given(&settings);
        let (job, priced) = self.priced_job(settings)?;
        let priced = match priced {
            Some(p) if !given => p,
            _ => {
                return Err(say(
                    self.lang,
                    text!("trials: give a cost for every sheet size and no combination";
                          "tentativas: informe um custo para cada tamanho de chapa e nenhuma combinação"),
                ))
            }
        };
        let trials = Trials::new(&job, &priced.stock, js_clock(&clock))
            .map_err(|e| say(self.lang, e.text()))?;
        Ok(NestTrials {
            lang: self.lang,
            notes: self.notes.clone(),
            stock: priced.stock,
            trials: Some(trials),
        })
    }
}

#[wasm_bindgen]
impl NestTrials {
    /// The next trial as settings to add to the nest's (`{combination,
    /// passed_over, max_evaluations, time_s, budget_s}`: the combination's
    /// sheets, the budget of each search and the whole it is shared out
    /// of), or null when the cheapest nest is
    /// found.
    pub fn next(&self, clock: js_sys::Function) -> JsValue {
        self.trials
            .as_ref()
            .and_then(|t| t.next(js_clock(&clock)))
            .and_then(|n| {
                serde_wasm_bindgen::to_value(&WebNext {
                    combination: n.counts,
                    passed_over: n.passed_over,
                    max_evaluations: n.job.settings.max_evaluations,
                    time_s: n.job.settings.time_s,
                    budget_s: n.job.settings.budget_s,
                })
                .ok()
            })
            .unwrap_or(JsValue::NULL)
    }

    /// The trial's nest: `search` (search 0 of the team that nested it,
    /// after its last exchange: the team's best), `evaluations` the team's
    /// sum. The search is spent.
    pub fn record(&mut self, search: &mut NestSearch, evaluations: f64) -> Result<(), JsError> {
        let nest = search.take(evaluations)?;
        let trials = self
            .trials
            .as_mut()
            .ok_or_else(|| err("the trials were finished already"))?;
        trials.record(nest, false);
        Ok(())
    }

    /// The cheapest nest, once `next` answers null; `seconds` the wall
    /// time of all the trials. Throws before; the trials are spent.
    pub fn finish(&mut self, seconds: f64) -> Result<NestResult, JsError> {
        let c = self
            .trials
            .take()
            .and_then(Trials::finish)
            .ok_or_else(|| err("the trials are not done"))?;
        let priced = super::nest_result::Priced {
            stock: self.stock.clone(),
            counts: c.counts,
            passed_over: c.tried,
        };
        Ok(NestResult::fresh(
            self.lang,
            c.job,
            c.nest,
            &self.notes,
            seconds,
            None,
            Some(priced),
        ))
    }
}
