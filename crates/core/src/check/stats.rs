//! The statistics and the path (no rule of their own): each move's extent, length and time
//! in the profile's units, and its segment for the backplot.

use std::f64::consts::PI;

use super::motion::{centre_of, plane_axes};
use super::{Before, BlockView, Checker, Segment};
use crate::decimal::Dec;
use crate::geometry::{self, RadiusArc};
use crate::lex::Family;
use crate::modal::{axis_index, Units};

impl Checker {
    /// A dwell's time in seconds, by the profile's dwell letters (`word::dwell_words`), the
    /// first of them the block gives: a FANUC or Haas P in milliseconds (a Haas P with a point
    /// in seconds, as convert reads it), X and a lathe's U in seconds (the FANUC operator's
    /// manuals, "Dwell (G04)"); LinuxCNC's P in seconds (G-code reference, G4); SINUMERIK's F
    /// in seconds, its S revolutions of the spindle, not counted (no time without the
    /// spindle's speed at the dwell); ISO 6983-1's, Okuma's and HEIDENHAIN's X, P, F in
    /// seconds. A time, never revolutions under G95 (FANUC's dwell by revolutions is a
    /// parameter's choice, not the default).
    ///
    /// A time not known is left out of the cycle time and said in `dwells_not_known` (each
    /// kind once, at its first line, with a count): SINUMERIK's S, and a FANUC or Haas X or U
    /// without a point under G20. Read with the inch format that word is a tenth of the time
    /// the same digits give under G21 (`G20 G04 X1500`, 0.15 s or 1.5 s), and no source at
    /// hand says whether the control's dwell follows G20's increment; `diff` keeps such a
    /// dwell apart (`ncread`, its `inch_in_doubt`) and convert refuses it, so the statistics
    /// do not state a time for it either.
    pub(super) fn dwell_time(&mut self, b: &BlockView<'_>) {
        for &letter in self.machine.settings.dwell {
            let Some(value) = self.values.get(letter) else {
                continue;
            };
            let word = b
                .words
                .iter()
                .find(|w| w.letter == letter && w.index.is_empty());
            let point = word.is_some_and(|w| w.point);
            // (a time by a parameter or an expression is the value the control computes, no
            // count of increments)
            let digits = word.is_some_and(|w| !w.point && w.expression.is_empty());
            let seconds = match (self.config.family, letter) {
                (Family::Sinumerik, b'S') => {
                    self.dwell_not_known(
                        b.line,
                        "SINUMERIK's G4 S",
                        "SINUMERIK's G4 S is revolutions of the spindle, no time without the \
                         spindle's speed at the dwell",
                    );
                    return;
                }
                (Family::MacroB, b'P') => {
                    if point {
                        value.to_f64()
                    } else {
                        value.to_f64() / 1000.0
                    }
                }
                (Family::MacroB, _) if digits && self.machine.state.units == Units::Inch => {
                    let token = word.map_or(&b""[..], |w| w.token);
                    let kind = format!("a dwell's {} ", letter as char);
                    let said = format!(
                        "{kind}without a decimal point under G20 ({}): read with the inch \
                         format it is {} s, with the metric one ten times that; no source says \
                         whether the control's dwell follows G20's increment (diff keeps such \
                         a dwell apart, convert refuses it)",
                        String::from_utf8_lossy(token),
                        value.to_f64()
                    );
                    self.dwell_not_known(b.line, &kind, &said);
                    return;
                }
                _ => value.to_f64(),
            };
            self.stats.seconds += seconds;
            return;
        }
    }

    /// A dwell whose time is not known: counted apart, its kind said once (`kind` starts
    /// the reason and tells one kind from another).
    fn dwell_not_known(&mut self, line: usize, kind: &str, why: &str) {
        self.stats.dwells_not_counted += 1;
        let known = self
            .stats
            .dwells_not_known
            .iter()
            .any(|m| m.split_once(": ").is_some_and(|(_, r)| r.starts_with(kind)));
        if !known {
            self.stats
                .dwells_not_known
                .push(format!("from line {line}: {why}"));
        }
    }

    /// `draws`: the block's axis words are a move the backplot draws ([`Checker::draws`]).
    pub(super) fn motion_stats(&mut self, before: &Before, moved: &[u8], line: usize, draws: bool) {
        let Some(motion) = self.machine.state.motion else {
            return;
        };
        if moved.is_empty() {
            return;
        }
        // the statistics are in the profile's units, whatever units the block is written in
        // (a rotary axis in degrees either way)
        let (factor, feed_factor) = (self.to_profile_units(false), self.to_profile_units(true));
        for &axis in moved {
            let (Some(i), Some(p)) = (axis_index(axis), self.machine.state.axis(axis)) else {
                continue;
            };
            if factor != 1.0 && !matches!(axis, b'A' | b'B' | b'C') {
                // in the profile's units, rounded to the axis's resolution (exactly only
                // where it can widen the extent)
                self.widen(axis, p.to_f64() * factor);
                continue;
            }
            if self.stats.low[i].is_none_or(|low| p < low) {
                self.stats.low[i] = Some(p);
            }
            if self.stats.high[i].is_none_or(|high| p > high) {
                self.stats.high[i] = Some(p);
            }
        }
        // lengths and arcs where the tool runs: a lathe's diameter X halved
        let across = if self.x_diameter() { 0.5 } else { 1.0 };
        let (start, end) = (point(&before.xyz), point(&self.machine.state.position));
        let (s, e) = (
            [start[0] * across, start[1], start[2]],
            [end[0] * across, end[1], end[2]],
        );
        let mut length = dist(s, e);
        let mut kind = if motion == 0 { "rapid" } else { "feed" };
        let (first, second, third) = plane_axes(self.machine.state.plane);
        let (a, b, k) = (xyz(first), xyz(second), xyz(third));
        let clockwise = motion == 2;
        let radius_arc = self.radius_arc.take();
        let lead = b"IJK".iter().any(|&l| self.values.has(l));
        let in_plane = match radius_arc {
            _ if !matches!(motion, 2 | 3) || self.machine.state.cycle.is_some() => None,
            Some(RadiusArc::Centre(cx, cy)) => Some((cx, cy)),
            Some(RadiusArc::Impossible) => {
                kind = "chord";
                None
            }
            None if lead && !self.values.has(self.config.modal.arc_radius) => {
                let ci = self.values.get(centre_of(first)).map_or(0.0, Dec::to_f64);
                let cj = self.values.get(centre_of(second)).map_or(0.0, Dec::to_f64);
                let scale = if self.machine.state.units == Units::Inch {
                    1.0 / 25.4
                } else {
                    1.0
                };
                Some(self.centre((s[a], s[b]), (e[a], e[b]), (ci, cj), clockwise, scale))
            }
            _ => None,
        };
        let mut centre = None;
        let mut large = false;
        if let Some((cx, cy)) = in_plane {
            let arc = geometry::Turn::new((s[a], s[b]), (e[a], e[b]), (cx, cy), clockwise);
            let (turn, r) = (arc.turn, arc.radius);
            length = (r * turn).hypot(e[k] - s[k]);
            large = turn > PI + 1e-9;
            kind = "arc";
            self.stats.arcs += 1;
            let mut c = s;
            c[a] = cx;
            c[b] = cy;
            c[0] /= across;
            centre = Some(c);
            let known = before.axis(first).is_some() && before.axis(second).is_some();
            if known
                && self.machine.state.axis(first).is_some()
                && self.machine.state.axis(second).is_some()
            {
                let reach = arc.extents((s[a], s[b]), (e[a], e[b]), (cx, cy), clockwise);
                for (axis, (least, most)) in [(first, reach[0]), (second, reach[1])] {
                    let scale = if axis == b'X' { across } else { 1.0 };
                    self.widen(axis, least / scale * factor);
                    self.widen(axis, most / scale * factor);
                }
            }
        }
        let revolutions = match kind != "rapid" && self.machine.state.feed_mode == 95 {
            true => self.revolutions(before),
            false => 0.0,
        };
        let stats = &mut self.stats;
        let length_in_profile = length * factor;
        if kind == "rapid" {
            stats.rapid_length += length_in_profile;
            stats.seconds += length_in_profile / self.config.rapid_rate * 60.0;
        } else {
            stats.feed_length += length_in_profile;
            let mut feed = self.machine.state.feed.map_or(0.0, Dec::to_f64);
            if self.machine.state.feed_mode != 93 {
                feed *= feed_factor;
            }
            if self.machine.state.feed_mode == 95 {
                feed *= revolutions;
            }
            if self.machine.state.feed_mode == 93 && feed != 0.0 {
                stats.seconds += 60.0 / feed;
            } else if feed > 0.0 {
                stats.seconds += length_in_profile / feed * 60.0;
            }
        }
        // (a full circle ends where it starts: an arc is recorded all the same)
        let unknown_before = (0..3)
            .filter(|&i| before.xyz[i].is_none())
            .fold(0u8, |axes, i| axes | 1 << i);
        let named = moved
            .iter()
            .filter_map(|&a| b"XYZ".iter().position(|&x| x == a))
            .fold(0u8, |axes, i| axes | 1 << i);
        // the axes the program had placed, unknown since (a shift, a skip, a call) and not
        // given again by the block: on them the move is somewhere nobody knows (drawn, it
        // would run at 0), and it is not drawn in a view that shows one of them
        let adrift = unknown_before & self.drawn.placed & !named;
        self.drawn.placed |= (0..3)
            .filter(|&i| self.machine.state.position[i].is_some())
            .fold(0u8, |axes, i| axes | 1 << i);
        if self.record_path && draws && (start != end || kind == "arc") {
            if adrift != 0 {
                self.drawn.adrift.push((line, adrift));
            }
            // an axis it moves from where the program has not yet put it: its start is not
            // drawn (an unknown position reads 0 here)
            let lost = named & unknown_before;
            if lost != 0 {
                self.drawn.unknown_start(line, lost);
            }
            self.drawn.units[usize::from(self.machine.state.units == Units::Inch)] = true;
            self.path.push(Segment {
                kind,
                start,
                end,
                line,
                centre,
                clockwise,
                plane: self.machine.state.plane,
                large,
            });
        }
    }

    /// A position in the profile's units, rounded to the resolution of the axis's format in
    /// them: what the control can reach and report.
    pub(super) fn in_profile_units(&self, axis: u8, value: f64) -> Option<Dec> {
        let decimals = self
            .format_in(axis, self.config.limit_units)
            .map_or(4, |f| f.after as usize);
        let text = format!("{value:.decimals$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.')
        } else {
            &text
        };
        Dec::parse(if text == "-0" { "0" } else { text })
    }

    /// Widen the statistics' extent of `axis` to `value` (an arc's quadrant point, in the
    /// profile's units), rounded to the resolution of the axis's format.
    pub(super) fn widen(&mut self, axis: u8, value: f64) {
        let Some(i) = axis_index(axis) else { return };
        // (an arc's four quadrant points and the next arc's ask the same extent: its floats a
        // step inside each end, kept while its ends are the ones they were found for)
        let ends = (self.stats.low[i], self.stats.high[i]);
        if let (Some(inside), (Some(low), Some(high))) = (self.inside[i], ends) {
            if same(inside.low, low)
                && same(inside.high, high)
                && value > inside.above
                && value < inside.below
            {
                return;
            }
        }
        // Most quadrant points lie well inside the extent already found: rounding moves a
        // value by half a step at most, so one more than a step inside cannot widen it (the
        // exact rounding below is only for the points near an edge).
        if let (Some(low), Some(high)) = (self.stats.low[i], self.stats.high[i]) {
            let decimals = self
                .format_in(axis, self.config.limit_units)
                .map_or(4, |f| f.after);
            let (least, most) = (low.to_f64(), high.to_f64());
            let step = STEPS
                .get(decimals as usize)
                .copied()
                .unwrap_or_else(|| 10f64.powi(-(decimals as i32)));
            let (above, below) = (least + step, most - step);
            self.inside[i] = Some(Inside {
                low,
                high,
                above,
                below,
            });
            if value > above && value < below {
                return;
            }
            // On an edge (a raster's every pass ends there): where both ends are on the
            // axis's grid, rounding a value between them cannot pass either (it moves to the
            // nearest step; an end's double is within 1e-10 of it, a step at least 1e-9)
            if decimals < STEPS.len() as u32
                && low.scale <= decimals
                && high.scale <= decimals
                && least.abs() < 1e6
                && most.abs() < 1e6
                && least <= value
                && value <= most
            {
                return;
            }
        }
        let Some(at) = self.in_profile_units(axis, value) else {
            return;
        };
        if self.stats.low[i].is_none_or(|low| at < low) {
            self.stats.low[i] = Some(at);
        }
        if self.stats.high[i].is_none_or(|high| at > high) {
            self.stats.high[i] = Some(at);
        }
    }
}

/// An axis's extent in the statistics, `low` to `high`, and its ends one step of the axis's
/// format inside, as floats (`above`, `below`): a point between these cannot widen it
/// ([`Checker::widen`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Inside {
    low: Dec,
    high: Dec,
    above: f64,
    below: f64,
}

/// The same digits at the same scale (not only the same value: `1.0` is not `1.00`).
fn same(a: Dec, b: Dec) -> bool {
    a.mantissa == b.mantissa && a.scale == b.scale
}

/// 10^-d for the decimals of a format, d = 0..9, without a `powi` per point.
const STEPS: [f64; 10] = [1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9];

pub(super) fn xyz(axis: u8) -> usize {
    match axis {
        b'X' => 0,
        b'Y' => 1,
        _ => 2,
    }
}

impl Checker {
    /// The spindle's revolutions per minute over a move, for a feed per revolution: S under
    /// G97; under G96 on a lathe S is a surface speed (m/min in metric, ft/min in inch: FANUC
    /// 0i-TF "Constant surface speed control", Haas lathe G96), turned into rpm at the move's
    /// middle diameter (exact for a straight move that does not cross the axis: the time
    /// grows with the diameter), rpm = S * 1000 / (pi * D) or S * 12 / (pi * D), and held to
    /// the speed limit in force (G50 S). Where the diameter is 0 or not known, the limit, else
    /// S as written.
    fn revolutions(&self, before: &Before) -> f64 {
        let speed = self.machine.state.speed.map_or(0.0, Dec::to_f64);
        if self.machine.state.spindle_mode != 96 || !self.config.diameter {
            return speed;
        }
        let limit = self
            .machine
            .state
            .speed_limit
            .map(|l| l.to_f64())
            .filter(|&l| l > 0.0);
        let (Some(a), Some(b)) = (before.xyz[0], self.machine.state.position[0]) else {
            return limit.unwrap_or(speed);
        };
        let diameter = ((a.to_f64() + b.to_f64()) / 2.0).abs();
        let per_length = if self.machine.state.units == Units::Inch {
            12.0
        } else {
            1000.0
        };
        if diameter <= 0.0 {
            return limit.unwrap_or(speed);
        }
        let rpm = speed * per_length / (PI * diameter);
        limit.map_or(rpm, |l| rpm.min(l))
    }
}

pub(super) fn point(position: &[Option<Dec>]) -> [f64; 3] {
    // X Y Z are the first three of the state's axes (modal::AXES)
    let at = |i: usize| position[i].map_or(0.0, Dec::to_f64);
    [at(0), at(1), at(2)]
}

pub(super) fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::super::testing::{
        dialect, fanuc_lathe, iso_mill, okuma_lathe, program, run, run_recording,
    };
    use super::super::Config;
    use crate::lex::Family;
    use std::f64::consts::PI;

    #[test]
    fn an_extent_widens_as_the_exact_rounding_says() {
        use super::super::Checker;
        use crate::decimal::Dec;
        use crate::rules::Selection;
        use std::sync::Arc;
        let mut checker = Checker::new(Arc::new(iso_mill()), Selection::all(), false);
        // ends on the grid and off it, values on, near and between the ends
        let ends = [
            ("-1.5", "2.25"),
            ("0", "0"),
            ("-0.00004", "0.00006"),
            ("10", "10.0001"),
        ];
        for (low, high) in ends {
            let (low, high) = (Dec::parse(low).unwrap(), Dec::parse(high).unwrap());
            for k in -400..=400 {
                let value = low.to_f64() + f64::from(k) * 0.0000137;
                let value = [value, high.to_f64() + f64::from(k) * 0.0000137];
                for v in value {
                    checker.stats.low[0] = Some(low);
                    checker.stats.high[0] = Some(high);
                    let at = checker.in_profile_units(b'X', v).unwrap();
                    let want = (
                        if at < low { at } else { low },
                        if at > high { at } else { high },
                    );
                    checker.widen(b'X', v);
                    let got = (
                        checker.stats.low[0].unwrap(),
                        checker.stats.high[0].unwrap(),
                    );
                    assert_eq!(got, want, "{v} in {low}..{high}");
                }
            }
        }
    }

    #[test]
    fn lengths_times_extents_and_the_path() {
        let config = iso_mill();
        let text = program("G00 X10. Y0\nG01 X10. Y10. F100.\nG02 X20. Y20. I10. J0\nG04 X2.");
        let (checker, found) = run_recording(config, &dialect(Family::Iso), &text, true);
        assert_eq!(found, []);
        let s = &checker.stats;
        assert_eq!((s.blocks, s.arcs), (7, 1));
        assert!((s.rapid_length - 10.0).abs() < 1e-9, "{}", s.rapid_length);
        let feed = 10.0 + 5.0 * PI;
        assert!((s.feed_length - feed).abs() < 1e-9, "{}", s.feed_length);
        let seconds = 10.0 / 10000.0 * 60.0 + feed / 100.0 * 60.0 + 2.0;
        assert!((s.seconds - seconds).abs() < 1e-9, "{}", s.seconds);
        let extent = |i: usize| {
            (
                s.low[i].unwrap().to_string(),
                s.high[i].unwrap().to_string(),
            )
        };
        assert_eq!(extent(0), ("10".into(), "20".into()));
        assert_eq!(extent(1), ("0".into(), "20".into()));
        let kinds: Vec<_> = checker.path.iter().map(|p| (p.kind, p.line)).collect();
        assert_eq!(kinds, [("rapid", 2), ("feed", 3), ("arc", 4)]);
        assert_eq!(checker.path[2].centre, Some([20.0, 10.0, 0.0]));
        assert!(checker.path[2].clockwise && !checker.path[2].large);
    }

    #[test]
    fn no_path_unless_asked_and_a_lathe_s_diameter_halved() {
        let text = program("G01 X20. Z0 F100.\nG01 X40. Z0");
        let (checker, _) = run(iso_mill(), &dialect(Family::Iso), &text);
        assert!(checker.path.is_empty());
        let lathe = Config {
            diameter: true,
            ..iso_mill()
        };
        let (lathe, _) = run(lathe, &dialect(Family::Iso), &text);
        // (from X0, a diameter: 10 then 10 more in radius)
        assert!(
            (lathe.stats.feed_length - 20.0).abs() < 1e-9,
            "{}",
            lathe.stats.feed_length
        );
        assert!((checker.stats.feed_length - 40.0).abs() < 1e-9);
    }

    #[test]
    fn a_surface_speed_is_turned_into_revolutions_at_the_diameter() {
        // 180 m/min at X50. (the diameter; Z2. to Z-10. at 0.2 mm/rev): 1145.9 rpm
        let lathe = || Config {
            diameter: true,
            ..fanuc_lathe()
        };
        let seconds = |body: &str| {
            let text = program(&format!("G99\n{body}\nG00 X50. Z2.\nG01 Z-10. F0.2"));
            run(lathe(), &dialect(Family::MacroB), &text)
                .0
                .stats
                .seconds
        };
        let rpm = 180.0 * 1000.0 / (PI * 50.0);
        let css = seconds("G50 S2500\nG96 S180 M03");
        // against 1146 rpm, a speed S's format holds (one of nine decimals is refused, and
        // unknown): the feed move's 12 mm at 0.2 mm/rev differs by the two speeds alone
        let feed_at = |n: f64| 12.0 / (0.2 * n) * 60.0;
        assert!(
            (css - seconds("G97 S1146 M03") - (feed_at(rpm) - feed_at(1146.0))).abs() < 1e-6,
            "{css}"
        );
        // the G50 clamp holds it: as 1000 rpm
        let clamped = seconds("G50 S1000\nG96 S180 M03");
        assert!(
            (clamped - seconds("G97 S1000 M03")).abs() < 1e-9,
            "{clamped}"
        );
        // the feed move alone: 12 mm at 0.2 mm/rev and 1145.9 rpm
        assert!(css > 12.0 / (0.2 * rpm) * 60.0);
    }

    #[test]
    fn an_okuma_lathe_s_l_arc_is_drawn_and_measured_as_an_arc() {
        // X20. Z0 to X26. Z-3. about the centre X/2 = 10, Z -3: a quarter circle of radius 3
        let text = program("G01 X20. Z0 F.2\nG03 X26. Z-3. L3.");
        let (checker, _) = run_recording(okuma_lathe(), &dialect(Family::Okuma), &text, true);
        let arc = checker.path.last().expect("the arc");
        assert_eq!(arc.kind, "arc");
        let centre = arc.centre.expect("its centre");
        assert!((centre[0] - 20.0).abs() < 1e-9 && (centre[2] + 3.0).abs() < 1e-9);
        assert!(!arc.large);
        assert_eq!(checker.stats.arcs, 1);
        // without L the same block is a chord, no arc
        let chord = program("G01 X20. Z0 F.2\nG03 X26. Z-3.");
        let (checker, _) = run_recording(okuma_lathe(), &dialect(Family::Okuma), &chord, true);
        assert_eq!(checker.stats.arcs, 0);
    }
}
