//! A FANUC's or a Haas's subprogram placed before its caller in the file (a memory backup
//! lists programs by their numbers, so `O0002` comes before the `O1000` that calls it; review
//! 39, finding 4). The control runs a subprogram in the units and under the shift in force
//! at its call (G20/G21 are modal and a call changes none; docs/dialects.md, "Several
//! programs in one file"), which the checker knows only once it reads a call.
//!
//! A program read from the reset state (the file's first with an O number, or one no call
//! before it names, [`Checker::called_units`]) is read as before, with its own positions kept
//! apart from the spans of the programs before it ([`Early`]); its findings are held from its
//! first limit finding (TG601, TG602, TG605), at most [`HOLD_MAX`] of them. Where it ends as
//! a main program does (M02/M30, the file's end, the next program), writes a units code or a
//! shift of its own, a shift not followed or a mirror restarts a span in it, or its hold is
//! full, the two are put together and the held findings said, in the order they came: the
//! same reading as before, byte for byte. Where it returns (M99) having written no units code,
//! it is a subprogram whose lengths are its caller's: its span contributions, its largest
//! feed and its machine positions' findings are kept ([`Pending`]) and its limits' findings
//! taken out, and the spans go back to those before it. At each call made in known units
//! and under a known shift ([`Checker::early_call`]) it is judged there, with the spans as
//! they stand (its span from its least to its most position, scaled and shifted; its largest
//! feed; its G53 positions where the units are those it was read in), said at the call's line
//! naming the body's (review 42, findings 0-2); a call inside another program read apart adds
//! to that one's spans, as inline (finding 8). A call in units or under a shift not known
//! leaves it with one TG140 at the file's end; a program no call names is read as before (its
//! findings said, its span added), at the end of the file.

use super::{Checker, Finding, Span};
use crate::decimal::Dec;
use crate::modal::AXES;
use crate::rules::Rule;

/// What names a subprogram read before its calls: a FANUC's or a Haas's O number, a
/// LinuxCNC definition's label (`o<name>`, as [`crate::statement::o_label`] gives it).
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Key {
    Number(i64),
    Label(Vec<u8>),
}

/// The program in hand, read from the reset state, while it may still be a subprogram of a
/// later call.
#[derive(Debug)]
pub(super) struct Early {
    /// Its O number (or label), and its O word (`o<name> sub`) as written.
    number: Key,
    name: String,
    /// Its O word's line and column.
    at: (usize, usize),
    /// The spans of the programs before it ([`Checker::spans`] holds its own meanwhile).
    stash: [Option<Span>; 9],
    /// The line and column of each axis's least and most position so far.
    least_at: [(usize, usize); 9],
    most_at: [(usize, usize); 9],
    /// Its largest feed (in the profile's units as read from the reset state), the F word
    /// and its line, and the feed mode (94/95).
    feed: Option<Feed>,
    /// LinuxCNC: whether the main program had written a units code before the definition
    /// (given back at its end; the body is read as not having written one).
    given_before: Option<bool>,
}

#[derive(Debug, Clone)]
struct Feed {
    value: f64,
    word: Dec,
    line: usize,
    mode: i64,
}

/// The units and the shift of a call of a [`Pending`] subprogram: the factors from its
/// lengths and feeds to the profile's units, and each axis's shift in the spans'
/// coordinates; None where not known.
#[derive(Debug, Clone, PartialEq)]
struct Call {
    factor: f64,
    feed_factor: f64,
    shift: Option<[f64; 9]>,
}

/// A subprogram read before any call named it, which returned without writing a units code.
#[derive(Debug)]
pub(super) struct Pending {
    number: Key,
    name: String,
    at: (usize, usize),
    /// Its own spans, read in `factor`'s units from the reset state.
    spans: [Option<Span>; 9],
    least_at: [(usize, usize); 9],
    most_at: [(usize, usize); 9],
    factor: f64,
    feed_factor: f64,
    feed: Option<Feed>,
    /// Its limits' findings as read from the reset state.
    removed: Vec<Finding>,
    /// Its machine positions' findings (G53, a work offset's) as read from the reset state:
    /// said at its first call in the units it was read in (review 42, finding 1).
    positions: Vec<Finding>,
    /// The calls so far: None, none; `Some(Ok(line))` each judged where it was made (the
    /// first's line); `Some(Err(line))` one of them (its line) made where the units or the
    /// shift are not known.
    calls: Option<Result<usize, usize>>,
    /// Its largest feed said above the maximum at a call: not said again at the next.
    feed_said: bool,
}

/// The most findings held for a program read apart (review 42, finding 3): past it the
/// program is read as before, its findings said as they come, and a later call of it noted
/// (TG140). A real subprogram's findings are seldom that many; the hold stays a few hundred
/// kB whatever the file.
pub(super) const HOLD_MAX: usize = 1024;

/// A span's ends, put together with another's (`said` of either).
fn joined(a: Option<Span>, b: Option<Span>) -> Option<Span> {
    match (a, b) {
        (Some(a), Some(b)) => Some(Span {
            least: a.least.min(b.least),
            most: a.most.max(b.most),
            said: a.said || b.said,
        }),
        (a, None) => a,
        (None, b) => b,
    }
}

impl Checker {
    /// A program read from the reset state begins (`number`, its O word at `at`): its own
    /// positions kept apart from the spans before it. Only with no shift, frame or
    /// transformation in force, where its positions are its own words' alone.
    #[cold]
    pub(super) fn early_begin(&mut self, number: Key, name: String, at: (usize, usize)) {
        if self.shifts_on() || self.frames_on() || self.transformed.is_some() {
            return;
        }
        let stash = std::mem::take(&mut self.spans);
        self.early = Some(Box::new(Early {
            number,
            name,
            at,
            stash,
            least_at: [(0, 0); 9],
            most_at: [(0, 0); 9],
            feed: None,
            given_before: None,
        }));
        self.early_on = true;
    }

    /// The program in hand is no subprogram read apart (it ended as a main program, wrote
    /// a units code, or a span of it starts again): its spans put together with those
    /// before it, its held findings said.
    #[cold]
    #[inline(never)]
    pub(super) fn early_merge(&mut self) {
        let Some(early) = self.early.take() else {
            return;
        };
        self.early_on = false;
        if let Some(given) = early.given_before {
            self.machine.state.units_given |= given;
        }
        for (span, before) in self.spans.iter_mut().zip(early.stash) {
            *span = joined(before, *span);
        }
        self.hold_from = None;
    }

    /// The program in hand returned (M99): a subprogram, whose lengths are its caller's. Its
    /// spans and largest feed kept for its calls, its limits' findings taken out, the spans
    /// back to those before it. (Not under a frame left on: merged as before.)
    #[cold]
    #[inline(never)]
    pub(super) fn early_pend(&mut self) {
        if !self.early_on {
            return;
        }
        if self.frames_on() || self.units_unknown {
            self.early_merge();
            return;
        }
        let early = self.early.take().expect("early_on");
        self.early_on = false;
        if let Some(given) = early.given_before {
            self.machine.state.units_given = given;
        }
        let (mut removed, mut positions) = (Vec::new(), Vec::new());
        if let Some(from) = self.hold_from.take() {
            let mut kept = Vec::with_capacity(self.found.len() - from);
            for f in self.found.drain(from..) {
                if f.rule == Rule::TravelExceeded && f.message.contains(" in machine coordinates") {
                    positions.push(f);
                } else if matches!(
                    f.rule,
                    Rule::TravelExceeded | Rule::FeedTooHigh | Rule::FeedClamped
                ) {
                    removed.push(f);
                } else {
                    kept.push(f);
                }
            }
            self.found.extend(kept);
        }
        let spans = std::mem::replace(&mut self.spans, early.stash);
        self.pending.push(Pending {
            number: early.number,
            name: early.name,
            at: early.at,
            spans,
            least_at: early.least_at,
            most_at: early.most_at,
            factor: self.to_profile_units(false),
            feed_factor: self.to_profile_units(true),
            feed: early.feed,
            removed,
            positions,
            calls: None,
            feed_said: false,
        });
    }

    /// The findings held for the program read apart are more than [`HOLD_MAX`]: it is read
    /// as before from here (its findings said), and a later call of it noted.
    #[cold]
    #[inline(never)]
    pub(super) fn early_unhold(&mut self) {
        if let Some(early) = self.early.as_ref() {
            self.given_up = Some((early.number.clone(), early.name.clone(), early.at));
        }
        self.early_merge();
    }

    /// A limit's finding in a program read apart: held from the first, so that the findings
    /// are said in the order they came.
    #[inline]
    pub(super) fn early_hold(&mut self) {
        if self.early_on && self.hold_from.is_none() {
            self.hold_from = Some(self.found.len());
        }
    }

    /// [`Checker::add_to_span`] in a program read apart, after `at` went to the axis's
    /// span (its own): the line and column of a new least or most position kept, and the
    /// span judged with the one before it. The ends to say TG601 of, where it is wider than
    /// the travel and nothing was said of it yet (then said).
    #[cold]
    #[inline(never)]
    pub(super) fn early_span(
        &mut self,
        i: usize,
        at: f64,
        line: usize,
        column: usize,
    ) -> Option<(f64, f64)> {
        let early = self.early.as_mut().expect("early_on");
        let span = self.spans[i].as_mut().expect("added");
        if span.least == at {
            early.least_at[i] = (line, column);
        }
        if span.most == at {
            early.most_at[i] = (line, column);
        }
        let all = joined(early.stash[i], Some(*span)).expect("added");
        let (low, high) = self.travel.of_place(i).expect("a travel");
        if all.said || all.most - all.least <= (high - low) + 1e-9 {
            return None;
        }
        span.said = true;
        Some((all.least, all.most))
    }

    /// The largest feed so far of the program read apart (-inf before its first).
    #[inline]
    pub(super) fn early_feed_max(&self) -> f64 {
        self.early
            .as_ref()
            .and_then(|e| e.feed.as_ref())
            .map_or(f64::NEG_INFINITY, |f| f.value)
    }

    /// A feed in a program read apart: the largest kept (`value` in the profile's units as
    /// read from the reset state).
    #[cold]
    #[inline(never)]
    pub(super) fn early_feed(&mut self, word: Dec, value: f64, line: usize) {
        let mode = self.machine.state.feed_mode;
        let Some(early) = self.early.as_mut() else {
            return;
        };
        if mode == 93 || early.feed.as_ref().is_some_and(|f| f.value >= value) {
            return;
        }
        early.feed = Some(Feed {
            value,
            word,
            line,
            mode,
        });
    }

    /// A call of program `number` (`token` at `at`): where a subprogram read before it has
    /// that number, it is judged here, in the units and under the shift in force (review
    /// 42, finding 0: the spans as they are at the call), and true returned. Made inside
    /// another program read apart, its positions join that one's, to be judged where that
    /// one is called (finding 8).
    #[cold]
    #[inline(never)]
    pub(super) fn early_call(&mut self, number: Key, token: String, at: (usize, usize)) -> bool {
        let Some(k) = self.pending.iter().position(|p| p.number == number) else {
            if self.given_up.as_ref().is_some_and(|(n, _, _)| *n == number) {
                let (_, name, (line, _)) = self.given_up.take().expect("matched");
                let message = format!(
                    "{token} calls {name}, read from the reset state on line {line} and said \
                     as read there (it held more than {HOLD_MAX} findings): its positions and \
                     feeds were compared in the reset units, not in this call's units and \
                     under its shift"
                );
                self.report(Rule::NotFollowed, message, at.0, at.1);
            }
            return false;
        };
        let call = (!self.units_unknown)
            .then(|| self.call_shift())
            .flatten()
            .map(|shift| Call {
                factor: self.to_profile_units(false),
                feed_factor: self.to_profile_units(true),
                shift: Some(shift),
            });
        let Some(call) = call else {
            let pending = &mut self.pending[k];
            if !matches!(pending.calls, Some(Err(_))) {
                pending.calls = Some(Err(at.0));
            }
            return true;
        };
        let mut p = self.pending.remove(k);
        self.early_judged(&mut p, &call, &token, at);
        if p.calls.is_none() {
            p.calls = Some(Ok(at.0));
        }
        self.pending.insert(k, p);
        true
    }

    /// LinuxCNC: an `o<name> sub` opens a definition in the main program (`name` its label,
    /// its statement at `at`). rs274 reads the body without running it, and runs it where
    /// an `o<name> call` calls it, in the units and under the G92/G52 shift in force there
    /// (review 41, finding 4): read apart as a FANUC's subprogram before its call is, its
    /// units as not written.
    #[cold]
    #[inline(never)]
    pub(super) fn definition_begin(&mut self, name: &[u8], at: (usize, usize)) {
        if self.early_on {
            return;
        }
        let given = self.machine.state.units_given;
        let written = String::from_utf8_lossy(name).into_owned();
        self.early_begin(Key::Label(name.to_vec()), written, at);
        if let Some(early) = self.early.as_mut() {
            early.given_before = Some(given);
            self.machine.state.units_given = false;
        }
    }

    /// LinuxCNC: the `o<name> endsub` that closes the definition read apart: kept for its
    /// calls, as a FANUC's subprogram is at its M99.
    #[cold]
    #[inline(never)]
    pub(super) fn definition_end(&mut self) {
        if self.early_on {
            self.early_pend();
        }
    }

    /// A call whose program number or label is not known here (`M98 P#1`, `G65 P#1`,
    /// `o[#1] call`; `token` of line `line`): it may run any subprogram read before it, in
    /// units and under a shift the others' calls do not say, and any program of the file
    /// after it (review 41, finding 5): the ones held are left unjudged at the end, the
    /// ones after it read in units not known ([`Checker::called_units`]), with one TG140
    /// naming the call where a program it could run has lengths or feeds to judge.
    #[cold]
    #[inline(never)]
    pub(super) fn call_unknown(&mut self, token: String, line: usize, column: usize) {
        for p in &mut self.pending {
            p.calls = Some(Err(line));
        }
        if self.unknown_call.is_none() {
            self.unknown_call = Some((token, line, column, false));
        }
    }

    /// TG140 of the call [`Checker::call_unknown`] kept, said once where a program it may
    /// run has a length or a feed not judged for it.
    #[cold]
    #[inline(never)]
    pub(super) fn unknown_call_note(&mut self) {
        let Some((token, line, column, said)) = self.unknown_call.as_mut() else {
            return;
        };
        if *said {
            return;
        }
        *said = true;
        let (token, line, column) = (token.clone(), *line, *column);
        let message = format!(
            "{token} calls a program whose number is not known here: it may run any \
             subprogram of the file, in the units and under the shift in force at the call, so \
             the programs after it (until they write a units code) and the subprograms before \
             it are read in units not known; their positions and feeds are not compared with \
             the travel and the feed maximum (TG601, TG602)"
        );
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// The file's end: each subprogram read before its calls is judged in their units and
    /// under their shift (all alike), left unjudged with a TG140 (they disagree, or are not
    /// known), or read as before where no call names it.
    #[cold]
    #[inline(never)]
    pub(super) fn early_finish(&mut self) {
        for p in std::mem::take(&mut self.pending) {
            // (one with no position on an axis with a travel and no feed has nothing to judge:
            // no note of it)
            let judged = p.feed.is_some() && self.config.feed_max.is_some()
                || (0..AXES.len())
                    .any(|i| p.spans[i].is_some() && self.travel.of_place(i).is_some());
            match p.calls {
                Some(_) if !judged => {}
                None => self.early_as_read(p),
                Some(Ok(_)) => {}
                Some(Err(line)) if self.unknown_call.as_ref().is_some_and(|u| u.1 == line) => {
                    self.unknown_call_note();
                }
                Some(Err(line)) => {
                    let message = format!(
                        "{} is a subprogram written before its calls, and runs in the units and \
                         under the shift of its call; the one of line {line} is made where they \
                         are not known: its positions and feeds are not compared there with the \
                         travel and the feed maximum (TG601, TG602)",
                        p.name
                    );
                    self.report(Rule::NotFollowed, message, p.at.0, p.at.1);
                }
            }
        }
    }

    /// A subprogram no call names: read as before, from the reset state (its findings said,
    /// its span added to those of the file).
    fn early_as_read(&mut self, p: Pending) {
        self.found.extend(p.removed);
        self.found.extend(p.positions);
        for i in 0..AXES.len() {
            let Some(span) = p.spans[i] else {
                continue;
            };
            if span.said || self.travel.of_place(i).is_none() {
                self.spans[i] = joined(self.spans[i], Some(span));
                continue;
            }
            let (l, m) = (p.least_at[i], p.most_at[i]);
            self.add_to_span(i, span.least, false, l.0, || l.1, "");
            self.add_to_span(i, span.most, false, m.0, || m.1, "");
        }
    }

    /// A subprogram at a call made in known units and under a known shift: its span (least
    /// and most position) in them, and its largest feed, judged with the spans as they are
    /// here (said at the call, naming the body's line); its machine positions' findings said
    /// at its first call where the units are those it was read in.
    fn early_judged(&mut self, p: &mut Pending, call: &Call, token: &str, at: (usize, usize)) {
        let r = call.factor / p.factor;
        let units = match (call.factor == p.factor, self.config.limit_units) {
            (true, _) => "",
            (false, crate::modal::Units::Metric) => " in inches",
            (false, crate::modal::Units::Inch) => " in millimetres",
        };
        let (line, column) = at;
        let under = |of: usize| {
            format!(
                " ({} runs{units} as called by {token} of line {line}, its position of line \
                 {of} there: a subprogram written before its call runs in the units and under \
                 the shift in force there)",
                p.name
            )
        };
        let shift = call.shift.unwrap_or([0.0; 9]);
        for (i, shift) in shift.into_iter().enumerate() {
            let Some(span) = p.spans[i] else {
                continue;
            };
            if self.travel.of_place(i).is_none() {
                continue;
            }
            let (l, m) = (p.least_at[i].0, p.most_at[i].0);
            self.add_to_span(i, span.least * r + shift, false, line, || column, &under(l));
            self.add_to_span(i, span.most * r + shift, false, line, || column, &under(m));
        }
        if r == 1.0 && !p.positions.is_empty() {
            let unshifted = shift.iter().all(|s| *s == 0.0);
            for mut f in std::mem::take(&mut p.positions) {
                if !unshifted && !f.message.contains("(G53)") {
                    continue;
                }
                f.message = format!("{}{}", f.message, under(f.line));
                (f.line, f.column) = at;
                self.early_hold();
                self.found.push(f);
            }
        } else if r > 1.0 && !p.positions.is_empty() {
            // (review 43, finding A: a machine position beyond the travel as read stays beyond
            // it in the larger units of the call, the travel holding the machine zero: said as
            // read, naming the call, as before sub41; none was said)
            for mut f in std::mem::take(&mut p.positions) {
                f.message = format!(
                    "{} (the position as written, in the units {} was read in; it runs{units} as \
                     called by {token} of line {line}, farther out there)",
                    f.message, p.name
                );
                self.early_hold();
                self.found.push(f);
            }
        } else if !p.positions.is_empty() {
            // (in the smaller units of the call a position beyond the travel as read may be
            // within it: not judged, said once)
            p.positions.clear();
            let message = format!(
                "{token}: {} runs{units} here, and its machine positions (G53, a work \
                 offset's), beyond the travel as read in the units it was read in, are not \
                 judged in these",
                p.name
            );
            self.report(Rule::NotFollowed, message, line, column);
        }
        let (Some(top), Some(feed)) = (self.config.feed_max, p.feed.as_ref()) else {
            return;
        };
        let value = feed.value / p.feed_factor * call.feed_factor;
        if self.early_on {
            // (a call inside a program read apart: its feed is that one's, judged where it is
            // called)
            self.early_feed(feed.word, value, line);
        }
        if value > top.to_f64() + 1e-9 && !p.feed_said {
            p.feed_said = true;
            let under = under(feed.line);
            self.feed_over(feed.word, call.feed_factor, feed.mode, at, &under);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{dialect, findings, fired, of_family, run};
    use super::super::{Checker, Config};
    use crate::decimal::Dec;
    use crate::lex::Family;
    use crate::modal::Units;
    use crate::rules::{Rule, Selection};
    use std::sync::Arc;

    /// A FANUC-like mill reset in `units`, travel X -762..762 mm (30 in), feed to 10000
    /// mm/min, its limits in mm.
    fn mill(units: Units) -> Config {
        let dec = |text: &str| Dec::parse(text).unwrap();
        let mut config = of_family(Family::MacroB);
        config.facts.program_number = Some(b'O');
        config.modal.inch = 20;
        config.modal.metric = 21;
        config.modal.default_units = units;
        let code = if units == Units::Inch { 20 } else { 21 };
        config.modal.reset = vec![0, 17, code, 40, 80, 90, 94];
        config.modal.units_kept_at_end = true;
        config.facts.travel = vec![(b'X', dec("-762"), dec("762"))];
        config.facts.feed_max = Some(dec("10000"));
        config.facts.limit_units = Units::Metric;
        config
    }

    fn limits(config: Config, text: &str) -> Vec<(usize, usize)> {
        let mut found = fired(config.clone(), text, Rule::TravelExceeded);
        found.extend(fired(config.clone(), text, Rule::FeedTooHigh));
        found.extend(fired(config, text, Rule::FeedClamped));
        found
    }

    /// Review 39, finding 4: a memory backup's O0002 before the O1000 that calls it under
    /// G20 runs in inches: X -35..35 in is 1778 mm, past the 1524 of travel.
    #[test]
    fn a_subprogram_before_its_call_is_read_in_the_call_s_units() {
        let backup = "%\nO0002\nG0 X35.\nM99\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nM30\n%\n";
        let metric = mill(Units::Metric);
        // (said at the call, naming the body's line: review 42, findings 0 and 2)
        assert_eq!(limits(metric.clone(), backup), [(8, 5)]);
        let said = findings(metric.clone(), backup, Rule::TravelExceeded);
        assert!(
            said[0].message.contains("X spans 1778 (from -889 to 889)")
                && said[0].message.contains(
                    "O0002 runs in inches as called by M98 P2 of line 8, its position of line 3"
                ),
            "{}",
            said[0].message
        );
        // the same with the subprogram after M30 (sub39): unchanged
        let after = "%\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nM30\nO0002\nG0 X35.\nM99\n%\n";
        assert_eq!(limits(metric.clone(), after), [(8, 4)]);
        // its feed too: F500. is 12700 mm/min under the G20 call
        let fast = "%\nO0002\nG1 X1. F500.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(metric.clone(), fast), [(8, 5)]);
        // called twice: said at the first call only
        let twice = fast.replace("M98 P2\n", "M98 P2\nM98 P2\n");
        assert_eq!(limits(metric.clone(), &twice), [(8, 5)]);
        assert_eq!(limits(metric, &fast.replace("G20", "G21")), []);
    }

    /// A G21 caller on a machine reset in inches: the subprogram's X35. and X-30. are mm,
    /// inside the travel (read in the reset inches they spanned 65 in, a false TG601).
    #[test]
    fn a_subprogram_before_a_metric_call_is_read_in_millimetres() {
        let text =
            "%\nO0002\nG0 X35.\nG0 X-30.\nM99\nO1000\nG21 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(mill(Units::Inch), text), []);
        // with no call it is a program of its own, read in the reset inches: as before
        let alone = text.replace("M98 P2\n", "");
        assert_eq!(limits(mill(Units::Inch), &alone), [(4, 4)]);
    }

    /// Calls in different units (review 42, finding 9): each judged where it is made, the
    /// G20 one running X -35..35 in (1778 mm); no TG140 of the body.
    #[test]
    fn a_subprogram_before_calls_that_disagree_is_judged_at_each() {
        let text = "%\nO0002\nG0 X35.\nM99\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nG21\nM98 P2\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), [(8, 5)]);
        assert!(findings(metric.clone(), text, Rule::NotFollowed)
            .iter()
            .all(|f| !f.message.starts_with("O0002")));
        // the G21 call alone: X-889 mm then 35 mm, inside
        let metric_first = text.replace("M98 P2\nG21\n", "G21\n");
        assert_eq!(limits(metric, &metric_first), []);
    }

    /// A call made inside another subprogram written before its calls (review 42, finding
    /// 8): the inner body's positions join the outer's, judged at the outer's call in its
    /// units (O1000's G20: X -35..35 in, 1778 mm) and in the same units (nest.nc: X-700,
    /// then O0003 runs O0002's X900.: 1600 mm).
    #[test]
    fn a_call_inside_a_subprogram_read_apart_is_judged_at_the_outer_call() {
        let text = "%\nO0002\nG0 X35.\nM99\nO0003\nM98 P2\nM99\nO1000\nG20 G90 G54\n\
                    G0 X-35. Y0\nM98 P3\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), [(11, 5)]);
        let said = findings(metric.clone(), text, Rule::TravelExceeded);
        assert!(
            said[0].message.contains("X spans 1778 (from -889 to 889)")
                && said[0].message.contains(
                    "O0003 runs in inches as called by M98 P3 of line 11, its position of line 6"
                ),
            "{}",
            said[0].message
        );
        assert!(findings(metric.clone(), text, Rule::NotFollowed)
            .iter()
            .all(|f| !f.message.starts_with("O0002")));
        let nest = "%\nO0002\nG0 X900.\nM99\nO0003\nM98 P2\nM99\nO1000\nG21 G90 G54\n\
                    G0 X-700. Y0\nM98 P3\nM30\n%\n";
        assert_eq!(limits(metric.clone(), nest), [(11, 5)]);
        // called from a main program read from the reset state: its units are that one's
        let main = "%\nO0002\nG0 X35.\nM99\nO0003\nG20 G90\nG0 X-35. Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(metric, main), [(8, 5)]);
    }

    /// The subprogram's own G21, and a program that ends as a main program: read as before.
    #[test]
    fn a_program_before_its_call_that_writes_its_units_is_read_as_before() {
        let own = "%\nO0002\nG21\nG0 X900.\nG0 X-900.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(mill(Units::Metric), own), [(5, 4)]);
        let main =
            "%\nO0002\nG0 X900.\nG0 X-900.\nM30\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(mill(Units::Metric), main), [(4, 4)]);
    }

    /// The shift at the call (review 39, finding 2, with finding 4's layout): X-25. in,
    /// then the subprogram's X35. under G52 X30.: 65 in from the work zero, 90 in of span.
    #[test]
    fn a_subprogram_before_its_call_is_read_under_the_call_s_shift() {
        let text = "%\nO0002\nG0 X35.\nM99\nO1000\nG20 G90 G54\nG0 X-25. Y0\nG52 X30.\nM98 P2\nG52 X0\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), [(9, 5)]);
        let said = findings(metric.clone(), text, Rule::TravelExceeded);
        assert!(
            said[0].message.contains("X spans 2286 (from -635 to 1651)"),
            "{}",
            said[0].message
        );
        // without the G52: 60 in, 1524 mm, inside
        assert_eq!(limits(metric, &text.replace("G52 X30.\n", "")), []);
    }

    /// A LinuxCNC profile of the user's (review 41's lc.toml): X -300..300 mm.
    fn lcnc() -> Config {
        let dec = |text: &str| Dec::parse(text).unwrap();
        let mut config = of_family(Family::LinuxCnc);
        config.facts.travel = vec![(b'X', dec("-300"), dec("300"))];
        config.facts.limit_units = Units::Metric;
        config
    }

    /// Review 41, finding 4: LinuxCNC's `o<s> sub` at the top of the file runs where it is
    /// called, under the G92 in force there (`rs274 -g`: X-250, SET_G92_OFFSET(150), X250 at
    /// 400): 650 > 600 of travel. Inline, the same span.
    #[test]
    fn a_linuxcnc_definition_before_its_call_runs_under_the_call_s_shift() {
        let ls1 =
            "o<s> sub\nG0 X250\no<s> endsub\nG21 G90\nG0 X-250 Y0\nG92 X-400\no<s> call\nM2\n";
        let said = findings(lcnc(), ls1, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!((said[0].line, said[0].column), (7, 1));
        assert!(
            said[0].message.contains("X spans 650 (from -250 to 400)")
                && said[0]
                    .message
                    .contains("o<s> runs as called by o<s> call of line 7, its position of line 2"),
            "{}",
            said[0].message
        );
        let inline = "G21 G90\nG0 X-250 Y0\nG92 X-400\nG0 X250\nM2\n";
        assert_eq!(fired(lcnc(), inline, Rule::TravelExceeded), [(4, 4)]);
        // with no shift at the call: 500, inside (as before)
        let plain = ls1.replace("G92 X-400\n", "");
        assert_eq!(fired(lcnc(), &plain, Rule::TravelExceeded), []);
        // a G92.1 after the call starts the span again: the body was judged at the call, in
        // the span of then (rs274: X250 at 400, then G92.1, X0; review 42, finding 0)
        let ended = ls1.replace("o<s> call\n", "o<s> call\nG92.1\nG0 X0\n");
        assert_eq!(fired(lcnc(), &ended, Rule::TravelExceeded), [(7, 1)]);
        // never called: read where it stands, as before (250 and -250: inside)
        let never = ls1.replace("o<s> call\n", "");
        assert_eq!(fired(lcnc(), &never, Rule::TravelExceeded), []);
    }

    /// Two calls under different shifts (rs274: X250 at 400, then at 250): each judged where
    /// it is made (review 42, finding 9), the first's 650 said; a body of G91 moves from
    /// where the call leaves the tool has no position of its own to judge.
    #[test]
    fn a_linuxcnc_definition_whose_calls_disagree_is_judged_at_each() {
        let two = "o<s> sub\nG0 X250\no<s> endsub\nG21 G90\nG0 X-250 Y0\nG92 X-400\n\
                   o<s> call\nG92 X-250\no<s> call\nM2\n";
        assert_eq!(fired(lcnc(), two, Rule::TravelExceeded), [(7, 1)]);
        assert!(findings(lcnc(), two, Rule::NotFollowed)
            .iter()
            .all(|f| !f.message.starts_with("o<s> is a subprogram")));
        let relative = "o<s> sub\nG91 G0 X100\nG90\no<s> endsub\nG21 G90\nG0 X-250 Y0\n\
                        G92 X-400\no<s> call\nM2\n";
        assert_eq!(fired(lcnc(), relative, Rule::TravelExceeded), []);
        assert!(findings(lcnc(), relative, Rule::NotFollowed)
            .iter()
            .all(|f| !f.message.starts_with("o<s> is")));
    }

    /// Review 41, finding 5: `M98 P#1` may run O2000 in the caller's inches (1778 mm): its
    /// lengths are not judged in the reset mm, one TG140 names the call. `#1=2000` before it
    /// (the number known) is judged as `M98 P2000` is.
    #[test]
    fn a_call_whose_number_is_not_known_leaves_the_programs_it_may_run_unknown() {
        let pv4 = "%\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P#1\nM30\nO2000\nG0 X35.\nM99\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), pv4), []);
        let notes: Vec<_> = findings(metric.clone(), pv4, Rule::NotFollowed)
            .into_iter()
            .filter(|f| {
                f.message
                    .starts_with("M98 P#1 calls a program whose number")
            })
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(notes, [(5, 5)]);
        let g65 = pv4.replace("M98 P#1", "G65 P#1 A1.");
        assert_eq!(limits(metric.clone(), &g65), []);
        // the number known: judged in the caller's inches
        let known = pv4.replace("M98 P#1", "#1=2000\nM98 P#1");
        assert_eq!(limits(metric.clone(), &known), [(9, 4)]);
        assert_eq!(
            limits(metric.clone(), &pv4.replace("P#1", "P2000")),
            [(8, 4)]
        );
        // a subprogram before it: not judged either (the call may run it in any units)
        let before = "%\nO0002\nG0 X35.\nM99\nO1000\nG21 G90 G54\nG0 X-35. Y0\nM98 P2\n\
                      G20\nM98 P#1\nM30\n%\n";
        assert_eq!(limits(metric.clone(), before), []);
        // a later program that writes its own units is judged from there
        let own = "%\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P#1\nM30\nO2000\nG21\nG0 X900.\n\
                   G0 X-900.\nM99\n%\n";
        assert_eq!(limits(metric, own), [(10, 4)]);
    }

    /// LinuxCNC reads a computed o-word label (rs274ngc `read_o`: `o#1 call`, `o[#1] call`,
    /// `o#<s> call`): a parameter holding a known whole number calls that subroutine, judged
    /// at the call as `o100 call` is; an expression the checker does not work out leaves the
    /// call's target not known (one TG140, the body not judged), as `M98 P#1` does.
    #[test]
    fn a_linuxcnc_call_by_a_parameter_calls_the_subroutine_of_its_value() {
        let named = "o100 sub\nG0 X900\no100 endsub\nG21 G90\nG0 X-700 Y0\n#1=100\n\
                     o100 call\nM2\n";
        assert_eq!(fired(lcnc(), named, Rule::TravelExceeded), [(7, 1)]);
        for call in ["o#1 call", "o[#1] call", "O [ #1 ] call", "o#<s> call [2]"] {
            let text = named
                .replace("#1=100", "#1=100\n#<s>=100")
                .replace("o100 call", call);
            assert_eq!(
                fired(lcnc(), &text, Rule::TravelExceeded),
                [(8, 1)],
                "{call}"
            );
        }
        for call in ["o[#1+0] call", "o#2 call"] {
            let text = named.replace("o100 call", call);
            assert_eq!(fired(lcnc(), &text, Rule::TravelExceeded), [], "{call}");
            let notes: Vec<_> = findings(lcnc(), &text, Rule::NotFollowed)
                .into_iter()
                .filter(|f| {
                    f.message
                        .contains("calls a program whose number is not known")
                })
                .map(|f| (f.line, f.column))
                .collect();
            assert_eq!(notes, [(7, 1)], "{call}");
        }
    }

    /// Findings held for a program read apart are said in the order they came, whether
    /// they are taken after each line or at the end: a main program's report is the same.
    #[test]
    fn held_findings_keep_their_order() {
        let text = "%\nO1000\nG21 G90\nG0 X-700.\nG0 X900.\nG1 X0 F20000.\nQ5\nM30\n%\n";
        let all = |take_each: bool| {
            let mut checker = Checker::new(Arc::new(mill(Units::Metric)), Selection::all(), false);
            let (mut tokens, mut found) = (Vec::new(), Vec::new());
            for (i, line) in text.lines().enumerate() {
                checker.check_line(
                    line.as_bytes(),
                    i + 1,
                    &dialect(Family::MacroB),
                    &mut tokens,
                );
                if take_each {
                    found.extend(checker.drain());
                }
            }
            checker.finish();
            found.extend(checker.take());
            found
                .into_iter()
                .map(|f| (f.rule, f.line, f.column))
                .collect::<Vec<_>>()
        };
        assert_eq!(all(true), all(false));
        let (_, found) = run(mill(Units::Metric), &dialect(Family::MacroB), text);
        let lines: Vec<_> = found.iter().map(|f| f.line).collect();
        let mut sorted = lines.clone();
        sorted.sort();
        assert_eq!(lines, sorted, "{found:?}");
    }

    /// Review 42, finding 0: the body judged at its call, with the spans as they stand
    /// there: a span started again after the call (rs1.nc's G92, rs3.nc's later program's
    /// G52) keeps the TG601 of X-700 then O0002's X900 (1600 mm), said at the call.
    #[test]
    fn a_subprogram_before_its_call_is_judged_at_the_call() {
        let rs1 = "%\nO0002\nG0 X900.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nM98 P2\nG92 X0\n\
                   G0 X10.\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), rs1), [(8, 5)]);
        let said = findings(metric.clone(), rs1, Rule::TravelExceeded);
        assert!(
            said[0].message.contains("X spans 1600 (from -700 to 900)")
                && said[0]
                    .message
                    .contains("O0002 runs as called by M98 P2 of line 8, its position of line 3"),
            "{}",
            said[0].message
        );
        let rs3 = "%\nO0002\nG0 X900.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nM98 P2\nM30\n\
                   O0003\nG52 X100.\nG0 X0\nM30\n%\n";
        assert_eq!(limits(metric, rs3), [(8, 5)]);
    }

    /// Review 42, finding 1: a G53 position of a body before its call, the call in the
    /// units it was read in: said at the call (the machine goes to X-900 whatever the
    /// shift); in other units not said in the reset ones.
    #[test]
    fn a_machine_position_of_a_subprogram_is_said_at_its_call() {
        let g53 = "%\nO0002\nG53 G0 X-900.\nM99\nO1000\nG21 G90 G54\nM98 P2\nM30\n%\n";
        let metric = mill(Units::Metric);
        let said = findings(metric.clone(), g53, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!((said[0].line, said[0].column), (7, 5));
        assert!(
            said[0]
                .message
                .contains("X goes to -900 in machine coordinates (G53)")
                && said[0].message.contains("its position of line 3"),
            "{}",
            said[0].message
        );
        // under a G52 too (G53 ignores it)
        let shifted = g53.replace("M98 P2\n", "G52 X10.\nM98 P2\nG52 X0\n");
        assert_eq!(limits(metric.clone(), &shifted), [(8, 5)]);
        // never called: as read, at the end
        assert_eq!(limits(metric, &g53.replace("M98 P2\n", "")), [(3, 8)]);
    }

    /// Review 42, finding 7: a body's own G52 replaces the call's local shift (FANUC 0i-F,
    /// "Local coordinate system"): read as before from there, X-800 then X750 (1550 mm).
    #[test]
    fn a_subprogram_that_sets_its_own_shift_is_read_as_before() {
        let text = "%\nO0002\nG52 X0\nG0 X750.\nM99\nO1000\nG21 G90 G54\nG52 X-100.\n\
                    G0 X-700. Y0\nM98 P2\nG52 X0\nM30\n%\n";
        let said = findings(mill(Units::Metric), text, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].message.contains("X spans 1550 (from -800 to 750)"),
            "{}",
            said[0].message
        );
    }

    /// Review 42, finding 3: a program read apart holds at most HOLD_MAX findings between
    /// drains; past it they are said as read (the same findings a main program gives), and
    /// a later call of it is noted once.
    #[test]
    fn the_hold_of_a_program_read_apart_is_bounded() {
        let mut text = String::from("%\nO0002\nG0 X-700. Y0\nG0 X900.\n");
        for _ in 0..3000 {
            text.push_str("G1 X1. F20000.\nS99999 M3\n");
        }
        text.push_str("M99\nO1000\nG21 G90 G54\nM98 P2\nM30\n%\n");
        let config = Arc::new(mill(Units::Metric));
        let mut checker = Checker::new(config.clone(), Selection::all(), false);
        let mut tokens = Vec::new();
        let (mut most, mut found) = (0, Vec::new());
        for (i, line) in text.lines().enumerate() {
            checker.check_line(
                line.as_bytes(),
                i + 1,
                &dialect(Family::MacroB),
                &mut tokens,
            );
            found.extend(checker.drain());
            most = most.max(checker.found.len());
        }
        checker.finish();
        found.extend(checker.take());
        assert!(most <= super::HOLD_MAX + 8, "{most}");
        assert!(found
            .iter()
            .any(|f| f.rule == Rule::TravelExceeded && f.line == 4));
        assert!(found.iter().any(|f| f.rule == Rule::NotFollowed
            && f.line == 6008
            && f.message
                .starts_with("M98 P2 calls O0002, read from the reset state")));
        let lines: Vec<_> = found.iter().map(|f| f.line).collect();
        assert!(lines.windows(2).all(|w| w[0] <= w[1]), "out of line order");
        // taken at the end alone: the same findings
        let (_, all) = run(mill(Units::Metric), &dialect(Family::MacroB), &text);
        assert_eq!(all.len(), found.len());
    }
}
