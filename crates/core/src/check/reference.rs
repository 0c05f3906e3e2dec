//! TG418: a lathe's reference position return through the part zero.
//!
//! `G28 X_ Z_` goes to its words' point first (the intermediate point), at rapid, and from
//! there to the reference position; on a Fanuc or Haas lathe (G code system A) X and Z are
//! absolute, so `G28 X0 Z0` rapids to the work zero -- the spindle's centre line at the part's
//! face -- before it goes home (Haas: "G28 G90 X0 Y0 Z0 moves to X0 Y0 Z0 in the current work
//! coordinate system then to machine zero", G28; FANUC 0i-TF operator's manual, "Automatic
//! reference position return": "G28 IP_ ;  IP_: command specifying the intermediate position
//! (absolute/incremental)"). From where the tool stands the return is `G28 U0 W0`, which the
//! lathe programs use. A warning at the word: the point may be clear on a given machine.

use super::{Checker, Facts};
use crate::rules::Rule;

impl Checker {
    /// TG418 on a Fanuc or Haas lathe's `G28` whose X or Z is 0.
    pub(super) fn reference_return(&mut self, line: usize, facts: &Facts<'_>) {
        if !self.config.modal.fanuc_lathe || !facts.has(28) {
            return;
        }
        let zero = |letter: u8| self.values.get(letter).is_some_and(|v| v.is_zero());
        let Some(letter) = [b'X', b'Z'].into_iter().find(|&l| zero(l)) else {
            return;
        };
        let message = format!(
            "G28 {l}0: the intermediate point lies at the work zero in {l} (X and Z are \
             absolute: the part's centre line or its face), where the tool rapids before it \
             returns to the reference position; G28 U0 W0 returns from where it stands",
            l = letter as char
        );
        self.report(Rule::ReturnThroughZero, message, line, facts.col(letter));
    }
}
