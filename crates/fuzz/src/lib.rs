//! What the fuzz targets share: the first input byte read as the dialect and the profile, and
//! the hand-made profiles (a Fanuc-style mill for the checker, metric/inch pairs for the
//! converter) that stand in for the ones Python builds from `formats/profiles/*.toml`.
//!
//! Input layout of `tokenize`, `check` and `convert`: byte 0 selects, the rest is the program.
//! Bits 0-5 of byte 0 are the six [`Dialect`] flags (so all 64 combinations are reachable),
//! bits 6-7 pick one of four variants of the target's configuration.

use std::sync::Arc;

use tapegate_core::check::{Code, Config, Ijk, ProfileFacts, Role, Status};
use tapegate_core::convert::{ConvertConfig, ParameterClass, ParameterClasses, Rounding, Spacing};
use tapegate_core::decimal::Dec;
use tapegate_core::modal::{ModalSettings, Units};
use tapegate_core::rules::Selection;
use tapegate_core::wordformat::{WordFormat, Zeros};
use tapegate_core::{Dialect, Family};

/// Byte 0 of an input and the program after it.
pub fn split(data: &[u8]) -> (u8, &[u8]) {
    match data.split_first() {
        Some((&b, rest)) => (b, rest),
        None => (0, data),
    }
}

/// The dialect of bits 0-5 of `selector`, and its family of bits 6-7 (with bit 5, which
/// turns the fourth into Heidenhain).
pub fn dialect(selector: u8) -> Dialect {
    let bit = |n: u8| selector & (1 << n) != 0;
    let family = match (selector >> 6, bit(5)) {
        (0, _) => Family::Iso,
        (1, _) => Family::MacroB,
        (2, _) => Family::LinuxCnc,
        (_, true) => Family::Sinumerik,
        (_, false) => Family::Heidenhain,
    };
    Dialect {
        family,
        lowercase: bit(0),
        hash: bit(1),
        brackets: bit(2),
        semicolon: bit(3),
        star: bit(4),
        expressions: bit(5),
        // a Haas reads Macro B without lower case and refuses `X 0`
        ngc: family == Family::MacroB && !bit(0),
    }
}

/// The variant (0..4) of bits 6-7 of `selector`.
pub fn variant(selector: u8) -> u8 {
    selector >> 6
}

fn dec(text: &str) -> Dec {
    Dec::parse(text).expect("a number")
}

pub fn format(address: u8, before: u32, after: u32, signed: bool, zeros: Zeros) -> WordFormat {
    WordFormat {
        address,
        before,
        after,
        signed,
        zeros,
        decimal: true,
    }
}

pub fn count(address: u8, before: u32, zeros: Zeros) -> WordFormat {
    WordFormat {
        address,
        before,
        after: 0,
        signed: false,
        zeros,
        decimal: false,
    }
}

fn code(status: Status, duration: &str) -> Option<Code> {
    Some(Code {
        status,
        duration: duration.to_string(),
    })
}

/// The G codes 0..1000 of a Fanuc-style mill: the ISO 6983-1 table's modal groups (a motion,
/// b plane, d compensation, e cycles, f zero shift, j distance, k feed, l spindle, m units),
/// a few permanently unassigned and conditional codes, the rest unassigned.
fn g_codes() -> Vec<Option<Code>> {
    use Status::*;
    let mut table = vec![code(Unassigned, ""); 1000];
    let mut set = |codes: &[usize], status: Status, duration: &str| {
        for &g in codes {
            table[g] = code(status, duration);
        }
    };
    set(&[0, 1, 2, 3, 6, 33], Assigned, "a");
    set(&[34, 35], Conditional, "a");
    set(&[4, 10, 28, 30, 52, 65], Assigned, "TBO");
    set(&[9, 63, 74, 92], Conditional, "TBO");
    set(&[15, 16], Assigned, "polar");
    set(&[17, 18, 19], Assigned, "b");
    set(&[20, 21], Assigned, "m");
    set(&[70, 71], Conditional, "m");
    set(&[25, 26, 27, 29, 36, 37, 38, 39], Permanent, "");
    set(&[40, 41, 42], Assigned, "d");
    set(&[43, 44, 49], Assigned, "length");
    set(&[53, 54, 55, 56, 57, 58, 59], Conditional, "f");
    set(&[68, 69], Assigned, "rotation");
    set(
        &[73, 76, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89],
        Assigned,
        "e",
    );
    set(&[90, 91], Conditional, "j");
    set(&[93], Conditional, "k");
    set(&[94, 95], Assigned, "k");
    set(&[96], Assigned, "l");
    set(&[97], Conditional, "l");
    set(&[98, 99], Assigned, "return");
    // A code the table does not have at all (TG301), beside the unassigned ones (TG302).
    table[999] = None;
    table
}

/// The M codes 0..100: spindle, coolant, ends, tool change; some unknown (None).
fn m_codes() -> Vec<Option<Code>> {
    use Status::*;
    let mut table = vec![code(Unassigned, ""); 100];
    for m in [0, 1, 2, 6, 19, 29, 30, 60, 98, 99] {
        table[m] = code(Assigned, "TBO");
    }
    for m in [3, 4, 5] {
        table[m] = code(Assigned, "spindle");
    }
    for m in [7, 8, 9] {
        table[m] = code(Assigned, "coolant");
    }
    for m in [48, 49] {
        table[m] = code(Conditional, "override");
    }
    for m in [90, 91, 92, 93, 94, 95, 96, 97] {
        table[m] = None;
    }
    table
}

/// A Fanuc-style mill (`formats/profiles/fanuc-mill.toml`, with the dimension words 5.4 signed
/// and leading zeros omitted). Variants: 0 the profile as it is (explicit decimal, a word
/// without a point read in least increments, incremental I J K); 1 implicit decimal; 2 absolute I J K in inch, select/ignore lists, path recorded;
/// 3 a quadrant-limited control with trailing zeros omitted and P Q R as parameters.
///
/// Built once per variant and shared, as a compiled machine is: making the 1,100-entry code
/// tables anew for every input took most of the time of a small one.
pub fn check_config(variant: u8) -> Arc<Config> {
    static CONFIGS: std::sync::OnceLock<Vec<Arc<Config>>> = std::sync::OnceLock::new();
    CONFIGS.get_or_init(|| (0..4).map(|v| Arc::new(make_check_config(v))).collect())
        [variant as usize % 4]
        .clone()
}

fn make_check_config(variant: u8) -> Config {
    let zeros = if variant == 3 {
        Zeros::Trailing
    } else {
        Zeros::Leading
    };
    let mut formats: Vec<(u8, WordFormat)> = vec![
        (b'O', count(b'O', 4, Zeros::Leading)),
        (b'N', count(b'N', 5, Zeros::Leading)),
        (b'G', count(b'G', 3, Zeros::Leading)),
    ];
    for &a in b"XYZIJKR" {
        formats.push((a, format(a, 5, 4, true, zeros)));
    }
    formats.push((b'A', format(b'A', 3, 3, true, zeros)));
    formats.push((b'F', format(b'F', 5, 2, false, zeros)));
    formats.push((b'S', count(b'S', 5, Zeros::Leading)));
    formats.push((b'T', count(b'T', 4, Zeros::None)));
    formats.push((b'D', count(b'D', 2, Zeros::Leading)));
    formats.push((b'M', count(b'M', 3, Zeros::Leading)));
    let explicit = variant != 1 && variant != 3;
    let classification = format!(
        "%:/{}O04 N05 G03 X+054 Y+054 Z+054 I+054 J+054 K+054 R+054 A+033 F052 S05 T4 D02 M03*",
        if explicit { "DS " } else { "" }
    );
    Config {
        facts: ProfileFacts {
            formats,
            explicit,
            // Fanuc reads a word without a point in least increments, but P and L (numbers.whole
            // = "PL" in formats/profiles/fanuc-mill.toml); the other variants read whole numbers.
            increments: (variant == 0).then(|| b"PL".to_vec()),
            feed_rev_formats: [None, None],
            // Fanuc IS-B: the dimension words are X+044 while inch is in force.
            formats_inch: (variant == 0).then(|| {
                b"XYZIJKR"
                    .iter()
                    .map(|&a| (a, format(a, 4, 4, true, Zeros::Leading)))
                    .collect()
            }),
            alignment: variant != 2,
            classification,
            table_name: "iso6983-1".into(),
            g_codes: g_codes(),
            g_decimal: Vec::new(),
            m_codes: m_codes(),
            program_number: Some(if variant == 2 { b':' } else { b'O' }),
            percent: variant != 3,
            tv_check: variant != 1,
            arc_tolerance: 0.028,
            arc_tolerance_relative: 0.001,
            ijk: match variant {
                2 => Ijk::Absolute,
                3 => Ijk::Quadrant,
                _ => Ijk::Incremental,
            },
            repeatable: b"M".to_vec(),
            m_classes: vec![0, 1],
            max_index: 9,
            max_parameter: 999,
            read_only: None,
            past_decimals: Default::default(),
            past_sequence: Default::default(),
            code_words: Vec::new(),
            index_g: variant == 2,
            // a tape reader that stops at a comment's ':' (variant 2), and G54/G55 work offsets
            // so that the travel is checked in machine positions
            colon_stop: variant == 2,
            work_offsets: vec![
                (54, b'X', dec("-300")),
                (54, b'Y', dec("-200")),
                (54, b'Z', dec("-400")),
                (55, b'X', dec("100")),
            ],
            travel: vec![
                (b'X', dec("-762"), dec("762")),
                (b'Y', dec("-406"), dec("406")),
                (b'Z', dec("-508"), dec("10")),
                (b'A', dec("-99999.999"), dec("99999.999")),
            ],
            feed_max: Some(dec("10000")),
            spindle_max: Some(dec("10000")),
            sample_limits: tapegate_core::check::SAMPLE_ALL,
            tool_max: Some(24),
            rapid_rate: 24000.0,
            limit_units: Units::Metric,
        },
        family: dialect(variant << 6).family,
        alarm_g: variant == 1,
        alarm_m: variant == 2,
        diameter: variant == 1,
        pqr: if variant == 3 {
            [Role::Parameter, Role::Parameter, Role::Parameter]
        } else {
            [Role::Other, Role::Length, Role::Length]
        },
        pointed_numbers: false,
        haas: false,
        turning: vec![3, 4],
        modal: ModalSettings {
            reset: vec![1, 17, 40, 21, 80, 90, 94],
            inch: 20,
            metric: 21,
            default_units: if variant == 2 {
                Units::Inch
            } else {
                Units::Metric
            },
            family: dialect(variant << 6).family,
            fanuc_lathe: variant == 1,
            g80_clears_motion: variant == 2,
            sinumerik_units: variant == 3,
            centre_codes: variant == 2,
            heidenhain: false,
            lap: false,
            g92_clamps: true,
            units_kept_at_end: variant == 1 || variant == 2,
            dwell: tapegate_core::word::dwell_words(dialect(variant << 6).family, variant == 1),
            arc_radius: tapegate_core::word::arc_radius(dialect(variant << 6).family, variant == 1),
            lacks_g: Vec::new(),
            g_system: Default::default(),
            haas: false,
        },
    }
}

/// The run's options of a variant: variant 2 selects and ignores rules and records the path.
pub fn check_run(variant: u8) -> (Selection, bool) {
    if variant % 4 != 2 {
        return (Selection::all(), false);
    }
    let select: Vec<String> = ["TG1", "TG2", "TG4", "TG5", "TG6"]
        .map(String::from)
        .to_vec();
    (Selection::new(&select, &["TG703".into()]), true)
}

/// Metric explicit-decimal formats (X+053 ...) and inch implicit ones (X+044 ...).
fn metric_formats(zeros: Zeros) -> Vec<(u8, WordFormat)> {
    let mut f: Vec<(u8, WordFormat)> = b"XYZUVWIJKPQR"
        .iter()
        .map(|&a| (a, format(a, 5, 3, true, zeros)))
        .collect();
    f.push((b'A', format(b'A', 3, 3, true, zeros)));
    f.push((b'F', format(b'F', 5, 1, false, zeros)));
    f.push((b'S', count(b'S', 5, zeros)));
    f.extend(
        [(b'N', 5), (b'G', 2), (b'M', 2), (b'T', 4), (b'O', 4)]
            .map(|(a, n)| (a, count(a, n, zeros))),
    );
    f
}

fn inch_formats(zeros: Zeros) -> Vec<(u8, WordFormat)> {
    let mut f: Vec<(u8, WordFormat)> = b"XYZUVWIJKPQR"
        .iter()
        .map(|&a| (a, format(a, 4, 4, true, zeros)))
        .collect();
    f.push((b'A', format(b'A', 3, 3, true, zeros)));
    f.push((b'F', format(b'F', 3, 2, false, zeros)));
    f.push((b'S', count(b'S', 5, zeros)));
    f.extend(
        [(b'N', 4), (b'G', 2), (b'M', 2), (b'T', 2), (b'O', 4)]
            .map(|(a, n)| (a, count(a, n, zeros))),
    );
    f
}

/// The converter's configuration. Variants: 0 explicit metric source to an implicit inch
/// target (leading zeros omitted); 1 the reverse; 2 as 0 from a Fanuc source (least
/// increments) with half-up rounding, spaces inserted, unconvertible words allowed and a
/// parameter analysis; 3 as 1 with trailing zeros omitted in the source, a Fanuc target,
/// spaces removed and rounding refused.
pub fn convert_config(variant: u8) -> ConvertConfig {
    let to_inch = variant.is_multiple_of(2);
    // one program, beginning on its first line (0): a file of several has a list of these
    let parameters = (variant >= 2).then(|| {
        let why = |s: &str| ParameterClass::Unproved(s.into());
        let classes = [
            ("R1", ParameterClass::Length),
            ("#1", ParameterClass::Length),
            ("#100", ParameterClass::Length),
            ("P2", ParameterClass::Length),
            ("R2", why("set from a non-linear expression on line 3")),
            ("#2", why("read as a length and as a count")),
        ];
        Arc::new(ParameterClasses {
            starts: vec![0],
            shared: classes
                .map(|(n, c)| (n.as_bytes().to_vec(), c))
                .into_iter()
                .collect(),
            own: Vec::new(),
            subs: Default::default(),
        })
    });
    let dwell = vec![
        (b'P', count(b'P', 5, Zeros::Leading)),
        (b'X', format(b'X', 5, 3, false, Zeros::Leading)),
    ];
    let source_zeros = if variant == 3 {
        Zeros::Trailing
    } else {
        Zeros::Leading
    };
    let (src_formats, out_formats) = if to_inch {
        (metric_formats(Zeros::Leading), inch_formats(Zeros::Leading))
    } else {
        (inch_formats(source_zeros), metric_formats(Zeros::Leading))
    };
    let (source, target) = if variant >= 2 {
        (Family::MacroB, Family::MacroB)
    } else {
        (Family::Iso, Family::Iso)
    };
    // the baseline (`ConvertConfig::between`), and what each variant sets
    ConvertConfig {
        src_formats,
        explicit_in: to_inch,
        // Variant 2 reads a Fanuc source (a word without a point in least increments, but P
        // and L), variant 3 writes for one (so no word is left without its point).
        src_increments: (variant == 2).then(|| b"PL".to_vec()),
        dst_increments: (variant == 3).then(|| b"PL".to_vec()),
        // Variants 2 and 3 have formats of their own for inch (on either side).
        src_formats_inch: (variant >= 2).then(|| inch_formats(source_zeros)),
        out_formats_inch: (variant >= 2).then(|| inch_formats(Zeros::Leading)),
        // the source's modal settings, as its compiled machine gives them
        src_modal: ModalSettings {
            reset: if to_inch {
                vec![1, 17, 40, 21, 80, 90, 94]
            } else {
                vec![1, 17, 40, 20, 80, 90, 94]
            },
            default_units: if to_inch { Units::Metric } else { Units::Inch },
            family: Family::Iso,
            centre_codes: variant == 2,
            dwell: b"XPF",
            arc_radius: b'R',
            ..ConvertConfig::between(Family::Iso, Family::Iso).src_modal
        },
        pqr: if variant >= 2 {
            [Role::Parameter, Role::Length, Role::Length]
        } else {
            [Role::Other, Role::Length, Role::Length]
        },
        out_formats,
        dwell_formats: dwell,
        explicit_out: !to_inch,
        target_units: if to_inch { Units::Inch } else { Units::Metric },
        units: Some(if to_inch { Units::Inch } else { Units::Metric }),
        rounding: match variant {
            2 => Rounding::HalfUp,
            3 => Rounding::Error,
            _ => Rounding::HalfEven,
        },
        spacing: match variant {
            2 => Spacing::Insert,
            3 => Spacing::Remove,
            _ => Spacing::Keep,
        },
        allow_unconverted: variant == 2,
        parameters,
        lathe: variant == 3,
        // (the target reads every form the source may write, `#`, `[ ]`, `*`; IS-B on both
        // sides; a Fanuc-like target alarms on a sequence number past its N format: the
        // baseline's)
        target_arc_radius: b'R',
        ..ConvertConfig::between(source, target)
    }
}
