//! A DXF record kept as its group list (ezdxf's `DXFTagStorage`): what the model does not
//! understand travels with the drawing and is written back unchanged. Values are kept as the
//! text they were read as, in one buffer per record, so writing back is exact and cheap.

use std::fmt::Write as _;

/// Group codes and their text values, in file order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TagList {
    text: String,
    /// (group code, end of its value in `text`).
    tags: Vec<(i16, u32)>,
}

impl TagList {
    /// A list of the given groups (tests build records this way).
    #[cfg(test)]
    pub fn of(groups: &[(i32, &str)]) -> TagList {
        let mut t = TagList::new();
        for (c, v) in groups {
            t.push(*c, v);
        }
        t
    }

    pub fn new() -> TagList {
        TagList::default()
    }

    pub fn push(&mut self, code: i32, value: &str) {
        self.text.push_str(value);
        self.tags.push((code as i16, self.text.len() as u32));
    }

    pub fn len(&self) -> usize {
        self.tags.len()
    }

    pub fn is_empty(&self) -> bool {
        self.tags.is_empty()
    }

    /// The i-th group.
    pub fn at(&self, i: usize) -> (i32, &str) {
        let start = if i == 0 {
            0
        } else {
            self.tags[i - 1].1 as usize
        };
        let (code, end) = self.tags[i];
        (code as i32, &self.text[start..end as usize])
    }

    pub fn iter(&self) -> impl Iterator<Item = (i32, &str)> + '_ {
        let mut start = 0usize;
        self.tags.iter().map(move |&(code, end)| {
            let v = &self.text[start..end as usize];
            start = end as usize;
            (code as i32, v)
        })
    }

    /// The value of the first group with this code.
    pub fn get(&self, code: i32) -> Option<&str> {
        self.iter().find(|(c, _)| *c == code).map(|(_, v)| v)
    }

    /// The record type (the value of its leading 0 group).
    pub fn type_name(&self) -> &str {
        match self.tags.first() {
            Some((0, _)) => self.at(0).1,
            _ => "",
        }
    }

    /// The record's handle (group 5, or 105 for DIMSTYLE records).
    pub fn handle(&self) -> Option<u64> {
        self.iter()
            .take(4)
            .find(|(c, _)| *c == 5 || *c == 105)
            .and_then(|(_, v)| u64::from_str_radix(v.trim(), 16).ok())
    }

    /// A copy with the first group of `code` (within the first record, before any 0 group
    /// past the start) set to `value`; inserted after group `after` (or at the end of the
    /// first record) when missing.
    pub fn with(&self, code: i32, value: &str, after: i32) -> TagList {
        let first_end = self.first_record_end();
        let mut out = TagList::new();
        let mut done = false;
        let mut insert_at = None;
        for (i, (c, v)) in self.iter().enumerate() {
            if !done && i < first_end && c == code {
                out.push(c, value);
                done = true;
                continue;
            }
            out.push(c, v);
            if c == after && i < first_end && insert_at.is_none() {
                insert_at = Some(out.len());
            }
        }
        if done {
            return out;
        }
        let at = insert_at.unwrap_or(first_end);
        let mut res = TagList::new();
        for (i, (c, v)) in out.iter().enumerate() {
            if i == at {
                res.push(code, value);
            }
            res.push(c, v);
        }
        if at >= out.len() {
            res.push(code, value);
        }
        res
    }

    /// The number of groups of the first record (up to the next 0 group).
    pub fn first_record_end(&self) -> usize {
        self.iter()
            .skip(1)
            .position(|(c, _)| c == 0)
            .map_or(self.len(), |i| i + 1)
    }

    /// The groups as DXF text (codes right-justified in three columns).
    pub fn write_to(&self, out: &mut String) {
        for (c, v) in self.iter() {
            let _ = writeln!(out, "{c:>3}");
            out.push_str(v);
            out.push('\n');
        }
    }

    /// Read back group/value line pairs written by the project's writers (trusted text).
    pub fn from_dxf_text(s: &str) -> TagList {
        let mut t = TagList::new();
        let mut lines = s.lines();
        while let (Some(c), Some(v)) = (lines.next(), lines.next()) {
            if let Ok(c) = c.trim().parse::<i32>() {
                if v.contains("\\U+") {
                    t.push(c, &super::dxfin::tags::decode_unicode_escapes(v));
                } else {
                    t.push(c, v);
                }
            }
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_and_insert() {
        let mut t = TagList::new();
        t.push(0, "LAYER");
        t.push(2, "A");
        t.push(70, "0");
        let u = t.with(62, "3", 70);
        assert_eq!(
            u.iter().collect::<Vec<_>>(),
            vec![(0, "LAYER"), (2, "A"), (70, "0"), (62, "3")]
        );
        let v = u.with(2, "B", 0);
        assert_eq!(v.get(2), Some("B"));
        assert_eq!(v.len(), 4);
    }
}
