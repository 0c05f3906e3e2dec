//! `formats._core.Converter`: the core's converter between two compiled `Machine`s, with the
//! options `formats.convert` gives.
//!
//! Whole lines of text a chunk at a time (no Python object per block) or `Block` objects go
//! in; the converted text comes out, with each end of block as written or in the target style.
//! A block that cannot be read raises the located `ParseError`, a word that cannot be
//! converted the located `ConversionError`.

use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyDict, PyList, PyString, PyType};
use std::sync::Arc;

use tapegate_core::convert::{BlockIn, ConvertError, LineError, Rounding, Spacing, WordSpan};
use tapegate_core::machine::ConvertOptions;
use tapegate_core::statement::Kind as StatementKind;
use tapegate_core::text::column;

use crate::files::{self, TextFile};
use crate::machine::Machine;
use crate::{find_token, item, parse_error, py_text, str_bytes, units, BadBlock, Block};

fn options(c: &Bound<'_, PyDict>) -> PyResult<ConvertOptions> {
    let target_units: Option<String> = item(c, "units")?;
    let rounding = match item::<String>(c, "rounding")?.as_str() {
        "half-up" => Rounding::HalfUp,
        "error" => Rounding::Error,
        _ => Rounding::HalfEven,
    };
    let spacing = match item::<String>(c, "spacing")?.as_str() {
        "remove" => Spacing::Remove,
        "insert" => Spacing::Insert,
        _ => Spacing::Keep,
    };
    let parameters: Option<PyRef<'_, ParameterClasses>> = item(c, "parameters")?;
    let read_units: Vec<(usize, String, String)> = item(c, "read_units")?;
    Ok(ConvertOptions {
        units: target_units.as_deref().map(units),
        rounding,
        spacing,
        allow_unconverted: item(c, "allow_unconverted")?,
        parameters: parameters.map(|classes| Arc::clone(&classes.inner)),
        source_detected: item(c, "source_detected")?,
        source_units_given: item(c, "source_units_given")?,
        upper_case: item(c, "upper_case")?,
        read_units: read_units
            .into_iter()
            .map(|(program, name, u)| (program, name, units(&u)))
            .collect(),
    })
}

static CONVERSION_ERROR: GILOnceCell<Py<PyType>> = GILOnceCell::new();

/// The stable code of a core conversion error (docs/errors.md), by the clause it breaks: the
/// core's `ConvertError` names a clause, one per kind of refusal.
fn conversion_code(clause: &str) -> &'static str {
    match clause {
        "Annex C" => "conversion-format",
        "units" | "units-reread" => "conversion-units",
        "6.4.7" => "conversion-unprovable",
        "cycle" => "conversion-cycle",
        "modal state" => "conversion-modal",
        "dialect" => "conversion-dialect",
        "meaning" => "conversion-meaning",
        _ => "conversion",
    }
}

fn conversion_error(
    py: Python<'_>,
    e: &ConvertError,
    file: &Option<PyObject>,
    line: usize,
) -> PyErr {
    let made = (|| -> PyResult<PyErr> {
        let class = CONVERSION_ERROR.import(py, "formats.errors", "ConversionError")?;
        let kwargs = PyDict::new(py);
        kwargs.set_item("file", file)?;
        kwargs.set_item("line", e.line.unwrap_or(line))?;
        kwargs.set_item("column", e.column.max(1))?;
        kwargs.set_item("clause", e.clause)?;
        kwargs.set_item("code", conversion_code(e.clause))?;
        Ok(PyErr::from_value(class.call((&e.message,), Some(&kwargs))?))
    })();
    made.unwrap_or_else(|err| err)
}

/// The end of `token` written at byte `start` of `text`, blanks inside the word included.
fn token_span(text: &[u8], start: usize, token: &[u8]) -> usize {
    let mut i = start;
    for &ch in token {
        while i < text.len() && text[i] != ch && matches!(text[i], b' ' | b'\t' | b'\r' | 0 | 0x7f)
        {
            i += 1;
        }
        i += 1;
    }
    i.min(text.len())
}

/// The byte offset of 1-based character column `col` in `text`.
fn offset_of(text: &[u8], col: usize) -> usize {
    if text.is_ascii() {
        return (col.max(1) - 1).min(text.len());
    }
    (0..=text.len())
        .find(|&o| column(text, o) >= col)
        .unwrap_or(text.len())
}

#[pyclass(module = "formats._core")]
pub struct Converter {
    inner: tapegate_core::convert::Converter,
    eob: Option<Vec<u8>>,
    file: Option<PyObject>,
}

/// The error of the line that failed, as `convert_lines` raises it: the located `ParseError`
/// of a line that cannot be read, the `ConversionError` of a word that cannot be converted.
fn line_error(
    py: Python<'_>,
    file: &Option<PyObject>,
    number: usize,
    text: &[u8],
    error: LineError,
) -> PyErr {
    match error {
        LineError::Read(e) => match parse_error(py, &e, text, file, number) {
            Ok(value) => PyErr::from_value(value),
            Err(e) => e,
        },
        LineError::Convert(e) => conversion_error(py, &e, file, number),
    }
}

/// The converted lines of `run` (whole lines without the last LF) after line `*line`, each
/// with its end of block, added to `out`; `*line` is the last line converted. The first line
/// that fails stops it: (its number, its text, why).
fn convert_run<'a>(
    inner: &mut tapegate_core::convert::Converter,
    eob: &Option<Vec<u8>>,
    run: &'a [u8],
    line: &mut usize,
    dialect: &tapegate_core::Dialect,
    out: &mut Vec<u8>,
) -> Result<(), (usize, &'a [u8], LineError)> {
    let mut tokens = Vec::with_capacity(16);
    for (number, text) in (*line + 1..).zip(tapegate_core::text::lines(run)) {
        *line = number;
        match inner.convert_line(text, number, dialect, &mut tokens) {
            Ok(Some(new)) => {
                finish_line(eob, out, &new, true);
                inner.give_back(new);
            }
            Ok(None) => finish_line(eob, out, text, true),
            Err(error) => return Err((number, text, error)),
        }
    }
    Ok(())
}

/// Where a step of `Converter.convert_file` stopped.
enum Step {
    /// The file is not plain text: nothing read or written.
    NotText,
    /// A chunk's lines converted and written: its notes to take.
    ChunkEnd,
    /// The whole file converted and written.
    Done,
    /// The text after the last LF is for Python to read.
    Rest,
}

/// Why a step of `Converter.convert_file` failed: the file's reading or the output's
/// writing, or a line (its number, its text, why).
enum Failed {
    Io(std::io::Error),
    Line(usize, Vec<u8>, LineError),
}

impl From<std::io::Error> for Failed {
    fn from(e: std::io::Error) -> Self {
        Failed::Io(e)
    }
}

/// `bytes` written to the open file `fd`, which stays open (it is the caller's).
fn write_to(fd: i32, bytes: &[u8]) -> std::io::Result<()> {
    use std::io::Write;
    use std::os::fd::FromRawFd;
    // SAFETY: `fd` is an open file the caller holds for the whole call (the `PendingFile` of
    // `formats.convert`), and ManuallyDrop never closes it.
    let mut file = std::mem::ManuallyDrop::new(unsafe { std::fs::File::from_raw_fd(fd) });
    file.write_all(bytes)
}

/// `text` with its end of block (`ends`) as `eob` writes it: as written (None) or with the
/// CRs before the LF replaced.
fn finish_line(eob: &Option<Vec<u8>>, out: &mut Vec<u8>, text: &[u8], ends: bool) {
    match (eob, ends) {
        (_, false) => out.extend_from_slice(text),
        (None, true) => {
            out.extend_from_slice(text);
            out.push(b'\n');
        }
        (Some(eob), true) => {
            let mut end = text.len();
            while end > 0 && text[end - 1] == b'\r' {
                end -= 1;
            }
            out.extend_from_slice(&text[..end]);
            out.extend_from_slice(eob);
        }
    }
}

#[pymethods]
impl Converter {
    #[new]
    /// A conversion of programs written for `source` to `target`, as `options` say.
    #[pyo3(signature = (source, target, options, eob, file))]
    fn new(
        source: &Machine,
        target: &Machine,
        options: &Bound<'_, PyDict>,
        eob: Option<String>,
        file: Option<PyObject>,
    ) -> PyResult<Self> {
        let config = source
            .inner
            .convert_to(&target.inner, self::options(options)?);
        Ok(Converter {
            inner: tapegate_core::convert::Converter::new(config),
            eob: eob.map(String::into_bytes),
            file,
        })
    }

    /// The converted text of whole lines (`data` without its last LF) after line `line`, each
    /// with its end of block.
    fn convert_lines<'py>(
        &mut self,
        py: Python<'py>,
        data: &Bound<'py, PyString>,
        line: usize,
        flags: crate::Flags,
    ) -> PyResult<Bound<'py, PyString>> {
        let dialect = crate::dialect(flags);
        let bytes = str_bytes(data)?;
        let mut out = Vec::with_capacity(bytes.len() + bytes.len() / 8);
        // converted with the GIL released (the threads of `tapegate convert -j` convert files
        // side by side); the first line that fails stops it, its error made afterwards
        let (inner, eob) = (&mut self.inner, &self.eob);
        let mut last = line;
        let failed =
            py.allow_threads(|| convert_run(inner, eob, &bytes, &mut last, &dialect, &mut out));
        match failed {
            Ok(()) => py_text(py, &out),
            Err((number, text, error)) => Err(line_error(py, &self.file, number, text, error)),
        }
    }

    /// The text file at `path` converted and written to the open file `fd` (its bytes after
    /// what it holds), read, converted and written with the GIL released, as `formats.convert`
    /// reads a file (`files.rs`). After each chunk, `said` is called with its notes (none is
    /// kept in the core). Returns None when the file is not plain text (nothing read or
    /// written: `formats.source` reads it), True when the whole file was converted, or
    /// `(rest, at, line)`: the text after the last LF for Python to read, as
    /// `Checker.check_file` gives it, and the number of the last line converted.
    ///
    /// Why here: each step of a file in Python (its chunks read and decoded, the lines cut,
    /// the output's string encoded and written) took the GIL, in every thread of
    /// `tapegate convert -j` (docs/benchmarks.md). The output's bytes are those `convert_lines`
    /// gives, encoded back as `surrogateescape` encodes them: the same bytes.
    fn convert_file<'py>(
        &mut self,
        py: Python<'py>,
        path: std::path::PathBuf,
        flags: crate::Flags,
        fd: i32,
        said: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let dialect = crate::dialect(flags);
        let mut file: Option<TextFile> = None;
        let mut line = 0usize;
        let mut out = Vec::new();
        loop {
            let (inner, eob, slot) = (&mut self.inner, &self.eob, &mut file);
            let step = py.allow_threads(|| -> Result<Step, Failed> {
                if slot.is_none() {
                    match TextFile::open(&path)? {
                        Some(opened) => *slot = Some(opened),
                        None => return Ok(Step::NotText),
                    }
                }
                let text = slot.as_mut().expect("opened above");
                match text.next_lines()? {
                    Some(run) => {
                        out.clear();
                        let run = &text.buffer()[run];
                        if let Err((number, failed, error)) =
                            convert_run(inner, eob, run, &mut line, &dialect, &mut out)
                        {
                            return Err(Failed::Line(number, failed.to_vec(), error));
                        }
                        write_to(fd, &out)?;
                        Ok(Step::ChunkEnd)
                    }
                    None => match text.end() {
                        (files::End::Eof, []) => Ok(Step::Done),
                        _ => Ok(Step::Rest),
                    },
                }
            });
            match step {
                Err(Failed::Io(e)) => return Err(files::os_error(py, e)),
                Err(Failed::Line(number, text, error)) => {
                    return Err(line_error(py, &self.file, number, &text, error))
                }
                Ok(Step::NotText) => return Ok(py.None().into_bound(py)),
                Ok(Step::ChunkEnd) => {
                    said.call1((self.take_notes(py)?,))?;
                }
                Ok(Step::Done) => return Ok(true.into_pyobject(py)?.to_owned().into_any()),
                Ok(Step::Rest) => {
                    let text = file.as_ref().expect("read");
                    let (end, rest) = text.end();
                    let at = match end {
                        files::End::Eof => None,
                        files::End::Overflow { at } => Some(at),
                    };
                    return Ok((files::text(py, rest)?, at, line)
                        .into_pyobject(py)?
                        .into_any());
                }
            }
        }
    }

    /// The converted text of one `Block` (without its end of block).
    fn convert_block<'py>(
        &mut self,
        py: Python<'py>,
        block: &Bound<'py, Block>,
    ) -> PyResult<Bound<'py, PyString>> {
        {
            // a line the source control never reads (after a LinuxCNC program's end): as it is
            let b = block.borrow();
            if self.inner.not_read(b.line, &str_bytes(b.text.bind(py))?) {
                return Ok(b.text.bind(py).clone());
            }
        }
        if let Ok(bad) = block.downcast::<BadBlock>() {
            let error = bad.borrow().error.clone_ref(py);
            return Err(PyErr::from_value(error.into_bound(py)));
        }
        let b = block.borrow();
        let text = str_bytes(b.text.bind(py))?.into_owned();
        let mut owned: Vec<Vec<u8>> = Vec::new();
        for token in b.words.bind(py).iter() {
            owned.push(str_bytes(token.downcast::<PyString>()?)?.into_owned());
        }
        let mut words = Vec::with_capacity(owned.len());
        let mut pos = 0;
        for token in &owned {
            let start = find_token(&text, token, pos);
            words.push(WordSpan {
                token,
                start,
                end: token_span(&text, start, token),
                plain: None,
                digits: Default::default(),
            });
            pos = (start + 1).min(text.len());
        }
        let (mut plain, mut percent, mut skip) = (true, false, Vec::new());
        let mut skip_within: Option<(usize, Vec<u8>)> = None;
        let mut comment_texts: Vec<(usize, Vec<u8>)> = Vec::new();
        let mut statement_texts: Vec<(usize, StatementKind, Vec<u8>)> = Vec::new();
        if let Some(info) = &b.info {
            plain = false;
            let info = info.borrow(py);
            percent = info.percent;
            skip = str_bytes(info.skip.bind(py))?.into_owned();
            if let Some((col, mark)) = info
                .skip_within
                .extract::<Option<(usize, Bound<'_, PyString>)>>(py)?
            {
                skip_within = Some((offset_of(&text, col), str_bytes(&mark)?.into_owned()));
            }
            for entry in info.comments.bind(py).iter() {
                let (col, comment): (usize, Bound<'_, PyString>) = entry.extract()?;
                comment_texts.push((offset_of(&text, col), str_bytes(&comment)?.into_owned()));
            }
            for entry in info.statements.bind(py).iter() {
                let (col, statement, kind): (usize, Bound<'_, PyString>, String) =
                    entry.extract()?;
                let kind = StatementKind::from_name(&kind).unwrap_or(StatementKind::Command);
                statement_texts.push((
                    offset_of(&text, col),
                    kind,
                    str_bytes(&statement)?.into_owned(),
                ));
            }
        }
        let statements: Vec<(usize, StatementKind, &[u8])> = statement_texts
            .iter()
            .map(|(o, k, t)| (*o, *k, t.as_slice()))
            .collect();
        let comments: Vec<(usize, &[u8])> = comment_texts
            .iter()
            .map(|(o, t)| (*o, t.as_slice()))
            .collect();
        let input = BlockIn {
            line: b.line,
            text: &text,
            words: &words,
            plain,
            percent,
            skip: &skip,
            skip_within: skip_within
                .as_ref()
                .map(|(at, mark)| (*at, mark.as_slice())),
            comments: &comments,
            statements: &statements,
        };
        match self.inner.block(&input) {
            Ok(Some(new)) => py_text(py, &new),
            Ok(None) => Ok(b.text.bind(py).clone()),
            Err(e) => Err(conversion_error(py, &e, &self.file, b.line)),
        }
    }

    /// What only the end of the file shows (under a change of units, a LinuxCNC subroutine
    /// body no call of the file runs): raised as a `ConversionError`.
    fn end(&mut self, py: Python<'_>) -> PyResult<()> {
        self.inner
            .end()
            .map_err(|e| conversion_error(py, &e, &self.file, e.line.unwrap_or(0)))
    }

    /// The units each LinuxCNC subroutine body was read in under a change of units, as
    /// (label, "inch" or "metric"): `convert --verify` reads the source's bodies in them.
    fn body_units(&self) -> Vec<(String, &'static str)> {
        self.inner
            .body_units()
            .into_iter()
            .map(|(label, u)| (String::from_utf8_lossy(&label).into_owned(), u.name()))
            .collect()
    }

    /// The units of the first reads a refusal of clause `units-reread` learned, as (program,
    /// parameter, "inch" or "metric"): given back as the option `read_units` of the
    /// conversion made again (`formats.convert.Converter`).
    fn read_units_learned(&self) -> Vec<(usize, String, &'static str)> {
        self.inner
            .read_units_learned()
            .into_iter()
            .map(|(program, name, u)| (program, name, u.name()))
            .collect()
    }

    /// The notes made since the last call (or the start), in order; they are not kept, so a
    /// caller that takes them after each chunk holds none of a long program's.
    fn take_notes<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(py, self.inner.take_notes())
    }

    /// What the conversion did: blocks, words, changed words, the notes not yet taken, the
    /// largest rounding per address as `(letter, numerator, denominator)`, and what was left
    /// as written where the units change, as `(count, first line, first column)` (0, 0 for
    /// none): the words, statements and parameters (`left_as_written`, which make a proof
    /// "partly verified"; `left_statements` of them whole statements) and the lines the control never reads (`never_read`); and
    /// `machine_units`, the units a target that selects them by a machine parameter is to be
    /// set to ("inch", "metric" or None).
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("blocks", self.inner.blocks)?;
        d.set_item("words", self.inner.words)?;
        d.set_item("changed", self.inner.changed)?;
        let left = |l: tapegate_core::convert::Left| {
            let (line, column) = l.first.unwrap_or((0, 0));
            (l.count, line, column)
        };
        d.set_item("left_as_written", left(self.inner.left_as_written))?;
        d.set_item("left_statements", self.inner.left_as_written.statements)?;
        d.set_item("never_read", left(self.inner.never_read))?;
        d.set_item("machine_units", self.inner.machine_units.map(|u| u.name()))?;
        d.set_item("notes", PyList::new(py, &self.inner.notes)?)?;
        let rounding = PyList::empty(py);
        for &(letter, e, den) in &self.inner.worst {
            rounding.append(((letter as char).to_string(), e, den))?;
        }
        d.set_item("rounding", rounding)?;
        Ok(d)
    }
}

/// `formats._core.ParameterAnalysis`: which parameters of a program are lengths, the proof a
/// units conversion needs (`tapegate_core::lengths`), read from the program's text a chunk of
/// whole lines at a time, with no Python object per word.
#[pyclass(module = "formats._core")]
pub struct ParameterAnalysis {
    inner: tapegate_core::lengths::Analysis,
}

#[pymethods]
impl ParameterAnalysis {
    /// The analysis of a program written for `machine`.
    #[new]
    fn new(machine: &Machine) -> Self {
        ParameterAnalysis {
            inner: tapegate_core::lengths::Analysis::new(&machine.inner),
        }
    }

    /// Whole lines (`data` without its last LF) after line `line`. A line that cannot be read
    /// and holds a word that may read or set a parameter raises its located `ParseError`, as
    /// the parser would.
    fn read_lines(
        &mut self,
        py: Python<'_>,
        data: &Bound<'_, PyString>,
        line: usize,
        flags: crate::Flags,
        file: Option<PyObject>,
    ) -> PyResult<()> {
        let dialect = crate::dialect(flags);
        let bytes = str_bytes(data)?;
        // read with the GIL released (the threads of `tapegate convert -j`)
        let inner = &mut self.inner;
        py.allow_threads(|| inner.lines(&bytes, line, &dialect))
            .map_err(
                |(number, text, error)| match parse_error(py, &error, text, &file, number) {
                    Ok(exception) => PyErr::from_value(exception),
                    Err(err) => err,
                },
            )
    }

    /// The text file at `path`, read as `Converter.convert_file` reads it, with the GIL
    /// released: None when it is not plain text (nothing read), True when it was read to its
    /// end, or `(rest, at, line)`, the text after the last LF for Python to read (as
    /// `Converter.convert_file` gives it). A line that cannot be read raises as `read_lines`.
    fn read_file<'py>(
        &mut self,
        py: Python<'py>,
        path: std::path::PathBuf,
        flags: crate::Flags,
        file: Option<PyObject>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let dialect = crate::dialect(flags);
        let inner = &mut self.inner;
        let mut line = 0usize;
        let read = py.allow_threads(|| -> Result<Option<TextFile>, Failed> {
            let Some(mut text) = TextFile::open(&path)? else {
                return Ok(None);
            };
            while let Some(run) = text.next_lines()? {
                let run = &text.buffer()[run];
                if let Err((number, failed, error)) = inner.lines(run, line, &dialect) {
                    return Err(Failed::Line(
                        number,
                        failed.to_vec(),
                        LineError::Read(error),
                    ));
                }
                // (the LFs counted by memchr: the byte-by-byte count was about 5 instructions
                // a byte, 160 a block)
                line += memchr::memchr_iter(b'\n', run).count() + 1;
            }
            Ok(Some(text))
        });
        match read {
            Err(Failed::Io(e)) => Err(files::os_error(py, e)),
            Err(Failed::Line(number, text, error)) => {
                Err(line_error(py, &file, number, &text, error))
            }
            Ok(None) => Ok(py.None().into_bound(py)),
            Ok(Some(text)) => match text.end() {
                (files::End::Eof, []) => Ok(true.into_pyobject(py)?.to_owned().into_any()),
                (end, rest) => {
                    let at = match end {
                        files::End::Eof => None,
                        files::End::Overflow { at } => Some(at),
                    };
                    Ok((files::text(py, rest)?, at, line)
                        .into_pyobject(py)?
                        .into_any())
                }
            },
        }
    }

    /// The classes, for the converter (its option `parameters`) as they are, in the core.
    fn result(&self) -> ParameterClasses {
        ParameterClasses {
            inner: Arc::new(self.inner.result()),
        }
    }
}

/// `formats._core.ParameterClasses`: the outcome of a `ParameterAnalysis`, which the converter
/// takes as it is: the file's classes held once, not a list per program.
#[pyclass(module = "formats._core", frozen)]
pub struct ParameterClasses {
    inner: Arc<tapegate_core::convert::ParameterClasses>,
}

#[pymethods]
impl ParameterClasses {
    /// Program by program in the file's order: the line each begins on (0 for the first), its
    /// parameters proved lengths, and `(parameter, why it cannot be proved)`, each sorted.
    #[allow(clippy::type_complexity)]
    fn programs(&self) -> Vec<(usize, Vec<String>, Vec<(String, String)>)> {
        (0..self.inner.starts.len())
            .map(|program| {
                let (lengths, problems) = self.inner.lists(program);
                (self.inner.starts[program], lengths, problems)
            })
            .collect()
    }
}
