//! The program's bytes as the writer appends them (issue 17, the page).
//!
//! Two ways with one interface: [`Bytes`] is [`Staged`] in the page's
//! build and [`Plain`] (a vector) in the native one.
//!
//! Why [`Staged`] in the page: a program is millions of words of one to a
//! dozen bytes, and in the page's build (opt-level "s")
//! `Vec::extend_from_slice` is not inlined: each word was two calls and a
//! `memory.copy`, which the engine runs as a call of its own (on the 25 MB
//! nest ~120 of the G-code stage's ~340 ms, a named build's profile).
//! [`Staged`] keeps its buffer initialised a little ahead of the text, so
//! a word is a few stores into a slice, and a number its whole fixed-size
//! window copied (known length: plain stores, no call) with the length
//! moved on by its digits only. Under Node, the 25 MB nest's G-code stage
//! 322 -> 277 ms (medians of 5 alternating runs), +3.5 KB of gzipped
//! wasm (435,201 B in all, 425 KiB).
//! Natively the vector is faster (its copies are inlined at opt-level 3;
//! [`Staged`] there was 111 -> 118 ms, one thread): kept. The programs
//! are byte for byte the same either way.

/// The page's build: see the module's note.
#[cfg(target_arch = "wasm32")]
pub(crate) type Bytes = Staged;
/// The native build: see the module's note.
#[cfg(not(target_arch = "wasm32"))]
pub(crate) type Bytes = Plain;

/// A vector of bytes with [`Staged`]'s interface.
#[derive(Clone, Debug, Default)]
pub(crate) struct Plain(Vec<u8>);

#[allow(dead_code)]
impl Plain {
    /// Empty, with room reserved for `n` bytes.
    pub(crate) fn with_capacity(n: usize) -> Plain {
        Plain(Vec::with_capacity(n))
    }
    pub(crate) fn from_vec(v: Vec<u8>) -> Plain {
        Plain(v)
    }
    pub(crate) fn into_vec(self) -> Vec<u8> {
        self.0
    }
    pub(crate) fn as_slice(&self) -> &[u8] {
        &self.0
    }
    pub(crate) fn clear(&mut self) {
        self.0.clear();
    }
    #[inline]
    pub(crate) fn push(&mut self, b: u8) {
        self.0.push(b);
    }
    /// `s` appended: a letter, a separator, an empty frame, mostly, which a
    /// general copy (a call into `memcpy` each) took longer to write than
    /// the digits.
    #[inline]
    pub(crate) fn extend_from_slice(&mut self, s: &[u8]) {
        match s {
            [] => {}
            [c] => self.0.push(*c),
            _ => self.0.extend_from_slice(s),
        }
    }
    /// The first `n` bytes of `window` appended: the whole window copied,
    /// a copy of fixed size (a few moves, where one of the number's length
    /// was a call into `memcpy`), and the vector cut back.
    #[inline]
    pub(crate) fn put_window<const W: usize>(&mut self, window: &[u8; W], n: usize) {
        let end = self.0.len() + n.min(W);
        self.0.extend_from_slice(window);
        self.0.truncate(end);
    }
}

/// Bytes written so far (`buf[..len]`) and initialised room after them
/// (`buf[len..]`), made a chunk at a time just ahead of the text.
#[derive(Debug, Default)]
pub(crate) struct Staged {
    buf: Vec<u8>,
    len: usize,
}

/// Room initialised at a time: zeroed just before it is written over (a
/// program's whole reservation zeroed at once was ~20 ms of the page's
/// G-code stage on the 25 MB nest, 35 MB of it).
const CHUNK: usize = 64 * 1024;

/// The bytes written, not the room (as a vector's clone leaves its
/// capacity): the writer is cloned for each range of cuts written on a
/// thread.
impl Clone for Staged {
    fn clone(&self) -> Staged {
        Staged {
            buf: self.as_slice().to_vec(),
            len: self.len,
        }
    }
}

#[allow(dead_code)]
impl Staged {
    /// Empty, with room reserved for `n` bytes (not yet initialised).
    pub(crate) fn with_capacity(n: usize) -> Staged {
        Staged {
            buf: Vec::with_capacity(n),
            len: 0,
        }
    }

    /// `v`'s bytes (its spare capacity kept for what follows: a program
    /// handed back with room for its footer is not copied for it).
    pub(crate) fn from_vec(v: Vec<u8>) -> Staged {
        let len = v.len();
        Staged { buf: v, len }
    }

    /// The bytes written, as a vector.
    pub(crate) fn into_vec(mut self) -> Vec<u8> {
        self.buf.truncate(self.len);
        self.buf
    }

    /// The bytes written.
    pub(crate) fn as_slice(&self) -> &[u8] {
        &self.buf[..self.len]
    }

    pub(crate) fn clear(&mut self) {
        self.len = 0;
    }

    /// The `n` bytes after those written, made room for.
    #[inline(always)]
    fn room(&mut self, n: usize) -> &mut [u8] {
        let end = self.len + n;
        if end > self.buf.len() {
            self.grow(end);
        }
        &mut self.buf[self.len..end]
    }

    /// Room to `end` and a chunk more, but not past the reservation while
    /// `end` is within it (a program handed back with room for its footer
    /// is not copied for a chunk it does not need); beyond, the vector's
    /// own doubling.
    #[cold]
    #[inline(never)]
    fn grow(&mut self, end: usize) {
        let cap = self.buf.capacity();
        let want = if end <= cap {
            (end + CHUNK).min(cap)
        } else {
            end + CHUNK
        };
        self.buf.resize(want, 0);
    }

    #[inline(always)]
    pub(crate) fn push(&mut self, b: u8) {
        self.room(1)[0] = b;
        self.len += 1;
    }

    /// `s` appended: a word of up to four bytes (a letter, a separator, a
    /// motion word) a byte at a time, longer text in one copy.
    #[inline(always)]
    pub(crate) fn extend_from_slice(&mut self, s: &[u8]) {
        match *s {
            [] => return,
            [a] => self.room(1)[0] = a,
            [a, b] => {
                let r = self.room(2);
                r[0] = a;
                r[1] = b;
            }
            [a, b, c] => {
                let r = self.room(3);
                r[0] = a;
                r[1] = b;
                r[2] = c;
            }
            [a, b, c, d] => {
                let r = self.room(4);
                r[0] = a;
                r[1] = b;
                r[2] = c;
                r[3] = d;
            }
            _ => self.room(s.len()).copy_from_slice(s),
        }
        self.len += s.len();
    }

    /// The first `n` bytes of `window` appended, the whole window copied
    /// (a copy of fixed size) and the bytes after the `n` left as room.
    #[inline(always)]
    pub(crate) fn put_window<const W: usize>(&mut self, window: &[u8; W], n: usize) {
        if let Ok(dst) = <&mut [u8; W]>::try_from(self.room(W)) {
            *dst = *window;
        }
        self.len += n.min(W);
    }
}

#[cfg(test)]
mod tests {
    use super::{Plain, Staged};

    /// The same appends through both ways, against a plain vector's:
    /// every length of word, windows longer than what they keep, and
    /// growth from nothing, from a vector with spare room and from full
    /// (past [`super::CHUNK`] more than once).
    #[test]
    fn both_ways_append_as_a_vector_does() {
        for start in [Vec::new(), Vec::with_capacity(100), vec![b'a'; 3]] {
            let mut staged = Staged::from_vec(start.clone());
            let mut plain = Plain::from_vec(start.clone());
            let mut v = start;
            for i in 0..20_000usize {
                let word: Vec<u8> = (0..i % 9).map(|k| b'a' + ((i + k) % 26) as u8).collect();
                staged.extend_from_slice(&word);
                plain.extend_from_slice(&word);
                v.extend_from_slice(&word);
                let mut w = [b'#'; 28];
                w[..i % 29].fill(b'0' + (i % 10) as u8);
                staged.put_window(&w, i % 29);
                plain.put_window(&w, i % 29);
                v.extend_from_slice(&w[..(i % 29).min(28)]);
                staged.push(b'\n');
                plain.push(b'\n');
                v.push(b'\n');
                if i % 1000 == 0 {
                    assert_eq!(staged.as_slice(), &v[..]);
                    assert_eq!(plain.as_slice(), &v[..]);
                }
            }
            // Room within a reservation stays in it.
            let reserved = Vec::with_capacity(10);
            let cap = reserved.capacity();
            let mut held = Staged::from_vec(reserved);
            held.extend_from_slice(b"G0 X1 Y2");
            assert_eq!(held.buf.capacity(), cap);
            let copy = staged.clone();
            assert_eq!(copy.buf.len(), copy.len, "a copy has no room");
            assert_eq!(copy.into_vec(), v);
            assert_eq!(plain.clone().into_vec(), v);
            staged.clear();
            plain.clear();
            assert!(staged.as_slice().is_empty() && plain.as_slice().is_empty());
        }
        let mut fresh = Staged::with_capacity(0);
        fresh.extend_from_slice(b"G1 X10");
        assert_eq!(fresh.into_vec(), b"G1 X10".to_vec());
    }
}
