//! The string builtins that work on characters: `vl-string-*`, `strcase`, `substr`, `atoi`,
//! `atof`, `itoa`.
//!
//! Positions count characters (not bytes), 0-based for the `vl-string-*` family and 1-based
//! for `substr`, as in AutoLISP. Argument order follows the Lisp call so the builtin wrappers
//! read straight across: `(vl-string-trim char-set str)` → `vl_string_trim(char_set, s)`.

use super::FmtError;

/// `(vl-string-trim char-set str)`: removes every leading and trailing character that occurs
/// in `char_set`.
pub fn vl_string_trim(char_set: &str, s: &str) -> String {
    s.trim_matches(|c| char_set.contains(c)).to_string()
}

/// `(vl-string-left-trim char-set str)`: removes leading characters that occur in `char_set`.
pub fn vl_string_left_trim(char_set: &str, s: &str) -> String {
    s.trim_start_matches(|c| char_set.contains(c)).to_string()
}

/// `(vl-string-right-trim char-set str)`: removes trailing characters that occur in `char_set`.
pub fn vl_string_right_trim(char_set: &str, s: &str) -> String {
    s.trim_end_matches(|c| char_set.contains(c)).to_string()
}

/// Byte offset of character number `index`, or `None` past the end (the end itself is valid).
fn byte_offset(s: &str, index: usize) -> Option<usize> {
    s.char_indices()
        .map(|(b, _)| b)
        .chain(std::iter::once(s.len()))
        .nth(index)
}

/// Character index of byte offset `byte` (which must be a char boundary).
fn char_index(s: &str, byte: usize) -> usize {
    s[..byte].chars().count()
}

/// `(vl-string-search pattern string [start-pos])`: the 0-based character position of the
/// first occurrence of `pattern` at or after `start`, case-sensitively.
///
/// An empty pattern is found at `start`; a negative start counts as 0; a start past the end
/// finds nothing.
pub fn vl_string_search(pattern: &str, s: &str, start: i64) -> Option<usize> {
    let start = usize::try_from(start.max(0)).ok()?;
    let from = byte_offset(s, start)?;
    s[from..].find(pattern).map(|b| char_index(s, from + b))
}

/// `(vl-string-position char-code str [start-pos [from-end-p]])`: the 0-based position of the
/// character with code `code`.
///
/// Forward: the first occurrence at or after `start`. With `from_end`: the search begins at
/// the end of the string and goes backward down to `start` (the reference's wording), i.e. the
/// last occurrence at or after `start`.
pub fn vl_string_position(code: u32, s: &str, start: i64, from_end: bool) -> Option<usize> {
    let target = char::from_u32(code)?;
    let start = usize::try_from(start.max(0)).ok()?;
    let mut hits = s
        .chars()
        .enumerate()
        .skip(start)
        .filter(|&(_, c)| c == target)
        .map(|(i, _)| i);
    if from_end {
        hits.last()
    } else {
        hits.next()
    }
}

/// `(vl-string-subst new-str pattern string [start-pos])`: replaces the first occurrence of
/// `pattern` at or after `start` with `new`; the string is returned unchanged if there is none.
pub fn vl_string_subst(new: &str, pattern: &str, s: &str, start: i64) -> String {
    let Some(pos) = vl_string_search(pattern, s, start) else {
        return s.to_string();
    };
    let at = byte_offset(s, pos).expect("search returned a position inside the string");
    let mut out = String::with_capacity(s.len() + new.len());
    out.push_str(&s[..at]);
    out.push_str(new);
    out.push_str(&s[at + pattern.len()..]);
    out
}

/// `(vl-string-translate source-set dest-set str)`: replaces each character of `s` found in
/// `source_set` by the character at the same position in `dest_set`.
///
/// The first occurrence in `source_set` decides; source characters without a partner in a
/// shorter `dest_set` are left as they are.
pub fn vl_string_translate(source_set: &str, dest_set: &str, s: &str) -> String {
    let dest: Vec<char> = dest_set.chars().collect();
    s.chars()
        .map(|c| {
            source_set
                .chars()
                .position(|x| x == c)
                .and_then(|i| dest.get(i).copied())
                .unwrap_or(c)
        })
        .collect()
}

/// `(vl-string-mismatch str1 str2 [pos1 pos2 ignore-case-p])`: the length of the longest
/// common prefix of `s1` from `pos1` and `s2` from `pos2`.
///
/// Negative positions count as 0; `ignore_case` compares characters case-insensitively.
pub fn vl_string_mismatch(s1: &str, s2: &str, pos1: i64, pos2: i64, ignore_case: bool) -> usize {
    let skip1 = usize::try_from(pos1.max(0)).unwrap_or(usize::MAX);
    let skip2 = usize::try_from(pos2.max(0)).unwrap_or(usize::MAX);
    s1.chars()
        .skip(skip1)
        .zip(s2.chars().skip(skip2))
        .take_while(|&(a, b)| a == b || (ignore_case && upper_char(a) == upper_char(b)))
        .count()
}

/// `(vl-string-elt string position)`: the character code at 0-based `pos`, or `None` when
/// `pos` is outside the string.
pub fn vl_string_elt(s: &str, pos: i64) -> Option<u32> {
    let pos = usize::try_from(pos).ok()?;
    s.chars().nth(pos).map(|c| c as u32)
}

/// Upper-cases one character when its upper case is a single character (so `ß` stays `ß`
/// and lengths never change, as with the C library's `toupper`).
fn upper_char(c: char) -> char {
    let mut up = c.to_uppercase();
    match (up.next(), up.next()) {
        (Some(u), None) => u,
        _ => c,
    }
}

fn lower_char(c: char) -> char {
    let mut low = c.to_lowercase();
    match (low.next(), low.next()) {
        (Some(l), None) => l,
        _ => c,
    }
}

/// `(strcase string [which])`: upper case, or lower case when `to_lower` (a non-nil `which`).
///
/// Characters whose case mapping is not a single character are left unchanged, so the result
/// always has as many characters as the input.
pub fn strcase(s: &str, to_lower: bool) -> String {
    if to_lower {
        s.chars().map(lower_char).collect()
    } else {
        s.chars().map(upper_char).collect()
    }
}

/// `(substr string start [length])`: `length` characters from 1-based `start` (to the end if
/// `length` is `None`).
///
/// A start past the end gives `""`; a length reaching past the end gives the rest.
/// `start < 1` and `length < 0` are errors (AutoLISP: "bad argument value").
pub fn substr(s: &str, start: i64, length: Option<i64>) -> Result<String, FmtError> {
    if start < 1 {
        return Err(FmtError::SubstrStart { start });
    }
    if let Some(length) = length {
        if length < 0 {
            return Err(FmtError::SubstrLength { length });
        }
    }
    let skip = usize::try_from(start - 1).unwrap_or(usize::MAX);
    let take = length.map_or(usize::MAX, |n| usize::try_from(n).unwrap_or(usize::MAX));
    Ok(s.chars().skip(skip).take(take).collect())
}

/// `(atoi string)`: C's `atoi` — optional leading whitespace, an optional sign, then as many
/// decimal digits as follow; no digits gives 0 (`"3.9"` → 3, `"abc"` → 0, `" 12abc"` → 12).
///
/// Values beyond 32 bits saturate to `i32::MAX`/`i32::MIN`, as Microsoft's `atoi` documents.
pub fn atoi(s: &str) -> i32 {
    let t = s.trim_start_matches(is_c_space);
    let (negative, digits) = match t.as_bytes().first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    };
    let mut value: i64 = 0;
    for d in digits.bytes().take_while(u8::is_ascii_digit) {
        value = (value * 10 + i64::from(d - b'0')).min(i64::from(i32::MAX) + 1);
    }
    let value = if negative { -value } else { value };
    value.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// The characters C's `isspace` accepts in the "C" locale.
fn is_c_space(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\n' | '\r' | '\u{b}' | '\u{c}')
}

/// Length in bytes of the longest prefix of `t` that is a decimal floating-point number
/// (`[+-]digits[.digits][(e|E)[+-]digits]`, at least one mantissa digit), or 0.
pub(crate) fn decimal_prefix_len(t: &str) -> usize {
    let b = t.as_bytes();
    let mut i = 0;
    if matches!(b.first(), Some(b'+' | b'-')) {
        i += 1;
    }
    let int_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    let mut mantissa_digits = i - int_start;
    if i < b.len() && b[i] == b'.' {
        let frac_start = i + 1;
        let mut j = frac_start;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        mantissa_digits += j - frac_start;
        if mantissa_digits > 0 {
            i = j;
        }
    }
    if mantissa_digits == 0 {
        return 0;
    }
    if i < b.len() && matches!(b[i], b'e' | b'E') {
        let mut j = i + 1;
        if j < b.len() && matches!(b[j], b'+' | b'-') {
            j += 1;
        }
        let exp_start = j;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        if j > exp_start {
            i = j;
        }
    }
    i
}

/// `(atof string)`: C's `atof` restricted to decimal numbers — optional leading whitespace,
/// then the longest prefix of the form `[+-]digits[.digits][e[+-]digits]`; nothing numeric
/// gives 0.0 (`"97.1"` → 97.1, `"3"` → 3.0, `"1.5e2x"` → 150.0, `".5"` → 0.5).
///
/// C's `inf`/`nan`/hexadecimal forms are not accepted (they give 0.0) so `atof` can never
/// produce NaN; an exponent too large overflows to ±infinity as in C.
pub fn atof(s: &str) -> f64 {
    let t = s.trim_start_matches(is_c_space);
    let n = decimal_prefix_len(t);
    if n == 0 {
        return 0.0;
    }
    t[..n].parse().unwrap_or(0.0)
}

/// `(itoa int)`: the decimal text of an integer.
pub fn itoa(n: i32) -> String {
    n.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    // Examples from the AutoLISP reference pages of each function.
    #[test]
    fn trim_reference_examples() {
        assert_eq!(vl_string_trim(" \t\n", " \t\n STR \n\t "), "STR");
        assert_eq!(vl_string_trim("012", "1212345211"), "345");
        assert_eq!(vl_string_trim("", "  x  "), "  x  ");
        assert_eq!(vl_string_trim("x", "xxx"), "");
        assert_eq!(vl_string_left_trim(" \t\n", "\n\t STR "), "STR ");
        assert_eq!(
            vl_string_left_trim("12456789", "12463CPO is not R2D2"),
            "3CPO is not R2D2"
        );
        assert_eq!(
            vl_string_left_trim(" ", " There are too many spaces here"),
            "There are too many spaces here"
        );
        assert_eq!(vl_string_right_trim(" \t\n", " STR \n\t "), " STR");
        assert_eq!(
            vl_string_right_trim("1356789", "3CPO is not R2D2"),
            "3CPO is not R2D2"
        );
        assert_eq!(
            vl_string_right_trim(" ", "There are too many spaces here       "),
            "There are too many spaces here"
        );
    }

    #[test]
    fn search_reference_examples() {
        assert_eq!(vl_string_search("foo", "pfooyey on you", 0), Some(1));
        assert_eq!(vl_string_search("who", "pfooyey on you", 0), None);
        assert_eq!(vl_string_search("foo", "fooey-more-fooey", 1), Some(11));
        assert_eq!(vl_string_search("", "pfooyey on you", 0), Some(0));
    }

    #[test]
    fn search_edges() {
        assert_eq!(vl_string_search("a", "abc", -5), Some(0));
        assert_eq!(vl_string_search("", "abc", 3), Some(3));
        assert_eq!(vl_string_search("", "abc", 4), None);
        assert_eq!(vl_string_search("c", "abc", 99), None);
        assert_eq!(vl_string_search("A", "abc", 0), None);
        // Positions count characters, not bytes.
        assert_eq!(vl_string_search("ø", "æøå ø", 0), Some(1));
        assert_eq!(vl_string_search("ø", "æøå ø", 2), Some(4));
    }

    #[test]
    fn position_reference_examples() {
        let z = u32::from(b'z');
        assert_eq!(vl_string_position(z, "azbdc az", 0, false), Some(1));
        assert_eq!(vl_string_position(z, "azbdc az", 2, false), Some(7));
        assert_eq!(vl_string_position(z, "azbdc az", 0, true), Some(7));
    }

    #[test]
    fn position_edges() {
        let z = u32::from(b'z');
        assert_eq!(vl_string_position(z, "abc", 0, false), None);
        assert_eq!(vl_string_position(z, "zabc", 1, true), None);
        assert_eq!(vl_string_position(z, "zzabc", 1, true), Some(1));
        assert_eq!(vl_string_position(z, "", 0, true), None);
        assert_eq!(vl_string_position(0xD800, "abc", 0, false), None);
        assert_eq!(vl_string_position('å' as u32, "æøå", 0, false), Some(2));
    }

    #[test]
    fn subst_reference_examples() {
        assert_eq!(
            vl_string_subst("Obi-wan", "Ben", "Ben Kenobi", 0),
            "Obi-wan Kenobi"
        );
        assert_eq!(
            vl_string_subst("Obi-wan", "Ben", "ben Kenobi", 0),
            "ben Kenobi"
        );
        assert_eq!(
            vl_string_subst("Obi-wan", "Ben", "Ben Kenobi Ben", 0),
            "Obi-wan Kenobi Ben"
        );
        assert_eq!(
            vl_string_subst("Obi-wan", "Ben", "Ben \"Ben\" Kenobi", 1),
            "Ben \"Obi-wan\" Kenobi"
        );
    }

    #[test]
    fn subst_edges() {
        assert_eq!(vl_string_subst("x", "", "abc", 0), "xabc");
        assert_eq!(vl_string_subst("", "b", "abc", 0), "ac");
        assert_eq!(vl_string_subst("Ø", "ø", "æøå", 0), "æØå");
    }

    #[test]
    fn translate_reference_examples() {
        assert_eq!(
            vl_string_translate("abcABC", "123123", "A is a, B is b, C is C"),
            "1 is 1, 2 is 2, 3 is 3"
        );
        assert_eq!(
            vl_string_translate("abc", "123", "A is a, B is b, C is C"),
            "A is 1, B is 2, C is C"
        );
    }

    #[test]
    fn translate_edges() {
        assert_eq!(vl_string_translate("abc", "1", "abc"), "1bc");
        assert_eq!(vl_string_translate("aa", "12", "a"), "1");
        assert_eq!(vl_string_translate("", "", "abc"), "abc");
    }

    #[test]
    fn mismatch_reference_examples() {
        assert_eq!(vl_string_mismatch("VL-FUN", "VL-VAR", 0, 0, false), 3);
        assert_eq!(vl_string_mismatch("vl-fun", "avl-var", 0, 0, false), 0);
        assert_eq!(vl_string_mismatch("vl-fun", "avl-var", 0, 1, false), 3);
        assert_eq!(vl_string_mismatch("VL-FUN", "Vl-vAR", 0, 0, false), 1);
        assert_eq!(vl_string_mismatch("VL-FUN", "Vl-vAR", 0, 0, true), 3);
    }

    #[test]
    fn mismatch_edges() {
        assert_eq!(vl_string_mismatch("abc", "abc", 0, 0, false), 3);
        assert_eq!(vl_string_mismatch("", "abc", 0, 0, false), 0);
        assert_eq!(vl_string_mismatch("abc", "abc", 9, 0, false), 0);
        assert_eq!(vl_string_mismatch("abc", "abc", -1, -1, false), 3);
    }

    #[test]
    fn elt_reference_example() {
        assert_eq!(vl_string_elt("May the Force be with you", 8), Some(70));
        assert_eq!(vl_string_elt("abc", 3), None);
        assert_eq!(vl_string_elt("abc", -1), None);
        assert_eq!(vl_string_elt("é", 0), Some(0xE9));
    }

    #[test]
    fn strcase_reference_examples() {
        assert_eq!(strcase("Sample", false), "SAMPLE");
        assert_eq!(strcase("Sample", true), "sample");
        assert_eq!(strcase("àbÇ 1-2", false), "ÀBÇ 1-2");
        assert_eq!(strcase("ÀBÇ", true), "àbç");
        // One-to-many mappings are left alone so lengths never change.
        assert_eq!(strcase("straße", false), "STRAßE");
        assert_eq!(strcase("İ", true), "İ");
    }

    #[test]
    fn substr_reference_examples() {
        assert_eq!(substr("abcde", 2, None).unwrap(), "bcde");
        assert_eq!(substr("abcde", 2, Some(1)).unwrap(), "b");
        assert_eq!(substr("abcde", 3, Some(2)).unwrap(), "cd");
    }

    #[test]
    fn substr_out_of_range() {
        assert_eq!(substr("abcde", 6, None).unwrap(), "");
        assert_eq!(substr("abcde", 10, Some(2)).unwrap(), "");
        assert_eq!(substr("abcde", 4, Some(10)).unwrap(), "de");
        assert_eq!(substr("abcde", 1, Some(0)).unwrap(), "");
        assert_eq!(substr("æøå", 2, Some(1)).unwrap(), "ø");
        assert_eq!(substr("", 1, None).unwrap(), "");
        assert_eq!(
            substr("abc", 0, None),
            Err(FmtError::SubstrStart { start: 0 })
        );
        assert_eq!(
            substr("abc", 1, Some(-1)),
            Err(FmtError::SubstrLength { length: -1 })
        );
        assert_eq!(
            substr("abc", 0, None).unwrap_err().to_string(),
            "bad argument value: positive 0 (substr start must be >= 1)"
        );
    }

    #[test]
    fn atoi_reference_examples() {
        assert_eq!(atoi("97"), 97);
        assert_eq!(atoi("3"), 3);
        assert_eq!(atoi("3.9"), 3);
    }

    #[test]
    fn atoi_c_semantics() {
        assert_eq!(atoi("abc"), 0);
        assert_eq!(atoi(" 12abc"), 12);
        assert_eq!(atoi("\t\n-42"), -42);
        assert_eq!(atoi("+7"), 7);
        assert_eq!(atoi("- 7"), 0);
        assert_eq!(atoi(""), 0);
        assert_eq!(atoi("1e3"), 1);
        assert_eq!(atoi("2147483647"), i32::MAX);
        assert_eq!(atoi("2147483648"), i32::MAX);
        assert_eq!(atoi("99999999999999999999999"), i32::MAX);
        assert_eq!(atoi("-2147483648"), i32::MIN);
        assert_eq!(atoi("-99999999999999999999"), i32::MIN);
    }

    #[test]
    fn atof_reference_examples() {
        assert_eq!(atof("97.1"), 97.1);
        assert_eq!(atof("3"), 3.0);
        assert_eq!(atof("3.9"), 3.9);
    }

    #[test]
    fn atof_c_semantics() {
        assert_eq!(atof("abc"), 0.0);
        assert_eq!(atof("  -2.5xyz"), -2.5);
        assert_eq!(atof(".5"), 0.5);
        assert_eq!(atof("5."), 5.0);
        assert_eq!(atof("."), 0.0);
        assert_eq!(atof("-.e5"), 0.0);
        assert_eq!(atof("1.5e2x"), 150.0);
        assert_eq!(atof("1.5E-2"), 0.015);
        assert_eq!(atof("2e"), 2.0);
        assert_eq!(atof("2e+"), 2.0);
        assert_eq!(atof("inf"), 0.0);
        assert_eq!(atof("nan"), 0.0);
        assert_eq!(atof("0x10"), 0.0);
        assert_eq!(atof("1e999"), f64::INFINITY);
        assert_eq!(atof("1'-3\""), 1.0);
    }

    #[test]
    fn itoa_reference_examples() {
        assert_eq!(itoa(33), "33");
        assert_eq!(itoa(-17), "-17");
        assert_eq!(itoa(i32::MIN), "-2147483648");
    }
}
