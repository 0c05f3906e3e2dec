//! The meanings a block's codes give its words ([`crate::meaning::Meanings`]), kept by the
//! block's shape.
//!
//! The meanings are worked out from the block's G and M codes, the cycle in force, which
//! letters the block writes and which of them with a point, and an L word's number (LinuxCNC
//! `G10 L1`/`L2`): [`crate::convert::code_meanings_of`] reads nothing else. A CAM program
//! writes a few dozen shapes over and over (`G1 X Y`, `G2 X Y I J`, each with and without
//! points): a block of a shape met before has the meanings worked out then, where the tables
//! of both readers (the converter's cycle table and [`crate::meaning::block`]) cost 100 to 400
//! instructions a block on a program whose every block writes its G code (a Fusion 360
//! post's) and more on LinuxCNC. A debug build (the tests') works every kept block's out
//! afresh too and holds the two equal (`Checker::code_meanings`).

use crate::meaning::Meanings;
use crate::word::Word;

/// The G, M and L words a key holds at most, and the longest number of one (`68.2`, `100`),
/// each word packed in a `u64` with its letter: a block with more, or a longer number, is
/// worked out afresh and not kept.
const CODES: usize = 4;
const DIGITS: usize = 7;
/// The places for shapes ([`Shapes`]): a power of two. A few dozen shapes in 64 places
/// share some (slot_assembly_12's 44 worked 1,654 of 20,480 blocks' meanings out afresh);
/// 256 places (24 KB) share few.
const KEPT: usize = 256;

/// What [`crate::convert::code_meanings_of`] reads of a block, and the cycle in force.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct Shape {
    /// The letters A-Z the block writes (bit `letter - b'A'`), and those written with a point.
    letters: u32,
    pointed: u32,
    /// The canned cycle in force that a block without a G code repeats (None on a lathe).
    cycle: Option<i64>,
    /// The G, M and L words in their order, each its letter in the low byte and its number's
    /// bytes above it (none of them 0: digits and a point), 0 past the last.
    codes: [u64; CODES],
}

impl Shape {
    /// The shape of a block's `words` under `cycle`, or None where it holds more G, M and L
    /// words than a key holds, or a longer number.
    pub(super) fn of(words: &[Word<'_>], cycle: Option<i64>) -> Option<Shape> {
        let mut shape = Shape {
            cycle,
            ..Shape::default()
        };
        let mut n = 0;
        for w in words {
            let letter = w.letter.to_ascii_uppercase();
            if !letter.is_ascii_uppercase() {
                continue;
            }
            let bit = 1 << (letter - b'A');
            shape.letters |= bit;
            // (a word's number holds a point exactly where `point` says: Word::new, Word::of)
            if w.point {
                shape.pointed |= bit;
            }
            if matches!(letter, b'G' | b'M' | b'L') {
                if n == CODES || w.number.len() > DIGITS {
                    return None;
                }
                // (a 0 byte, which would end the packed number early, found in the same pass)
                let (mut packed, mut nul) = (0u64, false);
                for &c in w.number.iter().rev() {
                    packed = packed << 8 | u64::from(c);
                    nul |= c == 0;
                }
                if nul {
                    return None;
                }
                shape.codes[n] = packed << 8 | u64::from(w.letter);
                n += 1;
            }
        }
        Some(shape)
    }
}

impl Shape {
    /// The place of the shape in [`Shapes`]: each field mixed in by a multiply (a
    /// multiplicative, Fibonacci hash), the top bits of the result. (Fields XORed together
    /// before one multiply cancelled: `G2 X. Y. I. J` and `G3 X. Y. I J.` differ by the same
    /// bit in their codes and in their pointed letters, and took one place, PaulSeelig 1001's
    /// arcs throwing each other out in one block of seven.)
    fn slot(&self) -> usize {
        const K: u64 = 0x9e37_79b9_7f4a_7c15;
        let cycle = self.cycle.map_or(u64::MAX, |c| c as u64);
        let fields = [
            u64::from(self.letters) << 32 | u64::from(self.pointed),
            self.codes[0],
            self.codes[1],
            self.codes[2],
            self.codes[3],
            cycle,
        ];
        let mixed = fields
            .iter()
            .fold(0u64, |h, &f| (h.rotate_left(29) ^ f).wrapping_mul(K));
        (mixed >> (64 - KEPT.trailing_zeros())) as usize
    }
}

/// The meanings of the shapes met, each in the place its hash gives it ([`Shape::slot`]), a
/// later shape of the same place taking it over: a CAM program's few dozen shapes
/// (`G1 X Y`, `G2 X Y I J`, each with and without points) mostly keep a place of their own.
#[derive(Clone, Debug)]
pub(super) struct Shapes {
    kept: Box<[(Shape, Meanings); KEPT]>,
    /// The places that hold a shape (bit `slot % 64` of word `slot / 64`).
    filled: [u64; KEPT / 64],
    /// Nothing is kept: every block's meanings are worked out afresh
    /// ([`super::Checker::keep_verdicts`]).
    pub(super) afresh: bool,
    /// The blocks whose shape was kept (the tests').
    #[cfg(test)]
    pub(super) hits: std::cell::Cell<usize>,
}

impl Default for Shapes {
    fn default() -> Shapes {
        Shapes {
            kept: Box::new([(Shape::default(), Meanings::default()); KEPT]),
            filled: [0; KEPT / 64],
            afresh: false,
            #[cfg(test)]
            hits: std::cell::Cell::new(0),
        }
    }
}

impl Shapes {
    pub(super) fn get(&self, shape: &Shape) -> Option<Meanings> {
        let slot = shape.slot();
        let (kept, meanings) = &self.kept[slot];
        let filled = self.filled[slot / 64] & 1 << (slot % 64) != 0;
        let found = (filled && kept == shape).then_some(*meanings);
        #[cfg(test)]
        self.hits
            .set(self.hits.get() + usize::from(found.is_some()));
        found
    }

    pub(super) fn keep(&mut self, shape: Shape, meanings: Meanings) {
        if self.afresh {
            return;
        }
        let slot = shape.slot();
        self.kept[slot] = (shape, meanings);
        self.filled[slot / 64] |= 1 << (slot % 64);
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{dialect, fanuc_lathe, of_family, run};
    use super::*;
    use crate::lex::Family;

    fn words(line: &'static str) -> Vec<Word<'static>> {
        line.split(' ')
            .map(|t| Word::new(t.as_bytes(), 1))
            .collect()
    }

    /// A CAM program's arcs, each way with the other centre word pointed (PaulSeelig 1001's
    /// `G2 X Y Z I J.` and `G3 X Y Z I. J`), take places of their own: with the fields
    /// XORed before one multiply they took one and threw each other out; and every place
    /// is one of the table's.
    #[test]
    fn shapes_that_differ_by_one_bit_in_two_fields_take_two_places() {
        let of = |line: &'static str| Shape::of(&words(line), None).unwrap();
        let pairs = [
            ("G2 X1. Y1. Z1. I1. J1", "G3 X1. Y1. Z1. I1 J1."),
            ("G2 X1. Y1. Z1. I1 J1.", "G3 X1. Y1. Z1. I1. J1"),
            ("G2 X1. Y1. I1. J1", "G3 X1. Y1. I1 J1."),
        ];
        for (a, b) in pairs {
            assert_ne!(of(a), of(b));
            assert_ne!(of(a).slot(), of(b).slot(), "{a} / {b}");
            assert!(of(a).slot() < KEPT && of(b).slot() < KEPT);
        }
    }

    /// Blocks that differ only in what the tables read have shapes of their own; blocks that
    /// differ elsewhere (the axis values) share one.
    #[test]
    fn a_shape_holds_what_the_tables_read() {
        let shape = |line, cycle| Shape::of(&words(line), cycle).unwrap();
        let same = [
            ("G1 X1. Y2.", "G1 X-3.5 Y4.25"),
            ("G83 X1. Y2. Z-3. R1. Q1. K2", "G83 X9. Y8. Z-7. R6. Q5. K4"),
            ("X1. Y2.", "X3. Y4."),
        ];
        for (a, b) in same {
            assert_eq!(shape(a, None), shape(b, None), "{a} / {b}");
        }
        let other = [
            ("G1 X1. Y2.", "G2 X1. Y2."),
            ("G1 X1. Y2.", "G01 X1. Y2."),
            ("G1 X1. Y2.", "G1 X1. Y2. Z3."),
            ("G83 X1. Q1. K2", "G83 X1. Q1. K2."),
            ("G10 L1 P1 R2.", "G10 L2 P1 R2."),
            ("G68.2 X1.", "G68.3 X1."),
            ("M98 P100", "M97 P100"),
            ("G1 M3", "M3 G1"),
        ];
        for (a, b) in other {
            assert_ne!(shape(a, None), shape(b, None), "{a} / {b}");
        }
        assert_ne!(shape("X1. Y2.", Some(81)), shape("X1. Y2.", None));
        assert_ne!(shape("X1. Y2.", Some(81)), shape("X1. Y2.", Some(83)));
        // more codes, or a longer number, than a key holds: no shape
        assert!(Shape::of(&words("G1 G17 G90 G94 G54"), None).is_none());
        assert!(Shape::of(&words("G1 G17 G90 M3"), None).is_some());
        assert!(Shape::of(&words("M12345678"), None).is_none());
        assert!(Shape::of(&words("M1234567"), None).is_some());
    }

    #[test]
    fn a_shape_kept_is_found_and_a_shape_of_its_place_takes_it_over() {
        let mut shapes = Shapes::default();
        let of = |line| Shape::of(&words(line), None).unwrap();
        let mut meanings = Meanings::default();
        meanings.data = true;
        assert_eq!(shapes.get(&of("G0 X1.")), None);
        shapes.keep(of("G0 X1."), meanings);
        assert_eq!(shapes.get(&of("G0 X5.")), Some(meanings));
        assert_eq!(shapes.get(&of("G0 X5")), None);
        // two shapes of one place: the later is kept, the earlier is not found
        let lines = [
            "G1 X1.",
            "G2 X1. I1.",
            "G3 X1. J1.",
            "G1 Y1.",
            "G1 Z1.",
            "G0 Y1.",
        ];
        let mut others = (0..200).map(|n| format!("G{n} X1. Y1."));
        let (a, b) = loop {
            let text = others.next().expect("two shapes of one place among 200");
            let first = Shape::of(&words(Box::leak(text.into_boxed_str())), None).unwrap();
            let found = lines
                .iter()
                .find(|l| of(l).slot() == first.slot() && of(l) != first);
            if let Some(line) = found {
                break (of(line), first);
            }
        };
        shapes.keep(a, meanings);
        assert_eq!(shapes.get(&a), Some(meanings));
        shapes.keep(b, Meanings::default());
        assert_eq!(shapes.get(&a), None);
        assert_eq!(shapes.get(&b), Some(Meanings::default()));
    }

    /// The checker's meanings, kept by shape, are those worked out afresh for every block
    /// (a debug build, the tests', holds each block's to it in `Checker::code_meanings`): on
    /// programs whose blocks come back to shapes met before, with what the tables read
    /// changed between them (the cycle in force, an L word, a K with a point), on a mill and a
    /// lathe of the families whose tables give meanings, and on a SINUMERIK, whose have none.
    #[test]
    fn kept_meanings_are_the_meanings_worked_out_afresh() {
        let macro_b = "%\nO1000\nG90 G17 G21\nG83 X1. Y2. Z-3. R1. Q1. K2 F100.\nX2. Y3.\n\
                       X4. Y5.\nG83 X1. Y2. Z-3. R1. Q1. K2. F100.\nX2. Y3.\nG80\n\
                       G68 X1. Y1. R45.\nG1 X1.\nG69\nG1 X2.\nG2 X3. Y4. I1. J1.\nG1 X2.\n\
                       G2 X3. Y4. I1. J1.\nG32 Z-5. F1. Q90000\nG1 X2.\nG32 Z-6. F1. Q0\n\
                       M98 P100 L2\nM30\n%\n";
        let linuxcnc = "G21 G90\nG10 L1 P1 Q1 R2. I3. J4.\nG10 L2 P1 R2.\n\
                        G10 L1 P1 Q1 R2. I3. J4.\nG64 P0.01 Q0.02\nG1 X1. F100.\n\
                        G64 P0.01 Q0.02\nM100 P1. Q2.\nG1 X2.\nM100 P1. Q2.\nM2\n";
        // (G1 and G2 beside G90: a block whose codes are G00-G03 alone has no meaning
        // worked out, Checker::code_meanings)
        let sinumerik = "G90 G17 G71\nG90 G1 X1. Y2. F100.\nG90 G2 X3. Y4. I1. J1.\n\
                         G90 G1 X1. Y2.\nG90 G1 X3. Y5.\nM30\n";
        let cases = [
            (of_family(Family::MacroB), macro_b),
            (fanuc_lathe(), macro_b),
            (of_family(Family::LinuxCnc), linuxcnc),
            (of_family(Family::Sinumerik), sinumerik),
        ];
        for (config, text) in cases {
            let family = config.family;
            let (checker, _) = run(config, &dialect(family), text);
            assert!(
                checker.shapes.hits.get() > 0,
                "{family:?}: no block met a kept shape"
            );
        }
    }
}
