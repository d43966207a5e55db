//! Work shared among a shop PC's cores, natively (issue 17: the 25 MB
//! nest's wall time). Every helper here gives exactly what one thread
//! gives, in the same order: a stage's output never depends on how many
//! threads made it (tests/threads.rs compares programs made with 1 and
//! with several threads, byte for byte).
//!
//! The page's WebAssembly has no std threads (spawning panics there), so
//! on wasm32 everything runs on the calling thread whatever is asked.

use std::num::NonZeroUsize;
use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};

/// How many threads a stage may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Threads(NonZeroUsize);

/// More threads than this buy nothing on the stages' sizes (and a CLI
/// run on a 64-core server should not start 64 threads per stage).
const MOST: usize = 8;

impl Threads {
    /// One thread: the calling one.
    pub const ONE: Threads = Threads(NonZeroUsize::MIN);

    /// `n` threads (0 is read as 1; more than 8 as 8).
    pub fn new(n: usize) -> Threads {
        Threads(NonZeroUsize::new(n.clamp(1, MOST)).unwrap_or(NonZeroUsize::MIN))
    }

    /// The machine's cores (at most 8); one in the page.
    pub fn available() -> Threads {
        if cfg!(target_arch = "wasm32") {
            return Threads::ONE;
        }
        Threads::new(std::thread::available_parallelism().map_or(1, NonZeroUsize::get))
    }

    /// The count.
    pub fn get(self) -> usize {
        if cfg!(target_arch = "wasm32") {
            1
        } else {
            self.0.get()
        }
    }
}

impl Default for Threads {
    /// [`Threads::available`].
    fn default() -> Threads {
        Threads::available()
    }
}

/// Runs `work` on contiguous ranges that cover `0..n` and returns its
/// results in the ranges' order. With one thread (or fewer than
/// `2 * min_chunk` items) it is `vec![work(0..n)]`. Otherwise the items are
/// cut into a few chunks per thread, of `min_chunk` items at least, and the
/// threads take the next chunk as they finish one: a chunk of big loops
/// does not hold the others up.
pub fn map_ranges<R, F>(n: usize, threads: Threads, min_chunk: usize, work: F) -> Vec<R>
where
    R: Send,
    F: Fn(Range<usize>) -> R + Sync,
{
    let t = threads.get();
    let min_chunk = min_chunk.max(1);
    if t == 1 || n < 2 * min_chunk {
        return vec![work(0..n)];
    }
    let chunks = (4 * t).min(n / min_chunk).max(1);
    let next = AtomicUsize::new(0);
    let take = || {
        take_chunks(&next, chunks, |i| {
            work((i * n / chunks)..((i + 1) * n / chunks))
        })
    };
    let all: Vec<(usize, R)> = std::thread::scope(|s| {
        let others: Vec<_> = (1..t.min(chunks)).map(|_| s.spawn(take)).collect();
        let mut all = take();
        for h in others {
            // A worker's panic is the stage's panic, as with one thread.
            all.extend(h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        }
        all
    });
    in_order(all)
}

/// Chunks `0..chunks` taken one after another through `next` (shared by
/// the threads taking them), each with `work`'s result, until none is
/// left.
fn take_chunks<R>(next: &AtomicUsize, chunks: usize, work: impl Fn(usize) -> R) -> Vec<(usize, R)> {
    let mut done = Vec::new();
    loop {
        let i = next.fetch_add(1, Ordering::Relaxed);
        if i >= chunks {
            return done;
        }
        done.push((i, work(i)));
    }
}

/// The results of [`take_chunks`] from every thread, in the chunks' order.
fn in_order<R>(mut all: Vec<(usize, R)>) -> Vec<R> {
    all.sort_unstable_by_key(|(i, _)| *i);
    all.into_iter().map(|(_, r)| r).collect()
}

/// Runs `a` and `b` at once when there are two threads or more (`b` on a
/// second thread), one after the other otherwise.
pub fn join<A, B, FA, FB>(threads: Threads, a: FA, b: FB) -> (A, B)
where
    A: Send,
    B: Send,
    FA: FnOnce() -> A + Send,
    FB: FnOnce() -> B + Send,
{
    if threads.get() == 1 {
        let ra = a();
        return (ra, b());
    }
    std::thread::scope(|s| {
        let hb = s.spawn(b);
        let ra = a();
        let rb = hb.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        (ra, rb)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_cover_every_item_once_in_order() {
        for n in [0, 1, 5, 63, 64, 1000, 12_345] {
            for t in 1..=5 {
                for min in [1, 7, 64] {
                    let parts = map_ranges(n, Threads::new(t), min, |r| r.collect::<Vec<_>>());
                    let flat: Vec<usize> = parts.concat();
                    assert_eq!(flat, (0..n).collect::<Vec<_>>(), "n {n} t {t} min {min}");
                    if t > 1 && n >= 2 * min {
                        assert!(
                            parts.iter().all(|p| p.len() >= min),
                            "n {n} t {t} min {min}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn threads_are_clamped() {
        assert_eq!(Threads::new(0).get(), 1);
        assert_eq!(Threads::new(3).get(), 3);
        assert_eq!(Threads::new(100).get(), MOST);
        assert!(Threads::available().get() >= 1);
    }

    #[test]
    fn join_gives_both_results() {
        for t in [1, 2] {
            let v: Vec<u32> = (0..100).collect();
            let (a, b) = join(Threads::new(t), || v.iter().sum::<u32>(), || v.len());
            assert_eq!((a, b), (4950, 100));
        }
    }
}
