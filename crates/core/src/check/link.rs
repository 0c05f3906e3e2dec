//! The link (rule TG703; TG701 and TG702, the tape's parity and code, are found where the
//! tape is decoded, in Python): the TV check's even block lengths.

use super::{chars, BlockView, Checker, OddBlocks};
use crate::rules::Rule;

impl Checker {
    /// TG703, once per file: the blocks of an odd number of characters.
    pub(super) fn odd_blocks(&mut self) {
        let OddBlocks {
            count: odd,
            line: first_line,
            length: first_length,
        } = self.tv_odd;
        if odd > 0 {
            let blocks = if odd == 1 { "block has" } else { "blocks have" };
            let message = format!(
                "{odd} {blocks} an odd number of characters (the first, line {first_line}: \
                 {first_length}); the control's TV check wants an even number, and tapegate's \
                 sender pads each with a space"
            );
            self.report(
                Rule::OddBlockLength,
                message,
                first_line,
                first_length.max(1),
            );
        }
    }

    /// The TV check: count the blocks of an odd number of characters (CR not counted).
    #[inline]
    pub(super) fn tv(&mut self, b: &BlockView<'_>) {
        // (the profile's test inlined where it is asked, once a block; a count out of line)
        if self.config.tv_check {
            match b.crs {
                // (an ASCII line whose CRs its reader counted, a line of plain words: its
                // length inline, no call)
                Some(crs) if b.ascii => {
                    debug_assert_eq!(crs, carriage_returns(b.text), "line {}: its CRs", b.line);
                    self.tv_length(b.line, b.text.len() - crs);
                }
                _ => self.tv_count(b),
            }
        }
    }

    /// [`Checker::tv`] under a profile with the TV check, of a line whose length is counted
    /// here.
    #[inline(never)]
    fn tv_count(&mut self, b: &BlockView<'_>) {
        let characters = if b.ascii {
            b.text.len()
        } else {
            chars(b.text, b.text.len())
        };
        // (counted by the line's reader where it read a line of plain words)
        let crs = b.crs.unwrap_or_else(|| carriage_returns(b.text));
        debug_assert_eq!(crs, carriage_returns(b.text), "line {}: its CRs", b.line);
        self.tv_length(b.line, characters - crs);
    }

    /// The TV check of a block of `length` characters (its CRs left out) on `line`.
    #[inline(always)]
    fn tv_length(&mut self, line: usize, length: usize) {
        if length % 2 == 1 {
            if self.tv_odd.count == 0 {
                self.tv_odd = OddBlocks {
                    count: 0,
                    line,
                    length,
                };
            }
            self.tv_odd.count += 1;
        }
    }
}

/// The CRs of a block's text. A CR that ends it (a CRLF file's) is counted on its own; whether
/// the rest holds one is found 8 bytes at a time, the first word that holds one ending the
/// search (the TV check asks it of every block, and nearly every block has none; a loop with
/// no exit was made vectors by the compiler, whose set-up cost more than a line's few words,
/// about 60 instructions a block in all): a word's bytes that equal
/// CR are the zero bytes of `word ^ CRs`, each marked by its high bit (exact: the low seven
/// bits' sum cannot carry into the next byte). The last bytes past a multiple of 8 are the
/// top bytes of the last 8, the ones before them shifted out. Only a rest that holds one is
/// counted byte by byte, as is a rest shorter than 8. (Whether the text is ASCII is the line
/// reader's, [`BlockView::ascii`].)
pub(super) fn carriage_returns(text: &[u8]) -> usize {
    const ONES: u64 = u64::from_le_bytes([1; 8]);
    const LOW: u64 = ONES * 0x7f;
    let (rest, last) = match text.split_last() {
        Some((b'\r', rest)) => (rest, 1),
        _ => (text, 0),
    };
    let count = || rest.iter().filter(|&&c| c == b'\r').count() + last;
    let crs = |raw: u64| {
        let x = raw ^ (ONES * u64::from(b'\r'));
        !(((x & LOW) + LOW) | x | LOW)
    };
    let n = rest.len();
    if n < 8 {
        return count();
    }
    let word = |at: usize| u64::from_le_bytes(rest[at..at + 8].try_into().expect("8 bytes"));
    // (a word that holds one ends the search: the loop's exit keeps the compiler from
    // unrolling it into vectors, whose set-up cost more than a line's few words)
    let mut at = 0;
    while at + 8 <= n {
        if crs(word(at)) != 0 {
            return count();
        }
        at += 8;
    }
    let tail = n - at;
    if tail > 0 && crs(word(n - 8)) >> (8 * (8 - tail)) != 0 {
        return count();
    }
    last
}

/// TG703's message.
pub fn tv_message(length: usize) -> String {
    format!(
        "{length} characters in the block (the control's TV check wants an even number; the \
         sender pads with a space)"
    )
}

#[cfg(test)]
mod tests {
    use super::super::testing::{findings, iso_mill};
    use super::carriage_returns;

    /// The CRs counted 8 bytes at a time as one at a time: CRs at every place of texts of 0
    /// to 24 bytes, none, one, several, beside bytes one above and below a CR, 0x7F, 0x80,
    /// 0x8D and 0xFF.
    #[test]
    fn a_block_s_crs_are_counted_eight_bytes_at_a_time_as_one_at_a_time() {
        let exact = |t: &[u8]| t.iter().filter(|&&c| c == b'\r').count();
        for fill in [b'X', b'\x0c', b'\x0e', 0x7f, 0x80, 0x8d, 0xff, 0] {
            for len in 0..=24 {
                for mask in [
                    0u32,
                    1,
                    0b101,
                    0x00ff_ffff,
                    0x0080_0001,
                    0x0012_3456,
                    0x0080_0000,
                ] {
                    let text: Vec<u8> = (0..len)
                        .map(|i| if mask >> i & 1 == 1 { b'\r' } else { fill })
                        .collect();
                    assert_eq!(carriage_returns(&text), exact(&text), "{text:?}");
                }
            }
        }
        assert_eq!(carriage_returns(b"N10 G01 X1.5 Y2.25 F100.\r"), 1);
        // one CR at each place of texts of 1 to 24 bytes: counted once, in a word of 8 or in
        // the last bytes read again
        for len in 1..=24 {
            for at in 0..len {
                let mut text = vec![b'X'; len];
                text[at] = b'\r';
                assert_eq!(carriage_returns(&text), 1, "{len} {at}");
            }
        }
    }
    use super::super::{Config, ProfileFacts};
    use crate::rules::Rule;

    fn tv() -> Config {
        Config {
            facts: ProfileFacts {
                tv_check: true,
                ..iso_mill().facts
            },
            ..iso_mill()
        }
    }

    #[test]
    fn blocks_of_an_odd_length_are_counted_and_said_once() {
        let text = "%\nG01 X10. F100.\nG01 X1.\nX22.\nM02\n%";
        let found = findings(tv(), text, Rule::OddBlockLength);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].line, found[0].column), (3, 7));
        assert!(
            found[0].message.starts_with("2 blocks have"),
            "{}",
            found[0].message
        );
        // a CR is not counted; an even block is quiet; without the TV check, nothing
        let even = "%\nG01 X10.\r\nX20.\r\nM02 \n%";
        assert_eq!(findings(tv(), even, Rule::OddBlockLength), []);
        assert_eq!(findings(iso_mill(), text, Rule::OddBlockLength), []);
        // a character of two bytes counts one: 11 characters, 12 bytes
        let found = findings(tv(), "%\nG01 X1. (\u{dc})\nM02 \n%", Rule::OddBlockLength);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].line, found[0].column), (2, 11));
    }
}
