//! The blocks a Custom Macro B jump surely taken passes over (issue 32, review 48's t1.nc).
//!
//! FANUC's `GOTO n` branches to the block of sequence number n: the control searches the
//! program for it and goes on from there, and an `IF [..] GOTO n` does so where its condition
//! holds (Custom Macro B, "Branch and repetition": Unconditional branch (GOTO statement),
//! Conditional branch (IF statement); a Haas's the same, Mill Operator's Manual, "Macros").
//! The blocks between the jump and its target are passed over: the control reads them for
//! the N it looks for, and runs none of them. Where the jump is surely taken -- a `GOTO n`
//! outside an IF, or an IF whose condition the values the checker knows make true
//! ([`Checker::condition_known`]: `#1=1` / `IF [#1 EQ 1] GOTO 10`) -- and its target comes
//! forward in the same program, the file's reading takes those blocks as not run: they are
//! still read (a block the checker cannot read, a word past its format, a code the profile
//! does not have are said, as the text is the program's), but no finding of what running
//! them would do (TG4xx-TG6xx: moves, arcs, feeds, cycles, the travel and the machine's
//! maxima; TG140/TG141, what is followed; TG106, words after an end) is said of them, and the
//! target starts from the state the jump left: the positions, modes, parameters and
//! statistics of the blocks passed over are not the machine's.
//!
//! Only where that is sure from the text, as [`super::reach`] reads it: the blocks passed over
//! carry no sequence number and no loop statement (a block with an N may be named by another
//! jump, a call's `M97 P`, a return's `M99 P` or a lathe cycle's P/Q, and so run: the first
//! such block ends the passage, and if it is not the target the blocks after it are judged
//! as before); no computed `GOTO #1` is read (a jump read before to the same target arrives
//! there, not between: the target then starts from what both leave, [`Passed::shared`]);
//! the jump is not under the `/` switch nor
//! inside a `WHILE` loop, not read apart as a subprogram's body (called.rs) and no jump's run
//! is being read beside the file's (params.rs); the blocks passed over leave the units and the
//! feed mode as the jump found them (the target's words are read in them before the passage
//! ends at it). Where the target does not come (the program ends first: TG118), nothing
//! changes: the blocks are judged as before, their findings said in their order when the
//! passage ends.

use super::{BlockView, Checker};
use crate::lex::Family;
use crate::rules::Rule;
use crate::statement::Kind;
use std::collections::HashMap;

/// A passage over the blocks after a jump surely taken, until its target.
#[derive(Clone)]
pub(super) struct Passed {
    /// The jump's line and its target's sequence number, and whether it has a condition.
    line: usize,
    target: u64,
    conditional: bool,
    /// Whether a jump read before it names its target too (an `IF [..] GOTO 44` before a
    /// `GOTO 44`): the target is reached from either, and starts from what both leave --
    /// the position, feed and speed not known (the earlier jump's are not kept) but for no
    /// feed ever set on either way (`no_feed`), the parameters those of an arrival
    /// ([`Checker::jump_arrival`]).
    shared: bool,
    /// The checker as the jump left it (its run state is the target's).
    run: Box<Checker>,
    /// Whether the jump left no feed ever set (the reset state's none, not one forgotten).
    no_feed: bool,
    /// The length of the path at the jump, and whether the sample machine's hint was said
    /// (a run's copy takes it as said: [`Checker::run_of`]).
    path: usize,
    hint_said: bool,
    /// The jumps read before the jump, by target (the jump's own taken out: at its target
    /// the values are its alone, no arrival of another).
    goto_targets: HashMap<u64, (usize, bool)>,
    /// Where the findings made since the jump start in the checker's list: held there (not
    /// handed over: [`Checker::take`], [`Checker::drain`]) until the passage ends, and then
    /// said, but for those of running the blocks passed over where the target comes.
    pub(super) from: usize,
}

/// What a jump's block left before the checker forgot it, not following the jump
/// ([`Checker::left`]): a `GOTO n` with no condition forgets the parameters as it is read
/// (no run is kept for its target), but where it is surely taken its target is reached from
/// it alone and starts with them, as a known-true IF's does (review 53, F17).
#[derive(Clone)]
pub(super) struct Left {
    machine: crate::modal::ModalMachine,
    params: HashMap<Vec<u8>, crate::decimal::Dec>,
    arrival: Option<super::params::Arrival>,
}

/// Whether a finding of `rule` is of running its block (dropped for a block passed over),
/// not of reading its text.
fn of_running(rule: Rule) -> bool {
    let id = rule.id();
    matches!(id.as_bytes().get(2), Some(b'4' | b'5' | b'6'))
        || matches!(
            rule,
            Rule::NotFollowed | Rule::NotEvaluated | Rule::WordsAfterEndNotRun
        )
}

impl Checker {
    /// At the end of block `b` (`after_block`): a passage starts where `b` surely jumps
    /// forward ([`Passed`]).
    #[cold]
    #[inline(never)]
    pub(super) fn passage_started(&mut self, b: &BlockView<'_>) {
        let left = self.jump_left.take();
        if self.config.family != Family::MacroB
            || self.passed.is_some()
            || self.run_target != 0
            || self.hold_from.is_some()
            || self.early_on
            || !self.runs.is_empty()
            || self.goto_computed
            || b.skip
            || b.skip_within.is_some()
            || self.reach.loops > 0
        {
            return;
        }
        // one jump forward, nothing else the checker does not follow
        let Some(conditional) = self.forward_jump(b) else {
            return;
        };
        let Some(upper) = b
            .statements
            .iter()
            .filter(|s| s.1 == Kind::Flow)
            .find_map(|s| self.jump_upper(s.2))
        else {
            return;
        };
        if conditional && self.condition_known(&upper) != Some(true) {
            return;
        }
        let Some(target) = super::targets::goto_words(&upper)
            .and_then(|(_, digits, _)| crate::text::digits_value(digits))
        else {
            return;
        };
        // (no jump read before names the target, or one does: it arrives at the target, not
        // in the blocks between, which this jump passes over all the same -- review 56b, F6:
        // `IF [#5 EQ 1] GOTO 44` / `GOTO 44` / `G0 X850.` / `N44 ...`: X850 runs on no path --
        // and the target is then an arrival of both, [`Passed::shared`]; a GOTO outside an IF
        // left as reach.rs reads it)
        let shared = match self.goto_targets.get(&target) {
            Some(&(line, false)) if line == b.line => false,
            Some(&(line, true)) if line < b.line => true,
            _ => return,
        };
        // (nor does a run kept for a jump a run met: it arrives there too; one kept for the
        // jump read before to the same target starts there as any arrival's)
        let key = format!("N{target}");
        if !shared
            && self
                .jumps_pending
                .iter()
                .any(|t| t.to(key.as_bytes()) && !t.own_of(b.line))
        {
            return;
        }
        if conditional {
            self.reach.left = Some((b.line, super::reach::Leaving::Jump));
        } else if self.reach.left.is_none_or(|(line, _)| line != b.line) {
            return;
        }
        let mut goto_targets = self.goto_targets.clone();
        if !shared {
            goto_targets.remove(&target);
        }
        let mut run = self.run_of();
        let mut no_feed = false;
        // (the position, feed and speed the jump's block left: the checker forgot them, as it
        // does at a jump it does not follow, and the blocks passed over never run -- review
        // 51, F14; "no feed ever set" stays so, review 53, F2 -- and the parameters, which a
        // `GOTO n` with no condition forgot as it was read: review 53, F17)
        if let Some(left) = left {
            let Left {
                machine,
                params,
                arrival,
            } = *left;
            run.machine.kept_of(&machine);
            // (none forgotten at jumps before it counts only where every jump read names this
            // target: one to a block after it may come back with a feed before the first
            // arrival; review 57c, F5)
            let forgotten = machine.state.unknown & crate::modal::bit(b'F') != 0;
            no_feed = machine.feed_never_set()
                && (!forgotten
                    || !self.goto_computed && self.goto_targets.keys().all(|&n| n == target));
            run.params = params;
            run.arrival = arrival;
        }
        self.passage_noted(b.line, target);
        self.passed = Some(Box::new(Passed {
            line: b.line,
            target,
            conditional,
            shared,
            run,
            no_feed,
            path: self.path.len(),
            hint_said: self.limits_hint_said,
            goto_targets,
            from: self.found.len(),
        }));
    }

    /// A jump or call the checker does not follow (block `b`; `calls`: a calling word): what
    /// the machine knows is forgotten, but a `GOTO n` read where no feed was ever set keeps
    /// that for the ways it makes (ModalMachine::feed_none_kept).
    /// A G10 before it whose L or P is a #-expression may run again with another value
    /// where the jump goes back: its axes of every offset written ([`Checker::g10_expression`]).
    pub(super) fn forget_at_jump(&mut self, b: &BlockView<'_>, calls: bool) {
        if self.reexpressed_held.is_some() {
            self.reexpression_comes_back(b.line);
        }
        self.jumped |= !calls;
        self.shift_unsure |= !calls;
        let expression = self.g10_expression | self.g10_local;
        if expression != 0 && !calls && self.forward_jump(b).is_none() {
            let every = super::limits::Written::on_every(expression);
            self.offsets_written.then(&every);
        }
        let kept = !calls && self.machine.feed_never_set() && self.goto_only(b);
        self.machine.forget();
        self.machine.feed_none_kept = kept;
    }

    /// What a jump's block leaves as it ends, before the checker forgets it (TG140):
    /// where the jump is surely taken, the position its target starts from.
    pub(super) fn left(&self) -> Left {
        Left {
            machine: self.machine.clone(),
            params: self.params.clone(),
            arrival: self.arrival.clone(),
        }
    }

    /// The note (TG140) the jump on line `line` made, said of a jump the checker does not
    /// follow, says what it does with one surely taken (review 51, F19): true whether the
    /// target comes or the passage is given up.
    fn passage_noted(&mut self, line: usize, target: u64) {
        let Some(note) = self
            .found
            .iter_mut()
            .rev()
            .find(|f| f.line == line && f.rule == Rule::NotFollowed)
        else {
            return;
        };
        let Some(what) = note.message.split(": the checker").next() else {
            return;
        };
        note.message = format!(
            "{what}: the jump is surely taken: where its target N{target} is the next numbered \
             block, the blocks up to it are read but not run, and the target starts from the \
             position, modes and parameters the jump left; otherwise the checker reads on in \
             file order, the position, feed and speed taken as unknown until the program sets \
             them"
        );
    }

    /// Whether the unreached part after line `left` is a passage after a jump with a
    /// condition (the values known make it true).
    pub(super) fn passage_conditional(&self, left: usize) -> bool {
        self.passed
            .as_ref()
            .is_some_and(|p| p.conditional && p.line == left)
    }

    /// Block `b` while a passage is open (asked where a jump may arrive, before the block's
    /// words are read: a passage keeps its target among the jumps read): it ends where `b`
    /// ends the unreached part -- its sequence number, or a loop's statement, as
    /// [`super::reach`] reads it; at the target only where that is its N (a loop's statement
    /// without it ends the passage as any other block there).
    #[cold]
    #[inline(never)]
    pub(super) fn passage_block(&mut self, b: &BlockView<'_>) {
        if self.reach.resumed == b.line {
            self.passage_ended(Some(b));
        }
    }

    /// The passage ends at block `b` (None: at a program's end, a `%` or the file's end):
    /// where `b` is its target, the file's reading goes on from the state the jump left, the
    /// findings of running the blocks between dropped; elsewhere every finding held is said.
    #[cold]
    #[inline(never)]
    pub(super) fn passage_ended(&mut self, b: Option<&BlockView<'_>>) {
        let Some(passed) = self.passed.take() else {
            return;
        };
        let Passed {
            line,
            target,
            shared,
            run,
            no_feed,
            path,
            hint_said,
            goto_targets,
            from,
            ..
        } = *passed;
        let arrived = b.filter(|b| {
            b.words
                .iter()
                .find(|w| w.letter == b'N' && w.expression.is_empty())
                .and_then(|w| w.value.filter(|_| !w.point))
                == Some(target)
        });
        // (the target's units and feed mode are read before this, with the modes in force
        // (`Checker::block_modes`): where the blocks passed over changed them, the target is
        // judged as before)
        let modes = |c: &Checker| {
            let s = &c.machine.state;
            (s.units, s.feed_units, s.feed_mode)
        };
        let Some(b) = arrived.filter(|_| modes(self) == modes(&run)) else {
            // (judged as before, but the jump's arrival at its target is its first, and has
            // the feed the jump left: none ever set stays none, whatever a block between
            // sets -- review 53, F2)
            if no_feed && b.is_some() {
                self.no_feed_target = target;
                if let Some(b) = arrived {
                    self.no_feed_arrival(b);
                }
            }
            return;
        };
        let mut i = 0;
        self.found.retain(|f| {
            i += 1;
            // (the target's own so far: a TG106 after an M30 passed over)
            i <= from || !(f.line > line && f.line <= b.line && of_running(f.rule))
        });
        self.path.truncate(path);
        self.goto_targets = goto_targets;
        // (the run kept for the jump is the passage's own; those kept for jumps read between
        // are not run)
        self.jumps_pending
            .retain(|t| !t.own_of(line) && !t.own_after(line));
        self.run_state_of(*run);
        self.limits_hint_said = hint_said;
        if shared {
            // (the jump read before arrives with the state it left, which the checker did not
            // keep: what the file's reading forgot at it is forgotten here too)
            self.machine.forget();
            // (but no feed ever set on either way stays none: review 57c F5, review 55b F3:
            // `IF [#5 EQ 1] GOTO 44` / `GOTO 44` / `F100.` / `N44 G1 X-7.` is TG401)
            if no_feed {
                self.machine.no_feed();
            }
            self.motion_unknown = true;
            self.polar = super::polar::Polar::default();
        }
    }

    /// Block `b` where a jump surely taken, whose passage was given up, left no feed ever set
    /// ([`Checker::no_feed_target`]): at its target, the feed is none. Where no jump read
    /// before names a block between, the jump runs before any way into one can (a jump back
    /// read after the target), so the target's first run has the jump's feed, and a feed
    /// move there without F is TG401 on a run that surely occurs (a FANUC's or a Haas's F is
    /// modal: "no feed" until an F is given). A block between that a jump read names gives
    /// that up: a way into it may come first.
    #[cold]
    #[inline(never)]
    pub(super) fn no_feed_arrival(&mut self, b: &BlockView<'_>) {
        let Some(n) = b
            .words
            .iter()
            .find(|w| w.letter == b'N' && w.expression.is_empty())
            .and_then(|w| w.value.filter(|_| !w.point))
        else {
            return;
        };
        if n == self.no_feed_target {
            self.no_feed_target = 0;
            self.machine.no_feed();
        } else if self.goto_computed || self.goto_targets.contains_key(&n) {
            self.no_feed_target = 0;
        }
    }

    /// The state of running the program taken from `run` (the checker at a jump): the
    /// machine, the parameters, the spans and the statistics of the moves, the frames,
    /// shifts and modes the rules keep, and the notes said once of what running finds; what
    /// reading the text finds (the sequence numbers, the formats, the reading errors, the
    /// blocks counted) stays the file's.
    fn run_state_of(&mut self, run: Checker) {
        let blocks = self.stats.blocks;
        let lists = (
            std::mem::take(&mut self.stats.travel_not),
            std::mem::take(&mut self.stats.moves_not_known),
            std::mem::take(&mut self.stats.dwells_not_known),
        );
        self.stats = run.stats;
        self.stats.blocks = blocks;
        (
            self.stats.travel_not,
            self.stats.moves_not_known,
            self.stats.dwells_not_known,
        ) = lists;
        self.machine = run.machine;
        self.inside = run.inside;
        self.spans = run.spans;
        self.params = run.params;
        self.arrival = run.arrival;
        self.ended_line = run.ended_line;
        self.after_watch = run.after_watch;
        self.skipped_end = run.skipped_end;
        self.surely_ended = run.surely_ended;
        self.sub_ended = run.sub_ended;
        self.cut_block = run.cut_block;
        self.after_end_reported = run.after_end_reported;
        self.arc_cause_said = run.arc_cause_said;
        self.unfollowed_noted = run.unfollowed_noted;
        self.unknown_noted = run.unknown_noted;
        self.quiet_d = run.quiet_d;
        self.assigned_at = run.assigned_at;
        self.g06_open = run.g06_open;
        self.speed_limit_seen = run.speed_limit_seen;
        self.travel = run.travel;
        self.centre_kept = run.centre_kept;
        self.centre_lost = run.centre_lost;
        self.diameter_mode = run.diameter_mode;
        self.polar = run.polar;
        self.polar_arc = run.polar_arc;
        self.opening_arc = run.opening_arc;
        self.radius_arc = run.radius_arc;
        self.work = run.work;
        self.offsets_lost = run.offsets_lost;
        // (a G10 passed over writes nothing: review 59a F2)
        self.offsets_written = run.offsets_written;
        self.g10_expression = run.g10_expression;
        self.g10_local = run.g10_local;
        self.offset_writers = run.offset_writers;
        self.frames = run.frames;
        self.noted = run.noted;
        self.mode_lost_codes = run.mode_lost_codes;
        self.mode_lost_by = run.mode_lost_by;
        self.shifts = run.shifts;
        self.transformed = run.transformed;
        self.length_decimal = run.length_decimal;
        self.motion_unknown = run.motion_unknown;
        self.cycle_unmodelled = run.cycle_unmodelled;
        self.data_input = run.data_input;
        self.compensation_exit = run.compensation_exit;
        self.call_units = run.call_units;
        self.call_works = run.call_works;
        self.call_works_unknown = run.call_works_unknown;
        self.call_works_seen = run.call_works_seen;
        self.units_unknown = run.units_unknown;
        self.unknown_call = run.unknown_call;
        self.feed_pending = run.feed_pending;
        self.feed_unheld = run.feed_unheld;
        self.outside = run.outside;
        self.meanings = run.meanings;
        self.meanings_none = run.meanings_none;
        self.shapes = run.shapes;
        self.goto_computed = run.goto_computed;
        self.goto_computed_line = run.goto_computed_line;
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{fired, of_family, program};
    use crate::lex::Family;
    use crate::rules::Rule;

    /// A FANUC (Custom Macro B, its O numbers) on the iso-mill's machine: X -500..500.
    fn fanuc() -> super::super::Config {
        let mut config = of_family(Family::MacroB);
        config.facts.program_number = Some(b'O');
        config
    }

    fn travel(body: &str) -> Vec<(usize, usize)> {
        fired(fanuc(), &program(body), Rule::TravelExceeded)
    }

    /// Review 48's t1.nc: the blocks a jump surely taken passes over are not run -- no
    /// finding of their moves -- whether the jump has no condition or one the known values
    /// make true (lines: 1 `%`, 2 `G0`, ...).
    #[test]
    fn the_blocks_a_jump_surely_taken_passes_over_are_not_run() {
        for jump in [
            "#1=1\nIF [#1 EQ 1] GOTO 10",
            "#1=1\nGOTO 10",
            "IF [1 EQ 1] GOTO10",
        ] {
            let body = format!("G0 X0 Y0\n{jump}\nG1 X9999. F100.\nN10 G0 X10. Y0");
            assert_eq!(travel(&body), [], "{jump}");
        }
        // the condition not known, or false: judged, as before
        for jump in ["#1=1\nIF [#5 EQ 1] GOTO 10", "#1=0\nIF [#1 EQ 1] GOTO 10"] {
            let body = format!("G0 X0 Y0\n{jump}\nG1 X9999. F100.\nN10 G0 X10. Y0");
            assert_eq!(travel(&body).len(), 1, "{jump}");
        }
    }

    /// The target starts from the state the jump left: a G91 and an assignment passed over
    /// are not in force there, and the values known at the jump are (no arrival forgets
    /// them: TG141 is not said). `X#2` goes to X-700 from X400: an 1100 span, at its word.
    #[test]
    fn the_target_starts_where_the_jump_left() {
        let body = "G0 X400. Y0\n#2=-700.\n#1=1\nIF[#1EQ1]GOTO10\nG91\n#2=0\nN10 G0 X#2";
        assert_eq!(travel(body), [(8, 8)]);
        assert_eq!(fired(fanuc(), &program(body), Rule::NotEvaluated), []);
        // a G91 passed over: X100. twice is X100, not X200 (no TG601 from X-450)
        let body = "G0 X-450. Y0\nGOTO10\nG91\nN10 G0 X100.\nX100.";
        assert_eq!(travel(body), []);
    }

    /// Review 51, F14: the target starts from the position the jump's block left (the blocks
    /// passed over never run): an increment there is followed, and a move out of the travel
    /// found, after a GOTO or an IF whose condition holds. X0 + 850 from X-700 is a 1350 span
    /// (travel X -500..500), at the target's X (column 12).
    #[test]
    fn an_increment_at_the_target_starts_where_the_jump_left() {
        for jump in ["GOTO10", "#1=1\nIF[#1EQ1]GOTO10"] {
            let body = format!("G0 X-700. Y0\nG0 X0\n{jump}\nG0 X10.\nN10 G91 G0 X650.\nG90");
            let line = 5 + jump.lines().count();
            assert_eq!(travel(&body), [(line, 12)], "{jump}");
            let found =
                super::super::testing::findings(fanuc(), &program(&body), Rule::TravelExceeded);
            assert!(
                found[0]
                    .message
                    .starts_with("X spans 1350 (from -700 to 650)"),
                "{}",
                found[0].message
            );
        }
        // a numbered block between: the passage is given up, the X10. run (a 1360 span)
        let body = "G0 X-700. Y0\nG0 X0\nGOTO10\nN5 G0 X10.\nN10 G91 G0 X650.\nG90";
        let found = super::super::testing::findings(fanuc(), &program(body), Rule::TravelExceeded);
        assert_eq!(found.len(), 1);
        assert!(
            found[0]
                .message
                .starts_with("X spans 1360 (from -700 to 660)"),
            "{}",
            found[0].message
        );
    }

    /// Review 53, F17: a `GOTO` with no condition keeps the parameters for its target, as a
    /// known-true IF does: `X#1` there is X-700, a 1100 span from X400 (travel X -500..500),
    /// at its word, and no TG141. Where a numbered block between may be another way in, the
    /// values are not known there (TG141, no span), as before.
    #[test]
    fn a_goto_keeps_the_parameters_for_its_target() {
        let body = "G0 X400. Y0\n#1=-700.\nGOTO26\nG0 X5.\nN26 G0 X#1";
        assert_eq!(travel(body), [(6, 8)]);
        assert_eq!(fired(fanuc(), &program(body), Rule::NotEvaluated), []);
        let body = "G0 X400. Y0\n#1=-700.\nGOTO26\nN20 #1=0\nN26 G0 X#1";
        assert_eq!(travel(body), []);
        assert_eq!(fired(fanuc(), &program(body), Rule::NotEvaluated), [(6, 8)]);
    }

    /// Review 53, F2: a jump surely taken from where no F was ever given arrives with none:
    /// a feed move at its target is TG401 (as without the jump), whether the blocks between
    /// are passed over or a numbered one gives the passage up -- an F between is not run
    /// before the target's first run. An F at the target, or before the jump, is in force.
    #[test]
    fn a_jump_surely_taken_keeps_no_feed_for_its_target() {
        let no_feed = |body: &str| fired(fanuc(), &program(body), Rule::NoFeedRate);
        for between in ["G0 X5.", "G1 X1. F100.", "N5 F100.", "N5 G1 X1. F100."] {
            let body = format!("G0 X0 Y0 Z10.\nGOTO10\n{between}\nN10 G1 Z-1.\nX50.");
            assert_eq!(no_feed(&body), [(5, 8), (6, 1)], "{between}");
        }
        for body in [
            "G0 X0 Y0 Z10.\nGOTO10\nN5 F100.\nN10 G1 Z-1. F50.\nX50.",
            "G0 X0 Y0 Z10. F50.\nGOTO10\nN5 G0 X5.\nN10 G1 Z-1.\nX50.",
            "G0 X0 Y0 Z10.\nGOTO10\nG0 X5.\nN10 F50.\nG1 Z-1.",
            // (a jump read before may come to N5 first, with its F)
            "G0 X0 Y0 Z10.\nIF[#5EQ1]GOTO5\nGOTO10\nN5 F100.\nN10 G1 Z-1.\nX50.",
        ] {
            assert_eq!(no_feed(body), [], "{body}");
        }
    }

    /// Review 51, F19: the note at a jump surely taken says what the checker does with it,
    /// not that it follows no jump.
    #[test]
    fn the_note_at_a_jump_surely_taken_says_it_is_followed() {
        let body = "G0 X0 Y0\nGOTO10\nG0 X10.\nN10 G0 X1.";
        let found = super::super::testing::findings(fanuc(), &program(body), Rule::NotFollowed);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].line, found[0].column), (3, 1));
        assert!(
            found[0]
                .message
                .starts_with("GOTO10 (flow): the jump is surely taken: where its target N10"),
            "{}",
            found[0].message
        );
        // a jump not surely taken keeps the note of a jump not followed
        let body = "G0 X0 Y0\nIF[#5EQ1]GOTO10\nG0 X10.\nN10 G0 X1.";
        let found = super::super::testing::findings(fanuc(), &program(body), Rule::NotFollowed);
        assert!(
            !found[0].message.contains("surely taken"),
            "{}",
            found[0].message
        );
    }

    /// Reading the blocks passed over: a line the checker cannot read stays an error after
    /// an IF whose condition holds (the condition is the checker's reading of the values),
    /// and is TG108 after a GOTO outside an IF, as before (reach.rs).
    #[test]
    fn the_blocks_passed_over_are_still_read() {
        let body = "#1=1\nIF[#1EQ1]GOTO10\nG1 X9999. F100.\n---\nN10 G0 X0 Y0";
        assert_eq!(fired(fanuc(), &program(body), Rule::Unreadable), [(5, 1)]);
        assert_eq!(fired(fanuc(), &program(body), Rule::NeverRun), []);
        let body = "GOTO10\nG1 X9999. F100.\n---\nN10 G0 X0 Y0";
        assert_eq!(fired(fanuc(), &program(body), Rule::NeverRun), [(4, 1)]);
        // a word past its format passed over is said (the text is the program's)
        let body = "GOTO10\nG1 X1.23456789 F100.\nN10 G0 X0 Y0";
        assert_eq!(
            fired(fanuc(), &program(body), Rule::TooManyDigits).len(),
            1,
            "{body}"
        );
    }

    /// Where the checker cannot be sure the blocks are passed over, they are judged as
    /// before: the target not in the program (TG118), a numbered block between (a jump,
    /// call or return may name it), a `/` jump, a jump inside a WHILE loop, a jump back.
    #[test]
    fn where_the_passage_is_not_sure_nothing_changes() {
        for body in [
            "G0 X0 Y0\nGOTO30\nG1 X9999. F100.\nN10 G0 X1. Y0",
            "G0 X0 Y0\n#1=1\nIF[#1EQ1]GOTO20\nG1 X9999. F100.\nN10 G0 X1. Y0\nN20 G0 X2.",
            "G0 X0 Y0\n/GOTO10\nG1 X9999. F100.\nN10 G0 X1. Y0",
            "G0 X0 Y0\nWHILE[#5LT1]DO1\nGOTO10\nG1 X9999. F100.\nN10 G0 X1. Y0\nEND1",
            "N5 G0 X0 Y0\n#1=1\nIF[#1EQ1]GOTO5\nG1 X9999. F100.\nN10 G0 X1. Y0",
        ] {
            assert_eq!(travel(body).len(), 1, "{body}");
        }
        // another jump to the target read before arrives there, not between: the blocks are
        // passed over all the same (review 56b, F6)
        let body =
            "G0 X0 Y0\nIF[#5EQ1]GOTO10\n#1=1\nIF[#1EQ1]GOTO10\nG1 X9999. F100.\nN10 G0 X1. Y0";
        assert_eq!(travel(body), []);
    }
}
