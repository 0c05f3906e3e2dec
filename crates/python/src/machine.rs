//! `formats._core.Machine`: a profile compiled once (`tapegate_core::machine`).
//!
//! The spec arrives from `formats.machine.machine_spec` as a dict of plain values (the
//! `MachineSpec` TypedDict of `formats/_core.pyi`); this is the one place it is read. Every
//! core object that reads programs for a machine (`Checker`, `ModalMachine`, `RestartWalk`,
//! `DiffReader`, `Converter`) takes the `Machine`, which is immutable and shared.

use std::sync::Arc;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use tapegate_core::check::{code_number, Code, CodeWord, Ijk, ProfileFacts, Role, Status};
use tapegate_core::decimal::Dec;
use tapegate_core::dialect::PastFormat;
use tapegate_core::machine::{self, MachineSpec};
use tapegate_core::restart::Control;
use tapegate_core::wordformat::WordFormat;

use crate::{item, units, word_formats, FormatEntry};

fn dec(text: Option<String>) -> PyResult<Option<Dec>> {
    text.map(|t| Dec::parse(&t).ok_or_else(|| PyValueError::new_err(format!("not a number: {t}"))))
        .transpose()
}

fn code(status: &str, duration: String) -> PyResult<Code> {
    let status = match status {
        "assigned" => Status::Assigned,
        "conditional" => Status::Conditional,
        "unassigned" => Status::Unassigned,
        "permanent" => Status::Permanent,
        other => return Err(PyValueError::new_err(format!("status {other:?}"))),
    };
    Ok(Code { status, duration })
}

fn codes(entries: Vec<Option<(String, String)>>) -> PyResult<Vec<Option<Code>>> {
    entries
        .into_iter()
        .map(|entry| {
            entry
                .map(|(status, duration)| code(&status, duration))
                .transpose()
        })
        .collect()
}

/// `code_words`: (code, letter, address) as `("G71", "P", "N")`.
fn code_words(entries: Vec<(String, String, String)>) -> PyResult<Vec<CodeWord>> {
    entries
        .into_iter()
        .map(|(code, word, address)| {
            let number = code
                .get(1..)
                .filter(|n| Dec::parse(n).is_some())
                .ok_or_else(|| PyValueError::new_err(format!("code {code:?}")))?;
            Ok(CodeWord {
                code: (letter(&code), code_number(number.as_bytes()).to_vec()),
                letter: letter(&word),
                address: letter(&address),
            })
        })
        .collect()
}

fn letter(text: &str) -> u8 {
    text.as_bytes().first().copied().unwrap_or(b'?')
}

/// `checks.pqr`'s role of a letter: `"length"`, `"parameter"`, `"other"`, or None (unstated).
fn role(name: Option<String>) -> Option<Role> {
    name.map(|name| match name.as_str() {
        "length" => Role::Length,
        "parameter" => Role::Parameter,
        _ => Role::Other,
    })
}

/// `checks.unknown_g` / `unknown_m`: "alarm", "warn", or None (the family decides).
fn alarms(policy: Option<String>) -> Option<bool> {
    policy.map(|p| p == "alarm")
}

/// `checks.past_decimals` / `past_sequence`: "alarm", "round", "unknown" or "any" (decimals
/// also "round_computed").
fn past_format(name: &str) -> PyResult<PastFormat> {
    PastFormat::from_name(name)
        .ok_or_else(|| PyValueError::new_err(format!("unknown checks.past_* value {name:?}")))
}

fn spec(c: &Bound<'_, PyDict>) -> PyResult<MachineSpec> {
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
    let g_decimal = item::<Vec<(String, String, String)>>(c, "g_decimal")?
        .into_iter()
        .map(|(number, status, duration)| Ok((number, code(&status, duration)?)))
        .collect::<PyResult<Vec<_>>>()?;
    let pqr: (Option<String>, Option<String>, Option<String>) = item(c, "pqr")?;
    let program_number: String = item(c, "program_number")?;
    Ok(MachineSpec {
        facts: ProfileFacts {
            formats: word_formats(item(c, "formats")?),
            formats_inch: item::<Option<Vec<FormatEntry>>>(c, "formats_inch")?.map(word_formats),
            feed_rev_formats: [
                feed_format(word_formats(item(c, "feed_rev_formats")?)),
                feed_format(word_formats(item(c, "feed_rev_formats_inch")?)),
            ],
            explicit: item(c, "explicit")?,
            increments: item::<Option<String>>(c, "increments")?.map(String::into_bytes),
            alignment: item(c, "alignment")?,
            percent: item(c, "percent")?,
            classification: item(c, "classification")?,
            table_name: item(c, "table_name")?,
            g_codes: codes(item(c, "g_codes")?)?,
            g_decimal,
            m_codes: codes(item(c, "m_codes")?)?,
            program_number: program_number.bytes().next(),
            colon_stop: item(c, "colon_stop")?,
            tv_check: item(c, "tv_check")?,
            arc_tolerance: item(c, "arc_tolerance")?,
            arc_tolerance_relative: item(c, "arc_tolerance_relative")?,
            ijk: match item::<String>(c, "ijk")?.as_str() {
                "absolute" => Ijk::Absolute,
                "quadrant" => Ijk::Quadrant,
                _ => Ijk::Incremental,
            },
            repeatable: item::<String>(c, "repeatable")?.into_bytes(),
            m_classes: item(c, "m_classes")?,
            max_index: item(c, "max_index")?,
            max_parameter: item(c, "max_parameter")?,
            read_only: item(c, "read_only")?,
            past_decimals: past_format(&item::<String>(c, "past_decimals")?)?,
            past_sequence: past_format(&item::<String>(c, "past_sequence")?)?,
            code_words: code_words(item(c, "code_words")?)?,
            index_g: item(c, "index_g")?,
            travel,
            work_offsets,
            feed_max: dec(item(c, "feed_max")?)?,
            spindle_max: dec(item(c, "spindle_max")?)?,
            sample_limits: item(c, "sample_limits")?,
            tool_max: item(c, "tool_max")?,
            rapid_rate: item(c, "rapid_rate")?,
            limit_units: units(&item::<String>(c, "limit_units")?),
        },
        control: Control::from_name(&item::<String>(c, "family")?),
        lathe: item(c, "lathe")?,
        dwell_formats: word_formats(item(c, "dwell_formats")?),
        unknown_g_alarms: alarms(item(c, "unknown_g")?),
        unknown_m_alarms: alarms(item(c, "unknown_m")?),
        pqr: [role(pqr.0), role(pqr.1), role(pqr.2)],
        reset: item(c, "reset")?,
        inch: item(c, "inch")?,
        metric: item(c, "metric")?,
        inch_code: item(c, "inch_code")?,
        metric_code: item(c, "metric_code")?,
        default_units: units(&item::<String>(c, "default_units")?),
        units_kept_at_end: item(c, "units_kept_at_end")?,
        increment_digits: item::<(u32, u32)>(c, "increment_digits")?.into(),
        meanings: item(c, "meanings")?,
        g_code_system: item(c, "g_code_system")?,
        dialect: crate::dialect(item(c, "dialect")?),
    })
}

/// A profile compiled once; immutable, shared by every reader of programs for that machine.
#[pyclass(module = "formats._core", frozen)]
pub struct Machine {
    pub(crate) inner: Arc<machine::Machine>,
}

#[pymethods]
impl Machine {
    #[new]
    fn new(spec: &Bound<'_, PyDict>) -> PyResult<Self> {
        Ok(Machine {
            inner: Arc::new(machine::Machine::new(self::spec(spec)?)),
        })
    }

    /// X is a diameter (a Fanuc or Haas lathe).
    #[getter]
    fn diameter(&self) -> bool {
        self.inner.diameter()
    }

    /// A Fanuc or Haas lathe: G98/G99 feed per minute and per revolution, G50 S clamps.
    #[getter]
    fn fanuc_lathe(&self) -> bool {
        self.inner.fanuc_lathe
    }
}

/// The F word's format among a facility note's formats.
fn feed_format(formats: Vec<(u8, WordFormat)>) -> Option<WordFormat> {
    formats
        .into_iter()
        .find(|(a, _)| *a == b'F')
        .map(|(_, f)| f)
}
