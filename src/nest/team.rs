//! Several searches of one job at once, one per core (issue 44 item 2):
//! independent searches, each with its own seed, that pause every
//! [`EXCHANGE_EVERY`] evaluations and all take the best nest any of them
//! holds (the lowest search number among equals: [`super::pick`]), then
//! go on from it with their own choices. This is the island model of
//! parallel metaheuristics with migration of the best (Alba & Tomassini,
//! IEEE TEC 2002), the migration at fixed evaluation counts so that it
//! depends on no clock.
//!
//! Deterministic: with a budget in evaluations (each search's, not the
//! team's), the same job, seed and number of searches give the same nest
//! on any machine and load, as one search does. Under a time budget each
//! search stops when the clock runs out, at a count that depends on the
//! machine: the nest is the one that the evaluation counts reached would
//! give, not reproducible from the seed alone. The page runs the same
//! exchange between web workers through its main thread (www/nest-team.js);
//! natively the searches are scoped threads.
//!
//! A team of one is [`super::nest`]: search 0 keeps the job's seed, and
//! a search paused without adopting is the run it would have been.

use std::sync::atomic::{AtomicBool, Ordering};

use super::rng::SplitMix;
use super::{nest, pick, Best, Nest, NestError, NestJob, Progress, Search};

/// Evaluations between two exchanges, per search: about a second of one
/// core's separation on the ESICUP instances (5 000–13 000 evaluations
/// a second), some tens of exchanges in a minute's run.
pub const EXCHANGE_EVERY: u64 = 10_000;

/// Most searches at once: the page caps its workers at 4 (a shop PC's
/// cores); the CLI at [`crate::par::Threads`]' 8.
pub const MOST: usize = 8;

/// The seed of search `k` of a team whose job is seeded `seed`: search 0
/// keeps it, the others draw theirs from it.
pub fn seed_of(seed: u64, k: usize) -> u64 {
    if k == 0 {
        return seed;
    }
    let mut g = SplitMix(seed ^ (k as u64).wrapping_mul(0xD1B5_4A32_D192_ED03));
    g.next()
}

/// The best of the searches' best nests (None before any first nest),
/// with the number of the search holding it.
pub fn team_best(bests: &[Option<Best>], eps: f64) -> Option<(usize, &Best)> {
    let have: Vec<(usize, &Best)> = bests
        .iter()
        .enumerate()
        .filter_map(|(k, b)| b.as_ref().map(|b| (k, b)))
        .collect();
    let list: Vec<&Best> = have.iter().map(|h| h.1).collect();
    (!have.is_empty()).then(|| have[pick(&list, eps)])
}

/// Nests `job` with `searches` searches on as many threads (one search:
/// [`nest`] itself), exchanging their best every [`EXCHANGE_EVERY`]
/// evaluations; the settings' budget holds for each search. `progress`
/// hears search 0, which holds the team's best after each exchange; false
/// stops every search. The nest's evaluations are the team's sum.
pub fn nest_team(
    job: &NestJob,
    searches: usize,
    clock: &(dyn Fn() -> f64 + Sync),
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Nest, NestError> {
    nest_team_every(job, searches, EXCHANGE_EVERY, clock, progress)
}

/// [`nest_team`] exchanging every `every` evaluations.
pub fn nest_team_every(
    job: &NestJob,
    searches: usize,
    every: u64,
    clock: &(dyn Fn() -> f64 + Sync),
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Nest, NestError> {
    let n = searches.clamp(1, MOST);
    let every = every.max(1);
    if n == 1 || cfg!(target_arch = "wasm32") {
        return nest(job, clock, progress);
    }
    let mut team = (0..n)
        .map(|k| Search::new(job, seed_of(job.settings.seed, k)))
        .collect::<Result<Vec<_>, _>>()?;
    let eps = job.settings.touch();
    let stop = AtomicBool::new(false);
    let mut until = 0u64;
    loop {
        until = until.saturating_add(every);
        let (first, rest) = team.split_at_mut(1);
        let stop = &stop;
        let paused = std::thread::scope(|s| {
            let others: Vec<_> = rest
                .iter_mut()
                .map(|search| {
                    s.spawn(move || {
                        search.run(Some(until), clock, &mut |_| !stop.load(Ordering::Relaxed))
                    })
                })
                .collect();
            let mut hear = |p: Progress| {
                let go = progress(p);
                if !go {
                    stop.store(true, Ordering::Relaxed);
                }
                go
            };
            let mut paused = first[0].run(Some(until), clock, &mut hear);
            for h in others {
                // A search's panic is the nest's panic, as with one thread.
                paused |= h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
            }
            paused
        });
        let bests: Vec<Option<Best>> = team.iter().map(Search::best).collect();
        if let Some((_, best)) = team_best(&bests, eps) {
            for search in &mut team {
                search.adopt(best);
            }
        }
        if !paused || stop.load(Ordering::Relaxed) {
            break;
        }
    }
    let evaluations = team.iter().map(Search::evaluations).sum();
    let mut nest = team.swap_remove(0).finish();
    nest.evaluations = evaluations;
    Ok(nest)
}

#[cfg(test)]
#[path = "team_tests.rs"]
mod tests;
