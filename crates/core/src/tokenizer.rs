//! One block's text to its word tokens and what stands beside them (clauses 4 to 6).
//!
//! A block is everything between two end-of-block LFs. The tokenizer walks it once, left to
//! right, in small functions over `(line, pos)`: blanks (space, tab, CR, and the NUL/DEL of a
//! tape leader) are skipped, `%` marks a program start or rewind stop, `/` or `/n` at the start
//! is the optional block skip (and, on a Fanuc or Haas, one in the middle of the block, which
//! skips from there to its end), `( )` and (where the dialect allows) `;` are comments, `:n` is an
//! alignment sequence number, and every word is an address letter, an optional index `n=` and a
//! value: a signed number or (after an index, or in brackets) a parameter expression.
//!
//! A word's token is its characters without the blanks inside it (`"X-12.345"`,
//! `"R29=R9+R15"`), borrowed from the line when it was written without any. The first thing
//! that is not allowed ends the block with a [`LexError`] that says what, where (byte offset)
//! and under which clause; its [`ErrorKind`] carries the checker's rule code, so no caller ever
//! matches message text.

use std::borrow::Cow;

use crate::expr::{self, skip_blanks};
use crate::statement::{self, Kind as StatementKind, Read, Statement};
use crate::text::{column, Char};
use crate::word::Word;

use crate::lex::{
    apart, blank, compact, err, number_ahead, Dialect, Digits, ErrorKind, Family, LexError, Token,
};

/// The DOS end-of-file character (Ctrl-Z).
pub const SUB: u8 = 0x1A;
/// The UTF-8 byte-order mark.
pub const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Longest block accepted: a guard against binary input or a file with no end of block.
pub const MAX_BLOCK: usize = 65536;

/// What a block holds beside its words. Absent for the plain blocks that most of a program is.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Extras<'a> {
    /// `0` for none, `b'/'` for `/`, or the level digit of `/1`..`/9`.
    pub skip: u8,
    /// A block skip in the middle of the block (Fanuc, Haas): the byte offset of its `/` and
    /// its level as in `skip`. With the block-skip switch on, the control ignores the block
    /// from the slash to its end; the words after it are read as the block's words all the
    /// same (the switch off), and the mark keeps its place among them.
    pub skip_within: Option<(usize, u8)>,
    /// Comments with their brackets (or leading `;`), at their byte offsets.
    pub comments: Vec<(usize, &'a [u8])>,
    /// A `%` program start or rewind stop.
    pub percent: bool,
    /// The text after `%`, without the blanks around it (program identification, clause 4).
    pub ident: &'a [u8],
    /// The statements of the dialect's family (`IF [..] GOTO 10`, `o100 sub`, `MSG("..")`).
    pub statements: Vec<Statement>,
}

impl Extras<'_> {
    /// The block's statements with their text in `text` (the block's): offset, kind, bytes,
    /// the form the converter's blocks and the diff's take them in.
    pub fn statement_texts<'t>(&self, text: &'t [u8]) -> Vec<(usize, StatementKind, &'t [u8])> {
        self.statements
            .iter()
            .map(|s| (s.offset, s.kind, &text[s.offset..s.end]))
            .collect()
    }
}

/// The words (pushed into the caller's vector) and the extras of a block.
pub type Reading<'a> = Option<Extras<'a>>;

/// What a tokenized block tells the end of reading ([`crate::dialect::ReadingEnd::read`]):
/// its word tokens and the extras of its `text` (the statements at their offsets, the skip).
pub fn note_reading_end(
    end: &mut crate::dialect::ReadingEnd,
    tokens: &[Token<'_>],
    extras: &Reading<'_>,
    text: &[u8],
    line: usize,
) {
    end.read(
        tokens.iter().map(|t| t.text.as_ref()),
        extras
            .iter()
            .flat_map(|e| &e.statements)
            .map(|s| (s.kind, &text[s.offset..s.end])),
        extras.as_ref().is_some_and(|e| e.skip != 0),
        line,
    );
}

/// Read one block's text (without its LF): its word tokens go to `words`, the extras are
/// returned. On error, `words` holds the tokens read before it.
pub fn tokenize<'a>(
    line: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Reading<'a>, LexError> {
    tokenize_as::<true>(line, dialect, words)
}

/// [`tokenize`], with its one-pass reading of plain words ([`plain_word`]) or without it (the
/// tests' reading, which the fast one must equal on every line).
#[inline(always)]
fn tokenize_as<'a, const PLAIN: bool>(
    line: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Reading<'a>, LexError> {
    if line.len() > MAX_BLOCK {
        return Err(err(
            ErrorKind::TooLong,
            "not an NC program (no end of block)".into(),
            MAX_BLOCK,
            "4",
        ));
    }
    let n = line.len();
    let mut extras: Option<Extras<'a>> = None;
    // Files as old editors leave them: a DOS end of file (Ctrl-Z, 0x1A) on a line of its own
    // after the program, and a UTF-8 byte-order mark before the first block, are kept in the
    // text (the reprint is byte for byte) and read as nothing.
    // (a line of only SUBs and blanks, one SUB at least, has a SUB first after its blanks:
    // no search of every line for one)
    let first = skip_blanks(line, 0);
    if line.get(first) == Some(&SUB) && line[first..].iter().all(|&b| b == SUB || blank(b)) {
        return Ok(None);
    }
    // (without a byte-order mark, the line's blanks are those skipped for a SUB)
    let mut pos = if line.starts_with(BOM) {
        skip_blanks(line, BOM.len())
    } else {
        first
    };
    if pos < n && line[pos] == b'%' {
        let mut start = pos + 1;
        let mut end = n;
        while start < end && blank(line[start]) {
            start += 1;
        }
        while end > start && blank(line[end - 1]) {
            end -= 1;
        }
        check_text(line, start, end, IDENT)?;
        return Ok(Some(Extras {
            percent: true,
            ident: &line[start..end],
            ..Extras::default()
        }));
    }
    if pos < n && line[pos] == b'/' {
        let skip = skip_level(line, pos);
        pos = skip_blanks(line, pos + if skip == b'/' { 1 } else { 2 });
        extras = Some(Extras {
            skip,
            ..Extras::default()
        });
    }
    // LinuxCNC reads a line number only first in the line, after a block delete `/`
    // (rs274 `read_items`; elsewhere 'Bad character 'n' used')
    let head = pos;
    loop {
        pos = skip_blanks(line, pos);
        // the plain words nearly every word of a CAM program is, each in one pass that
        // returns the offset after its blanks
        if PLAIN {
            pos = plain_words(line, pos, head, dialect, words);
        }
        if pos >= n {
            // (a plain block's reading returned with its tag alone, not a copy of `Extras`)
            return match extras {
                None => Ok(None),
                some => Ok(some),
            };
        }
        let b = line[pos];
        // A Macro B statement is a name of two letters or more (IF, GOTO, WHILE, O7997A
        // aside): an address followed by a digit, a sign or a point is a word, as in ISO
        let word_ahead = match dialect.family {
            Family::MacroB | Family::Okuma => {
                b.is_ascii_uppercase()
                    && b != b'O'
                    && line
                        .get(pos + 1)
                        .is_some_and(|&c| c.is_ascii_digit() || matches!(c, b'+' | b'-' | b'.'))
            }
            // (the SINUMERIK reader's own first look, without a call per word)
            Family::Sinumerik => statement::sinumerik_word_ahead(line, pos),
            Family::LinuxCnc => statement::linuxcnc_word_ahead(b),
            _ => false,
        };
        if dialect.family != Family::Iso && !word_ahead {
            let read = statement::read(line, pos, dialect, words);
            // a statement with a macro character the dialect does not read (`WHILE[1LT10]DO1`
            // on a FANUC without Custom Macro B): TG101 at that character, as the conversion
            // refuses it for such a target (`Dialect::unread_character`, one predicate);
            // where the statement cannot be read, up to the place its reading stopped
            let end = match &read {
                Ok(Some(Read::Statement(s))) => Some(s.end),
                Err(e) => Some((e.offset + 1).min(n)),
                _ => None,
            };
            if let Some(at) = end.and_then(|end| dialect.unread_in_statement(&line[pos..end])) {
                return Err(unread_statement_character(line, pos + at));
            }
            match read? {
                Some(Read::Statement(s)) => {
                    pos = s.end;
                    extras
                        .get_or_insert_with(Extras::default)
                        .statements
                        .push(s);
                    continue;
                }
                Some(Read::Word(end)) => {
                    pos = end;
                    continue;
                }
                None => {}
            }
        }
        if dialect.family == Family::LinuxCnc && matches!(b, b'N' | b'n') && pos != head {
            return Err(err(
                ErrorKind::Value,
                "a line number stands first in the line (rs274: 'Bad character 'n' used')".into(),
                pos,
                "LinuxCNC Overview",
            ));
        }
        match b {
            b'A'..=b'Z' => pos = word(line, pos, dialect, words)?,
            b'a'..=b'z' if dialect.lowercase => pos = word(line, pos, dialect, words)?,
            // a Haas NGC's program number: "The letter O, or o is followed by a 5-digit number"
            b'o' if dialect.ngc && line.get(pos + 1).is_some_and(u8::is_ascii_digit) => {
                pos = word(line, pos, dialect, words)?
            }
            b'#' if dialect.hash => pos = word(line, pos, dialect, words)?,
            // Heidenhain ends a block with '*'
            b'*' if dialect.family == Family::Heidenhain
                && line[pos + 1..].iter().all(|&c| blank(c)) =>
            {
                return Ok(extras)
            }
            // (Sinumerik's calls, NAME(..), are read as statements before this)
            b'(' => {
                let Some(end) = comment_close(line, pos, dialect.family)? else {
                    return Err(comment_open(pos, dialect.family));
                };
                check_text(line, pos + 1, end, COMMENT)?;
                extras
                    .get_or_insert_with(Extras::default)
                    .comments
                    .push((pos, &line[pos..=end]));
                pos = end + 1;
            }
            b';' if dialect.semicolon => {
                if dialect.family == Family::MacroB {
                    if let Some(at) = words_after_semicolon(line, pos + 1)? {
                        return Err(semicolon_words(at));
                    }
                }
                check_text(line, pos + 1, n, COMMENT)?;
                let mut end = n;
                while end > pos && line[end - 1] == b'\r' {
                    end -= 1;
                }
                extras
                    .get_or_insert_with(Extras::default)
                    .comments
                    .push((pos, &line[pos..end]));
                return Ok(extras);
            }
            b':' => {
                let mut end = pos + 1;
                while end < n && line[end].is_ascii_digit() {
                    end += 1;
                }
                if end == pos + 1 {
                    return Err(err(
                        ErrorKind::Alignment,
                        "alignment ':' must be followed by the sequence number digits".into(),
                        pos + 1,
                        "6.4.1",
                    ));
                }
                words.push(Token {
                    offset: pos,
                    end,
                    text: Cow::Borrowed(&line[pos..end]),
                    plain: None,
                    digits: Digits::default(),
                });
                pos = end;
            }
            b')' => {
                return Err(err(
                    ErrorKind::Unbalanced,
                    "')' without an opening '(' (nested or unbalanced comment)".into(),
                    pos,
                    "4",
                ))
            }
            // FANUC: a slash in the middle of a block skips from there to the end of the block
            // when the switch is on (docs/dialects.md); one per block is read
            b'/' if crate::dialect::skips_within_block(dialect.family)
                && extras.as_ref().is_none_or(|e| e.skip_within.is_none()) =>
            {
                let level = skip_level(line, pos);
                extras.get_or_insert_with(Extras::default).skip_within = Some((pos, level));
                pos += if level == b'/' { 1 } else { 2 };
            }
            b'/' => {
                let message = if crate::dialect::skips_within_block(dialect.family) {
                    "a second '/' block skip in the block: the first one already skips to the \
                     end of the block"
                } else {
                    "'/' block skip must stand at the start of the block, before the sequence \
                     number"
                };
                return Err(err(ErrorKind::Skip, message.into(), pos, "4"));
            }
            b'0'..=b'9' | b'.' | b'+' | b'-' => {
                // the number as written: one sign, then its digits and point (`01` of `T1 01`,
                // not its first digit alone)
                let start = pos + usize::from(matches!(b, b'+' | b'-'));
                let len = line[start..]
                    .iter()
                    .take_while(|c| c.is_ascii_digit() || **c == b'.')
                    .count();
                let number = String::from_utf8_lossy(&line[pos..start + len]);
                let mut message = format!("number '{number}' without an address letter");
                if dialect.family == Family::MacroB && split_word(line, pos) {
                    message.push_str(
                        "; if it is the rest of the word before it (G1 8 for G18), no Fanuc or \
                         Haas source at hand says the control reads a blank inside a word \
                         (docs/dialects.md)",
                    );
                }
                return Err(err(ErrorKind::Value, message, pos, "6.1"));
            }
            _ => return Err(character_error(line, pos, dialect)),
        }
    }
}

/// Where something other than blanks, further `;` and `( )` comments follows a Fanuc or
/// Haas `;` (the end of block as the control shows it), if anything does.
fn words_after_semicolon(line: &[u8], mut pos: usize) -> Result<Option<usize>, LexError> {
    while pos < line.len() {
        match line[pos] {
            b';' | b'\r' => pos += 1,
            c if blank(c) => pos += 1,
            b'(' => match comment_close(line, pos, Family::MacroB)? {
                Some(close) => pos = close + 1,
                // an open comment: read as the rest of the line, as before
                None => return Ok(None),
            },
            _ => return Ok(Some(pos)),
        }
    }
    Ok(None)
}

/// The offset of the `)` that closes the comment opened at `pos`, None if none follows.
///
/// ISO 6983-1 (clause 4) ends a comment at its first `)`, and so does every other family here;
/// on LinuxCNC a `(` inside a comment is refused where it stands, closed or not, as rs274
/// refuses it ("Nested comment found"). For a Fanuc or a Haas, no
/// source at hand says whether the control ends it there or nests it to the matching `)`
/// (docs/dialects.md, "A `(` inside a comment"), so both readings are taken. Where nothing the
/// first reading leaves can change what is sent or skipped -- the text between the first `)`
/// and the matching one holds, outside a comment, no letter, digit, `#`, `%`, `:`, no `;` (the
/// end of block), no `/` (the block skip) and no `,` that could join a `C`, `R` or `A` after
/// it, only a stray `)` or marks such as `...` -- the comment is read to its matching `)`, once,
/// and the checker warns (TG136). Otherwise (`(A (B) X5)`, `(A (B) ;) F50.`, or `(A (B) X5`
/// with no matching `)`) the two send different blocks: TG121, with what each reading sends.
fn comment_close(line: &[u8], pos: usize, family: Family) -> Result<Option<usize>, LexError> {
    let Some(first) = line[pos + 1..].iter().position(|&c| c == b')') else {
        return Ok(None);
    };
    let first = pos + 1 + first;
    if !matches!(family, Family::MacroB | Family::LinuxCnc) {
        return Ok(Some(first));
    }
    let Some(inner) = line[pos + 1..first].iter().position(|&c| c == b'(') else {
        return Ok(Some(first));
    };
    let inner = pos + 1 + inner;
    if family == Family::LinuxCnc {
        // rs274 refuses any '(' inside a comment, closed or not (`close_and_downcase`)
        return Err(err(
            ErrorKind::Unbalanced,
            "comment inside a comment: '(' before the ')' that closes the first (rs274: \
             'Nested comment found')"
                .into(),
            inner,
            "4",
        ));
    }
    let mut depth = 0usize;
    let mut matching = None;
    for (i, &c) in line.iter().enumerate().skip(pos) {
        match c {
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    matching = Some(i);
                    break;
                }
            }
            _ => {}
        }
    }
    // what the first reading leaves in the block up to where the nested one ends
    let mut left = &line[first + 1..matching.unwrap_or(line.len())];
    while let [rest @ .., b'\r'] = left {
        left = rest;
    }
    match (
        matching,
        first_reading_word(line, first + 1, first + 1 + left.len()),
    ) {
        (Some(close), None) => Ok(Some(close)),
        (_, Some((at, what))) => Err(nested_readings_differ(
            line,
            (inner, first),
            matching,
            at,
            what,
        )),
        // no matching ')' and nothing but marks after the first: the first reading closes the
        // comment there; the nested one leaves it open (TG120's doubt). Neither sends a word.
        (None, None) => Ok(Some(first)),
    }
}

/// What the first reading of a nested comment leaves in the block that changes what is sent or
/// skipped.
#[derive(Clone, Copy)]
enum FirstLeaves {
    /// A letter, digit, `#`, `%` (a rewind stop) or `:` (a FANUC program number).
    Word,
    /// A `;`: the end of block as a Fanuc or Haas shows it; what follows is another block.
    EndOfBlock,
    /// A `/` in the middle of the block: with the switch on, the block skip to its end (TG128).
    Skip,
    /// A `,` before this letter (`C`, `R`, `A`) once the stray `)` and blanks are passed over:
    /// a chamfer, corner or angle word (`,C1.`).
    Joins(u8),
}

/// Where the first reading of a nested comment (to its first `)`) leaves, in
/// `line[from..end]` (the text after that `)` up to where the nested reading ends), a
/// character that changes the block ([`FirstLeaves`]); the `( )` comments the first reading
/// finds there are passed over. None: only blanks, `)` and marks that make no word, end no
/// block and skip nothing.
fn first_reading_word(line: &[u8], from: usize, end: usize) -> Option<(usize, FirstLeaves)> {
    let mut i = from;
    while i < end {
        match line[i] {
            b'(' => match line[i + 1..end].iter().position(|&c| c == b')') {
                Some(close) => i += close + 2,
                None => return None,
            },
            c if c.is_ascii_alphanumeric() || matches!(c, b'#' | b'%' | b':') => {
                return Some((i, FirstLeaves::Word));
            }
            b';' => return Some((i, FirstLeaves::EndOfBlock)),
            b'/' => return Some((i, FirstLeaves::Skip)),
            b',' => {
                // the letter a control passing over the stray ')' would read after the ','
                let next = line[i + 1..]
                    .iter()
                    .find(|&&c| !(blank(c) || matches!(c, b')' | b'\r')));
                match next.map(u8::to_ascii_uppercase) {
                    Some(letter @ (b'C' | b'R' | b'A')) => {
                        return Some((i, FirstLeaves::Joins(letter)));
                    }
                    _ => i += 1,
                }
            }
            _ => i += 1,
        }
    }
    None
}

/// TG121 on a Fanuc or Haas: a `(` inside a comment whose two readings send different blocks.
#[cold]
#[inline(never)]
fn nested_readings_differ(
    line: &[u8],
    (inner, first): (usize, usize),
    matching: Option<usize>,
    at: usize,
    what: FirstLeaves,
) -> LexError {
    let shown = |bytes: &[u8]| {
        let text = String::from_utf8_lossy(bytes);
        let text = text.trim();
        if text.chars().count() > 40 {
            format!("{}...", text.chars().take(40).collect::<String>())
        } else {
            text.to_string()
        }
    };
    let nested = match matching {
        Some(close) => format!(
            "read nested, to the ')' that matches (column {}), it sends none of it",
            column(line, close)
        ),
        None => "read nested, it is never closed and runs to the end of the block (an alarm or \
                 a comment, TG120), sending none of it"
            .to_string(),
    };
    let end = matching.map_or(line.len(), |close| close + 1);
    let left = match what {
        // a '%' is the tape's end of record (FANUC B-63524EN/01, 8: a file ends with %): the
        // control stops reading the program there
        FirstLeaves::Word if line[at] == b'%' => {
            "a '%', the tape's end of record: the control stops reading the program there"
                .to_string()
        }
        FirstLeaves::Word => format!("a word at '{}'", line[at] as char),
        FirstLeaves::EndOfBlock => "a ';' that ends the block there: what follows it is a \
                                    block of its own (TG100)"
            .to_string(),
        FirstLeaves::Skip => "a '/' that, with the block-skip switch on, skips the block from \
                              there to its end (TG128)"
            .to_string(),
        FirstLeaves::Joins(letter) => format!(
            "a ',' that joins the '{}' after it into a ',{}' word (chamfer, corner or angle) \
             once the stray ')' is passed over",
            letter as char, letter as char
        ),
    };
    err(
        ErrorKind::Unbalanced,
        format!(
            "comment inside a comment, and its two readings send different blocks: read to \
             its first ')' (column {}), the block holds '{}', {left}; \
             {nested}; no Fanuc or Haas source at hand says which the control does \
             (docs/dialects.md)",
            column(line, first),
            shown(&line[first + 1..end]),
        ),
        inner,
        "4",
    )
}

/// Words after a Fanuc or Haas `;` in the same line (TG100): a control that takes `;` as the
/// end of block runs them as a block of their own, one that does not alarms on the `;`;
/// neither reads them as a comment, so tapegate reads neither (docs/dialects.md, "Block
/// forms").
#[cold]
#[inline(never)]
fn semicolon_words(at: usize) -> LexError {
    err(
        ErrorKind::Value,
        "words after ';' in the line: a control that takes ';' as the end of block runs them as \
         the next block, one that does not alarms; neither reads them as a comment (write \
         them on a line of their own, or in parentheses)"
            .into(),
        at,
        "4",
    )
}

/// A `(` with no `)` before the end of the block (TG120): ISO 6983-1 (clause 4) refuses it,
/// and on a Fanuc or a Haas no source at hand says whether the control alarms or takes the
/// rest of the block as the comment (docs/dialects.md), so the refusal says whose it is.
#[cold]
#[inline(never)]
fn comment_open(pos: usize, family: Family) -> LexError {
    let mut message = String::from("comment not closed: '(' without ')' before the end of block");
    if family == Family::MacroB {
        message.push_str(
            "; read as ISO 6983-1 has it: no Fanuc or Haas source at hand says whether the \
             control alarms or reads the rest of the block as the comment (docs/dialects.md)",
        );
    }
    err(ErrorKind::CommentOpen, message, pos, "4")
}

/// Whether the number at `pos` follows a word's digits after blanks (`G1 8`, `X1. 5`): a word
/// written with a blank inside it, not a number standing alone.
fn split_word(line: &[u8], pos: usize) -> bool {
    if !matches!(line[pos], b'0'..=b'9' | b'.') {
        return false;
    }
    let before = line[..pos].iter().rposition(|&c| !blank(c));
    before.is_some_and(|i| i + 1 < pos && (line[i].is_ascii_digit() || line[i] == b'.'))
}

/// The level of the block skip whose `/` is at `pos`: `b'/'` for a bare slash, or the digit of
/// `/1`..`/9`.
fn skip_level(line: &[u8], pos: usize) -> u8 {
    match line.get(pos + 1) {
        Some(&level) if (b'1'..=b'9').contains(&level) => level,
        _ => b'/',
    }
}

/// Annex A: every character of ISO 6983-1, and the blanks a control ignores.
fn annex_a(c: char) -> bool {
    c.is_ascii_uppercase() || c.is_ascii_digit() || "%()+,-./:= \t\r\x7f".contains(c)
}

/// The one character table of a profile: whether a control of `dialect` accepts `c`, in a
/// comment or outside one. The checker reads programs by it and the emulator's TH check
/// rejects by it, so `check` and `emulate` never disagree about the same bytes: a comment
/// may hold any printable character (lower case included); outside one, Annex A, lower case
/// where the dialect reads it, the profile's extra characters and the family's own
/// (`@ ^ $ < >` for LinuxCNC, `" _ $ = < > ' @` for Siemens, `< >` of a program's name for a
/// FANUC).
pub fn character_allowed(c: char, in_comment: bool, dialect: &Dialect) -> bool {
    if in_comment {
        return c == '\t' || c == '\r' || crate::text::printable(c);
    }
    if annex_a(c) || (c.is_ascii_lowercase() && dialect.lowercase) {
        return true;
    }
    match c {
        '#' => dialect.hash,
        '[' | ']' => dialect.brackets,
        ';' => dialect.semicolon,
        '*' => dialect.star || dialect.family == Family::Heidenhain,
        '@' | '^' | '$' => matches!(dialect.family, Family::LinuxCnc | Family::Sinumerik),
        // a FANUC program's name, `<NAME>` (B-64014EN/03, 2.5; where it may stand is the
        // statement reader's)
        '<' | '>' => {
            matches!(dialect.family, Family::LinuxCnc | Family::Sinumerik)
                || (dialect.family == Family::MacroB && !dialect.ngc)
        }
        '"' | '_' | '\'' => dialect.family == Family::Sinumerik,
        _ => false,
    }
}

fn character_error(line: &[u8], pos: usize, dialect: &Dialect) -> LexError {
    let (c, _) = Char::at(line, pos);
    let message = match c {
        Char::Text(ch) if ch.is_ascii_lowercase() && !dialect.lowercase => format!(
            "lower-case '{ch}' is outside ISO 6983-1 Annex A and the profile does not allow \
             lower case"
        ),
        Char::Text(ch) if annex_a(ch) => format!("character {} is not expected here", c.repr()),
        Char::Byte(b) => format!(
            "byte 0x{b:02X} is not ASCII or UTF-8 text (an 8-bit character set?) and is not \
             allowed in an NC program"
        ),
        _ if !c.printable() => {
            format!(
                "control or binary character {} is not allowed in an NC program",
                c.code()
            )
        }
        _ => format!(
            "character {} ({}) is outside ISO 6983-1 Annex A and not allowed by the profile",
            c.repr(),
            c.code()
        ),
    };
    err(ErrorKind::Character, message, pos, "Annex A")
}

/// A macro statement's `#`, `[`, `]` or `*` that the dialect does not read
/// ([`Dialect::unread_character`]).
fn unread_statement_character(line: &[u8], at: usize) -> LexError {
    err(
        ErrorKind::Character,
        format!(
            "character {} of a macro statement is not among the characters the profile \
             allows: a control without it has no such statement and refuses the block",
            line[at] as char
        ),
        at,
        "Annex A",
    )
}

/// Comments and the program identification may hold any printable character, tab and CR; the
/// identification also the NUL and DEL of a leader.
fn check_text(line: &[u8], start: usize, end: usize, place: &str) -> Result<(), LexError> {
    let leader = place == IDENT;
    let mut i = start;
    while i < end {
        let b = line[i];
        if (0x20..0x7f).contains(&b)
            || b == b'\t'
            || b == b'\r'
            || (leader && (b == 0 || b == 0x7f))
            || (leader && b == 0x1a && line[i..end].iter().all(|&c| c == 0x1a || c == b'\r'))
        {
            i += 1;
            continue;
        }
        let (c, len) = Char::at(line, i);
        // text outside ASCII in a comment (a Latin-1 degree sign, GBK or UTF-8 Chinese) is
        // read; the checker says so once per file (TG127)
        let text_byte = matches!(c, Char::Byte(b) if b >= 0x80) && place == COMMENT;
        if !c.printable() && !text_byte {
            let message = match c {
                Char::Byte(byte) => format!(
                    "byte 0x{byte:02X} {place} is not ASCII or UTF-8 text (an 8-bit character \
                     set?)"
                ),
                _ => format!("control or binary character {} {place}", c.code()),
            };
            return Err(err(ErrorKind::Character, message, i, "Annex A"));
        }
        i += len;
    }
    Ok(())
}

const IDENT: &str = "in the program identification";
const COMMENT: &str = "in a comment";

/// The ASCII digits from `pos`: where they end and their value (wrapping past 19 digits:
/// [`Digits::new`] keeps it only for as many as are exact).
fn digits_read(line: &[u8], pos: usize) -> (usize, u64) {
    digits_read_from(line, pos, 0)
}

/// [`digits_read`] after digits of value `value` (the fraction's after the whole part's).
fn digits_read_from(line: &[u8], pos: usize, mut value: u64) -> (usize, u64) {
    let mut i = pos;
    while i < line.len() && line[i].is_ascii_digit() {
        value = value
            .wrapping_mul(10)
            .wrapping_add(u64::from(line[i] - b'0'));
        i += 1;
    }
    (i, value)
}

/// [`expr::number_end`] (the digits at `pos` ending at `i`, of value `whole`) that reads
/// the number's digits after its point on the way: the end of the number, and its
/// [`Digits`].
fn number_read(line: &[u8], pos: usize, i: usize, whole: u64) -> Option<(usize, Digits)> {
    let digits = i > pos;
    if i < line.len() && line[i] == b'.' {
        let (j, m) = digits_read_from(line, i + 1, whole);
        if digits || j > i + 1 {
            return Some((j, Digits::new(i - pos, j - pos - 1, m)));
        }
    }
    digits.then(|| (i, Digits::new(i - pos, i - pos, whole)))
}

/// HEIDENHAIN ISO's mirror image, cycle 8 (`G28 X *`, `G28 X Y *`): the mirrored axes are
/// named by their address alone, with no value (the profile's `G28 = mirror image (cycle 8)`;
/// the cycle takes the axes to mirror and no coordinate. No manual page with the ISO block was
/// at hand: the form is read, not checked, so that a program using it is no false error). An axis address after a
/// G28 of its block, followed by the block end `*`, the next word's address or the end of the
/// line, is such a word: read as the address alone, kept as written.
fn mirrored_axis(
    dialect: &Dialect,
    address: u8,
    line: &[u8],
    pos: usize,
    words: &[Token<'_>],
) -> bool {
    dialect.family == Family::Heidenhain
        && matches!(
            address.to_ascii_uppercase(),
            b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'A' | b'B' | b'C'
        )
        && line
            .get(skip_blanks(line, pos))
            .is_none_or(|&c| c == b'*' || c.is_ascii_alphabetic())
        && words.iter().any(|t| {
            let t: &[u8] = &t.text;
            t.eq_ignore_ascii_case(b"G28") || t.eq_ignore_ascii_case(b"G028")
        })
}

/// The plain words from `pos` on ([`plain_word`]), each after the blanks of the one before:
/// the offset of the first thing that is not one (the line's length at its end). A function of
/// its own, out of line, so that its loops keep the line and their counts in registers: inside
/// [`tokenize`], among the full reading's values, the digit loops reloaded them from the stack.
#[inline(never)]
fn plain_words<'a, O: PlainOut<'a>>(
    line: &'a [u8],
    mut pos: usize,
    head: usize,
    dialect: &Dialect,
    words: &mut O,
) -> usize {
    while pos < line.len() {
        match plain_word(line, pos, head, dialect, words) {
            Some(next) => pos = next,
            None => break,
        }
    }
    pos
}

/// [`PLAIN_START`]: a byte no plain word starts with.
const NOT: u8 = 0;
/// [`PLAIN_START`]: a plain word's address.
const START: u8 = 1;
/// [`PLAIN_START`]: a plain word's address first in the line only (LinuxCNC's line number).
const FIRST: u8 = 2;

/// What each byte is to [`plain_word`] as a word's first, by family and whether lower case
/// is read ([`Family`] as a number, then 0 or 1): a letter ([`Dialect::lowercase`]: a lower
/// case one too) but for those whose word the family's statements or rules may read
/// otherwise -- Macro B's and Okuma's `O` and lower case, a SINUMERIK's `R`, LinuxCNC's `O`
/// and a line number after the line's first word, every HEIDENHAIN word. One look a word,
/// where the family's match and the letter's tests were about 15 instructions.
const PLAIN_START: [[[u8; 256]; 2]; 6] = {
    let mut table = [[[NOT; 256]; 2]; 6];
    let families = Family::ALL;
    let mut f = 0;
    while f < families.len() {
        let family = families[f];
        let mut lowercase = 0;
        while lowercase < 2 {
            let mut b = 0;
            while b < 256 {
                let c = b as u8;
                let upper = c.to_ascii_uppercase();
                let letter = c.is_ascii_uppercase() || (lowercase == 1 && c.is_ascii_lowercase());
                table[family as usize][lowercase][b] = if !letter {
                    NOT
                } else {
                    match family {
                        Family::Iso => START,
                        Family::MacroB | Family::Okuma if c == b'O' || !c.is_ascii_uppercase() => {
                            NOT
                        }
                        Family::MacroB | Family::Okuma => START,
                        Family::Sinumerik if upper == b'R' => NOT,
                        Family::Sinumerik => START,
                        Family::LinuxCnc if upper == b'O' => NOT,
                        Family::LinuxCnc if upper == b'N' => FIRST,
                        Family::LinuxCnc => START,
                        Family::Heidenhain => NOT,
                    }
                };
                b += 1;
            }
            lowercase += 1;
        }
        f += 1;
    }
    table
};

/// The plain word at `pos` -- a letter, an optional sign, digits with an optional point
/// (`X-12.345`, `G1`, `Y.5`, `N1000`) -- read in one pass, its digits' value and its point's
/// place on the way; its token pushed, and the offset of what follows its blanks returned.
/// None where the block holds anything else there, or anything the family's reading might take
/// otherwise: a statement's name (Macro B's and Okuma's `O`, a SINUMERIK's `R1=`, LinuxCNC's
/// `o`), an index (`X1=`, digits then `=`), a number read through blanks (LinuxCNC's `X1 2`),
/// a LinuxCNC line number after the first word, HEIDENHAIN's blocks, the `#` of a parameter.
/// Those, and every error, are [`tokenize`]'s full reading's ([`word`], the statements): a
/// word this takes is the token that reading makes of it, so it decides nothing of its own
/// (nearly every word of a CAM program is one; the full reading cost about 240 instructions a
/// word on them).
#[inline(always)]
fn plain_word<'a, O: PlainOut<'a>>(
    line: &'a [u8],
    pos: usize,
    head: usize,
    dialect: &Dialect,
    words: &mut O,
) -> Option<usize> {
    let b = line[pos];
    match PLAIN_START[dialect.family as usize][usize::from(dialect.lowercase)][usize::from(b)] {
        START => {}
        FIRST if pos == head => {}
        _ => return None,
    }
    let n = line.len();
    if line.get(pos + 1) == Some(&b'[') {
        return bracket_word(line, pos, dialect, words);
    }
    let mut i = pos + 1;
    let signed = matches!(line.get(i), Some(b'+' | b'-'));
    i += usize::from(signed);
    let number = i;
    let mut value: u64 = 0;
    while i < n && line[i].is_ascii_digit() {
        value = value
            .wrapping_mul(10)
            .wrapping_add(u64::from(line[i] - b'0'));
        i += 1;
    }
    let dot = i - number;
    let count = if i < n && line[i] == b'.' {
        i += 1;
        while i < n && line[i].is_ascii_digit() {
            value = value
                .wrapping_mul(10)
                .wrapping_add(u64::from(line[i] - b'0'));
            i += 1;
        }
        i - number - 1
    } else {
        dot
    };
    if count == 0 {
        return None;
    }
    let after = words.skip_blanks(line, i);
    match line.get(after) {
        // an index (`X1=`; after a sign or a point, the error the full reading words)
        Some(b'=') => return None,
        // LinuxCNC reads a number on through blanks
        Some(b'0'..=b'9' | b'.') if dialect.family == Family::LinuxCnc => return None,
        _ => {}
    }
    words.plain(line, pos, i, signed, Digits::new(dot, count, value));
    Some(after)
}

/// The bytes of a chunk of eight equal to `byte`, each as its high bit: exact (no false
/// flag: the low seven bits are added apart from the high one, and carry nothing on).
#[inline]
pub(crate) fn equal_bytes(chunk: u64, byte: u8) -> u64 {
    const LOWS: u64 = 0x7F7F_7F7F_7F7F_7F7F;
    let x = chunk ^ (0x0101_0101_0101_0101 * u64::from(byte));
    !(((x & LOWS) + LOWS) | x | LOWS)
}

/// A named parameter's name `text[from..from + len]` as one integer, for the names seen
/// (the check's `linuxcnc_unknown_name`; [`ExpressionWalk::keys`]): its first 8 bytes (fewer: zeros after them),
/// loaded at once where 8 bytes follow `from` in `text`.
#[inline]
pub(crate) fn name_key(text: &[u8], from: usize, len: usize) -> u64 {
    if let Some(chunk) = text.get(from..from + 8) {
        let mut bytes = [0u8; 8];
        bytes.copy_from_slice(chunk);
        let all = u64::from_le_bytes(bytes);
        if len >= 8 {
            all
        } else {
            all & ((1u64 << (8 * len)) - 1)
        }
    } else {
        let mut key = 0u64;
        for (k, &c) in text[from..from + len.min(8)].iter().enumerate() {
            key |= u64::from(c) << (8 * k);
        }
        key
    }
}

/// The bracketed words of a line [`bracket_word`] walks for the LinuxCNC rules: the first
/// eight of a block (a word after them is read by each rule's own walk).
pub const WALKED: usize = 8;

/// What one walk of a LinuxCNC word's bracketed expression finds for the three rules that
/// read its bytes: the bare-operator refusal (`between::bare_operator`), the named
/// parameters' reads and the read-refusal's test for a `/` (the check's `walk_expression`;
/// [`bracket_word`] finds the same of a plain line's bracketed word as it scans it,
/// [`LineWalks`]). A CAM program's `Y[#<yscale>*-3.608]Z[#<zscale>*-8.942]` was walked three
/// times a word. Two walks are equal by their first `count` names and keys (a walk written
/// in place may hold a word's before it past them).
#[derive(Clone, Copy, Default, Debug)]
pub struct ExpressionWalk {
    /// The expression is one pair of brackets with no other bracket, no `/` and no letter
    /// outside a named parameter's name (`[#<yscale>*-3.608]`, `[#1+2.5]`) and at most four
    /// named parameters: its first `[` closes at its last byte, and it has no `/`. False:
    /// each rule walks it itself.
    pub plain: bool,
    /// How many of `names` are found.
    pub count: u8,
    /// Each named parameter's `#` and its `>` in the expression, in their order.
    pub names: [(u16, u16); 4],
    /// Each name's key ([`name_key`]: its first 8 bytes as one integer), as `names`.
    pub keys: [u64; 4],
}

impl PartialEq for ExpressionWalk {
    fn eq(&self, other: &Self) -> bool {
        let n = usize::from(self.count).min(self.names.len());
        self.plain == other.plain
            && self.count == other.count
            && self.names[..n] == other.names[..n]
            && self.keys[..n] == other.keys[..n]
    }
}

impl Eq for ExpressionWalk {}

/// The walks [`bracket_word`] made of a line of plain words' bracketed words
/// ([`plain_line_words`]): the plain ones among the first [`WALKED`] words, by place. A word
/// whose bit is not in `set` (its expression not plain, or no bracketed word) is walked by
/// the check itself.
#[derive(Clone, Copy, Default, Debug)]
pub struct LineWalks {
    /// The words (bit `i` for the line's word `i`) whose walk is in `walks`.
    pub set: u8,
    /// Every bracketed word of the line is among `set` (none is past the first [`WALKED`]
    /// words, none is not plain): the LinuxCNC rules need read no word's expression of their
    /// own.
    pub all: bool,
    pub walks: [ExpressionWalk; WALKED],
    /// Names the check found among the names seen (`Checker::linuxcnc_names_all_seen`, the
    /// newest first; [`HotName::NONE`]: none), kept from line to line: a bracketed word's name
    /// that is one of them is read at once, by a compare of its bytes ([`bracket_word`]).
    pub hot: [HotName; HOT],
    /// Every name of the walks in `set` is one of `hot` (set where `set` is emptied, cleared
    /// by a name read otherwise): the check need look none of them up.
    pub all_hot: bool,
}

/// How many names [`LineWalks::hot`] keeps: a CAM program's `X[#<xscale>*..]`,
/// `Y[#<yscale>*..]`, `Z[#<zscale>*..]` and `F[#<fscale>*..]`.
pub const HOT: usize = 4;

/// A LinuxCNC parameter's name [`short_name_of`] takes, as [`LineWalks::hot`] keeps it: its
/// bytes and its `>` (`pattern`, the bytes `mask` covers), its length and key. A name's
/// 8 bytes after its `#<` that hold these bytes first are a name [`short_name_of`] reads as
/// this one (it reads no byte after the `>`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HotName {
    pattern: u64,
    mask: u64,
    len: usize,
    key: u64,
}

impl Default for HotName {
    fn default() -> Self {
        Self::NONE
    }
}

impl HotName {
    /// No name: a bit of its pattern is outside its mask, so no bytes are it.
    pub const NONE: HotName = HotName {
        pattern: 1,
        mask: 0,
        len: 0,
        key: 0,
    };

    /// The name whose key is `key` ([`name_key`]: its bytes, none of them zero, so that its
    /// length is its key's bytes), where [`short_name_of`] takes that name; else None.
    pub fn of_key(key: u64) -> Option<HotName> {
        let len = (64 - key.leading_zeros() as usize).div_ceil(8);
        if !(1..8).contains(&len) {
            return None;
        }
        let pattern = key | u64::from(b'>') << (8 * len);
        (short_name_of(pattern) == Some((len, key))).then_some(HotName {
            pattern,
            mask: u64::MAX >> (8 * (7 - len)),
            len,
            key,
        })
    }

    /// The name's key ([`name_key`]; 0 for [`HotName::NONE`]).
    pub fn key(&self) -> u64 {
        self.key
    }

    /// Whether the 8 bytes `chunk` after a `#<` begin with this name and its `>`.
    #[inline(always)]
    fn is(&self, chunk: u64) -> bool {
        chunk & self.mask == self.pattern
    }
}

/// [`bracket_word`]'s look at a byte of a LinuxCNC parameter's name: a blank ends the
/// reading (the full reading's), and a bracket or a `/` makes the expression not plain
/// ([`ExpressionWalk`]).
const NAME_BLANK: u8 = 1;
/// See [`NAME_BLANK`].
const NAME_NOT_PLAIN: u8 = 2;
/// [`NAME_BLANK`], [`NAME_NOT_PLAIN`] by byte.
const NAME_BYTES: [u8; 256] = {
    let mut table = [0u8; 256];
    let mut b = 0;
    while b < 256 {
        if crate::lex::BLANKS[b] {
            table[b] = NAME_BLANK;
        }
        b += 1;
    }
    table[b'[' as usize] = NAME_NOT_PLAIN;
    table[b']' as usize] = NAME_NOT_PLAIN;
    table[b'/' as usize] = NAME_NOT_PLAIN;
    table
};

/// Where [`plain_word`] writes a plain word: a token ([`tokenize`]), or the checker's word
/// ([`plain_line_words`]).
trait PlainOut<'a> {
    /// The plain word `line[pos..end]`, its sign one byte long where `signed`.
    fn plain(&mut self, line: &'a [u8], pos: usize, end: usize, signed: bool, digits: Digits);
    /// Whether [`bracket_word`] walks a bracketed word for the LinuxCNC rules
    /// ([`ExpressionWalk`]): the checker's words only.
    const WALKS: bool = false;
    /// The bracketed word `line[pos..end]` ([`bracket_word`]): no plain number. `walked`: the
    /// count of its expression's names, given by [`PlainOut::walk_name`], where
    /// [`PlainOut::WALKS`] and it is plain, else None.
    fn bracketed(&mut self, line: &'a [u8], pos: usize, end: usize, walked: Option<u8>);
    /// The next bracketed word's name `n` (below 4): its `#` and `>` in the expression and its
    /// key, written where its walk is kept; `hot`: it was read as one of the hot names
    /// ([`PlainOut::hot_name`]). False where none is (not [`PlainOut::WALKS`], or
    /// the word past the first [`WALKED`]): the word's walk is not kept.
    #[inline(always)]
    fn walk_name(&mut self, _n: usize, _place: (u16, u16), _key: u64, _hot: bool) -> bool {
        false
    }
    /// The name the 8 bytes `chunk` after a `#<` begin with, where it is one of the hot names
    /// ([`LineWalks::hot`]): its length and key, as [`short_name_of`] reads them.
    #[inline(always)]
    fn hot_name(&self, _chunk: u64) -> Option<(usize, u64)> {
        None
    }
    /// The offset of what follows the blanks from `pos` ([`skip_blanks`]): the blanks before
    /// a line's first word and after each word, the only bytes of a line of plain words that
    /// are not a word's.
    #[inline(always)]
    fn skip_blanks(&mut self, line: &[u8], pos: usize) -> usize {
        skip_blanks(line, pos)
    }
    /// A byte outside ASCII was read: in a LinuxCNC parameter's name in a bracketed word
    /// ([`bracket_word`]), every other byte a plain word or a bracketed one is made of being
    /// ASCII.
    #[inline(always)]
    fn not_ascii(&mut self) {}
}

impl<'a> PlainOut<'a> for Vec<Token<'a>> {
    #[inline(always)]
    fn plain(&mut self, line: &'a [u8], pos: usize, end: usize, signed: bool, digits: Digits) {
        self.push(Token {
            offset: pos,
            end,
            text: Cow::Borrowed(&line[pos..end]),
            plain: Some(u8::from(signed)),
            digits,
        });
    }

    #[inline(always)]
    fn bracketed(&mut self, line: &'a [u8], pos: usize, end: usize, _: Option<u8>) {
        self.push(Token {
            offset: pos,
            end,
            text: Cow::Borrowed(&line[pos..end]),
            plain: None,
            digits: Digits::default(),
        });
    }
}

/// The checker's words of a line, each at the column its offset gives; whether the names in
/// its bracketed words are ASCII (every other byte of a line of plain words is); with `CRS`,
/// the CRs among the blanks counted.
struct WordsOut<'w, 'a, F: Fn(usize) -> usize, const CRS: bool> {
    words: &'w mut Vec<Word<'a>>,
    walks: &'w mut LineWalks,
    at: F,
    ascii: bool,
    crs: usize,
    letters: u32,
    motion_codes_only: bool,
}

impl<'a, F: Fn(usize) -> usize, const CRS: bool> PlainOut<'a> for WordsOut<'_, 'a, F, CRS> {
    #[inline(always)]
    fn plain(&mut self, line: &'a [u8], pos: usize, end: usize, signed: bool, digits: Digits) {
        // (a plain word's address is a letter: `PLAIN_START`)
        let letter = line[pos].to_ascii_uppercase();
        self.letters |= 1 << (letter - b'A');
        if letter == b'G' {
            // G0-G3, G00-G03, G000-G003, and the planes' G17-G19, G017-G019: no sign, no
            // point, at most three digits
            let length = end - pos - 1 - usize::from(signed);
            self.motion_codes_only &= !signed
                && length <= 3
                && digits.dot as usize == length
                && digits
                    .value
                    .is_some_and(|v| v <= 3 || (17..=19).contains(&v));
        }
        self.words
            .push(Word::plain(&line[pos..end], signed, digits, (self.at)(pos)));
    }

    const WALKS: bool = true;

    #[inline(always)]
    fn bracketed(&mut self, line: &'a [u8], pos: usize, end: usize, walked: Option<u8>) {
        let i = self.words.len();
        // (its names and keys written in place by `walk_name`)
        if let Some(count) = walked.filter(|_| i < WALKED) {
            let walk = &mut self.walks.walks[i];
            walk.plain = true;
            walk.count = count;
            self.walks.set |= 1 << i;
        } else {
            self.walks.all = false;
        }
        let letter = line[pos].to_ascii_uppercase();
        self.letters |= 1 << (letter - b'A');
        self.motion_codes_only &= letter != b'G';
        self.words
            .push(Word::bracketed(&line[pos..end], (self.at)(pos)));
    }

    #[inline(always)]
    fn walk_name(&mut self, n: usize, place: (u16, u16), key: u64, hot: bool) -> bool {
        let i = self.words.len();
        if i >= WALKED {
            return false;
        }
        let walk = &mut self.walks.walks[i];
        walk.names[n] = place;
        walk.keys[n] = key;
        self.walks.all_hot &= hot;
        true
    }

    #[inline(always)]
    fn hot_name(&self, chunk: u64) -> Option<(usize, u64)> {
        let hot = self.walks.hot.iter().find(|h| h.is(chunk))?;
        Some((hot.len, hot.key))
    }

    #[inline(always)]
    fn not_ascii(&mut self) {
        self.ascii = false;
    }

    #[inline(always)]
    fn skip_blanks(&mut self, line: &[u8], mut pos: usize) -> usize {
        if !CRS {
            return skip_blanks(line, pos);
        }
        while pos < line.len() && blank(line[pos]) {
            self.crs += usize::from(line[pos] == b'\r');
            pos += 1;
        }
        pos
    }
}

/// What [`plain_line_words`] found of a line of plain words besides its words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlainLine {
    /// The line is ASCII (`line.is_ascii()`): every byte of a line of plain words is, but
    /// for a LinuxCNC parameter's name in a bracketed word, whose bytes are or'ed as it is
    /// scanned.
    pub ascii: bool,
    /// The line's CRs (a CR is a blank: one of the blanks between its words, or the last
    /// byte of a CRLF file's line), where they were asked for; else None.
    pub crs: Option<usize>,
    /// The letters of the line's words, bit `letter - 'A'` each (a lower case address as its
    /// capital): the check's `Checker::letters` of the block, found as the words are written.
    pub letters: u32,
    /// Every G word of the line is G0-G3 or a plane's G17-G19 written plainly (`G1`, `G01`,
    /// `G001`, `G17`: no sign, point,
    /// index or expression), as the check's `motion_codes_only` reads a block's codes.
    pub motion_codes_only: bool,
}

/// The words of a `line` made of plain words alone ([`plain_word`]: nearly every line of a
/// CAM program), written as the checker's [`Word`]s where they are scanned, each at the
/// column `at` gives its offset, with no token between: true, and `words` holds the words
/// [`Word::extend_of`] makes of [`tokenize`]'s tokens of the line, which has no extras. False
/// for any other line (a block skip, a `%`, a SUB, a byte-order mark, a comment, a statement,
/// anything the full reading reads): `words` then holds what it held and
/// some of the line's words, and the line is [`tokenize`]'s. Of a line of plain words, whether
/// it is ASCII and, where `crs`, its CRs ([`PlainLine`]), found on the way: a scan of the
/// line's bytes each saved (the columns given by `at` are the caller's to make right for a
/// line that is not ASCII). `walks`: the walks of its plain bracketed words for the LinuxCNC
/// rules ([`LineWalks`]; its `set` emptied and its `all` set first).
pub fn plain_line_words<'a>(
    line: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Word<'a>>,
    walks: &mut LineWalks,
    at: impl Fn(usize) -> usize,
    crs: bool,
) -> Option<PlainLine> {
    walks.set = 0;
    walks.all = true;
    walks.all_hot = true;
    if crs {
        plain_line_words_as::<true>(line, dialect, words, walks, at)
    } else {
        plain_line_words_as::<false>(line, dialect, words, walks, at)
    }
}

/// [`plain_line_words`], the CRs counted where `CRS`.
#[inline(always)]
fn plain_line_words_as<'a, const CRS: bool>(
    line: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Word<'a>>,
    walks: &mut LineWalks,
    at: impl Fn(usize) -> usize,
) -> Option<PlainLine> {
    if line.len() > MAX_BLOCK {
        return None;
    }
    let (plain, end) = plain_words_from_start::<_, CRS>(line, dialect, words, walks, at)?;
    (end >= line.len()).then_some(plain)
}

/// The plain words `text` begins with, after its blanks, scanned to where they stop (the
/// end of `text`, an LF, or a byte no plain word or blank is): that place and the words'
/// [`PlainLine`]; None where `text` begins as no line of plain words does (`%`, `/`, a DOS
/// end-of-file mark, a byte order mark). The one scan of [`plain_line_words`] and
/// [`plain_line_words_to_lf`].
#[inline(always)]
fn plain_words_from_start<'a, F: Fn(usize) -> usize, const CRS: bool>(
    text: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Word<'a>>,
    walks: &mut LineWalks,
    at: F,
) -> Option<(PlainLine, usize)> {
    let mut out = WordsOut::<_, CRS> {
        words,
        walks,
        at,
        ascii: true,
        crs: 0,
        letters: 0,
        motion_codes_only: true,
    };
    let pos = out.skip_blanks(text, 0);
    if matches!(text.get(pos), Some(&(SUB | b'%' | b'/'))) || text.starts_with(BOM) {
        return None;
    }
    let end = plain_words(text, pos, pos, dialect, &mut out);
    let plain = PlainLine {
        ascii: out.ascii,
        crs: CRS.then_some(out.crs),
        letters: out.letters,
        motion_codes_only: out.motion_codes_only,
    };
    Some((plain, end))
}

/// Whether every plain word of `dialect` is a letter, a sign, digits and a point
/// ([`plain_word`]), none a bracketed word (`bracket_word` reads those on ISO and LinuxCNC
/// where the dialect has expressions in brackets): a plain word then holds no LF, nor do the
/// blanks after it, and its line can be scanned before it is split from the lines after it
/// ([`plain_line_words_to_lf`]).
pub fn plain_words_without_brackets(dialect: &Dialect) -> bool {
    !(dialect.expressions
        && dialect.brackets
        && matches!(dialect.family, Family::LinuxCnc | Family::Iso))
}

/// [`plain_line_words`] of the line `rest` begins with (up to its first LF, or all of it)
/// where [`plain_words_without_brackets`] holds: the line's words scanned with no search for
/// its LF first (the scan stops at the LF, which no plain word or blank is), and the line's
/// length (the LF's place). None where the line is not one of plain words alone, as
/// [`plain_line_words`] finds of it (`words` then holds what it held and some of its words):
/// the same words and [`PlainLine`] where it is (a debug build reads the line split first as
/// well, and asserts them).
pub fn plain_line_words_to_lf<'a>(
    rest: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Word<'a>>,
    walks: &mut LineWalks,
    at: impl Fn(usize) -> usize,
    crs: bool,
) -> Option<(PlainLine, usize)> {
    debug_assert!(plain_words_without_brackets(dialect));
    walks.set = 0;
    walks.all = true;
    walks.all_hot = true;
    if crs {
        plain_line_words_to_lf_as::<true>(rest, dialect, words, walks, at)
    } else {
        plain_line_words_to_lf_as::<false>(rest, dialect, words, walks, at)
    }
}

/// [`plain_line_words_to_lf`], the CRs counted where `CRS`.
#[inline(always)]
fn plain_line_words_to_lf_as<'a, const CRS: bool>(
    rest: &'a [u8],
    dialect: &Dialect,
    words: &mut Vec<Word<'a>>,
    walks: &mut LineWalks,
    at: impl Fn(usize) -> usize,
) -> Option<(PlainLine, usize)> {
    let (plain, end) = plain_words_from_start::<_, CRS>(rest, dialect, words, walks, at)?;
    if end > MAX_BLOCK || rest.get(end).is_some_and(|&c| c != b'\n') {
        return None;
    }
    Some((plain, end))
}

/// The 8 bytes of `line` from `at`, as one integer (the first the lowest), where there are 8.
#[inline(always)]
fn chunk_at(line: &[u8], at: usize) -> Option<u64> {
    let chunk = line.get(at..at + 8)?;
    let mut bytes = [0u8; 8];
    bytes.copy_from_slice(chunk);
    Some(u64::from_le_bytes(bytes))
}

/// A LinuxCNC parameter's name whose 8 bytes after its `#<` are `c` (the first the lowest;
/// [`chunk_at`]), whose `>` is among them and after 1 to 7 bytes, none of them a blank
/// ([`crate::lex::BLANKS`]: below `0x21` tested, so a byte below it that is no blank is read
/// by the byte loop), `[`, `]`, `/`, DEL or outside ASCII: its length and key ([`name_key`]:
/// those bytes). None for any other, which [`bracket_word`]'s byte loop reads: of a name this
/// takes, that loop finds the same `>`, no blank, nothing that makes the walk not plain and
/// nothing outside ASCII. About 25 instructions, where the byte loop took about 10 a byte
/// (`yscale`: 65). It reads no byte after the `>`.
#[inline(always)]
fn short_name_of(c: u64) -> Option<(usize, u64)> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGHS: u64 = 0x8080_8080_8080_8080;
    let close = equal_bytes(c, b'>');
    // (the first `>`: the lowest flag, exact; the name's bytes below it)
    let len = (close.trailing_zeros() / 8) as usize;
    if len == 0 || len == 8 {
        return None;
    }
    let mask = (1u64 << (8 * len)) - 1;
    // a byte below 0x21 (`hasless`: the lowest such byte is flagged, and none below it, a
    // borrow running upward only: a flag among the name's bytes says one is there), DEL, a
    // bracket, a `/`, or a high bit
    let low = c.wrapping_sub(ONES * 0x21) & !c & HIGHS;
    let odd = equal_bytes(c, 0x7F)
        | equal_bytes(c, b'[')
        | equal_bytes(c, b']')
        | equal_bytes(c, b'/')
        | (c & HIGHS);
    ((low | odd) & mask == 0).then_some((len, c & mask))
}

/// [`bracket_word`]'s reading of a LinuxCNC parameter's name at `line[name..]` (after its
/// `#<`) that is none of the hot ones: the offset of its `>`, its key ([`name_key`]), the
/// kinds of its bytes ([`NAME_BYTES`] or'ed) and whether they are ASCII; None where the full
/// reading reads it (no `>`, an empty name, a blank in it). A name of 1 to 7 bytes of ASCII
/// that are no blank, bracket or `/` (`yscale`), its `>` among the 8 bytes after the `#<`, is
/// read at once, its key those bytes ([`short_name_of`]); any other by the byte loop. Out of
/// line: most names of a CAM program's lines are hot.
#[inline(never)]
fn cold_name(line: &[u8], name: usize) -> Option<(usize, u64, u8, bool)> {
    if let Some((len, key)) = chunk_at(line, name).and_then(short_name_of) {
        return Some((name + len, key, 0, true));
    }
    let n = line.len();
    let mut i = name;
    // (the name's bytes or'ed: the one part of the word that may be outside ASCII; their
    // kinds or'ed: a blank, or what makes the walk not plain)
    let mut bytes = 0u8;
    let mut kinds = 0u8;
    while i < n && line[i] != b'>' {
        kinds |= NAME_BYTES[usize::from(line[i])];
        bytes |= line[i];
        i += 1;
    }
    if i == n || i == name || kinds & NAME_BLANK != 0 {
        return None;
    }
    Some((i, name_key(line, name, i - name), kinds, bytes.is_ascii()))
}

/// The deepest brackets [`bracket_word`] reads; deeper ones (up to [`expr::MAX_DEPTH`]) are the
/// full reading's.
const BRACKET_DEPTH: u32 = 16;

/// [`plain_word`]'s reading of a letter followed by a bracketed expression written without
/// blanks (`Y[#<yscale>*-32.725]`, `Z[[#1+2]*.5]`, most words of a LinuxCNC program with scale
/// factors), on ISO and LinuxCNC, whose word takes one bracketed operand
/// ([`expr::scan_operand`]): its `[`s, operands and operators read in one pass by their shape,
/// and the token borrowed from the line. An operand is optional signs, then a number (digits,
/// an optional point, a digit at least), `#` and digits, LinuxCNC's `#<name>`, or a `[` that
/// opens a group; after it comes an operator (`+ - /`, `*` where the dialect has it, `**`
/// inside LinuxCNC's brackets) or a `]`. Anything else -- a blank, a function or a word
/// operator, `P1`, `#[..]`, `#<>`, a bracket left open, nesting deeper than
/// [`BRACKET_DEPTH`], an error -- is None: the full reading's ([`word`]), so this decides
/// nothing of its own. The expression scanner re-dispatched every character through its
/// descent (`sum`, `product`, `unary`, `atom`, each a call), about 1,000 instructions of
/// 3D_Chips' 2,180 a block.
#[inline(never)]
fn bracket_word<'a, O: PlainOut<'a>>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut O,
) -> Option<usize> {
    let linuxcnc = dialect.family == Family::LinuxCnc;
    if !(dialect.expressions && dialect.brackets && (linuxcnc || dialect.family == Family::Iso)) {
        return None;
    }
    let n = line.len();
    let mut i = pos + 2;
    let mut depth: u32 = 1;
    // the walk for the LinuxCNC rules (`O::WALKS`): whether the expression is plain (no
    // inner bracket, no `/`, no bracket or `/` in a name, at most four names), and its names'
    // `#` and `>` from the expression's `[` (`pos + 1`), written where the walk is kept
    // (`PlainOut::walk_name`), `count` of them
    let mut plain = O::WALKS && linuxcnc;
    let mut count = 0usize;
    loop {
        // an operand, after its signs
        while i < n && matches!(line[i], b'+' | b'-') {
            i += 1;
        }
        match *line.get(i)? {
            b'[' => {
                depth += 1;
                if depth > BRACKET_DEPTH {
                    return None;
                }
                plain = false;
                i += 1;
                continue;
            }
            b'0'..=b'9' | b'.' => {
                let start = i;
                while i < n && line[i].is_ascii_digit() {
                    i += 1;
                }
                let whole = i > start;
                if i < n && line[i] == b'.' {
                    i += 1;
                    let fraction = i;
                    while i < n && line[i].is_ascii_digit() {
                        i += 1;
                    }
                    if !whole && i == fraction {
                        return None;
                    }
                } else if !whole {
                    return None;
                }
            }
            b'#' if dialect.hash => match *line.get(i + 1)? {
                b'0'..=b'9' => {
                    i += 2;
                    while i < n && line[i].is_ascii_digit() {
                        i += 1;
                    }
                }
                b'<' if linuxcnc => {
                    let hash = i;
                    let name = i + 2;
                    // a hot name (`PlainOut::hot_name`) read by a compare of its 8 bytes;
                    // any other by `cold_name`
                    let hot = chunk_at(line, name).and_then(|c| {
                        let found = words.hot_name(c);
                        debug_assert!(found.is_none() || short_name_of(c) == found);
                        found
                    });
                    let (key, kinds, hot) = if let Some((len, key)) = hot {
                        i = name + len;
                        (key, 0, true)
                    } else {
                        let (close, key, kinds, ascii) = cold_name(line, name)?;
                        if !ascii {
                            words.not_ascii();
                        }
                        i = close;
                        (key, kinds, false)
                    };
                    if plain {
                        // (below 65,536: a line is at most MAX_BLOCK bytes, the `[` at
                        // `pos + 1` at least)
                        let place = ((hash - pos - 1) as u16, (i - pos - 1) as u16);
                        if kinds != 0 || count == 4 || !words.walk_name(count, place, key, hot) {
                            plain = false;
                        } else {
                            count += 1;
                        }
                    }
                    i += 1;
                }
                _ => return None,
            },
            _ => return None,
        }
        // after an operand: its operator, or the `]`s that close groups
        loop {
            match line.get(i) {
                Some(b']') => {
                    i += 1;
                    depth -= 1;
                    if depth == 0 {
                        let after = words.skip_blanks(line, i);
                        words.bracketed(line, pos, i, plain.then_some(count as u8));
                        return Some(after);
                    }
                }
                Some(b'+' | b'-') => {
                    i += 1;
                    break;
                }
                Some(b'/') => {
                    plain = false;
                    i += 1;
                    break;
                }
                Some(b'*') if linuxcnc && line.get(i + 1) == Some(&b'*') => {
                    i += 2;
                    break;
                }
                Some(b'*') if dialect.star => {
                    i += 1;
                    break;
                }
                _ => return None,
            }
        }
    }
}

/// Read the word at `pos` (its address character); push its token; return the offset after it.
fn word<'a>(
    line: &'a [u8],
    start: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<usize, LexError> {
    let n = line.len();
    let address = line[start];
    let mut pos = skip_blanks(line, start + 1);
    // whether a blank was skipped inside the word: else its text is borrowed as it stands,
    // with no second look at every byte for a blank to drop
    let mut spaced = pos > start + 1;
    if spaced && dialect.ngc && number_ahead(line, pos) {
        return Err(apart(address, start + 1));
    }
    let mut indexed = false;
    let digits_start = pos;
    // (the digits' value is read on the way: the number's, where they are its whole part)
    let (digits_end, whole) = if address == b'#' && dialect.family == Family::LinuxCnc {
        // rs274 drops the blanks of a line before it reads it (close_and_downcase): the
        // parameter set by `#1 2 = 3` is #12
        let end = expr::spaced_digits_end(line, pos);
        spaced |= line[pos..end].iter().any(|&b| blank(b));
        (end, 0)
    } else {
        digits_read(line, pos)
    };
    if digits_end > pos {
        let after = skip_blanks(line, digits_end);
        if after < n && line[after] == b'=' {
            indexed = true;
            // (a SINUMERIK's indexed words, R0 among them, are the statement reader's)
            if address != b'#' && line[pos..digits_end].iter().all(|&d| d == b'0') {
                return Err(err(
                    ErrorKind::Index,
                    format!(
                        "address index of {} must be greater than 0",
                        address as char
                    ),
                    pos,
                    "6.2",
                ));
            }
            pos = skip_blanks(line, after + 1);
            spaced |= after > digits_end || pos > after + 1;
        }
    }
    if address == b'#' && !indexed {
        if dialect.family == Family::MacroB && digits_end > pos {
            if let Some(mut e) = expr::variable_with_decimals(line, start, digits_end) {
                if dialect.ngc {
                    // a Haas reads one (TG212); what setting one does, no source says
                    let text = e.message.split(' ').nth(1).unwrap_or("").to_owned();
                    e.message = format!(
                        "variable {text} has a decimal part: a Haas NGC parameter element such \
                         as {text} is read as a value tapegate does not know, but set here, \
                         which no Haas source at hand documents (what the assignment changes on \
                         the machine is not known)"
                    );
                }
                return Err(e);
            }
        }
        return Err(err(
            ErrorKind::Value,
            "'#' parameter must be written #n = value".into(),
            start,
            "6.4.7",
        ));
    }
    let value_start = pos;
    let mut signed = 0;
    if pos < n && (line[pos] == b'+' || line[pos] == b'-') {
        let sign = pos;
        signed = 1;
        pos = skip_blanks(line, pos + 1);
        spaced |= pos > sign + 1;
        // `X- 1.`: the number written apart from its address's sign, as `X 1.` is apart from
        // its address: the same NGC alarm (the number is not where the address ends). After
        // `#8=` no address waits for its number: the value is an arithmetic expression (Haas
        // 96-8000, "Macros", "Arithmetic Expressions"), read as `#8= - #4` and `#8= 5. - 20.`
        if dialect.ngc
            && !indexed
            && pos > sign + 1
            && matches!(line.get(pos), Some(b'0'..=b'9' | b'.'))
        {
            return Err(apart(address, sign + 1));
        }
    }
    let number = if pos == digits_start {
        // no index and no sign: the number's digits are those read above
        number_read(line, pos, digits_end, whole)
    } else {
        let (i, whole) = digits_read(line, pos);
        number_read(line, pos, i, whole)
    };
    // LinuxCNC reads a number through blanks (`X1 2.5` is X12.5): read again so only where a
    // digit or a point stands after the blanks that follow the number read without them, or
    // where that reading found none (`X. 5`); in nearly every word the next is a letter
    let through_blanks = dialect.family == Family::LinuxCnc
        && number.is_none_or(|(end, _)| {
            matches!(line.get(skip_blanks(line, end)), Some(b'0'..=b'9' | b'.'))
        });
    let number = if through_blanks {
        expr::spaced_number_end(line, pos).map(|end| (end, Digits::default()))
    } else {
        number
    };
    if let Some((end, digits)) = number {
        spaced |= through_blanks && line[pos..end].iter().any(|&b| blank(b));
        let probe = skip_blanks(line, end);
        let operator = match line.get(probe) {
            Some(b'+' | b'-' | b'/') => true,
            Some(b'*') => dialect.star,
            _ => false,
        };
        if !(indexed && operator && dialect.expressions) {
            let text = if spaced {
                compact(line, start, end)
            } else {
                Cow::Borrowed(&line[start..end])
            };
            let digits = if through_blanks && !indexed {
                Digits::of(&text[1 + usize::from(signed)..])
            } else {
                digits
            };
            words.push(Token {
                offset: start,
                end,
                text,
                // (the address, the sign and the number, blanks left out: Word::of's parts)
                plain: (!indexed).then_some(signed),
                digits: if indexed { Digits::default() } else { digits },
            });
            return Ok(end);
        }
    }
    // LinuxCNC reads a word's value as rs274 `read_real_value` does: signs before any value
    // (`X--1` is X1, `X-#1`, `X-[1]`) and a unary function (`Xsin[30]`, `X-abs[#1]`)
    let mut operand_at = pos;
    if dialect.family == Family::LinuxCnc && !indexed {
        while matches!(line.get(operand_at), Some(b'+' | b'-')) {
            operand_at = skip_blanks(line, operand_at + 1);
        }
    }
    let operand = !indexed
        && match line.get(operand_at) {
            Some(b'#') => dialect.hash && dialect.brackets,
            // a SINUMERIK's `[ ]` holds an index: an address takes an expression after `=`
            Some(b'[') => dialect.brackets && dialect.family != Family::Sinumerik,
            Some(c) if dialect.family == Family::LinuxCnc && c.is_ascii_alphabetic() => {
                dialect.brackets && expr::function_ahead(line, operand_at)
            }
            Some(b'0'..=b'9' | b'.') => operand_at > pos,
            _ => false,
        };
    if !dialect.expressions || !(indexed || operand) {
        if mirrored_axis(dialect, address, line, pos, words) {
            words.push(Token {
                offset: start,
                end: start + 1,
                text: Cow::Borrowed(&line[start..start + 1]),
                plain: Some(0),
                digits: Digits::default(),
            });
            return Ok(start + 1);
        }
        let letter = address as char;
        if pos >= n || matches!(line[pos], b' ' | b'\t' | b'\r') {
            return Err(err(
                ErrorKind::Value,
                format!("address {letter} has no value"),
                start,
                "6.1",
            ));
        }
        if line[pos] == b'=' && !indexed {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "address {letter} has '=' but no index: a parameter is set with its index, \
                     as in {letter}1 = 22.2"
                ),
                pos,
                "6.4.7",
            ));
        }
        if dialect.family == Family::Sinumerik && matches!(line[pos], b'[' | b'(') {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "address {letter} takes a number, or '=' before a variable or an expression \
                     ({letter}=R2+10): a SINUMERIK requires the '=' where the value is more than \
                     one constant, and '[ ]' hold an index (Programming Manual Fundamentals, \
                     'Value assignments')"
                ),
                pos,
                "6.1",
            ));
        }
        let (c, _) = Char::at(line, pos);
        let shown = if c.printable() { c.repr() } else { c.code() };
        return Err(err(
            ErrorKind::Value,
            format!("address {letter} must be followed by a number, found {shown}"),
            pos,
            "6.1",
        ));
    }
    // Macro B reads X#114-#136 and X-#1 as the expressions they are; ISO and LinuxCNC take one
    // operand (a bracketed group or a parameter) after the address.
    let end = if indexed || (dialect.family == Family::MacroB && operand) {
        expr::scan(line, value_start, dialect.syntax())?
    } else {
        expr::scan_operand(line, operand_at, dialect.syntax())?
    };
    words.push(Token {
        offset: start,
        end,
        text: compact(line, start, end),
        plain: None,
        digits: Digits::default(),
    });
    Ok(end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rules::Rule;

    #[test]
    fn a_short_name_is_read_at_once_as_the_byte_loop_reads_it() {
        // drawn bytes after `#<`: letters, `>`, blanks, bytes below 0x21 that are no blank,
        // DEL, brackets, `/`, bytes outside ASCII; `short_name_of` takes a name only where the
        // byte loop finds its `>` after 1 to 7 bytes, none a blank, a bracket, a `/` or outside
        // ASCII (and DEL, a blank), and then the same length and the key `name_key` gives;
        // it takes every such name with 8 bytes after the `#<`
        let alphabet = b"abyZ_09>>> \t\r\x00\x0c\x1f\x7f[]/\xc3\x80!~";
        let mut next = crate::drawn::xorshift(0x51_7CC1_B727_220A);
        let mut taken = 0;
        for _ in 0..200_000 {
            let len = (next() % 12) as usize;
            let line: Vec<u8> = (0..len)
                .map(|_| alphabet[(next() % alphabet.len() as u64) as usize])
                .collect();
            let close = line.iter().position(|&c| c == b'>');
            let clean = close.is_some_and(|close| {
                (1..8).contains(&close)
                    && line[..close]
                        .iter()
                        .all(|&c| NAME_BYTES[usize::from(c)] == 0 && c.is_ascii() && c >= 0x21)
            });
            let found = chunk_at(&line, 0).and_then(short_name_of);
            if let Some((n, key)) = found {
                taken += 1;
                assert_eq!(Some(n), close, "{line:?}");
                assert!(clean, "{line:?}");
                assert_eq!(key, name_key(&line, 0, n), "{line:?}");
            } else {
                assert!(!clean || line.len() < 8, "{line:?}");
            }
        }
        assert!(taken > 5_000, "{taken}");
    }

    #[test]
    fn a_hot_name_is_read_as_the_short_name_reading_reads_it() {
        // a hot name is one `short_name_of` takes, and only such a name
        let key = |name: &[u8]| name_key(name, 0, name.len());
        for name in [&b"yscale"[..], b"a", b"Z_0~!", b"abcdefg"] {
            let hot = HotName::of_key(key(name)).expect("a short name");
            assert_eq!((hot.len, hot.key()), (name.len(), key(name)));
        }
        for name in [
            &b"abcdefgh"[..],
            b"",
            b"y\x7fs",
            b"a/b",
            b"a[",
            b"\xc3\xa9",
            b"a b",
        ] {
            assert_eq!(HotName::of_key(key(name)), None, "{name:?}");
        }
        // LinuxCNC lines of bracketed words whose names are drawn from names a hot one is,
        // begins or ends, and names the short reading does not take; read with hot names and
        // with none: the same words and walks, and `all_hot` where each walked name is one
        // of the hot names and has its 8 bytes after the `#<` in the line
        let names: [&[u8]; 10] = [
            b"yscale",
            b"zscale",
            b"yscal",
            b"yscalex",
            b"Yscale",
            b"abcdefg",
            b"abcdefgh",
            b"y\x7fs",
            b"\xc3\xa9",
            b"z",
        ];
        let hot = [
            HotName::of_key(key(b"yscale")).unwrap(),
            HotName::NONE,
            HotName::of_key(key(b"abcdefg")).unwrap(),
            HotName::of_key(key(b"z")).unwrap(),
        ];
        let dialect = Dialect::permissive(Family::LinuxCnc);
        let mut next = crate::drawn::xorshift(0x2545_F491_4F6C_DD1D);
        let (mut all_hot, mut not) = (0, 0);
        for _ in 0..20_000 {
            let mut line = Vec::new();
            for _ in 0..1 + next() % 3 {
                line.push(b"XYZF"[(next() % 4) as usize]);
                line.push(b'[');
                for k in 0..1 + next() % 3 {
                    if k > 0 {
                        line.extend_from_slice(
                            [&b"*"[..], b"+", b"/", b"**"][(next() % 4) as usize],
                        );
                    }
                    if next().is_multiple_of(4) {
                        line.extend_from_slice(b"-1.5");
                    } else {
                        line.extend_from_slice(b"#<");
                        // (half of them hot)
                        let n = next();
                        line.extend_from_slice(if n.is_multiple_of(2) {
                            [&b"yscale"[..], b"z", b"abcdefg"][(n / 2 % 3) as usize]
                        } else {
                            names[(n / 2 % names.len() as u64) as usize]
                        });
                        line.push(b'>');
                    }
                }
                line.push(b']');
                if next().is_multiple_of(3) {
                    line.push(b' ');
                }
            }
            let read = |hot: [HotName; HOT]| {
                let mut words = Vec::new();
                let mut walks = LineWalks {
                    hot,
                    ..LineWalks::default()
                };
                let found = plain_line_words(&line, &dialect, &mut words, &mut walks, |o| o, false);
                let words: Vec<_> = words
                    .iter()
                    .map(|w| (w.token, w.column, w.expression))
                    .collect();
                (found, words, walks)
            };
            let (found, words, walks) = read(hot);
            let (cold_found, cold_words, cold_walks) = read([HotName::NONE; HOT]);
            let shown = String::from_utf8_lossy(&line);
            assert_eq!((found, &words), (cold_found, &cold_words), "{shown}");
            assert_eq!(
                (walks.set, walks.all),
                (cold_walks.set, cold_walks.all),
                "{shown}"
            );
            assert_eq!(walks.walks, cold_walks.walks, "{shown}");
            if found.is_none() {
                continue;
            }
            // each walked name: its `#` and `>` from the `[`, the `[` at the word's column + 1
            // (`all_hot` is kept for a line whose every bracketed word is walked: of another,
            // a name read before its word's walk was given up may have cleared it)
            let (mut expected, mut named) = (true, false);
            for (i, walk) in walks.walks.iter().enumerate().take(words.len()) {
                if walks.set >> i & 1 == 0 {
                    continue;
                }
                for &(hash, close) in &walk.names[..usize::from(walk.count)] {
                    let from = words[i].1 + 1 + usize::from(hash) + 2;
                    let name = &line[from..words[i].1 + 1 + usize::from(close)];
                    named = true;
                    expected &= from + 8 <= line.len()
                        && hot
                            .iter()
                            .any(|h| h.len == name.len() && h.key() == key(name));
                }
            }
            if walks.all {
                assert_eq!(walks.all_hot, expected, "{shown}");
                assert_eq!(cold_walks.all_hot, !named, "{shown}");
                if named && expected {
                    all_hot += 1;
                } else if named {
                    not += 1;
                }
            } else {
                assert!(!walks.all_hot || expected, "{shown}");
            }
        }
        assert!(all_hot > 2_000 && not > 2_000, "{all_hot} {not}");
    }

    const STRICT: Dialect = Dialect {
        family: Family::Iso,
        lowercase: false,
        hash: false,
        brackets: false,
        semicolon: false,
        star: false,
        expressions: true,
        ngc: false,
    };
    const PERMISSIVE: Dialect = Dialect::permissive(Family::Iso);

    fn read(text: &str, d: &Dialect) -> Result<(Vec<String>, Reading<'static>), (String, usize)> {
        let line: &'static [u8] = Box::leak(text.as_bytes().to_vec().into_boxed_slice());
        let mut words = Vec::new();
        match tokenize(line, d, &mut words) {
            Ok(extras) => Ok((
                words
                    .iter()
                    .map(|w| String::from_utf8_lossy(&w.text).into_owned())
                    .collect(),
                extras,
            )),
            Err(e) => Err((e.message, e.offset)),
        }
    }

    fn words(text: &str, d: &Dialect) -> Vec<String> {
        read(text, d).expect("a valid block").0
    }

    #[test]
    fn words_after_a_fanuc_semicolon_are_refused_where_the_first_one_stands() {
        let fanuc = Dialect::permissive(Family::MacroB);
        // the end of block as the control shows it, a comment or blanks after it: read
        assert_eq!(words("G00 X1.;", &fanuc), ["G00", "X1."]);
        assert_eq!(words("G00 X1.; (NEXT) ;\r", &fanuc), ["G00", "X1."]);
        assert_eq!(words("O0064;", &fanuc), ["O0064"]);
        // words after it: a block the control runs or an alarm, never a comment
        let (message, at) = read("G00 X1.; G01 X2. F100.", &fanuc).unwrap_err();
        assert_eq!(at, 9);
        assert!(message.starts_with("words after ';'"), "{message}");
        assert_eq!(read("; G00 X500. Y500.", &fanuc).unwrap_err().1, 2);
        assert_eq!(read("G00 X1.;(A) M08", &fanuc).unwrap_err().1, 12);
        // LinuxCNC and SINUMERIK: ';' starts a comment to the end of the line
        for family in [Family::LinuxCnc, Family::Sinumerik] {
            let d = Dialect::permissive(family);
            assert_eq!(words("G0 X1 ; G1 X2", &d), ["G0", "X1"]);
        }
    }

    /// The one-pass reading of plain words against the full reading alone, on every family
    /// and the dialect's switches: the same tokens (text, offsets, sign, digits), extras and
    /// errors on a million lines of the characters that decide a word (letters a statement or
    /// an index may begin, signs, points, blanks, `=`, brackets, operators, comments), on
    /// 300,000 bracketed words of the tokens of an expression and its mistakes, and on the plain
    /// and bracketed words of CAM programs with what may follow them.
    #[test]
    fn plain_words_are_read_in_one_pass_as_the_full_reading_reads_them() {
        const BYTES: &[u8] = b"XGNROoxnr#=+-.0123456789 \t\r[]()*/;:,IFEQ<>\xc3\xa9";
        let mut next = crate::drawn::xorshift(0x9E37_79B9_7F4A_7C15);
        let families = Family::ALL;
        let mut dialects = Vec::new();
        for family in families {
            dialects.push(Dialect::permissive(family));
            dialects.push(Dialect { family, ..STRICT });
            dialects.push(Dialect {
                ngc: true,
                lowercase: false,
                ..Dialect::permissive(family)
            });
        }
        let (plain_lines, other_lines) = (std::cell::Cell::new(0), std::cell::Cell::new(0));
        let walked = std::cell::Cell::new(0);
        let same = |line: &[u8], dialect: &Dialect| {
            let (mut fast, mut full) = (Vec::new(), Vec::new());
            let a = tokenize_as::<true>(line, dialect, &mut fast);
            let b = tokenize_as::<false>(line, dialect, &mut full);
            assert_eq!(a, b, "{:?} {dialect:?}", String::from_utf8_lossy(line));
            assert_eq!(
                fast,
                full,
                "{:?} {dialect:?}",
                String::from_utf8_lossy(line)
            );
            // a line of plain words alone: its words written where they are scanned are the
            // words of its tokens, at the same columns (a column an offset, or a count of
            // characters: both ways of `at`)
            let mut words = vec![Word::new(b"G1", 1)];
            let at = |offset: usize| 3 * offset + 7;
            // (with the CRs counted or not: the same words, the CRs all the line's)
            let crs = line.len().is_multiple_of(2);
            let mut walks = LineWalks {
                set: 0xFF,
                ..LineWalks::default()
            };
            if let Some(found) = plain_line_words(line, dialect, &mut words, &mut walks, at, crs) {
                plain_lines.set(plain_lines.get() + 1);
                // the walk written of a bracketed word is the check's own walk of its
                // expression, and a plain one's is written (the other words' bits not set)
                for (i, w) in words.iter().enumerate().take(WALKED) {
                    let own = crate::check::walk_expression(w.expression);
                    let written = walks.set >> i & 1 != 0;
                    if written {
                        assert_eq!(walks.walks[i], own, "{:?}", String::from_utf8_lossy(line));
                        walked.set(walked.get() + 1);
                    } else {
                        assert!(
                            !own.plain || dialect.family != Family::LinuxCnc,
                            "{:?}: a plain expression not walked",
                            String::from_utf8_lossy(line)
                        );
                    }
                }
                // `all`: every bracketed word's walk written, and only then
                let unwritten = words.iter().enumerate().any(|(i, w)| {
                    !w.expression.is_empty() && (i >= WALKED || walks.set >> i & 1 == 0)
                });
                assert_eq!(
                    walks.all,
                    !unwritten,
                    "{:?} {dialect:?}",
                    String::from_utf8_lossy(line)
                );
                let counted = line.iter().filter(|&&c| c == b'\r').count();
                // the letters and the plain motion codes of the words written (the first
                // word was there before)
                let letters = words[1..]
                    .iter()
                    .fold(0, |l, w| l | crate::modal::bit(w.letter));
                let motion_codes_only = crate::check::motion_codes_only(&words[1..]);
                assert_eq!(
                    found,
                    PlainLine {
                        ascii: line.is_ascii(),
                        crs: crs.then_some(counted),
                        letters,
                        motion_codes_only,
                    },
                    "{:?} {dialect:?}",
                    String::from_utf8_lossy(line)
                );
                assert_eq!(
                    a,
                    Ok(None),
                    "{:?} {dialect:?}",
                    String::from_utf8_lossy(line)
                );
                let mut read = vec![Word::new(b"G1", 1)];
                Word::extend_of(&mut read, &fast, at);
                assert_eq!(words.len(), read.len());
                for (w, r) in words.iter().zip(&read) {
                    #[allow(clippy::type_complexity)]
                    fn parts<'w>(
                        w: &Word<'w>,
                    ) -> (u8, u8, [&'w [u8]; 5], usize, bool, usize, Option<u64>)
                    {
                        let texts = [w.index, w.sign, w.number, w.expression, w.token];
                        (
                            w.address, w.letter, texts, w.column, w.point, w.dot, w.value,
                        )
                    }
                    assert_eq!(parts(w), parts(r), "{:?}", String::from_utf8_lossy(line));
                }
            } else {
                // (the full reading's, always right: a fallback, never a difference)
                other_lines.set(other_lines.get() + 1);
            }
        };
        let plain = [
            "N1000 X2.756 Y78.188 I4.199 J-10.371",
            "G1 X-27.964 Y-14.678 Z.5 F1200.",
            "N430X2.9919Y-2.4502Z-0.6393",
            "G01 X+1. Y-.5 Z0 ",
            "X1 2.5",
            "X1 =2",
            "X1.5=2",
            "N10 N20 G0",
            "x1 y2 n3",
            "O1000 X1",
            "R1=5 R-2. R.5",
            "X- 1.",
            "X.",
            "X-.",
            "G28 X Y *",
            "X12345678901234567890.5 Y1.23456789012345678",
            "X1.5+2",
            "X1.5 /2",
            "N80G0X[#<xscale>*53.]Y[#<yscale>*-56.128]",
            "G1 Z[[#1+2.]*-.5/#<z>**2] F[#<f>]",
            "X[1,2] Y[1 ] Z[#<a b>] A[#<>] B[#[1]] C[sin[30]]",
            "X[#<a>*P1] Y[1.2.3] Z[.] A[-#1] B[--1] U[1]*2 V[1]]",
            "X[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]] Y[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]",
            "X[#<a",
            "X[1",
            "X[",
            "G1 X1.\r",
            " \r X1 \rY2\t\r",
            "N10 X[#<\u{e9}t\u{e9}>*2] Y1.5\r",
        ];
        for dialect in &dialects {
            for text in plain {
                same(text.as_bytes(), dialect);
            }
        }
        // bracketed words: a letter and `[`, then the characters of an expression
        // bracketed words: a letter and `[`, then the tokens of an expression and its mistakes
        const EXPR: &[&[u8]] = &[
            b"[",
            b"[",
            b"]",
            b"]",
            b"]",
            b"1",
            b"25.",
            b".5",
            b"3.75",
            b".",
            b"#1",
            b"#<a>",
            b"#<",
            b"#<>",
            b"#<a b>",
            b"#<\xe9>",
            b"#<a\r>",
            b"#",
            b">",
            b"+",
            b"-",
            b"*",
            b"**",
            b"/",
            b" ",
            b",",
            b"P1",
            b"sin",
            b"AND",
            b"x",
            b"=",
            b"0",
            b"#<yscale>",
            b"#<long_name_1>",
            b"#<a/b>",
            b"#<a[b>",
            b"#<a]b>",
            b"#<_x>",
            b"#<A>",
            b"#<a#<b>",
        ];
        let mut line = Vec::new();
        for _ in 0..300_000 / dialects.len() {
            line.clear();
            line.extend_from_slice(if next().is_multiple_of(4) {
                b"n["
            } else {
                b"X["
            });
            let len = (next() % 12) as usize;
            for _ in 0..len {
                line.extend_from_slice(EXPR[(next() % EXPR.len() as u64) as usize]);
            }
            if next().is_multiple_of(2) {
                line.extend_from_slice(b"]Y1");
            }
            // (more bracketed words after it: the walks are by the word's place)
            if next().is_multiple_of(3) {
                line.extend_from_slice(b" Z[#<zscale>*-27.725]A[#1+#<a>-#<b>*#<c>**#<d>]");
            }
            for dialect in &dialects {
                same(&line, dialect);
            }
        }
        // well-formed expressions (an operand, then operators and operands), most of them
        // read by the one pass, so that the walks are asserted on many: named parameters
        // (short, long, upper case, with a bracket or `/` in the name, more than four),
        // numbered ones, signs, inner groups, `/` and `**`
        const OPERANDS: &[&[u8]] = &[
            b"#<yscale>",
            b"#<a>",
            b"#<_x>",
            b"#<Long_Name_12>",
            b"#<a/b>",
            b"#<a[b>",
            b"#<a]b>",
            b"#1",
            b"#31",
            b"-56.128",
            b"1.",
            b".5",
            b"+2",
            b"--3",
            b"[1+#<z>]",
            b"[#<a>]",
        ];
        const OPERATORS: &[&[u8]] = &[b"*", b"*", b"+", b"-", b"/", b"**"];
        let linuxcnc: Vec<&Dialect> = dialects
            .iter()
            .filter(|d| d.family == Family::LinuxCnc)
            .collect();
        for _ in 0..60_000 {
            line.clear();
            if next().is_multiple_of(3) {
                line.extend_from_slice(b"G1 ");
            }
            for word in 0..1 + next() % 3 {
                line.extend_from_slice(if word % 2 == 0 { b"Y[" } else { b"z[" });
                line.extend_from_slice(OPERANDS[(next() % OPERANDS.len() as u64) as usize]);
                for _ in 0..next() % 6 {
                    line.extend_from_slice(OPERATORS[(next() % OPERATORS.len() as u64) as usize]);
                    line.extend_from_slice(OPERANDS[(next() % OPERANDS.len() as u64) as usize]);
                }
                line.push(b']');
            }
            same(&line, linuxcnc[(next() % linuxcnc.len() as u64) as usize]);
        }
        for _ in 0..1_000_000 / dialects.len() {
            line.clear();
            let len = 1 + (next() % 14) as usize;
            for _ in 0..len {
                line.push(BYTES[(next() % BYTES.len() as u64) as usize]);
            }
            for dialect in &dialects {
                same(&line, dialect);
            }
        }
        // both ways are taken, many times
        assert!(plain_lines.get() > 5_000, "{}", plain_lines.get());
        assert!(walked.get() > 10_000, "{}", walked.get());
        assert!(other_lines.get() > 50_000, "{}", other_lines.get());
    }

    #[test]
    fn the_sinumerik_first_look_finds_no_statement_the_reader_would() {
        // every pair of characters the tokenizer passes the SINUMERIK reader by, followed by
        // what may follow them: the reader itself finds no statement there either
        let dialect = Dialect::permissive(Family::Sinumerik);
        let tails: [&[u8]; 7] = [b"", b"5", b"=5", b" =5", b"AB=1", b"[1]=2", b"(1)"];
        let mut passed = 0;
        for first in 0..=127u8 {
            for second in 0..=127u8 {
                for tail in tails {
                    let mut line = vec![first, second];
                    line.extend_from_slice(tail);
                    if !statement::sinumerik_word_ahead(&line, 0) {
                        continue;
                    }
                    passed += 1;
                    reads_no_statement(&line, &dialect);
                }
            }
        }
        // letters and a sign, point or digit; R with a digit is the reader's (R1=R2*5), and
        // so is any letter whose digits `=` follows (an extended address, S1=5), two tails
        assert_eq!(passed, tails.len() * (52 * 13 - 2 * 10) - 2 * (50 * 10));
        assert!(!statement::sinumerik_word_ahead(b"S1=INI[53]", 0));
        assert!(!statement::sinumerik_word_ahead(b"R1=R2*5", 0));
        assert!(!statement::sinumerik_word_ahead(b"TURN=0", 0));
    }

    /// The statement reader finds no statement at the start of `line` (a first look's pass).
    fn reads_no_statement(line: &[u8], dialect: &Dialect) {
        let mut words = Vec::new();
        let read = statement::read(line, 0, dialect, &mut words);
        assert!(
            matches!(read, Ok(None)) && words.is_empty(),
            "{:?}",
            String::from_utf8_lossy(line)
        );
    }

    #[test]
    fn the_linuxcnc_first_look_finds_no_statement_the_reader_would() {
        // every character the tokenizer passes the LinuxCNC reader by, followed by what may
        // follow it: the reader itself finds no statement there either
        let dialect = Dialect::permissive(Family::LinuxCnc);
        let tails: [&[u8]; 6] = [b"", b"5", b"100 if [1]", b"<name> call", b"=5", b" 1"];
        let mut passed = 0;
        for first in 0..=127u8 {
            for tail in tails {
                let mut line = vec![first];
                line.extend_from_slice(tail);
                if !statement::linuxcnc_word_ahead(first) {
                    continue;
                }
                passed += 1;
                reads_no_statement(&line, &dialect);
            }
        }
        // the letters but O and o
        assert_eq!(passed, tails.len() * 50);
        assert!(!statement::linuxcnc_word_ahead(b'o'));
        assert!(!statement::linuxcnc_word_ahead(b'#'));
    }

    #[test]
    fn plain_and_glued_words() {
        assert_eq!(
            words("N10 G01 X12.5 Y-3 F200\r", &STRICT),
            ["N10", "G01", "X12.5", "Y-3", "F200"]
        );
        assert_eq!(words("N20G01X1Y2", &STRICT), ["N20", "G01", "X1", "Y2"]);
        assert_eq!(words("X - 5 Y.5", &STRICT), ["X-5", "Y.5"]);
        assert!(read("N1 X1", &STRICT).unwrap().1.is_none());
    }

    #[test]
    fn extras_skip_comments_percent_alignment() {
        let (w, extras) = read("/N30 X1 (COMMENT) Y2", &STRICT).unwrap();
        let extras = extras.unwrap();
        assert_eq!(w, ["N30", "X1", "Y2"]);
        assert_eq!(extras.skip, b'/');
        assert_eq!(extras.comments, vec![(8, &b"(COMMENT)"[..])]);
        assert_eq!(read("/2 N31", &STRICT).unwrap().1.unwrap().skip, b'2');
        let percent = read("\0\0%(PART 1)\r", &STRICT).unwrap().1.unwrap();
        assert!(percent.percent);
        assert_eq!(percent.ident, b"(PART 1)");
        assert_eq!(words(":40 R11 = 22.2", &STRICT), [":40", "R11=22.2"]);
    }

    #[test]
    fn a_skip_in_the_middle_of_a_block_is_read_on_a_fanuc_or_haas() {
        let macro_b = Dialect {
            family: Family::MacroB,
            ..PERMISSIVE
        };
        // the words after the slash are the block's words; the slash keeps its place
        let (w, extras) = read("G00 X10. /Y20. M08", &macro_b).unwrap();
        assert_eq!(w, ["G00", "X10.", "Y20.", "M08"]);
        let extras = extras.unwrap();
        assert_eq!((extras.skip, extras.skip_within), (0, Some((9, b'/'))));
        // glued to the word before it, with a level, after a skip at the head
        let (w, extras) = read("/N10 Z-1.0/2M08", &macro_b).unwrap();
        assert_eq!(w, ["N10", "Z-1.0", "M08"]);
        let extras = extras.unwrap();
        assert_eq!((extras.skip, extras.skip_within), (b'/', Some((10, b'2'))));
        // a division in a macro expression is not a skip
        let (w, extras) = read("#1 = #2 / 2", &macro_b).unwrap();
        assert_eq!((w, extras), (vec!["#1=#2/2".to_string()], None));
        // a second slash: refused where it stands
        let (message, at) = read("X1 /Y2 /M08", &macro_b).unwrap_err();
        assert!(message.contains("second '/'"), "{message}");
        assert_eq!(at, 7);
        // ISO 6983-1 and the other families: only at the head of the block
        for family in [Family::Iso, Family::LinuxCnc, Family::Sinumerik] {
            let d = Dialect {
                family,
                ..PERMISSIVE
            };
            let (message, at) = read("G00 X10. /Y20.", &d).unwrap_err();
            assert!(message.contains("must stand at the start"), "{message}");
            assert_eq!(at, 9);
        }
    }

    #[test]
    fn a_haas_refuses_an_address_written_apart_from_its_number() {
        let fanuc = Dialect {
            family: Family::MacroB,
            lowercase: false,
            ..PERMISSIVE
        };
        let haas = Dialect { ngc: true, ..fanuc };
        // the NGC manual's example: X 0 alarms, X [COS [90]] and X0 are read
        let (message, at) = read("G01 G90 X 0 Y3.0", &haas).unwrap_err();
        assert!(message.starts_with("address X written apart"), "{message}");
        assert!(message.contains("Haas Mill Operator's Manual"), "{message}");
        assert_eq!(at, 9);
        assert_eq!(
            words("G01 G90 X [COS [90]] Y3.0", &haas),
            ["G01", "G90", "X[COS[90]]", "Y3.0"]
        );
        assert_eq!(
            words("G01 G90 X0 Y3.0", &haas),
            ["G01", "G90", "X0", "Y3.0"]
        );
        // a sign or a point starts the number as a digit does; a variable is no number
        assert_eq!(read("N10 X -1.", &haas).unwrap_err().1, 5);
        assert_eq!(read("N10 X .5", &haas).unwrap_err().1, 5);
        assert_eq!(words("X #1", &haas), ["X#1"]);
        // an assignment's value is an expression, its sign an operator: no address stands
        // apart there (`#8= - 20.` as `#8= - #4`), while `X- 1.` stays refused
        assert_eq!(words("#8= - 20.", &haas), words("#8=-20.", &haas));
        assert_eq!(words("#8= + 20.", &haas), words("#8=+20.", &haas));
        assert_eq!(read("X- 1.", &haas).unwrap_err().1, 2);
        // a Fanuc skips the blank, as ISO 6983-1 4-08 does
        assert_eq!(
            words("G01 G90 X 0 Y3.0", &fanuc),
            ["G01", "G90", "X0", "Y3.0"]
        );
        // the program number's O may be written o on a Haas (5.3.1), no other lower case
        assert_eq!(words("o40001", &haas), ["o40001"]);
        assert!(read("o40001", &fanuc).is_err());
        assert!(read("g01 x0.0", &haas).is_err());
    }

    #[test]
    fn a_blank_inside_a_macro_b_word_is_refused_saying_no_source_reads_it() {
        let fanuc = Dialect {
            family: Family::MacroB,
            ..PERMISSIVE
        };
        let (message, at) = read("G0 G1 8 X1.", &fanuc).unwrap_err();
        assert!(
            message.contains("the rest of the word before it"),
            "{message}"
        );
        assert!(message.contains("no Fanuc or Haas source"), "{message}");
        assert_eq!(at, 6);
        // a number standing alone, and ISO's reading, say only what they are
        let (message, _) = read("G01 +5", &fanuc).unwrap_err();
        assert!(!message.contains("the rest of the word"), "{message}");
        let (message, _) = read("G1 8", &STRICT).unwrap_err();
        assert_eq!(message, "number '8' without an address letter");
        // the number is named whole, as written: one sign, its digits and point
        for (text, number, at) in [
            ("N20 T1 01", "'01'", 7),
            ("G0 X1 00. Y2.", "'00.'", 6),
            ("G0 X1. -2.5", "'-2.5'", 7),
            ("N10 ---", "'-'", 4),
            ("N10 .5", "'.5'", 4),
        ] {
            let (message, offset) = read(text, &fanuc).unwrap_err();
            assert!(
                message.starts_with(&format!("number {number} without an address letter")),
                "{text:?}: {message}"
            );
            assert_eq!(offset, at, "{text:?}");
        }
    }

    #[test]
    fn an_open_comment_says_whose_refusal_it_is() {
        let fanuc = Dialect {
            family: Family::MacroB,
            ..PERMISSIVE
        };
        let (message, at) = read("G0 X1. (OPEN", &fanuc).unwrap_err();
        assert_eq!(at, 7);
        assert!(message.starts_with("comment not closed"), "{message}");
        assert!(
            message.contains("no Fanuc or Haas source at hand"),
            "{message}"
        );
        let (message, at) = read("G0 X1. (OPEN", &STRICT).unwrap_err();
        assert_eq!(
            (message.as_str(), at),
            (
                "comment not closed: '(' without ')' before the end of block",
                7
            )
        );
    }

    #[test]
    fn a_fanuc_nested_comment_is_read_once_where_its_readings_agree() {
        let fanuc = Dialect::permissive(Family::MacroB);
        let comments = |text: &str| -> Vec<String> {
            let (_, extras) = read(text, &fanuc).expect("a valid block");
            extras
                .map(|e| e.comments)
                .unwrap_or_default()
                .iter()
                .map(|(_, c)| String::from_utf8_lossy(c).into_owned())
                .collect()
        };
        // the first ')' leaves a stray ')' or marks, no word: read to the matching ')'
        assert_eq!(
            words("G0 X1. (VNMG 332(1)) Y2.", &fanuc),
            ["G0", "X1.", "Y2."]
        );
        assert_eq!(comments("G0 X1. (VNMG 332(1)) Y2."), ["(VNMG 332(1))"]);
        assert_eq!(comments("(A (B) ...)\r"), ["(A (B) ...)"]);
        assert_eq!(comments("(A (B) (C) -)"), ["(A (B) (C) -)"]);
        // never closed when nested, nothing after the first ')': closed there
        assert_eq!(comments("G0 X1. (C:\\A(B\\C)"), ["(C:\\A(B\\C)"]);
        // after a ';' the comments are read the same way
        assert_eq!(comments("G0 X1.; (A (B) ...)"), ["; (A (B) ...)"]);
        // a word, digit, '#', '%' or ':' after the first ')': the readings differ
        for (text, at) in [
            ("G0 X1. (A (B) X5)", 10),
            ("G0 X1. (A (B) 5)", 10),
            ("G0 X1. (A (B) #1=2)", 10),
            ("G0 X1. (A (B) :12)", 10),
            ("G0 X1. (A (B) X5", 10),
            ("G0 X1.; (A (B) X5)", 11),
        ] {
            let (message, offset) = read(text, &fanuc).unwrap_err();
            assert_eq!(offset, at, "{text}");
            assert!(
                message.starts_with("comment inside a comment, and its two readings"),
                "{message}"
            );
        }
        // a ';' (end of block), a '/' (block skip) or a ',' that would join a C, R or A after
        // the stray ')' (a chamfer or corner word): the first reading changes the block
        for (text, at, said) in [
            (
                "G1 Z-5. (A (B) ;) F50.",
                11,
                "a ';' that ends the block there",
            ),
            (
                "G65 P9100 (A (B) ;) A1. B2.",
                13,
                "a ';' that ends the block there",
            ),
            (
                "G1 Z-5. F50. (A (B) /) X20.",
                16,
                "a '/' that, with the block-skip switch on",
            ),
            (
                "G1 X10. (A (B) ,)C1.",
                11,
                "a ',' that joins the 'C' after it into a ',C'",
            ),
            (
                "G1 X10. (A (B) , ) r1.",
                11,
                "a ',' that joins the 'R' after it into a ',R'",
            ),
            ("G0 X1. (A (B) ;", 10, "a ';' that ends the block there"),
        ] {
            let (message, offset) = read(text, &fanuc).unwrap_err();
            assert_eq!(offset, at, "{text}");
            assert!(message.contains(said), "{text}: {message}");
        }
        // a ',' before anything but C, R, A joins no word: the readings agree
        assert_eq!(words("G0 X1. (A (B) ,) Y2.", &fanuc), ["G0", "X1.", "Y2."]);
        // every other family ends a comment at its first ')'
        let (message, at) = read("G0 X1. (VNMG 332(1))", &PERMISSIVE).unwrap_err();
        assert_eq!((at, message.contains("without an opening")), (19, true));
    }

    #[test]
    fn expressions_after_an_index_and_in_brackets() {
        assert_eq!(
            words("R29 = R9 + R15 X2 = 105 + R9", &STRICT),
            ["R29=R9+R15", "X2=105+R9"]
        );
        assert_eq!(words("#1 = [#2 + 3] * 2", &PERMISSIVE), ["#1=[#2+3]*2"]);
        assert_eq!(words("X#1 Y[#2/2]", &PERMISSIVE), ["X#1", "Y[#2/2]"]);
        assert_eq!(words("X1=SIN[30]", &PERMISSIVE), ["X1=SIN[30]"]);
        let no_expr = Dialect {
            expressions: false,
            ..STRICT
        };
        assert!(read("R1 = R2 + 1", &no_expr).is_err());
    }

    #[test]
    fn linuxcnc_reads_a_parameter_number_through_its_blanks() {
        // rs274 drops the blanks of a line before reading it: #1 2 = 3 sets #12
        let linuxcnc = Dialect::permissive(Family::LinuxCnc);
        assert_eq!(words("#1 2 = 3", &linuxcnc), ["#12=3"]);
        assert_eq!(words("# 1 0 0=[1 + 2]", &linuxcnc), ["#100=[1+2]"]);
        // the reprint keeps the text: the token spans it as written
        let mut tokens = Vec::new();
        tokenize(b"#1 2 = 3 (c)", &linuxcnc, &mut tokens).unwrap();
        assert_eq!((tokens[0].offset, tokens[0].end), (0, 8));
        // a Custom Macro B control reads the number as written
        let (message, _) = read("#1 2 = 3", &Dialect::permissive(Family::MacroB)).unwrap_err();
        assert!(message.contains("#n = value"), "{message}");
    }

    #[test]
    fn linuxcnc_reads_a_number_through_its_blanks_as_it_reads_it_written_together() {
        // the number read without blanks first, read through them only where a digit or a
        // point follows its blanks: each word's text, span and digits are those of the same
        // number written without blanks
        let linuxcnc = Dialect::permissive(Family::LinuxCnc);
        let cases: [(&str, &str); 10] = [
            ("X1 2.5 Y1", "X12.5"),
            ("X1. 5 Y1", "X1.5"),
            ("X. 5 Y1", "X.5"),
            ("X 1 2 . 5", "X12.5"),
            ("X- 1 2 Y1", "X-12"),
            ("X1.2 .3 Y1", "X1.2"),
            ("X12 Y1", "X12"),
            ("X1.25\tY1", "X1.25"),
            ("X-.5 Y1", "X-.5"),
            ("X7", "X7"),
        ];
        for (text, together) in cases {
            let mut spaced = Vec::new();
            let spaced_read = tokenize(text.as_bytes(), &linuxcnc, &mut spaced);
            let mut plain = Vec::new();
            tokenize(together.as_bytes(), &linuxcnc, &mut plain).unwrap();
            if text == "X1.2 .3 Y1" {
                // a second point ends the number: `.3` stands where a word's address should
                assert!(spaced_read.is_err(), "{text}");
                continue;
            }
            spaced_read.unwrap();
            let (s, p) = (&spaced[0], &plain[0]);
            assert_eq!(&s.text[..], &p.text[..], "{text}");
            assert_eq!(s.digits, p.digits, "{text}");
            assert_eq!(s.plain, p.plain, "{text}");
            let written = text.find(" Y1").or(text.find("\tY1")).unwrap_or(text.len());
            assert_eq!((s.offset, s.end), (0, written), "{text}");
        }
    }

    #[test]
    fn linuxcnc_reads_a_line_number_first_in_the_line_only() {
        let linuxcnc = Dialect::permissive(Family::LinuxCnc);
        assert_eq!(words("  N10 G0 X1", &linuxcnc), ["N10", "G0", "X1"]);
        assert_eq!(words("/n 1 0 g0", &linuxcnc), ["n10", "g0"]);
        for (text, at) in [("(c) N10 G0", 4), ("G0 X1 N10", 6), ("G0 n1", 3)] {
            let (message, offset) = read(text, &linuxcnc).unwrap_err();
            assert!(message.contains("first in the line"), "{text}: {message}");
            assert_eq!(offset, at, "{text}");
        }
        // ISO 6983-1 reads N anywhere (TG130 says the order)
        assert_eq!(words("G0 X1 N10", &STRICT), ["G0", "X1", "N10"]);
    }

    /// A macro statement on a dialect without `#`, `[ ]` or `*` (a FANUC without Custom Macro
    /// B): TG101 at its first such character, the one the conversion refuses for such a
    /// target (`Dialect::unread_character`); the statement without them is read.
    #[test]
    fn a_statement_with_a_character_the_dialect_lacks_is_refused_there() {
        let fanuc = Dialect::permissive(Family::MacroB);
        let bare = Dialect {
            hash: false,
            brackets: false,
            star: false,
            ..fanuc
        };
        for (text, at) in [
            ("WHILE[1LT10]DO1", 5),
            ("WHILE[#1LT10]DO1", 5),
            ("N5 IF[1EQ0]GOTO10", 5),
            ("GOTO#2", 4),
            ("GOTO[2*5]", 4),
        ] {
            let mut words = Vec::new();
            let e = tokenize(text.as_bytes(), &bare, &mut words).unwrap_err();
            assert_eq!(
                e.kind.rule(),
                Rule::CharacterOutsideSet,
                "{text}: {}",
                e.message
            );
            assert_eq!(e.offset, at, "{text}");
            assert_eq!(bare.unread_character(text.as_bytes()), Some(at), "{text}");
            assert!(
                tokenize(text.as_bytes(), &fanuc, &mut words).is_ok(),
                "{text}"
            );
            assert_eq!(fanuc.unread_character(text.as_bytes()), None);
        }
        let mut words = Vec::new();
        assert!(tokenize(b"GOTO10", &bare, &mut words).is_ok());
        // a `*` alone is read where the dialect has it
        let star = Dialect { star: true, ..bare };
        assert_eq!(star.unread_character(b"GOTO[2*5]"), Some(4));
        assert_eq!(star.unread_character(b"A*B"), None);
        // a quoted string's text is no statement character
        assert_eq!(bare.unread_character(b"VUACM[1]='#1.'"), Some(5));
        let okuma = Dialect {
            hash: false,
            ..Dialect::permissive(Family::Okuma)
        };
        assert_eq!(
            okuma.unread_character(b"VUACM[1]='PSRT = 0 (MISSING) #1.'"),
            None
        );
        assert_eq!(okuma.unread_character(b"VUACM[1]=#1"), Some(9));
        // an OSP statement's `#` is its value form (`#80H`), no parameter
        assert_eq!(okuma.unread_in_statement(b"VFST=#80H"), None);
        assert_eq!(bare.unread_in_statement(b"GOTO#2"), Some(4));
        let mut words = Vec::new();
        assert!(tokenize(b"VFST=#80H", &okuma, &mut words).is_ok());
    }

    #[test]
    fn linuxcnc_reads_signs_and_functions_before_a_value() {
        // rs274 read_real_value: any signs before a value, a unary function as the value
        let linuxcnc = Dialect::permissive(Family::LinuxCnc);
        assert_eq!(
            words("G0 X--1 Y+-1.5 Z- - .5", &linuxcnc),
            ["G0", "X--1", "Y+-1.5", "Z--.5"]
        );
        assert_eq!(
            words("G0 Xsin[30] Y-abs[#1] Z-[1]", &linuxcnc),
            ["G0", "Xsin[30]", "Y-abs[#1]", "Z-[1]"]
        );
        // a name that is no function, a sign with nothing after it: refused where they stand
        let (message, at) = read("G0 Xfoo[1]", &linuxcnc).unwrap_err();
        assert!(message.contains("unknown function FOO"), "{message}");
        assert_eq!(at, 4);
        assert!(read("G0 X-", &linuxcnc).is_err());
        // ISO 6983-1 reads one sign and a number
        assert!(read("G0 X--1", &STRICT).is_err());
    }

    #[test]
    fn a_sinumerik_address_takes_an_expression_after_equals_only() {
        // Programming Manual Fundamentals, "Value assignments": the '=' is required where the
        // value is more than one constant; '[ ]' hold an index, '( )' a call's arguments
        let sinumerik = Dialect::permissive(Family::Sinumerik);
        assert_eq!(
            words("G1 X=R2+10 Z=R1*2 F100", &sinumerik),
            ["G1", "X=R2+10", "Z=R1*2", "F100"]
        );
        for (text, at) in [
            ("G1 X[R1] F100", 4),
            ("G1 X10 Z[R1*2]", 8),
            ("G1 X(R1+2)", 4),
        ] {
            let (message, offset) = read(text, &sinumerik).unwrap_err();
            assert!(
                message.contains("'=' before a variable or an expression"),
                "{message}"
            );
            assert!(message.contains("'Value assignments'"), "{message}");
            assert_eq!(offset, at, "{text:?}");
        }
        // FANUC's Custom Macro B reads the bracketed expression after the address
        let macro_b = Dialect::permissive(Family::MacroB);
        assert_eq!(words("G1 X[#1+10]", &macro_b), ["G1", "X[#1+10]"]);
    }

    #[test]
    fn errors_are_located() {
        let cases: [(&str, usize, &str); 13] = [
            ("N10 X", 4, "address X has no value"),
            ("N10 (ABC", 4, "comment not closed"),
            ("N10 x10", 4, "lower-case 'x'"),
            ("N10 X1 #5", 7, "outside ISO 6983-1 Annex A"),
            ("N10 \u{1}", 4, "control or binary character 0x01"),
            ("N10 1.5", 4, "without an address letter"),
            ("N10 X--1", 6, "must be followed by a number"),
            ("N10 X1)", 6, "without an opening"),
            ("R1 = 5 + ", 9, "expression ends without an operand"),
            ("N10 X1 / Y2", 7, "block skip must stand at the start"),
            ("X0=1", 1, "index of X must be greater than 0"),
            ("N10 (A\u{2}B)", 6, "in a comment"),
            (":A", 1, "alignment"),
        ];
        for (text, offset, message) in cases {
            let (got, at) = read(text, &STRICT).unwrap_err();
            assert!(got.contains(message), "{text:?}: {got}");
            assert_eq!(at, offset, "{text:?}");
        }
    }

    #[test]
    fn a_stray_byte_is_named_as_it_is_in_the_file() {
        // in a comment an 8-bit byte is text (the checker's TG127 names it); elsewhere it is
        // refused, named as it is in the file
        let mut words = Vec::new();
        assert!(tokenize(b"N1 (20\xb0C)", &STRICT, &mut words).is_ok());
        let line = b"N1 X1\xb0";
        let e = tokenize(line, &STRICT, &mut words).unwrap_err();
        assert!(e.message.contains("0xB0"), "{}", e.message);
        assert_eq!(e.kind.rule(), Rule::CharacterOutsideSet);
    }

    #[test]
    fn a_dos_end_of_file_and_a_byte_order_mark_are_read_as_nothing() {
        assert_eq!(read("\u{1a}", &STRICT), Ok((vec![], None)));
        assert_eq!(read("\u{1a}\u{1a}\r", &STRICT), Ok((vec![], None)));
        assert_eq!(words("\u{feff}%", &STRICT), Vec::<String>::new());
        assert_eq!(words("\u{feff}N10 X1", &STRICT), ["N10", "X1"]);
        assert!(read("N10 X1 \u{1a}", &STRICT).is_err()); // inside a block it is a stray byte
                                                          // glued to the closing % (a DOS editor's end of file after "%"): the end of the file
        assert!(read("%\u{1a}", &STRICT).is_ok());
        assert!(read("%\u{1a}X", &STRICT).is_err());
    }

    #[test]
    fn a_huge_number_is_a_token_not_a_crash() {
        let text = format!("X{}", "9".repeat(60_000));
        assert_eq!(words(&text, &STRICT)[0].len(), 60_001);
        let mut words = Vec::new();
        let long = vec![b'X'; MAX_BLOCK + 1];
        assert_eq!(
            tokenize(&long, &STRICT, &mut words).unwrap_err().kind,
            ErrorKind::TooLong
        );
    }
}
