//! Handle relocation: records copied from one DXF document into another get new handles,
//! and every group that points at a record by handle follows them (ezdxf's xref module and
//! AutoCAD's INSERT of a drawing do the same). A pointer to a record that was not brought
//! along is pointed at the target's equivalent when the caller knows one, else cleared:
//! a reactor or an extension dictionary is dropped, any other pointer becomes the null
//! handle "0", so nothing ever names an unrelated record of the target.

use super::record::TagList;

/// Whether a group code holds a handle of another record (DXF reference, "Group code value
/// types"). 320–329 are left alone: AutoCAD does not translate them either.
pub fn is_pointer(code: i32) -> bool {
    matches!(code, 330..=369 | 390..=399 | 480..=481 | 1005)
}

pub fn parse_handle(v: &str) -> Option<u64> {
    u64::from_str_radix(v.trim(), 16).ok()
}

/// The own handles (group 5, or 105 of a DIMSTYLE) of each record of a group list, in order.
pub fn own_handles(t: &TagList) -> Vec<u64> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, (c, v)) in t.iter().enumerate() {
        if c == 0 {
            start = i;
        } else if is_own_handle(c, i, start) {
            out.extend(parse_handle(v));
        }
    }
    out
}

fn is_own_handle(code: i32, i: usize, record_start: usize) -> bool {
    (code == 5 || code == 105) && i <= record_start + 2
}

/// An application group being gathered: its opening name ("{ACAD_REACTORS"), its groups, and
/// whether it is kept.
type AppGroup = (String, Vec<(i32, String)>, bool);

/// `t` with every own handle and pointer passed through `resolve` (old handle → new). Own
/// handles that do not resolve are kept; pointers that do not resolve are cleared (see the
/// module documentation). SORTENTSTABLE's sort handles (group 5 in its body) follow too.
pub fn relocate(t: &TagList, resolve: &dyn Fn(u64) -> Option<u64>) -> TagList {
    let map = |v: &str| -> Option<String> {
        let h = parse_handle(v)?;
        if h == 0 {
            return Some(v.to_string());
        }
        resolve(h).map(|n| format!("{n:X}"))
    };
    let mut out = TagList::new();
    // An application group ({ACAD_REACTORS ... }) is gathered first: it may be dropped whole.
    let mut app: Option<AppGroup> = None;
    let mut start = 0;
    let mut sortents = false;
    for (i, (c, v)) in t.iter().enumerate() {
        if c == 0 {
            start = i;
            sortents = v == "SORTENTSTABLE";
        }
        if let Some((name, groups, keep)) = &mut app {
            if c == 102 && v.trim() == "}" {
                let empty = groups.is_empty();
                if *keep && !(empty && name == "{ACAD_REACTORS") {
                    out.push(102, name);
                    for (c, v) in groups.iter() {
                        out.push(*c, v);
                    }
                    out.push(102, "}");
                }
                app = None;
                continue;
            }
            if !is_pointer(c) {
                groups.push((c, v.to_string()));
                continue;
            }
            match map(v) {
                Some(n) => groups.push((c, n)),
                None if name == "{ACAD_REACTORS" => {}
                // An extension dictionary left behind: the record has none.
                None if name == "{ACAD_XDICTIONARY" => *keep = false,
                None => groups.push((c, "0".to_string())),
            }
            continue;
        }
        if c == 102 && v.starts_with('{') {
            app = Some((v.to_string(), Vec::new(), true));
            continue;
        }
        if is_own_handle(c, i, start) || (sortents && c == 5) {
            match map(v) {
                Some(n) => out.push(c, &n),
                None => out.push(c, v),
            }
        } else if is_pointer(c) {
            out.push(c, map(v).as_deref().unwrap_or("0"));
        } else {
            out.push(c, v);
        }
    }
    // An application group the file never closed is written back as it was read.
    if let Some((name, groups, _)) = app {
        out.push(102, &name);
        for (c, v) in &groups {
            out.push(*c, v);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    fn tags(groups: &[(i32, &str)]) -> TagList {
        TagList::of(groups)
    }

    #[test]
    fn pointers_follow_and_strays_are_cleared() {
        let t = tags(&[
            (0, "HATCH"),
            (5, "2A"),
            (102, "{ACAD_REACTORS"),
            (330, "2B"),
            (330, "99"),
            (102, "}"),
            (102, "{ACAD_XDICTIONARY"),
            (360, "77"),
            (102, "}"),
            (330, "1F"),
            (100, "AcDbEntity"),
            (8, "0"),
            (340, "99"),
            (330, "2B"),
            (1001, "APP"),
            (1005, "2A"),
            (0, "SEQEND"),
            (5, "2C"),
            (330, "2A"),
        ]);
        let m: HashMap<u64, u64> = [(0x2A, 0x100), (0x2B, 0x101), (0x1F, 0x102), (0x2C, 0x103)]
            .into_iter()
            .collect();
        let r = relocate(&t, &|h| m.get(&h).copied());
        let want = tags(&[
            (0, "HATCH"),
            (5, "100"),
            (102, "{ACAD_REACTORS"),
            (330, "101"),
            (102, "}"),
            (330, "102"),
            (100, "AcDbEntity"),
            (8, "0"),
            (340, "0"),
            (330, "101"),
            (1001, "APP"),
            (1005, "100"),
            (0, "SEQEND"),
            (5, "103"),
            (330, "100"),
        ]);
        assert_eq!(r, want);
        assert_eq!(own_handles(&t), vec![0x2A, 0x2C]);
    }
}
