//! G and M codes and their modal groups (rules TG301-TG307): each code of a block against
//! the profile's code table, its M class, and the other codes of its group in the block.

use super::{BlockView, Checker, Config, Status, Word};
use crate::decimal::Dec;
use crate::dialect;
use crate::lex::Family;
use crate::modal::{bit, AxesTaken};
use crate::rules::Rule;

/// What the checker looks up for a code word, without borrowing the profile.
#[derive(Clone, Copy)]
struct CodeFacts {
    status: Status,
    modal: bool,
}

/// A code of the profile's table as a block's word names it: a whole G or M code (its number
/// within its M class), or a decimal G code by its place in the profile's `g_decimal`. Two
/// words naming one code (`G01 G1`) are the same code.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum CodeRef {
    Whole(u8, i64),
    Decimal(usize),
}

impl Checker {
    /// Each G and M code of the block against the profile's table (TG301, TG302, TG303,
    /// TG305, TG306) and against the others of its modal group (TG304), decimal codes
    /// (`G54.1`, `G43.4`) by the group the table gives them as whole ones.
    pub(super) fn code_words(&mut self, b: &BlockView<'_>) {
        // (a block with no G or M word, as most of a CAM program's, has no code to check)
        if self.letters & (bit(b'G') | bit(b'M')) == 0 {
            return;
        }
        // codes met before without a word said (`G1`, `G2`, `G0 G90`): nothing to say again
        // (a debug build, the tests', checks them anyway and holds them to silence)
        let key = self.code_key;
        let silent = key.is_some_and(|k| self.verdicts.get(k) & SILENT != 0);
        if silent && !cfg!(debug_assertions) {
            return;
        }
        let reports = self.reports;
        let line = b.line;
        let words = b.words;
        let mut groups = std::mem::take(&mut self.groups);
        groups.clear();
        // the extended M codes so far (`M1=3`): their extension, code and word
        let mut spindles: Vec<(u64, CodeRef, usize)> = Vec::new();
        for (i, w) in words.iter().enumerate() {
            if !(w.letter == b'G' || w.letter == b'M') {
                continue;
            }
            let Some(value) = self.readable[i] else {
                if let Some((extension, code)) = self.extended_m_code(w, line) {
                    if extension == 0 {
                        // `M0=3`: the master spindle's, the plain `M3` (H2)
                        self.plain_m_code(words, &mut groups, &spindles, i, code, line);
                        continue;
                    }
                    // one spindle's modal group: against the codes of the same extension
                    let mut same: Vec<(CodeRef, usize)> = spindles
                        .iter()
                        .filter(|&&(other, _, _)| other == extension)
                        .map(|&(_, code, j)| (code, j))
                        .collect();
                    let before = same.len();
                    self.modal_group(words, &mut same, i, code, line);
                    // the master's (may be), none of its group before: against the plain codes
                    if self.may_be_master(extension) && same.len() > before {
                        self.master_spindle(words, &groups, extension, i, code, line);
                    }
                    spindles.push((extension, code, i));
                }
                continue;
            };
            if w.letter == b'G' && !value.is_whole() {
                if let Some(code) = self.decimal_code(w, value, line) {
                    self.modal_group(words, &mut groups, i, code, line);
                }
                continue;
            }
            let n = value.trunc();
            let number = self.m_class(w, n, line);
            let Some(facts) = self.code_facts(w, n, number, line) else {
                continue;
            };
            if facts.modal {
                let code = CodeRef::Whole(w.letter, number);
                self.plain_m_code(words, &mut groups, &spindles, i, code, line);
            }
        }
        self.groups = groups;
        if silent {
            debug_assert_eq!(
                self.reports, reports,
                "line {line}: codes kept as silent said"
            );
        } else if let Some(k) = key.filter(|_| self.reports == reports) {
            self.verdicts.add(k, SILENT);
        }
    }

    /// A plain code of word `i` (`M3`, or a SINUMERIK's `M0=3`, the same) against the block's
    /// plain ones (`groups`), and where it is the first of its group, against the extended M
    /// codes before it of the spindle that may be the master ([`Checker::may_be_master`]:
    /// `M1=4 M3`).
    fn plain_m_code(
        &mut self,
        words: &[Word<'_>],
        groups: &mut Vec<(CodeRef, usize)>,
        spindles: &[(u64, CodeRef, usize)],
        i: usize,
        code: CodeRef,
        line: usize,
    ) {
        let before = groups.len();
        self.modal_group(words, groups, i, code, line);
        // (a SINUMERIK's spindle codes before it: most blocks have none)
        if spindles.is_empty() || groups.len() == before {
            return;
        }
        let found = spindles
            .iter()
            .find(|&&(extension, other, _)| {
                self.may_be_master(extension)
                    && group_of_code(&self.config, other) == group_of_code(&self.config, code)
            })
            .copied();
        if let Some((extension, other, j)) = found {
            self.master_spindle(words, &[(other, j)], extension, i, code, line);
        }
    }

    /// Whether spindle `extension` may be the master spindle, the plain M function's
    /// ([`Master`]): spindle 1 by the machine data, the one the program's `SETMS(n)` named, or
    /// any where the checker cannot read which one a `SETMS` named.
    fn may_be_master(&self, extension: u64) -> bool {
        match self.master {
            Master::MachineData => extension == 1,
            Master::Set { spindle, .. } => extension == spindle,
            Master::Unknown { .. } => true,
        }
    }

    /// The master spindle a SINUMERIK's `SETMS` statement (`text`, on `line`) sets
    /// (Programming Manual Fundamentals, "Main spindle, master spindle": `SETMS(<spindle
    /// number>)` makes that spindle the master, `SETMS` alone returns to the machine data's):
    /// an argument the checker cannot read as a spindle's number (`SETMS(R1)` with R1 not
    /// set to a constant) leaves it unknown.
    ///
    /// A blank between the name and its parenthesis separates them (Programming Manual
    /// Fundamentals, "Blank": `SETMS (2)` is `SETMS(2)`, review 56d F3). A `SETMS` that may not
    /// run (`may_skip`: after a condition, a loop, a jump or a label, whose blocks the checker
    /// does not follow) leaves the master unknown, neither the one it names nor the one before
    /// (review 56d F8).
    pub(super) fn set_master(&mut self, text: &[u8], line: usize, may_skip: bool) {
        let end = crate::statement::ident_end(text, 0);
        let rest = text[end..].trim_ascii();
        let inside = match rest.first() {
            Some(b'(') if rest.ends_with(b")") => Some(rest[1..rest.len() - 1].trim_ascii()),
            None => Some(&[][..]),
            Some(_) => None, // not a SETMS the checker reads: any spindle may be the master
        };
        self.master = match inside {
            _ if may_skip => Master::Unknown {
                line,
                skipped: true,
            },
            Some([]) => Master::MachineData,
            Some(inside) => match self.sinumerik_constant(inside) {
                Some(n) if n.is_whole() && n > Dec::ZERO => Master::Set {
                    spindle: u64::try_from(n.trunc()).unwrap_or(u64::MAX),
                    line,
                },
                _ => Master::Unknown {
                    line,
                    skipped: false,
                },
            },
            None => Master::Unknown {
                line,
                skipped: false,
            },
        };
    }

    /// A SINUMERIK's M function with an extended address, `M2=3` (spindle 2 turns clockwise;
    /// Programming Manual Fundamentals, "Extended addresses" and "M functions": the extension
    /// is the spindle's number, the value "an arithmetic expression"): its code, where the
    /// checker knows it ([`Checker::extended_m_number`]: `M1=+77`, `M1=(77)`, `M1=R1` with R1
    /// set to 77), against the profile's table as the plain `M77` would be (TG306, TG307).
    /// The extension and the code, where it is modal, for the modal group of that one
    /// spindle: `M1=3 M1=4` conflict as `M3 M4` do, `M1=3 M2=4` are two spindles'. Not into
    /// the modal state: the spindle numbered is not the one the profile describes. An
    /// extension out of range (`M100=77`) is TG206 alone, its code not checked; a code the
    /// checker cannot tell is TG141's (`Checker::read_block`).
    fn extended_m_code(&mut self, w: &Word<'_>, line: usize) -> Option<(u64, CodeRef)> {
        if w.letter != b'M'
            || w.index.is_empty()
            || !dialect::extended_address(self.config.family, w.letter)
        {
            return None;
        }
        let extension = super::formats::written_index(w.index);
        if !self.index_allowed(w.letter, extension).0 {
            return None;
        }
        let n = self.extended_m_number(w)?;
        let number = self.m_class(w, n, line);
        let facts = self.code_facts(w, n, number, line)?;
        facts
            .modal
            .then_some((extension, CodeRef::Whole(w.letter, number)))
    }

    /// The code an extended M word (`M2=3`) gives: its value, a number with its sign or an
    /// expression the checker evaluates (numbers and R parameters or variables set to a
    /// constant), where that is a whole number from 0; None where the checker cannot tell a
    /// code (an expression it cannot evaluate, a value below 0 or with a fraction).
    pub(super) fn extended_m_number(&self, w: &Word<'_>) -> Option<i64> {
        let value = if w.expression.is_empty() {
            let value = Dec::parse(std::str::from_utf8(w.number).ok()?)?;
            if w.sign == b"-" {
                -value
            } else {
                value
            }
        } else {
            self.sinumerik_constant(w.expression)?
        };
        (value.is_whole() && value >= Dec::ZERO).then(|| value.trunc())
    }

    /// A code the profile's table does not have: TG301, an error, under ISO 6983-1; on a
    /// control family that warns (`checks.unknown_g`/`unknown_m = "warn"`: a Fanuc or Haas
    /// runs a G code its parameters make a macro call) TG307, a warning naming it.
    fn unknown_code(&mut self, w: &Word<'_>, line: usize) {
        if self.config.family == Family::Iso {
            let message = format!("{} is not a code of {}", w.token(), self.config.table_name);
            self.report(Rule::CodeNotInTable, message, line, w.column);
        } else {
            let effect =
                dialect::unknown_code_effect(self.config.family, self.config.haas, w.letter);
            let message = format!(
                "{} is not in the profile's {} code list: {effect}",
                w.token(),
                w.letter as char
            );
            self.report(Rule::CodeNotInProfile, message, line, w.column);
        }
    }

    /// A decimal G code (`G91.1`) is a code of its own: TG306 where the profile has none and
    /// the control alarms whatever its configuration (LinuxCNC's `G41.25`: two decimals), else
    /// TG301 (TG307: LinuxCNC's `G41.2`, "Unknown g code used" unless a REMAP defines it).
    /// The code, where it is modal and so has a group to check.
    fn decimal_code(&mut self, w: &Word<'_>, value: Dec, line: usize) -> Option<CodeRef> {
        match self.config.decimal_code(value) {
            // (a LinuxCNC configuration may remap G68.2: TG307, naming REMAP)
            None if self.config.alarm_g
                && !dialect::g_code_remappable(self.config.family, value) =>
            {
                let message = format!(
                    "{}: the control has no such code and alarms on it",
                    w.token()
                );
                self.report(Rule::CodeAlarms, message, line, w.column);
                None
            }
            None => {
                self.unknown_code(w, line);
                None
            }
            Some((i, code)) => code.modal().then_some(CodeRef::Decimal(i)),
        }
    }

    /// TG305 for an M code of a class the profile does not have; the number within its
    /// class.
    fn m_class(&mut self, w: &Word<'_>, n: i64, line: usize) -> i64 {
        // M1xx is class 1 of ISO 6983-1's M codes; a Fanuc's M198 or LinuxCNC's M100 is
        // a code of its own
        let klass = if w.letter == b'M' && n >= 100 && self.config.family == Family::Iso {
            n / 100
        } else {
            0
        };
        if klass != 0 && !self.config.m_classes.contains(&klass) {
            let mut classes = self.config.m_classes.clone();
            classes.sort_unstable();
            let list: Vec<String> = classes.iter().map(i64::to_string).collect();
            let message = format!(
                "{}: class {klass} M codes are not in the profile (classes [{}])",
                w.token(),
                list.join(", ")
            );
            self.report(Rule::MClassMissing, message, line, w.column);
        }
        if klass != 0 {
            n % 100
        } else {
            n
        }
    }

    /// A code against the profile's table: TG306 where the control alarms on it, TG301 and
    /// TG302 where the table has it not, TG302 and TG303 by its status. On a control family
    /// (not ISO 6983-1) the standard's statuses say nothing of the control: a code the profile
    /// does not designate is TG307, named with what that control does with it. Its facts,
    /// where the modal group is to be checked.
    fn code_facts(&mut self, w: &Word<'_>, n: i64, number: i64, line: usize) -> Option<CodeFacts> {
        if let Some(why) = (w.letter == b'M')
            .then(|| dialect::m_code_alarms(self.config.family, n))
            .flatten()
        {
            let message = format!("{}: the control has no such code: {why}", w.token());
            self.report(Rule::CodeAlarms, message, line, w.column);
            return None;
        }
        let facts = self.config.code(w.letter, number).map(|c| CodeFacts {
            status: c.status,
            modal: c.modal(),
        });
        let alarm = if w.letter == b'G' {
            self.config.alarm_g
                && !dialect::g_code_remappable(self.config.family, Dec::from_int(n.into()))
        } else {
            self.config.alarm_m
        };
        let usable = facts
            .as_ref()
            .is_some_and(|f| !matches!(f.status, Status::Permanent | Status::Unassigned));
        if alarm && !usable {
            let message = format!(
                "{}: the control has no such code and alarms on it",
                w.token()
            );
            self.report(Rule::CodeAlarms, message, line, w.column);
            return None;
        }
        let Some(facts) = facts else {
            self.unknown_code(w, line);
            return None;
        };
        if self.config.family != Family::Iso
            && matches!(facts.status, Status::Permanent | Status::Unassigned)
        {
            self.unknown_code(w, line);
            return Some(facts);
        }
        match facts.status {
            Status::Permanent => {
                let message = format!("{} is permanently unassigned", w.token());
                self.report(Rule::CodePermanentlyUnassigned, message, line, w.column);
            }
            Status::Unassigned => {
                let message = format!(
                    "{} is unassigned (individual use) and the profile does not designate it",
                    w.token()
                );
                self.report(Rule::CodeUnassigned, message, line, w.column);
            }
            _ => {}
        }
        Some(facts)
    }

    /// TG304: the modal code of word `i` against the earlier ones of the block (`groups`: the
    /// code and word of the first of each group).
    fn modal_group(
        &mut self,
        words: &[Word<'_>],
        groups: &mut Vec<(CodeRef, usize)>,
        i: usize,
        code: CodeRef,
        line: usize,
    ) {
        let found = {
            let mine = group_of_code(&self.config, code);
            groups
                .iter()
                .find(|&&(other, _)| group_of_code(&self.config, other) == mine)
                .copied()
        };
        // HEIDENHAIN ISO: a G90 or G91 applies to the coordinates after it, so a block may
        // hold both (TNC 426/425 ISO manual, "Path contours - Cartesian coordinates": "G02
        // G91 X+5 G90 Y-5"; followed in polar.rs)
        let distance = |c: CodeRef| matches!(c, CodeRef::Whole(b'G', 90 | 91));
        let per_word = self.config.family == Family::Heidenhain;
        match found {
            Some((other, _)) if per_word && distance(other) && distance(code) => {}
            Some((other, j)) if other != code => {
                self.group_conflict(words, (other, j), (code, i), line, None);
            }
            Some(_) => {}
            None => groups.push((code, i)),
        }
    }

    /// A SINUMERIK's M function of spindle 1 (`M1=4`) against the block's plain ones of its
    /// group (`others`), or a plain one against spindle 1's: the plain address is the master
    /// spindle's (Function Manual Basic Functions, H2 "Auxiliary function outputs to PLC",
    /// address extension: none, or 0, refers to the master spindle of the channel), which
    /// machine data 20090 SPIND_DEF_MASTER_SPIND names (840D sl W1: `MD20090 = 2` makes
    /// spindle 2 the master). So where it is spindle 1, as on a one-spindle machine, `M3 M1=4`
    /// turns one spindle both ways: the two conflict as `M3 M4` do,
    /// the message naming that setting. Spindle 2's (`M3 M2=4`) is another spindle on such a
    /// machine, and no conflict (docs/dialects.md).
    fn master_spindle(
        &mut self,
        words: &[Word<'_>],
        others: &[(CodeRef, usize)],
        extension: u64,
        i: usize,
        code: CodeRef,
        line: usize,
    ) {
        let mine = group_of_code(&self.config, code);
        let found = others
            .iter()
            .find(|&&(other, _)| {
                matches!(other, CodeRef::Whole(b'M', _))
                    && other != code
                    && group_of_code(&self.config, other) == mine
            })
            .copied();
        if let Some(other) = found {
            let master = match self.master {
                Master::MachineData => format!(
                    " of one spindle where the master spindle, the plain M function's, is \
                     spindle {extension} (machine data 20090 SPIND_DEF_MASTER_SPIND; a \
                     one-spindle machine's)"
                ),
                Master::Set { spindle, line } => format!(
                    " of one spindle: the master spindle, the plain M function's, is spindle \
                     {spindle} since the SETMS on line {line}"
                ),
                Master::Unknown { line, skipped } => format!(
                    " of what may be one spindle: which spindle is the master, the plain M \
                     function's, is not known since the SETMS on line {line} ({}), so it may \
                     be spindle {extension}",
                    if skipped {
                        "after a condition, loop, jump or label: it may not run"
                    } else {
                        "an argument the checker cannot read"
                    }
                ),
            };
            self.group_conflict(words, other, (code, i), line, Some(&master));
        }
    }

    /// TG304, or TG308 where [`Checker::m_group_unsourced`], for two codes of one modal group
    /// in a block: word `j`'s code `other`, then word `i`'s `code` (`master`: a plain M
    /// function and one of spindle 1's, [`Checker::master_spindle`]). Where one of the two
    /// turns a spindle (the profile's meaning keys, [`turning_codes`]) it stays TG304 with the
    /// reason: whether and which way the spindle turns for the cuts after the block is not
    /// known, which decides how the tool meets the work (review 51 F9); a pair that turns
    /// nothing (`M05 M19`) stays TG308 (review 55a F6).
    fn group_conflict(
        &mut self,
        words: &[Word<'_>],
        (other, j): (CodeRef, usize),
        (code, i): (CodeRef, usize),
        line: usize,
        master: Option<&str>,
    ) {
        let group = group_of_code(&self.config, code).to_string();
        let m_code = matches!(code, CodeRef::Whole(b'M', _));
        let unsourced = m_code && self.m_group_unsourced();
        let spindle = unsourced && (self.turns_a_spindle(other) || self.turns_a_spindle(code));
        // (in the block's order: `M03 M05` names M03 first)
        let mut message = format!(
            "{} and {} are both in modal group {group}",
            words[j].token(),
            words[i].token(),
        );
        if let Some(master) = master {
            message.push_str(master);
        }
        if spindle {
            message.push_str("; ");
            message.push_str(self.spindle_pair_reason());
            message.push_str(
                ", so whether and which way the spindle turns for the cuts after it is not known",
            );
        }
        self.conflict_at
            .get_or_insert_with(|| (line, message.clone()));
        let rule = if unsourced && !spindle {
            Rule::MCodesOneGroup
        } else {
            Rule::ModalGroupConflict
        };
        self.report(rule, message, line, words[i].column);
    }

    /// Why two codes of a spindle's group leave its drive unknown, by who decodes them: a
    /// FANUC hands M03-M05 to the builder's PMC ladder (0i-F/30i-B Operator's Manuals,
    /// "Auxiliary function"), a SINUMERIK's NC decodes its spindle's M functions itself
    /// (Programming Manual Fundamentals, "M functions"; auxiliary function group 2), and the
    /// Okuma's List of M Codes gives their group only; none says which of two it takes.
    fn spindle_pair_reason(&self) -> &'static str {
        match self.config.family {
            Family::MacroB => {
                "the CNC hands them to the builder's PMC ladder and no source says which of \
                 the two it takes"
            }
            Family::Sinumerik => {
                "the NC decodes the spindle's M functions itself and no source says which of \
                 the two it takes or whether it alarms"
            }
            _ => "no source says which of the two the control takes",
        }
    }

    /// Whether `code` turns a spindle: an M code whose meaning key in the profile says so
    /// ([`Config::turning`]).
    fn turns_a_spindle(&self, code: CodeRef) -> bool {
        matches!(code, CodeRef::Whole(b'M', n) if self.config.turning.contains(&n))
    }

    /// Whether two M codes of one modal group in a block are TG308, a warning, rather than
    /// TG304 (issue 32, severity by evidence): on a FANUC, a SINUMERIK and an Okuma OSP no
    /// source at hand says the control alarms on them (the builder's ladder, PMC or PLC, takes
    /// most M codes; the Okuma's List of M Codes, 4203-E, names each code's group, not what
    /// the control does with two of one: audit 50, B1), while LinuxCNC's rs274 refuses them
    /// ("Two m codes used from same modal group"), the Haas NGC manual allows one M code a
    /// line, and the ISO profiles follow the standard's Annex E. The same evidence decides
    /// the group of program stops ([`Checker::program_stops`]).
    fn m_group_unsourced(&self) -> bool {
        match self.config.family {
            Family::MacroB => !self.config.haas,
            Family::Sinumerik | Family::Okuma => true,
            _ => false,
        }
    }

    /// M00 M01 M02 M30 (and LinuxCNC's M60) stop the program: one group on every control.
    /// Two of them in a block are TG304 where a source refuses them (rs274, the Haas's one M
    /// code a line, the standard on the ISO profiles) and TG308, a warning, where none at hand
    /// does (FANUC, SINUMERIK, Okuma: searched, docs/rules.md TG304); either way which stop the
    /// block makes is not known, so a restart after it is refused (`conflict_at`).
    pub(super) fn program_stops(&mut self, b: &BlockView<'_>) {
        // (two stops need two M codes: most blocks have none)
        if self.values.ms.len() < 2 {
            return;
        }
        let stops: Vec<i64> = self
            .values
            .ms
            .iter()
            .copied()
            .filter(|m| matches!(m, 0 | 1 | 2 | 30 | 60))
            .collect();
        if stops.len() > 1 && stops.iter().any(|&m| m != stops[0]) {
            let column = b
                .words
                .iter()
                .filter(|w| w.letter == b'M')
                .nth(1)
                .map_or(1, |w| w.column);
            let message = format!(
                "M{:02} and M{:02} are both in the group of program stops: one per block",
                stops[0], stops[1]
            );
            self.conflict_at
                .get_or_insert_with(|| (b.line, message.clone()));
            let rule = if self.m_group_unsourced() {
                Rule::MCodesOneGroup
            } else {
                Rule::ModalGroupConflict
            };
            self.report(rule, message, b.line, column);
        }
    }
}

/// Which spindle a SINUMERIK's plain M function addresses, the master spindle (Function
/// Manual Basic Functions H2: an M function without an address extension, or with 0, is the
/// master spindle's): machine data 20090 SPIND_DEF_MASTER_SPIND's until the program's
/// `SETMS(n)` names another, and again after `SETMS` alone ([`Checker::set_master`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Master {
    /// The machine data's, taken as spindle 1 (a one-spindle machine's).
    MachineData,
    /// The spindle a `SETMS(n)` on `line` named.
    Set { spindle: u64, line: usize },
    /// A `SETMS` on `line` whose argument the checker cannot read, or that may not run
    /// (`skipped`: after a condition, a loop, a jump or a label): any spindle may be it.
    Unknown { line: usize, skipped: bool },
}

/// The whole G and M codes of a block in their order ([`code_key`]), packed in a `u64`: what
/// TG301-TG307 ([`Checker::code_words`]), the motion group's reading
/// ([`Checker::motion_codes`]) and what the codes do with the axis words
/// (`ModalSettings::axes_taken`) read of a block whose codes are all whole numbers, with the
/// profile, and nothing else. A CAM program writes a few sets of codes over and over (`G1`,
/// `G2`, `G0 G90`): what the two found for a set is kept by its key ([`CodeVerdicts`]).
/// 12 bits a code: a marker bit, M or G, the number (below 1,024); five codes at most.
pub(super) type CodeKey = u64;

/// The key of a block's codes ([`CodeKey`]), or None where a code is not a plain whole number
/// below 1,024 (a decimal `G54.1`, `M1=3`, `G[#1]`, a value not read) or there are more than
/// five: such a block is checked afresh.
pub(super) fn code_key(words: &[Word<'_>], readable: &[Option<Dec>]) -> Option<CodeKey> {
    let mut key: u64 = 0;
    let mut n = 0;
    for (w, value) in words.iter().zip(readable) {
        if !matches!(w.letter, b'G' | b'M') {
            continue;
        }
        let v = value.filter(|v| v.is_whole() && w.index.is_empty() && w.expression.is_empty())?;
        let number = u64::try_from(v.trunc()).ok().filter(|&c| c < 1024)?;
        if n == 5 {
            return None;
        }
        key = key << 12 | 1 << 11 | u64::from(w.letter == b'M') << 10 | number;
        n += 1;
    }
    (n > 0).then_some(key)
}

/// [`code_key`] built code by code, in the walk of a block's words that reads their values
/// (`Checker::read_block`: one walk for both, where the key was a walk of its own): the same
/// key, or None, for the same words and values.
#[derive(Debug, Clone, Copy)]
pub(super) struct KeyBuilder {
    key: u64,
    n: u32,
    ok: bool,
}

impl KeyBuilder {
    pub(super) const fn new() -> KeyBuilder {
        KeyBuilder {
            key: 0,
            n: 0,
            ok: true,
        }
    }

    /// A G or M word whose value is no whole number read: no key.
    #[inline(always)]
    pub(super) fn refuse(&mut self) {
        self.ok = false;
    }

    /// G or M word `w`, whose value is the whole number `number`: its code in the key, or no
    /// key where the word has an index or an expression, the number is not below 1,024 or
    /// five codes came before.
    #[inline(always)]
    pub(super) fn code(&mut self, w: &Word<'_>, number: i64) {
        if !w.index.is_empty() || !w.expression.is_empty() || !(0..1024).contains(&number) {
            self.ok = false;
            return;
        }
        if self.n == 5 {
            self.ok = false;
            return;
        }
        self.key = self.key << 12 | 1 << 11 | u64::from(w.letter == b'M') << 10 | number as u64;
        self.n += 1;
    }

    /// The key: None where a word refused one or there was no code.
    pub(super) fn key(self) -> Option<CodeKey> {
        (self.ok && self.n > 0).then_some(self.key)
    }
}

/// [`CodeVerdicts`]: TG301-TG307 said nothing of the codes.
pub(super) const SILENT: u16 = 1;
/// [`CodeVerdicts`]: the motion group's reading of the codes is kept, in the bits below.
pub(super) const MOTION: u16 = 2;
pub(super) const MODELLED: u16 = 4;
pub(super) const UNMODELLED: u16 = 8;
pub(super) const TAKES_AXES: u16 = 16;
/// [`CodeVerdicts`]: what the codes do with the axis words (`ModalSettings::axes_taken`) is
/// kept, in the three bits from [`TAKEN_SHIFT`].
pub(super) const TAKEN: u16 = 32;
const TAKEN_SHIFT: u16 = 6;

/// The flags of what `ModalSettings::axes_taken` said ([`TAKEN`]).
pub(super) fn taken_flags(taken: Option<AxesTaken>) -> u16 {
    let n: u16 = match taken {
        None => 0,
        Some(AxesTaken::Data) => 1,
        Some(AxesTaken::Set) => 2,
        Some(AxesTaken::Positions) => 3,
        Some(AxesTaken::Unknown) => 4,
        Some(AxesTaken::Home) => 5,
    };
    TAKEN | n << TAKEN_SHIFT
}

/// What [`taken_flags`] kept.
pub(super) fn taken_of(flags: u16) -> Option<AxesTaken> {
    match flags >> TAKEN_SHIFT & 0b111 {
        1 => Some(AxesTaken::Data),
        2 => Some(AxesTaken::Set),
        3 => Some(AxesTaken::Positions),
        4 => Some(AxesTaken::Unknown),
        5 => Some(AxesTaken::Home),
        _ => None,
    }
}

/// What the rules found of each set of codes met ([`CodeKey`]), in the place its hash gives
/// it, a later set of the same place taking it over. Only what holds for every block of the
/// set is kept: silence (no finding, which no state of the program changes), the motion
/// group's reading where it named no cycle and no code the family's list lacks (those note
/// the line they are met on), and what the codes do with the axis words.
#[derive(Clone, Debug)]
pub(super) struct CodeVerdicts {
    keys: [CodeKey; 64],
    flags: [u16; 64],
}

impl Default for CodeVerdicts {
    fn default() -> CodeVerdicts {
        CodeVerdicts {
            keys: [0; 64],
            flags: [0; 64],
        }
    }
}

impl CodeVerdicts {
    fn slot(key: CodeKey) -> usize {
        (key.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 58) as usize
    }

    /// The flags kept for `key` (0: none).
    pub(super) fn get(&self, key: CodeKey) -> u16 {
        let slot = Self::slot(key);
        if self.keys[slot] == key {
            self.flags[slot]
        } else {
            0
        }
    }

    pub(super) fn add(&mut self, key: CodeKey, flags: u16) {
        let slot = Self::slot(key);
        if self.keys[slot] != key {
            self.keys[slot] = key;
            self.flags[slot] = 0;
        }
        self.flags[slot] |= flags;
    }
}

/// The modal group of a code of the profile ("" for none).
pub(super) fn group_of(config: &Config, letter: u8, number: i64) -> &str {
    config
        .code(letter, number)
        .map_or("", |c| c.duration.as_str())
}

/// The meaning keys of a code that turns a spindle (docs/profiles.md, "Code meanings"): the
/// main spindle's `spindle-cw` and `spindle-ccw` (M03, M04 of every dialect profile),
/// HEIDENHAIN's M13 and M14 (`spindle-cw-coolant-on`, `spindle-ccw-coolant-on`), and a
/// lathe's live tool (`live-tool-cw`, `live-tool-ccw`: the Okuma's M-tool spindle M13 M14,
/// Haas's M133 M134). The profile says a code's meaning; a profile of your own that keys its
/// codes so is read the same way.
pub const TURNING_KEYS: [&str; 6] = [
    "spindle-cw",
    "spindle-ccw",
    "spindle-cw-coolant-on",
    "spindle-ccw-coolant-on",
    "live-tool-cw",
    "live-tool-ccw",
];

/// The M codes of a profile's own list (`meanings`: the code, `M03`, its meaning key and its
/// function, [`crate::machine::MachineSpec::meanings`]) that turn a spindle ([`TURNING_KEYS`]),
/// by number: compiled once into [`Config::turning`], asked where two codes of a group meet.
/// M03 and M04 turn the spindle unless the profile keys them otherwise: that is their meaning
/// in ISO 6983-1's table (spindle clockwise, counter-clockwise), so a profile of your own that
/// lists them without a key keeps their refusal (review 56d, F5: `M03 M04` was a warning).
pub fn turning_codes(meanings: &[(String, String, String)]) -> Vec<i64> {
    let number = |code: &str| code.strip_prefix('M')?.parse::<i64>().ok();
    let mut turning: Vec<i64> = meanings
        .iter()
        .filter(|(_, key, _)| TURNING_KEYS.contains(&key.as_str()))
        .filter_map(|(code, ..)| number(code))
        .collect();
    for iso in [3, 4] {
        let keyed_otherwise = meanings
            .iter()
            .any(|(code, key, _)| number(code) == Some(iso) && !key.is_empty());
        if !keyed_otherwise && !turning.contains(&iso) {
            turning.push(iso);
        }
    }
    turning
}

fn group_of_code(config: &Config, code: CodeRef) -> &str {
    match code {
        CodeRef::Whole(letter, number) => group_of(config, letter, number),
        CodeRef::Decimal(i) => config.g_decimal[i].1.duration.as_str(),
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{findings, fired, iso_mill, of_family, program};
    use super::super::Config;
    use crate::decimal::Dec;
    use crate::lex::Family;
    use crate::rules::Rule;
    use crate::word::Word;

    fn at(config: Config, body: &str, rule: Rule) -> Vec<(usize, usize)> {
        fired(config, &program(body), rule)
    }

    /// The findings of the rules of codes and values on a SINUMERIK (the test profile
    /// classifies no R, and M3 M4 repeat M: those two rules left out).
    fn sinumerik_codes(body: &str) -> Vec<(Rule, usize, usize)> {
        super::super::testing::check(of_family(Family::Sinumerik), &program(body))
            .iter()
            .filter(|f| !matches!(f.rule, Rule::AddressNotClassified | Rule::WordRepeated))
            .map(|f| (f.rule, f.line, f.column))
            .collect()
    }

    /// Extended M codes of one extension are one spindle's (Fundamentals, "Extended
    /// addresses": `M3=5`, spindle 3 stops): two codes of one modal group for it conflict as
    /// `M3 M4` do (TG304: the spindle's group is refused, review 51 F9; a SINUMERIK's other
    /// groups are TG308); codes of two extensions are not. A plain code is the master
    /// spindle's (machine data 20090), spindle 1 on a one-spindle machine: beside one of
    /// spindle 1's it conflicts, naming that setting (review 55a F7); beside spindle 2's it
    /// does not.
    #[test]
    fn one_spindles_extended_m_codes_are_one_modal_group() {
        let sinumerik = || of_family(Family::Sinumerik);
        let found = sinumerik_codes;
        assert_eq!(found("G0 X0\nM3 M4"), [(Rule::ModalGroupConflict, 3, 4)]);
        assert_eq!(
            found("G0 X0\nM1=3 M1=4"),
            [(Rule::ModalGroupConflict, 3, 6)]
        );
        // the extension as a number: 01 is 1; a value given by a known constant
        assert_eq!(
            found("G0 X0\nR2=4\nM2=5 M1=3 M01=R2"),
            [(Rule::ModalGroupConflict, 4, 11)]
        );
        let message = findings(
            sinumerik(),
            &program("G0 X0\nM1=3 M1=4"),
            Rule::ModalGroupConflict,
        );
        assert!(
            message[0]
                .message
                .starts_with("M1=3 and M1=4 are both in modal group"),
            "{}",
            message[0].message
        );
        for quiet in [
            "M1=3 M2=4",
            "M3 M2=4",
            "M2=4 M3",
            "M3 M1=3",
            "M1=3 M1=3",
            "M1=3 M2=3 M3=5",
        ] {
            assert_eq!(found(&format!("G0 X0\n{quiet}")), [], "{quiet}");
        }
        // the plain code beside spindle 1's, in either order: one spindle on a machine whose
        // master spindle is spindle 1, as a one-spindle machine's is
        assert_eq!(found("G0 X0\nM3 M1=4"), [(Rule::ModalGroupConflict, 3, 4)]);
        assert_eq!(found("G0 X0\nM1=4 M3"), [(Rule::ModalGroupConflict, 3, 6)]);
        // each word once: M1=3 against the plain M5, M1=4 against spindle 1's M1=3
        assert_eq!(
            found("G0 X0\nM5 M1=3 M1=4"),
            [
                (Rule::ModalGroupConflict, 3, 4),
                (Rule::ModalGroupConflict, 3, 9)
            ]
        );
        let master = findings(
            sinumerik(),
            &program("G0 X0\nM3 M1=4"),
            Rule::ModalGroupConflict,
        );
        assert_eq!(
            master[0].message,
            "M3 and M1=4 are both in modal group spindle of one spindle where the master \
             spindle, the plain M function's, is spindle 1 (machine data 20090 \
             SPIND_DEF_MASTER_SPIND; a one-spindle machine's); the NC decodes the spindle's M functions \
             itself and no source says which of the two it takes or whether it alarms, so \
             whether and which way the spindle turns for the cuts after it is not known"
        );
        // a pair that turns nothing (M5 beside spindle 1's orientation): TG308, naming it
        let mut oriented = sinumerik();
        oriented.facts.m_codes[19] = oriented.facts.m_codes[5].clone();
        let stop = findings(
            oriented.clone(),
            &program("G0 X0\nM5 M1=19"),
            Rule::MCodesOneGroup,
        );
        assert_eq!((stop.len(), stop[0].line, stop[0].column), (1, 3, 4));
        assert!(
            stop[0]
                .message
                .ends_with("(machine data 20090 SPIND_DEF_MASTER_SPIND; a one-spindle machine's)"),
            "{}",
            stop[0].message
        );
        assert_eq!(
            at(oriented, "G0 X0\nM5 M1=19", Rule::ModalGroupConflict),
            []
        );
    }

    /// The master spindle, the plain M function's, is the one the program's `SETMS(n)` names
    /// (Programming Manual Fundamentals, "Main spindle, master spindle"), the machine data's
    /// again after `SETMS` alone, and not known after a `SETMS` whose argument the checker
    /// cannot read: then a plain code beside any spindle's of its group is refused, saying
    /// so (issue 32, review 56a F2). `M0=3` is the plain M3 (H2, extension 0; review 56a F7).
    #[test]
    fn the_master_spindle_is_the_one_setms_names() {
        let sinumerik = || of_family(Family::Sinumerik);
        let found = sinumerik_codes;
        let conflict = |line, column| vec![(Rule::ModalGroupConflict, line, column)];
        let message = |body: &str| {
            let said = findings(sinumerik(), &program(body), Rule::ModalGroupConflict);
            assert_eq!(said.len(), 1, "{body}");
            said[0].message.clone()
        };
        // spindle 2 the master: spindle 1's stop beside the master's start is two spindles'
        for quiet in [
            "SETMS(2)\nM3 S2000 M1=5",
            "SETMS(2)\nM1=4 M3 S2000",
            "R1=2\nSETMS(R1)\nM1=4 M3",
            "SETMS(2)\nM0=3 M1=4",
            "M0=3 M2=4",
        ] {
            assert_eq!(found(&format!("G0 X0\n{quiet}")), [], "{quiet}");
        }
        assert_eq!(found("G0 X0\nSETMS(2)\nM3 S2000 M2=4"), conflict(4, 10));
        assert_eq!(found("G0 X0\nSETMS(2)\nM2=4 M3"), conflict(4, 6));
        assert!(message("G0 X0\nSETMS(2)\nM3 M2=4").starts_with(
            "M3 and M2=4 are both in modal group spindle of one spindle: the master spindle, \
             the plain M function's, is spindle 2 since the SETMS on line 3; the NC decodes"
        ));
        // SETMS alone: the machine data's master again (spindle 1)
        assert_eq!(found("G0 X0\nSETMS(2)\nSETMS\nM3 M1=4"), conflict(5, 4));
        assert_eq!(found("G0 X0\nSETMS(2)\nSETMS()\nM3 M2=4"), []);
        // a master the checker cannot read: any spindle may be it, refused saying so
        for unknown in ["M3 M1=4", "M3 M2=4", "M7=4 M3"] {
            let body = format!("G0 X0\nSETMS(R9)\n{unknown}");
            assert_eq!(found(&body).len(), 1, "{unknown}");
            assert_eq!(found(&body)[0].0, Rule::ModalGroupConflict, "{unknown}");
        }
        assert!(message("G0 X0\nSETMS(R9)\nM3 M2=4").contains(
            "of what may be one spindle: which spindle is the master, the plain M function's, \
             is not known since the SETMS on line 3 (an argument the checker cannot read), so \
             it may be spindle 2;"
        ));
        // extension 0 is the plain address: the master spindle both ways
        assert_eq!(found("G0 X0\nM0=3 M4 S1000"), conflict(3, 6));
        assert_eq!(found("G0 X0\nM0=3 M0=4"), conflict(3, 6));
        assert_eq!(found("G0 X0\nM0=3 M1=4"), conflict(3, 6));
        assert_eq!(found("G0 X0\nM0=3 M3"), []);
        // a blank between SETMS and its parenthesis separates them (review 56d F3)
        assert_eq!(found("G0 X0\nSETMS (2)\nM3 M1=5"), []);
        assert_eq!(found("G0 X0\nSETMS (2)\nM3 M2=4"), conflict(4, 4));
        assert_eq!(
            found("G0 X0\nSETMS(2)\nSETMS ( 1 )\nM3 M1=4"),
            conflict(5, 4)
        );
        // a SETMS that may not run (under a condition, skipped by a jump, after a label): the
        // master is not known, neither the one it names nor spindle 1 (review 56d F8)
        for body in [
            "R1=0\nIF R1==1\nSETMS(2)\nENDIF\nM3 M1=4",
            "GOTOF LBL1\nSETMS(2)\nLBL1:\nM3 M1=4",
            "GOTOF LBL1\nSETMS(2)\nLBL1:\nM3 M2=4",
            "LBL1:\nSETMS(2)\nM3 M1=4",
        ] {
            let said = findings(sinumerik(), &program(body), Rule::ModalGroupConflict);
            assert_eq!(said.len(), 1, "{body}");
            let setms = 2 + body.lines().position(|l| l == "SETMS(2)").unwrap_or(0);
            assert!(
                said[0].message.contains(&format!(
                    "is not known since the SETMS on line {setms} (after a condition, loop, \
                     jump or label: it may not run), so it may be spindle"
                )),
                "{body}: {}",
                said[0].message
            );
        }
    }

    /// Which codes turn a spindle is the profile's meaning keys, compiled once
    /// ([`super::super::turning_codes`]), not a group's name: a pair of a group where one turns
    /// a spindle is TG304 on a FANUC, SINUMERIK or Okuma (the Okuma lathe's M-tool spindle
    /// M12-M14 as the main spindle's M03-M05, review 55a F1); a pair that turns nothing (a
    /// stop beside an orientation, `M05 M19`) is TG308 (review 55a F6); a profile that keys
    /// no code so leaves every pair of its M codes TG308.
    #[test]
    fn the_profiles_meaning_keys_say_which_codes_turn_a_spindle() {
        let meanings = |list: &[(&str, &str)]| -> Vec<(String, String, String)> {
            list.iter()
                .map(|&(code, key)| (code.to_string(), key.to_string(), String::new()))
                .collect()
        };
        assert_eq!(
            super::super::turning_codes(&meanings(&[
                ("M03", "spindle-cw"),
                ("M04", "spindle-ccw"),
                ("M05", "spindle-stop"),
                ("M19", "spindle-orient"),
                ("M13", "live-tool-cw"),
                ("M134", "live-tool-ccw"),
                ("M135", "live-tool-stop"),
                ("01", "linear-interpolation"),
                ("M08", "coolant-on"),
            ])),
            [3, 4, 13, 134]
        );
        let okuma = || {
            let mut config = of_family(Family::Okuma);
            for m in [12, 13, 14] {
                config.facts.m_codes[m] =
                    super::super::testing::code(super::super::Status::Assigned, "M-tool spindle");
            }
            config.facts.m_codes[19] = config.facts.m_codes[5].clone();
            config.turning = vec![3, 4, 13, 14];
            config
        };
        for pair in ["M13 M14", "M12 M13", "M14 M12", "M03 M19", "M19 M04"] {
            let found = findings(
                okuma(),
                &program(&format!("G0 X0\n{pair}")),
                Rule::ModalGroupConflict,
            );
            assert_eq!(found.len(), 1, "{pair}");
            assert_eq!((found[0].line, found[0].column), (3, 5), "{pair}");
            assert!(
                found[0].message.ends_with(
                    "no source says which of the two the control takes, so whether and which \
                     way the spindle turns for the cuts after it is not known"
                ),
                "{}",
                found[0].message
            );
        }
        for quiet in ["M05 M19", "M19 M05", "M12 M05"] {
            assert_eq!(
                at(
                    okuma(),
                    &format!("G0 X0\n{quiet}"),
                    Rule::ModalGroupConflict
                ),
                [],
                "{quiet}"
            );
        }
        assert_eq!(
            at(okuma(), "G0 X0\nM05 M19", Rule::MCodesOneGroup),
            [(3, 5)]
        );
        // a profile that keys none of its codes: its spindle pair is a warning like any other
        let unkeyed = Config {
            turning: Vec::new(),
            ..of_family(Family::MacroB)
        };
        assert_eq!(
            at(unkeyed.clone(), "G0 X0\nM03 M04", Rule::MCodesOneGroup),
            [(3, 5)]
        );
        assert_eq!(at(unkeyed, "G0 X0\nM03 M04", Rule::ModalGroupConflict), []);
    }

    /// An extended M code's value is "an arithmetic expression" (Fundamentals, "Extended
    /// addresses"): where the checker knows it (`+77`, `(77)`, an R parameter set to 77) it is
    /// the code M77 (TG307); where it cannot tell a code (an unknown parameter, a value below
    /// 0 or with a fraction) it is TG141; an extension out of range is TG206 alone.
    #[test]
    fn an_extended_m_codes_known_value_is_its_code() {
        let sinumerik = || of_family(Family::Sinumerik);
        let found = sinumerik_codes;
        for known in [
            "R1=77\nM1=R1",
            "M1=(77)",
            "M1=+77",
            "_CODE=70\nM1=_CODE+7",
            "M1=77.",
        ] {
            let line = 3 + known.matches('\n').count();
            assert_eq!(
                found(&format!("G0 X0\n{known}")),
                [(Rule::CodeNotInProfile, line, 1)],
                "{known}"
            );
            let said = findings(
                sinumerik(),
                &program(&format!("G0 X0\n{known}")),
                Rule::CodeNotInProfile,
            );
            let word = known.lines().last().unwrap();
            assert!(
                said[0]
                    .message
                    .starts_with(&format!("{word} is not in the profile's M code list")),
                "{}",
                said[0].message
            );
        }
        for code in ["R1=3\nM2=R1", "M2=+5", "M2=(4)"] {
            assert_eq!(found(&format!("G0 X0\n{code}")), [], "{code}");
        }
        for unknown in ["M1=R9", "M0=R9", "M1=-3", "M1=3.5", "R1=7\nM1=R1/2"] {
            let line = 3 + unknown.matches('\n').count();
            assert_eq!(
                found(&format!("G0 X0\n{unknown}")),
                [(Rule::NotEvaluated, line, 1)],
                "{unknown}"
            );
        }
        // extension 0 is the master spindle's (H2): `M0=3` is the plain M3, `M0=77` the M77
        assert_eq!(found("G0 X0\nM0=3"), []);
        assert_eq!(found("G0 X0\nM0=77"), [(Rule::CodeNotInProfile, 3, 1)]);
        // an extension out of range: TG206 at the extension, alone (no TG307, no TG141)
        for wrong in ["M100=77", "M100=R9", "M100=3"] {
            assert_eq!(
                found(&format!("G0 X0\n{wrong}")),
                [(Rule::IndexOutOfRange, 3, 2)],
                "{wrong}"
            );
        }
    }

    /// A SINUMERIK's M function with an extended address (`M2=3`, spindle 2 clockwise:
    /// Programming Manual Fundamentals, "Extended addresses") is its code, checked against the
    /// profile's table as the plain one is; it is spindle 2's, so the main spindle's state the
    /// checker follows does not change, and two spindles' codes in a block are no conflict.
    #[test]
    fn a_sinumerik_extended_m_code_is_checked_as_its_code() {
        let sinumerik = || of_family(Family::Sinumerik);
        // M77 is not in the table: the extended one warns as the plain one does
        assert_eq!(
            at(sinumerik(), "G0 X0\nM77", Rule::CodeNotInProfile),
            [(3, 1)]
        );
        let found = findings(
            sinumerik(),
            &program("G0 X0\nM1=77"),
            Rule::CodeNotInProfile,
        );
        assert_eq!(
            found.iter().map(|f| (f.line, f.column)).collect::<Vec<_>>(),
            [(3, 1)]
        );
        assert!(
            found[0]
                .message
                .starts_with("M1=77 is not in the profile's M code list"),
            "{}",
            found[0].message
        );
        // a code of the table, and two spindles' codes of one group in a block: quiet
        for quiet in ["M1=3", "M2=5 M1=4", "m3=3"] {
            let text = program(&format!("G0 X0\n{quiet}"));
            let rules: Vec<_> = super::super::testing::check(sinumerik(), &text)
                .iter()
                .map(|f| f.rule)
                .collect();
            assert_eq!(rules, [], "{quiet}");
        }
        // an expression (the code unknown) is TG141's, not a code's: no TG307
        let expression = program("G0 X0\nR1=77\nM1=R1+R2");
        assert_eq!(fired(sinumerik(), &expression, Rule::CodeNotInProfile), []);
        let found = findings(sinumerik(), &expression, Rule::NotEvaluated);
        assert_eq!(
            found.iter().map(|f| (f.line, f.column)).collect::<Vec<_>>(),
            [(4, 1)]
        );
        assert!(
            found[0]
                .message
                .starts_with("M1=R1+R2: an M function of another spindle"),
            "{}",
            found[0].message
        );
        // spindle 2's M3 does not turn the main spindle; the plain M3 does
        let dialect = super::super::testing::dialect(Family::Sinumerik);
        let (other, _) =
            super::super::testing::run(sinumerik(), &dialect, "G0 X0 Y0\nM2=3\nG1 X5 F100\n");
        assert_eq!(other.machine.state.spindle, 5);
        let (main, _) =
            super::super::testing::run(sinumerik(), &dialect, "G0 X0 Y0\nM3\nG1 X5 F100\n");
        assert_eq!(main.machine.state.spindle, 3);
        // elsewhere M1=3 is no extended address (ISO 6983-1: an index sets a parameter)
        assert_eq!(at(iso_mill(), "G00 X0\nM1=77", Rule::CodeNotInTable), []);
    }

    #[test]
    fn codes_outside_the_table() {
        assert_eq!(at(iso_mill(), "G01 X1. F100.", Rule::CodeNotInTable), []);
        assert_eq!(at(iso_mill(), "G91.1 X1.", Rule::CodeNotInTable), [(2, 1)]);
        assert_eq!(at(iso_mill(), "G1000 X1.", Rule::CodeNotInTable), [(2, 1)]);
        // on a dialect family whose profile does not say it alarms: TG307, a warning
        let macro_b = || Config {
            alarm_g: false,
            ..of_family(Family::MacroB)
        };
        assert_eq!(at(macro_b(), "G91.1 X1.", Rule::CodeNotInProfile), [(2, 1)]);
        assert_eq!(at(macro_b(), "G1000 X1.", Rule::CodeNotInProfile), [(2, 1)]);
        assert_eq!(at(macro_b(), "G91.1 X1.", Rule::CodeNotInTable), []);
        let found = findings(macro_b(), &program("G91.1 X1."), Rule::CodeNotInProfile);
        assert!(
            found.iter().any(|f| f.message.contains("macro call")),
            "{found:?}"
        );
    }

    #[test]
    fn unassigned_and_permanently_unassigned_codes() {
        assert_eq!(at(iso_mill(), "G07 X1.", Rule::CodeUnassigned), [(2, 1)]);
        assert_eq!(
            at(iso_mill(), "G01 X1. F100. M12", Rule::CodeUnassigned),
            [(2, 15)]
        );
        assert_eq!(
            at(iso_mill(), "G25 X1.", Rule::CodePermanentlyUnassigned),
            [(2, 1)]
        );
        assert_eq!(at(iso_mill(), "G25 X1.", Rule::CodeUnassigned), []);
        // on a control family the standard's statuses say nothing: a code the profile does
        // not designate is TG307, named with what the control does with it
        let found = findings(
            of_family(Family::MacroB),
            &program("M150"),
            Rule::CodeNotInProfile,
        );
        assert_eq!(found.len(), 1);
        assert!(
            found[0].message.contains("machine builder's ladder"),
            "{}",
            found[0].message
        );
        for family in [Family::MacroB, Family::Sinumerik, Family::LinuxCnc] {
            let config = || Config {
                alarm_g: false,
                ..of_family(family)
            };
            assert_eq!(at(config(), "M12", Rule::CodeUnassigned), []);
            assert_eq!(at(config(), "M12", Rule::CodeNotInProfile), [(2, 1)]);
            assert_eq!(at(config(), "G25 X1.", Rule::CodePermanentlyUnassigned), []);
            assert_eq!(at(config(), "G25 X1.", Rule::CodeNotInProfile), [(2, 1)]);
        }
        let plc = findings(
            of_family(Family::Sinumerik),
            &program("M12"),
            Rule::CodeNotInProfile,
        );
        assert!(plc[0].message.contains("to the PLC"), "{}", plc[0].message);
    }

    /// LinuxCNC's rs274 reads no M code past M999, whatever its configuration: TG306; up to
    /// M999, an M code its configuration may remap (M200-M999 too) or provide is TG307.
    #[test]
    fn linuxcnc_m_codes_past_m999_alarm() {
        let linuxcnc = || of_family(Family::LinuxCnc);
        assert_eq!(at(linuxcnc(), "M1000", Rule::CodeAlarms), [(2, 1)]);
        assert_eq!(at(linuxcnc(), "M1000", Rule::CodeNotInProfile), []);
        for code in ["M999", "M600", "M200", "M199"] {
            assert_eq!(at(linuxcnc(), code, Rule::CodeAlarms), [], "{code}");
            assert_eq!(
                at(linuxcnc(), code, Rule::CodeNotInProfile),
                [(2, 1)],
                "{code}"
            );
        }
        let found = findings(linuxcnc(), &program("M1250"), Rule::CodeAlarms);
        assert!(
            found[0].message.contains("M200-M999"),
            "{}",
            found[0].message
        );
        let found = findings(linuxcnc(), &program("M600"), Rule::CodeNotInProfile);
        assert!(found[0].message.contains("REMAP"), "{}", found[0].message);
        // another family's M200 is the machine builder's
        assert_eq!(at(of_family(Family::MacroB), "M200", Rule::CodeAlarms), []);
    }

    /// The key of a block's codes: their values in their order, G and M apart; None where
    /// one is not a plain whole number below 1,024, or there are more than five.
    #[test]
    fn a_code_key_holds_the_codes_values_in_their_order() {
        let key = |text: &str| {
            let words: Vec<Word<'_>> = text
                .split(' ')
                .map(|t| Word::new(t.as_bytes(), 1))
                .collect();
            let readable: Vec<Option<Dec>> = words
                .iter()
                .map(|w| {
                    let number = std::str::from_utf8(w.number).ok()?;
                    (w.expression.is_empty() && w.index.is_empty())
                        .then(|| Dec::parse(number))
                        .flatten()
                })
                .collect();
            super::code_key(&words, &readable)
        };
        assert_eq!(key("G1 X1. Y2."), key("G01 X5 Z3."));
        assert_eq!(key("G1 X1."), key("G1.0 X1."));
        assert_ne!(key("G1 M3"), key("M3 G1"));
        assert_ne!(key("G1"), key("M1"));
        assert_ne!(key("G1"), key("G1 G1"));
        assert_ne!(key("G0 G90"), key("G90 G0"));
        assert!(key("G1023").is_some());
        assert!(key("G17 G90 G94 G40 G49 X1.").is_some());
        for text in [
            "X1. Y2.",
            "G54.1 P1",
            "G1024",
            "M1=3",
            "G17 G90 G94 G40 G49 G80",
        ] {
            assert_eq!(key(text), None, "{text}");
        }
    }

    /// A set of codes kept as silent is so only once a block of it said nothing: a set
    /// that says something says it on each block it is met, and a set met silent, then in
    /// another order or beside another code, is checked afresh.
    #[test]
    fn codes_met_again_are_checked_again() {
        let body = "G01 X1. F100.\nG01 G00 X2.\nG01 X3.\nG01 G00 X4.\nG00 G01 X5.\nM12\nM12";
        let found: Vec<(Rule, usize)> = super::super::testing::check(iso_mill(), &program(body))
            .iter()
            .filter(|f| {
                matches!(
                    f.rule,
                    Rule::ModalGroupConflict | Rule::CodeUnassigned | Rule::CodeNotInTable
                )
            })
            .map(|f| (f.rule, f.line))
            .collect();
        let conflict = Rule::ModalGroupConflict;
        assert_eq!(
            found,
            [
                (conflict, 3),
                (conflict, 5),
                (conflict, 6),
                (Rule::CodeUnassigned, 7),
                (Rule::CodeUnassigned, 8)
            ]
        );
        let mut kept = super::CodeVerdicts::default();
        assert_eq!(kept.get(0x801), 0);
        kept.add(0x801, super::SILENT);
        kept.add(0x801, super::MOTION | super::MODELLED);
        assert_eq!(
            kept.get(0x801),
            super::SILENT | super::MOTION | super::MODELLED
        );
        // another key of the same place takes it over, with none of the flags before
        let slot = super::CodeVerdicts::slot(0x801);
        let other = (0x802u64..)
            .find(|&k| super::CodeVerdicts::slot(k) == slot)
            .unwrap();
        kept.add(other, super::MOTION);
        assert_eq!((kept.get(other), kept.get(0x801)), (super::MOTION, 0));
        // what the codes do with the axis words, beside the other flags
        use crate::modal::AxesTaken;
        let all = [
            None,
            Some(AxesTaken::Data),
            Some(AxesTaken::Set),
            Some(AxesTaken::Positions),
            Some(AxesTaken::Unknown),
            Some(AxesTaken::Home),
        ];
        for taken in all {
            let flags = super::taken_flags(taken) | super::SILENT | super::TAKES_AXES;
            assert_eq!(super::taken_of(flags), taken);
            assert_ne!(flags & super::TAKEN, 0);
        }
    }

    #[test]
    fn a_control_that_alarms_on_codes_it_lacks() {
        let alarms = Config {
            alarm_g: true,
            ..iso_mill()
        };
        assert_eq!(at(alarms.clone(), "G07 X1.", Rule::CodeAlarms), [(2, 1)]);
        assert_eq!(at(alarms.clone(), "G07 X1.", Rule::CodeUnassigned), []);
        assert_eq!(at(alarms.clone(), "G01 X1. F100.", Rule::CodeAlarms), []);
        // a decimal code the table lacks too (LinuxCNC's G41.2)
        assert_eq!(at(alarms.clone(), "G41.2 X1.", Rule::CodeAlarms), [(2, 1)]);
        assert_eq!(at(alarms.clone(), "G41.2 X1.", Rule::CodeNotInTable), []);
        // alarm_g says nothing of M codes
        assert_eq!(at(alarms, "G01 X1. F100. M12", Rule::CodeAlarms), []);
    }

    #[test]
    fn m_code_classes() {
        assert_eq!(at(iso_mill(), "M103", Rule::MClassMissing), []);
        assert_eq!(at(iso_mill(), "M203", Rule::MClassMissing), [(2, 1)]);
        let found = findings(iso_mill(), &program("M203"), Rule::MClassMissing);
        assert!(
            found[0].message.contains("classes [0, 1]"),
            "{}",
            found[0].message
        );
        // a Fanuc's M198 is a code of its own, not of class 1
        assert_eq!(
            at(of_family(Family::MacroB), "M298", Rule::MClassMissing),
            []
        );
    }

    #[test]
    fn two_codes_of_one_modal_group() {
        assert_eq!(
            at(iso_mill(), "G00 G01 X1. F100.", Rule::ModalGroupConflict),
            [(2, 5)]
        );
        assert_eq!(
            at(iso_mill(), "G17 G01 X1. F100.", Rule::ModalGroupConflict),
            []
        );
        assert_eq!(
            at(iso_mill(), "G01 G01 X1. F100.", Rule::ModalGroupConflict),
            []
        );
        // non-modal codes (G04, M00) have no group; the program stops are one
        assert_eq!(at(iso_mill(), "M03 M08", Rule::ModalGroupConflict), []);
        assert_eq!(
            at(iso_mill(), "M03 M04", Rule::ModalGroupConflict),
            [(2, 5)]
        );
        assert_eq!(
            at(iso_mill(), "M00 M01", Rule::ModalGroupConflict),
            [(2, 5)]
        );
    }

    /// Two M codes of one group, the program stops among them, are TG308, a warning, where no
    /// source shows the control alarms (a FANUC, a SINUMERIK, an Okuma OSP), TG304 where one
    /// does or the standard rules (the ISO profiles, LinuxCNC's rs274, the Haas manual's one M
    /// code a line); two G codes stay TG304 on every family, and so do two of the spindle's
    /// group, whose choice decides how the tool meets the work (review 51 F9).
    #[test]
    fn two_m_codes_of_one_group_by_evidence() {
        let fanuc = || of_family(Family::MacroB);
        let haas = || Config {
            haas: true,
            ..of_family(Family::MacroB)
        };
        for config in [
            fanuc(),
            of_family(Family::Sinumerik),
            of_family(Family::Okuma),
        ] {
            let family = config.family;
            let found = findings(
                config.clone(),
                &program("G0 X0\nM08 M09"),
                Rule::MCodesOneGroup,
            );
            assert_eq!(found.len(), 1, "{family:?}");
            assert_eq!((found[0].line, found[0].column), (3, 5), "{family:?}");
            assert!(
                found[0]
                    .message
                    .starts_with("M08 and M09 are both in modal group coolant"),
                "{}",
                found[0].message
            );
            assert_eq!(
                at(config.clone(), "G0 X0\nM08 M09", Rule::ModalGroupConflict),
                []
            );
            // the spindle's group: refused, with the reason
            let spindle = findings(
                config.clone(),
                &program("G0 X0\nM03 M05"),
                Rule::ModalGroupConflict,
            );
            assert_eq!(spindle.len(), 1, "{family:?}");
            assert_eq!((spindle[0].line, spindle[0].column), (3, 5), "{family:?}");
            // the reason by who decodes the spindle's codes (review 55a F3: a SINUMERIK's NC
            // decodes them, no ladder does)
            let reason = match family {
                Family::MacroB => "the CNC hands them to the builder's PMC ladder",
                Family::Sinumerik => "the NC decodes the spindle's M functions itself",
                _ => "no source says which of the two the control takes",
            };
            assert!(
                spindle[0].message.starts_with(&format!(
                    "M03 and M05 are both in modal group spindle; {reason}"
                )),
                "{}",
                spindle[0].message
            );
            assert!(
                spindle[0].message.ends_with(
                    "so whether and which way the spindle turns for the cuts after it is not known"
                ),
                "{}",
                spindle[0].message
            );
            assert_eq!(
                spindle[0].message.contains("ladder"),
                family == Family::MacroB,
                "{}",
                spindle[0].message
            );
            assert_eq!(
                at(config.clone(), "G0 X0\nM03 M05", Rule::MCodesOneGroup),
                [],
                "{family:?}"
            );
            assert_eq!(
                at(
                    config.clone(),
                    "G00 G01 X1. F100.",
                    Rule::ModalGroupConflict
                ),
                [(2, 5)]
            );
            assert_eq!(
                at(config.clone(), "G00 G01 X1. F100.", Rule::MCodesOneGroup),
                []
            );
            assert_eq!(
                at(config.clone(), "M00 M01", Rule::ModalGroupConflict),
                [],
                "{family:?}"
            );
            let stops = findings(config, &program("M00 M30"), Rule::MCodesOneGroup);
            assert_eq!(
                (stops.len(), stops[0].line, stops[0].column),
                (1, 2, 5),
                "{family:?}"
            );
            assert!(
                stops[0]
                    .message
                    .starts_with("M00 and M30 are both in the group of program stops"),
                "{}",
                stops[0].message
            );
        }
        for config in [haas(), of_family(Family::LinuxCnc), iso_mill()] {
            let family = config.family;
            assert_eq!(
                at(config.clone(), "G0 X0\nM03 M05", Rule::ModalGroupConflict),
                [(3, 5)],
                "{family:?}"
            );
            assert_eq!(
                at(config.clone(), "G0 X0\nM03 M05", Rule::MCodesOneGroup),
                []
            );
            assert_eq!(
                at(config.clone(), "M00 M30", Rule::ModalGroupConflict),
                [(2, 5)],
                "{family:?}"
            );
            assert_eq!(at(config, "M00 M30", Rule::MCodesOneGroup), []);
        }
    }

    /// A decimal code against the other codes of its group, as whole codes are: the group
    /// is the table's, decimal or not (`G54.1 P1 G55`, `G43.4 H1 G49` on a Fanuc).
    #[test]
    fn decimal_codes_in_a_modal_group() {
        let decimal = |code: &str, group: &str| {
            let facts = super::super::Code {
                status: super::super::Status::Assigned,
                duration: group.into(),
            };
            (code.to_string(), facts)
        };
        let mut config = Config {
            alarm_g: false,
            ..of_family(Family::MacroB)
        };
        config.facts.g_decimal = vec![
            decimal("54.1", "d"),
            decimal("43.4", "d"),
            decimal("5.1", "TBO"),
            decimal("12.1", "polar"),
            decimal("13.1", "polar"),
        ];
        let conflict = |body: &str| at(config.clone(), body, Rule::ModalGroupConflict);
        // G40 is in group d of the test table
        assert_eq!(conflict("G54.1 P1 G40"), [(2, 10)]);
        assert_eq!(conflict("G40 G54.1 P1"), [(2, 5)]);
        assert_eq!(conflict("G54.1 P1 G43.4"), [(2, 10)]);
        assert_eq!(conflict("G12.1 G13.1"), [(2, 7)]);
        // the same code twice, a code in its block only, and codes of two groups
        assert_eq!(conflict("G12.1 G12.1"), []);
        assert_eq!(conflict("G5.1 Q1 G04 P1"), []);
        assert_eq!(conflict("G12.1 G40"), []);
        let found = findings(config, &program("G54.1 P1 G40"), Rule::ModalGroupConflict);
        assert!(
            found[0].message.contains("G54.1 and G40") && found[0].message.contains("group d"),
            "{}",
            found[0].message
        );
        // G01 and G1 are one code
        assert_eq!(
            at(iso_mill(), "G01 G1 X1. F100.", Rule::ModalGroupConflict),
            []
        );
    }
}
