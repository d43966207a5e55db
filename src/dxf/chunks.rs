//! The ENTITIES section of a big ASCII DXF read on several threads (issue
//! 17): cut into chunks at entity starts, each chunk read by its own
//! [`Reader`] forked from the one that read HEADER, TABLES and BLOCKS, and
//! the chunks joined in file order into exactly the drawing one reader
//! makes (entities, places, layers and their order, counts, extent,
//! warnings). Binary DXF, and any chunk the join cannot vouch for, are
//! read by the one reader as before.
//!
//! Why a cut is safe. A cut is made at the start of a line holding `0`
//! whose next line is a type name (not a group code, not VERTEX, ATTRIB or
//! SEQEND, whose pairs belong to the entity before). Chunk 0 starts where
//! the one reader stands. A chunk read to its end without running out in
//! the middle of a pair (a code line without its value line) ends where
//! the one reader would also stand at a group code: both read the same
//! lines the same way (blank lines where a code is due are skipped by
//! both). So the next chunk starts in step with the one reader, and its
//! first pair `0 TYPE` ends the entity before it there as the end of the
//! chunk did (neither a child nor SEQEND follows). A cut that fell on a
//! value line shows as that running out; from there the one reader reads
//! on alone. A chunk that met ENDSEC, EOF, SECTION or a bad group code
//! ends the entities: the chunks after it are dropped.
//!
//! The one reader also reads on alone from a chunk after the first that
//! warned (its warnings name lines counted from the chunk's start, known
//! only once the chunks before it are read) or that came near the segment
//! budget ([`super::MAX_SEGMENTS`]: what was left of it when the chunk
//! started on its own thread is more than the one reader has at that point).

use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

use super::pairs::{find_newline, parse_code, AsciiPairs, BadCode, Pair, Place, Source};
use super::reader::Reader;
use super::stream::Stream;
use super::walk::Scratch;
use crate::par::Threads;

/// Least bytes of a chunk: a chunk is milliseconds of reading, well above
/// a thread's start (~50 µs), and a file under two of them is read alone.
const MIN_CHUNK_BYTES: usize = 512 * 1024;

thread_local! {
    /// [`MIN_CHUNK_BYTES`], smaller in tests so that small files are cut.
    static CHUNK_BYTES: Cell<usize> = const { Cell::new(MIN_CHUNK_BYTES) };
}

/// Sets the least chunk size for reads on this thread (tests cut small files).
#[cfg(test)]
pub(super) fn set_chunk_bytes(n: usize) {
    CHUNK_BYTES.with(|c| c.set(n.max(1)));
}

#[cfg(test)]
thread_local! {
    /// Chunks joined by reads on this thread (tests check that files are cut).
    pub(super) static JOINED: Cell<usize> = const { Cell::new(0) };
}

/// Chunks after the first count their lines from here: their line numbers
/// are not known until the chunks before them are read. A place at or past
/// it is a chunk's own and moved to the file's line when joined; a place
/// below it is a block definition's (already the file's). No file has this
/// many lines.
const FAR: usize = usize::MAX / 2;

/// What one chunk's reader made, and where its pairs stopped.
struct Chunk<'a, 'o> {
    r: Reader<'a, 'o>,
    it: AsciiPairs<'a>,
    peeked: Option<Pair<'a>>,
    bad: Option<BadCode>,
    /// ENDSEC, EOF or SECTION ended it.
    stopped: bool,
}

impl<'a, 'o> Reader<'a, 'o> {
    /// [`Reader::stream_entities`], on the threads of the options when the
    /// rest of an ASCII file is big enough to cut.
    pub fn stream_entities_par<I>(
        &mut self,
        pre: &[Pair<'a>],
        s: &mut Stream<'a, I>,
        sc: &mut Scratch<'a>,
    ) where
        I: Source<'a>,
    {
        let t = self.options.threads.get();
        if t > 1 && s.is_clear() {
            if let Some(it) = s.inner_mut().ascii() {
                let (rest, line) = (it.rest, it.line);
                let n = (4 * t).min(rest.len() / CHUNK_BYTES.with(Cell::get));
                let cuts = cuts(rest, n);
                if cuts.len() > 1 {
                    self.chunked(pre, s, sc, rest, line, &cuts);
                    return;
                }
            }
        }
        self.stream_entities(pre, s, sc);
    }

    /// Reads the chunks of `rest` starting at `cuts` on the threads and
    /// joins them in order; `line` is the lines read before `rest`.
    fn chunked<I>(
        &mut self,
        pre: &[Pair<'a>],
        s: &mut Stream<'a, I>,
        sc: &mut Scratch<'a>,
        rest: &'a [u8],
        line: usize,
        cuts: &[usize],
    ) where
        I: Source<'a>,
    {
        let n = cuts.len();
        // The context the chunks' readers start from (this reader is
        // joining chunks while they are read).
        let base = self.fork();
        let read = |i: usize| {
            let end = cuts.get(i + 1).copied().unwrap_or(rest.len());
            let mut r = base.fork();
            let mut cs = Stream::new(AsciiPairs {
                rest: &rest[cuts[i]..end],
                line: if i == 0 { line } else { FAR },
                truncated: false,
            });
            let stopped = r.stream_entities(pre, &mut cs, &mut Scratch::default());
            let (it, peeked, bad) = cs.into_parts();
            Chunk {
                r,
                it,
                peeked,
                bad,
                stopped,
            }
        };
        let budget = self.budget;
        let mut line = line;
        let mut redo = false;
        // Joins chunk `i`; false when the entities end there (or the one
        // reader read on from it).
        let join_next = |i: usize, c: Chunk<'a, 'o>| -> bool {
            let last = i + 1 == n;
            let ends = last || c.stopped || c.bad.is_some();
            // How much less budget the one reader has here than the chunk
            // had: the same reading if no request of the chunk came within
            // that of its budget, and it ended with some left over.
            let less = budget - self.budget;
            let budget_ok = less == 0 || (c.r.room >= less && c.r.budget > less);
            // Warnings of later chunks name places by their own lines.
            let ok =
                budget_ok && (i == 0 || c.r.d.warnings.is_empty()) && (ends || !c.it.truncated);
            let Some(it) = s.inner_mut().ascii() else {
                return false;
            };
            if !ok {
                // Read on alone once the threads have stopped.
                *it = AsciiPairs {
                    rest: &rest[cuts[i]..],
                    line,
                    truncated: false,
                };
                redo = true;
                return false;
            }
            #[cfg(test)]
            JOINED.with(|j| j.set(j.get() + 1));
            let fix = |at: usize| if at >= FAR { at - FAR + line } else { at };
            // Room for as many entities again in each chunk to come.
            let more = (n - i - 1) * c.r.d.entities.len();
            if ends {
                // On from where the chunk stopped, to the end of the file
                // (a chunk's bytes end at the next cut).
                let end = cuts.get(i + 1).copied().unwrap_or(rest.len());
                // After a bad code nothing is read (its reader emptied its bytes).
                let from = if c.bad.is_some() {
                    rest.len()
                } else {
                    end - c.it.rest.len()
                };
                *it = AsciiPairs {
                    rest: &rest[from..],
                    line: fix(c.it.line),
                    truncated: c.it.truncated,
                };
                let peeked = c.peeked.map(|p| Pair { at: fix(p.at), ..p });
                let bad = c.bad.map(|b| BadCode {
                    place: moved(b.place, &fix),
                    ..b
                });
                self.join(c.r, &fix, budget, more);
                s.resume(peeked, bad);
                return false;
            }
            let next = fix(c.it.line);
            self.join(c.r, &fix, budget, more);
            line = next;
            true
        };
        in_order(n, base.options.threads, read, join_next);
        if redo {
            s.resume(None, None);
            self.stream_entities(pre, s, sc);
        }
    }

    /// Adds what a chunk's reader (forked with `budget`) made to this one's,
    /// as if this one had read the chunk; `fix` moves its places.
    /// Room is made for `more` entities to come when the drawing has none yet.
    fn join(
        &mut self,
        c: Reader<'a, 'o>,
        fix: &dyn Fn(usize) -> usize,
        budget: usize,
        more: usize,
    ) {
        // Layers the chunk made are made here in its order: the same as
        // when they are first met by this reader, or found when an earlier
        // chunk made them.
        let shared = c.d.layers.len() - c.made_layers.len();
        let mut map: Vec<u32> = (0..shared as u32).collect();
        for &raw in &c.made_layers {
            map.push(self.layer_id(raw));
        }
        let id = |l: u32| map[l as usize];
        for (l, layer) in c.d.layers.iter().enumerate() {
            self.d.layers[map[l] as usize].entities += layer.entities;
        }
        for (l, k) in c.off_layers {
            *self.off_layers.entry(id(l)).or_default() += k;
        }
        let before = self.d.entities.len();
        // The chunk's INSERT copies follow this reader's.
        let shift = self.d.inserts.len() as u32;
        self.d.inserts.extend(c.d.inserts.into_iter().map(|mut i| {
            i.parent = i.parent.map(|p| p + shift);
            i
        }));
        let mut es = c.d.entities;
        for e in &mut es {
            e.layer = id(e.layer);
            e.place = moved(e.place, fix);
            e.insert = e.insert.map(|i| i + shift);
        }
        if before == 0 {
            // Taken over, not copied (a copy of a big nest's entities is
            // tens of megabytes, on the one thread).
            es.reserve(more);
            self.d.entities = es;
        } else {
            self.d.entities.append(&mut es);
        }
        self.d.spots.extend(c.d.spots.into_iter().map(|mut s| {
            s.layer = id(s.layer);
            s.after_entities += before;
            s
        }));
        self.d.warnings.extend(c.d.warnings);
        for (k, n) in c.count_runs.into_iter().chain(c.counts) {
            *self.counts.entry(k).or_default() += n;
        }
        for (k, n) in c.skipped {
            *self.skipped.entry(k).or_default() += n;
        }
        for (k, n) in c.in_blocks_skipped {
            *self.in_blocks_skipped.entry(k).or_default() += n;
        }
        self.paper_space += c.paper_space;
        self.tilted += c.tilted;
        if let Some((n, lo, hi, first)) = c.not_flat {
            let first = moved(first, fix);
            let f = self.not_flat.get_or_insert((0, lo, hi, first));
            *f = (f.0 + n, f.1.min(lo), f.2.max(hi), f.3);
        }
        // Each side its own running minimum or maximum: what one running
        // over both gives, bit for bit (`BBox::add` per point would mix a
        // box's min and max when they are equal zeros of two signs).
        let (e, o) = (&mut self.extent, &c.extent);
        if !o.is_empty() {
            e.min.x = e.min.x.min(o.min.x);
            e.min.y = e.min.y.min(o.min.y);
            e.max.x = e.max.x.max(o.max.x);
            e.max.y = e.max.y.max(o.max.y);
        }
        self.budget -= budget - c.budget;
    }
}

/// A chunk's place at the file's line (`fix`); other places as they are.
fn moved(p: Place, fix: &dyn Fn(usize) -> usize) -> Place {
    match p {
        Place::Line(l) => Place::Line(fix(l)),
        p => p,
    }
}

/// Runs `work` on `0..n` on the threads and hands each result to `take` in
/// index order, on this thread, as soon as it and those before it are
/// done (the joining overlaps the reading of later chunks); stops when
/// `take` says false. The threads take the next index as they finish one,
/// this thread too while the result it waits for is not done.
fn in_order<R, W, T>(n: usize, threads: Threads, work: W, mut take: T)
where
    R: Send,
    W: Fn(usize) -> R + Sync,
    T: FnMut(usize, R) -> bool,
{
    let t = threads.get().min(n);
    if t <= 1 {
        for i in 0..n {
            if !take(i, work(i)) {
                return;
            }
        }
        return;
    }
    let next = AtomicUsize::new(0);
    let (work, next) = (&work, &next);
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel::<(usize, R)>();
        for _ in 1..t {
            let tx = tx.clone();
            s.spawn(move || loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                // Stop when all are taken, or when `take` no longer wants any.
                if i >= n || tx.send((i, work(i))).is_err() {
                    return;
                }
            });
        }
        drop(tx);
        let mut done: Vec<Option<R>> = (0..n).map(|_| None).collect();
        let mut want = 0;
        while want < n {
            if let Some(r) = done[want].take() {
                if !take(want, r) {
                    // No more chunks are started (the ones being read are dropped).
                    next.store(n, Ordering::Relaxed);
                    return;
                }
                want += 1;
                continue;
            }
            if let Ok((i, r)) = rx.try_recv() {
                done[i] = Some(r);
                continue;
            }
            let i = next.fetch_add(1, Ordering::Relaxed);
            if i < n {
                done[i] = Some(work(i));
                continue;
            }
            match rx.recv() {
                Ok((i, r)) => done[i] = Some(r),
                // Every index was taken and every thread has ended: one
                // panicked (the scope passes its panic on).
                Err(_) => return,
            }
        }
    });
}

/// How far after a guessed cut an entity start is looked for.
const SEARCH_BYTES: usize = 1 << 20;

/// Where to cut `rest` (the ENTITIES section and what follows) into about
/// `n` chunks: 0, then the starts of entity lines near `k / n` of the way.
fn cuts(rest: &[u8], n: usize) -> Vec<usize> {
    let mut out = vec![0];
    for k in 1..n {
        // A megabyte without an entity start (one polyline of a million
        // vertices) is not searched further: one chunk fewer.
        let from = k * rest.len() / n;
        let to = ((k + 1) * rest.len() / n).min(from + SEARCH_BYTES);
        if let Some(c) = entity_start(rest, from, to) {
            out.push(c);
        }
    }
    out
}

/// The first line after `from` that holds `0` and is followed by a type
/// name, when it starts before `to`.
fn entity_start(b: &[u8], from: usize, to: usize) -> Option<usize> {
    let mut at = from + find_newline(b.get(from..)?)? + 1;
    let mut zero: Option<usize> = None;
    while at < to {
        let end = at + find_newline(&b[at..])?;
        let line = b[at..end].trim_ascii();
        if let Some(z) = zero {
            let child = matches!(line, b"VERTEX" | b"ATTRIB" | b"SEQEND");
            let ends = matches!(line, b"ENDSEC" | b"EOF" | b"SECTION");
            if !line.is_empty() && parse_code(line).is_none() && !child && !ends {
                return Some(z);
            }
        }
        zero = (line == b"0").then_some(at);
        at = end + 1;
    }
    None
}

#[cfg(test)]
#[path = "chunks_tests.rs"]
mod tests;
