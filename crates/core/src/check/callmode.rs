//! The caller's distance mode after a call of a body read later in the file (review
//! 77-calls77 F10): a Haas's `M97 P100` whose `N100` comes after the main's M30, a LinuxCNC
//! `o100 call` of a definition after M2. G90/G91 are modal and a return restores neither
//! (Haas Mill Operator's Manual, "M97 Local Sub-Program Call", M99; LinuxCNC keeps a
//! subroutine's G91 after its `endsub`, `rs274 -g`), so the caller's moves after such a call
//! run in the mode the body leaves, which the checker knows only where it reads the body.
//!
//! The caller's mode is read on across the call (review 77-calls77 F5: taking it as not known
//! lost spans, G53 positions and arcs that are true in either mode); the findings of its
//! positions and arcs made after the call, before a G90/G91 of its own, are held
//! ([`PENDING_CALL_MODE`]) to the body's return, and dropped there where the body wrote a
//! G90/G91 and leaves another mode than the call's (or its mode is not known there: a call
//! it does not follow, an end in it), said where it leaves the call's. A body the file does
//! not hold leaves them said, as before.
//!
//! `O1000` / `G20 G17 G90 G54` / `G0 X0 Y0` / `M97 P100` / `G55` / `G0 X-27.` / `M30` /
//! `N100 G91 G0 X5.` / `M99` on a Haas in inches (X -30..30, G55 X -4): N100 leaves G91, the
//! main's `G0 X-27.` is an increment from 5 to -22 (machine -26), not -27 (machine -31).

use super::Checker;
use crate::rules::Rule;

/// Among a finding's [`super::Finding::pending_on`], `PENDING_CALL_MODE - slot`: a position
/// or arc of the caller read in its own G90/G91 after the call of [`CallMode`] `slot`
/// ([`Checker::call_modes`]): resolved where that body returns, or at the file's end.
/// Between [`super::limits::PENDING_OTHER_CALL`]'s marks and
/// [`super::leaves::PENDING_LEAVES`]'s; never left to [`Checker::pending_on_ended`].
pub(super) const PENDING_CALL_MODE: i64 = super::limits::PENDING_MODE_SELF - 64;

/// Whether `m` is a [`PENDING_CALL_MODE`] mark (kept where a finding's other marks are set
/// anew).
pub(super) fn is_mark(m: i64) -> bool {
    (PENDING_CALL_MODE - SLOTS as i64..=PENDING_CALL_MODE).contains(&m)
}

/// The most bodies whose calls' modes are held: a call of one more is not held (read on in
/// the caller's mode, as before).
const SLOTS: usize = 64;

/// A body read later called from the main program ([`Checker::call_modes`]).
#[derive(Debug, Clone)]
pub(super) struct CallMode {
    /// The body's key (`structure::LOCAL_BODY`, `structure::LATER_DEFINITION`).
    key: i64,
    /// The machine's count of G90/G91 codes at its last call: the caller's findings are
    /// held while it stands there.
    codes: u32,
    /// The caller's modes at its calls (bit 0: G90, bit 1: G91).
    modes: u8,
    /// The count of G90/G91 codes where its body began to be read.
    begun: Option<u32>,
    /// Resolved: its held findings dropped or said.
    done: bool,
}

impl Checker {
    /// A call of the body `key`, read later in the file, from the main program: the findings
    /// after it held to its return.
    #[cold]
    #[inline(never)]
    pub(super) fn call_mode_kept(&mut self, key: i64) {
        if self.machine.settings.own_motion(90) {
            return;
        }
        let codes = self.machine.distance_codes;
        let mode = if self.machine.state.incremental { 2 } else { 1 };
        if let Some(c) = self.call_modes.iter_mut().find(|c| c.key == key && !c.done) {
            c.codes = codes;
            c.modes |= mode;
        } else if self.call_modes.len() < SLOTS {
            self.call_modes.push(CallMode {
                key,
                codes,
                modes: mode,
                begun: None,
                done: false,
            });
        }
    }

    /// A finding just made (`rule`): held where it reads a position or an arc of the
    /// caller's after such a call, before a G90/G91 of its own.
    #[cold]
    #[inline(never)]
    pub(super) fn call_mode_held(&mut self, rule: Rule) {
        if !matches!(
            rule,
            Rule::TravelExceeded
                | Rule::ArcRadiusMismatch
                | Rule::ArcZeroRadius
                | Rule::ArcCrossesQuadrant
                | Rule::ArcRadiusTooShort
        ) || self
            .in_hand
            .is_some_and(|n| n >= super::structure::LOCAL_BODY)
        {
            return;
        }
        let codes = self.machine.distance_codes;
        let marks: Vec<i64> = self
            .call_modes
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.done && c.begun.is_none() && c.codes == codes)
            .map(|(slot, _)| PENDING_CALL_MODE - slot as i64)
            .collect();
        if let Some(f) = self.found.last_mut() {
            f.pending_on.extend(marks);
        }
    }

    /// The body `key` begins to be read (its first block's codes not yet applied).
    pub(super) fn call_mode_begun(&mut self, key: i64) {
        let codes = self.machine.distance_codes;
        for c in &mut self.call_modes {
            if c.key == key && !c.done && c.begun.is_none() {
                c.begun = Some(codes);
            }
        }
    }

    /// The body in hand returns (`returned`: an M99, an `endsub`) or the file ends inside it
    /// (an M02/M30 of its own: the caller's blocks after the call do not run): the findings
    /// held for its calls said where it wrote no G90/G91, or leaves the calls' mode, and
    /// dropped where not.
    pub(super) fn call_mode_returned(&mut self, returned: bool) {
        if self.call_modes.is_empty() {
            return;
        }
        let codes = self.machine.distance_codes;
        let leaves = if self.machine.state.incremental { 2 } else { 1 };
        let lost = self.mode_lost_codes == Some(codes);
        let mut dropped = Vec::new();
        let mut said = Vec::new();
        for (slot, c) in self.call_modes.iter_mut().enumerate() {
            let Some(begun) = c.begun.filter(|_| !c.done) else {
                continue;
            };
            c.done = true;
            let mark = PENDING_CALL_MODE - slot as i64;
            if !returned || lost || begun != codes && c.modes != leaves {
                dropped.push(mark);
            } else {
                said.push(mark);
            }
        }
        self.call_mode_resolved(&dropped, &said);
    }

    /// At the file's end: a body never read (not in the file) leaves its calls' findings
    /// said, as before; one read and not returned from drops them.
    pub(super) fn call_modes_ended(&mut self) {
        if self.call_modes.is_empty() {
            return;
        }
        self.call_mode_returned(false);
        let mut said = Vec::new();
        for (slot, c) in self.call_modes.iter_mut().enumerate() {
            if !c.done {
                c.done = true;
                said.push(PENDING_CALL_MODE - slot as i64);
            }
        }
        self.call_mode_resolved(&[], &said);
    }

    fn call_mode_resolved(&mut self, dropped: &[i64], said: &[i64]) {
        if dropped.is_empty() && said.is_empty() {
            return;
        }
        self.found
            .retain(|f| !f.pending_on.iter().any(|m| dropped.contains(m)));
        for f in &mut self.found {
            f.pending_on.retain(|m| !said.contains(m));
        }
    }
}
