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
//! main's `G0 X-27.` is an increment: N100 left X at machine 5, G55 work 9, so work -18
//! (machine -22), not -27 (machine -31).

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
    (PENDING_CALL_MODE - 2 * SLOTS as i64..=PENDING_CALL_MODE).contains(&m)
}

/// `PENDING_CALL_MODE - SLOTS - slot`: a finding of an excursion opened again after the
/// caller's own G90 ([`Checker::call_mode_reopened`]): said where the held one of that call
/// is dropped, dropped where it is said (one excursion, one finding).
fn reopened_mark(slot: usize) -> i64 {
    PENDING_CALL_MODE - (SLOTS + slot) as i64
}

/// The most calls whose modes are held: a call past them is not held (read on in the
/// caller's mode, as before).
const SLOTS: usize = 256;

/// A call of a body read later from the main program ([`Checker::call_modes`]).
#[derive(Debug, Clone)]
pub(super) struct CallMode {
    /// The body's key (`structure::LOCAL_BODY`, `structure::LATER_DEFINITION`).
    key: i64,
    /// The machine's count of G90/G91 codes at the call: the caller's findings are held
    /// while it stands there and no later call was made.
    codes: u32,
    /// The caller's modes read at its calls (bit 0: G90, bit 1: G91).
    modes: u8,
    /// The call before it with no G90/G91 of the caller's between: the mode it is made in
    /// is the one that call's body leaves (review 78-calls78 F1).
    prev: Option<usize>,
    /// The count of G90/G91 codes where its body began to be read.
    begun: Option<u32>,
    /// Each axis's span (least, most) at the call, before any position held, and the axes
    /// whose span was said again from it ([`Checker::call_mode_span_again`]).
    spans: [Option<(f64, f64)>; 9],
    spans_said: u16,
    /// Resolved: its held findings dropped (`Some(true)`), said (`Some(false)`), or passed to
    /// `prev`'s (None: its body wrote no G90/G91).
    done: bool,
    decision: Option<bool>,
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
        let prev = self.call_mode_holding();
        if let Some(c) = prev
            .map(|p| &mut self.call_modes[p])
            .filter(|c| c.key == key)
        {
            // (the same body again, nothing between: one call)
            c.modes |= mode;
        } else if self.call_modes.len() < SLOTS {
            let spans = self.spans.map(|s| s.map(|s| (s.least, s.most)));
            self.call_modes.push(CallMode {
                key,
                codes,
                modes: mode,
                prev,
                spans,
                spans_said: 0,
                begun: None,
                done: false,
                decision: None,
            });
        }
    }

    /// The last call whose findings are held here (no G90/G91 of the caller's since).
    fn call_mode_holding(&self) -> Option<usize> {
        let slot = self.call_modes.len().checked_sub(1)?;
        let c = &self.call_modes[slot];
        (!c.done && c.begun.is_none() && c.codes == self.machine.distance_codes).then_some(slot)
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
        if let Some(slot) = self.call_mode_holding() {
            if let Some(f) = self.found.last_mut() {
                f.pending_on.push(PENDING_CALL_MODE - slot as i64);
            }
        }
    }

    /// Whether the caller's position on axis place `i`, beyond the travel on the side of the
    /// excursion before it, opens an excursion of its own: the one before was said under a
    /// hold the caller's own G90/G91 has ended (review 78-calls78 F2: that finding may be
    /// dropped, this one is the caller's own mode's).
    #[cold]
    #[inline(never)]
    pub(super) fn call_mode_reopened(&self, i: usize) -> Option<i64> {
        // (after the caller's own G91 its positions are increments from the held one: not
        // known better than it, review 78-calls78 F7)
        if self.machine.state.incremental {
            return None;
        }
        let f = self.found.iter().rev().find(|f| {
            f.rule == Rule::TravelExceeded
                && matches!(f.placed, super::Placed::Offset { place, .. } if usize::from(place) == i)
        })?;
        f.pending_on.iter().find_map(|&m| {
            let slot = usize::try_from(PENDING_CALL_MODE - m).ok()?;
            (slot < SLOTS
                && self
                    .call_modes
                    .get(slot)
                    .is_some_and(|c| c.codes != self.machine.distance_codes))
            .then(|| reopened_mark(slot))
        })
    }

    /// The span of axis place `i` grew to `at`, its finding said before: where that finding
    /// is held by a call's mode and the caller reads `at` in its own G90 since, the span from
    /// the extent before the call to `at` is judged (review 78-calls78 F2b: `G0 X-28.` /
    /// `M97 P100` / `G0 X32.5` / `G90 G0 X32.6` spans 60.6 whatever the body leaves), said
    /// only where the held finding is dropped. The extent between is not counted: the span
    /// said is at most the real one.
    #[cold]
    #[inline(never)]
    pub(super) fn call_mode_span_again(
        &mut self,
        i: usize,
        at: f64,
        (low, high): (f64, f64),
        (line, column): (usize, usize),
        under: &str,
    ) {
        if self.machine.state.incremental {
            return;
        }
        let axis = super::AXES[i];
        let Some(slot) = self
            .found
            .iter()
            .rev()
            .find(|f| {
                f.span
                    && f.rule == Rule::TravelExceeded
                    && f.message.as_bytes().first() == Some(&axis)
                    && f.message.get(1..7) == Some(" spans")
            })
            .and_then(|f| {
                f.pending_on.iter().find_map(|&m| {
                    let slot = usize::try_from(PENDING_CALL_MODE - m).ok()?;
                    (slot < SLOTS).then_some(slot)
                })
            })
        else {
            return;
        };
        let codes = self.machine.distance_codes;
        let Some(c) = self
            .call_modes
            .get_mut(slot)
            .filter(|c| c.codes != codes && c.spans_said & 1 << i == 0)
        else {
            return;
        };
        c.spans_said |= 1 << i;
        let (least, most) = c.spans[i].map_or((at, at), |(l, m)| (l.min(at), m.max(at)));
        if most - least <= (high - low) + 1e-9 {
            return;
        }
        let before = self.found.len();
        self.span_exceeded(axis, (least, most), (low, high), (line, column), under);
        if self.found.len() > before {
            let f = self.found.last_mut().expect("said");
            f.pending_on.retain(|&m| !is_mark(m));
            f.pending_on.push(reopened_mark(slot));
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
    /// held for its calls said where it leaves the mode they were read in, dropped where it
    /// leaves another (or one not known); where it wrote no G90/G91, decided as the call
    /// before it (if any, with no G90/G91 of the caller's between) is.
    pub(super) fn call_mode_returned(&mut self, returned: bool) {
        if self.call_modes.is_empty() {
            return;
        }
        let codes = self.machine.distance_codes;
        let leaves = if self.machine.state.incremental { 2 } else { 1 };
        let lost = self.mode_lost_codes == Some(codes);
        for slot in 0..self.call_modes.len() {
            let c = &mut self.call_modes[slot];
            let Some(begun) = c.begun.filter(|_| !c.done) else {
                continue;
            };
            c.done = true;
            let mark = PENDING_CALL_MODE - slot as i64;
            // (a body read known to its return: the G90/G91 it leaves written, not one in a
            // block known not to run or a jump to the next block; resumed.rs, review
            // 78-calls78 F3. None: it wrote none, decided as the call before it)
            let (key, modes) = (c.key, c.modes);
            let drop = match self.resumed_leaves(key).filter(|_| returned) {
                Some(wrote) => wrote.map(|g91| modes != if g91 { 2 } else { 1 }),
                None if !returned || lost || begun != codes => {
                    Some(!returned || lost || modes != leaves)
                }
                None => None,
            };
            if let Some(drop) = drop {
                self.call_modes[slot].decision = Some(drop);
                self.call_mode_decided(mark, Ok(drop));
            } else {
                let decided = self.call_mode_effective(self.call_modes[slot].prev);
                self.call_mode_decided(mark, decided);
            }
        }
    }

    /// What the call at `slot` decides: drop (true) or say (false), or the call still to be
    /// resolved that decides it.
    fn call_mode_effective(&self, mut slot: Option<usize>) -> Result<bool, usize> {
        while let Some(s) = slot {
            let c = &self.call_modes[s];
            if !c.done {
                return Err(s);
            }
            if let Some(d) = c.decision {
                return Ok(d);
            }
            slot = c.prev;
        }
        Ok(false)
    }

    /// At the file's end: a body never read (not in the file) leaves its calls' findings
    /// said, as before; one read and not returned from drops them.
    pub(super) fn call_modes_ended(&mut self) {
        if self.call_modes.is_empty() {
            return;
        }
        self.call_mode_returned(false);
        for slot in 0..self.call_modes.len() {
            let c = &mut self.call_modes[slot];
            if !c.done {
                c.done = true;
                c.decision = Some(false);
                self.call_mode_decided(PENDING_CALL_MODE - slot as i64, Ok(false));
            }
        }
    }

    /// The findings held by `mark`: dropped (`Ok(true)`), said (`Ok(false)`), or held by the
    /// mark of the call that decides them (`Err(slot)`).
    fn call_mode_decided(&mut self, mark: i64, decided: Result<bool, usize>) {
        let reopened = reopened_mark((PENDING_CALL_MODE - mark) as usize);
        match decided {
            Ok(drop) => {
                let gone = if drop { mark } else { reopened };
                self.found.retain(|f| !f.pending_on.contains(&gone));
                for f in &mut self.found {
                    f.pending_on.retain(|&m| m != mark && m != reopened);
                }
            }
            Err(slot) => {
                for f in &mut self.found {
                    for m in &mut f.pending_on {
                        if *m == mark {
                            *m = PENDING_CALL_MODE - slot as i64;
                        } else if *m == reopened {
                            *m = reopened_mark(slot);
                        }
                    }
                }
            }
        }
    }
}

/// A body read under its calls' work offset ([`super::structure::WorkCall`]): its positions
/// on one axis judged under another call's offset ([`super::structure::Other`] `other`)
/// before a units code of its own -- the least and the most, and the findings said of them.
/// The other call runs after the first, in the units the first run leaves (G20/G21 are
/// modal and M99 restores neither: Haas Mill Operator's Manual, G20/G21 and M99; FANUC
/// 0i-MF Operator's Manual, "Subprogram call (M98)"; LinuxCNC keeps a subroutine's G20 after
/// its `endsub`, `rs274 -g`): where the body writes a units code that leaves other units
/// than its start's, they are judged again in those (review 77-calls77 F9 and F7: a body
/// called in inches that leaves G21 runs its `G0 X-27.` at the second call as -27 mm, -1.06
/// in; one called in millimetres that leaves G20 its `G0 X-700.` as -700 in, -17780 mm).
#[derive(Debug, Clone)]
pub(super) struct Rescale {
    other: usize,
    /// That call's offset (G`work`) and its naming ([`super::structure::WorkCall::named_by`]).
    work: i64,
    named: String,
    i: usize,
    axis: u8,
    offset: crate::decimal::Dec,
    travel: (f64, f64),
    least: (f64, (usize, usize)),
    most: (f64, (usize, usize)),
    /// The marks its findings carry ([`super::limits::PENDING_OTHER_CALL`] less the
    /// offset's index, [`super::limits::PENDING_MODE_SELF`] or 0).
    marks: [i64; 2],
    said: Vec<String>,
}

/// The most axes and calls kept so (a body with more is judged as before).
const RESCALE_MAX: usize = 64;

type Place = (u8, usize, crate::decimal::Dec, (f64, f64));

impl Rescale {
    /// A position `at` (line and column `place`) judged under other call `other`.
    pub(super) fn judged(
        all: &mut Vec<Rescale>,
        (other, named): (usize, impl FnOnce() -> (i64, String)),
        (axis, i, offset, travel): Place,
        (at, place): (f64, (usize, usize)),
        marks: [i64; 2],
    ) {
        if let Some(r) = all.iter_mut().find(|r| r.other == other && r.i == i) {
            if at < r.least.0 {
                r.least = (at, place);
            }
            if at > r.most.0 {
                r.most = (at, place);
            }
            if marks[1] != 0 {
                r.marks[1] = marks[1];
            }
        } else if all.len() < RESCALE_MAX {
            let (work, named) = named();
            all.push(Rescale {
                other,
                work,
                named,
                i,
                axis,
                offset,
                travel,
                least: (at, place),
                most: (at, place),
                marks,
                said: Vec::new(),
            });
        }
    }

    /// Whether a finding was said of other call `other` before the units code.
    pub(super) fn other_said(&self, other: usize) -> bool {
        self.other == other && !self.said.is_empty()
    }

    /// The finding `f` said of the last position judged under other call `other`.
    pub(super) fn said(all: &mut [Rescale], other: usize, i: usize, f: &super::Finding) {
        if let Some(r) = all.iter_mut().find(|r| r.other == other && r.i == i) {
            r.said.push(f.message.clone());
        }
    }
}

impl Checker {
    /// The body read under its calls' offset ends: where it wrote a units code of its own
    /// and leaves other units than its start's, each other call's findings of its positions
    /// before that code are judged again in the units left ([`Rescale`]), in their place.
    pub(super) fn call_units_rescaled(&mut self) {
        let Some(w) = self.work_call.as_mut() else {
            return;
        };
        let rescale = std::mem::take(&mut w.rescale);
        let units = self.machine.state.units;
        if rescale.is_empty()
            || self.machine.units_codes == w.units_codes_at
            || units == w.units_at
            || self.units_unknown
        {
            return;
        }
        use crate::modal::Units;
        let (ratio, name) = match (w.units_at, units) {
            (Units::Metric, Units::Inch) => (25.4, "inches"),
            _ => (1.0 / 25.4, "millimetres"),
        };
        let selected = self.selection.enabled(Rule::TravelExceeded);
        for r in rescale {
            let mut first = None;
            let mut kept = 0;
            self.found.retain(|f| {
                let gone = f.rule == Rule::TravelExceeded
                    && f.pending_on.contains(&r.marks[0])
                    && r.said.contains(&f.message);
                if gone {
                    first.get_or_insert(kept);
                } else {
                    kept += 1;
                }
                !gone
            });
            let (work, named) = (r.work, &r.named);
            let (low, high) = r.travel;
            let mut at = first.unwrap_or(self.found.len());
            for (side, (value, (line, column))) in [(-1, r.least), (1, r.most)] {
                let work_at = value * ratio;
                let machine_at = work_at + r.offset.to_f64();
                if super::limits::travel_side(machine_at, r.travel) != side || !selected {
                    continue;
                }
                let message = format!(
                    "{} goes to {} in machine coordinates (work {} + G{work} offset {}), \
                     outside the travel {low} to {high}{named}, in {name}: the units the \
                     run before this call leaves (G20/G21 are modal)",
                    r.axis as char,
                    super::round6(machine_at),
                    super::round6(work_at),
                    r.offset,
                );
                let before = self.found.len();
                self.report(Rule::TravelExceeded, message, line, column);
                if self.found.len() > before {
                    let mut f = self.found.pop().expect("said");
                    f.pending_on.extend(r.marks.iter().filter(|&&m| m != 0));
                    let at_now = at.min(self.found.len());
                    self.found.insert(at_now, f);
                    at = at_now + 1;
                }
            }
        }
    }
}
