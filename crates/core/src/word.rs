//! A word and its number, as every reader of the core reads them: the checker, the diff's
//! reader ([`crate::ncread`]) and the converter.
//!
//! A word token is split into its address, index, sign and plain number (or the expression
//! that stands in its place) by [`Word::new`]. Its number is read through the profile's word
//! formats by [`Numbers`]: the format of its letter in the units in force (the inch formats
//! first while inch is), and whether a number written without a point counts least input
//! increments (Fanuc) or is a whole number (ISO 6983-1). That rule is written here once.
//! This module imports only the leaves below it: exact decimals, word formats and the modal
//! values and units.

use crate::decimal::{Dec, MAX_DIGITS};
use crate::lex::{Digits, Family, Token};
use crate::modal::{BlockValues, ModalSettings, Units};
use crate::wordformat::WordFormat;

/// The words that give a G04 dwell its time on a control: in a G04 block these are read as
/// the dwell's data (plain numbers, no move, no feed, no speed); every other word of the
/// block is what it is elsewhere. The reader, the modal state, the restart walk, the
/// converter and the checker (TG531, TG532) all take them from here.
/// - LinuxCNC: P alone (seconds). rs274 reads `G4 P1 X10` as a dwell, then a move to X10 in
///   the motion mode in force, and `G4 P1 F100` sets the feed; `G4 X1` is "Dwell time
///   missing with g4" (or "Cannot use axis values without a g code that uses them" with no
///   motion mode).
/// - SINUMERIK: F (seconds) and S (revolutions of the master spindle): Programming Manual
///   Fundamentals, "Dwell time (G4)"; the F and S programmed before stay in force.
/// - A Fanuc or Haas lathe: X, U or P ("G04 X_ ; or G04 U_ ; or G04 P_ ;", the FANUC lathe
///   operator's manuals, "Dwell (G04)"); U there is that time, not an increment of X.
/// - A Fanuc or Haas mill: X or P (the Fanuc machining-center manuals' "G04 X_ ; or
///   G04 P_ ;"); F is no dwell word there but the feed, as in any other block (`G04 X1. F100.`
///   is a dwell of 1 s and a feed of 100). No Haas page at hand lists the letters otherwise.
/// - Elsewhere (ISO, Okuma, HEIDENHAIN) X or P, and ISO 6983-1's F (clause 13): no source at
///   hand for Okuma's or HEIDENHAIN's letters says otherwise.
pub fn dwell_words(family: Family, fanuc_lathe: bool) -> &'static [u8] {
    match family {
        Family::LinuxCnc => b"P",
        Family::Sinumerik => b"FS",
        Family::MacroB if fanuc_lathe => b"XUP",
        Family::MacroB => b"XP",
        _ => b"XPF",
    }
}

/// The letter that gives an arc its radius (`G02 X Z R`, instead of the centre I J K) on a
/// control: R, as the profiles' `checks.pqr` reads it, but on an Okuma OSP lathe L (OSP-P200L
/// Programming Manual 5238-E, section 3 "Circular Interpolation (G02, G03)", P-26: "L: Sets
/// the radius of the arc"; R there is the drilling cycle's infeed). The checker's arc rules and
/// statistics, the converter and the diff's reader all take the letter from here, through
/// [`ModalSettings::arc_radius`].
pub fn arc_radius(family: Family, lathe: bool) -> u8 {
    if family == Family::Okuma && lathe {
        b'L'
    } else {
        b'R'
    }
}

/// What the radius letter L is in a block of a control whose arc radius is L (an Okuma OSP
/// lathe), given the motion in force after the block's G codes and the block's own G codes: a
/// length in an arc (G02/G03 in force, the block's other G codes only modes: plane, units,
/// nose radius compensation, distance, feed and spindle), and in the fixed thread cutting
/// cycle's block (G31/G33: its chamfering distance, 5238-E, section 7, "Fixed Thread Cutting
/// Cycle: Longitudinal", P-97), and in the automatic chamfering G75 and corner rounding G76 of
/// a G01 block (the chamfer's size, the corner's radius: the P200L list as NC-PB/gEdit's OSP
/// lathe notes give it). Elsewhere -- a cycle's block (G73 X Z K D L), whatever motion
/// is in force -- the sources at hand do not say what L is: a parameter in the converter's
/// terms, refused under a change of units unless `--allow-unconverted`. None on any other
/// control, where L keeps the role it has (a count: `M98 P L`, `G10 L`).
pub fn radius_letter_role(arc_radius: u8, motion: Option<i64>, gs: &[i64]) -> Option<Role> {
    if arc_radius != b'L' {
        return None;
    }
    let mode = |g: i64| matches!(g, 0..=3 | 17..=21 | 40..=42 | 90 | 91 | 94..=97);
    let arc = matches!(motion, Some(2 | 3)) && gs.iter().all(|&g| mode(g));
    let thread = gs.iter().any(|&g| matches!(g, 31 | 33 | 75 | 76));
    Some(if arc || thread {
        Role::Length
    } else {
        Role::Parameter
    })
}

/// What P, Q or R stands for on this control.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    Length,
    Parameter,
    Other,
    /// A length a cycle writes as a count of least input increments, with no decimal point
    /// (the Fanuc lathe's `G76 P1200 Q350`): the cycle tables of `convert::cycle_roles` only.
    Increments,
    /// A whole number that selects a mode or a function (`G05.1 Q1`, AI contour control on):
    /// read and written as it is written, never in least increments nor in units
    /// ([`crate::meaning`]).
    Selector,
}

/// A word of a block as the checker reads it.
#[derive(Debug, Clone, Copy)]
pub struct Word<'a> {
    /// The address as written (`x` in a lower-case program).
    pub address: u8,
    /// The address in upper case; `:` and `#` as they are.
    pub letter: u8,
    pub index: &'a [u8],
    pub sign: &'a [u8],
    pub number: &'a [u8],
    pub expression: &'a [u8],
    pub column: usize,
    pub token: &'a [u8],
    /// The number is written with a decimal point (found while it is split).
    pub point: bool,
    /// Where that point is in `number` (`number.len()` without one): found once, while the
    /// word is split, for the readers of its value and of its decimals ([`Word::fraction`]).
    pub dot: usize,
    /// The number's digits as one whole number, read while the word is split
    /// ([`crate::lex::Digits::value`]: Some for 1 to 18 digits): its value is taken from it
    /// by [`Numbers::read`] without a reading of its own.
    pub value: Option<u64>,
}

impl<'a> Word<'a> {
    /// Split a word token into its parts: a plain number, or else the expression after the
    /// address and index.
    pub fn new(token: &'a [u8], column: usize) -> Word<'a> {
        let address = token.first().copied().unwrap_or(b'?');
        let mut pos = 1.min(token.len());
        let mut digits = pos;
        while digits < token.len() && token[digits].is_ascii_digit() {
            digits += 1;
        }
        let mut index: &[u8] = b"";
        if digits > pos && token.get(digits) == Some(&b'=') {
            index = &token[pos..digits];
            pos = digits + 1;
        } else if digits == pos && token.get(pos) == Some(&b'=') {
            pos += 1; // Sinumerik's X=10 is X10; X=R1+5 an expression
        }
        let value = pos;
        let mut at = pos;
        if at < token.len() && matches!(token[at], b'+' | b'-') {
            at += 1;
        }
        let number_start = at;
        let mut digits: u64 = 0;
        while at < token.len() && token[at].is_ascii_digit() {
            digits = digits
                .wrapping_mul(10)
                .wrapping_add(u64::from(token[at] - b'0'));
            at += 1;
        }
        let point = at < token.len() && token[at] == b'.';
        let dot = at - number_start;
        if point {
            at += 1;
            while at < token.len() && token[at].is_ascii_digit() {
                digits = digits
                    .wrapping_mul(10)
                    .wrapping_add(u64::from(token[at] - b'0'));
                at += 1;
            }
        }
        let (sign, number, expression): (&[u8], &[u8], &[u8]) =
            if at == token.len() && at > number_start {
                (&token[value..number_start], &token[number_start..], b"")
            } else {
                (b"", b"", &token[value..])
            };
        Word {
            address,
            letter: address.to_ascii_uppercase(),
            index,
            sign,
            number,
            expression,
            column,
            token,
            point: point && !number.is_empty(),
            dot: if point && !number.is_empty() {
                dot
            } else {
                number.len()
            },
            value: if number.is_empty() {
                None
            } else {
                Digits::new(dot, number.len() - usize::from(point), digits).value
            },
        }
    }

    /// The word of a tokenizer's `token` at `column`: its parts as the tokenizer found them
    /// where it is a plain number after its address ([`Token::plain`], [`Token::digits`]),
    /// without a second reading; else as [`Word::new`] splits it. The same word either way.
    /// (A block's list of words is [`Word::extend_of`]'s, which writes them in place,
    /// or, for a line of plain words alone, [`crate::tokenizer::plain_line_words`]'s.)
    #[inline]
    pub fn of(token: &'a Token<'_>, column: usize) -> Word<'a> {
        match token.plain {
            Some(sign) => Word::plain_of(token, sign, column),
            None => Word::new(&token.text, column),
        }
    }

    /// The words of a tokenizer's `tokens` appended to `words`, each at the column `at` gives
    /// its offset: [`Word::of`] of each. Every token is first taken as a plain one, a mapping
    /// without a branch that `extend` writes straight into the list; then the few that are not
    /// plain are split again by [`Word::new`]. (`Word::of`, whose two ways meet in one value,
    /// built each word on the stack and copied its 120 bytes in: about 70 instructions a word.)
    #[inline]
    pub fn extend_of(
        words: &mut Vec<Word<'a>>,
        tokens: &'a [Token<'_>],
        at: impl Fn(usize) -> usize,
    ) {
        debug_assert!(
            tokens.iter().all(|t| !t.text.is_empty()),
            "a token without text"
        );
        let start = words.len();
        words.extend(
            tokens
                .iter()
                .map(|t| Word::plain_of(t, t.plain.unwrap_or(0), at(t.offset))),
        );
        for (w, t) in words[start..].iter_mut().zip(tokens) {
            if t.plain.is_none() {
                *w = Word::new(&t.text, w.column);
            }
        }
    }

    /// [`Word::of`] of a plain token, its sign `sign` bytes long (of any other token, a word
    /// to be split again: every token's text holds its address at least, the byte it starts
    /// at). (A placeholder text for the tokens that are not plain, to look at none of their
    /// bytes, cost 20-40 instructions a block: the map was no longer written in place.)
    #[inline(always)]
    fn plain_of(token: &'a Token<'_>, sign: u8, column: usize) -> Word<'a> {
        Word::plain(&token.text, sign != 0, token.digits, column)
    }

    /// The word of a plain `text` (its address, a sign where `signed`, digits with an optional
    /// point: [`crate::tokenizer`]'s plain word) at `column`, its number's `digits` as they were
    /// scanned: the word of the token the tokenizer makes of it ([`Word::plain_of`]), or the
    /// word the tokenizer writes where it scans a line of plain words alone
    /// ([`crate::tokenizer::plain_line_words`]). (Of a token that is not plain, `signed` false
    /// and no digits: a word to be split again, its text its address at least.)
    #[inline(always)]
    pub fn plain(text: &'a [u8], signed: bool, digits: Digits, column: usize) -> Word<'a> {
        let address = text[0];
        let value = 1 + usize::from(signed);
        let number = &text[value..];
        let dot = digits.dot as usize;
        Word {
            address,
            letter: address.to_ascii_uppercase(),
            index: b"",
            sign: &text[1..value],
            number,
            expression: b"",
            column,
            token: text,
            point: dot < number.len(),
            dot,
            value: digits.value,
        }
    }

    /// The word of a bracketed `text` (its address, then `[`, an expression and its `]`:
    /// [`crate::tokenizer`]'s bracketed word, `Y[#<yscale>*-32.725]`) at `column`: no index,
    /// sign or number, the expression all after the address -- what [`Word::new`] splits it
    /// into, written without its walk (about 100 instructions a word; a debug build splits it
    /// too and asserts the same parts).
    #[inline(always)]
    pub(crate) fn bracketed(text: &'a [u8], column: usize) -> Word<'a> {
        let address = text[0];
        let word = Word {
            address,
            letter: address.to_ascii_uppercase(),
            index: b"",
            sign: b"",
            number: b"",
            expression: &text[1..],
            column,
            token: text,
            point: false,
            dot: 0,
            value: None,
        };
        if cfg!(debug_assertions) {
            let split = Word::new(text, column);
            assert_eq!(text.get(1), Some(&b'['), "{text:?}: not bracketed");
            assert!(
                (split.index, split.sign, split.number, split.expression)
                    == (word.index, word.sign, word.number, word.expression)
                    && (split.point, split.dot, split.value) == (word.point, word.dot, word.value),
                "{text:?}: a bracketed word's parts"
            );
        }
        word
    }

    /// The digits of the number before its point and after it (all of them before, and none
    /// after, without a point).
    pub fn whole_and_fraction(&self) -> (&'a [u8], &'a [u8]) {
        match self.number.get(self.dot + 1..) {
            Some(fraction) => (&self.number[..self.dot], fraction),
            None => (self.number, b""),
        }
    }

    /// The token as text, for a message.
    pub(crate) fn token(&self) -> String {
        String::from_utf8_lossy(self.token).into_owned()
    }
}

/// (negative, plus written, integer digits, "." written, fraction digits).
pub type PlainNumber<'a> = (bool, bool, &'a [u8], bool, &'a [u8]);

/// The parts of a plain word token's number (`X-1.5`, `X.5`, `X10.`), or None for an index,
/// an expression, a value after `=`, or a point without digits.
pub fn plain(token: &[u8]) -> Option<PlainNumber<'_>> {
    if token.get(1) == Some(&b'=') {
        return None; // Sinumerik's X=10: a value after '=', not a plain number
    }
    let w = Word::new(token, 0);
    if !w.index.is_empty() || w.number.is_empty() || w.number == b"." {
        return None;
    }
    let (whole, point, fraction) = match w.number.iter().position(|&c| c == b'.') {
        Some(p) => (&w.number[..p], true, &w.number[p + 1..]),
        None => (w.number, false, &b""[..]),
    };
    Some((w.sign == b"-", w.sign == b"+", whole, point, fraction))
}

/// Whether a control that reads a number without a point as least increments, but for the
/// letters `whole` (None: a control that reads every such number as whole), reads `letter` so.
pub fn reads_increments(whole: Option<&[u8]>, letter: u8) -> bool {
    whole.is_some_and(|whole| !whole.contains(&letter))
}

/// Whether a word of `letter` written without a decimal point is a whole number on a control
/// that reads the other letters' in least increments (a Fanuc's F G P L: `numbers.whole`),
/// whatever decimal style a program or a conversion's target is said to have: G21 is code 21
/// and F100 is 100 there, never G2.1 or F0.100, so such a word is read whole and written with
/// its decimal point where it has a fraction.
pub fn reads_whole(whole: Option<&[u8]>, letter: u8) -> bool {
    whole.is_some_and(|whole| whole.contains(&letter))
}

/// The units a word of `letter` is read in: F and E in the feed's, the rest in the lengths'.
pub fn units_of(letter: u8, units: (Units, Units)) -> Units {
    if matches!(letter, b'F' | b'E') {
        units.1
    } else {
        units.0
    }
}

/// The format of `letter` in `units` in a profile's lists: the inch formats first while inch
/// is in force, then the formats of the classification.
pub fn format_in<'f>(
    formats: &'f [(u8, WordFormat)],
    formats_inch: Option<&'f [(u8, WordFormat)]>,
    letter: u8,
    units: Units,
) -> Option<&'f WordFormat> {
    let lookup =
        |list: &'f [(u8, WordFormat)]| list.iter().find(|(l, _)| *l == letter).map(|(_, f)| f);
    match (formats_inch, units) {
        (Some(inch), Units::Inch) => lookup(inch).or_else(|| lookup(formats)),
        _ => lookup(formats),
    }
}

/// How a control reads a number of one letter written without a decimal point: as a whole
/// number (`whole`: a profile with explicit decimal signs, or one of the letters a Fanuc
/// reads whole, F G P L) and whether in least input increments (`increments`, [`reads_increments`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NoPoint {
    pub whole: bool,
    pub increments: bool,
}

/// The value of a plain word's number through `fmt`, as the control whose reading of the
/// word's letter without a point is `no_point` reads it ([`Numbers::read`], where the profile's
/// lists give it; the checker's table of letters, which looked it up once). Err: the number has
/// more digits than the format holds. The one reading of a word's value: a number with a
/// point is read as written, and whether its letter counts increments is asked only of one
/// without; where it has no more than 18 digits, their value is the word's, read as it was
/// split (`Word::value`): only the scale is the format's; else `WordFormat::read` reads the
/// digits and says why where they are too many.
#[inline]
pub fn read_word(
    fmt: &WordFormat,
    w: &Word<'_>,
    no_point: impl FnOnce() -> NoPoint,
) -> Result<Dec, String> {
    let negative = w.sign == b"-";
    let signed = |value: Dec| if negative { -value } else { value };
    if w.point {
        let scale = (w.number.len() - w.dot - 1) as u32;
        if let Some(m) = w.value {
            return Ok(signed(Dec::from_u64(m, scale)));
        }
        let (whole, fraction) = w.whole_and_fraction();
        if let Some(value) = Dec::from_runs(whole, fraction, scale) {
            return Ok(signed(value));
        }
    }
    let no_point = no_point();
    let explicit = no_point.whole;
    let increments = !w.point && no_point.increments;
    if let (false, Some(m)) = (w.point, w.value) {
        let scale = fmt.scale_of_digits(w.number.len(), explicit, increments);
        if let Some(scale) = scale.filter(|&s| s as usize <= MAX_DIGITS) {
            return Ok(signed(Dec::from_u64(m, scale)));
        }
    }
    fmt.read(negative, w.number, explicit, increments)
}

/// How a profile's numbers are read: its word formats (and those that differ in inch), its
/// explicit decimal signs (DS), and the letters a number without a point is whole for.
#[derive(Debug, Clone, Copy)]
pub struct Numbers<'a> {
    pub formats: &'a [(u8, WordFormat)],
    pub formats_inch: Option<&'a [(u8, WordFormat)]>,
    pub explicit: bool,
    /// See [`reads_increments`].
    pub increments: Option<&'a [u8]>,
}

impl<'a> Numbers<'a> {
    /// The format of `letter` in `units`, if the profile names one.
    pub fn format_in(&self, letter: u8, units: Units) -> Option<&'a WordFormat> {
        format_in(self.formats, self.formats_inch, letter, units)
    }

    /// The format of `letter` in `units`: the profile's, else the fallback of its letter.
    pub fn format_or_fallback(&self, letter: u8, units: Units) -> WordFormat {
        self.format_in(letter, units)
            .cloned()
            .unwrap_or_else(|| WordFormat::fallback(letter))
    }

    /// Whether a word of `letter` written without a decimal point counts least increments.
    pub fn reads_increments(&self, letter: u8) -> bool {
        reads_increments(self.increments, letter)
    }

    /// How this control reads a number of `letter` written without a decimal point
    /// ([`NoPoint`]): asked of the profile's lists, so a reader that reads many words keeps
    /// each letter's (the checker's table of A-Z).
    pub fn no_point(&self, letter: u8) -> NoPoint {
        NoPoint {
            whole: self.explicit || reads_whole(self.increments, letter),
            increments: self.reads_increments(letter),
        }
    }

    /// The value of a plain word's number through `fmt`, as this control reads it; Err: the
    /// number has more digits than the format holds.
    pub fn read(&self, fmt: &WordFormat, w: &Word<'_>) -> Result<Dec, String> {
        read_word(fmt, w, || self.no_point(w.letter))
    }
    /// The values of a block's word tokens as the modal state reads them on its own (restart,
    /// plot, the diff's motion): plain numbers without an index, through the profile's formats
    /// in the units of lengths and of the feed in force (`units`); a word that cannot be read
    /// is left out, as the checker reports it. `counts`: the letters (bit `letter - b'A'`)
    /// the block's cycle makes a count, by the one rule the checker asks too
    /// (`convert::block_counts`, which this leaf module cannot name): a K among them is kept
    /// whole as well ([`BlockValues::k_whole`]), and a K not among them, with a point or
    /// without, counts nothing ([`BlockValues::k_no_count`]).
    pub fn block_values(
        &self,
        tokens: &[&[u8]],
        units: (Units, Units),
        counts: u32,
        out: &mut BlockValues,
    ) {
        out.clear();
        out.k_whole = None;
        out.k_no_count = false;
        for token in tokens {
            let w = Word::new(token, 0);
            if w.number.is_empty() || !w.index.is_empty() {
                continue;
            }
            let fmt = self.format_or_fallback(w.letter, units_of(w.letter, units));
            let Ok(value) = self.read(&fmt, &w) else {
                continue;
            };
            match w.letter {
                b'G' if !value.is_whole() => {
                    out.other_work_system |= matches!(value.trunc(), 54 | 59);
                    out.mirror |= crate::modal::mirror_code(value);
                    out.decimal_g = true;
                }
                b'G' => out.push_g(value.trunc()),
                b'M' => out.ms.push(value.trunc()),
                // (a count K3 is 3, where K's increments read 0.003: BlockValues::k_whole)
                b'K' if counts & 1 << (b'K' - b'A') != 0
                    && !w.point
                    && out.get(b'K').is_none()
                    && self.reads_increments(b'K') =>
                {
                    let negative = w.sign == b"-";
                    out.k_whole = w.value.map(|m| {
                        let n = Dec::from_u64(m, 0);
                        if negative {
                            -n
                        } else {
                            n
                        }
                    });
                    out.set_default(b'K', value);
                }
                b'K' => {
                    if out.get(b'K').is_none() {
                        out.k_no_count = counts & 1 << (b'K' - b'A') == 0;
                    }
                    out.set_default(b'K', value);
                }
                letter => out.set_default(letter, value),
            }
        }
    }
}

/// A profile as a modal walk beside another reader needs it (the diff's motion,
/// [`crate::ncread::Reader::with_motion`]): its modal settings and how its numbers are read.
pub trait ReadsBlocks {
    fn modal_settings(&self) -> &ModalSettings;
    fn numbers(&self) -> Numbers<'_>;
}

/// A compiled machine's settings are shared (`machine::Machine`): what it reads by, through
/// the `Arc` it is shared in.
impl<T: ReadsBlocks> ReadsBlocks for std::sync::Arc<T> {
    fn modal_settings(&self) -> &ModalSettings {
        (**self).modal_settings()
    }

    fn numbers(&self) -> Numbers<'_> {
        (**self).numbers()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_word_of_the_tokenizers_parts_is_the_word_read_again() {
        use crate::lex::{Dialect, Family};
        let lines = [
            "N10 G01 X-12.345 Y.5 Z10. F200 S1200 M03",
            "n20 g1 x 1.5 y - 2 z+.25 f 100.",
            "X1Y2Z3I-4J+5K.6",
            "G65 P9001 A1. B-2 #101=5. #102 = #101+1",
            "R1=5 R2=R1*2 X=10 Y=R1+1 TURN=0 G1 X.5",
            "G01 X[#1+2] Y#3 F#<feed> o100 sub",
            ":1234 G0 X0",
        ];
        let families = Family::ALL;
        let mut plain = 0;
        for family in families {
            let dialect = Dialect::permissive(family);
            for line in lines {
                let mut tokens = Vec::new();
                let _ = crate::tokenizer::tokenize(line.as_bytes(), &dialect, &mut tokens);
                for t in &tokens {
                    plain += usize::from(t.plain.is_some());
                    let (of, new) = (Word::of(t, 7), Word::new(&t.text, 7));
                    type Parts<'w> = (u8, u8, [&'w [u8]; 7], usize, bool, usize);
                    fn parts<'w>(w: &Word<'w>) -> Parts<'w> {
                        let (whole, fraction) = w.whole_and_fraction();
                        let texts = [
                            w.index,
                            w.sign,
                            w.number,
                            w.expression,
                            w.token,
                            whole,
                            fraction,
                        ];
                        (w.address, w.letter, texts, w.column, w.point, w.dot)
                    }
                    assert_eq!(parts(&of), parts(&new), "{family:?} {line}");
                    assert_eq!(of.value, new.value, "{family:?} {line}");
                }
                // the block's list, built in place after a word already there, is the same
                let mut words = vec![Word::new(b"G1", 1)];
                Word::extend_of(&mut words, &tokens, |offset| offset + 1);
                assert_eq!(words.len(), tokens.len() + 1);
                for (w, t) in words[1..].iter().zip(&tokens) {
                    let of = Word::of(t, t.offset + 1);
                    let (a, b) = (
                        (w.address, w.letter, w.index, w.sign),
                        (of.address, of.letter, of.index, of.sign),
                    );
                    assert_eq!(a, b, "{family:?} {line}");
                    let (a, b) = (
                        (w.number, w.expression, w.token, w.column),
                        (of.number, of.expression, of.token, of.column),
                    );
                    assert_eq!(a, b, "{family:?} {line}");
                    let (a, b) = ((w.point, w.dot, w.value), (of.point, of.dot, of.value));
                    assert_eq!(a, b, "{family:?} {line}");
                }
            }
        }
        assert!(plain > 100, "{plain}");
    }
    use crate::wordformat::Zeros;

    fn fmt(before: u32, after: u32) -> WordFormat {
        WordFormat {
            address: b'X',
            signed: true,
            decimal: true,
            before,
            after,
            zeros: Zeros::Leading,
        }
    }

    #[test]
    fn a_token_splits_into_address_index_sign_and_number() {
        let w = Word::new(b"x-12.5", 4);
        assert_eq!((w.address, w.letter, w.column), (b'x', b'X', 4));
        assert_eq!((w.sign, w.number, w.point), (&b"-"[..], &b"12.5"[..], true));
        let w = Word::new(b"R29=R9+R15", 1);
        assert_eq!(
            (w.index, w.number, w.expression),
            (&b"29"[..], &b""[..], &b"R9+R15"[..])
        );
        let w = Word::new(b"X=10", 1);
        assert_eq!((w.index, w.number), (&b""[..], &b"10"[..]));
        assert!(Word::new(b"X10", 1).number == b"10" && !Word::new(b"X10", 1).point);
        // a negative zero keeps its sign as written in the word's parts; its value is zero at
        // the scale written (a `Dec` has no negative zero)
        for (token, number, scale) in [(&b"X-0."[..], &b"0."[..], 0), (b"X-0.000", b"0.000", 3)] {
            let w = Word::new(token, 1);
            assert_eq!(
                (w.sign, w.number, w.point, w.value),
                (&b"-"[..], number, true, Some(0))
            );
            let v = read_word(&fmt(4, 3), &w, || NoPoint {
                whole: false,
                increments: false,
            })
            .unwrap();
            assert_eq!(({ v.mantissa }, v.scale), (0, scale));
        }
    }

    #[test]
    fn plain_numbers_and_what_is_not_one() {
        assert_eq!(
            plain(b"X-1.5"),
            Some((true, false, &b"1"[..], true, &b"5"[..]))
        );
        assert_eq!(
            plain(b"X+.5"),
            Some((false, true, &b""[..], true, &b"5"[..]))
        );
        assert_eq!(
            plain(b"X10."),
            Some((false, false, &b"10"[..], true, &b""[..]))
        );
        assert_eq!(
            plain(b"G01"),
            Some((false, false, &b"01"[..], false, &b""[..]))
        );
        for token in [
            &b"X1=5"[..],
            b"X.",
            b"X",
            b"X-",
            b"X=10",
            b"X[1+2]",
            b"X1.2.3",
        ] {
            assert_eq!(plain(token), None, "{}", String::from_utf8_lossy(token));
        }
    }

    #[test]
    fn least_increments_but_for_the_whole_letters() {
        let whole: &[u8] = b"NGMT";
        assert!(reads_increments(Some(whole), b'X'));
        assert!(!reads_increments(Some(whole), b'G'));
        assert!(!reads_increments(None, b'X'));
        let formats = vec![(b'X', fmt(4, 3))];
        let numbers = Numbers {
            formats: &formats,
            formats_inch: None,
            explicit: true,
            increments: Some(whole),
        };
        let read = |token: &[u8]| {
            let w = Word::new(token, 1);
            numbers.read(&numbers.format_or_fallback(w.letter, Units::Metric), &w)
        };
        assert_eq!(read(b"X1000").unwrap().to_string(), "1.000");
        assert_eq!(read(b"X1.").unwrap().to_string(), "1");
        let too_long = format!("X{}", "9".repeat(40));
        assert!(read(too_long.as_bytes()).is_err());
    }

    /// `WordFormat::read` as it was before a word's value was read while it was split: the
    /// reference the values read once are held to.
    fn read_before(
        fmt: &WordFormat,
        negative: bool,
        number: &[u8],
        explicit_program: bool,
        increments: bool,
    ) -> Option<Dec> {
        let value = if let Some(dot) = number.iter().position(|&b| b == b'.') {
            let (whole, fraction) = (&number[..dot], &number[dot + 1..]);
            Dec::from_runs(whole, fraction, fraction.len() as u32)?
        } else if increments && fmt.decimal {
            Dec::from_digits(number, fmt.after)?
        } else if explicit_program || !fmt.decimal {
            if !fmt.decimal && fmt.zeros == Zeros::Trailing && number.len() < fmt.before as usize {
                let mut padded = number.to_vec();
                padded.resize(fmt.before as usize, b'0');
                Dec::from_digits(&padded, 0)?
            } else {
                Dec::from_digits(number, 0)?
            }
        } else if fmt.zeros == Zeros::Trailing {
            let width = fmt.width() as usize;
            if number.len() > width {
                return None;
            }
            let mut padded = number.to_vec();
            padded.resize(width, b'0');
            Dec::from_digits(&padded, fmt.after)?
        } else {
            Dec::from_digits(number, fmt.after)?
        };
        Some(if negative { -value } else { value })
    }

    #[test]
    fn a_value_read_while_its_word_is_split_is_the_value_read_again() {
        // the tokenizer's digits (Word::of) and the split's (Word::new) against the reading
        // of the text as it was, on every family's tokenizer (LinuxCNC's numbers read through
        // blanks), every kind of format, and numbers of 1 to 40 digits of pseudo-random
        // digits, zeros and points
        use crate::lex::Dialect;
        let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = |n: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % n
        };
        let mut formats = Vec::new();
        for zeros in [Zeros::Leading, Zeros::Trailing, Zeros::None] {
            for (decimal, before, after) in
                [(true, 4, 3), (true, 5, 4), (false, 4, 0), (true, 2, 40)]
            {
                formats.push(WordFormat {
                    address: b'X',
                    signed: true,
                    decimal,
                    before,
                    after,
                    zeros,
                });
            }
        }
        let families = [
            Family::Iso,
            Family::MacroB,
            Family::LinuxCnc,
            Family::Sinumerik,
        ];
        let mut compared = 0;
        for _ in 0..3000 {
            let len = 1 + next(40) as usize;
            let mut number: Vec<u8> = (0..len)
                .map(|_| {
                    if next(3) == 0 {
                        b'0'
                    } else {
                        b'0' + next(10) as u8
                    }
                })
                .collect();
            if next(2) == 0 {
                number.insert(next(len as u64 + 1) as usize, b'.');
            }
            let sign: &[u8] = [&b""[..], b"-", b"+"][next(3) as usize];
            let letter = [b'X', b'F', b'G'][next(3) as usize];
            let token = [&[letter][..], sign, &number].concat();
            let line = [&token[..], b" Y1"].concat();
            let fmt = &formats[next(formats.len() as u64) as usize];
            let list = vec![(letter, fmt.clone())];
            let numbers = Numbers {
                formats: &list,
                formats_inch: None,
                explicit: next(2) == 0,
                increments: [None, Some(&b"G"[..])][next(2) as usize],
            };
            let family = families[next(families.len() as u64) as usize];
            let mut tokens = Vec::new();
            let dialect = Dialect::permissive(family);
            if crate::tokenizer::tokenize(&line, &dialect, &mut tokens).is_err() {
                continue;
            }
            let t = &tokens[0];
            let (of, new) = (Word::of(t, 1), Word::new(&token, 1));
            assert_eq!(
                (of.value, of.dot),
                (new.value, new.dot),
                "{family:?} {line:?}"
            );
            let w = &new;
            if w.number.is_empty() {
                continue;
            }
            let explicit = numbers.explicit || reads_whole(numbers.increments, w.letter);
            let increments = !w.point && numbers.reads_increments(w.letter);
            let before = read_before(fmt, w.sign == b"-", w.number, explicit, increments);
            for w in [&of, &new] {
                let now = numbers.read(fmt, w).ok();
                assert_eq!(
                    now.map(|v| (v.mantissa, v.scale)),
                    before.map(|v| (v.mantissa, v.scale)),
                    "{family:?} {}",
                    String::from_utf8_lossy(&token)
                );
                compared += 1;
            }
        }
        assert!(compared > 4000, "{compared}");
    }

    #[test]
    fn a_number_with_a_point_reads_as_its_format_reads_it() {
        // Numbers::read takes a number with a point from the word's split; WordFormat::read
        // finds the point itself: the same value, or the same error, for every form of number
        let mut numbers = Vec::new();
        for whole in [
            "",
            "0",
            "7",
            "00012",
            "123456789",
            &"9".repeat(18),
            &"1".repeat(30),
        ] {
            for fraction in ["", "0", "5", "500", "0001", "123456789", &"3".repeat(25)] {
                numbers.push(format!("{whole}.{fraction}"));
                numbers.push(format!("{whole}{fraction}"));
            }
        }
        let formats = vec![(b'X', fmt(4, 3)), (b'F', fmt(5, 0))];
        for (explicit, increments) in [(true, None), (false, None), (true, Some(&b"F"[..]))] {
            let numbers_of = Numbers {
                formats: &formats,
                formats_inch: None,
                explicit,
                increments,
            };
            let mut read = 0;
            for number in &numbers {
                for sign in ["", "-", "+"] {
                    for letter in ["X", "F", "Y"] {
                        let token = format!("{letter}{sign}{number}");
                        let Some(t) = ({
                            let mut tokens = Vec::new();
                            let dialect = crate::lex::Dialect::permissive(Family::MacroB);
                            crate::tokenizer::tokenize(token.as_bytes(), &dialect, &mut tokens)
                                .ok()
                                .and_then(|_| tokens.pop())
                        }) else {
                            continue;
                        };
                        for w in [Word::of(&t, 1), Word::new(token.as_bytes(), 1)] {
                            let fmt = numbers_of.format_or_fallback(w.letter, Units::Metric);
                            let slow = fmt.read(
                                w.sign == b"-",
                                w.number,
                                explicit || reads_whole(increments, w.letter),
                                !w.point && reads_increments(increments, w.letter),
                            );
                            let fast = numbers_of.read(&fmt, &w);
                            assert_eq!(
                                fast.as_ref().map(|v| (v.mantissa, v.scale)),
                                slow.as_ref().map(|v| (v.mantissa, v.scale)),
                                "{token}"
                            );
                            read += 1;
                        }
                    }
                }
            }
            assert!(read > 1000, "{read}");
        }
    }

    #[test]
    fn the_inch_formats_come_first_while_inch_is_in_force() {
        let formats = vec![(b'X', fmt(5, 3)), (b'F', fmt(5, 0))];
        let inch = vec![(b'X', fmt(4, 4))];
        let numbers = Numbers {
            formats: &formats,
            formats_inch: Some(&inch),
            explicit: false,
            increments: None,
        };
        assert_eq!(numbers.format_in(b'X', Units::Inch).unwrap().after, 4);
        assert_eq!(numbers.format_in(b'X', Units::Metric).unwrap().after, 3);
        assert_eq!(numbers.format_in(b'F', Units::Inch).unwrap().before, 5);
        assert!(numbers.format_in(b'Y', Units::Metric).is_none());
        assert_eq!(units_of(b'F', (Units::Metric, Units::Inch)), Units::Inch);
        assert_eq!(units_of(b'X', (Units::Metric, Units::Inch)), Units::Metric);
    }

    /// Review 54, F1, in the modal state's own reading: where K counts least increments (a
    /// FANUC's `K3` is 0.003 as a length) and the block's cycle makes K its count, its number
    /// written without a point is also kept whole, a canned cycle's repeat count; K with a
    /// point, a second K, a profile that reads K whole, or a K the cycle makes no count
    /// (review 55a, F4: a Haas G83's least peck depth) keep none. A first K the cycle makes
    /// no count, with a point or without, is marked so (`k_no_count`, review 56a, F8), one
    /// it counts is not.
    #[test]
    fn block_values_keep_a_pointless_k_whole_where_k_counts_increments() {
        let formats = vec![(b'K', fmt(5, 3))];
        let fanuc = Numbers {
            formats: &formats,
            formats_inch: None,
            explicit: true,
            increments: Some(b"PLFG"),
        };
        let k_count = 1 << (b'K' - b'A');
        let k = |numbers: &Numbers<'_>, counts: u32, tokens: &[&[u8]]| {
            let mut out = BlockValues::default();
            numbers.block_values(tokens, (Units::Metric, Units::Metric), counts, &mut out);
            let of = |d: Option<Dec>| d.map(|d| d.to_string());
            (of(out.get(b'K')), of(out.k_whole))
        };
        let no_count = |counts: u32, tokens: &[&[u8]]| {
            let mut out = BlockValues::default();
            fanuc.block_values(tokens, (Units::Metric, Units::Metric), counts, &mut out);
            out.k_no_count
        };
        assert!(!no_count(k_count, &[b"G81", b"K3."]) && !no_count(k_count, &[b"K3"]));
        assert!(no_count(0, &[b"G83", b"K3."]) && no_count(0, &[b"G83", b"K3"]));
        assert!(!no_count(0, &[b"G83", b"X1."]));
        // the first K decides, as its value does
        assert!(!no_count(k_count, &[b"K3.", b"K4"]));
        let some = |a: &str, b: &str| (Some(a.to_string()), Some(b.to_string()));
        assert_eq!(k(&fanuc, k_count, &[b"G81", b"K3"]), some("0.003", "3"));
        assert_eq!(k(&fanuc, k_count, &[b"G81", b"K03"]), some("0.003", "3"));
        assert_eq!(k(&fanuc, k_count, &[b"K-12"]), some("-0.012", "-12"));
        assert_eq!(k(&fanuc, k_count, &[b"K3."]), (Some("3".into()), None));
        assert_eq!(
            k(&fanuc, k_count, &[b"K3.", b"K4"]),
            (Some("3".into()), None)
        );
        // no count: the length K's increments read, and nothing kept whole
        let peck: &[&[u8]] = &[b"G83", b"I1.", b"K2"];
        assert_eq!(k(&fanuc, 0, peck), (Some("0.002".into()), None));
        let whole = Numbers {
            increments: None,
            ..fanuc
        };
        assert_eq!(k(&whole, k_count, &[b"K3"]), (Some("3".into()), None));
    }

    #[test]
    fn block_values_skip_what_the_modal_state_cannot_read() {
        let formats = vec![(b'X', fmt(4, 3))];
        let numbers = Numbers {
            formats: &formats,
            formats_inch: None,
            explicit: false,
            increments: None,
        };
        let tokens: Vec<&[u8]> = vec![b"G01", b"G91.1", b"X1500", b"Y=R1", b"M03", b"X2"];
        let mut out = BlockValues::default();
        numbers.block_values(&tokens, (Units::Metric, Units::Metric), 0, &mut out);
        assert_eq!(out.gs(), [1]);
        assert_eq!(out.ms, vec![3]);
        assert_eq!(out.get(b'X').unwrap().to_string(), "1.500");
        assert_eq!(out.get(b'Y'), None);
    }

    #[test]
    fn an_okuma_lathe_s_l_is_a_length_in_an_arc_and_a_thread_cycle_only() {
        let l = arc_radius(Family::Okuma, true);
        assert_eq!(l, b'L');
        for family in [Family::Okuma, Family::MacroB, Family::Iso, Family::LinuxCnc] {
            assert_eq!(arc_radius(family, false), b'R');
        }
        assert_eq!(arc_radius(Family::MacroB, true), b'R');
        let role = |motion: i64, gs: &[i64]| radius_letter_role(l, Some(motion), gs);
        // G02/G03 in the block or in force, beside the modes only
        assert_eq!(role(3, &[3]), Some(Role::Length));
        assert_eq!(role(2, &[]), Some(Role::Length));
        assert_eq!(role(2, &[42, 2, 95]), Some(Role::Length));
        // the thread cutting cycle's chamfering distance
        assert_eq!(role(33, &[33]), Some(Role::Length));
        assert_eq!(role(0, &[31]), Some(Role::Length));
        // a cycle's L, a linear move's, a thread's repeated pass: not said
        assert_eq!(role(2, &[73]), Some(Role::Parameter));
        assert_eq!(role(33, &[73]), Some(Role::Parameter));
        assert_eq!(role(1, &[]), Some(Role::Parameter));
        assert_eq!(role(33, &[]), Some(Role::Parameter));
        // R's controls: L keeps its role
        assert_eq!(radius_letter_role(b'R', Some(2), &[2]), None);
    }
}
