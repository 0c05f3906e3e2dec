//! Exact decimal values: an integer count of a power-of-ten resolution, never a float.
//!
//! A word's value is `mantissa × 10^-scale`, as written: `X12.50` is 1250 at scale 2, and it
//! prints back as `12.50`, the way Python's `decimal.Decimal` does, so messages and statistics
//! read the same from either side. Sums (incremental positions) are exact. A number with more
//! significant digits than an `i128` holds (38) is refused, not rounded.

use std::cmp::Ordering;
use std::fmt;

/// The most significant digits a value may have.
pub const MAX_DIGITS: usize = 38;

#[derive(Debug, Clone, Copy)]
pub struct Dec {
    pub mantissa: i128,
    pub scale: u32,
}

/// 10^0 to 10^38: every power of ten an `i128` holds.
pub const POW10: [i128; 39] = {
    let mut t = [1i128; 39];
    let mut i = 1;
    while i < 39 {
        t[i] = t[i - 1] * 10;
        i += 1;
    }
    t
};

impl Dec {
    pub const ZERO: Dec = Dec {
        mantissa: 0,
        scale: 0,
    };

    pub fn from_int(value: i128) -> Dec {
        Dec {
            mantissa: value,
            scale: 0,
        }
    }

    /// The value of ASCII `digits` (no sign) with `scale` of them after the decimal sign, or
    /// None when it has more than [`MAX_DIGITS`] significant digits.
    pub fn from_digits(digits: &[u8], scale: u32) -> Option<Dec> {
        Dec::from_runs(digits, b"", scale)
    }

    /// The value of the ASCII digits of `whole` followed by those of `fraction` (the two
    /// sides of a decimal sign, read where they stand, without copying them), with `scale`
    /// digits after the decimal sign; None past [`MAX_DIGITS`] significant digits.
    pub fn from_runs(whole: &[u8], fraction: &[u8], scale: u32) -> Option<Dec> {
        let lead = whole.iter().take_while(|&&d| d == b'0').count();
        let significant = if lead < whole.len() {
            whole.len() - lead + fraction.len()
        } else {
            fraction.iter().skip_while(|&&d| d == b'0').count()
        };
        if significant > MAX_DIGITS || scale as usize > MAX_DIGITS {
            return None;
        }
        let digits = whole.iter().chain(fraction);
        if significant <= 18 {
            // fewer than 19 significant digits: the value fits a u64 whatever the zeros before
            let mut m: u64 = 0;
            for &d in digits {
                m = m * 10 + u64::from(d - b'0');
            }
            return Some(Dec {
                mantissa: i128::from(m),
                scale,
            });
        }
        let mut m: i128 = 0;
        for &d in digits {
            m = m.checked_mul(10)?.checked_add((d - b'0') as i128)?;
        }
        Some(Dec { mantissa: m, scale })
    }

    /// Text as Python's `Decimal(text)` reads it: `12.5`, `.5`, `12.`, `-3`, `1E-7`.
    pub fn parse(text: &str) -> Option<Dec> {
        let (negative, body) = match text.as_bytes().first() {
            Some(b'-') => (true, &text[1..]),
            Some(b'+') => (false, &text[1..]),
            _ => (false, text),
        };
        let (body, exponent) = match body.find(['E', 'e']) {
            Some(at) => (&body[..at], body[at + 1..].parse::<i32>().ok()?),
            None => (body, 0),
        };
        let (whole, fraction) = body.split_once('.').unwrap_or((body, ""));
        let (whole, fraction) = (whole.as_bytes(), fraction.as_bytes());
        if whole.len() + fraction.len() == 0
            || !whole.iter().chain(fraction).all(u8::is_ascii_digit)
        {
            return None;
        }
        let scale = fraction.len() as i32 - exponent;
        let value = if scale >= 0 {
            Dec::from_runs(whole, fraction, scale as u32)?
        } else {
            let d = Dec::from_runs(whole, fraction, 0)?;
            Dec {
                mantissa: d.mantissa.checked_mul(*POW10.get((-scale) as usize)?)?,
                scale: 0,
            }
        };
        Some(if negative { -value } else { value })
    }

    pub fn abs(self) -> Dec {
        Dec {
            mantissa: self.mantissa.abs(),
            scale: self.scale,
        }
    }

    fn rescaled(self, scale: u32) -> Option<i128> {
        self.mantissa
            .checked_mul(*POW10.get((scale - self.scale) as usize)?)
    }

    /// The exact sum, at the finer of the two scales (as `Decimal` adds); None on overflow.
    pub fn checked_add(self, other: Dec) -> Option<Dec> {
        let scale = self.scale.max(other.scale);
        let m = self.rescaled(scale)?.checked_add(other.rescaled(scale)?)?;
        Some(Dec { mantissa: m, scale })
    }

    /// The exact product (its scale the sum of the two, as `Decimal` multiplies); None on
    /// overflow or beyond [`MAX_DIGITS`] decimals.
    pub fn checked_mul(self, other: Dec) -> Option<Dec> {
        let scale = self.scale + other.scale;
        if scale as usize > MAX_DIGITS {
            return None;
        }
        let mantissa = self.mantissa.checked_mul(other.mantissa)?;
        Some(Dec { mantissa, scale })
    }

    /// The value truncated toward zero, as Python's `int(Decimal)`, saturated to `i64`.
    pub fn trunc(self) -> i64 {
        if self.scale == 0 {
            return self.mantissa.clamp(i64::MIN as i128, i64::MAX as i128) as i64;
        }
        if let Ok(small) = i64::try_from(self.mantissa) {
            if self.scale < 19 {
                return small / POW10[self.scale as usize] as i64;
            }
        }
        let whole = self.mantissa / POW10[self.scale as usize];
        whole.clamp(i64::MIN as i128, i64::MAX as i128) as i64
    }

    /// The number of digits of the whole part of `|value|` when it is at least 1, else 0.
    pub fn integer_digits(self) -> usize {
        // the digits of the mantissa less those after the point (no division: a word's
        // value is asked this for every word)
        let digits = self
            .mantissa
            .unsigned_abs()
            .checked_ilog10()
            .map_or(0, |log| log as usize + 1);
        digits.saturating_sub(self.scale as usize)
    }

    pub fn to_f64(self) -> f64 {
        const SCALES: [f64; 10] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];
        if let (Ok(m), Some(&s)) = (
            i64::try_from(self.mantissa),
            SCALES.get(self.scale as usize),
        ) {
            return m as f64 / s;
        }
        self.mantissa as f64 / 10f64.powi(self.scale as i32)
    }

    /// Whether the value has no fractional part (`91`, `91.0`; not `91.1`).
    pub fn is_whole(self) -> bool {
        if self.scale == 0 {
            return true;
        }
        // (a 64-bit remainder where the value fits: i128 division is a library call)
        if let Ok(small) = i64::try_from(self.mantissa) {
            if self.scale < 19 {
                return small % POW10[self.scale as usize] as i64 == 0;
            }
        }
        self.mantissa % POW10[self.scale as usize] == 0
    }

    pub fn is_zero(self) -> bool {
        self.mantissa == 0
    }

    pub fn eq_int(self, value: i64) -> bool {
        if self.scale == 0 {
            return self.mantissa == i128::from(value);
        }
        self.cmp(&Dec::from_int(value as i128)) == Ordering::Equal
    }
}

impl std::ops::Neg for Dec {
    type Output = Dec;

    fn neg(self) -> Dec {
        Dec {
            mantissa: -self.mantissa,
            scale: self.scale,
        }
    }
}

impl PartialEq for Dec {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Dec {}

impl PartialOrd for Dec {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Dec {
    fn cmp(&self, other: &Self) -> Ordering {
        let scale = self.scale.max(other.scale);
        match (self.rescaled(scale), other.rescaled(scale)) {
            (Some(a), Some(b)) => a.cmp(&b),
            // One side does not fit at the finer scale: compare as floats (far apart anyway).
            _ => self.to_f64().total_cmp(&other.to_f64()),
        }
    }
}

impl fmt::Display for Dec {
    /// As `str(Decimal)`: plain notation unless the value is smaller than 1E-6 in magnitude.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sign = if self.mantissa < 0 { "-" } else { "" };
        let digits = self.mantissa.unsigned_abs().to_string();
        let scale = self.scale as usize;
        if scale == 0 {
            return write!(f, "{sign}{digits}");
        }
        let adjusted = digits.len() as i64 - 1 - scale as i64;
        if adjusted < -6 {
            let (head, tail) = digits.split_at(1);
            let dot = if tail.is_empty() { "" } else { "." };
            return write!(f, "{sign}{head}{dot}{tail}E{adjusted}");
        }
        if digits.len() > scale {
            let (whole, fraction) = digits.split_at(digits.len() - scale);
            write!(f, "{sign}{whole}.{fraction}")
        } else {
            write!(f, "{sign}0.{}{digits}", "0".repeat(scale - digits.len()))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(text: &str) -> Dec {
        Dec::parse(text).unwrap()
    }

    #[test]
    fn digits_read_in_place_as_when_joined() {
        // the 64-bit path (up to 18 significant digits, any zeros before) and the 128-bit one
        let cases: [(&[u8], &[u8]); 7] = [
            (b"12", b"5"),
            (b"000000000000000000000012", b"50"),
            (b"0", b"0000000000000000000001"),
            (b"999999999999999999", b""),
            (b"9999999999999999999", b"9"),
            (b"", b"5"),
            (b"12345678901234567890123456789012345678", b""),
        ];
        for (whole, fraction) in cases {
            let joined = [whole, fraction].concat();
            let mut slow: i128 = 0;
            for &d in &joined {
                slow = slow * 10 + i128::from(d - b'0');
            }
            let scale = fraction.len() as u32;
            let read = Dec::from_runs(whole, fraction, scale).unwrap();
            assert_eq!((read.mantissa, read.scale), (slow, scale));
            assert_eq!(Dec::from_digits(&joined, scale), Some(read));
        }
        assert!(Dec::from_runs(b"123456789012345678901234567890123456789", b"", 0).is_none());
        assert_eq!(d("12.50").integer_digits(), 2);
        assert_eq!(d("-0.5").integer_digits(), 0);
        assert!(d("3.000").is_whole() && !d("3.001").is_whole() && d("-2.0").eq_int(-2));
    }

    #[test]
    fn prints_as_python_decimal() {
        for text in ["12.50", "0.030", "-3", "1.030", "0.000001", "12", "-0.5"] {
            assert_eq!(d(text).to_string(), text);
        }
        assert_eq!(d("12.").to_string(), "12");
        assert_eq!(d(".5").to_string(), "0.5");
        assert_eq!(d("0.0000001").to_string(), "1E-7");
        assert_eq!(d("0.00000012").to_string(), "1.2E-7");
    }

    #[test]
    fn exact_arithmetic_and_order() {
        assert_eq!(d("1.5").checked_add(d("2.25")).unwrap().to_string(), "3.75");
        assert!(d("10.000") == d("10"));
        assert!(d("-508") < d("15."));
        assert_eq!(d("-91.9").trunc(), -91);
        assert_eq!(d("999.5").integer_digits(), 3);
        assert_eq!(d("0.5").integer_digits(), 0);
        assert!(Dec::from_digits(&[b'9'; 39], 0).is_none());
        assert!(Dec::from_digits(&[b'0'; 60], 0).is_some());
    }
}
