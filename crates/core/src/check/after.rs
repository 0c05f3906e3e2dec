//! What a called program leaves its caller after the return that the checker does not
//! follow for a caller's own G54-G59 after a call of a program written later (review 61a
//! F13, [`Checker::work_unread_reselected`]) nor for a body read apart with no work offset
//! judged at its calls (review 61a F7, `called.rs`): such positions are held, not judged with
//! a state that may be wrong (review 62a F1-F4).
//!
//! A program is marked ([`Checker::after_unsure`]) where it writes a work offset's system
//! variable (FANUC `#5221`-`#5326`, `#2500`-`#2906`, `#7001`-, `#14001`-; Haas the same
//! numbers; LinuxCNC `#5211`-`#5390`; a `#[...]` whose number is an expression), where it
//! ends (M02/M30: the blocks after its call do not run) or returns elsewhere (`M99 Pn`
//! returns to the caller's block Nn: 0i-MF Operator's Manual, "Subprogram call (M98)"),
//! where it ends leaving a tool length offset (G43/G44, modal through M99) or units other
//! than those it was called in (G20/G21 are modal), and where it calls a program so marked.

use super::{BlockView, Checker};

impl Checker {
    /// Whether the assignment block `b` writes a variable that may be a work offset's.
    fn writes_offset_variable(b: &BlockView<'_>) -> bool {
        b.words.iter().any(|w| {
            w.address == b'#'
                && (w.index.is_empty()
                    || std::str::from_utf8(w.index)
                        .ok()
                        .and_then(|n| n.parse::<u32>().ok())
                        .is_some_and(|n| {
                            matches!(n, 2500..=2906 | 5201..=5399 | 7001..=7999 | 14001..=19999)
                        }))
        })
    }

    /// An assignment block (`b`): where it writes a work offset's variable, the program in
    /// hand is marked, and its own positions are no longer judged on the paths named above.
    #[cold]
    #[inline(never)]
    pub(super) fn after_assignment(&mut self, b: &BlockView<'_>) {
        if self.early_on && Self::writes_offset_variable(b) {
            self.early_changes_offsets();
        }
        if self.offset_variable_written || !Self::writes_offset_variable(b) {
            return;
        }
        self.offset_variable_written = true;
        self.after_mark();
    }

    /// A conditional assignment (`IF [..] THEN #5241=0.`) of block `line` that may write a
    /// work offset's variable: the offsets are not known from here (the write may run or
    /// not), the program in hand marked, a program read apart changes them.
    #[cold]
    #[inline(never)]
    pub(super) fn conditional_offset_write(&mut self, line: usize) {
        if self.early_on {
            self.early_changes_offsets();
        }
        self.offset_variable_written = true;
        self.after_mark();
        self.offsets_rewritten(line, "a work offset's system variable may be set");
    }

    /// The program in hand marked ([`Checker::after_unsure`]).
    pub(super) fn after_mark(&mut self) {
        if let Some(n) = self.in_hand {
            self.after_unsure.insert(n);
        }
    }

    /// An end (`ends`: M02, M30) or a return of block `b`: the program in hand marked where
    /// it ends or returns elsewhere (`M99 Pn`).
    #[cold]
    #[inline(never)]
    pub(super) fn after_return(&mut self, b: &BlockView<'_>, ends: bool) {
        if !ends && self.resumed.is_some() {
            // (the caller's moves after its calls judged: resumed.rs)
            self.resumed_returned(b);
        }
        if ends
            || b.words
                .iter()
                .any(|w| w.letter == b'P' && w.index.is_empty())
        {
            self.after_mark();
        }
        // (a program written after its calls returns: what its run left for its later calls
        // is known here, review 76-calls76 F8)
        if self.work_call.as_ref().is_some_and(|w| w.held) {
            self.work_call_tentative_end();
        }
        self.after_watch |= self.local_called;
        // (a Haas's local subprogram returns: the main program in hand again)
        if !ends
            && self
                .in_hand
                .is_some_and(|n| n >= super::structure::LOCAL_BODY)
        {
            self.call_mode_returned(true);
            self.local_body_end();
        }
    }

    /// A call of program `number`: the caller marked where that one is.
    #[cold]
    #[inline(never)]
    pub(super) fn after_call(&mut self, number: i64) {
        if self.after_unsure.contains(&number) {
            self.after_mark();
        }
    }

    /// The program in hand ends (the next begins, or the file): marked where it leaves a
    /// tool length offset or units other than its calls' (the reset's where none was made
    /// before it).
    #[cold]
    #[inline(never)]
    pub(super) fn after_end(&mut self) {
        self.offset_variable_written = false;
        let Some(n) = self.in_hand else {
            return;
        };
        let s = &self.machine.state;
        let length = s.length_offset != 49 || self.length_decimal;
        let called_in = match self.call_units.get(&n) {
            Some(&Some((units, _, _))) => Some(units),
            Some(None) => None,
            None => Some(self.config.modal.default_units),
        };
        if length || self.units_unknown || called_in != Some(s.units) {
            self.after_unsure.insert(n);
        }
    }
}
