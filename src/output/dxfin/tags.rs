//! The tag stage of the DXF reader (ezdxf's `ascii_tags_loader` / `binary_tags_loader`):
//! bytes in, (group code, text value, position) out. It knows nothing of entities. ASCII and
//! binary files, the code page (`$DWGCODEPAGE` before R2007, UTF-8 from AC1021) and the
//! `\U+XXXX` escapes of old files are all settled here, so later stages see Unicode text.
//!
//! Values stay text (a binary file's numbers are printed in their shortest round-trip form),
//! so a record the model does not understand is written back exactly as it was read.

use std::borrow::Cow;

use encoding_rs::Encoding;

use super::DxfReadError;

/// The first 22 bytes of a binary DXF file.
pub const BINARY_SENTINEL: &[u8] = b"AutoCAD Binary DXF\r\n\x1a\0";

/// Where a tag was read: a 1-based line (ASCII) or a byte offset (binary).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pos {
    Line(usize),
    Byte(usize),
}

impl std::fmt::Display for Pos {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Pos::Line(n) => write!(f, "line {n}"),
            Pos::Byte(n) => write!(f, "byte {n}"),
        }
    }
}

/// One group: code, decoded value, position of its group-code line (or byte).
#[derive(Clone, Debug, PartialEq)]
pub struct Tag<'a> {
    pub code: i32,
    pub value: Cow<'a, str>,
    pub pos: Pos,
}

/// How a group code's value is typed (DXF reference, "Group code value types").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueType {
    Str,
    Float,
    Int16,
    Int32,
    Int64,
    Bool,
    Binary,
}

/// The group codes a DXF file can hold (AutoLISP's negative codes -5..-1 included).
const VALID_CODES: std::ops::RangeInclusive<i32> = -5..=1071;

pub fn value_type(code: i32) -> ValueType {
    match code {
        10..=59 | 110..=149 | 210..=239 | 460..=469 | 1010..=1059 => ValueType::Float,
        60..=79 | 170..=179 | 270..=289 | 370..=389 | 400..=409 | 1060..=1070 => ValueType::Int16,
        90..=99 | 420..=429 | 440..=459 | 1071 => ValueType::Int32,
        160..=169 => ValueType::Int64,
        290..=299 => ValueType::Bool,
        310..=319 | 1004 => ValueType::Binary,
        _ => ValueType::Str,
    }
}

/// Whether a numeric value is well formed (the reader checks every one, so a bad number is
/// reported where it is, not when some later stage trips on it).
pub fn check_number(code: i32, v: &str) -> bool {
    let t = v.trim();
    match value_type(code) {
        ValueType::Float => t.parse::<f64>().is_ok(),
        ValueType::Int16 | ValueType::Int32 | ValueType::Int64 | ValueType::Bool => {
            t.parse::<i64>().is_ok()
                // Some writers put "1.0" in integer groups; AutoCAD and ezdxf accept it.
                || t.parse::<f64>().is_ok_and(|x| x.fract() == 0.0 && x.abs() < 9.2e18)
        }
        _ => true,
    }
}

/// A damaged number read as its longest well-formed prefix ("-6,5" → "-6", as ezdxf's
/// recover reads it), or 0.
fn salvage_number(code: i32, v: &str) -> String {
    let t = v.trim();
    let float = value_type(code) == ValueType::Float;
    (1..=t.len())
        .rev()
        .filter(|&n| t.is_char_boundary(n))
        .map(|n| &t[..n])
        .find(|p| p.parse::<i64>().is_ok() || float && p.parse::<f64>().is_ok_and(f64::is_finite))
        .map_or_else(|| "0".to_string(), |p| p.to_string())
}

/// The text encoding of a DXF file: its version and code page.
#[derive(Clone, Copy, Debug)]
pub struct FileEncoding {
    /// `$ACADVER`, e.g. "AC1015" ("AC1009" when absent, as R12 files may omit it).
    pub version: &'static str,
    pub encoding: &'static Encoding,
}

impl FileEncoding {
    pub fn is_unicode(&self) -> bool {
        self.version >= "AC1021"
    }
}

const VERSIONS: [&str; 11] = [
    "AC1009", "AC1012", "AC1014", "AC1015", "AC1018", "AC1021", "AC1024", "AC1027", "AC1032",
    "AC1006", "AC1004",
];

/// The version string as one of the known constants (unknown ones map to the nearest
/// era: anything newer than R2018 is written as read, as R2018).
pub fn known_version(v: &str) -> &'static str {
    let v = v.trim().to_ascii_uppercase();
    VERSIONS
        .iter()
        .copied()
        .find(|k| *k == v)
        .unwrap_or(if v.as_str() > "AC1032" {
            "AC1032"
        } else if v.as_str() < "AC1009" {
            "AC1009"
        } else {
            "AC1015"
        })
}

/// The encoding of a `$DWGCODEPAGE` value (ANSI_1252, ANSI_936, DOS866 ...), Windows-1252
/// for unknown ones as AutoCAD does.
pub fn code_page(name: &str) -> &'static Encoding {
    let n = name.trim().to_ascii_uppercase();
    let label = match n.strip_prefix("ANSI_").or_else(|| n.strip_prefix("DOS")) {
        Some("932") => "shift_jis".to_string(),
        Some("936") => "gbk".to_string(),
        Some("949") => "euc-kr".to_string(),
        Some("950") => "big5".to_string(),
        Some("866") => "ibm866".to_string(),
        Some(num) if num.len() == 3 || num.len() == 4 => format!("windows-{num}"),
        _ => "windows-1252".to_string(),
    };
    Encoding::for_label(label.as_bytes()).unwrap_or(encoding_rs::WINDOWS_1252)
}

/// A group code and its raw value, before decoding.
struct Raw<'a> {
    code: i32,
    value: RawValue<'a>,
    pos: Pos,
}

enum RawValue<'a> {
    Bytes(&'a [u8]),
    Float(f64),
    Int(i64),
    Hex(&'a [u8]),
}

/// The tag reader over a whole file.
pub struct Tagger<'a> {
    data: &'a [u8],
    at: usize,
    line: usize,
    binary: Option<BinaryForm>,
    enc: FileEncoding,
    /// Lenient mode: lines that cannot be tags are skipped and counted.
    recover: bool,
    pub recovered: usize,
}

#[derive(Clone, Copy)]
struct BinaryForm {
    two_byte_codes: bool,
}

impl<'a> Tagger<'a> {
    /// A reader over `data`; decides ASCII or binary and reads the header's version and code
    /// page first.
    pub fn new(data: &'a [u8], recover: bool) -> Result<Tagger<'a>, DxfReadError> {
        let binary = if data.starts_with(BINARY_SENTINEL) {
            let two = data.get(BINARY_SENTINEL.len() + 1) == Some(&0);
            Some(BinaryForm {
                two_byte_codes: two,
            })
        } else {
            if data.iter().all(|b| b.is_ascii_whitespace()) {
                return Err(DxfReadError::at(None, "the file is empty"));
            }
            if let Some(i) = data.iter().take(4096).position(|b| *b == 0) {
                return Err(DxfReadError::at(
                    Some(Pos::Byte(i)),
                    "not a DXF file: binary content without the \"AutoCAD Binary DXF\" header",
                ));
            }
            None
        };
        let mut t = Tagger {
            data,
            at: if binary.is_some() {
                BINARY_SENTINEL.len()
            } else {
                0
            },
            line: 1,
            binary,
            enc: FileEncoding {
                version: "AC1009",
                encoding: encoding_rs::WINDOWS_1252,
            },
            recover,
            recovered: 0,
        };
        t.enc = t.clone_state().sniff_encoding();
        Ok(t)
    }

    fn clone_state(&self) -> Tagger<'a> {
        Tagger {
            data: self.data,
            at: self.at,
            line: self.line,
            binary: self.binary,
            enc: self.enc,
            recover: true,
            recovered: 0,
        }
    }

    pub fn encoding(&self) -> FileEncoding {
        self.enc
    }

    pub fn is_binary(&self) -> bool {
        self.binary.is_some()
    }

    /// `$ACADVER` and `$DWGCODEPAGE` from the header (the first section).
    fn sniff_encoding(mut self) -> FileEncoding {
        let mut version = "AC1009";
        let mut cp = encoding_rs::WINDOWS_1252;
        let mut var = Vec::new();
        while let Some(Ok(raw)) = self.next_raw() {
            let RawValue::Bytes(b) = raw.value else {
                continue;
            };
            match raw.code {
                0 if b.trim_ascii() == b"ENDSEC" => break,
                9 => var = b.trim_ascii().to_vec(),
                1 if var == b"$ACADVER" => {
                    version = known_version(&String::from_utf8_lossy(b));
                }
                3 if var == b"$DWGCODEPAGE" => cp = code_page(&String::from_utf8_lossy(b)),
                _ => {}
            }
        }
        FileEncoding {
            version,
            encoding: if version >= "AC1021" {
                encoding_rs::UTF_8
            } else {
                cp
            },
        }
    }

    fn pos(&self) -> Pos {
        match self.binary {
            Some(_) => Pos::Byte(self.at),
            None => Pos::Line(self.line),
        }
    }

    /// One line without its line break; `None` at the end of the data.
    fn line(&mut self) -> Option<&'a [u8]> {
        if self.at >= self.data.len() {
            return None;
        }
        let rest = &self.data[self.at..];
        let (mut l, adv) = match memchr(b'\n', rest) {
            Some(i) => (&rest[..i], i + 1),
            None => (rest, rest.len()),
        };
        if let [head @ .., b'\r'] = l {
            l = head;
        }
        self.at += adv;
        self.line += 1;
        Some(l)
    }

    fn next_raw(&mut self) -> Option<Result<Raw<'a>, DxfReadError>> {
        match self.binary {
            Some(form) => self.next_binary(form),
            None => self.next_ascii(),
        }
    }

    fn next_ascii(&mut self) -> Option<Result<Raw<'a>, DxfReadError>> {
        loop {
            let pos = self.pos();
            let code_line = self.line()?;
            let text = code_line.trim_ascii();
            if text.is_empty() && self.at >= self.data.len() {
                return None;
            }
            let parsed = std::str::from_utf8(text)
                .ok()
                .and_then(|s| s.parse::<i32>().ok());
            // A number outside DXF's codes is damage, not a code: kept, it would be written
            // back as another (codes are stored in 16 bits) and the copy would not read.
            let code = parsed.filter(|c| VALID_CODES.contains(c));
            let (value_at, value_line) = (self.at, self.line);
            let Some(value) = self.line() else {
                if self.recover {
                    self.recovered += 1;
                    return None;
                }
                return Some(Err(DxfReadError::at(
                    Some(pos),
                    "the file ends after a group code, without its value (odd number of lines: truncated file?)",
                )));
            };
            // A NUL ends a string for the C readers; kept, it would make the saved copy look
            // binary to every reader (this one's included), so it is damage here too.
            let value = match memchr(0, value) {
                None => value,
                Some(_) if !self.recover => {
                    return Some(Err(DxfReadError::at(
                        Some(Pos::Line(value_line)),
                        "a NUL byte in a value: binary content in an ASCII DXF",
                    )))
                }
                Some(i) => {
                    self.recovered += 1;
                    &value[..i]
                }
            };
            match code {
                Some(code) => {
                    return Some(Ok(Raw {
                        code,
                        value: RawValue::Bytes(value),
                        pos,
                    }))
                }
                None if self.recover => {
                    // Realign: drop one line and try again from the next.
                    self.recovered += 1;
                    self.at = value_at;
                    self.line = value_line;
                }
                None => {
                    let message = match parsed {
                        Some(c) => format!(
                            "group code {c} is out of range (DXF codes run from {} to {})",
                            VALID_CODES.start(),
                            VALID_CODES.end()
                        ),
                        None => format!(
                            "expected a group code (an integer), found {:?}",
                            String::from_utf8_lossy(&code_line[..code_line.len().min(40)])
                        ),
                    };
                    return Some(Err(DxfReadError::at(Some(pos), message)));
                }
            }
        }
    }

    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        let s = self.data.get(self.at..self.at + n)?;
        self.at += n;
        Some(s)
    }

    fn next_binary(&mut self, form: BinaryForm) -> Option<Result<Raw<'a>, DxfReadError>> {
        if self.at >= self.data.len() {
            return None;
        }
        let pos = self.pos();
        let truncated = move || {
            Some(Err(DxfReadError::at(
                Some(pos),
                "binary DXF truncated inside a group",
            )))
        };
        let code = if form.two_byte_codes {
            match self.take(2) {
                Some(b) => i16::from_le_bytes([b[0], b[1]]) as i32,
                None => return truncated(),
            }
        } else {
            match self.take(1) {
                Some([255]) => match self.take(2) {
                    Some(b) => i16::from_le_bytes([b[0], b[1]]) as i32,
                    None => return truncated(),
                },
                Some(b) => b[0] as i32,
                None => return truncated(),
            }
        };
        let value = match value_type(code) {
            ValueType::Float => self
                .take(8)
                .map(|b| RawValue::Float(f64::from_le_bytes(b.try_into().unwrap_or([0; 8])))),
            ValueType::Int16 => self
                .take(2)
                .map(|b| RawValue::Int(i16::from_le_bytes([b[0], b[1]]) as i64)),
            ValueType::Int32 => self
                .take(4)
                .map(|b| RawValue::Int(i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as i64)),
            ValueType::Int64 => self
                .take(8)
                .map(|b| RawValue::Int(i64::from_le_bytes(b.try_into().unwrap_or([0; 8])))),
            ValueType::Bool => self.take(1).map(|b| RawValue::Int(b[0] as i64)),
            ValueType::Binary => match self.take(1) {
                Some(n) => {
                    let n = n[0] as usize;
                    self.take(n).map(RawValue::Hex)
                }
                None => None,
            },
            ValueType::Str => {
                let rest = &self.data[self.at..];
                memchr(0, rest).map(|i| {
                    self.at += i + 1;
                    RawValue::Bytes(&rest[..i])
                })
            }
        };
        match value {
            Some(value) => Some(Ok(Raw { code, value, pos })),
            None => truncated(),
        }
    }

    /// Text of a raw string value in the file's encoding, `\U+XXXX` escapes decoded before
    /// R2007 (ezdxf does the same).
    fn decode(&self, b: &'a [u8]) -> Cow<'a, str> {
        let s: Cow<'a, str> = if b.is_ascii() {
            // ASCII is valid UTF-8 and the same in every supported code page.
            Cow::Borrowed(std::str::from_utf8(b).unwrap_or_default())
        } else {
            let (s, _) = self.enc.encoding.decode_without_bom_handling(b);
            s
        };
        if !self.enc.is_unicode() && s.contains("\\U+") {
            Cow::Owned(decode_unicode_escapes(&s))
        } else {
            s
        }
    }
}

impl<'a> Iterator for Tagger<'a> {
    type Item = Result<Tag<'a>, DxfReadError>;

    fn next(&mut self) -> Option<Self::Item> {
        let raw = match self.next_raw()? {
            Ok(r) => r,
            Err(e) => return Some(Err(e)),
        };
        let value: Cow<'a, str> = match raw.value {
            RawValue::Bytes(b) => {
                let v = self.decode(b);
                if !check_number(raw.code, &v) {
                    if self.recover {
                        // Kept, as ezdxf's recover does: dropping the group would leave
                        // a point without its y and the copy unreadable.
                        self.recovered += 1;
                        return Some(Ok(Tag {
                            code: raw.code,
                            value: Cow::Owned(salvage_number(raw.code, &v)),
                            pos: raw.pos,
                        }));
                    }
                    return Some(Err(DxfReadError::at(
                        Some(raw.pos),
                        format!(
                            "group code {} needs a number, found {:?}",
                            raw.code,
                            v.chars().take(40).collect::<String>()
                        ),
                    )));
                }
                v
            }
            RawValue::Float(x) => {
                let mut s = String::new();
                crate::output::dxf_writer::push_float(&mut s, x);
                Cow::Owned(s)
            }
            RawValue::Int(i) => Cow::Owned(i.to_string()),
            RawValue::Hex(b) => Cow::Owned(b.iter().map(|x| format!("{x:02X}")).collect()),
        };
        Some(Ok(Tag {
            code: raw.code,
            value,
            pos: raw.pos,
        }))
    }
}

fn memchr(needle: u8, hay: &[u8]) -> Option<usize> {
    hay.iter().position(|b| *b == needle)
}

/// `\U+XXXX` escapes (AutoCAD's way to put any BMP character into a code-page file) as the
/// characters; malformed escapes stay as they are.
pub fn decode_unicode_escapes(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find("\\U+") {
        out.push_str(&rest[..i]);
        let hex = rest.get(i + 3..i + 7);
        match hex
            // Upper-case hex only, as ezdxf decodes: a lower-case one stays text, so it is
            // written back as it was.
            .filter(|h| {
                h.bytes()
                    .all(|b| b.is_ascii_digit() || (b'A'..=b'F').contains(&b))
            })
            .and_then(|h| u32::from_str_radix(h, 16).ok())
            .and_then(char::from_u32)
        {
            Some(c) => {
                out.push(c);
                rest = &rest[i + 7..];
            }
            None => {
                out.push_str("\\U+");
                rest = &rest[i + 3..];
            }
        }
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tags(data: &[u8]) -> Vec<(i32, String)> {
        Tagger::new(data, false)
            .unwrap()
            .map(|t| t.map(|t| (t.code, t.value.into_owned())))
            .collect::<Result<_, _>>()
            .unwrap()
    }

    #[test]
    fn ascii_crlf_and_lf() {
        let a = tags(b"  0\r\nSECTION\r\n  2\r\nHEADER\r\n");
        let b = tags(b"0\nSECTION\n2\nHEADER\n");
        assert_eq!(a, b);
        assert_eq!(a[1], (2, "HEADER".to_string()));
    }

    #[test]
    fn code_page_and_escapes() {
        let data = b"0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$DWGCODEPAGE\n3\nANSI_936\n0\nENDSEC\n0\nSECTION\n1\n\xd6\xd0\\U+00E9\n";
        let t = tags(data);
        assert_eq!(t.last().unwrap().1, "中é");
    }

    #[test]
    fn errors_name_the_line() {
        let e = Tagger::new(b"0\nSECTION\n10\nabc\n", false)
            .unwrap()
            .find_map(|t| t.err())
            .unwrap();
        assert_eq!(e.pos, Some(Pos::Line(3)));
        let e = Tagger::new(b"0\nSECTION\n2\n", false)
            .unwrap()
            .find_map(|t| t.err())
            .unwrap();
        assert_eq!(e.pos, Some(Pos::Line(3)));
        assert!(Tagger::new(b"", false).is_err());
        assert!(Tagger::new(b"\x7fELF\0\0", false).is_err());
    }

    #[test]
    fn binary_two_byte_codes() {
        let mut d = BINARY_SENTINEL.to_vec();
        d.extend_from_slice(b"\0\0SECTION\0");
        d.extend_from_slice(&10i16.to_le_bytes());
        d.extend_from_slice(&1.5f64.to_le_bytes());
        d.extend_from_slice(&70i16.to_le_bytes());
        d.extend_from_slice(&3i16.to_le_bytes());
        assert_eq!(
            tags(&d),
            vec![(0, "SECTION".into()), (10, "1.5".into()), (70, "3".into())]
        );
    }
}
