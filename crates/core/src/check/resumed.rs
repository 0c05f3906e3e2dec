//! The caller's moves after a call of a body read later in the file, judged where the body
//! leaves the tool and in the mode it leaves (issue 32 item 4, calls80): a FANUC's or Haas's
//! `M98 P2000` of an `O2000` after the main's M30, a Haas's `M97 P100`, a LinuxCNC
//! `o2000 call` (or `M98 P2000`) of a definition after M2.
//!
//! G90/G91 are modal and a return restores neither (FANUC 0i-F / 30i-B Operator's Manual,
//! "Subprogram call (M98)" and M99; Haas Mill Operator's Manual, M97, M98, M99; LinuxCNC
//! keeps a subroutine's G91 after its `endsub`, `rs274 -g`). The checker reads the file in
//! order: at the caller's moves after such a call the body is not read yet, so main took
//! the caller's mode as not known (FANUC, Haas M98) or read it on and dropped what it held
//! where the body wrote another (Haas M97, LinuxCNC), and the offsets as not known: a real
//! overtravel passed. Here the caller's plain moves after the call are kept (their words,
//! not judged), and judged at the body's return, where its end is known: from the position
//! the body leaves, in the mode it leaves, under the call's work offset, which a body that
//! writes none keeps.
//!
//! Each run of a body from where the one before left the tool, in the mode it left (a repeat
//! count: `M98 P2000 L3`, a four-digit FANUC's `M98 P32000`), and a later call (of the same
//! body or another) from where the caller's moves after the call before end (calls81): the
//! calls judged in turn as their bodies return, whatever the bodies' order in the file.
//!
//! From the position a G54-G59 selection before the call re-expressed in the selected
//! system, under a G52 or G92 of the caller's whose shift is followed, and through a Haas
//! M97 body that runs on into the next one a call names (calls82).
//!
//! Only where all of it is surely known: calls of the first program of the file, not behind
//! a jump or condition, under a work offset known (no G10, shift, frame, polar mode), in
//! blocks that move nothing and enter no sequence number (no Q), a repeat count of 1 to
//! 9999; the caller's blocks from a call to the first that is not a plain G00/G01 move (a
//! statement, a parameter, any other G or M code ends them; a call there is kept as the
//! next one, any block else ends all later calls); X, Y and Z (Z where no tool length offset
//! is in force); a caller that writes no G20/G21 (read apart) only where it ends with M02
//! or M30, in the profile's units; a body of plain moves and arcs, G90/G91, feed and speed
//! only, whose every statement is known not to change its run -- a LinuxCNC `o1 if [0]`
//! block, or any `if` whose condition is false from numbers alone (`[1 GT 2]`; its lines never
//! run: rs274 skips them), a FANUC `IF [..] THEN` whose condition
//! the values known make false, a `GOTO n` or `IF [..] GOTO n` whose block `Nn` is the next
//! one (either way the run goes on there) -- and returns with a plain M99 or `endsub`.
//! Anything else leaves main's reading as it was (unknown: silent).
//!
//! `G54` / `G90 G0 X0` / `M98 P2000` / `G0 X500.` / `G0 X500.` / `M30` / `O2000` / `G91` /
//! `M99` (fanuc-mill, X -762..762, G54 X 0): O2000 leaves G91 and the tool at X0, so the
//! caller's two blocks are increments to X500 and X1000: "X goes to 1000" at the second.

use super::{BlockView, Checker, Finding, Placed};
use crate::lex::Family;
use crate::rules::Rule;
use crate::statement::Kind;

/// The axes judged (X, Y, Z: the places in [`super::AXES`]), Z where no tool length offset
/// is in force at the call (the profile gives no tool lengths: limits.rs judges Z so). The
/// angles A, B, C are no lengths (no inch/mm factor) and a mill's U, V, W seldom an axis of
/// the profile: not kept, as before.
const JUDGED: [usize; 3] = [0, 1, 2];

/// The judged axes' count.
const AXES: usize = JUDGED.len();

/// The most caller's moves kept after one call, the most calls kept.
const MOVES: usize = 256;
const CALLS: usize = 64;

/// The most positions of a body's runs followed for one call (its blocks' axes times its
/// repeat count): past them, not judged.
const STEPS: usize = 1 << 20;

/// Where the caller's moves after a call end: each axis's work position, the G91 in force,
/// the motion code in force.
#[derive(Debug, Clone, Copy)]
struct Carry {
    at: [Option<f64>; AXES],
    incremental: bool,
    motion: Option<i64>,
}

/// What the calls and the body read so far keep ([`Checker::resumed`]).
#[derive(Debug, Clone, Default)]
pub(super) struct Resumed {
    calls: Vec<Call>,
    /// The bodies read, or being read (the last), in the file's order.
    bodies: Vec<Body>,
    /// The program in hand at the first call (the caller).
    caller: Option<i64>,
    /// A body returned in the block in hand: its calls judged at the block's end.
    due: bool,
    /// No later call is kept (one was made where the moves before it were not all kept).
    closed: bool,
    /// The calls judged so far (each in turn, from the first), and where the caller's moves
    /// after the last of them end (None: not known, no later call judged).
    judged: usize,
    carry: Option<Carry>,
    /// A call not judged for good: none after it is.
    broken: bool,
    /// The caller was read apart at its first call (it wrote no G20/G21 yet: it may be a
    /// subprogram of a later call, `called.rs`), in the reset state's units, the profile's:
    /// judged only where it ends as a main program, with M02 or M30 (`main_end`), as main
    /// judges its own positions then.
    assumed: bool,
    main_end: bool,
}

/// A call kept, and the caller's moves after it.
#[derive(Debug, Clone)]
struct Call {
    key: i64,
    line: usize,
    /// How many times the body runs (`L3`, a FANUC's `P32000`).
    runs: u32,
    /// Made right after the moves kept after the call before it: it starts where they end,
    /// in the mode and motion in force there, not at [`Call::start`].
    chained: bool,
    /// The caller's distance mode at the call, and its work position there (its units).
    incremental: bool,
    start: [Option<f64>; AXES],
    /// The work offset (G`work`) in force, each judged axis's value (the profile's units).
    work: i64,
    offset: [Option<crate::decimal::Dec>; AXES],
    /// The G52 or G92 shift in force at the call, each judged axis's (the profile's units):
    /// the body runs under it, and the caller's moves after it until it writes another.
    shift: [f64; AXES],
    /// The caller's units to the profile's.
    factor: f64,
    /// The motion code in force at the call.
    motion: Option<i64>,
    /// The call as written (`M98 P2000`, `o2000 call`).
    named: String,
    moves: Vec<Move>,
    /// The caller's blocks are still kept (none ended them yet).
    recording: bool,
    /// The call's own block was seen and is a plain call.
    checked: bool,
}

/// One of the caller's blocks after the call.
#[derive(Debug, Clone)]
struct Move {
    line: usize,
    /// The caller's own G90 (false) or G91 (true) in force from this block, where it wrote
    /// one since the call.
    own: Option<bool>,
    /// The G00 or G01 it writes.
    motion: Option<i64>,
    axes: Vec<(usize, f64, usize)>,
    /// The columns of the TG601s main said on its line as it was read (handed over before
    /// the return: not in [`Checker::found`] there), none held.
    said: Vec<usize>,
}

/// A body's G90/G91 or position, in its order.
#[derive(Debug, Clone, Copy)]
enum Step {
    /// G91 (true) or G90.
    Mode(bool),
    /// An axis (its place in [`JUDGED`]) and the value written.
    Axis(usize, f64),
}

/// The body read.
#[derive(Debug, Clone)]
struct Body {
    key: i64,
    /// Every block was read and is known (see the module's list).
    sure: bool,
    /// The last G90/G91 it wrote.
    wrote: Option<bool>,
    /// The motion code it leaves (None: the call's).
    motion: Option<i64>,
    /// Its G90/G91 codes and positions, run from the call's mode and position.
    steps: Vec<Step>,
    /// A LinuxCNC `oN if [0]` open (its label): its lines never run.
    dead: Option<Vec<u8>>,
    /// A `GOTO n` read: the next block must be `Nn`.
    goto: Option<Vec<u8>>,
    /// It returned (M99, `endsub`).
    returned: bool,
    /// Its blocks read so far.
    blocks: usize,
    /// The variables it set to a number, still holding it, and their values.
    set: Vec<(u64, crate::decimal::Dec)>,
    /// A Haas's local subprogram (M97) that runs on, with no M99 before it, into the one at
    /// the next sequence number a call names (its key): its run goes on through that
    /// body's blocks to its M99 (Haas Mill Operator's Manual, M97: the subprogram runs from
    /// its sequence number to its M99; the N words between are no end).
    then: Option<i64>,
}

/// A Custom Macro B assignment statement of a local or common variable (`#1=0`, `#100 =
/// #100 + 1`; no system variable, nothing indirect): its number, and its value where it is
/// a number written there.
fn local_assignment(text: &[u8]) -> Option<(u64, Option<crate::decimal::Dec>)> {
    let rest = text.trim_ascii_start().strip_prefix(b"#")?;
    let digits = rest.iter().take_while(|c| c.is_ascii_digit()).count();
    let n = crate::text::digits_value(&rest[..digits]).filter(|n| (1..1000).contains(n))?;
    let value = rest[digits..].trim_ascii_start().strip_prefix(b"=")?;
    let value = std::str::from_utf8(value.trim_ascii()).ok()?;
    Some((n, crate::decimal::Dec::parse(value)))
}

/// A condition's text (in capitals) with each variable it reads (`#1`, `#100`) replaced by
/// the number the body set it to: None where one was not set so, or is indirect (`#[..]`).
fn with_values(text: &[u8], set: &[(u64, crate::decimal::Dec)]) -> Option<Vec<u8>> {
    let mut out = Vec::with_capacity(text.len());
    let mut k = 0;
    while k < text.len() {
        if text[k] != b'#' {
            out.push(text[k]);
            k += 1;
            continue;
        }
        let rest = &text[k + 1..];
        let digits = rest.iter().take_while(|c| c.is_ascii_digit()).count();
        let n = crate::text::digits_value(&rest[..digits])?;
        let &(_, v) = set.iter().find(|&&(m, _)| m == n)?;
        out.extend_from_slice(v.to_string().as_bytes());
        k += 1 + digits;
    }
    Some(out)
}

impl Checker {
    /// A call of the body `key`, not read yet, in the block in hand: kept where the caller
    /// and the offsets are known ([`Resumed`]).
    #[cold]
    #[inline(never)]
    pub(super) fn resumed_called(&mut self, key: i64) {
        let in_hand = self.in_hand;
        if let Some(c) = self
            .resumed
            .as_mut()
            .and_then(|r| r.calls.last_mut())
            .filter(|c| c.line == self.last_line && !c.checked)
        {
            // (LinuxCNC's `M98 P2000` of an `O2000` after M2: kept by its number, then by
            // the definition's key, which its body is read under)
            c.key = key;
            return;
        }
        if let Some(r) = self.resumed.as_mut() {
            // (a later call: kept where every block of the caller's since the call before
            // it was a plain move kept, so it starts where they end, which is known at the
            // returns; otherwise its start is where the runs before left the tool, which the
            // caller's reading does not know: review 80-calls80 W1)
            let chained = r.calls.last().filter(|p| {
                !r.closed
                    && p.recording
                    && p.checked
                    && p.line != self.last_line
                    && in_hand == r.caller
                    && r.bodies.is_empty()
                    && r.calls.len() < CALLS
            });
            let call = chained.map(|p| Call {
                key,
                line: self.last_line,
                runs: 1,
                chained: true,
                incremental: p.incremental,
                start: [None; AXES],
                work: p.work,
                offset: p.offset,
                shift: p.shift,
                factor: p.factor,
                motion: None,
                named: String::new(),
                moves: Vec::new(),
                recording: true,
                checked: false,
            });
            for c in &mut r.calls {
                c.recording = false;
            }
            match call {
                Some(call) => r.calls.push(call),
                None => r.closed = true,
            }
            return;
        }
        let family = self.config.family;
        let work = self
            .work
            .filter(|_| !self.offsets_lost && !self.offsets_written.moved)
            // (the offsets taken as lost by a G52 or G92 of the caller's alone, its shift
            // followed: below)
            .or(self.shift_work.filter(|_| self.offsets_lost))
            .filter(|_| !self.offsets_written.any() && self.work_guessed.is_none());
        // (a G52 or G92 of the caller's own followed (limits.rs, `shift_of`: a FANUC's or
        // Haas mill's G52 under G90, a G92 where the position before it is known) is in
        // force at the call: the body runs under it, as the caller's moves after it do
        // (FANUC 0i-F / 30i-B Operator's Manual, "Local coordinate system" (G52) and
        // "Setting a workpiece coordinate system" (G92): the shift holds until another
        // G52 or G92 or a reset, a call and M99 end neither; Haas NGC Mill Operator's
        // Manual, G52 and G92; LinuxCNC G92 offsets, rs274 -g). A shift not followed (its
        // amount not known: `offsets_written.shifted`, a local shift not known, one a
        // program read before may have left) leaves main's reading; a G52 the body writes
        // makes it not known, below)
        let shift = self
            .call_shift()
            .filter(|_| self.offsets_written.shifted == 0 && !self.shift_unsure);
        let Some(shift) = shift else {
            return;
        };
        let s = &self.machine.state;
        if !matches!(family, Family::MacroB | Family::LinuxCnc)
            || self.machine.settings.fanuc_lathe
            || self.ended_line != 0
            || self.sub_ended
            || self.programs > 1
            || self.jumped
            || self.early_on && self.machine.state.units_given
            || self.open_definition.is_some()
            || !self.linuxcnc_open_flow.is_empty()
            || self.frames_on()
            || self.transformed.is_some()
            || s.polar
            || s.cycle.is_some()
            || self.units_unknown
            || !matches!(s.motion, None | Some(0) | Some(1))
        {
            return;
        }
        let Some(work) = work else {
            return;
        };
        // (Z not under a tool length offset: the profile gives no tool lengths)
        let length = s.length_offset != 49 || self.length_decimal;
        let mut offset = [None; AXES];
        let shift = JUDGED.map(|i| shift[i]);
        for &(g, axis, value) in &self.config.work_offsets {
            if g != work {
                continue;
            }
            if let Some(k) = JUDGED.iter().position(|&i| super::AXES[i] == axis) {
                offset[k] = Some(value).filter(|_| !(length && axis == b'Z'));
            }
        }
        // (LinuxCNC's M98 forgets the position before its later call is kept: the one
        // before the block, which moves nothing; a FANUC's or Haas's call takes the mode as
        // G91 before it is kept, called.rs `call_mode_lost`: the mode before the block, which
        // writes none. Taken as G91, a body's move before its own G90/G91 ran from the
        // start as an increment: `G0 X50.` / `M98 P2000` of `G0 X100.` / `G91` / `G0 X620.`
        // runs at 720, inside, and was "X goes to 770")
        let from = self.call_from;
        let here = from.0 == self.last_line;
        // (after a G54-G59 selection from another system the real run keeps the machine
        // position: where the selection re-expressed the work position held in the new
        // system (limits.rs, `selection_reexpressed`: new work = old work + old offset - new
        // offset) the body runs from there, under the selected system (review 81-calls81
        // f_sel1: `G54` / `G0 X0` / `G55` (X -100) / `M98 P2000` of `G91 G0 X100.` / `G0
        // X600.` / `G0 X100.` runs at machine 100, 700, 800); an axis it left the old
        // system's (a loop that may come back, an offset not known) is not placed from it:
        // `G54` / `G0 X-650.` / `G57` / a call of a body that leaves G91 after `G91 G0 X10.`
        // / `G0 X-100.` on G57 X -300 runs at machine -740 (rs274), not -1040)
        let stale = self.selected_stale;
        let start = JUDGED.map(|i| {
            s.position[i]
                .or(from.1[i].filter(|_| here))
                .filter(|_| stale & 1 << i == 0)
                .map(|v| v.to_f64())
        });
        let call = Call {
            key,
            line: self.last_line,
            runs: 1,
            chained: false,
            incremental: if here { from.2 } else { s.incremental },
            start,
            work,
            offset,
            shift,
            factor: self.to_profile_units(false),
            motion: s.motion,
            named: String::new(),
            moves: Vec::new(),
            recording: true,
            checked: false,
        };
        let assumed = self.early_on;
        let r = self.resumed.get_or_insert_with(Box::default);
        r.caller = in_hand;
        r.assumed = assumed;
        r.calls.push(call);
    }

    /// After block `b` is read: the caller's moves after a call kept, the bodies' blocks
    /// followed ([`Resumed`]).
    #[cold]
    #[inline(never)]
    pub(super) fn resumed_block(&mut self, b: &BlockView<'_>) {
        let Some(mut r) = self.resumed.take() else {
            return;
        };
        if std::mem::take(&mut r.due) {
            self.resumed_finished(&mut r);
        } else if let Some(last) = r.bodies.last().filter(|body| !body.returned) {
            let local = |k: i64| {
                (super::structure::LOCAL_BODY..super::structure::LATER_DEFINITION).contains(&k)
            };
            let next = self.in_hand.filter(|&k| {
                self.config.haas
                    && local(last.key)
                    && local(k)
                    && r.calls.iter().any(|c| c.key == k)
                    && r.bodies.iter().all(|body| body.key != k)
            });
            let n = r.bodies.len() - 1;
            let body = &mut r.bodies[n];
            if self.in_hand == Some(body.key) {
                self.resumed_body(body, b);
                if body.returned {
                    self.resumed_finished(&mut r);
                }
            } else if let Some(k) = next.filter(|_| body.sure && body.dead.is_none()) {
                // (a local subprogram runs on into the next one a call names: followed
                // there, its return the end of both)
                body.then = Some(k);
                body.returned = true;
                self.resumed_begun(&mut r, k, b);
            } else {
                // (another program begins before its return: not known, and the next
                // body's first block, if this is one, is not followed either)
                body.sure = false;
                body.returned = true;
                self.resumed_finished(&mut r);
            }
        } else if let Some(&key) = r.calls.iter().map(|c| &c.key).find(|&&k| {
            self.in_hand == Some(k)
                && r.caller != Some(k)
                && r.bodies.iter().all(|body| body.key != k)
        }) {
            self.resumed_begun(&mut r, key, b);
        } else if r.bodies.is_empty() {
            if self.in_hand == r.caller {
                // (the caller's end as a main program: M02, M30)
                r.main_end |= b.words.iter().enumerate().any(|(k, w)| {
                    w.letter == b'M'
                        && w.index.is_empty()
                        && self
                            .readable
                            .get(k)
                            .copied()
                            .flatten()
                            .is_some_and(|v| v.is_whole() && matches!(v.trunc(), 2 | 30))
                });
            }
            self.resumed_caller(&mut r, b);
        }
        self.resumed = Some(r);
    }

    /// A body begins (`key`): its first block, `O2000`, `N100 ...`, `o100 sub`.
    fn resumed_begun(&mut self, r: &mut Resumed, key: i64, b: &BlockView<'_>) {
        let mut body = Body {
            key,
            sure: r.calls.iter().all(|c| c.key != key || c.checked),
            wrote: None,
            motion: None,
            steps: Vec::new(),
            dead: None,
            goto: None,
            returned: false,
            blocks: 0,
            set: Vec::new(),
            then: None,
        };
        for c in &mut r.calls {
            c.recording = false;
        }
        self.resumed_body(&mut body, b);
        let returned = body.returned;
        r.bodies.push(body);
        if returned {
            self.resumed_finished(r);
        }
    }

    /// How many times the body of `c` runs by the word `w` (P, L) of its call's block, whose
    /// value is `v`: `Some(1)` for a P that names it, `Some(n)` for a repeat count, None
    /// where the word is neither (not a plain call).
    fn resumed_runs(&self, c: &Call, letter: u8, v: crate::decimal::Dec) -> Option<u32> {
        if !v.is_whole() {
            return None;
        }
        let n = v.trunc();
        let digits = self
            .config
            .formats
            .iter()
            .find(|(l, _)| *l == b'O')
            .map_or(0, |(_, f)| f.before);
        match letter {
            // (`M98 P2000 L3`, `M97 P100 L3`: L is the repeat count, 1 to 9999: FANUC 0i-F /
            // 30i-B "Subprogram call (M98)", Haas Mill Operator's Manual M97/M98; L0 may run
            // it no time: not followed. LinuxCNC's `M98 P2000 L3` runs it three times too,
            // rs274 -g, but structure.rs keeps no call of that form with an L)
            b'L' => u32::try_from(n).ok().filter(|n| (1..=9999).contains(n)),
            b'P' if c.key >= super::structure::LOCAL_BODY => Some(1),
            // (a number of more than four digits names the program where the profile's O
            // format has more (a Haas's O05, a FANUC's with the 8-digit option: O08))
            b'P' if n == c.key && (self.config.haas || c.key <= 9999 || digits > 4) => Some(1),
            // (a FANUC whose program numbers have four digits (the profile's O format: no
            // 8-digit option) reads `M98 P32000` as O2000 three times, the digits above the
            // last four being the repeat count: 0i-F Operator's Manual, "Subprogram call
            // (M98)", P____ ____, as structure.rs reads its number; review 80-calls80 W2)
            b'P' if !self.config.haas
                && self.config.family == Family::MacroB
                && digits == 4
                && n % 10_000 == c.key =>
            {
                u32::try_from(n / 10_000)
                    .ok()
                    .filter(|n| (1..=9999).contains(n))
            }
            _ => None,
        }
    }

    /// A block of the caller's after the call (or the call's own): kept where it is a plain
    /// move, the keeping ended at any other.
    fn resumed_caller(&self, r: &mut Resumed, b: &BlockView<'_>) {
        let Some(c) = r.calls.last_mut().filter(|c| c.recording) else {
            return;
        };
        if self.in_hand != r.caller {
            c.recording = false;
            return;
        }
        if b.line == c.line && !c.checked {
            // (the call's own block: no move, no entry at a sequence number, no skip; the
            // call's statement or M98/M97 P, its N, a repeat count)
            let mut runs: Option<u32> = None;
            let mut plain = !b.skip
                && b.skip_within.is_none()
                && b.statements.iter().all(|s| s.1 == Kind::Call);
            for (k, w) in b.words.iter().enumerate() {
                let value = self.readable.get(k).copied().flatten();
                plain &= w.index.is_empty() && w.expression.is_empty();
                plain &= match (w.letter, value) {
                    (b'N' | b'M', _) => true,
                    (b'P' | b'L', Some(v)) => match self.resumed_runs(c, w.letter, v) {
                        // (one count only: L, or P's digits above four)
                        Some(n) if n > 1 && runs.is_some_and(|r| r > 1) => false,
                        Some(n) => {
                            runs = Some(runs.map_or(n, |r| r.max(n)));
                            true
                        }
                        None => false,
                    },
                    _ => false,
                };
            }
            c.checked = plain;
            c.recording = plain;
            c.runs = runs.unwrap_or(1);
            c.named = match b.statements.iter().find(|s| s.1 == Kind::Call) {
                Some(&(_, _, text)) => String::from_utf8_lossy(text.trim_ascii()).into_owned(),
                None => b
                    .words
                    .iter()
                    .filter(|w| matches!(w.letter, b'M' | b'P' | b'L'))
                    .map(|w| w.token())
                    .collect::<Vec<_>>()
                    .join(" "),
            };
            return;
        }
        if !c.checked {
            c.recording = false;
            return;
        }
        let mut m = Move {
            line: b.line,
            own: c.moves.last().and_then(|m| m.own),
            motion: None,
            axes: Vec::new(),
            said: Vec::new(),
        };
        let plain = !b.skip
            && b.skip_within.is_none()
            && b.statements.is_empty()
            && b.words.iter().enumerate().all(|(k, w)| {
                let Some(v) = self.readable.get(k).copied().flatten() else {
                    return false;
                };
                if !w.index.is_empty() || !w.expression.is_empty() {
                    return false;
                }
                let code = || v.is_whole().then(|| v.trunc());
                match w.letter {
                    b'N' | b'F' | b'S' | b'T' => true,
                    b'X' | b'Y' | b'Z' => {
                        let i = usize::from(w.letter - b'X');
                        m.axes.push((i, v.to_f64(), w.column));
                        true
                    }
                    b'G' => match code() {
                        Some(c @ (0 | 1)) => {
                            m.motion = Some(c);
                            true
                        }
                        Some(90) => {
                            m.own = Some(false);
                            true
                        }
                        Some(91) => {
                            m.own = Some(true);
                            true
                        }
                        Some(17 | 40 | 80 | 94) => true,
                        _ => false,
                    },
                    b'M' => matches!(code(), Some(0 | 1 | 3 | 4 | 5 | 7 | 8 | 9)),
                    _ => false,
                }
            });
        if !plain || c.moves.len() >= MOVES {
            c.recording = false;
            return;
        }
        m.said = self
            .found
            .iter()
            .filter(|f| f.rule == Rule::TravelExceeded && f.line == b.line)
            .filter(|f| f.pending_on.is_empty())
            .map(|f| f.column)
            .collect();
        c.moves.push(m);
    }
    /// A block of the body (its start to its return): followed, or the body not known.
    fn resumed_body(&self, body: &mut Body, b: &BlockView<'_>) {
        if !body.sure {
            return;
        }
        let first = body.blocks == 0;
        body.blocks += 1;
        let linuxcnc = self.config.family == Family::LinuxCnc;
        if let Some(target) = body.goto.take() {
            // (a jump to the next block: the run goes on there, taken or not)
            let here = b
                .words
                .first()
                .filter(|w| w.letter == b'N' && w.index.is_empty() && w.expression.is_empty());
            let number = |d: &[u8]| crate::text::digits_value(d.trim_ascii());
            if here
                .is_none_or(|w| number(w.number).is_none() || number(w.number) != number(&target))
            {
                body.sure = false;
                return;
            }
        }
        let mut returns = false;
        for &(_, kind, text) in b.statements {
            let keyword = if linuxcnc {
                crate::statement::o_keyword(text)
            } else {
                None
            };
            if let Some(dead) = &body.dead {
                // (the lines of a block known not to run, to its endif)
                if crate::statement::o_label(text) == *dead {
                    if keyword.as_deref() == Some(b"endif".as_slice()) {
                        body.dead = None;
                    } else {
                        body.sure = false;
                    }
                }
                continue;
            }
            match (kind, keyword.as_deref()) {
                (Kind::Definition, Some(b"sub")) => {}
                (Kind::Definition, Some(b"endsub")) => returns = true,
                (Kind::Flow, Some(b"if")) => {
                    // (false from numbers alone, `[0]`, `[2 LT 1]`: not from a parameter,
                    // which the caller may have changed after the call)
                    if super::structure::linuxcnc_constant_runs(text) == Some(false) {
                        body.dead = Some(crate::statement::o_label(text));
                    } else {
                        body.sure = false;
                    }
                }
                (Kind::Flow, None) if !linuxcnc && !b.skip && b.skip_within.is_none() => {
                    let upper = text.to_ascii_uppercase();
                    let t = upper.trim_ascii_start();
                    let is_if = t.starts_with(b"IF");
                    if t.windows(4).any(|w| w == b"THEN") {
                        // (`IF [..] THEN ..` whose condition is known false: nothing runs;
                        // known from numbers and the body's own constants only, not from
                        // values the caller may have changed after the call, review
                        // 80-calls80 W3)
                        if !(is_if
                            && with_values(t, &body.set)
                                .is_some_and(|t| self.condition_known(&t) == Some(false)))
                        {
                            body.sure = false;
                        }
                    } else if let Some((_, digits, _)) = super::targets::goto_words(&upper)
                        .filter(|(_, d, r)| !d.is_empty() && r.trim_ascii().is_empty())
                    {
                        body.goto = Some(digits.to_vec());
                    } else {
                        body.sure = false;
                    }
                }
                // (its `O2000` line; a LinuxCNC `O2000` of the M98 form)
                (Kind::Name, _) if !linuxcnc => {}
                (Kind::Definition | Kind::Name, Some(b"")) if first => {}
                // (a local or common variable's value: no mode, offset or position)
                (Kind::Assignment, _) if !linuxcnc => match local_assignment(text) {
                    Some((n, value)) => {
                        body.set.retain(|&(m, _)| m != n);
                        body.set.extend(value.map(|v| (n, v)));
                    }
                    None => body.sure = false,
                },
                _ => body.sure = false,
            }
        }
        if body.dead.is_some() {
            // (a line inside it: not run)
            return;
        }
        if body.returned {
            body.sure = false;
            return;
        }
        if b.skip || b.skip_within.is_some() {
            body.sure = false;
            return;
        }
        let mut codes = (None, None);
        let mut axes: Vec<(usize, f64)> = Vec::new();
        for (k, w) in b.words.iter().enumerate() {
            if w.letter == b'#' && !linuxcnc {
                // (`#1=0`: a local or common variable's value, no mode, offset or position)
                let n = crate::text::digits_value(w.index).filter(|n| (1..1000).contains(n));
                let Some(n) = n else {
                    body.sure = false;
                    return;
                };
                body.set.retain(|&(m, _)| m != n);
                let written = [w.sign, w.number].concat();
                let value = std::str::from_utf8(&written)
                    .ok()
                    .and_then(crate::decimal::Dec::parse);
                if let Some(v) = value.filter(|_| w.expression.is_empty()) {
                    body.set.push((n, v));
                }
                continue;
            }
            if !w.index.is_empty() || !w.expression.is_empty() {
                body.sure = false;
                return;
            }
            let Some(v) = self.readable.get(k).copied().flatten() else {
                // (an O word's number is no value here)
                if w.letter == b'O' && (!linuxcnc || first) {
                    continue;
                }
                body.sure = false;
                return;
            };
            let code = v.is_whole().then(|| v.trunc());
            let known = match w.letter {
                b'N' | b'F' | b'S' | b'I' | b'J' | b'K' | b'R' => true,
                b'O' => !linuxcnc || first,
                b'X' | b'Y' | b'Z' => {
                    axes.push((usize::from(w.letter - b'X'), v.to_f64()));
                    true
                }
                b'G' => match code {
                    Some(c @ 0..=3) => {
                        codes.0 = Some(c);
                        true
                    }
                    Some(c @ (90 | 91)) => {
                        codes.1 = Some(c == 91);
                        true
                    }
                    Some(17 | 40 | 80 | 94) => true,
                    _ => false,
                },
                b'M' => match code {
                    Some(0 | 1 | 3 | 4 | 5 | 7 | 8 | 9) => true,
                    Some(99) => {
                        returns = true;
                        true
                    }
                    _ => false,
                },
                _ => false,
            };
            if !known {
                body.sure = false;
                return;
            }
        }
        if returns && !axes.is_empty() {
            body.sure = false;
            return;
        }
        if let Some(mode) = codes.1 {
            body.wrote = Some(mode);
            body.steps.push(Step::Mode(mode));
        }
        if let Some(motion) = codes.0 {
            body.motion = Some(motion);
        }
        body.steps
            .extend(axes.into_iter().map(|(i, v)| Step::Axis(i, v)));
        if body.steps.len() > STEPS {
            body.sure = false;
        }
        body.returned = returns;
    }

    /// The body in hand returns (block `b`, its M99 or `endsub`, not read yet here): where
    /// it is known, what it leaves -- its G90/G91 (`Some(Some(g91))`, `Some(None)`: it wrote
    /// none) -- and the caller's moves after its calls judged.
    #[cold]
    #[inline(never)]
    pub(super) fn resumed_returned(&mut self, b: &BlockView<'_>) {
        let Some(mut r) = self.resumed.take() else {
            return;
        };
        if let Some(body) = r
            .bodies
            .last_mut()
            .filter(|body| !body.returned && body.sure && self.in_hand == Some(body.key))
        {
            self.resumed_body(body, b);
            if !body.returned {
                body.sure = false;
            }
            // (its block read after: nothing more of it followed; judged there, after the
            // findings held for its return are decided, callmode.rs: review 80-calls80 R1)
            body.returned = true;
            r.due = true;
        }
        self.resumed = Some(r);
    }

    /// A body just returned: the calls whose bodies are all known judged in turn, from
    /// the first not judged yet, each later call from where the moves before it end.
    fn resumed_finished(&mut self, r: &mut Resumed) {
        if r.assumed && !r.main_end {
            return;
        }
        while !r.broken && r.judged < r.calls.len() {
            let c = &r.calls[r.judged];
            // (its body, and those it runs on into, in turn: each returned, or judged at
            // its return)
            let mut chain: Vec<&Body> = Vec::new();
            let mut key = Some(c.key);
            while let Some(k) = key.filter(|_| chain.len() < r.bodies.len()) {
                let Some(body) = r.bodies.iter().find(|body| body.key == k) else {
                    // (its body not read yet: judged at its return)
                    return;
                };
                if !body.returned {
                    return;
                }
                chain.push(body);
                key = body.then;
            }
            let entry = if c.chained {
                r.carry
            } else {
                Some(Carry {
                    at: c.start,
                    incremental: c.incremental,
                    motion: c.motion,
                })
            };
            let steps = chain.iter().map(|body| body.steps.len()).sum::<usize>();
            let known = c.checked
                && key.is_none()
                && chain
                    .iter()
                    .all(|body| body.sure && body.dead.is_none() && body.goto.is_none())
                && steps.saturating_mul(c.runs as usize) <= STEPS;
            let Some(mut at) = entry.filter(|_| known) else {
                r.broken = true;
                return;
            };
            // (each run from where the one before left the tool, in the mode it left: a
            // body that leaves G91 moves again at each pass, one that leaves G90 ends where
            // it ends)
            for _ in 0..c.runs {
                for step in chain.iter().flat_map(|body| &body.steps) {
                    match *step {
                        Step::Mode(g91) => at.incremental = g91,
                        Step::Axis(k, v) if at.incremental => at.at[k] = at.at[k].map(|a| a + v),
                        Step::Axis(k, v) => at.at[k] = Some(v),
                    }
                }
            }
            at.motion = chain
                .iter()
                .rev()
                .find_map(|body| body.motion)
                .or(at.motion);
            let wrote = chain.iter().rev().find_map(|body| body.wrote);
            let carry = self.resumed_judged(c, wrote, at);
            r.carry = carry;
            r.judged += 1;
        }
    }

    /// Whether the body `key` returned known: the G90/G91 it leaves written (None: none).
    pub(super) fn resumed_leaves(&self, key: i64) -> Option<Option<bool>> {
        let r = self.resumed.as_ref()?;
        let body = r.bodies.iter().find(|body| body.key == key)?;
        (body.returned && body.sure && body.then.is_none()).then_some(body.wrote)
    }

    /// The caller's moves after call `c` judged from `at`, where the runs of `body` leave the
    /// tool, in the mode they leave: a TG601 at each position beyond the travel that begins
    /// an excursion. Where they end (None: not known).
    fn resumed_judged(&mut self, c: &Call, wrote: Option<bool>, at: Carry) -> Option<Carry> {
        let enabled = self.selection.enabled(Rule::TravelExceeded);
        let Carry {
            mut at,
            incremental: leaves,
            motion,
        } = at;
        let name = &c.named;
        let line = c.line;
        let mut outside = [0i8; AXES];
        let mut said = Vec::new();
        let mut incremental = leaves;
        for m in &c.moves {
            if m.motion.is_none() && !matches!(motion, Some(0 | 1)) {
                self.found.extend(said);
                return None;
            }
            incremental = m.own.unwrap_or(leaves);
            for &(k, v, column) in &m.axes {
                at[k] = if incremental {
                    at[k].map(|a| a + v)
                } else {
                    Some(v)
                };
                let (Some(work), Some(offset), Some((low, high)), true) =
                    (at[k], c.offset[k], self.travel.of_place(JUDGED[k]), enabled)
                else {
                    continue;
                };
                let work = work * c.factor;
                let machine = work + c.shift[k] + offset.to_f64();
                let side = super::limits::travel_side(machine, (low, high));
                if side == 0 || side == outside[k] {
                    outside[k] = side;
                    continue;
                }
                outside[k] = side;
                if m.said.contains(&column)
                    || self.found.iter().any(|f| {
                        f.rule == Rule::TravelExceeded && f.line == m.line && f.column == column
                    })
                {
                    continue;
                }
                let g = if incremental { 91 } else { 90 };
                let runs = if c.runs > 1 {
                    format!(" {} times", c.runs)
                } else {
                    String::new()
                };
                let why = match (m.own, wrote) {
                    (Some(_), _) => format!(
                        "read in the caller's own G{g} after {name} of line {line}, whose \
                         program writes no work offset"
                    ),
                    (None, Some(_)) => format!(
                        "read in G{g}: the program that {name} of line {line} runs{runs} \
                         leaves G{g} and writes no work offset; G90/G91 are modal and its \
                         return restores neither"
                    ),
                    (None, None) => format!(
                        "read in G{g}, in force at {name} of line {line}, whose program \
                         writes no G90/G91 and no work offset"
                    ),
                };
                let shifted = if c.shift[k] == 0.0 {
                    String::new()
                } else {
                    format!(" + shift {}", super::round6(c.shift[k]))
                };
                said.push(Finding {
                    rule: Rule::TravelExceeded,
                    message: format!(
                        "{} goes to {} in machine coordinates (work {}{shifted} + G{} offset \
                         {}), outside the travel {low} to {high} ({why})",
                        super::AXES[JUDGED[k]] as char,
                        super::round6(machine),
                        super::round6(work),
                        c.work,
                        offset,
                    ),
                    line: m.line,
                    column,
                    span: false,
                    guessed: false,
                    placed: Placed::Not,
                    pending_on: Vec::new(),
                });
            }
        }
        self.found.extend(said);
        Some(Carry {
            at,
            incremental,
            motion: c.moves.iter().rev().find_map(|m| m.motion).or(motion),
        })
    }
}
