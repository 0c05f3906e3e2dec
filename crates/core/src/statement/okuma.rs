//! The statements of an Okuma OSP control (OSP-P200/P300 programming manuals; docs/dialects.md),
//! read beside the words of ISO 6983-1:
//!
//! - the program's first line, `$NAME.MIN%` (a file name and its `%`), as a name statement; a
//!   `$` before a line's words continues the block before it (the LAP's condition changes);
//! - a sequence name, `N` and a letter (`NDTM8`, `NAT00`): a jump label, before the block's
//!   words (`NM64 M64`); `N0100` stays a sequence number;
//! - a program name `O` and a letter (`OSTRT`, the subprogram `OCHCK`);
//! - `IF [VC1 EQ 20] NDTM8` and `GOTO NDTM`: jumps to a sequence name;
//! - `CALL OCHCK DRIV=88.5`, `MODIN`/`MODOUT`: calls, with their arguments to the end of the
//!   block; `RTS` returns from a subprogram;
//! - variables by name, common (`VC1`, `VC32=1`), system (`VTOFD[1]`, `VGRIN[1]=1`) or the
//!   program's own (`PRES=1`, `FLAN=318`, `TL2=0404`): an assignment; an address set by an
//!   expression (`X=FLAN+5`, `H=VC32`, `T=TL7`) is a word whose value is not known here;
//! - the lathe's contour definition for the LAP cycles (`DEF WORK`, `PT ...`, `END`, `CLEAR`,
//!   `DRAW`), and the mill's hole patterns (`BHC`, `LAA`, `ARC`, `GRDX`, `SQRX`...): commands
//!   to the end of the block.
//!
//! - user task arithmetic: a value is operands joined by `+ - * /` with blanks between them
//!   (`CNTR = CNTR + 1`, `VC81 = VTOHT [[VC100],10001]`), or a string (`VUACM[1]='TEXT'`, the
//!   user alarm message); `WHILE [..] DO n`, `DO n` and `END n` loops (as Custom Macro B).
//!
//! Conditions and values are kept as text (the checker does not evaluate OSP expressions).

use super::{brackets, digits_end, ident_end, rest_end, statement, word, Kind, Read};
use crate::expr::{self, skip_blanks};
use crate::lex::{err, Dialect, ErrorKind, LexError, Token};

const CLAUSE: &str = "Okuma OSP";

/// Read an OSP statement (or a word `X=expression`) at `pos`, or None to leave `pos` to the word
/// reader.
pub fn read<'a>(
    line: &'a [u8],
    pos: usize,
    dialect: &Dialect,
    words: &mut Vec<Token<'a>>,
) -> Result<Option<Read>, LexError> {
    let b = line[pos];
    if b == b'$' {
        // $OKUMA.SSB%: the file's name; a `$` before the words of a line continues the block
        // of the line before it (a LAP call's cutting condition changes)
        let end = rest_end(line, pos, dialect, true);
        if line[..end].ends_with(b"%") {
            return Ok(statement(pos, end, Kind::Name));
        }
        return Ok(statement(pos, pos + 1, Kind::Command));
    }
    if !b.is_ascii_uppercase() {
        return Ok(None);
    }
    let end = ident_end(line, pos);
    let name = &line[pos..end];
    let after = skip_blanks(line, end);
    // (OG=1, a variable, is not a program name)
    let named = name.len() > 1 && name[1].is_ascii_uppercase() && line.get(after) != Some(&b'=');
    if named && b == b'N' {
        return Ok(statement(pos, end, Kind::Label));
    }
    // a program name is O and alphanumerics, a letter anywhere after the O (`OSTRT`,
    // `O12A`, `O1A2`; OSP-P200L Programming Manual 5238-E, "Program name": O and up to four
    // alphanumeric characters); `O1234`, digits only, is the O word
    let lettered = name.len() > 1 && name[1..].iter().any(u8::is_ascii_uppercase);
    if b == b'O' && lettered && line.get(after) != Some(&b'=') {
        return Ok(statement(pos, end, Kind::Name));
    }
    match name {
        b"IF" => {
            if line.get(after) != Some(&b'[') {
                return Err(osp_error(
                    "IF must be followed by a condition in [ ]",
                    after,
                ));
            }
            let close = brackets(line, after)?;
            let target = skip_blanks(line, close);
            let label = label_end(line, target)
                .ok_or_else(|| osp_error("IF [..] must be followed by a sequence name", target))?;
            return Ok(statement(pos, label, Kind::Flow));
        }
        b"GOTO" => {
            let label = label_end(line, after)
                .ok_or_else(|| osp_error("GOTO must be followed by a sequence name", after))?;
            return Ok(statement(pos, label, Kind::Flow));
        }
        b"CALL" | b"MODIN" | b"MODOUT" => {
            return Ok(statement(
                pos,
                rest_end(line, pos, dialect, true),
                Kind::Call,
            ));
        }
        // WHILE [cond] DO n ... END n, and DO n ... END n (a loop without a condition): the
        // Custom Macro B loop, as OSP-P500 programs write it (not in the OSP sources at hand;
        // read, not endorsed: docs/dialects.md)
        b"WHILE" => {
            if line.get(after) != Some(&b'[') {
                return Err(osp_error(
                    "WHILE must be followed by a condition in [ ]",
                    after,
                ));
            }
            let close = brackets(line, after)?;
            let p = skip_blanks(line, close);
            let word = ident_end(line, p);
            let number = skip_blanks(line, word);
            let digits = digits_end(line, number);
            if &line[p..word] != b"DO" || digits == number {
                return Err(osp_error(
                    "WHILE [condition] must be followed by DO and the loop's number",
                    p,
                ));
            }
            return Ok(statement(pos, digits, Kind::Flow));
        }
        b"DO" | b"END" if digits_end(line, after) > after => {
            return Ok(statement(pos, digits_end(line, after), Kind::Flow));
        }
        b"RTS" | b"CLEAR" | b"DRAW" | b"END" => return Ok(statement(pos, end, Kind::Command)),
        // the coordinate calculation functions: bolt hole circle, line at angle, arc, grid
        // (BHC X Y I J K, LAA X Y I J K ..., ARC, GRDX/GRDY, SQRX/SQRY): hole patterns for the
        // fixed cycle in force, with their words
        b"BHC" | b"LAA" | b"ARC" | b"GRDX" | b"GRDY" | b"SQRX" | b"SQRY" | b"DEF" | b"PT" => {
            return Ok(statement(
                pos,
                rest_end(line, pos, dialect, true),
                Kind::Command,
            ));
        }
        _ => {}
    }
    let assigned = match line.get(after) {
        Some(b'=') => Some(after + 1),
        Some(b'[') if name.len() > 1 => {
            let close = brackets(line, after)?;
            let eq = skip_blanks(line, close);
            (line.get(eq) == Some(&b'=')).then_some(eq + 1)
        }
        _ => None,
    };
    let Some(value) = assigned else {
        // a name of two letters or more is no word (an address is one letter): an OSP
        // command of its own (TLID)
        if name.len() > 1 && name[1].is_ascii_uppercase() {
            return Ok(statement(pos, end, Kind::Command));
        }
        return Ok(None);
    };
    let first = skip_blanks(line, value);
    if matches!(line.get(first), None | Some(b'(')) {
        return Err(osp_error("'=' must be followed by a value", value));
    }
    let value_end = value_end(line, first, dialect)?;
    if name.len() == 1 {
        // X=FLAN+5: the address's value is an expression
        return Ok(Some(word(line, pos, value_end, words)));
    }
    Ok(statement(pos, value_end, Kind::Assignment))
}

/// `RTS`: the statement that returns from an OSP subprogram.
pub fn returns(text: &[u8]) -> bool {
    text == b"RTS"
}

/// The end of a sequence name at `pos` (`N` and letters or digits), or None.
fn label_end(line: &[u8], pos: usize) -> Option<usize> {
    (line.get(pos) == Some(&b'N'))
        .then(|| ident_end(line, pos + 1).max(digits_end(line, pos + 1)))
        .filter(|&end| end > pos + 1)
}

/// The end of a value at `pos`, read by the shared expression reader ([`expr::scan`], with
/// the OSP's names as operands: `CNTR + 1`, `MROT = PRS + [ROT * [PINS - 1]]`, `VC[PNTR + 1]`,
/// `VTOHT [[VC100],10001]`), or a quoted string (`'TEXT'`, the user alarm message). An operand
/// missing (`VC1 = * 3`, `CNTR = CNTR +`) is the reader's located error, as on a Fanuc; so is a
/// second operand after the value with no operator between (`VC1 = VC2 VC3`, `VC1 = VC2 3`):
/// what may follow a value is a comment, the next word (`X80`) or the next assignment
/// (`VTSL=82`).
fn value_end(line: &[u8], pos: usize, dialect: &Dialect) -> Result<usize, LexError> {
    let end = if line.get(pos) == Some(&b'\'') {
        let close = line[pos + 1..]
            .iter()
            .position(|&c| c == b'\'')
            .ok_or_else(|| osp_error("a string ' without its closing '", pos))?;
        pos + close + 2
    } else {
        expr::scan(line, pos, dialect.syntax())?
    };
    // glued or after blanks alike: `VC1=[VC2]VC3`, `VC1='AB'VC2` lose no operand
    let next = skip_blanks(line, end);
    if operand_follows(line, next)? {
        return Err(osp_error(
            "two operands without an operator between them",
            next,
        ));
    }
    Ok(end)
}

/// Whether what stands at `pos`, after a value (and any blanks), is another operand of it rather
/// than the block's next word or statement: a number, a bracket, a string, or a name of two
/// letters or more that is not assigned (`VC3`, not `VTSL=82` nor `VGRIN[1]=1`).
fn operand_follows(line: &[u8], pos: usize) -> Result<bool, LexError> {
    let Some(&b) = line.get(pos) else {
        return Ok(false);
    };
    if b.is_ascii_digit() || matches!(b, b'[' | b'\'' | b'.' | b'#') {
        return Ok(true);
    }
    let end = ident_end(line, pos);
    if end - pos < 2 || !line[pos + 1].is_ascii_uppercase() {
        return Ok(false);
    }
    let mut after = skip_blanks(line, end);
    if line.get(after) == Some(&b'[') {
        after = skip_blanks(line, brackets(line, after)?);
    }
    Ok(line.get(after) != Some(&b'='))
}

fn osp_error(message: &str, offset: usize) -> LexError {
    err(ErrorKind::Value, message.into(), offset, CLAUSE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lex::Family;
    use crate::tokenizer::tokenize;

    fn statements(text: &str) -> Vec<(String, Kind)> {
        let dialect = Dialect {
            family: Family::Okuma,
            brackets: true,
            star: true,
            expressions: true,
            ..Dialect::default()
        };
        let mut words = Vec::new();
        let extras = tokenize(text.as_bytes(), &dialect, &mut words).expect("readable");
        extras
            .map(|e| {
                e.statements
                    .iter()
                    .map(|s| {
                        (
                            String::from_utf8_lossy(&text.as_bytes()[s.offset..s.end]).into_owned(),
                            s.kind,
                        )
                    })
                    .collect()
            })
            .unwrap_or_default()
    }

    #[test]
    fn osp_statements() {
        assert_eq!(
            statements("$OKUMA.SSB%"),
            [("$OKUMA.SSB%".into(), Kind::Name)]
        );
        assert_eq!(statements("OSTRT"), [("OSTRT".into(), Kind::Name)]);
        assert_eq!(statements("O12A"), [("O12A".into(), Kind::Name)]);
        assert_eq!(statements("O1A2 (NAME)"), [("O1A2".into(), Kind::Name)]);
        assert!(statements("O1234").is_empty());
        assert_eq!(statements("$ X40 D2"), [("$".into(), Kind::Command)]);
        assert_eq!(statements("NDTM8"), [("NDTM8".into(), Kind::Label)]);
        assert_eq!(
            statements("IF [FIX[VC2/7000] EQ 1] NNF80"),
            [("IF [FIX[VC2/7000] EQ 1] NNF80".into(), Kind::Flow)]
        );
        assert_eq!(
            statements("IF[PRES EQ 1]NM59"),
            [("IF[PRES EQ 1]NM59".into(), Kind::Flow)]
        );
        assert_eq!(statements("GOTO N1"), [("GOTO N1".into(), Kind::Flow)]);
        assert_eq!(
            statements("N0103 CALL OSETZ DRIV=88.5 (SET)"),
            [("CALL OSETZ DRIV=88.5".into(), Kind::Call)]
        );
        assert_eq!(
            statements("VGRIN[1]=1 VTSL=82"),
            [
                ("VGRIN[1]=1".into(), Kind::Assignment),
                ("VTSL=82".into(), Kind::Assignment)
            ]
        );
        assert_eq!(
            statements("NWF80 VC32=1"),
            [
                ("NWF80".into(), Kind::Label),
                ("VC32=1".into(), Kind::Assignment)
            ]
        );
        assert_eq!(statements("RTS"), [("RTS".into(), Kind::Command)]);
        assert_eq!(statements("N1130 TLID"), [("TLID".into(), Kind::Command)]);
        assert_eq!(
            statements("N0204 X80 TG=01 OG=1"),
            [
                ("TG=01".into(), Kind::Assignment),
                ("OG=1".into(), Kind::Assignment)
            ]
        );
        assert_eq!(
            statements("BHC X=XPOS Y=YPOS I35 J45 K4"),
            [("BHC X=XPOS Y=YPOS I35 J45 K4".into(), Kind::Command)]
        );
        assert_eq!(
            statements("PT LF,LC,[0,0],[80,80]"),
            [("PT LF,LC,[0,0],[80,80]".into(), Kind::Command)]
        );
        // user task arithmetic without brackets around the whole value, an index after a
        // blank, a string for the user alarm message
        assert_eq!(
            statements("CNTR = CNTR + 1 (NEXT)"),
            [("CNTR = CNTR + 1".into(), Kind::Assignment)]
        );
        assert_eq!(
            statements("MROT = PRS + [ROT * [PINS - 1]]"),
            [("MROT = PRS + [ROT * [PINS - 1]]".into(), Kind::Assignment)]
        );
        assert_eq!(
            statements("VC81 = VTOHT [[VC100],10001] (HEIGHT)"),
            [("VC81 = VTOHT [[VC100],10001]".into(), Kind::Assignment)]
        );
        assert_eq!(
            statements("VUACM[1]='TOOL # 2 = 0.5 (MAX)' VDOUT[993]=9001"),
            [
                ("VUACM[1]='TOOL # 2 = 0.5 (MAX)'".into(), Kind::Assignment),
                ("VDOUT[993]=9001".into(), Kind::Assignment)
            ]
        );
        assert_eq!(
            statements("PX=-VC1*2 PY= VC[PNTR + 1] VFST=#80H"),
            [
                ("PX=-VC1*2".into(), Kind::Assignment),
                ("PY= VC[PNTR + 1]".into(), Kind::Assignment),
                ("VFST=#80H".into(), Kind::Assignment)
            ]
        );
        // word operators between operands (ICAM's Okuma syntax: EQ ... LE, AND, OR, EOR)
        assert_eq!(
            statements("VC1 = VC2 AND VC3 VC4 = [VC5 EOR 3]"),
            [
                ("VC1 = VC2 AND VC3".into(), Kind::Assignment),
                ("VC4 = [VC5 EOR 3]".into(), Kind::Assignment)
            ]
        );
        // after a value: the next assignment, the next word
        assert_eq!(
            statements("VC1 = VC2 * 3 VGRIN[1] = 1 (C)"),
            [
                ("VC1 = VC2 * 3".into(), Kind::Assignment),
                ("VGRIN[1] = 1".into(), Kind::Assignment)
            ]
        );
        assert_eq!(
            statements("VC1=FIX[VC2/7000] X80"),
            [("VC1=FIX[VC2/7000]".into(), Kind::Assignment)]
        );
        // loops
        assert_eq!(
            statements("WHILE [CNTR LE PEND] DO 1"),
            [("WHILE [CNTR LE PEND] DO 1".into(), Kind::Flow)]
        );
        assert_eq!(statements("DO 2"), [("DO 2".into(), Kind::Flow)]);
        assert_eq!(statements("END 1"), [("END 1".into(), Kind::Flow)]);
        // END alone closes a LAP contour definition
        assert_eq!(statements("END"), [("END".into(), Kind::Command)]);
        // N0100 and X=FLAN+5 are words
        assert!(statements("N0100 M90").is_empty());
        assert!(statements("G0 X=FLAN+5 Z=SPFA+10 T=TL7").is_empty());
    }

    #[test]
    fn malformed_osp_statements_are_located() {
        let dialect = Dialect {
            family: Family::Okuma,
            brackets: true,
            star: true,
            ..Dialect::default()
        };
        let mut words = Vec::new();
        let e = tokenize(b"GOTO 10", &dialect, &mut words).unwrap_err();
        assert!(e.message.contains("sequence name"), "{}", e.message);
        assert_eq!(e.offset, 5);
        for (text, what, offset) in [
            ("VUACM[1]='NO END", "closing '", 9),
            // the shared expression reader's errors, as on a Fanuc: an operand missing...
            ("CNTR = CNTR +", "ends without an operand", 13),
            ("CNTR = CNTR + (ONE)", "found '('", 14),
            ("VC1 = * 3", "found '*'", 6),
            ("VC1 = [VC2 + ] (X)", "found ']'", 13),
            ("VC1 =", "'=' must be followed by a value", 5),
            // ... and a second operand with no operator before it
            ("VC1 = VC2 VC3", "two operands without an operator", 10),
            ("VC1 = VC2 3", "two operands without an operator", 10),
            ("VC1 = VC2 AND", "ends without an operand", 13),
            ("VC1 = [VC2] [VC3]", "two operands without an operator", 12),
            ("X=FLAN FLAN Z0", "two operands without an operator", 7),
            // glued to the value as well
            ("VC1=[VC2]VC3", "two operands without an operator", 9),
            ("VC1=SIN[30]VC2", "two operands without an operator", 11),
            ("VC1='AB'VC2", "two operands without an operator", 8),
            ("WHILE CNTR LE 3 DO 1", "condition in [ ]", 6),
            ("WHILE [CNTR LE 3] 1", "DO and the loop's number", 18),
            ("WHILE [CNTR LE 3] DO", "DO and the loop's number", 18),
            ("VC1 = VTOHT [1", "without a closing ']'", 14),
        ] {
            let e = tokenize(text.as_bytes(), &dialect, &mut words).unwrap_err();
            assert!(e.message.contains(what), "{text}: {}", e.message);
            assert_eq!(e.offset, offset, "{text}");
        }
    }
}
