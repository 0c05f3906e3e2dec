//! TG118: the block a cycle, a call or a jump names by its sequence number is in the program.
//!
//! A Fanuc or Haas control searches its program for the block a word names and alarms where it
//! is not there: the contour of a lathe's multiple repetitive cycle (`G70`-`G73 P ns Q nf`,
//! FANUC 0i-TF alarm PS0063, "the block with the sequence number specified by P or Q was not
//! found"), a Haas local subprogram (`M97 P`: "a P code is required and must match a line
//! number within the same program", Haas mill operator's manual, M97), the return of a main
//! program to a sequence number (`M99 P`, PS0060 "sequence number not found") and a macro's
//! branch (`GOTO n`, PS0128 "illegal macro sequence number"). The control stops there, at the
//! machine; the checker says so where the word is. The words that name a block are the
//! profile's ([`super::CodeWord`] with address N: `words = { P = "N" }`), and GOTO.
//!
//! Each is searched in its own program ([`Checker::next_program`] begins the next); an `M99 P`
//! only in a main program (one that ends with M02/M30), since a subprogram's returns to its
//! caller's block, which is another program's. A target written as an expression
//! (`GOTO #1`, `P#101`) is not followed.
//!
//! The sequence numbers are kept as a bit set up to N99999 (12.5 KB, the format N05 of every
//! Fanuc and Haas profile) and a set of at most [`WIDE_LABELS`] larger ones, and a target only
//! while no block of the program has shown it, at most [`PENDING`]: past either the program's
//! targets are not checked (memory stays flat on a drip-fed program).

use super::Checker;
use crate::rules::Rule;
use crate::statement::Kind;

/// The sequence numbers a bit each: N0-N99999.
const NARROW: usize = 100_000;
/// The most sequence numbers past N99999 kept for one program.
const WIDE_LABELS: usize = 100_000;
/// The most targets not found yet kept for one program.
const PENDING: usize = 100_000;

/// A block a word names: its number, where the word is, the word as written and what names it.
#[derive(Debug, Clone)]
pub(super) struct Target {
    n: u64,
    line: usize,
    column: usize,
    token: String,
    /// The returns of `M99 P`: checked in a main program only.
    returns: bool,
    /// A `GOTO n` of an IF whose condition the values known where it is read make false
    /// ([`Checker::condition_known`]): that run does not search for N n (review 56b, F8), and
    /// a later one -- a loop or a jump back -- may, so its missing block is TG139's warning.
    untaken: bool,
}

/// The sequence numbers of one program, and the blocks its words name.
#[derive(Clone, Debug, Default)]
pub(super) struct Targets {
    narrow: Vec<u64>,
    wide: std::collections::HashSet<u64>,
    overflow: bool,
    /// The targets not found so far, by number: a block found later takes its own away.
    pending: std::collections::HashMap<u64, Vec<Target>>,
    count: usize,
    /// A word of the program may bring the run back to a block with values other than those
    /// read down to it: a GOTO to a block already read (a jump back), one whose number is
    /// worked out, or a jump by number of a code (`M99 P`, Haas `M97 P`, `M98 Q`), which
    /// arrives with the values where it stands (review 57c F1, F4). An IF known false on the
    /// first pass may then be true on another: its missing target stays TG118.
    rejoins: bool,
    /// A SINUMERIK's labels (`MARKE:`) and block numbers (`N100`, kept as written in capitals):
    /// the first and last line of each. A block number, on nearly every block of a CAM
    /// program, is kept by [`block_number_key`] in `numbers`, with no text to allocate and
    /// hash; a label of another form by its name in `labels`.
    labels: std::collections::HashMap<Vec<u8>, (usize, usize)>,
    numbers: BlockNumbers,
    /// A SINUMERIK's jumps to a label: checked at the program's end, as the labels may follow.
    jumps: Vec<Jump>,
    /// The names a SINUMERIK declaration gives (`DEF STRING[8] ZIEL="M1"`): a jump to one goes
    /// where the variable's value names, which is not followed.
    declared: std::collections::HashSet<Vec<u8>>,
}

/// A SINUMERIK's block numbers by [`block_number_key`], the first and last line of each. A CAM
/// program numbers its blocks rising (`N10`, `N20`, ...), starting again after its largest or
/// at a repeated part: a rising number is kept at the end of a sorted list, and one written
/// again where the block before's was is found one step further on, so that nearly every block
/// is one comparison, not a hash and a search of the table (a number out of both orders is
/// searched in the list, then kept in the table).
#[derive(Clone, Debug, Default)]
struct BlockNumbers {
    /// Rising keys, each with its first and last line.
    rising: Vec<(u64, usize, usize)>,
    /// Where in `rising` the next block's number is looked for first.
    next: usize,
    /// The numbers written below the largest so far and not in `rising`.
    others: std::collections::HashMap<u64, (usize, usize), NumberHash>,
}

impl BlockNumbers {
    fn len(&self) -> usize {
        self.rising.len() + self.others.len()
    }

    /// `key` written on `line`; a new one kept only where there is `room` (false: not kept).
    fn note(&mut self, key: u64, line: usize, room: bool) -> bool {
        if let Some(entry) = self.rising.get_mut(self.next) {
            if entry.0 == key {
                entry.2 = line;
                self.next += 1;
                return true;
            }
        }
        // (a key above every rising one is above every other one too: those were below the
        // largest rising key when they came, and it only grows)
        if self.rising.last().is_none_or(|last| key > last.0) {
            if !room {
                return false;
            }
            self.rising.push((key, line, line));
            self.next = self.rising.len();
            return true;
        }
        if let Ok(i) = self.rising.binary_search_by_key(&key, |e| e.0) {
            self.rising[i].2 = line;
            self.next = i + 1;
            return true;
        }
        if let Some(lines) = self.others.get_mut(&key) {
            lines.1 = line;
            return true;
        }
        if room {
            self.others.insert(key, (line, line));
        }
        room
    }

    /// The first and last line of `key`.
    fn lines(&self, key: u64) -> Option<(usize, usize)> {
        match self.rising.binary_search_by_key(&key, |e| e.0) {
            Ok(i) => Some((self.rising[i].1, self.rising[i].2)),
            Err(_) => self.others.get(&key).copied(),
        }
    }
}

/// The hasher of [`BlockNumbers::others`]: a block number's key is already a number, mixed by
/// one multiplication (the keys are the program's own, no input chosen to collide).
type NumberHash = std::hash::BuildHasherDefault<NumberHasher>;

#[derive(Debug, Default)]
struct NumberHasher(u64);

impl std::hash::Hasher for NumberHasher {
    fn finish(&self) -> u64 {
        self.0 ^ (self.0 >> 29)
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
}

/// A SINUMERIK destination or label that is a block number, `N` and 1-17 digits (`N0100`,
/// in capitals): its digits' value and count in one number, so that `N0100` and `N100` stay
/// two names as their texts are.
fn block_number_key(name: &[u8]) -> Option<u64> {
    match name {
        [b'N', digits @ ..] => digits_key(digits),
        _ => None,
    }
}

/// [`block_number_key`] of `N` and these digits.
fn digits_key(digits: &[u8]) -> Option<u64> {
    if digits.is_empty() || digits.len() > 17 || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let value = digits
        .iter()
        .fold(0u64, |n, &d| n * 10 + u64::from(d - b'0'));
    Some(value | (digits.len() as u64) << 58)
}

/// Which way a SINUMERIK jump searches for its destination (Programming Manual Job
/// Planning, "Program jumps to jump markers (GOTOB, GOTOF, GOTO, GOTOC)"): GOTOF toward the
/// program's end, GOTOB toward its start, GOTO forward then backward.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Direction {
    Forward,
    Backward,
    Both,
}

/// A SINUMERIK jump: its destination in capitals, the way it searches, and where it is.
#[derive(Debug, Clone)]
struct Jump {
    name: Vec<u8>,
    direction: Direction,
    line: usize,
    column: usize,
    token: String,
}

/// A SINUMERIK flow statement's jump in `upper` (the statement in capitals): the column of
/// its GOTO word, the way it searches and the destination (a label or a block number `N100`).
/// `GOTOC` (no alarm where the destination is missing) and `GOTOS` (the program's start) name
/// none to check; nor does a destination in an expression or a string.
pub(super) fn sinumerik_jump(upper: &[u8]) -> Option<(usize, Direction, &[u8])> {
    let at = upper
        .windows(4)
        .enumerate()
        .position(|(i, w)| w == b"GOTO" && (i == 0 || !is_name(upper[i - 1])))?;
    let (direction, skip) = match upper.get(at + 4) {
        Some(b'F') => (Direction::Forward, 5),
        Some(b'B') => (Direction::Backward, 5),
        Some(&c) if crate::lex::blank(c) => (Direction::Both, 4),
        _ => return None,
    };
    let rest = &upper[at + skip..];
    if rest.first().is_some_and(|&c| !crate::lex::blank(c)) {
        return None;
    }
    let start = rest.iter().position(|&c| !crate::lex::blank(c))?;
    let end = rest[start..]
        .iter()
        .position(|&c| !is_name(c))
        .map_or(rest.len(), |e| start + e);
    let name = &rest[start..end];
    let tail_blank = rest[end..].iter().all(|&c| crate::lex::blank(c));
    let starts_well = name
        .first()
        .is_some_and(|c| c.is_ascii_alphabetic() || *c == b'_');
    (tail_blank && starts_well).then_some((at, direction, name))
}

fn is_name(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

impl Targets {
    fn label(&mut self, n: u64) {
        if !self.pending.is_empty() {
            if let Some(found) = self.pending.remove(&n) {
                self.count -= found.len();
            }
        }
        if (n as usize) < NARROW {
            if self.narrow.is_empty() {
                self.narrow = vec![0; NARROW / 64 + 1];
            }
            self.narrow[n as usize / 64] |= 1 << (n % 64);
        } else if self.wide.len() < WIDE_LABELS {
            self.wide.insert(n);
        } else {
            self.overflow = true;
        }
    }

    /// A SINUMERIK label or block number on `line` (its name in capitals).
    fn sinumerik_label(&mut self, name: &[u8], line: usize) {
        if let Some(key) = block_number_key(name) {
            self.sinumerik_number(key, line);
        } else if let Some(lines) = self.labels.get_mut(name) {
            lines.1 = line;
        } else if self.labels.len() + self.numbers.len() < WIDE_LABELS {
            self.labels.insert(name.to_vec(), (line, line));
        } else {
            self.overflow = true;
        }
    }

    /// A SINUMERIK block number on `line`, by its [`block_number_key`].
    fn sinumerik_number(&mut self, key: u64, line: usize) {
        let room = self.labels.len() + self.numbers.len() < WIDE_LABELS;
        if !self.numbers.note(key, line, room) {
            self.overflow = true;
        }
    }

    /// The first and last line of a SINUMERIK label or block number, by its name in capitals.
    pub(super) fn sinumerik_lines(&self, name: &[u8]) -> Option<(usize, usize)> {
        match block_number_key(name) {
            Some(key) => self.numbers.lines(key),
            None => self.labels.get(name).copied(),
        }
    }

    /// A block a word names: kept until the program's end unless the program has shown it.
    fn name(&mut self, target: Target) {
        if self.has(target.n) {
            return;
        }
        if self.count >= PENDING {
            self.overflow = true;
            return;
        }
        self.count += 1;
        self.pending.entry(target.n).or_default().push(target);
    }

    /// Custom Macro B: whether the program has shown sequence number `n` so far (a `GOTO n`
    /// may go back to it); None where the numbers are not all kept.
    pub(super) fn read_before(&self, n: u64) -> Option<bool> {
        (!self.overflow).then(|| self.has(n))
    }

    /// SINUMERIK: whether the program has shown label or block number `name` (in capitals)
    /// so far, or may have (its names not all kept).
    pub(super) fn sinumerik_read(&self, name: &[u8]) -> bool {
        self.overflow || self.sinumerik_lines(name).is_some()
    }

    /// A `GOTO n` of the program names a block not shown so far (or the numbers are not
    /// all kept): at its end, a block after it that a jump reaches (callflow.rs).
    pub(super) fn goto_pending(&self) -> bool {
        self.overflow
            || self
                .pending
                .values()
                .flatten()
                .any(|t| t.token.starts_with("GOTO"))
    }

    fn has(&self, n: u64) -> bool {
        if (n as usize) < NARROW {
            self.narrow
                .get(n as usize / 64)
                .is_some_and(|bits| bits & 1 << (n % 64) != 0)
        } else {
            self.wide.contains(&n)
        }
    }
}

/// A flow statement's `GOTO` in `upper` (the statement in capitals): the column of the word,
/// the digits after it (blanks skipped; none for `GOTO #1` or `GOTO [#1+1]`), and the text
/// after the digits. The jump targets here and the parameter analysis read it alike.
pub(super) fn goto_words(upper: &[u8]) -> Option<(usize, &[u8], &[u8])> {
    let at = upper.windows(4).position(|w| w == b"GOTO")?;
    let rest = &upper[at + 4..];
    let start = rest
        .iter()
        .position(|&c| !crate::lex::blank(c))
        .unwrap_or(rest.len());
    let end = rest[start..]
        .iter()
        .position(|c| !c.is_ascii_digit())
        .map_or(rest.len(), |e| start + e);
    Some((at, &rest[start..end], &rest[end..]))
}

impl Checker {
    /// A SINUMERIK block's label and block number, its declared names and its jump.
    #[inline(never)]
    fn sinumerik_targets(&mut self, b: &super::BlockView<'_>) {
        if let Some(w) = b
            .words
            .iter()
            .find(|w| w.letter == b'N' && w.expression.is_empty() && w.index.is_empty())
        {
            match (w.sign.is_empty(), digits_key(w.number)) {
                (true, Some(key)) => self.targets.sinumerik_number(key, b.line),
                _ => {
                    let name = w.token.to_ascii_uppercase();
                    self.targets.sinumerik_label(&name, b.line);
                }
            }
        }
        for &(column, kind, text) in b.statements {
            if !matches!(kind, Kind::Label | Kind::Declaration | Kind::Flow) {
                continue;
            }
            let upper = text.to_ascii_uppercase();
            match kind {
                Kind::Label => {
                    let name = upper.strip_suffix(b":").unwrap_or(&upper).trim_ascii();
                    self.targets.sinumerik_label(name, b.line);
                }
                Kind::Declaration => {
                    for name in upper.split(|&c| !is_name(c)).filter(|n| !n.is_empty()) {
                        if self.targets.declared.len() < WIDE_LABELS {
                            self.targets.declared.insert(name.to_vec());
                        }
                    }
                }
                Kind::Flow => {
                    let Some((at, direction, name)) = sinumerik_jump(&upper) else {
                        continue;
                    };
                    if self.targets.jumps.len() >= PENDING {
                        self.targets.overflow = true;
                        continue;
                    }
                    let token = String::from_utf8_lossy(&text[at..]).trim().to_string();
                    self.targets.jumps.push(Jump {
                        name: name.to_vec(),
                        direction,
                        line: b.line,
                        column: column + at,
                        token,
                    });
                }
                _ => {}
            }
        }
    }

    /// The block's sequence number, and the blocks its words and its GOTO name.
    #[inline]
    pub(super) fn targets(&mut self, b: &super::BlockView<'_>) {
        // (the family's test inlined where it is asked, once a block; the reading out of line)
        match self.config.family {
            crate::lex::Family::Sinumerik => self.sinumerik_targets(b),
            // (a block with no N word, no word its codes make name a block and no statement
            // -- most blocks of a program not numbered -- has nothing for it: not called)
            // (a block whose one target is its plain N word first: taken inline)
            crate::lex::Family::MacroB => {
                let names_more = !self.named.is_empty() || !b.statements.is_empty();
                if names_more
                    || (self.letters & crate::modal::bit(b'N') != 0 && !self.plain_label(b))
                {
                    self.macro_b_targets(b)
                }
            }
            _ => {}
        }
    }

    /// The sequence number of a block that names nothing else (no word its codes make name a
    /// block, no statement: asked only of such a block), taken inline where it is the plain,
    /// whole N word first in the block, below [`NARROW`], no jump waits for a label and the
    /// narrow labels are laid out: what [`Checker::macro_b_targets`] does with such a block,
    /// without its call (true). False, nothing done, for any other block.
    #[inline(always)]
    fn plain_label(&mut self, b: &super::BlockView<'_>) -> bool {
        let Some(w) = b.words.first() else {
            return false;
        };
        let t = &mut self.targets;
        let n = match w.value {
            Some(n) if w.letter == b'N' && w.expression.is_empty() && !w.point => n,
            _ => return false,
        };
        if (n as usize) >= NARROW || !t.pending.is_empty() || t.narrow.is_empty() {
            return false;
        }
        debug_assert_eq!(Some(n), crate::text::digits_value(w.number));
        t.narrow[n as usize / 64] |= 1 << (n % 64);
        true
    }

    /// [`Checker::targets`] on a Custom Macro B control (Fanuc, Haas).
    #[inline(never)]
    fn macro_b_targets(&mut self, b: &super::BlockView<'_>) {
        // (a block with no N word, as the letters say, is not walked for one; a plain N
        // word's digits are the value its reader kept, `Word::value`, without a point)
        if self.letters & crate::modal::bit(b'N') != 0 {
            if let Some(n) = b
                .words
                .iter()
                .find(|w| w.letter == b'N' && w.expression.is_empty())
                .and_then(|w| {
                    debug_assert_eq!(
                        w.value.filter(|_| !w.point),
                        crate::text::digits_value(w.number),
                        "line {}: an N word's kept digits",
                        b.line
                    );
                    w.value.filter(|_| !w.point)
                })
            {
                self.targets.label(n);
            }
        }
        // the words the block's codes make name a block (`Checker::named_words`, read with
        // the block's words: a block of statements only names none)
        for (letter, address, code) in self.named.iter().filter(|_| !b.words.is_empty()) {
            if *address != b'N' {
                continue;
            }
            let word = b
                .words
                .iter()
                .find(|v| v.letter == *letter && v.expression.is_empty() && v.sign.is_empty());
            self.targets.rejoins = true;
            if let Some((v, n)) = word.and_then(|v| Some((v, crate::text::digits_value(v.number)?)))
            {
                let returns = code
                    .as_bytes()
                    .first()
                    .is_some_and(|c| c.eq_ignore_ascii_case(&b'M'))
                    && super::code_number(&code.as_bytes()[1..]) == b"99";
                self.targets.name(Target {
                    n,
                    line: b.line,
                    column: v.column,
                    token: format!("{code} {}", v.token()),
                    returns,
                    untaken: false,
                });
            }
        }
        for &(column, kind, text) in b.statements {
            if kind != Kind::Flow {
                continue;
            }
            let upper = text.to_ascii_uppercase();
            let Some((at, digits, tail)) = goto_words(&upper) else {
                continue;
            };
            // GOTO 10 (a number, not GOTO #1 or GOTO [#1+1]), to the end of the statement
            let n = crate::text::digits_value(digits)
                .filter(|_| !tail.iter().any(|&c| !crate::lex::blank(c)));
            if n.is_none_or(|n| self.targets.has(n)) {
                self.targets.rejoins = true;
            }
            if let Some(n) = n {
                let untaken = self.condition_known(&upper) == Some(false);
                self.targets.name(Target {
                    n,
                    line: b.line,
                    column: column + at,
                    token: format!("GOTO {n}"),
                    returns: false,
                    untaken,
                });
            }
        }
    }

    /// Whether the block's one statement is a `GOTO n` to a number (of an IF or not), the
    /// block calling nothing: a jump whose ways in the checker knows (passed.rs).
    pub(super) fn goto_only(&self, b: &super::BlockView<'_>) -> bool {
        let [(_, Kind::Flow, text)] = b.statements else {
            return false;
        };
        let upper = text.to_ascii_uppercase();
        goto_words(&upper).is_some_and(|(_, digits, tail)| {
            !digits.is_empty() && tail.iter().all(|&c| crate::lex::blank(c))
        })
    }

    /// The sequence number a block that cannot be read begins with (`N200 G00 3.7347`): the
    /// block is there for a search (its own error is said), so a cycle naming it is no TG118.
    pub(super) fn unreadable_label(&mut self, text: &[u8]) {
        if self.config.family != crate::lex::Family::MacroB {
            return;
        }
        let start = text
            .iter()
            .position(|&c| !crate::lex::blank(c) && c != b'/')
            .unwrap_or(text.len());
        if !matches!(text.get(start), Some(b'N' | b'n')) {
            return;
        }
        let digits = &text[start + 1..];
        let end = digits
            .iter()
            .position(|c| !c.is_ascii_digit())
            .unwrap_or(digits.len());
        if let Some(n) = crate::text::digits_value(&digits[..end]) {
            self.targets.label(n);
        }
    }

    /// The end of a program: each block a word named that is not in it (TG118).
    pub(super) fn targets_ended(&mut self) {
        let targets = std::mem::take(&mut self.targets);
        if targets.overflow
            || !(self.enabled(Rule::TargetNotFound) || self.enabled(Rule::TargetNotFoundIfTrue))
        {
            return;
        }
        let main = self.ended_line > 0;
        let mut missing: Vec<&Target> = targets
            .pending
            .values()
            .flatten()
            .filter(|t| main || !t.returns)
            .collect();
        missing.sort_by_key(|t| (t.line, t.column));
        // a SINUMERIK jump whose destination is not where it searches (the same block counts:
        // the checker does not say whether the search includes it)
        let mut lost: Vec<(usize, usize, String)> = Vec::new();
        for jump in &targets.jumps {
            if targets.declared.contains(&jump.name) {
                continue;
            }
            let found = targets
                .sinumerik_lines(&jump.name)
                .is_some_and(|(first, last)| match jump.direction {
                    Direction::Forward => last >= jump.line,
                    Direction::Backward => first <= jump.line,
                    Direction::Both => true,
                });
            if !found {
                let way = match jump.direction {
                    Direction::Forward => " after it",
                    Direction::Backward => " before it",
                    Direction::Both => "",
                };
                let name = String::from_utf8_lossy(&jump.name);
                let message = format!(
                    "{}: no label or block {name}{way} in this program; the control stops here with an \
                     alarm (SINUMERIK: jump destination not found)",
                    jump.token
                );
                lost.push((jump.line, jump.column, message));
            }
        }
        for (line, column, message) in lost {
            self.report(Rule::TargetNotFound, message, line, column);
        }
        for t in missing {
            let alarm = if t.token.starts_with("GOTO") {
                "FANUC: alarm PS0128"
            } else if t.returns {
                "FANUC: alarm PS0060"
            } else if t.token.starts_with('M') {
                "Haas M97: the P must match a block number of the same program"
            } else {
                "FANUC: alarm PS0063"
            };
            if t.untaken && !targets.rejoins {
                let message = format!(
                    "{}: no block N{} in this program; the IF's condition is false with the \
                     values known here, so this pass goes on to the next block; a pass where \
                     it is true (a loop, a jump back, other values) stops here with an alarm \
                     ({alarm})",
                    t.token, t.n
                );
                self.report(Rule::TargetNotFoundIfTrue, message, t.line, t.column);
                continue;
            }
            let message = format!(
                "{}: no block N{} in this program; the control stops here with an alarm ({alarm})",
                t.token, t.n
            );
            self.report(Rule::TargetNotFound, message, t.line, t.column);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{BlockNumbers, NumberHash};

    #[test]
    fn the_block_numbers_keep_the_lines_a_table_keeps() {
        // rising, repeated (a wrapped or repeated part), falling and pseudo-random numbers,
        // with a cap: each key's first and last line as a hash table holds them, and the same
        // keys refused for want of room
        let mut seed: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = |n: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % n
        };
        for round in 0..200 {
            let cap = [usize::MAX, 5, 40][round % 3];
            let mut keys = Vec::new();
            let parts = 1 + next(4);
            for _ in 0..parts {
                let (start, step, count) = (next(50), 1 + next(20), next(60));
                let shape = next(4);
                for k in 0..count {
                    keys.push(match shape {
                        0 | 1 => start + k * step,
                        2 => (start + 2000).saturating_sub(k * step),
                        _ => next(300),
                    });
                }
            }
            let mut numbers = BlockNumbers::default();
            let mut table: std::collections::HashMap<u64, (usize, usize), NumberHash> =
                Default::default();
            for (line, &key) in keys.iter().enumerate() {
                let kept = numbers.note(key, line + 1, numbers.len() < cap);
                let expected = if let Some(lines) = table.get_mut(&key) {
                    lines.1 = line + 1;
                    true
                } else if table.len() < cap {
                    table.insert(key, (line + 1, line + 1));
                    true
                } else {
                    false
                };
                assert_eq!(kept, expected, "round {round} line {line}");
                assert_eq!(numbers.len(), table.len());
            }
            for key in 0..2400 {
                assert_eq!(
                    numbers.lines(key),
                    table.get(&key).copied(),
                    "{round} {key}"
                );
            }
        }
    }
}
