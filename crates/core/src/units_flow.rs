//! The units in force where a program's flow is not straight: a units code inside a condition
//! or a loop, or in a span a jump skips or repeats.
//!
//! A conversion reads a program in file order, and a units code (G20/G21, G70/G71,
//! G700/G710) sets the units of what follows. Where the code stands in an `o-if` (LinuxCNC
//! manual, "O Codes": conditional), a Macro B `IF ... THEN` / `WHILE ... DO` (FANUC Custom
//! Macro B, "Branch and repetition"), a SINUMERIK `IF`, `WHILE`, `LOOP`, `FOR`, `REPEAT`, or
//! between a jump (`GOTO n`, `GOTOF`/`GOTOB` label) and its target, the units after it depend
//! on values the conversion does not know: the path that skips it goes on in the units before
//! it (review 5, 1: `G21` in an `o-if`, then `G1 X2`, is 2 mm or 2 inches). Every path is
//! followed as far as the text shows it: where every path ends in the same units (an `else`
//! that selects the same, a jump over no change), nothing is in doubt; where they differ, the
//! units are unknown until the next units code, and a length or a call read there is refused,
//! as is a loop whose passes would run in different units and a backward jump to a label
//! reached first in other units. A LinuxCNC `break` is one more way out of its loop and a
//! `continue` one more way into its next pass (review 6, 1); a units code at the head of a
//! loop's body, or right after a label before any length, is what every pass, or every jump
//! there, reads the text in (review 6, 12); where the straight path does not reach a label
//! (after an unconditional jump, or the program's end), the jumps there bring their units; a
//! branch or loop left before its end (`break`, `continue`, `return`, an unconditional jump)
//! goes on in the units of its other ways, whatever its dead text selects (review 7, 3 and 4).

use crate::hash::FastMap;
use crate::lex::Family;
use crate::modal::Units;
use crate::statement::Kind as StatementKind;

/// Why the units are not known: where the units code stands whose path can be skipped.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Doubt {
    pub message: String,
}

/// A refusal at once: message, and the line and column it points at.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    pub message: String,
    pub column: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Construct {
    Condition,
    Loop,
}

#[derive(Debug, Clone)]
struct Frame {
    construct: Construct,
    /// A LinuxCNC loop's label (an `o1 do`'s: its `o1 while` closes it; any loop's: its
    /// `o1 break` and `o1 continue` name it).
    do_label: Option<Vec<u8>>,
    line: usize,
    start: Units,
    doubt_at_open: Option<Doubt>,
    /// Each branch's end so far: its units and whether they were known.
    ends: Vec<(Units, bool)>,
    has_else: bool,
    /// The last units code inside it: (line, column).
    code: Option<(usize, usize)>,
    /// A loop's paths out other than its end: each `break` (it leaves the loop) and
    /// `continue` (the loop may end at the check it goes to), with the units there, whether
    /// they were known, and the line.
    exits: Vec<(Units, bool, usize)>,
    /// A loop whose body has read nothing in units yet (no length, no flow statement, no
    /// units code): a units code read while it holds is at the head of the body.
    head_open: bool,
    /// The loop's body selects its units at its head, before anything read in them: every
    /// pass reads its text in those, whatever units the pass before ended in.
    head_code: bool,
}

/// What a block's statements do to the flow.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Event {
    Open(Construct, Option<Vec<u8>>),
    Middle,
    Close(Option<Vec<u8>>),
    /// A jump to a label (None: a target the text does not name, `GOTO #1`, `GOTOS`).
    Jump(Option<Vec<u8>>),
    Label(Vec<u8>),
    /// A Macro B `IF [..] THEN G20`: a units code that runs on one path only (its code).
    Conditional(i64),
    /// LinuxCNC's `oN break` (true: `oN continue`): the loop named leaves, or begins its
    /// next pass, in the units in force here.
    Leave(Vec<u8>, bool),
    /// The straight path does not go on past here: an unconditional jump (`GOTO n`,
    /// `GOTOF`/`GOTOB` with no `IF`), a LinuxCNC `return`.
    Dead,
}

#[derive(Debug, Default, Clone)]
pub struct UnitsFlow {
    frames: Vec<Frame>,
    doubt: Option<Doubt>,
    /// Each label seen: the units where it stands, known or not, and whether its own block
    /// selects units (a jump there runs that code first).
    labels: FastMap<Vec<u8>, (Units, bool, bool)>,
    /// The same for labels that are sequence numbers (`N10`, as [`target`] names them), by
    /// their number: nearly every block of a FANUC or Haas program has one, and a number
    /// keys the map without a string made for each block.
    numbers: FastMap<u64, (Units, bool, bool)>,
    /// Jumps whose label is not reached yet: target, units at the jump, known, line.
    pending: Vec<(Vec<u8>, Units, bool, usize)>,
    /// The last units code that changed the units in force: (line, column).
    changed: Option<(usize, usize)>,
    /// A jump to a target the text does not name was seen: its line, the units there and
    /// whether they were known (every later label can be reached in those).
    wild: Option<(usize, Units, bool)>,
    /// The labels read since the last length, flow statement or units code: a units code
    /// read next is at the label's block as far as a jump there is concerned (a SINUMERIK
    /// `LAB1:` on a line of its own, the code on the next). By number, or by name.
    heads: Vec<(Option<u64>, Vec<u8>)>,
    /// The straight path does not reach here (after an unconditional jump, `break`,
    /// `continue`, `return` or M99, or the end of the program): only a jump to a label, or
    /// the end of the branch or loop, comes on.
    dead: bool,
    /// The caller's `dead` while a LinuxCNC body is read ([`UnitsFlow::enter_body`]).
    caller_dead: bool,
    /// The units the jumps to a label read where the straight path does not come bring:
    /// the conversion reads on in them ([`UnitsFlow::arrived`]).
    arrived: Option<Units>,
    /// The first value read before the program's first units code: its units and line
    /// (what a main program's M99 runs again from its start).
    program_head: Option<(Units, usize)>,
    /// A units code of the program's was read (values after it are no longer its head).
    program_coded: bool,
    /// Haas local subprogram calls (`M97 P`): the block they name, the units at the call and
    /// its line; and the called block last reached, whose span an M99 ends.
    local_calls: Vec<(Vec<u8>, Units, usize)>,
    local: Option<Vec<u8>>,
    /// The program being read, by its number where a later program's M98 P may call it, and
    /// the calls made to it before it (their units, known or not, and line).
    program: Option<(u64, Vec<Call>)>,
    /// Kept across the programs of a file: `M98 P` calls to a program not read yet (number,
    /// units at the call, known, line), and each program read, by number (see [`Called`]).
    calls: Vec<(u64, Units, bool, usize)>,
    programs: FastMap<u64, Called>,
}

/// A call of a program (`M98 P`): the units at it, whether they were known, its line.
type Call = (Units, bool, usize);

/// What a program read before its call shows of its units: those its first values are read in
/// before its own units code (None: it selects its units first), and the units it returns in
/// where it changes them (None: it keeps its caller's; `Some(None)`: not known at its return).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Called {
    head: Option<Units>,
    exit: Option<Option<Units>>,
}

/// A label's name as a jump names it: `N10`, `GOTO 10` and `GOTO N010` the same; a name in
/// upper case; None where the target is computed (`GOTO #1`). A word names a block so too
/// (`M97 P100`'s `100`).
pub fn target(text: &[u8]) -> Option<Vec<u8>> {
    let t: Vec<u8> = text
        .iter()
        .copied()
        .filter(|c| !c.is_ascii_whitespace())
        .map(|c| c.to_ascii_uppercase())
        .collect();
    let t = t.strip_suffix(b":").unwrap_or(&t);
    if t.is_empty() || !t.iter().all(|c| c.is_ascii_alphanumeric() || *c == b'_') {
        return None;
    }
    let digits = t.strip_prefix(b"N").unwrap_or(t);
    if !digits.is_empty() && digits.iter().all(u8::is_ascii_digit) {
        let trimmed: Vec<u8> = digits.iter().copied().skip_while(|&c| c == b'0').collect();
        let mut name = b"N".to_vec();
        name.extend(if trimmed.is_empty() {
            b"0".to_vec()
        } else {
            trimmed
        });
        return Some(name);
    }
    Some(t.to_vec())
}

/// A sequence number's value, from a block's `N0010` or a label's name `N10`: 1 to 18 digits
/// after the N (None for any other name, which keys [`UnitsFlow::labels`] by its text).
/// [`sequence_key`] of an N word's `token` from what the tokenizer read of it
/// ([`crate::lex::Token::plain`], [`crate::lex::Token::digits`]): a plain number without
/// a sign or a point has the value of its digits, where they are 1 to 18. None where the
/// tokenizer did not give it (the caller reads the token then).
pub fn number_key(token: &[u8], plain: Option<u8>, digits: crate::lex::Digits) -> Option<u64> {
    let unsigned = plain == Some(0) && matches!(token.first(), Some(b'N' | b'n'));
    digits
        .value
        .filter(|_| unsigned && digits.dot as usize == token.len() - 1)
}

fn sequence_key(name: &[u8]) -> Option<u64> {
    let digits = name
        .strip_prefix(b"N")
        .or_else(|| name.strip_prefix(b"n"))?;
    crate::text::digits_value(digits)
}

/// The first target word after `keyword` ends in `upper`.
fn after(upper: &[u8], end: usize) -> Option<Vec<u8>> {
    let rest = &upper[end..];
    let start = rest.iter().position(|c| !c.is_ascii_whitespace())?;
    let rest = &rest[start..];
    let len = rest
        .iter()
        .position(|c| c.is_ascii_whitespace() || *c == b';')
        .unwrap_or(rest.len());
    target(&rest[..len])
}

/// Whether what follows Macro B's `DO` or `END` is its loop number: digits, after any blanks
/// (`DO 1`, `END 1`: the blank is skipped, as the reader skips it).
fn loop_number(rest: &[u8]) -> bool {
    rest.trim_ascii_start().iter().all(u8::is_ascii_digit)
}

fn events(family: Family, kind: StatementKind, statement: &[u8], out: &mut Vec<Event>) {
    if kind == StatementKind::Label {
        if let Some(name) = target(statement) {
            out.push(Event::Label(name));
        }
        return;
    }
    if kind != StatementKind::Flow {
        return;
    }
    if family == Family::LinuxCnc {
        let Some(keyword) = crate::statement::o_keyword(statement) else {
            return;
        };
        let label = crate::statement::o_label(statement);
        out.push(match keyword.as_slice() {
            b"if" => Event::Open(Construct::Condition, None),
            b"elseif" | b"else" => Event::Middle,
            b"endif" | b"endwhile" | b"endrepeat" | b"enddo" => Event::Close(None),
            b"while" => Event::Close(Some(label)),
            b"do" | b"repeat" => Event::Open(Construct::Loop, Some(label)),
            b"break" => Event::Leave(label, false),
            b"continue" => Event::Leave(label, true),
            // `o<name> return` leaves the body: its text after, to the end of the branch it
            // stands in, is read by no path (rs274 never reads it)
            b"return" => Event::Dead,
            _ => return,
        });
        return;
    }
    let upper: Vec<u8> = statement.iter().map(u8::to_ascii_uppercase).collect();
    let trimmed: Vec<u8> = upper
        .iter()
        .copied()
        .filter(|c| !c.is_ascii_whitespace())
        .collect();
    let starts = |w: &[u8]| trimmed.starts_with(w);
    if starts(b"CASE") {
        // SINUMERIK's CASE .. OF c1 GOTOF L1 c2 GOTOF L2 .. DEFAULT GOTOF Ln: a jump to each
        // label it names (without DEFAULT the straight path goes on too)
        for at in memchr::memmem::find_iter(&upper, b"GOTO") {
            let mut end = at + 4;
            while upper.get(end).is_some_and(u8::is_ascii_alphabetic) {
                end += 1;
            }
            out.push(Event::Jump(after(&upper, end)));
        }
        return;
    }
    if let Some(at) = memchr::memmem::find(&upper, b"GOTO") {
        // IF ... GOTO n, GOTO n, GOTOF/GOTOB/GOTOC label; GOTOS: the program's start
        let mut end = at + 4;
        while upper.get(end).is_some_and(u8::is_ascii_alphabetic) {
            end += 1;
        }
        let jump = &upper[at..end];
        out.push(Event::Jump(if jump == b"GOTOS" {
            None
        } else {
            after(&upper, end)
        }));
        // a GOTO with no IF before it (not GOTOC, which goes on where its label is missing,
        // nor a CASE's)
        if trimmed.starts_with(b"GOTO") && jump != b"GOTOC" {
            out.push(Event::Dead);
        }
        return;
    }
    if family == Family::Okuma && starts(b"IF") {
        // an OSP's IF [..] Nname jumps
        let end = upper.iter().rposition(|&c| c == b']').map_or(2, |e| e + 1);
        out.push(Event::Jump(after(&upper, end)));
    } else if starts(b"ENDIF") {
        out.push(Event::Close(None));
    } else if starts(b"ELSE") {
        out.push(Event::Middle);
    } else if starts(b"IF") {
        // a Macro B `IF [..] THEN` with nothing after THEN opens a block IF up to ENDIF; with
        // a statement after it, the condition is that block's only
        match memchr::memmem::find(&trimmed, b"THEN") {
            Some(t) if t + 4 < trimmed.len() => {
                // its statement's G codes: a units code among them runs when it holds only
                let mut rest = &trimmed[t + 4..];
                while let Some(g) = rest.iter().position(|&c| c == b'G') {
                    let digits: Vec<u8> = rest[g + 1..]
                        .iter()
                        .copied()
                        .take_while(u8::is_ascii_digit)
                        .collect();
                    if let Some(n) = std::str::from_utf8(&digits)
                        .ok()
                        .and_then(|d| d.parse::<i64>().ok())
                    {
                        out.push(Event::Conditional(n));
                    }
                    rest = &rest[g + 1..];
                }
            }
            _ => out.push(Event::Open(Construct::Condition, None)),
        }
    } else if starts(b"ENDWHILE") || starts(b"ENDFOR") || starts(b"ENDLOOP") || starts(b"UNTIL") {
        out.push(Event::Close(None));
    } else if starts(b"WHILE") || starts(b"FOR") || starts(b"LOOP") {
        out.push(Event::Open(Construct::Loop, None));
    } else if starts(b"REPEATB") || (starts(b"REPEAT") && trimmed.len() > 6) {
        // SINUMERIK's REPEAT label [label] P=n: the section from the label runs again
        let end = memchr::memmem::find(&upper, b"REPEAT").map_or(0, |a| a + 6);
        let end = end + usize::from(upper.get(end) == Some(&b'B'));
        out.push(Event::Jump(after(&upper, end)));
    } else if starts(b"REPEAT") || (trimmed.starts_with(b"DO") && loop_number(&trimmed[2..])) {
        // SINUMERIK's REPEAT ... UNTIL, Macro B's DOm ... ENDm
        out.push(Event::Open(Construct::Loop, None));
    } else if trimmed.starts_with(b"END") && loop_number(&trimmed[3..]) {
        out.push(Event::Close(None));
    }
}

impl UnitsFlow {
    /// A program begins: nothing of another program's flow carries over but the calls between
    /// the file's programs (`M98 P`), whose units the called program is checked against.
    pub fn reset(&mut self) {
        let calls = std::mem::take(&mut self.calls);
        let programs = std::mem::take(&mut self.programs);
        *self = UnitsFlow {
            calls,
            programs,
            ..UnitsFlow::default()
        };
    }

    /// A program of the file begins, numbered `number` (its O word), in `units`: a call of it
    /// read before (`M98 P`) in other units, or in units not known, runs its first values in
    /// those, so they are in doubt until its own units code (`refused`: the converter refuses
    /// them already, the units its caller leaves not being its start units, and says so).
    pub fn program_begins(&mut self, number: Option<u64>, units: Units, refused: bool) {
        let (Some(n), None) = (number, &self.program) else {
            return;
        };
        let mut calls = Vec::new();
        self.calls.retain(|c| {
            if c.0 == n {
                calls.push((c.1, c.2, c.3));
            }
            c.0 != n
        });
        let differs = calls.iter().find(|c| c.0 != units || !c.1);
        if let (Some(&(at, _, line)), false) = (differs, refused) {
            self.doubt = Some(Doubt {
                message: format!(
                    "the program O{n} is called by M98 on line {line} in {}, and read here in \
                     {}",
                    at.name(),
                    units.name()
                ),
            });
        }
        self.program = Some((n, calls));
    }

    /// A block reads a value in units (a length, a feed, a call's argument) while `units` are
    /// in force, on `line`: before the program's first units code it is the program's head,
    /// which a main program's M99 runs again.
    pub fn value(&mut self, units: Units, line: usize) {
        if self.program_head_open() {
            self.program_head = Some((units, line));
        }
    }

    /// Neither a value nor a units code of the program read yet: its head is still open.
    pub fn program_head_open(&self) -> bool {
        !self.program_coded && self.program_head.is_none()
    }

    /// A Haas local subprogram call (`M97 P n`, Haas mill operator's manual, M97: the block
    /// numbered n of the same program, up to its M99): the span runs in the units at the call,
    /// and the caller goes on in those it returns in. A span after the call is followed as a
    /// jump to it (its block is read in the units at the call, or refused) and its M99 checked
    /// ([`UnitsFlow::returns`]); a span before it, in a program that changes its units, is
    /// refused, the units it returns in not being followed.
    pub fn local_call(
        &mut self,
        name: Vec<u8>,
        line: usize,
        offset: usize,
        units: Units,
    ) -> Result<(), Refusal> {
        let seen = sequence_key(&name).map_or_else(
            || self.labels.contains_key(&name),
            |n| self.numbers.contains_key(&n),
        );
        if let (true, Some((l, c))) = (seen, self.changed) {
            return Err(Refusal {
                message: format!(
                    "M97 calls {}, a span before the call, in a program that changes its units \
                     (units code on line {l}, column {c}): the units it returns in are not \
                     followed; select the units after the call",
                    String::from_utf8_lossy(&name)
                ),
                column: offset,
            });
        }
        self.local_calls.push((name.clone(), units, line));
        self.event(Event::Jump(Some(name)), line, offset, units)
    }

    /// A jump a word makes (`M99 P n` in a main program: to its block n, FANUC
    /// "Subprogram"), to `label` as written (`10`, `N10`), followed as a `GOTO n`.
    pub fn word_jump(
        &mut self,
        label: &[u8],
        line: usize,
        offset: usize,
        units: Units,
    ) -> Result<(), Refusal> {
        self.event(Event::Jump(target(label)), line, offset, units)
    }

    /// A block reached by name (a label or sequence number): where an `M97 P` call names it,
    /// the span from it to the next M99 is that call's.
    fn reached(&mut self, name: &[u8]) {
        if self.local_calls.iter().any(|c| c.0 == name) {
            self.local = Some(name.to_vec());
        }
    }

    /// A subprogram call by number (`M98 P n`, FANUC "Subprogram"): a program of the file read
    /// before it is checked at once (its first values read in other units than the call's, or
    /// a return in other units, are refused); one read after it, when it begins
    /// ([`UnitsFlow::program_begins`]) and at its M99.
    pub fn program_call(
        &mut self,
        numbers: &[u64],
        line: usize,
        offset: usize,
        units: Units,
    ) -> Result<(), Refusal> {
        let known = self.doubt.is_none();
        for &n in numbers {
            let Some(&called) = self.programs.get(&n) else {
                self.calls.push((n, units, known, line));
                continue;
            };
            let why = match (called.head, called.exit) {
                (Some(head), _) if head != units || !known => {
                    Some(format!("its first values were read in {}", head.name()))
                }
                (_, Some(Some(exit))) if exit != units || !known => Some(format!(
                    "it returns in {}, while the text after the call is read in {}",
                    exit.name(),
                    units.name()
                )),
                (_, Some(None)) => Some("the units it returns in are not known".to_string()),
                _ => None,
            };
            if let Some(why) = why {
                return Err(Refusal {
                    message: format!(
                        "M98 calls O{n} in {}: {why}; select the units at the head of the \
                         subprogram and again after the call",
                        if known {
                            units.name()
                        } else {
                            "units not known"
                        }
                    ),
                    column: offset,
                });
            }
        }
        Ok(())
    }

    /// A return (M99 with no P) in `units`: the end of a local subprogram's span (`M97 P`),
    /// of a program called in the file (`M98 P`), whose caller goes on in the units it returns
    /// in, or of a main program, which M99 runs again from its start (FANUC "Subprogram": M99
    /// in a main program returns to its head; `after_end`: the program ended before, M02/M30,
    /// so this closes a span called from it).
    pub fn returns(&mut self, offset: usize, units: Units, after_end: bool) -> Result<(), Refusal> {
        self.leave(offset, units, after_end, false)
    }

    /// `M99 P n`: a return as [`UnitsFlow::returns`] (from a span or a program the file
    /// calls, to the caller's block n), or in a main program a jump to its block n, which
    /// [`UnitsFlow::word_jump`] follows: no return to the program's start.
    pub fn returns_to_block(
        &mut self,
        offset: usize,
        units: Units,
        after_end: bool,
    ) -> Result<(), Refusal> {
        self.leave(offset, units, after_end, true)
    }

    fn leave(
        &mut self,
        offset: usize,
        units: Units,
        after_end: bool,
        to_block: bool,
    ) -> Result<(), Refusal> {
        let known = self.doubt.is_none();
        let differ =
            |calls: Vec<(Units, usize)>| calls.into_iter().find(|&(at, _)| at != units || !known);
        let refuse = |what: String, at: Units, call: usize| Refusal {
            message: format!(
                "{what} returns here in {}, while its call on line {call} was in {}: the \
                 caller goes on after the call in these units, its text read in those; select \
                 the units again after the call",
                if known {
                    units.name()
                } else {
                    "units not known"
                },
                at.name()
            ),
            column: offset,
        };
        if let Some(name) = self.local.take() {
            let calls = self
                .local_calls
                .iter()
                .filter(|c| c.0 == name)
                .map(|c| (c.1, c.2))
                .collect();
            if let Some((at, call)) = differ(calls) {
                let what = format!("the span M97 calls at {}", String::from_utf8_lossy(&name));
                return Err(refuse(what, at, call));
            }
            return Ok(());
        }
        if after_end {
            return Ok(());
        }
        if let Some((n, calls)) = self.program.take() {
            if let Some((at, call)) = differ(calls.iter().map(|c| (c.0, c.2)).collect()) {
                return Err(refuse(format!("the subprogram O{n}"), at, call));
            }
            self.programs.insert(
                n,
                Called {
                    head: self.program_head.map(|h| h.0),
                    exit: self.changed.map(|_| known.then_some(units)),
                },
            );
            if !calls.is_empty() {
                return Ok(());
            }
        }
        if to_block {
            return Ok(());
        }
        match self.program_head {
            Some((head, at)) if head != units || !known => Err(Refusal {
                message: format!(
                    "M99 ends the program in {}: run as a main program, it begins again at its \
                     start, whose values from line {at} on, before its units code, were read in \
                     {}; select the units at the program's start",
                    if known {
                        units.name()
                    } else {
                        "units not known"
                    },
                    head.name()
                ),
                column: offset,
            }),
            _ => Ok(()),
        }
    }

    /// The units the program's first values were read in, before its own units code (None
    /// where it selected its units first, or read no value yet).
    pub fn head_units(&self) -> Option<Units> {
        self.program_head.map(|h| h.0)
    }

    /// Whether the program read a units code of its own.
    pub fn coded(&self) -> bool {
        self.program_coded
    }

    /// The units are not known here: why.
    pub fn doubt(&self) -> Option<&Doubt> {
        self.doubt.as_ref()
    }

    /// A LinuxCNC body begins, read in the units its calls give; its end gives back the
    /// caller's doubt.
    pub fn enter_body(&mut self) -> Option<Doubt> {
        self.caller_dead = std::mem::take(&mut self.dead);
        self.doubt.take()
    }

    pub fn leave_body(&mut self, doubt: Option<Doubt>) {
        self.doubt = doubt;
        self.dead = std::mem::take(&mut self.caller_dead);
    }

    /// No path reads the text here (after an unconditional jump, `break`, `continue` or
    /// `return`, or the program's end, before a label or the end of the branch): its units
    /// codes select nothing.
    pub fn is_dead(&self) -> bool {
        self.dead
    }

    /// The units are not known here: after a call of a body that may return in either
    /// ([`crate::sub_units::Bodies::call`]), at a label jumps come to in units whose feed is
    /// not followed.
    pub fn set_doubt(&mut self, message: String) {
        self.doubt = Some(Doubt { message });
    }

    /// The program ends here (M02, M30): what follows is reached by a jump only.
    pub fn ends(&mut self) {
        self.dead = true;
    }

    /// The block just read may be skipped (block delete, `/GOTO 10`): the straight path may
    /// go on past its jump or end.
    pub fn optional(&mut self) {
        self.dead = false;
    }

    /// The units the jumps to this block's label come in, where the straight path does not
    /// reach it and they differ from those the conversion read on in: it reads on in them.
    pub fn arrived(&mut self) -> Option<Units> {
        self.arrived.take()
    }

    /// Whether [`UnitsFlow::length`] is wanted: a label or a loop's head waits for a units
    /// code before anything is read in units.
    pub fn needs_lengths(&self) -> bool {
        !self.heads.is_empty() || self.frames.iter().any(|f| f.head_open)
    }

    /// A value in units (a length, a feed, a call's argument) is read: a units code after it
    /// is no longer at the head of a loop's body or at a label.
    pub fn length(&mut self) {
        self.heads.clear();
        for frame in &mut self.frames {
            frame.head_open = false;
        }
    }

    /// A block's label (its sequence number, where the family jumps to one; a SINUMERIK
    /// `LABEL:`), before its units code: `units` those in force before the block.
    pub fn block_labels(
        &mut self,
        family: Family,
        number: Option<&[u8]>,
        statements: &[(usize, StatementKind, &[u8])],
        units: Units,
        sets_units: bool,
    ) {
        self.block_labels_keyed(family, number, None, statements, units, sets_units);
    }

    /// [`UnitsFlow::block_labels`], given the number's key where the caller has it: `key`,
    /// where Some, is the sequence number's value as [`sequence_key`] reads `number` (the
    /// tokenizer's value of a plain word's digits: [`number_key`]), so that the number is not
    /// read again.
    pub fn block_labels_keyed(
        &mut self,
        family: Family,
        number: Option<&[u8]>,
        key: Option<u64>,
        statements: &[(usize, StatementKind, &[u8])],
        units: Units,
        sets_units: bool,
    ) {
        let mut names = Vec::new();
        if matches!(
            family,
            Family::MacroB | Family::Sinumerik | Family::Okuma | Family::Iso
        ) {
            // a plain sequence number with no jump waiting for a label: kept by its number,
            // no name made (the per-block case)
            match key.or_else(|| number.and_then(sequence_key)) {
                Some(n) if self.pending.is_empty() => {
                    self.numbers
                        .insert(n, (units, self.doubt.is_none(), sets_units));
                    if !sets_units {
                        self.heads.push((Some(n), Vec::new()));
                    }
                }
                _ => names.extend(number.and_then(target)),
            }
        }
        let mut found = Vec::new();
        for &(_, kind, text) in statements {
            if kind == StatementKind::Label {
                events(family, kind, text, &mut found);
            }
        }
        names.extend(found.into_iter().filter_map(|e| match e {
            Event::Label(name) => Some(name),
            _ => None,
        }));
        for name in names {
            let known = self.doubt.is_none();
            let mut arriving = Vec::new();
            self.pending.retain(|p| {
                if p.0 == name {
                    arriving.push((p.1, p.2, p.3));
                    false
                } else {
                    true
                }
            });
            let (mut units, mut known) = (units, known);
            if self.dead && !arriving.is_empty() {
                // the straight path does not come here: the jumps bring their units, where
                // they all bring the same, known (a computed jump's among them: it may land
                // on any label)
                arriving.extend(self.wild.map(|(line, at, known)| (at, known, line)));
                let (at, at_known, _) = arriving[0];
                if arriving.iter().all(|a| a.0 == at && a.1) && at_known {
                    self.dead = false;
                    self.doubt = None;
                    if at != units {
                        self.arrived = Some(at);
                    }
                    units = at;
                    known = true;
                    arriving.clear();
                } else {
                    let (other, other_line) = arriving
                        .iter()
                        .find(|a| a.0 != at)
                        .map_or((at, arriving[0].2), |a| (a.0, a.2));
                    self.dead = false;
                    known = false;
                    self.doubt = Some(Doubt {
                        message: format!(
                            "the jumps to {} come here in {} (line {}) and in {} (line \
                             {other_line}), or in units not known",
                            String::from_utf8_lossy(&name),
                            at.name(),
                            arriving[0].2,
                            other.name()
                        ),
                    });
                    arriving.clear();
                }
            }
            for (at, at_known, line) in arriving {
                if (at != units || !at_known || !known) && !sets_units {
                    self.doubt = Some(Doubt {
                        message: format!(
                            "the jump on line {line} to {} comes here in {}, the straight \
                             path in {}",
                            String::from_utf8_lossy(&name),
                            at.name(),
                            units.name()
                        ),
                    });
                }
            }
            self.reached(&name);
            let n = sequence_key(&name);
            if !sets_units {
                self.heads.push((n, name.clone()));
            }
            match n {
                Some(n) => self.numbers.insert(n, (units, known, sets_units)),
                None => self.labels.insert(name, (units, known, sets_units)),
            };
        }
    }

    /// A units code on `line` at `column`, the units before it and after it.
    pub fn units_code(&mut self, before: Units, after: Units, line: usize, column: usize) {
        self.program_coded = true;
        self.doubt = None;
        self.code_at_heads();
        if before != after {
            self.changed = Some((line, column));
            if let Some(frame) = self.frames.last_mut() {
                frame.code = Some((line, column));
            }
        }
        // a label after this code may be reached by the computed jump, in the units at the
        // jump: known only where this code selects those (a code repeated changes nothing)
        if let Some((wild, at, at_known)) = self.wild {
            if after != at || !at_known {
                self.doubt = Some(Doubt {
                    message: format!(
                        "the jump on line {wild} goes to a computed target, which may lie \
                         after the units code on line {line}"
                    ),
                });
            }
        }
    }

    /// A units code: at the head of the innermost loop's body where nothing was read in
    /// units there yet, and at the labels read since the last length.
    fn code_at_heads(&mut self) {
        if let Some(frame) = self.frames.last_mut() {
            if frame.construct == Construct::Loop && frame.head_open {
                frame.head_code = true;
            }
        }
        for (n, name) in std::mem::take(&mut self.heads) {
            let entry = match n {
                Some(n) => self.numbers.get_mut(&n),
                None => self.labels.get_mut(&name),
            };
            if let Some(entry) = entry {
                entry.2 = true;
            }
        }
        self.length();
    }

    /// A block's flow statements, after its words: `units` those in force.
    /// (`codes`: the source's inch and metric codes, for a units code a statement holds.)
    pub fn block_flow(
        &mut self,
        family: Family,
        line: usize,
        statements: &[(usize, StatementKind, &[u8])],
        units: Units,
        codes: (i64, i64),
    ) -> Result<(), Refusal> {
        for &(offset, kind, text) in statements {
            if kind == StatementKind::Label {
                continue;
            }
            let mut found = Vec::new();
            events(family, kind, text, &mut found);
            for event in found {
                if let Event::Conditional(n) = event {
                    self.length();
                    let selects = if n == codes.0 {
                        Units::Inch
                    } else if n == codes.1 {
                        Units::Metric
                    } else {
                        continue;
                    };
                    if selects != units {
                        self.changed = Some((line, 1));
                        self.doubt = Some(Doubt {
                            message: format!(
                                "the condition on line {line} selects {} when it holds, and \
                                 the units stay {} when not",
                                selects.name(),
                                units.name()
                            ),
                        });
                    }
                    continue;
                }
                self.event(event, line, offset, units)?;
            }
        }
        Ok(())
    }

    /// A construct closed where the straight path does not reach its end: the units after it
    /// as its other ways leave them (a loop's: its start's, checked against its breaks and
    /// continues; a condition's: its other branches', the start's where it has no else), set
    /// to be read on in where they differ from the file order's `units`. Where no way comes
    /// out (every branch left), the text after stays dead.
    fn dead_end(&mut self, frame: &mut Frame, units: Units) -> (Units, bool) {
        let out = match frame.construct {
            Construct::Loop => Some((frame.start, frame.doubt_at_open.is_none())),
            Construct::Condition => {
                if !frame.has_else {
                    frame
                        .ends
                        .push((frame.start, frame.doubt_at_open.is_none()));
                    frame.has_else = true;
                }
                frame.ends.pop()
            }
        };
        let Some((at, at_known)) = out else {
            self.dead = true;
            return (units, true);
        };
        self.doubt = if at_known {
            None
        } else {
            frame.doubt_at_open.clone()
        };
        if at != units {
            self.arrived = Some(at);
        }
        (at, at_known)
    }

    fn event(
        &mut self,
        event: Event,
        line: usize,
        offset: usize,
        units: Units,
    ) -> Result<(), Refusal> {
        let known = self.doubt.is_none();
        // a flow statement: a units code after it is at no label's block, nor at the head of
        // a loop's body but the one it opens; the end of a branch or a loop is reached from
        // paths before it
        self.length();
        // the branch or body just ended was left before its end (a jump, break, continue or
        // return): its end adds no path, and the units its dead text selects are no path's
        let was_dead = self.dead;
        if matches!(event, Event::Middle | Event::Close(_)) {
            self.dead = false;
        }
        match event {
            Event::Open(construct, do_label) => self.frames.push(Frame {
                construct,
                do_label,
                line,
                start: units,
                doubt_at_open: self.doubt.clone(),
                ends: Vec::new(),
                has_else: false,
                code: None,
                exits: Vec::new(),
                head_open: construct == Construct::Loop,
                head_code: false,
            }),
            Event::Dead => self.dead = true,
            Event::Leave(label, next) => {
                // the loop named, or the innermost
                let loops = || {
                    (0..self.frames.len())
                        .rev()
                        .filter(|&i| self.frames[i].construct == Construct::Loop)
                };
                let Some(i) = loops()
                    .find(|&i| self.frames[i].do_label.as_deref() == Some(label.as_slice()))
                    .or_else(|| loops().next())
                else {
                    return Ok(());
                };
                let changed = self.changed;
                let frame = &mut self.frames[i];
                let other = units != frame.start || (!known && frame.doubt_at_open.is_none());
                if next && other && !frame.head_code {
                    return Err(Refusal {
                        message: format!(
                            "the continue begins the next pass of the loop beginning on line \
                             {} in {}, while its first pass begins in {}{}: that pass's text \
                             before a units code is read in one of the two only; select the \
                             units at the head of the loop's body",
                            frame.line,
                            if known {
                                units.name()
                            } else {
                                "units not known"
                            },
                            frame.start.name(),
                            changed
                                .map(|(l, c)| format!(" (units code on line {l}, column {c})"))
                                .unwrap_or_default()
                        ),
                        column: offset,
                    });
                }
                frame.exits.push((units, known, line));
                self.dead = true;
            }
            Event::Middle => {
                if let Some(frame) = self.frames.last_mut() {
                    frame.has_else = true;
                    self.doubt = frame.doubt_at_open.clone();
                    if was_dead {
                        // the next branch begins in the units at the condition
                        if units != frame.start {
                            self.arrived = Some(frame.start);
                        }
                        return Ok(());
                    }
                    frame.ends.push((units, known));
                    if units != frame.start {
                        let (l, c) = frame.code.unwrap_or((line, 1));
                        self.doubt = Some(Doubt {
                            message: format!(
                                "the branch before ends in {} (units code on line {l}, column \
                                 {c}), while this one begins in {}",
                                units.name(),
                                frame.start.name()
                            ),
                        });
                    }
                }
            }
            Event::Close(label) => {
                // a LinuxCNC `o1 while` closes its `o1 do`, or opens a loop of its own
                if let Some(label) = label {
                    let closes = self
                        .frames
                        .last()
                        .is_some_and(|f| f.do_label.as_deref() == Some(label.as_slice()));
                    if !closes {
                        return self.event(
                            Event::Open(Construct::Loop, Some(label)),
                            line,
                            offset,
                            units,
                        );
                    }
                }
                let Some(mut frame) = self.frames.pop() else {
                    return Ok(());
                };
                let code = frame.code;
                if let (Some(outer), Some(c)) = (self.frames.last_mut(), code) {
                    outer.code = Some(c);
                }
                let (l, c) = code.unwrap_or((frame.line, 1));
                // a dead end: the units after the construct are those of its other ways,
                // which the conversion reads on in ([`UnitsFlow::arrived`])
                let (units, known) = if was_dead {
                    self.dead_end(&mut frame, units)
                } else {
                    (units, known)
                };
                match frame.construct {
                    Construct::Loop => {
                        let unknown_end = !known && frame.doubt_at_open.is_none();
                        if (units != frame.start || unknown_end) && !frame.head_code {
                            return Err(Refusal {
                                message: format!(
                                    "the loop beginning on line {} begins in {} and ends in \
                                     {} (units code on line {l}, column {c}): its passes \
                                     after the first run in other units than the text \
                                     before its units code is read in, and the units after \
                                     it depend on how often it runs; select the units before \
                                     the loop, or again at the head of its body",
                                    frame.line,
                                    frame.start.name(),
                                    if known {
                                        units.name()
                                    } else {
                                        "units not known"
                                    }
                                ),
                                column: 1,
                            });
                        }
                        // the ways out: its end after a pass, each break and continue, and
                        // where its body selects its units at its head, its start (no pass)
                        let mut ways = std::mem::take(&mut frame.exits);
                        if frame.head_code {
                            ways.push((frame.start, frame.doubt_at_open.is_none(), frame.line));
                        }
                        // a way in units not known leaves them so, where the end does not already
                        if let Some(&(other, other_known, at)) =
                            ways.iter().find(|w| w.0 != units || (!w.1 && known))
                        {
                            self.doubt = Some(Doubt {
                                message: format!(
                                    "the loop beginning on line {} is left in {} at its end \
                                     and in {} {}",
                                    frame.line,
                                    if known {
                                        units.name()
                                    } else {
                                        "units not known"
                                    },
                                    if other_known {
                                        other.name()
                                    } else {
                                        "units not known"
                                    },
                                    if at == frame.line {
                                        "where it runs no pass (its units code is in its body)"
                                            .to_string()
                                    } else {
                                        format!("on another way (line {at})")
                                    }
                                ),
                            });
                        }
                    }
                    Construct::Condition => {
                        frame.ends.push((units, known));
                        if !frame.has_else {
                            frame
                                .ends
                                .push((frame.start, frame.doubt_at_open.is_none()));
                        }
                        let same = frame.ends.iter().all(|e| e.0 == units);
                        let all_known = frame.ends.iter().all(|e| e.1);
                        self.doubt = if same && all_known {
                            None
                        } else if same {
                            frame.doubt_at_open.or(self.doubt.take())
                        } else {
                            Some(Doubt {
                                message: format!(
                                    "the condition beginning on line {} ends in {} on one \
                                     path and in {} on another (units code on line {l}, \
                                     column {c})",
                                    frame.line,
                                    units.name(),
                                    frame
                                        .ends
                                        .iter()
                                        .find(|e| e.0 != units)
                                        .map_or(units, |e| e.0)
                                        .name()
                                ),
                            })
                        };
                    }
                }
            }
            Event::Jump(None) => {
                self.wild = Some((line, units, known));
                if let Some((l, c)) = self.changed {
                    return Err(Refusal {
                        message: format!(
                            "the jump goes to a target the text computes, and the program \
                             changes its units (units code on line {l}, column {c}): the \
                             units where it lands are not known"
                        ),
                        column: offset,
                    });
                }
            }
            Event::Jump(Some(name)) => match sequence_key(&name)
                .map_or_else(|| self.labels.get(&name), |n| self.numbers.get(&n))
            {
                Some(&(at, at_known, sets_units)) => {
                    // the span runs again in the units at the jump: where those are in doubt,
                    // in either, whatever the file-order units say
                    if !sets_units && (at != units || !at_known || !known) {
                        return Err(Refusal {
                            message: format!(
                                "the jump back to {} (read first in {}) runs that span again \
                                 in {}{}: its lengths are read in one of the two only; select \
                                 the units at the label's block",
                                String::from_utf8_lossy(&name),
                                at.name(),
                                match &self.doubt {
                                    Some(d) => format!("units not known here ({})", d.message),
                                    None => units.name().to_string(),
                                },
                                self.changed
                                    .filter(|_| known)
                                    .map(|(l, c)| format!(" (units code on line {l}, column {c})"))
                                    .unwrap_or_default()
                            ),
                            column: offset,
                        });
                    }
                }
                None => self.pending.push((name, units, known, line)),
            },
            Event::Label(_) | Event::Conditional(_) => {}
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flow(family: Family, text: &str) -> Vec<Event> {
        let mut out = Vec::new();
        events(family, StatementKind::Flow, text.as_bytes(), &mut out);
        out
    }

    #[test]
    fn the_families_constructs_and_jumps_are_read() {
        let cond = || Event::Open(Construct::Condition, None);
        let lp = || Event::Open(Construct::Loop, None);
        assert_eq!(flow(Family::LinuxCnc, "o1 if [#5 GT #6]"), [cond()]);
        assert_eq!(
            flow(Family::LinuxCnc, "o1 while [#2]"),
            [Event::Close(Some(b"o1".to_vec()))]
        );
        assert_eq!(
            flow(Family::MacroB, "IF [#5 GT #6] GOTO 010"),
            [Event::Jump(Some(b"N10".to_vec()))]
        );
        assert_eq!(
            flow(Family::MacroB, "GOTO #10"),
            [Event::Jump(None), Event::Dead]
        );
        assert_eq!(
            flow(Family::MacroB, "GOTO 10"),
            [Event::Jump(Some(b"N10".to_vec())), Event::Dead]
        );
        assert_eq!(
            flow(Family::Sinumerik, "GOTOC LAB1"),
            [Event::Jump(Some(b"LAB1".to_vec()))]
        );
        assert_eq!(
            flow(Family::LinuxCnc, "o100 break"),
            [Event::Leave(b"o100".to_vec(), false)]
        );
        assert_eq!(
            flow(Family::LinuxCnc, "o100 continue"),
            [Event::Leave(b"o100".to_vec(), true)]
        );
        assert_eq!(
            flow(Family::LinuxCnc, "o7 repeat [3]"),
            [Event::Open(Construct::Loop, Some(b"o7".to_vec()))]
        );
        assert_eq!(flow(Family::MacroB, "IF [#1 EQ 0] THEN"), [cond()]);
        assert!(flow(Family::MacroB, "IF [#1 EQ 0] THEN #3=1").is_empty());
        assert_eq!(
            flow(Family::MacroB, "IF [#1 EQ 0] THEN G20"),
            [Event::Conditional(20)]
        );
        assert_eq!(flow(Family::MacroB, "WHILE [#1 LT 10] DO1"), [lp()]);
        assert_eq!(flow(Family::MacroB, "END1"), [Event::Close(None)]);
        assert_eq!(
            flow(Family::Sinumerik, "IF R5>R6 GOTOF LAB1"),
            [Event::Jump(Some(b"LAB1".to_vec()))]
        );
        assert_eq!(flow(Family::Sinumerik, "IF R5>R6"), [cond()]);
        assert_eq!(flow(Family::Sinumerik, "REPEAT"), [lp()]);
        assert_eq!(
            flow(Family::Sinumerik, "REPEAT LAB1 P=3"),
            [Event::Jump(Some(b"LAB1".to_vec()))]
        );
        assert_eq!(flow(Family::Sinumerik, "UNTIL R1>3"), [Event::Close(None)]);
        assert_eq!(
            flow(
                Family::Sinumerik,
                "CASE R1 OF 1 GOTOF LAB1 2 GOTOB LAB2 DEFAULT GOTOF LAB3"
            ),
            [b"LAB1", b"LAB2", b"LAB3"].map(|l| Event::Jump(Some(l.to_vec())))
        );
    }

    /// Review 6, 3: a jump back while the units are in doubt runs the span in either units,
    /// even where the file-order units are the label's; with the units known and equal it
    /// runs in the label's.
    #[test]
    fn a_jump_back_in_doubt_is_refused_whatever_the_file_order_units() {
        let mut f = UnitsFlow::default();
        f.block_labels(Family::MacroB, Some(b"N10"), &[], MM, false);
        assert!(f
            .event(Event::Jump(Some(b"N10".to_vec())), 3, 5, MM)
            .is_ok());
        f.doubt = Some(Doubt {
            message: "the condition on line 4 selects inch".into(),
        });
        let e = f
            .event(Event::Jump(Some(b"N10".to_vec())), 5, 5, MM)
            .unwrap_err();
        assert!(
            e.message.contains(
                "runs that span again in units not known here (the condition \
                                on line 4 selects inch)"
            ),
            "{}",
            e.message
        );
    }

    /// Review 6, 5: M99 P n is a jump; a main program's M99 runs its head again; a Haas
    /// `M97 P` span and an `M98 P` program of the file are entered and left in their calls'
    /// units, or refused.
    #[test]
    fn spans_run_again_by_words_are_checked_in_their_calls_units() {
        // M99 P10 after G20, N10 read in metric (a length after it: the G20 is not at N10)
        let mut f = UnitsFlow::default();
        f.block_labels(Family::MacroB, Some(b"N10"), &[], MM, false);
        f.length();
        f.units_code(MM, IN, 4, 1);
        assert!(f.word_jump(b"10", 6, 1, IN).is_err());
        // a units code right after N10, before any length, is what the jump runs first
        let mut f = UnitsFlow::default();
        f.block_labels(Family::MacroB, Some(b"N10"), &[], MM, false);
        f.units_code(MM, IN, 2, 1);
        f.length();
        assert!(f.word_jump(b"10", 6, 1, IN).is_ok());
        // a main program's M99: its head (line 3) in metric, its end in inch
        let mut f = UnitsFlow::default();
        f.value(MM, 3);
        f.units_code(MM, IN, 4, 1);
        f.value(IN, 5);
        let e = f.returns(1, IN, false).unwrap_err();
        assert!(e.message.contains("from line 3 on"), "{}", e.message);
        // one that selects its units before its first value loops in them
        let mut f = UnitsFlow::default();
        f.units_code(MM, IN, 3, 1);
        f.value(IN, 4);
        f.units_code(IN, MM, 5, 1);
        assert!(f.returns(1, MM, false).is_ok());
        // M97 P100 from inch and from metric: the span after M30 is in doubt
        let mut f = UnitsFlow::default();
        f.local_call(b"N100".to_vec(), 3, 1, IN).unwrap();
        f.local_call(b"N100".to_vec(), 5, 1, MM).unwrap();
        f.block_labels(Family::MacroB, Some(b"N100"), &[], MM, false);
        assert!(f.doubt().unwrap().message.contains("line 3 to N100"));
        // a span that returns in other units than its call's
        let mut f = UnitsFlow::default();
        f.local_call(b"N100".to_vec(), 3, 1, IN).unwrap();
        f.block_labels(Family::MacroB, Some(b"N100"), &[], IN, true);
        f.units_code(IN, MM, 8, 1);
        let e = f.returns(1, MM, true).unwrap_err();
        assert!(
            e.message.contains("call on line 3 was in inch"),
            "{}",
            e.message
        );
        // M98 P2000 in inch; O2000 after it, read in metric: its first values are in doubt,
        // and the calls' record survives the program's reset
        let mut f = UnitsFlow::default();
        f.program_call(&[2000], 4, 1, IN).unwrap();
        f.reset();
        f.program_begins(Some(2000), MM, false);
        assert!(f
            .doubt()
            .unwrap()
            .message
            .contains("O2000 is called by M98 on line 4"));
        f.units_code(MM, IN, 9, 1);
        assert!(f.returns(1, IN, false).is_ok());
        // a program read before its call: its head's units against the call's
        let mut f = UnitsFlow::default();
        f.program_begins(Some(2000), MM, false);
        f.value(MM, 3);
        f.returns(1, MM, false).unwrap();
        f.reset();
        assert!(f.program_call(&[2000], 7, 1, MM).is_ok());
        let e = f.program_call(&[2000], 9, 1, IN).unwrap_err();
        assert!(
            e.message.contains("first values were read in metric"),
            "{}",
            e.message
        );
    }

    /// A condition whose branches all end in the same units leaves them known; one that
    /// skips a change leaves them in doubt until the next units code.
    #[test]
    fn paths_that_end_in_other_units_leave_them_in_doubt() {
        const MM: Units = Units::Metric;
        const IN: Units = Units::Inch;
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Condition, None), 3, 0, IN)
            .unwrap();
        f.units_code(IN, MM, 4, 1);
        f.event(Event::Close(None), 5, 0, MM).unwrap();
        assert!(f.doubt().unwrap().message.contains("line 4, column 1"));
        f.units_code(MM, MM, 6, 1);
        assert!(f.doubt().is_none());
        // if/else both selecting metric
        f.event(Event::Open(Construct::Condition, None), 7, 0, IN)
            .unwrap();
        f.units_code(IN, MM, 8, 1);
        f.event(Event::Middle, 9, 0, MM).unwrap();
        assert!(f.doubt().is_some());
        f.units_code(IN, MM, 10, 1);
        f.event(Event::Close(None), 11, 0, MM).unwrap();
        assert!(f.doubt().is_none());
        // a loop that changes units after a length is refused at its end
        f.event(Event::Open(Construct::Loop, None), 12, 0, MM)
            .unwrap();
        f.length();
        f.units_code(MM, IN, 13, 1);
        let e = f.event(Event::Close(None), 14, 0, IN).unwrap_err();
        assert!(e.message.contains("line 13, column 1"), "{}", e.message);
        // a backward jump to a label read in other units
        let mut f = UnitsFlow::default();
        f.block_labels(Family::MacroB, Some(b"N10"), &[], MM, false);
        f.length();
        f.units_code(MM, IN, 3, 1);
        assert!(f
            .event(Event::Jump(Some(b"N10".to_vec())), 4, 5, IN)
            .is_err());
    }

    const MM: Units = Units::Metric;
    const IN: Units = Units::Inch;

    /// Review 6, 1: `break` leaves a loop, and `continue` begins its next pass, in the units
    /// in force there (rs274: the break path moves X1 in inch after a loop that ends in mm).
    #[test]
    fn break_and_continue_leave_the_loop_in_their_units() {
        let body = |f: &mut UnitsFlow, next: bool| {
            f.event(
                Event::Open(Construct::Loop, Some(b"o100".to_vec())),
                2,
                0,
                MM,
            )?;
            f.length();
            f.units_code(MM, IN, 3, 1);
            f.event(Event::Open(Construct::Condition, None), 4, 0, IN)?;
            f.event(Event::Leave(b"o100".to_vec(), next), 5, 7, IN)?;
            f.event(Event::Close(None), 6, 0, IN)?;
            f.units_code(IN, MM, 7, 1);
            f.event(Event::Close(None), 9, 0, MM)
        };
        let mut f = UnitsFlow::default();
        body(&mut f, false).unwrap();
        let doubt = &f.doubt().unwrap().message;
        assert!(
            doubt.contains("left in metric at its end and in inch on another way (line 5)"),
            "{doubt}"
        );
        f.units_code(MM, MM, 10, 1);
        assert!(f.doubt().is_none());
        let e = body(&mut UnitsFlow::default(), true).unwrap_err();
        assert_eq!(e.column, 7);
        assert!(
            e.message
                .contains("next pass of the loop beginning on line 2 in inch"),
            "{}",
            e.message
        );
        // a break in the units the loop ends in changes nothing
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Loop, Some(b"o1".to_vec())), 2, 0, MM)
            .unwrap();
        f.event(Event::Leave(b"o1".to_vec(), false), 3, 0, MM)
            .unwrap();
        f.event(Event::Close(None), 4, 0, MM).unwrap();
        assert!(f.doubt().is_none());
    }

    /// Review 7, 3: the text after a `continue`, `break` or `return` is read by no path: a
    /// loop or branch whose end is dead goes on in its other ways' units (the conversion reads
    /// on in them), where every branch is left the text after stays dead.
    #[test]
    fn a_construct_left_before_its_end_goes_on_in_its_other_ways_units() {
        assert_eq!(flow(Family::LinuxCnc, "o<s> return"), vec![Event::Dead]);
        // o100 while / o100 continue / G20 / o100 endwhile: metric after the loop
        let mut f = UnitsFlow::default();
        f.event(
            Event::Open(Construct::Loop, Some(b"o100".to_vec())),
            2,
            0,
            MM,
        )
        .unwrap();
        f.event(Event::Leave(b"o100".to_vec(), true), 3, 0, MM)
            .unwrap();
        assert!(f.is_dead());
        f.units_code(MM, IN, 4, 1);
        f.event(Event::Close(None), 5, 0, IN).unwrap();
        assert!(!f.is_dead() && f.doubt().is_none());
        assert_eq!(f.arrived(), Some(MM));
        // a continue in inch before the dead G21 is still refused
        let mut f = UnitsFlow::default();
        f.event(
            Event::Open(Construct::Loop, Some(b"o100".to_vec())),
            2,
            0,
            MM,
        )
        .unwrap();
        f.length();
        f.units_code(MM, IN, 3, 1);
        assert!(f
            .event(Event::Leave(b"o100".to_vec(), true), 4, 0, IN)
            .is_err());
        // o1 if / o100 break / G20 / o1 else / (metric) / o1 endif: the else begins in metric
        // and the condition ends in it; with both branches left, the text after stays dead
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Loop, None), 1, 0, MM)
            .unwrap();
        f.event(Event::Open(Construct::Condition, None), 2, 0, MM)
            .unwrap();
        f.event(Event::Leave(Vec::new(), false), 3, 0, MM).unwrap();
        f.units_code(MM, IN, 4, 1);
        f.event(Event::Middle, 5, 0, IN).unwrap();
        assert_eq!(f.arrived(), Some(MM));
        f.event(Event::Close(None), 7, 0, MM).unwrap();
        assert!(f.doubt().is_none() && !f.is_dead());
        f.event(Event::Open(Construct::Condition, None), 8, 0, MM)
            .unwrap();
        f.event(Event::Dead, 9, 0, MM).unwrap();
        f.event(Event::Middle, 10, 0, MM).unwrap();
        f.event(Event::Dead, 11, 0, MM).unwrap();
        f.event(Event::Close(None), 12, 0, MM).unwrap();
        assert!(f.is_dead());
    }

    /// Review 6, 12: a units code at the head of a loop's body, before anything read in
    /// units, is what every pass reads its text in: the loop converts, and only the units
    /// after it (no pass, or some) are in doubt. A code after a length is refused still.
    #[test]
    fn a_units_code_at_the_head_of_a_loop_s_body_settles_its_passes() {
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Loop, None), 2, 0, MM)
            .unwrap();
        assert!(f.needs_lengths());
        f.units_code(MM, IN, 3, 1);
        assert!(!f.needs_lengths());
        f.length();
        f.event(Event::Close(None), 5, 0, IN).unwrap();
        let doubt = &f.doubt().unwrap().message;
        assert!(
            doubt.contains("in inch at its end and in metric"),
            "{doubt}"
        );
        f.units_code(IN, MM, 6, 1);
        assert!(f.doubt().is_none());
        // entered in doubt: a pass settles the units, no pass leaves the doubt
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Condition, None), 2, 0, MM)
            .unwrap();
        f.units_code(MM, IN, 3, 1);
        f.event(Event::Close(None), 4, 0, IN).unwrap();
        f.event(Event::Open(Construct::Loop, None), 5, 0, IN)
            .unwrap();
        f.units_code(IN, IN, 6, 1);
        assert!(f.doubt().is_none());
        f.length();
        f.event(Event::Close(None), 8, 0, IN).unwrap();
        let doubt = &f.doubt().unwrap().message;
        assert!(
            doubt.contains("and in units not known where it runs no pass"),
            "{doubt}"
        );
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Loop, None), 2, 0, MM)
            .unwrap();
        f.length();
        f.units_code(MM, IN, 4, 1);
        assert!(f.event(Event::Close(None), 5, 0, IN).is_err());
        // a condition before the code: not at the head
        let mut f = UnitsFlow::default();
        f.event(Event::Open(Construct::Loop, None), 2, 0, MM)
            .unwrap();
        f.event(Event::Open(Construct::Condition, None), 3, 0, MM)
            .unwrap();
        f.event(Event::Close(None), 4, 0, MM).unwrap();
        f.units_code(MM, IN, 5, 1);
        assert!(f.event(Event::Close(None), 6, 0, IN).is_err());
    }

    /// Review 6, 6: after a computed jump, a later label may be reached in the units at the
    /// jump: a units code repeated leaves that doubt, one selecting the jump's units ends it.
    #[test]
    fn a_computed_jump_s_doubt_lasts_to_a_code_selecting_its_units() {
        let mut f = UnitsFlow::default();
        f.event(Event::Jump(None), 2, 0, MM).unwrap();
        f.units_code(MM, IN, 3, 1);
        assert!(f.doubt().is_some());
        f.units_code(IN, IN, 4, 1);
        let doubt = &f.doubt().unwrap().message;
        assert!(doubt.contains("the jump on line 2"), "{doubt}");
        f.units_code(IN, MM, 5, 1);
        assert!(f.doubt().is_none());
    }

    /// Review 6, 12: where the straight path does not reach a label (after an unconditional
    /// jump, or the program's end), the jumps there bring their units, and the conversion
    /// reads on in them; jumps bringing different units leave them in doubt.
    #[test]
    fn a_label_the_straight_path_does_not_reach_is_in_its_jumps_units() {
        let mut f = UnitsFlow::default();
        f.event(Event::Jump(Some(b"N10".to_vec())), 2, 0, MM)
            .unwrap();
        f.event(Event::Dead, 2, 0, MM).unwrap();
        f.units_code(MM, IN, 3, 1);
        f.block_labels(Family::MacroB, Some(b"N10"), &[], IN, false);
        assert!(f.doubt().is_none());
        assert_eq!(f.arrived(), Some(MM));
        assert_eq!(f.arrived(), None);
        // a conditional jump, then the end: two jumps in two units
        let mut f = UnitsFlow::default();
        f.event(Event::Jump(Some(b"N20".to_vec())), 2, 0, MM)
            .unwrap();
        f.units_code(MM, IN, 3, 1);
        f.event(Event::Jump(Some(b"N20".to_vec())), 4, 0, IN)
            .unwrap();
        f.ends();
        f.block_labels(Family::MacroB, Some(b"N20"), &[], IN, false);
        let doubt = &f.doubt().unwrap().message;
        assert!(
            doubt.contains("in metric (line 2) and in inch (line 4)"),
            "{doubt}"
        );
        assert_eq!(f.arrived(), None);
        // a jump under block skip: the straight path may go on
        let mut f = UnitsFlow::default();
        f.event(Event::Jump(Some(b"N10".to_vec())), 2, 0, MM)
            .unwrap();
        f.event(Event::Jump(Some(b"N20".to_vec())), 3, 0, MM)
            .unwrap();
        f.event(Event::Dead, 3, 0, MM).unwrap();
        f.optional();
        f.units_code(MM, IN, 4, 1);
        f.block_labels(Family::MacroB, Some(b"N10"), &[], IN, false);
        assert!(f.doubt().is_some());
        assert_eq!(f.arrived(), None);
        // a computed jump may land there too, in its units
        let mut f = UnitsFlow::default();
        f.event(Event::Jump(None), 2, 0, MM).unwrap();
        f.event(Event::Dead, 2, 0, MM).unwrap();
        f.units_code(MM, IN, 3, 1);
        f.event(Event::Jump(Some(b"N40".to_vec())), 4, 0, IN)
            .unwrap();
        f.units_code(IN, MM, 5, 1);
        f.event(Event::Jump(Some(b"N50".to_vec())), 6, 0, MM)
            .unwrap();
        f.event(Event::Dead, 6, 0, MM).unwrap();
        f.block_labels(Family::MacroB, Some(b"N40"), &[], MM, false);
        let doubt = &f.doubt().unwrap().message;
        assert!(
            doubt.contains("in inch (line 4) and in metric (line 2)"),
            "{doubt}"
        );
    }

    /// Review 6, 12: a SINUMERIK label on a line of its own, its units code on the next
    /// before any length: a jump back to it runs that code first.
    #[test]
    fn a_units_code_after_a_label_before_any_length_is_at_the_label() {
        let label: &[(usize, StatementKind, &[u8])] = &[(0, StatementKind::Label, b"LAB1:")];
        for length_first in [false, true] {
            let mut f = UnitsFlow::default();
            f.block_labels(Family::Sinumerik, None, label, MM, false);
            if length_first {
                f.length();
            }
            f.units_code(MM, MM, 3, 1);
            f.length();
            f.units_code(MM, IN, 5, 1);
            let back = f.event(Event::Jump(Some(b"LAB1".to_vec())), 6, 0, IN);
            assert_eq!(back.is_err(), length_first, "{back:?}");
        }
    }

    /// [`number_key`], the tokenizer's value of an N word's digits, against
    /// [`sequence_key`]'s reading of the token: on 300,000 drawn lines under every family's
    /// dialect, each N word's key, where given, is the one the token reads to, and where the
    /// token reads to one the key is given for most (the caller's reading is the fallback).
    #[test]
    fn an_n_words_key_from_the_tokenizer_is_its_reading() {
        use crate::lex::Dialect;
        const BYTES: &[u8] = b"NnXG0123456789.+- \t#[]=;(";
        const PIECES: [&str; 12] = [
            "N10 ",
            "n0070 ",
            "N1234567890123456789 ",
            "N123456789012345678 ",
            "N-5 ",
            "N+5 ",
            "N1.5 ",
            "N.5 ",
            "N 12 ",
            "N#1 ",
            "X1.5 ",
            "N",
        ];
        let mut next = crate::drawn::xorshift(0x5DEE_CE66_D1CE_4E5B);
        let dialects: Vec<Dialect> = Family::ALL.into_iter().map(Dialect::permissive).collect();
        let (mut given, mut read) = (0, 0);
        for _ in 0..300_000 {
            let line = crate::drawn::line(&mut next, BYTES, &PIECES, 4);
            let dialect = &dialects[(next() % dialects.len() as u64) as usize];
            let mut tokens = Vec::new();
            if crate::tokenizer::tokenize(&line, dialect, &mut tokens).is_err() {
                continue;
            }
            for t in tokens
                .iter()
                .filter(|t| t.text[0].eq_ignore_ascii_case(&b'N'))
            {
                let reading = sequence_key(&t.text);
                let key = number_key(&t.text, t.plain, t.digits);
                if key.is_some() {
                    given += 1;
                    assert_eq!(key, reading, "{:?}", String::from_utf8_lossy(&line));
                }
                read += usize::from(reading.is_some());
            }
        }
        assert!(given > 20_000 && given * 10 > read * 9, "{given} {read}");
    }
}
