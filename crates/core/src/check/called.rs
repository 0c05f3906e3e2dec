//! A FANUC's or a Haas's subprogram placed before its caller in the file (a memory backup
//! lists programs by their numbers, so `O0002` comes before the `O1000` that calls it; review
//! 39, finding 4). The control runs a subprogram in the units, the distance mode and under
//! the shift in force at its call (G20/G21 and G90/G91 are modal and a call changes none;
//! docs/dialects.md, "Several programs in one file"), which the checker knows only once it
//! reads a call.
//!
//! A program read from the reset state (the file's first with an O number, or one no call
//! before it names, [`Checker::called_units`]) is read as before, with its own positions kept
//! apart from the spans of the programs before it ([`Early`]); its findings are held from its
//! first limit finding (TG601, TG602, TG605). The hold is bounded where a finding is held,
//! not where the findings are taken (review 43, finding B): past [`HOLD_MAX`] findings of its
//! limits, or [`HOLD_ALL`] of any rule since the hold began, selected or not, it is given up,
//! so the CLI, the Python API, a chunk's boundary and `--select` read a file alike. Where it
//! ends as a main program does (M02/M30, the file's end, the next program), writes a units
//! code or a shift of its own, a shift not followed or a mirror restarts a span in it, or its
//! hold is given up, the two are put together and the held findings said, in the order they
//! came: the same reading as before, byte for byte. Where it returns (M99) having written no
//! units code, it is a subprogram whose lengths are its caller's: its span contributions, its
//! largest feed, its G53 positions' least and most per axis and its machine positions'
//! findings are kept ([`Pending`]) and its limits' findings taken out, and the spans go back
//! to those before it. At each call made in known units and under a known shift
//! ([`Checker::early_call`]) it is judged there, with the spans as they stand (its span from
//! its least to its most position, scaled and shifted; its largest feed; its G53 positions
//! in the call's units, review 43, finding A), said at the call's line naming the body's
//! (review 42, findings 0-2); a call inside another program read apart adds to that one's
//! spans, as inline (finding 8). A body whose first position comes before a G90/G91 of its
//! own, called in the other mode, has positions not known at that call: one TG140 there
//! (review 43, finding D). A body's last G90/G91 is in force in its caller after the call
//! ([`Checker::call_returns`]); inside another body read apart that is a G90/G91 of that
//! body's at the call, and the called body's positions from its own G90 on are that body's
//! too, at any depth (review 47, F1). A call in units or under a shift not known leaves it with one
//! TG140 at the file's end; a program no call names is judged alone (its own findings said,
//! its span not added to the file's: its caller is not known), at the end of the file; a
//! program given up is noted at each call of it (finding E).

use super::limits::Written;
use super::{Checker, Finding, Placed, Span};
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
#[derive(Clone, Debug)]
pub(super) struct Early {
    /// What it keeps for its calls.
    body: Body,
    /// The spans of the programs before it ([`Checker::spans`] holds its own meanwhile).
    stash: [Option<Span>; 9],
    /// LinuxCNC: whether the main program had written a units code before the definition
    /// (given back at its end; the body is read as not having written one).
    given_before: Option<bool>,
    /// The distance mode it is read in (G91: true), the machine's count of G90/G91 codes
    /// at its start, and whether its first position came before a G90/G91 of its own (None:
    /// no position yet). Such a body's positions are its caller's mode's (review 43, D).
    incremental: bool,
    distance_codes: u32,
    moved_first: Option<bool>,
    /// The machine's count of G90/G91 codes at its last call of a program the checker does
    /// not read there ([`Checker::call_mode_lost`]): where no G90/G91 came after it, the mode
    /// it returns in is not known (review 48, F11).
    lost_codes: Option<u32>,
    /// The findings of its limits held (TG601, TG602, TG605, selected or not) and
    /// [`Checker::reports`] where the hold began: the bound on the hold counted as they come,
    /// whoever takes them and whatever the selection (review 43, finding B).
    held: usize,
    reports_from: u64,
    /// [`Checker::offsets_written`], [`Checker::g10_expression`] and whether the profile's
    /// offsets were lost ([`Checker::lose_offsets`]) in the program it is read inside (a
    /// LinuxCNC main's, around a definition) or the one before it: given back at its end
    /// (review 58d F4: a G10, G52 or stored call of an earlier program, uncalled or called
    /// after, silenced every later program's machine positions).
    written_before: Written,
    expression_before: u16,
    local_before: u16,
    lost_before: bool,
    /// The tool length offset in force at its start ([`Body::changes`]).
    length_before: (i64, bool),
    /// LinuxCNC: the work offset the main program had selected before the definition,
    /// given back at its `endsub` (the definition is read with none: its calls select the
    /// one it runs under).
    work_before: Option<i64>,
}

/// What a program read apart ([`Early`]) and a subprogram kept for its calls ([`Pending`])
/// both hold: handed from the one to the other at its M99.
#[derive(Clone, Debug)]
struct Body {
    /// Its O number (or label), and its O word (`o<name> sub`) as written.
    number: Key,
    name: String,
    /// Its O word's line and column.
    at: (usize, usize),
    /// The line and column of each axis's least and most position.
    least_at: [(usize, usize); 9],
    most_at: [(usize, usize); 9],
    /// Its largest feed (in the profile's units as read from the reset state), the F word
    /// and its line, and the feed mode (94/95).
    feed: Option<Feed>,
    /// Where it moved before a G90/G91 of its own, its positions from its own G90 on
    /// ([`Absolute`]).
    absolute: Absolute,
    /// The first call in it whose program the checker does not read here (its calling words
    /// and line: a program not read before it, itself, one given up, a number not known, a
    /// Haas's M97), or such a call of a program it calls: a G90/G91 written there is not
    /// followed (review 47, F1). For a Haas's M97, the blocks it runs (`O2000's from N100 to
    /// an M99`: review 48, F18).
    unfollowed: Option<(String, usize, Option<String>)>,
    /// The least and the most value of each axis's G53 positions, in the units it is read
    /// in (review 43, A: judged at each call in that call's units).
    machine: Machine,
    /// The same of those written before a G90/G91 of its own (run in the call's mode: under
    /// a G91 call a G53 under G91, not judged; review 46, F3), and the line of the last.
    inherited: Machine,
    inherited_last: Option<usize>,
    /// The blocks in it that call a program (any call its dialect knows: `dialect::calls`, a
    /// LinuxCNC `o.. call`), and those of them whose program, read before it, was judged
    /// into its own spans there ([`Checker::early_call`]). No call naming it, where every
    /// call was so its own span holds what its callees run and is judged alone (review 56e,
    /// F2); where one was not (a program written after it: its positions go to the file's
    /// span), its span is joined to the file's, with those of the programs it runs (review
    /// 56b, F4).
    calls: u32,
    calls_judged: u32,
    /// The work offsets' axes it may write when it runs ([`Checker::offsets_written`] at
    /// its end): taken into its caller's at each call.
    writes: Written,
    /// It lost the profile's offsets (a G10, G52, G54.1, a frame, a stored program's
    /// call...): so does its caller from each call on.
    loses: bool,
    /// It may change what its caller's offsets are other than by `writes` and `loses`: it
    /// selects a work offset of its own (G54-G59 are modal: its caller's after the return),
    /// writes a work offset's system variable, or leaves a tool length offset other than
    /// the one it was read in ([`Checker::call_keeps`]).
    changes: bool,
    /// The end or return before it is one the block skip can pass over (`/M30`): with the
    /// switch on, the program before runs on into it (review 56e, F4).
    after_skippable_end: bool,
    /// It is the file's first program: where no program of the file ends as a main one
    /// (M02/M30), the control runs it from the reset state (a main program ending in M99
    /// loops; G90 is the power-on mode), so its caller's G90/G91 is no question (review
    /// 57c, F7). A file whose subprograms come before its main keeps the caller's reading,
    /// and so does a file of several programs none ends as a main (a library of
    /// subprograms loaded for a main elsewhere: review 57e F3), but where the first calls
    /// programs (its span then holds theirs).
    first: bool,
    /// The axes (their places' bits) whose machine position (a work offset's) it said
    /// outside the travel: that said more than its span can, which is not said again where
    /// it is judged alone (review 56b, F3).
    outside: u16,
    /// Each axis's least and most absolute work position read with no work offset in
    /// force ([`Checker::work_unplaced`]): its caller's offset's, judged at each call
    /// under that offset (review 61a F7, F6, F2).
    unplaced: [[Option<Unplaced>; 2]; 9],
}

impl Early {
    /// The program's number, where it is numbered and not run on into from the one before
    /// (skip switch on).
    pub(super) fn numbered(&self) -> Option<i64> {
        match self.body.number {
            Key::Number(n) if !self.body.after_skippable_end => Some(n),
            _ => None,
        }
    }
}

/// A program read apart merged by a G52 (its own, or one a call of a program read before
/// carries): its positions kept with no work offset in force before it, judged at its later
/// calls as a returned body's are (review 62a F8: `O3000` / `G0 X-780.` / `M98 P2000` of a
/// G52 program / `M99`, called under G55, runs X-780. at -880).
#[derive(Debug, Clone)]
pub(super) struct Merged {
    number: i64,
    name: String,
    unplaced: [[Option<Unplaced>; 2]; 9],
    factor: f64,
    read_incremental: Option<bool>,
    said: u128,
}

/// A work position of a program read apart with no work offset in force
/// ([`Body::unplaced`]): the position (the profile's units) and its line.
#[derive(Debug, Clone, Copy)]
struct Unplaced {
    at: f64,
    line: usize,
}

/// The positions of a body that moved before writing its own G90/G91, from the G90 it then
/// writes on: each axis's from its first position in G90 after that code, which is where
/// the axis is whatever the mode of the call (review 46, F1: `G0 X10.` / `G90` / `G0 X-900.`
/// called under G91 goes to X-900; finding D's rule had dropped it with the rest). An axis
/// first moved in G91 after the code stays not known.
#[derive(Debug, Clone, Copy, Default)]
struct Absolute {
    spans: [Option<Span>; 9],
    least_at: [(usize, usize); 9],
    most_at: [(usize, usize); 9],
    /// The axes (their places' bits) whose positions are known from here.
    known: u16,
}

/// A program read apart given up ([`Checker::early_unhold`]): its number, name and O word's
/// place, and whether it passed [`HOLD_ALL`] (findings of any rule) rather than
/// [`HOLD_MAX`] (its limits' findings).
#[derive(Clone, Debug)]
pub(super) struct GivenUp {
    number: Key,
    name: String,
    at: (usize, usize),
    all: bool,
}

/// A G53 position of a program read apart: its value as written, the same in the profile's
/// units as read, its line, and whether it was said beyond the travel at a call.
#[derive(Debug, Clone, Copy)]
struct MachineAt {
    value: Dec,
    at: f64,
    line: usize,
    said: bool,
}

/// Each axis's least and most G53 position ([`MachineAt`]).
type Machine = [[Option<MachineAt>; 2]; 9];

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
    /// G91 in force at the call (a call changes no modal state: the body runs in it).
    incremental: bool,
}

/// A subprogram read before any call named it, which returned without writing a units code.
#[derive(Clone, Debug)]
pub(super) struct Pending {
    /// What it kept while read apart ([`Early`]).
    body: Body,
    /// Its own spans, read in `factor`'s units from the reset state.
    spans: [Option<Span>; 9],
    factor: f64,
    feed_factor: f64,
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
    /// Its runs of increments from a position not known wider than the travel (TG601, among
    /// `removed`) said at a call: not said again at the next (issue 32, incr48's open case).
    runs_said: bool,
    /// Some(mode): its first position came before a G90/G91 of its own, read in `mode` (G91:
    /// true); a call in the other mode runs those positions otherwise, not known there
    /// (review 43, finding D). None: it wrote its own first, or has no position.
    read_incremental: Option<bool>,
    /// Some(G91): the distance mode it returns in, where it wrote a G90/G91 (of its own, or
    /// of a program it calls): its caller's from there (G90/G91 are modal; review 47, F1).
    ends: Option<bool>,
    /// That TG140 said at a call (not again at the next).
    mode_said: bool,
    /// The work offset it was read under, where that was the one the program before left,
    /// its caller's not known ([`Checker::work_offset_unknown`]): the findings among
    /// `positions` marked `guessed` are said at a call under this one only.
    work_guessed: Option<i64>,
    /// Its last G90/G91 not known: it called a program the checker did not read there, and
    /// wrote none after (review 48, F11).
    ends_lost: bool,
    /// The ends of [`Body::unplaced`] said at a call under each work offset (bit `18 *
    /// (G5x - 54) + 2 * place + end`): not again under that offset, said again under
    /// another (one subprogram called once a fixture, under G55 then G56).
    unplaced_said: u128,
}

/// The most findings held for a program read apart (review 42, finding 3): past it the
/// program is read as before, its findings said as they come, and a later call of it noted
/// (TG140). A real subprogram's findings are seldom that many; the hold stays a few hundred
/// kB whatever the file.
pub(super) const HOLD_MAX: usize = 1024;

/// The most findings of any rule (selected or not) made while a program's findings are held:
/// past it the program is read as before, as past [`HOLD_MAX`] of its limits' (the hold
/// stays a few MB whatever follows its first limit finding).
pub(super) const HOLD_ALL: u64 = 4 * HOLD_MAX as u64;

/// What a TG601 of a run of increments from a position not known says
/// (crate::check::limits): such a finding of a body read apart is said at its calls.
/// How a body's machine position stands at a call ([`Checker::offset_now`]).
enum Now {
    /// As read: the offset's value the profile's there.
    AsRead,
    /// Under a value a G10 before the call wrote, not known: kept.
    Unknown,
    /// Under the value (the last) a G10 before the call wrote: the axis's place, the offset
    /// (54-59), the work position and the value.
    Written(u8, u8, f64, f64),
}

const RUN: &str = " with its start not known: more than its whole travel of ";

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

/// A call's tail (`... its position of line 3 there ...`) naming the position of line `line`
/// instead: the excursion's farthest, which the value written judges.
fn farthest_named(tail: &str, line: usize) -> String {
    const AT: &str = "its position of line ";
    let Some(k) = tail.find(AT).map(|k| k + AT.len()) else {
        return tail.to_string();
    };
    let digits = tail[k..].bytes().take_while(u8::is_ascii_digit).count();
    format!("{}{line}{}", &tail[..k], &tail[k + digits..])
}

impl Placed {
    /// An offset's position as (`place`, `work`, `at`, `line`); None for any other.
    fn offset(&self) -> Option<(u8, u8, f64, usize)> {
        match *self {
            Placed::Offset {
                place,
                work,
                at,
                line,
            } => Some((place, work, at, line)),
            _ => None,
        }
    }
}

impl Checker {
    /// A program read from the reset state begins (`number`, its O word at `at`): its own
    /// positions kept apart from the spans before it. Only with no shift, frame or
    /// transformation in force, where its positions are its own words' alone.
    #[cold]
    pub(super) fn early_begin(&mut self, number: Key, name: String, at: (usize, usize)) {
        self.work_unplaced = false;
        let numbered = matches!(number, Key::Number(_));
        if self.shifts_on() || self.frames_on() || self.transformed.is_some() {
            return;
        }
        let stash = std::mem::take(&mut self.spans);
        let lost = self.offsets_lost;
        self.early = Some(Box::new(Early {
            body: Body {
                number,
                name,
                at,
                least_at: [(0, 0); 9],
                most_at: [(0, 0); 9],
                feed: None,
                absolute: Absolute::default(),
                unfollowed: None,
                machine: [[None; 2]; 9],
                inherited: [[None; 2]; 9],
                inherited_last: None,
                calls: 0,
                calls_judged: 0,
                writes: Written::default(),
                loses: false,
                changes: false,
                after_skippable_end: self.end_skippable,
                first: self.programs == 0,
                outside: 0,
                unplaced: [[None; 2]; 9],
            },
            stash,
            given_before: None,
            incremental: self.machine.state.incremental,
            distance_codes: self.machine.distance_codes,
            moved_first: None,
            lost_codes: None,
            held: 0,
            reports_from: 0,
            written_before: if self.end_skippable {
                self.offsets_written.clone()
            } else {
                std::mem::take(&mut self.offsets_written)
            },
            expression_before: std::mem::take(&mut self.g10_expression),
            local_before: std::mem::take(&mut self.g10_local),
            // (the program before runs on into it, skip switch on: that run's writes and loss)
            lost_before: std::mem::replace(&mut self.offsets_lost, lost && self.end_skippable),
            length_before: (self.machine.state.length_offset, self.length_decimal),
            work_before: None,
        }));
        self.early_on = true;
        // (a LinuxCNC definition runs under the work offset of each call, not the one the
        // main program selected before it: rs274 reads it without running it and runs it
        // at the call, `rs274 -g`; read with none, its positions kept for its calls)
        let linuxcnc = self.config.family == crate::lex::Family::LinuxCnc;
        if linuxcnc && !numbered && !self.config.work_offsets.is_empty() {
            let before = self.work.take();
            if let Some(early) = self.early.as_mut() {
                early.work_before = before;
            }
        }
        // (a FANUC's or a Haas's program with no offset in force at its start: its caller's
        // selects the one it runs under, review 61a F7; a LinuxCNC definition the same)
        self.work_unplaced = !self.config.work_offsets.is_empty()
            && self.work.is_none()
            && !self.end_skippable
            && (self.config.family == crate::lex::Family::MacroB && numbered
                || linuxcnc && !numbered);
    }

    /// The program in hand is no subprogram read apart (it ended as a main program, wrote
    /// a units code, or a span of it starts again): its spans put together with those
    /// before it, its held findings said.
    #[cold]
    #[inline(never)]
    pub(super) fn early_merge(&mut self) {
        self.early_merge_as(false);
    }

    /// [`Checker::early_merge`]; `main`: where the program ends as a main program (M02/M30,
    /// the file's end, the next program begun), not merged before its end.
    pub(super) fn early_merge_as(&mut self, main: bool) {
        let Some(early) = self.early.take() else {
            return;
        };
        // (a LinuxCNC definition merged (a G92.1, a units code...): read as before calls76,
        // its positions under a work offset not said and the offsets lost from here, as its
        // `sub` lost them; review 76-calls76 F5's l79c: an uncalled definition's G55 / X-780
        // / G92.1 never runs)
        if matches!(early.body.number, Key::Label(_)) && !self.config.work_offsets.is_empty() {
            if let Some(from) = self.hold_from {
                let kept: Vec<Finding> = self
                    .found
                    .drain(from..)
                    .filter(|f| !matches!(f.placed, Placed::Offset { .. }))
                    .collect();
                self.found.extend(kept);
            }
            self.offsets_rewritten(
                early.body.at.0,
                "a jump or call the checker does not follow",
            );
        }
        self.early_on = false;
        self.work_run_on = false;
        self.work_unplaced = false;
        // (its calls made in units only assumed: kept to its end, which says whose units
        // they were made in, `call_works_ended`)
        if let Some(given) = early.given_before {
            self.machine.state.units_given |= given;
        }
        // (no subprogram after all: the offset left before is not taken for its caller's,
        // its findings under it dropped, from here none judged until its own G54-G59)
        if self.work_guessed.take().is_some() {
            self.work = None;
            if let Some(from) = self.hold_from {
                let mut i = 0;
                self.found.retain(|f| {
                    i += 1;
                    i <= from || !f.guessed
                });
            }
        } else if let (Some(from), Key::Number(n), false) =
            (self.hold_from, &early.body.number, main)
        {
            // (its own G54-G59 since: its findings under the guess held to the file's end,
            // said where a call of it is in the file, review 61a F5's second form; the
            // fuzzer's 1986, O4000 called by a later O2000 under that offset, said)
            if *n >= 0 {
                for f in self.found.iter_mut().skip(from).filter(|f| f.guessed) {
                    f.pending_on.push(super::limits::PENDING_CALLED - n);
                    self.guess_marked = Some(*n);
                }
            }
        }
        for (span, before) in self.spans.iter_mut().zip(early.stash) {
            *span = joined(before, *span);
        }
        // (a FANUC's or a Haas's program of the file, not run on into from the one before
        // with the skip switch on, is a run of its own: what the program before wrote or
        // lost is not given back to it, review 59a F3: `G52 X10.` / `M30` / `O4000` / `G21
        // G90 G55` / `G0 X-700.`, its units code merging it, was no "X goes to -800"; a
        // LinuxCNC definition's main program gets its own back)
        let own_run = self.config.family == crate::lex::Family::MacroB
            && matches!(early.body.number, Key::Number(_))
            && !early.body.after_skippable_end;
        if !own_run {
            let mut written = early.written_before;
            written.then(&self.offsets_written);
            self.offsets_written = written;
            self.g10_expression |= early.expression_before;
            self.g10_local |= early.local_before;
            self.offsets_lost |= early.lost_before;
        }
        self.hold_from = None;
    }

    /// The program in hand, read apart, is merged by a G52 (`at` its block): the positions
    /// it kept with no work offset in force before it kept for its later calls
    /// ([`Merged`]), then merged. Its positions from here are read as before.
    #[cold]
    #[inline(never)]
    pub(super) fn early_merge_keeping(&mut self) {
        if let Some(early) = self.early.as_ref().filter(|_| self.early_on) {
            if let Key::Number(number) = early.body.number {
                if early.body.unplaced.iter().any(|e| e[0].is_some())
                    && !early.body.after_skippable_end
                {
                    let merged = Merged {
                        number,
                        name: early.body.name.clone(),
                        unplaced: early.body.unplaced,
                        factor: self.to_profile_units(false),
                        read_incremental: (early.moved_first == Some(true))
                            .then_some(early.incremental),
                        said: 0,
                    };
                    self.merged_unplaced.retain(|m| m.number != number);
                    self.merged_unplaced.push(merged);
                }
            }
        }
        self.early_merge();
    }

    /// A call of program `number` (`token` at `at`) merged after it kept positions with no
    /// work offset in force ([`Merged`]): judged under the call's offset, as a returned
    /// body's are ([`Checker::unplaced_judged`]), where the call runs it under no shift, in
    /// the units and distance mode it was read in.
    #[cold]
    #[inline(never)]
    pub(super) fn merged_unplaced_judged(&mut self, number: i64, token: &str, at: (usize, usize)) {
        let Some(k) = self.merged_unplaced.iter().position(|m| m.number == number) else {
            return;
        };
        let unshifted = !self.units_unknown
            && self
                .call_shift()
                .is_some_and(|shift| shift.iter().all(|s| *s == 0.0));
        let m = &self.merged_unplaced[k];
        if !unshifted
            || self.to_profile_units(false) != m.factor
            || m.read_incremental
                .is_some_and(|read| read != self.machine.state.incremental)
        {
            return;
        }
        let mut m = self.merged_unplaced.remove(k);
        let (name, line) = (m.name.clone(), at.0);
        let under = |of: usize| {
            format!(
                " ({name} runs as called by {token} of line {line}, its position of line {of} \
                 there: a subprogram written before its call runs in the units and under the \
                 shift in force there)"
            )
        };
        self.unplaced_judged(&m.unplaced, 1.0, &mut m.said, at, &under);
        self.merged_unplaced.insert(k, m);
    }

    /// The program in hand ends (`returned`: M99) with calls made in units only assumed
    /// ([`Checker::call_works_assumed`]), merged before its end (its own units code, G52
    /// or span started again) or not: a main program's (M02/M30, the file's end, the next
    /// program begun) were made in the reset state's units (review 61a F7: `O1000` / `G10 L2
    /// P2 X-200.` / `G55` / `M98 P3000` / `M30`), a subprogram's in its caller's, not known
    /// (review 62a F12: `O3000` / `G90 G55` / `M98 P2000` / `G20` / `M99`, merged at its
    /// G20, called by a G21 main on an inch profile, kept its call as made in inches).
    #[cold]
    #[inline(never)]
    pub(super) fn call_works_ended(&mut self, returned: bool) {
        if returned {
            // (a subprogram: its calls were made in its callers' units, known where all its
            // calls are seen; review 63 F1: a metric caller on a metric profile, the call
            // made in the millimetres assumed)
            match self.in_hand {
                Some(caller) if self.early.is_none() => {
                    for (number, here) in std::mem::take(&mut self.call_works_assumed) {
                        self.call_works_deferred.push((caller, number, here));
                    }
                }
                _ => self.call_works_dropped(),
            }
        } else {
            for (number, here) in std::mem::take(&mut self.call_works_assumed) {
                self.call_work_kept(number, here);
            }
        }
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
        self.work_run_on = false;
        self.work_unplaced = false;
        self.call_works_dropped();
        if let Some(given) = early.given_before {
            self.machine.state.units_given = given;
        }
        let (mut removed, mut positions) = (Vec::new(), Vec::new());
        if let Some(from) = self.hold_from.take() {
            let mut kept = Vec::with_capacity(self.found.len() - from);
            for mut f in self.found.drain(from..) {
                // (under the offset of the program that runs on into it, skip switch on:
                // that run's, said where read whoever calls it after; review 57e F2)
                if f.guessed && early.body.after_skippable_end {
                    f.guessed = false;
                    kept.push(f);
                } else if f.rule == Rule::TravelExceeded && f.placed != Placed::Not {
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
            // (the sample machine's hint, where one of those taken out carried it, goes to
            // the first finding said after all: review 48, F17)
            self.sample_hint_taken(&mut [&mut removed, &mut positions], &mut kept);
            self.found.extend(kept);
        }
        let spans = std::mem::replace(&mut self.spans, early.stash);
        let mut writes = std::mem::replace(&mut self.offsets_written, early.written_before);
        // (a G10 whose L or P is an expression: another call may give it another value)
        let expression = std::mem::replace(&mut self.g10_expression, early.expression_before);
        self.g10_local = early.local_before;
        writes.then(&Written::on_every(expression));
        let loses = std::mem::replace(&mut self.offsets_lost, early.lost_before);
        let length = (self.machine.state.length_offset, self.length_decimal);
        let changes = early.body.changes || length != early.length_before;
        if matches!(early.body.number, Key::Label(_)) && !self.config.work_offsets.is_empty() {
            self.work = early.work_before;
        }
        self.pending.push(Pending {
            body: Body {
                writes,
                loses,
                changes,
                ..early.body
            },
            spans,
            factor: self.to_profile_units(false),
            feed_factor: self.to_profile_units(true),
            removed,
            positions,
            calls: None,
            feed_said: false,
            runs_said: false,
            read_incremental: (early.moved_first == Some(true)).then_some(early.incremental),
            ends: (self.machine.distance_codes != early.distance_codes)
                .then_some(self.machine.state.incremental),
            mode_said: false,
            ends_lost: early.lost_codes == Some(self.machine.distance_codes),
            work_guessed: self.work_guessed.take(),
            unplaced_said: 0,
        });
    }

    /// The findings held for the program read apart are more than [`HOLD_MAX`] of its
    /// limits' (`all` false) or [`HOLD_ALL`] of any rule (`all`): it is read as before from
    /// here (its findings said), and a later call of it noted, naming that bound.
    #[cold]
    #[inline(never)]
    pub(super) fn early_unhold(&mut self, all: bool) {
        self.call_works_dropped();
        if let Some(early) = self.early.as_ref() {
            if !self.given_up.iter().any(|g| g.number == early.body.number) {
                self.given_up.push(GivenUp {
                    number: early.body.number.clone(),
                    name: early.body.name.clone(),
                    at: early.body.at,
                    all,
                });
            }
        }
        self.early_merge();
    }

    /// A program begins (`starting`): the calls deferred at a merged subprogram's M99
    /// ([`Checker::call_works_deferred`]) whose caller's calls are all seen in units known
    /// are kept where those are the units assumed (the reset state's), not known where not;
    /// those of the program beginning, still not resolved, not known.
    #[cold]
    #[inline(never)]
    pub(super) fn call_works_resolved(&mut self, starting: Option<i64>) {
        let assumed = self.config.modal.default_units;
        for (caller, number, here) in std::mem::take(&mut self.call_works_deferred) {
            match self.call_units.get(&caller) {
                Some(Some((units, _, _))) if *units == assumed => {
                    self.call_work_kept(number, here);
                }
                Some(_) => {
                    self.call_works_unknown.insert(number);
                    self.call_work_kept(number, None);
                }
                None if Some(number) == starting => {
                    self.call_works_unknown.insert(number);
                    self.call_work_kept(number, None);
                }
                None => self.call_works_deferred.push((caller, number, here)),
            }
        }
    }

    /// The calls of a program read apart in units only assumed ([`Checker::call_works_assumed`])
    /// whose units are not known: it returned (a subprogram's units are its caller's) or
    /// was given up.
    pub(super) fn call_works_dropped(&mut self) {
        for (number, _) in std::mem::take(&mut self.call_works_assumed) {
            self.call_works_unknown.insert(number);
            self.call_work_kept(number, None);
        }
    }

    /// A limit's finding in a program read apart (TG601, TG602, TG605, selected or not): held
    /// from the first, so that the findings are said in the order they came, and counted:
    /// past [`HOLD_MAX`] the program is read as before from here (review 43, finding B: the
    /// bound counted where a finding is held, not where the findings are taken, so the CLI,
    /// the Python API and any chunk boundary or selection give the same findings).
    #[inline]
    pub(super) fn early_hold(&mut self) {
        if self.early_on {
            self.early_held();
        }
    }

    #[cold]
    #[inline(never)]
    fn early_held(&mut self) {
        let reports = self.reports;
        let early = self.early.as_mut().expect("early_on");
        if self.hold_from.is_none() {
            self.hold_from = Some(self.found.len());
            early.reports_from = reports;
        }
        early.held += 1;
        if early.held > HOLD_MAX {
            self.early_unhold(false);
        }
    }

    /// A finding while a program's findings are held ([`Checker::report`]): past
    /// [`HOLD_ALL`] findings of any rule since the hold began (selected or not), the program
    /// is read as before from here, so that memory stays flat whatever follows its first
    /// limit finding.
    #[cold]
    #[inline(never)]
    pub(super) fn early_reported(&mut self) {
        if self
            .early
            .as_ref()
            .is_some_and(|e| self.reports - e.reports_from > HOLD_ALL)
        {
            self.early_unhold(true);
        }
    }

    /// A G53 position (`value` of `axis`, `at` in the profile's units as read) of the
    /// program read apart: kept where it is the axis's least or most, for its calls.
    #[cold]
    #[inline(never)]
    pub(super) fn early_machine(&mut self, axis: u8, value: Dec, at: f64, line: usize) {
        let (Some(early), Some(i)) = (self.early.as_mut(), crate::modal::axis_index(axis)) else {
            return;
        };
        let new = MachineAt {
            value,
            at,
            line,
            said: false,
        };
        // (before a G90/G91 of its own: it runs in the mode of each call)
        let inherited = self.machine.distance_codes == early.distance_codes;
        let machine = if inherited {
            early.body.inherited_last = Some(line);
            &mut early.body.inherited
        } else {
            &mut early.body.machine
        };
        let [least, most] = &mut machine[i];
        if least.is_none_or(|m| at < m.at) {
            *least = Some(new);
        }
        if most.is_none_or(|m| at > m.at) {
            *most = Some(new);
        }
    }

    /// Whether the program read apart moved before a G90/G91 of its own and has written one
    /// since: its positions from then on are kept apart too ([`Absolute`]).
    #[cold]
    #[inline(never)]
    pub(super) fn early_absolute(&self) -> bool {
        self.early.as_ref().is_some_and(|e| {
            e.moved_first == Some(true) && self.machine.distance_codes != e.distance_codes
        })
    }

    /// [`Checker::add_to_span`] in a program read apart, after `at` went to the axis's
    /// span (its own): the line and column of a new least or most position kept, and the
    /// span judged with the one before it. The ends to say TG601 of, where it is wider than
    /// the travel and nothing was said of it yet (then said). `said_outside`: its machine
    /// position was said outside the travel (kept, [`Body::outside`]).
    #[cold]
    #[inline(never)]
    pub(super) fn early_span(
        &mut self,
        i: usize,
        at: f64,
        line: usize,
        column: usize,
        said_outside: bool,
    ) -> Option<(f64, f64)> {
        // (one said under the offset the program before left is dropped where no call
        // confirms it: its span is judged all the same)
        let said_outside = said_outside && self.work_guessed.is_none();
        let early = self.early.as_mut().expect("early_on");
        if said_outside {
            early.body.outside |= 1 << i;
        }
        if early.moved_first.is_none() {
            // (its first position: before a G90/G91 of its own where the machine has applied
            // none since it began)
            early.moved_first = Some(self.machine.distance_codes == early.distance_codes);
        } else if early.moved_first == Some(true)
            && self.machine.distance_codes != early.distance_codes
        {
            // (its own G90/G91 written after its first move: an axis's positions are known
            // from its first in G90)
            let a = &mut early.body.absolute;
            if a.known & (1 << i) == 0 && !self.machine.state.incremental {
                a.known |= 1 << i;
            }
            if a.known & (1 << i) != 0 {
                let span = joined(
                    a.spans[i],
                    Some(Span {
                        least: at,
                        most: at,
                        said: false,
                    }),
                )
                .expect("added");
                if span.least == at {
                    a.least_at[i] = (line, column);
                }
                if span.most == at {
                    a.most_at[i] = (line, column);
                }
                a.spans[i] = Some(span);
            }
        }
        let span = self.spans[i].as_mut().expect("added");
        if span.least == at {
            early.body.least_at[i] = (line, column);
        }
        if span.most == at {
            early.body.most_at[i] = (line, column);
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
            .and_then(|e| e.body.feed.as_ref())
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
        if mode == 93 || early.body.feed.as_ref().is_some_and(|f| f.value >= value) {
            return;
        }
        early.body.feed = Some(Feed {
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
        let Some(k) = self.pending.iter().position(|p| p.body.number == number) else {
            // (inside a program read apart: a program not read before it, itself, or one given
            // up, whose G90/G91 are not followed)
            self.early_unfollowed(&token, at.0);
            if let Some(g) = self.given_up.iter().find(|g| g.number == number) {
                // (at each call of it: review 43, finding E; the bound it passed, review 46, F6)
                let (name, line) = (g.name.clone(), g.at.0);
                let bound = if g.all {
                    format!(
                        "more than {HOLD_ALL} findings of any rule were made after its first \
                         finding of the travel and feed limits"
                    )
                } else {
                    format!("it held more than {HOLD_MAX} findings of the travel and feed limits")
                };
                let message = format!(
                    "{token} calls {name}, read from the reset state on line {line} and said \
                     as read there ({bound}): its positions and feeds were compared in the \
                     reset units, not in this call's units and under its shift"
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
                incremental: self.machine.state.incremental,
            });
        let Some(call) = call else {
            let pending = &mut self.pending[k];
            if !matches!(pending.calls, Some(Err(_))) {
                pending.calls = Some(Err(at.0));
            }
            // (inside a program read apart: its positions not added to that one's)
            self.early_unfollowed(&token, at.0);
            self.call_returns(k, &token, at.0);
            self.call_writes(k, at.0);
            return true;
        };
        let mut p = self.pending.remove(k);
        // (after the main program's first jump or inside a loop: callflow.rs)
        let flow = if self.flow_calls.is_some() {
            self.flow_judging()
        } else {
            None
        };
        self.early_judged(&mut p, &call, &token, at);
        if let Some(before) = flow {
            self.flow_judged(before);
        }
        if let Some(early) = self.early.as_mut().filter(|_| self.early_on) {
            early.body.calls_judged += 1;
        }
        if p.calls.is_none() {
            p.calls = Some(Ok(at.0));
        }
        self.pending.insert(k, p);
        self.call_returns(k, &token, at.0);
        self.call_writes(k, at.0);
        true
    }

    /// Whether a program or definition of key `number` was read before here (held for its
    /// calls, or given up).
    pub(super) fn read_before(&self, number: &Key) -> bool {
        self.pending.iter().any(|p| &p.body.number == number)
            || self.given_up.iter().any(|g| &g.number == number)
    }

    /// After a call of the subprogram `pending[k]`: the work offsets it may have written
    /// are its caller's from here ([`Checker::offsets_written`]; review 58a F1: a G10 of an
    /// O2500 the main calls after O2000 holds no position of O2000's); where it lost the
    /// profile's offsets, its caller's positions after the call on `line` are not compared
    /// as machine positions either.
    fn call_writes(&mut self, k: usize, line: usize) {
        let writes = self.pending[k].body.writes.clone();
        self.offsets_written.then(&writes);
        self.offset_writer(&writes, self.pending[k].body.loses);
        if self.pending[k].body.loses {
            let why = format!("{} changes the offsets", self.pending[k].body.name);
            self.offsets_rewritten(line, &why);
        }
        self.call_keeps = self.keeps_offsets(k);
    }

    /// Whether the subprogram `pending[k]`, read before its call, surely leaves its
    /// caller's work offsets as they were: it writes none (no G10 L2/L20, no work offset's
    /// system variable), moves no coordinates (no G52, G92, frame left or undone), selects
    /// no G54-G59 of its own (modal: the caller's after its return), leaves the tool length
    /// offset it was read in, does not end the program or return elsewhere (`M99 Pn`), and
    /// calls no program that might do any of these, or one the checker does not follow
    /// there ([`Checker::after_unsure`]). The caller's positions after the call are then
    /// judged under the offset in force as before it, its later calls included: the same
    /// subprogram called once a fixture under G54, G55, G56 is judged at each call (issue
    /// 32 item 4; review 62a F6d: only the first call was).
    pub(super) fn keeps_offsets(&self, k: usize) -> bool {
        let body = &self.pending[k].body;
        let w = &body.writes;
        !body.loses
            && !body.changes
            && !w.any()
            && w.unread.is_empty()
            && !w.moved
            && w.shifted == 0
            && w.maybe.iter().all(|m| *m == 0)
            && match body.number {
                Key::Number(n) => !self.after_unsure.contains(&n),
                Key::Label(_) => true,
            }
    }

    /// The program read apart selects a work offset or writes a work offset's variable
    /// ([`Body::changes`]).
    pub(super) fn early_changes_offsets(&mut self) {
        if let Some(early) = self.early.as_mut().filter(|_| self.early_on) {
            early.body.changes = true;
        }
    }

    /// After a call of the subprogram `pending[k]` (`token` of line `line`): where it wrote a
    /// G90/G91, its last is in force in its caller from here (G90/G91 are modal, and a
    /// FANUC's or a Haas's M99 restores none): a distance code of the caller's at the call,
    /// which a program read apart counts as its own (review 47, F1: O0002 calling O0003,
    /// whose `G90` makes its `X-900.` absolute, under a G91 call of O0002). A LinuxCNC
    /// subroutine's may be undone at its return (M73): not followed, so noted.
    fn call_returns(&mut self, k: usize, token: &str, line: usize) {
        let p = &self.pending[k];
        if matches!(p.body.number, Key::Label(_)) {
            return; // (LinuxCNC: Checker::linuxcnc_call_distance)
        }
        if p.ends_lost {
            self.call_mode_lost(token, (line, 1), &p.body.name.clone(), None);
            return;
        }
        let Some(mode) = p.ends else {
            return;
        };
        self.machine.state.incremental = mode;
        self.machine.distance_codes = self.machine.distance_codes.wrapping_add(1);
    }

    /// A FANUC's or a Haas's call (`token` at `at`) of a program the checker does not read
    /// there (`name`: written after the call, not in the file, given up, or one that calls
    /// such a program last): a G90/G91 it writes stays in force in the caller after its M99
    /// (G90/G91 are modal, and M99 restores none), so the caller's mode is not known from
    /// here until it writes its own G90/G91. Taken as G91 from a position not known (the
    /// call forgot the position): no position is judged as absolute until then; one TG140 a
    /// file says so (review 48, F11).
    #[cold]
    #[inline(never)]
    pub(super) fn call_mode_lost(
        &mut self,
        token: &str,
        (line, column): (usize, usize),
        name: &str,
        by: Option<i64>,
    ) {
        // (a FANUC or Haas lathe of G code system A has no G90/G91 mode: its G90 is the
        // turning cycle, its increments U and W)
        if self.machine.settings.own_motion(90) {
            return;
        }
        if self.mode_lost_codes != Some(self.machine.distance_codes) {
            self.mode_lost_by.clear();
        }
        self.mode_lost_by.push(by.unwrap_or(i64::MIN));
        self.machine.state.incremental = true;
        self.flow_modes_lost();
        // (LinuxCNC: the main program's; a body's own mode is its own, review 50, F7)
        if self.open_definition.is_none() {
            self.linuxcnc_distance_unsure = true;
            self.linuxcnc_distance_from = None;
        }
        self.mode_lost_codes = Some(self.machine.distance_codes);
        if let Some(early) = self.early.as_mut().filter(|_| self.early_on) {
            early.lost_codes = Some(self.machine.distance_codes);
        }
        if self.noted & super::limits::MODE_LOST_NOTED != 0 {
            return;
        }
        self.noted |= super::limits::MODE_LOST_NOTED;
        let message = if self.config.family == crate::lex::Family::LinuxCnc {
            format!(
                "{token} runs {name}, whose G90/G91 after its return the checker does not know \
                 (it writes one inside a condition or loop of its own, returns in one mode at \
                 one return and in another at the next, restores with M72 or at its return a \
                 state M70 or M73 saved where that was not known, writes a G or M code by a \
                 parameter, or calls a subroutine the checker does not follow there; or the \
                 call is inside a condition or loop, may not run, and its body returns in \
                 another mode than the one in force): the positions after this call are not \
                 compared with the travel (TG601) until a G90 or G91 is written again (said \
                 once a file)"
            )
        } else {
            format!(
                "{token} runs {name}, whose G90/G91 the checker does not know here (a program \
             written after its call or not in the file, or one that calls such a program): a \
             G90 or G91 it writes stays in force after its M99 (G90/G91 are modal and M99 \
             restores none), so the positions after this call are not compared with the travel \
             (TG601) until a G90 or G91 is written again (said once a file)"
            )
        };
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// Whether a call here runs a body read under the offset `guessed` (the one the program
    /// before it left) under that same offset: its machine positions are then those read.
    fn work_confirms(&self, guessed: Option<i64>) -> bool {
        guessed.is_some() && self.work == guessed
    }

    /// At the file's end: a position said at a call after its caller called programs the
    /// checker had not read there ([`Finding::pending_on`]) is dropped where one of them,
    /// read later in the file, writes that offset's axis (its value there not known at the
    /// call: held, as a G10 of a program read before holds it); said where none does (a
    /// program the file does not hold writes nothing followed).
    pub(super) fn pending_on_ended(&mut self) {
        if self.found.iter().all(|f| f.pending_on.is_empty()) {
            return;
        }
        let found = std::mem::take(&mut self.found);
        for mut f in found {
            let mut numbers = std::mem::take(&mut f.pending_on);
            // (a span across a call of a program not read there: crate::check::leaves)
            let leaves = |n: i64| n <= super::leaves::PENDING_LEAVES;
            if numbers.iter().any(|&n| leaves(n)) {
                if !numbers
                    .iter()
                    .filter(|&&n| leaves(n))
                    .all(|&n| self.later_span_judged(n, &mut f))
                {
                    continue;
                }
                numbers.retain(|&n| !leaves(n));
                if numbers.is_empty() {
                    self.found.push(f);
                    continue;
                }
            }
            // (a position under a subprogram's own offset after its own units code: judged
            // with the value its callers' G10 wrote before every call, review 60 F4)
            if numbers
                .iter()
                .any(|&n| n <= super::limits::PENDING_CALLS_WRITTEN)
            {
                let Some(f2) = self.calls_rejudged(f, &numbers) else {
                    continue;
                };
                f = f2;
                numbers.retain(|&n| n > super::limits::PENDING_CALLS_WRITTEN);
                if numbers.is_empty() {
                    self.found.push(f);
                    continue;
                }
            }
            // (a guessed position of a program no call names, review 61a F5's second form)
            if numbers.iter().any(|&n| n <= super::limits::PENDING_CALLED) {
                let called = |n: i64| self.call_numbers_any || self.call_numbers.contains(&n);
                if numbers.iter().any(|&n| {
                    n <= super::limits::PENDING_CALLED && !called(super::limits::PENDING_CALLED - n)
                }) {
                    continue;
                }
                numbers.retain(|&n| n > super::limits::PENDING_CALLED);
                if numbers.is_empty() {
                    self.found.push(f);
                    continue;
                }
            }
            // (a position of the program's own after calls not read there: held unless
            // each is a program of the file, read, that lost no offsets; review 61a F13)
            if numbers.contains(&super::limits::PENDING_OWN)
                && !numbers
                    .iter()
                    .filter(|&&n| n != super::limits::PENDING_OWN)
                    .all(|&n| self.read_keeping(n, &mut Vec::new()))
            {
                continue;
            }
            let Some((place, work, at, line)) = f.placed.offset() else {
                self.found.push(f);
                continue;
            };
            match self.written_later(&numbers, usize::from(work), usize::from(place)) {
                // (none of them writes that offset's axis: as said)
                None => self.found.push(f),
                Some(values) if values.iter().any(|v| v.0.is_nan()) => {}
                Some(values) => {
                    // (the values it may have, a G10 that may not run: held where one puts the
                    // position inside the travel, else judged with the one that puts it
                    // least far out, as read where that is the profile's; review 60 F1)
                    let Some((low, high)) = self.travel.of_place(usize::from(place)) else {
                        continue;
                    };
                    let out = |v: f64| (low - (at + v)).max(at + v - high).max(0.0);
                    if values.iter().any(|&(v, _)| out(v) <= 1e-9) {
                        continue;
                    }
                    let least = values.iter().min_by(|a, b| out(a.0).total_cmp(&out(b.0)));
                    let Some(&(value, true)) = least else {
                        self.found.push(f);
                        continue;
                    };
                    // (the message's tail, naming the call, kept)
                    let tail = self
                        .travel
                        .of_place(usize::from(place))
                        .and_then(|(low, high)| {
                            let range = format!("outside the travel {low} to {high}");
                            let k = f.message.find(&range)? + range.len();
                            // (naming the excursion's farthest position, judged)
                            Some(farthest_named(&f.message[k..], line))
                        });
                    let Some(tail) = tail else {
                        self.found.push(f);
                        continue;
                    };
                    // (a position of the caller's own, on a line that is no call and a
                    // message naming none: "before it", review 62a F13; one said at a call
                    // or naming the call it runs as called by, "before this call")
                    let before = if tail.contains(" as called by ") {
                        "this call"
                    } else {
                        "it"
                    };
                    let judged =
                        self.rejudged(&f, (place, work, at, value), before, &|_| tail.clone());
                    self.found.extend(judged);
                }
            }
        }
    }

    /// A finding `f` marked [`super::limits::PENDING_CALLS_WRITTEN`] (`marks`): where every
    /// call of its program was made after a G10 of the same value on its offset's axis,
    /// judged again with it (None where within the travel, or where the value is not known);
    /// else as said.
    fn calls_rejudged(&self, f: Finding, marks: &[i64]) -> Option<Finding> {
        let Some((place, work, at, line)) = f.placed.offset() else {
            return Some(f);
        };
        let (w, i) = (usize::from(work), usize::from(place));
        let (low, high) = self.travel.of_place(i)?;
        let mut value = None;
        for &m in marks
            .iter()
            .filter(|&&m| m <= super::limits::PENDING_CALLS_WRITTEN)
        {
            let n = super::limits::PENDING_CALLS_WRITTEN - m;
            let Some((written, unread)) = self.calls_written(n, w, i) else {
                continue;
            };
            // (a program written later, called before: the value it leaves, review 60 F4's
            // q1; several values, one putting the position inside: not said)
            let later = (!unread.is_empty())
                .then(|| self.written_later(&unread, w, i))
                .flatten();
            value = match (later, written) {
                (Some(values), _) if values.iter().any(|v| v.0.is_nan()) => Some(f64::NAN),
                (Some(values), _) if values.len() == 1 && values[0].1 => Some(values[0].0),
                (Some(values), _) => {
                    let inside = |v: f64| (low - 1e-9..=high + 1e-9).contains(&(at + v));
                    if values.iter().any(|&(v, _)| inside(v)) {
                        Some(f64::NAN)
                    } else {
                        written
                    }
                }
                (None, written) => written,
            }
            .or(value);
        }
        let Some(value) = value else {
            return Some(f);
        };
        if value.is_nan() {
            return None;
        }
        let range = format!("outside the travel {low} to {high}");
        let mut tail = f
            .message
            .find(&range)
            .map(|k| farthest_named(&f.message[k + range.len()..], line))?;
        // (the excursion's farthest position, which the value judges, on another line than
        // its first, the finding's: named, review 63 F5)
        if line != f.line && !tail.contains("its position of line ") {
            tail = format!(" (its farthest position there, of line {line}){tail}");
        }
        self.rejudged(&f, (place, work, at, value), "its call", &|_| tail.clone())
    }

    /// The value offset G`work` (54-59) has on the axis of place `place` after the programs
    /// `numbers` ran, called in that order where the checker had not read them
    /// ([`Finding::pending_on`]): None where none writes it (the profile's holds), NaN where
    /// one writes it a value not known or moves the coordinates too (a G52, G92 or frame:
    /// the position is no longer work plus offset), or calls a program that writes it (its
    /// order not followed); else the value the last writes. A G52 or G92 left on by a
    /// program that writes no offset is not followed, as before (review 59a F10, c11: said,
    /// erring on the side of the alarm) (review 59a F1: a literal `G10 L2
    /// P2 X-200.` of an O100 written after the main that calls it before the call of O2000
    /// runs O2000's `X-700.` at -900, as the same O100 written before the main does).
    /// Where the last write of one may not have run ([`Written::maybe`]), the values it may
    /// have (each with whether a G10 wrote it, false for the profile's): review 60 F1.
    fn written_later(
        &self,
        numbers: &[i64],
        work: usize,
        place: usize,
    ) -> Option<Vec<(f64, bool)>> {
        let writers = &self.offset_writers;
        let mut values: Option<Vec<(f64, bool)>> = None;
        for n in numbers {
            let Some((w, _)) = writers.get(n) else {
                continue;
            };
            let mut seen = vec![*n];
            let own = w.value(work, place);
            if own.is_some() && (w.moved || w.shifted & 1 << place != 0)
                || w.unread
                    .iter()
                    .any(|m| self.touches(*m, (work, place), &mut seen))
            {
                return Some(vec![(f64::NAN, true)]);
            }
            if let Some((before, alt)) = w.maybe_of(work, place) {
                let mut now = if before.is_nan() {
                    values.take().unwrap_or_else(|| {
                        let profile = self
                            .config
                            .work_offsets
                            .iter()
                            .find(|&&(g, a, _)| g == work as i64 && a == AXES[place])
                            .map_or(f64::NAN, |&(_, _, v)| v.to_f64());
                        vec![(profile, false)]
                    })
                } else {
                    vec![(before, true)]
                };
                now.push((alt, true));
                values = Some(now);
            } else if let Some(value) = own {
                values = Some(vec![(value, true)]);
            }
        }
        values
    }

    /// Whether the program `n` is one of the file, read, that lost no offsets (a G52, G92,
    /// frame, G10 of a value not known), nor calls one that is not so (through any depth;
    /// `seen`: those looked at).
    fn read_keeping(&self, n: i64, seen: &mut Vec<i64>) -> bool {
        if seen.contains(&n) {
            return true;
        }
        seen.push(n);
        self.file_programs.contains(&n)
            // (review 62a F1-F4)
            && !self.after_unsure.contains(&n)
            && self.offset_writers.get(&n).is_none_or(|(w, loses)| {
                !loses
                    && !w.moved
                    && w.shifted == 0
                    && w.unread.iter().all(|&m| self.read_keeping(m, seen))
            })
    }

    /// Whether the program `n` of the file, or one it calls not read there (through any
    /// depth; `seen`: those looked at), writes offset G`work`'s axis of place `place`
    /// (review 59a F10, c12: a G10 three calls deep).
    fn touches(&self, n: i64, (work, place): (usize, usize), seen: &mut Vec<i64>) -> bool {
        if seen.contains(&n) {
            return false;
        }
        seen.push(n);
        self.offset_writers.get(&n).is_some_and(|(w, _)| {
            w.value(work, place).is_some()
                || w.unread
                    .iter()
                    .any(|&m| self.touches(m, (work, place), seen))
        })
    }

    /// How a body's machine position under a work offset (not a G53 one), read with the
    /// profile's offsets, stands at a call here, where a G10 ran in the caller before the
    /// call (its own, or one of a program it called: [`Checker::offsets_written`]). Where
    /// it wrote that offset's value on that axis with a value known (a G10 L2 of numbers
    /// under G90), the position is judged again with it (review 58d F9: `G10 L2 P2 X-200.`
    /// / `G90 G55` / `M98 P2000` runs O2000's `X-700.` at -900); where with a value not
    /// known it may stand elsewhere: kept, not said (review 57e F1); a write of another
    /// offset or axis, or of a tool offset, changes nothing (review 58a F3).
    fn offset_now(&self, f: &Finding) -> Now {
        if !self.offsets_written.any() && self.offsets_written.shifted == 0 {
            return Now::AsRead;
        }
        match f.placed {
            // (a G52 or G92 of the caller's run moved that axis's zero by an amount not
            // known to be zero: review 60 F5)
            Placed::Offset { place, .. } if self.offsets_written.shifted & 1 << place != 0 => {
                Now::Unknown
            }
            Placed::Offset {
                place, work, at, ..
            } => {
                match self
                    .offsets_written
                    .value(usize::from(work), usize::from(place))
                {
                    None => Now::AsRead,
                    Some(v) if v.is_nan() => Now::Unknown,
                    Some(v) => Now::Written(place, work, at, v),
                }
            }
            Placed::Machine => Now::AsRead,
            Placed::Not => Now::Unknown,
        }
    }

    /// A body's position `f` under offset G`work` (axis of place `place`, work position
    /// `at`, the profile's units) judged at a call with the value `value` a G10 before it
    /// wrote (`under`: the message's tail naming the call): Some(its finding there) where
    /// out of the travel, None where within.
    fn rejudged(
        &self,
        f: &Finding,
        (place, work, at, value): (u8, u8, f64, f64),
        before: &str,
        under: &dyn Fn(usize) -> String,
    ) -> Option<Finding> {
        let i = usize::from(place);
        let (low, high) = self.travel.of_place(i)?;
        // (the excursion's farthest position's line: limits.rs, excursion_farther)
        let line = match f.placed {
            Placed::Offset { line, .. } => line,
            _ => f.line,
        };
        let machine_at = at + value;
        if (low - 1e-9..=high + 1e-9).contains(&machine_at) {
            return None;
        }
        let message = format!(
            "{} goes to {} in machine coordinates (work {} + G{work} offset {} as a G10 before \
             {before} wrote it), outside the travel {low} to {high}{}",
            AXES[i] as char,
            super::round6(machine_at),
            super::round6(at),
            super::round6(value),
            under(line)
        );
        Some(Finding {
            message,
            ..f.clone()
        })
    }

    /// Inside a program read apart: a call by another word than a program number (a Haas's
    /// M97 of a sequence), which the checker does not follow ([`Checker::early_unfollowed`]).
    #[cold]
    #[inline(never)]
    pub(super) fn early_call_unread(&mut self, b: &super::BlockView<'_>) {
        let word = |letter: u8| {
            b.words
                .iter()
                .find(|w| w.letter == letter && w.index.is_empty())
        };
        let token = match (
            b.words
                .iter()
                .find(|w| w.letter == b'M' && w.number == b"97"),
            word(b'P'),
        ) {
            (Some(m), Some(p)) => format!("{} {}", m.token(), p.token()),
            (m, _) => m
                .or(b.words.first())
                .map_or_else(String::new, |w| w.token()),
        };
        // (a Haas's M97 runs the blocks of the program in hand from the sequence number its
        // P gives to an M99, a local subprogram call: no other program; review 48, F18)
        let m97 = b
            .words
            .iter()
            .any(|w| w.letter == b'M' && w.number == b"97");
        let local = word(b'P').filter(|_| m97).map(|p| {
            let sequence = match p.value {
                Some(n) if p.expression.is_empty() && p.sign.is_empty() && !p.point => {
                    format!("N{n}")
                }
                _ => "the sequence number its P gives".to_string(),
            };
            let name = self.early.as_ref().map_or("", |e| e.body.name.as_str());
            format!("{name}'s from {sequence} to an M99")
        });
        self.early_unfollowed_by(&token, b.line, local);
    }

    /// Inside a program read apart: a call (`token` of line `line`) whose program's G90/G91
    /// the checker does not follow, kept (the first) for the wording of that program's TG140
    /// at a call under the other mode.
    fn early_unfollowed(&mut self, token: &str, line: usize) {
        self.early_unfollowed_by(token, line, None);
    }

    /// A call (any the dialect knows) in the program read apart: kept, so that where no
    /// call names that program its span is still joined to the file's
    /// ([`Checker::early_as_read`]).
    #[cold]
    #[inline(never)]
    pub(super) fn early_calls(&mut self) {
        if let Some(early) = self.early.as_mut().filter(|_| self.early_on) {
            early.body.calls += 1;
        }
    }

    /// [`Checker::early_unfollowed`], of a Haas's M97 the blocks it runs (`local`).
    fn early_unfollowed_by(&mut self, token: &str, line: usize, local: Option<String>) {
        if let Some(early) = self.early.as_mut().filter(|_| self.early_on) {
            if early.body.unfollowed.is_none() {
                early.body.unfollowed = Some((token.to_string(), line, local));
            }
        }
    }

    /// A call inside a program read apart of the subprogram `p` (at `at`, `r` times the units
    /// it was read in, under `shift`), after its positions went to that one's spans: those
    /// `p` reaches whatever the mode of its call -- each one where it wrote its G90/G91
    /// before it moved, else those from its own G90 on ([`Absolute`]) -- are where they are
    /// at every call of the program read apart too, kept with its own from its G90 on where
    /// it moved before any (review 47, F1); and `p`'s calls not followed are that one's.
    fn early_nested(&mut self, p: &Pending, r: f64, shift: &[f64; 9], at: (usize, usize)) {
        let early = self.early.as_mut().expect("early_on");
        if early.body.unfollowed.is_none() {
            early.body.unfollowed.clone_from(&p.body.unfollowed);
        }
        if early.moved_first != Some(true) {
            return;
        }
        let spans = if p.read_incremental.is_none() {
            &p.spans
        } else {
            &p.body.absolute.spans
        };
        let a = &mut early.body.absolute;
        for (i, span) in spans.iter().enumerate() {
            let Some(span) = span else {
                continue;
            };
            if self.travel.of_place(i).is_none() {
                continue;
            }
            for at_ in [span.least * r + shift[i], span.most * r + shift[i]] {
                let point = Span {
                    least: at_,
                    most: at_,
                    said: false,
                };
                let all = joined(a.spans[i], Some(point)).expect("added");
                if all.least == at_ {
                    a.least_at[i] = at;
                }
                if all.most == at_ {
                    a.most_at[i] = at;
                }
                a.spans[i] = Some(all);
            }
        }
    }

    /// LinuxCNC: an `o<name> sub` opens a definition in the main program (`name` its label,
    /// `shown` as written, its statement at `at`). rs274 reads the body without running it, and runs it where
    /// an `o<name> call` calls it, in the units and under the G92/G52 shift in force there
    /// (review 41, finding 4): read apart as a FANUC's subprogram before its call is, its
    /// units as not written.
    #[cold]
    #[inline(never)]
    pub(super) fn definition_begin(&mut self, name: &[u8], shown: &[u8], at: (usize, usize)) {
        if self.early_on {
            return;
        }
        let given = self.machine.state.units_given;
        let written = String::from_utf8_lossy(shown).into_owned();
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
            // (rs274 reads a definition without running it: the main program's lines after
            // its endsub run in the distance mode from before its sub, as the feed mode)
            let before = self
                .early
                .as_ref()
                .map(|e| (e.incremental, e.distance_codes));
            self.early_pend();
            if let (Some((incremental, codes)), false) = (before, self.early_on) {
                self.machine.state.incremental = incremental;
                self.machine.distance_codes = codes;
            }
        } else if self.config.family == crate::lex::Family::LinuxCnc {
            // (a body not read apart: the same, from its sub)
            let (incremental, codes) = self.linuxcnc_body_distance.before;
            self.machine.state.incremental = incremental;
            self.machine.distance_codes = codes;
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
        self.early_unfollowed(&token, line);
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
            let judged = p.body.feed.is_some() && self.config.feed_max.is_some()
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
                        p.body.name
                    );
                    self.report(Rule::NotFollowed, message, p.body.at.0, p.body.at.1);
                }
            }
        }
    }

    /// A subprogram no call of the file names (it ends in M99: after a main program's M30, a
    /// subprogram called from another file or by hand): its own findings said, as read from
    /// the reset state. Nothing in the file runs it, so where it stands under a work offset
    /// is its caller's, not known here: a FANUC's M30 ends the main program and goes back to
    /// the program's head (0i-F Operator's Manual, miscellaneous functions, M30), and its M99
    /// returns to whoever called it; its span is judged alone (review 55b, F4: `G0 X850.` /
    /// `M30` / `O2000` / `G0 X-700.` / `M99` was "X spans 1550"). Only where that is sure to
    /// lose no error ([`Checker::judged_alone`]); elsewhere its span is joined to the file's,
    /// as before.
    fn early_as_read(&mut self, mut p: Pending) {
        // (a LinuxCNC definition no call of the file names never runs from this file (rs274
        // reads it without running it): its positions under a work offset it selects itself
        // are not said, as before a definition was read with no offset; review 76-calls76 F5)
        if matches!(p.body.number, Key::Label(_)) {
            p.positions
                .retain(|f| !matches!(f.placed, Placed::Offset { .. }));
        }
        if !self.judged_alone(&p) {
            // (joined for its own calls only, nothing of the file runs it: its positions read
            // under the offset the program before left are not its caller's, review 57e F0)
            let guessed_kept = self.main_may_run(&p);
            let positions = p
                .positions
                .into_iter()
                .filter(|f| guessed_kept || !f.guessed);
            for mut f in p.removed.into_iter().chain(positions) {
                self.sample_hint_shown(&mut f);
                self.found.push(f);
            }
            for i in 0..AXES.len() {
                let Some(span) = p.spans[i] else {
                    continue;
                };
                if span.said || self.travel.of_place(i).is_none() {
                    self.spans[i] = joined(self.spans[i], Some(span));
                    continue;
                }
                let (l, m) = (p.body.least_at[i], p.body.most_at[i]);
                self.add_to_span(i, span.least, false, l.0, || l.1, "");
                self.add_to_span(i, span.most, false, m.0, || m.1, "");
            }
            return;
        }
        // (its spans' findings, made with the spans of the programs before it, are judged
        // again with its own alone: said where the axis's travel is less than its own span,
        // and not where its machine positions already said more: review 56b, F3)
        // (and not its positions under the offset the program before left: its caller's is
        // not known)
        let mut said: Vec<Finding> = p
            .removed
            .into_iter()
            .filter(|f| !f.span)
            .chain(p.positions.into_iter().filter(|f| !f.guessed))
            .collect();
        let from = self.found.len();
        // (one that moved before a G90/G91 of its own runs those moves in its caller's mode,
        // not known: G91 makes them increments from where the caller left it. Its positions
        // are known from its own G90 on, as at a call in the other mode (review 56b, F10:
        // `O2000` / `G0 X-700.` / `G90 G0 X850.` / `M99` is no "X spans 1550")). Not one that
        // calls programs: its span holds theirs read in G90, as the span of one that calls a
        // program written after it is joined to the file's in G90 (review 56b, F4: y1.nc's
        // error kept, and the same programs in the other order, y2.nc, keep theirs). Nor on a
        // lathe of G code system A, which has no G90/G91 mode (its G90 a turning cycle, its
        // increments U and W): its X and Z are absolute whoever calls it (not on system B or
        // C, whose G90/G91 are absolute/incremental: review 57c, F3)
        let positions_known = p.read_incremental.is_none()
            || p.body.calls > 0
            || p.body.first && !self.main_ended && self.file_programs.len() <= 1
            || (self.machine.settings.own_motion(90)
                && self.machine.settings.g_system == crate::lex::GCodeSystem::A);
        let (spans, least_at, most_at) = if positions_known {
            (&p.spans, &p.body.least_at, &p.body.most_at)
        } else {
            (
                &p.body.absolute.spans,
                &p.body.absolute.least_at,
                &p.body.absolute.most_at,
            )
        };
        for (i, &axis) in AXES.iter().enumerate() {
            let (Some(span), Some((low, high))) = (spans[i], self.travel.of_place(i)) else {
                continue;
            };
            let said = p.body.outside & (1 << i) != 0;
            if !said && span.most - span.least > (high - low) + 1e-9 {
                let (l, m) = (least_at[i], most_at[i]);
                let at = if l.0 >= m.0 { l } else { m };
                // (read with no units code of its own, in the units it began in: where those
                // are the profile's inches and millimetres would fit, the remark says so)
                let fits = (span.most - span.least) / 25.4 <= high - low + 1e-9;
                let units = if fits
                    && p.factor == 1.0
                    && self.config.limit_units == crate::modal::Units::Inch
                {
                    self.units_remark()
                } else {
                    String::new()
                };
                let ends = (span.least, span.most);
                self.span_said(axis, ends, (low, high), at, "", &units);
            }
        }
        said.extend(self.found.drain(from..));
        said.sort_by_key(|f| (f.line, f.column));
        for mut f in said {
            self.sample_hint_shown(&mut f);
            self.found.push(f);
        }
    }

    /// Whether a subprogram no call of the file names is judged on its own span
    /// ([`Checker::early_as_read`]), where that cannot lose an overtravel its run makes: each
    /// program it calls was read before it and judged into its span at the call, so its own
    /// span is that of its run, callees and all (review 56e, F2); a program it runs that is
    /// written after it is judged with the file's span, not its own, so such a caller is
    /// joined to the file's (review 56b, F4); no call of the file may name it under another
    /// program-number option (`M98 P12000` is O2000 on a FANUC without the 8-digit option,
    /// `M198 P2000` may run the file's O2000 from a memory card: F1,
    /// [`Checker::call_numbers_seen`]); and it is not numbered O9000-O9999, the programs a
    /// FANUC runs for an M, G or T code its parameters name (0i-F Operator's Manual, custom
    /// macro: "Macro call with a G/M code", "Subprogram call with an M/T code", O9001-O9029)
    /// and a Haas for its aliased M and G codes (O9000-O9019): a call the file does not write
    /// (F2). Nor where the file holds such a program (an M06 of the subprogram may run it:
    /// review 56e, F1), or a call names a program the file does not hold (stored on the
    /// control, it may run this one: F5), or the end before it is one the block skip passes
    /// over (`/M30`: with the switch on, the main runs on into it; F4).
    fn judged_alone(&self, p: &Pending) -> bool {
        p.body.calls <= p.body.calls_judged
            && p.body.unfollowed.is_none()
            && self.file_programs.range(9000..=9999).next().is_none()
            && !self.may_run_here(p)
    }

    /// Whether something of the file may run the uncalled program `p` after all, under the
    /// offset in force there ([`Checker::judged_alone`]'s reasons but its own calls and an
    /// O9000-O9999 of the file, which its own M06 may run, not it: review 57e F0's jx3.nc):
    /// the end before it skipped, a call of a program the file does not hold or with a P
    /// the checker does not match, or its own number O9000-O9999 (an M, G or T code of the
    /// main may run it).
    fn may_run_here(&self, p: &Pending) -> bool {
        p.body.after_skippable_end
            || self
                .call_numbers
                .iter()
                .any(|n| !self.file_programs.contains(n))
            || self.number_may_be_run(p)
    }

    /// Whether `p`'s own number may have something of the file run it: O9000-O9999 (an M, G
    /// or T code of the main may run it), or a number a call names or a call whose P the
    /// checker does not match may name ([`Checker::may_run_here`], [`Checker::main_may_run`]).
    fn number_may_be_run(&self, p: &Pending) -> bool {
        match p.body.number {
            Key::Number(n) => {
                (9000..=9999).contains(&n)
                    || self.call_numbers_any
                    || self.call_numbers.contains(&n)
            }
            Key::Label(_) => false,
        }
    }

    /// Whether the main's run may run the uncalled program `p` under the offset it left (its
    /// positions read under that offset kept: [`Checker::early_as_read`]):
    /// [`Checker::may_run_here`], but for a call of a program the file does not hold made
    /// only where the main's run does not reach, in `p` itself, in a program only `p` calls
    /// or in another uncalled one: a stored program called there runs under the offset of
    /// that program's caller, not the main's (review 58a F2: an uncalled O2000's own `M98
    /// P8000` kept its `X-700.` under the main's G55, "X goes to -800").
    fn main_may_run(&self, p: &Pending) -> bool {
        let stored_call_reached = || {
            // (the programs the main's run reaches: the first and those called from them)
            let mut reached: std::collections::BTreeSet<Option<i64>> = [self.first_number].into();
            loop {
                let more: Vec<Option<i64>> = self
                    .call_sites
                    .iter()
                    .filter(|(caller, n)| {
                        reached.contains(caller)
                            && self.file_programs.contains(n)
                            && !reached.contains(&Some(*n))
                    })
                    .map(|&(_, n)| Some(n))
                    .collect();
                if more.is_empty() {
                    break;
                }
                reached.extend(more);
            }
            self.call_sites
                .iter()
                .any(|(caller, n)| reached.contains(caller) && !self.file_programs.contains(n))
        };
        p.body.after_skippable_end || self.number_may_be_run(p) || stored_call_reached()
    }

    /// A subprogram at a call made in known units and under a known shift: its span (least
    /// and most position) in them, and its largest feed, judged with the spans as they are
    /// here (said at the call, naming the body's line); its machine positions' findings said
    /// at its first call where the units are those it was read in or larger, and its G53
    /// positions' least and most judged in the call's units ([`Checker::early_machine_judged`]).
    /// A body whose first position comes before a G90/G91 of its own, called in the other
    /// mode, has positions not known there: one TG140 says so, its feed judged all the same
    /// (review 43, finding D), and its G53 positions but for those before its own G90/G91 at
    /// a G91 call (a G53 under G91, not judged: [`Checker::machine_incremental_call`]; review
    /// 46, F3).
    fn early_judged(&mut self, p: &mut Pending, call: &Call, token: &str, at: (usize, usize)) {
        let r = call.factor / p.factor;
        // (the units the call runs it in, where they are not those it was read in: the
        // profile's where its factor is 1)
        let units = match (call.factor == 1.0, self.config.limit_units) {
            _ if call.factor == p.factor => "",
            (true, crate::modal::Units::Metric) | (false, crate::modal::Units::Inch) => {
                " in millimetres"
            }
            _ => " in inches",
        };
        let (line, column) = at;
        let name = p.body.name.clone();
        let under_at = |what: &str| {
            format!(
                " ({name} runs{units} as called by {token} of line {line}, its {what} there: a \
                 subprogram written before its call runs in the units and under the shift in \
                 force there)"
            )
        };
        let under = |of: usize| under_at(&format!("position of line {of}"));
        // (a body whose G90/G91 code comes before its first move, the code written by a
        // program it calls too, read apart: the caller's positions from the call on follow
        // it, Checker::call_returns; a LinuxCNC subroutine's mode may be restored at its
        // return)
        if self.early_on
            && p.read_incremental.is_none()
            && p.ends.is_some()
            && matches!(p.body.number, Key::Number(_))
        {
            self.machine.distance_codes = self.machine.distance_codes.wrapping_add(1);
        }
        // (G90/G91 are modal and a call changes none: a body that moves before writing its
        // own runs its positions in the call's mode)
        let known = p
            .read_incremental
            .is_none_or(|read| read == call.incremental);
        let shift = call.shift.unwrap_or([0.0; 9]);
        // (where its positions are not known at this call, those from its own G90 on are
        // where they are whatever the call's mode)
        let (spans, least_at, most_at) = if known {
            (&p.spans, &p.body.least_at, &p.body.most_at)
        } else {
            (
                &p.body.absolute.spans,
                &p.body.absolute.least_at,
                &p.body.absolute.most_at,
            )
        };
        for (i, shift) in shift.into_iter().enumerate() {
            let Some(span) = spans[i] else {
                continue;
            };
            if self.travel.of_place(i).is_none() {
                continue;
            }
            let (l, m) = (least_at[i].0, most_at[i].0);
            let least = span.least * r + shift;
            self.add_to_span(i, least, false, line, || column, &under(l));
            // (where its least is an end of the span, its most's finding names both: review
            // 46, F5, a lathe body's X-25. of line 4 made the span wide, not its X6. of line 5)
            let both = l != m && self.spans[i].is_some_and(|s| s.least == least);
            let most = if both {
                under_at(&format!("positions of lines {l} and {m}"))
            } else {
                under(m)
            };
            self.add_to_span(i, span.most * r + shift, false, line, || column, &most);
        }
        if self.early_on {
            self.early_nested(p, r, &shift, at);
            // (its positions read with no work offset in force run, in a program read apart
            // with none in force either, under that one's caller's: kept with its own, in
            // the same units and mode and under no shift; review 62a F6b: `O4000` / `G0
            // X-780.` / `M99` / `O3000` / `M98 P4000` / `M99`, O3000 called under G55, runs
            // X-780. at -880)
            if self.work_unplaced
                && known
                && call.shift.is_some_and(|s| s.iter().all(|v| *v == 0.0))
            {
                for i in 0..AXES.len() {
                    for u in p.body.unplaced[i].into_iter().flatten() {
                        self.unplaced_at(i, u.at * r, u.line);
                    }
                }
            }
        }
        if !known
            && !p.mode_said
            && (0..AXES.len()).any(|i| p.spans[i].is_some() && self.travel.of_place(i).is_some())
        {
            p.mode_said = true;
            let (here, read) = if call.incremental {
                ("G91 (incremental)", "absolute")
            } else {
                ("G90 (absolute)", "incremental")
            };
            // (a G90/G91 of a program it calls is its own from that call on, where the checker
            // follows the call: review 47, F1)
            let unfollowed = p.body.unfollowed.as_ref().map_or_else(
                String::new,
                |(call, at, local)| match local {
                    Some(local) => format!(
                        "; the G90 or G91 of the blocks its {call} of line {at} runs ({local}: \
                         a local subprogram call) is not followed (the checker does not \
                         follow that call), so the positions after that call are taken in the \
                         mode before it"
                    ),
                    None => format!(
                        "; the G90 or G91 of a program its {call} of line {at} runs is not \
                         followed (the checker does not read that program at that call), so the \
                         positions after that call are taken in the mode before it"
                    ),
                },
            );
            let message = format!(
                "{token} runs {name} under the {here} in force here (G90/G91 are modal and a call \
                 changes none), and {name} moves before it writes a G90 or G91 of its own: its \
                 positions, read as {read} where it is written, are not known at this call and \
                 are not compared with the travel (TG601; said at its first such call), but for \
                 those of each axis from its first move in a G90 of its own (or of a program it \
                 calls) on{unfollowed}",
                name = p.body.name
            );
            self.report(Rule::NotFollowed, message, line, column);
        }
        // (its runs of increments from a position not known, out of travel wherever they
        // start: the same at a call in the units it was read in, and in the mode it was read
        // in where it moved before a G90/G91 of its own; said at the first such call, naming
        // the body's line. In other units, not judged: docs/check.md)
        if r == 1.0 && known && !p.runs_said {
            let runs: Vec<Finding> = p
                .removed
                .iter()
                .filter(|f| f.rule == Rule::TravelExceeded && f.message.contains(RUN))
                .cloned()
                .collect();
            for mut f in runs {
                p.runs_said = true;
                let increment = under_at(&format!("increment of line {}", f.line));
                f.message = format!("{}{increment}", f.message);
                (f.line, f.column) = at;
                self.early_hold();
                self.sample_hint_shown(&mut f);
                self.found.push(f);
            }
        }
        self.early_machine_judged(&mut p.body.machine, r, at, &under);
        // (its G53 positions before a G90/G91 of its own run in the call's mode: under G91
        // not judged, said once; review 46, F3)
        let last = p.body.inherited_last.filter(|_| call.incremental);
        let inherited =
            |f: &Finding| f.placed == Placed::Machine && last.is_some_and(|last| f.line <= last);
        if call.incremental && p.body.inherited_last.is_some() {
            self.machine_incremental_call(p.body.name.clone(), token, at);
        } else {
            self.early_machine_judged(&mut p.body.inherited, r, at, &under);
        }
        if r == 1.0 && !p.positions.is_empty() {
            let unshifted = shift.iter().all(|s| *s == 0.0);
            // (read from the reset state with no units code written: at a call after one,
            // its numbers are read in the call's units, not for want of a code; review 46, F5)
            let remark = self.machine.state.units_given.then(|| self.units_remark());
            for mut f in std::mem::take(&mut p.positions) {
                // (a G53 before the body's own G90/G91 at a G91 call: kept for a later call
                // under G90, which judges it; review 48, F7; a position under the offset
                // left before it, kept for a call under that offset)
                if inherited(&f) || f.guessed && !self.work_confirms(p.work_guessed) {
                    p.positions.push(f);
                    continue;
                }
                match self.offset_now(&f) {
                    Now::AsRead => {}
                    Now::Unknown => {
                        p.positions.push(f);
                        continue;
                    }
                    // (judged with the value written: said here where out, kept for a
                    // later call where within)
                    // (under a frame or shift, or one since the G10, the position is not
                    // the work position plus the value: kept, review 59a F5)
                    Now::Written(..) if self.offsets_written.moved || self.frames_on() => {
                        p.positions.push(f);
                        continue;
                    }
                    Now::Written(place, work, at_work, value) => {
                        let said = known
                            .then(|| {
                                self.rejudged(
                                    &f,
                                    (place, work, at_work, value),
                                    "this call",
                                    &under,
                                )
                            })
                            .flatten()
                            .filter(|_| unshifted);
                        match said {
                            Some(mut said) => {
                                said.guessed &= self.work_guessed.is_some();
                                (said.line, said.column) = at;
                                self.early_hold();
                                self.sample_hint_shown(&mut said);
                                self.found.push(said);
                            }
                            None => p.positions.push(f),
                        }
                        continue;
                    }
                }
                f.guessed &= self.work_guessed.is_some();
                // (a position said at a call inside the body keeps what it waited for there)
                if matches!(f.placed, Placed::Offset { .. }) {
                    for &n in &self.offsets_written.unread {
                        if !f.pending_on.contains(&n) {
                            f.pending_on.push(n);
                        }
                    }
                }
                if let Some(remark) = &remark {
                    f.message = f.message.replacen(remark.as_str(), "", 1);
                }
                // (a position under a work offset is the body's work position plus the
                // offset: not where it goes under a shift, or where its positions are not known)
                let machine = f.placed == Placed::Machine;
                if !(machine || unshifted && known) {
                    continue;
                }
                f.message = format!("{}{}", f.message, under(f.line));
                (f.line, f.column) = at;
                self.early_hold();
                self.sample_hint_shown(&mut f);
                self.found.push(f);
            }
        } else if r > 1.0 && !p.positions.is_empty() {
            // (review 43, finding A: a machine position beyond the travel as read stays beyond
            // it in the larger units of the call, the travel holding the machine zero: said as
            // read, naming the call, as before sub41; none was said)
            for mut f in std::mem::take(&mut p.positions) {
                // (in larger units, under a value a G10 wrote: not judged, kept)
                if inherited(&f)
                    || f.guessed && !self.work_confirms(p.work_guessed)
                    || !matches!(self.offset_now(&f), Now::AsRead)
                {
                    p.positions.push(f);
                    continue;
                }
                f.guessed &= self.work_guessed.is_some();
                if !known && f.placed != Placed::Machine {
                    continue;
                }
                f.message = format!(
                    "{} (the position as written, in the units {} was read in; it runs{units} as \
                     called by {token} of line {line}, farther out there)",
                    f.message, p.body.name
                );
                self.early_hold();
                self.sample_hint_shown(&mut f);
                self.found.push(f);
            }
        } else if p.positions.iter().any(|f| f.placed != Placed::Machine) {
            // (in the smaller units of the call a position under a work offset beyond the
            // travel as read may be within it: not judged, said once; the G53 ones are judged
            // above, and kept for a call in the units they were read in)
            p.positions.retain(|f| f.placed == Placed::Machine);
            let message = format!(
                "{token}: {} runs{units} here, and its machine positions under a work offset, \
                 beyond the travel as read in the units it was read in, are not judged in these",
                p.body.name
            );
            self.report(Rule::NotFollowed, message, line, column);
        }
        // (in the call's units: its numbers read in them, no units code of its own; review
        // 62a F6c: `G0 X-28.` under a G20 call is -711.2 mm)
        if known && shift.iter().all(|s| *s == 0.0) {
            self.unplaced_judged(&p.body.unplaced, r, &mut p.unplaced_said, at, &under);
        }
        let (Some(top), Some(feed)) = (self.config.feed_max, p.body.feed.as_ref()) else {
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

    /// A call made under G91 of a body that writes a G53 before a G90/G91 of its own: that
    /// G53 runs under the G91, and is not judged ([`Checker::machine_incremental`]), said
    /// once per file.
    #[cold]
    #[inline(never)]
    fn machine_incremental_call(
        &mut self,
        name: String,
        token: &str,
        (line, column): (usize, usize),
    ) {
        if self.noted & super::limits::G53_INCREMENTAL_NOTED != 0
            || self.config.family == crate::lex::Family::LinuxCnc
        {
            return;
        }
        self.noted |= super::limits::G53_INCREMENTAL_NOTED;
        let message = format!(
            "{token} runs {name} under the G91 (incremental) in force here (G90/G91 are modal \
             and a call changes none), and {name} writes a G53 before a G90 or G91 of its own: \
             no page at hand says whether the control moves to the machine position, by the \
             increment or not at all under G91 (a 9/Series ignores the block, a Mitsubishi \
             M700V moves by the increment), so those positions are not compared with the \
             travel (TG601; said once: the same for any later G53 under G91 of this file)"
        );
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// In a program read apart with no work offset in force ([`Checker::work_unplaced`]):
    /// an absolute work position of the axis of place `i`, kept (each axis's least and
    /// most) for its calls, which run it under theirs; none from the first block that
    /// moves its coordinates or writes or may write an offset (a G10, a G52, G92, a frame,
    /// a call the checker does not follow, a units code: the positions after are not the
    /// caller's offset's). A Z under a tool length offset of its own is not kept.
    #[cold]
    #[inline(never)]
    pub(super) fn unplaced_at(&mut self, i: usize, at: f64, line: usize) {
        let w = &self.offsets_written;
        if !self.early_on
            || self.offsets_lost
            || w.any()
            || !w.unread.is_empty()
            || w.moved
            || w.shifted != 0
            || self.shifts_on()
            || self.frames_on()
            || self.transformed.is_some()
            || self.units_unknown
        {
            self.work_unplaced = false;
            return;
        }
        if AXES[i] == b'Z' && (self.machine.state.length_offset != 49 || self.length_decimal) {
            return;
        }
        let Some(early) = self.early.as_mut() else {
            return;
        };
        let ends = &mut early.body.unplaced[i];
        let here = Some(Unplaced { at, line });
        if ends[0].is_none_or(|u| at < u.at) {
            ends[0] = here;
        }
        if ends[1].is_none_or(|u| at > u.at) {
            ends[1] = here;
        }
    }

    /// At a call of `p` in the units and the mode it was read in, under no shift: its
    /// positions read with no work offset in force ([`Body::unplaced`]) judged under the
    /// caller's (its profile value, or the one a G10 of the caller's run wrote), where the
    /// caller's is known here (selected, not guessed, no frame, no value not known); each
    /// end said once. A subprogram written before its call runs under the work offset in
    /// force there: G54-G59 are modal and M98/G65 change none (0i-MF Operator's Manual,
    /// "Subprogram call (M98)"; review 61a F7: `O1000` / `G10 L2 P2 X-200.` / `G55` / `M98
    /// P3000` / `M30` / `O4000` / `G0 X-780.` / `M99` / `O3000` / `M98 P4000` / `M99` runs
    /// X-780. at -980, and was said by none).
    #[cold]
    #[inline(never)]
    fn unplaced_judged(
        &mut self,
        unplaced: &[[Option<Unplaced>; 2]; 9],
        r: f64,
        said: &mut u128,
        at: (usize, usize),
        under: &dyn Fn(usize) -> String,
    ) {
        let Some(work) = self.work else {
            return;
        };
        if unplaced.iter().all(|e| e[0].is_none())
            || self.offsets_lost
            || self.work_guessed.is_some()
            || self.work_run_on
            || self.shifts_on()
            || self.frames_on()
            || self.transformed.is_some()
            || self.units_unknown
            || self.offsets_written.moved
            // (a work offset's variable written in the caller, review 62a F1)
            || self.offset_variable_written
            // (after a return in the caller's program, reached by a jump only: review 61a F10)
            || self.sub_ended
            // (a G66 runs it at each later move, under the offset in force there, review 61a
            // F9; `M98 P2000 Q10` enters it at its N10, F12)
            || self.values.gs().contains(&66)
            || self.values.ms.contains(&98) && self.letters & crate::modal::bit(b'Q') != 0
        {
            return;
        }
        let length = self.machine.state.length_offset != 49 || self.length_decimal;
        for (i, &axis) in AXES.iter().enumerate() {
            let Some((low, high)) = self.travel.of_place(i) else {
                continue;
            };
            if axis == b'Z' && length || self.offsets_written.shifted & 1 << i != 0 {
                continue;
            }
            let written = usize::try_from(work)
                .ok()
                .and_then(|w| self.offsets_written.value(w, i));
            let profile = self
                .config
                .work_offsets
                .iter()
                .find(|&&(g, a, _)| g == work && a == axis)
                .map(|&(_, _, v)| v);
            let (value, named) = match (written, profile) {
                (Some(v), _) if v.is_nan() => continue,
                (Some(v), _) => (
                    v,
                    format!("{} as a G10 before this call wrote it", super::round6(v)),
                ),
                (None, Some(v)) => (v.to_f64(), v.to_string()),
                (None, None) => continue,
            };
            let scaled = |u: Option<Unplaced>| u.map(|u| Unplaced { at: u.at * r, ..u });
            let [least, most] = [scaled(unplaced[i][0]), scaled(unplaced[i][1])];
            let out = |u: Option<Unplaced>| {
                u.map(|u| (u, u.at + value))
                    .filter(|&(_, m)| m < low - 1e-9 || m > high + 1e-9)
            };
            for (end, found) in [(0, out(least)), (1, out(most))] {
                let Some((u, machine_at)) = found else {
                    continue;
                };
                // (both ends beyond the same side: the farther said, one excursion)
                if end == 1 && machine_at < low && out(least).is_some() {
                    continue;
                }
                if end == 0 && machine_at > high && out(most).is_some() {
                    continue;
                }
                // (the caller's excursion beyond that side runs on into it: one excursion,
                // one finding, review 61a F3)
                let side = if machine_at < low { -1 } else { 1 };
                let bit = 1u128 << (18 * (work - 54).clamp(0, 5) as usize + 2 * i + end);
                if *said & bit != 0 || self.outside[i] == side {
                    continue;
                }
                *said |= bit;
                let message = format!(
                    "{} goes to {} in machine coordinates (work {} + G{work} offset {named}), \
                     outside the travel {low} to {high}{}",
                    axis as char,
                    super::round6(machine_at),
                    super::round6(u.at),
                    under(u.line)
                );
                let placed = if written.is_some() {
                    Placed::Not
                } else {
                    Placed::Offset {
                        place: i as u8,
                        work: work as u8,
                        at: u.at,
                        line: u.line,
                    }
                };
                if self.report_placed(message, at, placed) {
                    let unread = self.offsets_written.unread.clone();
                    if let Some(f) = self.found.last_mut() {
                        // (after a G54-G59 of the caller's own following such calls, held
                        // as its own positions are: review 62a F5)
                        if !f.pending_on.contains(&super::limits::PENDING_OWN) {
                            f.pending_on.retain(|&m| super::callmode::is_mark(m));
                            f.pending_on.extend(unread);
                        }
                    }
                }
            }
        }
    }

    /// A subprogram's G53 positions at a call whose units are `r` times those it was read in
    /// (review 43, finding A): G53 ignores every shift (G52, G92, G54-G59), so each axis's
    /// least and most value, times `r`, is where the machine goes; one beyond the travel
    /// there is said at the call (once), naming the body's line, unless the body's own
    /// finding of it says it at this call (beyond the travel as read, at a call in the units
    /// it was read in or larger). Made inside another program read apart, they join that
    /// one's, judged where it is called.
    fn early_machine_judged(
        &mut self,
        machine: &mut Machine,
        r: f64,
        at: (usize, usize),
        under: &dyn Fn(usize) -> String,
    ) {
        for i in 0..AXES.len() {
            for k in 0..2 {
                let Some(m) = machine[i][k] else {
                    continue;
                };
                if k == 1 && machine[i][0].is_some_and(|least| least.at == m.at) {
                    // (one value: its least is its most)
                    continue;
                }
                if self.early_on {
                    self.early_machine(AXES[i], m.value, m.at * r, at.0);
                }
                let Some((low, high)) = self.travel.of_place(i) else {
                    continue;
                };
                let there = m.at * r;
                if m.said || (low..=high).contains(&there) {
                    continue;
                }
                if let Some(m) = machine[i][k].as_mut() {
                    m.said = true;
                }
                if r >= 1.0 && !(low..=high).contains(&m.at) {
                    continue;
                }
                let message = self.machine_message(AXES[i], m.value, there, (low, high));
                let message = format!("{message}{}", under(m.line));
                self.report_placed(message, at, Placed::Machine);
            }
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
        // with no call it is a program of its own, read in the reset inches: as before, from
        // its own G90 on (its caller's G90/G91 is not known: review 56b, F10)
        let alone = text.replace("M98 P2\n", "");
        assert_eq!(limits(mill(Units::Inch), &alone), []);
        let absolute = alone.replace("O0002\nG0", "O0002\nG90 G0");
        assert_eq!(limits(mill(Units::Inch), &absolute), [(4, 4)]);
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

    /// Review 48, F16: a LinuxCNC subroutine's G90/G91 stays in force after its return
    /// (`rs274 -g` of `o<s> sub` / `G90 G0 X250` / `o<s> endsub` ... `G91` / `o<s> call` /
    /// `G0 X-400`: X250, then X-400), unless an M73 of its, before its own G90/G91, restores
    /// the caller's (then X-150), or after it restores its own; where the checker does not know
    /// it (a G90 inside a condition) the call says so (TG140) and nothing after it is judged
    /// as absolute; and a definition's own G91, never run where it stands, leaves the main
    /// program's G90 at its endsub.
    #[test]
    fn a_linuxcnc_subroutine_s_distance_mode_after_its_return() {
        let text = |body: &str| {
            format!(
                "o<s> sub\n{body}o<s> endsub\nG21 G90\nG0 X0 Y0\nG91\no<s> call\nG0 X-400\nM2\n"
            )
        };
        let said = |body: &str| fired(lcnc(), &text(body), Rule::TravelExceeded);
        let noted = |body: &str| {
            findings(lcnc(), &text(body), Rule::NotFollowed)
                .iter()
                .filter(|f| {
                    f.message
                        .contains("after its return the checker does not know")
                })
                .map(|f| f.line)
                .collect::<Vec<_>>()
        };
        // the G90 stays: X-400 after X250, a span of 650 (in G91, -150: inside)
        assert_eq!(said("G90 G0 X250\n"), [(8, 4)]);
        assert_eq!(noted("G90 G0 X250\n"), []);
        // M73 first: the caller's G91 comes back at the return
        assert_eq!(said("M73\nG90 G0 X250\n"), []);
        assert_eq!(noted("M73\nG90 G0 X250\n"), []);
        // M73 after the G90 saves the G90, which the return restores (rs274 -g: X-400 after
        // X250; review 50)
        assert_eq!(said("G90 G0 X250\nM73\n"), [(9, 4)]);
        assert_eq!(noted("G90 G0 X250\nM73\n"), []);
        // M72 restores the caller's G91 M70 saved: X-400 from X250 (rs274 -g: X-150)
        assert_eq!(said("M70\nG90 G0 X250\nM72\n"), []);
        assert_eq!(noted("M70\nG90 G0 X250\nM72\n"), []);
        // not known: said at the call, nothing judged as absolute after it (a G90 in a
        // condition; G90 at one return, the caller's mode at the endsub)
        for body in [
            "o1 if [#5220 GT 0]\nG90\no1 endif\nG0 X250\n",
            "G0 X250\no1 if [#5220 GT 0]\nG90\no<s> return\no1 endif\n",
        ] {
            let line = text(body).lines().position(|l| l == "o<s> call").unwrap() + 1;
            assert_eq!(said(body), [], "{body}");
            assert_eq!(noted(body), [line], "{body}");
        }
        // no G90/G91 of its own: the caller's G91 stays, whatever M codes it writes
        assert_eq!(said("M70\nG0 X250\nM72\n"), []);
        assert_eq!(noted("M70\nG0 X250\nM72\n"), []);
        // a definition's G91 read where it stands is not the main program's after it
        let definition = "G21 G90\nG0 X-250 Y0\no<s> sub\nG91 G0 X1\no<s> endsub\nG0 X400\nM2\n";
        assert_eq!(fired(lcnc(), definition, Rule::TravelExceeded), [(6, 4)]);
    }

    /// Review 49a, F1, F6: G53 is refused as incremental ("Cannot use g53 incremental") only
    /// where the checker knows G91 is in force. Not after a call whose G90/G91 after its
    /// return it does not know (it says so, TG140), a call inside a condition or loop (it may
    /// not run), a body's G91 after a return inside a condition, a G91 inside the main
    /// program's `o1 if [0]`, or M72 restoring M70's G90; each run to its M2 by `rs274 -g`. A
    /// body's top-level return ends what its G90/G91 say: `G91` / `o<s> return` / `G90`
    /// returns in G91, which rs274 refuses.
    #[test]
    fn linuxcnc_g53_is_not_refused_where_the_distance_mode_is_not_known() {
        let refused = |text: &str| {
            fired(lcnc(), text, Rule::LinuxCncRefuses)
                .iter()
                .map(|f| f.0)
                .collect::<Vec<_>>()
        };
        let g53 = "G53 G0 Z0\nM2\n";
        let runs = [
            // e1: the body's G91 in a condition: not known after the call
            "G21 G90\no<s> sub\no1 if [0]\nG91\no1 endif\no<s> endsub\no<s> call\n",
            // e3, c15, e4, c16, e6: the call may not run
            "G21 G90\no<s> sub\nG91\no<s> endsub\n#5=0\no1 if [#5 eq 1]\no<s> call\no1 endif\n",
            "G21 G90\no<s> sub\nG91\no<s> endsub\no1 if [0]\no<s> call\no1 endif\n",
            "G21 G90\no<s> sub\nG91\no<s> endsub\no1 while [0]\no<s> call\no1 endwhile\n",
            "G21 G90\no<s> sub\nG91\no<s> endsub\no1 repeat [0]\no<s> call\no1 endrepeat\n",
            "G21 G90\no<s> sub\nG91\no<s> endsub\no1 if [0]\no<s> call\no1 else\nG0 X1\n\
             o1 endif\n",
            // e5: a return inside a condition before the body's G91
            "G21 G90\no<s> sub\no1 if [#1 gt 0]\no<s> return\no1 endif\nG91\no<s> endsub\n\
             o<s> call [1]\n",
            // k3: a G91 after the body's own return never runs
            "G21 G90\no<s> sub\nG90\no<s> return\nG91\no<s> endsub\nG91\no<s> call\n",
            // f1: the main program's G91 in a condition that does not run
            "G21 G90\no1 if [0]\nG91\no1 endif\n",
            // m2: M72 restores the G90 M70 saved
            "G21 G90\nM70\nG91\nM72\n",
        ];
        for program in runs {
            let text = format!("{program}{g53}");
            assert_eq!(refused(&text), Vec::<usize>::new(), "{text}");
        }
        // k4: the G90 after the return never runs; the body's G91 stays
        let k4 = format!("G21 G90\no<s> sub\nG91\no<s> return\nG90\no<s> endsub\no<s> call\n{g53}");
        assert_eq!(refused(&k4), [8]);
        // the mode known again at a G91 the main program surely runs, or in G53's own block
        for (after, line) in [("G91\nG53 G0 Z0\nM2\n", 6), ("G91 G53 G0 Z0\nM2\n", 5)] {
            let text = format!("G21 G90\no1 if [0]\nG91\no1 endif\n{after}");
            assert_eq!(refused(&text), [line], "{text}");
        }
        // M72 without a state M70 saved outside a condition: not known, not refused
        let unsure = format!("G21 G90\no1 if [#<_x> GT 1]\nM70\no1 endif\nG91\nM72\n{g53}");
        assert_eq!(refused(&unsure), Vec::<usize>::new());
        // an M70 in a condition known false never saves: rs274 refuses the M72 (review 51, F4)
        let dead = format!("G21 G90\no1 if [0]\nM70\no1 endif\nG91\nM72\n{g53}");
        assert_eq!(refused(&dead), [6]);
        // M71 invalidates the saved state: rs274 refuses the M72 (review 50, F5); an M70 of
        // G91 restores G91
        let invalid = format!("G21 G90\nM70\nM71\nG91\nM72\n{g53}");
        assert_eq!(refused(&invalid), [5]);
        let saved_g91 = format!("G21 G91\nM70\nG90\nM72\n{g53}");
        assert_eq!(refused(&saved_g91), [5]);
    }

    /// Review 51, F1, F4, F13: a line rs274 never runs is refused by no rule and changes no
    /// state (`Checker::linuxcnc_dead`): the body of an `if [0]`, `while [0]`, `repeat [0]`
    /// (and `repeat [0.5]`, rounded half to even), the `else`/`elseif` after a branch known to
    /// run, a call there (its body's refusals wait for a call that runs), the lines after an
    /// M2 that surely runs (in the main program, in a body a call runs, in a block known to
    /// run: `if [1]`, `repeat [1]`, `do`). Each run to its end by `rs274 -g`; the same lines
    /// where they run are refused as rs274 refuses them.
    #[test]
    fn linuxcnc_refuses_nothing_on_a_line_that_never_runs() {
        let refused = |text: &str| {
            fired(lcnc(), text, Rule::LinuxCncRefuses)
                .iter()
                .map(|f| f.0)
                .collect::<Vec<_>>()
        };
        let head = "G21 G90\nG0 X0\n";
        let dead = [
            // F4 e1-e8: the distance mode and M70-M73 of a dead branch
            "o1 if [0]\nG91\nG53 G0 Z0\no1 endif\nG90\nM2\n",
            "G91\no1 if [0]\nG53 G0 Z0\no1 endif\nG90\nM2\n",
            "o1 if [0]\nM72\no1 endif\nM2\n",
            "o1 repeat [0]\nM72\no1 endrepeat\nM2\n",
            "o1 repeat [0.5]\nM72\no1 endrepeat\nM2\n",
            "o1 while [0]\nM72\no1 endwhile\nM2\n",
            "o1 if [1]\nG0 X1\no1 else\nM72\no1 endif\nM2\n",
            "o1 if [1]\nG0 X1\no1 elseif [1]\nM72\no1 endif\nM2\n",
            "o1 if [1]\nG0 X1\no1 elseif [1]\nM72\no1 else\nM72\no1 endif\nM2\n",
            // any other refusal of a dead line (G53 under an arc)
            "o1 if [0]\nG53 G2 Z0\no1 endif\nM2\n",
            // F4 d1: a condition the checker works out (2 LE 1.00005)
            "#<a> = 1\no1 if [[#<a>+1] LE 1.00005]\n/G91\nG53 G0 Z0\no1 endif\nM2\n",
            // F4 addendum: a call only in a dead branch
            "o<s> sub\nG0 X#<a>\no<s> endsub\no1 if [0]\no<s> call\no1 endif\nM2\n",
            "o<s> sub\nG91\nG53 G0 X0\no<s> endsub\no1 if [0]\no<s> call\no1 endif\nM2\n",
            "o<s> sub\nM72\no<s> endsub\no1 repeat [0.5]\no<s> call\no1 endrepeat\nM2\n",
            // F1: after a called body's M2, after the main program's M2
            "o<s> sub\nM2\no<s> endsub\no<s> call\nG0 X#<nope>\nG91 G53 G0 X0\nM72\nM2\n",
            "M2\no1 if [1]\nG91 G53 G0 X0\no1 endif\nM2\n",
            // F13: an M2/M30 in a block known to run ends the program
            "o1 if [1]\nM2\no1 endif\nG0 X#<nope>\nM2\n",
            "o1 repeat [1]\nM2\no1 endrepeat\nG0 X#<nope>\nM2\n",
            "o1 do\nM2\no1 while [0]\nG0 X#<nope>\nM2\n",
            "o1 if [1]\nM30\no1 else\nG0 X1\no1 endif\nG0 X#<nope>\nM2\n",
            "o1 if [1]\nM2\no1 endif\nG91 G53 G0 X0\nM2\n",
            // review 52, F5: a dead block nested in another, whether that one runs or not
            "o2 if [1]\no1 if [0]\nM72\no1 endif\no2 endif\nM2\n",
            "o2 if [#<_x> GT 0]\no1 if [0]\nM72\no1 endif\no2 endif\nM2\n",
            "o2 if [#<_x> GT 0]\no1 while [0]\nM72\no1 endwhile\no2 endif\nM2\n",
            "o2 repeat [2]\no1 if [0]\nM72\no1 endif\no2 endrepeat\nM2\n",
            "#<k>=0\no3 while [#<k> LT 1]\n#<k>=[#<k>+1]\no1 repeat [0.5]\nM72\no1 endrepeat\no3 endwhile\nM2\n",
            "o3 if [1]\no2 if [1]\no1 if [0]\nG91\nG53 G0 Z0\no1 endif\no2 endif\no3 endif\nM2\n",
            // the lines after an unconditional break or continue, to the loop's closing line
            "o3 do\no3 break\nM72\no3 while [0]\nM2\n",
            "#<k>=0\no3 while [#<k> LT 1]\n#<k>=[#<k>+1]\no3 continue\nM72\no3 endwhile\nM2\n",
            "o2 if [1]\no3 do\no3 break\nG999\nG2 X1 F100\nM72\no3 while [1]\no2 endif\nM2\n",
        ];
        for program in dead {
            let text = format!("{head}{program}");
            assert_eq!(refused(&text), Vec::<usize>::new(), "{text}");
        }
        // the same lines where they run: the else after a false if, a repeat [1.5] (2 times),
        // a condition the checker cannot work out (#<_x>, the current X, is not followed)
        let runs = [
            ("o1 if [0]\nG0 X1\no1 else\nM72\no1 endif\nM2\n", 6),
            (
                "o<s> sub\nM72\no<s> endsub\no1 repeat [1.5]\no<s> call\no1 endrepeat\nM2\n",
                4,
            ),
            ("o1 if [#<_x> GT 1]\nG53 G2 Z0\no1 endif\nM2\n", 4),
            ("o1 if [#<_x> GT 1]\nM2\no1 endif\nG91 G53 G0 X0\nM2\n", 6),
            // nested: a condition on a parameter is not taken as known, nor the else of a
            // nested dead if (it runs where the block around it does)
            (
                "o2 if [1]\no1 if [#<_x> GT 1]\nM72\no1 endif\no2 endif\nM2\n",
                5,
            ),
            (
                "o2 if [1]\no1 if [0]\nG0 X1\no1 else\nM72\no1 endif\no2 endif\nM2\n",
                7,
            ),
            // a break inside an if of the body: the lines after that if run where it did not
            (
                "o3 do\no2 if [#<_x> GT 1]\no3 break\no2 endif\nM72\no3 while [0]\nM2\n",
                7,
            ),
        ];
        for (program, line) in runs {
            let text = format!("{head}{program}");
            assert_eq!(refused(&text), [line], "{text}");
        }
        // review 52, F5's addendum: no other rule judges a nested dead block's lines either
        // (an unknown G code, an arc without its centre; rs274 runs both programs)
        for (body, rule) in [
            ("G999", Rule::CodeAlarms),
            ("G2 X1 F100", Rule::ArcCentreMissing),
        ] {
            for outer in ["o2 if [1]", "o2 if [#<_x> GT 1]", "o2 repeat [2]"] {
                let close = if outer.contains("repeat") {
                    "o2 endrepeat"
                } else {
                    "o2 endif"
                };
                let text = format!("{head}{outer}\no1 if [0]\n{body}\no1 endif\n{close}\nM2\n");
                assert_eq!(fired(lcnc(), &text, rule), [], "{text}");
                // the arc where it may run: judged
                let live = text.replace("o1 if [0]", "o1 if [#<_x> GT 1]");
                if rule == Rule::ArcCentreMissing {
                    assert_eq!(fired(lcnc(), &live, rule).len(), 1, "{live}");
                }
            }
        }
    }

    /// rfix51's remainder: rs274 reads a definition without running it (interp_o_word.cc
    /// skips from its sub to its endsub), so after its endsub the main program's parameters
    /// are the ones known at its sub, the body's assignments not made: a condition on them
    /// is worked out as before it (each run to its end by `rs274 -g`). A call runs the body,
    /// which may set them: after it the condition is not known, and its lines are refused as
    /// lines that may run.
    #[test]
    fn linuxcnc_keeps_the_parameters_across_a_definition_not_a_call() {
        let refused = |text: &str| {
            fired(lcnc(), text, Rule::LinuxCncRefuses)
                .iter()
                .map(|f| (f.0, f.1))
                .collect::<Vec<_>>()
        };
        let head = "G21 G90\nG0 X0\n#<a> = 1\n#1 = 0\n#<_g> = 0\n";
        let sub = "o<s> sub\n#<a> = 5\n#1 = 5\n#<_g> = 5\no<s> endsub\n";
        let conditions = [
            "o101 if [[#<a>+1] LE 1.00005]\nG91\nG53 G0 X0\no101 endif\nM2\n",
            "o101 if [#1 GT 0]\nM72\no101 endif\nM2\n",
            "o101 if [#<_g> GT 0]\nG91\nG53 G0 Z0\no101 endif\nM2\n",
        ];
        for condition in conditions {
            let text = format!("{head}{sub}{condition}");
            assert_eq!(refused(&text), [], "{text}");
        }
        // after a call of the body: the line inside the condition may run (rs274 runs it,
        // the body set #<_g> to 5: "Cannot use g53 incremental" at line 14)
        let called = format!("{head}{sub}o<s> call\n{}", conditions[2]);
        assert_eq!(refused(&called), [(14, 1)]);
    }

    /// Review 51, F2: a body's lines after its unconditional return never run, an o-word
    /// condition's reads among them too (`rs274 -g` runs `o<s> return` / `o1 if [#<b> GT 0]`
    /// to the end); F11: an o-word after a comment or a word in a block known to run is
    /// refused as outside any condition ("Bad character 'o' used").
    #[test]
    fn linuxcnc_judges_the_lines_known_to_run_and_no_other() {
        let refused = |text: &str| {
            fired(lcnc(), text, Rule::LinuxCncRefuses)
                .iter()
                .map(|f| f.0)
                .collect::<Vec<_>>()
        };
        let after_return = "G21 G90\nG0 X0\no<s> sub\no<s> return\no1 if [#<b> GT 0]\no1 endif\n\
                            G0 X#<c>\no<s> endsub\no<s> call\nM2\n";
        assert_eq!(refused(after_return), Vec::<usize>::new());
        let before_return = "G21 G90\nG0 X0\no<s> sub\no1 if [#<b> GT 0]\no1 endif\n\
                             o<s> return\no<s> endsub\no<s> call\nM2\n";
        assert_eq!(refused(before_return), [4]);
        for program in [
            "G21\no5 if [1]\n(c) o6 if [1]\no5 endif\nM2\n",
            "G21\no5 if [1]\nG0 X1 o6 call\no5 endif\nM2\n",
        ] {
            assert_eq!(refused(program), [3], "{program}");
        }
        // in a condition the checker cannot work out: not judged (it may not run)
        let unknown = "G21\no5 if [#<_x> GT 1]\n(c) o6 if [1]\no5 endif\nM2\n";
        assert_eq!(refused(unknown), Vec::<usize>::new());
    }

    /// Review 51, F3: `break` and `continue` leave a `do` or `while` only; of a label recorded
    /// for an `if` or a `repeat` rs274 refuses them where it reaches them ("5: no matching
    /// while/do label: 'o1 continue' (found 'repeat' in line 3)", `rs274 -g`), a skip of a
    /// block known not to run ending at them too; where the block's condition or count is not
    /// known, in its first branch with no o-word line before them, too (rs274 runs the branch
    /// to them or skips to them; review 52, F9); not where they may not be reached (after an
    /// `else` of a branch that may end the program, in a block not run).
    #[test]
    fn linuxcnc_refuses_a_break_of_an_if_or_a_repeat() {
        let refused = |text: &str| {
            findings(lcnc(), text, Rule::LinuxCncRefuses)
                .iter()
                .map(|f| {
                    (
                        f.line,
                        f.column,
                        f.message.split(" (").next().unwrap().to_owned(),
                    )
                })
                .collect::<Vec<_>>()
        };
        let head = "G21 G90\nG0 X0\n";
        for (open, exit, close) in [
            ("o1 repeat [2]", "o1 continue", "o1 endrepeat"),
            ("o1 repeat [2]", "o1 break", "o1 endrepeat"),
            ("o1 repeat [0]", "o1 continue", "o1 endrepeat"),
            ("o1 if [1]", "o1 break", "o1 endif"),
            ("o1 if [0]", "o1 break", "o1 endif"),
        ] {
            let text = format!("{head}{open}\nG0 X1\n{exit}\n{close}\nM2\n");
            let said = refused(&text);
            assert_eq!(said.len(), 1, "{text}");
            assert_eq!((said[0].0, said[0].1), (5, 1), "{text}");
            assert_eq!(said[0].2, "no matching while/do label", "{text}");
        }
        // (its count not known: rs274 runs the body to the break, or skips to it; review 52,
        // F9: "4: no matching while/do label: 'o1 break' (found 'repeat' in line 3)")
        for text in [
            "o1 repeat [#<_x>]\no1 break\no1 endrepeat\nM2\n",
            "o1 if [#<_x> GT 1]\no1 break\no1 endif\nM2\n",
        ] {
            let said = refused(&format!("{head}{text}"));
            assert_eq!(said.len(), 1, "{text}");
            assert_eq!((said[0].0, said[0].1), (4, 1), "{text}");
            assert_eq!(said[0].2, "no matching while/do label", "{text}");
        }
        for text in [
            "o1 do\nG0 X1\no1 break\no1 while [1]\nM2\n",
            "o1 while [#<_x> LT 1]\no2 repeat [2]\no1 break\no2 endrepeat\no1 endwhile\nM2\n",
            "o2 if [0]\no1 if [1]\no1 break\no1 endif\no2 endif\nM2\n",
            "o1 if [#<_x> GT 1]\nM2\no1 else\no1 break\no1 endif\nM2\n",
        ] {
            let text = format!("{head}{text}");
            assert!(refused(&text).is_empty(), "{text}");
        }
    }

    /// Review 50, F1-F8, F11: G53 in G91 ("Cannot use g53 incremental") and M72 with nothing
    /// saved ("Cannot restore context from invalid stack frame - missing M70/M73?") refused
    /// where rs274 refuses them wherever the line runs, and nowhere else: a body's nested call
    /// before its return (f1), M73 in the main program a save (f2), a G91 in a condition or
    /// loop known in its own block from there, one equal to the mode in force changing
    /// nothing, a `do` body run once (f3), a body's G53 judged at each call in the call's
    /// mode (f4), M72 in the main program and in a called body (f5), a dead G91 after a
    /// body's return (f6), a call inside a definition not the main program's (f7), a call in
    /// a loop of a body whose end mode is the one in force (f8), M72 in G53's own block
    /// (f11), M72 with a G90/G91 of its block (m72), M73's restore at the return (m73). Each
    /// program's (line, column) as `rs274 -g` stops there, or runs it to its M2 (f3g, f3h,
    /// m72h: rs274 stops where the checker cannot tell, not refused).
    #[test]
    fn review50_g53_and_m72_are_refused_where_rs274_refuses_them() {
        let refused = |text: &str| {
            findings(lcnc(), text, Rule::LinuxCncRefuses)
                .iter()
                .map(|f| (f.line, f.column))
                .collect::<Vec<_>>()
        };
        let cases: &[(&str, &[(usize, usize)])] = &[
            // f1
            ("G21 G90\no<t> sub\nG90\no<t> endsub\no<s> sub\nG91\no<t> call\no<s> return\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", &[]),
            // f1b
            ("G21 G91\no<t> sub\nG91\no<t> endsub\no<s> sub\nG90\no<t> call\no<s> return\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", &[(11, 1)]),
            // f2
            ("G21 G91\nM70\nG90\nM73\nG91\nM72\nG53 G0 Z0\nM2\n", &[]),
            // f2b
            ("G21 G90\nM73\nG91\nM72\nG53 G0 Z0\nM2\n", &[]),
            // f3a
            ("G21 G90\n#1=1\no1 if [#1 gt 0]\nG91\nG53 G0 Z0\no1 endif\nM2\n", &[(5, 1)]),
            // f3b
            ("G21 G90\n#1=0\no1 while [#1 lt 2]\nG91\nG53 G0 Z0\n#1=[#1+1]\no1 endwhile\nM2\n", &[(5, 1)]),
            // f3c
            ("G21 G91\n#1=1\no1 if [#1 gt 0]\nG91\no1 endif\nG53 G0 Z0\nM2\n", &[(6, 1)]),
            // f3d
            ("G21 G90\n#1=0\no1 if [#1 gt 0]\nG91\no1 endif\no<s> sub\nG91\nG53 G0 Z0\no<s> endsub\no<s> call\nM2\n", &[(8, 1)]),
            // f3e
            ("G21 G90\no1 do\nG91\no1 while [0]\nG53 G0 Z0\nM2\n", &[(5, 1)]),
            // f3f
            ("G21 G90\no<s> sub\nG91\no<s> endsub\no1 do\no<s> call\no1 while [0]\nG53 G0 Z0\nM2\n", &[(8, 1)]),
            // f3g
            ("G21 G90\n#1=1\no1 if [#1 gt 0]\nG91\no1 else\nG53 G0 Z0\no1 endif\nM2\n", &[]),
            // f3h: the condition known true (review 49a F2), the G91 surely runs: rs274 -g
            // refuses line 6 ("Cannot use g53 incremental")
            ("G21 G90\n#1=1\no1 if [#1 gt 0]\nG91\no1 endif\nG53 G0 Z0\nM2\n", &[(6, 1)]),
            // the same condition not known: not refused
            ("G21 G90\no1 if [#1 gt 0]\nG91\no1 endif\nG53 G0 Z0\nM2\n", &[]),
            // f4
            ("G21 G91\no<s> sub\nG53 G0 Z0\no<s> endsub\nG90\no<s> call\nM2\n", &[]),
            // f4b
            ("G21 G90\no<s> sub\nG53 G0 Z0\no<s> endsub\nG91\no<s> call\nM2\n", &[(3, 1)]),
            // f4c
            ("G21 G91\no<s> sub\no<s> return\nG53 G0 Z0\no<s> endsub\no<s> call\nM2\n", &[]),
            // f4d
            ("G21 G90\no<t> sub\nG53 G0 Z0\no<t> endsub\no<s> sub\nG91\no<t> call\no<s> endsub\no<s> call\nM2\n", &[(3, 1)]),
            // f4e
            ("G21 G90\no<s> sub\nG53 G0 Z0\no<s> endsub\nM2\n", &[]),
            // f5a
            ("G21 G90\nM72\nG53 G0 Z0\nM2\n", &[(2, 1)]),
            // f5b
            ("G21 G90\nG91\nM70\nG90\nM71\nM72\nG53 G0 Z0\nM2\n", &[(6, 1)]),
            // f5c
            ("G21 G90\no<s> sub\nM72\no<s> endsub\nM70\no<s> call\nM2\n", &[(3, 1)]),
            // f5d
            ("G21 G90\no<s> sub\nM70\nG91\nM72\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", &[]),
            // f6
            ("G21 G91\no<s> sub\nM70\no<s> return\nG91\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", &[(8, 1)]),
            // f7
            ("G21 G91\no<s0> sub\nM70\nG91\no<s0> endsub\no<s1> sub\no<s0> call\no<s1> endsub\nG53 G0 Z0\nM2\n", &[(9, 1)]),
            // f7b
            ("G21 G91\no<s0> sub\no1 if [#1 gt 0]\nG91\no1 endif\no<s0> endsub\no<s1> sub\no<s0> call\no<s1> endsub\nG53 G0 Z0\nM2\n", &[(10, 1)]),
            // f8
            ("G21 G90\no<s> sub\nG90\nG0 X1\no<s> endsub\no1 repeat [3]\no<s> call\no1 endrepeat\nG53 G0 Z0\nG91\nG53 G0 Z0\nM2\n", &[(11, 1)]),
            // f11a
            ("G21 G90\nM70\nG91\nM72 G53 G0 Z0\nM2\n", &[(4, 5)]),
            // f11b
            ("G21 G91\nM70\nG90\nM72 G53 G0 Z0\nM2\n", &[]),
            // m72g
            ("G21 G90\nM70\nG91\nM72 G91\nG53 G0 Z0\nM2\n", &[]),
            // m72h
            ("G21 G90\nM70\nM72 G91\nG53 G0 Z0\nM2\n", &[]),
            // m73r
            ("G21 G91\no<s> sub\nM73\nG90\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", &[(7, 1)]),
            // m73s
            ("G21 G90\no<s> sub\nG91\nM73\nG90\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", &[(8, 1)]),
        ];
        for (text, lines) in cases {
            assert_eq!(refused(text), *lines, "{text}");
        }
        // a subroutine file (called from another file): its own G91's G53 refused where it
        // stands; one before its own G90/G91 runs in its caller's mode, not judged
        let file = "o<x> sub\nG91\nG53 G0 Z0\no<x> endsub\n";
        assert_eq!(refused(file), [(3, 1)]);
        assert_eq!(refused("o<x> sub\nG53 G0 Z0\no<x> endsub\n"), []);
        // review 51, F17: a line inside a condition of the body runs for some calls only (on
        // its arguments: `o<s> call [0]` runs such a file to its end in rs274 -g)
        for file in [
            "o<x> sub\no1 if [#1 GT 0]\nM72\no1 endif\no<x> endsub\n",
            "o<x> sub\nG91\no1 if [#1 GT 0]\nG53 G0 Z0\no1 endif\nG90\no<x> endsub\n",
        ] {
            assert_eq!(refused(file), [], "{file}");
        }
        assert_eq!(refused("o<x> sub\nM72\no<x> endsub\n"), [(2, 1)]);
        // f8: after the loop the G90 is known, its X-900 absolute (rs274 -g: X-900), no note
        let f8 = "G21 G90\no<s> sub\nG90\nG0 X1\no<s> endsub\no1 repeat [3]\no<s> call\n\
                  o1 endrepeat\nG0 X-900\nM2\n";
        let said = findings(lcnc(), f8, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].message.contains("X spans 901 (from -900 to 1)"),
            "{said:?}"
        );
        assert!(
            findings(lcnc(), f8, Rule::NotFollowed)
                .iter()
                .all(|f| !f.message.contains("after its return")),
            "{f8}"
        );
        // the body's refusal names the call that runs it, said once a line
        let twice = "G21 G91\no<s> sub\nG53 G0 Z0\no<s> endsub\no<s> call\no<s> call\nM2\n";
        let said = findings(lcnc(), twice, Rule::LinuxCncRefuses);
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].message.starts_with("Cannot use g53 incremental")
                && said[0].message.contains("o<s> call of line 5"),
            "{}",
            said[0].message
        );
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
        // a known value with a fraction: rs274 stops, "Non integer value for integer"
        let fraction = named
            .replace("#1=100", "#1=100.5")
            .replace("o100 call", "o#1 call");
        let refused: Vec<_> = findings(lcnc(), &fraction, Rule::LinuxCncRefuses)
            .into_iter()
            .map(|f| (f.line, f.column, f.message.starts_with("Non integer value")))
            .collect();
        assert_eq!(refused, [(7, 1, true)]);
        // written in brackets too (review 47, F3)
        let written = named.replace("o100 call", "o[100.5] call");
        assert_eq!(findings(lcnc(), &written, Rule::LinuxCncRefuses).len(), 1);
        // a number in brackets is that number's label
        let bracket = named.replace("o100 call", "o[100] call");
        assert_eq!(fired(lcnc(), &bracket, Rule::TravelExceeded), [(7, 1)]);
        // the other labels rs274's read_o reads (interp_read.cc, read_integer_value): a sign,
        // a point with no fraction, an operation, a parameter whose number is a parameter's,
        // within 0.0001 of a whole number; each called o100 under rs274 -g
        // (tests/test_linuxcnc_o_labels.py)
        for call in [
            "o+100 call",
            "o100.0 call",
            "o 1 0 0 . 0 0 call",
            "o-[-100] call",
            "o[#1+0] call",
            "o[#1*2-100] call",
            "o100.00005 call",
            "o99.99995 call",
            "o##2 call",
            "o#[#2] call",
            "oabs[-100] call",
        ] {
            let text = named
                .replace("#1=100", "#1=100\n#2=1")
                .replace("o100 call", call);
            assert_eq!(
                fired(lcnc(), &text, Rule::TravelExceeded),
                [(8, 1)],
                "{call}"
            );
        }
        assert_eq!(
            findings(
                lcnc(),
                &named.replace("o100 call", "o100.5 call"),
                Rule::LinuxCncRefuses
            )
            .len(),
            1
        );
        // a parameter not set, or a function not worked out here (only ABS, FIX, FUP and
        // ROUND of a constant are: `oabs[-100] call` above)
        for call in ["o#2 call", "osqrt[10000] call"] {
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

    /// Issue 32, incr48's open case: a body read before its call whose own increments, from a
    /// position not known, run wider than the travel. Its TG601 was held and taken out at its
    /// M99, and at the call only its span (none: no position known) was judged: lost. Said at
    /// a call in the units it was read in, once, naming the body's line; at a call in other
    /// units not judged (docs/check.md).
    #[test]
    fn a_body_s_run_of_increments_wider_than_the_travel_is_said_at_its_call() {
        let b1 = "%\nO2000\nG91 G0 X800.\nY10.\nX800.\nG90\nM99\nO1000\nG21 G90 G54 G17\n\
                  G0 X0. Y0\nM98 P2000\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), b1), [(11, 5)]);
        let said = findings(metric.clone(), b1, Rule::TravelExceeded);
        assert!(
            said[0].message.starts_with(
                "X moves over 1600 mm in 2 increments in a row (the last X800.) with its start \
                 not known: more than its whole travel of 1524"
            ) && said[0]
                .message
                .contains("(O2000 runs as called by M98 P2000 of line 11, its increment of line 5"),
            "{}",
            said[0].message
        );
        // once, at the first call
        let twice = b1.replace("M98 P2000\n", "M98 P2000\nM98 P2000\n");
        assert_eq!(limits(metric.clone(), &twice), [(11, 5)]);
        // never called: said as read, at the file's end
        assert_eq!(
            limits(metric.clone(), &b1.replace("M98 P2000\n", "")),
            [(5, 1)]
        );
        // a run that fits: nothing
        assert_eq!(
            limits(metric.clone(), &b1.replace("\nX800.", "\nX700.")),
            []
        );
        // a call in inches (the body read in mm): not judged
        assert_eq!(limits(metric, &b1.replace("G21 G90", "G20 G90")), []);
    }

    /// Review 48, F17: the file's first finding of a limit said carries the sample machine's
    /// hint ("said once"), wherever the one first made was: a body's own finding, held and
    /// taken out at its M99, spent it, and the body's TG601 at its call went without it.
    #[test]
    fn the_first_limit_finding_said_carries_the_sample_machine_s_hint() {
        let hint = " (the built-in profile's limits are a typical machine of the family: a \
                    profile of your machine, `base` and its [limits], checks against yours; said \
                    once)";
        let metric = mill(Units::Metric);
        let hints = |said: &[super::Finding]| -> Vec<bool> {
            said.iter().map(|f| f.message.contains(hint)).collect()
        };
        // (review 48's sp2.nc: the body's own X700. / X-900. span 1600, said at the call)
        let sp2 = "%\nO2000\nG90\nG0 X700.\nG0 X-900.\nM99\nO1000\nG21 G90 G54 G17\n\
                   G0 X0. Y0\nM98 P2000\nM30\n%\n";
        let said = findings(metric.clone(), sp2, Rule::TravelExceeded);
        assert_eq!(
            said.iter().map(|f| (f.line, f.column)).collect::<Vec<_>>(),
            [(10, 5)]
        );
        assert!(
            said[0].message.ends_with(&format!(
                "(O2000 runs as called by M98 P2000 of line 10, its positions of lines 5 and 4 \
                 there: a subprogram written before its call runs in the units and under the \
                 shift in force there){hint}"
            )),
            "{}",
            said[0].message
        );
        // a body no call names: its finding said at the file's end, after the main program's
        // own, which comes first and carries the hint
        let uncalled = sp2.replace("M98 P2000", "G0 X800.\nG0 X-800.");
        let said = findings(metric.clone(), &uncalled, Rule::TravelExceeded);
        assert_eq!(
            said.iter().map(|f| f.line).collect::<Vec<_>>(),
            [11, 5],
            "{said:?}"
        );
        assert_eq!(hints(&said), [true, false]);
        // alone, it carries it as before
        let alone = sp2.replace("M98 P2000\n", "");
        let said = findings(metric.clone(), &alone, Rule::TravelExceeded);
        assert_eq!(hints(&said), [true]);
        // a call under a shift not known judges nothing: the hint goes to the next finding
        // said, the main program's own (it had none)
        let unknown = sp2.replace(
            "M98 P2000",
            "G52 X#1\nM98 P2000\nG52 X0\nG0 X800.\nG0 X-800.",
        );
        let said = findings(metric, &unknown, Rule::TravelExceeded);
        assert_eq!(
            said.iter().map(|f| f.line).collect::<Vec<_>>(),
            [14],
            "{said:?}"
        );
        assert_eq!(hints(&said), [true], "{said:?}");
    }

    /// Findings held for a program read apart are said in the order they came, whether
    /// they are taken after each line or at the end: a main program's report is the same.
    #[test]
    fn held_findings_keep_their_order() {
        let text = "%\nO1000\nG21 G90\nG0 X-700.\nG0 X900.\nG1 X0 F20000.\nQ5\nM30\n%\n";
        let all = |take_each: bool| {
            taken(text, Selection::all(), take_each)
                .into_iter()
                .map(|(rule, line, column, _)| (rule, line, column))
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

    /// Review 46, F3: a body's G53 written before a G90/G91 of its own runs in the call's
    /// mode; no page at hand says what a FANUC, Haas or SINUMERIK does with G53 under G91 (a
    /// 9/Series ignores the block, a Mitsubishi M700V moves by the increment), so at a G91
    /// call it is not judged, one TG140 says so; at a G90 call, and where the body writes its
    /// own G90 first, it is judged as before.
    #[test]
    fn a_body_s_g53_under_a_g91_call_is_not_judged() {
        let g53 = "%\nO0002\nG53 G0 X-800.\nM99\nO1000\nG21 G90 G54\nG0 X0 Y0\nG91\n\
                   M98 P2\nG90\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), g53), []);
        let notes: Vec<_> = findings(metric.clone(), g53, Rule::NotFollowed)
            .into_iter()
            .filter(|f| {
                f.message
                    .contains("writes a G53 before a G90 or G91 of its own")
            })
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(notes, [(9, 5)]);
        // a G90 call: judged, said at the call
        let absolute = g53.replace("G91\nM98 P2", "G90\nM98 P2");
        assert_eq!(limits(metric.clone(), &absolute), [(9, 5)]);
        // the body's own G90 before its G53: judged whatever the call's mode
        let own = g53.replace("G53 G0 X-800.", "G90\nG53 G0 X-800.");
        assert_eq!(limits(metric.clone(), &own), [(10, 5)]);
        // a later G53 after the body's own G90 is judged; the one before it is not
        let both = g53.replace("G53 G0 X-800.", "G53 G0 X-790.\nG90\nG53 G0 X-770.");
        let said = findings(metric.clone(), &both, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].message.contains("X goes to -770"),
            "{}",
            said[0].message
        );
        // LinuxCNC refuses the block (its own rule): no note, no position judged
        let lc = "o<s> sub\nG53 G0 X-800.\no<s> endsub\nG21 G90\nG0 X0\nG91\no<s> call\nG90\nM2\n";
        let mut linuxcnc = mill(Units::Metric);
        linuxcnc.family = crate::lex::Family::LinuxCnc;
        let dialect = dialect(crate::lex::Family::LinuxCnc);
        let (_, found) = run(linuxcnc, &dialect, lc);
        assert!(
            found.iter().all(
                |f| f.rule != Rule::TravelExceeded && f.rule != Rule::NotFollowed
                    || !f.message.contains("G53")
            ),
            "{found:?}"
        );
    }

    /// Review 48, F7: each call of a body judges its G53 written before a G90/G91 of its own
    /// in the call's own mode: a G91 call first (not judged, TG140 once) leaves it to a later
    /// G90 call, which says it; the other order says it at the G90 call as before.
    #[test]
    fn a_body_s_g53_is_judged_at_a_g90_call_after_a_g91_call() {
        let g3 = "%\nO2000\nG53 G0 X-800.\nM99\nO1000\nG21 G90 G54\nG91\nM98 P2000\nG90\n\
                  M98 P2000\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), g3), [(10, 5)]);
        let said = findings(metric.clone(), g3, Rule::TravelExceeded);
        assert!(said[0].message.contains("X goes to -800"), "{said:?}");
        assert!(said[0].message.contains("line 10"), "{said:?}");
        // the G90 call first: said there, once
        let g5 = "%\nO2000\nG53 G0 X-800.\nM99\nO1000\nG21 G90 G54\nM98 P2000\nG91\n\
                  M98 P2000\nG90\nM30\n%\n";
        assert_eq!(limits(metric.clone(), g5), [(7, 5)]);
        // two G90 calls after the G91 one: said once
        let twice = g3.replace("M30", "M98 P2000\nM30");
        assert_eq!(limits(metric, &twice), [(10, 5)]);
    }

    /// Review 48, F11: a subprogram written after its call (or not in the file) may leave
    /// G91 (a tool change's `G91 G28 Z0`; M99 restores no mode): the caller's positions after
    /// the call are not judged as absolute until it writes its own G90/G91, one TG140 a file
    /// says so; one written before its call is followed as before (nest48).
    #[test]
    fn the_mode_after_a_call_of_a_program_read_later_is_not_known() {
        let q1 = "%\nO1000\nG21 G90 G54 G17\nG0 X700. Y0\nM98 P3000\nG0 X-900.\nM30\nO3000\n\
                  G91\nM99\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), q1), []);
        let lost = |text: &str| -> Vec<(usize, usize)> {
            findings(metric.clone(), text, Rule::NotFollowed)
                .into_iter()
                .filter(|f| {
                    f.message
                        .contains("whose G90/G91 the checker does not know")
                })
                .map(|f| (f.line, f.column))
                .collect()
        };
        assert_eq!(lost(q1), [(5, 5)]);
        // the caller's own G90 after the call: judged again
        let own = q1.replace("G0 X-900.", "G90 G0 X-900.");
        assert_eq!(limits(metric.clone(), &own), [(6, 8)]);
        // a program not in the file: the same
        let absent = q1.replace("O3000\nG91\nM99\n", "");
        assert_eq!(limits(metric.clone(), &absent), []);
        // one level down: a body read apart calls the later program, then moves
        let q2 = "%\nO2000\nM98 P3000\nG0 X-900.\nM99\nO1000\nG21 G90 G54 G17\nG0 X700. Y0\n\
                  M98 P2000\nM30\nO3000\nG91\nM99\n%\n";
        assert_eq!(limits(metric.clone(), q2), []);
        // and its caller after it: the body's mode at its M99 is not known either
        let q2b = "%\nO2000\nM98 P3000\nM99\nO1000\nG21 G90 G54 G17\nG0 X700. Y0\n\
                   M98 P2000\nG0 X-900.\nM30\nO3000\nG91\nM99\n%\n";
        assert_eq!(limits(metric.clone(), q2b), []);
        // written before its call: followed (G91 after it), no note
        let q4 = "%\nO3000\nG91\nM99\nO1000\nG21 G90 G54 G17\nG0 X700. Y0\nM98 P3000\n\
                  G0 X-900.\nM30\n%\n";
        assert_eq!(limits(metric.clone(), q4), []);
        assert_eq!(lost(q4), []);
        // a body read before its call that writes G90 last: judged as absolute after it
        let back = q4.replace("G91\nM99", "G91\nG90\nM99");
        assert_eq!(limits(metric.clone(), &back), [(10, 4)]);
        // a G52 after such a call read as before (not as one under G91, whose shift is not
        // known): the later body's X900 under the call's G52 X700 still spans from X-600
        let g52 = "%\nO1000\nG21 G90 G54\nG0 X-600. Y0\nG52 X700.\nG0 X0 Y0\nM98 P2000\n\
                   G52 X0\nM30\nO2000\nG0 X900.\nM99\n%\n";
        assert_eq!(limits(metric, g52), [(11, 4)]);
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
        assert!(most <= super::HOLD_ALL as usize + 8, "{most}");
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

    /// The findings of `text` on [`mill`] in metric under `selection`, taken after each line
    /// (`each`, as the CLI's report) or once at the end (as the Python API's chunk).
    fn taken(text: &str, selection: Selection, each: bool) -> Vec<(Rule, usize, usize, String)> {
        let mut checker = Checker::new(Arc::new(mill(Units::Metric)), selection, false);
        let (mut tokens, mut found) = (Vec::new(), Vec::new());
        for (i, line) in text.lines().enumerate() {
            checker.check_line(
                line.as_bytes(),
                i + 1,
                &dialect(Family::MacroB),
                &mut tokens,
            );
            if each {
                found.extend(checker.drain());
            }
        }
        checker.finish();
        found.extend(checker.take());
        found
            .into_iter()
            .map(|f| (f.rule, f.line, f.column, f.message))
            .collect()
    }

    /// `O0002` of `n` lines `G53 G0 X-900.` and M99, then `O1000`, `G20`, `M98 P2`, `M30`
    /// (review 43's small.nc, 1000, and bound.nc, 1100).
    fn machine_body(n: usize) -> String {
        let mut text = String::from("%\nO0002\nG1 X0 Y0 F100.\n");
        for _ in 0..n {
            text.push_str("G53 G0 X-900.\n");
        }
        text.push_str("M99\nO1000\nG20 G90 G54\nM98 P2\nM30\n%\n");
        text
    }

    /// Review 43, finding B: the bound on the hold is counted where a finding is held (its
    /// limits' findings, selected or not), so the findings are the same taken after each line
    /// or once, and the program is given up whatever the selection.
    #[test]
    fn the_bound_on_the_hold_does_not_depend_on_who_takes_the_findings() {
        let bound = machine_body(1100);
        let each = taken(&bound, Selection::all(), true);
        let once = taken(&bound, Selection::all(), false);
        assert_eq!(each, once);
        let errors = |found: &[(Rule, usize, usize, String)]| {
            found.iter().filter(|f| f.0 == Rule::TravelExceeded).count()
        };
        let given_up = |found: &[(Rule, usize, usize, String)]| {
            found
                .iter()
                .filter(|f| {
                    f.0 == Rule::NotFollowed
                        && f.3
                            .starts_with("M98 P2 calls O0002, read from the reset state")
                })
                .map(|f| f.1)
                .collect::<Vec<_>>()
        };
        // given up at its 1025th: said as read, and its call noted
        assert_eq!(errors(&once), 1100);
        assert_eq!(given_up(&once), [1107]);
        // the same whatever the selection: the note with TG140 alone (nothing held)
        let select = |rules: &[Rule]| {
            let rules: Vec<String> = rules.iter().map(|r| r.id().to_string()).collect();
            Selection::new(&rules, &[])
        };
        for each in [true, false] {
            let notes = taken(&bound, select(&[Rule::NotFollowed]), each);
            assert_eq!(errors(&notes), 0);
            assert_eq!(given_up(&notes), [1107]);
            let limits = taken(
                &bound,
                select(&[
                    Rule::TravelExceeded,
                    Rule::FeedTooHigh,
                    Rule::FeedClamped,
                    Rule::NotFollowed,
                ]),
                each,
            );
            assert_eq!(errors(&limits), 1100);
            assert_eq!(given_up(&limits), [1107]);
        }
        // 1000 of them: held, and said at the call, taken either way
        let small = machine_body(1000);
        let each = taken(&small, Selection::all(), true);
        assert_eq!(each, taken(&small, Selection::all(), false));
        assert_eq!(errors(&each), 1000);
        assert!(given_up(&each).is_empty());
        assert!(each
            .iter()
            .filter(|f| f.0 == Rule::TravelExceeded)
            .all(|f| f.3.contains("as called by M98 P2 of line 1007")));
    }

    /// Review 43, finding E: two programs given up, each call of each noted.
    #[test]
    fn each_program_given_up_is_noted_at_each_call() {
        let mut text = String::from("%\n");
        for number in ["O0002", "O0003"] {
            text.push_str(number);
            text.push('\n');
            for _ in 0..1100 {
                text.push_str("G53 G0 X-900.\n");
            }
            text.push_str("M99\n");
        }
        text.push_str("O1000\nG20 G90 G54\nM98 P2\nM98 P3\nM98 P2\nM30\n%\n");
        let notes: Vec<_> = taken(&text, Selection::all(), false)
            .into_iter()
            .filter(|f| f.0 == Rule::NotFollowed && f.3.contains("held more than 1024"))
            .map(|f| (f.1, f.3[..14].to_string()))
            .collect();
        assert_eq!(
            notes,
            [
                (2208, "M98 P2 calls O".to_string()),
                (2209, "M98 P3 calls O".to_string()),
                (2210, "M98 P2 calls O".to_string())
            ]
        );
    }

    /// Review 43, finding D: a call made under G91 runs a body that moves before writing a
    /// G90/G91 of its own in G91 (G90/G91 are modal; a call changes none): its X900. is an
    /// increment, not judged as absolute (callg91b.nc: a false "X spans 1600"); one TG140 at
    /// the call says why. A body that writes its own G90 first is judged as before.
    #[test]
    fn a_call_under_g91_leaves_a_body_read_in_g90_not_known() {
        let text = "%\nO0002\nG0 X900.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nG91\nM98 P2\n\
                    G90\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), []);
        let notes: Vec<_> = findings(metric.clone(), text, Rule::NotFollowed)
            .into_iter()
            .filter(|f| f.message.starts_with("M98 P2 runs O0002 under the G91"))
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(notes, [(9, 5)]);
        // called twice in G91: said once
        let twice = text.replace("M98 P2\n", "M98 P2\nM98 P2\n");
        assert_eq!(
            findings(metric.clone(), &twice, Rule::NotFollowed)
                .iter()
                .filter(|f| f.message.contains("under the G91"))
                .count(),
            1
        );
        // G65 likewise
        assert_eq!(
            limits(metric.clone(), &text.replace("M98 P2", "G65 P2")),
            []
        );
        // a body that writes G90 before it moves: absolute, X-700 then 900 (1600 mm)
        let own = text.replace("O0002\n", "O0002\nG90\n");
        assert_eq!(limits(metric.clone(), &own), [(10, 5)]);
        // in the same block as its first move, too
        let same = text.replace("O0002\nG0", "O0002\nG90 G0");
        assert_eq!(limits(metric.clone(), &same), [(9, 5)]);
        // the call in G90: judged as before
        assert_eq!(limits(metric.clone(), &text.replace("G91\n", "")), [(8, 5)]);
        // review 46, F1: a G90 of its own after its first move: the positions from there on
        // are where they are in either mode (X-900 from X700: 1600 mm)
        let after = "%\nO0002\nG0 X10.\nG90\nG0 X-900.\nM99\nO1000\nG21 G90 G54\n\
                     G0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n";
        assert_eq!(limits(metric.clone(), after), [(11, 5)]);
        // an axis first moved in G91 after it stays not known
        let relative = after.replace("G0 X-900.", "G91 G0 X-900.");
        assert_eq!(limits(metric.clone(), &relative), []);
        // review 47, F0: a position after the G90 inside the body's span so far, kept too
        // (X-950. then X10. read before it: X-900. is inside; the call runs -900 to 700)
        let inside = after.replace("O0002\nG0 X10.", "O0002\nG0 X-950.\nG0 X10.");
        assert_eq!(limits(metric.clone(), &inside), [(12, 5)]);
        // its feed is judged all the same, whatever G90/G91 (F500. in/min: 12700 mm/min)
        let fast = "%\nO0002\nG1 X1. F500.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nG91\nM98 P2\n\
                    G90\nM30\n%\n";
        assert_eq!(limits(metric, fast), [(9, 5)]);
    }

    /// Finding D on LinuxCNC: an `o<s> call` under G91 runs the definition's `G0 X250` as an
    /// increment (rs274: a call changes no mode).
    #[test]
    fn a_linuxcnc_call_under_g91_leaves_a_definition_read_in_g90_not_known() {
        let text =
            "G21 G90\no<s> sub\nG0 X250\no<s> endsub\nG0 X-250 Y0\nG92 X-400\nG91\no<s> call\nG90\nM2\n";
        assert_eq!(fired(lcnc(), text, Rule::TravelExceeded), []);
        assert!(findings(lcnc(), text, Rule::NotFollowed)
            .iter()
            .any(|f| f.line == 8 && f.message.starts_with("o<s> call runs o<s> under the G91")));
        // in G90: 650 of span, as before
        assert_eq!(
            fired(lcnc(), &text.replace("G91\n", ""), Rule::TravelExceeded),
            [(7, 1)]
        );
    }

    /// Review 43, finding A's remainder: a body's G53 position within the travel as read
    /// (X-31. read in mm) is beyond it at a call in inches (-787.4 mm, past -762): said at
    /// the call, naming the body's line; G53 ignores the call's shift. At a call in mm, or
    /// of X-30. (-762 mm), nothing.
    #[test]
    fn a_machine_position_within_the_travel_as_read_is_judged_in_the_call_s_units() {
        let text = "%\nO0002\nG53 G0 X-31.\nG53 G0 X5.\nM99\nO1000\nG20 G90 G54\nM98 P2\nM30\n%\n";
        let metric = mill(Units::Metric);
        let said = findings(metric.clone(), text, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!((said[0].line, said[0].column), (8, 5));
        assert!(
            said[0]
                .message
                .starts_with("X goes to -31 in (-787.4 mm) in machine coordinates (G53)")
                && said[0].message.contains(
                    "O0002 runs in inches as called by M98 P2 of line 8, its position of line 3"
                ),
            "{}",
            said[0].message
        );
        // under a G52 too (G53 ignores it), and called twice: said at the first call
        let shifted = text.replace("M98 P2\n", "G52 X100.\nM98 P2\nG52 X0\nM98 P2\n");
        assert_eq!(limits(metric.clone(), &shifted), [(9, 5)]);
        assert_eq!(limits(metric.clone(), &text.replace("G20", "G21")), []);
        assert_eq!(limits(metric.clone(), &text.replace("X-31.", "X-30.")), []);
        // called from inside another body read apart: said at the outer call
        let nested = "%\nO0002\nG53 G0 X-31.\nM99\nO0003\nM98 P2\nM99\nO1000\nG20 G90 G54\n\
                      M98 P3\nM30\n%\n";
        assert_eq!(limits(metric, nested), [(10, 5)]);
    }

    /// The same at a call in smaller units (a machine reset in inches, the call in G21):
    /// X-40. read in inches (-1016 mm, said as read) is -40 mm there, inside; X-800. is -800
    /// mm, beyond: judged, where one TG140 said before that none was.
    #[test]
    fn a_machine_position_is_judged_at_a_call_in_smaller_units() {
        let text = "%\nO0002\nG53 G0 X-40.\nM99\nO1000\nG21 G90 G54\nM98 P2\nM30\n%\n";
        let inch = mill(Units::Inch);
        assert_eq!(limits(inch.clone(), text), []);
        assert!(findings(inch.clone(), text, Rule::NotFollowed)
            .iter()
            .all(|f| !f.message.contains("not judged")));
        let far = text.replace("X-40.", "X-800.");
        let said = findings(inch.clone(), &far, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!((said[0].line, said[0].column), (7, 5));
        assert!(
            said[0]
                .message
                .starts_with("X goes to -800 in machine coordinates (G53), outside")
                && said[0].message.contains(
                    "O0002 runs in millimetres as called by M98 P2 of line 7, its position of \
                     line 3"
                ),
            "{}",
            said[0].message
        );
        // then a call in inches: the finding as read, said there
        let both = far.replace("M98 P2\n", "M98 P2\nG20\nM98 P2\n");
        assert_eq!(limits(inch, &both), [(7, 5), (9, 5)]);
    }

    /// The TG140s of `text` on [`mill`] in metric that begin `from`.
    fn notes(text: &str, from: &str) -> Vec<(usize, String)> {
        findings(mill(Units::Metric), text, Rule::NotFollowed)
            .into_iter()
            .filter(|f| f.message.starts_with(from))
            .map(|f| (f.line, f.message))
            .collect()
    }

    /// Review 47, F1: O1000 calls O0002 under G91; O0002 calls O0003, whose own G90 makes its
    /// X-900. absolute. A called program's G90/G91 is its caller's from the call on (G90/G91
    /// are modal and M99 restores none), so O0003's X-900 is where it is at every call of
    /// O0002: X -900..700 (1600 mm) at the G91 call (n2.nc), and with O0003 moving first
    /// (n1.nc), and one level deeper.
    #[test]
    fn a_nested_call_s_own_g90_is_seen_by_the_body_that_calls_it() {
        let n2 = "%\nO0003\nG90\nG0 X-900.\nM99\nO0002\nG0 X5.\nM98 P3\nM99\nO1000\n\
                  G21 G90 G54\nG0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), n2), [(14, 5)]);
        let said = findings(metric.clone(), n2, Rule::TravelExceeded);
        assert!(
            said[0].message.contains("X spans 1600 (from -900 to 700)")
                && said[0]
                    .message
                    .contains("O0002 runs as called by M98 P2 of line 14, its position of line 8"),
            "{}",
            said[0].message
        );
        // O0003 moves before its G90 (n1.nc): its X-900 from there on all the same
        let n1 = n2.replace("O0003\nG90\n", "O0003\nG0 X10.\nG90\n");
        assert_eq!(limits(metric.clone(), &n1), [(15, 5)]);
        // three levels: O0004's G90, called by O0003, called by O0002
        let deep = "%\nO0004\nG90\nG0 X-900.\nM99\nO0003\nG0 X1.\nM98 P4\nM99\nO0002\nG0 X5.\n\
                    M98 P3\nM99\nO1000\nG21 G90 G54\nG0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n";
        assert_eq!(limits(metric.clone(), deep), [(18, 5)]);
        // O0003's X-900. inside what O0002 reached before (review 47, F0's form): kept too
        let inside = n2.replace("O0002\nG0 X5.", "O0002\nG0 X-950.\nG0 X5.");
        assert_eq!(limits(metric.clone(), &inside), [(15, 5)]);
        // a caller's position after the call, in the G90 O0003 left: known (X-900 then,
        // after O0002's call, X700: 1600 mm)
        let after = "%\nO0003\nG90\nG0 Y1.\nM99\nO0002\nG0 X5.\nM98 P3\nG0 X-900.\nM99\nO1000\n\
                     G21 G90 G54\nG0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n";
        assert_eq!(limits(metric.clone(), after), [(15, 5)]);
        // O0003 leaves G91: O0002's X-900. after the call is an increment from where O0003
        // left the tool, not known at the G91 call
        let left91 = after.replace("G0 Y1.\n", "G0 Y1.\nG91\n");
        assert_eq!(limits(metric.clone(), &left91), []);
        // O0003 writes no G90/G91: O0002's positions as before, not known under G91
        let plain = n2.replace("O0003\nG90\n", "O0003\n");
        assert_eq!(limits(metric, &plain), []);
    }

    /// A called program's last G90/G91 is in force in its caller after the call: O0002's G91
    /// makes O1000's X900. after `M98 P2` an increment from a place not known (main read it
    /// as absolute: X -700..900, a TG601 of a path the machine does not take).
    #[test]
    fn a_subprogram_s_distance_code_is_in_force_after_its_call() {
        let text = "%\nO0002\nG91\nG0 Z1.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nM98 P2\n\
                    G0 X900.\nM30\n%\n";
        let metric = mill(Units::Metric);
        assert_eq!(limits(metric.clone(), text), []);
        // its own G90 at its end: absolute after it, as read
        let back = text.replace("G0 Z1.\n", "G0 Z1.\nG90\n");
        assert_eq!(limits(metric, &back), [(11, 4)]);
    }

    /// Where the nesting cannot be followed, the G91 call's TG140 says the called program's
    /// G90/G91 is not followed: a program after it in the file, itself, a number not known,
    /// a Haas's M97.
    #[test]
    fn a_nested_call_not_followed_is_named_in_the_g91_note() {
        let later = "%\nO0002\nG0 X5.\nM98 P3\nM99\nO1000\nG21 G90 G54\nG0 X700. Y0\nG91\n\
                     M98 P2\nG90\nM30\nO0003\nG90\nG0 X-900.\nM99\n%\n";
        let said = notes(later, "M98 P2 runs O0002 under the G91");
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!(said[0].0, 10);
        assert!(
            said[0]
                .1
                .contains("the G90 or G91 of a program its M98 P3 of line 4 runs is not followed"),
            "{}",
            said[0].1
        );
        for (call, token) in [
            ("M98 P2", "M98 P2 of line 4"),
            ("M98 P#1", "M98 P#1 of line 4"),
            ("M97 P100", "M97 P100 of line 4"),
        ] {
            let text = later.replace("O0002\nG0 X5.\nM98 P3", &format!("O0002\nG0 X5.\n{call}"));
            let said = notes(&text, "M98 P2 runs O0002 under the G91");
            assert!(
                said.len() == 1 && said[0].1.contains(token),
                "{call}: {said:?}"
            );
        }
        // review 48, F18: M97 runs the blocks of the same program from its N to an M99 (a Haas
        // local subprogram call), not another program (review 48's h97.nc)
        let h97 = "%\nO2000\nG0 X100.\nM97 P100\nG0 X200.\nM99\nN100 G90\nM99\nO1000\n\
                   G20 G90 G54 G17\nG0 X0. Y0\nG91\nM98 P2000\nM30\n%\n";
        let said = notes(h97, "M98 P2000 runs O2000 under the G91");
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!(said[0].0, 13);
        assert!(
            said[0].1.contains(
                "the G90 or G91 of the blocks its M97 P100 of line 4 runs (O2000's from N100 to \
                 an M99: a local subprogram call) is not followed (the checker does not follow \
                 that call)"
            ) && !said[0].1.contains("a program its M97"),
            "{}",
            said[0].1
        );
        // its P by a parameter: the sequence named so
        let said = notes(
            &h97.replace("M97 P100", "M97 P#1"),
            "M98 P2000 runs O2000 under the G91",
        );
        assert!(
            said.len() == 1
                && said[0].1.contains(
                    "its M97 P#1 of line 4 runs (O2000's from the sequence number its P gives \
                     to an M99"
                ),
            "{said:?}"
        );
        // followed: no such words
        let before = "%\nO0003\nG0 X1.\nM99\nO0002\nG0 X5.\nM98 P3\nM99\nO1000\nG21 G90 G54\n\
                      G0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n";
        let said = notes(before, "M98 P2 runs O0002 under the G91");
        assert!(
            said.len() == 1 && !said[0].1.contains("not followed"),
            "{said:?}"
        );
        // a program called inside one that calls a program not followed: named there too
        let inner = "%\nO0003\nG0 X1.\nM98 P9\nM99\nO0002\nG0 X5.\nM98 P3\nM99\nO1000\n\
                     G21 G90 G54\nG0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n";
        let said = notes(inner, "M98 P2 runs O0002 under the G91");
        assert!(
            said.len() == 1
                && said[0]
                    .1
                    .contains("its M98 P9 of line 4 runs is not followed"),
            "{said:?}"
        );
    }

    /// Review 46, F5: a body's span too wide at a call names the lines of both its ends where
    /// both are the span's (X-35. of line 4 made it wide, not X30. of line 5).
    #[test]
    fn a_body_s_span_names_both_its_lines() {
        let text = "%\nO0002\nG0 X30.\nG0 X-35.\nG0 X30.\nM99\nO1000\nG20 G90 G54\nM98 P2\n\
                    M30\n%\n";
        let said = findings(mill(Units::Metric), text, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].message.contains(
                "O0002 runs in inches as called by M98 P2 of line 9, its positions of lines 4 \
                 and 5 there"
            ),
            "{}",
            said[0].message
        );
        // the caller's X-40. the span's least: the body's most alone
        let caller = text.replace("G54\nM98", "G54\nG0 X-40. Y0\nM98");
        let said = findings(mill(Units::Metric), &caller, Rule::TravelExceeded);
        assert!(
            said.len() == 1 && said[0].message.contains("its position of line 5 there"),
            "{said:?}"
        );
    }

    /// Review 46, F5: a body's G53 position read with no units code written, said at a call
    /// made after a G20: not "the program has written no units code by here".
    #[test]
    fn a_machine_position_said_at_a_call_after_a_units_code_says_no_units_remark() {
        let mut inch = mill(Units::Inch);
        inch.facts.limit_units = Units::Inch;
        inch.facts.travel = vec![(b'X', Dec::parse("-30").unwrap(), Dec::parse("30").unwrap())];
        let text = "%\nO0002\nG53 G0 X-35.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n";
        let said = findings(inch.clone(), text, Rule::TravelExceeded);
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!(said[0].line, 8);
        assert!(
            !said[0].message.contains("no units code") && said[0].message.contains("O0002 runs"),
            "{}",
            said[0].message
        );
        // called where no units code was written: the remark stays
        let unwritten = text.replace("G20 G90", "G90");
        let said = findings(inch, &unwritten, Rule::TravelExceeded);
        assert!(
            said.len() == 1 && said[0].message.contains("no units code by here"),
            "{said:?}"
        );
    }

    /// Review 46, F6: a program given up past HOLD_ALL findings of any rule is noted naming
    /// that bound, not "more than 1024 findings".
    #[test]
    fn a_program_given_up_is_noted_with_the_bound_it_passed() {
        let mut text = String::from("%\nO0002\nG53 G0 X-800.\n");
        for _ in 0..4200 {
            text.push_str("M456\n");
        }
        text.push_str("G0 X700.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n");
        let said: Vec<_> = taken(&text, Selection::all(), false)
            .into_iter()
            .filter(|f| f.0 == Rule::NotFollowed && f.3.starts_with("M98 P2 calls O0002"))
            .collect();
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].3.contains(
                "more than 4096 findings of any rule were made after its first finding of the \
                 travel and feed limits"
            ) && !said[0].3.contains("1024"),
            "{}",
            said[0].3
        );
    }

    /// Review 47, F1 on LinuxCNC: `o<b>`'s own G90 makes its X-330 absolute at every call of
    /// `o<a>`, which calls it: 610 of span from X280 at the G91 call. `o<b>`'s G90 is in force
    /// after its return, as it writes no M70-M73 (review 48, F16: it was said not followed).
    #[test]
    fn a_linuxcnc_nested_call_s_own_g90_is_seen_by_the_body_that_calls_it() {
        let text = "G21 G90\no<b> sub\nG90\nG0 X-330\no<b> endsub\no<a> sub\nG0 X5\no<b> call\n\
                    o<a> endsub\nG0 X280 Y0\nG91\no<a> call\nG90\nM2\n";
        assert_eq!(fired(lcnc(), text, Rule::TravelExceeded), [(12, 1)]);
        assert!(findings(lcnc(), text, Rule::NotFollowed)
            .iter()
            .any(|f| f.line == 12
                && f.message.starts_with("o<a> call runs o<a> under the G91")
                && !f.message.contains("not followed")));
        // with an M73 before its G90, the caller's G91 comes back at its return: o<a>'s
        // positions after the call are not known at the G91 call
        let restores = text.replace("o<b> sub\nG90\n", "o<b> sub\nM73\nG90\n");
        assert_eq!(fired(lcnc(), &restores, Rule::TravelExceeded), [(13, 1)]);
    }
}
