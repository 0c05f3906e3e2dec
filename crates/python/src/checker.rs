//! `formats._core.Checker`: the core's checker, given a profile by `postproc.check`.
//!
//! The profile arrives once, as a dict of plain values (`postproc.state.core_config`); the
//! program arrives as text a chunk of whole lines at a time (the fast way: no Python object per
//! block) or as `Block` objects (`Checker.run`). Findings leave as `postproc.findings.Finding`
//! tuples, made by the `make` callable, with the rule's severity and clause from `rules`.

use std::collections::HashMap;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use tapegate_core::check::{self, BlockView, Code, Config, Ijk, Status, Unreadable, Word};
use tapegate_core::decimal::Dec;
use tapegate_core::modal::{BlockValues, ModalSettings, ModalState, AXES, CYCLE_WORDS};
use tapegate_core::statement::Kind;
use tapegate_core::text::column;
use tapegate_core::Family;

use crate::{find_token, item, role, str_bytes, units, BadBlock, Block};

fn dec(text: Option<String>) -> PyResult<Option<Dec>> {
    text.map(|t| Dec::parse(&t).ok_or_else(|| PyValueError::new_err(format!("not a number: {t}"))))
        .transpose()
}

fn codes(entries: Vec<Option<(String, String)>>) -> PyResult<Vec<Option<Code>>> {
    entries
        .into_iter()
        .map(|entry| {
            entry
                .map(|(status, duration)| {
                    let status = match status.as_str() {
                        "assigned" => Status::Assigned,
                        "conditional" => Status::Conditional,
                        "unassigned" => Status::Unassigned,
                        "permanent" => Status::Permanent,
                        other => return Err(PyValueError::new_err(format!("status {other:?}"))),
                    };
                    Ok(Code { status, duration })
                })
                .transpose()
        })
        .collect()
}

fn letter(text: &str) -> u8 {
    text.as_bytes().first().copied().unwrap_or(b'?')
}

pub(crate) fn config(c: &Bound<'_, PyDict>) -> PyResult<Config> {
    let formats = crate::word_formats(item(c, "formats")?);
    let formats_inch =
        item::<Option<Vec<crate::FormatEntry>>>(c, "formats_inch")?.map(crate::word_formats);
    let ijk = match item::<String>(c, "ijk")?.as_str() {
        "absolute" => Ijk::Absolute,
        "quadrant" => Ijk::Quadrant,
        _ => Ijk::Incremental,
    };
    let pqr: (String, String, String) = item(c, "pqr")?;
    let travel: Vec<(String, String, String)> = item(c, "travel")?;
    let travel = travel
        .into_iter()
        .map(|(axis, low, high)| {
            Ok((
                letter(&axis),
                dec(Some(low))?.unwrap(),
                dec(Some(high))?.unwrap(),
            ))
        })
        .collect::<PyResult<Vec<_>>>()?;
    let offsets: Vec<(i64, String, String)> = item(c, "work_offsets")?;
    let work_offsets = offsets
        .into_iter()
        .map(|(g, axis, value)| Ok((g, letter(&axis), dec(Some(value))?.unwrap())))
        .collect::<PyResult<Vec<_>>>()?;
    let program_number: String = item(c, "program_number")?;
    Ok(Config {
        formats,
        formats_inch,
        explicit: item(c, "explicit")?,
        increments: item::<Option<String>>(c, "increments")?.map(String::into_bytes),
        alignment: item(c, "alignment")?,
        classification: item(c, "classification")?,
        table_name: item(c, "table_name")?,
        g_codes: codes(item(c, "g_codes")?)?,
        g_decimal: {
            let entries: Vec<(String, String, String)> = item(c, "g_decimal")?;
            let codes = codes(
                entries
                    .iter()
                    .map(|(_, s, d)| Some((s.clone(), d.clone())))
                    .collect(),
            )?;
            entries
                .into_iter()
                .zip(codes)
                .filter_map(|((n, _, _), c)| c.map(|c| (n, c)))
                .collect()
        },
        m_codes: codes(item(c, "m_codes")?)?,
        program_number: program_number.bytes().next(),
        family: Family::from_name(&item::<String>(c, "family")?).unwrap_or_default(),
        percent: item(c, "percent")?,
        colon_stop: item(c, "colon_stop")?,
        alarm_g: item(c, "alarm_g")?,
        alarm_m: item(c, "alarm_m")?,
        diameter: item(c, "diameter")?,
        tv_check: item(c, "tv_check")?,
        arc_tolerance: item(c, "arc_tolerance")?,
        arc_tolerance_relative: item(c, "arc_tolerance_relative")?,
        ijk,
        repeatable: item::<String>(c, "repeatable")?.into_bytes(),
        m_classes: item(c, "m_classes")?,
        max_index: item(c, "max_index")?,
        max_parameter: item(c, "max_parameter")?,
        index_g: item(c, "index_g")?,
        pqr: [role(&pqr.0), role(&pqr.1), role(&pqr.2)],
        travel,
        work_offsets,
        feed_max: dec(item(c, "feed_max")?)?,
        spindle_max: dec(item(c, "spindle_max")?)?,
        tool_max: item(c, "tool_max")?,
        rapid_rate: item(c, "rapid_rate")?,
        modal: modal_settings(c)?,
        select: item(c, "select")?,
        ignore: item(c, "ignore")?,
        record_path: item(c, "record_path")?,
    })
}

/// The modal state machine's settings from a profile's core config (`postproc.state`).
pub(crate) fn modal_settings(c: &Bound<'_, PyDict>) -> PyResult<ModalSettings> {
    let family: String = item(c, "family")?;
    let fanuc_lathe: bool = item(c, "fanuc_lathe")?;
    Ok(ModalSettings {
        reset: item(c, "reset")?,
        inch: item(c, "inch")?,
        metric: item(c, "metric")?,
        default_units: units(&item::<String>(c, "default_units")?),
        fanuc_lathe,
        g80_clears_motion: family == "linuxcnc",
        sinumerik_units: family == "sinumerik",
        centre_codes: matches!(family.as_str(), "fanuc" | "haas") && !fanuc_lathe,
        heidenhain: family == "heidenhain",
        units_kept_at_end: item(c, "units_kept_at_end")?,
    })
}

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
    inner: check::Checker,
    file: PyObject,
    /// Each rule's ID, severity and clause as the Python strings a finding holds (made once).
    rules: HashMap<String, [PyObject; 3]>,
    make: PyObject,
}

impl Checker {
    fn findings<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for f in self.inner.take() {
            let Some([rule, severity, clause]) = self.rules.get(f.rule) else {
                return Err(PyValueError::new_err(format!(
                    "rule {} is not in the catalogue",
                    f.rule
                )));
            };
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
    fn new(
        py: Python<'_>,
        config: &Bound<'_, PyDict>,
        rules: HashMap<String, (PyObject, PyObject)>,
        file: PyObject,
        make: PyObject,
    ) -> PyResult<Self> {
        let rules = rules
            .into_iter()
            .map(|(id, (severity, clause))| {
                let name = PyString::intern(py, &id).into_any().unbind();
                (id, [name, severity, clause])
            })
            .collect();
        Ok(Checker {
            inner: check::Checker::new(self::config(config)?),
            file,
            rules,
            make,
        })
    }

    /// The findings of whole lines of text (`data` without its last LF) after line `line`.
    fn check_lines<'py>(
        &mut self,
        py: Python<'py>,
        data: &Bound<'py, PyString>,
        line: usize,
        flags: crate::Flags,
    ) -> PyResult<Bound<'py, PyList>> {
        let dialect = crate::dialect(flags);
        let bytes = str_bytes(data)?;
        let mut tokens = Vec::with_capacity(16);
        for (number, text) in (line + 1..).zip(tapegate_core::text::lines(&bytes)) {
            self.inner.check_line(text, number, &dialect, &mut tokens);
        }
        self.findings(py)
    }

    /// The findings of one `Block` (or `BadBlock`).
    fn check_block<'py>(
        &mut self,
        py: Python<'py>,
        block: &Bound<'py, Block>,
    ) -> PyResult<Bound<'py, PyList>> {
        feed_block(py, &mut self.inner, block, |_, _| ())?;
        self.findings(py)
    }

    /// The program-level findings, once the program has ended.
    fn finish<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        self.inner.finish();
        self.findings(py)
    }

    /// The statistics: blocks, extents, lengths, time, tools.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
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
        d.set_item("units", self.inner.units().name())?;
        Ok(d)
    }

    /// The moves recorded for the backplot: (kind, start, end, line, centre, clockwise, plane,
    /// large), an arc's centre by I J K, R or CR= alike.
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
    if let Ok(bad) = block.downcast::<BadBlock>() {
        let error = bad.borrow().error.clone_ref(py);
        let error = error.bind(py);
        let b = block.borrow();
        let text = str_bytes(b.text.bind(py))?;
        let code: Option<String> = error.getattr("code")?.extract()?;
        let message: String = error.getattr("message")?.extract()?;
        let col: Option<usize> = error.getattr("column")?.extract()?;
        let rule = tapegate_core::ErrorKind::rule(code.as_deref().unwrap_or("TG100"));
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
    if let Some(info) = &b.info {
        let info = info.borrow(py);
        skip = !info.skip.bind(py).to_str()?.is_empty();
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
        words: &words,
        skip,
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
    config: Config,
    machine: tapegate_core::modal::ModalMachine,
    values: BlockValues,
}

#[pymethods]
impl ModalMachine {
    #[new]
    fn new(config: &Bound<'_, PyDict>) -> PyResult<Self> {
        let config = self::config(config)?;
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
        self.config.block_values(&tokens, units, &mut self.values);
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
