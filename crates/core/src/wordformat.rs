//! Word formats of ISO 6983-1 Annex C and how a word's digits are read.
//!
//! A decimal word (`X+053`: signed, 5.3, leading zeros omitted) has digits before and after
//! an implicit decimal sign; a count word (`N03`) has a largest number of digits. Reading an
//! implicit-decimal value depends on which zeros are omitted: leading zeros omitted means the
//! digits are right-aligned (`X1030` under 5.3 is 1.030), trailing zeros omitted means they
//! are left-aligned (`X1030` is 10300.000). A word with `.` is read as written, and in an
//! explicit-decimal program (DS) a word without `.` is a whole number (6.1). [`write()`] is the
//! other way: a count of `10^-after` in a format, as the converter and the diff write it.

use crate::decimal::{digits_of, explicit_into, Dec, MAX_DIGITS};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Zeros {
    Leading,
    Trailing,
    None,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WordFormat {
    pub address: u8,
    pub before: u32,
    pub after: u32,
    pub signed: bool,
    pub zeros: Zeros,
    /// A decimal (three-digit) spec rather than a count (two-digit) spec.
    pub decimal: bool,
}

impl WordFormat {
    pub fn width(&self) -> u32 {
        self.before + self.after
    }

    /// The canonical Annex C text of this format: `X+053`, `N03`.
    pub fn spec(&self) -> String {
        let sign = if self.signed { "+" } else { "" };
        let mut digits = if self.decimal {
            format!("{}{}", self.before, self.after)
        } else {
            format!("{}", self.before)
        };
        match self.zeros {
            Zeros::Leading => digits.insert(0, '0'),
            Zeros::Trailing => digits.push('0'),
            Zeros::None => {}
        }
        format!("{}{sign}{digits}", self.address as char)
    }

    /// The format tapegate reads an address with where a profile names none: counts for N,
    /// G, M and the like, 5.4 signed for the dimension words.
    pub fn fallback(letter: u8) -> WordFormat {
        let (before, after, signed, decimal) = match letter {
            b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'P' | b'Q' | b'R' | b'A' | b'B' | b'C'
            | b'I' | b'J' | b'K' | b'E' => (5, 4, true, true),
            b'F' => (5, 4, false, true),
            b'S' => (5, 3, false, true),
            _ => (9, 0, false, false),
        };
        WordFormat {
            address: letter,
            before,
            after,
            signed,
            zeros: Zeros::Leading,
            decimal,
        }
    }

    /// The exact value of a word written as `negative` + `number` (digits, maybe with `.`).
    ///
    /// `explicit_program`: the profile has DS, so a number without `.` is a whole number (6.1)
    /// -- or, with `increments`, a count of the format's least increment, as a Fanuc reads
    /// `X10000` at 0.001 mm (10.000 mm).
    pub fn read(
        &self,
        negative: bool,
        number: &[u8],
        explicit_program: bool,
        increments: bool,
    ) -> Result<Dec, String> {
        let too_many = || {
            format!(
                "{} digits: more than the {MAX_DIGITS} significant digits tapegate reads in a \
                 number",
                number.iter().filter(|b| b.is_ascii_digit()).count()
            )
        };
        let value = if let Some(dot) = number.iter().position(|&b| b == b'.') {
            let (whole, fraction) = (&number[..dot], &number[dot + 1..]);
            Dec::from_runs(whole, fraction, fraction.len() as u32).ok_or_else(too_many)?
        } else if let Some(scale) = self.scale_of_digits(number.len(), explicit_program, increments)
        {
            Dec::from_digits(number, scale).ok_or_else(too_many)?
        } else if explicit_program || !self.decimal {
            // no decimal sign, trailing zeros: the digits fill the format's whole part
            let mut padded = number.to_vec();
            padded.resize(self.before as usize, b'0');
            Dec::from_digits(&padded, 0).ok_or_else(too_many)?
        } else {
            // a decimal sign, trailing zeros: the digits fill the format's width
            let width = self.width() as usize;
            if number.len() > width {
                return Err(format!(
                    "{}{} has {} digits; the format {} holds {}",
                    self.address as char,
                    String::from_utf8_lossy(number),
                    number.len(),
                    self.spec(),
                    width
                ));
            }
            let mut padded = number.to_vec();
            padded.resize(width, b'0');
            Dec::from_digits(&padded, self.after).ok_or_else(too_many)?
        };
        Ok(if negative { -value } else { value })
    }

    /// How many of the `len` digits of a number written without a point [`WordFormat::read`]
    /// counts after the decimal sign, where it reads them as they are written; None where it
    /// pads them with the trailing zeros the format leaves out. Written once, for `read` and for [`crate::word::Numbers::read`], which
    /// has the digits' value already.
    pub fn scale_of_digits(
        &self,
        len: usize,
        explicit_program: bool,
        increments: bool,
    ) -> Option<u32> {
        let trailing = self.zeros == Zeros::Trailing;
        let scale = if increments && self.decimal {
            self.after
        } else if explicit_program || !self.decimal {
            if !self.decimal && trailing && len < self.before as usize {
                return None;
            }
            0
        } else if trailing {
            return None;
        } else {
            self.after
        };
        Some(scale)
    }
}

/// The digits after the address of the value `u * 10^-after` in the target format.
pub fn write(u: i128, after: u32, fmt: &WordFormat, explicit_out: bool, plus: bool) -> String {
    let mut out = Vec::with_capacity(24);
    write_into(&mut out, u, after, fmt, explicit_out, plus);
    String::from_utf8(out).expect("ASCII digits")
}

/// A whole code (`G55`, the `55` as `n`) as a format with no decimal sign and decimals reads
/// it: `G031` counts tenths, so G55 is written `G550` (a code with decimals, `G91.1`, is
/// `G911`). `None` where the format writes the code as it is (a decimal sign, no decimals).
pub fn implicit_code(letter: u8, n: i128, fmt: &WordFormat, explicit: bool) -> Option<Vec<u8>> {
    if explicit || !fmt.decimal || fmt.after == 0 {
        return None;
    }
    let mut out = vec![letter];
    write_into(
        &mut out,
        n * 10i128.pow(fmt.after),
        fmt.after,
        fmt,
        false,
        false,
    );
    Some(out)
}

/// [`write()`], appended to `out`.
pub fn write_into(
    out: &mut Vec<u8>,
    u: i128,
    after: u32,
    fmt: &WordFormat,
    explicit_out: bool,
    plus: bool,
) {
    if explicit_out && fmt.decimal {
        if plus && u > 0 {
            out.push(b'+');
        }
        explicit_into(out, u, after);
        return;
    }
    if u == 0 {
        out.push(b'0');
        return;
    }
    if u < 0 {
        out.push(b'-');
    } else if plus {
        out.push(b'+');
    }
    let mut buffer = [0u8; 40];
    let digits = digits_of(u.unsigned_abs(), &mut buffer);
    if fmt.zeros == Zeros::Leading {
        out.extend_from_slice(digits);
        return;
    }
    let width = if fmt.decimal { fmt.width() } else { fmt.before } as usize;
    let from = out.len();
    if digits.len() < width {
        out.resize(from + width - digits.len(), b'0');
    }
    out.extend_from_slice(digits);
    if fmt.zeros == Zeros::Trailing {
        while out.len() > from && out[out.len() - 1] == b'0' {
            out.pop();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fmt(before: u32, after: u32, zeros: Zeros) -> WordFormat {
        WordFormat {
            address: b'X',
            before,
            after,
            signed: true,
            zeros,
            decimal: true,
        }
    }

    #[test]
    fn implicit_digits_by_zero_suppression() {
        let leading = fmt(5, 3, Zeros::Leading);
        assert_eq!(
            leading
                .read(false, b"1030", false, false)
                .unwrap()
                .to_string(),
            "1.030"
        );
        assert_eq!(
            leading
                .read(false, b"1030", true, false)
                .unwrap()
                .to_string(),
            "1030"
        );
        assert_eq!(
            leading
                .read(true, b"1.5", false, false)
                .unwrap()
                .to_string(),
            "-1.5"
        );
        let trailing = fmt(4, 3, Zeros::Trailing);
        assert_eq!(
            trailing
                .read(false, b"00103", false, false)
                .unwrap()
                .to_string(),
            "10.300"
        );
        assert_eq!(
            trailing
                .read(false, b"1030", false, false)
                .unwrap()
                .to_string(),
            "1030.000"
        );
        assert!(trailing
            .read(false, b"12345678", false, false)
            .unwrap_err()
            .contains("holds 7"));
        assert_eq!(leading.spec(), "X+053");
        assert_eq!(trailing.spec(), "X+430");
    }

    #[test]
    fn a_fanuc_reads_a_word_without_a_point_in_least_increments() {
        let x = fmt(5, 3, Zeros::Leading);
        assert_eq!(
            x.read(false, b"10000", true, true).unwrap().to_string(),
            "10.000"
        );
        assert_eq!(
            x.read(true, b"10", true, true).unwrap().to_string(),
            "-0.010"
        );
        assert_eq!(x.read(false, b"10.", true, true).unwrap().to_string(), "10");
    }

    #[test]
    fn huge_numbers_are_refused_with_the_limit() {
        let long = vec![b'9'; 60_000];
        let e = fmt(5, 3, Zeros::Leading)
            .read(false, &long, true, false)
            .unwrap_err();
        assert!(e.contains("60000 digits") && e.contains("38"), "{e}");
    }

    #[test]
    fn numbers_are_written_in_the_target_format() {
        assert_eq!(
            write(1030, 3, &fmt(5, 3, Zeros::Leading), false, false),
            "1030"
        );
        assert_eq!(
            write(10300, 3, &fmt(4, 3, Zeros::Trailing), false, false),
            "00103"
        );
        assert_eq!(
            write(125, 1, &fmt(5, 3, Zeros::Leading), true, true),
            "+12.5"
        );
    }
}
