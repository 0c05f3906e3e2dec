//! LinuxCNC: a call of a subroutine written after the main program's end, made inside the main
//! program's `o.. if`, `o.. while`, `o.. do` or `o.. repeat` (issue 32 item 4).
//!
//! rs274ngc runs an `if` branch's lines where its condition is true, and a loop's body while
//! its condition holds or its count lasts (LinuxCNC G-code reference, "O Codes": "Conditional",
//! "Looping", "Repeat"; interp_o_word.cc `convert_control_functions`): a call among those lines
//! runs the subroutine (`control_back_to` seeks it to the end of the file) under the work
//! offset, distance mode and units in force at it, as a call outside a block does.
//!
//! - A block whose lines the checker knows run (`o1 if [1]`, a `repeat [3]`, a `while` whose
//!   condition holds on entry: [`Checker::linuxcnc_runs_surely`]): the call is kept as a call
//!   outside a block is (`Checker::later_call_of`), under the offset in force there. A loop's
//!   first pass runs it under that offset; a later pass runs the same body under the offset
//!   the loop leaves, which the checker does not follow (one judgment: the first pass's).
//! - A block whose condition is not known: the lines inside are read in file order, under no
//!   offset (the positions inside are not judged, `Checker::linuxcnc_flow_offsets`). A call
//!   there is kept with the offset in force where the outermost such block opened
//!   ([`MayCalls`]), and that judgment stands only where nothing in the region, in any branch
//!   or pass -- no line changing the offsets (`Checker::linuxcnc_flow_touched`), no G90/G91,
//!   G20/G21 or tool length code, no other call -- may have changed what the call runs
//!   under: then the call runs, if it runs, under that offset, and a position of its body
//!   beyond the travel is a real overtravel whenever it runs (as a FANUC's call after a
//!   conditional jump is judged, callflow.rs). Where anything may have, the call is taken
//!   as made under no known offset (its body not judged), as before.
//!
//! `G55` / `o1 if [#<_x> EQ 1]` / `o300 call` / `o1 endif` / `M2` / `o300 sub` / `G0 X-700` /
//! `o300 endsub` (G55 X -100, X -762..762): where `#<_x>` is 1 the body runs X-700 at machine
//! -800 (`rs274 -g` with `#<_x>` set: `SET_G5X_OFFSET(2, ...)` then the move).

use super::Checker;

/// What the main program had in force where the outermost block whose lines may not run
/// opened, and the calls kept under it.
#[derive(Debug, Clone, Default)]
pub(super) struct MayCalls {
    /// The machine's counts of G90/G91 and of G20/G21 codes, and the tool length offset's
    /// code and decimals, at the opening.
    codes: (u32, u32),
    length: (i64, bool),
    /// The keys (`LATER_DEFINITION` + n) of the calls kept under the opening's offset.
    keys: Vec<i64>,
    /// The calls read in the region (every calling line: o-word `call`s, M98s).
    calls: usize,
    /// A line in the region changed (or may have changed) the offsets.
    touched: bool,
}

impl Checker {
    /// The outermost condition or loop whose lines may not run opened (the offsets not lost,
    /// `Checker::linuxcnc_flow_offsets`): what is in force kept for the calls inside.
    #[cold]
    #[inline(never)]
    pub(super) fn may_opened(&mut self) {
        let s = &self.machine;
        self.linuxcnc_may = Some(MayCalls {
            codes: (s.distance_codes, s.units_codes),
            length: (s.state.length_offset, self.length_decimal),
            ..MayCalls::default()
        });
    }

    /// A line of the region changed or may have changed the offsets.
    pub(super) fn may_touched(&mut self) {
        if let Some(m) = self.linuxcnc_may.as_mut() {
            m.touched = true;
        }
    }

    /// A calling line in the region (any form).
    pub(super) fn may_call_seen(&mut self) {
        if let Some(m) = self.linuxcnc_may.as_mut() {
            m.calls += 1;
        }
    }

    /// Whether nothing read since the region opened changed what a call runs under: its
    /// offset at the opening (Some: the system), where so.
    fn may_work(&self) -> Option<i64> {
        let m = self.linuxcnc_may.as_ref()?;
        let s = &self.machine;
        let same = !m.touched
            && m.codes == (s.distance_codes, s.units_codes)
            && m.length == (s.state.length_offset, self.length_decimal);
        same.then_some(())?;
        self.linuxcnc_flow_work.flatten()
    }

    /// A call of a later definition (`key`) in a block whose lines may not run: kept by
    /// `keep` under the offset in force where the region opened, where nothing before it in
    /// the region changed it (else not kept, as before).
    pub(super) fn may_call(&mut self, key: i64, keep: impl FnOnce(&mut Checker)) {
        // (the region's first call only: another's body may change what the next runs under)
        let first = self
            .linuxcnc_may
            .as_ref()
            .is_some_and(|m| m.keys.is_empty())
            && !self.flow_reads_any();
        let Some(work) = self.may_work().filter(|_| first && !self.offsets_lost) else {
            return;
        };
        let before = self.work.replace(work);
        keep(self);
        self.work = before;
        if let Some(m) = self.linuxcnc_may.as_mut() {
            m.keys.push(key);
        }
    }

    /// After an o-word line of the main program (`text`): whether each open block's condition
    /// reads a numbered parameter the program itself may write (any but the read-only current
    /// position, #5420-#5428; an indirect `#[..]` or `##1` too). The checker's value of one set in a
    /// block that closed, or by a called body, may be stale or lost, so that a call the program
    /// never makes would be judged (review 80-lcnc80 R5, R6: `#1=5` / `o1 if [1]` / `#1=0` /
    /// `o1 endif` / `o2 if [#1 GT 2]`; rs274 skips it): a block reading one is not judged
    /// through (R10: `#5100`; R7: `#5399`, which M66 writes). Named parameters and the position
    /// are read as the checker reads them.
    #[cold]
    #[inline(never)]
    pub(super) fn flow_reads(&mut self, text: &[u8]) {
        let depth = self.linuxcnc_open_flow.len();
        let reads = text.iter().enumerate().any(|(i, &c)| {
            if c != b'#' {
                return false;
            }
            let rest = &text[i + 1..];
            let digits = rest.iter().take_while(|d| d.is_ascii_digit()).count();
            match rest.first() {
                Some(b'<') => false,
                Some(d) if d.is_ascii_digit() => !crate::text::digits_value(&rest[..digits])
                    .is_some_and(|n| (5420..=5428).contains(&n)),
                _ => true,
            }
        });
        let r = &mut self.linuxcnc_flow_reads;
        if r.len() > depth {
            r.truncate(depth);
        } else if r.len() == depth {
            // (an `elseif` or `else` of the innermost: its condition too)
            if let Some(last) = r.last_mut() {
                *last |= reads;
            }
        }
        while r.len() < depth {
            r.push(reads);
        }
    }

    /// Whether a block open reads a parameter in its condition ([`Checker::flow_reads`]).
    pub(super) fn flow_reads_any(&self) -> bool {
        let open = self.linuxcnc_open_flow.len();
        self.linuxcnc_flow_reads.iter().take(open).any(|&r| r)
    }

    /// The outermost block of the region closed: the calls kept under its opening's offset
    /// stand where nothing in it, after them too (a later branch, a loop's later lines), may
    /// have changed what they run under; else they are taken as made under no known offset.
    #[cold]
    #[inline(never)]
    pub(super) fn may_closed(&mut self) {
        let Some(m) = self.linuxcnc_may.take() else {
            return;
        };
        let s = &self.machine;
        let stands = !m.touched
            && m.calls == m.keys.len()
            && m.codes == (s.distance_codes, s.units_codes)
            && m.length == (s.state.length_offset, self.length_decimal);
        if !stands {
            for key in m.keys {
                self.call_works.insert(key, None);
                self.call_works_unknown.insert(key);
            }
        }
    }

    /// LinuxCNC: an `endif` line of the main program after a call of a body read later
    /// inside the block (the offsets lost by that call alone,
    /// `Checker::call_offsets_rewritten`): the line changes no offset and jumps back to
    /// nothing, so the spans set aside at a selection before the call stay so, as after the
    /// same call outside a block (review 80-lcnc80 R8: `G54` / `G0 X-650.` / `G57` / `o1 if
    /// [1]` / `M98 P2000` / `o1 endif` / `M2` / `O2000` / `G0 X1000.` / `M99`, G57 X -300,
    /// runs at machine -650 then 700, and was "X spans 1650"). An `if`, `elseif` or `else`
    /// line opens lines that may not run: a selection among them would set the spans aside
    /// where rs274 never selects (the lead's merge of stop 81: `G54` / `#1=1` / `M98 P2000` /
    /// `o10 if [#1 NE 1]` / `G57` / `o10 endif` / `G0 X800.`, body `G0 X-740.`, runs X800
    /// under G54, machine 800), so they lose the offsets as before, as a loop's closing line,
    /// which runs the lines before it again, does.
    #[cold]
    #[inline(never)]
    pub(super) fn later_call_if_line(&self, b: &super::BlockView<'_>) -> bool {
        self.config.family == crate::lex::Family::LinuxCnc
            && self.offsets_lost
            && self.offsets_unread_only
            && self.open_definition.is_none()
            && !b.statements.is_empty()
            && b.statements.iter().all(|&(_, kind, text)| {
                kind == crate::statement::Kind::Flow
                    && crate::statement::o_keyword(text).is_some_and(|k| k == b"endif")
            })
    }
}
