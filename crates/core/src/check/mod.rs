//! The checker: a program against a machine profile, rule by rule (`docs/rules.md`).
//!
//! One pass over the blocks in flat memory. Each block is read into its words (address,
//! index, sign, number or expression, column), the words are checked on their own (order,
//! repetition, Annex C formats), the block is applied to the one [`ModalMachine`], and the
//! codes, motion, arcs, cycles, feeds and limits are checked against the state before and
//! after it. Findings are handed out as they are found; the program-level ones (its start and
//! end) come from [`Checker::finish`]. This is the only implementation of the rules: the
//! Python `postproc.check` only gives the profile to it and turns its findings into reports.
//!
//! This module holds the profile ([`Config`]), the [`Checker`] and its walk over a block; the
//! rules are in one module per family of the registry (`rules::Family`), each an `impl
//! Checker` block with its unit tests: `structure`, `words`, `formats`, `codes`, `motion`,
//! `tooling`, `limits` and `link`. Beside them, `params` (what is known of parameters) and
//! `stats` (the statistics and the path) report no rule.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use crate::decimal::Dec;
use crate::dialect::{self, PastFormat};
use crate::geometry::RadiusArc;
use crate::lex::{blank, Dialect, Family, Token};
use crate::modal::{bit, BlockValues, ModalMachine, ModalSettings, ModalState, Units, AXES};
use crate::rules::{Rule, Selection};
use crate::statement::Kind;
use crate::text::column;
use crate::tokenizer::{
    plain_line_words, plain_line_words_to_lf, plain_words_without_brackets, tokenize, Extras,
};
use crate::word::{Numbers, ReadsBlocks};
use crate::wordformat::WordFormat;
use formats::FormatTable;

pub use crate::word::{Role, Word};
pub use codes::{turning_codes, TURNING_KEYS};
pub use drawn::Drawn;
pub use link::tv_message;
pub use motion::in_one_quadrant;
pub use structure::nested_comment;

// the rules, by family
mod after;
mod bodyrun;
mod called;
mod callflow;
mod callmode;
mod codes;
mod formats;
mod leaves;
mod limits;
mod link;
mod motion;
mod oflow;
mod polar;
mod reach;
mod reference;
mod resumed;
mod shapes;
mod structure;
#[cfg(test)]
pub(crate) use structure::walk_expression;
mod targets;
mod tooling;
mod words;
// beside them
mod drawn;
mod params;
mod passed;
mod stats;
#[cfg(test)]
mod testing;

/// How a control reads I J K (7.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ijk {
    Incremental,
    Absolute,
    Quadrant,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    Assigned,
    Conditional,
    Unassigned,
    Permanent,
}

/// One G or M code of the profile's table.
#[derive(Debug, Clone)]
pub struct Code {
    pub status: Status,
    /// The modal group, or "" / "TBO" for a code that is not modal.
    pub duration: String,
}

impl Code {
    fn modal(&self) -> bool {
        !(self.duration.is_empty() || self.duration == "TBO")
    }
}

/// A word whose value names a block or a program in the blocks of one code (`words` of a
/// profile's `[codes]` entry): `G71 P100 Q200` names sequence numbers, `M98 P1234` a program.
/// In such a block the word has the format of the address that numbers what it names (N or
/// O), and what the control does with digits past it (`checks.past_sequence` for N).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CodeWord {
    /// The code: its letter (G or M) and number as [`code_number`] writes it (`71`, `54.1`).
    pub code: (u8, Vec<u8>),
    pub letter: u8,
    pub address: u8,
}

/// A code's number as written (`071`, `54.10`, `71.`), in the one form [`CodeWord`] keeps it
/// (`71`, `54.1`): leading zeros and a fraction's trailing zeros left out. Compared byte for
/// byte, with no number read (asked for every G and M word of a Fanuc or Haas program).
pub fn code_number(number: &[u8]) -> &[u8] {
    let mut n = number;
    if n.contains(&b'.') {
        while let [rest @ .., b'0'] = n {
            n = rest;
        }
        if let [rest @ .., b'.'] = n {
            n = rest;
        }
    }
    while n.len() > 1 && n[0] == b'0' && n[1] != b'.' {
        n = &n[1..];
    }
    n
}

/// What a profile says that the checker reads as it is, decided by no family rule: a part of
/// [`crate::machine::MachineSpec`], kept whole in the compiled [`Config`] (which reads as it
/// through `Deref`), so each fact is declared once.
#[derive(Debug, Clone)]
pub struct ProfileFacts {
    /// The control's tape reader searches for ':' as its alignment (rewind) stop even inside a
    /// comment (`checks.comment_colon = "stop"`): each such comment is TG122, an error. Else a
    /// comment's ':' is text (a CAM time stamp `(21:09)`): one TG126 note per file, counted.
    pub colon_stop: bool,
    /// The classification has `%`: the program must begin with it (TG110, TG115).
    pub percent: bool,
    /// The word formats the profile's classification names, by letter.
    pub formats: Vec<(u8, WordFormat)>,
    /// The formats of the letters that differ while inch is in force (Fanuc IS-B: X+044 for
    /// 0.0001 in against X+053 for 0.001 mm); None: the same formats in both units.
    pub formats_inch: Option<Vec<(u8, WordFormat)>>,
    /// The F word's format in feed per revolution (G95, a lathe's G99), metric and inch: the
    /// classification's "feed per revolution" facility note (of `detailed`, `detailed_inch`),
    /// where the control reads such a feed to more decimals than a feed per minute (FANUC
    /// 0i-F: 0.0001 mm/rev against 0.01 mm/min). None: F's own format.
    pub feed_rev_formats: [Option<WordFormat>; 2],
    /// The profile's classification has DS: explicit decimal signs.
    pub explicit: bool,
    /// A word without a decimal point is a count of least increments (Fanuc), but for these
    /// letters; None: a whole number (ISO 6983-1).
    pub increments: Option<Vec<u8>>,
    pub alignment: bool,
    /// `str()` of the detailed classification, for TG134.
    pub classification: String,
    pub table_name: String,
    /// G codes 0..1000 and M codes 0..100 of the profile (its table and its own codes).
    pub g_codes: Vec<Option<Code>>,
    /// The profile's G codes with a decimal (`"91.1"`), each a code of its own.
    pub g_decimal: Vec<(String, Code)>,
    pub m_codes: Vec<Option<Code>>,
    pub program_number: Option<u8>,
    pub tv_check: bool,
    pub arc_tolerance: f64,
    pub arc_tolerance_relative: f64,
    pub ijk: Ijk,
    pub repeatable: Vec<u8>,
    pub m_classes: Vec<i64>,
    pub max_index: u64,
    pub max_parameter: u64,
    /// `checks.read_only`: the numbered variables the control's documentation gives read only
    /// (first, last, what each holds), an assignment to one being TG209, beside the family's
    /// own list ([`crate::dialect::read_only_variable`]); None where the profile states none.
    pub read_only: Option<Vec<(u64, u64, String)>>,
    /// What the control does with decimals past its resolution, and with a sequence number
    /// longer than its format (TG203/TG205 errors where it alarms, else TG208).
    pub past_decimals: PastFormat,
    pub past_sequence: PastFormat,
    /// The words that name a block or a program in a code's blocks, by code.
    pub code_words: Vec<CodeWord>,
    pub index_g: bool,
    pub travel: Vec<(u8, Dec, Dec)>,
    /// The profile's work offsets: (54..59, axis, the machine position of the work zero in the
    /// profile's units). Where the one in force is known, a work position is a machine
    /// position, checked against the travel.
    pub work_offsets: Vec<(i64, u8, Dec)>,
    pub feed_max: Option<Dec>,
    pub spindle_max: Option<Dec>,
    /// The limits that are a built-in profile's, a sample machine of the family, not the
    /// user's own ([`SAMPLE_TRAVEL`], [`SAMPLE_FEED`], [`SAMPLE_SPINDLE`], [`SAMPLE_TOOLS`]):
    /// every one on a built-in profile, none on a profile file without a `base`, and on a file
    /// with one those its own `[limits]` do not set. A spindle speed above a sample maximum is
    /// TG606, a warning, and TG603, the error, above the user's; the first finding against a
    /// sample limit says it is one.
    pub sample_limits: u8,
    pub tool_max: Option<i64>,
    pub rapid_rate: f64,
    /// The units of the limits, the work offsets, the rapid rate and the statistics: the
    /// profile's `units`, also where the machine's units at the program's start were given
    /// otherwise (`check --units`, `convert --from-units`: the modal settings' start units).
    pub limit_units: Units,
}

/// [`ProfileFacts::sample_limits`]: the travel is a sample machine's.
pub const SAMPLE_TRAVEL: u8 = 1;
/// [`ProfileFacts::sample_limits`]: the feed maximum is a sample machine's.
pub const SAMPLE_FEED: u8 = 2;
/// [`ProfileFacts::sample_limits`]: the spindle speed maximum is a sample machine's.
pub const SAMPLE_SPINDLE: u8 = 4;
/// [`ProfileFacts::sample_limits`]: the tool number maximum is a sample machine's.
pub const SAMPLE_TOOLS: u8 = 8;
/// [`ProfileFacts::sample_limits`] of a built-in profile: every limit a sample machine's.
pub const SAMPLE_ALL: u8 = SAMPLE_TRAVEL | SAMPLE_FEED | SAMPLE_SPINDLE | SAMPLE_TOOLS;

/// Everything the checker needs from a profile, resolved once (the checker's part of a
/// [`crate::machine::Machine`], shared by every checker of that machine): the profile's facts,
/// and what [`crate::machine::Machine::new`] decides from the family and the kind of machine.
#[derive(Debug, Clone)]
pub struct Config {
    pub facts: ProfileFacts,
    /// The control family of the profile's dialect. Siemens (`%MPF 90`) and Heidenhain
    /// (`%PART G71 *`) name the program on the `%` line (no TG111/TG112); LinuxCNC and Siemens
    /// read lower case natively (no TG102); '%' in a comment stops a transfer under every
    /// family but LinuxCNC's (TG122).
    pub family: Family,
    /// The control alarms on a G (M) code it does not have: TG306, an error, instead of the
    /// TG301/TG302/TG303 warnings.
    pub alarm_g: bool,
    pub alarm_m: bool,
    /// A Fanuc or Haas lathe: X is a diameter, so an arc in G18 has X/2 as its coordinate.
    pub diameter: bool,
    /// The roles of P, Q and R.
    pub pqr: [Role; 3],
    /// A number that is no length (a dwell's time, a scale factor, a cycle's dwell: P of the
    /// profile's or the cycle's role "other"), written with its decimal point, is read as
    /// written whatever the address's format holds: a Haas reads `G04 P1.5` as 1.5 s,
    /// `G51 P1.5` as the factor 1.5 (Haas mill operator's manual, G51: "P scaling factor,
    /// 0.001 to 999.999"), `G82 .. P0.5` as 0.5 s (no TG208 for its decimals).
    pub pointed_numbers: bool,
    /// A Haas control: its own wording where it differs from FANUC's (a read-only variable).
    pub haas: bool,
    /// The M codes that turn a spindle, by their meaning key in the profile
    /// ([`turning_codes`]): the one place the checker learns it.
    pub turning: Vec<i64>,
    pub modal: ModalSettings,
}

impl std::ops::Deref for Config {
    type Target = ProfileFacts;

    fn deref(&self) -> &ProfileFacts {
        &self.facts
    }
}

impl Config {
    /// How this profile's numbers are read (formats, DS, least increments).
    pub fn numbers(&self) -> Numbers<'_> {
        Numbers {
            formats: &self.formats,
            formats_inch: self.formats_inch.as_deref(),
            explicit: self.explicit,
            increments: self.increments.as_deref(),
        }
    }

    /// Whether a word of `letter` written without a decimal point counts least increments.
    pub fn reads_increments(&self, letter: u8) -> bool {
        self.numbers().reads_increments(letter)
    }

    /// The values of a block's word tokens as the modal state reads them on its own
    /// ([`Numbers::block_values`]), `cycle` the code in force before the block that a block
    /// naming none repeats (`ModalState::code_in_force`), by which a K is the cycle's count
    /// as the checker reads it ([`crate::convert::block_counts`]).
    pub fn block_values(
        &self,
        tokens: &[&[u8]],
        units: (Units, Units),
        cycle: Option<i64>,
        out: &mut BlockValues,
    ) {
        let counts = crate::convert::block_counts(&self.modal, cycle, tokens);
        self.numbers().block_values(tokens, units, counts, out);
        out.in_system(&self.modal);
    }

    /// The format of `letter` in `units`, if the profile names one.
    pub fn format_in(&self, letter: u8, units: Units) -> Option<&WordFormat> {
        self.numbers().format_in(letter, units)
    }

    fn role(&self, letter: u8) -> Option<Role> {
        match letter {
            b'P' => Some(self.pqr[0]),
            b'Q' => Some(self.pqr[1]),
            b'R' => Some(self.pqr[2]),
            _ => None,
        }
    }

    /// A decimal G code of the profile (`G54.1` is `54.1`): its place in `g_decimal` and its
    /// facts.
    fn decimal_code(&self, value: Dec) -> Option<(usize, &Code)> {
        let code = value.to_string();
        self.g_decimal
            .iter()
            .position(|(c, _)| *c == code)
            .map(|i| (i, &self.g_decimal[i].1))
    }

    fn code(&self, letter: u8, number: i64) -> Option<&Code> {
        let table = if letter == b'G' {
            &self.g_codes
        } else {
            &self.m_codes
        };
        usize::try_from(number)
            .ok()
            .and_then(|n| table.get(n))
            .and_then(Option::as_ref)
    }
}

impl ReadsBlocks for Config {
    fn modal_settings(&self) -> &ModalSettings {
        &self.modal
    }

    fn numbers(&self) -> Numbers<'_> {
        Config::numbers(self)
    }
}

/// One rule broken at one place.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Finding {
    pub rule: Rule,
    pub message: String,
    pub line: usize,
    pub column: usize,
    /// A TG601 of a span of positions wider than the travel (no work offset fits), not of
    /// one position: a program read apart and then judged alone judges its spans again with
    /// its own, and drops those said with the spans before it (called.rs).
    pub span: bool,
    /// A TG601 of a machine position under the work offset the program before left, in a
    /// program read apart that no call before it names ([`Checker::work_offset_unknown`]):
    /// said only where a call runs it under that offset (called.rs).
    pub guessed: bool,
    /// What a TG601 of one machine position compared: set where it is made (limits.rs),
    /// read where a subprogram's are judged at a call (called.rs).
    pub placed: Placed,
    /// A subprogram's machine position under a work offset said at a call after which its
    /// caller had called programs the checker had not read there (their O numbers: written
    /// after that call, or not in the file): held to the file's end, and dropped there
    /// where one of them, read after all, writes that offset's axis (review 58d F1: a G10
    /// of an O100 written after the main that calls it before the call of O2000).
    pub pending_on: Vec<i64>,
}

/// The machine position a TG601 judged ([`Finding::placed`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Placed {
    /// Not one position's (another rule, a span, a run of increments).
    #[default]
    Not,
    /// A position written in machine coordinates (G53).
    Machine,
    /// The work position `at` (in the profile's units) of the axis of place `place` plus
    /// the profile's value of work offset G`work` (54-59) on that axis: at a call after a
    /// G10 that wrote that value it is judged again with the value written.
    /// `line`: the line of `at`, the farthest position of its excursion
    /// ([`Checker::excursion_farther`]).
    Offset {
        place: u8,
        work: u8,
        at: f64,
        line: usize,
    },
}

// (`at` is a position read, never NaN)
impl Eq for Placed {}

/// One move, for the backplot. Positions as programmed (a lathe's X a diameter, its centre's
/// X too).
#[derive(Debug, Clone)]
pub struct Segment {
    /// "rapid", "feed", "arc" (by I J K, R or CR=), or "chord": an arc by a radius shorter than
    /// half its chord (TG410), which no arc can be; it is counted as the straight move.
    pub kind: &'static str,
    pub start: [f64; 3],
    pub end: [f64; 3],
    pub line: usize,
    pub centre: Option<[f64; 3]>,
    pub clockwise: bool,
    pub plane: i64,
    /// The arc turns through more than 180 degrees.
    pub large: bool,
}

#[derive(Debug, Clone, Default)]
pub struct Stats {
    pub blocks: usize,
    /// Arcs (G02/G03 by I J K, R or CR=) with their true length in the path lengths.
    pub arcs: usize,
    pub low: [Option<Dec>; 9],
    pub high: [Option<Dec>; 9],
    pub rapid_length: f64,
    pub feed_length: f64,
    pub seconds: f64,
    pub tools: Vec<i64>,
    /// Moves of an axis with travel limits, and how many of them were compared as machine
    /// positions through the profile's work offsets.
    pub travel_moves: usize,
    pub travel_absolute: usize,
    /// Why positions were not compared as machine positions, each said once, in order.
    pub travel_not: Vec<String>,
    /// Where the path stops being known and why, each G code the family's list lacks once
    /// (its first line): the control alarms on it or runs a macro, so the motion it may set
    /// is not known, and the moves after it are left out of the path, its lengths, the cycle
    /// time and the backplot until a motion code the list holds.
    pub moves_not_known: Vec<String>,
    /// Dwells whose time is not known ([`Checker::dwell_time`]), left out of `seconds`: how
    /// many, and why, each kind once at its first line.
    pub dwells_not_counted: usize,
    pub dwells_not_known: Vec<String>,
}

/// [`Checker::read_block`] of a block without words: statements alone (`AP=90`, `DIAMON`, an
/// o-word line), a comment alone, or a LinuxCNC FANUC-style program's O number or M99 line read
/// as the o-word form's (`Checker::linuxcnc_fanuc_program`): one text for both, expanded in
/// the hot `read_block` and in the cold reading of those lines.
macro_rules! statements_only_block {
    ($s:ident, $b:ident) => {{
        let returns = dialect::returns($s.config.family, $b.words, $b.statements, &[]);
        $s.split.ended(returns);
        if returns {
            // RET, RTS: as after M99, what follows starts where a caller left the machine
            // (and no run falls through to it: Checker::jump_arrival)
            $s.sub_ended = true;
            if !$b.skip {
                $s.cut_block = $s.stats.blocks;
            }
            $s.part_ended(true);
            $s.machine.forget();
        }
        if $b
            .statements
            .iter()
            .any(|&(_, kind, text)| kind == Kind::Name && text.first() == Some(&b'<'))
        {
            // a FANUC `<NAME>` alone in its block: where it stands, as an O number's
            let first = std::mem::replace(&mut $s.first_words, false);
            $s.program_name($b, first);
        }
        $s.tv($b);
        $s.jump_arrival($b);
        $s.targets($b);
        for &(column, comment) in $b.comments {
            $s.comment(comment, $b.line, column);
        }
        $s.frames($b);
        $s.named_motions($b);
        // a block of statements alone (`AP=90`, `DIAMON`): no words, its forms still move
        // or set (polar.rs)
        $s.values.clear();
        let before = Before::of(&$s.machine.state);
        $s.programmed_forms($b, &before);
        $s.speed_limit_statement($b);
        $s.formulas($b);
        $s.variables($b);
        if $s.config.haas {
            $s.parameter_elements($b);
        }
        if !$b.statements.is_empty() {
            $s.system_variables($b);
        }
        if $s.statements($b, None) {
            // (before the parameters are forgotten: callflow.rs)
            let never = $s.flow_never($b);
            $s.forget_at_jump($b, false);
            // (a conditional jump forward changes no parameter where it is not taken)
            if !$s.jump_keeps_params($b) {
                $s.params_forgotten();
            } else {
                $s.jump_noted($b);
            }
            $s.motion_unknown = true;
            $s.linuxcnc_motion_after_call($b, false);
            // a subprogram or the blocks jumped over may set another pole
            $s.polar = polar::Polar::default();
            $s.linuxcnc_spindle_unknown = true;
            $s.linuxcnc_uvw_unfollowed($b);
            $s.linuxcnc_compensation_unknown = true;
            $s.linuxcnc_plane_after_call($b, false);
            $s.linuxcnc_rate_after_statement($b);
            $s.linuxcnc_nurbs = tooling::Nurbs::unknown();
            $s.linuxcnc_nurbs_last = None;
            $s.linuxcnc_nurbs_last = None;
            // (a call of a body that keeps them, or a condition's or loop's own line,
            // loses no offset: the two are never one line)
            if !std::mem::take(&mut $s.call_keeps)
                && !$s.linuxcnc_flow_offsets($b)
                && !$s.later_call_if_line($b)
            {
                $s.call_offsets_rewritten($b.line, false, never);
            }
        }
        $s.call_keeps = false;
        $s.call_unread_here = false;
    }};
}

/// A block as the checker sees it.
pub struct BlockView<'a> {
    pub line: usize,
    pub text: &'a [u8],
    /// `text` holds no byte above 0x7F (`text.is_ascii()`): found once a line by its reader,
    /// and asked by the rules that count characters or look for bytes outside ASCII.
    pub ascii: bool,
    /// The CRs of `text` where its reader counted them (the checker's, in a line of plain
    /// words under the TV check: [`crate::tokenizer::PlainLine::crs`]); None where the TV
    /// check counts them itself.
    pub crs: Option<usize>,
    pub words: &'a [Word<'a>],
    pub skip: bool,
    /// The 1-based column of a block skip `/` in the middle of the block (Fanuc, Haas): the
    /// words after it are skipped when the block-skip switch is on.
    pub skip_within: Option<usize>,
    /// Comments with their 1-based columns.
    pub comments: &'a [(usize, &'a [u8])],
    pub percent: bool,
    pub ident: &'a [u8],
    /// The dialect's statements: column, kind and text.
    pub statements: &'a [(usize, Kind, &'a [u8])],
}

/// A block that could not be read: the rule, message and column of its error.
pub struct Unreadable<'a> {
    pub line: usize,
    pub text: &'a [u8],
    pub rule: Rule,
    pub message: &'a str,
    pub column: usize,
}

const DIMENSIONS: &[u8] = b"XYZUVWPQRABC";

/// Whether `letter` is one of [`DIMENSIONS`] (asked for every word: no search of the list).
fn is_dimension(letter: u8) -> bool {
    matches!(
        letter,
        b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'P' | b'Q' | b'R' | b'A' | b'B' | b'C'
    )
}

/// The letters A-Z of `words`, a bit each ([`bit`]); `:` and the other addresses have none,
/// a `#` word sets [`PARAMETER`], a `$`, `@` or `^` word [`SELECTOR`] and a word with an index
/// (`#1=`, `R1=`, `M2=3`) [`INDEXED`].
fn letters_of(words: &[Word<'_>]) -> u32 {
    words.iter().fold(0, |letters, w| {
        let letter = if w.letter.is_ascii_uppercase() {
            bit(w.letter)
        } else if w.letter == b'#' {
            PARAMETER
        } else if matches!(w.letter, b'$' | b'@' | b'^') {
            SELECTOR
        } else {
            0
        };
        let indexed = if w.index.is_empty() { 0 } else { INDEXED };
        letters | letter | indexed
    })
}

/// What [`letters_of`] gives a word by its letter: its bit for A-Z, [`PARAMETER`] for `#`,
/// [`SELECTOR`] for `$`, `@` and `^`, nothing for any other byte (one look a word, where the tests were about ten instructions).
const LETTER_BITS: [u32; 256] = {
    let mut table = [0u32; 256];
    let mut c = b'A';
    while c <= b'Z' {
        table[c as usize] = bit(c);
        c += 1;
    }
    table[b'#' as usize] = PARAMETER;
    table[b'$' as usize] = SELECTOR;
    table[b'@' as usize] = SELECTOR;
    table[b'^' as usize] = SELECTOR;
    table
};

/// [`letters_of`] `words`, and whether their codes are G00-G03 alone as [`motion_codes_only`]
/// reads them, in one walk of the words (each was a walk of its own, asked of every block; a
/// debug build walks both and holds them equal).
fn letters_and_motion(words: &[Word<'_>]) -> (u32, bool) {
    let mut letters = 0;
    let mut motion = true;
    for w in words {
        letters |= LETTER_BITS[usize::from(w.letter)];
        if !w.index.is_empty() {
            letters |= INDEXED;
        }
        if w.letter == b'G' {
            motion &= plain_motion_code(w);
        }
    }
    debug_assert_eq!(letters, letters_of(words));
    debug_assert_eq!(motion, motion_codes_only(words));
    (letters, motion)
}

/// [`Checker::letters`]: the block has a `#` word (a parameter set, or a value read from one).
const PARAMETER: u32 = 1 << 26;
/// [`Checker::letters`]: the block has a word with an index (`#1=5`, `R1=5`, `M2=3`).
const INDEXED: u32 = 1 << 27;
/// [`Checker::letters`]: the block has a `$`, `@` or `^` word (LinuxCNC's spindle selector,
/// a polar distance or angle: `tokenizer`'s words of LinuxCNC and SINUMERIK).
const SELECTOR: u32 = 1 << 28;

/// The column of the byte at an offset of `text`: in an ASCII line, as nearly every one is,
/// the offset and one.
#[inline(always)]
fn at_column(text: &[u8], ascii: bool) -> impl Fn(usize) -> usize + '_ {
    move |offset: usize| {
        if ascii {
            offset + 1
        } else {
            column(text, offset)
        }
    }
}

/// The column of the first word of `letter` in `words`, or 1 where there is none (a finding
/// about that word's block placed at the word it names).
fn column_of(words: &[Word<'_>], letter: u8) -> usize {
    words
        .iter()
        .find(|w| w.letter == letter)
        .map_or(1, |w| w.column)
}

/// Whether two lists of words have the same parts (a debug build's test of
/// [`plain_line_words`]).
fn same_words(a: &[Word<'_>], b: &[Word<'_>]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(a, b)| {
            (a.address, a.letter, a.index, a.sign, a.number)
                == (b.address, b.letter, b.index, b.sign, b.number)
                && (a.expression, a.column, a.token, a.point, a.dot, a.value)
                    == (b.expression, b.column, b.token, b.point, b.dot, b.value)
        })
}

/// An empty vector with the allocation of `buffer`, for elements of another lifetime: the
/// checker keeps one allocation for every block's words (and comments and statements), which
/// borrow the block's line. (`Vec` collects in place an iterator over its own elements mapped
/// to a type of the same size and alignment; the buffer is emptied first, so nothing is
/// mapped.)
fn recycle<T, U>(mut buffer: Vec<T>) -> Vec<U> {
    buffer.clear();
    buffer.into_iter().map(|_| unreachable!()).collect()
}

/// The number of characters of `text` (as Python counts them) before byte `end`.
fn chars(text: &[u8], end: usize) -> usize {
    crate::text::column(text, end) - 1
}

/// What the rules after the codes read of a block: its G codes, the axes it moves and where
/// its words are.
struct Facts<'b> {
    words: &'b [Word<'b>],
    /// The block's G codes 0 to 127, a bit each.
    mask: u128,
    /// The number of G codes the block gives.
    g_count: usize,
    moved: [u8; 9],
    n_moved: usize,
    /// The places in [`AXES`] of `moved` ([`crate::modal::axis_places`]), a bit each.
    places: u32,
}

/// What the rules read of the modal state before a block (the arc's start point, the length
/// of a move, the compensation and the cycle a block leaves): copied from the state before
/// the block is applied. The whole state is 17 `Option<Dec>` of 48 bytes and more, about
/// 1 KB; these are a fifth of it, copied in a few moves where the whole state took a `memcpy`
/// of every block.
#[derive(Debug, Clone, Copy)]
pub(super) struct Before {
    /// X Y Z, the first three of the state's axes ([`AXES`]): the plane's axes of an arc
    /// ([`motion::plane_axes`]) and the points of a move's length.
    xyz: [Option<Dec>; 3],
    unknown: u32,
    compensation: i64,
    /// G17, G18 or G19: LinuxCNC refuses a change of plane under cutter radius compensation.
    plane: i64,
    cycle: Option<i64>,
    /// G91 in force: a HEIDENHAIN block's coordinates before its own G90 or G91 (polar.rs).
    incremental: bool,
}

impl Before {
    fn of(state: &ModalState) -> Before {
        Before {
            xyz: [state.position[0], state.position[1], state.position[2]],
            unknown: state.unknown,
            compensation: state.compensation,
            plane: state.plane,
            cycle: state.cycle,
            incremental: state.incremental,
        }
    }

    /// X, Y or Z as [`ModalState::axis`] has it; no other axis is kept (None).
    pub(super) fn axis(&self, letter: u8) -> Option<Dec> {
        match letter {
            b'X' => self.xyz[0],
            b'Y' => self.xyz[1],
            b'Z' => self.xyz[2],
            _ => None,
        }
    }

    /// As [`ModalState::is_unknown`].
    fn is_unknown(&self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.unknown & crate::modal::bit(letter) != 0
    }
}

/// A SINUMERIK's kinematic transformation in force, from where it was selected.
#[derive(Clone)]
struct Transformed {
    line: usize,
    name: String,
    /// Whether the statistics already say the travel is not compared under it.
    noted: bool,
}

/// The axes of each set of places ([`crate::modal::axis_places`], 9 bits), in the order of
/// [`AXES`], and how many: [`Facts::moved`] of a block without G04, one look where a walk of
/// the places cost about 35 instructions a block.
const MOVED: [([u8; 9], u8); 512] = {
    let mut table = [([0u8; 9], 0u8); 512];
    let mut places = 0;
    while places < 512 {
        let mut n = 0;
        let mut i = 0;
        while i < 9 {
            if places >> i & 1 != 0 {
                table[places].0[n] = AXES[i];
                n += 1;
            }
            i += 1;
        }
        table[places].1 = n as u8;
        places += 1;
    }
    table
};

impl<'b> Facts<'b> {
    /// `dwell`: the control's dwell words, no move in a G04 block.
    fn new(words: &'b [Word<'b>], values: &BlockValues, dwell: &[u8]) -> Facts<'b> {
        let places = crate::modal::axis_places(values.given());
        // (a block without G04: the axes of its letters, looked up by their places)
        let (moved, n_moved, places) = if values.has_g(4) {
            let mut moved = [0u8; 9];
            let mut n_moved = 0;
            let mut kept = 0;
            // (the axes in the block's letters alone: most blocks write two or three of nine)
            for i in crate::modal::places(places) {
                let a = AXES[i];
                if !dwell.contains(&a) {
                    moved[n_moved] = a;
                    n_moved += 1;
                    kept |= 1 << i;
                }
            }
            (moved, n_moved, kept)
        } else {
            let (moved, n_moved) = MOVED[places as usize];
            (moved, usize::from(n_moved), places)
        };
        Facts {
            words,
            mask: values.g_mask(),
            g_count: values.gs().len(),
            moved,
            n_moved,
            places,
        }
    }

    /// Whether the block gives G`g`.
    fn has(&self, g: i64) -> bool {
        (0..128).contains(&g) && self.mask & (1 << g) != 0
    }

    /// The column of the block's first word of `letter`, else of its first word.
    fn col(&self, letter: u8) -> usize {
        self.words
            .iter()
            .find(|w| w.letter == letter)
            .map_or(self.words[0].column, |w| w.column)
    }

    /// The axes the block moves, in the order of [`AXES`].
    fn moved(&self) -> &[u8] {
        &self.moved[..self.n_moved]
    }

    /// The places in [`AXES`] of the axes the block moves ([`Facts::moved`]), a bit each.
    fn moved_places(&self) -> u32 {
        self.places
    }
}

/// Blocks of an odd number of characters, for the TV check (TG703, said once at the end).
#[derive(Debug, Clone, Copy, Default)]
struct OddBlocks {
    count: usize,
    /// The first one's line and length.
    line: usize,
    length: usize,
}

/// Comments holding a harmless ':' (TG126, said once at the end).
#[derive(Debug, Clone, Copy, Default)]
struct Colons {
    count: usize,
    /// The first one's line and column.
    line: usize,
    column: usize,
}

/// The span of the program's positions in one axis, in the profile's units, and whether
/// TG601 was said for the axis.
#[derive(Debug, Clone, Copy)]
struct Span {
    least: f64,
    most: f64,
    said: bool,
}

/// A word without a point that looked like an implicit-decimal one (TG201).
#[derive(Debug, Clone)]
struct Implicit {
    token: String,
    /// Its value as this control reads it.
    reading: String,
    line: usize,
    column: usize,
    /// Read in least increments (else as a whole number).
    increments: bool,
}

/// [`Checker::shift_ends`]: the axes a program's G52s wrote, the local shift it left, and
/// each axis's factor its last G52 was read at (0 where exact).
type ShiftEnd = (u16, [f64; 9], [f64; 9]);

/// A LinuxCNC definition's body as [`Checker::linuxcnc_bodies`] keeps it: its label, whether
/// it may set the feed mode or end the program, the labels it calls, the distance mode it
/// returns in, its refusals that wait for a call ([`structure::CallRefusal`]), and whether a
/// call of it surely ends the program (its M2 or M30; review 48, c19), and whether it surely
/// moves no axis and changes nothing the position is read in ([`structure::still_line`]).
type LinuxCncBody = (
    Vec<u8>,
    bool,
    Vec<Vec<u8>>,
    structure::Distance,
    Vec<structure::CallRefusal>,
    bool,
    bool,
);

#[derive(Clone)]
pub struct Checker {
    pub config: Arc<Config>,
    /// The rules this run reports (`select`, `ignore`), one flag per rule.
    selection: Selection,
    /// Keep every move in [`Checker::path`] (the backplot).
    record_path: bool,
    /// Whether the statistics' extents, lengths, arcs and time are kept ([`Checker::stats`]):
    /// asked of every move, and read only where a report shows them (`check --stats`).
    keep_stats: bool,
    pub machine: ModalMachine,
    pub stats: Stats,
    /// Each axis's extent in the statistics as floats, for [`Checker::widen`].
    inside: [Option<stats::Inside>; 9],
    pub path: Vec<Segment>,
    /// What the backplot needs beyond the path, where the path is recorded.
    pub drawn: Drawn,
    /// The programs of the file begun after its first (`dialect::ProgramSplit`): a reader
    /// beside the checker (the restart walk) starts its own state afresh when it grows.
    pub programs: usize,
    split: dialect::ProgramSplit,
    /// The block in hand is a Custom Macro B call (G65, G66): its words are the macro's
    /// arguments, any of them a real number (`G65 P9732 S1. W2.`). Worked out only for a
    /// FANUC block with an M, S or T word, whose point is all it is asked for.
    macro_arguments: bool,
    /// The block in hand has an M code the profile's table lacks, on a FANUC: its parameters
    /// 6080-6089 may make it a custom macro call, whose arguments are real numbers, so a
    /// decimal point in S or T there is PS0007 only where it is not one (TG307, a warning).
    /// Worked out only for a block with S or T and M: the M word as written.
    m_call_possible: Option<String>,
    /// A SINUMERIK program's first block of its program section (its line), after which a
    /// `DEF` is out of place (TG109); None in the definition section.
    program_section: Option<usize>,
    /// Where a LinuxCNC file stops being read (`dialect::ReadingEnd`): the lines after are
    /// passed over.
    reading_end: dialect::ReadingEnd,
    found: Vec<Finding>,
    first: bool,
    first_words: bool,
    /// The bit in [`Checker::letters`] of the profile's program number letter, which TG113
    /// looks for in a block after the first ([`Checker::program_number`]): 0 where none is
    /// looked for (none, `:`, or P, Q, R), every bit for a letter the mask does not hold.
    program_letter: u32,
    /// The program part a memory backup's folder marker (`&F=/USER/PATH2/`) began holds
    /// nothing else yet: an empty folder, not a program (no TG114 at its end).
    empty_folder: bool,
    /// A Haas file's offsets section: the `O999999` after a program's end heads the offsets
    /// the control saves with it (Setting 156), no program (no TG114, its lines not read).
    offsets_section: bool,
    ended_line: usize,
    /// A program of the file ended with M02/M30 (a main program): the file's first program,
    /// where it ends in M99, is then not the one the control starts (called.rs).
    main_ended: bool,
    /// LinuxCNC: the definition open is a FANUC-style O number program after the main
    /// program's end, closed by its M99 ([`Checker::linuxcnc_fanuc_program`]).
    linuxcnc_fanuc_open: bool,
    /// LinuxCNC: the main program's `M98 P..` calls surely run of a program not read yet:
    /// its label (`o300`) and line ([`Checker::linuxcnc_call_forms`]).
    linuxcnc_m98_calls: Vec<(Vec<u8>, usize)>,
    /// LinuxCNC: the program numbers an `M98 P..` names before the line in hand
    /// ([`Checker::linuxcnc_fanuc_line`]).
    linuxcnc_m98_numbers: Vec<i64>,
    /// LinuxCNC: the labels of the definitions opened after the main program's end, and
    /// whether the one open is the first of its label ([`Checker::linuxcnc_call_forms`]).
    linuxcnc_defs_after: Vec<Vec<u8>>,
    linuxcnc_def_first: bool,
    /// LinuxCNC: the line of an M2/M30 that ends the FANUC-style program open, which the next
    /// line closes ([`Checker::subroutine_file`]).
    linuxcnc_fanuc_close: Option<usize>,
    /// LinuxCNC: the line of the main program's M99 that ended it (0: none;
    /// [`Checker::linuxcnc_main_m99`]).
    linuxcnc_m99_end: usize,
    /// An M02/M30 the block skip passes over came last, which ends the program only with the
    /// switch off. LinuxCNC (`/M2`): no end for the lines after it, but an end for TG114. The
    /// other families (`/M30`, or an M30 after a `/` in the block's middle): the end on
    /// `ended_line`, but with the switch on the control runs the blocks after it, so they are
    /// no words after the end (TG106).
    skipped_end: bool,
    /// The last end or return (M02, M30, M99) the block skip can pass over: with the switch
    /// on the control runs on into the program written after it, which is then not one no
    /// call names ([`Checker::judged_alone`]; review 56e, F4).
    end_skippable: bool,
    /// The program has met an M02/M30 that surely runs: on LinuxCNC not one inside an o-word
    /// condition or loop of the main program or inside a definition, which may not run
    /// (rs274 reads on where it does not: review 19). The rules that judge the main program's
    /// lines up to its end (a named parameter not yet set, a definition after its call) read
    /// this, not `ended_line`.
    surely_ended: bool,
    /// LinuxCNC: the line of the main program's first call surely run of a body read before
    /// it that surely ends the program (0: none): the lines after it up to the main program's
    /// own end are never read.
    linuxcnc_call_ended_at: usize,
    /// LinuxCNC: the depth of the main program's open conditions and loops at an M02/M30
    /// inside one: the lines after it in its block run only where it did not run, and never
    /// in the rest of its branch; so they are taken as after the end until the block closes
    /// below that depth (`Checker::main_ended`).
    linuxcnc_end_depth: Option<usize>,
    after_end_reported: bool,
    closed: bool,
    styles_explicit: bool,
    styles_implicit: bool,
    mixed_reported: bool,
    /// The first arc error (TG403, TG405) after TG201 said that whole numbers without a point
    /// are read in least increments names that as a likely cause, once per file.
    arc_cause_said: bool,
    /// The first finding against a built-in profile's machine says its limits are a sample's.
    limits_hint_said: bool,
    /// A SINUMERIK's master spindle, the plain M function's (`SETMS(2)`).
    master: codes::Master,
    /// A SINUMERIK's condition, loop, jump or label so far: the blocks after it may not run
    /// ([`Checker::set_master`]).
    flow_seen: bool,
    /// TG140 and TG141 are said once per file: what the checker could not follow.
    unfollowed_noted: bool,
    unknown_noted: bool,
    /// TG212 is said once per Haas NGC parameter element (`#30003.078`) and file.
    elements_noted: HashSet<Vec<u8>>,
    /// Parameters set to a constant since the last jump or call (`#101 = 250.`, `R1=5`,
    /// `#<depth> = 2`), by name: what the checker knows statically, so `F#101` is the feed 250.
    params: HashMap<Vec<u8>, Dec>,
    /// LinuxCNC: the parameters known where the definition open was read (`o100 sub`): rs274
    /// reads its body without running it, so an endsub's computed label (`o#1 endsub`) has
    /// their values where rs274 reads it.
    linuxcnc_sub_params: HashMap<Vec<u8>, Dec>,
    /// LinuxCNC: the block (`stats.blocks`) whose endsub closed the main program's
    /// definition: the parameters it forgets are the ones known at its sub
    /// ([`Checker::params_forgotten`]).
    linuxcnc_sub_closed: Option<usize>,
    /// Custom Macro B: the sequence numbers a `GOTO` already read names (a jump forward may
    /// arrive at them), and whether one named its target by a value (`GOTO #1`: any may be).
    /// (Each with the line of the first jump naming it and whether another names it too;
    /// `goto_computed_line`: the last computed one's.)
    goto_targets: HashMap<u64, (usize, bool)>,
    goto_computed: bool,
    goto_computed_line: usize,
    /// SINUMERIK: the block numbers (`N100`, in capitals) a jump already read names, each
    /// with the line of the first and whether another names it too.
    goto_names: HashMap<Vec<u8>, (usize, bool)>,
    /// The program's sequence numbers and the blocks its words name (TG118).
    targets: targets::Targets,
    /// Whether the lines read now are reached (TG108).
    reach: reach::Reach,
    /// The last block a jump may arrive at, with the values known there in file order: the
    /// values where no jump arrives, which a jump may not bring ([`params::Arrival`]).
    arrival: Option<params::Arrival>,
    /// The words of the block on line `arrival_line` read with a value of the arrival
    /// (`X#1`, a position, feed, speed or tool number where the jump is not taken): their
    /// letters, forgotten after the block, and each one's column, word and value, named in
    /// a limit's finding at it ([`Checker::report`]).
    arrival_line: usize,
    arrival_letters: u32,
    arrival_words: Vec<(usize, String, Dec)>,
    /// The runs where a forward conditional jump is taken ([`params::Taken`]): the checker
    /// as it stood after each jump read whose target has not come yet (`jumps_pending`), and
    /// those whose target has come and that read the blocks from there on beside this one
    /// (`runs`, judged by the limits where they differ from the fall-through's values).
    /// `after_block`: a block's end has work for them (a jump to note, runs to feed).
    /// `run_target`: in a run, the line of its target (0 in the checker of the file).
    jumps_pending: Vec<params::Taken>,
    runs: Vec<params::Taken>,
    jump_to_note: Option<(usize, Vec<u8>, bool)>,
    after_block: bool,
    run_target: usize,
    /// In a run, the file's reading of the block in hand: Some(whether it has a condition)
    /// where it jumps forward alone ([`Checker::forward_jump`]).
    run_jump: Option<bool>,
    /// The block count (`stats.blocks`) of the last block that leaves unconditionally (a
    /// `GOTO` outside an IF, M02/M30, M99): a block a jump may arrive at right after it is
    /// reached by no fall-through, and its values in file order are no values at all.
    cut_block: usize,
    /// SINUMERIK: each `D=R1` under G41/G42 quieted by a known value ([`params::QuietD`]),
    /// and the line each R parameter or variable was last assigned on: a jump back to a
    /// block number before the D that passes over an assignment of what it reads makes
    /// its D unknown on the next pass (review 41, finding 3).
    quiet_d: Vec<params::QuietD>,
    assigned_at: HashMap<Vec<u8>, usize>,
    /// Odd-length blocks for the TV check (said once, at the end).
    tv_odd: OddBlocks,
    /// Comments holding a harmless ':' (said once, at the end).
    colons: Colons,
    /// A '%' line after the first block.
    percent_closed: bool,
    /// The span of the program's positions per axis (TG601).
    spans: [Option<Span>; 9],
    /// The spans set aside at a selection of another work system whose values are known
    /// (limits.rs, `selection_spans`), joined again where a later position is not judged
    /// as a machine position.
    spans_parked: Option<Box<[Option<Span>; 9]>>,
    /// The axes (their places' bits) whose span holds a position not judged as a machine
    /// position since it last started (limits.rs, `position_not_judged`).
    span_unjudged: u16,
    /// The spans set aside were kept across a call of a program read after the end
    /// (structure.rs, `call_offsets_rewritten`): a later position not judged as a machine
    /// position joins them whether they fit or not, as the call itself joined them before.
    spans_parked_call: bool,
    /// The spans set aside where a body read after the main program's end began under its
    /// calls' system, another than the one the main program ended in (limits.rs,
    /// `body_spans_parked`): the offsets written as it began, to tell at its end whether it
    /// wrote one (or a G90/G91: the count of those codes then).
    spans_parked_body: Option<Box<(limits::Written, u32)>>,
    /// The first word without a point that looked wrong (TG201).
    first_implicit: Option<Implicit>,
    g06_open: Option<usize>,
    speed_limit_seen: bool,
    last_line: usize,
    values: BlockValues,
    readable: Vec<Option<Dec>>,
    /// The block's words by first of their letter and index (TG131/TG132), kept from block to
    /// block.
    seen: Vec<usize>,
    /// The blocks' addresses whose word rules found nothing ([`Checker::words`]).
    clean_blocks: words::CleanBlocks,
    /// The letters A-Z of the block in hand's words ([`letters_of`]), and whether it has a `#`
    /// word ([`PARAMETER`]) or an indexed one ([`INDEXED`]), read once in
    /// [`Checker::read_block`] for the rules that ask whether a block writes a letter at all
    /// (most blocks write no M, no L, no parameter, and a G in some of them only).
    letters: u32,
    /// The block's codes are G00-G03 alone ([`motion_codes_only`]), set once a block in
    /// [`Checker::read_block`] before its words are read.
    motion_only: bool,
    /// The words of the block in hand that name a block or a program by its code
    /// ([`CodeWord`]): the letter, the address whose format it takes, and the code's token.
    named: Vec<(u8, u8, String)>,
    /// The allocation of the words of the block in hand, kept from block to block (empty: a
    /// block's words borrow its line).
    words_buffer: Vec<Word<'static>>,
    /// The same for the comments and the statements of the block in hand.
    comments_buffer: Vec<(usize, &'static [u8])>,
    statements_buffer: Vec<(usize, Kind, &'static [u8])>,
    /// The first code of each modal group in the block in hand (TG304), kept likewise.
    groups: Vec<(codes::CodeRef, usize)>,
    format_table: FormatTable,
    travel: limits::Travel,
    /// The units the words of the block in hand are read in (its own G20/G21, or the state's).
    block_units: Units,
    block_feed_units: Units,
    /// The block's feed is per revolution (G95, a Fanuc or Haas lathe's G99, in force or in
    /// the block): its F is read by `feed_rev_formats` where the profile has one.
    block_feed_rev: bool,
    /// HEIDENHAIN's circle centre CC (I J K), in force for the arcs after it.
    centre_kept: [Option<Dec>; 3],
    /// HEIDENHAIN: the CC in force was given by a value the checker could not follow (an
    /// incremental I J from an unknown position, a parameter): no arc about it is checked.
    centre_lost: [bool; 3],
    /// X is programmed as a diameter by a mode of the program (a SINUMERIK's DIAMON, LinuxCNC's
    /// G7), beside a lathe profile's fixed diameter ([`Config::diameter`]).
    diameter_mode: polar::XMode,
    /// A SINUMERIK's pole and polar words in force ([`polar`]).
    polar: polar::Polar,
    /// The block in hand moves by polar words (about the pole) or turns an arc by its opening
    /// angle (`AR=`): no centre words to check.
    polar_arc: bool,
    opening_arc: bool,
    /// The block in hand's arc by its radius (R, CR=), as [`Checker::arc`] found it: its
    /// centre in the plane's axes (a lathe's X a radius) for the path and the statistics.
    radius_arc: Option<RadiusArc>,
    /// The work offset the program selected (G54-G59), while the profile's value of it is the
    /// one in force: None before a selection, and for good after anything that shifts the
    /// coordinates in a way the profile cannot know (G10, G52, G92, a call...).
    work: Option<i64>,
    /// Some(G5x): `work` is the offset the program before left, taken for a program read
    /// apart that no call before it names, whose caller's is not known
    /// ([`Checker::work_offset_unknown`]); None once it selects its own.
    work_guessed: Option<i64>,
    /// `work` is the offset the program before left, in a program read apart that the one
    /// before runs on into with the block skip switch on (its end `/M30` or `/M99`): its
    /// machine positions under it are those of that run, said where read, not at a call
    /// under another offset (review 57e F2); false once it selects its own.
    work_run_on: bool,
    /// A program read apart whose start has no work offset in force (the file's first, or
    /// one after a program that lost the offsets): its absolute positions before anything
    /// moves its coordinates are its caller's offset's, kept for its calls
    /// ([`Checker::unplaced_at`]); false once it selects an offset, shifts, or writes one.
    work_unplaced: bool,
    /// `offsets_lost` holds only for calls of programs not read there (written later in
    /// the file, or not in it): a G54-G59 of the program's own after them re-selects an
    /// offset whose value only those programs could have changed
    /// ([`Checker::work_unread_reselected`]); and the block in hand made such a call.
    offsets_unread_only: bool,
    call_unread_here: bool,
    /// The block in hand called a subprogram read before it that surely leaves the work
    /// offsets as they were ([`Checker::keeps_offsets`]), or opened or closed a LinuxCNC
    /// definition read apart: the offsets are not lost at it.
    call_keeps: bool,
    /// A Haas's M97 of the program in hand was kept with its work offset
    /// ([`Checker::local_call`]): a block after an end that starts with the sequence number it
    /// names begins its local subprogram ([`Checker::local_body`]). And the number of the
    /// program whose local subprogram is in hand (its [`Checker::in_hand`] then the body's
    /// key), given back at the body's M99.
    local_called: bool,
    local_main: Option<i64>,
    /// An end (M02/M30, [`Checker::ended_line`]) was read, or a return after an M97 was kept
    /// ([`Checker::local_called`]): the blocks after it are looked at
    /// ([`Checker::words_after_end`]).
    after_watch: bool,
    /// LinuxCNC: the labels of the main program's calls kept for a definition after its end
    /// ([`Checker::later_call`]).
    later_called: Option<Vec<Vec<u8>>>,
    /// The axes (their places' bits) a G52 of the program in hand wrote (or a program's it
    /// called carried into it), and whether its start had no shift in force
    /// ([`Checker::program_shift_end`], [`Checker::shift_carried`]).
    g52_axes: u16,
    /// [`Checker::g52_read_at`]: the units the program in hand's last G52 of each axis was
    /// read in (the factor where only assumed, 0 where written).
    g52_read: [f64; 9],
    shift_clean_start: bool,
    /// A jump, condition or loop, a G52 after a return, or a call of a program whose shift at
    /// its end is not known, in the program in hand: what it leaves on is not surely known.
    shift_unsure: bool,
    /// Each FANUC/Haas program of the file that left a G52 or another shift on at its end:
    /// the axes its G52s wrote and the local shift it left, where surely known (no G92, no
    /// jump, condition or loop, no call not followed, no shift at its start); None where not.
    /// With them, each axis's, the factor to the profile's units its last G52 was read in
    /// where the program had written no units code by it (it runs in its caller's units), 0
    /// where it had.
    shift_ends: HashMap<i64, Option<ShiftEnd>>,
    offsets_lost: bool,
    /// The axes (their places' bits) of each work offset G54-G59 (0-5) whose value the
    /// program in hand has written before here: by a G10 of its own that writes it
    /// ([`Checker::g10_writes`]), or by a subprogram read before that it called (its own,
    /// `Body::writes`). A subprogram's machine position read under the profile's value of
    /// such an offset's axis is not said at a call here (review 57e F1: `G10 L2 P2 X0.` /
    /// `G90 G55` / `M98 P2000` ran O2000's `X-700.` at X-700, not at the -800 read under the
    /// profile's G55). Each program's run its own, in run order: reset where a program
    /// begins, a subprogram's writes taken into its caller's at the call (review 58a F1 and
    /// F3: set where read, file-wide, by any G10 and by a call of a program not read, it
    /// dropped real overtravels). What a program the checker does not read writes is not
    /// followed, as a `#5241=` write is not: its caller's positions said as the profile's
    /// offsets make them, erring on the side of the alarm.
    offsets_written: limits::Written,
    /// LinuxCNC: the values (the profile's units; NaN not known) a parameter write
    /// (`#5241=-200`) gave the axes (their places' bits) of the work offset G54-G59 (0-5)
    /// in force, which rs274 applies at that system's next selection from another only
    /// (interp_convert.cc `convert_coordinate_system` loads #5221 + 20 * (n - 1)... there,
    /// and does nothing where the system selected is the one in force): held here until
    /// then ([`Checker::linuxcnc_reselected`]).
    linuxcnc_pending: Option<Box<(usize, u16, [f64; 9])>>,
    /// LinuxCNC: the line of the last G54-G59 selected from another system in force: a
    /// parameter write of that system on the same line is loaded by it (rs274 sets a line's
    /// parameters before its codes run).
    linuxcnc_selected_at: usize,
    /// LinuxCNC: that selection was from a system not known (it may have been the same).
    linuxcnc_selected_maybe: bool,
    /// LinuxCNC: G59.1-G59.3 in force (the work system not known, surely none of G54-G59).
    linuxcnc_other_in_force: bool,
    /// LinuxCNC: the program has selected or restored a work system (G54-G59.3, M72): before
    /// that, the system in force is the one LinuxCNC persisted (#5220), G54 in `rs274 -g`.
    linuxcnc_work_selected: bool,
    /// LinuxCNC: the work system (54-59) an M70 or M73 saved for an M72 (None inside: not
    /// known; None: no save valid).
    linuxcnc_work_save: Option<Option<i64>>,
    /// LinuxCNC: the work system in force where the main program's condition or loop open
    /// began (Some while one is open and no line in it touched the offsets): the positions
    /// inside are not judged, and the system is back where the last one closes.
    linuxcnc_flow_work: Option<Option<i64>>,
    /// LinuxCNC: while such a condition or loop is open, what was in force where it opened
    /// and the calls of later definitions kept under it (oflow.rs).
    linuxcnc_may: Option<oflow::MayCalls>,
    /// LinuxCNC: for each block of `linuxcnc_open_flow`, whether its condition (or a branch's
    /// since) reads a parameter (oflow.rs: a value the checker may hold stale).
    linuxcnc_flow_reads: Vec<bool>,
    /// The axes (their places' bits) of the G10s of the program in hand that wrote their L
    /// or P by a #-expression: read once at the value it has there, though a jump back (a
    /// loop) or another call of the program may run it with another, so the program writes
    /// those axes of every offset where it is called or jumps back (review 58d F6: `#5=1` /
    /// `N10 G10 L2 P#5 X0.` / `#5=#5+1` / `IF [#5 LE 6] GOTO 10` writes G54-G59's X, not
    /// G54's only).
    g10_expression: u16,
    /// The axes of the G10s of the program in hand whose L or P is a #-expression of its own
    /// local variables, known where read (`#5=1` / `G10 L2 P#5 X0.`): the same at every call,
    /// but a jump back may run it with another value: those axes of every offset written
    /// there ([`Checker::forget_at_jump`]; review 59a F4).
    g10_local: u16,
    /// A jump, condition or loop statement (`GOTO`, `IF`, `WHILE`) was read in the program
    /// in hand ([`Checker::forget_at_jump`]): a G10 after it may not run, or be passed over
    /// by a jump while another runs, so the value it writes is not known (review 59a F2).
    jumped: bool,
    /// The frames in force (polar G16, scaling G51, rotation G68, Haas G268 and G101, mirror
    /// G51.1) and what they do to the spans of TG601 ([`Checker::turn_frames`]).
    frames: limits::Frames,
    /// The notes (TG140) said once per file, by their bits: a lathe cycle whose positions are
    /// not all known ([`limits::CYCLE_NOTED`], `Checker::cycle_walked`), a G53 under G91
    /// ([`limits::G53_INCREMENTAL_NOTED`], `Checker::machine_incremental`), a lathe block
    /// writing both X and U or Z and W ([`limits::UW_BESIDE_NOTED`], `Checker::uw_beside_xz`),
    /// a call after which G90/G91 are not known ([`limits::MODE_LOST_NOTED`],
    /// `Checker::call_mode_lost`).
    noted: u8,
    /// The machine's count of G90/G91 codes where [`Checker::call_mode_lost`] last took the
    /// mode as not known (G91 from a position not known): a G52 while it is the count is read
    /// as before, not as one under G91 (review 48, F11).
    mode_lost_codes: Option<u32>,
    /// The programs whose calls lost the distance mode since [`Checker::mode_lost_codes`]
    /// was set (`i64::MIN` for a call not by number): where they are all one program, a
    /// later call of it is made in the mode that program leaves ([`CallWork::others`]).
    mode_lost_by: Vec<i64>,
    /// The shifts of the coordinates (G52, G92) the spans of TG601 follow
    /// ([`Checker::shift_spans`]).
    shifts: limits::Shifts,
    /// A SINUMERIK's kinematic transformation in force (`TRACYL(400)` until `TRAFOOF`): its
    /// line and name. The axes are programmed in other coordinates: no travel comparison.
    transformed: Option<Transformed>,
    /// A tool length offset by a decimal code (G43.1, G43.4) in force.
    length_decimal: bool,
    /// The motion mode in force is one the modal state does not model (G05, G73, G76, G38.2 on
    /// LinuxCNC), or unknown after a jump or call: no TG411.
    motion_unknown: bool,
    /// A canned cycle of the control's list the modal state does not model is in force (a
    /// Haas lathe's G241): its strokes are no moves of the G00-G03 in force, so neither its
    /// block nor the positions after it count in the path, its lengths or the cycle time,
    /// until a code the state models (G80, G00-G03, G81-G89).
    cycle_unmodelled: bool,
    /// The first line of this program with a word or block the control refuses (a reading
    /// error): it alarms there ([`Checker::refused_at`]).
    refused_at: Option<usize>,
    /// The first block of this program with two codes of one modal group (TG304, whether or
    /// not the rule is selected), and the check's message ([`Checker::conflict_at`]).
    conflict_at: Option<(usize, String)>,
    /// LinuxCNC's motion mode as rs274ngc keeps it, for its canned-cycle refusals (TG412).
    linuxcnc_motion: tooling::LinuxCncMotion,
    /// LinuxCNC: the motion mode not known ([`tooling::LinuxCncMotion::Unknown`]) is surely
    /// one of G0-G3 (or none): a move without a motion code then ends at its words' point,
    /// as every reading of it does. Set after a call of a definition read before it whose
    /// body writes no other motion code, the mode before being G0-G3 or none (review 59b,
    /// F5), and after a possible M72 drop whose two modes are G0-G3 (F4)
    /// ([`Checker::linuxcnc_motion_after_call`]).
    linuxcnc_motion_plain: bool,
    /// LinuxCNC: the labels of the definitions whose body may leave a motion mode other
    /// than G0-G3: it writes another motion code (G5.2, G33, G38.x, G73-G89 ...), a G code
    /// of a value not known, or calls one that may ([`Checker::linuxcnc_motion_plain`]).
    linuxcnc_motion_subs: HashSet<Vec<u8>>,
    /// LinuxCNC: whether the motion mode before the open definition's `sub` was G0-G3 or
    /// none, in force again after its `endsub`.
    linuxcnc_plain_before_sub: bool,
    /// LinuxCNC: the modal state's motion mode, cycle and cycle words before the open
    /// definition's `sub`, and its label, put back at its `endsub` (rs274 reads a definition
    /// without running it; review 61b, F4).
    linuxcnc_motion_before_sub: structure::MotionBeforeSub,
    /// LinuxCNC: the open definition's body has a `return` (a way out before its end).
    linuxcnc_body_returns: bool,
    /// LinuxCNC: the motion mode (G0-G3) a definition's body surely leaves, by its label:
    /// the mode after a call of it (review 61b, F4); `None` where the body's last mode is
    /// not known and not the one before its sub (after a call: not known). A label not here
    /// leaves the caller's mode.
    linuxcnc_sub_motion: HashMap<Vec<u8>, Option<i64>>,
    /// LinuxCNC: the main program's calls of definitions not read yet, and the first move
    /// without a motion code after each, judged at the definition's `endsub`
    /// ([`structure::LaterCalls`]).
    linuxcnc_later: Box<structure::LaterCalls>,
    /// LinuxCNC: the bodies read after the main program's end that its calls surely run, for
    /// rs274's refusals there (bodyrun.rs).
    linuxcnc_later_bodies: Box<bodyrun::LaterBodies>,
    /// LinuxCNC: G41.1/G42.1 (dynamic cutter compensation, a decimal code the modal state
    /// leaves out) in force.
    linuxcnc_dynamic_compensation: bool,
    /// LinuxCNC: the last block (its count in `stats.blocks`) of an unbroken run from the one
    /// that turned cutter compensation on, each read in order by the main program with no
    /// axis word and no motion code: rs274 holds no compensated move yet, so a G17.1-G19.1
    /// there is only refused at the next move (review 53, F13).
    linuxcnc_compensation_quiet: Option<usize>,
    /// LinuxCNC: the line of a G17.1-G19.1 let pass under cutter compensation
    /// (`linuxcnc_compensation_quiet`), while the compensation and that plane hold: each
    /// move is refused, and where the checker stops following the program (a call, a flow
    /// it does not follow) it refuses there ([`Checker::linuxcnc_uvw_unfollowed`]).
    linuxcnc_uvw_let_pass: Option<usize>,
    /// LinuxCNC: G17.1, G18.1 or G19.1 (a plane of U V W, decimal codes the modal state
    /// leaves out) in force, where rs274 draws no arc and no spline (TG412).
    linuxcnc_uvw_plane: bool,
    /// LinuxCNC: the plane is not known here (after a call, a condition or loop whose
    /// branches may leave different planes, in a subroutine's body before it sets one): no
    /// refusal that depends on the plane until a G17-G19 (or .1) sets it again.
    linuxcnc_plane_unknown: bool,
    /// LinuxCNC: the plane at the opening of each condition or loop open in the main
    /// program, and the planes its branches read so far left (structure::PlaneBlock).
    linuxcnc_plane_blocks: Vec<structure::PlaneBlock>,
    /// LinuxCNC: the same for the conditions and loops open in a definition's body.
    linuxcnc_plane_body_blocks: Vec<structure::PlaneBlock>,
    /// LinuxCNC: the plane before the open definition's `sub`, in force again after its
    /// `endsub` (rs274 reads a definition without running it).
    linuxcnc_plane_before_sub: Option<structure::PlaneAt>,
    /// LinuxCNC: the labels of the definitions whose body writes a G17-G19 (or .1) or calls
    /// another subroutine, with the one plane (G code and whether a .1 plane) every plane
    /// code of the body writes, None where that is not one (two planes, a G code of a value
    /// not known, a call): after a call of one of them the plane is not known, but where the
    /// body's one plane is the caller's (every way through leaves it: review 55c, F5); after
    /// a call of another one defined before it, the plane stays.
    linuxcnc_plane_subs: HashMap<Vec<u8>, Option<(i64, bool)>>,
    /// LinuxCNC: after a call or jump the checker does not follow, the spindle direction and
    /// the cutter compensation the call may have set are unknown until the program sets them
    /// again (M3/M4/M5; G40/G41/G42): no refusal that depends on them (TG412).
    linuxcnc_spindle_unknown: bool,
    linuxcnc_compensation_unknown: bool,
    /// LinuxCNC: an M6 stopped the spindle (rs274ngc's convert_tool_change) and no M3, M4 or
    /// M5 has set it since: the modal state keeps the M3 before the tool change (TG412).
    linuxcnc_tool_change_stopped: bool,
    /// LinuxCNC: the axes (`modal::bit`) whose current point in the coordinates the program
    /// writes is not known exactly since a code moved it, or moved the coordinates, by an
    /// amount the checker does not follow (`tooling::linuxcnc_unsettles`); an absolute move
    /// on the axis knows it again. An R arc is not judged against such a start (TG412).
    linuxcnc_point_unsure: u32,
    /// LinuxCNC: the block (`stats.blocks`) whose G20 or G21 changed the units, whose X Y Z
    /// rs274 converts ([`tooling::linuxcnc_units_double`]); 0 none.
    linuxcnc_units_turned: usize,
    /// LinuxCNC: the units in force before the block in hand, where it has an M word and
    /// they are known (those an M70 or M73 beside a G20/G21 saves: review 75-lcnc75a N2).
    linuxcnc_m_units: Option<(crate::modal::Units, crate::modal::Units)>,
    /// LinuxCNC: the doubles rs274 holds for X, Y and Z, where a G91 sum made them other
    /// than the decimals' (`tooling::Double`, `Checker::linuxcnc_doubles`).
    linuxcnc_double: [tooling::Double; 3],
    /// LinuxCNC: the bottom of the canned cycle in force outside the XY plane (Y in G18, X in
    /// G19), which a repeated block keeps as rs274ngc's `cycle_cc` does.
    linuxcnc_cycle_bottom: Option<Dec>,
    /// LinuxCNC: where the series of back-to-back canned cycles in force started on the
    /// cycle's axis (its index in X Y Z, and the point), where known exactly in the
    /// coordinates in force; None where not known, or where a code changed the coordinates
    /// since (`Checker::linuxcnc_cycle_end`: G98's clearance is that number).
    linuxcnc_series_start: Option<(usize, Dec)>,
    /// LinuxCNC: the cycle the block runs starts a series (the motion mode before it is no
    /// canned cycle's and is known).
    linuxcnc_series_first: bool,
    /// LinuxCNC: the block ran a canned cycle or a rigid tap (its motion in tenths: G73, G74,
    /// G81-G89, G33.1), or a move whose motion is not known (0), which may be one: where it
    /// leaves the tool is set after the block's rules (`Checker::linuxcnc_cycle_end`).
    linuxcnc_cycle_ran: Option<i64>,
    /// LinuxCNC: the R of the G73 or G74 in force, which the modal state does not keep on
    /// this profile (rs274's `cycle_r`), for where the cycle leaves the tool.
    linuxcnc_cycle_r: Option<Dec>,
    /// LinuxCNC: rs274ngc's feed rate, which its probe moves and canned cycles read
    /// ([`tooling::LinuxCncFeed`]).
    linuxcnc_feed_rate: tooling::LinuxCncFeed,
    /// LinuxCNC: rs274ngc's feed rate where the checker knows its value: zero at the start
    /// and after a G94 or G95, an F of a number under them, each run surely by the main
    /// program; None after anything else (a G93 move's length times F, an F in a condition,
    /// loop or body, a parameter, a call or jump). M72's restore compares it
    /// ([`Checker::linuxcnc_feed_restore`]).
    linuxcnc_rate: Option<Dec>,
    /// LinuxCNC: rs274's feed rate (`linuxcnc_rate`, `linuxcnc_feed_rate`) before a
    /// definition's `sub`, which its `endsub` gives back (rs274 reads a definition without
    /// running it); at the `endsub`, the block (its count) it is given back at.
    linuxcnc_rate_before_sub: Option<(Option<usize>, Option<Dec>, tooling::LinuxCncFeed)>,
    /// LinuxCNC: the F word in force before a definition's `sub` (its value, whether it was
    /// not known, whether none was ever set), given back at its `endsub` with
    /// [`Checker::linuxcnc_rate_before_sub`]: rs274 reads the definition without running it
    /// (`o100 sub` / `G1 X1 F10` / `o100 endsub` / `G1 X2` with no F before is "Cannot do g1
    /// with zero feed rate").
    linuxcnc_f_before_sub: (Option<Dec>, bool, bool),
    /// LinuxCNC: the feed mode, rs274's feed rate and the speed the main program's M70 or
    /// M73 saved, where each is known ([`structure::FeedSaved`]); None where no save is
    /// followed.
    linuxcnc_feed_saved: Option<structure::FeedSaved>,
    /// LinuxCNC: the feed mode and speed every main program's M70 or M73 that may be the
    /// one in force agrees on ([`structure::LooseSaved`]); None before any.
    linuxcnc_feed_loose: Option<structure::LooseSaved>,
    /// LinuxCNC: the coolant and feed override rs274 holds where the main program runs in
    /// order, which an M72's restore writes where they differ from the save
    /// ([`structure::RestoreExtras`]).
    linuxcnc_extras: structure::RestoreExtras,
    /// LinuxCNC: A B C before the block in hand where it names one of them, and the state's
    /// unknown axes then (`Checker::linuxcnc_abc_named`); the axes of them whose double rs274
    /// holds is surely the nearest of the point the state keeps (bits 0-2: A B C): set at an
    /// absolute word, cleared at an increment that may not be exact.
    linuxcnc_abc_start: ([Option<Dec>; 3], u32, usize, u8),
    linuxcnc_abc_exact: u8,
    /// LinuxCNC: the block (its count in `stats.blocks`) whose M72 restored the feed, the
    /// restore followed or its values made unknown: the block's G93-G95 and F ran before it.
    linuxcnc_feed_restored_at: Option<usize>,
    /// LinuxCNC: the block (its count) of an M72, whose restore may run a block of its own,
    /// which rs274 2.9.0 runs in place of the M72's: its motion is not judged
    /// ([`Checker::linuxcnc_feed_restore`]).
    linuxcnc_m72_dropped: Option<usize>,
    /// LinuxCNC: the M72 of the block in hand surely finds another distance mode or plane in
    /// force than the save took (`Checker::linuxcnc_distance_modal`): its restore surely
    /// writes a block of its own.
    linuxcnc_m72_differs: bool,
    /// LinuxCNC: the M72 of the block in hand surely finds another plane in force than the
    /// save took (None: not known, its block writing a plane code): the restore writes the
    /// plane first, which rs274 refuses under cutter compensation (review 75-lcnc75a N5).
    linuxcnc_m72_plane_differs: Option<bool>,
    /// LinuxCNC: a block whose M72 may be dropped (`linuxcnc_m72_dropped`), with the motion
    /// mode before it: the block's own motion, plane and compensation codes do not take effect
    /// where rs274 drops it (`Checker::linuxcnc_m72_motion_back`).
    linuxcnc_m72_motion: Option<structure::M72Dropped>,
    /// LinuxCNC: the canned cycle in force before the block in hand, kept where a save is
    /// followed and the block has an M word (`structure::M72Cycle`).
    linuxcnc_m72_cycle: Option<structure::M72Cycle>,
    /// LinuxCNC: the NURBS control points rs274ngc holds ([`tooling::Nurbs`]).
    linuxcnc_nurbs: tooling::Nurbs,
    /// LinuxCNC: the X and Y of the NURBS list's last control point, where a G5.2 block of
    /// the list named one (None: none yet, the list's only point is the current point), each
    /// None where it is not known: where G5.3 leaves the current point
    /// (`Checker::linuxcnc_nurbs_position`).
    linuxcnc_nurbs_last: Option<[Option<Dec>; 2]>,
    /// FANUC's G10 L50 / G10 L3 data input mode (`dialect::DataInput`): its blocks are data.
    data_input: dialect::DataInput,
    /// TG127 (text outside ASCII) said: once per file.
    outside_ascii_noted: bool,
    /// LinuxCNC: G40 ended compensation and no move has followed yet (TG501 on an arc).
    compensation_exit: bool,
    /// The program in hand returned as a subprogram (M99; a SINUMERIK's M17 or RET): it needs
    /// no M02/M30 (TG114), and an O number after it starts the file's next program.
    sub_ended: bool,
    /// LinuxCNC: where the file is in the form of a subroutine file (one `o<name> sub` ...
    /// `o<name> endsub`, which needs no M2).
    sub_file: SubFile,
    /// The label of the definition a LinuxCNC subroutine file opened (`o<name>`).
    sub_label: Vec<u8>,
    /// LinuxCNC: lines before the file's first statement, which is an `o<name> sub`: the
    /// first such line and the sub's (0, 0: none). A call skips them ([`SubFile`]).
    sub_preamble: (usize, usize),
    /// LinuxCNC: in a subroutine file, the line and column of the first endsub inside a
    /// condition or loop of the body (a return when called), and the line of an endsub naming
    /// another label outside them with nothing but M2/M30 after it (the return that ends the
    /// file); 0: none.
    sub_returns: (usize, usize, usize),
    /// LinuxCNC: the block left open at that first endsub which rs274 may skip from when the
    /// body runs (an `if`, `while` or `repeat` whose condition or count is not surely true;
    /// a `do` never skips): its line, its statement, the endsub's line and whether the endsub
    /// stands in a later branch of it (the `else` or `elseif` line).
    #[allow(clippy::type_complexity)]
    sub_left_open: Option<(usize, Vec<u8>, usize, Option<Vec<u8>>)>,
    /// LinuxCNC: what stands after that endsub, which a run as a program reads as the main
    /// program (rs274 skips a definition not called to the first o-word line of its label).
    sub_after_return: structure::AfterReturn,
    /// LinuxCNC: in a subroutine file, an endsub naming another label outside the body's
    /// conditions and loops has been read while its definition is open: a call returns
    /// there, a run as a program skips on to the definition's own endsub, so no line before
    /// that is read as a block by either (review 57b F3).
    sub_returned: bool,
    /// LinuxCNC: the line and column of the first `%` line rs274 would refuse that stands
    /// after the endsub of a subroutine file (a call returns at the endsub and never reads
    /// it): reported only where a line after it makes the file a program.
    sub_percent: Option<(usize, usize)>,
    /// LinuxCNC: the label a call names this file by, where its name is `<label>.ngc` (rs274
    /// opens the lower-cased label with `.ngc` on its search path, interp_o_word.cc
    /// `find_ngc_file`): a subroutine file named otherwise is never called, only run as a
    /// program. `None`: another name, or none given.
    called_as: Option<Vec<u8>>,
    /// LinuxCNC: the definition open at this point of the file (`o<name> sub` not yet closed
    /// by its endsub): its line, column and label.
    open_definition: Option<(usize, usize, Vec<u8>)>,
    /// LinuxCNC: the subroutines the main program has defined so far, and those it called
    /// before their definition (label, line of the first call).
    linuxcnc_defined: Vec<Vec<u8>>,
    /// LinuxCNC: the local named parameters (`#<name>`, as `params::named_parameter` writes
    /// them) the main program has assigned so far (`Checker::linuxcnc_named_reads`).
    linuxcnc_named: HashSet<Vec<u8>>,
    /// Up to eight names, as written, found among `linuxcnc_named` or global: a CAM program's
    /// `Z[#<zscale>*..]` on every line compared by its bytes, not normalized and hashed. Each
    /// as its first 8 bytes packed in one integer and its length, so that a name of up to 8
    /// bytes is compared as one integer, and a longer one's bytes.
    linuxcnc_named_seen: Vec<(u64, usize, Vec<u8>)>,
    /// The keys of the names seen of up to 8 bytes (their first 8 bytes, zeros after them),
    /// each at its place in `linuxcnc_named_seen` (0 elsewhere: no name's key), for the
    /// walked lines' names (`Checker::linuxcnc_names_all_seen`).
    linuxcnc_short_seen: [u64; 8],
    /// LinuxCNC: which of a block's first eight words `structure::walk_expression` found a
    /// plain bracketed expression (which holds no `/`), and the block's count
    /// (`stats.blocks`) they are of: the read-refusal's test reads them, not the bytes again.
    linuxcnc_plain_words: (usize, u8),
    /// LinuxCNC: the count (`stats.blocks`) of the block in hand where no word has an
    /// expression, or the tokenizer walked each plain (`Checker::linuxcnc_line_walked`): no
    /// `/` in any, for the plain move's test (`Checker::linuxcnc_plain_move`); 0 before.
    linuxcnc_no_slash: usize,
    /// LinuxCNC: the count (`stats.blocks`) of the block in hand where it is a plain move
    /// (`Checker::linuxcnc_plain_move`), for the doubles (`Checker::linuxcnc_doubles`); 0
    /// before.
    linuxcnc_plain_block: usize,
    /// LinuxCNC: `Checker::linuxcnc_quiet_now` after the last block `Checker::subroutine_file`
    /// read in full (false before the first).
    linuxcnc_quiet: bool,
    /// The walks the tokenizer made of the last line of plain words' bracketed words
    /// (`tokenizer::LineWalks`), for the LinuxCNC rules of its block, and that line's text
    /// (its address and length), set while that block is checked (else (0, 0)): a block of
    /// another text, or one given by other means, walks its words itself.
    line_walks: crate::tokenizer::LineWalks,
    line_walks_of: (usize, usize),
    /// The letters and whether the codes are G00-G03 alone of the line of plain words
    /// `line_walks_of` names, found by its reader ([`letters_and_motion`] of its words).
    line_letters: (u32, bool),
    /// That line has no bracketed word (every word plain: a letter, a sign, a number).
    line_unbracketed: bool,
    /// The block in hand is a line of plain words without a bracketed word: no word has an
    /// index or an expression, and it has no block skip (set by `read_block`).
    plain_block: bool,
    /// LinuxCNC: the labels (`o_label`) of the main program's o-word conditions and loops
    /// (`if`, `while`, `do`, `repeat`) open at this line, outside a definition. Whether a line
    /// inside one runs depends on values the checker does not follow, so what rs274 refuses
    /// only in a line it runs (a named parameter not yet set, `M[3.5]`, `X[1/0]`) is judged
    /// only where none is open and no definition is (review 16c; review 17: after the
    /// `endif` the lines run again, unconditionally).
    linuxcnc_open_flow: Vec<Vec<u8>>,
    /// LinuxCNC: for each `if` of `linuxcnc_open_flow` (its index there), whether every branch
    /// read so far ended in an M02/M30 of its own, and whether an `else` was read: at its
    /// `endif`, an `if` with an `else` all of whose branches ended ends the main program
    /// there (issue 32: a definition after such an `endif` is never reached; rs274 agrees).
    linuxcnc_if_ends: Vec<(usize, bool, bool)>,
    /// LinuxCNC: for each block of `linuxcnc_open_flow`, what the checker knows of its lines'
    /// run ([`structure::OpenBlock`]): whether they run, a closing label worked out as the
    /// line runs read with the values of that first run (`Checker::linuxcnc_closing_label`;
    /// review 48, F10; review 49a, F2).
    linuxcnc_open_at: Vec<structure::OpenBlock>,
    /// LinuxCNC: the parameters (by key; empty: any, a call) assigned while a block of
    /// `linuxcnc_open_flow` is open, with their lines (review 48, F10).
    linuxcnc_flow_assigned: Vec<(usize, Vec<u8>)>,
    /// LinuxCNC: the labels of the main program's conditions and loops rs274 has recorded
    /// (interp_o_word.cc `control_save_offset`: `if`, `while`, `repeat`, `do`), by their name
    /// without `o` and `<>`, with their keyword's first letter, their line, and whether it
    /// surely ran (opened at the top of the main program): a second of the label is refused
    /// as rs274 refuses it ("duplicate O-word label"; review 48, F19). Keyed by the name:
    /// looked up at every condition and loop (a list searched in turn made a program of
    /// 80,000 labels quadratic: review 49a, F5).
    linuxcnc_o_labels: HashMap<Vec<u8>, (u8, usize, bool)>,
    /// LinuxCNC: every label an o-word line of the file has named so far (a condition, loop,
    /// definition or call, in the main program or a body), by its name without `o` and
    /// `<>`, and whether one was worked out from a value not known here (any label then):
    /// a closing word of a label none named is refused where it surely runs ("undefined
    /// O-word label"; review 49a, F8).
    linuxcnc_labels_named: (HashSet<Vec<u8>>, bool),
    /// LinuxCNC: a condition or loop opened at the top of the main program whose condition
    /// is known false (its label and line), until an o-word line of its label: rs274 skips
    /// every line to that one, reading no other (interp_read.cc `read_items`), so a file that
    /// has none ends in the skip, "File ended with no percent sign or program end" (review
    /// 49a, F3). Also the `else`/`elseif` after a branch known to run (the flag: the skip
    /// ends at the label's `endif` only, interp_o_word.cc skips the other branches of an `if`
    /// that ran one; review 51, F4). Every line in the skip is dead
    /// ([`Checker::linuxcnc_dead`]).
    linuxcnc_skipping: Option<(Vec<u8>, usize, bool)>,
    /// LinuxCNC: the subroutines the main program surely defines (at its top, before its
    /// end), by name without `o` and `<>`, and their lines: a second definition of one is
    /// rs274's "redefining sub" (review 48, F19). Keyed by the name (review 49a, F5).
    linuxcnc_subs_defined: HashMap<Vec<u8>, usize>,
    /// LinuxCNC: the feed mode in force may be another than the lines in their order give:
    /// after a call (the subroutine may set it; with M73 it restores the caller's) or a
    /// G93/G94/G95 inside a condition or loop, until a G93/G94/G95 the main program runs
    /// unconditionally. The probe's and cycles' feed mode refusals are not judged meanwhile
    /// (review 16c, 17).
    linuxcnc_mode_unsure: bool,
    /// LinuxCNC: the main program's distance mode (G90/G91) not known here: after a call
    /// whose G90/G91 after its return the checker does not know ([`Checker::call_mode_lost`]),
    /// after the condition or loop a G90/G91 that changed it was written in closes, or an M72
    /// whose saved state is not known; until a G90/G91 the main program runs. G53 is not
    /// refused as incremental meanwhile (review 49a, F1, F6: rs274 runs it where the mode is
    /// G90).
    linuxcnc_distance_unsure: bool,
    /// LinuxCNC: the depth of the main program's conditions and loops (`linuxcnc_open_flow`)
    /// at which a G90/G91 that changed the mode was written: known in that block from there,
    /// not known once it closes or another branch of its `if` begins (review 50, F3: `o1 if`
    /// / `G91` / `G53 G0 Z0` is refused wherever the G53 runs).
    linuxcnc_distance_from: Option<usize>,
    /// LinuxCNC: the main program's conditions and loops open where its distance mode was
    /// last written (a block the checker knows runs counts as none for
    /// [`Checker::linuxcnc_distance_from`]; its other branch, after an `else`, does not run
    /// with it: the mode is not known there).
    linuxcnc_distance_in: usize,
    /// LinuxCNC: what the main program's M70/M73 saved for M72 (LinuxCNC M-codes, "M70 Save
    /// Modal State", "M72 Restore Modal State"; interp_convert.cc: M70 and M73 save into the
    /// call level's context, M71 invalidates it; review 49a, F6; review 50, F2, F5).
    linuxcnc_saved: structure::Saved,
    /// LinuxCNC: the plane the main program's M70/M73 saved with it, which M72 restores
    /// ([`structure::PlaneAt`]; review 55c, F6).
    linuxcnc_plane_saved: structure::PlaneAt,
    /// LinuxCNC: a main program's block with M72 and G53: whether G91 was surely in force
    /// before it, which rs274's G53 test reads (the M72 restores after it; review 50, F11).
    linuxcnc_g53_before: Option<bool>,
    /// LinuxCNC: the distance mode inside the open definition's body, which runs under its
    /// caller's ([`structure::BodyDistance`]; review 50, F4).
    linuxcnc_body_distance: Box<structure::BodyDistance>,
    /// LinuxCNC: the lines of the refusals of bodies said at a call (said once).
    linuxcnc_call_refused: Vec<usize>,
    /// LinuxCNC: the subroutines defined so far in this file (their `o_label`), each with
    /// whether its body may set the feed mode or end the program (a G93/G94/G95, an M2/M30,
    /// M72, M98/M99, or a G or M code whose value is not known here) and the subroutines it
    /// calls: a call of one none of whose bodies, transitively, may leaves the feed mode as
    /// it was before the call (issue 32, item 4; `Checker::linuxcnc_call_keeps_mode`).
    /// The fourth: what the body does to the distance mode it returns in
    /// ([`structure::Distance`]; review 48, F16), and its refusals said at its calls.
    linuxcnc_bodies: Vec<LinuxCncBody>,
    /// LinuxCNC: the local named parameters the open definition's body has assigned so far
    /// (`Checker::linuxcnc_body_locals`).
    linuxcnc_body_named: HashSet<Vec<u8>>,
    /// LinuxCNC: each definition's first read of a local named parameter its body did not
    /// assign before (label, line, column, name), said where an `o<label> call` of the file
    /// calls it; and the labels the file's calls name.
    linuxcnc_body_unassigned: Vec<(Vec<u8>, usize, usize, Vec<u8>)>,
    linuxcnc_calls: HashSet<Vec<u8>>,
    /// LinuxCNC: an o-word's label of a known fraction was refused (TG412); rs274 stops there.
    linuxcnc_fraction_said: bool,
    /// LinuxCNC: the same of an open `o<name> sub` definition's body, which runs under its
    /// caller's feed mode, not the one the lines before the `sub` give: unsure from the `sub`
    /// until a G93/G94/G95 of the body outside its conditions and loops, again after a call
    /// in it (review 19). TG402 and the G95 spindle refusal are not judged meanwhile.
    linuxcnc_definition_mode_unsure: bool,
    /// LinuxCNC: the labels of the conditions and loops open in the open definition's body.
    linuxcnc_definition_flow: Vec<Vec<u8>>,
    /// LinuxCNC: the line and statement of each of them, innermost last,
    /// and its last `else` or `elseif` line read.
    linuxcnc_definition_opened: Vec<(usize, Vec<u8>, Option<Vec<u8>>)>,
    /// LinuxCNC: the feed mode where the open `o<name> sub` began: rs274 does not run a
    /// definition where it stands, so its `endsub` gives it back (review 17).
    linuxcnc_definition_feed: Option<i64>,
    /// LinuxCNC: the main program's open `o.. if` conditions, each with the spindle speed
    /// where it began (the speed, and whether it was unknown) and whether its branches may
    /// set another (an S word, a call, a loop, M2/M30/M98/M99, a line the checker cannot
    /// read); and the speed a clean `endif` gives back to the next line (review 21).
    linuxcnc_if_speed: Vec<(Vec<u8>, Option<Dec>, bool, bool)>,
    linuxcnc_speed_back: Option<(Option<Dec>, bool)>,
    linuxcnc_called_ahead: Vec<(Vec<u8>, usize)>,
    /// LinuxCNC: the subroutines whose only definition read so far stands in the skip of a
    /// block known not to run, which rs274 does not record (name, the definition's line, the
    /// skipped block's); the calls that surely run of one of them, not defined by then,
    /// waiting for a definition after them (name, line, column); and a skip held while a
    /// definition inside it is read (review 52, F7).
    linuxcnc_dead_defs: Vec<(Vec<u8>, usize, usize)>,
    linuxcnc_dead_called: Vec<(Vec<u8>, usize, usize)>,
    linuxcnc_skip_held: Option<(Vec<u8>, usize, bool)>,
    /// LinuxCNC: the main program's one loop open at its top whose body the checker knows
    /// runs, and the definitions its body holds where its lines surely ran
    /// ([`structure::LoopDefinitions`]; boxed: seldom set).
    linuxcnc_loop_defs: Option<Box<structure::LoopDefinitions>>,
    /// The units in force at the calls so far of each program number (`M98 P1000`, `G65
    /// P9010`): the lengths, the feed's units and whether the caller had written a units code;
    /// None where the calls disagree or a call was made in units not known. A program after
    /// an end that a call names runs in its caller's units, not in the reset state's
    /// ([`Checker::called_units`]; review 38, finding 10).
    call_units: HashMap<i64, Option<(Units, Units, bool)>>,
    /// The work offset in force at the calls so far of each program number, where the
    /// profile's value of it was (no G10, shift, frame or call not followed before it in the
    /// caller's run), with the distance mode and the first such call's words and line; None
    /// where the calls disagree or one's offset was not known. A program written after its
    /// calls runs under it ([`Checker::called_units`]; review 59a, F12).
    call_works: HashMap<i64, Option<structure::CallWork>>,
    /// The program numbers of [`Checker::call_works`] with a call made where the work offset
    /// in force was not known (not only calls that disagree): a program of that number
    /// written after them runs under no offset the checker knows (review 61a F5).
    call_works_unknown: HashSet<i64>,
    /// The work offsets (bit `G5x - 54`) of the calls of each program by number made where
    /// the offset was known ([`Checker::call_work`]): where the calls disagree, a program
    /// written after them is read under none unless all were made under the one in force
    /// at its start (review 76-calls76 F6).
    call_works_seen: HashMap<i64, u8>,
    /// Calls of a program read apart in units only assumed (no G20/G21 yet), each with the
    /// offset kept where all else is known: recorded where it ends as a main program (its
    /// units the reset state's), as not known where it returns, a subprogram whose units
    /// are its own caller's (review 61a F11 and F7).
    call_works_assumed: Vec<(i64, Option<structure::CallWork>)>,
    /// Those of a program merged before its M99 (its caller `.0`): made in its callers'
    /// units, resolved where those are known ([`Checker::call_works_resolved`]).
    call_works_deferred: Vec<(i64, i64, Option<structure::CallWork>)>,
    /// The spans kept apart after a call of a program not read there, until the caller's
    /// end ([`leaves::LaterShift`]), and those ended, judged at the file's end.
    later_shift: Option<Box<leaves::LaterShift>>,
    later_shifts: Vec<leaves::LaterShift>,
    /// The program in hand, written after its calls, runs under the work offset of
    /// [`Checker::call_works`]: what its messages name, and the state read before it, given
    /// back where it ends (boxed: seldom set).
    work_call: Option<Box<structure::WorkCall>>,
    /// The calls of bodies read later in the file (a Haas's M97 of a sequence after the
    /// M30, a LinuxCNC definition after M2) whose caller's findings after them are held to
    /// the body's return ([`callmode`]).
    call_modes: Vec<callmode::CallMode>,
    /// The caller's moves after a call of a body read later, judged at its return
    /// ([`resumed`]).
    resumed: Option<Box<resumed::Resumed>>,
    /// The line of the last block that calls, and its X, Y and Z and G91 before it
    /// ([`resumed`]).
    call_from: (usize, [Option<Dec>; 3], bool),
    /// The axes (their places' bits) whose work position a G54-G59 selection left as the old
    /// system's (not re-expressed into the new one, or taken back by a loop): a call's start
    /// is not taken from them ([`resumed`]).
    selected_stale: u16,
    /// The work system in force where the offsets were taken as lost by a G52 or G92 alone
    /// (limits.rs): with the shift followed, a call's body and the caller's moves after it
    /// are judged under both ([`resumed`]). Any other loss, or a selection, ends it.
    shift_work: Option<i64>,
    /// The system a G54-G59 selection re-expressed the held position into and those axes
    /// ([`Checker::selection_reexpressed`]): under it, a position after the selection is the
    /// new system's, judged as a machine position, and an increment does not join the span
    /// set aside at the selection again.
    reexpressed: Option<(i64, u16)>,
    /// The program in hand has read a sequence number (a block a `GOTO` or `M99 P` after it
    /// may jump back to; read where the profile gives work offsets:
    /// [`Checker::selection_reexpressed`]).
    numbered: bool,
    /// The block's selection re-expressed the position, or a loop took it back (the one
    /// change of the state a rule makes: [`Checker::selection_reexpressed`]; read by the
    /// debug build's check that no other rule changes it).
    #[cfg(debug_assertions)]
    position_reexpressed: bool,
    /// The axes whose positions are still the ones a selection re-expressed, and the delta
    /// it added to each ([`Checker::reexpression_held`]).
    reexpressed_held: Option<Box<limits::Held>>,
    /// The main program's first jump or loop and what came after it (callflow.rs).
    flow_calls: Option<Box<callflow::FlowCalls>>,
    /// The program in hand is a subprogram whose calls leave its units unknown (they
    /// disagree, or one was made in units not known): no limit that reads a length or a feed
    /// (TG601, TG602) is judged until it writes a units code of its own.
    units_unknown: bool,
    /// A program read from the reset state, while it may be a subprogram whose calls come
    /// later in the file (`called`; review 39, finding 4): `early_on` while there is one.
    early: Option<Box<called::Early>>,
    early_on: bool,
    /// Where the findings held for it begin in `found` (none drained from there).
    hold_from: Option<usize>,
    /// The programs read apart whose hold passed [`called::HOLD_MAX`] or [`called::HOLD_ALL`]
    /// (read as before from there): each one's number, name, O word's place and the bound it
    /// passed, for a TG140 at each later call (a short list: each held more than 1024
    /// findings of its limits or 4096 of any rule; review 43, finding E).
    given_up: Vec<called::GivenUp>,
    /// The subprograms read before their calls, judged at the file's end.
    pending: Vec<called::Pending>,
    /// The positions a program read apart kept with no work offset in force before it was
    /// merged by a G52 (its own or a call's carried), judged at its later calls
    /// ([`Checker::merged_unplaced_judged`]).
    merged_unplaced: Vec<called::Merged>,
    /// The program in hand, numbered, read apart until its own units code merged it: its
    /// positions under its own offset held ([`limits::PENDING_CALLS_WRITTEN`]) to its end.
    units_merged: Option<i64>,
    /// The program in hand, whose findings under a guessed offset were held at its merge
    /// ([`limits::PENDING_CALLED`]): where it ends as a main, said as a main's.
    guess_marked: Option<i64>,
    /// The program numbers the file's calls may name, and whether one may name any
    /// ([`Checker::call_numbers_seen`]).
    call_numbers: std::collections::BTreeSet<i64>,
    call_numbers_any: bool,
    /// The O numbers of the file's programs: a call naming another (a program stored on the
    /// control) may run any of the file's subprograms ([`Checker::judged_alone`]; review
    /// 56e, F5); and whether one is O9000-O9999, which an M, G or T code runs (F1).
    file_programs: std::collections::BTreeSet<i64>,
    /// The file's programs read so far (by O number) that write work offsets G54-G59 when
    /// they run (a G10 of their own, every offset where its L or P is an expression, or a
    /// call of a program that writes), and whether they lose the profile's (a G10, G52,
    /// G92, an offset the profile does not give, a frame): what a call the checker does not
    /// follow of one writes ([`Checker::offset_writer`]).
    offset_writers: std::collections::BTreeMap<i64, (limits::Written, bool)>,
    /// The file's programs read so far whose effects reach their caller after the return in
    /// a way the checker does not follow for a caller's own G54-G59 after their call
    /// ([`Checker::work_unread_reselected`], review 62a F1-F4): a work offset's system
    /// variable written (`#5221`), a tool length offset (G43/G44) or units (G20/G21) left
    /// in force, a return elsewhere (`M99 P`) or an end (M02/M30), or a call of one such.
    after_unsure: std::collections::BTreeSet<i64>,
    /// The program in hand wrote a work offset's system variable ([`Checker::after_unsure`]).
    offset_variable_written: bool,
    /// Each call by number's program (its O number: [`Checker::in_hand`]) and the numbers
    /// it may name, as [`Checker::call_numbers`] has them: which programs the main's run
    /// reaches ([`Checker::main_may_run`]; review 58a F2).
    call_sites: std::collections::BTreeSet<(Option<i64>, i64)>,
    /// The O number of the file's first program, which the control starts (None: it has
    /// none), and of the program in hand (None: one with none, taken for the first).
    first_number: Option<i64>,
    in_hand: Option<i64>,
    /// The first call whose program number is not known (its code, line and column), and
    /// whether its TG140 was said ([`Checker::call_unknown`]; review 41, finding 5).
    unknown_call: Option<(String, usize, usize, bool)>,
    /// TG401 findings of the program part in hand, held until its end says what it is: a
    /// subprogram (it returns: M99, M17/RET, RTS) runs under its caller's feed, so they are
    /// dropped; a main program (M02/M30, or the end of the file) alarms, so they are said.
    /// Their line and column; at most `motion::HELD_FEEDS`, after which the part's are said as
    /// they come (`feed_unheld`), so that memory stays flat on a long program without F.
    feed_pending: Vec<(usize, usize)>,
    feed_unheld: bool,
    /// The side of the travel each axis is outside as a machine position (-1 below, 1 above, 0
    /// inside), since the block that took it there
    /// (an excursion is said once, where it starts).
    outside: [i8; 9],
    /// What the block's codes make of its words ([`crate::meaning`]): an angle, a direction or
    /// a selector is no position, radius or word read in increments; a tilted plane's origin
    /// and a cylinder's radius are no move.
    meanings: crate::meaning::Meanings,
    /// `meanings` is [`crate::meaning::Meanings::default`], as no code gave it otherwise
    /// (false: it may be or not).
    meanings_none: bool,
    /// The meanings of the last block shapes met ([`shapes`]).
    shapes: shapes::Shapes,
    /// The key of the block in hand's codes ([`codes::code_key`]), and what the rules found
    /// of each set of codes met.
    code_key: Option<codes::CodeKey>,
    verdicts: codes::CodeVerdicts,
    /// How many findings the rules have said (those the selection drops too): a rule that
    /// says nothing of a block leaves it as it was.
    reports: u64,
    /// A passage over the blocks a jump surely taken passes over ([`passed`]).
    passed: Option<Box<passed::Passed>>,
    /// What a Custom Macro B jump's block left before the checker forgot it (it does not
    /// follow the jump): the state its target starts from where the jump is surely taken
    /// ([`passed`]); taken at the block's end.
    jump_left: Option<Box<passed::Left>>,
    /// The sequence number of a jump surely taken whose passage a numbered block between
    /// gave up, where the jump left no feed ever set (0: none): its target, when it comes,
    /// has none -- the jump's arrival is its first ([`passed`]; review 53, F2).
    no_feed_target: u64,
}

impl Checker {
    pub fn new(config: Arc<Config>, selection: Selection, record_path: bool) -> Checker {
        let program_letter = match config.program_number {
            None | Some(b':' | b'P' | b'Q' | b'R') => 0,
            Some(letter) if letter.is_ascii_uppercase() => bit(letter),
            Some(_) => u32::MAX,
        };
        let mut machine = ModalMachine::new(config.modal.clone());
        // a dialect's program starts where the operator or its caller left the machine: no
        // position is known, as at the start of every later program of the file
        // (next_program). A strict ISO 6983-1 profile keeps 7.1's reading, a span starts where
        // the previous one ended: an arc before any position is TG408 there.
        if config.family != crate::lex::Family::Iso {
            machine.forget_position();
        }
        let format_table = FormatTable::new(&config);
        let travel = limits::Travel::new(&config);
        let family = config.family;
        let data_input = dialect::DataInput::for_control(config.family, config.haas);
        Checker {
            selection,
            record_path,
            keep_stats: true,
            config,
            machine,
            stats: Stats::default(),
            path: Vec::new(),
            drawn: Drawn::default(),
            inside: [None; 9],
            found: Vec::new(),
            first: true,
            first_words: true,
            program_letter,
            empty_folder: false,
            offsets_section: false,
            ended_line: 0,
            main_ended: false,
            linuxcnc_m99_end: 0,
            linuxcnc_fanuc_open: false,
            linuxcnc_m98_calls: Vec::new(),
            linuxcnc_m98_numbers: Vec::new(),
            linuxcnc_defs_after: Vec::new(),
            linuxcnc_def_first: false,
            linuxcnc_fanuc_close: None,
            skipped_end: false,
            end_skippable: false,
            surely_ended: false,
            linuxcnc_call_ended_at: 0,
            linuxcnc_end_depth: None,
            after_end_reported: false,
            closed: false,
            styles_explicit: false,
            styles_implicit: false,
            mixed_reported: false,
            arc_cause_said: false,
            limits_hint_said: false,
            passed: None,
            jump_left: None,
            no_feed_target: 0,
            master: codes::Master::MachineData,
            flow_seen: false,
            unfollowed_noted: false,
            unknown_noted: false,
            elements_noted: HashSet::new(),
            params: HashMap::new(),
            linuxcnc_sub_params: HashMap::new(),
            linuxcnc_sub_closed: None,
            goto_targets: HashMap::new(),
            goto_computed: false,
            goto_computed_line: 0,
            goto_names: HashMap::new(),
            targets: targets::Targets::default(),
            reach: reach::Reach::default(),
            arrival: None,
            arrival_line: 0,
            arrival_letters: 0,
            arrival_words: Vec::new(),
            jumps_pending: Vec::new(),
            runs: Vec::new(),
            jump_to_note: None,
            after_block: false,
            run_target: 0,
            run_jump: None,
            cut_block: 0,
            quiet_d: Vec::new(),
            assigned_at: HashMap::new(),
            tv_odd: OddBlocks::default(),
            colons: Colons::default(),
            percent_closed: false,
            spans: [None; 9],
            spans_parked: None,
            span_unjudged: 0,
            spans_parked_call: false,
            spans_parked_body: None,
            first_implicit: None,
            g06_open: None,
            speed_limit_seen: false,
            last_line: 0,
            values: BlockValues::default(),
            readable: Vec::new(),
            seen: Vec::new(),
            clean_blocks: words::CleanBlocks::default(),
            letters: 0,
            motion_only: false,
            named: Vec::new(),
            words_buffer: Vec::new(),
            comments_buffer: Vec::new(),
            statements_buffer: Vec::new(),
            groups: Vec::new(),
            format_table,
            travel,
            block_units: Units::Metric,
            block_feed_units: Units::Metric,
            block_feed_rev: false,
            centre_kept: [None; 3],
            centre_lost: [false; 3],
            diameter_mode: polar::XMode::Radius,
            polar: polar::Polar::at_origin(),
            polar_arc: false,
            opening_arc: false,
            radius_arc: None,
            work: None,
            work_guessed: None,
            work_run_on: false,
            work_unplaced: false,
            offsets_unread_only: false,
            call_unread_here: false,
            call_keeps: false,
            local_called: false,
            local_main: None,
            after_watch: false,
            later_called: None,
            g52_axes: 0,
            g52_read: [0.0; 9],
            shift_clean_start: true,
            shift_unsure: false,
            shift_ends: HashMap::new(),
            offsets_lost: false,
            offsets_written: limits::Written::default(),
            linuxcnc_pending: None,
            linuxcnc_selected_at: 0,
            linuxcnc_selected_maybe: false,
            linuxcnc_other_in_force: false,
            linuxcnc_work_selected: false,
            linuxcnc_work_save: None,
            linuxcnc_flow_work: None,
            linuxcnc_may: None,
            linuxcnc_flow_reads: Vec::new(),
            g10_expression: 0,
            g10_local: 0,
            jumped: false,
            frames: limits::Frames::default(),
            noted: 0,
            mode_lost_codes: None,
            mode_lost_by: Vec::new(),
            shifts: limits::Shifts::default(),
            transformed: None,
            length_decimal: false,
            outside: [0; 9],
            meanings: crate::meaning::Meanings::default(),
            meanings_none: true,
            shapes: shapes::Shapes::default(),
            code_key: None,
            verdicts: codes::CodeVerdicts::default(),
            reports: 0,
            outside_ascii_noted: false,
            compensation_exit: false,
            sub_ended: false,
            sub_file: SubFile::Unknown,
            sub_label: Vec::new(),
            sub_preamble: (0, 0),
            sub_returns: (0, 0, 0),
            sub_left_open: None,
            sub_after_return: Default::default(),
            sub_returned: false,
            sub_percent: None,
            called_as: None,
            open_definition: None,
            linuxcnc_defined: Vec::new(),
            linuxcnc_named: HashSet::new(),
            linuxcnc_named_seen: Vec::new(),
            linuxcnc_short_seen: [0; 8],
            linuxcnc_plain_words: (0, 0),
            linuxcnc_no_slash: 0,
            linuxcnc_plain_block: 0,
            linuxcnc_quiet: false,
            line_walks: crate::tokenizer::LineWalks::default(),
            line_walks_of: (0, 0),
            line_letters: (0, false),
            line_unbracketed: false,
            plain_block: false,
            linuxcnc_open_flow: Vec::new(),
            linuxcnc_if_ends: Vec::new(),
            linuxcnc_open_at: Vec::new(),
            linuxcnc_flow_assigned: Vec::new(),
            linuxcnc_o_labels: HashMap::new(),
            linuxcnc_labels_named: (HashSet::new(), false),
            linuxcnc_skipping: None,
            linuxcnc_subs_defined: HashMap::new(),
            linuxcnc_mode_unsure: false,
            linuxcnc_distance_unsure: false,
            linuxcnc_distance_from: None,
            linuxcnc_distance_in: 0,
            linuxcnc_saved: structure::Saved::Empty,
            linuxcnc_plane_saved: structure::PlaneAt::UNKNOWN,
            linuxcnc_g53_before: None,
            linuxcnc_body_distance: Box::default(),
            linuxcnc_call_refused: Vec::new(),
            linuxcnc_bodies: Vec::new(),
            linuxcnc_body_named: HashSet::new(),
            linuxcnc_body_unassigned: Vec::new(),
            linuxcnc_calls: HashSet::new(),
            linuxcnc_fraction_said: false,
            linuxcnc_definition_mode_unsure: false,
            linuxcnc_definition_flow: Vec::new(),
            linuxcnc_definition_opened: Vec::new(),
            linuxcnc_definition_feed: None,
            linuxcnc_if_speed: Vec::new(),
            linuxcnc_speed_back: None,
            linuxcnc_called_ahead: Vec::new(),
            linuxcnc_dead_defs: Vec::new(),
            linuxcnc_dead_called: Vec::new(),
            linuxcnc_skip_held: None,
            linuxcnc_loop_defs: None,
            call_units: HashMap::new(),
            call_works: HashMap::new(),
            call_works_unknown: HashSet::new(),
            call_works_seen: HashMap::new(),
            call_works_assumed: Vec::new(),
            call_works_deferred: Vec::new(),
            later_shift: None,
            later_shifts: Vec::new(),
            work_call: None,
            call_modes: Vec::new(),
            resumed: None,
            call_from: (0, [None; 3], false),
            selected_stale: 0,
            shift_work: None,
            reexpressed: None,
            numbered: false,
            #[cfg(debug_assertions)]
            position_reexpressed: false,
            reexpressed_held: None,
            flow_calls: None,
            units_unknown: false,
            early: None,
            early_on: false,
            hold_from: None,
            given_up: Vec::new(),
            pending: Vec::new(),
            merged_unplaced: Vec::new(),
            units_merged: None,
            guess_marked: None,
            call_numbers: std::collections::BTreeSet::new(),
            file_programs: std::collections::BTreeSet::new(),
            offset_writers: std::collections::BTreeMap::new(),
            after_unsure: std::collections::BTreeSet::new(),
            offset_variable_written: false,
            call_sites: std::collections::BTreeSet::new(),
            first_number: None,
            in_hand: None,
            call_numbers_any: false,
            unknown_call: None,
            feed_pending: Vec::new(),
            feed_unheld: false,
            motion_unknown: false,
            cycle_unmodelled: false,
            refused_at: None,
            conflict_at: None,
            linuxcnc_motion: tooling::LinuxCncMotion::Known(None),
            linuxcnc_motion_plain: false,
            linuxcnc_motion_subs: HashSet::new(),
            linuxcnc_plain_before_sub: false,
            linuxcnc_motion_before_sub: structure::MotionBeforeSub::default(),
            linuxcnc_body_returns: false,
            linuxcnc_sub_motion: HashMap::new(),
            linuxcnc_later: Box::default(),
            linuxcnc_later_bodies: Box::default(),
            linuxcnc_spindle_unknown: false,
            linuxcnc_compensation_unknown: false,
            linuxcnc_tool_change_stopped: false,
            linuxcnc_point_unsure: 0,
            linuxcnc_units_turned: 0,
            linuxcnc_m_units: None,
            linuxcnc_double: Default::default(),
            linuxcnc_cycle_bottom: None,
            linuxcnc_series_start: None,
            linuxcnc_m72_cycle: None,
            linuxcnc_series_first: false,
            linuxcnc_cycle_ran: None,
            linuxcnc_cycle_r: None,
            linuxcnc_feed_rate: tooling::LinuxCncFeed::Zero,
            linuxcnc_rate: Some(Dec::ZERO),
            linuxcnc_rate_before_sub: None,
            linuxcnc_f_before_sub: (None, false, false),
            linuxcnc_feed_saved: None,
            linuxcnc_feed_loose: None,
            linuxcnc_extras: structure::RestoreExtras::START,
            linuxcnc_abc_start: ([None; 3], 0, 0, 0),
            linuxcnc_abc_exact: 0b111,
            linuxcnc_feed_restored_at: None,
            linuxcnc_m72_dropped: None,
            linuxcnc_m72_differs: false,
            linuxcnc_m72_plane_differs: None,
            linuxcnc_m72_motion: None,
            linuxcnc_nurbs: tooling::Nurbs::default(),
            linuxcnc_nurbs_last: None,
            linuxcnc_dynamic_compensation: false,
            linuxcnc_compensation_quiet: None,
            linuxcnc_uvw_let_pass: None,
            linuxcnc_uvw_plane: false,
            linuxcnc_plane_unknown: false,
            linuxcnc_plane_blocks: Vec::new(),
            linuxcnc_plane_body_blocks: Vec::new(),
            linuxcnc_plane_before_sub: None,
            linuxcnc_plane_subs: HashMap::new(),
            data_input,
            programs: 0,
            split: dialect::ProgramSplit::default(),
            macro_arguments: false,
            m_call_possible: None,
            program_section: None,
            reading_end: dialect::ReadingEnd::new(family),
        }
    }

    pub fn units(&self) -> Units {
        self.config.limit_units
    }

    /// Whether the statistics of the moves (extents, lengths, arcs, time) are kept: yes
    /// unless told here. Without them, and without the path, a move's geometry is not worked
    /// out for them at all; the findings are the same, and the statistics hold the blocks,
    /// tools and travel counts alone.
    pub fn keep_stats(&mut self, keep: bool) {
        self.keep_stats = keep;
    }

    /// Whether the statistics of the moves are kept ([`Checker::keep_stats`]).
    pub fn stats_kept(&self) -> bool {
        self.keep_stats
    }

    /// The findings made since the last call.
    pub fn take(&mut self) -> Vec<Finding> {
        let ready = self.ready();
        let held = self.found.split_off(ready);
        std::mem::replace(&mut self.found, held)
    }

    /// How many of the findings made are ready to hand over, the held ones' marks moved to
    /// the findings that stay: not those held for a program read apart
    /// (crate::check::called), nor those made while the blocks a jump passes over are read
    /// (passed.rs), nor a finding that waits for the programs after it
    /// ([`Finding::pending_on`]) and those after it.
    fn ready(&mut self) -> usize {
        let held = match self.hold_from {
            Some(from) => from,
            None => self.passed.as_ref().map_or(self.found.len(), |p| p.from),
        };
        let ready = self.found[..held]
            .iter()
            .position(|f| !f.pending_on.is_empty())
            .unwrap_or(held);
        if let Some(from) = self.hold_from.as_mut() {
            *from -= ready;
        } else if let Some(passed) = self.passed.as_mut() {
            passed.from -= ready;
        }
        ready
    }

    /// Whether any finding was made since the last call ([`Checker::drain`] hands over none
    /// where not: a report written as the lines are checked asks after every line, and most
    /// lines find nothing).
    #[inline]
    pub fn found_any(&self) -> bool {
        !self.found.is_empty()
    }

    /// The findings made since the last call, handed over one by one with the list's
    /// allocation kept for the next: a report written as the lines are checked asks after
    /// every line, and [`Checker::take`] gave the list away each time one had a finding.
    pub fn drain(&mut self) -> std::vec::Drain<'_, Finding> {
        let ready = self.ready();
        self.found.drain(..ready)
    }

    pub fn enabled(&self, rule: Rule) -> bool {
        self.selection.enabled(rule)
    }

    /// The first line of the program being read that holds a word or a block the control
    /// refuses (a reading error, whether or not its rule is selected): the control alarms
    /// there, so nothing after it ran, and what that word would have set is unknown. The
    /// restart refuses after it.
    pub fn refused_at(&self) -> Option<usize> {
        self.refused_at
    }

    /// The first block of the program being read with two codes of one modal group (TG304),
    /// with the check's message: which of them the control takes, or whether it alarms, is
    /// not known, so the modal state after it is not either. The restart refuses after it.
    pub fn conflict_at(&self) -> Option<(usize, &str)> {
        self.conflict_at
            .as_ref()
            .map(|(line, m)| (*line, m.as_str()))
    }

    pub fn report(&mut self, rule: Rule, message: String, line: usize, column: usize) {
        self.reports += 1;
        if self.hold_from.is_some() {
            // (a program's findings held: bounded, crate::check::called)
            self.early_reported();
        }
        // a limit's finding at a word read with a jump's arrival value says where it holds
        let message = match (self.arrival_letters != 0)
            .then(|| self.arrival_said(rule, line, column))
            .flatten()
        {
            Some(more) => message + &more,
            None => message,
        };
        if self.selection.enabled(rule) {
            self.found.push(Finding {
                rule,
                message,
                line,
                column,
                span: false,
                guessed: false,
                placed: Placed::Not,
                pending_on: Vec::new(),
            });
            if !self.linuxcnc_later.ends.is_empty() {
                // (after a call that may end the program: held, structure::PENDING_LATER)
                if let Some(f) = self.found.last_mut() {
                    f.pending_on.push(structure::PENDING_LATER);
                }
            }
            if !self.call_modes.is_empty() {
                // (after a call of a body read later: callmode.rs)
                self.call_mode_held(rule);
            }
        }
    }

    // -- the walk ---------------------------------------------------------------------------

    /// Check one line of a program (its text without the LF), read under `dialect`: the way
    /// the binding feeds whole chunks of text, with no object per block.
    /// `tokens` is the caller's buffer, kept from line to line (it is cleared here).
    pub fn check_line<'a>(
        &mut self,
        text: &'a [u8],
        line: usize,
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
    ) {
        tokens.clear();
        if self.not_read(line, text) {
            return;
        }
        // a line of plain words alone has its words written where they are scanned, with no
        // token between (a debug build reads it through the tokens as well, and asserts the
        // same words); any other line is read in full
        // (whether the line is ASCII, and its CRs where the TV check counts them, are found
        // while its plain words are scanned: the columns are an ASCII line's, made right after
        // for one that is not -- a LinuxCNC parameter's name outside ASCII)
        let mut words: Vec<Word<'a>> = recycle(std::mem::take(&mut self.words_buffer));
        let tv = self.config.tv_check;
        let walks = &mut self.line_walks;
        if let Some(plain) = plain_line_words(text, dialect, &mut words, walks, |o| o + 1, tv) {
            self.check_plain(text, line, dialect, tokens, words, plain);
            return;
        }
        words.clear();
        self.words_buffer = recycle(words);
        self.check_tokens(text, line, dialect, tokens);
    }

    /// Check the line `rest` begins with (up to its first LF, or all of it: [`text::lines`]'
    /// next line), as [`Checker::check_line`] checks it, and give its length. Under a dialect
    /// whose plain words have no bracketed word
    /// ([`crate::tokenizer::plain_words_without_brackets`]) its words are scanned before the
    /// line is split from the rest, the scan stopping at its LF: a line of plain words alone
    /// (nearly every line of a CAM program) is found with no search of its own for the LF,
    /// about 50 instructions a line; any other line is split at its LF and read in full.
    /// The same findings as [`Checker::check_line`] of each line of [`text::lines`].
    ///
    /// [`text::lines`]: crate::text::lines
    pub fn check_next_line<'a>(
        &mut self,
        rest: &'a [u8],
        line: usize,
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
    ) -> usize {
        if !plain_words_without_brackets(dialect) {
            let end = crate::text::line_end(rest);
            self.check_line(&rest[..end], line, dialect, tokens);
            return end;
        }
        // (the tokens are cleared where they are read: a line of plain words reads none)
        let mut words: Vec<Word<'a>> = recycle(std::mem::take(&mut self.words_buffer));
        let tv = self.config.tv_check;
        let walks = &mut self.line_walks;
        if let Some((plain, end)) =
            plain_line_words_to_lf(rest, dialect, &mut words, walks, |o| o + 1, tv)
        {
            let text = &rest[..end];
            if cfg!(debug_assertions) {
                assert_eq!(end, crate::text::line_end(rest), "line {line}: its end");
                let (mut split, mut walks) = (Vec::new(), crate::tokenizer::LineWalks::default());
                let found = plain_line_words(text, dialect, &mut split, &mut walks, |o| o + 1, tv);
                assert_eq!(
                    found,
                    Some(plain),
                    "line {line}: a plain line read to its LF"
                );
                assert!(
                    same_words(&split, &words),
                    "line {line}: its words read to its LF"
                );
            }
            if self.not_read(line, text) {
                words.clear();
                self.words_buffer = recycle(words);
            } else {
                self.check_plain(text, line, dialect, tokens, words, plain);
            }
            return end;
        }
        words.clear();
        self.words_buffer = recycle(words);
        let end = crate::text::line_end(rest);
        let text = &rest[..end];
        if cfg!(debug_assertions) {
            let (mut split, mut walks) = (Vec::new(), crate::tokenizer::LineWalks::default());
            assert!(
                plain_line_words(text, dialect, &mut split, &mut walks, |o| o + 1, tv).is_none(),
                "line {line}: a plain line not read to its LF"
            );
        }
        if !self.not_read(line, text) {
            tokens.clear();
            self.check_tokens(text, line, dialect, tokens);
        }
        end
    }

    /// [`Checker::check_line`] of a line of plain words alone (`plain`: what its reader found
    /// of it), its `words` written where they were scanned.
    #[inline(always)]
    fn check_plain<'a>(
        &mut self,
        text: &'a [u8],
        line: usize,
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
        mut words: Vec<Word<'a>>,
        plain: crate::tokenizer::PlainLine,
    ) {
        self.line_walks_of = (text.as_ptr() as usize, text.len());
        self.line_letters = (plain.letters, plain.motion_codes_only);
        self.line_unbracketed = self.line_walks.set == 0 && self.line_walks.all;
        let ascii = plain.ascii;
        if !ascii {
            for w in &mut words {
                w.column = column(text, w.token.as_ptr() as usize - text.as_ptr() as usize);
            }
        }
        if cfg!(debug_assertions) {
            assert_eq!(ascii, text.is_ascii(), "line {line}: a plain line's ASCII");
            assert!(
                plain
                    .crs
                    .is_none_or(|crs| crs == link::carriage_returns(text)),
                "line {line}: a plain line's CRs"
            );
            let mut read = Vec::new();
            tokens.clear();
            assert!(matches!(tokenize(text, dialect, tokens), Ok(None)));
            Word::extend_of(&mut read, tokens, at_column(text, ascii));
            assert!(
                same_words(&read, &words),
                "line {line}: a plain line's words differ from its tokens'"
            );
            tokens.clear();
        }
        self.check_words(text, line, ascii, plain.crs, words, None);
        // (read by this line's block alone: a block given by other means walks its own)
        self.line_walks_of = (0, 0);
    }

    /// [`Checker::check_line`] of a line that is not of plain words alone: read in full.
    fn check_tokens<'a>(
        &mut self,
        text: &'a [u8],
        line: usize,
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
    ) {
        match tokenize(text, dialect, tokens) {
            Ok(extras) => self.check_read(text, line, tokens, extras.as_ref()),
            Err(error) => self.unreadable(&Unreadable {
                line,
                text,
                rule: error.kind.rule(),
                message: &error.message,
                column: column(text, error.offset),
            }),
        }
    }

    /// Check one line already read by the tokenizer: its `tokens` and `extras`.
    pub fn check_read(
        &mut self,
        text: &[u8],
        line: usize,
        tokens: &[Token<'_>],
        extras: Option<&Extras<'_>>,
    ) {
        let ascii = text.is_ascii();
        let mut words: Vec<Word<'_>> = recycle(std::mem::take(&mut self.words_buffer));
        Word::extend_of(&mut words, tokens, at_column(text, ascii));
        self.check_words(text, line, ascii, None, words, extras);
    }

    /// Check one line's `words` and `extras` (its comments, statements, skip), and keep the
    /// buffers for the next line. `ascii`: the line is ASCII; `crs`: its CRs, where counted
    /// ([`BlockView::crs`]).
    fn check_words<'t>(
        &mut self,
        text: &'t [u8],
        line: usize,
        ascii: bool,
        crs: Option<usize>,
        words: Vec<Word<'t>>,
        extras: Option<&Extras<'t>>,
    ) {
        let Some(e) = extras else {
            // (a line without extras, nearly every one: no buffer of comments or statements
            // taken and given back)
            self.block(&BlockView {
                line,
                text,
                ascii,
                crs,
                words: &words,
                skip: false,
                skip_within: None,
                comments: &[],
                percent: false,
                ident: b"",
                statements: &[],
            });
            self.words_buffer = recycle(words);
            return;
        };
        let at = at_column(text, ascii);
        let mut comments: Vec<(usize, &[u8])> = recycle(std::mem::take(&mut self.comments_buffer));
        let mut statements: Vec<(usize, Kind, &[u8])> =
            recycle(std::mem::take(&mut self.statements_buffer));
        comments.extend(e.comments.iter().map(|&(o, c)| (column(text, o), c)));
        statements.extend(
            e.statements
                .iter()
                .map(|s| (column(text, s.offset), s.kind, &text[s.offset..s.end])),
        );
        self.block(&BlockView {
            line,
            text,
            ascii,
            crs,
            words: &words,
            skip: e.skip != 0,
            skip_within: e.skip_within.map(|(offset, _)| at(offset)),
            comments: &comments,
            percent: e.percent,
            ident: e.ident,
            statements: &statements,
        });
        self.words_buffer = recycle(words);
        self.comments_buffer = recycle(comments);
        self.statements_buffer = recycle(statements);
    }

    /// HEIDENHAIN gives a program's units in its first line, `%NAME G70 *` (inch) or
    /// `%NAME G71 *` (mm): the units its values are read in.
    fn heidenhain_units(&mut self, ident: &[u8]) {
        if self.config.family != Family::Heidenhain {
            return;
        }
        if let Some(code) = heidenhain_units_code(ident) {
            self.machine.codes(&[code]);
        }
    }

    /// Check one block (after the tokenizer's reading), and keep the backplot's facts of it
    /// where the path is recorded. (Out of line: inlined into [`Checker::check_words`], it
    /// kept that out of its callers, a call and the view's copy more at every line.)
    #[inline(never)]
    pub fn block(&mut self, b: &BlockView<'_>) {
        debug_assert_eq!(
            b.ascii,
            b.text.is_ascii(),
            "line {}: the view's ASCII",
            b.line
        );
        self.drawn_block(b);
        // (after a call of a body read later: resumed.rs)
        if self.resumed.is_some() {
            self.resumed_block(b);
        }
        // (a forward jump to note, or runs where one is taken to feed: params.rs)
        if self.after_block {
            self.jump_runs(b);
        }
    }

    /// How the program in hand has ended so far: the line of its M02/M30 (0: none yet), and
    /// whether it returned as a subprogram (M99; a SINUMERIK's M17 or RET; an Okuma's RTS).
    pub fn part_end(&self) -> (usize, bool) {
        (self.ended_line, self.sub_ended)
    }

    /// Asked before line `line` is read: whether the control never reads it
    /// (`dialect::ReadingEnd`), so that it is passed over; TG117 at the first such line that
    /// holds program text.
    #[inline(always)]
    pub fn not_read(&mut self, line: usize, text: &[u8]) -> bool {
        if !self.reading_end.skips(line, text) {
            return false;
        }
        if let Some(unread) = self.reading_end.take_unread() {
            self.never_read(unread);
            // a line of program text after the `%` that ends a subroutine file, past an
            // M2/M30 after it, makes the file a program all the same: run as one, rs274
            // refuses the `%` before it reaches the M2 (`rs274 -g` of `o<tp> sub` ...
            // `o<tp> endsub` / `%` / `M2` / `G0 X2`: "Bad character '%' used"; review 57b F2)
            if let Some((line, column)) = self.sub_percent.take() {
                self.percent_refusal(line, column);
            }
        }
        true
    }

    fn read_block(&mut self, b: &BlockView<'_>) {
        // (the letters first: every rule after may ask them, not walk the words)
        // (a line of plain words has them from its reader: no walk of its words)
        let motion_words;
        let plain_line = self.line_walks_of == (b.text.as_ptr() as usize, b.text.len());
        (self.letters, motion_words) = if plain_line {
            debug_assert_eq!(
                self.line_letters,
                letters_and_motion(b.words),
                "line {}: a plain line's letters",
                b.line
            );
            self.line_letters
        } else {
            letters_and_motion(b.words)
        };
        self.plain_block = plain_line && self.line_unbracketed;
        debug_assert!(
            !self.plain_block
                || !b.skip
                    && b.skip_within.is_none()
                    && b.words
                        .iter()
                        .all(|w| w.index.is_empty() && w.expression.is_empty()),
            "line {}: a plain block's words",
            b.line
        );
        // (a word's token begins with its address, whose capital is its letter: the block's
        // letters say whether one is an M word)
        let m_words = self.letters & bit(b'M') != 0;
        debug_assert_eq!(
            m_words,
            b.words
                .iter()
                .any(|w| w.token.first().is_some_and(|&c| c | 0x20 == b'm')),
            "line {}",
            b.line
        );
        self.reading_end.read_with_m(
            b.words.iter().map(|w| w.token),
            b.statements.iter().map(|&(_, kind, text)| (kind, text)),
            b.skip,
            b.line,
            m_words,
        );
        self.reach_block(b);
        if b.percent && self.reading_end.refuses_percent(b.line, b.text) {
            self.refused_percent(b);
        }
        self.stats.blocks += 1;
        // a byte order mark at the file's start is no text of the program (TG135)
        let mut text = b.text;
        if b.line == 1 {
            if let Some(rest) = text.strip_prefix(crate::tokenizer::BOM) {
                self.byte_order_mark();
                text = rest;
            }
        }
        // (the line's own test, but for the text after a byte order mark)
        let ascii = if text.len() == b.text.len() {
            b.ascii
        } else {
            text.is_ascii()
        };
        if !self.outside_ascii_noted && !ascii {
            self.outside_ascii(b.line, b.text, b.text.len() - text.len());
        }
        self.last_line = b.line;
        // (a body whose start set the main program's spans aside: limits.rs)
        if self.spans_parked_body.is_some() {
            self.body_block(b);
        }
        let first = self.first;
        self.first = false;
        if b.percent {
            // a SINUMERIK archive's next file (`%_N_SUB1_SPF`, whatever the one before ended
            // with): a program of its own (dialect::ProgramSplit), a subprogram by its name
            let opening = dialect::Opening::percent_line(b.text);
            let archived = opening
                .percent
                .and_then(|name| dialect::archive_file(self.config.family, name));
            if self
                .split
                .begins(self.config.family, self.config.program_number, &opening)
            {
                self.next_program();
            } else if !first {
                self.percent_after_start(b);
                return;
            }
            if archived == Some(true) {
                self.machine.forget();
            }
            if first {
                self.identification(b);
                self.heidenhain_units(b.ident);
            }
            return;
        }
        if first {
            self.program_start(b.line);
        }
        // the split every reader makes (dialect::ProgramSplit): an O number or a folder marker
        // after the end or the return of a program begins the next
        // (the block's opening built only after an end: most blocks follow none)
        let opening = || dialect::Opening {
            word: b.words.first().map(|w| (w.column, w.letter)),
            statement: b.statements.first().copied(),
            percent: None,
        };
        let folder = b.words.is_empty()
            && matches!(b.statements, [(_, Kind::Name, text)] if text.starts_with(b"&F="));
        // Setting 156 saves the offsets after a main program's end (M02/M30), as G10 lines
        // up to the final %: a G10 with its L, P, R, Q (a lathe's tip direction) and axis
        // values (G90/G91 and N beside them) and nothing else; any other block (a move, a
        // call, an O number, a G10 with a G00 or an M98 in it) is no saved offset, and is
        // read
        // (asked only inside that section)
        let offset_line = || {
            b.statements.iter().all(|s| s.1 == Kind::Name)
                && (b.words.is_empty()
                    || b.words
                        .iter()
                        .any(|w| w.letter == b'G' && w.number == b"10")
                        && b.words.iter().all(|w| {
                            w.expression.is_empty()
                                && w.index.is_empty()
                                && match w.letter {
                                    b'G' => matches!(w.number, b"10" | b"90" | b"91"),
                                    b'N' | b'L' | b'P' | b'Q' | b'R' => true,
                                    letter => AXES.contains(&letter),
                                }
                        }))
        };
        if self.offsets_section && !offset_line() {
            self.offsets_section = false;
            if b.words.first().is_none_or(|w| w.letter != b'O') {
                let column = b.words.first().map_or(1, |w| w.column);
                self.report(
                    Rule::DigitOverflow,
                    "a block that sets no offset after O999999, the heading of the offsets a \
                     Haas saves after a program's end (Setting 156: G10 lines up to the final \
                     %): what the control does with it is not known, and tapegate reads it as \
                     a program's block"
                        .to_string(),
                    b.line,
                    column,
                );
            } else {
                self.split.ended(true); // the saved offsets end where the next program begins
            }
        }
        if self
            .split
            .begins_after_end(self.config.family, self.config.program_number, opening)
        {
            // (a main program's M30, whatever follows it: its M97 local subroutines end in
            // M99 before the saved offsets)
            let main_ended = self.ended_line != 0;
            // (what the program before left, read before the reset state)
            self.after_end();
            self.program_shift_end();
            self.next_program();
            self.called_units(b);
            self.empty_folder = folder;
            self.offsets_section = self.config.haas
                && main_ended
                && b.words
                    .first()
                    .is_some_and(|w| w.letter == b'O' && w.number == b"999999");
        } else if self.offsets_section {
            return; // a saved offset's G10: what it sets is not read (TG205 said so)
        } else if !folder && (!b.words.is_empty() || !b.statements.is_empty()) {
            self.empty_folder = false;
        }
        // (LinuxCNC: a line in the skip of a block known not to run, no o-word line: rs274
        // reads it for its o-word only and runs nothing of it, interp_read.cc read_items)
        if self.subroutine_file(b) {
            return;
        }
        self.definition_section(b);
        if dialect::defines_subprogram(self.config.family, b.statements) {
            // PROC NAME: a subprogram, under its caller's position, feed and speed
            self.machine.forget();
        }
        if b.words.is_empty() {
            statements_only_block!(self, b);
            return;
        }
        // Heidenhain closes a program with "N99999999 %NAME G71 *": its closing %
        let name = b
            .statements
            .iter()
            .find(|&&(_, kind, text)| kind == Kind::Name && text.starts_with(b"%"))
            .filter(|_| self.config.family == Family::Heidenhain);
        if let Some(&(_, _, text)) = name {
            if heidenhain_units_code(text).is_some() {
                self.percent_closed = true;
                self.closed |= self.ended_line > 0;
            } else {
                self.heidenhain_call(b.line, &text[1..]);
            }
            return;
        }
        // FANUC's G10 L50 / G10 L3 data: parameter and tool life values, no program. Outside
        // the mode only a block with a G (its G10) and an L word opens it: no other is read for
        // its codes (a debug build, the tests', reads every block and holds it to that)
        let words = b.words.iter().map(|w| (w.letter, w.number));
        let g_and_l = bit(b'G') | bit(b'L');
        let may_be_data = self.data_input.open().is_some() || self.letters & g_and_l == g_and_l;
        let data = if may_be_data || cfg!(debug_assertions) {
            self.data_input.block(self.config.family, b.line, words)
        } else {
            dialect::DataBlock::Program
        };
        debug_assert!(may_be_data || matches!(data, dialect::DataBlock::Program));
        match data {
            dialect::DataBlock::Data { .. } => {
                self.tv(b);
                for &(column, comment) in b.comments {
                    self.comment(comment, b.line, column);
                }
                return;
            }
            dialect::DataBlock::Stray { opened, l, letter } => {
                // the control alarms at this block; the checker reads it as program
                let g11 = b
                    .words
                    .iter()
                    .any(|w| w.letter == b'G' && crate::meaning::code(w.number) == Some((11, 0)));
                let message = format!(
                    "G10 L{l} on line {opened} opens a data input mode whose blocks hold only \
                     {} words until its G11, and line {}'s {} word is none: {} (the control \
                     alarms at line {})",
                    if l == 50 { "N P R" } else { "N P L Q T H D" },
                    b.line,
                    letter as char,
                    if g11 {
                        "the G11 shares its block with a word of the program, which the mode \
                         does not take"
                    } else {
                        "the G11 is missing"
                    },
                    b.line
                );
                self.report(Rule::DataModeNotClosed, message, opened, 1);
            }
            dialect::DataBlock::Lacked { l } => {
                let message =
                    format!(
                    "G10 L{l} is FANUC's {} mode, which a Haas does not have (its G10 takes L2, \
                     L10-L13 and L20): the control alarms at the L, or reads the data blocks \
                     after it as program",
                    if l == 50 { "parameter input" } else { "tool life data input" }
                );
                let column = column_of(b.words, b'L');
                self.report(Rule::DataModeNotClosed, message, b.line, column);
            }
            dialect::DataBlock::Program => {}
        }
        self.words_after_end(b);
        let first_words = self.first_words;
        self.program_number(b);
        if !b.statements.is_empty() {
            self.program_name(b, first_words);
        }
        self.tv(b);
        // the block's codes are G00-G03 alone, as a CAM program's `G1 X Y` and `G2 X Y I J`
        // are: they set no units or feed mode and give no word a meaning, and the rules that
        // read those of the block's codes are not asked (a debug build asks them anyway and
        // holds them to the same)
        let motion_only = self.letters & (bit(b'G') | bit(b'M')) == bit(b'G')
            && !self.shapes.afresh
            && motion_words;
        self.motion_only = motion_only;
        (self.block_units, self.block_feed_units, self.block_feed_rev) =
            self.block_modes(b, motion_only);
        // a jump arrives only where a GOTO named a label (or computed one), and only a
        // statement names one
        if self.goto_computed
            || !self.goto_targets.is_empty()
            || !self.goto_names.is_empty()
            || !b.statements.is_empty()
        {
            self.jump_arrival(b);
        }
        // (no meaning, as most blocks': the meanings left as they are where they are none
        // already)
        match self.code_meanings(b, motion_only) {
            None if self.meanings_none => {}
            None => {
                self.meanings = crate::meaning::Meanings::default();
                self.meanings_none = true;
            }
            Some(meanings) => {
                self.meanings = meanings;
                self.meanings_none = false;
            }
        }
        debug_assert!(!self.meanings_none || self.meanings == crate::meaning::Meanings::default());
        self.words(b);
        self.targets(b);
        // (the rules that read only a block's statements are not called for a block with
        // none: nearly every block of a CAM program)
        if !b.statements.is_empty() {
            self.named_motions(b);
        }
        let before = Before::of(&self.machine.state);
        self.values.clear();
        let mut first_unknown = None;
        // a G code the family's list lacks: a macro call by parameter (FANUC, Haas) or a REMAP
        // (LinuxCNC) takes the block's axis words as its arguments, and where the axes stand
        // after it is not known (issue 32, item 4); where the control alarms, TG306 says so
        let mut lacked_code = false;
        // (the key of the block's codes, built code by code in this walk)
        let mut code_key = codes::KeyBuilder::new();
        for (i, w) in b.words.iter().enumerate() {
            let Some(v) = self.readable[i] else {
                if matches!(w.letter, b'G' | b'M') {
                    code_key.refuse();
                }
                // F#101, X[#1+#2], X=R1+5: a value in force that cannot be known here; and
                // S2=30000, X4=R1+5, a SINUMERIK's spindle or axis numbered by its extension
                // (a number or an expression), whose limits the profile's are not: not
                // evaluated, its address unknown. Whether S1= is the master spindle is machine
                // data: every extension is taken alike. (M1=3: another spindle's M code, in no
                // modal group with M2=4's.)
                let extended =
                    !w.index.is_empty() && dialect::extended_address(self.config.family, w.letter);
                // a plain word without a value: one its format refused (a reading error, said
                // at the word): the control alarms on it, so what it would set is not known,
                // and no rule reads a value guessed from the one before
                let refused = w.expression.is_empty() && w.index.is_empty();
                if refused && !matches!(w.letter, b'G' | b'M' | b'N' | b'O') {
                    if w.letter.is_ascii_uppercase() {
                        self.values.set_unknown(w.letter);
                    }
                    continue;
                }
                if (!w.expression.is_empty() && w.index.is_empty() || extended)
                    && w.letter.is_ascii_uppercase()
                    && self.centre_dimension(w).is_none()
                    && !matches!(w.letter, b'G' | b'M' | b'N' | b'O')
                {
                    self.values.set_unknown(w.letter);
                    // X0=R1: TG206 says the word names no axis; a note beside it adds nothing
                    let named = !extended
                        || self
                            .index_allowed(w.letter, formats::written_index(w.index))
                            .0;
                    if named {
                        first_unknown.get_or_insert(i);
                    }
                } else if extended
                    && w.letter == b'M'
                    && self
                        .index_allowed(w.letter, formats::written_index(w.index))
                        .0
                    && self.extended_m_number(w).is_none()
                {
                    // M2=R1+R2: spindle 2's M function chosen by a value the checker cannot
                    // evaluate, its code unknown (M100=R1: TG206 alone)
                    first_unknown.get_or_insert(i);
                }
                continue;
            };
            match w.letter {
                // G91.1 is a code of its own, never G91: a decimal G code sets no mode the
                // modal state knows (the dialect's code table names what it does)
                b'G' if !v.is_whole() => {
                    code_key.refuse();
                    self.values.other_work_system |= matches!(v.trunc(), 54 | 59);
                    self.values.mirror |= crate::modal::mirror_code(v);
                    self.values.decimal_g = true;
                    lacked_code |= self.code_lacked(v);
                    // (G66.1, a FANUC's modal macro call at each block: a call, which
                    // dialect::calls reads from the whole codes alone; the program its P
                    // names is not matched, so any of the file may be it)
                    if v.trunc() == 66 {
                        self.early_calls();
                        self.call_numbers_any = true;
                    }
                }
                b'G' => {
                    let g = v.trunc();
                    code_key.code(w, g);
                    self.values.push_g(g);
                    // (code_lacked's whole-number half, the value known whole here)
                    lacked_code |= self.machine.settings.lacks(g);
                }
                b'M' => {
                    let m = v.trunc();
                    if v.is_whole() {
                        code_key.code(w, m);
                    } else {
                        code_key.refuse();
                    }
                    self.values.ms.push(m);
                }
                // G68 R45 (an angle), G05.1 Q1 (a selector), G68.2 X Y Z (a tilted plane's
                // origin): no position, radius or cycle value
                // (no code of the block gives a meaning, as most blocks': none of these)
                letter
                    if !self.meanings_none
                        && (self.meanings.not_length(letter)
                            || (self.meanings.data && AXES.contains(&letter))) =>
                {
                    self.values.set_other(letter, v);
                }
                letter => self.values.set_default(letter, v),
            }
        }
        self.values.in_system(&self.config.modal);
        // (no key where verdicts are not kept: Checker::keep_verdicts, the tests' oracle)
        // (a debug build holds the key built in the walk to the one read from the words)
        self.code_key = if self.format_table.afresh {
            None
        } else {
            code_key.key()
        };
        debug_assert_eq!(
            self.code_key,
            codes::code_key(b.words, &self.readable).filter(|_| !self.format_table.afresh),
            "line {}: the codes' key",
            b.line
        );
        // what the codes do with the axis words: kept by the set of codes (a debug build, the
        // tests', works it out anyway and holds the two equal)
        let kept = self.code_key.map_or(0, |k| self.verdicts.get(k));
        let taken = if kept & codes::TAKEN != 0 && !cfg!(debug_assertions) {
            codes::taken_of(kept)
        } else {
            let taken = self.machine.settings.axes_taken(&self.values);
            debug_assert!(kept & codes::TAKEN == 0 || codes::taken_of(kept) == taken);
            if let Some(k) = self.code_key {
                self.verdicts.add(k, codes::taken_flags(taken));
            }
            taken
        };
        let taken = match taken {
            None if lacked_code => Some(crate::modal::AxesTaken::Unknown),
            taken => taken,
        };
        // (LinuxCNC's state steps around the modal state's, out of line: the other families'
        // blocks test the family once here)
        let linuxcnc = self.config.family == Family::LinuxCnc;
        if linuxcnc {
            self.linuxcnc_apply(b, taken, &before);
        } else {
            self.machine.apply_taken(&self.values, taken);
            // (one test of the two flags on a plain block: both are seldom set)
            if self.units_unknown | self.early_on {
                self.units_given_now();
            }
            // (a frame's cancel moves the position to the coordinates after it: state, not a
            // rule)
            self.cancel_frames(b, &before);
            self.programmed_forms(b, &before);
        }
        self.radius_arc = None;
        // (the rules read the state after the block in place: a build with debug assertions,
        // the tests', holds them to leaving it as they found it)
        let takes_axes = self.motion_codes(b);
        #[cfg(debug_assertions)]
        let mut applied = self.machine.state;
        #[cfg(debug_assertions)]
        {
            self.position_reexpressed = false;
        }
        self.codes(b, &before, takes_axes);
        // (but for the position a G54-G59 re-expresses in the new system, or a loop takes
        // back: limits.rs, `selection_reexpressed`, `reexpression_held`)
        #[cfg(debug_assertions)]
        if self.position_reexpressed {
            applied.position = self.machine.state.position;
        }
        #[cfg(debug_assertions)]
        assert_eq!(
            self.machine.state, applied,
            "line {}: a rule changed the state",
            b.line
        );
        // (LinuxCNC: where a cycle or a rigid tap left the tool, after the rules read its
        // bottom; state, not a rule)
        if linuxcnc {
            self.linuxcnc_after_rules(&before);
        }
        if let Some(i) = first_unknown {
            self.not_evaluated(b.line, &b.words[i]);
        }
        // (what a word read from a jump's arrival set is unknown after its block)
        if self.arrival_letters != 0 {
            self.arrival_forget(b.line);
        }
        // L100 calls; L1=R2 is an indexed word, no call
        let l_word = self.letters & bit(b'L') != 0
            && b.words
                .iter()
                .any(|w| w.letter == b'L' && w.index.is_empty());
        let calls = dialect::calls(
            self.config.family,
            self.values.gs(),
            &self.values.ms,
            l_word,
        );
        // LinuxCNC: an M word's value read before the line's own assignments, which rs274
        // makes at the line's end (`#1=2 M#1` after `#1=5` is M5; review 48, F8)
        let linuxcnc_m_end = linuxcnc
            && self.letters & bit(b'M') != 0
            && (self.linuxcnc_m_ends(b) || self.linuxcnc_main_m99(b));
        self.assignments(b);
        self.formulas(b);
        if self.config.haas {
            self.parameter_elements(b);
        }
        if !b.statements.is_empty() {
            self.variables(b);
            self.system_variables(b);
        }
        // a jump or a call the checker does not follow: a statement, or a calling word
        if calls {
            // (where a call of a body read later is made from, and in which G90/G91, before
            // the call forgets them: resumed.rs)
            self.call_from = (b.line, before.xyz, before.incremental);
            self.call_unread_here = false;
            self.early_calls();
            // (the shift the call is made under, before a G52 its program leaves on is
            // carried into this one, Checker::shift_carried)
            self.call_shifts();
            if self.shifts.on {
                self.shift_call(b);
            }
            self.call_made(b);
        }
        if (calls || !b.statements.is_empty()) && self.statements(b, calls.then_some(b)) {
            let never = !calls && self.flow_never(b);
            self.forget_at_jump(b, calls);
            // (a conditional jump forward changes no parameter where it is not taken)
            if calls || !self.jump_keeps_params(b) {
                self.params_forgotten();
            } else {
                self.jump_noted(b);
            }
            self.motion_unknown = true;
            self.linuxcnc_motion_after_call(b, calls);
            self.polar = polar::Polar::default();
            self.linuxcnc_spindle_unknown = true;
            self.linuxcnc_uvw_unfollowed(b);
            self.linuxcnc_compensation_unknown = true;
            self.linuxcnc_plane_after_call(b, calls);
            self.linuxcnc_feed_rate = tooling::LinuxCncFeed::Unknown;
            self.linuxcnc_rate = None;
            self.linuxcnc_nurbs = tooling::Nurbs::unknown();
            self.linuxcnc_nurbs_last = None;
            if !std::mem::take(&mut self.call_keeps) {
                self.call_offsets_rewritten(b.line, calls, never);
            }
        }
        self.call_keeps = false;
        // every M word with a value read is in `values.ms`: a block with none (nearly every
        // block) ends by no M02/M30 and returns by no M99/M17, and only a statement is left
        // to look at (RET, RTS)
        let m_read = !self.values.ms.is_empty();
        let mut ends = m_read
            && b.words.iter().enumerate().any(|(i, w)| {
                w.letter == b'M' && self.readable[i].is_some_and(|v| v.eq_int(2) || v.eq_int(30))
            });
        if self.config.family == Family::LinuxCnc && self.letters & bit(b'M') != 0 {
            ends = self.linuxcnc_end(b, ends || linuxcnc_m_end);
        }
        let returns = (m_read || !b.statements.is_empty())
            && dialect::returns(self.config.family, b.words, b.statements, &self.readable);
        self.sub_ended |= returns;
        self.split.ended(ends || returns);
        if ends {
            if self.linuxcnc_later.main_end == 0 && self.open_definition.is_none() {
                self.linuxcnc_later.main_end = b.line;
            }
            self.ended_line = b.line;
            self.after_watch = true;
            self.main_ended = true;
            // (LinuxCNC: one in a block known to run ends it too: review 51, F13)
            if self.config.family != Family::LinuxCnc || self.linuxcnc_runs_surely() {
                self.surely_ended = true;
                // (LinuxCNC: the lines after it are dead, read in full: subroutine_file)
                self.linuxcnc_quiet = false;
            } else if self.open_definition.is_none() {
                let depth = self.linuxcnc_open_flow.len();
                self.linuxcnc_end_depth =
                    Some(self.linuxcnc_end_depth.map_or(depth, |d| d.min(depth)));
            }
        }
        if ends || returns {
            // (an end, or a return elsewhere: review 62a F4)
            self.after_return(b, ends);
            // a return or end the block skip can pass over (`/M99` before an `M30`: a bar
            // feeder's loop, or `G00 X0 /M99` with the slash in the middle) does not show the
            // part to be a subprogram: its held findings wait
            let skipped_m = |codes: &[i64]| {
                b.skip
                    || b.skip_within.is_some_and(|at| {
                        b.words.iter().enumerate().any(|(i, w)| {
                            w.column > at
                                && w.letter == b'M'
                                && self.readable[i]
                                    .is_some_and(|v| codes.iter().any(|&c| v.eq_int(c)))
                        })
                    })
            };
            let skippable = skipped_m(&[99]);
            // (what follows a return in its program runs only where a jump arrives: a main's
            // `M99 P5` goes to its N5, a plain M99 to its start, passing over what lies
            // between (0i-MF Operator's Manual, "Subprogram call (M98)"): a G10 after it is
            // no value known, review 61a F10)
            self.jumped |= returns;
            if ends {
                self.skipped_end = skipped_m(&[2, 30]);
            }
            self.end_skippable = skipped_m(&[2, 30, 99]);
            if !(returns && !ends && skippable) {
                self.part_ended(returns);
            }
            // (no run falls through to the block after it: a jump's arrival there keeps no
            // values in file order, Checker::jump_arrival)
            if !skippable {
                self.cut_block = self.stats.blocks;
            }
            // what follows an end or a return in the file (a local subprogram N100 called by
            // M97/M98, another program) is reached only by a call or a jump, and starts where
            // its caller left the machine: no position, feed or speed is known there
            self.machine.forget();
        }
    }

    /// The reading of a block without words (`statements_only_block!`) out of line, for the
    /// LinuxCNC lines that read as o-word lines.
    #[cold]
    #[inline(never)]
    pub(super) fn statements_only_block(&mut self, b: &BlockView<'_>) {
        statements_only_block!(self, b);
    }

    /// A `%` line after the program's first block: a HEIDENHAIN program call (`%NAME *`
    /// without the units of an end line, which shares the Q parameters), else the closing `%`.
    fn percent_after_start(&mut self, b: &BlockView<'_>) {
        if self.config.family == Family::Heidenhain && heidenhain_units_code(b.ident).is_none() {
            self.heidenhain_call(b.line, b.ident);
        } else {
            self.percent_closed = true;
            self.jump_runs_ended();
            if self.ended_line > 0 {
                self.closed = true;
            }
        }
    }

    /// [`Checker::read_block`]'s application of a LinuxCNC block's values to the modal state,
    /// with the state steps of LinuxCNC around it (out of line: no other family's block runs
    /// them).
    #[inline(never)]
    fn linuxcnc_apply(
        &mut self,
        b: &BlockView<'_>,
        taken: Option<crate::modal::AxesTaken>,
        before: &Before,
    ) {
        // (an M2/M30 inside a condition, a loop or a definition may not run, and the lines
        // after it run only where it did not: it resets no mode; review 19)
        // (and one after a block delete `/`, which the switch may pass over)
        self.values.end_unsure = b.skip || !self.linuxcnc_runs_surely();
        // (the cycle an M72's dropped block leaves in force; rare)
        if self.letters & bit(b'M') != 0 {
            let state = &self.machine.state;
            // (the units an M70 or M73 saves: the block's G20/G21 runs after it)
            self.linuxcnc_m_units =
                (!self.units_unknown).then_some((state.units, state.feed_units));
        }
        // (A B C before a block that names one: a probe's start, rare)
        if self.letters & (bit(b'A') | bit(b'B') | bit(b'C')) != 0 {
            self.linuxcnc_abc_named();
        }
        if self.linuxcnc_feed_saved.is_some() && self.letters & bit(b'M') != 0 {
            let state = &self.machine.state;
            self.linuxcnc_m72_cycle = Some(structure::M72Cycle {
                motion: state.motion,
                cycle: state.cycle,
                words: state.cycle_words,
                bottom: self.linuxcnc_cycle_bottom,
                r: self.linuxcnc_cycle_r,
                units: (state.units, state.feed_units),
                abc: [state.position[6], state.position[7], state.position[8]],
                unknown: state.unknown,
            });
        }
        self.machine.apply_taken(&self.values, taken);
        if self.units_unknown | self.early_on {
            self.units_given_now();
        }
        // (a frame's cancel moves the position to the coordinates after it: state, not a rule)
        self.cancel_frames(b, before);
        self.linuxcnc_nurbs_position(b, before);
        self.programmed_forms(b, before);
        // (the main program's distance mode not known after a G90/G91 in a condition or
        // loop, M70's restored by M72: review 49a, F1, F6; state, not a rule)
        if self.letters & (bit(b'G') | bit(b'M')) != 0
            && !self.motion_only
            && self.open_definition.is_none()
        {
            self.linuxcnc_distance_modal(b, before.incremental);
        }
        // (and its feed mode, feed and speed, where an M70 or M73 of it saved them: rare; or
        // what a save's later turn in a loop may take)
        if self.letters & bit(b'M') != 0
            || self.linuxcnc_feed_saved.is_some()
            || self.linuxcnc_feed_loose.is_some() && !self.linuxcnc_open_flow.is_empty()
        {
            self.linuxcnc_feed_restore(b, before);
        }
    }

    /// LinuxCNC: where a cycle or a rigid tap left the tool, and the motion of a block whose
    /// M72 may be dropped, after the block's rules ([`Checker::read_block`]).
    #[inline]
    fn linuxcnc_after_rules(&mut self, before: &Before) {
        if let Some(ran) = self.linuxcnc_cycle_ran.take() {
            self.linuxcnc_cycle_end(ran, before);
        }
        if let Some(dropped) = self.linuxcnc_m72_motion.take() {
            self.linuxcnc_m72_motion_back(dropped);
        }
    }

    /// The meanings the block's codes give its words, as the converter reads them
    /// ([`crate::convert::code_meanings`]: the cycle tables and [`crate::meaning`]), from the
    /// whole G and M codes written in it. A shape met in the last few blocks ([`shapes::Shape`]: the codes, the letters, the
    /// cycle in force) has the meanings worked out for it then.
    ///
    /// `motion_only`: the block's codes are G00-G03 alone ([`motion_codes_only`]), which no
    /// table gives a word a meaning by (`convert::cycle_table`, [`crate::meaning::block`]),
    /// and a cycle in force is not read in a block that writes one of them: no meaning, no
    /// shape worked out (a debug build works the meanings out and holds them to none).
    ///
    /// None for a block no code gives a word a meaning without a look at its words (G00-G03
    /// alone, or no code and no code in force a block repeats, `ModalState::code_in_force`: a
    /// mill's canned cycle, a lathe's G32 or G92): [`crate::meaning::Meanings::default`].
    fn code_meanings(
        &mut self,
        b: &BlockView<'_>,
        motion_only: bool,
    ) -> Option<crate::meaning::Meanings> {
        // (a mill's cycle in force repeats in a block whose codes are planes alone, G17-G19:
        // `G17 X10. K4` after a G81 is four holes, its K the count; review 51, F10)
        let in_force = self
            .machine
            .state
            .code_in_force(self.config.modal.fanuc_lathe);
        if motion_only && (in_force.is_none() || motion_written(b)) {
            debug_assert_eq!(
                self.meanings_afresh(b),
                crate::meaning::Meanings::default(),
                "line {}: G00-G03 gave a word a meaning",
                b.line
            );
            return None;
        }
        let codes = self.letters & (bit(b'G') | bit(b'M')) != 0;
        // a block of words alone in a mill's canned cycle repeats it (`X2. Y2. K3` after
        // G81): its words mean what the cycle's do
        let cycle = in_force;
        if !codes && cycle.is_none() {
            return None; // no code gives a word a meaning
        }
        let Some(shape) = shapes::Shape::of(b.words, cycle) else {
            return Some(self.meanings_afresh(b));
        };
        if let Some(kept) = self.shapes.get(&shape) {
            debug_assert_eq!(kept, self.meanings_afresh(b), "line {}", b.line);
            return Some(kept);
        }
        let meanings = self.meanings_afresh(b);
        self.shapes.keep(shape, meanings);
        Some(meanings)
    }

    /// [`Checker::code_meanings`] worked out from the tables, as the modal state on its own
    /// reads them ([`crate::convert::block_meanings`]).
    fn meanings_afresh(&self, b: &BlockView<'_>) -> crate::meaning::Meanings {
        let control = (self.config.family, self.config.haas);
        let words = b.words.iter().map(|w| (w.letter, w.number));
        let modal = &self.config.modal;
        let cycle = self.machine.state.code_in_force(modal.fanuc_lathe);
        crate::convert::block_meanings(modal, control, cycle, words)
    }

    /// The units a block's lengths and its feed are in, and whether its feed is per
    /// revolution: the modes in force, or the block's own units code and G93, G94, G95 (a
    /// Fanuc or Haas lathe's G98, G99), which its words are read in. One pass over its G
    /// words, each number read once, for both.
    ///
    /// `motion_only`: the block's codes are G00-G03 alone ([`motion_codes_only`]), none of
    /// them a units or feed mode code: the modes in force (a debug build reads the codes
    /// anyway and holds the two equal).
    fn block_modes(&self, b: &BlockView<'_>, motion_only: bool) -> (Units, Units, bool) {
        let settings = &self.machine.settings;
        let lathe = settings.fanuc_lathe;
        let mut units = (self.machine.state.units, self.machine.state.feed_units);
        let mut mode = self.machine.state.feed_mode;
        if self.letters & bit(b'G') == 0 || motion_only && !cfg!(debug_assertions) {
            return (units.0, units.1, mode == 95);
        }
        let in_force = (units.0, units.1, mode == 95);
        for w in b
            .words
            .iter()
            .filter(|w| w.letter == b'G' && !w.number.is_empty() && !w.point)
        {
            let Some(n) = whole_number(w.number) else {
                continue;
            };
            let n = settings.read_g(n);
            if let Some(found) = settings.units_code(n) {
                units = found;
            }
            match n {
                93..=95 => mode = n,
                98 if lathe => mode = 94,
                99 if lathe => mode = 95,
                _ => {}
            }
        }
        debug_assert!(
            !motion_only || (units.0, units.1, mode == 95) == in_force,
            "line {}: G00-G03 set a units or feed mode",
            b.line
        );
        (units.0, units.1, mode == 95)
    }

    /// The program-level findings, said once the whole program has been read.
    pub fn finish(&mut self) {
        self.passage_ended(None);
        if let Some((opened, l)) = self.data_input.open() {
            // the file ends inside the mode: its G11 is missing too
            let message = format!(
                "G10 L{l} on line {opened} opens a data input mode whose G11 is missing: the \
                 file ends inside it"
            );
            self.report(Rule::DataModeNotClosed, message, opened, 1);
        }
        self.flow_ended();
        self.part_ended(false);
        self.early_finish();
        self.after_end();
        self.program_shift_end();
        if !self.linuxcnc_later.moves.is_empty() {
            self.linuxcnc_later_unanswered();
        }
        if self.config.family == Family::LinuxCnc {
            self.later_bodies_ended(self.last_line);
        }
        if !self.linuxcnc_later.ends.is_empty() {
            self.linuxcnc_later_released_at(true);
        }
        self.work_call_tentative_end();
        self.call_modes_ended();
        self.pending_on_ended();
        self.targets_ended();
        self.odd_blocks();
        self.colons_in_comments();
        self.linuxcnc_locals_ended();
        self.program_end();
    }

    // -- after the codes --------------------------------------------------------------------

    /// The rules that read the block's codes and the modal state before and after it, in the
    /// order their findings are said: codes and groups, the motion mode, a dwell (which ends
    /// the checks of its block unless it moves an axis too), speed, compensation, threads,
    /// cycles, feeds and arcs, then the limits and the statistics. The state after the block
    /// is the machine's (`self.machine.state`), read in place by each rule: none of them
    /// changes it, and a copy of its 1 KB a block was the largest single cost of the walk.
    fn codes(&mut self, b: &BlockView<'_>, before: &Before, takes_axes: bool) {
        self.code_words(b);
        self.program_stops(b);
        let facts = Facts::new(b.words, &self.values, self.machine.settings.dwell);
        self.motion_mode(b, &facts, takes_axes);
        self.reference_return(b.line, &facts);
        if facts.has(4) {
            self.dwell(b, &facts);
            self.dwell_time(b);
            if facts.moved().is_empty() {
                // a dwell's own refusals (G4 P-1), and the modes its block sets
                if self.config.family == Family::LinuxCnc {
                    self.linuxcnc_refusals(b, &facts, before);
                }
                // a frame's or a shift's code beside the dwell (`G04 P1. G69`) takes effect in
                // its block all the same: without this the position was taken back at G69 and
                // the rotation left on (review 15, finding 1)
                self.turn_frames(b);
                self.work_offset(b);
                self.shift_spans(b, before);
                return;
            }
            // LinuxCNC's G4 P1 X10 dwells, then moves to X10 in the motion mode in force
        }
        self.surface_speed(b, &facts);
        self.compensation(b.line, before, &facts);
        self.threads(b, &facts);
        self.cycles(b.line, before, &facts);
        // (LinuxCNC: the refusals first, which take the current point as unknown after a
        // code that moves it by an amount the checker does not follow, the arc checks then,
        // and the point known again after an absolute move)
        let unsettles =
            self.config.family == Family::LinuxCnc && self.linuxcnc_refusals(b, &facts, before);
        self.feeds(b, before, &facts);
        if self.config.family == Family::LinuxCnc {
            self.linuxcnc_doubles(before);
            if !unsettles {
                self.linuxcnc_settle();
            }
        }
        self.heidenhain_centre();
        self.turn_frames(b);
        let absolute = self.work_offset(b);
        self.limits(b.line, &facts, absolute);
        self.shift_spans(b, before);
        // the statistics and the path, where either is kept (no rule reads them)
        if (self.keep_stats || self.record_path) && !self.cycle_unmodelled {
            let draws = self.draws(b, &facts);
            self.motion_stats(before, facts.moved(), b.line, draws);
        }
    }
}

/// How far a LinuxCNC file is in the form of a subroutine file: one subroutine definition
/// and nothing after it but M2 ([`Checker::subroutine_file`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum SubFile {
    /// Nothing read yet but comments.
    Unknown,
    /// Its first statement opened a definition (`o<name> sub`).
    Open,
    /// The definition is closed (`o<name> endsub`), and nothing but M2 or M30 followed.
    Closed,
    /// Not a subroutine file.
    No,
}

/// Whether every G word of `words` is G00, G01, G02 or G03, or a plane's G17, G18 or G19,
/// written plainly -- one to three digits, no point, sign, expression or index (`G1`, `G02`,
/// `G003`, `G17`, `G018`) -- as nearly every G word of a CAM program's moves is (a ramp's
/// `G18 G2`): such a block's codes set no units or feed mode and give no word a meaning
/// ([`Checker::block_modes`], [`Checker::code_meanings`]; a debug build works them out and
/// asserts it). Asked of a block with a G word and no M word.
pub(crate) fn motion_codes_only(words: &[Word<'_>]) -> bool {
    words
        .iter()
        .all(|w| w.letter != b'G' || plain_motion_code(w))
}

/// Whether a block whose G codes are G00-G03 and G17-G19 written plainly
/// ([`motion_codes_only`]) writes one of G00-G03: one that writes planes alone keeps a mill's
/// canned cycle in force ([`Checker::code_meanings`]). Asked only under a cycle.
#[cold]
#[inline(never)]
fn motion_written(b: &BlockView<'_>) -> bool {
    b.words
        .iter()
        .any(|w| w.letter == b'G' && !matches!(w.number.last(), Some(b'7'..=b'9')))
}

/// Whether G word `w` is G00-G03 or G17-G19 written plainly ([`motion_codes_only`]).
#[inline(always)]
fn plain_motion_code(w: &Word<'_>) -> bool {
    matches!(
        w.number,
        [b'0'..=b'3']
            | [b'0', b'0'..=b'3']
            | [b'0', b'0', b'0'..=b'3']
            | [b'1', b'7'..=b'9']
            | [b'0', b'1', b'7'..=b'9']
    ) && w.sign.is_empty()
        && w.expression.is_empty()
        && w.index.is_empty()
}

/// The units code of a HEIDENHAIN `%NAME G71 *` line (70 inch, 71 mm), if it has one: the
/// first and last lines of a program have it, a program call (`%NAME *`) has not.
/// The value of a run of ASCII digits (a word's number, its sign split off), as
/// `str::parse::<i64>` reads it (None for a byte that is not a digit, an empty run or one past
/// `i64`), without the text checked for UTF-8 first: asked of every G word of every block.
fn whole_number(digits: &[u8]) -> Option<i64> {
    if digits.is_empty() {
        return None;
    }
    digits.iter().try_fold(0i64, |n, &d| {
        if !d.is_ascii_digit() {
            return None;
        }
        n.checked_mul(10)?.checked_add(i64::from(d - b'0'))
    })
}

fn heidenhain_units_code(text: &[u8]) -> Option<i64> {
    text.split(|&c| blank(c) || c == b'*')
        .find_map(|w| match w.to_ascii_uppercase().as_slice() {
            b"G70" => Some(70),
            b"G71" => Some(71),
            _ => None,
        })
}

/// A length for a message: six decimals at most, no trailing zeros.
fn round6(x: f64) -> String {
    let text = format!("{x:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

#[cfg(test)]
mod before_tests {
    use super::{
        bit, letters_of, Before, Dec, ModalState, Units, Word, AXES, INDEXED, PARAMETER, SELECTOR,
    };

    /// The letters mask: a bit for each letter written, one for a `#` word and one for a word
    /// with an index, whatever its letter.
    #[test]
    fn the_letters_mask_says_parameters_and_indexes() {
        let of = |text: &str| {
            let words: Vec<Word<'_>> = text
                .split(' ')
                .map(|t| Word::new(t.as_bytes(), 1))
                .collect();
            letters_of(&words)
        };
        assert_eq!(of("G1 X10. Y2."), bit(b'G') | bit(b'X') | bit(b'Y'));
        assert_eq!(of("#1=5"), PARAMETER | INDEXED);
        assert_eq!(of("X1. R1=5"), bit(b'X') | bit(b'R') | INDEXED);
        assert_eq!(of("M2=3"), bit(b'M') | INDEXED);
        assert_eq!(of("X#1"), bit(b'X'));
        assert_eq!(of("M30"), bit(b'M'));
        assert_eq!(of("M3 $1 S100"), bit(b'M') | SELECTOR | bit(b'S'));
        assert_eq!(of("G1 @5 ^30"), bit(b'G') | SELECTOR);
    }

    /// The state before a block as the rules read it is the whole state's: X Y Z (known and
    /// not), every letter's unknown bit, the compensation and the cycle; no other axis.
    #[test]
    fn the_state_before_a_block_reads_as_the_whole_state() {
        let mut state = ModalState::new(Units::Metric);
        for (i, unknown) in [0u32, 1 << 23, (1 << 26) - 1, 0b1010_1010_1010]
            .iter()
            .enumerate()
        {
            state.unknown = *unknown;
            state.compensation = [40, 41, 42, 40][i];
            state.cycle = [None, Some(81), Some(83), None][i];
            for (j, p) in state.position.iter_mut().enumerate() {
                *p = ((i + j) % 3 != 0).then(|| Dec::parse(&format!("{}.{j}", i * 10)).unwrap());
            }
            let before = Before::of(&state);
            for letter in b'A'..=b'Z' {
                assert_eq!(before.is_unknown(letter), state.is_unknown(letter));
                let kept = matches!(letter, b'X' | b'Y' | b'Z');
                let expected = if kept { state.axis(letter) } else { None };
                assert_eq!(before.axis(letter), expected, "{}", letter as char);
            }
            assert!(AXES[..3] == *b"XYZ");
            assert_eq!(before.compensation, state.compensation);
            assert_eq!(before.cycle, state.cycle);
        }
    }
}

#[cfg(test)]
mod buffer_tests {
    use super::testing::iso_mill;
    use super::{recycle, Checker, Config, ProfileFacts, Units, Word, WordFormat};
    use crate::rules::{Rule, Selection};
    use std::sync::Arc;

    #[test]
    fn a_whole_number_is_what_parse_reads() {
        // every digit string of 0-3 digits, long ones around i64::MAX, and strings with other
        // bytes (a sign, a point, a blank, a letter): the same value or the same refusal
        let mut texts: Vec<String> = vec![String::new()];
        for _ in 0..3 {
            let longer: Vec<String> = texts
                .iter()
                .flat_map(|t| "0123456789".chars().map(move |c| format!("{t}{c}")))
                .collect();
            texts.extend(longer);
        }
        for t in [
            "9223372036854775807",
            "9223372036854775808",
            "00009223372036854775807",
        ] {
            texts.push(t.into());
        }
        texts.push("9".repeat(40));
        for t in ["5.", ".5", " 5", "5 ", "5a", "a", "+", "-"] {
            texts.push(t.into());
        }
        for t in &texts {
            assert_eq!(
                super::whole_number(t.as_bytes()),
                t.parse::<i64>().ok(),
                "{t:?}"
            );
        }
        // a sign, which parse reads, is never in a word's number (Word splits it off)
        assert_eq!(super::whole_number(b"+5"), None);
    }

    #[test]
    fn the_format_table_finds_what_the_lists_find() {
        let mut inch_x = iso_mill().facts.formats[0].1.clone();
        inch_x.after += 1;
        let config = Config {
            facts: ProfileFacts {
                formats_inch: Some(vec![(inch_x.address, inch_x)]),
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let checker = Checker::new(Arc::new(config.clone()), Selection::all(), false);
        for letter in 0..=255u8 {
            for units in [Units::Metric, Units::Inch] {
                let table: Option<&WordFormat> = checker.format_in(letter, units);
                assert_eq!(table, config.format_in(letter, units), "{letter} {units:?}");
            }
        }
        let x = config.formats[0].0;
        assert_ne!(
            checker.format_in(x, Units::Inch),
            checker.format_in(x, Units::Metric)
        );
    }

    #[test]
    fn a_checker_without_statistics_finds_the_same() {
        // the moves' statistics are skipped, not their rules: the same findings (an arc's
        // centre, a helix), and only the blocks counted
        let program = "%\nG21 G17 G90 G94\nG00 X0 Y0 Z0\nG01 F100.\nG02 X20. Y0. R10.\n\
                       G03 X40. Y0. I10. J1. Z-1.\nG01 X900.\nM30\n%";
        let dialect = super::testing::dialect(crate::lex::Family::Iso);
        let mut runs = Vec::new();
        for keep in [true, false] {
            let mut checker = Checker::new(Arc::new(iso_mill()), Selection::all(), false);
            checker.keep_stats(keep);
            let mut tokens = Vec::new();
            for (i, line) in program.lines().enumerate() {
                checker.check_line(line.as_bytes(), i + 1, &dialect, &mut tokens);
            }
            checker.finish();
            let found: Vec<_> = checker
                .take()
                .into_iter()
                .map(|f| (f.rule, f.line, f.column, f.message))
                .collect();
            runs.push((
                found,
                checker.stats.arcs,
                checker.stats.high[0],
                checker.stats.blocks,
            ));
        }
        let rules: Vec<Rule> = runs[0].0.iter().map(|f| f.0).collect();
        assert!(rules.contains(&Rule::HelicalArc), "{rules:?}");
        assert_eq!(runs[0].0, runs[1].0);
        assert!(runs[0].1 > 0 && runs[0].2.is_some());
        assert_eq!((runs[1].1, runs[1].2), (0, None));
        assert_eq!(runs[0].3, runs[1].3);
    }

    /// The blocks whose codes are G00-G03 alone, whose units, feed mode and meanings are
    /// taken without their codes read (`motion_codes_only`): the forms it takes and those it
    /// leaves to the full reading.
    /// The moved axes' table is the walk of the places, for every set of them.
    #[test]
    fn the_moved_axes_by_their_places_are_the_walk_of_them() {
        for places in 0..512u32 {
            let walked: Vec<u8> = crate::modal::places(places)
                .map(|i| super::AXES[i])
                .collect();
            let (moved, n) = super::MOVED[places as usize];
            assert_eq!(&moved[..usize::from(n)], &walked[..], "{places:b}");
            assert!(moved[usize::from(n)..].iter().all(|&a| a == 0));
        }
    }

    #[test]
    fn motion_codes_only_takes_g00_to_g03_written_plainly() {
        let only = |line: &'static str| {
            let words: Vec<Word<'static>> = line
                .split(' ')
                .scan(1, |column, t| {
                    let w = Word::new(t.as_bytes(), *column);
                    *column += t.len() + 1;
                    Some(w)
                })
                .collect();
            super::motion_codes_only(&words)
        };
        for line in [
            "G1 X1.",
            "G00 Z5.",
            "G02 X1. Y1. I1. J0",
            "G003 X1.",
            "X1. Y2.",
            "G1 G0 X1.",
            "G17 G02 X1. Y1. I1.",
            "G018 G3 X1. Z1. K1.",
        ] {
            assert!(only(line), "{line}");
        }
        for line in [
            "G4 P1.",
            "G1 G20 X1.",
            "G1. X1.",
            "G0004 X1.",
            "G10 L2 P1",
            "G90 G1 X1.",
            "G33 Z-1. K1.",
            "G1.1 X1.",
            "G16 X1.",
            "G20 G17 X1.",
            "G0017 X1.",
        ] {
            assert!(!only(line), "{line}");
        }
    }

    /// The one walk of a block's words ([`super::letters_and_motion`]) finds the letters
    /// [`super::letters_of`] finds and says G00-G03 alone where [`super::motion_codes_only`]
    /// says it: lower case, `#` and `:` words, indexes, expressions, signed and decimal G
    /// words.
    #[test]
    fn letters_and_motion_codes_are_found_in_one_walk_as_in_two() {
        let words = |line: &'static str| -> Vec<Word<'static>> {
            line.split(' ')
                .map(|t| Word::new(t.as_bytes(), 1))
                .collect()
        };
        let lines = [
            "G1 X1. Y2.",
            "g1 x1.",
            "N10 G02 X1. Y1. I1. J0 F100.",
            "#1=5",
            "G1 X#1",
            "X[#1+2] G0",
            ":100",
            "R1=5 G1 X1.",
            "M2=3",
            "G-1 X1.",
            "G1. X1.",
            "G0004 X1.",
            "G90 G1 X1. M3",
            "G1=2 X1.",
            "X1.",
        ];
        for line in lines {
            let w = words(line);
            let (letters, motion) = super::letters_and_motion(&w);
            assert_eq!(letters, super::letters_of(&w), "{line}");
            assert_eq!(motion, super::motion_codes_only(&w), "{line}");
        }
        assert_eq!(
            super::letters_and_motion(&words("G1 X#1")),
            (super::bit(b'G') | super::bit(b'X'), true)
        );
        assert_eq!(
            super::letters_and_motion(&words("#1=5 G4")),
            (super::PARAMETER | super::INDEXED | super::bit(b'G'), false)
        );
    }

    /// A block whose codes are G00-G03 alone, on each family, mill and lathe, each G code
    /// system, in a canned cycle, in inch and per revolution, with every letter beside its
    /// code: the same findings as the rules asked of every block (`keep_verdicts(false)`),
    /// and (a debug build's assertions) no units, feed mode or meaning that the codes' full
    /// reading finds.
    #[test]
    fn a_block_of_motion_codes_alone_reads_as_its_codes_read() {
        use super::testing::{dialect, fanuc_lathe, of_family, okuma_lathe};
        use crate::lex::{Family, GCodeSystem};
        let body = "G20 G95\nG1 X1. Y2. F0.1\nG81 X1. Y1. Z-1. R1. F1.\nG1 X2. Y2.\nX3.\n\
                    G2 X1. Y1. I1. J0 K2. P2 Q1. R3.\nG03 X0 Y0 R1. L2 D1 E1. H1 S100 T1\n\
                    G80\nG21 G94\nG0 X0 Y0 Z0 A1. B1. C1. U1. V1. W1.\n\
                    G01 X1. F100.\nG1 X2. F100.\nG02 X3. Y3. I1. J1.\nG00 G01 X5.\n\
                    G18 G02 X1. Z1. I1. K0 P1 Q1.\nG019 G3 Y1. Z1. J1. K0\nG17 G1 X1. R1.\nG17\n\
                    M30\n";
        let mut configs: Vec<_> = Family::ALL.into_iter().map(of_family).collect();
        for system in [GCodeSystem::A, GCodeSystem::B, GCodeSystem::C] {
            let mut lathe = fanuc_lathe();
            lathe.modal.g_system = system;
            configs.push(lathe);
        }
        configs.push(okuma_lathe());
        for config in configs {
            let family = config.family;
            let dialect = dialect(family);
            let mut runs = Vec::new();
            for keep in [true, false] {
                let mut checker = Checker::new(Arc::new(config.clone()), Selection::all(), false);
                checker.keep_verdicts(keep);
                let mut tokens = Vec::new();
                let mut found = Vec::new();
                for (i, line) in body.lines().enumerate() {
                    checker.check_line(line.as_bytes(), i + 1, &dialect, &mut tokens);
                    found.extend(checker.take());
                }
                checker.finish();
                found.extend(checker.take());
                let found: Vec<_> = found
                    .into_iter()
                    .map(|f| (f.rule, f.line, f.column, f.message))
                    .collect();
                runs.push(found);
            }
            assert!(!runs[0].is_empty(), "{family:?}");
            assert_eq!(runs[0], runs[1], "{family:?} {:?}", config.modal.g_system);
        }
    }

    #[test]
    fn the_words_allocation_is_kept_from_block_to_block() {
        let line = b"X1 Y2".to_vec();
        let words = vec![Word::new(&line[..2], 1), Word::new(&line[3..], 4)];
        let (at, capacity) = (words.as_ptr() as usize, words.capacity());
        let kept: Vec<Word<'static>> = recycle(words);
        assert_eq!(
            (kept.as_ptr() as usize, kept.capacity(), kept.len()),
            (at, capacity, 0)
        );
    }
}
