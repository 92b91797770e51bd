//! `wcmatch`: AutoCAD's wild-card pattern matching.
//!
//! Pattern language (AutoLISP reference, "wcmatch"):
//! `#` one digit, `@` one alphabetic character, `.` one non-alphanumeric character,
//! `*` any sequence (also empty), `?` any one character, `~` first in a pattern = NOT the
//! pattern, `[...]` any one of the characters, `[~...]` any one character not listed, `-`
//! between two characters in brackets = a range, `` ` `` reads the next character literally,
//! `,` separates alternative patterns. Matching is case-sensitive.
//!
//! Choices where the reference is silent:
//! - `~` negates the alternative it starts (`"~A*,B*"` = not starting with A, or starting
//!   with B); a `~` anywhere else is literal;
//! - a comma inside brackets is a literal character (`"[,;]"` matches a comma or semicolon);
//! - a `]` right after `[` or `[~` is a member of the set; an unclosed `[` is a literal `[`;
//! - a `-` first or last in brackets is literal;
//! - "alphabetic"/"alphanumeric" use Unicode's definitions, "digit" is ASCII 0–9.
//!
//! Method: each alternative compiles to a sequence of single-character tests and stars, which
//! is matched with the classic two-pointer algorithm that remembers only the most recent star
//! (a later star subsumes every choice made for an earlier one), so matching costs
//! O(|string| · |pattern|) at worst — `*a*a*a*b` cannot blow up.

/// One element of a compiled alternative.
#[derive(Debug, Clone, PartialEq)]
enum Token {
    /// `*`: any sequence of characters.
    Star,
    /// Anything that matches exactly one character.
    One(CharTest),
}

#[derive(Debug, Clone, PartialEq)]
enum CharTest {
    Literal(char),
    Any,
    Digit,
    Alpha,
    NonAlnum,
    Set { negated: bool, items: Vec<SetItem> },
}

#[derive(Debug, Clone, PartialEq)]
enum SetItem {
    Char(char),
    Range(char, char),
}

impl CharTest {
    fn matches(&self, c: char) -> bool {
        match self {
            CharTest::Literal(l) => *l == c,
            CharTest::Any => true,
            CharTest::Digit => c.is_ascii_digit(),
            CharTest::Alpha => c.is_alphabetic(),
            CharTest::NonAlnum => !c.is_alphanumeric(),
            CharTest::Set { negated, items } => {
                let hit = items.iter().any(|item| match *item {
                    SetItem::Char(x) => x == c,
                    SetItem::Range(lo, hi) => lo <= c && c <= hi,
                });
                hit != *negated
            }
        }
    }
}

/// A compiled alternative: optional negation plus its tokens.
#[derive(Debug, Clone, PartialEq)]
struct Alternative {
    negated: bool,
    tokens: Vec<Token>,
}

/// Returns true if `s` matches `pattern` under AutoCAD's wild-card rules (see the module doc).
///
/// `(wcmatch "Name" "N*")` → T, `(wcmatch "Name" "???,~*m*,N*")` → T,
/// `(wcmatch "Name" "*`,*")` → nil (the reference's examples).
pub fn wcmatch(s: &str, pattern: &str) -> bool {
    WcPattern::new(pattern).matches(s)
}

/// A compiled wild-card pattern, for matching many strings against one pattern (`ssget`
/// filters on layer names, `vl-remove-if` over a list).
#[derive(Debug, Clone, PartialEq)]
pub struct WcPattern {
    alternatives: Vec<Alternative>,
}

impl WcPattern {
    /// Compiles `pattern`; every string is a valid pattern (see the module doc for the rules
    /// applied to unclosed brackets and trailing escapes).
    pub fn new(pattern: &str) -> WcPattern {
        WcPattern {
            alternatives: compile(pattern),
        }
    }

    /// True if `s` matches one of the alternatives.
    pub fn matches(&self, s: &str) -> bool {
        let text: Vec<char> = s.chars().collect();
        self.alternatives
            .iter()
            .any(|alt| match_tokens(&text, &alt.tokens) != alt.negated)
    }
}

/// Splits the pattern at top-level commas and compiles each alternative.
fn compile(pattern: &str) -> Vec<Alternative> {
    let chars: Vec<char> = pattern.chars().collect();
    let mut alternatives = Vec::new();
    let mut i = 0;
    loop {
        let mut alt = Alternative {
            negated: false,
            tokens: Vec::new(),
        };
        if chars.get(i) == Some(&'~') {
            alt.negated = true;
            i += 1;
        }
        while i < chars.len() && chars[i] != ',' {
            let c = chars[i];
            i += 1;
            let test = match c {
                '*' => {
                    // Consecutive stars are one star; keeping one keeps matching linear.
                    if alt.tokens.last() != Some(&Token::Star) {
                        alt.tokens.push(Token::Star);
                    }
                    continue;
                }
                '?' => CharTest::Any,
                '#' => CharTest::Digit,
                '@' => CharTest::Alpha,
                '.' => CharTest::NonAlnum,
                '`' => match chars.get(i) {
                    Some(&next) => {
                        i += 1;
                        CharTest::Literal(next)
                    }
                    // A trailing backquote escapes nothing and matches itself.
                    None => CharTest::Literal('`'),
                },
                '[' => match parse_set(&chars, i) {
                    Some((set, next)) => {
                        i = next;
                        set
                    }
                    None => CharTest::Literal('['),
                },
                other => CharTest::Literal(other),
            };
            alt.tokens.push(Token::One(test));
        }
        alternatives.push(alt);
        if i >= chars.len() {
            break;
        }
        i += 1; // skip the comma
    }
    alternatives
}

/// Parses a bracket set whose contents start at `start` (just after `[`). Returns the test and
/// the index after the closing `]`, or `None` if the set is never closed.
fn parse_set(chars: &[char], start: usize) -> Option<(CharTest, usize)> {
    let mut i = start;
    let negated = chars.get(i) == Some(&'~');
    if negated {
        i += 1;
    }
    // Read members as (char, was_escaped) so escaped `-` and `]` are literal.
    let mut members: Vec<(char, bool)> = Vec::new();
    let mut first = true;
    loop {
        let c = *chars.get(i)?;
        i += 1;
        match c {
            ']' if !first => break,
            '`' => {
                let next = *chars.get(i)?;
                i += 1;
                members.push((next, true));
            }
            other => members.push((other, false)),
        }
        first = false;
    }
    let mut items = Vec::new();
    let mut k = 0;
    while k < members.len() {
        let (c, _) = members[k];
        let is_range = k + 2 < members.len() && members[k + 1] == ('-', false);
        if is_range {
            items.push(SetItem::Range(c, members[k + 2].0));
            k += 3;
        } else {
            items.push(SetItem::Char(c));
            k += 1;
        }
    }
    Some((CharTest::Set { negated, items }, i))
}

/// Two-pointer wildcard matching with backtracking to the most recent star only.
fn match_tokens(text: &[char], tokens: &[Token]) -> bool {
    let (mut t, mut p) = (0usize, 0usize);
    // (token index after the star, text index the star currently stops at)
    let mut last_star: Option<(usize, usize)> = None;
    while t < text.len() {
        match tokens.get(p) {
            Some(Token::Star) => {
                p += 1;
                last_star = Some((p, t));
            }
            Some(Token::One(test)) if test.matches(text[t]) => {
                p += 1;
                t += 1;
            }
            _ => match last_star {
                Some((after_star, star_t)) => {
                    // Let the star swallow one more character and retry.
                    p = after_star;
                    t = star_t + 1;
                    last_star = Some((after_star, star_t + 1));
                }
                None => return false,
            },
        }
    }
    tokens[p..].iter().all(|tok| *tok == Token::Star)
}

#[cfg(test)]
mod tests {
    use super::*;

    // Examples from the AutoLISP reference, "wcmatch".
    #[test]
    fn reference_examples() {
        assert!(wcmatch("Name", "N*"));
        assert!(wcmatch("Name", "???,~*m*,N*"));
        assert!(!wcmatch("Name", "*`,*"));
        assert!(!wcmatch("Name", "?"));
        assert!(wcmatch("Name", "~*m*,N*"));
        assert!(!wcmatch("Name", "~*m*"));
        assert!(wcmatch("Name,Other", "*`,*"));
        assert!(wcmatch("Name", "n*,N*"));
        assert!(!wcmatch("Name", "n*"));
    }

    #[test]
    fn single_character_classes() {
        assert!(wcmatch("A1", "@#"));
        assert!(!wcmatch("AA", "@#"));
        assert!(!wcmatch("11", "@#"));
        assert!(wcmatch("a-b", "@.@"));
        assert!(wcmatch("a b", "@.@"));
        assert!(!wcmatch("aXb", "@.@"));
        assert!(!wcmatch("a1b", "@.@"));
        assert!(wcmatch("é", "@"));
        assert!(wcmatch("xyz", "???"));
        assert!(!wcmatch("xy", "???"));
        assert!(!wcmatch("xyzw", "???"));
    }

    #[test]
    fn star_matches_any_sequence_including_empty() {
        assert!(wcmatch("", "*"));
        assert!(wcmatch("", "**"));
        assert!(!wcmatch("", "?"));
        assert!(wcmatch("", ""));
        assert!(!wcmatch("a", ""));
        assert!(wcmatch("LAYER-01", "LAYER*"));
        assert!(wcmatch("LAYER", "LAYER*"));
        assert!(wcmatch("abcabd", "*abd"));
        assert!(wcmatch("mississippi", "m*iss*ppi"));
        assert!(!wcmatch("mississippi", "m*iss*ppx"));
        assert!(wcmatch("abc", "a*b*c"));
        assert!(wcmatch("ac", "a*c"));
        assert!(!wcmatch("ab", "a*c"));
        assert!(wcmatch("aXYb", "a*?b"));
        assert!(!wcmatch("ab", "a*?b"));
    }

    #[test]
    fn case_sensitive() {
        assert!(!wcmatch("name", "NAME"));
        assert!(wcmatch("NAME", "NAME"));
        assert!(!wcmatch("name", "[A-Z]*"));
    }

    #[test]
    fn bracket_sets_and_ranges() {
        assert!(wcmatch("b", "[abc]"));
        assert!(!wcmatch("d", "[abc]"));
        assert!(wcmatch("d", "[~abc]"));
        assert!(!wcmatch("a", "[~abc]"));
        assert!(wcmatch("5", "[0-9]"));
        assert!(wcmatch("Q", "[A-Z]"));
        assert!(!wcmatch("q", "[A-Z]"));
        assert!(wcmatch("q", "[A-Za-z]"));
        assert!(wcmatch("-", "[-a]"));
        assert!(wcmatch("-", "[a-]"));
        assert!(!wcmatch("b", "[a-]"));
        assert!(wcmatch("]", "[]a]"));
        assert!(wcmatch("]", "[~a]"));
        assert!(wcmatch("DIM-12", "DIM-[0-9][0-9]"));
        assert!(!wcmatch("DIM-1A", "DIM-[0-9][0-9]"));
        // Brackets in the middle of stars.
        assert!(wcmatch("WALL_EXT", "*[_-]EXT"));
        assert!(wcmatch("WALL-EXT", "*[_-]EXT"));
        assert!(!wcmatch("WALL EXT", "*[_-]EXT"));
    }

    #[test]
    fn comma_inside_brackets_is_literal() {
        assert!(wcmatch(",", "[,;]"));
        assert!(wcmatch(";", "[,;]"));
        assert!(!wcmatch("x", "[,;]"));
    }

    #[test]
    fn unclosed_bracket_is_literal() {
        assert!(wcmatch("[ab", "[ab"));
        assert!(!wcmatch("a", "[ab"));
    }

    #[test]
    fn backquote_escapes() {
        assert!(wcmatch("*", "`*"));
        assert!(!wcmatch("a", "`*"));
        assert!(wcmatch("a#b", "a`#b"));
        assert!(!wcmatch("a1b", "a`#b"));
        assert!(wcmatch("~x", "`~x"));
        assert!(wcmatch("a,b", "a`,b"));
        assert!(wcmatch("`", "`"));
        assert!(wcmatch("]", "[`]]"));
        assert!(wcmatch("-", "[a`-z]"));
        assert!(!wcmatch("m", "[a`-z]"));
    }

    #[test]
    fn tilde_negates_each_alternative() {
        assert!(!wcmatch("ABC", "~A*,B*"));
        assert!(wcmatch("XYZ", "~A*,B*"));
        assert!(wcmatch("BCD", "~A*,B*"));
        assert!(wcmatch("a~b", "a~b"));
        assert!(wcmatch("", "~?"));
        assert!(!wcmatch("", "~"));
        assert!(wcmatch("x", "~"));
    }

    #[test]
    fn empty_alternatives() {
        assert!(wcmatch("", "a,"));
        assert!(wcmatch("", ",a"));
        assert!(!wcmatch("b", "a,"));
    }

    #[test]
    fn compiled_pattern_reused() {
        let layers = WcPattern::new("WALL*,~*-OLD");
        assert!(layers.matches("WALL-EXT"));
        assert!(layers.matches("DOOR"));
        assert!(!layers.matches("DOOR-OLD"));
        assert!(layers.matches("WALL-OLD"));
    }

    #[test]
    fn pathological_pattern_is_fast() {
        let text = "a".repeat(20_000);
        let pattern = "*a*a*a*a*a*a*a*a*a*a*b";
        let start = std::time::Instant::now();
        assert!(!wcmatch(&text, pattern));
        // Not a timing assertion: exponential backtracking would not finish at all.
        let _ = start.elapsed();
        assert!(wcmatch(&(text.clone() + "b"), pattern));
    }

    /// A direct recursive matcher used as the oracle for random tests.
    fn oracle(text: &[char], tokens: &[Token]) -> bool {
        match tokens.split_first() {
            None => text.is_empty(),
            Some((Token::Star, rest)) => (0..=text.len()).any(|k| oracle(&text[k..], rest)),
            Some((Token::One(test), rest)) => {
                !text.is_empty() && test.matches(text[0]) && oracle(&text[1..], rest)
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        #[test]
        fn agrees_with_recursive_oracle(text in "[ab1 ]{0,8}", pattern in "[ab1*?#@.]{0,6}") {
            let chars: Vec<char> = text.chars().collect();
            let want = compile(&pattern).iter().any(|alt| oracle(&chars, &alt.tokens) != alt.negated);
            proptest::prop_assert_eq!(wcmatch(&text, &pattern), want);
        }
    }
}
