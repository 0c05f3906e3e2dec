//! What the checker knows of parameters (no rule of its own): a parameter or variable set to
//! a constant -- `#101 = 250.`, the 6.4.7 form `R11 = 22.2`, LinuxCNC's `#<depth> = 2`, a
//! Sinumerik's `R1=R2*SIN(30)` or `_X_HOME=-365.`, a HEIDENHAIN formula `Q1 = 5 * 2` -- is
//! that value where a word reads it (`F#101` is the feed 250), until it is set otherwise or a
//! jump or call forgets it. A value read from an unknown one is TG141 ([`super::words`]).

use super::{BlockView, Checker};
use std::collections::HashMap;

use crate::decimal::Dec;
use crate::expr;
use crate::lex::{blank, Family};
use crate::rules::Rule;
use crate::statement::{digits_end, formula_right_hand_side, q_parameter, Kind};

/// Where an arrival's values hold: the words of its message, for the jump of line `line` read
/// first to block `name` (`N10`), and whether another jump to it was read too.
fn not_taken((line, more): (usize, bool), name: &str) -> String {
    if more {
        format!("where none of the jumps to {name} (the first on line {line}) is taken")
    } else {
        format!("where the jump of line {line} is not taken")
    }
}

/// The most `D=R1` quieted by a known value kept for a jump back ([`Checker::quiet_d_noted`]).
const QUIET_D: usize = 256;

/// The values known at the last block a jump may arrive at ([`Checker::jump_arrival`]), in
/// file order: the values where no jump arrives.
#[derive(Debug, Clone)]
pub(super) struct Arrival {
    /// Its sequence number (Custom Macro B; 0 on a SINUMERIK) and line.
    n: u64,
    line: usize,
    /// Where the values hold: "where the jump of line 6 is not taken".
    not_taken: String,
    /// The values, by parameter, that no block has set since.
    then: HashMap<Vec<u8>, Dec>,
}

/// The most runs kept where a forward conditional jump is taken and its target has not come
/// yet ([`Taken`]); past them the oldest is dropped (its target judged as before: TG141).
const JUMPS_PENDING: usize = 4;

/// The most jumps whose runs are judged at one target: where more arrive there, none is (the
/// values they bring are TG141's, as before).
const RUNS: usize = 3;

/// The most blocks a run reads from its target on, beside the file's reading.
const RUN_BLOCKS: usize = 64;

/// A comparison of a jump's condition ([`Checker::condition_known`]).
#[derive(Clone, Copy)]
enum Ordering {
    Eq,
    Ne,
    Gt,
    Ge,
    Lt,
    Le,
}

impl Ordering {
    /// Whether the comparison holds of two values ordered `order`.
    fn holds(self, order: std::cmp::Ordering) -> bool {
        use std::cmp::Ordering as O;
        match self {
            Ordering::Eq => order == O::Equal,
            Ordering::Ne => order != O::Equal,
            Ordering::Gt => order == O::Greater,
            Ordering::Ge => order != O::Less,
            Ordering::Lt => order == O::Less,
            Ordering::Le => order != O::Greater,
        }
    }
}

/// Custom Macro B's comparisons (FANUC's Custom Macro B; Haas's Mill Operator's Manual).
const MACRO_B_COMPARISONS: &[(&[u8], Ordering)] = &[
    (b"EQ", Ordering::Eq),
    (b"NE", Ordering::Ne),
    (b"GT", Ordering::Gt),
    (b"GE", Ordering::Ge),
    (b"LT", Ordering::Lt),
    (b"LE", Ordering::Le),
];

/// A SINUMERIK's comparisons, the two-character ones first.
const SINUMERIK_COMPARISONS: &[(&[u8], Ordering)] = &[
    (b"==", Ordering::Eq),
    (b"<>", Ordering::Ne),
    (b">=", Ordering::Ge),
    (b"<=", Ordering::Le),
    (b">", Ordering::Gt),
    (b"<", Ordering::Lt),
];

/// A condition of one comparison outside brackets: its two sides and the comparison; None
/// where there is none or more than one, or it holds a logic operation.
fn comparison<'a>(
    condition: &'a [u8],
    ops: &[(&[u8], Ordering)],
) -> Option<(&'a [u8], Ordering, &'a [u8])> {
    let mut found = None;
    let mut depth = 0usize;
    let mut i = 0;
    while i < condition.len() {
        match condition[i] {
            b'[' | b'(' => depth += 1,
            b']' | b')' => depth = depth.checked_sub(1)?,
            _ if depth == 0 => {
                if let Some(&(name, op)) = ops.iter().find(|(n, _)| condition[i..].starts_with(n)) {
                    if found.is_some() {
                        return None;
                    }
                    found = Some((i, name.len(), op));
                    i += name.len();
                    continue;
                }
            }
            _ => {}
        }
        i += 1;
    }
    let (at, len, op) = found?;
    let (left, right) = (&condition[..at], &condition[at + len..]);
    // (AND, OR, XOR: more than one comparison, not read)
    let logic = |s: &[u8]| s.windows(2).any(|w| w == b"OR") || s.windows(3).any(|w| w == b"AND");
    if logic(left) || logic(right) {
        return None;
    }
    Some((left, op, right))
}

/// A forward conditional jump taken (issue 32, review 44 F3): the checker as it stood after
/// the jump's block -- the run where it is taken, which passes over the blocks between it and
/// its target -- read from the target on beside the file's reading, whose values there are
/// the fall-through's ([`Arrival`]). Where a parameter holds another value in it, a limit's
/// finding at a word reading it is that run's (`X#1 is -900 where the jump of line 6 is
/// taken`).
#[derive(Clone)]
pub(super) struct Taken {
    /// The jump's line and its target (`N10`; a SINUMERIK label or block number), in capitals.
    line: usize,
    key: Vec<u8>,
    /// Where the jump was met in the run of another jump (review 48, F2): the lines of the
    /// jumps taken before it, the first first.
    via: Vec<usize>,
    /// The blocks it has read from its target on.
    blocks: usize,
    run: Box<Checker>,
}

impl Taken {
    /// Whether this is the run kept for the file's own jump of `line`.
    pub(super) fn own_of(&self, line: usize) -> bool {
        self.line == line && self.via.is_empty()
    }

    /// Whether it was kept for the file's own jump read after `line`.
    pub(super) fn own_after(&self, line: usize) -> bool {
        self.line > line && self.via.is_empty()
    }

    /// Whether it goes to target `key` (`N10`).
    pub(super) fn to(&self, key: &[u8]) -> bool {
        self.key == key
    }
}

/// SINUMERIK: a `D=R1` under G41/G42 quieted by the known value of what it reads: its line,
/// column, word, compensation and the keys of the parameters and variables it reads.
#[derive(Debug, Clone)]
pub(super) struct QuietD {
    line: usize,
    column: usize,
    token: String,
    compensation: i64,
    reads: Vec<Vec<u8>>,
}

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
        let (negative, name) = self.parameter_key(expression)?;
        let value = *self.params.get(&name)?;
        Some(if negative { -value } else { value })
    }

    /// The parameter an expression reads alone, signed or in brackets (`#1`, `-#1`, `[R1]`,
    /// `#<name>`), by its key, and whether it is negated.
    #[inline]
    pub(super) fn parameter_key(&self, expression: &[u8]) -> Option<(bool, Vec<u8>)> {
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
        Some((negative, name))
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
    /// finding 3): the values known at the block in file order were set between a jump that
    /// may reach it and it, or before the jump, and a jump may arrive with others. Such a block
    /// is
    /// - Custom Macro B: one whose sequence number a `GOTO` read before it names (or any, after
    ///   a `GOTO #1`);
    /// - SINUMERIK: a label (`LBL:`), whether a jump to it was read or not (a `GOTOB`, a
    ///   `GOTO` or a `REPEAT` below may come back to it), and a block number (`N100`) that a
    ///   jump read before names;
    /// - Okuma: a label (`NLBL1`), as a SINUMERIK's.
    ///
    /// The values forgotten are kept aside ([`Arrival`]): where no jump arrives -- the block
    /// reached by falling through -- they are the values the parameters hold, so a limit's
    /// finding reads them (review 41, finding 0: [`Checker::arrival_value`]), and TG210 as
    /// its doubt ([`Checker::uncertain`]). Right after a block that always leaves (a `GOTO`
    /// outside an IF, M02/M30, M99) nothing falls through, and none is kept.
    ///
    /// Then the block's own jump targets are noted.
    pub(super) fn jump_arrival(&mut self, b: &BlockView<'_>) {
        // (the blocks a jump surely taken passes over end here, or at the target: passed.rs)
        if self.passed.is_some() {
            self.passage_block(b);
        }
        if self.no_feed_target != 0 {
            self.no_feed_arrival(b);
        }
        match self.config.family {
            Family::MacroB => self.macro_b_arrival(b),
            Family::Sinumerik => self.sinumerik_arrival(b),
            Family::Okuma if b.statements.iter().any(|s| s.1 == Kind::Label) => {
                self.params.clear();
            }
            _ => {}
        }
    }

    /// The values known at block `b`, a jump's arrival (`n` its sequence number, 0 for a
    /// SINUMERIK's; `not_taken` the words that say where they hold), set aside with those of
    /// the last arrival that no block has set since.
    /// `key`: the target's name, as [`Taken`] keeps it. The runs where a jump to it is taken
    /// start here ([`Checker::runs_started`]); the runs of an earlier target end.
    fn arrive(&mut self, b: &BlockView<'_>, n: u64, not_taken: String, key: &[u8]) {
        if self.run_target != 0 {
            // a run at its own target: its values are the jump's, none set aside
            return;
        }
        // (a Custom Macro B block that ends an unreached part, reach.rs; elsewhere the block
        // right after one that always leaves: reached by jumps alone)
        let falls = if self.config.family == Family::MacroB {
            self.reach.resumed != b.line
        } else {
            self.cut_block == 0 || self.stats.blocks != self.cut_block + 1
        };
        self.runs.clear();
        if !self.jumps_pending.is_empty() {
            self.runs_started(b, key, falls);
        }
        let known = std::mem::take(&mut self.params);
        let mut then = match self.arrival.take() {
            Some(old) if falls => old.then,
            _ => HashMap::new(),
        };
        if falls {
            then.extend(known);
        } else {
            then.clear();
        }
        self.arrival = Some(Arrival {
            n,
            line: b.line,
            not_taken,
            then,
        });
    }

    /// A block of a forward conditional jump that keeps the parameters
    /// ([`Checker::jump_keeps_params`]): the run where it is taken is kept for its target,
    /// the checker as it stands at the block's end ([`Checker::jump_runs`]). Not in a program
    /// whose findings are held (called.rs), nor for a block of two jumps, nor where no
    /// parameter is known.
    ///
    /// In a run (review 48, F2), a forward jump it meets, conditional or not (`GOTO 20`,
    /// `GOTOF LBL`), the file's reading tells which ([`Checker::forward_jump`]): its run is
    /// kept for its target in the same way, and the run itself ends where the jump is surely
    /// taken (no condition, or one its values make true).
    pub(super) fn jump_noted(&mut self, b: &BlockView<'_>) {
        self.jump_noted_of(b);
        // (a run at a jump with no condition that keeps no run: it ends here)
        if self.run_target != 0 && self.run_jump == Some(false) && self.jump_to_note.is_none() {
            self.params_forgotten();
        }
    }

    /// [`Checker::jump_noted`] but the end of a run.
    fn jump_noted_of(&mut self, b: &BlockView<'_>) {
        // (no parameter known here: the run where the jump is taken knows none at its target,
        // and judges nothing the fall-through's reading does not)
        if self.hold_from.is_some() || self.params.is_empty() {
            return;
        }
        let in_run = self.run_target != 0;
        // (in a run, only a jump the file's reading knows goes forward)
        if in_run && self.run_jump.is_none() {
            return;
        }
        let mut target = None;
        let mut leaves = false;
        for &(_, kind, text) in b.statements {
            if kind != Kind::Flow {
                continue;
            }
            let Some(upper) = self.jump_upper(text) else {
                continue;
            };
            let key = if self.config.family == Family::MacroB {
                super::targets::goto_words(&upper)
                    .and_then(|(_, digits, _)| crate::text::digits_value(digits))
                    .map(|n| format!("N{n}").into_bytes())
            } else {
                super::targets::sinumerik_jump(&upper).map(|(_, _, name)| name.to_vec())
            };
            if key.is_none() || target.is_some() {
                return;
            }
            // (a condition the known values make false: the jump is never taken, and keeps
            // no run -- review 48 F1; in a run, one they make true, or none, is always taken)
            match self.condition_known(&upper) {
                Some(false) => return,
                Some(true) => leaves = in_run,
                None => {
                    leaves = in_run && !upper.trim_ascii_start().starts_with(b"IF");
                }
            }
            target = key;
        }
        if let Some(key) = target {
            self.jump_to_note = Some((b.line, key, leaves));
            self.after_block = true;
        }
    }

    /// Whether the condition of a forward jump (`IF[#5EQ1]GOTO10`, a SINUMERIK's
    /// `IF R5==1 GOTOF LBL`; `upper` in capitals) is known: one comparison (Custom Macro B's
    /// EQ NE GT GE LT LE, a SINUMERIK's `== <> > >= < <=`) of two sides each a number or of
    /// parameters holding known constants (review 48 F1). None where a side is not known, the
    /// condition is of another form, or the jump has none (`GOTO 10`).
    pub(super) fn condition_known(&self, upper: &[u8]) -> Option<bool> {
        let text = upper.trim_ascii_start();
        let rest = text.strip_prefix(b"IF")?;
        let (condition, ops): (&[u8], &[(&[u8], Ordering)]) =
            if self.config.family == Family::MacroB {
                // the bracketed condition after IF, to its matching `]` (read as the
                // statement's reader reads it: crate::statement's `condition`)
                let open = rest.len() - rest.trim_ascii_start().len();
                let syntax = crate::lex::Syntax {
                    brackets: true,
                    hash: true,
                    macros: true,
                    parameter_elements: self.config.haas,
                    ..crate::lex::Syntax::default()
                };
                let end = expr::scan_group(rest, open, syntax).ok()?;
                (&rest[open + 1..end - 1], MACRO_B_COMPARISONS)
            } else {
                let at = super::targets::sinumerik_jump(upper)?.0;
                let start = text.as_ptr() as usize - upper.as_ptr() as usize + 2;
                if at < start {
                    return None;
                }
                (&upper[start..at], SINUMERIK_COMPARISONS)
            };
        let (left, op, right) = comparison(condition, ops)?;
        let side = |s: &[u8]| -> Option<Dec> {
            let s = s.trim_ascii();
            if s.is_empty() {
                return None;
            }
            if self.config.family == Family::Sinumerik {
                return self.sinumerik_constant(s);
            }
            std::str::from_utf8(s)
                .ok()
                .and_then(Dec::parse)
                .or_else(|| self.constant(s))
        };
        let (a, b) = (side(left)?, side(right)?);
        Some(op.holds(a.cmp(&b)))
    }

    /// After a block (`after_block`): the runs where a jump is taken read it, and a jump read
    /// in it keeps its run for its target.
    #[cold]
    #[inline(never)]
    pub(super) fn jump_runs(&mut self, b: &BlockView<'_>) {
        if !self.runs.is_empty() {
            self.runs_read(b);
        }
        if let Some((line, key, leaves)) = self.jump_to_note.take() {
            if self.jumps_pending.len() >= JUMPS_PENDING {
                // (the oldest a run met goes first: review 49, R4)
                let oldest = self.jumps_pending.iter().position(|t| !t.via.is_empty());
                self.jumps_pending.remove(oldest.unwrap_or(0));
            }
            let run = self.run_of();
            self.jumps_pending.push(Taken {
                line,
                key,
                via: Vec::new(),
                blocks: 0,
                run,
            });
            // (a run where the jump is surely taken: nothing of it falls through)
            if leaves {
                self.params_forgotten();
            }
        }
        self.passage_started(b);
        self.after_block = !self.runs.is_empty();
    }

    /// The checker as it stands, for a run where a jump is taken: without what grows with the
    /// program and a run does not read -- the findings, the path, the runs, the sequence
    /// numbers and jumps read (the file's reading says which jumps of a run go forward:
    /// [`Checker::forward_jump`]), the statistics' lists -- so that a copy costs the same at
    /// any length of program; nor the verdicts kept of words' formats (32 KB), which a run
    /// asks afresh; nor the subprograms kept for their calls and those given up (called.rs):
    /// a run ends at a call, and what a call of one says is at its calling word (`M98`,
    /// `G65`), which reads no parameter, so never the run's to say ([`Checker::run_finding`]).
    pub(super) fn run_of(&mut self) -> Box<Checker> {
        let found = std::mem::take(&mut self.found);
        let path = std::mem::take(&mut self.path);
        let pending = std::mem::take(&mut self.jumps_pending);
        let runs = std::mem::take(&mut self.runs);
        let targets = std::mem::take(&mut self.targets);
        let goto_targets = std::mem::take(&mut self.goto_targets);
        let goto_names = std::mem::take(&mut self.goto_names);
        let called = (
            std::mem::take(&mut self.pending),
            std::mem::take(&mut self.given_up),
        );
        let clean = self.format_table.take_clean();
        let stats = &mut self.stats;
        let lists = (
            std::mem::take(&mut stats.travel_not),
            std::mem::take(&mut stats.moves_not_known),
            std::mem::take(&mut stats.dwells_not_known),
        );
        let mut run = Box::new(self.clone());
        let stats = &mut self.stats;
        (
            stats.travel_not,
            stats.moves_not_known,
            stats.dwells_not_known,
        ) = lists;
        self.found = found;
        self.path = path;
        self.jumps_pending = pending;
        self.runs = runs;
        self.targets = targets;
        self.goto_targets = goto_targets;
        self.goto_names = goto_names;
        (self.pending, self.given_up) = called;
        self.format_table.give_clean(clean);
        // (its words' formats asked afresh, without the table of those kept: the same
        // findings, Checker::keep_verdicts)
        run.keep_verdicts(false);
        run.record_path = false;
        run.line_walks_of = (0, 0);
        run.after_block = false;
        // (the sample machine's hint is the file's to add, once: Checker::run_finding)
        run.limits_hint_said = true;
        run
    }

    /// The value parameter `key` holds in the file's reading: known, or the fall-through's
    /// at the last arrival.
    fn value_here(&self, key: &[u8]) -> Option<Dec> {
        self.params
            .get(key)
            .or_else(|| self.arrival.as_ref()?.then.get(key))
            .copied()
    }

    /// At block `b`, the target `key` (`falls`: a run falls through to it): the runs kept for
    /// the jumps to it start, each whose values differ from the fall-through's (where they
    /// agree, it is the same run); none where more than [`RUNS`] arrive.
    fn runs_started(&mut self, b: &BlockView<'_>, key: &[u8], falls: bool) {
        let pending = std::mem::take(&mut self.jumps_pending);
        let (arriving, kept): (Vec<Taken>, Vec<Taken>) =
            pending.into_iter().partition(|t| t.key == key);
        self.jumps_pending = kept;
        // (the file's own jumps count against the bound; the runs a run met take the places
        // left, never one of theirs: review 49, R4)
        let (mut arriving, met): (Vec<Taken>, Vec<Taken>) =
            arriving.into_iter().partition(|t| t.via.is_empty());
        if arriving.len() > RUNS {
            return;
        }
        let room = RUNS - arriving.len();
        arriving.extend(met.into_iter().take(room));
        for mut taken in arriving {
            let differs = taken
                .run
                .params
                .iter()
                .any(|(k, &v)| !falls || self.value_here(k) != Some(v));
            if differs {
                taken.run.run_target = b.line;
                self.runs.push(taken);
            }
        }
        self.after_block |= !self.runs.is_empty();
    }

    /// The runs where a jump is taken read block `b`: a limit's finding of theirs at a word
    /// read from parameters (`X#1`) is theirs to say where the file's reading has none at
    /// it, naming the jump and the word's value. A run ends after [`RUN_BLOCKS`] blocks and
    /// where its parameters hold the file's values.
    fn runs_read(&mut self, b: &BlockView<'_>) {
        // (a forward jump in the block, as the file's reading knows it: review 48, F2)
        let forward = if b.statements.is_empty() {
            None
        } else {
            self.forward_jump(b)
        };
        let mut runs = std::mem::take(&mut self.runs);
        runs.retain_mut(|taken| {
            // (at a jump, a run whose values are the file's ends there, as after any block:
            // the jump's run it would keep is the file's own, not copied again)
            taken.run.run_jump = forward.filter(|_| {
                taken
                    .run
                    .params
                    .iter()
                    .any(|(k, &v)| self.value_here(k) != Some(v))
            });
            taken.run.block(b);
            taken.blocks += 1;
            // (all of them, those the run holds for a program read apart too: the file's
            // reading holds what it reports as the run did, a copy of its own state; the
            // run's index of its held ones goes back to its emptied list: review 50, F9,
            // a panic where it was left past the end)
            let found = std::mem::take(&mut taken.run.found);
            if taken.run.hold_from.is_some() {
                taken.run.hold_from = Some(0);
            }
            for f in found {
                self.run_finding(taken, b, f);
            }
            // a jump the run met: its run kept for its target, as the file's own, the blocks
            // read so far counted in it; not where its values are the file's here (the file's
            // own run of that jump is the same)
            for mut met in std::mem::take(&mut taken.run.jumps_pending) {
                if taken.blocks >= RUN_BLOCKS {
                    break;
                }
                let differs = met
                    .run
                    .params
                    .iter()
                    .any(|(k, &v)| self.value_here(k) != Some(v));
                if !differs {
                    continue;
                }
                if self.jumps_pending.len() >= JUMPS_PENDING {
                    // (a met run pushes out only another met run, never the file's own
                    // jump's: review 49, R4)
                    match self.jumps_pending.iter().position(|t| !t.via.is_empty()) {
                        Some(oldest) => {
                            self.jumps_pending.remove(oldest);
                        }
                        None => continue,
                    }
                }
                met.via.clone_from(&taken.via);
                met.via.push(taken.line);
                met.blocks = taken.blocks;
                self.jumps_pending.push(met);
            }
            // (a block that surely leaves -- M02/M30, M99, RET, a GOTO with no condition, one
            // whose condition the run's values make true, back as forward -- ends the run:
            // what follows it in the file is not where the run goes; review 49, R1 and R2)
            let leaves = taken.run.cut_block == taken.run.stats.blocks
                || (forward.is_none() && taken.run.surely_jumps(b));
            !leaves
                && taken.blocks < RUN_BLOCKS
                && taken
                    .run
                    .params
                    .iter()
                    .any(|(k, &v)| self.value_here(k) != Some(v))
        });
        self.runs = runs;
    }

    /// Whether block `b` jumps forward and nothing else the checker does not follow: one
    /// Custom Macro B `GOTO 10` (in an IF or not) to a sequence number the program has not
    /// shown yet, or one SINUMERIK `GOTOF`/`GOTO` to a name not read yet; Some(whether it has
    /// a condition). Asked of the file's reading for its runs ([`Checker::jump_noted`]), which
    /// know not the numbers read.
    pub(super) fn forward_jump(&self, b: &BlockView<'_>) -> Option<bool> {
        let family = self.config.family;
        if !matches!(family, Family::MacroB | Family::Sinumerik) {
            return None;
        }
        let mut found = None;
        for &(_, kind, text) in b.statements {
            if !kind.unfollowed() {
                continue;
            }
            if kind != Kind::Flow || found.is_some() {
                return None;
            }
            let Some(upper) = self.jump_upper(text) else {
                continue;
            };
            if !self.forward(&upper) {
                return None;
            }
            found = Some(upper.trim_ascii_start().starts_with(b"IF"));
        }
        found
    }

    /// Whether a jump statement (`upper`, in capitals) goes forward: to a sequence number the
    /// program has not shown yet (`GOTO 10`, nothing after it), a SINUMERIK's `GOTOF`, or its
    /// `GOTO` to a name not read yet.
    fn forward(&self, upper: &[u8]) -> bool {
        if self.config.family == Family::MacroB {
            super::targets::goto_words(upper).is_some_and(|(_, digits, tail)| {
                tail.iter().all(|&c| blank(c))
                    && crate::text::digits_value(digits)
                        .is_some_and(|n| self.targets.read_before(n) == Some(false))
            })
        } else {
            super::targets::sinumerik_jump(upper).is_some_and(
                |(_, direction, name)| match direction {
                    super::targets::Direction::Forward => true,
                    super::targets::Direction::Backward => false,
                    super::targets::Direction::Both => !self.targets.sinumerik_read(name),
                },
            )
        }
    }

    /// A flow statement's text in capitals, where it may jump: None for a Custom Macro B
    /// conditional assignment (`IF [..] THEN #1=2`), the one flow statement that never jumps.
    pub(super) fn jump_upper(&self, text: &[u8]) -> Option<Vec<u8>> {
        if self.config.family == Family::MacroB
            && crate::statement::conditional_assignment(text).is_some()
        {
            return None;
        }
        Some(text.to_ascii_uppercase())
    }

    /// In a run, whether block `b` surely jumps (back, or forward where the file's reading
    /// does not say so): a `GOTO` with no condition, or an IF whose condition the run's
    /// values make true. Not a jump the block-skip switch can pass over (`/GOTO5`, or a `/`
    /// before it in the block): with the switch on the control goes on to the next block, as
    /// a run does at `/M30` (review 50, F10).
    fn surely_jumps(&self, b: &BlockView<'_>) -> bool {
        if b.skip {
            return false;
        }
        b.statements.iter().any(|&(column, kind, text)| {
            if kind != Kind::Flow || b.skip_within.is_some_and(|at| at < column) {
                return false;
            }
            let Some(upper) = self.jump_upper(text) else {
                return false;
            };
            let jumps = if self.config.family == Family::MacroB {
                super::targets::goto_words(&upper).is_some()
            } else {
                super::targets::sinumerik_jump(&upper).is_some()
            };
            jumps
                && (!upper.trim_ascii_start().starts_with(b"IF")
                    || self.condition_known(&upper) == Some(true))
        })
    }

    /// [`Checker::runs_read`]: finding `f` of the run `taken` in block `b`.
    fn run_finding(&mut self, taken: &Taken, b: &BlockView<'_>, f: super::Finding) {
        if !matches!(
            f.rule,
            Rule::TravelExceeded
                | Rule::FeedTooHigh
                | Rule::SpeedTooHigh
                | Rule::ToolOutOfRange
                | Rule::FeedClamped
                | Rule::SpeedLimited
        ) {
            return;
        }
        let Some(i) = b
            .words
            .iter()
            .position(|w| w.column == f.column && !w.expression.is_empty())
        else {
            return;
        };
        let Some(value) = taken.run.readable.get(i).copied().flatten() else {
            return;
        };
        let said = self
            .found
            .iter()
            .rev()
            .take(64)
            .any(|m| m.rule == f.rule && m.line == f.line && m.column == f.column);
        if said {
            return;
        }
        let jumps = match taken.via.as_slice() {
            [] => format!("the jump of line {}", taken.line),
            [first] => format!("the jumps of lines {first} and {}", taken.line),
            via => format!(
                "the jumps of lines {} and {}",
                via.iter()
                    .map(usize::to_string)
                    .collect::<Vec<_>>()
                    .join(", "),
                taken.line
            ),
        };
        let message = format!(
            "{}; {} is {value} where {jumps} {} taken (read from the values the parameters \
             hold there)",
            f.message,
            b.words[i].token(),
            if taken.via.is_empty() { "is" } else { "are" },
        );
        // (the file's first finding against the sample machine says so, a run's too, once:
        // review 49, R5)
        let message = match self.sample_hint(f.rule) {
            Some(hint) if !self.limits_hint_said && self.selection.enabled(f.rule) => {
                self.limits_hint_said = true;
                format!("{message}{hint}")
            }
            _ => message,
        };
        self.report(f.rule, message, f.line, f.column);
    }

    /// [`Checker::jump_arrival`] on a SINUMERIK.
    fn sinumerik_arrival(&mut self, b: &BlockView<'_>) {
        let label = b.statements.iter().find(|s| s.1 == Kind::Label);
        let named = if label.is_none() && !self.goto_names.is_empty() {
            b.words
                .iter()
                .find(|w| w.letter == b'N' && w.expression.is_empty() && w.index.is_empty())
                .and_then(|w| {
                    let name = w.token.to_ascii_uppercase();
                    self.goto_names.get(&name[..]).map(|&j| (name, j))
                })
        } else {
            None
        };
        if let Some(&(_, _, text)) = label {
            let name = String::from_utf8_lossy(text);
            let name = name.trim().trim_end_matches(':');
            let key = name.to_ascii_uppercase();
            let not_taken = format!("where no jump arrives at the label {name}");
            self.arrive(b, 0, not_taken, key.as_bytes());
        } else if let Some((name, jump)) = named {
            let text = String::from_utf8_lossy(&name).into_owned();
            self.arrive(b, 0, not_taken(jump, &text), &name);
        }
        for &(_, kind, text) in b.statements {
            if kind != Kind::Flow {
                continue;
            }
            let upper = text.to_ascii_uppercase();
            if let Some((_, direction, name)) = super::targets::sinumerik_jump(&upper) {
                let conditional = upper.trim_ascii_start().starts_with(b"IF");
                if !conditional && !b.skip && b.skip_within.is_none() {
                    self.cut_block = self.stats.blocks;
                }
                // (a label's name is forgotten at any label: only a block number is kept)
                if name.first() == Some(&b'N') && name[1..].iter().all(u8::is_ascii_digit) {
                    match self.goto_names.get_mut(name) {
                        Some(jump) => jump.1 = true,
                        None => {
                            self.goto_names.insert(name.to_vec(), (b.line, false));
                        }
                    }
                    let back = match direction {
                        super::targets::Direction::Backward => true,
                        super::targets::Direction::Forward => false,
                        super::targets::Direction::Both => self.targets.sinumerik_read(name),
                    };
                    if back && !self.quiet_d.is_empty() {
                        self.jump_back_to_number(b.line, name);
                    }
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
                let jump = self.goto_targets.get(&n).copied().or(self
                    .goto_computed
                    .then_some((self.goto_computed_line, false)));
                if let Some(jump) = jump {
                    let name = format!("N{n}");
                    self.arrive(b, n, not_taken(jump, &name), name.as_bytes());
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
            // (an IF whose condition the values known here make false does not jump: it is no
            // way into the block it names; review 53, F5. Those values are the first pass's,
            // and a jump back is not followed: the target's first run is the fall-through's)
            if self.condition_known(&upper) == Some(false) {
                continue;
            }
            match std::str::from_utf8(digits)
                .ok()
                .and_then(|d| d.parse().ok())
            {
                Some(n) => {
                    self.goto_targets
                        .entry(n)
                        .and_modify(|jump| jump.1 = true)
                        .or_insert((b.line, false));
                }
                None => {
                    self.goto_computed = true;
                    self.goto_computed_line = b.line;
                }
            }
        }
    }

    /// Whether a block of a jump or call the checker does not follow (TG140) leaves the
    /// parameters as they were where the run falls through it: a conditional jump forward
    /// (`IF [#2 EQ 1] GOTO 10` to a sequence number no block of the program has shown yet, a
    /// SINUMERIK's `IF R2==1 GOTOF LBL`) changes none where it is not taken, and where it
    /// is, its target forgets them ([`Checker::jump_arrival`]) (review 41, finding 0:
    /// `#1=-900.` / `IF[#2EQ1]GOTO10` / `G0 X#1` goes to X-900). A call (the subprogram may
    /// set them), a loop (its end comes back with the body's values), a jump back or one
    /// whose target is not known (`GOTO #5`, `GOTOC`) forget them all.
    pub(super) fn jump_keeps_params(&self, b: &BlockView<'_>) -> bool {
        let family = self.config.family;
        if !matches!(family, Family::MacroB | Family::Sinumerik) {
            return false;
        }
        // (in a run, a jump with no condition forward, which the file's reading tells it:
        // kept for its run, review 48 F2; a run knows not the numbers read, and keeps its
        // values where any conditional jump falls through, as jump48 had it)
        if self.run_target != 0 && self.run_jump == Some(false) {
            return true;
        }
        let mut jumps = false;
        for &(_, kind, text) in b.statements {
            if !kind.unfollowed() {
                continue;
            }
            if kind != Kind::Flow {
                return false;
            }
            let Some(upper) = self.jump_upper(text) else {
                continue;
            };
            if !upper.trim_ascii_start().starts_with(b"IF") || !self.forward(&upper) {
                return false;
            }
            jumps = true;
        }
        jumps
    }

    /// The value of word `w` (`X#1`, `F#1`, `S=R1`) on `line` where no parameter it reads is
    /// known but each holds a value of the last arrival ([`Checker::jump_arrival`]): the
    /// value the word has where no jump arrives, a run that really occurs (review 41,
    /// finding 0). Read for a position, a feed, a speed and a tool number, whose limits
    /// (TG601-TG606) say it is out of range on that run; the word is taken as unknown after
    /// its block ([`Checker::arrival_forget`]) and TG141 says so, as for any value not known.
    /// (Asked only where an arrival keeps values, of a word with an expression.)
    #[cold]
    #[inline(never)]
    pub(super) fn arrival_word(
        &mut self,
        w: &super::Word<'_>,
        line: usize,
        extended: bool,
    ) -> Option<Dec> {
        if !w.index.is_empty() || extended {
            return None;
        }
        self.arrival_value(w, line)
    }

    /// [`Checker::arrival_word`] of a word with no index.
    #[inline]
    fn arrival_value(&mut self, w: &super::Word<'_>, line: usize) -> Option<Dec> {
        let letter = w.letter;
        if !(crate::modal::axis_index(letter).is_some() || matches!(letter, b'F' | b'S' | b'T')) {
            return None;
        }
        let arrival = self.arrival.as_ref()?;
        if arrival.then.is_empty() {
            return None;
        }
        let value = if self.config.family == Family::Sinumerik {
            let expression = w.expression;
            let tree = expr::sinumerik_tree(expression).ok()?;
            let known = |p: &[u8]| {
                let key = sinumerik_key(p);
                self.params
                    .get(&key)
                    .or_else(|| arrival.then.get(&key))
                    .copied()
            };
            expr::sinumerik_value(&tree, expression, &known)?
        } else {
            let (negative, key) = self.parameter_key(w.expression)?;
            if self.params.contains_key(&key) {
                return None;
            }
            let value = *arrival.then.get(&key)?;
            if negative {
                -value
            } else {
                value
            }
        };
        if self.arrival_line != line {
            self.arrival_line = line;
            self.arrival_letters = 0;
            self.arrival_words.clear();
        }
        self.arrival_letters |= crate::modal::bit(letter);
        self.arrival_words.push((w.column, w.token(), value));
        self.not_evaluated(line, w);
        Some(value)
    }

    /// After the block on `line`: what its words read from an arrival set is unknown again
    /// ([`Checker::arrival_value`]): where the jump arrives, it is another value.
    #[cold]
    #[inline(never)]
    pub(super) fn arrival_forget(&mut self, line: usize) {
        let letters = std::mem::take(&mut self.arrival_letters);
        if self.arrival_line != line {
            return;
        }
        for letter in b'A'..=b'Z' {
            if letters & crate::modal::bit(letter) == 0 {
                continue;
            }
            match letter {
                b'F' => self.machine.forget_feed(),
                b'S' => self.machine.forget_speed(),
                b'T' => {
                    self.machine.state.tool = None;
                    self.machine.state.unknown |= crate::modal::bit(b'T');
                }
                _ => self.machine.forget_axis(letter),
            }
        }
    }

    /// What a limit's finding (TG601-TG606) at `column` of `line` adds where the word there
    /// was read with the value of an arrival ([`Checker::arrival_value`]): the word, its
    /// value and where it holds it.
    #[cold]
    pub(super) fn arrival_said(&self, rule: Rule, line: usize, column: usize) -> Option<String> {
        if self.arrival_letters == 0 || self.arrival_line != line {
            return None;
        }
        if !matches!(
            rule,
            Rule::TravelExceeded
                | Rule::FeedTooHigh
                | Rule::SpeedTooHigh
                | Rule::ToolOutOfRange
                | Rule::FeedClamped
                | Rule::SpeedLimited
        ) {
            return None;
        }
        let (_, token, value) = self.arrival_words.iter().find(|w| w.0 == column)?;
        let arrival = self.arrival.as_ref()?;
        // (review 48 F13: where a run where a jump is taken reads the block, the value the
        // jump brings is that run's to judge)
        let there = if self.runs.is_empty() {
            "where a jump arrives there it is not known"
        } else {
            "where a jump is taken it holds the value the jump brings, judged by that run"
        };
        Some(format!(
            "; {token} is {value} {} (the value the blocks above line {} set; {there})",
            arrival.not_taken, arrival.line
        ))
    }

    /// Where a jump may arrive with another value of the parameter `expression` (`#1`) than
    /// the one the blocks above give it: its value in file order, the sequence number the jump
    /// arrives at and its line, when the parameter was known there (and forgotten,
    /// [`Checker::jump_arrival`]) and no block has set it since.
    pub(super) fn uncertain(&self, expression: &[u8]) -> Option<(Dec, u64, usize)> {
        let arrival = self.arrival.as_ref()?;
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
        arrival
            .then
            .get(&key)
            .map(|&value| (value, arrival.n, arrival.line))
    }

    /// The value a Custom Macro B assignment copies (`#3 = #1`, `#3 = -[#1]`): the parameter's
    /// where it is known; where it holds the fall-through's value at the last arrival, that
    /// value in `arrived` (the assigned parameter holds it there too: review 44 F3, the value
    /// that reaches a word through an assignment at the target) and None.
    pub(super) fn copied(&self, expression: &[u8], arrived: &mut Option<Dec>) -> Option<Dec> {
        let (negative, key) = self.parameter_key(expression)?;
        let sign = |v: Dec| if negative { -v } else { v };
        if let Some(&value) = self.params.get(&key) {
            return Some(sign(value));
        }
        *arrived = self
            .arrival
            .as_ref()
            .and_then(|a| a.then.get(&key))
            .map(|&v| sign(v));
        None
    }

    /// LinuxCNC: the value of an assignment's bracketed expression (`#<k> = [#<k> + 1]`)
    /// where every parameter it reads is known, worked out as rs274 does, in doubles
    /// (interp_execute.cc; [`Checker::linuxcnc_value_of`]): the first line of the setting
    /// read (its first turn in a loop, the values after it forgotten at the loop's closing
    /// line). Asked only where no earlier word of the line set a parameter (rs274 reads the
    /// line's words with the values from before it). None for a value it cannot work out, or
    /// one not finite (review 52, F7: a counter's loop known to turn again).
    pub(super) fn linuxcnc_evaluated(&self, expression: &[u8]) -> Option<Dec> {
        if expression.first() != Some(&b'[') {
            return None;
        }
        let value = self.linuxcnc_value_of(expression)?;
        if !value.is_finite() {
            return None;
        }
        Dec::parse(&format!("{value}"))
    }

    /// A SINUMERIK expression's value where what it reads is known or holds the
    /// fall-through's value at the last arrival (one at least: else it is known, or not).
    fn sinumerik_arrived(&self, expression: &[u8]) -> Option<Dec> {
        let arrival = self.arrival.as_ref().filter(|a| !a.then.is_empty())?;
        let tree = expr::sinumerik_tree(expression).ok()?;
        let known = |p: &[u8]| {
            let key = sinumerik_key(p);
            self.params
                .get(&key)
                .or_else(|| arrival.then.get(&key))
                .copied()
        };
        expr::sinumerik_value(&tree, expression, &known)
    }

    /// `[k] = value` or `#1 = value`, a `#` word's expression whose variable's number is
    /// an expression (blanks allowed around the `=`): the number where its value is known and
    /// whole (read as [`Checker::indirect_assignment`] reads it for the ranges of TG206 and
    /// TG209), and the value's text; None where it is no assignment.
    fn indirect_target<'t>(&self, expression: &'t [u8]) -> Option<(Option<u64>, &'t [u8])> {
        let (inner, rhs) = if expression.first() == Some(&b'[') {
            let close = crate::statement::brackets(expression, 0).ok()?;
            let rest = expression[close..].trim_ascii_start();
            (&expression[1..close - 1], rest.strip_prefix(b"=")?)
        } else {
            let eq = expression.iter().position(|&c| c == b'=')?;
            (&expression[..eq], &expression[eq + 1..])
        };
        let number = crate::expr::tree(inner)
            .ok()
            .and_then(|tree| crate::expr::formula_value(&tree, inner, &|p| self.constant(p)))
            .filter(|v| *v >= Dec::ZERO && v.is_whole())
            .and_then(|v| u64::try_from(v.trunc()).ok());
        Some((number, rhs))
    }

    /// A parameter set since the last jump arrival: its value there no longer matters.
    fn set_since_arrival(&mut self, key: &[u8]) {
        if let Some(arrival) = &mut self.arrival {
            arrival.then.remove(key);
        }
    }

    /// A jump or call that forgets every parameter: the values of an arrival are no longer
    /// theirs either. LinuxCNC's endsub that closes a definition of the main program forgets
    /// the body's values only: rs274 reads a definition without running it (interp_o_word.cc
    /// skips from its sub to its endsub), so the main program's parameters after it are the
    /// ones known at its sub (`#<a> = 1` / `o<s> sub` ... `o<s> endsub` / `o1 if [#<a> GT 2]`
    /// is known false). A call runs the body, which may set them: forgotten there.
    pub(super) fn params_forgotten(&mut self) {
        if self.linuxcnc_sub_closed == Some(self.stats.blocks) {
            self.params = std::mem::take(&mut self.linuxcnc_sub_params);
        } else {
            self.params.clear();
        }
        self.arrival = None;
    }

    /// SINUMERIK: a `D=R1` (`w`) on `line` under G41/G42 (`compensation`) quieted by the
    /// known value of what it reads: noted, for a jump back to a block number before it
    /// ([`Checker::jump_back_to_number`]).
    pub(super) fn quiet_d_noted(&mut self, w: &super::Word<'_>, line: usize, compensation: i64) {
        if self.quiet_d.len() >= QUIET_D {
            return;
        }
        let mut reads = Vec::new();
        let text = w.expression;
        let mut i = 0;
        while i < text.len() {
            let c = text[i];
            if c.is_ascii_alphabetic() || c == b'_' {
                let end = text[i..]
                    .iter()
                    .position(|&c| !(c.is_ascii_alphanumeric() || c == b'_'))
                    .map_or(text.len(), |e| i + e);
                reads.push(sinumerik_key(&text[i..end]));
                i = end;
            } else {
                i += 1;
            }
        }
        self.quiet_d.push(QuietD {
            line,
            column: w.column,
            token: w.token(),
            compensation,
            reads,
        });
    }

    /// SINUMERIK: a jump on `line` back to block number `name` (`GOTOB N10`): each `D=R1`
    /// at or after that block that a known value quieted (TG503 not said) is TG503 now where
    /// what it reads was assigned between that block and the jump: the next pass reads the D
    /// with another value (review 41, finding 3; the block number's block was read before
    /// the jump, with the values above it).
    fn jump_back_to_number(&mut self, line: usize, name: &[u8]) {
        let Some((_, from)) = self.targets.sinumerik_lines(name) else {
            return;
        };
        let notes = std::mem::take(&mut self.quiet_d);
        let mut kept = Vec::with_capacity(notes.len());
        for note in notes {
            let assigned = (note.line >= from)
                .then(|| {
                    note.reads.iter().find_map(|key| {
                        self.assigned_at
                            .get(key)
                            .filter(|&&at| at >= from)
                            .map(|&at| (key, at))
                    })
                })
                .flatten();
            let Some((key, at)) = assigned else {
                kept.push(note);
                continue;
            };
            let g = note.compensation;
            let message = format!(
                "{} while G{g} is active: the jump of line {line} back to {} comes to it again \
                 with {} as assigned on line {at}, not the value read on the first pass: the \
                 D's value is not known there; a D change is allowed under compensation \
                 (840Di sl Fundamentals 8.8), but if it is 0, D0 switches the offset off under \
                 G{g} and the tool cuts a radius into the part",
                note.token,
                String::from_utf8_lossy(name),
                String::from_utf8_lossy(key),
            );
            self.report(
                Rule::UnknownDInCompensation,
                message,
                note.line,
                note.column,
            );
        }
        self.quiet_d = kept;
    }

    /// SINUMERIK: a `D=R1` (`w`) whose value is not known, on `line` under G41/G42: where
    /// what it reads holds 0 in file order at an arrival (the run where no jump arrives,
    /// [`Checker::arrival_value`]), that D0 is TG502's finding (review 41, finding 0).
    pub(super) fn arrival_d0(&mut self, w: &super::Word<'_>, line: usize, compensation: i64) {
        let Some(arrival) = self.arrival.as_ref().filter(|a| !a.then.is_empty()) else {
            return;
        };
        let Ok(tree) = expr::sinumerik_tree(w.expression) else {
            return;
        };
        let known = |p: &[u8]| {
            let key = sinumerik_key(p);
            self.params
                .get(&key)
                .or_else(|| arrival.then.get(&key))
                .copied()
        };
        let zero =
            expr::sinumerik_value(&tree, w.expression, &known).is_some_and(|v| v.to_f64() == 0.0);
        if !zero {
            return;
        }
        let message = format!(
            "{} while G{compensation} is active: D0 {} (the value the blocks above line {} \
             set; where a jump arrives there it is not known), which switches the offset off \
             under G{compensation}: the tool cuts a radius into the part; program G40 first",
            w.token(),
            arrival.not_taken,
            arrival.line
        );
        self.report(Rule::ToolChangeInCompensation, message, line, w.column);
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
                    // (a work offset's system variable, or one whose number is worked out:
                    // the offset may hold its value or the new one, not known; review
                    // 76-calls76 F4: `G55` / `IF [#1 EQ 1] THEN #5241=0.` / `G0 X-700.` was
                    // judged under the profile's G55)
                    let number = std::str::from_utf8(&target[1..])
                        .ok()
                        .and_then(|n| n.trim().parse::<u32>().ok());
                    if number.is_none_or(
                        |n| matches!(n, 2500..=2906 | 5201..=5399 | 7001..=7999 | 14001..=19999),
                    ) {
                        self.conditional_offset_write(b.line);
                    }
                }
            }
            return;
        }
        if self.config.family != Family::Sinumerik {
            return;
        }
        for &(_, kind, text) in b.statements {
            match kind {
                Kind::Assignment => self.variable(text, b.line),
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
                        self.variable(&[name, &b"="[..], value].concat(), b.line);
                    }
                }
                _ => {}
            }
        }
    }

    /// `NAME = expression` on `line`: the variable known, or unknown again (not a simple
    /// name: skipped).
    pub(super) fn variable(&mut self, text: &[u8], line: usize) {
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
        let arrived = (value.is_none() && self.arrival.is_some())
            .then(|| self.sinumerik_arrived(rhs))
            .flatten();
        self.set_since_arrival(&key);
        if let (Some(v), Some(arrival)) = (arrived, self.arrival.as_mut()) {
            arrival.then.insert(key.clone(), v);
        }
        self.assigned_at.insert(key.clone(), line);
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
    #[inline]
    pub(super) fn assignments(&mut self, b: &BlockView<'_>) {
        // (only a `#` word or an indexed one sets a parameter: most blocks have neither)
        if self.letters & (super::PARAMETER | super::INDEXED) == 0 {
            return;
        }
        self.assignments_of(b);
    }

    /// A work offset's system variable set (FANUC Custom
    /// Macro B, "System variables": #5201-#5206 the external offset, #5221-#5326 G54-G59,
    /// twenty a system from #5221, its axes in order; a Haas's the same numbers, Mill
    /// Operator's Manual, Macro Variables Table; LinuxCNC's numbered parameters likewise):
    /// the offset's value is no longer the one the G10 wrote, and not followed here
    /// ([`Checker::offsets_written`]: review 59a F11, `G10 L2 P2 X-200.` / `#5241=0.`). The
    /// axis a number names depends on the machine's axis order: every axis of that offset
    /// written before is taken as not known, as is every offset for the external one or for
    /// a variable chosen by a value (`#[#1]=`).
    #[cold]
    fn offset_variables(&mut self, b: &BlockView<'_>) {
        for w in b.words {
            if w.address != b'#' {
                continue;
            }
            let number = std::str::from_utf8(w.index)
                .ok()
                .and_then(|n| n.parse::<u32>().ok());
            let g = match number {
                Some(5201..=5206) => None,
                Some(n @ 5221..=5326) => Some((n - 5221) as usize / 20),
                None if w.index.is_empty() => None,
                _ => continue,
            };
            // (a program read apart with no offset in force: its positions after it are
            // not its caller's offset's)
            self.work_unplaced = false;
            // (the axis the variable names, its value where a number surely run, as a G10
            // L2 writes it; every axis of that offset where the axis cannot be named:
            // review 60 F3, `#5241=0.` / `G90 G55` / `M98 P1000` ran O1000's X-700. at
            // -700, and it was judged with the profile's -100; review 62a F10)
            let writes = self.variable_writes(w, g, number, b.line);
            self.offsets_written.then(&writes);
            // (and where a call the checker does not follow runs the program in hand, or
            // a caller calls it)
            self.offset_writer(&writes, false);
        }
    }

    /// [`Checker::assignments`] of a block with a `#` word or an indexed one.
    #[inline(never)]
    fn assignments_of(&mut self, b: &BlockView<'_>) {
        if !self.config.work_offsets.is_empty() {
            self.offset_variables(b);
        }
        // (review 62a F1)
        if !self.offset_variable_written || self.early_on {
            self.after_assignment(b);
        }
        // LinuxCNC: every setting of a line reads the values from before the line (RS274/NGC
        // 3.0, 3.2.1; review 48 F15: `#1=-900 #3=#1` copies the old #1): those set by an
        // earlier word of the line, by key, their values before it, known and at the arrival
        let linuxcnc = self.config.family == Family::LinuxCnc;
        let mut set_before: Vec<(Vec<u8>, Option<Dec>, Option<Dec>)> = Vec::new();
        for w in b.words {
            // (a value read from the fall-through's at the last arrival: kept there)
            let mut arrived = None;
            let (name, value) = match w.address {
                // #3 = #1 (signed or in brackets): a copy of a known value
                b'#' if !w.index.is_empty() && w.number.is_empty() && !w.expression.is_empty() => {
                    let earlier = if set_before.is_empty() {
                        None
                    } else {
                        self.parameter_key(w.expression)
                            .and_then(|(negative, key)| {
                                let s = set_before.iter().find(|s| s.0 == key)?;
                                Some((negative, s.1, s.2))
                            })
                    };
                    let value = match earlier {
                        Some((negative, old, then)) => {
                            let sign = |v: Dec| if negative { -v } else { v };
                            if old.is_none() {
                                arrived = then.map(sign);
                            }
                            old.map(sign)
                        }
                        None => self.copied(w.expression, &mut arrived),
                    };
                    let value = value.or_else(|| {
                        (linuxcnc && set_before.is_empty())
                            .then(|| self.linuxcnc_evaluated(w.expression))
                            .flatten()
                    });
                    (parameter_name(b'#', w.index), value)
                }
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
                        let value = self.sinumerik_constant(w.expression);
                        if value.is_none() && self.arrival.is_some() {
                            arrived = self.sinumerik_arrived(w.expression);
                        }
                        value
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
                // #[k] = value (Custom Macro B: a variable's number may be an expression in
                // brackets, on the left of `=` too; LinuxCNC's `##1 = value` likewise): with k
                // known and whole, the assignment to #k; else any parameter may be the one
                // set, and none is known after it (review 53, F6)
                b'#' if matches!(w.expression.first(), Some(b'[' | b'#')) => {
                    let Some((number, rhs)) = self.indirect_target(w.expression) else {
                        continue;
                    };
                    // (LinuxCNC reads the number with the values from before the line: after
                    // an earlier setting of the line, `#1=2 ##1=900`, the number is taken as
                    // not known; review 54, F3)
                    let number = number.filter(|_| !linuxcnc || set_before.is_empty());
                    let Some(number) = number else {
                        self.params.clear();
                        self.arrival = None;
                        continue;
                    };
                    let text: Vec<u8> = rhs.iter().copied().filter(|&c| !blank(c)).collect();
                    let value = std::str::from_utf8(&text)
                        .ok()
                        .and_then(Dec::parse)
                        .or_else(|| self.copied(&text, &mut arrived))
                        .or_else(|| {
                            (linuxcnc && set_before.is_empty())
                                .then(|| self.linuxcnc_evaluated(&text))
                                .flatten()
                        });
                    (parameter_name(b'#', number.to_string().as_bytes()), value)
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
                    let value = value.or_else(|| {
                        (linuxcnc && set_before.is_empty())
                            .then(|| self.linuxcnc_evaluated(&text))
                            .flatten()
                    });
                    (named_parameter(&w.expression[1..close]), value)
                }
                _ => continue,
            };
            // a setting the block skip deletes (`/#1=5`, or after a `/` inside the block): the
            // block delete switch is the operator's, on or off at the machine, so the value
            // after it is the old one or the new and known as neither (`rs274 -g` runs it
            // with the switch off, `rs274 -b -g` deletes it; review 49a, F4)
            let value = if b.skip || b.skip_within.is_some_and(|c| w.column > c) {
                arrived = None;
                None
            } else {
                value
            };
            if linuxcnc && !set_before.iter().any(|s| s.0 == name) {
                let then = self
                    .arrival
                    .as_ref()
                    .and_then(|a| a.then.get(&name))
                    .copied();
                set_before.push((name.clone(), self.params.get(&name).copied(), then));
            }
            if linuxcnc && !self.linuxcnc_open_flow.is_empty() {
                // (review 48, F10: a closing label worked out from it reads the new value)
                let assigned = &mut self.linuxcnc_flow_assigned;
                if assigned.len() < 256 {
                    assigned.push((b.line, name.clone()));
                } else if assigned.last().is_some_and(|a| !a.1.is_empty()) {
                    assigned.push((b.line, Vec::new()));
                }
            }
            if self.arrival.is_some() {
                self.set_since_arrival(&name);
                if let (Some(v), Some(arrival)) = (arrived, self.arrival.as_mut()) {
                    arrival.then.insert(name.clone(), v);
                }
            }
            if self.config.family == Family::Sinumerik {
                self.assigned_at.insert(name.clone(), b.line);
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
        // a jump surely taken to the next numbered block brings its values (review 53, F17);
        // a numbered block between may be another way in, setting another
        let jump = "#101 = 1500.\nGOTO 10\nN10 G01 X1. F#101";
        assert_eq!(feed(Family::MacroB, jump), (vec![4], vec![]));
        let jump = "#101 = 1500.\nGOTO 10\nN5 #101 = 100.\nN10 G01 X1. F#101";
        assert_eq!(feed(Family::MacroB, jump), (vec![], vec![5]));
    }

    /// Review 41, finding 0: at a sequence number a GOTO read before names, the values set
    /// since the jump are the values where it is not taken, a run that really occurs: the
    /// limits read them (iso-mill's travel X -500..500, feed 999.9, speed 6000), and the
    /// finding says where they hold.
    #[test]
    fn a_jump_target_keeps_the_value_where_the_jump_is_not_taken() {
        use super::super::testing::findings;
        let config = || of_family(Family::MacroB);
        // line 2 X400, line 6 N10 X#1 = -700 where line 4's jump is not taken: 1100 > 1000
        let travel = "G0 X400. Y0\n#1=0\nIF[#2EQ1]GOTO10\n#1=-700.\nN10 G0 X#1";
        let found = findings(config(), &program(travel), Rule::TravelExceeded);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (6, 8));
        assert!(
            found[0].message.ends_with(
                "; X#1 is -700 where the jump of line 4 is not taken (the value the blocks \
                 above line 6 set; where a jump is taken it holds the value the jump brings, \
                 judged by that run)"
            ),
            "{}",
            found[0].message
        );
        // two jumps to N10: the message names the first, and says there are more
        let two = "G0 X400. Y0\nIF[#2EQ1]GOTO10\nIF[#3EQ1]GOTO10\n#1=-700.\nN10 G0 X#1";
        let found = findings(config(), &program(two), Rule::TravelExceeded);
        assert!(
            found[0]
                .message
                .contains("X#1 is -700 where none of the jumps to N10 (the first on line 3)"),
            "{}",
            found[0].message
        );
        // the value is unknown after its block (TG141), as where the jump arrives
        let after = format!("{travel}\nG91 G0 X-400.");
        assert_eq!(
            fired(config(), &program(&after), Rule::TravelExceeded),
            [(6, 8)]
        );
        assert_eq!(
            fired(config(), &program(travel), Rule::NotEvaluated),
            [(6, 8)]
        );
        // a computed GOTO (r7.nc): every numbered block after it may be its target
        let computed = "N1 G0 X400. Y0\nN2 IF[#3EQ1]GOTO#5\nN3 #1=-700.\nN4 G0 X#1";
        assert_eq!(
            fired(config(), &program(computed), Rule::TravelExceeded),
            [(5, 7)]
        );
        // right after a GOTO outside an IF no run falls through: the value set between the
        // GOTO and N10 (unreached) is no value at all
        let cut = "G0 X400. Y0\nIF[#2EQ1]GOTO10\nGOTO 20\n#1=-700.\nN20 M5\nN10 G0 X#1";
        assert_eq!(fired(config(), &program(cut), Rule::TravelExceeded), []);
        // a feed (FANUC: clamped, TG605) and a speed (6000) likewise
        let feed = "#1=100.\nIF[#2EQ1]GOTO10\n#1=2000.\nN10 G1 X1. F#1";
        assert_eq!(
            fired(config(), &program(feed), Rule::FeedClamped),
            [(5, 12)]
        );
        let speed = "#1=1000\nIF[#2EQ1]GOTO10\n#1=8000\nN10 S#1 M3";
        assert_eq!(
            fired(config(), &program(speed), Rule::SpeedLimited).len()
                + fired(config(), &program(speed), Rule::SpeedTooHigh).len(),
            1
        );
    }

    /// Review 41, finding 0's older half: a conditional jump forward not taken changes no
    /// parameter (r5.nc); a jump back and a computed one still forget them all.
    #[test]
    fn a_conditional_jump_forward_keeps_the_parameters_where_it_falls_through() {
        let config = || of_family(Family::MacroB);
        let forward = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\nG0 X#1\nN10 M5";
        assert_eq!(
            fired(config(), &program(forward), Rule::TravelExceeded),
            [(5, 4)]
        );
        assert_eq!(fired(config(), &program(forward), Rule::NotEvaluated), []);
        let back = "N10 G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\nG0 X#1";
        assert_eq!(fired(config(), &program(back), Rule::TravelExceeded), []);
        assert_eq!(
            fired(config(), &program(back), Rule::NotEvaluated),
            [(5, 4)]
        );
        let computed = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO#3\nG0 X#1";
        assert_eq!(
            fired(config(), &program(computed), Rule::TravelExceeded),
            []
        );
        // a call: the subprogram may set #1
        let call = "G0 X400. Y0\n#1=-700.\nM98 P100\nG0 X#1";
        assert_eq!(fired(config(), &program(call), Rule::TravelExceeded), []);
        // SINUMERIK: IF .. GOTOF keeps R1, IF .. GOTOB forgets it
        let sinumerik = || of_family(Family::Sinumerik);
        let gotof = "G0 X400 Y0\nR1=-700\nIF R2==1 GOTOF LBL\nG0 X=R1\nLBL:\nM5";
        assert_eq!(
            fired(sinumerik(), &program(gotof), Rule::TravelExceeded),
            [(5, 4)]
        );
        let gotob = "LBL:\nG0 X400 Y0\nR1=-700\nIF R2==1 GOTOB LBL\nG0 X=R1";
        assert_eq!(
            fired(sinumerik(), &program(gotob), Rule::TravelExceeded),
            []
        );
    }

    /// SINUMERIK: a label keeps the values in file order aside as a Custom Macro B target
    /// does; a `D=R1` reading one is still TG503 (review 39, finding 3), and TG502 besides
    /// where that value is 0.
    #[test]
    fn a_sinumerik_label_keeps_the_value_where_no_jump_arrives() {
        use super::super::testing::findings;
        let config = || of_family(Family::Sinumerik);
        let travel = "G0 X400 Y0\nR1=-700\nLBL:\nG0 X=R1";
        let found = findings(config(), &program(travel), Rule::TravelExceeded);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(
            found[0]
                .message
                .contains("X=R1 is -700 where no jump arrives at the label LBL"),
            "{}",
            found[0].message
        );
        let head = "T1 D1\nM6\nS1000 M3\nG0 X0 Y0 Z5\nG1 G41 X10 Y0 F100\n";
        let zero = format!("{head}R1=5\nIF R2==1 GOTOF LBL\nR1=0\nLBL:\nD=R1 X20\nG40 G0 X60");
        assert_eq!(
            fired(config(), &program(&zero), Rule::UnknownDInCompensation),
            [(11, 1)]
        );
        assert_eq!(
            fired(config(), &program(&zero), Rule::ToolChangeInCompensation),
            [(11, 1)]
        );
        let five = zero.replace("R1=0", "R1=7");
        assert_eq!(
            fired(config(), &program(&five), Rule::ToolChangeInCompensation),
            []
        );
    }

    /// Review 41, finding 3 (fix (a)): a jump back to a block number (`GOTOB N10`) makes a
    /// `D=R1` at or after it that a known value quieted TG503 where R1 is assigned between
    /// the block and the jump; N-numbered blocks without such a loop stay quiet.
    #[test]
    fn a_jump_back_to_a_block_number_comes_to_d_with_another_value() {
        let config = || of_family(Family::Sinumerik);
        let head = "T1 D1\nM6\nS1000 M3\nR1=5\nR2=0\nG0 X0 Y0 Z5\nG1 G41 X10 Y0 F100\n";
        let looped = format!("{head}N10 D=R1 X20\nR1=0\nR2=R2+1\nIF R2<2 GOTOB N10\nG40 G0 X60");
        assert_eq!(
            fired(config(), &program(&looped), Rule::UnknownDInCompensation),
            [(9, 5)]
        );
        // the loop does not assign R1: the D reads 5 on every pass
        let kept = looped.replace("R1=0\n", "");
        assert_eq!(
            fired(config(), &program(&kept), Rule::UnknownDInCompensation),
            []
        );
        // no jump back: quiet, numbered blocks or not
        let plain = format!("{head}N10 D=R1 X20\nN20 R1=0\nN30 G40 G0 X60");
        assert_eq!(
            fired(config(), &program(&plain), Rule::UnknownDInCompensation),
            []
        );
        // the jump back to a block after the D passes over none of it
        let after = format!("{head}D=R1 X20\nN20 R1=0\nIF R2<2 GOTOB N20\nG40 G0 X60");
        assert_eq!(
            fired(config(), &program(&after), Rule::UnknownDInCompensation),
            []
        );
    }

    /// Review 44 F3: at a jump target, the run where a forward jump is taken arrives with
    /// the values the parameters hold at the jump's line, and the limits judge it as they
    /// judge the fall-through's (iso-mill's travel X -500..500, feed 999.9).
    #[test]
    fn a_forward_jump_taken_carries_the_values_of_its_line() {
        use super::super::testing::findings;
        let config = || of_family(Family::MacroB);
        let travel = |body: &str| findings(config(), &program(body), Rule::TravelExceeded);
        // the review's program: the jump of line 4 arrives at N10 with #1 = -700
        let taken = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 X#1";
        let found = travel(taken);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (6, 8));
        // (the sample machine's hint after it, as at the file's own first finding)
        assert!(
            found[0].message.contains(
                "; X#1 is -700 where the jump of line 4 is taken (read from the values the \
                 parameters hold there) (the built-in profile's limits"
            ),
            "{}",
            found[0].message
        );
        assert!(found[0]
            .message
            .starts_with("X spans 1100 (from -700 to 400)"));
        // still TG141 at the word: in the file's reading its value is not known after it
        assert_eq!(
            fired(config(), &program(taken), Rule::NotEvaluated),
            [(6, 8)]
        );
        // where the candidates agree, nothing changes: the fall-through's finding alone
        let agree = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\nN10 G0 X#1";
        let found = travel(agree);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0]
            .message
            .contains("where the jump of line 4 is not taken"));
        let inside = "G0 X400. Y0\n#1=-50.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 X#1";
        assert_eq!(travel(inside).len(), 0);
        // the value reaching the target through an assignment there, both ways
        let copied = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 #3=#1\nG0 X#3";
        let found = travel(copied);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (7, 4));
        assert!(
            found[0]
                .message
                .contains("; X#3 is -700 where the jump of line 4 is taken"),
            "{}",
            found[0].message
        );
        let fallen = "G0 X400. Y0\n#1=0\nIF[#2EQ1]GOTO10\n#1=-700.\nN10 #3=-[#1]\nG0 X-#3";
        let found = travel(fallen);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(
            found[0]
                .message
                .contains("; X-#3 is -700 where the jump of line 4 is not taken"),
            "{}",
            found[0].message
        );
        // a copy of a known value is known, jump or not
        assert_eq!(travel("G0 X400. Y0\n#1=-700.\n#3=#1\nG0 X#3").len(), 1);
        // the run where the jump is taken passes over the blocks between: X600 is not in
        // its span (0..600 where it falls through, -600..0 where it is taken: each fits)
        let over = "G0 X0 Y0\n#1=-600.\nIF[#2EQ1]GOTO10\nG0 X600.\n#1=0\nN10 G0 X#1";
        assert_eq!(travel(over).len(), 0, "{:?}", travel(over));
        // two jumps bring it: said once; more than three: TG141 alone, as before
        let two = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\nIF[#3EQ1]GOTO10\n#1=0\nN10 G0 X#1";
        let found = travel(two);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0]
            .message
            .contains("where the jump of line 4 is taken"));
        let four = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\nIF[#3EQ1]GOTO10\n\
                    IF[#4EQ1]GOTO10\nIF[#5EQ1]GOTO10\n#1=0\nN10 G0 X#1";
        assert_eq!(travel(four).len(), 0);
        // a feed (FANUC: clamped, TG605) likewise
        let feed = "#1=2000.\nIF[#2EQ1]GOTO10\n#1=100.\nN10 G1 X1. F#1";
        let found = findings(config(), &program(feed), Rule::FeedClamped);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (5, 12));
        assert!(found[0]
            .message
            .contains("F#1 is 2000 where the jump of line 3 is taken"));
        // the run ends where its parameters hold the file's values: a later X#1 is the
        // file's, known
        let later = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 M5\n#1=0\nG0 X#1";
        assert_eq!(travel(later).len(), 0);
    }

    /// Review 44 F3 on a SINUMERIK: `GOTOF` to a label or a block number, R parameters.
    #[test]
    fn a_sinumerik_jump_taken_carries_the_values_of_its_line() {
        use super::super::testing::findings;
        let config = || of_family(Family::Sinumerik);
        let travel = |body: &str| findings(config(), &program(body), Rule::TravelExceeded);
        let label = "G0 X400 Y0\nR1=-700\nIF R2==1 GOTOF LBL\nR1=0\nLBL:\nG0 X=R1";
        let found = travel(label);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].line, 7);
        assert!(
            found[0]
                .message
                .contains("; X=R1 is -700 where the jump of line 4 is taken"),
            "{}",
            found[0].message
        );
        let number = "G0 X400 Y0\nR1=-700\nIF R2==1 GOTOF N100\nR1=0\nN100 R3=R1*1\nG0 X=R3";
        let found = travel(number);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(
            found[0]
                .message
                .contains("; X=R3 is -700 where the jump of line 4 is taken"),
            "{}",
            found[0].message
        );
        let fallen = "G0 X400 Y0\nR1=0\nIF R2==1 GOTOF N100\nR1=-700\nN100 R3=R1\nG0 X=R3";
        let found = travel(fallen);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0]
            .message
            .contains("where the jump of line 4 is not taken"));
        // a jump back is no run of this kind: its block forgets the parameters
        let back = "LBL:\nG0 X400 Y0\nR1=-700\nIF R2==1 GOTOB LBL\nR1=0\nG0 X=R1";
        assert_eq!(travel(back).len(), 0);
    }

    /// Review 48 F9 and F14: where a run where a jump is taken ends -- at a program's start
    /// (an O number or a `%` after the first block, whether the program before ended or not),
    /// an end (M30, M99), a call, another jump, after 64 blocks -- and the four jumps kept
    /// (iso-mill's X travel -500..500).
    #[test]
    fn where_a_jump_run_ends() {
        use super::super::testing::findings;
        // (a FANUC's O number)
        let config = || {
            let mut config = of_family(Family::MacroB);
            config.facts.program_number = Some(b'O');
            config
        };
        let travel = |body: &str| findings(config(), &program(body), Rule::TravelExceeded).len();
        let head = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\n";
        // the run judged: the control
        assert_eq!(travel(&format!("{head}N10 G0 Y0\nG0 X#1")), 1);
        // F9: the next program's locals are its own, whether the first ended or not
        assert_eq!(travel(&format!("{head}N10 G0 Y0\nO2000\nG0 X#1")), 0);
        assert_eq!(travel(&format!("{head}N10 G0 Y0\n%\n%\nO2000\nG0 X#1")), 0);
        assert_eq!(travel(&format!("{head}N10 M30\nO2000\nG0 X#1")), 0);
        assert_eq!(travel(&format!("{head}N10 M99\nO2000\nG0 X#1")), 0);
        // a jump whose target is in the next program arrives nowhere
        let across = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nO2000\n#1=0\nN10 G0 X#1";
        assert_eq!(travel(across), 0);
        // a call: not followed (the run's values end there); another jump: its run kept for
        // its target (review 48, F2: a_jump_met_in_a_run_is_followed)
        assert_eq!(travel(&format!("{head}N10 M98 P2000\nG0 X#1")), 0);
        assert_eq!(
            travel(&format!("{head}N10 G0 Y0\nGOTO20\nN15 G0 X0\nN20 G0 X#1")),
            1
        );
        // a jump back: its fall-through keeps the run's values (as jump48), a jump back with
        // no condition ends the run
        assert_eq!(
            travel(&format!("N5 M5\n{head}N10 G0 Y0\nIF[#3EQ1]GOTO5\nG0 X#1")),
            1
        );
        assert_eq!(
            travel(&format!("N5 M5\n{head}N10 G0 Y0\nGOTO5\nN15 G0 X#1")),
            0
        );
        // 64 blocks from the target on: the 60th judged, the 70th not
        let long = |n: usize| format!("{head}N10 G0 Y0\n{}G0 X#1", "G0 Y1.\n".repeat(n - 2));
        assert_eq!(travel(&long(60)), 1);
        assert_eq!(travel(&long(64)), 1);
        assert_eq!(travel(&long(65)), 0);
        assert_eq!(travel(&long(70)), 0);
        // four jumps kept: the fifth drops the oldest (its target judged as before)
        let jumps = |targets: &[u32]| {
            let mut body = String::from("G0 X400. Y0\n#1=-700.\n");
            for t in targets {
                body += &format!("IF[#2EQ{t}]GOTO{t}\n");
            }
            body += "#1=0\n";
            for t in &targets[1..] {
                body += &format!("N{t} M5\n#1=0\n");
            }
            body + "N10 G0 X#1"
        };
        assert_eq!(travel(&jumps(&[10, 20, 30, 40])), 1);
        assert_eq!(travel(&jumps(&[10, 20, 30, 40, 50])), 0);
    }

    /// Review 48, F2: a forward jump met inside a jump's run (`IF..GOTO`, `GOTO`, `GOTOF`)
    /// keeps the run's values for its target, as the file's own jump does: f4.nc's feed of
    /// 9999 where the jumps of lines 6 and 9 are both taken, j9.nc's X#1 past a `GOTO20`.
    /// Not where the run's values make its condition false; where they make it true, or it
    /// has none, nothing of the run falls through.
    #[test]
    fn a_jump_met_in_a_run_is_followed() {
        use super::super::testing::findings;
        let config = || {
            let mut config = of_family(Family::MacroB);
            config.facts.program_number = Some(b'O');
            config
        };
        let found = |body: &str, rule| findings(config(), &program(body), rule);
        // f4.nc (the iso-mill's feeds to 999.9, which a FANUC clamps: TG605): F9999. where #2
        // and #3 are both 1
        let f4 = "G0 X1. Y0\n#9=9999.\nIF[#2EQ1]GOTO10\n#9=500.\nN10 G0 Y0\n\
                  IF[#3EQ1]GOTO20\n#9=400.\nN20 G1 X3. F#9";
        let feeds = found(f4, Rule::FeedClamped);
        assert_eq!(feeds.len(), 1, "{feeds:?}");
        assert_eq!((feeds[0].line, feeds[0].column), (9, 12));
        assert!(
            feeds[0]
                .message
                .contains("F#9 is 9999 where the jumps of lines 4 and 7 are taken"),
            "{}",
            feeds[0].message
        );
        // j9.nc: an unconditional GOTO in the run (X -500..500)
        let j9 = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\nGOTO20\n\
                  N15 G0 X0\nN20 G0 X#1";
        let spans = found(j9, Rule::TravelExceeded);
        assert_eq!(spans.len(), 1, "{spans:?}");
        assert!(spans[0]
            .message
            .contains("where the jumps of lines 4 and 7 are taken"));
        // three deep: each jump met in the run of the one before
        let deep = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\n\
                    IF[#3EQ1]GOTO20\n#1=0\nN20 G0 Y0\nIF[#4EQ1]GOTO30\n#1=0\nN30 G0 X#1";
        let spans = found(deep, Rule::TravelExceeded);
        assert_eq!(spans.len(), 1, "{spans:?}");
        assert!(spans[0]
            .message
            .contains("where the jumps of lines 4, 7 and 10 are taken"));
        // the condition: false by the run's values (#5 is 0), no run of it; true (#5 is 1),
        // the run where line 4's jump is taken goes to N20 and not on to the X#1 between
        let with = |five: &str, between: &str| {
            format!(
                "G0 X400. Y0\n#5={five}\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\n\
                 IF[#5EQ1]GOTO20\n{between}\nN20 G0 X#1"
            )
        };
        let lines = |body: &str| -> Vec<usize> {
            found(body, Rule::TravelExceeded)
                .iter()
                .map(|f| f.line)
                .collect()
        };
        // #1 set to 5 in the run's fall-through: the run arrives with 5 alone
        assert_eq!(lines(&with("0", "#1=5.")), Vec::<usize>::new());
        assert_eq!(lines(&with("1", "#1=5.")), [10]);
        // the X#1 between is never run where line 4's jump is taken and #5 is 1
        assert_eq!(lines(&with("1", "G0 X#1")), [10]);
        assert_eq!(lines(&with("0", "G0 X#1")), [9]);
        // SINUMERIK: a GOTOF in the run of another (X -500..500)
        let sinumerik = "G0 X400 Y0\nR1=-700\nIF R2==1 GOTOF AA\nR1=0\nAA: G0 Y0\n\
                         IF R3==1 GOTOF BB\nR1=0\nBB: G0 X=R1";
        let spans = findings(
            of_family(Family::Sinumerik),
            &program(sinumerik),
            Rule::TravelExceeded,
        );
        assert_eq!(spans.len(), 1, "{spans:?}");
        assert!(spans[0]
            .message
            .contains("where the jumps of lines 4 and 7 are taken"));
    }

    /// Review 49: a run met by another keeps no place of the file's own jumps (R4); a run
    /// ends at a block that surely leaves -- M30, M99, a jump back whose condition its values
    /// make true (R1, R2); the sample machine's hint said once, a run's finding or not (R5).
    #[test]
    fn a_run_ends_where_the_control_leaves_and_the_file_keeps_its_own() {
        use super::super::testing::findings;
        let config = || {
            let mut config = of_family(Family::MacroB);
            config.facts.program_number = Some(b'O');
            config
        };
        let spans = |body: &str| -> Vec<(usize, String)> {
            findings(config(), &program(body), Rule::TravelExceeded)
                .into_iter()
                .map(|f| (f.line, f.message))
                .collect()
        };
        // R4 (ev3.nc): four jumps the run of line 4's meets fill the places; line 4's own
        // run still arrives at N100 and is judged there
        let ev3 = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO100\n#1=0\n#7=1.\nIF[#3EQ1]GOTO10\n\
                   #7=2.\nIF[#4EQ1]GOTO10\n#7=0\nN10 G0 Y0\n#8=1.\nIF[#6EQ1]GOTO20\n#8=2.\n\
                   IF[#9EQ1]GOTO30\nN20 G0 Y0\nN30 G0 Y0\nN100 G0 X#1";
        let found = spans(ev3);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0]
            .1
            .contains("X#1 is -700 where the jump of line 4 is taken"));
        // R4 (ev4.nc): three met runs and the file's own arrive at N20: the file's is judged
        let ev4 = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO20\n#1=0\n#7=1.\nIF[#3EQ1]GOTO10\n\
                   #7=2.\nIF[#4EQ1]GOTO10\n#7=3.\nIF[#5EQ1]GOTO10\n#7=0\nN10 G0 Y0\n\
                   IF[#6EQ1]GOTO20\nN20 G0 X#1";
        let found = spans(ev4);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].1.contains("where the jump of line 4 is taken"));
        // R1 (e8.nc, e9.nc): the run of line 4's jump ends at the M99 or M30 after its target;
        // the N20 after it is not where the control goes with #1 = -700
        for end in ["M99", "M30"] {
            let body = format!(
                "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\n{end}\nN20 G0 X#1"
            );
            assert_eq!(spans(&body), [], "{end}");
        }
        // ... while a jump over the M30 is followed (e4.nc)
        let over = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\n\
                    IF[#3EQ1]GOTO20\nM30\nN20 G0 X#1";
        let found = spans(over);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0]
            .1
            .contains("where the jumps of lines 4 and 7 are taken"));
        // R2 (b1.nc): a jump back whose condition the run's values make true leaves; the
        // block after it is not the run's
        let b1 = "G0 X400. Y0\n#1=-700.\n#5=1\nIF[#2EQ1]GOTO30\n#1=0\n#5=0\nN20 #1=0\n\
                  #5=0\nN30 IF[#5EQ1]GOTO20\nG0 X#1";
        assert_eq!(spans(b1), []);
        // review 50 F10: a jump back the block-skip switch can pass over does not end the
        // run, as `/M30` does not: with the switch on, the X#1 after it runs with -700
        for jump in ["/IF[#5EQ1]GOTO5", "/M30", "G0 Y1."] {
            let body = format!(
                "N5 G0 X400. Y0\n#1=-700.\n#5=1\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\n\
                 {jump}\nG0 X#1"
            );
            let found = spans(&body);
            assert_eq!(found.len(), 1, "{jump}: {found:?}");
            assert_eq!(found[0].0, 9, "{jump}");
        }
        // without the slash the jump back leaves; a `/GOTO5` with no condition is a jump
        // the reading does not follow, after which no parameter is known, the run's as the
        // file's (nothing judged, no false finding)
        for jump in ["IF[#5EQ1]GOTO5", "GOTO5", "/GOTO5"] {
            let body = format!(
                "N5 G0 X400. Y0\n#1=-700.\n#5=1\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\n\
                 {jump}\nG0 X#1"
            );
            assert_eq!(spans(&body), [], "{jump}");
        }
        // review 50 F9: a run's findings held for a program read apart (no units code yet: a
        // program that may be a subprogram) reach the file's reading, held there in turn
        let no_units = |units: &str| {
            let body = format!(
                "N5 {units}G0 X400. Y0\n#1=-7000.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 Y0\nG0 X#1"
            );
            findings(
                of_family(Family::MacroB),
                &program(&body),
                Rule::TravelExceeded,
            )
            .len()
        };
        assert_eq!(no_units("G21 "), 1);
        assert_eq!(no_units(""), 1);
        // R5 (hh1.nc): the run's TG601 carries the sample machine's hint, and no later one
        let hh1 = "G0 X400. Y0\n#1=-700.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 X#1\nG0 X-700.";
        let found = spans(hh1);
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(found[0].1.contains("where the jump of line 4 is taken"));
        let hinted = found
            .iter()
            .filter(|(_, m)| m.contains("typical machine of the family"))
            .count();
        assert_eq!(hinted, 1, "{found:?}");
        assert!(found[0].1.contains("typical machine of the family"));
    }

    /// Review 48 F15: on LinuxCNC every setting of a line reads the values from before it
    /// (RS274/NGC 3.0, 3.2.1): `#1=-700 #3=#1` copies the old #1 (rs274 moves to 5).
    #[test]
    fn a_linuxcnc_copy_reads_the_value_before_its_line() {
        use super::super::testing::findings;
        let travel =
            |body: &str| findings(of_family(Family::LinuxCnc), body, Rule::TravelExceeded).len();
        assert_eq!(travel("G0 X400 Y0\n#1=5\n#1=-700 #3=#1\nG0 X#3\nM2\n"), 0);
        assert_eq!(travel("G0 X400 Y0\n#1=5\n#1=-700 #3=-#1\nG0 X#3\nM2\n"), 0);
        assert_eq!(travel("G0 X400 Y0\n#1=700\n#1=5 #3=-#1\nG0 X#3\nM2\n"), 1);
        // on lines of their own, the new value
        assert_eq!(travel("G0 X400 Y0\n#1=5\n#1=-700\n#3=#1\nG0 X#3\nM2\n"), 1);
        // the old one not known: not known
        assert_eq!(
            fired(
                of_family(Family::LinuxCnc),
                "G0 X400 Y0\n#1=-700 #3=#1\nG0 X#3\nM2\n",
                Rule::NotEvaluated
            ),
            [(3, 4)]
        );
    }

    /// Review 53 F6: `#[k] = value` sets #k where k is known and whole (`#[2]`, `# [2] = `,
    /// `#[1+1]`, `#[#2]` with #2 known: its old value gone); with k unknown any parameter may
    /// be the one set, and none is known after it (iso-mill's X -500..500).
    #[test]
    fn an_assignment_to_a_bracketed_number_sets_that_parameter() {
        use super::super::testing::findings;
        let at = |body: &str, rule| -> Vec<(usize, usize)> {
            findings(of_family(Family::MacroB), &program(body), rule)
                .iter()
                .map(|f| (f.line, f.column))
                .collect()
        };
        let start = "G21 G17 G90 G54\nG0 X-400. Y0 Z1.\n";
        // the new value known: the old one's false TG601 gone, a real one found
        for set in ["#[2]=5.", "# [2] = 5.", "#[1+1]=5.", "#[ 2 ]=5."] {
            let body = format!("{start}#2=900.\n{set}\nG0 X#2");
            assert_eq!(at(&body, Rule::TravelExceeded), [], "{set}");
            assert_eq!(at(&body, Rule::NotEvaluated), [], "{set}");
        }
        for set in ["#[2]=900.", "# [2] = 900.", "#[1+1]=900.", "#[#2]=900."] {
            let body = format!("{start}#2=2\n{set}\nG0 X#2");
            assert_eq!(at(&body, Rule::TravelExceeded), [(6, 4)], "{set}");
        }
        // a copy of a known value
        let body = format!("{start}#1=900.\n#[2]=#1\nG0 X#2");
        assert_eq!(at(&body, Rule::TravelExceeded), [(6, 4)]);
        // the number not known (nor whole): no parameter known after it
        for set in ["#[#3]=5.", "#[2.5]=5.", "#[#3+1]=5."] {
            let body = format!("{start}#2=900.\n{set}\nG0 X#2");
            assert_eq!(at(&body, Rule::TravelExceeded), [], "{set}");
            assert_eq!(at(&body, Rule::NotEvaluated), [(6, 4)], "{set}");
        }
        // LinuxCNC's `##1 = value` (rs274ngc read_parameter_setting reads a value after `#`)
        let travel = |body: &str| {
            findings(of_family(Family::LinuxCnc), body, Rule::TravelExceeded)
                .iter()
                .map(|f| (f.line, f.column))
                .collect::<Vec<_>>()
        };
        assert_eq!(travel("G0 X-400 Y0\n#1=2\n#2=900\n##1=5\nG0 X#2\nM2\n"), []);
        assert_eq!(
            travel("G0 X-400 Y0\n#1=2\n#2=5\n##1=900\nG0 X#2\nM2\n"),
            [(5, 4)]
        );
    }

    /// Review 48 F1: a forward jump whose condition the known values make false is never
    /// taken, and keeps no run; made true, or not known, it does (iso-mill's X -500..500).
    #[test]
    fn a_jump_known_not_taken_keeps_no_run() {
        use super::super::testing::findings;
        let travel = |family, body: &str| {
            findings(of_family(family), &program(body), Rule::TravelExceeded).len()
        };
        let macro_b = |five: &str, condition: &str| {
            format!("G0 X400. Y0\n#1=-700.\n#5={five}\nIF[{condition}]GOTO10\n#1=0\nN10 G0 X#1")
        };
        // the review's program: #5 is 0, `#5EQ1` false: X400 -> X0 alone
        assert_eq!(travel(Family::MacroB, &macro_b("0", "#5EQ1")), 0);
        assert_eq!(travel(Family::MacroB, &macro_b("1", "#5EQ1")), 1);
        assert_eq!(travel(Family::MacroB, &macro_b("0", "#5 NE 0")), 0);
        assert_eq!(travel(Family::MacroB, &macro_b("0", "#5LT1")), 1);
        assert_eq!(travel(Family::MacroB, &macro_b("2", "#5 GE [#5]")), 1);
        assert_eq!(travel(Family::MacroB, &macro_b("2", "1GT#5")), 0);
        // a side not known, or more than one comparison: the run kept
        assert_eq!(travel(Family::MacroB, &macro_b("0", "#2EQ1")), 1);
        assert_eq!(travel(Family::MacroB, &macro_b("0", "#5+1EQ5")), 1);
        assert_eq!(travel(Family::MacroB, &macro_b("0", "[#5EQ1]OR[#2EQ1]")), 1);
        let sinumerik = |five: &str, condition: &str| {
            format!("G0 X400 Y0\nR1=-700\nR5={five}\nIF {condition} GOTOF LBL\nR1=0\nLBL: G0 X=R1")
        };
        assert_eq!(travel(Family::Sinumerik, &sinumerik("0", "R5==1")), 0);
        assert_eq!(travel(Family::Sinumerik, &sinumerik("1", "R5==1")), 1);
        assert_eq!(travel(Family::Sinumerik, &sinumerik("0", "R5<>0")), 0);
        assert_eq!(travel(Family::Sinumerik, &sinumerik("0", "R5<=0")), 1);
        assert_eq!(travel(Family::Sinumerik, &sinumerik("0", "R2==1")), 1);
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
