//! The check's findings as its reports print them: text, JSON and JSON Lines.
//!
//! A finding is appended to a byte buffer exactly as `postproc.report` lays out its document
//! (the document's head, its end and the statistics stay in Python: they are written once per
//! run, a finding up to millions of times):
//!
//! - text: `file:line:column: severity rule message [clause]` and a newline, as
//!   `str(Finding)` prints it;
//! - JSON: `,\n` then the finding's object as `json.dumps(document, indent=2)` prints it four
//!   spaces deep in the `findings` array -- every finding preceded by the `,\n` that separates
//!   it from the one before; the report drops it before the document's first;
//! - JSON Lines: the finding's object on one line, as `json.dumps(finding)` prints it.
//!
//! A writer made [`Writer::folded`] (the text report of `tapegate check` without `--all`) folds
//! a file's repeated findings: of each rule's warnings or notes it writes the first [`SHOWN`],
//! and at the file's end ([`Writer::end`]) one line for the rest, at the place of the first it
//! left out: `file:line:column: severity rule N more like this on lines A-B (--all shows
//! each)`. A rule about a code ([`Rule::about_a_code`]: `M160 is not in the profile's M code
//! list`) is folded per rule and per the code each finding names, its fold line naming it
//! (`N more like this (M160) on lines ...`), so that every code is shown. Errors are all
//! written. A rule's fold is three counts (and a code's name), so the report's memory stays
//! flat; JSON and JSON Lines, for programs, are never folded.
//!
//! Strings are written as `json.dumps` writes them by default (`ensure_ascii`): `"` and `\`
//! escaped, `\b \f \n \r \t` by their short escapes, every other character outside the
//! printable ASCII range as `\u` and four lowercase hex digits of its UTF-16 code units (a
//! character beyond U+FFFF as its surrogate pair). A file name is taken as UTF-16 code units, so
//! a Python string's lone surrogates (a name that is not UTF-8, decoded with `surrogateescape`)
//! are written as Python writes them.

use std::sync::OnceLock;

use crate::check::Finding;
use crate::rules::{Rule, Severity};

/// Which report.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Text,
    Json,
    JsonLines,
}

impl Format {
    /// The format by its `--format` name: `text`, `json` or `jsonl`.
    pub fn from_name(name: &str) -> Option<Format> {
        match name {
            "text" => Some(Format::Text),
            "json" => Some(Format::Json),
            "jsonl" => Some(Format::JsonLines),
            _ => None,
        }
    }

    /// A string field as this format writes it: quoted and escaped for JSON, as it is for text.
    pub fn field(self, out: &mut Vec<u8>, text: &str) {
        match self {
            Format::Text => out.extend_from_slice(text.as_bytes()),
            Format::Json | Format::JsonLines => json_str(out, text),
        }
    }

    /// A string field given as UTF-16 code units (lone surrogates allowed): JSON as
    /// [`Format::field`]; text as UTF-8 with a lone surrogate in the three bytes Python's
    /// `surrogatepass` error handler gives it (decoded back the same way).
    pub fn field_units(self, out: &mut Vec<u8>, units: &[u16]) {
        match self {
            Format::Text => wtf8(out, units),
            Format::Json | Format::JsonLines => json_units(out, units),
        }
    }
}

/// A byte that a JSON string holds as it is (printable ASCII but the quote and the backslash).
fn plain(b: u8) -> bool {
    (b' '..=b'~').contains(&b) && b != b'"' && b != b'\\'
}

/// Whether any of the 8 bytes of `w` is not [`plain`] (the bit tricks of "Bit Twiddling
/// Hacks", Determine if a word has a byte less than / greater than n, and a zero byte: each
/// exact about whether there is one, which is all this asks).
fn any_special(w: u64) -> bool {
    const LO: u64 = u64::from_ne_bytes([1; 8]);
    const HI: u64 = LO * 0x80;
    let zero = |v: u64| v.wrapping_sub(LO) & !v & HI;
    let control = w.wrapping_sub(LO * 0x20) & !w & HI; // a byte below ' '
    let high = (w.wrapping_add(LO) | w) & HI; // a byte above '~'
    (control | high | zero(w ^ (LO * u64::from(b'"'))) | zero(w ^ (LO * u64::from(b'\\')))) != 0
}

/// The length of the run of [`plain`] bytes `bytes` starts with, 8 bytes at a time.
fn plain_run(bytes: &[u8]) -> usize {
    let mut at = 0;
    while let Some(word) = bytes.get(at..at + 8) {
        if any_special(u64::from_ne_bytes(word.try_into().expect("8 bytes"))) {
            break;
        }
        at += 8;
    }
    at + bytes[at..]
        .iter()
        .position(|&b| !plain(b))
        .unwrap_or(bytes.len() - at)
}

const HEX: &[u8; 16] = b"0123456789abcdef";

/// One UTF-16 code unit inside a JSON string.
fn escape_unit(out: &mut Vec<u8>, unit: u16) {
    let short = match unit {
        0x22 => b'"',
        0x5c => b'\\',
        0x08 => b'b',
        0x0c => b'f',
        0x0a => b'n',
        0x0d => b'r',
        0x09 => b't',
        u if u < 0x80 && plain(u as u8) => {
            out.push(u as u8);
            return;
        }
        u => {
            out.extend_from_slice(&[
                b'\\',
                b'u',
                HEX[usize::from(u >> 12)],
                HEX[usize::from(u >> 8 & 0xf)],
                HEX[usize::from(u >> 4 & 0xf)],
                HEX[usize::from(u & 0xf)],
            ]);
            return;
        }
    };
    out.extend_from_slice(&[b'\\', short]);
}

/// `text` as a JSON string, quotes included, as `json.dumps` writes it.
pub fn json_str(out: &mut Vec<u8>, text: &str) {
    out.push(b'"');
    let mut rest = text;
    loop {
        // the plain run copied at once: most of a message is plain ASCII
        let run = plain_run(rest.as_bytes());
        out.extend_from_slice(&rest.as_bytes()[..run]);
        rest = &rest[run..];
        let Some(c) = rest.chars().next() else { break };
        let mut units = [0u16; 2];
        for &unit in c.encode_utf16(&mut units).iter() {
            escape_unit(out, unit);
        }
        rest = &rest[c.len_utf8()..];
    }
    out.push(b'"');
}

/// UTF-16 code units as a JSON string, quotes included (a lone surrogate as its `\u` escape,
/// as `json.dumps` writes a Python string's).
pub fn json_units(out: &mut Vec<u8>, units: &[u16]) {
    out.push(b'"');
    for &unit in units {
        escape_unit(out, unit);
    }
    out.push(b'"');
}

/// UTF-16 code units as UTF-8, a lone surrogate as three bytes (Python's `surrogatepass`).
pub fn wtf8(out: &mut Vec<u8>, units: &[u16]) {
    for c in char::decode_utf16(units.iter().copied()) {
        match c {
            Ok(c) => out.extend_from_slice(c.encode_utf8(&mut [0; 4]).as_bytes()),
            Err(lone) => {
                let u = lone.unpaired_surrogate();
                out.extend_from_slice(&[
                    0xe0 | (u >> 12) as u8,
                    0x80 | (u >> 6 & 0x3f) as u8,
                    0x80 | (u & 0x3f) as u8,
                ]);
            }
        }
    }
}

/// A count in decimal, as Python's `int.__str__`.
fn number(out: &mut Vec<u8>, mut n: usize) {
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    loop {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&digits[at..]);
}

/// The fields of a finding, each already as `format` writes it ([`Format::field`]) but the
/// message, which `message` appends (escaped for JSON) and the line and column.
pub struct Fields<'a> {
    pub rule: &'a [u8],
    pub severity: &'a [u8],
    pub file: &'a [u8],
    pub line: usize,
    pub column: usize,
    pub clause: &'a [u8],
}

/// Append one finding to `out` in `format` (see the module's documentation).
pub fn write(
    format: Format,
    out: &mut Vec<u8>,
    f: &Fields<'_>,
    message: impl FnOnce(&mut Vec<u8>),
) {
    match format {
        Format::Text => {
            out.extend_from_slice(f.file);
            out.push(b':');
            number(out, f.line);
            out.push(b':');
            number(out, f.column);
            out.extend_from_slice(b": ");
            out.extend_from_slice(f.severity);
            out.push(b' ');
            out.extend_from_slice(f.rule);
            out.push(b' ');
            message(out);
            out.extend_from_slice(b" [");
            out.extend_from_slice(f.clause);
            out.extend_from_slice(b"]\n");
        }
        Format::Json | Format::JsonLines => {
            // the same members, laid out as json.dumps writes them: indented in the document,
            // on one line in JSON Lines
            let (open, next, close): (&[u8], &[u8], &[u8]) = if format == Format::Json {
                (b",\n    {\n      ", b",\n      ", b"\n    }")
            } else {
                (b"{", b", ", b"}\n")
            };
            out.extend_from_slice(open);
            out.extend_from_slice(b"\"rule\": ");
            out.extend_from_slice(f.rule);
            out.extend_from_slice(next);
            out.extend_from_slice(b"\"severity\": ");
            out.extend_from_slice(f.severity);
            out.extend_from_slice(next);
            out.extend_from_slice(b"\"message\": ");
            message(out);
            out.extend_from_slice(next);
            out.extend_from_slice(b"\"file\": ");
            out.extend_from_slice(f.file);
            out.extend_from_slice(next);
            out.extend_from_slice(b"\"line\": ");
            number(out, f.line);
            out.extend_from_slice(next);
            out.extend_from_slice(b"\"column\": ");
            number(out, f.column);
            out.extend_from_slice(next);
            out.extend_from_slice(b"\"clause\": ");
            out.extend_from_slice(f.clause);
            out.extend_from_slice(close);
        }
    }
}

/// How many warnings or notes of one rule a folded text report ([`Writer::folded`]) writes of
/// a file, one by one: enough to show what the rule finds, where, and that it repeats (clang's
/// `-ferror-limit` is 20 in all; this is per rule, so one rule does not hide the others).
pub const SHOWN: usize = 5;

/// One rule's findings in a file, as a folded report counts them.
#[derive(Debug, Clone, Copy, Default)]
struct Folded {
    /// The findings of the rule so far.
    seen: usize,
    /// The line and column of the first not written.
    line: usize,
    column: usize,
    /// The lowest and highest line of those not written.
    low: usize,
    high: usize,
    /// The rule is about a code ([`Rule::about_a_code`]): its counts are
    /// `subjects`' (by the code each finding names), these stay 0.
    by_code: bool,
}

/// Each rule's bytes before a finding's message and after it in `format` ([`Writer`]'s
/// `rules`): made once a process for each format, not once a file. They name no file, and a
/// writer is made for every file of a batch: made a writer at a time, they were 250,000
/// instructions a file (267 JSON strings and 180 joins), a quarter of what `check -j` did per
/// file with the GIL held (docs/benchmarks.md, "the GIL or the caches").
fn rule_pieces(format: Format) -> &'static [[Vec<u8>; 2]] {
    static PIECES: [OnceLock<Vec<[Vec<u8>; 2]>>; 3] = [const { OnceLock::new() }; 3];
    let index = match format {
        Format::Text => 0,
        Format::Json => 1,
        Format::JsonLines => 2,
    };
    PIECES[index].get_or_init(|| {
        let field = |text: &str| {
            let mut field = Vec::new();
            format.field(&mut field, text);
            field
        };
        let (open, next, close): (&[u8], &[u8], &[u8]) = match format {
            Format::Json => (b",\n    {\n      ", b",\n      ", b"\n    }"),
            Format::JsonLines | Format::Text => (b"{", b", ", b"}\n"),
        };
        Rule::ALL
            .iter()
            .map(|rule| {
                let [id, severity, clause] =
                    [rule.id(), rule.severity().name(), rule.clause()].map(field);
                match format {
                    Format::Text => [
                        [&b": "[..], &severity, b" ", &id, b" "].concat(),
                        [&b" ["[..], &clause, b"]\n"].concat(),
                    ],
                    Format::Json | Format::JsonLines => [
                        [
                            open,
                            b"\"rule\": ",
                            &id,
                            next,
                            b"\"severity\": ",
                            &severity,
                            next,
                            b"\"message\": ",
                        ]
                        .concat(),
                        [next, b"\"clause\": ", &clause, close].concat(),
                    ],
                }
            })
            .collect()
    })
}

/// The report of one file's findings: the file's name and every rule's ID, severity and clause
/// written once, as the format writes them, and laid out as [`write`] lays them out around a
/// finding's message, line and column -- a finding is then those pieces, its message and its
/// two numbers (where `write`'s two dozen pieces a finding cost about 800 instructions, each
/// variable one a `memcpy` call).
pub struct Writer {
    format: Format,
    file: Vec<u8>,
    /// Each rule's bytes before a finding's message and after it: JSON, the members up to the
    /// message's value, and from the clause on; text, from the column's colon up to the
    /// message, and the clause ([`rule_pieces`]: one table a format, shared by every writer).
    rules: &'static [[Vec<u8>; 2]],
    /// The bytes before the line number: JSON, from the message's comma through the file's
    /// member to the line's name; text, the file's name and its colon.
    before_line: Vec<u8>,
    /// The bytes between the line number and the column number.
    between: Vec<u8>,
    /// A folded report's counts, by [`Rule::index`] ([`Writer::folded`]); empty when every
    /// finding is written.
    fold: Vec<Folded>,
    /// The counts of a rule about a code ([`Rule::about_a_code`]), by rule and the code its
    /// finding names ([`crate::rules::subject`]), in the order met: a file names a few codes,
    /// so they are looked up one by one, with no allocation a finding (a hash map's key
    /// cost about 1,000 instructions a finding).
    subjects: Vec<(Rule, String, Folded)>,
}

impl Writer {
    /// A writer for the findings of the file named `file` (UTF-16 code units, as
    /// [`Format::field_units`] takes them).
    pub fn new(format: Format, file: &[u16]) -> Writer {
        let mut name = Vec::new();
        format.field_units(&mut name, file);
        let rules = rule_pieces(format);
        let next: &[u8] = match format {
            Format::Json => b",\n      ",
            Format::JsonLines | Format::Text => b", ",
        };
        let (before_line, between) = match format {
            Format::Text => ([&name[..], b":"].concat(), b":".to_vec()),
            Format::Json | Format::JsonLines => (
                [next, b"\"file\": ", &name, next, b"\"line\": "].concat(),
                [next, b"\"column\": "].concat(),
            ),
        };
        Writer {
            format,
            file: name,
            rules,
            before_line,
            between,
            fold: Vec::new(),
            subjects: Vec::new(),
        }
    }

    /// This writer folding each rule's warnings and notes past the first [`SHOWN`] of the file
    /// into one line, written by [`Writer::end`]: a text report's (`check` without `--all`);
    /// a JSON or JSON Lines writer is returned as it is, writing every finding.
    pub fn folded(mut self) -> Writer {
        if self.format == Format::Text {
            self.fold = (Rule::ALL.iter())
                .map(|rule| Folded {
                    by_code: rule.about_a_code(),
                    ..Folded::default()
                })
                .collect();
        }
        self
    }

    pub fn format(&self) -> Format {
        self.format
    }

    /// The file's name as the format writes it.
    pub fn file(&self) -> &[u8] {
        &self.file
    }

    /// Whether a finding of `rule` at `line` and `column` with `message` is written: always,
    /// but by a folded writer a warning or note past the first [`SHOWN`] of its rule -- of its
    /// rule and the code it names, for a rule about a code ([`Rule::about_a_code`]: each code
    /// is shown) --, which is counted for [`Writer::end`] instead. Errors are always written:
    /// each is a reason the program is refused.
    #[inline]
    pub fn shown(&mut self, rule: Rule, line: usize, column: usize, message: &str) -> bool {
        let Some(&Folded { by_code, .. }) = self.fold.get(rule.index()) else {
            return true;
        };
        if rule.severity() == Severity::Error {
            return true;
        }
        let folded = if by_code {
            self.code_folded(rule, message)
        } else {
            &mut self.fold[rule.index()]
        };
        folded.seen += 1;
        if folded.seen <= SHOWN {
            return true;
        }
        if folded.seen == SHOWN + 1 {
            (folded.line, folded.column, folded.low, folded.high) = (line, column, line, line);
        } else {
            folded.low = folded.low.min(line);
            folded.high = folded.high.max(line);
        }
        false
    }

    /// The counts of `rule`'s findings that name what `message` names (a rule about a code).
    #[inline(never)]
    fn code_folded(&mut self, rule: Rule, message: &str) -> &mut Folded {
        let subject = crate::rules::subject(message);
        let known = (self.subjects.iter()).position(|(r, s, _)| *r == rule && s == subject);
        let at = known.unwrap_or_else(|| {
            (self.subjects).push((rule, subject.to_string(), Folded::default()));
            self.subjects.len() - 1
        });
        &mut self.subjects[at].2
    }

    /// The end of the file's findings: for a folded writer, a line for each rule with findings
    /// not written, in the order of their places (the first one's line and column), appended
    /// to `out`, and the counts begun again (a finding after this is folded anew).
    pub fn end(&mut self, out: &mut Vec<u8>) {
        // (rule, then the code's place among the rule's about a code: usize::MAX for none)
        let mut folds: Vec<(usize, usize, usize, usize)> = (self.fold.iter().enumerate())
            .filter(|(_, f)| f.seen > SHOWN)
            .map(|(i, f)| (f.line, f.column, i, usize::MAX))
            .chain(
                (self.subjects.iter().enumerate())
                    .filter(|(_, (_, _, f))| f.seen > SHOWN)
                    .map(|(k, (rule, _, f))| (f.line, f.column, rule.index(), k)),
            )
            .collect();
        folds.sort_unstable();
        for (line, column, i, k) in folds {
            let (
                Folded {
                    seen, low, high, ..
                },
                subject,
            ) = match self.subjects.get(k) {
                Some((_, subject, folded)) => (*folded, Some(subject.as_str())),
                None => (self.fold[i], None),
            };
            out.extend_from_slice(&self.before_line);
            number(out, line);
            out.extend_from_slice(&self.between);
            number(out, column);
            out.extend_from_slice(&self.rules[i][0]);
            let more = seen - SHOWN;
            number(out, more);
            out.extend_from_slice(b" more like this");
            if let Some(subject) = subject {
                // (the code each of them names: the text report's own bytes, as the message's)
                out.extend_from_slice(b" (");
                out.extend_from_slice(subject.as_bytes());
                out.push(b')');
            }
            out.extend_from_slice(b" on line");
            if high > low {
                out.extend_from_slice(b"s ");
                number(out, low);
                out.push(b'-');
                number(out, high);
            } else {
                out.push(b' ');
                number(out, low);
            }
            out.extend_from_slice(if more == 1 {
                b" (--all shows it)\n"
            } else {
                b" (--all shows each)\n"
            });
        }
        for folded in &mut self.fold {
            *folded = Folded {
                by_code: folded.by_code,
                ..Folded::default()
            };
        }
        self.subjects.clear();
    }

    /// Append `finding` to `out`: the bytes [`write`] appends (a test holds the two equal),
    /// unless a folded writer leaves it out ([`Writer::shown`]).
    pub fn finding(&mut self, out: &mut Vec<u8>, finding: &Finding) {
        if !self.fold.is_empty()
            && !self.shown(finding.rule, finding.line, finding.column, &finding.message)
        {
            return;
        }
        let [head, tail] = &self.rules[finding.rule.index()];
        let numbers = |out: &mut Vec<u8>| {
            out.extend_from_slice(&self.before_line);
            number(out, finding.line);
            out.extend_from_slice(&self.between);
            number(out, finding.column);
        };
        match self.format {
            Format::Text => {
                numbers(out);
                out.extend_from_slice(head);
                out.extend_from_slice(finding.message.as_bytes());
                out.extend_from_slice(tail);
            }
            Format::Json | Format::JsonLines => {
                out.extend_from_slice(head);
                json_str(out, &finding.message);
                numbers(out);
                out.extend_from_slice(tail);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn json(text: &str) -> String {
        let mut out = Vec::new();
        json_str(&mut out, text);
        String::from_utf8(out).unwrap()
    }

    /// A writer's finding is the bytes `write` lays out of its fields, in each format, for
    /// every rule, of files whose names need escaping (a quote, a backslash, a character
    /// outside ASCII, a lone surrogate), at lines and columns of one digit and many, with
    /// messages plain and escaped.
    #[test]
    fn a_writer_s_finding_is_what_write_lays_out() {
        let names: [Vec<u16>; 3] = [
            "prog.nc".encode_utf16().collect(),
            "dir\\\"Ø\" 1.nc".encode_utf16().collect(),
            vec![0x61, 0xdc80, 0x2e, 0x6e, 0x63],
        ];
        let messages = ["a plain message", "\"quoted\" \\ tab\t é \u{1f600}", ""];
        for format in [Format::Text, Format::Json, Format::JsonLines] {
            for name in &names {
                let mut writer = Writer::new(format, name);
                let mut file = Vec::new();
                format.field_units(&mut file, name);
                assert_eq!(writer.file(), &file[..]);
                for &rule in Rule::ALL.iter() {
                    let field = |text: &str| {
                        let mut field = Vec::new();
                        format.field(&mut field, text);
                        field
                    };
                    let (id, severity, clause) = (
                        field(rule.id()),
                        field(rule.severity().name()),
                        field(rule.clause()),
                    );
                    for (line, column) in [(1, 1), (9, 10), (123_456, 0)] {
                        for message in messages {
                            let fields = Fields {
                                rule: &id,
                                severity: &severity,
                                file: &file,
                                line,
                                column,
                                clause: &clause,
                            };
                            let mut expected = b"before".to_vec();
                            write(format, &mut expected, &fields, |out| {
                                format.field(out, message)
                            });
                            let mut written = b"before".to_vec();
                            let finding = Finding {
                                rule,
                                message: message.to_string(),
                                line,
                                column,
                                span: false,
                                guessed: false,
                                placed: crate::check::Placed::Not,
                                pending_on: Vec::new(),
                            };
                            writer.finding(&mut written, &finding);
                            assert_eq!(
                                String::from_utf8_lossy(&written),
                                String::from_utf8_lossy(&expected),
                                "{format:?} {rule:?}"
                            );
                            assert_eq!(written, expected);
                        }
                    }
                }
            }
        }
    }

    /// A folded text writer writes the first `SHOWN` warnings and notes of each rule and
    /// every error; at the end, one line a rule for the rest, at the first left out, in the
    /// order of those places; a JSON writer, or one not folded, writes them all.
    #[test]
    fn a_folded_text_writer_writes_five_of_a_rule_and_the_rest_in_one_line() {
        let file: Vec<u16> = "p.nc".encode_utf16().collect();
        let finding = |rule, line, column| Finding {
            rule,
            message: format!("m{line}"),
            line,
            column,
            span: false,
            guessed: false,
            placed: crate::check::Placed::Not,
            pending_on: Vec::new(),
        };
        let mut found = Vec::new();
        for line in 1..=12 {
            found.push(finding(Rule::PastFormat, line * 10, 1));
            found.push(finding(Rule::NoFeedRate, line * 10, 4));
            if line <= 7 {
                // a note whose seventh comes before the sixth: the range is from the lowest
                found.push(finding(
                    Rule::HelicalArc,
                    if line == 7 { 3 } else { line },
                    2,
                ));
            }
        }
        found.push(finding(Rule::SeveralGWords, 5, 1));
        let write = |mut writer: Writer| {
            let mut out = Vec::new();
            for f in &found {
                writer.finding(&mut out, f);
            }
            writer.end(&mut out);
            String::from_utf8(out).unwrap()
        };
        let text = write(Writer::new(Format::Text, &file).folded());
        let lines: Vec<&str> = text.lines().collect();
        let of = |id: &str| lines.iter().filter(|l| l.contains(id)).count();
        assert_eq!(of("warning TG208 m"), SHOWN);
        assert_eq!(of("info TG406 m"), SHOWN);
        assert_eq!(of("error TG401 m"), 12, "every error is written");
        assert_eq!(of("info TG133 m5"), 1);
        assert_eq!(
            lines[lines.len() - 2..],
            [
                "p.nc:6:2: info TG406 2 more like this on lines 3-6 (--all shows each)",
                "p.nc:60:1: warning TG208 7 more like this on lines 60-120 (--all shows each)",
            ]
        );
        assert_eq!(lines.len(), SHOWN + SHOWN + 12 + 1 + 2);
        // the shown ones are the first of each rule, in their order among the others
        assert!(text.contains("p.nc:50:1: warning TG208 m50 [profile]\np.nc:50:4: error"));
        assert!(!text.contains("warning TG208 m60"));
        // one more is said as one
        let mut writer = Writer::new(Format::Text, &file).folded();
        let mut out = Vec::new();
        for line in 1..=SHOWN + 1 {
            writer.finding(&mut out, &finding(Rule::PastFormat, line, 1));
        }
        out.clear();
        writer.end(&mut out);
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "p.nc:6:1: warning TG208 1 more like this on line 6 (--all shows it)\n"
        );
        // the counts begin again after the end: a second end writes nothing
        let mut out = Vec::new();
        writer.end(&mut out);
        assert!(out.is_empty());
        // not folded, and JSON (folded or not): every finding, nothing at the end
        let all = write(Writer::new(Format::Text, &file));
        assert_eq!(all.lines().count(), found.len());
        for format in [Format::Json, Format::JsonLines] {
            assert_eq!(
                write(Writer::new(format, &file).folded()),
                write(Writer::new(format, &file))
            );
        }
    }

    /// A rule about a code is folded per the code its findings name: each code's first
    /// `SHOWN` are written and each has its fold line, naming it; a rule about none keeps one
    /// fold; errors about a code are all written.
    #[test]
    fn a_rule_about_a_code_is_folded_per_code() {
        let file: Vec<u16> = "p.nc".encode_utf16().collect();
        let finding = |rule, message: &str, line| Finding {
            rule,
            message: message.to_string(),
            line,
            column: 1,
            span: false,
            guessed: false,
            placed: crate::check::Placed::Not,
            pending_on: Vec::new(),
        };
        let mut found = Vec::new();
        for line in 1..=7 {
            found.push(finding(
                Rule::CodeNotInProfile,
                "M160 is not in the list",
                2 * line,
            ));
            found.push(finding(
                Rule::CodeNotInProfile,
                "M161 is not in the list",
                2 * line + 1,
            ));
            found.push(finding(
                Rule::AddressNotClassified,
                "address U is not in",
                100 + line,
            ));
            found.push(finding(
                Rule::CodeAlarms,
                "G12: the control has none",
                200 + line,
            ));
        }
        found.push(finding(
            Rule::CodeNotInProfile,
            "M162 is not in the list",
            300,
        ));
        found.push(finding(
            Rule::CodeNotInProfile,
            "S1.5: a decimal point in S",
            301,
        ));
        let mut writer = Writer::new(Format::Text, &file).folded();
        let mut out = Vec::new();
        for f in &found {
            writer.finding(&mut out, f);
        }
        writer.end(&mut out);
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let of = |what: &str| lines.iter().filter(|l| l.contains(what)).count();
        assert_eq!(of("warning TG307 M160 is"), SHOWN);
        assert_eq!(of("warning TG307 M161 is"), SHOWN);
        assert_eq!(
            (of("warning TG307 M162 is"), of("warning TG307 S1.5: a")),
            (1, 1)
        );
        assert_eq!(of("warning TG134 address U is"), SHOWN);
        assert_eq!(of("error TG306 G12:"), 7);
        assert_eq!(
            lines[lines.len() - 3..],
            [
                "p.nc:12:1: warning TG307 2 more like this (M160) on lines 12-14 (--all shows each)",
                "p.nc:13:1: warning TG307 2 more like this (M161) on lines 13-15 (--all shows each)",
                "p.nc:106:1: warning TG134 2 more like this (address U) on lines 106-107 (--all \
                 shows each)",
            ]
        );
        // begun again after the end
        let mut out = Vec::new();
        writer.end(&mut out);
        assert!(out.is_empty());
        assert!(writer.shown(Rule::CodeNotInProfile, 1, 1, "M160 is not in the list"));
    }

    #[test]
    fn strings_escaped_as_json_dumps_escapes_them() {
        assert_eq!(json("X+056"), "\"X+056\"");
        assert_eq!(json("a \"b\" \\ c"), r#""a \"b\" \\ c""#);
        assert_eq!(json("\u{8}\u{c}\n\r\t"), r#""\b\f\n\r\t""#);
        assert_eq!(json("\u{0}\u{1f}\u{7f}"), r#""\u0000\u001f\u007f""#);
        assert_eq!(json("Ø 20 é"), r#""\u00d8 20 \u00e9""#);
        assert_eq!(json("\u{20ac}\u{ffff}"), r#""\u20ac\uffff""#);
        assert_eq!(json("\u{1f600}"), r#""\ud83d\ude00""#);
        assert_eq!(json(""), "\"\"");
    }

    #[test]
    fn a_lone_surrogate_is_escaped_in_json_and_passed_in_text() {
        let units = [0x61, 0xdc80, 0x62];
        let mut out = Vec::new();
        json_units(&mut out, &units);
        assert_eq!(out, br#""a\udc80b""#);
        out.clear();
        wtf8(&mut out, &units);
        assert_eq!(out, b"a\xed\xb2\x80b");
        out.clear();
        wtf8(&mut out, &"Ø\u{1f600}".encode_utf16().collect::<Vec<_>>());
        assert_eq!(out, "Ø\u{1f600}".as_bytes());
    }

    #[test]
    fn the_plain_run_is_found_8_bytes_at_a_time_as_byte_by_byte() {
        for len in 0..20 {
            for at in 0..=len {
                for b in 0..=255u8 {
                    let mut bytes = vec![b'a'; len];
                    if at < len {
                        bytes[at] = b;
                    }
                    let slow = bytes.iter().position(|&c| !plain(c)).unwrap_or(len);
                    assert_eq!(plain_run(&bytes), slow, "{bytes:?}");
                }
            }
        }
        for word in [
            *b"abc\"defg",
            *b"~~~~~~~\x7f",
            *b"\x1f       ",
            *b"        ",
        ] {
            assert_eq!(
                any_special(u64::from_ne_bytes(word)),
                word.iter().any(|&c| !plain(c))
            );
        }
    }

    #[test]
    fn numbers_in_decimal() {
        for n in [0, 7, 10, 1_000_000, usize::MAX] {
            let mut out = Vec::new();
            number(&mut out, n);
            assert_eq!(out, n.to_string().as_bytes());
        }
    }

    #[test]
    fn a_finding_in_each_format() {
        let file: Vec<u16> = "part \"1\".nc".encode_utf16().collect();
        let finding = Finding {
            rule: Rule::ALL[0],
            message: "X-0.108370762: 9 decimals".to_string(),
            line: 12,
            column: 3,
            span: false,
            guessed: false,
            placed: crate::check::Placed::Not,
            pending_on: Vec::new(),
        };
        let rule = Rule::ALL[0];
        let (id, severity, clause) = (rule.id(), rule.severity().name(), rule.clause());
        let mut out = Vec::new();
        Writer::new(Format::Text, &file).finding(&mut out, &finding);
        assert_eq!(
            String::from_utf8(out).unwrap(),
            format!("part \"1\".nc:12:3: {severity} {id} X-0.108370762: 9 decimals [{clause}]\n")
        );
        let mut out = Vec::new();
        Writer::new(Format::JsonLines, &file).finding(&mut out, &finding);
        assert_eq!(
            String::from_utf8(out).unwrap(),
            format!(
                "{{\"rule\": {}, \"severity\": \"{severity}\", \"message\": \
                 \"X-0.108370762: 9 decimals\", \"file\": \"part \\\"1\\\".nc\", \
                 \"line\": 12, \"column\": 3, \"clause\": {}}}\n",
                json(id),
                json(clause)
            )
        );
        let mut out = Vec::new();
        Writer::new(Format::Json, &file).finding(&mut out, &finding);
        assert_eq!(
            String::from_utf8(out).unwrap(),
            format!(
                ",\n    {{\n      \"rule\": {},\n      \"severity\": \"{severity}\",\n      \
                 \"message\": \"X-0.108370762: 9 decimals\",\n      \"file\": \
                 \"part \\\"1\\\".nc\",\n      \"line\": 12,\n      \"column\": 3,\n      \
                 \"clause\": {}\n    }}",
                json(id),
                json(clause)
            )
        );
    }
}
