//! What the checker's unit tests share: a profile built in code (the built-in `iso-mill` as
//! `postproc.state.core_config` gives it to the core) and a program run through a [`Checker`].

use std::sync::Arc;

use super::{Checker, Code, Config, Finding, Ijk, ProfileFacts, Status};
use crate::decimal::Dec;
use crate::lex::{Dialect, Family};
use crate::modal::{ModalSettings, Units};
use crate::rules::{Rule, Selection};
use crate::word::Role;
use crate::wordformat::{WordFormat, Zeros};

fn format(address: u8, before: u32, after: u32, signed: bool, decimal: bool) -> WordFormat {
    WordFormat {
        address,
        before,
        after,
        signed,
        zeros: Zeros::Leading,
        decimal,
    }
}

pub(super) fn code(status: Status, duration: &str) -> Option<Code> {
    Some(Code {
        status,
        duration: duration.into(),
    })
}

/// The ISO 6983-1 G code table (`formats.codes`), as far as the tests read it.
fn g_codes() -> Vec<Option<Code>> {
    let mut table: Vec<Option<Code>> = (0..1000).map(|_| code(Status::Unassigned, "")).collect();
    let assigned = [
        (0, "a"),
        (1, "a"),
        (2, "a"),
        (3, "a"),
        (4, "TBO"),
        (6, "a"),
        (17, "b"),
        (18, "b"),
        (19, "b"),
        (33, "a"),
        (40, "d"),
        (41, "d"),
        (42, "d"),
        (80, "e"),
        (94, "k"),
        (95, "k"),
        (96, "l"),
    ];
    for (n, group) in assigned {
        table[n] = code(Status::Assigned, group);
    }
    let conditional = [
        (34, "a"),
        (35, "a"),
        (43, "d"),
        (44, "d"),
        (53, "f"),
        (70, "m"),
        (71, "m"),
        (90, "j"),
        (91, "j"),
        (92, "TBO"),
        (93, "k"),
        (97, "l"),
    ];
    for (n, group) in conditional {
        table[n] = code(Status::Conditional, group);
    }
    for entry in &mut table[54..60] {
        *entry = code(Status::Conditional, "f");
    }
    for entry in &mut table[81..90] {
        *entry = code(Status::Assigned, "e");
    }
    for range in [25..30, 36..40] {
        for entry in &mut table[range] {
            *entry = code(Status::Permanent, "");
        }
    }
    table
}

/// The ISO 6983-1 M code table, as far as the tests read it.
fn m_codes() -> Vec<Option<Code>> {
    let mut table: Vec<Option<Code>> = (0..100).map(|_| code(Status::Unassigned, "")).collect();
    for (n, group) in [
        (0, "TBO"),
        (1, "TBO"),
        (2, "TBO"),
        (3, "spindle"),
        (4, "spindle"),
        (5, "spindle"),
        (6, "TBO"),
        (8, "coolant"),
        (9, "coolant"),
        (30, "TBO"),
        (60, "TBO"),
    ] {
        table[n] = code(Status::Assigned, group);
    }
    table
}

/// The built-in `iso-mill`: `%:/DS N03 G02 X+053 Y+053 Z+053 I+053 J+053 K+053 F031 S04 T04
/// M02`, metric, travel X -500..500, Y -400..400, Z -300..100, feed 999.9, speed 6000, tools
/// to 99.
pub(super) fn iso_mill() -> Config {
    let mut formats = vec![
        (b'N', format(b'N', 3, 0, false, false)),
        (b'G', format(b'G', 2, 0, false, false)),
    ];
    for letter in *b"XYZIJK" {
        formats.push((letter, format(letter, 5, 3, true, true)));
    }
    formats.extend([
        (b'F', format(b'F', 3, 1, false, true)),
        (b'S', format(b'S', 4, 0, false, false)),
        (b'T', format(b'T', 4, 0, false, false)),
        (b'M', format(b'M', 2, 0, false, false)),
    ]);
    let dec = |text: &str| Dec::parse(text).expect("a number");
    Config {
        facts: ProfileFacts {
            colon_stop: true,
            percent: true,
            formats,
            formats_inch: None,
            feed_rev_formats: [None, None],
            explicit: true,
            increments: None,
            alignment: true,
            classification: "%:/DS N03 G02 X+053 Y+053 Z+053 I+053 J+053 K+053 F031 S04 T04 M02*"
                .into(),
            table_name: "iso6983-1".into(),
            g_codes: g_codes(),
            g_decimal: Vec::new(),
            m_codes: m_codes(),
            program_number: None,
            tv_check: false,
            arc_tolerance: 0.0282843,
            arc_tolerance_relative: 0.001,
            ijk: Ijk::Incremental,
            repeatable: Vec::new(),
            m_classes: vec![0, 1],
            max_index: 9,
            max_parameter: 999,
            read_only: None,
            past_decimals: Default::default(),
            past_sequence: Default::default(),
            code_words: Vec::new(),
            index_g: false,
            travel: vec![
                (b'X', dec("-500"), dec("500")),
                (b'Y', dec("-400"), dec("400")),
                (b'Z', dec("-300"), dec("100")),
            ],
            work_offsets: Vec::new(),
            feed_max: Some(dec("999.9")),
            spindle_max: Some(dec("6000")),
            sample_limits: crate::check::SAMPLE_ALL,
            tool_max: Some(99),
            rapid_rate: 10000.0,
            limit_units: Units::Metric,
        },
        family: Family::Iso,
        alarm_g: false,
        alarm_m: false,
        diameter: false,
        pqr: [Role::Parameter; 3],
        pointed_numbers: false,
        haas: false,
        // M03 M04 keyed `spindle-cw`, `spindle-ccw`, as every dialect profile keys them
        turning: vec![3, 4],
        modal: ModalSettings {
            reset: vec![1, 17, 40, 71, 80, 90, 94],
            inch: 70,
            metric: 71,
            default_units: Units::Metric,
            family: Family::Iso,
            fanuc_lathe: false,
            g80_clears_motion: false,
            centre_codes: false,
            heidenhain: false,
            lap: false,
            g92_clamps: true,
            sinumerik_units: false,
            units_kept_at_end: false,
            dwell: crate::word::dwell_words(Family::Iso, false),
            arc_radius: b'R',
            lacks_g: Vec::new(),
            g_system: Default::default(),
            haas: false,
        },
    }
}

/// The dialect a profile of `family` reads programs under (`formats.profile`).
pub(super) fn dialect(family: Family) -> Dialect {
    let macros = matches!(family, Family::MacroB | Family::LinuxCnc);
    Dialect {
        family,
        lowercase: matches!(family, Family::LinuxCnc | Family::Sinumerik),
        hash: macros,
        // (as the built-in profiles' characters: sinumerik-840d's and the OSP profiles' `[ ]`
        // and `*`, heidenhain-iso's `*`)
        brackets: macros || matches!(family, Family::Sinumerik | Family::Okuma),
        semicolon: matches!(family, Family::LinuxCnc | Family::Sinumerik),
        star: macros
            || matches!(
                family,
                Family::Sinumerik | Family::Okuma | Family::Heidenhain
            ),
        expressions: true,
        ngc: false,
    }
}

/// Every finding of `program` (lines separated by `\n`) checked against `config`, the
/// program's end included.
pub(super) fn check(config: Config, program: &str) -> Vec<Finding> {
    let dialect = dialect(config.family);
    check_in(config, &dialect, program)
}

/// [`check`] under a dialect of the test's own.
pub(super) fn check_in(config: Config, dialect: &Dialect, program: &str) -> Vec<Finding> {
    run(config, dialect, program).1
}

/// The checker after `program` (every rule reported, the path recorded where `record_path`),
/// and its findings.
pub(super) fn run_recording(
    config: Config,
    dialect: &Dialect,
    program: &str,
    record_path: bool,
) -> (Checker, Vec<Finding>) {
    run_file(config, dialect, program, record_path, None)
}

/// [`run_recording`] of a file the user named `name` ([`Checker::file_name`]).
pub(super) fn run_file(
    config: Config,
    dialect: &Dialect,
    program: &str,
    record_path: bool,
    name: Option<&str>,
) -> (Checker, Vec<Finding>) {
    let mut checker = Checker::new(Arc::new(config), Selection::all(), record_path);
    if let Some(name) = name {
        checker.file_name(name);
    }
    let mut tokens = Vec::new();
    let mut found = Vec::new();
    // (the lines joined by LF and each checked as the binding checks a run of lines,
    // `Checker::check_next_line`: it finds each line's end as `str::lines` split them)
    let joined = program.lines().collect::<Vec<_>>().join("\n");
    let mut start = 0;
    for (i, line) in program.lines().enumerate() {
        let rest = &joined.as_bytes()[start..];
        let length = checker.check_next_line(rest, i + 1, dialect, &mut tokens);
        assert_eq!(&rest[..length], line.as_bytes(), "line {}", i + 1);
        start += length + 1;
        found.extend(checker.take());
    }
    checker.finish();
    found.extend(checker.take());
    (checker, found)
}

/// The checker after `program` (every rule reported, no path kept), and its findings.
pub(super) fn run(config: Config, dialect: &Dialect, program: &str) -> (Checker, Vec<Finding>) {
    run_recording(config, dialect, program, false)
}

/// The findings of `rule` alone.
pub(super) fn findings(config: Config, program: &str, rule: Rule) -> Vec<Finding> {
    check(config, program)
        .into_iter()
        .filter(|f| f.rule == rule)
        .collect()
}

/// Where `rule` fires in `program`: (line, column) of each finding.
pub(super) fn fired(config: Config, program: &str, rule: Rule) -> Vec<(usize, usize)> {
    findings(config, program, rule)
        .iter()
        .map(|f| (f.line, f.column))
        .collect()
}

/// A profile of `family`, else the iso-mill's.
pub(super) fn of_family(family: Family) -> Config {
    let mill = iso_mill();
    Config {
        family,
        modal: ModalSettings {
            family,
            dwell: crate::word::dwell_words(family, false),
            ..mill.modal.clone()
        },
        ..mill
    }
}

/// A Fanuc lathe's: the family's codes with the lathe's modal settings and dwell words.
pub(super) fn fanuc_lathe() -> Config {
    let mut config = of_family(Family::MacroB);
    config.modal.fanuc_lathe = true;
    config.modal.dwell = crate::word::dwell_words(Family::MacroB, true);
    config
}

/// An Okuma OSP lathe's (`okuma-lathe`): X a diameter, arcs in G18 given their radius by L,
/// R a length (the drilling cycle's infeed), as `machine::Machine` compiles the profile.
pub(super) fn okuma_lathe() -> Config {
    let mut config = of_family(Family::Okuma);
    config.diameter = true;
    config.pqr = [Role::Other, Role::Other, Role::Length];
    config.modal.reset = vec![0, 18, 21, 40, 90, 95, 97];
    config.modal.inch = 20;
    config.modal.metric = 21;
    config.modal.lap = true;
    config.modal.arc_radius = crate::word::arc_radius(Family::Okuma, true);
    config
}

/// A program of `body` between `%` and `M02` and the closing `%`: quiet on the structure
/// rules.
pub(super) fn program(body: &str) -> String {
    format!("%\n{body}\nM02\n%\n")
}

#[test]
fn a_clean_program_is_quiet_on_every_rule() {
    let text = program("N10 G01 X10. Y20. F100.\nN20 G02 X20. Y30. I10. J0\nN30 G00 Z50.");
    assert_eq!(check(iso_mill(), &text), Vec::new());
}
