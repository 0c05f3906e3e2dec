//! The modal state of a program, block by block (ISO 6983-1 clauses 5.3, 7-14, Annex E).
//!
//! An omitted word means "no change" (5.3): what a block does depends on everything before
//! it. [`ModalMachine`] keeps the complete [`ModalState`] -- motion mode, plane, units,
//! distance mode, feed mode and value, spindle, coolant, compensation, offsets, zero shift,
//! tool, fixed cycle and its words, and the absolute position -- from the reset state of
//! clause 14 for the profile's control type, and resets again after M02/M30.
//!
//! This is the one modal state of tapegate: the checker reads it before and after each
//! block, and Python's `postproc.state` (restart preamble, plot) is a view of it.

use crate::decimal::Dec;
use crate::lex::Family;
use crate::lex::{GCodeSystem, ABSOLUTE, INCREMENTAL};

/// The axes whose words move the machine, in the order positions are kept.
pub const AXES: &[u8; 9] = b"XYZUVWABC";
/// The words a fixed cycle keeps for its later blocks.
pub const CYCLE_WORDS: &[u8; 5] = b"RZQPF";

/// Whether decimal G code `v` is a programmable mirror image's G50.1 or G51.1
/// ([`BlockValues::mirror`]).
pub fn mirror_code(v: Dec) -> bool {
    let tenths = v.normalized();
    tenths.scale == 1 && matches!(tenths.mantissa, 501 | 511)
}

/// The place of `letter` in [`AXES`] (asked for every axis of every block: no search).
pub fn axis_index(letter: u8) -> Option<usize> {
    match letter {
        b'X' => Some(0),
        b'Y' => Some(1),
        b'Z' => Some(2),
        b'U' => Some(3),
        b'V' => Some(4),
        b'W' => Some(5),
        b'A' => Some(6),
        b'B' => Some(7),
        b'C' => Some(8),
        _ => None,
    }
}

/// The axes among `letters` (a mask of [`bit`]s) by their places in [`AXES`], a bit each. The
/// letters' bits of X Y Z are 23-25, of U V W 20-22 and of A B C 0-2, so three shifts give
/// the places: a walk over the axes a block writes (two or three of the nine, most often)
/// looks at no other.
pub const fn axis_places(letters: u32) -> u32 {
    ((letters >> 23) & 0b111) | (((letters >> 20) & 0b111) << 3) | ((letters & 0b111) << 6)
}

/// The places of [`axis_places`] one by one, lowest first: the order of [`AXES`].
pub fn places(mut places: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        let i = places.trailing_zeros();
        places &= places.wrapping_sub(1);
        (i < 32).then_some(i as usize)
    })
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Units {
    Metric,
    Inch,
}

impl Units {
    pub fn name(self) -> &'static str {
        match self {
            Units::Metric => "metric",
            Units::Inch => "inch",
        }
    }
}

/// (Copy: the checker keeps the state before and after every block, and a copy is one move
/// of its bytes, where a clone went through a temporary, two moves.)
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModalState {
    pub motion: Option<i64>,
    pub plane: i64,
    pub units: Units,
    /// The units of the feed F: the units of lengths, but on Sinumerik, whose G70/G71 leave F
    /// in the basic system (the profile's units) and whose G700/G710 set both.
    pub feed_units: Units,
    /// Whether the program has written a units code: until it does, its numbers are in the
    /// units the machine is set to at power-on (a Haas's Setting 9), which the profile's
    /// `units` only assumes (the limits' messages say so).
    pub units_given: bool,
    pub incremental: bool,
    pub feed_mode: i64,
    pub feed: Option<Dec>,
    pub spindle_mode: i64,
    pub speed: Option<Dec>,
    pub speed_limit: Option<Dec>,
    /// 3 (cw), 4 (ccw) or 5 (stop).
    pub spindle: i64,
    /// 7 (mist), 8 (flood) or 9 (off).
    pub coolant: i64,
    pub compensation: i64,
    pub length_offset: i64,
    pub zero_shift: Option<i64>,
    pub tool: Option<i64>,
    pub offset: Option<i64>,
    pub cycle: Option<i64>,
    pub cycle_words: [Option<Dec>; 5],
    pub position: [Option<Dec>; 9],
    pub ended: bool,
    /// Letters (bit `letter - b'A'`) whose value in force was set by something the checker
    /// cannot evaluate -- `F#101`, `X[#1+#2]`, a jump, a call -- so it is there but unknown:
    /// a feed set by a parameter is a feed in force, not a missing one.
    pub unknown: u32,
    /// G16 is in force (a FANUC or Haas mill, [`crate::meaning::polar_code`]): the plane's axis
    /// words are a radius and an angle ([`crate::meaning::polar_axes`]), not coordinates.
    pub polar: bool,
}

/// A FANUC or Haas lathe's threading G32 and threading cycle G92 (system A numbers): codes
/// of the motion group (group 01), so a block after them that writes no other code of the
/// group repeats them, its words meaning what theirs do -- a multi-start thread's next pass
/// `X23.5 Q90000` under G92 cuts at the start angle Q, in 0.001 deg, as the G92 block's own Q
/// (FANUC 0i-TF operator's manual, "Threading cycle (G92)": the cycle's data are modal;
/// "Threading (G32)"; review 57a, F4: the angle was read as the cycle's only in the block
/// that names it). The one list of the converter's and the diff's reading
/// (`convert::Repeat`) and of the checker's ([`ModalState::code_in_force`]).
pub fn modal_thread(g: i64) -> bool {
    matches!(g, 32 | 92)
}

/// Whether a block whose G codes (system A numbers; `unread`: a G word read as no whole code,
/// a decimal `G7.1` or a macro's `G#1`) are `gs` is a plain pass of a lathe's thread in force
/// ([`modal_thread`]), its words the thread's: codes of the modal groups that give Q no
/// meaning alone -- the planes G17-G19, inch/metric G20/G21, the stroke check G22/G23, the
/// nose radius compensation G40-G42, the work coordinate systems G54-G59, the spindle and feed
/// modes G96-G99 and system B's and C's absolute and incremental G90/G91 (FANUC 0i-TF
/// B-64604EN, "G code list": groups 16, 06, 04, 07, 14, 02, 05, 03). Any other code is the
/// block's own, not a pass: a code of group 00 reads its Q as its own (G65's argument #17,
/// G74/G75/G76's depths in least input increments of length, G10's data), as does a drilling
/// cycle of group 10 (G83's peck); the motion group's others end the thread. The one test
/// of the checker's reading (`convert::block_meanings`), the converter's and the diff's
/// (review 58b, F1, F2, F7: a G75 straight after a G92 pass had its Q depth left unconverted).
pub fn thread_pass(gs: &[i64], unread: bool) -> bool {
    use crate::lex::{ABSOLUTE, INCREMENTAL};
    !unread
        && gs.iter().all(|&g| {
            matches!(g, 17..=23 | 40..=42 | 54..=59 | 96..=99 | ABSOLUTE | INCREMENTAL)
                || modal_thread(g)
        })
}

impl ModalState {
    /// The code a block of a FANUC or Haas control naming no code of the motion group
    /// repeats, its words read as that code's (`convert::block_meanings`): the mill's canned
    /// cycle in force, a lathe's (`fanuc_lathe`) threading G32 or G92 ([`modal_thread`]) where
    /// no drilling cycle is in force. A lathe's drilling cycles are not read into such a block.
    pub fn code_in_force(&self, fanuc_lathe: bool) -> Option<i64> {
        if fanuc_lathe {
            // (a drilling cycle after the thread, `G92 ...` then `G83 ...`: its repeats are
            // no thread's passes, though G83 of group 10 leaves G92 in group 01; review 58b, F7)
            self.motion
                .filter(|&g| modal_thread(g) && self.cycle.is_none())
        } else {
            self.cycle
        }
    }
}

/// Under G16, the plane's first axis is the radius and its second the angle in degrees
/// (FANUC Series 16/18-MC operator's manual, "Polar coordinate command (G15, G16)"): G17 X Y,
/// G18 Z X, G19 Y Z.
pub fn polar_axes(plane: i64) -> (u8, u8) {
    match plane {
        18 => (b'Z', b'X'),
        19 => (b'Y', b'Z'),
        _ => (b'X', b'Y'),
    }
}

/// A length `value` in `units` as millimetres.
/// An axis whose position is no longer known (a lathe's X beside U in one block): off the
/// hot path, which a mill's block never takes.
#[cold]
#[inline(never)]
fn lose_axis(s: &mut ModalState, drift: &mut Drift, j: usize, axis: u8) {
    s.position[j] = None;
    s.unknown |= bit(axis);
    *drift = Drift::default();
}

fn to_mm(value: Dec, units: Units) -> f64 {
    match units {
        Units::Inch => value.to_f64() * 25.4,
        Units::Metric => value.to_f64(),
    }
}

/// The bit of `letter` in [`ModalState::unknown`] and [`BlockValues::unknown`].
pub const fn bit(letter: u8) -> u32 {
    1 << (letter - b'A')
}

/// What a jump or a call leaves unknown: the position, the feed and the speed.
/// X, Z and their lathe increments U, W.
const XZUW: u32 = bit(b'X') | bit(b'Z') | bit(b'U') | bit(b'W');

/// [`ModalMachine::ran_cycle`]: the block ran a lathe's cycle that returns to its start point.
pub const CYCLE_RAN: u8 = 1;
/// [`ModalMachine::ran_cycle`]: some of where the block's cycle went is not known.
pub const CYCLE_UNSURE: u8 = 2;

pub const FORGOTTEN: u32 = bit(b'X')
    | bit(b'Y')
    | bit(b'Z')
    | bit(b'U')
    | bit(b'V')
    | bit(b'W')
    | bit(b'A')
    | bit(b'B')
    | bit(b'C')
    | bit(b'F')
    | bit(b'S');

impl ModalState {
    pub fn new(units: Units) -> ModalState {
        ModalState {
            motion: None,
            plane: 17,
            units,
            feed_units: units,
            units_given: false,
            incremental: false,
            feed_mode: 94,
            feed: None,
            spindle_mode: 97,
            speed: None,
            speed_limit: None,
            spindle: 5,
            coolant: 9,
            compensation: 40,
            length_offset: 49,
            zero_shift: None,
            tool: None,
            offset: None,
            cycle: None,
            cycle_words: [None; 5],
            position: [None; 9],
            ended: false,
            unknown: 0,
            polar: false,
        }
    }

    pub fn axis(&self, letter: u8) -> Option<Dec> {
        axis_index(letter).and_then(|i| self.position[i])
    }

    /// Whether `letter`'s value in force is there but unknown (see [`ModalState::unknown`]).
    pub fn is_unknown(&self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.unknown & bit(letter) != 0
    }
}

/// The readable values of one block: G and M codes in order, the first value of each letter.
///
/// The values of the letters A-Z are kept beside a mask of the letters given (by [`bit`]):
/// every block is cleared and asked for its letters, and a mask is cleared in one store and
/// asked in one test, where 26 `Option<Dec>` (1,248 bytes) were written for every block.
#[derive(Clone, Debug)]
pub struct BlockValues {
    /// The G codes in order ([`BlockValues::push_g`]).
    gs: Vec<i64>,
    /// The G codes 0 to 127 among them, a bit each: the modal state and the rules ask a
    /// block for a dozen codes ([`BlockValues::has_g`]), each a test of the mask, not a search
    /// of the list.
    g_mask: u128,
    pub ms: Vec<i64>,
    /// The block selects a work system the modal state does not number (a decimal code of
    /// G54 or G59: FANUC's G54.1, LinuxCNC's G59.1-G59.3): the system in force is not known.
    pub other_work_system: bool,
    /// The block has a G code with decimals (G51.1, G92.1): none of them is in `gs`, and the
    /// frames ask for them only where this is set.
    pub decimal_g: bool,
    /// The block has a programmable mirror image's code (G50.1, G51.1): its axis words are
    /// the mirror's axes and point, no move ([`ModalSettings::axes_taken`]).
    pub mirror: bool,
    /// The first value of each letter, meaningful where `given` has the letter's bit.
    values: [Dec; 26],
    given: u32,
    /// Letters whose word a code of the block makes no length, position or cycle value (`K3`
    /// of a FANUC canned cycle, its repeat count), their value kept in `values` all the same
    /// ([`BlockValues::other`]): the machine's positions never read them as `given`'s.
    others: u32,
    /// Letters given a value the checker cannot evaluate (`F#101`), by [`bit`].
    pub unknown: u32,
    /// The block's first K, written without a point where the profile reads K in least
    /// increments and the block's cycle makes K its count, read as its whole number: a FANUC
    /// canned cycle's repeat count (0i-MF, "Canned cycle": `K3`, three holes), which K's
    /// increments read 0.003 ([`ModalMachine::cycle_repeats`]). Set by the modal state's own
    /// reading alone ([`crate::word::Numbers::block_values`], which resets it), where the
    /// rule the checker asks says K counts (`meaning::Meanings::cycle_count`: not a Haas
    /// G73/G83's least peck depth, nor a K outside a cycle): the checker reads a count
    /// by its block's codes, and leaves it None (no cost on its path).
    pub k_whole: Option<Dec>,
    /// The block's first K is no count by the rule the checker asks (a K the modal state's
    /// own reading found in no count role, with a point or without: review 56a, F8, `K3.`
    /// was counted where the rule made it none), so a FANUC cycle's holes are not repeated
    /// by it ([`ModalMachine::cycle_repeats`]). Set by the modal state's own reading alone,
    /// as [`BlockValues::k_whole`] is; the checker leaves it false.
    pub k_no_count: bool,
    /// The block's M02/M30 may not run (LinuxCNC: one inside an o-word condition or loop, or
    /// in a subroutine's definition): the lines after it run only where it did not, so it
    /// resets nothing ([`ModalMachine::apply`]).
    pub end_unsure: bool,
}

impl Default for BlockValues {
    fn default() -> BlockValues {
        BlockValues {
            gs: Vec::new(),
            g_mask: 0,
            ms: Vec::new(),
            other_work_system: false,
            decimal_g: false,
            mirror: false,
            values: [Dec::ZERO; 26],
            given: 0,
            others: 0,
            unknown: 0,
            end_unsure: false,
            k_whole: None,
            k_no_count: false,
        }
    }
}

impl BlockValues {
    pub fn clear(&mut self) {
        self.gs.clear();
        self.g_mask = 0;
        self.ms.clear();
        self.other_work_system = false;
        self.decimal_g = false;
        self.mirror = false;
        self.given = 0;
        self.others = 0;
        self.unknown = 0;
        self.end_unsure = false;
    }

    /// Keep `value` for `letter`, a word the block's codes make no length, position or cycle
    /// value ([`BlockValues::other`]), unless the block already gave that letter one.
    pub fn set_other(&mut self, letter: u8, value: Dec) {
        if letter.is_ascii_uppercase() && (self.given | self.others) & bit(letter) == 0 {
            self.others |= bit(letter);
            self.values[(letter - b'A') as usize] = value;
        }
    }

    /// The value of a word the block's codes make no length, position or cycle value.
    pub fn other(&self, letter: u8) -> Option<Dec> {
        (letter.is_ascii_uppercase() && self.others & bit(letter) != 0)
            .then(|| self.values[(letter - b'A') as usize])
    }

    /// Note that the block gives `letter` a value that cannot be evaluated.
    pub fn set_unknown(&mut self, letter: u8) {
        if letter.is_ascii_uppercase() {
            self.unknown |= bit(letter);
        }
    }

    /// Keep `value` for `letter` unless the block already gave that letter one.
    pub fn set_default(&mut self, letter: u8, value: Dec) {
        if letter.is_ascii_uppercase() && self.given & bit(letter) == 0 {
            self.given |= bit(letter);
            self.values[(letter - b'A') as usize] = value;
        }
    }

    /// Give `letter` the value a form of the block makes of its word (a HEIDENHAIN centre
    /// under G91 made absolute, a SINUMERIK `I=AC(..)` made an increment): None, the letter is
    /// given but unknown.
    pub fn overwrite(&mut self, letter: u8, value: Option<Dec>) {
        if !letter.is_ascii_uppercase() {
            return;
        }
        match value {
            Some(v) => {
                self.given |= bit(letter);
                self.unknown &= !bit(letter);
                self.values[(letter - b'A') as usize] = v;
            }
            None => {
                self.given &= !bit(letter);
                self.unknown |= bit(letter);
            }
        }
    }

    pub fn get(&self, letter: u8) -> Option<Dec> {
        self.has(letter)
            .then(|| self.values[(letter - b'A') as usize])
    }

    pub fn has(&self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.given & bit(letter) != 0
    }

    /// Add the block's next G code.
    pub fn push_g(&mut self, g: i64) {
        if (0..128).contains(&g) {
            self.g_mask |= 1 << g;
        }
        self.gs.push(g);
    }

    /// The block's G codes, in order.
    pub fn gs(&self) -> &[i64] {
        &self.gs
    }

    /// The letters the block gives a value, by [`bit`].
    pub fn given(&self) -> u32 {
        self.given
    }

    /// The block's G codes 0 to 127, a bit each (bit `g` for G`g`).
    pub fn g_mask(&self) -> u128 {
        self.g_mask
    }

    /// The block's G codes by the numbers the core reads them by ([`ModalSettings::read_g`]):
    /// a FANUC lathe's codes of G code system B or C as system A's.
    #[inline(always)]
    pub fn in_system(&mut self, settings: &ModalSettings) {
        if settings.g_system != GCodeSystem::A {
            self.renumber(settings);
        }
    }

    #[cold]
    fn renumber(&mut self, settings: &ModalSettings) {
        let written = std::mem::take(&mut self.gs);
        self.g_mask = 0;
        for g in written {
            self.push_g(settings.read_g(g));
        }
    }

    pub fn has_g(&self, g: i64) -> bool {
        if (0..128).contains(&g) {
            self.g_mask & 1 << g != 0
        } else {
            self.gs.contains(&g)
        }
    }
}

/// What the profile says about the modal state: the reset codes and the units codes.
#[derive(Debug, Clone)]
pub struct ModalSettings {
    pub reset: Vec<i64>,
    pub inch: i64,
    pub metric: i64,
    pub default_units: Units,
    /// The control's family: which of its non-modal codes take a block's axis words
    /// ([`ModalSettings::axes_taken`]).
    pub family: Family,
    /// A Fanuc or Haas lathe: `G50 S` clamps the spindle speed (ISO: `G92 S`), and G98/G99 are
    /// feed per minute and per revolution (ISO: G94/G95).
    pub fanuc_lathe: bool,
    /// LinuxCNC: G80 cancels the motion mode too (no motion mode until the next G0-G3).
    pub g80_clears_motion: bool,
    /// Fanuc and Haas mills: `G68 X Y R` (rotation) and `G51 X Y Z P` (scaling) take their
    /// axis words as the centre, not as a move.
    pub centre_codes: bool,
    /// HEIDENHAIN ISO: G10-G13, G15, G16 are polar moves (about the pole, by R and H), G80
    /// tilts the working plane, G83-G86 define cycles (called by G79) rather than run them,
    /// G30/G31 define the blank form, and G28 (mirror), G54 (datum shift), G72 (scaling),
    /// G73 (rotation) change the coordinates by their words.
    pub heidenhain: bool,
    /// An Okuma lathe: G80-G87 define contours and call the LAP cycles (Lathe
    /// Auto-Programming), no drilling cycles; the contour's blocks are the cycle's data.
    pub lap: bool,
    /// A mill's G92 S is the spindle speed clamp (a FANUC mill, ISO 6983-1, a SINUMERIK's ISO
    /// mode); a Haas, Okuma or LinuxCNC mill's G92 only sets coordinates, and an S beside it
    /// is a speed (their code tables; review 38, finding 1: the restart's preamble took a
    /// Haas's `G92 S8000 M03` for a clamp and started the spindle at the speed before).
    pub g92_clamps: bool,
    /// Sinumerik: the units codes G70/G71 set the units of lengths only (the feed stays in the
    /// basic system, `default_units`), and G700/G710 set both (Programming Manual
    /// Fundamentals, "Inch or metric dimensions").
    pub sinumerik_units: bool,
    /// The units a program selected stay in force after its M02/M30, as on a Fanuc, a Haas
    /// (Setting 9) and LinuxCNC, so a program after it (a local subprogram, a second program
    /// of the file) is read in them. Otherwise they return to the reset state's, as clause 14
    /// and a Sinumerik (machine data MD20150 by default) have it.
    pub units_kept_at_end: bool,
    /// The words of a G04 block that are the dwell's data, not moves, feeds or speeds
    /// ([`crate::word::dwell_words`]).
    pub dwell: &'static [u8],
    /// The letter of an arc's radius, R or an Okuma lathe's L ([`crate::word::arc_radius`]).
    pub arc_radius: u8,
    /// The G numbers a control family's code table does not hold (true at such a number): its
    /// control alarms on them or runs a macro its parameters name, so they change no mode --
    /// `G91` on a FANUC lathe of G code system A is no incremental programming, `G06` on a
    /// FANUC mill no parabola. Empty where every number keeps the ISO 6983-1 reading below
    /// (the ISO profiles, whose checker reports the unassigned ones).
    pub lacks_g: Vec<bool>,
    /// A FANUC lathe's G code system: the block's G codes are read by their system A numbers
    /// ([`GCodeSystem::to_a`], [`BlockValues::in_system`]).
    pub g_system: GCodeSystem,
    /// A Haas lathe: its single cycles write their taper as I (G90, G92) and K (G94), and its
    /// one-block G76 as I (Haas lathe operator's manual, "G-codes"), where a FANUC's write R.
    pub haas: bool,
}

/// What a non-modal code does with its block's axis words, which are then no move of the
/// motion mode in force: a block `G91 G28 Z0` after a `G02` returns Z to the reference
/// position through its intermediate point, it runs no arc (FANUC 0i-MF/30i-B operator's
/// manuals: the codes of group 00 act in their block only, and "G28 IP_" gives the
/// intermediate point; rs274ngc: G10, G28, G30, G52 and G92 use the axis words themselves).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AxesTaken {
    /// The code's data (offsets, a call's arguments, a centre, a radius, a return level), or
    /// a cycle that returns to its start point: the position stays.
    Data,
    /// The coordinates set (G92, a lathe's G50): the position becomes the words' values.
    Set,
    /// A positioning of the code's own to the words' point (FANUC G27 reference position
    /// return check, G60 single direction positioning): the position follows the words as a
    /// move's would.
    Positions,
    /// A move of the code's own that ends where the program's coordinates do not say (the
    /// reference position, machine coordinates, a skip or a measurement, a pattern, a
    /// coordinate system shifted by the words): the named axes' positions are unknown.
    Unknown,
    /// A return to a home position the machine's parameters hold, which axes it moves too
    /// (an Okuma OSP lathe's G20 HP=n home position return, G21 tool change home position
    /// return, G24/G25 the same without interpolation): every axis's position is unknown.
    Home,
}

impl ModalSettings {
    /// The number whole G code `g` as written is read by: itself, or on a FANUC lathe of G
    /// code system B or C its system A number ([`GCodeSystem::to_a`]); a code the table lacks
    /// is [`crate::lex::NO_CODE`] there, as its number means another code in system A.
    #[inline]
    pub fn read_g(&self, g: i64) -> i64 {
        match self.g_system {
            GCodeSystem::A => g,
            _ if self.lacks(g) => crate::lex::NO_CODE,
            system => system.to_a(g),
        }
    }

    /// Whether G code `g` is one the control family's table does not hold ([`Self::lacks_g`]).
    pub fn lacks(&self, g: i64) -> bool {
        usize::try_from(g)
            .ok()
            .and_then(|n| self.lacks_g.get(n))
            .is_some_and(|&lacked| lacked)
    }

    /// The code whose S is the spindle speed clamp under G96: G50 on a Fanuc, Haas or Okuma
    /// lathe (OSP-P200L 5238-E: G50 S "maximum spindle speed"), G92 elsewhere (ISO 6983-1),
    /// none on a mill whose G92 only sets coordinates ([`Self::g92_clamps`]).
    pub fn clamp_code(&self) -> Option<i64> {
        if self.fanuc_lathe || self.lap {
            Some(50)
        } else if self.g92_clamps {
            Some(92)
        } else {
            None
        }
    }

    /// Whether the block's S is a limit of the spindle's speed, not its speed: the clamp
    /// code's ([`Self::clamp_code`]), or a SINUMERIK's G26 S (upper) or G25 S (lower limit;
    /// Programming Manual Fundamentals, "Programmable spindle speed limitation": review 38,
    /// finding 1, a restart after `G26 S3000` started the spindle at 3000). The upper one is
    /// the state's `speed_limit`.
    pub fn s_limit(&self, v: &BlockValues) -> (bool, bool) {
        self.s_limit_with(|g| v.has_g(g))
    }

    /// [`Self::s_limit`] of a block whose G codes `has_g` answers for: the converter's reader
    /// (`ncread`) asks it too, so that an S it leaves unconverted under G96 is the one the
    /// check and the restart take for a limit.
    pub fn s_limit_with(&self, has_g: impl Fn(i64) -> bool) -> (bool, bool) {
        let sinumerik = self.family == Family::Sinumerik;
        let upper = self.clamp_code().is_some_and(&has_g) || sinumerik && has_g(26);
        (upper, upper || sinumerik && has_g(25))
    }

    /// What the block's non-modal code, if it has one that takes the axis words on this
    /// control, does with them. Each family's codes are from its manuals' code lists (the
    /// profiles' `[codes]` name them): Fanuc and Haas G10, G27-G31, G52, G53, G65/G66, G92 on
    /// a mill and G50 on a lathe, the mills' G68/G51 centres, the measuring codes (G35-G37,
    /// G136), Haas's patterns and pockets (G12, G13, G47, G70-G72, G150) and mirror (G101, and its cancel G100),
    /// a lathe's multiple repetitive cycles G70-G76 (they end at their start point); rs274ngc
    /// G10, G28, G30, G52, G92 and the 2.9 lathe cycles G70-G72 (G53 is no such code there:
    /// it runs the G0 or G1 in force, "Must use G0 or G1 with G53"); SINUMERIK G25/G26
    /// (working area limits), G58/G59 (programmable offsets), G74/G75 (reference and fixed
    /// point approach), G110-G112 (pole), G63 and G147-G348 (their own moves to the point);
    /// Okuma G30 (zero point return), G31 (skip), the lathe's G20/G21/G24/G25 (home position returns: [`AxesTaken::Home`]), the
    /// mill's G71 (the cycles' return level), the lathe's G50 (zero offset, a shift), the
    /// lathe's LAP calls G84-G87 (5238-E section 8), compound thread cutting G71/G72 and
    /// grooving G73/G74 (section 7) and M-tool cycles G181-G189; ISO 6983-1 G92 ("preload
    /// registers (no motion)", also in the Okuma tables built on it).
    pub fn axes_taken(&self, v: &BlockValues) -> Option<AxesTaken> {
        use AxesTaken::{Data, Home, Positions, Set, Unknown};
        let lathe = self.fanuc_lathe || self.lap;
        // G51.1 X10. mirrors X about 10, G50.1 X0 ends X's mirror: the axis words name the
        // mirror's axes and point (FANUC 16/18, "Programmable mirror image"; SINUMERIK ISO
        // dialect: `G50.1 X... Y... Z...`), no move
        if v.mirror && self.family == Family::MacroB {
            return Some(Data);
        }
        v.gs().iter().find_map(|&g| match (self.family, g) {
            // (G10 L2/L20 may set the offsets of the coordinate system in force: where the
            // named axes stand in program coordinates is then not known)
            (Family::MacroB | Family::LinuxCnc, 10) => Some(Unknown),
            // G22 I J K: the stored stroke check's limits; Haas G101/G100 X: the axes whose
            // mirror image starts or ends (96-8000, G101), no move; on a control whose table
            // has no such code (a FANUC: an alarm, or a macro call by parameter) they are read
            // as any code it lacks (review 17)
            (Family::MacroB, 22 | 65 | 66 | 100 | 101 | 107) => {
                (!(100..=101).contains(&g) || !self.lacks(g)).then_some(Data)
            }
            (Family::MacroB, 51 | 68) if self.centre_codes => Some(Data),
            (Family::MacroB, 70..=76) if lathe => Some(Data),
            (Family::MacroB, 92) if !lathe => Some(Set),
            (Family::MacroB, 50) if lathe => Some(Set),
            (Family::MacroB, 27 | 60) => Some(Positions),
            (Family::MacroB, 28..=31 | 35..=37 | 52 | 53 | 136) => Some(Unknown),
            (Family::MacroB, 12 | 13 | 47 | 70..=72 | 150) if !lathe => Some(Unknown),
            (Family::LinuxCnc, 92) => Some(Set),
            (Family::LinuxCnc, 28 | 30 | 52 | 70..=72) => Some(Unknown),
            (Family::Sinumerik, 25 | 26 | 110..=112) => Some(Data),
            // G63 (tapping with a compensating chuck) and the soft approach and retraction
            // G147-G348 move on a path of their own to the block's point (Programming Manual
            // Fundamentals, "List of G functions": group 2, non-modal motions): no arc of the
            // G2/G3 in force
            (Family::Sinumerik, 63 | 147 | 148 | 247 | 248 | 347 | 348) => Some(Positions),
            (Family::Sinumerik, 58 | 59 | 74 | 75) => Some(Unknown),
            (Family::Okuma, 71) if !lathe => Some(Data),
            // an Okuma lathe's LAP calls G84-G87 (D, U, W: depth and allowances), compound
            // thread cutting G71/G72 and grooving G73/G74 end where they started; its M-tool
            // drilling and tapping cycles G181-G189 position to the hole first
            (Family::Okuma, 71..=74 | 84..=87) if self.lap => Some(Data),
            (Family::Okuma, 181..=189) if self.lap => Some(Unknown),
            (Family::Okuma, 30 | 31) => Some(Unknown),
            // an Okuma mill's G11 (parallel and rotation shift of the coordinate system) and
            // G62 (programmable mirror image), and G69 (three-dimensional coordinate system
            // conversion): the list at hand names them, no page says what their axis words
            // are; a move to them is not assumed, nor is the position kept
            (Family::Okuma, 11 | 62 | 69) if !lathe => Some(Unknown),
            // (unless the profile makes it its units code: a lathe profile of its own)
            (Family::Okuma, 20 | 21 | 24 | 25) if lathe && self.units_code(g).is_none() => {
                Some(Home)
            }
            (Family::Okuma, 50) if lathe => Some(Unknown),
            // (not where the profile's list lacks it, as the Okuma lathe's does: a code the
            // list lacks leaves the block's axes unknown, Checker::read_block; review 41, finding 6)
            (Family::Iso | Family::Okuma, 92) if !self.lacks(g) => Some(Set),
            _ => None,
        })
    }

    /// `letter` is the dwell's data in this block (a G04 block's time word on this control).
    pub fn dwell_word(&self, v: &BlockValues, letter: u8) -> bool {
        v.has_g(4) && self.dwell.contains(&letter)
    }

    /// A code of the control's motion group (group 01) other than G00-G03, G06 and G33-G35:
    /// it replaces the motion mode in force (a G02 before it runs no arc in its block nor in
    /// the blocks after it) until another code of the group. A Fanuc or Haas lathe's (G code
    /// system A) threading G32, G34 and single cycles G90, G92, G94 (FANUC 0i-TF operator's
    /// manual, "G code list", group 01; Haas lathe operator's manual, "G-codes": group 01 is
    /// G00, G01, G02, G03, G32, G90, G92, G94); an Okuma lathe's fixed thread cutting cycles
    /// G31 and G32 (OSP-P200L Programming Manual 5238-E, section 7, "Fixed thread cutting
    /// cycles": G31/G33 longitudinal, G32 end face). Their axis words are the cycle's or the
    /// thread's end point, their R, I, K a taper, never an arc's.
    pub fn own_motion(&self, g: i64) -> bool {
        (self.fanuc_lathe && matches!(g, 32 | 34 | 90 | 92 | 94))
            || (self.lap && matches!(g, 31 | 32))
    }

    /// A Fanuc or Haas control (Custom Macro B), mill or lathe.
    pub fn macro_b(&self) -> bool {
        self.centre_codes || self.fanuc_lathe
    }

    /// The units of lengths and of the feed a G code selects; None for no units code.
    pub fn units_code(&self, g: i64) -> Option<(Units, Units)> {
        let sinumerik = self.sinumerik_units;
        let units = match g {
            700 if sinumerik => return Some((Units::Inch, Units::Inch)),
            710 if sinumerik => return Some((Units::Metric, Units::Metric)),
            _ if g == self.inch => Units::Inch,
            _ if g == self.metric => Units::Metric,
            _ => return None,
        };
        Some((units, if sinumerik { self.default_units } else { units }))
    }
}

/// A block's motion, cycle and feed before its M02/M30 reset them ([`ModalMachine::ended_from`]).
#[derive(Clone, Copy, Debug)]
pub struct EndedFrom {
    pub motion: Option<i64>,
    pub cycle: Option<i64>,
    pub feed: Option<Dec>,
    pub feed_unknown: bool,
}

#[derive(Clone)]
pub struct ModalMachine {
    pub settings: ModalSettings,
    pub state: ModalState,
    /// A Fanuc or Haas lathe (system A) in G00-G03 or threading G32/G34, whose U W move X Z
    /// by an increment (FANUC 0i-TF operator's manual, "Thread cutting G32": the tool cuts to
    /// the end point and stays there); false in a cycle (G70-G76, G80-G90, G92, G94), whose
    /// U W are the cycle's and whose tool returns to its start point.
    uw_moves: bool,
    /// The end point X, Z (absolute) of a Fanuc or Haas lathe's single cycle G90, G92 or
    /// G94 (G code system A; and of the block's G74-G76, an Okuma's G32/G33), kept for the
    /// cycle's modal repeats: "data items X (U), Z (W)
    /// and R are modal" in the cycles until a code of group 01 other than G90, G92, G94 or a
    /// one-shot code other than G04 (FANUC 0i-TF operator's manual, "Canned cycle").
    cycle_end: [Option<Dec>; 2],
    /// `cycle_end` is the cycle's data in force (false: cleared, none kept; a flag, so that
    /// the G00-G03 of every lathe block clear it by one store).
    cycle_kept: bool,
    /// The taper of the single cycle in force (FANUC R, Haas I or K, Okuma I: the radius
    /// difference, G94's in Z), modal with `cycle_end` ("data items X (U), Z (W) and R are
    /// modal"); None for no taper or one not known (`taper_unknown`).
    cycle_taper: Option<Dec>,
    /// The taper in force was written with a value not known here (a parameter), or as an
    /// angle (an Okuma's A).
    taper_unknown: bool,
    /// The corner the taper of the block's cycle makes, where the tool goes before it cuts
    /// to the end point: X (the end point's X plus twice the radius difference, at the start
    /// point's Z: G90, G92, G76, Okuma G33) or Z (G94: the end point's Z plus R, at the start
    /// point's X); the other None, as both are where the cycle has no taper.
    cycle_corner: [Option<Dec>; 2],
    /// What the block last given to [`ModalMachine::apply`] did of a lathe's cycles
    /// ([`CYCLE_RAN`], [`CYCLE_UNSURE`]; 0 for none: one store a block clears it): the tool
    /// went to `cycle_end` (and `cycle_corner`) and back to its start point, where the
    /// position stays; or some of where it went is not known (`cycle_why` says why).
    ran_cycle: u8,
    /// The block's motion, cycle, feed and whether its F is not known, where its M02/M30
    /// reset the state once its words were done (`m_codes`): the rules of the block's own
    /// move read them, not the reset state's (a `G0 X1 M2` after a `G1` is a rapid, on a
    /// profile whose reset motion is G01 too).
    pub ended_from: Option<Box<EndedFrom>>,
    /// Why the positions of the block's cycle are not all known ([`CYCLE_UNSURE`]).
    cycle_why: &'static str,
    /// The feed, forgotten at a jump the checker does not follow, is none on every way here
    /// all the same: each jump forgotten since the last F was a `GOTO n` (one of an IF, or
    /// the sure one) read where no feed was ever set, and nothing else forgot it since
    /// (check/passed.rs: the target of a sure GOTO that earlier IFs name too; review 57c, F5).
    pub feed_none_kept: bool,
    /// A units code converts the known positions into the new units (true): the checker's and
    /// the restart walk's machine. The verify reader and the converter keep the numbers as
    /// they were and follow each axis's units themselves, exactly (`ncread::Factor`).
    pub units_convert_position: bool,
    /// What the block last given to [`ModalMachine::apply`] does with its axis words
    /// ([`ModalSettings::axes_taken`]), found once there for the machine and the checker's
    /// rules that ask it of the same block ([`ModalMachine::taken`]).
    taken: Option<AxesTaken>,
    /// How many codes of absolute or incremental programming (G90/G91, G code system B's and
    /// C's) were applied so far, the reset's included: the checker asks whether a program
    /// wrote one of its own before its first move (crate::check::called).
    pub distance_codes: u32,
    /// How many units codes (G20/G21, G70/G71) were applied so far: the checker asks whether
    /// a body read under its calls' units wrote one of its own (crate::check::callmode).
    pub units_codes: u32,
    /// Each axis's increments applied while its position is not known ([`Drift`]), by its
    /// place in [`AXES`]: started again wherever the axis is lost anew.
    pub drift: [Drift; 9],
    /// A lathe's thread G32 or G92 in force when a canned cycle the state does not model (a
    /// Haas lathe's G241-G249 live tool cycles) was given, and that cycle's code, which
    /// stands in the motion group in the thread's place until G80 puts the thread back
    /// ([`ModalMachine::cycle_over_thread`]): the cycle's repeats are no thread's passes.
    /// Both codes as bytes, `[0, 0]` for none (two bytes: the struct's padding holds them;
    /// a wider field moved the layout and cost the mills' blocks 7 instructions each).
    thread_under_cycle: [u8; 2],
}

/// The increments (G91, a lathe's U and W) an axis moved by while its position stays not
/// known, in millimetres: their running sum and the least and most of its partial sums (0,
/// where the run began, included). The checker compares `most - least` with the axis's whole
/// travel (crate::check's TG601): a run wider than it is out of travel wherever it started.
#[derive(Clone, Copy, Debug, Default)]
pub struct Drift {
    pub sum: f64,
    pub least: f64,
    pub most: f64,
    /// How many increments the run has.
    pub moves: u32,
    /// The run grew since the checker last looked, and it has been said (TG601, once a run).
    pub grew: bool,
    pub said: bool,
}

impl Drift {
    /// Add an increment `by` (millimetres) to the run.
    #[cold]
    #[inline(never)]
    fn add(&mut self, by: f64) {
        self.sum += by;
        self.least = self.least.min(self.sum);
        self.most = self.most.max(self.sum);
        self.moves += 1;
        self.grew = true;
    }
}

impl ModalMachine {
    pub fn new(settings: ModalSettings) -> ModalMachine {
        let state = ModalState::new(settings.default_units);
        let mut machine = ModalMachine {
            settings,
            state,
            uw_moves: true,
            cycle_end: [None; 2],
            cycle_kept: false,
            cycle_taper: None,
            taper_unknown: false,
            cycle_corner: [None; 2],
            ran_cycle: 0,
            ended_from: None,
            cycle_why: "",
            feed_none_kept: false,
            units_convert_position: true,
            taken: None,
            distance_codes: 0,
            units_codes: 0,
            drift: [Drift::default(); 9],
            thread_under_cycle: [0; 2],
        };
        machine.reset();
        machine
    }

    /// The reset state of clause 14 for the control type (the position is kept).
    pub fn reset(&mut self) {
        let position = self.state.position;
        let unknown = self.state.unknown & FORGOTTEN & !(bit(b'F') | bit(b'S'));
        let units_given = self.state.units_given;
        self.state = ModalState::new(self.settings.default_units);
        self.state.position = position;
        self.state.unknown = unknown;
        let reset = self.settings.reset.clone();
        for g in reset {
            self.g(g);
        }
        // (the reset's own units code is the machine's setting, not the program's; one the
        // file wrote before stays said: what follows an M30 in the program -- a Haas's M97
        // subprogram -- runs under its caller's units. The checker sets it again for the next
        // program of the file, by its calls: Checker::called_units)
        self.state.units_given = units_given;
    }

    /// Apply a whole block: its codes, its values, its position, then its end (M02/M30).
    pub fn apply(&mut self, v: &BlockValues) {
        let taken = self.settings.axes_taken(v);
        self.apply_taken(v, taken);
    }

    /// [`ModalMachine::apply`], where the caller has what [`ModalSettings::axes_taken`] says
    /// of the block's codes (the checker keeps it by the block's set of codes).
    pub fn apply_taken(&mut self, v: &BlockValues, taken: Option<AxesTaken>) {
        self.taken = taken;
        self.ran_cycle = 0;
        if self.ended_from.is_some() {
            self.ended_from = None;
        }
        self.codes(v.gs());
        if v.other_work_system {
            self.state.zero_shift = None;
        }
        if self.taken == Some(AxesTaken::Unknown) && v.has_g(10) && !self.g10_shifts_in_force(v) {
            self.taken = Some(AxesTaken::Data);
        }
        let s = &mut self.state;
        // a dwell's F (ISO, SINUMERIK) or S (SINUMERIK's revolutions) is its time: the feed
        // and speed in force stay
        let dwell = |letter: u8| self.settings.dwell_word(v, letter);
        let unknown = |letter: u8| v.unknown & bit(letter) != 0;
        if self.settings.family == Family::LinuxCnc && v.gs.iter().any(|g| matches!(g, 93..=95)) {
            // rs274ngc's convert_feed_mode sets the feed rate to zero at every G93, G94 and
            // G95, even one that restates the mode in force, before the block's F is read
            s.feed = None;
            s.unknown &= !bit(b'F');
        }
        // each of F S T D below changes the state only where the block gives the letter a
        // value, known or not: most blocks give none of the four
        let fstd = bit(b'F') | bit(b'S') | bit(b'T') | bit(b'D');
        if (v.given | v.unknown) & fstd != 0 {
            if let Some(f) = v.get(b'F') {
                if !dwell(b'F') {
                    s.feed = Some(f);
                    s.unknown &= !bit(b'F');
                }
            } else if unknown(b'F') && !dwell(b'F') {
                s.feed = None;
                s.unknown |= bit(b'F');
                self.feed_none_kept = false;
            }
            let (upper, limit) = self.settings.s_limit(v);
            if let Some(speed) = v.get(b'S').filter(|_| !dwell(b'S')) {
                if upper {
                    s.speed_limit = Some(speed);
                } else if !limit {
                    s.speed = Some(speed);
                    s.unknown &= !bit(b'S');
                }
            } else if unknown(b'S') && !limit && !dwell(b'S') {
                s.speed = None;
                s.unknown |= bit(b'S');
            }
            if let Some(t) = v.get(b'T') {
                s.tool = Some(t.trunc());
                s.unknown &= !bit(b'T');
            } else if unknown(b'T') {
                s.tool = None;
                s.unknown |= bit(b'T');
            }
            // in a lathe's G70-G76 (Haas) D is a depth of cut, not an offset; likewise in an
            // Okuma lathe's thread, LAP and M-tool cycles (`meaning::block`: a depth of cut)
            let cycle_d = (self.settings.fanuc_lathe && (70..=76).any(|g| v.has_g(g)))
                || (self.settings.lap && v.gs.iter().any(|&g| matches!(g, 71..=89 | 178..=189)));
            if let Some(d) = v.get(b'D').filter(|_| !cycle_d) {
                s.offset = Some(d.trunc());
                s.unknown &= !bit(b'D');
            } else if unknown(b'D') && !cycle_d {
                s.offset = None;
                s.unknown |= bit(b'D');
            }
        }
        self.moved(v);
        self.m_codes(&v.ms, !v.end_unsure);
    }

    /// Whether a G10 block may move the zero of the work coordinate system in force, so that
    /// the named axes' positions in program coordinates are no longer known. Only G10 L2 and
    /// L20 set a work system's origin: FANUC 0i-MF ("Changing workpiece coordinate system (G10
    /// L2, L20)": L2 P0 the external offset, which shifts every system, P1-P6 G54-G59; L20 P
    /// G54.1 P), Haas (L2 P0 the G52 shift, P1-P6 G54-G59; L20 P G154 P), LinuxCNC (G-code
    /// reference, G10 L2 and L20: P0 the system in force, P1-P9 G54-G59.3; rs274ngc executes
    /// G54-G59.3 before G10 in a block). A G10 for another system than the one in force changes
    /// no position of this program; one whose system is the one in force, or not known (P
    /// omitted or by a parameter, a G54.1/G59.1/G154 system in force, none selected), does. Other
    /// G10 forms (tool data) are left as the axes taken say.
    fn g10_shifts_in_force(&self, v: &BlockValues) -> bool {
        let whole = |letter: u8| v.get(letter).filter(|d| d.is_whole()).map(Dec::trunc);
        let Some(l @ (2 | 20)) = whole(b'L') else {
            return true;
        };
        let Some(p) = whole(b'P') else {
            return true;
        };
        let linuxcnc = self.settings.family == Family::LinuxCnc;
        // the system in force, 1-6 for G54-G59; None where it is not one of them
        let in_force = self.state.zero_shift.map(|g| g - 53);
        match (linuxcnc, l, p) {
            (_, _, 0) => true,
            // LinuxCNC's P1-P9 (G54-G59.3) under both forms, FANUC's and Haas's L2 P1-P6
            (true, _, 1..=9) | (false, 2, 1..=6) => in_force.is_none_or(|n| n == p),
            // FANUC's G54.1 P, Haas's G154 P: in force only where G54-G59 is not
            (false, 20, _) => in_force.is_none(),
            _ => true,
        }
    }

    /// What the block last given to [`ModalMachine::apply`] does with its axis words: the
    /// same as [`ModalSettings::axes_taken`] of its values, without a second search of its G
    /// codes (the checker asks it of every block two or three times).
    pub fn taken(&self) -> Option<AxesTaken> {
        self.taken
    }

    /// Whether the block last given to [`ModalMachine::apply`] moved X and Z by its U and W:
    /// a FANUC or Haas lathe of G code system A in G00-G03 or threading G32/G34, or an Okuma
    /// lathe in G00-G03, outside their cycles (U W the incremental commands of X Z, U a
    /// diameter as X is). In G code system B
    /// or C, where no page at hand says U and W still move X and Z, where X and Z stand after
    /// one is not followed (false).
    pub fn uw_moved_xz(&self) -> bool {
        (self.settings.fanuc_lathe || self.settings.lap)
            && self.uw_moves
            && self.state.cycle.is_none()
            && self.settings.g_system == GCodeSystem::A
    }

    /// Where the single cycle G90, G92 or G94 of the block last given to
    /// [`ModalMachine::apply`] went, X and Z (None where not known), the position having
    /// stayed at its start point: None where the block ran no such cycle
    /// ([`ModalMachine::ran_cycle`]) (a Fanuc or Haas lathe, B's and C's G77-G79 read as
    /// A's numbers; FANUC 0i-TF operator's manual, "Outer diameter/internal diameter cutting
    /// cycle G90", "Thread cutting cycle G92", "End face turning cycle G94":
    /// from the start point to the end point X(U) Z(W), U and W the increments from the start
    /// point, and back to the start point).
    pub fn cycle_end(&self) -> Option<[Option<Dec>; 2]> {
        (self.ran_cycle & CYCLE_RAN != 0).then_some(self.cycle_end)
    }

    /// The corner of the taper of the cycle the block last given to [`ModalMachine::apply`]
    /// ran (`cycle_corner`), where it has one.
    pub fn cycle_corner(&self) -> Option<[Option<Dec>; 2]> {
        (self.ran_cycle & CYCLE_RAN != 0 && self.cycle_corner != [None; 2])
            .then_some(self.cycle_corner)
    }

    /// What the block last given to [`ModalMachine::apply`] did of a lathe's cycles: 0 for
    /// none, else [`CYCLE_RAN`] (a single cycle G90, G92, G94, a multiple repetitive cycle
    /// G74-G76, an Okuma's fixed thread cutting cycle: [`ModalMachine::cycle_end`]) and
    /// [`CYCLE_UNSURE`] (some of its positions not known: [`ModalMachine::cycle_why`]).
    #[inline]
    pub fn ran_cycle(&self) -> u8 {
        self.ran_cycle
    }

    /// Why the positions of the block's cycle are not all known ([`CYCLE_UNSURE`]).
    pub fn cycle_why(&self) -> &'static str {
        self.cycle_why
    }

    /// Swap the positions of X and Z with the corner of the taper of the cycle the last
    /// block ran ([`ModalMachine::cycle_corner`]): the checker walks the spans from there,
    /// and swaps them back.
    #[cold]
    #[inline(never)]
    pub fn swap_cycle_corner(&mut self) {
        let position = &mut self.state.position;
        std::mem::swap(&mut position[0], &mut self.cycle_corner[0]);
        std::mem::swap(&mut position[2], &mut self.cycle_corner[1]);
    }

    /// Say that the block's cycle went where the check cannot work out, and why.
    #[cold]
    fn unsure(&mut self, why: &'static str) {
        self.ran_cycle |= CYCLE_UNSURE;
        self.cycle_why = why;
    }

    /// Swap the positions of X and Z with the end point of the single cycle the last block
    /// ran: the checker walks the spans from there, and swaps them back.
    #[cold]
    #[inline(never)]
    pub fn swap_cycle_end(&mut self) {
        let position = &mut self.state.position;
        std::mem::swap(&mut position[0], &mut self.cycle_end[0]);
        std::mem::swap(&mut position[2], &mut self.cycle_end[1]);
    }

    /// After a jump or a call the checker cannot follow: the position, feed and speed are
    /// unknown until the program sets them again.
    /// A lathe's canned cycle the state does not model, G code `g` (a Haas lathe's radial
    /// live tool cycles G241-G249: Lathe Operator's Manual, group 09, cancelled by G80), given
    /// with a thread G32 or G92 in force (group 01): a block of words alone after it repeats
    /// the cycle, not a pass of the thread, whose Q (its start angle) it does not read (review
    /// 59c, F1). The cycle's code stands in the motion group in the thread's place, and G80
    /// puts the thread back; any other motion code replaces it as it replaces the thread.
    /// Asked only where such a cycle is read (rare); nothing where the motion is no thread.
    #[cold]
    pub fn cycle_over_thread(&mut self, g: i64) {
        let [t, c] = self.thread_under_cycle;
        let thread = match self.state.motion {
            Some(m) if modal_thread(m) => m,
            // (a second such cycle over the same thread)
            Some(m) if t != 0 && m == i64::from(c) => i64::from(t),
            _ => return,
        };
        // (a code past 255 is no Haas lathe's cycle: left as the thread's repeats)
        let (Ok(thread), Ok(cycle)) = (u8::try_from(thread), u8::try_from(g)) else {
            return;
        };
        self.thread_under_cycle = [thread, cycle];
        self.state.motion = Some(g);
    }

    pub fn forget(&mut self) {
        self.cycle_kept = false;
        self.feed_none_kept = false;
        let s = &mut self.state;
        s.position = [None; 9];
        s.feed = None;
        s.speed = None;
        s.unknown |= FORGOTTEN;
        self.drift = [Drift::default(); 9];
    }

    /// The position alone is no longer known (a SINUMERIK's `REPOSA` returns to where an
    /// interrupted program left the path): the feed and the speed stay.
    pub fn forget_position(&mut self) {
        self.state.position = [None; 9];
        self.state.unknown |= FORGOTTEN & !(bit(b'F') | bit(b'S'));
        self.drift = [Drift::default(); 9];
    }

    /// What [`ModalMachine::forget`] forgot, as `left` holds it, the modes staying (a jump
    /// surely taken: its target starts where the jump's block left the axes, the feed and
    /// the speed -- none ever set stays none -- check/passed.rs).
    pub fn kept_of(&mut self, left: &ModalMachine) {
        self.state.position = left.state.position;
        self.state.feed = left.state.feed;
        self.state.speed = left.state.speed;
        self.state.unknown = self.state.unknown & !FORGOTTEN | left.state.unknown & FORGOTTEN;
        self.feed_none_kept = left.feed_none_kept;
        self.drift = left.drift;
    }

    /// No feed was ever set on any way here: none in force and none forgotten, or forgotten
    /// only at jumps that kept none (`feed_none_kept`).
    pub fn feed_never_set(&self) -> bool {
        self.state.feed.is_none() && (self.state.unknown & bit(b'F') == 0 || self.feed_none_kept)
    }

    /// The position of the axis `letter` alone is no longer known (a SINUMERIK's positioning
    /// axis, `POSA[X]=100`, moves on its own): the other axes, the feed and the speed stay.
    pub fn forget_axis(&mut self, letter: u8) {
        if let Some(i) = axis_index(letter) {
            self.state.position[i] = None;
            self.state.unknown |= bit(letter);
            self.drift[i] = Drift::default();
        }
    }

    /// The feed alone is no longer known (a block the control refuses wrote an F): the
    /// position and the speed stay.
    pub fn forget_feed(&mut self) {
        self.feed_none_kept = false;
        self.state.feed = None;
        self.state.unknown |= bit(b'F');
    }

    /// No feed in force, as at the reset (a jump surely taken from where none was ever set
    /// arrives at its target with none: check/passed.rs).
    pub fn no_feed(&mut self) {
        self.state.feed = None;
        self.state.unknown &= !bit(b'F');
    }

    /// The speed alone is no longer known (a SINUMERIK's `SETMS(2)` makes another spindle the
    /// one S addresses): the position and the feed stay.
    pub fn forget_speed(&mut self) {
        self.state.speed = None;
        self.state.unknown |= bit(b'S');
    }

    /// The modes a block's G codes set: the state its own words are read in.
    pub fn codes(&mut self, gs: &[i64]) {
        for &g in gs {
            self.g(g);
        }
    }

    /// What a block's M codes do once its words are done: spindle, coolant, and after M02 or
    /// M30 the reset state of clause 14 (the next program of the file starts from it).
    pub fn end_of_block(&mut self, ms: &[i64]) {
        self.m_codes(ms, true);
    }

    /// [`ModalMachine::end_of_block`], where `ends` says whether an M02/M30 among `ms` ends
    /// the program (resets the state).
    fn m_codes(&mut self, ms: &[i64], ends: bool) {
        let s = &mut self.state;
        for &m in ms {
            match m {
                3..=5 => s.spindle = m,
                7 | 8 => s.coolant = m,
                9 => s.coolant = 9,
                _ => {}
            }
        }
        if ends && ms.iter().any(|&m| m == 2 || m == 30) {
            let s = &self.state;
            self.ended_from = Some(Box::new(EndedFrom {
                motion: s.motion,
                cycle: s.cycle,
                feed: s.feed,
                feed_unknown: s.is_unknown(b'F'),
            }));
            let units = (self.state.units, self.state.feed_units);
            self.reset();
            if self.settings.units_kept_at_end {
                (self.state.units, self.state.feed_units) = units;
            }
            self.state.ended = true;
        }
    }

    /// The mode G code `g` sets. G00-G03, the motion codes of nearly every block that has a
    /// G word, inlined where they are asked: the same as [`ModalMachine::g_other`] does with
    /// them (a lathe's U W move again, no HEIDENHAIN or Okuma code among them, no code of the
    /// lathes' own motions, [`ModalSettings::own_motion`]), without the call and its tests of
    /// the family.
    #[inline]
    fn g(&mut self, g: i64) {
        if !matches!(g, 0..=3) {
            return self.g_other(g);
        }
        if self.settings.g_system == GCodeSystem::A && self.settings.lacks(g) {
            return;
        }
        if self.settings.fanuc_lathe || self.settings.lap {
            self.uw_moves = true;
            self.cycle_kept = false;
        }
        debug_assert!(!self.settings.own_motion(g));
        self.state.motion = Some(g);
        self.state.cycle = None;
    }

    /// [`ModalMachine::g`] of any code but G00-G03 (which it also takes, as it did before
    /// their inlined reading).
    #[inline(never)]
    fn g_other(&mut self, g: i64) {
        // (in G code system B or C the codes come read by system A's numbers, the lacked ones
        // as NO_CODE: `BlockValues::in_system`)
        if self.settings.g_system == GCodeSystem::A && self.settings.lacks(g) {
            return;
        }
        if self.settings.fanuc_lathe {
            // (threading G32/G34 cuts to its end point like G01: FANUC 0i-TF, "Thread cutting
            // G32"; the single cycles' end point data is kept until a code of group 01 other
            // than theirs or a one-shot code other than G04, "Canned cycle")
            match g {
                0..=3 | 32 | 34 => {
                    self.uw_moves = true;
                    self.cycle_kept = false;
                }
                90 | 92 | 94 => self.uw_moves = false,
                33 | 70..=76 | 80..=89 => {
                    self.uw_moves = false;
                    self.cycle_kept = false;
                }
                9..=11 | 27..=31 | 36 | 37 | 50 | 52 | 53 | 65 => self.cycle_kept = false,
                _ => {}
            }
        } else if self.settings.lap {
            // an Okuma lathe's U W too, but in its thread, LAP and M-tool cycles (5238-E)
            match g {
                0..=3 => {
                    self.uw_moves = true;
                    self.cycle_kept = false;
                }
                80 => self.uw_moves = true,
                // (the fixed thread cutting cycles' data kept for their repeats, as a
                // FANUC's single cycles' is: `X25.04` runs G33 again at the new diameter)
                32 | 33 => self.uw_moves = false,
                31 | 34 | 35 | 71..=89 | 178..=189 => {
                    self.uw_moves = false;
                    self.cycle_kept = false;
                }
                _ => {}
            }
        }
        let s = &mut self.state;
        if self.settings.heidenhain {
            match g {
                10..=13 | 15 | 16 => {
                    s.motion = Some(g);
                    return;
                }
                28..=31 | 54 | 72 | 73 | 80..=89 => return,
                _ => {}
            }
        }
        if self.settings.lap && (80..=89).contains(&g) {
            return;
        }
        if self.settings.own_motion(g) {
            s.motion = Some(g);
            s.cycle = None;
            return;
        }
        match g {
            0..=3 | 6 | 33..=35 => {
                s.motion = Some(g);
                s.cycle = None;
            }
            17..=19 => s.plane = g,
            40..=42 => s.compensation = g,
            43 | 44 | 49 => s.length_offset = g,
            53 => s.zero_shift = None,
            54..=59 => s.zero_shift = Some(g),
            // Haas's additional work systems (G154 P1-P99, G110-G129: mill operator's manual,
            // "G154 Select Work Coordinates P1-P99"); G110-G129 only where the profile's list
            // holds G110 (a Haas mill): a FANUC mill's and a lathe's G112/G113 are polar
            // coordinate interpolation, no work system (review 34: a Haas lathe's preamble
            // lost its G54 after them)
            154 if self.settings.family == Family::MacroB => s.zero_shift = None,
            110..=129
                if self.settings.family == Family::MacroB
                    && !self.settings.fanuc_lathe
                    && !self.settings.lacks_g.is_empty()
                    && !self.settings.lacks(110) =>
            {
                s.zero_shift = None
            }
            80 => {
                s.cycle = None;
                s.cycle_words = [None; 5];
                // (the thread a lathe's unmodelled cycle stood in for, where nothing else
                // replaced it since: cycle_over_thread)
                let [thread, cycle] = std::mem::take(&mut self.thread_under_cycle);
                if thread != 0 && s.motion == Some(i64::from(cycle)) {
                    s.motion = Some(i64::from(thread));
                }
                if self.settings.g80_clears_motion {
                    s.motion = None;
                }
            }
            81..=89 => {
                s.cycle = Some(g);
                s.cycle_words = [None; 5];
            }
            // a FANUC or Haas mill's G73 (high-speed peck), G74 (left-hand or reverse tapping)
            // and G76 (fine boring) are canned cycles as G81-G89 are, their format ending
            // `F_ K_` (FANUC 0i-MF, "Canned cycle": K the number of repeats; Haas mill: L);
            // a lathe's are its turning and threading cycles (review 53, F8)
            73 | 74 | 76
                if self.settings.family == Family::MacroB && !self.settings.fanuc_lathe =>
            {
                s.cycle = Some(g);
                s.cycle_words = [None; 5];
            }
            90 | 91 => {
                s.incremental = g == 91;
                self.distance_codes = self.distance_codes.wrapping_add(1);
            }
            // G code system B and C: G90/G91 (FANUC 0i-TF, "Absolute and incremental
            // programming"); their G98/G99 return levels change nothing the state follows
            ABSOLUTE | INCREMENTAL => {
                s.incremental = g == INCREMENTAL;
                self.distance_codes = self.distance_codes.wrapping_add(1);
            }
            93..=95 => s.feed_mode = g,
            98 if self.settings.fanuc_lathe => s.feed_mode = 94,
            99 if self.settings.fanuc_lathe => s.feed_mode = 95,
            96 | 97 => s.spindle_mode = g,
            // G16/G15: polar coordinates on a FANUC or Haas mill, the controls whose centre
            // codes are read (`centre_codes`), as `meaning::polar_code` has it
            15 | 16 if self.settings.centre_codes => s.polar = g == 16,
            _ => {
                if let Some((units, feed_units)) = self.settings.units_code(g) {
                    if units != s.units && self.units_convert_position {
                        // The machine does not move when the units change, only the numbers
                        // that say where it is: a G91 increment after G20/G21 adds to the
                        // position in the new units (X100. mm then G20 G91 X1. is 125.4 mm).
                        for (i, &axis) in AXES.iter().enumerate() {
                            if !matches!(axis, b'A' | b'B' | b'C') {
                                s.position[i] = s.position[i].and_then(|p| in_units(p, units));
                            }
                        }
                    }
                    s.units = units;
                    s.feed_units = feed_units;
                    s.units_given = true;
                    self.units_codes = self.units_codes.wrapping_add(1);
                }
            }
        }
    }

    fn moved(&mut self, v: &BlockValues) {
        let s = &mut self.state;
        if self.settings.heidenhain {
            if v.has_g(30) || v.has_g(31) {
                return; // the blank form's corners: data
            }
            let transform = [28, 54, 72, 73, 80].iter().any(|&g| v.has_g(g));
            let polar = s.motion.is_some_and(|m| (10..=16).contains(&m));
            if transform || polar {
                // a new coordinate system, or a move by angle and radius about the pole: where
                // the axes are is not followed
                for (i, &axis) in AXES.iter().enumerate() {
                    if transform || s.position[i].is_some() || v.get(axis).is_some() {
                        s.position[i] = None;
                        s.unknown |= bit(axis);
                        self.drift[i] = Drift::default();
                    }
                }
                return;
            }
        }
        let taken = self.taken;
        // G10 sets offsets (and elsewhere G52 a local coordinate system): data, not a move;
        // a Custom Macro B call's words are its arguments (G65 P9724 C1. E1.)
        if taken == Some(AxesTaken::Data) || (taken.is_none() && (v.has_g(10) || v.has_g(52))) {
            // (a lathe's multiple repetitive cycle: the block that writes its end point)
            if (self.settings.fanuc_lathe || self.settings.lap)
                && taken == Some(AxesTaken::Data)
                && (v.given | v.unknown) & XZUW != 0
            {
                self.repetitive_cycle(v);
            }
            return;
        }
        if taken == Some(AxesTaken::Home) {
            // to a home position of the parameters, the axes the parameters say: none of the
            // positions is known in the program's coordinates after it
            s.position = [None; 9];
            s.unknown |= FORGOTTEN & !(bit(b'F') | bit(b'S'));
            self.drift = [Drift::default(); 9];
            return;
        }
        // (an Okuma mill's G53 cancels the tool length offset, OSP List of G Codes: a move)
        let machine = v.has_g(53) && (self.settings.family != Family::Okuma || self.settings.lap);
        if taken == Some(AxesTaken::Unknown) || v.has_g(28) || v.has_g(30) || machine {
            // to the reference point through the words' point, in machine coordinates, to
            // where a skip or a measurement stopped: where that is in the program's
            // coordinates depends on offsets and signals not in the program
            for (i, &axis) in AXES.iter().enumerate() {
                if v.get(axis).is_some() || v.unknown & bit(axis) != 0 {
                    s.position[i] = None;
                    s.unknown |= bit(axis);
                    self.drift[i] = Drift::default();
                }
            }
            // a lathe's U and W there are X's and Z's incremental commands (`G28 U0 W0`: X
            // and Z to the reference point): X and Z are not known after it either
            if self.settings.fanuc_lathe || self.settings.lap {
                self.forget_uw_axes(v);
            }
            return;
        }
        if s.cycle.is_some() {
            for (i, &letter) in CYCLE_WORDS.iter().enumerate() {
                if let Some(value) = v
                    .get(letter)
                    .filter(|_| !self.settings.dwell_word(v, letter))
                {
                    s.cycle_words[i] = Some(value);
                }
            }
            // a mill's canned cycle under incremental programming with a repeat count steps
            // the hole position by the plane's increments that many times
            if s.incremental
                && !self.settings.fanuc_lathe
                && taken != Some(AxesTaken::Set)
                && !v.has_g(92)
            {
                self.cycle_repeated(v);
            }
        }
        // a Fanuc or Haas lathe's single cycle G90, G92, G94 (B's and C's G77-G79, read as A's
        // numbers): to the end point and back, the position stays; a block of its mode without
        // X U Z W runs none, nor does a dwell's (its U or X is the time)
        let mut touched = v.given | v.unknown;
        if (self.settings.fanuc_lathe || self.settings.lap) && self.single_cycle(v, touched) {
            touched &= !XZUW;
        }
        let s = &mut self.state;
        let absolute = taken == Some(AxesTaken::Set) || v.has_g(92) || !s.incremental;
        // under G16 the plane's words are a radius and an angle: where the axes end is not
        // followed (the pole, the radius or the angle in force may be another block's)
        let mut polar = 0;
        if s.polar {
            let (r, a) = polar_axes(s.plane);
            let given = |l: u8| v.get(l).is_some() || v.unknown & bit(l) != 0;
            if given(r) || given(a) {
                polar = bit(r) | bit(a);
            }
        }
        // an axis the block gives no value (known or not) and that is not of the polar pair
        // is left as it is by every branch below: only the others are looked at (most blocks
        // write two or three of the nine)
        let touched = touched | polar;
        for i in places(axis_places(touched)) {
            let axis = AXES[i];
            if polar & bit(axis) != 0 {
                s.position[i] = None;
                s.unknown |= bit(axis);
                self.drift[i] = Drift::default();
                continue;
            }
            if self.settings.dwell_word(v, axis) {
                continue; // a dwell's X (or a Fanuc lathe's U) is its time (clause 13)
            }
            // a Fanuc, Haas or Okuma lathe's U W move X Z by an increment (outside its
            // cycles): asked at a U or W word alone (a mill's every block paid for the test)
            if matches!(axis, b'U' | b'W')
                && (self.settings.fanuc_lathe || self.settings.lap)
                && self.uw_moves
                && s.cycle.is_none()
            {
                let on = if axis == b'U' { b'X' } else { b'Z' };
                let Some(j) = axis_index(on) else { continue };
                if self.settings.g_system != GCodeSystem::A {
                    // G code system B or C programs increments by G91 X Z; the manuals at hand
                    // do not say U and W still move X and Z there (docs/dialects.md): where X
                    // and Z stand after one is not followed
                    s.position[j] = None;
                    s.unknown |= bit(on);
                    self.drift[j] = Drift::default();
                    continue;
                }
                // X and U, Z and W, in one block: no page at hand says which the control
                // takes, or whether it alarms (docs/dialects.md), so X and Z are not known
                // after it (crate::check's `uw_beside_xz` says so; review 44, F7)
                if touched & bit(on) != 0 {
                    lose_axis(s, &mut self.drift[j], j, on);
                    continue;
                }
                // a U whose value is not known (`U#1`) leaves X not known, as a mill's `G91
                // X#1` does (review 48, F12: X kept its old position, and a later absolute X
                // made a span from a place the tool never was)
                let Some(value) = v.get(axis) else {
                    lose_axis(s, &mut self.drift[j], j, on);
                    continue;
                };
                // (a U from where X is not known: not known)
                if s.unknown & bit(on) == 0 {
                    s.position[j] = s.position[j]
                        .unwrap_or(Dec::ZERO)
                        .checked_add(value)
                        .or(s.position[j]);
                } else {
                    // its length is known all the same (the checker's TG601 of a run wider
                    // than the travel)
                    self.drift[j].add(to_mm(value, s.units));
                }
                continue;
            }
            let Some(value) = v.get(axis) else {
                if v.unknown & bit(axis) != 0 {
                    s.position[i] = None;
                    s.unknown |= bit(axis);
                    self.drift[i] = Drift::default();
                }
                continue;
            };
            if !absolute && s.unknown & bit(axis) != 0 {
                // an increment from an unknown position is unknown; its length is known (a
                // linear axis's, outside a canned cycle, whose words are its data too)
                if s.cycle.is_none() && taken.is_none() && !matches!(axis, b'A' | b'B' | b'C') {
                    self.drift[i].add(to_mm(value, s.units));
                } else {
                    self.drift[i] = Drift::default();
                }
                continue;
            }
            s.unknown &= !bit(axis);
            s.position[i] = if absolute {
                Some(value)
            } else {
                // An incremental sum too large for the core's numbers keeps the last position.
                s.position[i]
                    .unwrap_or(Dec::ZERO)
                    .checked_add(value)
                    .or(s.position[i])
            };
        }
    }

    /// The repeat count of a mill's canned cycle block, where it is more than one hole:
    /// FANUC's K ("number of repeats", 0i-MF operator's manual, "Canned cycle"), a Haas's and
    /// LinuxCNC's L (Haas NGC mill operator's manual, G81: "L number of holes"; LinuxCNC
    /// G-code reference, "Canned cycles": "L repeats the cycle, each from the position the
    /// last ended, under G91"). Some(None) for a count not known or not a whole number of one
    /// or more (K0 stores the cycle without a hole on a FANUC: where its position goes is not
    /// said); None for no count or 1.
    fn cycle_repeats(&self, v: &BlockValues) -> Option<Option<Dec>> {
        let letter = self
            .settings
            .family
            .cycle_repeat_letter(self.settings.haas)?;
        if v.unknown & bit(letter) != 0 {
            return Some(None);
        }
        if letter == b'K' && v.k_no_count {
            return None; // (one hole: the K is no count here)
        }
        let n = match v.k_whole.filter(|_| letter == b'K') {
            Some(n) => n,
            None => v.get(letter).or_else(|| v.other(letter))?,
        };
        if n.is_whole() && n.trunc() == 1 {
            return None;
        }
        Some(Some(n).filter(|n| n.is_whole() && n.trunc() >= 1))
    }

    /// The hole positions of a mill's canned cycle block under G91 with a repeat count
    /// ([`ModalMachine::cycle_repeats`]), before [`ModalMachine::apply_taken`] moves the
    /// plane's axes by one increment: the other holes' increments added (a count not known,
    /// or a sum too large for the core's numbers: the plane's axes the block moves not
    /// known). Off the hot path: only a block under a cycle in G91 asks.
    #[cold]
    #[inline(never)]
    fn cycle_repeated(&mut self, v: &BlockValues) {
        let Some(n) = self.cycle_repeats(v) else {
            return;
        };
        let (a, b) = polar_axes(self.state.plane);
        for axis in [a, b] {
            let (Some(i), Some(value)) = (axis_index(axis), v.get(axis)) else {
                continue;
            };
            let s = &mut self.state;
            if s.unknown & bit(axis) != 0 {
                continue; // (not known already)
            }
            let more = n
                .and_then(|n| n.checked_add(Dec::from_int(-1)))
                .and_then(|n| value.checked_mul(n))
                .and_then(|steps| s.position[i]?.checked_add(steps));
            match more {
                Some(end) => s.position[i] = Some(end),
                None => lose_axis(s, &mut self.drift[i], i, axis),
            }
        }
    }

    /// The X and Z of a lathe's U and W written in a block that takes the tool where the
    /// program's coordinates do not say (G28, G30, G53, a skip): not known after it (G code
    /// system A; `G28 U0 W0` took X and Z back to where they were).
    #[cold]
    #[inline(never)]
    fn forget_uw_axes(&mut self, v: &BlockValues) {
        if self.settings.g_system != GCodeSystem::A {
            return;
        }
        for (uw, on) in [(b'U', b'X'), (b'W', b'Z')] {
            if (v.given | v.unknown) & bit(uw) != 0 {
                self.forget_axis(on);
            }
        }
    }

    /// A block of a Fanuc or Haas lathe's single cycle G90, G92 or G94 (B's and C's G77-G79,
    /// read as A's numbers), or of an Okuma lathe's fixed thread cutting cycle G32 or G33
    /// (OSP-P200L 5238-E, section 7, 2-1; back at the starting point: CIMCO Edit's OSP
    /// threading exercise), in [`ModalMachine::moved`]: its end point kept in `cycle_end`,
    /// its taper (modal with it) in `cycle_taper` and the corner it makes in `cycle_corner`;
    /// true where the block ran the cycle (its X U Z W then move no position: the tool is
    /// back at the start point). A block of the mode without X U Z W runs none, nor does a
    /// dwell's (its U or X is the time), nor a code's that takes the axis words.
    #[cold]
    #[inline(never)]
    fn single_cycle(&mut self, v: &BlockValues, touched: u32) -> bool {
        let s = &self.state;
        // a FANUC's or Haas's G90, G92, G94; an Okuma's fixed thread cutting cycles G32 (end
        // face) and G33 (longitudinal; its G31 is read as the skip: axes_taken)
        let lap = self.settings.lap;
        let Some(motion) = s.motion.filter(|&g| {
            if lap {
                matches!(g, 32 | 33)
            } else {
                matches!(g, 90 | 92 | 94)
            }
        }) else {
            return false;
        };
        if s.cycle.is_some() || self.taken.is_some() || touched & XZUW == 0 || v.has_g(4) {
            return false;
        }
        if !self.cycle_kept {
            self.cycle_end = [None; 2];
            self.cycle_taper = None;
            self.taper_unknown = false;
            self.cycle_kept = true;
        }
        // (an Okuma's U and W: 5238-E's format of G31/G33 has none, and no page at hand says
        // they are increments from the start point there)
        let uw_known = self.settings.g_system == GCodeSystem::A && !lap;
        let end = self.end_point(v, touched, uw_known, |kept| kept);
        self.cycle_end = end;
        // the taper: FANUC R, Haas I (G90, G92) or K (G94), Okuma I (G33; its A, an angle,
        // and G32's taper words are not worked out here)
        let letter = match motion {
            94 if self.settings.haas => b'K',
            _ if self.settings.haas || lap => b'I',
            _ => b'R',
        };
        if let Some(taper) = v.get(letter).filter(|_| !(lap && motion == 32)) {
            self.cycle_taper = Some(taper);
            self.taper_unknown = false;
        } else if touched & bit(letter) != 0
            || (lap && touched & (bit(b'A') | bit(b'I')) != 0)
            // (G33's K is no taper word: 5238-E P-97 gives its taper as I or A; review 46, F2)
            || (lap && motion == 32 && touched & bit(b'K') != 0)
        {
            self.cycle_taper = None;
            self.taper_unknown = true;
        }
        self.cycle_corner = self.corner(motion == 94);
        self.ran_cycle |= CYCLE_RAN;
        if self.taper_unknown {
            self.unsure("its taper is written by a value not known here or by an angle");
        }
        true
    }

    /// The end point X, Z of the cycle of block `v` (absolute; None where not known): X or Z
    /// where written (under G91 of systems B and C an increment from the start point), else
    /// the start point plus U or W where `uw_known`, else `unwritten` of the value kept
    /// (a single cycle's modal data, or the start point's for a repetitive cycle). Says
    /// [`CYCLE_UNSURE`] where a written word's value is not known here.
    fn end_point(
        &mut self,
        v: &BlockValues,
        touched: u32,
        uw_known: bool,
        unwritten: impl Fn([Option<Dec>; 2]) -> [Option<Dec>; 2],
    ) -> [Option<Dec>; 2] {
        let s = &self.state;
        let mut end = unwritten(self.cycle_end);
        let mut unsure = false;
        for (k, (abs, inc)) in [(b'X', b'U'), (b'Z', b'W')].into_iter().enumerate() {
            let i = if abs == b'X' { 0 } else { 2 };
            let given = |l: u8| touched & bit(l) != 0;
            let start = s.position[i].filter(|_| s.unknown & bit(abs) == 0);
            if let Some(at) = v.get(abs) {
                // (G91 X of systems B and C: an increment from the start point)
                end[k] = if s.incremental {
                    start.and_then(|start| start.checked_add(at))
                } else {
                    Some(at)
                };
            } else if let Some(by) = v.get(inc).filter(|_| uw_known) {
                end[k] = start.and_then(|start| start.checked_add(by));
            } else if given(abs) || given(inc) {
                end[k] = None;
                unsure = true;
            }
        }
        if unsure {
            self.unsure("its end point X(U) Z(W) is not known here (a parameter, or U or W where no page at hand says what they are)");
        }
        end
    }

    /// The corner of the taper in force (`cycle_taper`) at the end point `cycle_end`: in Z
    /// (`in_z`: G94, the end point's Z plus R) or in X (the end point's X, a diameter, plus
    /// twice the radius difference).
    fn corner(&self, in_z: bool) -> [Option<Dec>; 2] {
        let Some(taper) = self.cycle_taper.filter(|t| !t.is_zero()) else {
            return [None; 2];
        };
        if in_z {
            [None, self.cycle_end[1].and_then(|z| z.checked_add(taper))]
        } else {
            let twice = taper.checked_add(taper);
            [
                self.cycle_end[0]
                    .zip(twice)
                    .and_then(|(x, t)| x.checked_add(t)),
                None,
            ]
        }
    }

    /// The block of a lathe's multiple repetitive cycle whose X(U) or Z(W) is its end point
    /// (the position stays: the tool returns to its start point). A FANUC's or Haas's G74
    /// (end face peck drilling), G75 (grooving) and G76 (threading: the final thread's root
    /// diameter and end, its taper the corner at the start point's Z): FANUC 0i-TF
    /// operator's manual, "Multiple repetitive cycle (G70-G76)", the second block of G74,
    /// G75, G76 (the first, P Q R alone, writes none); Haas's one-block G74, G75, G76 (Haas
    /// lathe operator's manual, "G-codes"). An X or Z not written is the start point's.
    /// An Okuma lathe's compound thread cutting cycles G71 and G72: no page at hand says what
    /// their X and Z are in full (one gives G72's X as the end and Z as the final depth):
    /// not worked out, said ([`CYCLE_UNSURE`]).
    #[cold]
    #[inline(never)]
    fn repetitive_cycle(&mut self, v: &BlockValues) {
        let touched = v.given | v.unknown;
        if self.settings.lap {
            if v.has_g(71) || v.has_g(72) {
                self.unsure("an Okuma lathe's compound thread cutting cycle G71/G72: no page at hand says where its X and Z take the tool");
            }
            return;
        }
        let Some(g) = [74, 75, 76].into_iter().find(|&g| v.has_g(g)) else {
            return;
        };
        let s = &self.state;
        let start = [
            s.position[0].filter(|_| s.unknown & bit(b'X') == 0),
            s.position[2].filter(|_| s.unknown & bit(b'Z') == 0),
        ];
        let uw_known = self.settings.g_system == GCodeSystem::A;
        self.cycle_end = self.end_point(v, touched, uw_known, |_| start);
        // (G76's taper: FANUC R of the second block, Haas I; G74's and G75's R is a relief)
        self.cycle_taper = None;
        if g == 76 {
            let letter = if self.settings.haas { b'I' } else { b'R' };
            if let Some(taper) = v.get(letter) {
                self.cycle_taper = Some(taper);
            } else if touched & bit(letter) != 0 {
                self.unsure("its taper is written by a value not known here");
            }
        }
        self.cycle_corner = self.corner(false);
        self.ran_cycle |= CYCLE_RAN;
    }
}

/// A length in the other units: millimetres times 25.4 exactly, inches from millimetres to
/// 10^-9 in (a ten-thousandth of the finest resolution a control offers: nothing the checker
/// compares can tell); None (the position unknown) where the core's numbers cannot hold it.
pub(crate) fn in_units(length: Dec, to: Units) -> Option<Dec> {
    match to {
        Units::Metric => length.checked_mul(Dec {
            mantissa: 254,
            scale: 1,
        }),
        Units::Inch => {
            // length / 25.4 = mantissa * 10 / (254 * 10^scale): to 9 more decimals
            let extra = 9u32;
            let numerator = length
                .mantissa
                .checked_mul(10 * crate::decimal::pow10(extra)?)?;
            let (q, r) = (numerator.div_euclid(254), numerator.rem_euclid(254));
            let (mantissa, _) = crate::decimal::round_quotient(q, r, 254, true);
            Some(
                Dec {
                    mantissa,
                    scale: length.scale + extra,
                }
                .normalized(),
            )
        }
    }
}

/// The feed mode a G code selects on a control, by ISO 6983-1's numbers (93 inverse time, 94
/// per minute, 95 per revolution): a FANUC or Haas lathe's G98/G99 (system A's numbers: `a`
/// is the code as `ModalSettings::read_g` reads it), every other control's G93-G95. None for
/// a code that selects no feed mode there (a system A lathe's G95, a mill's G99).
pub fn feed_mode_code(fanuc_lathe: bool, a: i64) -> Option<i64> {
    match (fanuc_lathe, a) {
        (true, 98) => Some(94),
        (true, 99) => Some(95),
        (false, 93..=95) => Some(a),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_axis_index_is_its_place_in_the_axes() {
        for letter in 0..=255u8 {
            assert_eq!(axis_index(letter), AXES.iter().position(|&a| a == letter));
        }
    }

    #[test]
    fn the_axis_places_of_letters_are_their_places_in_the_axes() {
        for letter in b'A'..=b'Z' {
            let place = axis_index(letter).map_or(0, |i| 1 << i);
            assert_eq!(axis_places(bit(letter)), place, "{}", letter as char);
        }
        // every letter at once: the nine axes, walked in the order of AXES
        let all = (0..26).fold(0u32, |m, i| m | 1 << i);
        assert_eq!(axis_places(all), 0b1_1111_1111);
        assert_eq!(
            places(axis_places(all)).collect::<Vec<_>>(),
            (0..9).collect::<Vec<_>>()
        );
        let some = bit(b'C') | bit(b'X') | bit(b'W') | bit(b'F') | bit(b'I');
        let walked: Vec<u8> = places(axis_places(some)).map(|i| AXES[i]).collect();
        assert_eq!(walked, b"XWC");
        assert_eq!(places(0).next(), None);
    }

    fn machine() -> ModalMachine {
        ModalMachine::new(ModalSettings {
            reset: vec![1, 17, 40, 21, 80, 90, 94],
            inch: 20,
            metric: 21,
            default_units: Units::Metric,
            family: Family::Iso,
            fanuc_lathe: false,
            g80_clears_motion: false,
            sinumerik_units: false,
            centre_codes: false,
            heidenhain: false,
            lap: false,
            g92_clamps: true,
            units_kept_at_end: false,
            dwell: crate::word::dwell_words(crate::lex::Family::Iso, false),
            arc_radius: b'R',
            lacks_g: Vec::new(),
            g_system: Default::default(),
            haas: false,
        })
    }

    fn block(gs: &[i64], ms: &[i64], words: &[(u8, &str)]) -> BlockValues {
        let mut v = BlockValues {
            ms: ms.to_vec(),
            ..Default::default()
        };
        for &g in gs {
            v.push_g(g);
        }
        for &(letter, text) in words {
            v.set_default(letter, Dec::parse(text).unwrap());
        }
        v
    }

    /// The machine's `taken` is what the settings find for the block it was last given, on
    /// every family and kind of machine, every G code 0-199 alone and after a G28 block (no
    /// answer kept from the block before).
    #[test]
    fn what_a_block_does_with_its_axis_words_is_the_settings_answer_for_the_last_block() {
        let families = Family::ALL;
        for family in families {
            for (fanuc_lathe, lap, centre_codes) in [
                (false, false, false),
                (true, false, false),
                (false, true, false),
                (false, false, true),
            ] {
                let mut m = machine();
                m.settings.family = family;
                m.settings.fanuc_lathe = fanuc_lathe;
                m.settings.lap = lap;
                m.settings.centre_codes = centre_codes;
                m.settings.heidenhain = family == Family::Heidenhain;
                for g in 0..200 {
                    m.apply(&block(&[28], &[], &[(b'X', "1")]));
                    let v = block(&[g], &[], &[(b'X', "1"), (b'Z', "2")]);
                    m.apply(&v);
                    assert_eq!(m.taken(), m.settings.axes_taken(&v), "{family:?} G{g}");
                    let plain = block(&[], &[], &[(b'X', "1")]);
                    m.apply(&plain);
                    assert_eq!(m.taken(), None, "{family:?} after G{g}");
                }
            }
        }
    }

    /// G00-G03 read inline (`ModalMachine::g`) set what the full reading (`g_other`) sets,
    /// the modal state and whether a lathe's U W move, on every family and kind of machine,
    /// G code system A and B, each code lacked or not, from a canned cycle, an arc, a lathe's
    /// thread and a HEIDENHAIN polar move.
    #[test]
    fn the_motion_codes_read_inline_set_what_the_full_reading_sets() {
        for family in Family::ALL {
            for (fanuc_lathe, lap, centre_codes) in [
                (false, false, false),
                (true, false, false),
                (false, true, false),
                (false, false, true),
            ] {
                for g_system in [GCodeSystem::A, GCodeSystem::B] {
                    for lacked in [None, Some(0), Some(1), Some(2), Some(3)] {
                        for before in [81, 2, 32, 11, 0] {
                            let mut m = machine();
                            m.settings.family = family;
                            m.settings.fanuc_lathe = fanuc_lathe;
                            m.settings.lap = lap;
                            m.settings.centre_codes = centre_codes;
                            m.settings.heidenhain = family == Family::Heidenhain;
                            m.settings.g_system = g_system;
                            if let Some(n) = lacked {
                                m.settings.lacks_g = vec![false; 200];
                                m.settings.lacks_g[n] = true;
                            }
                            m.g_other(before);
                            m.cycle_kept = fanuc_lathe || lap;
                            for g in 0..=3 {
                                let (state, uw, kept) = (m.state, m.uw_moves, m.cycle_kept);
                                m.g(g);
                                let inline = (m.state, m.uw_moves, m.cycle_kept);
                                (m.state, m.uw_moves, m.cycle_kept) = (state, uw, kept);
                                m.g_other(g);
                                assert_eq!(
                                    inline,
                                    (m.state, m.uw_moves, m.cycle_kept),
                                    "{family:?} lathe {fanuc_lathe} lap {lap} {g_system:?} \
                                     lacked {lacked:?} G{before} then G{g}"
                                );
                                (m.state, m.uw_moves, m.cycle_kept) = (state, uw, kept);
                            }
                        }
                    }
                }
            }
        }
    }

    fn fanuc_lathe() -> ModalMachine {
        let mut m = machine();
        m.settings.family = Family::MacroB;
        m.settings.fanuc_lathe = true;
        m.settings.dwell = crate::word::dwell_words(Family::MacroB, true);
        m.settings.reset = vec![0, 18, 21, 40, 97, 99];
        m.reset();
        m
    }

    fn xz(m: &ModalMachine) -> (Option<Dec>, Option<Dec>) {
        (m.state.position[0], m.state.position[2])
    }

    fn d(text: &str) -> Option<Dec> {
        Some(Dec::parse(text).unwrap())
    }

    /// Issue 32 (thr42): a FANUC or Haas lathe's threading G32 and G34 cut to their end
    /// point and stay there, U and W its increments as in G01 (FANUC 0i-TF operator's
    /// manual, "Thread cutting G32"); the single cycles G90, G92, G94 go to their end point
    /// X(U) Z(W) and back to the start point, where the position stays, the end point kept
    /// for their modal repeats until a code of group 01 other than theirs ("Canned cycle").
    #[test]
    fn a_lathe_s_thread_follows_u_and_w_and_its_single_cycles_return_to_the_start() {
        for thread in [32, 34] {
            let mut m = fanuc_lathe();
            m.apply(&block(&[0], &[], &[(b'X', "60."), (b'Z', "2.")]));
            m.apply(&block(&[thread], &[], &[(b'W', "-30."), (b'F', "1.5")]));
            assert!(m.uw_moved_xz(), "G{thread}");
            assert_eq!(xz(&m), (d("60."), d("-28.")), "G{thread}");
            assert_eq!(m.cycle_end(), None);
            m.apply(&block(&[], &[], &[(b'U', "-4."), (b'W', "-2.")]));
            assert_eq!(xz(&m), (d("56."), d("-30.")), "G{thread}");
        }
        for cycle in [90, 92, 94] {
            let mut m = fanuc_lathe();
            m.apply(&block(&[0], &[], &[(b'X', "60."), (b'Z', "2.")]));
            m.apply(&block(&[cycle], &[], &[(b'U', "-10."), (b'W', "-30.")]));
            assert!(!m.uw_moved_xz(), "G{cycle}");
            assert_eq!(m.cycle_end(), Some([d("50."), d("-28.")]), "G{cycle}");
            assert_eq!(xz(&m), (d("60."), d("2.")), "G{cycle}: the start point");
            // the modal repeat: a new X, the Z kept
            m.apply(&block(&[], &[], &[(b'X', "45.")]));
            assert_eq!(m.cycle_end(), Some([d("45."), d("-28.")]), "G{cycle}");
            m.apply(&block(&[], &[], &[(b'U', "-20.")]));
            assert_eq!(m.cycle_end(), Some([d("40."), d("-28.")]), "G{cycle}");
            assert_eq!(xz(&m), (d("60."), d("2.")), "G{cycle}");
            // a block of the mode without X U Z W, and a dwell, run no cycle
            m.apply(&block(&[], &[], &[(b'F', "0.2")]));
            assert_eq!(m.cycle_end(), None);
            m.apply(&block(&[4], &[], &[(b'U', "1.5")]));
            assert_eq!((m.cycle_end(), xz(&m)), (None, (d("60."), d("2."))));
            // another code of the cycles' group keeps the data; G00 ends it
            let other = if cycle == 90 { 94 } else { 90 };
            m.apply(&block(&[other], &[], &[(b'X', "30.")]));
            assert_eq!(m.cycle_end(), Some([d("30."), d("-28.")]), "G{cycle}");
            m.apply(&block(&[0], &[], &[(b'X', "70.")]));
            assert_eq!((m.cycle_end(), xz(&m)), (None, (d("70."), d("2."))));
            m.apply(&block(&[cycle], &[], &[(b'X', "30.")]));
            assert_eq!(m.cycle_end(), Some([d("30."), None]), "G{cycle}");
            assert_eq!(xz(&m), (d("70."), d("2.")), "G{cycle}");
        }
        // from an unknown start point, an increment's end is not known
        let mut m = fanuc_lathe();
        m.apply(&block(&[90], &[], &[(b'U', "-10."), (b'Z', "-5.")]));
        assert_eq!(m.cycle_end(), Some([None, d("-5.")]));
        assert_eq!(xz(&m), (None, None));
    }

    #[test]
    fn a_units_change_keeps_the_position_and_says_it_in_the_new_units() {
        let mut m = machine();
        m.apply(&block(&[0], &[], &[(b'X', "100")]));
        m.apply(&block(&[20, 91], &[], &[(b'X', "1")]));
        // 100 mm + 1 in = 125.4 mm = 4.937007874 in (to 10^-9 in)
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "4.937007874");
        m.apply(&block(&[21], &[], &[]));
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "125.3999999996");
        // a rotary axis is in degrees in either units
        m.apply(&block(&[90], &[], &[(b'A', "90")]));
        m.apply(&block(&[20], &[], &[]));
        assert_eq!(m.state.axis(b'A').unwrap().to_string(), "90");
        assert_eq!(
            in_units(Dec::parse("-25.4").unwrap(), Units::Inch),
            Dec::parse("-1")
        );
    }

    #[test]
    fn a_lathe_cycle_of_the_motion_group_replaces_the_arc_mode() {
        let mut m = machine();
        m.settings.family = Family::MacroB;
        m.settings.fanuc_lathe = true;
        m.apply(&block(
            &[2],
            &[],
            &[(b'X', "40"), (b'Z', "-10"), (b'R', "10")],
        ));
        for g in [32, 34, 90, 92, 94] {
            m.apply(&block(&[2], &[], &[]));
            m.apply(&block(&[g], &[], &[(b'X', "35"), (b'Z', "-20")]));
            assert_eq!(m.state.motion, Some(g));
        }
        // system A has no absolute-incremental codes: G90 is the turning cycle
        assert!(!m.state.incremental);
        m.apply(&block(&[1], &[], &[]));
        assert_eq!(m.state.motion, Some(1));
        // a mill's G90 is the absolute mode, and G02 stays in force
        let mut mill = machine();
        mill.apply(&block(&[2], &[], &[]));
        mill.apply(&block(&[91], &[], &[]));
        mill.apply(&block(&[90], &[], &[]));
        assert_eq!(
            (mill.state.motion, mill.state.incremental),
            (Some(2), false)
        );
        // an Okuma lathe's fixed thread cutting cycles G31/G32; its LAP calls keep the mode
        let mut okuma = machine();
        okuma.settings.family = Family::Okuma;
        okuma.settings.lap = true;
        okuma.apply(&block(&[2], &[], &[]));
        okuma.apply(&block(&[85], &[], &[(b'U', "0.4"), (b'W', "0.1")]));
        assert_eq!(okuma.state.motion, Some(2));
        assert_eq!(
            okuma
                .settings
                .axes_taken(&block(&[85], &[], &[(b'U', "0.4")])),
            Some(AxesTaken::Data)
        );
        okuma.apply(&block(&[32], &[], &[(b'X', "10"), (b'Z', "-1")]));
        assert_eq!(okuma.state.motion, Some(32));
    }

    #[test]
    fn positions_absolute_and_incremental() {
        let mut m = machine();
        m.apply(&block(&[], &[], &[(b'X', "10"), (b'Y', "5")]));
        m.apply(&block(&[91], &[], &[(b'X', "2.5")]));
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "12.5");
        m.apply(&block(&[92], &[], &[(b'X', "0")]));
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "0");
        m.apply(&block(&[4], &[], &[(b'X', "2")]));
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "0");
    }

    /// A G code a control family's table does not hold changes no mode: G91 on a FANUC lathe
    /// of G code system A (no G90/G91 there) leaves the moves absolute, G06 starts no motion.
    #[test]
    fn a_code_the_table_lacks_changes_no_mode() {
        let mut lacks_g = vec![false; 1000];
        lacks_g[91] = true;
        lacks_g[6] = true;
        let mut m = ModalMachine::new(ModalSettings {
            family: Family::MacroB,
            lacks_g,
            ..machine().settings
        });
        m.apply(&block(&[0], &[], &[(b'X', "10")]));
        m.apply(&block(&[91], &[], &[(b'X', "10")]));
        assert!(!m.state.incremental);
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "10");
        m.apply(&block(&[6], &[], &[]));
        assert_eq!(m.state.motion, Some(0));
        // where the table holds it (the default machine: no list), G91 is incremental
        let mut iso = machine();
        iso.apply(&block(&[0, 91], &[], &[(b'X', "10")]));
        iso.apply(&block(&[], &[], &[(b'X', "10")]));
        assert_eq!(iso.state.axis(b'X').unwrap().to_string(), "20");
    }

    /// An Okuma OSP lathe's G20 HP=n returns to a home position of its parameters: no axis's
    /// position is known after it, with or without axis words, and its units stay (no G code
    /// selects them there); on the machining centre G20 is inch.
    #[test]
    fn an_okuma_lathe_s_g20_is_a_home_return_that_leaves_no_position_known() {
        let okuma = |lathe: bool, (inch, metric): (i64, i64)| {
            ModalMachine::new(ModalSettings {
                family: Family::Okuma,
                lap: lathe,
                inch,
                metric,
                ..machine().settings
            })
        };
        let mut lathe = okuma(true, (-1, -1));
        lathe.apply(&block(&[0], &[], &[(b'X', "100"), (b'Z', "50")]));
        lathe.apply(&block(&[20], &[], &[]));
        assert_eq!(
            (lathe.state.axis(b'X'), lathe.state.axis(b'Z')),
            (None, None)
        );
        assert_eq!(lathe.state.units, Units::Metric);
        lathe.apply(&block(&[0], &[], &[(b'X', "80")]));
        assert_eq!(lathe.state.axis(b'X').unwrap().to_string(), "80");
        assert_eq!(lathe.state.axis(b'Z'), None);
        // a lathe profile that makes G20 its units code: inch, the place kept (100 mm in inches)
        let mut coded = okuma(true, (20, 21));
        coded.apply(&block(&[0], &[], &[(b'X', "100")]));
        coded.apply(&block(&[20], &[], &[]));
        assert_eq!(coded.state.units, Units::Inch);
        assert_eq!(coded.state.axis(b'X').unwrap().to_string(), "3.937007874");
        let mut mill = okuma(false, (20, 21));
        mill.apply(&block(&[0], &[], &[(b'X', "100"), (b'Z', "50")]));
        mill.apply(&block(&[20], &[], &[]));
        assert_eq!(mill.state.units, Units::Inch);
        assert_eq!(mill.state.axis(b'Z').unwrap().to_string(), "1.968503937");
    }

    #[test]
    fn m30_resets_the_modes_and_keeps_the_position() {
        let mut m = machine();
        m.apply(&block(&[91, 20], &[3, 8], &[(b'X', "1"), (b'F', "100")]));
        assert_eq!(
            (m.state.units, m.state.spindle, m.state.coolant),
            (Units::Inch, 3, 8)
        );
        m.apply(&block(&[], &[30], &[]));
        assert!(!m.state.incremental && m.state.ended);
        assert_eq!(m.state.units, Units::Metric);
        assert_eq!(m.state.axis(b'X').unwrap().to_string(), "1");
    }

    #[test]
    fn a_control_that_keeps_its_units_keeps_them_through_m30_only() {
        let mut m = machine();
        m.settings.units_kept_at_end = true;
        m.apply(&block(&[91, 20], &[], &[(b'X', "1")]));
        m.apply(&block(&[], &[30], &[]));
        assert!(!m.state.incremental && m.state.ended);
        assert_eq!(
            (m.state.units, m.state.feed_units),
            (Units::Inch, Units::Inch)
        );
        m.reset(); // power-on, or the operator's reset: the reset state's units
        assert_eq!(m.state.units, Units::Metric);
    }

    /// The mask of the letters given against the slow way, a value per letter kept in a map,
    /// over every byte as a letter and a block's clearing between rounds.
    #[test]
    fn block_values_keep_the_first_value_of_each_letter_as_a_map_would() {
        let mut v = BlockValues::default();
        let mut seed = 12345u64;
        for round in 0..200 {
            v.clear();
            let mut map = std::collections::HashMap::new();
            for _ in 0..40 {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let letter = (seed >> 33) as u8;
                let letter = if seed & 1 == 0 {
                    b'A' + letter % 26
                } else {
                    letter
                };
                let value = Dec::from_int(i128::from((seed >> 40) as i16) + round);
                v.set_default(letter, value);
                if letter.is_ascii_uppercase() {
                    map.entry(letter).or_insert(value);
                }
                for l in 0..=255u8 {
                    assert_eq!(v.get(l), map.get(&l).copied(), "{l}");
                    assert_eq!(v.has(l), map.contains_key(&l));
                }
            }
        }
    }

    /// The mask of the G codes against the slow way, a search of the list, over codes inside
    /// and outside 0-127 (negative ones too) and a block's clearing between rounds.
    #[test]
    fn a_block_has_the_g_codes_its_list_has() {
        let mut v = BlockValues::default();
        let mut seed = 99u64;
        for _ in 0..300 {
            v.clear();
            for _ in 0..6 {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                v.push_g(((seed >> 33) % 400) as i64 - 100);
                for g in -200..600 {
                    assert_eq!(v.has_g(g), v.gs().contains(&g), "{g}");
                }
            }
        }
    }

    #[test]
    fn a_cycle_keeps_its_words_until_g80() {
        let mut m = machine();
        m.apply(&block(&[81], &[], &[(b'Z', "-5"), (b'R', "2")]));
        assert_eq!(m.state.cycle, Some(81));
        assert!(m.state.cycle_words[0].is_some());
        m.apply(&block(&[80], &[], &[]));
        assert_eq!((m.state.cycle, m.state.cycle_words[0]), (None, None));
    }

    /// Review 59c F1: a lathe's cycle the state does not model (a Haas lathe's G243) over a
    /// thread stands in the motion group in its place, so that its repeats are no thread's
    /// (`code_in_force` none); G80 puts the thread back, unless another motion code replaced
    /// the cycle; with no thread in force nothing changes.
    #[test]
    fn a_lathe_s_unmodelled_cycle_over_a_thread_stands_in_its_place_until_g80() {
        for thread in [32, 92] {
            let mut m = fanuc_lathe();
            m.apply(&block(&[thread], &[], &[(b'Z', "-5."), (b'F', "1.5")]));
            assert_eq!(m.state.code_in_force(true), Some(thread));
            m.cycle_over_thread(243);
            assert_eq!(m.state.motion, Some(243));
            assert_eq!(m.state.code_in_force(true), None);
            m.cycle_over_thread(241); // a second cycle over the same thread
            assert_eq!(m.state.motion, Some(241));
            m.apply(&block(&[80], &[], &[]));
            assert_eq!(m.state.code_in_force(true), Some(thread), "G{thread}");
        }
        let mut m = fanuc_lathe();
        m.apply(&block(&[92], &[], &[(b'Z', "-5."), (b'F', "1.5")]));
        m.cycle_over_thread(243);
        m.apply(&block(&[1], &[], &[(b'X', "10.")]));
        m.apply(&block(&[80], &[], &[]));
        assert_eq!(m.state.motion, Some(1));
        m.cycle_over_thread(243);
        assert_eq!(m.state.motion, Some(1));
    }
}
