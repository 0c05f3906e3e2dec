//! LinuxCNC: what rs274ngc refuses in a body written after the main program's end, where a
//! call of the main program surely runs it (issue 32 item 4; review 78-lcnc78b M4, M15, M18,
//! A29, A83).
//!
//! The main program's `M98 P300` (or `o300 call`) seeks the body after the main program's end
//! and runs its lines one after the other (interp_o_word.cc `control_back_to`,
//! `convert_control_functions`): rs274 refuses there, as it runs them,
//!
//! - an `oN return` of a FANUC-style program `O300` ... `M99` ("Fanuc 'O....' subroutine
//!   definition must end with 'M99'"; M4),
//! - an `oN sub` in such a program ("'O.... sub' subroutine must be called with 'O....
//!   call'"; A29),
//! - an o-word line closing or continuing a block the body never opened, `o2 endif` (`N:
//!   undefined O-word label: 'o2 endif'`, whatever the main program has open; M18),
//! - a FANUC-style program whose every M99 is in a block that does not run: it runs on to
//!   the file's end ("File ended with no percent sign or program end"; M15), where no line
//!   but the ends of its blocks follows the M99 that closes it for the checker's reading
//!   ([`Checker::later_tail_line`]),
//! - an `M98 P300` (or an `o300 call`) of an `O300` (or an `o300 sub`) written after the
//!   main program's end but before the body: rs274 seeks the label forward from the call,
//!   and records none it passed over while seeking another ("EOF in file ... seeking
//!   o-word: o<300>"; A83).
//!
//! Said only where the line surely runs: the body is the first of its label after the end,
//! the main program's call surely runs and is its first calling line (a body called before
//! may end the program), no M2, M30 or M99 of the main program comes before it, every block of the body open is known to run from
//! numbers alone ([`super::structure::linuxcnc_constant_runs`]: `o1 if [1]`, not `o1 if
//! [#1]`, whose value a caller may have changed), and no line before it may have left the
//! body or ended the run (a call, an M2, M30, M99 or `return`, a `break` or `continue`, a
//! loop that may turn for ever). A block known not to run (`o1 if [0]`) is passed over, as
//! rs274 skips it. rs274 first runs a file named after the label on its subroutine path
//! where there is one (`rs274 -i` with `SUBROUTINE_PATH`): these are its refusals where no
//! such file stands in for the body, as the file's own reading of a call is elsewhere. A
//! call of a label the file never defines is no refusal: it is what the subroutine path is
//! for (LinuxCNC O codes, "Calling Files"; review 78-lcnc78b A36).

use super::structure::linuxcnc_constant_runs;
use super::{BlockView, Checker};
use crate::rules::Rule;
use crate::statement::Kind;

/// A block of the body open: its label, whether its lines run (known from numbers alone),
/// whether a branch of it before surely ran (an `if`'s), and its keyword.
#[derive(Debug, Clone)]
struct Open {
    label: Vec<u8>,
    runs: Option<bool>,
    taken: Option<bool>,
    keyword: Vec<u8>,
}

/// A call of a sure body seeking a label (`LaterBodies::seeking`).
#[derive(Debug, Clone)]
struct Seek {
    label: Vec<u8>,
    line: usize,
    column: usize,
    call: String,
    target: String,
}

/// The body a call of the main program surely runs, being read.
#[derive(Debug, Clone, Default)]
pub(super) struct SureBody {
    /// The body's label (`o300`), whether it is FANUC-style (`O300` ... `M99`), the line of
    /// the main program's call and where the body opened.
    label: Vec<u8>,
    fanuc: bool,
    call: usize,
    opened: usize,
    open: Vec<Open>,
    /// A line read before may have left the body or ended the run: nothing after it is said.
    left: bool,
    /// An M99 read in a block known not to run.
    skipped_m99: bool,
}

/// What the reading after the main program's end keeps for these refusals.
#[derive(Debug, Clone, Default)]
pub(super) struct LaterBodies {
    pub(super) sure: Option<SureBody>,
    /// The sure FANUC-style body closed for the checker's reading at an M99 in a block that
    /// does not run: rs274 runs on past it, and the lines after it are followed to the
    /// file's end ([`Checker::later_tail_line`]).
    pub(super) ran_on: Option<SureBody>,
    /// The label of the sure body refused at an o-word line before its end: rs274 stops
    /// there, and the refusal of its close is not said again.
    pub(super) refused: Option<Vec<u8>>,
    /// FANUC-style programs and o-word definitions read after the main program's end: the
    /// label, the line and whether it is FANUC-style (`O300`).
    defined: Vec<(Vec<u8>, usize, bool)>,
    /// The line of the main program's first calling line (an o-word `call`, an M98), 0 before
    /// one: a body it runs may end the program.
    first_call: usize,
    /// `O` number lines after the main program's end that no call before them names, passed
    /// over unread: the label and the line.
    passed: Vec<(Vec<u8>, usize)>,
    /// A call that surely runs in a sure body (`M98 P300`, `o300 call`) of a label whose
    /// program or definition is written after the end before the body only: the label, the
    /// line and column, and the call and what it seeks as the message names them; said at
    /// the file's end where no program or definition of the label comes after it.
    seeking: Vec<Seek>,
}

impl Checker {
    /// A definition after the main program's end opened (`text`'s label, `fanuc` for an
    /// `O300` line) on `line`: kept where the main program's call of it surely runs it.
    #[cold]
    #[inline(never)]
    pub(super) fn later_body_opened(&mut self, label: &[u8], fanuc: bool, line: usize) {
        let later = &mut self.linuxcnc_later_bodies;
        let first = !later.defined.iter().any(|d| d.0 == label)
            && !later.passed.iter().any(|d| d.0 == label);
        later.defined.push((label.to_vec(), line, fanuc));
        later.sure = None;
        let Some(call) = self
            .linuxcnc_later
            .ends
            .iter()
            .filter(|e| e.0 == label)
            .map(|e| e.1)
            .min()
        else {
            return;
        };
        // (a call of another body not read yet before it may end the program there; a call
        // of the other form is refused at the definition, Checker::linuxcnc_call_forms)
        let m98 = self
            .linuxcnc_m98_calls
            .iter()
            .any(|c| c.0 == label && c.1 == call);
        // (an M2, M30 or M99 of the main program before the call, in a condition whose
        // value is not known, may end the run before it: the first end read is the main
        // program's own only where it comes after the call)
        let end = self.linuxcnc_later.main_end;
        let before = |line: usize| line != 0 && line < call;
        if !first || m98 != fanuc || before(later.first_call) || before(end) {
            return;
        }
        later.sure = Some(SureBody {
            label: label.to_vec(),
            fanuc,
            call,
            opened: line,
            open: Vec::new(),
            left: false,
            skipped_m99: false,
        });
    }

    /// A calling line of the main program (`line`): the first kept.
    #[cold]
    #[inline(never)]
    pub(super) fn later_main_call(&mut self, line: usize) {
        let later = &mut self.linuxcnc_later_bodies;
        if later.first_call == 0 {
            later.first_call = line;
        }
    }
}

impl LaterBodies {
    /// Whether the main program has a calling line ([`Checker::later_main_call`]).
    pub(super) fn main_called(&self) -> bool {
        self.first_call != 0
    }
}

impl Checker {
    /// An `O` number line after the main program's end not read as a program (no call
    /// before it names it): kept for an `M98` of a body after it, which rs274 refuses.
    #[cold]
    #[inline(never)]
    pub(super) fn later_program_passed(&mut self, n: i64, line: usize) {
        let label = format!("o{n}").into_bytes();
        self.linuxcnc_later_bodies.passed.push((label, line));
    }

    /// A line of a definition read after the main program's end, before the checker's own
    /// reading of it: rs274's refusals where the sure body runs it.
    #[cold]
    #[inline(never)]
    pub(super) fn later_body_line(&mut self, b: &BlockView<'_>) {
        let Some(mut body) = self.linuxcnc_later_bodies.sure.take() else {
            return;
        };
        if b.line != body.opened && !body.left {
            self.sure_body_read(&mut body, b);
        }
        if self.open_definition.is_some() {
            self.linuxcnc_later_bodies.sure = Some(body);
        }
    }

    /// The definition after the main program's end closed (for the checker's reading): the
    /// sure FANUC-style body, where the M99 that closed it is in a block known not to run
    /// (`o1 if [0]` / `M99`), kept as run on past it ([`LaterBodies::ran_on`]): rs274 skips
    /// that M99 and reads the lines after it as the body's (review 78-lcnc78b M15).
    #[cold]
    #[inline(never)]
    pub(super) fn later_body_closed(&mut self) {
        let later = &mut self.linuxcnc_later_bodies;
        let Some(mut body) = later.sure.take() else {
            return;
        };
        let dead = body.open.iter().any(|o| o.runs == Some(false));
        if body.fanuc && !body.left && dead && !body.open.iter().any(turns) {
            body.skipped_m99 = true;
            later.ran_on = Some(body);
        }
    }

    /// A line after a FANUC-style body closed at an M99 that does not run
    /// ([`LaterBodies::ran_on`]): the run goes on through it. Only the ends of the body's
    /// blocks (`o1 endif`, a loop's that does not turn for ever) keep it followed; any other
    /// line (words, a definition or program, a block delete, another o-word line) may stop,
    /// return or refuse otherwise, and it is left.
    #[cold]
    #[inline(never)]
    pub(super) fn later_tail_line(&mut self, b: &BlockView<'_>) {
        let Some(mut body) = self.linuxcnc_later_bodies.ran_on.take() else {
            return;
        };
        if b.skip || !b.words.is_empty() {
            return;
        }
        for &(_, kind, text) in b.statements {
            let keyword = crate::statement::o_keyword(text).unwrap_or_default();
            let label = crate::statement::o_label(text);
            let at = body.open.iter().rposition(|o| o.label == label);
            let closes = matches!(keyword.as_slice(), b"endif" | b"endwhile" | b"endrepeat");
            let Some(at) = at.filter(|_| kind == Kind::Flow && closes) else {
                return;
            };
            if turns(&body.open[at]) {
                return;
            }
            body.open.truncate(at);
        }
        self.linuxcnc_later_bodies.ran_on = Some(body);
    }

    fn sure_body_read(&mut self, body: &mut SureBody, b: &BlockView<'_>) {
        if b.skip {
            // (a block delete: it may not run, nothing after it is sure)
            body.left = true;
            return;
        }
        let runs = body.open.iter().all(|o| o.runs == Some(true));
        let skipped = body.open.iter().any(|o| o.runs == Some(false));
        // (an M code of a value not known may be any of them)
        let m = |n: i64| {
            b.words.iter().any(|w| {
                w.letter == b'M'
                    && (!w.expression.is_empty()
                        || crate::dialect::linuxcnc_m_number(w.number, &|_| None) == Some(n))
            })
        };
        if !skipped && m(98) {
            if runs {
                self.sure_body_m98(body, b);
            }
            body.left = true;
            return;
        }
        body.skipped_m99 |= skipped && m(99);
        if !skipped && (m(2) || m(30) || m(99)) {
            // (the run ends or returns here, or may: nothing after it is sure; an M99 of
            // a FANUC-style program outside its blocks closes it, read as its endsub)
            body.left = true;
            return;
        }
        for &(column, kind, text) in b.statements {
            let keyword = crate::statement::o_keyword(text).unwrap_or_default();
            let label = crate::statement::o_label(text);
            if kind == Kind::Call {
                if !skipped {
                    if runs && keyword == b"call" {
                        let shown = crate::statement::o_label_shown(text);
                        let call = format!("{} call", String::from_utf8_lossy(&shown));
                        let target = format!("{} sub", String::from_utf8_lossy(&shown));
                        self.sure_body_seek(body, label, (b.line, column), call, target);
                    }
                    body.left = true;
                    return;
                }
                continue;
            }
            if kind == Kind::Definition {
                if keyword == b"sub" && body.fanuc && runs {
                    self.fanuc_body_refused(
                        body,
                        "'O.... sub' subroutine must be called with 'O.... call'",
                        "runs as a definition of the o-word form, refused inside a program an \
                         M98 runs",
                        b,
                        (column, text),
                    );
                    return;
                }
                continue;
            }
            if kind != Kind::Flow {
                continue;
            }
            let at = body.open.iter().rposition(|o| o.label == label);
            let inner_dead = body.open.iter().any(|o| o.runs == Some(false));
            let closes_do =
                keyword == b"while" && at.is_some_and(|at| body.open[at].keyword == b"do");
            match keyword.as_slice() {
                b"while" if closes_do => {
                    let at = at.unwrap_or_default();
                    // (a `do` whose lines ran may turn for ever, or leave by a break)
                    if body.open[at].runs != Some(false) {
                        body.left = true;
                    }
                    body.open.truncate(at);
                }
                b"if" | b"while" | b"repeat" | b"do" => {
                    let runs = if inner_dead {
                        Some(false)
                    } else {
                        linuxcnc_constant_runs(text)
                    };
                    body.open.push(Open {
                        label,
                        runs,
                        taken: runs,
                        keyword: keyword.clone(),
                    });
                }
                b"else" | b"elseif" => match at {
                    Some(at) if at + 1 == body.open.len() => {
                        let outer_dead = body.open[..at].iter().any(|o| o.runs == Some(false));
                        let o = &mut body.open[at];
                        let now = match (o.taken, outer_dead) {
                            (_, true) | (Some(true), _) => Some(false),
                            (Some(false), _) if keyword == b"else" => Some(true),
                            (Some(false), _) => linuxcnc_constant_runs(text),
                            (None, _) => None,
                        };
                        o.taken = match (o.taken, now) {
                            (Some(true), _) | (_, Some(true)) => Some(true),
                            (Some(false), Some(false)) => Some(false),
                            _ => None,
                        };
                        o.runs = now;
                    }
                    // (of a block not the innermost: left as not followed)
                    Some(_) => body.left = true,
                    None => self.sure_body_undefined(body, runs, b, (column, text)),
                },
                b"endif" | b"endwhile" | b"endrepeat" => match at {
                    Some(at) => {
                        let o = &body.open[at];
                        // (a loop whose lines ran may turn for ever, or leave by a break)
                        if o.keyword == b"while" && o.runs != Some(false) {
                            body.left = true;
                        }
                        body.open.truncate(at);
                    }
                    None => self.sure_body_undefined(body, runs, b, (column, text)),
                },
                _ if skipped => {}
                b"return" if runs && body.fanuc => {
                    self.fanuc_body_refused(
                        body,
                        "Fanuc 'O....' subroutine definition must end with 'M99'",
                        "refuses in a program an M98 runs",
                        b,
                        (column, text),
                    );
                    return;
                }
                // (a `do`'s closing `while`, a return, break, continue, anything else: the
                // run may leave here)
                _ => body.left = true,
            }
        }
    }

    /// An o-word line of the sure body (`text` at `column`) closing or continuing a block it
    /// never opened: refused where the line runs (`runs`).
    /// rs274's refusal (`reason`) of an o-word statement a FANUC-style program an M98 runs
    /// reaches; `what` says what rs274 2.9 does with it. The body is left there.
    fn fanuc_body_refused(
        &mut self,
        body: &mut SureBody,
        reason: &str,
        what: &str,
        b: &BlockView<'_>,
        (column, text): (usize, &[u8]),
    ) {
        let message = format!(
            "{reason} (rs274ngc): the FANUC-style program {} that the call on line {} runs \
             reaches {}, which rs274 2.9 {what}",
            fanuc_name(&body.label),
            body.call,
            String::from_utf8_lossy(text),
        );
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
        self.linuxcnc_later_bodies.refused = Some(body.label.clone());
        body.left = true;
    }

    fn sure_body_undefined(
        &mut self,
        body: &mut SureBody,
        runs: bool,
        b: &BlockView<'_>,
        (column, text): (usize, &[u8]),
    ) {
        if !runs {
            return;
        }
        let statement = String::from_utf8_lossy(text).into_owned();
        let message = format!(
            "undefined O-word label (rs274ngc): '{statement}' closes or continues a block that \
             the body {} (run by the call on line {}) never opened; rs274 2.9 stops there \
             (\"{}: undefined O-word label: '{statement}'\"), whatever the caller has open",
            name_of(&body.label, body.fanuc),
            body.call,
            b.line,
        );
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
        body.left = true;
    }

    /// An `M98 P300` that surely runs in the sure body: [`Checker::sure_body_seek`].
    fn sure_body_m98(&mut self, body: &SureBody, b: &BlockView<'_>) {
        // (a P of a whole number written plainly: one of a parameter is not followed)
        let mut p = b.words.iter().filter(|w| w.letter == b'P');
        let (Some(p), None) = (p.next(), p.next()) else {
            return;
        };
        let number = std::str::from_utf8(p.number).ok();
        let Some(n) = number.and_then(|t| t.parse::<i64>().ok()) else {
            return;
        };
        if !p.expression.is_empty()
            || !p.index.is_empty()
            || b.words.iter().any(|w| w.letter == b'L')
        {
            return;
        }
        let label = format!("o{n}").into_bytes();
        let column = b
            .words
            .iter()
            .find(|w| w.letter == b'M')
            .map_or(1, |w| w.column);
        let (call, target) = (format!("M98 P{n}"), format!("O{n}"));
        self.sure_body_seek(body, label, (b.line, column), call, target);
    }

    /// A call of `label` that surely runs in the sure body (`call`, at `at`): where a
    /// program or definition of the label was written after the main program's end before
    /// the body only ([`LaterBodies::passed`], [`LaterBodies::defined`]), held for the file's
    /// end. rs274 seeks the label forward from the call and records no definition it passed
    /// over while seeking the body (`rs274 -g`: `o300 call` / `M2` / `o400 sub` ... / `o300
    /// sub` / `o400 call` is "EOF in file ... seeking o-word: o<400> from line: 11", as the
    /// `M98 P400` form of it is).
    fn sure_body_seek(
        &mut self,
        body: &SureBody,
        label: Vec<u8>,
        (line, column): (usize, usize),
        call: String,
        target: String,
    ) {
        let later = &self.linuxcnc_later_bodies;
        // (a definition of the main program, read before its lines, is recorded and found; a
        // call of the body itself finds it; a label worked out as the line runs is not known)
        let before = later.passed.iter().any(|d| d.0 == label)
            || later
                .defined
                .iter()
                .any(|d| d.0 == label && !d.2 && d.1 < body.opened);
        if !before
            || label == body.label
            || self.linuxcnc_defined.contains(&label)
            || crate::statement::computed_label(&label)
        {
            return;
        }
        self.linuxcnc_later_bodies.seeking.push(Seek {
            label,
            line,
            column,
            call,
            target,
        });
    }

    /// At the file's end: the sure FANUC-style body never closed by an M99 that runs, and the
    /// M98s of a program found after them by no forward search.
    #[cold]
    #[inline(never)]
    pub(super) fn later_bodies_ended(&mut self, last: usize) {
        let later = std::mem::take(&mut self.linuxcnc_later_bodies);
        for seek in later.seeking {
            // (a FANUC-style program of the label read as one, before the body -- an earlier
            // call found it, rs274 keeps its place -- or a program or definition after the
            // call, found by its search)
            let label = &seek.label;
            let found = later
                .defined
                .iter()
                .any(|d| d.0 == *label && (d.2 || d.1 > seek.line))
                || later
                    .passed
                    .iter()
                    .any(|d| d.0 == *label && d.1 > seek.line);
            if found {
                continue;
            }
            // (rs274 names a label `o<400>`, a named one as written)
            let name = String::from_utf8_lossy(&super::structure::bare_label(label)).into_owned();
            let (call, target) = (&seek.call, &seek.target);
            let message = format!(
                "EOF in file seeking o-word (rs274ngc): this {call} runs in a body read after \
                 the main program's end, and rs274 2.9 seeks {target} from here to the file's \
                 end, where none is written; the one before was passed over unread (\"EOF in \
                 file ... seeking o-word: o<{name}>\"), unless a file {name}.ngc is on the \
                 subroutine path"
            );
            self.report(Rule::LinuxCncRefuses, message, seek.line, seek.column);
        }
        // (a FANUC-style body closed at an M99 that does not run, and no line after it but
        // the ends of its blocks: Checker::later_tail_line)
        if let Some(body) = later.ran_on.filter(|_| !self.percent_closed) {
            if self.open_definition.is_none() {
                self.file_ended(&body, last);
            }
        }
        let Some(body) = later.sure.filter(|s| s.fanuc && !s.left) else {
            return;
        };
        // (a closing `%` ends the run as an M2 does: rs274 reads no line after it)
        if self.open_definition.is_none() || self.percent_closed {
            return;
        }
        self.file_ended(&body, last);
    }

    /// "File ended with no percent sign or program end" at the file's `last` line: the sure
    /// FANUC-style body runs on to it.
    fn file_ended(&mut self, body: &SureBody, last: usize) {
        let m99 = if body.skipped_m99 {
            "has no M99 that runs (each is in a block that does not)"
        } else {
            "has no M99"
        };
        let message = format!(
            "File ended with no percent sign or program end (rs274ngc): the FANUC-style \
             program {} that the call on line {} runs {m99}, so rs274 2.9 runs on to the \
             file's end",
            fanuc_name(&body.label),
            body.call,
        );
        self.report(Rule::LinuxCncRefuses, message, last, 1);
    }
}

/// A loop of the body whose lines may run (a `while`, a `do`): it may turn for ever.
fn turns(o: &Open) -> bool {
    matches!(o.keyword.as_slice(), b"while" | b"do") && o.runs != Some(false)
}

/// `O300` for the label `o300`.
fn fanuc_name(label: &[u8]) -> String {
    format!(
        "O{}",
        String::from_utf8_lossy(label.get(1..).unwrap_or_default())
    )
}

/// The body's name as written: `O300` or `o300`.
fn name_of(label: &[u8], fanuc: bool) -> String {
    if fanuc {
        fanuc_name(label)
    } else {
        String::from_utf8_lossy(label).into_owned()
    }
}
