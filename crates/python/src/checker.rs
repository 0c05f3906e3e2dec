//! `formats._core.Checker`: the core's checker, given a compiled `Machine` by `postproc.check`.
//!
//! The machine is compiled once per profile (`crate::machine`); the program arrives as text a
//! chunk of whole lines at a time (the fast way: no Python object per block) or as `Block`
//! objects (`Checker.run`). Findings leave as `postproc.findings.Finding` tuples, made by the
//! `make` callable, with the rule's severity and clause from the core's registry; or, for a
//! checker made with a `report` format, written by the core (`tapegate_core::report`) as the
//! text, JSON or JSON Lines report prints them, handed to the caller's `write` about 64 KiB at
//! a time (drained after every line: memory holds a slice, not a chunk's findings), and only
//! counted. Made with `fold`, a text report folds each rule's warnings and notes past the
//! first five of the file into one line, written by `end` (`tapegate_core::report::Writer::
//! folded`).

use std::sync::Arc;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyString, PyTuple};
use tapegate_core::check::{self, BlockView, Config, Unreadable, Word};
use tapegate_core::decimal::Dec;
use tapegate_core::modal::{BlockValues, ModalState, AXES, CYCLE_WORDS};
use tapegate_core::report::Writer;
use tapegate_core::rules::{Rule, Selection, Severity};
use tapegate_core::statement::Kind;
use tapegate_core::text::column;

use crate::files::{self, TextFile};
use crate::machine::Machine;
use crate::{find_token, str_bytes, BadBlock, Block};

pub(crate) fn decimal<'py>(
    py: Python<'py>,
    value: Option<Dec>,
) -> PyResult<Option<Bound<'py, PyAny>>> {
    static DECIMAL: pyo3::sync::GILOnceCell<Py<pyo3::types::PyType>> =
        pyo3::sync::GILOnceCell::new();
    match value {
        None => Ok(None),
        Some(v) => Ok(Some(
            DECIMAL
                .import(py, "decimal", "Decimal")?
                .call1((v.to_string(),))?,
        )),
    }
}

/// The modal state as a dict of the fields of `postproc.state.ModalState`.
pub(crate) fn state_dict<'py>(py: Python<'py>, s: &ModalState) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("motion", s.motion)?;
    d.set_item("plane", s.plane)?;
    d.set_item("units", s.units.name())?;
    d.set_item("feed_units", s.feed_units.name())?;
    d.set_item("incremental", s.incremental)?;
    d.set_item("feed_mode", s.feed_mode)?;
    d.set_item("feed", decimal(py, s.feed)?)?;
    d.set_item("spindle_mode", s.spindle_mode)?;
    d.set_item("speed", decimal(py, s.speed)?)?;
    d.set_item("speed_limit", decimal(py, s.speed_limit)?)?;
    d.set_item(
        "spindle",
        match s.spindle {
            3 => "cw",
            4 => "ccw",
            _ => "stop",
        },
    )?;
    d.set_item(
        "coolant",
        match s.coolant {
            7 => "mist",
            8 => "flood",
            _ => "off",
        },
    )?;
    d.set_item("compensation", s.compensation)?;
    d.set_item("length_offset", s.length_offset)?;
    d.set_item("zero_shift", s.zero_shift)?;
    d.set_item("tool", s.tool)?;
    d.set_item("offset", s.offset)?;
    d.set_item("cycle", s.cycle)?;
    let cycle_words = PyDict::new(py);
    for (i, &l) in CYCLE_WORDS.iter().enumerate() {
        if let Some(v) = s.cycle_words[i] {
            cycle_words.set_item((l as char).to_string(), decimal(py, Some(v))?)?;
        }
    }
    d.set_item("cycle_words", cycle_words)?;
    let position = PyDict::new(py);
    for (i, &a) in AXES.iter().enumerate() {
        if let Some(v) = s.position[i] {
            position.set_item((a as char).to_string(), decimal(py, Some(v))?)?;
        }
    }
    d.set_item("position", position)?;
    d.set_item("ended", s.ended)?;
    Ok(d)
}

#[pyclass(module = "formats._core")]
pub struct Checker {
    /// Boxed: the core's checker is large, and a checker is made for every file of a batch,
    /// with the GIL held; inline, it was copied whole 6 times on its way into the Python
    /// object (52,000 instructions a file; docs/benchmarks.md, "the GIL or the caches").
    inner: Box<check::Checker>,
    file: PyObject,
    /// Each rule's ID, severity and clause as the Python strings a finding holds, by
    /// [`Rule::index`] ([`rule_strings`]).
    rules: &'static [[PyObject; 3]],
    make: PyObject,
    /// With a report format: the findings are written, not made into tuples...
    writer: Option<Writer>,
    /// ...into this, handed to the caller's `write` a slice at a time.
    written: Vec<u8>,
    /// The findings reported by this checker, by [`Severity`] (info, warning, error).
    counts: [usize; 3],
    /// The number of the last line `check_lines` read: where its next call goes on when it is
    /// given no line (the caller need not count the lines of its chunks).
    line: usize,
}

/// Where [`Checker::check_file`]'s work with the GIL released stopped.
enum Step {
    /// The file is not plain text: nothing read.
    NotText,
    /// A slice of the report to hand over; the run of lines goes on.
    Full,
    /// A chunk's lines checked, its findings to hand over.
    ChunkEnd,
    /// The program checked to its end, and finished.
    Done,
    /// The text after the last LF is for Python to read (a line without its LF at the end,
    /// or one past `MAX_BLOCK`).
    Rest,
}

/// Each rule's ID, severity and clause as interned Python strings, by [`Rule::index`]: made
/// once a process from the core's registry, not once a checker (a checker is made for every
/// file of a batch, under the GIL: the 246 strings were most of its 25 us).
fn rule_strings(py: Python<'_>) -> &'static [[PyObject; 3]] {
    static RULES: pyo3::sync::GILOnceCell<Vec<[PyObject; 3]>> = pyo3::sync::GILOnceCell::new();
    RULES.get_or_init(py, || {
        Rule::ALL
            .iter()
            .map(|rule| {
                [rule.id(), rule.severity().name(), rule.clause()]
                    .map(|text| PyString::intern(py, text).into_any().unbind())
            })
            .collect()
    })
}

fn severity_index(name: &str) -> Option<usize> {
    [Severity::Info, Severity::Warning, Severity::Error]
        .iter()
        .position(|s| s.name() == name)
}

/// The report's text handed to `write` about this many bytes at a time: a chunk's findings are
/// never held whole (a chunk of a program with findings on every word writes megabytes).
const SLICE: usize = 1 << 16;

/// The room a checker with a report format makes for its report at once: a slice and a
/// quarter, as a slice is handed over once a line's findings fill it. Grown from nothing, the
/// report's buffer was moved by `realloc` about 9 times a file, and in a `-j` thread's own
/// malloc arena each move was a copy (5M instructions of 200 files' check with `-j 2`, none
/// with `-j 1`: docs/benchmarks.md, "what -j 2 adds"). Below glibc's mmap threshold (128
/// KiB), so it is the arena's memory, used again by the next file.
const WRITTEN: usize = SLICE + SLICE / 4;

/// The findings `inner` made since the last call written by `writer` at the end of `written`
/// (a folded writer's past the first of their rule only counted by it), and counted: the part
/// of [`Checker::write_found`] that needs no Python (run with the GIL released).
fn render(
    inner: &mut check::Checker,
    writer: &mut Writer,
    written: &mut Vec<u8>,
    counts: &mut [usize; 3],
) {
    // (most lines find nothing: the drain's set-up, about 12 instructions a line, skipped)
    if !inner.found_any() {
        return;
    }
    for f in inner.drain() {
        counts[f.rule.severity() as usize] += 1;
        writer.finding(written, &f);
    }
}

impl Checker {
    /// The findings made since the last call written into `self.written` (and counted); when
    /// it holds a slice's worth, or `flush`, handed to `write`.
    fn write_found(
        &mut self,
        py: Python<'_>,
        write: &Bound<'_, PyAny>,
        flush: bool,
    ) -> PyResult<()> {
        let Some(writer) = &mut self.writer else {
            return Ok(());
        };
        render(&mut self.inner, writer, &mut self.written, &mut self.counts);
        self.hand_over(py, write, flush, false)
    }

    /// `self.written` handed to `write` (and emptied) when it holds a slice's worth, or
    /// `flush` and it holds anything: a `str`, or with `raw` the bytes as written (`bytes`:
    /// no string made, and none encoded again by the output's text layer).
    fn hand_over(
        &mut self,
        py: Python<'_>,
        write: &Bound<'_, PyAny>,
        flush: bool,
        raw: bool,
    ) -> PyResult<()> {
        let Some(writer) = &self.writer else {
            return Ok(());
        };
        if !self.written.is_empty() && (flush || self.written.len() >= SLICE) {
            if raw {
                let data = PyBytes::new(py, &self.written);
                self.written.clear();
                write.call1((data,))?;
            } else {
                let text = crate::report::string(py, writer.format(), &self.written)?;
                self.written.clear();
                write.call1((text,))?;
            }
        }
        Ok(())
    }

    /// The findings made since the last call: a list of `Finding` tuples (`write` None), or
    /// for a checker with a report format written through `write` (None returned).
    fn found<'py>(
        &mut self,
        py: Python<'py>,
        write: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        match (write, self.writer.is_some()) {
            (None, false) => Ok(self.findings(py)?.into_any()),
            (Some(write), true) => {
                self.write_found(py, write, true)?;
                Ok(py.None().into_bound(py))
            }
            (None, true) => Err(PyValueError::new_err(
                "a checker with a report format writes its findings: give it write",
            )),
            (Some(_), false) => Err(PyValueError::new_err(
                "the checker was made without a report format",
            )),
        }
    }

    fn findings<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for f in self.inner.take() {
            let [rule, severity, clause] = &self.rules[f.rule.index()];
            let row = PyTuple::new(
                py,
                [
                    rule.bind(py).clone(),
                    severity.bind(py).clone(),
                    PyString::new(py, &f.message).into_any(),
                    self.file.bind(py).clone(),
                    f.line.into_pyobject(py)?.into_any(),
                    f.column.into_pyobject(py)?.into_any(),
                    clause.bind(py).clone(),
                ],
            )?;
            out.append(self.make.bind(py).call1((row,))?)?;
        }
        Ok(out)
    }
}

#[pymethods]
impl Checker {
    #[new]
    #[pyo3(signature = (machine, select, ignore, record_path, file, make, report=None, stats=true,
                        fold=false))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        machine: &Machine,
        select: Vec<String>,
        ignore: Vec<String>,
        record_path: bool,
        file: Bound<'_, PyString>,
        make: PyObject,
        report: Option<&str>,
        stats: bool,
        fold: bool,
    ) -> PyResult<Self> {
        let writer = match report {
            Some(name) => {
                let writer =
                    Writer::new(crate::report::format(name)?, &crate::report::units(&file)?);
                Some(if fold { writer.folded() } else { writer })
            }
            None => None,
        };
        let rules = rule_strings(py);
        let mut inner = Box::new(check::Checker::new(
            machine.inner.check.clone(),
            Selection::new(&select, &ignore),
            record_path,
        ));
        inner.keep_stats(stats);
        if let Ok(name) = file.to_str() {
            inner.file_name(name);
        }
        Ok(Checker {
            inner,
            file: file.clone().into_any().unbind(),
            rules,
            make,
            written: if writer.is_some() {
                Vec::with_capacity(WRITTEN)
            } else {
                Vec::new()
            },
            writer,
            counts: [0; 3],
            line: 0,
        })
    }

    /// `findings` (`Finding` tuples made in Python: a tape's) written as this checker's report
    /// writes its own (folded with them), and counted with them.
    fn render<'py>(
        &mut self,
        py: Python<'py>,
        findings: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyString>> {
        let Some(writer) = &mut self.writer else {
            return Err(PyValueError::new_err(
                "the checker was made without a report format",
            ));
        };
        let mut out = Vec::new();
        let counts = &mut self.counts;
        let format = writer.format();
        crate::report::append_tuples(
            format,
            &mut out,
            findings,
            |id, severity, line, column, message| {
                if let Some(i) = severity_index(severity) {
                    counts[i] += 1;
                }
                Rule::from_id(id).is_none_or(|rule| writer.shown(rule, line, column, message))
            },
        )?;
        crate::report::string(py, format, &out)
    }

    /// The end of the file's report, after its last findings: a folded text report's line for
    /// each rule with findings it left out (`report::Writer::end`), handed to `write` with
    /// what is left of the report (a `str`, or with `raw` bytes). Nothing for a report not
    /// folded, or JSON.
    #[pyo3(signature = (write, raw=false))]
    fn end(&mut self, py: Python<'_>, write: &Bound<'_, PyAny>, raw: bool) -> PyResult<()> {
        let Some(writer) = &mut self.writer else {
            return Err(PyValueError::new_err(
                "the checker was made without a report format",
            ));
        };
        writer.end(&mut self.written);
        self.hand_over(py, write, true, raw)
    }

    /// Whether verdicts are kept by key (the default); False asks every rule afresh of every
    /// word and block: the tests' oracle for the kept verdicts (`check::Checker::keep_verdicts`).
    fn keep_verdicts(&mut self, keep: bool) {
        self.inner.keep_verdicts(keep);
    }

    /// The number of the last line `check_lines` read.
    #[getter]
    fn line(&self) -> usize {
        self.line
    }

    /// The findings reported so far by severity: `{"error": n, "warning": n, "info": n}`.
    #[getter]
    fn counts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for severity in [Severity::Error, Severity::Warning, Severity::Info] {
            d.set_item(severity.name(), self.counts[severity as usize])?;
        }
        Ok(d)
    }

    /// Whether this run reports the rule `id` (`--select`, `--ignore`); false for an ID the
    /// registry does not have.
    fn enabled(&self, id: &str) -> bool {
        Rule::from_id(id).is_some_and(|rule| self.inner.enabled(rule))
    }

    /// The findings of whole lines of text (`data` without its last LF) after line `line`
    /// (None: after the last line the call before read): a list, or with a report format
    /// written through `write`.
    #[pyo3(signature = (data, line, flags, write=None))]
    fn check_lines<'py>(
        &mut self,
        py: Python<'py>,
        data: &Bound<'py, PyString>,
        line: Option<usize>,
        flags: crate::Flags,
        write: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let dialect = crate::dialect(flags);
        let bytes = str_bytes(data)?;
        let mut tokens = Vec::with_capacity(16);
        let line = line.unwrap_or(self.line);
        let mut lines = (line + 1..).zip(tapegate_core::text::lines(&bytes));
        // writing: the findings are written line by line, a slice handed over when full
        let streamed = write.filter(|_| self.writer.is_some());
        // The lines are checked (and their findings written) with the GIL released, so that
        // threads check side by side: it is taken again only to hand a full slice to `write`,
        // and for the findings' tuples at the end.
        loop {
            let (inner, written, counts) = (&mut self.inner, &mut self.written, &mut self.counts);
            let last = &mut self.line;
            let mut writer = self.writer.as_mut().filter(|_| streamed.is_some());
            let full = py.allow_threads(|| {
                for (number, text) in lines.by_ref() {
                    *last = number;
                    inner.check_line(text, number, &dialect, &mut tokens);
                    if let Some(writer) = writer.as_deref_mut() {
                        render(inner, writer, written, counts);
                        if written.len() >= SLICE {
                            return true;
                        }
                    }
                }
                false
            });
            match streamed {
                Some(write) if full => self.hand_over(py, write, false, false)?,
                _ => break,
            }
        }
        self.found(py, write)
    }

    /// A text file checked by the core from its first line to its end, its findings written
    /// through `write` (a checker with a report format), the file read in 1 MiB chunks and
    /// checked with the GIL released (`crate::files`): the GIL is taken only to hand a full
    /// slice of the report to `write`, so the threads of `tapegate check -j` run side by side.
    /// It reads what `formats.source.Source` reads as plain text and checks it as
    /// `postproc.check.Checker.report_stream` does: returns None, with nothing read or
    /// written, for a file that is not (a tape image: Python's reading decodes it); True once
    /// the program is checked to its end (`finish` done); else (the text after the last LF,
    /// where the file's bytes not yet read begin or None at its end), for the caller to read
    /// on as `report_stream` does. An error of the file's opening or reading is Python's
    /// `OSError(errno, strerror)`. With `raw`, the report's slices are handed over as the
    /// bytes written (JSON and JSON Lines are ASCII; text is UTF-8, with any lone surrogate of
    /// a file's name as `surrogatepass` writes it), for an output written as bytes.
    #[pyo3(signature = (path, flags, write, raw=false))]
    fn check_file<'py>(
        &mut self,
        py: Python<'py>,
        path: std::path::PathBuf,
        flags: crate::Flags,
        write: &Bound<'py, PyAny>,
        raw: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        if self.writer.is_none() {
            return Err(PyValueError::new_err(
                "the checker was made without a report format",
            ));
        }
        let dialect = crate::dialect(flags);
        let mut file = None;
        // the run of whole lines being checked: (its range in the buffer, where its next line
        // begins); `at > end` once it is checked
        let (mut end, mut at) = (0usize, 1usize);
        loop {
            let (inner, written, counts) = (&mut self.inner, &mut self.written, &mut self.counts);
            let last = &mut self.line;
            let writer = self.writer.as_mut().expect("checked above");
            let slot = &mut file;
            let step = py.allow_threads(|| -> std::io::Result<Step> {
                if slot.is_none() {
                    match TextFile::open(&path)? {
                        Some(opened) => *slot = Some(opened),
                        None => return Ok(Step::NotText),
                    }
                }
                let text = slot.as_mut().expect("opened above");
                loop {
                    if at <= end {
                        let base = text.buffer().as_ptr() as usize;
                        let run = &text.buffer()[at..end];
                        let mut tokens = Vec::with_capacity(16);
                        // the run's lines as `text::lines` splits them, each found by its
                        // check (a line of plain words where its scan stops, at its LF)
                        let mut start = 0;
                        loop {
                            let number = *last + 1;
                            *last = number;
                            let rest = &run[start..];
                            let length = inner.check_next_line(rest, number, &dialect, &mut tokens);
                            render(inner, writer, written, counts);
                            // where the next line begins, past this one's LF
                            at = rest.as_ptr() as usize - base + length + 1;
                            if written.len() >= SLICE && at <= end {
                                return Ok(Step::Full);
                            }
                            if length == rest.len() {
                                break; // the run's last line: no LF after it
                            }
                            start += length + 1;
                        }
                        at = end + 1;
                        // the chunk's findings handed over at its end, as check_lines hands
                        // them (a thread of a stopped `-j` stops there), unless the file's
                        // end is next
                        if !written.is_empty() && !text.last_chunk() {
                            return Ok(Step::ChunkEnd);
                        }
                    }
                    match text.next_lines()? {
                        Some(run) => (at, end) = (run.start, run.end),
                        None => {
                            let (files::End::Eof, rest) = text.end() else {
                                return Ok(Step::Rest);
                            };
                            if !rest.is_empty() {
                                return Ok(Step::Rest);
                            }
                            inner.finish();
                            render(inner, writer, written, counts);
                            return Ok(Step::Done);
                        }
                    }
                }
            });
            match step.map_err(|e| files::os_error(py, e))? {
                Step::NotText => return Ok(py.None().into_bound(py)),
                Step::Full => self.hand_over(py, write, false, raw)?,
                Step::ChunkEnd => self.hand_over(py, write, true, raw)?,
                Step::Done => {
                    self.hand_over(py, write, true, raw)?;
                    return Ok(true.into_pyobject(py)?.to_owned().into_any());
                }
                Step::Rest => {
                    self.hand_over(py, write, true, raw)?;
                    let text = file.as_ref().expect("read");
                    let (end, rest) = text.end();
                    let at = match end {
                        files::End::Eof => None,
                        files::End::Overflow { at } => Some(at),
                    };
                    return Ok((files::text(py, rest)?, at).into_pyobject(py)?.into_any());
                }
            }
        }
    }

    /// The findings of one `Block` (or `BadBlock`), as [`Checker::check_lines`] gives them.
    #[pyo3(signature = (block, write=None))]
    fn check_block<'py>(
        &mut self,
        py: Python<'py>,
        block: &Bound<'py, Block>,
        write: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        feed_block(py, &mut self.inner, block, |_, _| ())?;
        self.found(py, write)
    }

    /// The program-level findings, once the program has ended.
    #[pyo3(signature = (write=None))]
    fn finish<'py>(
        &mut self,
        py: Python<'py>,
        write: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.inner.finish();
        self.found(py, write)
    }

    /// The statistics: blocks, extents, lengths, time, tools.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        if !self.inner.stats_kept() {
            return Err(PyValueError::new_err(
                "the checker was made without statistics (stats=False)",
            ));
        }
        let s = &self.inner.stats;
        let d = PyDict::new(py);
        d.set_item("blocks", s.blocks)?;
        d.set_item("arcs", s.arcs)?;
        let (low, high) = (PyDict::new(py), PyDict::new(py));
        for (i, &a) in AXES.iter().enumerate() {
            let name = (a as char).to_string();
            if let Some(v) = s.low[i] {
                low.set_item(&name, decimal(py, Some(v))?)?;
            }
            if let Some(v) = s.high[i] {
                high.set_item(&name, decimal(py, Some(v))?)?;
            }
        }
        d.set_item("low", low)?;
        d.set_item("high", high)?;
        d.set_item("rapid_length", s.rapid_length)?;
        d.set_item("feed_length", s.feed_length)?;
        d.set_item("seconds", s.seconds)?;
        d.set_item("tools", s.tools.clone())?;
        d.set_item("travel_moves", s.travel_moves)?;
        d.set_item("travel_absolute", s.travel_absolute)?;
        d.set_item("travel_not", s.travel_not.clone())?;
        d.set_item("moves_not_known", s.moves_not_known.clone())?;
        d.set_item("dwells_not_counted", s.dwells_not_counted)?;
        d.set_item("dwells_not_known", s.dwells_not_known.clone())?;
        d.set_item("units", self.inner.units().name())?;
        Ok(d)
    }

    /// The moves recorded for the backplot: (kind, start, end, line, centre, clockwise, plane,
    /// large), an arc's centre by I J K, R or CR= alike.
    /// The backplot's facts beyond the path (`check::Drawn`): the units of the moves
    /// (`metric`, `inch`), the axes (X 1, Y 2, Z 4) of each line that moves from an unknown
    /// position, the lines that move to or through the reference point, the first blocks
    /// that shift, rotate, scale or mirror the coordinates (line, code) and how many there
    /// are, and the axes of each line that moves at a position the program has lost.
    #[getter]
    #[allow(clippy::type_complexity)]
    fn drawn(
        &self,
    ) -> (
        Vec<&'static str>,
        Vec<(usize, u8)>,
        Vec<usize>,
        Vec<(usize, String)>,
        usize,
        Vec<(usize, u8)>,
    ) {
        let d = &self.inner.drawn;
        let units = [("metric", d.units[0]), ("inch", d.units[1])]
            .into_iter()
            .filter_map(|(name, set)| set.then_some(name))
            .collect();
        (
            units,
            d.unknown.clone(),
            d.machine.clone(),
            d.transforms.clone(),
            d.transform_count,
            d.adrift.clone(),
        )
    }

    #[getter]
    fn path<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for s in &self.inner.path {
            let start = (s.start[0], s.start[1], s.start[2]);
            let end = (s.end[0], s.end[1], s.end[2]);
            let centre = s.centre.map(|c| (c[0], c[1], c[2]));
            out.append((
                s.kind,
                start,
                end,
                s.line,
                centre,
                s.clockwise,
                s.plane,
                s.large,
            ))?;
        }
        Ok(out)
    }

    /// The modal state after the last block.
    #[getter]
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        state_dict(py, &self.inner.machine.state)
    }
}

/// Give `checker` one `Block` (or `BadBlock`), then call `after` with the block as the checker
/// read it (not for a `BadBlock`: the checker reports it and nothing more is read).
pub(crate) fn feed_block<'py>(
    py: Python<'py>,
    checker: &mut check::Checker,
    block: &Bound<'py, Block>,
    after: impl FnOnce(&mut check::Checker, &BlockView<'_>),
) -> PyResult<()> {
    {
        // a line the control never reads (after a LinuxCNC program's end): passed over
        let b = block.borrow();
        if checker.not_read(b.line, &str_bytes(b.text.bind(py))?) {
            return Ok(());
        }
    }
    if let Ok(bad) = block.downcast::<BadBlock>() {
        let error = bad.borrow().error.clone_ref(py);
        let error = error.bind(py);
        let b = block.borrow();
        let text = str_bytes(b.text.bind(py))?;
        let code: Option<String> = error.getattr("code")?.extract()?;
        let message: String = error.getattr("message")?.extract()?;
        let col: Option<usize> = error.getattr("column")?.extract()?;
        let rule = code
            .as_deref()
            .and_then(Rule::from_id)
            .unwrap_or(Rule::Unreadable);
        checker.unreadable(&Unreadable {
            line: b.line,
            text: &text,
            rule,
            message: &message,
            column: col.unwrap_or(1),
        });
        return Ok(());
    }
    let b = block.borrow();
    let text = str_bytes(b.text.bind(py))?;
    let mut token_bytes: Vec<Vec<u8>> = Vec::new();
    for token in b.words.bind(py).iter() {
        token_bytes.push(str_bytes(token.downcast::<PyString>()?)?.into_owned());
    }
    let mut words = Vec::with_capacity(token_bytes.len());
    let mut pos = 0;
    for token in &token_bytes {
        let at = find_token(&text, token, pos);
        words.push(Word::new(token, column(&text, at)));
        pos = (at + 1).min(text.len());
    }
    let mut comment_texts: Vec<(usize, Vec<u8>)> = Vec::new();
    let mut statement_texts: Vec<(usize, Kind, Vec<u8>)> = Vec::new();
    let (mut skip, mut percent, mut ident) = (false, false, Vec::new());
    let mut skip_within = None;
    if let Some(info) = &b.info {
        let info = info.borrow(py);
        skip = !info.skip.bind(py).to_str()?.is_empty();
        skip_within = info
            .skip_within
            .extract::<Option<(usize, String)>>(py)?
            .map(|(col, _)| col);
        percent = info.percent;
        ident = str_bytes(info.ident.bind(py))?.into_owned();
        for entry in info.comments.bind(py).iter() {
            let (col, comment): (usize, Bound<'_, PyString>) = entry.extract()?;
            comment_texts.push((col, str_bytes(&comment)?.into_owned()));
        }
        for entry in info.statements.bind(py).iter() {
            let (col, text, kind): (usize, Bound<'_, PyString>, String) = entry.extract()?;
            let kind = Kind::from_name(&kind).unwrap_or(Kind::Command);
            statement_texts.push((col, kind, str_bytes(&text)?.into_owned()));
        }
    }
    let statements: Vec<(usize, Kind, &[u8])> = statement_texts
        .iter()
        .map(|(c, k, t)| (*c, *k, t.as_slice()))
        .collect();
    let comments: Vec<(usize, &[u8])> = comment_texts
        .iter()
        .map(|(c, t)| (*c, t.as_slice()))
        .collect();
    let view = BlockView {
        line: b.line,
        text: &text,
        ascii: text.is_ascii(),
        crs: None,
        words: &words,
        skip,
        skip_within,
        comments: &comments,
        percent,
        ident: &ident,
        statements: &statements,
    };
    checker.block(&view);
    after(checker, &view);
    Ok(())
}

/// The one modal state machine, for Python's `postproc.state.ModalMachine` (restart, plot).
#[pyclass(module = "formats._core")]
pub struct ModalMachine {
    config: Arc<Config>,
    machine: tapegate_core::modal::ModalMachine,
    values: BlockValues,
}

#[pymethods]
impl ModalMachine {
    #[new]
    fn new(machine: &Machine) -> PyResult<Self> {
        let config = machine.inner.check.clone();
        let machine = tapegate_core::modal::ModalMachine::new(config.modal.clone());
        Ok(ModalMachine {
            config,
            machine,
            values: BlockValues::default(),
        })
    }

    /// Apply a block given by its word tokens.
    fn apply(&mut self, words: &Bound<'_, PyList>) -> PyResult<()> {
        let mut owned: Vec<Vec<u8>> = Vec::with_capacity(words.len());
        for token in words.iter() {
            owned.push(str_bytes(token.downcast::<PyString>()?)?.into_owned());
        }
        let tokens: Vec<&[u8]> = owned.iter().map(Vec::as_slice).collect();
        let units = (self.machine.state.units, self.machine.state.feed_units);
        let cycle = (self.machine.state).code_in_force(self.machine.settings.fanuc_lathe);
        self.config
            .block_values(&tokens, units, cycle, &mut self.values);
        self.machine.apply(&self.values);
        Ok(())
    }

    /// Back to the reset state of clause 14 (the position is kept).
    fn reset(&mut self) {
        self.machine.reset();
    }

    #[getter]
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        state_dict(py, &self.machine.state)
    }
}
