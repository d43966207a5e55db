//! The cuts of a program written on several threads (issue 17: ~110 ms
//! of the 25 MB nest's ~900 ms, mostly numbers formatted and stored).
//!
//! What one cut writes depends on what the cuts before it left: the
//! machine's position and motion word (modal posts leave out a word that
//! is already so), whether the feed was given, the height lock's pending
//! changes, a knife's unwrapped heading, the next block number. Most of it
//! is set again by the cut before: its rapid sets the position, its
//! blocks the motion word and the feed. So each run of cuts after the
//! first starts from a copy of the emitter after the header that writes
//! the cut just before the run (thrown away), then writes the run into
//! its own buffer. Runs are then checked in the program's order: a run
//! whose start state is not exactly where the run before it ended (a mark
//! or spot after a cut with a lock change left, a probe post's feed) is
//! written again, on this thread, from the right state. The program is
//! the same with any number of threads by construction; tests/threads.rs
//! and `runs_tests` compare it byte for byte.
//!
//! Posts that number their blocks (the number counts every block before)
//! or turn a knife (its heading is unwrapped over the whole program) are
//! written on one thread.

use super::emit::Cutter;
use super::post::Post;
use super::JobInfo;
use crate::par::{self, Threads};
use crate::plan::CutPlan;

/// Cuts a run at least: ~1 ms of writing (~0.8 µs a cut on the generated
/// nests), against ~50 µs to start a thread and a cut written twice.
const MIN_RUN: usize = 1500;

/// Bytes a cut takes, about (~210 on the generated nests): each run's
/// buffer is reserved from it.
const CUT_BYTES: usize = 256;

/// Room left after the cuts for the footer (a longer one costs a copy).
const FOOTER_BYTES: usize = 1 << 16;

/// Writes a G-code program (the post is already validated).
pub(crate) fn gcode(plan: &CutPlan, post: &Post, job: &JobInfo) -> String {
    let mut c = Cutter::new(plan, post, job);
    if write_cuts(&mut c, job.threads).is_none() {
        for i in 0..plan.cuts.len() {
            c.cut(i);
        }
    }
    c.finish()
}

/// One run of cuts written from a guessed start.
struct Run<'a> {
    range: std::ops::Range<usize>,
    /// The state the run started from (None: the header's, exact).
    entry: Option<Cutter<'a>>,
    text: Vec<u8>,
    exit: Cutter<'a>,
}

/// Writes every cut of `c`'s plan on `threads` and returns how many runs
/// were written again, or returns None and writes nothing when one thread
/// does it better (one thread asked, few cuts, a post whose state runs
/// through the program).
pub(super) fn write_cuts(c: &mut Cutter, threads: Threads) -> Option<usize> {
    write_runs(c, threads, MIN_RUN)
}

/// [`write_cuts`] in runs of `min_run` cuts at least.
fn write_runs(c: &mut Cutter, threads: Threads, min_run: usize) -> Option<usize> {
    let n = c.plan.cuts.len();
    if threads.get() == 1
        || n < 2 * min_run
        || c.post.line_numbers.is_some()
        || c.post.knife.is_some()
        || c.post.incremental
    {
        return None;
    }
    let mut base = c.clone();
    base.w.take_program(0);
    let runs = par::map_ranges(n, threads, min_run, |range| {
        let mut x = base.clone();
        let entry = (range.start > 0).then(|| {
            x.cut(range.start - 1);
            x.w.take_program(0);
            x.clone()
        });
        x.w.take_program(CUT_BYTES * range.len());
        for i in range.clone() {
            x.cut(i);
        }
        let text = x.w.take_program(0);
        Run {
            range,
            entry,
            text,
            exit: x,
        }
    });
    let mut redone = 0;
    let header = c.w.take_program(0);
    let mut texts: Vec<Vec<u8>> = Vec::with_capacity(runs.len());
    let mut end: Option<Cutter> = None;
    for run in runs {
        let exact = match (&run.entry, &end) {
            (None, _) => true,
            (Some(entry), Some(end)) => entry.same_course(end),
            (Some(_), None) => false,
        };
        if exact {
            texts.push(run.text);
            end = Some(run.exit);
            continue;
        }
        redone += 1;
        // Written again from where the program really is.
        let mut x = end.take().unwrap_or_else(|| base.clone());
        for i in run.range {
            x.cut(i);
        }
        texts.push(x.w.take_program(0));
        end = Some(x);
    }
    if let Some(end) = end {
        *c = end;
    }
    let mut parts: Vec<&[u8]> = vec![&header];
    parts.extend(texts.iter().map(Vec::as_slice));
    let size: usize = parts.iter().map(|p| p.len()).sum();
    // Zeroed pages come from the system untouched: the threads that copy
    // into them take their first-write faults too. Room for the footer.
    let mut out = vec![0u8; size + FOOTER_BYTES];
    fill(&mut out[..size], &parts, threads);
    out.truncate(size);
    c.w.set_program(out);
    Some(redone)
}

/// `parts` copied one after the other into `dst` (exactly their length),
/// halves on two threads at once while there are threads to share.
fn fill(dst: &mut [u8], parts: &[&[u8]], threads: Threads) {
    let t = threads.get();
    if t == 1 || parts.len() < 2 {
        let mut at = 0;
        for p in parts {
            dst[at..at + p.len()].copy_from_slice(p);
            at += p.len();
        }
        return;
    }
    let mid = parts.len() / 2;
    let left: usize = parts[..mid].iter().map(|p| p.len()).sum();
    let (a, b) = dst.split_at_mut(left);
    let (ta, tb) = (Threads::new(t - t / 2), Threads::new(t / 2));
    par::join(
        threads,
        || fill(a, &parts[..mid], ta),
        || fill(b, &parts[mid..], tb),
    );
}

#[cfg(test)]
#[path = "runs_tests.rs"]
mod tests;
