//! Which parameters of a program hold lengths: the proof a units conversion needs (ISO 6983-1
//! 6.4.7).
//!
//! A units conversion must scale `R11 = 22.2` when R11 is later used as a length
//! (`X2 = 105 + R9`) and must not touch it when R11 is a count or an angle. The program
//! does not say so, so tapegate proves it from how each parameter is used, in one streaming pass
//! over the program's text before converting ([`Analysis::lines`]; the expressions are read by
//! [`expr::terms`], the linear terms of [`expr::tree`] read without the tree, the reading the
//! converter uses to convert their number terms):
//!
//! - a length word (X Y Z U V W, I J K, a P/Q/R the profile calls a length, and a feed F or E,
//!   a length per minute or per revolution) whose value is an expression **linear** in its
//!   parameters (sums and differences of numbers, parameters, and
//!   parameters multiplied or divided by numbers) makes each parameter it reads a *length*; its
//!   number terms are lengths too and are converted;
//! - any other word that reads a parameter makes it *not a length*;
//! - an assignment `R29 = R9 + R15` passes the class of R29 on to R9 and R15 (again only through
//!   a linear expression);
//! - a parameter used both ways, a length read through a non-linear expression (`SIN[R1]`,
//!   `R1 * R2`), or an assignment to a parameter that is never read, cannot be proved: the
//!   conversion stops with an error naming the block, unless the user allows unconverted
//!   parameters.
//!
//! A file of several programs (a Fanuc or Haas memory backup, split as the converter splits it:
//! [`ProgramStarts`]) is read program by program for its **local** variables: on a Custom Macro
//! B control #1-#33 are the program's own (cleared at its end; a G65/G66 macro call gives the
//! macro a level of its own), so `#1` of one main program and `#1` of the next are two
//! parameters here, each proved from its own program's uses. A subprogram, though, runs at its
//! caller's level and reads and sets the caller's locals, and any program may call one: by M98,
//! or by an M or T code the machine maps to it (parameters 6071-6079, 6001#5), which the text
//! does not show. So only in a file with no subprogram (no program that returns by M99) has each
//! program locals of its own; in a file with one, every program's locals are read as one, as
//! for a file of one program. Every other parameter (the common #100-#199 and #500-#999, system
//! variables) is one parameter of the whole file: a program can set one that a later one reads.
//!
//! A LinuxCNC file is one program, but its subroutines have parameters of their own (LinuxCNC
//! manual, "Named Parameters" and "O Codes"): a local named parameter (`#<depth>`) read or set
//! between `o<name> sub` and `o<name> endsub` is that subroutine's, and so are #1-#30, its
//! call's arguments; a global one (`#<_depth>`) and #31 on are the file's. A named parameter is
//! keyed by its name as LinuxCNC reads it, in lower case without blanks.

use std::collections::hash_map::Entry;
use std::collections::{HashMap, HashSet};

use crate::convert::{Classes, ParameterClass, ParameterClasses, ProgramStarts};
use crate::dialect::ReadingEnd;
use crate::expr;
use crate::hash::{FastMap, FastSet};
use crate::lex::{blank, Dialect, Family, LexError, Token};
use crate::machine::Machine;
use crate::restart::Control;
use crate::statement::{
    is_parameter_name, linuxcnc_definition, o_label, parameter_name, parameter_number, scoped_name,
    sub_local, Kind as StatementKind,
};
use crate::tokenizer::tokenize;
use crate::word::{Role, Word};

/// How a parameter is read: as a length, or as something else.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Class {
    Length,
    Other,
}

/// A parameter as the analysis keys it: its name (by its number in [`Analysis::names`]), for
/// a program's own local variable the line its program begins on (0 for the file's first), and
/// for a LinuxCNC subroutine's own parameter the line of its `o<name> sub`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct Key {
    name: u32,
    program: Option<usize>,
    sub: Option<usize>,
}

impl Key {
    /// The key of the same parameter shared by every program (its name and subroutine).
    fn shared(self) -> Key {
        Key {
            program: None,
            ..self
        }
    }
}

/// A map that keeps its keys in the order they were first given: the proof reads uses and
/// assignments in the program's order, and which of two reasons is given first depends on it.
#[derive(Debug, Clone)]
struct Ordered<V> {
    index: FastMap<Key, usize>,
    entries: Vec<(Key, V)>,
}

impl<V> Default for Ordered<V> {
    fn default() -> Self {
        Ordered {
            index: FastMap::default(),
            entries: Vec::new(),
        }
    }
}

impl<V> Ordered<V> {
    fn entry(&mut self, key: Key, new: impl FnOnce() -> V) -> &mut V {
        let at = *self.index.entry(key).or_insert_with(|| {
            self.entries.push((key, new()));
            self.entries.len() - 1
        });
        &mut self.entries[at].1
    }

    fn contains(&self, key: Key) -> bool {
        self.index.contains_key(&key)
    }

    fn iter(&self) -> impl Iterator<Item = &(Key, V)> {
        self.entries.iter()
    }
}

/// The first line a parameter is read on as a length, and as something else.
#[derive(Debug, Clone, Copy, Default)]
struct Uses {
    length: Option<usize>,
    other: Option<usize>,
}

/// `target = expression`: the parameters the expression reads, whether it is linear in them,
/// and its line.
#[derive(Debug, Clone)]
struct Assigned {
    names: Vec<Key>,
    linear: bool,
    line: usize,
}

/// A call as it is kept once: the label, and what each argument reads and whether linearly.
type CallShape = (Vec<u8>, Vec<(Vec<Key>, bool)>);

/// The calls as assignments to the subroutines' parameters, and why the arguments passed to
/// a subroutine of another file cannot be proved.
type Links = (Vec<(Key, Assigned)>, Vec<(Key, String)>);

/// Collects the parameter uses of a program's text, a chunk of whole lines at a time;
/// [`Analysis::result`] solves the classes.
#[derive(Debug)]
pub struct Analysis {
    /// The converter's roles of P, Q and R on the source machine (an unstated one a parameter).
    pqr: [Role; 3],
    /// Where the file's programs begin; None where the machine's files hold one program.
    split: Option<ProgramStarts>,
    /// The classes of the bytes a line is looked through for, and the family they were made
    /// for ([`Analysis::byte_classes`]).
    classes: Option<(Family, [u8; 256])>,
    /// Where a LinuxCNC file stops being read (`dialect::ReadingEnd`): the lines after are
    /// passed over. Made at the first lines, for their dialect's family.
    reading_end: Option<ReadingEnd>,
    /// The parameters' names as written, each once, and whether each is a local variable.
    ids: FastMap<Box<[u8]>, u32>,
    names: Vec<Box<[u8]>>,
    local: Vec<bool>,
    uses: Ordered<Uses>,
    assignments: Ordered<Vec<Assigned>>,
    /// The assignments already kept, as (target, what it reads, linear): one repeated (a
    /// program or a backup's folder written again, a loop unrolled) says nothing new, and
    /// keeping only its first line keeps the memory of a long file flat.
    kept: FastSet<(Key, Vec<Key>, bool)>,
    /// A parameter read as a length through a non-linear expression: its first line.
    nonlinear: Ordered<usize>,
    /// The line each program of the file begins on (0 for the first).
    starts: Vec<usize>,
    /// A program of the file returns (M99): a subprogram.
    returned: bool,
    /// A local variable was keyed by its program.
    keyed: bool,
    /// The line of the LinuxCNC `o<name> sub` whose body is being read.
    sub: Option<usize>,
    /// The terms of the expression being read, its lists kept from one to the next.
    terms: expr::Terms,
    /// The shapes of the words read ([`expr::Terms::shape`]), as a length or not, in the
    /// program and subroutine of [`Analysis::shapes_in`]: a word of one of them reads the
    /// same parameters in the same way, and each use keeps its first line only, so it adds
    /// nothing (`Y[#<yscale>*-56.12]` on every line of a scaled CAM program).
    shapes_read: FastSet<(u64, bool)>,
    shapes_in: (usize, Option<usize>, bool),
    /// The shapes of the whole lines read in the program and subroutine of
    /// [`Analysis::lines_in`] ([`line_shape`]) that tokenized to words alone: a line of one of
    /// them tokenizes to the same words, its numbers aside, and adds nothing, so it is passed
    /// over without its tokenization (every line of a program scaled by parameters,
    /// `N9871Y[#<yscale>*24.458]Z[#<zscale>*-27.104]`, read once a shape, not once a line).
    lines_read: FastSet<Vec<u8>>,
    lines_in: (usize, Option<usize>, bool),
    /// How many line shapes are kept at most (4,096: the memory stays flat; 0 reads every
    /// line, as the tests that hold the shapes to it do).
    lines_cap: usize,
    /// The shape of the line being read, its buffer kept from one line to the next.
    line: Vec<u8>,
    /// Whose expressions the lines hold ([`expr::terms_of`]): set by [`Analysis::lines`].
    family: Family,
    /// The LinuxCNC subroutines defined in the file: their label (`o<name>`, `o100`, as
    /// [`o_label`] reads it) and the line of their `sub`.
    subs: HashMap<Vec<u8>, usize>,
    /// LinuxCNC calls (`o<name> call [a] [b]`), each once: the label called, and each argument
    /// as an assignment to the subroutine's #1, #2... (linked in [`Analysis::result`], as a
    /// subroutine may be defined after its call).
    calls: Vec<(Vec<u8>, Vec<Assigned>)>,
    called: HashSet<CallShape>,
    /// The parameters each condition compares (`IF [#1 EQ #2]`, `o1 while [#<n> GT 0]`), each
    /// set once, with its first line: they share a class.
    ties: Vec<(Vec<Key>, usize)>,
    tied: HashSet<Vec<Key>>,
    /// The first line that sets or reads a parameter chosen by a value (`#[#1+100] = 5`,
    /// `##1 = 7`, `X#[#1]`), and how: which parameter it is is known only when the program
    /// runs, so no parameter's class can be proved.
    indirect: Option<(usize, &'static str)>,
    /// The control the program is written for: which of its system variables hold no length
    /// ([`crate::dialect::system_not_length`]).
    control: Control,
}

/// Whether `text` names a parameter by a value: `#` then (after blanks) `[` or `#`.
fn indirect_reference(text: &[u8]) -> bool {
    memchr::memchr_iter(b'#', text).any(|at| {
        let next = text[at + 1..].iter().find(|&&c| !blank(c));
        matches!(next, Some(b'[' | b'#'))
    })
}

/// Whether `text` names a SINUMERIK R parameter by a value: `R[` (after blanks), not inside a
/// name (`R[R1]=10`, `X=R[R1+1]`: Programming Manual Job Planning, "R parameters": "R[R10]",
/// the number given by an arithmetic variable).
fn sinumerik_indirect(text: &[u8]) -> bool {
    text.iter().enumerate().any(|(at, &c)| {
        c.eq_ignore_ascii_case(&b'R')
            && (at == 0 || !(text[at - 1].is_ascii_alphanumeric() || text[at - 1] == b'_'))
            && text[at + 1..].iter().find(|&&c| !blank(c)) == Some(&b'[')
    })
}

/// The `=` of a SINUMERIK assignment to an R parameter chosen by a value (`R[R1]=R3`): the
/// first `=` after the index's closing bracket.
fn sinumerik_indirect_target(token: &[u8]) -> Option<usize> {
    let rest = token
        .strip_prefix(b"R")
        .or_else(|| token.strip_prefix(b"r"))?;
    if rest.iter().find(|&&c| !blank(c)) != Some(&b'[') {
        return None;
    }
    expr::assignment_outside_brackets(token, true)
}

/// The shape of a line of a Custom Macro B or LinuxCNC program, for the parameter analysis:
/// the line with the digits of each number of an axis or feed word (`X`, `Y`, `Z`, `A`, `B`,
/// `C`, `U`, `V`, `W`, `I`, `J`, `K`, `F`, and `N`) or of an operand (after `.`, `+`, `-`,
/// `*`, `/`, `[`) replaced by one byte, 0x01; every other byte as written. Into `shape`;
/// false where the line is not one the analysis may pass over by its shape: one holding a
/// byte other than letters, digits, blanks and `. + - * / [ ] # = < >`, or an M or O outside
/// a `#<name>` (an end code, a return, a program number or an O-word: the reading's end and
/// the program split read their values), or longer than a block may be.
///
/// Why two lines of one shape are read alike: the tokenizer and the expressions' scanner ask
/// of such a number only where it ends (its form, a point and digits on either side, is
/// kept), never its value or its length; the digits whose value names something are kept:
/// a parameter's number (`#12`, and LinuxCNC's `#1 2`, digits after a blank), a name
/// (`#<a1>`), an index (digits before `=`: `X0=` is refused for its zero), the P, Q and R
/// of a Custom Macro B expression (`R2` may be a parameter), the G and other codes. And the
/// analysis reads of a line's words only the parameters, kept as written, and the shapes of
/// their expressions, which it keys by the same forms ([`expr::Terms::shape`]).
fn line_shape(text: &[u8], shape: &mut Vec<u8>) -> bool {
    shape.clear();
    if text.len() > crate::tokenizer::MAX_BLOCK {
        // too long a block by its length, which the shape does not keep
        return false;
    }
    // the bytes as written since the last number replaced, copied a run at a time
    let mut from = 0;
    let mut i = 0;
    while i < text.len() {
        match SHAPE_BYTES[usize::from(text[i])] {
            ShapeByte::Kept => i += 1,
            ShapeByte::Digit => {
                let end = i + text[i..].iter().take_while(|d| d.is_ascii_digit()).count();
                let operand = i > 0 && SHAPE_OPERAND[usize::from(text[i - 1])];
                if operand && text.get(expr::skip_blanks(text, end)) != Some(&b'=') {
                    shape.extend_from_slice(&text[from..i]);
                    shape.push(1);
                    from = end;
                }
                i = end;
            }
            ShapeByte::Name => {
                // a LinuxCNC name, `#<_x1>`: as written, to its `>`
                let Some(close) = text[i..].iter().position(|&b| b == b'>') else {
                    return false;
                };
                if !text[i + 1..i + close]
                    .iter()
                    .all(|&b| b.is_ascii_alphanumeric() || b == b'_')
                {
                    return false;
                }
                i += close + 1;
            }
            ShapeByte::Refused => return false,
        }
    }
    shape.extend_from_slice(&text[from..]);
    true
}

/// What [`line_shape`] does with a byte.
#[derive(Clone, Copy)]
enum ShapeByte {
    Kept,
    Digit,
    Name,
    Refused,
}

/// [`ShapeByte`] of each byte: letters but M and O, blanks (space, tab), `. + - * / [ ] # = >`
/// kept, `<` a name, digits, and every other byte refuses the line.
const SHAPE_BYTES: [ShapeByte; 256] = {
    let mut table = [ShapeByte::Refused; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        table[c] = match b {
            b'0'..=b'9' => ShapeByte::Digit,
            b'<' => ShapeByte::Name,
            b'M' | b'm' | b'O' | b'o' => ShapeByte::Refused,
            b'A'..=b'Z' | b'a'..=b'z' => ShapeByte::Kept,
            b' ' | b'\t' | b'.' | b'+' | b'-' | b'*' | b'/' | b'[' | b']' | b'#' | b'=' | b'>' => {
                ShapeByte::Kept
            }
            _ => ShapeByte::Refused,
        };
        c += 1;
    }
    table
};

/// The bytes before a number whose digits [`line_shape`] replaces: an operator, `.`, `[`, and
/// the axis and feed words' letters and N, either case.
const SHAPE_OPERAND: [bool; 256] = {
    let mut table = [false; 256];
    let mut c = 0;
    while c < 256 {
        table[c] = matches!(
            (c as u8).to_ascii_uppercase(),
            b'.' | b'+'
                | b'-'
                | b'*'
                | b'/'
                | b'['
                | b'X'
                | b'Y'
                | b'Z'
                | b'A'
                | b'B'
                | b'C'
                | b'U'
                | b'V'
                | b'W'
                | b'I'
                | b'J'
                | b'K'
                | b'F'
                | b'N'
        );
        c += 1;
    }
    table
};

/// A byte of [`ProgramStarts::marked`]: the line may begin a program of the file or return.
const MARKED: u8 = 1;
/// `=`, `#` or `[`: the line may read or set a parameter.
const PARAMETERS: u8 = 2;
/// Another byte that makes a line worth reading ([`Analysis::byte_classes`]).
const READ: u8 = 4;

/// The classes ([`Analysis::byte_classes`]) of the bytes of `text`, together.
fn line_classes(classes: &[u8; 256], text: &[u8]) -> u8 {
    text.iter()
        .fold(0u8, |found, &c| found | classes[usize::from(c)])
}

/// A Custom Macro B local variable (#1-#33): a parameter of one program of the file.
fn is_local(name: &[u8]) -> bool {
    parameter_number(name).is_some_and(|n| (1..=33).contains(&n))
}

impl Analysis {
    /// The analysis of a program written for `machine`.
    pub fn new(machine: &Machine) -> Analysis {
        Analysis {
            control: machine.control,
            ..Analysis::of(
                machine.convert_roles(),
                ProgramStarts::new(machine.family, machine.check.program_number),
            )
        }
    }

    /// The analysis of a program whose P, Q and R have the converter's roles `pqr`, its file
    /// split into programs by `split`.
    fn of(pqr: [Role; 3], split: ProgramStarts) -> Analysis {
        Analysis {
            pqr,
            split: split.splits().then_some(split),
            classes: None,
            reading_end: None,
            ids: FastMap::default(),
            names: Vec::new(),
            local: Vec::new(),
            uses: Ordered::default(),
            assignments: Ordered::default(),
            kept: FastSet::default(),
            nonlinear: Ordered::default(),
            starts: vec![0],
            returned: false,
            keyed: false,
            sub: None,
            terms: expr::Terms::default(),
            shapes_read: FastSet::default(),
            shapes_in: (1, None, false),
            lines_read: FastSet::default(),
            lines_in: (1, None, false),
            lines_cap: 4096,
            line: Vec::new(),
            family: Family::Iso,
            subs: HashMap::new(),
            calls: Vec::new(),
            called: HashSet::new(),
            ties: Vec::new(),
            tied: HashSet::new(),
            indirect: None,
            control: Control::Iso,
        }
    }

    /// Whole lines `text` (split at LF) after line `line`: the words of each line that may read
    /// or set a parameter (holding `=`, `#` or `[`), where the file's next program begins or
    /// a program returns (before that line's words), and where a LinuxCNC subroutine's
    /// definition begins and ends. A line that cannot be read ends the reading with its
    /// number, its text and its error, where it holds such a word; one that holds none is
    /// passed over, by the split too (the conversion refuses it at that line).
    pub fn lines<'a>(
        &mut self,
        text: &'a [u8],
        line: usize,
        dialect: &Dialect,
    ) -> Result<(), (usize, &'a [u8], LexError)> {
        self.family = dialect.family;
        let mut tokens: Vec<Token<'a>> = Vec::with_capacity(16);
        let mut end = self
            .reading_end
            .take()
            .unwrap_or_else(|| ReadingEnd::new(dialect.family));
        let read = self.read_lines(text, line, dialect, &mut tokens, &mut end);
        self.reading_end = Some(end);
        read
    }

    /// [`Analysis::lines`] with the reading's end in hand.
    fn read_lines<'a>(
        &mut self,
        text: &'a [u8],
        line: usize,
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
        end: &mut ReadingEnd,
    ) -> Result<(), (usize, &'a [u8], LexError)> {
        let classes = self.byte_classes(dialect.family);
        for (number, text) in (line + 1..).zip(crate::text::lines(text)) {
            if end.skips(number, text) {
                continue;
            }
            // the bytes that make a line worth reading, looked for in one pass over it
            let found = line_classes(&classes, text);
            let marked = found & MARKED != 0;
            let parameters = found & PARAMETERS != 0;
            let read = found & !MARKED != 0;
            if !marked && !read {
                continue;
            }
            // a line of a shape read before in this program and subroutine adds nothing
            let shaped = !marked
                && parameters
                && matches!(dialect.family, Family::LinuxCnc | Family::MacroB)
                && line_shape(text, &mut self.line);
            if shaped && self.known_line() {
                continue;
            }
            // tokenized once for the split and the analysis
            tokens.clear();
            let tokenized = tokenize(text, dialect, tokens);
            if let (Some(split), Ok(extras)) = (&mut self.split, &tokenized) {
                if marked {
                    let (begins, returns) = split.read(text, tokens, extras);
                    if begins {
                        self.starts.push(number);
                    }
                    if returns {
                        self.returned = true;
                    }
                }
            }
            if !read {
                continue;
            }
            let extras = match tokenized {
                Ok(extras) => extras,
                Err(_) if !parameters => continue,
                Err(error) => return Err((number, text, error)),
            };
            // (kept where the line is words alone: no statement, comment, skip or `%` line)
            let words_alone = shaped && extras.is_none();
            crate::tokenizer::note_reading_end(end, tokens, &extras, text, number);
            // `o<name> sub` .. `o<name> endsub`: the subroutine's own parameters
            for statement in extras.iter().flat_map(|e| &e.statements) {
                let words = &text[statement.offset..statement.end];
                if statement.kind == StatementKind::Definition {
                    match linuxcnc_definition(words) {
                        Some(true) => {
                            self.subs.entry(o_label(words)).or_insert(number);
                            self.sub = Some(number);
                        }
                        Some(false) => self.sub = None,
                        None => {}
                    }
                }
                self.statement(words, statement.kind, dialect.family, number);
            }
            for token in tokens.iter() {
                if memchr::memchr3(b'=', b'#', b'[', &token.text).is_some() {
                    self.token(&token.text, number);
                }
            }
            if words_alone {
                self.keep_line();
            }
        }
        Ok(())
    }

    /// The classes of each byte a line is looked through for ([`MARKED`], [`PARAMETERS`],
    /// [`READ`]), for the lines of `family`: made once, kept while the family is the same.
    fn byte_classes(&mut self, family: Family) -> [u8; 256] {
        if let Some((made_for, classes)) = self.classes {
            if made_for == family {
                return classes;
            }
        }
        let linuxcnc = family == Family::LinuxCnc;
        let mut classes = [0u8; 256];
        for (c, class) in (0..=255u8).zip(classes.iter_mut()) {
            if self.split.as_ref().is_some_and(|split| split.is_mark(c)) {
                *class |= MARKED;
            }
            if matches!(c, b'=' | b'#' | b'[') {
                *class |= PARAMETERS;
            }
            // a LinuxCNC `o` word (a subroutine's definition, a call); a LinuxCNC M2/M30
            // ends the reading (`dialect::ReadingEnd`); a SINUMERIK condition may compare
            // without `=` (`UNTIL R3>R1`, `IF R1<R2 GOTOB L`)
            if linuxcnc && matches!(c, b'o' | b'O' | b'm' | b'M')
                || family == Family::Sinumerik && matches!(c, b'<' | b'>')
            {
                *class |= READ;
            }
        }
        self.classes = Some((family, classes));
        classes
    }

    /// Whether the shape of the line in [`Analysis::line`] was read in the program and
    /// subroutine being read (its parameters are keyed by them: [`Analysis::key`]).
    fn known_line(&mut self) -> bool {
        let within = (self.starts.len(), self.sub, self.returned);
        if within != self.lines_in {
            self.lines_read.clear();
            self.lines_in = within;
        }
        self.lines_read.contains(self.line.as_slice())
    }

    /// Keeps the shape of the line just read (at most [`Analysis::lines_cap`]).
    fn keep_line(&mut self) {
        if self.lines_read.len() >= self.lines_cap {
            self.lines_read.clear();
        }
        if self.lines_cap > 0 {
            self.lines_read.insert(self.line.clone());
        }
    }

    /// The parameters a statement reads or sets, on the families whose parameters are `#`
    /// words (Custom Macro B, LinuxCNC): the parameters a condition or value in brackets reads
    /// (`IF [#1 EQ #2]`, `o100 while [#<i> LT #<n>]`, `o1 return [#2]`) share a class, as a
    /// comparison of a converted length with an unconverted count would change its result
    /// (the statement is carried as written; one holding a number is refused by the
    /// converter), and are no length where nothing else says so; the assignment after a
    /// Custom Macro B `IF [..] THEN` is one; a LinuxCNC call's arguments set the called
    /// subroutine's #1, #2...
    fn statement(&mut self, words: &[u8], kind: StatementKind, family: Family, line: usize) {
        if family == Family::Sinumerik && kind == StatementKind::Flow {
            self.sinumerik_condition(words, line);
            return;
        }
        if family == Family::Sinumerik && sinumerik_indirect(words) {
            // R[R1]=R3, read as a statement: a parameter chosen by a value
            self.token(words, line);
            return;
        }
        if !matches!(family, Family::MacroB | Family::LinuxCnc) {
            return;
        }
        if kind == StatementKind::Call && family == Family::LinuxCnc {
            // a label worked out as the line runs (`o#1 call`, `o[#1] call [5]`) reads its
            // parameters as a subroutine's number, no length; the arguments come after it
            let after = crate::statement::o_label_len(words);
            if words[..after].contains(&b'#') {
                self.word(&words[1..after], false, line);
            }
            let full = words;
            let words = &words[after..];
            let (groups, _) = expr::bracket_groups(words);
            let args = groups
                .iter()
                .map(|&(a, b)| self.value(&words[a..b], line))
                .collect::<Vec<_>>();
            let label = o_label(&full[..after]);
            let shape = args.iter().map(|a| (a.names.clone(), a.linear)).collect();
            if self.called.insert((label.clone(), shape)) {
                self.calls.push((label, args));
            }
            return;
        }
        let (groups, rest) = expr::bracket_groups(words);
        for &(a, b) in &groups {
            self.tie(&words[a..b], line);
        }
        // what stands outside the brackets: a Custom Macro B `THEN #3 = #2 + 1` (or the same
        // without THEN) is an assignment; a `GOTO #1` reads a sequence number
        let rest: Vec<u8> = rest.into_iter().filter(|&c| !blank(c)).collect();
        if let Some(hash) = rest.iter().position(|&c| c == b'#') {
            if family == Family::MacroB && rest[hash..].contains(&b'=') {
                self.token(&rest[hash..], line);
            } else {
                self.word(&rest[hash..], false, line);
            }
        }
    }

    /// A condition in brackets (`[#1 EQ #2]`, `[#<n> GT 0]`): the parameters it compares
    /// share a class, each once per file.
    fn tie(&mut self, condition: &[u8], line: usize) {
        self.note_indirect(condition, line, "reads");
        let mut terms = std::mem::take(&mut self.terms);
        let read = expr::terms_of(condition, self.family, &mut terms).is_ok();
        let mut members: Vec<Key> = if read {
            terms
                .params
                .iter()
                .map(|&(a, b)| self.key(&condition[a..b]))
                .collect()
        } else {
            Vec::new()
        };
        self.terms = terms;
        if !read {
            return;
        }
        members.sort_by_key(|k| (k.name, k.program, k.sub));
        members.dedup();
        if !members.is_empty() && self.tied.insert(members.clone()) {
            self.ties.push((members, line));
        }
    }

    /// A SINUMERIK control statement (`WHILE R3<=R1`, `IF R3<=R1 GOTOB MARKE`, `UNTIL R3>R1`,
    /// `FOR R3=0 TO R1`): the R parameters it compares share a class, as a Custom Macro B
    /// condition's do ([`Analysis::tie`]); the jump's label after GOTO is no parameter.
    fn sinumerik_condition(&mut self, words: &[u8], line: usize) {
        let upper = words.to_ascii_uppercase();
        let end = memchr::memmem::find(&upper, b"GOTO").unwrap_or(upper.len());
        let text = &words[..end];
        let mut members = Vec::new();
        let mut i = 0;
        while i < text.len() {
            let Some((digits, parameter)) = expr::r_parameter_at(text, i) else {
                i += 1;
                continue;
            };
            if parameter {
                members.push(self.key(&text[i..i + 1 + digits]));
            }
            i += 1 + digits;
        }
        members.sort_by_key(|k| (k.name, k.program, k.sub));
        members.dedup();
        if !members.is_empty() && self.tied.insert(members.clone()) {
            self.ties.push((members, line));
        }
    }

    /// A value a call passes (an argument): what it reads, keyed where the call stands.
    fn value(&mut self, expression: &[u8], line: usize) -> Assigned {
        self.note_indirect(expression, line, "reads");
        let mut terms = std::mem::take(&mut self.terms);
        let (spans, linear) = match expr::terms_of(expression, self.family, &mut terms) {
            Err(_) => (&[][..], false),
            Ok(()) => (&terms.params[..], terms.linear),
        };
        let names = spans
            .iter()
            .map(|&(a, b)| self.key(&expression[a..b]))
            .collect();
        self.terms = terms;
        Assigned {
            names,
            linear,
            line,
        }
    }

    /// Notes the first parameter chosen by a value (`#[`, `##`) in `text`.
    fn note_indirect(&mut self, text: &[u8], line: usize, how: &'static str) {
        let sinumerik = self.family == Family::Sinumerik && sinumerik_indirect(text);
        if self.indirect.is_none() && (sinumerik || indirect_reference(text)) {
            self.indirect = Some((line, how));
        }
    }

    /// A word token that may read or set a parameter: an assignment (`R1=...`, `#1=...`, where
    /// the letter is a parameter on this machine; LinuxCNC's `#<name>=...`), or a word whose
    /// value is an expression. An assignment to a parameter chosen by a value (`#[#1]=...`,
    /// `##1=...`) is noted: it may set any parameter.
    fn token(&mut self, token: &[u8], line: usize) {
        if let Some(end) = crate::statement::named_target(token) {
            self.assignment(&token[..end], &token[end + 1..], line);
            return;
        }
        if let Some(eq) = expr::indirect_target(token) {
            self.note_indirect(token, line, "sets");
            self.word(&token[1..eq], false, line);
            self.word(&token[eq + 1..], false, line);
            return;
        }
        if self.family == Family::Sinumerik {
            if let Some(eq) = sinumerik_indirect_target(token) {
                // R[R1]=R3: the index is a count, the value goes to a parameter chosen by it
                self.note_indirect(token, line, "sets");
                let open = token.iter().position(|&c| c == b'[').unwrap_or(0);
                let close = token[..eq].iter().rposition(|&c| c == b']').unwrap_or(eq);
                self.word(&token[open + 1..close.max(open + 1)], false, line);
                self.word(&token[eq + 1..], false, line);
                return;
            }
            if sinumerik_indirect(token) {
                self.note_indirect(token, line, "reads");
            }
        }
        let w = Word::new(token, 0);
        let pqr = match w.letter {
            b'P' => Some(self.pqr[0]),
            b'Q' => Some(self.pqr[1]),
            b'R' => Some(self.pqr[2]),
            _ => None,
        };
        let indexed = !w.index.is_empty();
        if indexed && (w.address == b'#' || pqr == Some(Role::Parameter)) {
            let target = &token[..1 + w.index.len()];
            let value = if w.expression.is_empty() {
                &b"0"[..]
            } else {
                w.expression
            };
            self.assignment(target, value, line);
        } else if !w.expression.is_empty() {
            let length = matches!(w.letter, b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W')
                || matches!(w.letter, b'I' | b'J' | b'K' | b'F' | b'E')
                || pqr == Some(Role::Length);
            self.word(w.expression, length, line);
        }
    }

    /// The key of a parameter read or set in the program being read, by its
    /// [`parameter_name`]: a local variable is its program's own until a program returns
    /// (after an M99 no program has its own), and a LinuxCNC subroutine's own parameter
    /// ([`sub_local`]) its subroutine's.
    fn key(&mut self, raw: &[u8]) -> Key {
        let normal;
        let name = if is_parameter_name(raw) {
            raw
        } else {
            normal = parameter_name(raw);
            normal.as_bytes()
        };
        let id = match self.ids.get(name) {
            Some(&id) => id,
            None => {
                let id = self.names.len() as u32;
                self.ids.insert(name.into(), id);
                self.names.push(name.into());
                self.local.push(is_local(name));
                id
            }
        };
        let sub = self.sub.filter(|_| sub_local(&self.names[id as usize]));
        if self.returned || !self.local[id as usize] {
            return Key {
                name: id,
                program: None,
                sub,
            };
        }
        self.keyed = true;
        Key {
            name: id,
            program: self.starts.last().copied(),
            sub,
        }
    }

    fn read(&mut self, name: &[u8], class: Class, line: usize) {
        let key = self.key(name);
        let uses = self.uses.entry(key, Uses::default);
        let first = match class {
            Class::Length => &mut uses.length,
            Class::Other => &mut uses.other,
        };
        first.get_or_insert(line);
    }

    /// A word whose value is `expression`; `is_length` says the word is a length.
    ///
    /// A SINUMERIK's expression is read by its own reader ([`expr::terms_of`]): a variable
    /// (`Z=_Z_HOME`, `X=R1+_Z_HOME`) makes it non-linear, and the converter, meeting the word,
    /// refuses it at its column as an expression it cannot convert (`--allow-unconverted`
    /// leaves it as written), as it refuses the `_Z_HOME=610.` that sets it. An expression no
    /// reader reads is refused by the tokenizer before this.
    fn word(&mut self, expression: &[u8], is_length: bool, line: usize) {
        self.note_indirect(expression, line, "reads");
        let mut terms = std::mem::take(&mut self.terms);
        if expr::terms_of(expression, self.family, &mut terms).is_ok()
            && terms
                .shape()
                .is_none_or(|shape| self.new_shape(shape, is_length))
        {
            self.read_terms(expression, &terms, is_length, line);
        }
        self.terms = terms;
    }

    /// Whether a word of this shape, as a length or not, is the first of the program and
    /// subroutine being read (its parameters are keyed by them: [`Analysis::key`]).
    fn new_shape(&mut self, shape: u64, is_length: bool) -> bool {
        let within = (self.starts.len(), self.sub, self.returned);
        if within != self.shapes_in || self.shapes_read.len() >= 4096 {
            self.shapes_read.clear();
            self.shapes_in = within;
        }
        self.shapes_read.insert((shape, is_length))
    }

    fn read_terms(&mut self, expression: &[u8], terms: &expr::Terms, is_length: bool, line: usize) {
        if is_length && terms.linear {
            for &(a, b) in &terms.params {
                self.read(&expression[a..b], Class::Length, line);
            }
            return;
        }
        for &(a, b) in &terms.params {
            if is_length {
                let key = self.key(&expression[a..b]);
                self.nonlinear.entry(key, || line);
            } else {
                self.read(&expression[a..b], Class::Other, line);
            }
        }
    }

    /// `target = expression`; one the core cannot read passes the target's class on to
    /// nothing (the converter refuses the assignment where the target is a length).
    fn assignment(&mut self, target: &[u8], expression: &[u8], line: usize) {
        self.note_indirect(expression, line, "reads");
        let target = self.key(target);
        let mut terms = std::mem::take(&mut self.terms);
        let (spans, linear) = match expr::terms_of(expression, self.family, &mut terms) {
            Err(_) => (&[][..], false),
            Ok(()) => (&terms.params[..], terms.linear),
        };
        let names: Vec<Key> = spans
            .iter()
            .map(|&(a, b)| self.key(&expression[a..b]))
            .collect();
        self.terms = terms;
        // the first of identical assignments is the one every message names
        if !self.kept.insert((target, names.clone(), linear)) {
            return;
        }
        self.assignments.entry(target, Vec::new).push(Assigned {
            names,
            linear,
            line,
        });
    }

    /// The programs with local variables of their own: every program of a file of several that
    /// holds no subprogram; none where it holds one, or is one program (its locals are then
    /// just its parameters).
    fn own(&self) -> HashSet<usize> {
        if self.starts.len() == 1 || self.returned {
            return HashSet::new();
        }
        self.starts.iter().copied().collect()
    }

    /// A parameter's key as a message names it: `#1`, a program's own local variable
    /// `#1 of the program beginning on line 40` (`of the file's first program`), a LinuxCNC
    /// subroutine's own `#<depth> of the subroutine beginning on line 12`.
    /// A LinuxCNC parameter that holds a length in the units in force where it is read: the
    /// current position's X Y Z U V W (#5420-#5428). rs274 prints `#5420` after `G21 G1 X1`
    /// as 1 and, after G20, as 0.03937: a length read from it needs no conversion, and the
    /// text around it is converted as any other (review 5, 7). A work offset (#5221-#5390)
    /// is not one: rs274 prints `#5221` set by `G10 L2 P1 X1` under G20 as 1 before and after
    /// G21, and set to X10 under G21 as 0.393701, the machine's units, as a FANUC's #5221.
    fn follows_units(&self, key: Key) -> bool {
        if self.family != Family::LinuxCnc {
            return false;
        }
        let name = &self.names[key.name as usize];
        name.strip_prefix(b"#")
            .and_then(|d| std::str::from_utf8(d).ok())
            .and_then(|d| d.parse::<u32>().ok())
            .is_some_and(|n| [5420, 5421, 5422, 5426, 5427, 5428].contains(&n))
    }

    fn shown(&self, key: Key) -> String {
        let name = String::from_utf8_lossy(&self.names[key.name as usize]);
        match (key.sub, key.program) {
            (Some(sub), _) => format!("{name} of the subroutine beginning on line {sub}"),
            (None, None) => name.into_owned(),
            (None, Some(0)) => format!("{name} of the file's first program"),
            (None, Some(start)) => format!("{name} of the program beginning on line {start}"),
        }
    }

    /// The classes for the converter: where each program begins, the file's parameters (held
    /// once for every program) and each program's own local ones.
    pub fn result(&self) -> ParameterClasses {
        let own = self.own();
        // Where no program has locals of its own, the locals keyed by their programs (read
        // before the M99 that showed a subprogram, or in a file of one program) are one.
        let merged;
        let (uses, assignments, nonlinear) = if !own.is_empty() || !self.keyed {
            (&self.uses, &self.assignments, &self.nonlinear)
        } else {
            merged = self.merged();
            (&merged.0, &merged.1, &merged.2)
        };
        let merged_keys = own.is_empty() && self.keyed;
        let shared = |key: Key| if merged_keys { key.shared() } else { key };
        let (links, external) = self.calls(merged_keys);
        let mut assignments = assignments.clone();
        for (target, entry) in links {
            assignments.entry(target, Vec::new).push(entry);
        }
        let assignments = &assignments;
        let mut classes: HashMap<Key, Class> = HashMap::new();
        let mut problems: HashMap<Key, String> = HashMap::new();
        for (key, why) in external {
            problems.entry(key).or_insert(why);
        }
        for &(key, kinds) in uses.iter() {
            match (kinds.length, kinds.other) {
                (Some(length), Some(other)) => {
                    problems.insert(
                        key,
                        format!(
                            "{} is read as a length (line {length}) and as something else \
                             (line {other})",
                            self.shown(key)
                        ),
                    );
                }
                (Some(_), None) => {
                    classes.insert(key, Class::Length);
                }
                _ => {
                    classes.insert(key, Class::Other);
                }
            }
        }
        // A system variable whose meaning is not a length is none, whatever shows it or not.
        for (id, name) in self.names.iter().enumerate() {
            let Some(what) = name
                .strip_prefix(b"#")
                .and_then(|d| std::str::from_utf8(d).ok())
                .and_then(|d| d.parse::<u32>().ok())
                .and_then(|n| match self.control {
                    Control::Fanuc => crate::dialect::system_not_length(false, n),
                    Control::Haas => crate::dialect::system_not_length(true, n),
                    _ => None,
                })
            else {
                continue;
            };
            let key = Key {
                name: id as u32,
                program: None,
                sub: None,
            };
            match classes.entry(key) {
                Entry::Occupied(e) if *e.get() == Class::Length => {
                    problems.entry(key).or_insert_with(|| {
                        format!(
                            "{} is read as a length (line {}), but on this control it is \
                             {what}, not a length",
                            self.shown(key),
                            uses.iter()
                                .find(|(k, _)| *k == key)
                                .and_then(|(_, u)| u.length)
                                .unwrap_or(0),
                        )
                    });
                }
                Entry::Occupied(_) => {}
                Entry::Vacant(e) => {
                    e.insert(Class::Other);
                }
            }
        }
        for &(key, line) in nonlinear.iter() {
            problems.entry(key).or_insert_with(|| {
                format!(
                    "{} is read in a non-linear expression on line {line}, so its units cannot \
                     be converted",
                    self.shown(key)
                )
            });
        }
        // An assignment passes its target's class on to what it reads, until nothing changes.
        let mut changed = true;
        let mut settled = false;
        while changed {
            changed = false;
            for (target, entries) in assignments.iter() {
                let Some(&class) = classes.get(target) else {
                    continue;
                };
                for entry in entries {
                    for &name in &entry.names {
                        if !entry.linear && class == Class::Length {
                            problems.entry(name).or_insert_with(|| {
                                format!(
                                    "{} feeds the length {} through a non-linear expression \
                                     on line {}",
                                    self.shown(name),
                                    self.shown(*target),
                                    entry.line
                                )
                            });
                            continue;
                        }
                        match classes.get(&name) {
                            None => {
                                classes.insert(name, class);
                                changed = true;
                            }
                            Some(&have) if have != class => {
                                problems.entry(name).or_insert_with(|| {
                                    format!(
                                        "{} is used both as a length and as something else \
                                         (line {})",
                                        self.shown(name),
                                        entry.line
                                    )
                                });
                            }
                            Some(_) => {}
                        }
                    }
                }
            }
            // the parameters a condition compares share a class; those that have none from
            // elsewhere (a loop's counter) are no length, once nothing else can be learnt
            for (members, line) in &self.ties {
                let members: Vec<Key> = members.iter().map(|&k| shared(k)).collect();
                let Some(class) = members.iter().find_map(|k| classes.get(k).copied()) else {
                    continue;
                };
                let mixed = members
                    .iter()
                    .any(|k| classes.get(k).is_some_and(|&have| have != class));
                for &name in &members {
                    if mixed {
                        problems.entry(name).or_insert_with(|| {
                            format!(
                                "{} is compared on line {line} with a parameter of another \
                                 class (a length and something else)",
                                self.shown(name)
                            )
                        });
                    } else if let Entry::Vacant(e) = classes.entry(name) {
                        e.insert(class);
                        changed = true;
                    }
                }
            }
            if !changed && !settled {
                settled = true;
                for (members, _) in &self.ties {
                    for &name in members {
                        if let Entry::Vacant(e) = classes.entry(shared(name)) {
                            e.insert(Class::Other);
                            changed = true;
                        }
                    }
                }
            }
        }
        for (target, entries) in assignments.iter() {
            if !classes.contains_key(target) && !problems.contains_key(target) {
                // read into another parameter (`#<a>=#1`, passed on to a call) whose class
                // is not shown either: no use says what it is (review 5, 10)
                let copied = assignments.iter().find_map(|(t, es)| {
                    es.iter()
                        .find(|e| e.names.contains(target))
                        .map(|e| (*t, e.line))
                });
                let why = match copied {
                    Some((into, line)) => format!(
                        "{} is assigned on line {} and read into {} on line {line}, whose uses \
                         do not show whether it is a length",
                        self.shown(*target),
                        entries[0].line,
                        self.shown(into)
                    ),
                    None => format!(
                        "{} is assigned on line {} but never read in this program, so nothing \
                         shows whether it is a length",
                        self.shown(*target),
                        entries[0].line
                    ),
                };
                problems.insert(*target, why);
            }
        }
        // A length read here and set nowhere in the program holds what a caller (a macro's
        // argument) or the control put there, in units this conversion does not change.
        for &(key, kinds) in uses.iter() {
            if let Some(line) = kinds.length {
                if !assignments.contains(key) && !self.follows_units(key) {
                    problems.entry(key).or_insert_with(|| {
                        format!(
                            "{} is read as a length (line {line}) but not set in this program: \
                             its value comes from a caller or the control, in units this \
                             conversion does not change",
                            self.shown(key)
                        )
                    });
                }
            }
        }
        // The same value copied first (`#1=#5003`, `#1=#2001+2.`, `#<a>=#5221`, a call's
        // argument): the copy is a length, and what it reads is set nowhere here, so neither
        // is proved (review 4, 4: `#1=#5003` then `X[#1+1.]` converted 1. alone).
        for (target, entries) in assignments.iter() {
            if classes.get(target) != Some(&Class::Length) {
                continue;
            }
            for entry in entries {
                for &name in &entry.names {
                    if assignments.contains(name) || self.follows_units(name) {
                        continue;
                    }
                    problems.entry(name).or_insert_with(|| {
                        format!(
                            "{} is read into the length {} (line {}) but not set in this \
                             program: its value comes from a caller or the control, in units \
                             this conversion does not change",
                            self.shown(name),
                            self.shown(*target),
                            entry.line
                        )
                    });
                }
            }
        }
        if let Some((line, how)) = self.indirect {
            // any parameter may be the one chosen: none is proved
            let keys: Vec<Key> = uses
                .iter()
                .map(|&(key, _)| key)
                .chain(assignments.iter().map(|&(key, _)| key))
                .chain(nonlinear.iter().map(|&(key, _)| key))
                .collect();
            for key in keys {
                problems.insert(
                    key,
                    format!(
                        "line {line} {how} a parameter chosen by a value (#[..], ##, R[..]): \
                         which one is known only when the program runs, so the class of {} cannot be \
                         proved",
                        self.shown(key)
                    ),
                );
            }
        }
        classes.retain(|key, _| !problems.contains_key(key));
        self.programs(&classes, &problems, &own)
    }

    /// The LinuxCNC calls as assignments: each argument to the called subroutine's #1, #2...
    /// (`merged`: every local keyed by its name alone); and for a call of a subroutine not
    /// defined in the file, why the parameters its arguments read cannot be proved.
    fn calls(&self, merged: bool) -> Links {
        let mut links = Vec::new();
        let mut external = Vec::new();
        for (label, args) in &self.calls {
            let sub = self.subs.get(label).copied();
            for (i, arg) in args.iter().enumerate() {
                let shared = |key: Key| if merged { key.shared() } else { key };
                let names: Vec<Key> = arg.names.iter().map(|&k| shared(k)).collect();
                let Some(sub) = sub else {
                    for &name in &names {
                        external.push((
                            name,
                            format!(
                                "{} is passed on line {} to {}, a subroutine not defined in this \
                                 file: how it reads the value is not known here",
                                self.shown(name),
                                arg.line,
                                String::from_utf8_lossy(label)
                            ),
                        ));
                    }
                    continue;
                };
                let name = format!("#{}", i + 1);
                let Some(&id) = self.ids.get(name.as_bytes()) else {
                    continue; // the subroutine never reads nor sets it
                };
                let program = (!merged && !self.returned && self.local[id as usize])
                    .then(|| self.starts.last().copied())
                    .flatten();
                let target = Key {
                    name: id,
                    program,
                    sub: Some(sub),
                };
                links.push((
                    target,
                    Assigned {
                        names,
                        linear: arg.linear,
                        line: arg.line,
                    },
                ));
            }
        }
        (links, external)
    }

    /// The uses, assignments and non-linear reads with every local keyed by its name alone.
    fn merged(&self) -> (Ordered<Uses>, Ordered<Vec<Assigned>>, Ordered<usize>) {
        let mut uses: Ordered<Uses> = Ordered::default();
        for &(key, kinds) in self.uses.iter() {
            let merged = uses.entry(key.shared(), Uses::default);
            for (mine, theirs) in [
                (&mut merged.length, kinds.length),
                (&mut merged.other, kinds.other),
            ] {
                if let Some(line) = theirs {
                    *mine = Some(mine.map_or(line, |have| have.min(line)));
                }
            }
        }
        let mut assignments: Ordered<Vec<Assigned>> = Ordered::default();
        for (key, entries) in self.assignments.iter() {
            assignments
                .entry(key.shared(), Vec::new)
                .extend(entries.iter().map(|entry| Assigned {
                    names: entry.names.iter().map(|name| name.shared()).collect(),
                    ..*entry
                }));
        }
        let mut nonlinear: Ordered<usize> = Ordered::default();
        for &(key, line) in self.nonlinear.iter() {
            let first = nonlinear.entry(key.shared(), || line);
            *first = (*first).min(line);
        }
        (uses, assignments, nonlinear)
    }

    fn programs(
        &self,
        classes: &HashMap<Key, Class>,
        problems: &HashMap<Key, String>,
        own: &HashSet<usize>,
    ) -> ParameterClasses {
        let mut out = ParameterClasses {
            starts: self.starts.clone(),
            subs: self.subs.iter().map(|(k, &v)| (k.clone(), v)).collect(),
            ..ParameterClasses::default()
        };
        let lengths = classes
            .iter()
            .filter(|&(_, &class)| class == Class::Length)
            .map(|(key, _)| (key, ParameterClass::Length));
        let unproved = problems
            .iter()
            .map(|(key, why)| (key, ParameterClass::Unproved(why.clone())));
        for (key, class) in lengths.chain(unproved) {
            let name = String::from_utf8_lossy(&self.names[key.name as usize]).into_owned();
            let name = scoped_name(name, key.sub);
            let classes: &mut Classes = match key.program {
                // `starts` ascends, and a program's key is one of them
                Some(program) => {
                    let at = self.starts.binary_search(&program).unwrap_or_default();
                    match out.own.binary_search_by_key(&at, |&(p, _)| p) {
                        Ok(i) => &mut out.own[i].1,
                        Err(i) => {
                            out.own.insert(i, (at, Classes::default()));
                            &mut out.own[i].1
                        }
                    }
                }
                // a local variable is no program's where every program has its own
                None if !own.is_empty() && self.local[key.name as usize] => continue,
                None => &mut out.shared,
            };
            classes.insert(name.into_bytes(), class);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn macro_b() -> Dialect {
        Dialect {
            family: Family::MacroB,
            hash: true,
            brackets: true,
            star: true,
            expressions: true,
            ..Dialect::default()
        }
    }

    /// A Fanuc mill's analysis (P and R parameters, Q a length) of `lines`, chunk by chunk.
    fn analysis(chunks: &[(&str, usize)]) -> Analysis {
        let roles = [Role::Parameter, Role::Length, Role::Parameter];
        let mut analysis = Analysis::of(roles, ProgramStarts::new(Family::MacroB, Some(b'O')));
        for &(text, line) in chunks {
            analysis.lines(text.as_bytes(), line, &macro_b()).unwrap();
        }
        analysis
    }

    /// `(start, lengths, problems)` of each program.
    type Lists = Vec<(usize, Vec<String>, Vec<(String, String)>)>;

    fn lists(classes: &ParameterClasses) -> Lists {
        (0..classes.starts.len())
            .map(|program| {
                let (lengths, problems) = classes.lists(program);
                (classes.starts[program], lengths, problems)
            })
            .collect()
    }

    fn classes(text: &str) -> Lists {
        lists(&analysis(&[(text, 0)]).result())
    }

    fn why(text: &str) -> Vec<String> {
        let programs = classes(text);
        assert_eq!(programs.len(), 1);
        programs[0].2.iter().map(|(_, why)| why.clone()).collect()
    }

    #[test]
    fn a_parameter_read_by_a_length_through_a_linear_expression_is_a_length() {
        let text = "#1=10.\n#2=#1*2+5.\nG01 X[#2-#1/4] Y#2 F#3\n#3=100.\nS#4\n#4=1000";
        // a feed is a length per minute or per revolution, a speed (S) is not
        assert_eq!(
            classes(text),
            [(0, vec!["#1".into(), "#2".into(), "#3".into()], Vec::new())]
        );
        // Q is a length on this machine, R a parameter it assigns
        assert_eq!(classes("R1=5.\nG83 Q[R1]")[0].1, ["R1"]);
        assert_eq!(classes("R1=5.\nG83 P[R1]")[0].1, Vec::<String>::new());
    }

    #[test]
    fn what_cannot_be_proved_is_said_with_its_line() {
        assert_eq!(
            why("#1=1.\nG01 X#1\nM98 P100 L#1"),
            ["#1 is read as a length (line 2) and as something else (line 3)"]
        );
        assert_eq!(
            why("#1=1.\nG01 X[SIN[#1]]"),
            ["#1 is read in a non-linear expression on line 2, so its units cannot be converted"]
        );
        assert_eq!(
            why("#1=1.\n#2=#1*#1\nG01 X#2"),
            ["#1 feeds the length #2 through a non-linear expression on line 2"]
        );
        assert_eq!(
            why("#1=1.\n#2=#1\nG01 X#2\nL#1"),
            ["#1 is used both as a length and as something else (line 2)"]
        );
        assert_eq!(
            why("#1=1.\n#2=5"),
            [
                "#1 is assigned on line 1 but never read in this program, so nothing shows \
                 whether it is a length",
                "#2 is assigned on line 2 but never read in this program, so nothing shows \
                 whether it is a length"
            ]
        );
        assert_eq!(
            why("G01 X#24"),
            [
                "#24 is read as a length (line 1) but not set in this program: its value comes \
              from a caller or the control, in units this conversion does not change"
            ]
        );
        // a control's value copied into a local first is the same value (review 4, 4)
        for (copy, name) in [
            ("#1=#5003", "#5003"),
            ("#1=#2001", "#2001"),
            ("#1=#5021+2.", "#5021"),
        ] {
            assert_eq!(
                why(&format!("{copy}\nG0 X[#1+1.]")),
                [format!(
                    "{name} is read into the length #1 (line 1) but not set in this program: \
                     its value comes from a caller or the control, in units this conversion \
                     does not change"
                )]
            );
        }
        // through two copies, and not where the value read is set here
        assert_eq!(why("#2=#5003\n#1=#2\nG0 X#1").len(), 1);
        assert!(why("#3=5.\n#1=#3\nG0 X#1").is_empty());
        let (_, why) = linuxcnc_classes("#<a> = #5221\nG0 X#<a>\nM2");
        assert_eq!(why.len(), 1);
        assert!(
            why[0].1.starts_with("#5221 is read into the length #<a>"),
            "{why:?}"
        );
    }

    /// A FANUC or Haas system variable whose meaning is no length is none, set or read
    /// (audit 50, B6); read as a length it is refused; on another control it proves nothing.
    #[test]
    fn a_system_variable_that_holds_no_length_is_none() {
        let of = |control: Control, text: &str| {
            let mut a = analysis(&[]);
            a.control = control;
            a.lines(text.as_bytes(), 0, &macro_b()).unwrap();
            lists(&a.result())[0].2.clone()
        };
        for control in [Control::Fanuc, Control::Haas] {
            for text in ["#3000=1", "#3006=1", "#3901=#3901+1", "#3000=#4003"] {
                assert!(
                    of(control, text).is_empty(),
                    "{text}: {:?}",
                    of(control, text)
                );
            }
            assert_eq!(
                of(control, "G0 X#3901"),
                [(
                    "#3901".to_string(),
                    "#3901 is read as a length (line 1), but on this control it is a parts \
                     count, not a length"
                        .to_string()
                )]
            );
            assert_eq!(of(control, "#5221=10.").len(), 1);
        }
        assert_eq!(of(Control::Fanuc, "#4130=1"), []);
        assert_eq!(of(Control::Haas, "#4130=1").len(), 1);
        assert_eq!(of(Control::Haas, "#3026=1"), []);
        assert_eq!(of(Control::Fanuc, "#3026=1").len(), 1);
        assert_eq!(of(Control::Iso, "#3000=1").len(), 1);
    }

    /// A word of a shape read before ([`Analysis::new_shape`]) adds nothing, but the same shape
    /// as a length and as something else, or in the next program, is read again: the proof
    /// names the first line of each use, as it does where every word is read.
    #[test]
    fn a_shape_read_before_is_read_again_where_its_reading_differs() {
        assert_eq!(
            why("#1=1.\nG01 X[#1*2.]\nG01 X[#1*3.5]\nS[#1*4.]\nS[#1*5.]"),
            ["#1 is read as a length (line 2) and as something else (line 4)"]
        );
        assert_eq!(
            why("#1=1.\nG01 Y[#1*3.]\nG01 X[SIN[#1]*4.]\nG01 X[SIN[#1]*5.]"),
            ["#1 is read in a non-linear expression on line 3, so its units cannot be converted"]
        );
        // #1 is each main program's own: the second program's words are read as its own
        let text = "O1\n#1=1.\nG01 X[#1*2.]\nM30\nO2\nG01 X[#1*3.]\nM30";
        let programs = classes(text);
        assert_eq!(programs[0].1, ["#1"]);
        assert_eq!(
            programs[1]
                .2
                .iter()
                .map(|(_, why)| why.as_str())
                .collect::<Vec<_>>(),
            [
                "#1 of the program beginning on line 5 is read as a length (line 6) but not set \
                 in this program: its value comes from a caller or the control, in units this \
                 conversion does not change"
            ]
        );
    }

    /// An expression the expression reader refuses shows no class: it is passed over (the
    /// converter refuses the word); a line that cannot be read is the analysis's error.
    #[test]
    fn sinumerik_conditions_tie_and_an_index_proves_nothing() {
        let sinumerik = Dialect {
            family: Family::Sinumerik,
            brackets: true,
            star: true,
            expressions: true,
            ..Dialect::default()
        };
        let read = |text: &[u8]| {
            let split = ProgramStarts::new(Family::Sinumerik, None);
            let mut a = Analysis::of([Role::Parameter; 3], split);
            a.lines(text, 0, &sinumerik).unwrap();
            lists(&a.result()).remove(0)
        };
        // the bound R1 is read nowhere but in the condition: tied with the counter R3, a
        // length, it is one (the label R2D2 after GOTOB is no parameter)
        for text in [
            &b"R1=50 R3=0
WHILE R3<=R1
G0 X=R3
R3=R3+5
ENDWHILE"[..],
            b"R1=50 R3=0
R2D2:
G0 X=R3
R3=R3+5
IF R3<R1 GOTOB R2D2",
            b"R1=50 R3=0
REPEAT
G0 X=R3
R3=R3+5
UNTIL R3>R1",
        ] {
            let (_, lengths, problems) = read(text);
            assert_eq!(
                (lengths, problems),
                (vec!["R1".into(), "R3".into()], vec![])
            );
        }
        // R[R1]= sets the parameter R1 holds the number of: none is proved
        let (_, lengths, problems) = read(
            b"R1=2 R3=10
G0 X=R1
R[R1]=R3
G1 X=R3",
        );
        assert!(lengths.is_empty());
        assert_eq!(
            problems.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(),
            ["R1", "R3"]
        );
        assert!(problems[0]
            .1
            .starts_with("line 3 sets a parameter chosen by a value"));
    }

    #[test]
    fn what_cannot_be_read() {
        let sinumerik = Dialect {
            family: Family::Sinumerik,
            star: true,
            expressions: true,
            ..Dialect::default()
        };
        let split = ProgramStarts::new(Family::Sinumerik, None);
        let mut a = Analysis::of([Role::Parameter; 3], split);
        let text = b"R1=5.\nX=R1+_Z_HOME\nY=R1\nR2=_Z_HOME\nZ=R2 S=R3*2\nR3=1000";
        a.lines(text, 0, &sinumerik).unwrap();
        let programs = lists(&a.result());
        // a SINUMERIK's expression is read by its own reader: a variable (_Z_HOME) makes it
        // non-linear, so R1, read by a length through it, is not proved (it was passed over,
        // and R1 taken for a length)
        assert_eq!(programs[0].1, ["R2"]);
        let why = "R1 is read in a non-linear expression on line 2, so its units cannot be \
                   converted";
        assert_eq!(programs[0].2, [("R1".to_string(), why.to_string())]);
        // round brackets group, and names are the same in either case (r1 is R1): R1 and R4
        // are read by lengths, R5 by a spindle speed; none is "never read"
        let mut a = Analysis::of(
            [Role::Parameter; 3],
            ProgramStarts::new(Family::Sinumerik, None),
        );
        let text = b"R1=10\nr4=2\nR5=100\nG1 X=r1+5 F100\nX4=(R1+5)*2 Y=(R4)\nS1=(r5+20)*2";
        a.lines(text, 0, &sinumerik).unwrap();
        let programs = lists(&a.result());
        assert_eq!(programs[0].1, ["R1", "R4"]);
        assert_eq!(programs[0].2, []);
        let mut a = analysis(&[]);
        let (line, text, error) = a.lines(b"G0 X1.\nG0 X#1 Y[#2", 4, &macro_b()).unwrap_err();
        assert_eq!((line, text), (6, &b"G0 X#1 Y[#2"[..]));
        assert_eq!((error.offset, error.clause), (11, "6.4.7"));
    }

    /// The backup's three programs, a folder marker or an O number after M30 or M99; an O word
    /// with no end before it, or a `%`, begins none; the split's state carries from one chunk
    /// to the next.
    #[test]
    fn the_file_is_split_where_the_converter_splits_it() {
        let backup = "%\n&F=/USER/PATH1/\nO0001(MAIN)\nG20 G90\nG0 X1. Y2.\nM30\n\
                      &F=/USER/PATH2/\nO9010(PROBE)\nG21 G91\nG1 X25.4 F100.\nM99\n\
                      O0003(FACE)\nG1 X50. F500.\nM30\n%";
        let starts = |a: Analysis| a.result().starts;
        assert_eq!(starts(analysis(&[(backup, 0)])), [0, 7, 12]);
        assert!(analysis(&[(backup, 0)]).returned);
        let chunks = [("O1\nM98 P2\nO5\nM99", 0), ("%\nO2\nG0 X1.", 4)];
        assert_eq!(starts(analysis(&chunks)), [0, 6]);
        let mut linuxcnc = Analysis::of(
            [Role::Parameter; 3],
            ProgramStarts::new(Family::LinuxCnc, None),
        );
        linuxcnc
            .lines(b"G0 X1.\nM30\nO2\nG0 X2.", 0, &macro_b())
            .unwrap();
        assert_eq!(starts(linuxcnc), [0]);
    }

    /// A local variable of each main program is its own; after a subprogram (M99) the
    /// programs share them; a common variable is the file's.
    #[test]
    fn locals_are_each_main_programs_own() {
        let locals = "%\nO0001\n#1=10.\nG01 X#1\nM30\nO0002\n#1=3\nM98 P1000 L#1\nM30\n%";
        assert_eq!(
            classes(locals),
            [
                (0, vec!["#1".into()], Vec::new()),
                (6, Vec::new(), Vec::new())
            ]
        );
        let sub = locals.replace("M30\nO0002", "M99\nO0002");
        let shared = "#1 is read as a length (line 4) and as something else (line 8)";
        for (_, lengths, problems) in classes(&sub) {
            assert!(lengths.is_empty());
            assert_eq!(problems, [("#1".to_string(), shared.to_string())]);
        }
        let common = locals.replace("#1", "#100");
        let programs = classes(&common);
        assert_eq!(programs[0].2, programs[1].2);
        assert!(programs[0].2[0]
            .1
            .starts_with("#100 is read as a length (line 4)"));
        // a message names a program's own local by its program
        let unset = "%\nO0001\nG01 X#1\nM30\nO0002\n#1=3\nM30\n%";
        let programs = classes(unset);
        assert!(programs[0].2[0]
            .1
            .starts_with("#1 of the file's first program is read"));
        assert!(programs[1].2[0]
            .1
            .starts_with("#1 of the program beginning on line 5 is assigned on line 6"));
    }

    /// The classes of a line's bytes, found in one pass, say what the searches for each kind
    /// of byte said (the marks of a program's start, `= # [`, a LinuxCNC `o` or `m`, a
    /// SINUMERIK `<` or `>`), on every family, with a split and without.
    #[test]
    fn a_line_is_read_for_the_same_bytes_as_the_searches_found() {
        let mut lines: Vec<Vec<u8>> = (0..=255u8).map(|c| vec![b'G', c, b'1']).collect();
        for text in [
            "N10 G1 X1.",
            "#1=2",
            "X[#1*2]",
            "o100 sub",
            "M30",
            "m2",
            "IF R1<R2 GOTOB L1",
            "UNTIL R3>R1",
            "O0002",
            "%_N_SUB_SPF",
            "&F",
            "<PROG>",
            "RET",
            "ret",
            "",
            "(o m)",
            "N20 TURN=0",
            "G01 X1. Y2. Z3. F100",
        ] {
            lines.push(text.as_bytes().to_vec());
        }
        for family in [
            Family::Iso,
            Family::MacroB,
            Family::LinuxCnc,
            Family::Sinumerik,
            Family::Okuma,
        ] {
            for number in [None, Some(b'O'), Some(b':')] {
                let split = ProgramStarts::new(family, number);
                let mut analysis = Analysis::of([Role::Other; 3], split);
                let classes = analysis.byte_classes(family);
                for text in &lines {
                    let found = line_classes(&classes, text);
                    let marked = analysis.split.as_ref().is_some_and(|s| s.marked(text));
                    let parameters = memchr::memchr3(b'=', b'#', b'[', text).is_some();
                    let linuxcnc = family == Family::LinuxCnc;
                    let read = parameters
                        || linuxcnc && memchr::memchr2(b'o', b'O', text).is_some()
                        || linuxcnc && memchr::memchr2(b'm', b'M', text).is_some()
                        || family == Family::Sinumerik
                            && memchr::memchr2(b'<', b'>', text).is_some();
                    let said = (
                        found & MARKED != 0,
                        found & PARAMETERS != 0,
                        found & !MARKED != 0,
                    );
                    assert_eq!(said, (marked, parameters, read), "{family:?} {text:?}");
                }
            }
        }
    }

    /// The shape of a line keeps what names something and the form of each number.
    #[test]
    fn a_line_shape_keeps_names_and_forms() {
        let shape = |text: &[u8]| {
            let mut out = Vec::new();
            line_shape(text, &mut out).then_some(out)
        };
        assert_eq!(
            shape(b"N9871Y[#<yscale>*24.458]Z[#<zscale>*-27.104]").unwrap(),
            b"N\x01Y[#<yscale>*\x01.\x01]Z[#<zscale>*-\x01.\x01]"
        );
        // parameters' numbers, spaced digits, indexes, codes and P Q R as written
        assert_eq!(
            shape(b"G1 X#12 Y-.5 R2 #1 2=3. X0=1").unwrap(),
            b"G1 X#12 Y-.\x01 R2 #1 2=3. X0=1"
        );
        // an M or an O outside a name, a comment, a `%`, a name with a blank: no shape
        for text in [
            &b"G1 X#1 M30"[..],
            b"o100 call [#1]",
            b"G1 X#1 (a)",
            b"%",
            b"#< zs > = 1",
            b"G1 X[#<a",
            b"#1=1;",
        ] {
            assert_eq!(shape(text), None, "{}", String::from_utf8_lossy(text));
        }
        assert!(shape(b"#<xmax>=[#<ox>*2]").is_some());
        // a line the tokenizer refuses for its length alone
        let long = [&b"G1 X#1 Y"[..], &[b'1'; crate::tokenizer::MAX_BLOCK]].concat();
        assert_eq!(shape(&long), None);
        assert!(shape(&long[..crate::tokenizer::MAX_BLOCK]).is_some());
    }

    /// Passing over a line of a shape read before ([`Analysis::known_line`]) changes no class,
    /// no reason and no line a reason names: each program of Custom Macro B and LinuxCNC
    /// lines (parameters named and numbered, spaced digits, indexes, conditions, program
    /// splits and subroutines, non-linear uses), read with the shapes and line by line.
    #[test]
    fn lines_passed_over_by_shape_read_as_every_line_does() {
        let macro_lines = [
            "#1=10.",
            "#2=#1*2+5.",
            "G01 X[#2-#1/4] Y#2 F#3",
            "#3=100.",
            "S#4",
            "#4=1000",
            "G01 X[#1*2.5] Y[#2*-3.]",
            "G01 X[#1*7.25] Y[#2*-1.5]",
            "G01 X[#5*2.5] Y[#2*-3.]",
            "#5=3.",
            "#6=#1*#5",
            "G01 Z[#6*2.]",
            "G01 Z[#6*4.]",
            "IF [#1 GT 2] THEN #7=1",
            "G01 X#7",
            "M98 P100 L#8",
            "G01 X[#8*3.]",
            "G01 X#1 2",
            "G01 X#1 3",
            "#2=#1*5",
            "#2=#1*6",
            "G01 X[SIN[#9]*3.]",
            "G01 X[SIN[#9]*4.]",
            "#9=1.",
            "G01 R[#10*2.]",
            "G01 R[#10*3.]",
            "#10=2",
            "M30",
            "O2",
            "G01 X[#1*3.]",
            "M99",
            "O3",
            "G01 X[#1*4.]",
            "G01 X[#1*5.]",
            "#1=2.",
            "M30",
        ];
        let linuxcnc_lines = [
            "#<xs> = 1.0",
            "#<ys>=2.",
            "N10G1X[#<xs>*53.]Y[#<ys>*-56.128]",
            "N20G1X[#<xs>*52.]Y[#<ys>*-55.1]",
            "N30G1X[#<ys>*52.]Y[#<xs>*-55.1]",
            "N40G1X[#<zs>*1.]",
            "N50G1X[#<zs>*2.]",
            "#<zs>=#<xs>*#<ys>",
            "o<s> sub",
            "G1 X[#1*2.]",
            "G1 X[#1*3.]",
            "#1=5",
            "o<s> endsub",
            "G1 X[#1*4.]",
            "o<s> call [2.]",
            "G1 F[#<fs>*100]",
            "G1 F[#<fs>*225]",
            "S[#<fs>*3]",
            "#<fs>=10000.0",
            "#5=1",
            "G1 X#5",
            "G1 X#6",
            "#6=1",
            "M2",
        ];
        let macro_dialect = macro_b();
        let linuxcnc_dialect = Dialect::permissive(Family::LinuxCnc);
        let runs: [(&[&str], Family, &Dialect, Option<u8>); 2] = [
            (&macro_lines, Family::MacroB, &macro_dialect, Some(b'O')),
            (&linuxcnc_lines, Family::LinuxCnc, &linuxcnc_dialect, None),
        ];
        for (lines, family, dialect, number) in runs {
            // the lines in many orders: each first line of a shape is another line
            let mut kept = 0;
            for seed in 0..60u64 {
                let mut order: Vec<&str> = lines.to_vec();
                let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
                for i in (1..order.len() - 1).rev() {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    order.swap(i, (x % i as u64) as usize);
                }
                let text = order.join("\n");
                let read = |cap: usize| {
                    let mut a =
                        Analysis::of([Role::Parameter; 3], ProgramStarts::new(family, number));
                    a.lines_cap = cap;
                    let read = a.lines(text.as_bytes(), 0, dialect).map_err(|e| e.0);
                    (read, lists(&a.result()), a.lines_read.len())
                };
                let (by_shape, every_line) = (read(4096), read(0));
                assert_eq!(by_shape.0, every_line.0, "{text}");
                assert_eq!(by_shape.1, every_line.1, "{text}");
                assert_eq!(every_line.2, 0);
                kept += by_shape.2;
            }
            assert!(kept > 0);
        }
    }

    fn linuxcnc_classes(text: &str) -> (Vec<String>, Vec<(String, String)>) {
        let dialect = Dialect::permissive(Family::LinuxCnc);
        let split = ProgramStarts::new(Family::LinuxCnc, None);
        let mut a = Analysis::of([Role::Parameter; 3], split);
        a.lines(text.as_bytes(), 0, &dialect).unwrap();
        let classes = a.result();
        assert_eq!(classes.starts, [0]);
        classes.lists(0)
    }

    /// A LinuxCNC named parameter set in the program is an assignment as `#1 = ...` is: its
    /// class passes to what it reads, by its name without blanks and in lower case.
    #[test]
    fn a_named_parameter_set_in_the_program_is_an_assignment() {
        let text = "#1 = 2.5\n#<ZS> = 1.0\n#<y> = #< zs > * 2 + 1\nG1 X#1 Y[#<Y>*10.] F100";
        assert_eq!(
            linuxcnc_classes(text),
            (vec!["#1".into(), "#<y>".into(), "#<zs>".into()], Vec::new())
        );
        let (lengths, why) = linuxcnc_classes("#<n> = 3\n#<d> = 1\nG1 X[#<d>*#<n>]\nM98 L#<n>");
        assert!(lengths.is_empty());
        assert_eq!(
            why.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(),
            ["#<d>", "#<n>"]
        );
        let (_, why) = linuxcnc_classes("#<a> = 1\n#<b> = SIN[#<a>]\nG1 X#<b>\n#<c> = 2");
        assert_eq!(
            why,
            [
                (
                    "#<a>".into(),
                    "#<a> feeds the length #<b> through a non-linear expression on line 2".into()
                ),
                (
                    "#<c>".into(),
                    "#<c> is assigned on line 4 but never read in this program, so nothing \
                     shows whether it is a length"
                        .into()
                )
            ]
        );
    }

    /// A local named parameter and #1-#30 of an `o<name> sub` are the subroutine's own
    /// (listed as `name@line`); a global `#<_name>` and #31 are the file's. A line read only
    /// for an o-word, that cannot be read, is passed over (the conversion refuses it there).
    #[test]
    fn a_subroutine_has_its_own_local_parameters() {
        let (lengths, why) = linuxcnc_classes("o<s> frob\n#1 = 2\nG1 X#1");
        assert_eq!((lengths, why), (vec!["#1".into()], Vec::new()));
        let text = "#<a> = 5\n#<_g> = 7\n#31 = 1\no<s> sub\n#<a> = 3\n#1 = 2\n\
                    G1 X#<a> Y#<_g> Z#31 F100\nM98 L#1\no<s> endsub\nG1 X#<a>\nM2";
        assert_eq!(
            linuxcnc_classes(text),
            (
                vec!["#31".into(), "#<_g>".into(), "#<a>".into(), "#<a>@4".into()],
                Vec::new()
            )
        );
        let (lengths, why) =
            linuxcnc_classes("o100 sub\nG1 X#1 Y#<d>\no100 endsub\n#1 = 2\n#<d> = 1");
        assert!(lengths.is_empty());
        assert_eq!(
            why[0],
            (
                "#1".into(),
                "#1 is assigned on line 4 but never read in this program, so nothing shows \
                 whether it is a length"
                    .into()
            )
        );
        assert_eq!(
            why.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(),
            ["#1", "#1@1", "#<d>", "#<d>@1"]
        );
        assert_eq!(
            why[3],
            (
                "#<d>@1".into(),
                "#<d> of the subroutine beginning on line 1 is read as a length (line 2) but \
                 not set in this program: its value comes from a caller or the control, in \
                 units this conversion does not change"
                    .into()
            )
        );
    }

    /// The parameters an o-word's condition compares share a class (a loop's counter, read
    /// nowhere else, is no length); a call's arguments set the called subroutine's #1, #2...,
    /// wherever it is defined in the file.
    #[test]
    fn statements_read_and_calls_pass_parameters() {
        let text = "#<a> = 2\no100 if [#<a> GT 0]\nG1 X#<a> F100\no100 endif\nM2";
        assert_eq!(linuxcnc_classes(text), (vec!["#<a>".into()], Vec::new()));
        let text = "#<a> = 2\n#<b> = 2\n#<n> = 3\no100 if [#<a> GT #<n>]\nG1 X#<a> F100\n\
                    o100 endif\no101 if [#<a> LT #<b>]\no101 endif\nS#<n>\nM2";
        let (lengths, why) = linuxcnc_classes(text);
        assert_eq!(lengths, ["#<b>"]);
        let compared = |name: &str| {
            (
                name.to_string(),
                format!(
                    "{name} is compared on line 4 with a parameter of another class (a length \
                     and something else)"
                ),
            )
        };
        assert_eq!(why, [compared("#<a>"), compared("#<n>")]);
        let text = "#<n> = 3\no1 while [#<n> GT 0]\n#<n> = [#<n> - 1]\no1 endwhile\nM2";
        assert_eq!(linuxcnc_classes(text), (Vec::new(), Vec::new()));
        // the argument is a length where the subroutine reads its #1 as one, before or after
        let text = "o<s> sub\nG1 X#1 F100\no<s> endsub\n#<d> = 2.5\no<s> call [#<d> * 2]\nM2";
        assert_eq!(
            linuxcnc_classes(text),
            (vec!["#1@1".into(), "#<d>".into()], Vec::new())
        );
        let text = "#<d> = 2.5\nO <S> call [#<d>]\no<s> sub\nG1 X#1 F100\no<s> endsub\nM2";
        assert_eq!(
            linuxcnc_classes(text),
            (vec!["#1@3".into(), "#<d>".into()], Vec::new())
        );
        let text = "#<n> = 4\no<s> call [#<n>]\no<s> sub\nS#1\no<s> endsub\nG1 X#<n>\nM2";
        let (lengths, why) = linuxcnc_classes(text);
        assert_eq!(lengths, Vec::<String>::new());
        assert_eq!(
            why.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(),
            ["#<n>"]
        );
        // a subroutine of another file
        let (_, why) = linuxcnc_classes("#<d> = 2.5\nG1 X#<d> F100\nO<far> call [#<d>]\nM2");
        assert_eq!(
            why,
            [(
                "#<d>".into(),
                "#<d> is passed on line 3 to o<far>, a subroutine not defined in this file: how \
                 it reads the value is not known here"
                    .into()
            )]
        );
    }

    /// A parameter chosen by a value may be any: no class is proved, and each says why.
    #[test]
    fn an_indirect_reference_proves_no_class() {
        for (text, how) in [
            ("#1 = 2\n#[#1] = 5\nG1 X#2 F100\nM2", "line 2 sets"),
            ("#1 = 2\n##1 = 5\nG1 X#2 F100\nM2", "line 2 sets"),
            ("#1 = 2\n#2 = 5\nG1 X##1 F100\nM2", "line 3 reads"),
        ] {
            let (lengths, why) = linuxcnc_classes(text);
            assert!(lengths.is_empty(), "{text}");
            assert_eq!(
                why.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(),
                ["#1", "#2"],
                "{text}"
            );
            assert!(why[1].1.starts_with(how), "{text}: {why:?}");
            assert!(
                why[1].1.ends_with("so the class of #2 cannot be proved"),
                "{text}: {why:?}"
            );
        }
        let programs = classes("#1=2\n#[#1+100]=5\nG01 X#102");
        assert!(programs[0].1.is_empty());
        assert_eq!(programs[0].2.len(), 2);
    }

    /// Custom Macro B: the assignment after `IF [..] THEN` is one; a condition's parameters
    /// share a class.
    #[test]
    fn macro_b_conditions_and_their_assignments() {
        assert_eq!(
            classes("#1=2.\nIF [#2 GT 0] THEN #3=#1+1.\nG01 X#3\n#2=1\nG65 P10 A#2")[0].1,
            ["#1", "#3"]
        );
        assert_eq!(
            classes("#1=2.\n#2=#1\nIF [#1 EQ #2] GOTO 10\nG01 X#1\nN10 M30")[0].1,
            ["#1", "#2"]
        );
        let compared = |name: &str| {
            format!(
                "{name} is compared on line 3 with a parameter of another class (a length and \
                 something else)"
            )
        };
        assert_eq!(
            why("#1=2.\n#2=3\nWHILE [#1 LT #2] DO1\nEND1\nG01 X#1\nS#2"),
            [compared("#1"), compared("#2")]
        );
    }
    #[test]
    fn locals_by_number() {
        for (name, local) in [
            ("#1", true),
            ("#033", true),
            ("#34", false),
            ("#0", false),
            ("#00", false),
            ("#100", false),
            ("# 1", false),
            ("#<a>", false),
            ("#999999999999999999999999", false),
            ("R1", false),
        ] {
            assert_eq!(is_local(name.as_bytes()), local, "{name}");
        }
    }
}
