//! The machine: one profile compiled once into everything the core reads a program by.
//!
//! A profile is validated in Python (`formats.profile`) and turned, in one place
//! (`formats.machine.machine_spec`), into a [`MachineSpec`] of plain, typed values. The core
//! compiles the spec into one immutable [`Machine`]: the word formats per unit system, how a
//! number without a point is read, the code table with its groups, the reset state and what
//! M02/M30 keep, the modal settings of the family and the kind of machine, the roles of P, Q and
//! R, and the limits. Every rule that depends on the control family is decided here, once: the
//! checker, the converter (source and target), the diff and verify reader, the restart walk, the
//! modal machine and the plot all take a `Machine` and decide none of it again.
//!
//! A `Machine` is built once per profile and shared (`Arc`) across files, threads and gateway
//! ports.

use std::sync::Arc;

use crate::check::{Config, Ijk, ProfileFacts, Role};
use crate::convert::{CodeList, ConvertConfig, ParameterClasses, Rounding, Spacing};
use crate::lex::Family;
use crate::modal::{ModalSettings, Units};
use crate::ncread::ReadSettings;
use crate::restart::Control;
use crate::wordformat::WordFormat;

/// A profile's facts, as plain values: what `formats.machine.MachineSpec` holds.
#[derive(Debug, Clone)]
pub struct MachineSpec {
    /// The dialect's family (`fanuc`, `haas`, `sinumerik`, ...): Fanuc and Haas read one
    /// language (Custom Macro B) but differ in what a restart restores.
    pub control: Control,
    /// `control_type = "lathe"`.
    pub lathe: bool,
    /// The facts the checker reads as they are: word formats (and those that differ while inch
    /// is in force), how a number without a point is read, the code tables, the checks and the
    /// limits.
    pub facts: ProfileFacts,
    /// The dwell's word formats (`facilities.dwell`), for the converter's target.
    pub dwell_formats: Vec<(u8, WordFormat)>,
    /// `checks.unknown_g` / `unknown_m`: Some(true) for "alarm", Some(false) for "warn", None
    /// where the profile does not say (the family decides).
    pub unknown_g_alarms: Option<bool>,
    pub unknown_m_alarms: Option<bool>,
    /// The roles `checks.pqr` gives P, Q and R; None where it states none.
    pub pqr: [Option<Role>; 3],
    /// The reset state's G codes (clause 14), the units codes as numbers and as written.
    pub reset: Vec<i64>,
    pub inch: i64,
    pub metric: i64,
    pub inch_code: String,
    pub metric_code: String,
    pub default_units: Units,
    pub units_kept_at_end: bool,
    /// Decimals of one least input increment, metric and inch (IS-B: 3 and 4).
    pub increment_digits: [u32; 2],
    /// The codes the profile lists itself (`[codes]`, those it marks unassigned left out):
    /// (the code as [`differing_codes`] names it, `47`, `91.1`, `M98`; its meaning key,
    /// `codes.G47.meaning`, "" where it gives none; the profile's function).
    pub meanings: Vec<(String, String, String)>,
    /// A FANUC lathe's G code system (`g_code_system`: "A", "B", "C"; "" for other controls).
    pub g_code_system: String,
    /// What the profile's dialect reads beyond ISO 6983-1 Annex A (`formats.parser.Dialect`):
    /// the converter writes no `#`, `[ ]` or `*` for a target whose dialect does not read it.
    pub dialect: crate::lex::Dialect,
}

/// One profile, compiled: shared by every reader of programs for that machine.
#[derive(Debug)]
pub struct Machine {
    /// What the checker reads (formats, codes, checks, limits, modal settings).
    pub check: Arc<Config>,
    pub control: Control,
    /// The language of the control's statements (Fanuc and Haas: Custom Macro B).
    pub family: Family,
    pub lathe: bool,
    /// A Fanuc or Haas lathe: G98/G99 are feed per minute and per revolution, G50 S clamps the
    /// spindle (G50 X Z sets the coordinate system), and X is a diameter.
    pub fanuc_lathe: bool,
    /// The roles of P, Q and R as the profile states them (None: unstated).
    pub pqr: [Option<Role>; 3],
    pub dwell_formats: Vec<(u8, WordFormat)>,
    pub inch_code: String,
    pub metric_code: String,
    pub increment_digits: [u32; 2],
    /// The codes the profile lists, with their keys and functions ([`MachineSpec::meanings`]).
    pub meanings: Vec<(String, String, String)>,
    /// Every code the machine's table assigns, its own list's and its base table's, named as
    /// [`differing_codes`] names them, with its group ("" for one of its own list), sorted by
    /// code: made once per profile, for the comparisons between families.
    listed: CodeList,
    /// What the profile's dialect reads ([`MachineSpec::dialect`]).
    pub dialect: crate::lex::Dialect,
}

impl Machine {
    /// Compile a profile's spec. The family rules are decided here and nowhere else.
    pub fn new(spec: MachineSpec) -> Machine {
        let family = spec.control.family();
        let fanuc_lathe = family == Family::MacroB && spec.lathe;
        // G code system B and C are read by system A's numbers (meaning::GCodeSystem): the
        // reset codes and the units codes too (system C's G70/G71 are A's G20/G21)
        let g_system = if fanuc_lathe {
            crate::meaning::GCodeSystem::from_name(&spec.g_code_system)
        } else {
            crate::meaning::GCodeSystem::A
        };
        let mut modal = ModalSettings {
            reset: spec.reset.clone(),
            inch: g_system.to_a(spec.inch),
            metric: g_system.to_a(spec.metric),
            default_units: spec.default_units,
            family,
            fanuc_lathe,
            // LinuxCNC's G80 leaves no motion mode in force (rs274ngc)
            g80_clears_motion: family == Family::LinuxCnc,
            // Sinumerik's G70/G71 leave the feed in the basic system; G700/G710 set it too
            sinumerik_units: family == Family::Sinumerik,
            // Fanuc and Haas mills read G02/G03 I J K by the centre codes of their own table
            centre_codes: family == Family::MacroB && !fanuc_lathe,
            heidenhain: family == Family::Heidenhain,
            // an Okuma lathe's G80-G89 are the LAP's contours and cycle calls
            lap: family == Family::Okuma && spec.lathe,
            g92_clamps: !(spec.control == Control::Haas
                || matches!(family, Family::Okuma | Family::LinuxCnc)),
            units_kept_at_end: spec.units_kept_at_end,
            dwell: crate::word::dwell_words(family, fanuc_lathe),
            arc_radius: crate::word::arc_radius(family, spec.lathe),
            // a control family's table is its own list: a number it does not hold (or marks
            // unassigned) is no code of that control and changes no mode
            lacks_g: if family == Family::Iso {
                Vec::new()
            } else {
                spec.facts
                    .g_codes
                    .iter()
                    .map(|c| {
                        c.as_ref().is_none_or(|c| {
                            matches!(
                                c.status,
                                crate::check::Status::Unassigned | crate::check::Status::Permanent
                            )
                        })
                    })
                    .collect()
            },
            g_system,
            haas: spec.control == Control::Haas,
        };
        modal.reset = spec.reset.iter().map(|&g| modal.read_g(g)).collect();
        let check = Config {
            facts: spec.facts,
            family,
            // A control of a family alarms on a G code its table lacks; ISO 6983-1 leaves codes
            // unassigned for individual use (a warning). M codes go to the PLC: a warning.
            alarm_g: spec.unknown_g_alarms.unwrap_or(family != Family::Iso),
            alarm_m: spec.unknown_m_alarms.unwrap_or(false),
            // X is a diameter on a Fanuc, Haas or Okuma lathe
            diameter: fanuc_lathe || (family == Family::Okuma && spec.lathe),
            // the checker reads an unstated role as "other": neither a length nor a parameter
            pqr: spec.pqr.map(|role| role.unwrap_or(Role::Other)),
            pointed_numbers: spec.control == Control::Haas,
            haas: spec.control == Control::Haas,
            turning: crate::check::turning_codes(&spec.meanings),
            modal,
        };
        let listed = listed_codes(&spec.meanings, &check).into();
        Machine {
            listed,
            check: Arc::new(check),
            control: spec.control,
            family,
            lathe: spec.lathe,
            fanuc_lathe,
            pqr: spec.pqr,
            dwell_formats: spec.dwell_formats,
            inch_code: spec.inch_code,
            metric_code: spec.metric_code,
            increment_digits: spec.increment_digits,
            meanings: spec.meanings,
            dialect: spec.dialect,
        }
    }

    /// X is a diameter (a Fanuc or Haas lathe): an arc in G18 has X/2 as its coordinate.
    pub fn diameter(&self) -> bool {
        self.check.diameter
    }

    pub fn units_kept_at_end(&self) -> bool {
        self.check.modal.units_kept_at_end
    }

    /// The diff and verify reader's settings. Its modal state keeps what the values are read
    /// in, not the checker's family rules of motion (G80, centre codes, HEIDENHAIN's).
    pub fn read_settings(&self) -> ReadSettings {
        let c = &self.check;
        ReadSettings {
            formats: c.formats.clone(),
            formats_inch: c.formats_inch.clone(),
            explicit: c.explicit,
            increments: c.increments.clone(),
            pqr_length: self.pqr.map(|role| role == Some(Role::Length)),
            pqr_unstated: self
                .pqr
                .map(|role| matches!(role, None | Some(Role::Parameter))),
            m_listed: (self.family != Family::Iso).then(|| self.listed.clone()),
            family: self.family,
            lathe: self.lathe,
            fanuc_lathe: self.fanuc_lathe,
            modal: ModalSettings {
                g80_clears_motion: false,
                centre_codes: false,
                heidenhain: false,
                lap: false,
                ..c.modal.clone()
            },
            inch_code: self.inch_code.clone(),
            metric_code: self.metric_code.clone(),
            program_number: c.program_number,
        }
    }

    /// The roles of P, Q and R for the converter: an unstated role is a parameter there.
    pub fn convert_roles(&self) -> [Role; 3] {
        self.pqr.map(|role| role.unwrap_or(Role::Parameter))
    }
}

/// What a conversion is asked to do, beyond the two machines.
#[derive(Debug, Clone)]
pub struct ConvertOptions {
    /// The units to convert to; None keeps them.
    pub units: Option<Units>,
    pub rounding: Rounding,
    pub spacing: Spacing,
    pub allow_unconverted: bool,
    /// The parameter analysis of the file; None when the program has no parameters.
    pub parameters: Option<std::sync::Arc<ParameterClasses>>,
    /// [`crate::convert::ConvertConfig::read_units`].
    pub read_units: Vec<(usize, String, Units)>,
    /// The source machine was guessed from the program (no `--from`).
    pub source_detected: bool,
    /// The units the source machine is set to were given (`--from-units`), not taken from
    /// its profile.
    pub source_units_given: bool,
    /// [`crate::convert::ConvertConfig::upper_case`]: the source's dialect reads lower case,
    /// the target's does not.
    pub upper_case: bool,
}

impl Machine {
    /// The converter's settings from the machine a program was written for (`self`) to
    /// `target`.
    pub fn convert_to(&self, target: &Machine, options: ConvertOptions) -> ConvertConfig {
        let (source, out) = (&self.check, &target.check);
        ConvertConfig {
            src_formats: source.formats.clone(),
            src_formats_inch: source.formats_inch.clone(),
            out_formats_inch: out.formats_inch.clone(),
            explicit_in: source.explicit,
            src_increments: source.increments.clone(),
            dst_increments: out.increments.clone(),
            src_modal: source.modal.clone(),
            pqr: self.convert_roles(),
            family: self.family,
            lathe: self.lathe,
            target_family: target.family,
            target_dialect: target.dialect,
            // the roles of a cycle's words come from the source's cycle table: the target reads
            // them alike only on the same control (Fanuc and Haas write lathe cycles apart) and
            // the same kind of machine
            same_cycle_table: self.control == target.control && self.lathe == target.lathe,
            target_g_system: target
                .check
                .modal
                .fanuc_lathe
                .then_some(target.check.modal.g_system),
            target_data_input: crate::dialect::has_data_input(
                target.family,
                target.control == Control::Haas,
            ),
            fanuc_haas: match (self.control, target.control) {
                (Control::Haas, Control::Fanuc) => Some(true),
                (Control::Fanuc, Control::Haas) => Some(false),
                _ => None,
            },
            m98_repeats: {
                let repeats = |c: Control| match c {
                    Control::Fanuc => Some(true),
                    Control::Haas | Control::LinuxCnc => Some(false),
                    _ => None,
                };
                repeats(self.control).zip(repeats(target.control))
            },
            cycle_repeats: {
                let letter = |c: Control| c.family().cycle_repeat_letter(c == Control::Haas);
                letter(self.control).zip(letter(target.control))
            },
            source_detected: options.source_detected,
            src_units_given: options.source_units_given,
            upper_case: options.upper_case,
            target_ngc: target.control == Control::Haas,
            target_units_kept: target.units_kept_at_end(),
            src_increment: self.increment_digits,
            out_increment: target.increment_digits,
            program_number: source.program_number,
            target_past_sequence: out.past_sequence,
            target_g80_clears_motion: out.modal.g80_clears_motion,
            // 0 where the target reads no radius: its R a parameter (`checks.pqr`, an ISO
            // 6983-1 profile's), as its check reads an arc
            colon_stops: out.facts.colon_stop && !source.facts.colon_stop,
            lathe_tool_offset: source.modal.fanuc_lathe && !out.modal.fanuc_lathe,
            // (an ISO 6983-1 source, the profile a conversion takes without --from too, says
            // nothing of how its machine reads X)
            x_diameter: !self.lathe
                && self.control != Control::Iso
                && !source.diameter
                && out.diameter,
            // (an ISO 6983-1 lathe target says nothing of how its machine reads X)
            x_radius: source.diameter && !out.diameter && !target.lathe,
            x_lathe_fanuc: if self.lathe {
                self.control == Control::Fanuc
            } else {
                target.control == Control::Fanuc
            },
            // (an ISO 6983-1 profile without a `reset` list resets to clause 14's G94, a lathe
            // too: 14.4)
            reset_feed: (reset_feed(&source.modal) != reset_feed(&out.modal))
                .then(|| [reset_feed(&source.modal), reset_feed(&out.modal)]),
            // (SINUMERIK and HEIDENHAIN read the % line as the program's name; every other
            // target but a FANUC reads the text, whatever the source did with it: review 51,
            // F16, a Haas source's `% O1000 (TEXT)` for a Haas)
            percent_words_read: !crate::dialect::skips_leader(out.family, out.haas)
                && !matches!(out.family, Family::Sinumerik | Family::Heidenhain),
            leader_skipped: crate::dialect::skips_leader(source.family, source.haas),
            target_arc_radius: if out.modal.arc_radius == b'R' && out.pqr[2] != Role::Length {
                0
            } else {
                out.modal.arc_radius
            },
            differing_codes: if self.control == target.control && self.lathe == target.lathe {
                Vec::new()
            } else {
                let same_family = self.control.family() == target.control.family();
                let mut codes = differing_codes(source, out, same_family);
                codes.extend(own_meanings(self, target));
                let found = meaning_differences(self, target)
                    .into_iter()
                    .filter(|(code, ..)| !codes.iter().any(|c| &c.0 == code))
                    .collect::<Vec<_>>();
                codes.extend(found);
                let others = target_only(self, target)
                    .into_iter()
                    .filter(|(code, ..)| !codes.iter().any(|c| &c.0 == code))
                    .collect::<Vec<_>>();
                codes.extend(others);
                codes
            },
            one_group_codes: if self.control == target.control && self.lathe == target.lathe {
                Vec::new()
            } else {
                one_group_codes(source, out)
            },
            listed_codes: either_lists(self, target),
            target_alarm_g: out.alarm_g,
            src_listed: (self.family != Family::Iso).then(|| self.listed.clone()),
            src_decimal_g: (self.family != Family::Iso)
                .then(|| source.g_decimal.iter().map(|(c, _)| c.clone()).collect()),
            ijk: (source.ijk != out.ijk).then(|| (ijk_reading(source.ijk), ijk_reading(out.ijk))),
            out_formats: out.formats.clone(),
            dwell_formats: target.dwell_formats.clone(),
            feed_rev_formats: out.feed_rev_formats.clone(),
            explicit_out: out.explicit,
            inch_code: target.inch_code.clone(),
            metric_code: target.metric_code.clone(),
            target_units: out.modal.default_units,
            units: options.units,
            rounding: options.rounding,
            spacing: options.spacing,
            allow_unconverted: options.allow_unconverted,
            parameters: options.parameters,
            read_units: options.read_units,
        }
    }
}

/// The feed mode of a control's reset state ([`crate::modal::feed_mode_code`]'s numbers): the last feed
/// mode code of its reset list (a FANUC lathe's G99, an Okuma lathe's G95, clause 14's G94),
/// per minute (94) where the list has none (HEIDENHAIN's).
pub fn reset_feed(modal: &crate::modal::ModalSettings) -> i64 {
    modal
        .reset
        .iter()
        .filter_map(|&g| crate::modal::feed_mode_code(modal.fanuc_lathe, g))
        .next_back()
        .unwrap_or(94)
}

/// The G and M codes two profiles both list in modal groups that differ, as the profiles' `codes`
/// tables give them (`duration`): the same number does something else on the target. A code
/// of no modal group ("TBO", "non-modal") and the spellings of one group that the profiles
/// write apart ("cycle" and "motion": FANUC's canned cycles are in the group of G00-G03,
/// LinuxCNC's "cycle cancel") are the same.
pub fn differing_codes(
    source: &Config,
    target: &Config,
    m_codes: bool,
) -> Vec<(String, String, String)> {
    let group = |d: &str| {
        match d {
            "" | "TBO" | "non-modal" => "",
            "cycle" | "motion" | "cycle cancel" => "motion",
            other => other,
        }
        .to_string()
    };
    // a code a profile takes from the ISO 6983 table names its group by the standard's
    // letter (a, j): another vocabulary, not another meaning
    let differ = |a: &str, b: &str| a.len() != 1 && b.len() != 1 && group(a) != group(b);
    let mut out = Vec::new();
    // (a code the source's table lacks: a SINUMERIK's G28, which its check names TG307)
    let source_group = |codes: &[Option<crate::check::Code>], n: usize| match codes
        .get(n)
        .and_then(Option::as_ref)
    {
        Some(a) => group_name(&a.duration),
        None => "no code of its profile's table".to_string(),
    };
    for n in 0..target.g_codes.len() {
        if let Some(why) = target_refuses(target, b'G', n) {
            out.push((n.to_string(), source_group(&source.g_codes, n), why));
        }
    }
    for n in 0..target.m_codes.len() {
        if let Some(why) = target_refuses(target, b'M', n) {
            out.push((format!("M{n}"), source_group(&source.m_codes, n), why));
        }
    }
    let refused = |letter: u8, n: usize| target_refuses(target, letter, n).is_some();
    for (n, (a, b)) in source.g_codes.iter().zip(&target.g_codes).enumerate() {
        if refused(b'G', n) {
            continue;
        }
        if let (Some(a), Some(b)) = (a, b) {
            // a code the table leaves unassigned (ISO 6983's spare numbers) is no meaning
            let spare = |c: &crate::check::Code| c.status == crate::check::Status::Unassigned;
            if !spare(a) && !spare(b) && differ(&a.duration, &b.duration) {
                out.push((
                    n.to_string(),
                    group_name(&a.duration),
                    group_name(&b.duration),
                ));
            }
        }
    }
    // M codes likewise, named with their letter (`M97`), between controls of one family whose
    // profiles name their M groups alike (`m_codes`): Haas's M97 local subprogram call (no
    // group) is FANUC's interrupt type custom macro off (group "interrupt macro"). (Between
    // families the profiles group M codes in their own words: FANUC's M06 "TBO", LinuxCNC's
    // "tool change", the same function.)
    let m_pairs = source
        .m_codes
        .iter()
        .zip(&target.m_codes)
        .take(if m_codes { 100 } else { 0 });
    for (n, (a, b)) in m_pairs.enumerate() {
        if refused(b'M', n) {
            continue;
        }
        if let (Some(a), Some(b)) = (a, b) {
            let spare = |c: &crate::check::Code| c.status == crate::check::Status::Unassigned;
            if !spare(a) && !spare(b) && differ(&a.duration, &b.duration) {
                out.push((
                    format!("M{n}"),
                    group_name(&a.duration),
                    group_name(&b.duration),
                ));
            }
        }
    }
    // a decimal code the source lists and the target does not (LinuxCNC's G43.1 dynamic tool
    // length offset or G90.1 to a Haas mill): the target alarms on it or takes its number for
    // another code's, whose block then means something else; never the source's function
    for (code, a) in &source.g_decimal {
        match target.g_decimal.iter().find(|(c, _)| c == code) {
            Some((_, b)) if differ(&a.duration, &b.duration) => out.push((
                code.clone(),
                group_name(&a.duration),
                group_name(&b.duration),
            )),
            Some(_) => {}
            None => out.push((
                code.clone(),
                group_name(&a.duration),
                "no such code (its profile's code list has none)".to_string(),
            )),
        }
    }
    out
}

/// Why the target's check refuses code `n` of `letter` that its table holds: TG303 where an
/// ISO 6983-1 table leaves it permanently unassigned (ISO 6983-1 Annex E: G28 of the
/// standard's table is no code of the standard, whatever a FANUC or a SINUMERIK does with its
/// number). Whatever the source's table says of the code (a SINUMERIK's `G28`, which its own
/// table lacks), the target refuses the block, so the conversion does. None for every other
/// code, and for one the target's table lacks: a code the source lists and the target does
/// not is refused by [`target_only`]'s and `differing_codes`' lists ("no such code"), one
/// neither lists by the converter where the target alarms on it (TG306:
/// `ConvertConfig::target_alarm_g`), and carried with a note where it does not.
fn target_refuses(target: &Config, letter: u8, n: usize) -> Option<String> {
    let codes = if letter == b'G' {
        &target.g_codes
    } else {
        &target.m_codes
    };
    let code = codes.get(n).and_then(Option::as_ref)?;
    (target.family == Family::Iso && code.status == crate::check::Status::Permanent).then(|| {
        "a code the target's ISO 6983-1 table leaves permanently unassigned (Annex E)".to_string()
    })
}

/// The pairs of G codes (the lower number first) that the target's table puts in one modal
/// group and the source's in two (both modal there), with the target's group: written in one
/// block, the source runs both, the target refuses the block (TG304 of its check; ISO 6983-1
/// Annex E, "two codes of one modal group"). A Haas's `G49 G40` (tool length offset cancel,
/// cutter compensation cancel) is one group (d) of ISO 1056's table (pm322-eia).
fn one_group_codes(source: &Config, target: &Config) -> Vec<(i64, i64, String)> {
    fn modal(c: &Option<crate::check::Code>) -> Option<&str> {
        c.as_ref()
            .filter(|c| {
                !matches!(c.duration.as_str(), "" | "TBO" | "non-modal")
                    && !matches!(
                        c.status,
                        crate::check::Status::Permanent | crate::check::Status::Unassigned
                    )
            })
            .map(|c| c.duration.as_str())
    }
    let both: Vec<(usize, &str, &str)> = source
        .g_codes
        .iter()
        .zip(&target.g_codes)
        .enumerate()
        .filter_map(|(n, (a, b))| Some((n, modal(a)?, modal(b)?)))
        .collect();
    let mut out = Vec::new();
    for (i, &(n, a, b)) in both.iter().enumerate() {
        for &(m, other_a, other_b) in &both[i + 1..] {
            if b == other_b && a != other_a {
                out.push((n as i64, m as i64, b.to_string()));
            }
        }
    }
    out
}

/// A modal group as a refusal names it: `group "motion"`, or no modal group.
fn group_name(g: &str) -> String {
    if matches!(g, "" | "TBO" | "non-modal") {
        "no modal group".to_string()
    } else {
        format!("group \"{g}\"")
    }
}

/// Codes a control numbers as the ISO 6983 and FANUC tables do but gives a function of its own,
/// in the same modal group, so that [`differing_codes`] cannot tell them apart: the control, a
/// lathe or not, the code (`71`, `M98`), what it does there, and what the number does on the
/// other families' profiles that list it. Sources: Okuma OSP-P200L Programming Manual (5238-E):
/// G32/G33 the face and longitudinal thread cutting cycles (retract and return), G71/G72 the
/// compound (multi-pass) thread cutting cycles; FANUC/Haas lathe G32 a single thread cutting
/// move, G71/G72 the stock removal cycles; ISO 6983, LinuxCNC and SINUMERIK G33 a single thread
/// cutting move; OSP mill (4203-E, List of M Codes) M98 oil mist cycle mode on, FANUC/Haas M98
/// the subprogram call (docs/convert.md, "Codes of another meaning").
const OWN_MEANINGS: &[(Control, bool, &str, &str, &str)] = &[
    (
        Control::Okuma,
        true,
        "32",
        "a face thread cutting cycle",
        "a single thread cutting move",
    ),
    (
        Control::Okuma,
        true,
        "33",
        "a longitudinal thread cutting cycle",
        "a single thread cutting move",
    ),
    (
        Control::Okuma,
        true,
        "71",
        "a longitudinal multi-pass thread cutting cycle",
        "a stock removal (roughing) cycle in turning",
    ),
    (
        Control::Okuma,
        true,
        "72",
        "a face multi-pass thread cutting cycle",
        "a stock removal (roughing) cycle in facing",
    ),
    (
        Control::Okuma,
        false,
        "M98",
        "oil mist cycle mode on",
        "a subprogram call",
    ),
];

/// The codes of [`OWN_MEANINGS`] between `source` and `target` (machines of two controls or
/// kinds): a code one of them redefines that the other's profile lists too, as
/// [`differing_codes`] gives them (the code, the source's meaning, the target's), quoted.
fn own_meanings(source: &Machine, target: &Machine) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    for &(control, lathe, code, own, other) in OWN_MEANINGS {
        let on = |m: &Machine| m.control == control && m.lathe == lathe;
        // a control that takes the number from the ISO 6983-1 table (iso-lathe's G71, metric
        // dimensions) does what that table says, no FANUC cycle
        let iso = |m: &Machine| m.control == Control::Iso && code != "33";
        let pair = match (on(source), on(target)) {
            (true, false) if iso(target) => (own, "the ISO 6983-1 table's code of that number"),
            (true, false) => (own, other),
            (false, true) if iso(source) => ("the ISO 6983-1 table's code of that number", own),
            (false, true) => (other, own),
            _ => continue,
        };
        if lists(source, code) && lists(target, code) {
            out.push((
                code.to_string(),
                format!("{:?}", pair.0),
                format!("{:?}", pair.1),
            ));
        }
    }
    out
}

/// The codes whose function differs between two profiles by their own code lists
/// (`codes.G47`, with its `function` and `meaning` key, docs/profiles.md "Code meanings"), as
/// [`differing_codes`] gives them: the code, the source's function and the target's, as their
/// profiles word them, quoted.
///
/// - Both profiles give the code a meaning key and the keys differ: the same number does
///   another thing on the target (Haas's `G47` text engraving, FANUC's tool offset double
///   increase), which the modal groups cannot show where both put it in the same group.
/// - Between two control families ([`families_differ`]), a G code one of them gives no key is
///   not known to do one thing on both: refused unless the two functions are one text
///   ([`one_function`]). LinuxCNC's `G64 P` (blending within a tolerance) is FANUC's cutting
///   mode in the same group; Okuma's `G15 H` a work system, FANUC's polar coordinates off.
/// - Between two control families, a G code the source lists and the target's own list lacks:
///   the target alarms on it, or reads it by a table the program was not written for (LinuxCNC
///   takes an Okuma `G15 H1` for polar coordinates off): refused, as a decimal code is.
///
/// M codes are compared the same way where the source's profile lists the code itself (its
/// `[codes]`, with a function its control's manual gives): LinuxCNC's `M64 P0` (a digital
/// output on) is a Haas's user relay 4 cleared, a Haas's `M96 P Q` (jump if no input) no code
/// of an Okuma. A code the target's whole table lacks (unassigned or absent) is refused too:
/// FANUC and Haas hand an M code they do not decode to the machine builder's ladder (the 0i-F
/// operator's manual, "Auxiliary function"), LinuxCNC and a SINUMERIK alarm or hand it to the
/// PLC, so the source's machine action would not happen, or another one would. An M code of
/// the source's base table (the ISO 6983-1 one it builds on) is the standard's, carried. (The
/// other way, a code only the target lists, is [`target_only`]'s; a lathe cycle of one key
/// that each control writes in its own form, [`OWN_FORMS`], is refused here.)
fn meaning_differences(source: &Machine, target: &Machine) -> Vec<(String, String, String)> {
    let apart = families_differ(source, target);
    // an M code the target's table assigns, its own list or the base table it builds on
    let target_has_m = |code: &str| {
        let found = code[1..]
            .parse::<usize>()
            .ok()
            .and_then(|n| target.check.m_codes.get(n));
        matches!(found, Some(Some(c)) if c.status != crate::check::Status::Unassigned)
    };
    source
        .meanings
        .iter()
        .filter_map(|(code, key, function)| {
            let g = !code.starts_with('M');
            let Some((_, other_key, other)) = target.meanings.iter().find(|m| &m.0 == code) else {
                return (apart && (g || !target_has_m(code))).then(|| {
                    (
                        code.clone(),
                        format!("{function:?}"),
                        "no such code (its profile's code list has none)".to_string(),
                    )
                });
            };
            if !key.is_empty() && key == other_key && own_form(key, source.control, target.control)
            {
                let form = |control: Control, function: &str| {
                    format!(
                        "{function:?} with its words in {}'s form",
                        control_name(control)
                    )
                };
                return Some((
                    code.clone(),
                    form(source.control, function),
                    form(target.control, other),
                ));
            }
            let differ = if !key.is_empty() && !other_key.is_empty() {
                other_key != key
            } else {
                apart && !one_function(function, other)
            };
            differ.then(|| (code.clone(), format!("{function:?}"), format!("{other:?}")))
        })
        .collect()
}

/// Whether a machine's code table assigns `code`, named as [`differing_codes`] names it (`12`,
/// `91.1`, `M39`): its profile's own list or the base table it builds on (ISO 6983-1's M07
/// coolant), a code it marks unassigned left out.
fn lists(m: &Machine, code: &str) -> bool {
    m.listed
        .binary_search_by(|(c, _)| c.as_str().cmp(code))
        .is_ok()
}

/// Every code a table assigns with the profile's own list (`meanings`), named as
/// [`differing_codes`] names them, with its group ("" for one of the profile's own list),
/// sorted by code ([`Machine::listed`]).
fn listed_codes(meanings: &[(String, String, String)], c: &Config) -> Vec<(String, String)> {
    let assigned = |c: &&crate::check::Code| c.status != crate::check::Status::Unassigned;
    let mut out: Vec<(String, String)> = meanings
        .iter()
        .map(|(code, ..)| (code.clone(), String::new()))
        .collect();
    let g = c.g_codes.iter().enumerate().filter_map(|(n, code)| {
        code.as_ref()
            .filter(assigned)
            .map(|code| (n.to_string(), code.duration.clone()))
    });
    let m_codes = c.m_codes.iter().enumerate().filter_map(|(n, code)| {
        code.as_ref()
            .filter(assigned)
            .map(|code| (format!("M{n}"), code.duration.clone()))
    });
    let decimal = c
        .g_decimal
        .iter()
        .filter(|(_, code)| assigned(&code))
        .map(|(n, code)| (n.clone(), code.duration.clone()));
    out.extend(g.chain(m_codes).chain(decimal));
    // (the own list first: a stable sort keeps it before the table's entry of the same code)
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out.dedup_by(|a, b| a.0 == b.0);
    out
}

/// Between two control families, the codes the target's table assigns and the source's does
/// not, as [`differing_codes`] gives them. A G code the source's table lacks alarms there (or is
/// an option its profile does not list); an M code it lacks goes to the machine builder's ladder
/// (the 0i-F operator's manual, "Auxiliary function"; Haas and SINUMERIK hand theirs to the PLC
/// too). On the target the number runs the target's own function: FANUC `M39` (a grinder
/// builder's code) is a Haas's "rotate tool turret", `G12` a Haas's circular pocket milling.
fn target_only(source: &Machine, target: &Machine) -> Vec<(String, String, String)> {
    if !families_differ(source, target) {
        return Vec::new();
    }
    target
        .listed
        .iter()
        .filter(|(code, _)| !lists(source, code))
        .map(|(code, group)| {
            let own = target.meanings.iter().find(|m| &m.0 == code);
            let function = match own {
                Some((_, _, function)) => format!("{function:?}"),
                None => format!(
                    "its code table's code of that number ({})",
                    group_name(group)
                ),
            };
            let source_side = if code.starts_with('M') {
                "the machine builder's M function, handed to its PLC (its profile lists no such \
                 code)"
            } else {
                "an alarm, or an option (its profile lists no such code)"
            };
            (code.clone(), source_side.to_string(), function)
        })
        .collect()
}

/// Between two control families, the codes each machine's table assigns ([`Machine::listed`],
/// shared, not copied): a G or M code outside both is no function tapegate knows on either
/// control (the machine builder's M code, a G code of an option neither profile lists),
/// carried with a note ([`crate::convert::ConvertConfig::listed_codes`]).
fn either_lists(source: &Machine, target: &Machine) -> Option<[CodeList; 2]> {
    families_differ(source, target).then(|| [source.listed.clone(), target.listed.clone()])
}

/// A lathe's multiple repetitive cycles: one function on each control that has them (one
/// meaning key in their profiles), whose words each control writes in a form of its own, and
/// the controls that write one form. FANUC 0i-TF (B-64604EN, "Multiple repetitive cycle
/// (G70-G76)", standard format): two blocks, `G71 U(depth of cut) R(retract)` then `G71 P Q
/// U(X finishing allowance) W F`, and alike G72 `W R` / `P Q U W F`, G73 `U W R(divisions)` /
/// `P Q U W F`, G74 and G75 `R` / `X Z P Q R F` (P Q the moves in increments), G76 `P(m r a) Q
/// R` / `X Z R P Q F`. Haas lathe operator's manual (G-codes): one block, `G71 P Q U W D F`
/// (U the X finishing allowance, D the depth of cut), G72 `P Q U W D F`, G73 `P Q U W I K D F`
/// (D the number of passes), G74 and G75 `X Z I K D F`, G76 `X Z K D F A P Q`. LinuxCNC G-code
/// reference (G70-G72 lathe cycles, G76): `G71 Q(the contour's o-word subroutine) X Z D I R`,
/// `G70 Q X Z D L`, `G76 P Z I J R K Q H E L`. Carried between two controls, `G71 U2.` is a
/// FANUC's depth of cut and a Haas's finishing allowance; so a cycle of these keys is refused
/// between two controls unless both write the one form: FANUC's and Haas's `G70 P Q`, the
/// finishing cycle over blocks P to Q, read alike.
const OWN_FORMS: &[(&str, &[Control])] = &[
    ("finishing-cycle", &[Control::Fanuc, Control::Haas]),
    ("stock-removal-turning", &[]),
    ("stock-removal-facing", &[]),
    ("pattern-repeating", &[]),
    ("face-peck-cycle", &[]),
    ("grooving-cycle", &[]),
    ("multi-pass-threading", &[]),
];

/// Whether a code of meaning key `key` is written in another form on `target` than on
/// `source` ([`OWN_FORMS`]).
fn own_form(key: &str, source: Control, target: Control) -> bool {
    source != target
        && OWN_FORMS
            .iter()
            .any(|(k, one)| *k == key && !(one.contains(&source) && one.contains(&target)))
}

/// A control as a refusal names it.
fn control_name(control: Control) -> &'static str {
    match control {
        Control::Iso => "ISO 6983-1",
        Control::Fanuc => "FANUC",
        Control::Haas => "Haas",
        Control::LinuxCnc => "LinuxCNC",
        Control::Sinumerik => "SINUMERIK",
        Control::Heidenhain => "HEIDENHAIN",
        Control::Okuma => "Okuma OSP",
    }
}

/// Whether two machines are of two control families whose code lists say what each code
/// does: two controls (FANUC and Haas are two: their manuals number codes apart), neither of
/// them ISO 6983-1 (its codes are the standard's table, read the same by every profile that
/// takes them, and a program whose source is detected is read by it). One control's mill and
/// lathe are one family: their codes are compared by groups and keys as before.
fn families_differ(source: &Machine, target: &Machine) -> bool {
    source.control != target.control
        && source.control != Control::Iso
        && target.control != Control::Iso
}

/// Whether two profiles' functions of one code are one text, case and blanks aside: the only
/// sameness the converter takes without a meaning key.
fn one_function(a: &str, b: &str) -> bool {
    a.split_whitespace()
        .map(str::to_lowercase)
        .eq(b.split_whitespace().map(str::to_lowercase))
}

/// How a control reads an arc centre's I J K (`checks.ijk`), as a refusal names it.
pub fn ijk_reading(ijk: Ijk) -> &'static str {
    match ijk {
        Ijk::Incremental => "incremental from the start point",
        Ijk::Absolute => "absolute coordinates",
        Ijk::Quadrant => "sign-less (the control finds the quadrant)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::Ijk;
    use crate::dialect::PastFormat;

    fn spec(control: Control, lathe: bool) -> MachineSpec {
        MachineSpec {
            facts: ProfileFacts {
                formats: Vec::new(),
                formats_inch: None,
                feed_rev_formats: [None, None],
                explicit: true,
                increments: None,
                alignment: false,
                percent: true,
                classification: String::new(),
                table_name: "iso6983-1".into(),
                g_codes: Vec::new(),
                g_decimal: Vec::new(),
                m_codes: Vec::new(),
                program_number: Some(b'O'),
                colon_stop: false,
                tv_check: false,
                arc_tolerance: 0.01,
                arc_tolerance_relative: 0.0,
                ijk: Ijk::Incremental,
                repeatable: Vec::new(),
                m_classes: Vec::new(),
                max_index: 9,
                max_parameter: 999,
                read_only: None,
                past_decimals: PastFormat::Alarm,
                past_sequence: PastFormat::Alarm,
                code_words: Vec::new(),
                index_g: false,
                travel: Vec::new(),
                work_offsets: Vec::new(),
                feed_max: None,
                spindle_max: None,
                sample_limits: crate::check::SAMPLE_ALL,
                tool_max: None,
                rapid_rate: 5000.0,
                limit_units: Units::Metric,
            },
            control,
            lathe,
            dwell_formats: Vec::new(),
            unknown_g_alarms: None,
            unknown_m_alarms: None,
            pqr: [None, Some(Role::Length), Some(Role::Parameter)],
            reset: vec![0, 17, 90],
            inch: 20,
            metric: 21,
            inch_code: "G20".into(),
            metric_code: "G21".into(),
            default_units: Units::Metric,
            units_kept_at_end: true,
            increment_digits: [3, 4],
            meanings: Vec::new(),
            g_code_system: String::new(),
            dialect: crate::lex::Dialect {
                family: control.family(),
                ..Default::default()
            },
        }
    }

    /// Two profiles that give one code different meaning keys differ on it, named by their
    /// functions; a code only one of them keys, or both key alike, does not; the group
    /// comparison's finding and OWN_MEANINGS' naming come first.
    /// A conversion that changes nothing but the machine: no units, half-even rounding, the
    /// blanks kept.
    fn plain_options() -> ConvertOptions {
        ConvertOptions {
            units: None,
            rounding: Rounding::HalfEven,
            spacing: Spacing::Keep,
            allow_unconverted: false,
            parameters: None,
            read_units: Vec::new(),
            source_detected: false,
            source_units_given: false,
            upper_case: false,
        }
    }

    /// A machine of `control` whose code table gives each code (number, meaning key,
    /// function): the code tables the meaning tests compare.
    fn listed(control: Control, lathe: bool, codes: &[(&str, &str, &str)]) -> Machine {
        let mut s = spec(control, lathe);
        s.meanings = codes
            .iter()
            .map(|&(c, k, f)| (c.into(), k.into(), f.into()))
            .collect();
        Machine::new(s)
    }

    #[test]
    fn codes_of_two_meaning_keys_differ() {
        let keyed = |control, keys: &[(&str, &str, &str)]| listed(control, false, keys);
        let haas = keyed(
            Control::Haas,
            &[
                ("47", "text-engraving", "text engraving"),
                ("28", "reference-return", "return to machine zero point"),
                ("M98", "subprogram-call", "subprogram call"),
                ("73", "high-speed-peck-drilling", "peck"),
            ],
        );
        let fanuc = keyed(
            Control::Fanuc,
            &[
                (
                    "47",
                    "tool-offset-double-increase",
                    "tool offset double increase",
                ),
                (
                    "28",
                    "reference-return",
                    "automatic return to reference position",
                ),
            ],
        );
        let options = plain_options();
        let codes = haas.convert_to(&fanuc, options.clone()).differing_codes;
        let quoted = |s: &str| format!("{s:?}");
        assert_eq!(
            codes,
            [
                (
                    "47".to_string(),
                    quoted("text engraving"),
                    quoted("tool offset double increase")
                ),
                // an M code the source lists and the target's table lacks (this FANUC's
                // table is empty: its ladder would get it)
                (
                    "M98".to_string(),
                    quoted("subprogram call"),
                    "no such code (its profile's code list has none)".to_string()
                ),
                // a G code the target's own list lacks, between two control families
                (
                    "73".to_string(),
                    quoted("peck"),
                    "no such code (its profile's code list has none)".to_string()
                )
            ]
        );
        let back = fanuc.convert_to(&haas, options.clone()).differing_codes;
        assert_eq!(back[0].1, "\"tool offset double increase\"");
        // one machine: no code compared
        assert!(haas.convert_to(&haas, options).differing_codes.is_empty());
    }

    /// Between two control families a G or M code either profile gives no key is refused
    /// unless both functions are one text; one control's mill and lathe, and ISO 6983-1 (the
    /// standard's table, a detected source) compare keys alone, as before.
    #[test]
    fn unkeyed_codes_between_families_are_compared_by_function() {
        let linuxcnc = listed(
            Control::LinuxCnc,
            false,
            &[
                ("64", "", "path blending (P Q tolerances)"),
                ("17", "", "XY plane"),
                ("M8", "", "flood coolant on"),
            ],
        );
        let fanuc = listed(
            Control::Fanuc,
            false,
            &[
                ("64", "cutting-mode", "cutting mode"),
                ("17", "", "xy  plane"),
                ("M8", "", "coolant on"),
            ],
        );
        let codes = linuxcnc.convert_to(&fanuc, plain_options()).differing_codes;
        let names: Vec<&str> = codes.iter().map(|c| c.0.as_str()).collect();
        // G64: a key on one side only and two functions; G17: one text (case and blanks
        // aside); M8: two functions (flood coolant, the builder's coolant), as a G code
        assert_eq!(names, ["64", "M8"]);
        assert_eq!(codes[0].1, "\"path blending (P Q tolerances)\"");
        assert_eq!(codes[0].2, "\"cutting mode\"");
        // one control's lathe: not two families
        let fanuc_lathe = listed(Control::Fanuc, true, &[("64", "", "exact stop cancel")]);
        assert!(fanuc
            .convert_to(&fanuc_lathe, plain_options())
            .differing_codes
            .is_empty());
        // an ISO 6983-1 source: the standard's codes, compared by their groups
        let iso = listed(Control::Iso, false, &[("64", "", "continuous path")]);
        assert!(iso
            .convert_to(&fanuc, plain_options())
            .differing_codes
            .is_empty());
        // FANUC and Haas are two controls: their G10 and a lathe's G50 axis words differ
        let haas = listed(Control::Haas, false, &[]);
        assert_eq!(
            fanuc.convert_to(&haas, plain_options()).fanuc_haas,
            Some(false)
        );
        assert_eq!(
            haas.convert_to(&fanuc, plain_options()).fanuc_haas,
            Some(true)
        );
        assert_eq!(
            linuxcnc.convert_to(&fanuc, plain_options()).fanuc_haas,
            None
        );
    }

    /// Between two control families a code the target's table assigns and the source's lacks
    /// is refused: on the source it went to the builder's PLC (M) or alarmed (G), on the target
    /// it runs the target's function (FANUC `M39` a Haas's turret rotation). The source's base
    /// table counts as its list (ISO 6983-1's M07); a code neither lists is left to a note
    /// (`listed_codes`); one control's mill and lathe, and ISO 6983-1, compare as before.
    #[test]
    fn a_code_only_the_target_lists_is_refused_between_families() {
        let fanuc = listed(Control::Fanuc, false, &[("M8", "", "coolant on")]);
        let mut haas = spec(Control::Haas, false);
        haas.meanings = vec![
            ("M8".into(), String::new(), "coolant on".into()),
            ("M39".into(), String::new(), "rotate tool turret (T)".into()),
            (
                "12".into(),
                String::new(),
                "circular pocket milling CW".into(),
            ),
        ];
        // the base table's M07 (coolant no. 2) on both: carried
        let base = |m: &mut MachineSpec| {
            m.facts.m_codes = vec![None; 100];
            m.facts.m_codes[7] = Some(crate::check::Code {
                status: crate::check::Status::Assigned,
                duration: "coolant".into(),
            });
        };
        base(&mut haas);
        let haas = Machine::new(haas);
        let mut fanuc_base = spec(Control::Fanuc, false);
        fanuc_base.meanings = fanuc.meanings.clone();
        base(&mut fanuc_base);
        let fanuc_base = Machine::new(fanuc_base);
        let config = fanuc_base.convert_to(&haas, plain_options());
        let names: Vec<&str> = config
            .differing_codes
            .iter()
            .map(|c| c.0.as_str())
            .collect();
        assert_eq!(names, ["12", "M39"]);
        assert_eq!(
            config.differing_codes[1].1,
            "the machine builder's M function, handed to its PLC (its profile lists no such code)"
        );
        assert_eq!(config.differing_codes[1].2, "\"rotate tool turret (T)\"");
        assert_eq!(
            config.differing_codes[0].1,
            "an alarm, or an option (its profile lists no such code)"
        );
        assert_eq!(
            config.differing_codes[0].2,
            "\"circular pocket milling CW\""
        );
        // without the base table on the source, M07 is the target's alone: refused as well
        let config = fanuc.convert_to(&haas, plain_options());
        let names: Vec<&str> = config
            .differing_codes
            .iter()
            .map(|c| c.0.as_str())
            .collect();
        assert_eq!(names, ["12", "M39", "M7"]);
        assert_eq!(
            config.differing_codes[2].2,
            "its code table's code of that number (group \"coolant\")"
        );
        // every code either lists, for the note on the others
        let lists = fanuc_base.convert_to(&haas, plain_options()).listed_codes;
        let names = lists.map(|l| l.map(|l| l.iter().map(|c| c.0.clone()).collect::<Vec<_>>()));
        assert_eq!(
            names,
            Some([
                vec!["M7".into(), "M8".into()],
                vec!["12".into(), "M39".into(), "M7".into(), "M8".into()]
            ])
        );
        // one control's mill and lathe; ISO 6983-1: neither compared this way nor noted
        let fanuc_lathe = listed(Control::Fanuc, true, &[("M39", "", "a lathe's code")]);
        let same = fanuc.convert_to(&fanuc_lathe, plain_options());
        assert!(same.differing_codes.is_empty() && same.listed_codes.is_none());
        let iso = listed(Control::Iso, false, &[]);
        let iso = iso.convert_to(&haas, plain_options());
        assert!(iso.differing_codes.is_empty() && iso.listed_codes.is_none());
    }

    /// A lathe's multiple repetitive cycle keeps its key on FANUC, Haas and LinuxCNC, but each
    /// writes its words in a form of its own (FANUC's `G71 U R` / `G71 P Q U W F`, Haas's one
    /// block `G71 P Q U W D F`): refused between two controls, naming both forms; FANUC's and
    /// Haas's `G70 P Q` is one form, carried; LinuxCNC's `G70 Q` (an o-word) is not.
    #[test]
    fn lathe_cycles_written_in_another_form_are_refused() {
        let fanuc = listed(
            Control::Fanuc,
            true,
            &[
                ("70", "finishing-cycle", "finishing cycle (P Q)"),
                (
                    "71",
                    "stock-removal-turning",
                    "stock removal in turning (U R / P Q U W F)",
                ),
                ("76", "multi-pass-threading", "multiple threading cycle"),
            ],
        );
        let haas = listed(
            Control::Haas,
            true,
            &[
                ("70", "finishing-cycle", "finishing cycle (P Q)"),
                (
                    "71",
                    "stock-removal-turning",
                    "O.D./I.D. stock removal cycle (P Q U W D F)",
                ),
                (
                    "76",
                    "multi-pass-threading",
                    "threading cycle, multiple pass",
                ),
            ],
        );
        let linuxcnc = listed(
            Control::LinuxCnc,
            false,
            &[("70", "finishing-cycle", "lathe finishing cycle")],
        );
        for (from, to) in [(&fanuc, &haas), (&haas, &fanuc)] {
            let codes = from.convert_to(to, plain_options()).differing_codes;
            let names: Vec<&str> = codes.iter().map(|c| c.0.as_str()).collect();
            assert_eq!(names, ["71", "76"]);
        }
        let codes = fanuc.convert_to(&haas, plain_options()).differing_codes;
        assert_eq!(
            codes[0].1,
            "\"stock removal in turning (U R / P Q U W F)\" with its words in FANUC's form"
        );
        assert_eq!(
            codes[0].2,
            "\"O.D./I.D. stock removal cycle (P Q U W D F)\" with its words in Haas's form"
        );
        let codes = fanuc.convert_to(&linuxcnc, plain_options()).differing_codes;
        assert!(codes
            .iter()
            .any(|c| c.0 == "70" && c.2.contains("LinuxCNC's form")));
        // one control: its own form, whatever the kind of machine
        let fanuc_mill = listed(
            Control::Fanuc,
            false,
            &[("71", "stock-removal-turning", "another text")],
        );
        assert!(fanuc
            .convert_to(&fanuc_mill, plain_options())
            .differing_codes
            .is_empty());
    }

    #[test]
    fn family_rules_are_decided_once() {
        let lathe = Machine::new(spec(Control::Haas, true));
        assert!(lathe.fanuc_lathe && lathe.diameter() && lathe.check.modal.fanuc_lathe);
        assert!(!lathe.check.modal.centre_codes);
        let mill = Machine::new(spec(Control::Fanuc, false));
        assert!(!mill.fanuc_lathe && !mill.diameter() && mill.check.modal.centre_codes);
        assert!(mill.check.alarm_g && !mill.check.alarm_m);
        let iso = Machine::new(spec(Control::Iso, true));
        assert!(!iso.diameter() && !iso.check.alarm_g);
        assert!(
            Machine::new(spec(Control::LinuxCnc, false))
                .check
                .modal
                .g80_clears_motion
        );
        // Okuma OSP is a family of its own, by name as by control
        let okuma = Machine::new(spec(Control::from_name("okuma"), false));
        assert_eq!(
            (okuma.control, okuma.family),
            (Control::Okuma, Family::Okuma)
        );
        assert_eq!(okuma.check.family, Family::Okuma);
        assert!(!okuma.diameter() && !okuma.check.modal.lap);
        let okuma_lathe = Machine::new(spec(Control::Okuma, true));
        assert!(okuma_lathe.diameter() && okuma_lathe.check.modal.lap);
        assert!(!okuma_lathe.fanuc_lathe && !okuma_lathe.read_settings().modal.lap);
        // the arc's radius letter: an Okuma lathe's L (5238-E, P-26), R elsewhere; every
        // reader has it
        assert_eq!(okuma_lathe.check.modal.arc_radius, b'L');
        assert_eq!(okuma_lathe.read_settings().modal.arc_radius, b'L');
        let to_itself = okuma_lathe.convert_to(&okuma_lathe, plain_options());
        assert_eq!(
            (to_itself.src_modal.arc_radius, to_itself.target_arc_radius),
            (b'L', b'L')
        );
        for m in [&okuma, &mill, &lathe, &iso] {
            assert_eq!(m.check.modal.arc_radius, b'R');
        }
        let mut alarms = spec(Control::Iso, false);
        alarms.unknown_g_alarms = Some(true);
        alarms.unknown_m_alarms = Some(true);
        let alarms = Machine::new(alarms);
        assert!(alarms.check.alarm_g && alarms.check.alarm_m);
    }

    #[test]
    fn each_reader_sees_the_roles_it_reads() {
        let m = Machine::new(spec(Control::Fanuc, false));
        assert_eq!(m.check.pqr, [Role::Other, Role::Length, Role::Parameter]);
        assert_eq!(
            m.convert_roles(),
            [Role::Parameter, Role::Length, Role::Parameter]
        );
        let read = m.read_settings();
        assert_eq!(read.pqr_length, [false, true, false]);
        assert_eq!(read.pqr_unstated, [true, false, true]);
        assert!(!read.modal.centre_codes && m.check.modal.centre_codes);
    }
}
