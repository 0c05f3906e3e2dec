//! `formats._core.RestartWalk`: the checker's modal state and the restart walk of
//! `tapegate_core::restart`, for `postproc.restart`.
//!
//! A program is read up to its restart block either a chunk of whole lines at a time
//! ([`RestartWalk::walk_lines`], no Python object per block: how `send --restart-at` reads a
//! file) or a `Block` at a time ([`RestartWalk::step`]); [`RestartWalk::facts`] hands the walk's
//! facts to Python once, when the preamble is planned.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use tapegate_core::check;
use tapegate_core::modal::AXES;
use tapegate_core::restart::{Control, Step, Walk, Why};
use tapegate_core::rules::Selection;
use tapegate_core::statement::Kind;
use tapegate_core::tokenize;

use crate::checker::{decimal, feed_block, state_dict};
use crate::machine::Machine;
use crate::{py_text, str_bytes, Block};

#[pyclass(module = "formats._core")]
pub struct RestartWalk {
    checker: check::Checker,
    walk: Walk,
    /// The walk's start: each program of a file is walked from it, as the checker reads it
    /// from its own start state (`dialect::ProgramSplit`).
    fresh: Walk,
}

/// A `Why` as Python values: `("text", text)` or `("statement", text, line)`.
fn why<'py>(py: Python<'py>, why: &Why) -> PyResult<Bound<'py, PyTuple>> {
    match why {
        Why::Text(text) => PyTuple::new(
            py,
            [
                PyString::new(py, "text").into_any(),
                py_text(py, text)?.into_any(),
            ],
        ),
        Why::Statement(text, line) => PyTuple::new(
            py,
            [
                PyString::new(py, "statement").into_any(),
                py_text(py, text)?.into_any(),
                line.into_pyobject(py)?.into_any(),
            ],
        ),
    }
}

fn optional_text<'py>(
    py: Python<'py>,
    text: &Option<Vec<u8>>,
) -> PyResult<Option<Bound<'py, PyString>>> {
    text.as_deref().map(|t| py_text(py, t)).transpose()
}

impl RestartWalk {
    /// The program's end read on `line`, if the checker saw one there (`before`: its
    /// [`check::Checker::part_end`] before the line).
    fn ended(
        &self,
        line: usize,
        text: &[u8],
        before: (usize, bool),
    ) -> Option<(&'static str, usize, String)> {
        let (ended, returned) = self.checker.part_end();
        let text = String::from_utf8_lossy(text).trim().to_string();
        if returned && !before.1 {
            Some(("returns", line, text))
        } else if ended != before.0 && ended > 0 {
            Some(("ends", line, text))
        } else {
            None
        }
    }

    fn step_read(
        &mut self,
        line: usize,
        text: &[u8],
        tokens: &[&[u8]],
        statements: &[(Kind, &[u8])],
        extras: bool,
    ) {
        self.walk.step(
            &Step {
                line,
                text,
                tokens,
                statements,
                extras,
            },
            &self.checker.machine.state,
        );
    }
}

#[pymethods]
impl RestartWalk {
    /// The walk of a program for `machine`: the checker's modal state, with no rule reported.
    #[new]
    fn new(machine: &Machine) -> PyResult<Self> {
        let m = &machine.inner;
        let mut checker = check::Checker::new(m.check.clone(), Selection::none(), false);
        checker.keep_stats(false); // the walk reads the modal state, never the statistics
        let mut walk = Walk::new(m.control, m.lathe, m.fanuc_lathe);
        walk.units_settings = Some(checker.machine.settings.clone());
        // (a profile with its control's own list: ISO 6983-1's table reports its own codes)
        if !checker.machine.settings.lacks_g.is_empty() {
            let held = m.check.g_decimal.iter().map(|(c, _)| c.as_bytes().to_vec());
            walk.decimal_codes = Some(held.collect());
        }
        if matches!(m.control, Control::Fanuc | Control::Haas) {
            let lacks = m.check.m_codes.iter().map(|c| {
                c.as_ref().is_none_or(|c| {
                    matches!(
                        c.status,
                        check::Status::Unassigned | check::Status::Permanent
                    )
                })
            });
            walk.lacks_m = Some(lacks.collect());
        }
        for (code, key, function) in &m.meanings {
            let mode = match key.as_str() {
                "live-tool-cw" | "live-tool-ccw" => Some(("live tool", true)),
                "live-tool-stop" => Some(("live tool", false)),
                "c-axis-engage" => Some(("C axis", true)),
                "c-axis-disengage" => Some(("C axis", false)),
                _ => None,
            };
            let number = code.strip_prefix('M').and_then(|n| n.parse::<i64>().ok());
            // (a SINUMERIK's M70, the spindle to axis mode, holds as an orientation does: the
            // spindle under position control until M3, M4 or M5; review 56a F6)
            if let (Some(n), "spindle-orient" | "spindle-to-axis-mode") = (number, key.as_str()) {
                walk.orient_codes.push(n);
            }
            // the main spindle's other starts (a builder's M13: spindle and coolant)
            if let Some(n) = number.filter(|n| !matches!(n, 3 | 4) && m.check.turning.contains(n)) {
                if key.starts_with("spindle-") && !walk.turn_codes.contains(&n) {
                    walk.turn_codes.push(n);
                    if key.ends_with("-coolant-on") {
                        walk.coolant_starts.push(n);
                    }
                }
            }
            if let (Some((name, on)), Some(n)) = (mode, number) {
                walk.m_modes.push((n, name, on, function.clone()));
            }
        }
        // the spindle's modal group's other codes, which the walk does not read (review 56d
        // F9: a builder's M13 listed without a meaning key planned past with the spindle off)
        let group = |n: usize| {
            m.check
                .m_codes
                .get(n)
                .and_then(Option::as_ref)
                .map(|c| c.duration.as_str())
                .filter(|d| !d.is_empty() && *d != "TBO")
        };
        if let Some(spindle) = group(3) {
            for n in 0..m.check.m_codes.len() {
                let Ok(code) = i64::try_from(n) else { break };
                if group(n) == Some(spindle)
                    && !matches!(code, 3..=5)
                    && !walk.turn_codes.contains(&code)
                    && !walk.orient_codes.contains(&code)
                {
                    walk.unread_spindle.push(code);
                }
            }
        }
        Ok(RestartWalk {
            checker,
            fresh: walk.clone(),
            walk,
        })
    }

    /// When `block` (not read yet) is the second block of a FANUC lathe's two-block cycle
    /// whose first block was read: its cycle code and the first block's line.
    fn cycle_first_block(
        &self,
        py: Python<'_>,
        block: &Bound<'_, Block>,
    ) -> PyResult<Option<(i64, usize)>> {
        let b = block.borrow();
        let mut tokens: Vec<Vec<u8>> = Vec::new();
        for token in b.words.bind(py).iter() {
            tokens.push(str_bytes(token.downcast::<PyString>()?)?.into_owned());
        }
        let tokens: Vec<&[u8]> = tokens.iter().map(Vec::as_slice).collect();
        Ok(self.walk.cycle_first_block(&tokens))
    }

    /// Read one `Block` (a `BadBlock` goes to the checker alone: the walk leaves it out).
    fn step(&mut self, py: Python<'_>, block: &Bound<'_, Block>) -> PyResult<()> {
        let extras = block.borrow().info.is_some();
        let walk = &mut self.walk;
        let fresh = &self.fresh;
        let programs = self.checker.programs;
        feed_block(py, &mut self.checker, block, |checker, view| {
            if checker.programs != programs {
                *walk = fresh.clone();
            }
            let tokens: Vec<&[u8]> = view.words.iter().map(|w| w.token).collect();
            let statements: Vec<(Kind, &[u8])> =
                view.statements.iter().map(|&(_, k, t)| (k, t)).collect();
            let step = Step {
                line: view.line,
                text: view.text,
                tokens: &tokens,
                statements: &statements,
                extras,
            };
            walk.step(&step, &checker.machine.state);
        })
    }

    /// Read the whole lines of `data` (without its last LF) after line `line`, up to the line
    /// numbered `until`, which is not read: how many lines of `data` were read before it, or
    /// None when `data` ends first. A line that cannot be read goes to the checker alone, as
    /// `plan_restart` steps a `BadBlock`.
    fn walk_lines(
        &mut self,
        data: &Bound<'_, PyString>,
        line: usize,
        flags: crate::Flags,
        until: usize,
    ) -> PyResult<Option<usize>> {
        let dialect = crate::dialect(flags);
        let bytes = str_bytes(data)?;
        let mut tokens = Vec::with_capacity(16);
        for (read, text) in tapegate_core::text::lines(&bytes).enumerate() {
            let number = line + 1 + read;
            if number >= until {
                return Ok(Some(read));
            }
            tokens.clear();
            if self.checker.not_read(number, text) {
                continue;
            }
            let extras = match tokenize(text, &dialect, &mut tokens) {
                Ok(extras) => extras,
                Err(error) => {
                    // a line the control refuses: the checker leaves what it writes unknown,
                    // and the restart refuses after it (Checker::refused_at)
                    self.checker.unreadable(&check::Unreadable {
                        line: number,
                        text,
                        rule: error.kind.rule(),
                        message: &error.message,
                        column: tapegate_core::text::column(text, error.offset),
                    });
                    continue;
                }
            };
            let programs = self.checker.programs;
            self.checker
                .check_read(text, number, &tokens, extras.as_ref());
            if self.checker.programs != programs {
                self.walk = self.fresh.clone();
            }
            let words: Vec<&[u8]> = tokens.iter().map(|t| t.text.as_ref()).collect();
            let statements: Vec<(Kind, &[u8])> = extras
                .as_ref()
                .map(|e| {
                    e.statements
                        .iter()
                        .map(|s| (s.kind, &text[s.offset..s.end]))
                        .collect()
                })
                .unwrap_or_default();
            self.step_read(number, text, &words, &statements, extras.is_some());
        }
        Ok(None)
    }

    /// Read on from the restart block (line `line` + 1 is the first of `data`, without its
    /// last LF) to the end of its program: `("returns", line, text)` where it returns to a
    /// caller (M99; M17, RET; RTS: a subprogram or macro body, or a main program looping by
    /// M99), `("ends", line, text)` at its M02/M30, None where the file or the program ends
    /// first. The walk is spent: asked once, after the plan.
    fn part_end(
        &mut self,
        data: &Bound<'_, PyString>,
        line: usize,
        flags: crate::Flags,
    ) -> PyResult<Option<(&'static str, usize, String)>> {
        let dialect = crate::dialect(flags);
        let bytes = str_bytes(data)?;
        let mut tokens = Vec::with_capacity(16);
        let programs = self.checker.programs;
        for (read, text) in tapegate_core::text::lines(&bytes).enumerate() {
            let number = line + 1 + read;
            tokens.clear();
            if self.checker.not_read(number, text) {
                return Ok(None);
            }
            let Ok(extras) = tokenize(text, &dialect, &mut tokens) else {
                continue;
            };
            let before = self.checker.part_end();
            self.checker
                .check_read(text, number, &tokens, extras.as_ref());
            if self.checker.programs != programs {
                return Ok(None);
            }
            if let Some(found) = self.ended(number, text, before) {
                return Ok(Some(found));
            }
        }
        Ok(None)
    }

    /// [`RestartWalk::part_end`] of one `Block` at a time (the block walk's): read it, and
    /// say whether the program ended or returned there; None while it goes on.
    fn part_end_step(
        &mut self,
        py: Python<'_>,
        block: &Bound<'_, Block>,
    ) -> PyResult<Option<(&'static str, usize, String)>> {
        let programs = self.checker.programs;
        let before = self.checker.part_end();
        let mut at = None;
        feed_block(py, &mut self.checker, block, |_, view| {
            at = Some((view.line, view.text.to_vec()));
        })?;
        if self.checker.programs != programs {
            return Ok(Some(("other", 0, String::new())));
        }
        Ok(at.and_then(|(line, text)| self.ended(line, &text, before)))
    }

    /// Whether the control never reads line `line` (`text`): after a LinuxCNC program's end
    /// (the checker's `dialect::ReadingEnd`), asked of the block a restart is planned at.
    fn not_read(&mut self, line: usize, text: &Bound<'_, PyString>) -> PyResult<bool> {
        Ok(self.checker.not_read(line, &str_bytes(text)?))
    }

    /// The modal state in force (the fields of `postproc.state.ModalState`).
    #[getter]
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        state_dict(py, &self.checker.machine.state)
    }

    /// The walk's facts, as plain values for `postproc.restart`.
    fn facts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let w = &self.walk;
        let d = PyDict::new(py);
        match &w.flow {
            Some(f) => {
                let text = py_text(py, &f.text)?;
                let text = if f.block {
                    text.call_method0("strip")?.downcast_into::<PyString>()?
                } else {
                    text
                };
                d.set_item("flow", (f.line, text, f.kind))?;
            }
            None => d.set_item("flow", py.None())?,
        }
        let unrestored = PyList::empty(py);
        for (key, line, what) in &w.unrestored {
            unrestored.append((key.as_str(), *line, what.as_str()))?;
        }
        d.set_item("unrestored", unrestored)?;
        let lost = PyDict::new(py);
        for (i, entry) in w.lost.iter().enumerate() {
            if let Some(l) = entry {
                let kind = if l.machine {
                    "machine"
                } else if l.frame {
                    "frame"
                } else {
                    "unknown"
                };
                let replay = (l.replay.0.as_str(), py_text(py, &l.replay.1)?);
                lost.set_item(
                    (AXES[i] as char).to_string(),
                    (kind, l.line, why(py, &l.what)?, replay, l.cycle),
                )?;
            }
        }
        d.set_item("lost", lost)?;
        let unknown = PyDict::new(py);
        for (i, entry) in w.unknown.iter().enumerate() {
            if let Some(reason) = entry {
                unknown.set_item(((b'A' + i as u8) as char).to_string(), why(py, reason)?)?;
            }
        }
        d.set_item("unknown", unknown)?;
        let seen: String = AXES
            .iter()
            .enumerate()
            .filter(|(i, _)| w.seen & (1 << i) != 0)
            .map(|(_, &a)| a as char)
            .collect();
        d.set_item("seen", seen)?;
        d.set_item("t_token", optional_text(py, &w.t_token)?)?;
        d.set_item("spindle_t", optional_text(py, &w.spindle_t)?)?;
        d.set_item("m6", optional_text(py, &w.m6)?)?;
        d.set_item("h", optional_text(py, &w.h)?)?;
        d.set_item("g43_line", w.g43_line)?;
        d.set_item("d_token", optional_text(py, &w.d_token)?)?;
        d.set_item("work", w.work)?;
        d.set_item("arc_absolute", w.arc_absolute)?;
        d.set_item("comp_line", w.comp_line)?;
        d.set_item("cycle", w.cycle)?;
        let high = PyDict::new(py);
        for (slot, axis) in [(0, "X"), (1, "Z")] {
            if let Some(value) = decimal(py, w.high[slot])? {
                high.set_item(axis, value)?;
            }
        }
        d.set_item("high", high)?;
        d.set_item("too_long", w.too_long)?;
        d.set_item("refused", self.checker.refused_at())?;
        d.set_item("conflict", self.checker.conflict_at())?;
        let written = PyDict::new(py);
        for (i, entry) in w.written.iter().enumerate() {
            if let Some((units, line)) = entry {
                written.set_item(
                    ((b'A' + i as u8) as char).to_string(),
                    (units.name(), *line),
                )?;
            }
        }
        d.set_item("written", written)?;
        d.set_item("z_reached", w.z_reached)?;
        let held = PyDict::new(py);
        for (i, value) in w.held.iter().enumerate() {
            if let Some(value) = decimal(py, *value)? {
                held.set_item((AXES[i] as char).to_string(), value)?;
            }
        }
        d.set_item("held", held)?;
        d.set_item("contour_next", w.contour_next)?;
        d.set_item("thread", w.thread)?;
        d.set_item("cycle_r", w.cycle_r)?;
        d.set_item("units_line", w.units_line)?;
        d.set_item("program", self.checker.programs)?;
        d.set_item("program_name", optional_text(py, &w.program_name)?)?;
        d.set_item("m6_line", w.m6_line)?;
        d.set_item("coolant", w.coolant.clone())?;
        let hints = PyDict::new(py);
        for (mode, hint) in &w.mode_hints {
            hints.set_item(*mode, hint.as_str())?;
        }
        d.set_item("mode_hints", hints)?;
        // both the live tool's and the C axis's codes named (haas-lathe): a profile that names
        // its live tool alone (okuma-lathe's M-tool spindle) keeps the refusals of a lathe
        // whose C axis codes are the builder's
        let named = |mode: &str| w.m_modes.iter().any(|m| m.1 == mode);
        d.set_item("live_modes", named("live tool") && named("C axis"))?;
        d.set_item("oriented", w.oriented)?;
        d.set_item("oriented_since", w.oriented_since())?;
        d.set_item(
            "side_move",
            w.side_move
                .map(|(line, axis)| (line, (axis as char).to_string())),
        )?;
        d.set_item("builder_m", w.builder_m)?;
        d.set_item("spin_line", w.spin_line)?;
        d.set_item("turned_by", w.turned_by)?;
        d.set_item("keyed_coolant", w.keyed_coolant)?;
        d.set_item("unread_spin", w.unread_spin)?;
        d.set_item("builder_first", w.builder_first)?;
        let by_extension = w
            .spindle_by_extension
            .as_ref()
            .map(|(first, line, text, _)| (*first, *line, String::from_utf8_lossy(text)));
        d.set_item("spindle_by_extension", by_extension)?;
        d.set_item("coolant_line", w.coolant_line)?;
        let unset: String = AXES
            .iter()
            .enumerate()
            .filter(|(i, _)| w.unset & (1 << i) != 0)
            .map(|(_, &a)| a as char)
            .collect();
        d.set_item("unset", unset)?;
        let moves = PyList::empty(py);
        for m in &w.moves {
            let mut ends = Vec::new();
            for p in m.from.iter().chain(m.to.iter()) {
                ends.push(decimal(py, *p)?);
            }
            moves.append((ends, m.motion, m.line, m.first))?;
        }
        d.set_item("moves", moves)?;
        d.set_item("tool_change", w.tool_change)?;
        match &w.lane {
            Some((x, ranges)) => {
                let mut spans = Vec::new();
                for &(lo, hi) in ranges {
                    spans.push((decimal(py, Some(lo))?, decimal(py, Some(hi))?));
                }
                d.set_item("lane", (decimal(py, Some(*x))?, spans))?;
            }
            None => d.set_item("lane", py.None())?,
        }
        d.set_item("tool_moved", w.tool_moved)?;
        d.set_item("diameter_mode", w.diameter_mode)?;
        d.set_item("diameter_switch", w.diameter_switch)?;
        d.set_item("diameter_rewritten", w.diameter_rewritten)?;
        match &w.okuma_work {
            Some((h, line)) => d.set_item("okuma_work", (optional_text(py, h)?, *line))?,
            None => d.set_item("okuma_work", py.None())?,
        }
        match &w.okuma_length {
            Some((g, h, line)) => {
                d.set_item("okuma_length", (*g, optional_text(py, h)?, *line))?;
            }
            None => d.set_item("okuma_length", py.None())?,
        }
        Ok(d)
    }
}

/// The last alignment label (`:1000`) read, and its line.
type Alignment = Option<(String, usize)>;

/// A block's word `letter` + `digits` (`N120`, `:1000`) whose number is `wanted`: the digits are
/// compared as numbers (`N0120` is `N120`).
fn numbered(token: &[u8], letter: u8, wanted: &[u8]) -> bool {
    let Some((&first, digits)) = token.split_first() else {
        return false;
    };
    let trim = |d: &[u8]| {
        let zeros = d.iter().take_while(|&&c| c == b'0').count();
        d[zeros..].to_vec()
    };
    first.to_ascii_uppercase() == letter
        && !digits.is_empty()
        && digits.iter().all(u8::is_ascii_digit)
        && trim(digits) == trim(wanted)
}

/// Search the whole lines of `data` (without its last LF) after line `line` for the block with
/// the word `letter` + `wanted` (`N` and `120`, or `:` and `1000`): `(its line or None, the last
/// alignment label at or before it, as `(token, line)`)`, `alignment` being the last one before
/// `data`. A line that cannot be read is left out.
#[pyfunction]
pub fn find_numbered(
    data: &Bound<'_, PyString>,
    line: usize,
    flags: crate::Flags,
    letter: &str,
    wanted: &str,
    alignment: Alignment,
) -> PyResult<(Option<usize>, Alignment)> {
    let dialect = crate::dialect(flags);
    let bytes = str_bytes(data)?;
    let letter = letter
        .as_bytes()
        .first()
        .copied()
        .unwrap_or(b'N')
        .to_ascii_uppercase();
    let mut alignment = alignment;
    let mut tokens = Vec::with_capacity(16);
    for (number, text) in (line + 1..).zip(tapegate_core::text::lines(&bytes)) {
        tokens.clear();
        if tokenize(text, &dialect, &mut tokens).is_err() {
            continue;
        }
        for t in &tokens {
            let token: &[u8] = &t.text;
            if numbered(token, b':', token.get(1..).unwrap_or(&[])) {
                alignment = Some((String::from_utf8_lossy(token).into_owned(), number));
            }
            if numbered(token, letter, wanted.as_bytes()) {
                return Ok((Some(number), alignment));
            }
        }
    }
    Ok((None, alignment))
}
