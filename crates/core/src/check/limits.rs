//! The machine's limits (rules TG601-TG604): travel, as machine positions where the
//! profile's work offsets and the one in force are known, and as the span of the program's
//! positions; the feed, the spindle speed and the tool numbers.

use super::{round6, Before, BlockView, Checker, Config, Facts, Finding, Span};
use crate::decimal::Dec;
use crate::lex::Family;
use crate::modal::{axis_index, bit, AxesTaken, Units, AXES, CYCLE_RAN, CYCLE_UNSURE};
use crate::rules::Rule;
use crate::statement::{self, Effect, Kind};

/// The profile's travel of each axis A-Z as floating-point numbers, as [`Config::travel`]
/// gives it (its first entry of a letter), and of each axis of [`AXES`] by its place there,
/// found once for the checker: every move asks it of each axis it moves.
#[derive(Clone)]
pub(super) struct Travel([Option<(f64, f64)>; 26], [Option<(f64, f64)>; 9], u32);

impl Travel {
    pub(super) fn new(config: &Config) -> Travel {
        let letters: [Option<(f64, f64)>; 26] = std::array::from_fn(|i| {
            let letter = b'A' + i as u8;
            config
                .travel
                .iter()
                .find(|(a, _, _)| *a == letter)
                .map(|&(_, l, h)| (l.to_f64(), h.to_f64()))
        });
        let places: [Option<(f64, f64)>; 9] =
            std::array::from_fn(|i| letters[usize::from(AXES[i] - b'A')]);
        let given = (0..9)
            .filter(|&i| places[i].is_some())
            .fold(0, |m, i| m | 1 << i);
        Travel(letters, places, given)
    }

    /// The places in [`AXES`] of the axes with a travel, a bit each.
    #[inline(always)]
    fn places(&self) -> u32 {
        self.2
    }

    /// [`Travel::of`] the axis at place `i` of [`AXES`].
    #[inline(always)]
    pub(super) fn of_place(&self, i: usize) -> Option<(f64, f64)> {
        self.1[i]
    }

    /// The travel of `axis` (low, high), if the profile gives one.
    fn of(&self, axis: u8) -> Option<(f64, f64)> {
        match axis {
            b'A'..=b'Z' => self.0[usize::from(axis - b'A')],
            _ => None,
        }
    }
}

/// The frames in force (TG601's spans under them, [`Checker::turn_frames`]).
#[derive(Debug, Clone, Default)]
pub(super) struct Frames {
    /// A bit each: polar G16 (1), scaling G51 (2), rotation G68 (4), Haas G268 (8), (16 no
    /// longer used), mirror G51.1 or a Haas's G101 (32). A cancel (G15, G50, G69, G269,
    /// G50.1, G100) ends its own frame only, G50.1 and G100 the mirror of the axes they name
    /// ([`Checker::mirror_off`]). An Okuma mill's codes set the same bits ([`frame_bits`]).
    on: u8,
    /// The one rotation or scaling in force whose words say exactly what it does: the
    /// positions under it are taken back to the coordinates before it.
    map: Option<Map>,
    /// For each frame bit, the axes (bit `i` for `AXES[i]`) whose positions under it are
    /// left out of the spans: where a frame puts them is not known here.
    hidden: [u16; 6],
    /// For each frame bit, whether an axis it hides moved under it: at its cancel those axes
    /// are where the frame put them, not known here (none moved: where they stood before).
    moved: [bool; 6],
    /// The spans from before a mirror image, each axis's taken back at the cancel of its
    /// mirror: the positions under it stand apart (a mirror keeps the size of a span, not its
    /// place). Held for the axes of `saving` only.
    saved: [Option<Span>; 9],
    /// The axes (bit `i` for `AXES[i]`) whose span from before a mirror not known exactly is
    /// in `saved`: those the mirrors in force mirror, and no other (review 24, finding 1: a
    /// second G51.1 of X dropped Y's span, given back at Y's cancel, and passed an
    /// over-travel of Y).
    saving: u16,
    /// The axes (bit `i` for `AXES[i]`) a mirror image G51.1 not known exactly here
    /// mirrors: its positions stand apart until a G50.1 has ended every one of them.
    apart: u16,
    /// A G52 or G92 with axis words has shifted the coordinates in this file: a Haas G101,
    /// which mirrors about the work coordinate zero point, then mirrors about a point the
    /// checker does not know in the program's coordinates ([`Checker::exact_mirror`]).
    shifted: bool,
    /// The mirror image turning on in the block in hand is a Haas's G101 (not a G51.1).
    haas_mirror: bool,
    /// The mirrored axes whose mirror a cancel with an axis word not known here (`G100 X#1`,
    /// `G50.1 X#1`) may or may not have ended: their positions are not compared with the
    /// travel until a cancel names the axis plainly, or names none and ends them all
    /// ([`Checker::mirror_off`]; `send --restart-at` refuses there too).
    doubt: u16,
    /// Whether the note of a frame not applied (TG140) was said (once per file).
    noted: bool,
    /// Whether the block in hand has a code that may turn a frame or shift the coordinates
    /// ([`Checker::frame_codes`]), decided once a block by [`Checker::cancel_frames`].
    codes: bool,
}

impl Frames {
    fn hidden(&self) -> u16 {
        self.hidden.iter().fold(self.doubt, |all, &h| all | h)
    }
}

/// X, Y and Z (bits 0-2 of [`Frames::hidden`]).
const XYZ: u16 = 0b111;

/// Among a finding's [`Finding::pending_on`]: a position of the program's own after calls
/// of programs not read there ([`Checker::work_unread_reselected`]): dropped at the file's
/// end where one of them is not in the file or lost the offsets, not only where one writes
/// that axis.
pub(super) const PENDING_OWN: i64 = -1;

/// Among a finding's [`Finding::pending_on`]: a position of a program written after its
/// calls judged under a call's offset whose distance mode is the one the program leaves
/// ([`Checker::work_call_tentative_end`]). Between [`PENDING_CALLS_WRITTEN`]'s marks and
/// [`super::leaves::PENDING_LEAVES`]'s.
pub(super) const PENDING_MODE_SELF: i64 = -(1 << 44);

/// Among a finding's [`Finding::pending_on`]: a position of a program written after its
/// calls judged under the offset of a call after the first ([`CallWork::others`]): held to
/// the program's end, dropped where it may have changed the offsets the later calls run
/// under (a G10, a work offset variable, a shift or frame left on, a call not followed...;
/// review 76-calls76 F1). Less the offset's index (G5x - 54): a change of another offset
/// holds nothing (review 76-calls76 F7: a `G10 L2 P1` of the body leaves a G55 call's).
pub(super) const PENDING_OTHER_CALL: i64 = PENDING_MODE_SELF - 1;

/// Among a finding's [`Finding::pending_on`], `PENDING_CALLED - n`: a position of program
/// `n` read under the offset the program before it in the file left (a guess), said after
/// its own G54-G59 by its merge: dropped at the file's end where no call in the file names
/// `n` (review 61a F5's second form: an uncalled O4000's `G0 X-700.` / `G55` / `G10 L2 P2
/// X-100.` / `M99` was "X goes to -800"), as an uncalled program's guessed findings are.
pub(super) const PENDING_CALLED: i64 = -2;

/// Among a finding's [`Finding::pending_on`], `PENDING_CALLS_WRITTEN - n`: a position under
/// program `n`'s own G54-G59, read after its own units code merged it with the file's
/// reading, `n` ending with M99: judged again at the file's end with the value a G10 of its
/// callers' run wrote before its calls, where all its calls agree on it (review 60 F4:
/// `O1000` / `G21 G90 G55 G0 X-700.` / `M99` called after `G10 L2 P2 X0.` runs at -700).
/// Below every [`PENDING_CALLED`] mark.
pub(super) const PENDING_CALLS_WRITTEN: i64 = -(1 << 40);

/// The shifts of the coordinates (G52, G92, a lathe's G50) followed under TG601's spans
/// ([`Checker::shift_spans`]): each axis's span is kept in the coordinates of the file's start
/// (the work system, with no shift of the program's own), where a position of the program's
/// coordinates stands at itself plus its axis's `total`. Where a shift's amount is not known,
/// the axis's span starts again there, in the new coordinates (its `total` back to 0).
#[derive(Debug, Clone, Default)]
pub(super) struct Shifts {
    /// Some axis has a shift in force, or a local shift not known: the spans take the walk
    /// that adds it ([`Checker::limits`]), and the end of the program is looked at.
    pub(super) on: bool,
    /// For each axis of [`AXES`], in the profile's units: the program's coordinates' zero in
    /// the coordinates of the axis's span.
    total: [f64; 9],
    /// The part of `total` that is a FANUC or Haas mill's local coordinate system (G52): its
    /// zero in the work system. A G52 replaces it; a G92 keeps the rest.
    pub(super) local: [f64; 9],
    /// The axes (bit `i` for `AXES[i]`) whose local shift is not known: a G52 of theirs shifts
    /// by an amount not known here.
    pub(super) local_unknown: u16,
    /// Whether the note of a shift not followed (TG140) was said (once per file).
    noted: bool,
    /// The note of an end of the program that started spans again ([`Checker::shift_end`]):
    /// its code, line and column, and the axes whose spans it dropped. Said where a position
    /// after it goes to one of those spans: most programs end there, and lose nothing.
    end_note: Option<(String, usize, usize, u16, String)>,
    /// The axes shifted (or with a local shift not known) where the program in hand made a
    /// call (M97, M98, G65, G66), and the first such call's code and line
    /// ([`Checker::shift_call`]): a subprogram after the end runs under that shift, not the
    /// one at the end, so at the end their spans start again.
    call: u16,
    call_at: Option<(String, usize)>,
    /// The shift in force at the calls of the program in hand ([`Checker::call_shifts`]),
    /// which a subprogram after its end runs under: where all agree and are known, the text
    /// after the end is read under it ([`Checker::shift_end`]; review 39, finding 2).
    pub(super) calls: CallShifts,
}

/// The shift in force at a program's calls ([`Shifts::calls`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) enum CallShifts {
    /// No call made.
    #[default]
    None,
    /// Every call made under this shift (each axis's `total` and `local`).
    Known([f64; 9], [f64; 9]),
    /// Calls under different shifts, or one under a shift not known.
    Mixed,
}

impl Shifts {
    fn settle(&mut self) {
        self.on = self.local_unknown != 0
            || self.end_note.is_some()
            || self.call != 0
            || self
                .total
                .iter()
                .chain(&self.local)
                .any(|&shift| shift != 0.0);
    }
}

/// Why a shift of an axis is not followed ([`Checker::shift_of`]).
type NotKnown = String;

/// A re-expression held ([`Checker::reexpression_held`]).
#[derive(Debug, Clone)]
pub(super) struct Held {
    /// The axes (their places' bits) whose position is still the one a selection
    /// re-expressed.
    pub(super) axes: u16,
    /// The delta the re-expressions added to each axis's work position.
    pub(super) delta: [Dec; 9],
    /// Main's finding of a position after a sequence number while it was held, with its
    /// line ([`Checker::reexpression_shadow`]).
    pub(super) shadow: Option<Box<(usize, String)>>,
    /// The system each axis's position was re-expressed into.
    pub(super) system: [i64; 9],
}

/// An exact rotation or scaling: a position's X Y Z before the frame is
/// `centre + m (p - centre)`, in the profile's units.
#[derive(Debug, Clone)]
struct Map {
    bit: u8,
    centre: [f64; 3],
    m: [[f64; 3]; 3],
    /// X, Y, Z (bits 0-2) given as absolute positions since the frame turned: before that
    /// an axis stands where the frame's coordinates do not say.
    fresh: u8,
    /// X, Y, Z moved under the frame at all: an axis none of whose own axes moved stands
    /// where it stood before the frame (its cancel takes nothing back).
    touched: u8,
    /// "G68 of line 4", for the message.
    what: String,
}

/// The frame bits a G code turns on and off ([`Frames::on`]); none on a SINUMERIK, whose
/// frames are statements ([`Checker::frames`]). An Okuma mill numbers its frames otherwise
/// (OSP List of G Codes, `okuma-mill.toml`): G11/G10 the parallel and rotation shift of the
/// coordinate system and its cancel (a rotation's bit), G51/G50 the scaling, G69/G68 the
/// three-dimensional coordinate system conversion and its cancel (G268's bit: a frame of
/// words not followed), G62 the programmable mirror image; its G15/G16 select a work
/// system, no polar coordinates.
fn frame_bits(v: Dec, sinumerik: bool, fanuc_lathe: bool, haas: bool, okuma: bool) -> (u8, u8) {
    let tenths = v.normalized();
    if sinumerik {
        (0, 0)
    } else if okuma {
        match v.trunc() {
            _ if !v.is_whole() => (0, 0),
            11 => (4, 0),
            10 => (0, 4),
            51 => (2, 0),
            50 => (0, 2),
            69 => (8, 0),
            68 => (0, 8),
            62 => (32, 0),
            _ => (0, 0),
        }
    } else if v.is_whole() {
        match v.trunc() {
            16 => (1, 0),
            15 => (0, 1),
            51 => (2, 0),
            50 if !fanuc_lathe => (0, 2),
            68 => (4, 0),
            69 => (0, 4),
            268 if haas => (8, 0),
            269 if haas => (0, 8),
            // a Haas's G101/G100: the mirror image of the axes they name, as G51.1/G50.1
            // (Checker::exact_mirror: about the work zero point); no FANUC code (review 17)
            101 if haas => (32, 0),
            100 if haas => (0, 32),
            _ => (0, 0),
        }
    } else if tenths.scale == 1 && tenths.mantissa == 511 {
        (32, 0)
    } else if tenths.scale == 1 && tenths.mantissa == 501 {
        (0, 32)
    } else {
        (0, 0)
    }
}

/// The G codes below 128 whose whole part may turn a frame on or off or shift the
/// coordinates ([`frame_bits`], [`Checker::shift_spans`]): G10, G11 and G62 (an Okuma's),
/// G15, G16, G50 (G50.1), G51 (G51.1), G52, G68, G69, G92 (G92.1), G100, G101. A block with
/// none of them (and no Haas G268/G269) leaves the frames as they are: most blocks, tested
/// once by the block's G mask.
const FRAME_CODES: u128 = 1 << 10
    | 1 << 11
    | 1 << 62
    | 1 << 15
    | 1 << 16
    | 1 << 50
    | 1 << 51
    | 1 << 52
    | 1 << 68
    | 1 << 69
    | 1 << 92
    | 1 << 100
    | 1 << 101;

/// The two axes of a plane (G17 X Y, G18 Z X, G19 Y Z), as places in [`AXES`].
fn plane_axes(plane: i64) -> (usize, usize) {
    match plane {
        18 => (2, 0),
        19 => (1, 2),
        _ => (0, 1),
    }
}

/// Whether an expression reads no variable but the local ones #1-#33 (`#5`, `[#5+1]`): no
/// common (#100, #500), system (#5221) or indirect (`#[#1]`) variable.
fn locals_only(expression: &[u8]) -> bool {
    let mut k = 0;
    while let Some(at) = expression[k..].iter().position(|&c| c == b'#') {
        let start = k + at + 1;
        let end = expression[start..]
            .iter()
            .position(|c| !c.is_ascii_digit())
            .map_or(expression.len(), |n| start + n);
        let number = std::str::from_utf8(&expression[start..end])
            .ok()
            .and_then(|n| n.parse::<u32>().ok());
        if !number.is_some_and(|n| (1..=33).contains(&n)) {
            return false;
        }
        k = end;
    }
    true
}

/// The work offsets G54-G59 (0-5) a program's run has written before here, and what
/// ([`Checker::offsets_written`]).
#[derive(Clone, Debug, Default)]
pub(super) struct Written {
    /// The axes (their places' bits) of each it may have written.
    pub(super) axes: [u16; 6],
    /// The value last written on each of those axes (the first nine), in the profile's
    /// units, where the checker knows it (a G10 L2 of numbers under G90: `g10_writes`); NaN
    /// where it does not. Read only where the axis's bit is set.
    pub(super) values: [[f64; 9]; 6],
    /// The programs it called that the checker had not read there (by O number: written
    /// after the call, or not in the file), whose writes are known only at the file's end
    /// ([`Finding::pending_on`]; review 58d F1).
    pub(super) unread: Vec<i64>,
    /// The coordinates were moved other than by a G10 after it (a G52 or G92, a rotation,
    /// scaling or mirror, a call the checker does not follow: [`Checker::lose_offsets`]): a
    /// position is no longer the work position plus the value written, so none is judged
    /// with it (review 59a F5: `G68 X0 Y0 R180.` runs `X-700.` at X700).
    pub(super) moved: bool,
    /// The axes (their places' bits) whose zero a G52 or G92 (a lathe's G50) moved by an
    /// amount not known to be zero, not followed where the program is called (review 60 F5:
    /// an O100 written before the main whose `G92 X-300.` shifts every work system by where
    /// the main stood): a position under a work offset on such an axis is held, not judged
    /// with the offset's value alone.
    pub(super) shifted: u16,
    /// The axes of each offset whose last write may or may not have run: a G10 L2 of numbers
    /// after a jump or condition of its program, or one whose P is not known (review 60 F1:
    /// `IF [#500 EQ 1] GOTO 5` / `G10 L2 P2 X-200.` leaves G55's X at its value before or
    /// at -200). The value is then the one before (`values`, NaN where that is the one before
    /// the program) or the one written (`alt`); [`Written::value`] has it not known.
    pub(super) maybe: [u16; 6],
    pub(super) alt: [[f64; 9]; 6],
}

impl Written {
    /// Every axis of every offset, the values not known.
    pub(super) const ALL: Written = Written {
        axes: [u16::MAX; 6],
        values: [[f64::NAN; 9]; 6],
        unread: Vec::new(),
        moved: false,
        shifted: 0,
        maybe: [0; 6],
        alt: [[0.0; 9]; 6],
    };

    /// The axes `axes` (their places' bits) of every offset, the values not known.
    pub(super) fn on_every(axes: u16) -> Written {
        Written {
            axes: [axes; 6],
            values: [[f64::NAN; 9]; 6],
            unread: Vec::new(),
            moved: false,
            shifted: 0,
            maybe: [0; 6],
            alt: [[0.0; 9]; 6],
        }
    }

    /// The same writes, value for value (a value not known is the same as another).
    pub(super) fn same(&self, other: &Written) -> bool {
        self.axes == other.axes
            && self.unread == other.unread
            && self.moved == other.moved
            && (0..6).all(|g| {
                (0..9).all(|i| {
                    let (a, b) = (self.values[g][i], other.values[g][i]);
                    self.axes[g] & 1 << i == 0 || a.to_bits() == b.to_bits() || a == b
                })
            })
    }

    /// Whether it wrote any axis of any offset.
    pub(super) fn any(&self) -> bool {
        self.axes != [0; 6]
    }

    /// `later`'s writes, made after these: an axis it writes holds its value from then on.
    pub(super) fn then(&mut self, later: &Written) {
        self.moved |= later.moved;
        self.shifted |= later.shifted;
        for &n in &later.unread {
            if !self.unread.contains(&n) {
                self.unread.push(n);
            }
        }
        for g in 0..6 {
            for i in 0..9 {
                let bit = 1 << i;
                if later.axes[g] & bit == 0 {
                    continue;
                }
                let had = self.axes[g] & bit != 0;
                if later.maybe[g] & bit == 0 || !later.values[g][i].is_nan() {
                    // (written, or "this value or that one" whatever came before)
                    self.values[g][i] = later.values[g][i];
                    self.maybe[g] = self.maybe[g] & !bit | later.maybe[g] & bit;
                    self.alt[g][i] = later.alt[g][i];
                } else if self.maybe[g] & bit != 0 || had && self.values[g][i].is_nan() {
                    // (a third value, or one not known before it: not known)
                    self.values[g][i] = f64::NAN;
                    self.maybe[g] &= !bit;
                } else {
                    // (the value before, kept, or the one written)
                    self.maybe[g] |= bit;
                    self.alt[g][i] = later.alt[g][i];
                    if !had {
                        self.values[g][i] = f64::NAN;
                    }
                }
            }
            self.axes[g] |= later.axes[g];
        }
    }

    /// Where offset G`work`'s (54-59) last write on the axis of place `i` may not have run
    /// ([`Written::maybe`]): the value before it (NaN: the one before the program) and the
    /// one it writes.
    pub(super) fn maybe_of(&self, work: usize, i: usize) -> Option<(f64, f64)> {
        let g = work.checked_sub(54).filter(|&g| g < 6)?;
        (i < 9 && self.maybe[g] & 1 << i != 0).then(|| (self.values[g][i], self.alt[g][i]))
    }

    /// The axes `axes` of every offset written with the numbers `alt` by a G10 whose P is
    /// not known here: each offset keeps its value or takes the one written
    /// ([`Written::maybe`]), where `alt` is known.
    pub(super) fn maybe_every(axes: u16, alt: Option<[f64; 9]>) -> Written {
        let mut writes = Written::on_every(axes);
        if let Some(alt) = alt {
            let known = (0..9)
                .filter(|&i| !alt[i].is_nan())
                .fold(0, |m, i| m | 1 << i);
            writes.maybe = [axes & known; 6];
            writes.alt = [alt; 6];
        }
        writes
    }

    /// Every axis of offset G54-G59 number `g` (0-5; every one where None) written with a
    /// value not known (a system variable's assignment, `#5241=0.`: the axis it names
    /// depends on the machine's axis order).
    pub(super) fn unknown_of(g: Option<usize>) -> Written {
        let mut w = Written::on_every(0);
        for k in 0..6 {
            if g.is_none_or(|g| g == k) {
                w.axes[k] = (1 << 9) - 1;
            }
        }
        w
    }

    /// Offset G`work`'s (54-59) value on the axis of place `i` here: None where not written
    /// (the profile's holds), Some(NaN) where written a value not known.
    pub(super) fn value(&self, work: usize, i: usize) -> Option<f64> {
        let g = work.checked_sub(54).filter(|&g| g < 6)?;
        if self.axes[g] & 1 << i == 0 {
            return None;
        }
        if self.maybe[g] & 1 << i != 0 {
            return Some(f64::NAN);
        }
        Some(self.values[g].get(i).copied().unwrap_or(f64::NAN))
    }
}

impl Checker {
    /// Whether the block has a G code that may turn a frame or shift the coordinates: the
    /// mask of its codes against [`FRAME_CODES`], a decimal code (G51.1, G50.1, G92.1: not in
    /// the mask), a Haas G268/G269 above it; a FANUC lathe's
    /// G code system B or C (the mask is of system A's numbers) looks at every code.
    fn frame_codes(&self) -> bool {
        self.letters & bit(b'G') != 0
            && (self.values.g_mask() & FRAME_CODES != 0
                || self.values.decimal_g
                || self.config.modal.g_system != crate::lex::GCodeSystem::A
                || self.config.haas && self.values.gs().iter().any(|&g| g >= 128))
    }

    /// The frame bits G code `v` (as written) turns on and off ([`frame_bits`]), by the
    /// number the profile's code table reads it by ([`Checker::g_read`]).
    fn frame_bits_of(&self, v: Dec) -> (u8, u8) {
        frame_bits(
            self.g_read(v),
            self.config.family == Family::Sinumerik,
            self.config.modal.fanuc_lathe,
            self.config.haas,
            self.config.family == Family::Okuma,
        )
    }

    /// G code `v` by the number the core reads it by: a FANUC lathe's code of G code system
    /// B or C as system A's (`ModalSettings::read_g`, `GCodeSystem::tenths_to_a`), so that a
    /// code's role comes from the profile's code table, not from its written number: in B and
    /// C G92 is the coordinate setting (A's G50) and a written G50 is no code (FANUC 0i-TF,
    /// "G code list"; review 15, finding 4).
    fn g_read(&self, v: Dec) -> Dec {
        let system = self.config.modal.g_system;
        if system == crate::lex::GCodeSystem::A {
            v
        } else if v.is_whole() {
            Dec::from_int(i128::from(self.config.modal.read_g(v.trunc())))
        } else {
            let tenths = v.normalized();
            match i64::try_from(tenths.mantissa) {
                Ok(m) if tenths.scale == 1 => Dec {
                    mantissa: i128::from(system.tenths_to_a(m)),
                    scale: 1,
                },
                _ => v,
            }
        }
    }

    /// The factor from the block's units (of lengths, or of the feed) to the profile's, where
    /// limits are given.
    pub(super) fn to_profile_units(&self, feed: bool) -> f64 {
        let units = if feed {
            self.block_feed_units
        } else {
            self.block_units
        };
        match (units, self.config.limit_units) {
            (Units::Inch, Units::Metric) => 25.4,
            (Units::Metric, Units::Inch) => 1.0 / 25.4,
            _ => 1.0,
        }
    }

    /// From here on the profile's work offsets are not the ones in force, the coordinates
    /// moved (a shift, a frame, a jump or call not followed...): said once, why; nor is a
    /// position the work position plus a value a G10 wrote ([`Written::moved`]).
    pub(super) fn lose_offsets(&mut self, line: usize, why: &str) {
        self.offsets_written.moved = true;
        let moved = Written {
            moved: true,
            ..Default::default()
        };
        self.offset_writer(&moved, false);
        self.offsets_rewritten(line, why);
    }

    /// [`Checker::lose_offsets`] where no frame or shift of the program in hand moved the
    /// coordinates: a G10, a call (what a program of the file it runs moved comes with its
    /// writes, [`Written::moved`]; what a program the checker does not read does is not
    /// followed, as [`Checker::offsets_written`] says) or a jump.
    pub(super) fn offsets_rewritten(&mut self, line: usize, why: &str) {
        // (after the main program's first jump: callflow.rs)
        self.flow_spoiled();
        self.shift_work = None;
        self.span_unjudged = ALL_PLACES;
        if self.spans_parked.is_some() {
            self.spans_unparked(ALL_PLACES);
        }
        self.work_unplaced = false;
        self.offsets_unread_only = false;
        if let Some(w) = self.work_call.as_mut() {
            w.others.clear();
            w.unsure = true;
        }
        if self.config.work_offsets.is_empty() || self.offsets_lost {
            return;
        }
        self.offsets_lost = true;
        self.work = None;
        self.stats.travel_not.push(format!(
            "from line {line} on: {why} (the offsets may have changed)"
        ));
    }

    /// A program no call before it names begins on line `line` (called_units): the work
    /// offset it runs under is its caller's or the reset state's, not the one the program
    /// before it left (a FANUC's M30 ends that program; review 56e, F6: `G55` / `M30` /
    /// `O2000` / `G0 X-700.` / `M99` was judged under G55). Its positions are compared as
    /// machine positions again from its own G54-G59. Read apart (called.rs), it is read
    /// under the offset left before all the same, its machine positions' findings marked
    /// `guessed`: a call in the file that runs it under that offset says them, as its caller
    /// selected it (review 57c, F6: `O3000` / `G90 G55` / `M98 P2000` of an `O2000` written
    /// before it, after a main under G55); no call, or one under another offset, does not.
    pub(super) fn work_offset_unknown(&mut self, line: usize) {
        if self.config.work_offsets.is_empty() || self.work.is_none() {
            return;
        }
        if self.early_on {
            self.work_guessed = self.work;
        } else {
            self.work = None;
        }
        self.travel_not(format!(
            "from line {line} on: a program no call before it names runs under its caller's \
             work offset, not known here, until it selects one of its own"
        ));
    }

    /// The program in hand selects or restores a work system of its own: no longer the one
    /// it was placed under, one that changes its callers' where it is read apart
    /// ([`Checker::early_changes_offsets`]), and, in a program written after its calls, no
    /// longer the calls'.
    fn work_changed(&mut self) {
        self.work_unplaced = false;
        if self.early_on {
            self.early_changes_offsets();
        }
        if let Some(w) = self.work_call.as_mut() {
            w.others.clear();
        }
    }

    /// The program selects work offset `g` (G54-G59): its own, no longer one guessed.
    fn work_selected(&mut self, g: i64, line: usize) {
        self.flow_spoiled();
        // (the axes whose values are known under the system left: review 76-lcnc76b N3)
        let same = self.work == Some(g);
        let from = self.work.filter(|_| !same);
        let (mut left, positions) = match from {
            Some(from) => (self.selection_known(from), self.known_axes(from)),
            None => (0, 0),
        };
        // (the real run keeps the machine position: the work position held is the old
        // system's, not the new one's, where the selection does not re-express it; review of
        // the stop's merge, resumed.rs)
        let positioned = if same {
            0
        } else {
            (0..AXES.len())
                .filter(|&i| self.machine.state.position[i].is_some())
                .fold(0u16, |m, i| m | 1 << i)
        };
        let at_start = self.linuxcnc_at_start();
        self.linuxcnc_work_selected = true;
        if self.work != Some(g) && self.config.family == Family::LinuxCnc {
            // (from a system not known, not G59.1-G59.3: it may be this one, the line's
            // write loaded or not; review 76 F6)
            self.linuxcnc_selected_at = line;
            self.linuxcnc_selected_maybe =
                self.work.is_none() && !std::mem::take(&mut self.linuxcnc_other_in_force);
        }
        if self.linuxcnc_pending.is_some() {
            self.linuxcnc_reselected(g, at_start);
        }
        self.work_changed();
        if self.offsets_unread_only {
            self.work_unread_reselected();
        }
        self.work = Some(g);
        self.work_guessed = None;
        self.work_run_on = false;
        // (and the axes a re-expression holds, in the coordinates of the system it
        // re-expressed them into, however many selections of systems not known since)
        let held = self.reexpressed_held.as_ref().map_or(0, |h| h.axes);
        let moved = match from {
            Some(from) if positions | held != 0 => {
                self.selection_reexpressed(from, g, positions | held)
            }
            None if held != 0 && !same => self.selection_reexpressed(g, g, held),
            _ => 0,
        };
        // (the same system selected again keeps what was re-expressed into it)
        if !same {
            self.reexpressed = (moved != 0).then_some((g, moved));
        }
        self.selected_stale |= positioned & !moved;
        if !same {
            self.shift_work = None;
        }
        left |= moved;
        if left != 0 {
            self.selection_spans(left);
        }
    }

    /// A G54-G59 selected from G`from`, the values of both known on the axes `axes`
    /// ([`Checker::known_axes`], under the new system too): the real run keeps the machine
    /// position (LinuxCNC interp_convert.cc `convert_coordinate_system`; FANUC 0i-F and 30i-B
    /// and Haas NGC: selecting a work system moves no axis), so the work position held is
    /// re-expressed in the new system, axis by axis: new work = old work + old offset - new
    /// offset (in the block's units). An increment after it runs from there (review
    /// 80-sel80 R2: `G54` / `G0 X-700.` / `G57` / `G91 G0 X100.` on G54 X0, G57 X-300 runs at
    /// machine -600, inside, and was "X goes to -900"; its twin from `X700.` runs at 800,
    /// beyond, and was not said). An axis the block itself places (an absolute position, a
    /// G53, a G92, a code's data) is left as the block left it. The axes re-expressed.
    /// Whether the run may come back over the block in hand, a second pass the checker does
    /// not read: inside a LinuxCNC loop or condition; in a FANUC's or Haas's program after a
    /// jump or loop statement. (A FANUC's or Haas's sequence number a later `GOTO` or `M99 P`
    /// may jump back to is a label only until that jump is read: [`Checker::reexpression_held`]
    /// keeps main's judgement of the positions after it, said where the run comes back.)
    fn run_may_come_back(&self) -> bool {
        if self.config.family == Family::LinuxCnc {
            !self.linuxcnc_open_flow.is_empty()
        } else {
            self.jumped
        }
    }

    #[cold]
    #[inline(never)]
    fn selection_reexpressed(&mut self, from: i64, to: i64, axes: u16) -> u16 {
        // (not where the run may come back over the selection, a second pass beginning from
        // the machine position the first left, which the checker does not read: inside a
        // LinuxCNC loop or condition; in a FANUC's or Haas's program after a jump or loop
        // statement. There the work value held is kept, as main kept it: its judgement of
        // the first pass refused `G54` / `G0 X-700.` / a loop of two passes of `G57` / `G91
        // G0 X-50.` / `G90` / `G54`, which runs at -800 on the second; review 81-sel81 R1.
        // After a FANUC's or Haas's sequence number, which a jump read later may go back
        // to, main's judgement is kept beside it: Checker::reexpression_shadow)
        let back = self.run_may_come_back();
        if back {
            return 0;
        }
        let known = axes & self.known_axes(to);
        let carried = self.reexpressed_held.as_ref().map_or(0, |h| h.axes);
        let factor = self.to_profile_units(false);
        let given = self.values.given();
        let placed = self.values.has_g(53)
            || self.machine.taken().is_some()
            || !self.machine.state.incremental;
        let mut moved = 0;
        for i in crate::modal::places(u32::from(known)) {
            if given & bit(AXES[i]) != 0 && placed {
                continue;
            }
            // (an axis held: from the system its position was re-expressed into, where a
            // selection of a system not known came between, `G54` / `G0 X700.` / `G57` /
            // `G58` / `G57` / `G91 G0 X100.` at machine 800, review 82-sel82 R1; where that
            // is the new one, its position is already the new system's)
            let from = match &self.reexpressed_held {
                Some(h) if carried & 1 << i != 0 => h.system[i],
                _ => from,
            };
            if from == to || self.known_axes(from) & 1 << i == 0 {
                continue;
            }
            let (Some(old), Some(new), Some(at)) = (
                self.offset_value(from, i),
                self.offset_value(to, i),
                self.machine.state.position[i],
            ) else {
                continue;
            };
            let Some(now) = Dec::parse(&format!("{:.9}", (old - new) / factor))
                .and_then(|delta| at.checked_add(delta))
            else {
                continue;
            };
            self.machine.state.position[i] = Some(now);
            #[cfg(debug_assertions)]
            {
                self.position_reexpressed = true;
            }
            moved |= 1 << i;
            let held = self.reexpressed_held.get_or_insert_with(|| {
                Box::new(Held {
                    axes: 0,
                    delta: [Dec::ZERO; 9],
                    shadow: None,
                    system: [0; 9],
                })
            });
            // (added to the delta held on the axis, or from none where it holds none)
            let before = if held.axes & 1 << i != 0 {
                held.delta[i]
            } else {
                Dec::ZERO
            };
            held.axes |= 1 << i;
            held.system[i] = to;
            held.delta[i] = now
                .checked_add(-at)
                .and_then(|d| before.checked_add(d))
                .unwrap_or(before);
        }
        moved
    }

    /// A block after a re-expression ([`Checker::selection_reexpressed`]) while an axis's
    /// position is still the one it re-expressed (no position of the block's own on it
    /// since): where a loop opens or a block a jump back may arrive at is read (a LinuxCNC
    /// loop or condition; a FANUC's or Haas's jump or loop statement or a sequence number),
    /// the run may come back there with the machine position the first pass left, which the
    /// checker does not read: the re-expression is taken back (position - the delta added,
    /// main's work value) and the increments judged from it as main judged them (review
    /// 81-sel81 R5: `G54` / `G0 X-700.` / `G57` / a loop of two `G91 G0 X-50.` runs at -800
    /// on the second pass, refused by main's -1050 of the first). A call may place the
    /// position anew: no longer held.
    ///
    /// A FANUC's or Haas's block that may take the run back to a sequence number before it
    /// (a jump, condition or loop statement; an `M99`, whose `P` names one, or without it
    /// the program's start; an `M97`; a call, whose body's `M99 P` returns to the caller's
    /// sequence number, FANUC 0i-F Operator's Manual, "Subprogram call (M98)"), where a
    /// position after a sequence number went beyond the travel as main judged it
    /// ([`Checker::reexpression_shadow`]): main's finding is said here, at the block the
    /// second pass, which the checker does not read, begins from.
    #[cold]
    #[inline(never)]
    fn reexpression_held(&mut self, b: &BlockView<'_>) {
        let Some(mut held) = self.reexpressed_held.take() else {
            return;
        };
        // (the block's M and G codes by value, as the control reads them: `M098`, `M030`)
        let ms = &self.values.ms;
        let calls = b.statements.iter().any(|s| s.1 == Kind::Call)
            || ms.iter().any(|&m| matches!(m, 97 | 98 | 198))
            || self.values.has_g(65)
            || self.values.has_g(66);
        let returns = ms.contains(&99);
        let ends = ms.iter().any(|&m| m == 2 || m == 30);
        if held.shadow.is_some()
            && (calls
                || self.run_may_come_back()
                || b.statements.iter().any(|s| s.1 == Kind::Flow)
                || returns)
        {
            self.reexpressed_held = Some(held);
            self.reexpression_comes_back(b.line);
            let Some(back) = self.reexpressed_held.take() else {
                return;
            };
            held = back;
        }
        // (the main program's end: no jump of it runs after it, and a body after it runs
        // only where a call read before it called it, where main's finding was said; not an
        // end the block skip may pass over, `/M30`: review 82-sel82 n29blockdel)
        if held.shadow.is_some() && !b.skip && b.skip_within.is_none() && ends {
            held.shadow = None;
        }
        if calls {
            self.reexpressed_held = Some(held);
            return;
        }
        let placed = self.values.has_g(53)
            || self.machine.taken().is_some()
            || !self.machine.state.incremental;
        for i in crate::modal::places(u32::from(held.axes)) {
            if self.values.given() & bit(AXES[i]) != 0 && placed
                || self.machine.state.position[i].is_none()
            {
                held.axes &= !(1 << i);
                held.delta[i] = Dec::ZERO;
            }
        }
        let back = self.run_may_come_back();
        if back {
            #[cfg(debug_assertions)]
            {
                self.position_reexpressed = true;
            }
            for i in crate::modal::places(u32::from(held.axes)) {
                let s = &mut self.machine.state;
                s.position[i] = s.position[i].and_then(|p| p.checked_add(-held.delta[i]));
            }
            self.selected_stale |= held.axes;
            self.reexpressed = None;
        } else if held.axes != 0 || held.shadow.is_some() {
            self.reexpressed_held = Some(held);
        }
    }

    /// The work system a G52 or G92 leaves in force under its shift ([`Checker::shift_work`]):
    /// the one in force, where no other loss of the offsets came before it.
    fn shift_kept(&self) -> Option<i64> {
        if self.offsets_lost {
            self.shift_work
        } else {
            self.work
        }
    }

    /// A block that may take the run back to a sequence number (line `at`: a jump, loop or
    /// call statement, [`Checker::forget_at_jump`], or [`Checker::reexpression_held`]'s):
    /// main's finding kept ([`Checker::reexpression_shadow`]) is said here.
    #[cold]
    #[inline(never)]
    pub(super) fn reexpression_comes_back(&mut self, at: usize) {
        let Some((line, what)) = self
            .reexpressed_held
            .as_mut()
            .and_then(|h| h.shadow.take())
            .map(|f| *f)
        else {
            return;
        };
        self.report(
            Rule::TravelExceeded,
            format!(
                "{what}, as main judges the position held across a selection (line {line}): the \
                 run may go back from here to a sequence number before it, a pass beginning \
                 from the machine position the first left, which the checker does not read"
            ),
            at,
            1,
        );
    }

    /// A position of axis place `i` (`position`, in the program's units; `factor` to the
    /// profile's) judged under the system in force while a re-expression is held on it, in
    /// a FANUC's or Haas's program after a sequence number (a LinuxCNC N word is no label:
    /// rs274 jumps to none; review 82-sel82 R6): main, which kept the work value there,
    /// judged the position less the delta the re-expression added
    /// ([`Checker::selection_reexpressed`]); where that is beyond the travel, main's finding
    /// is kept (the first) and said where a block may take the run back
    /// ([`Checker::reexpression_held`]), unless the main program ends first: `N10 G57` /
    /// `G91 G0 X-50.` / `G90` / `G54` / `IF [#1 LT 2] GOTO10` from G54's machine -700 runs
    /// -750 on the first pass (said so, the re-expressed work -450 + G57 offset -300) and
    /// -800 on the second, refused by main's "X goes to -1050" (review 81-sel81 R1, R6).
    #[cold]
    #[inline(never)]
    fn reexpression_shadow(&mut self, i: usize, position: Dec, factor: f64, line: usize) {
        let Some(held) = self.reexpressed_held.as_ref() else {
            return;
        };
        if held.axes & 1 << i == 0 || held.shadow.is_some() {
            return;
        }
        let (Some(work), Some((low, high))) = (self.work, self.travel.of(AXES[i])) else {
            return;
        };
        let (Some(offset), Some(main)) = (
            self.offset_value(work, i),
            position.checked_add(-held.delta[i]),
        ) else {
            return;
        };
        let at = main.to_f64() * factor;
        let machine_at = at + offset;
        if travel_side(machine_at, (low, high)) == 0 {
            return;
        }
        let what = format!(
            "{} goes to {} in machine coordinates at line {line} (work {} + G{work} offset {}), \
             outside the travel {low} to {high}",
            AXES[i] as char,
            round6(machine_at),
            round6(at),
            round6(offset)
        );
        if let Some(held) = self.reexpressed_held.as_mut() {
            held.shadow = Some(Box::new((line, what)));
        }
    }

    /// The value of work offset G`work` on the axis of place `i`: a G10's of the run where
    /// one wrote it, else the profile's; None where not known.
    fn offset_value(&self, work: i64, i: usize) -> Option<f64> {
        if self.offset_unknown(work, i) {
            return None;
        }
        self.offset_written(work, i).or_else(|| {
            self.config
                .work_offsets
                .iter()
                .find(|&&(g, a, _)| g == work && a == AXES[i])
                .map(|&(_, _, value)| value.to_f64())
        })
    }

    /// The axes (their places' bits) of work system G`work` (54-59) whose positions are
    /// judged as machine positions with a value known: the profile gives it and no write
    /// made it not known, the offsets followed, no frame, program read apart or call's
    /// offset between, Z under no tool length offset.
    #[cold]
    #[inline(never)]
    fn selection_known(&self, work: i64) -> u16 {
        // (under G91 the next increment runs from where the tool stands, which the
        // selection changes in work coordinates; a lathe's U and W too: review 78-lcnc78b
        // F1; a selection re-expresses it where it can, Checker::selection_reexpressed)
        if self.machine.state.incremental {
            return 0;
        }
        self.known_axes(work)
    }

    /// [`Checker::selection_known`] whatever G90/G91 is in force.
    #[cold]
    #[inline(never)]
    fn known_axes(&self, work: i64) -> u16 {
        if self.offsets_lost
            || self.work_guessed.is_some()
            || self.work_run_on
            || self.work_call.is_some()
            || self.early_on
            || self.later_shift.is_some()
            || self.open_definition.is_some()
            || self.frames.on != 0
            || self.frames.map.is_some()
            || self.transformed.is_some()
            || self.units_unknown
            || self.offsets_written.moved
            || !self.offsets_written.unread.is_empty()
            || self.config.modal.fanuc_lathe
            || self.config.diameter
        {
            return 0;
        }
        let length = self.machine.state.length_offset != 49 || self.length_decimal;
        let mut known = 0u16;
        for i in crate::modal::places(self.travel.places()) {
            let axis = AXES[i];
            // (a span holding a position not judged as a machine position is kept: review
            // 78-lcnc78b F2, F3, an `if`'s or the start's X-1100 then G54 / G57)
            if axis == b'Z' && length
                || self.offset_unknown(work, i)
                || self.span_unjudged & 1 << i != 0
            {
                continue;
            }
            if self
                .config
                .work_offsets
                .iter()
                .any(|&(g, a, _)| g == work && a == axis)
            {
                known |= 1 << i;
            }
        }
        known
    }

    /// A G54-G59 selected from another system, the values of both known on the axes
    /// `axes` (their places' bits; [`Checker::selection_known`]): each position on them
    /// under either is judged as a machine position, so the span of those axes (one not yet
    /// said) is set aside and starts again: a span across the two, in work coordinates,
    /// mixes positions of two offsets (review 76-lcnc76b N3: `G54` / `G0 X-650` / `G57` /
    /// `G0 X1000` with G57 X -300 runs at -650 and 700, inside, and was "X spans 1650"; the
    /// FANUC's and the LinuxCNC's alike). Within one system a span wider than the travel
    /// still has a position beyond it, said as one. Where a later position is not judged so
    /// (a system not known, offsets lost), the span set aside joins the one in hand again
    /// ([`Checker::spans_unparked`]). Then the selection of a system not known.
    #[cold]
    #[inline(never)]
    fn selection_spans(&mut self, axes: u16) {
        let known = axes & self.work.map_or(0, |g| self.selection_known(g)) | self.moved_axes();
        for i in crate::modal::places(u32::from(known)) {
            let Some(span) = self.spans[i].filter(|s| !s.said) else {
                continue;
            };
            // (set aside before and now together where they fit the travel, else the
            // latest: positions of two systems known that together do not fit were each
            // judged as machine positions)
            let fits = self.span_fits(i, joined(parked_at(&self.spans_parked, i), span));
            let parked = self.spans_parked.get_or_insert_with(Default::default);
            parked[i] = Some(if fits { joined(parked[i], span) } else { span });
            self.spans[i] = None;
        }
        if self.spans_parked.is_some() {
            let unknown = !(self.work.map_or(0, |g| self.selection_known(g)) | self.moved_axes());
            self.spans_unparked(unknown);
        }
    }

    /// The axes the last selection re-expressed the position of, where its system is still
    /// in force ([`Checker::selection_reexpressed`]).
    fn moved_axes(&self) -> u16 {
        match self.reexpressed {
            Some((g, axes)) if self.work == Some(g) => axes,
            _ => 0,
        }
    }

    /// Where a body read after the main program's end begins (structure.rs,
    /// `local_body_begin`), the main program in hand until then: the work system it ended in
    /// and the axes whose values are known under it ([`Checker::selection_known`]), where
    /// every position it made was placed (no call lost its G90/G91), no span is set aside
    /// already and the only program it called whose writes are not known yet is this body
    /// (`key`: what it writes is known at its end, [`Checker::body_spans_end`]).
    #[cold]
    #[inline(never)]
    pub(super) fn body_spans_known(&mut self, key: i64) -> Option<(i64, u16)> {
        if self
            .in_hand
            .is_some_and(|n| n >= super::structure::LOCAL_BODY)
            || self.mode_lost_codes.is_some()
            || self.spans_parked.is_some()
            || self.offsets_written.unread.iter().any(|&k| k != key)
        {
            return None;
        }
        let from = self.work?;
        let unread = std::mem::take(&mut self.offsets_written.unread);
        let open = self.open_definition.take();
        let known = self.selection_known(from);
        self.offsets_written.unread = unread;
        self.open_definition = open;
        (known != 0).then_some((from, known))
    }

    /// The body begun ([`Checker::body_spans_known`]: `ended`, the main program's system at
    /// its end and the axes known there) runs under its calls' system, another: the main
    /// program's positions and the body's are each judged as machine positions, so the span
    /// in hand (the main program's, in its system's work coordinates) is set aside, as at a
    /// selection ([`Checker::selection_spans`]): the real run keeps the machine position
    /// across a G54-G59 (LinuxCNC interp_convert.cc `convert_coordinate_system`; FANUC and
    /// Haas: selecting a work system moves no axis). `G54` / `o2000 call` / `G57` / `G0
    /// X800.` / `M2` / `o2000 sub` / `G0 X-740.` / `o2000 endsub` on G57 X -300 runs X-740 at
    /// machine -740 and X800 at 500, inside -762..762, and was "X spans 1540". A body
    /// position not judged so joins them again ([`Checker::position_not_judged`]).
    #[cold]
    #[inline(never)]
    pub(super) fn body_spans_parked(&mut self, ended: Option<(i64, u16)>) {
        let Some((from, known_from)) = ended else {
            return;
        };
        let Some((work, codes)) = self
            .work_call
            .as_ref()
            .filter(|w| w.work != from && w.others.is_empty())
            .map(|w| (w.work, w.codes_at))
        else {
            return;
        };
        let call = self.work_call.take();
        let unread = std::mem::take(&mut self.offsets_written.unread);
        let open = self.open_definition.take();
        let known = known_from & self.selection_known(work);
        self.offsets_written.unread = unread;
        self.open_definition = open;
        self.work_call = call;
        let mut parked = [None; 9];
        for i in crate::modal::places(u32::from(known)) {
            if let Some(span) = self.spans[i].filter(|s| !s.said) {
                parked[i] = Some(span);
                self.spans[i] = None;
            }
        }
        if parked.iter().any(Option::is_some) {
            self.spans_parked = Some(Box::new(parked));
            self.spans_parked_body = Some(Box::new((self.offsets_written.clone(), codes)));
        }
    }

    /// A block of the body of [`Checker::body_spans_parked`]: anything but a move of G0-G3
    /// by numbers, a sequence number, the body's own end (M99 without P, `endsub`) or a
    /// comment -- an offset, shift, frame, units or mode code, a G10, a parameter or
    /// variable, a call, a jump, a condition, an M or T code -- may change where the main
    /// program's positions after the call really run (review 80-sel80 R5-R12: `G52 X400.`,
    /// `G92 X-1100.`, `G10 L20 P4 X-1100.`, `G10 L2 P4 R180.`, `G20`, `#5281=0.`, `M98
    /// P9999`, `M99 P20`): the spans set aside join the one in hand there
    /// ([`Checker::body_spans_rejoined`]), as main joined them.
    #[cold]
    #[inline(never)]
    pub(super) fn body_block(&mut self, b: &BlockView<'_>) {
        let plain = b.statements.iter().all(|s| s.1 == Kind::Definition)
            && b.words.iter().all(|w| {
                w.index.is_empty()
                    && w.expression.is_empty()
                    && match w.letter {
                        b'N' | b'X' | b'Y' | b'Z' | b'A' | b'B' | b'C' | b'U' | b'V' | b'W'
                        | b'I' | b'J' | b'K' | b'R' | b'F' | b'S' => true,
                        b'G' => matches!(
                            w.number,
                            b"0" | b"00" | b"1" | b"01" | b"2" | b"02" | b"3" | b"03"
                        ),
                        // (the spindle's M3-M5 and the coolant's M7-M9 move no axis and
                        // write no offset: review 80-sel80 R16)
                        b'M' => match w.number {
                            [d] | [b'0', d] => b"345789".contains(d),
                            b"99" => !b.words.iter().any(|w| w.letter == b'P'),
                            _ => false,
                        },
                        _ => false,
                    }
            });
        if !plain {
            self.body_spans_rejoined();
        }
    }

    /// The body of [`Checker::body_spans_parked`] ends: where it wrote an offset or a
    /// G90/G91 (the main program's positions were then not all where they were judged: a
    /// write changes the value they ran under, a G90/G91 it leaves the mode of those after
    /// its call), the spans set aside join the one in hand again
    /// ([`Checker::body_spans_rejoined`]).
    #[cold]
    #[inline(never)]
    pub(super) fn body_spans_end(&mut self) {
        let Some(at_start) = self.spans_parked_body.as_ref() else {
            return;
        };
        let (written, codes) = (&at_start.0, at_start.1);
        let w = &self.offsets_written;
        let same = w.axes == written.axes
            && w.unread == written.unread
            && w.moved == written.moved
            && w.shifted == written.shifted
            && w.maybe == written.maybe
            && codes == self.machine.distance_codes;
        if same {
            self.spans_parked_body = None;
        } else {
            self.body_spans_rejoined();
        }
    }

    /// The spans set aside where a body began ([`Checker::body_spans_parked`]) join the one
    /// in hand, fit or not, a span wider than the travel said here (the line in hand), as
    /// main said it where the body's position joined it.
    #[cold]
    #[inline(never)]
    fn body_spans_rejoined(&mut self) {
        if self.spans_parked_body.take().is_none() {
            return;
        }
        let Some(parked) = self.spans_parked.take() else {
            return;
        };
        self.spans_parked_call = false;
        let line = self.last_line;
        for (i, span) in parked.iter().enumerate() {
            if let Some(span) = span {
                self.add_to_span(i, span.least, false, line, || 1, "");
                self.add_to_span(i, span.most, false, line, || 1, "");
            }
        }
    }

    /// A position of axis place `i` not judged as a machine position: the span set aside for
    /// it joins the one in hand ([`Checker::spans_unparked`]).
    #[inline]
    fn position_not_judged(&mut self, i: usize) {
        self.span_unjudged |= 1 << i;
        if self.spans_parked.is_some() {
            self.spans_unparked(1 << i);
        }
    }

    /// A position outside a body read under its call's offset (the main program's after the
    /// call, a body read under no call's offset), the spans set aside having been kept across
    /// a call of a program read after the end (structure.rs, `call_offsets_rewritten`): they
    /// join the ones in hand, as that call joined them before (review 79-lcnc79: `G54` / `G0
    /// X-650` / `G57` / `M98 P2000` / `G0 X1100` runs at machine 800, said by the span).
    #[cold]
    #[inline(never)]
    fn spans_rejoined(&mut self) {
        if self.work_call.is_none() && self.spans_parked.is_some() {
            self.spans_unparked(ALL_PLACES);
        }
    }

    /// Whether `span` of axis place `i` fits its travel.
    fn span_fits(&self, i: usize, span: Span) -> bool {
        self.travel
            .of_place(i)
            .is_some_and(|(low, high)| span.most - span.least <= (high - low) + 1e-9)
    }

    /// The spans set aside at selections ([`Checker::selection_spans`]) of the axes `axes`
    /// join the ones in hand again, from here where positions are not judged as machine
    /// positions (the chain of positions main held in one span, erring on the side of the
    /// alarm: `G55` / `#5241=#1` / `G0 X-650` / `G54` / `G55` / `G0 X1000` loads a value not
    /// known, and X1000 is judged in the span from -650, as before) -- where the two fit the
    /// travel together: where they do not, every position of them was judged as a machine
    /// position, and only the span in hand is kept.
    #[cold]
    #[inline(never)]
    pub(super) fn spans_unparked(&mut self, axes: u16) {
        // (set aside where a body began: fit or not, review 80-sel80 R12)
        if self.spans_parked_body.is_some() {
            self.body_spans_rejoined();
            return;
        }
        if self.early_on || self.later_shift.is_some() || self.frames.on != 0 {
            return;
        }
        let Some(mut parked) = self.spans_parked.take() else {
            return;
        };
        for i in crate::modal::places(u32::from(axes & ALL_PLACES)) {
            let Some(aside) = parked[i].take() else {
                continue;
            };
            let both = joined(self.spans[i], aside);
            let said = self.spans[i].is_some_and(|s| s.said);
            // (kept across a call of a body read later: joined as the call joined them)
            if self.spans_parked_call {
                self.spans[i] = Some(both);
            } else if said || self.span_fits(i, both) {
                self.spans[i] = Some(Span { said, ..both });
            }
        }
        if parked.iter().any(Option::is_some) {
            self.spans_parked = Some(parked);
        } else {
            self.spans_parked_call = false;
        }
    }

    /// The program in hand ends (the next begins, or the file): where it left a shift on
    /// (a G52 of its own, or another shift), what it left ([`Checker::shift_ends`]), for
    /// its calls that come after it in the file.
    #[cold]
    #[inline(never)]
    pub(super) fn program_shift_end(&mut self) {
        let g52 = std::mem::take(&mut self.g52_axes);
        let read = std::mem::take(&mut self.g52_read);
        let clean = std::mem::replace(&mut self.shift_clean_start, true);
        let unsure = std::mem::take(&mut self.shift_unsure);
        let Some(n) = self.in_hand else {
            return;
        };
        if self.config.family != Family::MacroB {
            return;
        }
        let writer = self.offset_writers.get(&n);
        let moved = writer.is_some_and(|(w, _)| w.moved || w.shifted != 0);
        if g52 == 0 && !moved && !self.shifts.on {
            return;
        }
        let s = &self.shifts;
        let known = clean
            && !unsure
            && s.local_unknown == 0
            && (0..AXES.len()).all(|i| s.total[i] == s.local[i])
            && writer.is_none_or(|(w, _)| !w.moved && w.unread.is_empty());
        let end = known.then_some((g52, s.local, read));
        self.shift_ends.insert(n, end);
    }

    /// A G52 of axis place `i` (or one a call carries) read at `factor` to the profile's
    /// units: where the program had written no units code by it, the factor, 0 where it
    /// had or the value is exact (`exact`, carried from a body's own units); the last of
    /// each axis counts, as a G52 replaces the local shift (review 63 F8, F9)
    /// ([`Checker::shift_ends`]).
    fn g52_read_at(&mut self, i: usize, factor: f64, exact: bool) {
        self.g52_read[i] = if self.machine.state.units_given || exact {
            0.0
        } else {
            factor
        };
    }

    /// A call of program `number`, read before it in the file (`writes`: what it writes of
    /// the offsets): a G52 it leaves on stays in force for its caller after the call (a
    /// FANUC's local coordinate system is modal until cancelled, and M99 cancels none:
    /// 0i-MF Operator's Manual, "Local coordinate system"): the caller's spans from here are
    /// in the coordinates it sets, as after a G52 of its own. Where what it leaves is not
    /// surely known (a G92, a jump, condition or loop, a call not followed), as before: not
    /// followed, the caller's spans read on unshifted; so where the call may not run, or not
    /// from the body's start (`surely` false). A program read apart that runs such
    /// a call is read as before from here, as one that writes its own G52 is.
    #[cold]
    #[inline(never)]
    pub(super) fn shift_carried(&mut self, number: i64, surely: bool) {
        self.later_shift_closed();
        let Some(end) = self.shift_ends.get(&number).copied() else {
            return;
        };
        // (where not surely known, or the call may not run or not from the body's start
        // (`surely`), as before: the caller's spans read on unshifted, erring on the side
        // of the alarm; review 62a F7: `IF [#1 EQ 1] GOTO 5` / `M98 P2000` / `N5 G90` /
        // `G0 X800.` runs X800. at 800 where the call is passed over)
        let Some((axes, local, read)) = end.filter(|_| surely) else {
            self.shift_unsure = true;
            return;
        };
        // (G52s the body read before any units code of its own run in the caller's units:
        // taken by the caller's factor to the profile's units, not the one the body was
        // read in; review 62a F9: an inch profile, `G21` / `M98 P2000` of `G52 X-1000.` is
        // -1000 mm, not -1000 inches)
        let factor = self.to_profile_units(false);
        // (its positions before the call kept for its own calls, review 62a F8)
        self.early_merge_keeping();
        for i in crate::modal::places(u32::from(axes)) {
            if self.shifts.local_unknown & 1 << i != 0 {
                self.restart_span(i, true);
                continue;
            }
            let r = if read[i] == 0.0 {
                1.0
            } else {
                factor / read[i]
            };
            self.shifts.total[i] += local[i] * r - self.shifts.local[i];
            self.shifts.local[i] = local[i] * r;
            self.g52_read_at(i, factor, read[i] == 0.0);
        }
        self.g52_axes |= axes;
        self.shifts.settle();
    }

    /// A G54-G59 of the program's own after calls of programs the checker had not read
    /// there, and nothing else that may change the offsets ([`Checker::offsets_unread_only`]):
    /// the offset it selects has the profile's value unless one of those programs writes
    /// it. Its positions are judged again, each finding held to the file's end with those
    /// programs' numbers ([`Finding::pending_on`], [`PENDING_OWN`]): dropped where one of
    /// them writes that axis, moves the coordinates, or is not in the file; said where all
    /// are read and none does (review 61a F13: `O2000` / `G65 P4000 I2.` / `G90 G54` / `G0
    /// X850.` / `M99` / `O4000` / `M99` runs X850. at 850, beyond the travel, and was said
    /// by none). A G52 it leaves is modal through G54-G59 (0i-MF Operator's Manual, "Local
    /// coordinate system"): the axes it shifts are not judged.
    #[cold]
    #[inline(never)]
    fn work_unread_reselected(&mut self) {
        if self.offsets_lost
            && !self.offsets_written.any()
            && !self.offsets_written.moved
            && self.offsets_written.shifted == 0
            && !self.offsets_written.unread.is_empty()
            && !self.shifts_on()
            && !self.frames_on()
            && self.transformed.is_none()
            && !self.units_unknown
            // (a work offset's variable written in the program, review 62a F1)
            && !self.offset_variable_written
        {
            self.offsets_lost = false;
        }
    }

    /// The axes (their places' bits) of each of G54-G59 a G10 block may write, and the
    /// values it writes where they are known ([`Checker::offsets_written`]). A tool
    /// offset's (FANUC L10-L13 and L1, L3 its tool life data; Haas L1, L10-L12; LinuxCNC L1,
    /// L10, L11) writes none; L2 writes the axes it names (all, with a LinuxCNC rotation R)
    /// of the offset its P names, P1-P6 being G54-G59; a FANUC's or a Haas's L20 writes an
    /// additional offset (G54.1 Pn, G154 Pn), none of G54-G59, a LinuxCNC's the one its P
    /// names as L2 does, and its P7-P9 the G59.1-G59.3 the profile does not give. Anything
    /// else (P0, the external or the current offset; an L or P not known; FANUC L50,
    /// parameters) may write them all; so may one whose L or P is a #-expression, read once
    /// though its program may run it with other values, where that program is called or
    /// jumps back ([`Checker::g10_expression`]). The value an L2 writes is
    /// known where each of its words is a number (no #-expression), under G90 (under G91 a
    /// FANUC's, a Haas's and a LinuxCNC's L2 adds it to the offset) and on a mill (a lathe's
    /// X a diameter); a LinuxCNC L20 sets the offset so that the position in force becomes
    /// the value written: not known here.
    /// Sources: FANUC 0i-MF Operator's Manual "Changing workpiece coordinate system" (G10
    /// L2 Pp: absolute or incremental by G90/G91) and "Additional workpiece coordinate
    /// systems" (G10 L20 Pn); Haas Mill Operator's Manual, G10 Set Offsets (G90/G91);
    /// LinuxCNC G-code reference, G10 L1/L2/L10/L11/L20.
    #[cold]
    #[inline(never)]
    fn g10_writes(&self, b: &BlockView<'_>) -> Written {
        let word = |letter: u8| {
            b.words
                .iter()
                .position(|w| w.letter == letter && w.index.is_empty())
        };
        let value = |letter: u8| {
            word(letter)
                .and_then(|i| self.readable[i])
                .filter(|v| v.is_whole())
                .map(|v| v.trunc())
        };
        let linuxcnc = self.config.family == Family::LinuxCnc;
        let rotation = word(b'R').is_some();
        let axes = if rotation {
            u16::MAX
        } else {
            b.words
                .iter()
                .filter(|w| w.index.is_empty())
                .filter_map(|w| crate::modal::axis_index(w.letter))
                .fold(0, |bits, i| bits | 1 << i)
        };
        // (LinuxCNC: P0 is the system in force, interp_convert.cc `convert_setup`)
        let p_in_force = |p: Option<i64>| match (p, self.work) {
            (Some(0), Some(w @ 54..=59)) if linuxcnc => Some(w - 53),
            _ => p,
        };
        match (value(b'L'), p_in_force(value(b'P'))) {
            (Some(1 | 3 | 10..=13), _) => Written::default(),
            (Some(20), _) if !linuxcnc => Written::default(),
            (Some(2 | 20), Some(7..=9)) if linuxcnc => Written::default(),
            (Some(l @ (2 | 20)), Some(p @ 1..=6)) => {
                let g = p as usize - 1;
                let mut writes = Written::default();
                writes.axes[g] = axes;
                writes.values[g] = [f64::NAN; 9];
                // (after a jump, condition or loop of its program the G10 may not run, or
                // another may run instead: review 59a F2)
                let known = l == 2
                    && !self.jumped
                    && !rotation
                    && !self.machine.state.incremental
                    && !self.config.diameter
                    && b.words.iter().all(|w| w.expression.is_empty());
                if !known && l == 2 && b.words.iter().all(|w| w.expression.is_empty()) {
                    // (after a jump or condition: the value before or the one written)
                    if let Some(alt) = self.g10_numbers(b) {
                        let g10 = Written::maybe_every(axes, Some(alt));
                        writes.maybe[g] = g10.maybe[g];
                        writes.alt[g] = alt;
                    }
                }
                if known {
                    let factor = self.to_profile_units(false);
                    for (k, w) in b.words.iter().enumerate() {
                        let i = w
                            .index
                            .is_empty()
                            .then(|| crate::modal::axis_index(w.letter))
                            .flatten()
                            .filter(|&i| i < 9);
                        if let (Some(i), Some(v)) = (i, self.readable[k]) {
                            writes.values[g][i] = v.to_f64() * factor;
                        }
                    }
                }
                writes
            }
            // (an L2 or L20 of a P not known, or P0, the external offset: the axes it
            // names of any offset, or of every one)
            (Some(2), None) => Written::maybe_every(axes, self.g10_numbers(b)),
            (Some(2 | 20), _) => Written::on_every(axes),
            _ => Written::ALL,
        }
    }

    /// The values (the profile's units) a G10 L2's axis words write, where each is a number
    /// (no #-expression), under G90, on a mill, with no rotation: NaN on an axis it does not
    /// name ([`Written::maybe`]).
    fn g10_numbers(&self, b: &BlockView<'_>) -> Option<[f64; 9]> {
        let literal = b.words.iter().all(|w| {
            w.letter == b'L'
                || w.letter == b'P'
                || w.letter == b'G'
                || w.letter == b'N'
                || w.expression.is_empty()
        });
        let rotation = b
            .words
            .iter()
            .any(|w| w.letter == b'R' && w.index.is_empty());
        if !literal || rotation || self.machine.state.incremental || self.config.diameter {
            return None;
        }
        let factor = self.to_profile_units(false);
        let mut values = [f64::NAN; 9];
        for (k, w) in b.words.iter().enumerate() {
            let i = w
                .index
                .is_empty()
                .then(|| crate::modal::axis_index(w.letter))
                .flatten()
                .filter(|&i| i < 9);
            if let Some(i) = i {
                values[i] = self.readable[k]?.to_f64() * factor;
            }
        }
        Some(values)
    }

    /// The place in [`crate::modal::AXES`] of the axis a work offset system variable's
    /// `j`-th (0 the first) names, where it can be named surely: FANUC Custom Macro B and
    /// a Haas ("System variables", #5221 + 20 * (n - 1) + (axis - 1), the control's axes
    /// in order) on a profile whose travel names X, Y and Z, a mill's first three; its 4th
    /// and later the profile's other axes in its order; LinuxCNC's parameters X Y Z A B C
    /// U V W (its 10th, #5230, the rotation: none). None: every axis of the offset.
    fn variable_axis(&self, j: usize) -> Option<usize> {
        if self.config.family == Family::LinuxCnc {
            return b"XYZABCUVW"
                .get(j)
                .and_then(|&l| crate::modal::axis_index(l));
        }
        let named = |l: u8| self.config.travel.iter().any(|t| t.0 == l);
        if self.config.diameter || !(named(b'X') && named(b'Y') && named(b'Z')) {
            return None;
        }
        if j < 3 {
            return crate::modal::axis_index(b"XYZ"[j]);
        }
        self.config
            .travel
            .iter()
            .filter(|t| !matches!(t.0, b'X' | b'Y' | b'Z'))
            .nth(j - 3)
            .and_then(|t| crate::modal::axis_index(t.0))
            .filter(|_| self.config.travel.len() >= 4)
    }

    /// What a work offset system variable's assignment (`w`, its number `number`, of offset
    /// G54-G59 `g`, every one where None) writes: the axis it names with the value where
    /// it is a number surely run (as [`Checker::g10_writes`]'s G10 L2 P2 X-150.), the
    /// axis alone not known where its value is not; every axis of the offset not known
    /// where the axis cannot be named. A value known that the positions cannot be judged
    /// with loses the offsets as a G10's does. LinuxCNC applies a write of the offset in
    /// force at its next selection only (rs274): not known there, the value held for that
    /// selection ([`Checker::linuxcnc_pending`]).
    #[cold]
    #[inline(never)]
    pub(super) fn variable_writes(
        &mut self,
        w: &crate::word::Word<'_>,
        g: Option<usize>,
        number: Option<u32>,
        line: usize,
    ) -> Written {
        if self.units_merged.is_some() {
            self.units_merged_stopped();
        }
        if self.linuxcnc_flow_work.is_some() {
            self.linuxcnc_flow_touched(line);
        }
        let axis = g
            .zip(number)
            .and_then(|(_, n)| self.variable_axis((n as usize - 5221) % 20))
            .filter(|&i| i < 9);
        let (Some(g), Some(i)) = (g, axis) else {
            let writes = Written::unknown_of(g);
            // (a write held for the system in force that this one may replace: not known
            // either; review 76 N2, `#5241=-200` / `#[5241]=0` under G55 loads 0)
            if self
                .linuxcnc_pending
                .as_ref()
                .is_some_and(|p| g.is_none_or(|g| g == p.0))
            {
                self.linuxcnc_pending = None;
            }
            // (an index not known may name any variable, `#[#14]=#0` of a macro's table:
            // the spans read on, as before)
            if number.is_some() {
                self.variable_spans(w, (1 << 9) - 1, line);
            }
            return writes;
        };
        self.variable_spans(w, 1 << i, line);
        let mut writes = Written::default();
        writes.axes[g] = 1 << i;
        writes.values[g] = [f64::NAN; 9];
        let in_force = self.work == Some(54 + g as i64);
        let linuxcnc = self.config.family == Family::LinuxCnc;
        if w.expression.is_empty() && !self.jumped {
            let text = [w.sign, w.number].concat();
            if let Some(v) = std::str::from_utf8(&text).ok().and_then(Dec::parse) {
                writes.values[g][i] = v.to_f64() * self.to_profile_units(false);
            }
        } else if linuxcnc && !self.jumped && self.linuxcnc_open_flow.is_empty() {
            // (LinuxCNC: `#5241=[-200]`, `#5241=#1` where the value is known, read with the
            // values from before the line as rs274 reads it: review 75 N1)
            let value = self
                .copied(w.expression, &mut None)
                .or_else(|| self.linuxcnc_evaluated(w.expression));
            if let Some(v) = value {
                writes.values[g][i] = v.to_f64() * self.to_profile_units(false);
            }
        }
        // (rs274 sets a line's parameters before it runs its codes: a write of the system
        // the same line selects from another is loaded by that selection; review 75 N1,
        // `G54` / `G55 #5241=-200` / `G0 X-650` runs at -850)
        if in_force && linuxcnc && self.linuxcnc_selected_at == line && self.linuxcnc_selected_maybe
        {
            // (selected from a system not known: loaded or not, not known here; the value
            // written held for the next selection from another all the same, review 76 F7)
            self.linuxcnc_hold(g, i, writes.values[g][i]);
            writes.values[g][i] = f64::NAN;
        } else if in_force && linuxcnc && self.linuxcnc_selected_at != line {
            // (the system in force keeps its value until it is selected again from another:
            // not known here, the value written held for that selection)
            self.linuxcnc_hold(g, i, writes.values[g][i]);
            // (until then the system runs under its value before the write: nothing written
            // now; review 76 F1, `G55` / `#5241=-150` / `G0 X-700` runs at -800 under the
            // profile's -100)
            writes.axes[g] &= !(1 << i);
            writes.values[g][i] = f64::NAN;
        } else if g == 0 && self.linuxcnc_at_start() {
            // (before the program's first selection, a write of G54: rs274 starts in G54
            // and loads it at no G54 after (`#5221=-300` / `G54` / `G0 X-500` runs at -500 in
            // `rs274 -g`), but LinuxCNC starts in the system it persisted (#5220), from which
            // a G54 would load it: held as for the system in force, not known at a first G54
            // (`linuxcnc_reselected`); review 76-lcnc76b N5)
            self.linuxcnc_hold(g, i, writes.values[g][i]);
            writes.axes[g] &= !(1 << i);
            writes.values[g][i] = f64::NAN;
        }
        if !writes.values[g][i].is_nan() && !self.g10_followed(&writes, false) {
            self.offsets_rewritten(line, "a work offset's system variable sets offsets");
        }
        writes
    }

    /// LinuxCNC selects work offset G`g` (54-59) where the parameter write of the system in
    /// force waits ([`Checker::linuxcnc_pending`]): selected from another, that system's
    /// values written are its values from here on, for its next selection (rs274: `G55` /
    /// `#5241=-200` / `G54` / `G55` / `G0 X-700` runs at machine -900), where they are
    /// known and the offsets are followed; its own selection again changes nothing.
    #[cold]
    #[inline(never)]
    fn linuxcnc_reselected(&mut self, g: i64, at_start: bool) {
        // (the program's first selection, a write of G54 held: rs274 starts in G54, LinuxCNC
        // in the system it persisted (#5220); a G54 may load it or not, another surely
        // leaves G54 with it for its next selection; review 76-lcnc76b N5)
        if at_start && self.linuxcnc_pending.as_ref().is_some_and(|p| p.0 == 0) {
            if g == 54 {
                // (the value before the write, rs274 -g's, or the one written: a position
                // beyond under both is said, `Checker::offset_either`; review 77-lcnc77a F5)
                let (axes, held) = self
                    .linuxcnc_pending
                    .as_ref()
                    .map_or((0, [f64::NAN; 9]), |p| (p.1, p.2));
                let mut either = Written::default();
                either.values[0] = [f64::NAN; 9];
                either.axes[0] = axes;
                for (i, &v) in held.iter().enumerate() {
                    if axes & 1 << i != 0 && !v.is_nan() {
                        either.maybe[0] |= 1 << i;
                        either.alt[0][i] = v;
                    }
                }
                self.offsets_written.then(&either);
                self.offset_writer(&either, false);
            } else {
                self.linuxcnc_start_left();
            }
            return;
        }
        if self.work != Some(g) {
            self.linuxcnc_pending_applied();
        }
    }

    /// LinuxCNC: the block's M70 or M73 saves the work system in force (before the block's
    /// own G54-G59 runs), its M71 makes the save not valid, its M72 restores the one saved
    /// (rs274: `G54` / `M70` / `G55` / `M72` / `G0 X-700` runs under G54, SET_G5X_OFFSET(1)
    /// at the M72; a write of the system restored held for it is loaded there as at a
    /// selection, review 75 N1). A save in a condition, a loop or a definition, or one not
    /// known, leaves the system after the M72 not known. Whether the block has an M72 with a
    /// G54-G59 of its own: rs274 2.9.0 drops that selection (`M72 G55` runs under the system
    /// restored), so the system after it is taken as not known.
    #[cold]
    #[inline(never)]
    fn linuxcnc_work_saved(&mut self, b: &BlockView<'_>) -> bool {
        let mut selects = false;
        let mut m7 = None;
        for (i, w) in b.words.iter().enumerate() {
            let Some(v) = self.readable[i].filter(|_| w.index.is_empty()) else {
                if w.letter == b'M' {
                    // (an M code of a value not known: any of them)
                    m7 = Some(0);
                }
                continue;
            };
            match (w.letter, v.to_f64()) {
                (b'M', m) if (70.0..=73.0).contains(&m) && v.is_whole() => m7 = Some(m as i64),
                (b'G', g) if (54.0..60.0).contains(&g) => selects = true,
                _ => {}
            }
        }
        let in_order = self.open_definition.is_none() && self.linuxcnc_open_flow.is_empty();
        match m7 {
            Some(70 | 73) => self.linuxcnc_work_save = Some(self.work.filter(|_| in_order)),
            Some(71) => self.linuxcnc_work_save = None,
            Some(72) => {
                let saved = self.linuxcnc_work_save.flatten().filter(|_| in_order);
                if saved.is_none() || saved != self.work {
                    // (the system may change here; review 76-calls76 F3, F9)
                    self.work_changed();
                }
                match saved {
                    Some(g) if self.work != Some(g) && !self.offsets_lost => {
                        self.work_selected(g, b.line)
                    }
                    Some(_) => {}
                    None => self.linuxcnc_restore_selected(b.line),
                }
                return selects;
            }
            Some(_) => {
                self.linuxcnc_work_save = Some(None);
                if in_order {
                    self.linuxcnc_restore_selected(b.line);
                }
            }
            None => {}
        }
        false
    }

    /// LinuxCNC: an M72 restores a work system not known here (or drops its block's own
    /// G54-G59): the positions after it are not judged until a G54-G59 is selected again.
    #[cold]
    #[inline(never)]
    fn linuxcnc_restore_selected(&mut self, line: usize) {
        if self.config.work_offsets.is_empty() || self.offsets_lost || self.work.is_none() {
            return;
        }
        self.linuxcnc_pending = None;
        self.work = None;
        self.linuxcnc_work_selected = true;
        self.travel_not(format!(
            "from line {line} on: M72 restores a work system not known here, until a G54-G59 \
             is selected again"
        ));
    }

    /// LinuxCNC: an o-word line of the main program's conditions and loops alone (`if`,
    /// `elseif`, `else`, `endif`, `do`, `while`, `endwhile`, `repeat`, `endrepeat`): the
    /// offsets are not lost there as at a jump or call, the positions inside the blocks open
    /// are not judged (the system in force may be another where a line inside runs and one
    /// before it not), and where the last closes, the system before is back, where no line
    /// inside touched the offsets ([`Checker::linuxcnc_flow_touched`]; review 75 N1: `G55` /
    /// `#5241=-200` / `o1 if [#1 GT 0]` / `M0` / `o1 endif` / `G54` / `G55` / `G0 X-650` runs
    /// at -850). Whether the line is one.
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_flow_offsets(&mut self, b: &BlockView<'_>) -> bool {
        if self.config.family != Family::LinuxCnc
            || self.config.work_offsets.is_empty()
            || self.offsets_lost
            || self.open_definition.is_some()
            || b.statements.is_empty()
        {
            return false;
        }
        let flow = b.statements.iter().all(|&(_, kind, text)| {
            kind == crate::statement::Kind::Flow
                && crate::statement::o_keyword(text).is_some_and(|k| {
                    matches!(
                        k.as_slice(),
                        b"if"
                            | b"elseif"
                            | b"else"
                            | b"endif"
                            | b"do"
                            | b"while"
                            | b"endwhile"
                            | b"repeat"
                            | b"endrepeat"
                    )
                })
        });
        if !flow {
            return false;
        }
        if self.linuxcnc_open_flow.is_empty() {
            if let Some(work) = self.linuxcnc_flow_work.take() {
                self.work = work;
            }
        } else if self.linuxcnc_flow_work.is_none() {
            self.linuxcnc_flow_work = Some(self.work);
            self.work = None;
            self.may_opened();
        }
        true
    }

    /// LinuxCNC: a line inside the main program's condition or loop that may change the
    /// offsets (a G10, G52, G92, G54-G59, M70-M73 or a work offset's parameter write, `why`):
    /// it may run or not, so the offsets are lost from here, as at a jump
    /// ([`Checker::linuxcnc_flow_offsets`]).
    #[cold]
    #[inline(never)]
    pub(super) fn linuxcnc_flow_touched(&mut self, line: usize) {
        self.linuxcnc_flow_work = None;
        self.may_touched();
        self.offsets_rewritten(
            line,
            "a work offset's code in a condition or loop the checker does not follow",
        );
    }

    /// LinuxCNC selects G59.1-G59.3 (`code`), a system the profile does not give: the
    /// positions under it are not known until a G54-G59 is selected again; the writes held
    /// for the system left are its values from here ([`Checker::linuxcnc_reselected`]).
    #[cold]
    #[inline(never)]
    fn linuxcnc_other_system(&mut self, line: usize, code: &str) {
        if self.config.work_offsets.is_empty() || self.offsets_lost {
            return;
        }
        // (a definition read apart that selects one changes its callers' system)
        self.work_changed();
        if self.linuxcnc_at_start() {
            self.linuxcnc_start_left();
        }
        self.linuxcnc_pending_applied();
        self.linuxcnc_other_in_force = true;
        self.linuxcnc_work_selected = true;
        if self.work.is_some() {
            self.work = None;
            self.travel_not(format!(
                "from line {line} on: {code} selects a work system the profile does not give, \
                 until a G54-G59 is selected again"
            ));
        }
    }

    /// LinuxCNC: no work system selected or restored yet, the one in force that LinuxCNC
    /// persisted (#5220; G54 in `rs274 -g`).
    fn linuxcnc_at_start(&self) -> bool {
        !self.linuxcnc_work_selected
            && self.work.is_none()
            && self.config.family == Family::LinuxCnc
            && self.open_definition.is_none()
    }

    /// LinuxCNC: the program's first selection is of a system other than G54: the writes of
    /// G54 held since the start are its values from here ([`Checker::linuxcnc_pending_applied`]).
    fn linuxcnc_start_left(&mut self) {
        if self.linuxcnc_pending.as_ref().is_some_and(|p| p.0 == 0) {
            self.work = Some(54);
            self.linuxcnc_pending_applied();
            self.work = None;
        }
    }

    /// LinuxCNC: the value `v` written to axis `i` of work system `g` (0 = G54), the one in
    /// force, held for its next selection from another ([`Checker::linuxcnc_pending`]; a
    /// write of another system held before is given up).
    fn linuxcnc_hold(&mut self, g: usize, i: usize, v: f64) {
        let pending = self
            .linuxcnc_pending
            .get_or_insert_with(|| Box::new((g, 0, [f64::NAN; 9])));
        if pending.0 != g {
            **pending = (g, 0, [f64::NAN; 9]);
        }
        pending.1 |= 1 << i;
        pending.2[i] = v;
    }

    /// The parameter writes of the system in force held for its next selection
    /// ([`Checker::linuxcnc_pending`]) take effect: its values from here on, where the
    /// system is still the one in force and the offsets are followed.
    #[cold]
    #[inline(never)]
    fn linuxcnc_pending_applied(&mut self) {
        let Some(p) = self.linuxcnc_pending.take() else {
            return;
        };
        let (from, axes, values) = *p;
        if self.work != Some(54 + from as i64) {
            return;
        }
        let mut writes = Written::default();
        writes.values[from] = [f64::NAN; 9];
        let mut unknown = writes.clone();
        for (i, &v) in values.iter().enumerate() {
            if axes & 1 << i != 0 && !v.is_nan() {
                writes.axes[from] |= 1 << i;
                writes.values[from][i] = v;
            } else if axes & 1 << i != 0 {
                unknown.axes[from] |= 1 << i;
            }
        }
        // (a value not known loaded: that axis is not known from here, its span running on
        // as before; review 76 F4, `G55` / `#5241=#1` / `G54` / `G55` / `G0 X-700` loads #1)
        if unknown.any() {
            self.offsets_written.then(&unknown);
            self.offset_writer(&unknown, false);
        }
        if self.g10_followed(&writes, false) {
            self.offsets_written.then(&writes);
            self.offset_writer(&writes, false);
            // (the positions since the write were of an offset not known: the span of each
            // axis now known starts again here, as at a G10 of it; review 75 N4: `G55` /
            // `#5241=-300` / `G0 X-650` / `G54` / `G55` / `G0 X1000` runs at -750 and 700)
            for a in 0..9 {
                if writes.axes[from] & 1 << a != 0 {
                    self.restart_span(a, false);
                }
            }
            self.shifts.settle();
        }
    }

    /// A work offset system variable's write (`w`) of `axes` (their places' bits) may set
    /// the offset of the work system in force: their spans start again, as at a G10
    /// (`G0 X850.` / `#5241=150.` / `G0 X-700.` under G55 is no span of 1550).
    fn variable_spans(&mut self, w: &crate::word::Word<'_>, axes: u16, line: usize) {
        let mut lost = 0u16;
        for a in 0..9 {
            if axes & 1 << a != 0 && self.restart_span(a, false) {
                lost |= 1 << a;
            }
        }
        self.shifts.settle();
        if lost != 0 {
            let why = "it may set the offset of the work system in force";
            self.shift_note(&w.token(), lost, (line, w.column), why);
        }
    }

    /// A G10 whose writes of G54-G59 are all of values known (`g10_writes`: an L2 P1-P6 of
    /// numbers under G90, surely run), with the profile's offsets in force before it: the
    /// program's own positions after it are judged with the values written (review 59a,
    /// F8: `G90 G55` / `G10 L2 P2 X-200.` / `G0 X-700.` runs at -900, and was not compared).
    /// Not where the offset in force is one guessed for a program read apart, or the
    /// coordinates were moved: those lose the profile's offsets as before.
    #[cold]
    #[inline(never)]
    fn g10_followed(&self, writes: &Written, expression: bool) -> bool {
        !expression
            && self.writes_followed(writes)
            && (0..6).all(|g| {
                (0..9).all(|i| writes.axes[g] & 1 << i == 0 || !writes.values[g][i].is_nan())
                    && writes.axes[g] >> 9 == 0
            })
    }

    /// Whether the offsets' writes `writes` (some, every one read) fall where the offsets are
    /// followed: not lost, not a program read apart's guessed offset, not one run on from
    /// another program, the coordinates not moved ([`Checker::g10_followed`],
    /// [`Checker::linuxcnc_g10_axes`]).
    fn writes_followed(&self, writes: &Written) -> bool {
        !self.offsets_lost
            && self.work_guessed.is_none()
            && !self.work_run_on
            && !self.offsets_written.moved
            && writes.any()
            && writes.unread.is_empty()
    }

    /// LinuxCNC: a G10 L2/L20 of one system (P1-P6, or P0, the system in force) whose
    /// values are not all known (an L20's: where the tool stands) in a program whose offsets
    /// are followed: only the axes it names are not known from here on, the other axes of
    /// that system keep theirs (rs274 writes only the axes named, interp_convert.cc
    /// `convert_setup`; review 75 N1: `G55` / `G10 L20 P2 Y0` / `G0 X-900` runs at -1000).
    #[cold]
    #[inline(never)]
    fn linuxcnc_g10_axes(&self, writes: &Written, expression: bool) -> bool {
        self.config.family == Family::LinuxCnc
            && !expression
            && !self.jumped
            && self.writes_followed(writes)
            && writes.shifted == 0
            && (0..6).all(|g| writes.axes[g] >> 9 == 0 && writes.maybe[g] == 0)
            && (0..6).filter(|&g| writes.axes[g] != 0).count() == 1
    }

    /// Whether a G10's L or P is a #-expression whose value here may not be the one another
    /// run of it has (`.0`: another call may give it another value, [`Checker::g10_expression`]),
    /// or one whose value the parameter reading knows from the program's own local variables
    /// #1-#33 alone (`.1`: the same at every call, set in the program before the G10; only a
    /// jump back may change it, [`Checker::g10_local`]). A local is a call's argument or the
    /// program's own (FANUC Custom Macro B "Types of variables": #1-#33 local, cleared at each
    /// call; a Haas's the same): known here only where the program set it (review 59a F4:
    /// `#5=1` / `G10 L2 P#5 X0.` writes G54 where called, not every offset).
    fn g10_expression_of(&self, b: &BlockView<'_>) -> (bool, bool) {
        let (mut unknown, mut local) = (false, false);
        for (k, w) in b.words.iter().enumerate() {
            if !matches!(w.letter, b'L' | b'P') || !w.index.is_empty() || w.expression.is_empty() {
                continue;
            }
            let known = !matches!(self.config.family, Family::LinuxCnc | Family::Sinumerik)
                && self.readable[k].is_some()
                && locals_only(w.expression);
            if known {
                local = true;
            } else {
                unknown = true;
            }
        }
        (unknown, local)
    }

    /// The program in hand may write work offsets G54-G59 (`writes`, after what it wrote
    /// before), or lose the profile's (`loses`): [`Checker::offset_writers`].
    pub(super) fn offset_writer(&mut self, writes: &Written, loses: bool) {
        // (after the main program's first jump: callflow.rs; a call of a program not read
        // there, `unread` alone, is followed there)
        if self.flow_calls.is_some()
            && (loses
                || writes.any()
                || writes.moved
                || writes.shifted != 0
                || writes.maybe.iter().any(|m| *m != 0))
        {
            self.flow_spoiled();
        }
        if let Some(n) = self.in_hand {
            let entry = self.offset_writers.entry(n).or_default();
            entry.0.then(writes);
            entry.1 |= loses;
        }
    }

    /// Note once why a position was not compared as a machine position.
    pub(super) fn travel_not(&mut self, why: String) {
        if !self.stats.travel_not.contains(&why) {
            self.stats.travel_not.push(why);
        }
    }

    /// What the block does to the work offset in force: a plain G54-G59 selects one of the
    /// profile's; G10 (offsets set), G52 and G92 with axis words (shifts), an extended offset
    /// (G54.1, G154, Sinumerik G505-G599) and Sinumerik frames make the profile's values
    /// unknown for good; a tool length offset by a decimal code is noted. Whether the
    /// block's positions can be compared as machine positions (not a G53/G153/SUPA block).
    /// (The profile's test inlined where it is asked, once a block; the work out of line:
    /// most profiles give no work offsets.)
    #[inline]
    pub(super) fn work_offset(&mut self, b: &BlockView<'_>) -> bool {
        if self.config.work_offsets.is_empty() {
            return false;
        }
        self.work_offset_given(b)
    }

    /// [`Checker::work_offset`] under a profile that gives work offsets.
    #[inline(never)]
    fn work_offset_given(&mut self, b: &BlockView<'_>) -> bool {
        let line = b.line;
        // (a block a jump back may arrive at: Checker::selection_reexpressed)
        self.numbered |= self.letters & bit(b'N') != 0;
        if self.reexpressed_held.is_some() {
            self.reexpression_held(b);
        }
        if self.units_merged.is_some() && self.letters & bit(b'G') != 0 {
            let changes = b.words.iter().enumerate().any(|(i, w)| {
                w.letter == b'G'
                    && self.readable[i]
                        .is_some_and(|v| matches!(v.to_f64() as i64, 10 | 52 | 92 | 54..=59))
            });
            if changes {
                self.units_merged_stopped();
            }
        }
        let sinumerik = self.config.family == Family::Sinumerik;
        let axes = crate::modal::axis_places(self.values.given()) != 0;
        let mut one_shot = false;
        let lost = self.offsets_lost;
        if self.linuxcnc_flow_work.is_some() {
            let touches = b.words.iter().enumerate().any(|(i, w)| match w.letter {
                b'G' => self.readable[i].is_none_or(|v| {
                    // (G7/G8, a diameter mode, read as the positions' scale: review 76 F5)
                    matches!(v.trunc(), 7 | 8 | 10 | 52 | 92 | 54..=59)
                        || !v.is_whole() && v.trunc() == 92
                }),
                b'M' => self.readable[i].is_none_or(|v| matches!(v.trunc(), 70..=73)),
                _ => false,
            });
            if touches {
                self.linuxcnc_flow_touched(line);
            }
        }
        // (LinuxCNC's M70-M73 save and restore the work system, before the block's own
        // G54-G59 in the order of execution)
        let restored = self.config.family == Family::LinuxCnc && self.letters & bit(b'M') != 0 && {
            self.linuxcnc_work_saved(b)
        };
        // (only a G code selects, sets or suppresses an offset)
        let g_words = if self.letters & bit(b'G') != 0 {
            b.words
        } else {
            &[]
        };
        for (i, w) in g_words.iter().enumerate() {
            // (the letter before the value: a 32-byte `Option<Dec>` read for a G word only)
            if w.letter != b'G' {
                continue;
            }
            let Some(v) = self.readable[i] else {
                // (a G code not known here, `G#2`, `G[54]` after the parameters were
                // forgotten: it may select or set anything; callflow.rs)
                self.flow_g_unknown();
                continue;
            };
            if !v.is_whole() {
                match v.trunc() {
                    43 | 44 => self.length_decimal = true,
                    // G51.1: a programmable mirror image (Fanuc)
                    51 if self.config.family != Family::Sinumerik => {
                        self.lose_offsets(line, &format!("{} mirrors the coordinates", w.token()))
                    }
                    // LinuxCNC's G59.1-G59.3 (another system, not the profile's): the
                    // positions under it are not known, G54-G59's values stay as they are,
                    // a write of the system left held loaded (interp_convert.cc
                    // `convert_coordinate_system`; review 75 N1: `G55` / `#5241=-200` /
                    // `G59.1` / `G55` / `G0 X-650` runs at -850)
                    59 if self.config.family == Family::LinuxCnc
                        && v.normalized().scale == 1
                        && matches!(v.normalized().mantissa, 591..=593) =>
                    {
                        self.linuxcnc_other_system(line, &w.token())
                    }
                    // (another offset selected: no G54-G59 position moved, review 59a c13)
                    54..=59 => self.offsets_rewritten(
                        line,
                        &format!("{} selects an offset the profile does not give", w.token()),
                    ),
                    _ => {}
                }
                continue;
            }
            match v.trunc() {
                49 => {
                    self.length_decimal = false;
                    self.flow_spoiled();
                }
                // (after the main program's first jump: callflow.rs)
                43 | 44 if self.flow_calls.is_some() => self.flow_spoiled(),
                // (G91: the spans set aside at a selection join again, the increments from
                // a work position the selection changed; review 78-lcnc78b F1; not those
                // of the axes it re-expressed, Checker::selection_reexpressed)
                91 if self.spans_parked.is_some() => {
                    self.spans_unparked(ALL_PLACES & !self.moved_axes())
                }
                10 => {
                    let writes = self.g10_writes(b);
                    self.offsets_written.then(&writes);
                    // (LinuxCNC: a G10 L2/L20 of the system in force loads every axis of it
                    // from its parameters at once, interp_convert.cc `convert_setup`: the
                    // parameter writes waiting for its selection hold from here, those of
                    // the axes it writes replaced)
                    // (before the program's first selection, a G10 of G54 with a write of it
                    // held: rs274 -g, in G54, loads it there, a start in another system at
                    // the first G54: G54's values from here either way; review 77-lcnc77a F7)
                    if let Some(p) = self.linuxcnc_pending.as_mut() {
                        let g = p.0;
                        p.1 &= !writes.axes[g];
                        if writes.axes[g] != 0 && g == 0 && self.linuxcnc_at_start() {
                            self.linuxcnc_start_left();
                        } else if writes.axes[g] != 0 {
                            self.linuxcnc_pending_applied();
                        }
                    }
                    let (expression, local) = self.g10_expression_of(b);
                    let axes = writes.axes.iter().fold(0, |all, a| all | a);
                    if expression {
                        self.g10_expression |= axes;
                        // (an L2 written as a number: each offset its value or the one written)
                        let l2 = b.words.iter().enumerate().any(|(k, w)| {
                            w.letter == b'L'
                                && w.index.is_empty()
                                && w.expression.is_empty()
                                && self.readable[k] == Some(Dec::from_int(2))
                        });
                        let alt = self.g10_numbers(b).filter(|_| l2);
                        self.offset_writer(&Written::maybe_every(axes, alt), false);
                    } else {
                        if local {
                            self.g10_local |= axes;
                        }
                        self.offset_writer(&writes, false);
                    }
                    if !self.g10_followed(&writes, expression || local)
                        && !self.linuxcnc_g10_axes(&writes, expression || local)
                    {
                        self.offsets_rewritten(line, "G10 sets offsets");
                    }
                }
                // (a G52 moves the coordinates where it is not known to be zero: the axes
                // Written::shifted holds, not every value a G10 writes after it; review 60
                // F6: `G52 X0 Y0` / `G10 L2 P2 X-200.` runs X-700. under G55 at -900. A
                // G92's shift is where the tool stands, which a G54-G59 selected since its
                // last move changes: not followed so, every value held as before)
                52 if axes => {
                    let kept = self.shift_kept();
                    self.offsets_rewritten(line, &format!("{} shifts the coordinates", w.token()));
                    self.shift_work = kept;
                }
                92 if axes => {
                    // (a Haas's G92 works as Setting 33 says: not kept, resumed.rs)
                    let kept = self.shift_kept().filter(|_| !self.config.haas);
                    self.lose_offsets(line, &format!("{} shifts the coordinates", w.token()));
                    self.shift_work = kept;
                }
                // an Okuma mill's G53-G59 are its tool length offsets' cancel and axes (OSP
                // List of G Codes): no machine coordinates, no work system (G15 H selects it)
                53..=59 if self.config.family == Family::Okuma && !self.config.modal.lap => {}
                54..=57 => self.work_selected(v.trunc(), line),
                58 | 59 if !sinumerik => self.work_selected(v.trunc(), line),
                // an Okuma mill's G11 (parallel and rotation shift), G51 (scaling), G62
                // (mirror image), G69 (three-dimensional conversion): frame_bits
                11 | 51 | 62 | 69 if self.config.family == Family::Okuma => self.lose_offsets(
                    line,
                    &format!(
                        "{} shifts, rotates, scales or mirrors the coordinates",
                        w.token()
                    ),
                ),
                // rotation, scaling, polar coordinates, Haas's mirror image: a work position
                // is no longer the machine position plus the offset
                16 | 51 | 68 | 101 if !sinumerik && self.config.family != Family::Okuma => self
                    .lose_offsets(
                        line,
                        &format!(
                            "{} rotates, scales or mirrors the coordinates, or makes them polar",
                            w.token()
                        ),
                    ),
                // a Haas mill's feature coordinate system (G268): moves the coordinates by
                // words no stored page explains
                268 if self.config.haas => {
                    if !self.offsets_lost {
                        // said where the operator sees it, not only under --stats: the
                        // positions after it, G269 included, are no longer compared
                        let message = format!(
                            "{}: a feature coordinate system the checker does not follow: from \
                             here on no position is compared with the travel through the \
                             profile's work offsets (TG601), after G269 too (no source says \
                             whether G268 changes a stored offset), nor, until G269, the span \
                             of the positions under it",
                            w.token()
                        );
                        self.report(crate::rules::Rule::NotFollowed, message, line, w.column);
                    }
                    self.lose_offsets(
                        line,
                        &format!("{} sets a feature coordinate system", w.token()),
                    )
                }
                153 if sinumerik => one_shot = true,
                58 | 59 | 500..=599 if sinumerik => {
                    let why = format!("{} is an offset the profile does not give", w.token());
                    self.lose_offsets(line, &why);
                }
                154 => self.offsets_rewritten(
                    line,
                    &format!("{} selects an offset the profile does not give", w.token()),
                ),
                // a Haas mill's G110-G129: the additional work offsets #7-#26 (G154 P1-P20;
                // Haas Mill Operator's Manual, "G110-G129 Coordinate System #7-26"), none
                // of G54-G59 (review 76-calls76 F2: `G55` / `G110` / `G0 X-27.` was judged
                // under G55)
                110..=129 if self.config.haas => self.offsets_rewritten(
                    line,
                    &format!("{} selects an offset the profile does not give", w.token()),
                ),
                // G53: machine coordinates for the block; under ISO 6983-1 it cancels the
                // zero shift until the next G54-G59
                53 => {
                    one_shot = true;
                    if self.config.family == Family::Iso {
                        self.work = None;
                    }
                }
                _ => {}
            }
        }
        if restored && self.work.is_some() {
            self.linuxcnc_restore_selected(line);
        }
        one_shot |= self.frames(b);
        // (a program that shifts or sets the coordinates changes them where it is called)
        if self.offsets_lost && !lost {
            self.offset_writer(&Written::default(), true);
        }
        !one_shot && !self.offsets_lost
    }

    /// A frame turned on or off by the block's G codes, before its positions are read (a
    /// cancel applies to its own block's move: `G69 G00 Y20.`; the X Y Z of `G68 X Y R` and
    /// `G51 X Y Z P` are the centre, no move). TG601's span holds the positions in the
    /// coordinates before any frame, across its cancel: under a rotation or scaling whose
    /// words say exactly what it does (one at a time: `G68 X Y R` with the angle in degrees,
    /// a Haas `G51 X Y Z P` with the factor written with its point) each position is taken
    /// back through it; under one that cannot be known here (its angle or factor or the axes
    /// it scales from parameters, a three-dimensional rotation, Haas G268, G91, two at once),
    /// the axes it moves are left out of the spans until its cancel, said once as a note (a
    /// span compared with the wrong axis or size refuses a good program or passes a bad
    /// one); under polar coordinates the plane's axes hold no positions; under a mirror
    /// image the positions stand apart (a span of their own, the one before taken back at
    /// its cancel).
    #[inline]
    pub(super) fn turn_frames(&mut self, b: &BlockView<'_>) {
        // (only a G code turns a frame: the test inlined where it is asked, once a
        // block, the walk out of line)
        if self.frames.codes {
            self.turn_frames_walk(b);
        }
    }

    /// [`Checker::turn_frames`] of a block with such a code.
    #[inline(never)]
    fn turn_frames_walk(&mut self, b: &BlockView<'_>) {
        for (i, w) in b.words.iter().enumerate() {
            let Some(v) = self.readable[i].filter(|_| w.letter == b'G') else {
                continue;
            };
            let (on, off) = self.frame_bits_of(v);
            // (a G50.1 ends the mirror of the axes it names only: Checker::mirror_off)
            let mirror_on = off == 32
                && (self.frames.apart != 0
                    || self.frames.doubt != 0
                    || self.frames.map.as_ref().is_some_and(|map| map.bit == 32));
            if off != 0 && self.frames.on & off != 0 && !mirror_on {
                self.frame_off(off);
            }
            if on != 0 {
                self.frames.haas_mirror = self.config.haas && v.is_whole() && v.trunc() == 101;
                self.frame_on(on, b, w.token(), w.column);
            }
        }
    }

    fn frame_on(&mut self, on: u8, b: &BlockView<'_>, token: String, column: usize) {
        // (the increments under a frame move the machine's axes otherwise: the runs of
        // increments from positions not known, TG601's, start again; none is judged under it)
        self.machine.drift = Default::default();
        let place = on.trailing_zeros() as usize;
        let okuma = self.config.family == Family::Okuma;
        self.frames.moved[place] = false;
        let others = self.frames.on & !on;
        self.frames.on |= on;
        let (a, c) = plane_axes(self.machine.state.plane);
        let plane = (1u16 << a) | (1 << c);
        match on {
            2 | 4 | 8 => {
                let what = format!("{token} of line {}", b.line);
                let mirrored = self.frames.map.as_ref().is_some_and(|map| map.bit == 32);
                let exact = if others & (2 | 4 | 8) != 0 || mirrored {
                    Err("it turns inside another rotation, scaling or mirror image".to_string())
                } else if on == 8 && okuma {
                    Err("a 3-D coordinate system conversion the checker does not follow".into())
                } else if on == 8 {
                    Err("a feature coordinate system the checker does not follow".into())
                } else {
                    self.exact_frame(on == 4, b)
                };
                // a frame in force that was exact is no longer the whole of it
                if let Some(map) = self.frames.map.take() {
                    self.frames.hidden[map.bit.trailing_zeros() as usize] = XYZ;
                    self.frames.moved[map.bit.trailing_zeros() as usize] |= map.touched != 0;
                }
                match exact {
                    Ok((centre, m)) => {
                        // an axis the frame leaves as it is (Z under G17's rotation) stands
                        // where it stood
                        let fresh = (0..3)
                            .filter(|&k| (0..3).all(|l| m[k][l] == f64::from(u8::from(k == l))))
                            .fold(0u8, |all, k| all | 1 << k);
                        // an axis it moves about a centre not known here: left out, said
                        let unknown = (0..3)
                            .filter(|&k| fresh & 1 << k == 0 && centre[k].is_nan())
                            .fold(0u16, |all, k| all | 1 << k);
                        if unknown != 0 {
                            self.frames.hidden[place] = unknown;
                            let why = "its centre there is neither written nor the position \
                                       known here";
                            self.frame_not_applied(&token, unknown, (b.line, column), why);
                        }
                        self.frames.map = Some(Map {
                            bit: on,
                            centre,
                            m,
                            fresh,
                            touched: 0,
                            what,
                        })
                    }
                    Err(why) => {
                        // a plane's rotation moves its two axes; scaling, G268 and an
                        // Okuma's G11 (a parallel shift too) X Y Z
                        let two = on == 4
                            && !okuma
                            && !b.words.iter().any(|w| b"IJK".contains(&w.letter));
                        let axes = if two { plane } else { XYZ };
                        self.frames.hidden[place] = axes;
                        // (a G268 under the profile's work offsets has a note of its own,
                        // which says this too: Checker::work_offset)
                        let own = on == 8
                            && self.config.haas
                            && !self.config.work_offsets.is_empty()
                            && !self.offsets_lost;
                        if !own {
                            self.frame_not_applied(&token, axes, (b.line, column), &why);
                        }
                    }
                }
            }
            // polar coordinates: the plane's words are a radius and an angle
            1 => self.frames.hidden[place] = plane,
            // an Okuma's G62: neither its words nor its cancel are in a page at hand
            32 if okuma => {
                self.frames.hidden[place] = XYZ;
                self.frame_note(
                    &token,
                    XYZ,
                    (b.line, column),
                    "from here to the end of the file",
                    "an Okuma's programmable mirror image, whose words and cancel no page at hand \
                     gives",
                );
            }
            _ => {
                let exact_map = self.frames.map.as_ref().map(|map| map.bit == 32);
                // a G51.1 of an axis already mirrored: no page at hand says whether it moves
                // the point or mirrors the mirror (review 16b, finding 5), so its positions
                // stand apart, said
                let mirrored =
                    self.frames
                        .map
                        .as_ref()
                        .filter(|map| map.bit == 32)
                        .map_or(0, |map| {
                            (0..3)
                                .filter(|&k| map.m[k][k] == -1.0)
                                .fold(0u16, |all, k| all | 1 << k)
                        })
                        | self.frames.apart
                        | self.frames.doubt;
                // (a Haas's mirror is a setting per axis about one point, the work zero: a
                // second G101 of an axis leaves it mirrored as it was)
                let again = if on == 32 && !self.frames.haas_mirror {
                    Self::mirror_axes(b) & mirrored
                } else {
                    0
                };
                // (a Haas's G101 naming a doubtful axis plainly: mirrored for certain again)
                if self.frames.haas_mirror {
                    self.frames.doubt &= !self.mirror_words(b).0;
                }
                if again != 0 {
                    self.frame_note(
                        &token,
                        again,
                        (b.line, column),
                        "as one span with those before it, until its cancel",
                        "a second mirror image of an axis already mirrored, which no page at \
                         hand describes (a new point, or a mirror of the mirror)",
                    );
                }
                if on == 32
                    && again == 0
                    && others == 0
                    && exact_map != Some(false)
                    && self.frames.apart == 0
                {
                    if let Some((centre, m, fresh)) = self.exact_mirror(b) {
                        let what = format!("{token} of line {}", b.line);
                        match self.frames.map.as_mut() {
                            // a second G51.1 adds the axes it names (none mirrored
                            // already: `again`), each mirrored afresh where it stood
                            Some(map) => {
                                let already: [bool; 3] =
                                    std::array::from_fn(|k| map.m[k][k] == -1.0);
                                let mut added = false;
                                for k in (0..3).filter(|&k| m[k][k] == -1.0 && !already[k]) {
                                    map.touched &= !(1 << k);
                                    map.m[k][k] = -1.0;
                                    map.centre[k] = centre[k];
                                    map.fresh &= !(1 << k);
                                    added = true;
                                }
                                if added {
                                    map.what = what;
                                }
                            }
                            None => {
                                self.frames.map = Some(Map {
                                    bit: on,
                                    centre,
                                    m,
                                    fresh,
                                    touched: 0,
                                    what,
                                })
                            }
                        }
                        return;
                    }
                }
                // the axes whose mirror the block changes
                let mut changed = 0u16;
                if on == 32 {
                    // not exact here: the mirrored axes' positions stand apart, those of an
                    // exact mirror in force with them
                    if let Some(map) = self.frames.map.take_if(|map| map.bit == 32) {
                        for k in (0..3).filter(|&k| map.m[k][k] == -1.0) {
                            changed |= 1 << k;
                        }
                    }
                    let named = Self::mirror_axes(b);
                    let mirrors = if named == 0 { XYZ } else { named };
                    // (a Haas's second G101 of an axis apart leaves it mirrored as it was,
                    // about the same point: one span with the positions before it)
                    changed |= if self.frames.haas_mirror {
                        mirrors & !self.frames.apart
                    } else {
                        mirrors
                    };
                    self.frames.apart |= changed;
                    // (review 23) a FANUC G51.1 naming plainly an axis a doubtful cancel left
                    // in doubt: mirrored again (the cancel ended its mirror) or mirrored a
                    // second time (it did not), its positions from here are the ones written
                    // mirrored about one point whichever, each the same way (slope -1 or +1):
                    // a span of their own, as `again`'s, whose size both readings give alike
                    if !self.frames.haas_mirror {
                        self.frames.doubt &= !(self.mirror_words(b).0 & self.frames.apart);
                    }
                }
                // each axis the block mirrors anew keeps its span from before its mirror;
                // one mirrored already before this block (its span from before the mirror
                // kept) has its positions under the mirror before this block mirrored
                // otherwise than those after it: apart from them too. The other axes' spans
                // go on as they were (review 24, finding 1).
                if changed != 0 {
                    self.early_merge();
                    self.later_shift_closed();
                }
                for k in (0..AXES.len()).filter(|&k| changed & 1 << k != 0) {
                    if self.frames.saving & 1 << k == 0 {
                        self.frames.saved[k] = self.spans[k].take();
                        self.frames.saving |= 1 << k;
                    } else {
                        self.spans[k] = None;
                    }
                }
            }
        }
    }

    /// A mirror image about the points its block writes (`G51.1 X10.`: X about 10), under
    /// G90, of X Y Z alone: exact as a rotation is, each mirrored axis `2c - p` (review 14,
    /// finding 4: its positions apart missed a span past the travel). FANUC 16/18 Operator's
    /// Manual, "Programmable mirror image (G50.1, G51.1)": the axis words give the axis of
    /// symmetry. None where it is not exact here (the positions then stand apart).
    fn exact_mirror(&self, b: &BlockView<'_>) -> Option<([f64; 3], [[f64; 3]; 3], u8)> {
        // a Haas's G101 X0 mirrors X about the work coordinate zero point, whatever X's value
        // and under G91 too (Haas VF Series manual 96-8000, p. 201, G101: "Mirror image will
        // reflect programmed motion around your work coordinate zero point"; review 17): the
        // program's zero, unless a G52 or G92 shifted the coordinates
        let haas = self.frames.haas_mirror;
        if haas && self.frames.shifted
            || !haas && (!self.config.modal.centre_codes || self.machine.state.incremental)
        {
            return None;
        }
        let factor = self.to_profile_units(false);
        let mut centre = [0.0; 3];
        let mut m = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mut fresh = 0b111u8;
        for (i, w) in b.words.iter().enumerate() {
            if w.letter == b'G' || w.letter == b'N' {
                continue;
            }
            let k = AXES[..3].iter().position(|&a| a == w.letter)?;
            let value = self.readable[i]?;
            centre[k] = if haas { 0.0 } else { value.to_f64() * factor };
            m[k][k] = -1.0;
            fresh &= !(1 << k);
        }
        (fresh != 0b111).then_some((centre, m, fresh))
    }

    /// The block's cancels of the frames in force, as the state after it has them
    /// ([`Checker::take_back`]); read before the rules, which [`Checker::turn_frames`] is one
    /// of.
    /// (inlined where it is asked, twice a block's reading: the test of a frame in force and
    /// a frame code; the walk of the codes out of line)
    #[inline(always)]
    pub(super) fn cancel_frames(&mut self, b: &BlockView<'_>, before: &Before) {
        self.frames.codes = self.frame_codes();
        if self.frames.on == 0 || !self.frames.codes {
            return;
        }
        self.cancel_frames_of(b, before);
    }

    /// [`Checker::cancel_frames`] of a block with a frame code and a frame in force.
    #[inline(never)]
    fn cancel_frames_of(&mut self, b: &BlockView<'_>, before: &Before) {
        let mut done = 0u8;
        for (i, w) in b.words.iter().enumerate() {
            let Some(v) = self.readable[i].filter(|_| w.letter == b'G') else {
                continue;
            };
            let (_, off) = self.frame_bits_of(v);
            if off != 0 && self.frames.on & off & !done != 0 {
                done |= off;
                if off == 32 {
                    self.mirror_off(b, before, w.column);
                } else {
                    self.take_back(off, b, before, w.column, 0b111);
                }
            }
        }
    }

    /// The axes a mirror image's block names (bit `i` for `AXES[i]`): G51.1 mirrors them,
    /// G50.1 ends their mirror.
    fn mirror_axes(b: &BlockView<'_>) -> u16 {
        b.words
            .iter()
            .filter_map(|w| axis_index(w.letter))
            .fold(0, |all, i| all | 1 << i)
    }

    /// The axes a mirror image's block names with a value known here (plain) and with one
    /// not known (`X#1`: a parameter the checker does not follow), as bits of `AXES`.
    fn mirror_words(&self, b: &BlockView<'_>) -> (u16, u16) {
        b.words
            .iter()
            .enumerate()
            .filter_map(|(i, w)| axis_index(w.letter).map(|k| (i, k)))
            .fold((0, 0), |(plain, unknown), (i, k)| match self.readable[i] {
                Some(_) => (plain | 1 << k, unknown),
                None => (plain, unknown | 1 << k),
            })
    }

    /// G50.1 ends the mirror of the axes it names, the others stay mirrored (FANUC 16/18,
    /// "Programmable mirror image": `G50.1 IP_`, the axes whose mirror is cancelled; the
    /// SINUMERIK ISO dialect's `G50.1 X... Y... Z...`; review 15, finding 2): each of them is
    /// taken back as a rotation's axes are at its cancel ([`Checker::take_back`]), and the
    /// mirror ends with the last. A G50.1 that names no axis is taken to end them all (no
    /// page at hand says otherwise). A Haas's G100 is read the same way (96-8000, G101: the
    /// mirror selected per axis).
    /// An axis word whose value is not known here (`G100 X#1`) leaves that axis's mirror not
    /// known (issue 32, review 19 finding 1: it was read as ending X's mirror, while the
    /// restart calls it not known): the axis stands where the check does not know, and its
    /// positions are not compared with the travel ([`Frames::doubt`]) until a cancel names it
    /// plainly or names no axis at all. A block whose only axis words are such may be a cancel
    /// naming none (a vacant variable drops its address), so it leaves every mirrored axis so.
    fn mirror_off(&mut self, b: &BlockView<'_>, before: &Before, column: usize) {
        let (named, unknown) = self.mirror_words(b);
        let all = named == 0 && unknown == 0;
        self.frames.doubt &= if all { 0 } else { !named };
        // the mirrored axes the block may or may not end
        let exact_mirrored =
            self.frames
                .map
                .as_ref()
                .filter(|map| map.bit == 32)
                .map_or(0u16, |map| {
                    (0..3)
                        .filter(|&k| map.m[k][k] == -1.0)
                        .fold(0u16, |all, k| all | 1 << k)
                });
        // (review 22, finding 2) a block whose only axis words are not known here may be a
        // bare cancel: on Custom Macro B a vacant variable drops its address (Haas "Address
        // Substitution": `G00 X1.0 Z#1` with #1 undefined moves no Z; Mitsubishi M700V
        // user macro manual, 13.5), and a cancel naming no axis ends every mirror
        let maybe = if named == 0 && unknown != 0 {
            !0
        } else {
            unknown
        };
        let doubtful = (exact_mirrored | self.frames.apart) & maybe & !named;
        if doubtful != 0 {
            self.mirror_doubt(b, doubtful, column);
        }
        let Some(map) = self.frames.map.as_ref().filter(|map| map.bit == 32) else {
            let ending = if all { 0 } else { self.frames.apart & named };
            self.frames.apart &= if all { 0 } else { !named };
            // (the mirror stays in force while a doubtful axis's may: review 24)
            if (self.frames.apart != 0 || self.frames.doubt != 0) && ending != 0 {
                // (review 16b, finding 3) the axes whose mirror ends get their spans from
                // before it back; where the mirror left the tool on them is not known here,
                // so until an absolute position
                self.give_back(ending);
                for k in (0..3).filter(|&k| ending & 1 << k != 0) {
                    self.machine.forget_axis(AXES[k]);
                }
            }
            return;
        };
        let mirrored = (0..3)
            .filter(|&k| map.m[k][k] == -1.0)
            .fold(0u8, |all, k| all | 1 << k);
        let ending = if all {
            mirrored
        } else {
            mirrored & (named & XYZ) as u8
        };
        self.take_back(32, b, before, column, ending);
        let Some(map) = self.frames.map.as_mut() else {
            return;
        };
        for k in (0..3).filter(|&k| ending & 1 << k != 0) {
            map.m[k][k] = 1.0;
            map.centre[k] = 0.0;
            map.fresh |= 1 << k;
            map.touched &= !(1 << k);
        }
        if mirrored & !ending == 0 {
            self.frames.map = None;
        }
    }

    /// At the cancel of a rotation or scaling, the tool stands where the frame put it: the
    /// modal position (the frame's coordinates) becomes that point in the coordinates after
    /// the cancel, taken back through the exact frame (the cancel block's own absolute words
    /// stand as written, its increments add to the point); where the frame is not known here,
    /// or the tool's place in its coordinates was not, the axes it moves are unknown until an
    /// absolute position gives them, said once as a note. Haas "G68 Rotation" (Classic Mill
    /// Operator's Manual): G68 affects the positional values of the blocks after it, none
    /// after G69; Mitsubishi M700V, G68.1/G69.1 precautions: an absolute movement right after
    /// the cancel. Without it an increment after G69 adds to the frame's coordinate: a missed
    /// over-travel, a false TG403 on a correct arc (review 14, finding 1).
    /// `only`: the axes of an exact mirror image that its cancel ends ([`Checker::mirror_off`];
    /// all three for a rotation or scaling).
    fn take_back(&mut self, off: u8, b: &BlockView<'_>, before: &Before, column: usize, only: u8) {
        // (a mirror image only where it was exact: its positions apart otherwise)
        let exact_mirror = off == 32 && self.frames.map.as_ref().is_some_and(|map| map.bit == 32);
        if off & (2 | 4 | 8) == 0 && !exact_mirror {
            return;
        }
        let factor = self.to_profile_units(false);
        let old: [Option<f64>; 3] =
            std::array::from_fn(|k| before.xyz[k].map(|p| p.to_f64() * factor));
        let positions = matches!(self.machine.taken(), None | Some(AxesTaken::Positions));
        let absolute =
            |k: usize| positions && !self.machine.state.incremental && self.values.has(AXES[k]);
        let mut lost = 0u16;
        let mut now: [Option<Dec>; 3] = std::array::from_fn(|k| self.machine.state.position[k]);
        match self.frames.map.as_ref().filter(|map| map.bit == off) {
            Some(map) => {
                for k in 0..3 {
                    let made_of = (0..3)
                        .filter(|&l| map.m[k][l] != 0.0)
                        .fold(0u8, |all, l| all | 1 << l);
                    // an axis the frame leaves as it is, one whose axes never moved under
                    // it (where it stood before the frame), or the block's absolute word
                    if only & 1 << k == 0
                        || (made_of == 1 << k && map.m[k][k] == 1.0)
                        || made_of & map.touched == 0
                        || absolute(k)
                    {
                        continue;
                    }
                    let mut at = map.centre[k];
                    for l in (0..3).filter(|&l| made_of & 1 << l != 0) {
                        match old[l].filter(|_| map.fresh & 1 << l != 0) {
                            Some(p) => at += map.m[k][l] * (p - map.centre[l]),
                            None => at = f64::NAN,
                        }
                    }
                    // the cancel block's increment, on top of the point
                    let step = match (now[k], old[k]) {
                        (Some(p), Some(o)) => p.to_f64() * factor - o,
                        _ => f64::NAN,
                    };
                    now[k] = Some(at + step)
                        .filter(|v| v.is_finite())
                        .and_then(|v| Dec::parse(&format!("{:.6}", v / factor)));
                    if now[k].is_none() {
                        lost |= 1 << k;
                    }
                }
            }
            None => {
                let place = off.trailing_zeros() as usize;
                let moved = self.frames.moved[place];
                for k in (0..3).filter(|&k| moved && self.frames.hidden[place] & 1 << k != 0) {
                    if !absolute(k) {
                        now[k] = None;
                        lost |= 1 << k;
                    }
                }
            }
        }
        for (k, p) in now.into_iter().enumerate() {
            match p {
                Some(p) => self.machine.state.position[k] = Some(p),
                None if lost & 1 << k != 0 => self.machine.forget_axis(AXES[k]),
                None => {}
            }
        }
        // (a G268 under the profile's work offsets has a note of its own, which says the
        // positions after G269 are not compared either: Checker::work_offset)
        let own = off == 8 && self.config.haas && !self.config.work_offsets.is_empty();
        if lost != 0 && !own {
            let token = b
                .words
                .iter()
                .find(|w| w.column == column)
                .map_or_else(|| "the cancel".to_string(), |w| w.token());
            self.frame_note(
                &token,
                lost,
                (b.line, column),
                "until an absolute position gives them",
                "where the frame left the tool in the coordinates after its cancel is not known here",
            );
        }
    }

    /// The mirrored `axes` a cancel with a word not known here may or may not have ended
    /// ([`Checker::mirror_off`]): out of the mirror in force (exact or apart), into
    /// [`Frames::doubt`]; where the tool stands on them is not known (the mirror's point, or
    /// the position as written), said once.
    fn mirror_doubt(&mut self, b: &BlockView<'_>, axes: u16, column: usize) {
        self.frames.doubt |= axes;
        // (review 22, finding 1) an axis whose positions stood apart gets its span from
        // before the mirror back, as at a plain cancel of it: its positions under the mirror
        // are mirrored about a point not known here, and those after a plain cancel are
        // compared with the ones before the mirror
        self.give_back(self.frames.apart & axes);
        self.frames.apart &= !axes;
        if let Some(map) = self.frames.map.as_mut().filter(|map| map.bit == 32) {
            for k in (0..3).filter(|&k| axes & 1 << k != 0) {
                map.m[k][k] = 1.0;
                map.centre[k] = 0.0;
                map.fresh |= 1 << k;
                map.touched &= !(1 << k);
            }
            if (0..3).all(|k| map.m[k][k] == 1.0) {
                self.frames.map = None;
            }
        }
        for k in (0..AXES.len()).filter(|&k| axes & 1 << k != 0) {
            self.machine.forget_axis(AXES[k]);
        }
        let token = b
            .words
            .iter()
            .find(|w| w.column == column)
            .map_or_else(|| "the cancel".to_string(), |w| w.token());
        self.frame_note(
            &token,
            axes,
            (b.line, column),
            "until a cancel names the axis with a plain value or names none, or a mirror \
             names it plainly again",
            "an axis word whose value the checker does not know may or may not have ended the \
             axis's mirror image",
        );
    }

    fn frame_off(&mut self, off: u8) {
        self.frames.on &= !off;
        if off == 32 {
            self.frames.apart = 0;
        }
        self.frames.hidden[off.trailing_zeros() as usize] = 0;
        if self.frames.map.as_ref().is_some_and(|map| map.bit == off) {
            self.frames.map = None;
        }
        if self.frames.on & (16 | 32) == 0 {
            // (an axis given its span back at a partial cancel keeps the one it has now)
            self.give_back(self.frames.saving);
        }
    }

    /// The `axes` whose mirror not known exactly ends get their spans from before it back
    /// (those of them whose span is kept, [`Frames::saving`]): their positions under it
    /// stood apart.
    fn give_back(&mut self, axes: u16) {
        for k in (0..AXES.len()).filter(|&k| axes & self.frames.saving & 1 << k != 0) {
            self.spans[k] = self.frames.saved[k].take();
        }
        self.frames.saving &= !axes;
    }

    /// TG140 once per file: the positions under a frame the checker cannot apply are not
    /// compared with the travel.
    fn frame_not_applied(
        &mut self,
        token: &str,
        axes: u16,
        (line, column): (usize, usize),
        why: &str,
    ) {
        // (after the cancel an axis moved under the frame stands where the frame put it, not
        // known here: Checker::take_back; the note is said once, so it says that too)
        let until = "until its cancel, nor after the cancel an axis moved under it until an \
                     absolute position gives it";
        self.frame_note(token, axes, (line, column), until, why);
    }

    fn frame_note(
        &mut self,
        token: &str,
        axes: u16,
        (line, column): (usize, usize),
        until: &str,
        why: &str,
    ) {
        if self.frames.noted {
            return;
        }
        self.frames.noted = true;
        let names: Vec<String> = (0..AXES.len())
            .filter(|&k| axes & 1 << k != 0)
            .map(|k| (AXES[k] as char).to_string())
            .collect();
        let message = format!(
            "{token}: the positions of {} under it are not compared with the travel (TG601) \
             {until}: {why} (said once: the same for any later frame of this file)",
            names.join(" ")
        );
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// The centre and matrix of a rotation (`G68 X Y R`, R in degrees with its point) or a
    /// Haas scaling (`G51 X Y Z P`, P the factor with its point), or why they are not known:
    /// FANUC 16/18 Operator's Manual, "Coordinate system rotation" (the centre omitted is the
    /// current position; R omitted, parameter 5410; under G91 the angle may add to the last,
    /// parameter 5400) and "Scaling" (the factor's unit and the axes scaled are parameters
    /// 5400 and 5401); Haas Mill Operator's Manual, G68 and G51 (centre omitted: the current
    /// position; R omitted: Setting 72; under G91 with Setting 73 on, R adds to the angle;
    /// P omitted: Setting 71).
    fn exact_frame(
        &self,
        rotation: bool,
        b: &BlockView<'_>,
    ) -> Result<([f64; 3], [[f64; 3]; 3]), String> {
        if !self.config.modal.centre_codes {
            return Err("the control's words for it are not known to the checker".into());
        }
        if self.machine.state.incremental {
            return Err(if self.config.haas {
                "under G91 (with Setting 73 on) its angle adds to the one before".into()
            } else {
                "under G91 its centre and angle may add to the ones before".into()
            });
        }
        let word = |letter: u8| {
            b.words
                .iter()
                .enumerate()
                .find(|(_, w)| w.letter == letter)
                .map(|(i, w)| (self.readable[i], w.point))
        };
        if ["I", "J", "K"]
            .iter()
            .any(|l| word(l.as_bytes()[0]).is_some())
        {
            return Err(if rotation {
                "a three-dimensional rotation (I J K)".into()
            } else {
                "a factor for each axis (I J K), whose unit is a parameter".into()
            });
        }
        let factor = self.to_profile_units(false);
        let mut centre = [0.0; 3];
        for (k, &axis) in AXES[..3].iter().enumerate() {
            let given = word(axis).is_some();
            let at = if given {
                self.values.get(axis)
            } else {
                self.machine.state.axis(axis)
            };
            // (an axis whose centre is not known here is left out: Checker::frame_on)
            centre[k] = at.map_or(f64::NAN, |at| at.to_f64() * factor);
        }
        let mut m = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let (letter, missing) = if rotation && self.config.haas {
            ('R', "no R: the angle is Setting 72's")
        } else if rotation {
            ('R', "no R: the angle is parameter 5410's")
        } else {
            ('P', "no P: the factor is a setting's or a parameter's")
        };
        if !rotation && !self.config.haas {
            return Err("the factor's unit and the axes scaled are parameters".into());
        }
        let value = match word(letter as u8) {
            None => return Err(missing.into()),
            Some((Some(value), true)) => value.to_f64(),
            Some((None, _)) => return Err(format!("its {letter} is not known here")),
            Some(_) => {
                return Err(format!(
                    "its {letter} is written without a decimal point (least increments)"
                ))
            }
        };
        if rotation {
            let (a, c) = plane_axes(self.machine.state.plane);
            let (sin, cos) = value.to_radians().sin_cos();
            m[a][a] = cos;
            m[a][c] = -sin;
            m[c][a] = sin;
            m[c][c] = cos;
        } else {
            for (k, row) in m.iter_mut().enumerate() {
                row[k] = value;
            }
        }
        Ok((centre, m))
    }

    /// A shift of the coordinates (G52, G92, a Fanuc or Haas lathe's G50 X Z, G10 setting an
    /// offset that may be the one in force) moves the named axes' zero. Where the amount is
    /// known, the spans of TG601 follow it ([`Shifts`], [`Checker::shift_of`]); where it is
    /// not, the named axes' spans start again there, in the new coordinates, rather than mix
    /// positions of two (`G52 X-700.` then `X990.` is 290 in the old ones), and a TG140 note
    /// says so once per file. Inside a rotation or scaling taken back exactly, a shift leaves
    /// it unknown. At the end of the program the shifts in force end or stay as the control's
    /// parameters say ([`Checker::shift_end`]). Read after the block's own positions.
    #[inline]
    pub(super) fn shift_spans(&mut self, b: &BlockView<'_>, before: &Before) {
        // (only a G code shifts or turns the coordinates: the test inlined where it is asked, once a
        // block, the walk out of line; an end of the program matters only under a shift)
        if self.frames.codes {
            self.shift_spans_walk(b, before);
        }
        if self.shifts.on {
            self.shift_end(b);
        }
    }

    /// [`Checker::shift_spans`] of a block with such a code.
    #[inline(never)]
    fn shift_spans_walk(&mut self, b: &BlockView<'_>, before: &Before) {
        let fanuc_lathe = self.config.modal.fanuc_lathe;
        let sinumerik = self.config.family == Family::Sinumerik;
        for (i, w) in b.words.iter().enumerate() {
            let Some(v) = (w.letter == b'G').then(|| self.readable[i]).flatten() else {
                continue;
            };
            let v = self.g_read(v);
            let code = v.trunc();
            // (a G10 for a work system not in force shifts none: ModalMachine::taken)
            let other_system = self.machine.taken() == Some(crate::modal::AxesTaken::Data);
            let whole = v.is_whole();
            let shift = whole
                && ((code == 10 && !other_system)
                    || code == 52
                    || (code == 92 && !fanuc_lathe)
                    || (code == 50 && fanuc_lathe));
            let axes = crate::modal::axis_places(self.values.given()) != 0;
            if shift && self.later_shift.is_some() {
                self.later_shift_closed();
            }
            if self.record_path {
                let (on, _) = frame_bits(
                    v,
                    sinumerik,
                    fanuc_lathe,
                    self.config.haas,
                    self.config.family == Family::Okuma,
                );
                // G51.1 (mirror) and G92.1 (preset: the shift cancelled; B's and C's G92.1 is
                // read as A's G50.3), in tenths
                let tenths = v.normalized();
                let decimal = !sinumerik
                    && !v.is_whole()
                    && tenths.scale == 1
                    && (matches!(tenths.mantissa, 511 | 921)
                        || tenths.mantissa == 503
                            && self.config.modal.g_system != crate::lex::GCodeSystem::A);
                if (v.is_whole() && (on != 0 || shift && axes)) || decimal {
                    self.drawn.transform(b.line, w.token());
                }
            }
            // a preset of the work system (FANUC G92.1, a Fanuc lathe's G50.3, read as A's),
            // LinuxCNC's G92.1-G92.3 (G92's offsets ended, or restored from its parameters):
            // the coordinates go back to, or away from, a zero the file did not set
            let tenths = v.normalized();
            let preset = !sinumerik
                && !whole
                && tenths.scale == 1
                && (matches!(tenths.mantissa, 921..=923) && !fanuc_lathe
                    || tenths.mantissa == 503 && fanuc_lathe);
            if preset {
                self.preset(b, w);
            }
            if shift {
                if axes {
                    self.frames.shifted = true;
                    if let Some(map) = self.frames.map.take() {
                        self.frames.hidden[map.bit.trailing_zeros() as usize] = XYZ;
                        self.frames.moved[map.bit.trailing_zeros() as usize] |= map.touched != 0;
                        let why = format!("{} shifts the coordinates inside it", w.token());
                        self.frame_not_applied(&map.what, XYZ, (b.line, w.column), &why);
                    }
                }
                // each axis the code names, by a value known or not (`G52 X#1`)
                let named = self.values.given() | self.values.unknown;
                let (mut lost, mut why) = (0u16, None);
                let (mut shifted, mut own) = (0u16, 0u16);
                for a in crate::modal::places(crate::modal::axis_places(named)) {
                    let result = self.shift_of(code, a, before);
                    // (a zero not known to be the work system's where the program is called,
                    // or here, not followed: Written::shifted; not by a value not known,
                    // `G92 X#500`, said as before, erring on the side of the alarm)
                    let value = self.values.get(AXES[a]).is_some();
                    if code != 10 && value && result.is_err() {
                        own |= 1 << a;
                    }
                    if code != 10 && value && (result.is_err() || self.shifts.total[a] != 0.0) {
                        shifted |= 1 << a;
                    }
                    if let Err(not_known) = result {
                        // (a G10 leaves the local coordinate system as it was; any other
                        // shift not followed may have ended or set it)
                        let local_lost = code == 52 || code != 10 && self.shifts.local[a] != 0.0;
                        if self.restart_span(a, local_lost) {
                            lost |= 1 << a;
                            why.get_or_insert(not_known);
                        }
                    }
                }
                self.shifts.settle();
                if shifted != 0 {
                    self.offsets_written.shifted |= own;
                    let writes = Written {
                        shifted,
                        ..Default::default()
                    };
                    self.offset_writer(&writes, false);
                }
                if let Some(why) = why {
                    self.shift_note(&w.token(), lost, (b.line, w.column), &why);
                }
                if matches!(code, 92 | 50) && self.machine.taken() == Some(AxesTaken::Set) {
                    self.set_stands(b, named);
                }
            }
        }
    }

    /// A G92 (a lathe's G50) whose words set the coordinates (`named`): the tool stands at
    /// each named axis's value in the new coordinates, which goes to its span (plus the
    /// shift after it). Where the shift was followed that is where the tool stood before
    /// it, already in the span; where it was not (`G92 X0 Y0 Z0` at a program's start, the
    /// position before it not known) it starts the new span where the tool stands, so that
    /// the next moves span from there (review 39, finding 1). Its words are in the units
    /// the block sets where it writes a units code (`G21 G90 G92 X0 Y0 Z0`, the commonest
    /// header: a FANUC block's G20/G21 governs its own words, and LinuxCNC sets the length
    /// units before G92's offsets, its order of execution; review 41, finding 1). Not under a
    /// frame, in units not known, or for a FANUC lathe's U and W.
    #[cold]
    #[inline(never)]
    fn set_stands(&mut self, b: &BlockView<'_>, named: u32) {
        if self.frames.on != 0 || self.units_unknown {
            return;
        }
        // (the block's own units: Checker::block_modes)
        let factor = self.to_profile_units(false);
        let fanuc_lathe = self.config.modal.fanuc_lathe;
        for a in crate::modal::places(crate::modal::axis_places(named)) {
            if fanuc_lathe && matches!(AXES[a], b'U' | b'W') {
                continue;
            }
            let Some(value) = self.values.get(AXES[a]) else {
                continue;
            };
            let at = value.to_f64() * factor + self.shifts.total[a];
            let column = super::column_of(b.words, AXES[a]);
            self.add_to_span(a, at, false, b.line, || column, "");
        }
    }

    /// A preset of the work system or a cancel of G92's offsets (`w`): the named axes' spans,
    /// every axis's where it names none (LinuxCNC's G92.1-G92.3 take no axis words), start
    /// again, with the note: where the coordinates go is the offsets' from before the file.
    #[cold]
    #[inline(never)]
    fn preset(&mut self, b: &BlockView<'_>, w: &crate::word::Word<'_>) {
        let named = crate::modal::axis_places(self.values.given() | self.values.unknown);
        let axes = if named == 0 {
            (1 << AXES.len()) - 1
        } else {
            named
        };
        let mut lost = 0u16;
        for a in crate::modal::places(axes) {
            if self.restart_span(a, true) {
                lost |= 1 << a;
            }
        }
        self.shifts.settle();
        if lost != 0 {
            let why = "it sets the coordinates by the offsets in force before the file's own \
                       shifts, which the checker does not know";
            self.shift_note(&w.token(), lost, (b.line, w.column), why);
        }
    }

    /// Follow the shift of `AXES[i]` by the block's shift code `code` (as the profile reads
    /// it), or say why its amount is not known here (the sources: docs/dialects.md, "The
    /// shifts under TG601's spans"):
    /// - a FANUC or Haas mill's `G52 X_` under G90 sets the local coordinate system, whose zero
    ///   is X_ in the work system; `G52 X0` cancels it, and an axis it does not name keeps its
    ///   shift. Under G91 no FANUC or Haas page at hand says whether it adds to the local
    ///   shift: it is followed only where no local shift of the axis is in force, where both
    ///   readings agree;
    /// - a G92 (a Fanuc or Haas lathe's G50), where the checker reads its words as the
    ///   coordinates set (`AxesTaken::Set`), makes the position before it the words' values:
    ///   a shift of (position - value) where that position is known. Whether it also ends a
    ///   G52's local shift of the axis the pages at hand do not agree on (the FANUC-compatible
    ///   NCT 99M says it does), so after one the axis's local shift is not known;
    /// - G10 (the offset of the work system in force set), LinuxCNC's G52 (it sets the offset
    ///   G92 shares, which rs274 keeps from an earlier run by default), a lathe's G52, any other
    ///   control's code: not known.
    fn shift_of(&mut self, code: i64, i: usize, before: &Before) -> Result<(), NotKnown> {
        let axis = AXES[i] as char;
        let Some(value) = self.values.get(AXES[i]) else {
            return Err(format!("its {axis} is not known here"));
        };
        if self.frames.on != 0 {
            return Err(
                "a rotation, scaling, mirror image or polar coordinates are in force".into(),
            );
        }
        let settings = &self.machine.settings;
        if self
            .values
            .gs()
            .iter()
            .any(|&g| settings.units_code(g).is_some())
        {
            return Err("its block changes the units".into());
        }
        let factor = self.to_profile_units(false);
        let value = value.to_f64() * factor;
        let fanuc_lathe = self.config.modal.fanuc_lathe;
        let mill = self.config.family == Family::MacroB && !fanuc_lathe;
        // (a program read apart that sets its own shift: its positions after it do not add
        // to its call's, G52 replacing the local shift; read as before, review 42, finding 7;
        // those with no offset in force before a G52 kept for its calls, review 62a F8)
        if code == 52 {
            self.early_merge_keeping();
        } else {
            self.early_merge();
        }
        match code {
            52 if mill => {
                // (under G91 the two readings, the zero at X_ or X_ from the local zero before,
                // agree where there is none before)
                // (after a call that left the mode not known, read as before: the call's
                // body may have left G90 as well as G91; review 48, F11)
                let lost = self.mode_lost_codes == Some(self.machine.distance_codes);
                if self.machine.state.incremental && !lost && self.shifts.local[i] != 0.0 {
                    return Err(
                        "under G91 no page at hand says whether it adds to the local \
                                shift"
                            .into(),
                    );
                }
                if self.shifts.local_unknown & 1 << i != 0 {
                    return Err(format!(
                        "the local shift of {axis} before it is not known (an earlier shift not \
                         followed, or a G92 that may have ended it)"
                    ));
                }
                self.shifts.total[i] += value - self.shifts.local[i];
                self.shifts.local[i] = value;
                self.g52_axes |= 1 << i;
                self.g52_read_at(i, factor, false);
                // (after a return: reached by a jump only)
                self.shift_unsure |= self.sub_ended;
                Ok(())
            }
            92 | 50 if self.machine.taken() == Some(AxesTaken::Set) => {
                if fanuc_lathe && matches!(AXES[i], b'U' | b'W') {
                    return Err(format!("no page at hand says what its {axis} does"));
                }
                let Some(at) = before.axis(AXES[i]).filter(|_| !before.is_unknown(AXES[i])) else {
                    return Err(format!("where {axis} stood before it is not known"));
                };
                self.shifts.total[i] += at.to_f64() * factor - value;
                if self.shifts.local[i] != 0.0 {
                    self.shifts.local[i] = 0.0;
                    self.shifts.local_unknown |= 1 << i;
                }
                Ok(())
            }
            10 => Err("it may set the offset of the work system in force".into()),
            52 if self.config.family == Family::LinuxCnc => Err("LinuxCNC's G52 sets the offset \
                 G92 shares, which rs274 keeps from an earlier run unless the machine's INI \
                 file says otherwise"
                .into()),
            _ => Err("what it does to the coordinates is not followed here".into()),
        }
    }

    /// The span of `AXES[i]` starts again in the coordinates after a shift not known here;
    /// `local_lost`: the shift may have set or ended a G52's local shift of the axis. Whether
    /// a span of an axis with a travel was dropped (what the note says).
    fn restart_span(&mut self, i: usize, local_lost: bool) -> bool {
        self.later_shift_closed();
        // (a program read apart from those before it is read as before from here)
        self.early_merge();
        // (a call's shift kept for the end is in the coordinates before it)
        if self.shifts.calls != CallShifts::None {
            self.shifts.calls = CallShifts::Mixed;
        }
        let lost = self.spans[i].is_some() && self.travel.of_place(i).is_some();
        self.spans[i] = None;
        self.span_unjudged &= !(1 << i);
        if let Some(parked) = self.spans_parked.as_mut() {
            parked[i] = None;
        }
        self.shifts.total[i] = 0.0;
        if local_lost {
            self.shifts.local[i] = 0.0;
            self.shifts.local_unknown |= 1 << i;
        }
        lost
    }

    /// At the end of the program (M2, M30) a shift in force ends or stays as the control's
    /// parameters say (FANUC: the local coordinate system is cancelled at a reset where a
    /// parameter says so): the spans of the shifted axes start again, with the note. A Haas
    /// removes a G52 at M30 (Haas operator's manual, "Effective coordinate system": "Any G52 set
    /// during the program is removed once the program finishes at an M30"): an axis whose only
    /// shift is its G52 is back in the work system.
    #[cold]
    #[inline(never)]
    fn shift_end(&mut self, b: &BlockView<'_>) {
        self.later_shift_closed();
        let ends = !self.values.end_unsure && self.values.ms.iter().any(|&m| m == 2 || m == 30);
        if !ends {
            return;
        }
        if let CallShifts::Known(total, local) = self.shifts.calls {
            // (every call made under no shift, one a called program leaves on after them
            // or the program's own: the text after the end runs under none, review 61a's
            // fz558: `M98 P2000` / `G65 P3000` of an O3000 leaving `G52 X100.` on)
            let unshifted = total.iter().chain(&local).all(|&v| v == 0.0);
            if self.shifts.call != 0 || unshifted {
                // the calls, all under one known shift, run the text after the end (a Haas's
                // M97 N100, an O2000 after M30) under it: its positions are in the spans'
                // coordinates plus that shift
                self.shifts.total = total;
                self.shifts.local = local;
                self.shifts.local_unknown = 0;
                self.shifts.call = 0;
                self.shifts.call_at = None;
                self.shifts.calls = CallShifts::None;
                self.shifts.settle();
                return;
            }
        }
        let mut lost = 0u16;
        for i in 0..AXES.len() {
            let local_known = self.shifts.local_unknown & 1 << i == 0;
            let (total, local) = (self.shifts.total[i], self.shifts.local[i]);
            if self.shifts.call & 1 << i != 0 {
                // (a subprogram after the end runs under its call's shift, whatever the end's)
                if self.restart_span(i, true) {
                    lost |= 1 << i;
                }
                continue;
            }
            if total == 0.0 && local == 0.0 && local_known {
                continue;
            }
            if self.config.haas && local_known && total == local {
                self.shifts.total[i] = 0.0;
                self.shifts.local[i] = 0.0;
                continue;
            }
            if self.restart_span(i, local != 0.0 || !local_known) {
                lost |= 1 << i;
            }
        }
        if lost != 0 && !self.shifts.noted {
            let (token, column) = b
                .words
                .iter()
                .find(|w| w.letter == b'M')
                .map_or(("M30".to_string(), 1), |w| (w.token(), w.column));
            let why = match self.shifts.call_at.take() {
                Some((call, call_line)) if lost & self.shifts.call != 0 => format!(
                    "a subprogram after the end runs under the shift in force where it is \
                     called ({call} of line {call_line}), and the program's calls are made \
                     under different shifts or one not known"
                ),
                _ => "the end of the program may end the shift in force or keep it, as the \
                      control's parameters say"
                    .to_string(),
            };
            self.shifts.end_note = Some((token, b.line, column, lost, why));
        }
        self.shifts.call = 0;
        self.shifts.call_at = None;
        self.shifts.calls = CallShifts::None;
        self.shifts.settle();
    }

    /// A call (M97, M98, G65, G66): the shift in force here kept with the others of the
    /// program in hand ([`Shifts::calls`]).
    #[cold]
    #[inline(never)]
    pub(super) fn call_shifts(&mut self) {
        let here = if self.shifts.local_unknown != 0 {
            CallShifts::Mixed
        } else {
            CallShifts::Known(self.shifts.total, self.shifts.local)
        };
        self.shifts.calls = match std::mem::take(&mut self.shifts.calls) {
            CallShifts::None => here,
            known if known == here => known,
            _ => CallShifts::Mixed,
        };
    }

    /// A program no call before it names begins (not run on into by the block skip switch):
    /// it is read from the control's reset state, as a program of its own, not under a G52
    /// (or a local shift not known) the program before left at its end (review 59a, F3:
    /// `G52 X10.` / `M30` / `O2000` / `G90 G55 G0 X-700.` was no "X goes to -800", the
    /// offsets taken as lost for every later program). Its own findings are read apart
    /// (crate::check::called): a call of it under a shift judges it there.
    #[cold]
    #[inline(never)]
    pub(super) fn shifts_reset(&mut self) {
        let noted = self.shifts.noted;
        self.shifts = Shifts {
            noted,
            ..Shifts::default()
        };
    }

    /// The shift in force at a call, in the spans' coordinates: None where a local shift
    /// is not known.
    pub(super) fn call_shift(&self) -> Option<[f64; 9]> {
        (self.shifts.local_unknown == 0).then_some(self.shifts.total)
    }

    /// Some axis has a shift in force, or one not known.
    pub(super) fn shifts_on(&self) -> bool {
        self.shifts.on
    }

    /// Some frame (rotation, scaling, mirror, polar coordinates) is in force.
    pub(super) fn frames_on(&self) -> bool {
        self.frames.on != 0 || self.frames.map.is_some()
    }

    /// A call (M97, M98, G65, G66) made under a shift: the axes shifted there, or whose local
    /// shift is not known, are kept for the end of the program ([`Checker::shift_end`]). A
    /// Haas's M97 and M98 run a subprogram written after M30 (a sequence number or an O
    /// number of the file) when they are called, under the caller's G52 (review 39, finding
    /// 2); read after the end, its body would be taken under the shift left there.
    #[cold]
    #[inline(never)]
    pub(super) fn shift_call(&mut self, b: &BlockView<'_>) {
        let mut axes = self.shifts.local_unknown;
        for i in 0..AXES.len() {
            if self.shifts.total[i] != 0.0 || self.shifts.local[i] != 0.0 {
                axes |= 1 << i;
            }
        }
        if axes == 0 {
            return;
        }
        self.shifts.call |= axes;
        if self.shifts.call_at.is_none() {
            let calling = |(i, w): &(usize, &crate::word::Word<'_>)| {
                let code = self.readable[*i]
                    .filter(|v| v.is_whole())
                    .map(|v| v.trunc());
                match w.letter {
                    b'M' => matches!(code, Some(97 | 98)),
                    b'G' => matches!(code, Some(65 | 66)),
                    _ => false,
                }
            };
            let mut token = b
                .words
                .iter()
                .enumerate()
                .find(calling)
                .map_or_else(|| "the call".to_string(), |(_, w)| w.token());
            if let Some(p) = b.words.iter().find(|w| matches!(w.letter, b'P' | b'Q')) {
                token = format!("{token} {}", p.token());
            }
            self.shifts.call_at = Some((token, b.line));
        }
        self.shifts.settle();
    }

    /// The note of [`Shifts::end_note`], at the first position after the end that goes to
    /// a span it dropped.
    #[cold]
    #[inline(never)]
    fn end_noted(&mut self) {
        let Some((token, line, column, lost, why)) = self.shifts.end_note.take() else {
            return;
        };
        self.shift_note(&token, lost, (line, column), &why);
        self.shifts.settle();
    }

    /// TG140 once per file: a shift whose amount is not known here starts the spans of
    /// `axes` again.
    #[cold]
    fn shift_note(&mut self, token: &str, axes: u16, (line, column): (usize, usize), why: &str) {
        if self.shifts.noted {
            return;
        }
        self.shifts.noted = true;
        let names: Vec<String> = (0..AXES.len())
            .filter(|&k| axes & 1 << k != 0)
            .map(|k| (AXES[k] as char).to_string())
            .collect();
        let message = format!(
            "{token}: the span of {} (TG601) starts again here, in the coordinates after it, \
             since the shift's amount is not known: {why}; the positions before and after it \
             are not compared with each other (said once: the same for any later shift of \
             this file). The check follows a G52 written with its values under G90 and a G92 \
             where the position before it is known (an absolute move)",
            names.join(" ")
        );
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// `at`, a position of the program's coordinates on `AXES[i]` (in the profile's units), in
    /// the coordinates of its span: plus the shift followed ([`Shifts`]).
    #[inline]
    fn shifted(&self, i: usize, at: f64) -> f64 {
        if self.shifts.on {
            at + self.shifts.total[i]
        } else {
            at
        }
    }

    /// A Sinumerik's frames (TRANS, ATRANS, ROT, SCALE, MIRROR..., TOROT, TOFRAME, PAROT
    /// turned to the tool or the workpiece, and a frame variable set by assignment,
    /// `$P_PFRAME=CTRANS(X,-300)`) move the coordinates: the profile's offsets are no longer
    /// what is in force. Whether the block suppresses the
    /// offsets for itself (SUPA).
    pub(super) fn frames(&mut self, b: &BlockView<'_>) -> bool {
        if self.config.work_offsets.is_empty() || self.config.family != Family::Sinumerik {
            return false;
        }
        let line = b.line;
        let mut one_shot = false;
        for &(_, kind, text) in b.statements {
            let upper = text.to_ascii_uppercase();
            let word = upper
                .split(|c: &u8| !c.is_ascii_alphabetic())
                .next()
                .unwrap_or(b"");
            const FRAMES: [&[u8]; 8] = [
                b"TRANS", b"ATRANS", b"ROT", b"AROT", b"SCALE", b"ASCALE", b"MIRROR", b"AMIRROR",
            ];
            // TRANS X10 (SINUMERIK_REST), or TOROT, TOFRAME, PAROT: a frame turned to the tool
            // or the workpiece (SINUMERIK_INSTRUCTIONS)
            let turned = || {
                statement::sinumerik_instruction(word).is_some_and(|g| g.effect == Effect::Frame)
            };
            if kind == Kind::Command && (FRAMES.contains(&word) || turned()) {
                let what = String::from_utf8_lossy(word).into_owned();
                self.lose_offsets(line, &format!("the frame {what} moves the coordinates"));
            } else if let Some(name) = frame_variable(&upper).filter(|_| kind == Kind::Assignment) {
                let what = String::from_utf8_lossy(name).into_owned();
                self.lose_offsets(line, &format!("the frame {what} is set"));
            } else if word == b"SUPA" {
                one_shot = true;
            }
        }
        one_shot
    }

    /// Travel (6.4). Where the profile gives the work offsets and the one in force is known
    /// (`absolute`, [`Checker::work_offset`]), each move's machine position (work position
    /// plus offset) is checked against the travel, an excursion once where it starts; Z not
    /// while a tool length offset is in force (the profile gives no tool lengths). A position
    /// in machine coordinates (G53) is checked as it is. What holds whatever the offsets: the
    /// span of the program's positions in each axis against the span of the travel (once per
    /// axis, unless a machine position was already found outside). Under a SINUMERIK's
    /// kinematic transformation neither: its axes are not the machine's.
    pub(super) fn limits(&mut self, line: usize, facts: &Facts<'_>, absolute: bool) {
        let (mut moved, mut places) = (facts.moved(), facts.moved_places());
        // a lathe's U and W that moved X and Z (FANUC and Haas G code system A, Okuma): the
        // positions of X and Z go to their spans, U and W having no travel of their own
        // (review 41, finding 2: `G0 X100. Z0`, `G0 U520.` passed a 500 mm travel); only a
        // block that writes U or W asks the machine
        // a FANUC or Haas lathe's single cycle G90, G92, G94: its end point X(U) Z(W) goes to
        // the spans, the position (the start point, where the tool returns) being kept aside
        // while they are walked
        // (the same of a lathe's multiple repetitive cycle G74-G76 and of an Okuma's fixed
        // thread cutting cycle, X and Z both walked; the corner of a taper after it,
        // Checker::cycle_walked)
        let flags = self.machine.ran_cycle();
        let cycle = flags & CYCLE_RAN != 0;
        let uw = cycle || (places & UW_PLACES != 0 && self.machine.uw_moved_xz());
        let onto_xz;
        if uw {
            if !cycle {
                self.uw_beside_xz(line, facts, places);
            }
            onto_xz = uw_onto_xz(if cycle {
                places | 1 << 0 | 1 << 2
            } else {
                places
            });
            (moved, places) = (&onto_xz.0[..onto_xz.1], onto_xz.2);
        }
        if cycle {
            self.machine.swap_cycle_end();
        }
        if let Some(transformed) = self.transformed.as_mut() {
            // said at the first move under it (each block's message formatted and searched
            // for made a program of many transformations quadratic)
            if !moved.is_empty() && !transformed.noted {
                transformed.noted = true;
                let why = format!(
                    "from line {} on: the transformation {} programs the axes in other \
                     coordinates (until TRAFOOF)",
                    transformed.line, transformed.name
                );
                self.travel_not(why);
            }
            moved = &[];
            places = 0;
            // (nor a run of increments, TG601's)
            self.machine.drift = Default::default();
        }
        // a frame's block whose axis words are its data (G51.1 X0: the mirror's axis, no
        // move) adds no position: where the tool stands may be a span's that the block
        // started afresh
        // (nor does a G92's or a lathe's G50's: the tool stays where it was, which its new
        // coordinates name, Checker::shift_spans; taken as a position of the coordinates
        // before it, `G0 X700.` / `G92 X-900.` spanned 1600)
        if self.frames.codes
            && !cycle
            && matches!(self.machine.taken(), Some(AxesTaken::Data | AxesTaken::Set))
        {
            moved = &[];
            places = 0;
        }
        // (no moved axis with a travel -- a profile without travels, as LinuxCNC's -- and no
        // frame's map: the walks below find nothing, and are not set up)
        // (a subprogram whose calls leave its units unknown: its lengths and feeds are not
        // judged against the machine's until it writes a units code, Checker::called_units;
        // a speed or a tool number still is)
        self.walk_spans((moved, places), line, facts, absolute, uw);
        if flags != 0 {
            self.cycle_walked(flags, (moved, places), line, facts, absolute);
        }
        let v = &self.values;
        // (the feed, speed and tool limits below read the block's F, S and T alone: most
        // blocks have none)
        if v.given() & (bit(b'F') | bit(b'S') | bit(b'T')) == 0 {
            return;
        }
        // a dwell's F or S (a SINUMERIK's G4 F2 X10) is its time, not a feed or a speed
        let given = |l: u8| v.get(l).filter(|_| !self.machine.settings.dwell_word(v, l));
        let (f, s, t) = (given(b'F'), given(b'S'), v.get(b'T'));
        // a spindle speed limit's S (the clamp code's, a SINUMERIK's G25/G26 S) turns nothing:
        // a limit above the maximum never bites (audit 37); the modal state reads a block's S
        // by the same rule, ModalSettings::s_limit
        let s = s.filter(|_| !self.machine.settings.s_limit(v).1);
        let factor = self.to_profile_units(true);
        if self.units_unknown && f.is_some() && self.config.feed_max.is_some() {
            self.unknown_call_note();
        }
        let f = f.filter(|_| !self.units_unknown);
        if let Some(feed) = f.filter(|_| self.early_on) {
            // (a program read apart keeps its largest feed: a few blocks of it, where it grows)
            let value = feed.to_f64() * factor;
            if self.early_feed_max() < value {
                self.early_feed(feed, value, line);
            }
        }
        if let (Some(top), Some(feed)) = (self.config.feed_max, f) {
            if self.machine.state.feed_mode != 93 && feed.to_f64() * factor > top.to_f64() + 1e-9 {
                let mode = self.machine.state.feed_mode;
                self.feed_over(feed, factor, mode, (line, facts.col(b'F')), "");
            }
        }
        if let (Some(top), Some(speed)) = (self.config.spindle_max, s) {
            if self.machine.state.spindle_mode == 97 && speed > top {
                let message = format!("spindle speed {speed} above the maximum {top}");
                // a control family's: a SINUMERIK limits an excessive speed to its maximum
                // (808D Function Manual, MD35100 SPIND_VELO_LIMIT; 840D Function Manual, S1,
                // 18.8.4), and no source at hand says a FANUC, Haas, Okuma or Heidenhain
                // alarms rather than limiting it: a warning (issue 32, item 3), where the
                // maximum is a built-in profile's sample machine -- a user's file on a base
                // that sets no spindle_max of its own included (review 38, finding 4); the
                // strict ISO profiles, and a user's file that sets it, whose maximum is the
                // user's machine (a chuck's rating), keep TG603 (review 37, finding 6)
                let sample = self.config.sample_limits & super::SAMPLE_SPINDLE != 0;
                if self.config.family == Family::Iso || !sample {
                    self.report(Rule::SpeedTooHigh, message, line, facts.col(b'S'));
                } else {
                    let effect = if self.config.family == Family::Sinumerik {
                        "a SINUMERIK limits it to its maximum (MD35100), no alarm"
                    } else {
                        "no source says the control alarms rather than limiting it"
                    };
                    let message = format!(
                        "{message} of the profile's machine: {effect}; set the profile's \
                         spindle_max to your machine's"
                    );
                    self.report(Rule::SpeedLimited, message, line, facts.col(b'S'));
                }
            }
        }
        if let Some(t) = t {
            let word = t.trunc();
            if !self.stats.tools.contains(&word) {
                self.stats.tools.push(word);
            }
            if let Some(top) = self.config.tool_max {
                // a Fanuc or Haas lathe's T word is the tool number followed by the offset
                // number (dialect::LATHE_OFFSET_DIGITS): the limit is the tool part's
                let (tool, offset) = if self.config.modal.fanuc_lathe {
                    let split = 10_i64.pow(crate::dialect::LATHE_OFFSET_DIGITS);
                    (word / split, Some(word % split))
                } else {
                    (word, None)
                };
                if tool > top {
                    let message = match offset {
                        Some(offset) => format!(
                            "tool {tool} (T{word}: tool {tool}, offset {offset:02}) above the \
                             largest tool number {top}"
                        ),
                        None => format!("tool {tool} above the largest tool number {top}"),
                    };
                    self.report_limit(Rule::ToolOutOfRange, message, line, facts.col(b'T'));
                }
            }
        }
    }
}

/// The bits of [`Checker`]'s once-a-file notes: a lathe cycle not all known, a G53 under G91,
/// X and U (Z and W) in one lathe block.
pub(super) const CYCLE_NOTED: u8 = 1;
pub(super) const G53_INCREMENTAL_NOTED: u8 = 2;
pub(super) const UW_BESIDE_NOTED: u8 = 4;
/// A call of a program the checker does not read there, after which G90/G91 are not known
/// ([`Checker::call_mode_lost`]).
pub(super) const MODE_LOST_NOTED: u8 = 8;

/// The places of U and W in [`AXES`] ([`crate::modal::axis_places`]).
const UW_PLACES: u32 = 1 << 3 | 1 << 5;

/// The moved axes of a block whose U and W moved X and Z
/// ([`crate::modal::ModalMachine::uw_moved_xz`]): U's place taken by X, W's by Z (once each,
/// beside an X or Z the block writes too), the axes in the order of [`AXES`], how many, and
/// their places.
#[cold]
#[inline(never)]
fn uw_onto_xz(places: u32) -> ([u8; 9], usize, u32) {
    let mut onto = places & !UW_PLACES;
    if places & 1 << 3 != 0 {
        onto |= 1 << 0;
    }
    if places & 1 << 5 != 0 {
        onto |= 1 << 2;
    }
    // (the axes of the places looked up, as Facts::new does: a walk cost about 60
    // instructions a block)
    let (moved, n) = super::MOVED[onto as usize];
    (moved, usize::from(n), onto)
}

/// The column of [`Facts::col`] where U and W moved X and Z: X's, or U's where the block
/// writes no X (Z's, or W's).
#[cold]
#[inline(never)]
fn uw_column(facts: &Facts<'_>, letter: u8) -> usize {
    let own = facts.words.iter().any(|w| w.letter == letter);
    match letter {
        b'X' if !own => facts.col(b'U'),
        b'Z' if !own => facts.col(b'W'),
        _ => facts.col(letter),
    }
}

/// Every axis place's bit (the spans' nine).
const ALL_PLACES: u16 = (1 << 9) - 1;

/// The span of the positions of `a` (where there are some) and `b`.
fn joined(a: Option<Span>, b: Span) -> Span {
    a.map_or(b, |a| Span {
        least: a.least.min(b.least),
        most: a.most.max(b.most),
        said: a.said || b.said,
    })
}

/// The span of axis place `i` set aside ([`Checker::selection_spans`]).
fn parked_at(parked: &Option<Box<[Option<Span>; 9]>>, i: usize) -> Option<Span> {
    parked.as_ref().and_then(|p| p[i])
}

impl Checker {
    /// The walk of [`Checker::limits`]: the positions of the block's moved axes (`moved`, at
    /// `places`) to their spans and, where the offsets are known, to the travel; `uw` where
    /// the block's U and W (or a lathe cycle's words) stand for X and Z (their columns).
    /// Inlined into `limits`; a lathe cycle's corner walks it again out of line.
    #[inline(always)]
    fn walk_spans(
        &mut self,
        (mut moved, places): (&[u8], u32),
        line: usize,
        facts: &Facts<'_>,
        absolute: bool,
        uw: bool,
    ) {
        let col = |letter: u8| {
            if uw {
                uw_column(facts, letter)
            } else {
                facts.col(letter)
            }
        };
        if (places & self.travel.places() == 0 && self.frames.map.is_none()) || self.units_unknown {
            if self.units_unknown && places & self.travel.places() != 0 {
                self.unknown_call_note();
                // (increments in units not known: no run of them is judged)
                self.machine.drift = Default::default();
            }
            return;
        }
        let factor = self.to_profile_units(false);
        // (an Okuma mill's G53 cancels the tool length offset: work_offset)
        let machine =
            self.values.has_g(53) && (self.config.family != Family::Okuma || self.config.modal.lap);
        if machine && self.machine.state.incremental {
            // G53 under G91: no position judged (docs/dialects.md, "G53 under G91"); its
            // positions go to no span either way
            self.machine_incremental(line, facts);
            return;
        }
        // the axes whose positions go to the spans below through a frame, or not at all
        // (none where no frame is on: most programs)
        let framed = if self.frames.on == 0 {
            0
        } else {
            self.frames.hidden() | if self.frames.map.is_some() { XYZ } else { 0 }
        };
        // no machine coordinates, no offset compared, no frame: each axis's position only goes
        // to its span (a CAM program's moves under a profile without work offsets), walked by
        // the places of the axes that have a travel (none under a profile without travels),
        // where the walk below looked each axis up by its letter and passed the offsets' tests
        // (about 60 instructions an axis)
        // (and no frame's map, which reads the moved axes below)
        // (and no shift followed, which the walk below adds)
        if !machine && !absolute && framed == 0 && self.frames.map.is_none() && !self.shifts.on {
            debug_assert_eq!(
                moved,
                crate::modal::places(places)
                    .map(|i| AXES[i])
                    .collect::<Vec<_>>(),
                "line {line}: the moved axes' places"
            );
            let count = !self.config.work_offsets.is_empty();
            if count && self.spans_parked_call {
                self.spans_rejoined();
            }
            for i in crate::modal::places(places & self.travel.places()) {
                let (Some(_), Some(position)) =
                    (self.travel.of_place(i), self.machine.state.position[i])
                else {
                    // (the position not known: its increments' run, if it grew)
                    if self.machine.drift[i].grew {
                        self.drifted(i, line, facts, uw);
                    }
                    continue;
                };
                let at = position.to_f64() * factor;
                if count {
                    self.stats.travel_moves += 1;
                }
                self.add_to_span(i, at, false, line, || col(AXES[i]), "");
            }
            moved = &[];
        }
        for &axis in moved {
            let Some((low, high)) = self.travel.of(axis) else {
                continue;
            };
            if machine {
                let Some(value) = self.values.get(axis) else {
                    continue;
                };
                let at = value.to_f64() * factor;
                if !(low..=high).contains(&at) {
                    self.machine_outside(axis, value, at, (low, high), (line, col(axis)));
                }
                if self.early_on {
                    // (a program read apart: judged at its calls in their units too,
                    // crate::check::called)
                    self.early_machine(axis, value, at, line);
                }
                continue;
            }
            let (Some(i), Some(position)) = (axis_index(axis), self.machine.state.axis(axis))
            else {
                if let Some(i) = axis_index(axis).filter(|&i| self.machine.drift[i].grew) {
                    self.drifted(i, line, facts, uw);
                }
                continue;
            };
            let at = position.to_f64() * factor;
            if !self.config.work_offsets.is_empty() {
                self.stats.travel_moves += 1;
                if self.reexpressed_held.is_some()
                    && self.numbered
                    && self.config.family != Family::LinuxCnc
                {
                    self.reexpression_shadow(i, position, factor, line);
                }
                // (a span set aside at a selection joins again under G91, however it came in
                // force: an M72's restore, a call's; review 78-lcnc78b F4)
                // (and at a position outside a body read under its call's offset after they
                // were kept across that call: structure.rs, `call_offsets_rewritten`)
                if self.spans_parked.is_some() && self.machine.state.incremental {
                    // (not those a selection re-expressed: their increments run from the
                    // new system's position, judged as machine positions)
                    let axes = if self.reexpressed.is_some() {
                        ALL_PLACES & !self.moved_axes()
                    } else {
                        ALL_PLACES
                    };
                    self.spans_unparked(axes);
                } else if self.spans_parked_call {
                    self.spans_rejoined();
                }
            }
            let offset = self.work.and_then(|work| {
                self.config
                    .work_offsets
                    .iter()
                    .find(|&&(g, a, _)| g == work && a == axis)
                    .map(|&(_, _, value)| value)
            });
            let length =
                axis == b'Z' && (self.machine.state.length_offset != 49 || self.length_decimal);
            let mut said_outside = false;
            match (absolute, self.work, offset) {
                (true, Some(_), Some(_)) if length => {
                    self.position_not_judged(i);
                    self.travel_not(
                        "Z while a tool length offset was in force (the profile gives no tool \
                         lengths)"
                            .into(),
                    )
                }
                (true, Some(work), Some(offset))
                    if !self.offsets_written.any() && self.work_call.is_none() =>
                {
                    self.stats.travel_absolute += 1;
                    let machine_at = at + offset.to_f64();
                    let out = travel_side(machine_at, (low, high));
                    if out != 0 && out != self.outside[i] {
                        let message = format!(
                            "{} goes to {} in machine coordinates (work {} + G{work} offset \
                                 {offset}), outside the travel {low} to {high}",
                            axis as char,
                            round6(machine_at),
                            round6(at)
                        );
                        let placed = super::Placed::Offset {
                            place: i as u8,
                            work: work as u8,
                            at,
                            line,
                        };
                        if self.report_placed(message, (line, col(axis)), placed)
                            && (self.work_guessed.is_some() || self.work_run_on)
                        {
                            self.found.last_mut().expect("said").guessed = true;
                        }
                        said_outside = true;
                    } else if out != 0 {
                        // (an excursion held by a call's mode, ended by the caller's own
                        // G90/G91: this position opens its own, review 78-calls78 F2)
                        let reopened = if self.call_modes.is_empty() {
                            None
                        } else {
                            self.call_mode_reopened(i)
                        };
                        if let Some(mark) = reopened {
                            let place = ((axis, i), at, (work, offset));
                            said_outside =
                                self.offset_said_again(place, (low, high), (line, col(axis)));
                            if said_outside {
                                self.found.last_mut().expect("said").pending_on.push(mark);
                            }
                        } else {
                            self.excursion_farther(i, work, (at, line), out);
                        }
                    }
                    self.outside[i] = out;
                }
                // (after a G10 of a value known, review 59a F8, or in a program written
                // after its calls, F12: out of line)
                (true, Some(work), Some(offset)) => {
                    said_outside = self.offset_position(
                        (axis, i),
                        at,
                        (work, offset),
                        (low, high),
                        (line, col(axis)),
                    );
                }
                (true, Some(work), None) => {
                    self.position_not_judged(i);
                    self.travel_not(format!(
                        "{} under G{work}: the profile gives no G{work} {}",
                        axis as char, axis as char
                    ))
                }
                (true, None, _) => {
                    self.position_not_judged(i);
                    if self.work_unplaced {
                        self.unplaced_at(i, at, line);
                    }
                    self.travel_not(
                        "where the program has selected no work offset (G54-G59)".into(),
                    )
                }
                _ => {}
            }
            // (under a frame: X Y Z taken back through it below, or left out)
            if framed & (1 << i) != 0 {
                for (moved, hidden) in self.frames.moved.iter_mut().zip(self.frames.hidden) {
                    *moved |= hidden & (1 << i) != 0;
                }
                continue;
            }
            let at = self.shifted(i, at);
            if self
                .shifts
                .end_note
                .as_ref()
                .is_some_and(|n| n.3 & 1 << i != 0)
            {
                self.end_noted();
            }
            self.add_to_span(i, at, said_outside, line, || col(axis), "");
        }
        if self.frames.map.is_some() && !moved.is_empty() {
            self.mapped_spans(moved, line, facts);
        }
    }

    /// An axis whose position is not known moved by increments of known lengths (G91, a
    /// lathe's U and W: [`crate::modal::Drift`]): where the extent of their running sum (0
    /// included) is wider than the axis's whole travel, the axis is out of travel wherever it
    /// started, TG601 once a run (issue 32: `G28 U0 W0` then `G0 U520.` on a 510 mm X).
    /// Never where a frame is on (its increments move the machine's axes otherwise).
    #[cold]
    #[inline(never)]
    fn drifted(&mut self, i: usize, line: usize, facts: &Facts<'_>, uw: bool) {
        let drift = &mut self.machine.drift[i];
        drift.grew = false;
        if self.frames.on != 0 {
            *drift = Default::default();
            return;
        }
        let Some((low, high)) = self.travel.of_place(i) else {
            return;
        };
        let factor = match self.config.limit_units {
            Units::Metric => 1.0,
            Units::Inch => 1.0 / 25.4,
        };
        let extent = (drift.most - drift.least) * factor;
        if drift.said || extent <= high - low + 1e-9 {
            return;
        }
        drift.said = true;
        let moves = drift.moves;
        let axis = AXES[i];
        // the word that moved it: U or W where they stand for X and Z
        let letter = match axis {
            b'X' if uw => b'U',
            b'Z' if uw => b'W',
            _ => axis,
        };
        let word = facts
            .words
            .iter()
            .find(|w| w.letter == letter)
            .or_else(|| facts.words.iter().find(|w| w.letter == axis));
        let column = word.map_or(1, |w| w.column);
        let token = word.map_or(String::new(), |w| {
            String::from_utf8_lossy(w.token).into_owned()
        });
        let unit = match self.config.limit_units {
            Units::Metric => "mm",
            Units::Inch => "in",
        };
        let what = if moves == 1 {
            format!("{} moves {} ({token})", axis as char, round6(extent))
        } else {
            format!(
                "{} moves over {} {unit} in {moves} increments in a row (the last {token})",
                axis as char,
                round6(extent)
            )
        };
        let message = format!(
            "{what} with its start not known: more than its whole travel of {} ({low} to \
             {high}), out of travel wherever it starts",
            round6(high - low)
        );
        self.report_limit(Rule::TravelExceeded, message, line, column);
    }

    /// A position in machine coordinates (G53) written under G91 (in force, or in its
    /// block): not compared with the travel. LinuxCNC refuses the block ("Cannot use g53
    /// incremental", TG412 says it); for the other families no page at hand
    /// says what their control does (a Rockwell 9/Series ignores the block's G53 and axis
    /// words, a Mitsubishi M700V moves by the increment: docs/dialects.md), so a TG140 note
    /// says so once per file rather than a position judged as absolute (review 46, F3).
    #[cold]
    #[inline(never)]
    pub(super) fn machine_incremental(&mut self, line: usize, facts: &Facts<'_>) {
        if self.noted & G53_INCREMENTAL_NOTED != 0 || self.config.family == Family::LinuxCnc {
            return;
        }
        self.noted |= G53_INCREMENTAL_NOTED;
        let column = facts.words.first().map_or(1, |w| w.column);
        let message = "G53 under G91 (incremental): no page at hand says whether the control \
                       moves to the machine position, by the increment or not at all (a \
                       9/Series ignores the block, a Mitsubishi M700V moves by the increment), \
                       so its positions are not compared with the travel (TG601; said once: \
                       the same for any later such block of this file)"
            .to_string();
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// A lathe block that writes X and U (or Z and W) where U and W move X and Z: no page
    /// at hand says which the control takes, or whether it alarms, so the axis's position is
    /// not known until an absolute one ([`crate::modal::ModalMachine`]), said once per file
    /// (review 44, F7: `X100. U520.` was judged at X620, neither reading).
    #[cold]
    #[inline(never)]
    fn uw_beside_xz(&mut self, line: usize, facts: &Facts<'_>, places: u32) {
        // (a block whose words are a code's data, `G65 P9732 W1. Z1.`, moves nothing; the
        // axis itself is forgotten by the modal walk, ModalMachine::apply: a rule leaves the
        // state as it found it)
        let both = |pair: u32| places & pair == pair;
        if !(both(0b1001) || both(0b10_0100)) || self.machine.taken().is_some() {
            return;
        }
        if self.noted & UW_BESIDE_NOTED != 0 {
            return;
        }
        self.noted |= UW_BESIDE_NOTED;
        let column = facts.words.first().map_or(1, |w| w.column);
        let message = "a block writes X and U (or Z and W), the absolute and the incremental \
                       command of one axis: no page at hand says which the control takes, or \
                       whether it alarms, so where the axis stands is not known until an \
                       absolute position gives it, and is not compared with the travel (TG601; \
                       said once: the same for any later such block of this file)"
            .to_string();
        self.report(Rule::NotFollowed, message, line, column);
    }

    /// After [`Checker::limits`]'s walk of a block that ran a lathe's cycle
    /// ([`ModalMachine::ran_cycle`]): the position back at the start point, the corner of
    /// the cycle's taper walked as its end point was, and, where some of where the cycle
    /// went is not known, TG140 once per file.
    #[cold]
    #[inline(never)]
    fn cycle_walked(
        &mut self,
        flags: u8,
        axes: (&[u8], u32),
        line: usize,
        facts: &Facts<'_>,
        absolute: bool,
    ) {
        if flags & CYCLE_RAN != 0 {
            self.machine.swap_cycle_end();
            if self.machine.cycle_corner().is_some() && !axes.0.is_empty() {
                self.machine.swap_cycle_corner();
                self.walk_spans(axes, line, facts, absolute, true);
                self.machine.swap_cycle_corner();
            }
        }
        if flags & CYCLE_UNSURE != 0 && self.noted & CYCLE_NOTED == 0 {
            self.noted |= CYCLE_NOTED;
            let message = format!(
                "a lathe cycle's positions are not compared with the travel (TG601): {}; \
                 the check compares the end points and taper corners it can work out (said \
                 once: the same for any later such cycle of this file)",
                self.machine.cycle_why()
            );
            let column = facts.words.first().map_or(1, |w| w.column);
            self.report(Rule::NotFollowed, message, line, column);
        }
    }

    /// Add `at` (the profile's units) to the span of `AXES[i]`; TG601 once per axis where the
    /// span is wider than the travel. `under` ends the message: the frame the position was
    /// taken back through.
    /// (Its first test inlined where it is asked, for each moved axis of every block: once
    /// its callers grew (review 44's cycles) the whole was no longer inlined, a call at each
    /// axis, about 40 instructions a block on slot_assembly_12; a span that grows, and the
    /// finding, out of line.)
    #[inline(always)]
    pub(super) fn add_to_span(
        &mut self,
        i: usize,
        at: f64,
        said_outside: bool,
        line: usize,
        column: impl FnOnce() -> usize,
        under: &str,
    ) {
        let Some((low, high)) = self.travel.of_place(i) else {
            return;
        };
        // a position strictly inside the span so far, nothing said of the machine position:
        // the span stays as it is, and so does its test below, made (and said, if it failed)
        // when the span last grew (the travel is the profile's); most of a CAM program's
        // moves. (A position at a bound takes the walk below: 0.0 and -0.0 are equal, and
        // which of them `min` keeps is not the comparison's.)
        // (but in a body read apart whose positions from its own G90 on are kept: each of
        // them, inside or not, crate::check::called's `Absolute`; review 47, F0)
        if let Some(span) = &self.spans[i] {
            if !said_outside
                && span.least < at
                && at < span.most
                && !(self.early_on && self.early_absolute())
            {
                debug_assert!(span.said || span.most - span.least <= (high - low) + 1e-9);
                return;
            }
        }
        self.span_grows(i, at, said_outside, (line, column), (low, high), under);
    }

    /// [`Checker::add_to_span`] where `at` is not strictly inside the span so far.
    #[inline(never)]
    fn span_grows(
        &mut self,
        i: usize,
        at: f64,
        said_outside: bool,
        (line, column): (usize, impl FnOnce() -> usize),
        (low, high): (f64, f64),
        under: &str,
    ) {
        let axis = AXES[i];
        let span = self.spans[i].get_or_insert(Span {
            least: at,
            most: at,
            said: false,
        });
        span.least = span.least.min(at);
        span.most = span.most.max(at);
        span.said |= said_outside; // the machine position said more than the span can
        if self.early_on {
            // (a program read apart from those before it, crate::check::called)
            let column = column();
            if let Some(ends) = self.early_span(i, at, line, column, said_outside) {
                self.span_exceeded(axis, ends, (low, high), (line, column), under);
            }
            return;
        }
        // (after a call of a program not read there: crate::check::leaves)
        if self
            .later_shift
            .as_ref()
            .is_some_and(|w| w.watched & 1 << i != 0)
        {
            let column = column();
            self.later_span_grew(i, at, said_outside, (line, column), (low, high), under);
            return;
        }
        let Span { least, most, said } = *span;
        if !said && most - least > (high - low) + 1e-9 {
            span.said = true;
            self.span_exceeded(axis, (least, most), (low, high), (line, column()), under);
        } else if said && !self.call_modes.is_empty() {
            // (a span said under a call's mode: callmode.rs)
            self.call_mode_span_again(i, at, (low, high), (line, column()), under);
        }
    }

    /// TG602 (a FANUC's clamp, TG605): `feed`, read with `factor` to the profile's units
    /// under the feed mode `mode`, above the profile's maximum; `under` follows the numbers
    /// (a subprogram's call, crate::check::called).
    #[cold]
    #[inline(never)]
    pub(super) fn feed_over(
        &mut self,
        feed: Dec,
        factor: f64,
        mode: i64,
        (line, column): (usize, usize),
        under: &str,
    ) {
        let Some(top) = self.config.feed_max else {
            return;
        };
        let message = if factor == 1.0 {
            format!("feed {feed} above the maximum {top}")
        } else {
            // written in the other unit system: said in the profile's too
            let (written, profile) = match self.config.limit_units {
                Units::Metric => ("in", "mm"),
                Units::Inch => ("mm", "in"),
            };
            let per = if mode == 95 { "rev" } else { "min" };
            format!(
                "feed {feed} {written}/{per} ({} {profile}/{per}) above the maximum \
                 {top} {profile}/{per}",
                round6(feed.to_f64() * factor)
            )
        };
        let message = format!(
            "{message}{under}{}",
            self.units_not_written(feed.to_f64() * factor / 25.4 <= top.to_f64() + 1e-9)
        );
        // a FANUC clamps a cutting feed above its parameter's maximum (Power Mate i-D
        // B-63172EN 4.2.2, "Cutting feed rate clamp"; parameter 1422): no alarm, so a
        // warning (issue 32); a Haas alarms (NGC Mill Operator's Manual, G01)
        if self.config.family == Family::MacroB && !self.config.haas {
            let message = format!(
                "{message}: a FANUC clamps a cutting feed to its maximum (no alarm), so \
                 the cut runs slower than programmed"
            );
            self.report_limit(Rule::FeedClamped, message, line, column);
        } else {
            self.report_limit(Rule::FeedTooHigh, message, line, column);
        }
    }

    /// TG601 of [`Checker::add_to_span`]: `axis` spans `least` to `most`, wider than its
    /// travel `low` to `high`.
    #[cold]
    #[inline(never)]
    pub(super) fn span_exceeded(
        &mut self,
        axis: u8,
        (least, most): (f64, f64),
        (low, high): (f64, f64),
        (line, column): (usize, usize),
        under: &str,
    ) {
        let units = self.units_not_written((most - least) / 25.4 <= high - low + 1e-9);
        self.span_said(
            axis,
            (least, most),
            (low, high),
            (line, column),
            under,
            &units,
        );
    }

    /// [`Checker::span_exceeded`] with the units' remark given (a subprogram judged after it
    /// was read, in the units it was read in: crate::check::called).
    pub(super) fn span_said(
        &mut self,
        axis: u8,
        (least, most): (f64, f64),
        (low, high): (f64, f64),
        (line, column): (usize, usize),
        under: &str,
        units: &str,
    ) {
        let message = format!(
            "{} spans {} (from {} to {}), more than the travel {low} to {high}: no work \
             offset fits the program on this machine{under}{units}",
            axis as char,
            round6(most - least),
            round6(least),
            round6(most)
        );
        let before = self.found.len();
        self.report_limit(Rule::TravelExceeded, message, line, column);
        if self.found.len() > before {
            self.found.last_mut().expect("said").span = true;
        }
    }

    /// TG601 of a position in machine coordinates (G53): `value` as written, `at` in the
    /// profile's units. Written in the other unit system, the message says it in both and
    /// names them, as the feed's does (review 38, finding 11: `G21` ... `G53 X800.` on an
    /// inch profile said "X goes to 800 ..., outside the travel -30 to 30").
    #[cold]
    #[inline(never)]
    fn machine_outside(
        &mut self,
        axis: u8,
        value: Dec,
        at: f64,
        (low, high): (f64, f64),
        (line, column): (usize, usize),
    ) {
        let message = self.machine_message(axis, value, at, (low, high));
        self.report_placed(message, (line, column), super::Placed::Machine);
    }

    /// A position of axis place `i` under G`work` (work position `at`) beyond the travel on
    /// the side `out` of an excursion already said: the excursion's finding (the last TG601
    /// under that offset on that axis, not yet handed over) keeps the farthest work position,
    /// which decides where a call judges it with a value a G10 wrote (review 59a, F7: `G0
    /// X-700.` / `G1 X-780.` under a G55 X written 0 runs at -780, beyond; only the -700,
    /// inside, was judged, and the excursion dropped with it).
    #[cold]
    #[inline(never)]
    fn excursion_farther(&mut self, i: usize, work: i64, (at, line): (f64, usize), out: i8) {
        let excursion = self.found.iter_mut().rev().find(|f| {
            f.rule == Rule::TravelExceeded
                && matches!(f.placed, super::Placed::Offset { place, .. } if usize::from(place) == i)
        });
        if let Some(f) = excursion {
            if let super::Placed::Offset {
                work: w,
                at: first,
                line: first_line,
                ..
            } = &mut f.placed
            {
                if i64::from(*w) == work && (at - *first) * f64::from(out) > 0.0 {
                    (*first, *first_line) = (at, line);
                }
            }
        }
    }

    /// [`Checker::offset_position`]'s finding of a position beyond the travel said again on
    /// the side of the excursion before it ([`Checker::call_mode_reopened`]).
    #[cold]
    #[inline(never)]
    fn offset_said_again(
        &mut self,
        ((axis, i), at, (work, offset)): ((u8, usize), f64, (i64, Dec)),
        (low, high): (f64, f64),
        (line, column): (usize, usize),
    ) -> bool {
        let machine_at = at + offset.to_f64();
        let message = format!(
            "{} goes to {} in machine coordinates (work {} + G{work} offset {offset}), outside \
             the travel {low} to {high}",
            axis as char,
            round6(machine_at),
            round6(at)
        );
        let placed = super::Placed::Offset {
            place: i as u8,
            work: work as u8,
            at,
            line,
        };
        self.report_placed(message, (line, column), placed)
    }

    /// A position `at` of `axis` (place `i`) under work offset G`work`, whose value on that
    /// axis is the profile's `offset` unless a G10 of the program's run wrote it: TG601 where
    /// the machine position is beyond the travel, once an excursion. Whether it was said.
    /// (Out of line: read only under a profile that gives work offsets.)
    #[inline(never)]
    fn offset_position(
        &mut self,
        (axis, i): (u8, usize),
        at: f64,
        (work, offset): (i64, Dec),
        (low, high): (f64, f64),
        (line, column): (usize, usize),
    ) -> bool {
        if self.offset_unknown(work, i) {
            self.position_not_judged(i);
            if let Some(said) =
                self.offset_either((axis, i), at, (work, offset), (low, high), (line, column))
            {
                return said;
            }
            self.travel_not(format!(
                "{} under G{work} after its value was set by a variable (#5201-#5326)",
                axis as char
            ));
            return false;
        }
        self.stats.travel_absolute += 1;
        // (a G10 of the program's run with a value known: review 59a F8)
        let written = self.offset_written(work, i);
        let machine_at = at + written.unwrap_or_else(|| offset.to_f64());
        let out = travel_side(machine_at, (low, high));
        let mut said_outside = false;
        let reopened = if out != 0 && out == self.outside[i] && !self.call_modes.is_empty() {
            self.call_mode_reopened(i)
        } else {
            None
        };
        if out != 0 && (out != self.outside[i] || reopened.is_some()) {
            let value = written.map_or_else(
                || offset.to_string(),
                |v| format!("{} as a G10 before wrote it", round6(v)),
            );
            let mut message = format!(
                "{} goes to {} in machine coordinates (work {} + G{work} offset {value}), \
                 outside the travel {low} to {high}",
                axis as char,
                round6(machine_at),
                round6(at)
            );
            if let Some(w) = &self.work_call {
                message.push_str(&w.named(self.in_hand, self.later_label(), work));
            }
            // (one judged with a value written is not judged again at a call with the
            // caller's: its own G10 decides)
            let placed = if written.is_some() {
                super::Placed::Not
            } else {
                super::Placed::Offset {
                    place: i as u8,
                    work: work as u8,
                    at,
                    line,
                }
            };
            let said = self.report_placed(message, (line, column), placed);
            if said && (self.work_guessed.is_some() || self.work_run_on) {
                self.found.last_mut().expect("said").guessed = true;
            }
            if let Some(mark) = reopened.filter(|_| said) {
                self.found.last_mut().expect("said").pending_on.push(mark);
            }
            said_outside = true;
        } else if out != 0 {
            self.excursion_farther(i, work, (at, line), out);
        }
        self.outside[i] = out;
        if written.is_none()
            && self
                .work_call
                .as_ref()
                .is_some_and(|w| w.work == work && !w.others.is_empty())
        {
            self.offset_position_others((axis, i), at, (low, high), (line, column));
        }
        said_outside
    }

    /// In a program written after its calls, run under their offset ([`Checker::work_call`]):
    /// its position `at` on the axis `axis` (place `i`) judged under the offset of each other
    /// call ([`WorkCall::others`](super::structure::WorkCall)), an excursion beyond the
    /// travel said once a call, naming it (issue 32 item 4: `O1000` / `G90 G54` / `M98 P2000`
    /// / `G55` / `M98 P2000` / `M30` / `O2000` / `G0 X-700.` / `M99` runs X-700. at -800 at
    /// the second call; calls under different offsets left it not compared).
    #[cold]
    #[inline(never)]
    fn offset_position_others(
        &mut self,
        (axis, i): (u8, usize),
        at: f64,
        (low, high): (f64, f64),
        at_line: (usize, usize),
    ) {
        let w = &self.offsets_written;
        if w.any() || w.moved || w.shifted != 0 || self.work_guessed.is_some() || self.work_run_on {
            return;
        }
        let Some(mut call) = self.work_call.take() else {
            return;
        };
        let mut held = false;
        // (after a G90/G91 of its own, its positions are in its own mode at every call)
        let own_mode = self.machine.distance_codes != call.codes_at;
        // (before a units code of its own, in the units the run before leaves: F9)
        let rescaled = self.machine.units_codes == call.units_codes_at;
        if !rescaled && !call.units_cut {
            // (an excursion said before its units code may be judged again in other units at
            // its end, and dropped: one after the code is said on its own)
            call.units_cut = true;
            let said = |k: usize| call.rescale.iter().any(|r| r.other_said(k));
            let cut: Vec<bool> = (0..call.others.len()).map(said).collect();
            for (o, _) in call.others.iter_mut().zip(cut).filter(|(_, c)| *c) {
                o.3 = [0; 9];
            }
        }
        for (k, (work, words, line, outside, tentative, left)) in call.others.iter_mut().enumerate()
        {
            let Some(offset) = self
                .config
                .work_offsets
                .iter()
                .find(|&&(g, a, _)| g == *work && a == axis)
                .map(|&(_, _, v)| v)
            else {
                continue;
            };
            if rescaled && *left {
                let marks = [
                    PENDING_OTHER_CALL - (*work - 54).clamp(0, 5),
                    if *tentative && !own_mode {
                        PENDING_MODE_SELF
                    } else {
                        0
                    },
                ];
                let place = (axis, i, offset, (low, high));
                let named = || {
                    let named = super::structure::WorkCall::named_by(
                        self.in_hand,
                        self.later_label(),
                        words,
                        *line,
                    );
                    (*work, named)
                };
                super::callmode::Rescale::judged(
                    &mut call.rescale,
                    (k, named),
                    place,
                    (at, at_line),
                    marks,
                );
                held = true;
            }
            let machine_at = at + offset.to_f64();
            let out = travel_side(machine_at, (low, high));
            if out != 0 && out != outside[i] {
                let message = format!(
                    "{} goes to {} in machine coordinates (work {} + G{work} offset {offset}), \
                     outside the travel {low} to {high}{}",
                    axis as char,
                    round6(machine_at),
                    round6(at),
                    super::structure::WorkCall::named_by(
                        self.in_hand,
                        self.later_label(),
                        words,
                        *line
                    )
                );
                if self.report_placed(message, at_line, super::Placed::Not) {
                    if let Some(f) = self.found.last_mut() {
                        f.pending_on
                            .push(PENDING_OTHER_CALL - (*work - 54).clamp(0, 5));
                        if *tentative && !own_mode {
                            f.pending_on.push(PENDING_MODE_SELF);
                        }
                        held = true;
                        if rescaled && *left {
                            super::callmode::Rescale::said(&mut call.rescale, k, i, f);
                        }
                    }
                }
            }
            outside[i] = out;
        }
        call.held |= held;
        self.work_call = Some(call);
    }

    /// The value a G10 of the program's run wrote, known, of offset G`work` on the axis of
    /// place `i` (review 59a F8); None where none was written (the profile's holds).
    #[inline]
    fn offset_written(&self, work: i64, i: usize) -> Option<f64> {
        if !self.offsets_written.any() {
            return None;
        }
        usize::try_from(work)
            .ok()
            .and_then(|w| self.offsets_written.value(w, i))
            .filter(|v| !v.is_nan())
    }

    /// LinuxCNC: a position under a work offset whose value is one of two (the value before a
    /// parameter write or the one written, [`Written::maybe_of`]: a write of G54 before the
    /// program's first selection, then G54), both known: beyond the travel under both, said
    /// (review 77-lcnc77a F5: `#5221=-300` / `G54` / `G0 X-800` runs at -800 in `rs274 -g`,
    /// -1100 where the write is loaded). Whether it was said; None where not judged so.
    #[cold]
    #[inline(never)]
    fn offset_either(
        &mut self,
        (axis, i): (u8, usize),
        at: f64,
        (work, offset): (i64, Dec),
        (low, high): (f64, f64),
        (line, column): (usize, usize),
    ) -> Option<bool> {
        let (before, written) = self
            .offsets_written
            .maybe_of(usize::try_from(work).ok()?, i)?;
        let before = if before.is_nan() {
            offset.to_f64()
        } else {
            before
        };
        if written.is_nan() || self.config.family != Family::LinuxCnc {
            return None;
        }
        self.stats.travel_absolute += 1;
        let (one, two) = (at + before, at + written);
        let out = travel_side(one, (low, high));
        let said = out != 0 && out == travel_side(two, (low, high));
        if said && out != self.outside[i] {
            let message = format!(
                "{} goes to {} in machine coordinates (work {} + G{work} offset {}), or to {} \
                 where a parameter write before loaded {}, outside the travel {low} to {high} \
                 either way",
                axis as char,
                round6(one),
                round6(at),
                round6(before),
                round6(two),
                round6(written)
            );
            self.report_placed(message, (line, column), super::Placed::Not);
        }
        self.outside[i] = if said { out } else { 0 };
        Some(said)
    }

    /// That offset's axis was written with a value not known while the profile's offsets
    /// are still followed (a system variable set after a known G10, review 59a F11).
    #[inline]
    fn offset_unknown(&self, work: i64, i: usize) -> bool {
        self.offsets_written.any()
            && usize::try_from(work)
                .ok()
                .and_then(|w| self.offsets_written.value(w, i))
                .is_some_and(f64::is_nan)
    }

    /// TG601 of one machine position (`placed`: what it compared, kept on the finding for
    /// the calls that judge it again, called.rs): whether it was said (selected).
    pub(super) fn report_placed(
        &mut self,
        message: String,
        (line, column): (usize, usize),
        placed: super::Placed,
    ) -> bool {
        let before = self.found.len();
        self.report_limit(Rule::TravelExceeded, message, line, column);
        let said = self.found.len() > before;
        if said {
            let f = self.found.last_mut().expect("said");
            f.placed = placed;
            // (after calls of programs not read there, re-selected: review 61a F13)
            if !self.offsets_written.unread.is_empty() {
                // (a mark of the caller's mode after a call kept: callmode.rs)
                f.pending_on.retain(|&m| super::callmode::is_mark(m));
                f.pending_on.extend_from_slice(&self.offsets_written.unread);
                f.pending_on.push(PENDING_OWN);
            }
            // (a subprogram's own offset after its own units code: review 60 F4)
            if let Some(n) = self.units_merged {
                if matches!(placed, super::Placed::Offset { .. }) && self.work_guessed.is_none() {
                    f.pending_on.push(PENDING_CALLS_WRITTEN - n);
                }
            }
        }
        said
    }

    /// The message of [`Checker::machine_outside`], `value` read in the units in force (a
    /// subprogram's G53 position judged at its call: crate::check::called).
    pub(super) fn machine_message(
        &self,
        axis: u8,
        value: Dec,
        at: f64,
        (low, high): (f64, f64),
    ) -> String {
        let axis = axis as char;
        let message = if self.to_profile_units(false) == 1.0 {
            format!(
                "{axis} goes to {value} in machine coordinates (G53), outside the travel {low} \
                 to {high}"
            )
        } else {
            let (written, profile) = match self.config.limit_units {
                Units::Metric => ("in", "mm"),
                Units::Inch => ("mm", "in"),
            };
            format!(
                "{axis} goes to {value} {written} ({} {profile}) in machine coordinates (G53), \
                 outside the travel {low} to {high} {profile}",
                round6(at)
            )
        };
        let fits = (low..=high).contains(&(at / 25.4));
        format!("{message}{}", self.units_not_written(fits))
    }

    /// A finding against the profile's machine (TG601, TG602, TG604, TG605): the file's first
    /// on a built-in profile says that the travel and maxima are the profile's sample machine
    /// of the family, not the user's (audit 37: a VF-6 class table, a 30-tool changer and a
    /// Robodrill checked against the built-in profiles' typical machines).
    /// The limit's own: a user's file on a base that sets it (the travel: every axis's) is the
    /// user's machine, no hint; one it leaves to the base is the sample's (review 38, 4).
    #[cold]
    pub(super) fn report_limit(&mut self, rule: Rule, message: String, line: usize, column: usize) {
        if matches!(
            rule,
            Rule::TravelExceeded | Rule::FeedTooHigh | Rule::FeedClamped
        ) {
            self.early_hold();
        }
        // (on the first finding shown: one `--select`/`--ignore` leaves out never carries it,
        // review 49b, R6)
        let message = match self.sample_hint(rule) {
            Some(hint) if !self.limits_hint_said && self.selection.enabled(rule) => {
                self.limits_hint_said = true;
                format!("{message}{hint}")
            }
            _ => message,
        };
        self.report(rule, message, line, column);
    }

    /// What the file's first finding of `rule` against the profile's machine (TG601, TG602,
    /// TG604, TG605) adds where the limit is the built-in profile's sample machine
    /// ([`Checker::report_limit`]); None where it is the user's own, or of another rule.
    #[cold]
    pub(super) fn sample_hint(&self, rule: Rule) -> Option<&'static str> {
        let limit = match rule {
            Rule::TravelExceeded => super::SAMPLE_TRAVEL,
            Rule::FeedTooHigh | Rule::FeedClamped => super::SAMPLE_FEED,
            Rule::ToolOutOfRange => super::SAMPLE_TOOLS,
            _ => return None,
        };
        if self.config.sample_limits & limit == 0 {
            None
        } else if self.config.sample_limits == super::SAMPLE_ALL {
            Some(
                " (the built-in profile's limits are a typical machine of the family: a \
                 profile of your machine, `base` and its [limits], checks against yours; said \
                 once)",
            )
        } else {
            // a user's file on a base that leaves this limit to it
            Some(
                " (this limit is the base profile's, a typical machine of the family: the \
                 profile's own [limits] do not set it; said once)",
            )
        }
    }

    /// A subprogram read apart returned (crate::check::called's `early_pend`): its limits'
    /// findings, `taken` out of those said, are said at its calls or at the file's end, if
    /// at all. Where one of them carried the sample machine's hint, the hint goes from it to
    /// the first finding said after all (review 48, F17: a body's TG601 at its call lacked
    /// it, spent on the body's own finding, never shown): the first of `kept` (said now)
    /// that takes one, else the next made or said ([`Checker::sample_hint_shown`]).
    #[cold]
    #[inline(never)]
    pub(super) fn sample_hint_taken(
        &mut self,
        taken: &mut [&mut Vec<Finding>],
        kept: &mut [Finding],
    ) {
        if !self.limits_hint_said {
            return;
        }
        let mut found = false;
        for f in taken.iter_mut().flat_map(|list| list.iter_mut()) {
            let Some(hint) = self.sample_hint(f.rule) else {
                continue;
            };
            if let Some(at) = f.message.find(hint) {
                f.message.replace_range(at..at + hint.len(), "");
                found = true;
                break;
            }
        }
        if !found {
            return;
        }
        self.limits_hint_said = false;
        for f in kept {
            self.sample_hint_shown(f);
        }
    }

    /// A finding of a limit said (again) out of the order it was made in (a subprogram's,
    /// at its call or at the file's end): the sample machine's hint, where none was said yet.
    #[cold]
    pub(super) fn sample_hint_shown(&mut self, f: &mut Finding) {
        if self.limits_hint_said {
            return;
        }
        if let Some(hint) = self
            .sample_hint(f.rule)
            .filter(|_| self.selection.enabled(f.rule))
        {
            self.limits_hint_said = true;
            f.message.push_str(hint);
        }
    }

    /// What a limit's message adds where the program has written no units code and the
    /// profile's units are inches: the numbers are read in the units the machine is set to at
    /// power-on, which the profile assumes, and read in millimetres they would fit (`fits`):
    /// a metric shop's program that writes no G21, on a Haas set to mm by Setting 9 (audit 37:
    /// `Z150.` taken for 150 in). Empty otherwise.
    #[cold]
    fn units_not_written(&self, fits: bool) -> String {
        if self.machine.state.units_given
            || self.config.limit_units != Units::Inch
            || self.machine.state.units != Units::Inch
            || !fits
        {
            return String::new();
        }
        self.units_remark()
    }

    /// [`Checker::units_not_written`]'s words (a subprogram's machine position said at a call
    /// made after a units code leaves them out, crate::check::called; review 46, F5).
    pub(super) fn units_remark(&self) -> String {
        let setting = if self.config.haas {
            " (a Haas's Setting 9)"
        } else {
            ""
        };
        format!(
            "; the program has written no units code by here, so its numbers are read in \
             inches, the \
             units the profile takes the machine to be set to{setting}: read in millimetres \
             they fit (`check --units metric` for a machine set to mm)"
        )
    }

    /// The block's X Y Z under an exact rotation or scaling, taken back to the coordinates
    /// before it and added to the spans: each axis once every axis it is made of has been
    /// given as an absolute position under the frame.
    fn mapped_spans(&mut self, moved: &[u8], line: usize, facts: &Facts<'_>) {
        // (a block whose axis words are no move -- the frame's own centre, a G92 -- moves
        // nothing under the frame)
        if !matches!(self.machine.taken(), None | Some(AxesTaken::Positions)) {
            return;
        }
        let absolute = !self.machine.state.incremental;
        let factor = self.to_profile_units(false);
        let position: [Option<f64>; 3] = std::array::from_fn(|k| {
            self.machine
                .state
                .axis(AXES[k])
                .map(|p| p.to_f64() * factor)
        });
        let Some(map) = self.frames.map.as_mut() else {
            return;
        };
        let mut now = 0u8;
        for &axis in moved {
            if let Some(k) = axis_index(axis).filter(|&k| k < 3) {
                now |= 1 << k;
            }
        }
        // a Haas's scaling and a canned cycle's Z: "scaling does not affect canned cycle Z-axis
        // movements such as clearance planes and incremental values" (Mill Operator's Manual,
        // G51, programming notes); whether the cycle's Z depth is scaled it leaves open: Z
        // left out of the spans, and where Z stands in the frame after it not known
        let cycle_z = self.config.haas
            && map.bit == 2
            && self.machine.state.cycle.is_some()
            && now & 0b100 != 0;
        if cycle_z {
            now &= !0b100;
            map.fresh &= !0b100;
        }
        if absolute {
            map.fresh |= now;
        }
        map.touched |= now;
        let map = map.clone();
        let under = format!(
            " (its positions under the {} taken back to the coordinates before it)",
            map.what
        );
        // the axes moved before every axis they are made of was given under the frame
        let mut waiting = 0u16;
        for k in 0..3 {
            let made_of = (0..3)
                .filter(|&l| map.m[k][l] != 0.0)
                .fold(0u8, |all, l| all | 1 << l);
            if made_of & now == 0 {
                continue;
            }
            if made_of & !map.fresh != 0 {
                waiting |= 1 << k;
                continue;
            }
            if map.fresh & 1 << k != 0 && made_of == 1 << k && map.m[k][k] == 1.0 {
                // an axis the frame leaves as it is
                if let Some(p) = position[k].filter(|_| self.frames.hidden() & (1 << k) == 0) {
                    let p = self.shifted(k, p);
                    self.add_to_span(k, p, false, line, || facts.col(AXES[k]), "");
                }
                continue;
            }
            let mut at = map.centre[k];
            for l in (0..3).filter(|&l| made_of & 1 << l != 0) {
                let Some(p) = position[l] else {
                    at = f64::NAN;
                    break;
                };
                at += map.m[k][l] * (p - map.centre[l]);
            }
            if at.is_nan() || self.frames.hidden() & (1 << k) != 0 {
                continue;
            }
            // said at the first word of the block that moved it
            let column = || {
                (0..3)
                    .find(|&l| made_of & now & 1 << l != 0)
                    .map_or(0, |l| facts.col(AXES[l]))
            };
            let at = self.shifted(k, at);
            self.add_to_span(k, at, false, line, column, &under);
        }
        if cycle_z {
            self.frame_note(
                &map.what,
                0b100,
                (line, facts.col(b'Z')),
                "in a canned cycle, nor after it until Z is given there as an absolute position",
                "the Haas manual says scaling leaves a canned cycle's Z moves (its clearance \
                 plane, its increments) as written, and leaves open whether the cycle's Z depth \
                 is scaled",
            );
        }
        if waiting != 0 {
            // (said at the block's first moved axis)
            let column = moved.first().map_or(0, |&axis| facts.col(axis));
            self.frame_note(
                &map.what,
                waiting,
                (line, column),
                "until every axis they are made of is given there as an absolute position",
                "before that, where the tool stands in the frame's coordinates is not known",
            );
        }
    }
}

/// The frame variable an assignment sets (`$P_PFRAME`, `$P_UIFR[1,X,TR]`, `$P_CHBFR[0]`), if
/// its target is one: a SINUMERIK system variable `$P_` whose name ends in `FRAME` (a frame in
/// force: `$P_IFRAME`, `$P_PFRAME`, `$P_BFRAME`, `$P_ACTBFRAME`...) or `FR` (a frame of the
/// data management that G500, G54-G599 activate: `$P_UIFR`, `$P_CHBFR`, `$P_NCBFR`, the
/// system frames `$P_EXTFR`, `$P_PARTFR`...). Function Manual Basic functions, "Axes,
/// coordinate systems, frames (K2)", its list of system variables; Programming Guide Advanced,
/// "Frames": `$P_PFRAME=CTRANS(X,10)` is the programmable frame, as `TRANS X10`.
fn frame_variable(text: &[u8]) -> Option<&[u8]> {
    let end = text
        .iter()
        .position(|&c| !(c.is_ascii_alphanumeric() || c == b'_' || c == b'$'))
        .unwrap_or(text.len());
    let name = &text[..end];
    let rest = text[end..].trim_ascii_start();
    let assigned = match rest.first() {
        Some(b'=') => true,
        // an index or a component: $P_UIFR[1,X,TR]=10
        Some(b'[') => {
            crate::statement::brackets(rest, 0)
                .ok()
                .and_then(|end| rest[end..].trim_ascii_start().first().copied())
                == Some(b'=')
        }
        _ => false,
    };
    (assigned && name.starts_with(b"$P_") && (name.ends_with(b"FRAME") || name.ends_with(b"FR")))
        .then_some(name)
}

/// Which side of the travel `(low, high)` the machine position `at` is outside: -1 below, 1
/// above, 0 inside (within 1e-9). A move from one side to the other crosses the travel:
/// another excursion (TG601 said once an excursion).
#[inline]
pub(super) fn travel_side(at: f64, (low, high): (f64, f64)) -> i8 {
    if at < low - 1e-9 {
        -1
    } else if at > high + 1e-9 {
        1
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{
        dialect, fanuc_lathe, findings, fired, iso_mill, of_family, okuma_lathe, program, run,
    };
    use super::super::{Config, ProfileFacts};
    use crate::decimal::Dec;
    use crate::lex::{Family, GCodeSystem};
    use crate::modal::Units;
    use crate::rules::Rule;

    fn at(config: Config, body: &str, rule: Rule) -> Vec<(usize, usize)> {
        fired(config, &program(body), rule)
    }

    /// The iso-mill with its G54 X at -200 and Y at 0 (machine positions, mm).
    fn with_offsets() -> Config {
        let dec = |text: &str| Dec::parse(text).unwrap();
        Config {
            facts: ProfileFacts {
                work_offsets: vec![(54, b'X', dec("-200")), (54, b'Y', dec("0"))],
                ..iso_mill().facts
            },
            ..iso_mill()
        }
    }

    /// The travel table holds what the profile's list gives each letter (the first entry of
    /// a letter listed twice), and nothing for a letter it does not list or a byte that is no
    /// capital letter.
    /// A FANUC with G code system A's centre codes (G51.1, G68 and the like take a centre)
    fn fanuc_centres() -> Config {
        let mut fanuc = of_family(Family::MacroB);
        fanuc.modal.centre_codes = true;
        fanuc
    }

    /// A Haas: centre codes, and its own mirror codes (G101/G100)
    fn haas_centres() -> Config {
        let mut haas = fanuc_centres();
        haas.haas = true;
        haas
    }

    /// The two mirror images with a cancel naming axes: a Haas's G101/G100, a FANUC's
    /// G51.1/G50.1 (the control, its mirror code, its cancel)
    fn mirror_controls() -> [(Config, &'static str, &'static str); 2] {
        [
            (haas_centres(), "G101", "G100"),
            (fanuc_centres(), "G51.1", "G50.1"),
        ]
    }

    #[test]
    fn the_travel_table_finds_what_the_list_finds() {
        let dec = |text: &str| Dec::parse(text).unwrap();
        let config = Config {
            facts: ProfileFacts {
                travel: vec![
                    (b'X', dec("-500"), dec("0.125")),
                    (b'Z', dec("-1.0000001"), dec("600")),
                    (b'X', dec("-1"), dec("1")),
                    (b'B', dec("-360"), dec("360")),
                ],
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let travel = super::Travel::new(&config);
        for letter in 0..=255u8 {
            let listed = config
                .travel
                .iter()
                .find(|(a, _, _)| *a == letter)
                .map(|&(_, l, h)| (l.to_f64(), h.to_f64()));
            assert_eq!(travel.of(letter), listed, "{}", letter as char);
        }
        assert_eq!(travel.of(b'X'), Some((-500.0, 0.125)));
        assert_eq!(travel.of(b'Y'), None);
        // by the places of AXES (the spans' walk)
        for (i, &axis) in crate::modal::AXES.iter().enumerate() {
            assert_eq!(travel.of_place(i), travel.of(axis), "{}", axis as char);
            assert_eq!(
                travel.places() >> i & 1 == 1,
                travel.of(axis).is_some(),
                "{}",
                axis as char
            );
        }
    }

    #[test]
    fn the_spans_of_a_block_s_axes_each_against_its_travel() {
        // iso_mill: X -500 to 500, Y -400 to 400, Z -300 to 100, no travel of B, no work
        // offsets (each axis's position only goes to its span): Y spans 850 and Z 450 at the
        // second block, each said at its word; X 1050 at the third
        let moves = "G00 X-400. Y-300. Z-100.\nX300. Y550. Z350. B10.\nX650.";
        assert_eq!(
            at(iso_mill(), moves, Rule::TravelExceeded),
            [(3, 7), (3, 13), (4, 1)]
        );
        // at a bound of the span so far, and back inside: nothing more
        let bounds = "G00 X-400. Y-300.\nX400. Y300.\nX-400. Y0\nX0 Y-300.";
        assert_eq!(at(iso_mill(), bounds, Rule::TravelExceeded), []);
    }

    #[test]
    fn a_frame_variable_is_one_an_assignment_sets() {
        use super::frame_variable;
        let set = |text: &str| frame_variable(text.as_bytes()).map(<[u8]>::to_vec);
        assert_eq!(set("$P_PFRAME=CTRANS(X,-300)"), Some(b"$P_PFRAME".to_vec()));
        assert_eq!(set("$P_UIFR[1,X,TR] = 10"), Some(b"$P_UIFR".to_vec()));
        assert_eq!(
            set("$P_CHBFR[0]=$P_CHBFR[0]:CROT(Z,90)"),
            Some(b"$P_CHBFR".to_vec())
        );
        // read, not set; not a frame; a frame of the program's own
        assert_eq!(set("R1=$P_PFRAME[X,TR]"), None);
        assert_eq!(set("$P_UIFRNUM"), None);
        assert_eq!(set("$P_TOOLNO=3"), None);
        assert_eq!(set("MYFRAME=CTRANS(X,10)"), None);
    }

    /// A Haas-like mill: reset in inches (G20), travel X -30..30 in, feed to 30 in/min.
    fn inch_mill() -> Config {
        let dec = |text: &str| Dec::parse(text).unwrap();
        let mut config = of_family(Family::MacroB);
        config.haas = true;
        config.facts.program_number = Some(b'O');
        config.modal.inch = 20;
        config.modal.metric = 21;
        config.modal.default_units = Units::Inch;
        config.modal.reset = vec![0, 17, 20, 40, 80, 90, 94];
        config.modal.units_kept_at_end = true;
        config.facts.travel = vec![(b'X', dec("-30"), dec("30"))];
        config.facts.feed_max = Some(dec("30"));
        config.facts.limit_units = Units::Inch;
        config
    }

    #[test]
    fn a_subprogram_after_the_end_is_read_in_the_units_of_its_calls() {
        // (review 38, finding 10) O1000 after M30, called under G21: X900. is 900 mm, inside
        // 60 inches of travel, and F700. is 700 mm/min (27.6 in/min); read in the reset G20 it was 900 in
        let sub = |units: &str, body: &str| {
            format!("%\nO1\n{units}\nG0 G90 X0 Y0\nM98 P1000\nM30\nO1000\n{body}\nM99\n%\n")
        };
        let limits = |text: &str| {
            let mut found = fired(inch_mill(), text, Rule::TravelExceeded);
            found.extend(fired(inch_mill(), text, Rule::FeedTooHigh));
            found
        };
        assert_eq!(limits(&sub("G21", "G1 X900. F700.")), []);
        // called under G20: inches, as before
        assert_eq!(limits(&sub("G20", "G1 X900. F700.")), [(8, 4), (8, 10)]);
        // its own G21 under a G20 caller
        assert_eq!(limits(&sub("G20", "G21\nG1 X900. F700.")), []);
        // too far and too fast in the caller's millimetres too: still said
        assert_eq!(limits(&sub("G21", "G1 X2000. F999.")), [(8, 4), (8, 11)]);
        // the program after the end that no call names is a program of its own, read from the
        // reset state (G20) as the file's first is; its span is its own, not added to the
        // main program's (its caller, and the work offset it runs under, are not known: review
        // 55b, F4), so one position is no TG601 and two 1800 in apart are, from its own G90
        // on (its caller's G90/G91 is not known either: review 56b, F10)
        let alone = "%\nO1\nG21\nG0 G90 X0 Y0\nM30\nO1000\nG90\nG1 X900. F700.\nM99\n%\n";
        assert_eq!(limits(alone), [(8, 10)]);
        let wide = alone.replace("F700.\n", "F700.\nX-900.\n");
        assert_eq!(limits(&wide), [(9, 1), (8, 10)]);
        // without it, the two may be increments (900 in, then back): no span judged
        let unsure = wide.replace("G90\n", "");
        assert_eq!(limits(&unsure), [(7, 10)]);
        // a call of a program the file does not hold (O2000, stored on the control, may call
        // O1000): its span joined to the main's, as before (review 56e, F5)
        assert_eq!(
            limits(&sub("G21", "G1 X900. F700.").replace("P1000", "P2000")),
            [(8, 4), (8, 10)]
        );
    }

    #[test]
    fn a_subprogram_whose_calls_disagree_on_the_units_is_not_judged_until_it_writes_them() {
        // called under G21 and under G20: its lengths are in units not known
        let text = |body: &str| {
            format!(
                "%\nO1\nG21\nG0 G90 X0 Y0\nM98 P1000\nG20\nM98 P1000\nM30\nO1000\n{body}\nM99\n%\n"
            )
        };
        let limits = |text: &str| {
            let mut found = fired(inch_mill(), text, Rule::TravelExceeded);
            found.extend(fired(inch_mill(), text, Rule::FeedTooHigh));
            found
        };
        assert_eq!(limits(&text("G1 X900. F700.")), []);
        // its own G21: known from there, and 2000 mm past the travel found
        assert_eq!(
            limits(&text("G1 X900. F700.\nG21\nG1 X2000. F999.")),
            [(12, 4), (12, 11)]
        );
        // a subprogram it calls in those unknown units is read in unknown units too
        let nested = "%\nO1\nG21\nM98 P1000\nG20\nM98 P1000\nM30\nO1000\nM98 P2000\nM99\n\
                      O2000\nG1 X900. F700.\nM99\n%\n";
        assert_eq!(limits(nested), []);
    }

    #[test]
    fn the_span_starts_again_after_a_shift_of_the_coordinates() {
        // X-400. then, after G52 X-400. (or G92 X0 there), X700. is X300. in the coordinates
        // before: a span of 700, not 1100
        for shift in ["G52 X-400.", "G92 X0", "G10 L2 P1 X-400."] {
            let body = format!("G00 X-400.\n{shift}\nX0\nX700.\n");
            assert_eq!(at(iso_mill(), &body, Rule::TravelExceeded), [], "{shift}");
        }
        // a shift of Y leaves X's span as it was
        let body = "G00 X-400.\nG52 Y10.\nX700.\n";
        assert_eq!(at(iso_mill(), body, Rule::TravelExceeded), [(4, 1)]);
    }

    /// Review 38, finding 6: a FANUC or Haas mill's G52 written with its value under G90, and
    /// a G92 where the position before it is known, are followed: each span is kept in the
    /// coordinates of the file's start, so an over-travel across the shift is found (it was
    /// missed: the span started again), and a program that stays in the travel only through
    /// the shift is not flagged. Travel X -500 to 500.
    #[test]
    fn a_shift_whose_amount_is_known_is_followed_by_the_spans() {
        let fanuc = of_family(Family::MacroB);
        let mut haas = of_family(Family::MacroB);
        haas.haas = true;
        for config in [fanuc.clone(), haas.clone()] {
            // X-400., then X0 and X300. of a local zero at X500.: 500 and 800, a span of 1200
            let over = "G90 G00 X-400.\nG52 X500.\nG01 X0 F100.\nX300.\nG52 X0\nX0\n";
            assert_eq!(at(config.clone(), over, Rule::TravelExceeded), [(5, 1)]);
            // the same through G92 at X-400. (its zero is then X500. of the old coordinates)
            let over = "G90 G00 X-400.\nG92 X-900.\nG01 X0 F100.\nX300.\n";
            assert_eq!(at(config.clone(), over, Rule::TravelExceeded), [(5, 1)]);
            // X400., then a local zero at X800.: X-300. and X-700. are 500 and 100, a span of
            // 400 (the numbers as written span 1100)
            let inside = "G90 G00 X400.\nG52 X800.\nG01 X-300. F100.\nX-700.\n";
            assert_eq!(at(config.clone(), inside, Rule::TravelExceeded), []);
            // a G92's words are no position of the coordinates before it (X-600. beside X450.
            // spanned 1050); the tool stays at X450.
            let inside = "G90 G00 X450.\nG92 X-600.\nG01 X-1000. F100.\n";
            assert_eq!(at(config.clone(), inside, Rule::TravelExceeded), []);
            // an axis the G52 does not name keeps its shift: Y's G52 leaves X's local zero at
            // X500.
            let kept = "G90 G00 X-400.\nG52 X500.\nG52 Y10.\nX300.\n";
            assert_eq!(at(config.clone(), kept, Rule::TravelExceeded), [(5, 1)]);
            // G52 X0 cancels it: X300. is X300. again
            let cancelled = "G90 G00 X-400.\nG52 X500.\nX0\nG52 X0\nX50.\n";
            assert_eq!(at(config.clone(), cancelled, Rule::TravelExceeded), []);
            // no note where every shift is followed
            assert_eq!(at(config, over, Rule::NotFollowed), []);
        }
        // G91 across a shift: after G92 X0 at X-400. the increments are followed from X0
        // (X-400. in the span's coordinates): X500. X500. X100. end at 700, a span of 1100
        let increments = "G90 G00 X-400.\nG92 X0\nG91 G01 X500. F100.\nX500.\nX100.\n";
        assert_eq!(
            at(fanuc.clone(), increments, Rule::TravelExceeded),
            [(6, 1)]
        );
        // after a G52 where X stands in the new coordinates is not known until an absolute X
        let increments = "G90 G00 X-400.\nG52 X500.\nG91 X100.\nG90 X300.\n";
        assert_eq!(
            at(fanuc.clone(), increments, Rule::TravelExceeded),
            [(5, 5)]
        );
        // a G52 under G91 where no local shift is in force: the zero at X500. by either
        // reading (from the work zero, or from the local zero, which is it)
        let g91 = "G90 G00 X-400.\nG91 G52 X500.\nG90 X300.\n";
        assert_eq!(at(fanuc.clone(), g91, Rule::TravelExceeded), [(4, 5)]);
        // a Haas removes its G52 at M30: X-550. after it is in the work system, 1050 from the
        // X500. before; a FANUC's end keeps it or not by a parameter: the span starts again,
        // said when a position after the end comes to it
        let end = "G90 G00 X-400.\nG52 X100.\nX400.\nM30\nX-550.\n";
        assert_eq!(at(haas.clone(), end, Rule::TravelExceeded), [(6, 1)]);
        assert_eq!(at(haas, end, Rule::NotFollowed), []);
        assert_eq!(at(fanuc.clone(), end, Rule::TravelExceeded), []);
        let noted = findings(fanuc.clone(), &program(end), Rule::NotFollowed);
        assert_eq!(noted.len(), 1);
        assert_eq!((noted[0].line, noted[0].column), (5, 1));
        assert!(noted[0]
            .message
            .starts_with("M30: the span of X (TG601) starts again here"));
        // an end with no position after it says nothing
        let ended = "G90 G00 X-400.\nG52 X100.\nX400.\nM30\n";
        assert_eq!(at(fanuc, ended, Rule::NotFollowed), []);
    }

    /// Where a shift's amount is not known the span starts again, said once per file as a
    /// note (TG140) that names the reason and what the check follows; nothing is said where
    /// no span was dropped (a G92 before any move).
    #[test]
    fn a_shift_whose_amount_is_not_known_starts_the_span_again_with_a_note() {
        let fanuc = of_family(Family::MacroB);
        for (body, why) in [
            // G28 leaves X where the program's coordinates do not say
            (
                "G90 G00 X-400.\nG91 G28 X0\nG90 G92 X0\nX900.\n",
                "where X stood before it",
            ),
            (
                "G90 G00 X-400.\nG52 X100.\nG91 G52 X500.\nG90 X900.\n",
                "under G91",
            ),
            (
                "G54 G90 G00 X-400.\nG10 L2 P1 X100.\nX900.\n",
                "it may set the offset of the work system in force",
            ),
            // a G92 of X while a local shift of X is in force may have ended it
            (
                "G90 G00 X-400.\nG52 X100.\nX0\nG92 X0\nG52 X0\nX900.\n",
                "the local shift of X before it is not known",
            ),
            // a preset of the work system
            (
                "G90 G00 X-400.\nG92 X0\nG92.1 X0\nX900.\n",
                "the offsets in force before",
            ),
        ] {
            assert_eq!(at(fanuc.clone(), body, Rule::TravelExceeded), [], "{body}");
            let noted = findings(fanuc.clone(), &program(body), Rule::NotFollowed);
            assert_eq!(noted.len(), 1, "{body}");
            assert!(
                noted[0].message.contains(why),
                "{body}: {}",
                noted[0].message
            );
        }
        // a G92 before any move drops no span: nothing to say
        let first = "G90 G91 G28 X0\nG90 G92 X0\nX900.\n";
        assert_eq!(at(fanuc.clone(), first, Rule::NotFollowed), []);
        // LinuxCNC's G52 (the offset it shares with G92) and a SINUMERIK's G92: not followed
        let linuxcnc = of_family(Family::LinuxCnc);
        let body = "G90 G00 X-400.\nG52 X500.\nX900.\n";
        assert_eq!(at(linuxcnc.clone(), body, Rule::TravelExceeded), []);
        assert_eq!(at(linuxcnc.clone(), body, Rule::NotFollowed).len(), 1);
        // its G92 at a known position is: G92 X0 at X-400., X900. is 500, a span of 900;
        // X1100. is 700, 1100
        let body = "G90 G00 X-400.\nG92 X0\nX900.\nX1100.\n";
        assert_eq!(at(linuxcnc, body, Rule::TravelExceeded), [(5, 1)]);
    }

    /// Review 39, finding 1: a G92 whose shift is not followed (the position before it not
    /// known: `G92 X0 Y0 Z0` at a program's start, or after G91 moves from the unknown start)
    /// starts the new span where the tool stands, at its words' values, so the next moves
    /// span from there. Travel X -500 to 500.
    #[test]
    fn a_g92_puts_where_the_tool_stands_in_the_new_span() {
        for family in [Family::MacroB, Family::LinuxCnc] {
            let config = of_family(family);
            // the tool at X0 of the new coordinates goes 1100: more than 1000 of travel
            let start = "G21 G90\nG92 X0 Y0 Z0\nG0 X1100.\n";
            assert_eq!(at(config.clone(), start, Rule::TravelExceeded), [(4, 4)]);
            // G91 from the unknown start: the tool at X-500. of the new ones goes to 600
            let g91 = "G21 G91\nG0 X-200. Y0\nG92 X-500.\nG0 X1100.\n";
            assert_eq!(at(config.clone(), g91, Rule::TravelExceeded), [(5, 4)]);
            // within the travel from there: nothing
            let inside = "G21 G90\nG92 X0 Y0 Z0\nG0 X900.\nX-50.\n";
            assert_eq!(at(config.clone(), inside, Rule::TravelExceeded), []);
            // a shift followed: the point is where the tool stood, nothing changes (X450.
            // then X-1000. of a zero at X1050.: 50, a span of 400; X1100. after G92 X0 at X-400. is 700)
            let followed = "G90 G00 X450.\nG92 X-600.\nG01 X-1000. F100.\n";
            assert_eq!(at(config.clone(), followed, Rule::TravelExceeded), []);
            let followed = "G90 G00 X-400.\nG92 X0\nX1100.\n";
            assert_eq!(at(config, followed, Rule::TravelExceeded), [(4, 1)]);
        }
    }

    /// Review 41, finding 1: a G92 in a block that also writes a units code (the commonest
    /// header, `G21 G90 G92 X0 Y0 Z0`) puts where the tool stands in the new span too, its
    /// words in the units the block sets (a FANUC block's G20/G21 governs its own words;
    /// LinuxCNC sets the length units before G92's offsets: `rs274 -g` of `G20 G90`, `G0 X1`,
    /// `G21 G92 X10` gives SET_G92_OFFSET(15.4000, ...)). Travel X -500 to 500.
    #[test]
    fn a_g92_beside_a_units_code_reads_its_words_in_the_block_s_units() {
        for family in [Family::MacroB, Family::LinuxCnc] {
            let mut config = of_family(family);
            (config.modal.inch, config.modal.metric) = (20, 21);
            let header = "G21 G90 G92 X0 Y0 Z0\nG0 X1100.\n";
            assert_eq!(at(config.clone(), header, Rule::TravelExceeded), [(3, 4)]);
            // a code that changes nothing counts the same
            let again = "G21 G90\nG21 G92 X0 Y0 Z0\nG0 X1100.\n";
            assert_eq!(at(config.clone(), again, Rule::TravelExceeded), [(4, 4)]);
            // G20 beside it under a mm start: 40 in is 1016 mm, 39 in 990.6
            let inch = "G21 G90\nG20 G92 X0 Y0\nG0 X40.\n";
            assert_eq!(at(config.clone(), inch, Rule::TravelExceeded), [(4, 4)]);
            let inside = "G21 G90\nG20 G92 X0 Y0\nG0 X39.\n";
            assert_eq!(at(config.clone(), inside, Rule::TravelExceeded), []);
            // G21 beside it under an inch start: X400. is 400 mm, not 400 in (10160 mm), so
            // X-550. spans 950, inside; X-650. spans 1050
            let mm = "G20 G90\nG21 G92 X400.\nG0 X-550.\n";
            assert_eq!(at(config.clone(), mm, Rule::TravelExceeded), []);
            let mm = "G20 G90\nG21 G92 X400.\nG0 X-650.\n";
            assert_eq!(at(config, mm, Rule::TravelExceeded), [(4, 4)]);
        }
    }

    /// Review 41, finding 2: a lathe's U and W (FANUC and Haas G code system A, Okuma: the
    /// incremental commands of X and Z, U a diameter as X is) move X and Z, so the positions
    /// they reach go to X's and Z's spans; U and W have no travel. Travel X -500 to 500, Z
    /// -300 to 100.
    #[test]
    fn a_lathe_s_u_and_w_go_to_the_spans_of_x_and_z() {
        let mut haas = fanuc_lathe();
        haas.haas = true;
        for (name, lathe) in [
            ("fanuc", fanuc_lathe()),
            ("haas", haas),
            ("okuma", super::super::testing::okuma_lathe()),
        ] {
            // X -100 to 950, Z 0 to -450: each wider than its travel
            let u = "G00 X-100. Z0\nG00 U1050.\n";
            assert_eq!(
                at(lathe.clone(), u, Rule::TravelExceeded),
                [(3, 5)],
                "{name}"
            );
            let w = "G00 X100. Z0\nG01 W-450. F0.2\n";
            assert_eq!(
                at(lathe.clone(), w, Rule::TravelExceeded),
                [(3, 5)],
                "{name}"
            );
            // said at the W where the block writes X too
            let xw = "G00 X100. Z0\nG00 X150. W-450.\n";
            assert_eq!(
                at(lathe.clone(), xw, Rule::TravelExceeded),
                [(3, 11)],
                "{name}"
            );
            // beside X and Z moves, inside: X -400 to 550, Z 50 to -250
            let inside = "G00 X-400. Z50.\nG01 U300. W-300. F0.2\nG00 X450.\nU100.\n";
            assert_eq!(
                at(lathe.clone(), inside, Rule::TravelExceeded),
                [],
                "{name}"
            );
            // and out of it: Z 50 to -360
            let out = format!("{inside}W-110.\n");
            let found = findings(lathe.clone(), &program(&out), Rule::TravelExceeded);
            let spans: Vec<_> = found.iter().map(|f| (f.line, f.column)).collect();
            assert_eq!(spans, [(6, 1)], "{name}: {found:?}");
            assert!(found[0].message.starts_with("Z spans 410"), "{name}");
            // a FANUC's or Haas's dwell's U is its time, no move
            let dwell = "G00 X100. Z0\nG04 U1500.\n";
            if name != "okuma" {
                assert_eq!(at(lathe, dwell, Rule::TravelExceeded), [], "{name}");
            }
        }
        // G code system B and C: U and W are not read as X's and Z's increments (no page at
        // hand says they are): X after one is not known, and no span is said
        for system in [GCodeSystem::B, GCodeSystem::C] {
            let mut lathe = fanuc_lathe();
            lathe.modal.g_system = system;
            let u = "G00 X-100. Z0\nG00 U1050.\n";
            assert_eq!(at(lathe, u, Rule::TravelExceeded), [], "{system:?}");
        }
    }

    /// Review 44, F7: X and U (Z and W) in one block. No page at hand says which the control
    /// takes (or whether it alarms): the axis's position is not known until an absolute one,
    /// nothing judged from it, one TG140 a file. Review 46 (lathe48, item 3): U or W from a
    /// position not known (the file's start, after `G28 U0 W0`, `X#1`) leaves it not known.
    #[test]
    fn a_lathe_s_x_and_u_in_one_block_leave_x_not_known() {
        let mut haas = fanuc_lathe();
        haas.haas = true;
        for (name, lathe) in [
            ("fanuc", fanuc_lathe()),
            ("haas", haas),
            ("okuma", super::super::testing::okuma_lathe()),
        ] {
            // X100 or 0+1050, or X1150: none judged (travel X -500 to 500)
            let xu = "G00 X0 Z0\nG00 X100. U1050.\n";
            assert_eq!(at(lathe.clone(), xu, Rule::TravelExceeded), [], "{name}");
            let notes = findings(lathe.clone(), &program(xu), Rule::NotFollowed);
            assert_eq!(notes.len(), 1, "{name}: {notes:?}");
            assert!(notes[0].message.contains("writes X and U"), "{name}");
            assert_eq!((notes[0].line, notes[0].column), (3, 1), "{name}");
            // X stays not known: a later U from it judges nothing, a later X does
            let after = format!("{xu}G00 U-200.\nG00 X-450.\n");
            assert_eq!(
                at(lathe.clone(), &after, Rule::TravelExceeded),
                [],
                "{name}"
            );
            let known = format!("{xu}G00 X450.\nG00 X-450.\nG00 U-200.\n");
            assert_eq!(
                at(lathe.clone(), &known, Rule::TravelExceeded),
                [(6, 5)],
                "{name}"
            );
            // Z and W the same (Z -300 to 100), said once a file
            let zw = "G00 X0 Z0\nG00 Z50. W-400.\nG00 X10. U20.\n";
            assert_eq!(at(lathe.clone(), zw, Rule::TravelExceeded), [], "{name}");
            let notes = findings(lathe.clone(), &program(zw), Rule::NotFollowed);
            assert_eq!(notes.len(), 1, "{name}: {notes:?}");
            // nor a macro call's arguments (FANUC, Haas: G65 P9732 W1. Z1.)
            if name != "okuma" {
                let g65 = "G00 X0 Z0\nG65 P9732 W1. Z1.\n";
                let notes = findings(lathe.clone(), &program(g65), Rule::NotFollowed);
                assert!(
                    notes.iter().all(|f| !f.message.contains("writes X and U")),
                    "{name}: {notes:?}"
                );
            }
            // X and W (two axes) are no such block
            let xw = "G00 X0 Z0\nG00 X100. W-50.\n";
            assert_eq!(findings(lathe.clone(), &program(xw), Rule::NotFollowed), []);
            // U from a position not known: the file's start, a parameter (a U that fits
            // the travel: one wider than it is out of travel from anywhere, issue 32)
            for start in ["", "G00 X0 Z0\nG00 X#1\n"] {
                let u = format!("{start}G00 U950.\nG00 X-100.\n");
                assert_eq!(
                    at(lathe.clone(), &u, Rule::TravelExceeded),
                    [],
                    "{name}: {start}"
                );
            }
        }
        // after G28 U0 W0 (X and Z to the reference point) X and Z are not known (FANUC and
        // Haas: Okuma's G28 is no reference return)
        let g28 = "G00 X0 Z0\nG28 U0 W0\nG00 U600.\nG00 X-450.\n";
        assert_eq!(at(fanuc_lathe(), g28, Rule::TravelExceeded), []);
        // where X was known, the same U is judged
        let known = "G00 X0 Z0\nG00 U600.\nG00 X-450.\n";
        assert_eq!(at(fanuc_lathe(), known, Rule::TravelExceeded), [(4, 5)]);
    }

    /// Review 48, F12: a lathe's U (W) whose value is not known (`U#1`) leaves X (Z) not
    /// known, as a mill's `G91 X#1` does: X kept its old position, and a later absolute X
    /// made a span from a place the tool never was (u1.nc: TG601 "X spans 600"). A plain U
    /// after a known X is judged as before, and an increment run from the lost position
    /// wider than the whole travel is still out of travel (issue 32).
    #[test]
    fn a_lathe_s_u_whose_value_is_not_known_leaves_x_not_known() {
        let mut haas = fanuc_lathe();
        haas.haas = true;
        for (name, lathe) in [
            ("fanuc", fanuc_lathe()),
            ("haas", haas),
            ("okuma", super::super::testing::okuma_lathe()),
        ] {
            // travel X -500 to 500: X was at 0+#1+600, not 600
            let u = "G00 X0 Z0\nG00 U#1\nG00 U600.\nG00 X-450.\n";
            assert_eq!(at(lathe.clone(), u, Rule::TravelExceeded), [], "{name}");
            // the same U beside an X: X not known either
            let xu = "G00 X0 Z0\nG00 X100. U#1\nG00 U600.\nG00 X-450.\n";
            assert_eq!(at(lathe.clone(), xu, Rule::TravelExceeded), [], "{name}");
            // a plain U after a known X: judged (X spans 600 to -450)
            let plain = "G00 X0 Z0\nG00 U0\nG00 U600.\nG00 X-450.\n";
            assert_eq!(
                at(lathe.clone(), plain, Rule::TravelExceeded),
                [(5, 5)],
                "{name}"
            );
            // Z and W the same (Z -300 to 100)
            let w = "G00 X0 Z0\nG00 W#1\nG00 W-300.\nG00 Z150.\n";
            assert_eq!(at(lathe.clone(), w, Rule::TravelExceeded), [], "{name}");
            let plain = "G00 X0 Z0\nG00 W0\nG00 W-300.\nG00 Z150.\n";
            assert_eq!(
                at(lathe.clone(), plain, Rule::TravelExceeded),
                [(5, 5)],
                "{name}"
            );
            // a run of U wider than X's whole travel after it: out of travel wherever it
            // starts; one that fits says nothing
            let run = "G00 X0 Z0\nG00 U#1\nG00 U600.\nG01 U500. F0.2\n";
            assert_eq!(
                at(lathe.clone(), run, Rule::TravelExceeded),
                [(5, 5)],
                "{name}"
            );
            let found = findings(lathe.clone(), &program(run), Rule::TravelExceeded);
            assert!(
                found[0].message.starts_with(
                    "X moves over 1100 mm in 2 increments in a row (the last U500.) with its \
                     start not known"
                ),
                "{name}: {}",
                found[0].message
            );
            let fits = "G00 X0 Z0\nG00 U#1\nG00 U600.\nG01 U-500. F0.2\n";
            assert_eq!(at(lathe.clone(), fits, Rule::TravelExceeded), [], "{name}");
        }
    }

    /// Issue 32 (lathe48's lost TG601): an axis whose position is not known, moved by
    /// increments of known lengths, is out of travel wherever it started where the extent of
    /// their running sum (0 included) is wider than its whole travel; never where it fits.
    #[test]
    fn increments_wider_than_the_travel_from_a_start_not_known() {
        // the lathe: X -500 to 500, 1000 wide; after G28 U0 W0 X is not known
        let lathe = "G00 X0 Z0\nG28 U0 W0\nG00 U1020.\n";
        assert_eq!(at(fanuc_lathe(), lathe, Rule::TravelExceeded), [(4, 5)]);
        let found = findings(fanuc_lathe(), &program(lathe), Rule::TravelExceeded);
        assert!(
            found[0].message.starts_with(
                "X moves 1020 (U1020.) with its start not known: more than its whole travel \
                 of 1000 (-500 to 500), out of travel wherever it starts"
            ),
            "{}",
            found[0].message
        );
        // one that fits says nothing, nor does W within Z's 400
        let fits = "G00 X0 Z0\nG28 U0 W0\nG00 U990. W-390.\n";
        assert_eq!(at(fanuc_lathe(), fits, Rule::TravelExceeded), []);
        // two increments in a row: 600 and 500 reach over 1100; 600 and -500 span 600
        let two = "G00 X0 Z0\nG28 U0 W0\nG00 U600.\nG01 U500. F0.2\n";
        assert_eq!(at(fanuc_lathe(), two, Rule::TravelExceeded), [(5, 5)]);
        let back = "G00 X0 Z0\nG28 U0 W0\nG00 U600.\nG01 U-500. F0.2\nU-400.\n";
        assert_eq!(at(fanuc_lathe(), back, Rule::TravelExceeded), []);
        // started again where the axis is lost anew (a second G28): 600 + 600 is no run
        let again = "G00 X0 Z0\nG28 U0 W0\nG00 U600.\nG28 U0\nG00 U600.\n";
        assert_eq!(at(fanuc_lathe(), again, Rule::TravelExceeded), []);
        // the mill under G91 from a position not known (X#1), a run said once
        let mill = "G90 G00 X#1 Y0\nG91 X700.\nY10.\nX400.\nX100.\n";
        assert_eq!(at(iso_mill(), mill, Rule::TravelExceeded), [(5, 1)]);
        let found = findings(iso_mill(), &program(mill), Rule::TravelExceeded);
        assert!(
            found[0].message.starts_with(
                "X moves over 1100 mm in 2 increments in a row (the last X400.) with its start \
                 not known"
            ),
            "{}",
            found[0].message
        );
        // an absolute position makes it known again: the increments after it are spans
        let known = "G90 G00 X#1 Y0\nG91 X700.\nG90 X0\nG91 X400.\n";
        assert_eq!(at(iso_mill(), known, Rule::TravelExceeded), []);
        // G91 G28 Z0 (Z to the reference point) then Z-450. on Z's 400: out of travel
        let home = "G91 G28 Z0\nG00 Z-450.\n";
        assert_eq!(at(iso_mill(), home, Rule::TravelExceeded), [(3, 5)]);
        // inch and metric: 41 in is 1041.4 mm on a metric mill (X 1000 mm), 39 in is 990.6 mm
        for (inc, found) in [("X41.", vec![(5, 1)]), ("X39.", vec![])] {
            let body = format!("G20\nG90 G00 X#1\nG91 {inc}\n");
            let body = body.replace("G91 X", "G91\nX");
            let mut metric = inch_mill();
            metric.facts.limit_units = Units::Metric;
            metric.facts.travel = vec![(
                b'X',
                Dec::parse("-500").unwrap(),
                Dec::parse("500").unwrap(),
            )];
            assert_eq!(at(metric, &body, Rule::TravelExceeded), found, "{inc}");
        }
        // the inch mill (X -30 to 30 in) reads a G21 program's 1600 mm as 63 in
        let metric = "G21\nG90 G00 X#1\nG91 X1600.\n";
        assert_eq!(at(inch_mill(), metric, Rule::TravelExceeded), [(4, 5)]);
        let metric = "G21\nG90 G00 X#1\nG91 X1500.\n";
        assert_eq!(at(inch_mill(), metric, Rule::TravelExceeded), []);
        // a canned cycle's words, a frame's increments: no run
        let cycle = "G90 G00 X#1 Y0 Z50.\nG91 G81 X700. R-5. Z-10. F100.\nX700.\nG80\n";
        assert_eq!(at(iso_mill(), cycle, Rule::TravelExceeded), []);
    }

    /// Review 46, F3: G53 under G91 (in force or in its block). No page at hand says what a
    /// FANUC, Haas or SINUMERIK does (a 9/Series ignores the block, a Mitsubishi M700V moves
    /// by the increment): not compared with the travel, one TG140 a file; under G90 judged.
    #[test]
    fn a_g53_under_g91_is_not_judged() {
        for g91 in [
            "G91\nG53 G0 X-800.\n",
            "G91 G53 G0 X-800.\n",
            "G53 G91 X-800.\n",
        ] {
            assert_eq!(at(iso_mill(), g91, Rule::TravelExceeded), [], "{g91}");
            let notes = findings(iso_mill(), &program(g91), Rule::NotFollowed);
            let g53: Vec<_> = notes
                .iter()
                .filter(|f| f.message.starts_with("G53 under G91"))
                .collect();
            assert_eq!(g53.len(), 1, "{g91}: {notes:?}");
        }
        // G90 in the block, or in force: judged
        for (g90, said) in [
            ("G91\nG90 G53 G0 X-800.\n", (3, 12)),
            ("G53 G0 X-800.\n", (2, 8)),
        ] {
            assert_eq!(at(iso_mill(), g90, Rule::TravelExceeded), [said], "{g90}");
        }
        // said once: a later one under G90 is still judged
        let later = "G91\nG53 G0 X-800.\nG53 G0 X-900.\nG90\nG53 G0 X-800.\n";
        assert_eq!(at(iso_mill(), later, Rule::TravelExceeded), [(6, 8)]);
        let notes = findings(iso_mill(), &program(later), Rule::NotFollowed);
        assert_eq!(
            notes
                .iter()
                .filter(|f| f.message.starts_with("G53 under G91"))
                .count(),
            1
        );
    }

    /// Issue 32 (thr42): a FANUC or Haas lathe's threading G32/G34 moves X and Z by U and W
    /// as G01 does, and the end point X(U) Z(W) of a single cycle G90, G92, G94 goes to the
    /// spans, the tool back at the start point after it (FANUC 0i-TF operator's manual,
    /// "Thread cutting G32", "Outer diameter/internal diameter cutting cycle G90", "Thread
    /// cutting cycle G92", "End face turning cycle G94"). Travel X -500 to 500, Z -300 to 100.
    #[test]
    fn a_lathe_s_thread_and_single_cycles_reach_the_spans() {
        let mut haas = fanuc_lathe();
        haas.haas = true;
        for (name, lathe) in [("fanuc", fanuc_lathe()), ("haas", haas)] {
            let at = |body: &str| at(lathe.clone(), body, Rule::TravelExceeded);
            for thread in ["G32", "G34"] {
                // Z 0 to -450 by W and by Z (out), Z 50 to -250 (in)
                assert_eq!(
                    at(&format!("G00 X40. Z0\n{thread} W-450. F1.5\n")),
                    [(3, 5)]
                );
                assert_eq!(
                    at(&format!("G00 X40. Z0\n{thread} Z-450. F1.5\n")),
                    [(3, 5)]
                );
                assert_eq!(at(&format!("G00 X40. Z50.\n{thread} W-300. F1.5\n")), []);
                // the thread's position followed: its modal repeat from there
                let repeat = format!("G00 X40. Z0\n{thread} W-250. F1.5\nW-250.\n");
                assert_eq!(at(&repeat), [(4, 1)], "{name} {thread}");
            }
            for cycle in ["G90", "G92", "G94"] {
                // the end point out of Z's travel: by W, by Z, and by X of a modal repeat
                let w = format!("G00 X60. Z50.\n{cycle} U-10. W-500. F0.2\n");
                assert_eq!(at(&w), [(3, 11)], "{name} {cycle}");
                let z = format!("G00 X60. Z50.\n{cycle} X50. Z-400. F0.2\n");
                assert_eq!(at(&z), [(3, 10)], "{name} {cycle}");
                let x = format!("G00 X60. Z0\n{cycle} X50. Z-10. F0.2\nX-950.\n");
                assert_eq!(at(&x), [(4, 1)], "{name} {cycle}");
                let u = format!("G00 X60. Z0\n{cycle} U-10. W-10. F0.2\nU-1020.\n");
                assert_eq!(at(&u), [(4, 1)], "{name} {cycle}");
                // inside: Z 50 to -250, the tool back at X60. Z50. after each cycle (had it
                // stayed at Z-250., the W-300. after them would reach Z-550.)
                let inside =
                    format!("G00 X60. Z50.\n{cycle} U-10. W-300. F0.2\nU-20.\nG00 W-300.\n");
                assert_eq!(at(&inside), [], "{name} {cycle}");
            }
        }
    }

    /// Review 44, finding F5: the block of a FANUC's or Haas's multiple repetitive cycle
    /// G74, G75, G76 that writes X(U) Z(W) gives its end point (G76: the final thread's root
    /// diameter and end, its taper R -- Haas I -- the corner at the start point's Z), the
    /// tool back at the start point after it (FANUC 0i-TF operator's manual, "Multiple
    /// repetitive cycle (G70-G76)"; Haas lathe operator's manual, G74, G75, G76); the first
    /// block (P Q R alone) moves nothing. Travel X -500 to 500, Z -300 to 100.
    #[test]
    fn a_lathe_s_repetitive_cycles_reach_the_spans_with_their_end_point() {
        let mut haas = fanuc_lathe();
        (haas.haas, haas.modal.haas) = (true, true);
        for (name, lathe) in [("fanuc", fanuc_lathe()), ("haas", haas)] {
            let at = |body: &str| at(lathe.clone(), body, Rule::TravelExceeded);
            let taper = if name == "haas" { 'I' } else { 'R' };
            // the review's programs, to the travel here: G76's Z, G75's X, G74's Z
            let g76 = "G00 X60. Z50.\nG76 P010060 Q100 R0.05\nG76 X50. Z-400. P1000 Q300 F1.5\n";
            assert_eq!(at(g76), [(4, 10)], "{name}");
            let w = "G00 X60. Z50.\nG76 P010060 Q100 R0.05\nG76 U-10. W-460. P1000 Q300 F1.5\n";
            assert_eq!(at(w), [(4, 11)], "{name}");
            let g75 = "G00 X60. Z5.\nG75 R0.5\nG75 X-1000. Z-30. P1000 Q2000 F0.1\n";
            assert_eq!(at(g75), [(4, 5)], "{name}");
            let g74 = "G00 X0 Z50.\nG74 R0.5\nG74 Z-400. Q5000 F0.1\n";
            assert_eq!(at(g74), [(4, 5)], "{name}");
            // the first block alone moves nothing; after the cycle the tool is back at its
            // start point Z50. (had it stayed at Z-250., the W-320. would reach Z-570.)
            let back = "G00 X60. Z50.\nG76 P010060 Q100 R0.05\nG76 X50. Z-250. P1000 Q300 F1.5\n\
                        G00 W-320.\n";
            assert_eq!(at(back), [], "{name}");
            // G76's taper: the final pass starts at X 50 - 2 x 600 = -1150
            let tapered = format!(
                "G00 X60. Z50.\nG76 P010060 Q100 R0.05\nG76 X50. Z-30. {taper}-600. P1000 Q300 F1.5\n"
            );
            assert_eq!(at(&tapered), [(4, 5)], "{name}");
            let inside = format!(
                "G00 X60. Z50.\nG76 P010060 Q100 R0.05\nG76 X50. Z-30. {taper}-200. P1000 Q300 F1.5\n"
            );
            assert_eq!(at(&inside), [], "{name}");
        }
        // Haas's one block (X Z K D F)
        let mut haas = fanuc_lathe();
        (haas.haas, haas.modal.haas) = (true, true);
        let one = "G00 X60. Z50.\nG76 X50. Z-400. K1. D0.3 F1.5\n";
        assert_eq!(at(haas.clone(), one, Rule::TravelExceeded), [(3, 10)]);
        let one = "G00 X60. Z50.\nG76 X50. Z-200. K1. D0.3 F1.5\nG00 W-320.\n";
        assert_eq!(at(haas, one, Rule::TravelExceeded), []);
    }

    /// Review 44, finding F1: a single cycle's taper -- FANUC R, Haas I (G90, G92) and K
    /// (G94) -- takes the tool to a corner first: G90/G92 the end point's X plus twice the
    /// radius difference, at the start point's Z; G94 the end point's Z plus R, at the start
    /// point's X (FANUC 0i-TF operator's manual, "Outer diameter/internal diameter cutting
    /// cycle G90", "Thread cutting cycle G92", "End face turning cycle G94"; the taper is
    /// modal with X(U) and Z(W), "Canned cycle"). A taper not known here is said (TG140).
    #[test]
    fn a_single_cycle_s_taper_corner_reaches_the_spans() {
        let mut haas = fanuc_lathe();
        (haas.haas, haas.modal.haas) = (true, true);
        for (name, lathe) in [("fanuc", fanuc_lathe()), ("haas", haas)] {
            let at = |body: &str| at(lathe.clone(), body, Rule::TravelExceeded);
            let haas = name == "haas";
            for cycle in ["G90", "G92"] {
                let r = if haas { 'I' } else { 'R' };
                // the review's program: the tool rapids to X 50 - 1200 = -1150
                let out = format!("G00 X60. Z50.\n{cycle} X50. Z-30. {r}-600. F0.2\n");
                assert_eq!(at(&out), [(3, 5)], "{name} {cycle}");
                let inside = format!("G00 X60. Z50.\n{cycle} X50. Z-30. {r}-200. F0.2\n");
                assert_eq!(at(&inside), [], "{name} {cycle}");
                // the taper is modal: X-600.'s corner is -1000
                let repeat = format!("G00 X60. Z50.\n{cycle} X50. Z-30. {r}-200. F0.2\nX-600.\n");
                assert_eq!(at(&repeat), [(4, 1)], "{name} {cycle}");
                // ... until G00 ends the cycle's data
                let ended =
                    format!("G00 X60. Z50.\n{cycle} X50. Z-30. {r}-200. F0.2\nG00 X60.\n{cycle} X-600. Z-30.\n");
                assert_eq!(at(&ended), [], "{name} {cycle}");
            }
            let k = if haas { 'K' } else { 'R' };
            let face = format!("G00 X60. Z50.\nG94 X20. Z0 {k}-400. F0.2\n");
            assert_eq!(at(&face), [(3, 10)], "{name}");
            let face = format!("G00 X60. Z50.\nG94 X20. Z0 {k}-300. F0.2\n");
            assert_eq!(at(&face), [], "{name}");
        }
        // a Haas's taper letter is I: its R is no taper here (the manual's G90 has none)
        let mut haas = fanuc_lathe();
        (haas.haas, haas.modal.haas) = (true, true);
        let r = "G00 X60. Z50.\nG90 X50. Z-30. R-600. F0.2\n";
        assert_eq!(at(haas, r, Rule::TravelExceeded), []);
        // a taper by a parameter not known here: TG140 once, no TG601
        let unknown = "G00 X60. Z50.\nG90 X50. Z-30. R#5 F0.2\nX40.\n";
        assert_eq!(at(fanuc_lathe(), unknown, Rule::TravelExceeded), []);
        let notes = findings(fanuc_lathe(), &program(unknown), Rule::NotFollowed);
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(notes[0].message.contains("taper"), "{}", notes[0].message);
        assert_eq!(notes[0].line, 3);
    }

    /// Review 44, finding F2: an Okuma lathe's fixed thread cutting cycle G33 (OSP-P200L
    /// 5238-E, section 7, 2-1: X the thread diameter of the pass, Z the thread's end, I the
    /// radius difference of a taper) returns to its starting point at rapid traverse (CIMCO
    /// Edit's OSP threading exercise), and its X repeats it at a new diameter; its compound
    /// thread cutting cycles G71/G72 are said not to be worked out (TG140).
    #[test]
    fn an_okuma_thread_cycle_returns_to_its_start_point() {
        let at = |body: &str| at(okuma_lathe(), body, Rule::TravelExceeded);
        // (1) the tool back at Z50.: W430. reaches Z480. (span -30 to 480, out of 400)
        assert_eq!(
            at("G00 X60. Z50.\nG33 X50. Z-30. F1.5\nG00 W430.\n"),
            [(4, 5)]
        );
        // (2) no false error: from Z50., W-300. reaches Z-250. (span 300); had the tool stayed
        // at Z-30., it would reach Z-330.
        assert_eq!(
            at("G00 X60. Z50.\nG33 X50. Z-30. F1.5\nG00 W-300.\nG00 X100. Z100.\n"),
            []
        );
        // (3) the taper I: the tool goes to X 50 - 1200 = -1150
        assert_eq!(at("G00 X60. Z50.\nG33 X50. Z-30. I-600. F1.5\n"), [(3, 5)]);
        // the cycle's end point out of the travel, and its modal repeat
        assert_eq!(at("G00 X60. Z50.\nG33 X50. Z-400. F1.5\n"), [(3, 10)]);
        assert_eq!(
            at("G00 X60. Z50.\nG33 X50. Z-30. F1.5\nX-1000.\n"),
            [(4, 1)]
        );
        // review 46, F2: G33's K is no taper word (5238-E P-97: I or A): no note of a taper
        let k = "G00 X60. Z50.\nG33 X50. Z-30. F1.5 K0.5\n";
        assert!(findings(okuma_lathe(), &program(k), Rule::NotFollowed)
            .iter()
            .all(|f| !f.message.contains("taper")));
        // (4) G71: said, not silent
        let g71 = "G00 X60. Z50.\nG71 X50. Z-1200. K2. D0.5 F1.5\n";
        assert_eq!(at(g71), []);
        let notes = findings(okuma_lathe(), &program(g71), Rule::NotFollowed);
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(notes[0].message.contains("G71/G72"), "{}", notes[0].message);
    }

    /// Review 41, finding 6: a G92 the Okuma lathe's list lacks (its coordinate setting is
    /// G50) is a code the profile does not know: the block's axes are not known after it, as
    /// any lacked code's, not a setting where the tool stands. The Okuma mill's G92 (4203-E,
    /// List of G Codes), and a lathe profile that lists it, keep it. Travel X -500 to 500.
    #[test]
    fn a_g92_the_okuma_lathe_lacks_sets_no_position() {
        let mut lacked = super::super::testing::okuma_lathe();
        lacked.modal.lacks_g = vec![false; 200];
        lacked.modal.lacks_g[92] = true;
        let body = "G92 X0 Z0\nG00 X1100. Z0\n";
        assert_eq!(at(lacked, body, Rule::TravelExceeded), []);
        let listed = super::super::testing::okuma_lathe();
        assert_eq!(at(listed, body, Rule::TravelExceeded), [(3, 5)]);
        let mill = of_family(Family::Okuma);
        assert_eq!(
            at(mill, "G92 X0 Y0 Z0\nG00 X1100.", Rule::TravelExceeded),
            [(3, 5)]
        );
    }

    /// Review 39, finding 2 (the conservative half): a subprogram after the end (a Haas's M97
    /// sequence, an O number an M98 names) runs under the shift at its call, not the one at
    /// the end: where a call was made under a shift, the shifted axes' spans start again at
    /// the end, with the note naming the call. Travel X -500 to 500.
    /// Review 39, finding 2: a subprogram after the end (a Haas's M97 sequence, an O number
    /// an M98 names) runs under the shift at its call, not the one at the end: where every
    /// call of the program was made under one known shift, the text after the end is read
    /// under it; where they differ, the shifted axes' spans start again at the end, with the
    /// note naming the call. Travel X -500 to 500.
    #[test]
    fn a_subprogram_after_the_end_is_read_under_its_calls_shift() {
        let fanuc = of_family(Family::MacroB);
        let mut haas = of_family(Family::MacroB);
        haas.haas = true;
        let m97 = "G90 G00 X-400. Y0\nG52 X300.\nX0 Y0\nM97 P100\nM30\nN100 X450.\nM99\n";
        // the sub runs at X750.: 1150 from X-400. (the Haas took its G52 as removed at M30
        // and read X450. in the work system, silently; lim40 started the span again)
        for config in [fanuc.clone(), haas.clone()] {
            assert_eq!(at(config.clone(), m97, Rule::TravelExceeded), [(7, 6)]);
            let said = findings(config, &program(m97), Rule::TravelExceeded);
            assert!(
                said[0].message.contains("X spans 1150 (from -400 to 750)"),
                "{}",
                said[0].message
            );
        }
        // the G52 cancelled before M30: the sub still runs under it
        let m98 = "G90 G00 X-400. Y0\nG52 X300.\nX0 Y0\nM98 P2000\nG52 X0\nM30\n\
                   O2000\nX450.\nM99\n";
        for config in [fanuc.clone(), haas.clone()] {
            assert_eq!(at(config, m98, Rule::TravelExceeded), [(9, 1)]);
        }
        // calls under two shifts: the span starts again at the end, the note names the first
        let two = "G90 G00 X-400. Y0\nG52 X300.\nX0 Y0\nM97 P100\nG52 X0\nM97 P100\nM30\n\
                   N100 X450.\nM99\n";
        for config in [fanuc.clone(), haas.clone()] {
            assert_eq!(at(config.clone(), two, Rule::TravelExceeded), []);
            let noted = findings(config, &program(two), Rule::NotFollowed);
            let end: Vec<_> = noted
                .iter()
                .filter(|f| f.message.starts_with("M30"))
                .collect();
            assert_eq!(end.len(), 1, "{noted:?}");
            assert_eq!((end[0].line, end[0].column), (8, 1));
            assert!(
                end[0].message.contains("(M97 P100 of line 5)"),
                "{}",
                end[0].message
            );
        }
        // a call under a shift not known (G52 under G91 over a local shift): the same
        let unknown = "G90 G00 X-400. Y0\nG52 X300.\nG91 G52 X10.\nG90 X0 Y0\nM97 P100\n\
                       M30\nN100 X450.\nM99\n";
        assert_eq!(at(haas.clone(), unknown, Rule::TravelExceeded), []);
        // no shift at the call: the Haas's end removes the G52 as before (X-550. is 1050
        // from X500.)
        let before = "G90 G00 X-400.\nM98 P2000\nG52 X100.\nX400.\nM30\nX-550.\n";
        assert_eq!(at(haas, before, Rule::TravelExceeded), [(7, 1)]);
    }

    /// Review 38, finding 11: a G53 position written in the other unit system is said in
    /// both units, with the profile's named, as the span's and the feed's messages do.
    #[test]
    fn a_machine_position_in_the_other_units_is_said_in_both() {
        let dec = |text: &str| Dec::parse(text).unwrap();
        let inch = Config {
            facts: ProfileFacts {
                travel: vec![(b'X', dec("-30"), dec("30"))],
                limit_units: crate::modal::Units::Inch,
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let found = findings(
            inch.clone(),
            &program("G71 G00 X0\nG53 X800."),
            Rule::TravelExceeded,
        );
        assert_eq!(found.len(), 1);
        assert!(
            found[0].message.starts_with(
                "X goes to 800 mm (31.496063 in) in machine coordinates (G53), outside the \
                 travel -30 to 30 in"
            ),
            "{}",
            found[0].message
        );
        // in the profile's units: as before, the number as written
        let found = findings(inch, &program("G70 G00 X0\nG53 X31."), Rule::TravelExceeded);
        assert!(
            found[0].message.starts_with(
                "X goes to 31 in machine coordinates (G53), outside the travel -30 to 30"
            ),
            "{}",
            found[0].message
        );
    }

    #[test]
    fn a_decimal_mirror_restarts_the_spans_and_a_decimal_code_that_is_none_does_not() {
        // G51.1 and G50.1 are read in tenths (the whole codes are not): the mirror on, then
        // off, each starts the span again; G50.1 with no mirror on, and G43.1, change nothing
        let fanuc = of_family(Family::MacroB);
        let mirrored = "G00 X-400.\nG51.1 X0\nX700.\nG50.1 X0\nX-400.\n";
        assert_eq!(at(fanuc.clone(), mirrored, Rule::TravelExceeded), []);
        for code in ["G50.1 X0", "G43.1 Z0", "G51.10 X0"] {
            let body = format!("G00 X-400.\n{code}\nX700.\n");
            let found = at(fanuc.clone(), &body, Rule::TravelExceeded);
            if code == "G51.10 X0" {
                assert_eq!(found, [], "{code}: 51.10 is G51.1");
            } else {
                assert_eq!(found, [(4, 1)], "{code}");
            }
        }
    }

    #[test]
    fn a_frame_s_cancel_beside_a_dwell_takes_effect_in_its_block() {
        // G04 P1. G69: the rotation ends in the dwell's block as in a block of its own (review
        // 15, finding 1): Y-450. to Y450. spans 900, more than Y's 800; X450. after the
        // cancel is no Y position
        let fanuc = fanuc_centres();
        let missed = "G00 X0 Y-450.\nG68 X0 Y0 R90.\nG00 X0 Y0\nG04 P1. G69\nG00 X0 Y450.";
        assert_eq!(at(fanuc.clone(), missed, Rule::TravelExceeded), [(6, 8)]);
        let fits = "G00 X0 Y-300.\nG68 X0 Y0 R90.\nG00 X0 Y0\nG04 P1. G69\nG00 X450. Y0";
        assert_eq!(at(fanuc, fits, Rule::TravelExceeded), []);
    }

    #[test]
    fn the_spans_run_on_across_a_frame_s_cancel() {
        let fanuc = fanuc_centres();
        // under a mirror image the positions stand apart; at its cancel the span from before
        // it runs on: Y-450. and Y450. span 900, more than the 800 of Y's travel
        let mirror = "G00 Y-450.\nG51.1 Y0\nY400.\nG50.1 Y0\nY450.";
        assert_eq!(at(fanuc.clone(), mirror, Rule::TravelExceeded), [(6, 1)]);
        // a G50 (scaling off) under a rotation ends no frame
        let other = "G00 Y-450.\nG68 X0 Y0 R90.\nG50\nG00 X0 Y0\nG69\nY450.";
        assert_eq!(at(fanuc.clone(), other, Rule::TravelExceeded), [(7, 1)]);
        // a FANUC's scaling: its factor's unit and axes are parameters, said once
        let scaled = "G00 Y-300.\nG51 X0 Y0 Z0 P2000\nY400.\nG50\nY300.";
        assert_eq!(at(fanuc.clone(), scaled, Rule::TravelExceeded), []);
        let found = findings(fanuc, &program(scaled), Rule::NotFollowed);
        assert_eq!(found.len(), 1);
        assert!(
            found[0].message.contains("X Y Z under it are not compared"),
            "{}",
            found[0].message
        );
    }

    #[test]
    fn at_a_rotation_s_cancel_the_tool_stands_where_the_frame_put_it() {
        let fanuc = fanuc_centres();
        // X450. under R90 about X0 Y0 is Y450. before it; after G69 an increment of Y100.
        // goes to Y550., 850 from Y-300., more than the 800 of Y's travel (not Y100.)
        let rotated = |step: &str| {
            format!("G00 Y-300.\nG68 X0 Y0 R90.\nG00 X0 Y0\nX450.\nG69\nG91 Y{step}\nG90")
        };
        assert_eq!(
            at(fanuc.clone(), &rotated("100."), Rule::TravelExceeded),
            [(7, 5)]
        );
        assert_eq!(at(fanuc.clone(), &rotated("40."), Rule::TravelExceeded), []);
        // a correct arc after the cancel: it starts at X0 Y45., radius 45 at both ends
        let arc = "G00 X0 Y0 F100.\nG68 X0 Y0 R90.\nG00 X45. Y0\nG69\nG03 X-45. Y0 I0 J-45.";
        assert_eq!(at(fanuc.clone(), arc, Rule::ArcRadiusMismatch), []);
        // the cancel block's own absolute word stands as written, its other axis taken back
        let same = "G00 Y-300.\nG68 X0 Y0 R90.\nG00 X0 Y0\nX450.\nG69 X10.\nG91 Y100.\nG90";
        assert_eq!(at(fanuc.clone(), same, Rule::TravelExceeded), [(7, 5)]);
        // a rotation whose angle is a parameter's: the plane's axes unknown after the
        // cancel until an absolute position: no span, no arc compared from a wrong start
        let unknown = "G00 X0 Y0 F100.\nG68 X0 Y0\nG00 X45. Y0\nG69\nG03 X-45. Y0 I0 J-45.";
        assert_eq!(at(fanuc.clone(), unknown, Rule::ArcRadiusMismatch), []);
        let unknown = "G00 Y-300.\nG68 X0 Y0\nX450.\nG69\nG91 Y600.\nG90\nY400.";
        assert_eq!(at(fanuc.clone(), unknown, Rule::TravelExceeded), []);
        let unknown = "G00 Y-300.\nG68 X0 Y0\nX450.\nG69\nG90 Y600.";
        assert_eq!(at(fanuc.clone(), unknown, Rule::TravelExceeded), [(6, 5)]);
        // an exact rotation whose Y was never given under it: Y unknown after the cancel,
        // said once
        let unfresh = "G00 Y-300.\nG68 X0 Y0 R90.\nX450.\nG69\nG91 Y600.\nG90";
        assert_eq!(at(fanuc.clone(), unfresh, Rule::TravelExceeded), []);
        let notes = findings(fanuc, &program(unfresh), Rule::NotFollowed);
        assert_eq!(notes.len(), 1, "{notes:?}");
    }

    #[test]
    fn a_mirror_about_a_written_point_is_taken_back_exactly() {
        let fanuc = fanuc_centres();
        // X-500. about X10. is X520.: 1020 from X-500., more than the 1000 of X's travel
        let mirror = |x: &str| format!("G00 X-500. Y0\nG51.1 X10.\nG00 X{x}\nG50.1 X0\nX0");
        assert_eq!(
            at(fanuc.clone(), &mirror("-500."), Rule::TravelExceeded),
            [(4, 5)]
        );
        let found = findings(
            fanuc.clone(),
            &program(&mirror("-500.")),
            Rule::TravelExceeded,
        );
        assert!(
            found[0].message.contains("G51.1 of line 3 taken back"),
            "{}",
            found[0].message
        );
        assert_eq!(
            at(fanuc.clone(), &mirror("-400."), Rule::TravelExceeded),
            []
        );
        // at the cancel the tool stands at X410.: an increment of X-30. after it is X380.
        // (880 from X-500.), of X100. is X510. (1010); (the cancel's X0 names the axis whose
        // mirror ends, no move)
        let after = |x: &str| {
            format!("G00 X-500. Y0\nG51.1 X10. Y0\nG00 X-400.\nX-390.\nG50.1 X0 Y0\nG91 X{x}\nG90")
        };
        assert_eq!(at(fanuc.clone(), &after("-30."), Rule::TravelExceeded), []);
        assert_eq!(
            at(fanuc.clone(), &after("100."), Rule::TravelExceeded),
            [(7, 5)]
        );
        // a mirror whose point is not exact here (an A axis) keeps its positions apart
        let apart = "G00 X-500. Y0\nG51.1 X10. A0\nG00 X-500.\nG50.1 X0\nX0";
        assert_eq!(at(fanuc, apart, Rule::TravelExceeded), []);
    }

    #[test]
    fn a_mirror_is_set_and_ended_axis_by_axis() {
        // review 15, finding 2: G50.1 X0 ends X's mirror alone, a second G51.1 adds its axis
        let fanuc = fanuc_centres();
        // Y450. mirrored about Y0 (G50.1 X0 leaves it) is Y-450.: 800.5 from Y350.5, more
        // than Y's 800; with both ended Y450. is 99.5 from it
        let one = |cancel: &str| {
            format!("G00 X0 Y350.5\nG51.1 X0 Y0\nG00 X10. Y10.\n{cancel}\nG00 Y450.\nG50.1 Y0")
        };
        assert_eq!(
            at(fanuc.clone(), &one("G50.1 X0"), Rule::TravelExceeded),
            [(6, 5)]
        );
        assert_eq!(
            at(fanuc.clone(), &one("G50.1 X0 Y0"), Rule::TravelExceeded),
            []
        );
        // G51.1 X0 then G51.1 Y-50.: Y360. is Y-460., 820 from Y360.; G51.1 Y-50. alone the same
        let two = |first: &str| format!("G00 X0 Y360.\n{first}G51.1 Y-50.\nG00 Y360.\nG50.1 X0 Y0");
        assert_eq!(
            at(fanuc.clone(), &two("G51.1 X0\n"), Rule::TravelExceeded),
            [(5, 5)]
        );
        assert_eq!(at(fanuc.clone(), &two(""), Rule::TravelExceeded), [(4, 5)]);
        // the mirror's words are its axes and point, no move (they were read as one: review
        // 15): G51.1 X650. leaves the tool at X-400. (no span of 1050), and X1000. under it
        // is X300.; G50.1 X0 leaves the tool at X-100. (X100. about X0), and X-550. from
        // there is X-650., 1050 from X400.
        let about = "G00 X-400. Y0\nG51.1 X650.\nG00 X1000.\nG50.1 X0";
        assert_eq!(at(fanuc.clone(), about, Rule::TravelExceeded), []);
        let ended = "G00 X400. Y0\nG51.1 X0\nG00 X100.\nG50.1 X0\nG91 X-550.\nG90";
        assert_eq!(at(fanuc.clone(), ended, Rule::TravelExceeded), [(6, 5)]);
        let state = run(
            fanuc.clone(),
            &dialect(Family::MacroB),
            "%\nG00 X-300.\nG51.1 X450.\n",
        );
        assert_eq!(state.0.machine.state.axis(b'X'), Dec::parse("-300."));
        // an axis mirrored again: no page says what that does (review 16b, finding 5), so
        // the positions stand apart, with a note
        let again = "G00 X0 Y0\nG51.1 X0\nG00 X100.\nG51.1 X50.\nG50.1 X0\nG91 X10.\nG90";
        assert_eq!(at(fanuc.clone(), again, Rule::TravelExceeded), []);
        let notes = findings(fanuc, &program(again), Rule::NotFollowed);
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0]
                .message
                .contains("a second mirror image of an axis already mirrored"),
            "{}",
            notes[0].message
        );
    }

    #[test]
    fn a_lathe_s_coordinate_setting_is_its_g_code_system_s() {
        // review 15, finding 4: in G code systems B and C the coordinate setting is G92 (A's
        // G50), and G50 is no code: X900. then X-300. spans 1200, more than X's 1000, unless
        // a setting between them starts the span again
        let body = |code: &str| format!("G00 X900. Z0\n{code} X0 Z0\nG00 X-300.");
        for system in [GCodeSystem::A, GCodeSystem::B, GCodeSystem::C] {
            let mut lathe = fanuc_lathe();
            lathe.modal.g_system = system;
            let (setting, none) = if system == GCodeSystem::A {
                ("G50", "G92")
            } else {
                ("G92", "G50")
            };
            assert_eq!(
                at(lathe.clone(), &body(setting), Rule::TravelExceeded),
                [],
                "{system:?}"
            );
            assert_eq!(
                at(lathe, &body(none), Rule::TravelExceeded),
                [(4, 5)],
                "{system:?}"
            );
        }
    }

    #[test]
    fn an_okuma_mill_s_frames_are_its_own_codes() {
        // review 15, finding 3: G11 (parallel and rotation shift), G62 (mirror image) and
        // G69 (three-dimensional conversion on; G68 is its cancel): where they put the axes
        // is not known here, so X Y Z under them are left out, said once; Y-300. and X600.
        // under G11 R90. would be Y600. as the checker cannot know
        let okuma = of_family(Family::Okuma);
        for (frame, cancel) in [
            ("G11 X0 Y0 R90.", "G10"),
            ("G62 X10.", ""),
            ("G69 X0 Y0 Z0", "G68"),
        ] {
            let body = format!("G00 X0 Y-300. Z0\n{frame}\nG00 X450. Y350.\nX-450.\n{cancel}");
            assert_eq!(
                at(okuma.clone(), &body, Rule::TravelExceeded),
                [],
                "{frame}"
            );
            let notes = findings(okuma.clone(), &program(&body), Rule::NotFollowed);
            assert_eq!(notes.len(), 1, "{frame}: {notes:?}");
            assert!(notes[0].message.contains("X Y Z"), "{}", notes[0].message);
        }
        // after G10 the axes moved under G11 are unknown until given absolutely, then compared
        let after = "G00 X0 Y-300.\nG11 X0 Y0 R90.\nG00 X100. Y0\nG10\nG91 Y700.\nG90\nY510.";
        assert_eq!(at(okuma.clone(), after, Rule::TravelExceeded), [(8, 1)]);
        // G16 selects a work system on an Okuma (no polar coordinates), G68 ends a frame:
        // the positions after them are compared
        for code in ["G16 H1", "G68"] {
            let body = format!("G00 X0 Y-300.\n{code}\nG00 Y510.");
            assert_eq!(
                at(okuma.clone(), &body, Rule::TravelExceeded),
                [(4, 5)],
                "{code}"
            );
        }
    }

    #[test]
    fn a_mirror_cancel_with_a_word_not_known_leaves_the_axis_not_judged_until_a_known_state() {
        // issue 32 (review 19, finding 1): `G100 X#1` / `G50.1 X#1` was read as ending X's
        // mirror, while the restart calls it not known. X-400. under the mirror about X0 is
        // X400.; after the cancel X600. is X600. (spans 1100 from X-500., past the travel's
        // 1000) or, still mirrored, X-600. (spans 1000, fits): not judged until a known state
        for (config, on, off) in mirror_controls() {
            let body = |unknown: &str, known: &str| {
                format!(
                    "G00 X-500. Y0\n{on} X0 Y0\nG00 X-400. Y100.\n{off} {unknown}\n\
                     G00 X600. Y100.\n{off} {known}\nG00 X600.\n"
                )
            };
            // the known cancel after it: judged again there (X600. unmirrored)
            for known in ["X0", ""] {
                let text = body("X#1", known);
                let found = at(config.clone(), &text, Rule::TravelExceeded);
                assert_eq!(found, [(8, 5)], "{on} {known:?}");
                let notes = findings(config.clone(), &program(&text), Rule::NotFollowed);
                assert!(
                    notes
                        .iter()
                        .any(|n| n.line == 5 && n.message.contains("may or may not have ended")),
                    "{notes:?}"
                );
            }
            // a plain cancel judges at once, as before
            let plain = body("X0", "X0");
            assert_eq!(
                at(config.clone(), &plain, Rule::TravelExceeded),
                [(6, 5)],
                "{on}"
            );
            // another plain word leaves the doubt: Y's cancel says nothing of X
            let other = body("X#1", "Y0");
            assert_eq!(at(config.clone(), &other, Rule::TravelExceeded), [], "{on}");
            // Y beside the doubtful X: a vacant #1 makes the block a bare cancel (review 22,
            // finding 2), so Y is doubtful too: Y-450. not judged; after a plain cancel of Y,
            // Y-450. spans 850 from the Y400. (Y-400. mirrored) of line 4
            let y = format!(
                "G00 X0 Y0\n{on} X0 Y0\nG00 Y-400.\n{off} X#1\nG00 Y-450.\n{off} Y0\nG00 Y-450.\n"
            );
            assert_eq!(
                at(config.clone(), &y, Rule::TravelExceeded),
                [(8, 5)],
                "{on}"
            );
        }
    }

    #[test]
    fn a_mirror_cancel_whose_only_axis_words_are_not_known_leaves_every_mirror_not_known() {
        // review 22, finding 2: on Custom Macro B a vacant variable drops its address (Haas
        // "Address Substitution"; Mitsubishi M700V user macro manual 13.5), so `G50.1 X#1`
        // may be a bare `G50.1`, which ends every mirror. Y was kept mirrored for certain:
        // Y-420. taken as Y420., 20 from the Y400. before it, where a bare cancel makes it
        // 820 from there (the test travel is 800 wide): a possible over-travel passed
        for (config, on, off) in mirror_controls() {
            let body = |cancel: &str, then: &str| {
                format!("G00 X0 Y400.\n{on} X0 Y0\nG00 X10. Y-300.\n{cancel}\n{then}G00 Y-420.\n")
            };
            // a bare cancel: Y-420. spans 820 from Y400.
            let bare = body(off, "");
            assert_eq!(
                at(config.clone(), &bare, Rule::TravelExceeded),
                [(6, 5)],
                "{on}"
            );
            // the word not known: Y not judged (it may be Y420. or Y-420.), said at the cancel
            let vacant = body(&format!("{off} X#1"), "");
            assert_eq!(
                at(config.clone(), &vacant, Rule::TravelExceeded),
                [],
                "{on}"
            );
            let notes = findings(config.clone(), &program(&vacant), Rule::NotFollowed);
            assert!(
                notes.iter().any(|n| n.line == 5
                    && n.message.contains("the positions of X Y under it")
                    && n.message.contains("may or may not have ended")),
                "{notes:?}"
            );
            // a plain cancel of Y after it: judged again
            let known = body(&format!("{off} X#1"), &format!("{off} Y0\n"));
            assert_eq!(
                at(config.clone(), &known, Rule::TravelExceeded),
                [(7, 5)],
                "{on}"
            );
            // a plain word beside it names Y: dropping X#1 leaves `{off} Y0`, which ends Y's
            // mirror alone; X is doubtful, Y judged (820)
            let beside = body(&format!("{off} X#1 Y0"), "");
            assert_eq!(
                at(config.clone(), &beside, Rule::TravelExceeded),
                [(6, 5)],
                "{on}"
            );
            // `{off} X0 Y#1`: X ended, Y doubtful, not judged
            let other = body(&format!("{off} X0 Y#1"), "");
            assert_eq!(at(config.clone(), &other, Rule::TravelExceeded), [], "{on}");
        }
    }

    #[test]
    fn an_axis_mirrored_apart_gets_its_span_from_before_the_mirror_back_at_a_doubt() {
        // review 22, finding 1: a mirror not known exactly here (its point from a parameter,
        // or a Haas's G101 after a G52) keeps its positions apart; a cancel word not known
        // made X doubtful but kept X's span under the mirror, so after a plain cancel of X
        // (Y still mirrored) X's plain positions were compared with the mirrored X450.: a
        // false TG601 (X-560. spans 1010 from X450.) and a missed one (X710. is 1010 from the
        // X-300. before the mirror). With the doubt line or without it, the same verdicts.
        let haas = haas_centres();
        let fanuc = fanuc_centres();
        for (config, shift, on, off) in [
            (haas, "G52 X10. Y0\n", "G101 X0 Y0", "G100"),
            (fanuc, "", "G51.1 X#5 Y#5", "G50.1"),
        ] {
            let body = |doubt: &str, last: &str| {
                format!(
                    "{shift}G00 X-300. Y0\n{on}\nG00 X450. Y100.\n{doubt}\n{off} X0\n\
                     G00 {last}\n"
                )
            };
            for doubt in [format!("{off} X#1"), "(none)".to_string()] {
                let lines = usize::from(!shift.is_empty());
                let found = at(
                    config.clone(),
                    &body(&doubt, "X-560."),
                    Rule::TravelExceeded,
                );
                assert_eq!(found, [], "{on} {doubt}");
                let found = at(config.clone(), &body(&doubt, "X710."), Rule::TravelExceeded);
                assert_eq!(found, [(7 + lines, 5)], "{on} {doubt}");
            }
        }
    }

    #[test]
    fn a_fanuc_mirror_named_again_after_a_doubtful_cancel_is_judged_as_a_span_of_its_own() {
        // review 23: after `G50.1 X#1` (XY in doubt) a new `G51.1 X0 Y0` left Y unjudged,
        // where both readings of the doubtful line flag it (the line removed: a second
        // mirror, its positions apart; a bare G50.1: a fresh exact mirror): Y-420. and Y420.
        // under one mirror stand 840 apart whatever its point (travel Y -400..400)
        let body = |doubt: &str, on: &str, y: &str| {
            format!(
                "G00 X0 Y400.\nG51.1 X0 Y0\nG00 X10. Y-300.\n{doubt}\n{on}\nG00 Y-{y}\n\
                 G00 Y{y}\nG50.1"
            )
        };
        for doubt in ["G50.1 X#1", "(none)", "G50.1"] {
            let found =
                |on: &str, y: &str| at(fanuc_centres(), &body(doubt, on, y), Rule::TravelExceeded);
            assert_eq!(found("G51.1 X0 Y0", "420."), [(8, 5)], "{doubt}");
            assert_eq!(found("G51.1 X0 Y0", "390."), [], "{doubt}");
            // Y not named again: after the doubtful line Y stays unjudged (the other two
            // readings flag it, Y mirrored for certain, or plain: Y-420. is 820 from Y400.)
            let y_unnamed = found("G51.1 X0", "420.");
            let expected: &[(usize, usize)] = match doubt {
                "G50.1 X#1" => &[],
                "(none)" => &[(8, 5)],
                _ => &[(7, 5)],
            };
            assert_eq!(y_unnamed, expected, "{doubt}");
        }
        // named by a value not known here: still in doubt
        let found = at(
            fanuc_centres(),
            &body("G50.1 X#1", "G51.1 X0 Y#2", "420."),
            Rule::TravelExceeded,
        );
        assert_eq!(found, []);
    }

    #[test]
    fn a_mirror_resets_the_span_of_the_axes_it_mirrors_only() {
        // review 24, finding 1: a G51.1 not known exactly here (under G91, or with an axis
        // apart) while a mirror's spans were kept reset every axis's span, those of axes it
        // does not mirror too: Y given its span back by `G50.1 Y0` lost it at a `G51.1 X0`,
        // and Y400. and Y-420., both plain, 820 apart (travel Y -400..400), passed
        let found = |body: &str| at(fanuc_centres(), body, Rule::TravelExceeded);
        let ended = |second: &str, y: &str| {
            format!(
                "G00 X0 Y400.\nG91 G51.1 X0 Y0\nG90 G00 X10. Y-300.\nG50.1 Y0\n{second}\n\
                 G00 Y-{y}\nG50.1"
            )
        };
        for second in ["G51.1 X0", "(none)"] {
            assert_eq!(found(&ended(second, "420.")), [(7, 5)], "{second}");
            assert_eq!(found(&ended(second, "390.")), [], "{second}");
        }
        // Y mirrored again: its positions from there stand apart
        assert_eq!(found(&ended("G51.1 Y0", "420.")), []);
        // an axis no mirror names keeps one span across the mirror
        let beside =
            |mirror: &str| format!("G00 X0 Y400.\nG91 {mirror}\nG90 G00 X10. Y-420.\nG50.1");
        assert_eq!(found(&beside("G51.1 X0")), [(4, 14)]);
        assert_eq!(found(&beside("G51.1 Y0")), []);
        // review 23's case with a first mirror not known exactly: the doubtful line read
        // either way, or gone, Y400. before the mirrors and Y-420. after them are 820 apart
        let again = |doubt: &str, y: &str| {
            format!(
                "G00 X0 Y400.\nG91 G51.1 X0 Y0\nG90 G00 X10. Y-300.\n{doubt}\nG51.1 X0 Y0\n\
                 G00 Y-10.\nG50.1\nG00 Y-{y}"
            )
        };
        for doubt in ["G50.1 X#1", "G50.1", "(none)"] {
            assert_eq!(found(&again(doubt, "420.")), [(9, 5)], "{doubt}");
            assert_eq!(found(&again(doubt, "390.")), [], "{doubt}");
        }
        // an axis whose mirror ends plainly while another's is in doubt gets its span back
        // (X in doubt after `G50.1 X#1 Z0`; `G50.1 Y0` ends Y's mirror for certain)
        let doubt = |y: &str| {
            format!(
                "G00 X0 Y400.\nG91 G51.1 X0 Y0\nG90 G00 X10. Y-300.\nG50.1 X#1 Z0\nG50.1 Y0\n\
                 G00 Y-{y}\nG50.1"
            )
        };
        assert_eq!(found(&doubt("420.")), [(7, 5)]);
        assert_eq!(found(&doubt("390.")), []);
    }

    #[test]
    fn a_haas_scaling_leaves_a_canned_cycle_s_z_out_with_a_note() {
        let haas = haas_centres();
        // Z-180. scaled by 2 about Z0 is Z-360., 410 from Z50. (Z's travel 400): a plain
        // move is compared, a drilling cycle's Z is not (the manual leaves it open), said
        let body =
            |z: &str| format!("G00 X0 Y0 Z50.\nG51 X0 Y0 Z0 P2.\nG00 X0 Y0 Z20.\n{z}\nG80\nG50");
        assert_eq!(
            at(
                haas.clone(),
                &body("G01 Z-180. F100."),
                Rule::TravelExceeded
            ),
            [(5, 5)]
        );
        let cycle = body("G81 X0 Y0 Z-180. R20. F100.");
        assert_eq!(at(haas.clone(), &cycle, Rule::TravelExceeded), []);
        let notes = findings(haas.clone(), &program(&cycle), Rule::NotFollowed);
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].message.contains("canned cycle"),
            "{}",
            notes[0].message
        );
        // a FANUC's scaling is left out whole (its factor's unit is a parameter)
        assert_eq!(at(fanuc_centres(), &cycle, Rule::TravelExceeded), []);
    }

    #[test]
    fn the_span_of_the_program_fits_the_travel() {
        let fits = "G00 X-400.\nX400.";
        assert_eq!(at(iso_mill(), fits, Rule::TravelExceeded), []);
        let wide = "G00 X-400.\nX700.\nX-450.";
        assert_eq!(at(iso_mill(), wide, Rule::TravelExceeded), [(3, 1)]);
        assert_eq!(at(iso_mill(), "G53 X600.", Rule::TravelExceeded), [(2, 5)]);
        assert_eq!(at(iso_mill(), "G53 X400.", Rule::TravelExceeded), []);
    }

    #[test]
    fn a_polar_angle_and_a_tilted_plane_s_origin_are_no_positions() {
        // a FANUC mill: G16 makes the plane's axis words a radius and an angle (meaning.rs)
        let fanuc = fanuc_centres();
        // the span of Y is 900, more than the travel's 800
        let cartesian = "G00 X10. Y-450.\nX10. Y450.";
        assert_eq!(at(fanuc.clone(), cartesian, Rule::TravelExceeded), [(3, 6)]);
        // under G16 they are angles: where the axes are is not known, nothing is said
        let polar = "G17 G16\nG00 X10. Y-450.\nX10. Y450.\nG15";
        assert_eq!(at(fanuc.clone(), polar, Rule::TravelExceeded), []);
        // in G18 the angle is X: -600 and 600 are no positions either
        let zx = "G18 G16\nG00 Z10. X-600.\nZ10. X600.\nG15";
        assert_eq!(at(fanuc.clone(), zx, Rule::TravelExceeded), []);
        // after G15 the axes are coordinates again
        let after = "G16\nG00 X10. Y30.\nG15\nG00 Y-450.\nY450.";
        assert_eq!(at(fanuc.clone(), after, Rule::TravelExceeded), [(6, 1)]);
        // G68.2 X Y Z is the tilted plane's origin, G07.1 C the cylinder's radius: no move
        let tilted = "G68.2 X0 Y-450. Z0 I0 J45. K0\nG00 Y450.";
        assert_eq!(at(fanuc.clone(), tilted, Rule::TravelExceeded), []);
        let state = run(
            fanuc,
            &dialect(Family::MacroB),
            &program("G68.2 X0 Y-450. Z0 I0 J45. K0"),
        );
        assert_eq!(state.0.machine.state.axis(b'Y'), None);
    }

    #[test]
    fn machine_positions_through_the_work_offset_in_force() {
        let inside = "G54 G00 X-200. Y100.";
        assert_eq!(at(with_offsets(), inside, Rule::TravelExceeded), []);
        // X-400 under G54 is X-600 on the machine: said where the excursion starts
        let outside = "G54 G00 X-400.\nX-450.\nX0\nX-350.";
        assert_eq!(
            at(with_offsets(), outside, Rule::TravelExceeded),
            [(2, 9), (5, 1)]
        );
        let found = findings(with_offsets(), &program(outside), Rule::TravelExceeded);
        assert!(
            found[0].message.contains("G54 offset -200"),
            "{}",
            found[0].message
        );
        // after G10 the profile's offsets are not known to be in force
        let lost = "G10 L2 P1 X0\nG54 G00 X-400.";
        assert_eq!(at(with_offsets(), lost, Rule::TravelExceeded), []);
    }

    /// A span does not run across a selection of another work system where both systems'
    /// values are known: each position is judged as a machine position there (review
    /// 76-lcnc76b N3: `G54` / `G0 X-650` / `G57` / `G0 X1000` with G57 X -300 runs at -650
    /// and 700, inside, and was "X spans 1650"); it does across one not known.
    #[test]
    fn a_span_starts_again_at_a_selection_of_another_known_system() {
        let dec = |text: &str| Dec::parse(text).unwrap();
        for family in [Family::MacroB, Family::LinuxCnc] {
            let mut config = of_family(family);
            config.facts.work_offsets = vec![
                (54, b'X', dec("0")),
                (55, b'X', dec("-300")),
                (55, b'Y', dec("0")),
            ];
            // travel X -500..500: -450 under G54 and 550 under G55 (250 on the machine)
            let across = "G90 G54 G00 X-450.\nG55 X550.";
            assert_eq!(
                at(config.clone(), across, Rule::TravelExceeded),
                [],
                "{family:?}"
            );
            // G56, which the profile does not give: the span runs on across it
            let unknown = "G90 G54 G00 X-450.\nG56 X560.";
            assert_eq!(
                at(config.clone(), unknown, Rule::TravelExceeded),
                [(3, 5)],
                "{family:?}"
            );
            // G91 after the selection runs from where the tool stands, which the selection
            // moved in work coordinates: the span joins again (review 78-lcnc78b F1)
            let g91 = "G90 G54 G00 X-450.\nG55\nG91 X1010.";
            assert_eq!(
                at(config.clone(), g91, Rule::TravelExceeded),
                [(4, 5)],
                "{family:?}"
            );
            // a position before the first selection, not judged: the span is kept (F3)
            let start = "G90 G00 X-450.\nG54 X0\nG55 X560.";
            assert_eq!(
                at(config.clone(), start, Rule::TravelExceeded),
                [(4, 5)],
                "{family:?}"
            );
            // a span already said is kept (said once)
            let said = "G90 G54 G00 X-450.\nG56 X560.\nG54 X-450.\nG55 X550.\nG54 X-450.";
            assert_eq!(
                at(config, said, Rule::TravelExceeded),
                [(3, 5)],
                "{family:?}"
            );
        }
    }

    #[test]
    fn feed_speed_and_tool_limits() {
        let slow = Config {
            facts: ProfileFacts {
                feed_max: Some(Dec::parse("500").unwrap()),
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        assert_eq!(
            at(slow.clone(), "G01 X1. F600.", Rule::FeedTooHigh),
            [(2, 9)]
        );
        assert_eq!(at(slow.clone(), "G01 X1. F400.", Rule::FeedTooHigh), []);
        // a FANUC clamps the feed (a warning); a Haas alarms (the error)
        let fanuc = Config {
            family: Family::MacroB,
            ..slow.clone()
        };
        assert_eq!(
            at(fanuc.clone(), "G01 X1. F600.", Rule::FeedClamped),
            [(2, 9)]
        );
        assert_eq!(at(fanuc.clone(), "G01 X1. F600.", Rule::FeedTooHigh), []);
        let haas = Config {
            haas: true,
            ..fanuc
        };
        assert_eq!(
            at(haas.clone(), "G01 X1. F600.", Rule::FeedTooHigh),
            [(2, 9)]
        );
        assert_eq!(at(haas, "G01 X1. F600.", Rule::FeedClamped), []);
        // 30 in/min is 762 mm/min: said in both units
        let found = findings(slow, &program("G70 G01 X1. F30."), Rule::FeedTooHigh);
        assert_eq!(found.len(), 1);
        assert!(
            found[0].message.contains("(762 mm/min)"),
            "{}",
            found[0].message
        );
        assert_eq!(at(iso_mill(), "S7000 M03", Rule::SpeedTooHigh), [(2, 1)]);
        assert_eq!(at(iso_mill(), "S5000 M03", Rule::SpeedTooHigh), []);
        // the spindle speed clamp's S (G92 on a mill) turns nothing: not judged (audit 37)
        assert_eq!(at(iso_mill(), "G92 S7000", Rule::SpeedTooHigh), []);
        assert_eq!(
            at(iso_mill(), "G92 S7000\nS7000 M03", Rule::SpeedTooHigh),
            [(3, 1)]
        );
        // on a control family's profile: a warning (no source says the control alarms)
        let family = Config {
            family: Family::MacroB,
            ..iso_mill()
        };
        assert_eq!(
            at(family.clone(), "S7000 M03", Rule::SpeedLimited),
            [(2, 1)]
        );
        assert_eq!(at(family.clone(), "S7000 M03", Rule::SpeedTooHigh), []);
        assert_eq!(at(family.clone(), "G92 S7000", Rule::SpeedLimited), []);
        // a user's file that sets its spindle_max: the user's machine, the error; one on a
        // base that leaves it to the base keeps the sample's warning (review 38, finding 4)
        let mut own = family.clone();
        own.facts.sample_limits = super::super::SAMPLE_ALL & !super::super::SAMPLE_SPINDLE;
        own.facts.feed_max = Dec::parse("500");
        assert_eq!(at(own.clone(), "S7000 M03", Rule::SpeedTooHigh), [(2, 1)]);
        assert_eq!(at(own.clone(), "S7000 M03", Rule::SpeedLimited), []);
        // ... and its feed, left to the base, is said to be the sample's (a FANUC clamps it)
        let fast = findings(own, &program("G01 X1. F600."), Rule::FeedClamped);
        assert!(
            fast[0].message.contains("this limit is the base profile's"),
            "{}",
            fast[0].message
        );
        let mut feed_own = family;
        feed_own.facts.sample_limits = super::super::SAMPLE_SPINDLE;
        feed_own.facts.feed_max = Dec::parse("500");
        let fast = findings(feed_own, &program("G01 X1. F600."), Rule::FeedClamped);
        assert!(!fast[0].message.contains("typical"), "{}", fast[0].message);
        assert_eq!(at(iso_mill(), "T100", Rule::ToolOutOfRange), [(2, 1)]);
        assert_eq!(at(iso_mill(), "T12", Rule::ToolOutOfRange), []);
    }

    #[test]
    fn a_lathe_t_word_is_limited_by_its_tool_part_not_its_offset_digits() {
        // parameter 5028 = 2: T2500 is tool 25 with offset 00, T0101 tool 1 offset 1 (the
        // test profile's T has four digits)
        let lathe = || {
            let mut config = super::super::testing::fanuc_lathe();
            config.facts.tool_max = Some(30);
            config
        };
        assert_eq!(at(lathe(), "T2500", Rule::ToolOutOfRange), []);
        assert_eq!(at(lathe(), "T0101", Rule::ToolOutOfRange), []);
        let found = findings(lathe(), &program("T3101"), Rule::ToolOutOfRange);
        assert_eq!(found.len(), 1);
        assert!(
            found[0]
                .message
                .contains("tool 31 (T3101: tool 31, offset 01)"),
            "{}",
            found[0].message
        );
        // a mill's T is the tool number whole
        let mut mill = of_family(Family::MacroB);
        mill.facts.tool_max = Some(30);
        assert_eq!(at(mill, "T0301", Rule::ToolOutOfRange), [(2, 1)]);
    }
}
