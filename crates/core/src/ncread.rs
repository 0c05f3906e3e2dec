//! A program read as the control reads it, for comparing two programs (`formats.diff`:
//! `tapegate diff`, `convert --verify`).
//!
//! Every plain word is read through the profile's word format (the one [`WordFormat::read`]
//! the checker and the converter read by) in the units in force at its block, and its value is
//! held in one unit system, metric, exactly: an inch length times 25.4 and a surface speed in
//! ft/min times 0.3048 are exact in [`Dec`] (the mantissa times 254 or 3048), so nothing is
//! rounded before the comparison. What a word is -- a length, a feed, a surface speed, a code, a
//! number -- follows the few modes read here (units, distance, feed and spindle modes), kept
//! apart from the converter on purpose (a converter's misreading is not repeated by its
//! check), with the core's semantics: a G code is matched as [`crate::modal`] matches it, a
//! units code sets the units of the values beside it, and the roles a cycle gives its words
//! are those of [`crate::convert::cycle_roles`], the table the converter reads by. A dialect's
//! statements are read by the converter's table of their roles too ([`crate::meaning`]:
//! `Reader::statement_words`), their lengths as values, the rest as written.
//!
//! The table of what a word is compared as is in `formats/diff.py`; this module is the one
//! implementation of it.

use std::sync::Arc;

use crate::convert::WordSpan;
use crate::decimal::Dec;
use crate::dialect::{DataBlock, DataInput, Opening, ProgramSplit, ReadingEnd};
use crate::lex::Family;
use crate::modal::{BlockValues, ModalMachine, ModalSettings, ModalState, Units};
use crate::statement::Kind as StatementKind;
use crate::word::{reads_whole, units_of, Numbers, ReadsBlocks, Role, Word};
use crate::wordformat::{implicit_code, WordFormat};

/// What a word is compared as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Code,
    Units,
    Length,
    Feed,
    Speed,
    Number,
    Text,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Code => "code",
            Kind::Units => "units",
            Kind::Length => "length",
            Kind::Feed => "feed",
            Kind::Speed => "speed",
            Kind::Number => "number",
            Kind::Text => "text",
        }
    }
}

/// The exact factor from a word's unit as written to the metric unit of its kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Factor {
    One,
    /// 25.4 mm per inch.
    Inch,
    /// 0.3048 m per foot (a surface speed in ft/min).
    Foot,
}

impl Factor {
    /// `value × factor`, exactly; None when the product needs more digits than a [`Dec`]
    /// holds (38).
    pub fn times(self, value: Dec) -> Option<Dec> {
        let (multiplier, scale) = match self {
            Factor::One => return Some(value),
            Factor::Inch => (254, 1),
            Factor::Foot => (3048, 4),
        };
        Some(Dec {
            mantissa: value.mantissa.checked_mul(multiplier)?,
            scale: value.scale.checked_add(scale).filter(|&s| s <= 38)?,
        })
    }
}

/// The format a word was read by (for a length a cycle writes as a count, `G76 P1200`, its
/// least-increment reading), with the program's reading of a number without a point (explicit
/// program, least increments): two words of the same form and value are written alike.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Form {
    pub format: WordFormat,
    pub explicit: bool,
    pub increments: bool,
}

/// One word as the control reads it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ReadWord {
    /// Address (upper case) and index: `X`, `X1`, `#1`; `%`, `/` and `?` for the program
    /// start, the skip and a block that could not be read.
    pub key: Vec<u8>,
    /// As written, in upper case.
    pub token: Vec<u8>,
    /// Exactly as written (for a word read by a format; empty otherwise).
    pub written: Vec<u8>,
    pub kind: Kind,
    /// In the metric unit of its kind; None for a text word.
    pub value: Option<Dec>,
    /// The value as written (`value` is this times `factor`).
    pub raw: Option<Dec>,
    pub factor: Factor,
    /// One step of the word's format, in the unit of `value`; `raw_step` as written.
    pub step: Dec,
    pub raw_step: Dec,
    /// An axis word in G91.
    pub incremental: bool,
    /// The axis whose position an increment moves where it is not its own letter's (a Fanuc
    /// or Haas lathe's U moves X, W moves Z): the comparison carries it on that axis.
    pub moves: Option<u8>,
    /// A parameter assignment or an expression (6.4.7).
    pub parameter: bool,
    /// A dwell's time given by a parameter or an expression in milliseconds (a FANUC or Haas
    /// G04 P, a drilling cycle's P): its value is not read, but it is not the same time as
    /// the same text in seconds (a LinuxCNC P).
    pub milliseconds: bool,
    /// A P, Q or R of no stated role: the factor were it a length.
    pub as_length: Option<Factor>,
    /// Why its number could not be read (the word is then compared as written).
    pub error: Option<String>,
    /// A feed in G95 (G99 on a Fanuc or Haas lathe).
    pub per_revolution: bool,
    pub form: Option<Form>,
    /// What the word is of a dialect's statement ([`Reader::statement_words`]).
    pub statement: InStatement,
}

/// What a word read from a dialect's statement is ([`Reader::statement_words`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum InStatement {
    /// No statement's: a word of the block.
    #[default]
    No,
    /// A length of a statement by the converter's roles (`TRANS X10`, `,R1.5`, `BHC ... I50`:
    /// [`crate::meaning`]): compared by value, and byte for byte where both programs read it
    /// in the same units (the converter leaves a statement alone there).
    Number,
    /// A statement read as its text (the rest of a statement read by roles too, its angles
    /// and counts as written). `values`: it holds a number, in the units of `factor` (those
    /// in force): between two programs read in other units its number is not compared
    /// (`ncdiff::Comparer::unread`); `arguments`: a LinuxCNC call, whose arguments the
    /// converter converts by the parameter analysis, which the reading does not make.
    Text { values: bool, arguments: bool },
}

impl ReadWord {
    /// A word compared as its text.
    pub fn text(key: &[u8], token: &[u8]) -> ReadWord {
        ReadWord {
            key: key.to_vec(),
            token: token.to_ascii_uppercase(),
            written: Vec::new(),
            kind: Kind::Text,
            value: None,
            raw: None,
            factor: Factor::One,
            step: Dec::from_int(1),
            raw_step: Dec::from_int(1),
            incremental: false,
            moves: None,
            parameter: false,
            milliseconds: false,
            as_length: None,
            error: None,
            per_revolution: false,
            form: None,
            statement: InStatement::No,
        }
    }
}

/// What a block does to the reading of the blocks after it.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct BlockFlags {
    /// G04: X U P F are a time.
    pub dwell: bool,
    /// G92 S (G50 S on a Fanuc or Haas lathe): S is a speed clamp.
    pub clamp: bool,
    /// A units code in the block.
    pub units_code: bool,
    /// M02 or M30: the modes went back to the reset state of clause 14 after it.
    pub ended: bool,
    /// G92/G50, G28, G30, G53, M02/M30, the family's return (M99, a SINUMERIK's M17:
    /// `dialect::return_code`): positions start again after it.
    pub resets: bool,
    /// A return from a subprogram by the family's code (`dialect::return_code`): M99 (Fanuc,
    /// Haas), M17 (SINUMERIK); none on an Okuma or a HEIDENHAIN, whose M99 is no return.
    pub returns: bool,
}

/// What the reading needs from a profile.
#[derive(Debug, Clone)]
pub struct ReadSettings {
    pub formats: Vec<(u8, WordFormat)>,
    pub formats_inch: Option<Vec<(u8, WordFormat)>>,
    pub explicit: bool,
    /// The letters read as whole numbers by a control that reads a number without a point as
    /// least increments; None for a control that reads every such number as whole.
    pub increments: Option<Vec<u8>>,
    /// P, Q, R: whether `checks.pqr` says a length, and whether it states no role.
    pub pqr_length: [bool; 3],
    pub pqr_unstated: [bool; 3],
    /// The G and M codes the profile lists (None: ISO 6983-1): an M code gives its block's
    /// P Q R no known role where no G code that reads them does, read as written
    /// ([`crate::convert::m_code_roles`], [`crate::convert::pqr_code`]).
    pub m_listed: Option<crate::convert::CodeList>,
    pub family: Family,
    /// `control_type` lathe (the cycle tables).
    pub lathe: bool,
    /// A Fanuc or Haas lathe: G98/G99 are feed per minute and per revolution, G50 S clamps.
    pub fanuc_lathe: bool,
    /// The units codes, as the core's modal machine reads them, and as the profile writes
    /// them (`G20`, `G21`).
    pub modal: ModalSettings,
    pub inch_code: String,
    pub metric_code: String,
    /// The program number address (`O`): where a file holds several programs, one after the
    /// end of another begins with it (`dialect::ProgramSplit`).
    pub program_number: Option<u8>,
}

impl ReadSettings {
    /// How the profile's numbers are read (formats, DS, least increments).
    pub fn numbers(&self) -> Numbers<'_> {
        Numbers {
            formats: &self.formats,
            formats_inch: self.formats_inch.as_deref(),
            explicit: self.explicit,
            increments: self.increments.as_deref(),
        }
    }

    fn reads_increments(&self, letter: u8) -> bool {
        self.numbers().reads_increments(letter)
    }
}

/// The G codes the core's modal machine matches before the distance, feed, spindle and units
/// modes (`modal.rs` `g`): never one of those modes, whatever the profile says.
const CORE_FIRST: [i64; 34] = [
    0, 1, 2, 3, 6, 33, 34, 35, 17, 18, 19, 40, 41, 42, 43, 44, 49, 53, 54, 55, 56, 57, 58, 59, 80,
    81, 82, 83, 84, 85, 86, 87, 88, 89,
];
const AXES: &[u8] = b"XYZUVWABC";

fn one_step(fmt: &WordFormat) -> Dec {
    if fmt.decimal {
        Dec {
            mantissa: 1,
            scale: fmt.after,
        }
    } else {
        Dec::from_int(1)
    }
}

/// One program's reader: the modes its words are read in, from the profile's reset state.
pub struct Reader {
    pub settings: ReadSettings,
    /// The format of every letter in metric and in inch units, resolved once (a
    /// profile's own, else the fallback): read for every word.
    formats: [Vec<WordFormat>; 2],
    /// With the motion compared: the core's modal state machine, run beside the reading.
    pub motion: Option<Motion>,
    pub units: Units,
    pub feed_units: Units,
    pub incremental: bool,
    pub feed_mode: i64,
    pub css: bool,
    /// The motion mode in force (G00-G03, G06, G33-G35), for what an Okuma lathe's L is
    /// ([`crate::word::radius_letter_role`]).
    pub motion_mode: Option<i64>,
    /// The plane (17-19) and, on a FANUC or Haas mill, whether G16 is in force: the plane's
    /// axis words are then a radius and an angle ([`crate::meaning::polar_axes`]).
    plane: i64,
    polar: bool,
    /// A lathe's polar coordinate interpolation (G12.1 ... G13.1): C is a length
    /// ([`crate::meaning::polar_interpolation`]).
    polar_interpolation: bool,
    /// A lathe's U W moving X Z by an increment (G00-G03 or a thread of system A, not a
    /// turning or threading cycle): by the converter's rule (`convert::UwMoves`), so the two
    /// read a U or W alike.
    uw_moves: crate::convert::UwMoves,
    /// A drilling or boring cycle in force (G73, G82-G89), whose P is the dwell at the bottom.
    dwell_cycle: bool,
    /// The canned drilling cycle in force, whose words a block that names no cycle repeats
    /// with its roles, or a lathe's thread in force (`convert::Repeat`, as the converter reads
    /// them).
    cycle_code: crate::convert::Repeat,
    /// Where the file's next program begins: each program is read from its own start state.
    split: ProgramSplit,
    /// Where a LinuxCNC file stops being read (`dialect::ReadingEnd`).
    reading_end: ReadingEnd,
    /// FANUC's G10 L50 / G10 L3 data input mode (`dialect::DataInput`): its blocks are
    /// compared as text (parameter numbers and values, tool life data: no lengths).
    data_input: DataInput,
    /// The units LinuxCNC subroutine bodies are read in, by label, where not those in force
    /// where they stand (`convert --verify`: those the converter read each in, its calls',
    /// [`crate::sub_units`]); and while one is read, the units to go on in after its
    /// `endsub` (the body is skipped where it stands).
    pub bodies: Vec<(Vec<u8>, Units)>,
    body_caller: Option<(Units, Units)>,
}

impl Reader {
    pub fn new(settings: ReadSettings) -> Reader {
        let units = settings.modal.default_units;
        let numbers = settings.numbers();
        let table = |u| {
            (0..=255u8)
                .map(|l| numbers.format_or_fallback(l, u))
                .collect()
        };
        let formats = [table(Units::Metric), table(Units::Inch)];
        let family = settings.family;
        let uw_moves =
            crate::convert::UwMoves::new(settings.lathe, family, settings.modal.g_system);
        let mut reader = Reader {
            settings,
            formats,
            motion: None,
            units,
            feed_units: units,
            incremental: false,
            feed_mode: 94,
            css: false,
            motion_mode: None,
            plane: 17,
            polar: false,
            polar_interpolation: false,
            uw_moves,
            dwell_cycle: false,
            cycle_code: Default::default(),
            split: ProgramSplit::default(),
            reading_end: ReadingEnd::new(family),
            data_input: DataInput::default(),
            bodies: Vec::new(),
            body_caller: None,
        };
        reader.reset_modes();
        reader
    }

    /// The reset state of clause 14 as the core makes it: its modes, then the profile's reset
    /// codes in order (the units are the caller's to keep or not).
    fn reset_modes(&mut self) {
        self.incremental = false;
        self.uw_moves.reset();
        self.dwell_cycle = false;
        self.cycle_code = Default::default();
        self.feed_mode = 94;
        self.css = false;
        self.motion_mode = None;
        self.plane = 17;
        self.polar = false;
        self.polar_interpolation = false;
        for i in 0..self.settings.modal.reset.len() {
            self.mode(self.settings.modal.reset[i]);
        }
    }

    /// What one G code does to the modes read here, as the core's modal machine does it.
    fn mode(&mut self, code: i64) {
        if self.settings.modal.own_motion(code) {
            // a lathe's threading and single cycles (system A G90/G92/G94: no absolute mode,
            // no feed per minute), as `ModalMachine` reads them
            self.motion_mode = Some(code);
            return;
        }
        if matches!(code, 0..=3 | 6 | 33..=35) {
            self.motion_mode = Some(code);
        }
        if (17..=19).contains(&code) {
            self.plane = code;
        }
        let lathe = self.settings.lathe;
        if let Some(on) = crate::meaning::polar_code(self.settings.family, lathe, code) {
            self.polar = on;
        }
        if CORE_FIRST.contains(&code) {
            return;
        }
        match code {
            90 | 91 => self.incremental = code == 91,
            // G code system B and C's G90/G91 (`ModalSettings::read_g`)
            crate::meaning::ABSOLUTE | crate::meaning::INCREMENTAL => {
                self.incremental = code == crate::meaning::INCREMENTAL
            }
            93..=95 => self.feed_mode = code,
            98 | 99 if self.settings.fanuc_lathe => {
                self.feed_mode = if code == 98 { 94 } else { 95 }
            }
            96 | 97 => self.css = code == 96,
            _ => {
                if let Some((units, feed_units)) = self.settings.modal.units_code(code) {
                    self.units = units;
                    self.feed_units = feed_units;
                }
            }
        }
    }

    /// The format of `letter` (upper case) in `units`.
    fn format(&self, letter: u8, units: Units) -> &WordFormat {
        let table = &self.formats[usize::from(units == Units::Inch)];
        &table[usize::from(letter)]
    }

    fn is_units_code(&self, code: i64) -> bool {
        self.settings.modal.units_code(code).is_some()
    }

    /// The number of a G or M word as the core reads it: a plain number without an index,
    /// through the profile's format, and whole (`G01` and `G1.0` are G1, `G91.1` is no G91);
    /// None for anything else, or a number the format cannot read.
    fn code(&self, w: &Word<'_>) -> Option<i64> {
        if !w.index.is_empty() || w.number.is_empty() {
            return None;
        }
        let fmt = self.format(w.letter, self.units);
        let value = self.settings.numbers().read(fmt, w).ok()?;
        value.is_whole().then(|| value.trunc())
    }

    /// The words of one block (given by its word tokens), one per token in written order, and
    /// what the block does; the modes are those after the block.
    pub fn read(&mut self, tokens: &[&[u8]], out: &mut Vec<ReadWord>) -> BlockFlags {
        out.clear();
        let words: Vec<Word<'_>> = tokens.iter().map(|t| Word::new(t, 0)).collect();
        let numbers: Vec<Option<i64>> = words
            .iter()
            .map(|w| {
                if matches!(w.letter, b'G' | b'M') {
                    self.code(w)
                } else {
                    None
                }
            })
            .collect();
        let mut gs = Vec::new();
        let mut ms = Vec::new();
        for (w, n) in words.iter().zip(&numbers) {
            if let Some(n) = *n {
                if w.letter == b'G' {
                    // a FANUC lathe's code of G code system B or C by its system A number
                    gs.push(self.settings.modal.read_g(n));
                } else {
                    ms.push(n);
                }
            }
        }
        // the modes a block's G codes set are those its own words are read in (a units code
        // sets the units of the values beside it, as the core's modal machine has it)
        let incremental_before = self.incremental;
        for &g in &gs {
            self.mode(g);
            match g {
                _ if crate::convert::dwell_cycle(self.settings.lathe, g) => self.dwell_cycle = true,
                _ if crate::convert::ends_canned_cycle(self.settings.lathe, g) => {
                    self.dwell_cycle = false
                }
                _ => {}
            }
            // (G32/G34 threading moves by U W as G01 does, the checker's
            // `ModalMachine::g_other`: review 59c F7)
            self.uw_moves.code(g);
        }
        let spans: Vec<WordSpan<'_>> = tokens
            .iter()
            .map(|t| WordSpan {
                token: t,
                start: 0,
                end: 0,
                plain: None,
                digits: Default::default(),
            })
            .collect();
        let system = self.settings.modal.g_system;
        let (family, lathe) = (self.settings.family, self.settings.lathe);
        let haas = Some(self.settings.modal.haas);
        self.cycle_code = self.cycle_code.after(family, lathe, &gs, &ms);
        // a block repeating the cycle in force: its words by the cycle's roles (a lathe's
        // thread only in a plain pass, `modal::thread_pass`)
        let unread = words
            .iter()
            .zip(&numbers)
            .any(|(w, n)| w.letter == b'G' && n.is_none());
        let repeated = self.cycle_code.code().filter(|&c| {
            !gs.contains(&c)
                && (!crate::modal::modal_thread(c) || crate::modal::thread_pass(&gs, unread))
        });
        let mut with_cycle = gs.clone();
        with_cycle.extend(repeated);
        let meanings = crate::convert::cycle_meanings_in(
            system,
            family,
            haas,
            lathe,
            &with_cycle,
            &ms,
            &spans,
        );
        let mut roles = meanings.roles;
        let cycle_roles = roles;
        let radius = self.settings.modal.arc_radius;
        if let Some(role) = crate::word::radius_letter_role(radius, self.motion_mode, &gs) {
            roles[usize::from(radius - b'A')] = Some(role);
        }
        let words_of = tokens
            .iter()
            .filter(|t| !t.is_empty())
            .map(|t| (t[0], &t[1..]));
        let (family, lathe) = (self.settings.family, self.settings.lathe);
        if let Some(on) = crate::meaning::polar_interpolation(family, lathe, words_of) {
            self.polar_interpolation = on;
        }
        if self.polar_interpolation && roles[usize::from(b'C' - b'A')].is_none() {
            roles[usize::from(b'C' - b'A')] = Some(Role::Length);
        }
        if self.polar {
            // under G16 the plane's first axis word is a radius, its second an angle
            let (radius, angle) = crate::meaning::polar_axes(self.plane);
            roles[usize::from(radius - b'A')] = Some(Role::Length);
            roles[usize::from(angle - b'A')] = Some(Role::Other);
        }
        if let Some(list) = self.settings.m_listed.as_ref().filter(|_| !ms.is_empty()) {
            let pqr_code = with_cycle
                .iter()
                .any(|&g| crate::convert::pqr_code(family, lathe, g));
            crate::convert::m_code_roles(list, &ms, pqr_code, &mut roles);
        }
        if self.settings.family != Family::Iso && gs.iter().any(|&g| g == 65 || g == 66) {
            // a macro call's arguments (all but G N O P L) are numbers its macro reads, not
            // lengths or feeds: the converter refuses them under a change of units, or with
            // --allow-unconverted leaves them as written
            for letter in b'A'..=b'Z' {
                if !b"GNOPL".contains(&letter) {
                    roles[usize::from(letter - b'A')] = Some(Role::Other);
                }
            }
        }
        // an S that limits the spindle's speed, not the speed itself: the one rule of the
        // check and the restart (ModalSettings::s_limit): G50 S on a Fanuc, Haas or Okuma
        // lathe, G92 S on a mill whose G92 clamps, a SINUMERIK's G25/G26 S. (The reader's
        // settings leave the LAP out of its modal rules, machine::read_settings, so an Okuma
        // lathe's G50 is asked here.)
        let okuma_lathe = self.settings.lathe && self.settings.family == Family::Okuma;
        let clamp = okuma_lathe && gs.contains(&50)
            || !okuma_lathe && self.settings.modal.s_limit_with(|g| gs.contains(&g)).1;
        let flags = BlockFlags {
            dwell: gs.contains(&4),
            clamp,
            units_code: gs.iter().any(|&g| self.is_units_code(g)),
            ended: ms.contains(&2) || ms.contains(&30),
            resets: false,
            returns: crate::dialect::return_code(self.settings.family)
                .is_some_and(|code| ms.contains(&code)),
        };
        // the words the cycle's table makes a count or an angle of its own (`G81 K3`, three
        // repeats), which the control reads whole, as the checker (`Checker::selector`) and
        // the converter (`table_angle`) read them, where no later rule of the block gave the
        // letter another role (a macro call's arguments are its macro's)
        let macro_call =
            self.settings.family != Family::Iso && gs.iter().any(|&g| g == 65 || g == 66);
        // (but one that measures, a time, an angle or a ratio, is read so and compared within
        // the tolerance, as G04's P is: `Meanings::cycle_measure`; review 56a F5, issue 32)
        let read_whole = (0..26usize)
            .filter(|&i| {
                !macro_call && cycle_roles[i] == roles[i] && meanings.cycle_count(b'A' + i as u8)
            })
            .fold(0u32, |bits, i| bits | 1 << i);
        let measures = (0..26usize)
            .filter(|&i| read_whole & 1 << i != 0 && meanings.cycle_measure(b'A' + i as u8))
            .fold(0u32, |bits, i| bits | 1 << i);
        // (a macro call's P, the program, and L, the count, are compared exactly, as M98's
        // are, whatever cycle is in force: under a modal G82 `G65 P9000`'s P was read as its
        // dwell, review 57a F1)
        let called = if macro_call {
            1 << (b'P' - b'A') | 1 << (b'L' - b'A')
        } else {
            0
        };
        let counts = read_whole & !measures | called;
        // a thread's start angle (`Meanings::start_angle`: a lathe's G32/G92 Q, Haas G76 Q) is
        // in 0.001 deg without a point: compared in degrees, as a dwell's milliseconds are in
        // seconds
        let q = 1 << (b'Q' - b'A');
        let thousandths = if meanings.start_angle {
            measures & q
        } else {
            0
        };
        let absolute = gs.contains(&53);
        for (w, n) in words.iter().zip(&numbers) {
            if w.letter == b'G' {
                let read = n.map(|c| self.settings.modal.read_g(c));
                if let Some(code) = read.filter(|&c| self.is_units_code(c)) {
                    // the units code: its meaning is in every value after it
                    let mut word = ReadWord::text(b"G", w.token);
                    word.kind = Kind::Units;
                    word.value = Some(Dec::from_int(code as i128));
                    word.raw = word.value;
                    out.push(word);
                    continue;
                }
                // G code system B's and C's G90 where the moves are absolute already changes
                // nothing: not compared (system A has no such code, `Converter::g_in_target`)
                if read == Some(crate::meaning::ABSOLUTE) && !incremental_before {
                    continue;
                }
            }
            out.push(self.word(w, &roles, (counts, measures, thousandths), flags, absolute));
        }
        let resets = flags.ended
            || flags.clamp
            || gs.iter().any(|g| matches!(g, 28 | 30 | 53))
            || flags.returns;
        if flags.ended {
            // the reset state of clause 14, the units kept where the control keeps them
            let units = (self.units, self.feed_units);
            let kept = self.settings.modal.units_kept_at_end;
            if !kept {
                self.units = self.settings.modal.default_units;
                self.feed_units = self.units;
            }
            self.reset_modes();
            if kept {
                (self.units, self.feed_units) = units;
            }
        }
        BlockFlags { resets, ..flags }
    }

    /// Run the core's modal state machine beside the reading (`config`: the checker's
    /// reading of the same profile), so that every block carries the state after it.
    pub fn with_motion(mut self, config: impl ReadsBlocks + Send + Sync + 'static) -> Reader {
        let mut machine = ModalMachine::new(config.modal_settings().clone());
        // each axis's units are followed here (`Factor`), exactly: the numbers stay as read
        machine.units_convert_position = false;
        let config: Box<dyn ReadsBlocks + Send + Sync> = Box::new(config);
        let reset = Arc::new(machine.state);
        self.motion = Some(Motion {
            config,
            machine,
            values: BlockValues::default(),
            reset,
            factors: [None; 11],
        });
        self
    }

    /// The units code that selects the units of lengths and of the feed read here.
    pub fn units_code_now(&self) -> Vec<u8> {
        let s = &self.settings;
        if s.modal.sinumerik_units && self.feed_units != s.modal.default_units {
            return if self.feed_units == Units::Inch {
                b"G700".to_vec()
            } else {
                b"G710".to_vec()
            };
        }
        let code = if self.units == Units::Inch {
            &s.inch_code
        } else {
            &s.metric_code
        };
        if code.is_empty() {
            return Vec::new(); // no G code selects the units: the machine's parameter does
        }
        // written as the profile's format reads it: with no decimal sign and a G format with
        // decimals (G031), G20 counts tenths (G200), unless the control reads G whole (a Fanuc)
        let fmt = self.format(b'G', self.units);
        code[1..]
            .parse::<i128>()
            .ok()
            .and_then(|n| {
                let whole = reads_whole(s.increments.as_deref(), b'G');
                implicit_code(b'G', n, fmt, s.explicit || whole)
            })
            .unwrap_or_else(|| code.as_bytes().to_vec())
    }

    /// A program of the file after the end of another (`dialect::ProgramSplit`) is read from
    /// its own start state, as the checker and the converter read it: the reset state in the
    /// control's start units, no position known.
    fn start_program(&mut self) {
        self.units = self.settings.modal.default_units;
        self.feed_units = self.units;
        self.reset_modes();
        if let Some(m) = self.motion.as_mut() {
            m.machine.reset();
            m.machine.forget();
            m.factors = [None; 11];
        }
    }

    /// One block as read (its word tokens, what the block opens with, and from the tokenizer
    /// its `%`, its skip and its comments), or None for a block with nothing to compare; Err:
    /// `skip_within` is a block skip in the middle of the block (Fanuc, Haas): its text and
    /// the index of the first token after it. It is compared as a word of its own after the
    /// block's words, keyed by the address it skips from (`/Y` in `X1 /Y2`), so that a
    /// conversion that keeps its place is the same and a slash moved or lost is a difference.
    /// the modes read here are not the core's modal state machine's (with the motion
    /// compared).
    #[allow(clippy::too_many_arguments)]
    pub fn block(
        &mut self,
        line: usize,
        tokens: &[&[u8]],
        opening: &Opening<'_>,
        percent: bool,
        skip: &[u8],
        skip_within: Option<(&[u8], usize)>,
        comments: Vec<Vec<u8>>,
        statements: &[(usize, StatementKind, &[u8])],
    ) -> Result<Option<DiffBlock>, String> {
        self.reading_end.read(
            tokens.iter().copied(),
            opening.statement.map(|(_, kind, text)| (kind, text)),
            !skip.is_empty(),
            line,
        );
        // (a `%` line's opening is its name: a SINUMERIK archive's next file)
        let (family, number) = (self.settings.family, self.settings.program_number);
        if self.split.begins(family, number, opening) {
            self.start_program();
            self.data_input = DataInput::default();
        }
        let split = tokens
            .iter()
            .filter(|t| !t.is_empty())
            .map(|t| (t[0], &t[1..]));
        // a data block, and the `G10 L50` block that opens the mode (its words past G10 and
        // L are data too: `G10 L50 N1420 R15000`), compared as written
        let data = !percent
            && match self.data_input.block(family, line, split) {
                DataBlock::Data { .. } => true,
                DataBlock::Program => self.data_input.open().is_some_and(|o| o.0 == line),
                DataBlock::Stray { .. } | DataBlock::Lacked { .. } => false,
            };
        if data {
            let words = tokens
                .iter()
                .filter(|t| !t.is_empty())
                .map(|t| ReadWord::text(&t[..1].to_ascii_uppercase(), t))
                .collect();
            return Ok(Some(DiffBlock {
                line,
                number: None,
                words,
                comments,
                resets: false,
                state: None,
            }));
        }
        let mut words = Vec::with_capacity(tokens.len() + 2);
        if !skip.is_empty() {
            words.push(ReadWord::text(b"/", skip));
        }
        if percent {
            words.push(ReadWord::text(b"%", b"%"));
        }
        let at = words.len();
        if family == Family::LinuxCnc && !self.bodies.is_empty() {
            self.body(opening);
        }
        if matches!(family, Family::Sinumerik | Family::Okuma) && !self.bodies.is_empty() {
            self.named_body(opening);
        }
        let mut read = Vec::with_capacity(tokens.len());
        let flags = self.read(tokens, &mut read);
        // a SINUMERIK's RET, a statement of its own
        let ret = family == Family::Sinumerik
            && opening.statement.is_some_and(|(_, kind, text)| {
                kind == crate::statement::Kind::Command && text.eq_ignore_ascii_case(b"RET")
            });
        self.split.ended(flags.ended || flags.returns || ret);
        words.append(&mut read);
        if let Some((text, first)) = skip_within {
            let mut key = b"/".to_vec();
            if let Some(w) = words.get(at + first) {
                key.extend_from_slice(&w.key);
            }
            words.push(ReadWord::text(&key, text));
        }
        // an Okuma lathe's home position return (G20 HP=4: HP a count), as the converter
        // reads it
        let home = family == Family::Okuma
            && self.settings.lathe
            && tokens.iter().any(|t| {
                t.first().is_some_and(|l| l.eq_ignore_ascii_case(&b'G'))
                    && matches!(self.code(&Word::new(t, 0)), Some(20 | 21 | 24 | 25))
            });
        for &(_, kind, text) in statements {
            self.statement_words(kind, text, home, &mut words);
        }
        let number = words[at..]
            .iter()
            .find(|w| w.key == b"N")
            .and_then(|w| w.value);
        let state = if self.motion.is_some() {
            Some(Box::new(self.machine_state(tokens, &words, flags)?))
        } else {
            None
        };
        if words.is_empty() && comments.is_empty() {
            return Ok(None);
        }
        Ok(Some(DiffBlock {
            line,
            number,
            words,
            comments,
            resets: flags.resets,
            state,
        }))
    }

    /// The words of one of the block's statements, read by the roles the converter converts
    /// them by (the one table, [`crate::meaning`]): a SINUMERIK frame or radius (`TRANS X10`,
    /// `CR=5`), a FANUC or Haas corner (`,C2.`, `,R1.5`), an Okuma OSP hole pattern (`BHC X100
    /// Y50 I50 J0 K6`): each length a word of its own ([`InStatement::Number`], keyed by the
    /// address the converter rounds it by and the statement's name), the rest of the statement
    /// -- its name, angles, counts, blanks -- one text word. Any other statement is one text
    /// word, holding numbers or not ([`InStatement::Text`]), in the units in force.
    fn statement_words(
        &self,
        kind: StatementKind,
        text: &[u8],
        home: bool,
        out: &mut Vec<ReadWord>,
    ) {
        let family = self.settings.family;
        let numbers = match family {
            Family::Sinumerik => crate::meaning::sinumerik_statement(text),
            Family::MacroB => crate::meaning::corner_length(text).map(|n| vec![n]),
            Family::Okuma => crate::meaning::okuma_pattern(text).and_then(Result::ok),
            _ => None,
        };
        let inch = self.units == Units::Inch;
        let factor = if inch { Factor::Inch } else { Factor::One };
        let name_end = text
            .iter()
            .position(|c| !c.is_ascii_alphabetic() && c != &b',')
            .unwrap_or(text.len());
        let name = text[..name_end].to_ascii_uppercase();
        let mut key = b"{".to_vec();
        key.extend_from_slice(&name);
        let Some(numbers) = numbers else {
            // a number the converter converts nothing of, or refuses (but under
            // --allow-unconverted): as it tells them apart (`Converter::statements`); an Okuma
            // lathe's home position return (G20 HP=4) holds a count
            let refused = match family {
                Family::Sinumerik => crate::meaning::sinumerik_shift(text),
                Family::MacroB => {
                    matches!(text, [b',', c, ..] if matches!(c.to_ascii_uppercase(), b'C' | b'R'))
                }
                Family::Okuma => crate::meaning::okuma_pattern(text).is_some(),
                _ => false,
            };
            let values = !(home && crate::convert::okuma_home_number(text))
                && (refused || crate::convert::holds_values(text, family == Family::Sinumerik));
            let mut word = ReadWord::text(&key, b"");
            word.token = text.to_vec();
            word.written = text.to_vec();
            word.factor = if values { factor } else { Factor::One };
            word.statement = InStatement::Text {
                values,
                arguments: family == Family::LinuxCnc && kind == StatementKind::Call,
            };
            out.push(word);
            return;
        };
        let mut rest = Vec::with_capacity(text.len());
        let mut pos = 0;
        let one = numbers.len() == 1 && numbers[0].end == text.len();
        for n in numbers.iter().filter(|n| n.length) {
            rest.extend_from_slice(&text[pos..n.start]);
            rest.push(b'#');
            pos = n.end;
            let number = &text[n.start..n.end];
            // the number as the converter reads it (`Converter::statement_lengths`): with or
            // without its point, the value it writes
            let raw = if family == Family::MacroB {
                // a FANUC or Haas corner is read as the profile reads an X word (the
                // converter's `Converter::source_number`): without its point, in least
                // increments where the profile reads X so (`,C5` is 0.0005 in at X's 0.0001)
                let (negative, digits) = match number.first() {
                    Some(b'-') => (true, &number[1..]),
                    Some(b'+') => (false, &number[1..]),
                    _ => (false, number),
                };
                let explicit = self.settings.explicit
                    || reads_whole(self.settings.increments.as_deref(), b'X');
                self.format(b'X', self.units)
                    .read(
                        negative,
                        digits,
                        explicit,
                        self.settings.reads_increments(b'X'),
                    )
                    .ok()
            } else {
                std::str::from_utf8(number).ok().and_then(Dec::parse)
            };
            let fmt = self.format(n.address, self.units);
            let raw_step = if fmt.decimal {
                one_step(fmt)
            } else {
                // a whole number's format (an R of a control that has none): X's
                one_step(self.format(b'X', self.units))
            };
            let mut k = vec![n.address, b'='];
            k.extend_from_slice(&name);
            // the word as the messages show it: the statement, or its name and the word
            let mut token = Vec::new();
            if one {
                token.extend_from_slice(text);
            } else {
                token.extend_from_slice(&name);
                token.push(b' ');
                token.extend_from_slice(
                    text[..n.start]
                        .rsplit(|c| *c == b' ')
                        .next()
                        .unwrap_or_default(),
                );
                token.extend_from_slice(number);
            }
            let mut word = ReadWord::text(&k, b"");
            word.token = token.clone();
            word.written = token;
            word.statement = InStatement::Number;
            let (Some(raw), Some(value), Some(step)) = (
                raw,
                raw.and_then(|r| factor.times(r)),
                factor.times(raw_step),
            ) else {
                word.error = Some(format!(
                    "{} cannot be read as a number in metric units",
                    String::from_utf8_lossy(number)
                ));
                out.push(word);
                continue;
            };
            word.kind = Kind::Length;
            word.value = Some(value);
            word.raw = Some(raw);
            word.factor = factor;
            word.step = step;
            word.raw_step = raw_step;
            out.push(word);
        }
        rest.extend_from_slice(&text[pos..]);
        let mut word = ReadWord::text(&key, b"");
        word.token = rest.clone();
        word.written = rest;
        word.statement = InStatement::Text {
            values: false,
            arguments: false,
        };
        out.push(word);
    }

    /// A LinuxCNC `o<name> sub` of [`Reader::bodies`] is read in its units from here, and its
    /// `endsub` goes back to the units before it.
    fn body(&mut self, opening: &Opening<'_>) {
        let Some((_, crate::statement::Kind::Definition, text)) = opening.statement else {
            return;
        };
        let units = match crate::statement::linuxcnc_definition(text) {
            Some(true) => {
                let label = crate::statement::o_label(text);
                let Some(&(_, units)) = self.bodies.iter().find(|(l, _)| *l == label) else {
                    return;
                };
                self.body_caller = Some((self.units, self.feed_units));
                (units, units)
            }
            Some(false) => match self.body_caller.take() {
                Some(caller) => caller,
                None => return,
            },
            None => return,
        };
        (self.units, self.feed_units) = units;
        if let Some(motion) = &mut self.motion {
            (motion.machine.state.units, motion.machine.state.feed_units) = units;
        }
    }

    /// A SINUMERIK archive's subprogram or an Okuma OSP subprogram of [`Reader::bodies`],
    /// by its name: read from its head in those units, its calls' (`convert::named`). A
    /// SINUMERIK's G70/G71 leave the feed in its basic system, an OSP's unit system is one.
    fn named_body(&mut self, opening: &Opening<'_>) {
        let family = self.settings.family;
        let Some(name) = crate::convert::program_name(family, opening) else {
            return;
        };
        let Some(&(_, units)) = self.bodies.iter().find(|(l, _)| *l == name) else {
            return;
        };
        self.units = units;
        if family == Family::Okuma {
            self.feed_units = units;
        }
        if let Some(motion) = &mut self.motion {
            motion.machine.state.units = units;
            motion.machine.state.feed_units = self.feed_units;
        }
    }

    /// Asked before line `line` is read: whether the control never reads it
    /// (`dialect::ReadingEnd`: after a LinuxCNC program's end). Such a line is compared as
    /// its text ([`Reader::bad_block`]) where it holds more than blanks and comments.
    pub fn not_read(&mut self, line: usize, text: &[u8]) -> bool {
        self.reading_end.skips(line, text)
    }

    /// A block the profile cannot read: compared as its text (`shown`, upper case).
    pub fn bad_block(line: usize, shown: &[u8]) -> DiffBlock {
        let mut word = ReadWord::text(b"?", b"");
        word.token = shown.to_vec();
        DiffBlock {
            line,
            number: None,
            words: vec![word],
            comments: Vec::new(),
            resets: false,
            state: None,
        }
    }

    fn machine_state(
        &mut self,
        tokens: &[&[u8]],
        words: &[ReadWord],
        flags: BlockFlags,
    ) -> Result<State, String> {
        let units_code = self.units_code_now();
        let mine = (
            self.units,
            self.feed_units,
            self.incremental,
            self.feed_mode,
            if self.css { 96 } else { 97 },
        );
        let dwell = self.settings.modal.dwell;
        let m = self.motion.as_mut().expect("with_motion");
        if flags.units_code {
            // The core's machine reads a block's values in the units before it, its units
            // code aside (postproc.state.ModalMachine.apply; its checker and converter do
            // not): hand it the units first, so that it reads the values as the control.
            m.apply(&[&units_code]);
        }
        let (before, before_factors) = (m.machine.state.position, m.factors);
        m.apply(tokens);
        // An increment in other units than the position it moves from (G91 across G20/G21):
        // the machine keeps its place through the units code and the increment is in the new
        // units (FANUC, LinuxCNC; the converter's `tracked_across_units`), but the core's
        // machine adds the numbers as written. The sum is made here in mm, exactly.
        let mut metric = [false; 9];
        for w in words.iter().filter(|w| w.incremental && w.moves.is_none()) {
            let Some(i) = AXES.iter().position(|l| w.key.as_slice() == [*l]) else {
                continue;
            };
            let (Some(p), Some(f), Some(v)) = (before[i], before_factors[i], w.value) else {
                continue;
            };
            if f != w.factor {
                if let Some(sum) = f.times(p).and_then(|p| p.checked_add(v)) {
                    m.machine.state.position[i] = Some(sum);
                    metric[i] = true;
                }
            }
        }
        for w in words {
            if w.value.is_none() {
                continue; // an expression, or a number not read: the state keeps its unit
            }
            let slot = match w.key.as_slice() {
                // a dwell's time word keeps the unit of the value in force
                [letter] if flags.dwell && dwell.contains(letter) => None,
                [b'S'] if !flags.clamp => Some(10),
                [letter] => STATE_LETTERS[..10].iter().position(|l| l == letter),
                _ => None,
            };
            if let Some(i) = slot {
                m.factors[i] = Some(if metric.get(i) == Some(&true) {
                    Factor::One
                } else {
                    w.factor
                });
            }
        }
        let s = &m.machine.state;
        let core = (
            s.units,
            s.feed_units,
            s.incremental,
            s.feed_mode,
            s.spindle_mode,
        );
        if mine != core {
            return Err(format!(
                "the modal state read for the comparison (units, distance, feed and spindle \
                 modes {}) is not the core's ({})",
                modes_text(mine),
                modes_text(core)
            ));
        }
        Ok(State {
            modal: *s,
            factors: m.factors,
            reset: Arc::clone(&m.reset),
        })
    }

    /// A FANUC or Haas dwell's P (G04's, a drilling cycle's) written without a point, or given
    /// by a parameter or an expression: a time in milliseconds.
    fn milliseconds(&self, letter: u8, flags: BlockFlags, number: &[u8]) -> bool {
        letter == b'P'
            && self.settings.family == Family::MacroB
            && !number.contains(&b'.')
            && ((flags.dwell && self.settings.modal.dwell.contains(&letter)) || self.dwell_cycle)
    }

    fn word(
        &self,
        w: &Word<'_>,
        roles: &[Option<Role>; 26],
        (counts, measures, thousandths): (u32, u32, u32),
        flags: BlockFlags,
        absolute: bool,
    ) -> ReadWord {
        let letter = w.letter;
        let mut key = vec![letter];
        key.extend_from_slice(w.index);
        let pqr = match letter {
            b'P' => Some(0),
            b'Q' => Some(1),
            b'R' => Some(2),
            _ => None,
        };
        if !w.expression.is_empty()
            || w.number.is_empty()
            || letter == b'#'
            || (!w.index.is_empty() && pqr.is_some())
        {
            let mut word = ReadWord::text(&key, w.token);
            word.parameter = true;
            word.milliseconds = self.milliseconds(letter, flags, w.number);
            return word;
        }
        let role = letter
            .is_ascii_uppercase()
            .then(|| roles[(letter - b'A') as usize])
            .flatten();
        let units = units_of(letter, (self.units, self.feed_units));
        // (a count of the cycle's table: read whole, as a selector is)
        let bit = |mask: u32| letter.is_ascii_uppercase() && mask & 1 << (letter - b'A') != 0;
        // (a thread's start angle written with a point is no reading its manuals give, the
        // checker's TG208: compared as written, never "the same" as one without)
        if w.point && bit(thousandths) {
            return ReadWord::text(&key, w.token);
        }
        let count = bit(counts);
        // (a measure of the cycle's table, a time or an angle, read whole as a count is, but
        // compared within the tolerance: `Meanings::cycle_measure`)
        let measure = bit(measures);
        let cycle_increments = role == Some(Role::Increments);
        let (fmt, increments, mut step, mut kind) = if cycle_increments {
            // a length the cycle writes as a count (G76 P1200 Q350): a count of the control's
            // least increment in the units in force, or with a point the length it writes
            let least = one_step(self.format(b'X', self.units));
            let mut fmt = self.format(letter, self.units).clone();
            fmt.decimal = true;
            fmt.after = least.scale;
            (fmt, true, least, Kind::Length)
        } else {
            // LinuxCNC's polar radius `@` is a length in the plane's units, read as X is; a
            // number that is no length (G68 R) counts an A word's increment (0.001 deg), where
            // the control reads increments, as the converter reads it
            // (a dwell's time, G04's or a drilling cycle's, is no angle)
            let time = flags.dwell && self.settings.modal.dwell.contains(&letter)
                || letter == b'P' && self.dwell_cycle;
            let angle = role == Some(Role::Other)
                && !count
                && !measure
                && !time
                && self.settings.reads_increments(letter);
            // a length of a cycle or a code whose letter's format is a whole number's (Okuma
            // `H03`, Haas `Q05`, `D09`) is read by the lengths' format, as the converter
            // writes it (`Converter::length_by_axis`)
            let whole = |l: u8| {
                let f = self.format(l, units);
                !f.decimal || f.after == 0
            };
            // (a measure of the table written with a point that is no time, an angle in
            // degrees (Haas G199 `R30.`, G76 `A60.5`) or LinuxCNC G76's R ratio, steps by the
            // angles' format, the rotary axes', which no units code changes: its letter's
            // length format stepped 0.0001 in G20 and 0.001 in G21 for one angle; review 57a,
            // F5)
            let angle_measure = measure && w.point && !time;
            let format_letter = match letter {
                b'@' => b'X',
                _ if angle || angle_measure => b'A',
                _ if role == Some(Role::Length)
                    && (matches!(letter, b'A' | b'B' | b'C') || whole(letter)) =>
                {
                    b'X'
                }
                _ => letter,
            };
            let fmt = self.format(format_letter, units).clone();
            let kind = match letter {
                b'N' | b'G' | b'M' | b'T' | b'D' | b'H' | b'O' | b'L' | b':' => Kind::Code,
                b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'I' | b'J' | b'K' | b'@' => Kind::Length,
                _ if pqr.is_some_and(|i| self.settings.pqr_length[i]) => Kind::Length,
                b'F' | b'E' => Kind::Feed,
                b'S' => Kind::Speed,
                _ => Kind::Number,
            };
            // a measure the table reads whole where the letter is read in least increments
            // (a thread's start angle `Q60000`, in 0.001 deg; Haas G76's `A60`, degrees) steps
            // by one of its own unit, the number's last digit: its letter's length format's
            // step is no unit of it (review 55a F5 said the same of a count)
            // a dwell's time written with a point is seconds (the Haas NGC mill and lathe
            // manuals, G04: "P with a decimal point is seconds"; the drilling cycles' P read
            // alike) where its letter's format is a whole number's, which steps by a second: a
            // FANUC's or Haas's P05, the milliseconds of a P without its point, an Okuma's
            // P05. It steps by the millisecond (a FANUC's or Haas's P without its point, the
            // X time's 0.001 s), so `P0.5` and `P0.9` are 400 steps apart, not 0.4 (review
            // 58b, F4); a format with decimals (an ISO dwell's F022) keeps its own step.
            // An unpointed time of such a format read whole (an Okuma's `P5`, 5 s; not a
            // FANUC's milliseconds, stepped below) steps by the millisecond too: its value is exact, and a pair is stepped by its second word,
            // so `P5.4` against `P5` is 400 steps in either order, not 0.4 one way (review
            // 59c, F4)
            let step = if measure && !w.point && self.settings.reads_increments(letter) {
                Dec::from_int(1)
            } else if time
                && (!fmt.decimal || fmt.after == 0)
                && (w.point || !self.milliseconds(letter, flags, w.number))
            {
                Dec {
                    mantissa: 1,
                    scale: 3,
                }
            } else {
                one_step(&fmt)
            };
            (fmt, self.settings.reads_increments(letter), step, kind)
        };
        match role {
            Some(Role::Length) => kind = Kind::Length,
            // a selector (G05.1 Q1) is a whole number as written, a code's argument; so is a
            // count of the cycle's table (`G81 K3`, three holes): compared exactly, never
            // within a tolerance in the steps of its letter's length format, which are no
            // unit of a count (review 55a, F5: `K3 -> K4` was "+1000 steps")
            Some(Role::Selector) => kind = Kind::Code,
            _ if count => kind = Kind::Code,
            // so is a word the meaning table says nothing sure of (an Okuma G73's E, Haas M19
            // R), which the converter refuses or leaves as written (--allow-unconverted)
            Some(Role::Other | Role::Parameter)
                if matches!(kind, Kind::Length | Kind::Feed | Kind::Speed) =>
            {
                kind = Kind::Number
            }
            _ => {}
        }
        let selector = role == Some(Role::Selector) || count;
        let explicit = self.settings.explicit
            || reads_whole(self.settings.increments.as_deref(), w.letter)
            || selector
            || measure;
        let increments = increments && !selector && !measure;
        let raw = match fmt.read(w.sign == b"-", w.number, explicit, increments) {
            Ok(raw) => raw,
            Err(message) => {
                // not read as a number: compared as written, with the error where it differs
                let mut word = ReadWord::text(&key, w.token);
                word.error = Some(message);
                return word;
            }
        };
        let inch = self.units == Units::Inch;
        // a SINUMERIK's cutting rate is in the basic system under G70/G71, as its feed is
        // (`convert::Converter::cutting_rate_factor`)
        let speed_inch = if self.settings.modal.sinumerik_units {
            self.feed_units == Units::Inch
        } else {
            inch
        };
        let mut factor = Factor::One;
        // the dwell's time (the control's words, `word::dwell_words`); its other words are
        // what they are in any block
        let dwell = flags.dwell && self.settings.modal.dwell.contains(&letter);
        match kind {
            Kind::Code => {}
            _ if dwell => kind = Kind::Number,
            Kind::Length if inch => factor = Factor::Inch,
            Kind::Feed if self.feed_mode == 93 => kind = Kind::Number,
            Kind::Feed if self.feed_units == Units::Inch => factor = Factor::Inch,
            Kind::Speed if !self.css || flags.clamp => kind = Kind::Number,
            Kind::Speed if speed_inch => factor = Factor::Foot,
            _ => {}
        }
        let (mut raw_step, mut value) = (step, raw);
        // a FANUC lathe's code of G code system B or C compared by its system A number (B's G77
        // is A's G90, `ModalSettings::read_g`)
        // (its written form then no form the other side's is compared with byte for byte: the
        // two systems write the code by two numbers)
        let mut renumbered = false;
        let raw = if letter == b'G'
            && raw.is_whole()
            && self.settings.modal.g_system != crate::meaning::GCodeSystem::A
        {
            let read = self.settings.modal.read_g(raw.trunc());
            renumbered = read != raw.trunc();
            value = Dec::from_int(read.into());
            value
        } else if letter == b'G' && self.settings.modal.g_system != crate::meaning::GCodeSystem::A {
            // a decimal code by system A's number too (B's G92.1 is A's G50.3), as the
            // converter writes it (`GCodeSystem::tenths_to_a`)
            let system = self.settings.modal.g_system;
            let tenths = crate::lex::code_tenths(w.number);
            if let Some(read) = tenths
                .map(|t| system.tenths_to_a(t))
                .filter(|&a| Some(a) != tenths)
            {
                renumbered = true;
                value = Dec {
                    mantissa: read.into(),
                    scale: 1,
                };
            }
            value
        } else {
            raw
        };
        // a FANUC or Haas dwell's P without a point (G04 P1000, G82 ... P500) is milliseconds:
        // read in seconds, as a LinuxCNC P and a Haas P with a point are
        // (and a thread's start angle without a point, in 0.001 deg, is read in degrees)
        if self.milliseconds(letter, flags, w.number) || !w.point && bit(thousandths) {
            let ms = |d: Dec| Dec {
                mantissa: d.mantissa,
                scale: d.scale + 3,
            };
            (value, step, raw_step) = (ms(value), ms(step), ms(raw_step));
        }
        if factor != Factor::One {
            match (factor.times(raw), factor.times(step)) {
                (Some(r), Some(s)) => (value, step) = (r, s),
                _ => {
                    let mut word = ReadWord::text(&key, w.token);
                    word.error = Some(format!(
                        "{} in metric units needs more than the 38 significant digits \
                         tapegate holds in a number",
                        String::from_utf8_lossy(w.token)
                    ));
                    return word;
                }
            }
        }
        // under G16 the plane's words are a radius and an angle, which the converter rounds
        // each on its own (docs/convert.md, "Words a code gives another meaning"): compared
        // each as written, not as a path
        let polar_word = self.polar && {
            let (radius, angle) = crate::meaning::polar_axes(self.plane);
            letter == radius || letter == angle
        };
        // G92 (set position) and G53 (machine coordinates) take absolute values in G91 too
        let incremental = self.incremental
            && !polar_word
            && AXES.contains(&letter)
            && w.index.is_empty()
            && !dwell
            && !flags.clamp
            && !absolute;
        // a lathe's U W: an increment of X Z by its letter, carried on X Z's position, as the
        // converter carries it (`convert::UwMoves::carried`: not in G code system B or C,
        // whose U W are compared each on its own, as `ModalMachine::moved` does not follow them)
        let moves = (self.uw_moves.carried()
            && matches!(letter, b'U' | b'W')
            && w.index.is_empty()
            && roles[usize::from(letter - b'A')].is_none()
            && !dwell
            && !flags.clamp
            && !absolute)
            .then_some(if letter == b'U' { b'X' } else { b'Z' });
        let incremental = incremental || moves.is_some();
        // a dwell's time is compared by its time, whichever of the control's time letters
        // gives it (`word::dwell_words`; the check's statistics read it so): a FANUC `G04
        // X1.5` and its conversion `G4 P1.5`, both 1.5 s, are one word of the key P, as `G04
        // P1500` (milliseconds, read in seconds above) is. SINUMERIK's S is revolutions of
        // the spindle, no time: its own key
        // A FANUC or Haas dwell's X or U without a point under G20 is left out: read with the
        // inch length format it is a tenth of the time the same number is under G21 (`G20
        // G04 X1500`, 0.15 s), and no source at hand says whether the control's time unit
        // follows G20 (the FANUC-compatible ISO mode's table gives X's unit by the increment
        // system alone: SINUMERIK 840D ISO Milling, 3.3.1 "Dwell (G04)", by which it is 1.5
        // s). It keeps its own key, so it is never "the same" as a P or a time with a point
        // (review 28, finding 2: it was the same as `G04 P150` and as LinuxCNC's `G4 P0.15`)
        let inch_in_doubt =
            dwell && inch && letter != b'P' && !w.point && self.settings.family == Family::MacroB;
        if dwell
            && w.index.is_empty()
            && !(self.settings.family == Family::Sinumerik && letter == b'S')
            && !inch_in_doubt
        {
            key = vec![b'P'];
        }
        let as_length =
            (pqr.is_some_and(|i| self.settings.pqr_unstated[i]) && kind == Kind::Number && !dwell)
                .then_some(if inch { Factor::Inch } else { Factor::One });
        ReadWord {
            key,
            token: w.token.to_ascii_uppercase(),
            written: w.token.to_vec(),
            kind,
            value: Some(value),
            raw: Some(raw),
            factor,
            step,
            raw_step,
            incremental,
            moves,
            parameter: false,
            milliseconds: false,
            as_length,
            error: None,
            per_revolution: kind == Kind::Feed && self.feed_mode == 95,
            form: (!renumbered).then_some(Form {
                format: fmt,
                explicit: self.settings.explicit,
                increments,
            }),
            statement: InStatement::No,
        }
    }
}

/// The letters of the modal state whose value is kept with the unit it was set in:
/// the axes, F and S.
pub const STATE_LETTERS: &[u8; 11] = b"XYZUVWABCFS";

/// The core's modal state machine beside a reader.
pub struct Motion {
    config: Box<dyn ReadsBlocks + Send + Sync>,
    machine: ModalMachine,
    values: BlockValues,
    reset: Arc<ModalState>,
    factors: [Option<Factor>; 11],
}

impl Motion {
    /// A block's word tokens applied as `postproc.state.ModalMachine.apply` applies them.
    fn apply(&mut self, tokens: &[&[u8]]) {
        let units = (self.machine.state.units, self.machine.state.feed_units);
        let settings = self.config.modal_settings();
        let counts = crate::convert::block_counts(
            settings,
            self.machine.state.code_in_force(settings.fanuc_lathe),
            tokens,
        );
        self.config
            .numbers()
            .block_values(tokens, units, counts, &mut self.values);
        self.values.in_system(&self.machine.settings);
        self.machine.apply(&self.values);
    }
}

/// The core's modal state after a block, with the factor of the word that set each value
/// (by [`STATE_LETTERS`]) and the control's reset state.
#[derive(Debug, Clone)]
pub struct State {
    pub modal: ModalState,
    pub factors: [Option<Factor>; 11],
    pub reset: Arc<ModalState>,
}

/// One block as read.
#[derive(Debug, Clone)]
pub struct DiffBlock {
    pub line: usize,
    /// The sequence number (the first N), if any.
    pub number: Option<Dec>,
    pub words: Vec<ReadWord>,
    pub comments: Vec<Vec<u8>>,
    /// G92, G28, G30, G53, M02/M30/M99: positions start again after it.
    pub resets: bool,
    pub state: Option<Box<State>>,
}

fn modes_text(m: (Units, Units, bool, i64, i64)) -> String {
    let (units, feed_units, incremental, feed, spindle) = m;
    let feed_in = if feed_units == units {
        String::new()
    } else {
        format!(" (feed {})", feed_units.name())
    };
    let g = if incremental { 91 } else { 90 };
    format!("{}{feed_in} G{g} G{feed} G{spindle}", units.name())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wordformat::Zeros;

    fn fmt(address: u8, before: u32, after: u32, decimal: bool) -> (u8, WordFormat) {
        (
            address,
            WordFormat {
                address,
                before,
                after,
                signed: true,
                zeros: Zeros::Leading,
                decimal,
            },
        )
    }

    fn reader(fanuc_lathe: bool) -> Reader {
        let modal = ModalSettings {
            reset: vec![0, 17, 90, 94, 97, 21],
            inch: 20,
            metric: 21,
            default_units: Units::Metric,
            family: Family::MacroB,
            fanuc_lathe,
            g80_clears_motion: false,
            centre_codes: false,
            heidenhain: false,
            lap: false,
            g92_clamps: true,
            sinumerik_units: false,
            units_kept_at_end: true,
            dwell: crate::word::dwell_words(Family::MacroB, fanuc_lathe),
            arc_radius: b'R',
            lacks_g: Vec::new(),
            g_system: Default::default(),
            haas: false,
        };
        Reader::new(ReadSettings {
            formats: vec![
                fmt(b'X', 5, 3, true),
                fmt(b'F', 5, 3, true),
                fmt(b'G', 2, 0, false),
            ],
            formats_inch: Some(vec![fmt(b'X', 4, 4, true)]),
            explicit: true,
            increments: None,
            pqr_length: [false, false, true],
            pqr_unstated: [true, true, false],
            m_listed: None,
            family: Family::MacroB,
            lathe: fanuc_lathe,
            fanuc_lathe,
            modal,
            inch_code: "G20".into(),
            metric_code: "G21".into(),
            program_number: Some(b'O'),
        })
    }

    fn read(r: &mut Reader, text: &str) -> (Vec<ReadWord>, BlockFlags) {
        let tokens: Vec<&[u8]> = text.split(' ').map(str::as_bytes).collect();
        let mut out = Vec::new();
        let flags = r.read(&tokens, &mut out);
        (out, flags)
    }

    fn value(w: &ReadWord) -> String {
        w.value.map(|v| v.to_string()).unwrap_or_default()
    }

    #[test]
    fn a_units_code_sets_the_units_of_the_values_beside_it() {
        let mut r = reader(false);
        let (words, flags) = read(&mut r, "G20 X1.5 F10.");
        assert!(flags.units_code);
        assert_eq!(words[0].kind, Kind::Units);
        assert_eq!(
            (value(&words[1]), words[1].factor),
            ("38.10".into(), Factor::Inch)
        );
        assert_eq!(words[1].step.to_string(), "0.00254"); // the inch format's 0.0001 in
        assert_eq!(
            (value(&words[2]), words[2].kind),
            ("254.0".into(), Kind::Feed)
        );
        let (words, _) = read(&mut r, "G21 X1.5");
        assert_eq!(
            (value(&words[1]), words[1].step.to_string()),
            ("1.5".into(), "0.001".into())
        );
    }

    #[test]
    fn codes_are_read_whole_as_the_core_reads_them() {
        let mut r = reader(false);
        let (words, _) = read(&mut r, "G0091 X1.");
        assert!(r.incremental && words[1].incremental);
        assert_eq!((words[0].kind, value(&words[0])), (Kind::Code, "91".into()));
        read(&mut r, "G91.1");
        read(&mut r, "G90 M30");
        read(&mut r, "G91 M30"); // M30: back to the reset modes, G90
        assert!(!r.incremental);
    }

    /// Positions start again after a return by the family's own code: M99 on a Fanuc, M17 on
    /// a SINUMERIK; a SINUMERIK's M99 (a PLC's M function), a HEIDENHAIN's (the blockwise
    /// cycle call) and an Okuma's return nothing.
    #[test]
    fn a_return_is_the_family_s_own_code() {
        for (family, code, returns) in [
            (Family::MacroB, "M99", true),
            (Family::Sinumerik, "M17", true),
            (Family::Sinumerik, "M99", false),
            (Family::Heidenhain, "M99", false),
            (Family::Okuma, "M99", false),
        ] {
            let mut r = reader(false);
            r.settings.family = family;
            let (_, flags) = read(&mut r, &format!("G01 X1. {code}"));
            assert_eq!(
                (flags.returns, flags.resets),
                (returns, returns),
                "{family:?} {code}"
            );
        }
    }

    #[test]
    fn dwell_clamp_and_feed_modes() {
        let mut r = reader(true);
        assert_eq!(r.feed_mode, 94); // the reset codes' G94
        let (words, flags) = read(&mut r, "G04 X2.5");
        assert!(flags.dwell && words[1].kind == Kind::Number);
        let (words, flags) = read(&mut r, "G50 S2000");
        assert!(flags.clamp && flags.resets && words[1].kind == Kind::Number);
        // a mill whose G92 clamps (a FANUC's): G92 S is the clamp; on a Haas, Okuma or
        // LinuxCNC mill G92 only sets coordinates, and its S is a speed (ModalSettings::s_limit)
        let mut mill = reader(false);
        assert!(read(&mut mill, "G92 S3000").1.clamp);
        let mut haas = reader(false);
        haas.settings.modal.g92_clamps = false;
        assert!(!read(&mut haas, "G92 S3000").1.clamp);
        // a SINUMERIK's G26 S and G25 S are the upper and lower limits
        let mut sinumerik = reader(false);
        sinumerik.settings.modal.family = Family::Sinumerik;
        assert!(read(&mut sinumerik, "G26 S3000").1.clamp);
        assert!(read(&mut sinumerik, "G25 S100").1.clamp);
        assert!(!read(&mut sinumerik, "G97 S100").1.clamp);
        let (words, _) = read(&mut r, "G99 F0.2");
        assert!(words[1].per_revolution && r.feed_mode == 95);
        let (words, _) = read(&mut r, "R1. P2. Q#1 X1=2");
        assert_eq!(words[0].kind, Kind::Length);
        assert_eq!(words[1].as_length, Some(Factor::One));
        assert!(words[2].parameter && words[2].kind == Kind::Text);
        assert_eq!(
            (words[3].kind, words[3].key.as_slice()),
            (Kind::Length, &b"X1"[..])
        );
    }

    /// An Okuma lathe's L is an arc's radius, a length in the arc's block (G02/G03 in force)
    /// and in the thread cutting cycle; elsewhere it is compared as written.
    #[test]
    fn an_okuma_lathe_s_l_is_a_length_in_an_arc() {
        let mut r = reader(false);
        r.settings.family = Family::Okuma;
        r.settings.modal.arc_radius = crate::word::arc_radius(Family::Okuma, true);
        let kinds = |r: &mut Reader, text: &str| {
            let (words, _) = read(r, text);
            words.last().map(|w| (w.kind, w.factor))
        };
        assert_eq!(
            kinds(&mut r, "G73 X47. L12.4"),
            Some((Kind::Code, Factor::One))
        );
        assert_eq!(
            kinds(&mut r, "G20 G03 X1. L.5"),
            Some((Kind::Length, Factor::Inch))
        );
        // the G03 in force, and its value in millimetres
        let (words, _) = read(&mut r, "X2. L.5");
        assert_eq!(
            (words[1].kind, value(&words[1])),
            (Kind::Length, "12.70".into())
        );
        assert_eq!(
            kinds(&mut r, "G01 X3. L1."),
            Some((Kind::Code, Factor::One))
        );
        assert_eq!(
            kinds(&mut r, "G33 X3. L.1"),
            Some((Kind::Length, Factor::Inch))
        );
        // a Fanuc's L is a count
        let mut fanuc = reader(false);
        assert_eq!(
            kinds(&mut fanuc, "G03 X1. L2"),
            Some((Kind::Code, Factor::One))
        );
    }

    #[test]
    fn a_number_that_cannot_be_read_is_text_with_its_error() {
        let mut r = reader(false);
        let long = format!("X{}", "9".repeat(39));
        let (words, _) = read(&mut r, &long);
        assert_eq!(words[0].kind, Kind::Text);
        assert!(words[0].error.as_deref().unwrap().contains("38"));
        let inch = format!("G20 X{}", "9".repeat(38));
        let (words, _) = read(&mut r, &inch);
        assert!(words[1].error.as_deref().unwrap().contains("metric units"));
    }

    /// A statement's lengths by the converter's roles, in the units in force; the rest of it
    /// one text word; a statement of no known role one text word holding values or not.
    #[test]
    fn statements_are_read_by_the_converter_s_roles() {
        let mut r = reader(false);
        r.settings.family = Family::Okuma;
        read(&mut r, "G20");
        let mut out = Vec::new();
        r.statement_words(
            StatementKind::Command,
            b"BHC X100 Y50 I.5 J30 K6",
            false,
            &mut out,
        );
        let shown: Vec<(String, Kind, String)> = out
            .iter()
            .map(|w| {
                (
                    String::from_utf8_lossy(&w.key).into_owned(),
                    w.kind,
                    value(w),
                )
            })
            .collect();
        let length = |k: &str, v: &str| (k.to_string(), Kind::Length, v.to_string());
        assert_eq!(
            shown,
            vec![
                length("X=BHC", "2540.0"),
                length("Y=BHC", "1270.0"),
                length("I=BHC", "12.70"),
                ("{BHC".into(), Kind::Text, String::new()),
            ]
        );
        assert_eq!(out[2].token, b"BHC I.5");
        assert_eq!(out[3].token, b"BHC X# Y# I# J30 K6");
        assert!(out[..3]
            .iter()
            .all(|w| w.factor == Factor::Inch && w.statement == InStatement::Number));
        // a pattern whose roles are not documented holds values; a label holds none
        for (text, values) in [(&b"ARC X1 Y1 I2 J0 P30 K4"[..], true), (b"N10", false)] {
            out.clear();
            r.statement_words(StatementKind::Command, text, false, &mut out);
            let arguments = false;
            assert_eq!(out.len(), 1);
            assert_eq!(out[0].statement, InStatement::Text { values, arguments });
            assert_eq!(out[0].token, text);
        }
    }

    #[test]
    fn factors_are_exact() {
        let d = |t| Dec::parse(t).unwrap();
        assert_eq!(Factor::Inch.times(d("-1.0001")).unwrap(), d("-25.40254"));
        assert_eq!(Factor::Foot.times(d("500")).unwrap(), d("152.4"));
        assert!(Factor::Inch.times(Dec::from_int(i128::MAX / 10)).is_none());
    }
}
