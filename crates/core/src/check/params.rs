//! What the checker knows of parameters (no rule of its own): a parameter or variable set to
//! a constant -- `#101 = 250.`, the 6.4.7 form `R11 = 22.2`, LinuxCNC's `#<depth> = 2`, a
//! Sinumerik's `R1=R2*SIN(30)` or `_X_HOME=-365.`, a HEIDENHAIN formula `Q1 = 5 * 2` -- is
//! that value where a word reads it (`F#101` is the feed 250), until it is set otherwise or a
//! jump or call forgets it. A value read from an unknown one is TG141 ([`super::words`]).

use super::{BlockView, Checker};
use crate::decimal::Dec;
use crate::expr;
use crate::lex::{blank, Family};
use crate::rules::Rule;
use crate::statement::{digits_end, formula_right_hand_side, q_parameter, Kind};

impl Checker {
    /// The value of `#n`, `Rn` (`Pn`, `Qn`), `#<name>`, signed or in brackets (`-#n`, `[R1]`),
    /// where the parameter holds a known constant.
    /// Inline: its first look, which answers a CAM program's `[#<yscale>*-3.608]` (two in
    /// every line of one scaling its axes by parameters) where the word is read, the rest
    /// out of line ([`Checker::constant_of`]).
    #[inline]
    pub(super) fn constant(&self, expression: &[u8]) -> Option<Dec> {
        // a named parameter with more after it in brackets: no parameter alone, without the
        // readings (every family but a SINUMERIK's, read in full)
        if let [b'[', b'#', b'<', .., last, b']'] = expression {
            if *last != b'>' && self.config.family != Family::Sinumerik {
                return None;
            }
        }
        self.constant_of(expression)
    }

    /// [`Checker::constant`] read in full.
    #[inline(never)]
    fn constant_of(&self, expression: &[u8]) -> Option<Dec> {
        if self.config.family == Family::Sinumerik {
            return self.sinumerik_constant(expression);
        }
        self.constant_read(expression)
    }

    /// [`Checker::constant`] but a SINUMERIK's, read in full.
    fn constant_read(&self, expression: &[u8]) -> Option<Dec> {
        let (negative, rest) = match expression.first() {
            Some(b'-') => (true, &expression[1..]),
            Some(b'+') => (false, &expression[1..]),
            _ => (false, expression),
        };
        let rest = rest
            .strip_prefix(b"[")
            .and_then(|r| r.strip_suffix(b"]"))
            .unwrap_or(rest);
        let heidenhain = self.config.family == Family::Heidenhain;
        let name = match rest {
            [b'#', b'<', named @ .., b'>'] if !named.contains(&b'>') => named_parameter(named),
            // X+QL1: a HEIDENHAIN local (QL) or kept (QR) parameter
            [b'Q', ..] if heidenhain => q_parameter(rest)?,
            [letter @ (b'#' | b'P' | b'Q' | b'R'), digits @ ..]
                if !digits.is_empty() && digits.iter().all(u8::is_ascii_digit) =>
            {
                parameter_name(*letter, digits)
            }
            _ => return None,
        };
        let value = *self.params.get(&name)?;
        Some(if negative { -value } else { value })
    }

    /// TG212: a Haas NGC parameter element read in the block (`#30003.078`, outside its
    /// comments), once per element and file, at its `#`. The reader reads it as one variable
    /// (`Syntax::parameter_elements`) and no constant gives its value ([`Checker::constant`]
    /// reads whole-numbered variables only), so what depends on it is unknown (TG141), as
    /// for a system variable the checker cannot read.
    /// (The test of a plain line inline where it is asked, the search out of line.)
    #[inline]
    pub(super) fn parameter_elements(&mut self, b: &BlockView<'_>) {
        let text = b.text;
        // a line of plain words without a bracketed word (nearly every line of a CAM
        // program) holds no `#`: its words are letters, signs, digits and points, and it has
        // no comment; its reader said so (about 65 instructions a line, the search below)
        if self.line_walks_of == (text.as_ptr() as usize, text.len())
            && self.line_walks.set == 0
            && self.line_walks.all
        {
            debug_assert!(memchr::memchr(b'#', text).is_none(), "a plain line's `#`");
            return;
        }
        self.parameter_elements_found(b);
    }

    /// [`Checker::parameter_elements`] of a line that may hold one.
    #[inline(never)]
    fn parameter_elements_found(&mut self, b: &BlockView<'_>) {
        let text = b.text;
        // (most blocks hold no `#`: one search of the line, not a walk of its comments)
        let Some(first) = memchr::memchr(b'#', text) else {
            return;
        };
        // the walk of the comments starts at the last `(` before it (a comment open there
        // ends where one opened before it would: at the first `)` after it)
        let mut i = memchr::memrchr(b'(', &text[..first]).unwrap_or(first);
        while let Some(at) = text[i..].iter().position(|&c| c == b'#' || c == b'(') {
            let at = i + at;
            if text[at] == b'(' {
                // a comment, to its ')' (a '(' inside it read as the comment rules read it)
                match text[at..].iter().position(|&c| c == b')') {
                    Some(close) => i = at + close + 1,
                    None => return,
                }
                continue;
            }
            let digits = digits_end(text, at + 1);
            i = digits.max(at + 1);
            if digits == at + 1 || text.get(digits) != Some(&b'.') {
                continue;
            }
            let end = digits_end(text, digits + 1);
            if end == digits + 1 {
                continue;
            }
            i = end;
            let element = &text[at..end];
            if self.elements_noted.contains(element) {
                continue;
            }
            self.elements_noted.insert(element.to_vec());
            let shown = String::from_utf8_lossy(element);
            let parameter = std::str::from_utf8(&text[at + 1..digits])
                .ok()
                .and_then(|n| n.parse::<u64>().ok())
                .is_some_and(|n| (30000..=39999).contains(&n));
            let message = if parameter {
                format!(
                    "{shown}: a parameter variable with a decimal part, as Renishaw's \
                     Inspection Plus macros for the Haas NGC read parameters; the Mill \
                     Operator's Manual, NGC, 2017, 6.14.7, gives #30000-#39999 as the \
                     parameters, and no Haas source at hand says what a decimal part selects \
                     (an element of the parameter or one of its bits), so its value is \
                     unknown: read on, and no rule checks what depends on it \
                     (docs/dialects.md)"
                )
            } else {
                // (review 33, doubtful: any `#N.M` was named a parameter element)
                format!(
                    "{shown}: a variable with a decimal part outside the parameters \
                     (#30000-#39999, whose elements Renishaw's Inspection Plus macros for the \
                     Haas NGC read); the Mill Operator's Manual, NGC, 2017, 6.14.7, numbers \
                     variables with whole numbers and no Haas source at hand says what the \
                     control reads here, so its value is unknown: read on, and no rule checks \
                     what depends on it (docs/dialects.md)"
                )
            };
            let column = crate::text::column(text, at);
            self.report(Rule::ParameterElementRead, message, b.line, column);
        }
    }

    /// A block a jump may arrive at forgets the parameters known there (issue 32, review 39
    /// finding 3): every jump forgets them where it is read ([`Checker::statements`]), so the
    /// values known at the block are the ones assigned since, between a jump that may reach it
    /// and it, which the jump passes over. Such a block is
    /// - Custom Macro B: one whose sequence number a `GOTO` read before it names (or any, after
    ///   a `GOTO #1`). The values it forgets are kept aside for TG210 ([`Checker::uncertain`]);
    /// - SINUMERIK: a label (`LBL:`), whether a jump to it was read or not (a `GOTOB`, a
    ///   `GOTO` or a `REPEAT` below may come back to it), and a block number (`N100`) that a
    ///   jump read before names;
    /// - Okuma: a label (`NLBL1`), as a SINUMERIK's.
    ///
    /// Then the block's own jump targets are noted.
    pub(super) fn jump_arrival(&mut self, b: &BlockView<'_>) {
        match self.config.family {
            Family::MacroB => self.macro_b_arrival(b),
            Family::Sinumerik => self.sinumerik_arrival(b),
            Family::Okuma if b.statements.iter().any(|s| s.1 == Kind::Label) => {
                self.params.clear();
            }
            _ => {}
        }
    }

    /// [`Checker::jump_arrival`] on a SINUMERIK.
    fn sinumerik_arrival(&mut self, b: &BlockView<'_>) {
        let label = b.statements.iter().any(|s| s.1 == Kind::Label)
            || (!self.goto_names.is_empty()
                && b.words
                    .iter()
                    .find(|w| w.letter == b'N' && w.expression.is_empty() && w.index.is_empty())
                    .is_some_and(|w| self.goto_names.contains(&w.token.to_ascii_uppercase()[..])));
        if label {
            self.params.clear();
        }
        for &(_, kind, text) in b.statements {
            if kind != Kind::Flow {
                continue;
            }
            let upper = text.to_ascii_uppercase();
            if let Some((_, _, name)) = super::targets::sinumerik_jump(&upper) {
                // (a label's name is forgotten at any label: only a block number is kept)
                if name.first() == Some(&b'N') && name[1..].iter().all(u8::is_ascii_digit) {
                    self.goto_names.insert(name.to_vec());
                }
            }
        }
    }

    /// [`Checker::jump_arrival`] on a Custom Macro B control.
    fn macro_b_arrival(&mut self, b: &BlockView<'_>) {
        // (a block's N is read as a label only where a GOTO has named one, or computed one:
        // no number parsed and hashed a block in a program without GOTO)
        if self.goto_computed || !self.goto_targets.is_empty() {
            let label = b
                .words
                .iter()
                .find(|w| w.letter == b'N' && !w.number.is_empty())
                .and_then(|w| std::str::from_utf8(w.number).ok()?.parse::<u64>().ok());
            if let Some(n) = label {
                if self.goto_computed || self.goto_targets.contains(&n) {
                    let known = std::mem::take(&mut self.params);
                    self.arrival = Some((n, b.line, known));
                }
            }
        }
        for &(_, kind, text) in b.statements {
            if kind != Kind::Flow {
                continue;
            }
            let upper = text.to_ascii_uppercase();
            let Some((_, digits, _)) = super::targets::goto_words(&upper) else {
                continue;
            };
            match std::str::from_utf8(digits)
                .ok()
                .and_then(|d| d.parse().ok())
            {
                Some(n) => {
                    self.goto_targets.insert(n);
                }
                None => self.goto_computed = true,
            }
        }
    }

    /// Where a jump may arrive with another value of the parameter `expression` (`#1`) than
    /// the one the blocks above give it: its value in file order, the sequence number the jump
    /// arrives at and its line, when the parameter was known there (and forgotten,
    /// [`Checker::jump_arrival`]) and no block has set it since.
    pub(super) fn uncertain(&self, expression: &[u8]) -> Option<(Dec, u64, usize)> {
        let (n, line, then) = self.arrival.as_ref()?;
        let key = match expression {
            [b'#', b'<', named @ .., b'>'] => named_parameter(named),
            [letter, digits @ ..] if digits.iter().all(u8::is_ascii_digit) => {
                parameter_name(*letter, digits)
            }
            _ => return None,
        };
        if self.params.contains_key(&key) {
            return None;
        }
        then.get(&key).map(|&value| (value, *n, *line))
    }

    /// A parameter set since the last jump arrival: its value there no longer matters.
    fn set_since_arrival(&mut self, key: &[u8]) {
        if let Some((_, _, then)) = &mut self.arrival {
            then.remove(key);
        }
    }

    /// The value of a Sinumerik expression (`R1+5`, `R2*SIN(30)`) where it reads only numbers
    /// and R parameters holding known constants, by the expression evaluator; None for one
    /// that reads an unknown R parameter, a variable or system variable (`_X`, `$AA_IM[X]`), or
    /// what the evaluator leaves open.
    pub(super) fn sinumerik_constant(&self, expression: &[u8]) -> Option<Dec> {
        if let Some(value) = plain_number(expression) {
            return value;
        }
        let tree = expr::sinumerik_tree(expression).ok()?;
        let known = |p: &[u8]| self.params.get(&sinumerik_key(p)).copied();
        expr::sinumerik_value(&tree, expression, &known)
    }

    /// A Sinumerik variable set to a constant (`_X_HOME=-365.`, `_D=R1*2`) is that value where
    /// an expression reads it (`X=_X_HOME`), as an R parameter is; set otherwise, unknown
    /// again. Elements (`_A[1]=5`) and system variables (`$P_UIFR[1]=...`) are not followed:
    /// they stay unknown. An assignment's text is the statement's, as written (blanks kept).
    pub(super) fn variables(&mut self, b: &BlockView<'_>) {
        if self.config.family == Family::MacroB {
            // IF [..] THEN #106 = 1: the variable may hold its value or the new one
            for &(_, kind, text) in b.statements {
                if let Some(target) = (kind == Kind::Flow)
                    .then(|| crate::statement::conditional_assignment(text))
                    .flatten()
                {
                    let key = parameter_name(b'#', &target[1..]);
                    self.set_since_arrival(&key);
                    self.params.remove(&key);
                }
            }
            return;
        }
        if self.config.family != Family::Sinumerik {
            return;
        }
        for &(_, kind, text) in b.statements {
            match kind {
                Kind::Assignment => self.variable(text),
                // DEF REAL _A=2, _B: each declared name with its initial value, if any
                Kind::Declaration => {
                    for piece in split_arguments(text) {
                        let name_end = piece.iter().position(|&c| c == b'=').unwrap_or(piece.len());
                        let before: Vec<&[u8]> = piece[..name_end]
                            .split(|&c| blank(c))
                            .filter(|w| !w.is_empty())
                            .collect();
                        let Some(name) = before.last() else {
                            continue;
                        };
                        let value = piece.get(name_end + 1..).unwrap_or(b"");
                        self.variable(&[name, &b"="[..], value].concat());
                    }
                }
                _ => {}
            }
        }
    }

    /// `NAME = expression`: the variable known, or unknown again (not a simple name: skipped).
    pub(super) fn variable(&mut self, text: &[u8]) {
        let Some(eq) = text.iter().position(|&c| c == b'=') else {
            return;
        };
        let name: Vec<u8> = text[..eq].iter().copied().filter(|&c| !blank(c)).collect();
        let simple = name
            .first()
            .is_some_and(|&c| c.is_ascii_alphabetic() || c == b'_')
            && name.iter().all(|&c| c.is_ascii_alphanumeric() || c == b'_');
        if !simple {
            return;
        }
        let key = sinumerik_key(&name);
        let rhs = &text[eq + 1..];
        let value = if rhs.iter().all(|&c| blank(c)) {
            None // DEF REAL _A: declared without a value
        } else {
            self.sinumerik_constant(rhs)
        };
        match value {
            Some(value) => {
                self.params.insert(key, value);
            }
            None => {
                self.params.remove(&key);
            }
        }
    }

    /// A parameter set to a constant becomes known (`#n = 250.`, the 6.4.7 form `R11 = 22.2`,
    /// LinuxCNC's `#<name> = 2`); set by an expression, unknown again.
    pub(super) fn assignments(&mut self, b: &BlockView<'_>) {
        // (only a `#` word or an indexed one sets a parameter: most blocks have neither)
        if self.letters & (super::PARAMETER | super::INDEXED) == 0 {
            return;
        }
        for w in b.words {
            let (name, value) = match w.address {
                b'#' if !w.index.is_empty() => {
                    let text = [w.sign, w.number].concat();
                    let value = std::str::from_utf8(&text).ok().and_then(Dec::parse);
                    (
                        parameter_name(b'#', w.index),
                        value.filter(|_| !w.number.is_empty()),
                    )
                }
                // Sinumerik: R1=R2*SIN(30) is known where its operands are (r1= is R1)
                b'R' | b'r' if !w.index.is_empty() && self.config.family == Family::Sinumerik => {
                    let value = if w.number.is_empty() {
                        self.sinumerik_constant(w.expression)
                    } else {
                        let text = [w.sign, w.number].concat();
                        std::str::from_utf8(&text).ok().and_then(Dec::parse)
                    };
                    (parameter_name(b'R', w.index), value)
                }
                b'P' | b'Q' | b'R' if !w.index.is_empty() => {
                    let text = [w.sign, w.number].concat();
                    let value = std::str::from_utf8(&text).ok().and_then(Dec::parse);
                    (
                        parameter_name(w.address, w.index),
                        value.filter(|_| !w.number.is_empty()),
                    )
                }
                b'#' => {
                    // #<name> = value: the name and the value are in the word's expression
                    let Some(close) = w.expression.iter().position(|&c| c == b'>') else {
                        continue;
                    };
                    let (Some(b'<'), Some(rest)) = (
                        w.expression.first(),
                        w.expression[close + 1..].strip_prefix(b"="),
                    ) else {
                        continue;
                    };
                    let text: Vec<u8> = rest.iter().copied().filter(|&c| !blank(c)).collect();
                    let value = std::str::from_utf8(&text).ok().and_then(Dec::parse);
                    (named_parameter(&w.expression[1..close]), value)
                }
                _ => continue,
            };
            if self.arrival.is_some() {
                self.set_since_arrival(&name);
            }
            match value {
                Some(value) => {
                    self.params.insert(name, value);
                }
                None => {
                    self.params.remove(&name);
                }
            }
        }
    }

    /// A HEIDENHAIN formula `Q1 = ...` whose value is constant (numbers, PI, functions of
    /// them, parameters known here) makes its parameter known, as `#1 = 5` does; one that reads
    /// an unknown parameter, and a D function (`D01 Q1 P01 +Q2 P02 +5`), leave it unknown.
    ///
    /// A label (`G98 L1 *`) forgets them all: a jump (D09 to D12) or a repeat (`L1,3`) may come
    /// back to it with other values, and `Q1 = Q1 + 1` after it would be known wrongly.
    #[inline]
    pub(super) fn formulas(&mut self, b: &BlockView<'_>) {
        // (the family's test inlined where it is asked, once a block)
        if self.config.family == Family::Heidenhain {
            self.heidenhain_formulas(b);
        }
    }

    /// [`Checker::formulas`] on a HEIDENHAIN.
    #[inline(never)]
    fn heidenhain_formulas(&mut self, b: &BlockView<'_>) {
        let label = b
            .words
            .iter()
            .any(|w| w.letter == b'G' && w.number.strip_prefix(b"0").unwrap_or(w.number) == b"98");
        if label {
            self.params.clear();
        }
        for &(_, kind, text) in b.statements {
            if kind != Kind::Assignment {
                continue;
            }
            if text.starts_with(b"D") {
                // D00 Q1 P01 +5 (or D01Q1 ...): the function sets the parameter after its
                // number; where none can be read, nothing known is kept
                let digits = text[1..].iter().take_while(|c| c.is_ascii_digit()).count();
                let rest = &text[1 + digits..];
                let start = rest.iter().position(|&c| !blank(c)).unwrap_or(rest.len());
                let rest = &rest[start..];
                let kind = usize::from(matches!(rest.get(1), Some(b'L' | b'R')));
                let end = 1
                    + kind
                    + rest[(1 + kind).min(rest.len())..]
                        .iter()
                        .take_while(|c| c.is_ascii_digit())
                        .count();
                match q_parameter(&rest[..end.min(rest.len())]) {
                    Some(name) => {
                        self.params.remove(&name);
                    }
                    None => self.params.clear(),
                }
                continue;
            }
            let end = text.iter().position(|&c| c == b'=').unwrap_or(text.len());
            let target: Vec<u8> = text[..end].iter().copied().filter(|&c| !blank(c)).collect();
            // (QS5 = "...": a string, no value)
            let value = q_parameter(&target).and_then(|name| {
                let rhs = formula_right_hand_side(text, 0)?;
                let tree = expr::formula_tree(text, rhs).ok()?;
                let known = |p: &[u8]| q_parameter(p).and_then(|k| self.params.get(&k).copied());
                Some((name, expr::formula_value(&tree, text, &known)?))
            });
            // Every parameter the statement sets is unknown then, the one it gives a value
            // aside: a string (QS1 = "A") or a string function read as text may hold more
            // assignments after it on its line
            for name in assigned_parameters(text) {
                self.params.remove(&name);
            }
            if let Some((name, value)) = value {
                self.params.insert(name, value);
            }
        }
    }
}

/// The Q, QL and QR parameters a HEIDENHAIN statement's text sets (`Q2 =`, outside quoted
/// strings), by their keys.
pub(super) fn assigned_parameters(text: &[u8]) -> Vec<Vec<u8>> {
    let mut found = Vec::new();
    let mut quoted = false;
    let mut i = 0;
    while i < text.len() {
        let c = text[i];
        if c == b'"' {
            quoted = !quoted;
        } else if !quoted && c == b'Q' && (i == 0 || !text[i - 1].is_ascii_alphanumeric()) {
            let kind = usize::from(matches!(text.get(i + 1), Some(b'L' | b'R')));
            let digits = text[(i + 1 + kind).min(text.len())..]
                .iter()
                .take_while(|d| d.is_ascii_digit())
                .count();
            let end = i + 1 + kind + digits;
            let eq = text[end.min(text.len())..]
                .iter()
                .position(|&d| !blank(d))
                .map(|at| end + at);
            if digits > 0 && eq.is_some_and(|at| text[at] == b'=') {
                if let Some(name) = q_parameter(&text[i..end]) {
                    found.push(name);
                }
            }
            i = end.max(i + 1);
            continue;
        }
        i += 1;
    }
    found
}

/// The pieces of `text` between the commas outside brackets and strings (`DEF REAL _A=2,
/// _B[2], _C=ATAN2(1,2)` has three).
pub(super) fn split_arguments(text: &[u8]) -> Vec<&[u8]> {
    let mut pieces = Vec::new();
    let (mut depth, mut quoted, mut start) = (0usize, false, 0);
    for (i, &c) in text.iter().enumerate() {
        match c {
            b'"' => quoted = !quoted,
            _ if quoted => {}
            b'(' | b'[' => depth += 1,
            b')' | b']' => depth = depth.saturating_sub(1),
            b',' if depth == 0 => {
                pieces.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    pieces.push(&text[start..]);
    pieces
}

/// The checker's key of a Sinumerik operand: `R1` (`r01` too) for an R parameter, the name in
/// upper case for a variable (`_x_home` is `_X_HOME`: names are not case sensitive).
pub(super) fn sinumerik_key(text: &[u8]) -> Vec<u8> {
    match text {
        [b'R' | b'r', digits @ ..]
            if !digits.is_empty() && digits.iter().all(u8::is_ascii_digit) =>
        {
            parameter_name(b'R', digits)
        }
        _ => text.to_ascii_uppercase(),
    }
}

/// A macro variable's number without its leading zeros: `#0101` is `#101`.
pub(super) fn parameter_name(letter: u8, digits: &[u8]) -> Vec<u8> {
    let start = digits
        .iter()
        .position(|&d| d != b'0')
        .unwrap_or(digits.len());
    let trimmed = &digits[start..];
    let mut name = vec![letter];
    name.extend_from_slice(if trimmed.is_empty() { b"0" } else { trimmed });
    name
}

/// LinuxCNC's `#<name>`, as it reads names: blanks left out, case ignored.
pub(super) fn named_parameter(name: &[u8]) -> Vec<u8> {
    let mut out = b"#<".to_vec();
    out.extend(
        name.iter()
            .filter(|&&c| !blank(c))
            .map(u8::to_ascii_lowercase),
    );
    out
}

/// A Sinumerik expression that is one number, a sign before it at most and blanks around it
/// (`TURN=0`, `_X_HOME=-365.`, as CAM programs set their variables): the value the
/// expression evaluator gives it (`Dec::parse` of its text, negated after a `-`), without its
/// tree built and walked. None: not such a number (the evaluator decides); `Some(None)`: a
/// number the core's decimals cannot hold, as the evaluator finds too.
fn plain_number(expression: &[u8]) -> Option<Option<Dec>> {
    let start = expr::skip_blanks(expression, 0);
    let mut end = expression.len();
    while end > start && blank(expression[end - 1]) {
        end -= 1;
    }
    let text = &expression[start..end];
    let (negative, digits) = match text.first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    if digits.is_empty() || expr::number_end(digits, 0) != Some(digits.len()) {
        return None;
    }
    let value = std::str::from_utf8(digits).ok().and_then(Dec::parse);
    Some(if negative { value.map(|v| -v) } else { value })
}

#[cfg(test)]
mod tests {
    use super::super::testing::{fired, of_family, program};
    use crate::lex::Family;
    use crate::rules::Rule;

    /// `constant`'s first look (a named parameter with more after it in brackets is no
    /// parameter alone) against its full reading, on every family but SINUMERIK's (whose
    /// reading is its own) and on drawn expressions of the pieces a value is written with:
    /// brackets, signs, named and numbered parameters (known ones among them: `#<a>`, `#1`),
    /// numbers, operators, `>` and blanks.
    #[test]
    fn a_bracketed_expression_is_no_constant_as_its_full_reading_finds() {
        use super::super::Checker;
        use crate::decimal::Dec;
        const PIECES: &[&[u8]] = &[
            b"[",
            b"]",
            b"#<",
            b">",
            b"#<a>",
            b"#<A>",
            b"#<yscale>",
            b"#1",
            b"#",
            b"-",
            b"+",
            b"*",
            b"2",
            b".5",
            b" ",
            b"a",
            b"Q1",
            b"R2",
            b"P3",
        ];
        let mut next = crate::drawn::xorshift(0x2545_F491_4F6C_DD1D);
        let mut some = 0;
        for family in Family::ALL {
            if family == Family::Sinumerik {
                continue;
            }
            let config = std::sync::Arc::new(of_family(family));
            let mut checker = Checker::new(config, crate::rules::Selection::all(), false);
            for name in [&b"#<a>"[..], b"#1", b"Q1", b"R2", b"P3"] {
                checker.params.insert(name.to_vec(), Dec::from_int(25));
            }
            let mut text = Vec::new();
            for _ in 0..40_000 {
                text.clear();
                if next().is_multiple_of(2) {
                    text.extend_from_slice(b"[#<");
                }
                for _ in 0..next() % 6 {
                    text.extend_from_slice(PIECES[(next() % PIECES.len() as u64) as usize]);
                }
                if next().is_multiple_of(2) {
                    text.push(b']');
                }
                let fast = checker.constant(&text);
                assert_eq!(
                    fast,
                    checker.constant_read(&text),
                    "{family:?} {:?}",
                    String::from_utf8_lossy(&text)
                );
                some += usize::from(fast.is_some());
            }
        }
        assert!(some > 100, "{some}");
    }

    /// Where the feed of the last block is found too high (TG602, or TG605 where a FANUC
    /// clamps it: 999.9 at most) and where it is a value the checker cannot evaluate (TG141).
    fn feed(family: Family, body: &str) -> (Vec<usize>, Vec<usize>) {
        let text = program(body);
        let lines = |rule| {
            let found = fired(of_family(family), &text, rule);
            found.into_iter().map(|(line, _)| line).collect::<Vec<_>>()
        };
        let mut high = lines(Rule::FeedTooHigh);
        high.extend(lines(Rule::FeedClamped));
        (high, lines(Rule::NotEvaluated))
    }

    #[test]
    fn a_parameter_set_to_a_constant_is_known() {
        let known = "#101 = 1500.\nG01 X1. F#101";
        assert_eq!(feed(Family::MacroB, known), (vec![3], vec![]));
        assert_eq!(
            feed(Family::MacroB, "#0101 = 1500.\nG01 X1. F-#101"),
            (vec![], vec![])
        );
        assert_eq!(
            feed(Family::MacroB, "#101 = 1500.\nG01 X1. F[#101]"),
            (vec![3], vec![])
        );
        assert_eq!(
            feed(Family::LinuxCnc, "#<Fast> = 1500\nG01 X1. F#<fast>"),
            (vec![3], vec![])
        );
    }

    #[test]
    fn a_parameter_set_otherwise_or_past_a_jump_is_unknown() {
        let unknown = "G01 X1. F#102";
        assert_eq!(feed(Family::MacroB, unknown), (vec![], vec![2]));
        let expression = "#101 = 1500.\n#101 = [#1 + 2]\nG01 X1. F#101";
        assert_eq!(feed(Family::MacroB, expression), (vec![], vec![4]));
        let jump = "#101 = 1500.\nGOTO 10\nN10 G01 X1. F#101";
        assert_eq!(feed(Family::MacroB, jump), (vec![], vec![4]));
    }

    #[test]
    fn sinumerik_variables_and_r_parameters() {
        let r = "R1=750\nR2=R1*2\nG01 X1. F=R2";
        assert_eq!(feed(Family::Sinumerik, r), (vec![4], vec![]));
        let variable = "DEF REAL _FAST=1500, _B\nG01 X1. F=_fast";
        assert_eq!(feed(Family::Sinumerik, variable), (vec![3], vec![]));
        let unknown = "DEF REAL _FAST=1500, _B\nG01 X1. F=_B";
        assert_eq!(feed(Family::Sinumerik, unknown), (vec![], vec![3]));
    }

    #[test]
    fn heidenhain_formulas_and_labels() {
        let formula = "Q1 = 750 * 2\nG01 X+1 F+Q1";
        assert_eq!(feed(Family::Heidenhain, formula), (vec![3], vec![]));
        // a label may be jumped back to with other values: nothing known is kept
        let label = "Q1 = 750 * 2\nG98 L1\nG01 X+1 F+Q1";
        assert_eq!(feed(Family::Heidenhain, label), (vec![], vec![4]));
    }

    /// [`super::plain_number`] against the slow way, the expression's tree and its value,
    /// over numbers with and without signs, points, blanks, exponents and what follows them:
    /// where the fast path decides, its value and scale are the evaluator's.
    #[test]
    fn a_plain_number_is_worth_what_the_evaluator_makes_of_it() {
        let numbers = [
            "0",
            "5",
            "-365.",
            "+2.5",
            ".5",
            "-.5",
            "007",
            "12.50",
            "0.000",
            "-0",
            "1.",
            "99999999999999999999999999999999999999999",
            "1EX3",
            "1.5EX-2",
        ];
        let around = ["", " ", "  ", "\t"];
        let tails = ["", "+1", "*2", " R1", "X", "(", ")", "-", ".", "..5"];
        let heads = ["", "-", "+", "--", "- ", "R", "(", "NOT "];
        let (mut decided, mut cases) = (0, 0);
        for n in numbers {
            for h in heads {
                for t in tails {
                    for b in around {
                        let text = format!("{b}{h}{n}{t}{b}");
                        let bytes = text.as_bytes();
                        cases += 1;
                        let Some(fast) = super::plain_number(bytes) else {
                            continue;
                        };
                        decided += 1;
                        let slow = crate::expr::sinumerik_tree(bytes)
                            .ok()
                            .and_then(|tree| crate::expr::sinumerik_value(&tree, bytes, &|_| None));
                        let exact = |v: Option<super::Dec>| v.map(|v| (v.mantissa, v.scale));
                        assert_eq!(exact(fast), exact(slow), "{text:?}");
                    }
                }
            }
        }
        assert!(decided > 100 && decided < cases, "{decided} of {cases}");
    }
}
