//! Parameter expressions of ISO 6983-1 6.4.7: where one ends, and whether it is well formed.
//!
//! The standard shows `R11 = 22.2`, `R29 = R9 + R15` and `X2 = 105 + R9` and leaves the
//! operations to the control's manual. The grammar read here is the one of `formats/expr.py`
//! (its lark grammar is the reference the property tests hold this scanner to):
//!
//! ```text
//! sum     := product (("+" | "-") product)*
//! product := unary (("/" | "*") unary)*         "*" where the dialect allows it
//! unary   := ("+" | "-")* atom
//! atom    := NUMBER | PARAM | "[" sum "]" | FUNCTION "[" sum "]"   brackets where allowed
//! PARAM   := [PQR][0-9]+ | #[0-9]+                                 "#" where allowed
//! ```
//!
//! Blanks (space, tab, CR, NUL, DEL) may stand between any two tokens. Only brackets nest, and
//! their depth is limited, so no input can exhaust the stack.
//!
//! The macro dialects (Fanuc/Haas Macro B, LinuxCNC; [`Syntax::macros`]) read more inside
//! brackets: the operators `EQ NE GT GE LT LE AND OR XOR MOD` and `**`, the functions of
//! [`MACRO_FUNCTIONS`] (with `,` between arguments), `#[expr]` (a parameter by number) and, for
//! LinuxCNC, `#<name>` parameters and lower case.
//!
//! HEIDENHAIN's Q-parameter formulas (`Q3 = ( Q1 + 2 ) * SIN 30 *`) have a grammar of their own,
//! read by [`formula_tree`] and evaluated by [`formula_value`] where the value is constant.

use crate::decimal::Dec;
pub use crate::lex::Syntax;
use crate::lex::{blank, ErrorKind, Family, LexError};

/// The functions an expression may call, as `formats/expr.py` evaluates them.
pub const FUNCTIONS: [&str; 6] = ["ABS", "ATAN", "COS", "SIN", "SQRT", "TAN"];

/// The functions of Fanuc Custom Macro B and of LinuxCNC (`EXISTS`), as the manuals list them.
pub const MACRO_FUNCTIONS: [&str; 20] = [
    "ABS", "ACOS", "ADP", "ASIN", "ATAN", "BCD", "BIN", "COS", "EXISTS", "EXP", "FIX", "FUP", "LN",
    "POW", "ROUND", "SIN", "SQRT", "TAN", "ATN", "SQR",
];

/// The functions of LinuxCNC (rs274 `read_operation_unary`: 2.9 knows no other; `bcd[1]` is
/// "Unknown word where unary operation could be").
pub const LINUXCNC_FUNCTIONS: [&str; 14] = [
    "ABS", "ACOS", "ASIN", "ATAN", "COS", "EXISTS", "EXP", "FIX", "FUP", "LN", "ROUND", "SIN",
    "SQRT", "TAN",
];

/// The functions an expression of `syntax` calls.
fn known_functions(syntax: Syntax) -> &'static [&'static str] {
    if syntax.named {
        &LINUXCNC_FUNCTIONS
    } else if syntax.macros {
        &MACRO_FUNCTIONS
    } else {
        &FUNCTIONS
    }
}

/// The word operators of the macro dialects, read inside brackets only.
pub const WORD_OPERATORS: [&str; 10] = [
    "EQ", "NE", "GT", "GE", "LT", "LE", "AND", "OR", "XOR", "MOD",
];

/// The word operators of an Okuma OSP value, with or without brackets: comparisons, and
/// the logical AND, OR and EOR (exclusive or), as ICAM's Okuma pre-processor syntax lists them
/// (a third-party reference: the OSP manuals at hand do not list them; docs/dialects.md).
pub const OSP_OPERATORS: [&str; 9] = ["EQ", "NE", "GT", "GE", "LT", "LE", "AND", "OR", "EOR"];

/// Deepest nesting of brackets accepted in one expression.
pub const MAX_DEPTH: usize = 64;

/// The offset of the first byte at or after `pos` that is not a blank.
pub fn skip_blanks(line: &[u8], mut pos: usize) -> usize {
    while pos < line.len() && blank(line[pos]) {
        pos += 1;
    }
    pos
}

/// The end of the number `[0-9]+\.?[0-9]*|\.[0-9]+` at `pos`, if one starts there.
pub fn number_end(line: &[u8], pos: usize) -> Option<usize> {
    number_end_after(line, pos, digits_end(line, pos))
}

/// [`number_end`] where the digits at `pos` are known to end at `i`. (The tokenizer's word
/// reads the same form with its digits' value, `tokenizer::number_read`: kept apart, so that
/// the expressions' scans, which ask only where a number ends, do not pay for the value.)
fn number_end_after(line: &[u8], pos: usize, i: usize) -> Option<usize> {
    let digits = i > pos;
    if i < line.len() && line[i] == b'.' {
        let mut j = i + 1;
        while j < line.len() && line[j].is_ascii_digit() {
            j += 1;
        }
        if digits || j > i + 1 {
            return Some(j);
        }
    }
    digits.then_some(i)
}

fn digits_end(line: &[u8], pos: usize) -> usize {
    let mut i = pos;
    while i < line.len() && line[i].is_ascii_digit() {
        i += 1;
    }
    i
}

/// LinuxCNC reads a line without its blanks (rs274ngc `close_and_downcase`), so `1 0` is 10
/// and `# 1` is #1: the end of the digits and point at `pos` read through blanks (after the
/// last of them, blanks after it not included), or None where no number starts there.
pub fn spaced_number_end(line: &[u8], pos: usize) -> Option<usize> {
    let mut i = pos;
    let mut digits = false;
    let mut point = false;
    let mut end = None;
    loop {
        match line.get(i) {
            Some(d) if d.is_ascii_digit() => digits = true,
            Some(b'.') if !point => point = true,
            _ => break,
        }
        i += 1;
        if digits {
            end = Some(i);
        }
        i = skip_blanks(line, i);
    }
    end
}

/// Whether a function name of two to six letters followed by `[` stands at `pos` (`sin[30]`,
/// `ABS [#1]`): what LinuxCNC reads as a word's value (rs274 `read_real_value`, `read_unary`).
pub(crate) fn function_ahead(line: &[u8], pos: usize) -> bool {
    let end = pos
        + line[pos..]
            .iter()
            .take_while(|c| c.is_ascii_alphabetic())
            .count();
    (2..=6).contains(&(end - pos)) && line.get(skip_blanks(line, end)) == Some(&b'[')
}

/// LinuxCNC: the end of a parameter's number at `pos` read through blanks (`#1 2` is #12).
pub(crate) fn spaced_digits_end(line: &[u8], pos: usize) -> usize {
    let mut end = digits_end(line, pos);
    loop {
        let next = skip_blanks(line, end);
        if next == end || !line.get(next).is_some_and(u8::is_ascii_digit) {
            return end;
        }
        end = digits_end(line, next);
    }
}

fn error(message: String, offset: usize) -> LexError {
    LexError {
        kind: ErrorKind::Expression,
        message,
        offset,
        clause: "6.4.7",
    }
}

fn found(line: &[u8], pos: usize) -> LexError {
    let (c, _) = crate::text::Char::at(line, pos);
    error(
        format!(
            "expected a number or parameter in the expression, found {}",
            c.repr()
        ),
        pos,
    )
}

/// A Custom Macro B variable number written with a decimal part, `#30003.078` (the `#` at
/// `hash`, its digits ending at `digits`): the located error, or None where no `.` and digit
/// follow the digits. A variable is numbered with a whole number in the Fanuc and Haas macro
/// manuals at hand; the Haas NGC's `#30000`-range parameter variables with a decimal part, as
/// Renishaw's probing macros for the NGC write them, are documented by none of the sources at
/// hand (docs/dialects.md says what was searched). On a Haas a read of one is one variable
/// whose value is unknown (`Syntax::parameter_elements`, TG212: issue 32, severity by
/// evidence); elsewhere, and as the target of an assignment, it is refused, and said so.
pub fn variable_with_decimals(line: &[u8], hash: usize, digits: usize) -> Option<LexError> {
    if line.get(digits) != Some(&b'.') || !line.get(digits + 1).is_some_and(u8::is_ascii_digit) {
        return None;
    }
    let end = digits_end(line, digits + 1);
    let text = String::from_utf8_lossy(&line[hash..end]);
    Some(error(
        format!(
            "variable {text} has a decimal part: a macro variable is numbered with a whole \
             number (a Haas NGC parameter element such as {text} is not read: no source at \
             hand documents it)"
        ),
        hash,
    ))
}

/// The end of the word operator at `p` of a macro dialect's expression (`GE`, `AND`, ...),
/// one of `operators`, whose letters run to `letters_end`; or of one glued to the function
/// after it, `IF[#20NEFIX[#20]]` being NE FIX[#20] as the control reads its words (a Renishaw
/// probing macro of a Robodrill's memory). None where no operator begins there. The scanner
/// and the tree reader both read operators so.
fn operator_end(
    line: &[u8],
    p: usize,
    letters_end: usize,
    operators: &[&str],
    lowercase: bool,
    function: impl Fn(&[u8]) -> bool,
) -> Option<usize> {
    // no letter at `p` (a `]`, a `,`, the expression's end: where nearly every operand is
    // followed), no operator: none of the list is empty, nor any glued to a function
    if letters_end == p {
        return None;
    }
    let name = &line[p..letters_end];
    let is = |op: &str, text: &[u8]| {
        op.as_bytes().eq_ignore_ascii_case(text) && (lowercase || text == op.as_bytes())
    };
    if operators.iter().any(|op| is(op, name)) {
        return Some(letters_end);
    }
    if line.get(skip_blanks(line, letters_end)) != Some(&b'[') {
        return None;
    }
    operators.iter().find_map(|op| {
        let split = op.len();
        (name.len() > split && is(op, &name[..split]) && function(&name[split..]))
            .then_some(p + split)
    })
}

/// The well-formedness reader of an expression: where it ends, or why it is not one. Its
/// steps return their errors boxed (unboxed by [`scan`] and the other entries): a step's
/// `Result` of a position is then two registers, not a [`LexError`] of 64 bytes written
/// through memory at every level of the descent, on every word of an expression.
struct Scanner<'a> {
    line: &'a [u8],
    syntax: Syntax,
}

impl Scanner<'_> {
    fn sum(&self, pos: usize, depth: usize) -> Result<usize, Box<LexError>> {
        let mut pos = self.product(pos, depth)?;
        loop {
            let p = skip_blanks(self.line, pos);
            match self.line.get(p) {
                Some(b'+' | b'-') => pos = self.product(p + 1, depth)?,
                _ => match self.word_operator(p, depth) {
                    Some(end) => pos = self.product(end, depth)?,
                    None => return Ok(pos),
                },
            }
        }
    }

    /// The end of a word operator (`GE`, `AND`, ...) at `p`, inside brackets of a macro dialect.
    fn word_operator(&self, p: usize, depth: usize) -> Option<usize> {
        if !self.syntax.macros && !self.syntax.names {
            return None;
        }
        let end = self.letters_end(p);
        // Custom Macro B writes the logical operations and the remainder without brackets too
        // (#i = #j OR #k, #i = #j XOR #k, #i = #j AND #k, #i = #j MOD #k); LinuxCNC does not
        let operators: &[&str] = match depth {
            _ if self.syntax.names => &OSP_OPERATORS,
            0 if self.syntax.named => return None,
            0 => &WORD_OPERATORS[6..],
            _ => &WORD_OPERATORS,
        };
        operator_end(
            self.line,
            p,
            end,
            operators,
            self.syntax.lowercase,
            |name| self.function(name),
        )
    }

    /// Whether `name` is a function of the dialect's expressions.
    fn function(&self, name: &[u8]) -> bool {
        let name = String::from_utf8_lossy(name).to_ascii_uppercase();
        known_functions(self.syntax).contains(&name.as_str())
            || (self.syntax.macros && !self.syntax.named && name == "PRM")
    }

    fn letters_end(&self, p: usize) -> usize {
        let mut end = p;
        while end < self.line.len()
            && (self.line[end].is_ascii_uppercase()
                || (self.syntax.lowercase && self.line[end].is_ascii_lowercase()))
        {
            end += 1;
        }
        end
    }

    fn product(&self, pos: usize, depth: usize) -> Result<usize, Box<LexError>> {
        let mut pos = self.unary(pos, depth)?;
        loop {
            let p = skip_blanks(self.line, pos);
            match self.line.get(p) {
                Some(b'/') => pos = self.unary(p + 1, depth)?,
                Some(b'*')
                    if self.syntax.macros && depth > 0 && self.line.get(p + 1) == Some(&b'*') =>
                {
                    pos = self.unary(p + 2, depth)?
                }
                Some(b'*') if self.syntax.star => pos = self.unary(p + 1, depth)?,
                _ => return Ok(pos),
            }
        }
    }

    fn unary(&self, pos: usize, depth: usize) -> Result<usize, Box<LexError>> {
        let mut p = skip_blanks(self.line, pos);
        while matches!(self.line.get(p), Some(b'+' | b'-')) {
            p = skip_blanks(self.line, p + 1);
        }
        self.atom(p, depth)
    }

    fn atom(&self, p: usize, depth: usize) -> Result<usize, Box<LexError>> {
        let line = self.line;
        let Some(&b) = line.get(p) else {
            return Err(Box::new(error(
                "expression ends without an operand".into(),
                p,
            )));
        };
        let number = if self.syntax.named {
            spaced_number_end(line, p)
        } else {
            number_end(line, p)
        };
        if let Some(end) = number {
            return Ok(end);
        }
        let digit_after = line.get(p + 1).is_some_and(u8::is_ascii_digit);
        if self.syntax.names
            && b.is_ascii_uppercase()
            && line
                .get(p + 1)
                .is_some_and(|&c| c.is_ascii_digit() || c == b'.')
        {
            // Okuma OSP: a letter and a number is an address word (`Z5.`), the block's next
            // word, never a variable (its names begin with two letters: VC1, PRES), so the
            // value ended before it and the operator there has no operand: `X=VC1+ Z5.`
            let op = (0..p).rev().find(|&i| !blank(line[i])).unwrap_or(p);
            let word_end = p
                + 1
                + line[p + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_digit() || **c == b'.')
                    .count();
            let word = String::from_utf8_lossy(&line[p..word_end]);
            let what = if depth > 0 {
                // inside brackets the value has not ended: the word is no operand there
                format!("{word} is an address word, not a value (a variable's name begins with two letters)")
            } else {
                format!("{word} is the block's next address word, not a value")
            };
            return Err(Box::new(error(
                format!("'{}' without an operand after it: {what}", line[op] as char),
                op,
            )));
        }
        if (matches!(b, b'P' | b'Q' | b'R') || (b == b'#' && self.syntax.hash)) && digit_after {
            let end = if self.syntax.named {
                spaced_digits_end(line, p + 1)
            } else {
                digits_end(line, p + 1)
            };
            if b == b'#' && self.syntax.macros && !self.syntax.named {
                if let Some(e) = variable_with_decimals(line, p, end) {
                    // a Haas NGC's parameter element (`#30003.078`): one variable, its value
                    // unknown (the checker says so, TG212)
                    if self.syntax.parameter_elements {
                        return Ok(digits_end(line, end + 1));
                    }
                    return Err(Box::new(e));
                }
            }
            return Ok(end);
        }
        if b == b'#' && self.syntax.hash {
            if let Some(end) = self.special_parameter(p, depth)? {
                return Ok(end);
            }
        }
        if self.syntax.names {
            if let Some(end) = self.name(p, depth)? {
                return Ok(end);
            }
        }
        if b == b'[' && self.syntax.brackets {
            return self.group(p, depth);
        }
        let letter = b.is_ascii_uppercase() || (self.syntax.lowercase && b.is_ascii_lowercase());
        if letter && self.syntax.brackets {
            let end = self.letters_end(p);
            let open = skip_blanks(line, end);
            if (2..=6).contains(&(end - p)) && line.get(open) == Some(&b'[') {
                let name = std::str::from_utf8(&line[p..end])
                    .unwrap_or("")
                    .to_ascii_uppercase();
                let known = known_functions(self.syntax);
                // PRM[#j]: a parameter's value, a function of the 30i's Custom Macro B
                let prm = self.syntax.macros && !self.syntax.named && name == "PRM";
                if !known.contains(&name.as_str()) && !prm {
                    return Err(Box::new(error(
                        format!(
                            "unknown function {name} in an expression (known: {})",
                            known.join(" ")
                        ),
                        p,
                    )));
                }
                return self.group(open, depth);
            }
            if let Some(e) = self.function_with_parenthesis(p, end, open) {
                return Err(Box::new(e));
            }
        }
        if b == b'(' && self.syntax.macros && !self.syntax.named {
            // `#104 = #103 - (#101 - 1) * 2`: the same source as the function's case
            return Err(Box::new(error(
                "'(' where an operand should stand: on a FANUC or Haas '(' opens a comment, \
                 and brackets group an expression, [...] (FANUC Series 16/18-C lathe \
                 Operator's Manual, 16.3, p. 287)"
                    .into(),
                p,
            )));
        }
        Err(Box::new(found(line, p)))
    }

    /// Custom Macro B (FANUC, Haas): a function whose argument is written in parentheses,
    /// `ABS(#26 - #13)`, as other languages write it. On these controls brackets enclose an
    /// expression and a function's argument, and `(` opens a comment (FANUC Series
    /// 16/18/160/180-Model C for Lathe Operator's Manual, 16.3 "Arithmetic and logic
    /// operation", "Brackets", p. 287; Haas Mill Operator's Manual 96-8000, June 1999,
    /// "Macros", "Expressions": square brackets), so the control meets the function with no
    /// argument: the program's error, named as such rather than as an unknown operand. The
    /// function's letters run from `p` to `end`, and `open` is the first byte after them and
    /// any blanks.
    fn function_with_parenthesis(&self, p: usize, end: usize, open: usize) -> Option<LexError> {
        if !self.syntax.macros || self.syntax.named || self.line.get(open) != Some(&b'(') {
            return None;
        }
        let name = &self.line[p..end];
        if !self.function(name) {
            return None;
        }
        let name = String::from_utf8_lossy(name).to_ascii_uppercase();
        Some(error(
            format!(
                "function {name} takes its argument in brackets, {name}[...]: on a FANUC or \
                 Haas '(' opens a comment, so the control reads {name} with no argument \
                 (brackets enclose an expression, parentheses a comment: FANUC Series 16/18-C \
                 lathe Operator's Manual, 16.3, p. 287)"
            ),
            p,
        ))
    }

    /// `#[expr]` (a parameter chosen by number) and LinuxCNC's `#<name>`: its end, or None
    /// when `#` at `p` starts neither.
    fn special_parameter(&self, p: usize, depth: usize) -> Result<Option<usize>, Box<LexError>> {
        let line = self.line;
        // LinuxCNC reads blanks anywhere: "# <x>" is #<x>
        let q = if self.syntax.named {
            skip_blanks(line, p + 1)
        } else {
            p + 1
        };
        if self.syntax.macros && !self.syntax.named {
            // Custom Macro B `X # 1`: the blank after `#` is skipped as in `# 1 = 5` (a FANUC
            // reads a blank between an address and its number so: docs/dialects.md, "Blanks
            // inside a word"); a Haas NGC alarms on it there, and so here (audit 50, B12)
            // -- and `X # [1]` as `X#[1]`, the blank before a bracketed number the same blank
            // (review 52, F1: TG100 "expected a number or parameter")
            let r = skip_blanks(line, q);
            if r > q && matches!(line.get(r), Some(b'0'..=b'9' | b'[')) {
                if self.syntax.parameter_elements {
                    return Err(Box::new(crate::lex::apart(b'#', q)));
                }
                if line[r] == b'[' {
                    return self.group(r, depth).map(Some);
                }
                return Ok(Some(digits_end(line, r)));
            }
        }
        match line.get(q) {
            Some(b'[') if self.syntax.macros => self.group(q, depth).map(Some),
            // `# 1`: #1
            Some(d) if self.syntax.named && d.is_ascii_digit() => {
                Ok(Some(spaced_digits_end(line, q)))
            }
            Some(b'#') if self.syntax.named && depth < MAX_DEPTH => {
                self.atom(q, depth + 1).map(Some)
            }
            Some(b'<') if self.syntax.named => {
                match line[q + 1..].iter().position(|&c| c == b'>') {
                    Some(0) => Err(Box::new(error("parameter name '#<>' is empty".into(), p))),
                    Some(close) => Ok(Some(q + 1 + close + 1)),
                    None => Err(Box::new(error(
                        "named parameter '#<' without its closing '>'".into(),
                        p,
                    ))),
                }
            }
            _ => Ok(None),
        }
    }

    /// An Okuma OSP operand by its name at `p` (`CNTR`, `VC1`, `VTOFD[1]`, `FIX[VC2/7000]`,
    /// `VTOHT [[VC100],10001]`: a variable, its index or a function's argument in brackets,
    /// after blanks too), or a value written `#80H` (as the OSP program of the shops folder
    /// writes it; kept as text, not evaluated): its end, or None where no name starts there.
    fn name(&self, p: usize, depth: usize) -> Result<Option<usize>, Box<LexError>> {
        let line = self.line;
        let b = line[p];
        if b == b'#' {
            let end = p
                + 1
                + line[p + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_alphanumeric())
                    .count();
            return Ok((end > p + 1).then_some(end));
        }
        if !b.is_ascii_uppercase() {
            return Ok(None);
        }
        let end = p + line[p..]
            .iter()
            .take_while(|&&c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == b'_')
            .count();
        let open = skip_blanks(line, end);
        if line.get(open) == Some(&b'[') {
            return self.group(open, depth).map(Some);
        }
        Ok(Some(end))
    }

    /// `[ sum ]` with its `[` at `open`.
    fn group(&self, open: usize, depth: usize) -> Result<usize, Box<LexError>> {
        if depth >= MAX_DEPTH {
            return Err(Box::new(error(
                format!("expression nested deeper than {MAX_DEPTH} brackets"),
                open,
            )));
        }
        let mut inner = self.sum(open + 1, depth + 1)?;
        let mut close = skip_blanks(self.line, inner);
        while (self.syntax.macros || self.syntax.names) && self.line.get(close) == Some(&b',') {
            inner = self.sum(close + 1, depth + 1)?;
            close = skip_blanks(self.line, inner);
        }
        if self.line.get(close) == Some(&b']') {
            Ok(close + 1)
        } else {
            Err(Box::new(error(unclosed(self.line, close), close)))
        }
    }
}

/// Why a `[`'s contents end at `at` without its `]`: the line has none after it, or
/// something else stands first (`X[1 0]`: a value after the value, with no operation between
/// them; review 21, finding 2).
fn unclosed(line: &[u8], at: usize) -> String {
    match line.get(at) {
        Some(&c) if line[at..].contains(&b']') => format!(
            "'{}' after a value inside [ ], where an operation or the closing ']' must \
             follow it, in the expression",
            if c.is_ascii_graphic() {
                char::from(c).to_string()
            } else {
                format!("\\x{c:02x}")
            }
        ),
        _ => "'[' without a closing ']' in the expression".into(),
    }
}

/// The end of the expression that starts at `pos` (its last token's end, blanks after it not
/// included), or the located reason it is not well formed.
pub fn scan(line: &[u8], pos: usize, syntax: Syntax) -> Result<usize, LexError> {
    Scanner { line, syntax }.sum(pos, 0).map_err(|e| *e)
}

/// One bracketed group or `#n` standing for a value without an index (`X[#1+2]`, `X#1`).
pub fn scan_operand(line: &[u8], pos: usize, syntax: Syntax) -> Result<usize, LexError> {
    let scanner = Scanner { line, syntax };
    if line.get(pos) == Some(&b'[') {
        scanner.group(pos, 0)
    } else {
        scanner.atom(pos, 0)
    }
    .map_err(|e| *e)
}

/// A bracketed condition or argument `[ ... ]` at `open`, read with the dialect's operators.
pub fn scan_group(line: &[u8], open: usize, syntax: Syntax) -> Result<usize, LexError> {
    if line.get(open) != Some(&b'[') {
        return Err(error(
            "expected '[' to open a condition".into(),
            open.min(line.len()),
        ));
    }
    Scanner { line, syntax }.group(open, 0).map_err(|e| *e)
}

/// The value of a LinuxCNC expression's tree (from [`tree`]), computed in doubles as
/// rs274ngc computes it, where a parameter (`#<two>`, `#5`, its text) has the value `param`
/// gives it, if any: Err for a division by zero anywhere in it, None where a parameter not
/// given, a function or an operator other than `+ - * /` leaves the value to the machine.
pub(crate) fn linuxcnc_value(
    e: &Expr,
    text: &[u8],
    param: &dyn Fn(&[u8]) -> Option<f64>,
) -> Result<Option<f64>, ()> {
    Ok(match e {
        Expr::Number(a, b) => std::str::from_utf8(&text[*a..*b])
            .ok()
            .and_then(|t| t.replace([' ', '\t'], "").parse::<f64>().ok()),
        Expr::Param(a, b) => param(&text[*a..*b]),
        Expr::Sign(sign, inner) => {
            linuxcnc_value(inner, text, param)?.map(|v| if *sign == b'-' { -v } else { v })
        }
        Expr::Binary(op, l, r) => {
            let a = linuxcnc_value(l, text, param)?;
            let b = linuxcnc_value(r, text, param)?;
            if *op == b'/' && b == Some(0.0) {
                return Err(());
            }
            match (op, a, b) {
                (b'+', Some(a), Some(b)) => Some(a + b),
                (b'-', Some(a), Some(b)) => Some(a - b),
                (b'*', Some(a), Some(b)) => Some(a * b),
                (b'/', Some(a), Some(b)) => Some(a / b),
                _ => None,
            }
        }
        Expr::Call(inner) => {
            linuxcnc_value(inner, text, param)?;
            None
        }
        _ => None,
    })
}

/// Where a token stands in the expression text: `start..end` in bytes.
pub type Span = (usize, usize);

/// An expression as a tree, with the byte span of each number and parameter.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Expr {
    Number(usize, usize),
    Param(usize, usize),
    /// A unary `+` or `-`, and which.
    Sign(u8, Box<Expr>),
    Binary(u8, Box<Expr>, Box<Expr>),
    Call(Box<Expr>),
    /// HEIDENHAIN's constant `PI`, by its span.
    Pi(usize, usize),
    /// A HEIDENHAIN formula's `( )`: kept, so that the evaluator can tell `(2^3)^2` from
    /// `2^3^2`, whose order the manuals do not give.
    Group(Box<Expr>),
    /// A HEIDENHAIN formula function (`SIN 30`, `SQ (Q1 + 2)`): the span of its name, its
    /// argument, and whether the manuals' examples settle which operand it takes. They show a
    /// function taking the operand after it (`SQ 10 - 3^3` is 100 - 27) but never one before
    /// `*`, `/`, `%` or `^` without parentheses (`SQ 2 * 3`), which is read as `(SQ 2) * 3` and
    /// left without a value.
    Function(Span, Box<Expr>, bool),
    /// A Sinumerik variable or system variable by name (`_X_HOME`, `$P_TOOLR`, `TRUE`).
    Name(usize, usize),
    /// A Sinumerik string `"..."` or hexadecimal or binary constant `'H1F'`, quotes included.
    Text(usize, usize),
    /// A Sinumerik operator other than `+ - * /` (`DIV`, `==`, `AND`, `B_OR`, `<<`), by name.
    Operator(&'static str, Box<Expr>, Box<Expr>),
    /// Sinumerik's `NOT` or `B_NOT` before an operand.
    Not(&'static str, Box<Expr>),
    /// A Sinumerik call `NAME(a, b)` (`[` false) or element `NAME[a, b]` (`[` true): the span of
    /// the name and the arguments.
    Apply(Span, Vec<Expr>, bool),
}

/// The tree of the expression `text` (a whole expression, blanks allowed around its tokens),
/// read with every operator and bracket (the tree serves conversion, after the tokenizer has
/// judged the word under its dialect).
pub fn tree(text: &[u8]) -> Result<Expr, LexError> {
    whole(&mut TreeReader::new(text, 0, Trees))
}

/// The whole expression `text` read by `reader`'s builder.
fn whole<B: Build>(reader: &mut TreeReader<'_, B>) -> Result<B::Node, LexError> {
    let expr = reader.sum(0)?;
    let end = skip_blanks(reader.line, reader.pos);
    if end < reader.line.len() {
        return Err(found(reader.line, end));
    }
    Ok(expr)
}

/// What [`linear`] and [`parameters`] give of the tree of an expression, read without building
/// the tree (a tree is a box per node, made and dropped for each of the million words of a
/// long program: [`terms`]).
#[derive(Debug, Clone, Default)]
pub struct Terms {
    /// Whether the expression is linear ([`linear`] gives Some).
    pub linear: bool,
    /// Where it is, its number terms, as [`linear`] gives them.
    numbers: Vec<Span>,
    /// Every parameter the expression reads, in order, as [`parameters`] gives them.
    pub params: Vec<Span>,
    /// The shapes of the expressions [`terms_of`] has read into these terms ([`Shapes`]; boxed,
    /// made at the first: the terms are moved in and out of their readers for each word).
    shapes: Option<Box<Shapes>>,
}

/// Two readings are equal where their terms are: the shapes are only what was read before.
impl PartialEq for Terms {
    fn eq(&self, other: &Terms) -> bool {
        (self.linear, &self.numbers, &self.params) == (other.linear, &other.numbers, &other.params)
    }
}

impl Eq for Terms {}

/// The expressions of a program, read once a shape. A CAM program that scales its moves by
/// parameters writes the same expression on every line with other numbers
/// (`Y[#<yscale>*-56.12]`, `Y[#<yscale>*-55.992]`), and the reader of 6.4.7 ([`TreeReader`])
/// makes the same terms of both, at other offsets: it asks of a number only where it ends
/// ([`number_end`]: any digits, a point or not), never what it is. So an expression is keyed
/// by its *shape*, its text with each number that stands where an operand may begin replaced
/// by one byte of its form (digits; digits and a point; a point and digits), and the terms of
/// the first expression of a shape serve every later one, their offsets moved by the lengths
/// of its numbers. Where a digit is part of a name (`#1`, `R2`, `#<a1>`, `ATAN2`) or a number
/// is followed by what could continue it, the byte stays as written: a shape then keys fewer
/// expressions, never two the reader reads apart. An expression that cannot be read is read
/// again each time (its error is the reader's); the shapes are forgotten past [`SHAPES`].
#[derive(Debug, Clone, Default)]
struct Shapes {
    /// The terms of each shape read, with offsets into the shape.
    read: crate::hash::FastMap<Box<[u8]>, Shaped>,
    /// The shape of the expression being read.
    shape: Vec<u8>,
    /// Its numbers replaced: (offset in the shape, offset in the text, length in the text).
    runs: Vec<(usize, usize, usize)>,
    /// The shapes kept so far (each one's number), and the number of the last one read.
    made: u64,
    last: Option<u64>,
}

/// The terms of a shape: [`Terms`] with offsets into the shape.
#[derive(Debug, Clone)]
struct Shaped {
    /// Its number: the shapes' count when it was kept.
    id: u64,
    linear: bool,
    numbers: Box<[Span]>,
    params: Box<[Span]>,
}

/// The most shapes kept: a program of more forgets them and begins again (a few kilobytes).
const SHAPES: usize = 4096;

/// The shape byte of a number: digits, digits and a point, a point and digits.
const FORMS: [u8; 3] = [1, 2, 3];

/// The bytes where [`Shapes::make`] stops copying: a digit or point (a number may begin), `<`
/// (a LinuxCNC name), and the shape's own bytes ([`FORMS`]).
const STOPS: [bool; 256] = {
    let mut stops = [false; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        stops[c] = b.is_ascii_digit() || b == b'.' || b == b'<' || b <= FORMS[2];
        c += 1;
    }
    stops
};

impl Shapes {
    /// The shape of `text` into [`Shapes::shape`] and [`Shapes::runs`]; false where the text
    /// holds a byte a shape uses for its numbers (no shape: read as it is).
    fn make(&mut self, text: &[u8]) -> bool {
        self.shape.clear();
        self.runs.clear();
        let mut i = 0;
        while i < text.len() {
            // the bytes up to the next that may begin a number or a name, as they are
            let start = i;
            while i < text.len() && !STOPS[usize::from(text[i])] {
                i += 1;
            }
            self.shape.extend_from_slice(&text[start..i]);
            let Some(&c) = text.get(i) else { break };
            if c <= FORMS[2] {
                return false;
            }
            if c == b'<' {
                // `#<..>`: LinuxCNC's names hold digits and blanks, kept as written
                let close = text[i..]
                    .iter()
                    .position(|&c| c == b'>')
                    .map_or(text.len(), |p| i + p + 1);
                if text[i..close].iter().any(|&c| c <= FORMS[2]) {
                    return false;
                }
                self.shape.extend_from_slice(&text[i..close]);
                i = close;
                continue;
            }
            let operand = i == 0
                || matches!(
                    text[i - 1],
                    b'[' | b'(' | b'+' | b'-' | b'*' | b'/' | b',' | b'=' | b' ' | b'\t'
                );
            let end = if operand { number_end(text, i) } else { None };
            match end {
                Some(end)
                    if !text
                        .get(end)
                        .is_some_and(|&n| n.is_ascii_alphanumeric() || n == b'.' || n == b'_') =>
                {
                    let form = match text[i..end].iter().position(|&d| d == b'.') {
                        None => FORMS[0],
                        Some(0) => FORMS[2],
                        Some(_) => FORMS[1],
                    };
                    self.runs.push((self.shape.len(), i, end - i));
                    self.shape.push(form);
                    i = end;
                }
                _ => {
                    // a digit of a name (`#1`, `R2`) or a number that does not end there
                    let digits = text[i + 1..]
                        .iter()
                        .position(|&c| !(c.is_ascii_digit() || c == b'.'))
                        .map_or(text.len(), |p| i + 1 + p);
                    self.shape.extend_from_slice(&text[i..digits]);
                    i = digits;
                }
            }
        }
        true
    }

    /// The text's offset of the shape's offset `s` (a token's start or end).
    fn in_text(&self, s: usize) -> usize {
        match self.runs.partition_point(|&(at, _, _)| at < s) {
            0 => s,
            n => {
                let (at, start, len) = self.runs[n - 1];
                s - at - 1 + start + len
            }
        }
    }

    /// The shape's offset of the text's offset `t`; None inside a number replaced.
    fn in_shape(&self, t: usize) -> Option<usize> {
        match self.runs.partition_point(|&(_, start, _)| start < t) {
            0 => Some(t),
            n => {
                let (at, start, len) = self.runs[n - 1];
                (t >= start + len).then(|| t - start - len + at + 1)
            }
        }
    }
}

/// [`terms_into`] by the shape of `text` ([`Shapes`]): the terms of its shape where one was
/// read before, else read and kept for it.
fn shaped_into(text: &[u8], terms: &mut Terms) -> Result<(), LexError> {
    let shapes = terms.shapes.get_or_insert_with(Box::default);
    shapes.last = None;
    if !shapes.make(text) {
        return terms_into(text, terms);
    }
    if let Some(known) = shapes.read.get(&shapes.shape[..]) {
        let moved = |&(a, b): &Span| (shapes.in_text(a), shapes.in_text(b));
        terms.numbers.clear();
        terms.params.clear();
        terms.numbers.extend(known.numbers.iter().map(moved));
        terms.params.extend(known.params.iter().map(moved));
        terms.linear = known.linear;
        shapes.last = Some(known.id);
        return Ok(());
    }
    terms_into(text, terms)?;
    let Some(shapes) = terms.shapes.as_mut() else {
        return Ok(());
    };
    let moved = |spans: &[Span]| -> Option<Box<[Span]>> {
        spans
            .iter()
            .map(|&(a, b)| Some((shapes.in_shape(a)?, shapes.in_shape(b)?)))
            .collect()
    };
    if let (Some(numbers), Some(params)) = (moved(&terms.numbers), moved(&terms.params)) {
        if shapes.read.len() >= SHAPES {
            shapes.read.clear();
        }
        shapes.made += 1;
        let shaped = Shaped {
            id: shapes.made,
            linear: terms.linear,
            numbers,
            params,
        };
        shapes.read.insert(shapes.shape.as_slice().into(), shaped);
        shapes.last = Some(shapes.made);
    }
    Ok(())
}

impl Terms {
    /// The number terms of a linear expression; None for any other.
    pub fn numbers(&self) -> Option<&[Span]> {
        self.linear.then_some(&self.numbers[..])
    }

    /// The shape of the expression [`terms_of`] last read into these terms, by its number (an
    /// expression of the same shape has the same terms, its parameters the same names); None
    /// where it has none kept ([`Shapes`]).
    pub fn shape(&self) -> Option<u64> {
        self.shapes.as_ref().and_then(|s| s.last)
    }
}

/// The terms of the expression `text`: `linear(&tree(text)?)` and `parameters` of the same
/// tree, read by the same reader ([`TreeReader`]) into [`Walked`] summaries instead of nodes.
pub fn terms(text: &[u8]) -> Result<Terms, LexError> {
    let mut terms = Terms::default();
    terms_into(text, &mut terms)?;
    Ok(terms)
}

/// [`terms`] into `terms`, whose lists are cleared and reused (a reader of a million words
/// allocates them once). After an error they hold nothing that means anything.
pub fn terms_into(text: &[u8], terms: &mut Terms) -> Result<(), LexError> {
    terms.numbers.clear();
    terms.params.clear();
    let walk = Walk {
        numbers: std::mem::take(&mut terms.numbers),
        params: std::mem::take(&mut terms.params),
    };
    let mut reader = TreeReader::new(text, 0, walk);
    let read = whole(&mut reader);
    (terms.numbers, terms.params) = (reader.build.numbers, reader.build.params);
    terms.linear = read?.linear;
    Ok(())
}

/// [`terms_into`] for an expression of `family`'s: a SINUMERIK's read by its own reader
/// ([`sinumerik_tree`]: round brackets group, `r1` is `R1`, names and functions), whose
/// [`linear`] and [`parameters`] are the terms; any other family's by the reader of 6.4.7.
/// The one reading the parameter analysis and the converter share.
pub fn terms_of(text: &[u8], family: Family, terms: &mut Terms) -> Result<(), LexError> {
    if family != Family::Sinumerik {
        return shaped_into(text, terms);
    }
    // (read by no shape: none is this expression's)
    if let Some(shapes) = terms.shapes.as_mut() {
        shapes.last = None;
    }
    terms.numbers.clear();
    terms.params.clear();
    let tree = sinumerik_tree(text)?;
    let value = dimension_value(text, &tree).unwrap_or(&tree);
    terms.linear = walk(value, &mut terms.numbers, &mut terms.params);
    if !terms.linear {
        terms.numbers.clear();
        terms.params.clear();
        parameters(&tree, &mut terms.params);
    }
    Ok(())
}

/// The value inside a SINUMERIK axis value's dimension modifier, `IC(..)` or `AC(..)`
/// (`X=IC(5)`, `Y=AC(R1+2)`): the position, incremental or absolute, whatever the G90/G91 in
/// force, is the value inside (SINUMERIK 840D sl Programming Manual Fundamentals, "Absolute
/// dimensions (G90, AC)" and "Incremental dimensions (G91, IC)"), so a linear one converts as
/// the same value written alone does. None for any other expression.
fn dimension_value<'e>(text: &[u8], tree: &'e Expr) -> Option<&'e Expr> {
    match tree {
        Expr::Apply((a, b), args, false) if args.len() == 1 => {
            let name = &text[*a..*b];
            (name.eq_ignore_ascii_case(b"IC") || name.eq_ignore_ascii_case(b"AC")).then(|| &args[0])
        }
        _ => None,
    }
}

/// The dimension modifier of a SINUMERIK axis word, `X=IC(5)`, `Y = ac(R1)`: "IC" or "AC",
/// or None ([`dimension_value`]).
pub fn dimension_modifier(token: &[u8]) -> Option<&'static str> {
    let eq = token.iter().position(|&c| c == b'=')?;
    let value = &token[skip_blanks(token, eq + 1)..];
    let head = value.get(..2)?;
    if value.get(skip_blanks(value, 2)) != Some(&b'(') {
        return None;
    }
    if head.eq_ignore_ascii_case(b"IC") {
        Some("IC")
    } else if head.eq_ignore_ascii_case(b"AC") {
        Some("AC")
    } else {
        None
    }
}

/// What the reader of 6.4.7 expressions ([`TreeReader::sum`]) makes of each operand and
/// operation: a tree's node ([`Trees`]) or a summary of it ([`Walk`]).
trait Build {
    type Node;
    fn number(&mut self, start: usize, end: usize) -> Self::Node;
    fn param(&mut self, start: usize, end: usize) -> Self::Node;
    fn sign(&mut self, sign: u8, inner: Self::Node) -> Self::Node;
    fn binary(&mut self, op: u8, left: Self::Node, right: Self::Node) -> Self::Node;
    fn call(&mut self, inner: Self::Node) -> Self::Node;
}

/// The tree itself.
#[derive(Debug, Default)]
struct Trees;

impl Build for Trees {
    type Node = Expr;
    fn number(&mut self, start: usize, end: usize) -> Expr {
        Expr::Number(start, end)
    }
    fn param(&mut self, start: usize, end: usize) -> Expr {
        Expr::Param(start, end)
    }
    fn sign(&mut self, sign: u8, inner: Expr) -> Expr {
        Expr::Sign(sign, Box::new(inner))
    }
    fn binary(&mut self, op: u8, left: Expr, right: Expr) -> Expr {
        Expr::Binary(op, Box::new(left), Box::new(right))
    }
    fn call(&mut self, inner: Expr) -> Expr {
        Expr::Call(Box::new(inner))
    }
}

/// A subtree as [`walk`] and [`constant`] see it: whether it is linear and constant, and where
/// its number terms begin in [`Walk::numbers`] (a subtree's are contiguous, after its left
/// neighbour's).
#[derive(Debug, Clone, Copy)]
struct Walked {
    linear: bool,
    constant: bool,
    start: usize,
}

/// The number terms and parameters of the expression read so far.
#[derive(Debug, Default)]
struct Walk {
    numbers: Vec<Span>,
    params: Vec<Span>,
}

impl Build for Walk {
    type Node = Walked;
    fn number(&mut self, start: usize, end: usize) -> Walked {
        self.numbers.push((start, end));
        Walked {
            linear: true,
            constant: true,
            start: self.numbers.len() - 1,
        }
    }
    fn param(&mut self, start: usize, end: usize) -> Walked {
        self.params.push((start, end));
        Walked {
            linear: true,
            constant: false,
            start: self.numbers.len(),
        }
    }
    fn sign(&mut self, _: u8, inner: Walked) -> Walked {
        inner
    }
    /// As [`walk`]: `+` and `-` keep both sides' terms; `*` or `/` by a constant keeps the
    /// other side's only (a factor scales a length and stays as it is), a constant `*` before
    /// another operand likewise; anything else is not linear.
    fn binary(&mut self, op: u8, left: Walked, right: Walked) -> Walked {
        let linear = match op {
            b'+' | b'-' => left.linear && right.linear,
            b'*' | b'/' => match (left.constant, right.constant) {
                (false, true) => {
                    self.numbers.truncate(right.start);
                    left.linear
                }
                (true, false) if op == b'*' => {
                    self.numbers.drain(left.start..right.start);
                    right.linear
                }
                _ => false,
            },
            _ => false,
        };
        Walked {
            linear,
            constant: left.constant && right.constant,
            start: left.start,
        }
    }
    fn call(&mut self, inner: Walked) -> Walked {
        Walked {
            linear: false,
            constant: false,
            ..inner
        }
    }
}

/// A tree is dropped with a stack of its own, not by recursion: a chain of 30,000 terms
/// (`1+1+...`, or `-` signs, in one block) is a tree 30,000 deep, and dropping it recursively
/// overflowed a thread's stack.
impl Drop for Expr {
    fn drop(&mut self) {
        let mut stack = Vec::new();
        take_children(self, &mut stack);
        while let Some(mut e) = stack.pop() {
            take_children(&mut e, &mut stack);
        }
    }
}

/// Move the subtrees of `e` onto `stack`, leaving leaves in their place.
fn take_children(e: &mut Expr, stack: &mut Vec<Expr>) {
    let mut take = |child: &mut Box<Expr>| {
        if !matches!(
            **child,
            Expr::Number(..) | Expr::Param(..) | Expr::Pi(..) | Expr::Name(..) | Expr::Text(..)
        ) {
            stack.push(std::mem::replace(&mut **child, Expr::Number(0, 0)));
        }
    };
    match e {
        Expr::Sign(_, inner)
        | Expr::Call(inner)
        | Expr::Group(inner)
        | Expr::Function(_, inner, _) => take(inner),
        Expr::Binary(_, l, r) | Expr::Operator(_, l, r) => {
            take(l);
            take(r);
        }
        Expr::Not(_, inner) => take(inner),
        Expr::Apply(_, args, _) => stack.append(args),
        Expr::Number(..) | Expr::Param(..) | Expr::Pi(..) | Expr::Name(..) | Expr::Text(..) => {}
    }
}

/// The functions of a HEIDENHAIN Q-parameter formula, as the TNC manuals list them ("Entering
/// formulas directly"; docs/dialects.md).
pub const FORMULA_FUNCTIONS: [&str; 16] = [
    "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQ", "SQRT", "LN", "LOG", "EXP", "NEG", "INT",
    "ABS", "FRAC", "SGN",
];

/// Where a HEIDENHAIN formula's errors point: the manuals' section.
const FORMULA_CLAUSE: &str = "HEIDENHAIN formulas";

/// The tree of a HEIDENHAIN Q-parameter formula's right-hand side, `line[start..]` (the caller
/// cuts the line at the formula's end): the grammar of the TNC, not of 6.4.7:
///
/// ```text
/// sum     := product (("+" | "-") product)*
/// product := power (("*" | "/" | "%") power)*
/// power   := unary ("^" unary)*
/// unary   := ("+" | "-")* primary
/// primary := NUMBER | Q[LR]?[0-9]+ | "PI" | "(" sum ")" | FUNCTION unary
/// ```
///
/// Upper case only, blanks between any two tokens. The spans and the offsets of errors are in
/// `line`, so an error points at its column.
pub fn formula_tree(line: &[u8], start: usize) -> Result<Expr, LexError> {
    let (expr, end) = formula_prefix(line, start)?;
    let end = skip_blanks(line, end);
    if end < line.len() {
        let mut e = found(line, end);
        e.clause = FORMULA_CLAUSE;
        return Err(e);
    }
    Ok(expr)
}

/// The tree of the formula that starts at `start` and the end of its last token: what follows
/// is the caller's (a cycle's next parameter, `Q225=+15 Q226=+15`).
pub fn formula_prefix(line: &[u8], start: usize) -> Result<(Expr, usize), LexError> {
    let mut reader = TreeReader::new(line, start, Trees);
    match reader.formula_sum(0) {
        Ok(expr) => {
            // the reader looks past the blanks after the last token
            let mut end = reader.pos;
            while end > start && blank(line[end - 1]) {
                end -= 1;
            }
            Ok((expr, end))
        }
        Err(mut e) => {
            e.clause = FORMULA_CLAUSE;
            Err(e)
        }
    }
}

/// Where a Sinumerik expression's errors point.
const SINUMERIK_CLAUSE: &str = "Sinumerik";

/// The arithmetic functions of a Sinumerik expression, as the 840D sl programming manual lists
/// them ("Arithmetic functions": SIN COS TAN ASIN ACOS ATAN2 SQRT ABS POT TRUNC ROUND LN EXP;
/// docs/dialects.md). Any other `NAME(..)` is a call of a predefined or user function, read
/// and left without a value.
pub const SINUMERIK_FUNCTIONS: [&str; 13] = [
    "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN2", "SQRT", "ABS", "POT", "TRUNC", "ROUND", "LN",
    "EXP",
];

/// The binary operators of a Sinumerik expression, from the lowest priority to the highest
/// (the manual's "Priority of the operations", its levels 11 to 2; level 1 is `NOT`, `B_NOT`):
/// comparisons bind last, so `R1>5 AND R2<3` compares `5 AND R2`; the manuals write
/// `(R1==2) AND (R2<>3)`.
const SINUMERIK_LEVELS: [&[&str]; 10] = [
    &["==", "<>", "<=", ">=", "<", ">"],
    &["<<"],
    &["OR"],
    &["XOR"],
    &["AND"],
    &["B_OR"],
    &["B_XOR"],
    &["B_AND"],
    &["+", "-"],
    &["*", "/", "DIV", "MOD"],
];

/// The word operators, which a name cannot be.
const SINUMERIK_WORDS: [&str; 10] = [
    "OR", "XOR", "AND", "B_OR", "B_XOR", "B_AND", "DIV", "MOD", "NOT", "B_NOT",
];

fn ident_char(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_' || b == b'$'
}

fn ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_' || b == b'$'
}

fn sinumerik_error(message: String, offset: usize) -> LexError {
    LexError {
        kind: ErrorKind::Expression,
        message,
        offset,
        clause: SINUMERIK_CLAUSE,
    }
}

/// The tree of the Sinumerik expression that starts at `start` and the end of its last token
/// (what follows is the caller's: `X=R1+5 Y0`, `IF R1>5 GOTOF L1`):
///
/// ```text
/// expr    := level10 (("==" | "<>" | "<=" | ">=" | "<" | ">") level10)*   and so on down:
///            "<<", OR, XOR, AND, B_OR, B_XOR, B_AND, ("+" | "-"), ("*" | "/" | DIV | MOD)
/// unary   := ("+" | "-" | NOT | B_NOT)* primary
/// primary := NUMBER ("EX" [+-]? DIGITS)? | STRING | 'H1F' | 'B101' | R[0-9]+ | NAME
///          | NAME "(" args? ")"
///          | NAME "[" args "]" | "(" expr ")"
/// args    := expr ("," expr)*
/// NAME    := [A-Za-z_$][A-Za-z0-9_$]*                      not a word operator
/// ```
///
/// Operators of one level apply from left to right; names and operators in any case; blanks
/// between any two tokens. A word operator ends where a name would (`R1 AND R2`, `(R1)AND(R2)`).
pub fn sinumerik_prefix(line: &[u8], start: usize) -> Result<(Expr, usize), LexError> {
    let mut reader = TreeReader::new(line, start, Trees);
    let expr = match reader.siemens_lone_number() {
        Some(expr) => expr,
        None => {
            reader = TreeReader::new(line, start, Trees);
            reader.siemens_level(0, 0)?
        }
    };
    let mut end = reader.pos;
    while end > start && blank(line[end - 1]) {
        end -= 1;
    }
    Ok((expr, end))
}

/// The tree of the whole Sinumerik expression `text` (nothing after it but blanks).
pub fn sinumerik_tree(text: &[u8]) -> Result<Expr, LexError> {
    let (expr, end) = sinumerik_prefix(text, 0)?;
    let end = skip_blanks(text, end);
    if end < text.len() {
        let (c, _) = crate::text::Char::at(text, end);
        return Err(sinumerik_error(
            format!(
                "expected an operator or the end of the expression, found {}",
                c.repr()
            ),
            end,
        ));
    }
    Ok(expr)
}

impl TreeReader<'_> {
    /// The operator of `level` at the reader's position (blanks skipped), and its end.
    fn siemens_operator(&mut self, level: usize) -> Option<(&'static str, usize)> {
        let p = match self.peek() {
            Some(_) => self.pos,
            None => return None,
        };
        let line = self.line;
        if ident_start(line[p]) {
            let mut end = p;
            while end < line.len() && ident_char(line[end]) {
                end += 1;
            }
            let word = &line[p..end];
            return SINUMERIK_LEVELS[level]
                .iter()
                .find(|op| op.as_bytes().eq_ignore_ascii_case(word))
                .map(|op| (*op, end));
        }
        // the longest symbol first: "<<", "<>" and "<=" before "<"
        let two = line.get(p..p + 2);
        let mut best: Option<(&'static str, usize)> = None;
        for level_ops in SINUMERIK_LEVELS {
            for op in level_ops.iter() {
                let bytes = op.as_bytes();
                let symbol = !bytes[0].is_ascii_alphabetic() && !bytes.starts_with(b"B_");
                let matched = if bytes.len() == 2 {
                    two == Some(bytes)
                } else {
                    line[p] == bytes[0]
                };
                if symbol && matched && best.is_none_or(|(b, _)| b.len() < op.len()) {
                    best = Some((*op, p + op.len()));
                }
            }
        }
        best.filter(|(op, _)| SINUMERIK_LEVELS[level].contains(op))
    }

    /// A number with no operator after it (`TURN=0`, on many blocks of a CAM program's arcs):
    /// what the descent through the ten levels of operators reads there, read without it (the
    /// number, then no operator of any level after it); None for anything else, read by the
    /// descent from the start again.
    fn siemens_lone_number(&mut self) -> Option<Expr> {
        let first = self.peek()?;
        if !(first.is_ascii_digit() || first == b'.') || number_end(self.line, self.pos).is_none() {
            return None;
        }
        let expr = self.siemens_primary(0).ok()?;
        (0..SINUMERIK_LEVELS.len())
            .all(|level| self.siemens_operator(level).is_none())
            .then_some(expr)
    }

    fn siemens_level(&mut self, level: usize, depth: usize) -> Result<Expr, LexError> {
        if level == SINUMERIK_LEVELS.len() {
            return self.siemens_unary(depth);
        }
        let mut left = self.siemens_level(level + 1, depth)?;
        while let Some((op, end)) = self.siemens_operator(level) {
            self.pos = end;
            let right = self.siemens_level(level + 1, depth)?;
            left = match op {
                "+" | "-" | "*" | "/" => {
                    Expr::Binary(op.as_bytes()[0], Box::new(left), Box::new(right))
                }
                _ => Expr::Operator(op, Box::new(left), Box::new(right)),
            };
        }
        Ok(left)
    }

    fn siemens_unary(&mut self, depth: usize) -> Result<Expr, LexError> {
        let mut prefixes: Vec<&'static str> = Vec::new();
        loop {
            match self.peek() {
                Some(b'+') => prefixes.push("+"),
                Some(b'-') => prefixes.push("-"),
                Some(c) if ident_start(c) => {
                    let mut end = self.pos;
                    while end < self.line.len() && ident_char(self.line[end]) {
                        end += 1;
                    }
                    let word = &self.line[self.pos..end];
                    let Some(not) = ["NOT", "B_NOT"]
                        .into_iter()
                        .find(|n| n.as_bytes().eq_ignore_ascii_case(word))
                    else {
                        break;
                    };
                    prefixes.push(not);
                    self.pos = end - 1;
                }
                _ => break,
            }
            self.pos += 1;
        }
        let mut expr = self.siemens_primary(depth)?;
        for prefix in prefixes.into_iter().rev() {
            expr = match prefix {
                "+" | "-" => Expr::Sign(prefix.as_bytes()[0], Box::new(expr)),
                _ => Expr::Not(prefix, Box::new(expr)),
            };
        }
        Ok(expr)
    }

    fn siemens_primary(&mut self, depth: usize) -> Result<Expr, LexError> {
        let Some(b) = self.peek() else {
            return Err(sinumerik_error(
                "expression ends without an operand".into(),
                self.pos,
            ));
        };
        let (line, p) = (self.line, self.pos);
        if let Some(mut end) = number_end(line, p) {
            // 10EX-5: a REAL constant with its exponent
            if line
                .get(end..end + 2)
                .is_some_and(|e| e.eq_ignore_ascii_case(b"EX"))
            {
                let mut q = end + 2;
                if matches!(line.get(q), Some(b'+' | b'-')) {
                    q += 1;
                }
                let digits = digits_end(line, q);
                if digits > q {
                    end = digits;
                }
            }
            self.pos = end;
            return Ok(Expr::Number(p, end));
        }
        if b == b'"' {
            let Some(close) = line[p + 1..].iter().position(|&c| c == b'"') else {
                return Err(sinumerik_error("'\"' without its closing '\"'".into(), p));
            };
            let inner = &line[p + 1..p + 1 + close];
            // text outside ASCII in a string is read (TG127 says so once per file)
            if let Some(bad) = inner.iter().position(|&c| c < 0x20 || c == 0x7f) {
                return Err(LexError {
                    kind: ErrorKind::Character,
                    message: format!("control character 0x{:02X} in a string", inner[bad]),
                    offset: p + 1 + bad,
                    clause: SINUMERIK_CLAUSE,
                });
            }
            self.pos = p + close + 2;
            return Ok(Expr::Text(p, self.pos));
        }
        if b == b'\'' {
            // 'H1F', 'B0110': a hexadecimal or binary constant (kept, without a value)
            let digits = |c: &u8| match line.get(p + 1) {
                Some(b'H' | b'h') => c.is_ascii_hexdigit(),
                Some(b'B' | b'b') => matches!(c, b'0' | b'1'),
                _ => false,
            };
            let count = line[(p + 2).min(line.len())..]
                .iter()
                .take_while(|c| digits(c))
                .count();
            if count == 0 || line.get(p + 2 + count) != Some(&b'\'') {
                return Err(sinumerik_error(
                    "a constant in ' ' is 'H' and hexadecimal digits or 'B' and binary digits"
                        .into(),
                    p,
                ));
            }
            self.pos = p + count + 3;
            return Ok(Expr::Text(p, self.pos));
        }
        if depth >= MAX_DEPTH && (b == b'(' || ident_start(b)) {
            return Err(sinumerik_error(
                format!("expression nested deeper than {MAX_DEPTH} levels"),
                p,
            ));
        }
        if b == b'(' {
            self.pos += 1;
            let inner = self.siemens_level(0, depth + 1)?;
            if self.peek() != Some(b')') {
                return Err(sinumerik_error(
                    "'(' without a closing ')' in the expression".into(),
                    self.pos,
                ));
            }
            self.pos += 1;
            return Ok(Expr::Group(Box::new(inner)));
        }
        if !ident_start(b) {
            let (c, _) = crate::text::Char::at(line, p);
            return Err(sinumerik_error(
                format!("expected a value in the expression, found {}", c.repr()),
                p,
            ));
        }
        let mut end = p;
        while end < line.len() && ident_char(line[end]) {
            end += 1;
        }
        let name = &line[p..end];
        if SINUMERIK_WORDS
            .iter()
            .any(|w| w.as_bytes().eq_ignore_ascii_case(name))
        {
            return Err(sinumerik_error(
                format!(
                    "expected a value in the expression, found the operator {}",
                    String::from_utf8_lossy(name).to_ascii_uppercase()
                ),
                p,
            ));
        }
        self.pos = end;
        if matches!(b, b'R' | b'r') && end > p + 1 && name[1..].iter().all(u8::is_ascii_digit) {
            return Ok(Expr::Param(p, end));
        }
        let (open, close, element) = match self.peek() {
            Some(b'(') => (b'(', b')', false),
            Some(b'[') => (b'[', b']', true),
            _ => {
                self.pos = end;
                return Ok(Expr::Name(p, end));
            }
        };
        self.pos += 1;
        let mut args = Vec::new();
        if element || self.peek() != Some(close) {
            loop {
                args.push(self.siemens_level(0, depth + 1)?);
                if self.peek() == Some(b',') {
                    self.pos += 1;
                } else {
                    break;
                }
            }
        }
        if self.peek() != Some(close) {
            return Err(sinumerik_error(
                format!(
                    "'{}' without a closing '{}' in the expression",
                    open as char, close as char
                ),
                self.pos,
            ));
        }
        self.pos += 1;
        Ok(Expr::Apply((p, end), args, element))
    }
}

struct TreeReader<'a, B = Trees> {
    line: &'a [u8],
    pos: usize,
    build: B,
}

impl<'a, B> TreeReader<'a, B> {
    fn new(line: &'a [u8], pos: usize, build: B) -> Self {
        TreeReader { line, pos, build }
    }
}

impl TreeReader<'_> {
    fn formula_sum(&mut self, depth: usize) -> Result<Expr, LexError> {
        let mut left = self.formula_product(depth)?;
        while let Some(op @ (b'+' | b'-')) = self.peek() {
            self.pos += 1;
            left = Expr::Binary(op, Box::new(left), Box::new(self.formula_product(depth)?));
        }
        Ok(left)
    }

    fn formula_product(&mut self, depth: usize) -> Result<Expr, LexError> {
        let mut left = self.formula_power(depth)?;
        while let Some(op @ (b'*' | b'/' | b'%')) = self.peek() {
            self.pos += 1;
            left = Expr::Binary(op, Box::new(left), Box::new(self.formula_power(depth)?));
        }
        Ok(left)
    }

    fn formula_power(&mut self, depth: usize) -> Result<Expr, LexError> {
        let mut left = self.formula_unary(depth)?;
        while self.peek() == Some(b'^') {
            self.pos += 1;
            left = Expr::Binary(b'^', Box::new(left), Box::new(self.formula_unary(depth)?));
        }
        Ok(left)
    }

    fn formula_unary(&mut self, depth: usize) -> Result<Expr, LexError> {
        let mut signs = Vec::new();
        while let Some(sign @ (b'+' | b'-')) = self.peek() {
            self.pos += 1;
            signs.push(sign);
        }
        let mut expr = self.formula_primary(depth)?;
        for sign in signs.into_iter().rev() {
            expr = Expr::Sign(sign, Box::new(expr));
        }
        Ok(expr)
    }

    fn formula_primary(&mut self, depth: usize) -> Result<Expr, LexError> {
        let Some(b) = self.peek() else {
            return Err(error("formula ends without an operand".into(), self.pos));
        };
        let (line, p) = (self.line, self.pos);
        if let Some(end) = number_end(line, p) {
            self.pos = end;
            return Ok(Expr::Number(p, end));
        }
        if b == b'Q' {
            let digits = p + 1 + usize::from(matches!(line.get(p + 1), Some(b'L' | b'R')));
            let end = digits_end(line, digits);
            if end > digits {
                self.pos = end;
                return Ok(Expr::Param(p, end));
            }
        }
        if depth >= MAX_DEPTH && (b == b'(' || b.is_ascii_uppercase()) {
            return Err(error(
                format!("formula nested deeper than {MAX_DEPTH} levels"),
                p,
            ));
        }
        if b == b'(' {
            self.pos += 1;
            let inner = self.formula_sum(depth + 1)?;
            if self.peek() != Some(b')') {
                return Err(error(
                    "'(' without a closing ')' in the formula".into(),
                    self.pos,
                ));
            }
            self.pos += 1;
            return Ok(Expr::Group(Box::new(inner)));
        }
        if !b.is_ascii_uppercase() {
            return Err(found(line, p));
        }
        let mut end = p;
        while end < line.len() && line[end].is_ascii_uppercase() {
            end += 1;
        }
        let name = &line[p..end];
        self.pos = end;
        if name == b"PI" {
            return Ok(Expr::Pi(p, end));
        }
        if !FORMULA_FUNCTIONS.iter().any(|f| f.as_bytes() == name) {
            return Err(error(
                format!(
                    "unknown function {} in a formula (known: PI {})",
                    String::from_utf8_lossy(name),
                    FORMULA_FUNCTIONS.join(" ")
                ),
                p,
            ));
        }
        let argument = self.formula_unary(depth + 1)?;
        let settled = matches!(argument, Expr::Group(_))
            || !matches!(self.peek(), Some(b'*' | b'/' | b'%' | b'^'));
        Ok(Expr::Function((p, end), Box::new(argument), settled))
    }
}

impl<B: Build> TreeReader<'_, B> {
    fn peek(&mut self) -> Option<u8> {
        self.pos = skip_blanks(self.line, self.pos);
        self.line.get(self.pos).copied()
    }

    fn sum(&mut self, depth: usize) -> Result<B::Node, LexError> {
        let mut left = self.product(depth)?;
        loop {
            match self.peek() {
                Some(op @ (b'+' | b'-')) => {
                    self.pos += 1;
                    let right = self.product(depth)?;
                    left = self.build.binary(op, left, right);
                }
                // the macro dialects' word operators and ',' between arguments, inside
                // brackets: no length arithmetic (the tree marks them 'w')
                Some(c) if depth > 0 && (c == b',' || c.is_ascii_alphabetic()) => {
                    let end = if c == b',' {
                        self.pos + 1
                    } else {
                        let mut e = self.pos;
                        while e < self.line.len() && self.line[e].is_ascii_alphabetic() {
                            e += 1;
                        }
                        // the scanner has read the function names: any of 2 to 6 letters
                        let function = |name: &[u8]| (2..=6).contains(&name.len());
                        match operator_end(self.line, self.pos, e, &WORD_OPERATORS, true, function)
                        {
                            Some(end) => end,
                            None => return Ok(left),
                        }
                    };
                    self.pos = end;
                    let right = self.product(depth)?;
                    left = self.build.binary(b'w', left, right);
                }
                _ => return Ok(left),
            }
        }
    }

    fn product(&mut self, depth: usize) -> Result<B::Node, LexError> {
        let mut left = self.unary(depth)?;
        while let Some(op @ (b'*' | b'/')) = self.peek() {
            self.pos += 1;
            // ** is a power (LinuxCNC): no length arithmetic either
            let op = if op == b'*' && self.line.get(self.pos) == Some(&b'*') {
                self.pos += 1;
                b'w'
            } else {
                op
            };
            let right = self.unary(depth)?;
            left = self.build.binary(op, left, right);
        }
        Ok(left)
    }

    /// The signs before an atom, the last the innermost: read again from the text, backwards,
    /// rather than kept in a list (one allocation an expression saved; no recursion, so a chain
    /// of thousands of signs does not overflow the stack).
    fn unary(&mut self, depth: usize) -> Result<B::Node, LexError> {
        let first = self.peek().map(|_| self.pos);
        let mut end = None;
        while let Some(b'+' | b'-') = self.peek() {
            self.pos += 1;
            end = Some(self.pos);
        }
        let mut expr = self.atom(depth)?;
        if let (Some(first), Some(end)) = (first, end) {
            for &sign in self.line[first..end].iter().rev() {
                if matches!(sign, b'+' | b'-') {
                    expr = self.build.sign(sign, expr);
                }
            }
        }
        Ok(expr)
    }

    fn atom(&mut self, depth: usize) -> Result<B::Node, LexError> {
        let Some(b) = self.peek() else {
            return Err(error("expression ends without an operand".into(), self.pos));
        };
        let p = self.pos;
        let line = self.line;
        if let Some(end) = number_end(line, p) {
            self.pos = end;
            return Ok(self.build.number(p, end));
        }
        if matches!(b, b'P' | b'Q' | b'R' | b'#') && line.get(p + 1).is_some_and(u8::is_ascii_digit)
        {
            self.pos = digits_end(line, p + 1);
            // `#30003.078`, a Haas NGC parameter element, which only a Haas dialect's reader
            // lets through (`Syntax::parameter_elements`): one parameter, whose value no
            // constant gives
            if b == b'#' && variable_with_decimals(line, p, self.pos).is_some() {
                self.pos = digits_end(line, self.pos + 1);
            }
            return Ok(self.build.param(p, self.pos));
        }
        if b == b'#' {
            // #<name> (LinuxCNC), #[expr] and ##n (a parameter chosen by a value)
            let q = skip_blanks(line, p + 1);
            match line.get(q) {
                Some(b'<') => {
                    let close = line[q..].iter().position(|&c| c == b'>').ok_or_else(|| {
                        error("named parameter '#<' without its closing '>'".into(), p)
                    })?;
                    self.pos = q + close + 1;
                    return Ok(self.build.param(p, self.pos));
                }
                Some(b'[' | b'#') => {
                    if depth >= MAX_DEPTH {
                        return Err(error(
                            format!("expression nested deeper than {MAX_DEPTH} levels"),
                            p,
                        ));
                    }
                    self.pos = q;
                    let chosen = self.atom(depth + 1)?;
                    return Ok(self.build.call(chosen));
                }
                // `# 1` (a blank the scan let through: `Syntax` above)
                Some(d) if d.is_ascii_digit() => {
                    self.pos = digits_end(line, q);
                    return Ok(self.build.param(p, self.pos));
                }
                _ => return Err(found(line, p)),
            }
        }
        let call = b.is_ascii_alphabetic();
        if call {
            while self.pos < line.len() && line[self.pos].is_ascii_alphabetic() {
                self.pos += 1;
            }
            if !(2..=6).contains(&(self.pos - p)) {
                return Err(found(line, p));
            }
        }
        if self.peek() != Some(b'[') || depth >= MAX_DEPTH {
            return Err(found(line, p));
        }
        self.pos += 1;
        let inner = self.sum(depth + 1)?;
        if self.peek() != Some(b']') {
            let at = skip_blanks(line, self.pos);
            return Err(error(unclosed(line, at), at));
        }
        self.pos += 1;
        Ok(if call { self.build.call(inner) } else { inner })
    }
}

/// The value of a HEIDENHAIN formula's tree (read by [`formula_tree`] from `line`), given the
/// known value of a parameter by its text (`Q1`, `QL3`); None where the checker cannot know it:
/// a parameter without a known value, a division by zero, a function outside its domain, an
/// order of operations the manuals do not settle (`2^3^2`, `-2^2`, `SQ 2 * 3`, a power beside
/// `*`, `/` or `%`), and a step where the last bit of the TNC's binary arithmetic decides
/// (below).
///
/// `+`, `-` and `*` are exact, as `formats/expr.py` evaluates them; `/`, `%`, `^` and the
/// functions are computed as the TNC computes them, in IEEE 754 binary floating point (its
/// manuals, "Programming notes"), the result taken to 15 significant digits. Angles are in
/// degrees. Those 15 digits and the exact `+ - *` may differ from the control's binary result
/// in its last bit; where that bit decides a step -- INT, FRAC, SGN or `%` at an argument
/// within 1e-9 of a whole number, of 0, or of a multiple of the divisor (`INT (0.3 / 0.1)` is 2
/// on the control) -- or TAN at an odd multiple of 90, the value is unknown. The tree is walked with a stack of its own (post-order), not by recursion: a chain
/// of thousands of terms is a tree as deep.
pub fn formula_value(e: &Expr, line: &[u8], param: &dyn Fn(&[u8]) -> Option<Dec>) -> Option<Dec> {
    enum Task<'e> {
        Visit(&'e Expr),
        Apply(&'e Expr),
    }
    let mut tasks = vec![Task::Visit(e)];
    let mut values: Vec<Option<Dec>> = Vec::new();
    while let Some(task) = tasks.pop() {
        match task {
            Task::Visit(e) => match e {
                Expr::Number(a, b) => {
                    values.push(std::str::from_utf8(&line[*a..*b]).ok().and_then(Dec::parse))
                }
                // a Sinumerik variable by its name, as a parameter by its text
                Expr::Param(a, b) | Expr::Name(a, b) => values.push(param(&line[*a..*b])),
                Expr::Pi(..) => values.push(from_f64(std::f64::consts::PI)),
                // SIN(30), POT(R1): a Sinumerik function the manual lists, of one argument
                Expr::Apply(_, args, false) if args.len() == 1 => {
                    tasks.push(Task::Apply(e));
                    tasks.push(Task::Visit(&args[0]));
                }
                Expr::Text(..) | Expr::Operator(..) | Expr::Not(..) | Expr::Apply(..) => {
                    values.push(None)
                }
                // 2^3^2 and -2^2: which is done first the manuals do not say
                Expr::Binary(b'^', l, r) if !(simple(l) && simple(r)) => values.push(None),
                // 2 * 3^2: nor whether a power goes before a product (only before a sum)
                Expr::Binary(b'*' | b'/' | b'%', l, r) if is_power(l) || is_power(r) => {
                    values.push(None)
                }
                Expr::Function(_, _, false) | Expr::Call(_) => values.push(None),
                Expr::Binary(_, l, r) => {
                    tasks.push(Task::Apply(e));
                    tasks.push(Task::Visit(r));
                    tasks.push(Task::Visit(l));
                }
                Expr::Sign(_, inner) | Expr::Group(inner) | Expr::Function(_, inner, _) => {
                    tasks.push(Task::Apply(e));
                    tasks.push(Task::Visit(inner));
                }
            },
            Task::Apply(e) => {
                let value = if let Expr::Binary(op, ..) = e {
                    let b = values.pop().flatten();
                    let a = values.pop().flatten();
                    a.zip(b).and_then(|(a, b)| binary(*op, a, b))
                } else {
                    let x = values.pop().flatten();
                    x.and_then(|x| match e {
                        Expr::Sign(b'-', _) => Some(-x),
                        Expr::Function(name, ..) => function(&line[name.0..name.1], x),
                        Expr::Apply(name, ..) => sinumerik_function(&line[name.0..name.1], x),
                        _ => Some(x),
                    })
                };
                values.push(value);
            }
        }
    }
    values.pop().flatten()
}

/// The value of a Sinumerik expression's tree (read by [`sinumerik_prefix`] from `line`), by
/// the evaluator of the HEIDENHAIN formulas: `+ - *` exact, `/` and the functions SIN COS TAN
/// ASIN ACOS SQRT ABS POT (the square) TRUNC ROUND LN EXP in binary floating point to 15
/// significant digits, angles in degrees. `param` gives the known value of an R parameter or a
/// variable by its text (`R1`, `_X`). None for what the checker cannot know: an R parameter or
/// variable without a known value, an element or system variable (`_A[1]`, `$AA_IM[X]`), a
/// string, a user function, a comparison or logic operation, and what the sources leave open:
/// `DIV` and `MOD` (whole-number or not for a REAL operand), `ATAN2` (which argument is the
/// ordinate), `ROUND` of a half, a number in `EX` notation.
pub fn sinumerik_value(e: &Expr, line: &[u8], param: &dyn Fn(&[u8]) -> Option<Dec>) -> Option<Dec> {
    formula_value(e, line, param)
}

fn is_power(e: &Expr) -> bool {
    matches!(e, Expr::Binary(b'^', ..))
}

/// Whether `x` is within 1e-9 (relative beyond 1) of `to`: where a step function's value
/// turns on the last bit of the control's arithmetic.
fn near(x: f64, to: f64) -> bool {
    (x - to).abs() <= 1e-9 * x.abs().max(1.0)
}

/// Whether `e` is an operand a power may take without the order of operations in question.
fn simple(e: &Expr) -> bool {
    matches!(
        e,
        Expr::Number(..) | Expr::Param(..) | Expr::Pi(..) | Expr::Group(_)
    )
}

fn binary(op: u8, a: Dec, b: Dec) -> Option<Dec> {
    match op {
        b'+' => a.checked_add(b),
        b'-' => a.checked_add(-b),
        b'*' => a.checked_mul(b),
        b'/' if b.is_zero() => None,
        b'/' => from_f64(a.to_f64() / b.to_f64()),
        // 400 % 360 is 40; the manuals show no negative operand
        b'%' if b.is_zero() || a < Dec::ZERO || b < Dec::ZERO => None,
        b'%' => {
            let (a, b) = (a.to_f64(), b.to_f64());
            let r = a % b;
            if near(r, 0.0) || near(r, b) {
                return None;
            }
            from_f64(r)
        }
        b'^' => from_f64(a.to_f64().powf(b.to_f64())),
        _ => None,
    }
}

/// A formula function of `x` (angles in degrees).
fn function(name: &[u8], x: Dec) -> Option<Dec> {
    let x = x.to_f64();
    let y = match name {
        b"SIN" => x.to_radians().sin(),
        b"COS" => x.to_radians().cos(),
        // (the tangent of 90 is a rounding artefact of the conversion to radians)
        b"TAN" if near((x / 90.0).round(), x / 90.0) && (x / 90.0).round() % 2.0 != 0.0 => {
            return None
        }
        b"TAN" => x.to_radians().tan(),
        b"ASIN" => x.asin().to_degrees(),
        b"ACOS" => x.acos().to_degrees(),
        b"ATAN" => x.atan().to_degrees(),
        b"SQ" => x * x,
        b"SQRT" => x.sqrt(),
        b"LN" => x.ln(),
        b"LOG" => x.log10(),
        b"EXP" => x.exp(),
        b"NEG" => -x,
        b"INT" | b"FRAC" if near(x, x.round()) => return None,
        b"INT" => x.trunc(),
        b"ABS" => x.abs(),
        b"FRAC" => x.fract(),
        // 1 above 0; below, the TNC 410 manual gives 0 and the newer ones -1: unknown
        b"SGN" if x < 0.0 || near(x, 0.0) => return None,
        b"SGN" => 1.0,
        _ => return None,
    };
    from_f64(y)
}

/// The value of the Sinumerik function `name` (any case) of `x`, for the functions the manual
/// lists but ATAN2 (which argument is the ordinate, and the range of its angle, the sources do
/// not say); None for the others (user functions, MINVAL ...).
fn sinumerik_function(name: &[u8], x: Dec) -> Option<Dec> {
    let name = name.to_ascii_uppercase();
    let heidenhain: &[u8] = match name.as_slice() {
        b"SIN" | b"COS" | b"TAN" | b"ASIN" | b"ACOS" | b"SQRT" | b"ABS" | b"LN" | b"EXP" => &name,
        b"POT" => b"SQ",
        b"TRUNC" => b"INT",
        b"ROUND" => {
            // "round to an integer": which way a half goes the manual does not say (nor, near
            // one, the last bit of the control's binary arithmetic)
            let x = x.to_f64();
            return if near(x.fract().abs(), 0.5) {
                None
            } else {
                from_f64(x.round())
            };
        }
        _ => return None,
    };
    function(heidenhain, x)
}

/// `x` to 15 significant digits (the digits a binary double holds for any decimal, so that
/// `SIN 30` is 0.5, not 0.49999999999999994), trailing zeros left out; None for a value that
/// is not finite.
fn from_f64(x: f64) -> Option<Dec> {
    if !x.is_finite() {
        return None;
    }
    let d = Dec::parse(&format!("{x:.14e}"))?.normalized();
    Some(if d.mantissa == 0 { Dec::ZERO } else { d })
}

/// The number terms and the parameters of a linear expression -- sums and differences of
/// numbers and parameters, a parameter times or over a pure number -- or None for any other
/// (`SIN[R1]`, `R1 * R2`). `105 + R9` gives the number 105 and R9; in `2 * R9 - 3` the factor 2
/// is no term (it scales a length and stays as it is), 3 is.
pub fn linear(expr: &Expr) -> Option<(Vec<Span>, Vec<Span>)> {
    let mut numbers = Vec::new();
    let mut params = Vec::new();
    walk(expr, &mut numbers, &mut params).then_some((numbers, params))
}

fn walk(e: &Expr, numbers: &mut Vec<(usize, usize)>, params: &mut Vec<(usize, usize)>) -> bool {
    match e {
        Expr::Number(a, b) => {
            numbers.push((*a, *b));
            true
        }
        Expr::Param(a, b) => {
            params.push((*a, *b));
            true
        }
        Expr::Sign(_, inner) | Expr::Group(inner) => walk(inner, numbers, params),
        Expr::Name(..) | Expr::Text(..) | Expr::Operator(..) | Expr::Not(..) | Expr::Apply(..) => {
            false
        }
        Expr::Binary(b'+' | b'-', l, r) => walk(l, numbers, params) && walk(r, numbers, params),
        Expr::Binary(op @ (b'*' | b'/'), l, r) => match (constant(l), constant(r)) {
            (false, true) => walk(l, numbers, params),
            (true, false) if *op == b'*' => walk(r, numbers, params),
            _ => false,
        },
        Expr::Binary(..) => false, // a word operator, a power, an argument list
        Expr::Call(_) | Expr::Pi(..) | Expr::Function(..) => false,
    }
}

fn constant(e: &Expr) -> bool {
    match e {
        Expr::Number(..) => true,
        Expr::Param(..) | Expr::Call(_) | Expr::Pi(..) | Expr::Function(..) => false,
        Expr::Name(..) | Expr::Text(..) | Expr::Not(..) | Expr::Apply(..) => false,
        Expr::Sign(_, inner) | Expr::Group(inner) => constant(inner),
        Expr::Binary(_, l, r) | Expr::Operator(_, l, r) => constant(l) && constant(r),
    }
}

/// Every parameter an expression reads, in order.
pub fn parameters(e: &Expr, out: &mut Vec<(usize, usize)>) {
    match e {
        Expr::Param(a, b) => out.push((*a, *b)),
        Expr::Number(..) | Expr::Pi(..) | Expr::Name(..) | Expr::Text(..) => {}
        Expr::Sign(_, inner)
        | Expr::Call(inner)
        | Expr::Group(inner)
        | Expr::Not(_, inner)
        | Expr::Function(_, inner, _) => parameters(inner, out),
        Expr::Binary(_, l, r) | Expr::Operator(_, l, r) => {
            parameters(l, out);
            parameters(r, out);
        }
        Expr::Apply(_, args, _) => {
            for arg in args {
                parameters(arg, out);
            }
        }
    }
}

/// A Sinumerik expression's tree in a canonical form, each operation in parentheses with its
/// operator first (`(+ R1 (* 2 3))`, `SIN(30)`, `$AA_IM[X]`), names and numbers as written and
/// `( )` groups left out: what the property tests compare with the lark reference grammar's
/// tree, so that a difference in the operators' priority shows.
pub fn sinumerik_form(e: &Expr, line: &[u8]) -> String {
    let text = |a: usize, b: usize| String::from_utf8_lossy(&line[a..b]).into_owned();
    match e {
        Expr::Number(a, b) | Expr::Param(a, b) | Expr::Name(a, b) | Expr::Text(a, b) => {
            text(*a, *b)
        }
        Expr::Pi(a, b) => text(*a, *b),
        Expr::Group(inner) => sinumerik_form(inner, line),
        Expr::Sign(op, inner) => format!("({} {})", *op as char, sinumerik_form(inner, line)),
        Expr::Not(op, inner) => format!("({op} {})", sinumerik_form(inner, line)),
        Expr::Binary(op, l, r) => format!(
            "({} {} {})",
            *op as char,
            sinumerik_form(l, line),
            sinumerik_form(r, line)
        ),
        Expr::Operator(op, l, r) => {
            format!(
                "({op} {} {})",
                sinumerik_form(l, line),
                sinumerik_form(r, line)
            )
        }
        Expr::Apply((a, b), args, element) => {
            let args: Vec<String> = args.iter().map(|x| sinumerik_form(x, line)).collect();
            let (open, close) = if *element { ('[', ']') } else { ('(', ')') };
            format!(
                "{}{open}{}{close}",
                text(*a, *b).to_ascii_uppercase(),
                args.join(" ")
            )
        }
        Expr::Call(inner) | Expr::Function(_, inner, _) => sinumerik_form(inner, line),
    }
}

/// The `=` of an assignment token whose target is a parameter chosen by a value (`#[#1+1]=5`,
/// `##1=7`): the first `=` outside brackets.
pub(crate) fn indirect_target(token: &[u8]) -> Option<usize> {
    if !matches!(token, [b'#', b'[' | b'#', ..]) {
        return None;
    }
    assignment_outside_brackets(token, false)
}

/// The first `=` of `token` outside its brackets; with `comparisons`, not one of `==` (a
/// SINUMERIK comparison inside the value).
pub(crate) fn assignment_outside_brackets(token: &[u8], comparisons: bool) -> Option<usize> {
    let mut depth = 0usize;
    for (i, &c) in token.iter().enumerate() {
        match c {
            b'[' => depth += 1,
            b']' => depth = depth.saturating_sub(1),
            b'=' if depth == 0 && !(comparisons && token.get(i + 1) == Some(&b'=')) => {
                return Some(i)
            }
            _ => {}
        }
    }
    None
}

/// At `i` of `text`, an `R` that begins no longer name (`R1`, not `FR1`): how many digits
/// follow it, and whether they make a SINUMERIK R parameter (`R1`, not `R1A` or a bare `R`);
/// None where no such `R` begins there. The parameter analysis and the converter read R
/// parameters by it.
pub(crate) fn r_parameter_at(text: &[u8], i: usize) -> Option<(usize, bool)> {
    let starts = text.get(i)?.eq_ignore_ascii_case(&b'R')
        && (i == 0 || !(text[i - 1].is_ascii_alphanumeric() || text[i - 1] == b'_'));
    if !starts {
        return None;
    }
    let digits = text[i + 1..]
        .iter()
        .take_while(|c| c.is_ascii_digit())
        .count();
    let after = text.get(i + 1 + digits);
    Some((
        digits,
        digits > 0 && !after.is_some_and(|c| c.is_ascii_alphabetic() || *c == b'_'),
    ))
}

/// The spans of a statement's top-level bracket groups, brackets included (the expression
/// reader takes word operators only inside brackets), and the text outside them.
pub fn bracket_groups(text: &[u8]) -> (Vec<(usize, usize)>, Vec<u8>) {
    let mut groups = Vec::new();
    let mut rest = Vec::new();
    let mut depth = 0usize;
    let mut open = 0;
    for (i, &c) in text.iter().enumerate() {
        match c {
            b'[' => {
                if depth == 0 {
                    open = i;
                }
                depth += 1;
            }
            b']' if depth > 0 => {
                depth -= 1;
                if depth == 0 {
                    groups.push((open, i + 1));
                }
            }
            _ if depth == 0 => rest.push(c),
            _ => {}
        }
    }
    (groups, rest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_spaced_number_ends_after_its_last_digit_or_point() {
        let end = |t: &str| spaced_number_end(t.as_bytes(), 0);
        assert_eq!(end("1 0 Y2"), Some(3));
        assert_eq!(end("1 . 5]"), Some(5));
        assert_eq!(end("12."), Some(3));
        assert_eq!(end(". 5 "), Some(3));
        assert_eq!(end(". Y"), None);
        assert_eq!(end("Y1"), None);
        assert_eq!(spaced_digits_end(b"1 2 + 3", 0), 3);
        assert_eq!(spaced_digits_end(b"1 .5", 0), 1);
    }

    fn siemens(text: &str) -> Result<String, String> {
        sinumerik_tree(text.as_bytes())
            .map(|e| sinumerik_form(&e, text.as_bytes()))
            .map_err(|e| format!("{}@{}", e.message, e.offset))
    }

    /// The value of a Sinumerik expression with R1 = 5 known and every other parameter not.
    fn siemens_value(text: &str) -> Option<String> {
        let tree = sinumerik_tree(text.as_bytes()).unwrap_or_else(|e| panic!("{text}: {e:?}"));
        let known = |p: &[u8]| p.eq_ignore_ascii_case(b"R1").then(|| Dec::from_int(5));
        sinumerik_value(&tree, text.as_bytes(), &known).map(|v| v.to_string())
    }

    #[test]
    fn sinumerik_expressions_read_with_the_manuals_priorities() {
        for (text, form) in [
            ("R1+5", "(+ R1 5)"),
            ("R2*SIN(30)", "(* R2 SIN(30))"),
            ("1+2*3-4/5", "(- (+ 1 (* 2 3)) (/ 4 5))"),
            ("7 DIV 2 MOD 3", "(MOD (DIV 7 2) 3)"),
            // comparisons bind last: the manuals bracket the comparisons they join
            ("R1>5 AND R2<3", "(< (> R1 (AND 5 R2)) 3)"),
            ("(R1==2) AND (R2<>3)", "(AND (== R1 2) (<> R2 3))"),
            (
                "(R10<50) AND ($AA_IM[X]>=17.5)",
                "(AND (< R10 50) (>= $AA_IM[X] 17.5))",
            ),
            ("NOT R10", "(NOT R10)"),
            ("a OR b XOR c AND d", "(OR a (XOR b (AND c d)))"),
            (
                "1 B_OR 2 B_XOR 3 B_AND 4 + 5",
                "(B_OR 1 (B_XOR 2 (B_AND 3 (+ 4 5))))",
            ),
            ("B_NOT -R1 * 2", "(* (B_NOT (- R1)) 2)"),
            (r#""A" << "B" == "AB""#, r#"(== (<< "A" "B") "AB")"#),
            (
                "ATAN2(R1, 2) + _A[1,2] + f()",
                "(+ (+ ATAN2(R1 2) _A[1 2]) F())",
            ),
            ("10EX-5 <= r3", "(<= 10EX-5 r3)"),
            ("_R1 + R1_A + R12", "(+ (+ _R1 R1_A) R12)"),
            ("'H1F' B_AND 'b101'", "(B_AND 'H1F' 'b101')"),
        ] {
            assert_eq!(siemens(text).as_deref(), Ok(form), "{text}");
        }
        let mut params = Vec::new();
        parameters(
            &sinumerik_tree(b"R1 + _X * SIN(R22) + $A[R3]").unwrap(),
            &mut params,
        );
        assert_eq!(params, [(0, 2), (14, 17), (24, 26)]);
        // where an expression ends: at the first token that cannot continue it
        assert_eq!(sinumerik_prefix(b"X=R1+5 Y0", 2).unwrap().1, 6);
        assert_eq!(sinumerik_prefix(b"R1>5 GOTOF L1", 0).unwrap().1, 4);
        assert_eq!(sinumerik_prefix(b"R1 = 5", 0).unwrap().1, 2); // '=' assigns, '==' compares
    }

    #[test]
    fn sinumerik_values_by_the_formula_evaluator() {
        for (text, value) in [
            ("5*2", "10"),
            ("R1*2 + 0.5", "10.5"),
            ("r1/4", "1.25"),
            ("SIN(30)*R1", "2.5"),
            ("POT(3) + TRUNC(-2.7)", "7"),
            ("ROUND(2.4) + round(-2.6)", "-1"),
            ("SQRT(16) - ABS(-2) + COS(60)", "2.5"),
            ("ASIN(0.5) + ACOS(0.5) + TAN(45)", "91"),
            ("LN(1) + EXP(0)", "1"),
            ("-(R1 + 1) * 2", "-12"),
            ("10 / 3", "3.33333333333333"),
        ] {
            assert_eq!(siemens_value(text).as_deref(), Some(value), "{text}");
        }
        // unknown: what the checker cannot know, and what the sources leave open
        for text in [
            "R2 + 1",
            "_X * 2",
            "$AA_IM[X]",
            "MINVAL(1, 2)",
            "7 DIV 2",
            "7 MOD 2",
            "ATAN2(1, 1)",
            "ROUND(2.5)",
            // a step the control's binary arithmetic decides: TRUNC(0.3/0.1) is 2 there
            "TRUNC(0.3 / 0.1)",
            "TRUNC(3)",
            "ROUND(0.15 * 10)",
            "TAN(90)",
            "1EX2",
            "NOT 1",
            "R1 == 5",
            "\"A\"",
            "1 / 0",
            "SQRT(-1)",
        ] {
            assert_eq!(siemens_value(text), None, "{text}");
        }
    }

    /// A lone number is read as the descent through every level of operators reads it: the
    /// same tree and end, or the same error, whatever follows it.
    #[test]
    fn a_lone_sinumerik_number_reads_as_the_descent_does() {
        let texts = [
            "0",
            "0 ",
            "0 Y=5",
            "12.5 OR 1",
            "1 or 2",
            "1 ORX",
            "1 AND R1",
            "1+2",
            "1 - 2",
            "1 == 2",
            "1<>2",
            "1<<2",
            "1 <= 2",
            "2*3",
            "6 / 2",
            "10EX-5",
            "10EX-5 X1",
            "1.E",
            ".5 DIV 2",
            "3 MOD 2 X1",
            "0 B_AND 1",
            "5 B_XOR 1",
            ". ",
            ".",
            "1.",
            "1. ;c",
            "7 TURN=1",
            "7)",
            "7]",
            "8 $A",
            "9 _X",
            "1 NOT",
            "1 ==",
            "1 +",
        ];
        for text in texts {
            let line = text.as_bytes();
            let mut descent = TreeReader::new(line, 0, Trees);
            let full = descent.siemens_level(0, 0).map(|e| (e, descent.pos));
            let mut reader = TreeReader::new(line, 0, Trees);
            let read = match reader.siemens_lone_number() {
                Some(e) => Ok((e, reader.pos)),
                None => {
                    let mut again = TreeReader::new(line, 0, Trees);
                    again.siemens_level(0, 0).map(|e| (e, again.pos))
                }
            };
            assert_eq!(read, full, "{text}");
            assert_eq!(
                sinumerik_prefix(line, 0),
                full.map(|(e, pos)| {
                    let mut end = pos;
                    while end > 0 && blank(line[end - 1]) {
                        end -= 1;
                    }
                    (e, end)
                }),
                "{text}"
            );
        }
        let lone = |t: &str| TreeReader::new(t.as_bytes(), 0, Trees).siemens_lone_number();
        assert!(lone("0 Y=5").is_some() && lone("1 OR 2").is_none() && lone("R1").is_none());
    }

    #[test]
    fn malformed_sinumerik_expressions_are_located() {
        assert_eq!(
            siemens("(R1+2"),
            Err("'(' without a closing ')' in the expression@5".into())
        );
        assert_eq!(
            siemens("SIN(30"),
            Err("'(' without a closing ')' in the expression@6".into())
        );
        assert_eq!(
            siemens("5 +"),
            Err("expression ends without an operand@3".into())
        );
        assert_eq!(
            siemens("R1 + AND"),
            Err("expected a value in the expression, found the operator AND@5".into())
        );
        assert!(siemens("_A[]").unwrap_err().ends_with("found ']'@3"));
        assert!(siemens("\"ABC").unwrap_err().contains("closing '\"'@0"));
        assert!(siemens("R1 R2").unwrap_err().ends_with("found 'R'@3"));
        assert!(siemens("#1").unwrap_err().contains("found '#'@0"));
        assert!(siemens("'H1G'").unwrap_err().ends_with("binary digits@0"));
        // text outside ASCII in a string is read (the checker says so, TG127); a control
        // character is not
        assert!(sinumerik_tree("\"\u{e9}\"".as_bytes()).is_ok());
        let e = sinumerik_tree(b"\"A\x07\"").unwrap_err();
        assert_eq!((e.kind, e.offset), (ErrorKind::Character, 2));
        let deep = "(".repeat(MAX_DEPTH + 1) + "1" + &")".repeat(MAX_DEPTH + 1);
        assert!(siemens(&deep).unwrap_err().contains("nested deeper"));
        let calls = "SIN(".repeat(MAX_DEPTH + 1) + "1" + &")".repeat(MAX_DEPTH + 1);
        assert!(siemens(&calls).unwrap_err().contains("nested deeper"));
        let long = "1".to_string() + &"+1".repeat(2_000);
        let tree = sinumerik_tree(long.as_bytes()).unwrap();
        // (the evaluator walks a tree of its own stack: a chain of 2,000 terms has its value)
        assert_eq!(
            sinumerik_value(&tree, long.as_bytes(), &|_| None),
            Some(Dec::from_int(2001))
        );
    }

    fn linear_text(text: &str) -> Option<(Vec<String>, Vec<String>)> {
        let tree = tree(text.as_bytes()).unwrap();
        let piece = |&(a, b): &(usize, usize)| text[a..b].to_string();
        linear(&tree).map(|(n, p)| (n.iter().map(piece).collect(), p.iter().map(piece).collect()))
    }

    /// `terms` gives what `linear` and `parameters` give of `tree`, or the same error, on the
    /// tests' expressions and on 20,000 made of numbers, parameters, operators, brackets,
    /// functions, word operators and blanks in any order.
    #[test]
    fn terms_are_the_trees_linear_terms_and_parameters() {
        let pieces = [
            "1", "2.5", "-", "+", "*", "/", "**", "[", "]", "#1", "#<a>", "#< B >", "#<_g>", "R2",
            "#[", "##", "SIN[", "ATAN[", ",", " AND ", " GT ", " ", ".5", "3.",
        ];
        let mut texts: Vec<String> = [
            "105 + R9",
            "2 * R9 - 3",
            "R9 / 2 + [3]",
            "SIN[R1]",
            "R1 * R2",
            "2 / R1",
            "R1*[2*3]",
            "[2*3]*R1-4",
            "-[-#1]*-2+-.5",
            "#<xscale>*-56.128",
            "2*3",
            "#1*2*3",
            "[#1+2]*3/4-[5]",
            "#[#1+1] * 2",
            "[[#1 GT 2] AND [#2 LT 3]]",
        ]
        .map(String::from)
        .into();
        // operands and operators in turn (most of them read), or any pieces in any order
        let operands = [
            "1", "2.5", "#1", "#<a>", "R2", "[#1*2]", "-3", "SIN[#2]", "#[1]", "[4]",
        ];
        let operators = ["+", "-", "*", "/", "**", " AND "];
        let mut seed: u64 = 35;
        let mut next = |n: usize| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) as usize % n
        };
        for i in 0..20_000 {
            let mut text = String::new();
            for k in 0..1 + next(12) {
                text.push_str(match (i % 2, k % 2) {
                    (0, 0) => operands[next(operands.len())],
                    (0, _) => operators[next(operators.len())],
                    _ => pieces[next(pieces.len())],
                });
            }
            texts.push(text);
        }
        let (mut read, mut linears) = (0, 0);
        for text in &texts {
            let bytes = text.as_bytes();
            match (tree(bytes), terms(bytes)) {
                (Ok(t), Ok(got)) => {
                    let mut params = Vec::new();
                    parameters(&t, &mut params);
                    let want = linear(&t).map(|(numbers, _)| numbers);
                    assert_eq!(got.numbers(), want.as_deref(), "{text}");
                    assert_eq!(got.params, params, "{text}");
                    if let Some((_, linear_params)) = linear(&t) {
                        assert_eq!(linear_params, got.params, "{text}");
                    }
                    read += 1;
                    linears += usize::from(got.linear);
                }
                (Err(a), Err(b)) => {
                    assert_eq!((a.message, a.offset), (b.message, b.offset), "{text}")
                }
                (a, b) => panic!("{text}: {a:?} / {b:?}"),
            }
        }
        assert!(read > 3_000 && linears > 1_000, "{read} {linears}");
    }

    /// The terms read by shape ([`Shapes`], what [`terms_of`] gives) are the reader's own: on
    /// 30,000 expressions of 300 templates, each one's numbers written anew each time (of any
    /// length, with a point or not), among names with digits, blanks and unreadable ones.
    #[test]
    fn terms_by_shape_are_the_readers_terms() {
        let pieces = [
            "N", "N", "N", "-", "+", "*", "/", "**", "[", "]", "#1", "#<a>", "#< b 2 >", "R2",
            "#[", "##", "SIN[", "ATAN[", ",", " AND ", " ", "N.", "#N", "RN", "N ", " N", "1E",
            "=", "(", "\u{1}",
        ];
        let mut seed: u64 = 7;
        let mut next = |n: usize| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) as usize % n
        };
        // operands and operators in turn (most of them read), or any pieces in any order
        let operands = [
            "N", "N", "#1", "#<a1>", "R2", "[#1*N]", "-N", "SIN[#2]", "#[N]", "[N]",
        ];
        let operators = ["+", "-", "*", "/", "**", " AND ", " * ", "+ "];
        let shapes: Vec<Vec<&str>> = (0..300)
            .map(|i| {
                (0..1 + next(10))
                    .map(|k| match (i % 2, k % 2) {
                        (0, 0) => operands[next(operands.len())],
                        (0, _) => operators[next(operators.len())],
                        _ => pieces[next(pieces.len())],
                    })
                    .collect()
            })
            .collect();
        let mut shared = Terms::default();
        let (mut read, mut linears) = (0, 0);
        for _ in 0..30_000 {
            let mut text = String::new();
            for piece in &shapes[next(shapes.len())] {
                for c in piece.chars() {
                    if c != 'N' {
                        text.push(c);
                        continue;
                    }
                    let digits = |n: usize| "1234567890".chars().cycle().skip(n).take(n + 1);
                    match next(4) {
                        0 => text.extend(digits(next(12))),
                        1 => text.extend(digits(next(5)).chain(".".chars()).chain(digits(next(5)))),
                        2 => text.extend(".".chars().chain(digits(next(5)))),
                        _ => text.extend(digits(next(3)).chain(".".chars())),
                    }
                }
            }
            let bytes = text.as_bytes();
            match (terms_of(bytes, Family::LinuxCnc, &mut shared), terms(bytes)) {
                (Ok(()), Ok(want)) => {
                    assert_eq!(shared, want, "{text}");
                    read += 1;
                    linears += usize::from(want.linear);
                }
                (Err(a), Err(b)) => {
                    assert_eq!((a.message, a.offset), (b.message, b.offset), "{text}")
                }
                (a, b) => panic!("{text}: {a:?} / {b:?}"),
            }
        }
        assert!(read > 3_000 && linears > 1_000, "{read} {linears}");
        // (a template's numbers of three forms make up to 3^n shapes of it)
        let kept = shared.shapes.as_ref().map_or(0, |s| s.read.len());
        assert!(kept > 0 && kept * 4 < read, "{kept} {read}");
    }

    #[test]
    fn linear_terms_of_lengths() {
        let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
        assert_eq!(linear_text("105 + R9"), Some((s(&["105"]), s(&["R9"]))));
        assert_eq!(linear_text("2 * R9 - 3"), Some((s(&["3"]), s(&["R9"]))));
        assert_eq!(linear_text("R9 / 2 + [3]"), Some((s(&["3"]), s(&["R9"]))));
        assert_eq!(linear_text("SIN[R1]"), None);
        assert_eq!(linear_text("R1 * R2"), None);
        assert_eq!(linear_text("2 / R1"), None);
    }

    const ALL: Syntax = Syntax {
        brackets: true,
        hash: true,
        star: true,
        macros: false,
        named: false,
        names: false,
        lowercase: false,
        parameter_elements: false,
    };
    const ISO: Syntax = Syntax {
        brackets: false,
        hash: false,
        star: false,
        macros: false,
        named: false,
        names: false,
        lowercase: false,
        parameter_elements: false,
    };
    const MACRO: Syntax = Syntax {
        macros: true,
        ..ALL
    };
    const LINUXCNC: Syntax = Syntax {
        macros: true,
        named: true,
        lowercase: true,
        ..ALL
    };

    fn group(text: &str, syntax: Syntax) -> Result<usize, String> {
        scan_group(text.as_bytes(), 0, syntax).map_err(|e| format!("{}@{}", e.message, e.offset))
    }

    /// Audit 50, B12: Custom Macro B's `# 1` in a word's value is #1, as in `# 1 = 5`; a Haas
    /// NGC alarms on the blank (the address apart from its number); ISO reads no `#`.
    #[test]
    fn a_blank_after_the_hash_of_a_macro_value() {
        for text in ["# 1", "-# 12", "[# 1+1.]", "#  007*2"] {
            assert_eq!(
                scan(text.as_bytes(), 0, MACRO).map_err(|e| e.message),
                Ok(text.len()),
                "{text}"
            );
            assert!(tree(text.as_bytes()).is_ok(), "{text}");
        }
        let ngc = Syntax {
            parameter_elements: true,
            ..MACRO
        };
        let apart = scan(b"-# 1", 0, ngc).unwrap_err();
        assert!(
            apart
                .message
                .starts_with("address # written apart from its number")
                && apart.offset == 2,
            "{apart:?}"
        );
        // `# [1]` is `#[1]` (review 52, F1), the NGC's "written apart" there too; `# #1` (a
        // blank before a parameter choosing the variable) stays unread
        for text in ["# [1]", "-# [1+1]", "[# [2]*2.]"] {
            assert_eq!(
                scan(text.as_bytes(), 0, MACRO).map_err(|e| e.message),
                Ok(text.len()),
                "{text}"
            );
            assert!(tree(text.as_bytes()).is_ok(), "{text}");
        }
        let apart = scan(b"# [1]", 0, ngc).unwrap_err();
        assert!(
            apart
                .message
                .starts_with("address # written apart from its number")
                && apart.offset == 1,
            "{apart:?}"
        );
        assert!(scan(b"# #1", 0, MACRO).is_err());
    }

    #[test]
    fn the_tree_reads_what_the_macro_scanner_reads() {
        // only +, -, and * or / by a number are length arithmetic
        for (text, is_linear) in [
            ("[[#1 GT 2] AND [#2 LT 3]]", false),
            ("#[#1+1] * 2", false),
            ("#<_tool> / 2", true),
            ("ROUND[#1] + ATAN[1,2] + 2**2", false),
            ("atan[1]/[2]", false),
        ] {
            let t = tree(text.as_bytes()).unwrap_or_else(|e| panic!("{text}: {}", e.message));
            assert_eq!(linear(&t).is_some(), is_linear, "{text}");
        }
        let deep = "#".repeat(200) + "1";
        assert!(tree(deep.as_bytes()).is_err());
        assert!(end(&deep, LINUXCNC).is_err());
    }

    #[test]
    fn macro_conditions_and_functions() {
        let cond = "[ #5405 GE 6000 ]";
        assert_eq!(group(cond, MACRO), Ok(cond.len()));
        assert!(group(cond, ALL).is_err()); // no word operators outside the macro dialects
        let and = "[[#1 EQ 0] AND [#2 LT #[#3+1]]]";
        assert_eq!(group(and, MACRO), Ok(and.len()));
        let calls = "[ROUND[#1] + FIX[2.5] * ATAN[1,2] + #1 MOD 3 + 2**2]";
        assert_eq!(group(calls, MACRO), Ok(calls.len()));
        let named = "[#<_tool_dia> / 2 gt #<r>]";
        assert_eq!(group(named, LINUXCNC), Ok(named.len()));
        assert!(group(named, MACRO).is_err());
        assert!(group("[#<x]", LINUXCNC)
            .unwrap_err()
            .contains("closing '>'"));
        assert!(group("[FOO[1]]", MACRO)
            .unwrap_err()
            .contains("unknown function FOO"));
        // LinuxCNC knows its own functions only: rs274 refuses a Fanuc's BCD, POW, ATN
        assert_eq!(group("[exists[#<x>] + fup[1.5]]", LINUXCNC), Ok(25));
        for fanuc in ["[bcd[1]]", "[POW[2,3]]", "[atn[1]]"] {
            assert!(group(&fanuc.to_uppercase(), MACRO).is_ok(), "{fanuc}");
            let e = group(fanuc, LINUXCNC).unwrap_err();
            assert!(e.contains("unknown function"), "{fanuc}: {e}");
        }
        // a word operator is no operator at the top level: "#1 GT" ends after #1
        assert_eq!(end("#1 GT 2", MACRO), Ok(2));
    }

    #[test]
    fn an_operator_glued_to_the_function_after_it_is_read_as_the_control_reads_it() {
        // IF[#20NEFIX[#20]]GOTO700: NE, then FIX[#20] (a Renishaw macro of a Robodrill)
        for text in ["[#20NEFIX[#20]]", "[#1GTABS[#2]]", "[#1EQ#2ANDROUND[#3]]"] {
            assert_eq!(group(text, MACRO), Ok(text.len()), "{text}");
            let t = tree(text.as_bytes());
            assert!(t.is_ok(), "{text}");
        }
        // only before a function: NEFOO[ is no operator, NEX is none either
        assert!(group("[#20NEFOO[#20]]", MACRO).is_err());
        assert!(group("[#20NEX]", MACRO).is_err());
        assert!(group("[#20NEFIX[#20]]", ALL).is_err()); // no word operators there
    }

    #[test]
    fn a_macro_function_with_its_argument_in_parentheses_is_the_programs_error() {
        // `ABS(#26 - #13)`: '(' opens a comment on a FANUC or Haas, so ABS has no argument
        for text in ["ABS(#26 - #13)", "SQRT (#1)", "[1 + round(#2)]"] {
            let e = if text.starts_with('[') {
                group(
                    text,
                    Syntax {
                        lowercase: true,
                        ..MACRO
                    },
                )
            } else {
                end(text, MACRO)
            }
            .unwrap_err();
            assert!(e.contains("takes its argument in brackets"), "{text}: {e}");
            assert!(e.contains("16.3, p. 287"), "{text}: {e}");
        }
        let e = end("ABS(#1)", MACRO).unwrap_err();
        assert!(e.starts_with("function ABS ") && e.ends_with("@0"), "{e}");
        // the argument in brackets reads, as before
        assert_eq!(end("ABS[#26 - #13]", MACRO), Ok(14));
        // no function's name before '(': the error stays the general one
        let e = end("FOO(#1)", MACRO).unwrap_err();
        assert!(e.contains("expected a number or parameter"), "{e}");
        // a '(' where an operand stands: the same reading, the grouping written wrong
        let e = end("#103 - (#101 - 1) * 2", MACRO).unwrap_err();
        assert!(
            e.contains("brackets group an expression") && e.ends_with("@7"),
            "{e}"
        );
        // LinuxCNC and the ISO-like dialects are not Macro B: unchanged
        for syntax in [LINUXCNC, ALL] {
            for text in ["ABS(#1)", "#1 - (#2)"] {
                let e = end(text, syntax).unwrap_err();
                assert!(e.contains("expected a number or parameter"), "{e}");
            }
        }
    }

    fn end(text: &str, syntax: Syntax) -> Result<usize, String> {
        scan(text.as_bytes(), 0, syntax).map_err(|e| format!("{}@{}", e.message, e.offset))
    }

    #[test]
    fn an_expression_ends_at_the_first_token_that_cannot_continue_it() {
        assert_eq!(end("R9 + R15 X2", ISO), Ok(8));
        assert_eq!(end("105+R9", ISO), Ok(6));
        assert_eq!(end("- -5 / 2 Y", ISO), Ok(8));
        assert_eq!(end("[#2 + 3] * 2", ALL), Ok(12));
        assert_eq!(end("SIN[30] + SQRT [4]", ALL), Ok(18));
        assert_eq!(end("2 * 3", ISO), Ok(1)); // "*" is no operator without the dialect
    }

    #[test]
    fn malformed_expressions_are_located() {
        assert_eq!(
            end("5 + ", ISO),
            Err("expression ends without an operand@4".into())
        );
        assert!(end("[1 + 2", ALL)
            .unwrap_err()
            .starts_with("'[' without a closing ']'"));
        assert!(end("FOO[1]", ALL)
            .unwrap_err()
            .starts_with("unknown function FOO"));
        assert!(end("#1", ISO).unwrap_err().contains("found '#'"));
        assert!(end(".", ISO).unwrap_err().contains("found '.'"));
    }

    fn formula(text: &str) -> Result<Expr, String> {
        formula_tree(text.as_bytes(), 0).map_err(|e| format!("{}@{}", e.message, e.offset))
    }

    /// The value of a formula with Q1 = 5 known and every other parameter unknown.
    fn formula_text_value(text: &str) -> Option<String> {
        let tree = formula(text).unwrap_or_else(|e| panic!("{text}: {e}"));
        let known = |p: &[u8]| (p == b"Q1").then(|| Dec::from_int(5));
        formula_value(&tree, text.as_bytes(), &known).map(|v| v.to_string())
    }

    #[test]
    fn heidenhain_formulas_read_as_the_manuals_write_them() {
        // the manuals' examples ("Entering formulas directly", "Rules for formulas")
        for (text, value) in [
            ("5 * 3 + 2 * 10", "35"),
            ("SQ 10 - 3^3", "73"),
            ("400 % 360", "40"),
            ("3^3", "27"),
            ("ASIN 0.5", "30"),
            ("ABS -2.5", "2.5"),
            ("NEG Q1", "-5"),
            ("INT 2.75 + FRAC 2.75", "2.75"),
            ("SGN 3", "1"),
            ("( Q1 + 2 ) * SIN ( 30 )", "3.5"),
            ("10 / 3", "3.33333333333333"),
            ("SQRT ( SQ 3 + SQ 4 )", "5"),
            ("Q1/4", "1.25"),
            ("+Q1 - -1.5", "6.5"),
            ("LOG 1000 + LN 1 + EXP 0", "4"),
            ("(2^3)^2", "64"),
        ] {
            assert_eq!(formula_text_value(text).as_deref(), Some(value), "{text}");
        }
        assert!(formula_text_value("PI")
            .unwrap()
            .starts_with("3.14159265358979"));
        // unknown: a parameter without a value, no value, an order the manuals do not settle
        for text in [
            "Q2 + 1",
            "QL1 * 2",
            "1 / 0",
            "SQRT -1",
            "-400 % 360",
            "2^3^2",
            "-2^2",
            "SQ 2 * 3",
            "SIN 30 ^ 2",
            // which way the control's last bit goes decides these, or the manuals differ
            "INT ( 0.3 / 0.1 )",
            "INT ( ( 0.7 + 0.1 ) * 10 )",
            "FRAC 3",
            "1 % 0.1",
            "6 % 3",
            "SGN -3",
            "SGN 0",
            "TAN 90",
            "TAN -270",
            // a power beside a product: the manuals give it before a sum only
            "2 * 3^2",
            "3^2 / 2",
        ] {
            assert_eq!(formula_text_value(text), None, "{text}");
        }
        // a function's argument in parentheses settles it; after a + it is settled too
        assert_eq!(formula_text_value("SQ (2) * 3").as_deref(), Some("12"));
        assert_eq!(formula_text_value("SQ 2 + 3").as_deref(), Some("7"));
        let mut params = Vec::new();
        parameters(&formula("Q1 + QL12 * SIN QR3").unwrap(), &mut params);
        assert_eq!(params, [(0, 2), (5, 9), (16, 19)]);
    }

    #[test]
    fn malformed_formulas_are_located() {
        assert_eq!(
            formula("( Q1 + 2 * 3"),
            Err("'(' without a closing ')' in the formula@12".into())
        );
        assert!(formula("Q1 + FOO 2")
            .unwrap_err()
            .starts_with("unknown function FOO in a formula (known: PI SIN"));
        assert_eq!(
            formula("5 +"),
            Err("formula ends without an operand@3".into())
        );
        assert!(formula("Q1 Q2").unwrap_err().ends_with("found 'Q'@3"));
        assert!(formula("SINQ1")
            .unwrap_err()
            .contains("unknown function SINQ"));
        assert!(formula("[1]").unwrap_err().contains("found '['@0"));
        assert!(formula("sin 30").is_err()); // upper case only
        let e = formula_tree(b"Q1 = 2 +", 4).unwrap_err();
        assert_eq!((e.offset, e.clause), (8, "HEIDENHAIN formulas"));
        let deep = "(".repeat(MAX_DEPTH + 1) + "1" + &")".repeat(MAX_DEPTH + 1);
        assert!(formula(&deep).unwrap_err().contains("nested deeper"));
        let calls = "SIN ".repeat(MAX_DEPTH + 1) + "1";
        assert!(formula(&calls).unwrap_err().contains("nested deeper"));
    }

    #[test]
    fn a_long_formula_is_read_evaluated_and_dropped_on_a_small_stack() {
        let chain = "1".to_string() + &"+1".repeat(30_000);
        let signs = "-".repeat(60_000) + "1";
        std::thread::Builder::new()
            .stack_size(256 * 1024)
            .spawn(move || {
                for (text, expected) in [(chain, "30001"), (signs, "1")] {
                    let tree = formula_tree(text.as_bytes(), 0).unwrap();
                    let value = formula_value(&tree, text.as_bytes(), &|_| None);
                    assert_eq!(value.map(|v| v.to_string()), Some(expected.into()));
                    let (_, end) = formula_prefix(text.as_bytes(), 0).unwrap();
                    assert_eq!(end, text.len());
                }
            })
            .unwrap()
            .join()
            .unwrap();
    }

    #[test]
    fn nesting_is_bounded() {
        let deep = "[".repeat(MAX_DEPTH + 1) + "1" + &"]".repeat(MAX_DEPTH + 1);
        assert!(end(&deep, ALL).unwrap_err().contains("nested deeper"));
        let ok = "[".repeat(MAX_DEPTH) + "1" + &"]".repeat(MAX_DEPTH);
        assert_eq!(end(&ok, ALL), Ok(ok.len()));
        let long = "1".to_string() + &"+1".repeat(20_000);
        assert_eq!(end(&long, ISO), Ok(long.len()));
    }
}
