//! Two programs' blocks compared as NC (`formats.diff`: `tapegate diff`, `convert --verify`).
//!
//! The blocks are those of [`crate::ncread`]. Two paired blocks are the same when every word
//! of one has its partner in the other (by address; codes by value first) of the same value
//! within the tolerance -- `tolerance` steps of B's word format, exact, in integer ratios --
//! and within the bound of its address; with the same comments, and, with the motion
//! compared, the same modal state after them (a difference reported once where it starts or
//! changes). In G91 the axis words are compared as positions: the difference carried from the
//! words before is added. The common case -- the same -- is decided here without a Python
//! object; a difference is handed over as [`Found`], for `formats.diff` to describe.

use std::cmp::Ordering;
use std::collections::VecDeque;

use crate::decimal::{greater, round_quotient, Dec, POW10};
/// The exact integers and ratios of a tolerance (the binding builds them from Python ints).
pub use crate::decimal::{Big, Ratio};
use crate::modal::{ModalState, Units};
use crate::ncread::{DiffBlock, Factor, InStatement, Kind, ReadWord, State, STATE_LETTERS};
use crate::word::Word;
use crate::wordformat::write as write_digits;

impl Factor {
    fn ratio(self) -> (u128, u128) {
        match self {
            Factor::One => (1, 1),
            Factor::Inch => (254, 10),
            Factor::Foot => (3048, 10000),
        }
    }
}

/// How to compare (`formats.diff.DiffOptions`, resolved).
#[derive(Debug, Clone)]
pub struct Options {
    /// In resolution steps of B's word format.
    pub tolerance: Ratio,
    /// The largest difference accepted per address in B's units (verify: the rounding the
    /// converter reported); an address not named accepts none.
    pub bounds: Option<Vec<(u8, Ratio)>>,
    pub word_order: bool,
    /// Parameters and expressions compared only by their address.
    pub parameters_address: bool,
    /// A P/Q/R of no stated role beside a length is read as that length.
    pub unstated_adopt: bool,
    /// A word of the same value and format, written as its format writes it, must be the
    /// same text.
    pub same_text: bool,
    /// One step of B's profile's format by letter and units, for a value of the modal state.
    pub steps: Vec<(u8, Units, Dec)>,
}

/// A word as compared, where it is not the word as read: a P/Q/R adopted as a length, or
/// both words as written when one profile reads a length and the other a number.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct View {
    pub kind: Kind,
    pub value: Dec,
    pub factor: Factor,
    pub step: Dec,
}

/// One side of a word change: the index of the word in its block, and how it was compared.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Side {
    pub index: usize,
    pub view: Option<View>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChangeKind {
    Added,
    Removed,
    Changed,
    Order,
    Written,
    /// A statement whose number neither side reads by a role, in other units on each side
    /// ([`Comparer::unread`]): not compared, no difference.
    Unread,
}

impl ChangeKind {
    pub fn name(self) -> &'static str {
        match self {
            ChangeKind::Added => "added",
            ChangeKind::Removed => "removed",
            ChangeKind::Changed => "changed",
            ChangeKind::Order => "order",
            ChangeKind::Written => "written",
            ChangeKind::Unread => "unread",
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WordChange {
    pub kind: ChangeKind,
    pub key: Vec<u8>,
    pub a: Option<Side>,
    pub b: Option<Side>,
    /// B - A (as a position in G91), in the unit of the kind; None where not a value.
    pub difference: Option<Dec>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MotionChange {
    pub what: String,
    pub a: String,
    pub b: String,
    pub difference: Option<Dec>,
}

/// What makes a motion difference news: a value by its difference (a position off by the
/// same amount block after block is one difference), a mode by its two values.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Signature {
    Value(String, Dec),
    Text(String, String, String),
}

/// What differs between two paired blocks.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Found {
    pub words: Vec<WordChange>,
    pub comments: bool,
    pub motion: Vec<MotionChange>,
}

const AXES: &[u8; 9] = b"XYZUVWABC";

fn axis(key: &[u8]) -> Option<usize> {
    match key {
        [letter] => AXES.iter().position(|a| a == letter),
        _ => None,
    }
}

/// A statement's text without its blanks, but for those inside a string (`MSG("a b")`).
fn unblanked(text: &[u8]) -> Vec<u8> {
    let mut quoted = false;
    let mut out = Vec::with_capacity(text.len());
    for &c in text {
        quoted ^= c == b'"';
        if quoted || !matches!(c, b' ' | b'\t') {
            out.push(c);
        }
    }
    out
}

fn sub(b: Dec, a: Dec) -> Option<Dec> {
    b.checked_add(-a)
}

/// Whether a word is written as its format writes it, so that a conversion keeping its value
/// and format keeps its text: a count of no more digits than the format holds (all of them
/// where it omits no zeros); in an explicit-decimal program a number with a point and no more
/// decimals than the format's, or a whole number the control reads as such (not a count of
/// increments, which a conversion writes with its point); in an implicit-decimal program the
/// format's own writing of the value.
fn as_its_format_writes(word: &ReadWord) -> bool {
    let (Some(form), Some(raw)) = (&word.form, word.raw) else {
        return false;
    };
    let fmt = &form.format;
    let number = Word::new(&word.written, 0).number;
    let dot = number.iter().position(|&c| c == b'.');
    if !fmt.decimal {
        let digits = number.len();
        return dot.is_none()
            && digits <= fmt.before as usize
            && (fmt.zeros != crate::wordformat::Zeros::None || digits == fmt.before as usize);
    }
    if form.explicit {
        return match dot {
            Some(at) => number.len() - at - 1 <= fmt.after as usize,
            None => !form.increments,
        };
    }
    if dot.is_some() {
        return false;
    }
    let magnitude = raw.abs();
    let units = if magnitude.scale <= fmt.after {
        match POW10
            .get((fmt.after - magnitude.scale) as usize)
            .and_then(|p| magnitude.mantissa.checked_mul(*p))
        {
            Some(u) => u,
            None => return false,
        }
    } else {
        // to the format's resolution, half to even (Decimal's to_integral_value)
        let Some(&p) = POW10.get((magnitude.scale - fmt.after) as usize) else {
            return false;
        };
        let (q, r) = (magnitude.mantissa / p, magnitude.mantissa % p);
        round_quotient(q, r, p, false).0
    };
    write_digits(units, fmt.after, fmt, false, false).as_bytes() == number
}

fn view(w: &ReadWord) -> Option<(View, bool, Option<Factor>)> {
    Some((
        View {
            kind: w.kind,
            value: w.value?,
            factor: w.factor,
            step: w.step,
        },
        w.incremental,
        w.as_length,
    ))
}

/// A P/Q/R word of no stated role read as the length the other profile says it is.
fn adopted(v: &View, factor: Factor) -> Option<View> {
    Some(View {
        kind: Kind::Length,
        value: factor.times(v.value)?,
        factor,
        step: factor.times(v.step)?,
    })
}

/// A word as written: one profile reads a length, the other a number.
fn as_written(w: &ReadWord) -> Option<View> {
    Some(View {
        kind: Kind::Number,
        value: w.raw?,
        factor: Factor::One,
        step: w.raw_step,
    })
}

/// The modes of the modal state compared, in the order reported.
const MODES: [&str; 14] = [
    "motion",
    "plane",
    "incremental",
    "feed mode",
    "spindle mode",
    "spindle",
    "coolant",
    "compensation",
    "length offset",
    "zero shift",
    "tool",
    "offset",
    "cycle",
    "speed limit",
];

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Int(Option<i64>),
    Bool(bool),
    Name(&'static str),
    Value(Option<Dec>),
}

impl Mode {
    fn text(self) -> String {
        match self {
            Mode::Int(None) | Mode::Value(None) => "none".into(),
            Mode::Int(Some(v)) => v.to_string(),
            Mode::Bool(v) => (if v { "yes" } else { "no" }).into(),
            Mode::Name(name) => name.into(),
            Mode::Value(Some(v)) => v.plain(),
        }
    }
}

fn modes(s: &ModalState) -> [Mode; 14] {
    [
        Mode::Int(s.motion),
        Mode::Int(Some(s.plane)),
        Mode::Bool(s.incremental),
        Mode::Int(Some(s.feed_mode)),
        Mode::Int(Some(s.spindle_mode)),
        Mode::Name(match s.spindle {
            3 => "cw",
            4 => "ccw",
            _ => "stop",
        }),
        Mode::Name(match s.coolant {
            7 => "mist",
            8 => "flood",
            _ => "off",
        }),
        Mode::Int(Some(s.compensation)),
        Mode::Int(Some(s.length_offset)),
        Mode::Int(s.zero_shift),
        Mode::Int(s.tool),
        Mode::Int(s.offset),
        Mode::Int(s.cycle),
        Mode::Value(s.speed_limit),
    ]
}

fn slot(letter: u8) -> usize {
    STATE_LETTERS
        .iter()
        .position(|&l| l == letter)
        .expect("a letter of the state")
}

/// A value of the core's modal state (`F`, `S`, an axis) in its metric unit: times the factor
/// of the word that set it.
fn state_value(state: &State, letter: u8) -> Option<Dec> {
    let value = match letter {
        b'F' => state.modal.feed,
        b'S' => state.modal.speed,
        _ => state.modal.axis(letter),
    }?;
    state.factors[slot(letter)]
        .unwrap_or(Factor::One)
        .times(value)
}

fn state_unit(letter: u8, state: &State) -> &'static str {
    let length = b"XYZUVW".contains(&letter);
    if state.factors[slot(letter)].is_none() && !length {
        return "";
    }
    match letter {
        _ if length => " mm",
        b'F' if state.modal.feed_mode != 93 => {
            if state.modal.feed_mode == 95 {
                " mm/rev"
            } else {
                " mm/min"
            }
        }
        b'S' if state.modal.spindle_mode == 96 => " m/min",
        _ => "",
    }
}

/// Compares paired blocks; keeps what the blocks after need: the position carried in G91
/// and the motion difference last reported.
pub struct Comparer {
    pub options: Options,
    /// Head mismatches in a row whose search for a resync found nothing (see [`Aligner`]).
    pub misses: usize,
    carry: [Option<Dec>; 9],
    motion: Vec<Signature>,
    /// The statements whose numbers were not compared, as (A's line, B's line, A's text):
    /// a statement holding a number of no role the converter's table gives, read in other
    /// units in the two programs (`--allow-unconverted` left it as written; a LinuxCNC call's
    /// arguments, converted by the parameter analysis). Kept for the blocks compared with
    /// `commit`.
    pub unread: Vec<(usize, usize, Vec<u8>)>,
}

impl Comparer {
    pub fn new(options: Options) -> Comparer {
        Comparer {
            options,
            misses: 0,
            carry: [None; 9],
            motion: Vec::new(),
            unread: Vec::new(),
        }
    }

    /// Whether two blocks are the same, keeping nothing.
    pub fn same(&mut self, a: &DiffBlock, b: &DiffBlock) -> bool {
        self.compare(a, b, false).is_none()
    }

    /// A block only in one program: one program moved where the other did not.
    pub fn unpaired(&mut self, block: &DiffBlock) {
        if block.words.iter().any(|w| w.incremental) {
            self.carry = [None; 9];
        }
    }

    /// Whether two blocks are the same; if so, what the blocks after need is kept (the
    /// common case of pairing by position: compared once).
    pub fn pair(&mut self, a: &DiffBlock, b: &DiffBlock) -> bool {
        let saved = (self.carry, self.motion.clone());
        if self.compare(a, b, true).is_none() {
            return true;
        }
        (self.carry, self.motion) = saved;
        false
    }

    /// What differs between two paired blocks (None: the same). `commit` keeps the position
    /// carried and the motion difference reported, for the blocks after.
    pub fn compare(&mut self, a: &DiffBlock, b: &DiffBlock, commit: bool) -> Option<Found> {
        let mut carry = self.carry;
        let mut changes = Vec::new();
        if same_keys(a, b) {
            // the common case: the same addresses in the same order, each once
            for (i, (wa, wb)) in a.words.iter().zip(&b.words).enumerate() {
                if let Some(c) = self.word(wa, i, wb, i, &mut carry) {
                    changes.push(c);
                }
            }
        } else {
            self.keyed(a, b, &mut carry, &mut changes);
        }
        // a statement whose numbers cannot be compared is no difference: it is told apart
        let mut unread = Vec::new();
        changes.retain(|c| {
            if c.kind != ChangeKind::Unread {
                return true;
            }
            if let Some(side) = &c.a {
                unread.push((a.line, b.line, a.words[side.index].token.clone()));
            }
            false
        });
        if commit {
            self.unread.extend(unread);
        }
        if self.options.word_order && changes.is_empty() && order(a) != order(b) {
            changes.push(WordChange {
                kind: ChangeKind::Order,
                key: Vec::new(),
                a: None,
                b: None,
                difference: None,
            });
        }
        if a.resets || b.resets {
            carry = [None; 9];
        }
        let comments = a.comments != b.comments;
        let mut motion = Vec::new();
        if let (Some(sa), Some(sb)) = (&a.state, &b.state) {
            let found = self.motion_changes(sa, sb, b);
            let signature: Vec<Signature> = found
                .iter()
                .map(|m| match m.difference {
                    Some(d) => Signature::Value(m.what.clone(), d),
                    None => Signature::Text(m.what.clone(), m.a.clone(), m.b.clone()),
                })
                .collect();
            if signature != self.motion {
                motion = found;
            }
            if commit {
                self.motion = signature;
            }
        }
        if commit {
            self.carry = carry;
        }
        if changes.is_empty() && !comments && motion.is_empty() {
            return None;
        }
        Some(Found {
            words: changes,
            comments,
            motion,
        })
    }

    /// The words of two blocks paired by address, in the order of A's addresses and then B's
    /// new ones (codes by value first, see [`matched`]).
    fn keyed(
        &self,
        a: &DiffBlock,
        b: &DiffBlock,
        carry: &mut [Option<Dec>; 9],
        changes: &mut Vec<WordChange>,
    ) {
        let mut keys: Vec<&[u8]> = Vec::new();
        for w in a.words.iter().chain(&b.words) {
            if !keys.contains(&w.key.as_slice()) {
                keys.push(&w.key);
            }
        }
        for key in keys {
            let la: Vec<usize> = (0..a.words.len())
                .filter(|&i| a.words[i].key == key)
                .collect();
            let lb: Vec<usize> = (0..b.words.len())
                .filter(|&i| b.words[i].key == key)
                .collect();
            for pair in matched(a, b, &la, &lb) {
                match pair {
                    (Some(i), Some(j)) => {
                        if let Some(c) = self.word(&a.words[i], i, &b.words[j], j, carry) {
                            changes.push(c);
                        }
                    }
                    (i, j) => {
                        let word = match (i, j) {
                            (Some(i), _) => &a.words[i],
                            (_, Some(j)) => &b.words[j],
                            _ => unreachable!("a pair has a word"),
                        };
                        if word.kind != Kind::Units {
                            // a units code the other program has not: its meaning is in
                            // the values after it
                            changes.push(WordChange {
                                kind: if j.is_none() {
                                    ChangeKind::Removed
                                } else {
                                    ChangeKind::Added
                                },
                                key: key.to_vec(),
                                a: i.map(|index| Side { index, view: None }),
                                b: j.map(|index| Side { index, view: None }),
                                difference: None,
                            });
                        }
                    }
                }
            }
        }
    }

    fn word(
        &self,
        wa: &ReadWord,
        ia: usize,
        wb: &ReadWord,
        ib: usize,
        carry: &mut [Option<Dec>; 9],
    ) -> Option<WordChange> {
        let o = &self.options;
        let change = |kind, a: Option<View>, b: Option<View>, difference| WordChange {
            kind,
            key: wa.key.clone(),
            a: Some(Side { index: ia, view: a }),
            b: Some(Side { index: ib, view: b }),
            difference,
        };
        // (a dwell's time by a parameter or an expression, in milliseconds on one side and
        // seconds on the other: the same text is another time, in `diff`'s comparison as
        // written too -- review 24, finding 2: `G04 P#1` of a FANUC and `g4 p#1` of LinuxCNC,
        // 1000 times apart, were "the same program")
        if wa.parameter && wb.parameter && wa.milliseconds != wb.milliseconds {
            return Some(change(ChangeKind::Changed, None, None, None));
        }
        if wa.parameter && wb.parameter && o.parameters_address {
            return None;
        }
        match (wa.statement, wb.statement) {
            (InStatement::Text { values, arguments }, InStatement::Text { .. }) => {
                if values && wa.factor != wb.factor && (arguments || wa.token == wb.token) {
                    // its number read in other units on each side, by no role known
                    return Some(change(ChangeKind::Unread, None, None, None));
                }
                // `diff` compares whatever the spacing; the proof byte for byte
                let same = if o.same_text {
                    wa.token == wb.token
                } else {
                    unblanked(&wa.token) == unblanked(&wb.token)
                };
                return (!same).then(|| change(ChangeKind::Changed, None, None, None));
            }
            // a statement's length in the same units on both sides: left as written, where
            // the source wrote it with its point (a FANUC corner without one, read in least
            // increments, is written with its point: compared by value below)
            (InStatement::Number, InStatement::Number)
                if o.same_text
                    && wa.factor == wb.factor
                    && !wa.written.eq_ignore_ascii_case(&wb.written)
                    && wa.written.contains(&b'.') =>
            {
                return Some(change(ChangeKind::Written, None, None, None));
            }
            _ => {}
        }
        let (Some((mut va, inc_a, len_a)), Some((mut vb, inc_b, len_b))) = (view(wa), view(wb))
        else {
            // (a letter's case is no difference: a control that reads lower case reads it as
            // the upper-case letter, and `convert` writes a lower-case word in upper case for
            // one that does not: review 16c, finding 5)
            if wa.token.eq_ignore_ascii_case(&wb.token) && wa.value.is_none() == wb.value.is_none()
            {
                return None; // the same text; a number neither reads, written the same
            }
            return Some(change(ChangeKind::Changed, None, None, None));
        };
        if wa.kind == Kind::Units && wb.kind == Kind::Units {
            return None; // G20 and G21 alike: their meaning is in every value after them
        }
        if o.same_text
            && !wa.written.eq_ignore_ascii_case(&wb.written)
            && wa.value == wb.value
            && wa.factor == wb.factor
            && wa.form.is_some()
            && wa.form == wb.form
            && as_its_format_writes(wa)
        {
            return Some(change(ChangeKind::Written, None, None, None));
        }
        let codes = |k| matches!(k, Kind::Code | Kind::Units);
        if codes(wa.kind) || codes(wb.kind) {
            return (wa.value != wb.value).then(|| change(ChangeKind::Changed, None, None, None));
        }
        let (mut a_seen, mut b_seen) = (None, None);
        let (mut inc_a, mut inc_b) = (inc_a, inc_b);
        if va.kind != vb.kind && o.unstated_adopt {
            // a P/Q/R word of no stated role, where the other profile says it is a length
            if let (Some(f), Kind::Length) = (len_a, vb.kind) {
                let Some(v) = adopted(&va, f) else {
                    return Some(change(ChangeKind::Changed, None, None, None));
                };
                (va, a_seen) = (v.clone(), Some(v));
            } else if let (Some(f), Kind::Length) = (len_b, va.kind) {
                let Some(v) = adopted(&vb, f) else {
                    return Some(change(ChangeKind::Changed, None, None, None));
                };
                (vb, b_seen) = (v.clone(), Some(v));
            }
        }
        if va.kind != vb.kind {
            // one profile reads a length, the other a number: both as written
            let (Some(x), Some(y)) = (as_written(wa), as_written(wb)) else {
                return Some(change(ChangeKind::Changed, None, None, None));
            };
            (va, vb, a_seen, b_seen) = (x.clone(), y.clone(), Some(x), Some(y));
            (inc_a, inc_b) = (false, false);
        }
        let mut difference = sub(vb.value, va.value);
        // the position the word moves: its own axis, or X Z for a lathe's U W
        let slot = match (wa.moves, wb.moves) {
            (Some(l), Some(m)) if l == m => axis(&[l]),
            _ => axis(&wa.key),
        };
        if inc_a && inc_b {
            // B's position minus A's, after the word
            if let (Some(d), Some(c)) = (difference, slot.and_then(|i| carry[i])) {
                difference = d.checked_add(c);
            }
        }
        let Some(difference) = difference else {
            return Some(change(ChangeKind::Changed, a_seen, b_seen, None));
        };
        if self.within(difference, &vb, wb.key[0]) {
            if let Some(i) = slot {
                carry[i] = Some(difference);
            }
            return None;
        }
        if let Some(i) = slot {
            carry[i] = None; // reported: the words after it are compared afresh
        }
        Some(change(
            ChangeKind::Changed,
            a_seen,
            b_seen,
            Some(difference),
        ))
    }

    /// Whether a difference is accepted: within the tolerance in steps of `word`'s format and
    /// within the bound of its address (exact: integer ratios, no rounding).
    pub fn within(&self, difference: Dec, word: &View, letter: u8) -> bool {
        if difference.is_zero() {
            return true;
        }
        let m = difference.mantissa.unsigned_abs();
        let scale = POW10[difference.scale as usize] as u128;
        let step_m = word.step.mantissa.unsigned_abs();
        let step_scale = POW10[word.step.scale as usize] as u128;
        // |d| > tolerance * step  <=>  m * q * 10^s2 > p * m2 * 10^s1
        let t = &self.options.tolerance;
        let beyond = t
            .small
            .and_then(|(p, q)| greater([m, q, step_scale], [p, step_m, scale]))
            .unwrap_or_else(|| {
                let (m, scale) = difference.magnitude();
                let (step_m, step_scale) = word.step.magnitude();
                m.mul(&t.q).mul(&step_scale) > t.p.mul(&step_m).mul(&scale)
            });
        if beyond {
            return false;
        }
        if let Some(bounds) = &self.options.bounds {
            let (fp, fq) = word.factor.ratio();
            let Some((_, bound)) = bounds.iter().find(|(l, _)| *l == letter) else {
                return false; // an address not named accepts no difference
            };
            // |d| > bound * factor  <=>  m * bq * fq > bp * fp * 10^s1
            let beyond = bound
                .small
                .and_then(|(p, q)| greater([m, q, fq], [p, fp, scale]))
                .unwrap_or_else(|| {
                    let (m, scale) = difference.magnitude();
                    let left = m.mul(&bound.q).mul(&Big::from_u128(fq));
                    left > bound.p.mul(&Big::from_u128(fp)).mul(&scale)
                });
            if beyond {
                return false;
            }
        }
        true
    }

    fn motion_changes(&self, sa: &State, sb: &State, b: &DiffBlock) -> Vec<MotionChange> {
        let mut out = Vec::new();
        let (ma, mb) = (modes(&sa.modal), modes(&sb.modal));
        let (ra, rb) = (modes(&sa.reset), modes(&sb.reset));
        for i in 0..MODES.len() {
            // two controls, each in its own reset state, are no difference; nor is the motion
            // mode one control ends at G80 and the other keeps (LinuxCNC has none at its reset
            // and after G80, a Fanuc keeps G00): the two differ only where a block moves by it,
            // which the converter refuses and the target's checker reports (TG411)
            let no_motion = |m: Mode| m == Mode::Int(None);
            let g80 = i == 0
                && no_motion(ra[0]) != no_motion(rb[0])
                && no_motion(ma[0]) != no_motion(mb[0]);
            if ma[i] != mb[i] && !(ma[i] == ra[i] && mb[i] == rb[i]) && !g80 {
                out.push(MotionChange {
                    what: MODES[i].into(),
                    a: ma[i].text(),
                    b: mb[i].text(),
                    difference: None,
                });
            }
        }
        let mut letters: Vec<u8> = vec![b'F', b'S'];
        let mut axes: Vec<u8> = AXES
            .iter()
            .copied()
            .filter(|&l| sa.modal.axis(l).is_some() || sb.modal.axis(l).is_some())
            .collect();
        axes.sort_unstable();
        letters.extend(axes);
        for letter in letters {
            let (va, vb) = (state_value(sa, letter), state_value(sb, letter));
            if va == vb || self.state_within(va, vb, b, letter, sb) {
                continue;
            }
            let what = match letter {
                b'F' => "feed".to_string(),
                b'S' => "speed".to_string(),
                _ => format!("position {}", letter as char),
            };
            let unit = state_unit(letter, sb);
            let text = |v: Option<Dec>| match v {
                Some(v) => v.plain() + unit,
                None => "none".into(),
            };
            let difference = match (va, vb) {
                (Some(x), Some(y)) => sub(y, x),
                _ => None,
            };
            out.push(MotionChange {
                what,
                a: text(va),
                b: text(vb),
                difference,
            });
        }
        out
    }

    fn state_within(
        &self,
        va: Option<Dec>,
        vb: Option<Dec>,
        b: &DiffBlock,
        letter: u8,
        sb: &State,
    ) -> bool {
        let (Some(va), Some(vb)) = (va, vb) else {
            return false;
        };
        // the block's own word, where it has one and it sets that value, knows its format
        // (not a dwell's X, a time: G04 X1 left the position X of the block before, compared
        // by the dwell's step of 0.001)
        let own = b.words.iter().find(|w| {
            w.key == [letter]
                && w.value.is_some()
                && matches!(w.kind, Kind::Length | Kind::Feed | Kind::Speed)
        });
        let (step, factor) = match own {
            Some(w) => (w.step, w.factor),
            None => {
                let factor = sb.factors[slot(letter)].unwrap_or(Factor::One);
                let step = self
                    .options
                    .steps
                    .iter()
                    .find(|(l, u, _)| *l == letter && *u == sb.modal.units)
                    .map_or(Dec::from_int(1), |(_, _, s)| *s);
                match factor.times(step) {
                    Some(s) => (s, factor),
                    None => return false,
                }
            }
        };
        let word = View {
            kind: Kind::Number,
            value: vb,
            factor,
            step,
        };
        match sub(vb, va) {
            Some(d) => self.within(d, &word, letter),
            None => false,
        }
    }
}

/// A block as the pairing holds it (the Python side holds its own object beside it).
pub trait Held {
    fn block(&self) -> &DiffBlock;
}

/// Where the blocks of one program come from: the next, None at its end.
pub type Pull<'a, B, E> = &'a mut dyn FnMut() -> Result<Option<B>, E>;

/// A pair that is not the same: `(a, None)` only in A (removed), `(None, b)` only in B
/// (added), `(a, b)` changed.
pub type Pair<B> = (Option<B>, Option<B>);

/// Blocks paired by position, an added or removed block told from a changed one by looking
/// ahead `window` blocks on each side: memory is that window, whatever the programs. The
/// pairs that are the same are counted, not handed over (the common case of a verification).
pub struct Aligner<B> {
    window: usize,
    qa: VecDeque<B>,
    qb: VecDeque<B>,
    pending: VecDeque<Pair<B>>,
    /// One side ran out: the rest of A, then the rest of B, is unpaired.
    tail: bool,
}

fn fill<B, E>(queue: &mut VecDeque<B>, pull: Pull<'_, B, E>, size: usize) -> Result<(), E> {
    while queue.len() < size {
        match pull()? {
            Some(block) => queue.push_back(block),
            None => break,
        }
    }
    Ok(())
}

impl<B: Held> Aligner<B> {
    pub fn new(window: usize) -> Aligner<B> {
        Aligner {
            window: window.max(2),
            qa: VecDeque::new(),
            qb: VecDeque::new(),
            pending: VecDeque::new(),
            tail: false,
        }
    }

    /// How many pairs were the same, and the next pair that is not (None: the end). Each
    /// pair handed over is the caller's to compare (committing) or to take as unpaired
    /// before the next call: the blocks after are compared after it.
    pub fn next<E>(
        &mut self,
        c: &mut Comparer,
        pull_a: Pull<'_, B, E>,
        pull_b: Pull<'_, B, E>,
    ) -> Result<(usize, Option<Pair<B>>), E> {
        let mut same = 0;
        loop {
            if let Some(pair) = self.pending.pop_front() {
                return Ok((same, Some(pair)));
            }
            if self.tail {
                if let Some(a) = self.qa.pop_front() {
                    return Ok((same, Some((Some(a), None))));
                }
                if let Some(a) = pull_a()? {
                    return Ok((same, Some((Some(a), None))));
                }
                if let Some(b) = self.qb.pop_front() {
                    return Ok((same, Some((None, Some(b)))));
                }
                return Ok((same, pull_b()?.map(|b| (None, Some(b)))));
            }
            fill(&mut self.qa, pull_a, self.window)?;
            fill(&mut self.qb, pull_b, self.window)?;
            let (Some(a), Some(b)) = (self.qa.front(), self.qb.front()) else {
                self.tail = true;
                continue;
            };
            if c.pair(a.block(), b.block()) {
                // the common case: compared once
                c.misses = 0;
                self.qa.pop_front();
                self.qb.pop_front();
                same += 1;
                continue;
            }
            if !self.next_same(c) && c.misses < self.window {
                let removed = resync(c, &self.qa, &self.qb, false);
                let added = resync(c, &self.qb, &self.qa, true);
                if let Some(r) = removed.filter(|&r| added.is_none_or(|a| r <= a)) {
                    for _ in 0..r {
                        self.pending.push_back((self.qa.pop_front(), None));
                    }
                    continue;
                }
                if let Some(n) = added {
                    for _ in 0..n {
                        self.pending.push_back((None, self.qb.pop_front()));
                    }
                    continue;
                }
                c.misses += 1;
            }
            return Ok((same, Some((self.qa.pop_front(), self.qb.pop_front()))));
        }
    }

    /// Whether the blocks after the heads pair again (the heads are then one change).
    fn next_same(&self, c: &mut Comparer) -> bool {
        if self.qa.len() < 2 || self.qb.len() < 2 {
            return self.qa.len() == self.qb.len();
        }
        c.same(self.qa[1].block(), self.qb[1].block())
    }
}

/// The numbered block a block belongs to, `(run, number, repeat)`: an unnumbered block
/// belongs to the numbered block before it; a number lower than the one before starts the
/// next run, and the same number again is its next repeat, so keys only grow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Key {
    run: usize,
    number: Dec,
    repeat: usize,
}

/// One program's blocks as pairing by number reads them: each with its key, one block read
/// ahead (the first of the next group).
struct Keyed<B> {
    key: Key,
    head: Option<(Key, B)>,
    done: bool,
}

impl<B: Held> Keyed<B> {
    fn new() -> Keyed<B> {
        Keyed {
            key: Key {
                run: 0,
                number: Dec::from_int(-1),
                repeat: 0,
            },
            head: None,
            done: false,
        }
    }

    /// The key of the next block, None at the end of the program.
    fn peek<E>(&mut self, pull: Pull<'_, B, E>) -> Result<Option<Key>, E> {
        if self.head.is_none() && !self.done {
            match pull()? {
                None => self.done = true,
                Some(block) => {
                    if let Some(number) = block.block().number {
                        let k = &mut self.key;
                        match number.cmp(&k.number) {
                            Ordering::Less => (k.run, k.repeat) = (k.run + 1, 0),
                            Ordering::Equal => k.repeat += 1,
                            Ordering::Greater => k.repeat = 0,
                        }
                        k.number = number;
                    }
                    self.head = Some((self.key, block));
                }
            }
        }
        Ok(self.head.as_ref().map(|(key, _)| *key))
    }

    /// The next block if it belongs to `key`'s group.
    fn take<E>(&mut self, key: Key, pull: Pull<'_, B, E>) -> Result<Option<B>, E> {
        if self.peek(pull)? == Some(key) {
            Ok(self.head.take().map(|(_, block)| block))
        } else {
            Ok(None)
        }
    }
}

/// The group being handed over: both programs' blocks of one key, aligned by position, or
/// one program's, unpaired.
enum Group<B> {
    Between,
    Both(Key, Aligner<B>),
    OnlyA(Key),
    OnlyB(Key),
}

/// Blocks merged in sequence-number order, each numbered block with the unnumbered blocks
/// after it (`tapegate diff --pair number`): the groups of one key in both programs are
/// aligned by position (an [`Aligner`] each, its search for a resync starting afresh), a key
/// in one program only is unpaired. Memory is one group's window, whatever the programs.
pub struct NumberAligner<B> {
    window: usize,
    a: Keyed<B>,
    b: Keyed<B>,
    group: Group<B>,
}

impl<B: Held> NumberAligner<B> {
    pub fn new(window: usize) -> NumberAligner<B> {
        NumberAligner {
            window,
            a: Keyed::new(),
            b: Keyed::new(),
            group: Group::Between,
        }
    }

    /// As [`Aligner::next`]: how many pairs were the same, and the next pair that is not
    /// (None: the end).
    pub fn next<E>(
        &mut self,
        c: &mut Comparer,
        pull_a: Pull<'_, B, E>,
        pull_b: Pull<'_, B, E>,
    ) -> Result<(usize, Option<Pair<B>>), E> {
        let mut same = 0;
        loop {
            match &mut self.group {
                Group::Both(key, aligner) => {
                    let (key, a, b) = (*key, &mut self.a, &mut self.b);
                    let (n, pair) = aligner
                        .next(c, &mut || a.take(key, pull_a), &mut || b.take(key, pull_b))?;
                    same += n;
                    if pair.is_some() {
                        return Ok((same, pair));
                    }
                }
                Group::OnlyA(key) => {
                    if let Some(x) = self.a.take(*key, pull_a)? {
                        return Ok((same, Some((Some(x), None))));
                    }
                }
                Group::OnlyB(key) => {
                    if let Some(y) = self.b.take(*key, pull_b)? {
                        return Ok((same, Some((None, Some(y)))));
                    }
                }
                Group::Between => {}
            }
            self.group = match (self.a.peek(pull_a)?, self.b.peek(pull_b)?) {
                (None, None) => {
                    self.group = Group::Between;
                    return Ok((same, None));
                }
                (Some(ka), Some(kb)) if ka == kb => {
                    c.misses = 0;
                    Group::Both(ka, Aligner::new(self.window))
                }
                (Some(ka), Some(kb)) if ka < kb => Group::OnlyA(ka),
                (Some(ka), None) => Group::OnlyA(ka),
                (_, Some(kb)) => Group::OnlyB(kb),
            };
        }
    }
}

/// How many blocks of `ahead` come before one that pairs with `other`'s head (and the block
/// after it with the next), or None; `flipped`: `ahead` is B.
fn resync<B: Held>(
    c: &mut Comparer,
    ahead: &VecDeque<B>,
    other: &VecDeque<B>,
    flipped: bool,
) -> Option<usize> {
    let mut same = |x: &B, y: &B| {
        if flipped {
            c.same(y.block(), x.block())
        } else {
            c.same(x.block(), y.block())
        }
    };
    (1..ahead.len()).find(|&i| {
        same(&ahead[i], &other[0])
            && (i + 1 >= ahead.len() || other.len() < 2 || same(&ahead[i + 1], &other[1]))
    })
}

/// Whether two blocks have the same addresses in the same order, each once (their words pair
/// by position).
fn same_keys(a: &DiffBlock, b: &DiffBlock) -> bool {
    a.words.len() == b.words.len()
        && a.words.iter().zip(&b.words).all(|(x, y)| x.key == y.key)
        && a.words
            .iter()
            .enumerate()
            .all(|(i, x)| a.words[..i].iter().all(|y| y.key != x.key))
}

/// The words of one address in two blocks, paired: codes (`G90 G01` and `G01 G90`) by value
/// first, then the rest in written order.
fn matched(
    a: &DiffBlock,
    b: &DiffBlock,
    la: &[usize],
    lb: &[usize],
) -> Vec<(Option<usize>, Option<usize>)> {
    if la.len() == 1 && lb.len() == 1 {
        return vec![(Some(la[0]), Some(lb[0]))];
    }
    let mut out = Vec::new();
    let mut rest_b: Vec<usize> = lb.to_vec();
    let mut rest_a = Vec::new();
    for &i in la {
        let wa = &a.words[i];
        if matches!(wa.kind, Kind::Code | Kind::Units) {
            if let Some(j) = rest_b.iter().position(|&j| b.words[j].value == wa.value) {
                out.push((Some(i), Some(rest_b.remove(j))));
                continue;
            }
        }
        rest_a.push(i);
    }
    for k in 0..rest_a.len().max(rest_b.len()) {
        out.push((rest_a.get(k).copied(), rest_b.get(k).copied()));
    }
    out
}

/// The addresses of a block in written order, without its units code (inserted or replaced
/// by a conversion, and a units code under one profile is another code under the other's).
fn order(block: &DiffBlock) -> Vec<&[u8]> {
    let units = [20, 21, 70, 71, 700, 710];
    block
        .words
        .iter()
        .filter(|w| {
            w.kind != Kind::Units
                && !(w.key == b"G" && units.iter().any(|&u| w.value == Some(Dec::from_int(u))))
        })
        .map(|w| w.key.as_slice())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(text: &str) -> Dec {
        Dec::parse(text).unwrap()
    }

    fn comparer(tolerance: (&str, &str), bounds: Option<Vec<(u8, Ratio)>>) -> Comparer {
        Comparer::new(Options {
            tolerance: Ratio::new(
                Big::parse(tolerance.0).unwrap(),
                Big::parse(tolerance.1).unwrap(),
            ),
            bounds,
            word_order: true,
            parameters_address: false,
            unstated_adopt: true,
            same_text: false,
            steps: Vec::new(),
        })
    }

    fn word(step: &str, factor: Factor) -> View {
        View {
            kind: Kind::Length,
            value: d("0"),
            factor,
            step: d(step),
        }
    }

    #[test]
    fn a_dwell_by_a_parameter_in_milliseconds_differs_from_one_in_seconds_in_both_modes() {
        // review 24, finding 2: `G04 P#1` of a FANUC (milliseconds) and `g4 p#1` of LinuxCNC
        // (seconds) were the same in `diff`'s comparison as written (`--verify`'s by address
        // told them apart)
        let param = |token: &[u8], milliseconds: bool| {
            let mut w = crate::ncread::ReadWord::text(b"P", token);
            w.parameter = true;
            w.milliseconds = milliseconds;
            w
        };
        for address in [false, true] {
            let mut c = comparer(("0", "1"), None);
            c.options.parameters_address = address;
            let mut carry = [None; 9];
            let mut kind = |a: &crate::ncread::ReadWord, b: &crate::ncread::ReadWord| {
                c.word(a, 0, b, 0, &mut carry).map(|change| change.kind)
            };
            let (fanuc, lcnc) = (param(b"P#1", true), param(b"p#1", false));
            assert_eq!(kind(&fanuc, &lcnc), Some(ChangeKind::Changed), "{address}");
            assert_eq!(kind(&lcnc, &fanuc), Some(ChangeKind::Changed), "{address}");
            // one time unit on both sides: the same text is the same, another one differs
            // as written (by address alone: the same)
            assert_eq!(kind(&fanuc, &param(b"P#1", true)), None, "{address}");
            let other = kind(&fanuc, &param(b"P#2", true));
            let expected = (!address).then_some(ChangeKind::Changed);
            assert_eq!(other, expected, "{address}");
        }
    }

    struct T(DiffBlock);

    impl Held for T {
        fn block(&self) -> &DiffBlock {
            &self.0
        }
    }

    /// Blocks of text (`N10 X1`: numbered 10), compared as their texts.
    fn blocks(texts: &[&str]) -> VecDeque<T> {
        texts
            .iter()
            .enumerate()
            .map(|(i, t)| {
                let mut block = crate::ncread::Reader::bad_block(i + 1, t.as_bytes());
                block.number = t
                    .strip_prefix('N')
                    .map(|rest| d(rest.split(' ').next().unwrap()));
                T(block)
            })
            .collect()
    }

    /// The pairs an aligner's `step` hands over for two programs of text blocks, as (same
    /// pairs before, a, b) by their texts, then (same pairs before, "", "") at the end.
    fn run(
        a: &[&str],
        b: &[&str],
        mut step: impl FnMut(
            &mut Comparer,
            Pull<'_, T, ()>,
            Pull<'_, T, ()>,
        ) -> Result<(usize, Option<Pair<T>>), ()>,
    ) -> Vec<(usize, String, String)> {
        let mut c = comparer(("0", "1"), None);
        let (mut qa, mut qb) = (blocks(a), blocks(b));
        let mut pull_a = || Ok::<_, ()>(qa.pop_front());
        let mut pull_b = || Ok::<_, ()>(qb.pop_front());
        let text = |x: &Option<T>| {
            x.as_ref().map_or("-".to_string(), |t| {
                String::from_utf8_lossy(&t.0.words[0].token).into()
            })
        };
        let mut out = Vec::new();
        loop {
            let (same, pair) = step(&mut c, &mut pull_a, &mut pull_b).unwrap();
            match pair {
                Some((x, y)) => out.push((same, text(&x), text(&y))),
                None => {
                    out.push((same, String::new(), String::new()));
                    return out;
                }
            }
        }
    }

    /// The pairs of two programs of text blocks, paired by position.
    fn aligned(a: &[&str], b: &[&str], window: usize) -> Vec<(usize, String, String)> {
        let mut aligner = Aligner::new(window);
        run(a, b, |c, pa, pb| aligner.next(c, pa, pb))
    }

    /// The pairs of two numbered programs of text blocks, paired by number.
    fn by_number(a: &[&str], b: &[&str]) -> Vec<(usize, String, String)> {
        let mut aligner = NumberAligner::new(4);
        run(a, b, |c, pa, pb| aligner.next(c, pa, pb))
    }

    fn pairs(v: &[(usize, &str, &str)]) -> Vec<(usize, String, String)> {
        v.iter()
            .map(|&(n, a, b)| (n, a.to_string(), b.to_string()))
            .collect()
    }

    #[test]
    fn by_number_a_number_in_one_program_only_is_unpaired_in_number_order() {
        let a = ["O1", "N10 X1", "Y1", "N20 X2", "N30 X3", "N10 X9"];
        let b = ["O1", "N10 X1", "Y1", "N25 X5", "N30 X3", "N10 X9"];
        assert_eq!(
            by_number(&a, &b),
            pairs(&[(3, "N20 X2", "-"), (0, "-", "N25 X5"), (2, "", "")])
        );
        // a lower number starts a new run: the second N10 pairs with the other's second
        let b = ["O1", "N10 X1", "Y1", "N20 X2", "N30 X3", "N10 X8"];
        assert_eq!(
            by_number(&a, &b),
            pairs(&[(5, "N10 X9", "N10 X8"), (0, "", "")])
        );
    }

    #[test]
    fn by_number_the_blocks_of_one_number_are_aligned_by_position() {
        // an unnumbered block added inside N10's group, a changed one in N20's
        let a = ["N10 X1", "Y1", "Z1", "N20 X2", "Y2"];
        let b = ["N10 X1", "Y1", "Q5", "Z1", "N20 X2", "Y3"];
        assert_eq!(
            by_number(&a, &b),
            pairs(&[(2, "-", "Q5"), (2, "Y2", "Y3"), (0, "", "")])
        );
        // a group that runs out on one side: the rest of the other's is unpaired
        let a = ["N10 X1", "Y1", "Z1", "N20 X2"];
        let b = ["N10 X1", "N20 X2"];
        assert_eq!(
            by_number(&a, &b),
            pairs(&[(1, "Y1", "-"), (0, "Z1", "-"), (1, "", "")])
        );
        // a group whose blocks all differ spends the search for a resync; the next group
        // searches afresh and finds the block added in it
        let a = ["N10 X1", "A1", "B1", "C1", "D1", "N20 X1", "Y1", "Y2"];
        let b = ["N10 X2", "A2", "B2", "C2", "D2", "N20 X2", "Q5", "Y1", "Y2"];
        let mut want = vec![(0, "N10 X1", "N10 X2")];
        want.extend(
            [("A1", "A2"), ("B1", "B2"), ("C1", "C2"), ("D1", "D2")].map(|(x, y)| (0, x, y)),
        );
        want.extend([(0, "N20 X1", "N20 X2"), (0, "-", "Q5"), (2, "", "")]);
        assert_eq!(by_number(&a, &b), pairs(&want));
        assert_eq!(by_number(&[], &[]), pairs(&[(0, "", "")]));
        assert_eq!(
            by_number(&["N5 X1"], &[]),
            pairs(&[(0, "N5 X1", "-"), (0, "", "")])
        );
    }

    #[test]
    fn an_added_a_removed_and_a_changed_block_are_told_apart() {
        let s = |v: &[(usize, &str, &str)]| -> Vec<(usize, String, String)> {
            v.iter()
                .map(|(n, a, b)| (*n, a.to_string(), b.to_string()))
                .collect()
        };
        let found = aligned(&["A", "B", "C", "D"], &["A", "X", "B", "C", "D"], 64);
        assert_eq!(found, s(&[(1, "-", "X"), (3, "", "")]));
        let found = aligned(&["A", "B", "C", "D"], &["A", "C", "D"], 64);
        assert_eq!(found, s(&[(1, "B", "-"), (2, "", "")]));
        let found = aligned(&["A", "B", "C"], &["A", "Y", "C"], 64);
        assert_eq!(found, s(&[(1, "B", "Y"), (1, "", "")]));
        let found = aligned(&["A", "B"], &["A", "B", "E", "F"], 2);
        assert_eq!(found, s(&[(2, "-", "E"), (0, "-", "F"), (0, "", "")]));
    }

    #[test]
    fn a_statement_s_blanks_are_no_difference_but_to_the_proof() {
        assert_eq!(unblanked(b"IF R1 == R2 GOTOF  L"), b"IFR1==R2GOTOFL");
        assert_eq!(unblanked(b"MSG(\"a b\") "), b"MSG(\"a b\")");
    }

    #[test]
    fn half_a_step_is_accepted_and_beyond_is_not() {
        let c = comparer(("1", "2"), None);
        let x = word("0.0254", Factor::Inch); // 0.001 in
        assert!(c.within(d("0.0127"), &x, b'X'));
        assert!(c.within(d("-0.0127"), &x, b'X'));
        assert!(!c.within(d("0.01270000000000000000000000001"), &x, b'X'));
        assert!(c.within(d("0"), &x, b'X'));
        let exact = comparer(("0", "1"), None);
        assert!(!exact.within(d("1E-30"), &x, b'X'));
    }

    #[test]
    fn bounds_are_in_bs_units_times_the_factor() {
        let bound = Ratio::new(Big::from_u128(1), Big::from_u128(10000)); // 0.0001 in
        let c = comparer(("1", "2"), Some(vec![(b'X', bound)]));
        let x = word("0.0254", Factor::Inch);
        assert!(c.within(d("0.00254"), &x, b'X')); // 0.0001 in = 0.00254 mm
        assert!(!c.within(d("0.002541"), &x, b'X'));
        assert!(!c.within(d("0.001"), &x, b'Y')); // an address not named accepts none
    }
}
