//! Motion, feeds and arcs (rules TG401-TG411): a motion mode in force for the axis words, a
//! feed rate for a feed move, the G06 parabola's blocks, and an arc's centre, start, radius
//! and quadrants as the profile reads I J K (7.3).

use super::codes::{self, group_of};
use super::tooling::Double;
use super::{round6, Before, BlockView, Checker, Facts, Ijk, Role};
use crate::decimal::Dec;
use crate::dialect;
use crate::geometry::{self, RadiusArc};
use crate::lex::Family;
use crate::modal::{bit, Units};
use crate::rules::Rule;
use crate::statement::{self, Effect, Kind};
use crate::text::push_fixed;

/// TG401's message.
const NO_FEED: &str = "feed motion with no feed rate in force";

/// [`Checker::feeds`] in a block whose M02/M30 reset the state: its own move is a feed move
/// with no feed rate.
#[cold]
fn ended_without_feed(from: &crate::modal::EndedFrom, lathe_feed: bool) -> bool {
    (matches!(from.motion, Some(1 | 2 | 3 | 6)) || lathe_feed)
        && from.cycle.is_none()
        && from.feed.is_none()
        && !from.feed_unknown
}

/// The most TG401 findings a program part holds until its end says whether it is a
/// subprogram (its line and column each: 1.6 MB).
pub(super) const HELD_FEEDS: usize = 100_000;

/// What a block's G codes are to the motion group ([`Checker::read_motion_codes`]).
struct MotionCodes {
    /// A code whose motion the modal state models (G0-G3, G6, G33-G35, G80-G89, a lathe's own).
    modelled: bool,
    /// A code of the motion group (or of the canned cycles') that it does not model.
    unmodelled: bool,
    /// A code that takes the block's axis words itself (G10, G28, G30, G52, G92).
    takes_axes: bool,
    /// The token of such a canned cycle, and its whole number.
    cycle: Option<(String, i64)>,
    /// The G codes the family's list lacks, each with whether a configuration may define it
    /// (`dialect::g_code_remappable`).
    lacked: Vec<(String, bool)>,
}

impl Checker {
    /// TG401, TG402: a feed move has its feed rate (7, Annex E); then the parabola and the
    /// arc of the block.
    pub(super) fn feeds(&mut self, b: &BlockView<'_>, before: &Before, facts: &Facts<'_>) {
        let line = b.line;
        let moved = facts.moved();
        let v = &self.values;
        let has_f = v.has(b'F');
        let lead = v.has(b'I') || v.has(b'J') || v.has(b'K');
        // G10 data, G28/G30 reference return, G52/G92 coordinate settings, G53 machine
        // coordinates (rapid), a lathe's G50: the axis words are no feed move (G68 X Y R and
        // G51 X Y P give a centre of rotation or scaling, as the position does; a dwell's
        // time words are not among the moved axes)
        // (and each control's other non-modal codes that take the axis words: the modal
        // motion does not run in their block, ModalSettings::axes_taken)
        let taken = self.machine.taken().is_some() || self.decimal_taken(b);
        const NOT_FEED: u128 = 1 << 10 | 1 << 28 | 1 << 30 | 1 << 52 | 1 << 53 | 1 << 92;
        let not_a_feed_move = facts.mask & NOT_FEED != 0 || taken;
        // (a Fanuc or Haas lathe's threading and single cycles cut at the F in force too)
        let lathe_feed = self.config.modal.fanuc_lathe
            && self
                .machine
                .state
                .motion
                .is_some_and(|g| self.machine.settings.own_motion(g));
        let feed_motion = (matches!(self.machine.state.motion, Some(1 | 2 | 3 | 6)) || lathe_feed)
            && self.machine.state.cycle.is_none()
            && !moved.is_empty()
            && !not_a_feed_move
            && !self.linuxcnc_spline(facts)
            && self.linuxcnc_m72_dropped != Some(self.stats.blocks);
        // (the block's own motion and feed where its M02/M30 reset them after its words)
        let no_feed = match self.machine.ended_from.as_deref() {
            None => {
                feed_motion
                    && self.machine.state.feed.is_none()
                    && !self.machine.state.is_unknown(b'F')
            }
            Some(from) => {
                !moved.is_empty() && !not_a_feed_move && ended_without_feed(from, lathe_feed)
            }
        };
        if no_feed {
            let column = facts.col(moved[0]);
            if crate::dialect::has_returns(self.config.family)
                && self.enabled(Rule::NoFeedRate)
                && !self.feed_unheld
            {
                // a subprogram runs under its caller's feed: said once the program part
                // ends as a main program (Checker::part_ended)
                self.feed_pending.push((line, column));
                if self.feed_pending.len() >= HELD_FEEDS {
                    self.say_feed_pending();
                    self.feed_unheld = true;
                }
            } else {
                self.report(Rule::NoFeedRate, NO_FEED.into(), line, column);
            }
        }
        // F0 in force on a feed move, or under a fixed cycle that drills (its feed moves are
        // the cycle's): a feed rate of zero, which the controls alarm on as on a missing one
        // (LinuxCNC's cycles have their own rs274 message, TG412)
        let cycle_feed = self.machine.state.cycle.is_some()
            && !moved.is_empty()
            && !not_a_feed_move
            && self.config.family != Family::LinuxCnc;
        if (feed_motion || cycle_feed) && self.machine.state.feed.is_some_and(|f| f.is_zero()) {
            let message = format!(
                "feed motion at F0: a feed rate of zero is in force ({})",
                crate::dialect::zero_feed_effect(
                    self.config.family,
                    matches!(self.machine.state.motion, Some(2 | 3)),
                    self.config.haas
                )
            );
            let column = facts.col(moved[0]);
            self.report(Rule::NoFeedRate, message, line, column);
        }
        // LinuxCNC under G95 feeds by the spindle's turn: rs274 refuses a G1 or an arc with no
        // spindle speed (S0, or none since the start: rs274 starts at S0), after its check of
        // the feed rate (interp_convert.cc convert_straight, convert_arc)
        // (not judged where the mode in force is unsure: after a call, or a G93/G94/G95 in a
        // condition or loop; review 19; asked only under G93 or G95, most blocks' mode being
        // G94)
        let mode_unsure =
            |c: &Checker| c.config.family == Family::LinuxCnc && c.linuxcnc_feed_mode_unsure();
        let state = &self.machine.state;
        if feed_motion
            && state.feed_mode == 95
            && self.config.family == Family::LinuxCnc
            && !mode_unsure(self)
            && state.feed.is_some_and(|f| !f.is_zero())
            && state.speed.is_none_or(|s| s.is_zero())
            && !state.is_unknown(b'S')
        {
            let message = "Cannot feed with zero spindle speed in feed per rev mode (rs274ngc): \
                           under G95 the feed is a length a spindle turn, and no S is in force"
                .into();
            self.report(Rule::LinuxCncRefuses, message, line, facts.col(moved[0]));
        }
        // LinuxCNC's probes and NURBS points read rs274's feed rate, not the block's inverse
        // time (interp_convert.cc convert_probe, convert_nurbs): no F needed under G93 where
        // one of them runs, which the modal state, keeping the G1 before it, takes for a G1
        let rs274_rate = || {
            self.config.family == Family::LinuxCnc
                && matches!(
                    self.linuxcnc_motion,
                    super::tooling::LinuxCncMotion::Known(Some(52 | 382..=385))
                )
        };
        // an F the checker cannot evaluate (`F[75.0]`, `F#<rate>`) is the block's F all the
        // same: rs274 runs `G93 G1 X1 F[75.0]` (held12's inverse-time thread subroutine)
        let written_f = || facts.words.iter().any(|w| w.letter == b'F');
        if feed_motion
            && self.machine.state.feed_mode == 93
            && !mode_unsure(self)
            && !has_f
            && !written_f()
            && !rs274_rate()
        {
            let message = "G93 inverse time: every motion block needs its F".into();
            self.report(
                Rule::InverseTimeWithoutFeed,
                message,
                line,
                facts.col(moved[0]),
            );
        }
        // HEIDENHAIN's G06 is a circular arc with tangential connection, no parabola (TNC
        // 360/407 ISO manuals, G function list): its end point is all it takes
        let parabola =
            self.machine.state.motion == Some(6) && self.config.family != Family::Heidenhain;
        if parabola || self.g06_open.is_some() {
            self.parabola(line, facts.has(6), !moved.is_empty(), lead);
        }
        let arc = matches!(self.machine.state.motion, Some(2 | 3))
            && (!moved.is_empty() || lead || self.radius_given())
            && self.machine.state.cycle.is_none()
            && !taken;
        if arc && self.config.family == Family::LinuxCnc && facts.has(53) {
            // rs274ngc's G53 moves by the G0 or G1 in force, never by an arc
            // (interp_check.cc, NCE_MUST_USE_G0_OR_G1_WITH_G53)
            let message = "Must use g0 or g1 with g53 (rs274ngc): G53 moves in machine \
                           coordinates by G0 or G1, and G2/G3 is in force"
                .into();
            self.report(Rule::LinuxCncRefuses, message, line, facts.col(b'G'));
        } else if arc {
            let runs = !moved.is_empty() || facts.has(2) || facts.has(3);
            self.arc(b, before, runs);
        }
    }

    /// LinuxCNC: a block of G5 (5 in `facts`) or G5.1 (a decimal code). Its axis words are the spline's, not the motion in force's (convert_spline sets
    /// no motion mode), and its feed is convert_spline's to check, which the spline's own
    /// refusals follow (`linuxcnc_plane_refusal`: under G94 a zero feed rate, under G93 a
    /// block without F, under G95 nothing). TG401, TG402 and the zero-speed refusal judged
    /// the G1 in force instead (review 56c, F7: `G1 X2 F10` / `G95` / `G5.1 X1 Y1 I1 J1`
    /// runs in `rs274 -g`; after an M72 the checker does not follow, `G93 G1 X1 F100` /
    /// `o1 if [1]` / `M72` / `o1 endif` / `G5 ...` was refused under a G93 not in force).
    /// And a NURBS point (a G5.2 block, or a point after it, rs274's motion G5.2): its feed
    /// is TG412's "Cannot make a NURBS with 0 feedrate" (review 57d, F5: `G1 X2 F10` / `G95`
    /// / `G5.2 X1 Y1 P1 L3` / `X2 Y2 P1` / ... / `G5.3` runs).
    fn linuxcnc_spline(&self, facts: &Facts<'_>) -> bool {
        self.config.family == Family::LinuxCnc
            && (self.linuxcnc_motion == super::tooling::LinuxCncMotion::Known(Some(52))
                || (facts.has(5) || self.values.decimal_g) && self.linuxcnc_g5_or_g51(facts))
    }

    /// [`Checker::linuxcnc_spline`]: a G5 or G5.1 among the block's G words.
    fn linuxcnc_g5_or_g51(&self, facts: &Facts<'_>) -> bool {
        facts.words.iter().enumerate().any(|(i, w)| {
            w.letter == b'G'
                && self.readable.get(i).copied().flatten().is_some_and(|v| {
                    let tenths = v.to_f64() * 10.0;
                    (tenths - 50.0).abs() < 1e-6 || (tenths - 51.0).abs() < 1e-6
                })
        })
    }

    /// A Fanuc or Haas decimal code of group 00 that takes the block's axis words (the
    /// modal state holds whole codes only): G07.1 (the cylinder's radius), G10.6 (the retract
    /// amount), G30.1 (floating reference position return), G50.3 and G92.1 (workpiece
    /// coordinate system preset), G72.1/G72.2 (figure copying), G81.1 (chopping: Z the upper
    /// dead point); FANUC 0i-MF/0i-TF "G code list".
    fn decimal_taken(&self, b: &BlockView<'_>) -> bool {
        // the codes in tenths: 71 is G07.1; LinuxCNC's G33.1 (rigid tapping), G38.2-G38.5
        // (probing) and G43.1 (the dynamic tool length offset's Z) are no move of the G2/G3
        // in force either (rs274 runs each in G2 mode)
        const CODES: [i128; 8] = [71, 106, 301, 503, 921, 721, 722, 811];
        const LINUXCNC: [i128; 6] = [331, 382, 383, 384, 385, 431];
        let codes: &[i128] = match self.config.family {
            Family::MacroB => &CODES,
            Family::LinuxCnc => &LINUXCNC,
            _ => return false,
        };
        // (a block whose codes have a key has none with a fraction: codes::code_key)
        if self.letters & bit(b'G') == 0 || self.code_key.is_some() {
            return false;
        }
        b.words.iter().enumerate().any(|(i, w)| {
            w.letter == b'G'
                && self.readable[i].is_some_and(|v| {
                    let v = v.normalized();
                    v.scale == 1 && codes.contains(&{ v.mantissa })
                })
        })
    }

    /// Whether the block's axis words are a move the backplot draws. Not the data of a code
    /// that sets, shifts or mirrors the coordinates without moving (G10, G52, G92, a lathe's
    /// G50, G92.1 and G50.3 presets, G51.1/G50.1 mirror, G10.6, G07.1: FANUC 0i-MF "G code
    /// list"; rs274 runs `G52`/`G92` with no move, `SET_G92_OFFSET`), nor a move to a point
    /// nobody knows (a skip, a measurement, a pattern, a home position), except the reference
    /// returns the backplot keeps the start of (G28 G30 G53, [`super::drawn`]).
    pub(super) fn draws(&self, b: &BlockView<'_>, facts: &Facts<'_>) -> bool {
        use crate::modal::AxesTaken;
        match self.machine.taken() {
            Some(AxesTaken::Data | AxesTaken::Set | AxesTaken::Home) => false,
            Some(AxesTaken::Unknown) => [28, 30, 53].iter().any(|&g| facts.has(g)),
            Some(AxesTaken::Positions) => true,
            None => {
                // the codes in tenths: 921 is G92.1
                const SETS: [i128; 6] = [71, 106, 501, 503, 511, 921];
                let sets = self.config.family == Family::MacroB
                    && b.words.iter().enumerate().any(|(i, w)| {
                        w.letter == b'G'
                            && self.readable[i].is_some_and(|v| {
                                let v = v.normalized();
                                v.scale == 1 && SETS.contains(&{ v.mantissa })
                            })
                    });
                !sets && !facts.has(10) && !facts.has(52)
            }
        }
    }

    /// The end of a program part: where it returned (`returned`, a subprogram) its held TG401
    /// findings are dropped, else (M02/M30, the end of the file: a main program, which the
    /// control alarms on) they are said.
    pub(super) fn part_ended(&mut self, returned: bool) {
        // (a main program that returns runs again from its start; one whose jump names a
        // block after its end reaches blocks read after this one, a Haas's local
        // subprograms among them: callflow.rs, review 79-calls79 F5)
        if self.flow_calls.is_some() && !self.early_on && (returned || self.targets.goto_pending())
        {
            self.flow_spoiled();
        }
        if returned {
            self.feed_pending.clear();
        } else {
            self.say_feed_pending();
        }
        // a program read from the reset state that returns is a subprogram of a call later
        // in the file, if any (crate::check::called)
        if self.early_on {
            if returned {
                self.early_pend();
            } else {
                self.early_merge_as(true);
            }
        }
        if !self.call_works_assumed.is_empty() {
            self.call_works_ended(returned);
        }
        if self.later_shift.is_some() {
            self.later_shift_closed();
        }
        if self.units_merged.is_some() || self.guess_marked.is_some() {
            self.units_merged_ended(returned);
        }
        self.feed_unheld = false;
    }

    fn say_feed_pending(&mut self) {
        for (line, column) in std::mem::take(&mut self.feed_pending) {
            self.report(Rule::NoFeedRate, NO_FEED.into(), line, column);
        }
    }

    /// A program file that is a subprogram by its name (a SINUMERIK's `.SPF`): it runs
    /// where and as its caller left the machine, so its position, feed and speed are unknown
    /// from its start. `name` is the file's name as the user gave it.
    pub fn file_name(&mut self, name: &str) {
        if crate::dialect::subprogram_by_name(self.config.family, name) {
            self.machine.forget();
        }
        let base = name.rsplit(['/', '\\']).next().unwrap_or(name);
        self.called_as = base
            .strip_suffix(".ngc")
            .filter(|label| !label.is_empty())
            .map(|label| label.as_bytes().to_vec());
    }

    /// HEIDENHAIN: the circle centre CC (I J K, absolute) stays in force for the arcs after
    /// it.
    pub(super) fn heidenhain_centre(&mut self) {
        if self.config.family == Family::Heidenhain {
            for (i, &letter) in b"IJK".iter().enumerate() {
                if let Some(value) = self.values.get(letter) {
                    self.centre_kept[i] = Some(value);
                    self.centre_lost[i] = false;
                } else if self.values.unknown & crate::modal::bit(letter) != 0 {
                    // an increment from an unknown point, a parameter: a CC not followed
                    self.centre_kept[i] = None;
                    self.centre_lost[i] = true;
                }
            }
        }
    }

    /// A SINUMERIK's predefined instruction that moves in a way the checker does not model
    /// ([`statement::SINUMERIK_INSTRUCTIONS`]): after a spline, `CIP`, `CT` or an involute the
    /// motion in force is unknown until G0-G3 (its points are no lines or arcs to check);
    /// after a repositioning (`REPOSA`) the position is unknown; after a procedure that
    /// couples, reconfigures or sets axes (`LEADON`, `TRAORI`, `PRESETON`) the position is
    /// unknown and the work offsets are no longer the profile's (TG140 names it, once per
    /// file, as for a call); after a kinematic transformation (`TRACYL(400)`) or the `TRAFOOF`
    /// that ends it the position is unknown, and between them the travel is not compared
    /// ([`Checker::limits`]); after `SETMS` the speed is unknown and the master spindle the
    /// one it names ([`Checker::set_master`]); after a positioning axis's or
    /// a spindle's assignment (`POSA[X]=100`, `SPOS=90`) that axis is unknown
    /// ([`Checker::positioned`]). A variable a procedure takes
    /// as an argument may be one it writes (`READ(ERR,"F",1,1,_LINES)`, `GETSELT(_T)`): it is
    /// no longer known.
    pub(super) fn named_motions(&mut self, b: &BlockView<'_>) {
        if self.config.family != Family::Sinumerik {
            return;
        }
        // (a SETMS after a condition, loop, jump or label may not run: review 56d F8)
        let flow_here = b
            .statements
            .iter()
            .any(|&(_, kind, _)| matches!(kind, Kind::Flow | Kind::Label));
        let may_skip = self.flow_seen || flow_here;
        self.flow_seen = may_skip;
        for &(column, kind, text) in b.statements {
            if kind == Kind::Assignment {
                self.positioned(text);
                continue;
            }
            if kind != Kind::Command {
                continue;
            }
            let end = statement::ident_end(text, 0);
            let name = statement::Upper::of(&text[..end]);
            let Some(group) = statement::sinumerik_instruction(&name) else {
                continue;
            };
            if group.effect == Effect::Spindle {
                // (read before the arguments are forgotten: `SETMS(R1)`)
                self.set_master(text, b.line, may_skip);
            }
            if group.arguments && text.get(end) == Some(&b'(') {
                let inside = &text[end + 1..text.len().saturating_sub(1)];
                for argument in super::params::split_arguments(inside) {
                    let argument = argument.trim_ascii();
                    if !argument.is_empty() && statement::ident_end(argument, 0) == argument.len() {
                        self.params.remove(&super::params::sinumerik_key(argument));
                    }
                }
            }
            match group.effect {
                Effect::Motion => {
                    self.machine.state.motion = None;
                    self.motion_unknown = true;
                }
                Effect::Reposition => self.machine.forget_position(),
                Effect::Axes => {
                    let shown = String::from_utf8_lossy(&name).into_owned();
                    if !self.unfollowed_noted {
                        self.unfollowed_noted = true;
                        let message = format!(
                            "{} (predefined procedure): it {}, which the checker does not \
                             follow; from here on the position is taken as unknown until the \
                             program sets it",
                            String::from_utf8_lossy(text),
                            group.what
                        );
                        self.report(Rule::NotFollowed, message, b.line, column);
                    }
                    self.machine.forget_position();
                    self.lose_offsets(b.line, &format!("{shown} {}", group.what));
                }
                Effect::Transform => {
                    // into other coordinates and back: where the axes are is not known in
                    // either, and until TRAFOOF no position is a machine position; a TRAFOOF
                    // with no transformation in force (a program's opening) changes nothing
                    let off = name.as_slice() == b"TRAFOOF";
                    if !off || self.transformed.is_some() {
                        self.machine.forget_position();
                    }
                    self.transformed = (!off).then(|| super::Transformed {
                        line: b.line,
                        name: String::from_utf8_lossy(&name).into_owned(),
                        noted: false,
                    });
                }
                Effect::Spindle => self.machine.forget_speed(),
                Effect::Mode | Effect::Frame | Effect::Return | Effect::Unclear => {}
            }
        }
    }

    /// A SINUMERIK positioning axis or spindle moved by an assignment (Programming Manual
    /// Fundamentals, "Traversing positioning axes (POS, POSA, POSP, FA, WAITP, WAITMC)" and
    /// "Spindle positioning (SPOS, SPOSA, M19)"): `POS[X]=100`, `POSA[X]=100` (which goes on
    /// moving across the blocks after it, until `WAITP(X)` or the end of the program) and
    /// `POSP[X]=(..)` move the axis in brackets on its own interpolator, as no path word does,
    /// and the value may be `IC(..)`, `ACP(..)`, `CAC(..)` or an expression: that axis's position
    /// is no longer known (every axis's, where the brackets name none of the letters the
    /// checker follows: `POS[AX3]`, a variable). `SPOS=90`, `SPOSA[2]=..` turn a spindle to an
    /// angle; which rotary axis a spindle is in axis mode is machine data, so the rotary axes
    /// A, B and C are no longer known. `WAITP` itself then changes nothing.
    fn positioned(&mut self, text: &[u8]) {
        // asked of every assignment (`_X=1`, `CR=5`): the name compared, not copied
        let end = statement::ident_end(text, 0);
        let is = |names: &[&[u8]]| names.iter().any(|n| text[..end].eq_ignore_ascii_case(n));
        if is(&[b"POS", b"POSA", b"POSP"]) {
            let axis = match text.get(end) {
                Some(b'[') => text[end + 1..]
                    .iter()
                    .position(|&c| c == b']')
                    .map(|close| text[end + 1..end + 1 + close].trim_ascii()),
                _ => None,
            };
            match axis {
                Some(&[letter])
                    if crate::modal::axis_index(letter.to_ascii_uppercase()).is_some() =>
                {
                    self.machine.forget_axis(letter.to_ascii_uppercase());
                }
                _ => self.machine.forget_position(),
            }
        } else if is(&[b"SPOS", b"SPOSA"]) {
            for letter in [b'A', b'B', b'C'] {
                self.machine.forget_axis(letter);
            }
        }
    }

    /// TG411: axis words where no motion mode is in force. LinuxCNC has none at the start and
    /// after G80 (rs274: "Cannot use axis values without a g code that uses them"); the other
    /// controls keep G00 or G01 from their reset state and through G80. A block with a code
    /// that takes axis words itself (G10, G28, G30, G52, G92, a motion code the modal state does
    /// not model) is not one; nor is a dwell's time word, but another axis word beside G04 is
    /// (rs274 refuses `G4 P1 X1` with no motion mode).
    pub(super) fn motion_mode(&mut self, b: &BlockView<'_>, facts: &Facts<'_>, takes_axes: bool) {
        let moved = facts.moved();
        let takes_axes = takes_axes || self.machine.taken().is_some();
        if self.machine.state.motion.is_none()
            && self.machine.state.cycle.is_none()
            && !moved.is_empty()
            && !self.motion_unknown
            && !takes_axes
            && !self.ended_in_motion()
        {
            let names: Vec<String> = moved.iter().map(|&a| (a as char).to_string()).collect();
            let message = format!(
                "{} with no motion mode in force (this control has none at the start and after \
                 G80): program G00 or G01 first",
                names.join(" ")
            );
            self.report(Rule::NoMotionMode, message, b.line, facts.col(moved[0]));
        }
    }

    /// The block's M02/M30 reset the modes after its words, and its own axis words moved
    /// under a motion or cycle in force before (`G1 X1 M2` on LinuxCNC, whose reset has no
    /// motion mode: review 51, F7). Asked only where the state has no motion mode.
    #[cold]
    #[inline(never)]
    fn ended_in_motion(&self) -> bool {
        self.machine
            .ended_from
            .as_deref()
            .is_some_and(|from| from.motion.is_some() || from.cycle.is_some())
    }

    /// The block's motion-group codes, read with the machine's own changes of state before
    /// any rule reads it: a code of the motion group that the modal state does not model
    /// replaces the G2 or G3 it still holds, and leaves the motion unknown; a modelled one
    /// makes it known again. Whether a code of the block takes its axis words itself (G10,
    /// G28, G30, G52, G92) is returned for [`Checker::motion_mode`].
    pub(super) fn motion_codes(&mut self, b: &BlockView<'_>) -> bool {
        // (a block with no G word changes none of this)
        if self.letters & bit(b'G') == 0 {
            return false;
        }
        // codes met before: their reading, kept where it named no cycle and no code the list
        // lacks (a debug build, the tests', reads them anyway and holds the two equal)
        let key = self.code_key;
        let kept = key.map_or(0, |k| self.verdicts.get(k));
        if kept & codes::MOTION != 0 && !cfg!(debug_assertions) {
            // (what the reading below does with a kept reading, which names no cycle and no
            // code the list lacks, without the reading's value built and dropped)
            self.motion_read(kept & codes::MODELLED != 0, kept & codes::UNMODELLED != 0);
            return kept & codes::TAKES_AXES != 0;
        }
        let read = self.read_motion_codes(b);
        let flags = codes::MOTION
            | if read.modelled { codes::MODELLED } else { 0 }
            | if read.unmodelled {
                codes::UNMODELLED
            } else {
                0
            }
            | if read.takes_axes {
                codes::TAKES_AXES
            } else {
                0
            };
        if kept & codes::MOTION != 0 {
            let motion = codes::MOTION | codes::MODELLED | codes::UNMODELLED | codes::TAKES_AXES;
            debug_assert_eq!(kept & motion, flags, "line {}", b.line);
            debug_assert!(read.cycle.is_none() && read.lacked.is_empty());
        } else if let Some(k) = key.filter(|_| read.cycle.is_none() && read.lacked.is_empty()) {
            self.verdicts.add(k, flags);
        }
        let MotionCodes {
            modelled,
            unmodelled,
            takes_axes,
            cycle,
            lacked,
        } = read;
        self.motion_read(modelled, unmodelled);
        if let Some((code, g)) = cycle {
            self.cycle_unmodelled = true;
            // (a lathe's thread in force: the cycle's repeats are not its passes)
            if self.machine.settings.fanuc_lathe {
                self.machine.cycle_over_thread(g);
            }
            let said = format!(": {code} is ");
            if !self.stats.moves_not_known.iter().any(|m| m.contains(&said)) {
                self.stats.moves_not_known.push(format!(
                    "from line {}{said}a canned cycle of the control's list whose strokes \
                     tapegate does not model: its positions are not in the path, its lengths, \
                     the cycle time or the plot until G80 or a motion code",
                    b.line
                ));
            }
        }
        if !lacked.is_empty() {
            // a code the family's list lacks: the control alarms on it, or runs the macro its
            // parameters name, which may set any mode (a system B/C lathe program's G33 thread
            // is no rapid): the motion is not known until a motion code the list holds, and
            // the moves in between are no path, length or time of the program's
            self.motion_unknown = true;
            self.machine.state.motion = None;
            self.machine.state.cycle = None;
            for (code, remappable) in lacked {
                let said = format!(": {code} is not in ");
                if self.stats.moves_not_known.iter().any(|m| m.contains(&said)) {
                    continue;
                }
                // (where the control alarms whatever its parameters, TG306, no macro runs)
                let does = if remappable {
                    "the control alarms, or runs the REMAP its configuration names"
                } else if self.config.alarm_g {
                    "the control alarms"
                } else {
                    "the control alarms, or runs a macro its parameters name"
                };
                self.stats.moves_not_known.push(format!(
                    "from line {}{said}the family's code list ({does}), so the motion is not \
                     known until the next motion code the list holds; the moves in between are \
                     not in the path, its lengths, the cycle time or the plot",
                    b.line
                ));
            }
        }
        takes_axes
    }

    /// The motion state after a block whose G codes hold a motion code the modal state does
    /// not model (`unmodelled`) or one it does (`modelled`) ([`Checker::motion_codes`]).
    #[inline(always)]
    fn motion_read(&mut self, modelled: bool, unmodelled: bool) {
        if unmodelled {
            // the code replaces the G2 or G3 the modal state still holds: the block and the
            // ones after it are no arcs (LinuxCNC's G5 spline and G5.2 NURBS after a G2 run as
            // such in rs274 -g); a motion the state models itself (HEIDENHAIN's polar G11)
            // stays
            self.motion_unknown = true;
            if matches!(self.machine.state.motion, Some(2 | 3)) {
                self.machine.state.motion = None;
            }
        } else if modelled {
            self.motion_unknown = false;
            self.cycle_unmodelled = false;
        }
    }

    /// Whether G code `v` is one the family's list lacks: a whole number its list does not
    /// hold, or a decimal code a profile with its control's own list does not hold (ISO
    /// 6983-1's table reports its own: TG301). The motion it leaves (`read_motion_codes`) and
    /// where its block's axes stand (the block's reading, `AxesTaken::Unknown`) both ask it.
    #[inline]
    pub(super) fn code_lacked(&self, v: Dec) -> bool {
        if v.is_whole() {
            self.machine.settings.lacks(v.trunc())
        } else {
            !self.machine.settings.lacks_g.is_empty() && self.config.decimal_code(v).is_none()
        }
    }

    /// What the block's G codes are to the motion group ([`Checker::motion_codes`]): read
    /// from the profile's code list and the family's, nothing else.
    fn read_motion_codes(&self, b: &BlockView<'_>) -> MotionCodes {
        let motion_group = group_of(&self.config, b'G', 1);
        // the canned cycles' group (Fanuc and Haas group 09, G81's): a cycle of the control's
        // list the modal state does not model (a Haas lathe's radial G241-G249, live tool
        // tapping G195/G196) drills at its own feeds and returns where its words say, so its
        // block and the positions after it are no moves of the G00-G03 in force. None where
        // G81 is no code of the control: a SINUMERIK drills with CYCLE81 and the like, and its
        // table holds G81 as not its code, in the one-block codes' group (TBO), whose G4, G9,
        // G25/G26 (working area and spindle speed limits), G53 or G110 is no cycle and leaves
        // the moves after it as they are (review 38, finding 12: `G26 S3000` dropped the moves
        // after it from --stats and the plot)
        let cycle_group = self
            .config
            .code(b'G', 81)
            .filter(|c| c.status != super::Status::Unassigned)
            .map_or("", |c| c.duration.as_str());
        let (mut modelled, mut unmodelled, mut takes_axes) = (false, false, false);
        let mut cycle = None;
        let mut lacked = Vec::new();
        for (i, w) in b.words.iter().enumerate() {
            let Some(v) = self.readable[i].filter(|_| w.letter == b'G') else {
                continue;
            };
            let n = v.trunc();
            if self.code_lacked(v) {
                lacked.push((
                    w.token().to_string(),
                    dialect::g_code_remappable(self.config.family, v),
                ));
                continue;
            }
            if v.is_whole()
                && (matches!(n, 0..=3 | 6 | 33..=35 | 80..=89)
                    || self.machine.settings.own_motion(n))
            {
                modelled = true;
                continue;
            }
            takes_axes |= v.is_whole() && matches!(n, 10 | 28 | 30 | 52 | 92);
            // LinuxCNC's G43.1 and G43.2 take axis words without a motion mode in force
            // (interp_internal.cc enhance_block: their offsets)
            takes_axes |= self.config.family == Family::LinuxCnc
                && n == 43
                && matches!(
                    v.normalized(),
                    Dec {
                        mantissa: 431 | 432,
                        scale: 1
                    }
                );
            let group = if v.is_whole() {
                group_of(&self.config, b'G', n)
            } else {
                self.config
                    .decimal_code(v)
                    .map_or("", |(_, c)| c.duration.as_str())
            };
            unmodelled |= !motion_group.is_empty() && group == motion_group;
            // (LinuxCNC's cycles are of the motion group, which the line above takes)
            if !cycle_group.is_empty()
                && cycle_group != motion_group
                && group == cycle_group
                && !(73..=89).contains(&n)
            {
                unmodelled = true;
                cycle = Some((w.token().to_string(), n));
            }
        }
        MotionCodes {
            modelled,
            unmodelled,
            takes_axes,
            cycle,
            lacked,
        }
    }

    pub(super) fn parabola(&mut self, line: usize, g06: bool, moved: bool, lead: bool) {
        if let Some(open) = self.g06_open.take() {
            if !(self.machine.state.motion == Some(6) && moved) {
                let message = "G06 three-point parabola without its end point block".into();
                self.report(Rule::ParabolaIncomplete, message, open, 1);
            }
            return;
        }
        if g06 && !lead {
            self.g06_open = Some(line);
        }
    }

    /// Whether the block gives the radius letter where it is a radius: R only where the
    /// profile reads R as a length (a SINUMERIK's `R1=2` sets a parameter, its radius being
    /// CR=), so that a parameter alone in a block under G2/G3 runs no arc.
    fn radius_given(&self) -> bool {
        let radius = self.config.modal.arc_radius;
        self.values.has(radius) && (radius != b'R' || self.config.pqr[2] == Role::Length)
    }

    /// The arc checks of a block under G2/G3; `runs` that the block runs the arc (it moves
    /// an axis or gives G2/G3), where an `R` alone in arc mode runs none.
    pub(super) fn arc(&mut self, b: &BlockView<'_>, before: &Before, runs: bool) {
        let line = b.line;
        let words = b.words;
        let (first, second, third) = plane_axes(self.machine.state.plane);
        let centres = [centre_of(first), centre_of(second)];
        // (nor the arc of a block whose M72 rs274 2.9.0 surely drops: the restore's block
        // takes its place, convert_arc never sees it; `M70` / `S200` / `M72 G2 X1 Y0 R2` runs
        // in `rs274 -g`; review 59b F7)
        if self.linuxcnc_m72_surely_dropped() {
            return;
        }
        let v = &self.values;
        // rs274 draws no arc in G17.1-G19.1: TG412 refuses it first (convert_arc; the
        // plane's axes here are not the arc's)
        if self.config.family == Family::LinuxCnc && self.linuxcnc_uvw_plane {
            return;
        }
        // interp_convert.cc convert_arc refuses R beside any of I J K before it looks at the
        // plane (NCE_MIXED_RADIUS_IJK_FORMAT_FOR_ARC); a FANUC reads such an arc by its R
        if self.config.family == Family::LinuxCnc && runs && v.has(b'R') {
            if let Some(w) = words
                .iter()
                .find(|w| matches!(w.letter, b'I' | b'J' | b'K'))
            {
                let message = format!(
                    "Mixed radius ijk format for arc (rs274ngc): an arc takes R or I J K, \
                     and the block gives R and {}",
                    w.letter as char
                );
                self.report(Rule::LinuxCncRefuses, message, line, w.column);
                return;
            }
        }
        // nor is an arc judged by its plane where the plane is not known here (after a call,
        // an `if` whose branches may leave different planes, a body before it sets one:
        // review 54, F2), unless its block sets one; an arc with no centre word and no R is
        // refused in every plane (convert_arc: NCE_R_I_J_K_WORDS_ALL_MISSING_FOR_ARC, review
        // 55c, F2)
        if self.config.family == Family::LinuxCnc
            && self.linuxcnc_plane_unknown
            && ![17, 18, 19].iter().any(|&g| v.has_g(g))
        {
            let given = |letter: u8| v.has(letter) || v.unknown & crate::modal::bit(letter) != 0;
            if !b"IJKR".iter().any(|&a| given(a)) {
                // (a bare move after the main program's call of a definition not read yet,
                // under the caller's G2/G3: held for that definition's endsub)
                if self.linuxcnc_later.pending.is_some()
                    && !v.has_g(2)
                    && !v.has_g(3)
                    && self.linuxcnc_later_move(b)
                {
                    return;
                }
                let message = "arc without I J K (or R): none is given, whatever the plane";
                self.report(
                    Rule::ArcCentreMissing,
                    message.to_string(),
                    line,
                    words[0].column,
                );
            }
            return;
        }
        // about a SINUMERIK's pole, by its opening angle (polar.rs), or about a centre given by
        // a value the checker does not follow: no centre or radius to check
        let unknown = |letter: u8| v.unknown & crate::modal::bit(letter) != 0;
        let lost = self.config.family == Family::Heidenhain
            && centres
                .iter()
                .any(|&c| self.centre_lost[usize::from(c - b'I')])
            && !centres.iter().any(|&c| v.has(c));
        if self.polar_arc || self.opening_arc || centres.iter().any(|&c| unknown(c)) || lost {
            return;
        }
        let given = b"IJK".iter().copied().filter(|&a| v.has(a));
        let none_given = given.clone().next().is_none();
        for a in given {
            if !centres.contains(&a) {
                let column = super::column_of(words, a);
                let message = format!(
                    "{} is not a centre word of the G{} plane",
                    a as char, self.machine.state.plane
                );
                self.report(Rule::ArcCentreMissing, message, line, column);
                return;
            }
        }
        // the radius: R where the profile reads R as a length (an Okuma lathe's L: the
        // machine's radius letter), or Sinumerik's CR=, whose value is a number or, where
        // it is an expression (`CR=R1`, `CR=THR[1]`), given but not known here
        let cr = b.statements.iter().find_map(|&(_, _, text)| {
            let upper = text.to_ascii_uppercase();
            upper.strip_prefix(b"CR=").map(|v| {
                std::str::from_utf8(v)
                    .ok()
                    .and_then(|v| Dec::parse(v.trim()))
            })
        });
        let letter = self.config.modal.arc_radius;
        let radius_length = letter != b'R' || self.config.pqr[2] == Role::Length;
        if (radius_length && unknown(letter)) || cr == Some(None) {
            // a radius of unknown value (`R#500`, #500 not known; a SINUMERIK's `CR=R1`) is
            // given all the same: the arc is not judged, as with a centre of unknown value
            // (review 54, F6: TG404 "arc without I J (or R)"; held26's `CR=thr1`)
            return;
        }
        let cr = cr.flatten();
        let radius = match v.get(letter) {
            Some(r) if radius_length => Some(r),
            _ => cr,
        };
        let radius_word = radius.is_some();
        // HEIDENHAIN: an arc without I J turns about the centre CC last given
        let kept = |letter: u8| match self.config.family {
            Family::Heidenhain => self.centre_kept[usize::from(letter - b'I')],
            _ => None,
        };
        let centre = |letter: u8| v.get(letter).or_else(|| kept(letter));
        let (ci, cj) = (centre(centres[0]), centre(centres[1]));
        let kept_centre = none_given && kept(centres[0]).is_some() && kept(centres[1]).is_some();
        if none_given && !radius_word && !kept_centre {
            let mut names = [centres[0] as char, centres[1] as char];
            names.sort_unstable();
            // (a SINUMERIK's R word is a parameter, never a radius: its arc takes CR= or
            // AR=, Programming Manual Fundamentals, "Circular interpolation")
            let radius = match self.config.family {
                Family::Sinumerik => "CR=/AR=".to_string(),
                _ => char::from(letter).to_string(),
            };
            let message = format!("arc without {} {} (or {radius})", names[0], names[1]);
            self.report(Rule::ArcCentreMissing, message, line, words[0].column);
            return;
        }
        // LinuxCNC finds an R arc's centre from its start and end (interp_arc.cc arc_data_r,
        // without cutter compensation): an end that is the start leaves it undefined. Zero
        // increments under G91 end where they start, wherever that is.
        let state = &self.machine.state;
        let linuxcnc_r = self.config.family == Family::LinuxCnc
            && radius_word
            && v.has(b'R')
            && state.compensation == 40
            && !self.linuxcnc_dynamic_compensation
            && !self.linuxcnc_compensation_unknown;
        let stays = |axis: u8| {
            !v.has(axis) || (state.incremental && v.get(axis).is_some_and(|d| d.is_zero()))
        };
        let r_arc = self.config.family == Family::LinuxCnc && radius_word && v.has(b'R');
        if r_arc && !v.has(first) && !v.has(second) {
            // an R word alone runs no arc: rs274 refuses the word as no code's
            // (check_other_codes, TG412 of the LinuxCNC refusals), and says nothing more
            if !runs {
                return;
            }
            // interp_convert.cc convert_arc: an R arc names an end on its plane ("a full
            // circle is not allowed"), compensation or not
            let (a, b) = (first.to_ascii_lowercase(), second.to_ascii_lowercase());
            let (a, b) = if a < b { (a, b) } else { (b, a) };
            let message = format!(
                "{} and {} words missing for arc in {}{} plane (rs274ngc): an R arc ends on a \
                 point of its plane, and the block names none",
                a.to_ascii_uppercase() as char,
                b as char,
                a as char,
                b as char
            );
            self.report(Rule::LinuxCncRefuses, message, line, words[0].column);
            return;
        }
        if linuxcnc_r && stays(first) && stays(second) {
            self.report_same_end(line, words[0].column);
            return;
        }
        // set by a parameter, lost at a jump, or where a dialect's program starts (the tool
        // stands where the operator or the caller left it): nothing to check against. A strict
        // ISO profile's program has no such start (7.1): an arc before any position is TG408.
        let (Some(sx), Some(sy)) = (before.axis(first), before.axis(second)) else {
            if before.is_unknown(first) || before.is_unknown(second) {
                return;
            }
            let message = format!(
                "arc start point unknown: no earlier position on {} and {}",
                first as char, second as char
            );
            self.report(Rule::ArcWithoutStart, message, line, words[0].column);
            return;
        };
        // a lathe's X is a diameter: the arc's coordinate is its half (exact: 5 tenths)
        // (the diameter asked first: the 128-bit product only where it is one)
        let diameter = self.x_diameter();
        // (the test inlined, four times an arc; the halving out of line)
        let half = |axis: u8, d: Dec| {
            if diameter && axis == b'X' {
                half_of(d)
            } else {
                d
            }
        };
        // an end point not known (a value set by a parameter, a word the control refuses):
        // no arc is measured to a point guessed from the start
        let state = &self.machine.state;
        if (state.axis(first).is_none() && state.is_unknown(first))
            || (state.axis(second).is_none() && state.is_unknown(second))
        {
            return;
        }
        let (sx, sy) = (half(first, sx), half(second, sy));
        let ex = self
            .machine
            .state
            .axis(first)
            .map_or(sx, |d| half(first, d));
        let ey = self
            .machine
            .state
            .axis(second)
            .map_or(sy, |d| half(second, d));
        // rs274's start is the point in the active coordinates: where the checker does not know
        // it exactly, an absolute end named on that axis may be another point, and the arc is
        // not refused as one that ends where it starts (an axis not named stays where it is,
        // an increment is measured from the start wherever it is). The other arc checks keep
        // the start the program wrote: a tool offset in X or Y is a lathe's, rare on a mill,
        // and every CAM program's first arc after G43 would lose them.
        let unsure = [first, second]
            .iter()
            .any(|&a| v.has(a) && self.linuxcnc_point_unsure & bit(a) != 0)
            && !self.machine.state.incremental;
        // (under G90 as rs274 compares them: the doubles it holds, `Double`)
        let same = if linuxcnc_r && !self.machine.state.incremental {
            [(first, sx, ex), (second, sy, ey)]
                .iter()
                .all(|&(axis, s, e)| {
                    // (a diameter's half: its decimals compared)
                    if diameter && axis == b'X' {
                        return s == e;
                    }
                    let k = crate::modal::AXES[..3].iter().position(|&x| x == axis);
                    k.map_or(Double::Nearest, |k| self.linuxcnc_double[k])
                        .equals(s, e)
                })
        } else {
            ex == sx && ey == sy
        };
        if linuxcnc_r && !unsure && same {
            self.report_same_end(line, words[0].column);
            return;
        }
        if let Some(r) = radius {
            let scale = if self.machine.state.units == Units::Inch {
                1.0 / 25.4
            } else {
                1.0
            };
            let length = r.to_f64().abs();
            let tolerance = if self.config.family == Family::LinuxCnc {
                // rs274's arc_data_r: half the chord may pass the radius by 0.00005 in
                // (0.00127 mm), measured at the boundary (tests/test_oracle_rs274.py)
                0.00127 * scale
            } else {
                self.arc_tolerance(length, length, scale)
            };
            let clockwise = self.machine.state.motion == Some(2);
            let found = geometry::radius_arc((sx, sy), (ex, ey), r, clockwise, tolerance);
            self.radius_arc = Some(found);
            if r.is_zero() {
                let message = format!("arc of zero radius ({}0)", letter as char);
                self.report(Rule::ArcZeroRadius, message, line, words[0].column);
            } else if found == RadiusArc::Impossible {
                let chord = (ex.to_f64() - sx.to_f64()).hypot(ey.to_f64() - sy.to_f64());
                let message = format!(
                    "radius {} is shorter than half the chord {}: no arc of that radius joins \
                     the start and end points",
                    round6(length),
                    round6(chord / 2.0)
                );
                self.report(Rule::ArcRadiusTooShort, message, line, words[0].column);
            }
            return;
        }
        let (sx, sy, ex, ey) = (sx.to_f64(), sy.to_f64(), ex.to_f64(), ey.to_f64());
        let ci = ci.map_or(0.0, Dec::to_f64);
        let cj = cj.map_or(0.0, Dec::to_f64);
        // a third-axis word that leaves the axis where it was (CAM posts write `Z-4` in every
        // arc of a pass at Z-4) is no helix
        let stays = matches!(
            (before.axis(third), self.machine.state.axis(third)),
            (Some(a), Some(b)) if a == b
        );
        let helix = if v.has(third) && !stays {
            words
                .iter()
                .find(|w| w.letter == third)
                .map_or(0, |w| w.column)
        } else {
            0
        };
        let scale = if self.machine.state.units == Units::Inch {
            1.0 / 25.4
        } else {
            1.0
        };
        self.arc_geometry(
            line,
            words[0].column,
            (sx, sy),
            (ex, ey),
            (ci, cj),
            self.machine.state.motion == Some(2),
            scale,
            third,
            helix,
        );
    }

    /// LinuxCNC: a straight move or an arc in absolute coordinates ends at the point its
    /// axis words give: those axes are known again (`linuxcnc_unsettle`).
    pub(super) fn linuxcnc_settle(&mut self) {
        // the unsure axes the block names (most blocks: none, and nothing more is read)
        let named = self.values.given() & self.linuxcnc_point_unsure;
        if named == 0 {
            return;
        }
        let state = &self.machine.state;
        let plain = matches!(
            self.linuxcnc_motion,
            super::tooling::LinuxCncMotion::Known(Some(0 | 10 | 20 | 30))
        );
        if plain && !state.incremental && state.cycle.is_none() {
            self.linuxcnc_point_unsure &= !(named & !state.unknown);
        }
    }

    /// TG412: rs274ngc's refusal of an R arc that ends where it starts.
    fn report_same_end(&mut self, line: usize, column: usize) {
        let message = "Current point same as end point of arc (rs274ngc): an R arc's centre \
                       is found from its start and end, and they are one point"
            .into();
        self.report(Rule::LinuxCncRefuses, message, line, column);
    }

    /// What the file's first arc error adds where TG201 said the program mixes whole numbers
    /// without a point, which this control reads in least increments, with decimal points: a
    /// likely cause (audit 37: ten Grbl-style programs' `X67`, read as 0.067 on a FANUC, gave
    /// 530 TG403 errors that did not say why). Empty otherwise, and after the first.
    #[cold]
    fn arc_cause(&mut self) -> String {
        let Some(first) = self.first_implicit.as_ref().filter(|f| f.increments) else {
            return String::new();
        };
        if !self.mixed_reported || self.arc_cause_said {
            return String::new();
        }
        self.arc_cause_said = true;
        format!(
            "; the program mixes whole numbers without a decimal point with decimal ones \
             (TG201: {} on line {}, read as {}): if its post meant them as whole millimetres \
             or inches, the arc's points are not where it meant them",
            first.token, first.line, first.reading
        )
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn arc_geometry(
        &mut self,
        line: usize,
        column: usize,
        start: (f64, f64),
        end: (f64, f64),
        ij: (f64, f64),
        clockwise: bool,
        scale: f64,
        third: u8,
        helix: usize,
    ) {
        let (cx, cy) = self.centre(start, end, ij, clockwise, scale);
        let r1 = (start.0 - cx).hypot(start.1 - cy);
        let r2 = (end.0 - cx).hypot(end.1 - cy);
        // LinuxCNC's threshold: a radius under 0.00127 mm (0.00005 in) is no radius
        // (rs274's "Zero-radius arc"). The other families name no such threshold: their
        // alarm is for a centre on the point, so a radius of one least increment (FANUC's
        // 0.001 mm) is an arc there; only a float's noise counts as none.
        let zero = if self.config.family == Family::LinuxCnc {
            0.00127 * scale
        } else {
            1e-9
        };
        if r1 < zero || r2 < zero {
            let message = format!(
                "arc of zero radius (the centre is on the start or end point){}",
                self.arc_cause()
            );
            self.report(Rule::ArcZeroRadius, message, line, column);
            return;
        }
        let tolerance = self.arc_tolerance(r1, r2, scale);
        if (r1 - r2).abs() > tolerance {
            // "start radius {r1:.4} and end radius {r2:.4} differ by {:.4} (tolerance
            // {tolerance:.4})" and the cause, written without the formatter's exact float path
            // (said of most arcs of some programs: BrianHooper's 1001)
            let mut message = String::with_capacity(88);
            message.push_str("start radius ");
            push_fixed(&mut message, r1, 4);
            message.push_str(" and end radius ");
            push_fixed(&mut message, r2, 4);
            message.push_str(" differ by ");
            push_fixed(&mut message, (r1 - r2).abs(), 4);
            message.push_str(" (tolerance ");
            push_fixed(&mut message, tolerance, 4);
            message.push(')');
            message.push_str(&self.arc_cause());
            self.report(Rule::ArcRadiusMismatch, message, line, column);
        } else if self.config.ijk == Ijk::Quadrant
            && !in_one_quadrant(start, end, (cx, cy), clockwise)
        {
            let message = "arc crosses a quadrant boundary: this control limits a block to one \
                           quadrant (7.3); split it at the axis crossing"
                .into();
            self.report(Rule::ArcCrossesQuadrant, message, line, column);
        }
        if helix > 0 {
            // (said of every helical block of a 3D program: built without the formatter)
            let mut message = String::with_capacity(33);
            message.push_str("helical arc: ");
            message.push(char::from(third));
            message.push_str(" moves with the arc");
            self.report(Rule::HelicalArc, message, line, helix);
        }
    }

    /// LinuxCNC's rule, with the profile's figures: max(absolute, relative x radius), capped
    /// at 100 x absolute; the absolute part in inch is a tenth of the mm figure (0.0028284 in
    /// for 0.0282843 mm), as LinuxCNC has it.
    pub(super) fn arc_tolerance(&self, r1: f64, r2: f64, scale: f64) -> f64 {
        let absolute = if scale < 1.0 {
            self.config.arc_tolerance / 10.0
        } else {
            self.config.arc_tolerance * scale
        };
        (absolute.max(self.config.arc_tolerance_relative * r1.max(r2))).min(100.0 * absolute)
    }

    /// The arc centre in the plane, as the profile reads I J K (7.3): incremental from the
    /// start point, absolute, or sign-less for a quadrant-limited control -- then the signs
    /// that put the centre where the radii agree and the arc stays in one quadrant.
    /// (The two readings by a sum inlined where they are asked, once an arc; the quadrant
    /// search out of line.)
    #[inline]
    pub(super) fn centre(
        &self,
        start: (f64, f64),
        end: (f64, f64),
        ij: (f64, f64),
        clockwise: bool,
        scale: f64,
    ) -> (f64, f64) {
        let (sx, sy) = start;
        let (ci, cj) = ij;
        match self.config.ijk {
            Ijk::Absolute => (ci, cj),
            Ijk::Incremental => (sx + ci, sy + cj),
            Ijk::Quadrant => self.quadrant_centre(start, end, ij, clockwise, scale),
        }
    }

    /// [`Checker::centre`] of a quadrant-limited control: the signs of I J that fit best.
    #[inline(never)]
    fn quadrant_centre(
        &self,
        start: (f64, f64),
        end: (f64, f64),
        ij: (f64, f64),
        clockwise: bool,
        scale: f64,
    ) -> (f64, f64) {
        let (sx, sy) = start;
        let (ci, cj) = ij;
        let mut best = (sx, sy);
        let mut best_key: Option<(bool, bool, f64)> = None;
        for si in [1.0, -1.0] {
            for sj in [1.0, -1.0] {
                let c = (sx + si * ci.abs(), sy + sj * cj.abs());
                let r1 = (start.0 - c.0).hypot(start.1 - c.1);
                let r2 = (end.0 - c.0).hypot(end.1 - c.1);
                let miss = (r1 - r2).abs();
                let fits = miss <= self.arc_tolerance(r1, r2, scale);
                let key = (!fits, !in_one_quadrant(start, end, c, clockwise), miss);
                let better = match best_key {
                    None => true,
                    Some(k) => key.partial_cmp(&k) == Some(std::cmp::Ordering::Less),
                };
                if better {
                    best = c;
                    best_key = Some(key);
                }
            }
        }
        best
    }
}

pub(super) fn plane_axes(plane: i64) -> (u8, u8, u8) {
    match plane {
        18 => (b'Z', b'X', b'Y'),
        19 => (b'Y', b'Z', b'X'),
        _ => (b'X', b'Y', b'Z'),
    }
}

pub(super) fn centre_of(axis: u8) -> u8 {
    match axis {
        b'X' => b'I',
        b'Y' => b'J',
        _ => b'K',
    }
}

/// Whether the arc from `start` to `end` about `centre` stays within one quadrant: what a
/// quadrant-limited control can do in one block.
pub fn in_one_quadrant(
    start: (f64, f64),
    end: (f64, f64),
    centre: (f64, f64),
    clockwise: bool,
) -> bool {
    let eps = 1e-6;
    let a1 = (start.1 - centre.1)
        .atan2(start.0 - centre.0)
        .to_degrees()
        .rem_euclid(360.0);
    let a2 = (end.1 - centre.1)
        .atan2(end.0 - centre.0)
        .to_degrees()
        .rem_euclid(360.0);
    let sweep = (if clockwise { a1 - a2 } else { a2 - a1 }).rem_euclid(360.0);
    if sweep > 90.0 + eps {
        return false;
    }
    if clockwise {
        let top = ((a1 - eps) / 90.0).ceil() * 90.0;
        a1 - sweep >= top - 90.0 - eps
    } else {
        let bottom = ((a1 + eps) / 90.0).floor() * 90.0;
        a1 + sweep <= bottom + 90.0 + eps
    }
}

/// Half a lathe's diameter `d` (exact: 5 tenths of it), or its float half where the mantissa
/// or the scale would overflow.
#[inline(never)]
fn half_of(d: Dec) -> Dec {
    match d.mantissa.checked_mul(5) {
        Some(mantissa) if d.scale < 38 => Dec {
            mantissa,
            scale: d.scale + 1,
        },
        _ => Dec::parse(&(d.to_f64() / 2.0).to_string()).unwrap_or(d),
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{
        check, dialect, fanuc_lathe, findings, fired, iso_mill, of_family, okuma_lathe, program,
        run,
    };
    use super::super::{Config, ProfileFacts};
    use super::{in_one_quadrant, Ijk, Role};
    use crate::lex::Family;
    use crate::rules::Rule;

    fn at(config: Config, body: &str, rule: Rule) -> Vec<(usize, usize)> {
        fired(config, &program(body), rule)
    }

    /// LinuxCNC's convert_arc and arc_data_r: an R arc with no word of its plane's axes, or
    /// that ends where it starts (a known start, or zero increments), is refused; with
    /// compensation on the second is not judged (rs274's compensated arcs find the centre
    /// otherwise); another family is not judged.
    #[test]
    fn linuxcnc_refuses_an_r_arc_that_ends_where_it_starts() {
        let mut linuxcnc = of_family(Family::LinuxCnc);
        linuxcnc.pqr[2] = Role::Length;
        for (body, expected) in [
            ("G21 G17 G90\nG0 X0 Y0 Z0\nG2 X0 Y0 R5 F100", vec![(4, 1)]),
            ("G21 G17 G90\nG2 Z-1 R5 F100", vec![(3, 1)]),
            ("G21 G18 G90\nG2 Y1 R5 F100", vec![(3, 1)]),
            ("G21 G17 G91\nG2 X0 R5 F100", vec![(3, 1)]),
            ("G21 G17 G90\nG2 X1 Y0 R5 F100", vec![]),
            ("G21 G17 G90\nG0 X0 Y0 Z0\nG2 X1 Y0 R5 F100", vec![]),
            ("G21 G17 G90\nG0 X0 Y0 Z0\nG2 X0 Y0 I1 J0 F100", vec![]),
            (
                "G21 G17 G90\nG0 X0 Y0 Z0\nG41.1 D1\nG2 X0 Y0 R5 F100",
                vec![],
            ),
        ] {
            assert_eq!(
                at(linuxcnc.clone(), body, Rule::LinuxCncRefuses),
                expected,
                "{body}"
            );
        }
        let other = "G21 G17 G90\nG2 Z-1 R5 F100";
        assert_eq!(at(iso_mill(), other, Rule::LinuxCncRefuses), []);
        // a start moved by an amount the checker does not follow (a work offset, a return
        // home, a probe, a tool offset, G53) is not judged until an absolute move on the axis
        // names it again; an axis the arc does not name stays wherever it is
        let head = "G21 G17 G90\nG0 X1 Y0 Z0\n";
        for (body, expected) in [
            ("G55\nG2 X1 Y0 R5 F100", vec![]),
            ("G28\nG2 X1 Y0 R5 F100", vec![]),
            ("G38.2 X5 F10\nG2 X1 Y0 R5 F100", vec![]),
            // a tool length offset moves Z, and X in G18 (a lathe's table): not a G17 arc's
            ("G43 H1\nG2 X1 Y0 R5 F100", vec![(5, 1)]),
            ("G18\nG43 H1\nG2 X1 Z0 R5 F100", vec![]),
            ("G18\nG43 H1\nG2 Z0 R5 F100", vec![]),
            ("G49\nG2 X1 Y0 R5 F100", vec![(5, 1)]),
            // G92 sets the axes it names exactly, and leaves the others
            ("G92 X0\nG2 X0 Y0 R5 F100", vec![(5, 1)]),
            ("G28\nG92 X0\nG2 X0 Y0 R5 F100", vec![]),
            ("G28\nG92 X0 Y0\nG2 X0 Y0 R5 F100", vec![(6, 1)]),
            ("G92 X#1\nG2 X0 Y0 R5 F100", vec![]),
            ("G92.1\nG2 X1 Y0 R5 F100", vec![]),
            ("G53 G0 Z0\nG2 X1 Y0 R5 F100", vec![]),
            ("G55 G2 X1 Y0 R5 F100", vec![]),
            ("G55 G0 X1 Y0\nG2 X1 Y0 R5 F100", vec![(5, 1)]),
            ("G43 H1 G0 X1 Y0 Z1\nG2 X1 Y0 R5 F100", vec![(5, 1)]),
            ("G53 G0 X1 Y0\nG2 X1 Y0 R5 F100", vec![]),
            ("G28 X1 Y0\nG2 X1 Y0 R5 F100", vec![]),
            ("G10 L20 P1 X1 Y0\nG2 X1 Y0 R5 F100", vec![]),
            ("G55\nG0 X1 Y0\nG2 X1 Y0 R5 F100", vec![(6, 1)]),
            ("G55\nG0 X1\nG2 X1 Y0 R5 F100", vec![]),
            ("G55\nG0 X1\nG2 X1 R5 F100", vec![(6, 1)]),
            ("G55\nG91 G0 X0 Y0\nG90 G2 X1 Y0 R5 F100", vec![]),
            ("G55\nG91 G2 X0 Y0 R5 F100", vec![(5, 1)]),
            ("G28\nG0 X1 Y0\nG2 X1 Y0 R5 F100", vec![(6, 1)]),
        ] {
            let text = format!("{head}{body}");
            assert_eq!(
                at(linuxcnc.clone(), &text, Rule::LinuxCncRefuses),
                expected,
                "{body}"
            );
        }
    }

    /// LinuxCNC under G95: a feed move with no spindle speed is refused as rs274 refuses it
    /// (interp_convert.cc convert_straight and convert_arc), an S in force or set by the
    /// block is the speed; after a call the speed is unknown; another family is not judged.
    #[test]
    fn linuxcnc_feeds_per_revolution_only_with_a_spindle_speed() {
        let linuxcnc = of_family(Family::LinuxCnc);
        let body = "G21 G17 G90\nG0 X0 Y0 Z0\nG95 F0.1\nG1 X1\nG2 X3 Y0 I1 J0";
        assert_eq!(
            at(linuxcnc.clone(), body, Rule::LinuxCncRefuses),
            [(5, 4), (6, 4)]
        );
        let zero = "G21 G17 G90\nG0 X0 Y0 Z0\nS0 M3\nG95 G1 X1 F0.1";
        assert_eq!(at(linuxcnc.clone(), zero, Rule::LinuxCncRefuses), [(5, 8)]);
        for good in [
            "G21 G17 G90\nG0 X0 Y0 Z0\nS1000 M3\nG95 F0.1\nG1 X1",
            "G21 G17 G90\nG0 X0 Y0 Z0\nG95 F0.1 S500\nG1 X1",
            "G21 G17 G90\nG0 X0 Y0 Z0\no<s> call\nG95 F0.1\nG1 X1",
            // G0 and G94 need no speed
            "G21 G17 G90\nG0 X0 Y0 Z0\nG95 F0.1\nG0 X1\nG94 F100\nG1 X2",
        ] {
            assert_eq!(
                at(linuxcnc.clone(), good, Rule::LinuxCncRefuses),
                [],
                "{good}"
            );
        }
        assert_eq!(at(iso_mill(), body, Rule::LinuxCncRefuses), []);
    }

    /// A non-modal code that takes the block's axis words runs no arc, even with G02 in
    /// force: `G91 G28 Z0` after an arc is the everyday end of a Fanuc program (C3).
    #[test]
    fn a_non_modal_code_s_axis_words_are_no_arc() {
        let arc = "G00 X0 Y0 Z10.\nG01 Z-1. F100.\nG02 X10. Y0 I5. J0\n";
        let mill = of_family(Family::MacroB);
        for block in [
            "G91 G28 Z0",
            "G30 G91 Z0",
            "G53 Z0",
            "G92 X0 Y0",
            "G10 L2 P1 X0",
            "G52 X1.",
            "G31 X5.",
            "G27 X0",
            "G29 X0",
            "G60 X0",
            "G37 Z0",
            "G65 P9000 A1.",
            "G07.1 C57.3",
            "G30.1 Z0",
            "G92.1 X0",
        ] {
            let text = program(&format!("{arc}{block}"));
            assert_eq!(
                fired(mill.clone(), &text, Rule::ArcCentreMissing),
                [],
                "{block}"
            );
            assert_eq!(fired(mill.clone(), &text, Rule::NoFeedRate), [], "{block}");
        }
        // G09 (exact stop) and G45-G48 (tool offset) act on the motion in force: an arc
        for block in ["G09 X20.", "G45 X20."] {
            let text = program(&format!("{arc}{block}"));
            assert_eq!(fired(mill.clone(), &text, Rule::ArcCentreMissing), [(5, 1)]);
        }
        // a lathe: G50 X Z sets the coordinates, G70-G76 are cycles of their own
        let lathe_arc = "G18 G00 X0 Z10.\nG01 Z-1. F0.1\nG02 X10. Z-6. I0 K-5.\n";
        for block in [
            "G28 U0 W0",
            "G50 X100. Z50.",
            "G71 U2. R1.",
            "G71 P10 Q20 U0.5 W0.1 F0.2",
            "G76 X18. Z-20. P011060 Q100 R0.2 F1.5",
        ] {
            let text = program(&format!("{lathe_arc}{block}"));
            assert_eq!(
                fired(fanuc_lathe(), &text, Rule::ArcCentreMissing),
                [],
                "{block}"
            );
        }
        // rs274ngc: G10 G28 G30 G52 G92 take the axis words; G53 moves by G0 or G1 alone
        // and G30.1 takes none (rs274 -g: "R i j k words all missing for arc")
        let linuxcnc = of_family(Family::LinuxCnc);
        for block in ["G91 G28 Z0", "G30 Z0", "G92 X0", "G10 L2 P1 X0", "G52 X1"] {
            let text = program(&format!("{arc}{block}"));
            assert_eq!(
                fired(linuxcnc.clone(), &text, Rule::ArcCentreMissing),
                [],
                "{block}"
            );
            assert_eq!(
                fired(linuxcnc.clone(), &text, Rule::LinuxCncRefuses),
                [],
                "{block}"
            );
        }
        let g53 = program(&format!("{arc}G53 Z0"));
        assert_eq!(
            fired(linuxcnc.clone(), &g53, Rule::LinuxCncRefuses),
            [(5, 1)]
        );
        assert_eq!(fired(linuxcnc.clone(), &g53, Rule::ArcCentreMissing), []);
        let g53_rapid = program(&format!("{arc}G53 G0 Z0"));
        assert_eq!(
            fired(linuxcnc.clone(), &g53_rapid, Rule::LinuxCncRefuses),
            []
        );
        let g30_1 = program(&format!("{arc}G30.1 Z0"));
        assert_eq!(fired(linuxcnc, &g30_1, Rule::ArcCentreMissing), [(5, 1)]);
        // SINUMERIK's programmable offset and working area limit, ISO's preset
        for (family, block) in [
            (Family::Sinumerik, "G58 X1."),
            (Family::Sinumerik, "G26 X100. Y100."),
            (Family::Iso, "G92 X0 Y0"),
        ] {
            let text = program(&format!("{arc}{block}"));
            assert_eq!(
                fired(of_family(family), &text, Rule::ArcCentreMissing),
                [],
                "{block}"
            );
        }
    }

    /// Review 51, F19: the radius TG404 names is the family's -- a SINUMERIK's R word is a
    /// parameter (`R1=2`), its arc's radius CR= (or its opening angle AR=); elsewhere R.
    #[test]
    fn an_arc_without_its_centre_names_the_family_radius() {
        for (family, block, radius) in [
            (Family::Sinumerik, "G2 X10 Y0 R5", "(or CR=/AR=)"),
            (Family::Sinumerik, "G2 X10 Y0 R1=2", "(or CR=/AR=)"),
            (Family::MacroB, "G2 X10. Y0", "(or R)"),
        ] {
            let text = program(&format!("G17 G90 G0 X0 Y0\nG1 X0 Y0 F100\n{block}"));
            let found = findings(of_family(family), &text, Rule::ArcCentreMissing);
            assert_eq!(found.len(), 1, "{block}");
            assert_eq!((found[0].line, found[0].column), (4, 1), "{block}");
            assert_eq!(
                found[0].message,
                format!("arc without I J {radius}"),
                "{block}"
            );
        }
    }

    /// Where such a block leaves the position: G92 and a lathe's G50 set it, G27 and G60
    /// position there, G10 (an offset that may be the one in force) and G28/G30/G53/G31/G52
    /// leave it unknown, G65 and a lathe's cycle (which ends at its start point) keep it.
    #[test]
    fn a_non_modal_code_s_position() {
        let x_after = |config: Config, block: &str| {
            let text = format!("G00 X3. Y4. Z5.\n{block}\n");
            let (checker, _) = run(config.clone(), &dialect(config.family), &text);
            let s = &checker.machine.state;
            (s.axis(b'X').map(|d| d.to_string()), s.is_unknown(b'X'))
        };
        let mill = of_family(Family::MacroB);
        let known = |x: &str| (Some(x.to_string()), false);
        let unknown = (None, true);
        assert_eq!(x_after(mill.clone(), "G91 G92 X1."), known("1"));
        assert_eq!(x_after(mill.clone(), "G91 G27 X1."), known("4"));
        assert_eq!(x_after(mill.clone(), "G60 X7."), known("7"));
        for block in ["G28 X0", "G53 X0", "G31 X9. F100.", "G52 X1.", "G30 G91 X0"] {
            assert_eq!(x_after(mill.clone(), block), unknown, "{block}");
        }
        // G10 L2 may set the offsets of the coordinate system in force: the named axes are
        // then no longer known in program coordinates
        for block in ["G10 L2 P1 X9.", "G10 L2 P1 G91 X9."] {
            assert_eq!(x_after(mill.clone(), block), unknown, "{block}");
        }
        assert_eq!(x_after(fanuc_lathe(), "G50 X100. Z50."), known("100"));
        assert_eq!(
            x_after(fanuc_lathe(), "G74 X20. Z-5. P1000 Q2000 F0.1"),
            known("3")
        );
        // (a lathe's G92 is its thread cutting cycle, no setting: back at its start point,
        // FANUC 0i-TF, "Thread cutting cycle G92"; issue 32, thr42)
        assert_eq!(x_after(fanuc_lathe(), "G92 X20. Z-5. F1.5"), known("3"));
    }

    #[test]
    fn a_feed_move_at_f0_is_refused_with_its_family_s_alarm() {
        for (family, alarm) in [
            (Family::MacroB, "PS0011"),
            (Family::Sinumerik, "14800"),
            (Family::LinuxCnc, "Cannot do g1 with zero feed rate"),
            (Family::Iso, "ISO 6983-1 clause 7"),
        ] {
            let found = findings(
                of_family(family),
                &program("G00 X0 Y0\nG01 X1. F0\nY1."),
                Rule::NoFeedRate,
            );
            let at: Vec<_> = found.iter().map(|f| (f.line, f.column)).collect();
            assert_eq!(at, [(3, 5), (4, 1)], "{family:?}");
            assert!(found[0].message.contains(alarm), "{}", found[0].message);
        }
        // held for no subprogram: the F0 is the part's own, not its caller's
        let sub = "%\nO1002\nG91 G01 X1. F0\nM99\n%\n";
        assert_eq!(
            fired(of_family(Family::MacroB), sub, Rule::NoFeedRate),
            [(3, 9)]
        );
        // an arc, in rs274's words
        let arc = findings(
            of_family(Family::LinuxCnc),
            &program("G00 X0 Y0\nG02 X2. I1. F0"),
            Rule::NoFeedRate,
        );
        assert!(
            arc[0].message.contains("Cannot make arc"),
            "{}",
            arc[0].message
        );
        // a fixed cycle's holes are fed at the F in force
        let cycle = "G00 X0 Y0 Z10.\nG81 X1. Y1. Z-5. R2. F0\nX2.\nG80";
        assert_eq!(
            fired(of_family(Family::MacroB), &program(cycle), Rule::NoFeedRate),
            [(3, 5), (4, 1)]
        );
        // quiet: rapid moves under F0, a feed move once F is set again, no move at all
        let quiet = "G01 F0\nG00 X1.\nG01 X2. F100.\nG81 X1. Y1. Z-5. R2.\nG80";
        assert_eq!(
            fired(of_family(Family::MacroB), &program(quiet), Rule::NoFeedRate),
            []
        );
    }

    #[test]
    fn a_subprogram_starts_under_its_caller_s_feed() {
        let macro_b = || of_family(Family::MacroB);
        // a Fanuc or Haas subprogram ends with M99: its G01 runs at its caller's feed
        let sub = "%\nO1002\nG91 G01 X1.\nY1.\nM99\n%\n";
        assert_eq!(fired(macro_b(), sub, Rule::NoFeedRate), []);
        // a main program alarms on its first feed move without F: said at its M30, or at
        // the end of a file that has no end
        let main = "%\nO1000\nG91 G01 X1.\nY1.\nM30\n%\n";
        assert_eq!(fired(macro_b(), main, Rule::NoFeedRate), [(3, 9), (4, 1)]);
        assert_eq!(
            fired(macro_b(), "%\nO1000\nG01 X1.\n", Rule::NoFeedRate),
            [(3, 5)]
        );
        // a main program, then its subprogram after M30: each part as what it is
        let both = "%\nO1000\nG01 X1.\nM30\nO2000\nG01 X2.\nM99\n%\n";
        assert_eq!(fired(macro_b(), both, Rule::NoFeedRate), [(3, 5)]);
        // SINUMERIK: M17 or RET; Okuma: RTS
        for (family, end) in [
            (Family::Sinumerik, "M17"),
            (Family::Sinumerik, "RET"),
            // RET with the caller's block to return to (Job Planning, "Subprogram technique")
            (Family::Sinumerik, "RET(\"L1\")"),
            (Family::Sinumerik, "ret(N100,,2)"),
            (Family::Okuma, "RTS"),
        ] {
            let sub = format!("G1 X1\nY2\n{end}\n");
            assert_eq!(
                fired(of_family(family), &sub, Rule::NoFeedRate),
                [],
                "{end}"
            );
            let main = "G1 X1\nY2\nM30\n";
            assert_eq!(
                fired(of_family(family), main, Rule::NoFeedRate),
                [(1, 4), (2, 1)],
                "{end}"
            );
        }
        // ISO 6983-1 has no return: said where it is
        assert_eq!(at(iso_mill(), "G01 X1.", Rule::NoFeedRate), [(2, 5)]);
    }

    #[test]
    fn a_program_starts_where_its_caller_left_the_machine_first_in_its_file_or_not() {
        // a FANUC, Haas or Okuma subprogram in G91 draws its arc from where the caller left
        // the tool: the same findings whether it is alone or after another program (no
        // geometry rule on a start nobody knows; an arc with no earlier position was an
        // error alone and silent second)
        use crate::rules::Severity;
        let errors = |family, text: &str| -> Vec<(usize, Rule)> {
            check(of_family(family), text)
                .into_iter()
                .filter(|f| {
                    f.rule.severity() == Severity::Error
                        && f.rule.family() == crate::rules::Family::Motion
                })
                .map(|f| (f.line, f.rule))
                .collect()
        };
        let main = "%\nO1000\nG21 G90 G17\nG00 X100. Y100. Z5.\nG01 X50. F100.\nM30\n";
        for (family, end) in [
            (Family::MacroB, "M99"),
            (Family::Okuma, "RTS"),
            (Family::MacroB, "M30"),
        ] {
            for body in [
                "G91 G02 X10. Y0 I5. J0 F100.\nG90 G01 X0 Y0",
                "G21\nG01 X10. F100.\nG02 X20. Y0 I5. J0",
                "G02 X20. Y0 I5. J0 F100.",
            ] {
                let alone = format!("%\nO2000\n{body}\n{end}\n%\n");
                let second = format!("{main}O2000\n{body}\n{end}\n%\n");
                assert_eq!(errors(family, &alone), [], "{body} {end}");
                assert_eq!(errors(family, &second), [], "{body} {end}");
            }
        }
        // the radius is still checked once the program has given the start
        let known = "G00 X0 Y0\nG02 X10. Y0 I3. J0 F100.";
        assert_eq!(
            fired(
                of_family(Family::MacroB),
                &format!("{known}\nM30\n"),
                Rule::ArcRadiusMismatch
            )
            .len(),
            1
        );
    }

    #[test]
    fn after_a_return_on_a_line_of_its_own_the_position_is_unknown() {
        // from X0 Y0 the arc's radii would be 3 and 7 (TG403); after RET or RTS what follows
        // starts where some caller left the machine
        for (family, end) in [
            (Family::Sinumerik, "RET"),
            (Family::Sinumerik, "RET(\"L1\")"),
            (Family::Okuma, "RTS"),
        ] {
            let text = format!("G1 X0 Y0 F100\n{end}\nG2 X10 Y0 I3 J0\nM30\n");
            assert_eq!(
                fired(of_family(family), &text, Rule::ArcRadiusMismatch),
                [],
                "{end}"
            );
            let kept = "G1 X0 Y0 F100\nG2 X10 Y0 I3 J0\nM30\n";
            assert_eq!(
                fired(of_family(family), kept, Rule::ArcRadiusMismatch).len(),
                1,
                "{end}"
            );
        }
    }

    #[test]
    fn a_block_returns_or_ends_only_by_an_m_word_whose_value_is_read() {
        // M99 and M30 among other words forget the position; an M word whose value is not
        // read (M#1) and a block with no M word do not
        let arc = |family, end: &str| {
            let text = format!("G1 X0 Y0 F100\n{end}\nG2 X10 Y0 I3 J0\nM30\n");
            fired(of_family(family), &text, Rule::ArcRadiusMismatch).len()
        };
        for (family, end, found) in [
            (Family::MacroB, "N5 M99", 0),
            (Family::MacroB, "G4 P1. M99", 0),
            (Family::MacroB, "M30", 0),
            (Family::MacroB, "M#1", 1),
            (Family::MacroB, "M08", 1),
            (Family::MacroB, "G4 P1.", 1),
            (Family::Sinumerik, "M17", 0),
            (Family::Sinumerik, "M2", 0),
            (Family::Sinumerik, "M17.5", 1),
        ] {
            assert_eq!(arc(family, end), found, "{family:?} {end}");
        }
    }

    #[test]
    fn a_part_holds_its_tg401_findings_up_to_a_bound() {
        // memory stays flat: past HELD_FEEDS the part's findings are said as they come, as
        // for a main program, even if the part turns out to return
        let moves = super::HELD_FEEDS + 5;
        // (X within its format: a word the format refuses moves to no known point)
        let body: String = (0..moves).map(|i| format!("G01 X{}\n", i % 1000)).collect();
        let sub = format!("%\nO1002\n{body}M99\n%\n");
        let found = fired(of_family(Family::MacroB), &sub, Rule::NoFeedRate);
        assert_eq!(found.len(), moves);
        assert_eq!(found[0], (3, 5));
        assert_eq!(found[moves - 1].0, moves + 2);
    }

    #[test]
    fn a_sinumerik_spf_starts_under_its_caller_s_feed_whatever_its_end() {
        use super::super::testing::dialect;
        use super::super::Checker;
        use crate::rules::Selection;
        use std::sync::Arc;
        let run = |name: &str| {
            let config = Arc::new(of_family(Family::Sinumerik));
            let mut checker = Checker::new(config, Selection::all(), false);
            checker.file_name(name);
            let mut tokens = Vec::new();
            let d = dialect(Family::Sinumerik);
            let mut found = Vec::new();
            for (i, line) in ["G1 X1", "Y2", "M30"].iter().enumerate() {
                checker.check_line(line.as_bytes(), i + 1, &d, &mut tokens);
                found.extend(checker.take());
            }
            checker.finish();
            found.extend(checker.take());
            found
                .iter()
                .filter(|f| f.rule == Rule::NoFeedRate)
                .map(|f| f.line)
                .collect::<Vec<_>>()
        };
        assert_eq!(run("SPF/SHAPE/GEAR_60.SPF"), Vec::<usize>::new());
        // PROC opens a subprogram whatever the file's name
        let proc = "PROC SHAPE\nG1 X1\nM30\n";
        assert_eq!(
            fired(of_family(Family::Sinumerik), proc, Rule::NoFeedRate),
            []
        );
        assert_eq!(run("PART1.MPF"), [1, 2]);
    }

    /// From X0 Y0 at the feed 100.
    fn from_origin(body: &str) -> String {
        format!("G01 X0 Y0 F100.\n{body}")
    }

    #[test]
    fn axis_words_need_a_motion_mode() {
        // a reset state with no motion mode, as LinuxCNC's, where G80 clears it too
        let mut none = of_family(Family::LinuxCnc);
        none.modal.reset = vec![17, 40, 71, 80, 90, 94];
        none.modal.g80_clears_motion = true;
        assert_eq!(at(none.clone(), "X1. F100.", Rule::NoMotionMode), [(2, 1)]);
        assert_eq!(at(none.clone(), "G01 X1. F100.", Rule::NoMotionMode), []);
        let after_g80 = "G01 X1. F100.\nG80\nY2.";
        assert_eq!(at(none.clone(), after_g80, Rule::NoMotionMode), [(4, 1)]);
        // a code that takes axis words itself is no move
        assert_eq!(at(none, "G92 X0 Y0", Rule::NoMotionMode), []);
        assert_eq!(at(iso_mill(), "X1. F100.", Rule::NoMotionMode), []);
    }

    #[test]
    fn a_feed_move_needs_a_feed_rate() {
        assert_eq!(at(iso_mill(), "G01 X1.", Rule::NoFeedRate), [(2, 5)]);
        assert_eq!(at(iso_mill(), "G01 X1. F100.\nY2.", Rule::NoFeedRate), []);
        assert_eq!(at(iso_mill(), "G00 X1.", Rule::NoFeedRate), []);
        assert_eq!(at(iso_mill(), "G01 G92 X1.", Rule::NoFeedRate), []);
        let inverse = "G93 G01 X1. F10.\nY2.";
        assert_eq!(
            at(iso_mill(), inverse, Rule::InverseTimeWithoutFeed),
            [(3, 1)]
        );
        assert_eq!(
            at(
                iso_mill(),
                "G93 G01 X1. F10.\nY2. F20.",
                Rule::InverseTimeWithoutFeed
            ),
            []
        );
    }

    #[test]
    fn a_parabola_has_its_tangent_point_or_its_second_block() {
        let open = from_origin("G06 X1. Y1.\nG00 X0");
        assert_eq!(at(iso_mill(), &open, Rule::ParabolaIncomplete), [(3, 1)]);
        let two = from_origin("G06 X1. Y1.\nX2. Y4.");
        assert_eq!(at(iso_mill(), &two, Rule::ParabolaIncomplete), []);
        let tangent = from_origin("G06 X1. Y1. I1. J0");
        assert_eq!(at(iso_mill(), &tangent, Rule::ParabolaIncomplete), []);
    }

    #[test]
    fn an_arc_has_its_centre_and_start() {
        let good = from_origin("G02 X10. Y0 I5. J1.");
        assert_eq!(at(iso_mill(), &good, Rule::ArcCentreMissing), []);
        assert_eq!(at(iso_mill(), &good, Rule::ArcRadiusMismatch), []);
        let missing = from_origin("G02 X10. Y0");
        assert_eq!(at(iso_mill(), &missing, Rule::ArcCentreMissing), [(3, 1)]);
        let outside = from_origin("G02 X10. Y0 I5. K1.");
        assert_eq!(at(iso_mill(), &outside, Rule::ArcCentreMissing), [(3, 17)]);
        let no_start = "G02 X10. Y0 I5. J0 F100.";
        assert_eq!(at(iso_mill(), no_start, Rule::ArcWithoutStart), [(2, 1)]);
        assert_eq!(at(iso_mill(), &good, Rule::ArcWithoutStart), []);
        // a reference return in G2 mode takes the axis words: no arc (rs274 runs
        // `G28 G91 Z0.` so; the shops' QUAD-ABCD program has it)
        // (ISO 6983-1 has no G28: a Fanuc's and LinuxCNC's)
        let returned = from_origin("G02 X10. Y0 I5. J0\nG28 G91 Z0.\nG90 G00 X0");
        let again = from_origin("G02 X10. Y0 I5. J0\nG28 G91 Z0.\nG90 X0");
        for family in [Family::MacroB, Family::LinuxCnc] {
            let config = || of_family(family);
            assert_eq!(at(config(), &returned, Rule::ArcCentreMissing), []);
            assert_eq!(at(config(), &again, Rule::ArcCentreMissing), [(5, 1)]);
        }
        // LinuxCNC's G43.1 Z and G38.2 probe in G2 mode are no arc (rs274 runs both)
        for code in ["G43.1 Z1.", "G38.2 Z-5. F10"] {
            let text = from_origin(&format!("G02 X10. Y0 I5. J0\n{code}\nG00 X0"));
            assert_eq!(
                at(of_family(Family::LinuxCnc), &text, Rule::ArcCentreMissing),
                [],
                "{code}"
            );
        }
        // G10 L20 may shift the coordinate system in force: no radius measured from before
        let shifted = from_origin("G10 L20 P1 X5.\nG02 X10. Y0 R2.");
        assert_eq!(
            at(
                of_family(Family::LinuxCnc),
                &shifted,
                Rule::ArcRadiusMismatch
            ),
            []
        );
    }

    /// A SINUMERIK's R is a parameter (its radius is CR=): `R1=2` alone in a block under G2
    /// moves nothing and is no arc without a centre (audit 50, B8); an arc with neither
    /// centre nor CR= still is.
    #[test]
    fn a_sinumerik_r_parameter_is_no_arc_radius() {
        let sinumerik = || of_family(Family::Sinumerik);
        for set in ["R1=2", "R0=1 R1=R0*2", "R1=2 R2=3"] {
            for arc in ["G2 X20 Y0 CR=10 F100", "G2 X20 Y0 I10 J0 F100"] {
                let text = format!("G17 G90 G0 X0 Y0\n{arc}\n{set}\nM30\n");
                assert_eq!(
                    fired(sinumerik(), &text, Rule::ArcCentreMissing),
                    [],
                    "{arc} {set}"
                );
            }
        }
        let text = "G17 G90 G0 X0 Y0\nG2 X20 Y0 CR=10 F100\nR1=2\nX0 Y0\nM30\n";
        assert_eq!(fired(sinumerik(), text, Rule::ArcCentreMissing), [(4, 1)]);
    }

    /// A SINUMERIK arc's `CR=` of a parameter, a variable or an expression gives the radius
    /// with a value the checker does not follow (held26: NadjImre's `G3 X=XC Z=ZC CR=thr1`,
    /// a GUD): the arc is not judged, as a FANUC's `R#500` is not (review 54, F6); a number
    /// still is, and an arc with neither centre nor CR= still has none.
    #[test]
    fn a_sinumerik_radius_of_an_expression_is_given_not_known() {
        let sinumerik = || of_family(Family::Sinumerik);
        for cr in [
            "CR=R1",
            "CR=THR1",
            "CR=$P_F",
            "CR=THR[1]",
            "CR=A+1",
            "CR=(A+1)",
            "CR=R1*2",
        ] {
            let text = format!("DEF REAL A\nR1=10\nG17 G90 G1 X0 Y0 F100\nG2 X20 Y0 {cr}\nM30\n");
            for rule in [Rule::ArcCentreMissing, Rule::ArcRadiusTooShort] {
                assert_eq!(fired(sinumerik(), &text, rule), [], "{cr} {rule:?}");
            }
        }
        let small = "G17 G90 G1 X0 Y0 F100\nG2 X20 Y0 CR=5\nM30\n";
        assert_eq!(fired(sinumerik(), small, Rule::ArcRadiusTooShort), [(2, 1)]);
        let none = "G17 G90 G1 X0 Y0 F100\nG2 X20 Y0\nM30\n";
        assert_eq!(fired(sinumerik(), none, Rule::ArcCentreMissing), [(2, 1)]);
    }

    #[test]
    fn an_arc_s_radii() {
        let mismatch = from_origin("G02 X10. Y0 I4. J0");
        assert_eq!(at(iso_mill(), &mismatch, Rule::ArcRadiusMismatch), [(3, 1)]);
        let zero = from_origin("G02 X10. Y0 I0 J0");
        assert_eq!(at(iso_mill(), &zero, Rule::ArcZeroRadius), [(3, 1)]);
        let helix = from_origin("G02 X10. Y0 Z-1. I5. J0");
        assert_eq!(at(iso_mill(), &helix, Rule::HelicalArc), [(3, 13)]);
        let flat = from_origin("G02 X10. Y0 I5. J0");
        assert_eq!(at(iso_mill(), &flat, Rule::HelicalArc), []);
        // Z written at the height the arc starts at: no helix (a CAM pass at Z-1.)
        let level = "G00 X0 Y0\nG01 Z-1. F100.\nG02 X10. Y0 Z-1. I5. J0";
        assert_eq!(at(iso_mill(), level, Rule::HelicalArc), []);
        // R as a length: no arc of a radius under half the chord
        let by_radius = Config {
            pqr: [Role::Parameter, Role::Parameter, Role::Length],
            ..iso_mill()
        };
        let short = from_origin("G02 X10. Y0 R2.");
        assert_eq!(
            at(by_radius.clone(), &short, Rule::ArcRadiusTooShort),
            [(3, 1)]
        );
        let long = from_origin("G02 X10. Y0 R5.");
        assert_eq!(at(by_radius.clone(), &long, Rule::ArcRadiusTooShort), []);
        let r0 = from_origin("G02 X10. Y0 R0");
        assert_eq!(at(by_radius, &r0, Rule::ArcZeroRadius), [(3, 1)]);
    }

    #[test]
    fn a_radius_of_one_least_increment_is_an_arc_except_on_linuxcnc() {
        // held27, cifo-cnc 216.nc: the centre 0.001 mm from both points, read in thousandths
        let tiny = "G0 X0.017 Y-0.008\nG1 F100.\nG3 X0.015 I-0.001 J0\nM30";
        for family in [
            Family::MacroB,
            Family::Sinumerik,
            Family::Okuma,
            Family::Iso,
        ] {
            assert_eq!(
                fired(of_family(family), tiny, Rule::ArcZeroRadius),
                [],
                "{family:?}"
            );
        }
        // rs274 refuses it: "Zero-radius arc" under 0.00127 mm (0.00005 in)
        assert_eq!(
            fired(of_family(Family::LinuxCnc), tiny, Rule::ArcZeroRadius),
            [(3, 1)]
        );
        // the centre on the start point is no arc on any control
        let on_point = "G0 X0.017 Y-0.008\nG1 F100.\nG3 X0.015 I0 J0\nM30";
        for family in [Family::MacroB, Family::Sinumerik, Family::LinuxCnc] {
            assert_eq!(
                fired(of_family(family), on_point, Rule::ArcZeroRadius),
                [(3, 1)],
                "{family:?}"
            );
        }
    }

    #[test]
    fn a_quadrant_limited_control_turns_one_quadrant_a_block() {
        let quadrant = Config {
            facts: ProfileFacts {
                ijk: Ijk::Quadrant,
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let one = "G01 X5. Y0 F100.\nG03 X0 Y5. I5. J0";
        assert_eq!(at(quadrant.clone(), one, Rule::ArcCrossesQuadrant), []);
        let half = "G01 X5. Y0 F100.\nG03 X-5. Y0 I5. J0";
        assert_eq!(at(quadrant, half, Rule::ArcCrossesQuadrant), [(3, 1)]);
        assert_eq!(at(iso_mill(), half, Rule::ArcCrossesQuadrant), []);
        assert!(in_one_quadrant((5.0, 0.0), (0.0, 5.0), (0.0, 0.0), false));
        assert!(!in_one_quadrant((5.0, 0.0), (0.0, 5.0), (0.0, 0.0), true));
    }

    #[test]
    fn an_okuma_lathe_gives_an_arc_its_radius_by_l() {
        // from X20. (a diameter: 10 from the axis) Z0: to X26. Z-3. is a chord of 4.24, half
        // of it 2.12 (5238-E, P-26: G02/G03 X Z L, "L: Sets the radius of the arc")
        let from = |body: &str| format!("G01 X20. Z0 F.2\n{body}");
        let fits = from("G03 X26. Z-3. L3.\nG01 Z-10.\nG02 X30. Z-12. L2.\nX34. Z-14. L2.");
        for rule in [
            Rule::ArcCentreMissing,
            Rule::ArcRadiusTooShort,
            Rule::ArcZeroRadius,
        ] {
            assert_eq!(at(okuma_lathe(), &fits, rule), [], "{rule:?}");
        }
        let short = from("G03 X26. Z-3. L2.");
        assert_eq!(at(okuma_lathe(), &short, Rule::ArcRadiusTooShort), [(3, 1)]);
        let zero = from("G03 X26. Z-3. L0");
        let found = findings(okuma_lathe(), &program(&zero), Rule::ArcZeroRadius);
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].message, "arc of zero radius (L0)");
        // neither I K nor L; R is no radius on this control, its drilling cycle's infeed
        for body in ["G03 X26. Z-3.", "G03 X26. Z-3. R3."] {
            let found = findings(okuma_lathe(), &program(&from(body)), Rule::ArcCentreMissing);
            assert_eq!(found.len(), 1, "{body}");
            assert_eq!(found[0].message, "arc without I K (or L)");
            assert_eq!((found[0].line, found[0].column), (3, 1));
        }
        // I K as before; and a machining centre's R, where L is no radius
        let centre = from("G03 X26. Z-3. I3. K0");
        assert_eq!(at(okuma_lathe(), &centre, Rule::ArcCentreMissing), []);
        let mill = Config {
            pqr: [Role::Other, Role::Length, Role::Length],
            ..of_family(Family::Okuma)
        };
        let by_l = from_origin("G02 X10. Y0 L5.");
        assert_eq!(at(mill.clone(), &by_l, Rule::ArcCentreMissing), [(3, 1)]);
        let by_r = from_origin("G02 X10. Y0 R5.");
        assert_eq!(at(mill, &by_r, Rule::ArcCentreMissing), []);
    }

    /// The block's own move where its M02 or M30 resets the state after its words: a
    /// `G00 X1 M02` after a `G01` is a rapid, on a profile whose reset motion is G01 (iso-mill,
    /// ISO 6983-1 clause 14) as on any (audit 50's afixa50: a false TG401).
    #[test]
    fn an_end_block_s_move_is_judged_before_its_reset() {
        let no_feed = |body: &str| fired(iso_mill(), &format!("%\n{body}\n%\n"), Rule::NoFeedRate);
        assert_eq!(no_feed("N1 G01 X0 F100\nN2 G00 X1 M02"), []);
        assert_eq!(no_feed("N1 G01 X0 F100\nN2 X2 M30"), []);
        // the block's own feed move with no feed in force is still TG401
        assert_eq!(no_feed("N1 G00 X0\nN2 G01 X1 M02"), [(3, 8)]);
    }
}
