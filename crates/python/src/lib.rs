//! `formats._core`: tapegate-core seen from Python.
//!
//! This module only turns the core's results into Python objects: the lossless program model of
//! `formats.model` (`Block`, `BlockInfo`, `BadBlock`) and located `formats.errors.ParseError`s.
//! No rule is decided here. Text crosses as UTF-8 with every undecodable byte kept as Python's
//! `surrogateescape` keeps it, so the bytes of a file come back out exactly.

use std::borrow::Cow;
use std::ffi::c_char;

mod checker;
mod commits;
mod converter;
mod diff;
mod files;
mod machine;
mod report;
mod restart;

use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyBytes, PyDict, PyList, PyString, PyTuple, PyType};
use tapegate_core::check::Word;
use tapegate_core::rules::Rule;
use tapegate_core::text::column;
use tapegate_core::wordformat::{WordFormat, Zeros};
use tapegate_core::{tokenize, Dialect, Extras, Family, LexError, Token};

/// A Python str from bytes that are UTF-8 except for bytes kept by `surrogateescape`.
pub(crate) fn py_text<'py>(py: Python<'py>, bytes: &[u8]) -> PyResult<Bound<'py, PyString>> {
    if bytes.is_ascii() {
        return Ok(ascii(py, bytes));
    }
    if let Ok(text) = std::str::from_utf8(bytes) {
        return Ok(PyString::new(py, text));
    }
    // SAFETY: the pointer and length describe `bytes`, alive for the call; the error handler
    // name is a NUL-terminated literal. A NULL result is turned into the raised exception.
    unsafe {
        let ptr = pyo3::ffi::PyUnicode_DecodeUTF8(
            bytes.as_ptr() as *const c_char,
            bytes.len() as pyo3::ffi::Py_ssize_t,
            c"surrogateescape".as_ptr(),
        );
        Bound::from_owned_ptr_or_err(py, ptr).map(|o| o.downcast_into_unchecked())
    }
}

/// A word token as a Python str: tokens are ASCII, anything else ends the block with an error.
/// Python's cycle collector paused while it lives, then restored to what it was.
struct GcPause {
    was_enabled: bool,
}

impl GcPause {
    fn new() -> GcPause {
        // SAFETY: called with the GIL held (from a #[pyfunction]); PyGC_Disable only sets the
        // collector's flag and returns whether it was enabled.
        let was_enabled = unsafe { pyo3::ffi::PyGC_Disable() } != 0;
        GcPause { was_enabled }
    }
}

impl Drop for GcPause {
    fn drop(&mut self) {
        if self.was_enabled {
            // SAFETY: as in `new`, with the GIL still held by the same call.
            unsafe { pyo3::ffi::PyGC_Enable() };
        }
    }
}

pub(crate) fn ascii<'py>(py: Python<'py>, token: &[u8]) -> Bound<'py, PyString> {
    // A word token is ASCII; anything else is read as UTF-8 with its bad bytes dropped. The
    // stable ABI (abi3, the wheel) has no writable string data, so the string is made by
    // `PyUnicode_FromStringAndSize`, whose UTF-8 decoder copies an ASCII run a word at a time.
    match std::str::from_utf8(token) {
        Ok(text) => PyString::new(py, text),
        Err(_) => PyString::new(py, ""),
    }
}

/// A key of a dict the Python side builds (`formats.machine.machine_spec`, the converter's and
/// the comparison's options); a missing key names itself.
pub(crate) fn item<'py, T: FromPyObject<'py>>(
    config: &Bound<'py, PyDict>,
    key: &str,
) -> PyResult<T> {
    match config.get_item(key)? {
        Some(value) => value.extract(),
        None => Err(PyValueError::new_err(format!(
            "core configuration without {key:?}"
        ))),
    }
}

/// `"inch"` or `"metric"`.
pub(crate) fn units(name: &str) -> tapegate_core::modal::Units {
    use tapegate_core::modal::Units;
    if name == "inch" {
        Units::Inch
    } else {
        Units::Metric
    }
}

/// What the tokenizer is told, from `formats.parser.Dialect.flags`.
pub(crate) fn dialect(flags: Flags) -> Dialect {
    let (lowercase, hash, brackets, semicolon, star, expressions, family) = flags;
    Dialect {
        family: Family::from_name(&family).unwrap_or_default(),
        lowercase,
        hash,
        brackets,
        semicolon,
        star,
        expressions,
        ngc: family == "haas",
    }
}

/// A profile's word formats as the Python side hands them over:
/// `(address, before, after, signed, zeros, decimal)`.
pub(crate) type FormatEntry = (String, u32, u32, bool, String, bool);

pub(crate) fn word_formats(entries: Vec<FormatEntry>) -> Vec<(u8, WordFormat)> {
    entries
        .into_iter()
        .map(|(address, before, after, signed, zeros, decimal)| {
            let zeros = match zeros.as_str() {
                "trailing" => Zeros::Trailing,
                "none" => Zeros::None,
                _ => Zeros::Leading,
            };
            let a = address.as_bytes().first().copied().unwrap_or(b'?');
            (
                a,
                WordFormat {
                    address: a,
                    before,
                    after,
                    signed,
                    zeros,
                    decimal,
                },
            )
        })
        .collect()
}

/// The bytes of a Python str, as the file held them.
pub(crate) fn str_bytes<'a>(text: &'a Bound<'_, PyString>) -> PyResult<Cow<'a, [u8]>> {
    if let Ok(s) = text.to_str() {
        return Ok(Cow::Borrowed(s.as_bytes()));
    }
    let encoded = text.call_method1("encode", ("utf-8", "surrogateescape"))?;
    Ok(Cow::Owned(
        encoded.downcast_into::<PyBytes>()?.as_bytes().to_vec(),
    ))
}

/// What the careful tokenizer found beside the words of a block.
#[pyclass(module = "formats.model", get_all, set_all)]
pub struct BlockInfo {
    /// `""`, `"/"` or `"/1"`..`"/9"`: optional block skip (clause 4).
    skip: Py<PyString>,
    /// `(column, "/" or "/n")` of a block skip in the middle of the block (Fanuc, Haas: the
    /// switch on skips from it to the end of the block), or None.
    skip_within: PyObject,
    /// `[(column, text with its brackets), ...]`.
    comments: Py<PyList>,
    /// A `%` program start / rewind stop line.
    percent: bool,
    /// The text after `%` (program identification, clause 4).
    ident: Py<PyString>,
    /// False for a last line that has no end of block.
    eob: bool,
    /// `[(column, text, kind), ...]`: the dialect's statements (`IF [..] GOTO 10`, `o100 sub`),
    /// kind one of flow, call, definition, declaration, assignment, message, command, label,
    /// name.
    statements: Py<PyList>,
}

#[pymethods]
impl BlockInfo {
    #[new]
    fn new(py: Python<'_>) -> Self {
        BlockInfo {
            skip: PyString::new(py, "").unbind(),
            skip_within: py.None(),
            comments: PyList::empty(py).unbind(),
            percent: false,
            ident: PyString::new(py, "").unbind(),
            eob: true,
            statements: PyList::empty(py).unbind(),
        }
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "BlockInfo(skip={}, skip_within={}, comments={}, percent={}, ident={}, eob={}, \
             statements={})",
            self.skip.bind(py).repr()?,
            self.skip_within.bind(py).repr()?,
            self.comments.bind(py).repr()?,
            if self.percent { "True" } else { "False" },
            self.ident.bind(py).repr()?,
            if self.eob { "True" } else { "False" },
            self.statements.bind(py).repr()?,
        ))
    }
}

/// One block: its text as written, its line, its word tokens, and what else it holds.
#[pyclass(module = "formats.model", subclass, get_all, set_all)]
pub struct Block {
    /// Everything between two LFs, as written (CR, blanks, comments, leader included).
    text: Py<PyString>,
    /// 1-based line number in the file.
    line: usize,
    /// The word tokens in written order, without the blanks inside them.
    words: Py<PyList>,
    /// The extras (skip, comments, `%`, no end of block), or None for a plain block.
    info: Option<Py<BlockInfo>>,
}

static WORD: GILOnceCell<Py<PyType>> = GILOnceCell::new();
static PARSE_ERROR: GILOnceCell<Py<PyType>> = GILOnceCell::new();

pub(crate) fn python_class<'py>(
    py: Python<'py>,
    cell: &'static GILOnceCell<Py<PyType>>,
    module: &str,
    name: &str,
) -> PyResult<&'py Bound<'py, PyType>> {
    cell.import(py, module, name)
}

#[pymethods]
impl Block {
    #[new]
    #[pyo3(signature = (text, line, words, info=None))]
    fn new(
        text: Bound<'_, PyString>,
        line: usize,
        words: Bound<'_, PyList>,
        info: Option<Py<BlockInfo>>,
    ) -> Self {
        Block {
            text: text.unbind(),
            line,
            words: words.unbind(),
            info,
        }
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "Block(line={}, text={})",
            self.line,
            self.text.bind(py).repr()?
        ))
    }

    /// `""`, `"/"` or `"/n"`.
    #[getter]
    fn skip(&self, py: Python<'_>) -> Py<PyString> {
        match &self.info {
            Some(info) => info.borrow(py).skip.clone_ref(py),
            None => PyString::new(py, "").unbind(),
        }
    }

    /// `(column, "/" or "/n")` of a block skip in the middle of the block, or None.
    #[getter]
    fn skip_within(&self, py: Python<'_>) -> PyObject {
        match &self.info {
            Some(info) => info.borrow(py).skip_within.clone_ref(py),
            None => py.None(),
        }
    }

    /// `[(column, text), ...]`; a new empty list for a plain block.
    #[getter]
    fn comments(&self, py: Python<'_>) -> Py<PyList> {
        match &self.info {
            Some(info) => info.borrow(py).comments.clone_ref(py),
            None => PyList::empty(py).unbind(),
        }
    }

    /// `[(column, text, kind), ...]`: the dialect's statements; a new empty list for a plain
    /// block.
    #[getter]
    fn statements(&self, py: Python<'_>) -> Py<PyList> {
        match &self.info {
            Some(info) => info.borrow(py).statements.clone_ref(py),
            None => PyList::empty(py).unbind(),
        }
    }

    #[getter]
    fn percent(&self, py: Python<'_>) -> bool {
        self.info
            .as_ref()
            .is_some_and(|info| info.borrow(py).percent)
    }

    #[getter]
    fn has_eob(&self, py: Python<'_>) -> bool {
        self.info.as_ref().is_none_or(|info| info.borrow(py).eob)
    }

    /// The words as `formats.model.Word` objects, with their 1-based columns in the line.
    fn word_objects<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let word = python_class(py, &WORD, "formats.model", "Word")?;
        let text = self.text.bind(py);
        let bytes = str_bytes(text)?;
        let result = PyList::empty(py);
        let mut pos = 0;
        for token in self.words.bind(py).iter() {
            let token = token.downcast_into::<PyString>()?;
            let token_bytes = str_bytes(&token)?;
            let at = find_token(&bytes, &token_bytes, pos);
            let parts = Word::new(&token_bytes, 0);
            let args = (
                py_text(py, &token_bytes[..1.min(token_bytes.len())])?,
                py_text(py, parts.index)?,
                py_text(py, parts.sign)?,
                py_text(py, parts.number)?,
                py_text(py, parts.expression)?,
                column(&bytes, at),
                token,
            );
            result.append(word.call1(args)?)?;
            pos = (at + 1).min(bytes.len());
        }
        Ok(result)
    }
}

/// A block the parser could not read, kept (text and position) when errors are collected.
#[pyclass(module = "formats.parser", extends = Block, get_all, set_all)]
pub struct BadBlock {
    /// The located `formats.errors.ParseError`.
    error: PyObject,
}

#[pymethods]
impl BadBlock {
    #[new]
    fn new(text: Bound<'_, PyString>, line: usize, error: PyObject) -> (Self, Block) {
        let py = text.py();
        let words = PyList::empty(py).unbind();
        (
            BadBlock { error },
            Block {
                text: text.unbind(),
                line,
                words,
                info: None,
            },
        )
    }
}

/// The offset of `token` in `text` from `start`, where a word with blanks inside or after a
/// comment holding the same characters may stand.
pub(crate) fn find_token(text: &[u8], token: &[u8], start: usize) -> usize {
    let found = find(text, token, start);
    if let Some(at) = found {
        if !inside_comment(text, at) {
            return at;
        }
    }
    let Some(&first) = token.first() else {
        return found.unwrap_or(0);
    };
    let mut in_comment = false;
    for (i, &c) in text.iter().enumerate().skip(start) {
        if in_comment {
            in_comment = c != b')';
        } else if c == b'(' {
            in_comment = true;
        } else if c == b';' {
            break;
        } else if c == first {
            return i;
        }
    }
    found.unwrap_or(0)
}

fn find(text: &[u8], token: &[u8], start: usize) -> Option<usize> {
    if token.is_empty() || start > text.len() {
        return None;
    }
    text[start..]
        .windows(token.len())
        .position(|w| w == token)
        .map(|i| i + start)
}

fn inside_comment(text: &[u8], at: usize) -> bool {
    match text[..at].iter().rposition(|&c| c == b'(') {
        Some(open) => !text[open..at].contains(&b')'),
        None => false,
    }
}

/// One word format from its Python tuple (`FormatEntry`).
fn one_format(entry: FormatEntry) -> WordFormat {
    let (_, format) = word_formats(vec![entry])
        .pop()
        .expect("one entry, one format");
    format
}

/// The value of a word's unsigned digits `number` under `format` (Annex C, as
/// `WordFormat::read` reads it), as `str(Decimal)` writes it; `ValueError` with the reason
/// where the digits have none. For `formats.wordformat.WordFormat.read`.
#[pyfunction]
fn read_number(
    format: FormatEntry,
    number: &str,
    explicit: bool,
    increments: bool,
) -> PyResult<String> {
    one_format(format)
        .read(false, number.as_bytes(), explicit, increments)
        .map(|value| value.to_string())
        .map_err(PyValueError::new_err)
}

/// The digits (with sign) after the address of the value `units * 10^-after` under `format`,
/// as the converter writes them (`convert::write`). For `formats.wordformat.WordFormat.write`.
#[pyfunction]
fn write_number(
    format: FormatEntry,
    units: i128,
    after: u32,
    explicit: bool,
    plus: bool,
) -> String {
    tapegate_core::wordformat::write(units, after, &one_format(format), explicit, plus)
}

/// `(address, index, sign, number, expression)` of a word token.
#[pyfunction]
fn split_token<'py>(token: &Bound<'py, PyString>) -> PyResult<Bound<'py, PyTuple>> {
    let py = token.py();
    let bytes = str_bytes(token)?;
    if bytes.is_empty() {
        return Err(PyValueError::new_err("an empty word token"));
    }
    let w = Word::new(&bytes, 0);
    PyTuple::new(
        py,
        [
            py_text(py, &bytes[..1])?,
            py_text(py, w.index)?,
            py_text(py, w.sign)?,
            py_text(py, w.number)?,
            py_text(py, w.expression)?,
        ],
    )
}

pub(crate) fn parse_error<'py>(
    py: Python<'py>,
    error: &LexError,
    bytes: &[u8],
    file: &Option<PyObject>,
    line: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let class = python_class(py, &PARSE_ERROR, "formats.errors", "ParseError")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("file", file)?;
    kwargs.set_item("line", line)?;
    kwargs.set_item("column", column(bytes, error.offset))?;
    kwargs.set_item("clause", error.clause)?;
    kwargs.set_item("code", error.kind.rule().id())?;
    class.call((&error.message,), Some(&kwargs))
}

fn info<'py>(py: Python<'py>, line: &[u8], extras: Extras<'_>) -> PyResult<Py<BlockInfo>> {
    let skip = match extras.skip {
        0 => String::new(),
        b'/' => "/".to_string(),
        level => format!("/{}", level as char),
    };
    let skip_within = match extras.skip_within {
        Some((offset, level)) => {
            let text = &line[offset..offset + usize::from(level != b'/') + 1];
            (column(line, offset), py_text(py, text)?)
                .into_pyobject(py)?
                .into_any()
                .unbind()
        }
        None => py.None(),
    };
    let comments = PyList::empty(py);
    for (offset, text) in extras.comments {
        comments.append((column(line, offset), py_text(py, text)?))?;
    }
    let statements = PyList::empty(py);
    for s in extras.statements {
        let text = py_text(py, &line[s.offset..s.end])?;
        statements.append((column(line, s.offset), text, s.kind.name()))?;
    }
    Py::new(
        py,
        BlockInfo {
            skip: PyString::new(py, &skip).unbind(),
            skip_within,
            comments: comments.unbind(),
            percent: extras.percent,
            ident: py_text(py, extras.ident)?.unbind(),
            eob: true,
            statements: statements.unbind(),
        },
    )
}

/// What the tokenizer is told: lower case, `#`, `[ ]`, `;`, `*`, expressions.
pub(crate) type Flags = (bool, bool, bool, bool, bool, bool, String);

/// `formats._core.ReadingEnd`: where a program's reading ends (the core's
/// `dialect::ReadingEnd`: the lines after a LinuxCNC program's end), carried from one chunk
/// of [`parse_lines`] to the next.
#[pyclass(module = "formats._core")]
pub struct ReadingEnd {
    inner: tapegate_core::dialect::ReadingEnd,
}

#[pymethods]
impl ReadingEnd {
    /// The reading of a program of the dialect family `family` (`linuxcnc`, `fanuc`...).
    #[new]
    fn new(family: &str) -> Self {
        ReadingEnd {
            inner: tapegate_core::dialect::ReadingEnd::new(
                Family::from_name(family).unwrap_or_default(),
            ),
        }
    }
}

/// The blocks of `data` (whole lines, without the last LF) after line `line`.
///
/// Returns `(blocks, error)`: with `collect`, a block that cannot be read is a `BadBlock` and
/// `error` is None; without it, the blocks before the first such block and its located
/// `ParseError`, for the caller to raise after yielding them. With `end` (the reading of the
/// lines before), a line the control never reads is a block of its text alone, no word read.
#[pyfunction]
#[pyo3(signature = (data, line, flags, file, collect, end=None))]
fn parse_lines<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyString>,
    line: usize,
    flags: Flags,
    file: Option<PyObject>,
    collect: bool,
    end: Option<&Bound<'py, ReadingEnd>>,
) -> PyResult<(Bound<'py, PyList>, Option<Bound<'py, PyAny>>)> {
    let dialect = dialect(flags);
    let bytes = str_bytes(data)?;
    let mut end = end.map(|e| e.borrow_mut());
    // The blocks of a chunk are tens of thousands of new containers that hold no cycle: the
    // cycle collector, which would run over them every 700 allocations, is paused for the
    // chunk and restored as it was (as deserialisers of large documents do).
    let _paused = GcPause::new();
    let blocks = PyList::empty(py);
    let mut words: Vec<Token<'_>> = Vec::with_capacity(16);
    for (number, text) in (line + 1..).zip(tapegate_core::text::lines(&bytes)) {
        words.clear();
        if let Some(end) = end.as_mut() {
            if end.inner.skips(number, text) {
                let block = Block {
                    text: py_text(py, text)?.unbind(),
                    line: number,
                    words: PyList::empty(py).unbind(),
                    info: None,
                };
                blocks.append(Py::new(py, block)?)?;
                continue;
            }
        }
        match tokenize(text, &dialect, &mut words) {
            Ok(extras) => {
                if let Some(end) = end.as_mut() {
                    tapegate_core::tokenizer::note_reading_end(
                        &mut end.inner,
                        &words,
                        &extras,
                        text,
                        number,
                    );
                }
                // Tokens are ASCII: anything else ends the block with an error. (The list is
                // made at its size: no append growing it.)
                let tokens = PyList::new(py, words.iter().map(|w| ascii(py, &w.text)))?;
                let info = match extras {
                    Some(extras) => Some(info(py, text, extras)?),
                    None => None,
                };
                let block = Block {
                    text: py_text(py, text)?.unbind(),
                    line: number,
                    words: tokens.unbind(),
                    info,
                };
                blocks.append(Py::new(py, block)?)?;
            }
            Err(mut error) => {
                if let Some(note) = end.as_ref().and_then(|e| e.inner.unsure_note()) {
                    error.message.push_str(&note);
                }
                let exception = parse_error(py, &error, text, &file, number)?;
                if !collect {
                    return Ok((blocks, Some(exception)));
                }
                let bad = BadBlock::new(py_text(py, text)?, number, exception.unbind());
                blocks.append(Bound::new(py, bad)?)?;
            }
        }
    }
    Ok((blocks, None))
}

/// `(words, info, error)`: a block's tokens, its extras, and why it cannot be read.
type TokenizedBlock<'py> = (
    Bound<'py, PyList>,
    Option<Py<BlockInfo>>,
    Option<Bound<'py, PyAny>>,
);

/// `(words, info, error)` of one block's text: the careful tokenizer on its own.
#[pyfunction]
fn tokenize_block<'py>(
    py: Python<'py>,
    text: &Bound<'py, PyString>,
    flags: Flags,
) -> PyResult<TokenizedBlock<'py>> {
    let dialect = dialect(flags);
    let bytes = str_bytes(text)?;
    let mut words = Vec::new();
    let result = tokenize(&bytes, &dialect, &mut words);
    let tokens = PyList::empty(py);
    for w in &words {
        tokens.append(ascii(py, &w.text))?;
    }
    match result {
        Ok(extras) => {
            let info = match extras {
                Some(extras) => info(py, &bytes, extras)?,
                None => Py::new(py, BlockInfo::new(py))?,
            };
            Ok((tokens, Some(info), None))
        }
        Err(error) => Ok((
            tokens,
            None,
            Some(parse_error(py, &error, &bytes, &None, 0)?),
        )),
    }
}

/// Whether a control of the dialect accepts `ch` (one character), in a comment or outside one:
/// the one table the checker reads by and the emulator's TH check rejects by.
#[pyfunction]
fn character_allowed(ch: char, in_comment: bool, flags: Flags) -> bool {
    tapegate_core::character_allowed(ch, in_comment, &dialect(flags))
}

/// Whether a FANUC program's name, `<NAME>`, may hold `ch` (one character): the characters
/// the statement reader takes between `<` and `>`, which the emulator's TH check takes there.
#[pyfunction]
fn program_name_character(ch: char) -> bool {
    u8::try_from(ch).is_ok_and(tapegate_core::statement::program_name_character)
}

/// The number of ends of line (LF) in `text`: how many lines a chunk of whole lines holds.
#[pyfunction]
fn line_ends(text: &Bound<'_, PyString>) -> PyResult<usize> {
    Ok(tapegate_core::text::line_ends(&str_bytes(text)?))
}

/// `(blocks, words, comments)` of whole lines, or the located `ParseError` of the first block
/// that cannot be read: the counts of `tapegate parse --summary`, without a Python object per
/// block. With `end`, as [`parse_lines`]: a line the control never reads is a block alone.
#[pyfunction]
#[pyo3(signature = (data, line, flags, file, end=None))]
fn count_lines(
    py: Python<'_>,
    data: &Bound<'_, PyString>,
    line: usize,
    flags: Flags,
    file: Option<PyObject>,
    end: Option<&Bound<'_, ReadingEnd>>,
) -> PyResult<(usize, usize, usize)> {
    let dialect = dialect(flags);
    let bytes = str_bytes(data)?;
    let mut end = end.map(|e| e.borrow_mut());
    let mut words: Vec<Token<'_>> = Vec::with_capacity(16);
    let (mut blocks, mut total, mut comments) = (0, 0, 0);
    for (number, text) in (line + 1..).zip(tapegate_core::text::lines(&bytes)) {
        words.clear();
        if let Some(end) = end.as_mut() {
            if end.inner.skips(number, text) {
                blocks += 1;
                continue;
            }
        }
        match tokenize(text, &dialect, &mut words) {
            Ok(extras) => {
                if let Some(end) = end.as_mut() {
                    tapegate_core::tokenizer::note_reading_end(
                        &mut end.inner,
                        &words,
                        &extras,
                        text,
                        number,
                    );
                }
                blocks += 1;
                total += words.len();
                comments += extras.map_or(0, |e| e.comments.len());
            }
            Err(mut error) => {
                if let Some(note) = end.as_ref().and_then(|e| e.inner.unsure_note()) {
                    error.message.push_str(&note);
                }
                return Err(PyErr::from_value(parse_error(
                    py, &error, text, &file, number,
                )?));
            }
        }
    }
    Ok((blocks, total, comments))
}

fn expression_tree(text: &str) -> PyResult<tapegate_core::expr::Expr> {
    tapegate_core::expr::tree(text.as_bytes())
        .map_err(|e| PyValueError::new_err(format!("malformed expression {text:?}: {}", e.message)))
}

/// The parameters an expression reads, in order (`"105 + R9"` reads `["R9"]`); with
/// `formula`, the right-hand side of a HEIDENHAIN Q-parameter formula (`"SQ (Q1 + 2)"`).
#[pyfunction]
#[pyo3(signature = (text, formula = false))]
fn expression_parameters(text: &str, formula: bool) -> PyResult<Vec<String>> {
    let mut spans = Vec::new();
    let tree = if formula {
        tapegate_core::expr::formula_tree(text.as_bytes(), 0).map_err(|e| {
            PyValueError::new_err(format!("malformed formula {text:?}: {}", e.message))
        })?
    } else {
        expression_tree(text)?
    };
    tapegate_core::expr::parameters(&tree, &mut spans);
    Ok(spans.iter().map(|&(a, b)| text[a..b].to_string()).collect())
}

/// A Sinumerik expression's tree in its canonical form (`"(+ R1 (* 2 3))"`), as
/// `formats.expr.sinumerik_form` prints the lark reference grammar's: the property tests
/// compare the two.
#[pyfunction]
fn sinumerik_form(text: &str) -> PyResult<String> {
    let tree = tapegate_core::expr::sinumerik_tree(text.as_bytes()).map_err(|e| {
        PyValueError::new_err(format!("malformed expression {text:?}: {}", e.message))
    })?;
    Ok(tapegate_core::expr::sinumerik_form(&tree, text.as_bytes()))
}

/// The rule registry (`crates/core/src/rules.rs`), in the catalogue's order: for each rule its
/// variant's name, ID, severity, clause, title, family, and whether it means a block could not
/// be read.
#[pyfunction]
#[allow(clippy::type_complexity)]
fn rules() -> Vec<(
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    bool,
)> {
    Rule::ALL
        .iter()
        .map(|r| {
            (
                r.name(),
                r.id(),
                r.severity().name(),
                r.clause(),
                r.title(),
                r.family().name(),
                r.reading(),
            )
        })
        .collect()
}

/// The ID of the rule whose variant is `name` (`"Unreadable"` -> `"TG100"`).
#[pyfunction]
fn rule_id(name: &str) -> PyResult<&'static str> {
    Rule::ALL
        .iter()
        .find(|r| r.name() == name)
        .map(|r| r.id())
        .ok_or_else(|| PyKeyError::new_err(name.to_string()))
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<checker::Checker>()?;
    m.add_class::<checker::ModalMachine>()?;
    m.add_class::<machine::Machine>()?;
    m.add_class::<restart::RestartWalk>()?;
    m.add_class::<converter::Converter>()?;
    m.add_class::<commits::Commits>()?;
    m.add_class::<converter::ParameterAnalysis>()?;
    m.add_class::<converter::ParameterClasses>()?;
    m.add_class::<diff::DiffReader>()?;
    m.add_class::<diff::DiffBlock>()?;
    m.add_class::<diff::DiffComparer>()?;
    m.add_class::<diff::DiffAligner>()?;
    m.add_class::<Block>()?;
    m.add_class::<BlockInfo>()?;
    m.add_class::<BadBlock>()?;
    m.add_class::<ReadingEnd>()?;
    m.add_function(wrap_pyfunction!(parse_lines, m)?)?;
    m.add_function(wrap_pyfunction!(files::has_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(commits::pending_file, m)?)?;
    m.add_function(wrap_pyfunction!(commits::commit_file, m)?)?;
    m.add_function(wrap_pyfunction!(commits::discard_file, m)?)?;
    m.add_function(wrap_pyfunction!(commits::sweep_pending, m)?)?;
    m.add_function(wrap_pyfunction!(report::render_findings, m)?)?;
    m.add_function(wrap_pyfunction!(rules, m)?)?;
    m.add_function(wrap_pyfunction!(rule_id, m)?)?;
    m.add_function(wrap_pyfunction!(restart::find_numbered, m)?)?;
    m.add_function(wrap_pyfunction!(tokenize_block, m)?)?;
    m.add_function(wrap_pyfunction!(split_token, m)?)?;
    m.add_function(wrap_pyfunction!(read_number, m)?)?;
    m.add_function(wrap_pyfunction!(write_number, m)?)?;
    m.add_function(wrap_pyfunction!(expression_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(count_lines, m)?)?;
    m.add_function(wrap_pyfunction!(line_ends, m)?)?;
    m.add_function(wrap_pyfunction!(character_allowed, m)?)?;
    m.add_function(wrap_pyfunction!(program_name_character, m)?)?;
    m.add_function(wrap_pyfunction!(sinumerik_form, m)?)?;
    m.add("MAX_BLOCK", tapegate_core::MAX_BLOCK)?;
    m.add("TURNING_KEYS", tapegate_core::check::TURNING_KEYS.to_vec())?;
    Ok(())
}
