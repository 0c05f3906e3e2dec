//! Characters and structure (rules TG100-TG127): the program's start and end, its
//! identification and program number, comments, the block skip and the alignment ':', and a
//! block that cannot be read.

use super::{chars, BlockView, Checker, Colons, SubFile, Unreadable, Word};
use crate::decimal::Dec;
use crate::dialect;
use crate::lex::{blank, Family};
use crate::rules::Rule;
use crate::statement::Kind;
use crate::text::{column, py_repr};
use std::collections::HashSet;

/// The first `#` of `text` from `from`: 8 bytes at a time (a zero-byte mask of the bytes
/// XOR `#`), the last few one by one. A bracketed expression is a few dozen bytes, where
/// memchr's dispatch and `position`'s byte loop both cost more; the lowest flagged byte of
/// the mask is exact (a false flag is only ever above a true one).
#[inline]
fn next_hash(text: &[u8], mut from: usize) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGHS: u64 = 0x8080_8080_8080_8080;
    while let Some(chunk) = text.get(from..from + 8) {
        let mut bytes = [0u8; 8];
        bytes.copy_from_slice(chunk);
        let x = u64::from_le_bytes(bytes) ^ (ONES * u64::from(b'#'));
        let found = x.wrapping_sub(ONES) & !x & HIGHS;
        if found != 0 {
            return Some(from + (found.trailing_zeros() / 8) as usize);
        }
        from += 8;
    }
    text.get(from..)?
        .iter()
        .position(|&c| c == b'#')
        .map(|at| from + at)
}

use crate::tokenizer::{equal_bytes, name_key, HotName, HOT};
/// The words of a block walked by [`walk_expression`] (a word after them is read by each
/// rule's own walk), and what one walk finds: the tokenizer's ([`crate::tokenizer::WALKED`],
/// [`ExpressionWalk`]), which writes the same walk of a plain line's bracketed words as it
/// scans them.
pub(super) use crate::tokenizer::{ExpressionWalk, WALKED};

/// No word walked: each rule reads a word's expression itself.
const NOT_WALKED: [ExpressionWalk; WALKED] = [ExpressionWalk {
    plain: false,
    count: 0,
    names: [(0, 0); 4],
    keys: [0; 4],
}; WALKED];

/// The bytes a plain bracketed expression holds between its brackets outside a named
/// parameter ([`walk_expression`]): digits, `.`, `*`, `+`, `-` and blanks (`#` apart).
const PLAIN_BYTES: [bool; 256] = {
    let mut table = [false; 256];
    let mut c = b'0';
    while c <= b'9' {
        table[c as usize] = true;
        c += 1;
    }
    table[b'.' as usize] = true;
    table[b'*' as usize] = true;
    table[b'+' as usize] = true;
    table[b'-' as usize] = true;
    table[b' ' as usize] = true;
    table[b'\t' as usize] = true;
    table
};

/// One walk of a LinuxCNC word's `expression` ([`ExpressionWalk`]): whether it is a plain
/// bracketed one, and its named parameters. It stops at the first byte of another kind (a
/// function, a comparison, a `/`, a bracket inside): such an expression is read by each rule
/// as before.
pub(crate) fn walk_expression(expression: &[u8]) -> ExpressionWalk {
    let mut walk = ExpressionWalk::default();
    let n = expression.len();
    if n < 2 || n > usize::from(u16::MAX) || expression[0] != b'[' || expression[n - 1] != b']' {
        return walk;
    }
    let inside = &expression[..n - 1];
    let mut i = 1;
    while i < inside.len() {
        let c = inside[i];
        if PLAIN_BYTES[usize::from(c)] {
            i += 1;
            continue;
        }
        if c != b'#' {
            return walk;
        }
        if inside.get(i + 1) != Some(&b'<') {
            i += 1; // a numbered parameter's `#`
            continue;
        }
        // a named parameter: to its `>`, with no bracket or `/` in its name; a name of up
        // to 7 bytes found in the 8 after the `#<` at once
        let start = i;
        i += 2;
        let chunk = inside.get(i..i + 8).map(|c| {
            let mut bytes = [0u8; 8];
            bytes.copy_from_slice(c);
            u64::from_le_bytes(bytes)
        });
        match chunk.map(|c| (c, equal_bytes(c, b'>'))) {
            Some((c, close)) if close != 0 => {
                let len = (close.trailing_zeros() / 8) as usize;
                let name = (1u64 << (8 * len)) - 1;
                if (equal_bytes(c, b'[') | equal_bytes(c, b']') | equal_bytes(c, b'/')) & name != 0
                {
                    return walk;
                }
                i += len;
            }
            _ => loop {
                match inside.get(i) {
                    Some(b'>') => break,
                    Some(b'[' | b']' | b'/') | None => return walk,
                    Some(_) => i += 1,
                }
            },
        }
        if usize::from(walk.count) == walk.names.len() {
            return walk;
        }
        // (both below 65,536: the expression's length is)
        walk.names[usize::from(walk.count)] = (start as u16, i as u16);
        walk.keys[usize::from(walk.count)] = name_key(inside, start + 2, i - start - 2);
        walk.count += 1;
        i += 1;
    }
    walk.plain = true;
    walk
}

impl Checker {
    pub fn unreadable(&mut self, block: &Unreadable<'_>) {
        self.stats.blocks += 1;
        self.last_line = block.line;
        self.first = false;
        self.unreadable_label(block.text);
        // (LinuxCNC: a line after a call surely run of a body read before it that surely ends
        // the program, up to the main program's own end, is never read: rs274 runs `o300
        // sub` / `M2` / `o300 endsub` / `o300 call` / `G1 X` to its end, as the findings of
        // the other lines there are dropped, and as after a call of such a body written
        // later; review 63-lcnc63 N1)
        // (a definition after it is read where the program calls it: its lines are said;
        // review 76 F3)
        if self.linuxcnc_call_ended_at != 0
            && self.ended_line <= self.linuxcnc_call_ended_at
            && self.open_definition.is_none()
            && self.config.family == Family::LinuxCnc
        {
            return;
        }
        if self.unreached(block) {
            // never run: what it would set is not known all the same (a restart after it
            // is refused, as after any line the checker could not read)
            self.unread_effects(block.text, block.line);
            return;
        }
        // a Sinumerik's '(' is a bracket, not a comment: `R3=(R2-POT(3)` is an unclosed
        // bracket, said where the expression reader stopped
        // a Sinumerik's '(' is a bracket; a Fanuc's or Haas's nested comment is refused by the
        // tokenizer with what each of its readings sends (tokenizer::comment_close)
        let nested = if matches!(self.config.family, Family::Sinumerik | Family::MacroB) {
            0
        } else {
            nested_comment(block.text)
        };
        if nested > 0 {
            // ISO 6983-1 (clause 4) and rs274 refuse it
            let message = "comment inside a comment: '(' before the ')' that closes the first";
            self.report(Rule::NestedComment, message.into(), block.line, nested);
            return;
        }
        self.report(
            block.rule,
            block.message.to_string(),
            block.line,
            block.column.max(1),
        );
        self.unread_effects(block.text, block.line);
    }

    /// What a block the control refuses (a reading error) would have set is not known: the
    /// control alarms there, and no later rule may read a value kept from before it (a Haas's
    /// `N80 X 45. F300.`, refused at the X, followed by an arc measured from the X before).
    /// The words are found as the control's addresses are, a letter not inside a name and not
    /// in a comment: an axis's makes that axis unknown, F the feed, S the speed; any other
    /// (a G or M code, a tool, an offset number) or a parameter's assignment may change any
    /// mode, and everything the checker follows is forgotten, as after a call it cannot follow.
    fn unread_effects(&mut self, text: &[u8], line: usize) {
        self.refused_at.get_or_insert(line);
        // (what it sets may be the spindle speed: an `endif` after it gives none back)
        for open in &mut self.linuxcnc_if_speed {
            open.3 = false;
        }
        let mut depth = 0usize;
        let mut previous = b' ';
        let mut everything = false;
        for (i, &c) in text.iter().enumerate() {
            match c {
                b'(' => depth += 1,
                b')' => depth = depth.saturating_sub(1),
                b';' if depth == 0 => break,
                b'=' | b'#' if depth == 0 => everything = true,
                _ => {}
            }
            if depth == 0 && c.is_ascii_alphabetic() && !previous.is_ascii_alphanumeric() {
                let next = text[i + 1..]
                    .iter()
                    .find(|b| !crate::lex::blank(**b))
                    .copied()
                    .unwrap_or(b' ');
                if !next.is_ascii_alphabetic() && next != b'_' {
                    match c.to_ascii_uppercase() {
                        letter @ (b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'A' | b'B' | b'C') => {
                            self.machine.forget_axis(letter)
                        }
                        b'F' => self.machine.forget_feed(),
                        b'S' => self.machine.forget_speed(),
                        // a sequence number, a comment's or a message's letter: nothing set
                        b'N' | b'O' => {}
                        _ => everything = true,
                    }
                }
            }
            previous = c;
        }
        if everything {
            self.machine.forget();
            self.params.clear();
            self.motion_unknown = true;
            self.lose_offsets(line, "a block the control cannot read");
        }
    }

    /// TG412: a `%` line LinuxCNC's reader refuses ("Bad character '%' used",
    /// [`dialect::ReadingEnd::refuses_percent`]): in a file not begun with a `%` line, or a
    /// `%` with more than blanks after it. One after the endsub of a subroutine file named by
    /// its label (a `%` an editor or a post ends the file with) is never read: a call runs the file from
    /// its sub and returns at the endsub (LinuxCNC's O codes, "Calling Files"; `rs274 -g` of
    /// `o<tp> call` with `tp.ngc` ending in `o<tp> endsub` and `%`: no error), as the file's
    /// missing M2 is no TG114. It is said only where a line after it makes the file a
    /// program, which rs274 would run past the definition to the `%` ([`SubFile`]).
    pub(super) fn refused_percent(&mut self, b: &BlockView<'_>) {
        let column = b.text.iter().position(|&c| c == b'%').map_or(1, |i| i + 1);
        // (only a file whose name is its label's, `tp.ngc` for `o<tp> sub`, is called: rs274
        // opens the label, lower-cased and without blanks, with `.ngc`; one named otherwise
        // runs only as a program, where rs274 reads the `%`, review 57b F1)
        let label = self
            .sub_label
            .strip_prefix(b"o<")
            .and_then(|l| l.strip_suffix(b">"));
        let called = label.is_some() && self.called_as.as_deref() == label;
        // (one after an endsub of another label outside the body's conditions, TG138's, in the
        // definition still open, is read by neither: called, rs274 returns at that endsub;
        // run as a program, it skips the definition to its own endsub, the `%` a line it
        // skips, "File ended with no percent sign or program end" where there is none;
        // review 57b F3)
        if self.sub_file == SubFile::Open && self.sub_returned {
            return;
        }
        if self.sub_file == SubFile::Closed && called {
            self.sub_percent.get_or_insert((b.line, column));
            return;
        }
        self.percent_refusal(b.line, column);
    }

    /// The TG412 of [`Checker::refused_percent`], at `line` and `column`.
    pub(super) fn percent_refusal(&mut self, line: usize, column: usize) {
        let why = if self.reading_end.percent_file() {
            "the closing % of a file begun with % stands alone on its line"
        } else {
            "the file does not begin with a % line, so rs274 reads this one as a block, and no \
             word begins with %"
        };
        let message = format!("Bad character '%' used (rs274ngc): {why}");
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// The next program of a file of several (a memory backup, a subprogram after the main
    /// program): checked as its own, from the control's reset state, with the position, feed
    /// and speed unknown (it runs where its caller or the operator left the machine).
    pub(super) fn next_program(&mut self) {
        self.flow_ended();
        self.passage_ended(None);
        self.no_feed_target = 0;
        self.targets_ended();
        self.linuxcnc_locals_ended();
        self.reach_reset();
        self.refused_at = None;
        self.conflict_at = None;
        self.programs += 1;
        self.ended_line = 0;
        self.after_watch = false;
        self.skipped_end = false;
        self.surely_ended = false;
        self.linuxcnc_call_ended_at = 0;
        self.linuxcnc_end_depth = None;
        self.sub_ended = false;
        self.after_end_reported = false;
        self.closed = false;
        self.percent_closed = false;
        self.first_words = true;
        self.empty_folder = false;
        self.offsets_section = false;
        // the reset state, with no position known: the feed and the speed are the reset
        // state's (none), as for the file's first program, so that a main program's feed move
        // without F is found (held, as in the first, until the program shows it returns)
        self.machine.forget();
        self.machine.reset();
        self.drawn.placed = 0; // its positions are the new program's to give
        self.params.clear();
        self.polar = super::polar::Polar::at_origin();
        // a GOTO does not leave its program: the jumps read in the one before arrive nowhere
        // here (Fanuc's GOTOn searches the sequence number in the program it runs)
        self.goto_targets.clear();
        self.goto_computed = false;
        self.jumped = false;
        self.numbered = false;
        self.reexpressed_held = None;
        self.goto_names.clear();
        self.arrival = None;
        self.jumps_pending.clear();
        self.runs.clear();
        self.after_block = false;
        self.motion_unknown = false;
        self.cycle_unmodelled = false;
        self.linuxcnc_motion = super::tooling::LinuxCncMotion::Known(None);
        self.linuxcnc_dynamic_compensation = false;
        self.linuxcnc_compensation_quiet = None;
        self.linuxcnc_uvw_let_pass = None;
        self.linuxcnc_uvw_plane = false;
        self.linuxcnc_plane_unknown = false;
        self.linuxcnc_plane_blocks.clear();
        self.linuxcnc_plane_body_blocks.clear();
        self.linuxcnc_plane_before_sub = None;
        self.linuxcnc_plane_subs.clear();
        self.linuxcnc_motion_plain = false;
        self.linuxcnc_motion_subs.clear();
        self.linuxcnc_sub_motion.clear();
        *self.linuxcnc_later = LaterCalls::default();
        self.linuxcnc_spindle_unknown = false;
        self.linuxcnc_tool_change_stopped = false;
        self.linuxcnc_point_unsure = 0;
        self.linuxcnc_units_turned = 0;
        self.linuxcnc_double = Default::default();
        self.linuxcnc_defined.clear();
        self.linuxcnc_named.clear();
        self.linuxcnc_named_seen.clear();
        self.linuxcnc_short_seen = [0; 8];
        // (and the tokenizer's hot names, which are names seen; a line it read with them is
        // looked up as if it had none)
        self.line_walks.hot = [HotName::NONE; HOT];
        self.line_walks.all_hot = false;
        self.linuxcnc_open_flow.clear();
        self.linuxcnc_may = None;
        self.linuxcnc_flow_reads.clear();
        self.linuxcnc_if_ends.clear();
        self.linuxcnc_open_at.clear();
        self.linuxcnc_flow_assigned.clear();
        self.linuxcnc_o_labels.clear();
        self.linuxcnc_labels_named = (HashSet::new(), false);
        self.linuxcnc_skipping = None;
        self.linuxcnc_subs_defined.clear();
        self.linuxcnc_mode_unsure = false;
        self.linuxcnc_distance_unsure = false;
        self.linuxcnc_distance_from = None;
        self.linuxcnc_distance_in = 0;
        self.linuxcnc_saved = Saved::Empty;
        self.linuxcnc_plane_saved = PlaneAt::UNKNOWN;
        self.linuxcnc_g53_before = None;
        *self.linuxcnc_body_distance = BodyDistance::default();
        self.linuxcnc_call_refused.clear();
        self.linuxcnc_bodies.clear();
        self.linuxcnc_definition_mode_unsure = false;
        self.linuxcnc_definition_flow.clear();
        self.linuxcnc_definition_opened.clear();
        self.linuxcnc_definition_feed = None;
        self.linuxcnc_if_speed.clear();
        self.linuxcnc_speed_back = None;
        self.linuxcnc_called_ahead.clear();
        self.linuxcnc_dead_defs.clear();
        self.linuxcnc_dead_called.clear();
        self.linuxcnc_skip_held = None;
        self.linuxcnc_loop_defs = None;
        self.linuxcnc_compensation_unknown = false;
        self.linuxcnc_cycle_bottom = None;
        self.linuxcnc_cycle_r = None;
        self.linuxcnc_feed_rate = super::tooling::LinuxCncFeed::Zero;
        self.linuxcnc_rate = Some(Dec::ZERO);
        self.linuxcnc_feed_saved = None;
        self.linuxcnc_feed_loose = None;
        self.linuxcnc_extras = RestoreExtras::START;
        self.linuxcnc_feed_restored_at = None;
        self.linuxcnc_m72_dropped = None;
        self.linuxcnc_nurbs = super::tooling::Nurbs::default();
        self.linuxcnc_nurbs_last = None;
        self.data_input = dialect::DataInput::for_control(self.config.family, self.config.haas);
        self.program_section = None;
        self.mode_lost_codes = None;
        self.mode_lost_by.clear();
    }

    /// A call by number of a program the checker does not read there
    /// ([`Checker::call_mode_lost`]): its G90/G91 not known after it.
    #[cold]
    #[inline(never)]
    /// A program of the file read before that writes work offsets or shifts the coordinates
    /// ([`Checker::offset_writers`]; read as a program of its own, not kept for its calls:
    /// a G10 whose P is a G65 argument) writes them here as it did there (review 58d F5),
    /// and the profile's offsets are not in force after it where it lost them; what a
    /// program the file does not hold writes is not followed, erring on the side of the
    /// alarm ([`Checker::offsets_written`]).
    fn call_not_followed(&mut self, b: &BlockView<'_>, number: i64) {
        // (a Haas's local subprogram: the caller's G90/G91 read on, as before, its later
        // calls' findings held where it writes one; review 77-calls77 F5)
        if number < LOCAL_BODY {
            let (call, column) = self.call_words(b);
            self.call_mode_lost(&call, (b.line, column), &program_name(number), Some(number));
        }
        // (a call that surely runs and enters the body at its start: not behind a jump,
        // condition or loop of the caller's, not a modal call (G66, run at the moves after
        // it, or none), not `M98 P.. Q..` entering at a sequence number, not a skippable
        // block; review 62a F7)
        let surely = !self.jumped
            && !b.skip
            && b.skip_within.is_none()
            && !self.values.gs().contains(&66)
            && !b
                .words
                .iter()
                .any(|w| w.letter == b'Q' && w.index.is_empty())
            // (`M98 P2000 L0`: a repeat count of zero may run the body no time; no page
            // at hand says: not carried, review 62a F7's g75)
            && !b.words.iter().enumerate().any(|(i, w)| {
                w.letter == b'L'
                    && w.index.is_empty()
                    && self.readable[i].is_some_and(|v| v.to_f64() == 0.0)
            });
        if let Some((writes, loses)) = self.offset_writers.get(&number).cloned() {
            self.shift_carried(number, surely);
            self.offsets_written.then(&writes);
            self.offset_writer(&writes, loses);
            if loses {
                let name = program_name(number);
                self.offsets_rewritten(b.line, &format!("{name} changes the offsets"));
            }
        } else if !self.file_programs.contains(&number) {
            // (the G52 it leaves on, known at the file's end: crate::check::leaves)
            if surely && self.config.family == Family::MacroB && number < LOCAL_BODY {
                self.later_shift_called(number);
            }
            self.call_of_unread(number);
        }
    }

    /// A jump or call on `line` the checker does not follow: the offsets may be rewritten
    /// there ([`Checker::offsets_rewritten`]), unless it is a call of a program read after
    /// the end only ([`Checker::call_of_unread`]: a LinuxCNC definition or FANUC-style `O`
    /// program, a Haas's local subprogram), whose writes are known where its lines are read
    /// ([`Checker::offsets_unread_only`]). Such a call keeps the spans set aside at a
    /// selection of another known system ([`Checker::selection_spans`]) for the body, which
    /// runs under the call's system and is judged so; any position outside such a body (the
    /// main program's after the call, a body read under no call's offset), one not judged as
    /// a machine position in it, or a G91 joins them again, whether they fit or not, as the
    /// call joined them before (review 78-lcnc78b F7:
    /// `G54` / `G0 X-650.` / `G57` / `M98 P2000` /
    /// `M30` / `O2000` / `G0 X1000.` / `M99` on G57 X -300 runs at machine -650, then 700,
    /// and was "X spans 1650"; review 79-lcnc79 F1: its twins with such a position, kept).
    #[cold]
    #[inline(never)]
    pub(super) fn call_offsets_rewritten(&mut self, line: usize, calls: bool, never: bool) {
        // (a call of a LinuxCNC definition after the end, Checker::later_call: only its
        // writes, known there)
        let unread_here = std::mem::take(&mut self.call_unread_here);
        let unread_only = unread_here && (!self.offsets_lost || self.offsets_unread_only);
        let parked = if unread_only {
            self.spans_parked.take()
        } else {
            None
        };
        // (a FANUC's or Haas's first jump keeps what is in force for the calls after it:
        // callflow.rs)
        let unjudged = self.span_unjudged;
        self.flow_rewritten(line, calls, unread_here, never);
        // (the positions after it are judged as before, their findings held to where its
        // writes are known: a span holds no position not judged for it)
        if unread_only {
            self.span_unjudged = unjudged;
        }
        if parked.is_some() {
            self.spans_parked = parked;
            self.spans_parked_call = true;
        }
        self.offsets_unread_only = unread_only;
    }

    /// A call of the program `key`, not read yet: what it writes is known where its lines
    /// are read, at the file's end (a G54-G59 of the main's own after the call judged, held
    /// to then: [`Checker::work_unread_reselected`]).
    fn call_of_unread(&mut self, key: i64) {
        let unread = super::limits::Written {
            unread: vec![key],
            ..Default::default()
        };
        self.call_unread_here = true;
        self.resumed_called(key);
        self.flow_unread(key);
        self.offsets_written.then(&unread);
        self.offset_writer(&unread, false);
    }

    /// A Haas's M97 (`M97 P1000`: the blocks of the program in hand from its N1000 to an M99,
    /// Haas Mill Operator's Manual, "M97 Local Sub-Program Call"), in a main program not read
    /// apart, under a profile that gives work offsets: kept as a call of a program written
    /// after it, by the key [`local_key`] gives, in the one implementation of such calls --
    /// its work offset and distance mode ([`Checker::call_work`]), its units, its G90/G91
    /// not known after it and its writes known only where its blocks are read
    /// ([`Checker::call_not_followed`]). Its blocks, after the main's M30, are read under the
    /// calls' offset ([`Checker::local_body`]), as an O2000 written after its M98 calls is
    /// (issue 32 item 4: `M97 P1000` / `G55` / `M97 P1000` / `M30` / `N1000 G0 X-700.` /
    /// `M99` runs X-700. at -800 at the second call). A P not known, a sequence number above
    /// 99999, or an M97 of a local subprogram's own: as before, not followed.
    #[cold]
    #[inline(never)]
    fn local_call(&mut self, b: &BlockView<'_>) {
        let Some(key) = self
            .called_number(b)
            .and_then(|n| local_key(self.in_hand, n))
        else {
            // (inside a local subprogram: an M97 not followed, which may change the
            // offsets its callers run under after it; review 77-calls77 F2)
            if self.in_hand.is_some_and(|n| n >= LOCAL_BODY) {
                self.after_mark();
            }
            return;
        };
        self.local_called = true;
        self.flow_unread(key);
        self.after_call(key);
        self.call_mode_kept(key);
        self.call_work(b, key);
        self.call_not_followed(b, key);
        self.call_units_seen(key);
    }

    /// A block after an end or a return (M30, M99) of a Haas's program whose M97 calls were
    /// kept ([`Checker::local_call`]): where it starts with a sequence number one of them
    /// names, the local subprogram begins, read as a program written after its calls is
    /// ([`Checker::work_of_calls`]): under the calls' work offset where they agree (in
    /// their distance mode and units), under none where they do not or one was made where
    /// it was not known (a G110-G129, a G10, a call not followed before it).
    #[cold]
    #[inline(never)]
    pub(super) fn local_body(&mut self, b: &BlockView<'_>) {
        if !self.split.follows_end() || self.early_on {
            return;
        }
        let Some(p) = b
            .words
            .first()
            .filter(|w| w.letter == b'N' && w.index.is_empty() && w.expression.is_empty())
            .and_then(|w| std::str::from_utf8(w.number).ok())
            .and_then(|n| n.parse::<i64>().ok())
        else {
            return;
        };
        let main = if self.in_hand.is_some_and(|n| n >= LOCAL_BODY) {
            self.local_main
        } else {
            self.in_hand
        };
        let Some(key) = local_key(main, p).filter(|k| self.call_works.contains_key(k)) else {
            return;
        };
        // (the main program's blocks are all read, those after its M30 a jump may reach
        // among them: callflow.rs; review 79-calls79 F5)
        self.flow_ended();
        // (the body before it, run on into: its end)
        if self.in_hand.is_some_and(|n| n >= LOCAL_BODY) {
            self.local_body_end();
        }
        self.local_body_begin(key, main);
        // (its first block is this one: limits.rs, `body_block`)
        if self.spans_parked_body.is_some() {
            self.body_block(b);
        }
    }

    /// A local subprogram (Haas M97) or a LinuxCNC definition after the end, called before
    /// it (`key`), begins: read under its calls' offset, mode and units; `main` the program
    /// in hand again at its end.
    fn local_body_begin(&mut self, key: i64, main: Option<i64>) {
        let ended = if self.config.work_offsets.is_empty() {
            None
        } else {
            self.body_spans_known(key)
        };
        self.local_main = main;
        self.in_hand = Some(key);
        self.call_mode_begun(key);
        self.file_programs.insert(key);
        self.offsets_unread_only = false;
        self.outside = [0; 9];
        self.offsets_written = Default::default();
        self.units_unknown = false;
        match self.call_units.get(&key) {
            Some(&Some((units, feed_units, given))) => {
                let s = &mut self.machine.state;
                (s.units, s.feed_units, s.units_given) = (units, feed_units, given);
            }
            _ => {
                self.units_unknown = true;
                self.machine.state.units_given = false;
            }
        }
        // (its run starts in its calls' distance mode, not in the one the main left at its
        // end; calls that disagree: under no offset)
        self.work = None;
        if let Some(Some(c)) = self.call_works.get(&key) {
            self.machine.state.incremental = c.incremental;
            self.work_of_calls(key);
            self.body_spans_parked(ended);
        }
    }

    /// The local subprogram in hand returns (M99) or another begins: the state read before
    /// it given back ([`Checker::work_call`]), it marked where it leaves a tool length
    /// offset or other units ([`Checker::after_end`]), the main program in hand again.
    #[cold]
    #[inline(never)]
    pub(super) fn local_body_end(&mut self) {
        self.work_call_end();
        self.after_end();
        self.in_hand = self.local_main;
    }

    /// A call by number's calling words as the messages name it (`M98 P1000`, `G66 P9010`,
    /// `G65 P9010`) and the column of its P (1 where it has none).
    fn call_words(&self, b: &BlockView<'_>) -> (String, usize) {
        let p = b
            .words
            .iter()
            .find(|w| w.letter == b'P' && w.index.is_empty());
        let token = p.map_or_else(String::new, |w| w.token());
        let call = if self.values.ms.contains(&98) {
            format!("M98 {token}")
        } else if self.values.ms.contains(&97) {
            format!("M97 {token}")
        } else if let Some(&(_, _, text)) = b.statements.iter().find(|s| s.1 == Kind::Call) {
            let label = crate::statement::o_label_shown(text);
            return (format!("{} call", String::from_utf8_lossy(&label)), 1);
        } else if self.values.gs().contains(&66) {
            format!("G66 {token}")
        } else {
            format!("G65 {token}")
        };
        (call, p.map_or(1, |w| w.column))
    }

    /// A call (`M98 P1000`, `G65 P9010`) in a FANUC's or a Haas's file: the units in force
    /// where it is made, kept for the program of that number, which runs in them
    /// ([`Checker::called_units`]). A second call in other units, or one made where the units
    /// are not known, leaves them unknown there. (M97 calls a sequence number of the program
    /// in hand, and a SINUMERIK's L a subprogram of another file: no program of this file.)
    pub(super) fn call_made(&mut self, b: &BlockView<'_>) {
        // (only a FANUC's or a Haas's file is split into programs by their O numbers,
        // dialect::ProgramSplit)
        if !dialect::splits(self.config.family, self.config.program_number)
            || self.config.family != Family::MacroB
        {
            return;
        }
        let by_number =
            self.values.ms.contains(&98) || self.values.gs().iter().any(|&g| g == 65 || g == 66);
        self.call_numbers_seen(b, by_number);
        if !by_number {
            if self.early_on {
                // (a Haas's M97 inside a program read apart: a G90/G91 of the sequence it
                // runs is not followed; review 47, F1)
                self.early_call_unread(b);
            } else if self.config.haas
                && !self.config.work_offsets.is_empty()
                && self.values.ms.contains(&97)
            {
                self.local_call(b);
            }
            return;
        }
        let Some(number) = self.called_number(b) else {
            // (a P the check cannot evaluate, `M98 P#1`: which program runs is not known)
            if let Some(w) = b
                .words
                .iter()
                .find(|w| w.letter == b'P' && w.index.is_empty())
            {
                let code = if self.values.ms.contains(&98) {
                    "M98"
                } else if self.values.gs().contains(&66) {
                    "G66"
                } else {
                    "G65"
                };
                self.call_unknown(format!("{code} {}", w.token()), b.line, w.column);
            }
            return;
        };
        // a FANUC whose program numbers have four digits (no 8-digit option: the profile's O
        // format) reads M98's P as the repeat count above the number's four digits, `M98
        // P32000` O2000 three times (0i-F Operator's Manual, "Subprogram call (M98)":
        // P____ ____; review 39, finding 5); G65's P is the number alone
        let number = match self.config.formats.iter().find(|(l, _)| *l == b'O') {
            Some((_, f)) if f.before == 4 && self.values.ms.contains(&98) => {
                number % 10_i64.pow(f.before)
            }
            _ => number,
        };
        // (a program that leaves what is not followed: its caller too, review 62a)
        self.after_call(number);
        // (before the call's own reading: the state it is made in)
        self.call_work(b, number);
        if !self.merged_unplaced.is_empty() {
            let (call, column) = self.call_words(b);
            self.merged_unplaced_judged(number, &call, (b.line, column));
        }
        let followed = (self.early_on || !self.pending.is_empty() || !self.given_up.is_empty())
            && {
                let (call, column) = self.call_words(b);
                self.early_call(super::called::Key::Number(number), call, (b.line, column))
            };
        if !followed {
            self.call_not_followed(b, number);
        }
        self.call_units_seen(number);
    }

    /// The whole number a call's P gives (`M98 P2000`, `M97 P1000`): None where its value is
    /// not known or not whole.
    fn called_number(&self, b: &BlockView<'_>) -> Option<i64> {
        b.words
            .iter()
            .enumerate()
            .find(|(_, w)| w.letter == b'P' && w.index.is_empty())
            .and_then(|(i, _)| self.readable[i])
            .filter(|v| v.is_whole())
            .map(|v| v.trunc())
    }

    /// The units a call of program `key` (a number, a Haas's local subprogram, a later
    /// LinuxCNC definition) is made in, kept for it: the same at every call, or None where
    /// two calls differ or one is made where the units are not known. Read where its blocks
    /// are read after the calls and where it ends ([`Checker::after_end`]).
    fn call_units_seen(&mut self, key: i64) {
        let s = &self.machine.state;
        let units = (!self.units_unknown).then_some((s.units, s.feed_units, s.units_given));
        self.call_units
            .entry(key)
            .and_modify(|known| {
                if *known != units {
                    *known = None;
                }
            })
            .or_insert(units);
    }

    /// A call of program `number` (`b`): the work offset in force here kept for it where
    /// the profile's value of it is the one in force (no G10, shift, frame, or call the
    /// checker does not follow before it in the caller's run, none in the call's block; the
    /// caller's own selection, not one guessed from the program before), with the distance
    /// mode; a second call under another, or one where it is not known, leaves it unknown
    /// ([`Checker::call_works`]). A program of that number written after the call runs under
    /// it: a FANUC's M98 and G65 change no modal state, and the work offset (G54-G59, group
    /// 14) is modal (0i-MF Operator's Manual, "Subprogram call (M98)", "Custom Macro B"; Haas
    /// Mill Operator's Manual, M98; review 59a, F12).
    #[cold]
    #[inline(never)]
    fn call_work(&mut self, b: &BlockView<'_>, number: i64) {
        if self.config.work_offsets.is_empty() {
            return;
        }
        // (a G66 runs the program at each later move, under the offset in force there: not
        // this block's)
        let other_g = b
            .words
            .iter()
            .enumerate()
            .any(|(i, w)| w.letter == b'G' && !self.readable[i].is_some_and(|v| v.eq_int(65)));
        let q_entry = self.values.ms.contains(&98) && b.words.iter().any(|w| w.letter == b'Q');
        let known = self.work.filter(|_| {
            !self.offsets_lost
                && !other_g
                && self.work_guessed.is_none()
                && !self.work_run_on
                && !self.shifts_on()
                && !self.frames_on()
                && self.transformed.is_none()
                // (after a return in the caller's program: reached only by a jump, the
                // offset read in file order is not surely the one there, review 61a F10)
                && !self.sub_ended
                // (`M98 P2000 Q10` enters the body at its N10, not at its first block: 0i-F
                // Operator's Manual, "Subprogram call (M98)"; review 61a F12)
                && !q_entry
        });
        // a G66 makes no call here: it registers the macro, run after each later block that
        // moves until G67, under the offset in force at that move (0i-MF Operator's Manual,
        // "Modal call: G66"), or never (review 61a F9: `G66 P2000` / `G54` / `G0 X10.` /
        // `G67`, its body after M30 was judged under G55)
        let modal = self.values.gs().contains(&66);
        // (after the main program's first jump or inside a loop: callflow.rs)
        let known = match known {
            None if self.flow_calls.is_some()
                && !other_g
                && !modal
                && !q_entry
                && !self.sub_ended =>
            {
                self.flow_call_work(number)
            }
            known => known,
        };
        // (a caller read apart in units only assumed: its call's units are its own caller's
        // where it returns, review 61a F11; the reset state's where it ends as a main
        // program, F7: `O1000` / `G10 L2 P2 X-200.` / `G55` / `M98 P3000` / `M30`)
        let assumed = !self.machine.state.units_given && self.early_on;
        if known.is_none() && !modal {
            self.call_works_unknown.insert(number);
        }
        let mode_by_self = self.mode_lost_codes == Some(self.machine.distance_codes)
            && !self.mode_lost_by.is_empty()
            && self.mode_lost_by.iter().all(|&n| n == number);
        if let Some(work) = known.filter(|_| !modal) {
            *self.call_works_seen.entry(number).or_default() |= 1u8 << (work - 54).clamp(0, 7);
        }
        let here = known.filter(|_| !modal).map(|work| {
            let (call, _) = self.call_words(b);
            let s = &self.machine.state;
            CallWork {
                work,
                incremental: s.incremental,
                length: (s.length_offset, self.length_decimal),
                outside: self.outside,
                written: self.offsets_written.clone(),
                call,
                line: b.line,
                mode_by_self,
                others: Vec::new(),
                units_codes: self.machine.units_codes,
            }
        });
        if assumed && here.is_some() {
            self.call_works_assumed.push((number, here));
            return;
        }
        self.call_work_kept(number, here);
    }

    /// A program read apart, numbered, merged by its own units code: its positions under its
    /// own offset from here held to its end ([`Checker::units_merged`]).
    fn units_merged_from(&mut self) {
        if !self.early_on || self.config.family != crate::lex::Family::MacroB {
            return;
        }
        if let Some(n) = self.early.as_ref().and_then(|e| e.numbered()) {
            self.units_merged = Some(n);
        }
    }

    /// The program in hand ends (`returned`: M99): where it ends as a main, its positions
    /// held by [`Checker::units_merged_from`] are as said (the marks taken off).
    #[cold]
    #[inline(never)]
    pub(super) fn units_merged_ended(&mut self, returned: bool) {
        // (and its guessed findings held at its merge: a main's, said; review 61a F5's
        // second form is a program that returns)
        let marks = [
            self.units_merged
                .take()
                .map(|n| super::limits::PENDING_CALLS_WRITTEN - n),
            self.guess_marked
                .take()
                .map(|n| super::limits::PENDING_CALLED - n),
        ];
        if !returned {
            for mark in marks.into_iter().flatten() {
                for f in &mut self.found {
                    f.pending_on.retain(|&m| m != mark);
                }
            }
        }
    }

    /// The program in hand, merged by its own units code ([`Checker::units_merged`]), changes
    /// or shifts its own offsets (a G10, G52, G92, G54-G59, a work offset's variable): a
    /// position beyond the travel held before is one excursion with those after it, which
    /// this one may run under another value; held no longer, said as read, as before (review
    /// 63 F4: `G90 G55 G0 X-700.` / `G54` / `G0 X-780.` said only the first, which its
    /// callers' G10 puts inside).
    #[cold]
    #[inline(never)]
    pub(super) fn units_merged_stopped(&mut self) {
        let Some(n) = self.units_merged else {
            return;
        };
        // (none held yet: the offsets it selects or writes before its first are its own)
        let mark = super::limits::PENDING_CALLS_WRITTEN - n;
        if !self.found.iter().any(|f| f.pending_on.contains(&mark)) {
            return;
        }
        self.units_merged = None;
        for f in &mut self.found {
            f.pending_on.retain(|&m| m != mark);
        }
    }

    /// The value a G10 of its callers' run wrote before every call of program `n` on offset
    /// G`work`'s axis of place `place` (None where none wrote it, NaN where not known), and
    /// the programs written later called before them: None where no call, or calls that
    /// disagree.
    pub(super) fn calls_written(
        &self,
        n: i64,
        work: usize,
        place: usize,
    ) -> Option<(Option<f64>, Vec<i64>)> {
        let cw = self.call_works.get(&n)?.as_ref()?;
        Some((cw.written.value(work, place), cw.written.unread.clone()))
    }

    /// [`Checker::call_works`]: the offset `here` of a call of program `number`, joined
    /// with the calls' before it (None where they disagree).
    pub(super) fn call_work_kept(&mut self, number: i64, here: Option<CallWork>) {
        self.call_works
            .entry(number)
            .and_modify(|before| {
                let same = matches!((&*before, &here), (Some(a), Some(b))
                    if a.work == b.work && a.incremental == b.incremental
                        && a.length == b.length && a.written.same(&b.written));
                // (a call under another offset, no G10 value written, in the same mode or
                // in the one this program leaves: judged under each; the calls of this
                // program, not read there, are its own)
                let own = |w: &super::limits::Written| {
                    !w.any() && !w.moved && w.shifted == 0 && w.unread.iter().all(|&n| n == number)
                };
                let other = matches!((&*before, &here), (Some(a), Some(b))
                    if a.work != b.work && !a.mode_by_self
                        && (a.incremental == b.incremental || b.mode_by_self)
                        && a.length == b.length && own(&a.written) && own(&b.written));
                // (the same offset, the mode the one this program leaves: the first call's
                // reading holds for it, its own findings named; review 76-calls76 F6)
                let same_by_self = matches!((&*before, &here), (Some(a), Some(b))
                    if a.work == b.work && b.mode_by_self && a.length == b.length
                        && own(&a.written) && own(&b.written));
                // (the units codes counted at the call before this one: a units code of the
                // caller's since then, not since the first, makes this call's its own;
                // review 78-calls78 F6)
                let previous = before.as_ref().map(|a| a.units_codes);
                if let (Some(a), Some(b)) = (before.as_mut(), &here) {
                    a.units_codes = b.units_codes;
                }
                match (before.as_mut(), &here) {
                    (Some(a), Some(b)) if same || same_by_self => {
                        // (calls beyond the travel on different sides: the body's first
                        // position outside said, review 61a F3)
                        if a.outside != b.outside {
                            a.outside = [0; 9];
                        }
                    }
                    (Some(a), Some(b)) if other => {
                        if !a.others.iter().any(|o| o.0 == b.work) {
                            // (a Haas local subprogram or a LinuxCNC definition after the end: the G90/G91 it leaves
                            // after the first call is not followed there, so a later call's
                            // mode is its own only where it writes none)
                            let tentative = b.mode_by_self && a.incremental != b.incremental
                                || number >= LOCAL_BODY;
                            // (no units code of the caller's since the first call: it
                            // runs in the units the body leaves, callmode::Rescale)
                            let left = previous == Some(b.units_codes);
                            a.others.push((
                                b.work,
                                b.call.clone(),
                                b.line,
                                b.outside,
                                tentative,
                                left,
                            ));
                        }
                    }
                    _ => *before = None,
                }
            })
            .or_insert(here);
    }

    /// Where a program written after its calls ends (the next program begins): the state
    /// read before it given back ([`Checker::work_call`]).
    #[cold]
    #[inline(never)]
    fn work_call_end(&mut self) {
        self.body_spans_end();
        self.work_call_tentative_end();
        if let Some(w) = self.work_call.take() {
            self.work = w.work_before;
            self.offsets_lost = w.lost_before;
            self.outside = w.outside_before;
            (self.machine.state.length_offset, self.length_decimal) = w.length_before;
        }
    }

    /// The program read under its calls' offset ends (the next begins, or the file): the
    /// findings held for a call whose distance mode is the one it leaves ([`Other`]) are
    /// said where it wrote no G90/G91 (that call's mode is the first's), dropped where it
    /// wrote one.
    pub(super) fn work_call_tentative_end(&mut self) {
        let Some(w) = self.work_call.as_mut().filter(|w| w.held) else {
            return;
        };
        w.held = false;
        let wrote = w.codes_at != self.machine.distance_codes;
        // (what its run leaves for the next call: a G10 or variable write, a shift or frame
        // left on, an end or return elsewhere, a tool length offset or units left, a call
        // not followed: the next call's offsets are not the profile's, review 76 F1)
        let w = &self.offsets_written;
        let changed = self.work_call.as_ref().is_some_and(|c| c.unsure)
            || w.moved
            || w.shifted != 0
            || !w.unread.is_empty()
            || self.shifts_on()
            || self.frames_on()
            || self.transformed.is_some()
            || self.units_unknown
            || self.machine.state.length_offset != 49
            || self.length_decimal
            || self.in_hand.is_none_or(|n| self.after_unsure.contains(&n));
        // (each offset's own writes: a G10 L2 P1 holds nothing of a G55 call, F7)
        let (axes, maybe) = (w.axes, w.maybe);
        // (a units code of its own: the other calls run in the units it leaves, F9)
        self.call_units_rescaled();
        let (mode, other) = (
            super::limits::PENDING_MODE_SELF,
            super::limits::PENDING_OTHER_CALL,
        );
        let others = |m: i64| (other - 5..=other).contains(&m);
        self.found.retain(|f| {
            let held = f.pending_on.iter().find(|&&m| others(m));
            let dropped = held.is_some_and(|&m| {
                let g = (other - m) as usize;
                changed || axes[g] != 0 || maybe[g] != 0
            });
            !(dropped || wrote && f.pending_on.contains(&mode))
        });
        for f in &mut self.found {
            f.pending_on.retain(|&m| m != mode && !others(m));
        }
    }

    /// The program `number` begins, written after calls that name it: where each was made
    /// under the same work offset, with the profile's value of it, in the distance mode in
    /// force here, it runs under that offset, its machine positions judged as the caller's
    /// would be, each finding naming the call (review 59a, F12: `O1000` / `G90 G55` / `M98
    /// P2000` / `M30` / `O2000` / `G0 X-700.` / `M99` was no "X goes to -800", where the
    /// same body written before the main, or inline, was). Only the offset: a G10 before
    /// the call, in the caller's run, leaves it as before.
    #[cold]
    #[inline(never)]
    fn work_of_calls(&mut self, number: i64) {
        let Some(Some(c)) = self.call_works.get(&number) else {
            // (a call of it made where the offset was not known, as in a program read
            // apart: not the offset the program before it in the file left, review 61a F5:
            // `O2000` / `M98 P3000` / `M99` / `O1000` / `G90 G55` ... `M30` / `O3000` / `G0
            // X-760.` was "X goes to -860" under O1000's G55)
            if self.call_works_unknown.contains(&number) {
                self.work = None;
            }
            // (calls that disagree, one of them under another offset than the one the
            // program before left: not that one, review 76-calls76 F6: `G54` / `M98 P2000` /
            // `G54` / `M98 P2000` / `G55` / `M30` / `O2000` / `G0 X-700.` was judged under
            // the G55 the main selected after its calls)
            let seen = self.call_works_seen.get(&number).copied().unwrap_or(0);
            let left = self.work.map_or(0, |w| 1u8 << (w - 54).clamp(0, 7));
            if seen & !left != 0 {
                self.work = None;
            }
            return;
        };
        if c.incremental != self.machine.state.incremental
            || self.shifts_on()
            || self.frames_on()
            || self.transformed.is_some()
            || self.units_unknown
        {
            return;
        }
        let w = WorkCall {
            work: c.work,
            call: c.call.clone(),
            line: c.line,
            work_before: self.work,
            lost_before: self.offsets_lost,
            outside_before: self.outside,
            length_before: (self.machine.state.length_offset, self.length_decimal),
            others: c.others.clone(),
            codes_at: self.machine.distance_codes,
            held: false,
            unsure: false,
            units_codes_at: self.machine.units_codes,
            units_at: self.machine.state.units,
            rescale: Vec::new(),
            units_cut: false,
        };
        self.offsets_written = c.written.clone();
        self.work = Some(w.work);
        self.offsets_lost = false;
        // (the caller's excursion runs on into it: one excursion, one finding, review 61a F3)
        self.outside = c.outside;
        // (and its tool length offset: G43/G44 are modal and the call changes none; a Z
        // under it is not compared, as the same body inline, review 61a F1: `G43 H1 Z0` /
        // `M98 P2000` / `M30` / `O2000` / `G0 Z-515.` was a "Z goes to -515")
        (self.machine.state.length_offset, self.length_decimal) = c.length;
        self.work_call = Some(Box::new(w));
    }

    /// The program numbers a call by number (M98, G65, G66) or from an external device
    /// (M198) may name, whatever the control's program-number option: its P, and its last
    /// four digits (a FANUC without the 8-digit option reads `M98 P12000` as O2000 once, the
    /// digits above four being the repeat count: 0i-F Operator's Manual, "Subprogram call
    /// (M98)"). A program of the file among them is not judged as one no call names
    /// ([`Checker::early_finish`]; review 56b, F1); an M198 whose P is not known may name
    /// any.
    fn call_numbers_seen(&mut self, b: &BlockView<'_>, by_number: bool) {
        if !by_number && !self.values.ms.contains(&198) {
            return;
        }
        let p = b
            .words
            .iter()
            .enumerate()
            .find(|(_, w)| w.letter == b'P' && w.index.is_empty())
            .map(|(i, _)| self.readable[i]);
        match p {
            Some(Some(v)) if v.is_whole() => {
                let n = v.trunc();
                self.call_numbers.extend([n, n % 10_000]);
                let caller = self.in_hand;
                self.call_sites.extend([(caller, n), (caller, n % 10_000)]);
            }
            // (M98 P#1: every program after it is read in units not known, call_unknown)
            _ if !by_number => self.call_numbers_any = true,
            _ => {}
        }
    }

    /// The next program of the file begins with `b`'s O number: where a call before it in
    /// the file names that number, it is a subprogram and runs in the units of its calls, not
    /// in the reset state's (a FANUC's or a Haas's M98 runs the subprogram in the caller's
    /// modal state; G20/G21 are modal and the call changes none: Haas Mill Operator's Manual,
    /// M98 and G20/G21; review 38, finding 10). Calls in different units, or one in units
    /// not known, leave them unknown: no TG601/TG602 until the subprogram writes a units code
    /// of its own. A program no call before it names is read from the reset state, as the
    /// file's first is (a program of its own, whose units until it writes one are the
    /// control's start units the profile assumes).
    pub(super) fn called_units(&mut self, b: &BlockView<'_>) {
        self.work_call_end();
        if self.later_shift.is_some() {
            self.later_shift_closed();
        }
        self.offsets_unread_only = false;
        // (an excursion beyond the travel is one run's: the program before's last position
        // outside holds no first one of this program's, review 59a F9: `G90 G55` / `G0 X-700.`
        // / `M30` / `O2000` / `G90 G55` / `G0 X-700.` said only the first) -- but with the
        // block skip switch on, the program before runs on into it
        if !self.end_skippable {
            self.outside = [0; 9];
        }
        self.units_unknown = false;
        // (the program before, if read apart and not ended: read as before)
        self.early_merge_as(true);
        // (its calls in units only assumed: a program not ended runs on, the reset state's)
        if !self.call_works_assumed.is_empty() {
            self.call_works_ended(false);
        }
        if self.units_merged.is_some() || self.guess_marked.is_some() {
            self.units_merged_ended(false);
        }
        // (a run of its own: what the program before wrote is not this one's caller's; but
        // with the block skip switch on, the program before runs on into it: that run's)
        if !self.end_skippable {
            self.offsets_written = Default::default();
            self.linuxcnc_pending = None;
            self.g10_expression = 0;
            self.g10_local = 0;
        }
        self.shifts.calls = super::limits::CallShifts::None;
        let number = b
            .words
            .first()
            .filter(|w| w.letter == b'O' && w.index.is_empty() && w.expression.is_empty())
            .and_then(|w| std::str::from_utf8(w.number).ok())
            .and_then(|n| n.parse::<i64>().ok());
        self.file_programs.extend(number);
        self.in_hand = number;
        if !self.call_works_deferred.is_empty() {
            self.call_works_resolved(number);
        }
        // a program no call before it names may be the subprogram of a call after it (a
        // memory backup lists programs by number): read apart until it shows what it is
        // (crate::check::called; review 39, finding 4)
        // (after a call whose number is not known, any program may be the one it runs: its
        // units and shift not known, review 41, finding 5)
        if self.unknown_call.is_some() {
            self.units_unknown = true;
            self.machine.state.units_given = false;
            return;
        }
        if let Some(n) = number.filter(|n| !self.call_units.contains_key(n)) {
            if self.config.family == Family::MacroB {
                // (from the reset state: no G52 the program before left on, review 59a F3)
                if !self.end_skippable && self.shifts_on() {
                    self.shifts_reset();
                }
                // (its caller, not the program before it, selects the work offset it runs
                // under: not known until it writes its own G54-G59; review 56e, F6) -- unless
                // the end before it is under the `/` switch: with the switch on, the program
                // before runs on into it under its own offset (review 57c, F2)
                self.early_begin(
                    super::called::Key::Number(n),
                    b.words[0].token(),
                    (b.line, b.words[0].column),
                );
                if !self.end_skippable {
                    self.work_offset_unknown(b.line);
                } else {
                    self.work_run_on = self.early_on && self.work.is_some();
                }
            }
        }
        self.shift_clean_start = !self.shifts_on();
        match number.and_then(|n| self.call_units.get(&n)) {
            Some(&Some((units, feed_units, given))) => {
                let s = &mut self.machine.state;
                (s.units, s.feed_units, s.units_given) = (units, feed_units, given);
            }
            Some(None) => {
                self.units_unknown = true;
                self.machine.state.units_given = false;
            }
            None => self.machine.state.units_given = false,
        }
        if let Some(n) = number.filter(|n| self.call_works.contains_key(n)) {
            if self.config.family == Family::MacroB && !self.end_skippable {
                self.work_of_calls(n);
            }
        }
    }

    /// [`Checker::program_number`] of the file's first block of words: where it begins with
    /// an O number, its program is read apart from the start (crate::check::called).
    #[cold]
    #[inline(never)]
    fn first_program(&mut self, b: &BlockView<'_>) {
        if !dialect::splits(self.config.family, self.config.program_number) {
            return;
        }
        let number = b
            .words
            .first()
            .filter(|w| w.letter == b'O' && w.index.is_empty() && w.expression.is_empty())
            .and_then(|w| {
                let n = std::str::from_utf8(w.number).ok()?.parse::<i64>().ok()?;
                Some((n, w.token(), w.column))
            });
        if let Some((n, name, column)) = number {
            self.file_programs.insert(n);
            (self.first_number, self.in_hand) = (Some(n), Some(n));
            self.early_begin(super::called::Key::Number(n), name, (b.line, column));
        }
    }

    /// After a block's state is applied, where the units are not known or a program is read
    /// apart ([`Checker::early_merge`]): a units code the block wrote makes them known, and a
    /// program read apart that writes its own units is read as before.
    #[cold]
    #[inline(never)]
    pub(super) fn units_given_now(&mut self) {
        if self.machine.state.units_given {
            if self.units_unknown {
                self.units_known_again();
            }
            self.units_merged_from();
            self.early_merge();
        }
    }

    /// A subprogram whose units were not known has written a units code: its lengths are
    /// known from here. The axes the block does not write stand where lengths in unknown
    /// units put them: not known.
    pub(super) fn units_known_again(&mut self) {
        self.units_unknown = false;
        for &axis in crate::modal::AXES {
            if !self.values.has(axis) {
                self.machine.forget_axis(axis);
            }
        }
    }

    /// TG109: a SINUMERIK `DEF` after the first block of its program's program section
    /// (`dialect::sinumerik_section`); a `PROC` opens a subprogram's definition section.
    pub(super) fn definition_section(&mut self, b: &BlockView<'_>) {
        if dialect::defines_subprogram(self.config.family, b.statements) {
            self.program_section = None;
            return;
        }
        match dialect::sinumerik_section(self.config.family, b.words, b.statements) {
            Some(Some(column)) => {
                if let Some(first) = self.program_section {
                    let message = format!(
                        "DEF after the program section began (line {first}): a SINUMERIK \
                         program defines its variables in the definition section at its head, \
                         before its first block of words or instructions (Programming Manual \
                         Job Planning, DEF)"
                    );
                    self.report(Rule::DefinitionAfterProgram, message, b.line, column);
                }
            }
            Some(None) => {
                self.program_section.get_or_insert(b.line);
            }
            None => {}
        }
    }

    /// LinuxCNC: a binary operation outside `[ ]` after a value in an assignment (`#1=#2*3`,
    /// `#<b>=#<a>*2`): rs274ngc reads one only inside `[ ]`, and its read_items stops at the
    /// operator, "Bad character '*' used" (compared with rs274 -g; review 20, finding 1). In an
    /// address's value (`X#2+1`, `X#1*2`) the line's reading refuses the operator first, at the
    /// same column (TG100, TG101, TG123; review 21, finding 3), and no second finding is made.
    /// An indexed word of another letter (SINUMERIK's `R7=R5-R4`) stops it earlier, at its
    /// `=`: "Bad character '=' used" (a LinuxCNC word has no index).
    ///
    /// The line's form is refused whenever rs274 runs the line, as the other forms it refuses
    /// (G10 L50, an E word no code uses): judged wherever the line may run, in a condition, a
    /// loop or a definition's body too (review 21, finding 1; the check does not evaluate an
    /// o-word condition, so the line of an `o1 if [0]` branch is judged as well), its message
    /// then saying it is refused when it runs. The main program's lines after its end are
    /// never read (TG117).
    fn linuxcnc_bare_operator(&mut self, b: &BlockView<'_>, walks: &[ExpressionWalk; WALKED]) {
        if self.open_definition.is_none() && self.linuxcnc_dead() {
            return;
        }
        for (i, w) in b.words.iter().enumerate() {
            if w.expression.is_empty() {
                continue;
            }
            // a letter and one plain pair of brackets (`Y[#<yscale>*-3.608]`) has no
            // operation outside them: `bare_operator` goes from the letter to the matching `]`, the
            // token's last byte (the expression is the token's tail: one byte shorter, the
            // same end)
            if walks.get(i).is_some_and(|k| k.plain)
                && w.token.len() == w.expression.len() + 1
                && w.token.as_ptr_range().end == w.expression.as_ptr_range().end
                && w.token[0].is_ascii_alphabetic()
            {
                debug_assert_eq!(crate::between::bare_operator(w.token), None);
                continue;
            }
            let Some(at) = crate::between::bare_operator(w.token) else {
                continue;
            };
            let op = w.token[at];
            if !matches!(op, b'*' | b'/' | b'+' | b'-') {
                continue; // (a name after a value: the tokenizer's TG100)
            }
            // an indexed word of a letter (`R7=`): rs274 reads R7, then stops at the `=`
            let index_equals = (w.letter != b'#' && !w.index.is_empty())
                .then(|| 1 + w.index.len())
                .filter(|&i| w.token.get(i) == Some(&b'='));
            let at = index_equals.unwrap_or(at);
            // the column of the token's byte `at`: the token's bytes are the line's without
            // its blanks
            let start = w.column.saturating_sub(1);
            let mut left = at;
            let mut offset = start;
            for (i, c) in b.text.iter().enumerate().skip(start) {
                offset = i;
                if *c == b' ' || *c == b'\t' {
                    continue;
                }
                if left == 0 {
                    break;
                }
                left -= 1;
            }
            let token = String::from_utf8_lossy(w.token);
            let mut message = if index_equals.is_some() {
                format!(
                    "Bad character '=' used (rs274ngc): {token} is no LinuxCNC word; rs274 \
                     reads {} and stops at the '=' (LinuxCNC assigns a value to a parameter \
                     alone, #n= or #<name>=, and reads a binary operation only inside [ ])",
                    String::from_utf8_lossy(&w.token[..at]),
                )
            } else {
                // what stands before the value: `#1=`, `#<b>=` (an assignment's parameter,
                // to its `=`), or the word's letter
                let head = if w.letter == b'#' {
                    let equals = w.token.iter().position(|&c| c == b'=');
                    &w.token[..equals.map_or(0, |e| e + 1)]
                } else {
                    &w.token[..w.token.len() - w.expression.len()]
                };
                format!(
                    "Bad character '{}' used (rs274ngc): {token} has '{}' after a value \
                     outside [ ]; LinuxCNC reads a binary operation only inside [ ] (write \
                     {}[...])",
                    op as char,
                    op as char,
                    String::from_utf8_lossy(head),
                )
            };
            if !self.linuxcnc_runs_surely() {
                message.push_str(
                    "; the line stands in an o-word condition, loop or subroutine body, and \
                     rs274 refuses it when it runs it",
                );
            }
            self.report(
                Rule::LinuxCncRefuses,
                message,
                b.line,
                column(b.text, offset),
            );
            return; // (rs274 stops at the first)
        }
    }

    /// LinuxCNC: a file holding one subroutine definition, `o<name> sub` ... `o<name>
    /// endsub`, optionally followed by M2 (LinuxCNC's O codes, "Calling Files": `o<name>
    /// call` runs the file of that name, which holds the definition), returns to its caller
    /// and needs no M2 (no TG114). Anything else after the endsub makes it a program again.
    ///
    /// Returns whether the line is one of the main program rs274 never runs, no o-word line
    /// ([`Checker::linuxcnc_dead`]): in the skip of a block known not to run, or after the
    /// program's end -- an M2/M30 in a block known to run, the rest of a branch after its
    /// M2. rs274 reads it for its o-word only, or not at all, and runs nothing of it, so no
    /// rule judges it and it changes no state, as after an M2 at the top (review 51, F4;
    /// review 52, F8). A definition's body is read as one wherever it stands.
    #[inline(always)]
    pub(super) fn subroutine_file(&mut self, b: &BlockView<'_>) -> bool {
        if self.config.family != Family::LinuxCnc {
            return false;
        }
        // a block without a statement, outside any definition, in a file that is no
        // subroutine file, after no M2/M30 inside a condition and with no spindle speed
        // followed through a condition (most of a CAM program's blocks): what the full
        // reading below does with such a block, and no more
        // (`linuxcnc_quiet`: the full reading below is the one place that changes those, the
        // end's depth aside)
        debug_assert!(!self.linuxcnc_quiet || self.linuxcnc_quiet_now());
        if b.statements.is_empty() && self.linuxcnc_quiet && self.linuxcnc_end_depth.is_none() {
            // (a line of plain words: it has an expression where the tokenizer walked a
            // bracketed word, all of them or not)
            let walks = &self.line_walks;
            let line = self.line_walks_of == (b.text.as_ptr() as usize, b.text.len());
            let expressions = if line && walks.all {
                walks.set != 0
            } else {
                b.words.iter().any(|w| !w.expression.is_empty())
            };
            debug_assert_eq!(
                expressions,
                b.words.iter().any(|w| !w.expression.is_empty()),
                "line {}",
                b.line
            );
            // (and a block of neither words nor statements, which the full reading passes
            // over: the count kept is no other block's)
            if !expressions {
                self.linuxcnc_no_slash = self.stats.blocks;
                return false;
            }
            if self.linuxcnc_line_walked(b) {
                self.linuxcnc_no_slash = self.stats.blocks;
                if self.surely_ended || self.linuxcnc_names_all_seen(b) {
                    return false;
                }
                let walks = self.linuxcnc_walk_words(b);
                self.linuxcnc_named_reads(b, self.linuxcnc_open_flow.is_empty(), &walks);
                return false;
            }
        }
        if self.surely_ended {
            // (the lines after a FANUC-style body closed at an M99 that does not run)
            if self.linuxcnc_later_bodies.ran_on.is_some() {
                self.later_tail_line(b);
            }
            // (an M2/M30 of a FANUC-style program's body outside its blocks on the line
            // before: the program ends there, no line after it runs; closed before this line)
            if let Some(line) = self.linuxcnc_fanuc_close.take() {
                if let Some(open) = &self.open_definition {
                    let mut text = open.2.clone();
                    text.extend_from_slice(b" endsub");
                    self.linuxcnc_fanuc_open = false;
                    let view = BlockView { line, ..*b };
                    self.linuxcnc_fanuc_program(&view, &text);
                }
            }
            if b.statements.is_empty() && !b.words.is_empty() {
                if let Some(text) = self.linuxcnc_fanuc_line(b) {
                    self.linuxcnc_fanuc_program(b, &text);
                    return true;
                }
                if self.linuxcnc_fanuc_open && self.linuxcnc_fanuc_ends(b) {
                    self.linuxcnc_fanuc_close = Some(b.line);
                }
            }
        }
        if b.words.is_empty() && b.statements.is_empty() {
            return false;
        }
        self.subroutine_file_read(b);
        b.statements.is_empty() && self.open_definition.is_none() && self.linuxcnc_dead()
    }

    /// LinuxCNC 2.9: after the main program's end, a FANUC-style program, a bare O number
    /// (`O300`, alone on its line but for a comment) up to an `M99` alone on its line, is
    /// the body an `M98 P300` runs: rs274 seeks its O number as it seeks an `o300 sub` and
    /// returns at its M99 (interp_read.cc `read_o`, bare O-word and "m99"; interp_o_word.cc
    /// `convert_control_functions`, `O_` and `M_99`). The line's statement as the o-word
    /// form's (`o300 sub`, `o300 endsub`), where it is one ([`Checker::linuxcnc_fanuc_program`]).
    #[cold]
    #[inline(never)]
    fn linuxcnc_fanuc_line(&mut self, b: &BlockView<'_>) -> Option<Vec<u8>> {
        let mut words = b.words.iter().filter(|w| w.letter != b'N');
        let (Some(w), None) = (words.next(), words.next()) else {
            return None;
        };
        if b.skip || !w.index.is_empty() || !w.expression.is_empty() {
            return None;
        }
        let number = std::str::from_utf8(w.number).ok()?;
        if w.letter == b'O' && self.open_definition.is_none() && !number.contains('.') {
            // (one no M98 before it names is never read: rs274 stops at the main program's
            // end, and only a call seeks a program after it)
            let n: i64 = number.parse().ok()?;
            // (nor a second program of a number after the end: the call runs the first)
            let label = format!("o{n}").into_bytes();
            // (an `o300 call` of the main program reaches it too, and is refused there:
            // Checker::linuxcnc_call_forms)
            let called = self.linuxcnc_m98_numbers.contains(&n)
                || self.linuxcnc_later.ends.iter().any(|c| c.0 == label);
            if !called || self.linuxcnc_defs_after.contains(&label) {
                self.later_program_passed(n, b.line);
                return None;
            }
            self.linuxcnc_fanuc_open = true;
            return Some(format!("o{n} sub").into_bytes());
        }
        if w.letter == b'M' && self.linuxcnc_fanuc_open && number.parse::<i64>().ok()? == 99 {
            let open = &self.open_definition.as_ref()?.2;
            let mut text = open.clone();
            text.extend_from_slice(b" endsub");
            self.linuxcnc_fanuc_open = false;
            return Some(text);
        }
        None
    }

    /// LinuxCNC 2.9 refuses a call of one form that reaches a definition of the other, where
    /// the main program's call surely runs (interp_o_word.cc `convert_control_functions`):
    /// `M98 P300` reaching `o300 sub` ("'O.... sub' subroutine must be called with 'O....
    /// call'"), `o300 call` reaching `O300` ("Fanuc 'O....' subroutine must be called with
    /// 'M98'"), and an `O300` program closed by `o300 endsub` ("Fanuc 'O....' subroutine
    /// definition must end with 'M99'"), each at the definition's line (`rs274 -g`). Asked
    /// where a definition after the main program's end opens or closes (`was_open`).
    #[cold]
    #[inline(never)]
    fn linuxcnc_call_forms(&mut self, b: &BlockView<'_>, was_open: bool) {
        let label = match (&self.open_definition, was_open) {
            (Some(open), false) => open.2.clone(),
            (None, true) => match dialect::subroutine_statement(b.statements) {
                Some((false, label)) => label,
                _ => return,
            },
            _ => return,
        };
        // (a call reaches the first line of its label after it: a later definition of the
        // same label is not the one it runs; review 78-lcnc78 F3)
        if !was_open {
            self.linuxcnc_def_first = !self.linuxcnc_defs_after.contains(&label);
            self.linuxcnc_defs_after.push(label.clone());
        }
        if !self.linuxcnc_def_first {
            self.linuxcnc_fanuc_open &= !was_open;
            return;
        }
        let m98s = &self.linuxcnc_m98_calls;
        let m98 = m98s.iter().find(|c| c.0 == label).map(|c| c.1);
        let called = self
            .linuxcnc_later
            .ends
            .iter()
            .find(|c| c.0 == label && !m98s.contains(c))
            .map(|c| c.1);
        let fanuc = self.linuxcnc_fanuc_open;
        let shown = String::from_utf8_lossy(&label[1..]).into_owned();
        let message = match (was_open, fanuc, m98, called) {
            (false, false, Some(line), _) => format!(
                "'O.... sub' subroutine must be called with 'O.... call' (rs274ngc): the M98 \
                 P{shown} on line {line} reaches o{shown} sub, a definition of the o-word form, \
                 which rs274 2.9 runs only for an o{shown} call"
            ),
            (false, true, _, Some(line)) => format!(
                "Fanuc 'O....' subroutine must be called with 'M98' (rs274ngc): the o{shown} \
                 call on line {line} reaches the FANUC-style program O{shown}, which rs274 2.9 \
                 runs only for an M98 P{shown}"
            ),
            // (rs274 stopped at a refusal inside the body before its close: said once,
            // there; Checker::fanuc_body_refused)
            (true, true, Some(_), _)
                if self.linuxcnc_later_bodies.refused.as_ref() == Some(&label) =>
            {
                self.linuxcnc_fanuc_open = false;
                return;
            }
            (true, true, Some(line), _) => {
                self.linuxcnc_fanuc_open = false;
                format!(
                    "Fanuc 'O....' subroutine definition must end with 'M99' (rs274ngc): the \
                     FANUC-style program O{shown} that the M98 P{shown} on line {line} runs is \
                     closed by an o-word endsub, which rs274 2.9 refuses"
                )
            }
            _ => {
                self.linuxcnc_fanuc_open &= !was_open;
                return;
            }
        };
        let column = b.statements.first().map_or(1, |s| s.0);
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
    }

    /// LinuxCNC: an M2 or M30 of a FANUC-style program's body after the main program's end,
    /// outside the body's blocks: a call ends the program there, and no line after it up to
    /// the M99 runs.
    fn linuxcnc_fanuc_ends(&self, b: &BlockView<'_>) -> bool {
        !b.skip
            && self.linuxcnc_definition_flow.is_empty()
            && b.words.iter().any(|w| {
                w.letter == b'M'
                    && w.expression.is_empty()
                    && matches!(
                        std::str::from_utf8(w.number).map(str::parse::<i64>),
                        Ok(Ok(2 | 30))
                    )
            })
    }

    /// LinuxCNC: a FANUC-style program's O number or M99 line after the main program's end
    /// ([`Checker::linuxcnc_fanuc_line`]) read as the o-word form's `sub` or `endsub` line
    /// (`text`): the same reading of its body, of the main program's calls of it made before
    /// (its `M98`, [`Checker::linuxcnc_m98_later`]) and of the moves held after them.
    #[cold]
    #[inline(never)]
    fn linuxcnc_fanuc_program(&mut self, b: &BlockView<'_>, text: &[u8]) {
        let column = b.words.first().map_or(1, |w| w.column);
        let statements = [(column, Kind::Definition, text)];
        let view = BlockView {
            words: &[],
            statements: &statements,
            ..*b
        };
        self.letters = 0;
        self.plain_block = false;
        // (no SINUMERIK definition section here: `definition_section` keeps its one call,
        // inlined in `read_block`)
        if !self.subroutine_file(&view) {
            self.statements_only_block(&view);
        }
    }

    /// The file is no subroutine file, no definition is open, and no spindle speed is
    /// followed through a condition ([`Checker::linuxcnc_if_speed`]): the short path of
    /// [`Checker::subroutine_file`] may be taken (where no M2/M30 inside a condition came
    /// before, too), and no skip of a block known not to run is on, nor the program ended
    /// (its lines after the end, in a block, are dead: [`Checker::subroutine_file`]).
    fn linuxcnc_quiet_now(&self) -> bool {
        self.sub_file == SubFile::No
            && self.linuxcnc_skipping.is_none()
            && !self.surely_ended
            && self.open_definition.is_none()
            && self.linuxcnc_speed_back.is_none()
            && self.linuxcnc_if_speed.is_empty()
    }

    /// [`Checker::subroutine_file`] of any LinuxCNC block, and `linuxcnc_quiet` after it.
    #[inline(never)]
    fn subroutine_file_read(&mut self, b: &BlockView<'_>) {
        self.subroutine_file_body(b);
        self.linuxcnc_quiet = self.linuxcnc_quiet_now();
    }

    /// [`Checker::subroutine_file_read`].
    fn subroutine_file_body(&mut self, b: &BlockView<'_>) {
        // (a block of plain words, as most of a CAM program's are, has nothing to walk)
        let expressions = b.words.iter().any(|w| !w.expression.is_empty());
        // a line whose every bracketed word the tokenizer walked plain (a CAM program's
        // `Y[#<yscale>*-3.608]Z[#<zscale>*-8.942]`): its walks read where they are, no
        // operation outside a bracket to look for, and its names asked of the names seen
        let whole = expressions && self.linuxcnc_line_walked(b);
        if !expressions || whole {
            self.linuxcnc_no_slash = self.stats.blocks;
        }
        let walked = (expressions && !whole).then(|| {
            let walked = self.linuxcnc_walk_words(b);
            self.linuxcnc_bare_operator(b, &walked);
            walked
        });
        self.linuxcnc_if_speed(b);
        // (a block without a statement, most of a program's, opens, closes and calls no
        // definition: only a definition's body has its words to mark)
        let statement = if b.statements.is_empty() {
            if self.open_definition.is_some() {
                if self.linuxcnc_later_bodies.sure.is_some() {
                    self.later_body_line(b);
                }
                self.linuxcnc_body(b, None);
                self.bare_o_in_definition(b);
                self.linuxcnc_body_locals(b, None);
            }
            None
        } else {
            let statement = dialect::subroutine_statement(b.statements)
                .map(|(opens, label)| self.linuxcnc_definition_label(b, opens, label));
            self.linuxcnc_body_locals(b, statement.as_ref());
            self.definition_after_call(b, statement.as_ref());
            self.definition_feed(statement.as_ref());
            let was_open = self.open_definition.is_some();
            if was_open && self.linuxcnc_later_bodies.sure.is_some() {
                self.later_body_line(b);
            }
            self.definition_open(b, statement.as_ref());
            if was_open != self.open_definition.is_some() && self.surely_ended {
                self.linuxcnc_call_forms(b, was_open);
                match &self.open_definition {
                    Some(open) if !was_open => {
                        let label = open.2.clone();
                        self.later_body_opened(&label, self.linuxcnc_fanuc_open, b.line);
                    }
                    _ => self.later_body_closed(),
                }
            }
            self.linuxcnc_definition_plane(was_open);
            self.linuxcnc_body(b, statement.as_ref());
            if was_open && self.open_definition.is_none() && !self.linuxcnc_later.ends.is_empty() {
                self.linuxcnc_later_ends();
            }
            if self.open_definition.is_none() && b.statements.iter().any(|s| s.1 == Kind::Call) {
                self.later_main_call(b.line);
            }
            self.linuxcnc_called(b, statement.as_ref(), was_open);
            statement
        };
        if statement.is_none()
            && self.open_definition.is_none()
            && !self.main_ended()
            && (!b.statements.is_empty() || expressions)
        {
            // (inside a condition or loop its assignments count as made, its reads are not
            // judged)
            if !whole || !self.linuxcnc_names_all_seen(b) {
                let again;
                let walks = match &walked {
                    Some(walked) => walked,
                    None if whole => {
                        again = self.linuxcnc_walk_words(b);
                        &again
                    }
                    None => &NOT_WALKED,
                };
                self.linuxcnc_named_reads(b, self.linuxcnc_open_flow.is_empty(), walks);
            }
        }
        // (the condition's own reads run, judged above; the lines inside it may not)
        let main = self.open_definition.is_none();
        let mut ends_here = false;
        // (before a call's own line marks the block's lines as not surely run)
        let main_depth = self.linuxcnc_distance_depth();
        for &(column, kind, text) in b.statements {
            // (an o-word after a comment or a word is none to rs274: it opens and closes
            // nothing, and stops the program where the line runs)
            if self.linuxcnc_o_misplaced(b, column) && kind == Kind::Flow {
                continue;
            }
            if kind == Kind::Flow && main {
                self.linuxcnc_undefined_label(b, text, column);
                self.linuxcnc_loop_exit(b, text, column);
            }
            // a call that surely runs of a subroutine defined before it whose body surely
            // ends the program (`o<s> sub` / `M2` / `o<s> endsub` ... `o<s> call`): the main
            // program ends there, as rs274 reads no line after it (review 48, c19)
            ends_here |= kind == Kind::Call
                && main
                && !b.skip
                && self.linuxcnc_runs_surely()
                && !self.main_ended()
                && self.linuxcnc_call_ends(text);
            if kind == Kind::Call && main {
                self.linuxcnc_still_call(b, text);
                // (the body may set the coolant or the overrides)
                self.linuxcnc_extras = RestoreExtras::UNKNOWN;
            }
            let label = self.linuxcnc_call_label(text);
            // (the skip of a block known not to run ends at an o-word line of its label; one
            // whose label is worked out as the line runs, from values a line skipped may have
            // set here, or a definition, may end it too)
            // (a call the skip passes over never runs: it does not end the skip, review 51,
            // F4; an `else` or `elseif` after a branch that ran does not either)
            // (the skip of a branch known not to run that its label's line ends: the branch
            // this line begins runs where the blocks around it do, Checker::linuxcnc_branch)
            // (a definition in the skip is read as one, the skip held to its endsub: rs274
            // skips it, and the lines after it to the skip's end, review 52, F7)
            let mut skip_ended = false;
            if let Some(s) = &self.linuxcnc_skipping {
                skip_ended = s.0 == label && !s.2;
                if kind == Kind::Definition && self.open_definition.is_some() {
                    self.linuxcnc_skip_held = self.linuxcnc_skipping.take();
                    skip_ended = false;
                } else if skip_ended
                    || s.0 == label
                        && crate::statement::o_keyword(text).as_deref() == Some(b"endif".as_slice())
                    || kind == Kind::Definition
                    || crate::statement::computed_label(&crate::statement::o_label(text))
                {
                    self.linuxcnc_skipping = None;
                }
            } else if kind == Kind::Definition && self.open_definition.is_none() {
                if let Some(held) = self.linuxcnc_skip_held.take() {
                    self.linuxcnc_skipping = Some(held);
                }
            }
            let named = &mut self.linuxcnc_labels_named;
            if crate::statement::computed_label(&label) {
                named.1 = true;
            } else if !named.1 {
                named.0.insert(bare_label(&label));
            }
            if kind == Kind::Call && main && self.linuxcnc_loop_defs.is_some() {
                self.linuxcnc_loop_call(text);
            }
            if kind == Kind::Call && main && !self.linuxcnc_open_flow.is_empty() {
                self.may_call_seen();
                // (a call may set any parameter, or end the program: F10's first run ends)
                // (inside a loop a later turn may take another branch: not kept there, as
                // before, so `o1 if [#<k> EQ 0]` / call / `o1 else` in a while is judged)
                let looped = self.linuxcnc_open_at.iter().any(|e| e.looped.is_some());
                for e in &mut self.linuxcnc_open_at {
                    if e.runs == Some(true) {
                        e.runs = None;
                        e.called = !looped;
                    }
                    e.straight &= e.runs == Some(false);
                }
                self.linuxcnc_flow_assigned.push((b.line, Vec::new()));
            }
            if kind == Kind::Call
                && if main {
                    !self.linuxcnc_dead()
                } else {
                    !self.linuxcnc_body_distance.returned
                }
            {
                self.linuxcnc_call_distance(text, b.line, main_depth);
            }
            match (kind, main) {
                (Kind::Flow, true) => {
                    let top = self.linuxcnc_open_flow.is_empty();
                    // (whether the lines of the one block open ran up to this one)
                    let ran = !b.skip
                        && matches!(self.linuxcnc_open_at.as_slice(), [e] if e.runs == Some(true));
                    let step = self.linuxcnc_main_flow(text, (b.line, column), skip_ended);
                    if self.linuxcnc_open_flow.is_empty() && self.linuxcnc_may.is_some() {
                        self.may_closed();
                    }
                    self.flow_reads(text);
                    if top || self.linuxcnc_loop_defs.is_some() {
                        self.linuxcnc_loop_turns(text, top, ran);
                    }
                    if b.skip || self.linuxcnc_skipping.is_some() {
                    } else if step.dead {
                        self.linuxcnc_skipping = Some((label, b.line, false));
                    } else if step.other_branch {
                        self.linuxcnc_skipping = Some((label, b.line, true));
                    } else if !top && self.linuxcnc_nested_dead(text, b.line) {
                        self.linuxcnc_skipping = Some((label, b.line, false));
                    } else if !top {
                        self.linuxcnc_loop_leave(text, &label, b.line);
                    }
                }
                (Kind::Flow, false) => {
                    let flow = &mut self.linuxcnc_definition_flow;
                    let label = crate::statement::o_label(text);
                    let switched = linuxcnc_branch_switch(flow, text, &label);
                    let loop_at = flow.iter().rposition(|l| *l == label);
                    let depth = flow.len();
                    linuxcnc_flow(flow, text);
                    let open = flow.len();
                    let opened = &mut self.linuxcnc_definition_opened;
                    if open > depth {
                        opened.push((b.line, text.to_vec(), None));
                    } else {
                        opened.truncate(open);
                        // (an `else` or `elseif` of the innermost: its branches switched)
                        if let Some(last) = opened.last_mut().filter(|_| switched.is_some()) {
                            if crate::statement::o_label(&last.1) == label {
                                last.2 = Some(text.to_vec());
                            }
                        }
                    }
                    self.linuxcnc_body_distance.scope(open, switched);
                    // (a body's conditions are not evaluated: which branch runs, not known)
                    let mut blocks = std::mem::take(&mut self.linuxcnc_plane_body_blocks);
                    let keyword = crate::statement::o_keyword(text);
                    self.linuxcnc_body_do(keyword.as_deref(), &label, b.line);
                    let step = PlaneStep {
                        depth,
                        open,
                        switched,
                        is_else: keyword.as_deref() == Some(b"else".as_slice()),
                        main: false,
                        ran: None,
                        taken: false,
                        leaves: matches!(keyword.as_deref(), Some(b"break" | b"continue")),
                        loop_at,
                    };
                    self.linuxcnc_plane_flow(&mut blocks, step);
                    self.linuxcnc_plane_body_blocks = blocks;
                }
                // the subroutine may set another feed mode, or restore the caller's
                (Kind::Call, true) if !self.linuxcnc_call_keeps_mode(text) => {
                    self.linuxcnc_mode_unsure = true
                }
                _ => {}
            }
            // (a call in a condition or loop: an M70 of a later turn may save what it set)
            if kind == Kind::Call && main && !self.linuxcnc_open_flow.is_empty() {
                self.linuxcnc_feed_loose = self.linuxcnc_feed_loose.map(|_| LooseSaved::UNKNOWN);
            }
            if kind == Kind::Call && !main {
                self.linuxcnc_definition_mode_unsure = true;
            }
        }
        self.surely_ended |= ends_here;
        if ends_here && self.linuxcnc_call_ended_at == 0 {
            self.linuxcnc_call_ended_at = b.line;
        }
        // (the block of a conditional M2/M30 closed: the lines after run where it did not)
        if self
            .linuxcnc_end_depth
            .is_some_and(|d| self.linuxcnc_open_flow.len() < d)
        {
            self.linuxcnc_end_depth = None;
        }
        if self.sub_file == SubFile::No {
            // lines before the file's first statement, and that an `o<name> sub` (issue 32,
            // audit 37 I, 3): a subroutine file all the same, whose lines before the sub a
            // call never runs (rs274ngc `control_back_to` skips to the sub; TG117 said at the
            // file's end, where it is still one)
            match statement {
                Some((true, _))
                    if self.sub_preamble.0 != 0
                        && self.sub_preamble.1 == 0
                        && self.ended_line == 0 =>
                {
                    self.sub_preamble.1 = b.line;
                    self.sub_file = SubFile::Unknown;
                }
                _ => {
                    if !b.statements.is_empty() {
                        self.sub_preamble = (0, 0);
                    }
                    return;
                }
            }
        }
        // an endsub closes the definition only if it names it (rs274 reads `o<j> sub` ...
        // `o<k> endsub` as a definition never closed); in a subroutine file, called, rs274
        // returns at any endsub it runs, whatever its label (interp_read.cc `read_o` compares
        // the label only while it skips; issue 32, audit 37 I, 1 and 2): one inside a
        // condition or loop of the body returns early and closes nothing, one of another
        // label outside them is the file's return if nothing but M2/M30 follows (TG138)
        let inside = self.sub_file == SubFile::Open && !self.linuxcnc_definition_flow.is_empty();
        // (the endsub of a definition nested in the body, `o1000 sub` ... `o1000 endsub`, is
        // left as it was: rs274 2.9 runs such a body inline when called and returns at its
        // endsub, master refuses it, "Nested subroutine definition")
        let nested = |name: &[u8]| self.linuxcnc_bodies.iter().any(|e| e.0 == name);
        let definition = match statement {
            Some((false, name))
                if self.sub_file == SubFile::Open && name != self.sub_label && !nested(&name) =>
            {
                self.endsub_named_otherwise(b, &name);
                self.sub_returns.2 = if inside { 0 } else { b.line };
                self.sub_returned |= !inside;
                None
            }
            Some((false, _)) if inside => {
                if self.sub_returns.0 == 0 {
                    self.sub_returns.0 = b.line;
                    self.sub_returns.1 = b.statements.first().map_or(1, |s| s.0);
                    self.sub_left_open = self.block_left_open(b.line);
                }
                None
            }
            Some((false, name)) if name != self.sub_label => None,
            Some((opens, name)) => {
                if opens && self.sub_file == SubFile::Unknown {
                    self.sub_label = name;
                }
                Some(opens)
            }
            None => None,
        };
        // (an M2 or M30 among the block's M codes, beside a sequence number and other M codes:
        // `M5 M2`, `N5 M2`, `M2.0`, review 38, finding 2)
        // (an M value of a parameter or expression the checker evaluates, `M#<two>`, is one
        // too: rs274 reads it so, review 38, finding 8)
        let program_end = b.statements.is_empty() && {
            let mut ends = false;
            let plain = b.words.iter().all(|w| match w.letter {
                b'M' => {
                    let number = self.linuxcnc_m_number(w);
                    ends |= matches!(number, Some(2 | 30));
                    number.is_some()
                }
                b'N' => w.expression.is_empty(),
                _ => false,
            });
            plain && ends
        };
        if self.sub_returns.0 != 0 && b.line > self.sub_returns.0 {
            self.after_early_return(b, program_end);
        }
        // (the return that ends the file: nothing after it but M2/M30)
        if !program_end && self.sub_returns.2 != b.line {
            self.sub_returns.2 = 0;
        }
        let before = self.sub_file;
        self.sub_file = match (self.sub_file, definition) {
            (SubFile::Unknown, Some(true)) => SubFile::Open,
            (SubFile::Open, Some(false)) => SubFile::Closed,
            (SubFile::Open, _) => SubFile::Open,
            (SubFile::Closed, None) if program_end => SubFile::Closed,
            _ => SubFile::No,
        };
        self.sub_ended = self.sub_file == SubFile::Closed;
        if self.sub_file == SubFile::No {
            if before == SubFile::Unknown && b.statements.is_empty() {
                self.sub_preamble = (b.line, 0);
            }
            if self.sub_returns.0 != 0 {
                self.early_endsub_in_program();
            }
            if let Some((line, column)) = self.sub_percent.take() {
                self.percent_refusal(line, column);
            }
        }
    }

    /// LinuxCNC: a definition of the main program, before its end, read apart from its
    /// `sub` to its `endsub` and judged in the units and under the shift of its calls
    /// (crate::check::called; review 41, finding 4); an `o<name> call` keeps them for a
    /// definition read so, and one whose label is not known (`o[#1] call`) leaves every one
    /// not known.
    fn linuxcnc_called(
        &mut self,
        b: &BlockView<'_>,
        statement: Option<&(bool, Vec<u8>)>,
        was_open: bool,
    ) {
        match statement {
            Some((true, name))
                if !was_open && self.open_definition.is_some() && !self.main_ended() =>
            {
                let column = b.statements.first().map_or(1, |s| s.0);
                // (named as written, `o<300>`: review 81-lcnc81 R5)
                let shown = b
                    .statements
                    .first()
                    .map_or_else(|| name.clone(), |s| crate::statement::o_label_shown(s.2));
                self.definition_begin(name, &shown, (b.line, column));
                // (read apart, not run here: the offsets are not lost at its sub)
                self.call_keeps = self.early_on && !self.config.work_offsets.is_empty();
            }
            Some((true, name))
                if !was_open && self.open_definition.is_some() && self.later_called.is_some() =>
            {
                self.later_definition(name);
            }
            Some((false, _))
                if was_open
                    && self.open_definition.is_none()
                    && self.in_hand.is_some_and(|n| n >= LATER_DEFINITION) =>
            {
                self.resumed_returned(b);
                self.call_mode_returned(true);
                self.local_body_end();
                self.call_keeps = true;
            }
            Some((false, _)) if was_open && self.open_definition.is_none() => {
                let read_apart = self.early_on;
                self.definition_end();
                // (nor at its endsub, where it was kept for its calls and changed nothing
                // of the main program's offsets where read: a G49, G92 or G55 of its own
                // read there stays in the state the main program's lines are read in)
                self.call_keeps = read_apart
                    && !self.early_on
                    && self
                        .pending
                        .len()
                        .checked_sub(1)
                        .is_some_and(|k| self.keeps_offsets(k));
            }
            _ => {}
        }
        if !self.config.work_offsets.is_empty()
            && !self.early_on
            && b.statements.iter().any(|s| s.1 == Kind::Call)
        {
            if self.open_definition.is_none() {
                self.later_call(b);
            } else if self.in_hand.is_some_and(|n| n >= LATER_DEFINITION) {
                // (a call inside a definition after the end, not followed: it may change
                // the offsets its callers run under after it; review 77-calls77 F1)
                self.after_mark();
            }
        }
        if !self.early_on && self.pending.is_empty() && self.given_up.is_empty()
            || self.open_definition.is_none() && self.linuxcnc_dead()
        {
            return;
        }
        for &(column, kind, text) in b.statements {
            if kind != Kind::Call
                || crate::statement::o_keyword(text).as_deref() != Some(b"call".as_slice())
            {
                continue;
            }
            self.early_calls();
            let token = format!(
                "{} call",
                String::from_utf8_lossy(&crate::statement::o_label_shown(text))
            );
            let label = self.linuxcnc_call_label(text);
            if label.len() < 2 || crate::statement::computed_label(&label) {
                self.call_unknown(token, b.line, column);
            } else if self.early_call(super::called::Key::Label(label), token, (b.line, column)) {
                // (the shift at the call kept, as a FANUC's M98's is: the end that follows
                // does not start the spans the body is judged in again, Checker::shift_end)
                self.call_shifts();
                if self.shifts_on() {
                    self.shift_call(b);
                }
            }
        }
    }

    /// LinuxCNC, under a profile that gives work offsets: an `o<name> call` of the main
    /// program, outside its conditions and loops and before its end, of a label no definition
    /// read before it names (one after M2, which rs274 runs at the call: `rs274 -g` gives its
    /// moves after the call's SET_G5X_OFFSET), kept as a call of a program written after it
    /// by a key of its own ([`LATER_DEFINITION`]), in the one implementation of such calls, as
    /// a Haas's M97 is ([`Checker::local_call`]): its work offset, distance mode and units
    /// ([`Checker::call_work`]). The definition after the end is read under the calls'
    /// offset ([`Checker::later_definition`]).
    #[cold]
    #[inline(never)]
    fn later_call(&mut self, b: &BlockView<'_>) {
        if self.open_definition.is_some() || self.main_ended() || self.linuxcnc_dead() {
            return;
        }
        let calls: Vec<Vec<u8>> = b
            .statements
            .iter()
            .filter(|&&(_, kind, text)| {
                kind == Kind::Call
                    && crate::statement::o_keyword(text).as_deref() == Some(b"call".as_slice())
            })
            .map(|&(_, _, text)| self.linuxcnc_call_label(text))
            .collect();
        let [label] = calls.as_slice() else {
            return;
        };
        self.later_call_of(b, label);
    }

    /// [`Checker::later_call`] of `label` (`o300` for a main program's `M98 P300`: the one
    /// implementation of both forms' calls of a definition written after the end,
    /// [`Checker::linuxcnc_m98_later`]).
    fn later_call_of(&mut self, b: &BlockView<'_>, label: &[u8]) {
        if self.open_definition.is_some() || self.main_ended() || self.linuxcnc_dead() {
            return;
        }
        let key = super::called::Key::Label(label.to_vec());
        if label.len() < 2 || crate::statement::computed_label(label) || self.read_before(&key) {
            return;
        }
        let labels = self.later_called.get_or_insert_with(Vec::new);
        let index = labels.iter().position(|l| l == label).unwrap_or_else(|| {
            labels.push(label.to_vec());
            labels.len() - 1
        });
        let key = LATER_DEFINITION + index as i64;
        let keep = |c: &mut Checker| {
            c.after_call(key);
            c.call_mode_kept(key);
            c.call_work(b, key);
            c.call_of_unread(key); // (as after a FANUC's M98 of a program written later)
            c.call_units_seen(key);
        };
        // (inside the main program's conditions and loops: where its lines surely run, as
        // outside; where they may not, under the offset where they opened, oflow.rs. Not
        // where a call of the label before it was kept: the two would be judged under none
        // where they differ, and the first's judgment is kept as it was, review 80-lcnc80:
        // `G55` / `o300 call` / `G54` / `G55` / `o1 if [1]` / `o300 call` / `o1 endif`)
        if !self.linuxcnc_open_flow.is_empty() && self.call_works.contains_key(&key) {
            return;
        }
        if self.linuxcnc_runs_surely() && !self.flow_reads_any() {
            keep(self);
        } else {
            self.may_call(key, keep);
        }
    }

    /// LinuxCNC: the label of the definition after the main program's end being read, the
    /// key in hand ([`LATER_DEFINITION`] + its index among the labels its calls were kept for).
    pub(super) fn later_label(&self) -> Option<&[u8]> {
        let index = self.in_hand?.checked_sub(LATER_DEFINITION)?;
        let labels = self.later_called.as_ref()?;
        labels.get(usize::try_from(index).ok()?).map(Vec::as_slice)
    }

    /// LinuxCNC: an `o<name> sub` after the main program's end whose label calls kept
    /// ([`Checker::later_call`]) name: read as a program written after its calls is
    /// ([`Checker::work_of_calls`]), under the calls' work offset where they agree (in their
    /// distance mode and units), under none where they do not or one was made where it was
    /// not known; its `endsub` gives the state back ([`Checker::local_body_end`]).
    #[cold]
    #[inline(never)]
    fn later_definition(&mut self, name: &[u8]) {
        let Some(index) = self
            .later_called
            .as_ref()
            .and_then(|labels| labels.iter().position(|l| l.as_slice() == name))
        else {
            return;
        };
        let key = LATER_DEFINITION + index as i64;
        if !self.main_ended() || self.early_on || !self.call_works.contains_key(&key) {
            return;
        }
        self.local_body_begin(key, None);
        // (its sub line runs nothing: the offsets are not lost at it)
        self.call_keeps = true;
    }

    /// TG138: an endsub of a LinuxCNC subroutine file that names another label than its sub.
    fn endsub_named_otherwise(&mut self, b: &BlockView<'_>, name: &[u8]) {
        let (sub, end) = (
            String::from_utf8_lossy(&self.sub_label),
            String::from_utf8_lossy(name),
        );
        let message = format!(
            "{end} endsub names another label than the file's {sub} sub: called, rs274 returns \
             here all the same (it compares an endsub's label only while it skips a \
             definition, interp_read.cc read_o), while a program that defines {sub} reads on \
             past it to {sub} endsub; name it {sub}"
        );
        let column = b.statements.first().map_or(1, |s| s.0);
        self.report(Rule::EndsubNamedOtherwise, message, b.line, column);
    }

    /// TG412: the file opened as a subroutine file, taking an endsub inside a condition or
    /// loop of its body as a return, and is a program after all (its lines go on past the
    /// definition): rs274, reading the file from its top, ends the definition at the first
    /// endsub of its label and refuses the o-word line that closes the condition or loop
    /// after it (`o<t> sub` / `o100 if [#1 EQ 1]` / `o<t> endsub [1]` / `o100 endif` ...:
    /// "undefined O-word label: 'o100 endif'").
    fn early_endsub_in_program(&mut self) {
        let (line, column) = (self.sub_returns.0, self.sub_returns.1);
        self.sub_returns.0 = 0;
        let message = "undefined O-word label (rs274ngc): this endsub inside a condition or \
                       loop ends the definition where the file runs as a program (rs274 reads \
                       a definition to the first endsub of its label), and the o-word line \
                       that closes the condition or loop after it has no label open; only a \
                       subroutine file, which a call runs from its sub, returns here"
            .to_string();
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// TG412: a bare O number (`O103`, after an N at most, nothing but a comment after it)
    /// inside a LinuxCNC definition. rs274ngc reads it as the start of a FANUC-style program
    /// (interp_read.cc read_o, `O_`) and refuses it while it defines a subroutine, running the
    /// body or skipping it ("Nested subroutine definition"; called, "... found inside called
    /// subroutine"): the line is read in every way through the file, an o-word line read
    /// while a block skips too (`rs274 -g`; LCNC_BMC20's `toolchange.ngc`, an `O103` typed
    /// for `O103 endif`).
    fn bare_o_in_definition(&mut self, b: &BlockView<'_>) {
        // (signed, `O103.0`, or a parameter or expression, `O[103]`, `O#1`: rs274 reads the
        // label as a whole number, read_integer_value, and refuses each alike; review 78-lcnc78
        // N2. A value known not whole, `O103.5`, is refused otherwise: "Non integer value for
        // integer")
        let bare = |w: &Word<'_>| {
            w.letter == b'O'
                && w.index.is_empty()
                && (!w.expression.is_empty() || !w.number.is_empty())
        };
        let k = match b.words {
            [o] if bare(o) => 0,
            [_, o] if bare(o) => 1,
            _ => return,
        };
        let o = &b.words[k];
        if b.words.len() == 2 && b.words[0].letter != b'N' {
            return;
        }
        let whole = if o.expression.is_empty() {
            std::str::from_utf8(o.number)
                .ok()
                .and_then(|n| n.parse::<f64>().ok())
                .is_some_and(|v| v.fract() == 0.0)
        } else {
            // (a decimal in it, `O[103.5]`: not surely whole)
            !o.expression.contains(&b'.')
                && self
                    .readable
                    .get(k)
                    .copied()
                    .flatten()
                    .is_none_or(|v| v.is_whole())
        };
        if !whole {
            return;
        }
        // (a definition after the main program's end is read only where a call seeks it;
        // after a subroutine file's early return the lines are the main program's where the
        // file runs as a program, a FANUC-style program there: review 77 N3)
        let early = self.sub_file == SubFile::Open && self.sub_returns.0 != 0;
        let Some((line, _, name)) = self
            .open_definition
            .as_ref()
            .filter(|_| !self.main_ended() && !early)
        else {
            return;
        };
        // (the word as it is: `O103` a bare O number, `O[103]` an O word of an expression;
        // review 79-lcnc79 N4)
        let what = if o.expression.is_empty() && o.sign.is_empty() && !o.point {
            "a bare O number".to_string()
        } else {
            format!(
                "an O word alone on its line ({}, whose whole value rs274 takes for a program \
                 number: read_integer_value)",
                String::from_utf8_lossy(o.token)
            )
        };
        let message = format!(
            "Nested subroutine definition (rs274ngc): {what} is the start of a FANUC-style \
             program (interp_read.cc read_o), which rs274 refuses inside the {} definition \
             (line {line}), whether it runs the body or skips it",
            String::from_utf8_lossy(name)
        );
        let column = o.column;
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
    }

    /// LinuxCNC: of the blocks of the body open at its first endsub (a subroutine file's
    /// early return), the innermost rs274 may skip from when a call runs the body: an `if`
    /// or `while` whose condition, or a `repeat` whose count, is not surely true (a `do`
    /// runs its lines before any test, so it never skips to its `while`), or one whose
    /// endsub stands in a later branch. Its line, its statement, the endsub's line and the
    /// branch's line (`else`, `elseif`) where the endsub stands in one.
    #[allow(clippy::type_complexity)]
    fn block_left_open(&self, endsub: usize) -> Option<(usize, Vec<u8>, usize, Option<Vec<u8>>)> {
        self.linuxcnc_definition_opened
            .iter()
            .rev()
            .find(|(_, text, branch)| {
                let (keyword, condition) = o_keyword_condition(text);
                if branch.is_some() {
                    // (the endsub in an `else` or `elseif` branch: the branch before it, run,
                    // skips to the `endif`)
                    return true;
                }
                let value = (!condition.contains(&b'#'))
                    .then(|| self.linuxcnc_condition_value(condition))
                    .flatten();
                match keyword.as_slice() {
                    b"if" | b"while" => value.is_none_or(|v| v == 0.0),
                    b"repeat" => value.is_none_or(|v| v.round() < 1.0),
                    _ => false,
                }
            })
            .map(|(line, text, branch)| (*line, text.clone(), endsub, branch.clone()))
    }

    /// LinuxCNC: a block after a subroutine file's early return (an endsub inside a block of
    /// the body, [`Checker::sub_left_open`]), which a run of the file as a program reads as
    /// its main program ([`AfterReturn`]): rs274 skips a definition not called to the first
    /// o-word line of its label, that endsub. Read until the first of: an M2/M30 that surely
    /// runs there, an o-word line rs274 refuses there (one that closes or continues a block
    /// not opened after the endsub, "undefined O-word label"; an endsub outside a
    /// definition, "not in a subroutine definition"), a call of the definition that surely
    /// runs with values that make the block left open skip.
    fn after_early_return(&mut self, b: &BlockView<'_>, program_end: bool) {
        let mut after = std::mem::take(&mut self.sub_after_return);
        after.any |= !b.words.is_empty() || !b.statements.is_empty();
        if after.refused.is_some() || after.skips != 0 || after.end {
            self.sub_after_return = after;
            return;
        }
        let may_run = !after.in_def && after.flow.iter().all(|e| e.1 != Some(false));
        let surely = !after.in_def && after.flow.iter().all(|e| e.1 == Some(true));
        // (an M2/M30 beside other words ends the program too, `G0 X0 M2`: review 77 F6)
        let ends = program_end
            || b.statements.is_empty()
                && b.words
                    .iter()
                    .any(|w| w.letter == b'M' && matches!(self.linuxcnc_m_number(w), Some(2 | 30)));
        after.end |= ends && may_run;
        // (a body's M2, M30, M98 or M99 before a call in it: the call may not run; one of the
        // main program's calls)
        let m_stop = || {
            b.words.iter().any(|w| {
                w.letter == b'M' && matches!(self.linuxcnc_m_number(w), Some(2 | 30 | 98 | 99))
            })
        };
        if after.in_def {
            after.def_left |= ends || m_stop();
        } else if b
            .words
            .iter()
            .any(|w| w.letter == b'M' && self.linuxcnc_m_number(w) == Some(98))
        {
            after.other_call = true;
        }
        for &(column, kind, text) in b.statements {
            let keyword = crate::statement::o_keyword(text).unwrap_or_default();
            let label = crate::statement::o_label(text);
            let undefined = |what: &str| {
                Some((
                    b.line,
                    column,
                    format!(
                        "{what} (rs274ngc): run as a program, rs274 skips the definition to its \
                         endsub on line {} (the first o-word line of its label: \
                         interp_o_word.cc, skipping_o) and reads this line as the main \
                         program's",
                        self.sub_returns.0
                    ),
                ))
            };
            match (kind, keyword.as_slice()) {
                (Kind::Definition, b"sub") if !after.in_def && label == self.sub_label => {
                    after.refused = undefined("redefining sub");
                }
                (Kind::Definition, b"sub") => {
                    after.in_def = true;
                    after.def_label = label;
                    after.def_flow.clear();
                    after.def_left = false;
                }
                (_, b"return") if !after.in_def => {
                    after.refused = undefined("not in a subroutine definition");
                }
                (Kind::Definition, b"endsub") if after.in_def => after.in_def = false,
                (Kind::Definition, _) => {
                    after.refused = undefined("not in a subroutine definition");
                }
                (Kind::Flow, k) if after.in_def => {
                    // (the blocks of the definition's body: a call inside one may not run)
                    let flow = &mut after.def_flow;
                    let at = flow.iter().rposition(|l| *l == label);
                    match (k, at) {
                        (b"while" | b"endif" | b"endwhile" | b"endrepeat", Some(at)) => {
                            flow.truncate(at)
                        }
                        (b"if" | b"while" | b"repeat" | b"do", _) => flow.push(label),
                        (b"return", _) => after.def_left = true,
                        _ => {}
                    }
                }
                (Kind::Flow, k) => {
                    let at = after.flow.iter().rposition(|e| e.0 == label);
                    let (_, condition) = o_keyword_condition(text);
                    let value = (!condition.contains(&b'#'))
                        .then(|| self.linuxcnc_condition_value(condition))
                        .flatten();
                    match (k, at) {
                        (b"while", Some(at)) => after.flow.truncate(at),
                        (b"if" | b"while", _) => after.flow.push((label, value.map(|v| v != 0.0))),
                        (b"repeat", _) => {
                            after.flow.push((label, value.map(|v| v.round() >= 1.0)));
                        }
                        (b"do", _) => after.flow.push((label, Some(true))),
                        (b"endif" | b"endwhile" | b"endrepeat", Some(at)) => {
                            after.flow.truncate(at)
                        }
                        (b"else" | b"elseif", Some(at)) => after.flow[at].1 = None,
                        (
                            b"endif" | b"endwhile" | b"endrepeat" | b"else" | b"elseif" | b"break"
                            | b"continue",
                            None,
                        ) => {
                            after.refused = undefined("undefined O-word label");
                        }
                        _ => {}
                    }
                }
                (Kind::Call, b"call") if surely && !b.skip && label == self.sub_label => {
                    match self.call_skips(text) {
                        Some(true) => after.skips = b.line,
                        Some(false) if after.holds == 0 => after.holds = b.line,
                        _ => {}
                    }
                }
                // (a call of the definition in another definition's body, outside its blocks,
                // with values that make the block skip: a call of that other definition that
                // surely runs reads to the end of the file as well; review 77-lcnc77b F7:
                // `o300 sub` / `o200 call [0]` / `o300 endsub` / `o300 call` is "File ended
                // with no percent sign or program end" in `rs274 -g`)
                (Kind::Call, b"call")
                    if after.in_def
                        && after.def_flow.is_empty()
                        && !after.def_left
                        && !b.skip
                        && label == self.sub_label
                        && self.call_skips(text) == Some(true) =>
                {
                    let sub = String::from_utf8_lossy(&self.sub_label);
                    let via = format!(", whose call on line {} runs {sub}", b.line);
                    after.inner.push((after.def_label.clone(), via));
                }
                // (and one of such a definition, at any depth)
                (Kind::Call, b"call")
                    if after.in_def && after.def_flow.is_empty() && !after.def_left && !b.skip =>
                {
                    after.def_left = true;
                    if let Some(e) = after.inner.iter().find(|e| e.0 == label) {
                        let via = format!(
                            ", whose call on line {} runs {}{}",
                            b.line,
                            String::from_utf8_lossy(&label),
                            e.1
                        );
                        after.inner.push((after.def_label.clone(), via));
                    }
                }
                (Kind::Call, b"call") if surely && !b.skip && !after.other_call => {
                    if let Some(e) = after.inner.iter().find(|e| e.0 == label) {
                        after.skips = b.line;
                        after.via = Some(format!("{}{}", String::from_utf8_lossy(&label), e.1));
                    }
                    after.other_call = true;
                }
                (Kind::Call, _) if after.in_def => after.def_left = true,
                (Kind::Call, _) => after.other_call = true,
                _ => {}
            }
            if after.refused.is_some() || after.skips != 0 {
                break;
            }
        }
        self.sub_after_return = after;
    }

    /// Whether the call statement `text` of the definition runs it so that the block left
    /// open at its endsub ([`Checker::sub_left_open`]) skips (rs274 then reads to the end of
    /// the file): the block's conditions worked out with the call's arguments as #1 to #n
    /// and the other parameters of #1-#30 zero (interp_read.cc read_o, a call zeroes the
    /// parameters after its arguments). None where not known.
    fn call_skips(&mut self, text: &[u8]) -> Option<bool> {
        let (_, block, _, branch) = self.sub_left_open.clone()?;
        let args = self.call_arguments(text)?;
        let (keyword, condition) = o_keyword_condition(&block);
        let value = self.condition_at_call(condition, &args)?;
        let holds = if keyword.as_slice() == b"repeat" {
            value.round() >= 1.0
        } else {
            value != 0.0
        };
        let Some(branch) = branch else {
            return Some(!holds);
        };
        // (the endsub in a later branch: where the `if` holds, its first branch runs and
        // skips from its end; where an `elseif` before the endsub is false, no branch up to
        // the endsub's runs)
        if holds {
            return Some(true);
        }
        let (keyword, condition) = o_keyword_condition(&branch);
        if keyword.as_slice() != b"elseif" {
            return Some(false);
        }
        let value = self.condition_at_call(condition, &args)?;
        (value == 0.0).then_some(true)
    }

    /// The values of a LinuxCNC call's arguments (`o<min> call [0] [2.5]`), where the
    /// checker works each out; None otherwise.
    fn call_arguments(&self, text: &[u8]) -> Option<Vec<f64>> {
        let (_, rest) = o_keyword_condition(text);
        let mut values = Vec::new();
        let mut depth = 0usize;
        let mut start = 0;
        for (i, &c) in rest.iter().enumerate() {
            match c {
                b'[' => {
                    if depth == 0 {
                        start = i;
                    }
                    depth += 1;
                }
                b']' => {
                    depth = depth.checked_sub(1)?;
                    if depth == 0 {
                        values.push(self.linuxcnc_condition_value(&rest[start..=i])?);
                    }
                }
                b' ' | b'\t' => {}
                _ if depth == 0 => return None,
                _ => {}
            }
        }
        Some(values)
    }

    /// TG114, TG142: a LinuxCNC file whose definition's only endsub of its label stands
    /// inside a block of the body left open (`o<min> sub` / `o100 if [#1]` / `G0 X1` /
    /// `o<min> endsub` / `M2`). rs274 runs the file as a program past the definition: not
    /// called, a definition is skipped to the first o-word line of its label
    /// (interp_o_word.cc convert_control_functions, `skipping_o`), the endsub here, and the
    /// lines after it are the main program's (TG114 only where no M2/M30 is among them, and
    /// the file does not end at a closing %). A call runs the body from its sub: where the
    /// block's condition is false (a count below one), rs274 skips to the next o-word line
    /// of the block's label, which the file does not have, and reads to its end ("File ended
    /// with no percent sign or program end"); where it holds, it returns at the endsub. An
    /// error where a call of the main program that surely runs gives the condition values
    /// that make it false; else a warning at the block (TG142).
    fn definition_returns_open(&mut self, percent_ended: bool) {
        let endsub = self.sub_returns.0;
        let after = std::mem::take(&mut self.sub_after_return);
        let name = String::from_utf8_lossy(&self.sub_label).into_owned();
        let left = self.sub_left_open.take();
        if let Some((line, column, what)) = after.refused {
            self.report(Rule::LinuxCncRefuses, what, line, column);
        } else if after.any && !after.end && after.skips == 0 && !percent_ended {
            let message = format!(
                "the program has no M02 or M30 that surely runs: run as a program, rs274 skips \
                 the {name} definition, which no line before it calls, to the endsub on line \
                 {endsub} (the first o-word line of its label: interp_o_word.cc, skipping_o) \
                 and reads the lines after it as the main program"
            );
            let line = self.last_line.max(1);
            self.report(Rule::NoProgramEnd, message, line, 1);
        }
        let Some((open, text, _, branch)) = left else {
            return;
        };
        let (keyword, condition) = o_keyword_condition(&text);
        let label = String::from_utf8_lossy(&crate::statement::o_label(&text)).into_owned();
        let keyword = String::from_utf8_lossy(&keyword).into_owned();
        let always = !condition.contains(&b'#') && branch.is_none();
        let (when_true, then_false) = if keyword == "repeat" {
            ("its count is one or more", "it is below one")
        } else {
            ("its condition holds", "it is false")
        };
        // (a subroutine file, nothing after its endsub, whose block never runs: every call
        // reads to the end)
        if always && !after.any {
            let message = format!(
                "File ended with no percent sign or program end (rs274ngc): the {label} \
                 {keyword} of the {name} definition never runs and is not closed before its \
                 endsub (line {endsub}), so every call skips to the next o-word line of \
                 {label}, which the file does not have, and reads to its end \
                 (interp_o_word.cc, skipping_o)"
            );
            self.report(Rule::NoProgramEnd, message, open, 1);
            return;
        }
        if after.skips != 0 {
            let call = after.skips;
            let why = match (&branch, always) {
                (Some(_), _) => "no branch up to the endsub's runs alone",
                (None, true) => "the block never runs",
                (None, false) if keyword == "repeat" => {
                    "with the call's values its count is below one"
                }
                (None, false) => "with the call's values its condition is false",
            };
            let name = after.via.clone().unwrap_or(name);
            let message = format!(
                "File ended with no percent sign or program end (rs274ngc): the call on line \
                 {call} runs {name}, whose {label} {keyword} (line {open}) is not closed before \
                 its endsub (line {endsub}); {why}, so rs274 skips to the next o-word line of \
                 {label}, which the file does not have, and reads to its end \
                 (interp_o_word.cc, skipping_o)"
            );
            self.report(Rule::NoProgramEnd, message, call, 1);
            return;
        }
        let called = match after.holds {
            0 => String::new(),
            call => format!("the call on line {call} returns there; "),
        };
        let ways = if branch.is_some() {
            format!(
                "the endsub stands in a later branch of it: a call returns there where that \
                 branch runs, but where an earlier one does, or none, rs274 skips to the next \
                 o-word line of {label}"
            )
        } else if always {
            format!(
                "every call of {name} skips the block and seeks the next o-word line of {label}"
            )
        } else {
            format!(
                "a call returns at that endsub where {when_true}, but where {then_false} rs274 \
                 skips to the next o-word line of {label}"
            )
        };
        let message = format!(
            "{label} {keyword} is not closed before the {name} endsub on line {endsub}: {ways}, \
             which the file does not have, and reads to its end ('File ended with no percent \
             sign or program end'); {called}a run of the file as a program skips the \
             definition to that endsub (close the block before the endsub)"
        );
        self.report(Rule::BlockOpenAtEndsub, message, open, 1);
    }

    /// The value of a condition of a definition's body at a call of the main program whose
    /// arguments are constants (`o<min> call [0]`): its parameters #1 to #n those values
    /// (interp_o_word.cc execute_call), any other parameter not known.
    fn condition_at_call(&mut self, condition: &[u8], args: &[f64]) -> Option<f64> {
        // (only #1 to #n read: every `#` followed by the digits of one of them)
        let mut i = 0;
        while let Some(p) = condition[i..].iter().position(|&c| c == b'#') {
            let start = i + p + 1;
            let digits = condition[start..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            let n: usize = std::str::from_utf8(&condition[start..start + digits])
                .ok()?
                .parse()
                .ok()?;
            if n == 0 || n > 30 {
                return None;
            }
            i = start + digits;
        }
        let mut values = std::collections::HashMap::new();
        for n in 0..30 {
            let v = args.get(n).copied().unwrap_or(0.0);
            let (_, key) = self.parameter_key(format!("#{}", n + 1).as_bytes())?;
            values.insert(key, Dec::parse(&format!("{v}"))?);
        }
        std::mem::swap(&mut values, &mut self.params);
        let value = self.linuxcnc_condition_value(condition);
        std::mem::swap(&mut values, &mut self.params);
        value
    }

    /// TG412: LinuxCNC's main program reaches the definition of a subroutine it has called
    /// before it. A call of a subroutine not yet defined opens the file of its name, or
    /// else reads on in this file to the definition and records it there
    /// (interp_o_word.cc `convert_control_functions`, `control_save_offset`); when the
    /// program comes to that definition again after the call, rs274 refuses it ("sub: o|100|
    /// found in illegal location"; with a file of that name, "redefining sub"). Only the
    /// main program's own calls and definitions, before its M2/M30, are followed: a
    /// definition after the end is never reached. A definition in the skip of a block known
    /// not to run is one the program never comes to: found by a call before it (the search
    /// reads o-word lines alone, whatever block they stand in), it is recorded there and
    /// runs; else rs274 skips it without recording it, and a call after it that surely runs
    /// seeks the subroutine from the call to the file's end ([`LINUXCNC_EOF_SEEKING`],
    /// said at the end where no definition of it came after the call; `rs274 -g`; review
    /// 52, F7).
    fn definition_after_call(&mut self, b: &BlockView<'_>, statement: Option<&(bool, Vec<u8>)>) {
        if let Some((true, name)) = statement {
            if self.linuxcnc_skipping.is_none() {
                self.linuxcnc_dead_called.retain(|c| c.0 != *name);
            }
        }
        if self.open_definition.is_some() || self.main_ended() {
            return;
        }
        if let Some((true, name)) = statement.filter(|_| self.linuxcnc_skipping.is_some()) {
            if let Some(at) = self.linuxcnc_called_ahead.iter().position(|c| c.0 == *name) {
                self.linuxcnc_called_ahead.swap_remove(at);
                self.linuxcnc_defined.push(name.clone());
            } else if !self.linuxcnc_defined.contains(name) {
                let block = self.linuxcnc_skipping.as_ref().map_or(0, |s| s.1);
                self.linuxcnc_dead_defs.push((name.clone(), b.line, block));
            }
            return;
        }
        if let Some((true, name)) = statement {
            if self.linuxcnc_open_flow.is_empty() && !crate::statement::computed_label(name) {
                self.linuxcnc_redefined(b, name);
            }
            if let Some(at) = self
                .linuxcnc_called_ahead
                .iter()
                .position(|(l, _)| l == name)
            {
                let (_, called) = self.linuxcnc_called_ahead.swap_remove(at);
                let label = String::from_utf8_lossy(name);
                let bare = label
                    .trim_start_matches(['o', 'O'])
                    .trim_start_matches('<')
                    .trim_end_matches('>');
                let message = format!(
                    "sub: o|{bare}| found in illegal location (rs274ngc): the {label} call on \
                     line {called} found this definition ahead of it, and the program comes \
                     to it again after the call returns; define a subroutine before its first \
                     call or after M2"
                );
                let column = b.statements.first().map_or(1, |s| s.0);
                self.report(Rule::LinuxCncRefuses, message, b.line, column);
            }
            self.linuxcnc_defined.push(name.clone());
            // (a definition in the body of a loop at the top, reached: its turns are counted
            // at the loop's end, Checker::linuxcnc_loop_turns)
            if let Some(defs) = self.linuxcnc_loop_defs.as_mut() {
                if !b.skip
                    && self.linuxcnc_open_flow.len() == 1
                    && matches!(self.linuxcnc_open_at.as_slice(), [e] if e.runs == Some(true))
                {
                    let column = b.statements.first().map_or(1, |s| s.0);
                    defs.defs.push((name.clone(), b.line, column));
                }
            }
            return;
        }
        for &(_, kind, text) in b.statements {
            if kind != crate::statement::Kind::Call
                || crate::statement::o_keyword(text).as_deref() != Some(b"call".as_slice())
            {
                continue;
            }
            let label = self.linuxcnc_call_label(text);
            let dead_only = !self.linuxcnc_defined.contains(&label)
                && self.linuxcnc_dead_defs.iter().any(|d| d.0 == label);
            if dead_only
                && !b.skip
                && !self.linuxcnc_dead()
                && self.linuxcnc_runs_surely()
                && !self.linuxcnc_dead_called.iter().any(|c| c.0 == label)
            {
                let column = b.statements.first().map_or(1, |s| s.0);
                self.linuxcnc_dead_called
                    .push((label.clone(), b.line, column));
            }
            if !self.linuxcnc_defined.contains(&label)
                && !self.linuxcnc_called_ahead.iter().any(|(l, _)| *l == label)
            {
                self.linuxcnc_called_ahead.push((label, b.line));
            }
        }
    }

    /// TG412: the main program defines a subroutine it has defined before (both at its top,
    /// before its end): rs274 keeps a definition for the whole program by its name
    /// (interp_o_word.cc `control_save_offset`) and refuses the second, "redefining sub:
    /// o|100| already defined" (`rs274 -g`; `o[100] sub` after `o100 sub` too; review 48,
    /// F19).
    fn linuxcnc_redefined(&mut self, b: &BlockView<'_>, name: &[u8]) {
        let bare = bare_label(name);
        let first = match self.linuxcnc_subs_defined.entry(bare) {
            std::collections::hash_map::Entry::Occupied(e) => *e.get(),
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert(b.line);
                return;
            }
        };
        let bare = bare_label(name);
        let bare = String::from_utf8_lossy(&bare);
        let message = format!(
            "redefining sub: o|{bare}| already defined (rs274ngc): the definition on line \
             {first} has that name, and rs274 keeps a subroutine's definition for the whole \
             program (interp_o_word.cc control_save_offset); give each definition its own \
             label"
        );
        let column = b.statements.first().map_or(1, |s| s.0);
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
    }

    /// The subroutine a LinuxCNC `o… call` statement names, and the block any other o-word
    /// statement opens or closes: its o-word's label
    /// ([`crate::statement::o_label`]), and for a label worked out as the line runs (`o#1
    /// call`, `o[#1] call`, `o##2 call`: rs274ngc `read_o` reads a parameter or an expression
    /// there, at the line) the numbered one of its value where the checker knows it and it is
    /// an integer as rs274 reads one; else the label as written, which names no definition
    /// (the call's target not known).
    fn linuxcnc_call_label(&self, text: &[u8]) -> Vec<u8> {
        let label = crate::statement::o_label(text);
        if crate::statement::computed_label(&label) {
            if let Some(n) = self
                .linuxcnc_label_value(&label)
                .and_then(crate::statement::rs274_integer)
            {
                return format!("o{n}").into_bytes();
            }
        }
        label
    }

    /// The label of a LinuxCNC `sub` or `endsub` as rs274 matches it: rs274ngc's `read_o`
    /// works out a computed label where it reads the line (`#1=100` ... `o100 sub` ... `o#1
    /// endsub` closes o100 sub: `rs274 -g`; with #1 0 the definition is never closed, "File
    /// ended with no percent sign or program end"), so its value where the checker knows it
    /// ([`Checker::linuxcnc_call_label`]). An endsub whose value it does not know is taken as
    /// closing the definition open, said (TG140): rs274 reads on to another endsub where the
    /// value is another label.
    fn linuxcnc_definition_label(
        &mut self,
        b: &BlockView<'_>,
        opens: bool,
        label: Vec<u8>,
    ) -> (bool, Vec<u8>) {
        if opens && self.open_definition.is_none() {
            self.linuxcnc_sub_params.clone_from(&self.params);
        }
        // a definition whose label the checker could not work out (`osqrt[10000] sub`): its
        // endsub is taken as closing it, said (TG140), not a false TG114/TG138 (review 48, F4)
        if let Some((line, _, open)) = &self.open_definition {
            if !opens
                && label != *open
                && crate::statement::computed_label(open)
                && self.linuxcnc_label_value(open).is_none()
            {
                let (line, open) = (*line, open.clone());
                let message = format!(
                    "{} endsub: taken as closing {} sub (line {line}), whose label is worked \
                     out as the line runs, from a value the checker does not know (rs274 \
                     closes it here only where the values are the same)",
                    String::from_utf8_lossy(&label),
                    String::from_utf8_lossy(&open),
                );
                let column = b.statements.first().map_or(1, |s| s.0);
                self.report(Rule::NotFollowed, message, b.line, column);
                return (opens, open);
            }
        }
        if !crate::statement::computed_label(&label) {
            return (opens, label);
        }
        let Some(&(column, _, text)) = b.statements.iter().find(|s| s.1 == Kind::Definition) else {
            return (opens, label);
        };
        // (an endsub's value is read with the parameters the definition's first line had)
        if !opens {
            std::mem::swap(&mut self.params, &mut self.linuxcnc_sub_params);
        }
        let known = self.linuxcnc_call_label(text);
        // (a value known that is no integer, `o100.5 endsub`: refused at its line, TG412)
        let fraction = self.linuxcnc_label_value(&known).is_some();
        if !opens {
            std::mem::swap(&mut self.params, &mut self.linuxcnc_sub_params);
        }
        if !crate::statement::computed_label(&known) || fraction {
            return (opens, known);
        }
        match &self.open_definition {
            Some((line, _, open)) if !opens => {
                let open = open.clone();
                let message = format!(
                    "{} endsub: its label is worked out as the line runs, from a value the \
                     checker does not know; taken as closing {} sub (line {line}), which rs274 \
                     does only where the value is that label's (else it reads on to another \
                     endsub)",
                    String::from_utf8_lossy(&label),
                    String::from_utf8_lossy(&open),
                );
                self.report(Rule::NotFollowed, message, b.line, column);
                (opens, open)
            }
            _ => (opens, label),
        }
    }

    /// The value of a LinuxCNC o-word label worked out as the line runs (`o#1`, `o[#1+1]`,
    /// `o##2`; [`crate::statement::computed_label`]) where the checker knows the parameters it reads, as
    /// rs274ngc's `read_o` reads it (`read_integer_value`, before it is taken as an
    /// integer). None for one it does not know (a function's value among them).
    fn linuxcnc_label_value(&self, label: &[u8]) -> Option<f64> {
        self.linuxcnc_value_of(label.get(1..)?)
    }

    /// [`Checker::linuxcnc_label_value`] of the label's value, `expression`.
    pub(super) fn linuxcnc_value_of(&self, expression: &[u8]) -> Option<f64> {
        // `##2`, `#[#2]`: the parameter whose number the value after the `#` is
        if let Some(inner @ [b'#' | b'[', ..]) = expression.strip_prefix(b"#") {
            let n = crate::statement::rs274_integer(self.linuxcnc_value_of(inner)?)?;
            return self
                .constant(format!("#{n}").as_bytes())
                .map(|d| d.to_f64());
        }
        if expression.len() > 200 {
            return None; // (a chain of terms is a tree as deep, walked by recursion)
        }
        let tree = crate::expr::tree(expression).ok()?;
        let param = |p: &[u8]| self.constant(p).map(|d| d.to_f64());
        crate::expr::linuxcnc_value(&tree, expression, &param).ok()?
    }

    /// The value of a LinuxCNC condition (`[#1 LT 3]`, `[[#1 GE 2] AND [#2 EQ 0]]`) where the
    /// checker knows the parameters it reads: [`Checker::linuxcnc_value_of`] with rs274ngc's
    /// comparisons and logical operators (interp_execute.cc `execute_binary2`, 1.0 for true
    /// and 0.0 for false; interp_internal.cc `precedence`: `AND OR XOR` below `EQ NE GT GE
    /// LT LE`, below `+ - * / MOD **`, each level from the left). Split at the last operator
    /// of the lowest level outside brackets, each side worked out alone. A comparison of two
    /// values less than 1.1e-4 apart and not equal is not known: LinuxCNC 2.9 (`rs274 -g`)
    /// takes values 0.0001 apart as equal and compares GE and LE exactly, later versions use
    /// 1e-6 and compare GE and LE within it (commit 014777a, interp_internal.hh
    /// `TOLERANCE_EQUAL`). None for anything else it cannot work out (a function, MOD, `**`,
    /// a word it does not know).
    #[inline(never)]
    fn linuxcnc_condition_value(&self, expression: &[u8]) -> Option<f64> {
        linuxcnc_condition_of(expression, &|e| self.linuxcnc_value_of(e))
    }

    /// A LinuxCNC call whose label is worked out as it runs (`o#1 call`) from a value the
    /// checker knows holds a fraction (`#1=100.5`, `o[100.5] call`, `o100.5 call`): rs274
    /// stops there, "Non integer value for integer" (`read_o` reads the label as an integer;
    /// `rs274 -g`; review 45, finding L2; review 47, F3).
    #[cold]
    #[inline(never)]
    fn linuxcnc_fractional_label(
        &mut self,
        label: &[u8],
        keyword: &[u8],
        line: usize,
        column: usize,
    ) {
        if self.linuxcnc_fraction_said {
            return; // (rs274 stops at the first)
        }
        let Some(value) = self.linuxcnc_label_value(label) else {
            return;
        };
        if crate::statement::rs274_integer(value).is_some() {
            return;
        }
        self.linuxcnc_fraction_said = true;
        let message = format!(
            "Non integer value for integer (rs274ngc): the label of {} {} is {value}, \
             and an o-word's number must be a whole number",
            String::from_utf8_lossy(label),
            String::from_utf8_lossy(keyword)
        );
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// LinuxCNC: a definition's body reads a local named parameter (`#<zz>`, not a global
    /// `#<_zz>`) that no line of the body, nor a word before it in its line, assigns: rs274
    /// keeps local named parameters per call level (interp_namedparams.cc; LinuxCNC O-codes,
    /// "named parameters are local to the scope"), so the caller's `#<zz>` is not visible
    /// in the body and the call fails, "Named parameter #<zz> not defined" (`rs274 -g`; review
    /// 38, finding 9). Kept at the body's first such read, said by
    /// [`Checker::linuxcnc_locals_ended`] where the file calls the definition (a remap's body,
    /// whose locals the remapped block's words give, is called by no `o<name> call`). A read
    /// inside a condition or loop of the body is not judged (it may not run), its assignments
    /// are taken as made; the calls of the file's lines, body or not, are noted here.
    fn linuxcnc_body_locals(&mut self, b: &BlockView<'_>, statement: Option<&(bool, Vec<u8>)>) {
        for &(column, kind, text) in b.statements {
            let Some(keyword) = crate::statement::o_keyword(text) else {
                continue;
            };
            let label = self.linuxcnc_call_label(text);
            // (read_o reads the label of every o-word line, whatever its keyword: `o100.5 if`
            // and `o100.5 sub` stop rs274 at their line; review 48, F5)
            if crate::statement::computed_label(&label) {
                self.linuxcnc_fractional_label(&label, &keyword, b.line, column);
            }
            // (a call in the main program where it never runs calls nothing: review 51, F4)
            if kind == Kind::Call
                && keyword == b"call"
                && (self.open_definition.is_some() || !self.linuxcnc_dead())
            {
                self.linuxcnc_calls.insert(label);
            }
        }
        if let Some((true, _)) = statement {
            if self.open_definition.is_none() {
                self.linuxcnc_body_named.clear();
            }
            return;
        }
        let Some((_, _, label)) = &self.open_definition else {
            return;
        };
        let label = label.clone();
        // (not after a return outside the body's conditions and loops: the lines after it
        // never run, their conditions not either; review 51, F2)
        let judge =
            self.linuxcnc_definition_flow.is_empty() && !self.linuxcnc_body_distance.returned;
        let said = self.linuxcnc_body_unassigned.iter().any(|e| e.0 == label);
        let mut first: Option<(usize, Vec<u8>)> = None;
        for w in b.words {
            if w.expression.is_empty() {
                continue;
            }
            let mut reads = w.expression;
            let mut assigns = None;
            if w.letter == b'#' && w.expression.first() == Some(&b'<') {
                if let Some(close) = w.expression.iter().position(|&c| c == b'>') {
                    assigns = Some(super::params::named_parameter(&w.expression[1..close]));
                    reads = &w.expression[close + 1..];
                }
            }
            // rs274 creates an assignment's target when it reads it, before the value
            // (interp_read.cc `read_named_parameter_setting` -> `add_named_param`): the
            // value's own read of it finds it (`#<x> = [#<x> + 1]`, 0 + 1), as a later
            // setting's of the line does; one before it on the line does not (issue 32,
            // review 39 finding 6; rs274 -g in tests/test_linuxcnc_locals.py)
            if let Some(name) = assigns {
                self.linuxcnc_body_named.insert(name);
            }
            if first.is_none() {
                first = body_unassigned(reads, &self.linuxcnc_body_named).map(|n| (w.column, n));
            }
        }
        for &(column, kind, text) in b.statements {
            if first.is_none() && matches!(kind, Kind::Flow | Kind::Call | Kind::Definition) {
                // (an `o<name> endsub [#<v>]`'s value, a condition's, a call's arguments)
                // (past a label `o<name>`, whose name is no read; `o1` has no `#<`)
                let text = match text.get(1..) {
                    Some(t) if t.first() == Some(&b'<') => t
                        .iter()
                        .position(|&c| c == b'>')
                        .map_or(t, |at| &t[at + 1..]),
                    _ => text,
                };
                first = body_unassigned(text, &self.linuxcnc_body_named).map(|n| (column, n));
            }
        }
        if let Some((column, name)) = first.filter(|_| judge && !said) {
            self.linuxcnc_body_unassigned
                .push((label, b.line, column, name));
        }
    }

    /// The reads [`Checker::linuxcnc_body_locals`] kept, said (TG412) for each definition an
    /// `o<name> call` of the file calls; then forgotten, with the calls.
    pub(super) fn linuxcnc_locals_ended(&mut self) {
        let kept = std::mem::take(&mut self.linuxcnc_body_unassigned);
        for (label, line, column, name) in kept {
            if !self.linuxcnc_calls.contains(&label) {
                continue;
            }
            let (name, label) = (
                String::from_utf8_lossy(&name),
                String::from_utf8_lossy(&label),
            );
            let message = format!(
                "Named parameter {name}> not defined (rs274ngc) when {label} is called: no \
                 line of its body assigns it before, and a local named parameter is local to \
                 its call level, so the caller's {name}> is not visible in the body (a global, \
                 #<_name>, is)"
            );
            self.report(Rule::LinuxCncRefuses, message, line, column);
        }
        self.linuxcnc_calls.clear();
        self.linuxcnc_body_named.clear();
    }

    /// LinuxCNC: whether the block with an M word ends the program (`ends`: by the values the
    /// checker read for its M words). rs274 reads an M value as a number, a parameter or an
    /// expression, so `M#<two>` and `M[1+1]` end it as `M2` does: said to the reading's end
    /// ([`dialect::ReadingEnd::ended_at`]), whose lines after it are TG117's, as after `M2`.
    /// A block delete's `/M2` ends it only with the switch off; with it on rs274 reads on and
    /// runs the lines after it (`rs274 -b`): no end here, the lines after it checked as run,
    /// and it counts as the program's end for TG114 alone (review 38, finding 8).
    #[inline(never)]
    pub(super) fn linuxcnc_end(&mut self, b: &BlockView<'_>, ends: bool) -> bool {
        if !ends {
            return false;
        }
        if b.skip {
            self.skipped_end = true;
            return false;
        }
        self.reading_end.ended_at(b.line);
        true
    }

    /// LinuxCNC: whether an M word of block `b` written as a parameter or an expression is
    /// M2 or M30 by the values the checker knows -- asked before the block's assignments are
    /// made, as rs274 reads every word of a line with the values from before it (RS274/NGC
    /// 3.0, 3.2.1: parameters set on a line take effect after it; `rs274 -g` reads `#1=5` ...
    /// `#1=2 M#1` as M5 and runs on; review 48, F8).
    pub(super) fn linuxcnc_m_ends(&self, b: &BlockView<'_>) -> bool {
        b.words.iter().any(|w| {
            w.letter == b'M'
                && !w.expression.is_empty()
                && matches!(self.linuxcnc_m_number(w), Some(2 | 30))
        })
    }

    /// LinuxCNC: an M99 of the main program, outside any definition and before its end: rs274
    /// 2.9 reads it as the end of an endless main program (interp_convert.cc `convert_stop`:
    /// with no subprogram to return to, "M99 main program endless loop", which loops back to
    /// the file's start under task's `loop_on_main_m99` and ends the program as M2 does
    /// elsewhere, `rs274 -g` among them): no line after it runs. A FANUC-style `O300` ...
    /// `M99` written before the main program runs inline, and its M99 ends the program
    /// (`rs274 -g` of `O300` / `G0 X10` / `M99` / `G21 G90` / `G0 X0 Y0` / `M98 P300` / `M2`
    /// runs the X10 alone).
    /// The line is kept for TG117's message ([`Checker::never_read`]).
    pub(super) fn linuxcnc_main_m99(&mut self, b: &BlockView<'_>) -> bool {
        let ends = self.open_definition.is_none()
            && !self.main_ended
            && b.words
                .iter()
                .any(|w| w.letter == b'M' && self.linuxcnc_m_number(w) == Some(99));
        if ends {
            self.linuxcnc_m99_end = b.line;
        }
        ends
    }

    /// LinuxCNC: the number of M word `w` as rs274 reads it -- a number, a parameter or an
    /// expression (interp_read.cc `read_m`, `read_integer_value`: `M#<two>` and `M[1+1]` are
    /// M2) -- where the checker knows its value, by the rule every reading's end follows
    /// ([`dialect::linuxcnc_m_number`]). None for a value it does not know or no integer.
    pub(super) fn linuxcnc_m_number(&self, w: &Word<'_>) -> Option<i64> {
        let value = if w.expression.is_empty() {
            w.number
        } else {
            w.expression
        };
        let param = |p: &[u8]| self.constant(p).map(|d| d.to_f64());
        dialect::linuxcnc_m_number(value, &param)
    }

    /// TG412: LinuxCNC's main program reads a local named parameter (`#<name>`) that no line
    /// before it, nor a word before it in its line, assigns (interp_namedparams.cc: "Named
    /// parameter #<nope> not defined"; rs274 adds an assignment's name when it reads it, so
    /// `#<x> = [#<x> + 1]` runs and `G0 X#<x> #<x> = 1` does not). Followed in the main
    /// program's lines in their order, not through its flow: an assignment in a branch that
    /// does not run counts as made (rs274 refuses `o1 if [0]` / `#<v> = 1` / `o1 endif` /
    /// `G0 X#<v>`, tapegate does not). Not judged: a global (`#<_name>`, of which rs274
    /// predefines many: `#<_x>`, `#<_metric>`, `#<_ini[..]>`), a read inside `EXISTS[..]`, a
    /// comment's (`(DEBUG, #<x>)`), a subroutine's body, whose locals a remap's words or
    /// its own lines give, and a read inside an o-word condition or loop (`judge` false:
    /// the line may not run, or a loop's earlier pass may have assigned it; its assignments
    /// are taken all the same).
    #[inline(never)]
    fn linuxcnc_named_reads(
        &mut self,
        b: &BlockView<'_>,
        judge: bool,
        walks: &[ExpressionWalk; WALKED],
    ) {
        let mut undefined: Option<(Vec<u8>, usize)> = None;
        for (i, w) in b.words.iter().enumerate() {
            if w.expression.is_empty() {
                continue;
            }
            let mut reads = w.expression;
            if w.letter == b'#' {
                // `#<name> = ...`: the name is defined from here, its own value included
                if let Some(close) = w.expression.iter().position(|&c| c == b'>') {
                    if w.expression.first() == Some(&b'<') {
                        let name = super::params::named_parameter(&w.expression[1..close]);
                        reads = &w.expression[close + 1..];
                        self.linuxcnc_named.insert(name);
                        if undefined.is_none() {
                            undefined = self.linuxcnc_undefined_read(reads, w.column);
                        }
                        continue;
                    }
                }
            }
            if undefined.is_none() {
                // (the word's whole expression: its names as the walk found them)
                undefined = match walks.get(i) {
                    Some(k) if k.plain => {
                        let found = k.names[..usize::from(k.count)].iter().find_map(|&(s, c)| {
                            self.linuxcnc_unknown_name(reads, usize::from(s), usize::from(c))
                        });
                        let found = found.map(|name| (name, w.column));
                        #[cfg(debug_assertions)]
                        {
                            let seen = self.linuxcnc_named_seen.clone();
                            let short = self.linuxcnc_short_seen;
                            let full = self.linuxcnc_undefined_read(reads, w.column);
                            self.linuxcnc_named_seen = seen;
                            self.linuxcnc_short_seen = short;
                            debug_assert_eq!(found, full, "line {}", b.line);
                        }
                        found
                    }
                    _ => self.linuxcnc_undefined_read(reads, w.column),
                };
            }
        }
        for &(column, kind, text) in b.statements {
            if undefined.is_none() && matches!(kind, Kind::Flow | Kind::Call) {
                undefined = self.linuxcnc_undefined_read(text, column);
            }
        }
        if let Some((name, column)) = undefined.filter(|_| judge) {
            let name = String::from_utf8_lossy(&name);
            let message = format!(
                "Named parameter {name}> not defined (rs274ngc): no line before it assigns it \
                 (a local named parameter has no value until the program sets one)"
            );
            self.report(Rule::LinuxCncRefuses, message, b.line, column);
        }
    }

    /// LinuxCNC: the spindle speed after an `o.. endif` whose branches provably set none is
    /// the speed before its `if` (review 21: the G95 refusal with no spindle speed was lost
    /// after any condition, as after a call). Provably: no line inside has an S word, an M2,
    /// M30, M98 or M99 (or an M code written by an expression), a call, a loop or another
    /// o-word than a nested `if`/`elseif`/`else`/`endif`, nor is one a line the checker
    /// cannot read; otherwise the speed stays unknown after the `endif`, as before. The
    /// speed is given back to the next line (the flow's forgetting of the `endif` line comes
    /// after this), in the main program only (a definition's body runs under its caller's).
    #[inline]
    fn linuxcnc_if_speed(&mut self, b: &BlockView<'_>) {
        // (no speed to give back, no condition open and no o-word: as most of a program's
        // blocks)
        if self.linuxcnc_speed_back.is_none()
            && self.linuxcnc_if_speed.is_empty()
            && b.statements.is_empty()
        {
            return;
        }
        self.linuxcnc_if_speed_read(b);
    }

    /// [`Checker::linuxcnc_if_speed`] of a block after an `endif`, inside a condition or with
    /// an o-word.
    #[inline(never)]
    fn linuxcnc_if_speed_read(&mut self, b: &BlockView<'_>) {
        if let Some((speed, unknown)) = self.linuxcnc_speed_back.take() {
            let state = &mut self.machine.state;
            state.speed = speed;
            if unknown {
                state.unknown |= crate::modal::bit(b'S');
            } else {
                state.unknown &= !crate::modal::bit(b'S');
            }
        }
        // (no condition open and no o-word: a block's words have nothing to mark, as most of
        // a program's blocks)
        if self.open_definition.is_some()
            || (self.linuxcnc_if_speed.is_empty() && b.statements.is_empty())
        {
            return;
        }
        let ends_or_calls = |w: &Word<'_>| {
            let m = std::str::from_utf8(w.number)
                .ok()
                .and_then(|t| t.trim().parse::<f64>().ok());
            !w.expression.is_empty() || m.is_none_or(|m| [2.0, 30.0, 98.0, 99.0].contains(&m))
        };
        let sets = b
            .words
            .iter()
            .any(|w| w.letter == b'S' || w.letter == b'M' && ends_or_calls(w));
        let mut dirty = sets;
        for &(_, kind, text) in b.statements {
            let keyword = crate::statement::o_keyword(text);
            match (kind, keyword.as_deref()) {
                (Kind::Flow, Some(b"if")) => {
                    let state = &self.machine.state;
                    let label = crate::statement::o_label(text);
                    let entry = (label, state.speed, state.is_unknown(b'S'), true);
                    self.linuxcnc_if_speed.push(entry);
                }
                (Kind::Flow, Some(b"else" | b"elseif")) => {}
                (Kind::Flow, Some(b"endif")) => {
                    let label = crate::statement::o_label(text);
                    match self.linuxcnc_if_speed.pop() {
                        Some((open, speed, unknown, true)) if open == label => {
                            self.linuxcnc_speed_back = Some((speed, unknown));
                        }
                        // (an endif of another label: rs274 refuses the nesting; nothing given)
                        Some((open, ..)) if open != label => self.linuxcnc_if_speed.clear(),
                        _ => {}
                    }
                }
                _ => dirty = true,
            }
        }
        if dirty {
            for open in &mut self.linuxcnc_if_speed {
                open.3 = false;
            }
        }
    }

    /// LinuxCNC: whether the line in hand runs whenever the program runs to it: outside a
    /// subroutine's definition (rs274 runs its body only when called), every o-word condition
    /// or loop of the main program open is one whose lines the checker knows run
    /// ([`OpenBlock::runs`]: `o1 if [1]`, `o1 repeat [2]`, a `do`, nested in one another in
    /// any way; none open at the top). Only there are the refusals rs274 makes while it runs a
    /// line judged ([`Checker::linuxcnc_open_flow`]; `rs274 -g` refuses `M[3.5]` after `o1
    /// if [1]`: "Non integer value for integer"; review 51, F11, F13; review 52, F4).
    pub(super) fn linuxcnc_runs_surely(&self) -> bool {
        self.open_definition.is_none() && self.linuxcnc_open_known()
    }

    /// LinuxCNC: every condition or loop of the main program open is known to run
    /// ([`OpenBlock::runs`]), none open included.
    fn linuxcnc_open_known(&self) -> bool {
        self.linuxcnc_open_at.iter().all(|e| e.runs == Some(true))
    }

    /// LinuxCNC: whether the block is the o-word line that opened the main program's
    /// innermost condition or loop, or began its branch, where the checker knows whether its
    /// lines run and every block around it runs ([`Checker::linuxcnc_runs_surely`]): no
    /// jump, as rs274 runs the line after it next, in the state the program left (`o1 if
    /// [1]` / `X2 Y2 P1` under G0 is refused: "P word with no G2 G3 G4 ... to use it"), or
    /// skips to the next o-word line of its label, running nothing between (one known not
    /// to, outside a block delete: the state stays for that line). The lines after the
    /// block's closing line (an `endwhile` going back) are read as after a jump, as before.
    pub(super) fn linuxcnc_opened_running(&self, b: &BlockView<'_>) -> bool {
        let Some((last, around)) = self.linuxcnc_open_at.split_last() else {
            return false;
        };
        self.config.family == Family::LinuxCnc
            && matches!(b.statements, [(_, Kind::Flow, _)])
            && last.branch == b.line
            && (last.runs == Some(true) || last.runs == Some(false) && !b.skip)
            && around.iter().all(|e| e.runs == Some(true))
    }

    /// LinuxCNC: whether the line in hand of the main program is one rs274 never runs: in
    /// the skip of a block known not to run ([`Checker::linuxcnc_skipping`]: `o1 if [0]`,
    /// `o1 repeat [0]`, the `else` after a branch that ran), or after the program's end
    /// ([`Checker::main_ended`]: an M2/M30 that surely runs, a call of a body that ends the
    /// program, the rest of a branch after its M2). No refusal rs274 makes while it runs a
    /// line is said there, and no state it changes as it runs a line follows it: the
    /// distance mode, M70-M73, a call's body (review 51, F1, F4).
    pub(super) fn linuxcnc_dead(&self) -> bool {
        self.linuxcnc_skipping.is_some() || self.main_ended()
    }

    /// Whether the main program has ended where the line in hand stands, for the rules that
    /// judge its lines up to its end: an M02/M30 that surely runs before it, or on LinuxCNC
    /// one inside a condition or loop still open (the rest of its branch never runs after
    /// it, and the lines after the block run only where it did not: judged again there;
    /// review 19).
    pub(super) fn main_ended(&self) -> bool {
        self.surely_ended
            || self
                .linuxcnc_end_depth
                .is_some_and(|d| self.linuxcnc_open_flow.len() >= d)
    }

    /// LinuxCNC: an o-word condition or loop of the main program, outside a definition
    /// ([`Checker::linuxcnc_open_flow`]). An `else`/`elseif` runs where its `if` branch did
    /// not: an M2/M30 in that branch (at the label's depth or deeper) no longer ends the lines
    /// (review 20). An `endif` whose `if` has an `else` and whose every branch ended in an
    /// M2/M30 ends the main program where the `if` stands: rs274 reads no line after it
    /// (issue 32; interp_o_word.cc runs one branch, and each ends the program). What the
    /// checker knows of the run of the blocks open follows ([`OpenBlock`]): a block opened,
    /// a branch begun, blocks closed (`skip_ended`: the skip of a branch known not to run,
    /// of this line's label, ended here). Returns whether the line is an `else`/`elseif`
    /// whose branch before it surely ran (known true), so that rs274 skips from it to the
    /// `endif` (review 51, F4), and whether it opens a block or begins a branch known not to
    /// run where the program reaches it (review 52, F4).
    fn linuxcnc_main_flow(
        &mut self,
        text: &[u8],
        (line, column): (usize, usize),
        skip_ended: bool,
    ) -> FlowStep {
        let keyword = crate::statement::o_keyword(text);
        // (whether the innermost block's lines ran up to this one, one after the other: no
        // o-word line since it opened; and whether its branch in hand runs)
        let last = self.linuxcnc_open_at.last();
        let ran = last.filter(|e| e.straight).and_then(|e| e.runs);
        let branch_ran = last.and_then(|e| e.runs);
        let branch_began = last.is_some_and(|e| e.runs == Some(true) || e.called);
        for e in &mut self.linuxcnc_open_at {
            e.straight = false;
        }
        // (a computed label, `o#1 endwhile`, by its value where rs274 reads the line: matched
        // to the `o5 while` of #1=5, `rs274 -g`)
        let label = self.linuxcnc_closing_label(text, keyword.as_deref(), ran, (line, column));
        let branch_ended = |at: usize| self.linuxcnc_end_depth.is_some_and(|d| d > at);
        let mut all_ended = None;
        let switched = linuxcnc_branch_switch(&self.linuxcnc_open_flow, text, &label);
        let innermost = switched.is_some_and(|at| at + 1 == self.linuxcnc_open_flow.len());
        let other_branch = innermost && branch_began && !self.main_ended();
        if let Some(at) = switched {
            let ended = branch_ended(at);
            let is_else = keyword.as_deref() == Some(b"else".as_slice());
            if let Some(entry) = self.linuxcnc_if_ends.iter_mut().rfind(|e| e.0 == at) {
                entry.1 &= ended;
                entry.2 |= is_else;
            }
            if ended {
                self.linuxcnc_end_depth = None;
            }
        } else if keyword.as_deref() == Some(b"endif".as_slice()) {
            if let Some(at) = self.linuxcnc_open_flow.iter().rposition(|l| *l == label) {
                let ended = branch_ended(at);
                all_ended = self
                    .linuxcnc_if_ends
                    .iter()
                    .rfind(|e| e.0 == at)
                    .filter(|e| e.1 && e.2 && ended)
                    .map(|e| e.0);
            }
        }
        let depth = self.linuxcnc_open_flow.len();
        let loop_at = self.linuxcnc_open_flow.iter().rposition(|l| *l == label);
        self.linuxcnc_label_recorded(text, keyword.as_deref(), &label, (line, column));
        linuxcnc_flow_of(&mut self.linuxcnc_open_flow, text, label);
        let open = self.linuxcnc_open_flow.len();
        let mut dead = false;
        if open > depth {
            let opened = self.linuxcnc_opening(text, line);
            dead = opened.runs == Some(false);
            self.linuxcnc_open_at.push(opened);
        } else if open < depth {
            self.linuxcnc_blocks_closed(text, open);
        } else if let Some(at) = switched {
            let before_false = skip_ended && branch_ran == Some(false);
            dead = self.linuxcnc_branch(text, line, at, other_branch, before_false);
        } else if !matches!(keyword.as_deref(), Some(b"break" | b"continue")) {
            // (another o-word line: which lines run after it is not followed; a break or
            // continue, Checker::linuxcnc_loop_leave)
            for e in &mut self.linuxcnc_open_at {
                e.runs = None;
                e.called = false;
            }
        }
        if open == 0 {
            self.linuxcnc_flow_assigned.clear();
        }
        // (the `else` after a branch that surely ran never runs: the mode that branch wrote
        // is the mode after the `endif`)
        self.linuxcnc_distance_scope(open, switched.filter(|_| !other_branch));
        let mut blocks = std::mem::take(&mut self.linuxcnc_plane_blocks);
        // (an `elseif` whose condition is surely true, `elseif [1]`, closes its block as an
        // `else` does: every way through it runs one of its branches, review 63, F4)
        let is_else = match keyword.as_deref() {
            Some(b"else") => true,
            Some(b"elseif") => {
                let (_, condition) = o_keyword_condition(text);
                !condition.contains(&b'#')
                    && self
                        .linuxcnc_condition_value(condition)
                        .is_some_and(|v| v != 0.0)
            }
            _ => false,
        };
        let step = PlaneStep {
            depth,
            open,
            switched,
            is_else,
            main: true,
            ran: branch_ran,
            taken: other_branch,
            leaves: matches!(keyword.as_deref(), Some(b"break" | b"continue")),
            loop_at,
        };
        self.linuxcnc_plane_flow(&mut blocks, step);
        self.linuxcnc_plane_blocks = blocks;
        self.linuxcnc_if_ends.retain(|e| e.0 < open);
        if keyword.as_deref() == Some(b"if".as_slice()) && open > depth {
            self.linuxcnc_if_ends.push((depth, true, false));
        }
        if let Some(at) = all_ended {
            self.linuxcnc_end_depth = Some(self.linuxcnc_end_depth.map_or(at, |d| d.min(at)));
        }
        FlowStep { other_branch, dead }
    }

    /// LinuxCNC: the block the main program's o-word `text` on `line` opens. Where every
    /// block around it is known to run (its opening runs surely), before the program's end
    /// and outside a skip, whether its lines run is worked out
    /// ([`Checker::linuxcnc_body_runs`]) from the values the program set before it, its
    /// first run's; a condition that reads a parameter makes every loop around it one whose
    /// turns may differ ([`OpenBlock::varies`]).
    fn linuxcnc_opening(&mut self, text: &[u8], line: usize) -> OpenBlock {
        let (keyword, condition) = o_keyword_condition(text);
        let known = self.linuxcnc_skipping.is_none()
            && !self.main_ended()
            && self.linuxcnc_open_at.iter().all(|e| e.runs == Some(true));
        let runs = known.then(|| self.linuxcnc_body_runs(text)).flatten();
        if runs.is_some() && condition.contains(&b'#') {
            self.linuxcnc_turns_vary();
        }
        let looped = (keyword != b"if").then(|| {
            let again = (keyword == b"repeat")
                .then(|| self.linuxcnc_condition_value(condition))
                .flatten()
                .map(|v| v.round_ties_even() >= 2.0);
            (text.to_vec(), again)
        });
        OpenBlock {
            written: crate::statement::o_label(text),
            line,
            runs,
            branch: line,
            straight: true,
            looped,
            varies: false,
            called: false,
        }
    }

    /// LinuxCNC: an `else`/`elseif` (`text`, on `line`) of the `if` open at `at`: the branch
    /// it begins runs where every branch before it is known not to run (`before_false`) and
    /// the blocks around the `if` are known to run -- an `else` surely, an `elseif` as its
    /// condition is known; it does not where the branch before surely ran (`other_branch`).
    /// Returns whether it begins a branch known not to run (not that `else`, whose skip goes
    /// to the `endif`). An `else` of an `if` not the innermost block open (which rs274
    /// refuses) leaves the run of the blocks from it inwards not known.
    fn linuxcnc_branch(
        &mut self,
        text: &[u8],
        line: usize,
        at: usize,
        other_branch: bool,
        before_false: bool,
    ) -> bool {
        if at + 1 != self.linuxcnc_open_at.len() {
            for e in &mut self.linuxcnc_open_at[at..] {
                e.runs = None;
                e.called = false;
            }
            return false;
        }
        let around = !self.main_ended()
            && self.linuxcnc_open_at[..at]
                .iter()
                .all(|e| e.runs == Some(true));
        let runs = if other_branch {
            Some(false)
        } else if before_false && around {
            let (keyword, condition) = o_keyword_condition(text);
            if keyword == b"else" {
                Some(true)
            } else {
                let runs = self.linuxcnc_condition_value(condition).map(|v| v != 0.0);
                if runs.is_some() && condition.contains(&b'#') {
                    self.linuxcnc_turns_vary();
                }
                runs
            }
        } else {
            None
        };
        let e = &mut self.linuxcnc_open_at[at];
        e.runs = runs;
        e.called = false;
        e.branch = line;
        runs == Some(false) && !other_branch
    }

    /// LinuxCNC: the blocks open from `open` on closed by the o-word line `text` (an
    /// `endif`, `endwhile`, `endrepeat`, a `do`'s `while`). A loop whose turns may differ
    /// ([`OpenBlock::varies`]) and that may turn again -- a `repeat` of 2 or more, a
    /// `while` condition not known false at its end, a `do`'s closing condition not known
    /// false -- leaves the distance mode and what M70/M73 saved not known: the checker read
    /// its first turn only. The blocks around it are left as they were: the lines after it
    /// run where they are reached.
    fn linuxcnc_blocks_closed(&mut self, text: &[u8], open: usize) {
        let closed = self.linuxcnc_open_at.split_off(open);
        let again = |c: &Self, e: &OpenBlock| -> Option<bool> {
            let (opening, condition) = o_keyword_condition(&e.looped.as_ref()?.0);
            match opening.as_slice() {
                b"repeat" => e.looped.as_ref()?.1,
                b"while" => c.linuxcnc_condition_value(condition).map(|v| v != 0.0),
                _ => {
                    let (keyword, condition) = o_keyword_condition(text);
                    (keyword == b"while")
                        .then(|| c.linuxcnc_condition_value(condition))
                        .flatten()
                        .map(|v| v != 0.0)
                }
            }
        };
        let unsure = closed
            .iter()
            .any(|e| e.varies && again(self, e) != Some(false));
        if unsure {
            self.linuxcnc_distance_unsure = true;
            self.linuxcnc_distance_from = None;
            self.linuxcnc_saved = Saved::Maybe;
        }
    }

    /// LinuxCNC: a block opened or branched on a condition read from parameters, worked out
    /// for the first run: every loop open around it may run other lines on a later turn.
    fn linuxcnc_turns_vary(&mut self) {
        for e in &mut self.linuxcnc_open_at {
            e.varies |= e.looped.is_some();
        }
    }

    /// LinuxCNC: whether the o-word statement at `column` of block `b` stands after a comment
    /// or a word other than a line number (`(c) o5 if [1]`, `#1=1 o5 if [1]`), which rs274
    /// does not read as an o-word: `read_items` (interp_read.cc) reads one only at the start
    /// of the line, after a block delete `/` and an N word, and elsewhere refuses its `o`,
    /// "Bad character 'o' used"; after the o-word's label, keyword and brackets only a
    /// comment may follow, else "Unexpected character after O-word". Either refused (TG412)
    /// where the line surely runs (the main program's, no condition or loop open or only one
    /// known to run, [`Checker::linuxcnc_runs_surely`]; no block delete): rs274 reads no line
    /// of a condition it skips but its o-words (`rs274 -g`; review 49a, F8; review 51, F11).
    #[inline(never)]
    fn linuxcnc_o_misplaced(&mut self, b: &BlockView<'_>, column: usize) -> bool {
        let before = if b.comments.iter().any(|c| c.0 < column) {
            Some("a comment")
        } else {
            let word = b
                .words
                .iter()
                .any(|w| w.column < column && w.letter != b'N');
            word.then_some("a word")
        };
        let after = b.words.iter().find(|w| w.column > column);
        if before.is_none() && after.is_none() {
            return false;
        }
        if !b.skip && self.linuxcnc_runs_surely() && !self.main_ended() {
            let shown = |from: usize| {
                let text = b.text.get(from.saturating_sub(1)..).unwrap_or_default();
                String::from_utf8_lossy(text).trim_end().to_owned()
            };
            let (message, at) = match (before, after) {
                (Some(what), _) => (
                    format!(
                        "Bad character 'o' used (rs274ngc): rs274 reads an o-word only at the \
                         start of its line (after a block delete / and a line number), and {what} \
                         stands before '{}' (interp_read.cc read_items); write the o-word on a \
                         line of its own",
                        shown(column)
                    ),
                    column,
                ),
                (None, Some(w)) => (
                    format!(
                        "Unexpected character after O-word (rs274ngc): after an o-word's \
                         label, keyword and brackets rs274 reads only a comment on its line, \
                         and '{}' follows (interp_read.cc read_items); write it on a line of \
                         its own",
                        shown(w.column)
                    ),
                    w.column,
                ),
                (None, None) => return false,
            };
            self.report(Rule::LinuxCncRefuses, message, b.line, at);
        }
        before.is_some()
    }

    /// LinuxCNC: a `break` or `continue` of the main program whose label rs274 recorded for
    /// an `if` or a `repeat` (at the top of the main program, where it surely ran), where
    /// rs274 reads the line: where it surely runs (inside that block or after it), or inside
    /// the block of that label, the innermost open, whose opening surely runs and whose
    /// branch in hand rs274 either runs to the line or skips to it -- its condition known,
    /// or no o-word line since the block opened (`o1 if [#5399 GT 1]` / `o1 break`: run
    /// where true, met in the skip to the `endif` where false). rs274 leaves only a `do` or
    /// `while` by them: "5: no matching while/do label: 'o1 continue' (found 'repeat' in line
    /// 3)" (interp_o_word.cc `convert_control_functions`; `rs274 -g`; review 51, F3; review
    /// 52, F9).
    #[inline(never)]
    fn linuxcnc_loop_exit(&mut self, b: &BlockView<'_>, text: &[u8], column: usize) {
        let keyword = crate::statement::o_keyword(text);
        if !matches!(keyword.as_deref(), Some(b"break" | b"continue"))
            || b.skip
            || self.main_ended()
            || self.linuxcnc_labels_named.1
        {
            return;
        }
        let label = self.linuxcnc_call_label(text);
        let bare = bare_label(&label);
        if crate::statement::computed_label(&label) {
            return;
        }
        let Some(&(kind, line, true)) = self.linuxcnc_o_labels.get(&bare) else {
            return;
        };
        let found = match kind {
            b'i' => "if",
            b'r' => "repeat",
            _ => return,
        };
        let reached = if let Some((last, around)) = self.linuxcnc_open_at.split_last() {
            let skipped = self
                .linuxcnc_skipping
                .as_ref()
                .is_some_and(|s| s.0 != label);
            bare_label(&last.written) == bare
                && last.line == line
                && !skipped
                && (last.runs.is_some() || last.straight)
                && around.iter().all(|e| e.runs == Some(true))
        } else {
            false
        };
        if !reached && (!self.linuxcnc_runs_surely() || self.linuxcnc_dead()) {
            return;
        }
        let statement = String::from_utf8_lossy(text.trim_ascii()).into_owned();
        let message = format!(
            "no matching while/do label (rs274ngc): '{statement}' leaves a loop, and its label \
             {} is the {found} of line {line}, no do or while (\"{}: no matching while/do \
             label: '{statement}' (found '{found}' in line {line})\"; interp_o_word.cc \
             convert_control_functions)",
            String::from_utf8_lossy(&label),
            b.line,
        );
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
    }

    /// LinuxCNC: a closing word of the main program (`o2 endif`, `else`, `elseif`,
    /// `endwhile`, `endrepeat`, `break`, `continue`) whose label no o-word line before it
    /// named, where it surely runs (no condition or loop open, or one opened at the top of the
    /// main program whose lines ran up to it; no block delete): rs274 finds no label recorded
    /// and stops, "undefined O-word label" (interp_o_word.cc `convert_control_functions`,
    /// `control_find_oword`; `rs274 -g`; review 49a, F8).
    #[inline(never)]
    fn linuxcnc_undefined_label(&mut self, b: &BlockView<'_>, text: &[u8], column: usize) {
        let keyword = crate::statement::o_keyword(text);
        let closing = matches!(
            keyword.as_deref(),
            Some(
                b"endif"
                    | b"endwhile"
                    | b"endrepeat"
                    | b"else"
                    | b"elseif"
                    | b"break"
                    | b"continue"
            )
        );
        if !closing || b.skip || self.main_ended() || self.linuxcnc_labels_named.1 {
            return;
        }
        let runs = self.linuxcnc_open_known();
        // (a label worked out as the line runs, of a block open: read with the values its
        // block set, Checker::linuxcnc_closing_label)
        let written = crate::statement::computed_label(&crate::statement::o_label(text));
        let label = self.linuxcnc_call_label(text);
        if !runs
            || written && !self.linuxcnc_open_flow.is_empty()
            || crate::statement::computed_label(&label)
            || self.linuxcnc_labels_named.0.contains(&bare_label(&label))
        {
            return;
        }
        let statement = String::from_utf8_lossy(text.trim_ascii()).into_owned();
        let message = format!(
            "undefined O-word label (rs274ngc): '{statement}' closes the label {}, which no \
             o-word line before it names, so rs274 has no condition or loop of it to close \
             (\"{}: undefined O-word label: '{statement}'\"; interp_o_word.cc \
             control_find_oword); close the block with the label it opened with",
            String::from_utf8_lossy(&label),
            b.line,
        );
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
    }

    /// LinuxCNC: the label of the main program's o-word flow statement `text` (`keyword`) as
    /// rs274 reads it where the line runs ([`Checker::linuxcnc_call_label`]). A closing word
    /// whose label is worked out as the line runs (`o#1 endwhile`) is read with the values
    /// in force there (interp_read.cc `read_o`), which the block's own lines may have changed
    /// (review 48, F10: `#1=3` / `o#1 while [1]` / `#1=4` / `o#1 endwhile` is "undefined
    /// O-word label"). Where no parameter its label reads was set since the block it closes
    /// opened (nor a call made), its value is that block's, which it closes; where one was
    /// and the checker knows the new value, refused where the block's lines surely ran up to
    /// it (it opened at the top of the main program with a condition known true, `ran` Some
    /// true, and no o-word line came since) and no block of that label was ever recorded;
    /// where they surely did not (a condition known false, `ran` Some false), none of them
    /// set anything and it closes the block; else said (TG140) and taken as closing the block
    /// of its label as written.
    fn linuxcnc_closing_label(
        &mut self,
        text: &[u8],
        keyword: Option<&[u8]>,
        ran: Option<bool>,
        (line, column): (usize, usize),
    ) -> Vec<u8> {
        let label = self.linuxcnc_call_label(text);
        let Some(keyword) = keyword else {
            return label;
        };
        let closing = matches!(
            keyword,
            b"endif" | b"endwhile" | b"endrepeat" | b"else" | b"elseif" | b"break" | b"continue"
        );
        if !closing && keyword != b"while" || self.linuxcnc_open_flow.contains(&label) {
            return label;
        }
        let written = crate::statement::o_label(text);
        if !crate::statement::computed_label(&written) {
            return label;
        }
        let Some(at) = self
            .linuxcnc_open_at
            .iter()
            .rposition(|e| e.written == written)
        else {
            return label;
        };
        let opened = self.linuxcnc_open_at[at].line;
        // (the two lists open and close together: linuxcnc_main_flow)
        debug_assert_eq!(self.linuxcnc_open_at.len(), self.linuxcnc_open_flow.len());
        let Some(open) = self.linuxcnc_open_flow.get(at).cloned() else {
            return label;
        };
        let reads = label_reads(&written);
        let set = self.linuxcnc_flow_assigned.iter().find(|(l, key)| {
            *l > opened && (key.is_empty() || reads.as_ref().is_none_or(|r| r.contains(key)))
        });
        let Some(&(set_line, _)) = set else {
            // (nothing it reads set since: the value of the block's own line)
            return open;
        };
        if !closing {
            return label; // (a `while` of another value opens a loop)
        }
        let innermost = at + 1 == self.linuxcnc_open_flow.len();
        if innermost && ran == Some(false) {
            return open; // (the lines that set it never ran: review 49a, F2)
        }
        let runs = ran == Some(true);
        let shown = |l: &[u8]| String::from_utf8_lossy(l).into_owned();
        let statement = shown(text.trim_ascii());
        let known = !crate::statement::computed_label(&label);
        let bare = bare_label(&label);
        if known
            && runs
            && innermost
            && at == 0
            && !self.main_ended()
            && !self.linuxcnc_o_labels.contains_key(&bare)
        {
            let message = format!(
                "undefined O-word label (rs274ngc): '{statement}' is read with the values of \
                 its line, and line {set_line} inside the block of {} (line {opened}), which \
                 runs, set what its label reads: it is {} there, a label no condition or loop \
                 of the program has (interp_read.cc read_o works the label out where it reads \
                 the line); close the block with the label it opened with",
                shown(&open),
                shown(&label),
            );
            self.report(Rule::LinuxCncRefuses, message, line, column);
            return label;
        }
        let message = format!(
            "{statement}: its label is worked out as the line runs (interp_read.cc read_o), \
             and line {set_line} inside the block it closes set what it reads; taken as \
             closing the block {} opened on line {opened}, which rs274 does only where the value is still that \
             label's (else \"undefined O-word label\")",
            shown(&open)
        );
        self.report(Rule::NotFollowed, message, line, column);
        open
    }

    /// TG412: a subroutine defined in the body of a loop of the main program's top that runs
    /// its body a second time. rs274 records a definition where it first reads it and refuses
    /// to read the same definition line again (interp_o_word.cc `control_save_offset`: "File:
    /// ... line:5 sub: o|s| found in illegal location", `rs274 -g`; `o1 repeat [2]` / `o<s>
    /// sub` ... `o<s> endsub` / `o1 endrepeat`). Judged at the loop's closing line where the
    /// body's lines up to it surely ran ([`Checker::linuxcnc_runs_surely`]: no other o-word
    /// line, no end between, no call but a `repeat`'s of [`Checker::linuxcnc_loop_call`]) and
    /// a second turn is known: a `repeat` count that
    /// rounds to 2 or more where it opened, a `while` condition or a `do`'s closing `while`
    /// condition known true at the closing line. A `while` whose condition is false there
    /// (one turn), a body that may not run, or a condition not known: nothing said.
    #[inline(never)]
    fn linuxcnc_loop_turns(&mut self, text: &[u8], top: bool, ran: bool) {
        let (keyword, condition) = o_keyword_condition(text);
        let open = self.linuxcnc_open_flow.len();
        if top {
            self.linuxcnc_loop_defs = None;
            let known = matches!(self.linuxcnc_open_at.as_slice(), [e] if e.runs == Some(true));
            if open == 1 && known && matches!(keyword.as_slice(), b"repeat" | b"while" | b"do") {
                let twice = (keyword == b"repeat").then(|| {
                    self.linuxcnc_condition_value(condition)
                        .is_some_and(|v| v.round_ties_even() >= 2.0)
                });
                self.linuxcnc_loop_defs = Some(Box::new(LoopDefinitions {
                    opened: text.to_vec(),
                    twice,
                    defs: Vec::new(),
                    sure: true,
                    called: false,
                }));
            }
            return;
        }
        if open != 0 {
            // (another o-word line in the body: which lines run after it is not followed)
            if let Some(defs) = self.linuxcnc_loop_defs.as_mut() {
                defs.sure = false;
            }
            return;
        }
        let Some(defs) = self.linuxcnc_loop_defs.take() else {
            return;
        };
        if !(ran || defs.called) || !defs.sure || self.main_ended() || defs.defs.is_empty() {
            return;
        }
        let (opening, opened_condition) = o_keyword_condition(&defs.opened);
        let true_now = |c: &[u8]| self.linuxcnc_condition_value(c).is_some_and(|v| v != 0.0);
        let again = match opening.as_slice() {
            b"repeat" => defs.twice == Some(true),
            b"while" => true_now(opened_condition),
            _ => keyword == b"while" && true_now(condition),
        };
        if !again {
            return;
        }
        let closing = String::from_utf8_lossy(text).trim().to_owned();
        // (rs274 stops at the first definition it reads again)
        for (name, line, column) in defs.defs.into_iter().take(1) {
            let bare = bare_label(&name);
            let message = format!(
                "sub: o|{}| found in illegal location (rs274ngc): the loop's '{closing}' runs \
                 its body again, and rs274 reads a definition's line once; define the \
                 subroutine before the loop or after M2",
                String::from_utf8_lossy(&bare),
            );
            self.report(Rule::LinuxCncRefuses, message, line, column);
        }
    }

    /// LinuxCNC: a call in the body of the loop [`Checker::linuxcnc_loop_turns`] follows. A
    /// `repeat`'s turns do not depend on what the call sets: one of a subroutine defined
    /// before it that ends nothing and sets no feed mode (its callees too,
    /// [`Checker::linuxcnc_call_keeps_mode`]) returns to the next line (`o<s> sub` ...
    /// `o<s> endsub` / `o<s> call` in a `repeat [2]`: rs274 refuses the definition's line on
    /// the second turn). Any other call, or a call in a `while` or `do` (whose condition it
    /// may change), leaves the turns not known.
    #[inline(never)]
    fn linuxcnc_loop_call(&mut self, text: &[u8]) {
        let keeps = self.linuxcnc_open_flow.len() == 1 && self.linuxcnc_call_keeps_mode(text);
        if let Some(defs) = self.linuxcnc_loop_defs.as_mut() {
            defs.called = true;
            if !keeps || defs.twice.is_none() {
                defs.sure = false;
            }
        }
    }

    /// LinuxCNC: whether the line in hand opens, inside another block of the main program,
    /// an `if`, `while` or `repeat` whose condition or count reads no parameter and is known
    /// not to run (`o1 if [0]`, `o1 repeat [0.5]`). Whether the blocks around it run or not,
    /// rs274 runs none of its lines: it skips them to the next o-word line of its label
    /// (interp_o_word.cc; `rs274 -g`; review 52, F5). A condition reading a parameter is left
    /// out: inside a loop its value may differ turn to turn.
    fn linuxcnc_nested_dead(&self, text: &[u8], line: usize) -> bool {
        self.linuxcnc_skipping.is_none()
            && !self.main_ended()
            && self.linuxcnc_open_at.len() > 1
            && self.linuxcnc_open_at.last().is_some_and(|e| e.line == line)
            && !o_keyword_condition(text).1.contains(&b'#')
            && self.linuxcnc_body_runs(text) == Some(false)
    }

    /// LinuxCNC: a `break` or `continue` (`text` on `line`, its label `label`) of a loop (`do`
    /// or `while`) open around it: rs274 goes from it to the loop's closing line (or its top)
    /// and runs no line after it up to there (interp_o_word.cc `convert_control_functions`;
    /// `rs274 -g`; review 52, F5). Where every block inside the loop is known to run (the
    /// loop the innermost block, or the `break` in an `if [1]` of its body), it is taken
    /// wherever it is reached: the lines up to the loop's next o-word line are skipped. Inside
    /// a block not known to run, the rest of that block's branch is skipped (up to its next
    /// o-word line), and the loop's lines after the block, and the blocks' from the loop
    /// inwards, are not known to run: it may have left (review 52, F4).
    fn linuxcnc_loop_leave(&mut self, text: &[u8], label: &[u8], line: usize) {
        if self.main_ended()
            || !matches!(
                crate::statement::o_keyword(text).as_deref(),
                Some(b"break" | b"continue")
            )
            || crate::statement::computed_label(label)
        {
            return;
        }
        let bare = bare_label(label);
        let Some(at) = self
            .linuxcnc_open_at
            .iter()
            .rposition(|e| bare_label(&e.written) == bare)
        else {
            return;
        };
        let opened = self.linuxcnc_open_at[at].line;
        let a_loop = self
            .linuxcnc_o_labels
            .get(&bare)
            .is_some_and(|&(kind, first, _)| first == opened && matches!(kind, b'w' | b'd'));
        if !a_loop {
            return;
        }
        if self.linuxcnc_open_at[at + 1..]
            .iter()
            .all(|e| e.runs == Some(true))
        {
            self.linuxcnc_skipping = Some((label.to_vec(), line, false));
            return;
        }
        for e in &mut self.linuxcnc_open_at[at..] {
            e.runs = None;
            e.called = false;
        }
        if let Some(innermost) = self.linuxcnc_open_flow.last() {
            self.linuxcnc_skipping = Some((innermost.clone(), line, false));
        }
    }

    /// LinuxCNC: whether the lines of the block the main program's o-word `text` opens run
    /// (as far as the checker reads them in order): a `do` does, an `if` or `while` whose
    /// condition ([`Checker::linuxcnc_condition_value`]), a `repeat` whose count (rounded to
    /// the nearest whole number, half to even: interp_o_word.cc `round_to_int`, `nearbyint`),
    /// is a value the checker knows does where it is true or above zero and does not where
    /// not; None for any other.
    fn linuxcnc_body_runs(&self, text: &[u8]) -> Option<bool> {
        let (keyword, condition) = o_keyword_condition(text);
        block_runs(&keyword, || self.linuxcnc_condition_value(condition))
    }

    /// LinuxCNC: the main program's `if`, `while`, `repeat` or `do` whose label rs274 records
    /// (interp_o_word.cc `convert_control_functions`, `control_save_offset`: a label kept for
    /// the whole program, by its name, in `offset_map`), or refuses as one recorded before on
    /// another line: an `if` or a `repeat` of any label recorded ("duplicate O-word label -
    /// already defined in line 2", "duplicate O-word label: '...' - defined in line 2"), a
    /// `while` of one recorded by another keyword than `do` (the `while` that closes a `do`
    /// too); a `do` is recorded where its label is not, and refused nowhere (review 48, F19).
    /// Judged where both surely run: opened at the top of the main program, before its end.
    fn linuxcnc_label_recorded(
        &mut self,
        text: &[u8],
        keyword: Option<&[u8]>,
        label: &[u8],
        (line, column): (usize, usize),
    ) {
        let kind = match keyword {
            Some(b"if") => b'i',
            Some(b"while") => b'w',
            Some(b"repeat") => b'r',
            Some(b"do") => b'd',
            _ => return,
        };
        if self.main_ended() || crate::statement::computed_label(label) {
            return;
        }
        let at = self.linuxcnc_open_flow.iter().position(|l| l == label);
        let closes_do = kind == b'w' && at.is_some();
        let top = if closes_do {
            at == Some(0) && self.linuxcnc_open_flow.len() == 1
        } else {
            self.linuxcnc_open_flow.is_empty()
        };
        let bare = bare_label(label);
        let Some(entry) = self.linuxcnc_o_labels.get_mut(&bare) else {
            if !closes_do {
                self.linuxcnc_o_labels.insert(bare, (kind, line, top));
            }
            return;
        };
        let (was, first, surely) = *entry;
        if !top || !surely {
            entry.2 = false;
            return;
        }
        if first == line || kind == b'd' || kind == b'w' && was == b'd' {
            return;
        }
        let statement = String::from_utf8_lossy(text.trim_ascii()).into_owned();
        let keyword = |k: u8| match k {
            b'i' => "if",
            b'w' => "while",
            b'r' => "repeat",
            _ => "do",
        };
        let said = if kind == b'i' {
            format!("duplicate O-word label - already defined in line {first}: '{statement}'")
        } else {
            format!("duplicate O-word label: '{statement}' - defined in line {first}")
        };
        let message = format!(
            "{said} (rs274ngc): the {} on line {first} recorded the label {} for the whole \
             program (interp_o_word.cc control_save_offset), and {} of it on another line is \
             refused; give each condition and loop its own label",
            keyword(was),
            String::from_utf8_lossy(label),
            match kind {
                b'i' => "an if",
                b'w' => "a while",
                _ => "a repeat",
            },
        );
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// LinuxCNC: whether the feed mode in force where the line runs may be another than the
    /// lines in their order give (`linuxcnc_mode_unsure`, or in a definition's body
    /// `linuxcnc_definition_mode_unsure`): the rules that read the mode are not judged then.
    pub(super) fn linuxcnc_feed_mode_unsure(&self) -> bool {
        if self.open_definition.is_some() {
            self.linuxcnc_definition_mode_unsure
        } else {
            self.linuxcnc_mode_unsure
        }
    }

    /// LinuxCNC, a block `b` of the main program (`incremental`: G91 in force before it): its
    /// M70/M73 saves the distance mode for M72, M71 invalidates the saved state, M72 restores
    /// it; then its G90/G91 sets the mode (rs274 runs the M codes of group 7 before the
    /// block's G90/G91: LinuxCNC G-code overview, "G-code Order of Execution"). A G90/G91
    /// inside a condition or loop is known in its block from there, and not after it where it
    /// changed the mode (it may not run: `o1 if [0]` / `G91` / `o1 endif` leaves G90 in
    /// `rs274 -g`); one equal to the mode in force changes nothing (review 50, F3). A G or M
    /// code written by a parameter leaves the mode not known. An M72 with nothing saved
    /// wherever it runs is refused as rs274 does (review 50, F5: [`M72_EMPTY`]); M73 saves as
    /// M70 does (F2: the main program has no return to restore at).
    #[inline(never)]
    pub(super) fn linuxcnc_distance_modal(&mut self, b: &BlockView<'_>, incremental: bool) {
        let step = distance_step(b);
        self.linuxcnc_g53_before = None;
        if self.linuxcnc_dead() {
            return;
        }
        // (most blocks: a G1 or an M3, nothing of the distance mode)
        if step.distance.is_none() && step.m7.is_none() && !step.unread_g && !step.unread_m {
            return;
        }
        let depth = self.linuxcnc_distance_depth();
        let mut mode = if self.linuxcnc_distance_unsure {
            Distance::Unsure
        } else {
            Distance::Known(incremental)
        };
        // (rs274 tests G53 before the block runs, before its M72's restore: interp_check.cc
        // check_g_codes; review 50, F11)
        self.linuxcnc_g53_before =
            (step.m7 == Some(72) && step.g53).then_some(mode == Distance::Known(true));
        let flow = depth > 0;
        let before = mode;
        // (whether the M72's restore surely writes the distance mode or the plane, both known
        // where it runs, before the block's own G90/G91 and plane code: a sure drop of its
        // block, interp_convert.cc `gen_settings`)
        if step.m7 == Some(72) {
            let plane_now = self.linuxcnc_plane_now();
            let plane_saved = self.linuxcnc_plane_saved;
            // (the plane in force before the block: not known here where the block writes
            // one, which the modal state has applied)
            let plane_differs = (!step.plane).then(|| {
                matches!(self.linuxcnc_saved, Saved::Valid(_))
                    && !plane_now.unknown
                    && !plane_saved.unknown
                    && (plane_now.plane, plane_now.uvw) != (plane_saved.plane, plane_saved.uvw)
            });
            // (rs274's `convert_set_plane` refuses under the compensation a G17, G18 or G19
            // from another plane; G17.1-G19.1 pass: review 76-lcnc76a F8)
            self.linuxcnc_m72_plane_differs = plane_differs.map(|d| d && !plane_saved.uvw);
            self.linuxcnc_m72_differs = matches!(
                (self.linuxcnc_saved, before),
                (Saved::Valid(Distance::Known(s)), Distance::Known(n)) if s != n
            ) || plane_differs == Some(true);
        }
        self.linuxcnc_saved_plane(&step, flow);
        match step.m7 {
            Some(70 | 73) => self.linuxcnc_saved.set(Saved::Valid(mode), flow),
            Some(71) => self.linuxcnc_saved.set(Saved::Empty, flow),
            Some(72) => {
                mode = match self.linuxcnc_saved {
                    Saved::Valid(saved) => saved,
                    Saved::Empty => {
                        if !self.main_ended() {
                            self.report(
                                Rule::LinuxCncRefuses,
                                M72_EMPTY.to_string(),
                                b.line,
                                step.m_column,
                            );
                        }
                        Distance::Unsure
                    }
                    Saved::Maybe => Distance::Unsure,
                };
            }
            _ => {}
        }
        if step.unread_m {
            self.linuxcnc_saved = Saved::Maybe;
        }
        if step.unread_g || step.unread_m {
            mode = Distance::Unsure;
        } else if let Some(g91) = step.distance {
            mode = step.written(mode, g91);
        }
        self.linuxcnc_main_write(before, mode, depth);
    }

    /// LinuxCNC, a block of the main program: its M70/M73 saves the plane with the rest of
    /// the modal state, its M72 restores it (interp_convert.cc `save_settings`,
    /// `restore_settings`: the plane among the modes it restores; review 55c, F6: `G17` /
    /// `M70` / `G18` / `M72` / `G5 ...` runs in G17 in `rs274 -g`). A save inside a condition
    /// or loop of another plane than the one saved, one beside a plane code of its block (the
    /// M code runs first), a restore of a state not surely saved, one beside a plane code
    /// (rs274 then runs both: which wins is the saved state's to say), and an M code
    /// written by a parameter (perhaps M72) leave the plane not known.
    fn linuxcnc_saved_plane(&mut self, step: &DistanceStep, flow: bool) {
        let now = self.linuxcnc_plane_now();
        let unknown = PlaneAt {
            unknown: true,
            ..now
        };
        match step.m7 {
            Some(70 | 73) => {
                let differs = flow && self.linuxcnc_plane_saved != now;
                self.linuxcnc_plane_saved = if step.plane || differs { unknown } else { now };
            }
            Some(72) => {
                let at = match self.linuxcnc_saved {
                    Saved::Valid(_) if !step.plane => self.linuxcnc_plane_saved,
                    _ => unknown,
                };
                self.linuxcnc_plane_set(at);
            }
            _ if step.unread_m => self.linuxcnc_plane_set(unknown),
            _ => {}
        }
    }

    /// LinuxCNC, a block with an M word, or any while a save is followed: M70/M73 save the
    /// feed mode, rs274's feed rate and the speed, M72 restores them (interp_convert.cc
    /// `save_settings`, `restore_settings`, `gen_settings`; review 56c, F1-F9). rs274 2.9.0
    /// (the Debian build, git f1270d6ed7) restores by running one block: ` F%.1f` of the saved
    /// rate where it differs from the rate in force, ` S%.0f` of the saved speed where it
    /// differs, and the G code of each modal group that differs, the feed mode among them;
    /// the block runs in rs274's order, the feed mode first (a G94 or G95 zeroes the rate,
    /// `convert_feed_mode`), then the F (under G94 or G95 only: `execute_block`). So where
    /// the saved mode is the one in force, the rate after is the saved one; where a G94 or
    /// G95 is restored from another mode, the saved rate where it differs from the rate in
    /// force, zero where it is the same (`G94 F100` / `M70` / `G93` / `M72` / `G1 X1` is
    /// "Cannot do g1 with zero feed rate"); a G93 restored leaves the rate and each block
    /// gives its F. The speed after is the saved one. The M70's or M72's own G93-G95, F and
    /// S run before it (LinuxCNC G-code overview, "G-code Order of Execution"). That restore
    /// block takes the place of the M72's in rs274 2.9.0: where it surely runs (the feed
    /// mode, the rate or the speed differ) the M72 block's motion does not (review 56c, F5);
    /// where it may, the motion may not (`linuxcnc_m72_motion_dropped`).
    ///
    /// Followed only where nothing is guessed: the M70 and the M72 both run by the main
    /// program where they stand (no condition, loop or body: a loop's second turn saves
    /// again, F6, F8), the feed mode known at both (no call, no G93-G95 in a condition
    /// between, F9), no definition read between (a G20/G21 between converts no rate in
    /// `rs274 -g`: followed as any other, review 61b F1), no G or M code written by a parameter in either block. A rate or speed not
    /// known (an F of a parameter, a G93 move's length times F, a call: F1-F4), or one
    /// `%.1f`/`%.0f` would round, leaves the F or the S after the M72 unknown wherever the
    /// restore could write it. Elsewhere the feed mode, the rate and the speed after an M72
    /// are not known (`linuxcnc_feed_unfollowed`).
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_feed_restore(&mut self, b: &BlockView<'_>, before: &super::Before) {
        if self.linuxcnc_dead() {
            return;
        }
        let mut m7 = None;
        let mut m_column = 0;
        let mut unread = false;
        let mut mode_set = false;
        let mut zeroed = false;
        let mut f_at = None;
        // (a G or M code that may change a modal group the restore writes: any but a motion
        // of G0-G3 or G5-G5.3, whose group it does not restore, a G4, and M70-M73; `early`
        // where it runs before M70-M73 in the block, `late` after: the G-code overview's
        // "G-code Order of Execution", the feed mode, the I/O, M6 and M3-M5 before the save
        // and restore, the rest after; review 58c F3, F5)
        let mut early = false;
        let mut late = false;
        // (and neither an F nor an S word)
        let mut still = true;
        let mut speed_word = false;
        let mut m98 = false;
        let mut comp_set = false;
        let mut spindle_set = false;
        let mut tool_change = false;
        let mut units_set = false;
        // (the block's M7-M9, M48, M49: compared by value at an M72, `RestoreExtras`)
        let mut extra_codes = [false; 5];
        // (an M50: the feed override on (no P, or a P other than 0), off (P0), or not known)
        let mut m50: Option<Option<bool>> = None;
        for (i, w) in b.words.iter().enumerate() {
            let code = || {
                if !w.expression.is_empty() || !w.index.is_empty() {
                    return None;
                }
                std::str::from_utf8(w.number).ok()?.parse::<f64>().ok()
            };
            match (w.letter, code()) {
                (b'M', Some(m @ (70.0 | 71.0 | 72.0 | 73.0))) => {
                    m7 = Some(m as u8);
                    m_column = w.column;
                }
                (b'G', Some(g @ (93.0 | 94.0 | 95.0))) => {
                    mode_set = true;
                    zeroed |= g != 93.0;
                }
                (b'G' | b'M', None) => unread = true,
                (b'F', _) if f_at.is_none() => f_at = Some(i),
                (b'G', Some(40.0 | 41.0 | 41.1 | 42.0 | 42.1)) => comp_set = true,
                (b'M', Some(3.0 | 4.0 | 5.0)) => spindle_set = true,
                (b'M', Some(6.0)) => tool_change = true,
                (b'G', Some(20.0 | 21.0)) => units_set = true,
                _ => {}
            }
            still &= !matches!(w.letter, b'F' | b'S');
            speed_word |= w.letter == b'S';
            m98 |= w.letter == b'M' && code() == Some(98.0);
            match (w.letter, code()) {
                (b'G', Some(93.0 | 94.0 | 95.0)) => early = true,
                (b'G', Some(g)) => {
                    late |= !matches!(g, 0.0 | 1.0 | 2.0 | 3.0 | 4.0 | 5.0 | 5.1 | 5.2 | 5.3)
                }
                (b'M', Some(3.0 | 4.0 | 5.0 | 6.0 | 61.0 | 62.0..=68.0)) => early = true,
                // (M19, whose step the overview does not list: both)
                (b'M', Some(19.0)) => (early, late) = (true, true),
                (b'M', Some(50.0)) => {
                    let p = b.words.iter().position(|w| w.letter == b'P');
                    m50 = Some(match p {
                        None => Some(true),
                        Some(k) => self
                            .readable
                            .get(k)
                            .copied()
                            .flatten()
                            .map(|v| !v.is_zero()),
                    });
                }
                (b'M', Some(m @ (7.0 | 8.0 | 9.0 | 48.0 | 49.0))) => {
                    extra_codes[match m as u8 {
                        9 => 0,
                        7 => 1,
                        8 => 2,
                        48 => 3,
                        _ => 4,
                    }] = true
                }
                (b'M', Some(m)) => late |= !matches!(m, 70.0 | 71.0 | 72.0 | 73.0),
                _ => {}
            }
        }
        // (an M72's block: only its codes before the restore run between it and the save;
        // an M70's or M73's: only those after the save, F and S before it)
        let (modal, still) = match m7 {
            Some(72) => (early, still),
            Some(70 | 73) => (late, true),
            _ => (early || late, still),
        };
        if let Some(saved) = self.linuxcnc_feed_saved.as_mut() {
            saved.quiet &= !modal;
            saved.still &= !modal && still;
        }
        let in_order = self.open_definition.is_none() && self.linuxcnc_open_flow.is_empty();
        if unread || !in_order {
            self.linuxcnc_feed_saved = None;
        }
        let extras_here = extra_codes.contains(&true) || m50.is_some();
        // (the coolant and override where the block's M code runs, before its M7-M9, M48
        // and M49 (the G-code overview's "G-code Order of Execution"); then after them, in
        // the main program's order; in a condition, a loop, or after an M98 or an M code of
        // a parameter, not known; a body's codes run where it is called)
        let extras_at = self.linuxcnc_extras;
        let extras_after = |mut e: RestoreExtras| {
            for (k, code) in [9, 7, 8, 48, 49].into_iter().enumerate() {
                if extra_codes[k] {
                    e.apply(code);
                }
            }
            // (M50 after M48/M49 in rs274's order, group 9's codes one a block)
            if let Some(on) = m50 {
                e.feed_override = on;
            }
            e
        };
        if self.open_definition.is_none() {
            if unread || m98 || (extras_here || m7 == Some(72)) && !in_order {
                self.linuxcnc_extras = RestoreExtras::UNKNOWN;
            } else if m7 != Some(72) {
                self.linuxcnc_extras = extras_after(extras_at);
            }
        }
        if let Some(saved) = self.linuxcnc_feed_saved.as_mut() {
            saved.extras_touched |= extras_here && m7 != Some(72);
        }
        // (a feed mode, a speed or an M98 in a condition or loop of the main program, after a
        // save in one: an M70 of a loop's later turn may save what it set)
        if self.open_definition.is_none() && !self.linuxcnc_open_flow.is_empty() {
            if let Some(loose) = self.linuxcnc_feed_loose.as_mut().filter(|l| l.joined) {
                if mode_set || m98 {
                    loose.mode = None;
                }
                if speed_word || m98 {
                    loose.speed = None;
                }
                // (an F, or a G94/G95, which zeroes rs274's rate; an M70's own F runs before
                // its save, the same on every turn)
                if f_at.is_some() && !matches!(m7, Some(70 | 73)) || mode_set || m98 {
                    loose.rate = None;
                }
            }
        }
        // (an M code of a parameter may be an M70 or M73 saving values not known here)
        if unread && self.open_definition.is_none() {
            self.linuxcnc_feed_loose = Some(LooseSaved::UNKNOWN);
        }
        let Some(m7) = m7 else {
            return;
        };
        let followed = in_order && !unread;
        let state = &self.machine.state;
        let mode_known = mode_set || !self.linuxcnc_mode_unsure;
        // rs274's rate where the M code runs: the block's G94/G95 and F before it
        let mut rate = self.linuxcnc_rate;
        if zeroed {
            rate = Some(Dec::ZERO);
        }
        if let Some(at) = f_at.filter(|_| state.feed_mode != 93) {
            rate = self.readable.get(at).copied().flatten();
        }
        let speed = (!state.is_unknown(b'S')).then(|| state.speed.unwrap_or(Dec::ZERO));
        // the spindle's direction and the compensation the save takes: the block's M3-M5 run
        // before it (the checker's flags read them after this), its G40-G42 after it (the
        // compensation before the block: `M70 G40` saves it on); an M6 of the block stops
        // the spindle (`linuxcnc_tool_change_stopped`): not followed
        let spindle = if tool_change || !spindle_set && self.linuxcnc_spindle_unknown {
            None
        } else if !spindle_set && self.linuxcnc_tool_change_stopped {
            Some(5)
        } else {
            Some(state.spindle)
        };
        let compensation = (!self.linuxcnc_compensation_unknown)
            .then_some((before.compensation, self.linuxcnc_dynamic_compensation));
        // the units where the M code runs: before the block's G20/G21, which runs after it
        // (an M72's kept with the cycle before the block's codes applied)
        let units = if self.units_unknown {
            None
        } else if m7 == 72 {
            self.linuxcnc_m72_cycle.map(|c| c.units)
        } else if units_set {
            // (an M70's or M73's own G20/G21 runs after it: the units before the block,
            // review 75-lcnc75a N2, `M70 G20` / `S200` / `M72` / `G0 X-500` moves in mm)
            self.linuxcnc_m_units
        } else {
            Some((state.units, state.feed_units))
        };
        let now = FeedSaved {
            mode: state.feed_mode,
            rate,
            speed,
            spindle,
            compensation,
            units,
            quiet: !modal,
            still: !modal && still,
            extras: extras_at,
            extras_touched: extras_here && m7 != 72,
        };
        let main = self.open_definition.is_none();
        // (a body's own save, read straight after its sub: whether rs274's rate there is
        // surely zero -- the block's F0, G94/G95, or an F0 of the body in force)
        if !main && m7 != 72 {
            self.linuxcnc_later.body_zero_saved = matches!(m7, 70 | 73)
                && self.linuxcnc_definition_flow.is_empty()
                && !unread
                && rate.map_or(
                    f_at.is_none()
                        && !state.is_unknown(b'F')
                        && state.feed.is_none_or(|f| f.is_zero()),
                    |r| r.is_zero(),
                );
        }
        match m7 {
            70 | 73 => {
                if followed {
                    self.linuxcnc_feed_saved = mode_known.then_some(now);
                }
                // (the values every save that may be the one in force agrees on)
                if main {
                    let this = LooseSaved {
                        mode: mode_known.then_some(now.mode),
                        rate: now.rate,
                        speed: now.speed,
                        joined: !in_order || unread,
                    };
                    self.linuxcnc_feed_loose = Some(match self.linuxcnc_feed_loose {
                        Some(was) if !in_order || unread => was.merge(this),
                        _ => this,
                    });
                }
            }
            72 => {
                let kept = self
                    .linuxcnc_feed_saved
                    .filter(|_| followed)
                    .filter(|_| matches!(self.linuxcnc_saved, Saved::Valid(_)));
                let plane_differs = std::mem::take(&mut self.linuxcnc_m72_plane_differs);
                if let Some(s) = kept {
                    self.linuxcnc_m72_refused(s, now, plane_differs, (b.line, m_column));
                }
                self.linuxcnc_spindle_restored(kept, comp_set, tool_change);
                let saved = kept.filter(|_| mode_known);
                let dropped = match saved {
                    Some(saved) => self.linuxcnc_feed_restored(saved, now),
                    None => {
                        self.linuxcnc_feed_unfollowed(now, followed, mode_known);
                        None
                    }
                };
                // (a followed restore puts every other group back as saved: the block's codes
                // after it are all that differ; review 58c F5: `M70` / `M8` / `M72` / `M72 G1
                // X1` is "Cannot do g1 with zero feed rate" at the second M72; they count
                // for a later M72 either way)
                if let Some(s) = self.linuxcnc_feed_saved.as_mut() {
                    s.quiet = (s.quiet || saved.is_some()) && !late;
                    s.still &= !late;
                    s.extras_touched = s.extras_touched && saved.is_none() || extras_here;
                }
                // (the coolant and override after it: the restore's, then the block's own
                // where it surely runs; not known where the restore is not followed)
                if in_order && !unread && !m98 {
                    let restored = match saved {
                        Some(s) => s.extras.restored(extras_at),
                        None => RestoreExtras::UNKNOWN,
                    };
                    self.linuxcnc_extras = match dropped {
                        Some(false) => extras_after(restored),
                        Some(true) => restored,
                        None => restored.unsure(extras_after(restored)),
                    };
                }
                if dropped != Some(false) {
                    self.linuxcnc_m72_dropped = Some(self.stats.blocks);
                    let restored = (dropped == Some(true))
                        .then(|| (self.linuxcnc_plane_saved, kept.and_then(|s| s.compensation)));
                    self.linuxcnc_m72_motion_dropped(b, before, restored);
                }
                if dropped == Some(true) {
                    if let (Some(to), Some(from)) = (saved.and_then(|s| s.units), now.units) {
                        self.linuxcnc_m72_units(to, from, before);
                    }
                }
                // (a G93 move of the block, where it may run: its length times F)
                if saved.is_some()
                    && self.machine.state.feed_mode == 93
                    && f_at.is_some()
                    && dropped != Some(true)
                {
                    self.linuxcnc_rate = None;
                    self.linuxcnc_feed_rate = super::tooling::LinuxCncFeed::Unknown;
                }
            }
            _ => {}
        }
    }

    /// [`Checker::linuxcnc_feed_restore`]: an M72 of a followed save (`saved`) where the
    /// state is `now`, whose restore block rs274 2.9.0 refuses under the cutter compensation
    /// in force (interp_convert.cc `restore_settings` runs ` G17`/` G41`... that
    /// `gen_settings` writes, the plane first): a plane other than the one in force
    /// ("Cannot change planes with cutter radius compensation on"), or the other side of
    /// the compensation ("Cannot turn cutter radius comp on when on"; the same side, G41
    /// and G41.1, is not written). rs274 says it at the M72 ("M7x: restore_settings failed
    /// executing: ' G42': ..."; review 75-lcnc75a N5: `G42.1 D0.1` / `G1 X1` / `M70` / `G40`
    /// / `G1 X2` / `G41.1 D0.1` / `G1 X3` / `M72 G1 X4`).
    #[cold]
    fn linuxcnc_m72_refused(
        &mut self,
        saved: FeedSaved,
        now: FeedSaved,
        plane_differs: Option<bool>,
        (line, column): (usize, usize),
    ) {
        // (on: G41/G42, or G41.1/G42.1, whose side the modal state does not keep)
        let on = |c: Option<(i64, bool)>| c.filter(|&(side, dynamic)| side != 40 || dynamic);
        let Some((side, dynamic)) = on(now.compensation) else {
            return;
        };
        if self.main_ended() {
            return;
        }
        let written = match on(saved.compensation) {
            Some((s, false)) if !dynamic && s != side => Some(s),
            _ => None,
        };
        // (the plane before a block that writes one is not known here: neither said)
        let Some(plane_differs) = plane_differs else {
            return;
        };
        let message = if plane_differs {
            "Cannot change planes with cutter radius compensation on (rs274ngc): the M72's \
             restore writes the plane the M70 or M73 saved (interp_convert.cc \
             restore_settings) under the compensation in force; turn it off (G40) before the \
             M72"
            .to_string()
        } else if let Some(s) = written {
            format!(
                "Cannot turn cutter radius comp on when on (rs274ngc): the M72's restore writes \
                 the G{s} the M70 or M73 saved (interp_convert.cc restore_settings) under the \
                 G{side} in force; turn it off (G40) before the M72"
            )
        } else {
            return;
        };
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// [`Checker::linuxcnc_feed_restore`]: the spindle's direction and the cutter
    /// compensation (G40, G41, G42, G41.1, G42.1) after an M72, which restores them from the
    /// save (interp_convert.cc `restore_settings` writes the M3-M5 and G40-G42 that differ).
    /// The restore runs after the block's M3-M5 and M6, before its G40-G42 (the G-code
    /// overview's "G-code Order of Execution"): where the save is followed (`saved`) and the
    /// value it took is known, the value is the saved one (review 58c, F1: `M70` / `M72` /
    /// `G33 Z-1 K0.1` is rs274's "Spindle not turning in G33"; `G41.1 D0.1` / `M70` / `M72`
    /// / `G81 X1 Z-1 R1` is "Cannot use canned cycles with cutter compensation on");
    /// elsewhere it is not known until the program sets it (review 57d, F4: `S1000 M3` /
    /// `M70` / `M5` / `M72` / `G33 Z-1 K0.1` runs in `rs274 -g`). A G40-G42 of the block
    /// (`comp_set`) sets the compensation after the restore; an M6 of it (`tool_change`)
    /// stops the spindle before the restore, which the checker leaves not known.
    fn linuxcnc_spindle_restored(
        &mut self,
        saved: Option<FeedSaved>,
        comp_set: bool,
        tool_change: bool,
    ) {
        match saved.and_then(|s| s.spindle).filter(|_| !tool_change) {
            Some(direction) => {
                self.machine.state.spindle = direction;
                self.linuxcnc_spindle_unknown = false;
                self.linuxcnc_tool_change_stopped = false;
            }
            None => self.linuxcnc_spindle_unknown = true,
        }
        if comp_set {
            return;
        }
        match saved.and_then(|s| s.compensation) {
            Some((compensation, dynamic)) => {
                self.machine.state.compensation = compensation;
                self.linuxcnc_dynamic_compensation = dynamic;
                self.linuxcnc_compensation_unknown = false;
            }
            None => self.linuxcnc_compensation_unknown = true,
        }
    }

    /// [`Checker::linuxcnc_feed_restore`]: an M72 whose save the checker does not follow
    /// (its M70 or M73 in a condition or a loop, a G20/G21 or a call between, a code of a
    /// parameter, the M72 itself in a condition or a body), where the state is `now` (its
    /// feed mode known: `mode_known`). Its restore runs after the block's own G93-G95, F and
    /// S (`runs`: surely, where the M72 stands in the main program's order; else it may not
    /// run). rs274's feed rate after it is not known; the feed mode and the speed are
    /// where every save that may be the one in force agrees on them and the M72 surely runs,
    /// or agrees with `now` (`linuxcnc_feed_loose`); elsewhere not known until the program
    /// sets them (review 57d, F2: `F100` / `M70` / `o1 if [1]` / `F200` / `o1 endif` / `G95
    /// F200` / `M72` / `G1 X1` runs in `rs274 -g`, the restore's `G94 F100.0` in force, and
    /// was refused as a G95 feed with no spindle speed).
    fn linuxcnc_feed_unfollowed(&mut self, now: FeedSaved, runs: bool, mode_known: bool) {
        self.linuxcnc_rate = None;
        self.linuxcnc_feed_rate = super::tooling::LinuxCncFeed::Unknown;
        // (the block's G93-G95 and F ran before the M72: tooling reads them no more)
        self.linuxcnc_feed_restored_at = Some(self.stats.blocks);
        let state = &mut self.machine.state;
        // (not the block's own F: the restore writes the saved rate after it; `F10` /
        // `M70` / `G20` / `M72 F0` / `G1 X1` runs in `rs274 -g`)
        state.unknown |= crate::modal::bit(b'F');
        state.feed = None;
        if self.open_definition.is_some() {
            state.unknown |= crate::modal::bit(b'S');
            self.linuxcnc_definition_mode_unsure = true;
            // (an M72 of the body's own save of a zero rate, read straight through: the
            // restore writes the saved rate after the block's F, so the rate is zero and a
            // move without an F after it is refused in every feed mode; review 61b v9:
            // `o100 sub` / `F0` / `M70` / `M9` / `M72 F0` / `G1 X1` is "Cannot do g1 with
            // zero feed rate" where it is called)
            if std::mem::take(&mut self.linuxcnc_later.body_zero_saved)
                && self.linuxcnc_definition_flow.is_empty()
            {
                state.unknown &= !crate::modal::bit(b'F');
                self.linuxcnc_rate = Some(Dec::ZERO);
                self.linuxcnc_feed_rate = super::tooling::LinuxCncFeed::Zero;
            }
            return;
        }
        let loose = self.linuxcnc_feed_loose.unwrap_or(LooseSaved::UNKNOWN);
        let mode = loose.mode.filter(|&m| runs || mode_known && m == now.mode);
        match mode {
            Some(m) => {
                state.feed_mode = m;
                self.linuxcnc_mode_unsure = false;
            }
            None => self.linuxcnc_mode_unsure = true,
        }
        // (the rate, where every save agrees on it, the M72 surely runs and the feed mode is
        // the saved one: the saved rate where the rate in force is it, else its `F%.1f`, as
        // a followed restore; review 61b F3: `F0` / `o1 if [#5220 GT 0]` / `M70` / `o1
        // endif` / `M72 F0` / `G1 X1` is "Cannot do g1 with zero feed rate")
        let rate = match (loose.rate, now.rate) {
            _ if !runs || !mode_known || mode != Some(now.mode) || now.mode == 93 => None,
            (Some(s), Some(r)) if s == r => Some(s),
            (Some(s), r) => written(s, 1).filter(|&w| w == s || r.is_some()),
            _ => None,
        };
        if let Some(v) = rate {
            state.feed = (!v.is_zero()).then_some(v);
            state.unknown &= !crate::modal::bit(b'F');
            self.linuxcnc_rate = Some(v);
            self.linuxcnc_feed_rate = if v.is_zero() {
                super::tooling::LinuxCncFeed::Zero
            } else {
                super::tooling::LinuxCncFeed::Set
            };
        }
        let speed = match (loose.speed, now.speed) {
            (Some(s), Some(n)) if s == n => Some(s),
            (Some(s), Some(_)) if runs => written(s, 0),
            (Some(s), None) if runs => written(s, 0).filter(|&w| w == s),
            _ => None,
        };
        match speed {
            Some(v) => {
                state.speed = Some(v);
                state.unknown &= !crate::modal::bit(b'S');
            }
            None => state.unknown |= crate::modal::bit(b'S'),
        }
    }

    /// [`Checker::linuxcnc_feed_restore`]: the M72 block, whose motion rs274 2.9.0 does not
    /// run where the restore writes a block of its own (any modal group saved that differs:
    /// feed mode, rate, speed, spindle, plane, units, distance mode, compensation, coolant),
    /// which runs in its place. Where that surely happens (`surely`: the feed mode, the rate
    /// or the speed differ), the tool stays where the block found it: X, Y and Z go back to
    /// the block's start (review 57d, F1: `M70` / `G93` / `M72 G1 X1` / `G94 G2 X2 Y0 I0.5 J0
    /// F100` is rs274's "Radius to end of arc differs", the arc starting at X0). Elsewhere the
    /// checker does not know whether the motion runs (review 57d, F3: `M70` / `G18` / `M72 G1
    /// X1` runs in `rs274 -g` with no feed rate, the restore's `G17` in its place): each axis
    /// whose end may differ from its start is not known. Either way its motion is not judged
    /// (`linuxcnc_m72_dropped`).
    fn linuxcnc_m72_motion_dropped(
        &mut self,
        b: &BlockView<'_>,
        before: &super::Before,
        restored: Option<(PlaneAt, Option<(i64, bool)>)>,
    ) {
        let surely = restored.is_some();
        // (and whether the block writes a plane or a cutter compensation code: G17-G19.1,
        // G40-G42.1, read as written)
        let (mut plane, mut compensation, mut distance) = (false, false, None);
        for w in b
            .words
            .iter()
            .filter(|w| w.letter == b'G' && w.expression.is_empty())
        {
            let tenths = std::str::from_utf8(w.number)
                .ok()
                .and_then(|t| t.parse::<f64>().ok())
                .map(|v| (v * 10.0).round() as i64);
            plane |= matches!(tenths, Some(170 | 171 | 180 | 181 | 190 | 191));
            compensation |= matches!(tenths, Some(400 | 410 | 411 | 420 | 421));
            match tenths {
                Some(900) => distance = Some(false),
                Some(910) => distance = Some(true),
                _ => {}
            }
        }
        let cycle = self.linuxcnc_m72_cycle.take();
        self.linuxcnc_m72_motion = Some(M72Dropped {
            motion: self.linuxcnc_motion,
            cycle,
            restored,
            plane,
            compensation,
            distance,
            double: self.linuxcnc_double,
        });
        let state = &mut self.machine.state;
        for (i, &axis) in crate::modal::AXES.iter().enumerate() {
            let mask = crate::modal::bit(axis);
            if i < 3 && surely {
                state.position[i] = before.xyz[i];
                state.unknown = state.unknown & !mask | before.unknown & mask;
            } else if let Some(c) = cycle.filter(|_| i >= 6 && surely) {
                state.position[i] = c.abc[i - 6];
                state.unknown = state.unknown & !mask | c.unknown & mask;
            } else if i < 3
                && (state.position[i] != before.xyz[i]
                    || (state.unknown ^ before.unknown) & mask != 0)
                || i >= 3 && b.words.iter().any(|w| w.letter == axis)
            {
                state.position[i] = None;
                state.unknown |= mask;
            }
        }
    }

    /// The block in hand's M72 is one rs274 2.9.0 surely drops ([`M72Dropped::restored`]):
    /// its restore runs a block of its own in place of this one, so nothing of this block
    /// after the M72 in the order of execution runs (review 59b F7).
    #[inline]
    pub(super) fn linuxcnc_m72_surely_dropped(&self) -> bool {
        self.linuxcnc_m72_dropped == Some(self.stats.blocks)
            && self
                .linuxcnc_m72_motion
                .is_some_and(|d| d.restored.is_some())
    }

    /// The motion mode, plane and compensation after a block whose M72 may be dropped
    /// ([`M72Dropped`]), run after the block's rules: rs274 2.9.0 runs the restore's block in
    /// place of the M72's, so the block's own motion code never takes effect (review 58c, F7:
    /// `M70` / `G93` / `M72 G1 X1` / `X2` traverses to X2 in `rs274 -g`, G0 still in force).
    /// Where the drop is sure and the mode before is G0-G3 or none, that mode is back, and
    /// where it was a canned cycle, the cycle with its words (review 59b, F2); where the drop
    /// is only possible, or the mode before was another, the mode after is not known, as after
    /// a call: no motion is judged by it (TG401, TG411) until a motion code.
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_m72_motion_back(&mut self, dropped: M72Dropped) {
        use super::tooling::LinuxCncMotion;
        // (the block's plane and compensation codes do not take effect where rs274 drops
        // it, the restore's do: where the drop is sure, the plane and compensation the save
        // took, as the restore writes them (review 59b, F3: `F10` / `M70` / `G93` / `M72 G17`
        // / `G2 X1 Y0 I0.5 K0` is "K word given for arc in xy plane"); where it is only
        // possible, not known after it (review 58c, F6: `F10` / `M70` / `F[#<_x>+10]` / `M72
        // G18` / `G2 X1 Y0 I0.5 J0` may run in G17)
        if dropped.plane {
            match dropped.restored {
                Some((at, _)) => self.linuxcnc_plane_set(at),
                None => self.linuxcnc_plane_unknown = true,
            }
        }
        if dropped.compensation {
            match dropped.restored.and_then(|(_, c)| c) {
                Some((compensation, dynamic)) => {
                    self.machine.state.compensation = compensation;
                    self.linuxcnc_dynamic_compensation = dynamic;
                    self.linuxcnc_compensation_unknown = false;
                }
                None => self.linuxcnc_compensation_unknown = true,
            }
        }
        // (nor its G90/G91, which runs after the M72 (the G-code overview's "G-code Order of
        // Execution"): where the drop is sure, the distance mode the save took, which the
        // restore writes; where it is only possible and the two differ, not known; review 59b
        // F7: `M70` / `S200` / `M72 G91 G0 X1` / `G0 X1` / `G38.2 X1` is "Start point too
        // close to probe point" in `rs274 -g`, the X1s absolute)
        if let Some(g91) = dropped.distance.filter(|_| self.open_definition.is_none()) {
            self.linuxcnc_m72_distance_back(g91, dropped.restored.is_some());
        }
        // (and the doubles rs274 holds are the ones before the block where its axis words
        // surely do not run: the block's G91 words were added to them by the rules, review
        // 59b F7: `M70` / `S200` / `M72 G91 G0 Z1` / `Z1` / `G90 G38.2 Z2` runs, the probe
        // from Z1; an axis whose point may have changed is not known, its double the nearest)
        if dropped.restored.is_some() {
            self.linuxcnc_double = dropped.double;
        }
        let M72Dropped {
            motion,
            cycle,
            restored,
            ..
        } = dropped;
        let surely = restored.is_some();
        // (G73 and G74's R, which the modal state does not keep: a surely dropped block's R
        // never runs, the R before it is in force; where the drop is only possible, the R
        // is not known unless both agree; review 61b F5: `G73 X1 Z-1 R1 Q0.5` / `M70` /
        // `S200` / `M72 G73 X2 Z-1 R3 Q0.5` / `X3` retracts to Z1 in `rs274 -g`)
        match cycle {
            Some(c) if surely => self.linuxcnc_cycle_r = c.r,
            Some(c) if c.r == self.linuxcnc_cycle_r => {}
            _ => self.linuxcnc_cycle_r = None,
        }
        // (a canned cycle in force before a surely dropped block stays in force with its
        // words and bottom, even where the block writes no motion code: review 59b, F2,
        // `F10` / `G81 X1 Z-1 R1` / `M70` / `G93` / `M72 G1 X2` / `X3` is "Cannot feed with
        // zero feed rate" at `X3`; `M72 X2 R3` leaves R1, review 61b F5)
        if let Some(c) = cycle.filter(|c| {
            surely
                && matches!(motion, LinuxCncMotion::Known(Some(730 | 740 | 810..=890)))
                && c.cycle.is_some()
        }) {
            self.linuxcnc_motion = motion;
            let state = &mut self.machine.state;
            state.motion = c.motion;
            state.cycle = c.cycle;
            state.cycle_words = c.words;
            self.linuxcnc_cycle_bottom = c.bottom;
            return;
        }
        if self.linuxcnc_motion == motion {
            return;
        }
        let modal = match motion {
            LinuxCncMotion::Known(None) => Some(None),
            LinuxCncMotion::Known(Some(m @ (0 | 10 | 20 | 30))) => Some(Some(m / 10)),
            _ => None,
        };
        match modal.filter(|_| surely) {
            Some(back) => {
                self.linuxcnc_motion = motion;
                self.machine.state.motion = back;
                self.machine.state.cycle = None;
            }
            None => {
                // (where both readings are G0-G3 or none, a move without a motion code ends
                // at its words' point either way: review 59b, F4, `F10` / `G0 Z0` / `M70` /
                // `G18` / `M72 G1 X1` / `G17` / `Z0.5` / `G38.2 Z0.5` is "Start point too
                // close to probe point")
                let plain_before = modal.is_some()
                    || motion == LinuxCncMotion::Unknown && self.linuxcnc_motion_plain;
                self.linuxcnc_motion_plain = plain_before
                    && matches!(
                        self.linuxcnc_motion,
                        LinuxCncMotion::Known(None | Some(0 | 10 | 20 | 30))
                    );
                self.linuxcnc_motion = LinuxCncMotion::Unknown;
                self.motion_unknown = true;
                self.machine.state.motion = None;
                self.linuxcnc_later.pending = None;
                self.linuxcnc_later.body_via = None;
            }
        }
    }

    /// LinuxCNC: the units after an M72 whose restore surely runs a block of its own, from
    /// the units `from` in force where it runs (before its block's G20/G21) to the ones the
    /// save took (`to`): rs274 2.9.0 runs a G20/G21 block of the saved units first where
    /// they differ (interp_convert.cc `restore_settings`), and the M72 block's own G20/G21,
    /// which runs after the M72, is dropped with the rest of it (review 59b F7: `M70` /
    /// `S200` / `M72 G20` / `G0 X-500` moves to X-500 mm in `rs274 -g`; `M70` / `G20` /
    /// `M72` / `G0 X-500` too). Where the units change, the point rs274 holds is converted
    /// (the modal state's G20/G21), and the doubles of X Y Z as rs274 converts them
    /// (`tooling::linuxcnc_units_double`; review 75-lcnc75a F2: `M70` / `G20` / `M72 G91 G1
    /// X1` / `G38.2 X0` is "Start point too close to probe point" in `rs274 -g`).
    fn linuxcnc_m72_units(
        &mut self,
        to: (crate::modal::Units, crate::modal::Units),
        from: (crate::modal::Units, crate::modal::Units),
        before: &super::Before,
    ) {
        // (the block's X Y Z are back at its start, in the units before it; U V W, which its
        // own G20/G21 converted, are not known)
        let state = &mut self.machine.state;
        if state.units != from.0 {
            for &axis in b"UVW" {
                if let Some(i) = crate::modal::axis_index(axis) {
                    state.position[i] = None;
                    state.unknown |= crate::modal::bit(axis);
                }
            }
        }
        (state.units, state.feed_units) = from;
        if to != from {
            let code = if to.0 == crate::modal::Units::Inch {
                20
            } else {
                21
            };
            self.machine.codes(&[code]);
            (self.machine.state.units, self.machine.state.feed_units) = to;
            // (the doubles held before the block, which a sure drop gives back after its
            // rules: `linuxcnc_m72_motion_back`)
            let diameter = self.x_diameter();
            if let Some(dropped) = self.linuxcnc_m72_motion.as_mut() {
                for k in 0..3 {
                    dropped.double[k] = super::tooling::linuxcnc_units_double(
                        dropped.double[k],
                        before.xyz[k],
                        self.machine.state.position[k],
                        to.0,
                    );
                }
            }
            if diameter {
                self.linuxcnc_point_unsure |= crate::modal::bit(b'X');
            }
        }
    }

    /// LinuxCNC: the distance mode after a block whose M72 may be dropped and that writes
    /// G90 or G91 (`g91`, which [`Checker::linuxcnc_distance_modal`] applied after the
    /// restore), the drop sure or not ([`Checker::linuxcnc_m72_motion_back`]): where sure,
    /// the mode the save took; where only possible, that mode where it is the block's, else
    /// not known.
    fn linuxcnc_m72_distance_back(&mut self, g91: bool, surely: bool) {
        let now = if self.linuxcnc_distance_unsure {
            Distance::Unsure
        } else {
            Distance::Known(self.machine.state.incremental)
        };
        let saved = match self.linuxcnc_saved {
            Saved::Valid(saved) => saved,
            _ => Distance::Unsure,
        };
        let after = match saved {
            _ if surely => saved,
            Distance::Known(was) if was == g91 => return,
            _ => Distance::Unsure,
        };
        let depth = self.linuxcnc_distance_depth();
        self.linuxcnc_main_write(now, after, depth);
    }

    /// [`Checker::linuxcnc_feed_restore`]: the M72 of a followed save (`saved`), where the
    /// state is `now`, its restore applied; whether the restore surely runs a block of its
    /// own (the feed mode, the rate or the speed differ: `Some(true)`) or surely none
    /// (they are the saved ones and no other modal code ran between: `Some(false)`).
    fn linuxcnc_feed_restored(&mut self, saved: FeedSaved, now: FeedSaved) -> Option<bool> {
        use super::tooling::LinuxCncFeed;
        let differs = |a: Option<Dec>, b: Option<Dec>| Some(a? != b?);
        let differs_else = std::mem::take(&mut self.linuxcnc_m72_differs);
        // (the coolant and the feed override: where none ran since the save, the restore
        // writes neither)
        let extras = if saved.extras_touched {
            saved.extras.written(now.extras)
        } else {
            Some(false)
        };
        // (the restore surely runs a block of its own: the M72's motion does not run)
        // (or the units: the restore runs a G20/G21 block of its own first, interp_convert.cc
        // `restore_settings`; or the spindle's direction or the cutter compensation, which
        // `gen_m_codes` and `gen_settings` write where they differ; or the distance mode or
        // the plane, `linuxcnc_m72_differs`)
        let surely = saved.mode != now.mode
            || matches!((saved.units, now.units), (Some(s), Some(n)) if s != n)
            || matches!((saved.spindle, now.spindle), (Some(s), Some(n)) if s != n)
            || matches!((saved.compensation, now.compensation), (Some(s), Some(n)) if compensation_differs(s, n))
            || differs_else
            || extras == Some(true)
            || differs(saved.rate, now.rate) == Some(true)
            || differs(saved.speed, now.speed) == Some(true);
        let none = extras == Some(false) && saved.still && now.still
            || extras == Some(false)
                && saved.quiet
                && now.quiet
                && saved.mode == now.mode
                && differs(saved.rate, now.rate) == Some(false)
                && differs(saved.speed, now.speed) == Some(false);
        // rs274's rate after the restore, where known: Some(Some(v)); Some(None): not known;
        // None: a G93 restored, each block gives its F
        let rate: Option<Option<Dec>> = if saved.mode == 93 {
            None
        } else if saved.mode == now.mode {
            Some(match (saved.rate, now.rate) {
                (Some(s), Some(r)) if s == r => Some(s),
                (Some(s), _) => written(s, 1).filter(|&w| w == s || now.rate.is_some()),
                _ => None,
            })
        } else {
            Some(match (saved.rate, now.rate) {
                (Some(s), _) if s.is_zero() => Some(Dec::ZERO),
                (Some(s), Some(r)) if s == r => Some(Dec::ZERO),
                (Some(s), Some(_)) => written(s, 1),
                _ => None,
            })
        };
        let state = &mut self.machine.state;
        state.feed_mode = saved.mode;
        let speed = match (saved.speed, now.speed) {
            (Some(s), Some(n)) if s == n => Some(s),
            (Some(s), Some(_)) => written(s, 0),
            (Some(s), None) => written(s, 0).filter(|&w| w == s),
            _ => None,
        };
        match speed {
            Some(v) => {
                state.speed = Some(v);
                state.unknown &= !crate::modal::bit(b'S');
            }
            None => state.unknown |= crate::modal::bit(b'S'),
        }
        let after = match rate {
            // (each G93 block gives its F; rs274's rate is as the M72's block left it)
            None => {
                if now.mode != 93 {
                    state.feed = None;
                    state.unknown &= !crate::modal::bit(b'F');
                }
                now.rate
            }
            Some(Some(v)) => {
                state.feed = (!v.is_zero()).then_some(v);
                state.unknown &= !crate::modal::bit(b'F');
                Some(v)
            }
            Some(None) => {
                state.unknown |= crate::modal::bit(b'F');
                None
            }
        };
        // (the block's own G94/G95 and F are in `now`: tooling reads them no more)
        self.linuxcnc_rate = after;
        self.linuxcnc_feed_rate = match after {
            Some(v) if v.is_zero() => LinuxCncFeed::Zero,
            Some(_) => LinuxCncFeed::Set,
            None => LinuxCncFeed::Unknown,
        };
        self.linuxcnc_mode_unsure = false;
        self.linuxcnc_feed_restored_at = Some(self.stats.blocks);
        (surely || none).then_some(surely)
    }

    /// LinuxCNC: a subroutine file (its one definition, called from another file): the
    /// refusals of its body that hold at any call ([`CallRefusal`] not of the caller's mode:
    /// a G53 under its own G91, an M72 with nothing saved in its context, a `break` or
    /// `continue` of the subroutine's own label, on a line outside
    /// the body's conditions and loops) are said where they stand, as rs274 says them when the
    /// file is called (one inside a condition on the arguments runs for some calls only:
    /// review 51, F17).
    #[cold]
    fn subroutine_file_refusals(&mut self) {
        let refusals: Vec<CallRefusal> = self
            .linuxcnc_bodies
            .iter()
            .flat_map(|body| body.4.iter().copied())
            .filter(|r| !r.caller_g91 && !r.flow)
            .collect();
        for r in refusals {
            let message = if r.exit {
                format!("{SUB_LABEL_EXIT} (wherever this subroutine file is called from)")
            } else if r.m72 {
                format!("{M72_EMPTY} (in this subroutine file, wherever it is called from)")
            } else {
                format!("{G53_INCREMENTAL} (its own G91, wherever it is called from)")
            };
            self.report(Rule::LinuxCncRefuses, message, r.line, r.column);
        }
    }

    /// LinuxCNC: the depth of the main program's conditions and loops a line stands at, for
    /// the distance mode: that of the innermost block open not known to run, none inside
    /// blocks (a `do`, a condition or loop whose condition the checker knows true, nested in
    /// one another) whose lines up to here surely run wherever the program reaches the
    /// outermost not known (LinuxCNC O-codes, "Do-While loop": the body runs before the
    /// condition is tested; `Checker::linuxcnc_body_runs`; review 50, F3e; review 52, F4).
    fn linuxcnc_distance_depth(&self) -> usize {
        self.linuxcnc_open_at
            .iter()
            .rposition(|e| e.runs != Some(true))
            .map_or(0, |at| at + 1)
    }

    /// LinuxCNC: the main program's distance mode goes from `before` to `mode` at the depth
    /// `depth` of its conditions and loops ([`Checker::linuxcnc_distance_from`]); the
    /// machine's G91 is set by the block's own G90/G91, here by an M72's restore.
    fn linuxcnc_main_write(&mut self, before: Distance, mode: Distance, depth: usize) {
        if before == mode {
            return;
        }
        match mode {
            Distance::Known(g91) => {
                if self.machine.state.incremental != g91 {
                    self.machine.state.incremental = g91;
                    self.machine.distance_codes = self.machine.distance_codes.wrapping_add(1);
                }
                self.linuxcnc_distance_unsure = false;
                self.linuxcnc_distance_from = (depth > 0).then_some(depth);
                self.linuxcnc_distance_in = self.linuxcnc_open_flow.len();
            }
            _ => {
                self.linuxcnc_distance_unsure = true;
                self.linuxcnc_distance_from = None;
            }
        }
    }

    /// LinuxCNC: the plane where the line in hand stands ([`PlaneAt`]).
    fn linuxcnc_plane_now(&self) -> PlaneAt {
        PlaneAt {
            plane: self.machine.state.plane,
            uvw: self.linuxcnc_uvw_plane,
            unknown: self.linuxcnc_plane_unknown,
        }
    }

    /// LinuxCNC: a block the checker does not follow (`calls`: it has a calling word): after
    /// a call the plane the subroutine may set is not known, unless it calls a definition
    /// read before it whose body writes no plane and calls nothing
    /// ([`Checker::linuxcnc_plane_subs`]); after an o-word line of a condition or loop the
    /// plane is followed ([`Checker::linuxcnc_plane_flow`]).
    pub(super) fn linuxcnc_plane_after_call(&mut self, b: &BlockView<'_>, calls: bool) {
        let mut may_set = calls;
        let now = self.linuxcnc_plane_now();
        for &(_, kind, text) in b.statements {
            if kind != Kind::Call {
                continue;
            }
            let label = self.linuxcnc_call_label(text);
            // (a body whose every plane code writes the caller's plane leaves it: its lines
            // run in the caller's plane or in that one; an M72 of the body restores what the
            // body's own M70 saved, rs274's context being the call level's)
            let leaves_caller_plane =
                |one: &Option<(i64, bool)>| !now.unknown && *one == Some((now.plane, now.uvw));
            may_set |= self.open_definition.is_some()
                || crate::statement::computed_label(&label)
                || !self.linuxcnc_defined.contains(&label)
                || self
                    .linuxcnc_plane_subs
                    .get(&label)
                    .is_some_and(|one| !leaves_caller_plane(one));
        }
        if may_set {
            self.linuxcnc_plane_unknown = true;
            if let Some(open) = &self.open_definition {
                self.linuxcnc_plane_subs.insert(open.2.clone(), None);
            }
        }
    }

    /// The labels of a block of calls (a row of the main program's calls), the last first,
    /// as [`LaterChain`] holds them; None where one is worked out as the line runs (`o[#1]
    /// call`: no chain of known bodies).
    fn linuxcnc_row_labels(&self, b: &BlockView<'_>) -> Option<LaterChain> {
        let labels: LaterChain = b
            .statements
            .iter()
            .rev()
            .map(|&(_, _, text)| self.linuxcnc_call_label(text))
            .collect();
        labels
            .iter()
            .all(|l| !crate::statement::computed_label(l))
            .then_some(labels)
    }

    /// LinuxCNC: the motion mode after a block the checker does not follow (`calls`: it has
    /// a calling word), which is not known ([`LinuxCncMotion::Unknown`]). Where every
    /// statement of the block is a call of a definition read before it whose body writes no
    /// motion code but G0-G3 and calls none that may ([`Checker::linuxcnc_motion_subs`]),
    /// and the mode before is G0-G3 or none, the mode after is one of G0-G3 or none
    /// ([`Checker::linuxcnc_motion_plain`]): a move without a motion code after it ends at
    /// its words' point whichever it is, so its axes are known exactly (review 59b, F5:
    /// `o100 sub` / `G1 X1 F10` / `o100 endsub` / `G0 Z0` / `o100 call` / `Z0.5` / `G38.2
    /// Z0.5` is rs274's "Start point too close to probe point"). A call inside a definition
    /// of one that may leaves that body's mark too. After an `endsub` the mode is the one
    /// before its `sub` (rs274 reads a definition without running it).
    pub(super) fn linuxcnc_motion_after_call(&mut self, b: &BlockView<'_>, calls: bool) {
        use super::tooling::LinuxCncMotion;
        let mut before_plain = self.linuxcnc_motion_is_plain();
        let row = self.linuxcnc_later.pending.take();
        let only_calls =
            !calls && !b.statements.is_empty() && b.statements.iter().all(|s| s.1 == Kind::Call);
        if self.open_definition.is_some() && self.linuxcnc_later.sub_line != self.stats.blocks {
            let clean =
                !self.linuxcnc_later.body_moded && self.linuxcnc_motion == LinuxCncMotion::Unknown;
            // (a body's last call, outside its conditions and loops: review 63-lcnc63 K8)
            self.linuxcnc_later.body_via = match b.statements {
                [(_, Kind::Call, text)] if !calls && self.linuxcnc_definition_flow.is_empty() => {
                    Some((self.linuxcnc_call_label(text), clean))
                }
                _ => None,
            };
            self.linuxcnc_later.body_moded |= calls
                || self.linuxcnc_motion != LinuxCncMotion::Unknown
                || b.statements.iter().any(|s| s.1 == Kind::Call);
        }
        // (calls in a row of the main program after a call of a label not read yet: the
        // move after them held for all their bodies; review 63-lcnc63 N2)
        if let Some((chain, _, m)) = row.filter(|_| only_calls && self.open_definition.is_none()) {
            if let Some(mut labels) = self.linuxcnc_row_labels(b) {
                labels.extend(chain);
                self.linuxcnc_later.pending = Some((labels, b.line, m));
            }
        }
        self.linuxcnc_later.body_zero_saved = false;
        if self.linuxcnc_later.still.is_some() {
            self.linuxcnc_still_back(b.line);
        }
        // (a body's `do` loop closed here whose every turn ends in the G0-G3 read last)
        let do_closed = self
            .linuxcnc_motion_before_sub
            .do_closed
            .take()
            .filter(|&(line, _)| line == b.line && self.open_definition.is_some());
        self.linuxcnc_motion = LinuxCncMotion::Unknown;
        self.linuxcnc_motion_plain = false;
        if self.config.family != Family::LinuxCnc {
            return;
        }
        if calls {
            // (a calling word in a body, an M98 among them, may leave any mode: the body is
            // not plain; review 61b F2: `o100 sub` / `M98 P200` / `o100 endsub` / `o100
            // call` / `Z0.5` runs O200's G81 in `rs274 -g`)
            if let Some(open) = &self.open_definition {
                self.linuxcnc_motion_subs.insert(open.2.clone());
            }
            if self.open_definition.is_none() && !self.linuxcnc_open_flow.is_empty() {
                self.may_call_seen();
            }
            if self.open_definition.is_none() {
                self.later_main_call(b.line);
            }
            if self.letters & crate::modal::bit(b'P') != 0 {
                self.linuxcnc_m98_later(b);
            }
            return;
        }
        let (mut plain, mut called) = (true, false);
        // (the motion mode the last call's body surely leaves: review 61b, F4)
        let mut left = None;
        for &(_, kind, text) in b.statements {
            if kind == Kind::Definition && self.open_definition.is_none() {
                // (an endsub: rs274 reads a definition without running it, the mode before
                // its sub is in force after it)
                called = true;
                before_plain = self.linuxcnc_plain_before_sub;
                continue;
            }
            if kind != Kind::Call {
                plain = false;
                left = None;
                if self.open_definition.is_some()
                    && text.windows(6).any(|w| w.eq_ignore_ascii_case(b"return"))
                {
                    self.linuxcnc_body_returns = true;
                }
                continue;
            }
            called = true;
            let label = self.linuxcnc_call_label(text);
            left = self.linuxcnc_sub_motion.get(&label).copied();
            if crate::statement::computed_label(&label)
                || !self.linuxcnc_defined.contains(&label)
                || self.linuxcnc_motion_subs.contains(&label)
            {
                plain = false;
                if let Some(open) = &self.open_definition {
                    self.linuxcnc_motion_subs.insert(open.2.clone());
                }
            }
        }
        self.linuxcnc_motion_plain = called && plain && before_plain;
        // (a call of the main program of a label with no definition read yet: rs274 first
        // looks for a file named after the label on its subroutine path, which the checker
        // cannot see, and runs it if found (interp_o_word.cc, control_back_to; review 62b
        // F2: `o<foo> call` / `Z0.5` / `M2` / `o<foo> sub` / `G2 I0.5 J0` / `o<foo> endsub`
        // runs where a foo.ngc of a G1 is on the path); either body may end the program
        // (review 62b F3). The mode it leaves is not judged, and no mode a later call
        // surely leaves (from a plain body or a `do` loop), in the main program after
        // it: held; review 62b LE5)
        let unread = b
            .statements
            .iter()
            .filter(|&&(_, kind, _)| kind == Kind::Call && self.open_definition.is_none())
            .map(|&(_, _, text)| self.linuxcnc_call_label(text))
            .find(|label| {
                crate::statement::computed_label(label) || !self.linuxcnc_defined.contains(label)
            });
        if let Some(label) = unread {
            self.linuxcnc_later.unread = true;
            // (a call surely run: where the definition answering it surely ends the program,
            // no line after it runs; review 62b F3, LE1)
            if !b.skip && self.linuxcnc_runs_surely() && !self.main_ended() {
                let at = (label.clone(), b.line);
                self.linuxcnc_later.ends.push(at);
            }
            // (the caller's G2/G3 judges no move after it until the definition is read:
            // review 62b F4, Checker::linuxcnc_later_move)
            let state = &self.machine.state;
            if let (Some(m @ 2..=3), None) = (state.motion, state.cycle) {
                if !crate::statement::computed_label(&label) && only_calls {
                    if let Some(labels) = self
                        .linuxcnc_row_labels(b)
                        .filter(|_| self.linuxcnc_later.pending.is_none())
                    {
                        self.linuxcnc_later.pending = Some((labels, b.line, m));
                    }
                }
            }
        }
        if self.linuxcnc_later.unread && self.open_definition.is_none() {
            if left.is_some() {
                // (a body that may leave another mode than the caller's: not known)
                self.machine.state.motion = None;
                self.machine.state.cycle = None;
            }
            return;
        }
        if let Some(motion) = left {
            // (a G0-G3 ends a cycle in force)
            self.machine.state.motion = motion;
            self.machine.state.cycle = None;
        }
        // (the mode is surely known after a call of a body that surely leaves one, and
        // after a `do` loop whose every turn ends in one: the lines after it, and the
        // `endsub` of a body they end, judged by it; lcnc61's misses: `o200 sub` / `G2 X1
        // Y0 I0.5 J0` / `o200 endsub` / `o100 sub` / `o200 call` / `o100 endsub` / `o100
        // call` / `Z0.5` is "R i j k words all missing for arc" in `rs274 -g`)
        let sure = match (left, do_closed) {
            (Some(Some(m)), _) => Some(m),
            (None, Some((_, m))) if !called => Some(m),
            _ => None,
        };
        if let Some(m) = sure {
            self.linuxcnc_motion = LinuxCncMotion::Known(Some(m * 10));
            self.linuxcnc_motion_plain = false;
            self.motion_unknown = false;
            self.machine.state.motion = Some(m);
            self.machine.state.cycle = None;
        }
    }

    /// LinuxCNC: the main program's `M98 P300` (a P of a whole number, no L) calls the
    /// FANUC-style program `O300`, which rs274 2.9 seeks after it as it seeks an `o300 sub`
    /// ([`Checker::linuxcnc_fanuc_line`]): taken as the o-word form's call of a definition
    /// not read yet, `o300 call` -- the move after it under the caller's G2/G3 held for the
    /// body's M99, a body that surely ends the program ending it (the one reading of
    /// [`Checker::linuxcnc_motion_after_call`]; `rs274 -g` of `G2 X1 Y0 I0.5 J0` / `M98 P300`
    /// / `X2` / `M2` / `O300` / `G0 X0` / `M99` runs the X2 in the body's G0).
    #[cold]
    #[inline(never)]
    fn linuxcnc_m98_later(&mut self, b: &BlockView<'_>) {
        use super::tooling::LinuxCncMotion;
        let m98 = |w: &Word<'_>| w.letter == b'M' && w.number == b"98" && w.expression.is_empty();
        if b.skip
            || !b.statements.is_empty()
            || !b
                .words
                .iter()
                .all(|w| matches!(w.letter, b'N' | b'P') || m98(w))
        {
            return;
        }
        let Some(n) = self.called_number(b) else {
            return;
        };
        if !self.linuxcnc_m98_numbers.contains(&n) {
            self.linuxcnc_m98_numbers.push(n);
        }
        // (one in a body: the program it names read as a definition, no more)
        if self.open_definition.is_some() {
            return;
        }
        let label = format!("o{n}").into_bytes();
        if self.linuxcnc_defined.contains(&label) {
            // (a definition read before the main program's call is of the o-word form)
            if !self.main_ended() && self.linuxcnc_runs_surely() && !self.linuxcnc_dead() {
                self.linuxcnc_m98_of_sub(b, n);
            }
            return;
        }
        // (its work offset, distance mode and units kept for the body read after the end,
        // as an `o300 call`'s are: review 78-lcnc78 N1)
        if !self.config.work_offsets.is_empty() && !self.early_on {
            self.later_call_of(b, &label);
        }
        self.linuxcnc_later.unread = true;
        if self.linuxcnc_runs_surely() && !self.main_ended() {
            self.linuxcnc_later.ends.push((label.clone(), b.line));
            self.linuxcnc_m98_calls.push((label.clone(), b.line));
        }
        let state = &self.machine.state;
        if let (Some(m @ 2..=3), None) = (state.motion, state.cycle) {
            if self.linuxcnc_later.pending.is_none() {
                self.linuxcnc_later.pending = Some((vec![label], b.line, m));
            }
        }
        debug_assert_eq!(self.linuxcnc_motion, LinuxCncMotion::Unknown);
    }

    /// TG412: the main program's `M98 P300` (surely run) of an `o300 sub` defined before it:
    /// rs274 2.9 refuses it where it returns to the definition ("'O.... sub' subroutine must
    /// be called with 'O.... call'", interp_o_word.cc convert_control_functions; `rs274 -g`,
    /// review 78-lcnc78 M1, M2), said at the call.
    #[cold]
    #[inline(never)]
    fn linuxcnc_m98_of_sub(&mut self, b: &BlockView<'_>, n: i64) {
        let message = format!(
            "'O.... sub' subroutine must be called with 'O.... call' (rs274ngc): M98 P{n} \
             reaches o{n} sub, a definition of the o-word form written before it, which \
             rs274 2.9 runs only for an o{n} call"
        );
        let column = super::column_of(b.words, b'M');
        self.report(Rule::LinuxCncRefuses, message, b.line, column);
    }

    /// LinuxCNC: a move without a motion code or arc word (`b`) under the caller's G2/G3
    /// after the main program's call of a definition not read yet ([`LaterCalls`]), no
    /// motion code since: rs274 runs it in the mode the definition leaves, known at its
    /// `endsub` ([`Checker::linuxcnc_later_arcs`]). The first such move after the call is
    /// kept; the later ones are in the same mode, judged by the first.
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_later_move(&mut self, b: &BlockView<'_>) -> bool {
        use super::tooling::LinuxCncMotion;
        // (a motion code since the call: the mode is the main program's own; review
        // 63-lcnc63 F2)
        if self.linuxcnc_motion != LinuxCncMotion::Unknown {
            return false;
        }
        let Some((labels, call, m)) = self.linuxcnc_later.pending.clone() else {
            return false;
        };
        let column = b.words.first().map_or(1, |w| w.column);
        self.linuxcnc_later
            .moves
            .push((labels, call, b.line, column, m));
        true
    }

    /// LinuxCNC: at the `endsub` of a definition (`label`) the main program called before
    /// reading it under its own G2/G3 ([`LaterCalls`]): where the body surely leaves the
    /// mode as it found it (it moves no axis, writes no G code and calls nothing:
    /// [`still_line`]), the first move without a motion code or arc word after the call is
    /// an arc with no centre or radius ("R i j k words all missing for arc", interp_convert.cc
    /// convert_arc; review 62b LG4: `G2 X1 Y0 I0.5 J0` / `o300 call` / `X2` / `M2` / `o300
    /// sub` / `M8` / `o300 endsub`); where it surely leaves G0, G1 or a cycle (`plain`)
    /// nothing is said (review 62b F4: a body of `G0 X0` or `G81 X1 Z-1 R2`, and `X2` runs
    /// in `rs274 -g`); elsewhere (a call in it, a G0 in a condition) it may leave the
    /// caller's G2/G3, and the move is judged as before (review 63-lcnc63, K8, K12).
    #[cold]
    #[inline(never)]
    fn linuxcnc_later_arcs(&mut self, label: &[u8], sure: Option<i64>, keeps: bool, plain: bool) {
        let via = self.linuxcnc_later.body_via.take();
        let left = match sure {
            Some(m @ 2..=3) => LaterLeft::Arc(m),
            _ if plain => LaterLeft::Plain,
            _ if keeps => LaterLeft::Keeps(self.linuxcnc_bodies.last().is_some_and(|b| b.6)),
            _ => match via {
                Some((l, clean))
                    if self.linuxcnc_motion == super::tooling::LinuxCncMotion::Unknown
                        && !self.linuxcnc_body_returns
                        && !self.linuxcnc_body_distance.ends =>
                {
                    LaterLeft::Via(l, clean)
                }
                _ => LaterLeft::Unknown,
            },
        };
        let bare = std::mem::take(&mut self.linuxcnc_later.body_bare).1;
        let all = &mut self.linuxcnc_later.left;
        all.retain(|e| e.0 != label);
        all.push((label.to_vec(), left, bare));
        if !self.linuxcnc_later.moves.is_empty() {
            self.linuxcnc_later_settle();
        }
    }

    /// What the body of `label` leaves of the mode its call found, as far as the
    /// definitions read say ([`LaterLeft`]; None: not read yet), through its last call's,
    /// and whether a move of its own is judged by the mode it found (a bare line before any
    /// G word, in it or in the body its last call runs).
    fn linuxcnc_later_left(&self, label: &[u8], depth: usize) -> Option<(LaterLeft, u8)> {
        let left = self
            .linuxcnc_later
            .left
            .iter()
            .rev()
            .find(|e| e.0 == label)?;
        match &left.1 {
            LaterLeft::Via(next, clean) if depth < 16 => {
                let (then, bare) = self.linuxcnc_later_left(next, depth + 1)?;
                match then {
                    LaterLeft::Keeps(_) if !clean => Some((LaterLeft::Unknown, left.2)),
                    other => Some((other, bare.max(left.2))),
                }
            }
            LaterLeft::Via(..) => Some((LaterLeft::Unknown, left.2)),
            other => Some((other.clone(), left.2)),
        }
    }

    /// LinuxCNC: the moves held after the main program's calls of labels not read yet
    /// ([`LaterCalls::moves`]) whose bodies are all read now, run in call order from the
    /// caller's G2/G3: a body that leaves the mode it found keeps it, one that surely leaves
    /// G0-G3 or a cycle sets it, any other leaves it not known; a body with a move of its own
    /// before any G word, run under an arc or a mode not known, may be refused in itself.
    /// The move after the calls in an arc (the caller's kept, or a body's G2/G3) is one with
    /// no centre or radius ("R i j k words all missing for arc", interp_convert.cc
    /// convert_arc; review 62b LG4: `G2 X1 Y0 I0.5 J0` / `o300 call` / `X2` / `M2` / `o300
    /// sub` / `M8` / `o300 endsub`); after G0, G1 or a cycle nothing is said (review 62b F4:
    /// a body of `G0 X0` or `G81 X1 Z-1 R2`, and `X2` runs in `rs274 -g`; review 63-lcnc63
    /// N2: `o300 call` / `o301 call` / `X2` with o300's `G0 X0` and o301's `M8`; K8: o300's
    /// last line `o301 call` of a `G0 X0` body); elsewhere (a G0 in a condition, a body's
    /// own bare move) the move is judged as before (review 63-lcnc63 K12; review 75 F1b).
    fn linuxcnc_later_settle(&mut self) {
        let moves = std::mem::take(&mut self.linuxcnc_later.moves);
        for e in moves {
            let (labels, call, line, column, m) = &e;
            // (the mode after each call: Some(arc) for an arc, Some(0) for a line or
            // cycle, None not known; and whether a body may be refused in itself)
            let mut mode = Some((*m, false));
            let mut decider = &labels[0];
            let mut refused = false;
            let mut waits = false;
            for label in labels.iter().rev() {
                let Some((left, bare)) = self.linuxcnc_later_left(label, 0) else {
                    waits = true;
                    break;
                };
                // (axis words alone under an arc or a mode not known; an arc's words under
                // a line, a cycle or a mode not known: review 75 F3)
                let arc = matches!(mode, Some((2 | 3, _)));
                if bare == 2 && !arc || bare == 1 && mode.is_none_or(|(a, _)| a != 0) {
                    refused = true;
                    decider = label;
                }
                match left {
                    LaterLeft::Keeps(_) => {}
                    LaterLeft::Plain => mode = Some((0, true)),
                    LaterLeft::Arc(a) => mode = Some((a, true)),
                    _ => mode = None,
                }
                if !matches!(left, LaterLeft::Keeps(_)) && !refused {
                    decider = label;
                }
            }
            if waits {
                self.linuxcnc_later.moves.push(e);
                continue;
            }
            let leaves = match mode {
                _ if refused => format!("which may leave the G{m} before it in force"),
                Some((0, _)) => continue,
                Some((a, true)) => format!("which leaves G{a} in force"),
                Some(_) => format!("which leaves the G{m} before it in force"),
                None => format!("which may leave the G{m} before it in force"),
            };
            let message = format!(
                "arc without I J K (or R): none is given, whatever the plane (the call on \
                 line {call} runs {} written after it, {leaves})",
                String::from_utf8_lossy(decider)
            );
            self.linuxcnc_later_report(message, *line, *column);
        }
    }

    /// LinuxCNC: at the `endsub` of a definition the main program called before reading it,
    /// the call surely run ([`LaterCalls::ends`]), whose body surely ends the program (its M2
    /// or M30 outside its conditions): no line after the first such call runs, so the
    /// findings of the lines from it to the main program's end are dropped, as after a call
    /// of such a body read before it (review 62b F3, LE1: `o300 call` / `G2 Z0.5` / `M2` /
    /// `o300 sub` / `M8` / `M2` / `o300 endsub` runs to its end in `rs274 -g`; it was TG404).
    #[cold]
    #[inline(never)]
    fn linuxcnc_later_ends(&mut self) {
        let Some(body) = self.linuxcnc_bodies.last() else {
            return;
        };
        let label = body.0.clone();
        let ends = body.5;
        let calls = std::mem::take(&mut self.linuxcnc_later.ends);
        let (these, rest): (Vec<_>, Vec<_>) = calls.into_iter().partition(|e| e.0 == label);
        self.linuxcnc_later.ends = rest;
        // (the main program's own end, not a definition's M2 after it: review 63-lcnc63 F3)
        let end = self.linuxcnc_later.main_end;
        let Some(from) = these.iter().map(|e| e.1).min().filter(|&c| ends && c < end) else {
            self.linuxcnc_later_released();
            return;
        };
        let dead = |line: usize| line > from && line <= end;
        if self.hold_from.is_none() && self.passed.is_none() {
            self.found.retain(|f| !dead(f.line));
        }
        self.linuxcnc_later.moves.retain(|e| !dead(e.2));
        self.linuxcnc_later.ends.retain(|e| !dead(e.1));
        self.linuxcnc_later_released();
    }

    /// LinuxCNC: the findings held after the main program's calls of labels not read yet
    /// ([`PENDING_LATER`]) handed over where no such call waits for its definition any more
    /// (`all`: at the file's end, whatever waits; no call waits after it).
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_later_released_at(&mut self, all: bool) {
        if all {
            self.linuxcnc_later.ends.clear();
        } else if !self.linuxcnc_later.ends.is_empty() {
            return;
        }
        for f in &mut self.found {
            f.pending_on.retain(|&n| n != PENDING_LATER);
        }
    }

    fn linuxcnc_later_released(&mut self) {
        self.linuxcnc_later_released_at(false);
    }

    /// LinuxCNC: at the file's end, the moves kept after a call of a label no definition
    /// of the file answers ([`Checker::linuxcnc_later_move`]): judged by the caller's G2/G3,
    /// as before they were kept (rs274 refuses the call where no file of that name is on
    /// its subroutine path).
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_later_unanswered(&mut self) {
        for (_, _, line, column, _) in std::mem::take(&mut self.linuxcnc_later.moves) {
            let message = "arc without I J K (or R): none is given, whatever the plane";
            self.linuxcnc_later_report(message.to_string(), line, column);
        }
    }

    /// LinuxCNC: a TG404 said late of a move after a call of a label not read yet, placed
    /// among the findings still held after it ([`PENDING_LATER`]) in line order.
    fn linuxcnc_later_report(&mut self, message: String, line: usize, column: usize) {
        let before = self.found.len();
        self.report(Rule::ArcCentreMissing, message, line, column);
        // (not where findings are held by index for a program read apart or a jump's run)
        if self.found.len() > before && self.hold_from.is_none() && self.passed.is_none() {
            let at = self.found[..before]
                .iter()
                .position(|f| f.line > line)
                .unwrap_or(before);
            let f = self.found.remove(before);
            self.found.insert(at, f);
        }
    }

    /// LinuxCNC: a call line of the main program (`text`, one of its statements) whose
    /// every call names a definition read before it that moves no axis and calls nothing
    /// ([`still_line`]): the axes' positions before it kept ([`LaterCalls::still`]), put
    /// back after the call forgets them ([`Checker::linuxcnc_still_back`]).
    #[cold]
    #[inline(never)]
    fn linuxcnc_still_call(&mut self, b: &BlockView<'_>, text: &[u8]) {
        let label = self.linuxcnc_call_label(text);
        let still = !self.linuxcnc_later.unread
            && b.statements.len() == 1
            && crate::statement::o_keyword(text).as_deref() == Some(b"call".as_slice())
            && !crate::statement::computed_label(&label)
            && self.linuxcnc_defined.contains(&label)
            && self
                .linuxcnc_bodies
                .iter()
                .rfind(|e| e.0 == label)
                .is_some_and(|e| e.6 && e.2.is_empty());
        let state = &self.machine.state;
        self.linuxcnc_later.still = still.then(|| {
            (
                b.line,
                state.position,
                state.unknown
                    & crate::modal::FORGOTTEN
                    & !(crate::modal::bit(b'F') | crate::modal::bit(b'S')),
                self.machine.drift,
            )
        });
    }

    /// LinuxCNC: after the call line the checker does not follow, the axes' positions from
    /// before it where every call of the line is of a body that moves no axis
    /// ([`Checker::linuxcnc_still_call`]): rs274 runs the body, which leaves them as they
    /// were (lcnc60's list: `G0 Z0` / `o100 call` of a body of `M8` / `G38.2 Z0` is "Start
    /// point too close to probe point").
    #[cold]
    #[inline(never)]
    fn linuxcnc_still_back(&mut self, line: usize) {
        let Some((at, position, unknown, drift)) = self.linuxcnc_later.still.take() else {
            return;
        };
        if at != line {
            return;
        }
        let axes = crate::modal::FORGOTTEN & !(crate::modal::bit(b'F') | crate::modal::bit(b'S'));
        let state = &mut self.machine.state;
        state.position = position;
        state.unknown = state.unknown & !axes | unknown;
        self.machine.drift = drift;
    }

    /// LinuxCNC: a body's `do` loops through its o-word line (`keyword`, `label`): a `do`
    /// opens one, a `break` or `continue` marks every one open, and the `while` of the
    /// last one open closes it; where no `break` or `continue` stood in it and the motion
    /// mode read last is a G0-G3 known, every turn ends in it (a turn's lines run straight
    /// where the checker reads none of its o-word lines but its own; a `return` is the
    /// `endsub`'s matter), and so does the loop: kept for the line's
    /// [`Checker::linuxcnc_motion_after_call`].
    fn linuxcnc_body_do(&mut self, keyword: Option<&[u8]>, label: &[u8], line: usize) {
        use super::tooling::LinuxCncMotion;
        let sure = match self.linuxcnc_motion {
            LinuxCncMotion::Known(Some(m @ (0 | 10 | 20 | 30)))
                if !self.motion_unknown && self.machine.state.cycle.is_none() =>
            {
                Some(m / 10)
            }
            _ => None,
        };
        let dos = &mut self.linuxcnc_motion_before_sub.dos;
        match keyword {
            Some(b"do") => dos.push((label.to_vec(), false)),
            Some(b"break" | b"continue") => dos.iter_mut().for_each(|d| d.1 = true),
            Some(b"while") if dos.last().is_some_and(|d| d.0 == label) => {
                let left = dos.pop().is_some_and(|d| d.1);
                self.linuxcnc_motion_before_sub.do_closed =
                    sure.filter(|_| !left).map(|m| (line, m));
            }
            _ => {}
        }
    }

    /// LinuxCNC: rs274's feed rate after an o-word line the checker does not follow
    /// ([`Checker::linuxcnc_rate_through_if`]).
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_rate_after_statement(&mut self, b: &BlockView<'_>) {
        // (a definition's `endsub`: the rate from before its `sub`, rs274 reading the
        // definition without running it; review 62b, F1: `o100 sub` / `M8` / `o100 endsub`
        // / `M70` / `M72 F0` / `G1 X4` after an F100 runs in `rs274 -g`, the M70 saving 100)
        if let Some((Some(at), rate, feed)) = self.linuxcnc_rate_before_sub {
            self.linuxcnc_rate_before_sub = None;
            if at == self.stats.blocks {
                self.linuxcnc_rate = rate;
                self.linuxcnc_feed_rate = feed;
                // (and the F word in force: a plain G1's rate, review 63-lcnc63 N3)
                let (f, unknown, none_kept) = self.linuxcnc_f_before_sub;
                let m = &mut self.machine;
                m.state.feed = f;
                let bit = crate::modal::bit(b'F');
                m.state.unknown = m.state.unknown & !bit | if unknown { bit } else { 0 };
                m.feed_none_kept = none_kept;
                return;
            }
        }
        self.linuxcnc_feed_rate = super::tooling::LinuxCncFeed::Unknown;
        self.linuxcnc_rate = self.linuxcnc_rate_through_if(b);
    }

    /// LinuxCNC: rs274's feed rate ([`Checker::linuxcnc_rate`]) after an o-word line the
    /// checker does not follow: an `if` of the main program opening its first branch runs
    /// nothing, so the rate where its branch's first line runs is the one before it (kept
    /// for what an M70 there saves; review 61b, v2: `F0` / `o1 if [#5220 GT 0]` / `M70` /
    /// `o1 endif` / `M72 F0` / `G1 X1` is "Cannot do g1 with zero feed rate" in `rs274
    /// -g`); after any other, not known.
    fn linuxcnc_rate_through_if(&self, b: &BlockView<'_>) -> Option<Dec> {
        let opens_if = |&(_, kind, text): &(usize, Kind, &[u8])| {
            kind == Kind::Flow
                && crate::statement::o_keyword(text).as_deref() == Some(b"if".as_slice())
        };
        (self.config.family == Family::LinuxCnc
            && self.open_definition.is_none()
            && matches!(b.statements, [one] if opens_if(one)))
        .then_some(self.linuxcnc_rate)
        .flatten()
    }

    /// LinuxCNC: whether the motion mode in force is G0-G3 or none, known or not
    /// ([`Checker::linuxcnc_motion_plain`]).
    fn linuxcnc_motion_is_plain(&self) -> bool {
        use super::tooling::LinuxCncMotion;
        match self.linuxcnc_motion {
            LinuxCncMotion::Known(None | Some(0 | 10 | 20 | 30)) => true,
            LinuxCncMotion::Known(Some(_)) => false,
            LinuxCncMotion::Unknown => self.linuxcnc_motion_plain,
        }
    }

    /// LinuxCNC: the plane `at` in force again (the modal state's, and the two flags).
    fn linuxcnc_plane_set(&mut self, at: PlaneAt) {
        self.machine.state.plane = at.plane;
        self.linuxcnc_uvw_plane = at.uvw;
        self.linuxcnc_plane_unknown = at.unknown;
    }

    /// LinuxCNC: a definition opened or closed by the line in hand (`was_open`: one was open
    /// before it). rs274 reads a definition without running it (interp_o_word.cc
    /// control_save_offset skips to its endsub) and runs its body where a call calls it, in
    /// the caller's plane: the body starts in a plane not known here, and the lines after
    /// the endsub run in the plane from before the sub (`rs274 -g`: `o100 sub` / `G18` ...
    /// `o100 endsub` / `G2 Y10 R10` draws the arc in G17; review 54, F2).
    fn linuxcnc_definition_plane(&mut self, was_open: bool) {
        match (was_open, self.open_definition.is_some()) {
            (false, true) => {
                self.linuxcnc_plane_before_sub = Some(self.linuxcnc_plane_now());
                // (and whether the motion mode before it is G0-G3 or none, which its endsub
                // gives back: `Checker::linuxcnc_motion_after_call`)
                self.linuxcnc_plain_before_sub = self.linuxcnc_motion_is_plain();
                // (and rs274's feed rate, which its endsub gives back)
                self.linuxcnc_rate_before_sub =
                    Some((None, self.linuxcnc_rate, self.linuxcnc_feed_rate));
                let m = &self.machine;
                let unknown = m.state.unknown & crate::modal::bit(b'F') != 0;
                self.linuxcnc_f_before_sub = (m.state.feed, unknown, m.feed_none_kept);
                let state = &self.machine.state;
                let label = self.open_definition.as_ref().map(|o| o.2.clone());
                self.linuxcnc_motion_before_sub = MotionBeforeSub {
                    motion: state.motion,
                    cycle: state.cycle,
                    words: state.cycle_words,
                    label: label.unwrap_or_default(),
                    dos: Vec::new(),
                    do_closed: None,
                };
                self.linuxcnc_body_returns = false;
                self.linuxcnc_later.body_moded = false;
                self.linuxcnc_later.body_bare = (false, 0);
                self.linuxcnc_later.sub_line = self.stats.blocks;
                self.linuxcnc_plane_unknown = true;
                self.linuxcnc_plane_body_blocks.clear();
            }
            (true, false) => {
                if let Some(before) = self.linuxcnc_plane_before_sub.take() {
                    self.linuxcnc_plane_set(before);
                }
                self.linuxcnc_definition_motion();
                self.linuxcnc_plane_body_blocks.clear();
                if let Some(before) = self.linuxcnc_rate_before_sub.as_mut() {
                    before.0 = Some(self.stats.blocks);
                }
            }
            _ => {}
        }
    }

    /// LinuxCNC: at a definition's `endsub`, the motion mode its body surely leaves (a
    /// G0-G3 read last, not in a condition or loop, no `return` before it, no call after
    /// it) kept for its calls, and the motion mode, cycle and cycle words from before its
    /// `sub` put back: rs274 reads a definition without running it (review 61b, F4: `o100
    /// sub` / `G2 X1 Y0 I0.5 J0` / `o100 endsub` / `Z1` runs in `rs274 -g`, and `o100 call`
    /// / `Z0.5` after it is "R i j k words all missing for arc").
    fn linuxcnc_definition_motion(&mut self) {
        use super::tooling::LinuxCncMotion;
        let state = &self.machine.state;
        let known = matches!(
            self.linuxcnc_motion,
            LinuxCncMotion::Known(Some(0 | 10 | 20 | 30))
        ) && !self.motion_unknown
            && !self.linuxcnc_body_returns
            && !self.linuxcnc_body_distance.ends
            && state.cycle.is_none();
        let MotionBeforeSub {
            motion,
            cycle,
            words,
            label,
            ..
        } = std::mem::take(&mut self.linuxcnc_motion_before_sub);
        {
            // (the mode the body surely leaves, or whether it writes none: no motion code,
            // G code of a value not known or call in it; review 63-lcnc63 F1)
            let sure = self
                .machine
                .state
                .motion
                .filter(|m| known && (0..=3).contains(m));
            let keeps = !self.linuxcnc_later.body_moded
                && self.linuxcnc_motion == LinuxCncMotion::Unknown
                && !self.linuxcnc_motion_subs.contains(&label)
                && !self.linuxcnc_body_returns
                && !self.linuxcnc_body_distance.ends;
            // (whether it surely leaves G0, G1 or a cycle: the move after the call runs in
            // rs274, review 62b F4; a last call leaves what its body leaves, review 63-lcnc63
            // K8; elsewhere -- a G0 in a condition -- it may keep the caller's G2/G3, and the
            // move is judged as main did: review 63-lcnc63 K12)
            let plain = matches!(
                self.linuxcnc_motion,
                LinuxCncMotion::Known(Some(0 | 10 | 730 | 740 | 810..=890))
            ) && !self.motion_unknown
                && !self.linuxcnc_body_returns
                && !self.linuxcnc_body_distance.ends;
            self.linuxcnc_later_arcs(&label, sure, keeps, plain);
        }
        let state = &self.machine.state;
        // (a body whose last mode is not known but differs from the one before its sub as
        // read: a call of it leaves the mode not known, none of G0-G3 judged by it)
        match state.motion {
            Some(m @ 0..=3) if known => {
                self.linuxcnc_sub_motion.insert(label, Some(m));
            }
            now if now != motion || state.cycle != cycle => {
                self.linuxcnc_sub_motion.insert(label, None);
            }
            _ => {
                self.linuxcnc_sub_motion.remove(&label);
            }
        }
        let state = &mut self.machine.state;
        state.motion = motion;
        state.cycle = cycle;
        state.cycle_words = words;
    }

    /// LinuxCNC: the plane through a condition or loop (`blocks`, one for each block open,
    /// `step` the o-word line in hand). A branch after an `else`/`elseif` starts in the plane
    /// from before the `if` (rs274 runs one branch of it); at the block's end the plane is
    /// the one every way through it leaves: each branch read (one known not to run left
    /// out), and the plane from before it where no branch may run (no `else`; a loop of no
    /// turn). Where these differ the plane is not known ([`Checker::linuxcnc_plane_unknown`];
    /// review 54, F2: `o1 if [#5220 EQ 1]` / `G17` / `o1 else` / `G18` / `o1 endif` / `G5`
    /// runs in rs274 where #5220 is 1). A `break` or `continue` is one more way out, in its
    /// plane.
    fn linuxcnc_plane_flow(&mut self, blocks: &mut Vec<PlaneBlock>, step: PlaneStep) {
        let now = self.linuxcnc_plane_now();
        // (and the motion mode, the same way: lcnc63, a G2 in an `if` or `while` whose
        // condition is not known, and a bare move after it)
        // (the main program's alone: a definition's body, its conditions not evaluated, keeps
        // the mode as read, review 63, F4: `o100 sub` / `o1 if [#1 GT 0]` / G2 ... / `Z0.5`)
        let motion = (self.machine.state.motion, self.machine.state.cycle);
        let follow = step.main;
        if step.leaves {
            // (a `break` or `continue` leaves its turn in this plane: one more way out of its
            // loop and of every block around the loop; none into the conditions inside the
            // loop around it, whose branch in hand it leaves: review 55c, F9, a branch that
            // ends in `break` is no way to its `endif`. Its loop not found: every block)
            let inner = step.loop_at.filter(|&at| at < blocks.len());
            for (i, block) in blocks.iter_mut().enumerate() {
                if inner.is_none_or(|at| i <= at) {
                    block.ends.push(now);
                    block.motion_ends.push(motion);
                }
            }
            if let (Some(_), Some(block)) = (inner, blocks.last_mut()) {
                block.left = true;
            }
            return;
        }
        if step.open > step.depth {
            // (blocks opened where the plane was not followed: none to merge, none lost)
            blocks.truncate(step.depth);
            while blocks.len() < step.depth {
                blocks.push(PlaneBlock {
                    entry: PlaneAt {
                        unknown: true,
                        ..now
                    },
                    motion_entry: UNKNOWN_MOTION,
                    motion_ends: Vec::new(),
                    ends: Vec::new(),
                    has_else: false,
                    taken: false,
                    left: false,
                });
            }
            blocks.push(PlaneBlock {
                entry: now,
                motion_entry: motion,
                motion_ends: Vec::new(),
                ends: Vec::new(),
                has_else: false,
                taken: false,
                left: false,
            });
        } else if step.open < step.depth {
            let mut ran = step.ran;
            let mut after = now;
            let mut motion_after = motion;
            while blocks.len() > step.open {
                let Some(block) = blocks.pop() else { break };
                let mut ends = block.ends;
                let mut motion_ends = block.motion_ends;
                // (after a branch that surely ran, rs274 skips to the `endif`: the ways
                // through are that branch's alone, its end pushed where it ended)
                if ran != Some(false) && !block.taken && !block.left {
                    ends.push(after);
                    motion_ends.push(motion_after);
                }
                if !block.has_else && ran != Some(true) && !block.taken {
                    ends.push(block.entry);
                    motion_ends.push(block.motion_entry);
                }
                motion_after = flow_motion_merged(&motion_ends, motion_after);
                after = match ends.first() {
                    Some(&first) if ends.iter().all(|e| *e == first) => first,
                    _ => PlaneAt {
                        unknown: true,
                        ..after
                    },
                };
                // (an outer block closed on the same line: whether it ran, not known)
                ran = None;
            }
            if after != now {
                self.linuxcnc_plane_set(after);
            }
            if follow && motion_after != motion {
                self.linuxcnc_flow_motion(motion_after);
            }
        } else if let Some(at) = step.switched {
            if at + 1 != blocks.len() {
                // (a branch of a block not the innermost: the plane is not followed here)
                blocks.truncate(at + 1);
                self.linuxcnc_plane_unknown = true;
                if let Some(block) = blocks.last_mut() {
                    block.entry.unknown = true;
                    block.motion_entry = UNKNOWN_MOTION;
                }
                if follow {
                    self.linuxcnc_flow_motion(UNKNOWN_MOTION);
                }
                return;
            }
            let Some(block) = blocks.last_mut() else {
                return;
            };
            if step.ran != Some(false) && !block.taken && !block.left {
                block.ends.push(now);
                block.motion_ends.push(motion);
            }
            block.left = false;
            block.has_else |= step.is_else;
            block.taken |= step.taken;
            // (after a branch that surely ran the others are skipped: the plane stays)
            if !block.taken {
                let entry = block.entry;
                let motion_entry = block.motion_entry;
                self.linuxcnc_plane_set(entry);
                if follow && motion_entry != motion {
                    self.linuxcnc_flow_motion(motion_entry);
                }
            }
        }
    }

    /// LinuxCNC: the motion mode and canned cycle after a way through a condition or loop
    /// of the main program ([`Checker::linuxcnc_plane_flow`]): the one every way through
    /// it leaves, else not known (no mode, as after a call: none of G0-G3 judged by it). A
    /// G2 in an `if` whose condition is not known, or a `while` that may turn none, and a
    /// bare move after it, runs in `rs274 -g` where the branch does not run (`o102 while
    /// [#5220 GT 100]` / `G2 X1 Y0 I0.5 J0` / `o102 endwhile` / `Z0.5`; it was TG404).
    #[cold]
    #[inline(never)]
    fn linuxcnc_flow_motion(&mut self, (motion, cycle): FlowMotion) {
        let state = &mut self.machine.state;
        state.motion = motion;
        state.cycle = cycle;
    }

    /// LinuxCNC: the main program's flow went to depth `open`, or switched to another branch
    /// of the `if` at `switched`: a distance mode known only in the block it was set in is
    /// not known now ([`Checker::linuxcnc_distance_from`]).
    fn linuxcnc_distance_scope(&mut self, open: usize, switched: Option<usize>) {
        // (a mode written in a branch known to run: the `else` after it is the branch that
        // does not, and no mode is known there)
        if switched.is_some_and(|at| at < self.linuxcnc_distance_in)
            && !self.linuxcnc_distance_unsure
        {
            self.linuxcnc_distance_unsure = true;
            self.linuxcnc_distance_from = None;
        }
        self.linuxcnc_distance_in = self.linuxcnc_distance_in.min(open);
        if let Some(from) = self.linuxcnc_distance_from {
            if open < from || switched.is_some_and(|at| at < from) {
                self.linuxcnc_distance_unsure = true;
                self.linuxcnc_distance_from = None;
            }
        }
    }

    /// LinuxCNC: an `o<name> call` (`text` at `column` of line `line`), after the checker
    /// judged the body read apart at it (crate::check::called): the body's G90/G91 stays in
    /// force after its return as a FANUC's does (rs274 -g: `o<s> sub` / `G90 G0 X750` / `o<s>
    /// endsub` ... `G91` / `o<s> call` / `G0 X-900` goes to X-900), unless its M73 restores the
    /// caller's ([`BodyDistance`]). A call inside a condition or loop may not run: where the
    /// body returns in a mode other than the one in force, the mode after it is not known
    /// (review 49a, F1; one equal to it changes nothing: review 50, F8). In the main program,
    /// the body's refusals that wait for a call are said ([`CallRefusal`]; review 50, F4, F5).
    #[cold]
    #[inline(never)]
    fn linuxcnc_call_distance(&mut self, text: &[u8], line: usize, main_depth: usize) {
        if crate::statement::o_keyword(text).as_deref() != Some(b"call".as_slice()) {
            return;
        }
        let label = crate::statement::o_label(text);
        let main = self.open_definition.is_none();
        let open = self.open_definition.as_ref().map(|d| d.2.clone());
        let body = (label.len() >= 2
            && !crate::statement::computed_label(&label)
            && open.as_ref() != Some(&label))
        .then(|| self.linuxcnc_bodies.iter().rfind(|e| e.0 == label))
        .flatten()
        .map(|e| (e.3, e.4.clone()));
        let (depth, mode) = if main {
            let mode = if self.linuxcnc_distance_unsure {
                Distance::Unsure
            } else {
                Distance::Known(self.machine.state.incremental)
            };
            (main_depth, mode)
        } else {
            let ctx = &self.linuxcnc_body_distance;
            (self.linuxcnc_definition_flow.len(), ctx.mode)
        };
        let Some((end, refusals)) = body else {
            // (which body runs, or what it does, not known here)
            if main {
                self.linuxcnc_distance_unsure = true;
                self.linuxcnc_distance_from = None;
            } else {
                self.linuxcnc_body_distance.write(Distance::Unsure, depth);
            }
            return;
        };
        let token = format!(
            "{} call",
            String::from_utf8_lossy(&crate::statement::o_label_shown(text))
        );
        if main {
            for r in refusals {
                if r.caller_g91 && mode != Distance::Known(true)
                    || self.linuxcnc_call_refused.contains(&r.line)
                {
                    continue;
                }
                self.linuxcnc_call_refused.push(r.line);
                self.report(
                    Rule::LinuxCncRefuses,
                    r.message(&token, line),
                    r.line,
                    r.column,
                );
            }
        } else {
            let ctx = &mut self.linuxcnc_body_distance;
            for mut r in refusals {
                match ctx.mode {
                    _ if !r.caller_g91 => {}
                    Distance::Caller => {}
                    Distance::Known(true) => r.caller_g91 = false,
                    _ => continue,
                }
                ctx.refusals.push(r);
            }
            ctx.write(end, depth);
        }
        match end {
            Distance::Caller => {}
            Distance::Known(g91) if depth == 0 => {
                if self.machine.state.incremental != g91 {
                    self.machine.state.incremental = g91;
                    self.machine.distance_codes = self.machine.distance_codes.wrapping_add(1);
                }
                if main {
                    self.linuxcnc_distance_unsure = false;
                    self.linuxcnc_distance_from = None;
                }
            }
            known if known == mode && main => {}
            Distance::Known(g91) if !main && self.machine.state.incremental == g91 => {}
            _ => {
                let name = String::from_utf8_lossy(&label).into_owned();
                self.call_mode_lost(&token, (line, 1), &name, None);
            }
        }
    }

    /// LinuxCNC: what a definition's body does to the feed mode ([`Checker::linuxcnc_bodies`]):
    /// its `sub` line opens an entry, each line of its body adds to it; and to the distance
    /// mode ([`BodyDistance`]), which its `endsub` closes.
    fn linuxcnc_body(&mut self, b: &BlockView<'_>, statement: Option<&(bool, Vec<u8>)>) {
        let bare = &mut self.linuxcnc_later.body_bare;
        if statement.is_none() && !bare.0 && self.linuxcnc_definition_flow.is_empty() {
            if self.letters & crate::modal::bit(b'G') != 0 {
                bare.0 = true;
            } else if crate::modal::axis_places(self.letters) != 0 {
                let bit = crate::modal::bit;
                let arc = bit(b'I') | bit(b'J') | bit(b'K') | bit(b'R');
                bare.1 = bare.1.max(if self.letters & arc != 0 { 2 } else { 1 });
            }
        }
        match statement {
            Some((true, name)) => {
                if self.open_definition.is_some() {
                    self.linuxcnc_bodies.push((
                        name.clone(),
                        false,
                        Vec::new(),
                        Distance::Unsure,
                        Vec::new(),
                        false,
                        true,
                    ));
                    *self.linuxcnc_body_distance = BodyDistance {
                        open: true,
                        before: (self.machine.state.incremental, self.machine.distance_codes),
                        ..BodyDistance::default()
                    };
                }
                return;
            }
            Some((false, _)) => {
                let ctx = &mut self.linuxcnc_body_distance;
                if ctx.open && !ctx.returned {
                    // (an endsub returns; in a subroutine file one inside a condition or
                    // loop of the body returns early)
                    ctx.returns();
                    ctx.returned = self.open_definition.is_none();
                }
                if ctx.open && self.open_definition.is_none() {
                    ctx.open = false;
                    if let Some(body) = self.linuxcnc_bodies.last_mut() {
                        body.3 = ctx.end.unwrap_or(Distance::Unsure);
                        body.4 = std::mem::take(&mut ctx.refusals);
                        body.5 = ctx.ends;
                    }
                }
                return;
            }
            None => {}
        }
        if self.open_definition.is_none() {
            return;
        }
        let Some(body) = self.linuxcnc_bodies.last_mut() else {
            return;
        };
        if body.6 && !still_line(b) {
            body.6 = false;
        }
        // (read before the block's words are: the number as written, an expression not known)
        let mut ends = false;
        for w in b.words.iter().filter(|w| matches!(w.letter, b'G' | b'M')) {
            let value = std::str::from_utf8(w.number)
                .ok()
                .and_then(|n| n.parse::<f64>().ok())
                .filter(|_| w.expression.is_empty());
            let codes: &[f64] = if w.letter == b'G' {
                &[93.0, 94.0, 95.0]
            } else {
                ends |= matches!(value, Some(2.0 | 30.0));
                &[2.0, 30.0, 72.0, 98.0, 99.0]
            };
            body.1 |= value.is_none_or(|v| codes.contains(&v));
        }
        let depth = self.linuxcnc_definition_flow.len();
        let ctx = &mut self.linuxcnc_body_distance;
        if ctx.returned {
            return; // (after a return outside its conditions and loops: never runs)
        }
        if !b.words.is_empty() {
            let step = distance_step(b);
            let flow = depth > 0;
            // (before any return, one inside a condition or loop too, whose `end` is set)
            if !flow && ctx.end.is_none() && !b.skip && ends {
                ctx.ends = true;
            }
            // (rs274 tests G53 before the block runs, its M72 too: interp_check.cc
            // check_g_codes; review 50, F11)
            let mut restored = ctx.mode;
            let g53_mode = match step.distance {
                Some(g91) => Distance::Known(g91),
                None if step.unread_g => Distance::Unsure,
                None => ctx.mode,
            };
            match step.m7 {
                Some(m @ (70 | 73)) => {
                    ctx.saved.set(Saved::Valid(ctx.mode), flow);
                    if m == 73 && ctx.restore != Some(true) {
                        ctx.restore = if flow { None } else { Some(true) };
                    }
                }
                Some(71) => ctx.saved.set(Saved::Empty, flow),
                Some(72) => {
                    restored = match ctx.saved {
                        Saved::Valid(saved) => saved,
                        Saved::Empty => {
                            // (refused wherever it runs: said at the body's calls)
                            ctx.refusals.push(CallRefusal {
                                line: b.line,
                                column: step.m_column,
                                caller_g91: false,
                                flow,
                                m72: true,
                                exit: false,
                            });
                            Distance::Unsure
                        }
                        Saved::Maybe => Distance::Unsure,
                    };
                    ctx.write(restored, depth);
                }
                _ => {}
            }
            if step.unread_m {
                ctx.saved = Saved::Maybe;
                if ctx.restore == Some(false) {
                    ctx.restore = None;
                }
            }
            if step.unread_g || step.unread_m {
                ctx.write(Distance::Unsure, depth);
            } else if let Some(g91) = step.distance {
                ctx.write(step.written(restored, g91), depth);
            }
            // G53 is refused where G91 is in force: the body's own, or its caller's where it
            // has written none (judged at each call: review 50, F4)
            if step.g53 {
                let caller_g91 = match g53_mode {
                    Distance::Known(true) => Some(false),
                    Distance::Caller => Some(true),
                    _ => None,
                };
                if let Some(caller_g91) = caller_g91 {
                    ctx.refusals.push(CallRefusal {
                        line: b.line,
                        column: step.g_column,
                        caller_g91,
                        flow,
                        m72: false,
                        exit: false,
                    });
                }
            }
        }
        for &(_, kind, text) in b.statements {
            match crate::statement::o_keyword(text).as_deref() {
                Some(b"call") if kind == Kind::Call => {
                    body.2.push(crate::statement::o_label(text));
                }
                Some(b"return") => {
                    // (a return outside its conditions and loops ends the call: what
                    // follows it never runs; review 49a, F1)
                    ctx.returns();
                    ctx.returned |= depth == 0;
                }
                // (a break or continue naming the subroutine's own label, outside the body's
                // conditions and loops: rs274 finds no loop of it wherever the body runs,
                // "undefined O-word label"; review 52, F9)
                Some(b"break" | b"continue")
                    if kind == Kind::Flow
                        && depth == 0
                        && !b.skip
                        && self.open_definition.as_ref().is_some_and(|d| {
                            let label = crate::statement::o_label(text);
                            !crate::statement::computed_label(&label)
                                && bare_label(&label) == bare_label(&d.2)
                        }) =>
                {
                    let column = b.statements.first().map_or(1, |s| s.0);
                    ctx.refusals.push(CallRefusal {
                        line: b.line,
                        column,
                        caller_g91: false,
                        flow: false,
                        m72: false,
                        exit: true,
                    });
                }
                _ if kind == Kind::Call => body.1 = true,
                _ => {}
            }
        }
    }

    /// LinuxCNC: whether the call statement `text` (`o<s> call`, its label known) calls a
    /// subroutine defined before it whose body ends the program ([`BodyDistance`]'s `ends`).
    #[inline(never)]
    fn linuxcnc_call_ends(&self, text: &[u8]) -> bool {
        if crate::statement::o_keyword(text).as_deref() != Some(b"call".as_slice()) {
            return false;
        }
        let label = self.linuxcnc_call_label(text);
        !crate::statement::computed_label(&label)
            && self
                .linuxcnc_bodies
                .iter()
                .rfind(|e| e.0 == label)
                .is_some_and(|e| e.5)
    }

    /// LinuxCNC: whether the main program's call statement `text` leaves the feed mode as it
    /// was before it: an `o<name> call` of a subroutine defined in this file before the call
    /// whose body, and the bodies of the subroutines it calls (transitively, each defined
    /// before the call too), set no feed mode and end nothing ([`Checker::linuxcnc_bodies`]).
    /// rs274 runs the body under the caller's mode, and a body that writes no G93/G94/G95
    /// returns under it (issue 32, item 4: TG402 was not judged after any call). Anything
    /// else: not known here.
    fn linuxcnc_call_keeps_mode(&self, text: &[u8]) -> bool {
        if crate::statement::o_keyword(text).as_deref() != Some(b"call".as_slice()) {
            return false;
        }
        let mut todo = vec![crate::statement::o_label(text)];
        let mut seen: Vec<Vec<u8>> = Vec::new();
        while let Some(label) = todo.pop() {
            if label.len() < 2 {
                return false; // (`o[#1] call`: which one is not known here)
            }
            if seen.contains(&label) {
                continue;
            }
            let Some((_, sets, calls, _, _, _, _)) =
                self.linuxcnc_bodies.iter().rfind(|e| e.0 == label)
            else {
                return false;
            };
            if *sets {
                return false;
            }
            todo.extend(calls.iter().cloned());
            seen.push(label);
        }
        true
    }

    /// LinuxCNC: rs274 reads an `o<name> sub` ... `o<name> endsub` without running it, so
    /// the feed mode a G93/G95 in its body sets is not in force after the `endsub`: the one
    /// where the definition began is given back (review 16c, finding 1: a definition's G95
    /// refused the main program's probe).
    fn definition_feed(&mut self, statement: Option<&(bool, Vec<u8>)>) {
        match (statement, &self.open_definition) {
            (Some((true, _)), None) => {
                self.linuxcnc_definition_feed = Some(self.machine.state.feed_mode);
                // (its body runs under its caller's mode)
                self.linuxcnc_definition_mode_unsure = true;
                self.linuxcnc_definition_flow.clear();
                self.linuxcnc_definition_opened.clear();
            }
            (Some((false, name)), Some((_, _, open))) if self.definition_closes(name, open) => {
                if let Some(mode) = self.linuxcnc_definition_feed.take() {
                    self.machine.state.feed_mode = mode;
                }
            }
            _ => {}
        }
    }

    /// A named parameter's name (between `#<` and `>`, as written) that is a global (`_`
    /// first) or one the main program has assigned: looked up as rs274 reads names (blanks
    /// left out, case ignored), with no allocation for a name of up to 64 bytes, as every
    /// word of a CAM program that scales its axes by parameters reads one.
    fn linuxcnc_name_known(&self, written: &[u8]) -> bool {
        let mut buf = [0u8; 66];
        buf[..2].copy_from_slice(b"#<");
        let mut n = 2;
        for &c in written {
            if blank(c) {
                continue;
            }
            if n == buf.len() {
                let name = super::params::named_parameter(written);
                return name.get(2) == Some(&b'_') || self.linuxcnc_named.contains(&name);
            }
            buf[n] = c.to_ascii_lowercase();
            n += 1;
        }
        buf.get(2) == Some(&b'_') && n > 2 || self.linuxcnc_named.contains(&buf[..n])
    }

    /// The first local named parameter `text` reads that the main program has not assigned
    /// ([`Checker::linuxcnc_named_reads`]), with the column given.
    fn linuxcnc_undefined_read(&mut self, text: &[u8], column: usize) -> Option<(Vec<u8>, usize)> {
        // one pass over the bytes, without memchr, whose dispatch costs more than the few
        // dozen bytes of a word's expression (`[#<yscale>*-56.12]`, two in every line of a
        // CAM program scaling its axes by parameters): a `#` looked for 8 bytes at a time
        // (`next_hash`), then its name's `>` (a word's expression is walked once for its
        // names by `walk_expression` instead: this reads a statement's, an assignment's,
        // and a word's past the walked ones)
        let mut i = 0;
        while let Some(start) = next_hash(text, i) {
            if text.get(start + 1) != Some(&b'<') {
                i = start + 1;
                continue;
            }
            let close = start + 2 + text[start + 2..].iter().position(|&c| c == b'>')?;
            i = close + 1;
            if let Some(name) = self.linuxcnc_unknown_name(text, start, close) {
                return Some((name, column));
            }
        }
        None
    }

    /// The named parameter `text[start..=close]` (`#<name>`, its `#` at `start` and its `>`
    /// at `close`) if it is a local one the main program has not assigned, read outside
    /// `EXISTS[..]` ([`Checker::linuxcnc_undefined_read`]): its name as
    /// `params::named_parameter` writes it. A name found known is kept among the names seen
    /// (its first 8 bytes packed into one integer, and its length), compared with them first.
    #[inline]
    fn linuxcnc_unknown_name(
        &mut self,
        text: &[u8],
        start: usize,
        close: usize,
    ) -> Option<Vec<u8>> {
        let written = &text[start + 2..close];
        let key = name_key(text, start + 2, written.len());
        if self.linuxcnc_named_seen.iter().any(|(k, len, long)| {
            *k == key && *len == written.len() && (*len <= 8 || long.as_slice() == written)
        }) {
            return None;
        }
        self.linuxcnc_name_unseen(text, start, close, key)
    }

    /// [`Checker::linuxcnc_unknown_name`] of a name not among the names seen: looked up,
    /// kept among them if known (out of line: a CAM program's few names are soon all seen).
    #[inline(never)]
    fn linuxcnc_name_unseen(
        &mut self,
        text: &[u8],
        start: usize,
        close: usize,
        key: u64,
    ) -> Option<Vec<u8>> {
        let written = &text[start + 2..close];
        if self.linuxcnc_name_known(written) {
            if self.linuxcnc_named_seen.len() < 8 {
                // (a name with a zero byte, a blank, has no key of its own among the short)
                if written.len() <= 8 && !written.contains(&0) {
                    self.linuxcnc_short_seen[self.linuxcnc_named_seen.len()] = key;
                }
                let long = if written.len() > 8 {
                    written.to_vec()
                } else {
                    Vec::new()
                };
                self.linuxcnc_named_seen.push((key, written.len(), long));
            }
            return None;
        }
        let name = super::params::named_parameter(written);
        // EXISTS[#<name>] asks whether it is defined: no read
        if in_exists(text, start) {
            return None;
        }
        Some(name)
    }

    /// LinuxCNC: whether the block is the line of plain words just read and the tokenizer
    /// walked every bracketed word of it plain (`LineWalks::all`): then no word has an
    /// operation outside its brackets (`linuxcnc_bare_operator` has nothing to say: each is
    /// a letter and one plain pair of brackets), none has a `/` (kept for the read-refusal's
    /// test, `linuxcnc_plain_words`, as `linuxcnc_walk_words` keeps it) and no statement
    /// reads a name. A debug build walks the words again and asserts the same.
    #[inline]
    fn linuxcnc_line_walked(&mut self, b: &BlockView<'_>) -> bool {
        if self.line_walks_of != (b.text.as_ptr() as usize, b.text.len()) || !self.line_walks.all {
            return false;
        }
        let set = self.line_walks.set;
        if cfg!(debug_assertions) {
            assert!(b.statements.is_empty(), "line {}", b.line);
            for (i, w) in b.words.iter().enumerate() {
                let written = i < WALKED && set >> i & 1 != 0;
                assert_eq!(written, !w.expression.is_empty(), "line {}", b.line);
                if written {
                    assert_eq!(self.line_walks.walks[i], walk_expression(w.expression));
                    assert!(self.line_walks.walks[i].plain && w.letter.is_ascii_uppercase());
                }
                assert_eq!(
                    crate::between::bare_operator(w.token),
                    None,
                    "line {}",
                    b.line
                );
            }
        }
        self.linuxcnc_plain_words = (self.stats.blocks, set);
        true
    }

    /// LinuxCNC: whether every named parameter of the walked line's bracketed words
    /// ([`Checker::linuxcnc_line_walked`]) is among the names seen (`linuxcnc_named_seen`:
    /// each a global or one the main program assigned, and a name once assigned stays so
    /// until the next program): then no word reads a name not defined, and
    /// `linuxcnc_named_reads` has nothing to say (a debug build reads them in full and
    /// asserts it). False where one is not: the full reading decides.
    #[inline(always)]
    fn linuxcnc_names_all_seen(&mut self, b: &BlockView<'_>) -> bool {
        // (every name of the line read by the tokenizer as one of the hot names, each a name
        // seen: `LineWalks::hot` holds names of `linuxcnc_short_seen` alone. A debug build
        // looks them up as well, and asserts they are found)
        if self.line_walks.all_hot && !cfg!(debug_assertions) {
            return true;
        }
        self.linuxcnc_names_looked_up(b)
    }

    /// [`Checker::linuxcnc_names_all_seen`] with each name looked up: a name of up to 8
    /// bytes by its key among the hot names' and `linuxcnc_short_seen`, a longer one by its
    /// bytes too. Where all are seen, each short one not hot is made hot (the newest first:
    /// the oldest leave).
    #[inline(never)]
    fn linuxcnc_names_looked_up(&mut self, b: &BlockView<'_>) -> bool {
        let all_hot = self.line_walks.all_hot;
        let walks = &self.line_walks;
        let seen = &self.linuxcnc_named_seen;
        let short = &self.linuxcnc_short_seen;
        let hot = walks.hot.map(|h| h.key());
        // (the keys found that are not hot, the first four)
        let mut fresh = [0u64; 4];
        let mut set = walks.set;
        while set != 0 {
            let i = set.trailing_zeros() as usize;
            set &= set - 1;
            let walk = &walks.walks[i];
            for (n, &(start, close)) in walk.names[..usize::from(walk.count)].iter().enumerate() {
                let (name, close) = (usize::from(start) + 2, usize::from(close));
                let len = close - name;
                let key = walk.keys[n];
                // (a name of up to 8 bytes is its key: no byte of a walked name is zero, a
                // blank, so no key is 0, and no hot key is 0 but `HotName::NONE`'s. A longer
                // one is compared by its bytes too)
                let found = if len <= 8 {
                    debug_assert_ne!(key, 0);
                    hot.contains(&key)
                        || short.contains(&key) && {
                            if let Some(free) = fresh.iter_mut().find(|k| **k == 0 || **k == key) {
                                *free = key;
                            }
                            true
                        }
                } else {
                    let text = &b.words[i].expression[name..close];
                    seen.iter()
                        .any(|(k, l, long)| *k == key && *l == len && long == text)
                };
                if !found {
                    debug_assert!(!all_hot, "line {}: a hot name not seen", b.line);
                    return false;
                }
            }
        }
        for key in fresh.into_iter().take_while(|&k| k != 0) {
            if let Some(name) = HotName::of_key(key) {
                self.line_walks.hot.rotate_right(1);
                self.line_walks.hot[0] = name;
            }
        }
        #[cfg(debug_assertions)]
        {
            assert!(self
                .line_walks
                .hot
                .iter()
                .all(|h| *h == HotName::NONE || self.linuxcnc_short_seen.contains(&h.key())));
            let kept = (self.linuxcnc_named_seen.clone(), self.linuxcnc_short_seen);
            for w in b.words {
                let full = self.linuxcnc_undefined_read(w.expression, w.column);
                assert_eq!(full, None, "line {}", b.line);
            }
            (self.linuxcnc_named_seen, self.linuxcnc_short_seen) = kept;
        }
        true
    }

    /// LinuxCNC: the block's words' expressions walked once ([`walk_expression`]) for the
    /// rules that read their bytes; which of them are plain (and so hold no `/`) kept for the
    /// read-refusal's test of this block (`linuxcnc_plain_words`, by the block's count).
    #[inline(never)]
    fn linuxcnc_walk_words(&mut self, b: &BlockView<'_>) -> [ExpressionWalk; WALKED] {
        let mut walks = [ExpressionWalk::default(); WALKED];
        let mut plain = 0u8;
        // (the tokenizer's walks of the words of this block's line, where it was a line of
        // plain words: a debug build walks them again and asserts the same)
        let written = if self.line_walks_of == (b.text.as_ptr() as usize, b.text.len()) {
            self.line_walks.set
        } else {
            0
        };
        for (i, w) in b.words.iter().take(WALKED).enumerate() {
            if written >> i & 1 != 0 {
                walks[i] = self.line_walks.walks[i];
                debug_assert_eq!(walks[i], walk_expression(w.expression), "line {}", b.line);
                plain |= 1 << i;
            } else if !w.expression.is_empty() {
                walks[i] = walk_expression(w.expression);
                plain |= u8::from(walks[i].plain) << i;
            }
        }
        self.linuxcnc_plain_words = (self.stats.blocks, plain);
        walks
    }

    /// LinuxCNC: the definition a `o<name> sub` opens runs to its `o<name> endsub`; rs274
    /// reads every line between as the definition's, an M2 among them included, so a
    /// definition left open has swallowed the program's end (rs274: "File ended with no
    /// percent sign or program end"). Kept: where and which the open one is.
    fn definition_open(&mut self, b: &BlockView<'_>, statement: Option<&(bool, Vec<u8>)>) {
        match (statement, &self.open_definition) {
            (Some((true, name)), None) => {
                let column = b.statements.first().map_or(1, |s| s.0);
                self.open_definition = Some((b.line, column, name.clone()));
            }
            (Some((false, name)), Some((_, _, open))) if self.definition_closes(name, open) => {
                self.open_definition = None;
                self.linuxcnc_sub_closed = Some(self.stats.blocks);
            }
            _ => {}
        }
    }

    /// Whether an endsub naming `name` closes the open definition labelled `open`: one of its
    /// label, but in a subroutine file not one inside a condition or loop of the body, which
    /// returns when the file is called (a remap body's early `o<name> endsub [1]`) and leaves
    /// the body's lines after it its own ([`Checker::subroutine_file_body`]).
    fn definition_closes(&self, name: &[u8], open: &[u8]) -> bool {
        name == open && (self.sub_file != SubFile::Open || self.linuxcnc_definition_flow.is_empty())
    }

    /// Text outside ASCII in a comment, a string or a LinuxCNC name (TG127, once per file):
    /// the control reads it, a tape code of 7 bits cannot carry it. The message names the
    /// character, its column and what it stands in ([`dialect::outside_ascii_place`]).
    /// `skip`: the bytes of a byte order mark before it (TG135's).
    pub(super) fn outside_ascii(&mut self, line: usize, text: &[u8], skip: usize) {
        if let Some((offset, what)) = dialect::first_outside_ascii(&text[skip..]) {
            let offset = offset + skip;
            self.outside_ascii_noted = true;
            let place = dialect::outside_ascii_place(text, offset, self.config.family);
            let message = format!(
                "{what} {place}: read as text, but ISO and EIA tape codes cannot carry it \
                 (said once per file)"
            );
            self.report(Rule::OutsideAscii, message, line, column(text, offset));
        }
    }

    /// A UTF-8 byte order mark before the file's first line, which editors on Windows write.
    /// LinuxCNC refuses it (rs274ngc's read_text checks every byte of a line against the
    /// characters of its language: "Bad character '\357' used", the mark's first byte in
    /// octal): TG412. The other controls' manuals list the characters they read and the mark
    /// is not among them, nor can a 7-bit tape code carry it: TG135, a warning, since what a
    /// control does with it is not documented. The tokenizer reads the line after it.
    pub(super) fn byte_order_mark(&mut self) {
        if self.config.family == Family::LinuxCnc {
            self.report(
                Rule::LinuxCncRefuses,
                "Bad character '\\357' used (rs274ngc): a UTF-8 byte order mark (EF BB BF) \
                 begins the file; rs274 reads no byte outside its language, so it refuses the \
                 first line (save the file without the mark)"
                    .into(),
                1,
                1,
            );
        } else {
            self.report(
                Rule::ByteOrderMark,
                "a UTF-8 byte order mark (EF BB BF) begins the file: an editor's mark, not part \
                 of the program; the control's manuals do not list it among the characters it \
                 reads and a tape code cannot carry it (tapegate's DNC sender leaves it out; \
                 save the file without it)"
                    .into(),
                1,
                1,
            );
        }
    }

    /// TG110: the program begins with % where the classification has it.
    pub(super) fn program_start(&mut self, line: usize) {
        if self.config.percent {
            self.report(
                Rule::NoProgramStart,
                "the program does not begin with %".into(),
                line,
                1,
            );
        }
    }

    /// TG117: the first line after the end that the control never reads, said once.
    pub(super) fn never_read(&mut self, unread: dialect::Unread) {
        let message = if unread.percent {
            format!(
                "line {} and the lines after it are never read: the file begins with % and \
                 LinuxCNC stops reading at its closing % on line {} (rs274 read_text); passed \
                 over, kept as written",
                unread.line, unread.end
            )
        } else if !self.linuxcnc_later_waits() {
            // (no call of the main program may seek a body after the end: the text of before
            // review 80-lcnc80 R4, which names no body run there; review 81-lcnc81)
            let stop = if unread.end == self.linuxcnc_m99_end {
                format!(
                    "the M99 of the main program on line {} (rs274 2.9 ends the program there, \
                     or loops back to its start: interp_convert.cc convert_stop; an M98 call \
                     finds an O number program after it, reading O-word lines alone)",
                    unread.end
                )
            } else {
                format!(
                    "the M2/M30 on line {} (rs274's driver stops there; a call finds an \
                     o<name> sub definition after it, reading O-word lines alone)",
                    unread.end
                )
            };
            format!(
                "line {} and the lines after it that are not O-word lines are never read: \
                 LinuxCNC stops at {stop}; passed over, kept as written",
                unread.line
            )
        } else if unread.end == self.linuxcnc_m99_end {
            format!(
                "line {} and the lines after it that are not O-word lines are never read, but \
                 for the body of an O number program that a call finds there: LinuxCNC stops \
                 at the M99 of the main program on line {} (rs274 2.9 ends the program there, \
                 or loops back to its start: interp_convert.cc convert_stop; an M98 call finds \
                 an O number program after it, reading O-word lines alone, and runs its body \
                 to its M99); passed over, kept as written",
                unread.line, unread.end
            )
        } else {
            format!(
                "line {} and the lines after it that are not O-word lines are never read, but \
                 for the body of an o<name> sub definition or an O number program that a call \
                 finds there: LinuxCNC stops at the M2/M30 on line {} (rs274's driver stops \
                 there; a call finds such a definition after it, reading O-word lines alone, \
                 and runs its body to its endsub or M99); passed over, kept as written",
                unread.line, unread.end
            )
        };
        self.report(Rule::NotRead, message, unread.line, 1);
    }

    /// LinuxCNC: whether a call of the main program may seek a body after its end: the main
    /// program has a calling line (an o-word `call`, an `M98`, its target known or not).
    fn linuxcnc_later_waits(&self) -> bool {
        !self.linuxcnc_later.ends.is_empty() || self.linuxcnc_later_bodies.main_called()
    }

    /// TG116: words after the program's M02/M30, said once.
    pub(super) fn words_after_end(&mut self, b: &BlockView<'_>) {
        // (the one test of a block before any end, Checker::after_watch)
        if !self.after_watch {
            return;
        }
        // (a Haas's local subprogram after the end, or after a main program's M99:
        // Checker::local_body)
        if self.local_called {
            self.local_body(b);
        }
        if self.ended_line == 0 {
            return;
        }
        let line = b.line;
        // (after a jump the checker cannot follow, an M02 may sit in a branch: no TG116; a
        // LinuxCNC subroutine's body after the end is its definition, run when called)
        if !self.skipped_end
            && !self.after_end_reported
            && !self.unfollowed_noted
            && !self.reading_end.inside_block()
        {
            self.after_end_reported = true;
            // a control family's: ended there, the words are never run, and no source says
            // the control alarms (audit 37: `M30 / (Enable lookahead) / G5.1 Q1`): a
            // warning; the strict ISO profiles (Annex E) and LinuxCNC keep TG116
            let (rule, why) = match self.config.family {
                Family::Iso | Family::LinuxCnc => (Rule::WordsAfterEnd, ""),
                _ => (
                    Rule::WordsAfterEndNotRun,
                    ": the control ends the program there and never runs them unless a jump \
                     reaches them",
                ),
            };
            let message = format!(
                "words after the end of program on line {}{why}",
                self.ended_line
            );
            self.report(rule, message, line, 1);
        }
    }

    /// TG412: a call that surely runs (on `line`, at `column`) of the subroutine `label`,
    /// whose only definition stands in a block known not to run, and no definition of it
    /// after the call ([`Checker::definition_after_call`]; review 52, F7).
    #[cold]
    fn linuxcnc_eof_seeking(&mut self, label: &[u8], line: usize, column: usize) {
        let Some(&(_, defined, block)) = self.linuxcnc_dead_defs.iter().find(|d| d.0 == label)
        else {
            return;
        };
        let label = String::from_utf8_lossy(label);
        let message = format!(
            "{LINUXCNC_EOF_SEEKING} {label} from line: {line} (rs274ngc): the only definition \
             of {label} (line {defined}) stands in the block of line {block}, which does not \
             run, and rs274 skips it without recording the subroutine; the call seeks its sub \
             from here to the end of the file and does not find it (interp_o_word.cc \
             control_back_to; a file of its name on the SUBROUTINE_PATH is opened first where \
             there is one); define the subroutine outside the block"
        );
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// TG126, once per file: the comments holding a harmless ':'.
    pub(super) fn colons_in_comments(&mut self) {
        let Colons {
            count: colons,
            line: first_line,
            column: first_column,
        } = self.colons;
        if colons > 0 {
            let comments = if colons == 1 {
                "a comment holds".to_string()
            } else {
                format!("{colons} comments hold")
            };
            let message = format!(
                "{comments} ':' (the first, line {first_line}); this control reads a comment as \
                 text, so it stops nothing there (checks.comment_colon)"
            );
            self.report(Rule::ColonInComment, message, first_line, first_column);
        }
    }

    /// TG114, TG115: the program ends with M02/M30 and, where the classification has %, the
    /// closing %.
    pub(super) fn program_end(&mut self) {
        let line = self.last_line.max(1);
        // LinuxCNC: a program between two '%' lines ends at the second, without M2
        let percent_ended = self.config.family == Family::LinuxCnc && self.percent_closed;
        // LinuxCNC: a subroutine file with lines before its sub, which a call skips
        let sub_return = self.sub_file == SubFile::Open && self.sub_returns.2 != 0;
        if self.sub_file == SubFile::Closed || sub_return {
            self.subroutine_file_refusals();
        }
        if let Some((label, line, column)) = self.linuxcnc_dead_called.first().cloned() {
            self.linuxcnc_eof_seeking(&label, line, column);
        }
        if self.sub_preamble.1 != 0 && (self.sub_file == SubFile::Closed || sub_return) {
            let (first, sub) = self.sub_preamble;
            let label = String::from_utf8_lossy(&self.sub_label);
            let message = format!(
                "line {first} and the lines after it before the {label} sub on line {sub} \
                 never run when the file is called: {label} call opens it and skips to its \
                 sub (rs274ngc control_back_to; read_items reads only O-word lines while it \
                 skips), so what they set is not set"
            );
            self.report(Rule::NotRead, message, first, 1);
        }
        // (a FANUC-style O number program after the end with no M99: rs274 reads it only
        // where an M98 calls it, and then to the file's end; not judged, as before)
        if std::mem::take(&mut self.linuxcnc_fanuc_open) {
            self.open_definition = None;
        }
        if let Some((at, column, name)) = self.open_definition.take().filter(|_| !sub_return) {
            if self.sub_file == SubFile::Open && self.sub_returns.0 != 0 {
                // (its only endsub stands in a block of the body left open)
                self.definition_returns_open(percent_ended);
                return;
            }
            let name = String::from_utf8_lossy(&name);
            let message = format!(
                "{name} sub is not closed by {name} endsub: rs274 reads the rest of the file, \
                 its M2/M30 and closing % included, as the definition, so the program never \
                 ends (rs274: 'File ended with no percent sign or program end', or 'Failed to \
                 find sub ... before EOF' where a % closes the file)"
            );
            self.report(Rule::NoProgramEnd, message, at, column);
        } else if let Some((label, at, _)) = self.linuxcnc_skipping.take() {
            // (the skip of a block known not to run reached the end: no M2 read in it runs)
            let label = String::from_utf8_lossy(&label);
            let message = format!(
                "File ended with no percent sign or program end (rs274ngc): the {label} block \
                 on line {at} does not run (its condition false, or its count below one), and \
                 rs274 skips every line after it to an o-word line of {label}, which the file \
                 does not have, so no M2/M30 of it runs (interp_read.cc read_items reads only \
                 o-word lines while it skips)"
            );
            self.report(Rule::NoProgramEnd, message, line, 1);
        } else if self.ended_line == 0 && self.sub_ended || sub_return {
            // a subprogram or macro: it returns to its caller, no M02/M30 needed (a LinuxCNC
            // subroutine file returning at an endsub of another label: TG138 there)
        } else if self.empty_folder || self.offsets_section {
            // a memory backup's last folder marker with no program after it (the Robodrill
            // ALL-FLDR punch-out's `&F=/USER/PATH2/` before the closing %), or a Haas's saved
            // offsets after the program's end (O999999): no program
        } else if self.ended_line == 0 && !percent_ended && !self.skipped_end {
            self.report(
                Rule::NoProgramEnd,
                "the program has no M02 or M30".into(),
                line,
                1,
            );
        } else if !self.closed && self.config.percent {
            self.report(
                Rule::NoClosingPercent,
                "M02/M30 is not followed by the closing %".into(),
                line,
                1,
            );
        }
    }

    /// TG102, TG124, TG125: the characters of word `i` -- a lower-case address where the
    /// control does not read lower case natively, an alignment ':' the classification lacks
    /// or that does not start the block.
    pub(super) fn word_characters(&mut self, i: usize, w: &Word<'_>, line: usize) {
        let native_lower = matches!(self.config.family, Family::LinuxCnc | Family::Sinumerik);
        if w.address.is_ascii_lowercase() && !native_lower {
            let message = format!("lower-case address '{}'", w.address as char);
            self.report(Rule::LowerCaseAddress, message, line, w.column);
        }
        if w.letter == b':' {
            if !self.config.alignment {
                let message = "':' alignment, but the profile's classification has no ':'";
                self.report(
                    Rule::AlignmentNotInClassification,
                    message.into(),
                    line,
                    w.column,
                );
            }
            if i > 0 {
                self.report(
                    Rule::AlignmentNotFirst,
                    "alignment ':' must start the block".into(),
                    line,
                    w.column,
                );
            }
        }
    }

    /// TG123: the '/' block skip immediately precedes the sequence number.
    pub(super) fn block_skip(&mut self, b: &BlockView<'_>) {
        if b.skip
            && b.words.first().is_some_and(|w| w.letter != b'N')
            && b.words.iter().any(|w| w.letter == b'N')
        {
            let message = "'/' block skip must immediately precede the sequence number".into();
            self.report(Rule::SkipNotFirst, message, b.line, 1);
        }
        self.skip_within(b);
        self.slash_after_variable(b);
    }

    /// TG128, a doubtful reading: Custom Macro B's `X#146/2` is read as one expression, the
    /// division #146/2, as tapegate reads `X#114-#136`. The manuals write an expression in an
    /// address in brackets (FANUC "Custom macro", referencing variables: `G01 X[#1+#2]`), and
    /// a `/` in the middle of a block is the block skip (TG128); no source at hand says which
    /// of the two a control makes of a `/` after a variable outside brackets, or whether it
    /// alarms. Said at the slash, once per word.
    fn slash_after_variable(&mut self, b: &BlockView<'_>) {
        if self.config.family != Family::MacroB {
            return;
        }
        for w in b.words {
            let e = w.expression;
            let unbracketed = matches!(e, [b'#', ..] | [b'-' | b'+', b'#', ..]);
            if !w.letter.is_ascii_uppercase() || !w.index.is_empty() || !unbracketed {
                continue;
            }
            let mut depth = 0i32;
            let slash = e.iter().position(|&c| {
                match c {
                    b'[' => depth += 1,
                    b']' => depth -= 1,
                    _ => {}
                }
                c == b'/' && depth == 0
            });
            let Some(at) = slash else {
                continue;
            };
            let token = String::from_utf8_lossy(w.token);
            let letter = w.letter as char;
            let before = String::from_utf8_lossy(&e[..at]);
            let after = String::from_utf8_lossy(&e[at + 1..]);
            let message = format!(
                "{token}: a '/' after a variable outside brackets, read as a division ({letter} \
                 is {before}/{after}); a macro expression in an address is written in brackets \
                 ({letter}[{before}/{after}]), and no source at hand says whether the control \
                 divides, reads the '/' as a block skip ({letter}{before}, then /{after}: with \
                 the switch on the rest of the block is skipped) or alarms: the reading is \
                 doubtful"
            );
            // the expression follows the address letter (and its index, none here)
            self.report(Rule::SkipWithinBlock, message, b.line, w.column + 1 + at);
        }
    }

    /// TG128: a Fanuc or Haas skips from a `/` in the middle of the block to the end of the
    /// block when the block-skip switch is on. The block is checked as written (the switch
    /// off); what the switch on leaves out is named here, once per block.
    fn skip_within(&mut self, b: &BlockView<'_>) {
        let Some(at) = b.skip_within else {
            return;
        };
        let skipped: Vec<&[u8]> = b
            .words
            .iter()
            .filter(|w| w.column > at)
            .map(|w| w.token)
            .chain(
                b.statements
                    .iter()
                    .filter(|&&(column, _, _)| column > at)
                    .map(|&(_, _, text)| text),
            )
            .collect();
        let what = if skipped.is_empty() {
            "nothing (no word follows it)".to_string()
        } else {
            String::from_utf8_lossy(&skipped.join(&b' ')).into_owned()
        };
        // what the switch on changes for the blocks after this one, which the checker does not
        // follow: where the machine is, and the modes and feed it runs them in
        let after: Vec<&[u8]> = b
            .words
            .iter()
            .filter(|w| w.column > at)
            .map(|w| w.letter)
            .fold(Vec::new(), |mut kinds, letter| {
                let kind: &[u8] = match letter {
                    b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'A' | b'B' | b'C' => b"position",
                    b'G' => b"modal state",
                    b'F' => b"feed",
                    b'S' => b"speed",
                    // M06 and T the tool, M03-M05 the spindle, M07-M09 the coolant; any other
                    // M code a machine function of its own
                    b'T' | b'D' | b'H' => b"tool or offset",
                    b'M' => b"machine state (M code)",
                    _ => return kinds,
                };
                if !kinds.contains(&kind) {
                    kinds.push(kind);
                }
                kinds
            });
        let differs = if after.is_empty() {
            String::new()
        } else {
            format!(
                "; with it on, what follows runs with another {}, not followed here",
                String::from_utf8_lossy(&after.join(&b" and "[..]))
            )
        };
        let message = format!(
            "'/' in the middle of the block: with the block-skip switch on, the control \
             ignores the block from the slash to its end ({what}); checked with the switch \
             off{differs}"
        );
        self.report(Rule::SkipWithinBlock, message, b.line, at);
    }

    pub(super) fn identification(&mut self, b: &BlockView<'_>) {
        let ident = String::from_utf8_lossy(b.ident);
        let stripped = ident.trim();
        if stripped.is_empty() {
            return;
        }
        if matches!(self.config.family, Family::Sinumerik | Family::Heidenhain) {
            return;
        }
        if dialect::skips_leader(self.config.family, self.config.haas) {
            self.leader_skipped(b.line, stripped);
            return;
        }
        // issue 32, severity by evidence: no Haas or Okuma source says the control alarms
        let unsourced = match self.config.family {
            Family::Okuma => Some("Okuma"),
            Family::MacroB if self.config.haas => Some("Haas"),
            _ => None,
        };
        match (dialect::leader_text(b.ident), unsourced) {
            (Some(dialect::LeaderText::Words), Some(maker)) => {
                let message = format!(
                    "words after % ({}): ISO 6983-1 wants an end of block before the first \
                     block, and no {maker} source at hand says whether the control reads them, \
                     skips them or alarms: write them on a line of their own",
                    py_repr(stripped)
                );
                self.report(Rule::LeaderUnknown, message, b.line, 2);
            }
            (Some(dialect::LeaderText::Letters), Some(maker)) => {
                let message = format!(
                    "identification {} has letters outside parentheses, which ISO 6983-1 \
                     refuses, and no {maker} source at hand says what the control does with \
                     it: enclose it in parentheses",
                    py_repr(stripped)
                );
                self.report(Rule::LeaderUnknown, message, b.line, 2);
            }
            (Some(dialect::LeaderText::Words), None) => {
                let message = format!(
                    "words after % ({}): the first block must follow an end of block",
                    py_repr(stripped)
                );
                self.report(Rule::WordsOnPercentLine, message, b.line, 2);
            }
            (Some(dialect::LeaderText::Letters), None) => {
                let message = format!(
                    "identification {} contains letters and must be enclosed in parentheses",
                    py_repr(stripped)
                );
                self.report(Rule::IdentificationNotInParentheses, message, b.line, 2);
            }
            (None, _) => {}
        }
    }

    /// TG129: a FANUC skips the text between the first `%` and the next LF
    /// ([`dialect::skips_leader`]): a title there is never read, and an O number or a program
    /// name there is lost with it (the program is read as one without its number).
    fn leader_skipped(&mut self, line: usize, leader: &str) {
        let lost = dialect::leader_program_number(leader.as_bytes(), self.config.program_number)
            .map_or(String::new(), |number| {
                format!(
                    "; the program number {} there is lost with it (the program is read without \
                     it)",
                    py_repr(&String::from_utf8_lossy(number))
                )
            });
        let message = format!(
            "the control skips the text after the first % up to the end of the line ({}): not \
             read{lost} (FANUC B-63524EN/01, 8, memory card file format)",
            py_repr(leader)
        );
        self.report(Rule::LeaderSkipped, message, line, 2);
    }

    /// TG122 for a comment's '%' (a rewind stop on a tape reader; not on LinuxCNC or a
    /// SINUMERIK) and
    /// for its ':' where the control stops there; a harmless ':' is counted for TG126.
    pub(super) fn comment(&mut self, comment: &[u8], line: usize, column: usize) {
        if let Some(at) = comment.iter().position(|&c| c == b':') {
            let column = column + chars(comment, at);
            if self.config.colon_stop {
                let message = "comment contains ':', which this control's tape reader takes for \
                               the alignment (rewind) stop"
                    .into();
                self.report(Rule::StopCharacterInComment, message, line, column);
            } else {
                if self.colons.count == 0 {
                    self.colons = Colons {
                        count: 0,
                        line,
                        column,
                    };
                }
                self.colons.count += 1;
            }
        }
        if self.config.family == Family::MacroB {
            self.nested_comment_read(comment, line, column);
        }
        if matches!(self.config.family, Family::LinuxCnc | Family::Sinumerik) {
            // LinuxCNC reads files, not tapes; a SINUMERIK's punched-tape format takes '%' as
            // a file's header only in the first column of a line (840D/840Di/810D Operator's
            // Guide HMI Advanced, "Formats for saving and importing data"): inside a comment,
            // neither stops on it
            return;
        }
        if let Some(at) = comment.iter().position(|&c| c == b'%') {
            let message = "comment contains '%', which a control may read as a rewind stop".into();
            self.report(
                Rule::StopCharacterInComment,
                message,
                line,
                column + chars(comment, at),
            );
        }
    }

    /// TG136: a Fanuc or Haas comment holding a `(`, which the tokenizer read to its matching
    /// `)` because both readings leave the same words in the block (tokenizer::comment_close;
    /// where they differ it refused the block, TG121). Said with what the first reading leaves.
    fn nested_comment_read(&mut self, comment: &[u8], line: usize, column: usize) {
        let mut depth = 0usize;
        let (mut inner, mut first) = (None, None);
        let mut close = None;
        for (i, &c) in comment.iter().enumerate() {
            match c {
                b'(' if depth > 0 && inner.is_none() => {
                    inner = Some(i);
                    depth += 1;
                }
                b'(' => depth += 1,
                b')' if depth > 0 => {
                    depth -= 1;
                    if inner.is_some() && first.is_none() {
                        first = Some(i);
                    }
                    if depth == 0 && inner.is_some() {
                        close = Some(i);
                        break;
                    }
                }
                _ => {}
            }
        }
        let (Some(inner), Some(first)) = (inner, first) else {
            return;
        };
        let end = close.map_or(comment.len(), |close| close + 1);
        let left = String::from_utf8_lossy(&comment[first + 1..end]);
        let left = left.trim();
        let first_reading = if left.is_empty() {
            "the comment ends there".to_string()
        } else if left.bytes().all(|c| c == b')' || crate::lex::blank(c)) {
            format!("a stray '{left}' is left")
        } else {
            format!(
                "'{left}' is left: no word, no end of block, no block skip (a control reading \
                 so alarms on the marks or passes them over)"
            )
        };
        let nested = if close.is_some() {
            "read nested, to the matching ')', it is all comment"
        } else {
            "read nested, it is never closed and runs to the end of the block (an alarm or a \
             comment, TG120)"
        };
        let message = format!(
            "'(' inside a comment: read to its first ')' (column {}), {first_reading}; {nested}. \
             The block's words and its skip are the same either way, so it is read once; no \
             Fanuc or Haas \
             source at hand says which reading the control takes (docs/dialects.md)",
            column + chars(comment, first)
        );
        self.report(
            Rule::NestedCommentRead,
            message,
            line,
            column + chars(comment, inner),
        );
    }

    pub(super) fn program_number(&mut self, b: &BlockView<'_>) {
        // (the first block of words asked once: it is in its place)
        if self.first_words {
            self.first_words = false;
            if self.programs == 0 && self.config.family == Family::MacroB {
                // the file's first program, read from the reset state: it may be the
                // subprogram of a call later in the file (a memory backup's O0002 before its
                // O1000)
                self.first_program(b);
            }
            return;
        }
        // (the letters mask: a block without the letter has no such word to look for; the
        // profile's letter read once, Checker::program_letter)
        if self.letters & self.program_letter == 0 && self.program_letter != u32::MAX {
            return;
        }
        let Some(letter) = self.config.program_number else {
            return;
        };
        if letter == b':' || matches!(letter, b'P' | b'Q' | b'R') {
            return;
        }
        for w in b.words {
            if w.letter == letter {
                let message = format!(
                    "program number {} is not in the first block after %",
                    w.token()
                );
                self.report(Rule::ProgramNumberNotFirst, message, b.line, w.column);
                self.jump_runs_ended();
            }
        }
    }

    /// TG113 for a FANUC program's name in the O number's place (`<NAME>`: B-64014EN/03,
    /// 2.5) in a block after the first of its program (`first`: the block is the first).
    /// Asked of a block with statements only: most blocks hold none.
    #[cold]
    #[inline(never)]
    pub(super) fn program_name(&mut self, b: &BlockView<'_>, first: bool) {
        if first {
            return;
        }
        for &(column, kind, text) in b.statements {
            if kind == Kind::Name && text.first() == Some(&b'<') {
                let message = format!(
                    "program name {} is not in the first block after %: it names a program \
                     only at its start",
                    String::from_utf8_lossy(text)
                );
                self.report(Rule::ProgramNumberNotFirst, message, b.line, column);
                self.jump_runs_ended();
            }
        }
    }

    /// A program's start, whether the one before ended or not (an O number or a name after
    /// the first block, a `%` after the start): the runs where a forward jump is taken end
    /// there, and the jumps whose targets have not come arrive nowhere (review 48 F9: a
    /// GOTO searches its target in its own program, and the next program's locals are its
    /// own).
    pub(super) fn jump_runs_ended(&mut self) {
        self.jumps_pending.clear();
        self.runs.clear();
    }
}

/// The 1-based column of a `(` inside an open comment, or 0.
pub fn nested_comment(text: &[u8]) -> usize {
    let mut open = false;
    for (i, &c) in text.iter().enumerate() {
        if c == b'(' {
            if open {
                return chars(text, i) + 1;
            }
            open = true;
        } else if c == b')' {
            open = false;
        }
    }
    0
}

/// An o-word condition or loop opened or closed (as `dialect::ReadingEnd` follows them), in
/// `open`, the labels of those open (the main program's, or an open definition's body's):
/// `o1 while` closes the `o1 do` it ends, or opens a loop; an `endif`, `endwhile` or
/// `endrepeat` closes its label's block (and any left open inside it: rs274 refuses those).
fn linuxcnc_flow(open: &mut Vec<Vec<u8>>, text: &[u8]) {
    linuxcnc_flow_of(open, text, crate::statement::o_label(text));
}

/// [`linuxcnc_flow`] of a statement whose label is `label` (a computed one's value where the
/// checker knows it: [`Checker::linuxcnc_call_label`]).
/// LinuxCNC: the lines after a subroutine file's early return (an endsub of the definition's
/// label inside a block of its body), as a run of the file as a program reads them
/// ([`Checker::after_early_return`]).
#[derive(Clone, Debug, Default)]
pub(super) struct AfterReturn {
    /// A block stands there.
    any: bool,
    /// An M2/M30 line there that may run (in no block known not to run).
    end: bool,
    /// The o-word blocks opened there: label, whether known to run.
    flow: Vec<(Vec<u8>, Option<bool>)>,
    /// Inside a definition there.
    in_def: bool,
    /// The first o-word line rs274 refuses there: line, column, message.
    refused: Option<(usize, usize, String)>,
    /// The line of the first call of the definition that surely runs with values that make
    /// the block left open skip (0: none).
    skips: usize,
    /// The line of a call that surely runs with values where it returns (0: none).
    holds: usize,
    /// The label of the definition open there ([`AfterReturn::in_def`]), and the o-word
    /// blocks open in its body.
    def_label: Vec<u8>,
    def_flow: Vec<Vec<u8>>,
    /// The definitions there whose body calls the definition, outside its blocks, with
    /// values that make the block left open skip, or calls such a definition: label, the
    /// calls' words for the message (review 77-lcnc77b F7).
    inner: Vec<(Vec<u8>, String)>,
    /// Those words, where [`AfterReturn::skips`] is the line of a call of such a definition.
    via: Option<String>,
    /// The body of the definition open there may have returned, ended the program or run
    /// another call before the line in hand; the main program there has run a call of
    /// another kind: a call after it is not taken as surely reaching the definition.
    def_left: bool,
    other_call: bool,
}

/// What [`Checker::linuxcnc_main_flow`] found of an o-word line of the main program: an
/// `else`/`elseif` after a branch that surely ran (rs274 skips to the `endif`), or a block
/// or branch begun that is known not to run (rs274 skips to the next o-word line of its
/// label).
pub(super) struct FlowStep {
    other_branch: bool,
    dead: bool,
}

/// LinuxCNC: an o-word line as the plane is followed through it
/// ([`Checker::linuxcnc_plane_flow`]): the depth of blocks open before and after it, the
/// block whose branch it switches to, whether that branch is an `else`, whether the branch
/// it ends ran (`None`: not known), whether it ends a branch that surely ran (the rest
/// skipped), and whether it leaves a loop's turn (`break`, `continue`).
pub(super) struct PlaneStep {
    depth: usize,
    open: usize,
    switched: Option<usize>,
    is_else: bool,
    /// Whether the o-word line is the main program's (the motion mode is followed there
    /// only).
    main: bool,
    ran: Option<bool>,
    taken: bool,
    leaves: bool,
    /// For a `break` or `continue`: the depth of the loop it leaves (its label's), where found.
    loop_at: Option<usize>,
}

/// LinuxCNC: the plane where a line stands: the modal state's G17/G18/G19, whether a
/// G17.1-G19.1 is in force beside it (`Checker::linuxcnc_uvw_plane`), and whether the
/// checker cannot know it (`Checker::linuxcnc_plane_unknown`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct PlaneAt {
    plane: i64,
    uvw: bool,
    unknown: bool,
}

impl PlaneAt {
    /// A plane the checker does not know (what no M70 has saved).
    pub(super) const UNKNOWN: PlaneAt = PlaneAt {
        plane: 17,
        uvw: false,
        unknown: true,
    };
}

/// LinuxCNC: a condition or loop open where the plane is followed: the plane at its
/// opening (the one the lines after it run in where none of its branches runs, and the
/// one each branch after an `else`/`elseif` starts in), the planes the branches read so
/// far ended in, whether it has an `else` (some branch then surely runs), and whether a
/// branch read so far surely ran (rs274 runs none after it: review 55c, F8, an
/// `if [1]` / `G18` / `elseif [0]` / `G19` / `endif` leaves G18, not the plane before it).
#[derive(Clone, Debug)]
pub(super) struct PlaneBlock {
    entry: PlaneAt,
    ends: Vec<PlaneAt>,
    /// The motion mode and canned cycle at its opening, and the ones its ways through it
    /// read so far left, as for the plane ([`UNKNOWN_MOTION`]: not known).
    motion_entry: FlowMotion,
    motion_ends: Vec<FlowMotion>,
    has_else: bool,
    taken: bool,
    /// The branch in hand left its loop's turn (a `break` or `continue` of the loop around
    /// it): no way through it reaches the block's next branch or its close.
    left: bool,
}

/// LinuxCNC: the modal state's motion mode and canned cycle through the main program's
/// conditions and loops ([`PlaneBlock`]).
pub(super) type FlowMotion = (Option<i64>, Option<i64>);

/// A motion mode not known ([`FlowMotion`]): none, as after a call.
pub(super) const UNKNOWN_MOTION: FlowMotion = (None, None);

/// LinuxCNC: the motion mode after a condition or loop whose ways through it leave `ends`
/// (`now`: the one read last, in file order): the one they agree on; where one may leave G2
/// or G3 and another not, not known (a bare move after it is an arc one way, a line or a
/// cycle the other); elsewhere the one read last, as before.
fn flow_motion_merged(ends: &[FlowMotion], now: FlowMotion) -> FlowMotion {
    let arc = |e: &FlowMotion| matches!(e, (Some(2 | 3), None));
    match ends.first() {
        Some(&first) if ends.iter().all(|e| *e == first) => first,
        Some(_) if ends.iter().any(arc) && !ends.iter().all(arc) => UNKNOWN_MOTION,
        _ => now,
    }
}

/// LinuxCNC: a condition or loop of the main program open at the line in hand
/// (`Checker::linuxcnc_open_at`), as the checker reads its lines in their order: the first
/// run of them (a loop's first turn).
#[derive(Clone, Debug)]
pub(super) struct OpenBlock {
    /// Its label as written (`o#1`).
    written: Vec<u8>,
    /// The line that opened it.
    line: usize,
    /// Whether its lines up to the line in hand run whenever the program runs to its
    /// opening: known to (Some(true): a condition known true, a `do`, the `else` of an `if`
    /// whose every branch before is known false, a loop's count known above zero), known not
    /// to (Some(false): its lines are the skip of `Checker::linuxcnc_skipping`), or not known.
    /// Set only where every block around it is known to run (its opening runs surely), so
    /// that a line runs surely where every block open is Some(true)
    /// ([`Checker::linuxcnc_runs_surely`]; review 52, F4). A block that closes inside it
    /// leaves it as it was (its lines after that block run where they are reached); a call,
    /// or a `break`/`continue` in a block not known to run, makes it not known.
    runs: Option<bool>,
    /// The line where `runs` was set: its opening, or the `else`/`elseif` of its branch.
    branch: usize,
    /// No o-word line since it opened: its lines up to here ran one after the other, so the
    /// values they set are those its closing label reads.
    straight: bool,
    /// A loop (`while`, `do`, `repeat`), with its opening line's text (the `while`
    /// condition, read again at its end) and, for a `repeat`, whether its count (read where
    /// it opened) turns it again after the first turn.
    looped: Option<(Vec<u8>, Option<bool>)>,
    /// A loop inside whose body a block opened (or branched) on a condition that reads a
    /// parameter, which the checker worked out for the first turn: a later turn may run
    /// other lines, so the state the first turn leaves is not the loop's where it turns again.
    varies: bool,
    /// Its branch in hand was known to run (`runs` Some(true)) until a call made `runs` not
    /// known: the call may set any parameter or end the program, but not undo that the
    /// branch began, so an `else`/`elseif` after it is skipped all the same (interp_o_word.cc:
    /// after a branch that ran rs274 goes to the `endif`; review 55c, F7: `o1 if [1]` /
    /// `o<s> call` / `o1 elseif [1]` / `G2 Y10 R10` in G18 runs in `rs274 -g`). Not inside a
    /// loop, whose later turn may take another branch.
    called: bool,
}

/// LinuxCNC: a loop of the main program's top whose body runs, as
/// [`Checker::linuxcnc_loop_turns`] keeps it: its opening line, for a `repeat` whether its
/// count (read where it opened) is 2 or more, the definitions its body holds (label, line,
/// column), and whether its lines up to here surely ran.
/// The keys of a Haas's local subprograms (M97) among the program numbers
/// ([`Checker::call_works`], [`Checker::in_hand`]...): above every O number (eight digits),
/// below the marks of [`Finding::pending_on`](super::Finding) built from program numbers.
pub(super) const LOCAL_BODY: i64 = 1 << 38;

/// The keys of LinuxCNC definitions after the main program's end called before it
/// ([`Checker::later_call`]): above every [`LOCAL_BODY`] key, the place of the label in
/// [`Checker::later_called`] added.
pub(super) const LATER_DEFINITION: i64 = LOCAL_BODY + 20_000_000_000;

/// The key of the local subprogram at sequence number `sequence` of program `main` (None:
/// the file's first program with no O number): None where either is above 99999 (or a
/// local subprogram's own M97).
fn local_key(main: Option<i64>, sequence: i64) -> Option<i64> {
    let main = main.unwrap_or(0);
    let five = 0..100_000;
    (five.contains(&main) && five.contains(&sequence))
        .then_some(LOCAL_BODY + main * 100_000 + sequence)
}

/// A program's name in the messages: `O2000`, or a local subprogram's sequence number
/// (`N1000`).
pub(super) fn program_name(n: i64) -> String {
    if n >= LATER_DEFINITION {
        "a subroutine after the end".to_string()
    } else if n >= LOCAL_BODY {
        format!("N{}", (n - LOCAL_BODY) % 100_000)
    } else {
        format!("O{n:04}")
    }
}

/// The work offset in force at a call of a program by number ([`Checker::call_works`]): the
/// offset (54-59), the distance mode (G91: true), and the first such call's words and line.
#[derive(Clone, Debug)]
pub(super) struct CallWork {
    work: i64,
    incremental: bool,
    /// The tool length offset in force at the call (G43/G44/G49, and whether by a decimal
    /// code): the body runs under it (review 61a F1).
    length: (i64, bool),
    /// Which side of the travel each axis was outside at the call ([`Checker::outside`]):
    /// the body's first position continues that excursion (review 61a F3).
    outside: [i8; 9],
    /// The offsets a G10 of the caller's run wrote before the call, values known
    /// ([`Checker::offsets_written`]; review 59a F8).
    written: super::limits::Written,
    call: String,
    line: usize,
    /// Its distance mode was lost by calls of this program alone (written after them, not
    /// read there: [`Checker::mode_lost_by`]): it runs in the mode that program leaves.
    mode_by_self: bool,
    /// The calls made under another offset, the rest the same (no G10 value written, the
    /// same distance mode and tool length offset): each offset, its call's words and line,
    /// and where each axis was outside at it. The body's positions are judged under each
    /// of these too (one subprogram called once a fixture, under G54, G55, G56...).
    others: Vec<Other>,
    /// The machine's count of units codes at the call (kept for the first: at the last
    /// call made, [`Checker::call_work_kept`]).
    units_codes: u32,
}

/// A call of [`CallWork::others`]: the offset, the call's words and line, which side of
/// the travel each axis was outside at the call, then after each position of the body, and
/// whether the call's distance mode is the one the program leaves, not known to be the
/// first call's: its findings held to the program's end, dropped where it writes a G90/G91
/// ([`Checker::work_call_tentative_end`]); and whether the caller wrote no units code since
/// the first call (it runs in the units the program leaves: [`super::callmode::Rescale`]).
pub(super) type Other = (i64, String, usize, [i8; 9], bool, bool);

/// A program written after its calls read under their work offset ([`Checker::work_call`]):
/// the call it names and the state before it, given back at its end.
#[derive(Clone, Debug)]
pub(super) struct WorkCall {
    pub(super) work: i64,
    call: String,
    line: usize,
    work_before: Option<i64>,
    lost_before: bool,
    outside_before: [i8; 9],
    length_before: (i64, bool),
    /// [`CallWork::others`]: judged under each while the program runs under the calls'
    /// offset ([`Checker::offset_position_others`]); none once it selects, writes or loses
    /// one of its own.
    pub(super) others: Vec<Other>,
    /// The machine's count of G90/G91 codes at its start, and whether a finding of a
    /// tentative call ([`Other`]) is held.
    pub(super) codes_at: u32,
    pub(super) held: bool,
    /// It lost the profile's offsets ([`Checker::offsets_rewritten`]) while read: the
    /// findings held for the other calls are dropped at its end.
    pub(super) unsure: bool,
    /// The count of units codes and the units at its start, and the positions judged under
    /// the other calls' offsets before a units code of its own (review 77-calls77 F9:
    /// judged again in the units it leaves, [`super::callmode::Rescale`]).
    pub(super) units_codes_at: u32,
    pub(super) units_at: crate::modal::Units,
    pub(super) rescale: Vec<super::callmode::Rescale>,
    /// A position was judged after a units code of its own.
    pub(super) units_cut: bool,
}

impl WorkCall {
    /// What a TG601 of its machine position under offset G`work` adds: the call that runs it
    /// there (`label`: [`Checker::later_label`]).
    pub(super) fn named(&self, number: Option<i64>, label: Option<&[u8]>, work: i64) -> String {
        if work != self.work {
            return String::new();
        }
        Self::named_by(number, label, &self.call, self.line)
    }

    /// What a TG601 of a position run by the call `call` of line `line` adds; `label` that
    /// of a LinuxCNC definition after the end, which its call was kept for.
    pub(super) fn named_by(
        number: Option<i64>,
        label: Option<&[u8]>,
        call: &str,
        line: usize,
    ) -> String {
        // (a LinuxCNC definition after the end: its label, the call's)
        let program = match number {
            // (an `M98 P300` of LinuxCNC's FANUC-style `O300`: its O number, the label's
            // where the P is a parameter, `M98 P#1`: review 80-lcnc80 R9)
            Some(n) if n >= LATER_DEFINITION => match (call.strip_prefix("M98 P"), label) {
                (Some(_), Some([b'o', number @ ..])) => {
                    format!("O{}", String::from_utf8_lossy(number))
                }
                (Some(p), _) => format!("O{p}"),
                (None, _) => call.trim_end_matches(" call").to_string(),
            },
            Some(n) => program_name(n),
            None => "the program".to_string(),
        };
        format!(
            " ({program} runs as called by {call} of line {line}: a subprogram written after \
             its call runs under the work offset in force there)"
        )
    }
}

#[derive(Clone, Debug)]
pub(super) struct LoopDefinitions {
    opened: Vec<u8>,
    twice: Option<bool>,
    defs: Vec<(Vec<u8>, usize, usize)>,
    /// no other o-word line in the body yet, and no call but those of
    /// [`Checker::linuxcnc_loop_call`]
    sure: bool,
    /// a call of those made (the block's own record of its lines, `linuxcnc_open_at`, is
    /// cleared at any call)
    called: bool,
}

/// [`Checker::linuxcnc_condition_value`] with `leaf` the value of a term without an operator
/// outside brackets (a number, a parameter, a function): the one reading of a condition,
/// with the checker's values ([`Checker::linuxcnc_value_of`]) or from numbers alone
/// ([`linuxcnc_constant_runs`]).
fn linuxcnc_condition_of(expression: &[u8], leaf: &dyn Fn(&[u8]) -> Option<f64>) -> Option<f64> {
    let e = expression.trim_ascii();
    let mut depth = 0usize;
    // (the lowest level's last operator: start, end, level, name)
    let mut split: Option<(usize, usize, u8, [u8; 3])> = None;
    let mut i = 0;
    while i < e.len() {
        match e[i] {
            b'[' => depth += 1,
            b']' => depth = depth.checked_sub(1)?,
            b'<' => i += e[i..].iter().position(|&c| c == b'>')?,
            c if c.is_ascii_alphabetic() => {
                let end = e[i..]
                    .iter()
                    .position(|c| !c.is_ascii_alphabetic())
                    .map_or(e.len(), |p| i + p);
                let name = e[i..end].to_ascii_lowercase();
                let level = match name.as_slice() {
                    b"and" | b"or" | b"xor" => 2,
                    b"eq" | b"ne" | b"gt" | b"ge" | b"lt" | b"le" => 3,
                    // (MOD, and a function before its bracket, work out to None below)
                    _ => 9,
                };
                if depth == 0 && level < 9 && split.is_none_or(|s| level <= s.2) {
                    let mut op = [0u8; 3];
                    op[..name.len()].copy_from_slice(&name);
                    split = Some((i, end, level, op));
                }
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    let Some((start, end, _, op)) = split else {
        if let [b'[', inner @ .., b']'] = e {
            // (one bracket around it all, `[..]` not `[..] + [..]`: its inside, which may
            // hold the operators)
            let mut depth = 0usize;
            let whole = inner.iter().all(|&c| {
                match c {
                    b'[' => depth += 1,
                    b']' if depth == 0 => return false,
                    b']' => depth -= 1,
                    _ => {}
                }
                true
            });
            if whole {
                return linuxcnc_condition_of(inner, leaf);
            }
        }
        return leaf(e);
    };
    let a = linuxcnc_condition_of(&e[..start], leaf)?;
    let b = linuxcnc_condition_of(&e[end..], leaf)?;
    let truth = |t: bool| if t { 1.0 } else { 0.0 };
    let diff = (a - b).abs();
    let compared = matches!(
        &op,
        b"eq\0" | b"ne\0" | b"gt\0" | b"ge\0" | b"lt\0" | b"le\0"
    );
    if compared && diff > 0.0 && diff < 1.1e-4 {
        return None;
    }
    Some(match &op {
        b"and" => truth(a != 0.0 && b != 0.0),
        b"or\0" => truth(a != 0.0 || b != 0.0),
        b"xor" => truth((a != 0.0) != (b != 0.0)),
        b"eq\0" => truth(diff == 0.0),
        b"ne\0" => truth(diff != 0.0),
        b"gt\0" => truth(a > b),
        b"ge\0" => truth(a >= b),
        b"lt\0" => truth(a < b),
        b"le\0" => truth(a <= b),
        _ => return None,
    })
}

/// Whether the lines of a LinuxCNC `if`, `while`, `repeat` or `do` (`text`) run, worked out
/// from numbers alone (`o1 if [1]`, `o1 if [2 LT 1]`, `o1 repeat [3]`): None where its
/// condition reads a parameter or a function, whose value at the line the checker may not
/// know (one a caller or an earlier pass changed). The reading of
/// [`Checker::linuxcnc_body_runs`] without the values the checker follows.
pub(super) fn linuxcnc_constant_runs(text: &[u8]) -> Option<bool> {
    let (keyword, condition) = o_keyword_condition(text);
    block_runs(&keyword, || {
        linuxcnc_condition_of(condition, &|e| {
            if e.contains(&b'#') || e.len() > 200 {
                return None;
            }
            let tree = crate::expr::tree(e).ok()?;
            crate::expr::linuxcnc_value(&tree, e, &|_| None).ok()?
        })
    })
}

/// Whether a block of `keyword` runs, its condition's value `value`: a `do` does, an `if`
/// or `while` where the value is not zero, a `repeat` where its count (rounded half to
/// even: `nearbyint`, `repeat [0.5]` runs no time in `rs274 -g`) is one or more.
fn block_runs(keyword: &[u8], value: impl FnOnce() -> Option<f64>) -> Option<bool> {
    if keyword == b"do" {
        return Some(true);
    }
    if !matches!(keyword, b"if" | b"while" | b"repeat") {
        return None;
    }
    let value = value()?;
    Some(if keyword == b"repeat" {
        value.round_ties_even() >= 1.0
    } else {
        value != 0.0
    })
}

/// An o-word line's keyword (lower case) and the text after it (a condition, a count).
fn o_keyword_condition(text: &[u8]) -> (Vec<u8>, &[u8]) {
    let rest = &text[crate::statement::o_label_len(text).min(text.len())..];
    let rest = rest.trim_ascii_start();
    let letters = rest.iter().take_while(|c| c.is_ascii_alphabetic()).count();
    let (keyword, condition) = rest.split_at(letters);
    (keyword.to_ascii_lowercase(), condition.trim_ascii())
}

fn linuxcnc_flow_of(open: &mut Vec<Vec<u8>>, text: &[u8], label: Vec<u8>) {
    let Some(keyword) = crate::statement::o_keyword(text) else {
        return;
    };
    let at = open.iter().rposition(|l| *l == label);
    match (keyword.as_slice(), at) {
        (b"while", Some(at)) | (b"endif" | b"endwhile" | b"endrepeat", Some(at)) => {
            open.truncate(at)
        }
        (b"if" | b"do" | b"repeat" | b"while", _) => open.push(label),
        _ => {}
    }
}

/// A LinuxCNC distance mode as the checker knows it at a line: its caller's (a definition's
/// body before it writes its own), G90 or G91 (`Known(true)`: G91), or not known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Distance {
    Caller,
    Known(bool),
    Unsure,
}

impl Distance {
    /// The mode where either of two may be in force.
    fn merge(self, other: Distance) -> Distance {
        if self == other {
            self
        } else {
            Distance::Unsure
        }
    }
}

/// What a LinuxCNC call level's context holds for M72 (interp_convert.cc: M70 and M73 save
/// the modal state into `sub_context[call_level]` and mark it valid, M71 marks it invalid,
/// M72 refuses an invalid one; a call starts its level empty, interp_o_word.cc
/// `enter_context`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Saved {
    /// Nothing valid, wherever the line runs.
    Empty,
    /// A valid state, with the distance mode saved.
    Valid(Distance),
    /// Valid or not: a save or an invalidation inside a condition or loop.
    Maybe,
}

impl Saved {
    /// The context becomes `new` (`flow`: inside a condition or loop, where the line may not
    /// run: either).
    fn set(&mut self, new: Saved, flow: bool) {
        *self = match (flow, *self, new) {
            (false, _, new) => new,
            (true, Saved::Empty, Saved::Empty) => Saved::Empty,
            (true, Saved::Valid(a), Saved::Valid(b)) => Saved::Valid(a.merge(b)),
            _ => Saved::Maybe,
        };
    }
}

/// LinuxCNC's M72 restore: the value rs274 2.9.0's ` F%.1f` or ` S%.0f` writes of a saved
/// `v` (`places` decimals), rounded, or None on a half, where the double's binary value
/// decides the way (review 57d, F6: `F0.04` saved is written `F0.0`, a zero rate).
fn written(v: Dec, places: u32) -> Option<Dec> {
    if v.scale <= places {
        return Some(v);
    }
    let d = crate::decimal::pow10(v.scale - places)?;
    let (q, r) = (v.mantissa.div_euclid(d), v.mantissa.rem_euclid(d));
    (2 * r != d).then(|| Dec {
        mantissa: crate::decimal::round_quotient(q, r, d, false).0,
        scale: places,
    })
}

/// LinuxCNC: what every M70 or M73 of the main program that may be the one in force saved
/// (one in a condition or loop joins the one before it): the feed mode and the speed, each
/// None where not known or where two such saves differ ([`Checker::linuxcnc_feed_unfollowed`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct LooseSaved {
    mode: Option<i64>,
    /// rs274's feed rate (review 61b F3).
    rate: Option<Dec>,
    speed: Option<Dec>,
    /// A save in a condition or loop among them.
    joined: bool,
}

impl LooseSaved {
    const UNKNOWN: LooseSaved = LooseSaved {
        mode: None,
        rate: None,
        speed: None,
        joined: true,
    };

    /// The values this save and `other` agree on.
    fn merge(self, other: LooseSaved) -> LooseSaved {
        LooseSaved {
            mode: self.mode.filter(|&m| other.mode == Some(m)),
            rate: self.rate.filter(|&v| other.rate == Some(v)),
            speed: self.speed.filter(|&v| other.speed == Some(v)),
            joined: self.joined || other.joined,
        }
    }
}

/// LinuxCNC: a block whose M72 rs274 may drop, the restore's block running in its place
/// ([`Checker::linuxcnc_m72_motion_back`]): the motion mode before it, the canned cycle
/// before it, where the drop is sure the plane and compensation the restore writes (None:
/// the drop only possible), and whether the block writes a plane (G17-G19.1) or a cutter
/// compensation code (G40-G42.1), none of which takes effect where it is dropped.
#[derive(Debug, Clone, Copy)]
pub(super) struct M72Dropped {
    pub(super) motion: super::tooling::LinuxCncMotion,
    pub(super) cycle: Option<M72Cycle>,
    pub(super) restored: Option<(PlaneAt, Option<(i64, bool)>)>,
    pub(super) plane: bool,
    pub(super) compensation: bool,
    /// The block's G90 (false) or G91 (true), read as written.
    pub(super) distance: Option<bool>,
    /// The doubles rs274 holds for X Y Z before the block (`Checker::linuxcnc_double`).
    pub(super) double: [super::tooling::Double; 3],
}

/// LinuxCNC: whether a line of a definition's body surely moves no axis and changes nothing
/// the position is read in (units, distance mode, offsets, tool length, plane): o-word
/// lines other than calls, and words of S, F, T, a parameter below #5000 or named, and M0,
/// M1, M3-M5, M7-M9, M48-M53 of numbers as written. Anything else (a G code, an axis word,
/// M6, M70-M73, a call) may move an axis or change the coordinates the caller's position is
/// read in.
pub(super) fn still_line(b: &BlockView<'_>) -> bool {
    if b.statements.iter().any(|&(_, kind, _)| kind == Kind::Call) {
        return false;
    }
    b.words.iter().all(|w| match w.letter {
        b'S' | b'F' | b'T' | b'N' => true,
        // (a named parameter, or a number below the system's: none is an offset in force)
        b'#' => match w.index.first() {
            Some(c) if c.is_ascii_digit() => std::str::from_utf8(w.index)
                .ok()
                .and_then(|n| n.parse::<u32>().ok())
                .is_some_and(|n| n < 5000),
            Some(_) => true,
            // (`#<name>=`, read whole as the word's expression)
            None => w.expression.first() == Some(&b'<'),
        },
        b'M' => {
            w.expression.is_empty()
                && matches!(
                    w.number,
                    b"0" | b"1"
                        | b"3"
                        | b"4"
                        | b"5"
                        | b"7"
                        | b"8"
                        | b"9"
                        | b"48"
                        | b"49"
                        | b"50"
                        | b"51"
                        | b"52"
                        | b"53"
                )
        }
        _ => false,
    })
}

/// Among a finding's [`super::Finding::pending_on`]: said after a main program's call, surely
/// run, of a label not read yet ([`LaterCalls::ends`]), held until the definition is read.
pub(super) const PENDING_LATER: i64 = -2;

/// LinuxCNC: the labels of the main program's calls in a row (no move, motion code or
/// other o-word line between), the latest first: the mode after them is the latest body's,
/// or, where it leaves the mode it found, the one before ([`Checker::linuxcnc_later_settle`]).
pub(super) type LaterChain = Vec<Vec<u8>>;

/// LinuxCNC: what a definition's body leaves of the motion mode its call found.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum LaterLeft {
    /// G2 or G3, surely.
    Arc(i64),
    /// G0, G1 or a canned cycle, surely.
    Plain,
    /// The mode it found: it writes no motion code and calls nothing; whether every line of
    /// it is still ([`still_line`]: no axis word, whose move depends on the mode found).
    Keeps(bool),
    /// What the body of its last call (the label) leaves, that call outside its conditions
    /// and loops with no motion code after it; where that body keeps the mode, the mode
    /// this body found where it wrote none before the call (true), else not known.
    Via(Vec<u8>, bool),
    /// Not known.
    Unknown,
}

/// LinuxCNC: a call line's line and the axes before it ([`LaterCalls::still`]).
pub(super) type StillAt = (usize, [Option<Dec>; 9], u32, [crate::modal::Drift; 9]);

/// LinuxCNC: the main program's calls of a definition not read yet (rs274 finds one written
/// after M2 when the call runs), whose motion mode after them is not known until the
/// definition is read ([`Checker::linuxcnc_later_move`]).
#[derive(Debug, Clone, Default)]
pub(super) struct LaterCalls {
    /// The call whose mode is still in force, by label, and its line: no o-word line,
    /// motion code or possible M72 drop since, and the labels of the calls in a row before
    /// it, the latest first ([`LaterChain`]). The caller's G2 or G3 in force at it.
    pub(super) pending: Option<(LaterChain, usize, i64)>,
    /// The first move without a motion code or arc word after such a call: the labels, the
    /// call's line, the move's line and column, the caller's G2 or G3.
    pub(super) moves: Vec<(LaterChain, usize, usize, usize, i64)>,
    /// What each definition read leaves of the motion mode its call found, by label
    /// ([`LaterLeft`]), for the moves held after calls in a row (review 63-lcnc63 N2, K8).
    pub(super) left: Vec<(Vec<u8>, LaterLeft, u8)>,
    /// The open definition's last o-word line is a call of this label, outside its
    /// conditions and loops, and whether the body wrote no motion code before it.
    pub(super) body_via: Option<(Vec<u8>, bool)>,
    /// The open definition has read a G word (`.0`), and a line with axis words and no G
    /// word before any (`.1`: 1, or 2 where it has an arc's I, J, K or R, which only an arc
    /// found takes): a move the mode its call found judges (review 75 F1b).
    pub(super) body_bare: (bool, u8),
    /// A call line of the main program whose call is of a definition read before it whose
    /// body moves no axis and calls nothing ([`still_line`]): its line, and
    /// the axes' positions, their unknown marks and drifts before the call forgot them.
    pub(super) still: Option<StillAt>,
    /// The open definition's own M70/M73, read with no condition or loop open, saved a
    /// rate that is surely zero, and no o-word line, call or other M70-M73 came since
    /// ([`Checker::linuxcnc_feed_unfollowed`]).
    pub(super) body_zero_saved: bool,
    /// The main program called a label with no definition read before the call (or a
    /// computed one): rs274 may run a file of that name on its subroutine path, or the
    /// definition written after, either of which may end the program; the sure modes and
    /// kept positions after later calls of the main program are not used (review 62b F2,
    /// F3).
    pub(super) unread: bool,
    /// The main program's calls surely run of a label no definition was read for, by label,
    /// and their lines: where the definition written after answers one and surely ends the
    /// program, the findings of the lines after it are dropped at its `endsub`
    /// ([`Checker::linuxcnc_later_ends`]).
    pub(super) ends: Vec<(Vec<u8>, usize)>,
    /// The open definition wrote a motion code (or a G code of a value not known, or a
    /// call) before its last o-word line, and the line of its `sub`
    /// ([`Checker::linuxcnc_later_arcs`]).
    pub(super) body_moded: bool,
    /// The line of the main program's first M2/M30 outside a definition (0: none yet).
    pub(super) main_end: usize,
    pub(super) sub_line: usize,
}

/// LinuxCNC: the modal state's motion mode, cycle and cycle words before the open
/// definition's `sub`, put back at its `endsub`, and the definition's label
/// ([`Checker::linuxcnc_definition_motion`]).
#[derive(Debug, Clone, Default)]
pub(super) struct MotionBeforeSub {
    pub(super) motion: Option<i64>,
    pub(super) cycle: Option<i64>,
    pub(super) words: [Option<Dec>; 5],
    pub(super) label: Vec<u8>,
    /// The body's `do` loops open, by label, and whether a `break` or `continue` stands in
    /// one (a way out of a turn before its end).
    pub(super) dos: Vec<(Vec<u8>, bool)>,
    /// The line of the body's `while` that closed a `do` whose turn surely ends in the
    /// G0-G3 in force there (no `break` or `continue` in it), the mode after that line.
    pub(super) do_closed: Option<(usize, i64)>,
}

/// LinuxCNC: the canned cycle in force before a block with an M72 while a save is followed
/// (the modal state's motion, cycle and cycle words, and the cycle's bottom outside the XY
/// plane), kept before the block's codes apply: a surely dropped block leaves it in force.
#[derive(Debug, Clone, Copy)]
pub(super) struct M72Cycle {
    pub(super) motion: Option<i64>,
    pub(super) cycle: Option<i64>,
    pub(super) words: [Option<Dec>; 5],
    pub(super) bottom: Option<Dec>,
    /// G73 and G74's R (`linuxcnc_cycle_r`).
    pub(super) r: Option<Dec>,
    /// The units and feed units before the block's G20/G21.
    pub(super) units: (crate::modal::Units, crate::modal::Units),
    /// A B C before the block, and the state's unknown axes: a surely dropped block leaves
    /// them where they were, as X Y Z (review 76-lcnc76a F6).
    pub(super) abc: [Option<Dec>; 3],
    pub(super) unknown: u32,
}

/// LinuxCNC: what the main program's M70 or M73 saved of the feed
/// ([`Checker::linuxcnc_feed_restore`]), or the state an M72 restores from: the feed mode,
/// rs274's feed rate and the speed (None: not known).
#[derive(Debug, Clone, Copy)]
pub(super) struct FeedSaved {
    mode: i64,
    rate: Option<Dec>,
    speed: Option<Dec>,
    /// The spindle's direction (M3, M4, M5) and the cutter compensation (the G40-G42 code,
    /// G41.1/G42.1 among them) the save took, None where not known
    /// ([`Checker::linuxcnc_spindle_restored`]).
    spindle: Option<i64>,
    compensation: Option<(i64, bool)>,
    /// The units and feed units (G20/G21) the save took, or where the M72 runs (before its
    /// block's own G20/G21), None where not known.
    units: Option<(crate::modal::Units, crate::modal::Units)>,
    /// No G or M code since the save (or in the save's block) that may change another
    /// modal group the restore writes: where the feed mode, rate and speed are the saved
    /// ones, the restore writes nothing and the M72 block's motion runs.
    quiet: bool,
    /// `quiet`, and no F or S word either: the restore writes nothing, whatever the values.
    still: bool,
    /// The coolant and the feed override the save took ([`RestoreExtras`]), and whether an
    /// M7-M9, M48 or M49 ran since it (`extras_touched`): they are compared at the M72 by
    /// value, not counted in `quiet`.
    extras: RestoreExtras,
    extras_touched: bool,
}

/// LinuxCNC: the modal M codes besides the spindle's that rs274 2.9.0's restore writes where
/// they differ from the save (interp_convert.cc `gen_m_codes`, from interp_write.cc
/// `write_m_codes`' slots), each None where not known: mist (M7) and flood (M8), off at the
/// start of a program and after M9, and the feed override (M48 on, as at the start; M49
/// off). Slot 4 holds 7 under mist, 9 with both off, none (-1) under flood alone; slot 5 8
/// under flood, else none; slot 6 48 or 49. A slot written where it differs from the save and
/// the saved one is not none (`M8` / `M70` / `M7` / `M72 G2 X0 Y0 R1` is "Current point same
/// as end point of arc" in `rs274 -g`: the restore writes nothing; `M70` / `M8` / `M72 G2 X0
/// Y0 R1` runs, the restore's ` M9` in its place; review 76-lcnc76a F7).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct RestoreExtras {
    pub(super) mist: Option<bool>,
    pub(super) flood: Option<bool>,
    pub(super) feed_override: Option<bool>,
}

impl RestoreExtras {
    /// At the start of a program: coolant off, the overrides on.
    pub(super) const START: RestoreExtras = RestoreExtras {
        mist: Some(false),
        flood: Some(false),
        feed_override: Some(true),
    };
    pub(super) const UNKNOWN: RestoreExtras = RestoreExtras {
        mist: None,
        flood: None,
        feed_override: None,
    };

    /// After the block's M7, M8, M9, M48 or M49 (`code`).
    fn apply(&mut self, code: u8) {
        match code {
            7 => self.mist = Some(true),
            8 => self.flood = Some(true),
            9 => (self.mist, self.flood) = (Some(false), Some(false)),
            48 => self.feed_override = Some(true),
            49 => self.feed_override = Some(false),
            _ => {}
        }
    }

    /// The values after the restore of `self` (the save) where `now` is in force: each slot
    /// written where it differs and the saved one is not none.
    fn restored(self, now: RestoreExtras) -> RestoreExtras {
        match self.written(now) {
            Some(false) => now,
            _ if self != RestoreExtras::UNKNOWN
                && [
                    self.mist,
                    self.flood,
                    self.feed_override,
                    now.mist,
                    now.flood,
                    now.feed_override,
                ]
                .iter()
                .all(Option::is_some) =>
            {
                let mut after = now;
                let (mist, flood) = (self.mist == Some(true), self.flood == Some(true));
                if mist {
                    after.mist = Some(true);
                } else if !flood {
                    (after.mist, after.flood) = (Some(false), Some(false));
                }
                if flood {
                    after.flood = Some(true);
                }
                after.feed_override = self.feed_override;
                after
            }
            _ => RestoreExtras::UNKNOWN,
        }
    }

    /// The values that may be either `self` or `other`: those they agree on.
    fn unsure(self, other: RestoreExtras) -> RestoreExtras {
        RestoreExtras {
            mist: self.mist.filter(|_| self.mist == other.mist),
            flood: self.flood.filter(|_| self.flood == other.flood),
            feed_override: self
                .feed_override
                .filter(|_| self.feed_override == other.feed_override),
        }
    }

    /// Whether the restore of `self` (the save) where `now` is in force writes one of these
    /// codes (None: not known).
    fn written(self, now: RestoreExtras) -> Option<bool> {
        let slot4 = |e: RestoreExtras| match (e.mist?, e.flood?) {
            (true, _) => Some(7),
            (false, true) => Some(-1),
            (false, false) => Some(9),
        };
        let slot5 = |e: RestoreExtras| e.flood.map(|f| if f { 8 } else { -1 });
        let slot6 = |e: RestoreExtras| e.feed_override.map(|o| if o { 48 } else { 49 });
        let mut any_unknown = false;
        for (s, n) in [
            (slot4(self), slot4(now)),
            (slot5(self), slot5(now)),
            (slot6(self), slot6(now)),
        ] {
            match (s, n) {
                (Some(s), Some(n)) if s != n && s != -1 => return Some(true),
                (Some(-1), _) | (Some(_), Some(_)) => {}
                _ => any_unknown = true,
            }
        }
        (!any_unknown).then_some(false)
    }
}

/// LinuxCNC: whether two cutter compensations (the modal state's G40-G42 and whether it is
/// G41.1/G42.1, whose side the state does not keep) surely differ as rs274 compares them, by
/// the side alone (interp_write.cc `write_g_codes`: G40, G41 or G42): one off and the other
/// on, or both G41/G42 and on other sides. `G42` saved and `G42.1 D0.1` in force are the same
/// (review 76-lcnc76a F5: the M72's block runs, its canned cycle refused).
fn compensation_differs((a, a_dynamic): (i64, bool), (b, b_dynamic): (i64, bool)) -> bool {
    let on = |side: i64, dynamic: bool| side != 40 || dynamic;
    on(a, a_dynamic) != on(b, b_dynamic) || !a_dynamic && !b_dynamic && a != b
}

/// LinuxCNC: the distance mode through the open definition's body, read in its order
/// ([`Checker::linuxcnc_body`]). It runs under its caller's mode; a G90/G91 of its own sets
/// it (inside a condition or loop, known in that block from there: `from`, as the main
/// program's); M70-M73 save and restore it in the body's own context; a call takes on the
/// mode the called body returns in. Where it returns, the mode (or the one its M73 saved,
/// which rs274 restores: interp_o_word.cc `leave_context`; LinuxCNC M-codes, "M73 Save and
/// Autorestore Modal State") is the one its caller goes on in: `end`, the modes of all its
/// returns merged.
#[derive(Clone, Debug)]
pub(super) struct BodyDistance {
    /// A definition is open.
    open: bool,
    /// The machine's G91 and its count of distance codes at its `sub`: the main program's
    /// lines after its `endsub` run in it (rs274 reads a definition without running it).
    pub(super) before: (bool, u32),
    mode: Distance,
    from: Option<usize>,
    saved: Saved,
    /// Its M73 ran: Some(true); Some(false): none; None: one inside a condition or loop.
    restore: Option<bool>,
    end: Option<Distance>,
    /// A return outside its conditions and loops was read: the lines after it never run.
    returned: bool,
    /// Its refusals that wait for a call ([`CallRefusal`]).
    refusals: Vec<CallRefusal>,
    /// An M2 or M30 outside its conditions and loops, before any return and not deleted by
    /// the block skip: a call of it ends the program there (`rs274 -g` reads no line after
    /// the call; review 48, c19).
    ends: bool,
}

impl Default for BodyDistance {
    fn default() -> Self {
        BodyDistance {
            open: false,
            before: (false, 0),
            mode: Distance::Caller,
            from: None,
            saved: Saved::Empty,
            restore: Some(false),
            end: None,
            returned: false,
            refusals: Vec::new(),
            ends: false,
        }
    }
}

impl BodyDistance {
    /// The mode becomes `mode` at depth `depth` of the body's conditions and loops.
    fn write(&mut self, mode: Distance, depth: usize) {
        if self.mode == mode {
            return;
        }
        self.mode = mode;
        self.from = (depth > 0 && mode != Distance::Unsure).then_some(depth);
    }

    /// The body's flow went to depth `open`, or switched branch at `switched`.
    pub(super) fn scope(&mut self, open: usize, switched: Option<usize>) {
        if let Some(from) = self.from {
            if open < from || switched.is_some_and(|at| at < from) {
                self.mode = Distance::Unsure;
                self.from = None;
            }
        }
    }

    /// A return here: the mode its caller goes on in, merged into `end`.
    fn returns(&mut self) {
        let here = match (self.saved, self.restore) {
            (Saved::Empty, _) | (_, Some(false)) => self.mode,
            (Saved::Valid(saved), Some(true)) => saved,
            (Saved::Valid(saved), None) => saved.merge(self.mode),
            (Saved::Maybe, _) => Distance::Unsure,
        };
        self.end = Some(self.end.map_or(here, |end| end.merge(here)));
    }
}

/// A LinuxCNC body's line that rs274 refuses where the body runs, said at its calls in the
/// main program (a definition runs only when called): a G53 in G91 (`caller_g91`: where its
/// caller's mode is G91, the body having written none of its own before it; review 50, F4),
/// an M72 with nothing saved in the body's context (F5), or a `break`/`continue` of the
/// subroutine's own label (review 52, F9).
#[derive(Clone, Copy, Debug)]
pub(super) struct CallRefusal {
    line: usize,
    column: usize,
    caller_g91: bool,
    m72: bool,
    /// The line stands inside a condition or loop of the body: it runs for some calls only,
    /// so the refusal does not hold at any call (review 51, F17).
    flow: bool,
    /// A `break` or `continue` naming the subroutine's own label, no loop's (review 52, F9).
    exit: bool,
}

impl CallRefusal {
    fn message(&self, token: &str, line: usize) -> String {
        if self.exit {
            format!("{SUB_LABEL_EXIT} ({token} of line {line} runs it)")
        } else if self.m72 {
            format!("{M72_EMPTY} (in the body {token} of line {line} runs)")
        } else if self.caller_g91 {
            format!(
                "{G53_INCREMENTAL} (the body runs in the G91 of {token} of line {line}, having                  written no G90/G91 of its own before this line)"
            )
        } else {
            format!("{G53_INCREMENTAL} (the body's own G91; {token} of line {line} runs it)")
        }
    }
}

/// rs274's refusal of a `break` or `continue` of a subroutine's own label (`o<s> continue` in
/// `o<s> sub`, `rs274 -g`: "3: undefined O-word label: 'o<s> continue'"; interp_o_word.cc
/// `control_find_oword` finds no `do` or `while` of the label at the call level).
const SUB_LABEL_EXIT: &str = "undefined O-word label (rs274ngc): this break or continue names \
     the label of the subroutine it stands in, and rs274 leaves only a do or while by them: \
     the body has no loop of that label; name the loop's label, or return by o<name> return";

/// rs274's refusal of a G53 in G91.
pub(super) const G53_INCREMENTAL: &str = "Cannot use g53 incremental (rs274ngc): G53's axis \
     words are machine coordinates, absolute; G90 first";

/// rs274's refusal of an M72 with nothing saved at its call level.
const M72_EMPTY: &str = "Cannot restore context from invalid stack frame - missing M70/M73? \
     (rs274ngc): M72 restores the modal state M70 or M73 saved at this call level (the main \
     program's, or the running subroutine's), and none is saved here (or M71 invalidated it)";

/// rs274's refusal of a call whose subroutine it seeks to the end of the file (after it
/// the label and "from line: N", the call's; interp_o_word.cc `control_back_to`).
const LINUXCNC_EOF_SEEKING: &str = "EOF in file seeking o-word:";

/// What a LinuxCNC block does to the distance mode ([`Checker::linuxcnc_distance_modal`],
/// [`Checker::linuxcnc_body`]).
struct DistanceStep {
    /// Its last G90 (false) or G91 (true).
    distance: Option<bool>,
    g53: bool,
    /// Its M70, M71, M72 or M73 (one a block: one M code of group 7).
    m7: Option<u8>,
    /// A G17-G19 or G17.1-G19.1 of its own (rs274 runs it after the M code of group 7).
    plane: bool,
    /// A G or M code written by a parameter: perhaps any.
    unread_g: bool,
    unread_m: bool,
    g_column: usize,
    m_column: usize,
}

impl DistanceStep {
    /// The mode after the block's G90/G91 (`g91`), `restored` by its M72 where it has one:
    /// rs274 restores by running a line of its own where the saved state differs from the
    /// one in force (interp_convert.cc `restore_settings`), and the block's G90/G91 is not
    /// applied after it (rs274 -g: `G90` / `M70` / `G91` / `M72 G91` ends in G90; with
    /// nothing to restore, `M70` / `M72 G91`, in G91): either.
    fn written(&self, restored: Distance, g91: bool) -> Distance {
        if self.m7 == Some(72) {
            restored.merge(Distance::Known(g91))
        } else {
            Distance::Known(g91)
        }
    }
}

/// [`DistanceStep`] of block `b`.
fn distance_step(b: &BlockView<'_>) -> DistanceStep {
    let mut step = DistanceStep {
        distance: None,
        g53: false,
        m7: None,
        plane: false,
        unread_g: false,
        unread_m: false,
        g_column: 0,
        m_column: 0,
    };
    for w in b.words {
        let code = || {
            if !w.expression.is_empty() || !w.index.is_empty() {
                return None;
            }
            std::str::from_utf8(w.number).ok()?.parse::<f64>().ok()
        };
        match w.letter {
            b'G' => {
                if step.g_column == 0 {
                    step.g_column = w.column;
                }
                match code() {
                    Some(90.0) => step.distance = Some(false),
                    Some(91.0) => step.distance = Some(true),
                    Some(53.0) => step.g53 = true,
                    Some(17.0 | 18.0 | 19.0 | 17.1 | 18.1 | 19.1) => step.plane = true,
                    Some(_) => {}
                    None => step.unread_g = true,
                }
            }
            b'M' => match code() {
                Some(m @ (70.0 | 71.0 | 72.0 | 73.0)) => {
                    step.m7 = Some(m as u8);
                    step.m_column = w.column;
                }
                Some(_) => {}
                None => step.unread_m = true,
            },
            _ => {}
        }
    }
    step
}

/// An o-word label's name as rs274ngc keys it (interp_read.cc `read_o`: a `<name>`'s text,
/// a number's `%d`): `o100` and `o<100>` are `100`.
pub(super) fn bare_label(label: &[u8]) -> Vec<u8> {
    let rest = label.strip_prefix(b"o").unwrap_or(label);
    match rest {
        [b'<', name @ .., b'>'] => name.to_vec(),
        _ => rest.to_vec(),
    }
}

/// The parameters an o-word label worked out as the line runs reads (`o#1`, `o[#1+#<n>]`),
/// by their keys as `Checker::params` holds them; None where it reads one whose number is
/// itself worked out (`o##2`, `o#[#2]`).
fn label_reads(label: &[u8]) -> Option<Vec<Vec<u8>>> {
    let mut reads = Vec::new();
    let mut i = 0;
    while i < label.len() {
        if label[i] != b'#' {
            i += 1;
            continue;
        }
        match label.get(i + 1) {
            Some(b'<') => {
                let close = i + 2 + label[i + 2..].iter().position(|&c| c == b'>')?;
                reads.push(super::params::named_parameter(&label[i + 2..close]));
                i = close + 1;
            }
            Some(d) if d.is_ascii_digit() => {
                let digits = label[i + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_digit())
                    .count();
                reads.push(super::params::parameter_name(
                    b'#',
                    &label[i + 1..i + 1 + digits],
                ));
                i += 1 + digits;
            }
            _ => return None,
        }
    }
    Some(reads)
}

/// An `else` or `elseif` of a condition open in `open`: the index of its `if` there.
fn linuxcnc_branch_switch(open: &[Vec<u8>], text: &[u8], label: &[u8]) -> Option<usize> {
    let keyword = crate::statement::o_keyword(text)?;
    if !matches!(keyword.as_slice(), b"else" | b"elseif") {
        return None;
    }
    open.iter().rposition(|l| *l == label)
}

/// The first local named parameter `text` reads (`#<zz>`, as `params::named_parameter`
/// writes it) that is not a global (`#<_zz>`), not among `assigned`, and not read inside
/// `EXISTS[..]` ([`Checker::linuxcnc_body_locals`]).
fn body_unassigned(text: &[u8], assigned: &HashSet<Vec<u8>>) -> Option<Vec<u8>> {
    let mut i = 0;
    while let Some(at) = text[i..].windows(2).position(|p| p == b"#<") {
        let start = i + at;
        let close = start + 2 + text[start + 2..].iter().position(|&c| c == b'>')?;
        i = close + 1;
        let name = super::params::named_parameter(&text[start + 2..close]);
        if name.get(2) == Some(&b'_') || assigned.contains(&name) {
            continue;
        }
        if in_exists(text, start) {
            continue;
        }
        return Some(name);
    }
    None
}

/// Whether the named parameter at `start` of `text` is the argument of LinuxCNC's
/// `EXISTS[#<name>]`, which asks whether it is defined and reads no value.
fn in_exists(text: &[u8], start: usize) -> bool {
    let before: Vec<u8> = text[..start]
        .iter()
        .rev()
        .copied()
        .filter(|&c| !blank(c))
        .skip_while(|&c| c == b'[')
        .take(6)
        .collect();
    before.len() == 6 && before.eq_ignore_ascii_case(b"stsixe")
}
#[cfg(test)]
mod tests {
    use super::super::testing::{
        check, check_in, dialect, findings, fired, iso_mill, of_family, program,
    };
    use super::super::{Config, ProfileFacts};
    use crate::lex::{Dialect, Family};
    use crate::rules::Rule;

    /// A closing o-word with a computed label (`o#1 endsub`, `o#1 endif`): rs274ngc's
    /// `read_o` works out its value where it reads the line and matches the label by it
    /// (`rs274 -g`: `#1=100` closes `o100 sub`, `#1=200` leaves it open, "File ended with no
    /// percent sign or program end"; `#1=5` inside `o5 if` closes it).
    #[test]
    fn a_computed_closing_label_is_matched_by_its_value() {
        let lcnc = || of_family(Family::LinuxCnc);
        let errors = |text: &str| -> Vec<(Rule, usize)> {
            check(lcnc(), text)
                .iter()
                .filter(|f| f.rule.severity() == crate::rules::Severity::Error)
                .map(|f| (f.rule, f.line))
                .collect()
        };
        let sub = "G21 G90\n#1=100\no100 sub\nG0 X1\no#1 endsub\no100 call\nM2\n";
        assert_eq!(errors(sub), []);
        assert_eq!(
            errors(&sub.replace("#1=100", "#1=200")),
            [(Rule::NoProgramEnd, 3)]
        );
        // a value the checker does not know: taken as closing, said
        let unknown = sub.replace("#1=100", "#1=[#5220*100]");
        assert_eq!(errors(&unknown), []);
        let notes: Vec<_> = findings(lcnc(), &unknown, Rule::NotFollowed)
            .into_iter()
            .filter(|f| f.message.contains("value the checker does not know"))
            .map(|f| f.line)
            .collect();
        assert_eq!(notes, [5]);
        // a condition closed by its value: the line after it runs, judged
        let flow = "G21 G90\no5 if [1]\n#1=5\no#1 endif\nG0 X#<nope>\nM2\n";
        assert_eq!(errors(flow), [(Rule::LinuxCncRefuses, 5)]);
        assert_eq!(errors(&flow.replace("#1=5", "#1=6")), []);
    }

    /// Review 48, F19: rs274 keeps a subroutine's definition and a condition's or loop's label
    /// for the whole program (interp_o_word.cc `control_save_offset`, `offset_map`), and
    /// refuses a second of them on another line (each compared with `rs274 -g`): a sub
    /// defined again ("redefining sub: o|100| already defined", by a computed label of the
    /// same value too), an `if` or `repeat` of any label recorded, a `while` of one recorded
    /// by another keyword than `do` ("duplicate O-word label"). A `do` of a label recorded is
    /// no refusal, nor a label in a body and in the main program (a body's labels are its
    /// own), nor one whose first use may not have run (inside a condition).
    #[test]
    fn a_linuxcnc_label_kept_for_the_whole_program_is_refused_when_used_again() {
        let lcnc = || of_family(Family::LinuxCnc);
        let refused = |text: &str| -> Vec<(usize, String)> {
            findings(lcnc(), text, Rule::LinuxCncRefuses)
                .into_iter()
                .map(|f| {
                    (
                        f.line,
                        f.message.split(" (rs274ngc)").next().unwrap().to_string(),
                    )
                })
                .collect()
        };
        let head = "G21 G90\n";
        let sub = "o100 sub\nG0 X1\no100 endsub\n";
        for second in ["o100 sub", "o[100] sub", "o+100.0 sub", "o<100> sub"] {
            let text = format!("{sub}{second}\nG0 X2\no100 endsub\n{head}o100 call\nM2\n");
            assert_eq!(
                refused(&text),
                [(4, "redefining sub: o|100| already defined".to_string())],
                "{second}"
            );
        }
        let named = "o<s> sub\nG0 X1\no<s> endsub\no<S> sub\nG0 X2\no<s> endsub\nM2\n";
        assert_eq!(
            refused(named),
            [(4, "redefining sub: o|s| already defined".into())]
        );
        let if_ = |first: &str, second: &str| {
            format!("{head}{first}\nG0 X1\n{}\n{second}\nG0 X2\no1 end\nM2\n", {
                if first.contains(" do") {
                    "o1 while [0]".to_string()
                } else {
                    format!("o1 end{}", first.split(' ').nth(1).unwrap())
                }
            })
        };
        let dup_if = "duplicate O-word label - already defined in line 2: 'o1 if [1]'";
        let text = if_("o1 if [1]", "o1 if [1]").replace("o1 end\n", "o1 endif\n");
        assert_eq!(refused(&text), [(5, dup_if.to_string())]);
        let text = if_("o1 if [0]", "o1 while [0]").replace("o1 end\n", "o1 endwhile\n");
        assert_eq!(
            refused(&text),
            [(
                5,
                "duplicate O-word label: 'o1 while [0]' - defined in line 2".into()
            )]
        );
        let text = if_("o1 do", "o1 repeat [1]").replace("o1 end\n", "o1 endrepeat\n");
        assert_eq!(
            refused(&text),
            [(
                5,
                "duplicate O-word label: 'o1 repeat [1]' - defined in line 2".into()
            )]
        );
        // the first a parameter's value
        let text = format!("{head}#1=1\no#1 if [1]\no#1 endif\no1 if [1]\no1 endif\nM2\n");
        assert_eq!(refused(&text).len(), 1);
        assert_eq!(refused(&text)[0].0, 5);
        // no refusal: a do again, a body's label, a first use that may not have run
        let text = if_("o1 do", "o1 do").replace("o1 end\n", "o1 while [0]\n");
        assert_eq!(refused(&text), []);
        let body = "o<s> sub\no1 if [1]\no1 endif\no<s> endsub\n";
        let text = format!("{body}{head}o1 if [1]\no1 endif\no<s> call\no<s> call\nM2\n");
        assert_eq!(refused(&text), []);
        let text =
            format!("{head}o2 if [0]\no1 if [1]\no1 endif\no2 endif\no1 if [1]\no1 endif\nM2\n");
        assert_eq!(refused(&text), []);
        // a loop's own line again is no second label
        let text = format!(
            "{head}#1=0\no1 while [#1 LT 3]\n#1=[#1+1]\no2 if [1]\no2 endif\no1 endwhile\nM2\n"
        );
        assert_eq!(refused(&text), []);
    }

    /// Review 49a, F5: the labels kept for the whole program and the subs defined are looked
    /// up by name (a list searched in turn made 80,000 labels take 6.6 s): among 3,000 of
    /// each, the first used again at the end is refused with its own line, a new one is not.
    #[test]
    fn a_linuxcnc_label_among_thousands_is_found_by_its_name() {
        let n = 3000;
        let mut text = String::from("G21 G90\n");
        for k in 1..=n {
            text.push_str(&format!("o<s{k}> sub\nG0 X1\no<s{k}> endsub\n"));
        }
        for k in 1..=n {
            text.push_str(&format!("o{k} if [1]\nG0 X1\no{k} endif\n"));
        }
        let subs = 1 + 3 * n;
        let again = |first: &str, line: usize| {
            let mut t = text.clone();
            t.push_str(&format!("{first}\nG0 X2\n"));
            let label = first.split(' ').next().unwrap();
            let end = if first.contains("sub") {
                "endsub"
            } else {
                "endif"
            };
            t.push_str(&format!("{label} {end}\nM2\n"));
            let said: Vec<_> = findings(of_family(Family::LinuxCnc), &t, Rule::LinuxCncRefuses)
                .into_iter()
                .map(|f| {
                    (
                        f.line,
                        f.message.split(" (rs274ngc)").next().unwrap().to_string(),
                    )
                })
                .collect();
            (said, line)
        };
        let (said, line) = again("o<s1> sub", 2 + 6 * n);
        assert_eq!(
            said,
            [(line, "redefining sub: o|s1| already defined".to_string())]
        );
        let (said, line) = again("o1 if [1]", 2 + 6 * n);
        let first = subs + 1;
        assert_eq!(
            said,
            [(
                line,
                format!("duplicate O-word label - already defined in line {first}: 'o1 if [1]'")
            )]
        );
        let (said, _) = again("o<s0> sub", 0);
        assert_eq!(said, []);
    }

    /// Review 48, F10: a closing word whose label is worked out as the line runs is read with
    /// the values of its line (`rs274 -g`: `#1=3` / `o#1 if [1]` / `#1=4` / `o#1 endif` is
    /// "undefined O-word label"; with `o#1 while [0]` the body never runs and the endwhile
    /// closes it). Refused where the block surely ran; said (TG140) where the checker cannot
    /// follow the value (`#1=[#1+1]`) or the block may not run; and a label whose parameters
    /// did not change closes its block (the line after it judged again).
    #[test]
    fn a_linuxcnc_closing_label_is_read_with_the_values_its_block_set() {
        let lcnc = || of_family(Family::LinuxCnc);
        let refused = |text: &str| fired(lcnc(), text, Rule::LinuxCncRefuses);
        let noted = |text: &str| -> Vec<usize> {
            findings(lcnc(), text, Rule::NotFollowed)
                .into_iter()
                .filter(|f| f.message.contains("set what it reads"))
                .map(|f| f.line)
                .collect()
        };
        let text = "G21 G90\n#1=3\no#1 if [1]\n#1=4\no#1 endif\nM2\n";
        assert_eq!(refused(text), [(5, 1)]);
        assert!(findings(lcnc(), text, Rule::LinuxCncRefuses)[0]
            .message
            .starts_with("undefined O-word label (rs274ngc)"));
        for (from, to) in [("if [1]", "while [1]"), ("o#1 endif", "o#1 else\no3 endif")] {
            let text = text.replace(from, to).replace("endif\nM2", "endwhile\nM2");
            let text = if from == "if [1]" {
                text
            } else {
                text.replace("endwhile", "endif")
            };
            assert_eq!(refused(&text), [(5, 1)], "{text}");
        }
        // (a value worked out from one known, review 52, F7: rs274 -g, "5: undefined O-word
        // label: 'o#1 endif'")
        let counted = text.replace("#1=4", "#1=[#1+1]");
        assert_eq!(refused(&counted), [(5, 1)], "{counted}");
        // the body may not run, or its value is not followed: said, taken as closing
        for (from, to) in [("if [1]", "if [#5220 GT 1]"), ("#1=4", "#1=[#1+#5220]")] {
            let text = format!(
                "{}G0 X#<nope>\nM2\n",
                text.replace(from, to).replace("M2\n", "")
            );
            assert_eq!(noted(&text), [5], "{text}");
            assert_eq!(refused(&text), [(6, 4)], "{text}");
        }
        // nothing it reads set since: its block's own value, closed
        let kept = "G21 G90\n#1=5\no#1 if [1]\nG0 X1\no#1 endif\nG0 X#<nope>\nM2\n";
        assert_eq!(refused(kept), [(6, 4)]);
        assert_eq!(noted(kept), []);
    }

    #[test]
    fn a_call_of_a_sub_that_sets_no_feed_mode_keeps_the_mode_before_it() {
        // issue 32, item 4: G93, then a call of a sub defined before it that only moves, then
        // a G1 without F: TG402 (rs274: "F word missing with inverse time g1 move")
        let linuxcnc = || of_family(Family::LinuxCnc);
        let t = "o<t> sub\nG0 Y1\no<t> endsub\n";
        let s = "o<s> sub\nG1 X1 F10\no<t> call\no<s> endsub\n";
        let text = |before: &str, after: &str| {
            format!("G21 G17 G90 F100\n{before}G93\no<s> call\nG1 X2\nM2\n{after}")
        };
        let check = |t: &str| fired(linuxcnc(), t, Rule::InverseTimeWithoutFeed);
        assert_eq!(check(&text(&format!("{t}{s}"), "")), [(11, 4)]);
        // a body that writes a feed mode, an end, or a code not known: not judged
        for code in ["G94", "G95", "M2", "M72", "G#1", "M98 P1"] {
            let before = format!(
                "{t}{}",
                s.replace("G1 X1 F10", &format!("{code}\nG1 X1 F10"))
            );
            assert_eq!(check(&text(&before, "")), [], "{code}");
            let nested = format!("{}{s}", t.replace("G0 Y1", code));
            assert_eq!(check(&text(&nested, "")), [], "{code} in the sub it calls");
        }
        // defined after the call, or calling one defined after it: not judged
        assert_eq!(check(&text("", &format!("{s}{t}"))), []);
        assert_eq!(check(&text(s, t)), []);
        // a sub calling itself: each body is visited once
        let own = "o<s> sub\nG1 X1 F10\no<s> call\no<s> endsub\n";
        assert_eq!(check(&text(own, "")), [(8, 4)]);
    }

    #[test]
    fn an_if_all_of_whose_branches_end_ends_the_main_program_at_its_endif() {
        // issue 32: o<s> is defined after an if/else whose branches both end; the program
        // never comes to the definition again after the call (rs274 runs to its end)
        let linuxcnc = || of_family(Family::LinuxCnc);
        let text = |branch: &str| {
            format!(
                "G21 G17 G90\no<s> call\no1 if [#1 GT 0]\nM2\no1 else\n{branch}\no1 endif\n\
                 o<s> sub\nG0 X3\no<s> endsub\nM2\n"
            )
        };
        let check = |t: &str| fired(linuxcnc(), t, Rule::LinuxCncRefuses);
        assert_eq!(check(&text("M2")), []);
        assert_eq!(check(&text("M30")), []);
        // a nested if whose branches both end ends the branch it stands in
        assert_eq!(check(&text("o2 if [#2]\nM2\no2 else\nM2\no2 endif")), []);
        // a branch that runs on: the definition is read after the call
        assert_eq!(check(&text("G0 X2")), [(8, 1)]);
        assert_eq!(check(&text("o2 if [#2]\nM2\no2 endif")), [(10, 1)]);
        // no else: the condition may be false
        let no_else = "G21 G17 G90\no<s> call\no1 if [#1 GT 0]\nM2\no1 endif\n\
                       o<s> sub\nG0 X3\no<s> endsub\nM2\n";
        assert_eq!(check(no_else), [(6, 1)]);
    }

    #[test]
    fn next_hash_finds_the_first_hash_in_and_after_the_chunks_of_eight() {
        use super::next_hash;
        let text = b"[#<yscale>*-56.12]";
        assert_eq!(next_hash(text, 0), Some(1));
        assert_eq!(next_hash(text, 2), None);
        // in the second chunk, in the tail after the chunks, and the first of two in a chunk
        assert_eq!(next_hash(b"abcdefgh#", 0), Some(8));
        assert_eq!(next_hash(b"abcdefghijk#", 3), Some(11));
        assert_eq!(next_hash(b"ab#cd#gh", 0), Some(2));
        assert_eq!(next_hash(b"ab#cd#gh", 3), Some(5));
        // a byte just below or above `#` in the chunk is not taken for one
        assert_eq!(next_hash(b"\"$\"$\"$\"$#", 0), Some(8));
        assert_eq!(next_hash(b"", 0), None);
        assert_eq!(next_hash(b"abc", 3), None);
    }

    /// Expressions drawn from the bytes that matter to the three LinuxCNC rules that read a
    /// word's expression (brackets, `/`, `#<`, `>`, names' letters, a global's `_`, EXISTS's),
    /// by a fixed xorshift, each wrapped in brackets or not.
    fn drawn_expressions(count: usize) -> Vec<Vec<u8>> {
        let alphabet = b"[]]#<<>>>/*+-.1 aAb_x";
        let mut next = crate::drawn::xorshift(0x2545_F491_4F6C_DD1D);
        // pieces of a CAM program's expressions, and a few that end the walk's plain ones
        let pieces: [&[u8]; 20] = [
            b"#<ab>",
            b"#<x>",
            b"#<Ab>",
            b"#<a b>",
            b"#<_a>",
            b"#<abcdefgh>",
            b"#<abcdefghi>",
            b"#1",
            b"2.5",
            b"*",
            b"-",
            b"+",
            b" ",
            b"#<",
            b"/",
            b"[",
            b"]",
            b"a",
            b">",
            b"#<a/b>",
        ];
        (0..count)
            .map(|_| {
                let len = (next() % 25) as usize;
                let mut e: Vec<u8> = if next().is_multiple_of(2) {
                    (0..len)
                        .map(|_| alphabet[(next() % alphabet.len() as u64) as usize])
                        .collect()
                } else {
                    (0..len / 3)
                        .flat_map(|_| {
                            let k = next() % 64;
                            // (the last seven, which end a plain one, one draw in eight)
                            let k = if k < 8 { 13 + k % 7 } else { k % 13 };
                            pieces[k as usize].iter().copied()
                        })
                        .collect()
                };
                match next() % 4 {
                    0 => {}
                    1 => e = [b"[#<".as_slice(), &e, b"]"].concat(),
                    2 => e = [b"[EXISTS[#<".as_slice(), &e, b"]"].concat(),
                    _ => e = [b"[".as_slice(), &e, b"]"].concat(),
                }
                e
            })
            .collect()
    }

    #[test]
    fn the_walk_of_an_expression_finds_what_each_rule_s_own_walk_finds() {
        use super::{walk_expression, Checker};
        use crate::check::testing::run;
        // a checker with names assigned (`#<ab>`, `#<x>`): names known, unknown and global
        let (mut checker, _) = run(
            of_family(Family::LinuxCnc),
            &dialect(Family::LinuxCnc),
            "#<ab> = 1\n#<x> = 2\nG0 X1\n",
        );
        let names = checker.linuxcnc_named.clone();
        let mut plain = 0;
        let mut read = 0;
        for e in drawn_expressions(200_000) {
            let walk = walk_expression(&e);
            if !walk.plain {
                continue;
            }
            plain += 1;
            // the bare-operator refusal's own walk: nothing outside the brackets
            let token = [b"Y".as_slice(), &e].concat();
            assert_eq!(crate::between::bare_operator(&token), None, "{e:?}");
            // the read-refusal's test: no `/`
            assert!(!e.contains(&b'/'), "{e:?}");
            // the named reads: the first unknown name the walk's names give, as the
            // expression's own walk finds it, from the same names seen
            checker.linuxcnc_named.clone_from(&names);
            checker.linuxcnc_named_seen.clear();
            let fast = walk.names[..usize::from(walk.count)]
                .iter()
                .find_map(|&(s, c)| checker.linuxcnc_unknown_name(&e, s.into(), c.into()));
            let seen = checker.linuxcnc_named_seen.clone();
            checker.linuxcnc_named_seen.clear();
            let full = Checker::linuxcnc_undefined_read(&mut checker, &e, 7).map(|(n, _)| n);
            assert_eq!(fast, full, "{}", String::from_utf8_lossy(&e));
            read += usize::from(full.is_some());
            // (and the names seen kept alike: each compared by its key)
            if fast.is_none() {
                assert_eq!(seen, checker.linuxcnc_named_seen, "{e:?}");
            }
        }
        // the draw reaches the walk's plain expressions and their unknown names
        assert!(
            plain > 20_000 && read > 2_000,
            "{plain} plain, {read} unknown reads"
        );
    }

    #[test]
    fn a_walked_line_s_rules_find_what_the_full_reading_finds() {
        // drawn LinuxCNC programs: assignments of names, lines of plain and bracketed words
        // (a CAM program's `Y[#<yscale>*-3.6]`, names assigned or not, global, long, in
        // other case or with blanks; numbered parameters, signs, inner groups, functions,
        // `/`, `**`; drawn bytes), comments and o-words between. Each is checked as written,
        // where a line of plain words has its bracketed words walked by the tokenizer
        // (`linuxcnc_line_walked`, `linuxcnc_names_all_seen`: a debug build asserts them
        // against the full reading), and with a blank after each bracketed word's letter,
        // which rs274 reads alike and which sends the line to the full reading: the same
        // findings.
        let mut next = crate::drawn::xorshift(0x9E37_79B9_7F4A_7C15);
        let names = [
            "ab",
            "x",
            "Ab",
            "a b",
            "_a",
            "abcdefgh",
            "abcdefghi",
            "ABCDEFGHI",
            "yscale",
        ];
        let drawn = drawn_expressions(6_000);
        let mut pick = 0;
        let (mut lines, mut walked) = (0, 0);
        for _ in 0..400 {
            let mut fast = String::from("G21 G90 G94\nG0 X0 Y0 Z0\n");
            let mut full = fast.clone();
            for n in 0..(next() % 24 + 4) {
                let line = match next() % 10 {
                    0 | 1 => format!(
                        "#<{}> = {}\n",
                        names[(next() % names.len() as u64) as usize],
                        next() % 5
                    ),
                    2 => ["(c)\n", "o1 if [1]\n", "o1 endif\n", "G1 X1 F100\n", "M2\n"]
                        [(next() % 5) as usize]
                        .to_string(),
                    _ => {
                        let mut line = format!("N{}", n * 10);
                        let mut spaced = line.clone();
                        for letter in ["X", "y", "Z", "F", "S"]
                            .iter()
                            .take((next() % 4 + 1) as usize)
                        {
                            let expression = match next() % 6 {
                                0 => format!("{}", next() % 100),
                                1 => {
                                    pick += 1;
                                    String::from_utf8_lossy(&drawn[pick % drawn.len()]).into_owned()
                                }
                                k => {
                                    let a = names[(next() % names.len() as u64) as usize];
                                    let b = names[(next() % names.len() as u64) as usize];
                                    match k {
                                        2 => format!("[#<{a}>*-{}.5]", next() % 90),
                                        3 => format!("[-#<{a}>+#1*2-#<{b}>]"),
                                        4 => format!("[#<{a}>*[#<{b}>-1]]"),
                                        _ => format!("[SIN[#<{a}>]**2/#<{b}>]"),
                                    }
                                }
                            };
                            let blank = if expression.starts_with('[') { " " } else { "" };
                            line.push_str(&format!("{letter}{expression}"));
                            spaced.push_str(&format!("{letter}{blank}{expression}"));
                        }
                        lines += 1;
                        walked += usize::from(line != spaced);
                        fast.push_str(&line);
                        fast.push('\n');
                        full.push_str(&spaced);
                        full.push('\n');
                        continue;
                    }
                };
                fast.push_str(&line);
                full.push_str(&line);
            }
            fast.push_str("M2\n");
            full.push_str("M2\n");
            let config = of_family(Family::LinuxCnc);
            let said = |program: &str| -> Vec<(Rule, usize, String)> {
                check(config.clone(), program)
                    .into_iter()
                    .map(|f| (f.rule, f.line, f.message))
                    .collect()
            };
            assert_eq!(said(&fast), said(&full), "{fast}");
        }
        assert!(
            lines > 3_000 && walked > 2_000,
            "{lines} lines, {walked} bracketed"
        );
    }

    #[test]
    fn a_name_s_key_is_its_bytes_whether_loaded_at_once_or_one_by_one() {
        use crate::tokenizer::name_key;
        // a name followed by 8 bytes or more (loaded at once) and at the text's end (one by
        // one): the same key; names of one length that differ in their first 8: keys differ
        for len in 0..12 {
            let name: Vec<u8> = (0..len).map(|k| b'a' + k as u8).collect();
            let mut followed = name.clone();
            followed.extend_from_slice(b">*-3.608]");
            let at_end = [b"[#<".as_slice(), &name].concat();
            assert_eq!(
                name_key(&followed, 0, len),
                name_key(&at_end, 3, len),
                "{len}"
            );
            if len > 0 {
                let mut other = name.clone();
                other[len.min(8) - 1] = b'Z';
                let other_followed = [other.as_slice(), b">*-3.608]"].concat();
                assert_ne!(
                    name_key(&followed, 0, len),
                    name_key(&other_followed, 0, len)
                );
            }
        }
    }

    fn without_percent() -> Config {
        Config {
            facts: ProfileFacts {
                percent: false,
                ..iso_mill().facts
            },
            ..iso_mill()
        }
    }

    #[test]
    fn a_slash_after_a_macro_variable_is_a_doubtful_reading() {
        // read as the division, said as doubtful at the slash (no source settles it)
        let macro_b = || of_family(Family::MacroB);
        let text = program("#146 = 10.\nG90 G92 X#146/2\nG00 X[#146/2] Y-#1/#2");
        assert_eq!(
            fired(macro_b(), &text, Rule::SkipWithinBlock),
            [(3, 14), (4, 19)]
        );
        let found = findings(macro_b(), &text, Rule::SkipWithinBlock);
        assert!(
            found[0].message.contains("X#146, then /2") && found[0].message.contains("doubtful"),
            "{}",
            found[0].message
        );
        // in brackets, or without a slash: nothing; LinuxCNC reads no such word
        let quiet = program("#146 = 10.\nG00 X[#146/2] Y#1\nG00 X#114-#136");
        assert_eq!(fired(macro_b(), &quiet, Rule::SkipWithinBlock), []);
    }

    #[test]
    fn a_sinumerik_defines_its_variables_at_the_head_of_the_program() {
        // Job Planning, DEF: the definition section at the head, then the program section
        let sinumerik = || of_family(Family::Sinumerik);
        let late = "N10 G0 X0\nN20 DEF REAL ABC=1\nN30 G0 X=ABC\nN40 M30\n";
        assert_eq!(
            fired(sinumerik(), late, Rule::DefinitionAfterProgram),
            [(2, 5)]
        );
        let found = findings(sinumerik(), late, Rule::DefinitionAfterProgram);
        assert!(
            found[0].message.contains("(line 1)"),
            "{}",
            found[0].message
        );
        for quiet in [
            "N10 DEF REAL ABC=1\nN20 DEF INT I\nN30 G0 X=ABC\nN40 M30\n",
            // comments, a block number alone, DEFINE and EXTERN are no program section yet
            "; PART 1\nN5\nDEFINE M6 AS L6\nEXTERN SUB1(REAL)\nDEF REAL A\nG0 X=A\nM30\n",
            // a PROC opens a subprogram's definition section
            "G0 X0\nM17\nPROC SUB2\nDEF REAL B=2\nG0 X=B\nM17\n",
        ] {
            assert_eq!(
                fired(sinumerik(), quiet, Rule::DefinitionAfterProgram),
                [],
                "{quiet}"
            );
        }
        // a statement of the program section (MSG, an assignment) begins it as words do
        for text in ["MSG(\"A\")\nDEF REAL A\nM30\n", "R1=5\nDEF REAL A\nM30\n"] {
            assert_eq!(
                fired(sinumerik(), text, Rule::DefinitionAfterProgram).len(),
                1,
                "{text}"
            );
        }
        // another family's DEF is no SINUMERIK definition
        assert_eq!(fired(iso_mill(), late, Rule::DefinitionAfterProgram), []);
    }

    #[test]
    fn a_program_begins_with_percent_and_ends_with_m02_and_the_closing_percent() {
        let body = "N10 G01 X1. F100.";
        assert_eq!(fired(iso_mill(), &program(body), Rule::NoProgramStart), []);
        assert_eq!(fired(iso_mill(), &program(body), Rule::NoProgramEnd), []);
        assert_eq!(
            fired(iso_mill(), &program(body), Rule::NoClosingPercent),
            []
        );
        assert_eq!(
            fired(iso_mill(), "G01 X1. F100.\nM02\n%", Rule::NoProgramStart),
            [(1, 1)]
        );
        assert_eq!(
            fired(iso_mill(), "%\nG01 X1. F100.\n", Rule::NoProgramEnd),
            [(2, 1)]
        );
        assert_eq!(
            fired(
                iso_mill(),
                "%\nG01 X1. F100.\nM30\n",
                Rule::NoClosingPercent
            ),
            [(3, 1)]
        );
        // without % in the classification none is asked for; the end still is
        assert_eq!(
            fired(
                without_percent(),
                "G01 X1. F100.\nM02",
                Rule::NoProgramStart
            ),
            []
        );
        assert_eq!(
            fired(
                without_percent(),
                "G01 X1. F100.\nM02",
                Rule::NoClosingPercent
            ),
            []
        );
        assert_eq!(
            fired(without_percent(), "G01 X1. F100.", Rule::NoProgramEnd),
            [(1, 1)]
        );
        // LinuxCNC: a program between two '%' lines ends at the second, without M2
        let linuxcnc = of_family(Family::LinuxCnc);
        assert_eq!(
            fired(linuxcnc, "%\nG01 X1. F100.\n%\n", Rule::NoProgramEnd),
            []
        );
    }

    #[test]
    fn linuxcnc_never_reads_the_lines_after_its_end() {
        let linuxcnc = || of_family(Family::LinuxCnc);
        // the shops program's hand-added line after M30: not read, no TG100, one TG117
        let text = "G0 X1\nM30\nprint[\"Hello World!\"]\nG0 X\n%\n";
        let found = check(linuxcnc(), text);
        assert!(
            found.iter().all(|f| f.rule != Rule::Unreadable),
            "{found:?}"
        );
        let said: Vec<_> = found.iter().filter(|f| f.rule == Rule::NotRead).collect();
        assert_eq!(said.len(), 1, "{found:?}");
        assert_eq!((said[0].line, said[0].column), (3, 1));
        assert!(
            said[0].message.contains("M2/M30 on line 2"),
            "{}",
            said[0].message
        );
        // nor TG116: the words after the end are not read
        assert_eq!(fired(linuxcnc(), text, Rule::WordsAfterEnd), []);
        // a definition after the end is read, as rs274 finds it: its errors are said, its
        // words are no words after the end
        let sub = "o<s> call\nM2\no<s> sub\nG0 X\no<s> endsub\n";
        assert_eq!(fired(linuxcnc(), sub, Rule::Unreadable), [(4, 4)]);
        let sub = "G0 X0\nM2\no<s> sub\nG0 X1\no<s> endsub\n";
        assert_eq!(fired(linuxcnc(), sub, Rule::WordsAfterEnd), []);
        assert_eq!(fired(linuxcnc(), sub, Rule::NotRead), []);
        // after the closing % of a file begun with %: nothing
        let closed = "%\nG0 X1\nM2\n%\no<s> sub\nG0 X\n";
        assert_eq!(fired(linuxcnc(), closed, Rule::NotRead), [(5, 1)]);
        assert_eq!(fired(linuxcnc(), closed, Rule::Unreadable), []);
        // comments and blank lines after the end are nothing to say
        assert_eq!(fired(linuxcnc(), "M2\n\n(end)\n", Rule::NotRead), []);
        // review 51, F19: a line inside an `o1 if` block after the end is the first never
        // read, not the line after the block; a definition's body is read where it is called
        for (text, line) in [
            ("G0 X0\nM2\no1 if [1]\nG0 X1\no1 endif\nM2\n", 4),
            ("G0 X0\nM2\no<s> sub\nG0 X1\no<s> endsub\nG0 X2\n", 6),
        ] {
            let found = findings(linuxcnc(), text, Rule::NotRead);
            assert_eq!(found.len(), 1, "{text}");
            assert_eq!((found[0].line, found[0].column), (line, 1), "{text}");
            assert!(
                found[0]
                    .message
                    .starts_with(&format!("line {line} and the lines after it")),
                "{}",
                found[0].message
            );
        }
        // an M2 in a branch may not run: what follows is read
        let branch = "o1 if [#1 GT 0]\nM2\no1 endif\nG0 X\nM2\n";
        assert_eq!(fired(linuxcnc(), branch, Rule::Unreadable), [(4, 4)]);
        // a Fanuc reads on: no TG117; a line it cannot read right after the M30 is never
        // run (TG108, reach.rs), one a jump may name keeps its TG100
        let fanuc = "G0 X1\nM30\nG0 X--2\n";
        assert_eq!(
            fired(of_family(Family::MacroB), fanuc, Rule::NeverRun),
            [(3, 6)]
        );
        assert_eq!(fired(of_family(Family::MacroB), fanuc, Rule::NotRead), []);
        let named = "G0 X1\nM30\nN10 G0 X--2\n";
        assert_eq!(
            fired(of_family(Family::MacroB), named, Rule::Unreadable),
            [(3, 10)]
        );
    }

    #[test]
    fn a_linuxcnc_sub_body_reading_a_local_it_never_assigns_fails_when_called() {
        // rs274 keeps local named parameters per call level: the caller's #<zz> is not seen
        // in the body ("Named parameter #<zz> not defined", review 38, finding 9)
        let linuxcnc = || of_family(Family::LinuxCnc);
        let text = |before: &str, body: &str, call: &str| {
            format!("G21 G90\nG0 X0 Y0 Z1\n{before}o<s> sub\n{body}o<s> endsub\n{call}M2\n")
        };
        let refused = |t: &str| fired(linuxcnc(), t, Rule::LinuxCncRefuses);
        let read = "G1 X#<zz> F100\n";
        assert_eq!(refused(&text("", read, "o<s> call\n")), [(4, 4)]);
        // the caller's own: still not visible
        assert_eq!(refused(&text("#<zz> = 1\n", read, "o<s> call\n")), [(5, 4)]);
        let found = findings(
            linuxcnc(),
            &text("", read, "o<s> call\n"),
            Rule::LinuxCncRefuses,
        );
        assert!(
            found[0]
                .message
                .contains("#<zz> not defined (rs274ngc) when o<s> is called"),
            "{}",
            found[0].message
        );
        // a condition of the body runs: its read is judged; an endsub's value too
        let cond = "o1 if [#<zz> GT 0]\nG1 X1 F100\no1 endif\n";
        assert_eq!(refused(&text("", cond, "o<s> call\n")), [(4, 1)]);
        let ret = "#<zz> = 1\nG0 X0 Y0 Z1\no<s> sub\no<s> endsub [#<zz>]\no<s> call\nM2\n";
        assert_eq!(fired(linuxcnc(), ret, Rule::LinuxCncRefuses), [(4, 1)]);
        // what rs274 accepts: a global, a name the body assigns before (or earlier in the
        // line), a read inside a condition of the body (it may not run), EXISTS, a
        // definition the file never calls (a remap's body, whose locals its words give)
        for (before, body, call) in [
            ("#<_zz> = 1\n", "G1 X#<_zz> F100\n", "o<s> call\n"),
            ("", "#<zz> = 3\nG1 X#<zz> F100\n", "o<s> call\n"),
            ("", "#<zz> = 3 G1 X#<zz> F100\n", "o<s> call\n"),
            (
                "",
                "o1 if [#1 GT 0]\nG1 X#<zz> F100\no1 endif\n",
                "o<s> call [0]\n",
            ),
            (
                "",
                "o1 if [EXISTS[#<zz>]]\nG1 X1 F100\no1 endif\n",
                "o<s> call\n",
            ),
            ("#<zz> = 1\n", read, ""),
        ] {
            let t = text(before, body, call);
            assert_eq!(refused(&t), [], "{t}");
        }
        // a read after the assignment's word in its line is one; before it is not
        let late = "G1 X#<zz> F100 #<zz> = 3\n";
        assert_eq!(refused(&text("", late, "o<s> call\n")), [(4, 4)]);
    }

    #[test]
    fn linuxcnc_ends_at_an_m2_written_by_a_parameter_or_expression_not_at_a_deleted_one() {
        // rs274 reads an M value as a parameter or an expression (read_integer_value): each
        // of these is the end as `M2` is, the lines after it never read (review 38, 8)
        let linuxcnc = || of_family(Family::LinuxCnc);
        let text = |end: &str| format!("#<two> = 2\nG21 G90\nG0 X0 Y0 Z1\n{end}\nG0 X1\nM2\n");
        for end in [
            "M2",
            "M#<two>",
            "M[2]",
            "M[1+1]",
            "M[#<two>*15]",
            "M[2.00001]",
            "N5 M#<two>",
        ] {
            let found = check(linuxcnc(), &text(end));
            let rules: Vec<_> = found
                .iter()
                .filter(|f| matches!(f.rule, Rule::NotRead | Rule::WordsAfterEnd))
                .map(|f| (f.rule, f.line))
                .collect();
            assert_eq!(rules, [(Rule::NotRead, 5)], "{end}");
            assert!(
                found[0..].iter().any(|f| f.message.contains("on line 4")),
                "{end}"
            );
        }
        // the M word's value is the one from before the line's own assignments (rs274 makes
        // them at the line's end: `#1=5` ... `#1=2 M#1` is M5, `#1=2` ... `#1=5 M#1` M2; `rs274
        // -g`, review 48, F8)
        let same_line = |before: &str, on: &str| {
            let text = format!("G21 G90\n{before}\nG0 X1\n{on}\nG0 X2\nM2\n");
            fired(linuxcnc(), &text, Rule::NotRead)
        };
        assert_eq!(same_line("#1=5", "#1=2 M#1"), []);
        assert_eq!(same_line("(none)", "#1=2 M#1"), []);
        assert_eq!(same_line("#1=5", "#1=7 M#1"), []);
        assert_eq!(same_line("#1=2", "#1=5 M#1"), [(5, 1)]);
        // a value not known, or no end: read on
        for end in ["M#<nope>", "M[1+2]", "M#1", "M0"] {
            let text = text(end);
            assert_eq!(fired(linuxcnc(), &text, Rule::NotRead), [], "{end}");
            assert_eq!(fired(linuxcnc(), &text, Rule::WordsAfterEnd), [], "{end}");
        }
        // a block delete's `/M2` ends the program only with the switch off: with it on rs274
        // runs the lines after it (`rs274 -b`), so they are read and checked, no TG116/TG117
        let deleted = text("/M2");
        assert_eq!(fired(linuxcnc(), &deleted, Rule::NotRead), []);
        assert_eq!(fired(linuxcnc(), &deleted, Rule::WordsAfterEnd), []);
        assert_eq!(
            fired(linuxcnc(), &text("/M2\nG0 X"), Rule::Unreadable),
            [(5, 4)]
        );
        // ... and it is the program's end for TG114 (with the switch off it ends there)
        let last = "G21 G90\nG0 X0 Y0 Z1\n/M2\n";
        assert_eq!(fired(linuxcnc(), last, Rule::NoProgramEnd), []);
        // a subroutine file's end after its endsub by an expression: the file's end as M2
        for end in ["M2", "M[1+1]"] {
            let sub = format!("#<k> = 3\no<sx> sub\nG1 X#<k> F100\no<sx> endsub\n{end}\n");
            let found = check(linuxcnc(), &sub);
            assert!(
                found.iter().all(|f| f.rule != Rule::NoProgramEnd),
                "{end}: {found:?}"
            );
            assert_eq!(fired(linuxcnc(), &sub, Rule::NotRead), [(1, 1)], "{end}");
        }
    }

    #[test]
    fn linuxcnc_refuses_a_fractional_label_on_any_o_word_and_closes_a_function_s_label() {
        // rs274's read_o reads every o-word's label as an integer: `o100.5 if` and `o100.5 sub`
        // stop it at their line, "Non integer value for integer" (`rs274 -g`; review 48, F5)
        let linuxcnc = || of_family(Family::LinuxCnc);
        let refused = |text: &str| fired(linuxcnc(), text, Rule::LinuxCncRefuses);
        assert_eq!(
            refused("G21 G90\no100.5 if [1]\nG0 X1\no100.5 endif\nM2\n"),
            [(2, 1)]
        );
        assert_eq!(
            refused("G21 G90\n#1=3\no[#1+.5] while [0]\no[#1+.5] endwhile\nM2\n"),
            [(3, 1)]
        );
        let sub = "o100.5 sub\nG0 X1\no100.5 endsub\nG21 G90\no100.5 call\nM2\n";
        assert_eq!(refused(sub), [(1, 1)]);
        // (the endsub's label is known, a fraction: no note that it is not known)
        assert!(findings(linuxcnc(), sub, Rule::NotFollowed)
            .iter()
            .all(|f| f.line != 3));
        assert_eq!(
            refused("G21 G90\no100 if [1]\nG0 X1\no100.0 endif\nM2\n"),
            []
        );
        // a label not worked out (`osqrt[10000] sub`): its endsub taken as closing it, said
        let sub = "osqrt[10000] sub\nG0 X1\no100 endsub\nG21 G90\no100 call\nM2\n";
        assert_eq!(fired(linuxcnc(), sub, Rule::NoProgramEnd), []);
        assert_eq!(fired(linuxcnc(), sub, Rule::EndsubNamedOtherwise), []);
        assert!(findings(linuxcnc(), sub, Rule::NotFollowed)
            .iter()
            .any(|f| f.line == 3));
        // `oabs[-100] sub` is o100 sub, closed by `o100 endsub` (review 48, F4)
        let sub = "oabs[-100] sub\nG0 X1\no100 endsub\nG21 G90\no100 call\nM2\n";
        assert_eq!(fired(linuxcnc(), sub, Rule::NoProgramEnd), []);
        assert_eq!(fired(linuxcnc(), sub, Rule::EndsubNamedOtherwise), []);
    }

    #[test]
    fn linuxcnc_refuses_a_named_parameter_read_before_its_assignment() {
        // interp_namedparams.cc, each compared with rs274 -g: the line refused, if any
        let cases: &[(&str, Option<usize>)] = &[
            ("G0 X#<nope>", Some(3)),
            ("#<a> = #<nope>", Some(3)),
            ("o1 if [#<nope> GT 0]\no1 endif", Some(3)),
            ("o<s> call [#<arg>]", Some(3)),
            // the name is defined when its assignment is read, its own value included
            ("#<x> = [#<x> + 1]\nG0 X#<x>", None),
            ("#<x> = 1 G0 X#<x>", None),
            ("G0 X#<x> #<x> = 1", Some(3)),
            ("#<x> = 1 #<y> = [#<x> + #<z>]", Some(3)),
            // names as rs274 reads them: blanks left out, case ignored
            ("#<A b> = 1\nG0 X#< a B >", None),
            // EXISTS asks; globals and comments are not judged
            ("#<y> = EXISTS[#<nope>]\n#<w> = exists [ # < nope > ]", None),
            ("G0 X#<_x>\n(DEBUG, #<nope>)", None),
            // a subroutine's body is not judged; its locals are not the caller's
            ("o<s> sub\nG0 X#<inner>\no<s> endsub\nG0 X1", None),
            (
                "o<s> sub\n#<q> = 1\no<s> endsub\no<s> call\nG0 X#<q>",
                Some(7),
            ),
            // after a condition or loop, which lines run the checker does not follow: not
            // judged (rs274 refuses this loop's first pass, and runs the guarded read and the
            // branch not taken below: review 16c)
            ("o1 repeat [2]\nG0 X#<w>\n#<w> = 1\no1 endrepeat", None),
            (
                "#<i> = 0\no1 while [#<i> LT 2]\no2 if [#<i> GT 0]\nG1 X#<prev>\no2 endif\n\
                 #<prev> = #<i>\n#<i> = [#<i> + 1]\no1 endwhile",
                None,
            ),
            ("o1 if [0]\nG0 X#<never>\no1 endif", None),
            // after the block's end (a `do` closed by its `while`) the read is judged again
            // (rs274 refuses it: review 17)
            ("o1 do\nG1 X1\no1 while [0]\nG0 X#<u>", Some(6)),
            ("o1 if [1]\nG1 X1\no1 endif\nG0 X#<u>", Some(6)),
            // the lines in their order: an assignment in a branch counts as made
            ("o1 if [#1 GT 0]\n#<v> = 1\no1 endif\nG0 X#<v>", None),
        ];
        for &(body, line) in cases {
            let text = format!("G21 G90\nG0 X0 Y0\n{body}\nM2\n");
            let found: Vec<usize> =
                findings(of_family(Family::LinuxCnc), &text, Rule::LinuxCncRefuses)
                    .iter()
                    .filter(|f| f.message.starts_with("Named parameter"))
                    .map(|f| f.line)
                    .collect();
            assert_eq!(found, line.into_iter().collect::<Vec<_>>(), "{body}");
        }
        // another family's #<..> is no LinuxCNC name
        let other = "G21 G90\nG0 X#<nope>\nM30\n";
        assert!(findings(of_family(Family::MacroB), other, Rule::LinuxCncRefuses).is_empty());
    }

    #[test]
    fn linuxcnc_names_read_on_every_line_are_judged_as_each_first_read_is() {
        // a CAM program's scaled words: five names, more than the tokenizer keeps hot
        // (`tokenizer::HOT`), read in turns on lines of plain words, then a name not yet
        // assigned among them (interp_namedparams.cc: refused, as the first read of any is)
        let names = ["xs", "ys", "zs", "fs", "r"];
        let mut text = String::from("G21 G90\nG0 X0 Y0\n");
        for n in names {
            text += &format!("#<{n}> = 1\n");
        }
        for i in 0..40 {
            let [a, b, c] = [names[i % 5], names[(i + 1) % 5], names[(i * 3 + 2) % 5]];
            text += &format!("G1 X[#<{a}>*1.5]Y[#<{b}>*-2.25]Z[#<{c}>*3] F[#<fs>*100]\n");
        }
        // (line 48)
        text += "G1 X[#<xs>*1.5]Y[#<late>*2]Z[#<zs>*3]\n#<late> = 2\nG1 X[#<late>*1]\nM2\n";
        let found: Vec<usize> = findings(of_family(Family::LinuxCnc), &text, Rule::LinuxCncRefuses)
            .iter()
            .filter(|f| f.message.starts_with("Named parameter"))
            .map(|f| f.line)
            .collect();
        assert_eq!(found, [48]);
        // and none where it is assigned first
        let text = text.replace("#<xs> = 1\n", "#<xs> = 1\n#<late> = 0\n");
        assert!(findings(of_family(Family::LinuxCnc), &text, Rule::LinuxCncRefuses).is_empty());
    }

    #[test]
    fn linuxcnc_refuses_a_definition_in_a_loop_body_that_runs_twice() {
        // interp_o_word.cc control_save_offset on the second turn; each program compared
        // with rs274 -g (its stop line, or its run to the end)
        let refused = |text: &str| {
            check(of_family(Family::LinuxCnc), text)
                .into_iter()
                .filter(|f| f.rule == Rule::LinuxCncRefuses)
                .map(|f| (f.line, f.message))
                .collect::<Vec<_>>()
        };
        let def = "o<s> sub\nG0 X1\no<s> endsub\n";
        let lines = |text: &str| refused(text).iter().map(|f| f.0).collect::<Vec<_>>();
        for (body, expected) in [
            (format!("o1 repeat [2]\n{def}o1 endrepeat\n"), &[3][..]),
            // rounded half to even: 1.5 is 2 turns, 0.5 none
            (format!("o1 repeat [1.5]\n{def}o1 endrepeat\n"), &[3]),
            (format!("o1 repeat [0.5]\n{def}o1 endrepeat\n"), &[]),
            (format!("o1 repeat [1]\n{def}o1 endrepeat\n"), &[]),
            (format!("o1 while [1]\n{def}o1 endwhile\n"), &[3]),
            (format!("o1 do\n{def}o1 while [1]\n"), &[3]),
            (format!("o1 do\n{def}o1 while [0]\n"), &[]),
            // a while whose condition is false at its end: one turn
            (
                format!("#1=0\no1 while [#1 lt 1]\n{def}#1=1\no1 endwhile\n"),
                &[],
            ),
            // the call of a body that ends nothing, in a repeat: the second turn comes
            (
                format!("o1 repeat [2]\n{def}o<s> call\no1 endrepeat\n"),
                &[3],
            ),
            // one that ends the program, an M2 in the body, a condition not known, another
            // o-word line in the body: no second turn known
            (
                "o1 repeat [2]\no<s> sub\nM2\no<s> endsub\no<s> call\no1 endrepeat\n".into(),
                &[],
            ),
            (format!("o1 repeat [2]\n{def}M2\no1 endrepeat\n"), &[]),
            (format!("o1 repeat [#<_x>]\n{def}o1 endrepeat\n"), &[]),
            (
                format!("o1 repeat [2]\n{def}o2 if [1]\no2 endif\no1 endrepeat\n"),
                &[],
            ),
            // rs274 stops at the first definition it reads again
            (
                format!(
                    "o1 repeat [2]\n{def}{}o1 endrepeat\n",
                    def.replace("<s>", "<t>")
                ),
                &[3],
            ),
            // an if's body runs once
            (format!("o1 if [1]\n{def}o1 endif\n"), &[]),
        ] {
            let text = format!("G21\n{body}M2\n");
            assert_eq!(lines(&text), expected, "{text}");
        }
        let found = refused(&format!("G21\no1 repeat [2]\n{def}o1 endrepeat\nM2\n"));
        assert!(
            found[0]
                .1
                .starts_with("sub: o|s| found in illegal location (rs274ngc)"),
            "{}",
            found[0].1
        );
        assert!(found[0].1.contains("'o1 endrepeat'"), "{}", found[0].1);
    }

    #[test]
    fn linuxcnc_refuses_a_definition_its_program_reaches_after_calling_it() {
        // interp_o_word.cc control_save_offset, compared with rs274 -g
        let linuxcnc = || of_family(Family::LinuxCnc);
        let refused = |text: &str| {
            check(linuxcnc(), text)
                .into_iter()
                .filter(|f| f.rule == Rule::LinuxCncRefuses)
                .map(|f| (f.line, f.message))
                .collect::<Vec<_>>()
        };
        for name in ["o100", "o<a>"] {
            let ahead = format!("G21\n{name} call\n{name} sub\nG0 X1\n{name} endsub\nM2\n");
            let found = refused(&ahead);
            assert_eq!(found.len(), 1, "{found:?}");
            assert_eq!(found[0].0, 3);
            let bare = name.trim_start_matches('o').trim_matches(['<', '>']);
            assert!(
                found[0]
                    .1
                    .starts_with(&format!("sub: o|{bare}| found in illegal location")),
                "{}",
                found[0].1
            );
            assert!(found[0].1.contains("call on line 2"), "{}", found[0].1);
            // a call in a branch counts: the branch may run
            let branch = format!(
                "G21\no1 if [1]\n{name} call\no1 endif\n{name} sub\nG0 X1\n{name} endsub\nM2\n"
            );
            assert_eq!(refused(&branch).len(), 1);
            // defined before its call, or after the end (never reached): accepted
            let before = format!("G21\n{name} sub\nG0 X1\n{name} endsub\n{name} call\nM2\n");
            assert_eq!(refused(&before), []);
            let after_end = format!("G21\n{name} call\nM2\n{name} sub\nG0 X1\n{name} endsub\n");
            assert_eq!(refused(&after_end), []);
            // an M2 in the `if` branch ends nothing for its `else`/`elseif` branch, which
            // runs where it did not (review 20; rs274 -g refuses the definition on line 7)
            for other in ["else", "elseif [1]"] {
                let text = format!(
                    "G21\no1 if [#1 GT 0]\nM2\no1 {other}\n{name} call\no1 endif\n\
                     {name} sub\nG0 X1\n{name} endsub\nM2\n"
                );
                let found = refused(&text);
                assert_eq!(
                    found.iter().map(|f| f.0).collect::<Vec<_>>(),
                    [7],
                    "{found:?}"
                );
            }
            // an M2 before the condition still ends the program: nothing after it is read
            let ended = format!(
                "G21\nM2\no1 if [#1 GT 0]\nM2\no1 else\n{name} call\no1 endif\n\
                 {name} sub\nG0 X1\n{name} endsub\n"
            );
            assert_eq!(refused(&ended), []);
            // the M2 in a nested condition of the `if` branch is cleared by the outer `else`
            let nested = format!(
                "G21\no1 if [#1 GT 0]\no2 if [1]\nM2\no2 endif\no1 else\n{name} call\n\
                 o1 endif\n{name} sub\nG0 X1\n{name} endsub\nM2\n"
            );
            assert_eq!(
                refused(&nested).iter().map(|f| f.0).collect::<Vec<_>>(),
                [9]
            );
        }
        // another profile's o-words are no LinuxCNC subroutines
        let fanuc = of_family(Family::MacroB);
        assert_eq!(fired(fanuc, "G21\nG0 X1\nM30\n", Rule::LinuxCncRefuses), []);
    }

    #[test]
    fn a_linuxcnc_subroutine_file_is_read_as_a_call_runs_it() {
        // issue 32, audit 37 I: rs274 -i (SUBROUTINE_PATH) runs `o<t> call` from the file
        // from its sub: an endsub in a condition returns early, one of another label returns,
        // the lines before the sub are skipped
        let linuxcnc = || of_family(Family::LinuxCnc);
        let rules = |text: &str| -> Vec<(Rule, usize)> {
            check(linuxcnc(), text)
                .iter()
                .filter(|f| {
                    !matches!(
                        f.rule,
                        Rule::NotFollowed | Rule::NotEvaluated | Rule::NoProgramStart
                    )
                })
                .map(|f| (f.rule, f.line))
                .collect()
        };
        // 1. the local set before the early return is still the body's after it
        let early = "o<t> sub\n#<r> = 5\no100 if [#1 EQ 1]\n  o<t> endsub [1]\no100 endif\n\
                     G0 X#<r>\no<t> endsub [2]\n";
        assert_eq!(rules(early), []);
        let looped = early
            .replace("if [#1 EQ 1]", "while [#1 LT 3]")
            .replace("endif", "endwhile");
        assert_eq!(rules(&looped), []);
        // the same file run as a program (it calls the sub after it): rs274 ends the
        // definition at the first endsub and refuses `o100 endif`
        assert_eq!(
            fired(
                linuxcnc(),
                &format!("{early}o<t> call [0]\nM2\n"),
                Rule::LinuxCncRefuses
            ),
            [(4, 3)]
        );
        // no condition open: the first endsub closes it, and the file goes on as a program
        let plain = "o<t> sub\n#<r> = 5\no<t> endsub\nG0 X#<r>\no<t> endsub\n";
        assert!(rules(plain).contains(&(Rule::LinuxCncRefuses, 4)));
        // 2. an endsub of another label: a warning, no TG114; M2 after it too
        let other = "o<t-4> sub\nG0 X3\no<t_4> endsub\n\nm2\n";
        assert_eq!(rules(other), [(Rule::EndsubNamedOtherwise, 3)]);
        // in a condition it is a return as well, and the definition runs on to its endsub
        let inside = "o<mi> sub\no1 if [#1 GT 0]\no<x> endsub\no1 endif\nG0 Z7\no<mi> endsub\n";
        assert_eq!(rules(inside), [(Rule::EndsubNamedOtherwise, 3)]);
        // a program after it: the definition stays open, as rs274 reads it from the top
        let program = "o<j> sub\nG1 X1 F100\no<k> endsub\no<j> call\nM2\n";
        assert_eq!(
            rules(program),
            [(Rule::EndsubNamedOtherwise, 3), (Rule::NoProgramEnd, 1)]
        );
        // the endsub of a definition nested in the body is no TG138 (left as it was)
        let nested = "o<ns> sub\no1000 sub\nG0 Y2\no1000 endsub\no1000 call\no<ns> endsub\n";
        assert_eq!(rules(nested), []);
        // an endsub inside a condition never closed: not called, rs274 skips the definition
        // to it and ends at the M2 (`rs274 -g`); a call with the condition false reads to the
        // file's end: the block left open said (TG142), no TG114 (lcnc77b)
        let open = "o<tc> sub\no103 if [#5399 LT 0]\nG0 X1\no<tc> endsub [1]\nM2\n";
        assert_eq!(rules(open), [(Rule::BlockOpenAtEndsub, 2)]);
        let message = &findings(linuxcnc(), open, Rule::BlockOpenAtEndsub)[0].message;
        assert!(
            message.starts_with("o103 if is not closed before the o<tc> endsub on line 4"),
            "{message}"
        );
        // 3. lines before the sub: never run when called (TG117 at the first), no TG114
        let before = "(a library sub)\n#<_t3> = 0\nO<t3> SUB\n#<_t3> = [#1 + 1]\nO<t3> ENDSUB\n";
        assert_eq!(rules(before), [(Rule::NotRead, 2)]);
        let message = &findings(linuxcnc(), before, Rule::NotRead)[0].message;
        assert!(message.starts_with("line 2 and the lines after it before the o<t3> sub on line 3"));
        // ... but a file that goes on after the endsub, or calls before the sub, is a program
        assert_eq!(
            rules(&format!("{before}G0 X1\n")),
            [(Rule::NoProgramEnd, 6)]
        );
        let called = "#<_t3> = 0\no<u> call\nO<t3> SUB\nG0 X1\nO<t3> ENDSUB\n";
        assert!(rules(called).contains(&(Rule::NoProgramEnd, 5)));
        assert!(!rules(called).iter().any(|f| f.0 == Rule::NotRead));
    }

    #[test]
    fn a_byte_order_mark_is_said_as_what_it_is() {
        let bom = "\u{feff}G21 G90\n(25\u{b0}C)\nG0 X1\nM2\n";
        // LinuxCNC refuses it (rs274 -g: "Bad character '\\357' used")
        let found = check(of_family(Family::LinuxCnc), bom);
        let refused: Vec<_> = found
            .iter()
            .filter(|f| f.rule == Rule::LinuxCncRefuses)
            .collect();
        assert_eq!(refused.len(), 1, "{found:?}");
        assert_eq!((refused[0].line, refused[0].column), (1, 1));
        assert!(refused[0].message.starts_with("Bad character '\\357' used"));
        assert!(found.iter().all(|f| f.rule != Rule::ByteOrderMark));
        // elsewhere a warning; on neither is the mark text "in a comment": TG127 names the
        // degree sign of line 2, the first text outside ASCII
        for family in [Family::LinuxCnc, Family::MacroB, Family::Iso] {
            let found = check(of_family(family), bom);
            let outside: Vec<_> = found
                .iter()
                .filter(|f| f.rule == Rule::OutsideAscii)
                .map(|f| (f.line, f.column))
                .collect();
            assert_eq!(outside, [(2, 4)], "{family:?} {found:?}");
            if family != Family::LinuxCnc {
                assert_eq!(fired(of_family(family), bom, Rule::ByteOrderMark), [(1, 1)]);
            }
        }
        // a mark on its own first line, and none at all
        assert_eq!(
            fired(
                of_family(Family::MacroB),
                "\u{feff}\nG0 X1\nM30\n",
                Rule::ByteOrderMark
            ),
            [(1, 1)]
        );
        assert_eq!(
            fired(
                of_family(Family::MacroB),
                "G0 X1\nM30\n",
                Rule::ByteOrderMark
            ),
            []
        );
    }

    #[test]
    fn a_linuxcnc_subroutine_file_needs_no_m2() {
        let run = |text: &str| fired(of_family(Family::LinuxCnc), text, Rule::NoProgramEnd);
        // the called file of LinuxCNC's O codes: the definition, optionally M2 after it
        let sub = "(the file z_touch.ngc)\no<z_touch> sub\nG10 L20 P0 Z25\no<z_touch> endsub\n";
        assert_eq!(run(sub), []);
        assert_eq!(run(&format!("{sub}M2\n")), []);
        assert_eq!(run("o100 sub\nG0 X1\no100 end sub [3]\n"), []);
        // anything else after the endsub is a program, which ends with M2
        assert_eq!(run(&format!("{sub}o<z_touch> call\n")), [(5, 1)]);
        assert_eq!(run(&format!("{sub}G0 X0\n")), [(5, 1)]);
        // lines before the definition: a call skips them (TG117), no M2 needed (issue 32,
        // audit 37 I, 3); a statement before it (a call) makes it a program
        assert_eq!(run(&format!("G0 X0\n{sub}")), []);
        assert_eq!(run(&format!("G0 X0\no<b> call\n{sub}")), [(6, 1)]);
        // an unclosed definition is no subroutine file, and holds the rest of the file: its
        // M2 too, as rs274 2.9 reads it ("File ended with no percent sign or program end"),
        // said at the sub
        assert_eq!(run("o<a> sub\nG0 X1\n"), [(1, 1)]);
        assert_eq!(run("o<a> sub\nG0 X1\nM2\n"), [(1, 1)]);
        assert_eq!(run("%\no<a> sub\nG0 X1\nM2\n%\n"), [(2, 1)]);
        assert_eq!(run("G0 X0\n  O<A> SUB\nG1 X1 F100\nM2\n"), [(2, 3)]);
        // an endsub that names another definition closes nothing where rs274 reads the file
        // as a program; in a subroutine file, called, it returns (TG138: issue 32, audit 37
        // I, 2)
        assert_eq!(run("o<a> sub\nG0 X1\no<b> endsub\nM2\n"), []);
        assert_eq!(run("o<a> sub\nG0 X1\no<b> endsub\nG0 X2\nM2\n"), [(1, 1)]);
        // closed, then the main program and its M2: a program like any other
        assert_eq!(run("o<a> sub\nG0 X1\no<a> endsub\no<a> call\nM2\n"), []);
        let found = findings(
            of_family(Family::LinuxCnc),
            "o<a> sub\nG0 X1\nM2\n",
            Rule::NoProgramEnd,
        );
        assert_eq!(found.len(), 1);
        assert!(
            found[0]
                .message
                .starts_with("o<a> sub is not closed by o<a> endsub"),
            "{}",
            found[0].message
        );
    }

    /// A `%` line after the endsub of a LinuxCNC subroutine file not begun with `%` (a
    /// remap macro ending so, held23): a call returns at the endsub and never reads it
    /// (`rs274 -g` of `o<tp> call` / `M2` beside `tp.ngc`: no error), so no TG412 there;
    /// where the file goes on as a program, or its name is not its label's (rs274 calls only
    /// `tp.ngc` by `o<tp>`: a file named otherwise runs only as a program, review 57b F1),
    /// rs274 reads it as a block ("Bad character '%' used"), said at the `%`.
    #[test]
    fn a_percent_after_a_linuxcnc_subroutine_files_endsub_is_never_read() {
        let in_file = |name: Option<&str>, text: &str| -> Vec<(usize, usize)> {
            let config = of_family(Family::LinuxCnc);
            let dialect = super::super::testing::dialect(Family::LinuxCnc);
            super::super::testing::run_file(config, &dialect, text, false, name)
                .1
                .iter()
                .filter(|f| f.rule == Rule::LinuxCncRefuses)
                .map(|f| (f.line, f.column))
                .collect()
        };
        let run = |text: &str| in_file(Some("subs/tp.ngc"), text);
        let sub = "o<tp> sub\nG0 X1\no<tp> endsub\n";
        assert_eq!(run(&format!("{sub}%\n")), []);
        assert_eq!(run(&format!("\n{sub}\n%\n\n")), []);
        assert_eq!(run(&format!("{sub}M2\n%\n")), []);
        // the label as rs274 reads it: lower case, blanks left out
        assert_eq!(run("O< T P > sub\nG0 X1\nO<tp> endsub\n%\n"), []);
        // a file whose name is not its label's (or no name) is not called: run as a program,
        // rs274 reads the `%`
        for name in [Some("other.ngc"), Some("TP.ngc"), Some("tp.nc"), None] {
            assert_eq!(in_file(name, &format!("{sub}%\n")), [(4, 1)], "{name:?}");
        }
        // lines after it make the file a program: rs274 reads the `%` before them
        assert_eq!(run(&format!("{sub}%\nG0 X2\nM2\n")), [(4, 1)]);
        assert_eq!(run(&format!("{sub}%\no<tp> call\nM2\n")), [(4, 1)]);
        // and past an M2 after it too, as an O-word line there does (review 57b F2: `rs274
        // -g tp.ngc` stops at the `%`; called, it returns at the endsub)
        assert_eq!(run(&format!("{sub}%\nM2\nG0 X2\n")), [(4, 1)]);
        assert_eq!(run(&format!("{sub}%\nM2\n(done)\n\n")), []);
        // an endsub of another label that ends the file is its return (TG138): a call
        // never reads the `%` after it, run as a program rs274 seeks `o<tp> endsub` and
        // ends at the file's end without one, or at its endsub after it (review 57b F3)
        let other = "o<tp> sub\nG0 X1\no<tq> endsub\n";
        assert_eq!(run(&format!("{other}%\n")), []);
        assert_eq!(run(&format!("{other}%\nM2\n")), []);
        assert_eq!(run(&format!("{other}%\nG0 X2\n")), []);
        assert_eq!(run(&format!("{other}G0 X2\n%\n")), []);
        assert_eq!(run(&format!("{other}%\no<tp> endsub\nG0 X2\nM2\n")), []);
        // (before the return, a call reads it)
        assert_eq!(run("o<tp> sub\n%\no<tq> endsub\n"), [(2, 1)]);
        // in the body, a call reads it: refused as before; and in a program, where it is
        assert_eq!(run("o<tp> sub\n%\no<tp> endsub\n"), [(2, 1)]);
        assert_eq!(run("G0 X1\n%\nM2\n"), [(2, 1)]);
        // a file begun with `%` closes with it, as before
        assert_eq!(run(&format!("%\n{sub}%\n")), []);
        // the message is the refusal's own
        let found = findings(
            of_family(Family::LinuxCnc),
            &format!("{sub}  %\nG0 X2\nM2\n"),
            Rule::LinuxCncRefuses,
        );
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].line, found[0].column), (4, 3));
        assert!(
            found[0]
                .message
                .starts_with("Bad character '%' used (rs274ngc): the file does not begin"),
            "{}",
            found[0].message
        );
    }

    /// A memory backup whose last folder marker has no program after it: an empty folder,
    /// not a program without M30; a folder that holds a program is checked as before.
    #[test]
    fn an_empty_last_folder_of_a_backup_is_no_program() {
        let fanuc = || {
            let mut config = of_family(Family::MacroB);
            config.facts.program_number = Some(b'O');
            config
        };
        let run = |text: &str| fired(fanuc(), text, Rule::NoProgramEnd);
        let backup = "%\n&F=/USER/PATH1/\nO0001\nG0 X1.\nM30\n&F=/USER/PATH2/\n%\n";
        assert_eq!(run(backup), []);
        let after_return = "%\nO9001\nG0 X1.\nM99\n&F=/USER/PATH2/\n\n%\n";
        assert_eq!(run(after_return), []);
        // the folder holds a program that does not end: said
        let unended = "%\nO0001\nM30\n&F=/USER/PATH2/\nO0002\nG0 X1.\n%\n";
        assert_eq!(run(unended), [(7, 1)]);
        let words = "%\nO0001\nM30\n&F=/USER/PATH2/\nG0 X1.\n%\n";
        assert_eq!(run(words), [(6, 1)]);
    }

    /// `DO 1` and `END 1`: the blank between the loop word and its number is skipped, as
    /// between an address and its number (audit 50, B11); a DO with no number stays a
    /// reading error at the word.
    #[test]
    fn a_loop_number_after_a_blank_is_read() {
        let run = |text: &str| fired(of_family(Family::MacroB), text, Rule::Unreadable);
        let text = "%\nO1\n#1=0\nWHILE [#1 LT 3] DO 1\nWHILE [#1 LT 2] DO  2\n#1=#1+1\n\
                    END 2\nEND1\nM30\n%\n";
        assert_eq!(run(text), []);
        let nothing = "%\nO1\n#1=0\nWHILE [#1 LT 3] DO X\nEND 1\nM30\n%\n";
        assert_eq!(run(nothing), [(4, 17)]);
    }

    /// An M30 the block skip passes over (`/M30`, `G0 X1. /M30`) ends the program only with
    /// the switch off: with it on the blocks after it run, so they are no words after the end
    /// (audit 50, B13). An M30 before the slash, or one after, still ends it.
    #[test]
    fn a_skipped_end_leaves_no_words_after_it() {
        let run = |text: &str| fired(of_family(Family::MacroB), text, Rule::WordsAfterEndNotRun);
        assert_eq!(run("%\nO1\nG0 X1.\n/M30\nG0 X2.\nM30\n%\n"), []);
        assert_eq!(run("%\nO1\nG0 X1.\nG0 X3. /M30\nG0 X2.\nM30\n%\n"), []);
        assert_eq!(
            run("%\nO1\nG0 X1.\nM30 /G0 X3.\nG0 X2.\nM30\n%\n"),
            [(5, 1)]
        );
        assert_eq!(run("%\nO1\n/M30\nG0 X2.\nM30\nG0 X4.\n%\n"), [(6, 1)]);
    }

    /// A SINUMERIK archive in punched tape format holds several files, each after its `%`
    /// line: each file is a program of its own (no TG116), from the reset state, whatever the
    /// one before ended with, a subprogram by its name (`_SPF`: its feed its caller's, no
    /// TG401).
    #[test]
    fn a_sinumerik_archive_holds_programs_of_their_own() {
        let run = |text: &str, rule| fired(of_family(Family::Sinumerik), text, rule);
        let archive = "%_N_MAIN_MPF\n;$PATH=/_N_MPF_DIR\nG90 G1 X10 F100\nM30\n\
                       %_N_SUB1_SPF\n;$PATH=/_N_SPF_DIR\nG1 X5 Y5\nRET\n\
                       %_N_MAIN2_MPF\n;$PATH=/_N_MPF_DIR\nG90 G1 X20\nM30\n";
        assert_eq!(run(archive, Rule::WordsAfterEnd), []);
        assert_eq!(run(archive, Rule::WordsAfterEndNotRun), []);
        // the subprogram runs under its caller's feed; the second main program starts from
        // the reset state, with none
        assert_eq!(run(archive, Rule::NoFeedRate), [(11, 8)]);
        assert_eq!(run(archive, Rule::NoProgramEnd), []);
        // words after the end and before the next file's header stay words after the end
        // (never run: TG106, a warning, on a control family's profile)
        let glued = "%_N_MAIN_MPF\nG1 X10 F100\nM30\nG1 X5\n%_N_SUB1_SPF\nG1 X1\nM17\n";
        assert_eq!(run(glued, Rule::WordsAfterEndNotRun), [(4, 1)]);
        assert_eq!(run(glued, Rule::WordsAfterEnd), []);
        // a file that ends by M99 (no code of the SINUMERIK's program flow) or by nothing is
        // no less a file of its own: the next header begins the next program, from the
        // reset state, with no feed
        for end in ["M99\n", ""] {
            let text = format!(
                "%_N_A_MPF\n;$PATH=/_N_MPF_DIR\nG0 X0 Y0 Z5\nG1 X10 F100\n{end}\
                 %_N_B_MPF\n;$PATH=/_N_MPF_DIR\nG0 X0 Y0 Z5\nG1 X20\nM30\n"
            );
            let line = if end.is_empty() { 8 } else { 9 };
            assert_eq!(run(&text, Rule::NoFeedRate), [(line, 4)], "{end:?}");
            assert_eq!(run(&text, Rule::NoProgramEnd), [], "{end:?}");
        }
        // a Fanuc's % after M30 is its closing %
        let fanuc = of_family(Family::MacroB);
        assert_eq!(
            fired(fanuc, "%\nG01 X1. F100.\nM30\n%\n", Rule::NoClosingPercent),
            []
        );
    }

    #[test]
    fn words_after_the_end_are_said_once() {
        let text = "%\nG01 X1. F100.\nM02\nG00 X0\nG00 X5.\n%";
        assert_eq!(fired(iso_mill(), text, Rule::WordsAfterEnd), [(4, 1)]);
        assert_eq!(
            fired(iso_mill(), &program("G00 X0"), Rule::WordsAfterEnd),
            []
        );
    }

    #[test]
    fn the_identification_on_the_percent_line() {
        let run = |first: &str, rule| fired(iso_mill(), &format!("{first}\nM02\n%"), rule);
        assert_eq!(run("%G01 X1.", Rule::WordsOnPercentLine), [(1, 2)]);
        assert_eq!(
            run("%PART 7", Rule::IdentificationNotInParentheses),
            [(1, 2)]
        );
        assert_eq!(run("%(PART 7)", Rule::IdentificationNotInParentheses), []);
        assert_eq!(run("% 1234", Rule::IdentificationNotInParentheses), []);
        // Siemens and HEIDENHAIN name the program on the % line
        let sinumerik = of_family(Family::Sinumerik);
        assert_eq!(
            fired(
                sinumerik,
                "%MPF 90\nM02\n%",
                Rule::IdentificationNotInParentheses
            ),
            []
        );
    }

    #[test]
    fn a_fanuc_skips_the_text_after_the_first_percent() {
        let fanuc = || {
            let mut config = of_family(Family::MacroB);
            config.facts.program_number = Some(b'O');
            config
        };
        let program = |first: &str| format!("{first}\nO0001\nG21 G90 G00 X0\nM30\n%");
        // B-63524EN/01: skipped from the first % to the next LF, a warning, not TG111/TG112
        for leader in ["% PART A REV 2", "% O0001", "%O0003( 300-11 MILL FIXTURE)"] {
            let found = findings(fanuc(), &program(leader), Rule::LeaderSkipped);
            assert_eq!(found.len(), 1, "{leader}");
            assert_eq!((found[0].line, found[0].column), (1, 2));
            for rule in [
                Rule::WordsOnPercentLine,
                Rule::IdentificationNotInParentheses,
            ] {
                assert_eq!(fired(fanuc(), &program(leader), rule), [], "{leader}");
            }
        }
        let lost = |leader| findings(fanuc(), &program(leader), Rule::LeaderSkipped)[0].clone();
        assert!(lost("% O0001").message.contains("program number 'O0001'"));
        assert!(!lost("% PART A REV 2").message.contains("program number"));
        // a bare % and a later % line: nothing
        assert_eq!(fired(fanuc(), &program("%"), Rule::LeaderSkipped), []);
        // a Haas: no source says it skips, nor that it alarms: TG137, a warning
        let mut haas = fanuc();
        haas.haas = true;
        assert_eq!(
            fired(haas.clone(), &program("% PART A"), Rule::LeaderSkipped),
            []
        );
        for (leader, case) in [
            ("% PART A", "letters outside"),
            ("%N1 G90", "words after %"),
        ] {
            let found = findings(haas.clone(), &program(leader), Rule::LeaderUnknown);
            assert_eq!(found.len(), 1, "{leader}");
            assert_eq!((found[0].line, found[0].column), (1, 2));
            assert!(found[0].message.contains(case), "{}", found[0].message);
            assert!(
                found[0].message.contains("no Haas source"),
                "{}",
                found[0].message
            );
            for rule in [
                Rule::WordsOnPercentLine,
                Rule::IdentificationNotInParentheses,
            ] {
                assert_eq!(fired(haas.clone(), &program(leader), rule), [], "{leader}");
            }
        }
        // an Okuma alike; ISO 6983-1's profiles keep the errors (above: TG111, TG112)
        let okuma = of_family(Family::Okuma);
        let found = findings(okuma.clone(), &program("%BRACKET"), Rule::LeaderUnknown);
        assert_eq!((found.len(), found[0].line), (1, 1));
        assert!(found[0].message.contains("no Okuma source"));
        assert_eq!(
            fired(
                okuma,
                &program("%BRACKET"),
                Rule::IdentificationNotInParentheses
            ),
            []
        );
    }

    #[test]
    fn the_program_number_belongs_in_the_first_block() {
        let config = || Config {
            facts: ProfileFacts {
                program_number: Some(b'O'),
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        assert_eq!(
            fired(
                config(),
                &program("O1234\nG01 X1. F100."),
                Rule::ProgramNumberNotFirst
            ),
            []
        );
        let late = program("G01 X1. F100.\nO1234");
        assert_eq!(
            fired(config(), &late, Rule::ProgramNumberNotFirst),
            [(3, 1)]
        );
    }

    #[test]
    fn stop_characters_in_comments() {
        let text = program("G01 X1. F100. (50% FEED)");
        assert_eq!(
            fired(iso_mill(), &text, Rule::StopCharacterInComment),
            [(2, 18)]
        );
        let linuxcnc = of_family(Family::LinuxCnc);
        assert_eq!(fired(linuxcnc, &text, Rule::StopCharacterInComment), []);
        // a SINUMERIK reads '%' as a file header in the first column only
        let url = "G01 X1. F100. ; https://en.wikipedia.org/wiki/Runge%E2%80%93Kutta";
        let mut sinumerik = of_family(Family::Sinumerik);
        sinumerik.facts.colon_stop = false;
        assert_eq!(
            fired(sinumerik, &program(url), Rule::StopCharacterInComment),
            []
        );
        assert_eq!(
            fired(
                of_family(Family::MacroB),
                &text,
                Rule::StopCharacterInComment
            ),
            [(2, 18)]
        );
        // ':' stops a control whose tape reader searches for it (comment_colon = "stop")...
        let stamp = program("(21:09)\nG01 X1. F100. (T:1)");
        assert_eq!(
            fired(iso_mill(), &stamp, Rule::StopCharacterInComment),
            [(2, 4), (3, 17)]
        );
        assert_eq!(fired(iso_mill(), &stamp, Rule::ColonInComment), []);
        // ...and is counted, said once at the end, where the control reads it as text
        let text_colon = Config {
            facts: ProfileFacts {
                colon_stop: false,
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let found = findings(text_colon, &stamp, Rule::ColonInComment);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].line, found[0].column), (2, 4));
        assert!(
            found[0].message.starts_with("2 comments hold ':'"),
            "{}",
            found[0].message
        );
    }

    #[test]
    fn comments_open_and_nested() {
        let open = program("G01 X1. F100. (open");
        assert_eq!(fired(iso_mill(), &open, Rule::CommentNotClosed), [(2, 15)]);
        let nested = program("G01 X1. F100. (a (b) c)");
        assert_eq!(fired(iso_mill(), &nested, Rule::NestedComment), [(2, 18)]);
        assert_eq!(
            fired(iso_mill(), &program("G01 X1. (a) (b)"), Rule::NestedComment),
            []
        );
        // the standard's reading says so only where no other source is the control's
        let iso = findings(iso_mill(), &nested, Rule::NestedComment);
        assert!(!iso[0].message.contains("Fanuc"), "{}", iso[0].message);
        let fanuc = findings(of_family(Family::MacroB), &nested, Rule::NestedComment);
        assert_eq!((fanuc[0].line, fanuc[0].column), (2, 18));
        assert!(
            fanuc[0].message.contains("no Fanuc or Haas source at hand"),
            "{}",
            fanuc[0].message
        );
    }

    #[test]
    fn a_fanuc_nested_comment_read_once_is_a_warning() {
        let macro_b = of_family(Family::MacroB);
        let same = program("G01 X1. F100. (VNMG 332(1))");
        assert_eq!(
            fired(macro_b.clone(), &same, Rule::NestedCommentRead),
            [(2, 24)]
        );
        assert_eq!(fired(macro_b.clone(), &same, Rule::NestedComment), []);
        let found = findings(macro_b.clone(), &same, Rule::NestedCommentRead);
        assert!(
            found[0].message.contains("a stray ')' is left"),
            "{}",
            found[0].message
        );
        // the readings differ: the tokenizer's refusal, with its message, at the inner '('
        let differ = program("G01 X1. F100. (A (B) X5)");
        assert_eq!(
            fired(macro_b.clone(), &differ, Rule::NestedComment),
            [(2, 18)]
        );
        assert_eq!(fired(macro_b, &differ, Rule::NestedCommentRead), []);
        // ISO 6983-1: a '(' inside a comment is refused, whatever follows it
        assert_eq!(fired(iso_mill(), &same, Rule::NestedComment), [(2, 24)]);
        assert_eq!(fired(iso_mill(), &same, Rule::NestedCommentRead), []);
    }

    #[test]
    fn the_block_skip_precedes_the_sequence_number() {
        assert_eq!(
            fired(
                iso_mill(),
                &program("/N10 G01 X1. F100."),
                Rule::SkipNotFirst
            ),
            []
        );
        assert_eq!(
            fired(
                iso_mill(),
                &program("/G01 N10 X1. F100."),
                Rule::SkipNotFirst
            ),
            [(2, 1)]
        );
        assert_eq!(
            fired(iso_mill(), &program("N10 /G01 X1."), Rule::SkipNotFirst).len(),
            1
        );
    }

    #[test]
    fn a_skip_in_the_middle_of_a_block_is_a_warning_naming_what_it_skips() {
        let fanuc = of_family(Family::MacroB);
        let text = program("N10 G00 X10. /Y20. M08\n/N20 Z-1.0/M09");
        let found = findings(fanuc.clone(), &text, Rule::SkipWithinBlock);
        let places: Vec<(usize, usize)> = found.iter().map(|f| (f.line, f.column)).collect();
        assert_eq!(places, [(2, 14), (3, 11)]);
        assert!(
            found[0].message.contains("(Y20. M08)"),
            "{}",
            found[0].message
        );
        assert!(found[1].message.contains("(M09)"), "{}", found[1].message);
        assert!(
            found[0]
                .message
                .ends_with("with another position and machine state (M code), not followed here"),
            "{}",
            found[0].message
        );
        assert!(
            found[1]
                .message
                .ends_with("with another machine state (M code), not followed here"),
            "{}",
            found[1].message
        );
        // the words after the slash are checked as written (the switch off): read, no error
        assert!(check(fanuc.clone(), &text)
            .iter()
            .all(|f| f.rule.severity() != crate::rules::Severity::Error));
        // elsewhere the slash is where the block cannot be read (TG123)
        assert_eq!(
            fired(
                iso_mill(),
                &program("N10 G00 X10. /Y20."),
                Rule::SkipNotFirst
            ),
            [(2, 14)]
        );
        assert_eq!(
            fired(
                iso_mill(),
                &program("N10 G00 X10. /Y20."),
                Rule::SkipWithinBlock
            ),
            []
        );
    }

    #[test]
    fn the_alignment_starts_the_block_and_is_in_the_classification() {
        assert_eq!(
            fired(
                iso_mill(),
                &program(":10 G01 X1. F100."),
                Rule::AlignmentNotFirst
            ),
            []
        );
        let late = program("N10 :20 G01 X1. F100.");
        assert_eq!(fired(iso_mill(), &late, Rule::AlignmentNotFirst), [(2, 5)]);
        let unclassified = Config {
            facts: ProfileFacts {
                alignment: false,
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let text = program(":10 G01 X1. F100.");
        assert_eq!(
            fired(iso_mill(), &text, Rule::AlignmentNotInClassification),
            []
        );
        assert_eq!(
            fired(unclassified, &text, Rule::AlignmentNotInClassification),
            [(2, 1)]
        );
    }

    #[test]
    fn lower_case_addresses_and_characters_outside_the_set() {
        let lower = Dialect {
            lowercase: true,
            ..dialect(Family::Iso)
        };
        let text = program("g01 x1. F100.");
        let found = check_in(iso_mill(), &lower, &text);
        let at: Vec<_> = found
            .iter()
            .filter(|f| f.rule == Rule::LowerCaseAddress)
            .map(|f| (f.line, f.column))
            .collect();
        assert_eq!(at, [(2, 1), (2, 5)]);
        let linuxcnc = of_family(Family::LinuxCnc);
        let found = check_in(linuxcnc, &lower, &text);
        assert!(
            found.iter().all(|f| f.rule != Rule::LowerCaseAddress),
            "{found:?}"
        );
        let text = program("G01 X1. F100. $");
        assert_eq!(
            fired(iso_mill(), &text, Rule::CharacterOutsideSet),
            [(2, 15)]
        );
        assert_eq!(
            fired(iso_mill(), &program("G01 X"), Rule::Unreadable).len(),
            1
        );
    }

    /// Review 55c, F7 (lcnc56): a call in a branch known to run does not make the `else` or
    /// `elseif` after it live (rs274 goes from the branch that ran to the `endif`), but in a
    /// loop, whose later turn may take the other branch, it does. Each as `rs274 -g`.
    #[test]
    fn linuxcnc_a_call_in_a_branch_that_ran_leaves_the_next_branch_dead() {
        let subs = "o<sa> sub\no<sa> endsub\no<sb> sub\nG0 X1\no<sb> endsub\n";
        let head = "G21 G18 G90 G40 G94 F100\nG0 X0 Y0 Z0\n";
        let arc = "G2 X1 Y0 I0.5 J0";
        let cases: Vec<(String, Vec<usize>)> = vec![
            // dz1, e1: runs
            (
                format!(
                    "#<k>=1\no453 if [#<k> GT 0]\no<sb> call\no453 elseif [0]\n{arc}\no453 endif"
                ),
                vec![],
            ),
            (
                format!("o150 if [1]\no<sb> call\no150 elseif [1]\n{arc}\no150 endif"),
                vec![],
            ),
            (
                format!("o150 if [1]\no<sb> call\no<sa> call\no150 else\n{arc}\no150 endif"),
                vec![],
            ),
            // "J word given for arc in xz plane": a condition not known, or a later turn
            (
                format!("o1 if [#5220 GT 5]\no<sb> call\no1 else\n{arc}\no1 endif"),
                vec![11],
            ),
            (
                format!(
                    "#<k>=0\no2 while [#<k> LT 2]\no1 if [#<k> EQ 0]\no<sb> call\no1 else\n\
                     {arc}\no1 endif\n#<k>=[#<k>+1]\no2 endwhile"
                ),
                vec![13],
            ),
        ];
        for (body, expected) in cases {
            let text = format!("{subs}{head}{body}\nM2\n");
            let got: Vec<usize> = check(of_family(Family::LinuxCnc), &text)
                .into_iter()
                .filter(|f| f.rule == Rule::ArcCentreMissing)
                .map(|f| f.line)
                .collect();
            assert_eq!(got, expected, "{body}");
        }
    }

    /// Review 57d, F1 (lcnc57b): where the M72's restore runs a block of its own, rs274 2.9.0
    /// runs it in place of the M72's: the block's G1 does not move the tool, and the arc after
    /// starts where it was (`rs274 -g`: the first is "Radius to end of arc differs", the
    /// second runs).
    #[test]
    fn a_dropped_m72_motion_leaves_the_tool_where_it_was() {
        let head = "G21 G90 G17 G94\nG0 X0 Y0 Z0\nF100\nM70\nG93\nM72 G1 X1\n";
        let errors = |arc: &str| {
            check(of_family(Family::LinuxCnc), &format!("{head}{arc}\nM2\n"))
                .into_iter()
                .filter(|f| f.rule.severity() == crate::rules::Severity::Error)
                .map(|f| (f.line, f.rule))
                .collect::<Vec<_>>()
        };
        assert_eq!(
            errors("G94 G2 X2 Y0 I0.5 J0 F100"),
            [(7, Rule::ArcRadiusMismatch)]
        );
        assert_eq!(errors("G94 G2 X2 Y0 I1 J0 F100"), []);
    }

    /// Review 56c (lcnc57): M72 restores the feed mode, rs274's feed rate and the speed M70
    /// saved as rs274 2.9.0 does (`Checker::linuxcnc_feed_restore`), where both lines run
    /// where they stand and each value is known; else the feed is left unknown or as the
    /// lines give it, never guessed. Each program's first feed finding (line and rule) as
    /// `rs274 -g` stops at that line, or None: rs274 runs it to its M2, or the checker
    /// cannot know (marked "unknown": rs274 may stop or run).
    #[test]
    fn linuxcnc_m72_restores_the_feed_m70_saved_as_rs274() {
        let head = "G21 G90 G17 G94\nG0 X0 Y0 Z0\n";
        let no_feed = Some((0, Rule::NoFeedRate));
        let refused = Some((0, Rule::LinuxCncRefuses));
        let cases: &[(&str, Option<(usize, Rule)>)] = &[
            // the same mode: the saved rate ("Cannot do g1 with zero feed rate")
            ("M70\nF100\nM72\nG1 X1", no_feed),
            ("F100\nM70\nF200\nM72\nG1 X1", None),
            // G94 restored from G93 or G95: zero where the rate is the same (F1), the saved
            // rate where it differs (F3)
            ("F100\nM70\nG93\nF100\nM72\nG1 X2", no_feed),
            ("F100\nM70\nG95 F100\nM72\nG1 X1", no_feed),
            ("F100\nM70\nG95 F0.1\nG93\nM72\nG1 X3", None),
            ("F100\nM70\nG95 F0.1\nM72 G93\nG1 X1", None),
            ("F100\nM70\nG95\nM72\nG1 X1", None),
            // a spline after it (F2): rs274's "Cannot make arc with zero feed rate"
            ("F100\nM70\nG95 F100\nM72\nG5 X3 Y2 I1 J0 P1 Q1", refused),
            ("F100\nM70\nG95 F0.1\nG93\nM72\nG5 X3 Y2 I1 J0 P1 Q1", None),
            // G93 restored: each block its F ("F word missing with inverse time g1 move")
            (
                "G93\nM70\nG94 F100\nM72\nG1 X1 F10\nG1 X2",
                Some((0, Rule::InverseTimeWithoutFeed)),
            ),
            // the speed saved, under G95 ("Cannot feed with zero spindle speed ...")
            ("G95 F0.1\nM70\nS1000 M3\nM72\nG1 X1", refused),
            ("S1000 M3\nG95 F0.1\nM70\nS0\nM72\nG1 X1", None),
            // a G93 G1's rate, its length times F, where exact (F1): the same, zero; another,
            // the saved F
            ("F100\nM70\nG93\nG1 X1 F100\nM72\nG1 X2", no_feed),
            ("F100\nM70\nG93\nG1 X2 F50\nM72\nG1 X3", no_feed),
            ("F100\nM70\nG93\nG1 X1 F10\nM72\nG1 X2", None),
            // not known: a G93 move of two axes, an F the checker does not evaluate (F1, F4);
            // rs274 stops on each, the checker leaves the F unknown
            ("F100\nM70\nG93\nG1 X3 Y4 F20\nM72\nG1 X2", None),
            ("F[50*2]\nM70\nG95 F100\nM72\nG1 X1", None),
            // the saved rate as ` F%.1f` writes it: F0.04 is F0.0 (review 57d, F6); on a half
            // (F0.05) the double decides: not known, rs274 runs it at F0.1
            ("F0.04\nM70\nG95 F1\nM72\nG1 X1", no_feed),
            ("F0.04\nM70\nF1\nM72\nG1 X1", no_feed),
            ("F0.05\nM70\nG95 F0.1\nM72\nG1 X1", None),
            ("F0.04\nM70\nF0.04\nM72\nG1 X1", None),
            // a G93 G1 of no length leaves rs274's rate 0.1 (review 57d, F6)
            ("F0.1\nM70\nG93 G1 X0 F100\nM72\nG1 X3", no_feed),
            ("F0.1\nM70\nG93 G1 F50\nM72\nG1 X3", no_feed),
            ("F100\nM70\nG93 G1 X0 F100\nM72\nG1 X3", None),
            ("F0.1\nM70\nG93 G1 X0 A1 F100\nM72\nG1 X3", None),
            ("F#<_r>\nM70\nG95 F100\nM72\nG1 X1", None),
            // a save in a loop: its last turn's (F6, rs274 runs); a restore in a known-true
            // if or after a G93-G95 in one (F8, F9): not followed
            ("o1 repeat [2]\nM70\nF100\no1 endrepeat\nM72\nG1 X1", None),
            (
                "o1 if [1]\nG95\no1 endif\nM70\nG93\nM72\nG5.1 X1 Y1 I1 J1",
                None,
            ),
            // an M72 beside a motion: the restore's block takes its place where it runs
            // (F5), and where nothing differs the motion runs ("zero feed rate")
            ("M70\nG1 X1 F100\nM72 G1 X1", None),
            ("F100\nM70\nG93\nM72 G1 X1", None),
            ("M70\nM72 G1 X1", no_feed),
            // a G5/G5.1 under G95 is no feed move of the G1 in force (F7)
            ("S100 M3\nG1 X2 F10\nG95\nG5.1 X1 Y1 I1 J1", None),
        ];
        let judged = [
            Rule::NoFeedRate,
            Rule::InverseTimeWithoutFeed,
            Rule::LinuxCncRefuses,
        ];
        for (body, expected) in cases {
            let text = format!("{head}{body}\nM2\n");
            let last = 2 + body.lines().count();
            // (decimals past a format are no alarm on LinuxCNC, as its profile says: F0.04)
            let mut linuxcnc = of_family(Family::LinuxCnc);
            linuxcnc.facts.past_decimals = crate::dialect::PastFormat::Any;
            let got = check(linuxcnc, &text)
                .into_iter()
                .find(|f| judged.contains(&f.rule))
                .map(|f| (f.line, f.rule));
            let expected = expected.map(|(_, rule)| (last, rule));
            assert_eq!(got, expected, "{body}");
        }
    }

    /// Review 57d, F2-F4: an M72 whose save is not followed leaves the feed mode, rs274's
    /// feed rate and the speed unknown, save where every save that may be in force agrees;
    /// its block's motion is not judged where the restore may run a block in its place; the
    /// spindle's direction and the compensation after any M72 are not known. Each case run
    /// in `rs274 -g` (2.9.0): None where it runs, the line and column of its error.
    #[test]
    fn linuxcnc_m72_not_followed_leaves_what_it_restores_unknown() {
        let head = "G21 G90 G17 G94\nG0 X0 Y0 Z0\n";
        let refused = Rule::LinuxCncRefuses;
        // (the line, column and rule of the first feed refusal)
        type At = Option<(usize, usize, Rule)>;
        let cases: &[(&str, At)] = &[
            // F2: a save not followed (an `if` between, the M70 in one): rs274 runs each
            (
                "F100\nM70\no1 if [1]\nF200\no1 endif\nG95 F200\nM72\nG1 X1",
                None,
            ),
            (
                "F100\no1 if [1]\nM70\no1 endif\nG93 G1 X2 F10\nM72\nG1 X1",
                None,
            ),
            (
                "F100\no1 if [1]\nM70\no1 endif\nM72 G95\nG81 X1 Z-1 R1",
                None,
            ),
            // where every save agrees: the mode G93 ("Cannot feed with zero feed rate": the
            // F of a G93 block is no rate of the cycle), the speed S0, an M72 in an `if` that
            // leaves G93 whether it runs or not ("F word missing with inverse time g1 move")
            (
                "G93 F100\no1 if [1]\nM70\no1 endif\nM72 G94\nG81 X1 Z-1 R1 F50",
                Some((8, 1, refused)),
            ),
            (
                "o1 if [1]\nM70\no1 endif\nM72\nG95 F0.1\nG1 X1",
                Some((8, 4, refused)),
            ),
            (
                "G93\nM70\no1 if [1]\nM72\no1 endif\nG1 X1",
                Some((8, 4, Rule::InverseTimeWithoutFeed)),
            ),
            (
                "G93 F100\nG20\nM70\nG21\nM72\nG94\nG1 X1 F10\nG93\nG1 X2",
                Some((11, 4, Rule::NoFeedRate)),
            ),
            // a save in a loop: a later turn's may be taken under a mode set after it (G94)
            (
                "G95\no1 repeat [2]\nM70\nG94\no1 endrepeat\nM72\nG1 X1 F100",
                None,
            ),
            // F3: the restore's G17, or an F0 against a rate not known, takes the motion's
            // place
            ("M70\nG18\nM72 G1 X1", None),
            ("F[50*2]\nM70\nF0\nM72 G1 X1", None),
            // F4: the spindle and the compensation restored; an M5 after the M72 stops it
            ("S1000 M3\nM70\nM5\nM72\nG33 Z-1 K0.1", None),
            ("F100\nM70\nG41.1 D0.1\nG1 X1\nM72\nG81 X1 Z-1 R1", None),
            (
                "S1000 M3\nM70\nM72\nM5\nG33 Z-1 K0.1",
                Some((7, 1, refused)),
            ),
            // review 58c, F1: a followed save gives back the direction and the compensation
            // it took ("Spindle not turning in G33", "Spindle turning counterclockwise in
            // G84", "Cannot use canned cycles with cutter compensation on", "Cannot turn
            // cutter radius comp on when on"); an M6 before the save stops the spindle, a
            // G40 of the save's block runs after it, one of the M72's block after the restore
            ("M70\nM72\nG33 Z-1 K0.1", Some((5, 1, refused))),
            ("S100 M4\nM70\nM72\nG84 X1 Z-1 R1 F1", Some((6, 1, refused))),
            (
                "F10\nG41.1 D0.1\nG1 X1\nM70\nM72\nG81 X1 Z-1 R1",
                Some((8, 1, refused)),
            ),
            (
                "F10\nG41.1 D0.1\nG1 X1\nM70\nM72\nG41.1 D0.1",
                Some((8, 1, refused)),
            ),
            (
                "S1000 M3\nM6 T1\nM70\nM3\nM72\nG33 Z-1 K0.1",
                Some((8, 1, refused)),
            ),
            (
                "F10\nG41.1 D0.1\nG1 X1\nM70 G40\nG1 X2\nM72\nG81 X1 Z-1 R1",
                Some((9, 1, refused)),
            ),
            (
                "F10\nM70\nM72 G41.1 D0.1\nG1 X1\nG81 X1 Z-1 R1",
                Some((7, 1, refused)),
            ),
            // review 58c F3, F5: the M72 block's codes after the restore, the M70 block's
            // before the save, and what a followed M72 put back change nothing it compares
            // ("Cannot do g1 with zero feed rate" each); an M8 before the M72 does
            ("M70\nM72 G18 G1 X1", Some((4, 12, Rule::NoFeedRate))),
            ("M70 G95\nM72 G1 X1", Some((4, 8, Rule::NoFeedRate))),
            ("M70\nM8\nM72\nM72 G1 X1", Some((6, 8, Rule::NoFeedRate))),
            ("M70\nM8\nM72 G1 X1", None),
            // (an M6 of the M72's block, before the restore: not followed; rs274 runs it)
            ("S1000 M3\nM70\nM5\nM72 M6 T1\nG33 Z-1 K0.1", None),
            // a G20 between leaves the feed's restore not followed, not the spindle's; a save
            // in a condition leaves it not known
            ("M70\nG20\nM72\nG21\nG33 Z-1 K0.1", Some((7, 1, refused))),
            // across it the restore writes the saved rate after the block's own F: zero
            // below 0.05 (the linuxcnc profile's F0.04: tests/test_linuxcnc_refusals.py),
            // else not zero
            (
                "F0\nM70\nG20\nM72 F10\nG1 X1",
                Some((7, 4, Rule::NoFeedRate)),
            ),
            ("F10\nM70\nG20\nM72 F0\nG1 X1", None),
            ("o1 if [1]\nM70\no1 endif\nM72\nG33 Z-1 K0.1", None),
        ];
        let judged = [
            Rule::NoFeedRate,
            Rule::InverseTimeWithoutFeed,
            Rule::LinuxCncRefuses,
        ];
        for (body, expected) in cases {
            let text = format!("{head}{body}\nM2\n");
            let got = check(of_family(Family::LinuxCnc), &text)
                .into_iter()
                .find(|f| judged.contains(&f.rule))
                .map(|f| (f.line, f.column, f.rule));
            assert_eq!(got, *expected, "{body}");
        }
    }
}
