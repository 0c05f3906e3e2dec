//! Annex C word formats, decimal styles and indexes (rules TG201-TG209): each plain word's
//! number read through the profile's format in the units in force, and what it breaks of it.

use super::params;
use super::{is_dimension, BlockView, Checker, Config, Implicit, Word};
use crate::decimal::{Dec, MAX_DIGITS, POW10};
use crate::dialect::{self, PastFormat};
use crate::lex::{blank, Family};
use crate::modal::Units;
use crate::rules::Rule;
use crate::statement::Kind;
use crate::word::{read_word, units_of, NoPoint, Role};
use crate::wordformat::WordFormat;

/// The number a word's written index gives (`X4=` 4, `#1000=` 1000; past u64, u64::MAX).
pub(super) fn written_index(index: &[u8]) -> u64 {
    let digits = std::str::from_utf8(index)
        .unwrap_or("0")
        .trim_start_matches('0');
    if digits.is_empty() {
        0
    } else {
        digits.parse().unwrap_or(u64::MAX)
    }
}

/// What the profile says of each letter A-Z, looked up once for the checker: every word of
/// every block asks it of its letter (the other addresses, `:` and `#`, are asked of the
/// profile's lists). Its word format in metric and in inch, as [`Config::format_in`] finds it,
/// and how a number of it written without a point is read ([`crate::word::Numbers::no_point`]).
#[derive(Clone)]
pub(super) struct FormatTable {
    formats: [[Option<WordFormat>; 26]; 2],
    no_point: [NoPoint; 26],
    /// The keys ([`Checker::format_key`]) of words whose format rules found nothing, refused
    /// nothing and changed nothing, by a multiplicative hash of the key ([`KEPT`] places, 0
    /// for none), with the format they were read by (the key holds all it depends on): a
    /// word of a key kept here is only read ([`Checker::format_or_kept`]).
    /// With each, where the key's word has the digits' value of its scan ([`Word::value`]) and
    /// no point, the scale the format gives its digits ([`WordFormat::scale_of_digits`], a
    /// function of the key's length of the number, letter and units): a kept word's value is
    /// that value at that scale, with no reading through the format ([`NO_SCALE`]: read it).
    clean: Box<[(u64, WordFormat, u8)]>,
    /// No verdict is kept, of a word's format or of a block's addresses: every rule is asked
    /// of every word and block ([`Checker::keep_verdicts`], the tests' oracle).
    pub(super) afresh: bool,
    /// The whole G codes (`[0]`) and M codes (`[1]`) below 128 that the profile's code words
    /// ([`super::CodeWord`]) are of, a bit each: a G or M word of another whole number below
    /// 128 names nothing, and is not looked for in the list ([`Checker::named_words`]).
    pub(super) named_codes: [u128; 2],
    /// The letters the profile's classification lacks where it has one (`format_in` in mm
    /// None), a bit each ([`crate::modal::bit`]): 0 for a profile without formats.
    pub(super) unformatted: u32,
}

/// The places of [`FormatTable::clean`].
const KEPT: usize = 1024;

/// [`FormatTable::clean`]: no scale kept, the word's value is read through its format.
const NO_SCALE: u8 = u8::MAX;

impl FormatTable {
    pub(super) fn new(config: &Config) -> FormatTable {
        let of = |units| std::array::from_fn(|i| config.format_in(b'A' + i as u8, units).cloned());
        let numbers = config.numbers();
        let formats: [[Option<WordFormat>; 26]; 2] = [of(Units::Metric), of(Units::Inch)];
        let unformatted = if config.formats.is_empty() {
            0
        } else {
            (0..26)
                .filter(|&i| formats[0][i].is_none())
                .fold(0, |bits, i| bits | 1 << i)
        };
        FormatTable {
            formats,
            no_point: std::array::from_fn(|i| numbers.no_point(b'A' + i as u8)),
            clean: vec![(0, WordFormat::fallback(b'A'), NO_SCALE); KEPT].into_boxed_slice(),
            afresh: false,
            named_codes: named_codes(&config.facts.code_words),
            unformatted,
        }
    }
}

/// [`FormatTable::named_codes`] of `code_words`: a code of a point (`65.1`) is no whole
/// number, and sets no bit.
fn named_codes(code_words: &[super::CodeWord]) -> [u128; 2] {
    let mut codes = [0u128; 2];
    for c in code_words {
        let whole = std::str::from_utf8(&c.code.1)
            .ok()
            .filter(|n| n.bytes().all(|b| b.is_ascii_digit()))
            .and_then(|n| n.parse::<u32>().ok())
            .filter(|&n| n < 128);
        if let (Some(n), Some(place)) = (whole, [b'G', b'M'].iter().position(|&l| l == c.code.0)) {
            codes[place] |= 1 << n;
        }
    }
    codes
}

impl FormatTable {
    /// The verdicts kept of words' formats, taken out (an empty table left: only a checker
    /// that keeps no verdicts may read on with it, [`Checker::keep_verdicts`]).
    pub(super) fn take_clean(&mut self) -> Box<[(u64, WordFormat, u8)]> {
        std::mem::take(&mut self.clean)
    }

    /// [`FormatTable::take_clean`]'s table given back.
    pub(super) fn give_clean(&mut self, clean: Box<[(u64, WordFormat, u8)]>) {
        self.clean = clean;
    }
}

impl Checker {
    /// Whether verdicts are kept by key (the default): false asks every rule afresh of every
    /// word's format ([`Checker::format_key`]), block's addresses
    /// ([`Checker::addresses_key`]), block's codes' meanings ([`super::shapes`]) and block's
    /// codes' rules and axis reading ([`super::codes::code_key`]). The
    /// findings are the same either way; the tests compare the two on generated programs
    /// (tests/test_check_kept_verdicts.py), which a release build needs: only a debug
    /// build's assertions ask the rules of a kept word or block again.
    pub fn keep_verdicts(&mut self, keep: bool) {
        self.format_table.afresh = !keep;
        self.shapes.afresh = !keep;
    }

    /// The format of `letter` in `units`, if the profile names one ([`Config::format_in`]).
    pub(super) fn format_in(&self, letter: u8, units: Units) -> Option<&WordFormat> {
        if !letter.is_ascii_uppercase() {
            return self.config.format_in(letter, units);
        }
        let table = &self.format_table.formats[usize::from(units == Units::Inch)];
        table[usize::from(letter - b'A')].as_ref()
    }

    /// How the profile reads a number of `letter` written without a point.
    #[inline]
    fn no_point(&self, letter: u8) -> NoPoint {
        if !letter.is_ascii_uppercase() {
            return self.config.numbers().no_point(letter);
        }
        self.format_table.no_point[usize::from(letter - b'A')]
    }
}

/// The end of a TG209 message for a variable of the profile's `checks.read_only`.
const PROFILE_READ_ONLY: &str =
    "the control's documentation gives it read only (the profile's checks.read_only)";

impl Checker {
    /// TG206, TG207: an address index within the profile's range, and no index on a G word
    /// unless the profile allows it.
    pub(super) fn index(&mut self, w: &Word<'_>, line: usize) {
        if w.index.is_empty() {
            if w.letter == b'#' {
                self.named_assignment(w, line);
                self.indirect_assignment(w, line);
            }
            return;
        }
        let n = written_index(w.index);
        // located at the index, the digits after the letter
        self.numbered(w, n, &n.to_string(), line, None, w.column + 1);
    }

    /// Whether index `n` of `letter` is within the profile's range (TG206 where not), and the
    /// least allowed.
    pub(super) fn index_allowed(&self, letter: u8, n: u64) -> (bool, u64, u64) {
        let parameter = letter == b'#' || self.config.role(letter) == Some(Role::Parameter);
        let most = if parameter {
            self.config.max_parameter
        } else {
            self.config.max_index
        };
        // a SINUMERIK's R parameters count from R0 (machine data 28050), and its M function's
        // extension 0 is the master spindle (`M0=3`, Function Manual Basic Functions H2)
        let least =
            u64::from(!(matches!(letter, b'R' | b'M') && self.config.family == Family::Sinumerik));
        (n >= least && n <= most, least, most)
    }

    /// `#[5420] = 1`, `#[3000+1] = 1`, and LinuxCNC's `##1 = 1` (`# #1 = 1` read without
    /// its blanks): a variable chosen by an expression whose value the checker knows
    /// (numbers, and parameters set to a constant) is that variable, under the rules of
    /// `#5420 = 1` (TG206, TG209); a negative one is out of range (TG206). Where the value is
    /// not known, or has a fraction, nothing is said.
    fn indirect_assignment(&mut self, w: &Word<'_>, line: usize) {
        let text = w.expression;
        // the expression giving the number: a group's inside, or a parameter's value (rs274ngc
        // read_parameter_setting reads any value after the `#`, up to the `=`)
        let (inner, written) = match text.first() {
            Some(b'[') => {
                let Ok(close) = crate::statement::brackets(text, 0) else {
                    return;
                };
                (&text[1..close - 1], &text[..close])
            }
            Some(b'#') => {
                let Some(eq) = text.iter().position(|&c| c == b'=') else {
                    return;
                };
                (&text[..eq], &text[..eq])
            }
            _ => return,
        };
        let Ok(tree) = crate::expr::tree(inner) else {
            return;
        };
        // (a parameter a jump arrival forgot is read with its value in file order, and the
        // finding is TG210's doubt: a jump may arrive with another value)
        let known = |p: &[u8]| {
            self.constant(p)
                .or_else(|| self.uncertain(p).map(|(value, _, _)| value))
        };
        let Some(value) = crate::expr::formula_value(&tree, inner, &known) else {
            return;
        };
        // a parameter the index reads may hold another value where a jump arrives
        let mut read = Vec::new();
        crate::expr::parameters(&tree, &mut read);
        let doubt = read.iter().find_map(|&(a, z)| {
            self.uncertain(&inner[a..z])
                .map(|(_, n, at)| (String::from_utf8_lossy(&inner[a..z]).into_owned(), n, at))
        });
        if value < Dec::ZERO {
            // no control numbers a variable below zero: out of range whatever its fraction
            let message = format!(
                "index {} of {}: a negative variable number",
                String::from_utf8_lossy(written).trim(),
                w.letter as char
            );
            self.report(Rule::IndexOutOfRange, message, line, w.column);
            return;
        }
        if !value.is_whole() {
            return; // whether the control rounds or cuts the fraction, no source at hand says
        }
        let n = u64::try_from(value.trunc()).unwrap_or(u64::MAX);
        let shown = format!("{} (#{n})", String::from_utf8_lossy(written).trim());
        self.numbered(w, n, &shown, line, doubt, w.column);
    }

    /// TG206, TG207, TG209 of a word whose index is `n` (`shown` as the message writes it).
    /// `doubt`: the parameter of the index that a jump may change, the sequence number it may
    /// arrive at and its line; a read-only variable is then TG210, a warning.
    /// TG206 is located at `column`.
    fn numbered(
        &mut self,
        w: &Word<'_>,
        n: u64,
        shown: &str,
        line: usize,
        doubt: Option<(String, u64, usize)>,
        column: usize,
    ) {
        let letter = w.letter;
        let (allowed, least, most) = self.index_allowed(letter, n);
        if !allowed {
            // Custom Macro B's #0 exists: the null (vacant) variable, read only; reading it
            // (`#1 = #0`) is how a program empties a variable (audit 50, B3)
            let message = if letter == b'#' && n == 0 && self.config.family == Family::MacroB {
                format!(
                    "index {shown} of #: #0 is the null variable, always vacant and read only, \
                     so it cannot be assigned (the variables a program sets: {least} to {most})"
                )
            } else {
                format!(
                    "index {shown} of {}: allowed {least} to {most}",
                    letter as char
                )
            };
            self.report(Rule::IndexOutOfRange, message, line, column);
        } else if let Some(what) = (letter == b'#')
            .then(|| dialect::missing_variable(self.config.family, self.config.haas, n))
            .flatten()
        {
            let message = format!(
                "#{shown}: {what}; the control alarms (PS0115, variable number out of range)"
            );
            self.report(Rule::IndexOutOfRange, message, line, column);
        }
        if letter == b'#' {
            // the profile's list (its control's documentation), then the family's
            let listed = self.config.read_only.iter().flatten();
            let read_only = listed
                .into_iter()
                .find(|(first, last, _)| (*first..=*last).contains(&n))
                .map(|(_, _, what)| (what.as_str(), PROFILE_READ_ONLY))
                .or_else(|| {
                    dialect::read_only_variable(self.config.family, n).map(|what| {
                        (
                            what,
                            dialect::read_only_effect(self.config.family, self.config.haas),
                        )
                    })
                });
            if let Some((what, effect)) = read_only {
                // a Haas: Custom Macro B's list, which the NGC's table does not mark read only
                let undocumented = self.config.haas && effect != PROFILE_READ_ONLY;
                match doubt {
                    None if undocumented => {
                        let message = format!("#{shown} is {what}: {effect}");
                        self.report(Rule::ReadOnlyVariableUndocumented, message, line, w.column);
                    }
                    None => {
                        let message = format!("#{shown} is {what}, read only: {effect}");
                        self.report(Rule::ReadOnlyVariable, message, line, w.column);
                    }
                    Some((name, label, at)) => {
                        let message = format!(
                            "#{shown} is {what}, read only ({effect}) for the value of {name} \
                             known here; a jump to N{label} (line {at}) may arrive with \
                             another value of {name}"
                        );
                        self.report(Rule::ReadOnlyVariableUncertain, message, line, w.column);
                    }
                }
            }
        }
        if letter == b'G' && !self.config.index_g {
            let message = format!(
                "{}: the indexing of G codes is not intended (ISO 6983-1 6.2.2); \
                 checks.index_g allows it",
                w.token()
            );
            self.report(Rule::IndexedG, message, line, w.column);
        }
    }

    /// TG209 for LinuxCNC's `#<_x> = 1`: a predefined named parameter is read only.
    fn named_assignment(&mut self, w: &Word<'_>, line: usize) {
        let Some(close) = w.expression.iter().position(|&c| c == b'>') else {
            return;
        };
        if w.expression.first() != Some(&b'<') {
            return;
        }
        let name = params::named_parameter(&w.expression[1..close]);
        let bare = &name[2..]; // after "#<"
        if let Some(what) = dialect::read_only_name(self.config.family, bare) {
            let effect = dialect::read_only_effect(self.config.family, self.config.haas);
            let shown = String::from_utf8_lossy(&w.expression[..=close]);
            let message = format!("#{shown} is {what}, read only: {effect}");
            self.report(Rule::ReadOnlyVariable, message, line, w.column);
        }
    }

    /// TG209 for a SINUMERIK assignment to a read-only system variable (`$AA_IM[X]=5`).
    pub(super) fn system_variables(&mut self, b: &BlockView<'_>) {
        if self.config.family != Family::Sinumerik {
            return;
        }
        for &(column, kind, text) in b.statements {
            if kind != Kind::Assignment || text.first() != Some(&b'$') {
                continue;
            }
            let Some(eq) = text.iter().position(|&c| c == b'=') else {
                continue;
            };
            let target: Vec<u8> = text[..eq]
                .iter()
                .filter(|&&c| !blank(c))
                .map(u8::to_ascii_uppercase)
                .collect();
            if let Some(what) = dialect::read_only_name(self.config.family, &target) {
                let effect = dialect::read_only_effect(self.config.family, self.config.haas);
                let shown = String::from_utf8_lossy(&target);
                let message = format!("{shown} is {what}, read only: {effect}");
                self.report(Rule::ReadOnlyVariable, message, b.line, column);
            }
        }
    }

    /// The format a plain word is read and checked by, and whether the profile names it: the
    /// address `address` (the word's letter, or the address of what it names in this block),
    /// per revolution for an F in G95, else in the block's units, else its letter's fallback;
    /// a length the block's code makes of a word whose address's format holds none (Haas
    /// lathe `G83 ... Q0.1`, the peck, where Q05 numbers blocks), written with its point,
    /// holds the digits of a length, the Z word's format ("as a length, the format").
    fn word_format(
        &self,
        w: &Word<'_>,
        address: u8,
        naming: bool,
    ) -> (WordFormat, bool, &'static str) {
        let units = units_of(address, (self.block_units, self.block_feed_units));
        let per_revolution = (w.letter == b'F' && self.block_feed_rev)
            .then(|| self.config.feed_rev_formats[usize::from(units == Units::Inch)].as_ref())
            .flatten();
        let named = per_revolution
            .or_else(|| self.format_in(address, units))
            .or_else(|| self.format_in(w.letter, units));
        let in_formats = named.is_some();
        let fmt = named
            .cloned()
            .unwrap_or_else(|| WordFormat::fallback(w.letter));
        if w.point && !naming && self.meanings.role(w.letter) == Some(Role::Length) && !fmt.decimal
        {
            if let Some(length) = self.format_in(b'Z', units) {
                return (length.clone(), in_formats, "as a length, the format");
            }
        }
        (fmt, in_formats, "the format")
    }

    /// Whether `letter` is a selector or a count in this block: a selector (G05.1 Q1) is a
    /// whole number, whatever the control does with a length; so is a count or an angle of a
    /// cycle's table ([`crate::meaning::Meanings::cycle_count`]). Decided by the role and the
    /// table bit the block's codes give the letter, both in a word's key
    /// ([`Checker::format_key`]).
    fn selector(&self, letter: u8) -> bool {
        self.meanings.role(letter) == Some(Role::Selector) || self.meanings.cycle_count(letter)
    }

    /// How a number of `letter` written without a point is read in this block: a count or a
    /// selector ([`Checker::selector`]) is its whole number (`K3` of a canned cycle is three
    /// repeats, not 0.003, whatever the letter's reading as a length), anything else as the
    /// profile reads its letter. The one reading of [`Checker::format`] and of a kept
    /// verdict's ([`Checker::format_or_kept`]): the scale kept with a key is this reading's,
    /// so a word kept clean reads as the first word of its key was read (review 54 F1: the
    /// second `G81 ... K3` of a program was read 0.003, from the letter's reading).
    fn block_no_point(&self, letter: u8) -> NoPoint {
        match self.selector(letter) {
            true => NoPoint {
                whole: true,
                increments: false,
            },
            false => self.no_point(letter),
        }
    }

    /// The block's part of the keys of its words' verdicts ([`Checker::format_key`]): its
    /// units of lengths and of the feed, its feed mode and macro call, and the file's
    /// decimal styles so far and whether it has refused. Worked out once a block, and again
    /// after a word's rules change any of it.
    pub(super) fn format_context(&self) -> u64 {
        let flags = [
            self.block_units == Units::Inch,
            self.block_feed_units == Units::Inch,
            self.block_feed_rev,
            self.macro_arguments,
            self.styles_explicit,
            self.styles_implicit,
            self.mixed_reported,
            self.first_implicit.is_some(),
            self.refused_at.is_some(),
        ];
        let bits = flags
            .iter()
            .enumerate()
            .fold(0u64, |bits, (i, &f)| bits | u64::from(f) << i);
        1 << 63 | bits << 40
    }

    /// What every input of [`Checker::format`]'s verdict on plain word `w` is, packed in a
    /// key: the block's part (`context`, [`Checker::format_context`]), the word's letter and
    /// the role and kind the block's codes give it, and the number's sign, point and shape
    /// (what the digit rules, TG201-TG205 and TG208, compare; its value is read anew, and a
    /// word whose value cannot be read is not kept). None where the verdict reads more: a
    /// word that names a block in this block (`G71 P100`), a thread's start angle (its
    /// value's range), an index, an address other than A-Z, a number longer than 127
    /// characters; and none at all where verdicts are not kept ([`Checker::keep_verdicts`]).
    /// Whoever gives `format` another input adds it here.
    fn format_key(&self, w: &Word<'_>, context: u64) -> Option<u64> {
        let letter = w.letter;
        let n = w.number;
        if self.format_table.afresh
            || !letter.is_ascii_uppercase()
            || !w.index.is_empty()
            || n.len() > 127
            || (self.meanings.start_angle && letter == b'Q')
            || self.named.iter().any(|(named, ..)| *named == letter)
        {
            return None;
        }
        // the number's shape: with a point, the significant digits of its whole part (TG205
        // compares them with the format's) and its decimals without trailing zeros (TG203,
        // TG208); without one, its length and significant digits (its scale is the format's;
        // the width, TG203 and TG205, and the implicit-looking word, TG201, count them)
        let leading = n.iter().take_while(|&&c| c == b'0' || c == b'.').count();
        let shape = if w.point {
            let fraction = n.len() - w.dot - 1;
            let zeros = n[w.dot + 1..]
                .iter()
                .rev()
                .take_while(|&&c| c == b'0')
                .count();
            let whole = w.dot.saturating_sub(leading);
            whole | (fraction - zeros) << 7
        } else {
            n.len() | (n.len() - leading) << 7
        };
        let role: u64 = match self.meanings.role(letter) {
            None => 0,
            Some(Role::Length) => 1,
            Some(Role::Parameter) => 2,
            Some(Role::Other) => 3,
            Some(Role::Increments) => 4,
            Some(Role::Selector) => 5,
        };
        let table = self.meanings.table_others() >> (letter - b'A') & 1;
        let sign: u64 = match w.sign {
            b"-" => 2,
            b"" => 0,
            _ => 1,
        };
        Some(
            context
                | u64::from(letter - b'A')
                | role << 5
                | u64::from(table) << 8
                | sign << 9
                | u64::from(w.point) << 11
                | (shape as u64) << 12,
        )
    }

    /// What [`Checker::format`] may change: its findings, the refusal, the decimal styles.
    fn format_state(&self) -> (usize, Option<usize>, [bool; 4]) {
        let styles = [
            self.styles_explicit,
            self.styles_implicit,
            self.mixed_reported,
            self.first_implicit.is_some(),
        ];
        (self.found.len(), self.refused_at, styles)
    }

    /// [`Checker::format_key`] of a word of a block whose words' keys are their own
    /// (`plain_keys` of [`Checker::format_or_kept`]: no word names a block, no code or cycle
    /// table gives a word a role or makes Q a start angle, verdicts kept), worked out from what the scan
    /// found of its digits: the shape of its number from the value of its digits
    /// ([`Word::value`]) and its point's place, with no walk of its bytes (the walks for the
    /// leading and the trailing zeros, and the letter's role and table bit looked up, were
    /// about half of the 130 instructions a kept word cost). None where the scan gave no value
    /// (more than 18 digits) or the word has an index: [`Checker::format_key`] is asked. The
    /// same key (a debug build asks `format_key` too and asserts it).
    #[inline]
    fn plain_format_key(w: &Word<'_>, context: u64) -> Option<u64> {
        if !w.letter.is_ascii_uppercase() || !w.index.is_empty() {
            return None;
        }
        Checker::shape_format_key(w, context)
    }

    /// [`Checker::plain_format_key`] of a word whose letter is A-Z and that has no index.
    #[inline(always)]
    fn shape_format_key(w: &Word<'_>, context: u64) -> Option<u64> {
        let letter = w.letter;
        let m = w.value?;
        let n = w.number.len();
        // the significant digits: the number's digits less its leading zeros
        let significant = decimal_digits(m);
        let leading = n - usize::from(w.point) - significant;
        let shape = if w.point {
            // the leading zeros, and the point among them where every whole digit is one:
            // `format_key`'s count of leading '0' and '.' taken from the whole part
            let fraction = n - w.dot - 1;
            let zeros = if m == 0 {
                fraction
            } else {
                decimal_trailing_zeros(m).min(fraction)
            };
            w.dot.saturating_sub(leading) | (fraction - zeros) << 7
        } else {
            n | significant << 7
        };
        let sign: u64 = match (w.sign.len(), w.sign.first()) {
            (0, _) => 0,
            (1, Some(b'-')) => 2,
            _ => 1,
        };
        // (role and table bit 0: no code or cycle table of the block gives a role)
        Some(
            context
                | u64::from(letter - b'A')
                | sign << 9
                | u64::from(w.point) << 11
                | (shape as u64) << 12,
        )
    }

    /// [`Checker::format`] of a plain word: where a word of the same key
    /// ([`Checker::format_key`]) was found clean -- no finding, no refusal, nothing changed,
    /// a value read -- this one is too, and is only read; else its rules are asked and a
    /// clean verdict kept. (The rules of a CAM program's words find nothing nearly always:
    /// asking them was about 170 instructions a word.) A kept word's value is the value of
    /// its digits as scanned, at the scale of its point or the one kept with the key, as
    /// [`read_word`] reads it. `plain_keys`: the block's words' keys are their own
    /// ([`Checker::plain_format_key`]). A debug build asks the rules of a kept word as well
    /// and asserts the verdict clean and the value the same, to the scale.
    ///
    /// A plain key kept with its word's value from its scan (nearly every word of a CAM
    /// program) is read here, inline where the words are walked; anything else is
    /// [`Checker::format_or_kept_out`]'s, out of line (a debug build asks it of every word).
    #[inline(always)]
    pub(super) fn format_or_kept(
        &mut self,
        w: &Word<'_>,
        line: usize,
        context: &mut u64,
        plain_keys: bool,
    ) -> Option<Dec> {
        if plain_keys && !cfg!(debug_assertions) {
            if let Some(value) =
                Checker::plain_format_key(w, *context).and_then(|key| self.kept_read(w, key))
            {
                return Some(value);
            }
        }
        self.format_or_kept_out(w, line, context, plain_keys)
    }

    /// [`Checker::format_or_kept`] of a word of a plain block ([`Checker::plain_block`]: a
    /// letter A-Z without index or expression) whose words' keys are their own (`plain_keys`):
    /// its key with no test of its letter and index, nor of `plain_keys` at each word (about
    /// 6 instructions a word of a CAM program's kept block).
    #[inline(always)]
    pub(super) fn plain_word_or_kept(
        &mut self,
        w: &Word<'_>,
        line: usize,
        context: &mut u64,
    ) -> Option<Dec> {
        debug_assert!(w.letter.is_ascii_uppercase() && w.index.is_empty());
        if !cfg!(debug_assertions) {
            if let Some(value) =
                Checker::shape_format_key(w, *context).and_then(|key| self.kept_read(w, key))
            {
                return Some(value);
            }
        }
        self.format_or_kept_out(w, line, context, true)
    }

    /// The value of plain word `w` where a word of its `key` was kept clean and the value is
    /// read from its scan ([`Checker::format_or_kept`]), else None.
    #[inline(always)]
    fn kept_read(&self, w: &Word<'_>, key: u64) -> Option<Dec> {
        let place = (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 54) as usize % KEPT;
        let (kept, _, scale) = &self.format_table.clean[place];
        if *kept != key {
            return None;
        }
        let value = match (w.value, w.point) {
            (Some(m), true) => Dec::from_u64(m, (w.number.len() - w.dot - 1) as u32),
            (Some(m), false) if *scale != NO_SCALE => Dec::from_u64(m, u32::from(*scale)),
            _ => return None,
        };
        Some(if w.sign == b"-" { -value } else { value })
    }

    /// [`Checker::format_or_kept`] in full: the key, the kept verdict or the rules.
    #[inline(never)]
    fn format_or_kept_out(
        &mut self,
        w: &Word<'_>,
        line: usize,
        context: &mut u64,
        plain_keys: bool,
    ) -> Option<Dec> {
        let plain = if plain_keys {
            Checker::plain_format_key(w, *context)
        } else {
            None
        };
        debug_assert!(
            plain.is_none() || plain == self.format_key(w, *context),
            "{} at line {line}: the plain key differs: {:x?} {:x?}",
            w.token(),
            plain,
            self.format_key(w, *context)
        );
        let Some(key) = plain.or_else(|| self.format_key(w, *context)) else {
            let value = self.format(w, line);
            *context = self.format_context();
            return value;
        };
        let place = (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 54) as usize % KEPT;
        let (kept, fmt, scale) = &self.format_table.clean[place];
        if *kept == key {
            let read = match (w.value, w.point) {
                (Some(m), true) => Some(Dec::from_u64(m, (w.number.len() - w.dot - 1) as u32)),
                (Some(m), false) if *scale != NO_SCALE => Some(Dec::from_u64(m, u32::from(*scale))),
                _ => None,
            };
            let value = match read {
                Some(value) if w.sign == b"-" => Ok(-value),
                Some(value) => Ok(value),
                None => read_word(fmt, w, || self.block_no_point(w.letter)),
            };
            if let Ok(value) = value {
                if cfg!(debug_assertions) {
                    let before = self.format_state();
                    let checked = self.format(w, line);
                    assert!(
                        checked.is_some_and(|c| { (c.mantissa, c.scale) } == {
                            (value.mantissa, value.scale)
                        }) && self.format_state() == before,
                        "{} at line {line}: kept as clean, but {checked:?} (kept {value:?})",
                        w.token()
                    );
                }
                return Some(value);
            }
        }
        let before = self.format_state();
        let value = self.format(w, line);
        if self.format_state() != before {
            *context = self.format_context();
        } else if value.is_some() {
            // (a word of a key has no naming: its address is its letter)
            let (fmt, ..) = self.word_format(w, w.letter, false);
            let scale = if w.point || w.value.is_none() {
                NO_SCALE
            } else {
                let no_point = self.block_no_point(w.letter);
                fmt.scale_of_digits(w.number.len(), no_point.whole, no_point.increments)
                    .filter(|&s| s as usize <= MAX_DIGITS)
                    .map_or(NO_SCALE, |s| s as u8)
            };
            self.format_table.clean[place] = (key, fmt, scale);
        }
        value
    }

    /// Annex C checks of one plain word; its value, or None if it cannot be read.
    pub(super) fn format(&mut self, w: &Word<'_>, line: usize) -> Option<Dec> {
        // a word that names a block or a program in this block (G71 P100, M98 P1234) has the
        // format of the address that numbers what it names
        let naming = self
            .named
            .iter()
            .find(|(letter, ..)| *letter == w.letter)
            .map(|(_, address, code)| (*address, code.clone()));
        let address = naming.as_ref().map_or(w.letter, |(a, _)| *a);
        let (fmt, in_formats, the_format) = self.word_format(w, address, naming.is_some());
        let explicit = w.point;
        let role = self.meanings.role(w.letter);
        let profile_explicit = self.config.explicit;
        // a word the control refuses (an alarm of its format): its value is no reading of the
        // control's, so it is given to no rule (the caller makes its address unknown)
        let mut refused = false;
        if explicit && !profile_explicit {
            let message = format!(
                "{}: decimal point, but the profile has no DS (implicit decimal only)",
                w.token()
            );
            self.report(Rule::UnexpectedDecimalPoint, message, line, w.column);
            refused = true;
        }
        let whole = (explicit && profile_explicit && !self.macro_arguments)
            .then(|| dialect::whole_address(self.config.family, self.config.haas, w.letter))
            .flatten();
        let call = self.m_call_possible.as_ref().filter(|_| w.letter != b'M');
        if let (Some((what, _)), Some(m)) = (whole, call) {
            // issue 32, severity by evidence: an M code the table lacks may be a custom macro
            // call by the machine's parameters, whose arguments are real numbers; where it is
            // not one, the control alarms (nothing moves). Which it is, the parameters say, not
            // the program: a warning, and the word's value unknown (an argument, or no value)
            let message = format!(
                "{}: a decimal point in {what}, alarm PS0007 where {m} is a machine builder's M \
                 code; parameters 6080-6089 may make {m} a custom macro call (O9020-O9029; \
                 FANUC 0i-F/30i-B Operator's Manuals, \"Custom macro\"), whose arguments are \
                 real numbers ({}: the argument {}), and which this machine has its parameters \
                 say, not the program: {} is taken as unknown here",
                w.token(),
                w.token(),
                w.letter as char,
                w.letter as char
            );
            self.report(Rule::CodeNotInProfile, message, line, w.column);
            return None;
        }
        if let Some((what, note)) = whole {
            let message = format!(
                "{}: a decimal point in {what}, which the control reads as a whole number: it \
                 alarms (PS0007, illegal use of decimal point); {}[{}] is rounded{note}",
                w.token(),
                w.letter as char,
                String::from_utf8_lossy(w.number)
            );
            self.report(Rule::UnexpectedDecimalPoint, message, line, w.column);
            self.refused_at.get_or_insert(line);
            return None;
        }
        if !w.sign.is_empty() && !fmt.signed && in_formats {
            let message = format!("{}: the format {} has no sign", w.token(), fmt.spec());
            self.report(Rule::UnexpectedSign, message, line, w.column);
            refused = true;
        }
        // (a selector or a count is a whole number, no dimension: `G81 K3`, `G05.1 Q1`)
        let selector = self.selector(w.letter);
        // (a word whose role its code leaves unknown, Haas `M19 R90`, is read as the profile
        // reads its letter: TG201 says how it is read without a point, and claims no role)
        let dimension =
            (is_dimension(w.letter) || matches!(w.letter, b'I' | b'J' | b'K')) && !selector;
        if profile_explicit && fmt.decimal && dimension && !self.mixed_reported {
            let increments = self.no_point(w.letter).increments;
            let first = if explicit {
                self.styles_explicit = true;
                self.first_implicit.clone()
            } else {
                let significant = w.number.iter().skip_while(|&&d| d == b'0').count();
                // Read in increments (a Fanuc), any word without a point but 0 is the slip
                // that moves the machine 1,000 times less than meant; read as whole numbers,
                // one with more digits than the format has decimals looks implicit.
                let suspect = if increments {
                    significant > 0
                } else {
                    significant > fmt.after as usize
                };
                if suspect {
                    self.styles_implicit = true;
                    let written = String::from_utf8_lossy(w.number).into_owned();
                    let reading = match increments {
                        true => fmt
                            .read(w.sign == b"-", w.number, true, true)
                            .map_or(written, |v| v.to_string()),
                        false => written,
                    };
                    let this = Implicit {
                        token: w.token(),
                        reading,
                        line,
                        column: w.column,
                        increments,
                    };
                    if self.first_implicit.is_none() {
                        self.first_implicit = Some(this.clone());
                    }
                    Some(this)
                } else {
                    None
                }
            };
            if let (true, true, Some(first)) = (self.styles_explicit, self.styles_implicit, first) {
                let Implicit {
                    token,
                    reading,
                    line: at,
                    column,
                    increments,
                } = first;
                self.mixed_reported = true;
                let message = if increments {
                    format!(
                        "{token} has no decimal point in a program that uses decimal points: this \
                         control reads it in least input increments, as {reading} (6.1: the two \
                         must not be mixed)"
                    )
                } else {
                    format!(
                        "{token} looks like an implicit-decimal word in a program that uses \
                         decimal points; it is read as the whole number {reading} (6.1: the two \
                         must not be mixed)"
                    )
                };
                self.report(Rule::MixedDecimalStyles, message, at, column);
            }
        }
        let value = match read_word(&fmt, w, || self.block_no_point(w.letter)) {
            Ok(v) => v,
            Err(message) => {
                self.refused_at.get_or_insert(line);
                self.report(
                    Rule::TooManyDigits,
                    format!("{}: {message}", w.token()),
                    line,
                    w.column,
                );
                return None;
            }
        };
        if in_formats {
            let after = if fmt.decimal { fmt.after as usize } else { 0 };
            if explicit {
                let (_, fraction) = w.whole_and_fraction();
                let decimals =
                    fraction.len() - fraction.iter().rev().take_while(|&&c| c == b'0').count();
                let past = self.config.past_decimals;
                // a time or a factor the control reads with its point (Haas `G04 P1.5`)
                let number = self.config.pointed_numbers
                    && match role {
                        Some(role) => role == Role::Other,
                        None => self.config.role(w.letter) == Some(Role::Other),
                    };
                let decimals = if number { 0 } else { decimals };
                if decimals > after && !matches!(past, PastFormat::Alarm | PastFormat::Any) {
                    let message = format!(
                        "{}: {decimals} decimals; {the_format} {} holds {after}: {}",
                        w.token(),
                        fmt.spec(),
                        past.effect()
                    );
                    self.report(Rule::PastFormat, message, line, w.column);
                } else if decimals > after && past == PastFormat::Alarm {
                    let message = format!(
                        "{}: {decimals} decimals; {the_format} {} holds {after}",
                        w.token(),
                        fmt.spec()
                    );
                    self.report(Rule::TooManyDigits, message, line, w.column);
                    refused = true;
                }
            } else if !profile_explicit && fmt.decimal && w.number.len() > fmt.width() as usize {
                let message = format!(
                    "{}: {} digits; the format {} holds {}",
                    w.token(),
                    w.number.len(),
                    fmt.spec(),
                    fmt.width()
                );
                self.report(Rule::TooManyDigits, message, line, w.column);
                refused = true;
            }
            // a thread's start angle written with a point (`Q180.`): the manuals give it in
            // 0.001 deg without one (Haas lathe G32/G76: "Q - Thread Start Angle (do not use
            // a decimal point)"; FANUC 0i-TF "Threading (G32)": least increment 0.001 deg),
            // so whether it is 180 deg or 0.18 deg is the control's reading, not the program's
            if self.meanings.start_angle && w.letter == b'Q' && explicit {
                let message = format!(
                    "{}: a thread's start angle is written without a decimal point, in 0.001 \
                     deg (Q180000 for 180 deg); with one, whether the control reads {} deg or \
                     an alarm is not in its manual",
                    w.token(),
                    value.plain()
                );
                self.report(Rule::PastFormat, message, line, w.column);
                return Some(value);
            }
            // a thread's start angle (`Q180000`, 0.001 deg) runs to 360000 by its meaning,
            // whatever Q's format holds
            if self.meanings.start_angle && w.letter == b'Q' && !explicit {
                if value > Dec::from_int(360_000) || value < Dec::ZERO {
                    let message = format!(
                        "{}: a thread's start angle runs from 0 to 360000 (0.001 deg)",
                        w.token()
                    );
                    self.report(Rule::DigitOverflow, message, line, w.column);
                }
                return Some(value);
            }
            let over = more_whole_digits(value, fmt.before);
            let digits = || value.integer_digits();
            // "P100000: ...; in a G71 block P names a sequence number, whose format N05 ..."
            // (the message's words, written only where a message is said)
            let what = || match &naming {
                Some((a, code)) => format!(
                    "; in {} {code} block {} names a {}, whose format",
                    if code.starts_with('M') { "an" } else { "a" },
                    w.letter as char,
                    if *a == b'N' {
                        "sequence number"
                    } else {
                        "program"
                    }
                ),
                None => "; the format".into(),
            };
            if over && address == b'N' && self.config.past_sequence != PastFormat::Alarm {
                let message = format!(
                    "{}: {} digits{} {} holds {}: {}",
                    w.token(),
                    digits(),
                    what(),
                    fmt.spec(),
                    fmt.before,
                    self.config.past_sequence.effect()
                );
                self.report(Rule::PastFormat, message, line, w.column);
            } else if over {
                let mut message = format!(
                    "{}: {} digits before the decimal sign{} {} holds {}",
                    w.token(),
                    digits(),
                    what(),
                    fmt.spec(),
                    fmt.before
                );
                // a Haas program number past five digits (`O03082011`, a date): the manual
                // gives the format and no reading of a longer one (docs/dialects.md)
                // O999999 after a program's end is the control's own heading: the offsets
                // saved with the program (Setting 156), which loading the file offers to set;
                // as a program's own number it is only a number past the five digits
                let source = if self.config.diameter {
                    "the Mill Operator's Manual's setting (NGC, 2017); no lathe manual was at \
                     hand"
                } else {
                    "Mill Operator's Manual, NGC, 2017"
                };
                if w.letter == b'O' && self.config.haas && self.offsets_section {
                    message.push_str(&format!(
                        ": O999999 after the program's end heads the offsets a Haas saves with \
                         a program (Setting 156, Save Offsets with Program: before the final %, \
                         and loading the file asks whether to load them; {source}); the G10 \
                         lines that follow it, up to the next program number or %, would set \
                         offsets, and tapegate does not read what they set: check them before \
                         loading (docs/dialects.md)"
                    ));
                } else if w.letter == b'O' && self.config.haas && w.number == b"999999" {
                    message.push_str(&format!(
                        ": a Haas program number is O and five digits; O999999 is the heading \
                         the control gives the offsets it saves after a program's end \
                         (Setting 156; {source}), not a program's own number (docs/dialects.md)"
                    ));
                } else if w.letter == b'N'
                    && naming.is_none()
                    && self.config.family == Family::MacroB
                    && !self.config.haas
                    && (fmt.before == 5 || digits() > 5)
                {
                    // a CAM post numbering past N99999 (Fusion 360: 15,177 such blocks in one
                    // program): the manual's range and the alarm, so the error is sourced.
                    // Only where the number is past the manual's five digits too: a profile
                    // narrowed to N04 refuses N12345 by its own format, which the manual's
                    // range would contradict
                    message.push_str(
                        ": a FANUC sequence number is N and at most five digits, 1 to 99999 \
                         (Series 16i/18i/160i/180i-PB Operator's Manual, B-63684EN, 13 \
                         \"Program configuration\", p. 129), and a word with more digits than its \
                         address holds is alarm PS0003, too many digits",
                    );
                } else if w.letter == b'O' && self.config.haas {
                    // issue 32, severity by evidence: the number names the program and moves
                    // nothing; under either answer (an alarm at loading, or the file loaded
                    // under its name) the blocks after it are read as written, so what is not
                    // known is said, and the program is read on (docs/dialects.md)
                    message.push_str(
                        ": a Haas program number is O and five digits (Mill Operator's Manual, \
                         NGC, 2017, 4.3.3 and 5.2.2); whether the control alarms on a file \
                         whose O has more, or loads it under its file name, no Haas source at \
                         hand says; no motion depends on it, and the program is read as written \
                         (docs/dialects.md)",
                    );
                    self.report(Rule::PastFormat, message, line, w.column);
                    return Some(value);
                }
                self.report(Rule::DigitOverflow, message, line, w.column);
                refused = true;
            }
        }
        // (a code, a sequence or a program number keeps its reading: what the block's codes
        // do is read by the code rules, which report such a word on their own)
        if refused {
            self.refused_at.get_or_insert(line);
        }
        if refused && !matches!(w.letter, b'G' | b'M' | b'N' | b'O') {
            return None;
        }
        Some(value)
    }
}

/// 10^i for i = 0 to 19, the powers a u64 holds ([`decimal_digits`]).
const POW10_U64: [u64; 20] = {
    let mut table = [1u64; 20];
    let mut i = 1;
    while i < 20 {
        table[i] = table[i - 1] * 10;
        i += 1;
    }
    table
};

/// The number of decimal digits of `m` (0 for 0), as `m.checked_ilog10() + 1` counts them:
/// the binary length's estimate (log10(2) is about 1233 / 4096) corrected by one comparison
/// with a power of ten, where `ilog10` took about 20 instructions.
#[inline]
fn decimal_digits(m: u64) -> usize {
    if m == 0 {
        return 0;
    }
    let bits = 64 - m.leading_zeros() as usize;
    let estimate = (bits * 1233) >> 12;
    estimate + usize::from(m >= POW10_U64[estimate])
}

/// The zeros `m` (not zero) ends with in decimal: a number's trailing zeros, its digits'
/// value read by the scan ([`Checker::plain_format_key`]).
#[inline]
fn decimal_trailing_zeros(m: u64) -> usize {
    let (mut m, mut zeros) = (m, 0);
    while m % 10 == 0 && m != 0 {
        m /= 10;
        zeros += 1;
    }
    zeros
}

/// Whether `value` has more whole digits than `before` (`value.integer_digits() > before`):
/// |mantissa| >= 10^(before + scale), a comparison, where the count itself is wanted only
/// for a message (asked for every word of a format).
fn more_whole_digits(value: Dec, before: u32) -> bool {
    POW10
        .get((before + value.scale) as usize)
        .is_some_and(|&limit| value.mantissa.unsigned_abs() >= limit.unsigned_abs())
}

#[cfg(test)]
mod tests {
    use super::super::testing::{findings, fired, iso_mill, of_family, program};
    use super::super::{Config, ProfileFacts};
    use crate::lex::Family;
    use crate::rules::Rule;

    /// The key of a word's verdict ([`super::Checker::format_key`]) is the same for words
    /// that differ only in their digits' values, and differs where any digit rule could
    /// answer otherwise: the letter, the sign, the point, the significant digits of the whole
    /// part, the decimals without trailing zeros, a plain number's length or significant
    /// digits, the block's units.
    #[test]
    fn a_verdict_is_kept_by_the_words_shape() {
        use super::super::testing::{dialect, run};
        use super::super::Word;
        use crate::modal::Units;
        let (mut checker, _) = run(iso_mill(), &dialect(Family::Iso), &program("G01 X1. F100."));
        let context = checker.format_context();
        let key = |checker: &super::Checker, text: &str| {
            checker.format_key(&Word::new(text.as_bytes(), 1), context)
        };
        let same = [
            ("X12.345", "X98.001"),
            ("X12.345", "X12.3450"),
            ("X12.345", "X012.345"),
            ("X.5", "X0.7"),
            ("X0.05", "X.09"),
            ("X-1.", "X-9."),
            ("X1000", "X2000"),
            ("X1000", "X1001"),
            ("X5", "X7"),
        ];
        for (a, b) in same {
            assert_eq!(key(&checker, a), key(&checker, b), "{a} {b}");
        }
        let other = [
            ("X12.345", "Y12.345"),
            ("X12.345", "X-12.345"),
            ("X12.345", "X+12.345"),
            ("X12.345", "X123.45"),
            ("X12.345", "X12.34"),
            ("X12.345", "X12345"),
            ("X1.", "X1"),
            ("X1000", "X01000"),
            ("X0", "X5"),
            ("X0", "X00"),
            ("X0100", "X1000"),
            ("X0.5", "X5.5"),
        ];
        for (a, b) in other {
            assert_ne!(key(&checker, a), key(&checker, b), "{a} {b}");
        }
        // an index, an address other than A-Z: no key, the rules are asked
        assert_eq!(key(&checker, "X4=10"), None);
        assert_eq!(key(&checker, ":10"), None);
        // the block's units are in its part of the key
        checker.block_units = Units::Inch;
        assert_ne!(checker.format_context(), context);
    }

    fn at(config: Config, body: &str, rule: Rule) -> Vec<(usize, usize)> {
        fired(config, &program(body), rule)
    }

    /// The digits counted by the binary length as `ilog10` counts them, and the trailing
    /// zeros as a division counts them, about every power of ten and on drawn values.
    #[test]
    fn decimal_digits_and_trailing_zeros_are_counted_as_the_division_counts() {
        let mut values = vec![0u64, 1, 9, u64::MAX];
        for p in super::POW10_U64 {
            values.extend([p.saturating_sub(1), p, p + 1, p.saturating_mul(7)]);
        }
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            values.push(x >> (x % 64));
        }
        for m in values {
            assert_eq!(
                super::decimal_digits(m),
                m.checked_ilog10().map_or(0, |l| l as usize + 1),
                "{m}"
            );
            if m != 0 {
                let text = m.to_string();
                let zeros = text.len() - text.trim_end_matches('0').len();
                assert_eq!(super::decimal_trailing_zeros(m), zeros, "{m}");
            }
        }
    }

    #[test]
    fn more_whole_digits_is_the_count_compared() {
        use super::more_whole_digits;
        use crate::decimal::Dec;
        let values = [
            "0",
            "0.000",
            "1",
            "-1",
            "9.999",
            "10",
            "-10.000",
            "99999",
            "100000",
            "0.5",
            "123456.789",
            "-999999999.9999",
            "1000000000",
            "99999999999999999999",
            "100000000000000000000.5",
        ];
        for text in values {
            let value = Dec::parse(text).expect(text);
            for before in 0..40 {
                assert_eq!(
                    more_whole_digits(value, before),
                    value.integer_digits() > before as usize,
                    "{text} {before}"
                );
            }
        }
    }

    /// The iso-mill without DS: implicit decimals (`X1000` is 1.000).
    fn implicit() -> Config {
        Config {
            facts: ProfileFacts {
                explicit: false,
                ..iso_mill().facts
            },
            ..iso_mill()
        }
    }

    #[test]
    fn implicit_and_explicit_decimals_are_not_mixed() {
        let mixed = "G01 X1. F100.\nG01 X1000";
        assert_eq!(at(iso_mill(), mixed, Rule::MixedDecimalStyles), [(3, 5)]);
        let found = findings(iso_mill(), &program(mixed), Rule::MixedDecimalStyles);
        assert!(
            found[0].message.contains("whole number 1000"),
            "{}",
            found[0].message
        );
        // said at the first implicit-looking word, once, whichever style comes first
        let first = "G01 X1000\nG01 Y2000\nG01 X1. F100.";
        assert_eq!(at(iso_mill(), first, Rule::MixedDecimalStyles), [(2, 5)]);
        // a whole number with no more digits than the format has decimals looks whole
        assert_eq!(
            at(
                iso_mill(),
                "G01 X1. F100.\nG01 X10",
                Rule::MixedDecimalStyles
            ),
            []
        );
        // a control reading least increments (Fanuc): any such word but 0 is the slip
        let fanuc = Config {
            facts: ProfileFacts {
                increments: Some(b"NGMSTOPLHD".to_vec()),
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let found = findings(
            fanuc,
            &program("G01 X1. F100.\nG01 X10"),
            Rule::MixedDecimalStyles,
        );
        assert_eq!(found.len(), 1);
        assert!(
            found[0].message.contains("as 0.010"),
            "{}",
            found[0].message
        );
    }

    #[test]
    fn a_selector_is_no_word_read_in_increments() {
        let fanuc = Config {
            facts: ProfileFacts {
                increments: Some(b"NGMSTOPLHD".to_vec()),
                ..iso_mill().facts
            },
            ..of_family(Family::MacroB)
        };
        // G05.1 Q1 switches AI contour control on: a whole number, not 0.001 (meaning.rs)
        let selector = "G01 X1. F100.\nG05.1 Q1\nG05 P10000\nG08 P1";
        assert_eq!(at(fanuc.clone(), selector, Rule::MixedDecimalStyles), []);
        // Q of another block is still a length read in increments
        let peck = "G01 X1. F100.\nG83 Z-10. R1. Q5";
        assert_eq!(at(fanuc, peck, Rule::MixedDecimalStyles), [(3, 15)]);
    }

    #[test]
    fn a_decimal_point_needs_ds() {
        assert_eq!(
            at(implicit(), "G01 X1.5 F1000", Rule::UnexpectedDecimalPoint),
            [(2, 5)]
        );
        assert_eq!(
            at(implicit(), "G01 X1500 F1000", Rule::UnexpectedDecimalPoint),
            []
        );
        assert_eq!(
            at(iso_mill(), "G01 X1.5 F100.", Rule::UnexpectedDecimalPoint),
            []
        );
    }

    #[test]
    fn digits_and_signs_the_format_does_not_hold() {
        assert_eq!(
            at(iso_mill(), "G01 X1.2345 F100.", Rule::TooManyDigits),
            [(2, 5)]
        );
        assert_eq!(at(iso_mill(), "G01 X1.2340 F100.", Rule::TooManyDigits), []);
        assert_eq!(
            at(implicit(), "G01 X123456789 F1000", Rule::TooManyDigits),
            [(2, 5)]
        );
        assert_eq!(
            at(iso_mill(), "G01 X123456. F100.", Rule::DigitOverflow),
            [(2, 5)]
        );
        assert_eq!(at(iso_mill(), "G01 X12345. F100.", Rule::DigitOverflow), []);
        assert_eq!(
            at(iso_mill(), "G01 X1. F-100.", Rule::UnexpectedSign),
            [(2, 9)]
        );
        assert_eq!(at(iso_mill(), "G01 X-1. F100.", Rule::UnexpectedSign), []);
        // an address outside the classification has the fallback format, and no sign rule
        assert_eq!(
            at(iso_mill(), "G01 X1. F100. U-1.", Rule::UnexpectedSign),
            []
        );
    }

    /// What P means in a block is its code's: where the profile's code table says a word
    /// names a sequence number (`G71 P Q`, `M99 P`) or a program (`G65 P`), it has N's or O's
    /// format there, and N's treatment past it; elsewhere its own (P08: a dwell, M98 P).
    #[test]
    fn a_word_naming_a_block_or_a_program_has_that_address_s_format() {
        use super::super::{code_number, CodeWord};
        use crate::dialect::PastFormat;
        use crate::wordformat::WordFormat;
        let count = |address: u8, before: u32| WordFormat {
            address,
            before,
            after: 0,
            signed: false,
            zeros: crate::wordformat::Zeros::Leading,
            decimal: false,
        };
        let named = |code: (u8, &str), letter, address| CodeWord {
            code: (code.0, code.1.as_bytes().to_vec()),
            letter,
            address,
        };
        let lathe = |past_sequence| {
            let base = of_family(Family::MacroB);
            let mut formats = base.facts.formats.clone();
            formats.retain(|(l, _)| !matches!(l, b'N' | b'O' | b'P' | b'Q'));
            formats.extend([
                (b'N', count(b'N', 5)),
                (b'O', count(b'O', 8)),
                (b'P', count(b'P', 8)),
                (b'Q', count(b'Q', 5)),
            ]);
            Config {
                facts: ProfileFacts {
                    formats,
                    past_sequence,
                    code_words: vec![
                        named((b'G', "71"), b'P', b'N'),
                        named((b'G', "71"), b'Q', b'N'),
                        named((b'M', "99"), b'P', b'N'),
                        named((b'G', "65"), b'P', b'O'),
                    ],
                    ..base.facts
                },
                ..base
            }
        };
        for (written, kept) in [
            ("071", "71"),
            ("71.", "71"),
            ("54.10", "54.1"),
            ("00", "0"),
            ("0.5", "0.5"),
            ("99", "99"),
        ] {
            assert_eq!(
                code_number(written.as_bytes()),
                kept.as_bytes(),
                "{written}"
            );
        }
        let alarm = || lathe(PastFormat::Alarm);
        // a sequence number: N's five digits, as N100000 itself
        let cycle = "G71 P100000 Q100010 U0.2 W0.1 F0.2";
        assert_eq!(at(alarm(), cycle, Rule::DigitOverflow), [(2, 5), (2, 13)]);
        assert_eq!(
            at(alarm(), "G71 P100 Q200 U0.2 W0.1 F0.2", Rule::DigitOverflow),
            []
        );
        // in any order in the block
        assert_eq!(
            at(alarm(), "P100000 Q10 G71", Rule::DigitOverflow),
            [(2, 1)]
        );
        assert_eq!(at(alarm(), "M99 P123456", Rule::DigitOverflow), [(2, 5)]);
        assert_eq!(at(alarm(), "G071 P123456", Rule::DigitOverflow), [(2, 6)]);
        assert_eq!(at(alarm(), "G71. P123456", Rule::DigitOverflow), [(2, 6)]);
        // the whole codes below 128 the list is of, by letter: G71 G65 G200, M99, not G65.1
        let mut words = alarm().facts.code_words;
        words.push(named((b'G', "65.1"), b'P', b'O'));
        words.push(named((b'G', "200"), b'P', b'O'));
        assert_eq!(
            super::named_codes(&words),
            [1 << 71 | 1 << 65, 1 << 99],
            "G200 is past the bits, G65.1 no whole code"
        );
        // a program number: O's eight digits
        assert_eq!(at(alarm(), "G65 P12345678 A1.", Rule::DigitOverflow), []);
        assert_eq!(
            at(alarm(), "G65 P123456789 A1.", Rule::DigitOverflow),
            [(2, 5)]
        );
        // elsewhere P's own eight digits (a dwell in ms, M98 P count and number)
        assert_eq!(at(alarm(), "G04 P12345678", Rule::DigitOverflow), []);
        assert_eq!(at(alarm(), "M98 P12345678", Rule::DigitOverflow), []);
        assert_eq!(at(alarm(), "G04 P123456789", Rule::DigitOverflow), [(2, 5)]);
        let found = findings(alarm(), &program(cycle), Rule::DigitOverflow);
        assert!(
            found[0]
                .message
                .ends_with("in a G71 block P names a sequence number, whose format N05 holds 5"),
            "{}",
            found[0].message
        );
        // N100000 itself on a FANUC: an error naming the manual's range and the alarm
        let found = findings(alarm(), &program("N100000 G00 X1."), Rule::DigitOverflow);
        assert_eq!(found.len(), 1);
        assert!(
            found[0].message.contains("1 to 99999")
                && found[0].message.contains("B-63684EN")
                && found[0].message.ends_with("PS0003, too many digits"),
            "{}",
            found[0].message
        );
        assert!(findings(alarm(), &program("N99999 G00 X1."), Rule::DigitOverflow).is_empty());
        // where the control says nothing of a longer sequence number (a Haas), what N is
        let haas = || lathe(PastFormat::Unknown);
        assert_eq!(at(haas(), cycle, Rule::DigitOverflow), []);
        assert_eq!(at(haas(), cycle, Rule::PastFormat), [(2, 5), (2, 13)]);
        assert_eq!(
            at(haas(), "G65 P123456789 A1.", Rule::DigitOverflow),
            [(2, 5)]
        );
    }

    /// A Haas program number past its five digits is TG208, a warning (issue 32, severity by
    /// evidence: the number moves nothing), and says which of it is the manual's (the format)
    /// and which no source gives (what the control does with it); the program is read on. On
    /// a Fanuc profile whose O format is five digits it stays TG205.
    #[test]
    fn a_haas_program_number_past_five_digits_says_what_is_not_known() {
        let with_o = |haas: bool| {
            let base = of_family(Family::MacroB);
            let mut formats = base.facts.formats.clone();
            formats.push((
                b'O',
                crate::wordformat::WordFormat {
                    address: b'O',
                    before: 5,
                    after: 0,
                    signed: false,
                    zeros: crate::wordformat::Zeros::Leading,
                    decimal: false,
                },
            ));
            Config {
                facts: ProfileFacts {
                    formats,
                    ..base.facts
                },
                haas,
                ..base
            }
        };
        let body = "O03082011\nG00 X1.";
        assert_eq!(at(with_o(true), body, Rule::DigitOverflow), []);
        assert_eq!(at(with_o(true), body, Rule::PastFormat), [(2, 1)]);
        assert_eq!(at(with_o(true), "O12345\nG00 X1.", Rule::PastFormat), []);
        let haas = findings(with_o(true), &program(body), Rule::PastFormat);
        assert!(
            haas[0].message.starts_with("O03082011: 7 digits")
                && haas[0].message.contains("no Haas source at hand says")
                && haas[0].message.contains("the program is read as written"),
            "{}",
            haas[0].message
        );
        // a Fanuc's (not a Haas) says the format alone, and stays an error
        assert_eq!(at(with_o(false), body, Rule::PastFormat), []);
        let fanuc = findings(with_o(false), &program(body), Rule::DigitOverflow);
        assert!(!fanuc[0].message.contains("Haas"), "{}", fanuc[0].message);
    }

    #[test]
    fn a_fanuc_alarms_on_a_decimal_point_in_m_s_t() {
        // PS0007 (FANUC alarm list): M3.0, S1000.0, T1.0 are refused, M[3.0] is rounded, and a
        // macro call's arguments are real numbers (G65 P9732 S1. W2.)
        let macro_b = || of_family(Family::MacroB);
        for (text, column) in [
            ("M3.0", 1),
            ("M03 S1000.0", 5),
            ("T1.0 M06", 1),
            ("S1000.", 1),
        ] {
            assert_eq!(
                at(macro_b(), text, Rule::UnexpectedDecimalPoint),
                [(2, column)],
                "{text}"
            );
            assert_eq!(at(macro_b(), text, Rule::PastFormat), [], "{text}");
        }
        for text in [
            "M[3.0]",
            "M03 S1000",
            "G65 P9732 S1. W2.",
            "G65 P9725 X1. M1.",
            "X1.5",
        ] {
            assert_eq!(
                at(macro_b(), text, Rule::UnexpectedDecimalPoint),
                [],
                "{text}"
            );
        }
        let found = super::super::testing::check(macro_b(), &program("M03 S1000.5"));
        let f = found
            .iter()
            .find(|f| f.rule == Rule::UnexpectedDecimalPoint)
            .expect("a decimal point refused");
        assert!(
            f.message.contains("PS0007") && f.message.contains("3451#2"),
            "{}",
            f.message
        );
        // issue 32, severity by evidence: beside an M code the table lacks, which parameters
        // 6080-6089 may make a custom macro call (real arguments), S2. is a warning (TG307),
        // at its column, and its value unknown; an M code of the table, or the M word's own
        // point, keeps PS0007
        let text = "M165P9811Z0S2.";
        assert_eq!(at(macro_b(), text, Rule::UnexpectedDecimalPoint), []);
        assert_eq!(
            at(macro_b(), text, Rule::CodeNotInProfile),
            [(2, 12), (2, 1)]
        );
        let found = super::super::testing::check(macro_b(), &program(text));
        let s = found
            .iter()
            .find(|f| f.rule == Rule::CodeNotInProfile && f.column == 12)
            .expect("S2. said");
        assert!(
            s.message.starts_with(
                "S2.: a decimal point in a spindle speed, alarm PS0007 where \
                 M165 is a machine builder's M code; parameters 6080-6089 may make M165 a \
                 custom macro call"
            ),
            "{}",
            s.message
        );
        assert_eq!(
            at(macro_b(), "M165 T1.0", Rule::CodeNotInProfile),
            [(2, 6), (2, 1)]
        );
        for (text, column) in [("M03 S2.", 5), ("M165.0 S2.", 1), ("M165 M3.0", 6)] {
            assert!(
                at(macro_b(), text, Rule::UnexpectedDecimalPoint).contains(&(2, column)),
                "{text}"
            );
        }
        // a Haas: no source says; the ISO profiles: their own rules
        let haas = || Config {
            haas: true,
            ..macro_b()
        };
        assert_eq!(at(haas(), "M3.0", Rule::UnexpectedDecimalPoint), []);
        assert_eq!(at(iso_mill(), "M3.0", Rule::UnexpectedDecimalPoint), []);
    }

    #[test]
    fn indexes_within_the_profile_and_none_on_g() {
        let macro_b = || of_family(Family::MacroB);
        assert_eq!(at(macro_b(), "#999 = 1.", Rule::IndexOutOfRange), []);
        // #0, the null variable: read, it is no error; assigned, the error says what it is
        assert_eq!(at(macro_b(), "#1 = #0", Rule::IndexOutOfRange), []);
        assert_eq!(
            at(macro_b(), "IF [#1 EQ #0] GOTO 5", Rule::IndexOutOfRange),
            []
        );
        let found = super::super::testing::check(macro_b(), &program("#0 = 1"));
        let f = found
            .iter()
            .find(|f| f.rule == Rule::IndexOutOfRange)
            .expect("#0 = 1 refused");
        assert_eq!((f.line, f.column), (2, 2));
        assert!(
            f.message
                .starts_with("index 0 of #: #0 is the null variable, always vacant and read only"),
            "{}",
            f.message
        );
        // located at the index, as the reader locates an index it refuses
        assert_eq!(at(macro_b(), "#1000 = 1.", Rule::IndexOutOfRange), [(2, 2)]);
        assert_eq!(at(iso_mill(), "X9=1.", Rule::IndexOutOfRange), []);
        assert_eq!(at(iso_mill(), "X10=1.", Rule::IndexOutOfRange), [(2, 2)]);
        // Custom Macro B has no #34-#99 (a FANUC alarms, PS0115); chosen by a value, the same
        for (text, column) in [("#34 = 1.", 2), ("#50 = 1.", 2), ("#99 = 1.", 2)] {
            assert_eq!(
                at(macro_b(), text, Rule::IndexOutOfRange),
                [(2, column)],
                "{text}"
            );
        }
        assert_eq!(
            at(macro_b(), "#[40+10] = 1.", Rule::IndexOutOfRange),
            [(2, 1)]
        );
        for text in ["#33 = 1.", "#100 = 1.", "#500 = 1."] {
            assert_eq!(at(macro_b(), text, Rule::IndexOutOfRange), [], "{text}");
        }
        let found = super::super::testing::check(macro_b(), &program("#50 = 1."));
        assert!(found[0].message.contains("PS0115"), "{}", found[0].message);
        // a Haas's table was not read for them: not judged
        let haas = || Config {
            haas: true,
            ..macro_b()
        };
        assert_eq!(at(haas(), "#50 = 1.", Rule::IndexOutOfRange), []);
        // a SINUMERIK's extended address X0=: TG206 at the 0, and no TG141 beside it (the
        // error says the word names no axis); R0 is a parameter
        let sinumerik = || of_family(Family::Sinumerik);
        for text in ["N30 X0=5", "N30 X0=R1", "N30 S00=R1+2"] {
            let found: Vec<_> = super::super::testing::check(sinumerik(), &program(text))
                .iter()
                .map(|f| (f.rule, f.line, f.column))
                .collect();
            assert_eq!(found, [(Rule::IndexOutOfRange, 2, 6)], "{text}");
        }
        assert_eq!(at(sinumerik(), "R0=5", Rule::IndexOutOfRange), []);
        assert_eq!(at(iso_mill(), "G2=1", Rule::IndexedG), [(2, 1)]);
        // a read-only system variable of Custom Macro B is read, never set (TG209)
        let wide = || Config {
            facts: ProfileFacts {
                max_parameter: 999_999,
                ..macro_b().facts
            },
            ..macro_b()
        };
        assert_eq!(at(wide(), "#5021 = 1.", Rule::ReadOnlyVariable), [(2, 1)]);
        assert_eq!(at(wide(), "#5021 = 1.", Rule::IndexOutOfRange), []);
        assert_eq!(at(wide(), "#100 = #5021", Rule::ReadOnlyVariable), []);
        assert_eq!(at(wide(), "#3000 = 1.", Rule::ReadOnlyVariable), []);
        // a Haas: Custom Macro B's list is not the NGC's, a warning naming the gap
        let haas = || Config {
            haas: true,
            ..wide()
        };
        assert_eq!(at(haas(), "#5021 = 1.", Rule::ReadOnlyVariable), []);
        assert_eq!(
            at(haas(), "#5021 = 1.", Rule::ReadOnlyVariableUndocumented),
            [(2, 1)]
        );
        assert_eq!(
            at(wide(), "#5021 = 1.", Rule::ReadOnlyVariableUndocumented),
            []
        );
        // chosen by an expression the checker can evaluate: the same rules, at the word
        assert_eq!(
            at(wide(), "G00 X0\n#[5000+21] = 1.", Rule::ReadOnlyVariable),
            [(3, 1)]
        );
        assert_eq!(
            at(wide(), "#1 = 5021\n#[#1] = 1.", Rule::ReadOnlyVariable),
            [(3, 1)]
        );
        assert_eq!(at(wide(), "#[3000+1] = 1.", Rule::ReadOnlyVariable), []);
        assert_eq!(at(wide(), "#[#2] = 1.", Rule::ReadOnlyVariable), []);
        assert_eq!(at(wide(), "#[5021.5] = 1.", Rule::ReadOnlyVariable), []);
        assert_eq!(
            at(wide(), "#[999999+1] = 1.", Rule::IndexOutOfRange),
            [(2, 1)]
        );
        let found = findings(wide(), &program("#[5000+21] = 1."), Rule::ReadOnlyVariable);
        assert!(
            found[0]
                .message
                .starts_with("#[5000+21] (#5021) is a position"),
            "{}",
            found[0].message
        );
        let iso = Config {
            facts: ProfileFacts {
                max_parameter: 999_999,
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        assert_eq!(at(iso, "#5021 = 1.", Rule::ReadOnlyVariable), []);
        // a profile's own list (checks.read_only: a Haas NGC's) adds to the family's
        let listed = || Config {
            facts: ProfileFacts {
                max_parameter: 999_999,
                read_only: Some(vec![
                    (3020, 3020, "the power-on timer".into()),
                    (11000, 11255, "a discrete input".into()),
                ]),
                ..macro_b().facts
            },
            ..macro_b()
        };
        assert_eq!(at(listed(), "#3020 = 1.", Rule::ReadOnlyVariable), [(2, 1)]);
        assert_eq!(
            at(listed(), "#11255 = 1.", Rule::ReadOnlyVariable),
            [(2, 1)]
        );
        assert_eq!(
            at(listed(), "#1 = 11018\n#[#1] = 1.", Rule::ReadOnlyVariable),
            [(3, 1)]
        );
        assert_eq!(at(listed(), "#11256 = 1.", Rule::ReadOnlyVariable), []);
        assert_eq!(at(listed(), "#5021 = 1.", Rule::ReadOnlyVariable), [(2, 1)]);
        assert_eq!(at(listed(), "#3001 = 1.", Rule::ReadOnlyVariable), []);
        assert_eq!(at(listed(), "#10000 = #11018", Rule::ReadOnlyVariable), []);
        let found = findings(listed(), &program("#3020 = 0"), Rule::ReadOnlyVariable);
        assert_eq!(
            found[0].message,
            "#3020 is the power-on timer, read only: the control's documentation gives it read \
             only (the profile's checks.read_only)"
        );
        // LinuxCNC: the tool data #5400-#5413 and the position #5420-#5428 (rs274 2.9)
        let linuxcnc = || Config {
            facts: ProfileFacts {
                max_parameter: 5601,
                ..of_family(Family::LinuxCnc).facts
            },
            ..of_family(Family::LinuxCnc)
        };
        for (body, fires) in [
            ("#5420 = 1", true),
            ("#5413 = 1", true),
            ("#5400 = 1", true),
            ("#5428 = 1", true),
            ("#5414 = 1", false),
            ("#5399 = 1", false),
            ("#5429 = 1", false),
            ("#1 = #5420", false),
            ("#<_x> = 1", true),
            ("#<_Current_Tool> = 1", true),
            ("#<_abs_u> = 1", false),
            ("#<_foo> = 1", false),
            ("#<x> = 1", false),
            // a variable chosen by a constant expression is that variable (rs274 2.9:
            // `#[5420] = 1` is "Parameter is readonly" too)
            ("#[5420] = 1", true),
            ("#[5400 + 20] = 1", true),
            ("#<i> = 20\n#[5400+#<i>] = 1", true),
            ("#[5414] = 1", false),
            ("#[5400+#<unknown>] = 1", false),
        ] {
            let line = 2 + body.matches('\n').count();
            let expected = if fires { vec![(line, 1)] } else { vec![] };
            assert_eq!(
                at(linuxcnc(), body, Rule::ReadOnlyVariable),
                expected,
                "{body}"
            );
        }
        let found = findings(linuxcnc(), &program("#<_x> = 1"), Rule::ReadOnlyVariable);
        assert!(
            found[0]
                .message
                .starts_with("#<_x> is a predefined named parameter")
                && found[0].message.contains("rs274"),
            "{}",
            found[0].message
        );
        let allowed = Config {
            facts: ProfileFacts {
                index_g: true,
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        assert_eq!(at(allowed, "G2=1", Rule::IndexedG), []);
    }

    /// `keep_verdicts(false)`, the tests' oracle for the kept verdicts, keeps nothing -- no
    /// word's format, no block's addresses, no block's meanings -- and finds what the kept
    /// verdicts find: here words and blocks that come back in another units code, feed mode
    /// and canned cycle, where the kept run meets them again.
    /// Drawn lines -- upper and lower case, signs, leading and trailing zeros, a point
    /// anywhere or none, numbers past 18 and past 38 digits, blanks, comments with text
    /// outside ASCII, brackets, indexes, cycles and calls among plain moves -- checked with
    /// the verdicts kept and afresh on an explicit, an implicit, a Macro B (a Haas's too) and
    /// a LinuxCNC profile: the same findings. A debug build (the tests') also holds every word
    /// with a plain key ([`super::Checker::plain_format_key`]) to `format_key`'s key, and
    /// every kept word's value to the one its format's rules read, to the scale.
    #[test]
    fn drawn_words_kept_by_their_plain_keys_read_as_afresh() {
        use super::super::testing::dialect;
        use super::super::Checker;
        use crate::rules::Selection;
        use std::sync::Arc;
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut draw = move |n: u64| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x % n
        };
        let number = |draw: &mut dyn FnMut(u64) -> u64| {
            let mut t = String::new();
            match draw(6) {
                0 => t.push('-'),
                1 => t.push('+'),
                _ => {}
            }
            let digits = match draw(20) {
                0 => 19 + draw(25) as usize,
                _ => 1 + draw(8) as usize,
            };
            let point = match draw(4) {
                0 => None,
                _ => Some(draw(digits as u64 + 1) as usize),
            };
            for i in 0..digits {
                if point == Some(i) {
                    t.push('.');
                }
                let d = match draw(4) {
                    0 => 0,
                    _ => draw(10),
                };
                t.push(char::from(b'0' + d as u8));
            }
            if point == Some(digits) {
                t.push('.');
            }
            t
        };
        let letters = b"XYZIJKFSTNRPQABCUVWDHLEGMxyzfn";
        let extras = [
            "(comment \u{e9}t\u{e9})",
            "G81 R1. Z-2.",
            "G80",
            "G91",
            "G90",
            "G20",
            "G21",
            "M98 P100",
            "G65 P9010 A1. B2.",
            "G4 P500",
            "G95",
            "G94",
            "X[1+2]",
            "#1=5",
            "G71 P10 Q20 U1. W1.",
        ];
        let mut lines = String::from("%\nO1000\nG21 G90 G17\n");
        for _ in 0..3000 {
            if draw(6) == 0 {
                lines.push_str(extras[draw(extras.len() as u64) as usize]);
                lines.push(' ');
            }
            for _ in 0..1 + draw(5) {
                let letter = letters[draw(letters.len() as u64) as usize];
                lines.push(char::from(letter));
                if letter.eq_ignore_ascii_case(&b'G') {
                    lines.push_str(["1", "01", "0", "2", "3", "00", "1.", "17"][draw(8) as usize]);
                } else {
                    lines.push_str(&number(&mut draw));
                }
                lines.push_str(["", " ", "  ", "\t"][draw(4) as usize]);
            }
            lines.push('\n');
        }
        lines.push_str("M30\n%\n");
        let configs = [
            (iso_mill(), Family::Iso),
            (implicit(), Family::Iso),
            (of_family(Family::MacroB), Family::MacroB),
            (
                Config {
                    haas: true,
                    ..of_family(Family::MacroB)
                },
                Family::MacroB,
            ),
            (of_family(Family::LinuxCnc), Family::LinuxCnc),
        ];
        for (config, family) in configs {
            let config = Arc::new(config);
            let run = |keep: bool| {
                let mut checker = Checker::new(config.clone(), Selection::all(), false);
                checker.keep_verdicts(keep);
                let (d, mut tokens) = (dialect(family), Vec::new());
                for (i, line) in lines.lines().enumerate() {
                    checker.check_line(line.as_bytes(), i + 1, &d, &mut tokens);
                }
                checker.finish();
                let kept = checker
                    .format_table
                    .clean
                    .iter()
                    .filter(|c| c.0 != 0)
                    .count();
                (checker.take(), kept)
            };
            let (kept_run, kept) = run(true);
            let (afresh_run, _) = run(false);
            assert!(kept > 0, "{family:?}: nothing kept");
            assert!(!kept_run.is_empty(), "{family:?}: nothing found");
            assert_eq!(kept_run, afresh_run, "{family:?}");
        }
    }

    /// Review 54, F1: a cycle's repeat count written without a point (`K3`, `K03`) is its
    /// whole number in every block that writes it, not only in the first: a word kept clean
    /// is read with the reading its first word was read with (the count's, not its letter's
    /// least increments, 0.003), so the second of two identical `G91 G81 ... K3` blocks has
    /// no TG544 and its holes are followed (TG601 past the travel). The same on a FANUC
    /// lathe's G83 and with the verdicts kept or not; a Haas mill's L counts too, and its K
    /// under G83 stays the least peck depth, a length (no TG544 whatever its value). A debug
    /// build asserts each kept word's value equal to the one its rules read, a selector's
    /// (`G05.1 Q1`) too.
    #[test]
    fn a_count_kept_reads_as_its_first_reading() {
        use super::super::testing::{dialect, fanuc_lathe};
        use super::super::Checker;
        use crate::rules::Selection;
        use std::sync::Arc;
        let run = |config: &Config, text: &str, keep: bool| {
            let family = config.family;
            let mut checker = Checker::new(Arc::new(config.clone()), Selection::all(), false);
            checker.keep_verdicts(keep);
            let (d, mut tokens) = (dialect(family), Vec::new());
            for (i, line) in text.lines().enumerate() {
                checker.check_line(line.as_bytes(), i + 1, &d, &mut tokens);
            }
            checker.finish();
            checker.take()
        };
        let at = |config: &Config, text: &str, rule: Rule| {
            let kept = run(config, text, true);
            assert_eq!(kept, run(config, text, false), "{text}");
            kept.iter()
                .filter(|f| f.rule == rule)
                .map(|f| (f.line, f.column))
                .collect::<Vec<_>>()
        };
        // iso-mill's X -500..500: three holes 200 apart from X-300 end at X300; three 300
        // apart from X0 at X900, a span of 1200
        let mill = |cycle: &str, count: &str| {
            program(&format!(
                "G21 G17 G90 G54\nM4 S1000\nG0 X-300. Y0 Z10.\n\
                 G91 {cycle} X200. Y0 Z-5. R-8. {count} F100.\nG80 G90\nG0 X0 Y0\n\
                 G91 {cycle} X300. Y0 Z-5. R-8. {count} F100.\nG80 G90"
            ))
        };
        // (a FANUC's reading: a word without a point in least increments, P L F G whole;
        // iso-mill's K+053 holds 0.003)
        let increments = |mut config: Config| {
            config.facts.increments = Some(b"PLFG".to_vec());
            config
        };
        let fanuc = increments(of_family(Family::MacroB));
        for cycle in ["G81", "G73 Q1.", "G83 Q1."] {
            for k in ["K3", "K03", "K3."] {
                let text = mill(cycle, k);
                assert_eq!(at(&fanuc, &text, Rule::CycleRepeatCount), [], "{text}");
                assert_eq!(
                    at(&fanuc, &text, Rule::TravelExceeded),
                    [(8, 6 + cycle.len())]
                );
            }
            // a count that is none is still one, kept or not
            let text = mill(cycle, "K0");
            let col = 25 + cycle.len();
            assert_eq!(
                at(&fanuc, &text, Rule::CycleRepeatCount),
                [(5, col), (8, col)]
            );
        }
        let mut haas = increments(Config {
            haas: true,
            ..of_family(Family::MacroB)
        });
        haas.modal.haas = true;
        let text = mill("G81", "L3");
        assert_eq!(at(&haas, &text, Rule::CycleRepeatCount), []);
        assert_eq!(at(&haas, &text, Rule::TravelExceeded), [(8, 9)]);
        for k in ["K3", "K2.5"] {
            let text = mill("G83 Q1.", k);
            assert_eq!(at(&haas, &text, Rule::CycleRepeatCount), [], "{text}");
        }
        // a selector read without a point, met again: a FANUC's G05.1 Q1 (AI contour
        // control), its value 1 both times (the debug build's assertion), none refused
        let text = program("G05.1 Q1\nG01 X1. F100.\nG05.1 Q0\nG05.1 Q1\nG05.1 Q1");
        assert_eq!(at(&fanuc, &text, Rule::MixedDecimalStyles), []);
        let lathe = |count: &str| {
            program(&format!(
                "G21 G18 G97\nM3 S500\nG0 X0 Z5.\nG83 Z-10. R-3. Q2000 {count} F0.1\nG80\n\
                 G0 X0 Z5.\nG83 Z-10. R-3. Q2000 {count} F0.1\nG80"
            ))
        };
        let fanuc_lathe = increments(fanuc_lathe());
        for k in ["K3", "K03"] {
            assert_eq!(
                at(&fanuc_lathe, &lathe(k), Rule::CycleRepeatCount),
                [],
                "{k}"
            );
        }
        assert_eq!(
            at(&fanuc_lathe, &lathe("K0"), Rule::CycleRepeatCount),
            [(5, 22), (8, 22)]
        );
    }

    #[test]
    fn verdicts_not_kept_find_the_same() {
        use super::super::testing::dialect;
        use super::super::Checker;
        use crate::rules::Selection;
        use std::sync::Arc;
        let text = "%\nO1000\nG21 G90 G17\nG1 X1.2345 Y2. F100.\nG20\nG1 X1.2345 Y2. F100.\n\
                    G21\nG1 X1.2345 Y2. F100.\nG95 G1 X1.2345 Y2. F0.12345\n\
                    G94 G1 X1.2345 Y2. F0.12345\nG81 X1. Y2. Z-1. R1. F100.\nX1. Y2.\nG80\n\
                    X1. Y2.\nx1. Y2.\nM30\n%\n";
        let run = |keep: bool| {
            let config = of_family(Family::MacroB);
            let mut checker = Checker::new(Arc::new(config), Selection::all(), false);
            checker.keep_verdicts(keep);
            let (d, mut tokens) = (dialect(Family::MacroB), Vec::new());
            for (i, line) in text.lines().enumerate() {
                checker.check_line(line.as_bytes(), i + 1, &d, &mut tokens);
            }
            checker.finish();
            let found = checker.take();
            let kept = checker
                .format_table
                .clean
                .iter()
                .filter(|c| c.0 != 0)
                .count()
                + checker.clean_blocks.kept()
                + checker.shapes.hits.get();
            (found, kept)
        };
        let (kept_run, kept) = run(true);
        let (afresh_run, none) = run(false);
        assert!(kept > 0, "the kept run kept nothing");
        assert_eq!(none, 0, "a run without kept verdicts kept some");
        assert!(kept_run.iter().any(|f| f.rule == Rule::TooManyDigits));
        assert_eq!(kept_run, afresh_run);
    }
}
