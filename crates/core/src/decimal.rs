//! Exact decimal values: an integer count of a power-of-ten resolution, never a float.
//!
//! A word's value is `mantissa × 10^-scale`, as written: `X12.50` is 1250 at scale 2, and it
//! prints back as `12.50`, the way Python's `decimal.Decimal` does, so messages and statistics
//! read the same from either side. Sums (incremental positions) are exact. A number with more
//! significant digits than an `i128` holds (38) is refused, not rounded.
//!
//! This is the core's one module of exact arithmetic: beside [`Dec`], powers of ten, the
//! greatest common divisor of the converter's ratios, the digits of a count and its explicit
//! text, and [`Big`] and [`Ratio`], the integers of any size the diff compares products in.

use std::cmp::Ordering;
use std::fmt;

/// The most significant digits a value may have.
pub const MAX_DIGITS: usize = 38;

/// A value as written: `mantissa × 10^-scale`.
///
/// Packed to 8 bytes' alignment: an `i128` is aligned to 16, which made a value 32 bytes
/// (12 of them padding) and an `Option<Dec>` 48, and the checker copies dozens of them a
/// block (the modal state's positions, feeds and cycle words, the block's values, the words'
/// values). Packed, a value is 24 bytes and an `Option<Dec>` 32; the mantissa is read by value
/// (`{ d.mantissa }` where a reference is wanted: a reference to it would be unaligned).
#[derive(Debug, Clone, Copy)]
#[repr(C, packed(8))]
pub struct Dec {
    pub mantissa: i128,
    pub scale: u32,
}

// the sizes the layout above is for: a change that makes a value wider fails to build
const _: () = assert!(std::mem::size_of::<Dec>() == 24 && std::mem::size_of::<Option<Dec>>() == 32);

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

    /// `m` with `scale` digits after the decimal sign: what [`Dec::from_runs`] reads of digits
    /// whose value is `m` (their value read where they were scanned, `lex::Digits`). The scale
    /// is at most [`MAX_DIGITS`], as from_runs asks.
    pub fn from_u64(m: u64, scale: u32) -> Dec {
        debug_assert!(scale as usize <= MAX_DIGITS);
        Dec {
            mantissa: i128::from(m),
            scale,
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
        if whole.len() + fraction.len() <= 18 && scale as usize <= MAX_DIGITS {
            // a word's number: at most 18 digits fit a u64 whatever their zeros, so there is no
            // count of significant digits to make, and no i128 arithmetic
            let mut m: u64 = 0;
            for &d in whole {
                m = m * 10 + u64::from(d - b'0');
            }
            for &d in fraction {
                m = m * 10 + u64::from(d - b'0');
            }
            return Some(Dec {
                mantissa: i128::from(m),
                scale,
            });
        }
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
        let magnitude = self.mantissa.unsigned_abs();
        let log = match u64::try_from(magnitude) {
            Ok(small) => small.checked_ilog10(),
            Err(_) => magnitude.checked_ilog10(),
        };
        let digits = log.map_or(0, |log| log as usize + 1);
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

    /// The same value without the trailing zeros of its fraction (`12.500` -> `12.5`).
    pub fn normalized(self) -> Dec {
        let (mut mantissa, mut scale) = (self.mantissa, self.scale);
        // (in 64 bits where the mantissa fits, as nearly every one does: an i128 remainder
        // and quotient are calls of the runtime library; the checker asks it of every G word)
        if let Ok(mut small) = i64::try_from(mantissa) {
            while scale > 0 && small % 10 == 0 {
                small /= 10;
                scale -= 1;
            }
            return Dec {
                mantissa: i128::from(small),
                scale,
            };
        }
        while scale > 0 && mantissa % 10 == 0 {
            mantissa /= 10;
            scale -= 1;
        }
        Dec { mantissa, scale }
    }

    /// ``10.5`` -> ``10.5``, ``12.500`` -> ``12.5``, ``-0.001``, ``10`` (no exponent), as
    /// `formats.diff._plain`.
    pub fn plain(self) -> String {
        if self.mantissa == 0 {
            return "0".into();
        }
        let Dec { mantissa: m, scale } = self.normalized();
        let sign = if m < 0 { "-" } else { "" };
        let digits = m.unsigned_abs().to_string();
        let scale = scale as usize;
        if scale == 0 {
            format!("{sign}{digits}")
        } else if digits.len() > scale {
            let (whole, fraction) = digits.split_at(digits.len() - scale);
            format!("{sign}{whole}.{fraction}")
        } else {
            format!("{sign}0.{}{digits}", "0".repeat(scale - digits.len()))
        }
    }

    /// `|self|` as a ratio of integers: (mantissa, 10^scale).
    pub fn magnitude(self) -> (Big, Big) {
        (
            Big::from_u128(self.mantissa.unsigned_abs()),
            Big::pow10(self.scale),
        )
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
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Dec {
    /// Two values of one scale compared where they are asked (an arc's end against its
    /// start, a position against a limit: a call of about 28 instructions each); other scales
    /// out of line (`Dec::cmp_scales`).
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        if self.scale == other.scale {
            return { self.mantissa }.cmp(&{ other.mantissa });
        }
        self.cmp_scales(other)
    }
}

impl Dec {
    /// [`Dec::cmp`] of two values of different scales.
    #[inline(never)]
    fn cmp_scales(&self, other: &Self) -> Ordering {
        // Nearly every value compared is a word's or a position's: its mantissa fits an i64
        // and the scales differ by a few digits. An i64 times 10^18 at most fits an i128, so
        // no overflow check (and no i128 multiplication by the library) is needed then.
        if let (Ok(a), Ok(b)) = (i64::try_from(self.mantissa), i64::try_from(other.mantissa)) {
            let (a, b) = (i128::from(a), i128::from(b));
            return match self.scale.abs_diff(other.scale) {
                d if d > 18 => self.to_f64().total_cmp(&other.to_f64()),
                d if self.scale < other.scale => (a * POW10[d as usize]).cmp(&b),
                d => a.cmp(&(b * POW10[d as usize])),
            };
        }
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

/// `10^n`, or None past the 38 digits an `i128` holds.
pub fn pow10(n: u32) -> Option<i128> {
    POW10.get(n as usize).copied()
}

/// `q + r / d` (`0 <= r < d`) rounded to a whole number, half to even (or half up): the
/// whole number, and its distance from the exact value in `1 / d` (`r` or `d - r`).
pub fn round_quotient(q: i128, r: i128, d: i128, half_up: bool) -> (i128, i128) {
    let twice = 2 * r;
    if twice > d || (twice == d && (half_up || q & 1 == 1)) {
        (q + 1, d - r)
    } else {
        (q, r)
    }
}

/// The greatest common divisor of `a` and `b`, at least 1 (so that it always divides).
pub fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    if let (Ok(x), Ok(y)) = (u64::try_from(a), u64::try_from(b)) {
        return i128::from(gcd64(x, y).max(1));
    }
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

/// Binary GCD in 64 bits (no division).
fn gcd64(mut a: u64, mut b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

/// "00" "01" ... "99": the two digits of each number below 100, for [`digits_of`] (and the
/// G numbers of system A that `lex::GCodeSystem::token` writes).
pub(crate) static DIGIT_PAIRS: [u8; 200] = {
    let mut pairs = [0u8; 200];
    let mut i = 0;
    while i < 100 {
        pairs[2 * i] = b'0' + (i / 10) as u8;
        pairs[2 * i + 1] = b'0' + (i % 10) as u8;
        i += 1;
    }
    pairs
};

/// The decimal digits of `n`, in the tail of `buffer` (no allocation: every word's value goes
/// through here).
pub fn digits_of(n: u128, buffer: &mut [u8; 40]) -> &[u8] {
    let mut at = buffer.len();
    // (in 64 bits where the value fits, as every word's does: 128-bit division is slow; two
    // digits a step, from a table of the hundred pairs, half the steps of one at a time)
    if let Ok(mut small) = u64::try_from(n) {
        while small >= 100 {
            let pair = usize::from((small % 100) as u8) * 2;
            small /= 100;
            at -= 2;
            buffer[at..at + 2].copy_from_slice(&DIGIT_PAIRS[pair..pair + 2]);
        }
        if small >= 10 {
            let pair = usize::from(small as u8) * 2;
            at -= 2;
            buffer[at..at + 2].copy_from_slice(&DIGIT_PAIRS[pair..pair + 2]);
        } else {
            at -= 1;
            buffer[at] = b'0' + small as u8;
        }
        return &buffer[at..];
    }
    let mut n = n;
    loop {
        at -= 1;
        buffer[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            return &buffer[at..];
        }
    }
}

/// Explicit text of `u * 10^-after`: `12.5`, `0.03`, `10.`, `0`.
pub fn explicit(u: i128, after: u32) -> String {
    let mut out = Vec::with_capacity(24);
    explicit_into(&mut out, u, after);
    String::from_utf8(out).expect("ASCII digits")
}

/// [`explicit`], appended to `out`. Every explicit word the conversion writes comes here: the
/// fraction's trailing zeros are divided off first, then the text is written backwards into a
/// buffer on the stack (the fraction's digits, its zeros after the point, the point, the whole
/// part) and appended in one copy, without the digits' own buffer and four appends.
pub fn explicit_into(out: &mut Vec<u8>, u: i128, after: u32) {
    if u == 0 {
        out.push(b'0');
        return;
    }
    let after = after as usize;
    // (the sign, 39 digits and the point, and `after` digits of the fraction: on the stack
    // for every format a profile gives, on the heap past it)
    let mut stack = [0u8; 96];
    let mut heap = Vec::new();
    let buffer: &mut [u8] = if after <= 48 {
        &mut stack
    } else {
        heap.resize(after + 48, 0);
        &mut heap
    };
    let mut at = buffer.len();
    // (in 64 bits where the value fits, as every word's does: 128-bit division is slow)
    match u64::try_from(u.unsigned_abs()) {
        Ok(mut m) => {
            // (two digits a step from the table of pairs, as `digits_of`)
            let pair = |m: u64| {
                let at = (m % 100) as usize * 2;
                [DIGIT_PAIRS[at], DIGIT_PAIRS[at + 1]]
            };
            let mut fraction = after;
            while fraction > 0 && m.is_multiple_of(10) {
                m /= 10;
                fraction -= 1;
            }
            while fraction >= 2 {
                at -= 2;
                buffer[at..at + 2].copy_from_slice(&pair(m));
                m /= 100;
                fraction -= 2;
            }
            if fraction == 1 {
                at -= 1;
                buffer[at] = b'0' + (m % 10) as u8;
                m /= 10;
            }
            at -= 1;
            buffer[at] = b'.';
            while m >= 100 {
                at -= 2;
                buffer[at..at + 2].copy_from_slice(&pair(m));
                m /= 100;
            }
            if m >= 10 {
                at -= 2;
                buffer[at..at + 2].copy_from_slice(&pair(m));
            } else {
                at -= 1;
                buffer[at] = b'0' + m as u8;
            }
        }
        Err(_) => {
            let mut m = u.unsigned_abs();
            let mut fraction = after;
            while fraction > 0 && m.is_multiple_of(10) {
                m /= 10;
                fraction -= 1;
            }
            for _ in 0..fraction {
                at -= 1;
                buffer[at] = b'0' + (m % 10) as u8;
                m /= 10;
            }
            at -= 1;
            buffer[at] = b'.';
            loop {
                at -= 1;
                buffer[at] = b'0' + (m % 10) as u8;
                m /= 10;
                if m == 0 {
                    break;
                }
            }
        }
    }
    if u < 0 {
        at -= 1;
        buffer[at] = b'-';
    }
    out.extend_from_slice(&buffer[at..]);
}

/// A non-negative integer of any size, for exact comparisons of products (little-endian
/// 32-bit limbs).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Big(Vec<u32>);

impl Big {
    pub fn from_u128(mut v: u128) -> Big {
        let mut limbs = Vec::new();
        while v > 0 {
            limbs.push(v as u32);
            v >>= 32;
        }
        Big(limbs)
    }

    /// ASCII decimal digits (Python's `str(int)`); None for anything else.
    pub fn parse(text: &str) -> Option<Big> {
        if text.is_empty() || !text.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let mut big = Big(Vec::new());
        for b in text.bytes() {
            big = big.mul(&Big::from_u128(10));
            big = big.add_small((b - b'0') as u32);
        }
        Some(big)
    }

    pub fn to_u128(&self) -> Option<u128> {
        if self.0.len() > 4 {
            return None;
        }
        Some(
            self.0
                .iter()
                .rev()
                .fold(0u128, |acc, &limb| (acc << 32) | limb as u128),
        )
    }

    fn add_small(mut self, v: u32) -> Big {
        let mut carry = v as u64;
        for limb in self.0.iter_mut() {
            if carry == 0 {
                break;
            }
            let sum = *limb as u64 + carry;
            *limb = sum as u32;
            carry = sum >> 32;
        }
        if carry > 0 {
            self.0.push(carry as u32);
        }
        self
    }

    pub fn mul(&self, other: &Big) -> Big {
        let mut out = vec![0u32; self.0.len() + other.0.len()];
        for (i, &x) in self.0.iter().enumerate() {
            let mut carry = 0u64;
            for (j, &y) in other.0.iter().enumerate() {
                let t = out[i + j] as u64 + x as u64 * y as u64 + carry;
                out[i + j] = t as u32;
                carry = t >> 32;
            }
            let mut k = i + other.0.len();
            while carry > 0 {
                let t = out[k] as u64 + carry;
                out[k] = t as u32;
                carry = t >> 32;
                k += 1;
            }
        }
        while out.last() == Some(&0) {
            out.pop();
        }
        Big(out)
    }

    pub fn pow10(n: u32) -> Big {
        let mut big = Big::from_u128(1);
        let mut left = n;
        while left > 0 {
            let k = left.min(38);
            big = big.mul(&Big::from_u128(POW10[k as usize] as u128));
            left -= k;
        }
        big
    }
}

impl PartialOrd for Big {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Big {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0
            .len()
            .cmp(&other.0.len())
            .then_with(|| self.0.iter().rev().cmp(other.0.iter().rev()))
    }
}

/// A non-negative ratio `p / q` (q > 0), with both in 128 bits where they fit (the fast
/// path of every comparison).
#[derive(Debug, Clone)]
pub struct Ratio {
    pub p: Big,
    pub q: Big,
    /// `(p, q)` where both fit in 128 bits.
    pub small: Option<(u128, u128)>,
}

impl Ratio {
    pub fn new(p: Big, q: Big) -> Ratio {
        let small = p.to_u128().zip(q.to_u128());
        Ratio { p, q, small }
    }
}

/// Whether `a0 * a1 * a2 > b0 * b1 * b2`, or None where a product needs more than 128 bits.
pub fn greater(a: [u128; 3], b: [u128; 3]) -> Option<bool> {
    let left = a[0].checked_mul(a[1])?.checked_mul(a[2])?;
    let right = b[0].checked_mul(b[1])?.checked_mul(b[2])?;
    Some(left > right)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(text: &str) -> Dec {
        Dec::parse(text).unwrap()
    }

    /// `normalized` in 64 bits against the 128-bit reading it keeps for the rest: mantissas
    /// with 0 to 20 trailing zeros, both signs, 0, the bounds of `i64` and beyond, scales 0-38.
    #[test]
    fn a_value_is_normalized_in_64_bits_as_in_128() {
        fn wide(d: Dec) -> Dec {
            let (mut mantissa, mut scale) = (d.mantissa, d.scale);
            while scale > 0 && mantissa % 10 == 0 {
                mantissa /= 10;
                scale -= 1;
            }
            Dec { mantissa, scale }
        }
        let mut mantissas = vec![0i128, 1, 7, i128::from(i64::MAX), i128::from(i64::MIN)];
        mantissas.extend([
            i128::from(i64::MAX) + 1,
            i128::from(i64::MIN) - 10,
            i128::MAX,
        ]);
        for zeros in 0..=20u32 {
            for base in [1i128, 5, 12, 123_456_789] {
                if let Some(m) = base.checked_mul(10i128.pow(zeros)) {
                    mantissas.extend([m, -m]);
                }
            }
        }
        for &mantissa in &mantissas {
            for scale in 0..=38 {
                let d = Dec { mantissa, scale };
                let (got, want) = (d.normalized(), wide(d));
                assert_eq!(
                    (got.mantissa, got.scale),
                    (want.mantissa, want.scale),
                    "{d:?}"
                );
            }
        }
    }

    /// A value at the edges of its layout and of its 64-bit paths: the bounds of `i64` (read,
    /// added past, compared at other scales, truncated), 18 and 19 digits (the switch from the
    /// u64 reading to the i128 one), every scale 0 to 38 and none past it, 38 and 39 digits,
    /// and a negative zero as written (`-0.`, `-0.000`: zero at the scale written, no sign).
    /// Each read through `Option`s and a list, as the packed layout stores them.
    #[test]
    fn a_value_at_its_edges() {
        let (max, min) = (i128::from(i64::MAX), i128::from(i64::MIN));
        assert_eq!({ d("9223372036854775807").mantissa }, max);
        assert_eq!({ d("-9223372036854775808").mantissa }, min);
        assert_eq!({ d("9223372036854775808").mantissa }, max + 1);
        assert_eq!({ d("-9223372036854775809").mantissa }, min - 1);
        assert_eq!(d("922337203685477580.7").scale, 1);
        let past = d("9223372036854775807").checked_add(d("1")).unwrap();
        assert_eq!((past.mantissa, past.scale), (max + 1, 0));
        let below = d("-9223372036854775808").checked_add(d("-0.5")).unwrap();
        assert_eq!((below.mantissa, below.scale), (min * 10 - 5, 1));
        // the order's 64-bit path and its exact one meet at the bounds
        assert!(d("9223372036854775807") < d("9223372036854775807.1"));
        assert!(d("-9223372036854775808") > d("-9223372036854775808.01"));
        assert!(d("922337203685477580.7") < d("9223372036854775807"));
        assert!(d("9223372036854775807.000") == d("9223372036854775807"));
        assert_eq!(d("9223372036854775807.9").trunc(), i64::MAX);
        assert_eq!(d("-9223372036854775809").trunc(), i64::MIN);
        // 18 digits in a u64, 19 and more in an i128: the same value either way
        for count in [17, 18, 19, 20, 37, 38] {
            let digits = "9".repeat(count);
            let all = Dec::from_digits(digits.as_bytes(), 0).unwrap();
            assert_eq!({ all.mantissa }, 10i128.pow(count as u32) - 1, "{count}");
            let split = Dec::from_runs(&digits.as_bytes()[..3], &digits.as_bytes()[3..], 5);
            assert_eq!(
                split.map(|v| (v.mantissa, v.scale)),
                Some((all.mantissa, 5))
            );
            assert_eq!({ d(&format!("-{digits}")).mantissa }, -all.mantissa);
        }
        assert!(Dec::from_digits("9".repeat(39).as_bytes(), 0).is_none());
        assert!(Dec::parse(&"9".repeat(39)).is_none());
        // every scale an i128 holds, and none past it
        for scale in 0..=38u32 {
            let one = Dec::from_digits(b"1", scale).unwrap();
            assert_eq!((one.mantissa, one.scale), (1, scale));
            assert_eq!(Dec::from_u64(1, scale), one);
            assert_eq!(d(&format!("1E-{scale}")), one);
            let text = format!("0.{}1", "0".repeat(scale.saturating_sub(1) as usize));
            if scale > 0 {
                assert_eq!(d(&text).scale, scale, "{text}");
            }
        }
        assert!(Dec::from_digits(b"1", 39).is_none());
        assert!(Dec::parse(&format!("0.{}1", "0".repeat(38))).is_none());
        // a negative zero as written: zero at the scale written, equal to zero, no sign
        for (text, scale, shown) in [("-0.", 0, "0"), ("-0", 0, "0"), ("-0.000", 3, "0.000")] {
            let z = d(text);
            assert_eq!((z.mantissa, z.scale), (0, scale), "{text}");
            assert!(z == Dec::ZERO && z >= Dec::ZERO && z.is_whole(), "{text}");
            assert_eq!({ (-z).mantissa }, 0);
            assert_eq!(z.to_string(), shown);
        }
        // read back through Options and a list, whatever the alignment of their places
        let values = [
            d("-9223372036854775809"),
            d("1E-38"),
            d("-0.000"),
            d("12.5"),
        ];
        let kept: Vec<Option<Dec>> = values.iter().map(|&v| Some(v)).chain([None]).collect();
        for (v, k) in values.iter().zip(&kept) {
            let k = k.unwrap();
            assert_eq!(({ k.mantissa }, k.scale), ({ v.mantissa }, v.scale));
        }
        assert!(kept[4].is_none());
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

    #[test]
    fn the_fast_order_and_digits_agree_with_the_exact_ones() {
        // the order by rescaled i128 (checked), as every comparison was made before the fast
        // paths for equal scales and i64 mantissas
        let exact = |a: Dec, b: Dec| {
            let scale = a.scale.max(b.scale);
            match (a.rescaled(scale), b.rescaled(scale)) {
                (Some(x), Some(y)) => x.cmp(&y),
                _ => a.to_f64().total_cmp(&b.to_f64()),
            }
        };
        let mantissas = [
            0,
            1,
            -1,
            7,
            -12_345,
            999_999_999,
            i128::from(i64::MAX),
            i128::from(i64::MIN),
            i128::from(i64::MAX) + 1,
            -(10i128.pow(30)),
            10i128.pow(37),
        ];
        for &m in &mantissas {
            for &n in &mantissas {
                for s in [0, 1, 3, 4, 18, 19, 25, 38] {
                    for t in [0, 2, 4, 17, 20, 38] {
                        let (a, b) = (
                            Dec {
                                mantissa: m,
                                scale: s,
                            },
                            Dec {
                                mantissa: n,
                                scale: t,
                            },
                        );
                        assert_eq!(a.cmp(&b), exact(a, b), "{a:?} {b:?}");
                    }
                }
            }
            let a = Dec {
                mantissa: m,
                scale: 3,
            };
            let written = m.unsigned_abs().to_string().len();
            let whole = if m == 0 { 0 } else { written.saturating_sub(3) };
            assert_eq!(a.integer_digits(), whole, "{a:?}");
        }
    }

    #[test]
    fn a_quotient_rounds_half_to_even_or_up() {
        assert_eq!(round_quotient(2, 5, 10, false), (2, 5));
        assert_eq!(round_quotient(3, 5, 10, false), (4, 5));
        assert_eq!(round_quotient(2, 5, 10, true), (3, 5));
        assert_eq!(round_quotient(2, 4, 10, true), (2, 4));
        assert_eq!(round_quotient(2, 6, 10, false), (3, 4));
        assert_eq!(round_quotient(-3, 0, 10, false), (-3, 0));
    }

    #[test]
    fn explicit_text_of_a_count() {
        assert_eq!(explicit(125, 1), "12.5");
        assert_eq!(explicit(3, 2), "0.03");
        assert_eq!(explicit(10, 0), "10.");
        assert_eq!(explicit(-100, 2), "-1.");
        // written in place: the fraction's trailing zeros dropped, zeros after the point kept
        assert_eq!(explicit(1000, 2), "10.");
        assert_eq!(explicit(5, 3), "0.005");
        assert_eq!(explicit(120, 3), "0.12");
        assert_eq!(explicit(-1203, 2), "-12.03");
        assert_eq!(explicit(-7, 1), "-0.7");
        assert_eq!(explicit(123_456_000, 4), "12345.6");
        assert_eq!(
            explicit(i128::MIN + 1, 3),
            format!("-{}", the_text(i128::MAX, 3))
        );
        assert_eq!(explicit(7, 60), format!("0.{}7", "0".repeat(59)));
        assert_eq!(explicit(-70, 49), format!("-0.{}7", "0".repeat(47)));
        let mut buffer = [0u8; 40];
        assert_eq!(
            digits_of(u128::MAX, &mut buffer),
            u128::MAX.to_string().as_bytes()
        );
        assert_eq!(digits_of(0, &mut buffer), b"0");
    }

    /// The explicit text by the standard library's digits: the whole part, the point, the
    /// fraction without its trailing zeros.
    fn the_text(u: i128, after: u32) -> String {
        if u == 0 {
            return "0".to_string();
        }
        let digits = u.unsigned_abs().to_string();
        let after = after as usize;
        let padded = "0".repeat((after + 1).saturating_sub(digits.len())) + &digits;
        let (whole, fraction) = padded.split_at(padded.len() - after);
        let sign = if u < 0 { "-" } else { "" };
        format!("{sign}{whole}.{}", fraction.trim_end_matches('0'))
    }

    /// [`explicit`], written backwards in one pass, writes [`the_text`]: every value below
    /// 100,000 and each power of ten and its neighbours, signed, past 64 bits, at 0 to 40
    /// decimals and past the stack's buffer.
    #[test]
    fn explicit_text_is_the_digits_with_the_point_placed() {
        let mut values: Vec<i128> = (0..100_000).collect();
        // (10^38 times 3 or 10 is past i128: the powers up to 10^37, and i128's ends below)
        for k in 0..=37 {
            let p = 10i128.pow(k);
            values.extend([p - 1, p, p + 1, p * 3 + 7, p * 10 - 10]);
        }
        let top = i128::from(u64::MAX);
        values.extend([top - 1, top, top + 1, top * 10, i128::MAX, i128::MIN + 1]);
        for u in values {
            for after in (0..=40).chain([47, 48, 49, 60, 100]) {
                for u in [u, -u] {
                    assert_eq!(explicit(u, after), the_text(u, after), "{u} {after}");
                }
            }
        }
    }

    /// [`explicit_into`] (two digits a step in 64 bits) on drawn values: 300,000 of every
    /// size up to 64 bits and past it (a few bits, a power of ten's neighbours, numbers ending
    /// in zeros), signed, at 0-18 and 19-60 decimals, against [`the_text`], the standard
    /// library's digits.
    #[test]
    fn explicit_text_of_drawn_values_is_the_standard_digits() {
        let mut next = crate::drawn::xorshift(0x2545_F491_4F6C_DD1D);
        for _ in 0..300_000 {
            let r = next();
            let bits = (r % 66) as u32;
            let mut u = i128::from(next() >> (64 - bits.clamp(1, 64)));
            if bits == 65 {
                u = (u << 20) + i128::from(next() % 1_000_000);
            }
            match r >> 60 {
                0 => u *= 10i128.pow((r >> 8) as u32 % 6),
                1 => u = 10i128.pow((r >> 8) as u32 % 19) - (r >> 16) as i128 % 3 + 1,
                _ => {}
            }
            let after = if r & 0x80 == 0 {
                (r >> 24) as u32 % 19
            } else {
                (r >> 24) as u32 % 61
            };
            let u = if r & 0x100 == 0 { u } else { -u };
            let mut out = b"X".to_vec();
            explicit_into(&mut out, u, after);
            assert_eq!(out[1..], *the_text(u, after).as_bytes(), "{u} {after}");
        }
    }

    /// [`digits_of`], two digits a step, writes what `to_string` writes: every number below
    /// 100,000, each power of ten and its neighbours, the ends of 64 bits and past them.
    #[test]
    fn the_digits_of_a_number_are_its_text() {
        let mut values: Vec<u128> = (0..100_000).collect();
        for k in 0..=38 {
            let p = 10u128.pow(k);
            values.extend([p - 1, p, p + 1, p * 3 + 7]);
        }
        let top = u128::from(u64::MAX);
        values.extend([top - 1, top, top + 1, top * 10 + 9, u128::MAX]);
        let mut buffer = [0u8; 40];
        for n in values {
            assert_eq!(digits_of(n, &mut buffer), n.to_string().as_bytes(), "{n}");
        }
        assert_eq!((pow10(38), pow10(39)), (Some(POW10[38]), None));
    }

    #[test]
    fn binary_gcd_is_euclid() {
        fn euclid(mut a: u64, mut b: u64) -> u64 {
            while b != 0 {
                (a, b) = (b, a % b);
            }
            a
        }
        let values = [
            0u64,
            1,
            2,
            3,
            4,
            6,
            10,
            12,
            127,
            254,
            381,
            1000,
            1250,
            65536,
            1 << 40,
        ];
        for &a in &values {
            for &b in &values {
                assert_eq!(gcd64(a, b), euclid(a, b), "gcd({a}, {b})");
            }
        }
        assert_eq!(gcd(-12, 18), 6);
        assert_eq!(gcd(0, 0), 1);
        assert_eq!(gcd(i128::MAX, 3), 1);
    }

    #[test]
    fn big_products_compare_exactly() {
        let a = Big::parse("340282366920938463463374607431768211456").unwrap(); // 2^128
        let b = Big::from_u128(u128::MAX);
        assert!(a > b && a.cmp(&b) == Ordering::Greater);
        assert_eq!(
            a.mul(&Big::from_u128(3)),
            Big::parse("1020847100762815390390123822295304634368").unwrap()
        );
        assert_eq!(
            Big::pow10(40),
            Big::parse(&format!("1{}", "0".repeat(40))).unwrap()
        );
        assert!(Big::parse("12a").is_none() && Big::parse("").is_none());
    }

    #[test]
    fn plain_text_has_no_exponent_nor_trailing_zeros() {
        for (value, text) in [
            ("12.500", "12.5"),
            ("-0.0000001", "-0.0000001"),
            ("100", "100"),
            ("0.000", "0"),
            ("-3.10", "-3.1"),
        ] {
            assert_eq!(d(value).plain(), text);
        }
    }
}
