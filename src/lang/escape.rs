//! AutoLISP string escapes: decoding for the reader, encoding for `prin1`.
//!
//! The AutoLISP reference ("Strings") lists `\\`, `\"`, `\e` (escape), `\n`, `\r`, `\t` and
//! `\nnn` (the character whose octal code is nnn). A backslash before any other character is
//! dropped and the character kept, which is what AutoCAD's reader does with `"\x"`.

/// A string literal ending in a lone backslash (the reader never produces one, since it would
/// have escaped the closing quote).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("malformed string: trailing backslash at character {position}")]
pub struct TrailingBackslash {
    pub position: usize,
}

/// Decodes the escapes in the text between a string literal's quotes.
///
/// `\nnn` takes one to three octal digits; the code is reduced to a byte (`& 0xFF`) because
/// AutoLISP strings are byte strings, and the byte is read as Latin-1 (`"\351"` → `é`).
/// An escape of an unknown character yields the character itself (`"\q"` → `q`).
/// A trailing lone backslash is an error (the reader never produces one, since it would have
/// escaped the closing quote).
pub fn unescape(src: &str) -> Result<String, TrailingBackslash> {
    let mut out = String::with_capacity(src.len());
    let mut chars = src.char_indices().peekable();
    while let Some((position, c)) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        let Some((_, e)) = chars.next() else {
            return Err(TrailingBackslash { position });
        };
        match e {
            'n' => out.push('\n'),
            'r' => out.push('\r'),
            't' => out.push('\t'),
            'e' => out.push('\u{1b}'),
            '0'..='7' => {
                let mut code = e.to_digit(8).expect("matched an octal digit");
                for _ in 0..2 {
                    match chars.peek().and_then(|&(_, d)| d.to_digit(8)) {
                        Some(d) => {
                            code = code * 8 + d;
                            chars.next();
                        }
                        None => break,
                    }
                }
                out.push(char::from((code & 0xFF) as u8));
            }
            other => out.push(other),
        }
    }
    Ok(out)
}

/// Renders a string as `prin1` prints it: in double quotes, with `\\`, `\"`, `\n`, `\r`, `\t`,
/// `\e`, and every other control character (codes 0–31 and 127) as a three-digit octal escape
/// (`(prin1 (chr 1))` prints `"\001"`). Other characters are printed as they are.
///
/// `unescape` of the text between the quotes gives back the original string.
pub fn escape_for_prin1(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '"' => out.push_str("\\\""),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{1b}' => out.push_str("\\e"),
            c if (c as u32) < 32 || c as u32 == 127 => {
                out.push_str(&format!("\\{:03o}", c as u32));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unescape_documented_escapes() {
        assert_eq!(unescape(r"a\\b").unwrap(), "a\\b");
        assert_eq!(unescape(r#"say \"hi\""#).unwrap(), "say \"hi\"");
        assert_eq!(unescape(r"line1\nline2").unwrap(), "line1\nline2");
        assert_eq!(unescape(r"a\rb").unwrap(), "a\rb");
        assert_eq!(unescape(r"a\tb").unwrap(), "a\tb");
        assert_eq!(unescape(r"\e[0m").unwrap(), "\u{1b}[0m");
    }

    #[test]
    fn unescape_octal_takes_up_to_three_digits() {
        // AutoLISP reference: "\nnn — character whose octal code is nnn".
        assert_eq!(unescape(r"\101").unwrap(), "A");
        assert_eq!(unescape(r"\1011").unwrap(), "A1");
        assert_eq!(unescape(r"\7").unwrap(), "\u{7}");
        assert_eq!(unescape(r"\12x").unwrap(), "\nx");
        assert_eq!(unescape(r"\0").unwrap(), "\0");
        assert_eq!(unescape(r"\18").unwrap(), "\u{1}8");
        assert_eq!(unescape(r"\351").unwrap(), "é");
        // 0o777 = 511 is reduced to a byte: 0xFF.
        assert_eq!(unescape(r"\777").unwrap(), "\u{ff}");
    }

    #[test]
    fn unescape_unknown_escape_keeps_the_character() {
        assert_eq!(unescape(r"\x").unwrap(), "x");
        assert_eq!(unescape(r"C:\Temp").unwrap(), "C:Temp");
        assert_eq!(unescape(r"\N").unwrap(), "N");
        assert_eq!(unescape(r"\8").unwrap(), "8");
        assert_eq!(unescape(r"\é").unwrap(), "é");
    }

    #[test]
    fn unescape_plain_text_and_unicode_unchanged() {
        assert_eq!(unescape("").unwrap(), "");
        assert_eq!(unescape("plain ünïcode ∅").unwrap(), "plain ünïcode ∅");
    }

    #[test]
    fn unescape_trailing_backslash_is_an_error() {
        assert_eq!(unescape("ab\\"), Err(TrailingBackslash { position: 2 }));
    }

    #[test]
    fn prin1_escapes() {
        assert_eq!(escape_for_prin1("abc"), "\"abc\"");
        assert_eq!(escape_for_prin1(""), "\"\"");
        assert_eq!(escape_for_prin1("a\"b"), r#""a\"b""#);
        assert_eq!(escape_for_prin1("C:\\dir"), r#""C:\\dir""#);
        assert_eq!(escape_for_prin1("1\n2\r3\t4"), r#""1\n2\r3\t4""#);
        assert_eq!(escape_for_prin1("\u{1b}"), r#""\e""#);
        assert_eq!(escape_for_prin1("\u{1}"), r#""\001""#);
        assert_eq!(escape_for_prin1("\0"), r#""\000""#);
        assert_eq!(escape_for_prin1("\u{7f}"), r#""\177""#);
        assert_eq!(escape_for_prin1("é∅"), "\"é∅\"");
    }

    #[test]
    fn prin1_then_unescape_round_trips_every_byte() {
        let all: String = (0u8..=255).map(char::from).collect();
        let printed = escape_for_prin1(&all);
        let inner = &printed[1..printed.len() - 1];
        assert_eq!(unescape(inner).unwrap(), all);
    }
}
