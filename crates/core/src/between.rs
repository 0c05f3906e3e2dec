//! Words, variables and the program frame whose meaning differs between two control families,
//! for a conversion from one family to another (`convert --from A --to B`).
//!
//! The converter carries every word it does not change as written. Between families a word of
//! the same letter, in a block of the same code, can be other data: a SINUMERIK's `D1` selects
//! a tool's length and radius, a FANUC's only the radius for G41/G42; a LinuxCNC `G10 L20` sets
//! a work offset from the current position, a FANUC's an additional work offset G54.1 P; a
//! Custom Macro B `#5001` is the block end position, a LinuxCNC `#5001` a parameter nothing
//! sets. Each rule here compares what the two controls' documents say of the word; where they
//! do not say the same the block is refused at the word, naming both meanings. A word both
//! documents read alike is carried. (A G or M code whose number does another thing is the code
//! tables' to compare, `machine::differing_codes`; here the words within a code, the variables
//! and the frame a program needs on the target.) Sources per rule, and the list, in
//! docs/convert.md, "Words and variables between families".

use crate::lex::Family;

/// A word of the block: its text (`D1`, `#100=#5001`) and its byte offset in the line.
#[derive(Debug, Clone, Copy)]
pub struct Word<'a> {
    pub token: &'a [u8],
    pub start: usize,
}

/// A word refused: why, the byte offset of the word in its line, and the clause it breaks (the
/// converter makes its located error of it).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    pub message: String,
    pub at: usize,
    pub clause: &'static str,
}

/// A control family as messages name it (the converter's names).
pub type Name = fn(Family) -> &'static str;

/// Why a program of `from` is not converted for a control of `to` at all: a HEIDENHAIN ISO
/// program is framed by `%NAME G71 *` ... `N99999 %NAME G71 *` and ends every block with `*`
/// (HEIDENHAIN TNC ISO programming manual, "Program structure"), which tapegate does not write,
/// and the TNC gives its own functions to codes other families use (G28 mirror image, G30/G31
/// the blank form, M98 and M99 its own; heidenhain-iso.toml). None: the conversion may go on.
pub fn frame(from: Family, to: Family, name: Name) -> Option<String> {
    (to == Family::Heidenhain && from != Family::Heidenhain).then(|| {
        format!(
            "a HEIDENHAIN ISO program begins and ends with %NAME G71 * (or G70) and ends every \
             block with *, which tapegate does not write for a program of another family, and \
             the TNC gives codes of the {} program other functions (G28 mirror image, G30 and \
             G31 the blank form, M98, M99 a cycle call): tapegate does not convert a program of \
             another family for a HEIDENHAIN; write it in the TNC's own form",
            name(from)
        )
    })
}

/// What the block being converted is, beside its words: its whole G codes (`gs`) and M codes
/// (`ms`) as the source reads them, the motion in force after its codes, whether a cycle is
/// in force, and whether it is read in incremental (G91) distance.
pub struct Block<'a> {
    pub words: &'a [Word<'a>],
    pub name: Name,
    pub gs: &'a [i64],
    pub ms: &'a [i64],
    pub motion: Option<i64>,
    pub cycle: bool,
    pub incremental: bool,
}

/// The words and variables of one block that the target family reads otherwise: the first is
/// refused, at its column. Only between two families (a conversion within a family reads
/// every word alike).
pub fn block(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    if from == to {
        return Ok(());
    }
    tool_offsets(from, to, k)?;
    length_offset_without_h(from, to, k)?;
    offset_data(from, to, k)?;
    variables(from, to, k)?;
    expressions(from, to, k)?;
    thread_lead(from, to, k)?;
    helix_turns(from, to, k)?;
    spindle_limit(from, to, k)?;
    blending_tolerance(from, to, k)?;
    if from == Family::MacroB && k.ms.contains(&19) {
        orient_angle(k.words, k.name, to)?;
    }
    subprogram_calls(from, to, k)
}

fn refuse(w: &Word<'_>, message: String, clause: &'static str) -> Refusal {
    Refusal {
        message,
        at: w.start,
        clause,
    }
}

/// A family's name with its article, as a message reads it: "a LinuxCNC", "an ISO 6983-1".
fn article(name: Name, family: Family) -> String {
    let name = name(family);
    let vowel = name.starts_with(['A', 'E', 'I', 'O', 'U']);
    format!("{} {name}", if vowel { "an" } else { "a" })
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The block's first word of `letter`.
fn word<'a>(k: &Block<'a>, letter: u8) -> Option<&'a Word<'a>> {
    k.words
        .iter()
        .find(|w| w.token[0].eq_ignore_ascii_case(&letter))
}

/// The first word of `letters` in a LinuxCNC block holding G`code`, converted for another
/// family: the word whose LinuxCNC meaning that family does not read.
fn linuxcnc_word<'a>(
    from: Family,
    to: Family,
    k: &Block<'a>,
    code: i64,
    letters: &[u8],
) -> Option<&'a Word<'a>> {
    if from != Family::LinuxCnc || to == Family::LinuxCnc || !k.gs.contains(&code) {
        return None;
    }
    letters.iter().find_map(|&l| word(k, l))
}

/// The whole number a word gives (`D1`, `L10`, `P3.`), None for another number or an
/// expression.
fn whole(w: &Word<'_>) -> Option<i64> {
    let number = &w.token[1..];
    let number = number.strip_suffix(b".").unwrap_or(number);
    if number.is_empty() || number.len() > 9 || !number.iter().all(u8::is_ascii_digit) {
        return None;
    }
    Some(number.iter().fold(0, |n, &c| n * 10 + i64::from(c - b'0')))
}

/// A word whose value is zero as written (`D0`, `T00`): no tool or no offset on every family.
fn zero(w: &Word<'_>) -> bool {
    whole(w) == Some(0)
}

/// Tool offsets selected by T and D. On a SINUMERIK, D1-D9 activate the tool edge's
/// compensation data, length and radius, the length applied on the first move of the axis it
/// acts on; a new tool without a D takes the edge MD20270 $MC_CUTTING_EDGE_DEFAULT names
/// (SINUMERIK 840D sl Function Manual Basic logic functions: Tool Offset (W1), 2.1; 802D:
/// "If a D word is not written, D1 is automatically effective ... Tool length compensations
/// become effective immediately when the tool is active"). A FANUC, Haas or LinuxCNC control
/// reads D as the radius offset number of G41/G42 only and applies a length only by G43 H (an
/// Okuma by G56 H; ISO 6983-1 applies an offset only by the codes that name it); on a
/// SINUMERIK H is an auxiliary function output to the PLC. So a SINUMERIK's T or D
/// carried elsewhere runs without a length offset, and another family's D or H carried to a
/// SINUMERIK does something else: refused, D0 and T0 (no offset, no tool) excepted.
fn tool_offsets(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let d = word(k, b'D').filter(|w| !w.token.contains(&b'=') && !zero(w));
    if from == Family::Sinumerik {
        let selects = d.or_else(|| word(k, b'T').filter(|w| !w.token.contains(&b'=') && !zero(w)));
        if let Some(w) = selects {
            let by = if w.token[0].eq_ignore_ascii_case(&b'D') {
                "selects the tool edge's offset data set"
            } else {
                "selects the tool with its default offset data set (D1 unless MD20270 \
                 $MC_CUTTING_EDGE_DEFAULT says otherwise)"
            };
            return Err(refuse(
                w,
                format!(
                    "{}: on a SINUMERIK this {by}, whose tool length is applied on the next \
                     move of the tool axis (Function Manual Tool Offset W1, 2.1); {} control \
                     {}: carried as written the program would run without the tool's length; \
                     tapegate does not write length compensation: write the target's (or \
                     convert for a SINUMERIK)",
                    text(w.token),
                    article(k.name, to),
                    match to {
                        // ISO 6983-1 leaves what an offset number holds to the control
                        Family::Iso => {
                            "applies an offset only by the codes that name it (G41-G44), \
                             none on a tool selection"
                        }
                        // OSP: G56 H the tool length offset (okuma-mill.toml)
                        Family::Okuma => {
                            "reads D as the radius offset number of G41/G42 only and applies \
                             a tool length only by G56 H"
                        }
                        _ => {
                            "reads D as the radius offset number of G41/G42 only and applies \
                             a tool length only by G43 H"
                        }
                    }
                ),
                "meaning",
            ));
        }
        return Ok(());
    }
    if to != Family::Sinumerik {
        return Ok(());
    }
    if let Some(w) = d {
        return Err(refuse(
            w,
            format!(
                "{}: on {} control D names {}; on a SINUMERIK D selects the tool edge's \
                 offset data set, length and radius, the length applied on the next move of \
                 the tool axis (Function Manual Tool Offset W1, 2.1): tapegate does not \
                 translate tool offsets between families",
                text(w.token),
                article(k.name, from),
                if from == Family::Iso {
                    // ISO 6983-1 leaves what an offset number holds to the control
                    "an offset only the codes that apply it (G41-G44) use"
                } else {
                    "a cutter radius offset for G41/G42 only"
                }
            ),
            "meaning",
        ));
    }
    if let Some(w) = word(k, b'H') {
        return Err(refuse(
            w,
            format!(
                "{}: on {} control H is a word of the block's code (on a mill the tool \
                 length offset number of G43/G44); on a SINUMERIK H is an auxiliary function \
                 output to the PLC, and no length is applied (SINUMERIK Programming Manual \
                 Fundamentals, auxiliary functions H): tapegate does not translate tool \
                 offsets between families",
                text(w.token),
                article(k.name, from)
            ),
            "meaning",
        ));
    }
    Ok(())
}

/// G43 without H between LinuxCNC and a FANUC or Haas: LinuxCNC applies the length of
/// the tool in the spindle ("If no H word is given, the currently loaded tool is used",
/// G-code reference, G43); a FANUC the offset number H in force, none after its reset (H0, no
/// offset: FANUC 0i-MF operator's manual, "Tool length compensation (G43, G44, G49)").
fn length_offset_without_h(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let pair = matches!(
        (from, to),
        (Family::LinuxCnc, Family::MacroB) | (Family::MacroB, Family::LinuxCnc)
    );
    if !pair || !k.gs.contains(&43) || word(k, b'H').is_some() {
        return Ok(());
    }
    let Some(w) = k
        .words
        .iter()
        .find(|w| w.token[0].eq_ignore_ascii_case(&b'G') && whole(w) == Some(43))
    else {
        return Ok(());
    };
    let (linuxcnc, fanuc) = (
        "LinuxCNC applies the length of the tool in the spindle",
        "a FANUC or Haas the offset number H in force (none after its reset: H0, no offset)",
    );
    let (a, b) = if from == Family::LinuxCnc {
        (linuxcnc, fanuc)
    } else {
        (fanuc, linuxcnc)
    };
    Err(refuse(
        w,
        format!(
            "{}: a tool length compensation with no H: {a} (on the source), {b} (on the \
             target); write the offset number (G43 H..) in the block",
            text(w.token)
        ),
        "meaning",
    ))
}

/// A lathe's G50 between two controls (FANUC, Haas, Okuma OSP lathes): the spindle speed
/// clamp by S on each (the FANUC 0i-TF's "maximum spindle speed clamp", the Haas lathe's
/// "spindle speed limit", the OSP's "maximum spindle speed"), one key in their profiles; its
/// axis words are not one function: on a FANUC `G50 X Z` makes the current position X Z
/// (coordinate system setting), on a Haas `G50 X Z U W` sets or shifts the global coordinate
/// offset kept on the work offset page (Haas lathe operator's manual, "Effective coordinate
/// system": global, common, work and child coordinates add up), on an OSP it is a zero offset
/// (okuma-lathe.toml). An axis word in a G50 block is refused at the word.
pub fn lathe_g50_axes(words: &[Word<'_>], gs: &[i64]) -> Result<(), Refusal> {
    if !gs.contains(&50) {
        return Ok(());
    }
    let axis = words
        .iter()
        .find(|w| matches!(w.token[0].to_ascii_uppercase(), b'X' | b'Z' | b'U' | b'W'));
    match axis {
        Some(w) => Err(refuse(
            w,
            format!(
                "{}: a lathe's G50 with axis words sets the coordinate system otherwise on each \
                 control (FANUC: the current position becomes the coordinates given; Haas: the \
                 global coordinate offset of the work offset page; Okuma OSP: a zero offset); \
                 only G50 S, the spindle speed clamp, is one function on all: write the \
                 target's coordinate setting",
                text(w.token)
            ),
            "meaning",
        )),
        None => Ok(()),
    }
}

/// G10's data types that a FANUC and a Haas read apart, though both write Custom Macro B.
/// FANUC (0i-MF operator's manual, "Changing of tool offset value (programmable data input)
/// (G10)", "Changing workpiece coordinate system (G10 L2)"): L1 the tool offset value in offset
/// memory A (one value, length and radius), L12 and L13 the radius geometry and wear of offset
/// D, L2 P0 the external work zero offset. Haas (mill operator's manual, "G10 Set Offsets", as
/// the Haas UK "Programmable Offsets" page gives it): L1 (and L11) the tool length wear (H),
/// L12 and L13 the *diameter* offset and its wear (D) -- the Haas's cutter compensation reads
/// "the radius/diameter offset column" (Classic Control Mill Operator's Manual, "Entry and exit
/// from cutter compensation"), which setup decides, not the program -- and L2 P0 the G52 work
/// coordinate. Whether one machine's column is a radius cannot be seen in the program. Carried as
/// written, a FANUC's `G10 L12 P1 R5.` sets a Haas's cutter a diameter of 5 (half the radius
/// compensation meant), and a Haas's L12 a FANUC's radius twice as large: refused at the L
/// (or the P) word. L10, L11, L20 and L2 P1-P6 are one datum on both: carried.
pub fn fanuc_haas_words(
    from_haas: bool,
    lathe: bool,
    words: &[Word<'_>],
    gs: &[i64],
) -> Result<(), Refusal> {
    let m19 = |w: &Word<'_>| w.token[0].eq_ignore_ascii_case(&b'M') && whole(w) == Some(19);
    if from_haas && words.iter().any(m19) {
        orient_angle(words, |_| "FANUC", Family::MacroB)?;
    }
    fanuc_haas_variables(from_haas, lathe, words)?;
    let find = |letter: u8| {
        words
            .iter()
            .find(|w| w.token[0].eq_ignore_ascii_case(&letter))
    };
    if !gs.contains(&10) {
        return Ok(());
    }
    let Some(l_word) = find(b'L') else {
        return Ok(());
    };
    let (fanuc, haas) = match whole(l_word) {
        Some(1) => (
            "the value of tool offset P in offset memory A (one value for length and radius)",
            "the length wear of tool offset H P (as L11)",
        ),
        Some(12) => (
            "the radius geometry of tool offset D P",
            "the diameter geometry of tool offset D P (the Haas's radius/diameter offset \
             column, as the machine is set up)",
        ),
        Some(13) => (
            "the radius wear of tool offset D P",
            "the diameter wear of tool offset D P (the same column's wear)",
        ),
        Some(2) => match find(b'P') {
            Some(p) if whole(p) == Some(0) => {
                return Err(refuse(
                    p,
                    format!(
                        "{}: G10 L2 P0 sets {} on the source and {} on the target; tapegate \
                         does not translate offset data between these controls: write the \
                         target's G10, or set the offset at the machine",
                        text(p.token),
                        if from_haas {
                            "the G52 work coordinate (Haas)"
                        } else {
                            "the external work zero offset (FANUC)"
                        },
                        if from_haas {
                            "the external work zero offset (FANUC)"
                        } else {
                            "the G52 work coordinate (Haas)"
                        },
                    ),
                    "meaning",
                ));
            }
            _ => return Ok(()),
        },
        _ => return Ok(()),
    };
    let (source, target) = if from_haas {
        (haas, fanuc)
    } else {
        (fanuc, haas)
    };
    let (a, b) = if from_haas {
        ("Haas", "FANUC")
    } else {
        ("FANUC", "Haas")
    };
    Err(refuse(
        l_word,
        format!(
            "{}: G10 {} sets {source} on a {a} and {target} on a {b} (FANUC operator's manual, \
             G10; Haas operator's manual, G10 Set Offsets): tapegate does not translate offset \
             data between these controls: write the target's G10, or set the offset at the \
             machine",
            text(l_word.token),
            text(l_word.token),
        ),
        "meaning",
    ))
}

/// A variable a word names by its `#`: a number (`#5221`; `element`: a decimal part follows,
/// a Haas NGC parameter element `#30003.078`), or none where a value chooses it (`#[#1]`) or
/// it has a name (`#<x>`: `named`).
enum HashVariable {
    Number { n: u64, element: bool },
    Chosen { named: bool },
}

/// The variables of a word's text, in order: one walk of its `#` signs, shared by the
/// conversions between families and between a FANUC and a Haas.
fn hash_variables(t: &[u8]) -> impl Iterator<Item = HashVariable> + '_ {
    let mut at = 0;
    std::iter::from_fn(move || {
        let p = t[at..].iter().position(|&c| c == b'#')? + at;
        at = p + 1;
        let rest = &t[at..];
        let digits = rest.iter().take_while(|c| c.is_ascii_digit()).count();
        if digits == 0 {
            return Some(HashVariable::Chosen {
                named: rest.first() == Some(&b'<'),
            });
        }
        let n = std::str::from_utf8(&rest[..digits])
            .ok()
            .and_then(|d| d.parse::<u64>().ok())
            .unwrap_or(u64::MAX);
        let element =
            rest.get(digits) == Some(&b'.') && rest.get(digits + 1).is_some_and(u8::is_ascii_digit);
        Some(HashVariable::Number { n, element })
    })
}

/// What a numbered variable is on a Haas, where the NGC's Macro Variables Table (Mill
/// Operator's Manual, NGC, 2017, 6.14.7; docs/dialects.md, "Variables") gives it a use of its
/// own; None where it gives it none here (the number is then judged by FANUC's reading alone).
fn haas_variable(n: u64) -> Option<&'static str> {
    Some(match n {
        1..=33 => "a local variable",
        550..=580 => "the probe's calibration data (where a probe is installed)",
        100..=199 | 500..=699 | 800..=999 => "a general purpose variable",
        700..=749 => "a hidden variable for the control's internal use",
        750..=799 => "a number its table does not list",
        1000..=1999 => "a discrete or analog input or output of the machine",
        2001..=2800 => "a tool length or diameter offset (geometry or wear)",
        3020..=3025 => "a timer (power-on, cycle, feed or part time)",
        3026 => "the tool in the spindle",
        3027 => "the spindle speed",
        3901 | 3902 => "an M30 part counter",
        4001..=4021 => {
            "the G code of a modal group as the Haas numbers its groups (its work coordinate \
             system is group 12, a FANUC's 14; it has no group 4, 13, 14 or 17-21)"
        }
        4101..=4126 => "the previous block's address by the macro arguments' letters (#4124 X)",
        5001..=5006 | 5021..=5026 | 5041..=5046 | 5061..=5069 | 5081..=5086 | 5221..=5326 => {
            "a position or offset of an axis (X Y Z A B C on a mill; a lathe's order is in no \
             table at hand)"
        }
        5201..=5206 => "the G52 work offset",
        6001..=6999 => "a setting or parameter (the control's own numbering)",
        8500..=8599 => "advanced tool management or tool data",
        10000..=10999 => "a general purpose variable under its NGC number (#100 is #10100)",
        11000..=11255 => "a discrete input",
        12000..=12255 => "a discrete output",
        13000..=13063 => "an analog input",
        20000..=29999 => "a setting (setting number + 20000)",
        30000..=39999 => "a parameter (parameter number + 30000)",
        50001..=52800 => "tool data",
        _ => return None,
    })
}

/// The numbered variables a FANUC and a Haas read alike, beside the ones both leave to the
/// program (FANUC 0i-MF operator's manual, "System variables"; the NGC table, 6.14.7, and its
/// pages on #3004 and #4001-#4021):
/// - on every pair: the null variable, the alarm, the clocks, the stop with a message, the
///   date and time, the feed hold, override and exact stop bits of #3004 (the same 0-7 table),
///   the motion group's code (#4001), and the previous block's B D F H M S T (#4102 ... #4120:
///   FANUC's modal information, the Haas's letters mapped as the macro arguments'
///   alphabetic addressing (the table's note 1); the other #4101-#4126 are letters a FANUC does not keep there, or its
///   sequence and program numbers);
/// - between mills only (the tables are the mill's; no Haas lathe table was at hand, and the
///   lathes' group numbers and axis orders are not known to agree): the G codes of the groups
///   both number alike (02 plane, 03 distance, 05 feed mode, 06 units, 07 cutter, 08 length,
///   09 cycle, 10 cycle return, 11 scaling, 15 exact stop, 16 rotation; FANUC's 04, 12-14 and
///   17-21 are other groups or none on a Haas: its work system is group 12, FANUC's 14), the
///   X Y Z A B C positions, and the G54-G59 and additional work offsets laid out alike (FANUC
///   G54.1 P1-P48 #7001-#7960 and P1-P300 #14001-#19988, 20 a set; Haas G110-G129
///   #7001-#7386 and G154 P1-P99 #14001-#15966: X to C, the first six of each set of 20).
fn fanuc_haas_alike(n: u64, lathe: bool) -> bool {
    let six_of_twenty = |first: u64| (n - first) % 20 < 6;
    match n {
        0 | 3000..=3002 | 3004 | 3006 | 3011 | 3012 | 4001 => true,
        4102 | 4107 | 4109 | 4111 | 4113 | 4119 | 4120 => true,
        _ if lathe => false,
        4002 | 4003 | 4005..=4011 | 4015 | 4016 => true,
        5001..=5006 | 5021..=5026 | 5041..=5046 | 5061..=5066 | 5081..=5086 => true,
        5221..=5326 => six_of_twenty(5221),
        7001..=7386 => six_of_twenty(7001),
        14001..=15966 => six_of_twenty(14001),
        _ => false,
    }
}

/// `#3003 = 0` or `#3003 = 1` (a whole literal, spaces anywhere): single block suppression off
/// or on, FANUC's bit 0 and the Haas's whole value (NGC table, "#3003 Single Block
/// Suppression"). FANUC's bit 1 (2 and 3: the completion of an auxiliary function not
/// awaited) has no Haas meaning, and a value the text does not show may be 2 or 3.
fn single_block_literal(token: &[u8]) -> bool {
    let bare: Vec<u8> = token.iter().copied().filter(|&c| c != b' ').collect();
    let Some(value) = bare.strip_prefix(b"#3003=") else {
        return false;
    };
    let (whole, fraction) = match value.iter().position(|&c| c == b'.') {
        Some(p) => (&value[..p], &value[p + 1..]),
        None => (value, &value[..0]),
    };
    let significant = &whole[whole.iter().take_while(|&&c| c == b'0').count()..];
    (!whole.is_empty() || !fraction.is_empty())
        && whole.iter().all(u8::is_ascii_digit)
        && fraction.iter().all(|&c| c == b'0')
        && matches!(significant, b"" | b"1")
}

/// Numbered variables between a FANUC and a Haas, which both write Custom Macro B: a variable
/// both leave to the program (#1-#33, #100-#199, #500-#699 but the Haas probe's #550-#580,
/// #800-#999) or both read alike ([`fanuc_haas_alike`]) is carried; one the Haas's table gives another use (the G52 offset
/// at #5201, the tool offsets at #2001-#2800 in another order, the M30 counters at #3901, the
/// settings and parameters at #20000-#39999, the NGC's #10000 numbers of the general purpose
/// variables, which a FANUC reads as tool offsets) or that neither names alike is refused,
/// naming both uses; so is a Haas NGC parameter element (`#30003.078`), which a FANUC does
/// not read (a variable is numbered with a whole number), and a variable chosen by a value.
/// `lathe`: the pair is two lathes ([`fanuc_haas_alike`]).
fn fanuc_haas_variables(from_haas: bool, lathe: bool, words: &[Word<'_>]) -> Result<(), Refusal> {
    let (source, target) = if from_haas {
        ("Haas", "FANUC")
    } else {
        ("FANUC", "Haas")
    };
    for w in words.iter().filter(|w| w.token.contains(&b'#')) {
        let t = w.token;
        let fail = |what: String| Err(refuse(w, format!("{}: {what}", text(t)), "meaning"));
        for variable_named in hash_variables(t) {
            let n = match variable_named {
                HashVariable::Chosen { .. } => {
                    return fail(format!(
                        "a variable chosen by a value: which one the text does not show, so \
                         not that a {target} reads it as a {source} does; tapegate carries only \
                         the variables both controls read alike"
                    ));
                }
                HashVariable::Number { n, element: true } => {
                    let what = if (30000..=39999).contains(&n) {
                        "a Haas NGC parameter element (docs/dialects.md)"
                    } else {
                        "a variable with a decimal part outside the Haas NGC parameters"
                    };
                    return fail(format!(
                        "#{n} with a decimal part, {what}: a FANUC numbers a variable with a \
                         whole number and does not read it; read the target's own data for it"
                    ));
                }
                HashVariable::Number { n: 3003, .. } if single_block_literal(t) => continue,
                HashVariable::Number { n: 3003, .. } => {
                    return fail(
                        "#3003 is single block suppression on both, but a FANUC's values 2 and \
                         3 (the completion of an auxiliary function not awaited) have no Haas \
                         meaning (NGC table, \"#3003 Single Block Suppression\": 1 or 0): \
                         tapegate carries only #3003 = 0 or #3003 = 1"
                            .to_string(),
                    );
                }
                HashVariable::Number { n, .. } => n,
            };
            let fanuc = variable(Family::MacroB, n);
            let haas = haas_variable(n);
            let user = fanuc.1
                && haas
                    .is_none_or(|h| h == "a local variable" || h == "a general purpose variable");
            if user || fanuc_haas_alike(n, lathe) {
                continue;
            }
            let haas = haas.unwrap_or("a variable not known here to be read alike");
            let (a, b) = if from_haas {
                (haas, fanuc.0)
            } else {
                (fanuc.0, haas)
            };
            return fail(format!(
                "#{n} is {a} on a {source} and {b} on a {target}; tapegate carries only the \
                 variables both controls leave to the program or read alike (FANUC 0i-MF \
                 operator's manual, \"System variables\"; Haas Mill Operator's Manual, NGC, \
                 6.14.7): read or write the target's own variable for it"
            ));
        }
    }
    Ok(())
}

/// What G10 with the data type `l` (None: no L, a FANUC lathe's `G10 P X Z R Q`) sets on a
/// control of `family`: FANUC 0i-MF/TF operator's manuals, "Changing of tool offset value
/// (programmable data input) (G10)" and "Changing workpiece coordinate system (G10 L2, L20)";
/// LinuxCNC G-code reference, G10 L1, L2, L10, L11, L20 (rs274: "Line with G10 does not have
/// L0, L1, L10, L11, L2, or L20").
fn g10_meaning(family: Family, l: Option<i64>) -> &'static str {
    match (family, l) {
        (Family::MacroB, None) => "a lathe's tool offset (P the offset number, X Z R Q its values)",
        (Family::MacroB, Some(1)) => "the value of tool offset P (offset memory A: one value, R)",
        (Family::MacroB, Some(2)) => {
            "a work offset (P0 the external offset, P1-P6 G54-G59), added to it in G91"
        }
        (Family::MacroB, Some(10)) => "the length geometry of tool offset H P (R)",
        (Family::MacroB, Some(11)) => "the length wear of tool offset H P (R)",
        (Family::MacroB, Some(12)) => "the radius geometry of tool offset D P (R)",
        (Family::MacroB, Some(13)) => "the radius wear of tool offset D P (R)",
        (Family::MacroB, Some(20)) => "the additional work offset G54.1 P",
        (Family::LinuxCnc, Some(1)) => {
            "the tool table entry of tool P (its offsets X-W and its radius R)"
        }
        (Family::LinuxCnc, Some(2)) => {
            "the origin of coordinate system P (P0 the active one, P1-P9 G54-G59.3; R a \
             rotation about Z), G91 ignored"
        }
        (Family::LinuxCnc, Some(10)) => {
            "tool P's table entry, set so that the current position becomes the given values"
        }
        (Family::LinuxCnc, Some(11)) => {
            "tool P's table entry, set so that the current position becomes the given values \
             in G59.3"
        }
        (Family::LinuxCnc, Some(20)) => {
            "coordinate system P, set so that the current position becomes the given values"
        }
        _ => "no such G10 form (the control refuses the block)",
    }
}

/// G10's data between a FANUC or Haas and LinuxCNC: the one form both documents
/// read alike is `G10 L2 P1`-`P6` with axis words in G90 (the origin of G54-G59 in machine
/// coordinates); every other L (tool data, L20, a lathe's G10 without L), P0 (FANUC's external
/// offset, LinuxCNC's active system), P7-P9, R (LinuxCNC's rotation about Z; FANUC's G10 L2 has
/// none) and G91 (FANUC adds, LinuxCNC ignores it: rs274 `G91 G10 L2 P1 X5` sets X5) is
/// refused at the word that differs.
fn offset_data(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let pair = matches!(
        (from, to),
        (Family::LinuxCnc, Family::MacroB) | (Family::MacroB, Family::LinuxCnc)
    );
    if !pair || !k.gs.contains(&10) {
        return Ok(());
    }
    let g10 = k
        .words
        .iter()
        .find(|w| w.token[0].eq_ignore_ascii_case(&b'G') && whole(w) == Some(10));
    let Some(g10) = g10 else {
        return Ok(());
    };
    let l_word = word(k, b'L');
    let l = l_word.and_then(whole);
    let p = word(k, b'P').and_then(whole);
    let differs = |w: &Word<'_>, why: String| {
        Err(refuse(
            w,
            format!(
                "{}: {why}; tapegate does not translate offset data between control \
                 families: write the target's G10, or set the offset at the machine",
                text(w.token)
            ),
            "meaning",
        ))
    };
    let both = |what: Option<i64>| {
        format!(
            "G10{} sets {} on {} control and {} on {} control",
            what.map_or(String::new(), |l| format!(" L{l}")),
            g10_meaning(from, what),
            article(k.name, from),
            g10_meaning(to, what),
            article(k.name, to)
        )
    };
    if l != Some(2) {
        return differs(l_word.unwrap_or(g10), both(l));
    }
    if let Some(r) = word(k, b'R') {
        return differs(
            r,
            "LinuxCNC's G10 L2 R rotates coordinate system P about Z; a FANUC or Haas G10 L2 \
             has no rotation"
                .into(),
        );
    }
    if !matches!(p, Some(1..=6)) {
        let w = word(k, b'P').unwrap_or(g10);
        return differs(
            w,
            "G10 L2 P0 is the external work offset on a FANUC or Haas and the active \
             coordinate system on LinuxCNC, P7-P9 (G59.1-G59.3) LinuxCNC's only; P1-P6 \
             (G54-G59) are the same on both"
                .into(),
        );
    }
    if k.incremental {
        return differs(
            g10,
            "in G91 a FANUC or Haas adds G10 L2's values to the work offset, LinuxCNC sets \
             them as written"
                .into(),
        );
    }
    Ok(())
}

/// What a numbered variable is on a control of `family`, and whether the family leaves it to
/// the program (a user variable). Custom Macro B: FANUC 0i-MF operator's manual, "Custom
/// macro", "Types of variables" and "System variables" (#1-#33 local, #100-#199 and #500-#999
/// common, #1000 up system: #3000 the alarm, #3006 the stop with a message, #4001-#4130 modal
/// information, #5001-#5120 positions, #5201-#5340 work offsets). LinuxCNC: G-code reference,
/// "Numbered Parameters" (rs274ngc `interp_parameter_def.hh`: #1-#30 a call's arguments,
/// #31-#5000 user parameters, #5061-#5601 the interpreter's). ISO 6983-1 6.4.7 gives its
/// parameters no fixed meaning.
fn variable(family: Family, n: u64) -> (&'static str, bool) {
    match family {
        Family::MacroB => match n {
            0 => ("the vacant (null) variable", false),
            1..=33 => ("a local variable", true),
            100..=999 => ("a common variable", true),
            34..=99 => ("no variable (the control alarms)", false),
            1000..=1999 => ("an interface signal (PMC) variable", false),
            2000..=2999 => ("a tool offset value", false),
            3000 => (
                "the macro alarm: writing it stops the program with an alarm",
                false,
            ),
            3001 | 3002 => ("a clock", false),
            3003 | 3004 => ("the single block and feed hold control", false),
            3006 => (
                "the stop with a message: writing it stops the program",
                false,
            ),
            3007 => ("the mirror image state", false),
            3011 | 3012 => ("the date or time", false),
            3901 | 3902 => ("the parts count", false),
            4001..=4999 => (
                "modal information (the G codes, D F H M N O S T in force)",
                false,
            ),
            5001..=5020 => ("the block end position of an axis", false),
            5021..=5060 => ("the current position of an axis", false),
            5061..=5080 => ("the skip signal position of an axis", false),
            5081..=5120 => ("a tool length offset value or servo deviation", false),
            5201..=5340 => ("a work offset value (external, G54-G59)", false),
            7001..=7999 | 14001..=19999 => ("an additional work offset value (G54.1 P)", false),
            _ => ("a system variable", false),
        },
        Family::LinuxCnc => match n {
            1..=30 => ("a call's argument, a parameter of the main program", true),
            31..=5000 => ("a user parameter", true),
            5061..=5070 => ("the probe result (G38)", false),
            5161..=5169 => ("the G28 home position", false),
            5181..=5189 => ("the G30 position", false),
            5210..=5219 => ("the G92 offset", false),
            5220 => ("the number of the active coordinate system", false),
            5221..=5390 => (
                "a coordinate system's offset or rotation (G54-G59.3), in machine units",
                false,
            ),
            5399 => ("the result of M66", false),
            5400 => ("the number of the tool in the spindle", false),
            5401..=5413 => (
                "the loaded tool's offsets, diameter, orientation or angles",
                false,
            ),
            5420..=5428 => ("the current position of an axis", false),
            5599..=5601 => ("an interpreter or tool changer flag", false),
            _ => (
                "a parameter of no documented use (nothing sets it: it reads 0)",
                false,
            ),
        },
        _ => ("a parameter (ISO 6983-1 6.4.7: no fixed meaning)", true),
    }
}

/// Numbered variables between the families that read `#`: a variable the two families both
/// leave to the program (Custom Macro B #1-#33 and #100-#999, LinuxCNC #1-#5000, ISO any) is
/// carried; any other is refused naming both meanings, as is a variable chosen by a value
/// (`#[#1]`: which one, the text does not show) and a LinuxCNC named parameter (`#<x>`,
/// `#<_metric>`), which the other families do not read. (An ISO 6983-1 profile reads `#` only
/// where its dialect allows it; the converter refuses `#` for a target whose dialect does not
/// before these rules: `ConvertConfig::target_dialect`.)
fn variables(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let hash = |f: Family| matches!(f, Family::Iso | Family::MacroB | Family::LinuxCnc);
    if !hash(from) || !hash(to) {
        return Ok(());
    }
    for w in k.words.iter().filter(|w| w.token.contains(&b'#')) {
        let t = w.token;
        for variable_named in hash_variables(t) {
            let n = match variable_named {
                HashVariable::Chosen { named } => {
                    let what = if named {
                        "a named parameter, which only a LinuxCNC control reads"
                    } else {
                        "a variable chosen by a value: which one the text does not show"
                    };
                    return Err(refuse(
                        w,
                        format!(
                            "{}: {what}, so not that it means the same on {} control; tapegate \
                             carries only variables both families leave to the program",
                            text(t),
                            article(k.name, to)
                        ),
                        "meaning",
                    ));
                }
                HashVariable::Number { n, .. } => n,
            };
            let (a, user_a) = variable(from, n);
            let (b, user_b) = variable(to, n);
            if user_a && user_b {
                continue;
            }
            return Err(refuse(
                w,
                format!(
                    "{}: #{n} is {a} on {} control and {b} on {} control; tapegate \
                     carries only the variables both families leave to the program (Custom \
                     Macro B #1-#33 and #100-#999, LinuxCNC #1-#5000): read or write the \
                     target's own variable for it",
                    text(t),
                    article(k.name, from),
                    article(k.name, to)
                ),
                "meaning",
            ));
        }
    }
    Ok(())
}

/// The names an expression in `[ ]` may hold on a family that reads them: the operators and
/// functions of Custom Macro B and of LinuxCNC (the longest first, so that a name run on into
/// the next, `NEFIX`, is split as the controls read it).
const EXPRESSION_NAMES: [&str; 30] = [
    "EXISTS", "ROUND", "ACOS", "ASIN", "ATAN", "SQRT", "AND", "XOR", "MOD", "ABS", "COS", "EXP",
    "FIX", "FUP", "SIN", "TAN", "BIN", "BCD", "ADP", "POW", "ATN", "SQR", "OR", "LN", "EQ", "NE",
    "GT", "GE", "LT", "LE",
];

/// What an operator or function of an expression computes on a control of `family`, None
/// where the family has no such name (the control alarms). Two families carry an expression
/// only where every name in it has the same text here. LinuxCNC: G-code reference, "Binary
/// Operators" and "Functions" (AND OR XOR logical, 1 or 0; ATAN[y]/[x] -180 to 180; ASIN -90
/// to 90; FIX rounds down, FUP up; ROUND to the nearest integer), as rs274 2.9 computes them
/// (`FIX[-1.2]` -2, `FUP[-1.2]` -1, `-7 MOD 3` 2, `[2 OR 4]` 1, `[2 XOR 3]` 0; ROUND a half
/// away from zero, `ROUND[-1.5]` -2, `ROUND[-2.5]` -3, `ROUND[2.5]` 3: interp_execute.cc
/// `execute_unary`, `(int)(x + (x < 0 ? -0.5 : 0.5))`; issue 32). Custom Macro
/// B: FANUC 0i-MF operator's manual, "Arithmetic and logic operation" (OR XOR AND bitwise;
/// ATAN 0 to 360 and ASIN 270 to 90 with parameter NAT (No. 6004#0) 0, -180 to 180 and -90 to
/// 90 with NAT 1; FIX discards the fraction, FUP raises it to a unit, both on the absolute
/// value; ROUND within an address rounds to the address's least input increment; how ROUND
/// rounds a negative half no FANUC page at hand says); the Haas mill operator's manual
/// (96-8000, "Macros": OR XOR AND on the integer part's bits, ROUND in an address to its
/// precision; in an arithmetic expression "a fractional part greater than or equal to .5 is
/// rounded up to the next whole integer; otherwise, the fractional part is truncated", which
/// leaves a negative half open: -2 or -3 for -2.5). So ROUND stays refused between LinuxCNC
/// and Custom Macro B even in a plain assignment: the two agree except on a negative half,
/// which no page at hand settles on the FANUC or Haas side (issue 32, item 3). ISO 6983-1 6.4.7 leaves every operation to the control's
/// manual: no name has a meaning there that another family's could be compared with.
fn expression_name(family: Family, name: &str) -> Option<&'static str> {
    let shared = match name {
        "SIN" => Some("the sine of an angle in degrees"),
        "COS" => Some("the cosine of an angle in degrees"),
        "TAN" => Some("the tangent of an angle in degrees"),
        "ACOS" => Some("the arc cosine in degrees, 0 to 180"),
        "SQRT" => Some("the square root"),
        "ABS" => Some("the absolute value"),
        "LN" => Some("the natural logarithm"),
        "EXP" => Some("e to the power of the argument"),
        _ => None,
    };
    match family {
        Family::LinuxCnc => shared.or(match name {
            "ASIN" => Some("the arc sine in degrees, -90 to 90"),
            "ATAN" => Some("the arc tangent ATAN[y]/[x] in degrees, -180 to 180"),
            "ROUND" => {
                Some("rounding to the nearest integer, a half away from zero (ROUND[-2.5] is -3)")
            }
            "FIX" => Some("rounding down (FIX[-1.2] is -2)"),
            "FUP" => Some("rounding up (FUP[-1.2] is -1)"),
            "AND" => Some("a logical AND, 1 or 0 (`[2 AND 1]` is 1)"),
            "OR" => Some("a logical OR, 1 or 0 (`[2 OR 4]` is 1)"),
            "XOR" => Some("a logical exclusive OR, 1 or 0 (`[2 XOR 3]` is 0)"),
            "MOD" => Some("the remainder made positive (`[-7 MOD 3]` is 2)"),
            "EQ" | "NE" | "GT" | "GE" | "LT" | "LE" => Some("a comparison whose value is 1 or 0"),
            "**" => Some("a power"),
            "EXISTS" => Some("whether a named parameter exists"),
            _ => None,
        }),
        Family::MacroB => shared.or(match name {
            "ASIN" => {
                Some("the arc sine in degrees, 270 to 90 (-90 to 90 only with parameter NAT 1)")
            }
            "ATAN" => Some(
                "the arc tangent ATAN[y]/[x] in degrees, 0 to 360 (-180 to 180 only with \
                 parameter NAT 1)",
            ),
            "ROUND" => Some(
                "rounding to the nearest integer (a negative half, ROUND[-2.5], in no page at \
                 hand), but within an address's expression to the address's least input \
                 increment",
            ),
            "FIX" => Some("discarding the fraction (FIX[-1.2] is -1)"),
            "FUP" => Some("raising the fraction to a unit (FUP[-1.2] is -2)"),
            "AND" => Some("a bitwise AND of the integer parts (`[2 AND 1]` is 0)"),
            "OR" => Some("a bitwise OR of the integer parts (`[2 OR 4]` is 6)"),
            "XOR" => Some("a bitwise exclusive OR of the integer parts (`[2 XOR 3]` is 1)"),
            "MOD" => Some("the remainder (of a negative operand, in no page at hand)"),
            "EQ" | "NE" | "GT" | "GE" | "LT" | "LE" => {
                Some("a comparison of a condition (IF, WHILE)")
            }
            "BIN" | "BCD" => Some("a conversion between BCD and binary"),
            "ADP" => Some("a decimal point added to the argument"),
            "POW" => Some("a power"),
            "ATN" | "SQR" => Some("the abbreviated ATAN or SQRT"),
            _ => None,
        }),
        _ => None,
    }
}

/// The first operation written outside `[ ]` after a value in a word's `token` (`#1=#2*3`,
/// `X#2+1`, `#4=SIN[30]*2`, `#5=#2OR#3`): its byte offset in the token. A Custom Macro B
/// control reads such a value as an expression; LinuxCNC reads a binary operation only inside
/// `[ ]` (rs274ngc read_real_expression; outside them read_items stops: "Bad character '*'
/// used", "Bad character 'o' used"). A sign before the value (`#3=-#2`, `X-1.`) is no
/// operation. None for a plain number, a parameter, and a bracketed expression.
pub(crate) fn bare_operator(token: &[u8]) -> Option<usize> {
    // the address: `#n=` / `#<name>=` of an assignment, else the letter (and an index `=`)
    let value = if token.first() == Some(&b'#') {
        token.iter().position(|&c| c == b'=')? + 1
    } else {
        let letter = usize::from(token.first().is_some_and(u8::is_ascii_alphabetic));
        letter + usize::from(token.get(letter) == Some(&b'='))
    };
    let mut seen = false;
    // ATAN's two arguments, `ATAN[y]/[x]`: its `/` is no operation (`atan` set by the name,
    // then `divide` for the `/` after its first argument's `]`)
    let (mut atan, mut divide) = (false, false);
    let mut i = value;
    while i < token.len() {
        let c = token[i];
        if divide && c != b' ' && c != b'\t' {
            divide = false;
            if c == b'/' {
                seen = false;
                i += 1;
                continue;
            }
        }
        match c {
            b'[' => {
                // inside the brackets only their depth counts (an operation there is read by
                // every family): on to the matching `]` by the brackets alone (memchr2)
                let mut open = 1usize;
                let mut j = i + 1;
                while open > 0 {
                    j += memchr::memchr2(b'[', b']', &token[j..])?;
                    open = if token[j] == b'[' { open + 1 } else { open - 1 };
                    j += 1;
                }
                divide = std::mem::take(&mut atan);
                seen = true;
                i = j;
                continue;
            }
            b']' => seen = true, // a `]` with no `[`
            b'A' | b'a'
                if token[i..].len() >= 4 && token[i..i + 4].eq_ignore_ascii_case(b"ATAN") =>
            {
                if seen {
                    return Some(i);
                }
                atan = true;
                i += 4;
                continue;
            }
            b'<' => {
                // a LinuxCNC named parameter `#<name>`: its name may hold any character
                i += token[i..]
                    .iter()
                    .position(|&c| c == b'>')
                    .unwrap_or(token.len() - i);
                seen = true;
            }
            b'*' | b'/' | b'+' | b'-' if seen => return Some(i),
            b'*' | b'/' | b'+' | b'-' | b'#' | b' ' | b'\t' => {}
            b'0'..=b'9' | b'.' => seen = true,
            _ if c.is_ascii_alphabetic() && seen => return Some(i),
            _ => seen = false,
        }
        i += 1;
    }
    None
}

/// The first operator or function name (upper case) in an expression word's `token` whose
/// meaning `differs` says is not the same on both families: the name, None when every one is.
fn expression_names(token: &[u8], mut differs: impl FnMut(&str) -> bool) -> Option<String> {
    // the word's address letter first (`X[..]`, `Xsin[30]`): from there on the value
    let mut i = usize::from(token.first().is_some_and(u8::is_ascii_alphabetic));
    while i < token.len() {
        let c = token[i];
        if c == b'<' {
            // a LinuxCNC named parameter `#<name>`: refused by the variables' rule
            i += token[i..]
                .iter()
                .position(|&c| c == b'>')
                .map_or(token.len(), |p| p + 1);
            continue;
        }
        if c == b'*' && token.get(i + 1) == Some(&b'*') {
            if differs("**") {
                return Some("**".into());
            }
            i += 2;
            continue;
        }
        if !c.is_ascii_alphabetic() {
            i += 1;
            continue;
        }
        let run = token[i..]
            .iter()
            .take_while(|c| c.is_ascii_alphabetic())
            .count();
        let upper = token[i..i + run].to_ascii_uppercase();
        let mut at = 0;
        while at < run {
            let name = EXPRESSION_NAMES
                .iter()
                .find(|n| upper[at..].starts_with(n.as_bytes()));
            match name {
                Some(n) => {
                    if differs(n) {
                        return Some((*n).to_string());
                    }
                    at += n.len();
                }
                None => return Some(String::from_utf8_lossy(&upper[at..]).into_owned()),
            }
        }
        i += run;
    }
    None
}

/// Expressions between the families that read `[ ]` expressions (Custom Macro B, LinuxCNC,
/// ISO 6983-1 as tapegate reads it): an expression is carried only where every operator and
/// function in it computes the same on both ([`expression_name`]); `X[2 OR 4]` is 1 on a
/// LinuxCNC and 6 on a FANUC, `ATAN[-1]/[1]` -45 and 315 (review 19, finding 2). The word is
/// refused naming the first that differs, with both meanings. A SINUMERIK reads `[ ]` as an
/// array's index and writes an expression `X=(..)`: a bracketed expression carried to it is
/// refused whole.
fn expressions(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let bracket = |f: Family| matches!(f, Family::Iso | Family::MacroB | Family::LinuxCnc);
    if from == Family::Okuma {
        // an OSP sets an address by an expression written `X=..` (docs/dialects.md, Okuma):
        // another family reads no `=` in an address, nor the OSP's functions as no page at
        // hand sets beside theirs
        let written = |w: &&Word<'_>| {
            w.token[0].is_ascii_alphabetic() && w.token.iter().any(|&c| c == b'=' || c == b'[')
        };
        if let Some(w) = k.words.iter().find(written) {
            return Err(refuse(
                w,
                format!(
                    "{}: an Okuma OSP's expression (an address set by `=`), which {} control \
                     does not read in that form, and whose functions no page at hand compares \
                     with its: tapegate does not translate expressions between families",
                    text(w.token),
                    article(k.name, to)
                ),
                "meaning",
            ));
        }
        return Ok(());
    }
    if !bracket(from) {
        return Ok(());
    }
    // (a value with an operation outside `[ ]`, `#1=#2*#3`, is an expression too: review 20,
    // finding 1)
    let expression = |w: &&Word<'_>| w.token.contains(&b'[') || bare_operator(w.token).is_some();
    for w in k.words.iter().filter(expression) {
        if to == Family::Okuma && w.token.contains(&b'[') {
            return Err(refuse(
                w,
                format!(
                    "{}: an expression in [ ] after an address, which an Okuma OSP writes \
                     X=.. (docs/dialects.md, Okuma), and whose functions no page at hand \
                     compares with the OSP's: tapegate does not translate expressions between \
                     families",
                    text(w.token)
                ),
                "meaning",
            ));
        }
        if to == Family::Sinumerik && w.token.contains(&b'[') {
            return Err(refuse(
                w,
                format!(
                    "{}: an expression in [ ], which a SINUMERIK reads as an array's index (its \
                     expressions are written X=(..), Programming Manual Fundamentals): \
                     tapegate does not translate expressions between families",
                    text(w.token)
                ),
                "meaning",
            ));
        }
        if !bracket(to) {
            continue;
        }
        let differs = |n: &str| {
            let (a, b) = (expression_name(from, n), expression_name(to, n));
            a.is_none() || a != b
        };
        if let Some(name) = expression_names(w.token, differs) {
            let meaning = |f: Family| match expression_name(f, &name) {
                Some(m) => m.to_string(),
                None if f == Family::Iso => {
                    "an operation ISO 6983-1 (6.4.7) leaves to the control's manual".to_string()
                }
                None => "no operator or function of that name".to_string(),
            };
            return Err(refuse(
                w,
                format!(
                    "{}: {name} is {} on {} control and {} on {} control; tapegate carries an \
                     expression between families only where every operator and function in it \
                     computes the same on both: write the target's own expression",
                    text(w.token),
                    meaning(from),
                    article(k.name, from),
                    meaning(to),
                    article(k.name, to)
                ),
                "meaning",
            ));
        }
        // every operation means the same: LinuxCNC still reads one only inside `[ ]`
        if let Some(at) = bare_operator(w.token).filter(|_| to == Family::LinuxCnc) {
            let op = w.token[at] as char;
            return Err(refuse(
                w,
                format!(
                    "{}: '{op}' after a value outside [ ], which {} control reads as an \
                     expression and LinuxCNC refuses (rs274ngc reads a binary operation only \
                     inside [ ]: \"Bad character '{}' used\"); tapegate does not rewrite \
                     expressions between families: write the value in [ ]",
                    text(w.token),
                    article(k.name, from),
                    op.to_ascii_lowercase()
                ),
                "meaning",
            ));
        }
    }
    Ok(())
}

/// The letters a family reads a G33 thread's lead from: F on a FANUC or Haas (0i-MF "Thread
/// cutting (G33)": F the lead), K on LinuxCNC (G-code reference, G33: "K - distance per
/// revolution" along the move), I J K on a SINUMERIK and by ISO 6983-1 (the lead parallel to
/// X, Y, Z; Programming Manual Fundamentals, "Thread cutting with constant lead G33").
fn lead_letters(family: Family) -> Option<&'static [u8]> {
    match family {
        Family::MacroB => Some(b"F"),
        Family::LinuxCnc => Some(b"K"),
        Family::Sinumerik | Family::Iso => Some(b"IJK"),
        _ => None,
    }
}

/// A G33 thread's lead between families that give it by other letters: a SINUMERIK's
/// or LinuxCNC's `G33 Z-20 K1.5` on a FANUC threads at the modal F (a feed) as its lead. The
/// one case read alike across the K families is a thread along Z only, its lead K: LinuxCNC's
/// K is the distance per revolution along the move, a SINUMERIK's (and ISO's) the lead along
/// Z, the same there; a taper or another axis's lead is refused.
fn thread_lead(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    if !k.gs.contains(&33) {
        return Ok(());
    }
    let (Some(a), Some(b)) = (lead_letters(from), lead_letters(to)) else {
        return Ok(());
    };
    let lead = k
        .words
        .iter()
        .find(|w| a.contains(&w.token[0].to_ascii_uppercase()));
    if a == b {
        return Ok(());
    }
    let along_z = !a.contains(&b'F')
        && !b.contains(&b'F')
        && lead.is_some_and(|w| w.token[0].eq_ignore_ascii_case(&b'K'))
        && !k.words.iter().any(|w| {
            matches!(
                w.token[0].to_ascii_uppercase(),
                b'X' | b'Y' | b'U' | b'V' | b'I' | b'J'
            )
        });
    if along_z {
        return Ok(());
    }
    let letters = |l: &[u8]| {
        l.iter()
            .map(|&c| (c as char).to_string())
            .collect::<Vec<_>>()
            .join(" ")
    };
    let g33 = k
        .words
        .iter()
        .find(|w| w.token[0].eq_ignore_ascii_case(&b'G') && whole(w) == Some(33));
    let Some(w) = lead.or(g33) else {
        return Ok(());
    };
    Err(refuse(
        w,
        format!(
            "{}: {} control reads G33's thread lead from {}, {} control from {}{}: \
             carried as written the target threads with another lead (a FANUC takes the F in \
             force, a feed, as the lead); tapegate does not rename words: write the target's \
             lead word",
            text(w.token),
            article(k.name, from),
            letters(a),
            article(k.name, to),
            letters(b),
            if a.contains(&b'F') || b.contains(&b'F') {
                ""
            } else {
                " (LinuxCNC's K along the move, the others' along their axis: alike only \
                 for a thread along Z)"
            }
        ),
        "meaning",
    ))
}

/// LinuxCNC's helix turn count, P of G2/G3 ("P - number of turns", G-code reference, G2/G3):
/// no other family's arc has one (a FANUC's helical interpolation, ISO 6983's and a
/// SINUMERIK's G2/G3 take no P; a SINUMERIK writes TURN=), so the target alarms or cuts one
/// turn: the helix descends in a fraction of the turns, steeper. Refused.
fn helix_turns(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    if from != Family::LinuxCnc || to == Family::LinuxCnc || k.cycle {
        return Ok(());
    }
    // the block's own arc code, or an arc in force in a block of no code that takes P
    let own = k.gs.iter().any(|&g| g == 2 || g == 3);
    let neutral = |g: &i64| matches!(g, 17..=19 | 90 | 91 | 93 | 94 | 95 | 40..=42);
    let modal = matches!(k.motion, Some(2 | 3)) && k.ms.is_empty() && k.gs.iter().all(neutral);
    if !own && !modal {
        return Ok(());
    }
    let Some(p) = word(k, b'P') else {
        return Ok(());
    };
    Err(refuse(
        p,
        format!(
            "{}: LinuxCNC's number of turns of a helix (G2/G3 P); {} control's arc has no \
             turn count, so it alarms or cuts the helix's whole descent in one turn; tapegate \
             does not split helices: write the turns as arcs of their own",
            text(p.token),
            article(k.name, to)
        ),
        "meaning",
    ))
}

/// LinuxCNC's spindle speed limit in a G96 block, D ("G96 D- S- ... D - maximum spindle
/// speed", G-code reference, G96): another family reads a D as an offset number (FANUC, Haas:
/// the cutter compensation offset G41/G42 take; a SINUMERIK: the tool edge's data) and limits
/// the speed by a code of its own (G50 S or G92 S, LIMS=): carried, the limit is lost and the
/// next compensation takes another radius. Refused.
fn spindle_limit(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let Some(d) = linuxcnc_word(from, to, k, 96, b"D") else {
        return Ok(());
    };
    Err(refuse(
        d,
        format!(
            "{}: LinuxCNC's maximum spindle speed under G96 (G96 D); {} control reads D as an \
             offset number and limits the speed by a code of its own, so the limit would be \
             lost: write the target's spindle limit",
            text(d.token),
            article(k.name, to)
        ),
        "meaning",
    ))
}

/// LinuxCNC's path blending tolerances, G64 P (blending tolerance) and Q (naive CAM tolerance;
/// G-code reference, G64). G64 without them keeps the best speed with no exact stop at block
/// ends, the cutting mode of FANUC, Haas and OSP and SINUMERIK's continuous-path mode (their
/// profiles share the key `cutting-mode`), so it is carried; no other family's G64 reads a
/// tolerance (a FANUC alarms on the P or ignores it, a SINUMERIK takes its tolerance from
/// G641 ADIS=), so the path would deviate by another amount than the program allows. Refused.
fn blending_tolerance(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let Some(w) = linuxcnc_word(from, to, k, 64, b"PQ") else {
        return Ok(());
    };
    Err(refuse(
        w,
        format!(
            "{}: LinuxCNC's path blending tolerance (G64 P, Q); {} control's G64 takes no \
             tolerance, so the path would deviate by another amount than the program allows: \
             write the target's own tolerance, or G64 alone",
            text(w.token),
            article(k.name, to)
        ),
        "meaning",
    ))
}

/// A Haas's spindle orientation angle, M19 P (whole degrees) or R (degrees with a decimal
/// point; Haas mill operator's manual, "M19 Orient Spindle"). M19 alone orients the spindle to
/// the position its setting or parameter holds on every control whose profile keys M19
/// `spindle-orient` (FANUC, Haas, OSP, SINUMERIK); the angle is the Haas's own: a FANUC's M19
/// takes none, a SINUMERIK positions by SPOS=. Refused where the target is not a Haas.
fn orient_angle(words: &[Word<'_>], name: Name, to: Family) -> Result<(), Refusal> {
    let Some(w) = words
        .iter()
        .find(|w| matches!(w.token[0].to_ascii_uppercase(), b'P' | b'R'))
    else {
        return Ok(());
    };
    Err(refuse(
        w,
        format!(
            "{}: a Haas's spindle orientation angle (M19 P, R); {} control's M19 takes no \
             angle and orients to the position its parameters hold: write the target's own \
             spindle positioning",
            text(w.token),
            article(name, to)
        ),
        "meaning",
    ))
}

/// A subprogram call or return by M98/M99 (and a Haas's M97) from a FANUC, Haas or LinuxCNC
/// (2.9: "M98 and M99", Fanuc style) to a family that calls otherwise: a SINUMERIK
/// calls by the program's name or `L` and returns by RET/M17, so M98/M99 are M functions
/// handed to the PLC and the program runs on without the subprogram (Programming Manual
/// Fundamentals, "Subroutines"); a HEIDENHAIN's M98 and M99 are its own functions, an Okuma's
/// M98 its own (CALL O calls), ISO 6983-1 leaves M98 and M99 unassigned. Refused.
fn subprogram_calls(from: Family, to: Family, k: &Block<'_>) -> Result<(), Refusal> {
    let calls_by_m = |f: Family| matches!(f, Family::MacroB | Family::LinuxCnc);
    if !calls_by_m(from) || calls_by_m(to) {
        return Ok(());
    }
    let m = k.words.iter().find(|w| {
        w.token[0].eq_ignore_ascii_case(&b'M')
            && match whole(w) {
                Some(98 | 99) => true,
                // Haas's local subprogram call
                Some(97) => from == Family::MacroB,
                _ => false,
            }
    });
    let Some(w) = m else {
        return Ok(());
    };
    Err(refuse(
        w,
        format!(
            "{}: a subprogram call or return on {} control; {} control calls and returns \
             by other means (a SINUMERIK by the program's name or L and RET, a HEIDENHAIN by \
             L, an Okuma by CALL) and reads this M code as another function, so the \
             subprogram would not run; tapegate does not translate subprogram calls between \
             families",
            text(w.token),
            article(k.name, from),
            article(k.name, to)
        ),
        "meaning",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_operation_outside_brackets_after_a_value_is_found() {
        // review 20, finding 1 (each compared with rs274 -g: "Bad character '*' used")
        assert_eq!(bare_operator(b"#1=#2*#3"), Some(5));
        assert_eq!(bare_operator(b"#4=SIN[30]*2"), Some(10));
        assert_eq!(bare_operator(b"#1=[#2+2]*3"), Some(9));
        assert_eq!(bare_operator(b"#4=#<a>/2"), Some(7));
        assert_eq!(bare_operator(b"X#2+1"), Some(3));
        assert_eq!(bare_operator(b"#5=#2OR#3"), Some(5));
        assert_eq!(bare_operator(b"#1=2-1"), Some(4));
        // a sign, a bracketed expression, ATAN's two arguments: no operation outside [ ]
        for plain in [
            &b"#3=-#2"[..],
            b"X-1.5",
            b"Y-[#1]",
            b"X[#1+2]",
            b"#1=ATAN[#2]/[1]",
            b"#1=[ATAN[1]/[2]*[1]]",
            b"G01",
            b"#1=#2",
            b"#<a-b>=#<c-d>",
        ] {
            assert_eq!(bare_operator(plain), None, "{}", text(plain));
        }
        // ... but an operation after ATAN's second argument is one
        assert_eq!(bare_operator(b"#1=ATAN[1]/[2]*3"), Some(14));
    }

    /// `bare_operator` as first written, walking every byte inside the brackets: the fast
    /// one (to the matching `]` by memchr2) must find what it finds on any token.
    fn bare_operator_bytewise(token: &[u8]) -> Option<usize> {
        let value = if token.first() == Some(&b'#') {
            token.iter().position(|&c| c == b'=')? + 1
        } else {
            let letter = usize::from(token.first().is_some_and(u8::is_ascii_alphabetic));
            letter + usize::from(token.get(letter) == Some(&b'='))
        };
        let (mut depth, mut seen) = (0usize, false);
        let (mut atan, mut divide) = (None, false);
        let mut i = value;
        while i < token.len() {
            let c = token[i];
            if divide && c != b' ' && c != b'\t' {
                divide = false;
                if c == b'/' {
                    seen = false;
                    i += 1;
                    continue;
                }
            }
            match c {
                b'[' => {
                    if atan == Some(usize::MAX) {
                        atan = Some(depth);
                    }
                    depth += 1;
                }
                b']' => {
                    depth = depth.saturating_sub(1);
                    if atan == Some(depth) {
                        atan = None;
                        divide = true;
                    }
                    seen = depth == 0;
                }
                _ if depth > 0 => {}
                b'A' | b'a'
                    if token[i..].len() >= 4 && token[i..i + 4].eq_ignore_ascii_case(b"ATAN") =>
                {
                    if seen {
                        return Some(i);
                    }
                    atan = Some(usize::MAX);
                    i += 4;
                    continue;
                }
                b'<' => {
                    i += token[i..]
                        .iter()
                        .position(|&c| c == b'>')
                        .unwrap_or(token.len() - i);
                    seen = true;
                }
                b'*' | b'/' | b'+' | b'-' if seen => return Some(i),
                b'*' | b'/' | b'+' | b'-' | b'#' | b' ' | b'\t' => {}
                b'0'..=b'9' | b'.' => seen = true,
                _ if c.is_ascii_alphabetic() && seen => return Some(i),
                _ => seen = false,
            }
            i += 1;
        }
        None
    }

    #[test]
    fn the_fast_bracket_walk_finds_what_the_bytewise_one_finds() {
        // tokens drawn from the bytes that matter (brackets, ATAN's letters, operators, names,
        // digits, '=' and '#'), 200,000 of them, up to 14 bytes, by a fixed xorshift
        let alphabet = b"[[]]ATNatn*/+-#<>=1.2XOR ";
        let mut next = crate::drawn::xorshift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..200_000 {
            let len = (next() % 15) as usize;
            let mut token: Vec<u8> = (0..len)
                .map(|_| alphabet[(next() % alphabet.len() as u64) as usize])
                .collect();
            if next().is_multiple_of(2) {
                token.splice(0..0, b"#1=".iter().copied());
            } else if next().is_multiple_of(2) {
                token.splice(0..0, b"XATAN[".iter().copied());
            }
            assert_eq!(
                bare_operator(&token),
                bare_operator_bytewise(&token),
                "{}",
                text(&token)
            );
        }
    }

    fn words(line: &str) -> Vec<Word<'_>> {
        let mut at = 0;
        line.split(' ')
            .map(|t| {
                let w = Word {
                    token: t.as_bytes(),
                    start: at,
                };
                at += t.len() + 1;
                w
            })
            .collect()
    }

    #[test]
    fn fanuc_and_haas_read_some_g10_data_and_lathes_their_g50_axes_apart() {
        let refused = |from_haas, line: &str, gs: &[i64]| {
            fanuc_haas_words(from_haas, false, &words(line), gs)
                .err()
                .map(|r| r.at)
        };
        // L12 (radius on a FANUC, diameter on a Haas), L13, L1: refused at the L word
        assert_eq!(refused(false, "G10 L12 P1 R5.", &[10]), Some(4));
        let message = fanuc_haas_words(false, false, &words("G10 L12 P1 R5."), &[10])
            .unwrap_err()
            .message;
        assert!(
            message.contains("radius geometry") && message.contains("diameter geometry"),
            "{message}"
        );
        assert_eq!(refused(true, "G10 L13 P1 R0.1", &[10]), Some(4));
        assert_eq!(refused(true, "G10 L1 P1 R0.1", &[10]), Some(4));
        // L2 P0: the external offset against G52, at the P
        assert_eq!(refused(false, "G10 L2 P0 X1.", &[10]), Some(7));
        // one datum on both: length geometry and wear, G54-G59, the extra work offsets
        for line in [
            "G10 L10 P1 R100.",
            "G10 L11 P1 R0.1",
            "G10 L2 P1 X1.",
            "G10 L20 P1 X1.",
        ] {
            assert_eq!(refused(false, line, &[10]), None, "{line}");
        }
        // a lathe's G50: S alone is the clamp on every lathe control; an axis word is not
        // one function
        let g50 = |line: &str| lathe_g50_axes(&words(line), &[50]).err().map(|r| r.at);
        assert_eq!(g50("G50 S2000"), None);
        assert_eq!(g50("G50 X100. Z50."), Some(4));
        assert_eq!(g50("G50 S2000 W-1."), Some(10));
        // no G10 or G50 in the block
        assert_eq!(refused(false, "G01 X1. L12", &[1]), None);
    }

    #[test]
    fn fanuc_and_haas_carry_only_the_variables_they_read_alike() {
        let refused_on = |from_haas, lathe, line: &str| {
            fanuc_haas_variables(from_haas, lathe, &words(line))
                .err()
                .map(|r| r.message)
        };
        let refused = |from_haas, line: &str| refused_on(from_haas, false, line);
        for line in [
            "#1=#5221",
            "#101=[#5021+#4001]",
            "#500=#14001",
            "#1=#3000",
            "#1=#0",
            "#3004=2",
            "#3003=1",
            "#3003=0.",
            "#1=#4003+#4016+#4120",
            "#1=#7006+#14386",
        ] {
            assert_eq!(refused(true, line), None, "{line}");
            assert_eq!(refused(false, line), None, "{line}");
        }
        // another use on the Haas (the G52 offset, the NGC's numbers, an element, the probe's
        // calibration), a group numbered apart (FANUC's 14 is the work system, the Haas's 12),
        // FANUC's #3003 bit 1, an axis past C of a work offset, or chosen by a value
        for line in [
            "#1=#5201",
            "#10100=1.",
            "#1=#30003.078",
            "#1=#101.5",
            "#550=1.",
            "#1=#580",
            "#1=#4014",
            "#1=#4012",
            "#1=#4004",
            "#1=#4124",
            "#1=#4114",
            "#3003=2",
            "#3003=#1",
            "#1=#3003",
            "#1=#5227",
            "#1=#7007",
            "#1=#14021+#14027",
            "#750=1.",
            "#[#1]=1.",
        ] {
            assert!(refused(true, line).is_some(), "{line}");
            assert!(refused(false, line).is_some(), "{line}");
        }
        let m = refused(false, "#1=#2001").unwrap();
        assert!(
            m.contains("a tool offset value on a FANUC") && m.contains("length or diameter"),
            "{m}"
        );
        assert!(refused(false, "#555=1.")
            .unwrap()
            .contains("probe's calibration"));
        assert!(refused(false, "#720=1.")
            .unwrap()
            .contains("hidden variable"));
        assert!(refused(false, "#750=1.").unwrap().contains("does not list"));
        assert!(refused(false, "#3003=3")
            .unwrap()
            .contains("values 2 and 3"));
        let element = refused(true, "#1=#101.5").unwrap();
        assert!(
            element.contains("outside the Haas NGC parameters") && !element.contains("element ("),
            "{element}"
        );
        assert!(refused(true, "#1=#30003.078")
            .unwrap()
            .contains("a Haas NGC parameter element"));
        // between lathes only the motion group, the letters, the alarm and the clocks: the
        // lathes' group numbers and axis orders are not in a table at hand
        for line in ["#1=#4001", "#1=#4120", "#3000=1", "#3004=1"] {
            assert_eq!(refused_on(false, true, line), None, "{line}");
        }
        for line in ["#1=#4005", "#1=#5001", "#1=#5041", "#1=#5221", "#1=#7001"] {
            assert!(refused_on(false, true, line).is_some(), "{line}");
            assert_eq!(refused_on(false, false, line), None, "{line}");
        }
    }

    #[test]
    fn single_block_suppression_is_carried_as_a_literal_0_or_1() {
        for t in [
            "#3003=1",
            "#3003=0",
            "#3003 = 1.",
            "#3003=1.0",
            "#3003=01",
            "#3003=.0",
        ] {
            assert!(single_block_literal(t.as_bytes()), "{t}");
        }
        for t in [
            "#3003=2",
            "#3003=1.5",
            "#3003=#1",
            "#3003=",
            "#3003=.",
            "#1=#3003",
            "#3003=10",
        ] {
            assert!(!single_block_literal(t.as_bytes()), "{t}");
        }
    }

    #[test]
    fn the_user_ranges_of_the_families_that_read_hash_variables() {
        // both leave #1-#33 and #100-#999 to the program
        for n in [1, 30, 33, 100, 199, 500, 999] {
            assert!(
                variable(Family::MacroB, n).1 && variable(Family::LinuxCnc, n).1,
                "#{n}"
            );
        }
        // a Custom Macro B system variable is a LinuxCNC parameter of another use, and back
        for n in [0, 1000, 2001, 3000, 3006, 4001, 5001, 5221, 7001] {
            assert!(!variable(Family::MacroB, n).1, "#{n}");
        }
        for n in [5061, 5221, 5400, 5420, 5601] {
            assert!(!variable(Family::LinuxCnc, n).1, "#{n}");
        }
        assert!(variable(Family::LinuxCnc, 40).1 && !variable(Family::MacroB, 40).1);
        assert_eq!(
            variable(Family::MacroB, 5001).0,
            "the block end position of an axis"
        );
        assert_eq!(
            variable(Family::LinuxCnc, 5420).0,
            "the current position of an axis"
        );
        assert!(variable(Family::Iso, 5001).1);
    }

    #[test]
    fn g10_forms_read_alike_only_for_l2() {
        for l in [Some(1), Some(10), Some(11), Some(20), None] {
            assert_ne!(
                g10_meaning(Family::MacroB, l),
                g10_meaning(Family::LinuxCnc, l),
                "L{l:?}"
            );
        }
        assert!(g10_meaning(Family::LinuxCnc, Some(12)).starts_with("no such G10 form"));
    }

    #[test]
    fn only_a_heidenhain_target_of_another_family_is_refused_whole() {
        assert!(frame(Family::MacroB, Family::Heidenhain, |_| "").is_some());
        assert!(frame(Family::Sinumerik, Family::Heidenhain, |_| "").is_some());
        assert!(frame(Family::Heidenhain, Family::Heidenhain, |_| "").is_none());
        assert!(frame(Family::Heidenhain, Family::MacroB, |_| "").is_none());
        assert!(frame(Family::MacroB, Family::LinuxCnc, |_| "").is_none());
    }

    #[test]
    fn an_expression_s_names_are_read_as_the_controls_read_them() {
        let differs = |from: Family, to: Family| {
            move |n: &str| {
                let a = expression_name(from, n);
                a.is_none() || a != expression_name(to, n)
            }
        };
        let lc_fanuc = || differs(Family::LinuxCnc, Family::MacroB);
        // the address letter is no name; SIN, COS and + - * / compute alike
        assert_eq!(expression_names(b"X[SIN[30]*COS[60]-1]", lc_fanuc()), None);
        assert_eq!(
            expression_names(b"x[2or4]", lc_fanuc()).as_deref(),
            Some("OR")
        );
        // names run on into each other are split, the longest first
        assert_eq!(
            expression_names(b"X[#1NEFIX[#2]]", lc_fanuc()).as_deref(),
            Some("NE")
        );
        assert_eq!(
            expression_names(b"#1=[SQRT[4]XOR1]", lc_fanuc()).as_deref(),
            Some("XOR")
        );
        assert_eq!(
            expression_names(b"X[2**3]", lc_fanuc()).as_deref(),
            Some("**")
        );
        // a name neither family has is refused as written; a named parameter is skipped
        assert_eq!(
            expression_names(b"X[FOO[1]]", lc_fanuc()).as_deref(),
            Some("FOO")
        );
        assert_eq!(expression_names(b"X[#<depth>+1]", lc_fanuc()), None);
        // FANUC to LinuxCNC: BCD is FANUC's alone
        let fanuc_lc = differs(Family::MacroB, Family::LinuxCnc);
        assert_eq!(
            expression_names(b"#1=BCD[12]", fanuc_lc).as_deref(),
            Some("BCD")
        );
        // ISO 6983-1 gives no operation a meaning
        let iso = differs(Family::LinuxCnc, Family::Iso);
        assert_eq!(expression_names(b"X[ABS[-1]]", iso).as_deref(), Some("ABS"));
        assert_eq!(
            expression_names(b"X[1+2]", differs(Family::LinuxCnc, Family::Iso)),
            None
        );
    }

    #[test]
    fn the_lead_letters_of_g33() {
        assert_eq!(lead_letters(Family::MacroB), Some(&b"F"[..]));
        assert_eq!(lead_letters(Family::LinuxCnc), Some(&b"K"[..]));
        assert_eq!(lead_letters(Family::Sinumerik), lead_letters(Family::Iso));
        assert_eq!(lead_letters(Family::Okuma), None);
    }
}
