//! `formats._core.DiffReader`: one program read for the comparison of `formats.diff`.
//!
//! The profile arrives once, as a dict of plain values (`formats.diff._reader_config`); each
//! block arrives as its word tokens and leaves as one tuple per word, its exact values as text
//! that `decimal.Decimal` reads back exactly. No rule is decided here: they are
//! `tapegate_core::ncread`'s.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};
use tapegate_core::modal::ModalSettings;
use tapegate_core::ncread::{Factor, ReadSettings, ReadWord, Reader};
use tapegate_core::Family;

use crate::{item, str_bytes, units};

fn factor(f: Factor) -> u8 {
    match f {
        Factor::One => 0,
        Factor::Inch => 1,
        Factor::Foot => 2,
    }
}

fn settings(c: &Bound<'_, PyDict>) -> PyResult<ReadSettings> {
    let family: String = item(c, "family")?;
    Ok(ReadSettings {
        formats: crate::word_formats(item(c, "formats")?),
        formats_inch: item::<Option<Vec<crate::FormatEntry>>>(c, "formats_inch")?
            .map(crate::word_formats),
        explicit: item(c, "explicit")?,
        increments: item::<Option<String>>(c, "increments")?.map(String::into_bytes),
        pqr_length: item(c, "pqr_length")?,
        pqr_unstated: item(c, "pqr_unstated")?,
        family: Family::from_name(&family).unwrap_or_default(),
        lathe: item(c, "lathe")?,
        fanuc_lathe: item(c, "fanuc_lathe")?,
        modal: ModalSettings {
            reset: item(c, "reset")?,
            inch: item(c, "inch")?,
            metric: item(c, "metric")?,
            default_units: units(&item::<String>(c, "default_units")?),
            fanuc_lathe: item(c, "fanuc_lathe")?,
            g80_clears_motion: false,
            centre_codes: false,
            heidenhain: false,
            sinumerik_units: family == "sinumerik",
        },
    })
}

type ReadBlock<'py> = (Bound<'py, PyList>, bool, bool, bool, bool, bool);

#[pyclass(module = "formats._core", unsendable)]
pub struct DiffReader {
    inner: Reader,
    out: Vec<ReadWord>,
}

#[pymethods]
impl DiffReader {
    #[new]
    fn new(config: &Bound<'_, PyDict>) -> PyResult<Self> {
        Ok(DiffReader {
            inner: Reader::new(settings(config)?),
            out: Vec::new(),
        })
    }

    /// `(words, dwell, clamp, units_code, ended, resets)` of a block given by its word
    /// tokens; a word is `(key, kind, value, factor, step, incremental, parameter, as_length,
    /// error, per_revolution, form)`: factors 0 (one), 1 (25.4), 2 (0.3048), a form 1 for the
    /// inch format plus 2 for a cycle's least-increment count.
    fn read<'py>(&mut self, words: &Bound<'py, PyList>) -> PyResult<ReadBlock<'py>> {
        let py = words.py();
        let mut owned: Vec<Vec<u8>> = Vec::with_capacity(words.len());
        for token in words.iter() {
            owned.push(str_bytes(token.downcast::<PyString>()?)?.into_owned());
        }
        let tokens: Vec<&[u8]> = owned.iter().map(Vec::as_slice).collect();
        let flags = self.inner.read(&tokens, &mut self.out);
        let list = PyList::empty(py);
        for (w, token) in self.out.iter().zip(&tokens) {
            let mut key = String::with_capacity(1 + w.index_len);
            key.push(w.letter as char);
            key.push_str(std::str::from_utf8(&token[1..1 + w.index_len]).unwrap_or(""));
            let form = w
                .form
                .map(|f| u8::from(f.inch) + 2 * u8::from(f.cycle_increments));
            list.append((
                key,
                w.kind.name(),
                w.value.map(|v| v.to_string()),
                factor(w.factor),
                w.step.to_string(),
                w.incremental,
                w.parameter,
                w.as_length.map(factor),
                w.error.as_deref(),
                w.per_revolution,
                form,
            ))?;
        }
        Ok((
            list,
            flags.dwell,
            flags.clamp,
            flags.units_code,
            flags.ended,
            flags.resets,
        ))
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

    /// The distance mode read here (a test makes it drift from the core's on purpose).
    #[getter]
    fn incremental(&self) -> bool {
        self.inner.incremental
    }

    #[setter]
    fn set_incremental(&mut self, incremental: bool) {
        self.inner.incremental = incremental;
    }
}
