//! Calls after a jump or inside a loop (issue 32 item 4): a FANUC's or a Haas's `WHILE [..]
//! DO1` ... `END1`, `GOTO n`, `IF [..] GOTO n` before an `M98`, `M97` or `G65` of the main
//! program.
//!
//! The checker reads the program in file order and does not follow a jump or a loop: at the
//! first it takes the work offsets as lost ([`Checker::offsets_rewritten`]), and a body called
//! after it was judged under none. Where nothing the run can reach after that first jump or
//! loop, to the main program's end, changes the offset or the modes a body is judged in -- no
//! G54-G59, no write of an offset (G10, a system variable), no shift or frame (G52, G92, G68,
//! G51...), no G90/G91, no G20/G21, no G43/G44/G49, no call of a body that may change them --
//! every path to a call there arrives with the offset and modes in force at that jump, which
//! are those the call reads in file order: the body is judged under them at that call (once:
//! a body whose positions are absolute runs the same positions at each pass of a loop).
//!
//! Which of those hold is known only at the main program's end (a loop's `END1` or a jump
//! back may bring a later selection to a call before it): a body read before the main
//! program is judged at its call, its findings held ([`PENDING_FLOW`]) and dropped at the
//! main program's end where something changed; the calls of a body read after it (after the
//! main's M30) are kept with the offset, and taken as made under none at the main's end
//! where something changed. A body read later whose G90/G91 is not known at its call is the
//! only one of its kind the region may call (its first run is the one judged: the modes the
//! region's own blocks could change are those of the jump; a second body read later may
//! change what the first runs under at its next pass); a region calling a body read later
//! keeps no finding of a body read before (that body may change the offsets their next pass
//! runs under).
//!
//! `O1000` / `G21 G90 G54` / `G55` / `#1=0` / `WHILE [#1 LT 3] DO1` / `M98 P2000` /
//! `#1=#1+1` / `END1` / `M30` / `O2000` / `G0 X-700.` / `M99` (fanuc-mill, X -762..762, G55
//! X -100): each of the three passes runs X-700. at machine -800 (FANUC Custom Macro B,
//! "WHILE [conditional expression] DO m ... END m": the blocks between run while the
//! condition holds; the offsets modal), said at line 6.

use super::{BlockView, Checker};
use crate::lex::Family;
use crate::statement::Kind;

/// Among a finding's [`super::Finding::pending_on`]: a finding of a body read before the main
/// program, judged at a call after a jump or inside a loop under the offset in force at the
/// jump: dropped at the main program's end where the region changed it. Between
/// [`super::limits::PENDING_MODE_SELF`]'s and [`super::callmode::PENDING_CALL_MODE`]'s marks.
pub(super) const PENDING_FLOW: i64 = super::limits::PENDING_MODE_SELF - 32;

/// What the main program had in force at its first jump or loop, and what came after it.
#[derive(Debug, Clone)]
pub(super) struct FlowCalls {
    /// The work offset (G54-G59) in force at the jump.
    work: i64,
    /// The machine's counts of G90/G91 and of G20/G21 codes at the jump.
    codes: u32,
    units: u32,
    /// Something after the jump changed (or may have changed) the offsets, the tool length
    /// offset or the modes: nothing judged under the jump's offset stands.
    spoiled: bool,
    /// A call after the jump left the caller's G90/G91 not known (a body read later).
    modes_lost: bool,
    /// The bodies read later called after the jump (their keys).
    unread: Vec<i64>,
    /// The calls of bodies read later kept with the jump's offset (their keys).
    numbers: Vec<i64>,
    /// Findings of bodies read before were held.
    held: bool,
    /// The block in hand called a body not read here ([`Checker::flow_unread`]).
    unread_now: bool,
}

impl Checker {
    /// A jump, condition or loop of the main program loses the offsets (`line`): where it is
    /// the first and a FANUC's or a Haas's, under a work offset known, what is in force is
    /// kept for the calls after it.
    #[cold]
    #[inline(never)]
    pub(super) fn flow_rewritten(&mut self, line: usize, calls: bool, unread: bool, never: bool) {
        let why = "a jump or call the checker does not follow";
        let unread = unread
            || self
                .flow_calls
                .as_mut()
                .is_some_and(|f| std::mem::take(&mut f.unread_now));
        if calls && !(unread && self.flow_calls.is_some()) {
            self.offsets_rewritten(line, why);
            return;
        }
        let kept = self.flow_calls.take();
        let (codes, units) = (self.machine.distance_codes, self.machine.units_codes);
        // (a jump surely taken or a loop never entered: the blocks after it, its calls
        // among them, may never run)
        let kept = match kept {
            // (a G90/G91 or units code since the first jump: a jump back or a loop's end
            // brings it to the calls before it)
            Some(mut k) => {
                k.spoiled |= k.codes != codes || k.units != units || never;
                Some(k)
            }
            None if !calls && !never => self.flow_begun().map(Box::new),
            None => None,
        };
        self.offsets_rewritten(line, why);
        self.flow_calls = kept;
    }

    /// A jump whose condition is known true or that has none (`GOTO 10`, `IF [#1 EQ 1]
    /// GOTO 10` after `#1=1`), or a `WHILE` whose condition is known false: the blocks after
    /// it are not surely run (a call among them may never be made). Or an `IF [..] THEN`
    /// of anything but a local or common variable's assignment.
    pub(super) fn flow_never(&self, b: &BlockView<'_>) -> bool {
        if self.config.family != Family::MacroB || self.config.work_offsets.is_empty() {
            return false;
        }
        b.statements.iter().any(|&(_, kind, text)| {
            if kind != Kind::Flow {
                return false;
            }
            let upper = text.to_ascii_uppercase();
            let t = upper.trim_ascii_start();
            // (`IF [..] THEN` and what follows: where that is not an assignment of a local or
            // common variable, `THEN G54`, it may select or set anything)
            if let Some(at) = t.windows(4).position(|w| w == b"THEN") {
                let then = t[at + 4..].trim_ascii_start();
                let Some(rest) = then.strip_prefix(b"#") else {
                    return true;
                };
                let digits = rest.iter().take_while(|c| c.is_ascii_digit()).count();
                let number = crate::text::digits_value(&rest[..digits]);
                return !(number.is_some_and(|n| n < 1000)
                    && rest[digits..].trim_ascii_start().starts_with(b"="));
            }
            if let Some(rest) = t.strip_prefix(b"WHILE") {
                let condition = [b"IF".as_slice(), rest].concat();
                return self.condition_known(&condition) == Some(false);
            }
            // (`GOTO #1`: a target not known, any block)
            super::targets::goto_words(&upper).is_some_and(|(_, digits, _)| {
                digits.is_empty()
                    || !t.starts_with(b"IF")
                    || self.condition_known(&upper) == Some(true)
            })
        })
    }

    /// The state kept at the first jump, where it is known.
    fn flow_begun(&self) -> Option<FlowCalls> {
        if self.config.family != Family::MacroB
            || self.config.work_offsets.is_empty()
            || self.offsets_lost
            || self.early_on
            || self.open_definition.is_some()
            || self.work_guessed.is_some()
            || self.work_run_on
            || self.work_call.is_some()
            || self.shifts_on()
            || self.frames_on()
            || self.transformed.is_some()
            || self.units_unknown
            || self.sub_ended
            || self.mode_lost_codes.is_some()
            || self
                .in_hand
                .is_some_and(|n| n >= super::structure::LOCAL_BODY)
        {
            return None;
        }
        let work = self.work?;
        Some(FlowCalls {
            work,
            codes: self.machine.distance_codes,
            units: self.machine.units_codes,
            spoiled: false,
            modes_lost: false,
            unread: Vec::new(),
            numbers: Vec::new(),
            held: false,
            unread_now: false,
        })
    }

    /// Something after the jump changed (or may have changed) the offsets or the modes.
    #[inline]
    pub(super) fn flow_spoiled(&mut self) {
        if let Some(f) = self.flow_calls.as_mut() {
            f.spoiled = true;
        }
    }

    /// A G code whose value is not known after the jump: it may select or set anything.
    #[cold]
    #[inline(never)]
    pub(super) fn flow_g_unknown(&mut self) {
        self.flow_spoiled();
    }

    /// A call after the jump left the caller's G90/G91 not known.
    pub(super) fn flow_modes_lost(&mut self) {
        if let Some(f) = self.flow_calls.as_mut() {
            f.modes_lost = true;
        }
    }

    /// The offset a call here runs under, where the offsets were lost by the jump alone and
    /// nothing after it changed what is in force.
    fn flow_work(&self) -> Option<i64> {
        let f = self.flow_calls.as_ref()?;
        (self.offsets_lost
            && !f.spoiled
            && self.passed.is_none()
            && !self.early_on
            && f.codes == self.machine.distance_codes
            && f.units == self.machine.units_codes
            && !self.shifts_on()
            && !self.frames_on()
            && self.transformed.is_none()
            && !self.units_unknown)
            .then_some(f.work)
    }

    /// A call of a body read before (early_call): the offset it is judged under, set for
    /// the judgment (the state before given back by [`Checker::flow_judged`]).
    pub(super) fn flow_judging(&mut self) -> Option<(bool, Option<i64>, usize)> {
        let work = self.flow_work()?;
        if self
            .flow_calls
            .as_ref()
            .is_some_and(|f| f.modes_lost || !f.unread.is_empty())
        {
            return None;
        }
        let before = (self.offsets_lost, self.work, self.found.len());
        self.offsets_lost = false;
        self.work = Some(work);
        Some(before)
    }

    /// After [`Checker::flow_judging`]: its findings held to the main program's end.
    pub(super) fn flow_judged(&mut self, (lost, work, from): (bool, Option<i64>, usize)) {
        self.offsets_lost = lost;
        self.work = work;
        let mut any = false;
        let from = from.min(self.found.len());
        // (only the positions judged through the offset: a G53 position, a span, are where
        // they are whatever the offset, and said as before; review 79-calls79 F4)
        for f in &mut self.found[from..] {
            if matches!(f.placed, super::Placed::Offset { .. }) {
                f.pending_on.push(PENDING_FLOW);
                any = true;
            }
        }
        if let Some(f) = self.flow_calls.as_mut() {
            f.held |= any;
        }
    }

    /// A call of a body read later (`number` its key, call_work): the offset it is kept
    /// with.
    pub(super) fn flow_call_work(&mut self, number: i64) -> Option<i64> {
        let work = self.flow_work()?;
        if let Some(f) = self.flow_calls.as_mut() {
            f.numbers.push(number);
        }
        Some(work)
    }

    /// A call of a body not read here after the jump (`number` its key).
    pub(super) fn flow_unread(&mut self, number: i64) {
        if let Some(f) = self.flow_calls.as_mut() {
            f.unread_now = true;
            if !f.unread.contains(&number) {
                f.unread.push(number);
            }
        }
    }

    /// The main program ends (or another begins): what was held under the jump's offset is
    /// said or dropped.
    #[cold]
    #[inline(never)]
    pub(super) fn flow_ended(&mut self) {
        let Some(f) = self.flow_calls.take() else {
            return;
        };
        // (a code after the last jump or loop reaches no call: the counts were compared at
        // each jump and call; the end's reset codes come before this)
        let clean = !f.spoiled;
        let early = clean && !f.modes_lost && f.unread.is_empty();
        if f.held {
            if early {
                for x in &mut self.found {
                    x.pending_on.retain(|m| *m != PENDING_FLOW);
                }
            } else {
                self.found.retain(|x| !x.pending_on.contains(&PENDING_FLOW));
            }
        }
        let later = clean && f.unread.len() <= 1;
        if !later {
            for n in f.numbers {
                self.call_works.insert(n, None);
                self.call_works_unknown.insert(n);
            }
        }
    }
}
