//! The unit tests' random numbers: a xorshift generator, the same
//! sequence for the same seed on every machine (the tests' inputs are
//! reproducible, and no crate is needed for them).

/// Numbers in [0, 1) from `seed` (not 0): xorshift64, the top 53 bits.
pub(crate) fn unit(seed: u64) -> impl FnMut() -> f64 {
    let mut x = seed;
    move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
}
