//! The units a LinuxCNC subroutine's body is read in under a change of units.
//!
//! A body (`o<name> sub` ... `o<name> endsub`) runs where it is called, not where it stands:
//! the interpreter skips it where it is written and runs it at each call in the modal state
//! of the caller (LinuxCNC manual, "O Codes": subroutines; G20/G21 are modal and a call does
//! not change them, M73 aside). Written above the main program, as most are, it stands before
//! the main program's G20/G21, so read in file order it would be read in the file's start
//! units (review 4, 8: `G1 Z-0.1` of a body called under G20 written `Z-0.003937`). So a body
//! is read in the units in force at its calls: those of the first call where it is written
//! after one, and where it is written before every call, those the call learns, the
//! conversion made again ([`crate::convert::REREAD`]). What cannot be shown is refused, with
//! its line and column: a body with a length before a units code of its own whose calls are
//! in different units, or that no call in the file runs (another file's program calls it, in
//! units this one does not show), and a body that selects units of its own (without M73) that
//! a caller in other units goes on from, as the caller then runs in the body's units. A body
//! that may return in other units than at its end (an early `o<name> return`), or in units in
//! doubt there, leaves its caller in units not known after each call (review 6, 1 and 2).

use crate::hash::FastMap;
use crate::modal::Units;

/// A body read to its end.
#[derive(Debug, Clone)]
struct Body {
    line: usize,
    units: Units,
    /// Where it was read in units a call showed (`Some(line)` of that call, 0 where a
    /// conversion before learned them), not in those in force where it stands.
    shown: Option<usize>,
    /// Its first length before a units code of its own: (line, column).
    depends: Option<(usize, usize)>,
    /// The units it leaves the machine in, where it selects its own and does not restore the
    /// caller's (M73).
    exit: Option<Units>,
    /// Why the units it returns in are not known: a return (`o<name> return`) in other units
    /// than its end, or a return or end in units in doubt (review 6, 1 and 2).
    exit_doubt: Option<String>,
}

/// What a call of a subroutine asks of the conversion.
#[derive(Debug, PartialEq, Eq)]
pub enum Call {
    Read,
    /// Read, and the caller goes on in units not known: why.
    Doubt(String),
    /// Convert again from the start, the body read in these units.
    Again(Units),
}

/// The body being read.
#[derive(Debug)]
struct Open {
    label: Vec<u8>,
    body: Body,
    /// It selected units of its own (G20/G21), and it restores the caller's state (M73).
    own_units: bool,
    restores: bool,
    /// The units an M73 after the body's own units code saved: those it returns in.
    saved: Option<Units>,
    /// Each way out so far (`return`, and its end): its line, the units it returns in, and
    /// why they are not known.
    exits: Vec<(usize, Units, Option<String>)>,
}

#[derive(Debug, Default)]
pub struct Bodies {
    read: FastMap<Vec<u8>, Body>,
    /// The first call of each label: its units and line.
    calls: FastMap<Vec<u8>, (Units, usize)>,
    /// A later call in other units than the first: (its line, its units).
    differing: FastMap<Vec<u8>, (usize, Units)>,
    open: Option<Open>,
}

/// A body whose units cannot be shown: why, and where (the converter's refusal of clause
/// "units").
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    pub message: String,
    pub line: usize,
    pub column: usize,
}

fn refusal(message: String, line: usize, column: usize) -> Refusal {
    Refusal {
        message,
        line,
        column,
    }
}

fn shown(label: &[u8]) -> String {
    String::from_utf8_lossy(label).into_owned()
}

impl Bodies {
    pub fn is_open(&self) -> bool {
        self.open.is_some()
    }

    /// A body begins on `line`: the units to read it in, those `learned` by a conversion
    /// before, or of its first call seen, or those in force (`current`).
    pub fn begin(
        &mut self,
        label: Vec<u8>,
        line: usize,
        current: Units,
        learned: Option<Units>,
    ) -> Units {
        let call = self.calls.get(&label).copied();
        let (units, shown) = match (learned, call) {
            (Some(u), _) => (u, Some(0)),
            (None, Some((u, at))) => (u, Some(at)),
            (None, None) => (current, None),
        };
        self.open = Some(Open {
            label,
            body: Body {
                line,
                units,
                shown,
                depends: None,
                exit: None,
                exit_doubt: None,
            },
            own_units: false,
            restores: false,
            saved: None,
            exits: Vec::new(),
        });
        units
    }

    /// The body's block on `line` reads a length at `column` (a block that selects units is
    /// given to [`Bodies::units_code`] instead: its code comes first).
    pub fn length(&mut self, line: usize, column: usize) -> Result<(), Refusal> {
        let Some(open) = &mut self.open else {
            return Ok(());
        };
        if open.own_units || open.body.depends.is_some() {
            return Ok(());
        }
        open.body.depends = Some((line, column));
        let Some(&(other, units)) = self.differing.get(&open.label) else {
            return Ok(());
        };
        let (first, first_line) = self.calls[&open.label];
        Err(refusal(
            format!(
                "{}: the subroutine is called in {} on line {first_line} and in {} on line \
                 {other}, and this length comes before a units code of its own, so it is read \
                 in the units of each call; write G20 or G21 in the subroutine before its \
                 first length",
                shown(&open.label),
                first.name(),
                units.name()
            ),
            line,
            column,
        ))
    }

    /// The body selects its units: what follows is read in them.
    pub fn units_code(&mut self) {
        if let Some(open) = &mut self.open {
            open.own_units = true;
        }
    }

    /// M73 in `units`: the modal state it runs in is restored at the return (LinuxCNC
    /// manual, "M73 Save and Autorestore Modal State"). Before the body's own units code
    /// that is the caller's; after it, the body's own, which its caller goes on in (review 5,
    /// 2: `G21 ... M73` under a G20 caller returns in metric).
    pub fn restores(&mut self, units: Units) {
        if let Some(open) = &mut self.open {
            if open.restores || open.saved.is_some() {
                return;
            }
            if open.own_units {
                open.saved = Some(units);
            } else {
                open.restores = true;
            }
        }
    }

    /// `o<name> return` on `line` in `units` (`doubt`: why they are not known): the body
    /// returns there, in the units it leaves the machine in at that point (LinuxCNC manual,
    /// "O Codes": return; the caller's where M73 restores them).
    pub fn returns(&mut self, line: usize, units: Units, doubt: Option<&str>) {
        if let Some(open) = &mut self.open {
            let doubt = doubt.map(str::to_string);
            let (units, doubt) = if open.restores {
                (open.body.units, None)
            } else if open.own_units {
                (open.saved.unwrap_or(units), doubt)
            } else {
                (units, doubt)
            };
            open.exits.push((line, units, doubt));
        }
    }

    /// The body ends on `line` in `units` (`doubt`: why they are not known). Where it may return in
    /// other units than at its end, or in units not known, a caller goes on in units not
    /// known: refused where a call before it went on already, else at each call
    /// ([`Call::Doubt`]).
    /// `dead`: no path reaches the end (an unconditional `return` before it): the body leaves
    /// by its returns only, in their units (review 7, 3).
    pub fn end(
        &mut self,
        line: usize,
        units: Units,
        doubt: Option<&str>,
        dead: bool,
    ) -> Result<(), Refusal> {
        let returned = self.open.as_ref().is_some_and(|o| !o.exits.is_empty());
        if !(dead && returned) {
            self.returns(line, units, doubt);
        }
        let Some(mut open) = self.open.take() else {
            return Ok(());
        };
        let units = open.exits[open.exits.len() - 1].1;
        if open.own_units && !open.restores {
            open.body.exit = Some(open.saved.unwrap_or(units));
        }
        let end = open.exits[open.exits.len() - 1].1;
        open.body.exit_doubt = open.exits.iter().find_map(|(at, u, doubt)| {
            if let Some(doubt) = doubt {
                Some(format!(
                    "the subroutine {} may return in units not known (line {at}: {doubt})",
                    shown(&open.label)
                ))
            } else if *u != end {
                Some(format!(
                    "the subroutine {} returns in {} on line {at} and in {} at its end",
                    shown(&open.label),
                    u.name(),
                    end.name()
                ))
            } else {
                None
            }
        });
        if let (Some(why), Some(&(_, at))) = (&open.body.exit_doubt, self.calls.get(&open.label)) {
            return Err(refusal(
                format!(
                    "{why}, and its call on line {at} goes on after it in either: select the \
                     units again after the call, or make every path through the subroutine \
                     end in the same units"
                ),
                line,
                1,
            ));
        }
        let label = open.label;
        if let (Some(exit), Some(&(called, at))) = (open.body.exit, self.calls.get(&label)) {
            if exit != called {
                return Err(leaves(&label, exit, called, at, line));
            }
        }
        self.read.insert(label, open.body);
        Ok(())
    }

    /// A call of `label` on `line` in `units` (column `column`).
    pub fn call(
        &mut self,
        label: Vec<u8>,
        line: usize,
        column: usize,
        units: Units,
    ) -> Result<Call, Refusal> {
        match self.calls.get(&label) {
            None => {
                self.calls.insert(label.clone(), (units, line));
            }
            Some(&(first, _)) if first != units => {
                self.differing.entry(label.clone()).or_insert((line, units));
            }
            Some(_) => {}
        }
        let Some(body) = self.read.get(&label) else {
            return Ok(Call::Read);
        };
        if let Some(exit) = body.exit.filter(|&exit| exit != units) {
            return Err(leaves(&label, exit, units, line, line));
        }
        let read = body.exit_doubt.clone().map_or(Call::Read, Call::Doubt);
        let Some((at, _)) = body.depends.filter(|_| body.units != units) else {
            return Ok(read);
        };
        match body.shown {
            None => Ok(Call::Again(units)),
            Some(shown_by) => {
                let by = if shown_by == 0 {
                    "those of another call".to_string()
                } else {
                    format!("those of the call on line {shown_by}")
                };
                Err(refusal(
                    format!(
                        "{}: called here in {}, the subroutine (line {}) is read in {}, {by}, \
                         and its length on line {at} comes before a units code of its own; \
                         write G20 or G21 in the subroutine before its first length",
                        shown(&label),
                        units.name(),
                        body.line,
                        body.units.name()
                    ),
                    line,
                    column,
                ))
            }
        }
    }

    /// The units each body read was read in, by label (for `convert --verify`, whose reader
    /// reads them so: [`crate::ncread::Reader::bodies`]).
    pub fn units(&self) -> Vec<(Vec<u8>, Units)> {
        let mut out: Vec<(Vec<u8>, Units)> = self
            .read
            .iter()
            .map(|(label, body)| (label.clone(), body.units))
            .collect();
        out.sort_by(|a, b| a.0.cmp(&b.0));
        out
    }

    /// At the end of the file: a body read in the units in force where it stands, no call of
    /// it seen, with a length before a units code of its own, is refused.
    pub fn finish(&self) -> Result<(), Refusal> {
        let mut unshown: Vec<(&Vec<u8>, &Body)> = self
            .read
            .iter()
            .filter(|(label, body)| body.shown.is_none() && !self.calls.contains_key(*label))
            .collect();
        unshown.sort_by_key(|(_, body)| body.line);
        // a call whose label is worked out as it runs (`o#1 call`, `o[#1] call`) may be one
        let computed = self
            .calls
            .iter()
            .filter(|(label, _)| crate::statement::computed_label(label))
            .map(|(_, &(_, line))| line)
            .min();
        for (label, body) in unshown {
            if let Some((line, column)) = body.depends {
                let none = match computed {
                    Some(call) => format!(
                        "no call in this file names the subroutine (line {}; the call of line \
                         {call} works out its label as it runs)",
                        body.line
                    ),
                    None => format!(
                        "no call of the subroutine (line {}) is in this file",
                        body.line
                    ),
                };
                return Err(refusal(
                    format!(
                        "{}: {none}, so the units it runs in, its caller's, are not shown, and \
                         this length comes before a units code of its own; write G20 or G21 in \
                         the subroutine before its first length",
                        shown(label),
                    ),
                    line,
                    column,
                ));
            }
        }
        Ok(())
    }
}

/// A body that selects units of its own and does not restore the caller's (M73) leaves the
/// machine in them: its caller, in others, goes on in the body's.
fn leaves(label: &[u8], exit: Units, called: Units, call: usize, line: usize) -> Refusal {
    refusal(
        format!(
            "{}: the subroutine selects {} and returns in it (no M73 before that units code), \
             and its call on line {call} is in {}: the caller goes on in the subroutine's \
             units, which the caller's text does not show; write the caller's units code again \
             after the call, or M73 in the subroutine before its units code",
            shown(label),
            exit.name(),
            called.name()
        ),
        line,
        1,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const MM: Units = Units::Metric;
    const IN: Units = Units::Inch;

    /// A body above its calls is read where it stands, then again in its first call's units
    /// where its length before any units code of its own is read otherwise; a second call in
    /// other units is refused.
    #[test]
    fn a_body_above_its_calls_is_read_again_in_the_first_call_s_units() {
        let mut bodies = Bodies::default();
        assert_eq!(bodies.begin(b"o<a>".to_vec(), 1, MM, None), MM);
        bodies.length(2, 4).unwrap();
        bodies.end(3, MM, None, false).unwrap();
        assert_eq!(bodies.call(b"o<a>".to_vec(), 5, 1, IN), Ok(Call::Again(IN)));
        // read again, the call's units learned
        let mut bodies = Bodies::default();
        assert_eq!(bodies.begin(b"o<a>".to_vec(), 1, MM, Some(IN)), IN);
        bodies.length(2, 4).unwrap();
        bodies.end(3, IN, None, false).unwrap();
        assert_eq!(bodies.call(b"o<a>".to_vec(), 5, 1, IN), Ok(Call::Read));
        let e = bodies.call(b"o<a>".to_vec(), 7, 1, MM).unwrap_err();
        assert_eq!((e.line, e.column), (7, 1));
        assert!(e.message.contains("called here in metric"), "{}", e.message);
        assert_eq!(bodies.units(), [(b"o<a>".to_vec(), IN)]);
        bodies.finish().unwrap();
    }

    /// A body with its own units code first needs no caller's units; one with no call in the
    /// file and a length before any is refused at the end; one below calls in two units at
    /// its first length.
    #[test]
    fn what_the_file_does_not_show_is_refused_where_it_is_read() {
        let mut own = Bodies::default();
        own.begin(b"o1".to_vec(), 1, MM, None);
        own.restores(MM);
        own.units_code();
        own.length(3, 1).unwrap();
        own.end(4, IN, None, false).unwrap();
        own.finish().unwrap();
        assert_eq!(own.call(b"o1".to_vec(), 6, 1, MM), Ok(Call::Read));
        // an M73 after the body's own units code saves those: the return is in them
        let mut late = Bodies::default();
        late.call(b"o1".to_vec(), 1, 1, IN).unwrap();
        late.begin(b"o1".to_vec(), 4, MM, None);
        late.units_code();
        late.restores(MM);
        let e = late.end(7, MM, None, false).unwrap_err();
        assert!(e.message.contains("selects metric"), "{}", e.message);
        let mut uncalled = Bodies::default();
        uncalled.begin(b"o1".to_vec(), 1, MM, None);
        uncalled.length(2, 8).unwrap();
        uncalled.end(3, MM, None, false).unwrap();
        let e = uncalled.finish().unwrap_err();
        assert_eq!((e.line, e.column), (2, 8));
        let mut below = Bodies::default();
        below.call(b"o1".to_vec(), 2, 1, IN).unwrap();
        below.call(b"o1".to_vec(), 4, 1, MM).unwrap();
        assert_eq!(below.begin(b"o1".to_vec(), 6, MM, None), IN);
        let e = below.length(7, 8).unwrap_err();
        assert!(e
            .message
            .contains("in inch on line 2 and in metric on line 4"));
    }

    /// Review 6, 1 and 2: a body that may return in other units than at its end (an early
    /// `return`), or in units in doubt at its end (an if/else selecting one each), leaves its
    /// caller in units not known: after each call, or refused at its end where a call before
    /// it went on already.
    #[test]
    fn a_body_that_may_return_in_other_units_leaves_its_caller_in_doubt() {
        let mut early = Bodies::default();
        early.begin(b"o<s>".to_vec(), 1, MM, None);
        early.units_code();
        early.returns(4, IN, None);
        early.units_code();
        early.end(7, MM, None, false).unwrap();
        match early.call(b"o<s>".to_vec(), 9, 1, MM) {
            Ok(Call::Doubt(why)) => assert!(
                why.contains("returns in inch on line 4 and in metric at its end"),
                "{why}"
            ),
            other => panic!("{other:?}"),
        }
        let mut doubt = Bodies::default();
        doubt.begin(b"o<s>".to_vec(), 1, MM, None);
        doubt.units_code();
        doubt
            .end(
                6,
                MM,
                Some("the condition beginning on line 2 ends in ..."),
                false,
            )
            .unwrap();
        assert!(matches!(
            doubt.call(b"o<s>".to_vec(), 9, 1, MM),
            Ok(Call::Doubt(why)) if why.contains("(line 6: the condition beginning on line 2")
        ));
        // the body below its call: refused at its end
        let mut below = Bodies::default();
        below.call(b"o<s>".to_vec(), 2, 1, MM).unwrap();
        below.begin(b"o<s>".to_vec(), 4, MM, None);
        below.units_code();
        below.returns(6, IN, None);
        below.units_code();
        let e = below.end(8, MM, None, false).unwrap_err();
        assert_eq!((e.line, e.column), (8, 1));
        assert!(
            e.message.contains("its call on line 2 goes on"),
            "{}",
            e.message
        );
        // M73 before its units code: every return restores the caller's
        let mut restored = Bodies::default();
        restored.begin(b"o<s>".to_vec(), 1, MM, None);
        restored.restores(MM);
        restored.units_code();
        restored.returns(4, IN, Some("not known"));
        restored.end(7, MM, None, false).unwrap();
        assert_eq!(restored.call(b"o<s>".to_vec(), 9, 1, MM), Ok(Call::Read));
    }
}
