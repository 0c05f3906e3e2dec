//! Subprograms called by name from a program of the same file, under a change of units: a
//! SINUMERIK archive's `%_N_SUBA_SPF` (or `%_N_L100_SPF`) called by `SUBA`, `CALL "SUBA"`,
//! `PCALL SUBA`, `MCALL SUBA` or `L100`, and an Okuma OSP subprogram (`OSUBA` ... `RTS`, after
//! the main program's end) called by `CALL OSUBA` or `MODIN OSUBA` ([`called_name`]). A call
//! the converter cannot name (`CALL PNAME`, `EXTCALL`) is refused where the file holds a
//! subprogram; a `PROC ... SAVE` subprogram returns its caller to the caller's units.
//!
//! On the control a subprogram runs in the units in force at its call: a SINUMERIK's G70/G71
//! (G700/G710) are modal and a subprogram inherits them (Programming Manual Fundamentals,
//! "Inch or metric dimensions"; Job Planning, "Subprogram technique": the modal functions in
//! force at the call stay so in the subprogram), an OSP's unit system is the machine's
//! selection, which the main program's G20/G21 confirm (docs/dialects.md, Okuma "Inch"). So
//! the subprogram's text is converted in the units of its calls, as FANUC's `M98 P` and
//! Haas's M97 are followed ([`crate::units_flow`]): where every call of it read before it
//! stands in the same known units, it is read in those, the target's in those the converted
//! caller leaves in force; where its calls differ, or one is in units not known, its first
//! value before its own units code is refused. A call of a subprogram read earlier in the file
//! (an archive holding the SPF before the MPF), whose first values were read in other units
//! than the call's, is refused at the call. An MPF of an archive is a program of its own and
//! starts from the reset state, as before.

use super::{text, BlockIn, ConvertError, Converter, Family, FastMap, StatementKind, Units};
use crate::dialect::Opening;

/// The units at a call: the source's lengths and feed, the output's lengths and feed; whether
/// they were known (no doubt of the units flow), and the call's line.
#[derive(Debug, Clone, Copy)]
struct Call {
    src: Units,
    src_feed: Units,
    out: Units,
    out_feed: Units,
    known: bool,
    line: usize,
}

/// What the converter keeps of the file's named programs and their calls.
#[derive(Debug, Default, Clone)]
pub(super) struct NamedPrograms {
    /// Calls of a program not begun yet, by its name in upper case.
    calls: Vec<(Vec<u8>, Call)>,
    /// Each program read, by name: the units its first values were read in before its own
    /// units code (None where it selected its units first, or read no value), and those it
    /// ends in where it selects units itself (its caller goes on in them).
    heads: FastMap<Vec<u8>, (Option<Units>, Option<Units>)>,
    /// The subprogram being read in its calls' units: its name, those units, the first
    /// call's line.
    open: Option<(Vec<u8>, Units, usize)>,
    /// The line of the last block read.
    pub(super) last_line: usize,
    /// The program being read, by name.
    current: Option<Vec<u8>>,
    /// The subprograms read in their calls' units, by name: `convert --verify` reads the
    /// source's so ([`Converter::body_units`]).
    pub(super) followed: Vec<(Vec<u8>, Units)>,
    /// The first call of a program the converter cannot name (`CALL PNAME`, `EXTCALL`): its
    /// line, column and text, refused once the file shows a subprogram it could reach.
    unresolved: Option<(usize, usize, String)>,
    /// Whether a subprogram of the file has begun.
    subprograms: bool,
    /// Whether the program being read is declared `PROC ... SAVE` ([`proc_save`]).
    save: bool,
    /// The subprogram being read with no call the converter recognised before it: its name
    /// and first line.
    uncalled: Option<(Vec<u8>, usize)>,
    /// The units the programs read so far select with their own units codes.
    selected: Vec<Units>,
}

/// The name of the program a block begins as its opening shows it: a SINUMERIK archive's
/// subprogram header (`%_N_SUBA_SPF` SUBA, `%_N_L100_SPF` L100, `%L100` L100; None for a part
/// program, `_MPF`), an Okuma OSP program name (`OSUBA`). The converter and the verify reader
/// ([`crate::ncread::Reader`]) name a program so.
pub(crate) fn program_name(family: Family, opening: &Opening<'_>) -> Option<Vec<u8>> {
    match family {
        Family::Sinumerik => {
            let name = opening.percent?;
            if crate::dialect::archive_file(family, name) != Some(true) {
                return None;
            }
            let upper: Vec<u8> = name
                .iter()
                .filter(|c| !c.is_ascii_whitespace())
                .map(u8::to_ascii_uppercase)
                .collect();
            let upper = upper.strip_prefix(b"_N_").unwrap_or(&upper);
            Some(upper.strip_suffix(b"_SPF").unwrap_or(upper).to_vec())
        }
        Family::Okuma => opening
            .statement
            .filter(|s| s.1 == StatementKind::Name && s.2.first() == Some(&b'O'))
            .map(|s| leading_name(s.2)),
        _ => None,
    }
}

/// The leading name of `text` (letters, digits, `_`), upper case.
fn leading_name(text: &[u8]) -> Vec<u8> {
    text.iter()
        .take_while(|c| c.is_ascii_alphanumeric() || **c == b'_')
        .map(u8::to_ascii_uppercase)
        .collect()
}

/// What a call statement calls.
#[derive(Debug, PartialEq)]
enum Called {
    /// A program named as written (upper case).
    Name(Vec<u8>),
    /// A program the converter cannot name: a SINUMERIK `CALL` of a string variable or an
    /// expression, an `EXTCALL` (a program of external memory, which may be one of the
    /// file's names or not).
    Unknown,
}

/// The program a call statement names, by every call form of the dialect that names one:
/// - SINUMERIK (Programming Manual Fundamentals, "Subprogram technique"; Job Planning,
///   "Indirect subprogram call", "Subprogram call with path specification", "Execute
///   external subprogram"): `SUBA` or `SUBA(1, 2)` (the name alone), `CALL "SUBA"` (a
///   string constant), `PCALL SUBA` or `PCALL /_N_WKS_DIR/_N_W_WPD/SUBA` (the name with or
///   without its path: the last part); `MCALL SUBA` is the command MCALL and the call
///   statement `SUBA`. `CALL PNAME` (a string variable), a `CALL` of a string expression and
///   `EXTCALL` are [`Called::Unknown`].
/// - Okuma OSP (the programming manual's list of mnemonic codes names CALL and MODIN/MODOUT,
///   docs/dialects.md): `CALL OSUBA Q3`, and `MODIN OSUBA`, the modal call that runs OSUBA
///   after each move until `MODOUT` (no name: None), in the caller's units as a `CALL` does.
fn called_name(family: Family, statement: &[u8]) -> Option<Called> {
    let trimmed = statement.trim_ascii();
    let keyword = |k: &[u8]| {
        trimmed.len() > k.len()
            && trimmed[..k.len()].eq_ignore_ascii_case(k)
            && !(trimmed[k.len()].is_ascii_alphanumeric() || trimmed[k.len()] == b'_')
    };
    let name = |rest: &[u8]| {
        let name = leading_name(rest.trim_ascii_start());
        (!name.is_empty()).then_some(Called::Name(name))
    };
    match family {
        Family::Sinumerik if keyword(b"EXTCALL") => Some(Called::Unknown),
        Family::Sinumerik if keyword(b"PCALL") => {
            let rest = trimmed[5..].trim_ascii();
            let end = rest
                .iter()
                .position(|c| !(c.is_ascii_alphanumeric() || matches!(c, b'_' | b'/')))
                .unwrap_or(rest.len());
            let path = &rest[..end];
            let last = path.rsplit(|&c| c == b'/').next().unwrap_or(path);
            name(last).or(Some(Called::Unknown))
        }
        Family::Sinumerik if keyword(b"CALL") => {
            // only a string constant alone names a program: `CALL "SUBA"`, or with a section
            // of it (`CALL "SUBA" BLOCK START TO END`); `CALL BLOCK START TO END` repeats a
            // section of the program itself (Job Planning, "Program section repetition")
            let rest = trimmed[4..].trim_ascii();
            let block = |r: &[u8]| {
                r.len() > 5 && r[..5].eq_ignore_ascii_case(b"BLOCK") && r[5].is_ascii_whitespace()
            };
            if block(rest) {
                return None;
            }
            match rest.strip_prefix(b"\"") {
                Some(quoted) => {
                    let n = leading_name(quoted);
                    let after = quoted.get(n.len() + 1..).unwrap_or_default().trim_ascii();
                    let closed =
                        quoted.get(n.len()) == Some(&b'"') && (after.is_empty() || block(after));
                    Some(if closed && !n.is_empty() {
                        Called::Name(n)
                    } else {
                        Called::Unknown
                    })
                }
                None => Some(Called::Unknown),
            }
        }
        Family::Sinumerik => name(trimmed),
        Family::Okuma if keyword(b"CALL") => name(&trimmed[4..]),
        Family::Okuma if keyword(b"MODIN") => name(&trimmed[5..]),
        _ => None,
    }
}

/// Whether a SINUMERIK statement declares its program with the attribute SAVE (`PROC SUBA
/// SAVE`, `PROC SUBA(REAL X) SAVE`): at its return the control restores the modal G
/// functions in force at the call, G70/G71 among them (Programming Manual Fundamentals,
/// "Subprograms with SAVE mechanism").
fn proc_save(statement: &[u8]) -> bool {
    let trimmed = statement.trim_ascii();
    if trimmed.len() < 5 || !trimmed[..4].eq_ignore_ascii_case(b"PROC") {
        return false;
    }
    // after the name and its parameters in parentheses, the attributes
    let after = match trimmed.iter().rposition(|&c| c == b')') {
        Some(close) => &trimmed[close + 1..],
        None => &trimmed[4..],
    };
    after
        .split(|c| !(c.is_ascii_alphanumeric() || *c == b'_'))
        .any(|w| w.eq_ignore_ascii_case(b"SAVE"))
}

impl Converter {
    /// Whether this conversion follows named calls: a change of units on a SINUMERIK or an
    /// Okuma OSP source.
    fn names_followed(&self) -> bool {
        self.c.units.is_some() && matches!(self.c.family, Family::Sinumerik | Family::Okuma)
    }

    /// Before a block is read: the name of the subprogram it begins, if any (a SINUMERIK
    /// archive's SPF header; an OSP program name after the end of the program before), the
    /// program before it recorded by its name.
    pub(super) fn named_opening(
        &mut self,
        b: &BlockIn<'_>,
        opening: &Opening<'_>,
    ) -> Result<Option<Vec<u8>>, ConvertError> {
        if !self.names_followed() {
            return Ok(None);
        }
        self.named.last_line = b.line;
        let name = program_name(self.c.family, opening);
        if !b.percent && name.is_none() {
            return Ok(None);
        }
        self.named_ends(b.line)?;
        self.named.current.clone_from(&name);
        // an OSP program name at the file's head names the main program, not a subprogram
        if self.c.family == Family::Okuma && self.ended_on.is_none() {
            return Ok(None);
        }
        if name.is_some() {
            self.named.subprograms = true;
            self.unresolved_call()?;
        }
        Ok(name)
    }

    /// The program being read ends (the next begins on `line`, or the file ends): recorded by
    /// its name; one read in its calls' units that selects other units itself returns in
    /// those, while its callers' text after the calls was read in theirs: refused.
    pub(super) fn named_ends(&mut self, line: usize) -> Result<(), ConvertError> {
        let units = self.modal.state.units;
        let coded = self.flow.coded();
        // a SAVE subprogram returns its caller to the caller's units
        let save = std::mem::take(&mut self.named.save);
        let head = self.flow.head_units();
        if let Some(before) = self.named.current.take() {
            let exit = (coded && !save).then_some(units);
            self.named.heads.insert(before, (head, exit));
        }
        if let (Some((name, first)), Some(head)) = (self.named.uncalled.take(), head) {
            if let Some(other) = self.named.selected.iter().find(|&&u| u != head) {
                self.note_line(
                    first,
                    format!(
                        "line {first}: the subprogram {} has no call in the file the converter \
                         recognises; it is read in {}, the units at its start, while a program \
                         of the file selects {}: called from there it would run in those",
                        String::from_utf8_lossy(&name),
                        head.name(),
                        other.name()
                    ),
                );
            }
        }
        match self.named.open.take() {
            Some((name, at, call)) if coded && !save && units != at => Err(ConvertError {
                message: format!(
                    "the subprogram {} ends in {}, its own units code's, and returns so to its \
                     caller, whose text after the call on line {call} was read in {}; select \
                     the units again after the call, or leave them as they were at the end of \
                     the subprogram",
                    String::from_utf8_lossy(&name),
                    units.name(),
                    at.name()
                ),
                clause: "units",
                column: 1,
                line: Some(line.saturating_sub(1).max(1)),
            }),
            _ => Ok(()),
        }
    }

    /// A subprogram of the file begins (after its reset, [`Converter::start_program`], on a
    /// SINUMERIK): read in the units of its calls before it where they agree, in doubt where
    /// they do not.
    pub(super) fn named_begins(&mut self, name: &[u8], line: usize) {
        let mut calls = Vec::new();
        self.named.calls.retain(|(n, call)| {
            if n == name {
                calls.push(*call);
            }
            n != name
        });
        let Some(&first) = calls.first() else {
            self.named.uncalled = Some((name.to_vec(), line));
            return;
        };
        let shown = String::from_utf8_lossy(name);
        let differs = calls.iter().find(|c| {
            !c.known
                || (c.src, c.src_feed, c.out, c.out_feed)
                    != (first.src, first.src_feed, first.out, first.out_feed)
        });
        if let Some(other) = differs {
            let at = |c: &Call| {
                if c.known {
                    c.src.name()
                } else {
                    "units not known"
                }
            };
            self.flow.set_doubt(format!(
                "the subprogram {shown} (line {line}) runs in the units of its call, and is \
                 called on line {} in {} and on line {} in {}",
                first.line,
                at(&first),
                other.line,
                at(other)
            ));
            return;
        }
        self.named.followed.push((name.to_vec(), first.src));
        self.named.open = Some((name.to_vec(), first.src, first.line));
        self.modal.state.units = first.src;
        self.modal.state.feed_units = first.src_feed;
        self.out_length_units = first.out;
        self.out_feed_units = first.out_feed;
        self.follow_units();
        self.set_factor();
        // its units are its caller's: no units code is inserted, nothing is in doubt
        self.units_seen = true;
        self.program_doubt = None;
        self.units_doubt = None;
        self.ended_on = None;
        self.note_line(
            line,
            format!(
                "line {line}: the subprogram {shown} is read in {}, the units of its call on \
                 line {} (a subprogram runs in its caller's units)",
                first.src.name(),
                first.line
            ),
        );
    }

    /// A call the converter cannot name, in a file that holds a subprogram it may reach:
    /// refused at the call, since the subprogram would be read in other units than those it
    /// runs in.
    fn unresolved_call(&mut self) -> Result<(), ConvertError> {
        let Some((line, column, call)) = self.named.unresolved.clone() else {
            return Ok(());
        };
        if !self.named.subprograms {
            return Ok(());
        }
        Err(ConvertError {
            message: format!(
                "{call}: a call of a program the converter cannot name (a string variable, an \
                 expression or an external program), in a file that holds a subprogram it may \
                 call; a subprogram runs in the units of its call, which cannot be followed to \
                 it; call the program by its name"
            ),
            clause: "units",
            column,
            line: Some(line),
        })
    }

    /// The calls of the file's named programs a block makes, in the units in force: kept for
    /// a subprogram not read yet, checked against the units the first values of one read
    /// already were read in.
    pub(super) fn named_calls(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if !self.names_followed() {
            return Ok(());
        }
        let family = self.c.family;
        let units = self.modal.state.units;
        if self.flow.coded() && !self.named.selected.contains(&units) {
            self.named.selected.push(units);
        }
        if family == Family::Sinumerik
            && b.statements
                .iter()
                .any(|s| s.1 == StatementKind::Declaration && proc_save(s.2))
        {
            self.named.save = true;
        }
        let mut names: Vec<(usize, Vec<u8>)> = Vec::new();
        for s in b.statements.iter().filter(|s| s.1 == StatementKind::Call) {
            match called_name(family, s.2) {
                Some(Called::Name(name)) => names.push((s.0, name)),
                Some(Called::Unknown) if self.named.unresolved.is_none() => {
                    self.named.unresolved =
                        Some((b.line, crate::text::column(b.text, s.0), text(s.2)));
                    if self.named.subprograms {
                        return self.unresolved_call();
                    }
                }
                _ => {}
            }
        }
        if family == Family::Sinumerik {
            // `L100`: the subprogram L100 (Programming Manual Fundamentals, "Subprograms")
            // (a loop of the first bytes: most blocks have no L word, and the filter's
            // extend cost a look of about 20 instructions at every word)
            for w in b.words {
                if w.token[0].eq_ignore_ascii_case(&b'L')
                    && w.token.len() > 1
                    && w.token[1..].iter().all(u8::is_ascii_digit)
                {
                    names.push((w.start, w.token.to_ascii_uppercase()));
                }
            }
        }
        let known = self.flow.doubt().is_none();
        for (at, name) in names {
            let units = self.modal.state.units;
            if let Some(&(head, exit)) = self.named.heads.get(&name) {
                let why = match (head, exit) {
                    (Some(head), _) if head != units || !known => Some(format!(
                        "reads its first values in {}, before its own units code, and runs in \
                         the units of its call, here {}; select the units at the head of the \
                         subprogram",
                        head.name(),
                        if known { units.name() } else { "not known" }
                    )),
                    (_, Some(exit)) if exit != units || !known => Some(format!(
                        "ends in {}, its own units code's, and returns so, while the text \
                         after the call is read in {}; select the units again after the call",
                        exit.name(),
                        if known {
                            units.name()
                        } else {
                            "units not known"
                        }
                    )),
                    _ => None,
                };
                if let Some(why) = why {
                    return Err(ConvertError {
                        message: format!(
                            "{}: this subprogram, earlier in the file, {why}",
                            text(&name)
                        ),
                        clause: "units",
                        column: crate::text::column(b.text, at),
                        line: None,
                    });
                }
                continue;
            }
            let call = Call {
                src: units,
                src_feed: self.modal.state.feed_units,
                out: self.out_length_units,
                out_feed: self.out_feed_units,
                known,
                line: b.line,
            };
            self.named.calls.push((name, call));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_call_form_that_names_a_program_is_read() {
        let s = Family::Sinumerik;
        let name = |n: &str| Some(Called::Name(n.as_bytes().to_vec()));
        assert_eq!(called_name(s, b"SUBA"), name("SUBA"));
        assert_eq!(called_name(s, b"suba(1, 2)"), name("SUBA"));
        assert_eq!(called_name(s, b"CALL \"SUBA\""), name("SUBA"));
        assert_eq!(called_name(s, b"PCALL SUBA"), name("SUBA"));
        assert_eq!(
            called_name(s, b"PCALL /_N_WKS_DIR/_N_W_WPD/SUBA"),
            name("SUBA")
        );
        assert_eq!(called_name(s, b"CALL PNAME"), Some(Called::Unknown));
        assert_eq!(
            called_name(s, b"CALL \"SU\" << \"BA\""),
            Some(Called::Unknown)
        );
        assert_eq!(called_name(s, b"EXTCALL \"SUBA\""), Some(Called::Unknown));
        assert_eq!(called_name(s, b"CALL BLOCK START TO END"), None);
        assert_eq!(
            called_name(s, b"CALL \"SUBA\" BLOCK START TO END"),
            name("SUBA")
        );
        let o = Family::Okuma;
        assert_eq!(called_name(o, b"CALL OSUBA Q3"), name("OSUBA"));
        assert_eq!(called_name(o, b"MODIN OSUBA"), name("OSUBA"));
        assert_eq!(called_name(o, b"MODOUT"), None);
        assert_eq!(called_name(Family::MacroB, b"CALL OSUBA"), None);
    }

    #[test]
    fn save_is_read_after_the_name_and_parameters() {
        assert!(proc_save(b"PROC SUBA SAVE"));
        assert!(proc_save(b"proc SUBA(REAL X, STRING[8] SAVE) save DISPLOF"));
        assert!(!proc_save(b"PROC SUBA(REAL SAVE)"));
        assert!(!proc_save(b"PROC SUBA DISPLOF"));
        assert!(!proc_save(b"DEF REAL SAVE"));
    }
}
