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

/// A line of 1-24 drawn bytes (`bytes`), or, as often, of pieces of lines (`pieces`, one for
/// every `per` of the drawn length, and one more): the lines the tokenizer-side property tests
/// feed to a fast path and its plain reference.
pub(crate) fn line(
    next: &mut impl FnMut() -> u64,
    bytes: &[u8],
    pieces: &[&str],
    per: usize,
) -> Vec<u8> {
    let len = 1 + (next() % 24) as usize;
    if next().is_multiple_of(2) {
        (0..len)
            .map(|_| bytes[(next() % bytes.len() as u64) as usize])
            .collect()
    } else {
        (0..len / per + 1)
            .flat_map(|_| pieces[(next() % pieces.len() as u64) as usize].bytes())
            .collect()
    }
}
