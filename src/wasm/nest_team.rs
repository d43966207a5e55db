//! A team of web workers nesting one job (issue 44 item 2): each worker
//! holds one search ([`NestSearch`]), the page's main thread runs the
//! exchange of [`crate::nest::team`] between them by `postMessage`
//! (www/nest-team.js): every worker runs to the same evaluation count,
//! hands its best nest over, and takes the best of all of them.
//!
//! ```js
//! const s = nester.search(settings, k);              // search k of the team
//! while (s.run(until += every, clock, onProgress)) { // paused: exchange
//!   s.adopt(bestsOfAllWorkers);                       // [s.best(), …] in worker order
//! }
//! const result = s.finish(teamEvaluations, seconds); // a NestResult
//! ```

use wasm_bindgen::prelude::*;

use super::nest_progress::{js_clock, tell};
use super::nest_result::{NestResult, Priced};
use super::nest_settings::combination_given;
use super::Nester;
use crate::nest::team::{seed_of, team_best};
use crate::nest::{Best, Nest, NestJob, Placement, Search, Unplaced};
use crate::warning::Lang;

/// One search of a team, paused between exchanges.
#[wasm_bindgen]
pub struct NestSearch {
    lang: Lang,
    job: NestJob,
    notes: Vec<Unplaced>,
    search: Option<Search>,
    /// The placements last sent to the page.
    shown: Option<Vec<Placement>>,
    /// Sheets at a cost: the stock and the combination searched.
    priced: Option<Priced>,
}

fn err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

#[wasm_bindgen]
impl Nester {
    /// Search `k` (0, 1, …) of a team nesting these parts with `settings`
    /// (as `nest` takes them; one torch): search 0 has the settings' seed
    /// and is `nest`'s own search, the others seeds drawn from it.
    /// With costs, the `combination` given is searched (a trial that
    /// [`super::NestTrials`] gives, or a stopped cheapest nest kept): a team
    /// does not choose among combinations itself.
    pub fn search(&self, settings: JsValue, k: usize) -> Result<NestSearch, JsError> {
        let given = combination_given(&settings);
        let (job, priced) = self.priced_job(settings)?;
        if priced.is_some() && !given {
            return Err(super::say(
                self.lang,
                crate::text!("sheets at a cost: a team searches one combination at a time (the trials say which)";
                             "chapas com custo: uma equipe busca uma combinação por vez (as tentativas dizem qual)"),
            ));
        }
        let search = Search::new(&job, seed_of(job.settings.seed, k))
            .map_err(|e| super::say(self.lang, e.text()))?;
        Ok(NestSearch {
            lang: self.lang,
            job,
            notes: self.notes.clone(),
            search: Some(search),
            shown: None,
            priced,
        })
    }
}

#[wasm_bindgen]
impl NestSearch {
    /// Runs up to the first pause from `until` evaluations on, or to the
    /// end of the budget; `on_progress` hears as `Nester.nest`'s does, with
    /// `best` (the nest to adopt, or to keep on Stop) whenever the
    /// placements change, and stops every search by returning `false`.
    /// True when it paused with more to do.
    pub fn run(
        &mut self,
        until: f64,
        clock: js_sys::Function,
        on_progress: Option<js_sys::Function>,
    ) -> bool {
        let Some(search) = &mut self.search else {
            return false;
        };
        let until = (until.is_finite() && until >= 0.0).then_some(until as u64);
        let now = || js_clock(&clock);
        let shown = &mut self.shown;
        search.run(until, &now, &mut |p| {
            tell(on_progress.as_ref(), shown, p, true)
        })
    }

    /// The best nest so far, for the other workers' `adopt` (null before
    /// the first nest).
    pub fn best(&self) -> JsValue {
        self.search
            .as_ref()
            .and_then(Search::best)
            .and_then(|b| serde_wasm_bindgen::to_value(&b).ok())
            .unwrap_or(JsValue::NULL)
    }

    /// The exchange: `bests` is every worker's `best()` in worker order
    /// (nulls allowed); the best of them (the first among equals) becomes
    /// this search's when it is better than its own. True when taken.
    pub fn adopt(&mut self, bests: JsValue) -> Result<bool, JsError> {
        let bests: Vec<Option<Best>> =
            serde_wasm_bindgen::from_value(bests).map_err(|e| err(format!("bests: {e}")))?;
        let Some(search) = &mut self.search else {
            return Ok(false);
        };
        let eps = self.job.settings.touch();
        Ok(team_best(&bests, eps).is_some_and(|(_, b)| search.adopt(b)))
    }

    /// Evaluations this search made.
    pub fn evaluations(&self) -> f64 {
        self.search.as_ref().map_or(0.0, |s| s.evaluations() as f64)
    }

    /// The nest: this search's best (after the last exchange, the team's),
    /// `evaluations` the team's sum, `seconds` its wall time. The search
    /// is spent: a second call throws.
    pub fn finish(&mut self, evaluations: f64, seconds: f64) -> Result<NestResult, JsError> {
        let nest = self.take(evaluations)?;
        Ok(NestResult::fresh(
            self.lang,
            self.job.clone(),
            nest,
            &self.notes,
            seconds,
            None,
            self.priced.clone(),
        ))
    }
}

impl NestSearch {
    /// This search's best nest as the engine made it (the files' notes not
    /// added), `evaluations` the team's sum; the search is spent.
    pub(super) fn take(&mut self, evaluations: f64) -> Result<Nest, JsError> {
        let search = self
            .search
            .take()
            .ok_or_else(|| err("the search was finished already"))?;
        let mut nest = search.finish();
        if evaluations.is_finite() && evaluations >= 0.0 {
            nest.evaluations = evaluations as u64;
        }
        Ok(nest)
    }
}
