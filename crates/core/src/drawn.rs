//! The tests' drawn inputs: a fixed xorshift, so that a property test of a fast path against
//! its plain reference draws the same inputs on every run and a failure can be replayed.

/// Marsaglia's xorshift64 from `seed` (not zero): each call the next 64 bits.
pub(crate) fn xorshift(seed: u64) -> impl FnMut() -> u64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}
