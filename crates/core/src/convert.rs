//! Exact conversion of a program from one machine format to another (ISO 6983-1 Annex C, 6.1).
//!
//! What changes: the way numbers are written (implicit or explicit decimal sign, which zeros
//! are omitted, digits before and after the decimal sign), the units (1 in = 25.4 mm exactly),
//! the units code and, on request, the spacing. Everything else is kept as written.
//!
//! Units follow the modal state of each block (see `docs/convert.md`): X Y Z U V W and I J K
//! are lengths except in a G04 dwell; F is one under G94/G95, never G93; S under G96 but not
//! an S that limits the spindle's speed (`ModalSettings::s_limit`); P Q R where the source profile says so; parameters where the analysis of the
//! program ([`crate::lengths`]) proved them lengths. Arithmetic is on integers: a value
//! `m * 10^-k` times the factor `num/den` is rounded to the target resolution `10^-after` with
//! one division, under the rounding policy, and the largest rounding per address is kept. In
//! G91 the exact absolute position is converted and the difference of converted absolutes is
//! written, so rounding never accumulates along a path.

mod named;

pub(crate) use named::program_name;

use std::collections::HashSet;
use std::sync::Arc;

use crate::decimal::{self, explicit, explicit_into, gcd, round_quotient, Dec};
use crate::dialect::{DataBlock, DataInput, Opening, PastFormat, ProgramSplit, ReadingEnd};
use crate::expr;
use crate::hash::FastMap;
use crate::lex::{Dialect, Digits, Family, LexError, Token};
use crate::modal::{ModalMachine, ModalSettings, Units};
use crate::statement::Kind as StatementKind;
use crate::tokenizer::tokenize;
use crate::word::{
    format_in, plain, reads_increments, reads_whole, units_of, Numbers, PlainNumber, Role, Word,
};
use crate::wordformat::{implicit_code, write, write_into, WordFormat, Zeros};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rounding {
    HalfEven,
    HalfUp,
    Error,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spacing {
    Keep,
    Remove,
    Insert,
}

/// What the parameter analysis proved of one parameter: a length, or that it cannot be proved
/// one way or the other (and why). A parameter proved not a length is not listed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ParameterClass {
    Length,
    Unproved(String),
}

/// The classes of parameters by name, as the analysis names them
/// ([`crate::statement::scoped_name`]), in bytes: the converter looks a name up as the
/// program's text writes it, without making a string of it.
pub type Classes = FastMap<Vec<u8>, ParameterClass>;

/// The parameter analysis of a file ([`crate::lengths`]): where each of its programs begins, as
/// [`ProgramStarts`] splits it, the classes of the parameters every program shares (the common
/// variables, and every parameter of a file of one program or of one holding a subprogram),
/// and each program's own (a Custom Macro B main program's local variables #1-#33). Each class
/// is held once: a memory backup of 1,500 programs does not repeat the file's for each.
#[derive(Debug, Clone, Default)]
pub struct ParameterClasses {
    /// The line each program begins on (0 for the first), ascending.
    pub starts: Vec<usize>,
    pub shared: Classes,
    /// The programs with parameters of their own: (index in `starts`, their classes).
    pub own: Vec<(usize, Classes)>,
    /// A LinuxCNC file's subroutines: the line of the `sub` of each label ([`crate::statement::o_label`]),
    /// the scope of its own parameters (#1-#30 its call's arguments).
    pub subs: FastMap<Vec<u8>, usize>,
}

impl ParameterClasses {
    /// The class of parameter `name` in the file's program number `program` (0 for the first).
    pub fn class(&self, program: usize, name: &[u8]) -> Option<&ParameterClass> {
        if program >= self.starts.len() {
            return None;
        }
        if let Ok(at) = self.own.binary_search_by_key(&program, |&(p, _)| p) {
            if let Some(class) = self.own[at].1.get(name) {
                return Some(class);
            }
        }
        self.shared.get(name)
    }

    /// Program number `program`'s parameters proved lengths, and `(parameter, why it cannot be
    /// proved)`, each sorted: the lists a user (or a test) reads.
    pub fn lists(&self, program: usize) -> (Vec<String>, Vec<(String, String)>) {
        let own = self
            .own
            .binary_search_by_key(&program, |&(p, _)| p)
            .map(|at| &self.own[at].1);
        let mut lengths = Vec::new();
        let mut problems = Vec::new();
        for (name, class) in self.shared.iter().chain(own.into_iter().flatten()) {
            let name = String::from_utf8_lossy(name).into_owned();
            match class {
                ParameterClass::Length => lengths.push(name),
                ParameterClass::Unproved(why) => problems.push((name, why.clone())),
            }
        }
        lengths.sort();
        problems.sort();
        (lengths, problems)
    }
}

/// A control's table of codes, each with its group, sorted by code
/// ([`ConvertConfig::listed_codes`]): shared between the configurations, never copied.
pub type CodeList = std::sync::Arc<[(String, String)]>;

#[derive(Debug, Clone)]
pub struct ConvertConfig {
    pub src_formats: Vec<(u8, WordFormat)>,
    /// The source's formats while inch is in force, where they differ; likewise the target's.
    pub src_formats_inch: Option<Vec<(u8, WordFormat)>>,
    pub out_formats_inch: Option<Vec<(u8, WordFormat)>>,
    pub explicit_in: bool,
    /// The source control reads a word without a point in least increments (Fanuc), but for
    /// these letters; None: as a whole number.
    pub src_increments: Option<Vec<u8>>,
    /// The same, for the target control: a word is then never left without its point.
    pub dst_increments: Option<Vec<u8>>,
    /// The source machine's modal settings (`machine::Machine`): its units codes and default
    /// units, its reset state (clause 14) that M02/M30 return it to, whether it keeps its units
    /// through M02/M30, and its family's rules of motion.
    pub src_modal: ModalSettings,
    /// The source profile's roles of P, Q and R.
    pub pqr: [Role; 3],
    pub out_formats: Vec<(u8, WordFormat)>,
    pub dwell_formats: Vec<(u8, WordFormat)>,
    /// The target's F format for a feed per revolution (G95, a lathe's G99), metric and inch,
    /// where the profile gives one (`machine::MachineSpec::feed_rev_formats`).
    pub feed_rev_formats: [Option<WordFormat>; 2],
    pub explicit_out: bool,
    pub inch_code: String,
    pub metric_code: String,
    pub target_units: Units,
    /// The units to convert to; None keeps them.
    pub units: Option<Units>,
    pub rounding: Rounding,
    pub spacing: Spacing,
    pub allow_unconverted: bool,
    /// None when the program has no parameters; shared, never copied, by each program's
    /// fresh state.
    pub parameters: Option<Arc<ParameterClasses>>,
    /// The units each length parameter set before its first read is read in, by program and
    /// name, as a conversion refused with [`REREAD`] learned them
    /// ([`Converter::read_units_learned`]): its assignments are converted by the factor of
    /// those units, not of the units in force where they stand.
    pub read_units: Vec<(usize, String, Units)>,
    /// The source's control family and whether it is a lathe: the roles of a cycle's words
    /// (G71 P Q are block numbers, U R lengths) come from the family's cycle table.
    pub family: Family,
    pub lathe: bool,
    /// The target's control family: on Sinumerik its units codes G70/G71 leave the feed in the
    /// basic system (the target's units) and G700/G710 set it too.
    pub target_family: Family,
    /// What the target profile's dialect reads (its `#` parameters, `[ ]` expressions, `*`):
    /// a word holding one it does not read is refused ([`Converter::statements`]), whatever
    /// the target's family reads elsewhere (an ISO 6983-1 profile reads `#` only where its
    /// characters allow it).
    pub target_dialect: crate::lex::Dialect,
    /// The target reads cycles by the source's table: the same dialect (Fanuc and Haas are
    /// one family here but write their lathe cycles differently) and the same kind of machine.
    pub same_cycle_table: bool,
    /// The target's G code system where it is a FANUC or Haas lathe (a Haas reads system A's
    /// codes), None otherwise: between two such lathes of different systems a code is written
    /// by the target's number of its function ([`Converter::renumbers`]).
    pub target_g_system: Option<crate::meaning::GCodeSystem>,
    /// The target is a FANUC: it reads FANUC's G10 L50 / G10 L3 data input modes (a Haas's
    /// G10 lists L2, L10-L13 and L20 only).
    pub target_data_input: bool,
    /// Between a FANUC and a Haas (one language, two controls): Some(true) where the source is
    /// the Haas, Some(false) where it is the FANUC; None otherwise. Their G10 gives some data
    /// types other data ([`crate::between::fanuc_haas_words`]).
    pub fanuc_haas: Option<bool>,
    /// How the source and the target read an M98 P of more than four digits, where both are
    /// known: true the repetitions and the program number (a FANUC), false the program number
    /// alone, the repetitions by L (a Haas, LinuxCNC) ([`Converter::m98_long_p`]).
    pub m98_repeats: Option<(bool, bool)>,
    /// The letter the source and the target count a drilling canned cycle's repeats in, where
    /// both have one ([`crate::lex::Family::cycle_repeat_letter`]; [`Converter::cycle_repeat_words`]).
    pub cycle_repeats: Option<(u8, u8)>,
    /// The source profile was guessed from the program (no `--from`): whether its control
    /// keeps its units through M02/M30 is not known either.
    pub source_detected: bool,
    /// The source's start units were given (`--from-units`: the units its machine is set to),
    /// not taken from its profile: a control that selects them by a machine parameter (the OSP
    /// lathe) then reads the program in them with nothing left to say.
    pub src_units_given: bool,
    /// The source reads lower case (LinuxCNC, SINUMERIK) and the target does not (a FANUC
    /// alarms on `g1 x2.5`: TG101): a word written in lower case is written in upper case,
    /// which both read as the same word (review 16c, finding 5).
    pub upper_case: bool,
    /// The target is a Haas NGC: it alarms on a blank between an address and its number
    /// (`X 1.5`, TG100), where the other controls skip it ([`crate::lex::apart`]).
    pub target_ngc: bool,
    /// The target control keeps the units a program selected through its M02/M30
    /// (`ModalSettings::units_kept_at_end`; the profile says, `Profile.units_kept_at_end`).
    pub target_units_kept: bool,
    /// Decimals of one least input increment of the source control, metric and inch (IS-B:
    /// 3 for 0.001 mm, 4 for 0.0001 in); likewise of the target. A length a cycle writes as a
    /// count (`G76 P1200`) is that many increments (`formats.profile.Profile.least_increment`).
    pub src_increment: [u32; 2],
    pub out_increment: [u32; 2],
    /// What the target control does with a sequence number longer than its N format
    /// (`checks.past_sequence`, as the checker reads it): only where it alarms is such a
    /// number a digit overflow; elsewhere it is carried as written (TG208 on the target).
    pub target_past_sequence: PastFormat,
    /// The target control has no motion mode at its reset and after G80 (LinuxCNC), where
    /// the source's keeps one (`ModalSettings::g80_clears_motion`).
    pub target_g80_clears_motion: bool,
    /// The letter the target control reads an arc's radius from (`word::arc_radius`), 0 where
    /// it reads none (an ISO 6983-1 profile whose `checks.pqr` makes R a parameter): where it
    /// is not the source's, an arc given by its radius is refused.
    pub target_arc_radius: u8,
    /// The target's tape reader takes a ':' for the alignment (rewind) stop, in a comment too
    /// (ISO 6983-1 5.1, `colon_stop`; TG122 of its check), where the source's does not: a
    /// comment holding one is refused ([`colon_in_comment`]).
    pub colon_stops: bool,
    /// The source is a FANUC or Haas lathe, whose T word is the tool number followed by the
    /// offset number (`T0101`: tool 1, offset 1; dialect::LATHE_OFFSET_DIGITS), and the target
    /// reads its T as one number (a mill, an ISO 6983-1 or another family's control): a T word
    /// is refused ([`Converter::same_tool_word`]).
    pub lathe_tool_offset: bool,
    /// Pairs of G codes (the lower first) the target's table puts in one modal group and the
    /// source's in two, with the target's group (`machine::one_group_codes`): both in one
    /// block are refused at the second ([`Converter::same_meaning`]).
    pub one_group_codes: Vec<(i64, i64, String)>,
    /// The source reads X as a length from the origin (a mill), the target as a diameter (a
    /// FANUC, Haas or Okuma lathe: `check::Config::diameter`): an X word is refused
    /// ([`Converter::same_x_reading`]).
    pub x_diameter: bool,
    /// The mirror of `x_diameter`: the source reads X as a diameter (a FANUC, Haas or Okuma
    /// lathe), the target, not a lathe, as a length from the origin (a mill, LinuxCNC's
    /// mill profile in G8's radius reading, an ISO 6983-1 mill): an X word is refused
    /// ([`Converter::same_x_reading`]).
    pub x_radius: bool,
    /// The lathe of `x_diameter` or `x_radius` (the target, or the source) is a FANUC, whose
    /// manual says how G10 reads a tool offset's X ([`Converter::g10_x_reading`]); a Haas or
    /// Okuma lathe's is in no source at hand.
    pub x_lathe_fanuc: bool,
    /// The feed modes of the source's and the target's reset states where they differ
    /// (`machine::reset_feed`: 94 per minute, 95 per revolution): a FANUC or Haas lathe's G99
    /// for a mill or LinuxCNC (G94), and the other way. An F word with no feed mode code both
    /// read alike written before it is refused ([`Converter::reset_feed_mode`]).
    pub reset_feed: Option<[i64; 2]>,
    /// The target's reader reads the text after the first `%` (Haas, Okuma, ISO 6983-1 as the
    /// identification, LinuxCNC not at all; a FANUC skips it): a leader line whose text the
    /// target does not take, or may not, is refused ([`percent_words`]), whatever the source
    /// did with it.
    pub percent_words_read: bool,
    /// The source's control skips that text (a FANUC): said in the refusal.
    pub leader_skipped: bool,
    /// The source's program number address (`O`): where a file holds several programs, one
    /// after the end of another begins with it (`dialect::ProgramSplit`).
    pub program_number: Option<u8>,
    /// Between two controls, the G codes both profiles list in different modal groups (Okuma
    /// `G56` a tool length offset, FANUC `G56` a work offset), and those one control gives a
    /// function of its own in the same group (OSP lathe `G71`), those whose meaning keys or
    /// functions differ, a lathe cycle each control writes in its own form (FANUC's two-block
    /// `G71`, Haas's one block), and, between families, a code only one of the two tables
    /// lists (FANUC's builder's `M39`, a Haas's turret rotation): `(code as written without its
    /// letter, what it is on the source, on the target)`. A block with one is refused
    /// ([`crate::machine::differing_codes`], `machine::meaning_differences`).
    pub differing_codes: Vec<(String, String, String)>,
    /// Between two control families, the G and M codes the source's and the target's table
    /// assign, each sorted by code (`12`, `91.1`, `M39`; with its group): a code outside both
    /// is the machine builder's on the source (an M code its PLC decodes) or an option neither
    /// profile lists, so tapegate cannot say what either control does with it; it is carried
    /// with a note. None on one family, where the code tables are compared by group
    /// ([`crate::machine::differing_codes`]).
    pub listed_codes: Option<[CodeList; 2]>,
    /// The target control alarms on a G code its table lacks (`check::Config::alarm_g`:
    /// LinuxCNC, rs274 "Unknown g code used" unless a REMAP defines it; a SINUMERIK;
    /// HEIDENHAIN): a G code outside both tables (`listed_codes`) is refused there, not
    /// carried with a note.
    pub target_alarm_g: bool,
    /// The decimal G codes the source family's own list holds (`54.1`; a FANUC 0i-MF mill's
    /// has no `71.7`), as [`Dec`] writes them; None on an ISO 6983-1 profile, whose table
    /// lends every code the standard's meaning. With [`ModalSettings::lacks`] for the whole
    /// numbers: a block with a code outside the list has words of no known role
    /// ([`Converter::lacked_code_words`]).
    pub src_decimal_g: Option<Vec<String>>,
    /// The G and M codes the source's table and profile list ([`crate::machine::Machine`]'s
    /// `listed`); None on an ISO 6983-1 profile. Under a change of units, the P Q R of an M
    /// code outside it (FANUC `M100`: the builder's, or a macro call by parameters 6080-6089)
    /// are of no known role.
    pub src_listed: Option<CodeList>,
    /// The source's and the target's reading of arc centres, where they differ (FANUC
    /// incremental I J, HEIDENHAIN ISO absolute, a CM 332's sign-less quadrant I J): an arc
    /// with I J K is refused.
    /// (How the source reads them, how the target does: `machine::ijk_reading`.)
    pub ijk: Option<(&'static str, &'static str)>,
}

impl ConvertConfig {
    /// The baseline of a conversion from a `from` control to a `to` control, for the tests
    /// and the fuzz crate: no word formats, IS-B increments (0.001 mm, 0.0001 in) on both
    /// sides, metric by ISO 6983-1 clause 14.3's reset, the target reading every form the
    /// source may write (`#`, `[ ]`, `*`), nothing refused between the two beyond what the
    /// formats say. Each user sets what it tests by struct update (`ConvertConfig { ..,
    /// ..ConvertConfig::between(from, to) }`), so a new field is written here once. A real
    /// conversion's config comes from the two compiled machines (`Machine::convert_to`).
    pub fn between(from: Family, to: Family) -> ConvertConfig {
        ConvertConfig {
            src_formats: Vec::new(),
            src_formats_inch: None,
            out_formats_inch: None,
            explicit_in: true,
            src_increments: None,
            dst_increments: None,
            src_modal: ModalSettings {
                reset: vec![1, 17, 40, 21, 80, 90, 94],
                inch: 20,
                metric: 21,
                default_units: Units::Metric,
                family: from,
                fanuc_lathe: false,
                g80_clears_motion: false,
                centre_codes: false,
                heidenhain: from == Family::Heidenhain,
                lap: false,
                g92_clamps: true,
                sinumerik_units: false,
                units_kept_at_end: true,
                dwell: crate::word::dwell_words(from, false),
                arc_radius: crate::word::arc_radius(from, false),
                lacks_g: Vec::new(),
                g_system: Default::default(),
                haas: false,
            },
            pqr: [Role::Other, Role::Other, Role::Length],
            out_formats: Vec::new(),
            dwell_formats: Vec::new(),
            feed_rev_formats: [None, None],
            explicit_out: true,
            inch_code: "G20".into(),
            metric_code: "G21".into(),
            target_units: Units::Metric,
            units: None,
            rounding: Rounding::HalfEven,
            spacing: Spacing::Keep,
            allow_unconverted: false,
            parameters: None,
            read_units: Vec::new(),
            family: from,
            lathe: false,
            target_family: to,
            target_dialect: Dialect {
                family: to,
                hash: true,
                brackets: true,
                star: true,
                ..Dialect::default()
            },
            same_cycle_table: true,
            target_g_system: None,
            target_data_input: true,
            fanuc_haas: None,
            m98_repeats: None,
            cycle_repeats: None,
            source_detected: false,
            src_units_given: false,
            upper_case: false,
            target_ngc: false,
            target_units_kept: true,
            src_increment: [3, 4],
            out_increment: [3, 4],
            target_past_sequence: PastFormat::Alarm,
            target_g80_clears_motion: false,
            target_arc_radius: crate::word::arc_radius(to, false),
            colon_stops: false,
            lathe_tool_offset: false,
            one_group_codes: Vec::new(),
            x_diameter: false,
            x_radius: false,
            x_lathe_fanuc: false,
            reset_feed: None,
            percent_words_read: false,
            leader_skipped: false,
            program_number: Some(b'O'),
            differing_codes: Vec::new(),
            listed_codes: None,
            target_alarm_g: false,
            src_decimal_g: None,
            src_listed: None,
            ijk: None,
        }
    }
}

/// Why a word cannot be converted; `column` is filled in by the block.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConvertError {
    pub message: String,
    pub clause: &'static str,
    pub column: usize,
    /// The line of the word, where it is not the block being converted (an error found only
    /// when a later block shows it, as the M99 that makes a program a subprogram).
    pub line: Option<usize>,
}

/// The clause of a refusal the caller answers by converting again, given the units the
/// refusal learned ([`ConvertConfig::read_units`]): a length parameter set before its first
/// read, in other units than the read's.
pub const REREAD: &str = "units-reread";

/// A Fanuc or Haas comment read to its matching `)` (a `(` inside it, TG136) is refused for a
/// target of another family: ISO 6983-1 ends a comment at its first `)` and LinuxCNC refuses
/// it (rs274 "Nested comment found"), so written as it stands the target reads the rest as the
/// block's or refuses it (docs/dialects.md, "A `(` inside a comment on a Fanuc or Haas"). Only
/// a `(` inside an open comment counts: the text after a `;`, kept as one comment, may hold
/// comments side by side (`; (A) (B)`).
fn nested_comment_to(b: &BlockIn<'_>, target: Family) -> Result<(), ConvertError> {
    for &(at, comment) in b.comments {
        let mut depth = 0usize;
        let inner = comment.iter().position(|&c| {
            match c {
                b'(' if depth > 0 => return true,
                b'(' => depth = 1,
                b')' => depth = depth.saturating_sub(1),
                _ => {}
            }
            false
        });
        if let Some(inner) = inner {
            let target = match target {
                Family::LinuxCnc => "LinuxCNC refuses it (rs274: \"Nested comment found\")",
                Family::Sinumerik => "a SINUMERIK reads '( )' as brackets, not a comment",
                _ => "the target ends a comment at its first ')' (ISO 6983-1, clause 4)",
            };
            return Err(ConvertError {
                message: format!(
                    "a '(' inside a comment, which a Fanuc or Haas profile reads to its matching \
                     ')' but {target}: write the comment without the inner parentheses"
                ),
                clause: "4",
                column: crate::text::column(b.text, at + inner),
                line: None,
            });
        }
    }
    Ok(())
}

/// A comment holding a ':' for a target whose tape reader stops there (ISO 6983-1 5.1: ':' is
/// the alignment function, the rewind stop; TG122 of the target's check), where the source's
/// does not: written as it stands the target stops in the middle of the program, so it is
/// refused at the ':' (tapegate changes no comment it was not asked to).
fn colon_in_comment(b: &BlockIn<'_>) -> Result<(), ConvertError> {
    for &(at, comment) in b.comments {
        if let Some(colon) = comment.iter().position(|&c| c == b':') {
            return Err(ConvertError {
                message: "a ':' in a comment, which the target's tape reader takes for the \
                          alignment (rewind) stop (ISO 6983-1 5.1; its check: TG122) and the \
                          source's does not: write the comment without the ':'"
                    .into(),
                clause: "dialect",
                column: crate::text::column(b.text, at + colon),
                line: None,
            });
        }
    }
    Ok(())
}

/// The leader `%` line (the file's first, before any block), for a target whose reader takes
/// the text after it: `%O0003(TITLE)`, whose O number a FANUC source loses (it skips the
/// text: `dialect::skips_leader`, TG129 of its check), would be read as words before the first
/// end of block; a Haas's or an Okuma's own such leader is refused alike for those targets
/// (review 51, F16: no source says what their control does with it). What counts is what the target reads there:
/// LinuxCNC no text at all (rs274: "Bad character '%' used", TG412 of its check: `%(TITLE)`,
/// `%;` too), a Haas, an Okuma or an ISO 6983-1 reader an identification, which may not begin
/// like a word (TG111) nor hold letters outside parentheses (`%TITLE`: TG112;
/// `dialect::leader_text`, the target's check's own test; on a Haas or an Okuma, whose
/// sources do not say what the control does with the text, TG137, a warning, which the
/// conversion still refuses to write: the source never ran the text, the target may);
/// `%(TITLE)` and `%:0003` are its identification. tapegate does not move the text to a line of its own (the source never
/// ran it), so the line is refused at its first character after the `%`. The closing `%` is
/// the end of the program on every target: text after it is read by none.
fn percent_words(b: &BlockIn<'_>, target: Family, skipped: bool) -> Result<(), ConvertError> {
    let Some(percent) = b.text.iter().position(|&c| c == b'%') else {
        return Ok(());
    };
    let rest = &b.text[percent + 1..];
    let Some(start) = rest.iter().position(|c| !c.is_ascii_whitespace()) else {
        return Ok(());
    };
    let bytes = &rest[start..];
    // a Haas (the only Custom Macro B target that reads the text) or an Okuma: TG137
    let unsourced = matches!(target, Family::MacroB | Family::Okuma);
    let how = if target == Family::LinuxCnc {
        "LinuxCNC reads no text after it (rs274: \"Bad character '%' used\"; its check: TG412)"
    } else {
        match crate::dialect::leader_text(bytes) {
            None => return Ok(()),
            Some(crate::dialect::LeaderText::Words) if unsourced => {
                "the target's reader may take it for words before the first end of block (ISO \
                 6983-1 clause 4; no source of the target's says what it does; its check: \
                 TG137)"
            }
            Some(crate::dialect::LeaderText::Letters) if unsourced => {
                "the target's reader may take it for the program's identification, which may \
                 hold letters only in parentheses (ISO 6983-1 clause 4; no source of the \
                 target's says what it does; its check: TG137)"
            }
            Some(crate::dialect::LeaderText::Words) => {
                "the target's reader takes it for words before the first end of block (ISO \
                 6983-1 clause 4; its check: TG111)"
            }
            Some(crate::dialect::LeaderText::Letters) => {
                "the target's reader takes it for the program's identification, which may hold \
                 letters only in parentheses (ISO 6983-1 clause 4; its check: TG112)"
            }
        }
    };
    let source = if skipped {
        " which the source control skips (FANUC B-63524EN/01, 8, memory card file format; its \
         check: TG129) and"
    } else {
        ""
    };
    Err(ConvertError {
        message: format!(
            "{:?}: text after the first '%',{source} {how}: write the '%' on a line of its own, \
             the program number (if it is to be read) on the next",
            String::from_utf8_lossy(bytes.trim_ascii_end())
        ),
        clause: "4",
        column: crate::text::column(b.text, percent + 1 + start),
        line: None,
    })
}

fn error(message: String, clause: &'static str) -> ConvertError {
    ConvertError {
        message,
        clause,
        column: 0,
        line: None,
    }
}

/// Why a line was not converted: it cannot be read, or a word cannot be converted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LineError {
    Read(LexError),
    Convert(ConvertError),
}

/// One word of a block: its token and where it is written in the line (bytes).
#[derive(Debug, Clone, Copy)]
pub struct WordSpan<'a> {
    pub token: &'a [u8],
    pub start: usize,
    pub end: usize,
    /// The tokenizer's [`Token::plain`]: a plain number after the address, the length of its
    /// sign; None where not known (or not a plain number): [`plain`] reads the token then.
    pub plain: Option<u8>,
    /// The tokenizer's [`Token::digits`] of a plain number (where `plain` is Some).
    pub digits: Digits,
}

pub struct BlockIn<'a> {
    pub line: usize,
    pub text: &'a [u8],
    pub words: &'a [WordSpan<'a>],
    /// No comments, skip, `%` or missing end of block.
    pub plain: bool,
    pub percent: bool,
    pub skip: &'a [u8],
    /// A block skip in the middle of the block (Fanuc, Haas): its byte offset and text (`/`,
    /// `/2`), written back at its place among the words.
    pub skip_within: Option<(usize, &'a [u8])>,
    /// Comments with their byte offsets.
    pub comments: &'a [(usize, &'a [u8])],
    /// The dialect's statements with their byte offsets and kinds: carried through as written.
    pub statements: &'a [(usize, StatementKind, &'a [u8])],
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Axis,
    Angle,
    Centre,
    Feed,
    Speed,
    Pqr,
    Count,
    /// A code or count word whose format has decimals (G031), where the source or the
    /// target writes numbers without a decimal sign: a number, read and written by format.
    Code,
}

fn kind(letter: u8) -> Option<Kind> {
    Some(match letter {
        b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' => Kind::Axis,
        b'A' | b'B' | b'C' => Kind::Angle,
        b'I' | b'J' | b'K' => Kind::Centre,
        b'F' | b'E' => Kind::Feed,
        b'S' => Kind::Speed,
        // LinuxCNC's polar radius (`@`, a length; its angle `^` is kept as written)
        b'P' | b'Q' | b'R' | b'@' => Kind::Pqr,
        b'N' | b'G' | b'M' | b'T' | b'D' | b'H' | b'O' | b'L' => Kind::Count,
        _ => return None,
    })
}

fn pow10(n: u32) -> Result<i128, ConvertError> {
    decimal::pow10(n).ok_or_else(too_long)
}

fn too_long() -> ConvertError {
    error(
        "the number has more digits than tapegate converts exactly (38 significant digits)".into(),
        "Annex C",
    )
}

/// A block's words as the checks between two families read them ([`crate::between`]).
fn between_words<'t>(b: &BlockIn<'t>) -> Vec<crate::between::Word<'t>> {
    b.words
        .iter()
        .map(|w| crate::between::Word {
            token: w.token,
            start: w.start,
        })
        .collect()
}

/// The exact value `m * 10^-k` of digits written `whole.fraction`, trailing zeros of the
/// fraction dropped for the arithmetic (the value is the same).
fn exact(whole: &[u8], fraction: &[u8]) -> Result<(i128, u32), ConvertError> {
    let kept = fraction.len() - fraction.iter().rev().take_while(|&&c| c == b'0').count();
    let d = Dec::from_runs(whole, &fraction[..kept], kept as u32).ok_or_else(too_long)?;
    Ok((d.mantissa, d.scale))
}

/// As [`exact`], from the value the tokenizer read while it scanned the digits
/// ([`Digits::value`]: 1 to 18 of them) where it has one, without reading them again: only
/// for a plain word the tokenizer split (`WordSpan::plain`), whose digits are these.
fn exact_of(
    digits: Option<Digits>,
    whole: &[u8],
    fraction: &[u8],
) -> Result<(i128, u32), ConvertError> {
    let Some(value) = digits.and_then(|d| d.value) else {
        return exact(whole, fraction);
    };
    let (mut m, mut k) = (value, fraction.len() as u32);
    while k > 0 && m % 10 == 0 {
        m /= 10;
        k -= 1;
    }
    Ok((i128::from(m), k))
}

fn split_number(number: &[u8]) -> (&[u8], &[u8]) {
    match number.iter().position(|&c| c == b'.') {
        Some(p) => (&number[..p], &number[p + 1..]),
        None => (number, &b""[..]),
    }
}

type Ratio = (i128, i128);
const ONE: Ratio = (1, 1);

/// `HP=1`, `HP = 4`: an Okuma OSP lathe's home position number (the G20 block's), a whole
/// number written as such.
/// An Okuma OSP lathe's home position number, `HP=4` of `G20 HP=4` (a count).
pub(crate) fn okuma_home_number(statement: &[u8]) -> bool {
    let Some(rest) = statement
        .get(..2)
        .filter(|name| name.eq_ignore_ascii_case(b"HP"))
        .map(|_| statement[2..].trim_ascii())
    else {
        return false;
    };
    let Some(number) = rest.strip_prefix(b"=").map(|n| n.trim_ascii()) else {
        return false;
    };
    !number.is_empty() && number.iter().all(u8::is_ascii_digit)
}

/// A word of an address and a plain number (`X-1.5`, `G01`, `x.5`): no index, parameter or
/// expression.
fn bare_number_word(token: &[u8]) -> bool {
    let Some((letter, rest)) = token.split_first() else {
        return false;
    };
    let rest = rest
        .strip_prefix(b"+")
        .or(rest.strip_prefix(b"-"))
        .unwrap_or(rest);
    letter.is_ascii_alphabetic()
        && !rest.is_empty()
        && rest.iter().all(|c| c.is_ascii_digit() || *c == b'.')
}

/// A run of blanks in a word's `text` between two characters of a number (a digit or a
/// point), or after a `#` (`#1 0`, `[1 0]`, `# 1`): LinuxCNC reads through it, another
/// control reads two values or none.
fn blank_inside_number(text: &[u8]) -> bool {
    let number = |c: u8| c.is_ascii_digit() || c == b'.';
    let mut before = None;
    let mut gap = false;
    for &c in text {
        if c == b' ' || c == b'\t' {
            gap = before.is_some();
            continue;
        }
        match before {
            Some(b'#') if gap => return true,
            Some(b) if gap && number(b) && number(c) => return true,
            _ => {}
        }
        gap = false;
        before = Some(c);
    }
    false
}

/// Whether a word's written span is its token's bytes (in either case) with blanks between
/// them and nothing else: no comment inside it.
fn spells(span: &[u8], token: &[u8]) -> bool {
    let mut letters = span.iter().filter(|c| **c != b' ' && **c != b'\t');
    token
        .iter()
        .all(|t| letters.next().is_some_and(|c| c.eq_ignore_ascii_case(t)))
        && letters.next().is_none()
}

/// `text` (starting at byte `start` of its block) in upper case but inside the block's
/// `comments` (byte offsets in the block) and inside double quotes (a SINUMERIK string):
/// those are kept as written.
fn upper_outside(text: &[u8], start: usize, comments: &[(usize, &[u8])]) -> Vec<u8> {
    let mut quoted = false;
    text.iter()
        .enumerate()
        .map(|(i, &c)| {
            let at = start + i;
            let commented = comments.iter().any(|&(o, t)| o <= at && at < o + t.len());
            if c == b'"' && !commented {
                quoted = !quoted;
            }
            if quoted || commented {
                c
            } else {
                c.to_ascii_uppercase()
            }
        })
        .collect()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

pub struct Converter {
    c: ConvertConfig,
    /// The source's and the target's formats of A-Z, looked up once ([`FormatTable`]).
    src_table: FormatTable,
    out_table: FormatTable,
    /// [`reads_whole`] and [`reads_increments`] of the source's and the target's lists.
    src_letters: WholeLetters,
    dst_letters: WholeLetters,
    /// The source program's modal state (the one state machine of `modal.rs`): the units,
    /// distance, feed and spindle modes its words are read in.
    modal: ModalMachine,
    src_units: Units,
    /// The units of the source's feed words, and of the output's (see `ModalState::feed_units`).
    src_feed_units: Units,
    out_feed_units: Units,
    /// The units of lengths the target control is in at this point of the output: its
    /// default, then what the codes written select, and after M02/M30 its default again
    /// unless it keeps its units (`ConvertConfig::target_units_kept`).
    out_length_units: Units,
    units_seen: bool,
    /// A G code the source's list lacks, and its line, whose motion is in force as far as
    /// the converter can tell (no listed motion code since): a later block's words of a
    /// motion's or cycle's role (P Q R I J K E L) are not known to it either
    /// ([`Converter::lacked_code_words`]).
    lacked_in_force: Option<(String, usize)>,
    /// The canned cycle in force on a FANUC or Haas control whose words the cycle table gives
    /// roles (a mill's G73, G74, G76, G81-G89, a lathe's G83-G89 and G243), until G80, a motion
    /// code G00-G03 or the end of the program: a block under it repeats it, and its words have
    /// the cycle's roles; and a lathe's thread in force ([`Repeat`]).
    cycle_code: Repeat,
    /// The line of the M02/M30 that ended the program before this one, if any.
    ended_on: Option<usize>,
    /// A guessed source after an M02/M30 where the units the program selected and those of
    /// the reset state differ: (that line, the units kept, the units reset). A program that
    /// moves before it selects its units cannot be read then.
    units_doubt: Option<(usize, Units, Units)>,
    /// The units where the flow is not straight ([`crate::units_flow`]).
    flow: crate::units_flow::UnitsFlow,
    /// The same for the feed's units, on a SINUMERIK only, where they are a flow of their own:
    /// G700/G710 set them with the lengths', G70/G71 set them to the machine's (a branch from
    /// G700 into G70 leaves the lengths in inch on both paths, the feed in mm on one). None
    /// while the feed's units have been the lengths' all along: then it is the lengths' flow,
    /// which it starts as a copy of where they first part.
    feed_flow: Option<crate::units_flow::UnitsFlow>,
    /// The caller's doubt, kept over a LinuxCNC body.
    flow_caller: Option<crate::units_flow::Doubt>,
    /// Why the units after the last block's call are not known: its body may return in
    /// either ([`crate::sub_units::Call::Doubt`]); the doubt begins with the next block.
    flow_after_call: Option<String>,
    /// The units were brought by the jumps to a label the straight path does not reach
    /// ([`Converter::arrive`]): a note on the text after an end says so.
    jumped_in: bool,
    /// LinuxCNC M70: the units saved, and why they were not known there (M71 forgets them).
    saved_units: Option<(Units, Option<String>)>,
    /// The units of the source's reset state (clause 14, or the profile's own).
    reset_units: Units,
    src_pos: [Option<Dec>; 26],
    out_pos: [Option<i128>; 26],
    abs_raw: [Option<(bool, i128, u32)>; 26],
    /// The units of a length's `src_pos`/`abs_raw` (millimetres once a program has switched
    /// its units in G91: inch converts to mm exactly, mm to inch does not), and the units
    /// and decimals of its `out_pos`: a position is carried across a G20/G21 (G70/G71) into
    /// the new units, never added to in the wrong ones.
    pos_units: [Option<Units>; 26],
    out_at: [Option<(Units, u32)>; 26],
    /// The output's position of a length, exactly in millimetres, once the source or the
    /// output has switched its units ([`Converter::tracked_across_units`]).
    out_mm: [Option<Dec>; 26],
    /// A Fanuc, Haas or Okuma lathe's U W are increments of X Z by their letter: tracked as
    /// G91 words are while the motion in force is G00-G03 or a thread (not in a turning or
    /// threading cycle, whose U W are the cycle's and whose tool returns to its start point);
    /// in G code system B or C each converted on its own ([`UwMoves`]).
    uw_moves: UwMoves,
    /// A rounded U or W of system B or C, converted on its own, has been noted (once).
    uw_own_noted: bool,
    /// The source program has written a feed mode code (G93-G95; a FANUC lathe's G98/G99 by
    /// system A's numbers): its F no longer reads by the reset state's feed mode.
    feed_mode_written: bool,
    /// A `%` line or a block with words has been read: a `%` line now is no leader.
    leader_passed: bool,
    /// A lathe's polar coordinate interpolation (G12.1 ... G13.1) is on: its C words are
    /// lengths ([`crate::meaning::polar_interpolation`]).
    polar_interpolation: bool,
    /// A lathe's program commanded C as an axis (`G00 C0`, `G83 ... C90.`, `G07.1 C`): its
    /// machine has a C axis, and a C beside X or Z in G01 is a move of it, no chamfer.
    c_axis: bool,
    /// Whether the last [`Converter::round`] rounded; the first increment of the program
    /// being converted whose target position was rounded `(line, word)`, and whether the
    /// program has a jump or loop: a body run again repeats that rounding.
    rounded: bool,
    rounded_step: Option<(usize, String)>,
    /// The word [`Converter::expression`] is converting is one of unknown role left as written
    /// (`M19 R#2`): a parameter it reads that the conversion scales is refused.
    left_word: bool,
    loops: bool,
    length: Ratio,
    feed: Ratio,
    speed: Ratio,
    noted: Vec<u8>,
    /// Buffers of words written before, cleared, and the vector of a block's changed words:
    /// kept from block to block.
    spare: Vec<Vec<u8>>,
    replacements: Vec<Option<Vec<u8>>>,
    /// The roles the block's cycle gives its words (see [`cycle_roles`]), by letter.
    cycle: [Option<Role>; 26],
    /// LinuxCNC: the motion mode in force as rs274ngc keeps it, in tenths of a G code
    /// (`meaning::linuxcnc_motion_code`), in the order of the text; None where it is unknown:
    /// at the start, and after o-word flow, a call or a definition.
    linuxcnc_motion: Option<i64>,
    /// The block's letters (bit `letter - b'A'`) that the meaning table or the polar mode
    /// make an angle, a direction or a factor: no count of the cycle table (`meaning.rs`).
    angles: u32,
    /// Whether the program being converted (since the file's start or the last M02, M30 or
    /// M99) has selected G90 or G91 itself.
    own_distance: bool,
    /// Its first axis word before that, under a change of units: `(word, line, column)`. An
    /// M99 ending the program makes it a subprogram, whose distance mode is the caller's.
    inherited: Option<(String, usize, usize)>,
    /// The program selected G96 or G97 itself: its S words are read in its own spindle mode.
    own_spindle: bool,
    /// An S word written before the program selected G96 or G97 (its text, line, column): a
    /// subprogram's is a surface speed or a spindle speed by its caller's mode, which the text
    /// does not show ([`Converter::inherited_speed`]).
    inherited_speed: Option<(String, usize, usize)>,
    /// The block's S limits the spindle's speed (G50 S on a lathe, G92 S on a mill whose G92
    /// clamps, a SINUMERIK's G25/G26 S: `ModalSettings::s_limit`, the check's and the
    /// restart's rule): revolutions per minute in either units, never a surface speed.
    s_limit: bool,
    /// Where the file's next program begins (the checker's split of a file into programs).
    split: ProgramSplit,
    /// Where a LinuxCNC file stops being read (`dialect::ReadingEnd`): the lines after are
    /// written as they are.
    reading_end: ReadingEnd,
    /// The lines not read have been said (once a file) under a change of units.
    unread_noted: bool,
    /// A sequence number past the target's N format has been said (once a file: the first).
    long_sequence_noted: bool,
    /// FANUC's G10 L50 / G10 L3 data input mode (`dialect::DataInput`): its blocks are
    /// parameter and tool life data, written as they are.
    data_input: DataInput,
    /// The thread lead word of the block being converted (F of a FANUC or Haas lathe's
    /// G32/G76/G92 or a mill's G33, K of LinuxCNC's or ISO's G33), and its value exact and as
    /// rounded in the target's units where the conversion rounded it: said in a note, since
    /// a lead's error builds up over every revolution of the thread.
    lead_watch: Option<u8>,
    lead_rounded: Option<(f64, f64)>,
    /// A cycle that returns to its start point (G70-G89, a lathe's G92, G33.1) ran since the
    /// last block that set Z: the tracked Z is its end, not where the tool is.
    z_after_cycle: bool,
    /// The parameters whose assignment of a number this conversion rounded, by name: (its
    /// line, the assignment as written, as converted). Where one is then compared in a
    /// condition (`WHILE [#1 LE #2]`, `IF [..] GOTO`) or added to a parameter that adds
    /// itself (`#1=#1+#3`), a note says so: a loop's bound and step rounded each on its own
    /// may change how many times it runs, and a step's rounding builds up at every pass.
    rounded_params: FastMap<String, (usize, String, String)>,
    /// Under a change of units, each length parameter's first use (set or read as a length):
    /// the length factor then, its line and the source's units. Its one value is converted
    /// once, by that factor; a use under another (after a mid-program G20/G21, G70/G71) reads
    /// it in units it no longer has ([`Converter::length_use`]).
    length_uses: FastMap<String, (Ratio, usize, Units)>,
    /// Under a change of units, each length parameter set before any read of it: the length
    /// factor of its first assignment, its line, the source's units there, and whether a later
    /// assignment before the read had another factor ([`Converter::set_length`]).
    set_before_read: FastMap<String, (Ratio, usize, Units, bool)>,
    /// The units of the first read of the parameters whose assignments before it were
    /// converted by another factor: (program, name, units), for a conversion made again
    /// ([`ConvertConfig::read_units`]).
    learned: Vec<(usize, String, Units)>,
    /// The program of the file being converted (0 for the first): its entry in the parameter
    /// analysis ([`ConvertConfig::parameters`]).
    program: usize,
    /// Under a change of units, a program of the file whose start units differ from those the
    /// program before it leaves in force: (its first line, those units, its start units). Run
    /// as a subprogram of the program before, it is in the first, run on its own in the
    /// second: one that moves before it selects its units cannot be read.
    program_doubt: Option<(usize, Units, Units)>,
    /// SINUMERIK and Okuma OSP subprograms of the file called by name, and their calls
    /// ([`named`]).
    named: named::NamedPrograms,
    /// Where the target has no motion mode in force and the source has one: the line of the
    /// G80 that ended it, or 0 at the start of the program (see `target_g80_clears_motion`).
    target_no_motion: Option<usize>,
    /// The line of the program number that began the program being converted, after the
    /// file's first program.
    program_line: Option<usize>,
    /// The line of the LinuxCNC `o<name> sub` whose body is being converted: its own
    /// parameters are its own in the analysis ([`crate::statement::scoped_name`]).
    sub: Option<usize>,
    /// Under a change of units, the units of LinuxCNC subroutine bodies and their calls
    /// ([`crate::sub_units`]); and, while a body is read, the caller's units to go on in after
    /// its `endsub` (the source's lengths and feed, the target's lengths and feed): the body
    /// is skipped where it stands.
    bodies: crate::sub_units::Bodies,
    body_caller: Option<(Units, Units, Units, Units)>,
    /// By axis, a SINUMERIK `X=IC(..)` whose conversion rounded, since the axis's last absolute
    /// position: (its line, the word). Such an increment is converted on its own, not against
    /// the positions as a G91 word is, so a second one adds its rounding to the first's
    /// ([`Converter::dimension_rounding`]).
    ic_rounded: [Option<(usize, String)>; 26],
    /// The terms of the expression being converted, its lists kept from one to the next.
    terms: expr::Terms,
    /// The G and M codes of the block ([`Converter::block`]), their vectors kept from block
    /// to block.
    codes: (Vec<i64>, Vec<i64>),
    /// The expression shapes whose parameters [`Converter::expression_with`] looked at and
    /// found nothing to refuse or note, by the shape's number ([`expr::Terms::shape`]) modulo
    /// [`SHAPE_USES`]: see [`ShapeUse`].
    shape_uses: [Option<ShapeUse>; SHAPE_USES],
    /// The vector of a line's words ([`Converter::convert_line`]), kept from line to line.
    spans: Vec<WordSpan<'static>>,
    /// The largest rounding per address, as an exact fraction `(letter, e, d)`.
    pub worst: Vec<(u8, i128, i128)>,
    /// Each address's place in [`Converter::worst`], plus one (0: none yet): every rounded
    /// word looks its address up, a lookup instead of a walk of the list.
    worst_at: [u16; 256],
    pub blocks: usize,
    pub words: usize,
    pub changed: usize,
    /// The notes made and not yet taken ([`Converter::take_notes`]): a caller that takes them
    /// as it goes (the file converter, after each chunk) holds none of a long program's.
    pub notes: Vec<String>,
    /// The words, statements and parameters left as written where the units change
    /// (`--allow-unconverted`: a word of unknown role, a value left unconverted, a macro
    /// call's arguments), each named in a note. A proof reads them as written on both sides,
    /// so it cannot say they move as in the source (`X#1` with `#1=10.` kept is 10 in where
    /// it was 10 mm): `convert --verify` says "partly verified" for any. Counted here, where
    /// they are left, and not from the notes' wording.
    pub left_as_written: Left,
    /// The lines after the program's end that the control never reads, left as written where
    /// the units change: no word the control runs, so not in `left_as_written`.
    pub never_read: Left,
    /// A target that selects its units by a machine parameter: the units the first note
    /// "set the machine to" named, those the output is to be read in (`convert --verify`).
    pub machine_units: Option<Units>,
    /// The notes without a line made, to say each once: a set, not a search of `notes` (a
    /// program with a note per word made that quadratic). Their number is bounded by the
    /// program's addresses, parameters and ends, not by its length.
    noted_once: HashSet<String>,
    /// The codes neither machine's table lists that a note has named (once per conversion:
    /// a builder's M code stands at every tool change).
    unlisted_noted: Vec<String>,
    /// The notes of one line ([`Converter::note_line`]), to say each once on that line: a
    /// note naming its line is made again only on the same line, so the set is cleared when
    /// the line changes and memory does not grow with the notes (a note per word on 1,000,000
    /// blocks of LinuxCNC's 3D_Chips kept 2 million strings twice).
    line_noted: (usize, Vec<String>),
}

/// What a conversion left as written: how many, and where the first one is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Left {
    pub count: usize,
    /// How many of `count` are whole statements (`DPRNT[...]`, `CYCLE81(...)`), not words:
    /// the summary names each kind by its own name.
    pub statements: usize,
    /// The first one's line and column (1-based).
    pub first: Option<(usize, usize)>,
}

impl Left {
    fn add(&mut self, line: usize, column: usize) {
        self.count += 1;
        self.first.get_or_insert((line, column));
    }
}

/// An expression shape whose parameters were looked at, and under what. An expression of a
/// shape read before reads the same parameters, by the same text ([`expr::Terms::shape`]):
/// each one's class is the same in the same program and subroutine, and each length among
/// them was used under this length factor ([`Converter::length_use`] recorded it, and a use
/// under the same factor adds nothing). So a word of a shape looked at under the same key
/// has nothing to refuse, note or record, and its parameters are not looked up again
/// (3D_Chips: every line's `X[#<xscale>*..]`, `Y[#<yscale>*..]`). A new program clears the
/// uses the key's `program` holds; a mid-program units code changes `length`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct ShapeUse {
    shape: u64,
    program: usize,
    sub: Option<usize>,
    factor: Ratio,
    length: Ratio,
    is_param: bool,
}

/// The shapes [`Converter::shape_uses`] keeps, one a slot.
const SHAPE_USES: usize = 16;

/// The parts of a word's plain number, as [`plain`] reads them, taken from where the
/// tokenizer found them ([`WordSpan::plain`]) without reading the word again.
fn plain_word<'t>(w: &WordSpan<'t>) -> Option<PlainNumber<'t>> {
    let Some(sign) = w.plain else {
        return plain(w.token);
    };
    let token = w.token;
    let number = &token[1 + usize::from(sign)..];
    // (the point where the tokenizer found it: the number is not walked again)
    let p = w.digits.dot as usize;
    let (whole, dot, fraction) = match number.get(p + 1..) {
        Some(fraction) => (&number[..p], true, fraction),
        None => (number, false, &b""[..]),
    };
    let signed = |c: u8| sign == 1 && token[1] == c;
    Some((signed(b'-'), signed(b'+'), whole, dot, fraction))
}

/// `10^n` for the exponents a `u64` holds.
const SMALL_POW10: [u64; 20] = {
    let mut p = [1u64; 20];
    let mut i = 1;
    while i < 20 {
        p[i] = p[i - 1] * 10;
        i += 1;
    }
    p
};

/// An empty vector of word spans of another lifetime, in the allocation of `spans` (a
/// collect from a vector's own iterator into elements of the same size reuses it).
fn reuse<'b>(mut spans: Vec<WordSpan<'_>>) -> Vec<WordSpan<'b>> {
    spans.clear();
    spans.into_iter().map(|_| unreachable!()).collect()
}

/// Whether the fraction `e / d` is no larger than `we / wd` (all four positive), where the
/// products can be formed: in 64-bit factors and a 128-bit product where they fit (nearly
/// every rounding: a word's error against the largest kept, made for each rounded word),
/// else with 128-bit checked products; None where those overflow.
fn no_larger(e: i128, d: i128, we: i128, wd: i128) -> Option<bool> {
    if let (Ok(e), Ok(d), Ok(we), Ok(wd)) = (
        u64::try_from(e),
        u64::try_from(d),
        u64::try_from(we),
        u64::try_from(wd),
    ) {
        return Some(u128::from(e) * u128::from(wd) <= u128::from(we) * u128::from(d));
    }
    Some(e.checked_mul(wd)? <= we.checked_mul(d)?)
}

/// The parameters an expression or a statement reads, as written: `#12`, `#<depth>`, and a
/// SINUMERIK's R parameter `R12` (an R then digits, not inside a name: `WHILE R3<=R1`).
fn parameter_names(text: &[u8]) -> Vec<Vec<u8>> {
    let mut names = Vec::new();
    let mut i = 0;
    while i < text.len() {
        if let Some((digits, parameter)) = expr::r_parameter_at(text, i) {
            if parameter {
                names.push(text[i..i + 1 + digits].to_vec());
            }
            i += 1 + digits;
            continue;
        }
        if text[i] != b'#' {
            i += 1;
            continue;
        }
        let start = i;
        i += 1;
        if text.get(i) == Some(&b'<') {
            match text[i..].iter().position(|&c| c == b'>') {
                Some(end) => i += end + 1,
                None => break,
            }
        } else {
            while i < text.len() && text[i].is_ascii_digit() {
                i += 1;
            }
            if i == start + 1 {
                continue; // `#[..]`, `##1`: chosen by a value
            }
        }
        names.push(text[start..i].to_vec());
    }
    names
}

/// The first read of the parameter that tells a `family`'s units in `text`: its offset and
/// its name as written ([`Converter::units_flag`]). On a Custom Macro B control, a parameter
/// chosen by a value ([`macro_b_indirect_flag`]) counts too.
fn units_flag_read(piece: &[u8], family: Family) -> Option<(usize, String)> {
    // every form below begins with `#` (Macro B, LinuxCNC) or `$` (SINUMERIK): nearly every
    // word of a program has neither, and is passed over without a copy or a scan of its names
    let marker = if family == Family::Sinumerik {
        b'$'
    } else {
        b'#'
    };
    memchr::memchr(marker, piece)?;
    match family {
        Family::LinuxCnc => {
            // (the word as written, its name compared in either case: no upper-case copy of
            // every word that reads a parameter, and no copy of each name)
            for at in memchr::memchr_iter(b'#', piece) {
                let rest = &piece[at + 1..];
                let Some(open) = rest.iter().position(|&c| !crate::lex::blank(c)) else {
                    continue;
                };
                if rest[open] != b'<' {
                    continue;
                }
                let Some(close) = rest[open..].iter().position(|&c| c == b'>') else {
                    continue;
                };
                let name = rest[open + 1..open + close]
                    .iter()
                    .filter(|&&c| !crate::lex::blank(c));
                let is = |flag: &[u8]| {
                    let mut name = name.clone();
                    flag.iter()
                        .all(|f| name.next().is_some_and(|c| c.eq_ignore_ascii_case(f)))
                        && name.next().is_none()
                };
                if is(b"_METRIC") || is(b"_IMPERIAL") {
                    return Some((at, text(&piece[at..at + 1 + open + close + 1])));
                }
            }
            None
        }
        Family::MacroB => parameter_names(piece)
            .into_iter()
            .find_map(|raw| {
                let n = integer(raw.get(1..)?)?;
                let at = memchr::memmem::find(piece, &raw)?;
                matches!(n, 4006 | 4206).then(|| (at, format!("#{n}")))
            })
            .or_else(|| macro_b_indirect_flag(piece)),
        Family::Sinumerik => {
            let upper = piece.to_ascii_uppercase();
            let at = memchr::memmem::find(&upper, b"$P_GG")?;
            let rest: Vec<u8> = upper[at + 5..]
                .iter()
                .copied()
                .filter(|&c| !crate::lex::blank(c))
                .collect();
            let group = rest
                .strip_prefix(b"[")
                .and_then(|r| r.iter().position(|&c| c == b']').map(|end| &r[..end]));
            let other_group = group.is_some_and(|g| {
                !g.is_empty() && g.iter().all(u8::is_ascii_digit) && integer(g) != Some(13)
            });
            (!other_group).then(|| (at, "$P_GG[13] (the units group)".to_string()))
        }
        _ => None,
    }
}

/// A Custom Macro B parameter read by a value that is, or may be, the units flag: `#[4006]`
/// is #4006 (a bracketed number names its variable: FANUC Custom Macro B, "Variables", `#[#1]`
/// the variable numbered by #1's value), and one numbered by anything but a number
/// (`#[#1]`, `#[4000+6]`, `##1`) cannot be shown not to be #4006 or #4206: its offset and
/// name as [`units_flag_read`] gives them. The target of an assignment (`#[#1]=5`) is no read.
fn macro_b_indirect_flag(piece: &[u8]) -> Option<(usize, String)> {
    let target_end = expr::indirect_target(piece).map_or(0, |eq| eq + 1);
    for at in memchr::memchr_iter(b'#', &piece[target_end..]).map(|i| i + target_end) {
        let Some(open) = piece[at + 1..].iter().position(|&c| !crate::lex::blank(c)) else {
            continue;
        };
        let open = at + 1 + open;
        match piece[open] {
            b'#' => {
                return Some((
                    at,
                    format!("{} (a variable chosen by a value)", text(&piece[at..=open])),
                ))
            }
            b'[' => {
                let mut depth = 0usize;
                let close = piece[open..].iter().position(|&c| {
                    match c {
                        b'[' => depth += 1,
                        b']' => depth -= 1,
                        _ => {}
                    }
                    depth == 0
                });
                let inside = &piece[open + 1..close.map_or(piece.len(), |c| open + c)];
                let digits: Vec<u8> = inside
                    .iter()
                    .copied()
                    .filter(|&c| !crate::lex::blank(c))
                    .collect();
                match integer(&digits) {
                    Some(n @ (4006 | 4206)) => return Some((at, format!("#{n}"))),
                    Some(_) => continue,
                    None => {
                        let end = close.map_or(piece.len(), |c| open + c + 1);
                        return Some((
                            at,
                            format!("{} (a variable chosen by a value)", text(&piece[at..end])),
                        ));
                    }
                }
            }
            _ => {}
        }
    }
    None
}

/// A small positive number for a note, to three significant digits: 0.0000449, 0.0091.
fn significant(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return "0".into();
    }
    let decimals = (2 - value.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{value:.decimals$}");
    if !text.contains('.') {
        return text;
    }
    let text = text.trim_end_matches('0');
    text.strip_suffix('.').unwrap_or(text).to_string()
}

/// A number for a note: at most seven decimals, no trailing zeros.
fn trim_float(value: f64) -> String {
    let text = format!("{value:.7}");
    let text = text.trim_end_matches('0');
    text.strip_suffix('.').unwrap_or(text).to_string()
}

/// A profile's word format of each letter A-Z in metric and in inch, as [`format_in`] finds it
/// in the lists, looked up once for a conversion: every word of every block asks for its
/// letter's, in the source's and in the target's formats (other addresses, `@` and `#`, are
/// looked up in the lists).
struct FormatTable([[Option<WordFormat>; 26]; 2]);

impl FormatTable {
    fn new(formats: &[(u8, WordFormat)], inch: Option<&[(u8, WordFormat)]>) -> FormatTable {
        let of = |units| {
            std::array::from_fn(|i| format_in(formats, inch, b'A' + i as u8, units).cloned())
        };
        FormatTable([of(Units::Metric), of(Units::Inch)])
    }

    /// [`format_in`] of these lists, the ones the table was made of.
    fn get<'a>(
        &'a self,
        formats: &'a [(u8, WordFormat)],
        inch: Option<&'a [(u8, WordFormat)]>,
        letter: u8,
        units: Units,
    ) -> Option<&'a WordFormat> {
        if !letter.is_ascii_uppercase() {
            return format_in(formats, inch, letter, units);
        }
        self.0[usize::from(units == Units::Inch)][usize::from(letter - b'A')].as_ref()
    }
}

/// [`reads_whole`] and [`reads_increments`] of a profile's list of the letters it reads whole,
/// for every byte, looked up once: a conversion asks them of every word, several times, and
/// `contains` on the list is a call each time.
struct WholeLetters {
    whole: [bool; 256],
    increments: [bool; 256],
}

impl WholeLetters {
    fn new(list: Option<&[u8]>) -> WholeLetters {
        WholeLetters {
            whole: std::array::from_fn(|b| reads_whole(list, b as u8)),
            increments: std::array::from_fn(|b| reads_increments(list, b as u8)),
        }
    }

    fn whole(&self, letter: u8) -> bool {
        self.whole[usize::from(letter)]
    }

    fn increments(&self, letter: u8) -> bool {
        self.increments[usize::from(letter)]
    }
}

fn slot(letter: u8) -> usize {
    (letter.to_ascii_uppercase().wrapping_sub(b'A') as usize).min(25)
}

impl Converter {
    pub fn new(c: ConvertConfig) -> Converter {
        let uw_moves = UwMoves::new(c.lathe, c.family, c.src_modal.g_system);
        let mut modal = ModalMachine::new(ModalSettings {
            // the lathe's G50 S and G98/G99 change no factor of a conversion (F per minute and
            // per revolution both scale with the length unit)
            fanuc_lathe: false,
            ..c.src_modal.clone()
        });
        // the converter follows positions across a units code itself (`tracked_across_units`)
        modal.units_convert_position = false;
        let src_units = modal.state.units;
        let src_feed_units = modal.state.feed_units;
        // the output starts as the target control does: lengths and feed in its basic system,
        // unless the conversion selects other units for both before the first value
        let out_feed_units = if c.target_family == Family::Sinumerik {
            c.target_units
        } else {
            c.units.unwrap_or(src_feed_units)
        };
        let out_length_units = c.target_units;
        let family = c.family;
        let src_table = FormatTable::new(&c.src_formats, c.src_formats_inch.as_deref());
        let out_table = FormatTable::new(&c.out_formats, c.out_formats_inch.as_deref());
        let src_letters = WholeLetters::new(c.src_increments.as_deref());
        let dst_letters = WholeLetters::new(c.dst_increments.as_deref());
        let mut converter = Converter {
            c,
            src_table,
            out_table,
            src_letters,
            dst_letters,
            modal,
            src_units,
            src_feed_units,
            out_feed_units,
            out_length_units,
            units_seen: false,
            lacked_in_force: None,
            cycle_code: Repeat::default(),
            ended_on: None,
            units_doubt: None,
            flow: crate::units_flow::UnitsFlow::default(),
            feed_flow: None,
            flow_caller: None,
            flow_after_call: None,
            jumped_in: false,
            saved_units: None,
            reset_units: src_units,
            cycle: [None; 26],
            linuxcnc_motion: None,
            angles: 0,
            own_distance: false,
            inherited: None,
            own_spindle: false,
            inherited_speed: None,
            s_limit: false,
            src_pos: [None; 26],
            out_pos: [None; 26],
            abs_raw: [None; 26],
            pos_units: [None; 26],
            out_at: [None; 26],
            out_mm: [None; 26],
            uw_moves,
            uw_own_noted: false,
            feed_mode_written: false,
            leader_passed: false,
            polar_interpolation: false,
            c_axis: false,
            rounded: false,
            rounded_step: None,
            left_word: false,
            loops: false,
            length: ONE,
            feed: ONE,
            speed: ONE,
            noted: Vec::new(),
            spare: Vec::new(),
            replacements: Vec::new(),
            worst: Vec::new(),
            worst_at: [0; 256],
            blocks: 0,
            words: 0,
            changed: 0,
            notes: Vec::new(),
            left_as_written: Left::default(),
            never_read: Left::default(),
            machine_units: None,
            noted_once: HashSet::new(),
            unlisted_noted: Vec::new(),
            split: ProgramSplit::default(),
            reading_end: ReadingEnd::new(family),
            unread_noted: false,
            long_sequence_noted: false,
            data_input: DataInput::default(),
            lead_watch: None,
            lead_rounded: None,
            z_after_cycle: false,
            rounded_params: FastMap::default(),
            length_uses: FastMap::default(),
            set_before_read: FastMap::default(),
            learned: Vec::new(),
            program: 0,
            program_line: None,
            sub: None,
            bodies: crate::sub_units::Bodies::default(),
            body_caller: None,
            ic_rounded: Default::default(),
            program_doubt: None,
            named: named::NamedPrograms::default(),
            target_no_motion: None,
            line_noted: (0, Vec::new()),
            terms: expr::Terms::default(),
            codes: (Vec::new(), Vec::new()),
            shape_uses: [None; SHAPE_USES],
            spans: Vec::new(),
        };
        converter.target_no_motion = converter.motion_differs().then_some(0);
        converter.set_factor();
        converter
    }

    /// A program of the file after the end of another (`dialect::ProgramSplit`: an O number
    /// or a folder marker after M02, M30 or M99) is converted as its own program, as if it
    /// were a file of its own: from the source's reset state in its start units, no position
    /// known, its units looked at afresh; and the target control in its own start units.
    fn start_program(&mut self, line: usize) {
        // the units the program before leaves in force: those a subprogram it calls runs in
        let caller = self.modal.state.units;
        let fresh = Converter::new(self.c.clone());
        self.program_doubt = (self.c.units.is_some() && caller != fresh.src_units).then_some((
            line,
            caller,
            fresh.src_units,
        ));
        self.modal = fresh.modal;
        self.src_units = fresh.src_units;
        self.src_feed_units = fresh.src_feed_units;
        self.out_feed_units = fresh.out_feed_units;
        self.out_length_units = fresh.out_length_units;
        self.units_seen = false;
        self.lacked_in_force = None;
        self.ended_on = None;
        self.units_doubt = None;
        self.flow.reset();
        self.feed_flow = None;
        self.flow_after_call = None;
        self.jumped_in = false;
        self.saved_units = None;
        self.cycle = [None; 26];
        self.program_line = Some(line);
        self.length_uses.clear();
        self.set_before_read.clear();
        self.target_no_motion = self.motion_differs().then_some(0);
        self.data_input = DataInput::default();
        self.fresh_program();
        self.set_factor();
    }

    /// A parameter's name as the parameter analysis lists it: without blanks, a LinuxCNC
    /// named parameter in lower case, a subroutine's own parameter by its subroutine.
    fn parameter(&self, raw: &[u8]) -> String {
        crate::statement::scoped_name(crate::statement::parameter_name(raw), self.sub)
    }

    /// The class of the parameter written `raw` in the program being converted, by its
    /// [`Converter::parameter`] name (built only where the text is not that name already: a
    /// word a block reads it in); None where the analysis proved it no length, or there is none.
    fn class(&self, raw: &[u8]) -> Option<&ParameterClass> {
        let classes = self.c.parameters.as_ref()?;
        let scoped = self.sub.is_some() && crate::statement::sub_local(raw);
        if !scoped && raw.is_ascii() && crate::statement::is_parameter_name(raw) {
            return classes.class(self.program, raw);
        }
        classes.class(self.program, self.parameter(raw).as_bytes())
    }

    /// A Custom Macro B `IF [..] GOTO n`, `IF [..] THEN #i = ..` or `WHILE [..] DOm` whose
    /// numbers are surely no lengths, so it is kept as written: each comparison of its condition
    /// (the parts between AND, OR and XOR) reads a parameter, every parameter the condition
    /// reads is a system variable that FANUC's and Haas's tables both give a meaning that is no
    /// length (#4003, the G code of group 3: [`crate::dialect::system_not_length`]), every one
    /// the THEN assignment reads or sets is one the analysis proved no length (#3000, the
    /// alarm: `IF [#4003 EQ 91] THEN #3000 = 2`), and none is chosen by a value (`#[..]`,
    /// `##`). A local or common variable in a condition is not enough: its value may be a
    /// caller's length (a G65 argument), which the condition's number would then be compared
    /// with in the other units; such a statement, and any other holding a number, is refused
    /// by the caller.
    fn macro_b_condition_kept(&self, statement: &[u8]) -> bool {
        if self.c.family != Family::MacroB || self.c.parameters.is_none() {
            return false;
        }
        let upper = statement.to_ascii_uppercase();
        let head = upper.trim_ascii_start();
        if !(head.starts_with(b"IF") || head.starts_with(b"WHILE")) {
            return false;
        }
        let (Some(open), Some(close)) = (
            upper.iter().position(|&c| c == b'['),
            upper.iter().rposition(|&c| c == b']'),
        ) else {
            return false;
        };
        let (condition, rest) = (&upper[open + 1..close], upper[close + 1..].trim_ascii());
        // after the condition: a jump, a loop's DOm, or THEN and one assignment
        let tail_ok = if let Some(assignment) = rest.strip_prefix(b"THEN") {
            assignment.contains(&b'=')
        } else {
            rest.starts_with(b"GOTO") || rest.starts_with(b"DO")
        };
        if !tail_ok {
            return false;
        }
        let mut depth = 0usize;
        let mut part_start = 0usize;
        let mut parts = Vec::new();
        for (i, &c) in condition.iter().enumerate() {
            match c {
                b'[' => depth += 1,
                b']' => depth = depth.saturating_sub(1),
                _ if depth == 0 => {
                    let at = &condition[i..];
                    let joined = [&b"AND"[..], b"OR", b"XOR"].iter().any(|op| {
                        at.starts_with(op)
                            && (i == 0 || !condition[i - 1].is_ascii_alphabetic())
                            && at.get(op.len()).is_none_or(|c| !c.is_ascii_alphabetic())
                    });
                    if joined {
                        parts.push(&condition[part_start..i]);
                        part_start = i + 3;
                    }
                }
                _ => {}
            }
        }
        parts.push(&condition[part_start.min(condition.len())..]);
        if !parts.iter().all(|part| part.contains(&b'#')) {
            return false;
        }
        // every parameter read or set: proved no length, none chosen by a value
        let mut i = 0;
        while let Some(at) = upper[i..].iter().position(|&c| c == b'#') {
            let mut j = i + at + 1;
            while upper.get(j).is_some_and(|&c| c == b' ' || c == b'\t') {
                j += 1;
            }
            let digits = upper[j..].iter().take_while(|c| c.is_ascii_digit()).count();
            if digits == 0 {
                return false; // #[..], ##, or a name this family does not have
            }
            let mut name = Vec::with_capacity(digits + 1);
            name.push(b'#');
            name.extend_from_slice(&upper[j..j + digits]);
            let in_condition = j < close;
            let number = std::str::from_utf8(&name[1..])
                .ok()
                .and_then(|d| d.parse().ok());
            let no_length = number.is_some_and(|n| {
                [false, true]
                    .iter()
                    .all(|&haas| crate::dialect::system_not_length(haas, n).is_some())
            });
            if (in_condition && !no_length) || self.class(&name).is_some() {
                return false;
            }
            i = j + digits;
        }
        true
    }

    /// Why the class of the parameter written `raw` cannot be proved, where it cannot.
    fn unproved(&self, raw: &[u8]) -> Option<String> {
        match self.class(raw) {
            Some(ParameterClass::Unproved(why)) => Some(why.clone()),
            _ => None,
        }
    }

    /// The parameter analysis split the file where this converter does ([`ProgramStarts`]
    /// mirrors [`Converter::block`]'s split): a program begun where the analysis saw none, or
    /// one the analysis saw begin that has not, would convert a program's parameters by the
    /// classes of another, so it is refused rather than converted so.
    fn same_programs(&self, line: usize) -> Result<(), ConvertError> {
        let Some(programs) = &self.c.parameters else {
            return Ok(());
        };
        let begun = self.program_line == Some(line);
        let this = programs.starts.get(self.program).copied();
        let next = programs.starts.get(self.program + 1).copied();
        let agrees = match (begun, this) {
            (true, Some(start)) => start == line && next.is_none_or(|n| n > line),
            (true, None) => false,
            (false, _) => next.is_none_or(|n| n > line),
        };
        if agrees {
            return Ok(());
        }
        Err(error(
            format!(
                "the parameter analysis and the conversion split the file's programs \
                 differently at line {line}; convert each program on its own"
            ),
            "6.4.7",
        ))
    }

    /// The conversion factors follow the source's units as its modal state changes them (a
    /// units code, or the reset after M02/M30).
    fn follow_units(&mut self) {
        let state = &self.modal.state;
        if state.units != self.src_units || state.feed_units != self.src_feed_units {
            self.src_units = state.units;
            self.src_feed_units = state.feed_units;
            self.set_factor();
        }
    }

    /// The units code written for a source units code (or inserted, `all` false): on a
    /// Sinumerik target, G700/G710 where the source set the feed's units too, G70/G71 where it
    /// set those of lengths only; and the units of the output's feed after it.
    fn out_units_code(&mut self, all: bool) -> String {
        let units = self.out_units();
        let sinumerik = self.c.target_family == Family::Sinumerik;
        let code = if all && sinumerik {
            if units == Units::Inch { "G700" } else { "G710" }.to_string()
        } else {
            self.units_code()
        };
        self.out_feed_units = if sinumerik && !all {
            self.c.target_units
        } else {
            units
        };
        self.out_length_units = units;
        self.set_factor();
        code
    }

    fn incremental(&self) -> bool {
        self.modal.state.incremental
    }

    /// A note that names no line (or not the current block's), said once per conversion:
    /// whether it was new.
    pub fn note(&mut self, note: String) -> bool {
        let new = self.noted_once.insert(note.clone());
        if new {
            self.notes.push(note);
        }
        new
    }

    /// A note that names `line`, the current block's, said once: only the same line can make
    /// it again, so only that line's notes are remembered.
    fn note_line(&mut self, line: usize, note: String) -> bool {
        let (noted_line, noted) = &mut self.line_noted;
        if *noted_line != line {
            *noted_line = line;
            noted.clear();
        }
        let new = !noted.contains(&note);
        if new {
            noted.push(note.clone());
            self.notes.push(note);
        }
        new
    }

    /// A word, statement or parameter at `line`:`column` left as written, its note `note`
    /// (said once on its line): counted in [`Converter::left_as_written`] where the units
    /// change there (a word kept where they do not is the same number on both sides).
    fn left_line(&mut self, line: usize, column: usize, note: String) -> bool {
        let counted = self.note_line(line, note) && self.length != ONE;
        if counted {
            self.left_as_written.add(line, column);
        }
        counted
    }

    /// The note of a word of unknown role left exactly as written (--allow-unconverted), by
    /// its line and column: the operator finds the one X still in the source's units.
    fn left_note(&mut self, b: &BlockIn<'_>, i: usize) {
        let w = &b.words[i];
        let column = crate::text::column(b.text, w.start);
        self.left_line(
            b.line,
            column,
            format!(
                "line {}:{column}: {} left as written (its role here is not known; \
                 --allow-unconverted)",
                b.line,
                text(w.token)
            ),
        );
    }

    /// The notes made since the last call, in the order made (the caller says them; they are
    /// not kept).
    pub fn take_notes(&mut self) -> Vec<String> {
        std::mem::take(&mut self.notes)
    }

    fn out_units(&self) -> Units {
        self.c.units.unwrap_or(self.src_units)
    }

    fn set_factor(&mut self) {
        (self.length, self.speed) = match (self.src_units, self.out_units()) {
            (a, b) if a == b => (ONE, ONE),
            (_, Units::Inch) => ((5, 127), (1250, 381)),
            _ => ((127, 5), (381, 1250)),
        };
        self.feed = match (self.src_feed_units, self.out_feed_units) {
            (a, b) if a == b => ONE,
            (_, Units::Inch) => (5, 127),
            _ => (127, 5),
        };
    }

    /// The factor of a surface speed (S under G96): m/min and ft/min follow the units of
    /// lengths, but not on a SINUMERIK, whose G70/G71 set "all geometric parameters that
    /// directly refer to the workpiece" and leave every other value, feeds among them, in the
    /// basic system (SINUMERIK 802D sl Programming, 8.2.3 "Dimensions in metric units and
    /// inches: G71, G70, G710, G700"; the 840D's Fundamentals, "Inch or metric dimensions"):
    /// there the cutting rate is in the basic system (probe P3-13: `G96 S200` written S656
    /// under G70, 3.3 times the speed). G700/G710 also set "the feedrate F"; whether they set
    /// the cutting rate no source at hand says, so a surface speed converted with a SINUMERIK
    /// side under G700/G710 (its feed out of the basic system) is refused.
    fn cutting_rate_factor(&self) -> Result<Ratio, ConvertError> {
        let src_sinumerik = self.c.family == Family::Sinumerik;
        let out_sinumerik = self.c.target_family == Family::Sinumerik;
        if !src_sinumerik && !out_sinumerik {
            return Ok(self.speed);
        }
        let unknown = (src_sinumerik && self.src_feed_units != self.c.src_modal.default_units)
            || (out_sinumerik && self.out_feed_units != self.c.target_units);
        let src = if src_sinumerik {
            self.c.src_modal.default_units
        } else {
            self.src_units
        };
        let out = if out_sinumerik {
            self.c.target_units
        } else {
            self.out_units()
        };
        let factor = match (src, out) {
            (a, b) if a == b => ONE,
            (_, Units::Inch) => (1250, 381),
            _ => (381, 1250),
        };
        if unknown && (factor != ONE || self.speed != ONE) {
            return Err(error(
                "a surface speed (S under G96) where a SINUMERIK's G700/G710 set the feed's \
                 units: G70/G71 leave the cutting rate in the basic system, but whether G700/G710 \
                 convert it no source at hand says, so its units cannot be converted; select \
                 G70/G71 around the G96 blocks, or convert the S by hand"
                    .into(),
                "units",
            ));
        }
        Ok(factor)
    }

    /// Whether the source and the target are FANUC (or Haas) lathes of two G code systems:
    /// each code is then written by the target's number ([`Converter::g_in_target`]). A source
    /// of system B or C for any other control keeps its codes as written, compared by meaning.
    fn renumbers(&self) -> bool {
        self.c.src_modal.fanuc_lathe
            && self
                .c
                .target_g_system
                .is_some_and(|to| to != self.c.src_modal.g_system)
    }

    fn target_system(&self) -> crate::meaning::GCodeSystem {
        self.c.target_g_system.unwrap_or_default()
    }

    /// Between two FANUC lathes of different G code systems (fanuc-lathe, -b, -c): what the
    /// target's system cannot say is refused at its word, before any word is written. System A
    /// has no G90/G91 (its increments are U and W) and no drilling cycles' return levels
    /// (G98/G99 of B and C); B and C program increments by G91, and the manuals at hand do not
    /// say their U and W are increments of X and Z (docs/dialects.md), so a U or W that moves
    /// (outside a dwell, G10 and the multiple repetitive cycles, whose U and W are their data)
    /// is refused for them; a code the source's system lacks, or one whose number the target
    /// system gives another function, is refused.
    fn between_g_systems(&self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        use crate::meaning::{GCodeSystem, NO_CODE};
        let (from, to) = (self.c.src_modal.g_system, self.target_system());
        let refuse = |w: &WordSpan<'_>, why: String| ConvertError {
            message: format!("{}: {why}", text(w.token)),
            clause: "codes",
            column: crate::text::column(b.text, w.start),
            line: None,
        };
        let name = |s: GCodeSystem| match s {
            GCodeSystem::A => "A",
            GCodeSystem::B => "B",
            GCodeSystem::C => "C",
        };
        let data_uw = gs.iter().any(|&g| matches!(g, 4 | 10 | 70..=76));
        for w in b.words {
            let letter = w.token[0].to_ascii_uppercase();
            if from == GCodeSystem::A && matches!(letter, b'U' | b'W') && !data_uw {
                return Err(refuse(
                    w,
                    format!(
                        "an increment of {} in G code system A; system {} programs increments \
                         by G91 and its manuals at hand do not say it reads U and W so: \
                         tapegate does not rewrite U W as G91 X Z, write the move in absolute X Z",
                        if letter == b'U' { "X" } else { "Z" },
                        name(to)
                    ),
                ));
            }
            if letter != b'G' {
                continue;
            }
            let Some(n) = self.code_of(w.token) else {
                continue;
            };
            let read = self.c.src_modal.read_g(n);
            if read == NO_CODE {
                // Two causes, two reasons: a number the source's code list lacks altogether
                // (B's G251, which no source at hand gives system B), or system A's number of
                // a function the source's system numbers otherwise (B's G32, whose threading
                // is B's G33).
                let why = if from.to_a(n) == NO_CODE {
                    "its function has another number there"
                } else {
                    "not in the source profile's code list"
                };
                return Err(refuse(
                    w,
                    format!(
                        "no code of G code system {} ({why}): the source control alarms on it",
                        name(from)
                    ),
                ));
            }
            // (B's and C's G90 for system A, which reads X Z absolute always: dropped, as every
            // G91 is refused)
            let absolute = read == crate::meaning::ABSOLUTE;
            if to.from_a(read).is_none() && !absolute {
                return Err(refuse(
                    w,
                    format!(
                        "G code system {} has no code for this code's function ({}); \
                         tapegate does not rewrite the program around it",
                        name(to),
                        crate::meaning::system_function(read)
                            .unwrap_or("its number is another function's in the target's system")
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A G word of the source's G code system as the target's system writes its function
    /// ([`Converter::between_g_systems`] refused what it cannot): `G77` of system B is `G90` of
    /// system A; `G92.1` of B and C is `G50.3` of A; B's and C's G90 is no word in system A.
    fn g_in_target(&self, token: &[u8]) -> Vec<u8> {
        use crate::meaning::GCodeSystem;
        let (from, to) = (self.c.src_modal.g_system, self.target_system());
        if let Some(tenths) = crate::lex::code_tenths(&token[1..]) {
            // (G50.3 of A is G92.1 of B and C: `GCodeSystem::tenths_to_a`)
            let out = to.tenths_from_a(from.tenths_to_a(tenths));
            if out == tenths || out == crate::meaning::NO_CODE {
                return token.to_vec();
            }
            return format!("{}{}.{}", token[0] as char, out / 10, out % 10).into_bytes();
        }
        let Some(n) = self.code_of(token) else {
            return token.to_vec();
        };
        let read = self.c.src_modal.read_g(n);
        if read == crate::meaning::ABSOLUTE && to == GCodeSystem::A {
            return Vec::new();
        }
        match to.from_a(read) {
            Some(out) if out != n => self.code_text(&format!("G{out:02}")).into_bytes(),
            _ => token.to_vec(),
        }
    }

    /// The target's code for the output's units; empty where no G code selects them on the
    /// target (`units_codes = "none"`: its machine parameter does).
    fn units_code(&self) -> String {
        let code = if self.out_units() == Units::Inch {
            &self.c.inch_code
        } else {
            &self.c.metric_code
        };
        if code.is_empty() {
            return String::new();
        }
        self.code_text(code)
    }

    /// A code as the target writes it: where it writes numbers without a decimal sign, its G
    /// format has decimals (G031, for G91.1) and it does not read G whole ([`reads_whole`]),
    /// the code's number counts the format's resolution as every other word's does (G21 is
    /// written G210), as the checker and `--verify` read it back.
    fn code_text(&self, code: &str) -> String {
        let (Some(&letter), Ok(n)) = (code.as_bytes().first(), code[1..].parse::<i128>()) else {
            return code.to_string();
        };
        let units = self.out_length_units;
        let inch = self.c.out_formats_inch.as_deref();
        format_in(&self.c.out_formats, inch, letter, units)
            .and_then(|fmt| implicit_code(letter, n, fmt, self.explicit_out(letter)))
            .map_or_else(
                || code.to_string(),
                |out| String::from_utf8_lossy(&out).into_owned(),
            )
    }

    /// Whether the source reads a word of `letter` without a point as a whole number: an
    /// explicit-decimal source, or a letter its control reads whole where it counts the others'
    /// increments ([`reads_whole`]).
    fn explicit_in(&self, letter: u8) -> bool {
        self.c.explicit_in || self.src_letters.whole(letter)
    }

    /// Whether the target writes a word of `letter` with its decimal point: an explicit-decimal
    /// target, or a letter it reads whole ([`reads_whole`]): a Fanuc given implicit decimals
    /// still reads G21 and F100 whole, so G20 is not written G200 nor 3.937 in/min F3937.
    fn explicit_out(&self, letter: u8) -> bool {
        self.c.explicit_out || self.dst_letters.whole(letter)
    }

    /// Whether a code or count word of `letter` is a number to read and write by its formats:
    /// its format has decimals in the source or the target, and one of them writes numbers
    /// without a decimal sign (N and O are counts whatever their format).
    fn decimal_count(&self, letter: u8) -> bool {
        if (self.explicit_in(letter) && self.explicit_out(letter)) || matches!(letter, b'N' | b'O')
        {
            return false;
        }
        let decimal = |formats: &[(u8, WordFormat)], inch: Option<&[(u8, WordFormat)]>, u| {
            format_in(formats, inch, letter, u).is_some_and(|f| f.decimal && f.after > 0)
        };
        decimal(
            &self.c.src_formats,
            self.c.src_formats_inch.as_deref(),
            self.src_units,
        ) || decimal(
            &self.c.out_formats,
            self.c.out_formats_inch.as_deref(),
            self.out_length_units,
        )
    }

    /// The number of a G or M code as the source control reads it: written with its decimal
    /// sign, or by its format where the source writes none (an implicit `G910` under G031 is
    /// G91); None for a code with a fraction (G91.1 is a code of its own) or not a number.
    fn code_of(&self, token: &[u8]) -> Option<i64> {
        let letter = token[0].to_ascii_uppercase();
        let numbers = Numbers {
            formats: &self.c.src_formats,
            formats_inch: self.c.src_formats_inch.as_deref(),
            explicit: self.c.explicit_in,
            increments: self.c.src_increments.as_deref(),
        };
        let inch = self.c.src_formats_inch.as_deref();
        match self
            .src_table
            .get(&self.c.src_formats, inch, letter, self.src_units)
        {
            Some(fmt) if !self.explicit_in(letter) && fmt.decimal && fmt.after > 0 => {
                let value = numbers.read(fmt, &Word::new(token, 0)).ok()?;
                value.is_whole().then(|| value.trunc())
            }
            _ => integer(&token[1..]),
        }
    }

    fn out_format(&mut self, letter: u8, dwell: bool) -> WordFormat {
        if dwell {
            if let Some((_, f)) = self.c.dwell_formats.iter().find(|(l, _)| *l == letter) {
                return f.clone();
            }
        } else if letter == b'F' && self.modal.state.feed_mode == 95 {
            // a feed per revolution by its own format where the target has one
            let inch = self.out_feed_units == Units::Inch;
            if let Some(f) = &self.c.feed_rev_formats[usize::from(inch)] {
                return f.clone();
            }
        }
        let units = units_of(letter, (self.out_units(), self.out_feed_units));
        let inch = self.c.out_formats_inch.as_deref();
        if let Some(f) = self.out_table.get(&self.c.out_formats, inch, letter, units) {
            return f.clone();
        }
        let fmt = WordFormat::fallback(letter);
        if !self.noted.contains(&letter) {
            self.noted.push(letter);
            self.note(format!(
                "address {} is not in the target classification; written with the format {}",
                letter as char,
                fmt.spec()
            ));
        }
        fmt
    }

    /// A word a cycle or a code makes a length (Okuma LAP `D`, a thread's `H`, Haas lathe
    /// `G83 Q0.1`, `G07.1 H57299`) whose letter's format elsewhere holds a whole number (an
    /// offset number `H03`, a block number `Q05`, `D09`): its number is read and written by the
    /// format of the lengths, X's, as the control reads it in that block (it was written
    /// `Q0` for a 2.5 mm peck and `H57299` read as 57299 mm).
    fn length_by_axis(&self, letter: u8) -> bool {
        if self.cycle[slot(letter)] != Some(Role::Length) || letter == b'@' {
            return false;
        }
        if matches!(letter, b'A' | b'B' | b'C') {
            return true; // a rotary address's format counts degrees
        }
        let whole = |formats: &[(u8, WordFormat)], inch: Option<&[(u8, WordFormat)]>, units| {
            format_in(formats, inch, letter, units).is_none_or(|f| !f.decimal || f.after == 0)
        };
        let src = units_of(letter, (self.src_units, self.src_feed_units));
        let out = units_of(letter, (self.out_units(), self.out_feed_units));
        whole(&self.c.src_formats, self.c.src_formats_inch.as_deref(), src)
            || whole(&self.c.out_formats, self.c.out_formats_inch.as_deref(), out)
    }

    fn src_format(&self, letter: u8) -> WordFormat {
        let units = units_of(letter, (self.src_units, self.src_feed_units));
        self.src_table
            .get(
                &self.c.src_formats,
                self.c.src_formats_inch.as_deref(),
                letter,
                units,
            )
            .cloned()
            .unwrap_or_else(|| WordFormat::fallback(letter))
    }

    fn role(&self, letter: u8) -> Role {
        if letter == b'@' {
            return Role::Length; // LinuxCNC's polar radius
        }
        if let Some(role) = self.cycle[slot(letter)] {
            return role;
        }
        match letter {
            b'P' => self.c.pqr[0],
            b'Q' => self.c.pqr[1],
            b'R' => self.c.pqr[2],
            _ => Role::Parameter,
        }
    }

    /// Convert one line of a program (its text without the LF), read under `dialect`: its new
    /// text, or None when it is written as it was. The binding feeds whole chunks this way.
    /// `tokens` is the caller's buffer, kept from line to line (it is cleared here).
    pub fn convert_line<'a>(
        &mut self,
        text: &'a [u8],
        line: usize,
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
    ) -> Result<Option<Vec<u8>>, LineError> {
        tokens.clear();
        if self.not_read(line, text) {
            return Ok(None);
        }
        let extras = tokenize(text, dialect, tokens).map_err(LineError::Read)?;
        let mut words = reuse(std::mem::take(&mut self.spans));
        words.extend(tokens.iter().map(|t| WordSpan {
            token: &t.text,
            start: t.offset,
            end: t.end,
            plain: t.plain,
            digits: t.digits,
        }));
        let skip: Vec<u8> = match extras.as_ref().map_or(0, |e| e.skip) {
            0 => Vec::new(),
            b'/' => b"/".to_vec(),
            level => vec![b'/', level],
        };
        let skip_within = extras
            .as_ref()
            .and_then(|e| e.skip_within)
            .map(|(at, level)| (at, &text[at..at + usize::from(level != b'/') + 1]));
        let comments = extras
            .as_ref()
            .map(|e| e.comments.clone())
            .unwrap_or_default();
        let statements = extras
            .as_ref()
            .map(|e| e.statement_texts(text))
            .unwrap_or_default();
        let block = BlockIn {
            line,
            text,
            words: &words,
            plain: extras.is_none(),
            percent: extras.as_ref().is_some_and(|e| e.percent),
            skip: &skip,
            skip_within,
            comments: &comments,
            statements: &statements,
        };
        let out = self.block(&block).map_err(LineError::Convert);
        self.spans = reuse(words);
        out
    }

    /// Asked before line `line` is read: whether the source control never reads it
    /// (`dialect::ReadingEnd`: after a LinuxCNC program's end), so that it is written as it is.
    pub fn not_read(&mut self, line: usize, text: &[u8]) -> bool {
        let skipped = self.reading_end.skips(line, text);
        if skipped && self.length != ONE {
            // never run, so never converted: counted, and said once, so that nobody takes
            // such a line of the output for one in the target's units
            let holds = text.iter().any(u8::is_ascii_alphanumeric);
            if holds {
                // its place: where its text begins
                let at = text.iter().position(|c| !c.is_ascii_whitespace());
                let column = crate::text::column(text, at.unwrap_or(0));
                self.never_read.add(line, column);
            }
            if holds && !self.unread_noted {
                self.unread_noted = true;
                self.note(format!(
                    "line {line}: the lines after the program's end that the control never \
                     reads (LinuxCNC reads only O-word lines there) are left as written, in \
                     the source's units"
                ));
            }
        }
        skipped
    }

    /// Whether the block is data of FANUC's G10 L50 (parameters) or G10 L3 (tool life) input
    /// mode, written as it is: its numbers are parameter numbers and values in the
    /// parameter's own unit, tool groups, lives and numbers, none a length of the program
    /// (`dialect::DataInput`). Said in a note where the units change, at the G11. Refused: the
    /// mode carried to a control of another family, which reads the blocks as program; a
    /// word of the program inside the mode (a G11 missing: the control alarms there).
    fn data_block(&mut self, b: &BlockIn<'_>) -> Result<bool, ConvertError> {
        let words = b.words.iter().map(|w| (w.token[0], &w.token[1..]));
        let column = |at: usize| crate::text::column(b.text, at);
        let refuse_target = |opened: usize, l: i64| {
            if self.c.target_data_input {
                return Ok(());
            }
            Err(ConvertError {
                message: format!(
                    "{} opened on line {opened}: the target control ({:?}{}) has no such mode \
                     and would read the block as program",
                    crate::dialect::data_input_name(l),
                    self.c.target_family,
                    if self.c.target_family == Family::MacroB {
                        ", not a FANUC: a Haas's G10 takes L2, L10-L13 and L20"
                    } else {
                        ""
                    }
                ),
                clause: "dialect",
                column: b.words.first().map_or(1, |w| column(w.start)),
                line: None,
            })
        };
        // a data word that reads a parameter (`R#1`): the program's parameters are converted
        // where they hold lengths, the data is kept as the parameter's own unit
        let reads_parameter = |opened: usize, l: i64, letters: &[u8]| {
            let found = b.words.iter().find(|w| {
                letters.contains(&w.token[0].to_ascii_uppercase()) && w.token.contains(&b'#')
            });
            match found {
                Some(w) if self.length != ONE => Err(ConvertError {
                    message: format!(
                        "{}: the data of the {} opened on line {opened} reads a parameter, \
                         which the change of units may have converted as a length, while the \
                         data is written in the parameter's own unit; write the value",
                        text(w.token),
                        crate::dialect::data_input_name(l)
                    ),
                    clause: "dialect",
                    column: column(w.start),
                    line: None,
                }),
                _ => Ok(()),
            }
        };
        match self.data_input.block(self.c.family, b.line, words) {
            // (the source's reader opens the mode for any control of the family)
            DataBlock::Lacked { .. } => Ok(false),
            DataBlock::Program => {
                // the `G10 L50` block itself: its own words past G10 and L are data
                // (`G10 L50 N1420 R15000`), kept as the mode's other blocks are; any other
                // word is none the control takes there
                let Some((opened, l)) = self.data_input.open().filter(|o| o.0 == b.line) else {
                    return Ok(false);
                };
                let letters = crate::dialect::data_letters(l);
                if let Some(w) = b.words.iter().find(|w| {
                    let a = w.token[0].to_ascii_uppercase();
                    !(matches!(a, b'G' | b'L') || letters.contains(&a))
                }) {
                    return Err(ConvertError {
                        message: format!(
                            "{}: a word the {} does not take in its G10 block, which holds \
                             only {} data words: the control alarms here",
                            text(w.token),
                            crate::dialect::data_input_name(l),
                            letters
                                .iter()
                                .map(|&c| (c as char).to_string())
                                .collect::<Vec<_>>()
                                .join(" ")
                        ),
                        clause: "dialect",
                        column: column(w.start),
                        line: None,
                    });
                }
                refuse_target(opened, l)?;
                reads_parameter(opened, l, letters)?;
                Ok(true)
            }
            DataBlock::Data { opened, l, closes } => {
                refuse_target(opened, l)?;
                reads_parameter(opened, l, crate::dialect::data_letters(l))?;
                if closes && self.length != ONE {
                    self.note_line(
                        b.line,
                        format!(
                            "lines {opened}-{}: {} kept as written: no unit of the program \
                             applies to them",
                            b.line,
                            crate::dialect::data_input_name(l)
                        ),
                    );
                }
                Ok(true)
            }
            DataBlock::Stray { opened, l, letter } => {
                let at = b
                    .words
                    .iter()
                    .find(|w| w.token[0].eq_ignore_ascii_case(&letter))
                    .map_or(1, |w| column(w.start));
                Err(ConvertError {
                    message: format!(
                        "{} word inside the {} opened on line {opened}, which holds only {} \
                         words until its G11: the G11 is missing, or the control alarms here",
                        letter as char,
                        crate::dialect::data_input_name(l),
                        String::from_utf8_lossy(if l == 50 { b"N P R" } else { b"N P L Q T H D" })
                    ),
                    clause: "dialect",
                    column: at,
                    line: None,
                })
            }
        }
    }

    /// After an assignment `token` converted to `out`: a number assignment rounded is kept
    /// ([`Converter::rounded_params`]); an accumulation (`#1=#1+#3`, the target read in its
    /// own value) that reads a rounded parameter is a loop's step rounded: refused as a
    /// rounded bound is ([`Converter::compared_parameters`]: its rounding builds up at every
    /// pass and may change how many times the loop runs), located at the rounding; with
    /// `--allow-unconverted` said in a note there.
    fn loop_parameter(
        &mut self,
        b: &BlockIn<'_>,
        token: &[u8],
        out: &[u8],
    ) -> Result<(), ConvertError> {
        if self.length == ONE {
            return Ok(());
        }
        let Some(eq) = token.iter().position(|&c| c == b'=') else {
            return Ok(());
        };
        let target = self.parameter(&token[..eq]);
        let read = parameter_names(&token[eq + 1..]);
        let accumulates = read.iter().any(|raw| self.parameter(raw) == target);
        if self.rounded && out != token && read.is_empty() {
            self.rounded_params.insert(
                target.clone(),
                (
                    b.line,
                    text(token),
                    String::from_utf8_lossy(out).into_owned(),
                ),
            );
        }
        if accumulates {
            for raw in &read {
                let name = self.parameter(raw);
                if name == target {
                    continue;
                }
                if let Some((line, from, to)) = self.rounded_params.remove(&name) {
                    let why = format!(
                        "{from} is written {to}, rounded, and {name} is added to {target} on \
                         line {}, which adds itself: a loop's step rounded builds up its \
                         rounding at every pass and may change how many times the loop runs",
                        b.line
                    );
                    self.rounded_loop(line, why)?;
                }
            }
        }
        Ok(())
    }

    /// A loop's bound or step rounded apart (`why` says which, at the rounding's `line`):
    /// refused, or with `--allow-unconverted` a note at the line.
    fn rounded_loop(&mut self, line: usize, why: String) -> Result<(), ConvertError> {
        if !self.c.allow_unconverted {
            return Err(ConvertError {
                message: format!(
                    "{why}, which tapegate does not count; write the bound and the step in \
                     values the target's format holds exactly, or a count of passes, or give \
                     --allow-unconverted to convert it with a note"
                ),
                clause: "6.4.7",
                column: 1,
                line: Some(line),
            });
        }
        self.note_line(line, format!("line {line}: {why}"));
        Ok(())
    }

    /// A condition (`WHILE [#1 LE #2] DO1`, `IF [#1 GT #2] GOTO10`, `o1 while [..]`) that
    /// compares a parameter whose assignment was rounded: said in a note, located at the
    /// rounding (a loop's bound rounded apart from its counter and step may change how many
    /// times the loop runs: probe F12, a hole lost).
    ///
    /// Without `--allow-unconverted` it is refused, located at the rounding: the converter
    /// does not count the passes (`#2=0.25 #3=1.` by steps from 0 are 4 passes, `#2=0.0098
    /// #3=0.0394` 5: a cut more), and a loop run once more or less is a move the source did
    /// not make or one it made, which `--verify` (comparing the text) does not see.
    fn compared_parameters(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if self.length == ONE || self.rounded_params.is_empty() {
            return Ok(());
        }
        for &(_, kind, statement) in b.statements {
            if kind != StatementKind::Flow {
                continue;
            }
            for raw in parameter_names(statement) {
                let name = self.parameter(&raw);
                if let Some((line, from, to)) = self.rounded_params.remove(&name) {
                    let why = format!(
                        "{from} is written {to}, rounded, and {name} is compared in the \
                         condition on line {}: a loop's bound or step rounded apart from the \
                         value it is compared with may change how many times the loop runs",
                        b.line
                    );
                    self.rounded_loop(line, why)?;
                }
            }
        }
        Ok(())
    }

    /// Under a change of units, a read of the parameter that tells which units are in force
    /// is refused: the conversion changes its value, so a branch on it takes the other way
    /// and a value computed from it changes (probe P3-25). LinuxCNC's `#<_metric>` and
    /// `#<_imperial>` (manual, "Predefined Named Parameters": 1 where G21, resp. G20, is in
    /// force), Custom Macro B's #4006 and #4206 (the modal G code of group 06, G20/G21, of the
    /// block read before and of the block running: FANUC 0i "System variables for modal
    /// information"), a SINUMERIK's `$P_GG[13]` (the G function active in group 13, G70 G71
    /// G700 G710: Lists, "G functions" group 13) or a `$P_GG` whose group is a value.
    fn units_flag(&self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if self.length == ONE {
            return Ok(());
        }
        // every read of the flag begins with `#` or (SINUMERIK) `$`, and a word's token and a
        // statement's text are bytes of the line (the token without its blanks at most): a
        // line without the marker holds none, and its words are not looked at one by one
        let marker = if self.c.family == Family::Sinumerik {
            b'$'
        } else {
            b'#'
        };
        if memchr::memchr(marker, b.text).is_none() {
            return Ok(());
        }
        let pieces = b
            .words
            .iter()
            .map(|w| (w.start, w.token))
            .chain(b.statements.iter().map(|&(at, _, t)| (at, t)));
        for (at, piece) in pieces {
            if let Some((offset, name)) = units_flag_read(piece, self.c.family) {
                // (a word's token may have lost the blanks of its text: the name is found there)
                let written = &piece[offset..(offset + name.len()).min(piece.len())];
                let offset = b
                    .text
                    .get(at..)
                    .and_then(|rest| memchr::memmem::find(rest, written))
                    .unwrap_or(offset);
                let what = if name.ends_with("(a variable chosen by a value)") {
                    "it may be #4006 or #4206, which tell"
                } else {
                    "it tells"
                };
                return Err(ConvertError {
                    message: format!(
                        "{name} is read: {what} which units are in force, and the conversion \
                         changes them, so a branch or a value that reads it takes the other way \
                         or another value than in the source; tapegate does not rewrite it: \
                         convert the program without it"
                    ),
                    clause: "units",
                    column: crate::text::column(b.text, at + offset),
                    line: None,
                });
            }
        }
        Ok(())
    }

    /// The letter that gives the thread lead in a block of `gs`, where the block threads
    /// with a constant lead per revolution: F of G32 (FANUC, Haas lathe: "Thread cutting"),
    /// G76 and G92 (the threading cycles of a lathe) and G33 (FANUC mill), F of the OSP
    /// lathe's G31-G33, G71/G72 and G88, K of G33 (LinuxCNC:
    /// "G33 Spindle Synchronized Motion", K the distance per revolution; ISO 6983-1 and
    /// SINUMERIK: the lead in I, J or K, K along Z), LinuxCNC's G33.1 K (rigid tapping) and
    /// G76 P (the threading cycle's pitch).
    fn lead_letter(&self, b: &BlockIn<'_>, gs: &[i64]) -> Option<u8> {
        let has = |g: i64| gs.contains(&g);
        // LinuxCNC's G33.1 (rigid tapping, K the pitch): a code with a fraction
        let tapping = || {
            b.words.iter().any(|w| {
                w.token[0].eq_ignore_ascii_case(&b'G')
                    && crate::meaning::code(&w.token[1..]) == Some((33, 1))
            })
        };
        match self.c.family {
            Family::MacroB if self.c.lathe && (has(32) || has(76) || has(92)) => Some(b'F'),
            Family::MacroB if !self.c.lathe && has(33) => Some(b'F'),
            // the OSP lathe's thread cutting cycles G31-G33, its compound thread cycles G71/G72
            // and the LAP thread cycle G88: F the lead (5238-E; docs/convert.md's table)
            Family::Okuma if self.c.lathe && [31, 32, 33, 71, 72, 88].iter().any(|&g| has(g)) => {
                Some(b'F')
            }
            // LinuxCNC's G76 threading cycle: P the pitch
            Family::LinuxCnc if has(76) => Some(b'P'),
            Family::LinuxCnc if tapping() => Some(b'K'),
            Family::LinuxCnc | Family::Iso | Family::Sinumerik if has(33) => Some(b'K'),
            _ => None,
        }
    }

    /// A note for a thread lead the change of units rounded: its error per revolution, and
    /// over the thread where the block's Z travel is known (the revolutions it turns), since
    /// a lead that is off is off at every turn: F1.5 mm written F0.0591 in is 0.0011 mm long
    /// per revolution, 0.023 mm over 20 turns, past the gauge of a fine thread.
    fn lead_note(
        &mut self,
        b: &BlockIn<'_>,
        lead: u8,
        exact: f64,
        rounded: f64,
        z_before: Option<Dec>,
    ) {
        let word = b
            .words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&lead))
            .map_or(String::new(), |w| text(w.token));
        let unit = |u: Units| if u == Units::Inch { "in" } else { "mm" };
        let (src, out) = (unit(self.src_units), unit(self.out_units()));
        let error = rounded - exact;
        // the block's travel along Z in the source's units: W, an incremental Z, or an
        // absolute Z from the position before it, each read as the source control reads it
        // (`Converter::source_number`: `Z-20000` in least increments under --from-decimal
        // increments is 20 mm, as the position before it was read; review 58b, F5: the note
        // said "the thread's 20005 mm")
        let value = |letter: u8| {
            let w = b
                .words
                .iter()
                .find(|w| w.token[0].eq_ignore_ascii_case(&letter))?;
            let (negative, _, whole, dot, fraction) = plain_word(w)?;
            let digits = w.plain.map(|_| w.digits);
            let (m, scale) = self
                .source_number(w.token, letter, letter, digits, (whole, dot, fraction))
                .ok()?;
            let magnitude = Dec { mantissa: m, scale }.to_f64();
            Some(if negative { -magnitude } else { magnitude })
        };
        let w_travel = value(b'W').filter(|_| self.c.lathe && self.c.family == Family::MacroB);
        let travel = w_travel.or_else(|| {
            let z = value(b'Z')?;
            if self.incremental() {
                Some(z)
            } else {
                Some(z - z_before?.to_f64())
            }
        });
        let over = match travel.map(f64::abs).filter(|t| *t > 0.0) {
            Some(length) => {
                // the lead in the source's units, from the exact value in the target's
                let per_unit = if src == out {
                    1.0
                } else if out == "in" {
                    1.0 / 25.4
                } else {
                    25.4
                };
                let turns = length * per_unit / exact;
                format!(
                    ", {} {out} over the thread's {} {src} ({:.1} revolutions)",
                    significant((error * turns).abs()),
                    crate::decimal::Dec::parse(&format!("{length:.4}"))
                        .map_or(format!("{length}"), |d| d.plain()),
                    turns
                )
            }
            None => String::new(),
        };
        self.note_line(
            b.line,
            format!(
                "line {}: the thread lead {word} converts to {} {out} per revolution and is \
                 written {}: {} {out} {} per revolution{over}, an error that builds up at \
                 every turn of the thread",
                b.line,
                trim_float(exact),
                trim_float(rounded),
                significant(error.abs()),
                if error > 0.0 { "long" } else { "short" },
            ),
        );
    }

    /// The block's new text, or None when it is written as it was.
    pub fn block(&mut self, b: &BlockIn<'_>) -> Result<Option<Vec<u8>>, ConvertError> {
        self.reading_end.read(
            b.words.iter().map(|w| w.token),
            b.statements.iter().map(|&(_, kind, text)| (kind, text)),
            !b.skip.is_empty(),
            b.line,
        );
        self.blocks += 1;
        self.words += b.words.len();
        if self.c.family == Family::MacroB && self.c.target_family != Family::MacroB {
            nested_comment_to(b, self.c.target_family)?;
        }
        if self.c.colon_stops && !b.comments.is_empty() {
            colon_in_comment(b)?;
        }
        let opening = if b.percent {
            Opening::percent_line(b.text)
        } else {
            Opening {
                word: b
                    .words
                    .first()
                    .map(|w| (w.start, w.token[0].to_ascii_uppercase())),
                statement: b.statements.first().copied(),
                percent: None,
            }
        };
        let begins = self
            .split
            .begins(self.c.family, self.c.program_number, &opening);
        let named = self.named_opening(b, &opening)?;
        if begins {
            self.start_program(b.line);
            self.program += 1;
        }
        if let Some(name) = named {
            self.named_begins(&name, b.line);
        }
        if (begins || self.program == 0) && self.words_call() {
            // the program's number, where a call in the file (M98 P) may name it
            let number = b
                .words
                .first()
                .filter(|w| Some(w.token[0].to_ascii_uppercase()) == self.c.program_number)
                .and_then(|w| crate::text::digits_value(&w.token[1..]));
            if number.is_some() {
                let refused = self.program_doubt.is_some();
                self.flow
                    .program_begins(number, self.modal.state.units, refused);
            }
        }
        if let (Some(why), true) = (
            crate::between::frame(self.c.family, self.c.target_family, family_name),
            self.blocks == 1,
        ) {
            return Err(ConvertError {
                message: why,
                clause: "dialect",
                column: 1,
                line: None,
            });
        }
        if b.percent {
            // (only the leader: the closing `%` ends the program on every target)
            if self.c.percent_words_read && !self.leader_passed {
                percent_words(b, self.c.target_family, self.c.leader_skipped)?;
            }
            self.leader_passed = true;
            return Ok(None);
        }
        self.leader_passed |= !b.words.is_empty();
        if self.data_block(b)? {
            return Ok(None);
        }
        self.same_programs(b.line)?;
        self.units_flag(b)?;
        self.statements(b)?;
        self.compared_parameters(b)?;
        if b.statements.iter().any(|s| s.1 == StatementKind::Flow) {
            self.loops = true;
        }
        // LinuxCNC's o100 sub ... o100 endsub, Sinumerik's RET: where a subprogram begins or
        // ends by a statement
        let (sub_begins, sub_ends) = self.subprogram_statements(b);
        // under a change of units, a LinuxCNC body is read in its calls' units
        let bodies = self.c.family == Family::LinuxCnc && self.c.units.is_some();
        if let Some(why) = self.flow_after_call.take() {
            self.flow.set_doubt(why);
        }
        if sub_begins {
            self.fresh_program();
            self.sub = Some(b.line);
            if bodies {
                self.flow_caller = self.flow.enter_body();
                self.begin_body(b);
            }
        }
        // an OSP subprogram ends with RTS: its S before its own G96/G97 is its caller's mode's
        let rts = self.c.family == Family::Okuma
            && b.statements.iter().any(|&(_, kind, statement)| {
                kind == StatementKind::Command && crate::statement::okuma::returns(statement)
            });
        if rts {
            self.inherited_speed(b.line, "RTS")?;
        }
        // A LinuxCNC subroutine body runs when it is called, not where it stands: the units a
        // program never selected are written before the main program's first value, and a
        // call before that would run the body in the control's start units.
        let in_sub = self.c.family == Family::LinuxCnc && self.sub.is_some();
        if self.c.family == Family::LinuxCnc
            && !in_sub
            && !self.units_seen
            && (self.length != ONE || self.out_units() != self.out_length_units)
        {
            if let Some(&(at, _, call)) = b.statements.iter().find(|s| s.1 == StatementKind::Call) {
                return Err(ConvertError {
                    message: format!(
                        "{}: the main program calls a subroutine before it selects its units, \
                         so the subroutine runs in the control's start units, before any units \
                         code written in the main program; write the program's units code \
                         (G20/G21) before the call",
                        text(call)
                    ),
                    clause: "units",
                    column: crate::text::column(b.text, at),
                    line: None,
                });
            }
        }
        if bodies {
            if self.bodies.is_open() && !sub_begins {
                self.body_block(b)?;
            }
            self.body_calls(b)?;
        }
        if let Some(end) = sub_ends {
            if bodies && self.bodies.is_open() {
                self.end_body(b.line)?;
                let caller = self.flow_caller.take();
                self.flow.leave_body(caller);
            }
            self.inherited_distance(b.line, &end)?;
            self.fresh_program();
            self.split.ended(true);
            self.sub = None;
        }
        // LinuxCNC: o-word flow, a call or a definition leaves the motion mode in force unknown
        // (the text's order is not the order the blocks run in)
        if b.statements.iter().any(|&(_, kind, _)| {
            matches!(
                kind,
                StatementKind::Flow | StatementKind::Call | StatementKind::Definition
            )
        }) {
            self.linuxcnc_motion = None;
        }
        if b.words.is_empty() {
            self.flow_block(b, false)?;
            self.named_calls(b)?;
            // a SINUMERIK frame (TRANS X10) is a block of its own
            if b.statements.is_empty() {
                return Ok(None);
            }
            let statements = self.statement_lengths(b)?;
            return Ok((!statements.is_empty()).then(|| splice(b.text, &statements)));
        }
        let (mut dwell, mut set_position, mut machine_move) = (false, false, false);
        // the units code of the block, and whether it sets the feed's units too (Sinumerik's
        // G700/G710; every other family's units codes)
        let mut units_at = None;
        let mut units_all = true;
        // (the block's codes in the vectors of the block before: refused blocks aside, no
        // allocation a block)
        let (mut gs, mut ms) = std::mem::take(&mut self.codes);
        gs.clear();
        ms.clear();
        // whether the block has a G word, an M word and a Z word, read in this one pass: the
        // searches for particular G codes, for Z and for the codes' meanings below look only
        // where there is one (most CAM blocks have no G word)
        let (mut g_word, mut m_word, mut z_word) = (false, false, false);
        // and, in the same pass, the first N word (the units flow's label), whether a G word
        // reads as no whole code (`G33.1` is one: looked for below only then), and whether a
        // G word's number is 65 or 66 as written (a macro call's arguments, below)
        let mut n_word = None;
        let (mut g_unread, mut g_macro) = (false, false);
        for (i, w) in b.words.iter().enumerate() {
            let letter = w.token[0].to_ascii_uppercase();
            z_word |= letter == b'Z';
            if letter == b'N' && n_word.is_none() {
                n_word = Some(i);
            }
            if letter != b'G' && letter != b'M' {
                continue;
            }
            g_word |= letter == b'G';
            m_word |= letter == b'M';
            if letter == b'G' {
                g_macro |= matches!(integer(&w.token[1..]), Some(65 | 66));
            }
            let Some(n) = self.code_of(w.token) else {
                g_unread |= letter == b'G';
                continue;
            };
            if letter == b'M' {
                ms.push(n);
                continue;
            }
            // a FANUC lathe's code of G code system B or C by its system A number
            let n = self.c.src_modal.read_g(n);
            gs.push(n);
            match n {
                4 => dwell = true,
                92 => set_position = true,
                // a Fanuc or Haas lathe's G50: the coordinate setting and the spindle clamp
                50 if self.c.lathe && self.c.family == Family::MacroB => set_position = true,
                28 | 30 | 53 => machine_move = true,
                700 | 710 if self.c.family == Family::Sinumerik => {
                    units_at = Some(i);
                    units_all = true;
                    self.units_seen = true;
                }
                _ if n == self.c.src_modal.inch || n == self.c.src_modal.metric => {
                    units_at = Some(i);
                    units_all = self.c.family != Family::Sinumerik;
                    // (a subroutine's own units code is no choice of the main program's)
                    self.units_seen |= !in_sub;
                }
                _ => {}
            }
        }
        self.s_limit = self.c.src_modal.s_limit_with(|g| gs.contains(&g)).1;
        let mut units_before = self.modal.state.units;
        let mut feed_before = self.modal.state.feed_units;
        if self.c.units.is_some() {
            let number = n_word.map(|i| b.words[i].token);
            // (its value as the tokenizer read it, not read again)
            let key = n_word.and_then(|i| {
                let w = &b.words[i];
                crate::units_flow::number_key(w.token, w.plain, w.digits)
            });
            self.flow.block_labels_keyed(
                self.c.family,
                number,
                key,
                b.statements,
                units_before,
                units_at.is_some(),
            );
            if let Some(feed_flow) = &mut self.feed_flow {
                feed_flow.block_labels_keyed(
                    self.c.family,
                    number,
                    key,
                    b.statements,
                    feed_before,
                    units_at.is_some(),
                );
            }
            self.arrive();
            units_before = self.modal.state.units;
            feed_before = self.modal.state.feed_units;
        }
        self.modal.codes(&gs);
        let state = &self.modal.state;
        if self.feed_flow.is_none()
            && self.c.units.is_some()
            && self.c.family == Family::Sinumerik
            && state.feed_units != state.units
        {
            self.feed_flow = Some(self.flow.clone());
        }
        self.saved_units(b, &ms, units_before, units_at.is_some());
        if let (Some(i), true) = (units_at, self.c.units.is_some()) {
            let column = crate::text::column(b.text, b.words[i].start);
            self.flow
                .units_code(units_before, self.modal.state.units, b.line, column);
            if let Some(feed_flow) = &mut self.feed_flow {
                let feed = self.modal.state.feed_units;
                feed_flow.units_code(feed_before, feed, b.line, column);
            }
        }
        self.follow_units();
        self.flow_block(b, true)?;
        self.named_calls(b)?;
        if self.words_call()
            && (ms.iter().any(|&m| (97..=99).contains(&m))
                || gs.iter().any(|&g| g == 65 || g == 66))
        {
            self.flow_words(b)?;
        }
        if self.length != ONE && self.c.family == Family::Heidenhain {
            return Err(ConvertError {
                message: "a HEIDENHAIN program gives its units in its first and last lines \
                          (%NAME G71 *), which tapegate does not rewrite, and its Q parameters \
                          are not analysed: its units cannot be converted"
                    .into(),
                clause: "units",
                column: b
                    .words
                    .first()
                    .map_or(1, |w| crate::text::column(b.text, w.start)),
                line: None,
            });
        }
        if let (Some(i), true) = (units_at, self.c.inch_code.is_empty()) {
            // the target has no such code: what the source's code says there is the machine's
            // setting, and a word left as written is another code on it (an Okuma OSP lathe's
            // G20 is a home position return)
            return Err(ConvertError {
                message: format!(
                    "{}: the target control selects its units by a machine parameter, not by \
                     a G code, and reads this code as another function; tapegate does not \
                     delete it: remove it from the source and set the machine's units",
                    text(b.words[i].token)
                ),
                clause: "units",
                column: crate::text::column(b.text, b.words[i].start),
                line: None,
            });
        }
        let out_code = units_at.map(|_| self.out_units_code(units_all));
        if gs.iter().any(|&g| g == 90 || g == 91) {
            self.own_distance = true;
        }
        if gs.iter().any(|&g| g == 96 || g == 97) {
            self.own_spindle = true;
        }
        let absolute = gs.contains(&53);
        let mut insert = None;
        // The units a program never selected are written before the first value they change,
        // not before a block of modes: a G21 coming after "G90 G17 G40" is replaced in place.
        let measures = |w: &WordSpan<'_>| {
            w.token[0] == b'#'
                || matches!(
                    kind(w.token[0].to_ascii_uppercase()),
                    Some(Kind::Axis | Kind::Centre | Kind::Feed | Kind::Speed | Kind::Pqr)
                )
        };
        // a value whose reading depends on the units: all of those but a speed in rpm
        let css = self.modal.state.spindle_mode == 96;
        let depends = |w: &&WordSpan<'_>| {
            measures(w) && (css || kind(w.token[0].to_ascii_uppercase()) != Some(Kind::Speed))
        };
        let doubted = self.units_doubt.filter(|_| !self.units_seen);
        let called = self.program_doubt.filter(|_| !self.units_seen);
        // (the words searched only where there is a doubt: not on every block)
        let first_depending =
            |doubt: Option<_>| doubt.and_then(|d| b.words.iter().find(depends).map(|w| (d, w)));
        if let Some(((start, caller, own), w)) = first_depending(called) {
            let column = crate::text::column(b.text, w.start);
            return Err(ConvertError {
                message: format!(
                    "the program beginning on line {start} moves before it selects its units, \
                     so it runs in the units in force when it starts, which its text does not \
                     show: in {}, the units the program before it in the file leaves in force, \
                     where it runs after that program or is called as a subprogram (from this \
                     file or from another); in {}, the control's start units, where it is run \
                     as a program of its own; under a change of units the two readings differ \
                     by 25.4, so write the program's units code before its first move",
                    caller.name(),
                    own.name()
                ),
                clause: "units",
                column,
                line: None,
            });
        }
        let doubted = doubted.or(called);
        if let Some(((end, kept, reset), w)) = first_depending(doubted) {
            let column = crate::text::column(b.text, w.start);
            return Err(ConvertError {
                message: format!(
                    "the program after the end on line {end} moves before it selects its \
                     units, and the source control was not given: a control that keeps \
                     its units through M02/M30 (Fanuc, Haas, LinuxCNC) reads it in {}, one \
                     that resets them (clause 14, Sinumerik) in {}; give the source \
                     profile (--from), or write the program's units code before its \
                     first move",
                    kept.name(),
                    reset.name()
                ),
                clause: "units",
                column,
                line: None,
            });
        }
        // with the units in doubt, a block of speeds in rpm waits for the program's units code
        if !self.units_seen && !in_sub && doubted.is_none() && b.words.iter().any(measures) {
            self.units_seen = true;
            let differs = self.out_units() != self.out_length_units;
            if let Some(end) = self.ended_on.filter(|_| differs && self.length == ONE) {
                // The source and target controls differ in what M30 does to the units: a
                // subprogram runs in its caller's, a program of its own in the reset state's
                // or the kept ones, and no code written here means the same on both.
                let column = b
                    .words
                    .iter()
                    .find(|w| measures(w))
                    .map_or(1, |w| crate::text::column(b.text, w.start));
                let (src, target) = if self.c.src_modal.units_kept_at_end {
                    ("keeps", "does not")
                } else {
                    ("does not keep", "does")
                };
                return Err(ConvertError {
                    message: format!(
                        "the program after the end on line {end} moves before it selects its \
                         units: the source control {src} its units through M02/M30 and the \
                         target {target}, so whether it is a subprogram (its caller's units) \
                         or a program of its own, its text cannot mean the same on both; \
                         write its units code before its first move"
                    ),
                    clause: "units",
                    column,
                    line: None,
                });
            }
            // a source control that selects its units by a machine parameter (the OSP
            // lathe): the program was read in its profile's units, which its text does not
            // confirm; said wherever the units matter (docs/convert.md, "A control without
            // units codes"), unless the units the machine is set to were given (--from-units)
            let src_parameter = self.c.src_modal.inch < 0 && !self.c.src_units_given;
            let read_in = format!(
                "the source was read in {}, the source profile's units: its control selects \
                 them by a machine parameter the program does not show",
                self.src_units.name()
            );
            let other_control = self.c.target_family != self.c.family;
            if self.length == ONE
                && !differs
                && src_parameter
                && (self.c.units.is_some() || other_control)
            {
                self.note_line(
                    b.line,
                    format!(
                        "no length converted: {read_in}; a program written for the machine set \
                         to the other units is not converted by this"
                    ),
                );
            }
            if self.length != ONE || differs {
                let code = self.out_units_code(false);
                if code.is_empty() {
                    // the units the machine is told to be set to: the output's reading
                    self.machine_units.get_or_insert(self.out_units());
                }
                let by_parameter = |units: Units| {
                    format!(
                        "no units code written: the target control selects its units by a \
                         machine parameter, not by a G code; every length from line {} on \
                         is converted to {}: set the machine to {} before running it{}",
                        b.line,
                        units.name(),
                        units.name(),
                        if src_parameter {
                            format!("; {read_in}")
                        } else {
                            String::new()
                        }
                    )
                };
                let note = match self.ended_on {
                    _ if code.is_empty() => by_parameter(self.out_units()),
                    None if self.c.src_modal.inch < 0 => format!(
                        "inserted {code}: the source control selects its units by a machine \
                         parameter, not by a G code; the program was read in {}, {}",
                        self.src_units.name(),
                        if self.c.src_units_given {
                            "the units given for its machine (--from-units)"
                        } else {
                            "the source profile's units"
                        }
                    ),
                    None => match self.program_line {
                        None => format!(
                            "inserted {code}: the program did not select its units before \
                             line {}",
                            b.line
                        ),
                        Some(start) => format!(
                            "inserted {code}: the program beginning on line {start} did not \
                             select its units before line {}; it was read in {}, the source \
                             control's start units, as a program of its own",
                            b.line,
                            self.src_units.name()
                        ),
                    },
                    Some(end) => format!(
                        "inserted {code}: the program after the end on line {end} did not \
                         select its units before line {}; it was read in {}, the units {}",
                        b.line,
                        self.src_units.name(),
                        if self.jumped_in {
                            "the jumps to its label bring (the straight path does not reach it)"
                        } else if self.c.source_detected {
                            "both the program before left in force and the reset state has"
                        } else if self.c.src_modal.units_kept_at_end {
                            "the program before left in force"
                        } else {
                            "of the source control's reset state"
                        }
                    ),
                };
                self.note_line(b.line, note);
                insert = Some(code).filter(|code| !code.is_empty());
            }
        }
        let statements = if b.statements.is_empty() {
            Vec::new()
        } else {
            self.statement_lengths(b)?
        };
        if self.renumbers() {
            self.between_g_systems(b, &gs)?;
        }
        self.motion_mode(b, &gs)?;
        self.dwell_feed_words(b, &gs)?;
        // (between two LinuxCNC profiles only a change of units refuses an E: without one
        // nothing needs the motion followed; from another family's program the target reads
        // an E the source wrote for a meaning of its own)
        let other = self.c.family != Family::LinuxCnc;
        if self.c.target_family == Family::LinuxCnc && (other || self.c.units.is_some()) {
            let motion = self.linuxcnc_block_motion(b);
            if other {
                // a G code the two controls give different meanings (a FANUC G05.1 Q1, AI
                // contour control, is LinuxCNC's quadratic spline) is refused as such, before
                // its words are read by LinuxCNC's code (review 26: the Q was refused, with a
                // reason of LinuxCNC's G5.1)
                self.same_meaning(b, b'G')?;
                self.lathe_uw_for_linuxcnc(b, &gs)?;
                self.linuxcnc_dwell_words(b, &gs)?;
                self.linuxcnc_d_h_words(b, &gs)?;
            }
            self.linuxcnc_e_word(b, &ms, motion)?;
            if other {
                self.linuxcnc_m98_alone(b, &ms)?;
                self.linuxcnc_data_words(b, &gs, &ms, motion)?;
                self.linuxcnc_arc_turns(b, &ms, motion)?;
                self.linuxcnc_mixed_arc(b, motion)?;
            }
            // M98 calls a subprogram, which may leave another motion mode in force
            if ms.contains(&98) {
                self.linuxcnc_motion = None;
            }
        }
        // a block under a canned cycle in force repeats it at a new position, with the words it
        // changes: they have the cycle's roles (`Repeat`, which `--verify` reads by too)
        self.cycle_code = self.cycle_code.after(self.c.family, self.c.lathe, &gs, &ms);
        // (a lathe's thread in force only into a plain pass, `modal::thread_pass`: a G75
        // after a G92 reads its Q as its own depth)
        let repeated = self.cycle_code.code().filter(|&c| {
            !gs.contains(&c)
                && (!crate::modal::modal_thread(c) || crate::modal::thread_pass(&gs, g_unread))
        });
        if let Some(c) = repeated {
            gs.push(c);
        }
        let system = self.c.src_modal.g_system;
        // (a block without G or M words and no cycle repeated, most of a CAM program's moves:
        // no code gives a word a meaning, `code_meanings_of`'s own answer without its look at
        // the words)
        let meanings = if gs.is_empty() && ms.is_empty() && !g_word && !m_word {
            crate::meaning::Meanings::default()
        } else {
            // (a Haas's cycles read some words otherwise than a FANUC's: its G73/G83 K)
            let haas = Some(self.c.src_modal.haas);
            cycle_meanings_in(system, self.c.family, haas, self.c.lathe, &gs, &ms, b.words)
        };
        let family = self.c.family;
        let pqr_code = gs.iter().any(|&g| pqr_code(family, self.c.lathe, g));
        if repeated.is_some() {
            gs.pop();
        }
        self.cycle = meanings.roles;
        self.angles = meanings.table_others();
        if !ms.is_empty() {
            self.unlisted_m_words(&ms, pqr_code);
        }
        if self.c.family != Family::Iso
            && self.length == ONE
            && (gs.contains(&65) || gs.contains(&66))
        {
            // a macro call's arguments (all but G N O P L) are the macro's to read, as an M code
            // macro call's are (FANUC parameters 6050-6059 and 6080-6089: one argument rule):
            // under a change of decimal style each goes by the one rule for a word of unknown
            // role (`G65 P9010 A1.5` was written `A1500`, "verified"); under a change of units
            // they are refused or left as written (`arguments_kept`, below)
            for letter in b'A'..=b'Z' {
                if !b"GNOPL".contains(&letter) {
                    self.cycle[slot(letter)] = Some(Role::Parameter);
                }
            }
        }
        let tokens = b.words.iter().map(|w| (w.token[0], &w.token[1..]));
        if let Some(on) = crate::meaning::polar_interpolation(self.c.family, self.c.lathe, tokens) {
            self.polar_interpolation = on;
        }
        if self.polar_interpolation && self.cycle[slot(b'C')].is_none() {
            // G12.1 ... G13.1: C is the hypothetical axis, a length
            self.cycle[slot(b'C')] = Some(Role::Length);
        } else if self.c.lathe && self.c.family == Family::MacroB {
            if self.chamfer_or_axis(b, &gs) {
                // `G01 X30. C1.`: a chamfer (a length) on a lathe without a C axis, a move of
                // C (degrees) on one with it: which, the program does not show
                self.cycle[slot(b'C')] = Some(Role::Parameter);
            } else if b
                .words
                .iter()
                .any(|w| w.token[0].eq_ignore_ascii_case(&b'C'))
            {
                // C commanded otherwise (G00 C0, a drilling cycle's C, G07.1 C): the machine
                // has a C axis, and its chamfer is written `,C`
                self.c_axis = true;
            }
        }
        // words that are no coordinates: a tilted plane's origin (G68.2 X Y Z), a cylinder's
        // radius (G07.1 C), a polar radius and angle under G16; none is a position followed
        let mut data_axes = [false; 26];
        if meanings.data {
            for w in b.words {
                let letter = w.token[0].to_ascii_uppercase();
                if matches!(kind(letter), Some(Kind::Axis)) && self.cycle[slot(letter)].is_none() {
                    self.cycle[slot(letter)] = Some(Role::Length);
                    data_axes[slot(letter)] = true;
                }
            }
        }
        let polar = self
            .modal
            .state
            .polar
            .then(|| crate::meaning::polar_axes(self.modal.state.plane));
        if let Some((radius, angle)) = polar {
            self.cycle[slot(radius)] = Some(Role::Length);
            self.cycle[slot(angle)] = Some(Role::Other);
            self.angles |= 1 << slot(angle);
            data_axes[slot(radius)] = true;
            data_axes[slot(angle)] = true;
        }
        // an Okuma lathe's L: the radius of an arc, a length (`word::radius_letter_role`)
        let radius = self.c.src_modal.arc_radius;
        if let Some(role) = crate::word::radius_letter_role(radius, self.modal.state.motion, &gs) {
            self.cycle[slot(radius)] = Some(role);
        }
        // a lathe's U W: the move's or a cycle's, by the codes of the block (`UwMoves`, the
        // rule `--verify`'s reader keeps too; review 59c F7: `G32 W-20.` in inch failed
        // --verify by 0.00004 mm, carried as a G01's)
        for &g in &gs {
            self.uw_moves.code(g);
        }
        // (the code first: a cycle the target writes in another form is refused as such,
        // before its words)
        self.same_meaning(b, b'G')?;
        self.lacked_code_words(b, g_word)?;
        self.same_cycle_reading(b)?;
        self.same_radius_letter(b)?;
        self.same_tool_word(b)?;
        self.same_x_reading(b)?;
        self.reset_feed_mode(b, &gs)?;
        self.m98_long_p(b, &ms)?;
        self.cycle_repeat_words(b, &gs)?;
        // a lathe's G50 on another control (on another kind of machine G50 is in another
        // group, refused above), and FANUC and Haas G10 data
        let lathe_g50 = self.c.lathe && !self.c.same_cycle_table && gs.contains(&50);
        if self.c.fanuc_haas.is_some() || lathe_g50 {
            let words = between_words(b);
            let found = if lathe_g50 {
                crate::between::lathe_g50_axes(&words, &gs)
            } else {
                Ok(())
            };
            found
                .and_then(|()| match self.c.fanuc_haas {
                    Some(from_haas) => {
                        crate::between::fanuc_haas_words(from_haas, self.c.lathe, &words, &gs)
                    }
                    None => Ok(()),
                })
                .map_err(|r| ConvertError {
                    message: r.message,
                    clause: r.clause,
                    column: crate::text::column(b.text, r.at),
                    line: None,
                })?;
        }
        if self.c.family != self.c.target_family {
            // words and variables the target family reads as other data
            let words = between_words(b);
            let k = crate::between::Block {
                words: &words,
                name: family_name,
                gs: &gs,
                ms: &ms,
                motion: self.modal.state.motion,
                cycle: self.modal.state.cycle.is_some(),
                incremental: self.incremental(),
            };
            crate::between::block(self.c.family, self.c.target_family, &k).map_err(|r| {
                ConvertError {
                    message: r.message,
                    clause: r.clause,
                    column: crate::text::column(b.text, r.at),
                    line: None,
                }
            })?;
        }
        if (self.c.x_radius || self.c.x_diameter) && whole_g_code(b, &[10]) {
            self.g10_x_reading(b)?;
        }
        self.same_meaning(b, b'M')?;
        // under a change of units, a macro call's arguments (all but G N O P L) are the macro's
        // to read: refused, or with --allow-unconverted left as written (they were converted
        // as lengths, which the message promised not to do)
        let mut arguments_kept = false;
        if self.length != ONE && self.c.family != Family::Iso && g_macro {
            if let Some(w) = b.words.iter().find(|w| {
                let g = w.token[0].eq_ignore_ascii_case(&b'G');
                g && matches!(integer(&w.token[1..]), Some(65 | 66))
            }) {
                let args = b.words.iter().any(|a| {
                    let l = a.token[0].to_ascii_uppercase();
                    l.is_ascii_uppercase() && !b"GNOPL".contains(&l)
                });
                if args && !self.c.allow_unconverted {
                    return Err(ConvertError {
                        message: format!(
                            "{}: the arguments of a macro call are read by the macro, and nothing \
                             shows which are lengths; convert the macro's units, or give \
                             --allow-unconverted to leave them as written",
                            text(w.token)
                        ),
                        clause: "6.4.7",
                        column: crate::text::column(b.text, w.start),
                        line: None,
                    });
                }
                if args {
                    arguments_kept = true;
                    self.note(format!(
                        "the arguments of macro calls ({}) left as written \
                         (--allow-unconverted)",
                        text(w.token)
                    ));
                }
            }
        }
        // the words that change, by place (the others are written as they are), in a vector
        // kept from block to block
        // a thread's lead: its rounding is said with the error it builds over the thread
        self.lead_watch = self.lead_letter(b, &gs).filter(|_| self.length != ONE);
        self.lead_rounded = None;
        let z_before = self.src_pos[slot(b'Z')].or_else(|| {
            self.abs_raw[slot(b'Z')].map(|(negative, m, scale)| Dec {
                mantissa: if negative { -m } else { m },
                scale,
            })
        });
        // (a slot a word, kept from block to block with every slot None and as long as the
        // longest block's: neither cleared nor filled anew each block; `new`: a slot was set)
        let mut changed = std::mem::take(&mut self.replacements);
        let count = b.words.len();
        if changed.len() < count {
            changed.resize(count, None);
        }
        let mut new = false;
        for (i, w) in b.words.iter().enumerate() {
            let letter = w.token[0].to_ascii_uppercase();
            if arguments_kept && letter.is_ascii_uppercase() && !b"GNOPL".contains(&letter) {
                let column = crate::text::column(b.text, w.start);
                self.left_as_written.add(b.line, column);
                // I1 without its point is a count of the least input increment, 0.001 mm or
                // 0.0001 in: left as written it passes the macro another number
                let counts = self.src_letters.increments(letter) && self.src_format(letter).decimal;
                if let Some((_, _, whole, false, _)) = plain(w.token).filter(|_| counts) {
                    if whole.iter().any(|&d| d != b'0') {
                        return Err(ConvertError {
                            message: format!(
                                "{}: a macro argument without its decimal point counts the \
                                 least input increment, which the units change (0.001 mm, \
                                 0.0001 in): left as written it passes the macro another \
                                 number; write it with its decimal point",
                                text(w.token)
                            ),
                            clause: "6.4.7",
                            column: crate::text::column(b.text, w.start),
                            line: None,
                        });
                    }
                }
                continue;
            }
            // a word the cycle makes a length or a number (Haas G71 D, G76 K) goes by that role
            let role = self.cycle[slot(letter)].filter(|_| letter.is_ascii_uppercase());
            let k = match kind(letter) {
                // a selector (G05.1 Q1) is a number written as it is
                Some(_) if letter != b'G' && role == Some(Role::Selector) => Some(Kind::Count),
                Some(Kind::Count | Kind::Centre | Kind::Angle)
                    if letter != b'G' && self.cycle[slot(letter)].is_some() =>
                {
                    Some(Kind::Pqr)
                }
                // an angle, a direction or a number on an axis, rotary or feed address (G68.2
                // I J K, a polar angle, M67 E), a length on a rotary one (G07.1 C), an axis
                // word that is its code's data (a tilted plane's origin, a polar radius), a
                // word its code leaves unexplained (an OSP mill cycle's E, Haas G268's X Y Z
                // and A B C: refused by its role)
                Some(Kind::Axis | Kind::Angle | Kind::Feed)
                    if data_axes[slot(letter)]
                        || matches!(role, Some(Role::Other | Role::Parameter))
                        || (role == Some(Role::Length) && kind(letter) != Some(Kind::Axis)) =>
                {
                    Some(Kind::Pqr)
                }
                other => other,
            };
            // where the program turns out to be a subprogram, this word's distance mode is the
            // caller's (a Fanuc or Haas lathe's U W are increments by their letter); a word the
            // conversion leaves as written (X#24 under --allow-unconverted, X0) means the same
            // in either mode, so only one it writes anew counts (below)
            let distance_unknown = k == Some(Kind::Axis)
                && self.length != ONE
                && !self.own_distance
                && self.inherited.is_none()
                && !(self.c.lathe && self.c.family == Family::MacroB)
                && !(dwell && self.c.src_modal.dwell.contains(&letter))
                && !set_position
                && !absolute;
            if k == Some(Kind::Speed)
                && self.c.lathe
                && self.length != ONE
                && !self.own_spindle
                && self.inherited_speed.is_none()
                && !self.s_limit
                && !(dwell && self.c.src_modal.dwell.contains(&letter))
            {
                let column = crate::text::column(b.text, w.start);
                self.inherited_speed = Some((text(w.token), b.line, column));
            }
            // the word's new text, or None where it is written as it was
            let sinumerik_r = self.c.family == Family::Sinumerik
                && letter == b'R'
                && self.role(letter) == Role::Parameter;
            if sinumerik_r {
                self.rounded = false;
            }
            let out = if w.token[0] == b'#' {
                // #136 = .375: a macro variable, converted where the analysis shows a length
                self.rounded = false;
                let out = self.expression(b, i, self.length);
                if let Ok(out) = &out {
                    self.loop_parameter(b, w.token, out)?;
                }
                out.map(Some)
            } else if let Some(k) = k {
                if k == Kind::Count {
                    if let (Some(code), true) = (&out_code, units_at == Some(i)) {
                        Ok(Some(code.clone().into_bytes()))
                    } else if letter == b'G' && self.renumbers() {
                        Ok(Some(self.g_in_target(w.token)))
                    } else if self.decimal_count(letter) && role != Some(Role::Selector) {
                        // (a selector is the whole number written, whatever the formats)
                        self.value(b, i, Kind::Code, false, false).map(Some)
                    } else if self.length != ONE && w.plain.is_none() && plain(w.token).is_none() {
                        // (`plain_word(w).is_none()`, which is Some wherever the tokenizer
                        // found the word plain: its parts are not split for the question)
                        // a count or selector given by a parameter (`G05.1 Q#1`, `T#1`):
                        // kept, and refused where the parameter is one the conversion
                        // scales as a length (the word would read its new value)
                        self.expression(b, i, ONE).map(Some)
                    } else {
                        self.count(w.token)
                    }
                } else {
                    self.value(b, i, k, dwell, set_position).map(Some)
                }
            } else {
                continue;
            };
            let out = out.map_err(|mut e| {
                e.column = crate::text::column(b.text, w.start);
                e
            })?;
            let Some(out) = out else { continue };
            if sinumerik_r && w.token.contains(&b'=') {
                // R1=50: a SINUMERIK's R parameter set, watched as a macro variable is
                self.loop_parameter(b, w.token, &out)?;
            }
            let differs = out != w.token;
            if differs && dwell {
                self.inch_dwell(b, i, letter)?;
            }
            if distance_unknown && differs {
                let column = crate::text::column(b.text, w.start);
                self.inherited = Some((text(w.token), b.line, column));
            }
            if differs {
                self.changed += 1;
                new = true;
                changed[i] = Some(out);
            } else {
                self.recycle(out);
            }
        }
        if let Some(lead) = self.lead_watch.take() {
            if let Some((exact, rounded)) = self.lead_rounded.take() {
                let z_before = z_before.filter(|_| !self.z_after_cycle);
                self.lead_note(b, lead, exact, rounded, z_before);
            }
        }
        let returns = gs
            .iter()
            .any(|&g| (70..=89).contains(&g) || (g == 92 && self.c.lathe))
            || g_unread
                && b.words.iter().any(|w| {
                    w.token[0].eq_ignore_ascii_case(&b'G')
                        && crate::meaning::code(&w.token[1..]) == Some((33, 1))
                });
        if returns {
            self.z_after_cycle = true;
        } else if z_word {
            self.z_after_cycle = false;
        }
        if polar.is_some() || meanings.data {
            // after a polar move or a tilted plane, where the axes are in the program's
            // coordinates is not followed: an increment after it starts afresh
            for (i, &data) in data_axes.iter().enumerate() {
                if data {
                    self.src_pos[i] = None;
                    self.out_pos[i] = None;
                    self.abs_raw[i] = None;
                }
            }
        }
        if machine_move {
            self.src_pos = [None; 26];
            self.out_pos = [None; 26];
            self.abs_raw = [None; 26];
            self.pos_units = [None; 26];
            self.out_at = [None; 26];
            self.out_mm = [None; 26];
        }
        // After M02/M30 the control is in its reset state: G90, G94, no cycle... A new program
        // in the file starts from it, in the units the program before selected where the
        // control keeps them (`ModalSettings::units_kept_at_end`); before its first value it
        // is given its units code, or refused where its units cannot be known (above).
        // M99 returns from a subprogram; on a SINUMERIK M17 does (and RET, a statement), on a
        // HEIDENHAIN nothing does (its M99 calls a cycle: `crate::dialect::return_code`)
        let code = crate::dialect::return_code(self.c.family);
        let returns = code.is_some_and(|code| ms.contains(&code));
        if let (true, Some(code)) = (returns, code) {
            self.inherited_distance(b.line, &format!("M{code}"))?;
            self.inherited_speed(b.line, &format!("M{code}"))?;
        }
        let ends = ms.iter().any(|&m| m == 2 || m == 30);
        if let (true, Some((at, word))) = (returns || (ends && self.loops), &self.rounded_step) {
            let why = if returns {
                format!(
                    "the subprogram (it returns at line {}) runs it again at each call and \
                     each repeat of M98 L",
                    b.line
                )
            } else {
                "the program's jumps or loops may run it again".to_string()
            };
            let note = format!(
                "line {at}: the incremental move {word} is rounded to the target's format, and \
                 {why}: every run adds that rounding (up to half a step) to the position; \
                 check the repeated path, or program it in G90"
            );
            self.note(note);
        }
        if returns || ends {
            self.fresh_program();
        }
        self.split.ended(returns || ends);
        let units_before = self.modal.state.units;
        self.modal.end_of_block(&ms);
        if ends {
            // the straight path stops here (an optional or a conditional end aside): what
            // follows runs only where a jump comes to it
            if b.skip.is_empty()
                && b.skip_within.is_none()
                && !b.statements.iter().any(|s| s.1 == StatementKind::Flow)
            {
                self.flow.ends();
                if let Some(feed_flow) = &mut self.feed_flow {
                    feed_flow.ends();
                }
            }
            self.jumped_in = false;
            // the program after the end has its units looked at afresh (above)
            self.units_seen = false;
            self.lacked_in_force = None;
            self.target_no_motion = self.motion_differs().then_some(0);
            self.ended_on = Some(b.line);
            let reset = self.reset_units;
            self.units_doubt = (self.c.source_detected && units_before != reset).then_some((
                b.line,
                units_before,
                reset,
            ));
            if !self.c.target_units_kept {
                // the target control returns to its basic system, lengths and feed
                self.out_length_units = self.c.target_units;
                self.out_feed_units = self.c.target_units;
            }
        }
        self.follow_units();
        self.close_blanks(b, &mut new, &mut changed[..count]);
        if self.c.upper_case {
            self.upper_case(b, &mut new, &mut changed[..count]);
        }
        if !new && insert.is_none() && self.c.spacing == Spacing::Keep && statements.is_empty() {
            self.replacements = changed;
            self.codes = (gs, ms);
            return Ok(None);
        }
        let replacements = &mut changed[..count];
        let line = if statements.is_empty() {
            self.text(b, replacements, insert.as_deref())
        } else {
            // the statements' new texts in place, the words written around them as always
            let text = splice(b.text, &statements);
            let at = |offset: usize| shifted(offset, &statements);
            let words: Vec<WordSpan<'_>> = b
                .words
                .iter()
                .map(|w| WordSpan {
                    token: w.token,
                    start: at(w.start),
                    end: at(w.end),
                    plain: w.plain,
                    digits: w.digits,
                })
                .collect();
            let comments: Vec<(usize, &[u8])> =
                b.comments.iter().map(|&(o, c)| (at(o), c)).collect();
            let kept: Vec<(usize, StatementKind, &[u8])> = b
                .statements
                .iter()
                .map(|&(o, kind, t)| {
                    let new = statements.iter().find(|r| r.0 == o);
                    (at(o), kind, new.map_or(t, |r| r.2.as_slice()))
                })
                .collect();
            let moved = BlockIn {
                text: &text,
                words: &words,
                comments: &comments,
                statements: &kept,
                skip_within: b.skip_within.map(|(o, t)| (at(o), t)),
                ..*b
            };
            self.text(&moved, replacements, insert.as_deref())
        };
        for buffer in changed[..count].iter_mut().filter_map(Option::take) {
            self.recycle(buffer);
        }
        self.replacements = changed;
        self.codes = (gs, ms);
        Ok(Some(line))
    }

    /// A plain word (an address and a number) written with blanks in it that the target reads
    /// otherwise (review 20, finding 2): a Haas NGC alarms on `X 1.5` and `X- 1.5` (TG100), and
    /// `X1 2.5`, LinuxCNC's X12.5 (it reads a number through blanks), is on any other control
    /// a word X1 and a number without an address. Such a word is written as its token, the
    /// blanks dropped, in upper and lower case alike; elsewhere the word's blanks are kept.
    fn close_blanks(
        &mut self,
        b: &BlockIn<'_>,
        new: &mut bool,
        replacements: &mut [Option<Vec<u8>>],
    ) {
        let through = self.c.family == Family::LinuxCnc && self.c.target_family != Family::LinuxCnc;
        if !(self.c.target_ngc || through) {
            return;
        }
        let closed = |w: &WordSpan<'_>| -> bool {
            // a span as long as its token holds no blank beside it (a span with a blank that
            // spells the token is longer), so most words are passed over without a look at
            // their bytes
            if w.end.checked_sub(w.start) == Some(w.token.len()) {
                return false;
            }
            let Some(text) = b.text.get(w.start..w.end) else {
                return false;
            };
            let blank = |c: &u8| *c == b' ' || *c == b'\t';
            if !text.iter().any(blank) {
                return false;
            }
            // (the span holds the token's bytes and blanks only: no comment inside it)
            if !spells(text, w.token) {
                return false;
            }
            if !bare_number_word(w.token) {
                // a parameter's or an expression's word (review 21, finding 2): rs274 drops
                // the blanks inside its numbers too (`X#1 0` is X#10, `X[1 0]` X[10], `#2 0=3`
                // #20=3), which the target reads as two values: such a word is written as its
                // token, all its blanks dropped; one whose blanks stand only beside an
                // operator, a bracket or the address is read alike by both and kept
                return through && blank_inside_number(text);
            }
            // a blank after the number's first digit or point is LinuxCNC's alone; on a Haas
            // any blank in the word alarms
            let first_digit = text.iter().position(|c| c.is_ascii_digit() || *c == b'.');
            self.c.target_ngc || first_digit.is_some_and(|at| text[at..].iter().any(blank))
        };
        if !b.words.iter().any(closed) {
            return;
        }
        *new = true;
        for (slot, w) in replacements.iter_mut().zip(b.words) {
            if !closed(w) {
                continue;
            }
            match slot {
                None => *slot = Some(w.token.to_vec()),
                // a word written anew from its text (`#2 0=3` given a point, `#2 0=3.`): its
                // blanks dropped as well
                Some(written) => written.retain(|c| *c != b' ' && *c != b'\t'),
            }
        }
    }

    /// The block's words written in lower case (`g1 x[sin[30]]`), in upper case for a target
    /// that reads no lower case ([`ConvertConfig::upper_case`]): a lower-case address or
    /// function name is the upper-case one to the source (LinuxCNC reads a line in lower
    /// case, SINUMERIK does not tell them apart), and a FANUC or Haas reads only upper case
    /// (TG101). Comments are kept as written (any text there); statements are no matter here:
    /// between control families they are refused.
    fn upper_case(
        &mut self,
        b: &BlockIn<'_>,
        new: &mut bool,
        replacements: &mut [Option<Vec<u8>>],
    ) {
        if !b
            .words
            .iter()
            .any(|w| w.token.iter().any(u8::is_ascii_lowercase))
        {
            return;
        }
        *new = true;
        for (slot, w) in replacements.iter_mut().zip(b.words) {
            if let Some(token) = slot.as_mut() {
                token.make_ascii_uppercase(); // a word written anew: no blanks of its own
                continue;
            }
            if !w.token.iter().any(u8::is_ascii_lowercase) {
                continue;
            }
            // the word as written, its blanks kept (review 19, finding 5: `x [1 + 2]` was
            // written `X[1+2]`, the token's text), when its span lies in the block's text
            let written = b.text.get(w.start..w.end).filter(|t| spells(t, w.token));
            *slot = Some(match written {
                Some(text) => upper_outside(text, w.start, b.comments),
                None => w.token.to_ascii_uppercase(),
            });
        }
    }

    /// A G code the target reads in another modal group than the source
    /// ([`crate::machine::differing_codes`]), or an arc whose centre the two controls read differently
    /// (`checks.ijk`): the block cannot mean the same on the target, so it is refused. The G
    /// codes (`letter` G) are compared before the words between families
    /// ([`crate::between::block`]), the M codes (`letter` M) after them: a subprogram call's
    /// refusal there says more than the code table's.
    /// Under a change of units, a block with a G code the source's list lacks (FANUC mill
    /// `G71.7`, system B/C lathe `G33` on a system A profile, Haas lathe `G241`): the control
    /// alarms on it, or runs the macro its parameters name, so what its other words are to it
    /// (`Q200` a block number or a length, `P` a count or a dwell) is not known, and no
    /// conversion of them can be verified. Each word whose role a code decides is refused,
    /// located; the code itself is carried, and so are the words whose role no code changes:
    /// the axes (lengths, or degrees unconverted, as a cycle's or a macro's arguments too),
    /// the feed, the spindle speed, the tool, the M codes and the sequence number.
    ///
    /// Without a change of units, only the words a role would rewrite are refused: one
    /// without a decimal point that the source reads in least increments (a FANUC's `Q200`,
    /// written `Q0.02` as a length, is block N200 to a turning cycle).
    /// Whether the source control's list lacks G code `g`: a number past the end of its table
    /// too (Haas's ends at G269, so `G310` was taken for a code of the list and its words
    /// converted by checks.pqr's roles).
    fn src_lacks(&self, g: i64) -> bool {
        let table = &self.c.src_modal.lacks_g;
        self.c.src_modal.lacks(g)
            || (!table.is_empty() && usize::try_from(g).is_ok_and(|n| n >= table.len()))
    }

    fn lacked_code_words(&mut self, b: &BlockIn<'_>, g_word: bool) -> Result<(), ConvertError> {
        let units = self.length != ONE;
        // a motion code the source's list holds ends the lacked code's motion (as the check
        // takes it: `Checker` makes the motion known again there); until then, under a change
        // of units, a later block's words of a motion's or cycle's role are refused as its own
        // are (`G241 X1. Z-.5` then `X.8 Q.2`: what Q is to the control is not known)
        if self.lacked_in_force.is_some() {
            let listed_motion = b.words.iter().any(|w| {
                w.token[0].eq_ignore_ascii_case(&b'G')
                    && code_number(&w.token[1..])
                        .filter(|n| n.is_whole())
                        .map(|n| n.trunc())
                        .is_some_and(|g| {
                            !self.src_lacks(g)
                                && (matches!(g, 0..=3 | 73..=89) || self.c.src_modal.own_motion(g))
                        })
            });
            if listed_motion {
                self.lacked_in_force = None;
            } else if !units {
                // under a change of decimal style, the same words go by the one rule for a word
                // of unknown role (kept where both controls read its text as the same number,
                // else refused at its column), as the lacked code's own block's do (below)
                for w in b.words.iter() {
                    let letter = w.token[0].to_ascii_uppercase();
                    if b"PQRIJKEL".contains(&letter) {
                        self.cycle[slot(letter)].get_or_insert(Role::Parameter);
                    }
                }
            } else {
                let role =
                    |w: &&WordSpan<'_>| b"PQRIJKEL".contains(&w.token[0].to_ascii_uppercase());
                if let Some(w) = b.words.iter().find(role) {
                    let (code, line) = self.lacked_in_force.clone().unwrap_or_default();
                    return Err(ConvertError {
                        message: format!(
                            "{}: the motion in force is that of {code} (line {line}), which is not in the \
                            source control's G code list (the control alarms on it, or runs the macro its \
                            parameters name), so what this word is to it (a length, a block number, a count) \
                            is not known and the change of units cannot convert it; write a motion code of \
                            the control's list before it",
                            text(w.token)
                        ),
                        clause: "profile",
                        column: crate::text::column(b.text, w.start),
                        line: None,
                    });
                }
            }
        }
        if !g_word {
            return Ok(()); // no G word: no code the list lacks (below)
        }
        let in_increments = |w: &WordSpan<'_>| {
            let letter = w.token[0].to_ascii_uppercase();
            let digits = &w.token[1..];
            self.c
                .src_increments
                .as_ref()
                .is_some_and(|except| !except.contains(&letter))
                && !digits.contains(&b'.')
                && digits
                    .iter()
                    .all(|c| c.is_ascii_digit() || *c == b'-' || *c == b'+')
        };
        // the converter's cycle table gives this block's words their roles from the maker's
        // manual (an Okuma lathe's LAP G88 thread, 5238-E, which the profile's code list
        // lacks): those roles, and the table's own refusals, hold
        let table_roles = self.cycle.iter().any(Option::is_some);
        if table_roles {
            return Ok(());
        }
        let lacked = b.words.iter().find_map(|w| {
            if !w.token[0].eq_ignore_ascii_case(&b'G') {
                return None;
            }
            let number = code_number(&w.token[1..])?;
            let not_held = if number.is_whole() {
                self.src_lacks(number.trunc())
            } else {
                let held = self.c.src_decimal_g.as_ref()?;
                !held.contains(&number.to_string())
            };
            not_held.then(|| text(w.token))
        });
        let Some(code) = lacked else {
            return Ok(());
        };
        self.lacked_in_force = Some((code.clone(), b.line));
        let kept = b"NOGMSTFXYZUVWABC";
        let own = |w: &&WordSpan<'_>| !kept.contains(&w.token[0].to_ascii_uppercase());
        if !units && !b.words.iter().filter(own).any(in_increments) {
            // under a change of decimal style only: what these words are to the control is not
            // known either, so none is read by a format its role does not give and written
            // anew (`G310 Q2.5 R1.` was written `Q2500 R1000`, "verified"): the one rule for a
            // word of unknown role, kept exactly where both controls read its text as the same
            // number, else refused at its column (`Converter::value`)
            for w in b.words.iter() {
                let letter = w.token[0].to_ascii_uppercase();
                if letter.is_ascii_uppercase() && !kept.contains(&letter) {
                    self.cycle[slot(letter)] = Some(Role::Parameter);
                }
            }
            return Ok(());
        }
        let refused: Vec<&WordSpan<'_>> = b
            .words
            .iter()
            .filter(|w| !kept.contains(&w.token[0].to_ascii_uppercase()))
            .filter(|w| units || in_increments(w))
            .collect();
        let Some(w) = refused.first() else {
            return Ok(());
        };
        let words: Vec<String> = refused.iter().map(|w| text(w.token)).collect();
        Err(ConvertError {
            message: format!(
                "{}: {code} is not in the source control's G code list (the control alarms on \
                 it, or runs the macro its parameters name), so what {} to it (a length, a \
                 block number, a count) is not known and {} cannot convert {}; write the \
                 block with a code of the control's list",
                words.join(" "),
                if words.len() == 1 {
                    "this word is"
                } else {
                    "these words are"
                },
                if units {
                    "the change of units"
                } else {
                    "writing it with a decimal point"
                },
                if words.len() == 1 { "it" } else { "them" },
            ),
            clause: "profile",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// An M code gives the block's P, Q and R no known role ([`m_code_roles`]; as for a G65
    /// call or a G code the list lacks): under a change of units or of decimal style they are
    /// kept as written or refused. A role a code of the block gives them stands.
    fn unlisted_m_words(&mut self, ms: &[i64], pqr_code: bool) {
        if let Some(list) = &self.c.src_listed {
            m_code_roles(list, ms, pqr_code, &mut self.cycle);
        }
    }

    fn same_meaning(&mut self, b: &BlockIn<'_>, letter: u8) -> Result<(), ConvertError> {
        // (no code differs between the two profiles, the common case of a conversion on one
        // control: no G or M word's number to read)
        let codes_differ = !self.c.differing_codes.is_empty() || self.c.listed_codes.is_some();
        for w in b.words.iter().filter(|_| codes_differ) {
            let m = w.token[0].eq_ignore_ascii_case(&b'M');
            if !w.token[0].eq_ignore_ascii_case(&letter) {
                continue;
            }
            let number = std::str::from_utf8(&w.token[1..]).unwrap_or("");
            let number = number.trim_start_matches('0');
            let number = if number.is_empty() || number.starts_with('.') {
                format!("0{number}")
            } else {
                number.to_string()
            };
            // (a units code is the converter's to write: the target's own)
            // (as the source writes them: a lathe of G code system C's G70/G71, which the
            // modal settings hold by system A's numbers)
            let modal = &self.c.src_modal;
            let units = [modal.inch, modal.metric]
                .map(|n| modal.g_system.from_a(n).unwrap_or(n).to_string());
            if !m && units.contains(&number) {
                continue;
            }
            let number = if m { format!("M{number}") } else { number };
            if let Some((_, a, t)) = self.c.differing_codes.iter().find(|c| c.0 == number) {
                return Err(ConvertError {
                    message: format!(
                        "{}: the source and target controls give this code different \
                         meanings ({} on the source, {} on the target, by their profiles); \
                         tapegate does not translate it: write the target's code for it",
                        text(w.token),
                        a,
                        t
                    ),
                    clause: "codes",
                    column: crate::text::column(b.text, w.start),
                    line: None,
                });
            }
            let unlisted = self.c.listed_codes.as_ref().is_some_and(|lists| {
                lists.iter().all(|listed| {
                    listed
                        .binary_search_by(|(c, _)| c.as_str().cmp(&number))
                        .is_err()
                })
                    // (a code with letters or signs in its number is the words' to refuse)
                    && number.trim_start_matches('M').bytes().all(|c| c.is_ascii_digit() || c == b'.')
            });
            if unlisted && !m && self.c.target_alarm_g {
                // (a LinuxCNC configuration may REMAP a G code of G0-G99.9 its tables leave
                // blank, to a function of its own: no reason to take it for the source's)
                let alarms = if self.c.target_family == Family::LinuxCnc {
                    "alarms on a G code its table lacks unless its configuration remaps it \
                     (LinuxCNC's rs274: \"Unknown g code used\"; its check: TG307 naming \
                     REMAP, or TG306 past G99.9)"
                } else {
                    "alarms on a G code its table lacks (its check: TG306)"
                };
                return Err(ConvertError {
                    message: format!(
                        "{}: neither the source's nor the target's profile lists this code, and \
                         the target control {alarms}; on the source it is an option or a macro \
                         call by parameter: write the target's code for its function",
                        text(w.token)
                    ),
                    clause: "codes",
                    column: crate::text::column(b.text, w.start),
                    line: None,
                });
            }
            if unlisted && !self.unlisted_noted.contains(&number) {
                self.unlisted_noted.push(number.clone());
                let whose = if m {
                    "the machine builder's M function (its PLC decodes it)"
                } else {
                    "an option or the machine builder's code (a control without it alarms)"
                };
                let note = format!(
                    "line {}: {}: neither the source's nor the target's profile lists this \
                     code; its meaning is {whose}, carried as written here and wherever it \
                     stands: check that the target machine's builder gives it the same function",
                    b.line,
                    text(w.token)
                );
                self.note(note);
            }
        }
        if letter == b'G' && !self.c.one_group_codes.is_empty() {
            // (a units code is the converter's to write: the target's own, as above)
            let modal = &self.c.src_modal;
            let units = [modal.inch, modal.metric].map(|n| modal.g_system.from_a(n).unwrap_or(n));
            let mut seen: Vec<i64> = Vec::new();
            for w in b.words.iter() {
                let Some(n) = w.token[0]
                    .eq_ignore_ascii_case(&b'G')
                    .then(|| code_number(&w.token[1..]))
                    .flatten()
                    .filter(|n| n.is_whole())
                    .map(|n| n.trunc())
                    .filter(|n| !units.contains(n))
                else {
                    continue;
                };
                let pair = seen.iter().find_map(|&m| {
                    let (lo, hi) = (m.min(n), m.max(n));
                    self.c
                        .one_group_codes
                        .iter()
                        .find(|c| c.0 == lo && c.1 == hi)
                        .map(|c| (m, c.2.clone()))
                });
                if let Some((m, group)) = pair {
                    return Err(ConvertError {
                        message: format!(
                            "{}: the target's code table puts this code and G{m:02} of the \
                             same block in one modal group ({group}), the source's in two; \
                             the target refuses two codes of one group in a block (ISO \
                             6983-1 Annex E; its check: TG304): write them in two blocks",
                            text(w.token)
                        ),
                        clause: "codes",
                        column: crate::text::column(b.text, w.start),
                        line: None,
                    });
                }
                seen.push(n);
            }
        }
        let arc = letter == b'G'
            && matches!(self.modal.state.motion, Some(2 | 3))
            && self.modal.state.cycle.is_none();
        if let (Some((from, to)), true) = (self.c.ijk, arc) {
            if let Some(w) = b
                .words
                .iter()
                .find(|w| matches!(w.token[0].to_ascii_uppercase(), b'I' | b'J' | b'K'))
            {
                return Err(ConvertError {
                    message: format!(
                        "{}: the source control reads an arc centre's I J K as {}, the target \
                         as {}; tapegate does not recompute arc centres: give the arc by R or \
                         in the target's form",
                        text(w.token),
                        from,
                        to
                    ),
                    clause: "7.3",
                    column: crate::text::column(b.text, w.start),
                    line: None,
                });
            }
        }
        Ok(())
    }

    /// A length the source's cycle writes as a count of least input increments (the Fanuc
    /// lathe's `G76 P1200`) means that only to a control that reads the cycle by the same table:
    /// for a control of another dialect the count may be another number, so the block is
    /// refused.
    fn same_cycle_reading(&self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if self.c.same_cycle_table {
            return Ok(());
        }
        let Some(w) = b.words.iter().find(|w| {
            let letter = w.token[0].to_ascii_uppercase();
            letter.is_ascii_uppercase() && self.cycle[slot(letter)] == Some(Role::Increments)
        }) else {
            return Ok(());
        };
        Err(ConvertError {
            message: format!(
                "{}: this cycle writes a length as a count of least input increments, and the \
                 target control (of another dialect, or not a lathe) may not read it so; \
                 tapegate does not translate cycles between control families: convert for a \
                 profile of the program's own family",
                text(w.token)
            ),
            clause: "cycle",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// A mill's X word for a lathe that reads X as a diameter (`ConvertConfig::x_diameter`;
    /// FANUC 0i-TF B-64604EN "Diameter and radius programming", the Haas lathe and Okuma
    /// OSP-P200L manuals likewise): carried, `X10.` is 5 from the axis there, an arc's end and
    /// centre no longer agree (the target's check: TG403, TG405), and the mill's XY plane
    /// (G17, its reset) is not the lathe's (G18). tapegate does not double X, so the
    /// conversion stops at the first X word; a dwell's (G04 X) and a macro call's (G65/G66)
    /// X is no position. (The system A lathe profile refused most mill programs at their G90
    /// or G94 by its code table; systems B and C number those codes as a mill does.)
    ///
    /// The mirror (`ConvertConfig::x_radius`): a lathe's X, a diameter, for a target that
    /// reads X as a length from the origin (LinuxCNC starts in G8, X a radius: rs274 then
    /// refuses the lathe's R arcs, "Arc radius too small to reach end point", and moves every
    /// other X to twice its radius): refused at the first X word too.
    ///
    /// Both ways an X written as zero (`X0`, `X-0.`) passes: the spindle axis as a diameter
    /// and as a radius, and no increment under G91 (`G28 X0`, `G53 X0`, a lathe's drilling
    /// on the axis); the first X of another value (or a parameter's) is refused. For a target
    /// that is no lathe, a FANUC, Haas or Okuma lathe's U or W that moves the tool (an
    /// increment of X, a diameter, or of Z; on a FANUC or ISO mill an axis of its own moved to
    /// an absolute place, so `U0` and `W0` too) is refused, and for a lathe a mill's Y other
    /// than `Y0` (review 28).
    fn same_x_reading(&self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if !self.c.x_diameter && !self.c.x_radius {
            return Ok(());
        }
        // a FANUC, Haas or Okuma lathe's dwell by U (its time, as X) for a target that is no
        // lathe: there U is an axis, and its G04 has no time (the target's check: TG532; review
        // 29, finding 4: carried "ok")
        if self.c.x_radius
            && self.c.lathe
            && matches!(self.c.family, Family::MacroB | Family::Okuma)
            && self.c.target_family != Family::LinuxCnc
            && whole_g_code(b, &[4])
        {
            if let Some(w) = b
                .words
                .iter()
                .find(|w| w.token[0].eq_ignore_ascii_case(&b'U'))
            {
                return Err(ConvertError {
                    message: format!(
                        "{}: the source lathe's dwell time by U, which the target reads as an \
                         axis, not a time (its G04 would have none); tapegate does not rename \
                         it: write the dwell with the target's time word",
                        text(w.token)
                    ),
                    clause: "profile",
                    column: crate::text::column(b.text, w.start),
                    line: None,
                });
            }
        }
        // (a dwell's X is its time, a macro call's X its argument #24: no position)
        if whole_g_code(b, &[4, 65, 66]) {
            return Ok(());
        }
        // (G10's X: after the G10 rules, which name a form the target lacks first)
        if whole_g_code(b, &[10]) {
            return Ok(());
        }
        // a FANUC, Haas or Okuma lathe's U moving the tool is an increment of X, a diameter
        // too (a cycle's U is its allowance or depth: `uw_moves`)
        let u = self.c.x_radius && self.uw_moves.of_move();
        // X0 (U0) is the spindle axis read as a diameter and as a radius alike (and no
        // increment under G91): the same place on both machines; a parameter's or an
        // expression's value is not known here, so refused with any other number
        // its W moving the tool, an increment of Z, is on a FANUC or ISO mill an axis of its
        // own moved to an absolute place (LinuxCNC's: `lathe_uw_for_linuxcnc`); a mill's Y
        // has no axis on a lathe (review 28, from fix27's report: both were carried "ok")
        let w_axis = u && self.c.target_family != Family::LinuxCnc;
        let y_axis = self.c.x_diameter;
        let Some(w) = b.words.iter().find(|w| {
            let letter = w.token[0].to_ascii_uppercase();
            // (W0 and U0 too: no move on the lathe, a move to W0 or U0 on the mill)
            w_axis && (letter == b'W' || letter == b'U')
                || (letter == b'X' || u && letter == b'U' || y_axis && letter == b'Y')
                    && !literal_zero(&w.token[1..])
        }) else {
            return Ok(());
        };
        let letter = w.token[0].to_ascii_uppercase();
        if letter == b'W' {
            return Err(ConvertError {
                message: format!(
                    "{}: the source lathe reads W as an increment of Z, the target as an axis \
                     of its own moved to that place, so the move would be another; tapegate \
                     does not rename it: write the program for the target",
                    text(w.token)
                ),
                clause: "profile",
                column: crate::text::column(b.text, w.start),
                line: None,
            });
        }
        if letter == b'Y' {
            return Err(ConvertError {
                message: format!(
                    "{}: the source mill moves Y, an axis the target lathe's plane (G18, X and \
                     Z) does not hold; tapegate does not convert a mill's program for a lathe: \
                     write it for the lathe",
                    text(w.token)
                ),
                clause: "profile",
                column: crate::text::column(b.text, w.start),
                line: None,
            });
        }
        if self.c.x_radius && letter == b'U' {
            return Err(ConvertError {
                message: format!(
                    "{}: the source lathe reads U as an increment of X, a diameter (U20. moves \
                     10. from the spindle axis), the target as a length or an axis of its own, \
                     so the move would be another; tapegate does not halve nor rename it: write \
                     the program for the target",
                    text(w.token)
                ),
                clause: "profile",
                column: crate::text::column(b.text, w.start),
                line: None,
            });
        }
        if self.c.x_radius {
            return Err(ConvertError {
                message: format!(
                    "{}: the source lathe reads X as a diameter, the target as a length from \
                     the origin (X20. is 10. from the spindle axis on the lathe, 20. on the \
                     target), so every position and arc in X would be another; tapegate does \
                     not halve X: write the program for the target (on LinuxCNC, G7 reads X \
                     as a diameter)",
                    text(w.token)
                ),
                clause: "profile",
                column: crate::text::column(b.text, w.start),
                line: None,
            });
        }
        Err(ConvertError {
            message: format!(
                "{}: the source reads X as a length from the origin (a mill), the target lathe \
                 as a diameter (X10. is 5. from the spindle axis there), so every position and \
                 arc in X would be another; tapegate does not convert a mill's program for a \
                 lathe: write it for the lathe",
                text(w.token)
            ),
            clause: "profile",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// G10's X (and a lathe's U, its increment) between a lathe that reads X as a diameter and
    /// a target that reads it as a length, either way ([`Converter::same_x_reading`]): an
    /// offset's value on the X axis. A FANUC lathe reads it as a diameter or a radius by its
    /// parameters (B-63444EN/01, 8.4 "Diameter and radius programming": the tool offset's
    /// component by parameter No. 5004#1; the manual's table says nothing of the work
    /// offset's), so what the value is on the lathe is not known from the program. For a Haas
    /// or an Okuma lathe no source at hand says how its G10 reads X (the Haas G10 pages at hand
    /// are the mill's: L2, L10-L13, L20, R the value), so it is not known either. Refused at
    /// the word, the safe side, the message naming which of the two it follows. A value
    /// written as zero is the same offset either way.
    fn g10_x_reading(&self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        let lathe_source = self.c.x_radius;
        let Some(w) = b.words.iter().find(|w| {
            let letter = w.token[0].to_ascii_uppercase();
            (letter == b'X' || lathe_source && letter == b'U') && !literal_zero(&w.token[1..])
        }) else {
            return Ok(());
        };
        let (source, target) = if lathe_source {
            ("the source lathe", "the target as a length from the origin")
        } else {
            ("the source (a mill) as a length", "the target lathe")
        };
        let lathe_family = if lathe_source {
            self.c.family
        } else {
            self.c.target_family
        };
        let (why, safe) = if self.c.x_lathe_fanuc {
            (
                "a FANUC lathe reads an offset's X as a diameter or a radius by its parameters \
                 (B-63444EN/01, 8.4: the tool offset's by parameter No. 5004#1), which the \
                 program does not show"
                    .to_string(),
                "",
            )
        } else {
            (
                format!(
                    "no source at hand says whether a{} lathe's G10 reads an offset's X as a \
                     diameter or a radius (the Haas G10 pages at hand are the mill's; FANUC's \
                     B-63444EN/01, 8.4, makes it a parameter's choice on a FANUC)",
                    if lathe_family == Family::Okuma {
                        "n Okuma"
                    } else {
                        " Haas"
                    }
                ),
                ", and it is refused on the safe side",
            )
        };
        Err(ConvertError {
            message: format!(
                "{}: G10's offset value on the X axis, read by {source} and by {target}; \
                 {why}, so the offset may be another by a factor of two; tapegate does not \
                 halve nor double it{safe}: set the offset for the target",
                text(w.token)
            ),
            clause: "profile",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// An F word read by the source's reset feed mode where the target's reset feeds by
    /// another (`ConvertConfig::reset_feed`): per revolution on a FANUC or Haas lathe (its
    /// G99; FANUC 0i-TF B-64604EN "Feed per revolution"), per minute on a mill or LinuxCNC
    /// (G94), on an ISO 6983-1 control by clause 14 (G94, a lathe too: 14.4). Carried, `F0.2`
    /// mm/rev is 0.2 mm/min on the target, a mill's `F20.` in/min 20 in/rev on the lathe. A
    /// feed mode code written before the F is carried where the target reads its number as
    /// the same mode (a system B lathe's G95 for LinuxCNC), and refused at the code where it
    /// does not (a system A lathe's G99 is unassigned in ISO 6983-1's table; the codes'
    /// meanings refuse it for a mill first); with none written, the conversion stops at the
    /// first F word (a G65/G66 macro call's F is its argument #9).
    fn reset_feed_mode(&mut self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        let Some([source, target]) = self.c.reset_feed else {
            return Ok(());
        };
        if self.feed_mode_written {
            return Ok(());
        }
        let lathe = self.c.src_modal.fanuc_lathe;
        let name = |mode: i64| match mode {
            95 => "per revolution",
            93 => "by inverse time",
            _ => "per minute",
        };
        for &g in gs {
            let Some(mode) = crate::modal::feed_mode_code(lathe, g) else {
                continue;
            };
            if self.target_feed_mode(g) == Some(mode) {
                self.feed_mode_written = true;
                return Ok(());
            }
            let w = b
                .words
                .iter()
                .find(|w| {
                    w.token[0].eq_ignore_ascii_case(&b'G')
                        && self
                            .code_of(w.token)
                            .is_some_and(|n| self.c.src_modal.read_g(n) == g)
                })
                .or_else(|| first_word(b, b'G'));
            let at = w.map_or(1, |w| crate::text::column(b.text, w.start));
            let code = w.map_or_else(|| format!("G{g}"), |w| text(w.token));
            return Err(ConvertError {
                message: format!(
                    "{code}: the source's code of feed {}, whose number the target reads as \
                     another code or none (its reset feeds {}), so the F words after it would \
                     be read otherwise; tapegate does not write the feed mode, so the program \
                     cannot be converted to this target as it stands: write it for the target",
                    name(mode),
                    name(target)
                ),
                clause: "profile",
                column: at,
                line: None,
            });
        }
        if whole_g_code(b, &[65, 66]) {
            return Ok(());
        }
        let Some(w) = first_word(b, b'F') else {
            return Ok(());
        };
        // the code the source writes for its reset mode, where the target reads it alike
        let code = if lathe {
            let a = if source == 95 { 99 } else { 98 };
            self.c.src_modal.g_system.from_a(a)
        } else {
            Some(source)
        };
        let advice = match code
            .filter(|&c| self.target_feed_mode(self.c.src_modal.read_g(c)) == Some(source))
        {
            Some(c) => {
                format!("write G{c} before the first F in the source (both controls read it so)")
            }
            None => "the source's code of that mode is another code (or none) on the target, so \
                     the program cannot be converted to this target as it stands: write it for \
                     the target"
                .to_string(),
        };
        Err(ConvertError {
            message: format!(
                "{}: a feed {} by the source control's reset state (no feed mode code written \
                 before it), where the target's reset feeds {}, so the feed would be another; \
                 tapegate does not write the feed mode: {advice}",
                text(w.token),
                name(source),
                name(target)
            ),
            clause: "profile",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// The feed mode (`modal::feed_mode_code`) the target reads the source's code `g` (by
    /// the source's system A number) as, written as the conversion writes it: between two
    /// FANUC lathes of different G code systems by the target's number of the function, else
    /// by the number written.
    fn target_feed_mode(&self, g: i64) -> Option<i64> {
        let lathe = self.c.src_modal.fanuc_lathe;
        if self.renumbers() {
            return crate::modal::feed_mode_code(true, g);
        }
        let written = if lathe {
            self.c.src_modal.g_system.from_a(g)?
        } else {
            g
        };
        match self.c.target_g_system {
            Some(system) => crate::modal::feed_mode_code(true, system.to_a(written)),
            None => crate::modal::feed_mode_code(false, written),
        }
    }

    /// A FANUC or Haas lathe's T word (`T0101`: tool 1 with offset 1, the last two digits the
    /// offset number; FANUC 0i-TF B-64604EN "Tool offset", Haas lathe operator's manual "T
    /// Tool Function") for a target that reads T as one tool number (`ConvertConfig::
    /// lathe_tool_offset`): carried, `T0101` is tool 101 there (its check: TG604 above the
    /// largest tool number) and the offset is not applied. tapegate does not split the word
    /// into a tool and an offset word (the target's offset letter and its reading are its
    /// own), so the conversion stops at the T word.
    fn same_tool_word(&self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if !self.c.lathe_tool_offset {
            return Ok(());
        }
        // (a macro call's T is its argument #20, no tool)
        if whole_g_code(b, &[65, 66]) {
            return Ok(());
        }
        let Some(w) = first_word(b, b'T') else {
            return Ok(());
        };
        Err(ConvertError {
            message: format!(
                "{}: a FANUC or Haas lathe's T word is the tool number followed by the offset \
                 number (T0101: tool 1, offset 1), the target reads its T as one tool number \
                 (T0101 tool 101) and has no place in it for the offset; tapegate does not \
                 split the word: write the target's tool and offset words",
                text(w.token)
            ),
            clause: "profile",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// An arc given by its radius where the target control reads the radius from another
    /// letter (an Okuma lathe's L, another control's R): the target would read the arc
    /// without it, or the word as something else. tapegate does not rename words, so the
    /// conversion stops at the radius word.
    fn same_radius_letter(&self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        let (source, target) = (self.c.src_modal.arc_radius, self.c.target_arc_radius);
        if source == target || !matches!(self.modal.state.motion, Some(2 | 3)) {
            return Ok(());
        }
        // R is the radius where the source profile reads it as a length (a SINUMERIK's R1= is
        // a parameter)
        let radius = source != b'R' || self.c.pqr[2] == Role::Length;
        let Some(w) = b.words.iter().find(|w| {
            radius && w.token[0].eq_ignore_ascii_case(&source) && !w.token.contains(&b'=')
        }) else {
            return Ok(());
        };
        let message = if target == 0 {
            format!(
                "{}: the source control reads an arc's radius from {}, the target profile reads \
                 no radius (its R is a parameter: checks.pqr), so its control finds no centre \
                 for the arc; tapegate does not work out the centre: give the arc by its centre \
                 (I J K)",
                text(w.token),
                source as char
            )
        } else {
            format!(
                "{}: the source control reads an arc's radius from {}, the target control from \
                 {}; tapegate does not rename words: convert for a profile of the program's own \
                 family, or give the arc by its centre",
                text(w.token),
                source as char,
                target as char
            )
        };
        Err(ConvertError {
            message,
            clause: "7.3",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// LinuxCNC: the motion rs274ngc runs a block by (`motion_to_be`, interp_internal.cc
    /// `enhance_block`, as the check's `linuxcnc_runs` reads it), in tenths: the block's own
    /// motion code; else the mode in force where the block moves axes and has no code that
    /// takes them as data (G10, G28, G30, G52, G53, G92), or where it gives only I, J or K
    /// under G2/G3; else none. None where it depends on a mode in force that is not known
    /// (at the start, after o-word flow, a call, a `G#1`). Follows the mode in force: G5 and
    /// G5.1 leave it as it was (interp_convert.cc `convert_spline`).
    fn linuxcnc_block_motion(&mut self, b: &BlockIn<'_>) -> Option<Option<i64>> {
        let mut given = None;
        let mut data = false;
        for w in b.words {
            if !w.token[0].eq_ignore_ascii_case(&b'G') {
                continue;
            }
            match g_tenths(w.token) {
                Some(t) if crate::meaning::linuxcnc_motion_code(t) => given = given.or(Some(t)),
                Some(t) => data |= crate::meaning::linuxcnc_takes_axes(t),
                // a code written otherwise (`G#1`): the motion from here on is not known
                None => self.linuxcnc_motion = None,
            }
        }
        let before = self.linuxcnc_motion;
        if let Some(g) = given.filter(|&g| g != 50 && g != 51) {
            self.linuxcnc_motion = Some(g);
        }
        if given.is_some() {
            return Some(given);
        }
        let moves = b.words.iter().any(|w| {
            matches!(
                kind(w.token[0].to_ascii_uppercase()),
                Some(Kind::Axis | Kind::Angle)
            )
        });
        let ijk = b
            .words
            .iter()
            .any(|w| matches!(w.token[0].to_ascii_uppercase(), b'I' | b'J' | b'K'));
        if data || !(moves || ijk) {
            return Some(None);
        }
        match before {
            None => None,
            Some(m) if moves => Some(Some(m)),
            Some(m @ (20 | 30)) => Some(Some(m)),
            Some(_) => Some(None),
        }
    }

    /// LinuxCNC: an E word no code of its block uses (`meaning::linuxcnc_e_used`) is refused
    /// under a change of units: rs274ngc refuses the block, so the E has no meaning to
    /// convert by (G76's taper is a length, M66-M68's E a channel number). Where the motion
    /// mode a moving block runs is unknown (`motion` None), the E is converted as before (a
    /// G76's taper).
    /// An M98 P of more than four digits (leading zeros not counted, a sign or a point
    /// allowed) between controls that read it apart: on a FANUC the digits before the last
    /// four are the number of repetitions (0i-MB Operator's Manual B-64124EN/01, 12.3: "M98
    /// P51002 ... Call the subprogram (number 1002) five times"); on a Haas the program number,
    /// the repetitions by L (96-8000 Mill Operator's Manual, "M98 Sub Program Call": "M98 Pnnnn
    /// (Pnnnn is the number of the program being called) ... An Lnn count"), and on LinuxCNC
    /// the program number, the repetitions by L (rs274: `M98 P12345` runs O12345). Refused at
    /// the P wherever it stands in the block (review 29, finding 3; review 30, findings 1, 3,
    /// 4: LinuxCNC's P12345 to a FANUC was carried, a Haas's to LinuxCNC refused).
    fn m98_long_p(&self, b: &BlockIn<'_>, ms: &[i64]) -> Result<(), ConvertError> {
        let Some((from, to)) = self.c.m98_repeats else {
            return Ok(());
        };
        if from == to || !ms.contains(&98) {
            return Ok(());
        }
        let long = |digits: &[u8]| {
            let digits = digits
                .strip_prefix(b"+")
                .or_else(|| digits.strip_prefix(b"-"))
                .unwrap_or(digits);
            let whole = digits.split(|&c| c == b'.').next().unwrap_or(digits);
            whole.iter().all(u8::is_ascii_digit)
                && whole.iter().skip_while(|&&c| c == b'0').count() > 4
        };
        let Some(p) = b
            .words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&b'P') && long(&w.token[1..]))
        else {
            return Ok(());
        };
        // (a FANUC with the 8-digit program number option reads it as a Haas does: which
        // of the two a FANUC has, the program does not show, so both are said)
        let reading = |repeats: bool| {
            if repeats {
                "as the number of repetitions and the program number on a FANUC without the \
                 8-digit program number option (M98 P51002 calls O1002 five times: \
                 B-64124EN/01, 12.3), or as the program number, the repetitions by L, on one \
                 with it (0i-F, 30i: O51002 once; the FANUC profiles' O08)"
            } else {
                "as the program number, the repetitions by L"
            }
        };
        let advice = if from {
            "write the call with L (M98 P1002 L5), which both read alike"
        } else {
            "give the subprogram a number of four digits"
        };
        Err(ConvertError {
            message: format!(
                "{}: M98's P of more than four digits reads {} on the source and {} on the \
                 target; which of the two readings a FANUC takes, the program does not show, \
                 and tapegate does not split the P: {advice}",
                text(p.token),
                reading(from),
                reading(to)
            ),
            clause: "meaning",
            column: crate::text::column(b.text, p.start),
            line: None,
        })
    }

    /// A mill's canned cycle block with a K or an L between controls that read them apart: a
    /// FANUC counts the cycle's repeats in K (0i-MF operator's manual, "Canned cycle"), a Haas
    /// and LinuxCNC in L (Haas 96-8000, G81-G89; LinuxCNC G-code reference, "Canned cycles"),
    /// and a Haas's G73/G83 K is the least peck depth, a length. Carried as written, a FANUC's
    /// `G83 ... K4` drills one hole on a Haas, a Haas's `L3` is no FANUC cycle word and its
    /// `K0.05` a FANUC repeat count (review 52, F6: converted "ok"). tapegate does not move the
    /// count from one letter to the other: refused at the word, the block's cycle code or the
    /// one in force (a FANUC's or Haas's modal cycle; LinuxCNC's in its own block only, whose
    /// later blocks of hole positions are not followed here).
    ///
    /// Between controls of one letter too, a count that is not a whole number (a FANUC's
    /// `K2.5`, a Haas's or LinuxCNC's `L2.5`) is refused at the word: what the control does
    /// with it no source at hand says (rs274 refuses `L2.5`), and carried as written under a
    /// change of units it stayed a count no one knows (review 52, F11; the checker's TG544,
    /// TG412). K0, a whole count, is kept.
    fn cycle_repeat_words(&self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        let Some((count, to)) = self.c.cycle_repeats else {
            return Ok(());
        };
        // (a lathe's drilling cycles are G83-G89, their K the count: 0i-TF "Canned cycle for
        // drilling"; its G73-G76 are the multiple repetitive cycles, whose K is no count. A
        // non-whole count is refused there as on a mill: review 56d F10)
        let lathe = self.c.lathe;
        let cycle = |g: i64| {
            if lathe {
                matches!(g, 83..=89)
            } else {
                matches!(g, 73 | 74 | 76 | 81..=89)
            }
        };
        if !(self.cycle_code.code().is_some_and(cycle) || gs.iter().copied().any(cycle)) {
            return Ok(());
        }
        // (a Haas's G73/G83 K is a length, its count L; a FANUC's G73/G83 K is its count,
        // with a point or without, beside I or J too: review 56a, F3, F8)
        let fraction = b.words.iter().find(|w| {
            w.token[0].eq_ignore_ascii_case(&count)
                && std::str::from_utf8(&w.token[1..])
                    .ok()
                    .and_then(Dec::parse)
                    .is_some_and(|n| !n.is_whole())
        });
        if let Some(w) = fraction {
            return Err(ConvertError {
                message: format!(
                    "{}: a canned cycle's repeat count that is not a whole number; what the \
                     control does with it (an alarm, a rounding) no source at hand says, and \
                     tapegate does not carry a count it cannot read: write a whole number",
                    text(w.token),
                ),
                clause: "cycle",
                column: crate::text::column(b.text, w.start),
                line: None,
            });
        }
        if count == to || lathe {
            return Ok(());
        }
        let Some(w) = b
            .words
            .iter()
            .find(|w| matches!(w.token[0].to_ascii_uppercase(), b'K' | b'L'))
        else {
            return Ok(());
        };
        let reading = |letter: u8| {
            if letter == b'K' {
                "a FANUC counts a canned cycle's repeats in K"
            } else {
                "a Haas and LinuxCNC count a canned cycle's repeats in L (a Haas's G73/G83 K is \
                 the least peck depth)"
            }
        };
        Err(ConvertError {
            message: format!(
                "{}: {} on the source, and {} on the target: carried as written the cycle \
                 drills another number of holes or pecks to another depth; tapegate does not \
                 move the count between letters: write it in the target's",
                text(w.token),
                reading(count),
                reading(to),
            ),
            clause: "cycle",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// A FANUC or Haas M98 sharing its block with other words (`G1 X10. F100. M98 P100`: the
    /// move, then the call), which LinuxCNC reads only as its block's first word with its P
    /// and L alone ([`crate::meaning::linuxcnc_m98_stray`]; review 28, finding 3: converted
    /// "ok", and rs274 refused it, "Unknown m code used: M98"). Refused, naming the word.
    fn linuxcnc_m98_alone(&self, b: &BlockIn<'_>, ms: &[i64]) -> Result<(), ConvertError> {
        if !ms.contains(&98) {
            return Ok(());
        }
        let is_m98 = |t: &[u8]| {
            t.first().is_some_and(|c| c.eq_ignore_ascii_case(&b'M'))
                && t.len() > 1
                && t[1..].iter().all(u8::is_ascii_digit)
                && t[1..].iter().skip_while(|&&c| c == b'0').eq(b"98".iter())
        };
        let Some(m98) = b.words.iter().position(|w| is_m98(w.token)) else {
            return Ok(());
        };
        let at = b.words[m98].start;
        let mut letters: Vec<u8> = b
            .words
            .iter()
            .map(|w| w.token[0].to_ascii_uppercase())
            .collect();
        let before_it =
            b.comments.iter().any(|&(c, _)| c < at) || b.statements.iter().any(|&(c, _, _)| c < at);
        if before_it {
            letters.insert(0, b'(');
        }
        let shift = usize::from(before_it);
        let Some((i, before)) = crate::meaning::linuxcnc_m98_stray(&letters, m98 + shift) else {
            return Ok(());
        };
        let (word, start) = if before {
            (b.words[m98].token, at)
        } else {
            (b.words[i - shift].token, b.words[i - shift].start)
        };
        let why = if before {
            "LinuxCNC reads M98 only as its block's first word, after the N (rs274ngc \
             interp_read.cc read_o: \"Unknown m code used: M98\")"
        } else {
            "LinuxCNC reads M98 as a call with its P and L alone (rs274ngc interp_read.cc \
             read_o) and refuses the block's other words or does not run them"
        };
        Err(ConvertError {
            message: format!(
                "{} {}: {why}; tapegate does not split the block: put the other words in a \
                 block of their own before the M98",
                text(word),
                if before {
                    "after other words or a comment of its block"
                } else {
                    "after M98"
                }
            ),
            clause: "meaning",
            column: crate::text::column(b.text, start),
            line: None,
        })
    }

    fn linuxcnc_e_word(
        &self,
        b: &BlockIn<'_>,
        ms: &[i64],
        motion: Option<Option<i64>>,
    ) -> Result<(), ConvertError> {
        let Some(e) = b
            .words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&b'E'))
        else {
            return Ok(());
        };
        let Some(runs) = motion else {
            return Ok(()); // the motion in force is not known
        };
        let analog = ms.iter().any(|&m| (66..=68).contains(&m));
        let other = self.c.family != Family::LinuxCnc;
        if (self.length == ONE && !other) || crate::meaning::linuxcnc_e_used(runs, analog) {
            return Ok(());
        }
        let why = if other {
            "LinuxCNC refuses this block: the source control's E (a word of its own cycles, \
             such as an Okuma thread cycle's start shift; one the FANUC profiles do not \
             classify, TG134) has no LinuxCNC word that carries it; tapegate does not rewrite \
             it: remove it, or give the LinuxCNC code that uses it"
        } else {
            "LinuxCNC refuses this block, so E has no meaning the change of units could convert \
             it by (G70's end distance and G76's taper are lengths, M66-M68's E a channel \
             number); remove it, or give the code that uses it"
        };
        Err(ConvertError {
            message: format!(
                "{}: {} (rs274ngc): {why}",
                text(e.token),
                crate::meaning::LINUXCNC_E_UNUSED
            ),
            clause: if other { "meaning" } else { "6.4.7" },
            column: crate::text::column(b.text, e.start),
            line: None,
        })
    }

    /// A FANUC, Haas or Okuma lathe's U and W (increments of X and Z, or a cycle's
    /// allowances; an ISO 6983-1 lathe's secondary axes parallel to X and Z) converted for
    /// LinuxCNC, whose U and W are axes of their own, moved to an
    /// absolute position under G90 (rs274 of a machine without them: "Bad character 'u'
    /// used"): refused at the word. A dwell's U (seconds, a time word of the source's G04)
    /// is converted as a dwell; a W beside it is refused as any W is.
    fn lathe_uw_for_linuxcnc(&self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        if !self.c.lathe {
            return Ok(());
        }
        let dwell = gs.contains(&4);
        let Some(w) = b.words.iter().find(|w| {
            let letter = w.token[0].to_ascii_uppercase();
            matches!(letter, b'U' | b'W')
                && !w.token.contains(&b'=')
                && !(dwell && self.c.src_modal.dwell.contains(&letter))
        }) else {
            return Ok(());
        };
        let on = if w.token[0].eq_ignore_ascii_case(&b'U') {
            "X"
        } else {
            "Z"
        };
        let lower = (w.token[0].to_ascii_lowercase()) as char;
        let message = if self.c.family == Family::Iso {
            // ISO 6983-1, Annex A: U, W "secondary dimension parallel to X, Z" -- axes of
            // their own, not increments (review 23: the message said increments)
            format!(
                "{}: the source (ISO 6983-1, Annex A) reads U and W as secondary axes of their \
                 own, parallel to X and Z (a second slide); LinuxCNC reads U and W only on a \
                 machine configured with those axes (rs274 of a machine without them: \"Bad \
                 character '{lower}' used\"), and whether the target machine has them as the \
                 same slides the profiles do not say: tapegate does not carry them; write the \
                 move without U and W",
                text(w.token)
            )
        } else {
            format!(
                "{}: the source lathe reads U and W as increments of X and Z (or a cycle's \
                 allowances); LinuxCNC reads them as axes of their own, moved to an absolute \
                 position (rs274 of a machine without them: \"Bad character '{lower}' used\"); \
                 tapegate does not rewrite U W as G91 {on}: write the move in absolute X Z",
                text(w.token)
            )
        };
        Err(ConvertError {
            message,
            clause: "meaning",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// A G04 of another family with two time words (a FANUC or Haas lathe's `G04 X1. U1.`,
    /// `G04 P1000 U1.`, a mill's `G04 X1. P500`): LinuxCNC reads the time in one P, and two
    /// are refused by rs274 ("Multiple p words on one line"); which one the source control
    /// uses, or whether it alarms, the manuals tapegate has do not say. Refused at the
    /// second time word.
    fn linuxcnc_dwell_words(&self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        if !gs.contains(&4) {
            return Ok(());
        }
        let mut times = b.words.iter().filter(|w| {
            self.c
                .src_modal
                .dwell
                .contains(&w.token[0].to_ascii_uppercase())
                && !w.token.contains(&b'=')
        });
        let (Some(first), Some(second)) = (times.next(), times.next()) else {
            return Ok(());
        };
        Err(ConvertError {
            message: format!(
                "{}: a second time word in the dwell's block (beside {}); LinuxCNC reads a \
                 dwell's time in one P word and refuses two (rs274: \"Multiple p words on one \
                 line\"), and which of the two the source control dwells by, tapegate's manuals \
                 do not say: write one time word",
                text(second.token),
                text(first.token)
            ),
            clause: "dwell",
            column: crate::text::column(b.text, second.start),
            line: None,
        })
    }

    /// An F in a G04 block that is a dwell's time on one control and a feed on the other: ISO
    /// 6983-1 (clause 13), an Okuma or a HEIDENHAIN reads `G04 F2.` as the dwell's time, a
    /// FANUC or Haas control reads G04's time in X or P only (the FANUC machining-center
    /// manuals, "Dwell": "G04 X_ ; or G04 P_ ;"; the lathe's adds U), F there being the feed.
    /// Carried as written, the time would become a feed (and the block a dwell without its time)
    /// or the feed a second time; the unit the ISO and Okuma sources read a dwell's F in is not
    /// in tapegate's sources, so it is not rewritten as X or P: refused at the F. Between two
    /// families that both dwell by F (SINUMERIK's G4 F, HEIDENHAIN's G04 F) `dwell_time` judges
    /// it.
    fn dwell_feed_words(&self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        if !gs.contains(&4) || self.c.family == self.c.target_family {
            return Ok(());
        }
        let source = self.c.src_modal.dwell.contains(&b'F');
        let target = crate::word::dwell_words(self.c.target_family, self.c.lathe).contains(&b'F');
        if source == target || (source && self.c.target_family != Family::MacroB) {
            return Ok(()); // (to LinuxCNC: `dwell_time` refuses a dwell's F with its reason)
        }
        let Some(w) = b
            .words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&b'F') && !w.token.contains(&b'='))
        else {
            return Ok(());
        };
        let message = if source {
            format!(
                "{}: the dwell's time by F, which the target control reads as a feed, not as a \
                 dwell (a FANUC or Haas G04 takes its time in X or P: the FANUC \
                 machining-center manuals, \"G04 X_ ; or G04 P_ ;\", the lathe's adds U); the \
                 unit the source reads a dwell's F in, tapegate's sources do not say: write the \
                 dwell's time as the target's (G04 X in seconds with its point, or P in \
                 milliseconds)",
                text(w.token)
            )
        } else {
            format!(
                "{}: a feed in the dwell's block, which the target control reads as the \
                 dwell's time (ISO 6983-1, clause 13: G04's time by F; SINUMERIK: \"Dwell time \
                 (G4)\", G4 F in seconds), not as a feed: write the feed in a block of its own",
                text(w.token)
            )
        };
        Err(ConvertError {
            message,
            clause: "dwell",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// Another family's D or H word in a block whose codes LinuxCNC does not read it with:
    /// rs274 refuses the block ("D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or
    /// G96 to use it", "H word with no G43 or G76 to use it", interp_check.cc
    /// `check_other_codes`), where a FANUC or Haas keeps the offset number for a later
    /// G41/G42 or G43 (or cancels with G49 H0): refused at the word (FANUC and Haas sources). A G65/G66 macro call's
    /// D and H are its arguments, left to the call's own conversion.
    fn linuxcnc_d_h_words(&self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        // (a SINUMERIK's D, its tool edge, is refused by its own meaning: between.rs)
        if self.c.family != Family::MacroB || gs.iter().any(|&g| matches!(g, 65 | 66)) {
            return Ok(());
        }
        let tenths: Vec<i64> = b
            .words
            .iter()
            .filter(|w| w.token[0].eq_ignore_ascii_case(&b'G'))
            .filter_map(|w| g_tenths(w.token))
            .collect();
        let runs = tenths
            .iter()
            .copied()
            .find(|&t| crate::meaning::linuxcnc_motion_code(t))
            .or(self.linuxcnc_motion);
        let word = |letter: u8| {
            b.words
                .iter()
                .find(|w| w.token[0].eq_ignore_ascii_case(&letter) && !w.token.contains(&b'='))
        };
        let (w, message, holds) = if let Some(w) =
            word(b'D').filter(|_| !crate::meaning::linuxcnc_d_used(&tenths, runs))
        {
            (
                w,
                crate::meaning::LINUXCNC_D_UNUSED,
                "D as the cutter radius offset number, kept for a later G41/G42",
            )
        } else if let Some(w) =
            word(b'H').filter(|_| !crate::meaning::linuxcnc_h_used(&tenths, runs))
        {
            (
                w,
                crate::meaning::LINUXCNC_H_UNUSED,
                "H as an offset number of its own (a tool length one kept for a later G43, G49 \
                 H0's cancel, or beside G41/G42 the radius one a parameter may give it)",
            )
        } else {
            return Ok(());
        };
        Err(ConvertError {
            message: format!(
                "{}: {message} (rs274ngc): LinuxCNC refuses this block, where the source \
                 control reads {holds}; tapegate does not move the word: write it in the \
                 block of the code that uses it",
                text(w.token)
            ),
            clause: "meaning",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// Another family's I, J, K, L, P, Q or R word in a block where no code LinuxCNC runs it
    /// by uses it (`meaning::linuxcnc_word_used`, which the check's TG412 reads too): rs274
    /// refuses the block with its message ("R word with no g code that uses it", interp_check.cc
    /// `check_other_codes`), where the source control read the word with its own meaning (a
    /// FANUC `G01 X1 R5` its corner, `G00 X1 P2`, a `K` repeat count of a drilling cycle):
    /// refused at the word. Nothing is said where the motion the block runs is not known
    /// (`motion` None), nor of a G65/G66 macro call's arguments (the call's own conversion).
    fn linuxcnc_data_words(
        &self,
        b: &BlockIn<'_>,
        gs: &[i64],
        ms: &[i64],
        motion: Option<Option<i64>>,
    ) -> Result<(), ConvertError> {
        let Some(runs) = motion else {
            return Ok(());
        };
        // (most blocks, plain moves, hold none of the letters: no codes read for them)
        let data = |w: &WordSpan<'_>| {
            crate::meaning::LINUXCNC_DATA_LETTERS.contains(&w.token[0].to_ascii_uppercase())
        };
        if !b.words.iter().any(data) || gs.iter().any(|&g| matches!(g, 65 | 66)) {
            return Ok(());
        }
        let tenths: Vec<i64> = b
            .words
            .iter()
            .filter(|w| w.token[0].eq_ignore_ascii_case(&b'G'))
            .filter_map(|w| g_tenths(w.token))
            .collect();
        let Some((w, letter)) = b.words.iter().find_map(|w| {
            let letter = w.token[0].to_ascii_uppercase();
            (crate::meaning::LINUXCNC_DATA_LETTERS.contains(&letter)
                && !w.token.contains(&b'=')
                && !crate::meaning::linuxcnc_word_used(letter, &tenths, ms, runs))
            .then_some((w, letter))
        }) else {
            return Ok(());
        };
        let motion = match runs {
            Some(t) if t % 10 == 0 => format!("runs G{} there", t / 10),
            Some(t) => format!("runs G{}.{} there", t / 10, t % 10),
            None => "runs no motion there".to_string(),
        };
        Err(ConvertError {
            message: format!(
                "{}: {} (rs274ngc): LinuxCNC refuses this block, which {motion}, where the \
                 source control read {} as a word of its own; tapegate does not rewrite or move \
                 the word: remove it, or write it in the block of the code that uses it",
                text(w.token),
                crate::meaning::linuxcnc_unused(letter),
                letter as char
            ),
            clause: "meaning",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// A FANUC or Haas arc's P (`G02 X2. Y0 R0.5 P1`), where no other code of the block
    /// uses P: LinuxCNC runs it as the number of the helix's turns (G-code reference, G2/G3:
    /// "P - number of turns"), a meaning no FANUC or Haas page at hand gives P in an arc (the
    /// FANUC Series 15i-MA tape format list, "Helical interpolation (G02, G03)": X Y R or I J,
    /// an axis, F; the Haas mill operator's manual, G02/G03: F I J K R X Y Z A and ,C ,R).
    /// Carried as written, the arc would be another path (P2: a full turn more). Refused at the
    /// P (review 26, doubtful: `G2 ... P1` was carried, rs274 ran it).
    fn linuxcnc_arc_turns(
        &self,
        b: &BlockIn<'_>,
        ms: &[i64],
        motion: Option<Option<i64>>,
    ) -> Result<(), ConvertError> {
        if self.c.family != Family::MacroB || !matches!(motion, Some(Some(20 | 30))) {
            return Ok(());
        }
        let Some(w) = b
            .words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&b'P') && !w.token.contains(&b'='))
        else {
            return Ok(());
        };
        let tenths: Vec<i64> = b
            .words
            .iter()
            .filter(|w| w.token[0].eq_ignore_ascii_case(&b'G'))
            .filter_map(|w| g_tenths(w.token))
            .collect();
        if crate::meaning::linuxcnc_word_used(b'P', &tenths, ms, None) {
            return Ok(()); // a dwell's, G10's, G64's or an M code's P
        }
        Err(ConvertError {
            message: format!(
                "{}: P in an arc is the number of the helix's turns on LinuxCNC (G2/G3 \
                 P), which the FANUC and Haas manuals at hand give no meaning in G02/G03: \
                 carried as written the arc would run another path; tapegate does not \
                 rewrite it: remove the P, or write the arc for LinuxCNC",
                text(w.token)
            ),
            clause: "meaning",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// Another family's arc with R and any of I J K: rs274 refuses it ("Mixed radius ijk
    /// format for arc", interp_convert.cc convert_arc, which the check's TG412 reads too),
    /// where a FANUC or Haas reads the arc by its R and ignores I J K (FANUC Series 16/18-C
    /// Lathe Operator's Manual, "Circular interpolation": "If I, J, K, and R addresses are
    /// specified simultaneously, the arc specified by address R takes precedence and the
    /// other are ignored"). Refused at the first I, J or K word, not dropped.
    fn linuxcnc_mixed_arc(
        &self,
        b: &BlockIn<'_>,
        motion: Option<Option<i64>>,
    ) -> Result<(), ConvertError> {
        if !matches!(motion, Some(Some(20 | 30))) {
            return Ok(());
        }
        let letter = |w: &&WordSpan<'_>| w.token[0].to_ascii_uppercase();
        if !b
            .words
            .iter()
            .any(|w| letter(&w) == b'R' && !w.token.contains(&b'='))
        {
            return Ok(());
        }
        let Some(w) = b
            .words
            .iter()
            .find(|w| matches!(letter(w), b'I' | b'J' | b'K') && !w.token.contains(&b'='))
        else {
            return Ok(());
        };
        let source = match self.c.family {
            Family::MacroB => "the source control reads the arc by its R and ignores I J K",
            _ => "the source control reads the arc by one of them",
        };
        Err(ConvertError {
            message: format!(
                "{}: Mixed radius ijk format for arc (rs274ngc): LinuxCNC refuses an arc with \
                 R and I J K, where {source}; tapegate does not drop the word: remove the \
                 I J K words (or the R)",
                text(w.token)
            ),
            clause: "meaning",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// The target has no motion mode where the source keeps one (LinuxCNC for a Fanuc
    /// program): at the start and after G80.
    fn motion_differs(&self) -> bool {
        self.c.target_g80_clears_motion && !self.c.src_modal.g80_clears_motion
    }

    /// Axis words with no motion code, where the source control moves them in the motion
    /// mode it keeps and the target has none in force: the target refuses the block (rs274:
    /// "Cannot use axis values without a g code that uses them"), so the conversion does.
    /// A code that takes axis words itself (G10, G28, G30, G52, G92, a dwell; the arguments of a
    /// G65/G66 macro call) is no move by the motion mode.
    fn motion_mode(&mut self, b: &BlockIn<'_>, gs: &[i64]) -> Result<(), ConvertError> {
        if !self.motion_differs() {
            return Ok(());
        }
        let sets = gs
            .iter()
            .any(|&g| matches!(g, 0..=3 | 33 | 73 | 74 | 76 | 81..=89));
        if gs.contains(&80) {
            self.target_no_motion = Some(b.line);
        } else if sets {
            self.target_no_motion = None;
        }
        let takes = gs
            .iter()
            .any(|&g| matches!(g, 4 | 10 | 28 | 30 | 52 | 65 | 66 | 92));
        let Some(since) = self.target_no_motion.filter(|_| !takes && !sets) else {
            return Ok(());
        };
        let Some(w) = b.words.iter().find(|w| {
            matches!(
                kind(w.token[0].to_ascii_uppercase()),
                Some(Kind::Axis | Kind::Angle)
            )
        }) else {
            return Ok(());
        };
        let (source, target) = if since == 0 {
            (
                "at the start of the program the source control is in the motion mode of its \
                 reset state (G00)"
                    .to_string(),
                "the target control has none there".to_string(),
            )
        } else {
            (
                format!("after G80 on line {since} the source control keeps its motion mode"),
                "the target control has none after G80".to_string(),
            )
        };
        Err(ConvertError {
            message: format!(
                "{}: an axis word with no motion code: {source}, {target} and refuses the block \
                 (LinuxCNC's rs274: \"Cannot use axis values without a g code that uses \
                 them\"); write G00 or G01 in this block",
                text(w.token)
            ),
            clause: "modal state",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// The next program of the file starts where its caller, or the operator, leaves the
    /// machine: its own distance mode and its own positions, tracked afresh.
    fn fresh_program(&mut self) {
        self.own_distance = false;
        self.inherited = None;
        self.own_spindle = false;
        self.inherited_speed = None;
        self.src_pos = [None; 26];
        self.out_pos = [None; 26];
        self.abs_raw = [None; 26];
        self.pos_units = [None; 26];
        self.out_at = [None; 26];
        self.out_mm = [None; 26];
        self.rounded_step = None;
        self.loops = false;
        self.uw_moves.reset();
        self.rounded_params.clear();
        self.polar_interpolation = false;
        self.ic_rounded = Default::default();
    }

    /// At the end of a subprogram (`end` says how it ends): an axis word written before the
    /// subprogram selected G90 or G91 had the caller's distance mode, which the text does not
    /// show.
    fn inherited_distance(&mut self, line: usize, end: &str) -> Result<(), ConvertError> {
        let Some((word, at, column)) = self.inherited.take() else {
            return Ok(());
        };
        Err(ConvertError {
            message: format!(
                "{word}: an axis word of a subprogram (it ends with {end} at line {line}) before \
                 the subprogram selects G90 or G91: its distance mode is the caller's, which the \
                 text does not show, and under a change of units an incremental path is \
                 converted by its positions, an absolute one word by word; write G90 or G91 in \
                 the subprogram before its first move"
            ),
            clause: "modal state",
            column,
            line: Some(at),
        })
    }

    /// Whether a Fanuc or Haas lathe's block is a linear move of one of X (U) or Z (W) with a C
    /// word beside it: the "Chamfering and corner R" form `X(U)_ C_` / `Z(W)_ C_` of a lathe
    /// whose C is no axis (FANUC 0i-TF lathe manual; its comma-less `R_` is the corner's
    /// radius), and a move of the C axis on a lathe with one (the profile says "a C axis is an
    /// option").
    fn chamfer_or_axis(&self, b: &BlockIn<'_>, gs: &[i64]) -> bool {
        let motion = gs
            .iter()
            .rev()
            .find(|&&g| (0..=3).contains(&g))
            .copied()
            .or(self.modal.state.motion);
        let has = |l: u8| b.words.iter().any(|w| w.token[0].eq_ignore_ascii_case(&l));
        let axes = [b'X', b'U', b'Z', b'W'].iter().filter(|&&l| has(l)).count();
        !self.c_axis
            && motion == Some(1)
            && axes == 1
            && has(b'C')
            && self.cycle[slot(b'C')].is_none()
    }

    /// At the end of a subprogram: an S word written before the subprogram selected G96 or
    /// G97 is a surface speed (converted with the units: m/min, ft/min) or a spindle speed
    /// (rpm, kept) by its caller's mode, which the text does not show; under a change of units
    /// it is refused (it was kept as rpm under a caller's G96: 600 m/min for 600 ft/min).
    fn inherited_speed(&mut self, line: usize, end: &str) -> Result<(), ConvertError> {
        let Some((word, at, column)) = self.inherited_speed.take() else {
            return Ok(());
        };
        Err(ConvertError {
            message: format!(
                "{word}: a spindle speed of a subprogram (it ends with {end} at line {line}) \
                 before the subprogram selects G96 or G97: it is a surface speed under the \
                 caller's G96, converted with the units, and revolutions per minute under G97, \
                 which the text does not show; write G96 or G97 in the subprogram before its \
                 first S"
            ),
            clause: "modal state",
            column,
            line: Some(at),
        })
    }

    /// Where the flow is not straight ([`crate::units_flow`]): a length or a call read while
    /// the units are in doubt is refused, one read where a loop's head or a label waits for a
    /// units code, or before the program's first units code (its head, which a main program's
    /// M99 runs again), is told the flow, and the block's conditions, loops and jumps are
    /// followed (`labelled`: the block's labels were given already, with its words).
    fn flow_block(&mut self, b: &BlockIn<'_>, labelled: bool) -> Result<(), ConvertError> {
        if self.c.units.is_none() {
            return Ok(());
        }
        if !labelled {
            let (units, feed) = (self.modal.state.units, self.modal.state.feed_units);
            self.flow
                .block_labels(self.c.family, None, b.statements, units, false);
            if let Some(feed_flow) = &mut self.feed_flow {
                feed_flow.block_labels(self.c.family, None, b.statements, feed, false);
            }
            self.arrive();
        }
        let units = self.modal.state.units;
        if self.flow.doubt().is_none()
            && !self.flow.needs_lengths()
            && !self.flow.program_head_open()
        {
            if self.feed_flow.is_none() && b.statements.is_empty() {
                return Ok(());
            }
            return self.flow_statements(b, units);
        }
        let css = self.modal.state.spindle_mode == 96;
        let length = b.words.iter().find(|w| {
            w.token[0] == b'#'
                || match kind(w.token[0].to_ascii_uppercase()) {
                    Some(Kind::Speed) => css,
                    Some(k) => matches!(k, Kind::Axis | Kind::Centre | Kind::Feed | Kind::Pqr),
                    None => false,
                }
        });
        let family = self.c.family;
        let at = length.map(|w| w.start).or_else(|| {
            b.statements
                .iter()
                .find(|s| {
                    s.1 == StatementKind::Call
                        || holds_values(s.2, false)
                        || role_lengths(family, s.2)
                })
                .map(|s| s.0)
        });
        if at.is_some() {
            // a units code after this value is at no loop's head nor label, for the feed's
            // flow as for the lengths' (both read the same labels, loops and codes)
            self.flow.length();
            if let Some(feed_flow) = &mut self.feed_flow {
                feed_flow.length();
            }
        }
        // a program's head (what its M99 runs again): a value in units, not the P of a call
        // or a return (`M98 P2000`, `M99 P10`), a program or block number
        let calls = |w: &WordSpan<'_>| {
            w.token[0].eq_ignore_ascii_case(&b'M') && matches!(self.code_of(w.token), Some(97..=99))
        };
        let head = match length {
            Some(w) if w.token[0].eq_ignore_ascii_case(&b'P') => !b.words.iter().any(calls),
            Some(_) => true,
            None => at.is_some(),
        };
        if head {
            self.flow.value(units, b.line);
        }
        if let (Some(at), Some(doubt)) = (at, self.flow.doubt()) {
            return Err(ConvertError {
                message: format!(
                    "the units in force here are not known: {}; a value read here is in {} \
                     on one path and in the other units on another, so no conversion of it \
                     is right on both; select the units again before it",
                    doubt.message,
                    units.name()
                ),
                clause: "units",
                column: crate::text::column(b.text, at),
                line: None,
            });
        }
        self.flow_statements(b, units)
    }

    /// The block's statements given to the flows ([`Converter::flow_block`]), once its values
    /// passed: the feed's first where it has a flow of its own.
    #[inline]
    fn flow_statements(&mut self, b: &BlockIn<'_>, units: Units) -> Result<(), ConvertError> {
        if self.feed_flow.is_some() {
            self.feed_flow_block(b)?;
        }
        if b.statements.is_empty() {
            return Ok(());
        }
        self.flow
            .block_flow(
                self.c.family,
                b.line,
                b.statements,
                units,
                // (the units codes as the source writes them: C's G70/G71)
                {
                    let modal = &self.c.src_modal;
                    let written = |n: i64| modal.g_system.from_a(n).unwrap_or(n);
                    (written(modal.inch), written(modal.metric))
                },
            )
            .map_err(|r| flow_refusal(b, r, ""))?;
        // a construct whose end no path reaches (left by a jump, break, continue or return)
        // goes on in its other ways' units: read on in them from the next block
        self.arrive();
        // a block skip makes the block's jump optional: the straight path may go on past it
        if !b.skip.is_empty() || b.skip_within.is_some() {
            self.flow.optional();
            if let Some(feed_flow) = &mut self.feed_flow {
                feed_flow.optional();
            }
        }
        Ok(())
    }

    /// A SINUMERIK's feed units followed as [`Converter::flow_block`] follows the lengths':
    /// an F or E word read while they are in doubt is refused (a branch from G700 into G70
    /// changes them, not the lengths', docs/dialects.md), as are a loop and a jump back whose
    /// passes read feeds in other units. (Its labels were given with the lengths'.)
    fn feed_flow_block(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        let units = self.modal.state.feed_units;
        let Some(feed_flow) = &mut self.feed_flow else {
            return Ok(());
        };
        if let Some(doubt) = feed_flow.doubt() {
            let feed = b.words.iter().find(|w| {
                matches!(w.token[0].to_ascii_uppercase(), b'F' | b'E')
                    && kind(w.token[0].to_ascii_uppercase()) == Some(Kind::Feed)
            });
            if let Some(w) = feed {
                return Err(ConvertError {
                    message: format!(
                        "the feed's units in force here are not known (G700/G710 set them, \
                         G70/G71 set them to the machine's): {}; a feed read here is in {} on \
                         one path and in the other units on another; write G700 or G710 again \
                         before it",
                        doubt.message,
                        units.name()
                    ),
                    clause: "units",
                    column: crate::text::column(b.text, w.start),
                    line: None,
                });
            }
        }
        feed_flow
            .block_flow(self.c.family, b.line, b.statements, units, (700, 710))
            .map_err(|r| flow_refusal(b, r, "the feed's units (G700/G710): "))
    }

    /// Under a change of units, the source's words jump and call (M97, M98, M99 P: Custom
    /// Macro B and Haas, and the neutral ISO reading; [`Converter::flow_words`]).
    fn words_call(&self) -> bool {
        self.c.units.is_some() && matches!(self.c.family, Family::MacroB | Family::Iso)
    }

    /// The jumps and calls a block's words make (Custom Macro B and Haas, under a change of
    /// units): `M99 P n` jumps to block n (FANUC "Subprogram"), M99 returns (a main program
    /// to its start), `M97 P n` runs the block n of the program up to its M99 (Haas, M97),
    /// `M98 P n` the program On ([`crate::units_flow::UnitsFlow`] follows each).
    fn flow_words(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        let units = self.modal.state.units;
        let at = |code: i64| {
            b.words.iter().find(|w| {
                w.token[0].eq_ignore_ascii_case(&b'M') && self.code_of(w.token) == Some(code)
            })
        };
        let (m99, m97, m98) = (at(99), at(97), at(98));
        let macro_call = b.words.iter().find(|w| {
            w.token[0].eq_ignore_ascii_case(&b'G') && matches!(self.code_of(w.token), Some(65 | 66))
        });
        let m = |code: i64| match code {
            99 => m99,
            97 => m97,
            _ => m98,
        };
        let p = b
            .words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&b'P'))
            .map(|w| &w.token[1..]);
        let flow = &mut self.flow;
        let result = if let Some(w) = m(99) {
            match p {
                Some(p) => flow
                    .returns_to_block(w.start, units, self.ended_on.is_some())
                    .and_then(|()| flow.word_jump(p, b.line, w.start, units)),
                None => flow.returns(w.start, units, self.ended_on.is_some()),
            }
        } else if let (Some(w), Some(p)) = (m(97), p) {
            match crate::units_flow::target(p) {
                Some(name) => flow.local_call(name, b.line, w.start, units),
                None => Ok(()),
            }
        } else if let (Some(w), Some(n)) = (m(98), p.and_then(crate::text::digits_value)) {
            // without the 8-digit option, a P of more than four digits is a repeat count
            // before a four-digit number (docs/dialects.md): both readings are followed
            let numbers = [n, n % 10_000];
            let count = if n >= 10_000 { 2 } else { 1 };
            flow.program_call(&numbers[..count], b.line, w.start, units)
        } else if let (Some(w), Some(n)) = (macro_call, p.and_then(crate::text::digits_value)) {
            // a macro call (G65 P n) or a modal one (G66 P n, run after each move) enters the
            // program On as M98 does and its caller goes on in the units it returns in
            // (FANUC "Custom Macro", macro call): followed the same way
            flow.program_call(&[n], b.line, w.start, units)
        } else {
            Ok(())
        };
        result.map_err(|r| flow_refusal(b, r, ""))?;
        // after M99 (a return, a main program's run again from its start, `M99 P n` a jump)
        // the straight path does not go on: what follows runs where a jump comes to it only,
        // as after GOTO or M30 (unless a block skip or a condition makes the M99 optional)
        if m99.is_some()
            && b.skip.is_empty()
            && b.skip_within.is_none()
            && !b.statements.iter().any(|s| s.1 == StatementKind::Flow)
        {
            self.flow.ends();
            if let Some(feed_flow) = &mut self.feed_flow {
                feed_flow.ends();
            }
        }
        Ok(())
    }

    /// The jumps to this block's label come in other units than the conversion read on in,
    /// where the straight path does not reach it (after an unconditional jump or the program's
    /// end: [`crate::units_flow::UnitsFlow::arrived`]): the text from here is read in theirs.
    /// The same where a construct's end is dead (its units flow's other ways). A SINUMERIK's
    /// feed may be in other units than its lengths (G70 against G700): its own flow
    /// ([`Converter::feed_flow`]), which reads the same jumps, labels and dead text, gives the
    /// feed units the jumps bring (review 7, 4).
    fn arrive(&mut self) {
        let feed = self
            .feed_flow
            .as_mut()
            .and_then(crate::units_flow::UnitsFlow::arrived);
        let lengths = self.flow.arrived();
        if lengths.is_none() && feed.is_none() {
            return;
        }
        // the feed's own flow says in which feed units the jumps come (where it differs from
        // the file order's); without one, the feed's units were the lengths' all along
        let units = lengths.unwrap_or(self.modal.state.units);
        let feed = match (&self.feed_flow, feed) {
            (Some(_), Some(feed)) => feed,
            (Some(_), None) => self.modal.state.feed_units,
            (None, _) => units,
        };
        self.modal.state.units = units;
        self.modal.state.feed_units = feed;
        self.follow_units();
        self.jumped_in = true;
    }

    /// LinuxCNC's M70 saves the modal state, M71 forgets it, M72 restores it (manual, "M70
    /// Save Modal State" to "M72 Restore Modal State"). They run before the block's units
    /// code (manual, "Order of Execution"), so M70 saves the units before it (`before`) and a
    /// units code in M72's block selects the units after it. M72 brings back the units M70
    /// saved: the conversion reads on in them, known where they were known at M70, in doubt
    /// where they were not.
    fn saved_units(&mut self, b: &BlockIn<'_>, ms: &[i64], before: Units, code: bool) {
        if self.c.family != Family::LinuxCnc || self.c.units.is_none() {
            return;
        }
        for &m in ms {
            match m {
                70 => {
                    let doubt = self.flow.doubt().map(|d| d.message.clone());
                    self.saved_units = Some((before, doubt));
                }
                71 => self.saved_units = None,
                72 if !code => {
                    let Some((saved, doubt)) = self.saved_units.clone() else {
                        continue;
                    };
                    let column = b
                        .words
                        .iter()
                        .find(|w| {
                            w.token[0].eq_ignore_ascii_case(&b'M')
                                && self.code_of(w.token) == Some(72)
                        })
                        .map_or(1, |w| crate::text::column(b.text, w.start));
                    let now = self.modal.state.units;
                    self.modal.state.units = saved;
                    self.modal.state.feed_units = saved;
                    self.follow_units();
                    self.flow.units_code(now, saved, b.line, column);
                    if let Some(doubt) = doubt {
                        self.flow.set_doubt(format!(
                            "M72 restores the units M70 saved, which were not known there: \
                             {doubt}"
                        ));
                    }
                }
                _ => {}
            }
        }
    }

    /// A LinuxCNC body begins (`o<name> sub`): it is read in the units
    /// [`crate::sub_units::Bodies::begin`] gives, the caller's kept for its `endsub`.
    fn begin_body(&mut self, b: &BlockIn<'_>) {
        let Some(&(_, _, statement)) = b
            .statements
            .iter()
            .find(|s| crate::statement::linuxcnc_definition(s.2) == Some(true))
        else {
            return;
        };
        let label = crate::statement::o_label(statement);
        let name = String::from_utf8_lossy(&label).into_owned();
        let program = self.program;
        let learned = self
            .c
            .read_units
            .iter()
            .find(|(p, n, _)| *p == program && *n == name)
            .map(|r| r.2);
        let state = &self.modal.state;
        self.body_caller = Some((
            state.units,
            state.feed_units,
            self.out_length_units,
            self.out_feed_units,
        ));
        let units = self.bodies.begin(label, b.line, state.units, learned);
        self.modal.state.units = units;
        self.modal.state.feed_units = units;
        self.follow_units();
    }

    /// A block of a LinuxCNC body: its units code, its M73, or its first length before either
    /// (any word but G M N O T H D, any statement holding a number).
    fn body_block(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if self.flow.is_dead() {
            // after an unconditional return (or jump): no path reads this text, its units
            // code and its return are no way out of the body (review 7, 3)
            return Ok(());
        }
        let (mut units_code, mut restores, mut length) = (false, false, None);
        let mut units = self.modal.state.units;
        for w in b.words {
            let letter = w.token[0].to_ascii_uppercase();
            let code = matches!(letter, b'G' | b'M')
                .then(|| self.code_of(w.token))
                .flatten();
            // (a G code by its system A number: a FANUC lathe's of G code system B or C)
            let code = code.map(|n| match letter {
                b'G' => self.c.src_modal.read_g(n),
                _ => n,
            });
            match (letter, code) {
                (b'G', Some(n)) if n == self.c.src_modal.inch || n == self.c.src_modal.metric => {
                    units_code = true;
                    units = if n == self.c.src_modal.inch {
                        Units::Inch
                    } else {
                        Units::Metric
                    };
                }
                (b'M', Some(73)) => restores = true,
                _ if !b"GMNOTHD".contains(&letter) => {
                    length = length.or(Some(w.start));
                }
                _ => {}
            }
        }
        for &(offset, _, statement) in b.statements {
            if holds_values(statement, false) {
                length = length.or(Some(offset));
            }
            // `o<name> return`: the body returns here, in the units in force
            if crate::statement::o_keyword(statement).as_deref() == Some(b"return".as_slice()) {
                let doubt = self.flow.doubt().map(|d| d.message.clone());
                self.bodies.returns(b.line, units, doubt.as_deref());
            }
        }
        // M73 saves the state it runs in: written with or after the body's own units code,
        // the return is in those units (a units code in its block is taken as run first,
        // which refuses where it may not be)
        if units_code {
            self.bodies.units_code();
        }
        if restores {
            self.bodies.restores(units);
        }
        if !units_code {
            if let Some(at) = length {
                self.bodies
                    .length(b.line, crate::text::column(b.text, at))
                    .map_err(body_refusal)?;
            }
        }
        Ok(())
    }

    /// A LinuxCNC call's units against its body's ([`crate::sub_units::Bodies::call`]): a
    /// body read before in other units is read again in the call's, the conversion made again
    /// ([`REREAD`]).
    fn body_calls(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        for &(offset, kind, statement) in b.statements {
            if kind != StatementKind::Call {
                continue;
            }
            let label = crate::statement::o_label(statement);
            let name = String::from_utf8_lossy(&label).into_owned();
            let column = crate::text::column(b.text, offset);
            let units = self.modal.state.units;
            match self
                .bodies
                .call(label, b.line, column, units)
                .map_err(body_refusal)?
            {
                crate::sub_units::Call::Read => {}
                crate::sub_units::Call::Doubt(why) => self.flow_after_call = Some(why),
                crate::sub_units::Call::Again(units) => {
                    self.learned.push((self.program, name.clone(), units));
                    return Err(ConvertError {
                        message: format!(
                            "{name}: called here in {}, its body was read where it stands, in \
                             other units: it is read again in those of its call",
                            units.name()
                        ),
                        clause: REREAD,
                        column,
                        line: None,
                    });
                }
            }
        }
        Ok(())
    }

    /// The end of a LinuxCNC body: the caller's units again, as the body is skipped where it
    /// stands.
    fn end_body(&mut self, line: usize) -> Result<(), ConvertError> {
        let doubt = self.flow.doubt().map(|d| d.message.clone());
        self.bodies
            .end(
                line,
                self.modal.state.units,
                doubt.as_deref(),
                self.flow.is_dead(),
            )
            .map_err(body_refusal)?;
        if let Some((units, feed, out, out_feed)) = self.body_caller.take() {
            self.modal.state.units = units;
            self.modal.state.feed_units = feed;
            self.out_length_units = out;
            self.out_feed_units = out_feed;
            self.follow_units();
            self.set_factor();
        }
        Ok(())
    }

    /// At the end of the file: what only its end shows ([`crate::sub_units::Bodies::finish`]:
    /// a body no call of the file runs; a subprogram read in its calls' units that returns in
    /// others, [`named`]).
    pub fn end(&mut self) -> Result<(), ConvertError> {
        self.bodies.finish().map_err(body_refusal)?;
        // (as where a next program would begin after the last line)
        self.named_ends(self.named.last_line + 1)
    }

    /// The units each LinuxCNC subroutine body was read in, by label
    /// ([`crate::sub_units::Bodies::units`]), and each SINUMERIK or Okuma OSP subprogram of the
    /// file read in its calls' units, by name ([`named`]).
    pub fn body_units(&self) -> Vec<(Vec<u8>, Units)> {
        let mut units = self.bodies.units();
        // and a SINUMERIK's or an Okuma's subprogram of the file read in its calls' units
        units.extend(self.named.followed.iter().cloned());
        units
    }

    /// Whether a block's statements begin a subprogram (LinuxCNC `o100 sub`) and how they end
    /// one (`o100 endsub`, Sinumerik `RET`; a `return` inside is no end of its text).
    fn subprogram_statements(&self, b: &BlockIn<'_>) -> (bool, Option<String>) {
        let mut begins = false;
        let mut ends = None;
        for &(_, _, statement) in b.statements {
            match self.c.family {
                Family::LinuxCnc => match crate::statement::linuxcnc_definition(statement) {
                    Some(true) => begins = true,
                    Some(false) => ends = Some(text(statement)),
                    None => {}
                },
                Family::Sinumerik if sinumerik_ret(statement) => {
                    ends = Some("RET".to_string());
                }
                _ => {}
            }
        }
        (begins, ends)
    }

    /// Statements are carried through as written. Under a change of units, one that holds a
    /// number (`IF [#5021 GT 10.]`, `CR=5`, `_X=-365.`) is refused: nothing shows whether that
    /// number is a length, and a length left in the old units moves the machine 25.4 times
    /// too far or too short. `--allow-unconverted` leaves it as written, with a note.
    /// The refusal of a piece of the source family's language (`what`: "a statement of")
    /// that the target family's control does not read, at its column: tapegate does not
    /// translate `these` between families.
    fn foreign(
        &self,
        b: &BlockIn<'_>,
        offset: usize,
        piece: &[u8],
        what: &str,
        these: &str,
    ) -> ConvertError {
        ConvertError {
            message: format!(
                "{:?}: {what} {}, which a {} control does not read; tapegate does not \
                 translate {these} between control families: convert for a profile of the \
                 program's own family",
                text(piece),
                family_name(self.c.family),
                family_name(self.c.target_family)
            ),
            clause: "dialect",
            column: crate::text::column(b.text, offset),
            line: None,
        }
    }

    fn statements(&mut self, b: &BlockIn<'_>) -> Result<(), ConvertError> {
        if let (Some(&(offset, _, statement)), true) =
            (b.statements.first(), self.c.target_family != self.c.family)
        {
            // carried as written, the statement would be words of another language to the
            // target control (a Fanuc IF[#1EQ0]GOTO10 is I, F... to LinuxCNC): the output
            // could not be read there, or would do something else
            return Err(self.foreign(b, offset, statement, "a statement of", "statements"));
        }
        // a `#` parameter (`#1=5.`, `X#1`), an expression in `[ ]` or its `*` carried as
        // written would be a character the target's dialect does not read (an ISO 6983-1
        // profile's characters are Annex A's and those it adds): its control refuses the word,
        // as tapegate's check on the target profile does (TG101, TG100)
        // (a target that reads all three, most conversions, looks at no word's characters)
        // (a token is bytes of the line, as written or without its blanks: a line that holds
        // none of the characters the target does not read has no word that does, found by one
        // search of the line instead of a look at every word's bytes)
        let reads = &self.c.target_dialect;
        let look = !(reads.hash && reads.brackets && reads.star) && unread_in_line(b.text, reads);
        // a statement of the same family (a Fanuc's IF[#1EQ0]GOTO10, WHILE[#1LT10]DO1) with
        // such a character is a macro statement the target control does not read: refused at
        // that character, where no word before it in the block is (review 26, finding 4)
        let first_word = b
            .words
            .iter()
            .filter(|_| look)
            .find_map(|w| reads.unread_character(w.token).map(|at| w.start + at));
        if let Some((offset, statement, at)) = b
            .statements
            .iter()
            .filter(|_| look)
            .find_map(|&(offset, _, statement)| {
                reads
                    .unread_in_statement(statement)
                    .map(|at| (offset, statement, at))
            })
            .filter(|&(offset, _, at)| first_word.is_none_or(|w| offset + at < w))
        {
            let c = statement[at] as char;
            let what = match c {
                '#' => "a `#` parameter",
                '*' => "an expression's '*'",
                _ => "an expression in [ ]",
            };
            return Err(ConvertError {
                message: format!(
                    "{:?}: a statement with {what}, which the target profile's dialect does not \
                     read ('{c}' is not among the characters it allows: a control without them \
                     has no such macro statement and refuses the block); tapegate does not \
                     work out statements, parameters or expressions: convert for a profile that \
                     reads them, or write the program without them",
                    text(statement)
                ),
                clause: "dialect",
                column: crate::text::column(b.text, offset + at),
                line: None,
            });
        }
        if let Some((w, at)) = b
            .words
            .iter()
            .filter(|_| look)
            .find_map(|w| reads.unread_character(w.token).map(|at| (w, at)))
        {
            if w.token[at] == b'#' && !reads_hash_parameters(self.c.target_family) {
                // the target's family reads no `#` at all: refused as a statement of another
                // family is
                return Err(self.foreign(b, w.start, w.token, "a parameter of", "parameters"));
            }
            let (c, what) = match w.token[at] {
                b'#' => ('#', "a `#` parameter"),
                b'*' => ('*', "an expression's '*'"),
                c => (c as char, "an expression in [ ]"),
            };
            return Err(ConvertError {
                message: format!(
                    "{:?}: {what}, which the target profile's dialect does not read ('{c}' is \
                     not among the characters it allows: its control refuses the word, as \
                     tapegate's check on that profile does); tapegate does not work out \
                     parameters or expressions into numbers: convert for a profile that reads \
                     them, or write the values",
                    text(w.token)
                ),
                clause: "dialect",
                column: crate::text::column(b.text, w.start + at),
                line: None,
            });
        }
        if self.c.family == Family::Sinumerik && self.c.target_family != Family::Sinumerik {
            // a SINUMERIK's word with '=' (X=R1+5, R1=5, an extended address S1=470, X4=20,
            // M1=3: Programming Manual Fundamentals, "Extended addresses") is no word another
            // family's control reads: carried as written it would be refused there, or read as
            // something else (a Fanuc's R1 is an arc's radius)
            if let Some(w) = b.words.iter().find(|w| w.token.contains(&b'=')) {
                let what = "a word with '=' (an expression, a parameter or an extended address) of";
                return Err(self.foreign(b, w.start, w.token, what, "these"));
            }
        }
        if let Some((at, _)) = b
            .skip_within
            .filter(|_| !crate::dialect::skips_within_block(self.c.target_family))
        {
            // a slash after the first word is read on a Fanuc or Haas only (docs/dialects.md):
            // carried to another family's control it would be refused there, or read as
            // something else
            return Err(ConvertError {
                message: format!(
                    concat!(
                        "'/' in the middle of the block: a {} control skips from there to the ",
                        "end of the block when its block-skip switch is on, a {} control ",
                        "refuses it; tapegate does not move a block skip between control ",
                        "families (write the words after it as a block of their own with '/' ",
                        "at its head)"
                    ),
                    family_name(self.c.family),
                    family_name(self.c.target_family)
                ),
                clause: "dialect",
                column: crate::text::column(b.text, at),
                line: None,
            });
        }
        if self.length == ONE {
            return Ok(());
        }
        // an Okuma OSP lathe's home position return: G20 HP=n, n which of the home positions
        // the parameters hold, a count
        let home = self.c.family == Family::Okuma
            && self.c.lathe
            && b.words.iter().any(|w| {
                w.token[0].eq_ignore_ascii_case(&b'G')
                    && matches!(self.code_of(w.token), Some(20 | 21 | 24 | 25))
            });
        for &(offset, kind, text_of) in b.statements {
            if home && okuma_home_number(text_of) {
                continue;
            }
            if self.c.family == Family::LinuxCnc && kind == StatementKind::Call {
                // its arguments, by the called subroutine's parameters: `statement_lengths`
                continue;
            }
            let sinumerik = self.c.family == Family::Sinumerik;
            let documented = sinumerik && crate::meaning::sinumerik_statement(text_of).is_some();
            // a zero offset of another form (TRANS X=R1) shifts by a length nothing converts
            let shift = sinumerik && crate::meaning::sinumerik_shift(text_of);
            // a Fanuc or Haas corner, `,C1.` a chamfer's and `,R2.` a rounding's length (the
            // FANUC operator's manuals, "Chamfering and corner R"): a plain number is converted
            // in `statement_lengths`, a value computed from parameters is refused rather than
            // left in the old units (a 1 mm chamfer read as 1 inch)
            let corner = self.c.family == Family::MacroB
                && matches!(text_of, [b',', c, ..] if matches!(c.to_ascii_uppercase(), b'C' | b'R'));
            let corner_number = corner && crate::meaning::corner_length(text_of).is_some();
            // an Okuma OSP hole pattern (BHC, LAA, GRDX...): its words converted by their roles
            // in `statement_lengths`, refused where a role is not documented
            let pattern = (self.c.family == Family::Okuma)
                .then(|| crate::meaning::okuma_pattern(text_of))
                .flatten();
            let why = match &pattern {
                Some(Ok(_)) => continue,
                Some(Err((at, why))) => Some((offset + at, why.clone())),
                None => None,
            };
            if why.is_none()
                && (documented
                    || corner_number
                    || self.macro_b_condition_kept(text_of)
                    || !(shift || corner || holds_values(text_of, sinumerik)))
            {
                continue;
            }
            let shown = text(text_of);
            if !self.c.allow_unconverted {
                let (at, reason) = why.unwrap_or_else(|| {
                    let reason = if corner {
                        "a chamfer's or corner rounding's length given by a parameter or an \
                         expression, whose units the converter does not follow"
                    } else {
                        "it holds a number the converter cannot show to be a length or not"
                    };
                    (offset, reason.to_string())
                });
                return Err(ConvertError {
                    message: format!(
                        "cannot convert the units of the statement {shown:?}: {reason} \
                         (--allow-unconverted leaves it as written)"
                    ),
                    clause: "6.4.7",
                    column: crate::text::column(b.text, at),
                    line: None,
                });
            }
            let statement = format!("line {}: statement {shown:?} left unconverted", b.line);
            if self.left_line(b.line, crate::text::column(b.text, offset), statement) {
                self.left_as_written.statements += 1;
            }
        }
        Ok(())
    }

    /// A SINUMERIK statement's lengths under a change of units: `TRANS X10` (the programmable
    /// zero offset), `CR=5`, `RP=`, `RND=`, `CHF=`, `CHR=` ([`crate::meaning::sinumerik_statement`],
    /// from the Fundamentals' list of what G70/G71 apply to); its angles, factors and mirrors
    /// (`ROT Z45`, `AP=45`, `SCALE X2`) stay as written. A FANUC or Haas corner's length (`,C2.`
    /// `,R1.`: [`crate::meaning::corner_length`]) and an Okuma OSP hole pattern's lengths (its
    /// centre or reference point, radius and pitches: [`crate::meaning::okuma_pattern`]; its
    /// angle and counts as written) the same way. Each statement changed, as (its offset, its
    /// end, its new text). A statement of any other form holding a number is refused in
    /// [`Converter::statements`].
    fn statement_lengths(
        &mut self,
        b: &BlockIn<'_>,
    ) -> Result<Vec<(usize, usize, Vec<u8>)>, ConvertError> {
        let mut out = Vec::new();
        // a FANUC or Haas corner without its point is read as the source reads an axis word
        // (increments, digits by format, or whole units under `--from-decimal explicit`), and
        // written with its point for a target that may read it otherwise, as the axis words
        // beside it are, whatever the units: `,C5` read as 5 in is `,C5.` to a FANUC that
        // reads `,C5` as 0.0005 in (one written with its point is kept as it stands)
        if self.length == ONE && self.c.family != Family::MacroB {
            return Ok(out);
        }
        if self.c.family == Family::LinuxCnc {
            for &(offset, kind, statement) in b.statements {
                if kind != StatementKind::Call {
                    continue;
                }
                if let Some(new) = self.call_arguments(b, offset, statement)? {
                    self.changed += 1;
                    out.push((offset, offset + statement.len(), new));
                }
            }
            return Ok(out);
        }
        if !matches!(
            self.c.family,
            Family::Sinumerik | Family::MacroB | Family::Okuma
        ) {
            return Ok(out);
        }
        for &(offset, _, statement) in b.statements {
            // a SINUMERIK frame or radius, a FANUC or Haas corner (`,C2.`), an Okuma OSP hole
            // pattern (`BHC X100 Y50 I50 J0 K6`): their numbers by role
            let numbers = match self.c.family {
                Family::Sinumerik => crate::meaning::sinumerik_statement(statement),
                Family::MacroB => crate::meaning::corner_length(statement).map(|n| vec![n]),
                _ => crate::meaning::okuma_pattern(statement).and_then(Result::ok),
            };
            let Some(numbers) = numbers else {
                continue;
            };
            let mut new = Vec::with_capacity(statement.len() + 8);
            let mut pos = 0;
            for n in numbers.iter().filter(|n| n.length) {
                let column = crate::text::column(b.text, offset + n.start);
                if self.length == ONE && statement[n.start..n.end].contains(&b'.') {
                    continue; // read and written as it stands
                }
                if !self.units_seen && self.length != ONE {
                    // the units code goes before the first word the units change, and this
                    // is no word: a frame set before it would be read in the other units
                    return Err(ConvertError {
                        message: format!(
                            "{}: a length of a statement before the program selects its units; \
                             write the program's units code ({}) before it",
                            text(statement),
                            if self.c.family == Family::Sinumerik {
                                "G70/G71"
                            } else {
                                "G20/G21"
                            }
                        ),
                        clause: "units",
                        column,
                        line: None,
                    });
                }
                let number = &statement[n.start..n.end];
                let (negative, plus, digits) = match number.first() {
                    Some(b'-') => (true, false, &number[1..]),
                    Some(b'+') => (false, true, &number[1..]),
                    _ => (false, false, number),
                };
                let (whole, fraction) = split_number(digits);
                let located = |mut e: ConvertError| {
                    e.column = column;
                    e
                };
                // a corner's `,C5` without its point is read as an axis word is (FANUC,
                // "Decimal point programming": a distance without a point counts least input
                // increments where the source does), not as 5 whole units
                let (m, k) = if self.c.family == Family::MacroB {
                    let dot = digits.contains(&b'.');
                    self.source_number(statement, b'X', b'X', None, (whole, dot, fraction))
                } else {
                    exact(whole, fraction)
                }
                .map_err(located)?;
                let fmt = self.out_format(n.address, false);
                let mut u = self
                    .scale(n.address, m, k, self.length, fmt.after)
                    .map_err(located)?;
                if negative {
                    u = -u;
                }
                new.extend_from_slice(&statement[pos..n.start]);
                write_into(&mut new, u, fmt.after, &fmt, true, plus);
                pos = n.end;
            }
            new.extend_from_slice(&statement[pos..]);
            if new != statement {
                self.changed += 1;
                out.push((offset, offset + statement.len(), new));
            }
        }
        Ok(out)
    }

    /// A LinuxCNC call's arguments under a change of units (`o100 call [1.188] [0.25]`): each
    /// sets the called subroutine's #1, #2... (LinuxCNC manual, "O Codes": "the values of the
    /// arguments are assigned to parameters #1-#30"), so an argument holding a number is
    /// converted as an assignment to that parameter is, by its class in the parameter analysis
    /// ([`crate::lengths`], which reads the call so): a length's linear numbers by the factor
    /// of the parameter's reads, any other kept. One the analysis cannot class, or of a
    /// subroutine not in the file, is refused. The new text, or None where nothing changed.
    fn call_arguments(
        &mut self,
        b: &BlockIn<'_>,
        offset: usize,
        statement: &[u8],
    ) -> Result<Option<Vec<u8>>, ConvertError> {
        let label = crate::statement::o_label(statement);
        let sub = self
            .c
            .parameters
            .as_ref()
            .and_then(|p| p.subs.get(&label).copied());
        // the arguments come after the label, which may be bracketed (`o[#1] call [5]`)
        let after = crate::statement::o_label_len(statement);
        let (mut groups, _) = expr::bracket_groups(statement);
        groups.retain(|&(a, _)| a >= after);
        let mut new = Vec::with_capacity(statement.len() + 8);
        let mut pos = 0;
        let mut terms = std::mem::take(&mut self.terms);
        let result = (|| {
            for (k, &(a, e)) in groups.iter().enumerate() {
                let arg = &statement[a..e];
                // an argument of parameters alone (`[#2]`) has no number to convert, but a
                // parameter it passes on may be one whose units are not shown (`[#5221]`)
                let plain = !holds_values(arg, false);
                if plain && !arg.contains(&b'#') {
                    continue;
                }
                let column = crate::text::column(b.text, offset + a);
                let located = |message: String, clause: &'static str| ConvertError {
                    message,
                    clause,
                    column,
                    line: None,
                };
                let Some(sub) = sub else {
                    if plain {
                        continue;
                    }
                    let e = located(
                        format!(
                            "{}: {} is not defined in this file, so whether its argument {} \
                             is a length is not shown here (--allow-unconverted leaves it as \
                             written)",
                            text(arg),
                            String::from_utf8_lossy(&label),
                            k + 1
                        ),
                        "6.4.7",
                    );
                    self.unconverted(b.line, e)?;
                    continue;
                };
                let name = format!("#{}@{sub}", k + 1);
                let class = self
                    .c
                    .parameters
                    .as_ref()
                    .and_then(|p| p.class(self.program, name.as_bytes()))
                    .cloned();
                match class {
                    None => continue,
                    Some(ParameterClass::Unproved(_)) if plain => continue,
                    Some(ParameterClass::Unproved(why)) => {
                        let e = located(
                            format!(
                                "{}: cannot convert the units of argument {} (the subroutine's \
                                 #{}): {why}",
                                text(arg),
                                k + 1,
                                k + 1
                            ),
                            "6.4.7",
                        );
                        self.unconverted(b.line, e)?;
                        continue;
                    }
                    Some(ParameterClass::Length) => {}
                }
                expr::terms_of(arg, self.c.family, &mut terms)
                    .map_err(|_| located(format!("{}: cannot be read", text(arg)), "6.4.7"))?;
                let Some(numbers) = terms.numbers() else {
                    if plain {
                        continue;
                    }
                    let e = located(
                        format!(
                            "{}: argument {} is a length of the subroutine and a non-linear \
                             expression, so its units cannot be converted exactly",
                            text(arg),
                            k + 1
                        ),
                        "6.4.7",
                    );
                    self.unconverted(b.line, e)?;
                    continue;
                };
                let numbers = numbers.to_vec();
                // a parameter the argument reads whose units are not shown (`#5221`, a work
                // offset in the machine's units): refused here as where it is read directly
                // (review 5, 7)
                let unproved = terms
                    .params
                    .iter()
                    .find_map(|&(p, q)| self.unproved(&arg[p..q]).map(|why| (p, q, why)));
                if let Some((p, q, why)) = unproved {
                    let e = located(
                        format!(
                            "{}: cannot convert the units of argument {} (the subroutine's \
                             #{}): {} is read in it: {why}",
                            text(arg),
                            k + 1,
                            k + 1,
                            text(&arg[p..q])
                        ),
                        "6.4.7",
                    );
                    self.unconverted(b.line, e)?;
                    continue;
                }
                if plain {
                    continue;
                }
                for &(p, q) in &terms.params {
                    if self.class(&arg[p..q]) == Some(&ParameterClass::Length) {
                        self.length_use(&arg[p..q], b.line)?;
                    }
                }
                let factor = self.set_length_of(name, b.line);
                let after = self.out_format(b'X', false).after;
                for (start, end) in numbers {
                    let (whole, fraction) = split_number(&arg[start..end]);
                    let (m, k) = exact(whole, fraction).map_err(|mut e| {
                        e.column = column;
                        e
                    })?;
                    let u = self.scale(b'X', m, k, factor, after).map_err(|mut e| {
                        e.column = column;
                        e
                    })?;
                    new.extend_from_slice(&statement[pos..a + start]);
                    explicit_into(&mut new, u, after);
                    pos = a + end;
                }
            }
            Ok(())
        })();
        self.terms = terms;
        result?;
        if pos == 0 {
            return Ok(None);
        }
        new.extend_from_slice(&statement[pos..]);
        Ok((new != statement).then_some(new))
    }

    /// After a SINUMERIK `X=AC(..)` or `X=IC(..)` converted ([`expr::dimension_value`]): an
    /// AC is an absolute position; an IC an increment converted on its own, not against the
    /// positions (as a G91 word is: [`Converter::tracked`]), so where it rounded, a second
    /// rounded IC of the axis before an absolute position, or one in a program with a jump or
    /// a loop (a body run again repeats it), would add up their roundings along the path:
    /// refused, naming both.
    fn dimension_rounding(
        &mut self,
        b: &BlockIn<'_>,
        letter: u8,
        token: &[u8],
        modifier: &str,
    ) -> Result<(), ConvertError> {
        let s = slot(letter);
        if modifier == "AC" {
            self.ic_rounded[s] = None;
            return Ok(());
        }
        if !self.rounded {
            return Ok(());
        }
        let word = text(token);
        let why = match (&self.ic_rounded[s], self.loops) {
            (Some((at, first)), _) => format!("{first} on line {at} and {word} here"),
            (None, true) => format!("{word} in a program with a jump or a loop, run again,"),
            (None, false) => {
                self.ic_rounded[s] = Some((b.line, word));
                return Ok(());
            }
        };
        Err(error(
            format!(
                "{why} are increments written with IC, each converted and rounded on its own \
                 (not against the positions, as a G91 increment is), so their roundings add up \
                 along the path; write the moves in G91 or as absolute positions"
            ),
            "units",
        ))
    }

    /// A refusal that `--allow-unconverted` turns into a note, the value left as written.
    fn unconverted(&mut self, line: usize, e: ConvertError) -> Result<(), ConvertError> {
        if !self.c.allow_unconverted {
            return Err(e);
        }
        self.left_line(
            line,
            e.column,
            format!("line {line}: {} left unconverted", e.message),
        );
        Ok(())
    }

    /// A count word (N, T, a code...) in the target's format: its new text, or None where it
    /// is written as it was.
    fn count(&mut self, token: &[u8]) -> Result<Option<Vec<u8>>, ConvertError> {
        let letter = token[0].to_ascii_uppercase();
        let digits = &token[1..];
        if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
            return Ok(None);
        }
        let fmt = self.out_format(letter, false);
        if fmt.decimal {
            return Ok(None);
        }
        let lead = digits.iter().take_while(|&&d| d == b'0').count();
        let value: &[u8] = if lead == digits.len() {
            b"0"
        } else {
            &digits[lead..]
        };
        let before = fmt.before as usize;
        if value.len() > before
            && letter == b'N'
            && self.c.target_past_sequence != PastFormat::Alarm
        {
            // a Haas numbers past N99999 (Fusion 360's post): the control's manuals name no
            // alarm, and the checker says so on the target (TG208); the number stays, said
            // once a file with the first such number
            if std::mem::replace(&mut self.long_sequence_noted, true) {
                return Ok(None);
            }
            self.note(format!(
                "sequence numbers longer than the target format {} carried as written (the \
                 first, {}): {}",
                fmt.spec(),
                text(token),
                self.c.target_past_sequence.effect()
            ));
            return Ok(None);
        }
        if value.len() > before {
            return Err(error(
                format!(
                    "{} needs {} digits; the target format {} holds {} (digit overflow{})",
                    text(token),
                    value.len(),
                    fmt.spec(),
                    fmt.before,
                    if letter == b'N' {
                        ": the target control alarms on a longer sequence number, \
                         checks.past_sequence = \"alarm\" (a Fanuc's PS0003)"
                    } else {
                        ""
                    }
                ),
                "Annex C",
            ));
        }
        if letter == b'O' {
            return Ok(None); // a program number is carried as written: O01010
        }
        // (the buffer taken only for a word that changes: most N and G words do not)
        let padded = fmt.zeros == Zeros::None && digits.len() != before;
        if !padded && digits.len() <= before {
            return Ok(None);
        }
        let mut out = self.spare.pop().unwrap_or_default();
        out.push(token[0]);
        if padded {
            out.resize(1 + before - value.len(), b'0');
        }
        out.extend_from_slice(value);
        Ok(Some(out))
    }

    fn value(
        &mut self,
        b: &BlockIn<'_>,
        i: usize,
        k: Kind,
        dwell: bool,
        set_position: bool,
    ) -> Result<Vec<u8>, ConvertError> {
        let token = b.words[i].token;
        let letter = token[0].to_ascii_uppercase();
        // the dwell's time (the source control's words, `word::dwell_words`); its other words
        // are moves and feeds as in any block
        let dwell_word = dwell && self.c.src_modal.dwell.contains(&letter);
        // LinuxCNC's polar radius `@` is a length in the plane's units: written as X is. A
        // number that is no length (G68 R, a polar angle) counts no length's increment where
        // the control reads increments: 0.001 deg in either units, as an A word does
        let table_angle = letter.is_ascii_uppercase() && self.angles & (1 << slot(letter)) != 0;
        let angle = k == Kind::Pqr
            && !dwell_word
            && table_angle
            && self.role(letter) == Role::Other
            && self.src_letters.increments(letter);
        let format_letter = match letter {
            b'@' => b'X',
            _ if angle => b'A',
            _ if k == Kind::Pqr && !dwell_word && self.length_by_axis(letter) => b'X',
            _ => letter,
        };
        let mut factor = self.length;
        let mut tracked = false;
        // a word whose role is not known, left as written under a change of units
        // (--allow-unconverted): its text is kept exactly, or it is refused (below)
        let mut left = false;
        if dwell_word {
            factor = ONE;
        } else {
            match k {
                Kind::Axis => tracked = true,
                Kind::Angle => {
                    factor = ONE;
                    tracked = true;
                }
                Kind::Code => factor = ONE,
                Kind::Feed if self.modal.state.feed_mode == 93 => factor = ONE,
                Kind::Feed => factor = self.feed,
                Kind::Speed => {
                    factor = if self.modal.state.spindle_mode == 96 && !self.s_limit {
                        self.cutting_rate_factor()?
                    } else {
                        ONE
                    };
                }
                Kind::Pqr => {
                    let role = self.role(letter);
                    if role != Role::Length {
                        if role == Role::Parameter && self.length != ONE && !token.contains(&b'=') {
                            if !self.c.allow_unconverted
                                && letter == b'C'
                                && self.c.lathe
                                && self.cycle[slot(letter)] == Some(Role::Parameter)
                            {
                                return Err(error(
                                    format!(
                                        "{}: beside one of X or Z in a linear move, a lathe's C \
                                         is the chamfer of \"chamfering and corner R\" (a length) \
                                         on a machine without a C axis and a move of the C axis \
                                         (degrees) on one with it, which the program does not \
                                         show; give --allow-unconverted to leave it as written \
                                         (a C axis), or write the chamfer as a move",
                                        text(token)
                                    ),
                                    "6.4.7",
                                ));
                            }
                            if !self.c.allow_unconverted
                                && letter == b'L'
                                && self.c.src_modal.arc_radius == b'L'
                            {
                                return Err(error(
                                    format!(
                                        "{}: outside an arc and a thread cutting cycle the \
                                         source control's manual does not say whether {l} is a \
                                         length; give --allow-unconverted to leave it as written",
                                        text(token),
                                        l = letter as char
                                    ),
                                    "6.4.7",
                                ));
                            }
                            if !self.c.allow_unconverted
                                && self.cycle[slot(letter)] == Some(Role::Parameter)
                            {
                                return Err(error(
                                    format!(
                                        "{}: the source control's manual, as tapegate has it, \
                                         does not say what {l} is in this block (a length or \
                                         not), so the change of units cannot convert it; give \
                                         --allow-unconverted to leave it as written",
                                        text(token),
                                        l = letter as char
                                    ),
                                    "6.4.7",
                                ));
                            }
                            if !self.c.allow_unconverted {
                                return Err(error(
                                    format!(
                                        "{}: the source profile does not say whether {l} is a \
                                         length here (checks.pqr.{l} = \"parameter\"); give a \
                                         --from profile that does, or --allow-unconverted to \
                                         leave it as written",
                                        text(token),
                                        l = letter as char
                                    ),
                                    "6.4.7",
                                ));
                            }
                            left = true;
                        }
                        factor = ONE;
                    }
                }
                _ => {}
            }
        }
        let in_increments = k == Kind::Pqr && self.cycle[slot(letter)] == Some(Role::Increments);
        let Some((negative, plus, whole, dot, fraction)) = plain_word(&b.words[i]) else {
            if in_increments && self.length != ONE {
                // Q#1 in a G76: a count of increments the converter cannot scale as written
                if !self.c.allow_unconverted {
                    return Err(error(
                        format!(
                            "{}: a length of this cycle in least input increments, written as \
                             an expression, whose units cannot be converted exactly (give \
                             --allow-unconverted to leave it as written)",
                            text(token)
                        ),
                        "6.4.7",
                    ));
                }
                self.left_line(
                    b.line,
                    crate::text::column(b.text, b.words[i].start),
                    format!(
                        "line {}: {} left unconverted (a length in increments, an expression)",
                        b.line,
                        text(token)
                    ),
                );
            }
            let modifier = (self.c.family == Family::Sinumerik && k == Kind::Axis)
                .then(|| expr::dimension_modifier(token))
                .flatten();
            self.dwell_expression(token, dwell_word)?;
            self.rounded = false;
            self.left_word = left;
            let out = self.expression(b, i, factor);
            self.left_word = false;
            let out = out?;
            if left {
                self.left_note(b, i);
            }
            if let Some(modifier) = modifier {
                self.dimension_rounding(b, letter, token, modifier)?;
            }
            return Ok(out);
        };
        // (a dwell's time is a dwell word's or a P's: `dwell_time` answers None for any other
        // word, asked only of those)
        if dwell_word || letter == b'P' {
            if let Some(out) = self.dwell_time(token, dwell_word, whole, dot, fraction)? {
                return Ok(out);
            }
        }
        if in_increments {
            return self.increments(token, negative, plus, whole, dot, fraction);
        }
        // a count or selector of the cycle (`G81 K3` repeats, `G73 R3` divisions, Haas `G76
        // A60`, `G71 R1`, `G84 J2`): the control reads it whole, never in increments, and no
        // change of units or decimal style changes it
        let counted =
            k == Kind::Pqr && !table_angle && self.cycle[slot(letter)] == Some(Role::Other);
        if counted && !dot {
            return Ok(self.kept(token));
        }
        if counted {
            // the same number written with its point (`M96 P100 Q8.`, `G81 ... K2.`): a target
            // that writes points keeps the text; one that writes none would write it by the
            // letter's format (`Q80000`, `K2000`: input 80000, 2000 repeats, where the control
            // reads a count whole), so it is refused, not rewritten
            if self.explicit_out(letter) {
                return Ok(self.kept(token));
            }
            return Err(error(
                format!(
                    "{}: a number the control reads whole here (a count, a block or input \
                     number), written with its point; the target writes no decimal point, and \
                     the letter's format would write it as another number: write it without \
                     its point, or convert to an explicit-decimal target",
                    text(token)
                ),
                "6.4.7",
            ));
        }
        // a number the conversion does not scale (a dwell's time, a scale factor, a count),
        // written with more decimals than the target's format holds: the control reads the
        // point (Haas G04 P1.5 is 1.5 s, G51 P1.5 a factor 1.5), so rounding it to the format
        // would change what the machine does; an explicit-decimal target reads it as written
        if dot
            && ((k == Kind::Pqr && self.role(letter) == Role::Other) || dwell_word)
            && factor == ONE
            && fraction
                .iter()
                .rposition(|&c| c != b'0')
                .map_or(0, |p| p + 1)
                > self.out_format(letter, dwell_word).after as usize
        {
            if self.explicit_out(letter) {
                return Ok(self.kept(token));
            }
            return Err(error(
                format!(
                    "{}: a value this conversion does not scale, with more decimals than the \
                     target format {} holds; the target writes no decimal point, and rounding \
                     it would change what the control reads",
                    text(token),
                    self.out_format(letter, dwell_word).spec()
                ),
                "Annex C",
            ));
        }
        let src_increments =
            self.src_letters.increments(letter) && self.src_format(format_letter).decimal;
        // a word whose role is not known, left as written (--allow-unconverted): the same
        // text, where the target reads it as the source does: with its point wherever the
        // target writes one, without where neither control reads the letter in least
        // increments (Haas `M19 R90`, `Q123`); else the number written would be another one
        // to the target (`G51.2 R10` in increments is 0.010 mm, R10 in inch 0.0010 in), and
        // reading it as a length in increments to write it anew assumes the role it lacks
        if left {
            let fmt = self.out_format(format_letter, dwell_word);
            let target_reads = self.explicit_out(letter)
                && (dot || !self.dst_letters.increments(letter) || !fmt.decimal);
            let source_reads = dot || (self.explicit_in(letter) && !src_increments);
            if target_reads && source_reads {
                self.left_note(b, i);
                return Ok(self.kept(token));
            }
            return Err(error(
                format!(
                    "{}: a word whose role the source control's manual, as tapegate has it, \
                     does not give, to be left as written (--allow-unconverted), but {}: \
                     written anew it would be read as a length in increments, a role nothing \
                     gives it; write it with a decimal point{}",
                    text(token),
                    if !source_reads {
                        "the source reads it without a point in least input increments, and \
                         the same digits are another number in the target's units"
                    } else {
                        "the target writes no decimal point for it and reads the same digits \
                         as another number"
                    },
                    if self.explicit_out(letter) {
                        ""
                    } else {
                        " and convert to an explicit-decimal target"
                    }
                ),
                "6.4.7",
            ));
        }
        let (m, scale) = self.source_number(
            token,
            letter,
            format_letter,
            b.words[i].plain.map(|_| b.words[i].digits),
            (whole, dot, fraction),
        )?;
        let fmt = self.out_format(format_letter, dwell_word);
        let after = fmt.after;
        let limit = match SMALL_POW10.get(fmt.width() as usize) {
            Some(&p) => i128::from(p),
            None => pow10(fmt.width())?,
        };
        let uw_word = matches!(letter, b'U' | b'W')
            && k == Kind::Axis
            && self.cycle[slot(letter)].is_none()
            && !set_position
            && !dwell_word;
        let uw = uw_word && self.uw_moves.carried();
        let u = if uw || (tracked && (self.incremental() || set_position) && !dwell_word) {
            // a lathe's U W move X Z by an increment: tracked on X Z's positions
            let on = match letter {
                b'U' if uw => b'X',
                b'W' if uw => b'Z',
                other => other,
            };
            self.rounded = false;
            let u = self.tracked(letter, on, negative, m, scale, factor, after, set_position)?;
            if self.rounded && on != letter {
                // the position of X Z is as far off as the U W that moved it
                if let Some((_, e, d)) = self.worst_entry(letter) {
                    self.record(on, e, d, 0);
                }
            }
            if self.rounded && !set_position && self.rounded_step.is_none() {
                self.rounded_step = Some((b.line, text(token)));
            }
            u
        } else {
            let own = uw_word && self.uw_moves.on_its_own();
            self.rounded = false;
            let mut u = self.scale(letter, m, scale, factor, after)?;
            if negative {
                u = -u;
            }
            if own && self.rounded && !self.uw_own_noted {
                self.uw_own_noted = true;
                // G code system B or C: converted on its own, as `--verify` reads it (no
                // manual at hand says these U W move X Z); if they do, each rounding adds up
                self.note(format!(
                    "line {}: {} (G code system B/C) is rounded to the target's format and \
                     converted on its own, not carried on {}'s position, as is every U and W \
                     of a move in system B or C: no manual at hand says whether they are \
                     increments of X and Z there; if they are, each rounded one adds its \
                     rounding (up to half a step) to the position: check the path, or \
                     program it by X Z",
                    b.line,
                    text(token),
                    if letter == b'U' { "X" } else { "Z" }
                ));
            }
            if tracked && !dwell_word {
                self.ic_rounded[slot(letter)] = None;
                self.abs_raw[slot(letter)] = Some((negative, m, scale));
                self.out_pos[slot(letter)] = Some(u);
                self.src_pos[slot(letter)] = None;
                self.pos_units[slot(letter)] = Some(self.src_units);
                self.out_at[slot(letter)] = Some((self.out_units(), after));
                self.out_mm[slot(letter)] = None;
            }
            u
        };
        if -limit >= u || u >= limit {
            return Err(error(
                format!(
                    "{} is {} in the target format {}, which holds {} digits before the decimal \
                     sign (digit overflow)",
                    text(token),
                    explicit(u.abs(), after).trim_end_matches('.'),
                    fmt.spec(),
                    fmt.before
                ),
                "Annex C",
            ));
        }
        let mut out = self.spare.pop().unwrap_or_default();
        out.push(token[0]);
        let explicit_out = self.explicit_out(letter);
        write_into(&mut out, u, after, &fmt, explicit_out, plus);
        if k == Kind::Code && out.last() == Some(&b'.') {
            out.pop(); // a whole code is written whole: G55, not G55.
        }
        // (the texts compared last: a word scaled by a change of units passes on its factor)
        if explicit_out
            && factor == ONE
            && (dot || (self.explicit_in(letter) && !src_increments))
            && (dot || !self.dst_letters.increments(letter) || !fmt.decimal)
            && fraction.len() as u32 <= after
            && out != token
        {
            out.clear();
            out.extend_from_slice(token);
        }
        // a word whose role is not known, under a change of decimal style (no change of
        // units): the digits the target would write are the source's number read by a
        // format its role does not give, and written anew (`M199 Q10.` is not `Q10000`);
        // it is kept exactly where both controls read its text as the same number, else
        // refused at its column, as under a change of units
        if k == Kind::Pqr && self.role(letter) == Role::Parameter && out != token {
            let src_increments =
                self.src_letters.increments(letter) && self.src_format(format_letter).decimal;
            let target_reads =
                explicit_out && (dot || !self.dst_letters.increments(letter) || !fmt.decimal);
            let source_reads = dot || (self.explicit_in(letter) && !src_increments);
            // without its point, on two controls that both read decimal points and count the
            // letter's least increment alike (`G65 ... I1`, 0.001 mm to either: FANUC to FANUC
            // with --decimal explicit): the same text is the same number to both, whatever
            // the machine's parameters make of it
            let counted_alike = !dot
                && self.explicit_in(letter)
                && explicit_out
                && src_increments
                && self.dst_letters.increments(letter)
                && fmt.decimal
                && self.src_format(format_letter).after == fmt.after;
            if (target_reads && source_reads) || counted_alike {
                // both controls read the text as the same number: kept exactly (`G107 Q2.0`
                // stays, no `Q2`), a number nobody converts
                out.clear();
                self.spare.push(out);
                if self.c.allow_unconverted {
                    self.left_note(b, i);
                }
                return Ok(self.kept(token));
            }
            let written = text(&out);
            out.clear();
            self.spare.push(out);
            return Err(error(
                format!(
                    "{}: a word whose role the source control's manual, as tapegate has it, \
                     does not give (a length or not); the target's decimal style would write \
                     it anew as {}, a number read by a format its role does not give, and {}: \
                     {}, or write the block with a code of the control's list",
                    text(token),
                    written,
                    if explicit_out {
                        "the source reads it without a point in least input increments, which \
                         the target does not count alike"
                    } else {
                        "the target cannot hold it as written (it would read the same text as \
                         another number)"
                    },
                    if explicit_out {
                        "write it with its decimal point"
                    } else {
                        "convert to an explicit-decimal target"
                    },
                ),
                "6.4.7",
            ));
        }
        Ok(out)
    }

    /// A number as the source control reads it, `m * 10^-scale` of the units in force:
    /// written with its point, as written; without, in least input increments where the
    /// source counts them for `letter` (`--from-decimal increments`, a FANUC's distance
    /// words), whole where it reads the letter whole (`--from-decimal explicit`), else by the
    /// source format of `format_letter`. The one reading of a word's number: a FANUC corner's
    /// `,C5` is read so as an axis word ([`Converter::statement_lengths`]). `token` names the
    /// number in a refusal; `digits` the tokenizer's value of a plain word's digits.
    fn source_number(
        &self,
        token: &[u8],
        letter: u8,
        format_letter: u8,
        digits: Option<Digits>,
        number: (&[u8], bool, &[u8]),
    ) -> Result<(i128, u32), ConvertError> {
        // a count format (S05 on a Fanuc) has no increments to count: S0600 is 600 rpm
        let src_increments =
            self.src_letters.increments(letter) && self.src_format(format_letter).decimal;
        let (whole, dot, fraction) = number;
        Ok(if dot || (self.explicit_in(letter) && !src_increments) {
            exact_of(digits, whole, fraction)?
        } else if src_increments {
            let fmt_in = self.src_format(format_letter);
            let d = Dec::from_digits(whole, 0).ok_or_else(too_long)?;
            (d.mantissa, if fmt_in.decimal { fmt_in.after } else { 0 })
        } else {
            let units = units_of(format_letter, (self.src_units, self.src_feed_units));
            let inch = self.c.src_formats_inch.as_deref();
            let formats = &self.c.src_formats;
            if self
                .src_table
                .get(formats, inch, format_letter, units)
                .is_none()
            {
                // without a point, only the source's format says where the decimal sign is:
                // a letter it has none for would be read at a guessed scale (Z1 as 0.0001)
                return Err(error(
                    format!(
                        "{}: the source writes numbers without a decimal point and its profile \
                         gives no format for address {}, so where its decimal sign falls is \
                         not known; give a source profile with a format for {} or write the \
                         word with its point",
                        text(token),
                        letter as char,
                        letter as char
                    ),
                    "Annex C",
                ));
            }
            let fmt_in = self.src_format(format_letter);
            let mut digits = whole.to_vec();
            if fmt_in.zeros == Zeros::Trailing {
                let width = if fmt_in.decimal {
                    fmt_in.width()
                } else {
                    fmt_in.before
                } as usize;
                if digits.len() > width {
                    return Err(error(
                        format!(
                            "{} has {} digits; the source format {} holds {width}",
                            text(token),
                            digits.len(),
                            fmt_in.spec()
                        ),
                        "Annex C",
                    ));
                }
                digits.resize(width, b'0');
            }
            let d = Dec::from_digits(&digits, 0).ok_or_else(too_long)?;
            (d.mantissa, if fmt_in.decimal { fmt_in.after } else { 0 })
        })
    }

    /// A dwell's time between controls that write it differently: a FANUC or Haas mill's
    /// `G04 P1000` and a cycle's `G82 ... P500` are milliseconds (P takes no point; a Haas
    /// P with a point is seconds), `G04 X1.5` seconds; LinuxCNC's G4 and cycle P are seconds
    /// (LinuxCNC G-code reference, G4 "P - seconds to dwell"; it refuses X). Converted to the
    /// target's form, exactly, or refused; between other families that differ a dwell's time
    /// is refused (HEIDENHAIN's G04 F, SINUMERIK's G4 F/S). None: not a dwell's time, or the
    /// same family.
    fn dwell_time(
        &self,
        token: &[u8],
        dwell_word: bool,
        whole: &[u8],
        dot: bool,
        fraction: &[u8],
    ) -> Result<Option<Vec<u8>>, ConvertError> {
        let (from, to) = (self.c.family, self.c.target_family);
        let letter = token[0].to_ascii_uppercase();
        let cycle_dwell = self.cycle_dwell(letter);
        let digits = |d: &[u8]| d.iter().all(u8::is_ascii_digit);
        // seconds (a point) as whole milliseconds: P1.5 is P1500
        let milliseconds = || {
            let kept = fraction.len() - fraction.iter().rev().take_while(|&&c| c == b'0').count();
            if !digits(whole) || !digits(fraction) || kept > 3 {
                return None;
            }
            let mut ms = whole.to_vec();
            ms.extend_from_slice(&fraction[..kept]);
            ms.resize(whole.len() + 3, b'0');
            Some(format!("P{}", integer(&ms).unwrap_or(0)).into_bytes())
        };
        if from == Family::MacroB
            && to == Family::MacroB
            && letter == b'P'
            && dot
            && (dwell_word || cycle_dwell)
        {
            // a FANUC or Haas dwell's P with a point is seconds (Haas NGC manuals, G04: "P with
            // a decimal point is seconds"), without one milliseconds (FANUC's P takes no point):
            // `P1.0` written by the target's format as `P1` would dwell 1 ms, so it is written
            // in the milliseconds both controls read
            return match milliseconds() {
                Some(out) => Ok(Some(out)),
                None => Err(error(
                    format!(
                        "{}: a dwell in seconds that is no whole number of milliseconds, the \
                         unit a FANUC or Haas control reads a P without a point in",
                        text(token)
                    ),
                    "dwell",
                )),
            };
        }
        if !dwell_differs(from, to) || !(dwell_word || cycle_dwell) {
            return Ok(None);
        }
        let refuse = |why: &str| {
            Err(error(
                format!(
                    "{}: the dwell's time is written differently on the target control \
                     ({} to {}): {why}",
                    text(token),
                    family_name(from),
                    family_name(to)
                ),
                "dwell",
            ))
        };
        match (from, to) {
            (Family::MacroB, Family::LinuxCnc) => {
                if !digits(whole) || !digits(fraction) {
                    return refuse("write it as a plain number");
                }
                if letter == b'P' && !dot {
                    // milliseconds to seconds: P1500 is P1.5
                    let ms = integer(whole).unwrap_or(0);
                    let mut out = format!("P{}.", ms / 1000).into_bytes();
                    let rest = format!("{:03}", ms % 1000);
                    out.extend_from_slice(rest.trim_end_matches('0').as_bytes());
                    return Ok(Some(out));
                }
                if letter == b'P' {
                    return Ok(Some(token.to_vec())); // seconds (Haas P1.5)
                }
                if dot && matches!(letter, b'X' | b'U') {
                    let mut out = vec![b'P'];
                    out.extend_from_slice(&token[1..]);
                    return Ok(Some(out)); // G04 X1.5: 1.5 s, LinuxCNC's P
                }
                refuse("LinuxCNC reads the time in P seconds; write the source's X with its point")
            }
            (Family::LinuxCnc, Family::MacroB) => {
                // seconds to whole milliseconds: P1.5 is P1500
                match milliseconds().filter(|_| letter == b'P') {
                    Some(out) => Ok(Some(out)),
                    None => refuse(
                        "a FANUC or Haas control reads G04 P in whole milliseconds, which \
                         this time is not",
                    ),
                }
            }
            _ => refuse(
                "tapegate does not translate it between these controls; write the dwell in \
                 the target's form",
            ),
        }
    }

    /// A FANUC or Haas dwell's X or U written as digits without a point under G20
    /// (`G20 G04 X1500`), written anew: read with the inch format it is 0.15 s, by the
    /// increment system alone 1.5 s (SINUMERIK 840D ISO Milling, 3.3.1 "Dwell (G04)"), and no
    /// source at hand says which the control does. `diff` never calls it the same as another
    /// dwell and the check's statistics leave it out of the cycle time, so the conversion does
    /// not write either reading: refused at the word. Carried where its text is kept.
    fn inch_dwell(&self, b: &BlockIn<'_>, i: usize, letter: u8) -> Result<(), ConvertError> {
        let w = &b.words[i];
        if self.c.family != Family::MacroB
            || self.src_units != Units::Inch
            || letter == b'P'
            || !self.c.src_modal.dwell.contains(&letter)
            || plain_word(w).is_none_or(|(_, _, _, dot, _)| dot)
        {
            return Ok(());
        }
        Err(ConvertError {
            message: format!(
                "{}: a dwell's {} without a decimal point under G20: read with the inch format \
                 it is a tenth of the time the same digits give by the increment system alone \
                 (SINUMERIK 840D ISO Milling, 3.3.1 \"Dwell (G04)\"), and no source at hand \
                 says which a FANUC or Haas control takes; write the time in seconds with its \
                 point",
                text(w.token),
                letter as char
            ),
            clause: "dwell",
            column: crate::text::column(b.text, w.start),
            line: None,
        })
    }

    /// A drilling cycle's P in force or named in the block (`G82 ... P500`): the dwell at
    /// the bottom, a time as G04's is.
    fn cycle_dwell(&self, letter: u8) -> bool {
        let lathe = self.c.lathe;
        letter == b'P'
            && (self
                .modal
                .state
                .cycle
                .is_some_and(|g| dwell_cycle(lathe, g))
                || self
                    .cycle_code
                    .code()
                    .is_some_and(|g| dwell_cycle(lathe, g)))
    }

    /// A dwell's time (G04's, a drilling cycle's P) written as a parameter or an expression
    /// (`G04 P#1`, `P[1500]`, a lathe's `U#1`), between controls that write the time
    /// differently ([`Converter::dwell_time`]: a FANUC or Haas P without a point is
    /// milliseconds, LinuxCNC's P seconds): the value the control computes is read in the
    /// source's unit, and carried as written it would be read in the target's (1500 ms as
    /// 1500 s). The manuals tapegate has do not say how a FANUC or Haas control rounds a
    /// computed dwell (to whole milliseconds or not), so it is not rewritten as an expression
    /// (`P[#1/1000]`): refused at the word.
    fn dwell_expression(&self, token: &[u8], dwell_word: bool) -> Result<(), ConvertError> {
        let (from, to) = (self.c.family, self.c.target_family);
        let letter = token[0].to_ascii_uppercase();
        if !dwell_differs(from, to) || !(dwell_word || self.cycle_dwell(letter)) {
            return Ok(());
        }
        Err(error(
            format!(
                "{}: a dwell's time given by a parameter or an expression, where the controls \
                 write the time differently ({} to {}: a FANUC or Haas G04 P and a cycle's P \
                 are milliseconds, a FANUC or Haas X or U seconds, LinuxCNC's P seconds); the \
                 value would be read in another unit on the target, and tapegate does not \
                 rewrite the expression: write the time as a plain number",
                text(token),
                family_name(from),
                family_name(to)
            ),
            "dwell",
        ))
    }

    /// A length the cycle writes as a count of least input increments, with no decimal point
    /// (the 0i's `G76 P1200 Q350`, `G74 P3000 Q5000`): exactly the count times the source's
    /// increment in the units in force, converted to the target's units, rounded to the
    /// target's increment under the rounding policy (recorded as any rounding is, refused
    /// with `--round error`), and written back as a count. Where nothing changes the count,
    /// the word is kept as written (`Q0044`). A word written with a point is read as the
    /// length it writes, and written as the count the control reads.
    fn increments(
        &mut self,
        token: &[u8],
        negative: bool,
        plus: bool,
        whole: &[u8],
        dot: bool,
        fraction: &[u8],
    ) -> Result<Vec<u8>, ConvertError> {
        let letter = token[0].to_ascii_uppercase();
        let of = |units: Units| usize::from(units == Units::Inch);
        let out_after = self.c.out_increment[of(self.out_units())];
        let (m, k) = if dot {
            exact(whole, fraction)?
        } else {
            let count = Dec::from_digits(whole, 0).ok_or_else(too_long)?.mantissa;
            (count, self.c.src_increment[of(self.src_units)])
        };
        let u = self.scale(letter, m, k, self.length, out_after)?;
        if !dot && u == m {
            return Ok(token.to_vec());
        }
        let fmt = self.out_format(letter, false);
        let digits = u.to_string();
        if digits.len() > fmt.width() as usize {
            return Err(error(
                format!(
                    "{} is {u} least increments in the target, {} digits; the target format {} \
                     holds {} (digit overflow)",
                    text(token),
                    digits.len(),
                    fmt.spec(),
                    fmt.width()
                ),
                "Annex C",
            ));
        }
        let count = WordFormat {
            after: 0,
            decimal: false,
            before: fmt.width(),
            ..fmt
        };
        let mut out = vec![token[0]];
        write_into(
            &mut out,
            if negative { -u } else { u },
            0,
            &count,
            false,
            plus,
        );
        Ok(out)
    }

    /// `round(m * 10^-k * factor / 10^-after)` under the rounding policy, the error recorded
    /// (`m` may be negative: a tracked absolute position; the division floors).
    fn scale(
        &mut self,
        letter: u8,
        m: i128,
        k: u32,
        f: Ratio,
        after: u32,
    ) -> Result<i128, ConvertError> {
        // (in 64 bits where every factor fits, as nearly every value does: 128-bit
        // multiplication with an overflow check is several times slower)
        const SMALL: [i64; 19] = {
            let mut p = [1i64; 19];
            let mut i = 1;
            while i < 19 {
                p[i] = p[i - 1] * 10;
                i += 1;
            }
            p
        };
        let small = (
            i64::try_from(m),
            i64::try_from(f.0),
            i64::try_from(f.1),
            SMALL.get(after as usize),
            SMALL.get(k as usize),
        );
        let fast = match small {
            (Ok(m), Ok(f0), Ok(f1), Some(&pa), Some(&pk)) => m
                .checked_mul(f0)
                .and_then(|x| x.checked_mul(pa))
                .zip(f1.checked_mul(pk)),
            _ => None,
        };
        let (numerator, denominator) = match fast {
            Some((n, d)) => (i128::from(n), i128::from(d)),
            None => (
                m.checked_mul(f.0)
                    .and_then(|x| x.checked_mul(pow10(after).ok()?))
                    .ok_or_else(too_long)?,
                f.1.checked_mul(pow10(k)?).ok_or_else(too_long)?,
            ),
        };
        if denominator == 1 {
            return Ok(numerator);
        }
        // (the rounding compares 2r with the denominator: no need to reduce the fraction first;
        // in 64 bits where it fits, as nearly every value does, since 128-bit division is slow)
        let (q, r) = match (i64::try_from(numerator), i64::try_from(denominator)) {
            (Ok(n), Ok(d)) => (i128::from(n.div_euclid(d)), i128::from(n.rem_euclid(d))),
            _ => (
                numerator.div_euclid(denominator),
                numerator.rem_euclid(denominator),
            ),
        };
        if r == 0 {
            return Ok(q);
        }
        self.round(letter, q, r, denominator, after)
    }

    fn round(
        &mut self,
        letter: u8,
        q: i128,
        r: i128,
        d: i128,
        after: u32,
    ) -> Result<i128, ConvertError> {
        if self.c.rounding == Rounding::Error {
            return Err(error(
                format!(
                    "{}: the value needs more than {after} decimals in the target format and \
                     rounding is not allowed (--round error)",
                    letter as char
                ),
                "Annex C",
            ));
        }
        if self.lead_watch == Some(letter) {
            let exact = (q as f64 + r as f64 / d as f64) / 10f64.powi(after as i32);
            let (rounded, _) = round_quotient(q, r, d, self.c.rounding == Rounding::HalfUp);
            self.lead_rounded = Some((exact, rounded as f64 / 10f64.powi(after as i32)));
        }
        // (the exact value in floating point only for a feed per revolution's check: the
        // conversion of an i128 and a power of ten on every rounded word cost more than its
        // rounding)
        let per_revolution =
            letter == b'F' && self.modal.state.feed_mode == 95 && self.lead_watch != Some(letter);
        let exact =
            per_revolution.then(|| (q as f64 + r as f64 / d as f64) / 10f64.powi(after as i32));
        let (q, r) = round_quotient(q, r, d, self.c.rounding == Rounding::HalfUp);
        if let Some(exact) = exact {
            self.per_revolution(exact, q, r, d, after)?;
        }
        self.rounded = true;
        self.record(letter, r, d, after);
        Ok(q)
    }

    /// A feed per revolution (G95) rounded to the target's F format, `q` steps of `after`
    /// decimals off by `r / d` of a step: a feed per minute's format (FANUC F052, 0.01 mm) is
    /// coarse for one per revolution, which the control reads to its least input increment
    /// (IS-B 0.001 mm/rev: FANUC-type manuals, "Feed per revolution in G95 mode F0.001~
    /// F999.999 mm/rev"; Mitsubishi M700V 7.4). A feed rounded to zero on any target, or on a
    /// FANUC or Haas one changed by more than half of that increment (probe P3-18: `F0.0002` in/rev, 0.00508 mm/rev, written `F0.01`,
    /// twice the feed; `F0.0001` written `F0`) is refused: a micro drill at twice its feed
    /// breaks.
    fn per_revolution(
        &self,
        exact: f64,
        q: i128,
        r: i128,
        d: i128,
        after: u32,
    ) -> Result<(), ConvertError> {
        let inch = self.out_feed_units == Units::Inch;
        let increment = self.c.out_increment[usize::from(inch)];
        let written = q as f64 / 10f64.powi(after as i32);
        let unit = if inch { "in" } else { "mm" };
        let off = || {
            // |r / d| step of 10^-after against half a step of 10^-increment
            let twice = r.unsigned_abs().checked_mul(2)?;
            let lhs = twice.checked_mul(10u128.checked_pow(increment)?)?;
            let rhs = d.unsigned_abs().checked_mul(10u128.checked_pow(after)?)?;
            Some(lhs > rhs)
        };
        let why = if q == 0 {
            "rounds to zero".to_string()
        } else if self.c.target_family == Family::MacroB
            && increment > after
            && off().unwrap_or(true)
        {
            format!(
                "changes by {} {unit}/rev, more than half of the {} {unit} the control reads a \
                 feed per revolution to",
                significant((written - exact).abs()),
                trim_float(10f64.powi(-(increment as i32)))
            )
        } else {
            return Ok(());
        };
        Err(error(
            format!(
                "F: a feed per revolution (G95) of {} {unit}/rev is written {} by the target's F \
                 format ({after} decimals) and {why}; write the feed in values the format holds, \
                 or in feed per minute",
                trim_float(exact),
                trim_float(written)
            ),
            "units",
        ))
    }

    fn record(&mut self, letter: u8, e: i128, d: i128, after: u32) {
        // The error is e / (d * 10^after) in the target's units; kept reduced.
        let (mut e, mut d) = (e, d);
        // (the denominator in 64 bits where it fits, as nearly every one does: a 128-bit
        // multiplication with an overflow check is several times slower, and every rounded
        // word comes here)
        let small = u64::try_from(d)
            .ok()
            .zip(SMALL_POW10.get(after as usize))
            .and_then(|(d, &p)| d.checked_mul(p))
            .map(i128::from);
        match small.or_else(|| pow10(after).ok().and_then(|p| d.checked_mul(p))) {
            Some(whole) => {
                // most roundings are no larger than the worst one kept: no reduction for those
                let kept = self.worst_entry(letter);
                if let Some((_, we, wd)) = kept {
                    if no_larger(e, whole, we, wd) == Some(true) {
                        return;
                    }
                }
                let g = gcd(e, whole);
                (e, d) = (e / g, whole / g);
            }
            None => {
                // reduced a digit at a time, so that it fits as long as it can
                let mut after = after;
                while after > 0 {
                    match d.checked_mul(10) {
                        Some(next) => {
                            d = next;
                            after -= 1;
                        }
                        None => break,
                    }
                    let g = gcd(e, d);
                    (e, d) = (e / g, d / g);
                }
            }
        }
        let bigger = |(we, wd): (i128, i128)| match (e.checked_mul(wd), we.checked_mul(d)) {
            (Some(a), Some(b)) => a > b,
            _ => (e as f64 / d as f64) > (we as f64 / wd as f64),
        };
        match self.worst_at[usize::from(letter)] {
            0 => {
                self.worst.push((letter, e, d));
                // (a place of at most 256, one an address)
                self.worst_at[usize::from(letter)] = self.worst.len() as u16;
            }
            at => {
                let entry = &mut self.worst[usize::from(at) - 1];
                if bigger((entry.1, entry.2)) {
                    *entry = (letter, e, d);
                }
            }
        }
    }

    /// The largest rounding kept for `letter` ([`Converter::worst`]).
    fn worst_entry(&self, letter: u8) -> Option<(u8, i128, i128)> {
        match self.worst_at[usize::from(letter)] {
            0 => None,
            at => self.worst.get(usize::from(at) - 1).copied(),
        }
    }

    /// The increment (or G92 position) to write for an axis word: the exact absolute
    /// position of the source, converted and rounded, less the position the output has
    /// reached, so rounding never accumulates. A length's positions are held in the units
    /// they were written in; a units code in between (G21 G91 X10. G20 X1.) carries them
    /// into millimetres exactly, and the output's last position into the units and decimals
    /// now written (docs/convert.md "Incremental programs").
    #[allow(clippy::too_many_arguments)]
    fn tracked(
        &mut self,
        letter: u8,
        on: u8,
        negative: bool,
        m: i128,
        k: u32,
        f: Ratio,
        after: u32,
        set_position: bool,
    ) -> Result<i128, ConvertError> {
        let value = Dec {
            mantissa: if negative { -m } else { m },
            scale: k,
        };
        let s = slot(on);
        let start = match self.src_pos[s] {
            Some(p) => p,
            None => match self.abs_raw[s].take() {
                Some((neg, m, k)) => Dec {
                    mantissa: if neg { -m } else { m },
                    scale: k,
                },
                None => Dec::ZERO,
            },
        };
        let length = kind(on) == Some(Kind::Axis);
        let held = self.pos_units[s].unwrap_or(self.src_units);
        let out_switched = self.out_at[s].is_some_and(|at| at.0 != self.out_units());
        if length && (self.out_mm[s].is_some() || held != self.src_units || out_switched) {
            return self.tracked_across_units(letter, s, start, held, value, after, set_position);
        }
        if length {
            self.pos_units[s] = Some(held);
        }
        let position = if set_position {
            value
        } else {
            start.checked_add(value).ok_or_else(too_long)?
        };
        self.src_pos[s] = Some(position);
        let q = self.scale(letter, position.mantissa, position.scale, f, after)?;
        let previous = self.out_pos[s].unwrap_or(0);
        self.out_pos[s] = Some(q);
        self.out_at[s] = Some((self.out_units(), after));
        Ok(if set_position { q } else { q - previous })
    }

    /// [`Converter::tracked`] for a length once the source or the output has switched its
    /// units: the source's position and the output's are both held exactly in millimetres
    /// (1 in = 25.4 mm exactly), and the word written is the gap between them in the output's
    /// units, rounded; the output's position moves by exactly what was written. The machine
    /// keeps its place through a units code, so an increment after it is added to the place
    /// reached, in the new units.
    #[allow(clippy::too_many_arguments)]
    fn tracked_across_units(
        &mut self,
        letter: u8,
        s: usize,
        start: Dec,
        held: Units,
        value: Dec,
        after: u32,
        set_position: bool,
    ) -> Result<i128, ConvertError> {
        let mm = |d: Dec, units: Units| {
            if units == Units::Inch {
                d.checked_mul(Dec {
                    mantissa: 254,
                    scale: 1,
                })
                .ok_or_else(too_long)
            } else {
                Ok(d)
            }
        };
        let start = mm(start, held)?;
        let value = mm(value, self.src_units)?;
        let position = if set_position {
            value
        } else {
            start.checked_add(value).ok_or_else(too_long)?
        };
        self.src_pos[s] = Some(position);
        self.pos_units[s] = Some(Units::Metric);
        let out = self.out_units();
        let to_out = if out == Units::Inch { (5, 127) } else { ONE };
        let machine = match (self.out_mm[s], self.out_pos[s], self.out_at[s]) {
            (Some(d), _, _) => d,
            (None, Some(p), Some((units, at))) => mm(
                Dec {
                    mantissa: p,
                    scale: at,
                },
                units,
            )?,
            _ => Dec::ZERO,
        };
        let written = if set_position {
            self.scale(letter, position.mantissa, position.scale, to_out, after)?
        } else {
            let gap = position
                .checked_add(Dec {
                    mantissa: -machine.mantissa,
                    scale: machine.scale,
                })
                .ok_or_else(too_long)?;
            self.scale(letter, gap.mantissa, gap.scale, to_out, after)?
        };
        let moved = mm(
            Dec {
                mantissa: written,
                scale: after,
            },
            out,
        )?;
        self.out_mm[s] = Some(if set_position {
            moved
        } else {
            machine.checked_add(moved).ok_or_else(too_long)?
        });
        self.out_pos[s] = None;
        self.out_at[s] = Some((out, after));
        Ok(written)
    }

    /// The length factor of an assignment to the length parameter written `raw` on `line`: a
    /// parameter has no units of its own, its value is read in the units of the block that
    /// reads it (review 4: LinuxCNC's mmount.ngc sets `#102=3.0` before its G20 and reads it
    /// after), so the factor is that of its first read where one was seen or learned
    /// ([`ConvertConfig::read_units`]), and otherwise the one in force, noted for the read to
    /// compare ([`Converter::length_use`]).
    fn set_length(&mut self, raw: &[u8], line: usize) -> Ratio {
        if self.c.units.is_none() {
            return self.length;
        }
        let name = self.parameter(raw);
        self.set_length_of(name, line)
    }

    /// [`Converter::set_length`] of the parameter named `name` as the analysis names it.
    fn set_length_of(&mut self, name: String, line: usize) -> Ratio {
        if let Some(&(read, _, _)) = self.length_uses.get(&name) {
            return read;
        }
        let program = self.program;
        if let Some((_, _, units)) = self
            .c
            .read_units
            .iter()
            .find(|(p, n, _)| *p == program && *n == name)
        {
            return match (*units, self.out_units()) {
                (a, b) if a == b => ONE,
                (_, Units::Inch) => (5, 127),
                _ => (127, 5),
            };
        }
        let (length, units) = (self.length, self.src_units);
        self.set_before_read
            .entry(name)
            .and_modify(|e| e.3 |= e.0 != length)
            .or_insert((length, line, units, false));
        length
    }

    /// A length parameter written `raw` read on `line` under a change of units: its value is
    /// converted once, by the length factor where it is first read, so a read where the source
    /// is in other units (after a mid-program G20/G21, G70/G71: probe P3-17, `#1 = 10` read by
    /// `G0 X#1` in G21 and again after G20, 10 mm and 10 inches in the source, 10 mm twice
    /// once converted) is refused, naming both lines. An assignment before the first read
    /// converted by another factor is refused with [`REREAD`], the read's units learned: the
    /// conversion made again converts it by them ([`Converter::set_length`]).
    fn length_use(&mut self, raw: &[u8], line: usize) -> Result<(), ConvertError> {
        if self.c.units.is_none() {
            return Ok(());
        }
        // a parameter read as a length again under the same factor (every line of a program
        // scaled by parameters): looked up by its text where that is its name already, as
        // `class` does, with no name built
        let scoped = self.sub.is_some() && crate::statement::sub_local(raw);
        if !scoped && raw.is_ascii() && crate::statement::is_parameter_name(raw) {
            let again = std::str::from_utf8(raw)
                .ok()
                .and_then(|name| self.length_uses.get(name));
            if again.is_some_and(|&(first, _, _)| first == self.length) {
                return Ok(());
            }
        }
        let name = self.parameter(raw);
        let (length, units) = (self.length, self.src_units);
        match self.length_uses.get(&name) {
            None => {
                if let Some(&(set, at, set_units, mixed)) = self.set_before_read.get(&name) {
                    if set != length || mixed {
                        let message = format!(
                            "{name} is read as a length on line {line} in {}, and set on line \
                             {at} in {}: the value is in the units of its read, and the \
                             assignment was converted in those where it stands",
                            units.name(),
                            set_units.name()
                        );
                        self.learned.push((self.program, name.clone(), units));
                        self.length_uses.insert(name, (length, line, units));
                        return Err(error(message, REREAD));
                    }
                }
                self.length_uses.insert(name, (length, line, units));
                Ok(())
            }
            Some(&(first, _, _)) if first == length => Ok(()),
            Some(&(_, at, first_units)) => Err(error(
                format!(
                    "{name} is read as a length on line {line} in {}, and on line {at} in {}: \
                     its one value is converted once, so one of the two would read it in units \
                     it no longer has; use a parameter for each units system, or select the \
                     units once",
                    units.name(),
                    first_units.name()
                ),
                "units",
            )),
        }
    }

    /// The units of the first reads [`REREAD`] refused at, for the conversion made again.
    pub fn read_units_learned(&self) -> Vec<(usize, String, Units)> {
        self.learned.clone()
    }

    /// An indexed word or an expression: numbers converted where they are provably lengths.
    fn expression(
        &mut self,
        b: &BlockIn<'_>,
        i: usize,
        factor: Ratio,
    ) -> Result<Vec<u8>, ConvertError> {
        let mut terms = std::mem::take(&mut self.terms);
        let out = self.expression_with(b, i, factor, &mut terms);
        self.terms = terms;
        out
    }

    /// [`Converter::expression`], its expression's terms read into `terms`.
    fn expression_with(
        &mut self,
        b: &BlockIn<'_>,
        i: usize,
        factor: Ratio,
        terms: &mut expr::Terms,
    ) -> Result<Vec<u8>, ConvertError> {
        let w = b.words[i];
        let token = w.token;
        let word = Word::new(token, 0);
        let letter = word.letter;
        let mut factor = factor;
        let indexed = !word.index.is_empty();
        // the assignment's target: `R1=`, `#1=`, LinuxCNC's `#<name>=`
        let target = if indexed && b"PQR#".contains(&letter) && self.role(letter) == Role::Parameter
        {
            Some(1 + word.index.len())
        } else {
            crate::statement::named_target(token)
        };
        let is_param = target.is_some() || word.address == b'#';
        if is_param {
            let raw = &token[..target.unwrap_or(1)];
            let is_length = self.class(raw) == Some(&ParameterClass::Length);
            if self.length != ONE && !is_length {
                if let Some(problem) = self.unproved(raw) {
                    let name = self.parameter(raw);
                    if !self.c.allow_unconverted {
                        return Err(error(
                            format!("cannot convert the units of parameter {name}: {problem}"),
                            "6.4.7",
                        ));
                    }
                    // said once a conversion, counted once too (where first left)
                    if self.note(format!("parameter {name} left unconverted: {problem}")) {
                        let column = crate::text::column(b.text, w.start);
                        self.left_as_written.add(b.line, column);
                    }
                }
            }
            factor = if is_length {
                self.set_length(raw, b.line)
            } else {
                ONE
            };
        }
        let written = &b.text[w.start..w.end.min(b.text.len())];
        let format_letter = if b"PQR#".contains(&letter) {
            b'X'
        } else {
            letter
        };
        if !word.number.is_empty() {
            if factor == ONE && self.c.explicit_out {
                return Ok(self.kept(token));
            }
            let number = word.number;
            let (whole, fraction) = split_number(number);
            let (m, k) = exact(whole, fraction)?;
            let fmt = self.out_format(if indexed { format_letter } else { letter }, false);
            let u = self.scale(letter, m, k, factor, fmt.after)?;
            let negative = word.sign == b"-";
            let digits = write(
                if negative { -u } else { u },
                fmt.after,
                &fmt,
                true,
                word.sign == b"+",
            );
            let tail: Vec<u8> = word.sign.iter().chain(number).copied().collect();
            let head = if written.ends_with(&tail) {
                written
            } else {
                token
            };
            let mut out = self.kept(&head[..head.len() - tail.len()]);
            out.extend(digits.bytes());
            return Ok(out);
        }
        // a word kept as written, but one that under a change of units reads a parameter,
        // which may be converted (below)
        let as_written = factor == ONE && (is_param || self.length == ONE);
        // (a length word kept as written still reads its parameters in the units in force:
        // looked at under a change of units, `Converter::length_use`)
        if as_written && (is_param || self.c.units.is_none() || self.c.parameters.is_none()) {
            return Ok(self.kept(token));
        }
        let value_at = |written: &[u8]| {
            if indexed || target.is_some() {
                written.iter().position(|&c| c == b'=').map_or(0, |p| p + 1)
            } else {
                // Sinumerik's X=R1+5: the value after the '='
                let p = expr::skip_blanks(written, 1);
                if written.get(p) == Some(&b'=') {
                    p + 1
                } else {
                    1
                }
            }
        };
        let mut written = written;
        let mut read = expr::terms_of(&written[value_at(written)..], self.c.family, terms);
        if read.is_err() && self.c.family == Family::LinuxCnc && written != token {
            // LinuxCNC reads a line without its blanks (`X# 1` is X#1, `1 0` is 10: rs274ngc
            // close_and_downcase), which the reader of 6.4.7 does not: the word is converted
            // as the token has it, without them
            written = token;
            read = expr::terms_of(&written[value_at(written)..], self.c.family, terms);
        }
        let at = value_at(written);
        let source = &written[at..];
        let linear = match read {
            Ok(()) => terms.numbers().map(|numbers| (numbers, &terms.params[..])),
            Err(_) => None,
        };
        // (a shape looked at before under the same key: nothing to ask again, `ShapeUse`)
        let shape_use = terms.shape().map(|shape| ShapeUse {
            shape,
            program: self.program,
            sub: self.sub,
            factor,
            length: self.length,
            is_param,
        });
        let slot = shape_use.map_or(0, |u| (u.shape % SHAPE_USES as u64) as usize);
        let looked_at = shape_use.is_some() && self.shape_uses[slot] == shape_use;
        if let Some((_, params)) = linear.as_ref().filter(|_| !looked_at) {
            // Two questions of the parameters the word reads, each parameter's class looked up
            // once for both. A length read from a parameter the analysis could not class (set
            // nowhere in the program, or used both ways): its value is in units nothing here
            // converts. And each is converted as a length (by the length factor) or kept: a
            // word scaled by another factor (a feed in inverse time, a dwell's X, a surface
            // speed) reads it in units its value does not have.
            let (mut problem, mut kept) = (None, None);
            let mut lengths = Vec::new();
            for &(a, e) in params.iter() {
                let raw = &source[a..e];
                let class = self.class(raw);
                if class == Some(&ParameterClass::Length) && factor == self.length {
                    lengths.push(raw);
                }
                if let Some(ParameterClass::Unproved(why)) = class {
                    if factor != ONE && problem.is_none() {
                        problem = Some(why.clone());
                    }
                } else if !is_param && kept.is_none() {
                    let length = class == Some(&ParameterClass::Length);
                    let scaled = if length { self.length } else { ONE };
                    if scaled != factor {
                        kept = Some((self.parameter(raw), length));
                    }
                }
            }
            for raw in lengths {
                self.length_use(raw, b.line)?;
            }
            if problem.is_none() && kept.is_none() {
                self.shape_uses[slot] = shape_use;
            }
            if as_written {
                return Ok(self.kept(token));
            }
            if let Some(problem) = problem {
                if !self.c.allow_unconverted {
                    return Err(error(
                        format!(
                            "{}: cannot convert the units of the value: {problem}",
                            text(token)
                        ),
                        "6.4.7",
                    ));
                }
                self.left_line(
                    b.line,
                    crate::text::column(b.text, w.start),
                    format!(
                        "line {}: {} left unconverted: {problem}",
                        b.line,
                        text(token)
                    ),
                );
                // left exactly as written, as the note says: its numbers scaled with the
                // parameter not would be neither the old value nor the new
                return Ok(self.kept(token));
            }
            if let Some((name, true)) = kept.as_ref().filter(|_| self.left_word) {
                // a word of unknown role kept as written reads the parameter's new value
                // where the conversion scales it: the word would change, kept or not
                return Err(error(
                    format!(
                        "{}: the source control's manual, as tapegate has it, does not say \
                         what {} is in this block, so it is left as written, but it reads \
                         {name}, which this conversion converts as a length: its value would \
                         change; write the value in the word, or in a parameter read by no \
                         length",
                        text(token),
                        letter as char
                    ),
                    "6.4.7",
                ));
            }
            if let Some((name, length)) = kept {
                let why = format!(
                    "{} reads {name}, which this conversion {}, but this word's value is \
                     scaled otherwise here (as a selector's, an angle's, a feed's in inverse \
                     time, a dwell's or a surface speed's is), so its units cannot be \
                     converted exactly",
                    text(token),
                    if length {
                        "converts as a length"
                    } else {
                        "leaves as written"
                    }
                );
                // a parameter the conversion scales: the word left as written would read
                // its new value, so --allow-unconverted cannot keep it (`G05.1 Q#1`)
                if !self.c.allow_unconverted || length {
                    return Err(error(why, "6.4.7"));
                }
                let column = crate::text::column(b.text, w.start);
                self.left_line(
                    b.line,
                    column,
                    format!("line {}: {why}; left as written", b.line),
                );
                return Ok(self.kept(token));
            }
        }
        if factor == ONE {
            return Ok(self.kept(token));
        }
        let Some((numbers, _)) = linear else {
            if self.c.allow_unconverted {
                self.left_line(
                    b.line,
                    crate::text::column(b.text, w.start),
                    format!(
                        "line {}: {} left unconverted (non-linear)",
                        b.line,
                        text(token)
                    ),
                );
                return Ok(self.kept(token));
            }
            return Err(error(
                format!(
                    "{}: the value is a non-linear expression, so its units cannot be converted \
                     exactly (use --allow-unconverted to leave it as written)",
                    text(token)
                ),
                "6.4.7",
            ));
        };
        if numbers.is_empty() {
            return Ok(self.kept(token));
        }
        let after = self.out_format(format_letter, false).after;
        let mut out = self.kept(&[]);
        let mut pos = 0;
        for &(start, end) in numbers {
            let (whole, fraction) = split_number(&source[start..end]);
            let (m, k) = exact(whole, fraction)?;
            let u = self.scale(letter, m, k, factor, after)?;
            out.extend_from_slice(&written[pos..at + start]);
            explicit_into(&mut out, u, after);
            pos = at + end;
        }
        out.extend_from_slice(&written[pos..]);
        Ok(out)
    }

    /// A word's buffer back to the spares, for the next word written (a few per block, not a
    /// new allocation for each).
    /// A line's text [`Converter::convert_line`] returned, once written out: its buffer is
    /// used again (a buffer a line, not an allocation a line).
    pub fn give_back(&mut self, line: Vec<u8>) {
        self.recycle(line);
    }

    /// `bytes` in a buffer of the spares: a word's text the block gives back once written
    /// ([`Converter::recycle`]), so that a word written as it was (an expression a length
    /// parameter scales, a count) allocates and frees nothing.
    fn kept(&mut self, bytes: &[u8]) -> Vec<u8> {
        let mut out = self.spare.pop().unwrap_or_default();
        out.extend_from_slice(bytes);
        out
    }

    #[inline]
    fn recycle(&mut self, mut buffer: Vec<u8>) {
        if self.spare.len() < 64 {
            buffer.clear();
            self.spare.push(buffer);
        }
    }

    /// The block's text with the words of `replacements` (by place; None: as written).
    fn text(
        &mut self,
        b: &BlockIn<'_>,
        replacements: &mut [Option<Vec<u8>>],
        insert: Option<&str>,
    ) -> Vec<u8> {
        // the words' spans must lie in order inside the text (a word re-found in a block's text
        // whose token dropped a blank, such as a NUL, may not): else the block is written anew
        let placed = b
            .words
            .iter()
            .try_fold(0usize, |pos, w| {
                (pos <= w.start && w.start <= w.end && w.end <= b.text.len()).then_some(w.end)
            })
            .is_some();
        if self.c.spacing != Spacing::Keep || !placed {
            let spacing = if placed {
                self.c.spacing
            } else {
                Spacing::Insert
            };
            let tokens: Vec<&[u8]> = replacements
                .iter()
                .zip(b.words)
                .map(|(r, w)| r.as_deref().unwrap_or(w.token))
                .collect();
            return self.respace(b, &tokens, insert, spacing);
        }
        if let Some(code) = insert {
            let first = replacements[0]
                .take()
                .unwrap_or_else(|| b.words[0].token.to_vec());
            let numbered = matches!(b.words[0].token[0], b'N' | b'n');
            replacements[0] = Some(if numbered {
                [first.as_slice(), b" ", code.as_bytes()].concat()
            } else {
                [code.as_bytes(), b" ", first.as_slice()].concat()
            });
        }
        // the words alone, one blank between each (compared in place, without joining them):
        // the two ways of writing the line differ only where a word is replaced by nothing
        // (the join drops the blank before it, the copy the blanks after it), so the
        // comparison is made only then
        let joined_as_written = b.plain
            && replacements
                .iter()
                .any(|r| r.as_ref().is_some_and(Vec::is_empty))
            && {
                let mut pos = 0;
                b.words.iter().enumerate().all(|(i, w)| {
                    let blank = usize::from(i > 0);
                    let end = pos + blank + w.token.len();
                    let same = end <= b.text.len()
                        && (blank == 0 || b.text[pos] == b' ')
                        && &b.text[pos + blank..end] == w.token;
                    pos = end;
                    same
                }) && pos == b.text.len()
            };
        // (into a buffer of the spare ones: the caller may give each line's back, `give_back`)
        let mut out = self.spare.pop().unwrap_or_default();
        out.reserve(b.text.len() + 8);
        // (a word replaced by nothing, B's and C's G90 for system A, goes with its blank)
        if joined_as_written {
            let mut first = true;
            for (r, w) in replacements.iter().zip(b.words) {
                let word = r.as_deref().unwrap_or(w.token);
                if word.is_empty() {
                    continue;
                }
                if !first {
                    out.push(b' ');
                }
                first = false;
                out.extend_from_slice(word);
            }
            return out;
        }
        let mut pos = 0;
        for (r, w) in replacements.iter().zip(b.words) {
            if let Some(new) = r {
                // (the text between two words is mostly one blank: pushed, not copied by a
                // call of memcpy)
                match &b.text[pos..w.start] {
                    [c] => out.push(*c),
                    between => out.extend_from_slice(between),
                }
                out.extend_from_slice(new);
                pos = w.end;
                if new.is_empty() {
                    pos += b.text[pos..].iter().take_while(|&&c| c == b' ').count();
                }
            }
        }
        out.extend_from_slice(&b.text[pos..]);
        out
    }

    fn respace(
        &self,
        b: &BlockIn<'_>,
        tokens: &[&[u8]],
        insert: Option<&str>,
        spacing: Spacing,
    ) -> Vec<u8> {
        let mut pieces: Vec<(usize, &[u8])> = b
            .words
            .iter()
            .zip(tokens)
            .map(|(w, t)| (w.start, *t))
            .collect();
        pieces.extend(b.comments.iter().copied());
        pieces.extend(b.statements.iter().map(|&(at, _, t)| (at, t)));
        pieces.extend(b.skip_within);
        pieces.sort_by_key(|&(at, _)| at);
        let mut texts: Vec<&[u8]> = pieces.into_iter().map(|(_, t)| t).collect();
        // a statement keeps a blank on each side: GOTO 10 glued to a word could read otherwise
        let glued_ok = b.statements.is_empty();
        if let Some(code) = insert {
            let at = usize::from(
                texts
                    .first()
                    .is_some_and(|t| matches!(t.first(), Some(b'N' | b'n'))),
            );
            texts.insert(at, code.as_bytes());
        }
        let joiner: &[u8] = if spacing == Spacing::Remove && glued_ok {
            b""
        } else {
            b" "
        };
        let mut line = texts.join(joiner);
        if !b.skip.is_empty() {
            let mut head = b.skip.to_vec();
            if spacing == Spacing::Insert {
                head.extend_from_slice(joiner);
            }
            head.extend(line);
            line = head;
        }
        // HEIDENHAIN's end of block, ` *`, is no word: kept as the block's last piece, with
        // its blank (the TNC writes one before it), whatever the spacing
        if self.c.family == Family::Heidenhain && heidenhain_end(b.text) && !line.ends_with(b"*") {
            line.extend_from_slice(b" *");
        }
        if b.text.ends_with(b"\r") {
            line.push(b'\r');
        }
        line
    }
}

/// A refusal of the units flow ([`crate::units_flow`]) as the converter's: at the byte offset
/// it gives in the block (1: the block's start), its message after `prefix`.
fn flow_refusal(b: &BlockIn<'_>, r: crate::units_flow::Refusal, prefix: &str) -> ConvertError {
    ConvertError {
        message: format!("{prefix}{}", r.message),
        clause: "units",
        column: if r.column == 1 {
            1
        } else {
            crate::text::column(b.text, r.column)
        },
        line: None,
    }
}

/// A LinuxCNC body's refusal ([`crate::sub_units`]) as the converter's, at its line.
fn body_refusal(r: crate::sub_units::Refusal) -> ConvertError {
    ConvertError {
        message: r.message,
        clause: "units",
        column: r.column,
        line: Some(r.line),
    }
}

/// `text` with the spans `(start, end, new)` (in order, apart) replaced.
fn splice(text: &[u8], spans: &[(usize, usize, Vec<u8>)]) -> Vec<u8> {
    let mut out = Vec::with_capacity(text.len() + 16);
    let mut pos = 0;
    for (start, end, new) in spans {
        out.extend_from_slice(&text[pos..*start]);
        out.extend_from_slice(new);
        pos = *end;
    }
    out.extend_from_slice(&text[pos..]);
    out
}

/// Where byte `offset` of a text is once the spans before it are replaced ([`splice`]).
fn shifted(offset: usize, spans: &[(usize, usize, Vec<u8>)]) -> usize {
    spans
        .iter()
        .filter(|(start, ..)| *start < offset)
        .fold(offset, |at, (start, end, new)| {
            at + new.len() - (end - start)
        })
}

/// Whether a HEIDENHAIN ISO block's text ends with its end-of-block mark `*` (blanks and a CR
/// after it); a comment that runs to the end holds it already (`; TEXT *`).
fn heidenhain_end(text: &[u8]) -> bool {
    let end = text
        .iter()
        .rposition(|&c| !matches!(c, b' ' | b'\t' | b'\r'))
        .map_or(0, |i| i + 1);
    text[..end].ends_with(b"*")
}

/// The roles a block's cycle gives its words, from the family's cycle table (docs/convert.md):
/// a Fanuc or Haas lathe's G70-G76, the peck and boring cycles of a mill, and the numbers of
/// G10, G65 and M98. None for a letter the cycle says nothing about (the profile's
/// `checks.pqr` applies). `Role::Increments` is a length the cycle writes as a count of least
/// input increments (the Fanuc lathe's `G76 P1200 Q350`, `G74 P3000 Q5000`).
pub fn cycle_roles(
    family: Family,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    words: &[WordSpan<'_>],
) -> [Option<Role>; 26] {
    cycle_meanings(family, lathe, gs, ms, words).roles
}

/// [`cycle_roles`], and whether the block's axis words are its code's data, not a move: the
/// cycle tables, then the words a code gives a meaning of its own ([`crate::meaning`]: an
/// angle, a direction, a selector), which take precedence.
pub fn cycle_meanings(
    family: Family,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    words: &[WordSpan<'_>],
) -> crate::meaning::Meanings {
    cycle_meanings_in(
        crate::meaning::GCodeSystem::A,
        family,
        None,
        lathe,
        gs,
        ms,
        words,
    )
}

/// Whether G code `g` (by its system A number, [`crate::modal::ModalSettings::read_g`]) is of
/// the motion group (group 01) of a FANUC or Haas control: on a lathe G00-G03, threading G32
/// and G34 (G33 of B and C, read as G32) and the single cycles G90, G92, G94 (G77-G79 of B,
/// G20/G21/G24 of C); on a mill G00-G03 and threading G33 (FANUC 0i-TF B-64604EN and 0i-MF
/// B-64694EN, "G code list"). A lathe's G80 is no code of it: group 10's, the drilling cycles'
/// cancel, which leaves a threading G92 or G32 in force.
pub fn motion_group(lathe: bool, g: i64) -> bool {
    match g {
        0..=3 | 33 => true,
        32 | 34 | 90 | 92 | 94 => lathe,
        _ => false,
    }
}

/// Whether G code `g` (by its system A number) ends a canned drilling cycle in force on a
/// FANUC or Haas control: G80, and every code of the motion group ([`motion_group`]; FANUC
/// 0i-TF and 0i-MF, "Canned cycle for drilling": the cycle is cancelled by G80 or a group 01 G
/// code; Haas NGC lathe and mill manuals, G80 and G00-G03).
pub fn ends_canned_cycle(lathe: bool, g: i64) -> bool {
    g == 80 || motion_group(lathe, g)
}

/// Whether two control families write a dwell's time differently (units, or words), so that
/// a conversion between them converts it or refuses it ([`Converter::dwell_time`]): between
/// FANUC/Haas Macro B and LinuxCNC, and between any two families where one is LinuxCNC,
/// HEIDENHAIN or SINUMERIK (an ISO or Okuma G04 X to a Macro B control is the same word).
fn dwell_differs(from: Family, to: Family) -> bool {
    const OWN: [Family; 3] = [Family::LinuxCnc, Family::Heidenhain, Family::Sinumerik];
    from != to && (OWN.contains(&from) || OWN.contains(&to))
}

/// Whether canned cycle `g` (its system A number) takes P as the dwell at the hole's bottom on a
/// FANUC or Haas control: a mill's G73, G74, G76 and G82-G89 (FANUC 0i-MF, Haas NGC mill
/// manual), a lathe's G83-G89 (FANUC 0i-TF "Canned cycle for drilling") and the Haas lathe's
/// radial live-tool cycles G241-G249 (their P the dwell, haas-lathe.toml). A lathe's G73, G74
/// and G76 are multiple repetitive cycles, whose P is no time.
pub fn dwell_cycle(lathe: bool, g: i64) -> bool {
    match g {
        82..=89 => true,
        73 | 74 | 76 => !lathe,
        241..=249 => lathe,
        _ => false,
    }
}

/// Whether a lathe's U and W move X and Z by an increment, their rounding carried on X Z's
/// positions as a G91 word's is: the one rule the converter ([`Converter::block`]) and
/// `--verify`'s reader (`ncread::Reader`) each keep one of and ask alike, so that the proof
/// reads a U or W as the conversion wrote it (review 60, F2: the converter carried a system B
/// thread's `G33 W-20.` to inch as a move, `W-0.7875`, and the reader, per word, refused it).
///
/// A FANUC or Haas lathe of G code system A: in G00-G03 and threading G32/G34 U and W are the
/// increments of X and Z (FANUC 0i-TF, "Absolute and incremental programming" and "Thread
/// cutting G32": the tool cuts to the end point and stays there), not in a turning or threading
/// cycle (G90, G92, G94, G70-G76, G80-G89; system A's G33, as the checker reads it), whose U
/// and W are its own and whose tool returns to its start point
/// ([`crate::modal::ModalMachine::uw_moved_xz`]). An Okuma OSP lathe's likewise, but for the
/// finishing allowances of its thread, LAP and M-tool cycles (G31-G35, G71-G89 but G80,
/// G178-G189; OSP-P200L, 5238-E, "Absolute and incremental commands"). In G code system B or
/// C, which programs increments by G90/G91, no manual at hand says whether U and W still move
/// X and Z (docs/dialects.md, "G code systems B and C"): there a U or W is converted on its
/// own, as the value it is, and compared so ([`UwMoves::carried`] false), though it is still a
/// word of the move, not a cycle's ([`UwMoves::of_move`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UwMoves {
    lathe: UwLathe,
    /// The motion in force is one whose U and W are the move's, not a cycle's: from the start
    /// of a program until a cycle's code.
    motion: bool,
}

/// The lathes whose U and W are increments of X and Z ([`UwMoves`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum UwLathe {
    None,
    /// A FANUC or Haas lathe; whether of G code system A.
    Fanuc {
        system_a: bool,
    },
    Okuma,
}

impl UwMoves {
    /// The rule of a machine: a lathe or not, its family and (a FANUC lathe) its G code system.
    pub fn new(lathe: bool, family: Family, system: crate::meaning::GCodeSystem) -> UwMoves {
        let lathe = match family {
            _ if !lathe => UwLathe::None,
            Family::MacroB => UwLathe::Fanuc {
                system_a: system == crate::meaning::GCodeSystem::A,
            },
            Family::Okuma => UwLathe::Okuma,
            _ => UwLathe::None,
        };
        UwMoves {
            lathe,
            motion: true,
        }
    }

    /// The start of a program (G00-G03 in force).
    pub fn reset(&mut self) {
        self.motion = true;
    }

    /// After a G code `g` of the block (its system A number).
    pub fn code(&mut self, g: i64) {
        match self.lathe {
            UwLathe::None => {}
            UwLathe::Fanuc { .. } => match g {
                0..=3 | 32 | 34 => self.motion = true,
                33 | 70..=76 | 80..=90 | 92 | 94 => self.motion = false,
                _ => {}
            },
            UwLathe::Okuma => match g {
                0..=3 | 80 => self.motion = true,
                31..=35 | 71..=89 | 178..=189 => self.motion = false,
                _ => {}
            },
        }
    }

    /// A U or W now is a word of the move (in whatever G code system), not a cycle's.
    pub fn of_move(&self) -> bool {
        self.lathe != UwLathe::None && self.motion
    }

    /// A U or W now moves X or Z by an increment, its rounding carried on X Z's position (not
    /// in G code system B or C, whose U and W are converted and compared each on its own).
    pub fn carried(&self) -> bool {
        self.of_move() && self.lathe != UwLathe::Fanuc { system_a: false }
    }

    /// A U or W now is a move's word of G code system B or C, read on its own.
    pub fn on_its_own(&self) -> bool {
        self.of_move() && self.lathe == UwLathe::Fanuc { system_a: false }
    }
}

/// The codes a block of a FANUC or Haas control that names none of its own repeats, with the
/// words it changes (`Z-22. Q4000` after a lathe's `G83 ... Q5000`): they take the code's
/// roles. The converter and `--verify`'s reader keep one each and ask [`Repeat::after`] at
/// every block, so the two read a repeated block alike.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Repeat {
    /// The canned drilling cycle in force (its system A number): a mill's G73, G74, G76 and
    /// G81-G89, a lathe's G83-G89 and a Haas lathe's G241-G249 (a lathe's G70-G76 act in their
    /// block); ended by [`ends_canned_cycle`] and by M02/M30.
    pub cycle: Option<i64>,
    /// A lathe's threading G32 or threading cycle G92 in force ([`crate::modal::modal_thread`]),
    /// codes of the motion group, which only another code of the group ends
    /// ([`motion_group`]) or M02/M30: not G80, of group 10, nor a drilling cycle of the group,
    /// after whose G80 the thread is in force again (FANUC 0i-TF B-64604EN, "G code list"), as
    /// the checker's modal state has it ([`crate::modal::ModalState::code_in_force`]; review
    /// 58b, F8: `G92 ...` / `G80` / `X23.5 Q180000` was refused as a digit overflow).
    pub thread: Option<i64>,
}

impl Repeat {
    /// The code a block naming none repeats: the drilling cycle in force, else the thread.
    pub fn code(&self) -> Option<i64> {
        self.cycle.or(self.thread)
    }

    /// What is in force after a block whose G codes (read in system A numbers) are `gs` and M
    /// codes `ms`.
    pub fn after(self, family: Family, lathe: bool, gs: &[i64], ms: &[i64]) -> Repeat {
        if family != Family::MacroB || ms.iter().any(|&m| m == 2 || m == 30) {
            return Repeat::default();
        }
        let modal_cycle = |g: i64| match g {
            81..=89 => true,
            73 | 74 | 76 => !lathe,
            241..=249 => lathe,
            _ => false,
        };
        let cycle = if gs.iter().any(|&g| ends_canned_cycle(lathe, g)) {
            None
        } else {
            gs.iter().copied().find(|&g| modal_cycle(g)).or(self.cycle)
        };
        let thread = match gs.iter().copied().find(|&g| motion_group(lathe, g)) {
            Some(g) if lathe && crate::modal::modal_thread(g) => Some(g),
            Some(_) => None,
            None => self.thread.filter(|_| lathe),
        };
        Repeat { cycle, thread }
    }
}

/// [`cycle_meanings`] on a FANUC lathe of G code `system` B or C: `gs` by their system A
/// numbers ([`crate::modal::ModalSettings::read_g`]), the G words as written in `system`.
pub fn cycle_meanings_in(
    system: crate::meaning::GCodeSystem,
    family: Family,
    haas: Option<bool>,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    words: &[WordSpan<'_>],
) -> crate::meaning::Meanings {
    let tokens = words.iter().map(move |w| match w.token[0] {
        b'G' | b'g' => (w.token[0], system.token(&w.token[1..])),
        letter => (letter, &w.token[1..]),
    });
    code_meanings_of(family, haas, lathe, gs, ms, tokens)
}

/// [`cycle_meanings`] from a block's words as (address, number as written): the checker reads
/// a word's format by the same roles as the converter (a count or an angle of the cycle is no
/// length read in least input increments).
pub fn code_meanings<'a, I>(
    family: Family,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    tokens: I,
) -> crate::meaning::Meanings
where
    I: Iterator<Item = (u8, &'a [u8])> + Clone,
{
    code_meanings_of(family, None, lathe, gs, ms, tokens)
}

/// [`code_meanings`] on a control known to be a Haas or not (`haas`; None: either control of
/// the FANUC family, as the converter reads its source): a meaning only a Haas gives a word
/// (G84/G74 J, the retract multiple of the Haas mill manual) is not read on a FANUC, whose
/// G84 has no J (0i-MF: X Y Z R P Q F K).
pub fn code_meanings_of<'a, I>(
    family: Family,
    haas: Option<bool>,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    tokens: I,
) -> crate::meaning::Meanings
where
    I: Iterator<Item = (u8, &'a [u8])> + Clone,
{
    // the block's addresses (bit `letter - b'A'`)
    let letters = tokens.clone().fold(0u32, |letters, (address, _)| {
        let address = address.to_ascii_uppercase();
        if !address.is_ascii_uppercase() {
            return letters;
        }
        letters | 1 << (address - b'A')
    });
    // a block without a G or M word (most of a CAM program's moves): no code gives any word a
    // meaning, neither the cycle tables (by the block's G and M codes) nor `meaning::block`
    // (by its G and M words)
    let codes = 1 << (b'G' - b'A') | 1 << (b'M' - b'A');
    if gs.is_empty() && ms.is_empty() && letters & codes == 0 {
        return crate::meaning::Meanings::default();
    }
    meanings_by_codes(family, haas, lathe, gs, ms, tokens, letters)
}

/// The meanings the codes of a block give its words (`words` as (letter, number as written))
/// on a control of `family` (a Haas or not: `haas`) read by `settings` (its lathe, its G
/// code system), `cycle` the code in force before it (`ModalState::code_in_force`: a mill's canned
/// cycle, a lathe's G32 or G92): the block's G and M codes, and that code where the block
/// writes no other code of the motion group
/// (a `G91 X10. K4` repeats a G81 at the next hole, K its repeat count; FANUC 0i-MF "Canned
/// cycle"; audit 50, B9). The one reading of the checker ([`crate::check::Checker`]'s) and
/// of the modal state on its own ([`block_counts`]), so that the two count a cycle's
/// repeats alike (review 55a, F4).
pub fn block_meanings<'a, I>(
    settings: &ModalSettings,
    (family, haas): (Family, bool),
    cycle: Option<i64>,
    words: I,
) -> crate::meaning::Meanings
where
    I: Iterator<Item = (u8, &'a [u8])> + Clone,
{
    let (mut gs, mut ms) = ([0i64; 8], [0i64; 4]);
    let (mut g, mut m) = (0, 0);
    let mut g_unread = false;
    for (letter, number) in words.clone().filter(|(l, _)| matches!(l, b'G' | b'M')) {
        let Some((n, 0)) = crate::meaning::code(number) else {
            g_unread |= letter == b'G';
            continue;
        };
        if letter == b'G' && g < gs.len() {
            gs[g] = n;
            g += 1;
        } else if letter == b'M' && m < ms.len() {
            ms[m] = n;
            m += 1;
        }
    }
    let lathe = settings.fanuc_lathe || settings.lap;
    // a FANUC lathe's codes of G code system B or C by their system A numbers
    for n in &mut gs[..g] {
        *n = settings.read_g(*n);
    }
    // (a lathe's code in force, its G32 or G92, is read only into a plain pass: no code of
    // the block's own reads Q, `modal::thread_pass`)
    let motion = match lathe {
        false => gs[..g].iter().any(|&c| matches!(c, 0..=3 | 73..=89)),
        true => !crate::modal::thread_pass(&gs[..g], g_unread || g == gs.len()),
    };
    // (a lathe's drilling cycle in force is not read into a block of positions: its thread)
    let cycle = cycle.filter(|&c| !lathe || settings.fanuc_lathe && crate::modal::modal_thread(c));
    if let Some(code) = cycle.filter(|_| !motion && g < gs.len()) {
        gs[g] = code;
        g += 1;
    }
    let system = settings.g_system;
    let words = words.map(move |(letter, number)| match letter {
        b'G' => (letter, system.token(number)),
        _ => (letter, number),
    });
    code_meanings_of(family, Some(haas), lathe, &gs[..g], &ms[..m], words)
}

/// The letters (bit `letter - b'A'`) a block's cycle makes a count ([`block_meanings`],
/// [`crate::meaning::Meanings::cycle_count`]) among those of its word `tokens` written
/// without a point, and its K however written, the modal state's own reading (restart,
/// plot, the diff's motion: [`crate::word::Numbers::block_values`]); `cycle` the one in
/// force before the block. The control's family and whether it is a Haas are the settings'
/// (a machine's modal settings and its checker's are one profile's, `machine::Machine::new`).
/// Only a block with such a word under a cycle, or with G or M codes, is read for them.
pub fn block_counts(settings: &ModalSettings, cycle: Option<i64>, tokens: &[&[u8]]) -> u32 {
    let (mut letters, mut asked) = (0u32, 0u32);
    for token in tokens {
        let w = Word::new(token, 0);
        if w.letter.is_ascii_uppercase() {
            letters |= 1 << (w.letter - b'A');
            if !w.number.is_empty() && (!w.point || w.letter == b'K') {
                asked |= 1 << (w.letter - b'A');
            }
        }
    }
    let codes = 1 << (b'G' - b'A') | 1 << (b'M' - b'A');
    if asked & !codes == 0 || (cycle.is_none() && letters & codes == 0) {
        return 0;
    }
    let words = tokens.iter().map(|token| {
        let w = Word::new(token, 0);
        (w.letter, w.number)
    });
    let meanings = block_meanings(settings, (settings.family, settings.haas), cycle, words);
    (0..26u8)
        .filter(|&i| asked & 1 << i != 0 && meanings.cycle_count(b'A' + i))
        .fold(0u32, |bits, i| bits | 1 << i)
}

/// [`code_meanings_of`] of a block with G or M codes, its addresses `letters` (bit
/// `letter - b'A'`) in hand.
fn meanings_by_codes<'a, I>(
    family: Family,
    haas: Option<bool>,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    tokens: I,
    letters: u32,
) -> crate::meaning::Meanings
where
    I: Iterator<Item = (u8, &'a [u8])> + Clone,
{
    // the addresses written with a decimal point, which only the cycles G73-G89 and G243 ask
    // of (`cycle_table`: a count of increments or a length, a Haas peck): not read for others
    let asked = gs.iter().any(|&g| (73..=89).contains(&g) || g == 243);
    let pointed = tokens
        .clone()
        .filter(|_| asked)
        .fold(0u32, |pointed, (address, number)| {
            let address = address.to_ascii_uppercase();
            if !address.is_ascii_uppercase() || !number.contains(&b'.') {
                return pointed;
            }
            pointed | 1 << (address - b'A')
        });
    let table = cycle_table(family, haas, lathe, gs, ms, letters, pointed);
    let mut meanings = crate::meaning::block(family, lathe, tokens);
    meanings.start_angle = table.start_angle;
    if !meanings.any() {
        meanings.roles = table.roles;
        meanings.measures = table.measures;
        return meanings;
    }
    for (i, (meaning, role)) in meanings.roles.iter_mut().zip(table.roles).enumerate() {
        if meaning.is_none() {
            *meaning = role;
            meanings.measures |= table.measures & 1 << i;
        }
    }
    meanings
}

/// What the cycle tables make of a block's letters: each one's role, and which of the numbers
/// they make `Role::Other` measure (bit `letter - b'A'`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct CycleTable {
    roles: [Option<Role>; 26],
    /// A time, an angle or a ratio the control reads as written, whole where it has no point
    /// (a drilling cycle's dwell P, a thread's start angle Q, Haas G76's tool nose angle A):
    /// the diff compares it within its tolerance, where a number the table makes that counts
    /// or names (K and L repeats, P and Q block numbers, H passes, G76's packed P, a
    /// selector) is compared exactly ([`crate::meaning::Meanings::cycle_measure`]).
    measures: u32,
    /// Q is a thread's start angle in 0.001 deg ([`crate::meaning::Meanings::start_angle`]).
    start_angle: bool,
}

fn cycle_table(
    family: Family,
    haas: Option<bool>,
    lathe: bool,
    gs: &[i64],
    ms: &[i64],
    letters: u32,
    pointed: u32,
) -> CycleTable {
    let mut roles = [None; 26];
    let measures = std::cell::Cell::new(0u32);
    if family == Family::Iso {
        return CycleTable {
            roles,
            measures: 0,
            start_angle: false,
        };
    }
    // the block's addresses, and those written with a point (bit `letter - b'A'`)
    let has = |letter: u8| letters & 1 << (letter - b'A') != 0;
    let has_point = |letter: u8| pointed & 1 << (letter - b'A') != 0;
    let mut set = |letters: &[u8], role: Role| {
        for &l in letters {
            roles[slot(l)] = Some(role);
            measures.set(measures.get() & !(1 << slot(l)));
        }
    };
    // of the numbers just set, those that measure (a time, an angle, a ratio: [`CycleTable`])
    let measure = |letters: &[u8]| {
        for &l in letters {
            measures.set(measures.get() | 1 << slot(l));
        }
    };
    let (length, number, increments) = (Role::Length, Role::Other, Role::Increments);
    let linuxcnc = family == Family::LinuxCnc;
    let mut start_angle = false;
    for &g in gs {
        match g {
            // LinuxCNC's G-code reference: G64 P(blending tolerance) Q(naive CAM tolerance)
            // are lengths; G5 I J P Q (the cubic spline's control point offsets) too; G76
            // P(pitch) I(peak offset) J(first cut) K(thread depth) E(taper) are lengths and
            // R(depth degression) Q(compound slide angle) H(spring passes) L(taper ends) not
            64 if linuxcnc => set(b"PQ", length),
            5 if linuxcnc => set(b"IJPQ", length),
            76 if linuxcnc => {
                set(b"PIJKE", length);
                set(b"RQHL", number);
                measure(b"RQ");
            }
            70 if lathe => set(b"PQ", number),
            // a Haas lathe's G199 R: the secondary spindle's phase angle to the main one, in
            // degrees (Haas NGC lathe manual, G199), no length
            199 if lathe && family == Family::MacroB && haas != Some(false) => {
                set(b"R", number);
                measure(b"R");
            }
            // a Haas lathe's G107 Q R: the Haas mill manual gives Q the cylinder's diameter and
            // R its radius, lengths; the lathe manual's page was not at hand, so on a lathe
            // they are refused under a change of units rather than guessed
            107 if lathe && family == Family::MacroB && haas != Some(false) => {
                set(b"QR", Role::Parameter)
            }
            // a lathe's threading G32, threading cycle G92 (and a block repeating them,
            // `Repeat`): Q the start angle shift, least increment 0.001 deg,
            // 0-360000 (FANUC 0i-TF operator's manual, "Threading (G32)", "Threading cycle
            // (G92)"; Haas lathe G32: "Q - Thread Start Angle (do not use a decimal point)")
            32 | 92 if lathe && family == Family::MacroB => {
                set(b"Q", number);
                measure(b"Q");
                start_angle = true;
            }
            71 | 72 if lathe => {
                if has(b'P') && has(b'Q') {
                    // G71 P(ns) Q(nf) U W (D F): block numbers, finishing allowances (Haas: D
                    // the depth of cut; R1 the YASNAC type II roughing selector, Haas lathe
                    // operator's manual, G71)
                    set(b"PQRL", number);
                    set(b"UWD", length);
                } else {
                    set(b"UWRD", length); // G71 U(depth) R(retract), the 0i's first block
                }
            }
            73 if lathe => {
                if has(b'P') && has(b'Q') {
                    set(b"PQ", number);
                    set(b"UW", length);
                } else {
                    set(b"UW", length);
                    set(b"R", Role::Selector); // the number of divisions, a whole count
                }
            }
            74 | 75 if lathe => {
                // G74 X Z P(travel) Q(peck) R(relief): P and Q in least input increments, no
                // decimal point; R (and the first block's R, the return) a length as written
                set(b"PQ", increments);
                set(b"RD", length);
            }
            76 if lathe => {
                if has(b'K') {
                    // Haas one-block G76 X Z K(height) D(first cut) I(taper) A(angle) P Q;
                    // A the tool nose angle in degrees, "do not use a decimal point" (Haas
                    // lathe operator's manual, G76)
                    // (P the infeed method, 1-4: a selector; Q the start angle, in 0.001 deg
                    // as G32's, meaning::Meanings::start_angle)
                    set(b"KDI", length);
                    set(b"PQA", number);
                    measure(b"QA");
                    start_angle = family == Family::MacroB;
                } else if has(b'X') || has(b'Z') || has(b'U') || has(b'W') {
                    // the 0i's second block: P thread height and Q first cut in least input
                    // increments, R the taper, a length as written
                    set(b"PQ", increments);
                    set(b"R", length);
                } else {
                    set(b"P", number); // the first block: P packs m, r, a as digits
                    set(b"Q", increments); // the least cut depth
                    set(b"R", length); // the finishing allowance
                }
            }
            83 | 87 | 243 if lathe => {
                // a lathe's face and side drilling (FANUC 0i-TF, "Canned cycle for
                // drilling"; Haas lathe G83, and G243 its radial live-tool form): Q the peck,
                // without a point a count of least input increments as in G74 (`Q5000`: 5 mm),
                // with one the length it writes (Haas `Q0.1`)
                set(b"Q", if has_point(b'Q') { length } else { increments });
                set(b"P", number); // the dwell
                measure(b"P");
            }
            84 | 88 if lathe && family == Family::MacroB => {
                // a FANUC lathe's face and side tapping: with peck rigid tapping (0i-TF,
                // "Peck rigid tapping cycle (G84 or G88)", parameter PCT No. 5200#5) Q is the
                // depth of each peck, read as G83's (review 59c F3: kept unconverted under a
                // change of units, "verified"); a Haas lathe's G84 reads no Q (Haas lathe
                // operator's manual, G84), so there, or where the control is not known, Q
                // is refused under a change of units rather than guessed
                let peck = if has_point(b'Q') { length } else { increments };
                set(
                    b"Q",
                    if haas == Some(false) {
                        peck
                    } else {
                        Role::Parameter
                    },
                );
                set(b"P", number); // the dwell
                measure(b"P");
            }
            73 | 83 => {
                set(b"Q", length); // the peck
                set(b"P", number); // the dwell
                measure(b"P");
            }
            76 | 87 => {
                set(b"Q", length); // the shift
                set(b"P", number); // the dwell
                measure(b"P");
            }
            74 | 82 | 84 | 86 | 88 | 89 => {
                set(b"P", number); // the dwell
                measure(b"P");
            }
            _ => {}
        }
        // a mill's canned cycle: K the number of repeats on a FANUC (0i-MF operator's
        // manual, canned cycles, "K: number of repeats"); a Haas G73/G83's I J K are the
        // first, reducing and least peck depths, lengths; Haas G84 J the retract multiple
        // (J2: twice as fast, Haas mill operator's manual, G84)
        match g {
            // a Haas's repeat count is L ("L: number of holes", Haas mill operator's manual,
            // G81-G89), its G73/G83's K the least peck depth, a length, in a block of hole
            // positions too (review 51, F15: `G91 X1. K4` after a G83 was read as four
            // repeats, and kept unconverted under a change of units); no other Haas cycle
            // reads K
            73 | 74 | 76 | 81..=89 if !lathe && family == Family::MacroB && haas == Some(true) => {
                if matches!(g, 73 | 83) {
                    set(b"K", length);
                }
                if matches!(g, 74 | 84) {
                    set(b"J", number); // the retract multiple (G84; G74 its reverse)
                }
            }
            73 | 74 | 76 | 81..=89 if !lathe && family == Family::MacroB && haas != Some(true) => {
                if matches!(g, 73 | 83) && haas.is_none() {
                    // either control of the language: a Haas G73/G83's K is the least peck
                    // depth, a length, a FANUC's the repeat count: not known which, refused
                    // under a change of units rather than guessed (review 56a, F3)
                    set(b"K", Role::Parameter);
                } else {
                    // a FANUC's K is the repeat count in every cycle, whether or not the
                    // block writes I or J (0i-MF / 30i-MB, G73 and G83: X Y Z R Q F K, no I
                    // or J peck words; review 56a, F3: `I1. J0.5 K2` was converted as a
                    // length, K0.0001 in inch, where the checker and the FANUC count two
                    // holes), and with a point too: `K3.` is three, as the checker reads it
                    // (no source at hand says otherwise; review 56a, F8), and a K that is no
                    // whole count is TG544 and refused by the converter
                    set(b"K", number);
                }
                if (g == 84 || g == 74) && haas != Some(false) {
                    // (G74, the reverse of G84 in Haas's cycle list; its own page was not at
                    // hand, and FANUC's G74 has no J: no control reads it as a length)
                    set(b"J", number);
                }
            }
            // a Haas lathe's G83: I J K the first, reducing and least peck depths, lengths,
            // with or without I and J (Haas lathe operator's manual, G83 "End face peck
            // drilling": K the optional minimum depth of cut); no other of its drilling
            // cycles reads K, and none counts repeats in it (review 55a F8: `G83 Z-1. R0.1
            // Q0.1 K0.05` kept K unscaled under a change of units, as a FANUC count)
            83 if lathe && family == Family::MacroB && haas == Some(true) => set(b"K", length),
            // a lathe's drilling cycles G83-G89: K the number of repeats on a FANUC (0i-TF,
            // "Canned cycle for drilling": "K: number of repeats"), whether or not the block
            // writes I or J, which its G83 has not (review 56a, F3); on either control of
            // the language a G83's K (a Haas's least peck depth, above) is refused under a
            // change of units rather than guessed
            83 if lathe && family == Family::MacroB && haas.is_none() => set(b"K", Role::Parameter),
            83..=89 if lathe && family == Family::MacroB && haas != Some(true) => {
                set(b"K", number);
            }
            _ => {}
        }
    }
    if gs.iter().any(|&g| matches!(g, 10 | 65 | 66)) {
        // G10 L2 P1: the offset's number (R the value, a length); G65/G66 P the macro and L
        // the count: the block's own code's, whatever canned cycle is in force (review 57a
        // F1: under a modal G82, `G10 L2 P1`'s P was read as the cycle's dwell)
        set(b"PL", number);
    }
    if ms.iter().any(|&m| matches!(m, 97..=99 | 198)) {
        // the program or block number and the count (M99 P: the sequence number returned to)
        set(b"PL", number);
    }
    if family == Family::MacroB {
        if ms.contains(&98) && haas != Some(true) {
            // FANUC `M98 Q101`: the subprogram call by sequence number, Q the sequence number
            // of the block called in the same program (or in program P) (FANUC 0i-F / 30i-B
            // operator's manuals, "Subprogram call": M98 Q_); a block number, never a length
            set(b"Q", number);
        }
        if ms.contains(&96) {
            // Haas `M96 P100 Q8`: jump to block P if input Q is off (Haas NGC mill operator's
            // manual, M96): a block number and an input number; FANUC's M96 (the interrupt
            // type custom macro on, parameter 6033) takes P, the interrupt macro's program
            // number (0i-F operator's manual, "Interruption type custom macro"): a number too
            set(b"P", number);
            if haas != Some(false) {
                set(b"Q", number);
            }
        }
    }
    // a word the table reads in least input increments (G74 Q, G76 P Q) written with a point
    // is no count of increments: the length it writes, as a lathe's G83 Q (`Q2.5` stays
    // `Q2.5` on its own control and is scaled as a length in a change of units)
    for (i, role) in roles.iter_mut().enumerate() {
        if *role == Some(increments) && has_point(b'A' + i as u8) {
            *role = Some(length);
        }
    }
    let measures = measures.get();
    CycleTable {
        roles,
        measures,
        start_angle,
    }
}

/// The P, Q and R of a block with an M code are of no known role where no code of the
/// block gives them one: an M code the profile's `list` lacks, or any M code in a block
/// without a G code that reads P, Q or R ([`pqr_code`], `pqr_code` here; a cycle repeated
/// counts): a cycle's R beside M08 and an arc's R beside it stand, a `G90` or `G00` beside
/// `M96 P100 Q8` gives them nothing. A profile lists an M code by its name only, never what
/// its words are, and a FANUC hands an M code to the machine builder's ladder or, by
/// parameters 6080-6089, calls a macro with them as its arguments, so nothing shows which is a
/// length, whatever `checks.pqr` says of the letter elsewhere (Haas M130's Q R, `M199 Q10.`).
/// A role the tables give an M code's own words (`M98 P Q L`, `M96 P Q`: [`cycle_table`])
/// stands. The `--verify` reader reads them so too, as written.
pub fn m_code_roles(list: &CodeList, ms: &[i64], pqr_code: bool, roles: &mut [Option<Role>; 26]) {
    let listed = |m: i64| {
        let (short, long) = (format!("M{m}"), format!("M{m:02}"));
        list.iter().any(|(c, _)| *c == short || *c == long)
    };
    if ms.iter().any(|&m| m >= 0 && (!pqr_code || !listed(m))) {
        for letter in *b"PQR" {
            roles[slot(letter)].get_or_insert(Role::Parameter);
        }
    }
}

/// Whether G code `g` (its system A number) reads P, Q or R by the roles the profile's
/// `checks.pqr` or the cycle tables give them, in its own block: an arc's R (the radius,
/// FANUC 0i-MF "Circular interpolation"), a dwell's P, G10's P and R, a macro call's P, a
/// canned cycle's R, Q and P (the drilling cycles of every family; a lathe's G70-G76, its
/// threading G32 and turning cycles G90/G92/G94 in system A, Haas's G241-G249; an Okuma
/// lathe's thread, LAP and M-tool cycles), LinuxCNC's G5 and G64. Any other code (G00, G90,
/// G54, G43) gives an M code's P, Q and R beside it no role ([`m_code_roles`]).
pub fn pqr_code(family: Family, lathe: bool, g: i64) -> bool {
    let macro_b_lathe = lathe && family == Family::MacroB;
    let okuma_lathe = lathe && family == Family::Okuma;
    matches!(g, 2..=4 | 10 | 65 | 66 | 73 | 74 | 76 | 81..=89)
        || (family == Family::LinuxCnc && matches!(g, 5 | 64))
        || (macro_b_lathe && matches!(g, 32 | 70..=76 | 90 | 92 | 94 | 241..=249))
        || (okuma_lathe && matches!(g, 31..=35 | 71..=89 | 178..=189))
}

/// Whether a statement's text holds a number as a value: digits inside brackets or
/// parentheses, or after `=`, that are not a parameter's number (`#5021`, `R1`, `_X2`).
/// A control family as messages name it.
fn family_name(family: Family) -> &'static str {
    match family {
        Family::Iso => "ISO 6983-1",
        Family::MacroB => "Custom Macro B (Fanuc, Haas)",
        Family::Sinumerik => "SINUMERIK",
        Family::Heidenhain => "HEIDENHAIN",
        Family::LinuxCnc => "LinuxCNC",
        Family::Okuma => "Okuma OSP",
    }
}

/// A G word's code in tenths (`G41.1` 411, `G1` 10), from the token's number after its
/// letter; None for a code written otherwise (`G#1`) or finer than tenths.
fn g_tenths(token: &[u8]) -> Option<i64> {
    std::str::from_utf8(&token[1..])
        .ok()
        .and_then(|t| Dec::parse(t.trim()))
        .map(|v| v.to_f64() * 10.0)
        .filter(|t| (t - t.round()).abs() < 1e-6)
        .map(|t| t.round() as i64)
}

/// Whether a family's controls read `#` parameters (`#1=5.`, `X#1`): ISO 6983-1's 6.4.7,
/// Custom Macro B, LinuxCNC; a SINUMERIK (R parameters), a HEIDENHAIN (Q) and an Okuma OSP (V
/// variables) do not. (Whether a profile of the family does is its dialect's:
/// [`ConvertConfig::target_dialect`].)
fn reads_hash_parameters(family: Family) -> bool {
    matches!(family, Family::Iso | Family::MacroB | Family::LinuxCnc)
}

/// Whether a SINUMERIK statement is `RET` alone (in either case, blanks around it): compared
/// in place, no lower-case copy of each piece made (a statement a block on some programs).
fn sinumerik_ret(statement: &[u8]) -> bool {
    let mut pieces = statement
        .split(|&c| crate::lex::blank(c))
        .filter(|w| !w.is_empty());
    pieces
        .next()
        .is_some_and(|w| w.eq_ignore_ascii_case(b"ret"))
        && pieces.next().is_none()
}

/// Whether `line` holds a character `reads` does not read (a `#`, `[`, `]` or `*`: see
/// [`crate::lex::Dialect::unread_character`]), by a search of the line for each kind the
/// dialect lacks.
fn unread_in_line(line: &[u8], reads: &crate::lex::Dialect) -> bool {
    (!reads.hash && memchr::memchr(b'#', line).is_some())
        || (!reads.brackets && memchr::memchr2(b'[', b']', line).is_some())
        || (!reads.star && memchr::memchr(b'*', line).is_some())
}

/// Whether a statement holds lengths by the roles of its words, with no `=` or brackets to
/// show them: a FANUC or Haas corner (`,C2.`), an Okuma OSP hole pattern (`BHC X100 ...`).
/// The units flow refuses one read where the units are not known, as it does a length word.
fn role_lengths(family: Family, text: &[u8]) -> bool {
    match family {
        Family::MacroB => crate::meaning::corner_length(text).is_some(),
        Family::Okuma => crate::meaning::okuma_pattern(text).is_some(),
        _ => false,
    }
}

/// Whether a statement holds a number that is a value: inside brackets or after an `=`, and
/// where `comparisons` (a SINUMERIK's, whose conditions compare without brackets: `WHILE
/// R1<10`, `IF R1>=2 GOTOB LAB`, Programming Manual Job Planning, "Program loops") after a
/// `<` or `>`: the bound of a loop, compared with a parameter the conversion may scale.
pub(crate) fn holds_values(text: &[u8], comparisons: bool) -> bool {
    let mut depth = 0usize;
    let mut assigned = false;
    let mut quoted = false;
    // the length of a SINUMERIK string, DEF STRING[100] NAME or a PROC's string[32] name, and
    // the dimensions of an array, DEF REAL NAME[10]: counts, no values of the machine's
    let mut size: Option<usize> = None;
    let def = text
        .trim_ascii_start()
        .get(..4)
        .is_some_and(|head| head.eq_ignore_ascii_case(b"DEF "));
    for (i, &c) in text.iter().enumerate() {
        if let Some(open) = size {
            if c == b']' && depth == open {
                size = None;
                depth -= 1;
            }
            continue;
        }
        match c {
            b'"' => quoted = !quoted,
            _ if quoted => {}
            b'[' if (def && !assigned)
                || (i >= 6 && text[i - 6..i].eq_ignore_ascii_case(b"STRING")) =>
            {
                depth += 1;
                size = Some(depth);
            }
            b'[' | b'(' => depth += 1,
            b']' | b')' => depth = depth.saturating_sub(1),
            b'=' => assigned = true,
            b'<' | b'>' if comparisons => assigned = true,
            b'0'..=b'9' | b'.' => {
                let prev = if i == 0 { b' ' } else { text[i - 1] };
                let part_of_name =
                    prev.is_ascii_alphanumeric() || matches!(prev, b'#' | b'_' | b'$' | b'.');
                if !part_of_name && (depth > 0 || assigned) {
                    return true;
                }
            }
            _ => {}
        }
    }
    false
}

/// Where the programs of a file begin, as [`Converter::block`] splits the file
/// (`dialect::ProgramSplit`): on a Custom Macro B control, after M02, M30 or M99, a block that
/// begins with an O number or a folder marker; on a SINUMERIK, an archive's `%_N_NAME_SPF`
/// line after its first, whatever came before it (`dialect::splits`). So this reads the M
/// words, a SINUMERIK's RET, and the opening of each block and nothing else: the parameter
/// analysis of a units conversion ([`crate::lengths`]) reads each program's local variables
/// apart by it, and the converter refuses a file it splits elsewhere.
/// It also says which lines return (M99): a file that holds a subprogram may call it from any
/// of its programs (M98, or an M or T code the machine calls it by), and a subprogram runs at
/// its caller's level of local variables, so none of its programs has local variables of its
/// own.
#[derive(Debug, Clone, Copy)]
pub struct ProgramStarts {
    family: Family,
    program_number: Option<u8>,
    split: ProgramSplit,
    /// The bytes a line must hold to be read ([`ProgramStarts::marked`]), either case: a table
    /// made once, as every line of the file is looked through for them.
    marks: [bool; 256],
}

impl ProgramStarts {
    pub fn new(family: Family, program_number: Option<u8>) -> ProgramStarts {
        let letter = program_number.unwrap_or(b'M').to_ascii_uppercase();
        let ret = if family == Family::Sinumerik {
            b'R'
        } else {
            b'M'
        };
        let mut marks = [false; 256];
        for (c, mark) in (0..=255u8).zip(marks.iter_mut()) {
            let c = c.to_ascii_uppercase();
            *mark = matches!(c, b'M' | b'&' | b'%')
                || c == letter
                || c == ret
                || (c == b'<' && family == Family::MacroB);
        }
        ProgramStarts {
            family,
            program_number,
            split: ProgramSplit::default(),
            marks,
        }
    }

    /// Whether a file of this machine can hold several programs: none, nothing to read.
    pub fn splits(&self) -> bool {
        crate::dialect::splits(self.family, self.program_number)
    }

    /// Whether a line may begin the next program of the file or return from one: one with no
    /// M, no program number letter, no `&` (of a folder marker), no `%` (of a SINUMERIK
    /// archive's next file), on a Custom Macro B control no `<` (of a FANUC `<NAME>`) and,
    /// on a SINUMERIK, no R (of RET) does neither, and is not read.
    pub fn marked(&self, text: &[u8]) -> bool {
        text.iter().any(|&c| self.marks[usize::from(c)])
    }

    /// Whether byte `c` is one [`ProgramStarts::marked`] looks for (for a reader that looks
    /// for these among other bytes in one pass over a line).
    pub fn is_mark(&self, c: u8) -> bool {
        self.marks[usize::from(c)]
    }

    /// One [`ProgramStarts::marked`] line, as the tokenizer read it (`tokens`, `extras`):
    /// whether it begins the next program of the file, and whether it returns from one (M99).
    /// (The caller tokenizes it once for this and its own reading of the line.)
    pub fn read(
        &mut self,
        text: &[u8],
        tokens: &[Token<'_>],
        extras: &crate::tokenizer::Reading<'_>,
    ) -> (bool, bool) {
        if extras.as_ref().is_some_and(|e| e.percent) {
            // a SINUMERIK archive's next file, `%_N_SUB1_SPF`
            let begins = self.split.begins(
                self.family,
                self.program_number,
                &Opening::percent_line(text),
            );
            return (begins, false);
        }
        let opening = Opening {
            word: tokens
                .first()
                .map(|t| (t.offset, t.text[0].to_ascii_uppercase())),
            statement: extras.as_ref().and_then(|e| {
                e.statements
                    .first()
                    .map(|s| (s.offset, s.kind, &text[s.offset..s.end]))
            }),
            percent: None,
        };
        let begins = self
            .split
            .begins(self.family, self.program_number, &opening);
        // M02, M30 end a program, the family's return code returns from one (M99; a
        // SINUMERIK's M17 and RET: [`crate::dialect::return_code`]), as the converter reads them
        let m = |codes: &[i64]| {
            tokens.iter().any(|t| {
                t.text[0].eq_ignore_ascii_case(&b'M')
                    && integer(&t.text[1..]).is_some_and(|n| codes.contains(&n))
            })
        };
        let ret = self.family == Family::Sinumerik
            && extras.as_ref().is_some_and(|e| {
                e.statements.iter().any(|s| {
                    s.kind == StatementKind::Command
                        && text[s.offset..s.end].eq_ignore_ascii_case(b"RET")
                })
            });
        let returns =
            crate::dialect::return_code(self.family).is_some_and(|code| m(&[code])) || ret;
        let (ends, returns) = (m(&[2, 30]) || returns, returns);
        self.split.ended(ends);
        (begins, returns)
    }
}

/// The number of a G code's digits as [`Dec::parse`] reads it (`33.1`, `1E2`), a whole one
/// read by [`integer`] without its text made a `str` first.
/// Whether a block holds a G word of one of these whole numbers (`G65`, `g04`; not `G65.1`).
fn whole_g_code(b: &BlockIn<'_>, codes: &[i64]) -> bool {
    b.words.iter().any(|w| {
        w.token[0].eq_ignore_ascii_case(&b'G')
            && code_number(&w.token[1..])
                .is_some_and(|n| n.is_whole() && codes.contains(&n.trunc()))
    })
}

/// A word's value written as a number that is zero (`0`, `-0.`, `0.000`, `+0`): no parameter,
/// no expression.
fn literal_zero(value: &[u8]) -> bool {
    let digits = value.iter().filter(|c| !c.is_ascii_whitespace());
    let mut zero = false;
    for (i, &c) in digits.enumerate() {
        match c {
            b'0' => zero = true,
            b'.' => {}
            b'+' | b'-' if i == 0 => {}
            _ => return false,
        }
    }
    zero
}

/// A block's first word of this address letter (either case).
fn first_word<'a>(b: &BlockIn<'a>, letter: u8) -> Option<&'a WordSpan<'a>> {
    b.words
        .iter()
        .find(|w| w.token[0].eq_ignore_ascii_case(&letter))
}

fn code_number(digits: &[u8]) -> Option<Dec> {
    match integer(digits) {
        Some(n) => Some(Dec {
            mantissa: i128::from(n),
            scale: 0,
        }),
        None => Dec::parse(std::str::from_utf8(digits).ok()?),
    }
}

/// Python's `int()` of a G code's digits: an optional sign and digits only. (Summed a digit
/// at a time: at most 18 digits fit `i64`; the standard parser, through a `str`, cost more
/// than the rest of a G word's reading, and every G word of a block is read several times.)
fn integer(digits: &[u8]) -> Option<i64> {
    let (negative, body) = match digits.first() {
        Some(b'-') => (true, &digits[1..]),
        Some(b'+') => (false, &digits[1..]),
        _ => (false, digits),
    };
    if body.is_empty() || !body.iter().all(u8::is_ascii_digit) || body.len() > 18 {
        return None;
    }
    let n = body.iter().fold(0i64, |n, &c| n * 10 + i64::from(c - b'0'));
    Some(if negative { -n } else { n })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_word_is_upper_cased_outside_its_comments_and_strings() {
        // review 19, finding 5: the written text, blanks kept
        assert_eq!(upper_outside(b"x [1 + 2]", 3, &[]), b"X [1 + 2]");
        // a comment inside the span (block bytes 7..13) and a string are kept as written
        let comments: [(usize, &[u8]); 1] = [(7, b"(abc)")];
        assert_eq!(
            upper_outside(b"x [1 (abc) + 2]", 3, &comments),
            b"X [1 (abc) + 2]"
        );
        assert_eq!(upper_outside(b"t=\"mill\" x", 0, &[]), b"T=\"mill\" X");
    }

    /// A drilling cycle in force ends at every motion-group code (a lathe's threading and
    /// single cycles too), at G80 and M02/M30, and is kept through a block that names none; a
    /// lathe's thread only at another code of the motion group and M02/M30.
    #[test]
    fn the_cycle_in_force_ends_at_the_motion_group() {
        let fanuc = Family::MacroB;
        let cycle = |g: Option<i64>| Repeat {
            cycle: g,
            thread: None,
        };
        let after = |before: Option<i64>, lathe, gs: &[i64], ms: &[i64]| {
            cycle(before).after(fanuc, lathe, gs, ms).code()
        };
        assert_eq!(after(None, true, &[83], &[]), Some(83));
        assert_eq!(after(Some(83), true, &[], &[]), Some(83));
        for g in [0, 1, 2, 3, 33, 34, 80, 90, 94] {
            assert_eq!(after(Some(83), true, &[g], &[]), None, "lathe G{g}");
        }
        // a lathe's threading G32 and G92 end it and are in force themselves: a block
        // naming no code of the motion group repeats them (review 57a, F4)
        for g in [32, 92] {
            let thread = Repeat {
                cycle: None,
                thread: Some(g),
            };
            let then = |r: Repeat, gs: &[i64], ms: &[i64]| r.after(fanuc, true, gs, ms);
            assert_eq!(after(Some(83), true, &[g], &[]), Some(g), "lathe G{g}");
            assert_eq!(then(thread, &[], &[]), thread, "lathe G{g}");
            assert_eq!(then(thread, &[0], &[]).code(), None, "lathe G{g}, G00");
            assert_eq!(then(thread, &[90], &[]).code(), None, "lathe G{g}, G90");
            assert_eq!(then(thread, &[], &[30]).code(), None, "lathe G{g}, M30");
            // G80, group 10's, leaves it in force, and a drilling cycle's repeats are the
            // cycle's until its G80 (review 58b, F8, F7)
            assert_eq!(then(thread, &[80], &[]), thread, "lathe G{g}, G80");
            let drilling = then(thread, &[83], &[]);
            assert_eq!(drilling.code(), Some(83), "lathe G{g}, G83");
            assert_eq!(then(drilling, &[], &[]).code(), Some(83), "lathe G{g}, G83");
            assert_eq!(then(drilling, &[80], &[]), thread, "lathe G{g}, G83, G80");
            assert_eq!(
                then(drilling, &[1], &[]).code(),
                None,
                "lathe G{g}, G83, G01"
            );
            assert_eq!(after(None, false, &[g], &[]), None, "mill G{g}");
        }
        let state = |cycle, motion| crate::modal::ModalState {
            cycle,
            motion,
            ..crate::modal::ModalState::new(crate::modal::Units::Metric)
        };
        assert_eq!(state(None, Some(92)).code_in_force(true), Some(92));
        assert_eq!(state(Some(83), Some(92)).code_in_force(true), None);
        assert_eq!(state(Some(83), Some(1)).code_in_force(true), None);
        assert_eq!(state(Some(81), Some(92)).code_in_force(false), Some(81));
        for g in [0, 1, 2, 3, 33, 80] {
            assert_eq!(after(Some(81), false, &[g], &[]), None, "mill G{g}");
        }
        // a mill's G90 (absolute), G92 (setting) and G94 (feed per minute) are no motion
        for g in [90, 92, 94, 17] {
            assert_eq!(after(Some(81), false, &[g], &[]), Some(81), "mill G{g}");
        }
        assert!(!motion_group(true, 80) && ends_canned_cycle(true, 80));
        assert_eq!(after(Some(83), true, &[], &[30]), None);
        assert_eq!(after(Some(249), true, &[], &[]), Some(249));
        assert_eq!(after(Some(83), true, &[241], &[]), Some(241));
        // no other family's cycle is followed here
        assert_eq!(
            Repeat::default().after(Family::LinuxCnc, false, &[83], &[]),
            Repeat::default()
        );
        // which cycles' P is a dwell: a lathe's G73/G74/G76 are multiple repetitive cycles
        assert!(dwell_cycle(false, 76) && !dwell_cycle(true, 76) && dwell_cycle(true, 249));
        assert!(!dwell_cycle(false, 249) && dwell_cycle(true, 83) && !dwell_cycle(true, 81));
    }

    /// The one rule of a lathe's U and W (`UwMoves`), kept by the converter and `--verify`'s
    /// reader: carried on X Z in system A's moves and threads (and an OSP's), not in a cycle,
    /// and in G code system B or C a move's word read on its own (review 60, F2).
    #[test]
    fn a_lathes_u_and_w_move_x_and_z_by_one_rule() {
        use crate::meaning::GCodeSystem;
        let after = |lathe, family, system, gs: &[i64]| {
            let mut uw = UwMoves::new(lathe, family, system);
            gs.iter().for_each(|&g| uw.code(g));
            (uw.of_move(), uw.carried(), uw.on_its_own())
        };
        let a = GCodeSystem::A;
        for gs in [&[][..], &[1], &[32], &[34], &[92, 0]] {
            assert_eq!(
                after(true, Family::MacroB, a, gs),
                (true, true, false),
                "A {gs:?}"
            );
        }
        // system A's cycles (and its G33, as the checker reads it): the cycle's U W
        for g in [33, 71, 76, 83, 90, 92, 94] {
            assert_eq!(
                after(true, Family::MacroB, a, &[g]),
                (false, false, false),
                "A G{g}"
            );
        }
        // B and C (their G33 read as A's G32): a move's word, converted and read on its own
        for system in [GCodeSystem::B, GCodeSystem::C] {
            for gs in [&[][..], &[1], &[32], &[90, 1]] {
                assert_eq!(after(true, Family::MacroB, system, gs), (true, false, true));
            }
            assert_eq!(
                after(true, Family::MacroB, system, &[90]),
                (false, false, false)
            );
        }
        // an OSP lathe: its thread cycle G33 is a cycle, G01 a move
        assert_eq!(after(true, Family::Okuma, a, &[1]), (true, true, false));
        assert_eq!(after(true, Family::Okuma, a, &[33]), (false, false, false));
        // a mill, or another family's lathe: no U W of the lathe's
        assert_eq!(after(false, Family::MacroB, a, &[1]), (false, false, false));
        assert_eq!(
            after(true, Family::LinuxCnc, a, &[1]),
            (false, false, false)
        );
        let mut uw = UwMoves::new(true, Family::MacroB, a);
        uw.code(71);
        uw.reset();
        assert!(uw.carried());
    }

    /// A G code's digits read a digit at a time are what the standard parser reads, and
    /// nothing it would not (signs, blanks, points, letters, 19 digits, empty).
    #[test]
    fn a_codes_digits_read_by_hand_are_the_parsers() {
        let reference = |digits: &[u8]| -> Option<i64> {
            let body = match digits.first() {
                Some(b'+' | b'-') => &digits[1..],
                _ => digits,
            };
            if body.is_empty() || !body.iter().all(u8::is_ascii_digit) || body.len() > 18 {
                return None;
            }
            std::str::from_utf8(digits).ok()?.parse().ok()
        };
        let mut cases: Vec<Vec<u8>> = [
            "",
            "0",
            "00",
            "1",
            "01",
            "65",
            "-0",
            "+0",
            "-1",
            "+66",
            "--1",
            "+-1",
            "1.",
            "1.5",
            " 1",
            "1 ",
            "1a",
            "a",
            "-",
            "+",
            "999999999999999999",
            "-999999999999999999",
            "1000000000000000000",
            "0000000000000000001",
            "123456789012345678",
        ]
        .iter()
        .map(|c| c.as_bytes().to_vec())
        .collect();
        cases.extend((0..=255u8).map(|c| vec![b'1', c]));
        cases.extend((0..=255u8).map(|c| vec![c, b'7']));
        for case in &cases {
            assert_eq!(integer(case), reference(case), "{case:?}");
            // (as written: mantissa and scale, not the value Dec's == compares)
            let written = |d: Option<Dec>| d.map(|d| (d.mantissa, d.scale));
            let parsed = std::str::from_utf8(case).ok().and_then(Dec::parse);
            assert_eq!(written(code_number(case)), written(parsed), "{case:?}");
        }
        for case in ["33.1", "1E2", "91.10", "-.5", "+7.", "1e-1", "5.5.5", "1,5"] {
            let written = |d: Option<Dec>| d.map(|d| (d.mantissa, d.scale));
            assert_eq!(
                written(code_number(case.as_bytes())),
                written(Dec::parse(case)),
                "{case}"
            );
        }
    }

    /// One line read by the split as the parameter analysis reads it: tokenized where it is
    /// [`ProgramStarts::marked`].
    fn split_line<'a>(
        starts: &mut ProgramStarts,
        text: &'a [u8],
        dialect: &Dialect,
        tokens: &mut Vec<Token<'a>>,
    ) -> Result<(bool, bool), LexError> {
        if !starts.marked(text) {
            return Ok((false, false));
        }
        tokens.clear();
        let extras = tokenize(text, dialect, tokens)?;
        Ok(starts.read(text, tokens, &extras))
    }

    fn fmt(before: u32, after: u32, zeros: Zeros, decimal: bool) -> WordFormat {
        WordFormat {
            address: b'X',
            before,
            after,
            signed: true,
            zeros,
            decimal,
        }
    }

    /// A Fanuc-style control at IS-B (0.001 mm, 0.0001 in), P and Q counts, converting to inch.
    fn fanuc(lathe: bool) -> ConvertConfig {
        let length = |a: u8, before, after| (a, fmt(before, after, Zeros::Leading, true));
        let counts = [b'P', b'Q', b'G', b'M', b'T', b'N', b'O'].map(|a| {
            let mut f = fmt(5, 0, Zeros::Leading, false);
            f.address = a;
            (a, f)
        });
        let metric: Vec<_> = b"XYZUWRF"
            .iter()
            .map(|&a| length(a, 5, 3))
            .chain(counts.clone())
            .collect();
        let inch: Vec<_> = b"XYZUWRF".iter().map(|&a| length(a, 4, 4)).collect();
        ConvertConfig {
            src_formats: metric.clone(),
            src_formats_inch: Some(inch.clone()),
            out_formats_inch: Some(inch),
            src_increments: Some(b"FGPQL".to_vec()),
            dst_increments: Some(b"FGPQL".to_vec()),
            src_modal: ModalSettings {
                reset: vec![0, 18, 21, 40, 80, 97, 99],
                family: Family::MacroB,
                fanuc_lathe: lathe,
                centre_codes: !lathe,
                dwell: crate::word::dwell_words(Family::MacroB, lathe),
                arc_radius: crate::word::arc_radius(Family::MacroB, lathe),
                ..ConvertConfig::between(Family::MacroB, Family::MacroB).src_modal
            },
            out_formats: metric,
            units: Some(Units::Inch),
            lathe,
            target_dialect: crate::lex::Dialect::permissive(Family::MacroB),
            target_arc_radius: crate::word::arc_radius(Family::MacroB, lathe),
            ..ConvertConfig::between(Family::MacroB, Family::MacroB)
        }
    }

    /// An Okuma OSP lathe's, converting to inch: a number without a point is whole, and an
    /// arc's radius is L (5238-E, P-26), a length of L053 (L044 in inch).
    fn okuma_lathe() -> ConvertConfig {
        let mut c = fanuc(true);
        let l = |before, after| {
            let mut f = fmt(before, after, Zeros::Leading, true);
            (f.address, f.signed) = (b'L', false);
            (b'L', f)
        };
        c.src_formats.push(l(5, 3));
        c.out_formats.push(l(5, 3));
        for inch in [&mut c.src_formats_inch, &mut c.out_formats_inch] {
            inch.as_mut().expect("inch formats").push(l(4, 4));
        }
        (c.src_increments, c.dst_increments) = (None, None);
        (c.family, c.target_family) = (Family::Okuma, Family::Okuma);
        c.src_modal.fanuc_lathe = false;
        c.src_modal.lap = true;
        c.src_modal.dwell = crate::word::dwell_words(Family::Okuma, false);
        c.src_modal.arc_radius = crate::word::arc_radius(Family::Okuma, true);
        c.target_arc_radius = c.src_modal.arc_radius;
        c
    }

    #[test]
    fn an_okuma_lathe_s_arc_radius_l_is_converted_as_a_length() {
        let okuma = Dialect {
            family: Family::Okuma,
            ..Dialect::default()
        };
        let program = [
            "G00 X20. Z5.",
            "G01 Z0 F.2",
            "G03 X26. Z-3. L3.",
            "G01 Z-10.",
            "G02 X30. Z-12. L2.",
            "X34. Z-14. L2.",
            "G33 X18. Z-20. F1.5 L1.5",
        ];
        let inch = run_in(okuma_lathe(), &program, &okuma).expect("converted");
        assert_eq!(inch[2], "G03 X1.0236 Z-0.1181 L0.1181");
        assert_eq!(inch[4], "G02 X1.1811 Z-0.4724 L0.0787");
        // modal G02: the block without its G code is an arc too
        assert_eq!(inch[5], "X1.3386 Z-0.5512 L0.0787");
        // the thread cutting cycle's chamfering distance (5238-E, P-97)
        assert_eq!(inch[6], "G33 X0.7087 Z-0.7874 F0.0591 L0.0591");
        // the automatic chamfer and corner rounding of a G01 block: L their size
        let corners = ["G00 X20. Z5.", "G01 G75 X30. L2. F.2", "G76 Z-10. L1.5"];
        let inch = run_in(okuma_lathe(), &corners, &okuma).expect("converted");
        assert_eq!(inch[1], "G01 G75 X1.1811 L0.0787 F0.0079");
        assert_eq!(inch[2], "G76 Z-0.3937 L0.0591");
        // elsewhere the manual does not say what L is: refused, or left as written
        let unknown = ["G00 X20. Z5.", "G73 X47. Z53. K2.79 L12.4"];
        let (line, e) = run_in(okuma_lathe(), &unknown, &okuma).expect_err("refused");
        assert_eq!(line, 2);
        assert!(
            e.message
                .starts_with("L12.4: outside an arc and a thread cutting cycle"),
            "{}",
            e.message
        );
        let left = ConvertConfig {
            allow_unconverted: true,
            ..okuma_lathe()
        };
        let out = run_in(left, &unknown, &okuma).expect("left as written");
        assert!(out[1].ends_with("K0.1098 L12.4"), "{}", out[1]);
        // no change of units, no question
        let kept = ConvertConfig {
            units: None,
            ..okuma_lathe()
        };
        assert_eq!(run_in(kept, &unknown, &okuma).expect("kept")[1], unknown[1]);
        // a target that reads the radius from another letter: refused at the radius word, in
        // any units (tapegate renames no word), and so from R to an Okuma lathe
        for (source, target) in [
            (okuma_lathe(), b'R'),
            (fanuc(true), crate::word::arc_radius(Family::Okuma, true)),
        ] {
            let to = ConvertConfig {
                units: None,
                target_arc_radius: target,
                ..source
            };
            let arc = ["G01 X20. Z0 F.2", "G03 X26. Z-3. R3. L3."];
            let (line, e) = run_in(to.clone(), &arc, &okuma).expect_err("refused");
            let at = if target == b'R' { 19 } else { 15 };
            assert_eq!((line, e.column, e.clause), (2, at, "7.3"), "{}", e.message);
            // a line is no arc
            assert!(run_in(to, &["G01 X20. Z0 F.2", "G01 Z-3. L3."], &okuma).is_ok());
        }
        // on a Fanuc, L stays a count: M98 P100 L3 calls three times in any units
        let fanuc_calls = run(fanuc(true), &["M98 P100 L3"]).expect("converted");
        assert!(
            fanuc_calls[0].ends_with("M98 P100 L3"),
            "{}",
            fanuc_calls[0]
        );
    }

    #[test]
    fn okuma_lap_thread_and_m_tool_cycles_convert_their_depths_and_keep_counts_and_times() {
        let okuma = Dialect {
            family: Family::Okuma,
            ..Dialect::default()
        };
        let program = [
            "G00 X50. Z2.",
            "G85 NLAP1 D4. F0.3 U0.4 W0.1",
            "G84 D3. F0.2",
            "G88 NTHR1 H1.083 B60 D0.4 U0.05 F1.5",
            "G71 X27.835 Z-25. B60 D0.4 U0.05 H1.083 F1.5 J1 M32",
            "G72 X10. Z-2. B60 D0.4 W0.05 H1.083 F1.5 J1 Q2 M32",
            "G32 X10. Z-1. F1.5 J2",
            "G183 X0 Z-30. D5. E0.5 F100.",
            "G178 X40. Z-30. C0 D0.5 E0.2 U0.1 F200.",
        ];
        let inch = run_in(okuma_lathe(), &program, &okuma).expect("converted");
        // LAP: the depth of cut (5238-E section 8), the finishing allowances as before
        assert_eq!(inch[1], "G85 NLAP1 D0.1575 F0.0118 U0.0157 W0.0039");
        assert_eq!(inch[2], "G84 D0.1181 F0.0079");
        // the thread height and first cut are lengths, the tool's angle degrees
        assert_eq!(inch[3], "G88 NTHR1 H0.0426 B60 D0.0157 U0.002 F0.0591");
        // compound thread cycles: J (threads within F) and Q (starts) counts
        assert_eq!(
            inch[4],
            "G71 X1.0959 Z-0.9843 B60 D0.0157 U0.002 H0.0426 F0.0591 J1 M32"
        );
        assert_eq!(
            inch[5],
            "G72 X0.3937 Z-0.0787 B60 D0.0157 W0.002 H0.0426 F0.0591 J1 Q2 M32"
        );
        assert_eq!(inch[6], "G32 X0.3937 Z-0.0394 F0.0591 J2");
        // M-tool deep-hole drilling: D the peck, E the dwell (seconds) kept
        assert_eq!(inch[7], "G183 X0 Z-1.1811 D0.1969 E0.5 F3.937");
        // key way cutting: E the infeed, a length
        assert_eq!(
            inch[8],
            "G178 X1.5748 Z-1.1811 C0 D0.0197 E0.0079 U0.0039 F7.874"
        );
        // without a change of units every word is kept
        let kept = ConvertConfig {
            units: None,
            ..okuma_lathe()
        };
        let same = run_in(kept, &program, &okuma).expect("kept");
        assert_eq!(same, program.map(String::from).to_vec());
        // the turning tool's G73: D and E not explained by the pages at hand: refused
        let (line, e) = run_in(
            okuma_lathe(),
            &["G73 X47. Z53. K2.79 D4 F0.1 E0.14"],
            &okuma,
        )
        .expect_err("refused");
        assert_eq!((line, e.column, e.clause), (1, 21, "6.4.7"));
        assert!(
            e.message
                .starts_with("D4: the source control's manual, as tapegate has it, does not say"),
            "{}",
            e.message
        );
    }

    #[test]
    fn an_okuma_lathe_s_u_w_steps_are_tracked_on_x_z() {
        let okuma = Dialect {
            family: Family::Okuma,
            ..Dialect::default()
        };
        let mut program = vec!["G00 X10. Z0"];
        program.extend(std::iter::repeat_n("G01 W-1. F0.1", 20));
        let inch = run_in(okuma_lathe(), &program, &okuma).expect("converted");
        // 20 mm = 0.7874 in: the steps add up to the converted position, not 20 x W-0.0394
        let sum: f64 = inch[1..]
            .iter()
            .map(|l| {
                l[5..l
                    .find(' ')
                    .map_or(l.len(), |_| l[5..].find(' ').unwrap() + 5)]
                    .parse::<f64>()
                    .unwrap()
            })
            .sum();
        assert!((sum + 0.7874).abs() < 1e-9, "{sum}");
    }

    #[test]
    fn a_lathe_s_drilling_cycles_count_repeats_and_peck_in_increments() {
        let lathe = |units| ConvertConfig {
            units,
            ..fanuc(true)
        };
        let program = [
            "G21 G98",
            "G83 X0 C0 Z-20. R-3. Q5000 P500 F100. K1",
            "G83 X0 C0 Z-20. R-3. Q5. F100.",
            "G87 Z-10. C0 X20. R-5. Q3000 P300 F80.",
            "G84 X0 C0 Z-15. R-3. P300 F125. K2",
        ];
        let inch = run(lathe(Some(Units::Inch)), &program).expect("converted");
        // Q a count of 0.001 mm written as one of 0.0001 in; K a count of repeats
        assert_eq!(inch[1], "G20 G98".replace("G20 G98", &inch[1]));
        assert!(inch[1].ends_with("Q1969 P500 F3.937 K1"), "{}", inch[1]);
        // with a point, the length it writes
        assert!(inch[2].contains(" Q0.1969 "), "{}", inch[2]);
        assert!(inch[3].contains(" Q1181 "), "{}", inch[3]);
        assert!(inch[4].ends_with("P300 F4.9213 K2"), "{}", inch[4]);
        // no change of units: K is not read in increments (it was written K0.001)
        let kept = run(lathe(None), &program).expect("kept");
        assert_eq!(kept, program.map(String::from).to_vec());
        // inch to metric: a count of 0.0001 in becomes one of 0.001 mm (it was 10x too deep)
        let metric = run(
            lathe(Some(Units::Metric)),
            &["G20 G98", "G83 X0 C0 Z-1. R-0.1 Q1969 F4."],
        )
        .expect("converted");
        assert!(metric[1].contains(" Q5001 "), "{}", metric[1]);
        // the one-block G71's depth of cut D, written as a count (FS15 format): 2.000 mm
        let fs15 = run(
            lathe(Some(Units::Inch)),
            &["G21", "G71 P10 Q20 U0.4 W0.1 D2000 F0.25"],
        )
        .expect("converted");
        assert_eq!(fs15[1], "G71 P10 Q20 U0.0157 W0.0039 D0.0787 F0.0098");
        // a block under the cycle in force repeats it: its Q is the cycle's peck as well (it
        // was the profile's Q, no length on a lathe, and kept as written)
        let repeat = run(
            lathe(Some(Units::Metric)),
            &[
                "G20 G98",
                "G83 X0 C0 Z-1. R-0.1 Q0.1 F4.",
                "C90. Z-1.2 Q0.2",
                "G80",
            ],
        )
        .expect("converted");
        assert_eq!(repeat[2], "C90. Z-30.48 Q5.08");
        // after G80 (or G00-G03) a block is no repetition: its Q is the profile's again
        let after = run(
            lathe(Some(Units::Metric)),
            &[
                "G20 G98",
                "G83 X0 C0 Z-1. R-0.1 Q0.1 F4.",
                "G80",
                "M98 P100 Q200",
            ],
        )
        .expect("converted");
        assert_eq!(after[3], "M98 P100 Q200");
    }

    #[test]
    fn polar_interpolation_cylinder_radius_chamfer_and_orientation() {
        let lathe = |units| ConvertConfig {
            units,
            ..fanuc(true)
        };
        let polar = [
            "G21 G98",
            "G12.1",
            "G42 G1 X40. F200.",
            "C10.",
            "G3 X20. C20. R10.",
            "G13.1",
            "G0 C90.",
        ];
        let inch = run(lathe(Some(Units::Inch)), &polar).expect("converted");
        // between G12.1 and G13.1 C is the hypothetical axis, a length
        assert_eq!(inch[3], "C0.3937");
        assert_eq!(inch[4], "G3 X0.7874 C0.7874 R0.3937");
        // after G13.1 C is the rotary axis again, degrees
        assert_eq!(inch[6], "G0 C90.");
        let g112 = run(
            lathe(Some(Units::Inch)),
            &["G21", "G112", "C10.", "G113", "C10."],
        )
        .expect("converted");
        assert_eq!((g112[2].as_str(), g112[4].as_str()), ("C0.3937", "C10."));
        // the cylinder's radius by the C axis's incremental address H (system A)
        let cylinder = run(
            lathe(Some(Units::Inch)),
            &["G21", "G07.1 H57299", "G07.1 C25."],
        )
        .expect("converted");
        assert_eq!(cylinder[1], "G07.1 H2.2559");
        assert_eq!(cylinder[2], "G07.1 C0.9843");
        // a C beside X or Z in G01 on a lathe that has shown no C axis: a chamfer or a move
        let chamfer = [
            "G21 G99",
            "G0 X20. Z2.",
            "G1 Z0 F0.2",
            "X30. C1.",
            "Z-20. R2.",
        ];
        let (line, e) = run(lathe(Some(Units::Inch)), &chamfer).expect_err("refused");
        assert_eq!((line, e.column), (4, 6));
        assert!(e
            .message
            .starts_with("C1.: beside one of X or Z in a linear move"));
        let with_axis = ["G21 G98", "G0 X20. Z2. C0", "G1 X30. C1. F100."];
        let moved = run(lathe(Some(Units::Inch)), &with_axis).expect("a C axis");
        assert_eq!(moved[2], "G1 X1.1811 C1. F3.937");
        // Haas M19 R: no page at hand says it is the angle: refused, not scaled to R2286.
        let (line, e) = run(fanuc(false), &["G21", "M19 R90."]).expect_err("refused");
        assert_eq!((line, e.column), (2, 5));
        assert!(e.message.starts_with("R90.: the source control's manual"));
    }

    #[test]
    fn a_subprogram_s_speed_before_its_own_spindle_mode_is_refused() {
        let lathe = ConvertConfig {
            units: Some(Units::Metric),
            ..fanuc(true)
        };
        let program = [
            "O1",
            "G20 G99",
            "G96 S500 M03",
            "M98 P2",
            "M30",
            "O2",
            "G20",
            "G01 X1.2 Z-1.5 S650 F0.01",
            "M99",
        ];
        let (line, e) = run(lathe.clone(), &program).expect_err("refused");
        assert_eq!((line, e.column, e.clause), (8, 16, "modal state"));
        assert!(e
            .message
            .contains("before the subprogram selects G96 or G97"));
        // the subprogram's own G96: its S is a surface speed, converted
        let mut own = program;
        own[7] = "G96 G01 X1.2 Z-1.5 S650. F0.01";
        let out = run(lathe, &own).expect("converted");
        assert!(out[7].contains(" S198.12 "), "{}", out[7]);
    }

    /// The converted lines, or the first error with its line.
    fn run(c: ConvertConfig, lines: &[&str]) -> Result<Vec<String>, (usize, ConvertError)> {
        let dialect = Dialect {
            family: Family::MacroB,
            ..Dialect::default()
        };
        run_in(c, lines, &dialect)
    }

    /// An Okuma OSP lathe selects no units by a G code (units_codes = "none": its G20 HP=n is a
    /// home position return, the unit system a parameter): converting to inch writes no units
    /// code and says so, keeps G20 HP=4 as written (HP a count), and a source's units code
    /// has nothing to become on it.
    #[test]
    fn an_okuma_lathe_s_units_are_its_parameter_and_its_g20_a_home_return() {
        let okuma = Dialect {
            family: Family::Okuma,
            ..Dialect::default()
        };
        let mut c = okuma_lathe();
        (c.src_modal.inch, c.src_modal.metric) = (-1, -1);
        (c.inch_code, c.metric_code) = (String::new(), String::new());
        let program = [
            "G00 X100. Z100.",
            "G20 HP=4 (HOME POSITION RETURN 4)",
            "G00 X50. Z2.",
        ];
        let mut converter = Converter::new(c.clone());
        let mut tokens = Vec::new();
        let mut out = Vec::new();
        for (i, line) in program.iter().enumerate() {
            let new = converter
                .convert_line(line.as_bytes(), i + 1, &okuma, &mut tokens)
                .unwrap_or_else(|_| panic!("line {} refused", i + 1));
            out.push(new.map_or(line.to_string(), |n| text(&n)));
        }
        assert_eq!(
            out,
            [
                "G00 X3.937 Z3.937",
                "G20 HP=4 (HOME POSITION RETURN 4)",
                "G00 X1.9685 Z0.0787"
            ]
        );
        assert_eq!(
            converter.take_notes(),
            [
                "no units code written: the target control selects its units by a machine \
              parameter, not by a G code; every length from line 1 on is converted to inch: \
              set the machine to inch before running it; the source was read in metric, the \
              source profile's units: its control selects them by a machine parameter the \
              program does not show"
            ]
        );
        // HP=4. is no whole number: nothing shows it a count
        let pointed = ["G20 HP=4."];
        assert!(run_in(c.clone(), &pointed, &okuma).is_err());
        // a Fanuc lathe's G21 has no code to become on the Okuma lathe: refused at the word
        let from_fanuc = ConvertConfig {
            inch_code: String::new(),
            metric_code: String::new(),
            ..fanuc(true)
        };
        let (line, e) = run(from_fanuc, &["G40 G21", "G00 X1."]).expect_err("refused");
        assert_eq!((line, e.column, e.clause), (1, 5, "units"));
        assert!(
            e.message
                .starts_with("G21: the target control selects its units by a machine parameter"),
            "{}",
            e.message
        );
    }

    fn run_in(
        c: ConvertConfig,
        lines: &[&str],
        dialect: &Dialect,
    ) -> Result<Vec<String>, (usize, ConvertError)> {
        let mut converter = Converter::new(c);
        let mut tokens = Vec::new();
        let mut out = Vec::new();
        for (i, line) in lines.iter().enumerate() {
            match converter.convert_line(line.as_bytes(), i + 1, dialect, &mut tokens) {
                Ok(new) => out.push(new.map_or(line.to_string(), |n| text(&n))),
                Err(LineError::Convert(e)) => return Err((e.line.unwrap_or(i + 1), e)),
                Err(LineError::Read(e)) => panic!("{e:?}"),
            }
        }
        Ok(out)
    }

    /// What `--allow-unconverted` leaves as written where the units change is counted where
    /// it is left, with the first one's line and column (the proof's "partly verified"), not
    /// from the notes' wording; a word kept where the units do not change is the same number
    /// on both sides and is not counted.
    #[test]
    fn words_left_as_written_are_counted_where_the_units_change() {
        let c = ConvertConfig {
            allow_unconverted: true,
            ..fanuc(false)
        };
        let program = [
            "G21",
            "G65 P9810 X10. W2.",
            "G00 X25.4",
            "G20",
            "G65 P9810 X1.",
            "M30",
        ];
        let mut converter = Converter::new(c);
        let mut tokens = Vec::new();
        for (i, line) in program.iter().enumerate() {
            let dialect = Dialect {
                family: Family::MacroB,
                ..Dialect::default()
            };
            assert!(converter
                .convert_line(line.as_bytes(), i + 1, &dialect, &mut tokens)
                .is_ok());
        }
        // X10. and W2. of the metric call; the inch call's X1. is not converted at all
        let left = converter.left_as_written;
        assert_eq!((left.count, left.first), (2, Some((2, 11))));
        assert_eq!(converter.never_read, Left::default());
        assert!(converter
            .take_notes()
            .iter()
            .any(|n| n.starts_with("the arguments of macro calls (G65) left as written")));
        // nothing left: nothing counted
        let mut converter = Converter::new(fanuc(false));
        for (i, line) in ["G21", "G00 X25.4", "M30"].iter().enumerate() {
            let dialect = Dialect {
                family: Family::MacroB,
                ..Dialect::default()
            };
            assert!(converter
                .convert_line(line.as_bytes(), i + 1, &dialect, &mut tokens)
                .is_ok());
        }
        assert_eq!(converter.left_as_written, Left::default());
    }

    /// [`Converter::text`] compares the words with the line only where a word is replaced by
    /// nothing: on 100,000 drawn lines (words of letters and digits, one or more blanks or none
    /// between them, blanks before and after, plain or not, each word replaced by nothing, by
    /// another text or not at all) it writes what the reference writes, which compares on
    /// every line (the join where the line is its words one blank apart, else the copy).
    #[test]
    fn a_line_is_written_as_the_reference_writes_it_on_drawn_lines() {
        fn reference(b: &BlockIn<'_>, replacements: &[Option<Vec<u8>>]) -> Vec<u8> {
            let mut pos = 0;
            let joined = b.plain
                && b.words.iter().enumerate().all(|(i, w)| {
                    let blank = usize::from(i > 0);
                    let end = pos + blank + w.token.len();
                    let same = end <= b.text.len()
                        && (blank == 0 || b.text[pos] == b' ')
                        && &b.text[pos + blank..end] == w.token;
                    pos = end;
                    same
                })
                && pos == b.text.len();
            let mut out = Vec::new();
            if joined {
                let words = replacements.iter().zip(b.words);
                let kept = words.map(|(r, w)| r.as_deref().unwrap_or(w.token));
                let kept: Vec<&[u8]> = kept.filter(|w| !w.is_empty()).collect();
                return kept.join(&b' ');
            }
            let mut pos = 0;
            for (r, w) in replacements.iter().zip(b.words) {
                if let Some(new) = r {
                    out.extend_from_slice(&b.text[pos..w.start]);
                    out.extend_from_slice(new);
                    pos = w.end;
                    if new.is_empty() {
                        pos += b.text[pos..].iter().take_while(|&&c| c == b' ').count();
                    }
                }
            }
            out.extend_from_slice(&b.text[pos..]);
            out
        }
        let mut converter = Converter::new(fanuc(false));
        let mut next = crate::drawn::xorshift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..100_000 {
            let count = 1 + (next() % 6) as usize;
            let mut text = Vec::new();
            let mut places = Vec::new();
            text.extend(std::iter::repeat_n(
                b' ',
                usize::from(next().is_multiple_of(8)),
            ));
            for i in 0..count {
                if i > 0 {
                    // one blank mostly, none or three now and then
                    let blanks = match next() % 10 {
                        0 => 3,
                        1 => 0,
                        _ => 1,
                    };
                    text.extend(std::iter::repeat_n(b' ', blanks));
                }
                let start = text.len();
                text.push(b"XYZGNF"[(next() % 6) as usize]);
                let digits = 1 + next() % 5;
                for _ in 0..digits {
                    text.push(b'0' + (next() % 10) as u8);
                }
                places.push((start, text.len()));
            }
            text.extend(std::iter::repeat_n(
                b' ',
                usize::from(next().is_multiple_of(8)),
            ));
            let words: Vec<WordSpan<'_>> = places
                .iter()
                .map(|&(start, end)| WordSpan {
                    token: &text[start..end],
                    start,
                    end,
                    plain: None,
                    digits: Default::default(),
                })
                .collect();
            let replacements: Vec<Option<Vec<u8>>> = (0..count)
                .map(|_| match next() % 4 {
                    0 => Some(Vec::new()),
                    1 => Some(b"X1.5".to_vec()),
                    _ => None,
                })
                .collect();
            let b = BlockIn {
                line: 1,
                text: &text,
                words: &words,
                plain: !next().is_multiple_of(4),
                percent: false,
                skip: b"",
                skip_within: None,
                comments: &[],
                statements: &[],
            };
            let expected = reference(&b, &replacements);
            let mut given = replacements.clone();
            let written = converter.text(&b, &mut given, None);
            assert_eq!(
                written,
                expected,
                "{:?} {:?}",
                String::from_utf8_lossy(&text),
                replacements
            );
        }
    }

    /// [`Converter::close_blanks`] passes over a word whose span is as long as its token:
    /// such a span never both holds a blank and spells the token, which is what the full look
    /// asks first. Drawn spans and tokens of letters, digits, signs, points, blanks and tabs,
    /// the token the span without its blanks (in either case), or another text of its length.
    #[test]
    fn a_span_as_long_as_its_token_has_no_blank_to_close() {
        let mut next = crate::drawn::xorshift(0x2545_F491_4F6C_DD1D);
        let bytes = b"XxYz019.-+#[] \t";
        let (mut spelled, mut blanks) = (0, 0);
        for _ in 0..200_000 {
            let len = 1 + (next() % 8) as usize;
            let span: Vec<u8> = (0..len)
                .map(|_| bytes[(next() % bytes.len() as u64) as usize])
                .collect();
            let token: Vec<u8> = match next() % 3 {
                0 => span
                    .iter()
                    .copied()
                    .filter(|c| !matches!(c, b' ' | b'\t'))
                    .collect(),
                1 => span.to_ascii_uppercase(),
                _ => (0..len)
                    .map(|_| bytes[(next() % bytes.len() as u64) as usize])
                    .collect(),
            };
            let blank = span.iter().any(|c| matches!(c, b' ' | b'\t'));
            let spells_it = spells(&span, &token);
            spelled += usize::from(spells_it);
            blanks += usize::from(spells_it && blank);
            if span.len() == token.len() {
                assert!(!(blank && spells_it), "{span:?} {token:?}");
            }
        }
        // (the draw reaches both: spans that spell their token, with blanks among them)
        assert!(spelled > 10_000 && blanks > 10_000, "{spelled} {blanks}");
    }

    /// [`Converter::units_flag`] looks at a line's words only where the line holds the
    /// marker (`#`, `$`): on 300,000 drawn lines under every family's dialect, every word's
    /// token and every statement's text that holds a marker comes from a line that holds it
    /// (the tokens are the line's bytes, without their blanks at most).
    #[test]
    fn a_word_or_statement_holds_a_marker_only_where_its_line_does() {
        const BYTES: &[u8] = b"XGNRPo#$=+-.019 \t[]()<>*;:_AMLS";
        const PIECES: [&str; 16] = [
            "X1.5 ",
            "#1=2 ",
            "X#1 ",
            "#<a> ",
            "$P_GG[13] ",
            "G1 ",
            "R1=#2 ",
            " ",
            "N10 ",
            "X[#1+2] ",
            "$AA_IW[X] ",
            "(c#) ",
            ";c$",
            "IF #1 ",
            "X=$A ",
            "TURN=0 ",
        ];
        let mut next = crate::drawn::xorshift(0x9E37_79B9_7F4A_7C15);
        let dialects: Vec<Dialect> = Family::ALL.into_iter().map(Dialect::permissive).collect();
        let mut marked = 0;
        for _ in 0..300_000 {
            // (half of them of a program's pieces, which read more often than bytes do)
            let line = crate::drawn::line(&mut next, BYTES, &PIECES, 3);
            let dialect = &dialects[(next() % dialects.len() as u64) as usize];
            let mut tokens = Vec::new();
            let Ok(extras) = tokenize(&line, dialect, &mut tokens) else {
                continue;
            };
            let statements = extras
                .as_ref()
                .map(|e| e.statement_texts(&line))
                .unwrap_or_default();
            let pieces = tokens
                .iter()
                .map(|t| &*t.text)
                .chain(statements.iter().map(|s| s.2));
            for piece in pieces {
                for marker in [b'#', b'$'] {
                    if piece.contains(&marker) {
                        marked += 1;
                        assert!(
                            line.contains(&marker),
                            "{:?} {dialect:?}",
                            String::from_utf8_lossy(&line)
                        );
                    }
                }
            }
        }
        assert!(marked > 10_000, "{marked}");
    }

    /// [`sinumerik_ret`] finds the `RET` statements the lower-case copy of each piece found:
    /// 200,000 drawn statements of `R`, `E`, `T`, `r`, `e`, `t`, blanks, tabs and other bytes
    /// (and whole `RET`s among them), against that reading.
    #[test]
    fn a_sinumerik_ret_is_found_as_the_lower_case_copies_found_it() {
        fn reference(statement: &[u8]) -> bool {
            statement
                .split(|&c| crate::lex::blank(c))
                .filter(|w| !w.is_empty())
                .map(<[u8]>::to_ascii_lowercase)
                .eq([b"ret".to_vec()])
        }
        const BYTES: &[u8] = b"RETret \t=1X;";
        const PIECES: [&str; 5] = ["RET", " ret ", "Ret\t", "RETX", " "];
        let mut next = crate::drawn::xorshift(0x0DDB_1A5E_5BAD_5EED);
        let mut found = 0;
        for _ in 0..200_000 {
            let len = (next() % 9) as usize;
            let statement: Vec<u8> = if next().is_multiple_of(2) {
                (0..len)
                    .map(|_| BYTES[(next() % BYTES.len() as u64) as usize])
                    .collect()
            } else {
                (0..len / 3 + 1)
                    .flat_map(|_| PIECES[(next() % PIECES.len() as u64) as usize].bytes())
                    .collect()
            };
            let ret = reference(&statement);
            assert_eq!(
                sinumerik_ret(&statement),
                ret,
                "{:?}",
                String::from_utf8_lossy(&statement)
            );
            found += usize::from(ret);
        }
        assert!(found > 10_000, "{found}");
    }

    /// [`Converter::record`]'s lookup of an address's largest rounding by its place
    /// ([`Converter::worst_at`]) keeps the list the walk of it kept: 200,000 drawn roundings
    /// (any byte as the address, errors and denominators of up to 90 bits, 0-30 decimals)
    /// against the list by the old walk, the same in order, entries and values.
    #[test]
    fn the_largest_rounding_per_address_is_kept_as_the_walk_of_the_list_kept_it() {
        fn reference(worst: &mut Vec<(u8, i128, i128)>, letter: u8, e: i128, d: i128, after: u32) {
            let (mut e, mut d) = (e, d);
            let small = u64::try_from(d)
                .ok()
                .zip(SMALL_POW10.get(after as usize))
                .and_then(|(d, &p)| d.checked_mul(p))
                .map(i128::from);
            match small.or_else(|| pow10(after).ok().and_then(|p| d.checked_mul(p))) {
                Some(whole) => {
                    if let Some(&(_, we, wd)) = worst.iter().find(|w| w.0 == letter) {
                        if no_larger(e, whole, we, wd) == Some(true) {
                            return;
                        }
                    }
                    let g = gcd(e, whole);
                    (e, d) = (e / g, whole / g);
                }
                None => {
                    let mut after = after;
                    while after > 0 {
                        match d.checked_mul(10) {
                            Some(next) => {
                                d = next;
                                after -= 1;
                            }
                            None => break,
                        }
                        let g = gcd(e, d);
                        (e, d) = (e / g, d / g);
                    }
                }
            }
            let bigger = |(we, wd): (i128, i128)| match (e.checked_mul(wd), we.checked_mul(d)) {
                (Some(a), Some(b)) => a > b,
                _ => (e as f64 / d as f64) > (we as f64 / wd as f64),
            };
            match worst.iter_mut().find(|w| w.0 == letter) {
                Some(entry) => {
                    if bigger((entry.1, entry.2)) {
                        *entry = (letter, e, d);
                    }
                }
                None => worst.push((letter, e, d)),
            }
        }
        let mut next = crate::drawn::xorshift(0x1234_5678_9ABC_DEF1);
        for round in 0..20 {
            let mut converter = Converter::new(fanuc(false));
            let mut kept = Vec::new();
            // (a few addresses in most rounds, as a program has; any byte in some)
            let addresses = if round % 4 == 0 {
                256
            } else {
                1 + round as u64
            };
            for _ in 0..10_000 {
                let letter = (next() % addresses) as u8 ^ if round % 4 == 0 { 0 } else { b'A' };
                let bits = 1 + next() % 90;
                let d =
                    (1 + i128::from(next()) % (1i128 << bits.min(62))) << bits.saturating_sub(62);
                let e = i128::from(next()) % d;
                let after = (next() % 31) as u32;
                converter.record(letter, e, d, after);
                reference(&mut kept, letter, e, d, after);
            }
            assert_eq!(converter.worst, kept, "round {round}");
        }
    }

    /// The target dialect's look at a block's words for a character it does not read
    /// ([`Converter::statements`]) is made only where the line holds one
    /// ([`unread_in_line`]): on 300,000 drawn lines under every family's dialect, for targets
    /// lacking each of the seven choices of `#`, `[ ]`, `*`, no word of a line the search
    /// passes over holds such a character, and the first word found is the one the look at
    /// every word finds.
    #[test]
    fn a_word_holds_a_character_the_target_does_not_read_only_where_its_line_does() {
        const BYTES: &[u8] = b"XGNRPo#$=+-.019 \t[]()<>*/;:_AMLS";
        const PIECES: [&str; 14] = [
            "X1.5 ",
            "#1=2 ",
            "X#1 ",
            "#<a> ",
            "G1 ",
            "R1=#2 ",
            " ",
            "N10 ",
            "X[#1+2] ",
            "X[2*3] ",
            "(c#*) ",
            ";c[",
            "IF [#1 GT 2] ",
            "Y2*3 ",
        ];
        let mut next = crate::drawn::xorshift(0x2545_F491_4F6C_DD1D);
        let dialects: Vec<Dialect> = Family::ALL.into_iter().map(Dialect::permissive).collect();
        let (mut found, mut passed) = (0, 0);
        for _ in 0..300_000 {
            let line = crate::drawn::line(&mut next, BYTES, &PIECES, 3);
            let dialect = &dialects[(next() % dialects.len() as u64) as usize];
            let mut tokens = Vec::new();
            if tokenize(&line, dialect, &mut tokens).is_err() {
                continue;
            }
            let lacks = 1 + next() % 7; // which of the three the target does not read
            let mut reads = dialects[(next() % dialects.len() as u64) as usize];
            reads.hash = lacks & 1 == 0;
            reads.brackets = lacks & 2 == 0;
            reads.star = lacks & 4 == 0;
            let every = tokens
                .iter()
                .find_map(|t| reads.unread_character(&t.text).map(|at| (t.offset, at)));
            let look = unread_in_line(&line, &reads);
            let searched = tokens
                .iter()
                .filter(|_| look)
                .find_map(|t| reads.unread_character(&t.text).map(|at| (t.offset, at)));
            assert_eq!(
                searched,
                every,
                "{:?} {reads:?}",
                String::from_utf8_lossy(&line)
            );
            if every.is_some() {
                found += 1;
            } else if !look {
                passed += 1;
            }
        }
        assert!(found > 10_000 && passed > 10_000, "{found} {passed}");
    }

    /// [`units_flag_read`] of a LinuxCNC word, which compares the names in either case in
    /// place, finds what the upper-case copy it replaces found: 300,000 drawn pieces of `#`,
    /// `<`, `>`, blanks, tabs and the flags' letters in either case (and whole flag names among
    /// them), against that reading.
    #[test]
    fn the_linuxcnc_units_flag_is_found_as_the_upper_case_copy_found_it() {
        fn reference(piece: &[u8]) -> Option<(usize, String)> {
            memchr::memchr(b'#', piece)?;
            let upper = piece.to_ascii_uppercase();
            for (at, _) in upper.iter().enumerate().filter(|&(_, &c)| c == b'#') {
                let rest = &upper[at + 1..];
                let Some(open) = rest.iter().position(|&c| !crate::lex::blank(c)) else {
                    continue;
                };
                if rest[open] != b'<' {
                    continue;
                }
                let Some(close) = rest[open..].iter().position(|&c| c == b'>') else {
                    continue;
                };
                let name: Vec<u8> = rest[open + 1..open + close]
                    .iter()
                    .copied()
                    .filter(|&c| !crate::lex::blank(c))
                    .collect();
                if name == b"_METRIC" || name == b"_IMPERIAL" {
                    return Some((at, text(&piece[at..at + 1 + open + close + 1])));
                }
            }
            None
        }
        const PIECES: [&str; 14] = [
            "#",
            "<",
            ">",
            " ",
            "\t",
            "_metric",
            "_IMPERIAL",
            "_Metri",
            "c",
            "l",
            "x",
            "1",
            "#<_metric>",
            "#< _imp erial >",
        ];
        let mut next = crate::drawn::xorshift(0x9E37_79B9_7F4A_7C15);
        let mut found = 0;
        for _ in 0..300_000 {
            let count = 1 + (next() % 10) as usize;
            let piece: Vec<u8> = (0..count)
                .flat_map(|_| PIECES[(next() % PIECES.len() as u64) as usize].bytes())
                .collect();
            let expected = reference(&piece);
            found += usize::from(expected.is_some());
            assert_eq!(
                units_flag_read(&piece, Family::LinuxCnc),
                expected,
                "{:?}",
                String::from_utf8_lossy(&piece)
            );
        }
        assert!(found > 10_000, "{found}");
    }

    fn spans(words: &[&'static str]) -> Vec<WordSpan<'static>> {
        words
            .iter()
            .map(|w| WordSpan {
                token: w.as_bytes(),
                start: 0,
                end: 0,
                plain: None,
                digits: Default::default(),
            })
            .collect()
    }

    /// Review 13, findings 1 and 3: an M code's own words keep the M code's roles whatever G
    /// codes share the block; only a code that reads P, Q or R gives them `checks.pqr`'s.
    #[test]
    fn an_m_codes_words_take_no_role_from_a_g_code_that_reads_none() {
        let list: CodeList = vec![
            ("M130".to_string(), String::new()),
            ("M96".to_string(), String::new()),
            ("M08".to_string(), String::new()),
        ]
        .into();
        let roles = |gs: &[i64], ms: &[i64], words: &[&'static str]| {
            let mut roles = cycle_roles(Family::MacroB, false, gs, ms, &spans(words));
            let pqr = gs.iter().any(|&g| pqr_code(Family::MacroB, false, g));
            m_code_roles(&list, ms, pqr, &mut roles);
            roles
        };
        // G90 and G00 read no P, Q or R: M130's words stay of no known role
        for gs in [&[90][..], &[0], &[]] {
            let m130 = roles(gs, &[130], &["M130", "P5.", "Q10.", "R2."]);
            assert_eq!(m130[slot(b'Q')], Some(Role::Parameter), "{gs:?}");
            assert_eq!(m130[slot(b'R')], Some(Role::Parameter), "{gs:?}");
        }
        // Haas M96 P (a block) and Q (an input), FANUC M98 Q (a sequence number): numbers
        for gs in [&[90][..], &[0], &[]] {
            let m96 = roles(gs, &[96], &["M96", "P100", "Q8"]);
            assert_eq!(m96[slot(b'P')], Some(Role::Other));
            assert_eq!(m96[slot(b'Q')], Some(Role::Other));
            let m98 = roles(gs, &[98], &["M98", "Q101"]);
            assert_eq!(m98[slot(b'Q')], Some(Role::Other));
            assert_eq!(m98[slot(b'P')], Some(Role::Other));
        }
        // a drilling cycle's R and an arc's R beside M08 are left to checks.pqr (a length)
        assert_eq!(
            roles(&[81], &[8], &["G81", "R0.1", "M08"])[slot(b'R')],
            None
        );
        assert_eq!(roles(&[2], &[8], &["G02", "R1.", "M08"])[slot(b'R')], None);
        // a mill's G90 is no turning cycle; a lathe's is (its R the taper)
        assert!(!pqr_code(Family::MacroB, false, 90));
        assert!(pqr_code(Family::MacroB, true, 90));
        assert!(pqr_code(Family::Okuma, true, 32) && !pqr_code(Family::MacroB, false, 32));
    }

    #[test]
    fn the_lathe_cycle_table_gives_lengths_in_increments() {
        let roles = |gs: &[i64], words: &[&'static str]| {
            cycle_roles(Family::MacroB, true, gs, &[], &spans(words))
        };
        let second = roles(&[76], &["G76", "X20.", "Z-30.", "R0", "P1200", "Q350"]);
        assert_eq!(second[slot(b'P')], Some(Role::Increments));
        assert_eq!(second[slot(b'Q')], Some(Role::Increments));
        assert_eq!(second[slot(b'R')], Some(Role::Length));
        let first = roles(&[76], &["G76", "P020060", "Q100", "R0.05"]);
        assert_eq!(first[slot(b'P')], Some(Role::Other));
        assert_eq!(first[slot(b'Q')], Some(Role::Increments));
        let peck = roles(&[74], &["G74", "X0", "Z-50.", "P0", "Q5000"]);
        assert_eq!(peck[slot(b'Q')], Some(Role::Increments));
        // written with a point, the peck is the length it writes
        let pointed = roles(&[74], &["G74", "Z-10.", "Q2.5", "F0.1"]);
        assert_eq!(pointed[slot(b'Q')], Some(Role::Length));
        assert_eq!(peck[slot(b'R')], Some(Role::Length));
        // a mill's G76 Q is a shift written as a length; ISO 6983-1 has no cycle table
        let mill = cycle_roles(Family::MacroB, false, &[76], &[], &spans(&["G76", "Q1."]));
        assert_eq!(mill[slot(b'Q')], Some(Role::Length));
        // a lathe's drilling cycles: Q a count of increments or, with a point, a length (K:
        // the_k_of_a_drilling_cycle_is_the_fanuc_s_count_the_haas_s_depth_or_unknown)
        let lathe = roles(&[83], &["G83", "Z-20.", "Q5000", "K1"]);
        assert_eq!(lathe[slot(b'Q')], Some(Role::Increments));
        assert_eq!(
            roles(&[83], &["G83", "Q2.5"])[slot(b'Q')],
            Some(Role::Length)
        );
        let iso = cycle_roles(Family::Iso, true, &[76], &[], &spans(&["G76", "Q100"]));
        assert_eq!(iso[slot(b'Q')], None);
    }

    #[test]
    fn linuxcnc_cycles_give_their_words_the_roles_of_its_reference() {
        let roles = |g: i64| cycle_roles(Family::LinuxCnc, false, &[g], &[], &spans(&[]));
        let role = |g: i64, letter: u8| roles(g)[slot(letter)];
        // G64 P Q tolerances, G5 I J P Q offsets: lengths
        for (g, letters) in [(64, b"PQ".as_slice()), (5, b"IJPQ")] {
            for &l in letters {
                assert_eq!(role(g, l), Some(Role::Length), "G{g} {}", l as char);
            }
        }
        // G76: pitch, peak offset, first cut, depth, taper lengths; degression, angle, spring
        // passes, taper ends not
        for &l in b"PIJKE" {
            assert_eq!(role(76, l), Some(Role::Length), "G76 {}", l as char);
        }
        for &l in b"RQHL" {
            assert_eq!(role(76, l), Some(Role::Other), "G76 {}", l as char);
        }
    }

    #[test]
    fn angles_directions_and_selectors_keep_their_numbers() {
        let mill = || fanuc(false);
        let out = run(
            mill(),
            &[
                "G21",
                "G68 X25.4 Y0 R45.",
                "G69",
                "G68 X0 Y0 Z0 I0 J1. K0 R30.",
                "G68.2 X10. Y0 Z0 I0. J45. K0.",
                "G05.1 Q1",
                "G05 P10000",
                "G08 P1",
                "G07.1 C57.3",
            ],
        )
        .unwrap();
        assert_eq!(
            out,
            [
                "G20",
                "G68 X1. Y0 R45.",
                "G69",
                "G68 X0 Y0 Z0 I0 J1. K0 R30.",
                "G68.2 X0.3937 Y0 Z0 I0. J45. K0.",
                "G05.1 Q1",
                "G05 P10000",
                "G08 P1",
                "G07.1 C2.2559",
            ]
        );
        // a lathe's G68 is the double turret's mirror image: its R is the profile's length
        let lathe = run(fanuc(true), &["G21", "G68 R25.4"]).unwrap();
        assert_eq!(lathe[1], "G68 R1.");
    }

    #[test]
    fn polar_coordinates_scale_the_radius_and_keep_the_angle() {
        let out = run(
            fanuc(false),
            &[
                "G21 G17",
                "G16",
                "G00 X25.4 Y30.",
                "G18",
                "G01 Z50.8 X-45. F100.",
                "G15",
                "G01 X25.4 Y25.4",
            ],
        )
        .unwrap();
        assert_eq!(
            out,
            [
                "G20 G17",
                "G16",
                "G00 X1. Y30.",
                "G18",
                "G01 Z2. X-45. F3.937",
                "G15",
                "G01 X1. Y1.",
            ]
        );
        // an increment after a polar move starts afresh (where the axis is is not followed)
        let out = run(
            fanuc(false),
            &[
                "G21 G17 G91",
                "G00 X1.",
                "G16",
                "X10. Y30.",
                "G15",
                "X1.",
                "X1.",
            ],
        )
        .unwrap();
        assert_eq!(out[3..], ["X0.3937 Y30.", "G15", "X0.0394", "X0.0393"]);
    }

    /// [`fanuc`]'s formats read as LinuxCNC reads a program: numbers as written, no
    /// increments, arc centres incremental, to LinuxCNC.
    fn linuxcnc() -> ConvertConfig {
        let mut c = fanuc(false);
        c.family = Family::LinuxCnc;
        c.target_family = Family::LinuxCnc;
        c.src_increments = None;
        c.dst_increments = None;
        c.src_modal.centre_codes = false;
        c
    }

    #[test]
    fn linuxcnc_rotation_and_io_numbers_are_no_lengths() {
        let c = linuxcnc();
        let dialect = Dialect {
            family: Family::LinuxCnc,
            ..Dialect::default()
        };
        let lines = [
            "G21",
            "G10 L2 P1 X25.4 R45",
            "G10 L20 P1 R30",
            "G10 L1 P1 R2.54 Q3",
            "M66 P0 L3 Q5",
            "M19 R90 Q2",
        ];
        let out = run_in(c, &lines, &dialect).unwrap();
        assert_eq!(
            out,
            [
                "G20",
                "G10 L2 P1 X1. R45",
                "G10 L20 P1 R30",
                "G10 L1 P1 R0.1 Q3",
                "M66 P0 L3 Q5",
                "M19 R90 Q2",
            ]
        );
    }

    #[test]
    fn a_linuxcnc_e_word_no_code_uses_is_refused_under_a_change_of_units() {
        let dialect = Dialect {
            family: Family::LinuxCnc,
            ..Dialect::default()
        };
        // rs274 refuses these blocks ("E word with no G70, G76, M66, M67 or M68 to use it")
        for (lines, line, column) in [
            (&["G21", "G1 X25.4 E1 F100"][..], 2, 10),
            (&["G21", "E1"][..], 2, 1),
            (&["G21", "G33 Z-1 K1", "G1 X1", "Z-2 E1"][..], 4, 5),
            (&["G21", "G10 L2 P1 X0 E1"][..], 2, 14),
        ] {
            let (at, e) = run_in(linuxcnc(), lines, &dialect).unwrap_err();
            assert_eq!((at, e.column), (line, column), "{lines:?}");
            assert!(
                e.message
                    .contains("E word with no G70, G76, M66, M67 or M68 to use it"),
                "{}",
                e.message
            );
        }
        // a code that uses E, G33 in force, or a motion not known after a call
        let lines = [
            "G21",
            "G76 P2.54 Z-25.4 I-0.254 J0.254 K2.54 E2.54",
            "G33 Z-25.4 K2.54",
            "Z-50.8 K2.54 E2.54",
            "M67 E1 Q2",
            "G0 X0",
            "o100 call",
            "Z-25.4 E2.54",
        ];
        assert_eq!(
            run_in(linuxcnc(), &lines, &dialect).unwrap(),
            [
                "G20",
                "G76 P0.1 Z-1. I-0.01 J0.01 K0.1 E0.1",
                "G33 Z-1. K0.1",
                "Z-2. K0.1 E0.1",
                "M67 E1 Q2",
                "G0 X0",
                "o100 call",
                "Z-1. E0.1",
            ]
        );
    }

    #[test]
    fn a_sinumerik_frame_and_named_lengths_convert_its_angles_stay() {
        let mut c = fanuc(false);
        c.family = Family::Sinumerik;
        c.target_family = Family::Sinumerik;
        c.src_increments = None;
        c.dst_increments = None;
        c.src_modal.centre_codes = false;
        c.src_modal.sinumerik_units = true;
        (c.src_modal.inch, c.src_modal.metric) = (70, 71);
        (c.inch_code, c.metric_code) = ("G70".into(), "G71".into());
        c.pqr = [Role::Other, Role::Other, Role::Parameter];
        let dialect = Dialect {
            family: Family::Sinumerik,
            semicolon: true,
            lowercase: true,
            brackets: true,
            expressions: true,
            ..Dialect::default()
        };
        let lines = [
            "G71",
            "TRANS X25.4 Y-12.7 A90 ; shift",
            "ATRANS Z=50.8",
            "ROT Z45",
            "AROT RPL=30",
            "SCALE X2 Y2",
            "G2 X25.4 Y0 CR=12.7",
            "G1 X50.8 RND=2.54 CHF=1.27",
            "G1 RP=25.4 AP=45",
            "G3 X0 Y25.4 AR=90",
        ];
        let out = run_in(c.clone(), &lines, &dialect).unwrap();
        assert_eq!(
            out,
            [
                "G70",
                "TRANS X1. Y-0.5 A90 ; shift",
                "ATRANS Z=2.",
                "ROT Z45",
                "AROT RPL=30",
                "SCALE X2 Y2",
                "G2 X1. Y0 CR=0.5",
                "G1 X2. RND=0.1 CHF=0.05",
                "G1 RP=1. AP=45",
                "G3 X0 Y1. AR=90",
            ]
        );
        // a frame before the program's units code would be read in the other units
        let (line, e) = run_in(c.clone(), &["TRANS X10", "G71 G1 X1"], &dialect).unwrap_err();
        assert_eq!((line, e.column, e.clause), (1, 8, "units"));
        // a value the statement computes is no number shown to be a length or not
        let (line, e) = run_in(c.clone(), &["G71", "G2 X1 Y0 CR=5+R2"], &dialect).unwrap_err();
        assert_eq!((line, e.clause), (2, "6.4.7"));
        // a shift by a parameter is refused, not carried in the other units
        let (line, e) = run_in(c, &["G71", "TRANS X=R1"], &dialect).unwrap_err();
        assert_eq!((line, e.column, e.clause), (2, 1, "6.4.7"));
    }

    #[test]
    fn a_count_of_increments_converts_as_a_length_and_reports_its_rounding() {
        let out = run(
            fanuc(true),
            &[
                "G21 G99",
                "G76 P020060 Q127",
                "G76 X20.3 Z-30. R0 P1200 Q350 F2.",
            ],
        )
        .unwrap();
        assert_eq!(out[1], "G76 P020060 Q50"); // 0.127 mm = 0.005 in, exactly
        assert_eq!(out[2], "G76 X0.7992 Z-1.1811 R0 P472 Q138 F0.0787");
        let mut converter = Converter::new(fanuc(true));
        let mut tokens = Vec::new();
        let dialect = Dialect::default();
        converter
            .convert_line(b"G76 X1. Z1. P1200 Q350", 1, &dialect, &mut tokens)
            .unwrap();
        // Q350: 137.795... increments of 0.0001 in written 138, off by 0.205 of one
        let q = converter.worst.iter().find(|w| w.0 == b'Q').unwrap();
        assert_eq!((q.1, q.2), (13, 635_000));
        let mut exact = fanuc(true);
        exact.rounding = Rounding::Error;
        let (line, e) = run(exact, &["G21", "G76 P020060 Q100"]).unwrap_err();
        assert_eq!((line, e.column), (2, 13));
        // no change of units: the count is kept as written, zeros and all
        let mut same = fanuc(true);
        same.units = None;
        assert_eq!(
            run(same, &["G76 P020060 Q0044"]).unwrap()[0],
            "G76 P020060 Q0044"
        );
    }

    #[test]
    fn a_subprogram_that_inherits_its_distance_mode_is_refused_under_a_change_of_units() {
        let main = ["G21 G90", "G0 X1.", "M98 P2", "M30"];
        let sub = [&main[..], &["O2", "X1. Y2.", "G91 X1.", "M99"]].concat();
        let (line, e) = run(fanuc(false), &sub).unwrap_err();
        assert_eq!((line, e.column, e.clause), (6, 1, "modal state"));
        assert!(e.message.contains("M99 at line 8"), "{}", e.message);
        // its own G91 (or G90) before its first move: converted, by positions; and given the
        // units the converted caller runs in, as any program after M30 is
        let own = [&main[..], &["O2", "G91 X1.", "X1.", "M99"]].concat();
        assert_eq!(run(fanuc(false), &own).unwrap()[5], "G20 G91 X0.0394");
        // a program that ends with M30 starts from the reset state; no change of units, no
        // conversion to refuse; a Fanuc lathe's U W are increments by their letter
        assert!(run(fanuc(false), &["G21", "X1.", "M30"]).is_ok());
        let mut same = fanuc(false);
        same.units = None;
        assert!(run(same, &sub).is_ok());
        assert!(run(fanuc(true), &["G21", "U1. W2.", "M99"]).is_ok());
    }

    /// Review 56a, F3 and F8: a FANUC's G73/G83 K is its repeat count whether or not the block
    /// writes I or J (its G73/G83 have none: 0i-MF, 30i-MB) and with a point or without, on a
    /// mill and on a lathe; a Haas's the least peck depth, a length; on either control of the
    /// language (not known which) a G73/G83's K is refused under a change of units
    /// (`Role::Parameter`), whatever else the block writes. A FANUC's other cycles count in K
    /// too; a Haas's G81 reads no K.
    #[test]
    fn the_k_of_a_drilling_cycle_is_the_fanuc_s_count_the_haas_s_depth_or_unknown() {
        let k = |haas: Option<bool>, lathe: bool, g: i64, words: &[&'static str]| {
            let spans = spans(words);
            let tokens = spans.iter().map(|w| (w.token[0], &w.token[1..]));
            code_meanings_of(Family::MacroB, haas, lathe, &[g], &[], tokens).role(b'K')
        };
        let blocks: [&[&'static str]; 5] = [
            &["G83", "Z-5.", "R-3.", "Q1.", "K3"],
            &["G83", "Z-5.", "R-3.", "I1.", "J0.5", "K2"],
            &["G83", "Z-5.", "R-3.", "J0.5", "K2"],
            &["G83", "Z-5.", "R-3.", "I1.", "J0.5", "K3."],
            &["G83", "Z-5.", "R-3.", "Q1.", "K.5"],
        ];
        for lathe in [false, true] {
            for words in blocks {
                let count = Some(Role::Other);
                assert_eq!(k(Some(false), lathe, 83, words), count, "{lathe} {words:?}");
                let length = Some(Role::Length);
                assert_eq!(k(Some(true), lathe, 83, words), length, "{lathe} {words:?}");
                let unknown = Some(Role::Parameter);
                assert_eq!(k(None, lathe, 83, words), unknown, "{lathe} {words:?}");
            }
        }
        for haas in [Some(false), None] {
            let g73 = ["G73", "Z-5.", "R-3.", "I1.", "K2"];
            let expected = [Some(Role::Other), Some(Role::Parameter)][usize::from(haas.is_none())];
            assert_eq!(k(haas, false, 73, &g73), expected, "{haas:?}");
            assert_eq!(
                k(haas, false, 81, &["G81", "Z-5.", "K3"]),
                Some(Role::Other)
            );
        }
        assert_eq!(k(Some(true), false, 81, &["G81", "Z-5.", "K3"]), None);
    }

    /// A FANUC or Haas control's modal settings, as far as [`block_counts`] asks them.
    fn macro_b(haas: bool, fanuc_lathe: bool) -> ModalSettings {
        ModalSettings {
            reset: vec![0, 17, 90],
            inch: 20,
            metric: 21,
            default_units: Units::Metric,
            family: Family::MacroB,
            fanuc_lathe,
            g80_clears_motion: false,
            sinumerik_units: false,
            centre_codes: true,
            heidenhain: false,
            lap: false,
            g92_clamps: false,
            units_kept_at_end: true,
            dwell: crate::word::dwell_words(Family::MacroB, fanuc_lathe),
            arc_radius: b'R',
            lacks_g: Vec::new(),
            g_system: Default::default(),
            haas,
        }
    }

    /// Review 55a, F4: the modal state's own reading counts a cycle's repeats by the one rule
    /// the checker asks (`Meanings::cycle_count` of [`block_meanings`]), the cycle in force
    /// read into a block of hole positions: a FANUC mill's K is the count, beside I or J and
    /// with a point too (review 56a, F3, F8), but not a Haas's K (its count is L, its
    /// G73/G83 K a length), nor a K outside a cycle, nor one a lathe's cycle in force is not
    /// read into.
    #[test]
    fn the_modal_reading_counts_a_cycle_s_k_as_the_checker_does() {
        let k = 1 << (b'K' - b'A');
        let counts = |settings: &ModalSettings, cycle: Option<i64>, line: &str| {
            let tokens: Vec<&[u8]> = line.split(' ').map(str::as_bytes).collect();
            block_counts(settings, cycle, &tokens) & k
        };
        let (fanuc, haas) = (macro_b(false, false), macro_b(true, false));
        for (cycle, line, counted) in [
            (None, "G91 G81 X10. Z-5. R-3. K3 F100.", true),
            (None, "G91 G73 X10. Z-5. R-3. Q1. K3 F100.", true),
            (None, "G91 G83 X10. Z-5. R-3. I1. J0.5 K2 F100.", true),
            (None, "G91 G73 X10. Z-5. R-3. J0.5 K2 F100.", true),
            (None, "G91 G83 X10. Z-5. R-3. I1. J0.5 K3. F100.", true),
            (Some(81), "X10. K3", true),
            (Some(81), "G17 X10. K4", true),
            (Some(83), "G91 X10. K4", true),
            (Some(81), "G01 X10. K4", false),
            (Some(81), "X10. K3.", true),
            (None, "X10. K3", false),
            (None, "G18 G02 X0.02 Z0 I0.01 K3 F100.", false),
        ] {
            assert_eq!(
                counts(&fanuc, cycle, line) != 0,
                counted,
                "{cycle:?} {line}"
            );
        }
        for (cycle, line) in [
            (None, "G91 G81 X10. Z-5. R-3. K3 L3 F100."),
            (None, "G91 G83 X10. Z-5. R-3. Q1. K2 F100."),
            (Some(83), "G91 X1. K4"),
        ] {
            assert_eq!(counts(&haas, cycle, line), 0, "haas {cycle:?} {line}");
        }
        // a lathe's drilling cycle counts in its own block; the one in force is not read into
        // a block of positions (as the checker reads it)
        let lathe = macro_b(false, true);
        assert_eq!(counts(&lathe, None, "G83 Z-10. R-1. Q2000 K3 F0.1"), k);
        assert_eq!(counts(&lathe, Some(83), "X10. K3"), 0);
    }

    #[test]
    fn a_count_word_the_conversion_keeps_is_kept_as_written() {
        // S05 is a count: S0600 in G97 (or a G50 clamp) is 600 rpm in any units, written as it
        // was (the byte check of --verify found it written S600)
        let mut c = fanuc(true);
        c.out_formats.push((b'S', fmt(5, 0, Zeros::Leading, false)));
        c.src_formats.push((b'S', fmt(5, 0, Zeros::Leading, false)));
        let out = run(c, &["G21 G99", "G50 S0600", "G97 S0450 M03"]).unwrap();
        assert_eq!(out[1..], ["G50 S0600", "G97 S0450 M03"]);
    }

    #[test]
    fn an_increment_after_a_units_code_moves_from_the_place_reached() {
        // G91 across G20/G21: the machine keeps its place, the next increment is in the new
        // units (10 mm, +1 in = 35.4 mm, +1 mm = 36.4 mm = 1.43307 in)
        let src = ["G21 G91", "G0 X10.", "G20", "X1.", "G21", "X1."];
        let out = run(fanuc(false), &src).unwrap();
        assert_eq!(
            out,
            ["G20 G91", "G0 X0.3937", "G20", "X1.", "G20", "X0.0394"]
        );
        let mut c = fanuc(false);
        c.units = Some(Units::Metric);
        let src = ["G20 G91", "G0 X1.", "G21", "X10.", "G20", "X1."];
        let out = run(c, &src).unwrap();
        assert_eq!(out, ["G21 G91", "G0 X25.4", "G21", "X10.", "G21", "X25.4"]);
        // without a change of units the program is written as it was, and nothing is rounded
        let mut c = fanuc(false);
        c.units = None;
        let src = [
            "G21 G91", "G0 X10.", "G20", "X1.", "G21", "X1.", "G90 X5.", "G91 X-1.",
        ];
        let mut converter = Converter::new(c);
        let dialect = Dialect {
            family: Family::MacroB,
            ..Dialect::default()
        };
        let mut tokens = Vec::new();
        for (i, line) in src.iter().enumerate() {
            let new = converter.convert_line(line.as_bytes(), i + 1, &dialect, &mut tokens);
            assert!(matches!(new, Ok(None)), "{line}: {new:?}");
        }
        assert!(converter.worst.is_empty(), "{:?}", converter.worst);
    }

    #[test]
    fn a_statement_holds_values_but_for_the_size_of_a_string() {
        for (text, holds) in [
            ("IF [#5405 GE 6000] THEN #3000=15", true),
            ("CR=4.", true),
            ("DEF REAL XV=0.5", true),
            ("DEF STRING[100] NAZIVF", false),
            ("def string[32] fname", false),
            ("PROC MS150(STRING[32] ALAT, INT IVICA, REAL PREC)", false),
            ("DEF STRING[8] S=\"A1\" DEF REAL R=2.5", true),
            ("def real merenja[10]", false),
            ("DEF REAL TAB[2,3]=SET(1.5, 2)", true),
            ("MSG(\"T1 D6.\")", false),
            ("GOTOF LABEL_1", false),
            ("WHILE R1<10", true),
            ("IF R1>2.5 GOTOB LAB", true),
            ("WHILE R3<=R1", false),
            ("IF R1<R2 GOTOF MARK_2", false),
        ] {
            assert_eq!(holds_values(text.as_bytes(), true), holds, "{text}");
        }
        // a LinuxCNC label in angle brackets is a name, no comparison
        for text in ["o<1st> call", "o<100> sub"] {
            assert!(!holds_values(text.as_bytes(), false), "{text}");
        }
    }

    /// O1's #1 is a length, O2's a count: each program gets its own classes, found where
    /// [`ProgramStarts`] splits the file as the converter does; an analysis split elsewhere
    /// is refused.
    #[test]
    fn each_program_converts_by_its_own_parameter_classes() {
        let lines = [
            "%",
            "O1",
            "G21 G90",
            "#1=10.",
            "G01 X#1 F100.",
            "M30",
            "O2",
            "G21 G90",
            "#1=3",
            "M98 P1000 L#1",
            "M30",
            "%",
        ];
        let dialect = Dialect {
            family: Family::MacroB,
            hash: true,
            brackets: true,
            expressions: true,
            ..Dialect::default()
        };
        let mut starts = ProgramStarts::new(Family::MacroB, Some(b'O'));
        let mut tokens = Vec::new();
        let found: Vec<usize> = (1..)
            .zip(lines)
            .filter(|(_, l)| {
                split_line(&mut starts, l.as_bytes(), &dialect, &mut tokens)
                    .unwrap()
                    .0
            })
            .map(|(n, _)| n)
            .collect();
        assert_eq!(found, [7]);
        // M99 returns; a call (M98, M198) or an end (M30) does not
        let mut starts = ProgramStarts::new(Family::MacroB, Some(b'O'));
        for (line, returns) in [
            ("N9 M99", true),
            ("M98 P1000 L#1", false),
            ("M198 P2", false),
        ]
        .into_iter()
        .chain([("M30", false), ("G01 X#1 F100.", false)])
        {
            let read = split_line(&mut starts, line.as_bytes(), &dialect, &mut tokens).unwrap();
            assert_eq!(read, (false, returns), "{line}");
        }
        let classes = |starts: &[usize]| {
            let mut shared = Classes::default();
            shared.insert(b"#1".to_vec(), ParameterClass::Length);
            // the first program's own #1 a length, the second's nothing
            Some(Arc::new(ParameterClasses {
                starts: starts.to_vec(),
                shared: Classes::default(),
                own: vec![(0, shared)],
                subs: Default::default(),
            }))
        };
        let mut c = fanuc(false);
        c.units = Some(Units::Inch);
        c.parameters = classes(&[0, 7]);
        let out = run_in(c.clone(), &lines, &dialect).unwrap();
        assert_eq!(out[3..5], ["#1=0.3937", "G01 X#1 F3.937"]);
        assert_eq!(out[8..10], ["#1=3", "M98 P1000 L#1"]);
        c.parameters = classes(&[0, 8]);
        let (line, e) = run_in(c, &lines, &dialect).unwrap_err();
        assert_eq!((line, e.clause), (7, "6.4.7"));
        assert!(e
            .message
            .contains("split the file's programs differently at line 7"));
    }

    /// On a SINUMERIK M17 and RET return and M2/M30 end a program; M99 is no code of the
    /// control's program flow (a PLC's M function), and returns nothing. An archive's next
    /// file header begins the next program whatever the one before ended with (M99 or no end
    /// at all): each file is a program of its own.
    #[test]
    fn a_sinumerik_program_ends_by_its_own_codes() {
        let dialect = Dialect::permissive(Family::Sinumerik);
        let mut starts = ProgramStarts::new(Family::Sinumerik, None);
        let mut tokens = Vec::new();
        let read: Vec<(bool, bool)> = [
            "%_N_A_MPF",
            "G0 X1",
            "M99",
            "%_N_B_SPF",
            "M17",
            "%_N_C_SPF",
            "RET",
            "%_N_D_SPF",
            "M30",
            "%_N_E_MPF",
        ]
        .iter()
        .map(|l| split_line(&mut starts, l.as_bytes(), &dialect, &mut tokens).unwrap())
        .collect();
        let begins: Vec<usize> = (1..)
            .zip(&read)
            .filter(|(_, r)| r.0)
            .map(|(n, _)| n)
            .collect();
        let returns: Vec<usize> = (1..)
            .zip(&read)
            .filter(|(_, r)| r.1)
            .map(|(n, _)| n)
            .collect();
        assert_eq!(begins, [4, 6, 8, 10]);
        assert_eq!(returns, [5, 7]);
        assert_eq!(crate::dialect::return_code(Family::MacroB), Some(99));
        assert_eq!(crate::dialect::return_code(Family::Okuma), None);
        // HEIDENHAIN ISO's M99 calls a cycle for its block: no return
        assert_eq!(crate::dialect::return_code(Family::Heidenhain), None);
    }

    /// On a HEIDENHAIN (ISO programming) M99 calls the cycle last defined, for its block only:
    /// no return, so the split of a file into programs does not take it for one.
    #[test]
    fn a_heidenhain_m99_is_no_return() {
        let dialect = Dialect::permissive(Family::Heidenhain);
        let mut starts = ProgramStarts::new(Family::Heidenhain, None);
        let mut tokens = Vec::new();
        for line in ["N10 G79 M99 *", "N20 M99 *", "N30 M30 *"] {
            let read = split_line(&mut starts, line.as_bytes(), &dialect, &mut tokens).unwrap();
            assert_eq!(read, (false, false), "{line}");
        }
        assert!(!starts.splits());
    }

    #[test]
    fn the_cycle_tables_ask_of_points_only_for_the_cycles_g73_to_g89_and_g243() {
        // `meanings_by_codes` reads the words' points only for those codes: for any other, the
        // tables give the same roles whatever the points
        let families = Family::ALL;
        let all = (1u32 << 26) - 1;
        for family in families {
            for (haas, lathe) in [(None, false), (Some(true), false), (Some(false), true)] {
                for g in (0..=400).filter(|g| !((73..=89).contains(g) || *g == 243)) {
                    for ms in [&[][..], &[98], &[97], &[198], &[3]] {
                        for letters in [all, 0, 1 << (b'K' - b'A') | 1 << (b'Q' - b'A')] {
                            let unread = cycle_table(family, haas, lathe, &[g], ms, letters, 0);
                            let pointed = cycle_table(family, haas, lathe, &[g], ms, letters, all);
                            let (unread, pointed) = (unread.roles, pointed.roles);
                            assert_eq!(unread, pointed, "{family:?} G{g} {ms:?} lathe {lathe}");
                        }
                    }
                }
            }
        }
        // and a cycle that asks: a lathe's G83 Q, a count of increments without its point
        let q = 1 << (b'Q' - b'A');
        let roles = cycle_table(Family::MacroB, None, true, &[83], &[], q, 0).roles;
        assert_eq!(roles[slot(b'Q')], Some(Role::Increments));
        let roles = cycle_table(Family::MacroB, None, true, &[83], &[], q, q).roles;
        assert_eq!(roles[slot(b'Q')], Some(Role::Length));
    }

    #[test]
    fn the_cycle_tables_mark_a_time_or_an_angle_as_a_measure_and_a_count_not() {
        // issue 32: the one rule the diff compares by (`Meanings::cycle_measure`)
        let bit = |l: u8| 1u32 << slot(l);
        let table = |family, haas, lathe, g: i64, letters: &[u8]| {
            let letters = letters.iter().fold(0u32, |bits, &l| bits | bit(l));
            cycle_table(family, haas, lathe, &[g], &[], letters, 0).measures
        };
        let macro_b = Family::MacroB;
        // a lathe's thread start angle Q (G32, G92), Haas G76's start angle Q and tool nose
        // angle A (its P the infeed method, a selector), Haas G199's phase angle R
        for haas in [None, Some(true), Some(false)] {
            for g in [32, 92] {
                assert_eq!(table(macro_b, haas, true, g, b"XZFQ"), bit(b'Q'), "G{g}");
            }
        }
        let haas76 = table(macro_b, Some(true), true, 76, b"XZKDIAPQF");
        assert_eq!(haas76, bit(b'A') | bit(b'Q'));
        assert_eq!(table(macro_b, Some(true), true, 199, b"R"), bit(b'R'));
        // a drilling cycle's dwell P, a mill's and a lathe's; K (a FANUC's repeats) and J (a
        // Haas's retract multiple) stay counts
        for g in [73, 74, 76, 82, 83, 84, 86, 87, 88, 89] {
            for haas in [Some(true), Some(false)] {
                let measures = table(macro_b, haas, false, g, b"XYZRPQFKJ");
                assert_eq!(measures, bit(b'P'), "G{g} {haas:?}");
            }
        }
        for g in [83, 84, 86, 87, 88, 89] {
            assert_eq!(
                table(macro_b, Some(false), true, g, b"XZRPQFK"),
                bit(b'P'),
                "G{g}"
            );
        }
        // a lathe's multiple repetitive cycles: block numbers, selectors, the packed P of
        // G76's first block: no measure
        for (g, letters) in [
            (70, &b"PQ"[..]),
            (71, b"PQUWRF"),
            (72, b"PQUWF"),
            (73, b"PQUW"),
            (73, b"UWR"),
            (76, b"PQR"),
            (76, b"XZPQRF"),
        ] {
            assert_eq!(table(macro_b, Some(false), true, g, letters), 0, "G{g}");
        }
        // LinuxCNC G76: Q (the compound slide angle) and R (the depth degression) measure; H
        // (spring passes) and L (taper ends) count
        let lcnc = table(Family::LinuxCnc, None, false, 76, b"PZIJKRQHEL");
        assert_eq!(lcnc, bit(b'Q') | bit(b'R'));
        // a call's numbers (G10, G65, M98) are no measure
        assert_eq!(table(macro_b, Some(false), false, 10, b"LPR"), 0);
        assert_eq!(table(macro_b, Some(false), false, 65, b"PLAB"), 0);
    }

    #[test]
    fn a_block_without_g_or_m_words_has_no_code_meanings() {
        // `code_meanings_of` answers such a block without the tables: they give it nothing
        let words: [&[u8]; 24] = [
            b"X1.", b"Y2", b"Z-3.5", b"U4", b"W5.", b"A60", b"B1.", b"C2", b"I1.", b"J2", b"K3",
            b"K4.", b"P1", b"P1.5", b"Q2", b"Q2.", b"R3", b"L5", b"H6", b"D4", b"E3", b"F100.",
            b"S1000", b"#1=2",
        ];
        let families = Family::ALL;
        for (n, family) in families.into_iter().enumerate() {
            for (haas, lathe) in [(None, false), (Some(true), false), (Some(false), true)] {
                // every run of 1 to 6 words, from every start
                for start in 0..words.len() {
                    for len in 1..=6 {
                        let block: Vec<&[u8]> = (0..len)
                            .map(|i| words[(start + i * (n + 1)) % words.len()])
                            .collect();
                        let tokens = block.iter().map(|w| (w[0], &w[1..]));
                        let letters = block
                            .iter()
                            .filter(|w| w[0].is_ascii_uppercase())
                            .fold(0u32, |l, w| l | 1 << (w[0] - b'A'));
                        let read =
                            meanings_by_codes(family, haas, lathe, &[], &[], tokens, letters);
                        assert_eq!(
                            read,
                            crate::meaning::Meanings::default(),
                            "{family:?} {block:?}"
                        );
                        let tokens = block.iter().map(|w| (w[0], &w[1..]));
                        let answered = code_meanings_of(family, haas, lathe, &[], &[], tokens);
                        assert_eq!(answered, read);
                    }
                }
            }
        }
        // a G or M word, or a code given apart from the words, is read by the tables
        let tokens = [(b'G', &b"76"[..]), (b'K', b"1."), (b'Q', b"2")];
        let read = code_meanings_of(Family::MacroB, None, true, &[76], &[], tokens.into_iter());
        assert_eq!(read.roles[slot(b'K')], Some(Role::Length));
        let tokens = [(b'P', &b"1"[..]), (b'L', b"2")];
        let read = code_meanings_of(Family::MacroB, None, false, &[], &[98], tokens.into_iter());
        assert_eq!(read.roles[slot(b'P')], Some(Role::Other));
    }

    #[test]
    fn an_expression_shape_read_again_is_asked_again_where_its_reading_differs() {
        // The shape's parameters, looked at once, are not looked up again for a word of the
        // same shape (`ShapeUse`); what differs between the two readings is asked again: the
        // length factor (a units code between), the subroutine (its #1-#30 its own)
        let dialect = Dialect::permissive(Family::LinuxCnc);
        let mut c = linuxcnc();
        c.program_number = None;
        let why = "#1 is read as a length (line 6) but not set in this subroutine".to_string();
        let classes = [
            ("#1", ParameterClass::Length),
            ("#1@5", ParameterClass::Unproved(why.clone())),
            ("#<a>", ParameterClass::Length),
        ];
        c.parameters = Some(Arc::new(ParameterClasses {
            starts: vec![0],
            shared: classes
                .map(|(n, class)| (n.as_bytes().to_vec(), class))
                .into_iter()
                .collect(),
            own: Vec::new(),
            subs: Default::default(),
        }));
        // the same shape in metric, again in metric, then after G20: refused at its line
        let units = [
            "G21 G90",
            "G1 X[#<a>*2.] F100.",
            "G1 X[#<a>*3.5]",
            "G20",
            "G1 X[#<a>*4.]",
        ];
        let (line, e) = run_in(c.clone(), &units, &dialect).unwrap_err();
        assert_eq!((line, e.clause), (5, "units"), "{}", e.message);
        assert!(e
            .message
            .starts_with("#<a> is read as a length on line 5 in inch, and on line 2"));
        // the same shape in the main program and in a subroutine: its #1 is the subroutine's
        let sub = [
            "G21 G90",
            "G1 X[#1*2.] F100.",
            "G1 X[#1*3.]",
            "o<s> call",
            "o<s> sub",
            "G1 X[#1*4.]",
            "o<s> endsub",
        ];
        let (line, e) = run_in(c.clone(), &sub, &dialect).unwrap_err();
        assert_eq!((line, e.clause), (6, "6.4.7"), "{}", e.message);
        assert_eq!(
            e.message,
            format!("X[#1*4.]: cannot convert the units of the value: {why}")
        );
        // and where nothing differs, each word converts as the first did (#<a>, a length,
        // converted where it is set: its factors kept)
        let out = run_in(c, &units[..3], &dialect).unwrap();
        assert_eq!(out, ["G20 G90", "G1 X[#<a>*2.] F3.937", "G1 X[#<a>*3.5]"]);
    }

    /// LinuxCNC's `#<name> = value` is converted as `#1 = value` is, by the name the analysis
    /// lists (lower case, without blanks); in an `o<name> sub` a local named parameter is the
    /// subroutine's own (`#<a>@3`), the main program's `#<a>` another, and a global `#<_zs>`
    /// the file's. A word reading a parameter the analysis lists nowhere (the subroutine's
    /// `#<zs>@3`) is refused: it is kept, and the word's value is scaled.
    #[test]
    fn a_named_parameter_converts_by_its_name_and_subroutine() {
        let lines = [
            "G21 G90",
            "#<_Z S > = 1.0",
            "o<s> sub",
            "#<a> = [2. + #<_zs>]",
            "G1 X#<a> Y[#<_zs>*10.] F100.",
            "o<s> endsub",
            "#<a> = 3",
            "M98 L#<a>",
            "G1 X#<B>",
        ];
        let dialect = Dialect::permissive(Family::LinuxCnc);
        let mut c = fanuc(false);
        c.family = Family::LinuxCnc;
        c.target_family = Family::LinuxCnc;
        c.program_number = None;
        let why = "#<b> is read as a length (line 9) but not set in this program".to_string();
        let named = [
            ("#<_zs>", ParameterClass::Length),
            ("#<a>@3", ParameterClass::Length),
            ("#<b>", ParameterClass::Unproved(why.clone())),
        ];
        c.parameters = Some(Arc::new(ParameterClasses {
            starts: vec![0],
            shared: named
                .map(|(n, class)| (n.as_bytes().to_vec(), class))
                .into_iter()
                .collect(),
            own: Vec::new(),
            subs: Default::default(),
        }));
        let (line, e) = run_in(c.clone(), &lines, &dialect).unwrap_err();
        assert_eq!((line, e.clause), (9, "6.4.7"), "{}", e.message);
        assert_eq!(
            e.message,
            format!("X#<B>: cannot convert the units of the value: {why}")
        );
        let mut local = lines;
        local[4] = "G1 Y[#<zs>*10.]";
        let (line, e) = run_in(c.clone(), &local, &dialect).unwrap_err();
        assert_eq!((line, e.clause), (5, "6.4.7"));
        assert!(e.message.starts_with(
            "Y[#<zs>*10.] reads #<zs>@3, which this conversion leaves as written, but"
        ));
        c.allow_unconverted = true;
        let out = run_in(c, &lines, &dialect).unwrap();
        assert_eq!(out[1], "#<_Z S > = 0.0394");
        assert_eq!(out[3], "#<a> = [0.0787 + #<_zs>]");
        assert_eq!(out[6..9], ["#<a> = 3", "M98 L#<a>", "G1 X#<B>"]);
    }

    #[test]
    fn the_parameters_a_condition_or_an_expression_reads() {
        let names = |t: &str| -> Vec<String> {
            super::parameter_names(t.as_bytes())
                .iter()
                .map(|n| String::from_utf8_lossy(n).into_owned())
                .collect()
        };
        assert_eq!(names("WHILE [#1 LE #2] DO1"), ["#1", "#2"]);
        assert_eq!(names("o1 while [#<n> LE #<end>]"), ["#<n>", "#<end>"]);
        // chosen by a value: no name
        assert_eq!(names("IF [#[#1+1] GT ##2] GOTO10"), ["#1", "#2"]);
        assert_eq!(names("#1+#30*2"), ["#1", "#30"]);
    }

    /// `value` asks [`Converter::dwell_time`] only of a dwell word or a P: for every other
    /// word it answers None, between any two families, on a mill or a lathe, under any cycle
    /// in force or repeated (on 200,000 drawn words of every other letter).
    #[test]
    fn a_dwells_time_is_none_but_for_a_dwell_word_or_a_p() {
        const BYTES: &[u8] = b"0123456789.-+";
        let mut next = crate::drawn::xorshift(0x3C6E_F372_FE94_F82B);
        let mut converters = Vec::new();
        for lathe in [false, true] {
            for from in Family::ALL {
                for to in Family::ALL {
                    let mut c = fanuc(lathe);
                    (c.family, c.target_family, c.lathe) = (from, to, lathe);
                    converters.push(Converter::new(c));
                }
            }
        }
        for _ in 0..200_000 {
            let k = (next() % converters.len() as u64) as usize;
            let converter = &mut converters[k];
            let cycle = [
                None,
                Some(82),
                Some(83),
                Some(73),
                Some(76),
                Some(89),
                Some(243),
            ];
            converter.modal.state.cycle = cycle[(next() % cycle.len() as u64) as usize];
            converter.cycle_code = Repeat {
                cycle: cycle[(next() % cycle.len() as u64) as usize],
                thread: None,
            };
            let letter = loop {
                let l =
                    b"ABCDEFGHIJKLMNOQRSTUVWXYZabcdefghijklmnoqrstuvwxyz@#"[(next() % 52) as usize];
                if l != b'p' && l != b'P' {
                    break l;
                }
            };
            let len = (next() % 8) as usize;
            let mut token = vec![letter];
            token.extend((0..len).map(|_| BYTES[(next() % BYTES.len() as u64) as usize]));
            let number = &token[1..];
            let (whole, dot, fraction) = match number.iter().position(|&c| c == b'.') {
                Some(p) => (&number[..p], true, &number[p + 1..]),
                None => (number, false, &b""[..]),
            };
            assert_eq!(
                converter.dwell_time(&token, false, whole, dot, fraction),
                Ok(None),
                "{:?}",
                String::from_utf8_lossy(&token)
            );
        }
    }

    #[test]
    fn the_format_and_letter_tables_find_what_the_lists_find() {
        let c = fanuc(false);
        let converter = Converter::new(c.clone());
        for letter in 0..=255u8 {
            for units in [Units::Metric, Units::Inch] {
                for (table, formats, inch) in [
                    (&converter.src_table, &c.src_formats, &c.src_formats_inch),
                    (&converter.out_table, &c.out_formats, &c.out_formats_inch),
                ] {
                    let inch = inch.as_deref();
                    assert_eq!(
                        table.get(formats, inch, letter, units),
                        format_in(formats, inch, letter, units),
                        "{letter} {units:?}"
                    );
                }
            }
        }
        for letter in 0..=255u8 {
            for (letters, list) in [
                (&converter.src_letters, &c.src_increments),
                (&converter.dst_letters, &c.dst_increments),
            ] {
                let list = list.as_deref();
                assert_eq!(letters.whole(letter), reads_whole(list, letter));
                assert_eq!(letters.increments(letter), reads_increments(list, letter));
            }
        }
        let none = WholeLetters::new(None);
        assert!((0..=255u8).all(|l| !none.whole(l) && !none.increments(l)));
        // the inch formats differ from the metric ones in this configuration: both are kept
        let inch = c.src_formats_inch.as_deref();
        let x = |units| converter.src_table.get(&c.src_formats, inch, b'X', units);
        assert_ne!(x(Units::Inch), x(Units::Metric));
    }

    #[test]
    fn plain_tokens() {
        assert_eq!(
            plain(b"X-1.5"),
            Some((true, false, &b"1"[..], true, &b"5"[..]))
        );
        assert_eq!(plain(b"X1=5"), None);
        assert_eq!(plain(b"X."), None);
        assert_eq!(integer(b"01"), Some(1));
        assert_eq!(integer(b"91.1"), None);
    }

    /// The exact value from the digits' one reading ([`Digits`]) is [`exact`]'s, trailing
    /// zeros, leading zeros, a bare point and 18 digits included; past 18, the fallback.
    #[test]
    fn exact_values_from_the_tokenizers_digits() {
        let numbers: [&[u8]; 14] = [
            b"0",
            b"0.000",
            b"10.500",
            b"007.0700",
            b".5",
            b"5.",
            b"123456789012.345678",
            b"1234567890123456789",
            b"99999999999999999.9",
            b"100",
            b"0.0001",
            b"25.4",
            b"1.10",
            b"000",
        ];
        for n in numbers {
            let (whole, fraction) = split_number(n);
            assert_eq!(
                exact_of(Some(Digits::of(n)), whole, fraction).ok(),
                exact(whole, fraction).ok(),
                "{}",
                String::from_utf8_lossy(n)
            );
        }
    }

    /// A word's plain number taken where the tokenizer found it is the one [`plain`] reads
    /// from its text, in every family, blanks and signs and points included.
    #[test]
    fn plain_numbers_where_the_tokenizer_found_them() {
        let lines: [&[u8]; 7] = [
            b"N10 G01 X-1.5 Y+.5 Z10. F100",
            b"X - 1 . 5 Y 2 0 Z+ 3",
            b"G1 X=10 Y=R1+5 R1=2.5 TURN=0 I.748 J-.286",
            b"#1=5. X#1 Y[#1*2] Z-0.004",
            b"n10 g1 x-1.5 y.5 (a comment) z0",
            b"G01X-12.345Y67.890F1500.S20000M3",
            b"X1 2 . 5 0 Y-0",
        ];
        let mut seen = 0;
        for family in [
            Family::Iso,
            Family::MacroB,
            Family::LinuxCnc,
            Family::Sinumerik,
            Family::Heidenhain,
        ] {
            let dialect = Dialect::permissive(family);
            for line in lines {
                let mut tokens = Vec::new();
                if tokenize(line, &dialect, &mut tokens).is_err() {
                    continue;
                }
                for t in &tokens {
                    let w = WordSpan {
                        token: &t.text,
                        start: t.offset,
                        end: t.end,
                        plain: t.plain,
                        digits: t.digits,
                    };
                    seen += usize::from(t.plain.is_some());
                    if t.plain.is_some() {
                        assert_eq!(plain_word(&w), plain(&t.text), "{:?}", t.text);
                        // and its exact value from the tokenizer's digits is the one read
                        // from them again
                        let (_, _, whole, _, fraction) = plain_word(&w).unwrap();
                        assert_eq!(
                            exact_of(Some(t.digits), whole, fraction).ok(),
                            exact(whole, fraction).ok(),
                            "{:?}",
                            t.text
                        );
                    }
                }
            }
        }
        assert!(seen > 60, "{seen}");
    }
}
