//! The check's text, JSON and JSON Lines findings written by the core (`tapegate_core::report`)
//! for `postproc.report` and `postproc.check`: a chunk's findings leave as one Python string.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyString, PyTuple};
use tapegate_core::report::{self, Fields, Format};

/// The format named `name` (`text`, `json`, `jsonl`), or a ValueError.
pub(crate) fn format(name: &str) -> PyResult<Format> {
    Format::from_name(name).ok_or_else(|| {
        PyValueError::new_err(format!("no report format '{name}': text, json or jsonl"))
    })
}

/// A Python string's UTF-16 code units, lone surrogates included.
pub(crate) fn units(text: &Bound<'_, PyString>) -> PyResult<Vec<u16>> {
    if let Ok(s) = text.to_str() {
        return Ok(s.encode_utf16().collect());
    }
    let encoded = text.call_method1("encode", ("utf-16-le", "surrogatepass"))?;
    let bytes = encoded.downcast_into::<PyBytes>()?;
    Ok(bytes
        .as_bytes()
        .chunks_exact(2)
        .map(|pair| u16::from_le_bytes([pair[0], pair[1]]))
        .collect())
}

/// A string field of a finding as `format` writes it.
fn field(format: Format, out: &mut Vec<u8>, text: &Bound<'_, PyAny>) -> PyResult<()> {
    let text = text.downcast::<PyString>()?;
    match text.to_str() {
        Ok(s) => format.field(out, s),
        Err(_) => format.field_units(out, &units(text)?),
    }
    Ok(())
}

/// What a writer wrote, as a Python string: UTF-8, or (a text report naming a file whose name
/// holds lone surrogates) UTF-8 with them as `surrogatepass` wrote them. JSON is ASCII.
pub(crate) fn string<'py>(
    py: Python<'py>,
    format: Format,
    written: &[u8],
) -> PyResult<Bound<'py, PyString>> {
    if format != Format::Text {
        debug_assert!(written.is_ascii());
        // SAFETY: a JSON writer escapes every byte outside printable ASCII (report::json_str,
        // json_units): what it wrote is ASCII, so UTF-8.
        return Ok(PyString::new(py, unsafe {
            std::str::from_utf8_unchecked(written)
        }));
    }
    match std::str::from_utf8(written) {
        Ok(s) => Ok(PyString::new(py, s)),
        Err(_) => Ok(PyBytes::new(py, written)
            .call_method1("decode", ("utf-8", "surrogatepass"))?
            .downcast_into::<PyString>()?),
    }
}

/// Append `findings`, `postproc.findings.Finding` tuples, to `out` in `format`; each one's
/// rule ID, severity, line, column and message are handed to `shown`, and it is written if it
/// answers true.
pub(crate) fn append_tuples(
    format: Format,
    out: &mut Vec<u8>,
    findings: &Bound<'_, PyAny>,
    mut shown: impl FnMut(&str, &str, usize, usize, &str) -> bool,
) -> PyResult<()> {
    let mut fields: [Vec<u8>; 5] = Default::default();
    for finding in findings.try_iter()? {
        let finding = finding?;
        let finding = finding.downcast::<PyTuple>()?;
        if finding.len() != 7 {
            return Err(PyValueError::new_err("a finding has 7 fields"));
        }
        for (slot, at) in fields.iter_mut().zip([0, 1, 3, 6, 2]) {
            slot.clear();
            field(format, slot, &finding.get_item(at)?)?;
        }
        let (line, column) = (
            finding.get_item(4)?.extract()?,
            finding.get_item(5)?.extract()?,
        );
        let (id, severity) = (finding.get_item(0)?, finding.get_item(1)?);
        let (id, severity) = (id.downcast::<PyString>()?, severity.downcast::<PyString>()?);
        let message = finding.get_item(2)?;
        let message = message.downcast::<PyString>()?.to_string_lossy();
        if !shown(id.to_str()?, severity.to_str()?, line, column, &message) {
            continue;
        }
        let [rule, severity, file, clause, message] = &fields;
        let row = Fields {
            rule,
            severity,
            file,
            line,
            column,
            clause,
        };
        report::write(format, out, &row, |out| out.extend_from_slice(message));
    }
    Ok(())
}

/// `findings` (`Finding` tuples) as the report `format` (`text`, `json`, `jsonl`) writes them:
/// text and JSON Lines a line each, JSON each object after a `,\n`.
#[pyfunction]
pub(crate) fn render_findings<'py>(
    py: Python<'py>,
    format: &str,
    findings: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyString>> {
    let format = self::format(format)?;
    let mut out = Vec::new();
    append_tuples(format, &mut out, findings, |_, _, _, _, _| true)?;
    string(py, format, &out)
}
