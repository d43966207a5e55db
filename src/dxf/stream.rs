//! Group-code pairs with one pair of look-ahead, for reading the ENTITIES
//! section one entity at a time (an entity ends where the next `0` pair is).

use super::pairs::{BadCode, Pair, Source};

/// Pairs with one pair of look-ahead; a bad group code ends the input and is kept.
pub struct Stream<'a, I> {
    it: I,
    peeked: Option<Pair<'a>>,
    /// The first bad group code met (reading stops there).
    pub bad: Option<BadCode>,
    /// True once any pair was read.
    pub any: bool,
}

impl<'a, I: Source<'a>> Stream<'a, I> {
    pub fn new(it: I) -> Self {
        Stream {
            it,
            peeked: None,
            bad: None,
            any: false,
        }
    }
    pub fn inner(&self) -> &I {
        &self.it
    }
    pub fn inner_mut(&mut self) -> &mut I {
        &mut self.it
    }
    /// True when nothing is held back: no pair looked ahead at, no bad code met.
    pub fn is_clear(&self) -> bool {
        self.peeked.is_none() && self.bad.is_none()
    }
    /// The source, the pair looked ahead at and the bad code met.
    pub fn into_parts(self) -> (I, Option<Pair<'a>>, Option<BadCode>) {
        (self.it, self.peeked, self.bad)
    }
    /// Sets the pair looked ahead at and the bad code met (the source
    /// having been moved to where another stream stopped).
    pub fn resume(&mut self, peeked: Option<Pair<'a>>, bad: Option<BadCode>) {
        self.peeked = peeked;
        self.bad = bad;
    }
    #[inline]
    pub fn next_pair(&mut self) -> Option<Pair<'a>> {
        if let Some(p) = self.peeked.take() {
            return Some(p);
        }
        if self.bad.is_some() {
            return None;
        }
        match self.it.next()? {
            Ok(p) => {
                self.any = true;
                Some(p)
            }
            Err(e) => {
                self.bad = Some(e);
                None
            }
        }
    }
    #[inline]
    pub fn peek(&mut self) -> Option<Pair<'a>> {
        if self.peeked.is_none() {
            self.peeked = self.next_pair();
        }
        self.peeked
    }
    #[inline]
    pub fn push_back(&mut self, p: Pair<'a>) {
        self.peeked = Some(p);
    }
    /// Appends pairs up to (not including) the next `0` pair to `buf`.
    #[inline]
    pub fn take_body(&mut self, buf: &mut Vec<Pair<'a>>) {
        // Straight from the source, not through the look-ahead slot: this
        // loop sees nearly every pair of the ENTITIES section, and the
        // source pushes each pair from registers into `buf` (returned one
        // at a time as a `Result` through memory, its reload stalled on
        // store forwarding: most of this loop's time).
        if let Some(p) = self.peeked.take() {
            if p.code == 0 {
                self.peeked = Some(p);
                return;
            }
            buf.push(p);
        }
        if self.bad.is_some() {
            return;
        }
        let before = buf.len();
        let end = self.it.body_into(buf);
        self.any |= buf.len() > before;
        match end {
            Some(Ok(p)) => {
                self.any = true;
                self.peeked = Some(p);
            }
            Some(Err(e)) => self.bad = Some(e),
            None => {}
        }
    }
}
