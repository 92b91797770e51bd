//! CSV tables through the `csv` crate, as spreadsheets save them: a UTF-8 byte-order mark is
//! dropped, the delimiter (`,`, `;` or tab) is taken from the header line, CRLF is accepted,
//! and a ragged row or an unterminated quote is reported with its line number.
//!
//! The crate does not say which fields were quoted, and a quoted cell is a string even when
//! it reads as a number ("007"); `quoted_fields` finds that out from the record's raw bytes,
//! which the crate has already split, so it only looks at where each field starts.

use super::source::{Cell, Row};
use crate::lang::reader::parse_number;

/// The delimiter of a table: whichever of `,` `;` tab occurs most in the header line
/// (outside quotes); `,` when none does.
pub fn sniff_delimiter(text: &str) -> u8 {
    let mut counts = [0usize; 3];
    let mut in_quotes = false;
    for b in text.bytes() {
        match b {
            b'"' => in_quotes = !in_quotes,
            b'\n' | b'\r' if !in_quotes => break,
            b',' if !in_quotes => counts[0] += 1,
            b';' if !in_quotes => counts[1] += 1,
            b'\t' if !in_quotes => counts[2] += 1,
            _ => {}
        }
    }
    let best = (0..3).max_by_key(|&i| (counts[i], 3 - i)).unwrap_or(0);
    if counts[best] == 0 {
        b','
    } else {
        [b',', b';', b'\t'][best]
    }
}

/// The header and the rows of a table.
pub fn table(text: &str) -> Result<(Vec<String>, Vec<Row>), String> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let delim = sniff_delimiter(text);
    let mut rd = csv::ReaderBuilder::new()
        .delimiter(delim)
        .has_headers(false)
        .flexible(true)
        .from_reader(text.as_bytes());
    let mut records = Vec::new();
    let mut rec = csv::StringRecord::new();
    loop {
        let start = rd.position().clone();
        match rd.read_record(&mut rec) {
            Ok(false) => break,
            Ok(true) => {}
            Err(e) => {
                let byte = e.position().map_or(start.byte(), |p| p.byte());
                return Err(format!("line {}: {e}", line_at(text, byte)));
            }
        }
        let pos = rec.position().cloned().unwrap_or(start);
        // A record of one empty field is a blank line (the crate skips most of them).
        if rec.len() == 1 && rec[0].trim().is_empty() {
            continue;
        }
        records.push((pos, rec.clone()));
    }
    let ends: Vec<usize> = records
        .iter()
        .skip(1)
        .map(|(p, _)| p.byte() as usize)
        .chain(std::iter::once(text.len()))
        .collect();
    let mut cells: Vec<(u64, Vec<Cell>)> = Vec::with_capacity(records.len());
    for ((pos, rec), end) in records.iter().zip(ends) {
        // The crate's record position is where reading began: before any blank lines.
        let from = pos.byte() as usize;
        let at = from
            + text.as_bytes()[from..end]
                .iter()
                .take_while(|b| matches!(b, b'\r' | b'\n'))
                .count();
        let quoted = quoted_fields(&text.as_bytes()[at..end], delim).map_err(|off| {
            let line = line_at(text, (at + off) as u64);
            format!("line {line}: unterminated quoted field")
        })?;
        let row = rec
            .iter()
            .enumerate()
            .map(|(i, f)| {
                let q = quoted.get(i).copied().unwrap_or(false);
                Cell {
                    text: if q {
                        f.to_string()
                    } else {
                        f.trim().to_string()
                    },
                    quoted: q,
                }
            })
            .collect();
        cells.push((line_at(text, at as u64), row));
    }
    let mut it = cells.into_iter();
    let Some((_, header)) = it.next() else {
        return Err("the table is empty (it needs a header of variable names)".into());
    };
    let header: Vec<String> = header.into_iter().map(|c| c.text).collect();
    for h in &header {
        if h.is_empty() || parse_number(h).is_some() || h.contains(char::is_whitespace) {
            return Err(format!("header: `{h}` is not a variable name"));
        }
    }
    let rows = it
        .enumerate()
        .map(|(i, (line, r))| {
            if r.len() != header.len() {
                return Err(format!(
                    "line {line}: {} fields, the header has {}",
                    r.len(),
                    header.len()
                ));
            }
            Ok(Row {
                number: i as u64 + 1,
                values: header.iter().cloned().zip(r).collect(),
                ..Row::default()
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok((header, rows))
}

/// The line (from 1) of a byte offset. The crate's own line count skips blank lines.
fn line_at(text: &str, byte: u64) -> u64 {
    let end = (byte as usize).min(text.len());
    1 + text.as_bytes()[..end]
        .iter()
        .filter(|&&c| c == b'\n')
        .count() as u64
}

/// Which fields of one raw record start with a quote; `Err(offset)` of a quote left open.
fn quoted_fields(raw: &[u8], delim: u8) -> Result<Vec<bool>, usize> {
    let mut out = Vec::new();
    let mut i = 0;
    loop {
        let q = raw.get(i) == Some(&b'"');
        out.push(q);
        if q {
            let open = i;
            i += 1;
            loop {
                match raw.get(i) {
                    None => return Err(open),
                    Some(b'"') if raw.get(i + 1) == Some(&b'"') => i += 2,
                    Some(b'"') => {
                        i += 1;
                        break;
                    }
                    Some(_) => i += 1,
                }
            }
        }
        while let Some(&c) = raw.get(i) {
            if c == delim || c == b'\n' || c == b'\r' {
                break;
            }
            i += 1;
        }
        if raw.get(i) != Some(&delim) {
            return Ok(out);
        }
        i += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(rows: &[Row]) -> Vec<Vec<String>> {
        rows.iter()
            .map(|r| r.values.iter().map(|(_, c)| c.text.clone()).collect())
            .collect()
    }

    #[test]
    fn quotes_doubled_quotes_and_newlines_in_quotes() {
        let (h, rows) =
            table("name,L1\n\"big, wide\",140\n\"say \"\"hi\"\"\",135.5\n\"two\nlines\",1\n")
                .unwrap();
        assert_eq!(h, ["name", "L1"]);
        assert_eq!(texts(&rows)[0], ["big, wide", "140"]);
        assert!(rows[0].values[0].1.quoted);
        assert!(!rows[0].values[1].1.quoted);
        assert_eq!(texts(&rows)[1], ["say \"hi\"", "135.5"]);
        assert_eq!(texts(&rows)[2], ["two\nlines", "1"]);
    }

    #[test]
    fn excel_bom_semicolons_tabs_and_crlf() {
        let plain = table("name,L1\r\nbig,140\r\n").unwrap();
        for t in [
            "\u{feff}name,L1\r\nbig,140\r\n",
            "name;L1\r\nbig;140\r\n",
            "\u{feff}name;L1\nbig;140",
            "name\tL1\nbig\t140\n",
            "name , L1\n\nbig, 140\n\n",
        ] {
            let got = table(t).unwrap();
            assert_eq!(got.0, plain.0, "{t:?}");
            assert_eq!(texts(&got.1), texts(&plain.1), "{t:?}");
        }
        // A semicolon table whose values have decimal commas keeps them.
        let (_, rows) = table("L1;R\n\"140,5\";12\n").unwrap();
        assert_eq!(texts(&rows)[0], ["140,5", "12"]);
    }

    #[test]
    fn ragged_rows_and_open_quotes_name_their_line() {
        let e = table("a,b\n1,2\n\n3\n").unwrap_err();
        assert_eq!(e, "line 4: 1 fields, the header has 2");
        let e = table("a,b\r\n1,2\r\n3,4,5\r\n").unwrap_err();
        assert_eq!(e, "line 3: 3 fields, the header has 2");
        let e = table("a,b\n1,2\n3,\"open\n\n").unwrap_err();
        assert_eq!(e, "line 3: unterminated quoted field");
        let e = table("a,b\n\"x\ny\",2\n5,\"z\n").unwrap_err();
        assert_eq!(e, "line 4: unterminated quoted field");
    }

    #[test]
    fn bad_headers() {
        assert!(table("").is_err());
        assert!(table("\u{feff}").is_err());
        assert!(table("1,b\n").unwrap_err().contains("`1`"));
        assert!(table("a b,c\n").is_err());
    }
}
