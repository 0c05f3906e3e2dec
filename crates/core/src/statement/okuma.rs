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
//! Conditions and values are kept as text (the checker does not evaluate OSP expressions).

use super::{brackets, digits_end, ident_end, rest_end, statement, word, Kind, Read};
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
    if named && b == b'O' {
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
    let value_end = value_end(line, skip_blanks(line, value));
    if value_end == skip_blanks(line, value) {
        return Err(osp_error("'=' must be followed by a value", value));
    }
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

/// The end of a value: up to a blank or a `(` comment outside brackets.
fn value_end(line: &[u8], pos: usize) -> usize {
    let mut depth = 0usize;
    for (i, &b) in line.iter().enumerate().skip(pos) {
        match b {
            b'[' => depth += 1,
            b']' => depth = depth.saturating_sub(1),
            b' ' | b'\t' | b'\r' | b'(' if depth == 0 => return i,
            _ => {}
        }
    }
    line.len()
}

fn skip_blanks(line: &[u8], pos: usize) -> usize {
    let mut p = pos;
    while p < line.len() && matches!(line[p], b' ' | b'\t') {
        p += 1;
    }
    p
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
        // N0100 and X=FLAN+5 are words
        assert!(statements("N0100 M90").is_empty());
        assert!(statements("G0 X=FLAN+5 Z=SPFA+10 T=TL7").is_empty());
    }

    #[test]
    fn malformed_osp_statements_are_located() {
        let dialect = Dialect {
            family: Family::Okuma,
            brackets: true,
            ..Dialect::default()
        };
        let mut words = Vec::new();
        let e = tokenize(b"GOTO 10", &dialect, &mut words).unwrap_err();
        assert!(e.message.contains("sequence name"), "{}", e.message);
        assert_eq!(e.offset, 5);
    }
}
