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
use crate::modal::{ModalSettings, ModalState, Units};

/// The backplot's facts, gathered block by block while the path is recorded.
#[derive(Debug, Clone, Default)]
pub struct Drawn {
    /// The units after each block that names a units code (metric, inch), as a set.
    pub units: [bool; 2],
    /// By line, the axes (bit 0 X, 1 Y, 2 Z) a block names whose position before it is
    /// unknown.
    pub unknown: Vec<(usize, u8)>,
    /// The lines of the blocks that move to or through the reference point, or in machine
    /// coordinates.
    pub machine: Vec<usize>,
    /// X Y Z set absolutely since the start (read only until all three are).
    known: u8,
    /// X Y Z at the reference point since a G28 G30 G53, not set again since.
    homed: u8,
}

/// What a block's words say for [`Drawn`], read before the block is applied.
pub(super) struct Named {
    units_code: bool,
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
    pub(super) fn of(words: &[Word<'_>], settings: &ModalSettings) -> Named {
        let mut named = Named {
            units_code: false,
            reference: false,
            axes: 0,
        };
        for w in words {
            if let Some(g) = plain_g(w) {
                named.units_code |= g == settings.inch || g == settings.metric;
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

impl Drawn {
    /// One block, its words read before it and the state after it.
    pub(super) fn note(&mut self, line: usize, named: &Named, after: &ModalState) {
        let locating =
            named.axes != 0 && (self.known != 0b111 || named.reference || self.homed != 0);
        if named.units_code {
            self.units[usize::from(after.units == Units::Inch)] = true;
        }
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
            self.unknown.push((line, missing));
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
    pub(super) fn drawn_block(&mut self, b: &BlockView<'_>) {
        if !self.record_path {
            self.read_block(b);
            return;
        }
        let named = Named::of(b.words, &self.machine.settings);
        self.read_block(b);
        self.drawn.note(b.line, &named, &self.machine.state);
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{dialect, iso_mill, program, run_recording};
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
        // G71 at the start, G70 at the end
        assert_eq!(d.units, [true, true]);
    }

    #[test]
    fn nothing_without_the_path() {
        let text = program("G00 X10. Y10. Z1.");
        let (checker, _) = run_recording(iso_mill(), &dialect(Family::Iso), &text, false);
        assert!(checker.drawn.unknown.is_empty() && checker.drawn.units == [false, false]);
    }
}
