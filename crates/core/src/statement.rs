//! The statements of control families beyond the words of ISO 6983-1 (docs/dialects.md).
//!
//! A statement is read where a word would start and could not: an address letter followed by
//! another letter (`IF`, `GOTO`, `WHILE`, `MSG`, `CYCLE800`), LinuxCNC's `o100 sub`, Siemens'
//! `@` commands and `X=R1+5`. Each family's reader says where the statement ends and what kind
//! it is; the statement's text stays in the line (reprint and conversion keep it byte for byte)
//! and its [`Kind`] tells the checker what it can and cannot follow: a jump or a call leaves
//! the modal state unknown from there on. A word that is not a statement is left to the word
//! reader, so no family changes how an ISO word reads. An Okuma OSP's statements are read by
//! [`okuma`], with this module's helpers.

pub mod okuma;

use crate::expr::{self, skip_blanks};
use crate::lex::{
    blank, compact, err, Dialect, Digits, ErrorKind, Family, LexError, Syntax, Token,
};

/// What a statement does, as far as the checker is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A jump, a condition or a loop (`IF`, `GOTO`, `WHILE`/`DO`/`END`, `o100 if`): which block
    /// runs next depends on values the checker does not know.
    Flow,
    /// A call of a subprogram or cycle (`o100 call`, `CYCLE800(..)`).
    Call,
    /// The start or end of a subprogram's definition (`o100 sub`, `o100 endsub`).
    Definition,
    /// A declaration (`DEF REAL _X`).
    Declaration,
    /// A value set by a name the checker does not follow (`CR=5`, `_X=R1`, `TURN=0`).
    Assignment,
    /// An operator message or output (`MSG("..")`, `DPRNT[..]`).
    Message,
    /// A control instruction of its own (`TRAFOOF`, `SUPA`, `@714`, `TRANS X10`).
    Command,
    /// A jump label (`LABEL1:`).
    Label,
    /// A program name (`O7997A`).
    Name,
}

impl Kind {
    pub const ALL: [Kind; 9] = [
        Kind::Flow,
        Kind::Call,
        Kind::Definition,
        Kind::Declaration,
        Kind::Assignment,
        Kind::Message,
        Kind::Command,
        Kind::Label,
        Kind::Name,
    ];

    pub fn from_name(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// Whether the checker loses track of the program here: a jump, a loop, a call, or the
    /// start of a subprogram that runs in its caller's state.
    pub fn unfollowed(self) -> bool {
        matches!(self, Kind::Flow | Kind::Call | Kind::Definition)
    }

    pub fn name(self) -> &'static str {
        match self {
            Kind::Flow => "flow",
            Kind::Call => "call",
            Kind::Definition => "definition",
            Kind::Declaration => "declaration",
            Kind::Assignment => "assignment",
            Kind::Message => "message",
            Kind::Command => "command",
            Kind::Label => "label",
            Kind::Name => "name",
        }
    }
}

/// One statement: its byte span in the line and its kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Statement {
    pub offset: usize,
    pub end: usize,
    pub kind: Kind,
}

/// What was read at a word position.
pub enum Read {
    /// A statement, ending at `end`.
    Statement(Statement),
    /// A word (`X=R1+5`, `#<x>=2`, `#[#1]=0`), pushed into the words; it ends at the offset.
    Word(usize),
}

fn letter(b: u8, lowercase: bool) -> bool {
    b.is_ascii_uppercase() || (lowercase && b.is_ascii_lowercase())
}

fn letters_end(line: &[u8], pos: usize, lowercase: bool) -> usize {
    let mut end = pos;
    while end < line.len() && letter(line[end], lowercase) {
        end += 1;
    }
    end
}

pub(crate) fn digits_end(line: &[u8], pos: usize) -> usize {
    let mut end = pos;
    while end < line.len() && line[end].is_ascii_digit() {
        end += 1;
    }
    end
}

/// The end of the statement text: the end of the line, or the start of a trailing `;` or `(`
/// comment (where `(` is a comment), with the blanks before it left out.
pub(crate) fn rest_end(line: &[u8], pos: usize, dialect: &Dialect, paren: bool) -> usize {
    let mut depth = 0usize;
    let mut quoted = false;
    let mut end = line.len();
    for (i, &b) in line.iter().enumerate().skip(pos) {
        match b {
            b'"' => quoted = !quoted,
            _ if quoted => {}
            b'[' => depth += 1,
            b']' => depth = depth.saturating_sub(1),
            b';' if dialect.semicolon && depth == 0 => {
                end = i;
                break;
            }
            b'(' if paren && depth == 0 => {
                end = i;
                break;
            }
            b'*' if dialect.family == Family::Heidenhain && depth == 0 => {
                end = i;
                break;
            }
            _ => {}
        }
    }
    while end > pos && blank(line[end - 1]) {
        end -= 1;
    }
    end
}

/// A word of the family's own form (`#<x>=2`, `@10`, `X=R1+5`), from `pos` to `end`.
pub(crate) fn word<'a>(line: &'a [u8], pos: usize, end: usize, words: &mut Vec<Token<'a>>) -> Read {
    words.push(Token {
        offset: pos,
        end,
        text: compact(line, pos, end),
        plain: None,
        digits: Digits::default(),
    });
    Read::Word(end)
}

pub(crate) fn statement(offset: usize, end: usize, kind: Kind) -> Option<Read> {
    Some(Read::Statement(Statement { offset, end, kind }))
}

/// The most characters a FANUC program's name holds between its `<` and `>` (FANUC Fast
/// Ethernet / Fast Data Server for 30i/300i/31i/310i/32i/320i-A Operator's Manual, B-64014EN/03,
/// 2.5 "NC program format").
pub const PROGRAM_NAME_MAX: usize = 32;

/// Whether a FANUC program name may hold `c`: the characters of a file name on the FANUC data
/// server (digits, letters, `. ! # $ & - @ ^ _ ' { } ~`: FANUC Ethernet / Data Server Board
/// Operator's Manual, B-63354EN/04, list file formats 3 and 4), but `%`, which that list has
/// and which ends the record in an NC file (FANUC Series 16i/18i-TB Operator's Manual,
/// B-63524EN/01, 8, memory card file format: a file ends with `%`).
pub fn program_name_character(c: u8) -> bool {
    c.is_ascii_alphanumeric() || b".!#$&-@^_'{}~".contains(&c)
}

/// `<NAME>` at the start of a block: a FANUC program named by a file name of up to 32
/// characters in place of its O number (B-64014EN/03, 2.5: "at the beginning of the program
/// section", an O number or a file name enclosed by `<` and `>`). Read as the program's name,
/// as an O number is; anywhere else, and a `>` without its `<`, refused: a call by name (`M98
/// <NAME>`, `G65 <NAME>`) is in no FANUC source at hand.
fn program_name(line: &[u8], pos: usize) -> Result<Option<Read>, LexError> {
    let before = &line[..pos];
    let before = before.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(before);
    let at_start = before.iter().all(|&c| blank(c));
    if line[pos] == b'>' || !at_start {
        let message = if line[pos] == b'>' {
            "'>' without its '<': a FANUC program name is written <NAME> at the start of its \
             program (FANUC B-64014EN/03, 2.5)"
        } else {
            "'<' stands only at the start of a program, where <NAME> names it in place of an O \
             number (FANUC B-64014EN/03, 2.5); a call by name (M98 <NAME>, G65 <NAME>) is in no \
             FANUC source at hand, so it is not read"
        };
        return Err(err(ErrorKind::Character, message.into(), pos, "dialect"));
    }
    let mut end = pos + 1;
    while end < line.len() && line[end] != b'>' {
        let c = line[end];
        if !program_name_character(c) {
            let what = match c {
                b' ' | b'\t' => "a blank".into(),
                _ if c.is_ascii_graphic() => format!("'{}'", c as char),
                _ => format!("byte 0x{c:02X}"),
            };
            return Err(err(
                ErrorKind::Character,
                format!(
                    "{what} in a program name: a FANUC program's file name holds letters, digits \
                     and . ! # $ & - @ ^ _ ' {{ }} ~ (FANUC B-63354EN/04, list files; \
                     B-64014EN/03, 2.5){}",
                    if c == b'%' {
                        "; '%', which that list has too, ends the record in an NC file (FANUC \
                         B-63524EN/01, 8)"
                    } else {
                        ""
                    }
                ),
                end,
                "dialect",
            ));
        }
        end += 1;
    }
    if end == line.len() {
        return Err(err(
            ErrorKind::Value,
            "program name '<' not closed by '>' before the end of block (FANUC B-64014EN/03, \
             2.5: <NAME>)"
                .into(),
            pos,
            "dialect",
        ));
    }
    let length = end - pos - 1;
    if length == 0 || length > PROGRAM_NAME_MAX {
        let message = if length == 0 {
            "empty program name '<>': a FANUC program's name holds 1 to 32 characters \
             (B-64014EN/03, 2.5)"
                .to_string()
        } else {
            format!(
                "program name of {length} characters: a FANUC program's name holds up to \
                 {PROGRAM_NAME_MAX} (B-64014EN/03, 2.5)"
            )
        };
        let at = if length == 0 {
            pos
        } else {
            pos + 1 + PROGRAM_NAME_MAX
        };
        return Err(err(ErrorKind::Value, message, at, "dialect"));
    }
    Ok(statement(pos, end + 1, Kind::Name))
}

/// Read a statement (or a word of the family's own form) at `pos`, or None to leave `pos` to
/// the word reader.
pub fn read<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    match dialect.family {
        Family::Iso => Ok(None),
        Family::MacroB => macro_b(line, pos, dialect, words),
        Family::LinuxCnc => linuxcnc(line, pos, dialect, words),
        Family::Sinumerik => sinumerik(line, pos, dialect, words),
        Family::Heidenhain => heidenhain(line, pos, dialect, words),
        Family::Okuma => okuma::read(line, pos, dialect, words),
    }
}

/// A condition: bracketed groups joined by `AND`, `OR`, `XOR` (Fanuc writes
/// `IF[#1EQ#2]AND[#3EQ#4]`).
fn condition(line: &[u8], pos: usize, syntax: Syntax, what: &str) -> Result<usize, LexError> {
    let open = skip_blanks(line, pos);
    if line.get(open) != Some(&b'[') {
        return Err(err(
            ErrorKind::Expression,
            format!("{what} must be followed by a condition in brackets [ ]"),
            open,
            "6.4.7",
        ));
    }
    let mut end = expr::scan_group(line, open, syntax)?;
    loop {
        let p = skip_blanks(line, end);
        let word = letters_end(line, p, syntax.lowercase);
        let op = &line[p..word];
        let joined = [&b"AND"[..], b"OR", b"XOR"]
            .iter()
            .any(|j| j.eq_ignore_ascii_case(op));
        let next = skip_blanks(line, word);
        if joined && line.get(next) == Some(&b'[') {
            end = expr::scan_group(line, next, syntax)?;
        } else {
            return Ok(end);
        }
    }
}

/// A jump target: a number, `#n`, or a bracketed expression.
fn target(line: &[u8], pos: usize, syntax: Syntax, what: &str) -> Result<usize, LexError> {
    let p = skip_blanks(line, pos);
    let end = digits_end(line, p);
    if end > p {
        return Ok(end);
    }
    if matches!(line.get(p), Some(b'#' | b'[')) {
        return expr::scan_operand(line, p, syntax);
    }
    Err(err(
        ErrorKind::Value,
        format!("{what} must be followed by a block number"),
        p,
        "6.4.7",
    ))
}

// -- Fanuc and Haas Custom Macro B --------------------------------------------------------------

/// The statement words of Custom Macro B that the reader reads in full; a shorter run of their
/// first letters (`WH`, `GO`) is refused with its own message.
const MACRO_WORDS: [&[u8]; 8] = [
    b"WHILE", b"GOTO", b"THEN", b"END", b"DPRNT", b"BPRNT", b"POPEN", b"PCLOS",
];

fn macro_b<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let syntax = dialect.syntax();
    let low = dialect.lowercase;
    let b = line[pos];
    if b == b'#' {
        return parameter_word(line, pos, dialect, words);
    }
    // ,C2. ,R1.5 ,A30.: chamfer, corner radius and angle of the move (chamfering and corner R,
    // direct drawing dimension programming), kept as a command of the block
    if b == b',' {
        let letter_at = skip_blanks(line, pos + 1);
        if letter_at > pos + 1 && matches!(line.get(letter_at), Some(b'C' | b'R' | b'A')) {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "',' written apart from its letter (', {0}'): the corner and angle words are \
                     read written together (',{0}'), since no Fanuc or Haas source at hand says \
                     the control reads a blank after the comma (docs/dialects.md)",
                    line[letter_at] as char
                ),
                pos + 1,
                "6.1",
            ));
        }
    }
    if b == b',' && matches!(line.get(pos + 1), Some(b'C' | b'R' | b'A')) {
        let v = pos + 2;
        if line.get(v).is_some_and(|&c| blank(c)) {
            let after = skip_blanks(line, v);
            if crate::lex::number_ahead(line, after) {
                if dialect.ngc {
                    return Err(crate::lex::apart(line[pos + 1], v));
                }
                return Err(err(
                    ErrorKind::Value,
                    format!(
                        "',{0}' written apart from its number: read only written together, \
                         since no Fanuc source at hand says the control reads a blank there \
                         (docs/dialects.md)",
                        line[pos + 1] as char
                    ),
                    v,
                    "6.1",
                ));
            }
        }
        let end = match line.get(v) {
            Some(b'#' | b'[') => expr::scan_operand(line, v, syntax)?,
            _ => {
                let digits = usize::from(matches!(line.get(v), Some(b'+' | b'-')));
                expr::number_end(line, v + digits).ok_or_else(|| {
                    err(
                        ErrorKind::Value,
                        format!("',{}' must be followed by a number", line[pos + 1] as char),
                        v,
                        "6.1",
                    )
                })?
            }
        };
        return Ok(statement(pos, end, Kind::Command));
    }
    // &F=/USER/PATH1/: a folder of the control's memory, as a 30i punches a backup of all
    // folders: the programs after it are in that folder
    if b == b'&' && line[pos..].starts_with(b"&F=") {
        let end = line.len()
            - line
                .iter()
                .rev()
                .take_while(|c| c.is_ascii_whitespace())
                .count();
        return Ok(statement(pos, end.max(pos + 3), Kind::Name));
    }
    // <NAME>: a FANUC program named by a file name in place of its O number
    if (b == b'<' || b == b'>') && !dialect.ngc {
        return program_name(line, pos);
    }
    if !letter(b, low) {
        return Ok(None);
    }
    // O7997A: a program number with letters after its digits names the program
    if b.eq_ignore_ascii_case(&b'O') {
        let digits = digits_end(line, pos + 1);
        let end = ident_end(line, digits);
        if digits > pos + 1 && end > digits && !line[digits].is_ascii_digit() {
            return Ok(statement(pos, end, Kind::Name));
        }
        return Ok(None);
    }
    let end = letters_end(line, pos, low);
    if end - pos < 2 {
        return Ok(None);
    }
    let name = line[pos..end].to_ascii_uppercase();
    let read = match name.as_slice() {
        b"IF" => {
            let cond = condition(line, end, syntax, "IF")?;
            let p = skip_blanks(line, cond);
            let word = letters_end(line, p, low);
            match line[p..word].to_ascii_uppercase().as_slice() {
                b"GOTO" => target(line, word, syntax, "GOTO")?,
                b"THEN" => rest_end(line, word, dialect, true),
                // IF [..] #712=#609: the assignment without THEN, as programs from a Fanuc
                // grinder's memory write it; read as IF [..] THEN #712=#609
                _ if line.get(p) == Some(&b'#') => rest_end(line, p, dialect, true),
                _ => {
                    return Err(err(
                        ErrorKind::Value,
                        "IF [condition] must be followed by GOTO n or THEN".into(),
                        p,
                        "6.4.7",
                    ))
                }
            }
        }
        b"WHILE" => {
            let cond = condition(line, end, syntax, "WHILE")?;
            let p = skip_blanks(line, cond);
            let word = letters_end(line, p, low);
            // DO 1 as DO1: a blank between a word and its number is skipped (ISO 6983-1 reads
            // past SP; FANUC's WHILE sample writes `DO 1`, docs/dialects.md)
            let number = skip_blanks(line, word);
            if !line[p..word].eq_ignore_ascii_case(b"DO") || digits_end(line, number) == number {
                return Err(err(
                    ErrorKind::Value,
                    "WHILE [condition] must be followed by DOm (m = 1, 2 or 3)".into(),
                    p,
                    "6.4.7",
                ));
            }
            digits_end(line, number)
        }
        b"GOTO" => target(line, end, syntax, "GOTO")?,
        b"DO" | b"END" => {
            // `END 1`, `DO  2` as END1, DO2 (the blank skipped, as after WHILE's DO)
            let number = skip_blanks(line, end);
            let digits = digits_end(line, number);
            if digits == number {
                return Ok(None);
            }
            digits
        }
        b"DPRNT" | b"BPRNT" => {
            let open = skip_blanks(line, end);
            match brackets(line, open) {
                Ok(close) if line.get(open) == Some(&b'[') => close,
                _ => {
                    return Err(err(
                        ErrorKind::Value,
                        format!(
                            "{} must be followed by its text in brackets [ ]",
                            String::from_utf8_lossy(&name)
                        ),
                        open,
                        "6.4.7",
                    ))
                }
            }
        }
        b"POPEN" | b"PCLOS" => digits_end(line, end),
        // IF [..] THEN on a block of its own, the statements on the blocks after it, then
        // ELSE and ENDIF (a probing macro written for a FANUC): the macro chapters at hand
        // give IF [..] GOTO n and IF [..] THEN with its one statement in the same block, and
        // no block form; what a control does at ELSE or ENDIF (an alarm, or the branch run
        // or skipped) none of them says (docs/dialects.md says what was searched). Refused at
        // the word, and said so, where the word reader would only say that E wants a number.
        b"ELSE" | b"ENDIF" => {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "'{}' is not read: an IF [..] THEN over several blocks closed by ELSE and \
                     ENDIF is in no Fanuc or Haas source at hand, which give IF [..] GOTO n \
                     and IF [..] THEN with its one statement in the block (docs/dialects.md)",
                    String::from_utf8_lossy(&line[pos..end])
                ),
                pos,
                "6.4.7",
            ));
        }
        _ => {
            // WH[..]DO1, GO10: the first letters of a macro word. A Fanuc 0i-MD macro writes
            // them, but none of the sources at hand documents that a control reads them
            // (docs/dialects.md says what was searched): refused, and said so, where the word
            // reader would only say that W wants a number
            if let Some(full) = MACRO_WORDS
                .iter()
                .find(|w| w.len() > name.len() && w.starts_with(&name))
            {
                // `GO Y0.` (a lathe program typed by hand): no block number follows, so no
                // GOTO however written; a G with the letter O for its zero, the class of `GOO`
                // and `TO303` (the word reader's "found 'O'"), said so
                let at = skip_blanks(line, end);
                let next = line.get(at);
                // `GO TO 10`: GOTO with a blank inside it, its block number after TO
                let to = at + 2;
                if name == b"GO"
                    && line
                        .get(at..to)
                        .is_some_and(|w| w.eq_ignore_ascii_case(b"TO"))
                    && !line.get(to).is_some_and(|&c| letter(c, low))
                {
                    return Err(err(
                        ErrorKind::Value,
                        format!(
                            "'{}' is not read as GOTO: the macro words are read written in \
                             full, with no blank inside (no source at hand documents another \
                             spelling)",
                            String::from_utf8_lossy(&line[pos..to])
                        ),
                        pos,
                        "6.4.7",
                    ));
                }
                // `GO1 X1.`: digits, then an address word, as in a motion block: the letter O
                // for the zero of G01 as likely as GOTO 1 abbreviated, and the message says both
                let digits = digits_end(line, at);
                if name == b"GO" && digits > at {
                    let after = skip_blanks(line, digits);
                    if let Some(&address) = line.get(after).filter(|&&c| letter(c, low)) {
                        let number = String::from_utf8_lossy(&line[at..digits]);
                        return Err(err(
                            ErrorKind::Value,
                            format!(
                                "'{}' is neither G0{number} nor GOTO {number}: G takes \
                                 digits, and the letter O stands where a zero belongs \
                                 (G0{number}, the address {} after it as in a motion block), \
                                 or GOTO is abbreviated, which no source at hand documents \
                                 (the macro words are read written in full)",
                                String::from_utf8_lossy(&line[pos..digits]),
                                address as char
                            ),
                            pos,
                            "6.4.7",
                        ));
                    }
                }
                if name == b"GO"
                    && !next.is_some_and(|&c| c.is_ascii_digit() || c == b'#' || c == b'[')
                {
                    return Err(err(
                        ErrorKind::Value,
                        format!(
                            "'{}' is neither G0 nor GOTO: G takes digits, and the letter O \
                             stands where a zero belongs (G0), or a GOTO has no block number \
                             after it",
                            String::from_utf8_lossy(&line[pos..end])
                        ),
                        pos,
                        "6.4.7",
                    ));
                }
                return Err(err(
                    ErrorKind::Value,
                    format!(
                        "'{}' is not read as {}: the macro words are read written in full \
                         (no source at hand documents their abbreviations)",
                        String::from_utf8_lossy(&line[pos..end]),
                        String::from_utf8_lossy(full)
                    ),
                    pos,
                    "6.4.7",
                ));
            }
            return Ok(None);
        }
    };
    let kind = match name.as_slice() {
        b"DPRNT" | b"BPRNT" | b"POPEN" | b"PCLOS" => Kind::Message,
        _ => Kind::Flow,
    };
    Ok(statement(pos, read, kind))
}

/// `#[expr] = value` (a parameter chosen by number) and LinuxCNC's `#<name> = value`, as one
/// word; None leaves `#n = value` to the word reader.
fn parameter_word<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let syntax = dialect.syntax();
    // LinuxCNC reads a line without its blanks (rs274ngc's close_and_downcase), so `# <x> = 1`
    // is `#<x>=1`; and what follows the `#` of an assignment is a parameter's name or any
    // value giving its number: `#[1+1] = 5`, `##1 = 5` (read_parameter_setting)
    let q = if syntax.named {
        skip_blanks(line, pos + 1)
    } else {
        // Custom Macro B `# [2] = 10.`: the blank skipped as in `# 2 = 10.` on a FANUC, the
        // NGC's "written apart" alarm on a Haas (review 52, F1; `Tokenizer::word`, audit 50 B12)
        let r = skip_blanks(line, pos + 1);
        if r > pos + 1 && line.get(r) == Some(&b'[') {
            if dialect.ngc {
                return Err(crate::lex::apart(b'#', pos + 1));
            }
            r
        } else {
            pos + 1
        }
    };
    let reference_end = match line.get(q) {
        Some(b'[') => expr::scan_group(line, q, syntax)?,
        Some(b'<' | b'#') if syntax.named => expr::scan_operand(line, pos, syntax)?,
        _ => return Ok(None),
    };
    let eq = skip_blanks(line, reference_end);
    if line.get(eq) != Some(&b'=') {
        return Err(err(
            ErrorKind::Value,
            "a parameter must be set as #n = value".into(),
            eq,
            "6.4.7",
        ));
    }
    let end = expr::scan(line, skip_blanks(line, eq + 1), syntax)?;
    Ok(Some(word(line, pos, end, words)))
}

// -- LinuxCNC -----------------------------------------------------------------------------------

/// The number of a parameter `#n` (leading zeros left out), or None for any other name.
pub(crate) fn parameter_number(name: &[u8]) -> Option<u32> {
    let Some((b'#', digits)) = name.split_first() else {
        return None;
    };
    if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let start = digits
        .iter()
        .position(|&d| d != b'0')
        .unwrap_or(digits.len());
    let digits = &digits[start..];
    (digits.len() <= 2).then(|| digits.iter().fold(0, |n, &d| n * 10 + u32::from(d - b'0')))
}

/// A LinuxCNC subroutine's own parameter: a local named parameter (`#<depth>`, not a global
/// `#<_depth>`) and #1-#30, the call's arguments, which the control saves at the call and
/// restores at the return (LinuxCNC manual, "Named Parameters" and "O Codes").
pub(crate) fn sub_local(name: &[u8]) -> bool {
    match name {
        [b'#', b'<', b'_', ..] => false,
        [b'#', b'<', ..] => true,
        _ => parameter_number(name).is_some_and(|n| (1..=30).contains(&n)),
    }
}

/// A parameter's name as the control reads it, one key for every way of writing it: without
/// its blanks (`# 1`, `#< x >`); a LinuxCNC named parameter in lower case (`#<ZS>` is `#<zs>`:
/// "Named Parameters"), any other in upper case (a SINUMERIK's `r1` is `R1` and `_z_home`
/// `_Z_HOME`: "The SINUMERIK NC language does not distinguish between uppercase and lowercase
/// letters", Programming Manual NC programming, 2.2.1; the other families' names have no
/// letters or are written in capitals).
pub(crate) fn parameter_name(raw: &[u8]) -> String {
    let named = raw.contains(&b'<');
    let mut name = Vec::with_capacity(raw.len());
    for &c in raw.iter().filter(|&&c| !blank(c)) {
        name.push(if named {
            c.to_ascii_lowercase()
        } else {
            c.to_ascii_uppercase()
        });
    }
    // a number's leading zeros are no part of it: `R01` is R1 (Programming Manual
    // Fundamentals, "Extended addresses": leading zeros of the extension are ignored), `#007`
    // is #7 (Custom Macro B, LinuxCNC read the digits as a number)
    let zeros = leading_zeros(&name);
    name.drain(1..1 + zeros);
    String::from_utf8(name).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

/// The zeros after the letter or `#` of a numbered name (`R01`, `#007`) that are not its
/// last digit: none in a name with anything but digits after its first character.
fn leading_zeros(name: &[u8]) -> usize {
    match name {
        [_, digits @ ..] if digits.len() > 1 && digits.iter().all(u8::is_ascii_digit) => digits
            .iter()
            .take_while(|&&c| c == b'0')
            .count()
            .min(digits.len() - 1),
        _ => 0,
    }
}

/// Whether `raw` is already its [`parameter_name`]: no blanks, no capital in a named one and
/// no small letter in another.
pub(crate) fn is_parameter_name(raw: &[u8]) -> bool {
    // one pass, each byte's classes from a table, or-ed (the analysis and the converter ask
    // it of every parameter a word reads)
    let seen = raw
        .iter()
        .fold(0, |seen, &c| seen | NAME_BYTES[usize::from(c)]);
    if seen & BLANK != 0 {
        false
    } else if seen & NAMED != 0 {
        seen & CAPITAL == 0
    } else {
        seen & SMALL == 0 && leading_zeros(raw) == 0
    }
}

/// The classes of a byte that [`is_parameter_name`] asks of a name's: a blank ([`blank`]), the
/// `<` of a named parameter, a capital or a small letter.
const BLANK: u8 = 1;
const NAMED: u8 = 2;
const CAPITAL: u8 = 4;
const SMALL: u8 = 8;
const NAME_BYTES: [u8; 256] = {
    let mut table = [0; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        table[c] = if b == b' ' || b == b'\t' || b == b'\r' || b == 0 || b == 0x7f {
            BLANK
        } else if b == b'<' {
            NAMED
        } else if b.is_ascii_uppercase() {
            CAPITAL
        } else if b.is_ascii_lowercase() {
            SMALL
        } else {
            0
        };
        c += 1;
    }
    table
};

/// The name the analysis lists a parameter by, and the converter looks it up by: its
/// [`parameter_name`], and for a LinuxCNC subroutine's own parameter (`sub`: the line of its
/// `o<name> sub`) `@` and that line (`#<depth>@12`), the main program's `#<depth>` being
/// another parameter.
pub(crate) fn scoped_name(name: String, sub: Option<usize>) -> String {
    match sub {
        Some(line) if sub_local(name.as_bytes()) => format!("{name}@{line}"),
        _ => name,
    }
}

/// The end of the target of a LinuxCNC named parameter's assignment token (`#<zs>=1.0`: 5,
/// the `=` after it), or None for any other token.
pub(crate) fn named_target(token: &[u8]) -> Option<usize> {
    if !token.starts_with(b"#<") {
        return None;
    }
    let end = token.iter().position(|&c| c == b'>')? + 1;
    (token.get(end) == Some(&b'=')).then_some(end)
}

/// An o-word statement as rs274 reads it: in lower case, without blanks (`read_o` after
/// `close_and_downcase`).
fn o_text(statement: &[u8]) -> Vec<u8> {
    statement
        .iter()
        .filter(|&&c| !blank(c))
        .map(u8::to_ascii_lowercase)
        .collect()
}

/// A LinuxCNC o-word's label as the messages show it: as written, in lower case and without
/// blanks (`o<300>` of `o<300> call`, which [`o_label`] reads as `o300`; review 81-lcnc81
/// R5), where it is a name or a plain number; [`o_label`]'s reading otherwise.
pub(crate) fn o_label_shown(statement: &[u8]) -> Vec<u8> {
    let text = o_text(statement);
    if text.get(1) == Some(&b'<') {
        let end = o_label_end(&text).unwrap_or(text.len());
        return text[..end].to_vec();
    }
    o_label(statement)
}

/// A LinuxCNC o-word's label as the interpreter reads it (lower case, without blanks, a
/// number without its leading zeros): `o<name>` of `O <Name> call [1]`, `o100` of `o0100 sub`.
/// rs274ngc `read_o` reads a numbered o-word as a number (`o0100 sub` ... `o100 call` runs)
/// and a named one after `close_and_downcase` (`o<Name>` is `o<name>`). A label rs274 works
/// out when the line runs (`o#1 call`, `o#<sub> call`, `o[#1+1] call`: `read_o` reads a
/// parameter or an expression there) is kept as written (`o[#1+1]`): no definition is named
/// so, and the checker takes its call's target as not known.
pub(crate) fn o_label(statement: &[u8]) -> Vec<u8> {
    let text = o_text(statement);
    if text.is_empty() {
        return text;
    }
    if text.get(1) == Some(&b'<') {
        let end = o_label_end(&text).unwrap_or(text.len());
        // (a name that is a number as rs274 prints one, `o<300>`, is the label `o300`:
        // read_o names a numbered label by its value's `%d`, so `o<300> sub` answers `o300
        // call` and `M98 P300`; `o<0300>` is no `o300`; lcnc81, `rs274 -g`)
        if let Some(name) = text[..end]
            .strip_prefix(b"o<")
            .and_then(|t| t.strip_suffix(b">"))
        {
            let shown = std::str::from_utf8(name).ok();
            if let Some(n) = shown.and_then(|t| t.parse::<i64>().ok()) {
                if shown == Some(n.to_string().as_str()) {
                    return format!("o{n}").into_bytes();
                }
            }
        }
        return text[..end].to_vec();
    }
    let end = o_label_end(&text).unwrap_or(text.len());
    // a number, signed, with a point or in brackets, is that number's label (`o+100 sub`,
    // `o100.0 call` and `o[0100] call` name `o100 sub`; `o[100] endsub` closes it): rs274
    // reads the value as an integer (`read_integer_value`)
    match o_constant(&text[1..end], 0).and_then(rs274_integer) {
        Some(n) => format!("o{n}").into_bytes(),
        None => text[..end].to_vec(),
    }
}

/// Whether an [`o_label`] is worked out as the line runs (`o#1`, `o[#1+1]`, `o##2`,
/// `oabs[-100]`, a fraction `o100.5`): neither a name (`o<name>`) nor a whole number
/// (`o100`, `o-100`), so that no definition is named so as written.
pub(crate) fn computed_label(label: &[u8]) -> bool {
    match label {
        [b'o', b'<', ..] => false,
        [b'o', b'-', digits @ ..] | [b'o', digits @ ..] => {
            digits.is_empty() || !digits.iter().all(u8::is_ascii_digit)
        }
        _ => false,
    }
}

/// The value of a label written as a number ([`o_number`]) or as one of rs274ngc's unary
/// functions that keep a whole number whole, of such a value (`abs[-100]`, `[abs[-100]]`,
/// `fix[100.9]`, `-fup[-100.5]`): `ABS`, `FIX` (floor), `FUP` (ceil) and `ROUND` (half away
/// from zero), as interp_execute.cc `execute_unary` computes them; `rs274 -g` runs `oabs[-100]
/// sub` ... `o100 endsub` ... `o100 call` (review 48, F4). None for anything else (a
/// parameter, an operation, another function: worked out as the line runs).
fn o_constant(text: &[u8], depth: usize) -> Option<f64> {
    if let Some(value) = o_number(text) {
        return Some(value);
    }
    if depth > 8 {
        return None;
    }
    match text {
        [b'-', inner @ ..] => return o_constant(inner, depth + 1).map(|v| -v),
        [b'+', inner @ ..] => return o_constant(inner, depth + 1),
        [b'[', inner @ .., b']'] if one_group(text) => return o_constant(inner, depth + 1),
        _ => {}
    }
    let letters = text.iter().take_while(|c| c.is_ascii_alphabetic()).count();
    let (name, argument) = text.split_at(letters);
    if !one_group(argument) {
        return None;
    }
    let value = o_constant(&argument[1..argument.len() - 1], depth + 1)?;
    Some(match name {
        b"abs" => value.abs(),
        b"fix" => value.floor(),
        b"fup" => value.ceil(),
        b"round" => (value + if value < 0.0 { -0.5 } else { 0.5 }).trunc(),
        _ => return None,
    })
}

/// Whether `text` is one bracketed group, `[` ... its matching `]`, and nothing after.
fn one_group(text: &[u8]) -> bool {
    if text.first() != Some(&b'[') {
        return false;
    }
    let mut depth = 0usize;
    for (i, &c) in text.iter().enumerate() {
        match c {
            b'[' => depth += 1,
            b']' => {
                depth -= 1;
                if depth == 0 {
                    return i + 1 == text.len();
                }
            }
            _ => {}
        }
    }
    false
}

/// The value of a label written as a number (blanks taken out): signs, brackets around it and
/// inside (`+100`, `-[100]`, `[0100.0]`); None for anything else (a parameter, an operation,
/// a function: worked out as the line runs) and for a number too long to be a label.
fn o_number(text: &[u8]) -> Option<f64> {
    let mut negative = false;
    let mut rest = text;
    loop {
        match rest {
            [b'-', inner @ ..] => {
                negative = !negative;
                rest = inner;
            }
            [b'+', inner @ ..] => rest = inner,
            [b'[', inner @ .., b']'] if !inner.contains(&b'[') => rest = inner,
            _ => break,
        }
    }
    if rest.is_empty()
        || rest.len() > 15
        || !rest.iter().all(|&c| c.is_ascii_digit() || c == b'.')
        || !rest.iter().any(u8::is_ascii_digit)
    {
        return None;
    }
    let value: f64 = std::str::from_utf8(rest).ok()?.parse().ok()?;
    Some(if negative { -value } else { value })
}

/// A value read as an integer as rs274ngc reads one (interp_read.cc `read_integer_value`,
/// which `read_o` and `read_m` use): the whole number below it, or the one above where the
/// value is within 0.0001 of it; None (rs274: "Non integer value for integer") for a value
/// further from both.
pub(crate) fn rs274_integer(value: f64) -> Option<i64> {
    if !value.is_finite() || value.abs() > 1e15 {
        return None;
    }
    let below = value.floor();
    if value - below > 0.9999 {
        Some(value.ceil() as i64)
    } else if value - below > 0.0001 {
        None
    } else {
        Some(below as i64)
    }
}

/// The length of an o-word statement's label in `statement` as written (blanks kept: `o [#1]
/// call` gives 6), from its `o` to the end of its number, name, parameter or bracketed
/// expression ([`o_label_end`]); the whole text where the label is not closed.
pub(crate) fn o_label_len(statement: &[u8]) -> usize {
    let mut seen = 0;
    let wanted = {
        let text: Vec<u8> = statement.iter().copied().filter(|&c| !blank(c)).collect();
        o_label_end(&text).unwrap_or(text.len())
    };
    for (i, &c) in statement.iter().enumerate() {
        if seen == wanted {
            return i;
        }
        if !blank(c) {
            seen += 1;
        }
    }
    statement.len()
}

/// Where the label of an o-word ends in `text` (blanks taken out, `text[0]` the `o`): after
/// its `<name>`, or the value rs274ngc's `read_o` reads there ([`o_value_end`]: a number,
/// signed or with a point, a parameter, `##2`, a bracketed expression, brackets nested, or a
/// function of one); None where a name or a bracket is left open.
fn o_label_end(text: &[u8]) -> Option<usize> {
    if text.get(1)? == &b'<' {
        return Some(text.iter().position(|&c| c == b'>')? + 1);
    }
    o_value_text_end(text, 1)
}

/// [`o_label_end`]'s value from `at` in a text without blanks.
fn o_value_text_end(text: &[u8], at: usize) -> Option<usize> {
    let close = |from: usize| -> Option<usize> {
        let mut depth = 0usize;
        for (i, &c) in text.iter().enumerate().skip(from) {
            match c {
                b'[' => depth += 1,
                b']' if depth == 1 => return Some(i + 1),
                b']' => depth = depth.checked_sub(1)?,
                _ => {}
            }
        }
        None
    };
    let at = at
        + text[at..]
            .iter()
            .take_while(|&&c| matches!(c, b'+' | b'-'))
            .count();
    match text.get(at) {
        Some(b'[') => close(at),
        Some(b'#') => match text.get(at + 1)? {
            b'<' => Some(at + 1 + text[at + 1..].iter().position(|&c| c == b'>')? + 1),
            b'#' | b'[' => o_value_text_end(text, at + 1),
            _ => Some(
                at + 1
                    + text[at + 1..]
                        .iter()
                        .take_while(|c| c.is_ascii_digit())
                        .count(),
            ),
        },
        Some(c) if c.is_ascii_alphabetic() => {
            let letters = text[at..]
                .iter()
                .take_while(|c| c.is_ascii_alphabetic())
                .count();
            if text.get(at + letters) == Some(&b'[') {
                close(at + letters)
            } else {
                Some(at)
            }
        }
        _ => Some(
            at + text[at..]
                .iter()
                .take_while(|&&c| c.is_ascii_digit() || c == b'.')
                .count(),
        ),
    }
}

/// Whether a LinuxCNC statement begins a subroutine's definition (`o<name> sub`, `o100 sub`:
/// Some(true)) or ends it (`o<name> endsub`: Some(false)); None for any other. LinuxCNC reads
/// the line without its blanks, so `o<name>sub` is the same.
pub(crate) fn linuxcnc_definition(statement: &[u8]) -> Option<bool> {
    match o_keyword(statement)?.as_slice() {
        b"sub" => Some(true),
        b"endsub" => Some(false),
        _ => None,
    }
}

/// The keyword of a LinuxCNC o-word statement (`sub`, `endsub`, `if`, `while`...), in lower
/// case and without blanks (`o1 end sub` is endsub); None where the text is no o-word.
pub(crate) fn o_keyword(statement: &[u8]) -> Option<Vec<u8>> {
    let statement: Vec<u8> = statement.iter().copied().filter(|&c| !blank(c)).collect();
    if !statement.first()?.eq_ignore_ascii_case(&b'o') {
        return None;
    }
    let rest = &statement[o_label_end(&statement)?..];
    Some(
        rest.iter()
            .take_while(|c| c.is_ascii_alphabetic())
            .map(u8::to_ascii_lowercase)
            .collect(),
    )
}

const O_WORDS: [&[u8]; 16] = [
    b"SUB",
    b"ENDSUB",
    b"CALL",
    b"IF",
    b"ELSEIF",
    b"ELSE",
    b"ENDIF",
    b"WHILE",
    b"ENDWHILE",
    b"DO",
    b"REPEAT",
    b"ENDREPEAT",
    b"RETURN",
    b"BREAK",
    b"CONTINUE",
    b"ENDDO",
];

fn linuxcnc<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let syntax = dialect.syntax();
    let b = line[pos];
    if b == b'#' {
        return parameter_word(line, pos, dialect, words);
    }
    if b == b'@' || b == b'^' || b == b'$' {
        return polar_word(line, pos, syntax, words);
    }
    if !b.eq_ignore_ascii_case(&b'O') {
        return Ok(None);
    }
    // o100 or o<name>, then the keyword; blanks anywhere (`O <name> call`, `o 1 0 0 if`), as
    // rs274ngc drops them before it reads the line
    let open = skip_blanks(line, pos + 1);
    let label_end = match line.get(open) {
        Some(b'<') => match line[open + 1..].iter().position(|&c| c == b'>') {
            Some(close) if close > 0 => open + 1 + close + 1,
            _ => {
                return Err(err(
                    ErrorKind::Value,
                    "o-word name 'o<' without its closing '>'".into(),
                    pos,
                    "LinuxCNC O codes",
                ))
            }
        },
        // rs274ngc `read_o` reads any other label as `read_integer_value` reads a value: a
        // number (`o100`, `o+100`, `o100.0`), or one worked out when the line runs
        // (`o[#1+1] call`, `o#1 call`, `o#<sub> call`, `o##2 call`, `oabs[-100] call`)
        _ => match o_value_end(line, open, syntax)? {
            Some(end) => end,
            None => return Ok(None),
        },
    };
    // LinuxCNC reads a line without its blanks: "else if" is elseif
    let p = skip_blanks(line, label_end);
    let mut keyword = Vec::new();
    let mut word = p;
    let mut q = p;
    while q < line.len() && keyword.len() <= 9 {
        if line[q].is_ascii_alphabetic() {
            keyword.push(line[q].to_ascii_uppercase());
            q += 1;
            word = q;
        } else if blank(line[q]) {
            q += 1;
        } else {
            break;
        }
    }
    let Some(known) = O_WORDS.iter().find(|k| **k == keyword.as_slice()) else {
        if word > p {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "unknown o-word keyword '{}' (known: sub endsub call if elseif else endif \
                     while endwhile do repeat endrepeat return break continue)",
                    String::from_utf8_lossy(&line[p..word])
                ),
                p,
                "LinuxCNC O codes",
            ));
        }
        return Ok(None); // O100: a program number
    };
    // the arguments or the condition: bracketed groups
    let mut end = word;
    loop {
        let q = skip_blanks(line, end);
        if line.get(q) == Some(&b'[') {
            end = expr::scan_group(line, q, syntax)?;
        } else {
            break;
        }
    }
    let needs_condition = matches!(*known, b"IF" | b"ELSEIF" | b"WHILE" | b"REPEAT");
    if needs_condition && end == word {
        return Err(err(
            ErrorKind::Expression,
            format!(
                "o-word {} must be followed by its condition in brackets [ ]",
                String::from_utf8_lossy(&keyword).to_lowercase()
            ),
            skip_blanks(line, word),
            "LinuxCNC O codes",
        ));
    }
    let kind = match *known {
        b"SUB" | b"ENDSUB" => Kind::Definition,
        b"CALL" => Kind::Call,
        _ => Kind::Flow,
    };
    Ok(statement(pos, end, kind))
}

/// Where the value of a LinuxCNC o-word's label that is no `<name>` ends, from `at` (its
/// first byte after the `o` and blanks), read as rs274ngc's `read_real_value` reads one
/// (interp_read.cc, called by `read_o` through `read_integer_value`): signs before it (`+`,
/// `-`), then a number (`100`, `100.0`, `.5`, its digits through blanks), a parameter (`#1`,
/// `#<sub>`, `#[#1+1]`, `##2`), an expression in brackets or a function of one (`abs[-100]`).
/// None where none of these stands there (`O100` is a word of another reading then, and
/// `o` before anything else is no label).
#[inline(never)]
fn o_value_end(line: &[u8], at: usize, syntax: Syntax) -> Result<Option<usize>, LexError> {
    let mut at = at;
    while matches!(line.get(at), Some(b'+' | b'-')) {
        at = skip_blanks(line, at + 1);
    }
    Ok(Some(match line.get(at) {
        Some(d) if d.is_ascii_digit() || *d == b'.' => match expr::spaced_number_end(line, at) {
            Some(end) => end,
            None => return Ok(None),
        },
        Some(b'[') => expr::scan_group(line, at, syntax)?,
        Some(b'#') => {
            let next = skip_blanks(line, at + 1);
            match line.get(next) {
                Some(b'<') => match line[next..].iter().position(|&c| c == b'>') {
                    Some(close) if close > 1 => next + close + 1,
                    _ => {
                        return Err(err(
                            ErrorKind::Value,
                            "o-word parameter '#<' without its closing '>'".into(),
                            next,
                            "LinuxCNC O codes",
                        ))
                    }
                },
                Some(d) if d.is_ascii_digit() => expr::spaced_digits_end(line, next),
                // `##2`, `#[#1+1]`: the parameter whose number is a value
                Some(b'#' | b'[') => match o_value_end(line, next, syntax)? {
                    Some(end) => end,
                    None => return Ok(None),
                },
                _ => return Ok(None),
            }
        }
        Some(c) if c.is_ascii_alphabetic() && expr::function_ahead(line, at) => {
            expr::scan_operand(line, at, syntax)?
        }
        _ => return Ok(None),
    }))
}

/// LinuxCNC's words of other characters: the polar `@` (distance) and `^` (angle), and `$`
/// (the spindle an M3/M4/M5/S applies to).
fn polar_word<'a>(
    line: &'a [u8],
    pos: usize,
    syntax: Syntax,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let mut p = skip_blanks(line, pos + 1);
    if matches!(line.get(p), Some(b'+' | b'-')) {
        p = skip_blanks(line, p + 1);
    }
    let end = match expr::number_end(line, p) {
        Some(end) => end,
        None if matches!(line.get(p), Some(b'#' | b'[')) => expr::scan_operand(line, p, syntax)?,
        None => {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "polar word {} must be followed by a number",
                    line[pos] as char
                ),
                p,
                "LinuxCNC G codes",
            ))
        }
    };
    Ok(Some(word(line, pos, end, words)))
}

// -- Siemens Sinumerik 840D ---------------------------------------------------------------------

/// Keywords that take the rest of the block as their arguments: the axis words after `TRANS`
/// shift the frame, they do not move. (`IF`, `WHILE` and `UNTIL` read their condition into
/// the expression tree: [`SINUMERIK_CONDITIONS`].)
const SINUMERIK_REST: &[&[u8]] = &[
    // declarations (Job Planning, "Flexible NC programming" and "Subprogram technique"): a
    // variable's `DEF REAL _X`, a macro's `DEFINE M6 AS L6`, a subprogram's own head
    // `PROC NAME(REAL X) SAVE` and another's `EXTERN NAME(REAL)`: none calls anything
    b"DEF",
    b"DEFINE",
    b"PROC",
    b"EXTERN",
    b"ELSE",
    b"ENDIF",
    b"ENDWHILE",
    b"FOR",
    b"ENDFOR",
    b"LOOP",
    b"ENDLOOP",
    b"REPEAT",
    b"REPEATB",
    b"CASE",
    b"GOTOF",
    b"GOTOB",
    b"GOTO",
    b"GOTOC",
    b"GOTOS",
    // frames (Fundamentals, "Coordinate transformations (frames)"): the axis words after the
    // instruction shift, turn, scale or mirror the frame, they do not move
    b"TRANS",
    b"ATRANS",
    b"ROT",
    b"AROT",
    b"ROTS",
    b"AROTS",
    // CROTS: "works in the same way as ROTS but refers to the valid frame in the data
    // memory" (NC programming 12/2019, 2.12, beside ROTS and AROTS, a frame statement in a
    // block of its own); the list of operations types it a function, for its use in a frame
    // expression (`$P_PFRAME=CROTS(..)`, an assignment)
    b"CROTS",
    b"SCALE",
    b"ASCALE",
    b"MIRROR",
    b"AMIRROR",
    // synchronized actions: ID=7 EVERY $A_IN[7]<>0 DO $R1=1 (their conditions and actions run
    // beside the program, in the interpolation cycle)
    b"WHEN",
    b"WHENEVER",
    b"EVERY",
    b"FROM",
];

/// The letters a SINUMERIK's extended address takes (in either case): the axes by their ISO
/// letters, I J K, S, M, H, T and F (Programming Manual Fundamentals, "Extended addresses";
/// SPOS and SPOSA are names). [`crate::dialect::extended_address`] asks it for the checker.
pub(crate) fn extended_letter(letter: u8) -> bool {
    matches!(
        letter.to_ascii_uppercase(),
        b'X' | b'Y'
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
            | b'S'
            | b'M'
            | b'H'
            | b'T'
            | b'F'
    )
}

fn ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_' || b == b'$'
}

pub(crate) fn ident_end(line: &[u8], pos: usize) -> usize {
    let mut end = pos;
    while end < line.len()
        && (line[end].is_ascii_alphanumeric() || line[end] == b'_' || line[end] == b'$')
    {
        end += 1;
    }
    end
}

/// Whether the LinuxCNC reader ([`read`]) would find no statement at a character `b`, asked by
/// the tokenizer before it calls the reader for every word: its statements open with an O word
/// (`o100 if`, `o<name> call`) and its own words with `#`, `@`, `^` or `$` ([`linuxcnc`]), so
/// any other letter is a word it would pass back.
pub(crate) fn linuxcnc_word_ahead(b: u8) -> bool {
    b.is_ascii_alphabetic() && !b.eq_ignore_ascii_case(&b'O')
}

/// Whether the SINUMERIK reader ([`read`]) would find no statement at `pos` by the first two
/// characters alone: the plain words most blocks are (`X-1.5`, `G1`, `Y.5`), asked by the
/// tokenizer before it calls the reader for every word. A letter and a sign or a point is a
/// word, as `sinumerik` reads it; a letter and a digit too (a name begins with two letters or
/// underscores), but for R, whose `R1=R2*5` is read whole there, and for an extended address
/// (`S1=INI[53]`, digits then `=`), whose value is an expression read there too.
pub(crate) fn sinumerik_word_ahead(line: &[u8], pos: usize) -> bool {
    let b = line[pos];
    b.is_ascii_alphabetic()
        && line.get(pos + 1).is_some_and(|&c| {
            matches!(c, b'+' | b'-' | b'.')
                || (c.is_ascii_digit()
                    && !b.eq_ignore_ascii_case(&b'R')
                    && !extended(line, pos + 1))
        })
}

/// Whether the digits at `pos` are an address extension: `=` follows them (`S1=`, `X4=`).
fn extended(line: &[u8], pos: usize) -> bool {
    let digits = line[pos..]
        .iter()
        .take_while(|c| c.is_ascii_digit())
        .count();
    line.get(skip_blanks(line, pos + digits)) == Some(&b'=')
}

fn sinumerik<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let b = line[pos];
    if b == b'@' {
        let end = rest_end(line, pos, dialect, false);
        return Ok(statement(pos, end, Kind::Command));
    }
    if !ident_start(b) {
        return Ok(None);
    }
    let end = ident_end(line, pos);
    let single = end - pos == 1
        || (b.is_ascii_alphabetic() && line[pos + 1..end].iter().all(u8::is_ascii_digit));
    let after = skip_blanks(line, end);
    if single && b.is_ascii_alphabetic() && end - pos == 1 && line.get(after) == Some(&b'=') {
        // X=R1+5, F=R2, T="TOOL": a word whose value is an expression
        let value_end = siemens_expression(line, skip_blanks(line, after + 1))?;
        return Ok(Some(word(line, pos, value_end, words)));
    }
    // R1=R2*SIN(30): an R parameter set by an expression, as one word (R0 included: the R
    // parameters count from 0, machine data 28050). S1=INI[53], M3=5, X4=20, H1=2: an
    // extended address, a numeric extension and an arithmetic expression after '=', the same
    // expression as after X= (Programming Manual Fundamentals, "Extended addresses"); the
    // extension's range is the checker's (TG206). Another letter's index (D1=R1, L1=R2) is
    // the ISO reader's, as before extended addresses were read.
    let assigned = line.get(after) == Some(&b'=') && line.get(after + 1) != Some(&b'=');
    let extended = b.eq_ignore_ascii_case(&b'R') || extended_letter(b);
    if single && end > pos + 1 && assigned && extended {
        let value_end = siemens_expression(line, skip_blanks(line, after + 1))?;
        return Ok(Some(word(line, pos, value_end, words)));
    }
    // G[8]=MER_KORD_SYS: indirect G code programming, the code of G group 8 chosen by a
    // value; M[BrojVretena]=3: an address extension given by a variable (the spindle)
    if end - pos == 1 && b.is_ascii_alphabetic() && line.get(after) == Some(&b'[') {
        let close = brackets(line, after)?;
        let eq = skip_blanks(line, close);
        if line.get(eq) == Some(&b'=') {
            let value_end = siemens_expression(line, skip_blanks(line, eq + 1))?;
            return Ok(statement(pos, value_end, Kind::Assignment));
        }
    }
    if single {
        return Ok(None); // X10, R11=2, G601, L100: ISO words
    }
    // A name's first two characters are letters or underscores (Programming Manual
    // Fundamentals, "Identifiers" / "Naming rules"): a letter and a digit begin address words
    // written without a blank between them, G1X-1 or G0X170Z5, not a name.
    if b.is_ascii_alphabetic() && line[pos + 1].is_ascii_digit() {
        return Ok(None);
    }
    let name = Upper::of(&line[pos..end]);
    if SINUMERIK_CONDITIONS.contains(&name.as_slice()) {
        let end = siemens_condition(line, &name, end, dialect)?;
        return Ok(statement(pos, end, Kind::Flow));
    }
    if matches!(name.as_slice(), b"CALL" | b"PCALL" | b"EXTCALL") {
        // CALL "name" or a string variable, PCALL name with a path, EXTCALL "name" from
        // external memory (Job Planning, "Subprogram technique")
        return Ok(statement(
            pos,
            rest_end(line, pos, dialect, false),
            Kind::Call,
        ));
    }
    if SINUMERIK_REST.contains(&name.as_slice()) {
        let kind = match name.as_slice() {
            b"DEF" | b"DEFINE" | b"PROC" | b"EXTERN" => Kind::Declaration,
            b"TRANS" | b"ATRANS" | b"ROT" | b"AROT" | b"ROTS" | b"AROTS" | b"CROTS" | b"SCALE"
            | b"ASCALE" | b"MIRROR" | b"AMIRROR" | b"WHEN" | b"WHENEVER" | b"EVERY" | b"FROM" => {
                Kind::Command
            }
            _ => Kind::Flow,
        };
        return Ok(statement(pos, rest_end(line, pos, dialect, false), kind));
    }
    match line.get(after) {
        Some(b'=') if line.get(after + 1) != Some(&b'=') => {
            let value_end = siemens_expression(line, skip_blanks(line, after + 1))?;
            Ok(statement(pos, value_end, Kind::Assignment))
        }
        Some(b'(') => {
            let close = parens(line, after)?;
            // TRAORI(1), SETMS(2): a predefined procedure with its arguments, no subprogram
            // (a program may not take a predefined instruction's name); CYCLE800(..) or a
            // user's MYSUB(1, 2) is a call
            let kind = if name.starts_with(b"MSG") {
                Kind::Message
            } else {
                match sinumerik_instruction(&name) {
                    Some(group) if group.arguments && group.effect != Effect::Unclear => {
                        Kind::Command
                    }
                    _ => Kind::Call,
                }
            };
            Ok(statement(pos, close, kind))
        }
        Some(b':') if line.get(after + 1) != Some(&b'=') => {
            Ok(statement(pos, after + 1, Kind::Label))
        }
        Some(b'[') => {
            // an array element: _A[1]=5
            let close = brackets(line, after)?;
            let eq = skip_blanks(line, close);
            if line.get(eq) == Some(&b'=') {
                let value = skip_blanks(line, eq + 1);
                // OSCTRL[Z]=(1+2,16+32+64): a pair of values in parentheses (the options
                // an oscillation sets and resets)
                let value_end = match siemens_expression(line, value) {
                    Err(_) if line.get(value) == Some(&b'(') => parens(line, value)?,
                    other => other?,
                };
                Ok(statement(pos, value_end, Kind::Assignment))
            } else {
                Ok(statement(pos, close, Kind::Command))
            }
        }
        // a predefined instruction (TRAFOOF, SUPA, STOPRE...), or else a subprogram called
        // by its name ("an NC program can be called as subprogram just by specifying the
        // program name", Programming Manual, "Subprogram names"; a cycle's name too). An
        // identifier takes no separator inside, so `G0SUPAZ0` writes the one name SUPAZ0: a
        // call of a program of that name, not SUPA then Z0 (Fundamentals, "Identifiers")
        _ if sinumerik_instruction(&name).is_some_and(|g| g.effect != Effect::Unclear) => {
            Ok(statement(pos, end, Kind::Command))
        }
        _ => Ok(statement(pos, end, Kind::Call)),
    }
}

/// What an instruction of [`SINUMERIK_INSTRUCTIONS`] leaves the checker to follow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Effect {
    /// A mode the checker does not model (a feed profile, a compensation type, an
    /// orientation...): the program is followed past it, the position, feed and speed kept.
    Mode,
    /// A motion of G group 1 the checker does not model (splines, `CIP`, `CT`, involutes): the
    /// motion in force is unknown until G0, G1, G2 or G3 sets one, so the points after it are
    /// not checked as lines or arcs.
    Motion,
    /// A repositioning to where an interrupted program left the path (`REPOSA`): the position
    /// is unknown until a move sets it.
    Reposition,
    /// A frame turned to the tool or the workpiece (`TOROT`, `TOFRAME`, `PAROT`): the work
    /// offsets are no longer the profile's, as after `ROT`.
    Frame,
    /// A procedure that moves, couples or reconfigures axes, or sets their actual values
    /// (`LEADON`, `TRAORI`, `GEOAX`, `PRESETON`): the position is unknown until a move sets
    /// it, and the profile's work offsets are no longer the ones in force; the feed and speed
    /// stay. The checker says so once, naming the procedure (TG140).
    Axes,
    /// The master spindle set (`SETMS(2)`): S and M3 address another spindle from here on,
    /// whose speed the checker does not know.
    Spindle,
    /// The end of a subprogram (`RET`, `RET("L1")`), as M17.
    Return,
    /// A procedure whose effect the sources leave unclear for the checker (`NEWCONF`,
    /// `EXECSTRING`, `TCA`): read as a call, after which nothing is known (TG140).
    Unclear,
    /// A kinematic transformation (`TRACYL(400)`, `TRAORI`, `TRANSMIT(1)`...): until `TRAFOOF`
    /// the axes are programmed in other coordinates (under `TRACYL`, Y is the distance round
    /// the cylinder), so the position is unknown and no position is a machine position.
    Transform,
}

/// One group of the SINUMERIK's predefined instructions, as a manual lists them.
pub(crate) struct Instructions {
    pub(crate) effect: Effect,
    /// Whether its names are predefined procedures that take arguments in parentheses
    /// (`TRAORI(1)`, `SETMS(2)`): no call of a subprogram, since a program may not take the
    /// name of a predefined instruction.
    pub(crate) arguments: bool,
    /// What the group's procedures do to the axes, for the checker's message ([`Effect::Axes`]
    /// only; empty otherwise).
    pub(crate) what: &'static str,
    /// The names, in upper case (the reader compares a name in upper case).
    pub(crate) names: &'static [&'static [u8]],
}

/// The instruction group of `name` (in upper case), if it is one of the SINUMERIK's predefined
/// instructions: [`SINUMERIK_INSTRUCTIONS`].
/// A name in upper case, on the stack where it is short (an instruction's name, looked up for
/// every SINUMERIK statement of every block), else in a `Vec`: no allocation a statement.
pub(crate) enum Upper {
    Short([u8; 32], usize),
    Long(Vec<u8>),
}

impl Upper {
    pub(crate) fn of(text: &[u8]) -> Upper {
        if text.len() <= 32 {
            let mut buffer = [0u8; 32];
            buffer[..text.len()].copy_from_slice(text);
            buffer[..text.len()].make_ascii_uppercase();
            Upper::Short(buffer, text.len())
        } else {
            Upper::Long(text.to_ascii_uppercase())
        }
    }

    pub(crate) fn as_slice(&self) -> &[u8] {
        match self {
            Upper::Short(buffer, len) => &buffer[..*len],
            Upper::Long(text) => text,
        }
    }
}

impl std::ops::Deref for Upper {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        self.as_slice()
    }
}

pub(crate) fn sinumerik_instruction(name: &[u8]) -> Option<&'static Instructions> {
    // (a name's length and first letter compared before its bytes: the list holds some 400
    // names, and a program's statements are looked up in it block after block)
    let first = *name.first()?;
    SINUMERIK_INSTRUCTIONS.iter().find(|group| {
        group
            .names
            .iter()
            .any(|n| n.len() == name.len() && n[0] == first && *n == name)
    })
}

/// Whether a SINUMERIK statement is a return from a subprogram: `RET`, also with the block
/// of the caller to return to (`RET("L1")`, `RET(N100,,2)`; Job Planning, "Subprogram
/// technique").
pub(crate) fn sinumerik_returns(text: &[u8]) -> bool {
    let name = Upper::of(&text[..ident_end(text, 0)]);
    sinumerik_instruction(&name).is_some_and(|group| group.effect == Effect::Return)
}

/// The SINUMERIK's predefined instructions that a block may hold as a name alone (`TRAFOOF`,
/// `SOFT`, `DYNNORM`), or, for the procedures among them, with arguments in parentheses
/// (`TRAORI(1)`): the reader takes them for instructions, not subprogram calls, and the
/// group's [`Effect`] tells the checker what it follows past one. Every predefined procedure
/// of the list of operations is here, in one of three classes: (a) nothing the checker
/// follows changes ([`Effect::Mode`]); (b) the axes move, couple or change configuration, or
/// their actual values are set ([`Effect::Axes`]: the position unknown, named); (c) what it
/// leaves is unclear from the sources ([`Effect::Unclear`]: read as a call). A name not here
/// is read as a call, after which the checker takes the position as unknown, which is safe for
/// an instruction the list lacks. The frame instructions with axis words (`TRANS X10`) and the
/// declarations are [`SINUMERIK_REST`].
///
/// Checked name by name against two sources: the G function tables ("List of G
/// functions/preparatory functions", Programming Manual Fundamentals 10.2004, 6FC5
/// 298-7AB00-0BP1, and 11/2006, 6FC5398-1BP10-2BA0, 12.3; "G commands", SINUMERIK ONE / 840D sl
/// Programming Manual NC programming 12/2019, 6FC5398-2EP40-0BA0, 4.3), whose G groups name
/// the modal commands written as names; and the list of operations of the NC programming
/// manual (CNC software 6.20), whose type says a G command, a predefined procedure (P), a
/// keyword (K) or a program attribute (PA). Functions (F: `CTRANS`, `CROT`, `CSCALE`,
/// `CMIRROR`, which give a frame inside an expression) stand in no block alone and are not
/// here. docs/dialects.md keeps the table of the groups and what changed.
pub(crate) static SINUMERIK_INSTRUCTIONS: &[Instructions] = &[
    // G group 1: modally valid motion commands
    Instructions {
        effect: Effect::Motion,
        arguments: false,
        what: "",
        names: &[
            b"CIP", b"ASPLINE", b"BSPLINE", b"CSPLINE", b"POLY", b"OEMIPO1", b"OEMIPO2", b"CT",
            b"INVCW", b"INVCCW",
        ],
    },
    // G group 2: non-modal motions (repositioning, REPOS)
    Instructions {
        effect: Effect::Reposition,
        arguments: false,
        what: "",
        names: &[
            b"REPOSL", b"REPOSQ", b"REPOSH", b"REPOSA", b"REPOSQA", b"REPOSHA",
        ],
    },
    // G group 4: FIFO
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[b"STARTFIFO", b"STOPFIFO", b"FIFOCTRL"],
    },
    // G group 9: frame suppression
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[b"SUPA", b"SUPD"],
    },
    // G groups 52 and 53: workpiece-oriented frame, frame rotations in tool direction
    Instructions {
        effect: Effect::Frame,
        arguments: false,
        what: "",
        names: &[
            b"PAROT",
            b"PAROTOF",
            b"TOROT",
            b"TOROTOF",
            b"TOROTX",
            b"TOROTY",
            b"TOROTZ",
            b"TOFRAME",
            b"TOFRAMEX",
            b"TOFRAMEY",
            b"TOFRAMEZ",
        ],
    },
    // G commands of feedrate and path dynamic response (G groups 16, 21, 24, 45, 57, 59...)
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[
            b"CFC",
            b"CFTCP",
            b"CFIN",
            b"BRISK",
            b"SOFT",
            b"DRIVE",
            b"FFWOF",
            b"FFWON",
            b"FNORM",
            b"FLIN",
            b"FCUB",
            b"CPRECOF",
            b"CPRECON",
            b"SPATH",
            b"UPATH",
            b"FENDNORM",
            b"DYNNORM",
            b"DYNPOS",
            b"DYNROUGH",
            b"DYNSEMIFIN",
            b"DYNFINISH",
            b"DYNPREC",
        ],
    },
    // G commands of fast retraction (G group 46...; LIFTFAST, a keyword)
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[b"LIFTFAST", b"LFOF", b"LFON", b"LFTXT", b"LFWP", b"LFPOS"],
    },
    // G commands of tool radius compensation and tool offsets (G groups 17, 22, 23, 27, 56...)
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[
            b"NORM",
            b"KONT",
            b"KONTT",
            b"KONTC",
            b"CUT2D",
            b"CUT2DF",
            b"CUT3DC",
            b"CUT3DF",
            b"CUT3DFS",
            b"CUT3DFF",
            b"CUT3DCC",
            b"CUT3DCCD",
            b"CUT2DD",
            b"CUT2DFD",
            b"CUT3DCD",
            b"CUT3DFD",
            b"CDOF",
            b"CDON",
            b"CDOF2",
            b"ORIC",
            b"ORID",
            b"FTOCOF",
            b"FTOCON",
            b"OSOF",
            b"OSC",
            b"OSS",
            b"OSSE",
            b"OSD",
            b"OST",
            b"CUTCONOF",
            b"CUTCONON",
            b"TOWSTD",
            b"TOWMCS",
            b"TOWWCS",
            b"TOWBCS",
            b"TOWTCS",
            b"TOWKCS",
        ],
    },
    // G commands of tool orientation (G groups 25, 50, 51, 54...)
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[
            b"ORIWKS",
            b"ORIMKS",
            b"TCOABS",
            b"TCOFR",
            b"TCOFRZ",
            b"TCOFRY",
            b"TCOFRX",
            b"CP",
            b"PTP",
            b"PTPG0",
            b"PTPWOC",
            b"ORIEULER",
            b"ORIRPY",
            b"ORIVIRT1",
            b"ORIVIRT2",
            b"ORIAXPOS",
            b"ORIRPY2",
            b"ORIVECT",
            b"ORIAXES",
            b"ORIPATH",
            b"ORIPLANE",
            b"ORICONCW",
            b"ORICONCCW",
            b"ORICONIO",
            b"ORICONTO",
            b"ORICURVE",
            b"ORIPATHS",
            b"ORIAXESFR",
            b"ORICURINV",
            b"ORIANGLE",
            b"ORIROTA",
            b"ORIROTR",
            b"ORIROTT",
            b"ORIROTC",
            b"ORISOF",
            b"ORISON",
        ],
    },
    // G groups 19, 20, 30: spline transitions and compressor
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[
            b"BNAT",
            b"BTAN",
            b"BAUTO",
            b"ENAT",
            b"ETAN",
            b"EAUTO",
            b"COMPOF",
            b"COMPON",
            b"COMPCURV",
            b"COMPCAD",
            b"COMPSURF",
            b"COMPPATH",
        ],
    },
    // G group 29: radius/diameter programming (DIAMCHAN, a keyword)
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[b"DIAMOF", b"DIAMON", b"DIAM90", b"DIAMCYCOF", b"DIAMCHAN"],
    },
    // G commands of repositioning mode, working area limitation, rapid traverse (G groups 26,
    // 28, 55, 60)
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[
            b"RMB", b"RMI", b"RME", b"RMN", b"RMBBL", b"RMIBL", b"RMEBL", b"RMNBL", b"WALIMON",
            b"WALIMOF", b"WALCS0", b"WALCS1", b"WALCS2", b"WALCS3", b"WALCS4", b"WALCS5",
            b"WALCS6", b"WALCS7", b"WALCS8", b"WALCS9", b"WALCS10", b"RTLION", b"RTLIOF",
        ],
    },
    // G commands of punching and nibbling
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[
            b"SPOF",
            b"SON",
            b"PON",
            b"SONS",
            b"PONS",
            b"PDELAYON",
            b"PDELAYOF",
            b"SPIF1",
            b"SPIF2",
        ],
    },
    // list of operations, keyword (K) and program attributes (PA): MCALL, DISPLOF, DISPLON
    Instructions {
        effect: Effect::Mode,
        arguments: false,
        what: "",
        names: &[b"MCALL", b"DISPLOF", b"DISPLON"],
    },
    // The predefined procedures (P) of the list of operations, each in the class of what the
    // checker must do after it (docs/dialects.md, "SINUMERIK predefined procedures"). They
    // take their arguments in parentheses (`SETAL(61000)`, `LEADON(A,X,1)`).
    //
    // (a) nothing the checker follows changes. Program run and preprocessing (NC
    // programming): STOPRE, single block, alarms, messages and dialogs, stop delay
    Instructions {
        effect: Effect::Mode,
        arguments: true,
        what: "",
        names: &[
            b"STOPRE",
            b"STOPREOF",
            b"SBLOF",
            b"SBLON",
            b"ACTBLOCNO",
            b"IPTRLOCK",
            b"IPTRUNLOCK",
            b"DELAYFSTON",
            b"DELAYFSTOF",
            b"SETAL",
            b"MSG",
            b"MMC",
            b"WRTPR",
            b"CALLPATH",
            b"ICYCON",
            b"ICYCOF",
        ],
    },
    // (a) channels, markers and waits (program coordination), interrupts, synchronized actions
    // (Function Manual Synchronized actions): the other channel's or action's motion is not
    // this program's position; WAITP waits for a positioning axis whose POS[X]= or POSA[X]=
    // already left its position unknown (check::motion, `positioned`)
    Instructions {
        effect: Effect::Mode,
        arguments: true,
        what: "",
        names: &[
            b"INIT",
            b"START",
            b"WAITE",
            b"WAITM",
            b"WAITMC",
            b"SETM",
            b"CLEARM",
            b"CHANDATA",
            b"WAITC",
            b"WAITENC",
            b"WAITP",
            b"WAITS",
            b"ENABLE",
            b"DISABLE",
            b"CLRINT",
            b"CANCEL",
            b"LOCK",
            b"UNLOCK",
            b"RDISABLE",
            b"SYNFCT",
        ],
    },
    // (a) files, auxiliary function lists, drive data, stop and retract, Safety Integrated
    Instructions {
        effect: Effect::Mode,
        arguments: true,
        what: "",
        names: &[
            b"DELETE",
            b"EXTOPEN",
            b"EXTCLOSE",
            b"READ",
            b"WRITE",
            b"FILEDATE",
            b"FILEINFO",
            b"FILESIZE",
            b"FILESTAT",
            b"FILETIME",
            b"AUXFUDEL",
            b"AUXFUDELG",
            b"AUXFUMSEQ",
            b"AUXFUSYNC",
            b"DRVPRD",
            b"DRVPWR",
            b"ESRR",
            b"ESRS",
            b"POLFA",
            b"POLFMASK",
            b"POLFMLIN",
            b"SIRELIN",
            b"SIRELOUT",
            b"SIRELTIME",
        ],
    },
    // (a) modes of single axes and of the path (acceleration, filters, revolutional feed,
    // positioning windows, spline and polynomial groups, load adjustment), spindle position
    // control
    Instructions {
        effect: Effect::Mode,
        arguments: true,
        what: "",
        names: &[
            b"BRISKA",
            b"SOFTA",
            b"DRIVEA",
            b"JERKA",
            b"ADISPOSA",
            b"IPOBRKA",
            b"AFISON",
            b"AFISOF",
            b"CALCFIR",
            b"FPR",
            b"FPRAON",
            b"FPRAOF",
            b"FGROUP",
            b"PUNCHACC",
            b"CADAPTON",
            b"CADAPTOF",
            b"SPLINEPATH",
            b"POLYPATH",
            b"SPCON",
            b"SPCOF",
        ],
    },
    // (a) definitions that move nothing until an activation of class (b) does: couplings,
    // tangential control, polynomials, protection areas, curve tables' locks; the axis
    // container's enable withdrawn
    Instructions {
        effect: Effect::Mode,
        arguments: true,
        what: "",
        names: &[
            b"COUPDEF",
            b"COUPDEL",
            b"EGDEF",
            b"EGDEL",
            b"MASLDEF",
            b"TANG",
            b"TANGDEL",
            b"TANGOF",
            b"TLIFT",
            b"FCTDEF",
            b"CPROTDEF",
            b"NPROTDEF",
            b"CPROT",
            b"NPROT",
            b"PROTA",
            b"PROTS",
            b"CTABDEL",
            b"CTABLOCK",
            b"CTABUNLOCK",
            b"AXCTSWEC",
        ],
    },
    // (a) tool management and monitoring (Function Manual Tool management): data and
    // magazine positions, not this program's axes
    Instructions {
        effect: Effect::Mode,
        arguments: true,
        what: "",
        names: &[
            b"DELT",
            b"DELTC",
            b"DELMT",
            b"DZERO",
            b"GETSELT",
            b"GETEXET",
            b"GETFREELOC",
            b"SETPIECE",
            b"SETTA",
            b"SETTIA",
            b"SETMTH",
            b"MVTOOL",
            b"POSM",
            b"POSMT",
            b"TMON",
            b"TMOF",
            b"RESETMON",
        ],
    },
    // the master spindle (SETMS(2): S and M3 are spindle 2's from here on): its speed unknown
    Instructions {
        effect: Effect::Spindle,
        arguments: true,
        what: "",
        names: &[b"SETMS"],
    },
    // the end of a subprogram, also with a return to a block of the caller (`RET("L1")`, Job
    // Planning, "Subprogram technique")
    Instructions {
        effect: Effect::Return,
        arguments: true,
        what: "",
        names: &[b"RET", b"RETB"],
    },
    // (b) couplings of axes and spindles: the following axes move with their leading axis,
    // and stay where the coupling took them when it ends
    Instructions {
        effect: Effect::Axes,
        arguments: true,
        what: "couples axes or spindles",
        names: &[
            b"LEADON",
            b"LEADOF",
            b"TRAILON",
            b"TRAILOF",
            b"EGON",
            b"EGONSYN",
            b"EGONSYNE",
            b"EGOFC",
            b"EGOFS",
            b"COUPON",
            b"COUPONC",
            b"COUPOF",
            b"COUPOFS",
            b"COUPRES",
            b"MASLON",
            b"MASLOF",
            b"MASLOFS",
            b"MASLDEL",
            b"TANGON",
        ],
    },
    // (b) the kinematic transformations: until TRAFOOF the axes are programmed in other
    // coordinates (Job Planning, "Transformations")
    Instructions {
        effect: Effect::Transform,
        arguments: true,
        what: "selects or ends a kinematic transformation",
        names: &[
            b"TRAORI",
            b"TRACYL",
            b"TRANSMIT",
            b"TRAANG",
            b"TRACON",
            b"TRAFOON",
            b"TRAFOOF",
        ],
    },
    // (b) the axis configuration: geometry axes, axis exchange between channels, axis
    // containers, the initial tool orientation
    Instructions {
        effect: Effect::Axes,
        arguments: true,
        what: "changes the axis configuration",
        names: &[
            b"GEOAX",
            b"GET",
            b"GETD",
            b"RELEASE",
            b"AXTOCHAN",
            b"AXCTSWE",
            b"AXCTSWED",
            b"ORIRESET",
        ],
    },
    // (b) actual values and overlaid motions: PRESETON sets an actual value; an online tool
    // offset (TOFFON, and PUTFTOC, PUTFTOCF, FTOC: "overlaid movement for a geometry axis",
    // Job Planning 8.3 and 10.4.9) or a motion table moves the axes; CORROF, DELDTG and DRFOF
    // (the handwheel's DRF offset of every axis) end overlaid motions and distances to go
    Instructions {
        effect: Effect::Axes,
        arguments: true,
        what: "sets actual values or moves the axes by an overlaid motion",
        names: &[
            b"PRESETON",
            b"PRESETONS",
            b"TOFFON",
            b"TOFFOF",
            b"CORROF",
            b"DELDTG",
            b"EXECTAB",
            b"DRFOF",
            b"PUTFTOC",
            b"PUTFTOCF",
            b"FTOC",
        ],
    },
    // (b) tables: the blocks from CTABDEF to CTABEND define a curve table, from CONTPRON or
    // CONTDCON to EXECUTE a contour table: they are stored, not run
    Instructions {
        effect: Effect::Axes,
        arguments: true,
        what: "begins or ends a table whose blocks are stored, not run",
        names: &[b"CTABDEF", b"CTABEND", b"CONTPRON", b"CONTDCON", b"EXECUTE"],
    },
    // (c) not clear from the source what they leave: read as calls (TG140). NEWCONF applies
    // changed machine data (any of them); EXECSTRING runs a string as a block; CANCELSUB ends
    // a subprogram level from a synchronized action; TCA, TCI, TML select or change a tool
    // outside the T word; GWPSON/GWPSOF turn S into a grinding wheel's peripheral speed
    Instructions {
        effect: Effect::Unclear,
        arguments: true,
        what: "",
        names: &[
            b"NEWCONF",
            b"EXECSTRING",
            b"CANCELSUB",
            b"TCA",
            b"TCI",
            b"TML",
            b"GWPSON",
            b"GWPSOF",
        ],
    },
];

fn unclosed(what: &str, offset: usize) -> LexError {
    err(
        ErrorKind::Expression,
        format!("'{what}' without its closing bracket"),
        offset,
        "Sinumerik",
    )
}

/// The end of `( ... )` at `open`, strings and nested parentheses included.
fn parens(line: &[u8], open: usize) -> Result<usize, LexError> {
    balanced(line, open, b'(', b')')
}

pub(crate) fn brackets(line: &[u8], open: usize) -> Result<usize, LexError> {
    balanced(line, open, b'[', b']')
}

fn balanced(line: &[u8], open: usize, left: u8, right: u8) -> Result<usize, LexError> {
    let mut depth = 0usize;
    let mut quoted = false;
    for (i, &b) in line.iter().enumerate().skip(open) {
        if b == b'"' {
            quoted = !quoted;
        } else if quoted {
            // text outside ASCII in a string is read (TG127 says so once per file)
            if b < 0x20 || b == 0x7f {
                return Err(err(
                    ErrorKind::Character,
                    format!("control character 0x{b:02X} in a string"),
                    i,
                    "Sinumerik",
                ));
            }
        } else if !(0x20..0x7f).contains(&b) && b != b'\t' {
            return Err(err(
                ErrorKind::Character,
                format!("byte 0x{b:02X} in an argument list: the control's text is ASCII"),
                i,
                "Sinumerik",
            ));
        } else if b == left {
            depth += 1;
        } else if b == right {
            depth -= 1;
            if depth == 0 {
                return Ok(i + 1);
            }
        } else if b == b';' {
            break;
        }
    }
    Err(unclosed(&(left as char).to_string(), open))
}

/// The end of the Sinumerik expression at `pos`: where its tree ([`expr::sinumerik_prefix`])
/// ends, so that what the checker evaluates and what the block keeps as the value are one
/// reading; a malformed one is an error at its column.
fn siemens_expression(line: &[u8], pos: usize) -> Result<usize, LexError> {
    expr::sinumerik_prefix(line, pos).map(|(_, end)| end)
}

/// The keywords whose condition follows them (`IF R1>5 GOTOF L1`, `WHILE R1<10`, `UNTIL ..`).
const SINUMERIK_CONDITIONS: [&[u8]; 3] = [b"IF", b"WHILE", b"UNTIL"];

/// The jumps that may follow an `IF` condition, each with its target.
const SINUMERIK_JUMPS: [&[u8]; 4] = [b"GOTOF", b"GOTOB", b"GOTO", b"GOTOC"];

/// The end of an `IF`, `WHILE` or `UNTIL` statement whose keyword ends at `keyword_end`: its
/// condition read into the expression tree, then (after `IF`) a jump and its target, and the
/// end of the statement (a `;` comment may follow, or, after a jump's target, the next
/// conditional jump's `IF`).
fn siemens_condition(
    line: &[u8],
    keyword: &[u8],
    keyword_end: usize,
    dialect: &Dialect,
) -> Result<usize, LexError> {
    siemens_condition_jump(line, keyword, keyword_end, dialect).map(|(end, _)| end)
}

/// [`siemens_condition`], and whether the statement is a conditional jump (`IF .. GOTOF L`).
fn siemens_condition_jump(
    line: &[u8],
    keyword: &[u8],
    keyword_end: usize,
    dialect: &Dialect,
) -> Result<(usize, bool), LexError> {
    let statement_end = rest_end(line, keyword_end, dialect, false);
    let text = &line[..statement_end];
    let mut end = siemens_expression(text, skip_blanks(text, keyword_end))?;
    let next = skip_blanks(text, end);
    let word = ident_end(text, next);
    let jump = text[next..word].to_ascii_uppercase();
    let jumped = keyword == b"IF" && SINUMERIK_JUMPS.contains(&jump.as_slice());
    if jumped {
        let target = skip_blanks(text, word);
        end = ident_end(text, target);
        if end == target {
            return Err(err(
                ErrorKind::Value,
                format!(
                    "{} must be followed by a label or block number",
                    String::from_utf8_lossy(&jump)
                ),
                target,
                "Sinumerik",
            ));
        }
        // another conditional jump in the same block (`IF DP==0 GOTOF _MM0 IF DP==HH2 GOTOF
        // _MM1`, Siemens' own CYCLE81/82/84, HOLES1/HOLES2): the control tests them in turn;
        // the next `IF` is read as a statement of its own, and must be a jump too (an IF
        // that opens an IF ... ENDIF after a jump is not a form the cycles show)
        let next_if = skip_blanks(text, end);
        let next_end = ident_end(text, next_if);
        if text[next_if..next_end].eq_ignore_ascii_case(b"IF") {
            let (_, also_jumps) = siemens_condition_jump(line, b"IF", next_end, dialect)?;
            if !also_jumps {
                return Err(err(
                    ErrorKind::Expression,
                    format!(
                        "after {}'s destination an IF must be another conditional jump \
                         (IF .. GOTOF/GOTOB/GOTO/GOTOC)",
                        String::from_utf8_lossy(&jump)
                    ),
                    next_if,
                    "Sinumerik",
                ));
            }
            return Ok((end, true));
        }
    }
    let after = skip_blanks(text, end);
    if after < statement_end {
        let what = if jumped {
            format!(
                "after {}'s destination expected another conditional jump (IF) or the end of \
                 the block",
                String::from_utf8_lossy(&jump)
            )
        } else if keyword == b"IF" {
            "after the IF condition expected an operator, GOTOF/GOTOB/GOTO/GOTOC or the end \
             of the block"
                .to_string()
        } else {
            format!(
                "after the {} condition expected an operator or the end of the block",
                String::from_utf8_lossy(keyword)
            )
        };
        let (c, _) = crate::text::Char::at(text, after);
        return Err(err(
            ErrorKind::Expression,
            format!("{what}, found {}", c.repr()),
            after,
            "Sinumerik",
        ));
    }
    Ok((end, jumped))
}

// -- Heidenhain TNC, ISO mode -------------------------------------------------------------------

/// `Q1 =`, `QL12 =`, `QR3 =`, `QS4 =` at `pos`: the offset after the `=`.
fn formula(line: &[u8], pos: usize) -> Option<usize> {
    let mut p = pos + 1;
    if matches!(line.get(p), Some(b'L' | b'R' | b'S')) {
        p += 1;
    }
    let digits = digits_end(line, p);
    if digits == p {
        return None;
    }
    let eq = skip_blanks(line, digits);
    (line.get(eq) == Some(&b'=')).then_some(eq + 1)
}

/// The end of a formula: before the `;` comment (outside a QS string's quotes) and the block's
/// closing `*`, blanks left out. A formula continued on the next line (a cycle parameter such
/// as `Q200=2 ;SAFETY CLEARANCE`) has no `*` of its own.
fn formula_end(line: &[u8], pos: usize, dialect: &Dialect) -> usize {
    let mut end = line.len();
    let mut quoted = false;
    for (i, &b) in line.iter().enumerate().skip(pos) {
        match b {
            b'"' => quoted = !quoted,
            b';' if !quoted && dialect.semicolon => {
                end = i;
                break;
            }
            _ => {}
        }
    }
    while end > pos && blank(line[end - 1]) {
        end -= 1;
    }
    if end > pos && line[end - 1] == b'*' {
        end -= 1;
        while end > pos && blank(line[end - 1]) {
            end -= 1;
        }
    }
    end
}

/// The string functions a numeric formula may call (`QL1 = STRLEN ( SRC_QS10 )`): their
/// arguments are strings, so such a formula stays text.
const STRING_FUNCTIONS: [&[u8]; 4] = [b"STRNUM", b"STRLEN", b"INSTR", b"STRCOMP"];

/// Where the right-hand side of the formula `Q1 = ...` in `text` (from `pos`) starts, or None
/// for one that stays text: a QS string's, or a string function's.
pub fn formula_right_hand_side(text: &[u8], pos: usize) -> Option<usize> {
    let rhs = formula(text, pos)?;
    if text.get(pos + 1) == Some(&b'S') {
        return None;
    }
    let p = skip_blanks(text, rhs);
    let word = &text[p..letters_end(text, p, false)];
    if STRING_FUNCTIONS.contains(&word) {
        return None;
    }
    // a cycle's feed given by a word (`Q253=FMAX`, `Q206=FAUTO`) or its default (`PREDEF`)
    let alone = skip_blanks(text, p + word.len()) == text.len();
    (!(alone && SYMBOLIC_VALUES.contains(&word))).then_some(rhs)
}

/// Words a cycle parameter may hold instead of a number on newer TNCs (a feed at rapid
/// traverse or automatic, a cycle's default): not in the manuals at hand (docs/dialects.md), so
/// kept as text, without a value, rather than refused.
const SYMBOLIC_VALUES: [&[u8]; 3] = [b"FMAX", b"FAUTO", b"PREDEF"];

/// The checker's key of a HEIDENHAIN parameter `Q12`, `QL012`, `QR3` (leading zeros left
/// out, as `#0101` is `#101`), or None for text that is none.
pub fn q_parameter(text: &[u8]) -> Option<Vec<u8>> {
    let (kind, digits) = match text {
        [b'Q', kind @ (b'L' | b'R'), digits @ ..] => (&[b'Q', *kind][..], digits),
        [b'Q', digits @ ..] => (&b"Q"[..], digits),
        _ => return None,
    };
    if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let start = digits
        .iter()
        .position(|&d| d != b'0')
        .unwrap_or(digits.len() - 1);
    Some([kind, &digits[start..]].concat())
}

/// `+Q12`, `-QL12` or `QR12` at `pos` (the value of a word given by a Q parameter): its end.
fn parameter_value(line: &[u8], pos: usize) -> Option<usize> {
    let mut p = pos;
    if matches!(line.get(p), Some(b'+' | b'-')) {
        p += 1;
    }
    if line.get(p) != Some(&b'Q') {
        return None;
    }
    let kind = usize::from(matches!(line.get(p + 1), Some(b'L' | b'R')));
    let digits = digits_end(line, p + 1 + kind);
    (digits > p + 1 + kind).then_some(digits)
}

fn heidenhain<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let b = line[pos];
    match b {
        // N99999999 %NAME G71: the end of the program, which names it again
        b'%' => Ok(statement(
            pos,
            rest_end(line, pos, dialect, false),
            Kind::Name,
        )),
        // D00 Q1 P01 +5: a Q parameter function (D09 to D12 jump)
        b'D' if line.get(pos + 1).is_some_and(u8::is_ascii_digit) => {
            let digits = digits_end(line, pos + 1);
            let function: u32 = std::str::from_utf8(&line[pos + 1..digits])
                .ok()
                .and_then(|d| d.parse().ok())
                .unwrap_or(0);
            let end = rest_end(line, pos, dialect, false);
            let kind = if (9..=12).contains(&function) {
                Kind::Flow
            } else {
                Kind::Assignment
            };
            Ok(statement(pos, end, kind))
        }
        // Q1 = 5 * (Q2 + 3) *: a formula (also QL, QR local and kept, QS strings); its `*`
        // multiply and its `( )` group, so it runs to the last `*` of the line. Its right-hand
        // side is read into the expression tree (a malformed one is a located error), except
        // a string's and a string function's (STRLEN ...), which stay text. A cycle's
        // parameters may share a line (`N54 G221 Q225=+15 Q226=+15 ... *`): each is a formula.
        b'Q' if formula(line, pos).is_some() => {
            let mut end = formula_end(line, pos, dialect);
            if let Some(rhs) = formula_right_hand_side(&line[..end], pos) {
                let (_, stop) = expr::formula_prefix(&line[..end], rhs)?;
                let next = skip_blanks(line, stop);
                if next < end {
                    if formula(line, next).is_none() {
                        expr::formula_tree(&line[..end], rhs)?; // the error, located
                    }
                    end = stop;
                }
            }
            Ok(statement(pos, end, Kind::Assignment))
        }
        // L1,0: call label 1
        b'L' if digits_end(line, pos + 1) > pos + 1 => {
            let digits = digits_end(line, pos + 1);
            if digits > pos + 1 && line.get(digits) == Some(&b',') {
                let end = digits_end(line, digits + 1);
                return Ok(statement(pos, end, Kind::Call));
            }
            Ok(None)
        }
        // G83 P01 +2 P02 -20 ...: the parameters of an older cycle's definition, each a P
        // number and a signed value (as in the D functions)
        b'P' if {
            let digits = digits_end(line, pos + 1);
            let value = skip_blanks(line, digits);
            digits > pos + 1 && value > digits && matches!(line.get(value), Some(b'+' | b'-'))
        } =>
        {
            Ok(statement(
                pos,
                rest_end(line, pos, dialect, false),
                Kind::Assignment,
            ))
        }
        // X+Q1: a coordinate given by a Q parameter
        _ if letter(b, false) => match parameter_value(line, pos + 1) {
            Some(end) => Ok(Some(word(line, pos, end, words))),
            None if line.get(pos + 1).is_some_and(|c| c.is_ascii_uppercase()) => {
                // a cycle's name after its G code (G200 BOHREN), or a word of the control's own
                Ok(statement(pos, ident_end(line, pos), Kind::Command))
            }
            None => Ok(None),
        },
        _ => Ok(None),
    }
}

/// A Custom Macro B conditional statement, `IF [..] THEN ...` at the start of a statement, in
/// any case: what follows its THEN (FANUC "Custom macro", conditional execution: the macro
/// statement after THEN runs where the condition holds; no jump). None for any other
/// statement, and for the grinder's `IF [..] #712=#609` written without THEN.
pub fn conditional_body(text: &[u8]) -> Option<&[u8]> {
    // Python's `\s` in ASCII: the blanks, VT, and the separators FS GS RS US
    let space = |c: u8| c.is_ascii_whitespace() || c == 0x0b || (0x1c..=0x1f).contains(&c);
    let skip = |t: &[u8], mut i: usize| {
        while t.get(i).is_some_and(|&c| space(c)) {
            i += 1;
        }
        i
    };
    let i = skip(text, 0);
    if !text
        .get(i..i + 2)
        .is_some_and(|w| w.eq_ignore_ascii_case(b"IF"))
    {
        return None;
    }
    let i = skip(text, i + 2);
    if text.get(i) != Some(&b'[') {
        return None;
    }
    (i + 1..text.len())
        .filter(|&j| text[j] == b']')
        .find_map(|j| {
            let k = skip(text, j + 1);
            let then = text
                .get(k..k + 4)
                .is_some_and(|w| w.eq_ignore_ascii_case(b"THEN"))
                // a word character after THEN is not its end (a byte of UTF-8 may be one)
                && text
                    .get(k + 4)
                    .is_none_or(|&c| !(c.is_ascii_alphanumeric() || c == b'_' || c >= 0x80));
            then.then(|| &text[k + 4..])
        })
}

/// The variable a conditional assignment sets, `#106` of `IF [..] THEN #106 = 1` (its text
/// before the `=`, blanks dropped): a plain `#n`, or None where the statement after THEN is
/// no assignment to a numbered variable (`#[#1] = 1`, a named or a system form).
pub fn conditional_assignment(text: &[u8]) -> Option<Vec<u8>> {
    let body = conditional_body(text)?;
    let eq = body.iter().position(|&c| c == b'=')?;
    let target: Vec<u8> = body[..eq].iter().copied().filter(|&c| !blank(c)).collect();
    let digits = target.strip_prefix(b"#")?;
    (!digits.is_empty() && digits.iter().all(u8::is_ascii_digit)).then_some(target)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `is_parameter_name` by its table against the byte-by-byte reading it replaced, over
    /// every name of up to 4 bytes from the bytes that decide it (blanks, `<`, letters of both
    /// cases, digits, leading zeros) and each byte's classes against [`blank`].
    #[test]
    fn a_parameter_name_is_judged_by_its_bytes_classes_as_before() {
        fn before(raw: &[u8]) -> bool {
            let (mut named, mut capital, mut small) = (false, false, false);
            for &c in raw {
                if blank(c) {
                    return false;
                }
                named |= c == b'<';
                capital |= c.is_ascii_uppercase();
                small |= c.is_ascii_lowercase();
            }
            if named {
                !capital
            } else {
                !small && leading_zeros(raw) == 0
            }
        }
        for c in 0..=255u8 {
            assert_eq!(NAME_BYTES[usize::from(c)] & BLANK != 0, blank(c), "{c}");
        }
        let bytes = b" \t\r\x00\x7f<>#_aZR07";
        let mut names: Vec<Vec<u8>> = vec![Vec::new()];
        for _ in 0..4 {
            let longer: Vec<Vec<u8>> = names
                .iter()
                .filter(|n| n.len() == names.last().map_or(0, Vec::len))
                .flat_map(|n| {
                    bytes.iter().map(move |&b| {
                        let mut m = n.clone();
                        m.push(b);
                        m
                    })
                })
                .collect();
            names.extend(longer);
        }
        assert!(names.len() > 20_000);
        for name in &names {
            assert_eq!(is_parameter_name(name), before(name), "{name:?}");
        }
        for name in [
            &b"#<yscale>"[..],
            b"#<_Depth>",
            b"#1",
            b"#01",
            b"R10",
            b"r1",
            b"#<a b>",
        ] {
            assert_eq!(is_parameter_name(name), before(name), "{name:?}");
        }
    }

    use crate::tokenizer::tokenize;

    #[test]
    fn a_name_upper_cased_on_the_stack_is_the_name_upper_cased() {
        // every length around the stack buffer's, mixed case, digits, '_' and bytes past ASCII
        let pattern = b"aB_c9$\xe4Zz";
        for len in 0..70 {
            let text: Vec<u8> = pattern.iter().cycle().take(len).copied().collect();
            assert_eq!(
                Upper::of(&text).as_slice(),
                text.to_ascii_uppercase().as_slice()
            );
        }
        // an instruction's name looked up by its letters in either case, as the list holds it
        for name in [&b"trafoof"[..], b"TraOri", b"RET", b"NOSUCHNAME"] {
            assert_eq!(
                sinumerik_instruction(&Upper::of(name)).map(|g| g as *const Instructions),
                sinumerik_instruction(&name.to_ascii_uppercase()).map(|g| g as *const Instructions)
            );
        }
        assert!(sinumerik_instruction(&Upper::of(b"trafoof")).is_some());
        assert!(sinumerik_instruction(b"").is_none());
    }

    #[test]
    fn an_o_label_is_a_number_or_a_name_in_lower_case() {
        let label = |t: &str| String::from_utf8(o_label(t.as_bytes())).unwrap();
        assert_eq!(label("o0100 sub"), "o100");
        assert_eq!(label("O 0 1 0 0 call [1]"), "o100");
        assert_eq!(label("o100 endsub"), "o100");
        assert_eq!(label("o000 if [1]"), "o0");
        assert_eq!(label("O <Name> call"), "o<name>");
        assert_eq!(label("o<name>sub"), "o<name>");
        assert_eq!(label(""), "");
    }

    fn dialect(family: Family) -> Dialect {
        Dialect {
            family,
            lowercase: matches!(family, Family::LinuxCnc | Family::Sinumerik),
            hash: matches!(family, Family::MacroB | Family::LinuxCnc),
            // (as the built-in profiles' characters: sinumerik-840d's and the OSP profiles'
            // `[ ]`)
            brackets: matches!(
                family,
                Family::MacroB | Family::LinuxCnc | Family::Sinumerik | Family::Okuma
            ),
            semicolon: !matches!(family, Family::MacroB),
            star: true,
            expressions: true,
            ngc: false,
        }
    }

    type Reading = (Vec<String>, Vec<(String, Kind)>);

    /// The words and the statements (text, kind) of one block.
    fn read(text: &str, family: Family) -> Result<Reading, String> {
        let line: &'static [u8] = Box::leak(text.as_bytes().to_vec().into_boxed_slice());
        let mut words = Vec::new();
        let extras = tokenize(line, &dialect(family), &mut words)
            .map_err(|e| format!("{}@{}", e.message, e.offset))?;
        let words = words
            .iter()
            .map(|w| String::from_utf8_lossy(&w.text).into_owned())
            .collect();
        let statements = extras
            .map(|e| e.statements)
            .unwrap_or_default()
            .iter()
            .map(|s| (text[s.offset..s.end].to_string(), s.kind))
            .collect();
        Ok((words, statements))
    }

    fn statements(text: &str, family: Family) -> Vec<(String, Kind)> {
        read(text, family).expect("a readable block").1
    }

    fn words(text: &str, family: Family) -> Vec<String> {
        read(text, family).expect("a readable block").0
    }

    /// The error of reading one block: its message and byte offset.
    fn refused(text: &str, family: Family) -> (String, usize) {
        let line: &'static [u8] = Box::leak(text.as_bytes().to_vec().into_boxed_slice());
        let mut words = Vec::new();
        let e = tokenize(line, &dialect(family), &mut words).expect_err("an unreadable block");
        (e.message, e.offset)
    }

    #[test]
    fn a_fanuc_program_name_in_angle_brackets() {
        let m = Family::MacroB;
        // B-64014EN/03, 2.5: an O number or a file name of up to 32 characters in < >
        assert_eq!(
            statements("<SVG_TEST>", m),
            [("<SVG_TEST>".into(), Kind::Name)]
        );
        assert_eq!(
            read("<101>M60", m).unwrap(),
            (vec!["M60".into()], vec![("<101>".into(), Kind::Name)])
        );
        assert_eq!(
            statements("  <A.b-C_1~{x}>(TITLE)", m),
            [("<A.b-C_1~{x}>".into(), Kind::Name)]
        );
        let longest = format!("<{}>", "N".repeat(PROGRAM_NAME_MAX));
        assert_eq!(statements(&longest, m), [(longest.clone(), Kind::Name)]);
        // too long: refused at its 33rd character
        let (message, at) = refused(&format!("<{}>", "N".repeat(33)), m);
        assert!(message.contains("33 characters") && message.contains("up to 32"));
        assert_eq!(at, 33);
        // characters a file name does not hold, and '%', which ends the record
        let (message, at) = refused("<PART A>", m);
        assert!(
            message.starts_with("a blank in a program name"),
            "{message}"
        );
        assert_eq!(at, 5);
        let (message, at) = refused("<A%B>", m);
        assert!(message.contains("ends the record"), "{message}");
        assert_eq!(at, 2);
        assert_eq!(refused("<A(B)>", m).1, 2);
        // not closed, empty, a '>' alone, a name after the start of the block
        assert!(refused("<OPEN", m).0.contains("not closed"));
        assert!(refused("<>", m).0.starts_with("empty program name"));
        assert_eq!(refused("X1. >", m), (refused("X1. >", m).0, 4));
        let (message, at) = refused("M98 <SUB_A>", m);
        assert!(message.contains("call by name"), "{message}");
        assert_eq!(at, 4);
        // a Haas (the NGC) names its programs O and five digits: '<' stays refused as before
        let haas = Dialect {
            ngc: true,
            ..dialect(m)
        };
        let mut words = Vec::new();
        let e = tokenize(b"<PART_A>", &haas, &mut words).expect_err("refused");
        assert!(e.message.contains("outside ISO 6983-1"), "{}", e.message);
    }

    /// Issue 32, severity by evidence: on a Haas a parameter variable read with a decimal part
    /// (`#30003.078`) is one variable whose value is unknown (the checker says so, TG212), in
    /// an assignment's value, a condition and a word's expression alike; set with one, it stays
    /// refused at its `#`, saying so. A Fanuc's reading is unchanged (refused by name).
    #[test]
    fn a_haas_reads_a_parameter_variable_with_a_decimal_part() {
        let haas = Dialect {
            ngc: true,
            ..dialect(Family::MacroB)
        };
        let tokens = |text: &'static str| {
            let mut words = Vec::new();
            let extras = tokenize(text.as_bytes(), &haas, &mut words).map_err(|e| e.message)?;
            let words: Vec<String> = words
                .iter()
                .map(|w| String::from_utf8_lossy(&w.text).into_owned())
                .collect();
            let statements: Vec<String> = extras
                .map(|e| e.statements)
                .unwrap_or_default()
                .iter()
                .map(|s| text[s.offset..s.end].to_string())
                .collect();
            Ok::<_, String>((words, statements))
        };
        assert_eq!(
            tokens("#10100=#30003.078").unwrap().0,
            ["#10100=#30003.078"]
        );
        assert_eq!(
            tokens("IF [ #30057.21 ] GOTO22").unwrap().1,
            ["IF [ #30057.21 ] GOTO22"]
        );
        assert_eq!(
            tokens("M79 G31 Z [ - [ [ #30003.036 - 12.7 ] * #179 ] - #31 ] F [ 2032. * #179 ]")
                .unwrap()
                .0,
            [
                "M79",
                "G31",
                "Z[-[[#30003.036-12.7]*#179]-#31]",
                "F[2032.*#179]"
            ]
        );
        let e = tokens("#30003.078 = 5").unwrap_err();
        assert!(
            e.starts_with("variable #30003.078 has a decimal part: a Haas NGC parameter")
                && e.contains("set here"),
            "{e}"
        );
        // a point with no digit after it is no such variable: refused as before
        assert!(tokens("#10100=#30003.").is_err());
        // the tree reads the variable whole, its value no constant
        let tree = crate::expr::tree(b"[#30003.036 - 12.7]").unwrap();
        let mut read = Vec::new();
        crate::expr::parameters(&tree, &mut read);
        assert_eq!(read, [(1, 11)]);
    }

    #[test]
    fn macro_b_control_flow() {
        let m = Family::MacroB;
        assert_eq!(
            read("N40 IF [ #5405 GE 6000 ] THEN #3000= 15 ( TOOL LIFE )", m).unwrap(),
            (
                vec!["N40".to_string()],
                vec![("IF [ #5405 GE 6000 ] THEN #3000= 15".into(), Kind::Flow)]
            )
        );
        assert_eq!(
            statements("IF[#118EQ#116]AND[#119EQ#117]GOTO10(if 2-pt)", m),
            [("IF[#118EQ#116]AND[#119EQ#117]GOTO10".into(), Kind::Flow)]
        );
        assert_eq!(
            statements("WHILE [#1 LT 10] DO1", m),
            [("WHILE [#1 LT 10] DO1".into(), Kind::Flow)]
        );
        assert_eq!(statements("END1", m), [("END1".into(), Kind::Flow)]);
        // a blank between DO or END and its number is skipped (FANUC's sample writes `DO 1`)
        for text in ["WHILE [#1 LT 10] DO 1", "WHILE[#1LT10]DO  2"] {
            assert_eq!(statements(text, m), [(text.into(), Kind::Flow)]);
        }
        for text in ["END 1", "END3", "DO 2"] {
            assert_eq!(statements(text, m), [(text.into(), Kind::Flow)]);
        }
        assert_eq!(statements("GOTO #10", m), [("GOTO #10".into(), Kind::Flow)]);
        assert_eq!(
            statements("O7997A(NAME)", m),
            [("O7997A".into(), Kind::Name)]
        );
        // the corner words of chamfering and corner R and of direct drawing dimensions
        assert_eq!(
            read("G01 X50.,C2.", m).unwrap(),
            (
                vec!["G01".into(), "X50.".into()],
                vec![(",C2.".into(), Kind::Command)]
            )
        );
        assert_eq!(
            statements("G01 Z-20. ,R#101 ,A-30.", m),
            [
                (",R#101".into(), Kind::Command),
                (",A-30.".into(), Kind::Command)
            ]
        );
        assert!(read("G01 X50. ,C", m).is_err());
        // the logical operations without brackets, as the Custom Macro B manuals list them
        assert_eq!(words("#157=#157XOR2.0", m), ["#157=#157XOR2.0"]);
        assert_eq!(words("#1=#2 MOD 3", m), ["#1=#2MOD3"]);
        assert_eq!(
            statements("&F=/USER/PATH1/ ", m),
            [("&F=/USER/PATH1/".into(), Kind::Name)]
        );
        assert_eq!(
            statements("N230IF[#609GT0]#712=#609", m).as_slice(),
            [("IF[#609GT0]#712=#609".into(), Kind::Flow)]
        );
        assert_eq!(
            statements("DPRNT[X#5041[44]]", m),
            [("DPRNT[X#5041[44]]".into(), Kind::Message)]
        );
        // words of Macro B: expressions without brackets, a sign before an operand, #[..]
        assert_eq!(
            words("G0X#114-#136Y#115 M#501", m),
            ["G0", "X#114-#136", "Y#115", "M#501"]
        );
        assert_eq!(words("X-#1 #[#2+1]=5", m), ["X-#1", "#[#2+1]=5"]);
        assert_eq!(
            words("O1234 N10 G01 X1.", m),
            ["O1234", "N10", "G01", "X1."]
        );
    }

    #[test]
    fn macro_b_errors_are_located() {
        let m = Family::MacroB;
        assert_eq!(
            read("IF #1 GT 2 GOTO 5", m).unwrap_err(),
            "IF must be followed by a condition in brackets [ ]@3"
        );
        assert!(read("IF [#1 GT 2] X5", m)
            .unwrap_err()
            .starts_with("IF [condition] must be followed by GOTO n or THEN@13"));
        assert!(read("WHILE [#1 LT 2] X1", m).unwrap_err().contains("DOm"));
        assert!(read("GOTO", m).unwrap_err().contains("block number"));
        // not a statement: left to the word reader, which says what is wrong
        assert!(read("N10 XY1", m).unwrap_err().contains("address X"));
    }

    /// The two classes of issue 32 that no source at hand documents (docs/dialects.md): a
    /// variable number with a decimal part (Renishaw's macros for the Haas NGC) and the first
    /// letters of a macro word (a Fanuc 0i-MD macro's `WH[..]DO1`). Each is refused at its
    /// column with a message naming it; whole numbers and words in full still read.
    #[test]
    fn undocumented_macro_forms_are_refused_by_name() {
        let m = Family::MacroB;
        let decimal = |text: &str, var: &str, at: usize| {
            let e = read(text, m).unwrap_err();
            assert!(
                e.starts_with(&format!("variable {var} has a decimal part"))
                    && e.ends_with(&format!("@{at}")),
                "{text}: {e}"
            );
        };
        decimal("#10100=#30003.078", "#30003.078", 7);
        decimal("IF [ #30057.21 ] GOTO22", "#30057.21", 5);
        decimal(
            "Z [ - [ [ #30003.036 - 12.7 ] * #179 ] - #31 ]",
            "#30003.036",
            10,
        );
        decimal("#30003.078 = 5", "#30003.078", 0);
        decimal("X#1.5", "#1.5", 1);
        // whole numbers, and a number after a variable, read as before
        assert_eq!(read("#10100=#30003", m).unwrap().0, ["#10100=#30003"]);
        assert_eq!(read("#1=#2+.5", m).unwrap().0, ["#1=#2+.5"]);
        assert_eq!(
            statements("IF [ #30057 EQ 1.5 ] GOTO22", m),
            [("IF [ #30057 EQ 1.5 ] GOTO22".to_string(), Kind::Flow)]
        );
        // LinuxCNC's reader is its own: not this message
        assert!(!read("#1=#2.5", Family::LinuxCnc)
            .unwrap_err()
            .contains("decimal part"));
        let abbreviation = |text: &str, word: &str, full: &str| {
            let e = read(text, m).unwrap_err();
            assert!(
                e.starts_with(&format!("'{word}' is not read as {full}")) && e.ends_with("@0"),
                "{text}: {e}"
            );
        };
        abbreviation("WH[[#1GE#2]AND[#3GE#7]]DO1", "WH", "WHILE");
        abbreviation("GO10", "GO", "GOTO");
        abbreviation("EN1", "EN", "END");
        abbreviation("DP[X#1]", "DP", "DPRNT");
        abbreviation("GO #5", "GO", "GOTO");
        // GO with no block number after it is no GOTO: the letter O for G0's zero
        for text in ["GO Y0.", "GO X20. Z2.", "GO"] {
            let e = read(text, m).unwrap_err();
            assert!(
                e.starts_with("'GO' is neither G0 nor GOTO") && e.ends_with("@0"),
                "{text}: {e}"
            );
        }
        // GOTO with a blank inside: its block number follows TO, and the message says so
        for (text, word) in [("GO TO 10", "'GO TO'"), ("GO TO#5", "'GO TO'")] {
            let e = read(text, m).unwrap_err();
            assert!(
                e.starts_with(&format!("{word} is not read as GOTO")) && e.ends_with("@0"),
                "{text}: {e}"
            );
        }
        // GO, digits, then an address word: G01 with the letter O, or GOTO abbreviated
        for (text, start) in [
            ("GO1 X1.", "'GO1' is neither G01 nor GOTO 1"),
            ("GO2X5.Y1.R3.", "'GO2' is neither G02 nor GOTO 2"),
            ("GO 1 Z0.", "'GO 1' is neither G01 nor GOTO 1"),
        ] {
            let e = read(text, m).unwrap_err();
            assert!(e.starts_with(start) && e.ends_with("@0"), "{text}: {e}");
        }
        // the block form's closing words: refused at the word, saying why
        for (text, word) in [
            ("ENDIF", "ENDIF"),
            ("ELSE", "ELSE"),
            ("  ENDIF (Q1)", "ENDIF"),
        ] {
            let e = read(text, m).unwrap_err();
            let at = format!("@{}", text.find(word).unwrap());
            assert!(
                e.starts_with(&format!(
                    "'{word}' is not read: an IF [..] THEN over several"
                )) && e.ends_with(&at),
                "{text}: {e}"
            );
        }
        // END1 is still the loop's end, and IF [..] THEN one statement reads
        assert_eq!(statements("END1", m), [("END1".to_string(), Kind::Flow)]);
        assert_eq!(
            statements("IF [#1 GT 0] THEN #2 = 1", m),
            [("IF [#1 GT 0] THEN #2 = 1".to_string(), Kind::Flow)]
        );
        // the words in full read; other letter pairs are left to the word reader
        assert_eq!(
            statements("WHILE[[#1GE#2]AND[#3GE#7]]DO1", m),
            [("WHILE[[#1GE#2]AND[#3GE#7]]DO1".to_string(), Kind::Flow)]
        );
        assert!(read("N10 XY1", m).unwrap_err().starts_with("address X"));
    }

    /// rs274ngc `read_o` reads an o-word's label as a number, a `<name>`, a parameter or a
    /// bracketed expression (`o#1 call`, `o#<sub> call`, `o[#1+1] call [5]`: run by `rs274
    /// -g`); the label is kept as written, blanks out, and the keyword and arguments follow it.
    #[test]
    fn linuxcnc_o_words_with_computed_labels() {
        let l = Family::LinuxCnc;
        for text in [
            "o#1 call",
            "o#<sub> call",
            "o[#1+1] call [5]",
            "O [ #1 ] call",
            "o# 1 call",
        ] {
            assert_eq!(
                statements(text, l),
                [(text.to_string(), Kind::Call)],
                "{text}"
            );
        }
        assert_eq!(o_label(b"O [ #1 + 1 ] call [5]"), b"o[#1+1]");
        assert_eq!(o_label(b"o#<Sub> call"), b"o#<sub>");
        assert_eq!(o_label(b"o#12call"), b"o#12");
        assert_eq!(o_label(b"o[[#1]*2]if[1]"), b"o[[#1]*2]");
        // a number in brackets is that number's label, as rs274 reads its value
        assert_eq!(o_label(b"o[100] endsub"), b"o100");
        assert_eq!(o_label(b"O [ 0100.00 ] call"), b"o100");
        assert_eq!(o_label(b"o[100.5] call"), b"o[100.5]");
        assert_eq!(o_label(b"o[0] call"), b"o0");
        assert_eq!(
            o_keyword(b"o[#1+1]call[5]").as_deref(),
            Some(b"call".as_slice())
        );
        assert_eq!(
            o_keyword(b"o#<s>endsub").as_deref(),
            Some(b"endsub".as_slice())
        );
        assert_eq!(o_label_len(b"o [#1] call [5]"), 6);
        assert_eq!(o_label_len(b"o100 call"), 4);
        assert!(read("o#<s call", l).unwrap_err().contains("closing '>'"));
        assert!(read("o[#1 call", l).is_err());
    }

    /// The rest of what `read_o` reads as a label through `read_integer_value` (interp_read.cc
    /// `read_real_value`): a sign, a point with no fraction, a function of a bracketed value,
    /// a parameter whose number is a value (`o##2`, `o#[#2]`); each run by `rs274 -g`
    /// (tests/test_linuxcnc_o_labels.py). A number is its whole number's label within 0.0001
    /// of it (`read_integer_value`'s tolerance); a fraction is kept as written.
    #[test]
    fn linuxcnc_o_words_with_signs_points_and_functions() {
        let l = Family::LinuxCnc;
        for (text, kind) in [
            ("o+100 sub", Kind::Definition),
            ("o+100 call", Kind::Call),
            ("o100.0 endsub", Kind::Definition),
            ("o-100 call", Kind::Call),
            ("o-[100] call", Kind::Call),
            ("oabs[-100] call", Kind::Call),
            ("O ABS [ -100 ] call [1]", Kind::Call),
            ("o##2 call", Kind::Call),
            ("o#[#2] call", Kind::Call),
            ("o.5 call", Kind::Call),
            ("o#1 endwhile", Kind::Flow),
        ] {
            assert_eq!(statements(text, l), [(text.to_string(), kind)], "{text}");
        }
        assert_eq!(o_label(b"o+100 sub"), b"o100");
        assert_eq!(o_label(b"O 1 0 0 . 0 0 call"), b"o100");
        assert_eq!(o_label(b"o-100 call"), b"o-100");
        assert_eq!(o_label(b"o-[-100] call"), b"o100");
        assert_eq!(o_label(b"o100.00005 call"), b"o100");
        assert_eq!(o_label(b"o99.99995 call"), b"o100");
        assert_eq!(o_label(b"o100.5 call"), b"o100.5");
        assert_eq!(o_label(b"o-0 call"), b"o0");
        // a function of a constant that keeps a whole number whole is its value's label
        // (review 48, F4: `rs274 -g` runs `oabs[-100] sub` ... `o100 endsub`)
        assert_eq!(o_label(b"oABS[-100]call[1]"), b"o100");
        assert_eq!(o_label(b"o[abs[-100]] sub"), b"o100");
        assert_eq!(o_label(b"ofix[100.9] call"), b"o100");
        assert_eq!(o_label(b"o-fup[-100.5] endsub"), b"o100");
        assert_eq!(o_label(b"oround[99.5] call"), b"o100");
        assert_eq!(o_label(b"oround[-99.5] call"), b"o-100");
        assert_eq!(o_label(b"oabs[[-100]] call"), b"o100");
        assert_eq!(o_label(b"oabs[-100.5] call"), b"oabs[-100.5]");
        assert_eq!(o_label(b"osin[90] call"), b"osin[90]");
        assert_eq!(o_label(b"oabs[#1] call"), b"oabs[#1]");
        assert_eq!(o_label(b"o##2 call"), b"o##2");
        assert_eq!(o_label(b"o#[#2]endsub"), b"o#[#2]");
        assert_eq!(o_label_len(b"o abs [-100] call [5]"), 12);
        assert_eq!(o_keyword(b"o+100sub").as_deref(), Some(b"sub".as_slice()));
        assert_eq!(o_keyword(b"o100.0sub").as_deref(), Some(b"sub".as_slice()));
        assert!(computed_label(b"o100.5") && computed_label(b"o##2"));
        assert!(!computed_label(b"o-100") && !computed_label(b"o<a>") && !computed_label(b"o7"));
        // an unknown function is refused where it is read; `o` before a word is no label
        assert!(read("onope[1] call", l)
            .unwrap_err()
            .contains("unknown function"));
        assert_eq!(rs274_integer(2.00009), Some(2));
        assert_eq!(rs274_integer(1.99991), Some(2));
        assert_eq!(rs274_integer(2.5), None);
        assert_eq!(rs274_integer(-2.00009), Some(-2));
    }

    #[test]
    fn linuxcnc_o_words_and_named_parameters() {
        let l = Family::LinuxCnc;
        assert_eq!(
            statements("o100 sub", l),
            [("o100 sub".into(), Kind::Definition)]
        );
        assert_eq!(
            statements("O<probe> call [1.5] [#<depth>] (comment)", l),
            [("O<probe> call [1.5] [#<depth>]".into(), Kind::Call)]
        );
        assert_eq!(
            statements(" o<100> else if [#5422 GE 0]", l),
            [("o<100> else if [#5422 GE 0]".into(), Kind::Flow)]
        );
        assert_eq!(
            words("#<_tool> = [#<a> + # <b>] g1 x#<_tool> @1 ^45 m3 $0", l),
            [
                "#<_tool>=[#<a>+#<b>]",
                "g1",
                "x#<_tool>",
                "@1",
                "^45",
                "m3",
                "$0"
            ]
        );
        assert!(read("O<g20sub> callsub", l)
            .unwrap_err()
            .starts_with("unknown o-word keyword 'callsub'"));
        assert!(read("o100 if", l)
            .unwrap_err()
            .contains("condition in brackets"));
        assert!(read("o<abc call", l).unwrap_err().contains("closing '>'"));
    }

    #[test]
    fn sinumerik_words_and_statements() {
        let s = Family::Sinumerik;
        assert_eq!(
            read("N190 G0 SUPA X=_X_HOME Y=R1+5 D1 ; home", s).unwrap(),
            (
                vec![
                    "N190".to_string(),
                    "G0".into(),
                    "X=_X_HOME".into(),
                    "Y=R1+5".into(),
                    "D1".into()
                ],
                vec![("SUPA".into(), Kind::Command)]
            )
        );
        assert_eq!(
            statements("N30 DEF REAL _X, _Y ;declared", s),
            [("DEF REAL _X, _Y".into(), Kind::Declaration)]
        );
        assert_eq!(
            statements("MSG(\"MILL (FINISH)\") CYCLE832(_tol,1,1)", s),
            [
                ("MSG(\"MILL (FINISH)\")".into(), Kind::Message),
                ("CYCLE832(_tol,1,1)".into(), Kind::Call)
            ]
        );
        assert_eq!(
            read("G2 X10 Y5 CR=5 TURN=0", s).unwrap().1,
            [
                ("CR=5".into(), Kind::Assignment),
                ("TURN=0".into(), Kind::Assignment)
            ]
        );
        assert_eq!(
            words("T=\"SCHAFT_D8\" R11=384.553 L100", s),
            ["T=\"SCHAFT_D8\"", "R11=384.553", "L100"]
        );
        assert_eq!(
            statements("@371 R52 K2 K0", s),
            [("@371 R52 K2 K0".into(), Kind::Command)]
        );
        assert_eq!(
            statements("TRANS X10 Y20", s),
            [("TRANS X10 Y20".into(), Kind::Command)]
        );
        assert_eq!(statements("LOOP1:", s), [("LOOP1:".into(), Kind::Label)]);
        // words written without blanks: a letter and a digit begin no name
        assert_eq!(
            read("N230 g0X-170 Y-5.5Z2", s).unwrap(),
            (
                vec![
                    "N230".to_string(),
                    "g0".into(),
                    "X-170".into(),
                    "Y-5.5".into(),
                    "Z2".into()
                ],
                vec![]
            )
        );
        assert_eq!(words("G1X10Y-5 F100", s), ["G1", "X10", "Y-5", "F100"]);
        assert!(read("MSG(\"open", s)
            .unwrap_err()
            .contains("closing bracket"));
    }

    /// The list of predefined instructions is one the reader can use: each name once, in
    /// upper case (the reader compares the name in upper case), an identifier that begins
    /// with two letters (a letter and a digit begin an address word, `G1X10`), and none the
    /// reader takes before the list (a keyword of [`SINUMERIK_REST`], a condition, a jump or
    /// `CALL`), so that each name is read as the instruction it lists.
    #[test]
    fn the_sinumerik_instruction_list_is_in_the_form_the_reader_needs() {
        let mut seen = std::collections::HashSet::new();
        for group in SINUMERIK_INSTRUCTIONS {
            assert!(!group.names.is_empty());
            for &name in group.names {
                let shown = String::from_utf8_lossy(name);
                assert!(seen.insert(name), "{shown} is listed twice");
                assert!(name[..2].iter().all(u8::is_ascii_uppercase), "{shown}");
                assert_eq!(ident_end(name, 0), name.len(), "{shown}");
                assert_eq!(name.to_ascii_uppercase(), name, "{shown}");
                assert!(
                    !SINUMERIK_REST.contains(&name)
                        && !SINUMERIK_CONDITIONS.contains(&name)
                        && !SINUMERIK_JUMPS.contains(&name)
                        && !matches!(name, b"CALL" | b"PCALL" | b"EXTCALL"),
                    "{shown} is read before the list"
                );
                assert!(sinumerik_instruction(name).is_some_and(|g| std::ptr::eq(g, group)));
                // a procedure whose effect the sources leave unclear is read as a call
                let kind = if group.effect == Effect::Unclear {
                    Kind::Call
                } else {
                    Kind::Command
                };
                assert_eq!(
                    statements(&shown, Family::Sinumerik),
                    [(shown.to_string(), kind)]
                );
                if group.arguments {
                    // MSG("..") is read as the message it shows
                    let kind = if name == b"MSG" { Kind::Message } else { kind };
                    let called = format!("{shown}(1)");
                    assert_eq!(
                        statements(&called, Family::Sinumerik),
                        [(called.clone(), kind)]
                    );
                }
            }
        }
    }

    /// A predefined procedure with its arguments (`TRAORI(1)`: list of operations, type P) is
    /// an instruction; a cycle, a user's subprogram with arguments, or a function of the list
    /// that gives a value (`CTRANS`, type F, read in an expression) written alone is a call.
    #[test]
    fn a_sinumerik_procedure_with_arguments_is_no_call() {
        let s = Family::Sinumerik;
        for procedure in [
            "TRAORI(1)",
            "traori(1,0,0,1)",
            "TRACYL(20.5)",
            "SETMS(2)",
            "SETAL(61000)",
            "LEADON(A,X,1)",
            // RET with the caller's block to return to is a return (Job Planning, "Subprogram
            // technique"), no call
            "RET(\"L1\")",
            "RET(N100,,2)",
        ] {
            assert_eq!(
                statements(procedure, s),
                [(procedure.to_string(), Kind::Command)]
            );
        }
        for call in [
            "CYCLE800(1,\"TC1\",0,57)",
            "MYSUB(1, 2)",
            "CTRANS(X,10)",
            // a procedure whose effect is unclear (NEWCONF applies any machine data)
            "NEWCONF()",
            "EXECSTRING(_BLOCK)",
        ] {
            assert_eq!(statements(call, s), [(call.to_string(), Kind::Call)]);
        }
        // a G command takes no arguments: SOFT is read, and (1) is no argument list of it
        assert_eq!(statements("SOFT", s), [("SOFT".to_string(), Kind::Command)]);
        assert_eq!(
            statements("SOFT(1)", s),
            [("SOFT(1)".to_string(), Kind::Call)]
        );
    }

    #[test]
    fn sinumerik_expressions_and_conditions_are_read_into_the_tree() {
        let s = Family::Sinumerik;
        // R parameters set by an expression, words of an address given by one
        assert_eq!(
            words(
                "N10 R1=R2*SIN(30) R3 = (R1+2)/4 G1 X=R1+5 F=POT(R2) D1 ;c",
                s
            ),
            [
                "N10",
                "R1=R2*SIN(30)",
                "R3=(R1+2)/4",
                "G1",
                "X=R1+5",
                "F=POT(R2)",
                "D1"
            ]
        );
        assert_eq!(
            words("Y=$AA_IM[X]*2 Z=-_Z_HOME", s),
            ["Y=$AA_IM[X]*2", "Z=-_Z_HOME"]
        );
        // conditions: the statement's text as written, up to the comment
        for text in [
            "IF R1>5 GOTOF LABEL1",
            "IF (R1==2) AND (R2<>3) GOTOF N100",
            "IF NOT R10 GOTOB START",
            "IF (R10<50) AND ($AA_IM[X]>=17.5) GOTOF DEST",
            "WHILE R1<10",
            "UNTIL R1 >= 10",
            "IF _A[1] == \"ABC\"",
        ] {
            assert_eq!(
                statements(&format!("N20 {text} ; why"), s),
                [(text.to_string(), Kind::Flow)],
                "{text}"
            );
        }
        // malformed: located at the column where the reading stopped
        assert_eq!(
            read("N30 R1=(R2+3", s).unwrap_err(),
            "'(' without a closing ')' in the expression@12"
        );
        assert_eq!(
            read("N40 X=R1+ ;c", s).unwrap_err(),
            "expected a value in the expression, found ';'@10"
        );
        assert!(read("N50 IF R1=5 GOTOF L1", s)
            .unwrap_err()
            .ends_with("found '='@9"));
        assert!(read("N60 IF R1>5 GOTOF", s)
            .unwrap_err()
            .starts_with("GOTOF must be followed by a label"));
        assert!(read("N70 WHILE R1<10 GOTOF L1", s)
            .unwrap_err()
            .contains("expected an operator or the end of the block, found 'G'@16"));
        assert!(read("N80 IF R1 > AND 2", s)
            .unwrap_err()
            .ends_with("found the operator AND@12"));
        // several conditional jumps in one block (Siemens' CYCLE81: `IF DP==0 GOTOF _MM0 IF
        // DP==HH2 GOTOF _MM1`): each IF one statement; any other word after a jump's
        // destination is still refused
        assert_eq!(
            statements("N90 IF DP==0 GOTOF _MM0 if DP==HH2 gotob N10 ; two", s),
            [
                ("IF DP==0 GOTOF _MM0".to_string(), Kind::Flow),
                ("if DP==HH2 gotob N10".to_string(), Kind::Flow)
            ]
        );
        assert!(read("N91 IF R1==1 GOTOF L1 G0 X5", s)
            .unwrap_err()
            .contains("after GOTOF's destination expected another conditional jump (IF) or the end of the block, found 'G'@22"));
        assert!(read("N92 IF R1==1 GOTOF L1 IF R2==2", s)
            .unwrap_err()
            .ends_with("an IF must be another conditional jump (IF .. GOTOF/GOTOB/GOTO/GOTOC)@22"));
        assert!(read("N94 IF R1==1 GOTOF L1 IF R2==2 GOTOC L2 IF R3 GOTO N10", s).is_ok());
        assert!(read("N93 IF R1==1 GOTOF L1 IFX", s)
            .unwrap_err()
            .ends_with("found 'I'@22"));
        // R0 is a SINUMERIK's first R parameter (machine data 28050)
        assert!(read("R0=1", s).is_ok());
        assert!(read("R0=R1*2", s).is_ok());
        // indirect G code programming, and an oscillation's pair of option sets
        assert_eq!(
            read("G[8]=MER_KORD_SYS", s).unwrap().1,
            [("G[8]=MER_KORD_SYS".into(), Kind::Assignment)]
        );
        assert_eq!(
            read("m[BrojVretena]=3", s).unwrap().1,
            [("m[BrojVretena]=3".into(), Kind::Assignment)]
        );
        assert_eq!(
            read("ID=7 EVERY $A_IN[7]<>0 DO $R1=1", s).unwrap().1,
            [
                ("ID=7".into(), Kind::Assignment),
                ("EVERY $A_IN[7]<>0 DO $R1=1".into(), Kind::Command)
            ]
        );
        assert_eq!(
            read("OSCTRL[Z]=(1+2,16+32+64)", s).unwrap().1,
            [("OSCTRL[Z]=(1+2,16+32+64)".into(), Kind::Assignment)]
        );
    }

    #[test]
    fn sinumerik_extended_addresses_take_the_expression_of_an_address() {
        // Programming Manual Fundamentals, "Extended addresses": a numeric extension, '=' and
        // an arithmetic expression, read as after X= (a GUD array, a user or system variable,
        // round brackets, word operators), in any case and with blanks
        let s = Family::Sinumerik;
        assert_eq!(
            words("N10 X4=20 S1=470 M3=5 H1=2 T2=7 F1=R1*2 I1=(R2+3)/2", s),
            [
                "N10",
                "X4=20",
                "S1=470",
                "M3=5",
                "H1=2",
                "T2=7",
                "F1=R1*2",
                "I1=(R2+3)/2"
            ]
        );
        assert_eq!(
            words(
                "M1=3 S1=INI[53] s2 = _speed * 2 S3=$AA_IM[X] x1=(100+20)*2",
                s
            ),
            [
                "M1=3",
                "S1=INI[53]",
                "s2=_speed*2",
                "S3=$AA_IM[X]",
                "x1=(100+20)*2"
            ]
        );
        assert_eq!(words("S1=10 DIV 3 G1", s), ["S1=10DIV3", "G1"]);
        // an extension given by a variable in square brackets (M, H, S, SPOS, SPOSA; T in the
        // manual's example): an assignment statement, its text kept
        for text in [
            "S[SPINU]=470",
            "M[SPINU]=3",
            "T[SPINU]=7",
            "H[_N+1]=2",
            "SPOS[2]=90",
        ] {
            assert_eq!(
                statements(&format!("N20 {text} ; c"), s),
                [(text.to_string(), Kind::Assignment)],
                "{text}"
            );
        }
        // nothing after '=', an unclosed bracket: located where the reading stopped
        assert_eq!(
            read("N30 S1=", s).unwrap_err(),
            "expression ends without an operand@7"
        );
        assert_eq!(
            read("N40 S1=INI[53 M1=3", s).unwrap_err(),
            "'[' without a closing ']' in the expression@14"
        );
        assert_eq!(
            read("N50 M1=(3", s).unwrap_err(),
            "'(' without a closing ')' in the expression@9"
        );
        assert!(read("N60 M[SPINU=3", s)
            .unwrap_err()
            .ends_with("without its closing bracket@5"));
        // the extension's range (one or two digits, positive) is the checker's, TG206
        assert_eq!(words("X0=5 S100=1", s), ["X0=5", "S100=1"]);
        // only the manual's letters take an extension: D1= L1= P1= are the ISO reader's (its
        // parameter expressions, no round brackets), as before extended addresses were read
        assert_eq!(
            words("N20 D1=R1 L1=R2 p1=R3", s),
            ["N20", "D1=R1", "L1=R2", "p1=R3"]
        );
        assert!(read("N20 D1=(R1+2)", s).is_err());
    }

    #[test]
    fn heidenhain_iso_blocks() {
        let h = Family::Heidenhain;
        assert_eq!(
            words("N10 G00 G40 G90 Z+100 *", h),
            ["N10", "G00", "G40", "G90", "Z+100"]
        );
        assert_eq!(
            statements("N99999999 %PROG1 G71 *", h),
            [("%PROG1 G71".into(), Kind::Name)]
        );
        assert_eq!(
            statements("N20 D00 Q1 P01 +5 *", h),
            [("D00 Q1 P01 +5".into(), Kind::Assignment)]
        );
        assert_eq!(
            statements("N30 D11 P01 +Q1 P02 +0 P03 5 *", h)[0].1,
            Kind::Flow
        );
        assert_eq!(statements("N40 L1,0 *", h), [("L1,0".into(), Kind::Call)]);
        assert_eq!(
            statements("N50 G200 BOHREN", h),
            [("BOHREN".into(), Kind::Command)]
        );
        assert!(read("N60 X1 * Y2", h).is_err());
        // formulas: their '*' multiplies and their '( )' group, to the block's closing '*'
        assert_eq!(
            statements("N70 Q3 = ( Q1 + 2 ) * SIN ( 30 ) ; ANGLE *", h),
            [("Q3 = ( Q1 + 2 ) * SIN ( 30 )".into(), Kind::Assignment)]
        );
        assert_eq!(
            statements("N71 QS5 = \"A;B\" *", h),
            [("QS5 = \"A;B\"".into(), Kind::Assignment)]
        );
        // a cycle parameter on its own line: no '*' of its own
        assert_eq!(
            statements("  Q200=2 ;SAFETY CLEARANCE", h),
            [("Q200=2".into(), Kind::Assignment)]
        );
        // a coordinate given by a Q parameter is a word
        assert_eq!(
            words("N80 G01 X+Q1 Y-Q22 ZQ3 F200 *", h),
            ["N80", "G01", "X+Q1", "Y-Q22", "ZQ3", "F200"]
        );
        assert!(statements("N80 G01 X+Q1 *", h).is_empty());
        // an older cycle's parameters: a P number and a signed value each
        assert_eq!(
            statements("N90 G83 P01 +2 P02 -20 P03 -5 *", h),
            [("P01 +2 P02 -20 P03 -5".into(), Kind::Assignment)]
        );
        assert_eq!(words("N91 G04 P2 *", h), ["N91", "G04", "P2"]);
    }

    #[test]
    fn heidenhain_formulas_are_read_into_the_expression_tree() {
        let h = Family::Heidenhain;
        assert_eq!(
            statements("N10 QL12 = SQ 10 - 3^3 + 400 % 360 * PI *", h),
            [(
                "QL12 = SQ 10 - 3^3 + 400 % 360 * PI".into(),
                Kind::Assignment
            )]
        );
        // a malformed right-hand side is an error at its column, not text carried through
        assert_eq!(
            read("N20 Q3 = ( Q1 + 2 * SIN 30 *", h).unwrap_err(),
            "'(' without a closing ')' in the formula@26"
        );
        let unknown = read("N30 Q1 = Q2 + FOO 3 *", h).unwrap_err();
        assert!(unknown.starts_with("unknown function FOO in a formula"));
        assert!(unknown.ends_with("@14"));
        assert!(read("  Q200= ;SAFETY CLEARANCE", h)
            .unwrap_err()
            .contains("ends without an operand"));
        // strings and string functions stay text
        assert_eq!(
            statements("N40 QS1 = \"A ( B\" *", h),
            [("QS1 = \"A ( B\"".into(), Kind::Assignment)]
        );
        assert_eq!(
            statements("N50 QL1 = STRLEN ( SRC_QS10 ) *", h),
            [("QL1 = STRLEN ( SRC_QS10 )".into(), Kind::Assignment)]
        );
        // a coordinate given by a local or kept parameter is a word
        assert_eq!(
            words("N60 G01 X+QL1 Y-QR22 *", h),
            ["N60", "G01", "X+QL1", "Y-QR22"]
        );
        // a cycle's parameters on one line: one formula each
        assert_eq!(
            statements("N54 G221 Q225=+15 Q226=+15 Q237=+10 *", h),
            [
                ("Q225=+15".into(), Kind::Assignment),
                ("Q226=+15".into(), Kind::Assignment),
                ("Q237=+10".into(), Kind::Assignment)
            ]
        );
        assert!(read("N55 Q1 = 5 X+10 *", h)
            .unwrap_err()
            .ends_with("found 'X'@11"));
        assert_eq!(
            statements("  Q253=FMAX ;F PRE-POSITIONING", h),
            [("Q253=FMAX".into(), Kind::Assignment)]
        );
        assert!(read("N56 Q1 = FMAX + 1 *", h).is_err());
        assert_eq!(q_parameter(b"QL012"), Some(b"QL12".to_vec()));
        assert_eq!(q_parameter(b"Q0"), Some(b"Q0".to_vec()));
        assert_eq!(q_parameter(b"QS1"), None);
    }

    #[test]
    fn iso_reads_none_of_it() {
        let iso = Dialect {
            family: Family::Iso,
            ..dialect(Family::MacroB)
        };
        let mut words = Vec::new();
        assert!(tokenize(b"IF [#1 GT 2] GOTO 5", &iso, &mut words).is_err());
        assert!(tokenize(b"o100 sub", &iso, &mut words).is_err());
    }

    #[test]
    fn linuxcnc_parameter_names_and_definitions() {
        for (raw, name, sub) in [
            ("#<ZS>", "#<zs>", "#<zs>@7"),
            ("# < Z s >", "#<zs>", "#<zs>@7"),
            ("#<_Tool>", "#<_tool>", "#<_tool>"),
            ("# 1", "#1", "#1@7"),
            ("#30", "#30", "#30@7"),
            ("#31", "#31", "#31"),
            ("R1", "R1", "R1"),
            ("r1", "R1", "R1"),
            ("_z_Home", "_Z_HOME", "_Z_HOME"),
            ("R01", "R1", "R1"),
            ("r007", "R7", "R7"),
            ("R0", "R0", "R0"),
            ("R00", "R0", "R0"),
            ("R10", "R10", "R10"),
            ("#007", "#7", "#7@7"),
            ("# 0 1", "#1", "#1@7"),
            ("_R01", "_R01", "_R01"),
        ] {
            assert_eq!(parameter_name(raw.as_bytes()), name);
            assert_eq!(is_parameter_name(raw.as_bytes()), raw == name, "{raw}");
            assert_eq!(scoped_name(name.into(), Some(7)), sub);
            assert_eq!(scoped_name(name.into(), None), name);
        }
        assert_eq!(named_target(b"#<zs>=1.0"), Some(5));
        assert_eq!(named_target(b"#<zs>"), None);
        assert_eq!(named_target(b"#1=2"), None);
        for (statement, definition) in [
            ("o<s> sub", Some(true)),
            ("O100SUB", Some(true)),
            ("o<s> end sub", Some(false)),
            ("o<s> endsub [#<a>]", Some(false)),
            ("o<s> call [1]", None),
            ("o<sub> if [1]", None),
        ] {
            assert_eq!(
                linuxcnc_definition(statement.as_bytes()),
                definition,
                "{statement}"
            );
        }
    }

    #[test]
    fn conditional_bodies_and_their_assignments() {
        assert_eq!(
            conditional_body(b"IF [#1 GT 2] THEN #3 = 1"),
            Some(&b" #3 = 1"[..])
        );
        assert_eq!(conditional_body(b"  if[#1]then#3=1"), Some(&b"#3=1"[..]));
        assert_eq!(conditional_body(b"IF [#1 GT 2] THENX"), None);
        assert_eq!(conditional_body(b"IF #1 THEN #2=1"), None);
        assert_eq!(conditional_body(b"WHILE [#1 LT 3] DO1"), None);
        assert_eq!(conditional_body(b"IF[#609GT0]#712=#609"), None);
        assert_eq!(
            conditional_assignment(b"IF [#1 GT 2] THEN #3000 = 1").as_deref(),
            Some(&b"#3000"[..])
        );
        assert_eq!(conditional_assignment(b"IF [#1 GT 2] THEN #[#2] = 1"), None);
        assert_eq!(conditional_assignment(b"IF [#1 GT 2] THEN # = 1"), None);
        assert_eq!(conditional_assignment(b"IF [#1 GT 2] GOTO 10"), None);
    }
}
