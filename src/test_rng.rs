//! The unit tests' random numbers: a xorshift generator, the same
//! sequence for the same seed on every machine (the tests' inputs are
//! reproducible, and no crate is needed for them).

/// xorshift64 (Marsaglia, J. Stat. Softw. 2003): the state must not be 0.
pub(crate) struct Xorshift(pub(crate) u64);

impl Xorshift {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// A number in [0, 1): the top 53 bits.
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A number in [a, b).
    pub(crate) fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
    /// An index below `n` (0 when `n` is 0).
    pub(crate) fn below(&mut self, n: usize) -> usize {
        ((self.unit() * n as f64) as usize).min(n.saturating_sub(1))
    }
}

/// Numbers in [0, 1) from `seed` (not 0).
pub(crate) fn unit(seed: u64) -> impl FnMut() -> f64 {
    let mut x = Xorshift(seed);
    move || x.unit()
}
