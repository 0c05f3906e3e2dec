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
    /// The manuals say a value the control computes in an address (a variable's, an
    /// expression's) is rounded to the address's increment, and not what a number written
    /// with more decimals does (Fanuc and Haas decimals past the increment: FANUC Custom
    /// Macro, "ROUND"; Haas Mill Operator's Manual 96-8000, "Notes on functions"): TG208, a
    /// warning saying both.
    RoundComputed,
    /// The manuals at hand do not say (a Haas sequence number past N99999, an Okuma's decimals
    /// past the increment): TG208, a warning.
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
            "round_computed" => PastFormat::RoundComputed,
            "unknown" => PastFormat::Unknown,
            "any" => PastFormat::Any,
            _ => return None,
        })
    }

    /// The end of a TG208 message: what the control does.
    pub fn effect(self) -> &'static str {
        match self {
            PastFormat::Round => "the control rounds it to its resolution",
            PastFormat::RoundComputed => {
                "the control's manuals say a variable's or expression's value in an address is \
                 rounded to its increment, not whether a number written with more decimals is \
                 rounded too, cut or alarms"
            }
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

/// Where the character at `offset` of a line of a `family` program stands, as TG127 names it:
/// in a comment (`( )` but on a SINUMERIK, whose `( )` are calls, or after `;`), in a string
/// (`" "`), or on LinuxCNC in a named parameter's name (`#<été>`) or a subroutine's
/// (`o<été>`), which rs274 reads as text too; "in a comment or string" where the line does not
/// show which (review 24: a parameter's name was called a comment or string).
pub fn outside_ascii_place(text: &[u8], offset: usize, family: Family) -> &'static str {
    let linuxcnc = family == Family::LinuxCnc;
    let parens = family != Family::Sinumerik;
    let (mut comment, mut string) = (0usize, false);
    let mut name: Option<&'static str> = None;
    let mut before = 0u8; // the last byte outside blanks, outside comments
    for &c in &text[..offset.min(text.len())] {
        if string {
            string = c != b'"';
        } else if comment > 0 {
            match c {
                b'(' => comment += 1,
                b')' => comment -= 1,
                _ => {}
            }
        } else if name.is_some() {
            if c == b'>' {
                name = None;
            }
        } else {
            match c {
                b'(' if parens => comment = 1,
                b'"' => string = true,
                b';' => return "in a comment",
                b'<' if linuxcnc && before == b'#' => name = Some("in a parameter's name"),
                b'<' if linuxcnc && before.eq_ignore_ascii_case(&b'o') => {
                    name = Some("in a subroutine's name")
                }
                b' ' | b'\t' => {}
                _ => before = c,
            }
        }
    }
    match (comment > 0, string, name) {
        (true, _, _) => "in a comment",
        (_, true, _) => "in a string",
        (_, _, Some(place)) => place,
        _ => "in a comment or string",
    }
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

/// Whether the family's controls read a `/` block skip after the first word of a block, skipping
/// from there to the end of the block when the switch is on: a Fanuc or Haas (docs/dialects.md,
/// block skip); every other family takes `/` only at the head of a block. The reader reads it,
/// the converter refuses to carry it to a family that does not.
pub fn skips_within_block(family: Family) -> bool {
    family == Family::MacroB
}

/// Whether a word `letter` with an index (`S1=470`, `X4=20`, `M3=5`) gives that address its
/// value, as a SINUMERIK's extended address does (an axis or spindle numbered by its
/// extension: Programming Manual Fundamentals, "Extended addresses"), rather than setting a
/// parameter (ISO 6983-1 6.4.7 `P1=..`, a Fanuc's `#1=..`, a SINUMERIK's `R1=..`). The
/// manual extends the axis addresses, I J K, S, M, H, T and F only (SPOS and SPOSA, the
/// others, are names): the axes by their ISO letters, X Y Z A B C U V W. Any other letter's
/// index (`D1=`, `L1=`, `P1=`) is read as elsewhere. `letter` in either case.
pub fn extended_address(family: Family, letter: u8) -> bool {
    family == Family::Sinumerik && crate::statement::extended_letter(letter)
}

/// Whether a block's codes call a subprogram or a macro, after which the checker knows neither
/// the position nor the modes: M98 (and Haas's M97, a local subprogram; a FANUC's M198, from
/// an external device) and G65/G66 on a Fanuc or Haas and in the neutral ISO reading (which has no table of its own to say otherwise),
/// M98 on LinuxCNC (2.9's Fanuc-style M98/M99). Not on an Okuma, whose M98 is a coolant code
/// (oil mist, the OSP M code list) and whose call is the `CALL` statement, nor on a SINUMERIK
/// (a call by name or `L`) or a HEIDENHAIN (`L` labels): there these codes are the machine's
/// own, and taking one for a call would drop what the checker knows of the position. On a
/// SINUMERIK the L word calls the subprogram of that number (`L100`, `L785 P2`: address L is
/// the subprogram's, Programming Manual "Fundamentals"); `l_word` says the block has one.
pub fn calls(family: Family, gs: &[i64], ms: &[i64], l_word: bool) -> bool {
    match family {
        Family::Sinumerik => l_word,
        Family::Okuma | Family::Heidenhain => false,
        Family::LinuxCnc => ms.contains(&98),
        Family::Iso => {
            ms.iter().any(|&m| m == 98 || m == 97) || gs.iter().any(|&g| g == 65 || g == 66)
        }
        // (a FANUC's M198 calls a subprogram from an external device or the data server,
        // which the CNC itself decodes: 0i-F/30i-B Operator's Manuals, "Auxiliary function"
        // and "External device subprogram call"; its return may come back to any block)
        Family::MacroB => {
            ms.iter().any(|&m| m == 98 || m == 97 || m == 198)
                || gs.iter().any(|&g| g == 65 || g == 66)
        }
    }
}

/// The M code that returns from a subprogram, for the converter and the split of a file into
/// programs: M17 on a SINUMERIK (Programming Manual "Fundamentals", "M functions": M0 M1 M2
/// M17 M30 are its program flow codes; M99 is none of them, a code the PLC gets), none on an
/// Okuma (`RTS` returns; the OSP M code list gives M99 no such meaning) nor on a HEIDENHAIN
/// (TNC ISO Programming User's Manual, M functions: M99 is the blockwise cycle call; a
/// subprogram ends at its `G98 L0` label, a program at its `N99999999 %` line), M99
/// elsewhere (Fanuc and Haas, LinuxCNC's Fanuc-style M98/M99, and the neutral ISO reading).
pub fn return_code(family: Family) -> Option<i64> {
    match family {
        Family::Sinumerik => Some(17),
        Family::Okuma | Family::Heidenhain => None,
        _ => Some(99),
    }
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
        Family::MacroB | Family::Sinumerik => return_code(family).unwrap_or_default(),
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
        && statements.iter().any(|&(_, kind, text)| {
            kind == Kind::Command && crate::statement::sinumerik_returns(text)
        }))
}

/// Whether a program of the family can return to a caller by its last block (M99, M17/RET,
/// RTS: [`returns`]), so that what a program part is shows only at its end.
pub fn has_returns(family: Family) -> bool {
    matches!(family, Family::MacroB | Family::Sinumerik | Family::Okuma)
}

/// Whether a file is a subprogram by its name: a SINUMERIK's `.SPF` (Programming Manual,
/// "Fundamentals": main programs `.MPF`, subprograms `.SPF`), whatever its last block.
pub fn subprogram_by_name(family: Family, name: &str) -> bool {
    family == Family::Sinumerik
        && name
            .rsplit_once('.')
            .is_some_and(|(_, extension)| extension.eq_ignore_ascii_case("SPF"))
}

/// Whether a block opens a subprogram's definition by a statement: a SINUMERIK's `PROC NAME`
/// (Programming Manual "Job Planning", subprograms with parameter transfer), whatever the
/// file is called. What follows runs where and as its caller left the machine.
pub fn defines_subprogram(family: Family, statements: &Statements<'_>) -> bool {
    family == Family::Sinumerik
        && statements
            .iter()
            .any(|&(_, kind, text)| kind == Kind::Declaration && first_name_is(text, b"PROC"))
}

/// A SINUMERIK block's place in its program's two parts: a program (a main program or a
/// subprogram) holds its definitions (`DEF`) in a definition section at its head, before
/// the first block of its program section (Programming Manual "Job Planning", definition
/// of user variables (DEF): program-global and local user variables are defined in the
/// definition section of the part program, each definition in a block of its own; SINUMERIK
/// 808D Programming and Operating Manual, Local User Data: the definition is made at the
/// start of the program). `Some(Some(column))`: the block's `DEF` statement, at its column;
/// `Some(None)`: a block of the program section (a word other than N, or a statement that
/// is no definition, label or name); None: neither (a block number, a comment, `DEFINE`,
/// `EXTERN`, `PROC`, a label).
pub fn sinumerik_section(
    family: Family,
    words: &[Word<'_>],
    statements: &Statements<'_>,
) -> Option<Option<usize>> {
    if family != Family::Sinumerik {
        return None;
    }
    if let Some(&(column, _, _)) = statements
        .iter()
        .find(|&&(_, kind, text)| kind == Kind::Declaration && first_name_is(text, b"DEF"))
    {
        return Some(Some(column));
    }
    let executes = words.iter().any(|w| w.letter != b'N')
        || statements
            .iter()
            .any(|&(_, kind, _)| !matches!(kind, Kind::Declaration | Kind::Label | Kind::Name));
    executes.then_some(None)
}

/// Whether a statement's text begins with the name `name` (in either case), the whole name:
/// `PROC MYSUB(REAL X)` begins with PROC, `PROCESS=1` does not.
fn first_name_is(text: &[u8], name: &[u8]) -> bool {
    text.len() >= name.len()
        && text[..name.len()].eq_ignore_ascii_case(name)
        && !text
            .get(name.len())
            .is_some_and(|&c| c.is_ascii_alphanumeric() || c == b'_')
}

/// A LinuxCNC subroutine definition's start (`o<name> sub`: Some(true)) or end (`o<name>
/// endsub`, with or without its return value: Some(false)) among a block's statements.
pub fn subroutine_definition(statements: &Statements<'_>) -> Option<bool> {
    subroutine_statement(statements).map(|(opens, _)| opens)
}

/// [`subroutine_definition`], with the definition's label (`o<name>` or `o100`, lower case:
/// LinuxCNC reads a line in lower case), which its `endsub` must repeat.
pub fn subroutine_statement(statements: &Statements<'_>) -> Option<(bool, Vec<u8>)> {
    statements.iter().find_map(|&(_, kind, text)| {
        if kind != Kind::Definition {
            return None;
        }
        let opens = crate::statement::linuxcnc_definition(text)?;
        Some((opens, crate::statement::o_label(text)))
    })
}

/// What comes first in a block, for the split of a file into programs: its first word's
/// place and letter (upper case), and its first statement's place, kind and text. The places
/// are columns or byte offsets, the same for both.
#[derive(Debug, Clone, Copy, Default)]
pub struct Opening<'a> {
    pub word: Option<(usize, u8)>,
    pub statement: Option<(usize, Kind, &'a [u8])>,
    /// The block is a `%` line: what follows its `%`, blanks around it left out (a SINUMERIK
    /// archive's file name, `_N_SUB1_SPF`).
    pub percent: Option<&'a [u8]>,
}

impl<'a> Opening<'a> {
    /// The opening of the `%` line `text` (`%_N_SUB1_SPF`): what follows its `%`.
    pub fn percent_line(text: &'a [u8]) -> Opening<'a> {
        let after = text
            .iter()
            .position(|&c| c == b'%')
            .map_or(&text[text.len()..], |at| &text[at + 1..]);
        Opening {
            percent: Some(after.trim_ascii()),
            ..Opening::default()
        }
    }
}

impl Opening<'_> {
    /// Whether the block begins a program of its own, were it after the end of one: a program
    /// number first in the block (`O1234`, `O7997A`, a Fanuc memory backup's next program), a
    /// FANUC program's name in its place (`<SVG_TEST>`, `<101>M60`: B-64014EN/03, 2.5, a file
    /// name enclosed by `<` and `>`), a backup's folder marker (`&F=/USER/PATH1/`), or a
    /// SINUMERIK archive's `%` line naming
    /// the next file ([`archive_file`]). `program_number` is the profile's program number
    /// address.
    pub fn starts_program(&self, family: Family, program_number: Option<u8>) -> bool {
        if let Some(name) = self.percent {
            return archive_file(family, name).is_some();
        }
        if family != Family::MacroB {
            return false;
        }
        let Some(letter) = program_number else {
            return false;
        };
        let word = self.word.map(|(at, l)| (at, l == letter));
        let statement = self.statement.map(|(at, kind, text)| {
            let named = kind == Kind::Name
                && (text.starts_with(b"&F=")
                    || text.first() == Some(&letter)
                    || text.first() == Some(&b'<'));
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

/// Whether the control skips the text between a file's first `%` and the next LF: a FANUC
/// ("In a read operation, data between the first % and the next LF is skipped": FANUC Series
/// 16i/18i/160i/180i-TB Operator's Manual, B-63524EN/01, 8, memory card file format; the
/// leader section of B-64014EN/03, 2.5, where a title may stand). Not a Haas: its manuals at
/// hand say only that `%` begins and ends a program written in a text editor (Mill Operator's
/// Manual, NGC, 2017, 5.3.1), nor that it alarms: there (and on an Okuma) the words ISO
/// 6983-1 clause 4 refuses are TG137, a warning.
pub fn skips_leader(family: Family, haas: bool) -> bool {
    family == Family::MacroB && !haas
}

/// How a control that reads the text after a program's first `%` (ISO 6983-1 clause 4: the
/// program start, then an identification before the first end of block; a Haas, an Okuma)
/// takes `ident`, that text: None where it reads it as the identification (blank, a comment
/// `(TITLE)`, digits and signs such as `:0003`), [`LeaderText::Words`] where it begins like a
/// word (`O0003`, `X-1`, a macro statement `#1=1`: TG111 of its check, words before the
/// first end of block),
/// [`LeaderText::Letters`] where it holds letters outside a leading `(` (`TITLE`: TG112).
/// LinuxCNC reads no text there at all (rs274: "Bad character '%' used").
/// A leading comment is the identification's and the text after it is judged as if it stood
/// first (review 29, finding 5: `% (TITLE) O1000` passed where `%O1000` is TG111); letters
/// inside a comment are the comment's.
pub fn leader_text(ident: &[u8]) -> Option<LeaderText> {
    let mut bytes = ident.trim_ascii_start();
    while bytes.first() == Some(&b'(') {
        match bytes.iter().position(|&c| c == b')') {
            Some(close) => bytes = bytes[close + 1..].trim_ascii_start(),
            None => return None, // (a comment to the end of the line)
        }
    }
    if bytes.trim_ascii_end().is_empty() {
        return None;
    }
    let mut depth = 0usize;
    let outside: Vec<u8> = bytes
        .iter()
        .copied()
        .filter(|&c| {
            match c {
                b'(' => depth += 1,
                b')' => depth = depth.saturating_sub(1),
                _ => return depth == 0,
            }
            false
        })
        .collect();
    // (a macro statement, `#1=1`, is read as a block's words would be: review 31, doubtful)
    let wordlike = bytes.first() == Some(&b'#')
        || bytes.first().is_some_and(u8::is_ascii_uppercase) && {
            let rest = match bytes.get(1) {
                Some(b'+' | b'-') => &bytes[2..],
                _ => &bytes[1..],
            };
            rest.first().is_some_and(u8::is_ascii_digit)
        };
    if wordlike {
        Some(LeaderText::Words)
    } else if String::from_utf8_lossy(&outside)
        .chars()
        .any(char::is_alphabetic)
    {
        Some(LeaderText::Letters)
    } else {
        None
    }
}

/// What [`leader_text`] finds after a `%` that a reading control does not take for its
/// identification.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LeaderText {
    Words,
    Letters,
}

/// The program number (`O0001`, `O7997A`) or name (`<PART_A>`) that a skipped leader
/// ([`skips_leader`]) begins with, after blanks, and so loses: `letter` is the profile's
/// program number address.
pub fn leader_program_number(leader: &[u8], letter: Option<u8>) -> Option<&[u8]> {
    let text = leader.trim_ascii_start();
    if text.first() == Some(&b'<') {
        let close = text.iter().position(|&c| c == b'>')?;
        return Some(&text[..=close]);
    }
    let letter = letter?;
    if text.first()? != &letter || !text.get(1).is_some_and(u8::is_ascii_digit) {
        return None;
    }
    let end = text[1..]
        .iter()
        .position(|c| !c.is_ascii_alphanumeric())
        .map_or(text.len(), |i| i + 1);
    Some(&text[..end])
}

/// Whether a file of the family can hold several programs split by [`ProgramSplit`]: a
/// Custom Macro B control (Fanuc, Haas) with a program number address begins one by its O
/// number (or a FANUC's `<NAME>`) or a folder marker, a SINUMERIK archive by the `%` line
/// naming the next file.
pub fn splits(family: Family, program_number: Option<u8>) -> bool {
    (family == Family::MacroB && program_number.is_some()) || family == Family::Sinumerik
}

/// A SINUMERIK file in punched tape format, as an archive holds several one after another:
/// `%` in the first column and the file's name (`%_N_SHAFT123_MPF`, `%Flange3_MPF`, `%MPF123`,
/// `%L100`), then optionally its `;$PATH=/_N_SPF_DIR` line; what follows belongs to that file
/// (SINUMERIK 840D/840Di/810D Operator's Guide HMI Advanced, "Formats for saving and importing
/// data": punched tape format). Some(true) where the file is a subprogram by its name (`_SPF`,
/// or `SPFn` and `Ln`, which the control stores as subroutines), Some(false) for any other
/// file (a part program `_MPF`, a file it stores elsewhere), None where `name` names no file.
pub fn archive_file(family: Family, name: &[u8]) -> Option<bool> {
    if family != Family::Sinumerik
        || !name
            .first()
            .is_some_and(|&c| c.is_ascii_alphanumeric() || c == b'_')
    {
        return None;
    }
    // (blanks in the name are ignored, as the control reads it)
    let upper: Vec<u8> = name
        .iter()
        .filter(|c| !c.is_ascii_whitespace())
        .map(u8::to_ascii_uppercase)
        .collect();
    let numbered = |prefix: &[u8]| {
        upper
            .strip_prefix(prefix)
            .is_some_and(|n| !n.is_empty() && n.iter().all(u8::is_ascii_digit))
    };
    Some(upper.ends_with(b"_SPF") || numbered(b"SPF") || numbered(b"L"))
}

/// The split of a file into its programs, as every reader makes it (the checker, the
/// converter, the diff and verify reader, the restart walk): after the end (M02, M30) or the
/// return (M99, M17, `RET`, `RTS`) of a program, a block that starts one
/// ([`Opening::starts_program`]) begins the next one, which is read from its own start state
/// (the reset state in the control's start units, no position known), not from where the
/// program before it left the machine. A SINUMERIK archive's file header after its first
/// begins the next program whatever came before it ([`archive_file`]: each file is stored
/// and run apart).
#[derive(Debug, Clone, Copy, Default)]
pub struct ProgramSplit {
    after_end: bool,
    /// A SINUMERIK archive's first file header has been read: every later one begins the
    /// next file, whatever the file before ended with.
    archived: bool,
}

impl ProgramSplit {
    /// Whether the block `opening` shows begins the next program of the file (asked before
    /// the block is read).
    #[inline]
    pub fn begins(
        &mut self,
        family: Family,
        program_number: Option<u8>,
        opening: &Opening<'_>,
    ) -> bool {
        // (asked of every block: one that is no archive's header and follows no end begins
        // nothing, the two tests below, made here before the call)
        (opening.percent.is_some() || self.after_end)
            && self.begins_after(family, program_number, opening)
    }

    /// [`ProgramSplit::begins`] of a block that is no `%` line, its opening built only where
    /// it follows an end (asked of every block: most follow none).
    #[inline]
    pub fn begins_after_end<'a>(
        &mut self,
        family: Family,
        program_number: Option<u8>,
        opening: impl FnOnce() -> Opening<'a>,
    ) -> bool {
        self.after_end && self.begins_after(family, program_number, &opening())
    }

    /// [`ProgramSplit::begins`] of a block after an end, or of a `%` line.
    #[inline(never)]
    fn begins_after(
        &mut self,
        family: Family,
        program_number: Option<u8>,
        opening: &Opening<'_>,
    ) -> bool {
        let header = opening
            .percent
            .is_some_and(|name| archive_file(family, name).is_some());
        if header {
            // each file of an archive is a program of its own, stored and run apart: the
            // header names it whether or not the one before ended by M30, M17 or RET
            let begins = self.archived;
            self.archived = true;
            self.after_end = false;
            return begins;
        }
        if self.after_end && opening.starts_program(family, program_number) {
            self.after_end = false;
            return true;
        }
        false
    }

    /// Whether an end or a return came before, no program begun since.
    pub fn follows_end(&self) -> bool {
        self.after_end
    }

    /// After a block: whether it ended the program or returned from it.
    pub fn ended(&mut self, ends_or_returns: bool) {
        self.after_end |= ends_or_returns;
    }
}

/// FANUC's data input modes, which a block `G10 L50` (programmable parameter input) or
/// `G10 L3` (tool life management data registration) opens and a block `G11` closes
/// (FANUC Series 0i-MF/0i-TF operator's manual, "Programmable parameter input (G10)" and
/// "Tool life management"; the same in the Series 16/18/30i manuals). The blocks between are
/// data, not program: under L50 `N` is a parameter number, `P` an axis number and `R` the
/// parameter's value, in the parameter's own unit (an integer of least increments, a bit
/// pattern, a time), which the program's G20/G21 do not touch; under L3 `P` is a tool group,
/// `L` a tool life, `Q` how it is counted, `T`, `H`, `D` a tool's numbers. No reader takes
/// them for positions, sequence numbers, tool changes or lengths: the checker passes over
/// them, the converter writes them as they are.
#[derive(Debug, Clone, Default)]
pub struct DataInput {
    /// The line of the `G10 L50`/`G10 L3` that opened the mode in force, and its L.
    open: Option<(usize, i64)>,
    /// The control has no such mode ([`has_data_input`]): a `G10 L50`/`G10 L3` opens none.
    lacking: bool,
}

/// Whether the control has FANUC's G10 L50 / G10 L3 data input modes: a FANUC does; a Haas,
/// of the same family here, does not (its G10 takes L2, L10-L13 and L20 only: Haas mill and
/// lathe operator's manuals, G10), nor does a control of another family. The one place the
/// checker, the restart walk and the converter's target ask.
pub fn has_data_input(family: Family, haas: bool) -> bool {
    family == Family::MacroB && !haas
}

/// The letters a data block may hold: L50's N P R, L3's P L Q T H D (and N, a sequence
/// number); any other word is a program's (the control alarms on it in the mode).
/// The addresses a data block of `G10 L<l>` holds (L50: N P R; L3: N P L Q T H D).
pub fn data_letters(l: i64) -> &'static [u8] {
    if l == 50 {
        b"NPR"
    } else {
        b"NPLQTHD"
    }
}

/// What [`DataInput::block`] found a block to be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataBlock {
    /// A block of the program (the `G10 L50` itself among them).
    Program,
    /// A block of data of the mode opened on `opened` by `G10 L<l>`; `closes` where it holds
    /// the G11.
    Data { opened: usize, l: i64, closes: bool },
    /// A block inside the mode with a word no data block holds (`letter`): a G11 missing,
    /// or a program word where the control alarms.
    Stray { opened: usize, l: i64, letter: u8 },
    /// A `G10 L<l>` (50 or 3) on a control of the family that lacks the mode (a Haas): it
    /// alarms at the L, or reads the blocks after it as program.
    Lacked { l: i64 },
}

impl DataInput {
    /// The reading of the control: a Haas (`haas`) of the FANUC family lacks the modes.
    pub fn for_control(family: Family, haas: bool) -> DataInput {
        DataInput {
            open: None,
            lacking: family == Family::MacroB && !has_data_input(family, haas),
        }
    }

    /// The block `words` (address, number as written) on `line`: whether it is data of an
    /// open mode. A `G10 L50` or `G10 L3` block opens the mode (on a FANUC or Haas family
    /// only), a `G11` block closes it (the G11 block is data too: it holds nothing else).
    pub fn block<'a, I>(&mut self, family: Family, line: usize, words: I) -> DataBlock
    where
        I: Iterator<Item = (u8, &'a [u8])> + Clone,
    {
        if family != Family::MacroB {
            return DataBlock::Program;
        }
        let code = |letter: u8| {
            words
                .clone()
                .filter(move |(a, _)| a.eq_ignore_ascii_case(&letter))
                .filter_map(|(_, n)| crate::meaning::code(n))
        };
        if let Some((opened, l)) = self.open {
            let closes = code(b'G').any(|c| c == (11, 0));
            let stray = words
                .clone()
                .map(|(a, _)| a.to_ascii_uppercase())
                .find(|a| !(data_letters(l).contains(a) || (closes && *a == b'G')));
            if let Some(letter) = stray {
                self.open = None;
                return DataBlock::Stray { opened, l, letter };
            }
            if closes {
                self.open = None;
            }
            return DataBlock::Data { opened, l, closes };
        }
        if code(b'G').any(|c| c == (10, 0)) {
            if let Some((l @ (3 | 50), 0)) = code(b'L').next() {
                if self.lacking {
                    return DataBlock::Lacked { l };
                }
                self.open = Some((line, l));
            }
        }
        DataBlock::Program
    }

    /// The mode in force: the line of its `G10` and its L.
    pub fn open(&self) -> Option<(usize, i64)> {
        self.open
    }
}

/// What a FANUC data input mode's words are, for a note: "G10 L50 programmable parameter
/// input (N parameter numbers, R values in the parameter's own unit)".
pub fn data_input_name(l: i64) -> &'static str {
    if l == 50 {
        "G10 L50 programmable parameter input (N a parameter number, P an axis, R the \
         parameter's value in its own unit)"
    } else {
        "G10 L3 tool life data (P a tool group, L a life, Q how it is counted, T H D a tool's \
         numbers)"
    }
}

/// Where a LinuxCNC file stops being read, as every reader of the core takes it (the checker,
/// the converter, the parameter analysis, the diff and verify reader, the restart walk):
/// rs274's driver stops at the INTERP_EXIT of an M2 or M30 it runs (LinuxCNC `src/emc/sai/
/// driver.cc`, `interpret_from_file`), and its reader at the closing `%` of a file whose first
/// line is a `%` (`interp_read.cc`, `read_text`: INTERP_ENDFILE). The lines after are never
/// run. One thing still reads there: a call of a subroutine not yet defined scans forward in
/// skip mode, where `read_items` reads the O-word lines alone, so an `o<name> sub` ...
/// `o<name> endsub` after the end is found, and its body runs when called. So after an M2 or
/// M30 at the top level (outside any `o` block or definition: one there may not run, and the
/// reader goes on, on the side of reading too much), a line that is not an O-word line (nor
/// a `%` line) is not read as program: no reading error, its bytes kept as they are; an
/// O-word line is read, and a definition it opens is read to its endsub. After the closing
/// `%` nothing is read. Every other family reads on (a Fanuc file may hold a subprogram
/// after M30: [`ProgramSplit`]).
#[derive(Debug, Clone, Default)]
pub struct ReadingEnd {
    family: Family,
    /// The labels of the `o` blocks open here (sub, if, while, do, repeat), innermost last.
    open: Vec<Vec<u8>>,
    /// The first line read was a bare `%`: a later bare `%` line closes the file.
    percent_file: Option<bool>,
    /// The line of that first `%`.
    opening: Option<usize>,
    /// The line of the M2/M30 after which only O-word lines are read.
    ended: Option<usize>,
    /// The line of the closing `%`, once read: nothing after it is.
    closed: Option<usize>,
    /// The first line not read that holds more than blanks and comments, once.
    first_unread: Option<Unread>,
    /// After the end, the first line that holds program inside an `o` block other than a
    /// definition (`o1 if` ... `o1 endif`): read here, as the block is, though rs274 never
    /// reads it -- the line TG117 names, where it comes before the first passed over
    /// (review 51, F19).
    first_in_block: Option<usize>,
    /// The outermost `o` block open is a definition (`o<s> sub`): a call reads its body.
    open_sub: bool,
    noted: bool,
    /// The first line (outside any `o` block, before the end) with an M word whose value
    /// the reader does not know (`M#<two>` without the parameter's value): an M2 or M30
    /// there would end the reading, which goes on.
    unsure: Option<usize>,
    /// LinuxCNC, where the file is opened by `%` (or its first line not yet read), closed or
    /// ended: [`ReadingEnd::skips`] looks at the line. False on any other family, and on a
    /// LinuxCNC file not opened by `%`, neither closed nor ended (every line is read, as in
    /// most of a program): set where those change ([`ReadingEnd::unsettled_now`]).
    unsettled: bool,
}

impl ReadingEnd {
    pub fn new(family: Family) -> ReadingEnd {
        ReadingEnd {
            family,
            unsettled: family == Family::LinuxCnc,
            ..ReadingEnd::default()
        }
    }

    /// [`ReadingEnd::unsettled`] from the fields it stands for.
    fn unsettled_now(&self) -> bool {
        self.family == Family::LinuxCnc
            && !(self.percent_file == Some(false) && self.closed.is_none() && self.ended.is_none())
    }

    /// Asked before line `line` (its text `text`) is read: whether the control never reads
    /// it as program, so that the reader passes over it (its bytes kept). (The family's test
    /// inlined where it is asked, once a line; the reading out of line.)
    #[inline]
    pub fn skips(&mut self, line: usize, text: &[u8]) -> bool {
        // (a file not opened by `%`, neither closed nor ended: every line is read, as in
        // most of a program)
        debug_assert_eq!(self.unsettled, self.unsettled_now());
        self.unsettled && self.linuxcnc_skips(line, text)
    }

    /// [`ReadingEnd::skips`] on LinuxCNC.
    #[inline(never)]
    fn linuxcnc_skips(&mut self, line: usize, text: &[u8]) -> bool {
        let bare_percent = |text: &[u8]| text.trim_ascii() == b"%";
        if self.percent_file.is_none() {
            if text.trim_ascii().is_empty() {
                return false;
            }
            self.percent_file = Some(bare_percent(text));
            self.opening = bare_percent(text).then_some(line);
            self.unsettled = self.unsettled_now();
            return false;
        }
        if let Some(end) = self.closed {
            self.unread(line, text, end, true);
            return true;
        }
        if self.percent_file == Some(true) && bare_percent(text) {
            // the closing %: read, and nothing after it
            self.closed = Some(line);
            self.unsettled = self.unsettled_now();
            return false;
        }
        let Some(end) = self.ended else {
            return false;
        };
        if o_word_line(text) || first_non_blank(text) == Some(b'%') {
            return false;
        }
        if !self.open.is_empty() {
            if !self.open_sub && self.first_in_block.is_none() && holds_program(text) {
                self.first_in_block = Some(line);
            }
            return false;
        }
        self.unread(line, text, end, false);
        true
    }

    /// Whether rs274 refuses the `%` line `line` it reads ("Bad character '%' used"): its
    /// reader takes a `%` for the opening of a file only on the first line that is not blank,
    /// and for the closing only where the file opened so and the line is `%` alone, blanks
    /// aside (`rs274ngc_pre.cc` `open`, `interp_read.cc` `read_text`, after
    /// `close_and_downcase`, which keeps comments: `% (end)` is no closing); any other `%`
    /// is a character no word begins with (`read_items`). After the M2/M30 rs274 has
    /// stopped: nothing is refused there.
    pub fn refuses_percent(&self, line: usize, text: &[u8]) -> bool {
        self.family == Family::LinuxCnc
            && self.ended.is_none()
            && first_non_blank(text) == Some(b'%')
            && self.opening != Some(line)
            && self.closed != Some(line)
    }

    /// Whether the file opened with a `%` line (rs274's `percent_flag`).
    pub fn percent_file(&self) -> bool {
        self.percent_file == Some(true)
    }

    fn unread(&mut self, line: usize, text: &[u8], end: usize, percent: bool) {
        if self.first_unread.is_none() && !self.noted && holds_program(text) {
            let line = match self.first_in_block {
                Some(first) if !percent => first,
                _ => line,
            };
            self.first_unread = Some(Unread { line, end, percent });
        }
    }

    /// The first line whose M word's value the reading did not know
    /// ([`ReadingEnd::read_with_values`]): an end there is not known, and the lines after it
    /// are read as program. The note a reading's error after it carries, which says so.
    pub fn unsure_note(&self) -> Option<String> {
        let line = self.unsure?;
        Some(format!(
            " (read as program: the M word on line {line} reads a value not known here, and \
             LinuxCNC reads no line after it if it is M2 or M30)"
        ))
    }

    /// Whether the line in hand stands inside an `o` block or definition (after the end: a
    /// subroutine's body, read as its definition).
    pub fn inside_block(&self) -> bool {
        !self.open.is_empty()
    }

    /// The first line not read that holds program text (not blanks and comments alone): said
    /// once.
    pub fn take_unread(&mut self) -> Option<Unread> {
        let first = self.first_unread.take();
        self.noted |= first.is_some();
        first
    }

    /// After a block is read: its word tokens (`M30`, `m2`), its statements and whether it
    /// begins with a block skip `/` (the switch may pass over its M2).
    #[inline]
    pub fn read<'a>(
        &mut self,
        tokens: impl IntoIterator<Item = &'a [u8]>,
        statements: impl IntoIterator<Item = (Kind, &'a [u8])>,
        skip: bool,
        line: usize,
    ) {
        self.read_with_m(tokens, statements, skip, line, true);
    }

    /// [`ReadingEnd::read`] where the caller knows whether a token is an M word (its first
    /// byte `M` or `m`): false, and the tokens are not searched for an M2 or M30 (most blocks
    /// have no M word).
    pub fn read_with_m<'a>(
        &mut self,
        tokens: impl IntoIterator<Item = &'a [u8]>,
        statements: impl IntoIterator<Item = (Kind, &'a [u8])>,
        skip: bool,
        line: usize,
        m_words: bool,
    ) {
        self.read_with_values(tokens, statements, skip, line, m_words, &|_| None);
    }

    /// [`ReadingEnd::read_with_m`] where the caller knows the values of parameters (`param`:
    /// of a parameter's text, `#<two>`, `#5`), which an M word's value may read (`M#<two>`).
    /// The readings know none: an M word of a parameter is then an end not known
    /// ([`ReadingEnd::unsure_note`]), and the reading goes on. (The checker, which knows
    /// some, reads its M words' values by the same [`linuxcnc_m_number`] after the block's
    /// words and tells the end so, [`ReadingEnd::ended_at`].)
    pub fn read_with_values<'a>(
        &mut self,
        tokens: impl IntoIterator<Item = &'a [u8]>,
        statements: impl IntoIterator<Item = (Kind, &'a [u8])>,
        skip: bool,
        line: usize,
        m_words: bool,
        param: &dyn Fn(&[u8]) -> Option<f64>,
    ) {
        if self.family != Family::LinuxCnc {
            return;
        }
        for (kind, text) in statements {
            if matches!(kind, Kind::Definition | Kind::Flow) {
                self.o_word(text);
            }
        }
        if self.ended.is_some() {
            // LinuxCNC 2.9's FANUC-style subprogram after the end: `O1000` ... `M99`, called
            // by `M98 P1000` (G-code reference, "M98, M99"; rs274 -g runs its body from the
            // call), read to its M99 as an `o<name> sub` is to its endsub
            let (mut program, mut returns) = (false, false);
            for (i, t) in tokens.into_iter().enumerate() {
                let Some(c) = t.first() else { continue };
                let n = whole_number(&t[1..]);
                program |= i == 0 && c.eq_ignore_ascii_case(&b'O') && n.is_some();
                returns |= c.eq_ignore_ascii_case(&b'M') && n == Some(99);
            }
            if program && self.open.is_empty() {
                // (a definition as an `o<name> sub` is: its lines run when called, so none
                // is TG117's; after its M99 the reader is back at the top level, where the
                // lines a call never reaches are: `rs274 -g` of `M98 P2000` / `M2` /
                // `O2000` / `G0 X1.` / `M99` / `G0 X2.` runs X1 and never X2; review
                // 79-lcnc79 N2)
                self.open_sub = true;
                self.open.push(FANUC_SUBPROGRAM.to_vec());
            } else if returns && self.open.last().is_some_and(|l| l == FANUC_SUBPROGRAM) {
                self.open.pop();
            }
            return;
        }
        if self.open.is_empty() && !skip && m_words {
            // (a token's first byte `M` or `m` by its case bit; the number read only then)
            let mut unsure = false;
            let ends = tokens.into_iter().any(|t| match t {
                [m, digits @ ..] if m | 0x20 == b'm' => match whole_number(digits) {
                    Some(n) => n == 2 || n == 30,
                    // (`M#<two>`, `M[1+1]`: by its value, where known)
                    None => match linuxcnc_m_number(digits, param) {
                        Some(n) => n == 2 || n == 30,
                        None => {
                            unsure = true;
                            false
                        }
                    },
                },
                _ => false,
            });
            if unsure && !ends && self.unsure.is_none() {
                self.unsure = Some(line);
            }
            if ends {
                self.ended = Some(line);
                self.unsettled = self.unsettled_now();
            }
        }
    }

    /// The block on line `line` ends the program by an M2/M30 its words do not show as
    /// written (`M#<two>`, `M[1+1]`: the checker evaluated it): as one read by
    /// [`ReadingEnd::read`], outside any `o` block (no block skip: the caller's test).
    pub fn ended_at(&mut self, line: usize) {
        if self.family == Family::LinuxCnc && self.ended.is_none() && self.open.is_empty() {
            self.ended = Some(line);
            self.unsettled = self.unsettled_now();
        }
    }

    /// An `o` statement: the block it opens or closes.
    fn o_word(&mut self, text: &[u8]) {
        let label = crate::statement::o_label(text);
        let Some(keyword) = crate::statement::o_keyword(text) else {
            return;
        };
        let closes = |open: &mut Vec<Vec<u8>>| {
            if let Some(at) = open.iter().rposition(|l| *l == label) {
                open.truncate(at);
            }
        };
        match keyword.as_slice() {
            // `o1 while [..]` closes the `o1 do` it ends, else opens a loop
            b"while" if self.open.contains(&label) => closes(&mut self.open),
            b"sub" | b"if" | b"do" | b"repeat" | b"while" => {
                if self.open.is_empty() {
                    self.open_sub = keyword == b"sub";
                }
                self.open.push(label);
            }
            b"endsub" | b"endif" | b"endwhile" | b"endrepeat" => closes(&mut self.open),
            _ => {}
        }
    }
}

/// The label [`ReadingEnd`] keeps for an open FANUC-style subprogram (`O1000` to its `M99`):
/// no `o` label is written so.
const FANUC_SUBPROGRAM: &[u8] = b"O (M99)";

/// The first line [`ReadingEnd`] passed over that holds program text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Unread {
    pub line: usize,
    /// The line of the M2/M30, or of the closing `%`, after which it stands.
    pub end: usize,
    /// After the closing `%` (nothing read), not after an M2/M30 (O-word lines read).
    pub percent: bool,
}

fn first_non_blank(text: &[u8]) -> Option<u8> {
    text.iter().copied().find(|c| !c.is_ascii_whitespace())
}

/// Whether rs274 reads a line as an O-word line (`read_items`): after its blanks, an optional
/// `/` and an optional line number `N..`, an `o`.
fn o_word_line(text: &[u8]) -> bool {
    let mut rest = text.iter().copied().filter(|c| !c.is_ascii_whitespace());
    let mut c = rest.next();
    if c == Some(b'/') {
        c = rest.next();
    }
    if c.is_some_and(|c| c.eq_ignore_ascii_case(&b'N')) {
        c = rest.find(|c| !c.is_ascii_digit() && *c != b'.');
    }
    c.is_some_and(|c| c.eq_ignore_ascii_case(&b'O'))
}

/// Whether a line holds more than blanks and comments (`( )`, `;` to its end).
pub fn holds_program(text: &[u8]) -> bool {
    let mut comment = false;
    for &c in text {
        match c {
            b')' if comment => comment = false,
            _ if comment => {}
            b'(' => comment = true,
            b';' => return false,
            c if c.is_ascii_whitespace() => {}
            _ => return true,
        }
    }
    false
}

/// LinuxCNC: the number of an M word whose value is `value` (the text after the `M`) as rs274
/// reads it -- a number, a parameter or an expression (interp_read.cc `read_m`,
/// `read_integer_value`: `M#<two>` and `M[1+1]` are M2) -- where it is known (`param`: a
/// parameter's value by its text): the integer [`crate::statement::rs274_integer`] makes of
/// it. None for a value not known or no integer. The one reading of an M word's number that
/// the end of a program follows, in the checker and in every reading ([`ReadingEnd`]).
pub fn linuxcnc_m_number(value: &[u8], param: &dyn Fn(&[u8]) -> Option<f64>) -> Option<i64> {
    let value = value.trim_ascii();
    let number = match std::str::from_utf8(value).ok()?.parse::<f64>() {
        Ok(number) => number,
        // (a chain of terms is a tree as deep, walked by recursion)
        Err(_) if value.len() > 200 => return None,
        Err(_) => {
            let tree = crate::expr::tree(value).ok()?;
            crate::expr::linuxcnc_value(&tree, value, param).ok()??
        }
    };
    crate::statement::rs274_integer(number)
}

/// A code's number written whole (`30`, `02`, `+2`, `2.0`): rs274 reads an M word's value as
/// an integer within a small tolerance (`read_integer_value`). An expression is None.
fn whole_number(digits: &[u8]) -> Option<i64> {
    let digits = digits.strip_prefix(b"+").unwrap_or(digits);
    let (whole, fraction) = match digits.iter().position(|&c| c == b'.') {
        Some(p) => (&digits[..p], &digits[p + 1..]),
        None => (digits, &b""[..]),
    };
    if whole.is_empty()
        || whole.len() > 9
        || !whole.iter().all(u8::is_ascii_digit)
        || !fraction.iter().all(|&c| c == b'0')
    {
        return None;
    }
    std::str::from_utf8(whole).ok()?.parse().ok()
}

/// In a Custom Macro B call (G65, G66, G66.1) an I, J or K word may repeat: argument
/// specification II passes A B C and up to ten I J K sets. Some(which word of its `letter` the
/// block's word `i` is: 1 for the first) where that applies, None elsewhere.
pub fn argument_sets(family: Family, words: &[Word<'_>], letter: u8, i: usize) -> Option<usize> {
    if family != Family::MacroB || !matches!(letter, b'I' | b'J' | b'K') {
        return None;
    }
    macro_call(words).then(|| words[..=i].iter().filter(|w| w.letter == letter).count())
}

/// A Custom Macro B call block: G65, G66 or G66.1.
pub fn macro_call(words: &[Word<'_>]) -> bool {
    words
        .iter()
        .any(|w| w.letter == b'G' && w.expression.is_empty() && macro_call_code(w.number))
}

/// Whether a G word's number reads as 65, 66 or 66.1. A number of digits and one point, as
/// nearly every one is, is compared by its digits, leading zeros of its whole part and
/// trailing zeros of its fraction left out (up to 15 digits a float reads them exactly, so
/// this is what the float's comparison finds); any other is read as a float. (A float was
/// read for every G word of every block a FANUC or Haas checks: 60-100 instructions each.)
fn macro_call_code(number: &[u8]) -> bool {
    // every way of writing a number that reads as 65, 66 or 66.1 has a 6 among its first
    // significant digits (64.99.., 65, 66.0.., 0.65E2): nearly every G word has none
    if !number.contains(&b'6') {
        return false;
    }
    let plain = number.len() <= 15
        && number.iter().all(|&c| c.is_ascii_digit() || c == b'.')
        && number.iter().filter(|&&c| c == b'.').count() <= 1
        && number.iter().any(u8::is_ascii_digit);
    if !plain {
        return matches!(
            std::str::from_utf8(number).ok().and_then(|n| n.parse::<f64>().ok()),
            Some(n) if n == 65.0 || n == 66.0 || n == 66.1
        );
    }
    let (whole, fraction) = match number.iter().position(|&c| c == b'.') {
        Some(p) => (&number[..p], &number[p + 1..]),
        None => (number, &b""[..]),
    };
    let lead = whole.iter().take_while(|&&c| c == b'0').count();
    let trail = fraction.iter().rev().take_while(|&&c| c == b'0').count();
    let (whole, fraction) = (&whole[lead..], &fraction[..fraction.len() - trail]);
    matches!(
        (whole, fraction),
        (b"65", b"") | (b"66", b"") | (b"66", b"1")
    )
}

/// In a Custom Macro B call (G65, G66, G66.1), `letter` is an argument: argument
/// specification I passes A B C D E F H I J K M Q R S T U V W X Y Z to #1-#26 (FANUC 0i-F
/// operator's manual, "Custom macro", "Argument specification I"), whatever the control's own
/// addresses are (a mill has no E, U, V or W word of its own).
pub fn macro_argument(family: Family, words: &[Word<'_>], letter: u8) -> bool {
    family == Family::MacroB
        && letter.is_ascii_uppercase()
        && !matches!(letter, b'G' | b'L' | b'N' | b'O' | b'P')
        && macro_call(words)
}

/// A FANUC reads M, S and T as whole numbers and alarms on a decimal point written in one,
/// `M3.0`, `S1000.0`, `T1.0` (PS0007, illegal use of decimal point: a decimal point at an
/// address that takes none; FANUC alarm list), where in brackets (`M[3.0]`) the value is
/// rounded (S. K. Sinha's summary of Custom Macro B: `M3.0 S1000` and `M03 S1000.0` are
/// illegal statements). What the address holds, for the message; None elsewhere. A Haas is
/// not judged: no Haas source at hand says what its control does (TG208 there). What the
/// address holds, and what the message adds (a mill's parameter 3451#2 for S).
pub fn whole_address(
    family: Family,
    haas: bool,
    letter: u8,
) -> Option<(&'static str, &'static str)> {
    if family != Family::MacroB || haas {
        return None;
    }
    Some(match letter {
        b'M' => ("an M code", ""),
        b'S' => (
            "a spindle speed",
            "; a FANUC mill whose parameter 3451#2 is set reads one decimal of S and rounds it",
        ),
        b'T' => ("a tool number", ""),
        _ => return None,
    })
}

/// A FANUC's Custom Macro B has no variable of the number `n` below its system variables:
/// local #1-#33, common #100-#199 (#100-#999 with the option) and #500-#999, none between
/// (0i-F/30i-B Operator's Manuals, "Custom macro", types of variables); a number that names
/// none is alarm PS0115, variable number out of range (FANUC alarm list). What the numbers
/// are, for the message. A Haas is not judged: its NGC table (Mill Operator's Manual, 2017,
/// 6.14.7) was not read for #34-#99.
pub fn missing_variable(family: Family, haas: bool, n: u64) -> Option<&'static str> {
    (family == Family::MacroB && !haas && (34..=99).contains(&n)).then_some(
        "Custom Macro B has local #1-#33, common #100-#199 (#100-#999 with the option) and \
         #500-#999, and system variables from #1000: no variable #34-#99",
    )
}

/// A numbered system variable that a program may read but not set: what it holds, or None.
/// Custom Macro B (FANUC 0i-F/30i-B "Custom macro", system variables; an assignment is alarm
/// PS0116): interface inputs, the clock's date and time, the modal information and the
/// positions; offsets, #3000 (alarm), #3001 (timer), #3006 (stop with message), #3901 (parts)
/// are set. LinuxCNC (rs274 2.9, "Parameter is readonly"): #5400-#5413, the tool in the
/// spindle and its offsets, and #5420-#5428, the current position.
pub fn read_only_variable(family: Family, n: u64) -> Option<&'static str> {
    Some(match (family, n) {
        (Family::MacroB, 1000..=1035) => "an interface input signal",
        (Family::MacroB, 3011 | 3012) => "the date or time",
        (Family::MacroB, 4001..=4400) => "modal information",
        (Family::MacroB, 5001..=5200) => {
            "a position (block end, machine, workpiece, skip, deviation)"
        }
        (Family::LinuxCnc, 5400..=5413) => "the tool in the spindle or its offsets",
        (Family::LinuxCnc, 5420..=5428) => "the current position",
        _ => return None,
    })
}

/// The read-only predefined named parameters of LinuxCNC 2.9 (without their `_`): rs274
/// refuses an assignment to each ("Cannot assign to read-only parameter").
const LINUXCNC_READ_ONLY: &[&str] = &[
    "vmajor",
    "vminor",
    "line",
    "motion_mode",
    "plane",
    "ccomp",
    "metric",
    "imperial",
    "absolute",
    "incremental",
    "inverse_time",
    "units_per_minute",
    "units_per_rev",
    "coord_system",
    "tool_offset",
    "retract_r_plane",
    "retract_old_z",
    "spindle_rpm_mode",
    "spindle_css_mode",
    "ijk_absolute_mode",
    "lathe_diameter_mode",
    "lathe_radius_mode",
    "spindle_on",
    "spindle_cw",
    "mist",
    "flood",
    "speed_override",
    "feed_override",
    "adaptive_feed",
    "feed_hold",
    "feed",
    "rpm",
    "x",
    "y",
    "z",
    "a",
    "b",
    "c",
    "u",
    "v",
    "w",
    "abs_x",
    "abs_y",
    "abs_z",
    "abs_a",
    "abs_b",
    "abs_c",
    "current_tool",
    "current_pocket",
    "selected_tool",
    "selected_pocket",
    "value",
    "value_returned",
    "task",
    "call_level",
    "remap_level",
];

/// The SINUMERIK system variables the List of System Variables gives part programs read
/// access only ("RS R": read, with a preprocessing stop): the actual values of an axis in each
/// coordinate system, its software limits, distances of synchronized axes, the reapproach
/// point. By the name before its `[`, in upper case.
const SINUMERIK_READ_ONLY: &[&str] = &[
    "$AA_IM",
    "$AA_IB",
    "$AA_IBN",
    "$AA_IEN",
    "$AA_SOFTENDP",
    "$AA_SOFTENDN",
    "$AA_DTBW",
    "$AA_DTBB",
    "$AA_DTEW",
    "$AA_DTEB",
    "$AC_RETPOINT",
    "$VA_IS",
];

/// A named variable a program may read but not set: LinuxCNC's predefined `#<_x>` (`name` is
/// what stands between `#<` and `>`, blanks out and in lower case), a SINUMERIK system
/// variable (`$AA_IM[X]`, `name` in upper case with its index). What it is, or None.
pub fn read_only_name(family: Family, name: &[u8]) -> Option<&'static str> {
    match family {
        Family::LinuxCnc => {
            let bare = name.strip_prefix(b"_")?;
            LINUXCNC_READ_ONLY
                .iter()
                .any(|n| n.as_bytes() == bare)
                .then_some("a predefined named parameter")
        }
        Family::Sinumerik => {
            let end = name.iter().position(|&c| c == b'[').unwrap_or(name.len());
            SINUMERIK_READ_ONLY
                .iter()
                .any(|n| n.as_bytes() == &name[..end])
                .then_some("a system variable of the current values")
        }
        _ => None,
    }
}

/// What a control does with a feed move at F0, for TG401's message: the alarm each family's
/// documentation names (docs/rules.md, TG401).
/// `arc`: the move is a G2/G3 (rs274 says so in its own words); `haas`: a Haas profile.
pub fn zero_feed_effect(family: Family, arc: bool, haas: bool) -> &'static str {
    match family {
        Family::LinuxCnc if arc => "rs274: 'Cannot make arc with zero feed rate'",
        Family::MacroB if haas => {
            "Custom Macro B's FANUC alarm PS0011 feed zero; the Haas sources at hand do not say"
        }
        Family::MacroB => {
            "FANUC alarm PS0011 feed zero; the F1-digit feed option, where F0 selects the rapid \
             rate, is not modelled"
        }
        Family::Sinumerik => {
            "SINUMERIK alarm 14800 programmed path velocity less than or equal to zero"
        }
        Family::LinuxCnc => "rs274: 'Cannot do g1 with zero feed rate'",
        _ => "no feed move runs at a feed rate of zero (ISO 6983-1 clause 7: F for a feed move)",
    }
}

/// The number of offset digits at the end of a Fanuc or Haas lathe's T word: `T0101` is tool
/// 1 with offset 1, `T025300` (a multi-turret lathe's eight-digit T, parameter 3032) tool 253
/// with offset 00. FANUC 30i-A Connection Manual (Function), B-63943EN-1, "Tool functions":
/// the lowest 1 to 3 digits of the T command are the compensation number, their count set in
/// parameter 5028 (the manual's example: 2, T0313 is tool 03 with offset 13; 0i-F alike).
/// Parameter 5028 at 2 is assumed; a machine set otherwise reads its T words otherwise.
pub const LATHE_OFFSET_DIGITS: u32 = 2;

/// What the control does with an assignment to a read-only variable: the end of a TG209
/// message. FANUC's alarm is PS0116; the Haas sources at hand (its operator's manual's macro
/// variable list) give no alarm number, so a Haas message quotes none.
pub fn read_only_effect(family: Family, haas: bool) -> &'static str {
    match family {
        Family::MacroB if haas => {
            "read only on Custom Macro B (FANUC PS0116), but the Haas NGC's macro variables \
             table does not mark it so, nor say what a Haas does with the assignment"
        }
        Family::LinuxCnc => {
            "rs274 refuses an assignment to it ('Parameter is readonly', 'Cannot assign to \
             read-only parameter')"
        }
        Family::Sinumerik => {
            "the List of System Variables gives a part program read access only, not write"
        }
        _ => "the control alarms on an assignment to it (FANUC PS0116 write-protected variable)",
    }
}

/// What a control of a dialect family does with a G (`letter` b'G') or M code its profile's
/// table lacks, where the profile does not say it alarms: the end of a TG307 message. A Haas
/// (`haas`) is its own machine builder: its M codes are the NGC manual's list, which the
/// profile holds, and the manual does not say what the control does with one it lacks (Mill
/// Operator's Manual, NGC, 2017, "M-codes"); FANUC's decoding and ladder are not Haas facts.
pub fn unknown_code_effect(family: Family, haas: bool, letter: u8) -> &'static str {
    match (family, letter) {
        (Family::MacroB, b'M') if haas => {
            "it is not in the Haas NGC manual's M-code list, which the profile holds, and the \
             manual does not say what the control does with an M code it lacks; an option, or an \
             M code alias making it a macro call, may add it on this machine"
        }
        (Family::MacroB, b'G') => {
            "the control alarms on it unless its parameters make it a macro call (Fanuc \
             6050-6059 G codes, 6080-6089 M codes; Haas G and M code aliases)"
        }
        (Family::MacroB, _) => {
            "the CNC itself decodes M00 M01 M02 M30 M98 M99 M198 and the M codes its \
             parameters make macro or subprogram calls; any other goes to the machine \
             builder's ladder (Fanuc PMC), so whether this machine has it is the builder's \
             M code list, which the profile does not hold"
        }
        (Family::Sinumerik, b'M') => {
            "the NC decodes M0 M1 M2 M17 M30, M3 M4 M5 M6 M19 M40-M45 M70 itself and hands \
             any other M function to the PLC: the machine manufacturer's"
        }
        (Family::LinuxCnc, b'G') => {
            "rs274 refuses it ('Unknown g code used') unless the configuration remaps it \
             (REMAP: the codes G0-G99.9 that LinuxCNC's tables leave blank are open to it)"
        }
        (Family::LinuxCnc, b'M') => {
            "rs274 refuses it ('Unknown m code used', past M199 'M-code greater than 199') \
             unless the configuration remaps it (REMAP; M200-M999 are open to it) or, \
             M100-M199, has a user M code program of that name in USER_M_PATH"
        }
        (Family::Okuma, b'M') => {
            "the profile's M code list holds only what the public sources name; the \
             machine's own list decides"
        }
        _ => "the profile does not know it; the machine's configuration may",
    }
}

/// A G code the control's configuration may define (LinuxCNC: a REMAP). LinuxCNC's Remap
/// manual, "Currently unallocated G-codes": a code of G0-G99.9 (one decimal at most) that its
/// tables leave blank may be remapped; rs274 2.9 refuses G100 and above, and two decimals
/// (G68.25), under a REMAP too ("G-code out of range"). A code its tables hold is no such
/// code: the caller asks only of a code the profile lacks.
pub fn g_code_remappable(family: Family, value: Dec) -> bool {
    let v = value.normalized();
    family == Family::LinuxCnc && v.scale <= 1 && v.mantissa >= 0 && v.trunc() < 100
}

/// An M code the control refuses whatever its configuration. LinuxCNC's rs274 reads an M code
/// past M199 only where the configuration remaps it (`read_m` looks the code up among the
/// remaps before it refuses "M-code greater than 199"), and the codes open to remapping there
/// are M200 to M999 (LinuxCNC Remap manual, "Currently unallocated M-codes", 2.7 to 2.9):
/// M200-M999 are the configuration's, as M10 or M100-M199 are (TG307); rs274 2.9 refuses
/// M1000 under a `REMAP=M1000` too. The reason, or None.
pub fn m_code_alarms(family: Family, n: i64) -> Option<&'static str> {
    (family == Family::LinuxCnc && n > 999).then_some(
        "rs274 reads M codes up to M199, and M200-M999 where the configuration remaps them \
         (REMAP), no others",
    )
}

/// What a Custom Macro B system variable numbered `n` holds on a FANUC (`haas` false) or a Haas, where its maker's
/// table gives it a meaning that is not a length: the program's alarm and message stop, the
/// clocks, the parts counts, the modal G codes... Assigned (`#3000 = 1 (TOOL BROKEN)`) or read,
/// such a variable is not a length, as the proof would otherwise have to be shown by the
/// program's uses, which an alarm never has (audit 50, B6). The positions (#5001 on), the tool
/// and work offsets (#2001 on, #5201 on, #7001 on, #10001 on) are lengths in the machine's
/// units and are not here, nor are a previous block's F, E or S (#4108, #4109, #4119: a feed
/// or a surface speed, lengths per minute). Sources: FANUC 0i-MF operator's manual, "System
/// variables"; Haas Mill Operator's Manual, NGC, 2017, 6.14.7 (Macro Variables Table); the
/// ranges as docs/dialects.md, "Variables", lists them.
pub(crate) fn system_not_length(haas: bool, n: u32) -> Option<&'static str> {
    let shared = match n {
        3000 => Some("the program's alarm"),
        3001 | 3002 => Some("a clock"),
        3003 | 3004 => Some("the control of single block, feed hold and override"),
        3006 => Some("the stop with a message"),
        3011 | 3012 => Some("the date or time"),
        3901 | 3902 => Some("a parts count"),
        4001..=4021 => Some("the G code of a modal group"),
        _ => None,
    };
    let own = if haas {
        match n {
            3020..=3025 => Some("a timer"),
            3026 => Some("the tool in the spindle"),
            3027 => Some("the spindle's speed"),
            _ => None,
        }
    } else {
        match n {
            1000..=1035 => Some("an interface signal"),
            3005 => Some("the settings"),
            3007 => Some("the mirror image state"),
            4022..=4030 => Some("the G code of a modal group"),
            4107 | 4111 | 4113 | 4114 | 4115 | 4120 | 4130 => {
                Some("the previous block's D, H, M, N, O, T or P code")
            }
            _ => None,
        }
    };
    shared.or(own)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What follows a program's first `%`, by [`leader_text`]: a leading comment is the
    /// identification's, and what comes after it is judged as if it stood first (review 29,
    /// finding 5); letters inside a comment are the comment's.
    #[test]
    fn leader_text_reads_past_a_leading_comment() {
        let words = Some(LeaderText::Words);
        let letters = Some(LeaderText::Letters);
        for (ident, expected) in [
            (&b""[..], None),
            (b"  ", None),
            (b"(TITLE)", None),
            (b"(TITLE", None),
            (b":0003", None),
            (b":0003 (TITLE)", None),
            (b"O1000", words),
            (b"X-1.", words),
            (b" (TITLE) O1000", words),
            (b"(T)X1", words),
            (b"(A)(B) O1", words),
            (b"#1=1", words),
            (b"(A)#1=1", words),
            (b"TITLE", letters),
            (b"(A) TITLE", letters),
            (b":0003 TITLE", letters),
        ] {
            assert_eq!(
                leader_text(ident),
                expected,
                "{:?}",
                String::from_utf8_lossy(ident)
            );
        }
    }

    /// A G word's number is a macro call's code where a float reads it as 65, 66 or 66.1,
    /// as it was read before the digits were compared: every number of up to five of the
    /// characters `0156.`, and longer ones either side of the 15 digits compared.
    #[test]
    fn a_macro_call_code_is_what_a_float_reads() {
        let float = |n: &[u8]| {
            matches!(
                std::str::from_utf8(n).ok().and_then(|n| n.parse::<f64>().ok()),
                Some(v) if v == 65.0 || v == 66.0 || v == 66.1
            )
        };
        let mut numbers: Vec<Vec<u8>> = vec![Vec::new()];
        let mut last: Vec<Vec<u8>> = vec![Vec::new()];
        for _ in 0..5 {
            last = last
                .iter()
                .flat_map(|n| {
                    b"0156.".iter().map(move |&c| {
                        let mut m = n.clone();
                        m.push(c);
                        m
                    })
                })
                .collect();
            numbers.extend(last.iter().cloned());
        }
        for long in [
            &b"0000000000000065"[..],
            b"000000000000066.1",
            b"66.100000000000000",
            b"65.000000000000000000001",
            b"66.0999999999999999999",
            b"0066.10",
            b"6.6e1",
            b"64.99999999999999999999",
            b"650e-1",
            b"0.661E2",
            b"+66",
        ] {
            numbers.push(long.to_vec());
        }
        let mut calls = 0;
        for n in &numbers {
            assert_eq!(
                super::macro_call_code(n),
                float(n),
                "{}",
                String::from_utf8_lossy(n)
            );
            calls += usize::from(float(n));
        }
        assert!(calls > 20, "{calls}");
    }

    #[test]
    fn a_program_number_or_a_folder_after_an_end_begins_the_next_program() {
        let o = |at| Opening {
            word: Some((at, b'O')),
            ..Opening::default()
        };
        let folder = Opening {
            word: None,
            statement: Some((1, Kind::Name, &b"&F=/USER/PATH2/"[..])),
            ..Opening::default()
        };
        let name = Opening {
            word: None,
            statement: Some((1, Kind::Name, &b"O7997A"[..])),
            ..Opening::default()
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
            ..Opening::default()
        };
        assert!(!split.begins(fanuc.0, fanuc.1, &g0)); // a local N100 subprogram's block
        assert!(split.begins(fanuc.0, fanuc.1, &folder));
        assert!(!split.begins(fanuc.0, fanuc.1, &o(1))); // the folder began it
        split.ended(true);
        assert!(split.begins(fanuc.0, fanuc.1, &name));
        split.ended(true);
        // a FANUC program named by a file name in < > (B-64014EN/03, 2.5), words after it
        let named = Opening {
            word: Some((6, b'M')),
            statement: Some((1, Kind::Name, &b"<101>"[..])),
            ..Opening::default()
        };
        assert!(split.begins(fanuc.0, fanuc.1, &named));
        assert!(!split.begins(fanuc.0, fanuc.1, &named)); // no end since
        split.ended(true);
        // a word before the statement decides: "G0 O7997A" is no program number first
        let later = Opening {
            word: Some((1, b'G')),
            statement: Some((4, Kind::Name, &b"O7997A"[..])),
            ..Opening::default()
        };
        assert!(!split.begins(fanuc.0, fanuc.1, &later));
        // only Custom Macro B splits so; a profile without a program number address neither
        assert!(!split.begins(Family::LinuxCnc, Some(b'O'), &o(1)));
        assert!(!split.begins(Family::MacroB, None, &o(1)));
        assert!(split.begins(fanuc.0, fanuc.1, &o(1)));
    }

    #[test]
    fn a_fanuc_skips_its_leader_and_the_program_number_in_it() {
        assert!(skips_leader(Family::MacroB, false));
        assert!(!skips_leader(Family::MacroB, true)); // a Haas: no source says so
        assert!(!skips_leader(Family::Iso, false));
        let o = Some(b'O');
        assert_eq!(leader_program_number(b" O0001", o), Some(&b"O0001"[..]));
        assert_eq!(
            leader_program_number(b"O0003( 300-11 MILL)", o),
            Some(&b"O0003"[..])
        );
        assert_eq!(
            leader_program_number(b"<PART_A> REV 2", o),
            Some(&b"<PART_A>"[..])
        );
        assert_eq!(leader_program_number(b"PART A REV 2", o), None);
        assert_eq!(leader_program_number(b"OLD PART", o), None);
        assert_eq!(leader_program_number(b"O0001", None), None);
    }

    #[test]
    fn a_sinumerik_archive_s_next_file_begins_the_next_program() {
        let sinumerik = (Family::Sinumerik, None);
        let header = Opening::percent_line(b"%_N_SUB1_SPF  ");
        assert_eq!(header.percent, Some(&b"_N_SUB1_SPF"[..]));
        let mut split = ProgramSplit::default();
        // the archive's first file begins nothing new
        assert!(!split.begins(
            sinumerik.0,
            sinumerik.1,
            &Opening::percent_line(b"%_N_MAIN_MPF")
        ));
        split.ended(true); // M30, M17 or RET
                           // a bare closing % names no file
        assert!(!split.begins(sinumerik.0, sinumerik.1, &Opening::percent_line(b"%")));
        assert!(split.begins(sinumerik.0, sinumerik.1, &header));
        // no end before it (M99, a PLC's code, or nothing): the next file all the same
        assert!(split.begins(
            sinumerik.0,
            sinumerik.1,
            &Opening::percent_line(b"%_N_B_MPF")
        ));
        // a bare % line or a comment in parentheses names no file: nothing begins
        assert!(!split.begins(sinumerik.0, sinumerik.1, &Opening::percent_line(b"%(X)")));
        // a Fanuc's % line begins no program
        split.ended(true);
        assert!(!split.begins(Family::MacroB, Some(b'O'), &header));
        assert!(crate::dialect::splits(Family::Sinumerik, None));
        // what the file is, by its name (punched tape format, and the control's own names)
        for (name, sub) in [
            (&b"_N_SHAFT123_MPF"[..], Some(false)),
            (b"Flange3_MPF", Some(false)),
            (b"_N_SUB1_SPF", Some(true)),
            (b"_n_sub1_spf", Some(true)),
            (b"SPF12", Some(true)),
            (b"L100", Some(true)),
            (b"MPF 90", Some(false)),
            (b"_N_COMPLETE_TEA_INI", Some(false)),
            (b"", None),
            (b"(PART 1)", None),
        ] {
            assert_eq!(archive_file(Family::Sinumerik, name), sub, "{name:?}");
        }
        assert_eq!(archive_file(Family::MacroB, b"_N_SUB1_SPF"), None);
    }

    /// The lines a [`ReadingEnd`] passes over in `program`, the M2/M30 read from each line's
    /// words (split at blanks) and its `o` statement (a line beginning with `o`).
    fn passed_over(family: Family, program: &str) -> Vec<usize> {
        let mut end = ReadingEnd::new(family);
        let mut skipped = Vec::new();
        for (i, text) in program.lines().enumerate() {
            let line = i + 1;
            if end.skips(line, text.as_bytes()) {
                skipped.push(line);
                continue;
            }
            let body = text.trim_start_matches('/');
            let statement = body
                .trim_start()
                .starts_with(['o', 'O'])
                .then_some((Kind::Flow, body.trim().as_bytes()));
            let words = body.split_whitespace().map(str::as_bytes);
            end.read(words, statement, text.starts_with('/'), line);
        }
        skipped
    }

    #[test]
    fn linuxcnc_reads_no_line_after_a_top_level_end_but_the_o_word_lines() {
        let lcnc = |p: &str| passed_over(Family::LinuxCnc, p);
        assert_eq!(lcnc("G0 X1\nM30\nprint[x]\n(note)\nG0 X2\n"), [3, 4, 5]);
        // M2, M02, m30, M2.0, +2, an expression of the value (rs274 read_m reads it by
        // read_integer_value: `M[30]`, `M[1+1]` end the program, rs274 -g), a value within
        // 0.0001 of 2: the values rs274 reads as an end; M20, M3, M2.5 are none
        for end in [
            "M2", "M02", "m30", "M2.0", "M+2", "M[30]", "M[1+1]", "M2.00005",
        ] {
            assert_eq!(lcnc(&format!("{end}\nX\n")), [2], "{end}");
        }
        for other in ["M20", "M3", "M2.5", "M[2.5]", "M#<two>"] {
            assert_eq!(
                lcnc(&format!("{other}\nX\n")),
                Vec::<usize>::new(),
                "{other}"
            );
        }
        // a parameter's value, which the reading does not know: no end, said at the first
        let mut end = ReadingEnd::new(Family::LinuxCnc);
        assert_eq!(end.unsure_note(), None);
        for (line, text) in [(1, "M#<two>"), (2, "M#1"), (3, "M[#1+1]")] {
            end.read([text.as_bytes()], None, false, line);
        }
        assert!(end.unsure_note().unwrap().contains("M word on line 1 "));
        // ... which the checker's values give (read_with_values)
        let mut end = ReadingEnd::new(Family::LinuxCnc);
        let two = |p: &[u8]| (p == b"#<two>").then_some(2.0);
        assert!(!end.skips(1, b"M#<two>"));
        end.read_with_values([b"M#<two>".as_slice()], None, false, 1, true, &two);
        assert!(end.skips(2, b"G0 X1"));
        // a subroutine's definition after the end is read to its endsub, then no more
        let sub = "M2\nX\no<s> sub\nG0 X1\no<s> endsub\nG0 X2\n";
        assert_eq!(lcnc(sub), [2, 6]);
        // an O-word line is read, a % line too (the checker's closing %)
        assert_eq!(lcnc("M2\no100 if [1]\n%\n"), Vec::<usize>::new());
        assert_eq!(
            lcnc("M2\n  N10 o<a> call\n/o1 return\n"),
            Vec::<usize>::new()
        );
        // an end inside an o block (a branch, a loop, a definition) may not run: read on
        assert_eq!(lcnc("o1 if [#1]\nM2\no1 endif\nG0 X1\nM2\nX\n"), [6]);
        assert_eq!(lcnc("o2 do\nM30\no2 while [#1]\nG0\nM30\nX\n"), [6]);
        assert_eq!(lcnc("o3 sub\nM2\no3 endsub\nG0\n"), Vec::<usize>::new());
        // a block skip may pass over the M30: read on
        assert_eq!(lcnc("/M30\nG0 X1\n"), Vec::<usize>::new());
        // a file begun with % ends at its closing %: nothing after, O-word lines neither
        assert_eq!(lcnc("\n%\nG0 X1\n%\no<s> sub\nX\n"), [5, 6]);
        // a % mid-file of a file not begun with % closes nothing
        assert_eq!(lcnc("G0 X1\n%\nG0 X2\n"), Vec::<usize>::new());
        // every other family reads on (a Fanuc file holds its subprograms after M30)
        assert_eq!(
            passed_over(Family::MacroB, "M30\nO100\nG0 X1\nM99\n"),
            Vec::<usize>::new()
        );
    }

    /// The `%` lines rs274 refuses in `program` ("Bad character '%' used").
    fn refused_percent(family: Family, program: &str) -> Vec<usize> {
        let mut end = ReadingEnd::new(family);
        let mut refused = Vec::new();
        for (i, text) in program.lines().enumerate() {
            let line = i + 1;
            if end.skips(line, text.as_bytes()) {
                continue;
            }
            if end.refuses_percent(line, text.as_bytes()) {
                refused.push(line);
            }
            end.read(text.split_whitespace().map(str::as_bytes), [], false, line);
        }
        refused
    }

    #[test]
    fn linuxcnc_refuses_a_percent_line_but_the_opening_and_the_closing_one() {
        let lcnc = |p: &str| refused_percent(Family::LinuxCnc, p);
        // a file begun with % (blank lines before it aside): its closing % alone is read
        assert_eq!(lcnc("\n  %  \nG0 X1\n%\n"), Vec::<usize>::new());
        // ... a closing % with a comment is no closing (close_and_downcase keeps comments)
        assert_eq!(lcnc("%\nG0 X1\n% (end)\nG0 X5\n"), [3]);
        // a file not begun with %: every % line is a block of a bad character
        assert_eq!(lcnc("(hdr)\n%\nG0 X1\n%\nM30\n"), [2, 4]);
        assert_eq!(lcnc("% (c)\nG0 X1\nM30\n"), [1]);
        // after the M2/M30 nothing is read: no refusal
        assert_eq!(lcnc("G0 X1\nM30\n%\n"), Vec::<usize>::new());
        // every other family takes % for the tape's rewind stop
        assert_eq!(
            refused_percent(Family::MacroB, "(hdr)\n%\nG0 X1\n"),
            Vec::<usize>::new()
        );
    }

    #[test]
    fn a_fanuc_g10_l50_or_l3_opens_data_until_g11() {
        let blocks = |family: Family, program: &str| {
            let mut input = DataInput::default();
            program
                .lines()
                .enumerate()
                .map(|(i, text)| {
                    let words = text
                        .split_whitespace()
                        .map(|w| (w.as_bytes()[0], &w.as_bytes()[1..]));
                    input.block(family, i + 1, words)
                })
                .collect::<Vec<_>>()
        };
        let data = |closes| DataBlock::Data {
            opened: 1,
            l: 50,
            closes,
        };
        let l50 = "G10 L50\nN1420 R15000\nN1422 P1 R20000\nG11\nG0 X1.";
        assert_eq!(
            blocks(Family::MacroB, l50),
            [
                DataBlock::Program,
                data(false),
                data(false),
                data(true),
                DataBlock::Program
            ]
        );
        // a program word inside the mode: the mode ends there (a G11 missing)
        let stray = blocks(Family::MacroB, "G10 L50\nN1420 R15000\nG0 X1.\nN5 X2.");
        let expected = DataBlock::Stray {
            opened: 1,
            l: 50,
            letter: b'G',
        };
        assert_eq!(stray[2], expected);
        assert_eq!(stray[3], DataBlock::Program);
        // G10 L3: tool life data, T the tools of a group (no tool change)
        let l3 = blocks(Family::MacroB, "G10 L3\nP1 L500 Q1\nT10\nG11");
        assert_eq!(
            l3[2],
            DataBlock::Data {
                opened: 1,
                l: 3,
                closes: false
            }
        );
        // G10 L2 (a work offset) opens nothing; another family has no such mode
        assert_eq!(
            blocks(Family::MacroB, "G10 L2 P1 X0\nN10 R5")[1],
            DataBlock::Program
        );
        assert_eq!(blocks(Family::LinuxCnc, l50)[1], DataBlock::Program);
    }

    #[test]
    fn the_first_line_not_read_with_program_text_is_said_once() {
        let mut end = ReadingEnd::new(Family::LinuxCnc);
        assert!(!end.skips(1, b"G0 X1"));
        end.read([&b"M30"[..]], [], false, 2);
        assert!(end.skips(3, b"  (comment) ; and another"));
        assert_eq!(end.take_unread(), None);
        assert!(end.skips(4, b"print[x]"));
        assert!(end.skips(5, b"G0 X2"));
        let first = Unread {
            line: 4,
            end: 2,
            percent: false,
        };
        assert_eq!(end.take_unread(), Some(first));
        assert!(end.skips(6, b"G0 X3"));
        assert_eq!(end.take_unread(), None);
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
    fn finds_a_linuxcnc_subroutine_definition() {
        let of = |text: &'static [u8], kind| subroutine_definition(&[(1, kind, text)]);
        assert_eq!(of(b"o<fv_cut-to> sub", Kind::Definition), Some(true));
        assert_eq!(of(b"O100 SUB", Kind::Definition), Some(true));
        assert_eq!(of(b"o<z_touch> endsub", Kind::Definition), Some(false));
        assert_eq!(of(b"o123 end sub [3 * 4]", Kind::Definition), Some(false));
        assert_eq!(of(b"o<x> call", Kind::Call), None);
        assert_eq!(subroutine_definition(&[]), None);
    }

    #[test]
    fn a_sinumerik_proc_opens_a_subprogram() {
        assert!(defines_subprogram(
            Family::Sinumerik,
            &[(1, Kind::Declaration, b"PROC MYSUB")]
        ));
        assert!(defines_subprogram(
            Family::Sinumerik,
            &[(1, Kind::Declaration, b"proc mysub(real x) save")]
        ));
        assert!(!defines_subprogram(
            Family::Sinumerik,
            &[(1, Kind::Declaration, b"PROCESS")]
        ));
        assert!(!defines_subprogram(
            Family::Sinumerik,
            &[(1, Kind::Declaration, b"EXTERN MYSUB(REAL)")]
        ));
        assert!(!defines_subprogram(
            Family::MacroB,
            &[(1, Kind::Declaration, b"PROC MYSUB")]
        ));
    }

    #[test]
    fn a_sinumerik_spf_is_a_subprogram_by_its_name() {
        assert!(subprogram_by_name(
            Family::Sinumerik,
            "SPF/SHAPE/GEAR_60.SPF"
        ));
        assert!(subprogram_by_name(Family::Sinumerik, "l100.spf"));
        assert!(!subprogram_by_name(Family::Sinumerik, "MAIN.MPF"));
        assert!(!subprogram_by_name(Family::Sinumerik, "<input>"));
        assert!(!subprogram_by_name(Family::MacroB, "O1000.SPF"));
    }

    #[test]
    fn reads_the_profile_names() {
        assert_eq!(PastFormat::from_name("round"), Some(PastFormat::Round));
        assert_eq!(PastFormat::from_name("cut"), None);
    }
}
