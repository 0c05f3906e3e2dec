//! `formats._core.DiffReader`, `DiffBlock` and `DiffComparer`: two programs read and compared
//! for `formats.diff` (`tapegate diff`, `convert --verify`).
//!
//! A profile arrives once, compiled (`crate::machine::Machine`); a block arrives as its word
//! tokens and stays in Rust. Only a block that differs is turned into Python objects (`DiffBlock.words`), its exact
//! values as text that `decimal.Decimal` reads back exactly. No rule is decided here: they are
//! `tapegate_core::ncread`'s and `tapegate_core::ncdiff`'s.

use std::sync::Arc;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyDict, PyIterator, PyList, PyString, PyType};
use tapegate_core::decimal::Dec;
use tapegate_core::dialect::Opening;
use tapegate_core::ncdiff::{self, Big, Comparer, Held, Options, Ratio, Side, View};
use tapegate_core::ncread::{self, Factor, Reader, STATE_LETTERS};
use tapegate_core::statement::Kind as StatementKind;

use crate::checker::state_dict;
use crate::machine::Machine;
use tapegate_core::text::column;
use tapegate_core::{tokenize, Token};

use crate::{find_token, item, parse_error, py_text, python_class, str_bytes, units};

static DIFF_ERROR: GILOnceCell<Py<PyType>> = GILOnceCell::new();

fn factor(f: Factor) -> u8 {
    match f {
        Factor::One => 0,
        Factor::Inch => 1,
        Factor::Foot => 2,
    }
}

fn tokens(words: &Bound<'_, PyList>) -> PyResult<Vec<Vec<u8>>> {
    let mut owned: Vec<Vec<u8>> = Vec::with_capacity(words.len());
    for token in words.iter() {
        owned.push(str_bytes(token.downcast::<PyString>()?)?.into_owned());
    }
    Ok(owned)
}

/// One program's reader (`formats.diff.ProgramReader`).
#[pyclass(module = "formats._core")]
pub struct DiffReader {
    inner: Reader,
    file: PyObject,
}

/// The located `formats.diff.DiffError` of a block's words whose number could not be read
/// (`first`: the index of its first word token among its words, after `/` and `%`), by word
/// index; columns found as `Block.word_objects` finds them.
fn located(
    py: Python<'_>,
    file: &PyObject,
    block: &ncread::DiffBlock,
    text: &[u8],
    tokens: &[&[u8]],
    first: usize,
) -> PyResult<Option<PyObject>> {
    if block.words.iter().all(|w| w.error.is_none()) {
        return Ok(None);
    }
    let class = python_class(py, &DIFF_ERROR, "formats.diff", "DiffError")?;
    let errors = PyDict::new(py);
    let mut pos = 0;
    for (i, token) in tokens.iter().enumerate() {
        let at = find_token(text, token, pos);
        pos = (at + 1).min(text.len());
        if let Some(message) = &block.words[first + i].error {
            let kwargs = PyDict::new(py);
            kwargs.set_item("file", file)?;
            kwargs.set_item("line", block.line)?;
            kwargs.set_item("column", column(text, at))?;
            kwargs.set_item("clause", "Annex C")?;
            kwargs.set_item("code", "diff-number")?;
            errors.set_item(first + i, class.call((message,), Some(&kwargs))?)?;
        }
    }
    Ok(Some(errors.into_any().unbind()))
}

impl DiffReader {
    fn drift<'py>(&self, py: Python<'py>, message: String, line: usize) -> PyResult<PyErr> {
        let class = python_class(py, &DIFF_ERROR, "formats.diff", "DiffError")?;
        let kwargs = PyDict::new(py);
        kwargs.set_item("file", &self.file)?;
        kwargs.set_item("line", line)?;
        kwargs.set_item("clause", "modal state")?;
        kwargs.set_item("code", "diff-modal-drift")?;
        Ok(PyErr::from_value(class.call((message,), Some(&kwargs))?))
    }

    /// One block of a line's words and extras, with its located errors.
    #[allow(clippy::too_many_arguments)]
    fn block(
        &mut self,
        py: Python<'_>,
        line: usize,
        text: &[u8],
        tokens: &[&[u8]],
        opening: &Opening<'_>,
        percent: bool,
        skip: &[u8],
        skip_within: Option<(&[u8], usize)>,
        comments: Vec<Vec<u8>>,
        statements: &[(usize, StatementKind, &[u8])],
    ) -> PyResult<Option<DiffBlock>> {
        match self.inner.block(
            line,
            tokens,
            opening,
            percent,
            skip,
            skip_within,
            comments,
            statements,
        ) {
            Ok(Some(inner)) => {
                let first = usize::from(percent) + usize::from(!skip.is_empty());
                let errors = located(py, &self.file, &inner, text, tokens, first)?;
                Ok(Some(DiffBlock {
                    inner: Arc::new(inner),
                    text: text.to_vec(),
                    errors,
                }))
            }
            Ok(None) => Ok(None),
            Err(message) => Err(self.drift(py, message, line)?),
        }
    }
}

/// A block that cannot be read, compared as its text (stripped, upper case, as Python says).
fn bad_block(text: &Bound<'_, PyString>, line: usize) -> PyResult<DiffBlock> {
    let shown = text
        .call_method1("strip", (" \t\r\x00\x7f",))?
        .call_method0("upper")?;
    Ok(DiffBlock {
        inner: Arc::new(Reader::bad_block(
            line,
            &str_bytes(shown.downcast::<PyString>()?)?,
        )),
        text: str_bytes(text)?.into_owned(),
        errors: None,
    })
}

/// `(blocks, where to go on, lines read, error)` of [`DiffReader::read_lines`].
type ReadLines<'py> = (Bound<'py, PyList>, Option<usize>, usize, Option<PyErr>);

#[pymethods]
impl DiffReader {
    /// A reader of programs for `machine`; with `motion`, the core's modal state machine runs
    /// beside the reading (the checker's, family rules of motion and all); `file` names the
    /// program in errors.
    #[new]
    fn new(machine: &Machine, motion: bool, file: PyObject) -> PyResult<Self> {
        let mut inner = Reader::new(machine.inner.read_settings());
        if motion {
            inner = inner.with_motion(machine.inner.check.clone());
        }
        Ok(DiffReader { inner, file })
    }

    /// The units LinuxCNC subroutine bodies are read in, as (label, "inch" or "metric"), where
    /// not those in force where they stand (`ncread::Reader::bodies`).
    fn set_bodies(&mut self, bodies: Vec<(String, String)>) {
        self.inner.bodies = bodies
            .into_iter()
            .map(|(label, u)| (label.into_bytes(), units(&u)))
            .collect();
    }

    /// A block (its line, text, word tokens, extras and statements `(column, text, kind)`)
    /// as read, or None for one with nothing to compare; `formats.diff.DiffError` where the
    /// modes read here are not the core's.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (line, text, words, percent, skip, comments, statements=Vec::new(),
                        skip_within=None))]
    fn read(
        &mut self,
        py: Python<'_>,
        line: usize,
        text: &Bound<'_, PyString>,
        words: &Bound<'_, PyList>,
        percent: bool,
        skip: &Bound<'_, PyString>,
        comments: Vec<String>,
        statements: Vec<(usize, String, String)>,
        skip_within: Option<(usize, String)>,
    ) -> PyResult<Option<DiffBlock>> {
        let owned = tokens(words)?;
        let refs: Vec<&[u8]> = owned.iter().map(Vec::as_slice).collect();
        let skip = str_bytes(skip)?;
        let comments = comments.into_iter().map(String::into_bytes).collect();
        let text = str_bytes(text)?;
        // the places of the first word and the first statement, both as columns
        let opening = if percent {
            Opening::percent_line(&text)
        } else {
            Opening {
                word: refs.first().and_then(|t| {
                    let letter = t.first()?.to_ascii_uppercase();
                    Some((column(&text, find_token(&text, t, 0)), letter))
                }),
                statement: statements.first().map(|(col, statement, kind)| {
                    let kind = StatementKind::from_name(kind).unwrap_or(StatementKind::Command);
                    (*col, kind, statement.as_bytes())
                }),
                percent: None,
            }
        };
        // the tokens written after the slash's column are those it skips
        let within = skip_within.as_ref().map(|(col, mark)| {
            let mut pos = 0;
            let first = refs
                .iter()
                .position(|t| {
                    let at = find_token(&text, t, pos);
                    pos = (at + 1).min(text.len());
                    column(&text, at) > *col
                })
                .unwrap_or(refs.len());
            (mark.as_bytes(), first)
        });
        let statements: Vec<(usize, StatementKind, &[u8])> = statements
            .iter()
            .map(|(col, statement, kind)| {
                let kind = StatementKind::from_name(kind).unwrap_or(StatementKind::Command);
                (*col, kind, statement.as_bytes())
            })
            .collect();
        self.block(
            py,
            line,
            &text,
            &refs,
            &opening,
            percent,
            &skip,
            within,
            comments,
            &statements,
        )
    }

    /// The blocks of `data` (UTF-8 bytes of whole lines, without the last LF) from byte `start`,
    /// whose first line is line `line + 1`, tokenized and read here with no Python object per
    /// block but those kept, `limit` lines at most (memory stays that of a few blocks):
    /// `(blocks, where to go on or None at the end, the lines read, error)`, the error (a
    /// `ParseError`, or the `DiffError` of a modal drift) ending the reading, for the caller to
    /// raise after the blocks before it. With `collect` a line that cannot be tokenized is a
    /// block compared as its text.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (data, start, line, limit, flags, collect, ignore_comments))]
    fn read_lines<'py>(
        &mut self,
        py: Python<'py>,
        data: &[u8],
        start: usize,
        line: usize,
        limit: usize,
        flags: crate::Flags,
        collect: bool,
        ignore_comments: bool,
    ) -> PyResult<ReadLines<'py>> {
        let dialect = crate::dialect(flags);
        let out = PyList::empty(py);
        let mut words: Vec<Token<'_>> = Vec::with_capacity(16);
        let rest = data.get(start..).unwrap_or_default();
        let mut at = start;
        let mut read = 0;
        for (number, text) in (line + 1..).zip(rest.split(|&b| b == b'\n')) {
            if read == limit {
                return Ok((out, Some(at), read, None));
            }
            read += 1;
            at += text.len() + 1;
            words.clear();
            if self.inner.not_read(number, text) {
                // never read by the control (after a LinuxCNC program's end): its text
                if tapegate_core::dialect::holds_program(text) {
                    out.append(Py::new(py, bad_block(&py_text(py, text)?, number)?)?)?;
                }
                continue;
            }
            let extras = match tokenize(text, &dialect, &mut words) {
                Ok(extras) => extras,
                Err(error) => {
                    let exception =
                        parse_error(py, &error, text, &Some(self.file.clone_ref(py)), number)?;
                    if !collect {
                        return Ok((out, None, read, Some(PyErr::from_value(exception))));
                    }
                    out.append(Py::new(py, bad_block(&py_text(py, text)?, number)?)?)?;
                    continue;
                }
            };
            let (mut percent, mut skip, mut comments): (bool, &[u8], Vec<Vec<u8>>) =
                (false, b"", Vec::new());
            let level: [u8; 2];
            if let Some(e) = &extras {
                percent = e.percent;
                if e.skip == b'/' {
                    skip = b"/";
                } else if e.skip != 0 {
                    level = [b'/', e.skip];
                    skip = &level;
                }
                if !ignore_comments {
                    if e.percent && !e.ident.is_empty() {
                        comments.push(e.ident.to_vec());
                    }
                    comments.extend(e.comments.iter().map(|(_, c)| c.to_vec()));
                }
            }
            let refs: Vec<&[u8]> = words.iter().map(|w| w.text.as_ref()).collect();
            let within = extras
                .as_ref()
                .and_then(|e| e.skip_within)
                .map(|(at, level)| {
                    let mark = &text[at..at + usize::from(level != b'/') + 1];
                    (mark, words.iter().take_while(|w| w.offset < at).count())
                });
            let opening = if percent {
                Opening::percent_line(text)
            } else {
                Opening {
                    word: words
                        .first()
                        .and_then(|w| Some((w.offset, w.text.first()?.to_ascii_uppercase()))),
                    statement: extras.as_ref().and_then(|e| {
                        let s = e.statements.first()?;
                        Some((s.offset, s.kind, &text[s.offset..s.end]))
                    }),
                    percent: None,
                }
            };
            let statements = extras
                .as_ref()
                .map(|e| e.statement_texts(text))
                .unwrap_or_default();
            let block = self.block(
                py,
                number,
                text,
                &refs,
                &opening,
                percent,
                skip,
                within,
                comments,
                &statements,
            );
            match block {
                Ok(Some(block)) => out.append(Py::new(py, block)?)?,
                Ok(None) => {}
                Err(error) => return Ok((out, None, read, Some(error))),
            }
        }
        Ok((out, None, read, None))
    }

    /// Whether the control never reads line `line` (after a LinuxCNC program's end: the
    /// core's `dialect::ReadingEnd`), asked before it is read.
    fn not_read(&mut self, line: usize, text: &Bound<'_, PyString>) -> PyResult<bool> {
        Ok(self.inner.not_read(line, &str_bytes(text)?))
    }

    /// A block the profile cannot read, compared as its text.
    #[staticmethod]
    fn bad(line: usize, text: &Bound<'_, PyString>) -> PyResult<DiffBlock> {
        bad_block(text, line)
    }

    /// `(units, feed_units, incremental, feed_mode, css)` read here after the last block.
    #[getter]
    fn modes(&self) -> (&'static str, &'static str, bool, i64, bool) {
        let r = &self.inner;
        (
            r.units.name(),
            r.feed_units.name(),
            r.incremental,
            r.feed_mode,
            r.css,
        )
    }

    #[getter]
    fn incremental(&self) -> bool {
        self.inner.incremental
    }

    /// The distance mode read here (a test makes it drift from the core's on purpose).
    #[setter]
    fn set_incremental(&mut self, incremental: bool) {
        self.inner.incremental = incremental;
    }
}

/// One block as read, held in Rust.
#[pyclass(module = "formats._core")]
pub struct DiffBlock {
    inner: Arc<ncread::DiffBlock>,
    text: Vec<u8>,
    errors: Option<PyObject>,
}

type WordTuple<'py> = (
    Bound<'py, PyString>,
    Bound<'py, PyString>,
    &'static str,
    Option<String>,
    u8,
    String,
    (bool, bool, bool, bool),
    Option<u8>,
    Option<String>,
    Bound<'py, PyString>,
);

#[pymethods]
impl DiffBlock {
    #[getter]
    fn line(&self) -> usize {
        self.inner.line
    }

    #[getter]
    fn text<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyString>> {
        py_text(py, &self.text)
    }

    /// The sequence number as text, if any.
    #[getter]
    fn number(&self) -> Option<String> {
        self.inner.number.map(|n| n.to_string())
    }

    /// Whether it has a word other than `%` (pairing by number counts these).
    #[getter]
    fn has_words(&self) -> bool {
        self.inner.words.iter().any(|w| w.key != b"%")
    }

    #[getter]
    fn resets(&self) -> bool {
        self.inner.resets
    }

    /// The located errors of its words whose number could not be read, by word index.
    #[getter]
    fn errors(&self, py: Python<'_>) -> Option<PyObject> {
        self.errors.as_ref().map(|e| e.clone_ref(py))
    }

    #[getter]
    fn comments<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyString>>> {
        self.inner.comments.iter().map(|c| py_text(py, c)).collect()
    }

    /// Its words: `(key, token, kind, value, factor, step, (incremental, parameter,
    /// per_revolution, milliseconds), as_length, error, written)`, factors 0 (one), 1 (25.4),
    /// 2 (0.3048).
    fn words<'py>(&self, py: Python<'py>) -> PyResult<Vec<WordTuple<'py>>> {
        self.inner
            .words
            .iter()
            .map(|w| {
                Ok((
                    py_text(py, &w.key)?,
                    py_text(py, &w.token)?,
                    w.kind.name(),
                    w.value.map(|v| v.to_string()),
                    factor(w.factor),
                    w.step.to_string(),
                    (w.incremental, w.parameter, w.per_revolution, w.milliseconds),
                    w.as_length.map(factor),
                    w.error.clone(),
                    py_text(py, &w.written)?,
                ))
            })
            .collect()
    }

    /// The core's modal state after the block (with the motion compared), with the factor of
    /// the word that set each value.
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(state) = &self.inner.state else {
            return Ok(None);
        };
        let d = state_dict(py, &state.modal)?;
        let factors = PyDict::new(py);
        for (i, f) in state.factors.iter().enumerate() {
            if let Some(f) = f {
                factors.set_item((STATE_LETTERS[i] as char).to_string(), factor(*f))?;
            }
        }
        d.set_item("factors", factors)?;
        Ok(Some(d))
    }
}

fn ratio(text: &(String, String)) -> PyResult<Ratio> {
    let big = |t: &str| {
        Big::parse(t).ok_or_else(|| PyValueError::new_err(format!("not a whole number: {t}")))
    };
    Ok(Ratio::new(big(&text.0)?, big(&text.1)?))
}

type ViewTuple = (&'static str, String, u8, String);
type SideTuple = (usize, Option<ViewTuple>);
type ChangeTuple<'py> = (
    &'static str,
    Bound<'py, PyString>,
    Option<SideTuple>,
    Option<SideTuple>,
    Option<String>,
);
type MotionTuple = (String, String, String, Option<String>);
type FoundTuple<'py> = (Vec<ChangeTuple<'py>>, bool, Vec<MotionTuple>);

fn side(s: &Option<Side>) -> Option<SideTuple> {
    s.as_ref().map(|s| {
        let view = s.view.as_ref().map(|v: &View| {
            (
                v.kind.name(),
                v.value.to_string(),
                factor(v.factor),
                v.step.to_string(),
            )
        });
        (s.index, view)
    })
}

/// The comparison of two programs' blocks (`formats.diff.Differ`).
#[pyclass(module = "formats._core")]
pub struct DiffComparer {
    inner: Comparer,
}

#[pymethods]
impl DiffComparer {
    /// `options`: `tolerance` and each bound as `(numerator, denominator)` text, the flags,
    /// and `steps`: `[(letter, units, step)]` of B's profile.
    #[new]
    fn new(options: &Bound<'_, PyDict>) -> PyResult<Self> {
        let bounds: Option<Vec<(String, (String, String))>> = item(options, "bounds")?;
        let bounds = bounds
            .map(|b| {
                b.iter()
                    .map(|(letter, r)| Ok((letter.as_bytes()[0], ratio(r)?)))
                    .collect::<PyResult<Vec<_>>>()
            })
            .transpose()?;
        let steps: Vec<(String, String, String)> = item(options, "steps")?;
        let steps = steps
            .iter()
            .map(|(letter, u, step)| {
                let step = Dec::parse(step)
                    .ok_or_else(|| PyValueError::new_err(format!("not a number: {step}")))?;
                Ok((letter.as_bytes()[0], units(u), step))
            })
            .collect::<PyResult<Vec<_>>>()?;
        Ok(DiffComparer {
            inner: Comparer::new(Options {
                tolerance: ratio(&item(options, "tolerance")?)?,
                bounds,
                word_order: item(options, "word_order")?,
                parameters_address: item(options, "parameters_address")?,
                unstated_adopt: item(options, "unstated_adopt")?,
                same_text: item(options, "same_text")?,
                steps,
            }),
        })
    }

    /// What differs between two blocks (None: the same): `(words, comments, motion)`, a word
    /// change `(kind, key, a, b, difference)` with each side `(index, view)`, a view `(kind,
    /// value, factor, step)` where the word was compared otherwise than read; a motion change
    /// `(what, a, b, difference)`.
    fn compare<'py>(
        &mut self,
        py: Python<'py>,
        a: PyRef<'_, DiffBlock>,
        b: PyRef<'_, DiffBlock>,
        commit: bool,
    ) -> PyResult<Option<FoundTuple<'py>>> {
        let Some(found) = self.inner.compare(&a.inner, &b.inner, commit) else {
            return Ok(None);
        };
        let words = found
            .words
            .iter()
            .map(|c| {
                Ok((
                    c.kind.name(),
                    py_text(py, &c.key)?,
                    side(&c.a),
                    side(&c.b),
                    c.difference.map(|d| d.to_string()),
                ))
            })
            .collect::<PyResult<Vec<_>>>()?;
        let motion = found
            .motion
            .into_iter()
            .map(|m| (m.what, m.a, m.b, m.difference.map(|d| d.to_string())))
            .collect();
        Ok(Some((words, found.comments, motion)))
    }

    /// The statements whose numbers were not compared (`ncdiff::Comparer::unread`): `[(line
    /// in A, line in B, A's text)]`.
    fn unread(&self, py: Python<'_>) -> PyResult<Vec<(usize, usize, Py<PyString>)>> {
        self.inner
            .unread
            .iter()
            .map(|(a, b, text)| Ok((*a, *b, py_text(py, text)?.unbind())))
            .collect()
    }

    /// A block only in one program.
    fn unpaired(&mut self, block: PyRef<'_, DiffBlock>) {
        self.inner.unpaired(&block.inner);
    }
}

/// A block held by the pairing: the core's block, and the Python object handed back.
struct Item {
    block: Arc<ncread::DiffBlock>,
    object: Py<DiffBlock>,
}

impl Held for Item {
    fn block(&self) -> &ncread::DiffBlock {
        &self.block
    }
}

fn pull(py: Python<'_>, blocks: &Py<PyIterator>) -> PyResult<Option<Item>> {
    match blocks.bind(py).clone().next() {
        None => Ok(None),
        Some(found) => {
            let object = found?.downcast_into::<DiffBlock>()?;
            let block = Arc::clone(&object.borrow().inner);
            Ok(Some(Item {
                block,
                object: object.unbind(),
            }))
        }
    }
}

/// How the pairing goes: by position, or by sequence number.
enum Pairing {
    Position(ncdiff::Aligner<Item>),
    Number(Box<ncdiff::NumberAligner<Item>>),
}

/// Two programs' blocks paired (`formats.diff.Differ.run`) by position (the core's
/// `ncdiff::Aligner`) or by sequence number (`ncdiff::NumberAligner`), pulling the blocks
/// from two Python iterators.
#[pyclass(module = "formats._core")]
pub struct DiffAligner {
    comparer: Py<DiffComparer>,
    left: Py<PyIterator>,
    right: Py<PyIterator>,
    inner: Pairing,
}

type Step = (usize, Option<Py<DiffBlock>>, Option<Py<DiffBlock>>);

#[pymethods]
impl DiffAligner {
    #[new]
    #[pyo3(signature = (comparer, left, right, window, by_number = false))]
    fn new(
        comparer: Py<DiffComparer>,
        left: &Bound<'_, PyAny>,
        right: &Bound<'_, PyAny>,
        window: usize,
        by_number: bool,
    ) -> PyResult<Self> {
        Ok(DiffAligner {
            comparer,
            left: left.try_iter()?.unbind(),
            right: right.try_iter()?.unbind(),
            inner: if by_number {
                Pairing::Number(Box::new(ncdiff::NumberAligner::new(window)))
            } else {
                Pairing::Position(ncdiff::Aligner::new(window))
            },
        })
    }

    /// `(same, a, b)`: how many pairs were the same, then the next that is not -- `a` only in
    /// A, `b` only in B, or both, changed -- or `(same, None, None)` at the end.
    fn step(&mut self, py: Python<'_>) -> PyResult<Step> {
        let mut comparer = self.comparer.borrow_mut(py);
        let (left, right) = (&self.left, &self.right);
        let (pull_a, pull_b) = (&mut || pull(py, left), &mut || pull(py, right));
        let found = match &mut self.inner {
            Pairing::Position(a) => a.next(&mut comparer.inner, pull_a, pull_b)?,
            Pairing::Number(a) => a.next(&mut comparer.inner, pull_a, pull_b)?,
        };
        Ok(match found {
            (same, None) => (same, None, None),
            (same, Some((a, b))) => (same, a.map(|i| i.object), b.map(|i| i.object)),
        })
    }
}
