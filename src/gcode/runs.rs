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
use crate::par::{self, Threads};

/// Cuts a run at least: ~1 ms of writing (~0.8 µs a cut on the generated
/// nests), against ~50 µs to start a thread and a cut written twice.
const MIN_RUN: usize = 1500;

/// Bytes a cut takes, about (~210 on the generated nests): each run's
/// buffer is reserved from it.
const CUT_BYTES: usize = 256;

/// One run of cuts written from a guessed start.
struct Run<'a> {
    range: std::ops::Range<usize>,
    /// The state the run started from (None: the header's, exact).
    entry: Option<Cutter<'a>>,
    text: Vec<u8>,
    exit: Cutter<'a>,
}

/// Writes every cut of `c`'s plan on `threads` and returns true, or
/// returns false and writes nothing when one thread does it better (one
/// thread asked, few cuts, a post whose state runs through the program).
pub(super) fn write_cuts(c: &mut Cutter, threads: Threads) -> bool {
    let n = c.plan.cuts.len();
    if threads.get() == 1
        || n < 2 * MIN_RUN
        || c.post.line_numbers.is_some()
        || c.post.knife.is_some()
    {
        return false;
    }
    let mut base = c.clone();
    base.w.take_program(0);
    let runs = par::map_ranges(n, threads, MIN_RUN, |range| {
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
    let mut out = c.w.take_program(0);
    let mut end: Option<Cutter> = None;
    for run in runs {
        let exact = match (&run.entry, &end) {
            (None, _) => true,
            (Some(entry), Some(end)) => entry.same_course(end),
            (Some(_), None) => false,
        };
        if exact {
            out.extend_from_slice(&run.text);
            end = Some(run.exit);
            continue;
        }
        // Written again from where the program really is.
        let mut x = end.take().unwrap_or_else(|| base.clone());
        for i in run.range {
            x.cut(i);
        }
        out.extend_from_slice(&x.w.take_program(0));
        end = Some(x);
    }
    if let Some(end) = end {
        *c = end;
    }
    c.w.set_program(out);
    true
}
