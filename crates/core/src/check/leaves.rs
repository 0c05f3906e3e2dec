//! TG601's spans after a call of a FANUC's or a Haas's program written later in the file:
//! the G52 it leaves on is not known at the call (review 63-unit63 F10, benchmarks.md
//! flow62's g52l/g52p: `O1000` / `G21 G90 G54` / `G0 X-750.` / `M98 P2000` / `G90` / `G0
//! X800.` / `M30` / `O2000` / `G52 X-1000.` / `M99` runs X800. at -200, and was "X spans
//! 1550"). Each axis's span is kept apart from the call on ([`LaterShift`]), the span said
//! as before held to the file's end, and judged there with what that program leaves: as
//! said where it leaves nothing on the axis or what it leaves is not known, with its G52
//! where that is known.

use super::{Checker, Finding, Span, AXES};

/// Among a finding's [`Finding::pending_on`], `PENDING_LEAVES - (k * 16 + i)`: a span of
/// axis place `i` said across a call of a program not read there, held with
/// [`Checker::later_shifts`]`[k]`. Below every [`super::limits::PENDING_CALLS_WRITTEN`] mark;
/// taken off before those are read.
pub(super) const PENDING_LEAVES: i64 = -(1 << 45);

/// The spans kept apart after a call of a program not read there ([`Checker::later_shift`]).
#[derive(Debug, Clone, Default)]
pub(super) struct LaterShift {
    /// The programs called so (the first, and any later one called before the watch ends).
    programs: Vec<i64>,
    /// The caller's factor to the profile's units at the call (the G52 a body left read in
    /// units only assumed is in its caller's, [`Checker::shift_carried`]).
    factor: f64,
    /// The caller's local shift (G52) of each axis at the call: the body's G52 replaces it.
    local: [f64; 9],
    /// The value of each axis of the work offset in force at the call, where it is the
    /// profile's (selected, no G10, shift or loss before): a position beyond the travel under
    /// it keeps the span as read.
    offset: [Option<f64>; 9],
    /// The axes kept apart (bit `i`: a span before the call, not said).
    pub(super) watched: u16,
    /// Each axis's span before the call, and after it (until the watch ends).
    before: [Option<Span>; 9],
    after: [Option<Span>; 9],
    /// The span before and after the call together, read with no shift between, said
    /// (held) or past the travel.
    joined_said: u16,
    /// The least and most position after the call of each axis, and the line and column of
    /// the first position that reached it (bits `2 * i`, `2 * i + 1` of `reached`: seen).
    least: [f64; 9],
    most: [f64; 9],
    least_at: [(usize, usize); 9],
    most_at: [(usize, usize); 9],
    reached: u32,
}

/// What the programs of a [`LaterShift`] leave on one axis.
enum Leaves {
    /// Nothing: the span as read before.
    Nothing,
    /// A G52 known: the positions after the call are this far from where they were read.
    By(f64),
    /// Not known (a G52 of a value not known, a call of a program read later, two programs
    /// that leave different shifts).
    Unknown,
}

impl Checker {
    /// A call of program `number`, not read there (written later in the file, or not in it),
    /// that surely runs from its start: where the caller has a span on an axis, not said, its
    /// positions from here are kept apart from those before (a G52 the program leaves on
    /// shifts them, known only at the file's end).
    #[cold]
    #[inline(never)]
    pub(super) fn later_shift_called(&mut self, number: i64) {
        if let Some(w) = self.later_shift.as_mut() {
            if !w.programs.contains(&number) {
                w.programs.push(number);
            }
            return;
        }
        if self.early_on || self.frames_on() || self.transformed.is_some() {
            return;
        }
        let mut w = LaterShift {
            programs: vec![number],
            factor: self.to_profile_units(false),
            local: self.shifts.local,
            ..LaterShift::default()
        };
        if let Some(work) = self.work.filter(|_| {
            !self.offsets_lost
                && !self.offsets_written.any()
                && !self.offsets_written.moved
                && self.work_guessed.is_none()
                && !self.shifts_on()
        }) {
            for &(g, axis, value) in &self.config.work_offsets {
                if let Some(i) = AXES.iter().position(|&a| a == axis).filter(|_| g == work) {
                    w.offset[i] = Some(value.to_f64());
                }
            }
        }
        for i in 0..AXES.len() {
            if self.travel.of_place(i).is_none() || self.shifts.local_unknown & 1 << i != 0 {
                continue;
            }
            if let Some(span) = self.spans[i].filter(|s| !s.said) {
                w.before[i] = Some(span);
                w.watched |= 1 << i;
                self.spans[i] = None;
            }
        }
        if w.watched != 0 {
            self.later_shift = Some(Box::new(w));
        }
    }

    /// The span of watched axis place `i` grew to `at` (read at `line`, `column`; `said`: a
    /// machine position said there, which says more than the span can): the span
    /// before and after together judged as before, said (held to the file's end) where past
    /// the travel.
    #[cold]
    #[inline(never)]
    pub(super) fn later_span_grew(
        &mut self,
        i: usize,
        at: f64,
        said: bool,
        (line, column): (usize, usize),
        (low, high): (f64, f64),
        under: &str,
    ) {
        let k = self.later_shifts.len();
        let Some(after) = self.spans[i] else {
            return;
        };
        let w = self.later_shift.as_mut().expect("watched");
        let Some(before) = w.before[i] else {
            return;
        };
        // (each end named by the first position that reached it)
        if w.reached & 1 << (2 * i) == 0 || at < w.least[i] {
            (w.least[i], w.least_at[i]) = (at, (line, column));
            w.reached |= 1 << (2 * i);
        }
        if w.reached & 1 << (2 * i + 1) == 0 || at > w.most[i] {
            (w.most[i], w.most_at[i]) = (at, (line, column));
            w.reached |= 1 << (2 * i + 1);
        }
        let width = high - low + 1e-9;
        if said {
            // (a machine position said here: the span as before says no more)
            w.joined_said |= 1 << i;
        }
        if let Some(s) = self.spans[i].as_mut() {
            // (the span after alone is judged with the one before, not by itself)
            s.said = s.said || after.most - after.least > width;
        }
        let (least, most) = (before.least.min(after.least), before.most.max(after.most));
        if w.joined_said & 1 << i != 0 || most - least <= width {
            return;
        }
        w.joined_said |= 1 << i;
        let found = self.found.len();
        self.span_exceeded(AXES[i], (least, most), (low, high), (line, column), under);
        if let Some(f) = self.found.get_mut(found) {
            f.pending_on
                .push(PENDING_LEAVES - (k as i64 * 16 + i as i64));
        }
    }

    /// The watch ([`Checker::later_shift`]) ends (the caller's end, a shift, frame or call
    /// that moves the coordinates, the next program): each axis's span is the one read
    /// before, the positions since added to it with no shift between, as they were read.
    #[cold]
    #[inline(never)]
    pub(super) fn later_shift_closed(&mut self) {
        let Some(mut w) = self.later_shift.take() else {
            return;
        };
        for i in crate::modal::places(u32::from(w.watched)) {
            let after = self.spans[i];
            w.after[i] = after;
            let before = w.before[i].expect("watched");
            let Some((low, high)) = self.travel.of_place(i) else {
                continue;
            };
            let span = match after {
                Some(a) => Span {
                    least: before.least.min(a.least),
                    most: before.most.max(a.most),
                    said: false,
                },
                None => before,
            };
            let said = w.joined_said & 1 << i != 0 || span.most - span.least > high - low + 1e-9;
            self.spans[i] = Some(Span { said, ..span });
        }
        self.later_shifts.push(*w);
    }

    /// At the file's end, a span held with `mark` ([`PENDING_LEAVES`]): true where said (as
    /// read, or again with what the called program leaves: `f` rewritten), false where not.
    pub(super) fn later_span_judged(&self, mark: i64, f: &mut Finding) -> bool {
        let k = usize::try_from((PENDING_LEAVES - mark) / 16).unwrap_or(usize::MAX);
        let i = usize::try_from((PENDING_LEAVES - mark) % 16).unwrap_or(usize::MAX);
        let (Some(w), Some((low, high))) = (self.later_shifts.get(k), self.travel.of_place(i))
        else {
            return true;
        };
        let mut leaves = Leaves::Nothing;
        for n in &w.programs {
            let here = match self.shift_ends.get(n) {
                // (it leaves units other than its calls', a tool length offset, or may not
                // return to the call: after.rs; review 75 F7: `G20` / `G52 X-40.` / `M99`
                // leaves the caller's X800. in inches)
                _ if self.after_unsure.contains(n) => Leaves::Unknown,
                // (not in the file: what it does is not followed, as before; or in it,
                // leaving no shift)
                None => Leaves::Nothing,
                Some(None) => Leaves::Unknown,
                Some(Some((axes, local, read))) if axes & 1 << i != 0 => {
                    let r = if read[i] == 0.0 {
                        1.0
                    } else {
                        w.factor / read[i]
                    };
                    Leaves::By(local[i] * r - w.local[i])
                }
                Some(Some(_)) => Leaves::Nothing,
            };
            leaves = match (leaves, here) {
                (Leaves::Nothing, here) => here,
                (known, Leaves::Nothing) => known,
                _ => Leaves::Unknown,
            };
        }
        // (two programs called: the positions between their calls under the first's, those
        // after under what the second leaves)
        if w.programs.len() > 1 && matches!(leaves, Leaves::By(_)) {
            leaves = Leaves::Unknown;
        }
        let (Some(before), Some(after)) = (w.before[i], w.after[i]) else {
            return true;
        };
        let (least, most, at) = match leaves {
            Leaves::Nothing | Leaves::By(0.0) => return true,
            Leaves::By(by) => {
                let (least, most) = (
                    before.least.min(after.least + by),
                    before.most.max(after.most + by),
                );
                if most - least <= high - low + 1e-9 {
                    // (a position after the call beyond the travel under the call's offset:
                    // the alarm kept as read; review 75 F7's L6)
                    let out = |at: f64| at < low - 1e-9 || at > high + 1e-9;
                    return w.offset[i]
                        .is_some_and(|v| out(after.least + by + v) || out(after.most + by + v));
                }
                // (named by the position after the call that ends it, the later one where
                // both ends are after the call)
                let ends = [
                    (after.least + by <= before.least).then_some(w.least_at[i]),
                    (after.most + by >= before.most).then_some(w.most_at[i]),
                ];
                let Some(at) = ends.into_iter().flatten().max() else {
                    return false;
                };
                (least, most, at)
            }
            // (not surely known: as read, erring on the side of the alarm, as a call of a
            // program read before whose G52 is not known, Checker::shift_carried)
            Leaves::Unknown => return true,
        };
        let Some(k) = f.message.find(", more than the travel") else {
            return true;
        };
        f.message = format!(
            "{} spans {} (from {} to {}){}",
            AXES[i] as char,
            super::round6(most - least),
            super::round6(least),
            super::round6(most),
            &f.message[k..]
        );
        (f.line, f.column) = at;
        true
    }
}
