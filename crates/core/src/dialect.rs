//! What a control does with a program that goes past its documented formats, the text
//! outside ASCII it reads in comments and strings, and where a program of a file of several
//! ends and the next begins: the facts of the dialect families' manuals (docs/dialects.md)
//! that the checker consults, kept out of the rule walk.

use crate::decimal::Dec;
use crate::lex::Family;
use crate::statement::Kind;
use crate::word::Word;

/// A block's statements as the reader found them: column, kind and text.
pub type Statements<'a> = [(usize, Kind, &'a [u8])];

/// What the control does with a value written past its word format: more decimals than its
/// least input increment, or (for a sequence number) more digits than its manual lists.
/// `checks.past_format` of a profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PastFormat {
    /// The control alarms (ISO 6983-1's formats, a Fanuc's PS0003): TG203/TG205, errors.
    #[default]
    Alarm,
    /// The control rounds to its resolution (a SINUMERIK, machine data 10200): TG208, a
    /// warning naming what it rounds to.
    Round,
    /// The manuals at hand do not say (Fanuc and Haas decimals past the increment, a Haas
    /// sequence number past N99999): TG208, a warning.
    Unknown,
    /// The control has no least increment (LinuxCNC reads double-precision numbers): nothing
    /// to say.
    Any,
}

impl PastFormat {
    pub fn from_name(name: &str) -> Option<PastFormat> {
        Some(match name {
            "alarm" => PastFormat::Alarm,
            "round" => PastFormat::Round,
            "unknown" => PastFormat::Unknown,
            "any" => PastFormat::Any,
            _ => return None,
        })
    }

    /// The end of a TG208 message: what the control does.
    pub fn effect(self) -> &'static str {
        match self {
            PastFormat::Round => "the control rounds it to its resolution",
            _ => "the control's manuals do not say whether it rounds, cuts or alarms",
        }
    }
}

/// The first character outside ASCII of a line the reader has read: its offset and how a
/// message names it (`byte 0xB0 (not UTF-8: ...)`, or `'中' (U+4E2D, UTF-8)`). The reader
/// takes such characters only in comments and strings, so this is where one stands.
pub fn first_outside_ascii(text: &[u8]) -> Option<(usize, String)> {
    let offset = text.iter().position(|b| !b.is_ascii())?;
    Some((offset, describe(&text[offset..])))
}

fn describe(rest: &[u8]) -> String {
    let len = match rest[0] {
        0xC2..=0xDF => 2,
        0xE0..=0xEF => 3,
        0xF0..=0xF4 => 4,
        _ => 0,
    };
    if let Some(ch) = rest
        .get(..len)
        .and_then(|s| std::str::from_utf8(s).ok())
        .and_then(|s| s.chars().next())
    {
        return format!("'{ch}' (U+{:04X}, UTF-8)", ch as u32);
    }
    format!(
        "byte 0x{:02X} (not UTF-8: an 8-bit code page such as Latin-1 or GBK?)",
        rest[0]
    )
}

/// Whether a block returns from a subprogram or macro: M99 on a Fanuc or Haas (Custom Macro
/// B), M17 or `RET` on a SINUMERIK (a `.SPF` ends so, with no M02/M30), `RTS` on an Okuma.
/// `values` are the block's words' values as the checker read them.
pub fn returns(
    family: Family,
    words: &[Word<'_>],
    statements: &Statements<'_>,
    values: &[Option<Dec>],
) -> bool {
    let code = match family {
        Family::MacroB => 99,
        Family::Sinumerik => 17,
        Family::Okuma => {
            // RTS ends an OSP subprogram
            return statements.iter().any(|&(_, kind, text)| {
                kind == Kind::Command && crate::statement::okuma::returns(text)
            });
        }
        _ => return false,
    };
    let by_m = words
        .iter()
        .zip(values)
        .any(|(w, v)| w.letter == b'M' && v.as_ref().is_some_and(|v| v.eq_int(code)));
    by_m || (family == Family::Sinumerik
        && statements
            .iter()
            .any(|&(_, kind, text)| kind == Kind::Command && text.eq_ignore_ascii_case(b"RET")))
}

/// What comes first in a block, for the split of a file into programs: its first word's
/// place and letter (upper case), and its first statement's place, kind and text. The places
/// are columns or byte offsets, the same for both.
#[derive(Debug, Clone, Copy, Default)]
pub struct Opening<'a> {
    pub word: Option<(usize, u8)>,
    pub statement: Option<(usize, Kind, &'a [u8])>,
}

impl Opening<'_> {
    /// Whether the block begins a program of its own, were it after the end of one: a program
    /// number first in the block (`O1234`, `O7997A`, a Fanuc memory backup's next program), or
    /// a backup's folder marker (`&F=/USER/PATH1/`). `program_number` is the profile's program
    /// number address.
    pub fn starts_program(&self, family: Family, program_number: Option<u8>) -> bool {
        if family != Family::MacroB {
            return false;
        }
        let Some(letter) = program_number else {
            return false;
        };
        let word = self.word.map(|(at, l)| (at, l == letter));
        let statement = self.statement.map(|(at, kind, text)| {
            let named =
                kind == Kind::Name && (text.starts_with(b"&F=") || text.first() == Some(&letter));
            (at, named)
        });
        match (word, statement) {
            (Some((wc, w)), Some((sc, s))) => {
                if wc < sc {
                    w
                } else {
                    s
                }
            }
            (Some((_, w)), None) => w,
            (None, Some((_, s))) => s,
            (None, None) => false,
        }
    }
}

/// The split of a file into its programs, as every reader makes it (the checker, the
/// converter, the diff and verify reader, the restart walk): after the end (M02, M30) or the
/// return (M99, M17, `RET`, `RTS`) of a program, a block that starts one
/// ([`Opening::starts_program`]) begins the next one, which is read from its own start state
/// (the reset state in the control's start units, no position known), not from where the
/// program before it left the machine.
#[derive(Debug, Clone, Copy, Default)]
pub struct ProgramSplit {
    after_end: bool,
}

impl ProgramSplit {
    /// Whether the block `opening` shows begins the next program of the file (asked before
    /// the block is read).
    pub fn begins(
        &mut self,
        family: Family,
        program_number: Option<u8>,
        opening: &Opening<'_>,
    ) -> bool {
        if self.after_end && opening.starts_program(family, program_number) {
            self.after_end = false;
            return true;
        }
        false
    }

    /// After a block: whether it ended the program or returned from it.
    pub fn ended(&mut self, ends_or_returns: bool) {
        self.after_end |= ends_or_returns;
    }
}

/// In a Custom Macro B call (G65, G66, G66.1) an I, J or K word may repeat: argument
/// specification II passes A B C and up to ten I J K sets. Some(which word of its `letter` the
/// block's word `i` is: 1 for the first) where that applies, None elsewhere.
pub fn argument_sets(family: Family, words: &[Word<'_>], letter: u8, i: usize) -> Option<usize> {
    if family != Family::MacroB || !matches!(letter, b'I' | b'J' | b'K') {
        return None;
    }
    let call = words.iter().any(|w| {
        w.letter == b'G'
            && w.expression.is_empty()
            && matches!(
                std::str::from_utf8(w.number).ok().and_then(|n| n.parse::<f64>().ok()),
                Some(n) if n == 65.0 || n == 66.0 || n == 66.1
            )
    });
    call.then(|| words[..=i].iter().filter(|w| w.letter == letter).count())
}

/// A Custom Macro B system variable that a program may read but not set (FANUC 0i-F/30i-B
/// "Custom macro", system variables; an assignment is alarm PS0116): what it holds, or None.
/// Interface inputs, the clock's date and time, the modal information and the positions;
/// offsets, #3000 (alarm), #3001 (timer), #3006 (stop with message), #3901 (parts) are set.
pub fn read_only_variable(family: Family, n: u64) -> Option<&'static str> {
    if family != Family::MacroB {
        return None;
    }
    Some(match n {
        1000..=1035 => "an interface input signal",
        3011 | 3012 => "the date or time",
        4001..=4400 => "modal information",
        5001..=5200 => "a position (block end, machine, workpiece, skip, deviation)",
        _ => return None,
    })
}

/// What a control of a dialect family does with a code its profile's table lacks, where the
/// profile does not say it alarms.
pub fn unknown_code_effect(family: Family) -> &'static str {
    match family {
        Family::MacroB => {
            "the control alarms on it unless its parameters make it a macro call (Fanuc \
             6050-6059 G codes, 6080-6089 M codes; Haas G and M code aliases)"
        }
        _ => "the profile does not know it; the machine's configuration may",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_program_number_or_a_folder_after_an_end_begins_the_next_program() {
        let o = |at| Opening {
            word: Some((at, b'O')),
            statement: None,
        };
        let folder = Opening {
            word: None,
            statement: Some((1, Kind::Name, &b"&F=/USER/PATH2/"[..])),
        };
        let name = Opening {
            word: None,
            statement: Some((1, Kind::Name, &b"O7997A"[..])),
        };
        let mut split = ProgramSplit::default();
        let fanuc = (Family::MacroB, Some(b'O'));
        // the file's first program begins nothing new
        assert!(!split.begins(fanuc.0, fanuc.1, &o(1)));
        split.ended(false);
        assert!(!split.begins(fanuc.0, fanuc.1, &o(1))); // no end yet
        split.ended(true); // M30 or M99
        let g0 = Opening {
            word: Some((1, b'G')),
            statement: None,
        };
        assert!(!split.begins(fanuc.0, fanuc.1, &g0)); // a local N100 subprogram's block
        assert!(split.begins(fanuc.0, fanuc.1, &folder));
        assert!(!split.begins(fanuc.0, fanuc.1, &o(1))); // the folder began it
        split.ended(true);
        assert!(split.begins(fanuc.0, fanuc.1, &name));
        split.ended(true);
        // a word before the statement decides: "G0 O7997A" is no program number first
        let later = Opening {
            word: Some((1, b'G')),
            statement: Some((4, Kind::Name, &b"O7997A"[..])),
        };
        assert!(!split.begins(fanuc.0, fanuc.1, &later));
        // only Custom Macro B splits so; a profile without a program number address neither
        assert!(!split.begins(Family::LinuxCnc, Some(b'O'), &o(1)));
        assert!(!split.begins(Family::MacroB, None, &o(1)));
        assert!(split.begins(fanuc.0, fanuc.1, &o(1)));
    }

    #[test]
    fn names_the_first_character_outside_ascii() {
        let (at, what) = first_outside_ascii("G01 X1 (25\u{b0}C) (\u{4e2d})".as_bytes()).unwrap();
        assert_eq!(at, 10);
        assert!(what.contains("U+00B0"), "{what}");
        let (at, what) = first_outside_ascii(b"G01 X1 (25\xb0C)").unwrap();
        assert_eq!(at, 10);
        assert!(what.starts_with("byte 0xB0"), "{what}");
        assert!(first_outside_ascii(b"G01 (ASCII)").is_none());
    }

    #[test]
    fn reads_the_profile_names() {
        assert_eq!(PastFormat::from_name("round"), Some(PastFormat::Round));
        assert_eq!(PastFormat::from_name("cut"), None);
    }
}
