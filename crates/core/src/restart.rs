//! What a restart preamble needs to know beyond the modal state, read block by block.
//!
//! `tapegate send --restart-at` reads the program up to the restart block with the checker's
//! modal state machine ([`crate::check::Checker`]) and, beside it, this walk: which modes are in
//! force that a preamble cannot restore (a rotation, a G92 shift), the first jump or call after
//! which nothing is known, why an axis's position is not a plain value (sent to the reference
//! point, set by a parameter, lost at a statement), the tool and offsets as the program wrote
//! them, the highest retract height, and the units each value was last written in.
//!
//! A program of millions of blocks is read here, in one pass, without a Python object per
//! block; `postproc.restart` plans the preamble from the facts once, at the restart block. The
//! reasons are kept as their texts, except where a statement's text is quoted: that one is kept
//! as the text and its line ([`Why::Statement`]), and quoted with Python's `repr` there.
//!
//! Where the walk cannot tell, it says so, for the restart to be refused: a height with too
//! many digits to be compared in mm ([`Walk::too_long`]), a decimal code longer than the
//! 28 digits Python's `Decimal` read it with (an unrestored mode).

use crate::decimal::Dec;
use crate::lex::Family;
use crate::modal::{axis_index, ModalState, Units, AXES};
use crate::statement::{conditional_body, Kind};

/// The control family, as far as the walk tells them apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    Iso,
    Fanuc,
    Haas,
    LinuxCnc,
    Sinumerik,
    Heidenhain,
    /// Okuma OSP: a family of its own (`okuma`), read by `crate::okuma`.
    Okuma,
}

impl Control {
    pub fn from_name(name: &str) -> Control {
        match name {
            "fanuc" => Control::Fanuc,
            "haas" => Control::Haas,
            "linuxcnc" => Control::LinuxCnc,
            "sinumerik" => Control::Sinumerik,
            "heidenhain" => Control::Heidenhain,
            "okuma" => Control::Okuma,
            _ => Control::Iso,
        }
    }

    /// The language of its statements: Fanuc and Haas both read Custom Macro B.
    pub fn family(self) -> Family {
        match self {
            Control::Iso => Family::Iso,
            Control::Fanuc | Control::Haas => Family::MacroB,
            Control::LinuxCnc => Family::LinuxCnc,
            Control::Sinumerik => Family::Sinumerik,
            Control::Heidenhain => Family::Heidenhain,
            Control::Okuma => Family::Okuma,
        }
    }
}

/// The modes a preamble cannot restore, the code that ends each, and their names (a mill's).
const UNRESTORED: [(i64, i64, &str); 3] = [
    (68, 69, "coordinate rotation"),
    (51, 50, "scaling"),
    (16, 15, "polar coordinates"),
];
const MOTION_CODES: [i64; 9] = [0, 1, 2, 3, 6, 32, 33, 34, 35];
const LATHE_CYCLES: [i64; 10] = [70, 71, 72, 73, 74, 75, 76, 90, 92, 94];
/// An Okuma mill's frames (OSP List of G Codes, `okuma-mill.toml`): its G68 is the 3-D
/// conversion's cancel, its G15/G16 select a work system. And its air cut reduction mode, G38
/// on, G37 its cancel (the later OSP machining centres' List of G Codes, `okuma-mill.toml`):
/// a mode of the feed in the air, no frame, which the preamble does not write: a restart
/// under it is refused, as it was before the profile named the two (review 57b, F6: it was
/// planned without the mode, and without a word of it).
const OKUMA_UNRESTORED: [(i64, i64, &str); 4] = [
    (
        11,
        10,
        "parallel and rotation shift of the coordinate system",
    ),
    (51, 50, "scaling"),
    (69, 68, "3-D coordinate system conversion"),
    (38, 37, "air cut reduction"),
];
/// Decimal codes whose state the preamble does not write: G54.1 (an extra work system), G41.1 /
/// G42.1 (normal direction control), and the length offsets it cannot restore with the tool's
/// H: G43.1 (in the tool axis direction), G43.4 / G43.5 (tool centre point control, types 1
/// and 2; review 29, finding 1: a restart under them dropped the length offset, the tool tip
/// one tool length below the programmed Z), each ended by G49 or another length offset code.
const DECIMAL_UNRESTORED: [&str; 6] = ["54.1", "41.1", "42.1", "43.1", "43.4", "43.5"];
/// The length offsets among [`DECIMAL_UNRESTORED`], ended by G49 or G43.
const DECIMAL_LENGTH_OFFSETS: [&str; 3] = ["43.1", "43.4", "43.5"];
/// FANUC's tilted working plane (0i-MF/30i, `fanuc-mill.toml`: G68.2 indexing, G68.3 by the
/// tool axis direction, G68.4 incremental multi-command), each ended by G69: a 3-D frame the
/// preamble cannot restore, under which a move of one axis is a move of all three (review 28,
/// finding 1: G68.3/G68.4 were planned without it, the axes moved under any of the three
/// counted as known after G69).
const TILTED_PLANES: [&str; 3] = ["68.2", "68.3", "68.4"];
/// FANUC's polar coordinate interpolation (G12.1, a lathe's G112 in G code system A; cancel
/// G13.1 / G113) and cylindrical interpolation (G07.1 / G107 with the cylinder's radius; cancel
/// the same code with C0), also a Haas lathe's G112/G113 and G107 (Haas lathe operator's
/// manual): the program's X and C (or Z and C) are a plane's coordinates the control turns into
/// the axes' own, so a move under them leaves the axes at places the program did not write, and
/// the preamble cannot restore the mode (review 32, finding 2: `G00 X10. Y0 C5.` was planned as
/// a straight move of X and 5 degrees of C). Keyed by the decimal code, whichever was written.
const INTERPOLATED_PLANES: [&str; 2] = ["12.1", "7.1"];
/// LinuxCNC's work systems 7-9 (G59.1-G59.3, the G54-G59.3 group): the preamble writes a
/// G54-G59 alone, so one of these in force is refused, and a change to or from one loses the
/// axes seen, as any change of work system does (review 32, finding 3: G54 was planned).
const LINUXCNC_WORK_SYSTEMS: [&str; 3] = ["59.1", "59.2", "59.3"];

fn machine_move(g: i64) -> Option<&'static str> {
    match g {
        28 => Some("reference point"),
        30 => Some("second reference point"),
        53 => Some("machine coordinates"),
        _ => None,
    }
}

fn mill_cycle(g: i64) -> bool {
    matches!(g, 73 | 74 | 76 | 81..=89)
}

/// Why a value is not a plain one in the program's coordinates, as facts for the message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Why {
    /// A text already whole (`X#1, set by a parameter`); bytes, as the tokens are.
    Text(Vec<u8>),
    /// Lost at a statement the modal state does not follow: its text and line, for
    /// `"{text!r}, which the modal state does not follow"` (an axis) or
    /// `"after {text!r} on line {line}, ..."` (a feed or speed).
    Statement(Vec<u8>, usize),
}

/// An axis whose position is not a plain value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Lost {
    /// Sent to a reference point or a machine position (the preamble sends it there again),
    /// rather than unknown.
    pub machine: bool,
    /// Lost to a change of work coordinate system after the axis's last position (G54 ->
    /// G55, an Okuma mill's G15 H1 -> H2): the value the walk holds is a place of the old
    /// system, which the same number in the new one is not.
    pub frame: bool,
    /// Lost to a canned cycle that moved an axis: the tool is at the cycle's return level,
    /// from which a block that sets Z itself goes to its own Z (the restart's approach goes
    /// there), unlike a position nothing tells.
    pub cycle: bool,
    pub line: usize,
    pub what: Why,
    /// For a machine move: the codes and the word that send it there again (`G91 G28`, `Z0`).
    pub replay: (String, Vec<u8>),
}

/// The first jump, loop, call or control instruction: nothing is known after it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Flow {
    pub line: usize,
    /// The statement's text, or the block's text for a call by code (`M98 P100`), which
    /// `postproc.restart` strips of its blanks.
    pub text: Vec<u8>,
    /// `flow`, `call`, `definition` or `command`.
    pub kind: &'static str,
    /// Whether `text` is a whole block's, to be stripped.
    pub block: bool,
}

/// One block as the walk reads it: its word tokens and statements.
pub struct Step<'a> {
    pub line: usize,
    pub text: &'a [u8],
    pub tokens: &'a [&'a [u8]],
    pub statements: &'a [(Kind, &'a [u8])],
    /// Whether the block has extras (a comment, a skip, `%`, statements): a block with neither
    /// words nor extras is not read at all.
    pub extras: bool,
}

/// The walk's facts after the blocks read so far.
#[derive(Debug, Clone)]
pub struct Walk {
    control: Control,
    lathe: bool,
    fanuc_lathe: bool,
    /// An Okuma lathe: G50 S clamps the spindle and G50 X Z sets the zero, U W are X Z
    /// incremental, and G71-G89 are thread, grooving and LAP cycles (OSP-P200L 5238-E).
    okuma_lathe: bool,
    /// The line of the Okuma lathe's LAP contour definition (G81-G83) being read, up to its
    /// G80: its blocks are the cycle's data, no moves.
    lap_contour: Option<usize>,
    /// FANUC's G10 L50 / G10 L3 data input mode: its blocks are parameter and tool life data,
    /// no moves or tool changes, and a restart inside it would run them as program.
    data_input: crate::dialect::DataInput,
    /// The words of a G04 block that are the dwell's time ([`crate::word::dwell_words`]).
    dwell: &'static [u8],
    /// The checker's position after the block before: where the next block starts, unless
    /// [`Walk::held`] says otherwise.
    before: [Option<Dec>; 9],
    /// Per axis of [`AXES`]: where a lathe's cycle left the tool, its start point, where the
    /// checker's modal state reads the cycle's words as the place reached. A FANUC or Haas
    /// lathe's G70-G76 and single cycles G90, G92, G94 (and their repeats in their mode) end
    /// where they started (FANUC 0i-TF operator's manual, "Canned cycle" and "Multiple
    /// repetitive cycle": the tool returns to the start point), as an Okuma lathe's thread
    /// cutting cycles G31-G33 do (OSP-P200L 5238-E, section 7). Cleared by the axis's next
    /// absolute move.
    pub held: [Option<Dec>; 9],
    /// A FANUC or Haas lathe's G71-G73 P Q just read: (P, Q, code, line). Its contour, the
    /// blocks N P to N Q, follows when the next block is N P.
    pub contour_next: Option<(i64, i64, i64, usize)>,
    /// Inside that contour: (Q, code, line of the cycle). Its blocks are the cycle's data,
    /// no moves, until G70 runs them (0i-TF: the P..Q blocks are the shape program; F, S and
    /// T in them count in G70 only).
    contour: Option<(i64, i64, usize)>,
    /// The line of the block before, when it cut a thread (G32 on a FANUC lathe): a thread
    /// move right after it continues the same thread, which cannot be entered mid-way.
    pub thread: Option<usize>,
    /// An Okuma machining centre's work coordinate system, `G15 H n`: its H word (None when
    /// not plain) and line (OSP: G15 H selects the work system; 4203-E's List of G Codes).
    pub okuma_work: Option<(Option<Vec<u8>>, usize)>,
    /// An Okuma machining centre's tool length offset in force, `G56 H n` (G53 cancels it):
    /// its code, H word (None when not plain) and line.
    pub okuma_length: Option<(i64, Option<Vec<u8>>, usize)>,
    /// The line of the R (taper) of a FANUC or Haas lathe's single cycle G90/G92/G94 in
    /// force: modal within the cycle, with its Z (W) (0i-TF, "Canned cycle"), which a restart
    /// at a repeat of X alone loses to the preamble's G00.
    pub cycle_r: Option<usize>,
    pub flow: Option<Flow>,
    /// Mode key (`68`, `54.1`) -> (line, what).
    pub unrestored: Vec<(String, usize, String)>,
    /// Per axis of [`AXES`].
    pub lost: [Option<Lost>; 9],
    /// Per letter `A`..`Z`: why its value in force is not known.
    pub unknown: [Option<Why>; 26],
    /// The axes that have had a position (bits of [`AXES`] indexes).
    pub seen: u16,
    pub t_token: Option<Vec<u8>>,
    pub spindle_t: Option<Vec<u8>>,
    pub m6: Option<Vec<u8>>,
    pub h: Option<Vec<u8>>,
    pub g43_line: usize,
    pub d_token: Option<Vec<u8>>,
    pub work: Option<i64>,
    pub arc_absolute: bool,
    pub comp_line: usize,
    /// (code, line) of a canned cycle in force.
    pub cycle: Option<(i64, usize)>,
    /// The highest value of X and of Z, in mm (exact).
    pub high: [Option<Dec>; 2],
    /// The first line with a height of too many digits to be compared in mm (the highest
    /// point is not known after it).
    pub too_long: Option<usize>,
    /// Per letter `A`..`Z`: the units it was last written in, and where (F and the axes).
    pub written: [Option<(Units, usize)>; 26],
    /// The motion mode in force after the last block that wrote Z, and its line: how the
    /// program reached the height it is at (a rapid or a feed), which a restart refused for
    /// want of a clear height names.
    pub z_reached: Option<(Option<i64>, usize)>,
    /// The profile's units codes (set by the binding from the checker's settings): which G
    /// codes select the units, for [`Walk::units_line`].
    pub units_settings: Option<crate::modal::ModalSettings>,
    /// The decimal G codes the profile's list holds (`54.1`), set by the binding where the
    /// profile has its control's own list: a decimal code outside it is one the control alarms
    /// on or runs as a macro call, as an unlisted whole code is (review 31, finding 2: Haas's
    /// `G68.2` and `G53.1`, or FANUC's `G43.9`, were planned past as if they had run).
    pub decimal_codes: Option<Vec<Vec<u8>>>,
    /// The M codes the profile's list lacks (index: the code), set by the binding for a FANUC
    /// or Haas profile: there an M code parameters 6080-6089 name (a Haas: its M code aliases)
    /// is a custom macro call, whose other words are its arguments, so a plain S, F, T, D, H or
    /// axis word beside an unlisted M code with a word only an argument is (a P or Q, a point
    /// in S, T, D or H) is not known to be a speed, feed, tool or position (review 33,
    /// finding 5: `M165 P9811 Z0 S2` was planned as `S2 M03`).
    pub lacks_m: Option<Vec<bool>>,
    /// The M codes that switch a machine mode the preamble does not restore, set by the
    /// binding from the profile's meanings (a lathe's live tool drive, `live-tool-cw`/`-ccw`
    /// on and `live-tool-stop` off; its C axis, `c-axis-engage` and `-disengage`): (code, the
    /// mode's name, on, the profile's function). Refused while one is on (review 34, finding
    /// 2: a Haas lathe's `M154` and `M133 P2000` were planned past, the radial drill fed in
    /// with the live tool stopped).
    pub m_modes: Vec<(i64, &'static str, bool, String)>,
    /// Per mode of [`Walk::m_modes`] switched on: where a restart can be made instead, for the
    /// refusal (the tool change before it, or the mode's own code, and the codes that end it).
    pub mode_hints: Vec<(&'static str, String)>,
    /// The M codes of the profile's `spindle-orient` meaning (M19), and of
    /// `spindle-to-axis-mode` (a SINUMERIK's M70), set by the binding.
    pub orient_codes: Vec<i64>,
    /// The last spindle orientation in force (M19 on FANUC, Haas, OSP, SINUMERIK: "adjusts
    /// the spindle to a fixed position", Haas mill manual, "M19 Orient Spindle"): its line and
    /// code. The spindle stands oriented, not turning, until an M03, M04 or M05 (review 35,
    /// finding 1: the preamble started it with the modal state's M03 of before the M19).
    pub oriented: Option<(usize, i64)>,
    /// Each orientation of the spindle so far: the line of its first M19 and that of the
    /// M03, M04, M05 or tool change that ended it (None: in force). A second M19 does not end
    /// one, so a restart after it is refused for the first (review 38, finding 5): a hint
    /// goes back to its first M19 ([`Walk::before_orientation`]).
    pub orientations: Vec<(usize, Option<usize>)>,
    /// A lathe's last move of C or Y (line, axis) since the main spindle last started (M03,
    /// M04): C positioned, a live tool's milling or drilling at an angle (review 35, finding 2).
    pub side_move: Option<(usize, u8)>,
    /// The first line a mode code of `m_modes` switched on since the main spindle last
    /// started (M03, M04): where a restart hint points after a C or Y move, whose way in is
    /// not known (review 37, finding 7).
    pub mode_since_spin: Option<usize>,
    /// The last M code the profile's list lacks since the main spindle last started (line,
    /// code): on a FANUC lathe the live tool drive and the C-axis (Cs) mode are the builder's
    /// M codes (TG307), which the walk cannot name; on a mill it may be the builder's spindle
    /// start (M13, spindle and coolant).
    pub builder_m: Option<(usize, i64)>,
    /// The line of the last M03/M04 (0: none yet), or of a code of `turn_codes`.
    pub spin_line: usize,
    /// The M codes other than M03/M04 whose meaning key in the profile says they turn the
    /// main spindle (`spindle-cw-coolant-on`: a builder's M13, spindle and coolant), set by
    /// the binding.
    pub turn_codes: Vec<i64>,
    /// The code of `turn_codes` that last started the spindle, while no M03, M04 or M05 has
    /// come since (line, code): the preamble restores the spindle by it (review 56a F9).
    pub turned_by: Option<(usize, i64)>,
    /// The codes of `turn_codes` that also turn a coolant on (`spindle-cw-coolant-on`,
    /// `spindle-ccw-coolant-on`: a builder's M13 and M14), set by the binding.
    pub coolant_starts: Vec<i64>,
    /// The code of `coolant_starts` whose coolant is on (line, code): set by the code, ended
    /// by M09, a FANUC or Haas mill's M06 (not one of its own block: review 57a F2) and the
    /// program's end, not by M05 (review 56d F1: the modal state reads M07-M09 alone, so the
    /// preamble restores that coolant by it).
    pub keyed_coolant: Option<(usize, i64)>,
    /// The M codes of the spindle's modal group (M03's `duration`) that the walk does not
    /// read: neither M03-M05 nor a code of `turn_codes` or `orient_codes` (a builder's M13
    /// listed without a meaning key, LinuxCNC's M19), set by the binding.
    pub unread_spindle: Vec<i64>,
    /// The codes of `unread_spindle` run while no M03, M04, M05 or code the walk reads has
    /// come since (the first one's line, the last one's line and code): what they did to the
    /// spindle the preamble cannot know (review 56d F9).
    pub unread_spin: Option<(usize, usize, i64)>,
    /// The first M code the profile's list lacks since the spindle last stopped or started,
    /// or since the last M06 (the line of the first code of [`Walk::builder_m`]'s run): a
    /// restart there is not refused for it, where one at `builder_m`'s line may be.
    pub builder_first: usize,
    /// A SINUMERIK's spindle functions by an address extension (`M1=3`, `M0=70`,
    /// `M[SPINU]=3`) or position (`SPOS=90`, `SPOSA[2]=0`) since the last plain M3, M4 or M5:
    /// the first one's line, the last one's line and text, and whether a plain M3, M4 or M5
    /// commands each one's spindle (extension 0, the master; 1 while no `SETMS` has named
    /// another), and so ends them. The modal state follows the plain codes alone, so the
    /// preamble would restore another spindle state (review 56d F6, F11).
    pub spindle_by_extension: Option<(usize, usize, Vec<u8>, bool)>,
    /// Whether a `SETMS` came before: the master spindle is no longer machine data's 1.
    setms: bool,
    /// The line of the last M07/M08 (0: none yet): a FANUC or Haas mill's M06 after it has
    /// stopped the coolant ([`RestartWalk::tool`]).
    pub coolant_line: usize,
    /// The axes whose number in the modal state is no place the preamble goes to (bits of
    /// [`AXES`] indexes): a Haas lathe's Y after G112/G113, the virtual axis of the XC plane
    /// (Autodesk's HAAS Lathe post writes Y only under G112), and C after its disengage (a C
    /// word then is no position). Not positioned, until the program writes the axis again.
    pub unset: u16,
    /// Whether Y had a position before the lathe's G112 in force: then its number after G113
    /// is not known (the real Y of a Y-axis lathe), else the virtual axis, unset.
    polar_y: bool,
    /// The line of the program's own last units code (G20/G21, a SINUMERIK's G70/G71/G700/
    /// G710): without one the units are the control's setting, which the preamble must not
    /// choose for it.
    pub units_line: Option<usize>,
    /// The program's name as it is written: its first O word, or its `%_N_..._SPF` header.
    pub program_name: Option<Vec<u8>>,
    /// The line of the last M06 (0: none yet).
    pub m6_line: usize,
    /// The coolant M codes on since the last M09, in the order they came (M07, M08): LinuxCNC
    /// has mist and flood on at once (rs274: MIST_ON, FLOOD_ON).
    pub coolant: Vec<i64>,
    /// The axes moved under a rotation, scaling or mirror image (bits of [`AXES`] indexes):
    /// at its cancel the tool stands at the transformed point, which the modal state's
    /// number is not.
    transformed: u16,
    /// A Haas G107's mapped linear axis (bits of [`AXES`] indexes; every linear axis where its
    /// block names none): the only linear axis its moves transform (review 36, finding 8).
    haas_cylinder: u16,
    /// The axes a G92 in force shifted (bits of [`AXES`] indexes): lost at its cancel.
    shifted: u16,
    /// The axes a FANUC G51.1 mirrors (bits of [`AXES`] indexes): G50.1 ends the mirror of
    /// the axes it names, the mirror is in force until it has ended every one (review 15,
    /// finding 2).
    mirrored: u16,
    /// The axes a Haas mill's G101 mirrors: G100 ends the mirror of the axes it names, the
    /// mirror is in force until it has ended every one (Haas VF Series manual 96-8000, G101:
    /// the mirror selected per axis; review 16b, finding 2).
    haas_mirrored: u16,
    /// The axes of `mirrored` and `haas_mirrored` whose mirror a cancel with an axis word the
    /// walk does not know (`G50.1 X#1`, `G100 X[0]`) may have ended ([`Walk::mirror_off`]).
    mirror_doubt: u16,
    haas_mirror_doubt: u16,
    /// A FANUC's or Haas's G68 with I, J or K in force: the 3-D coordinate conversion (a
    /// rotation about the vector I J K), under which a move of one of X, Y, Z moves all three.
    rotation_3d: bool,
    /// A lathe's last moves of the tool in use (the last first, at most [`MOVES_KEPT`]): the
    /// way the program reached its start point with this tool, for an approach that goes the
    /// same way. A tool change (a T word or M06 on a lathe) clears them: the moves before it
    /// are another tool's path (its length, width and shape), not a clear way for this one.
    pub moves: Vec<Move>,
    /// The line of a lathe's last tool change (T word or M06): the first move after it starts
    /// from where the previous tool left the turret.
    pub tool_change: Option<usize>,
    /// Whether the tool has moved X or Z since that tool change (a restart before its first
    /// move starts at the previous tool's point).
    pub tool_moved: bool,
    /// A lathe's lane: the largest X the tool in use went to, and the ranges of Z it moved
    /// along Z at that X (all in mm, the ranges merged). A rapid along Z there, from the
    /// clearance plane to a Z within a range that reaches the program's highest Z, goes where
    /// the program itself went; a diameter reached only radially (an ID groove's bottom) has
    /// no range. Cleared at a tool change.
    pub lane: Option<(Dec, Vec<(Dec, Dec)>)>,
    /// The units the lane was followed in: a change of units clears it (the first move after
    /// it starts at a number written in the other units).
    lane_units: Units,
    /// LinuxCNC's diameter mode G7 / radius mode G8 as the program last selected it, and where
    /// (LinuxCNC G-code reference, "G7 Lathe Diameter Mode", "G8 Lathe Radius Mode"): the
    /// preamble selects it again, or X is read as half or twice the program's.
    pub diameter_mode: Option<(i64, usize)>,
    /// The line of a G7/G8 that changed the mode after X had a position: the X in force, the
    /// highest X and the moves were written in the other mode, which the walk does not convert.
    pub diameter_switch: Option<usize>,
    /// An increment of X read while [`Walk::diameter_switch`] was pending: the X reached
    /// counts from a number of the other mode, and the largest X from then on is not known,
    /// so the switch stays noted after X is written again.
    diameter_kept: bool,
    /// The G7/G8 switch's line and the line that wrote X again after it, as an absolute
    /// number of the new mode: that block's move starts at the old mode's number (marked as a
    /// first move, [`Move::first`]), which the planner names.
    pub diameter_rewritten: Option<(usize, usize)>,
    /// A FANUC lathe's multiple repetitive cycles in their two-block form: per set of data
    /// ([`two_block_cycle`]), the line of the last first block read. Its data stay in the
    /// control's parameters for every later second block, which a restart at a second block
    /// would run without.
    pub cycle_data: Vec<(i64, usize)>,
}

/// A FANUC lathe's multiple repetitive cycle in its two-block form (FANUC 0i-TF operator's
/// manual, "Multiple repetitive cycle"): the first block (G71 U R, G72 W R, G73 U W R, G74 R,
/// G75 R, G76 P Q R) sets the depth of cut, retract, pass count, thread data, which the control
/// keeps as parameters ("this designation is modal ... the parameter is changed by the program
/// command"); the second (G71-G73 with P and Q, G74-G76 with X(U) or Z(W)) runs the cycle with
/// them. Gives the code naming the set of data the block's cycle uses (G71 and G72 share the
/// depth of cut and retract, parameters 5132/5133; G74 and G75 the return, 5139) and whether
/// the block is a first block; None for a block of neither form (a one-block form as a Haas
/// writes it, with D, is a second block with no first block before it).
pub fn two_block_cycle(gs: &[i64], letters: &[u8]) -> Option<(i64, bool)> {
    let &code = gs.iter().find(|g| (71..=76).contains(*g))?;
    let has = |l: u8| letters.contains(&l);
    let second = match code {
        71..=73 => has(b'P') && has(b'Q'),
        _ => [b'X', b'Z', b'U', b'W'].iter().any(|&l| has(l)),
    };
    let data = match code {
        72 => 71,
        75 => 74,
        c => c,
    };
    if second {
        Some((data, false))
    } else if [b'U', b'W', b'R', b'P', b'Q'].iter().any(|&l| has(l)) {
        Some((data, true))
    } else {
        None
    }
}

/// How many separate Z ranges of the lane ([`Walk::lane`]) the walk keeps.
pub const LANE_RANGES: usize = 16;

/// How many of a lathe's last moves the walk keeps for the approach.
pub const MOVES_KEPT: usize = 8;

/// One move of X and Z on a lathe: from, to, its motion code and line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Move {
    pub from: [Option<Dec>; 2],
    pub to: [Option<Dec>; 2],
    pub motion: Option<i64>,
    pub line: usize,
    /// The first move after a tool change: `from` is where the previous tool left the turret,
    /// a point this tool has not been at.
    pub first: bool,
}

/// A plain number word, `X-12.5`: a letter, a sign, digits with at most one `.` (the regex
/// `[A-Za-z][+-]?(?:\d+\.?\d*|\.\d+)$`).
pub fn plain(token: &[u8]) -> bool {
    let Some((&first, rest)) = token.split_first() else {
        return false;
    };
    if !first.is_ascii_alphabetic() {
        return false;
    }
    let rest = match rest.first() {
        Some(b'+' | b'-') => &rest[1..],
        _ => rest,
    };
    let whole = rest.iter().take_while(|c| c.is_ascii_digit()).count();
    let after = &rest[whole..];
    if whole > 0 {
        match after.split_first() {
            None => true,
            Some((b'.', fraction)) => fraction.iter().all(u8::is_ascii_digit),
            Some(_) => false,
        }
    } else {
        matches!(after.split_first(), Some((b'.', f)) if !f.is_empty()
            && f.iter().all(u8::is_ascii_digit))
    }
}

/// A SINUMERIK tool name, `T="MILL10"`: a constant (840D tool management), not a parameter.
fn quoted_name(token: &[u8]) -> bool {
    token.len() > 4
        && token[1] == b'='
        && token[2] == b'"'
        && token.last() == Some(&b'"')
        && !token[3..token.len() - 1].contains(&b'"')
}

/// An indexed address, `X1=3` (the regex `[A-Za-z]\d+=` at the start).
fn indexed(token: &[u8]) -> bool {
    let digits = token
        .iter()
        .skip(1)
        .take_while(|c| c.is_ascii_digit())
        .count();
    token.first().is_some_and(u8::is_ascii_alphabetic)
        && digits > 0
        && token.get(1 + digits) == Some(&b'=')
}

/// The value of a plain `G` or `M` word's number, `token[1:]`: (whole part truncated toward
/// zero, saturated; the fraction without trailing zeros, empty when whole; the sign).
fn code_number(number: &[u8]) -> (i64, Vec<u8>, bool) {
    let (negative, digits) = match number.first() {
        Some(b'-') => (true, &number[1..]),
        Some(b'+') => (false, &number[1..]),
        _ => (false, number),
    };
    let dot = digits
        .iter()
        .position(|&c| c == b'.')
        .unwrap_or(digits.len());
    let whole = digits[..dot].iter().fold(0i64, |n, &c| {
        n.saturating_mul(10).saturating_add(i64::from(c - b'0'))
    });
    let mut fraction = digits.get(dot + 1..).unwrap_or(&[]).to_vec();
    while fraction.last() == Some(&b'0') {
        fraction.pop();
    }
    (if negative { -whole } else { whole }, fraction, negative)
}

/// The significant digits of a number as written (`+054.10`: 4), leading zeros left out.
fn significant(number: &[u8]) -> usize {
    let digits: Vec<u8> = number.iter().copied().filter(u8::is_ascii_digit).collect();
    digits.iter().skip_while(|&&c| c == b'0').count()
}

/// A sequence number or P word's digits as a whole number (`0100`: 100); None if not whole.
fn whole_number(digits: &[u8]) -> Option<i64> {
    crate::text::digits_value(digits).and_then(|n| i64::try_from(n).ok())
}

fn bit(axis: usize) -> u16 {
    1 << axis
}

fn letter_index(letter: u8) -> usize {
    usize::from(letter - b'A')
}

impl Walk {
    pub fn new(control: Control, lathe: bool, fanuc_lathe: bool) -> Walk {
        Walk {
            control,
            lathe,
            fanuc_lathe,
            okuma_lathe: lathe && control.family() == Family::Okuma,
            lap_contour: None,
            data_input: crate::dialect::DataInput::for_control(
                control.family(),
                control == Control::Haas,
            ),
            dwell: crate::word::dwell_words(control.family(), fanuc_lathe),
            before: [None; 9],
            held: [None; 9],
            contour_next: None,
            contour: None,
            thread: None,
            okuma_work: None,
            okuma_length: None,
            cycle_r: None,
            flow: None,
            unrestored: Vec::new(),
            lost: Default::default(),
            unknown: Default::default(),
            seen: 0,
            t_token: None,
            spindle_t: None,
            m6: None,
            h: None,
            g43_line: 0,
            d_token: None,
            work: None,
            arc_absolute: false,
            comp_line: 0,
            cycle: None,
            high: [None, None],
            too_long: None,
            written: [None; 26],
            z_reached: None,
            units_settings: None,
            decimal_codes: None,
            lacks_m: None,
            m_modes: Vec::new(),
            mode_hints: Vec::new(),
            orient_codes: Vec::new(),
            oriented: None,
            orientations: Vec::new(),
            side_move: None,
            mode_since_spin: None,
            builder_m: None,
            spin_line: 0,
            turn_codes: Vec::new(),
            turned_by: None,
            coolant_starts: Vec::new(),
            keyed_coolant: None,
            unread_spindle: Vec::new(),
            unread_spin: None,
            builder_first: 0,
            spindle_by_extension: None,
            setms: false,
            coolant_line: 0,
            unset: 0,
            polar_y: false,
            units_line: None,
            program_name: None,
            m6_line: 0,
            coolant: Vec::new(),
            transformed: 0,
            haas_cylinder: 0,
            shifted: 0,
            mirrored: 0,
            haas_mirrored: 0,
            mirror_doubt: 0,
            haas_mirror_doubt: 0,
            rotation_3d: false,
            moves: Vec::new(),
            tool_change: None,
            tool_moved: true,
            lane: None,
            lane_units: Units::Metric,
            diameter_mode: None,
            diameter_switch: None,
            cycle_data: Vec::new(),
            diameter_kept: false,
            diameter_rewritten: None,
        }
    }

    /// The line of the first M19 of the orientation in force (a second M19 does not end
    /// one), or None.
    pub fn oriented_since(&self) -> Option<usize> {
        match self.orientations.last() {
            Some(&(at, None)) => Some(at),
            _ => None,
        }
    }

    /// A SINUMERIK's `M<n>=<code>` on `line` (`token`): a function of the spindle's modal
    /// group (M3, M4, M5, M19, M70; Function Manual S1) by its address extension, or one whose
    /// code is not a constant, is one the modal state does not follow.
    fn spindle_extension(&mut self, line: usize, token: &[u8]) {
        let digits = token[1..].iter().take_while(|c| c.is_ascii_digit()).count();
        let value = &token[2 + digits..];
        let spindle_code = if plain(&[b"M", value].concat()) {
            let (whole, fraction, _) = code_number(value);
            fraction.is_empty() && matches!(whole, 3 | 4 | 5 | 19 | 70)
        } else {
            true
        };
        if spindle_code {
            let extension = token[1..1 + digits].iter().fold(0u64, |n, &c| {
                n.saturating_mul(10).saturating_add(u64::from(c - b'0'))
            });
            let master = extension == 0 || (extension == 1 && !self.setms);
            self.by_extension(line, token, master);
        }
    }

    /// A spindle function by extension or position on `line` (`text`), see
    /// [`Walk::spindle_by_extension`].
    fn by_extension(&mut self, line: usize, text: &[u8], master: bool) {
        let (first, master) = match &self.spindle_by_extension {
            Some((first, _, _, was)) => (*first, master && *was),
            None => (line, master),
        };
        self.spindle_by_extension = Some((first, line, text.to_vec(), master));
    }

    /// An M03, M04, M05 or a tool change on `line` ends the orientation in force.
    fn orientation_ended(&mut self, line: usize) {
        self.oriented = None;
        if let Some(last) = self
            .orientations
            .last_mut()
            .filter(|(_, end)| end.is_none())
        {
            last.1 = Some(line);
        }
    }

    /// `line`, or where an orientation in force at it began: a restart at `line` walks the
    /// lines before it, so one whose first M19 is before it and that no line before it ended
    /// refuses it; the first M19's own line is no such restart (review 38, finding 5).
    pub fn before_orientation(&self, mut line: usize) -> usize {
        while let Some(&(at, _)) = self
            .orientations
            .iter()
            .rev()
            .find(|&&(at, end)| at < line && end.is_none_or(|end| end >= line))
        {
            line = at;
        }
        line
    }

    /// A lathe whose G50 S is the spindle clamp, G50 X Z a coordinate setting, and U W the
    /// increments of X Z: Fanuc, Haas and Okuma (5238-E: "G50 ... maximum spindle speed").
    fn g50_lathe(&self) -> bool {
        self.fanuc_lathe || self.okuma_lathe
    }

    /// The axis a word moves: on a Fanuc, Haas or Okuma lathe U and W are X and Z incremental.
    fn axis(&self, letter: u8) -> u8 {
        match letter {
            b'U' if self.g50_lathe() => b'X',
            b'W' if self.g50_lathe() => b'Z',
            _ => letter,
        }
    }

    fn lose(&mut self, axis: u8, machine: bool, line: usize, what: Why, replay: (String, Vec<u8>)) {
        if let Some(i) = axis_index(axis) {
            self.lost[i] = Some(Lost {
                machine,
                frame: false,
                cycle: false,
                line,
                what,
                replay,
            });
        }
    }

    fn lose_unknown(&mut self, axis: u8, line: usize, what: Vec<u8>) {
        self.lose(
            axis,
            false,
            line,
            Why::Text(what),
            (String::new(), Vec::new()),
        );
    }

    /// A change of work coordinate system (`code`, on `line`): every axis that has had a
    /// position, and is not already lost, holds a place of the old system.
    fn frame_change(&mut self, line: usize, code: String) {
        for i in 0..AXES.len() {
            if self.seen & bit(i) != 0 && self.lost[i].is_none() {
                self.lost[i] = Some(Lost {
                    machine: false,
                    frame: true,
                    cycle: false,
                    line,
                    what: Why::Text(code.clone().into_bytes()),
                    replay: (String::new(), Vec::new()),
                });
            }
        }
    }

    /// An Okuma mill's `G16 H n` (a work system for its block only; OSP List of G Codes): an
    /// axis the block moves stands at a place of that system, and from the next block on the
    /// program's numbers are those of the `G15 H` system again, whose offset from the other
    /// is not known. Lost as after a change of work system, until an absolute position.
    fn one_block_work_system(&mut self, line: usize, tokens: &[&[u8]]) {
        let h = tokens
            .iter()
            .find(|t| t.first().is_some_and(|c| c.eq_ignore_ascii_case(&b'H')))
            .map(|t| String::from_utf8_lossy(t).into_owned());
        let what = match h {
            Some(h) => format!("G16 {h} (a work coordinate system for one block)"),
            None => "G16 (a work coordinate system for one block)".to_string(),
        };
        for &token in tokens {
            let Some(letter) = token.first().map(u8::to_ascii_uppercase) else {
                continue;
            };
            if let Some(i) = AXES.contains(&letter).then(|| axis_index(letter)).flatten() {
                self.lost[i] = Some(Lost {
                    machine: false,
                    frame: true,
                    cycle: false,
                    line,
                    what: Why::Text(what.clone().into_bytes()),
                    replay: (String::new(), Vec::new()),
                });
            }
        }
    }

    /// A Haas machining centre: G101 mirrors, G100 cancels it (Haas mill operator's manual).
    fn haas_mill(&self) -> bool {
        self.control == Control::Haas && !self.lathe
    }

    /// Whether a rotation, scaling or mirror image is in force.
    fn transforms_on(&self) -> bool {
        self.unrestored.iter().any(|(k, _, _)| {
            matches!(
                k.as_str(),
                "68" | "51" | "51.1" | "51.1?" | "101" | "101?" | "11" | "69" | "62"
            ) || TILTED_PLANES.contains(&k.as_str())
                || INTERPOLATED_PLANES.contains(&k.as_str())
        })
    }

    /// `code` on `line` ends the interpolation in force under `key` ([`INTERPOLATED_PLANES`]),
    /// if any: the axes moved under it are lost as at a transform's cancel.
    fn interpolation_cancel(&mut self, key: &str, line: usize, code: &str) {
        let was = self.unrestored.iter().any(|(k, _, _)| k == key);
        self.drop_unrestored(key);
        if was {
            let name = if key == "7.1" {
                "cylindrical interpolation"
            } else {
                "polar coordinate interpolation"
            };
            self.transform_cancel(line, code, name, 0);
            if key == "12.1" && self.lathe {
                // (review 35, finding 8) the polar interpolation turns the program's plane into
                // X and C moves: C stands where the control turned it. A Haas lathe's Y under
                // G112 is the plane's virtual axis (Autodesk's HAAS Lathe post writes Y only
                // under G112, "required for G112"): no place after G113, unless Y had one
                // before (a Y-axis lathe's real Y, whose number the modal state no longer has)
                let what =
                    format!("{code} ends the {name}: the control turned C for the moves under it");
                if axis_index(b'C').is_some_and(|i| self.lost[i].is_none()) {
                    self.lose_unknown(b'C', line, what.into_bytes());
                }
                if self.control == Control::Haas && !self.polar_y {
                    if let Some(i) = axis_index(b'Y') {
                        self.lost[i] = None;
                        self.unset |= bit(i);
                    }
                }
            }
        }
    }

    /// FANUC's G07.1 (a lathe's G107) with the rotary axis's cylinder radius starts the
    /// cylindrical interpolation; with the radius 0, or no rotary or R word, it ends it; a
    /// Haas's G107 with any axis, Q or R word starts it, and with none ends it. A radius set
    /// by a parameter (`C#1`, bits of `param_axes`) counts as given.
    fn cylindrical(&mut self, line: usize, code: &str, plain_words: &[(u8, &[u8])], params: u16) {
        // (a Haas lathe's G107 gives the radius as R: Haas lathe operator's manual; a FANUC
        // lathe's G07.1 H the radius by C's incremental address in G code system A, the lathe
        // manual's `G07.1 H57299`: review 33, finding 3, it was read as a cancel)
        let rotary = [b'A', b'B', b'C'];
        let radius = plain_words.iter().any(|&(l, t)| {
            (rotary.contains(&l) || matches!(l, b'R' | b'H'))
                && t[1..].iter().any(|c| !b"+-0.".contains(c))
        }) || rotary
            .iter()
            .any(|&a| axis_index(a).is_some_and(|i| params & bit(i) != 0));
        // the block's other axis words are read as the code's data by the modal state, where
        // the control may move them: not known (review 33, finding 4: `G07.1 C0 G00 X60. Z5.`
        // left the tool at the block before's X Z)
        for &(letter, token) in plain_words {
            if AXES.contains(&letter) && !rotary.contains(&letter) {
                let mut why = token.to_vec();
                why.extend_from_slice(format!(" in a {code} block").as_bytes());
                let axis = self.axis(letter);
                self.lose_unknown(axis, line, why);
            }
        }
        // A Haas's G107 (mill 96-8000, "G107 Cylindrical Mapping"; the lathe's alike) turns the
        // mapping on when it names an axis, whatever its value (the values only name the
        // axes; Q the diameter, R the radius, else the last or the setting's), and off only
        // with no address: any axis, Q or R word is taken as on (review 34, finding 1:
        // `G107 Y0 A0 Q2.` was read as the cancel; `G107 A0 R2.`, which only sets the
        // diameter, is refused so too, the safe side)
        let on = if self.control == Control::Haas {
            params != 0
                || plain_words
                    .iter()
                    .any(|&(l, _)| AXES.contains(&l) || matches!(l, b'Q' | b'R'))
        } else {
            radius
        };
        if on {
            if self.control == Control::Haas {
                // (review 35, finding 4) the mapping turns the rotary axis for the moves of the
                // linear one ("translates all programmed motion occurring in a specified linear
                // axis into the equivalent motion along the surface of a cylinder", Haas mill
                // manual, G107): its word here names the axis, no position, and it is lost at
                // the cancel. With none named, every rotary axis the program has moved (or all)
                let mut named = rotary
                    .iter()
                    .filter(|&&a| {
                        plain_words.iter().any(|&(l, _)| l == a)
                            || axis_index(a).is_some_and(|i| params & bit(i) != 0)
                    })
                    .filter_map(|&a| axis_index(a))
                    .fold(0u16, |m, i| m | bit(i));
                if named == 0 {
                    let all = rotary
                        .iter()
                        .filter_map(|&a| axis_index(a))
                        .fold(0u16, |m, i| m | bit(i));
                    named = if self.seen & all != 0 {
                        self.seen & all
                    } else {
                        all
                    };
                }
                self.transformed |= named;
                let linear = [b'X', b'Y', b'Z'];
                let mask = |pick: &dyn Fn(u8) -> bool| {
                    linear
                        .iter()
                        .filter(|&&a| pick(a))
                        .filter_map(|&a| axis_index(a))
                        .fold(0u16, |m, i| m | bit(i))
                };
                let given = mask(&|a| {
                    plain_words.iter().any(|&(l, _)| l == a)
                        || axis_index(a).is_some_and(|i| params & bit(i) != 0)
                });
                self.haas_cylinder = if given != 0 { given } else { mask(&|_| true) };
            }
            let what = format!("{code} (cylindrical interpolation)");
            self.set_unrestored("7.1", line, what);
        } else {
            self.interpolation_cancel("7.1", line, code);
        }
    }

    /// `code` on `line` ends the transform `name`: the axes moved under it stand at the
    /// transformed point (the control moves from there: FANUC's first move after G69 is
    /// absolute), which the modal state's number is not; unknown until an absolute move. The
    /// axes of `kept` stay under the transform (a mirror cancel naming other axes only): they
    /// are lost at the cancel that ends it, and that line is the one a refusal names (fix23:
    /// `G50.1 Y0` was named for X, whose mirror it left in force).
    fn transform_cancel(&mut self, line: usize, code: &str, name: &str, kept: u16) {
        for (i, &axis) in AXES.iter().enumerate() {
            if self.transformed & bit(i) & !kept != 0 && self.lost[i].is_none() {
                let what = format!(
                    "{code} ends the {name}: the tool stands where the transformed moves left \
                     it, not at the number the program wrote"
                );
                self.lose_unknown(axis, line, what.into_bytes());
            }
        }
        // the axes lost here are no longer under a transform: a later move of one is plain
        // unless a transform still in force moves it (review 26, finding 2: a Y given again
        // after its own mirror ended was lost at a later cancel of X's mirror)
        self.transformed &= kept;
        if !self.transforms_on() {
            self.transformed = 0;
        }
    }

    /// The axes a move of `bits` moves under a transform: all of them under a rotation,
    /// scaling or other transform, those mirrored (for certain or in doubt) where mirror
    /// images are the only transforms in force (a mirror of X leaves Y's numbers as written:
    /// FANUC G51.1, Haas G101 mirror the axes they name).
    fn under_transform(&self, bits: u16) -> u16 {
        // a Haas G107 maps its one linear axis onto the cylinder, the others move as written
        // (Haas mill manual, G107: "all programmed motion occurring in a specified linear
        // axis"; review 36, finding 8: a Z written under it was lost at the cancel)
        let haas = self.control == Control::Haas;
        let other = self.unrestored.iter().any(|(k, _, _)| {
            !(haas && k == "7.1")
                && (matches!(k.as_str(), "68" | "51" | "11" | "69" | "62")
                    || TILTED_PLANES.contains(&k.as_str())
                    || INTERPOLATED_PLANES.contains(&k.as_str()))
        });
        if other {
            return bits;
        }
        let cylinder = if haas && self.unrestored.iter().any(|(k, _, _)| k == "7.1") {
            self.haas_cylinder
        } else {
            0
        };
        bits & (self.mirrored
            | self.mirror_doubt
            | self.haas_mirrored
            | self.haas_mirror_doubt
            | cylinder)
    }

    /// A mirror cancel `code` (FANUC G50.1, Haas G100) on `line`, given the axes (bits of
    /// [`AXES`] indexes) `mirrored` before it and those of them whose mirror is not known
    /// (`doubt`): the same two after it. It ends the mirror of the axes its plain words name
    /// (`named`), of all of them when it has no axis word at all. An axis word whose value the
    /// walk does not know (`param_axes`: X#1, X[0]) leaves a mirrored axis's mirror not known
    /// (review 19, finding 1: `G100 X#1` was read as a cancel naming no axis, so as ending every
    /// mirror): an unrestored mode under `keys.1` (the restart is refused) until a cancel names
    /// the axis plainly or ends them all; with no plain axis word beside it, every mirrored
    /// axis (a vacant variable drops its address: the block may name none, ending them all).
    /// `keys.0` is the mirror's own unrestored mode, kept while an axis is mirrored for
    /// certain.
    fn mirror_off(
        &mut self,
        line: usize,
        code: &str,
        keys: (&str, &str),
        (mirrored, doubt): (u16, u16),
        named: u16,
        param_axes: (u16, Option<&[u8]>),
    ) -> (u16, u16) {
        let (unknown, token) = param_axes;
        if named == 0 && unknown == 0 {
            self.drop_unrestored(keys.0);
            self.drop_unrestored(keys.1);
            return (0, 0);
        }
        let left = mirrored & !named;
        // (review 22, finding 2) a block whose only axis words are not known here may be a
        // bare cancel (a vacant variable drops its address on Custom Macro B), which ends
        // every mirror: none is then mirrored for certain
        let maybe = if named == 0 { left } else { left & unknown };
        let fresh = maybe & !doubt;
        let was = doubt;
        let doubt = (doubt & !named) | maybe;
        if left & !doubt == 0 {
            self.drop_unrestored(keys.0);
        }
        let axes = |bits: u16| -> String {
            (0..AXES.len())
                .filter(|&i| bits & bit(i) != 0)
                .map(|i| char::from(AXES[i]))
                .collect()
        };
        if doubt == 0 {
            self.drop_unrestored(keys.1);
        } else if fresh != 0 {
            let what = format!(
                "the mirror image of {}, which {code} {} may or may not have ended (an \
                 axis word whose value the restart does not know),",
                axes(doubt),
                String::from_utf8_lossy(token.unwrap_or_default())
            );
            self.set_unrestored(keys.1, line, what);
        } else if doubt != was {
            // (review 23) a plain cancel of some of the doubtful axes: the refusal names
            // those still in doubt, of the cancel that made the doubt
            let (old, new) = (axes(was), axes(doubt));
            if let Some(entry) = self.unrestored.iter_mut().find(|(k, _, _)| k == keys.1) {
                entry.2 = entry.2.replacen(
                    &format!("the mirror image of {old},"),
                    &format!("the mirror image of {new},"),
                    1,
                );
            }
        }
        (left, doubt)
    }

    fn set_unrestored(&mut self, key: &str, line: usize, what: String) {
        match self.unrestored.iter_mut().find(|(k, _, _)| k == key) {
            Some(entry) => *entry = (key.to_string(), line, what),
            None => self.unrestored.push((key.to_string(), line, what)),
        }
    }

    fn drop_unrestored(&mut self, key: &str) {
        self.unrestored.retain(|(k, _, _)| k != key);
    }

    /// What the core forgets at a statement it does not follow: position, feed, speed.
    fn forget(&mut self, line: usize, text: &[u8]) {
        for (i, &axis) in AXES.iter().enumerate() {
            if self.seen & bit(i) != 0 {
                let what = Why::Statement(text.to_vec(), line);
                self.lose(axis, false, line, what, (String::new(), Vec::new()));
            }
        }
        for letter in [b'F', b'S'] {
            self.unknown[letter_index(letter)] = Some(Why::Statement(text.to_vec(), line));
        }
    }

    /// Read one block, after the checker's modal state machine has read it (`after` is its
    /// state then).
    pub fn step(&mut self, b: &Step<'_>, after: &ModalState) {
        if b.tokens.is_empty() && !b.extras {
            return;
        }
        let line = b.line;
        let words = b
            .tokens
            .iter()
            .filter(|t| t.first().is_some_and(u8::is_ascii_alphabetic))
            .map(|t| (t[0], &t[1..]));
        match self.data_input.block(self.control.family(), line, words) {
            crate::dialect::DataBlock::Data { closes, .. } => {
                if closes {
                    self.drop_unrestored("data");
                }
                return;
            }
            crate::dialect::DataBlock::Stray { .. } => self.drop_unrestored("data"),
            crate::dialect::DataBlock::Lacked { .. } => {}
            crate::dialect::DataBlock::Program => {
                if let Some((_, l)) = self.data_input.open() {
                    let what = format!("the G10 L{l} data input mode (data blocks up to its G11)");
                    self.set_unrestored("data", line, what);
                }
            }
        }
        let mut gs: Vec<i64> = Vec::new();
        let mut gdec: Vec<Vec<u8>> = Vec::new();
        let mut ms: Vec<i64> = Vec::new();
        // letter -> its first plain word, in the order the letters first appear
        let mut plain_words: Vec<(u8, &[u8])> = Vec::new();
        // the axes (bits of [`AXES`] indexes) whose words are not plain (X#1, X[0]), and the
        // first such word: a mirror code's axes whose value the walk does not know
        let mut param_axes: (u16, Option<&[u8]>) = (0, None);
        let mut param_code = false;
        for &token in b.tokens {
            let Some(&first) = token.first() else {
                continue;
            };
            if !first.is_ascii_alphabetic() {
                continue; // ":1000", an alignment label
            }
            let letter = first.to_ascii_uppercase();
            if letter == b'T' && self.control == Control::Sinumerik && quoted_name(token) {
                // T="MILL10": the tool's name, a constant (840D tool management)
                if !plain_words.iter().any(|&(l, _)| l == letter) {
                    plain_words.push((letter, token));
                }
                self.unknown[letter_index(letter)] = None;
                continue;
            }
            if !plain(token) {
                if letter == b'M' && self.control == Control::Sinumerik && indexed(token) {
                    self.spindle_extension(line, token);
                }
                if matches!(letter, b'G' | b'M') && matches!(token.get(1), Some(b'#' | b'[')) {
                    // G#1, G[68.2], M#500: a code set by a parameter, so which code ran is not
                    // known (review 32, finding 1: the rotation or tilt it sets was left out)
                    param_code = true;
                }
                if !indexed(token) && !b"GMNO".contains(&letter) {
                    // F#101, X[#1+2], X=R1+5: a value set by a parameter
                    let mut why = token.to_vec();
                    if AXES.contains(&letter) {
                        if let Some(i) = axis_index(letter) {
                            param_axes.0 |= bit(i);
                            param_axes.1.get_or_insert(token);
                        }
                        why.extend_from_slice(b", set by a parameter");
                        let axis = self.axis(letter);
                        self.lose_unknown(axis, line, why);
                    } else {
                        why.extend_from_slice(
                            format!(" on line {line} sets it by a parameter").as_bytes(),
                        );
                        self.unknown[letter_index(letter)] = Some(Why::Text(why));
                    }
                }
                continue;
            }
            if letter == b'G' || letter == b'M' {
                let (whole, fraction, negative) = code_number(&token[1..]);
                if letter == b'M' {
                    ms.push(whole);
                    if whole == 6 {
                        self.m6 = Some(token.to_vec());
                        self.m6_line = line;
                    }
                    match whole {
                        7 | 8 => {
                            self.coolant.retain(|&m| m != whole);
                            self.coolant.push(whole);
                            self.coolant_line = line;
                        }
                        9 => {
                            self.coolant.clear();
                            self.keyed_coolant = None;
                        }
                        2 | 30 => self.keyed_coolant = None,
                        _ => {}
                    }
                } else if fraction.is_empty() {
                    gs.push(whole);
                } else if significant(&token[1..]) > 28 {
                    // more digits than the code table's names were compared with: not a mode
                    // the walk can name, so none the preamble restores
                    let what = format!(
                        "{} (a code of more than 28 digits)",
                        String::from_utf8_lossy(token)
                    );
                    self.set_unrestored("long", line, what);
                } else {
                    let mut text = Vec::new();
                    if negative {
                        text.push(b'-');
                    }
                    text.extend_from_slice(whole.unsigned_abs().to_string().as_bytes());
                    text.push(b'.');
                    text.extend_from_slice(&fraction);
                    gdec.push(text);
                }
                continue;
            }
            if !plain_words.iter().any(|&(l, _)| l == letter) {
                plain_words.push((letter, token));
            }
            self.unknown[letter_index(letter)] = None;
        }
        // a plain F or S whose value the checker could not take (`S2.` beside an M code that
        // may be a macro call: an argument, or the control's alarm): not known in force
        for letter in [b'F', b'S'] {
            if after.is_unknown(letter) && self.unknown[letter_index(letter)].is_none() {
                if let Some(&(_, token)) = plain_words.iter().find(|&&(l, _)| l == letter) {
                    let mut why = token.to_vec();
                    why.extend_from_slice(
                        format!(" on line {line}, a value the check takes as unknown").as_bytes(),
                    );
                    self.unknown[letter_index(letter)] = Some(Why::Text(why));
                }
            }
        }
        if self.program_name.is_none() {
            let text = b.text.trim_ascii();
            if text.starts_with(b"%_N_") {
                self.program_name = Some(text.to_vec());
            } else if let Some(&(_, o)) = plain_words.iter().find(|&&(l, _)| l == b'O') {
                self.program_name = Some(o.to_vec());
            }
        }
        if let Some(settings) = &self.units_settings {
            if gs.iter().any(|&g| settings.units_code(g).is_some()) {
                self.units_line = Some(line);
            }
        }
        if self.contour_block(&plain_words) {
            return;
        }
        if self.flow.is_none() {
            for &(kind, text) in b.statements {
                let upper = text.to_ascii_uppercase();
                let goto = upper.windows(4).any(|w| w == b"GOTO");
                if kind == Kind::Flow && conditional_body(text).is_some() && !goto {
                    self.forget(line, text); // IF [..] THEN #n = ..: sets a value, no jump
                } else if kind.unfollowed()
                    || (kind == Kind::Command && self.control == Control::Sinumerik)
                {
                    self.flow = Some(Flow {
                        line,
                        text: text.to_vec(),
                        kind: kind.name(),
                        block: false,
                    });
                    break;
                }
            }
        }
        let has_plain = |letter: u8| plain_words.iter().any(|&(l, _)| l == letter);
        if self.flow.is_none()
            && (ms.iter().any(|m| matches!(m, 97 | 98))
                || gs.iter().any(|g| matches!(g, 65 | 66))
                || (self.control == Control::Sinumerik && has_plain(b'L')))
        {
            self.flow = Some(Flow {
                line,
                text: b.text.to_vec(),
                kind: "call",
                block: true,
            });
        }
        // a G code the control's table does not hold: the control alarms on it, or its
        // parameters make it a macro call (FANUC 6050-6059), so what ran after it is not known
        let lacked = self
            .units_settings
            .as_ref()
            .is_some_and(|settings| gs.iter().any(|&g| settings.lacks(g)))
            || self
                .decimal_codes
                .as_ref()
                .is_some_and(|held| gdec.iter().any(|d| !held.contains(d)));
        if self.flow.is_none() && lacked {
            self.flow = Some(Flow {
                line,
                text: b.text.to_vec(),
                kind: "code",
                block: true,
            });
        }
        if self.flow.is_none() && param_code {
            self.flow = Some(Flow {
                line,
                text: b.text.to_vec(),
                kind: "parameter code",
                block: true,
            });
        }
        // An unlisted M code is read as a macro call only where the block carries a word its
        // block cannot use otherwise: a P or Q (a subprogram call by M code, or the builder's
        // own data), an I, J, K, R or E where no arc or cycle is in force (argument
        // specification I or II: review 34, finding 4, `M165 I1. Z-3. S2`), or a point in
        // S, T, D or H (none of them a value those take). A builder's M code beside a plain
        // speed or tool (`S300 M45`, `T0101 M16`) is the control's own function, as the
        // check reads it (TG307).
        let arguments = || {
            let arcs = matches!(after.motion, Some(2 | 3)) || after.cycle.is_some();
            plain_words.iter().any(|&(l, t)| {
                matches!(l, b'P' | b'Q')
                    || (!arcs && matches!(l, b'I' | b'J' | b'K' | b'R' | b'E'))
                    || (matches!(l, b'S' | b'T' | b'D' | b'H') && t.contains(&b'.'))
            })
        };
        for &m in &ms {
            let Some((_, mode, on, function)) =
                self.m_modes.iter().find(|(code, ..)| *code == m).cloned()
            else {
                continue;
            };
            if on {
                if !self.unrestored.iter().any(|(k, _, _)| k == mode) {
                    // (review 35, finding 10) where a restart can be made instead: at or before
                    // the block of the first of these codes still in force (it is sent as
                    // written, the tool and the moves before it restored), or after the codes
                    // that end the modes. Not the tool change before it: the code may come
                    // before the live tool's T word, and that change is the tool before
                    // (review 36, finding 7)
                    // (review 37, finding 7) nor where that block is refused itself: before
                    // an M19 still in force, and, after a C or Y move of this tool (the way
                    // in is not known from there), at its tool change
                    let mut first = self
                        .unrestored
                        .iter()
                        .filter(|(k, _, _)| self.m_modes.iter().any(|(_, m, _, _)| m == k))
                        .map(|&(_, l, _)| l)
                        .fold(line, usize::min);
                    if self.side_move.is_some() {
                        let since = self.mode_since_spin.unwrap_or(line);
                        first = first.min(self.tool_change.map_or(since, |t| t.min(since)));
                    }
                    // (review 38, finding 5) and not under an orientation in force there:
                    // at or before its first M19, whichever line the min above came to
                    let first = self.before_orientation(first);
                    let before = format!("line {first}");
                    let ends: Vec<String> = self
                        .m_modes
                        .iter()
                        .filter(|(_, _, on, _)| !on)
                        .map(|(code, _, _, _)| format!("M{code}"))
                        .collect();
                    let hint = format!(
                        "restart at or before {before}, or after the {} that end{}",
                        ends.join(" and "),
                        if ends.len() == 1 {
                            "s it"
                        } else {
                            " the modes"
                        }
                    );
                    self.mode_hints.retain(|(k, _)| *k != mode);
                    self.mode_hints.push((mode, hint));
                }
                self.mode_since_spin.get_or_insert(line);
                self.set_unrestored(mode, line, format!("M{m} ({function})"));
            } else {
                self.drop_unrestored(mode);
                if mode == "C axis" {
                    // (review 35, finding 9) C disengaged: no place of C to go to
                    if let Some(i) = axis_index(b'C') {
                        self.lost[i] = None;
                        self.unset |= bit(i);
                    }
                }
            }
        }
        if self.control == Control::Sinumerik {
            for &(kind, text) in b.statements {
                let upper = text.to_ascii_uppercase();
                let name = &upper[..crate::statement::ident_end(&upper, 0)];
                if name == b"SETMS" {
                    self.setms = true;
                }
                // SPOS=90, SPOSA[2]=0: the spindle positioned (position control, as M19), and
                // M[SPINU]=3, a spindle function of a spindle named by a variable
                let positions = matches!(name, b"SPOS" | b"SPOSA");
                if kind == Kind::Assignment && (positions || upper.starts_with(b"M[")) {
                    let master = positions && upper.get(name.len()) == Some(&b'=');
                    self.by_extension(line, text, master && !self.setms);
                }
            }
        }
        for &m in &ms {
            if matches!(m, 3..=5) || self.turn_codes.contains(&m) || self.orient_codes.contains(&m)
            {
                self.unread_spin = None;
                if self
                    .spindle_by_extension
                    .as_ref()
                    .is_some_and(|(.., master)| *master)
                {
                    self.spindle_by_extension = None;
                }
            } else if self.unread_spindle.contains(&m) {
                let first = self.unread_spin.map_or(line, |(first, ..)| first);
                self.unread_spin = Some((first, line, m));
            }
            if self.orient_codes.contains(&m) {
                self.oriented = Some((line, m));
                if self.oriented_since().is_none() {
                    self.orientations.push((line, None));
                }
            } else if matches!(m, 3..=5) || self.turn_codes.contains(&m) {
                // (a keyed start, a builder's M13, ends it as M03 does: review 56d F2)
                self.orientation_ended(line);
            }
            let turns = self.turn_codes.contains(&m);
            if matches!(m, 3..=5) || turns {
                self.turned_by = turns.then_some((line, m));
            }
            if self.coolant_starts.contains(&m) {
                self.keyed_coolant = Some((line, m));
            }
            if m == 5 && !self.lathe {
                // (a mill's M05 stops what a builder's M13 started; a lathe's live tool or C
                // axis mode stays)
                self.builder_m = None;
            }
            if matches!(m, 3 | 4) || turns {
                self.side_move = None;
                self.mode_since_spin = None;
                self.spin_line = line;
                self.builder_m = None; // (the main spindle turns: no live tool's mode)
            }
        }
        let unlisted_m = self
            .lacks_m
            .as_ref()
            .and_then(|lacks| {
                ms.iter().copied().find(|&m| {
                    usize::try_from(m)
                        .ok()
                        .is_none_or(|n| lacks.get(n).copied().unwrap_or(true))
                })
            })
            .filter(|_| arguments());
        if let Some(m) = unlisted_m {
            for &(letter, token) in &plain_words {
                let mut why = token.to_vec();
                why.extend_from_slice(
                    format!(
                        " on line {line}, beside M{m}, an M code the profile's list lacks: an argument of a \
                         macro call where the control's parameters make M{m} one (FANUC \
                         parameters 6080-6089, a Haas's M code aliases)"
                    )
                    .as_bytes(),
                );
                if AXES.contains(&letter) {
                    let axis = self.axis(letter);
                    self.lose_unknown(axis, line, why);
                } else if matches!(letter, b'S' | b'F' | b'T' | b'D' | b'H') {
                    self.unknown[letter_index(letter)] = Some(Why::Text(why));
                }
            }
        }
        let dwell: &[u8] = if gs.contains(&4) { self.dwell } else { &[] };
        for &(letter, _) in plain_words.iter().filter(|(l, _)| !dwell.contains(l)) {
            if letter == b'F' {
                self.written[letter_index(b'F')] = Some((after.feed_units, line));
            } else if AXES.contains(&letter) {
                let axis = self.axis(letter);
                self.written[letter_index(axis)] = Some((after.units, line));
                if axis == b'Z' {
                    self.z_reached = Some((after.motion, line));
                }
            }
        }
        if self.fanuc_lathe {
            // every letter, plain or not (G71 U#1 R1 is a first block as well)
            let letters: Vec<u8> = b
                .tokens
                .iter()
                .filter_map(|t| t.first().map(u8::to_ascii_uppercase))
                .collect();
            if let Some((data, true)) = two_block_cycle(&gs, &letters) {
                self.cycle_data.retain(|&(d, _)| d != data);
                self.cycle_data.push((data, line));
            }
        }
        self.modes(line, &gs, &gdec, &plain_words, param_axes, after.cycle);
        // any T word, plain or not (T#1 changes the tool as well)
        let tool_word = b
            .tokens
            .iter()
            .any(|t| t.first().is_some_and(|c| c.eq_ignore_ascii_case(&b'T')));
        self.tool(
            line,
            &gs,
            &ms,
            &plain_words,
            tool_word,
            matches!(after.spindle, 3 | 4),
            after.length_offset,
        );
        // (a mill's too: a builder's M code after the tool change may start the spindle,
        // review 56a F9)
        if !self.lathe || self.m_modes.is_empty() {
            if let Some(lacks) = &self.lacks_m {
                let builder = ms.iter().copied().rfind(|&m| {
                    usize::try_from(m)
                        .ok()
                        .is_none_or(|n| lacks.get(n).copied().unwrap_or(true))
                        && !self.orient_codes.contains(&m)
                });
                if let Some(m) = builder {
                    if self.builder_m.is_none_or(|(at, _)| at < self.m6_line) {
                        self.builder_first = line;
                    }
                    self.builder_m = Some((line, m));
                }
            }
        }
        // a mirror's axes, a G92 shift's cancel or restore, a tilted plane's origin: data,
        // no move
        let data = gdec.iter().any(|d| {
            matches!(
                d.as_slice(),
                b"51.1" | b"50.1" | b"92.1" | b"92.2" | b"92.3" | b"68.2" | b"68.3" | b"68.4"
            )
        }) || (self.haas_mill() && gs.iter().any(|&g| g == 100 || g == 101))
            // (a cylindrical interpolation's block: its rotary word is the radius, its other
            // axes lost in `cylindrical`, not set here -- review 33, finding 4)
            || (self.control.family() == Family::MacroB
                && (gs.contains(&107) || gdec.iter().any(|d| d.as_slice() == b"7.1")))
            // (a macro call's arguments, where the unlisted M code is one: lost above)
            || unlisted_m.is_some();
        self.positions(line, &gs, &plain_words, after, data);
        if self.control == Control::Okuma && !self.lathe && gs.contains(&16) {
            self.one_block_work_system(line, b.tokens);
        }
        self.home_return(b, &gs);
        self.before = after.position;
    }

    /// The first block whose data `tokens` (a block not yet read) runs its cycle with, when it
    /// is the second block of a two-block cycle ([`two_block_cycle`]) on a FANUC lathe: its
    /// own code and the first block's line. A restart there leaves that block out.
    pub fn cycle_first_block(&self, tokens: &[&[u8]]) -> Option<(i64, usize)> {
        if !self.fanuc_lathe {
            return None;
        }
        let mut gs = Vec::new();
        let mut letters = Vec::new();
        for &token in tokens {
            let Some(letter) = token.first().map(u8::to_ascii_uppercase) else {
                continue;
            };
            if letter != b'G' {
                letters.push(letter); // plain or not (P#1 is the cycle's P as well)
            } else if plain(token) {
                let (whole, fraction, _) = code_number(&token[1..]);
                if fraction.is_empty() {
                    gs.push(whole);
                }
            }
        }
        let code = *gs.iter().find(|g| (71..=76).contains(*g))?;
        match two_block_cycle(&gs, &letters)? {
            (data, false) => self
                .cycle_data
                .iter()
                .find(|&&(d, _)| d == data)
                .map(|&(_, line)| (code, line)),
            _ => None,
        }
    }

    /// A block of a FANUC or Haas lathe's G71-G73 contour (N P to N Q, right after the cycle):
    /// the cycle's data, no move. Its F, S and T count in G70 only, so the feed and speed in
    /// force after the contour are not followed; a restart inside it is refused.
    fn contour_block(&mut self, plain_words: &[(u8, &[u8])]) -> bool {
        let n = plain_words
            .iter()
            .find(|&&(l, _)| l == b'N')
            .and_then(|&(_, t)| whole_number(&t[1..]));
        if let Some((p, q, code, at)) = self.contour_next.take() {
            if n == Some(p) {
                self.contour = Some((q, code, at));
                let what = format!("the contour N{p} to N{q} of the cycle G{code} (its blocks are the cycle's data, no moves)");
                self.set_unrestored("contour", at, what);
            }
        }
        let Some((q, code, at)) = self.contour else {
            return false;
        };
        for &(letter, token) in plain_words {
            if letter == b'F' || letter == b'S' {
                let mut why = token.to_vec();
                why.extend_from_slice(
                    format!(
                        " in the contour of the cycle G{code} on line {at} (it counts in G70 only)"
                    )
                    .as_bytes(),
                );
                self.unknown[letter_index(letter)] = Some(Why::Text(why));
            }
        }
        if n == Some(q) {
            self.contour = None;
            self.drop_unrestored("contour");
        }
        true
    }

    /// An Okuma lathe's home position return (`G20 HP=1`, G21 to the tool change position,
    /// G24/G25 without interpolation; 5238-E's G code list) written alone: X and Z are at a
    /// place of the machine's parameters, which the preamble reaches by the same block, as a
    /// Fanuc lathe's by its G28 U0 W0. With other words in the block, they stay unknown.
    fn home_return(&mut self, b: &Step<'_>, gs: &[i64]) {
        if !gs.iter().any(|&g| matches!(g, 20 | 21 | 24 | 25)) {
            return;
        }
        let alone = gs.len() == 1
            && b.tokens
                .iter()
                .all(|t| t.first().is_some_and(|c| b"GgNn".contains(c)));
        if !self.okuma_lathe || !alone {
            return;
        }
        let text = b.text.split(|&c| c == b'(').next().unwrap_or_default();
        let mut words = text
            .split(u8::is_ascii_whitespace)
            .filter(|w| !w.is_empty() && !b"Nn".contains(&w[0]));
        let block: Vec<&[u8]> = words.by_ref().collect();
        let replay = String::from_utf8_lossy(&block.join(&b' ')).into_owned();
        for axis in [b'X', b'Z'] {
            let what = format!("{replay} (home position return)").into_bytes();
            self.lose(
                axis,
                true,
                b.line,
                Why::Text(what),
                (replay.clone(), Vec::new()),
            );
        }
    }

    fn modes(
        &mut self,
        line: usize,
        gs: &[i64],
        gdec: &[Vec<u8>],
        plain_words: &[(u8, &[u8])],
        param_axes: (u16, Option<&[u8]>),
        core_cycle: Option<i64>,
    ) {
        let axes: Vec<&[u8]> = plain_words
            .iter()
            .filter(|(l, _)| AXES.contains(l))
            .map(|&(_, t)| t)
            .collect();
        let okuma_mill = self.control == Control::Okuma && !self.lathe;
        let table: &[(i64, i64, &str)] = if okuma_mill {
            &OKUMA_UNRESTORED
        } else {
            &UNRESTORED
        };
        for &g in gs {
            if let Some(&(_, _, name)) = table.iter().find(|(c, _, _)| *c == g) {
                if !(g == 51 && self.lathe) {
                    // FANUC's G68 X Y Z I J K R: the 3-D coordinate conversion, a rotation
                    // about the vector I J K, whose moves of one axis move all three (the
                    // plane's rotation moves its two)
                    let space = g == 68
                        && plain_words
                            .iter()
                            .any(|&(l, _)| matches!(l, b'I' | b'J' | b'K'));
                    if g == 68 {
                        // a plane's G68 inside the 3-D conversion leaves it in force until
                        // G69: whether the control nests the two or replaces one is not in
                        // the sources, and either way X Y Z stay lost (review 31, doubtful)
                        self.rotation_3d |= space;
                    }
                    let name = if space {
                        "3-D coordinate conversion"
                    } else {
                        name
                    };
                    self.set_unrestored(&g.to_string(), line, format!("G{g} ({name})"));
                }
            }
            // (a Haas mill's G112/G113 are work systems 9 and 10: review 33, finding 1 -- a
            // FANUC mill's G112/G113/G107 and a Haas mill's G107 were planned past)
            if self.control.family() == Family::MacroB && !(self.haas_mill() && g != 107) {
                match g {
                    112 => {
                        if !self.unrestored.iter().any(|(k, _, _)| k == "12.1") {
                            self.polar_y = axis_index(b'Y')
                                .is_some_and(|i| self.seen & bit(i) != 0 || self.lost[i].is_some());
                        }
                        self.set_unrestored(
                            "12.1",
                            line,
                            "G112 (polar coordinate interpolation)".into(),
                        );
                    }
                    113 => self.interpolation_cancel("12.1", line, "G113"),
                    107 => self.cylindrical(line, "G107", plain_words, param_axes.0),
                    _ => {}
                }
            }
            if okuma_mill && g == 62 {
                // no page at hand names its cancel: in force to the end of the walk
                let what = "G62 (programmable mirror image)";
                self.set_unrestored("62", line, what.into());
            }
            for &(code, cancel, name) in table {
                if g == cancel && !(cancel == 50 && self.lathe) {
                    let was = self
                        .unrestored
                        .iter()
                        .any(|(k, _, _)| *k == code.to_string());
                    self.drop_unrestored(&code.to_string());
                    if code == 68 {
                        self.rotation_3d = false;
                    }
                    // (polar coordinates and air cut reduction move no axis off the program's
                    // coordinates: nothing is lost at their cancel)
                    if was && code != 16 && code != 38 {
                        self.transform_cancel(line, &format!("G{g}"), name, 0);
                    }
                }
            }
            let named = plain_words
                .iter()
                .filter_map(|&(letter, _)| axis_index(letter))
                .fold(0u16, |all, i| all | bit(i));
            if self.haas_mill() && g == 101 {
                // Haas G101 X0: the mirror image of X (Haas mill operator's manual, G101); a
                // G101 naming no axis is in no page at hand: taken to mirror them all, as the
                // check takes it, until a G100 (review 17: the restart was planned under it).
                // G101 X#1 names X as well (review 19, finding 1)
                self.set_unrestored("101", line, "G101 (mirror image)".into());
                let all = named | param_axes.0;
                self.haas_mirror_doubt &= if all == 0 { 0 } else { !all };
                self.haas_mirrored |= if all == 0 {
                    bit(0) | bit(1) | bit(2)
                } else {
                    all
                };
            }
            if self.haas_mill() && g == 100 {
                let was = self
                    .unrestored
                    .iter()
                    .any(|(k, _, _)| k == "101" || k == "101?");
                // G100 X0 ends X's mirror alone (a G100 naming none, all); G100 X#1 leaves
                // X's mirror not known (review 19, finding 1: it was read as naming none)
                (self.haas_mirrored, self.haas_mirror_doubt) = self.mirror_off(
                    line,
                    "G100",
                    ("101", "101?"),
                    (self.haas_mirrored, self.haas_mirror_doubt),
                    named,
                    param_axes,
                );
                if was {
                    // an axis still mirrored for certain is not ended here
                    let kept = self.haas_mirrored & !self.haas_mirror_doubt;
                    self.transform_cancel(line, "G100", "mirror image", kept);
                }
            }
            if (54..=59).contains(&g) {
                // (an Okuma mill's G54-G59 are length offsets; G54 is in force at reset)
                let okuma_mill = self.control == Control::Okuma && !self.lathe;
                let extra = LINUXCNC_WORK_SYSTEMS
                    .iter()
                    .any(|k| self.unrestored.iter().any(|(u, _, _)| u == k));
                if (self.work.unwrap_or(54) != g || extra) && !okuma_mill {
                    self.frame_change(line, format!("G{g}"));
                }
                for key in LINUXCNC_WORK_SYSTEMS {
                    self.drop_unrestored(key);
                }
                self.work = Some(g);
                self.drop_unrestored("54.1");
                self.drop_unrestored("154");
                for extended in 110..130 {
                    self.drop_unrestored(&extended.to_string());
                }
            }
            // (a Haas lathe's list has no G110-G129; its G112/G113 are the XC interpolation)
            if g == 154 || ((110..=129).contains(&g) && self.haas_mill()) {
                let what = format!("G{g} (an extended work offset)");
                self.set_unrestored(&g.to_string(), line, what);
            }
            if g == 52 {
                // a shift by anything but zero
                if axes
                    .iter()
                    .any(|t| t[1..].iter().any(|c| !b"+-0.".contains(c)))
                {
                    self.set_unrestored("52", line, "G52 (a local coordinate shift)".into());
                } else {
                    self.drop_unrestored("52");
                }
            }
            if g == 92 && !axes.is_empty() && !self.g50_lathe() {
                for &(letter, _) in plain_words {
                    if let Some(i) = axis_index(self.axis(letter)) {
                        self.shifted |= bit(i);
                    }
                }
                let what = "G92 (a coordinate system set at the machine's position)";
                self.set_unrestored("92", line, what.into());
            }
            if g == 50 && self.g50_lathe() && !axes.is_empty() {
                let what = "G50 (a coordinate system set at the machine's position)";
                self.set_unrestored("50", line, what.into());
            }
            if self.okuma_lathe && (81..=83).contains(&g) {
                self.lap_contour = Some(line);
                let what = format!("the LAP contour definition G{g}");
                self.set_unrestored("lap", line, what);
            }
            if self.okuma_lathe && g == 80 {
                self.lap_contour = None;
                self.drop_unrestored("lap");
            }
            if g == 41 || g == 42 {
                self.comp_line = line;
            }
            if g == 40 {
                self.comp_line = 0;
            }
            if mill_cycle(g) && !self.lathe {
                self.cycle = Some((g, line));
            }
            if g == 80 || MOTION_CODES.contains(&g) {
                self.cycle = None;
            }
        }
        if self.control == Control::LinuxCnc {
            if let Some(&g) = gs.iter().rev().find(|&&g| g == 7 || g == 8) {
                let x_seen = axis_index(b'X').is_some_and(|i| self.seen & bit(i) != 0);
                if x_seen && self.diameter_mode.map(|(m, _)| m) != Some(g) {
                    self.diameter_switch = Some(line);
                    // the same places in the new mode's numbers: the largest X is half (G8)
                    // or twice (G7) the number; the moves and lane, numbers of the old mode
                    // beside the new, are no way back in
                    let factor = if g == 8 { (5, 1) } else { (2, 0) };
                    if let Some(high) = self.high[0] {
                        match high.checked_mul(Dec {
                            mantissa: factor.0,
                            scale: factor.1,
                        }) {
                            Some(v) => self.high[0] = Some(v),
                            None => {
                                self.too_long.get_or_insert(line);
                            }
                        }
                    }
                    self.moves.clear();
                    self.lane = None;
                }
                self.diameter_mode = Some((g, line));
            }
        }
        for dec in gdec {
            let text = String::from_utf8_lossy(dec);
            if self.control == Control::LinuxCnc && LINUXCNC_WORK_SYSTEMS.contains(&text.as_ref()) {
                let was = self.unrestored.iter().any(|(k, _, _)| *k == text);
                if !was {
                    self.frame_change(line, format!("G{text}"));
                }
                for key in LINUXCNC_WORK_SYSTEMS {
                    self.drop_unrestored(key);
                }
                let n = 6 + text.as_bytes()[3] - b'0';
                let what = format!("G{text} (work coordinate system {n})");
                self.set_unrestored(&text, line, what);
            }
            if self.control == Control::Fanuc && text == "54.2" {
                // FANUC's rotary table dynamic fixture offset (30i-B: G54.2 Pn, P0 cancels):
                // a frame the preamble does not write; its change moves the axes' numbers
                let cancel = plain_words
                    .iter()
                    .any(|&(l, t)| l == b'P' && t[1..].iter().all(|c| b"+-0.".contains(c)));
                self.frame_change(line, format!("G{text}"));
                if cancel {
                    self.drop_unrestored("54.2");
                } else {
                    let what = "G54.2 (rotary table dynamic fixture offset)".to_string();
                    self.set_unrestored("54.2", line, what);
                }
            }
            if self.control.family() == Family::MacroB {
                match text.as_ref() {
                    "12.1" => self.set_unrestored(
                        "12.1",
                        line,
                        "G12.1 (polar coordinate interpolation)".into(),
                    ),
                    "13.1" => self.interpolation_cancel("12.1", line, "G13.1"),
                    "7.1" => self.cylindrical(line, "G07.1", plain_words, param_axes.0),
                    _ => {}
                }
            }
            let mirror_codes = self.control.family() == Family::MacroB;
            let named = plain_words
                .iter()
                .filter_map(|&(letter, _)| axis_index(letter))
                .fold(0u16, |all, i| all | bit(i));
            if mirror_codes && text == "51.1" && (named | param_axes.0) != 0 {
                // FANUC G51.1 X0: programmable mirror image about X0 (0i-MF, group 22);
                // G51.1 X#1 mirrors X as well, about a point set by a parameter (review 19)
                let what = "G51.1 (programmable mirror image)";
                self.set_unrestored("51.1", line, what.into());
                self.mirrored |= named | param_axes.0;
                self.mirror_doubt &= !(named | param_axes.0);
            }
            if mirror_codes && text == "50.1" {
                let was = self
                    .unrestored
                    .iter()
                    .any(|(k, _, _)| k == "51.1" || k == "51.1?");
                // G50.1 X0 ends X's mirror alone (a G50.1 naming none, all); G50.1 X#1
                // leaves X's mirror not known (review 19, finding 1)
                (self.mirrored, self.mirror_doubt) = self.mirror_off(
                    line,
                    "G50.1",
                    ("51.1", "51.1?"),
                    (self.mirrored, self.mirror_doubt),
                    named,
                    param_axes,
                );
                if was {
                    // an axis still mirrored for certain is not ended here
                    let kept = self.mirrored & !self.mirror_doubt;
                    self.transform_cancel(line, "G50.1", "mirror image", kept);
                }
            }
            if (text == "92.1" || text == "92.2")
                && self.unrestored.iter().any(|(k, _, _)| k == "92")
            {
                // the G92 shift cancelled (FANUC G92.1 presets the workpiece system back;
                // LinuxCNC G92.1/G92.2 reset the G92 offsets): the numbers change under the tool
                self.drop_unrestored("92");
                let seen = self.seen;
                self.seen &= self.shifted; // (only the axes the G92 set change their numbers)
                self.frame_change(line, format!("G{text} (the G92 shift cancelled)"));
                self.seen = seen;
                self.shifted = 0;
            }
            if text == "92.3" {
                let what = "G92.3 (the G92 offsets restored from the parameters)";
                self.set_unrestored("92", line, what.into());
            }
            if DECIMAL_UNRESTORED.contains(&text.as_ref()) {
                if DECIMAL_LENGTH_OFFSETS.contains(&text.as_ref()) {
                    // (one length offset code replaces another: the same group)
                    for key in DECIMAL_LENGTH_OFFSETS {
                        self.drop_unrestored(key);
                    }
                }
                self.set_unrestored(&text, line, format!("G{text}"));
            }
            if text == "53.1" {
                // FANUC's tool axis direction control turns the rotary axes to the tilted
                // working plane's direction by the control's own sums: their places are not
                // followed, and they stay there after G69 (review 29, finding 2: the preamble
                // sent B and C back to their places before the tilt)
                // (the rotary axes the program has moved; where it has moved none, all three:
                // which of them the machine has is not in the program -- review 30, finding 2:
                // an A never written was refused on a B-C machine)
                let rotary = [b'A', b'B', b'C'];
                // (moved: given plainly, or lost already -- a G28, G30 or G53 move leaves its
                // axis lost with a replay, not seen: review 31, finding 1)
                let seen: Vec<u8> = rotary
                    .into_iter()
                    .filter(|&a| {
                        axis_index(a)
                            .is_some_and(|i| self.seen & bit(i) != 0 || self.lost[i].is_some())
                    })
                    .collect();
                let lost = if seen.is_empty() {
                    rotary.to_vec()
                } else {
                    seen
                };
                for axis in lost {
                    let what = "G53.1 (the tool axis direction control turns the rotary axes \
                                to the tilted working plane; their places are not followed)";
                    self.lose_unknown(axis, line, what.as_bytes().to_vec());
                }
            }
            if TILTED_PLANES.contains(&text.as_ref()) {
                // one tilted plane replaces another (the same G code group)
                for key in TILTED_PLANES {
                    self.drop_unrestored(key);
                }
                self.set_unrestored(&text, line, format!("G{text} (tilted working plane)"));
            }
            if text == "90.1" {
                self.arc_absolute = true;
            }
            if text == "91.1" {
                self.arc_absolute = false;
            }
        }
        // (an Okuma mill's G69 is its 3-D conversion on, no cancel)
        if gs.contains(&69) && (self.control != Control::Okuma || self.lathe) {
            let was = self
                .unrestored
                .iter()
                .any(|(k, _, _)| TILTED_PLANES.contains(&k.as_str()));
            for key in TILTED_PLANES {
                self.drop_unrestored(key);
            }
            if was {
                self.transform_cancel(line, "G69", "tilted working plane", 0);
            }
        }
        if gs.contains(&40) {
            self.drop_unrestored("41.1");
            self.drop_unrestored("42.1");
        }
        if gs.contains(&49) || gs.contains(&43) {
            for key in DECIMAL_LENGTH_OFFSETS {
                self.drop_unrestored(key);
            }
        }
        if core_cycle.is_none() && self.cycle.is_some_and(|(c, _)| (81..90).contains(&c)) {
            self.cycle = None; // the core ended it (a motion code)
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn tool(
        &mut self,
        line: usize,
        gs: &[i64],
        ms: &[i64],
        plain_words: &[(u8, &[u8])],
        tool_word: bool,
        turning: bool,
        length_offset: i64,
    ) {
        let word = |letter: u8| {
            plain_words
                .iter()
                .find(|&&(l, _)| l == letter)
                .map(|&(_, t)| t.to_vec())
        };
        if let Some(t) = word(b'T') {
            self.t_token = Some(t);
        }
        if self.lathe && (tool_word || ms.contains(&6)) {
            if turning {
                // with the main spindle stopped a builder's code before the T word, or that a
                // live tool before this one switched on, stays in force across the change
                // (review 36, finding 2: `M76 / T0505` and a second live tool were planned)
                self.builder_m = None;
            }
            self.moves.clear();
            self.tool_change = Some(line);
            self.tool_moved = false;
            self.lane = None;
        }
        if ms.contains(&6) && !self.lathe && matches!(self.control, Control::Fanuc | Control::Haas)
        {
            // (review 36, finding 1) a mill's M06 "stops the spindle, stops coolant, moves the
            // Z Axis to the tool change position, and orients the spindle" (Haas mill manual,
            // NGC, "M06 Tool Change"; a FANUC's M06 is the builder's macro, which does the same
            // on the machines at hand): Z is at no height the program wrote, and X and Y are
            // reached from it, so until the program writes them they are no place the
            // preamble goes to, as at the program's start (the new tool went down to Z25. with
            // the old tool's H01); the spindle and coolant are left off until the program's
            // own M03/M04 and M07/M08 after it (the preamble's postproc side)
            for letter in [b'X', b'Y', b'Z'] {
                if let Some(i) = axis_index(letter) {
                    self.lost[i] = None;
                    self.unset |= bit(i);
                }
            }
            // the tool change ends an orientation before it: the spindle is stopped after it
            // either way (review 36, finding 2: an M19 before the M06 refused every restart
            // up to the new tool's M03)
            self.orientation_ended(line);
            // (a keyed M13 of the M06's own block runs after the change, as the preamble's
            // side reads a spindle start there: its coolant stays on, review 57a F2)
            if self.keyed_coolant.is_some_and(|(at, _)| at != line) {
                self.keyed_coolant = None;
            }
        }
        if ms.contains(&6) {
            self.spindle_t = if self.unknown[letter_index(b'T')].is_some() {
                None
            } else {
                self.t_token.clone()
            };
        }
        if !self.lathe {
            // (a lathe's D is a cycle's depth of cut)
            if let Some(d) = word(b'D') {
                self.d_token = Some(d);
            }
        }
        if gs.contains(&43) || gs.contains(&44) {
            self.g43_line = line;
            self.h = word(b'H');
        } else if let Some(h) = word(b'H') {
            if matches!(length_offset, 43 | 44)
                && !gs.iter().any(|g| matches!(g, 10 | 41 | 42 | 65))
            {
                self.h = Some(h); // a new H in G43 mode takes effect (Fanuc)
            }
        }
        if gs.contains(&49) {
            self.h = None;
        }
        if self.control == Control::Okuma && !self.lathe {
            // OSP: G15 H the work system, G54-G59 H the length offsets, G53 their cancel
            let h = word(b'H');
            if gs.contains(&15) {
                let before = self.okuma_work.as_ref().and_then(|w| w.0.clone());
                if before.is_none() || before != h {
                    let what = match &h {
                        Some(h) => format!("G15 {}", String::from_utf8_lossy(h)),
                        None => "G15".to_string(),
                    };
                    self.frame_change(line, what);
                }
                self.okuma_work = Some((h.clone(), line));
            }
            if let Some(&g) = gs.iter().find(|g| (54..=59).contains(*g)) {
                self.okuma_length = Some((g, h, line));
            } else if gs.contains(&53) {
                self.okuma_length = None;
            }
        }
    }

    /// The lathe cycle this block runs, by its own code or as a repeat in the mode of one: a
    /// FANUC or Haas lathe's G70-G76, G90, G92, G94 (G90/G92/G94 are modal, group 01: a block
    /// of axis words alone in their mode is another pass; 0i-TF "G code list"), an Okuma
    /// lathe's thread cutting cycles G31-G35 (5238-E section 7; G31/G32 modal in the core,
    /// `ModalSettings::own_motion`, G33-G35 of the motion group).
    fn lathe_cycle(&self, gs: &[i64], motion: Option<i64>) -> Option<i64> {
        let (own, modal): (&[i64], &[i64]) = if self.fanuc_lathe {
            (&LATHE_CYCLES, &[90, 92, 94])
        } else if self.okuma_lathe {
            (&[31, 32, 33, 34, 35], &[31, 32, 33, 34, 35])
        } else {
            return None;
        };
        if let Some(&g) = gs.iter().filter(|g| own.contains(g)).min() {
            return Some(g);
        }
        let moving = gs
            .iter()
            .any(|g| MOTION_CODES.contains(g) || LATHE_CYCLES.contains(g));
        motion.filter(|m| !moving && modal.contains(m))
    }

    /// A thread cutting move's code on this control: G32-G35 (FANUC G32, G33 of ISO 6983 and
    /// LinuxCNC), except an Okuma lathe's, whose G31-G35 are cycles.
    fn thread_code(&self, g: i64) -> bool {
        (32..=35).contains(&g) && !self.okuma_lathe
    }

    fn replay(&self, g: i64, letter: u8, token: &[u8]) -> (String, Vec<u8>) {
        if g == 53 {
            return ("G53 G00".into(), token.to_vec());
        }
        if self.fanuc_lathe {
            // through the point where the tool is: U0 W0
            let word = if self.axis(letter) == b'X' {
                b"U0"
            } else {
                b"W0"
            };
            return (format!("G{g}"), word.to_vec());
        }
        (format!("G91 G{g}"), vec![letter, b'0'])
    }

    /// Follow the lane ([`Walk::lane`]) through a move from `from` to `to` (X, Z); `along`:
    /// whether both ends are followed positions.
    fn widen_lane(
        &mut self,
        from: [Option<Dec>; 2],
        to: [Option<Dec>; 2],
        along: bool,
        units: Units,
    ) {
        let mm = |v: Dec| match units {
            Units::Inch => v.checked_mul(Dec {
                mantissa: 254,
                scale: 1,
            }),
            _ => Some(v),
        };
        if units != self.lane_units {
            self.lane = None;
            self.lane_units = units;
        }
        let (Some(x), Some(z)) = (to[0].and_then(mm), to[1].and_then(mm)) else {
            return;
        };
        if self.lane.as_ref().is_none_or(|(lx, _)| x > *lx) {
            self.lane = Some((x, Vec::new()));
        }
        let start = from[1].and_then(mm);
        let (Some((lx, ranges)), Some(z0)) = (self.lane.as_mut(), start) else {
            return;
        };
        if !along || *lx != x || from[0].and_then(mm) != Some(x) || z0 == z {
            return;
        }
        let (mut lo, mut hi) = if z0 < z { (z0, z) } else { (z, z0) };
        ranges.retain(|&(a, b)| {
            let apart = b < lo || a > hi;
            if !apart {
                lo = lo.min(a);
                hi = hi.max(b);
            }
            apart
        });
        ranges.push((lo, hi));
        if ranges.len() > LANE_RANGES {
            // the range ending lowest goes: a lane lost is a restart refused, never a crash
            if let Some(low) = (0..ranges.len()).min_by_key(|&i| ranges[i].1) {
                ranges.swap_remove(low);
            }
        }
    }

    fn positions(
        &mut self,
        line: usize,
        gs: &[i64],
        plain_words: &[(u8, &[u8])],
        after: &ModalState,
        data: bool,
    ) {
        // where the tool stands before the block: a lathe cycle's start point, where it held one
        let from =
            [b'X', b'Z'].map(|axis| axis_index(axis).and_then(|i| self.held[i].or(self.before[i])));
        // a dwell's time words are no move; its other axis words are (LinuxCNC's G4 P1 Z5)
        let dwell: &[u8] = if gs.contains(&4) { self.dwell } else { &[] };
        let letters: Vec<(u8, &[u8])> = plain_words
            .iter()
            .filter(|(l, _)| AXES.contains(l) && !dwell.contains(l))
            .copied()
            .collect();
        // (an Okuma mill's G53 cancels the tool length offset: no machine coordinates)
        let okuma_mill = self.control == Control::Okuma && !self.lathe;
        if let Some(&g) = gs
            .iter()
            .find(|&&g| machine_move(g).is_some() && !(g == 53 && okuma_mill))
        {
            let name = machine_move(g).unwrap_or("");
            if letters.is_empty() && g != 53 && self.control == Control::LinuxCnc {
                // LinuxCNC's G28 alone: every axis home
                for (i, &axis) in AXES.iter().enumerate() {
                    if self.seen & bit(i) != 0 {
                        let what = format!("G{g} ({name})").into_bytes();
                        self.lose(
                            axis,
                            true,
                            line,
                            Why::Text(what),
                            (format!("G{g}"), Vec::new()),
                        );
                    }
                }
            }
            for &(letter, token) in &letters {
                let axis = self.axis(letter);
                let mut what = format!("G{g} ").into_bytes();
                what.extend_from_slice(token);
                what.extend_from_slice(format!(" ({name})").as_bytes());
                let replay = self.replay(g, letter, token);
                self.lose(axis, true, line, Why::Text(what), replay);
            }
            return;
        }
        let has = |g: i64| gs.contains(&g);
        if self.control == Control::Okuma && !self.lathe && (has(11) || has(62) || has(69)) {
            // an Okuma mill's G11, G62 and G69 (OSP List of G Codes): no page at hand gives
            // their axis words, so neither a move nor a position kept is assumed
            // (`ModalSettings::axes_taken`)
            for &(letter, token) in &letters {
                let mut what = token.to_vec();
                what.extend_from_slice(
                    b" in an Okuma frame block, whose axis words no page at hand gives",
                );
                self.lose_unknown(self.axis(letter), line, what);
            }
            return;
        }
        if has(10)
            || has(52)
            || (has(92) && !self.g50_lathe())
            || (has(50) && self.g50_lathe())
            || data
            || (!self.lathe && (has(68) || has(51)))
        {
            return; // data, not a move (a mirror's axis, a rotation's or scaling's centre)
        }
        // an Okuma lathe's contour definition, LAP, thread, grooving and M-tool cycles: their
        // X Z U W are the contour, the cycle's targets and allowances (5238-E sections 7, 8)
        let lap_cycle = gs
            .iter()
            .find(|&&g| matches!(g, 71..=89 | 178..=189))
            .copied();
        if self.okuma_lathe
            && !letters.is_empty()
            && (lap_cycle.is_some() || self.lap_contour.is_some())
        {
            let what = match (lap_cycle, self.lap_contour) {
                (Some(g), _) => format!("the cycle G{g}, whose end point is not followed"),
                (None, Some(at)) => format!("the LAP contour definition from line {at}, no move"),
                (None, None) => String::new(),
            };
            for axis in [b'X', b'Z'] {
                self.lose_unknown(axis, line, what.clone().into_bytes());
            }
            return;
        }
        if let Some(cycle) = self.lathe_cycle(gs, after.motion) {
            if cycle == 34 || cycle == 35 {
                // an Okuma lathe's variable lead threading: whether it ends where it started
                // was not found in 5238-E's pages read, so the place is not followed
                for axis in [b'X', b'Z'] {
                    let what =
                        format!("the thread cutting G{cycle}, whose end point is not followed");
                    self.lose_unknown(axis, line, what.into_bytes());
                }
                self.thread = None;
                return;
            }
            if (70..=73).contains(&cycle) {
                let number = |letter: u8| {
                    plain_words
                        .iter()
                        .find(|&&(l, _)| l == letter)
                        .and_then(|&(_, t)| whole_number(&t[1..]))
                };
                if let (Some(p), Some(q), true) = (number(b'P'), number(b'Q'), cycle != 70) {
                    self.contour_next = Some((p, q, cycle, line));
                }
            }
            if self.fanuc_lathe && matches!(cycle, 90 | 92 | 94) {
                let r = plain_words.iter().any(|&(l, _)| l == b'R');
                if gs.contains(&cycle) {
                    self.cycle_r = r.then_some(line); // a new cycle: its own R or none
                } else if r {
                    self.cycle_r = Some(line);
                }
            }
            if !letters.is_empty() {
                // the cycle returns to its start point: where the block before left the tool
                for axis in [b'X', b'Z'] {
                    let Some(i) = axis_index(axis) else { continue };
                    if self.lost[i].is_some() {
                        continue;
                    }
                    match self.held[i].or(self.before[i]) {
                        Some(start) => self.held[i] = Some(start),
                        None => {
                            let what = format!("the cycle G{cycle}, from a start point not known");
                            self.lose_unknown(axis, line, what.into_bytes());
                        }
                    }
                }
            }
            self.thread = None;
            self.moves.clear(); // the cycle's own moves are not followed
            self.tool_moved = true;
            return;
        }
        let absolute = !after.incremental;
        if !letters.is_empty() {
            // a thread move right after a thread move continues the same thread
            let threading = after.motion.is_some_and(|m| self.thread_code(m));
            self.thread = threading.then_some(line);
        }
        let mut rewritten = false; // X written again after a G7/G8 switch
        for &(letter, token) in &letters {
            let axis = self.axis(letter);
            if let Some(i) = axis_index(axis) {
                if self.held[i].is_some() {
                    self.held[i] = None;
                    if letter != axis || !absolute {
                        let what = format!(
                            "{}, an increment from the start point of the cycle the checker does not follow",
                            String::from_utf8_lossy(token)
                        );
                        self.lose_unknown(axis, line, what.into_bytes());
                        continue;
                    }
                }
            }
            if letter != axis {
                // U, W: an increment of X, Z
                let mut what = token.to_vec();
                what.extend_from_slice(
                    format!(
                        ", an increment of {} on a lathe, not followed",
                        axis as char
                    )
                    .as_bytes(),
                );
                self.lose_unknown(axis, line, what);
            } else if absolute {
                if let Some(i) = axis_index(axis) {
                    self.lost[i] = None;
                }
                if axis == b'X' && !self.diameter_kept {
                    if let Some(switch) = self.diameter_switch.take() {
                        // X in force is now a number of the new mode (rs274 reads X words by
                        // the mode in force; its own position is kept in radius); this move
                        // starts at the old mode's number, a point the walk cannot place, as
                        // a tool change's first move starts from one
                        self.moves.clear();
                        self.lane = None;
                        self.diameter_rewritten = Some((switch, line));
                        rewritten = true;
                    }
                }
            } else if let Some(i) = axis_index(axis) {
                if axis == b'X' && self.diameter_switch.is_some() {
                    self.diameter_kept = true;
                }
                if self.before[i].is_none() && self.lost[i].is_none() {
                    // the control moves from wherever the tool stands; the modal state
                    // counts from 0
                    let mut what = token.to_vec();
                    what.extend_from_slice(
                        b", an increment from a position the program has not set",
                    );
                    self.lose_unknown(axis, line, what);
                }
            }
        }
        for &(letter, _) in &letters {
            // the axis written again: a place of the program's (a U/W increment is lost above)
            if let Some(i) = axis_index(self.axis(letter)) {
                self.unset &= !bit(i);
            }
        }
        // (review 35, finding 3) a lathe's move of another axis (C, Y, B) is no way in along
        // X and Z: the moves before it were made at another angle or Y, and a replay of them
        // after the preamble has set C or Y would go where the program did not (a hole's depth
        // at C0 drilled again at C90); it breaks the chain and the lane
        let side = letters
            .iter()
            .map(|&(l, _)| self.axis(l))
            .find(|&a| a != b'X' && a != b'Z');
        // (review 36, finding 3) a FANUC lathe's H and V in G code system A are the increments
        // of C and Y, as U and W are of X and Z (the profile's classification does not hold
        // them, TG134): a move of C or Y from where the walk cannot say, so C or Y is lost
        let increment = if self.fanuc_lathe {
            plain_words.iter().find_map(|&(l, t)| match l {
                b'H' => Some((b'C', t)),
                b'V' => Some((b'Y', t)),
                _ => None,
            })
        } else {
            None
        };
        if let Some((axis, token)) = increment {
            self.moves.clear();
            self.lane = None;
            self.side_move = Some((line, axis));
            let mut what = token.to_vec();
            what.extend_from_slice(b", an increment of ");
            what.push(axis);
            what.extend_from_slice(b" (G code system A) the walk does not follow");
            self.lose_unknown(axis, line, what);
        }
        if self.lathe && side.is_some() {
            self.moves.clear();
            self.lane = None;
            let yc = letters
                .iter()
                .map(|&(l, _)| self.axis(l))
                .find(|&a| a == b'C' || a == b'Y');
            if let Some(axis) = yc {
                self.side_move = Some((line, axis));
            }
        }
        if !letters.is_empty() && self.transforms_on() {
            let mut bits = 0;
            for &(letter, _) in &letters {
                if let Some(i) = axis_index(self.axis(letter)) {
                    bits |= bit(i);
                }
            }
            let (a, b) = match after.plane {
                18 => (b'Z', b'X'),
                19 => (b'Y', b'Z'),
                _ => (b'X', b'Y'),
            };
            let pair = [a, b]
                .iter()
                .filter_map(|&l| axis_index(l))
                .fold(0, |m, i| m | bit(i));
            if self.unrestored.iter().any(|(k, _, _)| k == "68") && bits & pair != 0 {
                bits |= pair; // a rotation moves both axes of its plane
            }
            let tilted = self
                .unrestored
                .iter()
                .any(|(k, _, _)| TILTED_PLANES.contains(&k.as_str()));
            let space = [b'X', b'Y', b'Z']
                .iter()
                .filter_map(|&l| axis_index(l))
                .fold(0, |m, i| m | bit(i));
            if (tilted || self.rotation_3d) && bits & space != 0 {
                // a tilted plane's or a 3-D conversion's move of one axis moves all three
                bits |= space;
            }
            self.transformed |= self.under_transform(bits);
        }
        if self.lathe && !letters.is_empty() {
            let pick = |p: &[Option<Dec>; 9], axis: u8| axis_index(axis).and_then(|i| p[i]);
            let to = [pick(&after.position, b'X'), pick(&after.position, b'Z')];
            if from != to || rewritten {
                let lost = [b'X', b'Z']
                    .iter()
                    .any(|&a| axis_index(a).is_some_and(|i| self.lost[i].is_some()));
                let first = !self.tool_moved || rewritten;
                let one = Move {
                    from,
                    to,
                    // (a move of X or Z with C or Y: its path is not along X and Z alone)
                    motion: if lost || side.is_some() {
                        None
                    } else {
                        after.motion
                    },
                    line,
                    first,
                };
                self.tool_moved = true;
                self.moves.insert(0, one);
                self.moves.truncate(MOVES_KEPT);
                if side.is_none() {
                    self.widen_lane(from, to, !lost, after.units);
                }
            }
        }
        if let (Some((code, _)), false) = (self.cycle, letters.is_empty()) {
            let what = format!("the canned cycle G{code}: the tool is at its return level");
            self.lose_unknown(b'Z', line, what.into_bytes());
            if let Some(lost) = axis_index(b'Z').and_then(|i| self.lost[i].as_mut()) {
                lost.cycle = true;
            }
        }
        for (i, p) in after.position.iter().enumerate() {
            if p.is_some() {
                self.seen |= bit(i);
            }
        }
        let lifts: &[(usize, u8)] = if self.lathe {
            &[(0, b'X'), (1, b'Z')]
        } else {
            &[(1, b'Z')]
        };
        for &(slot, axis) in lifts {
            let Some(i) = axis_index(axis) else { continue };
            let Some(value) = after.position[i] else {
                continue;
            };
            if self.lost[i].is_some() || (letters.is_empty() && self.high[slot].is_some()) {
                continue;
            }
            if slot == 0 && self.diameter_switch.is_some() {
                continue; // X's number of the old mode, counted (converted) at the switch
            }
            let value = if after.units == Units::Inch {
                // exact: the highest point compared in one unit
                match value.checked_mul(Dec {
                    mantissa: 254,
                    scale: 1,
                }) {
                    Some(v) => v,
                    None => {
                        self.too_long.get_or_insert(line);
                        continue;
                    }
                }
            } else {
                value
            };
            self.high[slot] = Some(match self.high[slot] {
                Some(high) if high >= value => high,
                _ => value,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_words_are_a_letter_a_sign_and_a_number() {
        for yes in [&b"X-12.5"[..], b"G1", b"X.5", b"X5.", b"M06", b"x+0"] {
            assert!(plain(yes), "{}", String::from_utf8_lossy(yes));
        }
        for no in [
            &b"X"[..],
            b"X-",
            b"X.",
            b"X1.2.3",
            b"X#1",
            b"X[1]",
            b"X1=3",
            b":1000",
            b"X=R1",
            b"X1e3",
        ] {
            assert!(!plain(no), "{}", String::from_utf8_lossy(no));
        }
    }

    #[test]
    fn indexed_and_conditional_sets() {
        assert!(indexed(b"X1=3"));
        assert!(!indexed(b"X=3"));
        assert!(!indexed(b"X13"));
    }

    #[test]
    fn code_numbers_keep_their_fraction_without_trailing_zeros() {
        assert_eq!(code_number(b"54.10"), (54, b"1".to_vec(), false));
        assert_eq!(code_number(b"01"), (1, Vec::new(), false));
        assert_eq!(code_number(b"1."), (1, Vec::new(), false));
        assert_eq!(code_number(b"-.5"), (0, b"5".to_vec(), true));
    }

    fn state() -> ModalState {
        ModalState::new(Units::Metric)
    }

    #[test]
    fn a_change_of_work_system_loses_the_axes_seen_to_the_frame() {
        let mut walk = Walk::new(Control::Fanuc, false, false);
        walk.seen = bit(0) | bit(2); // X and Z have had a position
        for (line, code) in [(5, &b"G54"[..]), (6, &b"G55"[..])] {
            let tokens: Vec<&[u8]> = vec![code];
            walk.step(
                &Step {
                    line,
                    text: code,
                    tokens: &tokens,
                    statements: &[],
                    extras: false,
                },
                &state(),
            );
            if line == 5 {
                assert!(walk.lost.iter().all(Option::is_none)); // G54 is in force at reset
            }
        }
        let lost: Vec<(usize, bool, usize)> = walk
            .lost
            .iter()
            .enumerate()
            .filter_map(|(i, l)| l.as_ref().map(|l| (i, l.frame, l.line)))
            .collect();
        assert_eq!(lost, vec![(0, true, 6), (2, true, 6)]);
    }

    #[test]
    fn a_jump_is_the_flow_and_a_rotation_is_unrestored() {
        let mut walk = Walk::new(Control::Fanuc, false, false);
        let tokens: Vec<&[u8]> = vec![b"G68", b"X0", b"Y0", b"R30."];
        walk.step(
            &Step {
                line: 3,
                text: b"G68 X0 Y0 R30.",
                tokens: &tokens,
                statements: &[],
                extras: false,
            },
            &state(),
        );
        assert_eq!(
            walk.unrestored,
            vec![("68".into(), 3, "G68 (coordinate rotation)".into())]
        );
        let statements = [(Kind::Flow, &b"GOTO 10"[..])];
        walk.step(
            &Step {
                line: 4,
                text: b"GOTO 10",
                tokens: &[],
                statements: &statements,
                extras: true,
            },
            &state(),
        );
        assert_eq!(
            walk.flow.as_ref().map(|f| (f.line, f.kind)),
            Some((4, "flow"))
        );
    }

    fn step_text(walk: &mut Walk, line: usize, text: &[u8], s: &ModalState) {
        let tokens: Vec<&[u8]> = text.split(|&c| c == b' ').collect();
        walk.step(
            &Step {
                line,
                text,
                tokens: &tokens,
                statements: &[],
                extras: false,
            },
            s,
        );
    }

    #[test]
    fn a_tool_name_is_a_constant_and_an_increment_from_nowhere_is_lost() {
        assert!(quoted_name(b"T=\"MILL10\""));
        assert!(!quoted_name(b"T=R1") && !quoted_name(b"T=\"A\"B\""));
        let mut walk = Walk::new(Control::Sinumerik, false, false);
        step_text(&mut walk, 1, b"T=\"MILL10\"", &state());
        assert_eq!(walk.t_token.as_deref(), Some(&b"T=\"MILL10\""[..]));
        assert!(walk.unknown[letter_index(b'T')].is_none());
        let mut walk = Walk::new(Control::Fanuc, false, false);
        let mut s = state();
        s.incremental = true;
        s.position[0] = Some(Dec {
            mantissa: 10,
            scale: 0,
        }); // the modal state counted from 0
        step_text(&mut walk, 2, b"X10.", &s);
        assert_eq!(walk.lost[0].as_ref().map(|l| l.line), Some(2));
    }

    #[test]
    fn a_mirror_cancel_with_a_word_not_known_leaves_that_axis_s_mirror_not_known() {
        // review 19, finding 1: G50.1 X#1 was read as naming no axis, so ending every mirror
        let mut walk = Walk::new(Control::Fanuc, false, false);
        let s = state();
        step_text(&mut walk, 1, b"G51.1 X0 Y0", &s);
        step_text(&mut walk, 2, b"G50.1 X#1", &s);
        // (review 22, finding 2) a vacant #1 makes it a bare G50.1, which ends them all: Y is
        // not mirrored for certain either
        let keys: Vec<&str> = walk.unrestored.iter().map(|(k, _, _)| k.as_str()).collect();
        assert_eq!(keys, ["51.1?"]);
        assert!(walk.unrestored[0]
            .2
            .contains("of XY, which G50.1 X#1 may or may not"));
        step_text(&mut walk, 3, b"G50.1 Y0", &s);
        assert_eq!(walk.unrestored.len(), 1);
        assert_eq!(walk.unrestored[0].0, "51.1?");
        step_text(&mut walk, 4, b"G50.1 X0", &s);
        assert!(walk.unrestored.is_empty());
        // a plain word beside it: Y's mirror ends (X#1 dropped or not), X not known
        step_text(&mut walk, 5, b"G51.1 X0 Y0", &s);
        step_text(&mut walk, 6, b"G50.1 X#1 Y0", &s);
        let keys: Vec<&str> = walk.unrestored.iter().map(|(k, _, _)| k.as_str()).collect();
        assert_eq!(keys, ["51.1?"]);
        assert!(walk.unrestored[0]
            .2
            .contains("of X, which G50.1 X#1 may or may not"));
        step_text(&mut walk, 7, b"G50.1", &s);
        assert!(walk.unrestored.is_empty());
        // an axis not mirrored is not made doubtful
        step_text(&mut walk, 5, b"G51.1 Y0", &s);
        step_text(&mut walk, 6, b"G50.1 X[1] Y0", &s);
        assert!(walk.unrestored.is_empty());
    }

    #[test]
    fn a_mirror_moves_nothing_and_its_cancel_loses_the_axes_moved_under_it() {
        let mut walk = Walk::new(Control::Fanuc, false, false);
        walk.seen = bit(0) | bit(1) | bit(2);
        let s = state();
        step_text(&mut walk, 1, b"G51.1 X0", &s);
        assert!(walk.lost.iter().all(Option::is_none)); // no move to X0
        assert_eq!(walk.unrestored[0].0, "51.1");
        step_text(&mut walk, 2, b"G01 X20.", &s);
        step_text(&mut walk, 3, b"G50.1 X0", &s);
        assert!(walk.unrestored.is_empty());
        assert_eq!(walk.lost[0].as_ref().map(|l| l.line), Some(3));
        assert!(walk.lost[2].is_none()); // Z did not move under it
    }

    #[test]
    fn the_highest_z_is_kept_in_mm() {
        let mut walk = Walk::new(Control::Fanuc, false, false);
        let mut s = ModalState::new(Units::Inch);
        s.position[2] = Some(Dec {
            mantissa: 2,
            scale: 0,
        });
        let tokens: Vec<&[u8]> = vec![b"Z2."];
        let step = Step {
            line: 1,
            text: b"Z2.",
            tokens: &tokens,
            statements: &[],
            extras: false,
        };
        walk.step(&step, &s);
        assert_eq!(walk.high[1].map(|d| d.to_string()), Some("50.8".into()));
        s.position[2] = Some(Dec {
            mantissa: 1,
            scale: 0,
        });
        walk.step(&step, &s);
        assert_eq!(walk.high[1].map(|d| d.to_string()), Some("50.8".into()));
        assert_eq!(walk.written[letter_index(b'Z')], Some((Units::Inch, 1)));
    }

    #[test]
    fn the_motion_that_last_wrote_z_is_kept() {
        let mut walk = Walk::new(Control::Fanuc, false, false);
        let mut s = ModalState::new(Units::Metric);
        let block = |line, text: &'static [u8], tokens: &'static [&'static [u8]]| Step {
            line,
            text,
            tokens,
            statements: &[],
            extras: false,
        };
        s.motion = Some(0);
        walk.step(
            &block(1, b"G00 X-10. Z-1.", &[b"G00", b"X-10.", b"Z-1."]),
            &s,
        );
        assert_eq!(walk.z_reached, Some((Some(0), 1)));
        // a feed along X alone leaves how Z was reached as it was
        s.motion = Some(1);
        walk.step(&block(2, b"G01 X10.", &[b"G01", b"X10."]), &s);
        assert_eq!(walk.z_reached, Some((Some(0), 1)));
        walk.step(&block(3, b"Z-2.", &[b"Z-2."]), &s);
        assert_eq!(walk.z_reached, Some((Some(1), 3)));
    }

    fn lathe_state(x: i128, z: i128, motion: i64) -> ModalState {
        let mut s = state();
        s.position[axis_index(b'X').unwrap()] = Some(Dec {
            mantissa: x,
            scale: 0,
        });
        s.position[axis_index(b'Z').unwrap()] = Some(Dec {
            mantissa: z,
            scale: 0,
        });
        s.motion = Some(motion);
        s
    }

    #[test]
    fn a_lathe_tool_change_clears_the_moves_and_marks_the_next_tools_first_move() {
        let mut walk = Walk::new(Control::Fanuc, true, true);
        step_text(&mut walk, 1, b"G00 X50. Z2.", &lathe_state(50, 2, 0));
        step_text(&mut walk, 2, b"G01 Z-30.", &lathe_state(50, -30, 1));
        assert_eq!(walk.moves.len(), 2);
        step_text(&mut walk, 3, b"T0202", &lathe_state(50, -30, 1));
        assert!(
            walk.moves.is_empty(),
            "another tool's moves are no way in for this one"
        );
        assert_eq!((walk.tool_change, walk.tool_moved), (Some(3), false));
        step_text(&mut walk, 4, b"G00 X48.", &lathe_state(48, -30, 0));
        step_text(&mut walk, 5, b"G01 X40.", &lathe_state(40, -30, 1));
        let firsts: Vec<(usize, bool)> = walk.moves.iter().map(|m| (m.line, m.first)).collect();
        assert_eq!(firsts, vec![(5, false), (4, true)]);
        assert!(walk.tool_moved);
        // an offset change alone (T0500) and a T set by a parameter change the tool as well
        step_text(&mut walk, 6, b"T0500", &lathe_state(40, -30, 1));
        assert!(walk.moves.is_empty() && !walk.tool_moved);
        step_text(&mut walk, 7, b"G00 X60.", &lathe_state(60, -30, 0));
        step_text(&mut walk, 8, b"T#1", &lathe_state(60, -30, 0));
        assert_eq!((walk.moves.len(), walk.tool_change), (0, Some(8)));
        // a mill keeps no moves and no tool change
        let mut mill = Walk::new(Control::Fanuc, false, false);
        step_text(&mut mill, 1, b"T1 M06", &state());
        assert_eq!(mill.tool_change, None);
    }

    #[test]
    fn the_lane_holds_the_ranges_of_z_moved_along_at_the_largest_x_of_the_tool() {
        let dec = |m: i128| Dec {
            mantissa: m,
            scale: 0,
        };
        let mut walk = Walk::new(Control::Fanuc, true, true);
        step_text(&mut walk, 1, b"T0101", &state());
        step_text(&mut walk, 2, b"G00 X18. Z15.", &lathe_state(18, 15, 0));
        step_text(&mut walk, 3, b"G00 Z1.", &lathe_state(18, 1, 0));
        step_text(&mut walk, 4, b"G00 X11.", &lathe_state(11, 1, 0));
        step_text(&mut walk, 5, b"G01 Z-16.", &lathe_state(11, -16, 1));
        step_text(&mut walk, 6, b"G00 X18.", &lathe_state(18, -16, 0));
        step_text(&mut walk, 7, b"G00 Z1.", &lathe_state(18, 1, 0));
        assert_eq!(walk.lane, Some((dec(18), vec![(dec(-16), dec(15))])));
        // a larger X reached radially (a groove's bottom, inside a bore) has no range yet
        step_text(&mut walk, 8, b"G01 X38.", &lathe_state(38, 1, 1));
        assert_eq!(walk.lane, Some((dec(38), vec![])));
        step_text(&mut walk, 9, b"G01 Z-3.", &lathe_state(38, -3, 1));
        step_text(&mut walk, 10, b"G01 Z-8.", &lathe_state(38, -8, 1));
        step_text(&mut walk, 11, b"G01 Z-20.", &lathe_state(38, -20, 1));
        step_text(&mut walk, 12, b"G00 Z-30.", &lathe_state(38, -30, 0));
        assert_eq!(walk.lane, Some((dec(38), vec![(dec(-30), dec(1))])));
        step_text(&mut walk, 13, b"T0202", &state());
        assert_eq!(
            walk.lane, None,
            "another tool's lane is no lane for this one"
        );
        step_text(&mut walk, 14, b"G00 X50. Z5.", &lathe_state(50, 5, 0));
        for i in 0..40 {
            // 40 separate ranges along Z at X50.: the walk keeps the 16 that end highest
            // (in at X40., out diagonally, then along Z: X and Z as the states give them)
            let line = 15 + 3 * i;
            let z = -10 * i128::try_from(i).unwrap_or(0);
            step_text(&mut walk, line, b"G00 X40.", &lathe_state(40, z, 0));
            step_text(
                &mut walk,
                line + 1,
                b"G00 X50. Z1.",
                &lathe_state(50, z - 1, 0),
            );
            step_text(&mut walk, line + 2, b"G01 Z1.", &lathe_state(50, z - 5, 1));
        }
        let ranges = walk.lane.as_ref().map(|l| l.1.clone()).unwrap_or_default();
        assert_eq!(ranges.len(), LANE_RANGES);
        assert!(ranges.iter().all(|&(_, hi)| hi >= dec(-151)));
        // a change of units clears it
        let mut inch = lathe_state(2, 1, 0);
        inch.units = Units::Inch;
        step_text(&mut walk, 200, b"G20 G00 X2. Z1.", &inch);
        assert_eq!(walk.lane.as_ref().map(|l| l.1.len()), Some(0));
    }

    #[test]
    fn linuxcnc_diameter_mode_is_kept_and_a_switch_after_x_is_noted() {
        let mut walk = Walk::new(Control::LinuxCnc, true, false);
        step_text(&mut walk, 1, b"G18 G7", &state());
        assert_eq!(
            (walk.diameter_mode, walk.diameter_switch),
            (Some((7, 1)), None)
        );
        step_text(&mut walk, 2, b"G00 X30. Z2.", &lathe_state(30, 2, 0));
        step_text(&mut walk, 3, b"G7", &lathe_state(30, 2, 0));
        assert_eq!(walk.diameter_switch, None); // the same mode again
        step_text(&mut walk, 4, b"G8", &lathe_state(30, 2, 0));
        assert_eq!(
            (walk.diameter_mode, walk.diameter_switch),
            (Some((8, 4)), Some(4))
        );
        // the largest X is now a radius: half the diameter written
        assert_eq!(walk.high[0], Some(Dec::from_int(15)));
        // X written again in the new mode: the X in force is a radius, the switch is done
        step_text(&mut walk, 5, b"G00 Z5.", &lathe_state(30, 5, 0));
        assert_eq!(walk.diameter_switch, Some(4)); // Z alone leaves X in the old mode
        let mut kept = walk.clone();
        step_text(&mut walk, 7, b"G90 G00 X14. Z5.", &lathe_state(14, 5, 0));
        assert_eq!(walk.diameter_switch, None);
        // the move from the old number, marked as a first move
        assert!(walk.moves[0].first && walk.moves.len() == 1);
        assert_eq!(walk.diameter_rewritten, Some((4, 7)));
        assert_eq!(walk.high[0], Some(Dec::from_int(15)));
        // an increment of X first counts from the old mode's number: the largest X reached is
        // not known, and the switch stays noted after X is written again
        let mut incremental = lathe_state(31, 5, 0);
        incremental.incremental = true;
        step_text(&mut kept, 6, b"G91 X1.", &incremental);
        step_text(&mut kept, 7, b"G90 G00 X14. Z5.", &lathe_state(14, 5, 0));
        assert_eq!(kept.diameter_switch, Some(4));
        // G7 is no mode on a FANUC (G07.1 is cylindrical interpolation)
        let mut fanuc = Walk::new(Control::Fanuc, true, true);
        step_text(&mut fanuc, 1, b"G7", &state());
        assert_eq!(fanuc.diameter_mode, None);
    }

    #[test]
    fn a_two_block_cycle_is_told_by_its_words() {
        let first = |g: i64, letters: &[u8]| two_block_cycle(&[g], letters);
        assert_eq!(first(71, b"NUR"), Some((71, true)));
        assert_eq!(first(71, b"PQUWF"), Some((71, false)));
        assert_eq!(first(72, b"WR"), Some((71, true))); // G71 and G72 share 5132/5133
        assert_eq!(first(73, b"UWR"), Some((73, true)));
        assert_eq!(first(73, b"PQUWF"), Some((73, false)));
        assert_eq!(first(74, b"R"), Some((74, true)));
        assert_eq!(first(75, b"XZPQRF"), Some((74, false))); // G74 and G75 share 5139
        assert_eq!(first(74, b"ZQF"), Some((74, false)));
        assert_eq!(first(76, b"PQR"), Some((76, true)));
        assert_eq!(first(76, b"XZRPQF"), Some((76, false)));
        assert_eq!(first(76, b"UWPQF"), Some((76, false)));
        assert_eq!(first(71, b"N"), None); // no data, no cycle
        assert_eq!(two_block_cycle(&[70], b"PQ"), None);
        assert_eq!(two_block_cycle(&[1], b"XZ"), None);
    }

    #[test]
    fn a_second_block_names_the_first_block_it_runs_with() {
        let tokens = |t: &'static [u8]| -> Vec<&'static [u8]> { t.split(|&c| c == b' ').collect() };
        let mut walk = Walk::new(Control::Fanuc, true, true);
        // a one-block form (as a Haas writes it) with no first block before it: nothing left out
        assert_eq!(
            walk.cycle_first_block(&tokens(b"G71 P100 Q200 U0.4 W0.1 D2. F0.25")),
            None
        );
        step_text(&mut walk, 8, b"G71 U2. R0.5", &lathe_state(52, 2, 0));
        assert_eq!(walk.cycle_data, vec![(71, 8)]);
        let second = tokens(b"G71 P100 Q200 U0.4 W0.1 F0.25");
        assert_eq!(walk.cycle_first_block(&second), Some((71, 8)));
        // the same data for a G72, and a P set by a parameter is still the cycle's P
        assert_eq!(
            walk.cycle_first_block(&tokens(b"g72 p#1 q200 f0.2")),
            Some((72, 8))
        );
        // the first block itself, another cycle's data, and a G76 with no first block
        assert_eq!(walk.cycle_first_block(&tokens(b"G71 U1. R0.2")), None);
        assert_eq!(walk.cycle_first_block(&tokens(b"G73 P1 Q2 U0.2")), None);
        assert_eq!(
            walk.cycle_first_block(&tokens(b"G76 X18. Z-20. P920 Q300 F1.5")),
            None
        );
        step_text(
            &mut walk,
            20,
            b"G76 P010060 Q100 R0.05",
            &lathe_state(22, 5, 0),
        );
        step_text(&mut walk, 30, b"G71 U#1 R0.5", &lathe_state(22, 5, 0));
        assert_eq!(walk.cycle_data, vec![(76, 20), (71, 30)]);
        assert_eq!(
            walk.cycle_first_block(&tokens(b"G76 U-3.84 W-25. P920 Q300 F1.5")),
            Some((76, 20))
        );
        assert_eq!(walk.cycle_first_block(&second), Some((71, 30)));
        // none of this on a LinuxCNC lathe, whose G71 is a one-block cycle
        let mut linuxcnc = Walk::new(Control::LinuxCnc, true, false);
        step_text(&mut linuxcnc, 1, b"G71 U2. R0.5", &lathe_state(52, 2, 0));
        assert!(linuxcnc.cycle_data.is_empty());
        assert_eq!(linuxcnc.cycle_first_block(&second), None);
    }

    #[test]
    fn a_lathe_move_of_c_ends_the_way_in_and_is_noted_until_the_spindle_starts() {
        // review 35, findings 2 and 3
        let mut walk = Walk::new(Control::Fanuc, true, true);
        step_text(&mut walk, 1, b"T0505", &state());
        step_text(&mut walk, 2, b"G00 X60. Z2.", &lathe_state(60, 2, 0));
        step_text(&mut walk, 3, b"G00 X50. Z-10.", &lathe_state(50, -10, 0));
        assert_eq!(walk.moves.len(), 2);
        assert!(walk.lane.is_some());
        step_text(&mut walk, 4, b"G00 C90.", &lathe_state(50, -10, 0));
        assert!(walk.moves.is_empty() && walk.lane.is_none());
        assert_eq!(walk.side_move, Some((4, b'C')));
        // a move of X with C: kept, but as no way (its path is not along X and Z alone)
        step_text(&mut walk, 5, b"G00 X40. C0.", &lathe_state(40, -10, 0));
        assert_eq!(walk.moves.len(), 1);
        assert_eq!(walk.moves[0].motion, None);
        step_text(&mut walk, 6, b"M03", &lathe_state(40, -10, 0));
        assert_eq!((walk.side_move, walk.spin_line), (None, 6));
    }

    #[test]
    fn a_keyed_start_is_the_spindles_until_m03_m04_or_m05_and_a_mills_builder_code_until_m05() {
        // review 56a F9: a builder's M13 (spindle and coolant) keyed by the profile, and one
        // the profile's list lacks
        let mut walk = Walk::new(Control::Fanuc, false, false);
        walk.turn_codes = vec![13];
        step_text(&mut walk, 1, b"S1000 M13", &state());
        assert_eq!((walk.turned_by, walk.spin_line), (Some((1, 13)), 1));
        step_text(&mut walk, 2, b"G00 X1.", &state());
        assert_eq!(walk.turned_by, Some((1, 13)));
        step_text(&mut walk, 3, b"M05", &state());
        assert_eq!(walk.turned_by, None);
        // review 56d F1: its coolant outlasts the M05 and ends at M09, a mill's M06 or M30
        let mut cooled = Walk::new(Control::Fanuc, false, false);
        (cooled.turn_codes, cooled.coolant_starts) = (vec![13, 14], vec![13, 14]);
        for (line, ends) in [(2, &b"M09"[..]), (4, b"T2 M06"), (6, b"M30")] {
            step_text(&mut cooled, line - 1, b"S1000 M14", &state());
            step_text(&mut cooled, line, b"M05", &state());
            assert_eq!(cooled.keyed_coolant, Some((line - 1, 14)));
            step_text(&mut cooled, line, ends, &state());
            assert_eq!(
                cooled.keyed_coolant,
                None,
                "{}",
                String::from_utf8_lossy(ends)
            );
        }
        let mut unlisted = Walk::new(Control::Fanuc, false, false);
        unlisted.lacks_m = Some((0..100).map(|m| m == 13).collect());
        step_text(&mut unlisted, 1, b"S1000 M13", &state());
        assert_eq!(unlisted.builder_m, Some((1, 13)));
        step_text(&mut unlisted, 2, b"M05", &state());
        assert_eq!(unlisted.builder_m, None);
    }

    #[test]
    fn the_spindle_orientation_holds_until_m03_m04_or_m05() {
        // review 35, finding 1
        let mut walk = Walk::new(Control::Haas, false, false);
        walk.orient_codes = vec![19];
        step_text(&mut walk, 1, b"S800 M03", &state());
        step_text(&mut walk, 2, b"M19 P0", &state());
        assert_eq!(walk.oriented, Some((2, 19)));
        step_text(&mut walk, 3, b"G00 X1.", &state());
        assert_eq!(walk.oriented, Some((2, 19)));
        step_text(&mut walk, 4, b"M05", &state());
        assert_eq!(walk.oriented, None);
    }

    #[test]
    fn a_second_m19_ends_no_orientation_and_a_hint_goes_back_to_the_first() {
        // review 38, finding 5
        let mut walk = Walk::new(Control::Haas, true, true);
        walk.orient_codes = vec![19];
        step_text(&mut walk, 1, b"M05", &state());
        step_text(&mut walk, 2, b"M19", &state());
        step_text(&mut walk, 3, b"G00 X1.", &state());
        step_text(&mut walk, 4, b"M19", &state());
        assert_eq!(walk.oriented, Some((4, 19)));
        assert_eq!(walk.oriented_since(), Some(2));
        // in force from line 3 on (a restart at line 2 walks nothing of it)
        assert_eq!(walk.before_orientation(2), 2);
        assert_eq!(walk.before_orientation(3), 2);
        assert_eq!(walk.before_orientation(5), 2);
        step_text(&mut walk, 5, b"S300 M03", &state());
        assert_eq!((walk.oriented, walk.oriented_since()), (None, None));
        // ended by line 5's M03: a restart at line 5 still walks it, at 6 not
        assert_eq!(walk.before_orientation(5), 2);
        assert_eq!(walk.before_orientation(6), 6);
        step_text(&mut walk, 6, b"M05", &state());
        step_text(&mut walk, 7, b"M19", &state());
        assert_eq!(walk.orientations, [(2, Some(5)), (7, None)]);
        assert_eq!(walk.before_orientation(9), 7);
        assert_eq!(walk.before_orientation(4), 2);
        assert_eq!(walk.before_orientation(1), 1);
    }

    #[test]
    fn a_haas_g107_loses_its_rotary_axis_at_the_cancel() {
        // review 35, finding 4
        let mut walk = Walk::new(Control::Haas, false, false);
        let a = axis_index(b'A').unwrap_or(0);
        step_text(&mut walk, 1, b"G00 X0 Y0 A0", &state());
        step_text(&mut walk, 2, b"G107 A0 Y0 R1.", &state());
        step_text(&mut walk, 3, b"G01 Y2.", &state());
        assert!(walk.lost[a].is_none());
        step_text(&mut walk, 4, b"G107", &state());
        assert_eq!(walk.lost[a].as_ref().map(|l| l.line), Some(4));
    }

    #[test]
    fn a_haas_lathe_g113_loses_c_and_leaves_the_virtual_y_unset() {
        // review 35, findings 8 and 9
        let (c, y) = (axis_index(b'C').unwrap_or(0), axis_index(b'Y').unwrap_or(0));
        let mut walk = Walk::new(Control::Haas, true, true);
        walk.m_modes = vec![
            (154, "C axis", true, "C axis engage".into()),
            (155, "C axis", false, "C axis disengage".into()),
        ];
        step_text(&mut walk, 1, b"T0505", &state());
        step_text(&mut walk, 2, b"M154", &state());
        assert!(walk.mode_hints.iter().any(|(k, h)| {
            *k == "C axis" && h == "restart at or before line 2, or after the M155 that ends it"
        }));
        step_text(&mut walk, 3, b"G00 X2. Z0.1 C0.", &lathe_state(2, 0, 0));
        step_text(&mut walk, 4, b"G112", &state());
        step_text(&mut walk, 5, b"G01 X0.5 Y0.5", &state());
        step_text(&mut walk, 6, b"G113", &state());
        assert_eq!(walk.lost[c].as_ref().map(|l| l.line), Some(6));
        assert!(walk.lost[y].is_none() && walk.unset & bit(y) != 0);
        step_text(&mut walk, 7, b"M155", &state());
        assert!(walk.lost[c].is_none() && walk.unset & bit(c) != 0);
        step_text(&mut walk, 8, b"G00 C10.", &state());
        assert_eq!(walk.unset & bit(c), 0);
        // a Y the program had before G112: not known after G113
        let mut real = Walk::new(Control::Haas, true, true);
        step_text(&mut real, 1, b"G00 X2. Y0 Z0.1", &lathe_state(2, 0, 0));
        real.seen |= bit(y);
        step_text(&mut real, 2, b"G112", &state());
        step_text(&mut real, 3, b"G01 X0.5 Y0.5", &state());
        step_text(&mut real, 4, b"G113", &state());
        assert_eq!(real.lost[y].as_ref().map(|l| l.line), Some(4));
        assert_eq!(real.unset & bit(y), 0);
    }
}
