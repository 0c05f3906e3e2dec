//! TG108: a line tapegate cannot read that no run of a FANUC or Haas program reaches.
//!
//! A FANUC or Haas control stores a program's text as it comes (registration reads it to the
//! `%` that ends the record: FANUC 16i/18i-TB Operator's Manual B-63524EN/01, 8, "File
//! format": a file always ends with %) and reads a block's words when it runs the block: an
//! alarm of a block's form (FANUC PS0009 "improper NC-address", a Haas "alarm at runtime",
//! Mill Operator's Manual, NGC, 2017, 6.14) stops the machine at that block, not at the
//! registration. A line no run reaches is never read so, and is no reading error of the
//! program: the control keeps it, and alarms only if it is ever run.
//!
//! A line is taken as unreached only where that is sure from the program's own text, read
//! from the top: it follows, with no block carrying a sequence number between, a block that
//! leaves unconditionally -- an end or a return (M02, M30, M99, which always leaves: a
//! subprogram returns, a main program's goes back to its head or to its P), an alarm
//! (`#3000=` outside any IF: FANUC's macro alarm, which stops there) or a `GOTO` (not
//! `IF [..] GOTO`) -- and it carries no sequence number of its own. Any block with an `N`
//! ends that: a jump may name it (`GOTO n`, `IF [..] GOTO n`, a computed `GOTO #1`, which may
//! name every one, a Haas `M97 P`, and an `M99 P n` of a subprogram stored anywhere else on
//! the control, which returns to its caller's block `N n`), so no reading of this file alone
//! can say it is never run. A block skipped by the `/` switch leaves only with the switch
//! off: no such block starts an unreached part; nor does one inside a `WHILE`/`DO` loop (its
//! `END` sends the run back), and a loop's statement ends an unreached part. A line in
//! doubt stays the reading error it is.
//!
//! A `%` glued to the block after a program's end (`N7422%` after `N7421 M30`) is the end of
//! record the control stops reading at: said so, as this rule.

use super::{Checker, Unreadable};
use crate::lex::Family;
use crate::rules::Rule;
use crate::statement::Kind;

/// Where the read stands, for [`Checker::unreached`].
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Reach {
    /// The line and kind of the block that left unconditionally, while no block with a
    /// sequence number has come since (None: the lines here may run).
    pub(super) left: Option<(usize, Leaving)>,
    /// How deep in `WHILE`/`DO` loops the read stands.
    pub(super) loops: usize,
    /// The line of the block with a sequence number that ended an unreached part: no run
    /// falls through to it, only a jump reaches it (a jump's arrival there keeps no values in
    /// file order, [`Checker::jump_arrival`]).
    pub(super) resumed: usize,
}

/// How a block leaves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Leaving {
    /// M02 or M30: the program's end.
    End,
    /// M99: a return.
    Return,
    /// `#3000=`: a macro alarm.
    Alarm,
    /// `GOTO`: a jump.
    Jump,
}

impl Leaving {
    fn what(self) -> &'static str {
        match self {
            Leaving::End => "M02/M30, the program's end",
            Leaving::Return => "M99, which always returns",
            Leaving::Alarm => "a #3000 alarm, which stops the program",
            Leaving::Jump => "a GOTO, which always jumps",
        }
    }
}

/// The first byte of `text` that is not blank, after a block skip `/`.
fn head(text: &[u8]) -> Option<u8> {
    text.iter()
        .copied()
        .find(|&c| !crate::lex::blank(c) && c != b'/')
}

/// How the words and statements of a block leave, if they always do.
fn leaving(b: &super::BlockView<'_>) -> Option<Leaving> {
    for w in b.words {
        if w.letter == b'M' && w.expression.is_empty() && w.index.is_empty() {
            match crate::text::digits_value(w.number) {
                Some(2 | 30) => return Some(Leaving::End),
                Some(99) => return Some(Leaving::Return),
                _ => {}
            }
        }
        if w.letter == b'#' {
            let token = w.token;
            let rest = token.strip_prefix(b"#3000").unwrap_or(b"");
            if rest
                .iter()
                .copied()
                .find(|&c| !crate::lex::blank(c))
                .is_some_and(|c| c == b'=')
            {
                return Some(Leaving::Alarm);
            }
        }
    }
    for &(_, kind, text) in b.statements {
        if kind == Kind::Flow && text.trim_ascii_start().len() >= 4 {
            let start = text.trim_ascii_start();
            if start[..4].eq_ignore_ascii_case(b"GOTO") {
                return Some(Leaving::Jump);
            }
        }
    }
    None
}

/// Whether a flow statement opens (`WHILE [..] DO n`, `DO n`) or closes (`END n`) a loop:
/// +1, -1 or 0.
fn loop_step(text: &[u8]) -> i32 {
    let start = text.trim_ascii_start();
    let starts = |word: &[u8]| {
        start
            .get(..word.len())
            .is_some_and(|s| s.eq_ignore_ascii_case(word))
    };
    if starts(b"WHILE") || starts(b"DO") {
        1
    } else if starts(b"END") {
        -1
    } else {
        0
    }
}

impl Checker {
    /// A block read (Custom Macro B): whether the lines after it are reached.
    pub(super) fn reach_block(&mut self, b: &super::BlockView<'_>) {
        if self.config.family != Family::MacroB {
            return;
        }
        if b.percent {
            self.reach = Reach::default();
            return;
        }
        let mut in_loop_statement = false;
        // (the walk's set-up asked only where there are statements: most blocks have none)
        if !b.statements.is_empty() {
            for &(_, kind, text) in b.statements {
                if kind != Kind::Flow {
                    continue;
                }
                match loop_step(text) {
                    1 => {
                        self.reach.loops += 1;
                        in_loop_statement = true;
                    }
                    -1 => {
                        self.reach.loops = self.reach.loops.saturating_sub(1);
                        in_loop_statement = true;
                    }
                    _ => {}
                }
            }
        }
        // (read, not taken: most blocks have a sequence number and no unreached part ended)
        if (in_loop_statement || self.letters & crate::modal::bit(b'N') != 0)
            && self.reach.left.is_some()
        {
            self.reach.left = None;
            self.reach.resumed = b.line;
        }
        if b.skip || b.skip_within.is_some() || self.reach.loops > 0 {
            return;
        }
        // (only an M word, a `#` word or a statement leaves: most blocks have none)
        let may_leave = self.letters & (crate::modal::bit(b'M') | super::PARAMETER) != 0
            || !b.statements.is_empty();
        if let Some(how) = if may_leave { leaving(b) } else { None } {
            self.reach.left = Some((b.line, how));
        }
    }

    /// The next program of the file: read from its top.
    pub(super) fn reach_reset(&mut self) {
        self.reach = Reach::default();
    }

    /// A line that cannot be read: TG108 (a warning) where no run reaches it, and true;
    /// false where it may run (its reading error stands).
    pub(super) fn unreached(&mut self, block: &Unreadable<'_>) -> bool {
        if self.config.family != Family::MacroB {
            return false;
        }
        let Some((left, how)) = self.reach.left else {
            return false;
        };
        let text = block.text;
        // a `%` glued to the block after the end: the end of record (columns are offsets in
        // an ASCII line)
        let at = block.column.saturating_sub(1);
        let glued = text.is_ascii()
            && text.get(at) == Some(&b'%')
            && text[at + 1..].iter().all(|&c| crate::lex::blank(c))
            && how == Leaving::End;
        if glued {
            let message = format!(
                "'%' glued to the block after the program's end (M02/M30 on line {left}): the end of \
                 record, where the control stops reading the program (FANUC B-63524EN/01, 8: a \
                 file ends with %); the words before it stand after the program's end"
            );
            self.report(Rule::NeverRun, message, block.line, block.column.max(1));
            // the closing % (no TG115)
            self.percent_closed = true;
            self.closed |= self.ended_line > 0;
            return true;
        }
        // a line that may carry a sequence number or begin a program is in doubt: a jump or
        // a search may find it
        if matches!(
            head(text).map(|c| c.to_ascii_uppercase()),
            Some(b'N' | b'O' | b'<' | b':' | b'&' | b'%')
        ) {
            self.passage_ended(None);
            self.reach.left = None;
            return false;
        }
        // (an IF GOTO whose condition the values known make true leaves too, passed.rs, but
        // the condition is the checker's reading of the values, not the text's alone: a line
        // after it stays the error it is)
        if self.passage_conditional(left) {
            return false;
        }
        let message = format!(
            "line not read ({}): line {left} before it always leaves ({}) and no block a jump \
             may name stands between, so no run reaches it; the control stores it and alarms \
             only if it is ever run (FANUC, Haas: a block's form is read when it runs)",
            block.message,
            how.what()
        );
        self.report(Rule::NeverRun, message, block.line, block.column.max(1));
        true
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{fired, of_family};
    use crate::lex::Family;
    use crate::rules::Rule;

    fn program(leave: &str, line: &str) -> String {
        format!("%\nO1000\nG21 G90 G00 X0\nIF[#1EQ0]GOTO10\n{leave}\n{line}\nN10 G01 X1. F100.\nM30\n%\n")
    }

    #[test]
    fn a_line_after_a_block_that_always_leaves_is_never_run() {
        let macro_b = || of_family(Family::MacroB);
        for leave in ["#3000=1(STOP)", "GOTO10", "M99", "M30", "M02"] {
            let text = program(leave, "---------");
            assert_eq!(fired(macro_b(), &text, Rule::NeverRun), [(6, 1)], "{leave}");
            assert_eq!(fired(macro_b(), &text, Rule::Unreadable), [], "{leave}");
        }
    }

    #[test]
    fn a_line_a_run_may_reach_keeps_its_reading_error() {
        let macro_b = || of_family(Family::MacroB);
        for (leave, line, column) in [
            ("G00 X1.", "---------", 1),
            ("IF[#1EQ1]THEN#3000=1(STOP)", "---------", 1),
            ("/GOTO10", "---------", 1),
            ("GOTO10\nN5", "---------", 1),
            ("GOTO10", "N5 ---------", 4),
            ("#3000=1\nWHILE[#2LT1]DO1", "---------", 1),
        ] {
            let text = program(leave, line);
            let at = 6 + leave.matches('\n').count();
            assert_eq!(fired(macro_b(), &text, Rule::NeverRun), [], "{leave}");
            assert_eq!(
                fired(macro_b(), &text, Rule::Unreadable),
                [(at, column)],
                "{leave}"
            );
        }
        // another family: the reading error
        let iso = of_family(Family::Iso);
        assert_eq!(fired(iso, &program("M30", "---"), Rule::NeverRun), []);
    }

    #[test]
    fn a_percent_glued_after_the_end_is_the_end_of_record() {
        let text = "%\nO1\nG21 G90 G00 X0\nN7421M30\nN7422%\n";
        assert_eq!(
            fired(of_family(Family::MacroB), text, Rule::NeverRun),
            [(5, 6)]
        );
        assert_eq!(
            fired(of_family(Family::MacroB), text, Rule::NoClosingPercent),
            []
        );
    }
}
