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
    pub(super) fn tv(&mut self, b: &BlockView<'_>) {
        if !self.config.tv_check {
            return;
        }
        let length = chars(b.text, b.text.len()) - b.text.iter().filter(|&&c| c == b'\r').count();
        if length % 2 == 1 {
            if self.tv_odd.count == 0 {
                self.tv_odd = OddBlocks {
                    count: 0,
                    line: b.line,
                    length,
                };
            }
            self.tv_odd.count += 1;
        }
    }
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
    }
}
