//! Where the data of a source text start and end, found lexically (no values built): the
//! top-level forms an edit may re-read one by one, and the items of a list (a defun's
//! parameters, a setq's targets) that the reader keeps no position for.
//!
//! The rules are the reader's (`grammar/lispcad.pest` and `reader::scan`): whitespace includes
//! form feed and the byte-order mark, comments are `;` to the end of the line and `;| ... |;`,
//! a string ends at an unescaped `"`, a token runs to the next delimiter, and a quote binds to
//! the datum after it, trivia in between.

/// Width of the whitespace character at `i` (0 if there is none).
fn space_width(b: &[u8], i: usize) -> usize {
    match b[i] {
        b' ' | b'\t' | b'\r' | b'\n' | 0x0C => 1,
        0xEF if b[i + 1..].starts_with(&[0xBB, 0xBF]) => 3,
        _ => 0,
    }
}

fn is_delimiter(c: u8) -> bool {
    matches!(
        c,
        b' ' | b'\t' | b'\r' | b'\n' | 0x0C | b'(' | b')' | b'\'' | b'"' | b';'
    )
}

/// The first offset from `i` that is neither whitespace nor inside a comment.
pub fn skip_trivia(text: &str, mut i: usize) -> usize {
    let b = text.as_bytes();
    while i < b.len() {
        let w = space_width(b, i);
        if w > 0 {
            i += w;
        } else if b[i] == b';' {
            i = if b.get(i + 1) == Some(&b'|') {
                text[i + 2..].find("|;").map_or(b.len(), |k| i + 2 + k + 2)
            } else {
                text[i..].find('\n').map_or(b.len(), |k| i + k)
            };
        } else {
            break;
        }
    }
    i
}

fn string_end(b: &[u8], i: usize) -> usize {
    let mut j = i + 1;
    loop {
        match b.get(j) {
            None => return b.len(),
            Some(b'\\') => j += 2,
            Some(b'"') => return j + 1,
            Some(_) => j += 1,
        }
    }
}

/// The end of the datum starting at `i` (which is past any trivia). A `)` there is no datum:
/// the answer is `i`. Iterative, so deep nesting or a long run of quotes cannot exhaust the
/// stack; an unclosed list ends at the end of the text.
pub fn datum_end(text: &str, mut i: usize) -> usize {
    let b = text.as_bytes();
    let mut depth = 0usize;
    loop {
        match b.get(i) {
            None => return i,
            Some(b'\'') => {
                i = skip_trivia(text, i + 1);
                continue;
            }
            Some(b'(') => {
                depth += 1;
                i += 1;
            }
            Some(b')') => {
                if depth == 0 {
                    return i;
                }
                depth -= 1;
                i += 1;
            }
            Some(b'"') => i = string_end(b, i),
            Some(_) => {
                while i < b.len() && !is_delimiter(b[i]) {
                    i += 1;
                }
            }
        }
        if depth == 0 {
            return i;
        }
        i = skip_trivia(text, i);
    }
}

/// Byte ranges of the top-level data of a text whose brackets balance (`reader::scan`
/// accepted it), in order.
pub fn top_level(text: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut i = skip_trivia(text, 0);
    while i < text.len() {
        let end = datum_end(text, i);
        if end == i {
            // A stray `)`: the scan rejects such a text before it gets here.
            break;
        }
        out.push((i, end));
        i = skip_trivia(text, end);
    }
    out
}

/// Byte ranges of the items of the list written at `start` (its `(`), in order.
pub fn list_items(text: &str, start: usize) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    if text.as_bytes().get(start) != Some(&b'(') {
        return out;
    }
    let mut i = skip_trivia(text, start + 1);
    while i < text.len() {
        let end = datum_end(text, i);
        if end == i {
            break;
        }
        out.push((i, end));
        i = skip_trivia(text, end);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pieces(text: &str) -> Vec<&str> {
        top_level(text)
            .into_iter()
            .map(|(a, b)| &text[a..b])
            .collect()
    }

    #[test]
    fn top_level_data_with_their_quotes_and_without_trivia() {
        let t = "; head\n(a (b \")\") c) 'x ' ;c\n (q)\n\"s\\\"t\" tok;|(|;\u{FEFF}(z)";
        assert_eq!(
            pieces(t),
            [
                "(a (b \")\") c)",
                "'x",
                "' ;c\n (q)",
                "\"s\\\"t\"",
                "tok",
                "(z)"
            ]
        );
        // A byte-order mark inside a token is part of it, as the grammar has it.
        assert_eq!(pieces("a\u{FEFF}b c"), ["a\u{FEFF}b", "c"]);
        assert_eq!(pieces("'"), ["'"]);
        assert_eq!(pieces(&"'".repeat(100_000)).len(), 1);
    }

    #[test]
    fn items_of_a_list() {
        let t = "(defun f (a b / c) (setq c 'd))";
        let items: Vec<&str> = list_items(t, 0)
            .into_iter()
            .map(|(a, b)| &t[a..b])
            .collect();
        assert_eq!(items, ["defun", "f", "(a b / c)", "(setq c 'd)"]);
        let inner: Vec<&str> = list_items(t, 9)
            .into_iter()
            .map(|(a, b)| &t[a..b])
            .collect();
        assert_eq!(inner, ["a", "b", "/", "c"]);
        assert!(list_items(t, 1).is_empty());
        // A quote before `)` binds to nothing.
        assert_eq!(list_items("(a ')", 0), [(1, 2), (3, 4)]);
    }
}
