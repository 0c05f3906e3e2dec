//! What the backplot needs beyond the path (no rule of its own): the units the program sets,
//! the blocks that move from a position nobody knows, and those that move to or through the
//! reference point. Gathered in the checker's own pass, so `tapegate plot` reads a program
//! once, through the core.
//!
//! A move from an unknown position is not drawn: an unknown axis reads 0 in the path, and a
//! rapid drawn from 0 would cross the part. The position is unknown for each of X, Y, Z until
//! the program sets it absolutely, and wholly unknown after a reference return (G28, G30, G53:
//! the tool is where the machine left it, in no work position) until the axes it named are set
//! again.

use super::{BlockView, Checker, Word};
use crate::modal::ModalState;

/// The backplot's facts, gathered block by block while the path is recorded.
#[derive(Debug, Clone, Default)]
pub struct Drawn {
    /// The units (metric, inch) of the moves drawn, as a set: a program's reset units where
    /// it names no units code (the next program of a file too), the code's after one.
    pub units: [bool; 2],
    /// By line, the axes (bit 0 X, 1 Y, 2 Z) a block names whose position before it is
    /// unknown.
    pub unknown: Vec<(usize, u8)>,
    /// The lines of the blocks that move to or through the reference point, or in machine
    /// coordinates.
    pub machine: Vec<usize>,
    /// The first [`TRANSFORMS_KEPT`] blocks that shift, rotate, scale or mirror the
    /// coordinates (G52, G92, G92.1, G10, G68, G51, G51.1, G16, Haas G101...): (line, code as
    /// written). The backplot draws the program's coordinates, not these: the picture says so.
    pub transforms: Vec<(usize, String)>,
    /// How many such blocks there are, those past the kept ones too.
    pub transform_count: usize,
    /// By line, the axes (bit 0 X, 1 Y, 2 Z) a move does not name whose position the program
    /// had given and has lost since (a shift, a skip, a call): a view showing one of them
    /// does not draw the move.
    pub adrift: Vec<(usize, u8)>,
    /// X Y Z (bits 0-2) whose position was known at some block of the program: one unknown
    /// again (after a shift, a skip, a jump) leaves the tool where nobody knows.
    pub(super) placed: u8,
    /// X Y Z set absolutely since the start (read only until all three are).
    known: u8,
    /// X Y Z at the reference point since a G28 G30 G53, not set again since.
    homed: u8,
}

/// What a block's words say for [`Drawn`], read before the block is applied.
pub(super) struct Named {
    reference: bool,
    axes: u8,
}

/// A plain G word's number (`G28`, not `G28.1`, `G#1` or `G-1`).
fn plain_g(w: &Word<'_>) -> Option<i64> {
    let digits = w.token.get(1..)?;
    if !matches!(w.token.first(), Some(b'G' | b'g'))
        || digits.is_empty()
        || !digits.iter().all(u8::is_ascii_digit)
    {
        return None;
    }
    std::str::from_utf8(digits).ok()?.parse().ok()
}

impl Named {
    pub(super) fn of(words: &[Word<'_>]) -> Named {
        let mut named = Named {
            reference: false,
            axes: 0,
        };
        for w in words {
            if let Some(g) = plain_g(w) {
                named.reference |= matches!(g, 28 | 30 | 53);
            }
            if let Some(axis) = b"XYZ"
                .iter()
                .position(|&a| a == w.address.to_ascii_uppercase())
            {
                named.axes |= 1 << axis;
            }
        }
        named
    }
}

/// The transforming blocks [`Drawn::transforms`] names (the picture's note names a few).
pub const TRANSFORMS_KEPT: usize = 8;

impl Drawn {
    /// A block that shifts, rotates, scales or mirrors the coordinates by `code`.
    pub(super) fn transform(&mut self, line: usize, code: String) {
        self.transform_count += 1;
        if self.transforms.len() < TRANSFORMS_KEPT {
            self.transforms.push((line, code));
        }
    }

    /// `axes` (bit 0 X, 1 Y, 2 Z) of the move on `line` start where nobody knows (after a
    /// shift or a skip the position is unknown): its start is not drawn.
    pub(super) fn unknown_start(&mut self, line: usize, axes: u8) {
        match self.unknown.last_mut() {
            Some((last, named)) if *last == line => *named |= axes,
            _ => self.unknown.push((line, axes)),
        }
    }

    /// One block, its words read before it and the state after it.
    pub(super) fn note(&mut self, line: usize, named: &Named, after: &ModalState) {
        let locating =
            named.axes != 0 && (self.known != 0b111 || named.reference || self.homed != 0);
        if !locating {
            return;
        }
        if named.reference {
            // to or through the machine's reference point: the end is no work position, and
            // unknown until set again
            self.machine.push(line);
            self.known &= !named.axes;
            self.homed |= named.axes;
            return;
        }
        // an axis at the reference point makes the whole start unknown (drawn at 0 it would
        // be a rapid through the part); an axis never set, only itself
        let missing = if self.homed != 0 {
            0b111
        } else {
            named.axes & !self.known
        };
        if missing != 0 {
            self.unknown_start(line, missing);
        }
        if !after.incremental {
            // incremental from an unknown point is still unknown
            self.known |= named.axes;
            self.homed &= !named.axes;
        }
    }
}

impl Checker {
    /// [`Checker::block`], and the backplot's facts of it where the path is recorded.
    #[inline(always)]
    pub(super) fn drawn_block(&mut self, b: &BlockView<'_>) {
        if !self.record_path {
            self.read_block(b);
            return;
        }
        self.recorded_block(b);
    }

    /// [`Checker::drawn_block`] where the path is recorded, out of line: inlined, its values
    /// made [`Checker::block`] save and restore six registers at every block of a check that
    /// records none (about 16 instructions a block).
    #[inline(never)]
    fn recorded_block(&mut self, b: &BlockView<'_>) {
        let named = Named::of(b.words);
        self.read_block(b);
        self.drawn.note(b.line, &named, &self.machine.state);
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{dialect, iso_mill, of_family, program, run_recording};
    use crate::lex::Family;

    #[test]
    fn the_start_the_reference_return_and_the_units() {
        // iso-mill: G70 inch, G71 metric
        // lines 2-9 (line 1 is the %)
        let text =
            program("G71\nG00 X10. Y10.\nG00 Z5.\nG01 X20. F100.\nG28 Z0\nG00 X30.\nG00 Z2.\nG70");
        let (checker, _) = run_recording(iso_mill(), &dialect(Family::Iso), &text, true);
        let d = &checker.drawn;
        // X Y never set before line 3, Z before line 4; after the G28 Z of line 6 the whole
        // start of lines 7 and 8 is unknown (Z at the reference point until line 8 sets it)
        assert_eq!(
            d.unknown,
            [(3, 0b011), (4, 0b100), (7, 0b111), (8, 0b111)],
            "{d:?}"
        );
        assert_eq!(d.machine, [6]);
        // G71 at the start, G70 at the end with no move after it: the moves are metric
        assert_eq!(d.units, [true, false]);
    }

    #[test]
    fn blocks_that_set_or_shift_draw_nothing_and_are_named() {
        // FANUC: G52, G92, G92.1, G10 L2, G51.1/G50.1 take the axis words as data; rs274
        // runs `g52`/`g92` as SET_G92_OFFSET, no move
        let text = program(
            "G21 G17 G90\nG00 X110. Y0 Z5.\nG01 Z-1. F100.\nG52 X100. Y0\n\
             G02 X20. Y0 I5. J0\nG52 X0 Y0\nG01 X130. Y0\nG92 X30. Y0\nG02 X40. Y0 I5. J0\n\
             G92.1 X0 Y0\nG51.1 X0\nG50.1 X0\nG10 L2 P1 X100. Y0 Z0\nG01 X70.",
        );
        let (checker, _) = run_recording(
            of_family(Family::MacroB),
            &dialect(Family::MacroB),
            &text,
            true,
        );
        let lines: Vec<usize> = checker.path.iter().map(|s| s.line).collect();
        // recorded: the rapid and the arc after G52 and the X130 after G52 X0 from starts
        // nobody knows (drawn as their end points), the plunge, the arc after G92 (its start
        // known: 30), X70 after G10 (at a Y and Z nobody knows: drawn in no view that shows
        // them); no segment of the blocks that set
        assert_eq!(lines, [3, 4, 6, 8, 10, 15], "{:?}", checker.path);
        assert_eq!(
            checker.drawn.unknown,
            [(3, 0b111), (6, 0b011), (8, 0b011), (15, 0b001)]
        );
        assert_eq!(checker.drawn.adrift, [(15, 0b110)]);
        let named: Vec<(usize, &str)> = checker
            .drawn
            .transforms
            .iter()
            .map(|(l, c)| (*l, c.as_str()))
            .collect();
        assert_eq!(
            named,
            [
                (5, "G52"),
                (7, "G52"),
                (9, "G92"),
                (11, "G92.1"),
                (12, "G51.1"),
                (14, "G10")
            ]
        );
        assert_eq!(checker.drawn.transform_count, 6);
    }

    #[test]
    fn nothing_without_the_path() {
        let text = program("G00 X10. Y10. Z1.");
        let (checker, _) = run_recording(iso_mill(), &dialect(Family::Iso), &text, false);
        assert!(checker.drawn.unknown.is_empty() && checker.drawn.units == [false, false]);
    }
}
