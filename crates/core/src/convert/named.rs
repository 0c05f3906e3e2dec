//! Subprograms called by name from a program of the same file, under a change of units: a
//! SINUMERIK archive's `%_N_SUBA_SPF` (or `%_N_L100_SPF`) called by `SUBA`, `CALL "SUBA"` or
//! `L100`, and an Okuma OSP subprogram (`OSUBA` ... `RTS`, after the main program's end)
//! called by `CALL OSUBA`.
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

/// The program a call statement names: `CALL "SUBA"`, `CALL OSUBA X1`, a SINUMERIK's `SUBA`
/// or `SUBA(1, 2)`; None where the name is computed (`CALL PROGNAME`, a string variable, is
/// taken as written: no program of the file is named so unless it is that program).
fn called_name(family: Family, statement: &[u8]) -> Option<Vec<u8>> {
    let trimmed = statement.trim_ascii();
    let keyword = trimmed.len() >= 4 && trimmed[..4].eq_ignore_ascii_case(b"CALL");
    let rest = if keyword {
        trimmed[4..].trim_ascii_start()
    } else if family == Family::Sinumerik {
        trimmed
    } else {
        return None;
    };
    let rest = rest.strip_prefix(b"\"").unwrap_or(rest);
    let name = leading_name(rest);
    (!name.is_empty()).then_some(name)
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
        Ok(name)
    }

    /// The program being read ends (the next begins on `line`, or the file ends): recorded by
    /// its name; one read in its calls' units that selects other units itself returns in
    /// those, while its callers' text after the calls was read in theirs: refused.
    pub(super) fn named_ends(&mut self, line: usize) -> Result<(), ConvertError> {
        let units = self.modal.state.units;
        let coded = self.flow.coded();
        if let Some(before) = self.named.current.take() {
            let exit = coded.then_some(units);
            self.named
                .heads
                .insert(before, (self.flow.head_units(), exit));
        }
        match self.named.open.take() {
            Some((name, at, call)) if coded && units != at => Err(ConvertError {
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

    /// The calls of the file's named programs a block makes, in the units in force: kept for
    /// a subprogram not read yet, checked against the units the first values of one read
    /// already were read in.
    pub(super) fn named_calls(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if !self.names_followed() {
            return Ok(());
        }
        let family = self.c.family;
        let mut names: Vec<(usize, Vec<u8>)> = b
            .statements
            .iter()
            .filter(|s| s.1 == StatementKind::Call)
            .filter_map(|s| called_name(family, s.2).map(|n| (s.0, n)))
            .collect();
        if family == Family::Sinumerik {
            // `L100`: the subprogram L100 (Programming Manual Fundamentals, "Subprograms")
            names.extend(
                b.words
                    .iter()
                    .filter(|w| {
                        w.token[0].eq_ignore_ascii_case(&b'L')
                            && w.token.len() > 1
                            && w.token[1..].iter().all(u8::is_ascii_digit)
                    })
                    .map(|w| (w.start, w.token.to_ascii_uppercase())),
            );
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
