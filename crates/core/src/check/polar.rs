//! Forms of a programmed point that the modal state does not read from the block's words
//! alone, followed after the block is applied (`Checker::programmed_forms`): a SINUMERIK's
//! polar moves about its pole (`G111 X Y`, `G1 RP= AP=`), its arc by opening angle and end
//! point (`AR=`), its absolute centre (`I=AC(..)`), the diameter modes of a SINUMERIK
//! (`DIAMON`, `DIAMOF`, `DIAM90`) and of LinuxCNC (`G7`, `G8`), and HEIDENHAIN's G90/G91 for
//! the one coordinate after it. Where a form cannot be followed, the position it sets is
//! unknown, never guessed: no geometry rule runs on it.

use super::{Before, BlockView, Checker};
use crate::decimal::Dec;
use crate::lex::Family;
use crate::modal::{axis_index, bit, polar_axes, AXES};
use crate::statement::{self, Kind};

/// How X is programmed: as a radius (the distance from the turning axis), as a diameter, or
/// (a SINUMERIK's `DIAM90`) as a diameter under G90 and a radius under G91.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum XMode {
    Radius,
    Diameter,
    Diam90,
}

/// A SINUMERIK's pole and the polar radius and angle in force (Programming Manual
/// Fundamentals, "Travel commands with polar coordinates (G0, G1, G2, G3, AP, RP)" and
/// "Polar coordinates, pole definition (G110, G111, G112)"): the pole in the plane's two axes
/// where it is known, and RP and AP as last given about it (each "is stored and must only be
/// written in blocks in which it changes, after changing the pole or when switching the plane",
/// 808D Programming and Operating Manual).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Polar {
    pole: Option<[f64; 2]>,
    /// The plane the pole and the words were given in (0: none yet).
    plane: i64,
    rp: Option<f64>,
    ap: Option<f64>,
}

impl Polar {
    /// A program's start: "If no pole is defined, the origin of the current workpiece
    /// coordinate system will act as the pole" (808D Programming and Operating Manual,
    /// "Polar coordinates, pole definition: G110, G111, G112"; 840D Fundamentals the same).
    /// After a jump or a call the pole is unknown ([`Polar::default`]).
    pub(super) fn at_origin() -> Polar {
        Polar {
            pole: Some([0.0, 0.0]),
            ..Polar::default()
        }
    }
}

/// A number the checker keeps as a position: nine decimals (a nanometre, far below any
/// control's resolution).
fn dec(x: f64) -> Option<Dec> {
    x.is_finite()
        .then(|| Dec::parse(&format!("{x:.9}")))
        .flatten()
        .map(Dec::normalized)
}

/// The point at `radius` and `angle` degrees (from the plane's first axis, counterclockwise)
/// from `from`.
fn polar_point(from: [f64; 2], radius: f64, angle: f64) -> [f64; 2] {
    let a = angle.to_radians();
    [from[0] + radius * a.cos(), from[1] + radius * a.sin()]
}

impl Checker {
    /// What the block's forms make of the position the modal state gave it (`before`: the
    /// state before the block).
    #[inline]
    pub(super) fn programmed_forms(&mut self, b: &BlockView<'_>, before: &Before) {
        self.polar_arc = false;
        self.opening_arc = false;
        // (inlined where it is asked, once a block: the family's test, LinuxCNC's two codes;
        // a SINUMERIK's forms out of line)
        match self.config.family {
            Family::Sinumerik => self.sinumerik_forms(b, before),
            Family::LinuxCnc => {
                // G7 lathe diameter mode, G8 radius mode (LinuxCNC G-code reference, "G7
                // Lathe Diameter Mode", "G8 Lathe Radius Mode"): X is a diameter, I K are not
                // doubled (rs274 -g: `G7 G18 G2 X20 Z-1 I5 K0` from X0 Z-1 turns about X5)
                if self.values.has_g(7) {
                    self.diameter_mode = XMode::Diameter;
                } else if self.values.has_g(8) {
                    self.diameter_mode = XMode::Radius;
                }
            }
            Family::Heidenhain => self.heidenhain_distance(b, before),
            _ => {}
        }
    }

    /// [`Checker::programmed_forms`] on a SINUMERIK.
    #[inline(never)]
    fn sinumerik_forms(&mut self, b: &BlockView<'_>, before: &Before) {
        self.sinumerik_diameter(b, before);
        // (only a centre word, I J K, can be `I=AC(..)` or `I=IC(..)`)
        if self.letters & (bit(b'I') | bit(b'J') | bit(b'K')) != 0 {
            self.sinumerik_centre(b, before);
        }
        self.sinumerik_polar(b, before);
        self.opening_angle(b, before);
    }

    /// The plane's two axes at `end` (a polar move's or an arc's end point), or unknown where
    /// it is not known or not a number the state holds.
    fn place_plane_axes(&mut self, axes: [u8; 2], end: Option<[f64; 2]>) {
        for (k, &axis) in axes.iter().enumerate() {
            let Some(i) = axis_index(axis) else { continue };
            match end.and_then(|p| dec(p[k])) {
                Some(value) => {
                    self.machine.state.position[i] = Some(value);
                    self.machine.state.unknown &= !bit(axis);
                }
                None => self.machine.forget_axis(axis),
            }
        }
    }

    /// Whether the X position the checker keeps is a diameter: a lathe profile's, or a mode
    /// the program selected (under `DIAM90` too: its G91 increments are doubled into it).
    pub(super) fn x_diameter(&self) -> bool {
        self.config.diameter || self.diameter_mode != XMode::Radius
    }

    /// A SINUMERIK's `DIAMON` (X a diameter), `DIAMOF` (a radius) and `DIAM90` (a diameter
    /// under G90, a radius under G91): G group 29, Programming Manual Fundamentals
    /// "Diameter/radius programming for the transverse axis (DIAMON, DIAM90, DIAMOF,
    /// DIAMCYCOF)". The centre words stay radii. Under `DIAM90` the position is kept as a
    /// diameter, so a G91 increment (a radius) moves it twice its value. The axis-wise forms
    /// (`DIAMONA[AX]`, `DIAMCHAN`) name axes by machine data: X's mode is then unknown, and
    /// its position with it.
    fn sinumerik_diameter(&mut self, b: &BlockView<'_>, before: &Before) {
        for &(_, kind, text) in b.statements {
            if !matches!(kind, Kind::Command | Kind::Assignment) {
                continue;
            }
            let end = statement::ident_end(text, 0);
            let name = statement::Upper::of(&text[..end]);
            match name.as_slice() {
                b"DIAMON" => self.diameter_mode = XMode::Diameter,
                b"DIAMOF" => self.diameter_mode = XMode::Radius,
                b"DIAM90" => self.diameter_mode = XMode::Diam90,
                b"DIAMONA" | b"DIAMOFA" | b"DIAM90A" | b"DIAMCHANA" | b"DIAMCHAN" => {
                    self.machine.forget_axis(b'X');
                }
                _ => {}
            }
        }
        let state = &self.machine.state;
        if self.diameter_mode == XMode::Diam90 && state.incremental {
            if let (Some(step), Some(from), Some(i)) =
                (self.values.get(b'X'), before.axis(b'X'), axis_index(b'X'))
            {
                let twice = step.checked_add(step).and_then(|s| from.checked_add(s));
                match twice {
                    Some(x) => self.machine.state.position[i] = Some(x),
                    None => self.machine.forget_axis(b'X'),
                }
            }
        }
    }

    /// A SINUMERIK's centre given absolute, `I=AC(20)` (Programming Manual Fundamentals,
    /// "Circular interpolation with center point and end point (G2/G3, X... Y... Z..., I...
    /// J... K...)": "I=AC(...)" the centre in absolute dimensions) or incremental, `I=IC(5)`
    /// (the default, as I5): the centre word as the arc reads it, an increment from the start.
    /// Any other expression of a centre stays unknown (no arc check).
    fn sinumerik_centre(&mut self, b: &BlockView<'_>, before: &Before) {
        for w in b.words {
            let Some((absolute, value)) = self.centre_dimension(w) else {
                continue;
            };
            let axis = b"XYZ"[usize::from(w.letter - b'I')];
            let centre = if absolute {
                // a lathe's X start is a diameter under DIAMON: the centre's X is a radius
                let start = before.axis(axis).and_then(|s| {
                    if axis == b'X' && self.x_diameter() {
                        dec(s.to_f64() / 2.0)
                    } else {
                        Some(s)
                    }
                });
                start.and_then(|s| dec(value.to_f64() - s.to_f64()))
            } else {
                Some(value)
            };
            self.values.overwrite(w.letter, centre);
        }
    }

    /// A SINUMERIK centre word `I=AC(c)` or `I=IC(c)` of a constant `c`: whether absolute,
    /// and `c` (read by [`Checker::programmed_forms`], not left unknown).
    pub(super) fn centre_dimension(&self, w: &crate::word::Word<'_>) -> Option<(bool, Dec)> {
        // (asked of every word of every SINUMERIK block: the test nearly every word fails,
        // a plain value, first)
        if w.expression.is_empty()
            || self.config.family != Family::Sinumerik
            || !matches!(w.letter, b'I' | b'J' | b'K')
            || !w.index.is_empty()
        {
            return None;
        }
        let (absolute, inner) = dimension_function(w.expression)?;
        Some((absolute, self.sinumerik_constant(inner)?))
    }

    /// A SINUMERIK's pole (G110 from the last programmed point, G111 from the workpiece zero,
    /// G112 from the last pole, each by the plane's axes or by RP= AP=) and its polar moves
    /// (G0-G3 with RP= and AP=: the end point at the radius RP and the angle AP about the pole;
    /// an arc turns about the pole). Where the pole, RP, AP or the start is not known (a pole
    /// from an unknown point or lost at a call, a value the checker cannot evaluate, an angle by
    /// IC(..) or under G91), the plane's two axes are unknown after the move.
    fn sinumerik_polar(&mut self, b: &BlockView<'_>, before: &Before) {
        let plane = self.machine.state.plane;
        if plane != self.polar.plane && self.polar.plane != 0 {
            // RP and AP are given again in a new plane ("after changing the pole or when
            // switching the plane"), and the pole is the old plane's
            self.polar = Polar {
                plane,
                ..Default::default()
            };
        }
        self.polar.plane = plane;
        let (first, second) = polar_axes(plane);
        // the polar words of the block: None where absent, Some(None) where not evaluated
        let rp = self.assigned(b, b"RP");
        let ap = self.assigned(b, b"AP");
        let pole_code = [110, 111, 112].into_iter().find(|&g| self.values.has_g(g));
        if let Some(code) = pole_code {
            self.polar.rp = None;
            self.polar.ap = None;
            let last = |s: &Before| -> Option<[f64; 2]> {
                Some([s.axis(first)?.to_f64(), s.axis(second)?.to_f64()])
            };
            let origin = match code {
                110 => last(before),
                111 => Some([0.0, 0.0]),
                _ => self.polar.pole,
            };
            let axis_word = |letter: u8| {
                if self.values.unknown & bit(letter) != 0 {
                    Some(None)
                } else {
                    self.values.get(letter).map(|v| Some(v.to_f64()))
                }
            };
            let by_axes = (axis_word(first), axis_word(second));
            let lathe_x = self.x_diameter() && (first == b'X' || second == b'X');
            self.polar.pole = match (by_axes, rp, ap) {
                _ if lathe_x => None,
                ((Some(Some(a)), Some(Some(c))), None, None) => {
                    origin.map(|o| [o[0] + a, o[1] + c])
                }
                ((None, None), Some(Some(r)), Some(Some(angle))) => {
                    origin.map(|o| polar_point(o, r, angle))
                }
                _ => None,
            };
            return;
        }
        if rp.is_none() && ap.is_none() {
            return;
        }
        if let Some(r) = rp {
            self.polar.rp = r;
        }
        if let Some(angle) = ap {
            self.polar.ap = angle;
        }
        let lathe_x = self.x_diameter() && (first == b'X' || second == b'X');
        let cartesian = [first, second]
            .iter()
            .any(|&a| self.values.has(a) || self.values.unknown & bit(a) != 0);
        let end = match (self.polar.pole, self.polar.rp, self.polar.ap) {
            (Some(pole), Some(r), Some(angle))
                if !self.machine.state.incremental && !lathe_x && !cartesian =>
            {
                Some(polar_point(pole, r, angle))
            }
            _ => None,
        };
        self.place_plane_axes([first, second], end);
        // the arc turns about the pole: no centre words to check (Checker::arc)
        self.polar_arc = true;
    }

    /// A SINUMERIK arc by its opening angle `AR=` (Programming Manual Fundamentals, "Circular
    /// interpolation with opening angle and center point (G2/G3, X... Y... Z.../ I... J...
    /// K..., AR)"): with the end point, every chord has its arc (the radius follows from the
    /// chord and the angle), so nothing is checked; with the centre and no end point, the end
    /// is the start turned about the centre by AR (clockwise under G2).
    fn opening_angle(&mut self, b: &BlockView<'_>, before: &Before) {
        let Some(angle) = self.assigned(b, b"AR") else {
            return;
        };
        self.opening_arc = true;
        let state = self.machine.state;
        let (first, second) = polar_axes(state.plane);
        let ends_given = [first, second]
            .iter()
            .any(|&a| self.values.has(a) || self.values.unknown & bit(a) != 0);
        if ends_given || !matches!(state.motion, Some(2 | 3)) {
            return;
        }
        let centre_letter = |axis: u8| match axis {
            b'X' => b'I',
            b'Y' => b'J',
            _ => b'K',
        };
        let start = (|| Some([before.axis(first)?.to_f64(), before.axis(second)?.to_f64()]))();
        let ij = (|| {
            Some([
                self.values.get(centre_letter(first))?.to_f64(),
                self.values.get(centre_letter(second))?.to_f64(),
            ])
        })();
        let lathe_x = self.x_diameter() && (first == b'X' || second == b'X');
        let end = match (start, ij, angle) {
            (Some(s), Some(c), Some(a)) if !lathe_x => {
                let turn = if state.motion == Some(2) { -a } else { a }.to_radians();
                let (dx, dy) = (-c[0], -c[1]);
                let (centre_x, centre_y) = (s[0] + c[0], s[1] + c[1]);
                Some([
                    centre_x + dx * turn.cos() - dy * turn.sin(),
                    centre_y + dx * turn.sin() + dy * turn.cos(),
                ])
            }
            _ => None,
        };
        self.place_plane_axes([first, second], end);
    }

    /// The value the block assigns to the SINUMERIK address `name` (`RP=10`, `AP=R1*2`):
    /// None where it assigns none, Some(None) where the value is not a constant the checker
    /// evaluates (or is an `IC(..)`/`AC(..)` dimension, which it does not follow here).
    ///
    /// Asked three times of every SINUMERIK block (RP, AP, AR), nearly all of which have no
    /// statement: that test is made here, inlined, and the search only where there is one.
    #[inline(always)]
    fn assigned(&self, b: &BlockView<'_>, name: &[u8]) -> Option<Option<f64>> {
        if b.statements.is_empty() {
            return None;
        }
        self.assigned_in(b, name)
    }

    /// [`Checker::assigned`] in a block with statements.
    fn assigned_in(&self, b: &BlockView<'_>, name: &[u8]) -> Option<Option<f64>> {
        b.statements.iter().find_map(|&(_, kind, text)| {
            let end = statement::ident_end(text, 0);
            (kind == Kind::Assignment && text[..end].eq_ignore_ascii_case(name)).then(|| {
                text[end..]
                    .trim_ascii()
                    .strip_prefix(b"=")
                    .map(<[u8]>::trim_ascii)
                    .filter(|v| dimension_function(v).is_none())
                    .and_then(|v| self.sinumerik_constant(v))
                    .map(Dec::to_f64)
            })
        })
    }

    /// HEIDENHAIN ISO: a G90 or G91 applies to the coordinates after it in its block, so one
    /// block may give one coordinate incremental and the next absolute (TNC 426/425 ISO
    /// manual, "Path contours - Cartesian coordinates": "Resulting NC block: G02 G91 X+5 G90
    /// Y-5"); the mode after the block is its last. A coordinate before the block's first G90
    /// or G91 is read in the mode in force before it. A circle centre I J K under G91 is an
    /// increment from the last programmed point ("G29 ... incremental: relative to the last
    /// programmed position"), kept absolute as the CC; from an unknown point it is unknown.
    #[inline(never)]
    fn heidenhain_distance(&mut self, b: &BlockView<'_>, before: &Before) {
        // a polar move, a new coordinate system or the blank form: the modal state follows no
        // axis word of it (ModalMachine::moved)
        let followed = !(self
            .machine
            .state
            .motion
            .is_some_and(|m| (10..=16).contains(&m))
            || [28, 30, 31, 54, 72, 73, 80]
                .iter()
                .any(|&g| self.values.has_g(g)));
        let mut incremental = before.incremental;
        let mut seen = 0u32;
        for (i, w) in b.words.iter().enumerate() {
            let Some(value) = self.readable[i] else {
                continue;
            };
            match w.letter {
                b'G' if value.eq_int(90) => incremental = false,
                b'G' if value.eq_int(91) => incremental = true,
                letter @ (b'I' | b'J' | b'K') => {
                    if seen & bit(letter) != 0 || !incremental {
                        continue;
                    }
                    seen |= bit(letter);
                    let axis = b"XYZ"[usize::from(letter - b'I')];
                    let centre = before.axis(axis).and_then(|from| from.checked_add(value));
                    self.values.overwrite(letter, centre);
                }
                letter if AXES.contains(&letter) => {
                    if seen & bit(letter) != 0 {
                        continue;
                    }
                    seen |= bit(letter);
                    let Some(k) = axis_index(letter) else {
                        continue;
                    };
                    if !followed
                        || incremental == self.machine.state.incremental
                        || self.values.get(letter) != Some(value)
                    {
                        continue;
                    }
                    let position = if incremental {
                        before.axis(letter).and_then(|from| from.checked_add(value))
                    } else {
                        Some(value)
                    };
                    match position {
                        Some(p) => {
                            self.machine.state.position[k] = Some(p);
                            self.machine.state.unknown &= !bit(letter);
                        }
                        None => self.machine.forget_axis(letter),
                    }
                }
                _ => {}
            }
        }
    }
}

/// `AC(..)` (absolute) or `IC(..)` (incremental) around a value, with what is inside.
fn dimension_function(expression: &[u8]) -> Option<(bool, &[u8])> {
    let text = expression.trim_ascii();
    let (name, rest) = text.split_at_checked(2)?;
    let absolute = if name.eq_ignore_ascii_case(b"AC") {
        true
    } else if name.eq_ignore_ascii_case(b"IC") {
        false
    } else {
        return None;
    };
    let inner = rest.trim_ascii().strip_prefix(b"(")?.strip_suffix(b")")?;
    Some((absolute, inner.trim_ascii()))
}

#[cfg(test)]
mod tests {
    use super::{dimension_function, polar_point};

    #[test]
    fn a_dimension_function_is_ac_or_ic_around_its_value() {
        assert_eq!(dimension_function(b"AC(20)"), Some((true, &b"20"[..])));
        assert_eq!(
            dimension_function(b"ic( -5.5 )"),
            Some((false, &b"-5.5"[..]))
        );
        assert_eq!(dimension_function(b"AC(R1+2)"), Some((true, &b"R1+2"[..])));
        for text in [&b"20"[..], b"ACP(20)", b"AC 20", b"R1", b"AC(20"] {
            assert_eq!(dimension_function(text), None, "{text:?}");
        }
    }

    #[test]
    fn a_polar_angle_turns_counterclockwise_from_the_plane_s_first_axis() {
        let close =
            |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9;
        assert!(close(polar_point([0.0, 0.0], 10.0, 0.0), [10.0, 0.0]));
        assert!(close(polar_point([10.0, 0.0], 5.0, 90.0), [10.0, 5.0]));
        assert!(close(polar_point([1.0, 1.0], 2.0, 180.0), [-1.0, 1.0]));
    }
}
