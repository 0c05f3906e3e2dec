//! The lexer's primitives: what every reader of a block's text shares, and nothing else.
//!
//! The control [`Family`] and the [`Dialect`] a block is read under (and the [`Syntax`] of
//! its expressions), the word [`Token`], the [`LexError`] that ends a block with its
//! [`ErrorKind`], and the blanks a word may hold. The tokenizer, the statements of the
//! dialects and the expression scanner all build on this module and import nothing of each
//! other's through it; it imports only the rule registry.

use std::borrow::Cow;

use crate::rules::Rule;

/// The control family whose statements a profile reads beyond the words of ISO 6983-1.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Family {
    /// ISO 6983-1 to the letter: words, comments, parameters of 6.4.7.
    #[default]
    Iso,
    /// Fanuc and Haas Custom Macro B: `IF [..] GOTO n`, `IF [..] THEN`, `WHILE [..] DOm`,
    /// `ENDm`, `GOTO`, `#[expr]`, `DPRNT[..]`, program names `O7997A`.
    MacroB,
    /// Siemens Sinumerik 840D: `X=R1+5`, `CR=5`, `MSG("..")`, `DEF`, `CYCLE800(..)`, labels,
    /// `@` commands; `( )` are calls, not comments.
    Sinumerik,
    /// Heidenhain TNC in ISO mode: `*` ends a block, `%NAME G71` begins and ends a program.
    Heidenhain,
    /// LinuxCNC: `o` words, `#<named>` parameters, `;` comments, lower case.
    LinuxCnc,
    /// Okuma OSP: `$NAME.MIN%` headers, `Nname` labels, `IF [..] Nname`, `GOTO Nname`,
    /// `CALL Oname`, named variables (`VC1=`, `PRES=1`), `X=expression` words.
    Okuma,
}

impl Family {
    /// The letter a drilling canned cycle's repeat count is written in: a FANUC's K (0i-MF
    /// operator's manual, "Canned cycle": K the number of repeats), a Haas's L (mill operator's
    /// manual, G81-G89: "L number of holes"; its G73/G83 K is the least peck depth, a length),
    /// LinuxCNC's L (G-code reference, G81-G89: "L- repeat"); None for a control of another
    /// family. The one place the modal state (the hole positions a count steps under G91), the
    /// checker (TG544) and the converter (a count moved between letters) ask.
    pub fn cycle_repeat_letter(self, haas: bool) -> Option<u8> {
        match self {
            Family::MacroB if haas => Some(b'L'),
            Family::MacroB => Some(b'K'),
            Family::LinuxCnc => Some(b'L'),
            _ => None,
        }
    }

    /// Every family, in declaration order: the tables built per family and the tests that
    /// walk them all take this one list, so a new family is not missed in one of them.
    pub const ALL: [Family; 6] = [
        Family::Iso,
        Family::MacroB,
        Family::Sinumerik,
        Family::Heidenhain,
        Family::LinuxCnc,
        Family::Okuma,
    ];

    pub fn from_name(name: &str) -> Option<Family> {
        Some(match name {
            "iso" => Family::Iso,
            "fanuc" | "haas" | "macro-b" => Family::MacroB,
            "sinumerik" => Family::Sinumerik,
            "heidenhain" => Family::Heidenhain,
            "linuxcnc" => Family::LinuxCnc,
            "okuma" => Family::Okuma,
            _ => return None,
        })
    }
}

/// What a profile allows beyond ISO 6983-1 Annex A, as far as reading text is concerned.
#[derive(Debug, Clone, Copy, Default)]
pub struct Dialect {
    /// Whose statements are read (see [`Family`]).
    pub family: Family,
    /// Lower-case addresses, read as their upper-case letters.
    pub lowercase: bool,
    /// `#n = value` parameters, and `#n` as an operand.
    pub hash: bool,
    /// `[ ]` in expressions, and `X[...]` values.
    pub brackets: bool,
    /// `;` starts a comment that runs to the end of the block (on a Fanuc or Haas, Custom
    /// Macro B, `;` is the end of block as the control shows it: only blanks or `( )`
    /// comments may follow it in the line, `tokenizer::words_after_semicolon`).
    pub semicolon: bool,
    /// `*` multiplies in expressions.
    pub star: bool,
    /// Parameter expressions of 6.4.7 after `index =`.
    pub expressions: bool,
    /// A Haas Next Generation Control's reading of words (Mill Operator's Manual, NGC, 2017): a
    /// blank between an address and its number is the control's alarm, not a blank to skip
    /// (6.14 "Macros", Editing: `X 0` alarms at run time; elsewhere the blank is skipped, as
    /// ISO 6983-1 4-08 has it), and the program number's O may be written `o` (5.3.1: "The
    /// letter O, or o is followed by a 5-digit number").
    pub ngc: bool,
}

impl Dialect {
    /// A dialect of `family` reading every form (lower case, `#`, brackets, `;` comments, `*`,
    /// expressions): the tests' reading of a family's statements.
    #[cfg(test)]
    pub(crate) const fn permissive(family: Family) -> Dialect {
        Dialect {
            family,
            lowercase: true,
            hash: true,
            brackets: true,
            semicolon: true,
            star: true,
            expressions: true,
            ngc: false,
        }
    }

    /// Where `text` first holds a macro character this dialect does not read: a `#`, a `[`
    /// or `]`, a `*`. One predicate for the checker's reading of a statement
    /// (`tokenizer`: TG101 at that character) and the conversion's refusal of a statement or
    /// a word for a target profile (`convert`, `conversion-dialect`): a control without them
    /// has no such macro statement and refuses the block. A quoted string's text (an OSP
    /// `VUACM[1]='... #1.'`, a SINUMERIK `MSG("...")`) is text, not the statement's
    /// characters.
    pub fn unread_character(&self, text: &[u8]) -> Option<usize> {
        self.unread(text, true)
    }

    /// [`Dialect::unread_character`] of a statement of the dialect's own family: an Okuma
    /// OSP statement's `#` is its own form of a value (`VFST=#80H`, `expr::Parser::name`),
    /// no parameter, read whatever the profile's characters. The checker's reading of a
    /// statement (TG101) and the conversion's refusal of a statement of the target's family
    /// both ask this.
    pub fn unread_in_statement(&self, text: &[u8]) -> Option<usize> {
        self.unread(text, self.family != Family::Okuma)
    }

    fn unread(&self, text: &[u8], hash_parameter: bool) -> Option<usize> {
        let hash = self.hash || !hash_parameter;
        if hash && self.brackets && self.star {
            return None;
        }
        let mut quote = None;
        text.iter().position(|&c| match (quote, c) {
            (Some(q), _) => {
                if c == q {
                    quote = None;
                }
                false
            }
            (None, b'\'' | b'"') => {
                quote = Some(c);
                false
            }
            (None, b'#') => !hash,
            (None, b'[' | b']') => !self.brackets,
            (None, b'*') => !self.star,
            _ => false,
        })
    }

    /// What an expression may hold under this dialect.
    pub(crate) fn syntax(&self) -> Syntax {
        Syntax {
            brackets: self.brackets,
            hash: self.hash,
            star: self.star,
            macros: matches!(self.family, Family::MacroB | Family::LinuxCnc),
            named: self.family == Family::LinuxCnc,
            names: self.family == Family::Okuma,
            lowercase: self.lowercase,
            parameter_elements: self.ngc,
        }
    }
}

/// Why a block cannot be read; each kind is one rule of the checker.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// A character outside Annex A that the dialect does not allow, or a control byte.
    Character,
    /// `(` without `)` before the end of block.
    CommentOpen,
    /// `)` without `(`: nested or unbalanced comments.
    Unbalanced,
    /// `/` anywhere but at the start of the block.
    Skip,
    /// `:` without the sequence number digits.
    Alignment,
    /// An address index of 0.
    Index,
    /// A word without a value, or a value that is not a number.
    Value,
    /// A malformed parameter expression.
    Expression,
    /// A block longer than `tokenizer::MAX_BLOCK`.
    TooLong,
}

impl ErrorKind {
    /// The checker's rule for a block that fails this way (docs/rules.md).
    pub fn rule(self) -> Rule {
        match self {
            ErrorKind::Character => Rule::CharacterOutsideSet,
            ErrorKind::CommentOpen => Rule::CommentNotClosed,
            ErrorKind::Unbalanced => Rule::NestedComment,
            ErrorKind::Skip => Rule::SkipNotFirst,
            ErrorKind::Alignment => Rule::AlignmentNotFirst,
            ErrorKind::Index => Rule::IndexOutOfRange,
            ErrorKind::Value | ErrorKind::Expression | ErrorKind::TooLong => Rule::Unreadable,
        }
    }
}

/// Whether a number (its digits, a point, or a sign before them) starts at `pos`.
pub(crate) fn number_ahead(line: &[u8], pos: usize) -> bool {
    let at = pos + usize::from(matches!(line.get(pos), Some(b'+' | b'-')));
    matches!(line.get(at), Some(b'0'..=b'9' | b'.'))
}

/// A Haas NGC's alarm for an address written apart from its number (`X 0`, `,R 15`): the
/// control takes a letter standing alone for an address expression, which needs its `[ ]`
/// (Mill Operator's Manual, NGC, 2017, 6.14 "Macros", Editing: `G01 G90 X 0 Y3.0` "will result
/// in an alarm at runtime"; `X [COS [90]]`, a blank before the bracket, is its correct form).
#[cold]
#[inline(never)]
pub(crate) fn apart(address: u8, blank_at: usize) -> LexError {
    let letter = address as char;
    err(
        ErrorKind::Value,
        format!(
            "address {letter} written apart from its number: a Haas takes a letter standing \
             alone for an address expression, {letter}[...], and alarms at run time (Haas Mill \
             Operator's Manual, NGC, 2017, 6.14 Macros, Editing: no blank between the address \
             and its number)"
        ),
        blank_at,
        "Haas NGC 6.14",
    )
}

/// A block that cannot be read: what, where (byte offset in the line) and under which clause.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LexError {
    pub kind: ErrorKind,
    pub message: String,
    pub offset: usize,
    pub clause: &'static str,
}

/// One word token and the byte offset of its address in the line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Token<'a> {
    pub offset: usize,
    /// The offset just after the word as written (blanks inside it included).
    pub end: usize,
    pub text: Cow<'a, [u8]>,
    /// A plain number right after the address (`X-1.5`, `G01`, `Y.5`, no index): the length
    /// of its sign (0 or 1), as the tokenizer found it, so that [`crate::word::Word::of`]
    /// takes the word's parts without reading it again. None: any other word.
    pub plain: Option<u8>,
    /// A plain word's number as the tokenizer read it, its digits walked once: see
    /// [`Digits`]. The default (no point found, no value) for any other word.
    pub digits: Digits,
}

/// Where a plain number's point stands and the value of its digits, found while the tokenizer
/// scans them, so that the word's split ([`crate::word::Word::of`]) and its value
/// ([`crate::word::Numbers::read`]) do not walk them again.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Digits {
    /// The offset of the point in the number (its length without one).
    pub dot: u32,
    /// The number's digits, before and after the point, as one whole number (`12.345` is
    /// 12345): Some where there are 1 to 18 of them, which a u64 holds whatever they are.
    pub value: Option<u64>,
}

impl Digits {
    /// The most digits [`Digits::value`] is given for.
    pub const MAX: usize = 18;

    /// `count` digits of value `value` (read with wrapping arithmetic: kept only where they
    /// are few enough to be exact), the point at `dot`.
    pub fn new(dot: usize, count: usize, value: u64) -> Digits {
        Digits {
            dot: dot as u32,
            value: (1..=Digits::MAX).contains(&count).then_some(value),
        }
    }

    /// The digits of a number written without blanks (`12.345`, `.5`, `7`): a walk of its
    /// bytes, where no scan has read them (LinuxCNC's numbers, read through blanks).
    pub fn of(number: &[u8]) -> Digits {
        let mut dot = number.len();
        let mut value: u64 = 0;
        for (i, &c) in number.iter().enumerate() {
            if c == b'.' {
                dot = i;
            } else {
                value = value
                    .wrapping_mul(10)
                    .wrapping_add(u64::from(c.wrapping_sub(b'0')));
            }
        }
        Digits::new(dot, number.len() - usize::from(dot < number.len()), value)
    }
}

pub(crate) fn err(
    kind: ErrorKind,
    message: String,
    offset: usize,
    clause: &'static str,
) -> LexError {
    LexError {
        kind,
        message,
        offset,
        clause,
    }
}

/// The blanks a word may hold (space, tab, CR, NUL, DEL), as a table: the tokenizer asks for
/// every byte.
pub(crate) const BLANKS: [bool; 256] = {
    let mut table = [false; 256];
    table[b' ' as usize] = true;
    table[b'\t' as usize] = true;
    table[b'\r' as usize] = true;
    table[0] = true;
    table[0x7f] = true;
    table
};

#[inline]
pub(crate) fn blank(b: u8) -> bool {
    BLANKS[b as usize]
}

/// Whether `part` holds a blank ([`blank`]), read 8 bytes at a time: a blank is a byte below
/// `0x21` or DEL, and a word of 8 bytes holds one of those where the borrows of two
/// subtractions say so (the bit tricks `hasless(x, 0x21)` and `haszero(x ^ DEL)`, exact for
/// whether such a byte is there); a word that does is then read byte by byte, so a byte below
/// `0x21` that is no blank (a form feed) costs a look, never a wrong answer. An expression's
/// word (`Y[#<yscale>*-56.12]`) is read for blanks at a cost of about 2 instructions a byte,
/// not 6.
fn holds_blank(part: &[u8]) -> bool {
    const ONES: u64 = u64::from_le_bytes([1; 8]);
    const HIGH: u64 = ONES * 0x80;
    let mut words = part.chunks_exact(8);
    for word in &mut words {
        let x = u64::from_le_bytes(word.try_into().expect("8 bytes"));
        let del = x ^ (ONES * 0x7f);
        let below = x.wrapping_sub(ONES * 0x21) & !x & HIGH;
        let deleted = del.wrapping_sub(ONES) & !del & HIGH;
        if below | deleted != 0 && word.iter().any(|&b| blank(b)) {
            return true;
        }
    }
    words.remainder().iter().any(|&b| blank(b))
}

/// `line[start..end]` without its blanks, borrowed when it has none.
pub(crate) fn compact(line: &[u8], start: usize, end: usize) -> Cow<'_, [u8]> {
    let part = &line[start..end];
    if holds_blank(part) {
        Cow::Owned(part.iter().copied().filter(|&b| !blank(b)).collect())
    } else {
        Cow::Borrowed(part)
    }
}

/// What the dialect allows inside an expression.
#[derive(Debug, Clone, Copy, Default)]
pub struct Syntax {
    pub brackets: bool,
    pub hash: bool,
    pub star: bool,
    /// Macro B / LinuxCNC: word operators, `**`, more functions, `#[..]`, `,` in calls.
    pub macros: bool,
    /// LinuxCNC: `#<name>` parameters.
    pub named: bool,
    /// Okuma OSP: an operand may be a variable or function by its name (`CNTR`, `VC1`,
    /// `FIX[VC2/7000]`, `VTOHT [[VC100],10001]`: its index or argument after blanks too), and
    /// `,` separates the indices or arguments inside brackets.
    pub names: bool,
    /// Lower-case letters read as upper case (function and operator names).
    pub lowercase: bool,
    /// A Haas NGC: a variable read with a decimal part (`#30003.078`, a parameter element as
    /// Renishaw's macros for the NGC write it) is read as one variable whose value is unknown
    /// (TG212); elsewhere a variable is numbered with a whole number and it is refused.
    pub parameter_elements: bool,
}

/// A FANUC lathe's G code system (parameter No. 3401, bits 6 GSB and 7 GSC, on the 0i-F and
/// 30i-B): which numbers its G codes have. The operator's manuals' G code list of the lathe
/// system gives the three columns A, B and C (FANUC 0i-TF Plus/0i-TF B-64604EN, 30i/31i/32i-B
/// lathe system B-64484EN). The core reads a lathe's threading, single and multiple repetitive
/// cycles, feed modes and coordinate setting by their system A numbers (`G90` the cutting
/// cycle, `G98` feed per minute, `G50` the setting): [`GCodeSystem::to_a`] gives the number a
/// code written in system B or C is read by, so each rule is written once, in A's numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GCodeSystem {
    /// System A, and every control that is no FANUC lathe: codes read as written.
    #[default]
    A,
    B,
    C,
}

/// The numbers the core reads B's and C's own codes by, which system A has no code for:
/// absolute and incremental programming (G90/G91 of B and C; A writes U and W) and the drilling
/// cycles' return levels (G98/G99 of B and C). Outside the G numbers any control writes.
pub const ABSOLUTE: i64 = 1090;
pub const INCREMENTAL: i64 = 1091;
pub const RETURN_INITIAL: i64 = 1098;
pub const RETURN_R_POINT: i64 = 1099;
/// The number a code is read by where it is no code of the system (a written `G32` or `G50` in
/// system B, whose functions are its G33 and G92): it sets no mode.
pub const NO_CODE: i64 = -1;

/// (code written in system B, the number it is read by): the 0i-TF's G code list, columns A
/// and B, where they differ.
const SYSTEM_B: [(i64, i64); 11] = [
    (33, 32),             // threading
    (77, 90),             // outer/inner diameter cutting cycle
    (78, 92),             // threading cycle
    (79, 94),             // end face turning cycle
    (90, ABSOLUTE),       // absolute programming (group 03)
    (91, INCREMENTAL),    // incremental programming
    (92, 50),             // coordinate system setting, maximum spindle speed clamp
    (94, 98),             // feed per minute (group 05)
    (95, 99),             // feed per revolution
    (98, RETURN_INITIAL), // drilling cycles: return to the initial level (group 11)
    (99, RETURN_R_POINT), // return to the R point level
];

/// The same for system C (columns A and C): B's, with the units codes, the single cycles and
/// the multiple repetitive cycles numbered otherwise.
const SYSTEM_C: [(i64, i64); 20] = [
    (33, 32),
    (90, ABSOLUTE),
    (91, INCREMENTAL),
    (92, 50),
    (94, 98),
    (95, 99),
    (98, RETURN_INITIAL),
    (99, RETURN_R_POINT),
    (20, 90), // outer/inner diameter cutting cycle
    (21, 92), // threading cycle
    (24, 94), // end face turning cycle
    (70, 20), // input in inch (group 06)
    (71, 21), // input in mm
    (72, 70), // finishing cycle
    (73, 71), // stock removal in turning
    (74, 72), // stock removal in facing
    (75, 73), // pattern repeating
    (76, 74), // end face peck drilling
    (77, 75), // outer/inner diameter grooving
    (78, 76), // multiple threading cycle
];

impl GCodeSystem {
    /// The system a profile's `g_code_system` names ("A", "B", "C"; anything else: A).
    pub fn from_name(name: &str) -> GCodeSystem {
        match name {
            "B" => GCodeSystem::B,
            "C" => GCodeSystem::C,
            _ => GCodeSystem::A,
        }
    }

    fn table(self) -> &'static [(i64, i64)] {
        match self {
            GCodeSystem::A => &[],
            GCodeSystem::B => &SYSTEM_B,
            GCodeSystem::C => &SYSTEM_C,
        }
    }

    /// The number the core reads whole G code `g` of this system by: system A's number of its
    /// function, one of B's and C's own ([`ABSOLUTE`] ...), [`NO_CODE`] for a number whose
    /// system A function this system numbers otherwise (B's G32), else `g` itself.
    pub fn to_a(self, g: i64) -> i64 {
        let table = self.table();
        if let Some(&(_, a)) = table.iter().find(|&&(written, _)| written == g) {
            return a;
        }
        if table.iter().any(|&(_, a)| a == g) {
            return NO_CODE;
        }
        g
    }

    /// The number this system writes the function of system A's number (or B's and C's own
    /// code) `a` by: the inverse of [`GCodeSystem::to_a`]; None where the system has no code
    /// for it (system A's absolute programming) or its number is another code here (G77 of A,
    /// which A lacks, is the cutting cycle in B).
    pub fn from_a(self, a: i64) -> Option<i64> {
        let table = self.table();
        if let Some(&(written, _)) = table.iter().find(|&&(_, read)| read == a) {
            return Some(written);
        }
        let own = matches!(a, ABSOLUTE | INCREMENTAL | RETURN_INITIAL | RETURN_R_POINT);
        (!own && a != NO_CODE && !table.iter().any(|&(written, _)| written == a)).then_some(a)
    }

    /// A decimal G code of this system (its number in tenths, `921` for G92.1) by system A's
    /// number in tenths: the 0i-TF's G code list numbers the workpiece coordinate system
    /// preset G50.3 in A and G92.1 in B and C; every other decimal code alike in the three.
    /// The converter writes it and `--verify` reads it by this one table.
    pub fn tenths_to_a(self, tenths: i64) -> i64 {
        match (self, tenths) {
            (GCodeSystem::B | GCodeSystem::C, 921) => 503,
            (GCodeSystem::B | GCodeSystem::C, 503) => NO_CODE,
            _ => tenths,
        }
    }

    /// The inverse of [`GCodeSystem::tenths_to_a`]: the number in tenths this system writes
    /// system A's decimal code `tenths` by.
    pub fn tenths_from_a(self, tenths: i64) -> i64 {
        match (self, tenths) {
            (GCodeSystem::B | GCodeSystem::C, 503) => 921,
            (GCodeSystem::B | GCodeSystem::C, 921) => NO_CODE,
            _ => tenths,
        }
    }

    /// A G word's number as written (`b"78"`) as the number [`GCodeSystem::to_a`] reads it by,
    /// written as system A writes it (`b"92"`), for the readers that take a block's words as
    /// text (`meaning::block`); B's and C's own codes and [`NO_CODE`] as a number no rule reads.
    pub fn token(self, number: &[u8]) -> &[u8] {
        if self == GCodeSystem::A {
            return number;
        }
        let Some(g) = whole_code(number) else {
            return number;
        };
        match self.to_a(g) {
            a if (0..100).contains(&a) => {
                let i = 2 * a as usize;
                &crate::decimal::DIGIT_PAIRS[i..i + 2]
            }
            a if a == g => number,
            _ => b"999999",
        }
    }
}

/// A decimal code's number as written (`b"92.1"`, `b"092.10"`) in tenths (921); None for a
/// whole number, one with a finer digit, or no number.
pub fn code_tenths(number: &[u8]) -> Option<i64> {
    let value = crate::decimal::Dec::parse(std::str::from_utf8(number).ok()?)?;
    if value.is_whole() {
        return None;
    }
    let tenths = value.checked_mul(crate::decimal::Dec::from_int(10))?;
    tenths.is_whole().then(|| tenths.trunc())
}

/// What B's and C's own codes do, for a refusal that names them.
pub fn system_function(a: i64) -> Option<&'static str> {
    match a {
        ABSOLUTE => Some("absolute programming"),
        INCREMENTAL => Some("incremental programming"),
        RETURN_INITIAL => Some("a drilling cycle's return to the initial level"),
        RETURN_R_POINT => Some("a drilling cycle's return to the R point level"),
        _ => None,
    }
}

/// A code's number written as a whole number (`b"78"`, `b"078"`, `b"78.0"`), None otherwise.
fn whole_code(number: &[u8]) -> Option<i64> {
    let (whole, fraction) = match number.iter().position(|&c| c == b'.') {
        Some(p) => (&number[..p], &number[p + 1..]),
        None => (number, &b""[..]),
    };
    let digits = |d: &[u8]| d.iter().all(u8::is_ascii_digit);
    if whole.is_empty() || whole.len() > 6 || !digits(whole) || fraction.iter().any(|&c| c != b'0')
    {
        return None;
    }
    Some(
        whole
            .iter()
            .fold(0i64, |n, &c| n * 10 + i64::from(c - b'0')),
    )
}

#[cfg(test)]
mod tests {
    use super::{code_tenths, GCodeSystem, ABSOLUTE, INCREMENTAL, NO_CODE, RETURN_R_POINT};

    /// A's G50.3 (workpiece coordinate system preset) is B's and C's G92.1, both ways; other
    /// decimal codes are alike in the three systems.
    #[test]
    fn decimal_codes_are_renumbered_between_the_systems() {
        assert_eq!(code_tenths(b"92.1"), Some(921));
        assert_eq!(code_tenths(b"092.10"), Some(921));
        assert_eq!(code_tenths(b"92"), None);
        assert_eq!(code_tenths(b"92.15"), None);
        for s in [GCodeSystem::B, GCodeSystem::C] {
            assert_eq!(s.tenths_to_a(921), 503);
            assert_eq!(s.tenths_from_a(503), 921);
            assert_eq!(s.tenths_to_a(503), NO_CODE);
            assert_eq!(s.tenths_from_a(921), NO_CODE);
            assert_eq!(s.tenths_to_a(71), 71);
        }
        assert_eq!(GCodeSystem::A.tenths_to_a(503), 503);
        assert_eq!(GCodeSystem::A.tenths_from_a(921), 921);
    }

    #[test]
    fn g_code_systems_read_by_system_a_numbers_and_back() {
        let (a, b, c) = (GCodeSystem::A, GCodeSystem::B, GCodeSystem::C);
        // B: the single cycles, absolute/incremental, setting, feeds, threading, return levels
        let pairs = [
            (77, 90),
            (78, 92),
            (79, 94),
            (92, 50),
            (94, 98),
            (95, 99),
            (33, 32),
        ];
        for (written, read) in pairs {
            assert_eq!(b.to_a(written), read, "G{written}");
            assert_eq!(b.from_a(read), Some(written), "G{read} of system A");
        }
        assert_eq!((b.to_a(90), b.to_a(91)), (ABSOLUTE, INCREMENTAL));
        assert_eq!(b.to_a(99), RETURN_R_POINT);
        // system A's numbers whose functions B numbers otherwise are no code there
        assert_eq!((b.to_a(32), b.to_a(50)), (NO_CODE, NO_CODE));
        assert_eq!((b.to_a(71), b.to_a(1)), (71, 1));
        // C: units, cycles and the multiple repetitive cycles two up
        let pairs = [
            (70, 20),
            (71, 21),
            (20, 90),
            (21, 92),
            (24, 94),
            (72, 70),
            (78, 76),
        ];
        for (written, read) in pairs {
            assert_eq!(c.to_a(written), read, "G{written}");
            assert_eq!(c.from_a(read), Some(written), "G{read} of system A");
        }
        // what a system cannot say: A's absolute programming, B's G77 for a program of A
        assert_eq!(a.from_a(ABSOLUTE), None);
        assert_eq!(a.from_a(RETURN_R_POINT), None);
        assert_eq!(b.from_a(77), None);
        assert_eq!((a.to_a(90), a.from_a(90)), (90, Some(90)));
        // the token the word readers take: written as system A writes it
        assert_eq!(b.token(b"78"), b"92");
        assert_eq!(c.token(b"073"), b"71");
        assert_eq!(b.token(b"12.1"), b"12.1");
        assert_eq!(b.token(b"90"), b"999999");
        assert_eq!(a.token(b"78"), b"78");
    }

    use super::*;

    /// `holds_blank` against the byte-by-byte reading it replaces: every byte value at every
    /// place of words of 1 to 24 bytes (within, across and after the 8-byte steps), among
    /// letters and among bytes just above and below the bounds of the bit tricks.
    #[test]
    fn a_blank_is_found_eight_bytes_at_a_time_as_one_at_a_time() {
        let exact = |part: &[u8]| part.iter().any(|&b| blank(b));
        for fill in [b'X', 0x21, 0x7e, 0x80, 0xff, 0x01, 0x0c] {
            for len in 1..=24 {
                for at in 0..len {
                    for b in 0..=255u8 {
                        let mut part = vec![fill; len];
                        part[at] = b;
                        assert_eq!(holds_blank(&part), exact(&part), "{part:?}");
                    }
                }
            }
        }
        assert!(!holds_blank(b""));
        assert!(!holds_blank(b"Y[#<yscale>*-56.12]"));
        assert!(holds_blank(b"Y[#<yscale> * -56.12]"));
        assert!(holds_blank(b"Y[#<yscale>*-56.12]\r"));
        assert_eq!(compact(b"X [1 + 2]", 0, 9), Cow::Borrowed(&b"X[1+2]"[..]));
        assert!(matches!(compact(b"X[1+2]", 0, 6), Cow::Borrowed(_)));
    }
}
