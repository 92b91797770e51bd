//! Strings: building, measuring, converting, and reading values from text.

use crate::builtin;
use crate::lang::builtin::{bad_arg, Builtin, MANY};
use std::rc::Rc;

use crate::lang::error::{err, Exn, LResult};
use crate::lang::reader::read_one;
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!(
        "strcat",
        "(strcat string...)",
        "The strings joined into one.",
        0,
        MANY,
        strcat
    ),
    builtin!(
        "strlen",
        "(strlen [string...])",
        "The total number of characters of the strings.",
        0,
        MANY,
        strlen
    ),
    builtin!(
        "ascii",
        "(ascii string)",
        "The character code of the first character (0 for \"\").",
        1,
        1,
        ascii
    ),
    builtin!(
        "chr",
        "(chr code)",
        "A one-character string from a character code.",
        1,
        1,
        chr
    ),
    builtin!("itoa", "(itoa int)", "The integer as a string.", 1, 1, itoa),
    builtin!(
        "read",
        "(read [string])",
        "The first expression read from the string (nil for none).",
        0,
        1,
        read
    ),
    builtin!(
        "vl-princ-to-string",
        "(vl-princ-to-string x)",
        "What princ would print for x, as a string.",
        1,
        1,
        princ_to_string
    ),
    builtin!(
        "vl-prin1-to-string",
        "(vl-prin1-to-string x)",
        "What prin1 would print for x, as a string.",
        1,
        1,
        prin1_to_string
    ),
    builtin!(
        "vl-string->list",
        "(vl-string->list string)",
        "The character codes of a string.",
        1,
        1,
        string_to_list
    ),
    builtin!(
        "vl-list->string",
        "(vl-list->string codes)",
        "A string from a list of character codes.",
        1,
        1,
        list_to_string
    ),
];

/// AutoLISP's string length limit: `strlen` answers a 32-bit integer.
const MAX_STRING: usize = i32::MAX as usize;

/// An empty string with room for `len` bytes: within AutoLISP's string limit and the memory
/// budget, and reserved fallibly, so a huge result is an error before any allocation (an
/// address-space limit below the budget included), never an abort.
pub fn string_with_room(len: usize) -> Result<String, Exn> {
    check_string_room(len)?;
    let mut s = String::new();
    s.try_reserve_exact(len)
        .map_err(|_| crate::lang::memory::system_refused(len))?;
    Ok(s)
}

/// An error unless a string of `len` bytes is within AutoLISP's limit and the memory budget.
pub fn check_string_room(len: usize) -> Result<(), Exn> {
    if len > MAX_STRING {
        return Err(err(format!(
            "string too long: {len} bytes (strings hold at most {MAX_STRING})"
        )));
    }
    crate::lang::memory::reserve(len)
}

/// A string value made by `f` from text of at most `len` bytes, within the limits of
/// `string_with_room` (for builtins that copy or transform a string).
pub fn build_string(len: usize, f: impl FnOnce(&mut String)) -> LResult {
    // `f` works on a temporary of about the same size.
    crate::lang::memory::reserve(len.saturating_mul(2))?;
    let mut s = string_with_room(len)?;
    f(&mut s);
    // Moved into the value, not copied.
    Ok(Value::Str(Rc::new(s)))
}

fn strcat(it: &mut Interp, a: &[Value]) -> LResult {
    let mut len = 0usize;
    for x in a {
        len = len.saturating_add(it.string(x)?.len());
    }
    let mut s = string_with_room(len)?;
    for x in a {
        s.push_str(it.string(x)?);
    }
    Ok(Value::Str(Rc::new(s)))
}

fn strlen(it: &mut Interp, a: &[Value]) -> LResult {
    let mut n = 0usize;
    for x in a {
        n += it.string(x)?.chars().count();
    }
    i32::try_from(n).map(Value::Int).map_err(|_| {
        err(format!(
            "string too long: {n} characters (strlen counts to {MAX_STRING})"
        ))
    })
}

fn ascii(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?;
    Ok(Value::Int(s.chars().next().map_or(0, |c| c as i32)))
}

fn chr(it: &mut Interp, a: &[Value]) -> LResult {
    let c = it.int(&a[0])?;
    match u32::try_from(c).ok().and_then(char::from_u32) {
        Some('\0') => Ok(Value::str("")),
        Some(ch) => Ok(Value::str(ch.encode_utf8(&mut [0; 4]))),
        None => Err(err(format!("bad argument value: character code {c}"))),
    }
}

fn itoa(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::str(&it.int(&a[0])?.to_string()))
}

fn read(it: &mut Interp, a: &[Value]) -> LResult {
    let Some(s) = a.first() else {
        return Ok(Value::Nil);
    };
    let text = it.string(s)?.to_string();
    let r = read_one(&text, &mut it.syms);
    it.sync_cells();
    match r {
        Ok(Some((v, _))) => Ok(v),
        // Nothing read: empty text is nil, an unfinished or stray bracket is AutoLISP's error.
        Ok(None) => match crate::lang::reader::scan(&text) {
            crate::lang::reader::Scan::Incomplete(e) if e.message.contains("string") => {
                Err(err("malformed string on input"))
            }
            crate::lang::reader::Scan::Incomplete(e) if e.message.contains("comment") => {
                Ok(Value::Nil)
            }
            crate::lang::reader::Scan::Incomplete(_) => Err(err("malformed list on input")),
            crate::lang::reader::Scan::Invalid(e) => Err(err(e.message)),
            crate::lang::reader::Scan::Complete => Ok(Value::Nil),
        },
        Err(e) => Err(err(if e.message.starts_with("malformed list") {
            "malformed list on input".to_string()
        } else {
            e.message
        })),
    }
}

fn princ_to_string(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Str(Rc::new(it.try_print_string(&a[0], false)?)))
}

fn prin1_to_string(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Str(Rc::new(it.try_print_string(&a[0], true)?)))
}

fn string_to_list(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?;
    crate::lang::memory::reserve(s.len().saturating_mul(super::lists::CONS_BYTES))?;
    Ok(Value::list(
        s.chars().map(|c| Value::Int(c as i32)).collect::<Vec<_>>(),
    ))
}

fn list_to_string(it: &mut Interp, a: &[Value]) -> LResult {
    let n = it.list_arg(&a[0])?.iter().count();
    let mut s = string_with_room(n)?;
    for x in it.list_arg(&a[0])?.iter() {
        let c = match x {
            Value::Int(c) => *c,
            other => return Err(bad_arg(it, "fixnump", other)),
        };
        s.push(
            u32::try_from(c)
                .ok()
                .and_then(char::from_u32)
                .unwrap_or('\u{FFFD}'),
        );
    }
    Ok(Value::Str(Rc::new(s)))
}
