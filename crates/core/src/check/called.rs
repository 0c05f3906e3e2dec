//! A FANUC's or a Haas's subprogram placed before its caller in the file (a memory backup
//! lists programs by their numbers, so `O0002` comes before the `O1000` that calls it; review
//! 39, finding 4). The control runs a subprogram in the units and under the shift in force
//! at its call (G20/G21 are modal and a call changes none; docs/dialects.md, "Several
//! programs in one file"), which the checker knows only once it reads a call.
//!
//! A program read from the reset state (the file's first with an O number, or one no call
//! before it names, [`Checker::called_units`]) is read as before, with its own positions kept
//! apart from the spans of the programs before it ([`Early`]); its limits' findings (TG601,
//! TG602, TG605) are held from the first, and every finding after them with them. Where it ends as a main program does (M02/M30, the file's end, the next program),
//! or writes a units code, or a shift or a mirror restarts a span in it, the two are put
//! together and the held findings said, in the order they came: the same reading as before,
//! byte for byte. Where it returns (M99) having written no units code, it is a subprogram
//! whose lengths are its caller's: its span contributions and its largest feed are kept
//! ([`Pending`]) and its limits' findings taken out, and the spans go back to those before
//! it. At the file's end ([`Checker::early_finish`]), a subprogram whose calls agree on the
//! units and the shift is judged in them (its span from its least to its most position,
//! scaled and shifted; its largest feed); calls that disagree, or one in units or under a
//! shift not known (a call inside another program read apart that turns out a subprogram),
//! leave it unjudged with one TG140; a program no call names is read as before (its findings
//! said, its span added), at the end of the file.

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
    /// and its line and column, and the feed mode (94/95).
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
    column: usize,
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
    /// The calls so far: None, none; `Some(Ok(call))` all alike; `Some(Err(line))` one of
    /// them (its line) in other units or under another shift, or where they are not known.
    calls: Option<Result<(Call, String, usize), usize>>,
    /// The programs read apart in which calls of it were made, and the line of the first:
    /// where one of them turns out a subprogram, its units were its own caller's, not known
    /// at those calls.
    called_inside: Vec<(Key, usize)>,
}

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
        let mut removed = Vec::new();
        if let Some(from) = self.hold_from.take() {
            let mut kept = Vec::with_capacity(self.found.len() - from);
            for f in self.found.drain(from..) {
                if matches!(
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
            calls: None,
            called_inside: Vec::new(),
        });
        // (a call made in it, in the units it was read in, was made in units not known)
        let number = self.pending.last().expect("pushed").number.clone();
        for p in &mut self.pending {
            if let Some(&(_, line)) = p.called_inside.iter().find(|(n, _)| *n == number) {
                p.calls = Some(Err(line));
            }
        }
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
    pub(super) fn early_feed(&mut self, word: Dec, value: f64, line: usize, column: usize) {
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
            column,
            mode,
        });
    }

    /// A call of program `number` (`token` of line `line`): where a subprogram read before
    /// it has that number, the units and the shift in force here are kept for it (and
    /// true returned).
    #[cold]
    #[inline(never)]
    pub(super) fn early_call(&mut self, number: Key, token: String, line: usize) -> bool {
        let Some(k) = self.pending.iter().position(|p| p.number == number) else {
            return false;
        };
        let call = (!self.units_unknown).then(|| Call {
            factor: self.to_profile_units(false),
            feed_factor: self.to_profile_units(true),
            shift: self.call_shift(),
        });
        let inside = self.early.as_ref().map(|e| e.number.clone());
        let pending = &mut self.pending[k];
        if let Some(n) = inside {
            pending.called_inside.push((n, line));
        }
        pending.calls = match (pending.calls.take(), call) {
            (_, None) => Some(Err(line)),
            (None, Some(call)) => Some(Ok((call, token, line))),
            (Some(Ok((first, token, at))), Some(call)) if first == call => {
                Some(Ok((first, token, at)))
            }
            (Some(Ok(_)), Some(_)) => Some(Err(line)),
            (Some(Err(at)), _) => Some(Err(at)),
        };
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

    /// The span of `AXES[i]` starts again after the calls kept so far: their shift is in
    /// the coordinates of the span before, not of the one the body would be judged in at
    /// the file's end. A subprogram with positions on that axis is left with its calls'
    /// shift not known (one TG140 at the end, its feed still judged).
    #[cold]
    #[inline(never)]
    pub(super) fn early_restarted(&mut self, i: usize) {
        for p in &mut self.pending {
            if p.spans[i].is_none() {
                continue;
            }
            if let Some(Ok((call, _, _))) = p.calls.as_mut() {
                call.shift = None;
            }
        }
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
            match p.calls.clone() {
                Some(_) if !judged => {}
                None => self.early_as_read(p),
                Some(Ok((call, token, line))) => self.early_judged(&p, &call, &token, line),
                Some(Err(line)) if self.unknown_call.as_ref().is_some_and(|u| u.1 == line) => {
                    self.unknown_call_note();
                }
                Some(Err(line)) => {
                    let message = format!(
                        "{} is a subprogram written before its calls, and runs in the units and \
                         under the shift of its call; its calls disagree on them, or the one \
                         of line {line} is made where they are not known: its positions and \
                         feeds are not compared with the travel and the feed maximum (TG601, \
                         TG602)",
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

    /// A subprogram all of whose calls are made in the same units and under the same shift:
    /// its span (least and most position) in them, and its largest feed.
    fn early_judged(&mut self, p: &Pending, call: &Call, token: &str, line: usize) {
        let r = call.factor / p.factor;
        let units = match (call.factor == p.factor, self.config.limit_units) {
            (true, _) => "",
            (false, crate::modal::Units::Metric) => " in inches",
            (false, crate::modal::Units::Inch) => " in millimetres",
        };
        let under = format!(
            " ({} runs{units} as called by {token} of line {line}: a subprogram written \
             before its call runs in the units and under the shift in force there)",
            p.name
        );
        let Some(shift) = call.shift else {
            let message = format!(
                "{} is a subprogram written before its calls, and runs under the shift of its \
                 call; the shift at {token} of line {line} is not known: its positions are \
                 not compared with the travel (TG601)",
                p.name
            );
            self.report(Rule::NotFollowed, message, p.at.0, p.at.1);
            self.early_feed_judged(p, call, &under);
            return;
        };
        for (i, shift) in shift.into_iter().enumerate() {
            let Some(span) = p.spans[i] else {
                continue;
            };
            if self.travel.of_place(i).is_none() {
                continue;
            }
            let (l, m) = (p.least_at[i], p.most_at[i]);
            self.add_to_span(i, span.least * r + shift, false, l.0, || l.1, &under);
            self.add_to_span(i, span.most * r + shift, false, m.0, || m.1, &under);
        }
        self.early_feed_judged(p, call, &under);
    }

    fn early_feed_judged(&mut self, p: &Pending, call: &Call, under: &str) {
        let (Some(top), Some(feed)) = (self.config.feed_max, p.feed.as_ref()) else {
            return;
        };
        let value = feed.value / p.feed_factor * call.feed_factor;
        if value > top.to_f64() + 1e-9 {
            self.feed_over(
                feed.word,
                call.feed_factor,
                feed.mode,
                (feed.line, feed.column),
                under,
            );
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
        assert_eq!(limits(metric.clone(), backup), [(3, 4)]);
        let said = findings(metric.clone(), backup, Rule::TravelExceeded);
        assert!(
            said[0].message.contains("X spans 1778 (from -889 to 889)")
                && said[0]
                    .message
                    .contains("O0002 runs in inches as called by M98 P2 of line 8"),
            "{}",
            said[0].message
        );
        // the same with the subprogram after M30 (sub39): unchanged
        let after = "%\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nM30\nO0002\nG0 X35.\nM99\n%\n";
        assert_eq!(limits(metric.clone(), after), [(8, 4)]);
        // its feed too: F500. is 12700 mm/min under the G20 call
        let fast = "%\nO0002\nG1 X1. F500.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(metric.clone(), fast), [(3, 8)]);
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

    /// Calls in different units: the subprogram's lengths are not judged, one TG140 at its O.
    #[test]
    fn a_subprogram_before_calls_that_disagree_is_noted_not_judged() {
        let text = "%\nO0002\nG0 X35.\nM99\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nG21\nM98 P2\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), []);
        let notes: Vec<_> = findings(metric, text, Rule::NotFollowed)
            .into_iter()
            .filter(|f| f.message.starts_with("O0002"))
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(notes, [(2, 1)]);
    }

    /// A call made inside another subprogram written before its calls is made in units not
    /// known there (that one's caller's): noted, not judged in the reset units.
    #[test]
    fn a_call_inside_a_subprogram_read_apart_is_in_units_not_known() {
        let text = "%\nO0002\nG0 X35.\nM99\nO0003\nM98 P2\nM99\nO1000\nG20 G90 G54\n\
                    G0 X-35. Y0\nM98 P3\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), []);
        let notes: Vec<_> = findings(metric.clone(), text, Rule::NotFollowed)
            .into_iter()
            .filter(|f| f.message.starts_with("O0002"))
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(notes, [(2, 1)]);
        // called from a main program read from the reset state: its units are that one's
        let main = "%\nO0002\nG0 X35.\nM99\nO0003\nG20 G90\nG0 X-35. Y0\nM98 P2\nM30\n%\n";
        assert_eq!(limits(metric, main), [(3, 4)]);
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
        assert_eq!(limits(metric.clone(), text), [(3, 4)]);
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
        assert_eq!((said[0].line, said[0].column), (2, 4));
        assert!(
            said[0].message.contains("X spans 650 (from -250 to 400)")
                && said[0]
                    .message
                    .contains("o<s> runs as called by o<s> call of line 7"),
            "{}",
            said[0].message
        );
        let inline = "G21 G90\nG0 X-250 Y0\nG92 X-400\nG0 X250\nM2\n";
        assert_eq!(fired(lcnc(), inline, Rule::TravelExceeded), [(4, 4)]);
        // with no shift at the call: 500, inside (as before)
        let plain = ls1.replace("G92 X-400\n", "");
        assert_eq!(fired(lcnc(), &plain, Rule::TravelExceeded), []);
        // a G92.1 after the call starts the span again (its amount not known here): the
        // call's shift is in the coordinates of the span before, so the body is not judged
        // in the new one, noted (rs274: X250 at 400, then G92.1, X0)
        let ended = ls1.replace("o<s> call\n", "o<s> call\nG92.1\nG0 X0\n");
        assert_eq!(fired(lcnc(), &ended, Rule::TravelExceeded), []);
        assert!(findings(lcnc(), &ended, Rule::NotFollowed)
            .iter()
            .any(|f| f.line == 1 && f.message.contains("the shift at o<s> call of line 7")));
        // never called: read where it stands, as before (250 and -250: inside)
        let never = ls1.replace("o<s> call\n", "");
        assert_eq!(fired(lcnc(), &never, Rule::TravelExceeded), []);
    }

    /// Two calls under different shifts (rs274: X250 at 400, then at 250): not judged, one
    /// TG140 at the definition; a body of G91 moves from where the call leaves the tool has
    /// no position of its own to judge.
    #[test]
    fn a_linuxcnc_definition_whose_calls_disagree_is_noted() {
        let two = "o<s> sub\nG0 X250\no<s> endsub\nG21 G90\nG0 X-250 Y0\nG92 X-400\n\
                   o<s> call\nG92 X-250\no<s> call\nM2\n";
        assert_eq!(fired(lcnc(), two, Rule::TravelExceeded), []);
        let notes: Vec<_> = findings(lcnc(), two, Rule::NotFollowed)
            .into_iter()
            .filter(|f| f.message.starts_with("o<s> is a subprogram"))
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(notes, [(1, 1)]);
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
}
