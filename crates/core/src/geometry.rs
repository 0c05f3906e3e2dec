//! Arc geometry of the checker's path: the centre of an arc given by its radius (`G02 X Y R`,
//! Sinumerik `CR=`), the angle an arc turns through, and the points where it crosses a
//! quadrant boundary (its extents). The checker's TG410, the statistics and the backplot all
//! take an arc from here, so they cannot disagree about where it runs.
//!
//! Why the radius arc starts from exact decimals: its centre lies on the chord's perpendicular
//! bisector at the distance `sqrt(R^2 - (chord/2)^2)` from the chord's middle. For the common
//! half circle (R is half the chord) that difference of two nearly equal squares is where
//! floats lose every digit: `G02 X10.001 Y0 R5.0005` is an exact half circle that floats can
//! turn into "no such arc" or into a centre off the chord. From the written decimals the
//! squares and their comparison are exact integers; only the square root is a float.

use std::f64::consts::PI;

use crate::decimal::{Dec, POW10};

/// Where an arc given by its radius runs, in the plane's first and second axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RadiusArc {
    /// Its centre.
    Centre(f64, f64),
    /// No arc of that radius joins the points: the radius is shorter than half the chord by
    /// more than the tolerance (TG410), or it is zero.
    Impossible,
    /// The start and end are one point: a radius gives no circle there.
    Point,
}

/// The mantissas of `values` at their finest common scale, and that scale; None on overflow.
fn common<const N: usize>(values: [Dec; N]) -> Option<([i128; N], u32)> {
    let scale = values.iter().map(|v| v.scale).max().unwrap_or(0);
    let mut out = [0i128; N];
    for (slot, v) in out.iter_mut().zip(values) {
        *slot = v
            .mantissa
            .checked_mul(*POW10.get((scale - v.scale) as usize)?)?;
    }
    Some((out, scale))
}

/// The arc from `start` to `end` of the signed `radius`: positive for the arc of at most 180
/// degrees, negative for the arc over 180 degrees (the Fanuc, Haas, LinuxCNC and Sinumerik
/// reading of R and CR). A radius short of half the chord by at most `tolerance` is the half
/// circle about the chord's middle, as the controls take it.
pub fn radius_arc(
    start: (Dec, Dec),
    end: (Dec, Dec),
    radius: Dec,
    clockwise: bool,
    tolerance: f64,
) -> RadiusArc {
    let exact = common([start.0, start.1, end.0, end.1, radius.abs()]).and_then(|(m, scale)| {
        let (dx, dy) = (m[2].checked_sub(m[0])?, m[3].checked_sub(m[1])?);
        let chord2 = dx.checked_mul(dx)?.checked_add(dy.checked_mul(dy)?)?;
        let diameter2 = m[4].checked_mul(m[4])?.checked_mul(4)?;
        let unit = POW10[scale as usize] as f64;
        let middle = (
            (m[0] + m[2]) as f64 / (2.0 * unit),
            (m[1] + m[3]) as f64 / (2.0 * unit),
        );
        // (2R)^2 - chord^2, exact, and the chord, both in the plane's units
        let excess = (diameter2 - chord2) as f64 / (unit * unit);
        Some((
            excess,
            (chord2 as f64).sqrt() / unit,
            middle,
            (dx as f64 / unit, dy as f64 / unit),
        ))
    });
    let (excess, chord, middle, (dx, dy)) = exact.unwrap_or_else(|| {
        // beyond the exact integers (values of 19 digits): floats all the way
        let (sx, sy, ex, ey) = (
            start.0.to_f64(),
            start.1.to_f64(),
            end.0.to_f64(),
            end.1.to_f64(),
        );
        let chord = (ex - sx).hypot(ey - sy);
        let r = radius.to_f64().abs();
        (
            4.0 * r * r - chord * chord,
            chord,
            ((sx + ex) / 2.0, (sy + ey) / 2.0),
            (ex - sx, ey - sy),
        )
    });
    let r = radius.to_f64().abs();
    if r == 0.0 {
        return RadiusArc::Impossible;
    }
    if chord == 0.0 {
        return RadiusArc::Point;
    }
    let height = if excess >= 0.0 {
        excess.sqrt() / 2.0
    } else if chord / 2.0 > r + tolerance {
        return RadiusArc::Impossible;
    } else {
        0.0
    };
    // the centre is right of the way from start to end for a clockwise arc of at most 180
    // degrees, left for a counter-clockwise one; a negative radius takes the other side
    let side = if clockwise == (radius.mantissa > 0) {
        1.0
    } else {
        -1.0
    };
    let centre = (
        middle.0 + side * height * dy / chord,
        middle.1 - side * height * dx / chord,
    );
    RadiusArc::Centre(centre.0, centre.1)
}

/// `x.rem_euclid(2 pi)`, without the library's floating remainder where `x` is within one turn
/// of 0, as every difference of two angles from `atan2` is: there the remainder is `x` itself,
/// or `x + 2 pi` below 0, exactly as `rem_euclid` works it out.
fn in_one_turn(x: f64) -> f64 {
    const TURN: f64 = 2.0 * PI;
    if (0.0..TURN).contains(&x) {
        x
    } else if x < 0.0 && x > -TURN {
        x + TURN
    } else {
        x.rem_euclid(TURN)
    }
}

/// An arc about `centre` from `start` to `end` in its plane, as its length and its extents
/// read it: the radius at its start, the start's angle and the angle it turns through, each
/// worked out once.
#[derive(Debug, Clone, Copy)]
pub struct Turn {
    pub radius: f64,
    start_angle: f64,
    /// In radians, 0 < turn <= 2 pi: the same start and end point is a full circle, as on the
    /// control.
    pub turn: f64,
}

impl Turn {
    pub fn new(start: (f64, f64), end: (f64, f64), centre: (f64, f64), clockwise: bool) -> Turn {
        let a0 = (start.1 - centre.1).atan2(start.0 - centre.0);
        let a1 = (end.1 - centre.1).atan2(end.0 - centre.0);
        let turn = in_one_turn(if clockwise { a0 - a1 } else { a1 - a0 });
        Turn {
            radius: (start.0 - centre.0).hypot(start.1 - centre.1),
            start_angle: a0,
            turn: if turn > 1e-12 { turn } else { 2.0 * PI },
        }
    }

    /// The least and most of each plane axis the arc reaches: its end points and each
    /// quadrant point (centre +- radius on an axis) it passes, at the start's radius.
    pub fn extents(
        &self,
        start: (f64, f64),
        end: (f64, f64),
        centre: (f64, f64),
        clockwise: bool,
    ) -> [(f64, f64); 2] {
        let mut out = [
            (start.0.min(end.0), start.0.max(end.0)),
            (start.1.min(end.1), start.1.max(end.1)),
        ];
        let (r, a0) = (self.radius, self.start_angle);
        let points = [
            (0.0, (centre.0 + r, centre.1)),
            (PI / 2.0, (centre.0, centre.1 + r)),
            (PI, (centre.0 - r, centre.1)),
            (1.5 * PI, (centre.0, centre.1 - r)),
        ];
        for (angle, (x, y)) in points {
            // how far the arc turns from its start to reach this angle
            let to = in_one_turn(if clockwise { a0 - angle } else { angle - a0 });
            if to <= self.turn + 1e-12 {
                out[0] = (out[0].0.min(x), out[0].1.max(x));
                out[1] = (out[1].0.min(y), out[1].1.max(y));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sweep(start: (f64, f64), end: (f64, f64), centre: (f64, f64), clockwise: bool) -> f64 {
        Turn::new(start, end, centre, clockwise).turn
    }

    fn extents(
        start: (f64, f64),
        end: (f64, f64),
        centre: (f64, f64),
        clockwise: bool,
    ) -> [(f64, f64); 2] {
        Turn::new(start, end, centre, clockwise).extents(start, end, centre, clockwise)
    }

    #[test]
    fn one_turn_is_the_euclidean_remainder() {
        let turn = 2.0 * PI;
        let mut values = vec![0.0, -0.0, turn, -turn, PI, -PI, 2.5 * PI, -2.5 * PI, 1e-300];
        values.extend([f64::NAN, f64::INFINITY, 4.0 * turn + 0.1, f64::MIN_POSITIVE]);
        for i in -4000..=4000 {
            let x = f64::from(i) * 0.00397 * PI;
            values.extend([x, x.next_up(), x.next_down(), turn - x, x - turn]);
        }
        for x in values {
            let (fast, exact) = (in_one_turn(x), x.rem_euclid(turn));
            assert!(
                fast.to_bits() == exact.to_bits() || fast.is_nan() && exact.is_nan(),
                "{x}"
            );
        }
    }

    fn d(text: &str) -> Dec {
        Dec::parse(text).unwrap()
    }

    fn arc(end: (&str, &str), radius: &str, clockwise: bool) -> RadiusArc {
        radius_arc(
            (d("0"), d("0")),
            (d(end.0), d(end.1)),
            d(radius),
            clockwise,
            0.0282843,
        )
    }

    #[test]
    fn a_radius_arc_takes_its_side_of_the_chord() {
        // from X0 Y0 to X10 Y10 with R10: G02 about X10 Y0, G03 about X0 Y10
        assert_eq!(arc(("10", "10"), "10", true), RadiusArc::Centre(10.0, 0.0));
        assert_eq!(arc(("10", "10"), "10", false), RadiusArc::Centre(0.0, 10.0));
        // a negative radius is the arc over 180 degrees, about the other centre
        assert_eq!(arc(("10", "10"), "-10", true), RadiusArc::Centre(0.0, 10.0));
        let turn = sweep((0.0, 0.0), (10.0, 10.0), (0.0, 10.0), true);
        assert!((turn - 1.5 * PI).abs() < 1e-12);
    }

    #[test]
    fn a_half_circle_written_in_decimals_is_exact() {
        assert_eq!(
            arc(("10.001", "0"), "5.0005", true),
            RadiusArc::Centre(5.0005, 0.0)
        );
        // a negative radius of exactly half the chord is still the half circle
        assert_eq!(
            arc(("10.001", "0"), "-5.0005", true),
            RadiusArc::Centre(5.0005, 0.0)
        );
    }

    #[test]
    fn a_short_radius_is_the_half_circle_within_the_tolerance_and_else_impossible() {
        assert_eq!(arc(("10", "0"), "4.99", true), RadiusArc::Centre(5.0, 0.0));
        assert_eq!(arc(("10", "0"), "4", true), RadiusArc::Impossible);
        assert_eq!(arc(("10", "0"), "0", true), RadiusArc::Impossible);
        assert_eq!(arc(("0", "0"), "4", true), RadiusArc::Point);
    }

    #[test]
    fn sweep_and_extents_of_a_half_circle() {
        // G02 from X0 Y0 to X20 Y0 about X10 Y0: over the top, through X10 Y10
        let half = sweep((0.0, 0.0), (20.0, 0.0), (10.0, 0.0), true);
        assert!((half - PI).abs() < 1e-12);
        let [x, y] = extents((0.0, 0.0), (20.0, 0.0), (10.0, 0.0), true);
        assert_eq!((x, y), ((0.0, 20.0), (0.0, 10.0)));
        // G03 the same way round goes under
        let [_, y] = extents((0.0, 0.0), (20.0, 0.0), (10.0, 0.0), false);
        assert_eq!(y, (-10.0, 0.0));
        // a full circle reaches every quadrant point
        let [x, y] = extents((0.0, 0.0), (0.0, 0.0), (10.0, 0.0), true);
        assert_eq!((x, y), ((0.0, 20.0), (-10.0, 10.0)));
        // a quarter circle inside one quadrant adds none
        let [x, y] = extents((0.0, 0.0), (10.0, 10.0), (10.0, 0.0), true);
        assert_eq!((x, y), ((0.0, 10.0), (0.0, 10.0)));
    }
}
