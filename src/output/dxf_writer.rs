//! DXF group-code/value writing: codes right-justified in three columns as AutoCAD writes them,
//! floats in their shortest round-trip form, strings in the drawing's code page (Windows-1252)
//! with AutoCAD's `\\U+XXXX` escapes for everything else.

use std::fmt::Write as _;

use glam::{DVec2, DVec3};

/// Every group code below 1000 as it is written: right-justified in three columns and followed
/// by its newline, four bytes each ("  0\n" … "999\n"), so writing one is a four-byte copy
/// (the writers emit about 800 groups a file).
const CODES: &str = {
    const BYTES: [u8; 4000] = {
        let mut b = [b' '; 4000];
        let mut c = 0;
        while c < 1000 {
            let i = 4 * c;
            if c >= 100 {
                b[i] = b'0' + (c / 100) as u8;
            }
            if c >= 10 {
                b[i + 1] = b'0' + (c / 10 % 10) as u8;
            }
            b[i + 2] = b'0' + (c % 10) as u8;
            b[i + 3] = b'\n';
            c += 1;
        }
        b
    };
    match std::str::from_utf8(&BYTES) {
        Ok(s) => s,
        Err(_) => panic!("group codes are ASCII"),
    }
};

/// Group-code/value pair emitter into one string buffer.
pub struct DxfWriter {
    pub out: String,
    /// Write strings as they are (only control characters replaced): the caller encodes
    /// the file in its own code page or UTF-8 afterwards.
    pub raw_text: bool,
}

impl Default for DxfWriter {
    fn default() -> Self {
        DxfWriter::new()
    }
}

impl DxfWriter {
    /// The groups of a plain text style record after its name (R12 and R2000 alike): no
    /// fixed height, width factor 1, no oblique angle, last height 2.5, font "txt".
    pub fn text_style_fields(&mut self) {
        self.int(70, 0);
        self.float(40, 0.0);
        self.float(41, 1.0);
        self.float(50, 0.0);
        self.int(71, 0);
        self.float(42, 2.5);
        self.str(3, "txt");
        self.str(4, "");
    }

    /// The groups of a solid line-type record from its name on (R12 and R2000 alike).
    pub fn solid_linetype_fields(&mut self, name: &str, description: &str) {
        self.str(2, name);
        self.int(70, 0);
        self.str(3, description);
        self.int(72, 65);
        self.int(73, 0);
        self.float(40, 0.0);
    }

    pub fn new() -> DxfWriter {
        DxfWriter {
            out: String::with_capacity(1 << 16),
            raw_text: false,
        }
    }

    /// The group code right-justified in three columns, with its newline.
    fn code(&mut self, code: u16) {
        let c = usize::from(code);
        if c < 1000 {
            self.out.push_str(&CODES[4 * c..4 * c + 4]);
        } else {
            // Four digits and more (xdata's 1000-1071) fill the columns.
            self.out.push_str(itoa::Buffer::new().format(code));
            self.out.push('\n');
        }
    }

    pub fn str(&mut self, code: u16, value: &str) {
        self.code(code);
        if self.raw_text {
            self.out
                .extend(value.chars().map(|c| if c.is_control() { ' ' } else { c }));
        } else {
            push_dxf_string(&mut self.out, value);
        }
        self.out.push('\n');
    }

    pub fn int(&mut self, code: u16, value: i64) {
        self.code(code);
        self.out.push_str(itoa::Buffer::new().format(value));
        self.out.push('\n');
    }

    /// A handle in upper-case hexadecimal (as `{:X}` writes it, without going through
    /// `fmt`: a file has a few hundred of them).
    pub fn handle(&mut self, code: u16, h: u64) {
        self.code(code);
        let mut buf = [b'0'; 16];
        let mut i = buf.len();
        let mut h = h;
        loop {
            i -= 1;
            buf[i] = b"0123456789ABCDEF"[(h & 0xF) as usize];
            h >>= 4;
            if h == 0 {
                break;
            }
        }
        self.out.extend(buf[i..].iter().map(|&b| char::from(b)));
        self.out.push('\n');
    }

    pub fn float(&mut self, code: u16, value: f64) {
        self.code(code);
        push_float(&mut self.out, value);
        self.out.push('\n');
    }

    /// A point as codes `code`, `code + 10`, `code + 20`.
    pub fn point(&mut self, code: u16, p: DVec3) {
        self.float(code, p.x);
        self.float(code + 10, p.y);
        self.float(code + 20, p.z);
    }

    pub fn point2(&mut self, code: u16, p: DVec2) {
        self.float(code, p.x);
        self.float(code + 10, p.y);
    }
}

/// The shortest decimal that reads back as the same f64 (Ryū, Adams 2018), with -0 written as
/// 0. Ryū's form always has a decimal point or an exponent ("1.0", "1e-7", "1e21"), which
/// AutoCAD, LibreCAD and ezdxf all read.
pub fn push_float(out: &mut String, x: f64) {
    let x = if x == 0.0 { 0.0 } else { x };
    if (1e-5..1e16).contains(&x.abs()) {
        // Where Ryū writes plain decimals, zmij (Schubfach) writes the same bytes in about
        // half the instructions: the same digits (the shortest that read back, the nearest
        // of them when there are several) and the same plain form ("91.0", "0.00001").
        // Outside this range their exponent forms differ ("1e21" and "1e+21").
        let mut b = zmij::Buffer::new();
        out.push_str(b.format_finite(x));
    } else if x.is_finite() {
        let mut b = ryu::Buffer::new();
        out.push_str(b.format_finite(x));
    } else {
        // Never produced: entities are validated before writing. Keep the file parseable.
        out.push_str("0.0");
    }
}

/// DXF strings are one line of the drawing's code page ($DWGCODEPAGE = ANSI_1252): control
/// characters become spaces, characters outside Windows-1252 AutoCAD's `\U+XXXX` escapes.
/// (The file is encoded to Windows-1252 bytes at the end, by `encode_cp1252`.)
fn push_dxf_string(out: &mut String, s: &str) {
    if s.bytes().all(|b| (0x20..0x7F).contains(&b)) {
        out.push_str(s);
        return;
    }
    for c in s.chars() {
        if c.is_ascii_control() {
            out.push(' ');
        } else if c.is_ascii() || cp1252_byte(c).is_some() {
            out.push(c);
        } else {
            let cp = c as u32;
            if cp <= 0xFFFF {
                let _ = write!(out, "\\U+{cp:04X}");
            } else {
                // Outside the BMP: AutoCAD has no escape for it; a mark keeps the file valid.
                out.push('?');
            }
        }
    }
}

/// The Windows-1252 byte of a non-ASCII character, if it has one.
fn cp1252_byte(c: char) -> Option<u8> {
    const HIGH: [char; 32] = [
        '€', '\u{81}', '‚', 'ƒ', '„', '…', '†', '‡', 'ˆ', '‰', 'Š', '‹', 'Œ', '\u{8D}', 'Ž',
        '\u{8F}', '\u{90}', '‘', '’', '“', '”', '•', '–', '—', '˜', '™', 'š', '›', 'œ', '\u{9D}',
        'ž', 'Ÿ',
    ];
    let cp = c as u32;
    if (0xA0..=0xFF).contains(&cp) {
        return Some(cp as u8);
    }
    // The five undefined positions (0x81, 0x8D, 0x8F, 0x90, 0x9D) are C1 controls, never
    // produced: `push_dxf_string` turns control characters into spaces first.
    HIGH.iter()
        .position(|h| *h == c && !c.is_control())
        .map(|i| 0x80 + i as u8)
}

/// The file text as Windows-1252 bytes (every character was made representable when written).
pub fn encode_cp1252(s: String) -> Vec<u8> {
    if s.is_ascii() {
        return s.into_bytes();
    }
    s.chars()
        .map(|c| {
            if c.is_ascii() {
                c as u8
            } else {
                cp1252_byte(c).unwrap_or(b'?')
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_round_trip_and_have_a_point() {
        let mut s = String::new();
        for x in [0.1, 1.0 / 3.0, 1e-300, 12345678.9, -0.0, 2.0, 1e21] {
            s.clear();
            push_float(&mut s, x);
            assert!(s.contains('.') || s.contains('e'), "{s}");
            assert!(!s.starts_with('-') || x < 0.0, "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), if x == 0.0 { 0.0 } else { x });
        }
    }

    /// What `push_float` wrote before it used zmij: Ryū's form of every finite value.
    fn ryu_form(x: f64) -> String {
        let x = if x == 0.0 { 0.0 } else { x };
        let mut b = ryu::Buffer::new();
        b.format_finite(x).to_string()
    }

    fn written(x: f64) -> String {
        let mut s = String::new();
        push_float(&mut s, x);
        s
    }

    #[test]
    fn floats_are_ryu_bytes_at_the_edges() {
        let mut xs = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.5,
            2.5,
            91.0,
            1e-5,
            1e16,
            1e15,
            1e21,
            1e-7,
            1e-300,
            5e-324,
            -5e-324,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::MIN,
            123456789012345678.0,
            9999999999999998.0,
            0.3,
            2.0 / 3.0,
            1e23,
            4.35,
            0.000012345,
        ];
        // Each side of both ends of the zmij range, a few ulps apart.
        for edge in [1e-5f64, 1e16] {
            for k in -4i64..=4 {
                let y = f64::from_bits((edge.to_bits() as i64 + k) as u64);
                xs.extend([y, -y]);
            }
        }
        // Integers and short decimals, the usual drawing numbers.
        for i in 0..20_000i64 {
            xs.extend([
                i as f64,
                i as f64 / 8.0,
                i as f64 / 1000.0,
                -(i as f64) * 1e6,
            ]);
        }
        for x in xs {
            assert_eq!(written(x), ryu_form(x), "x = {x:e} ({:#x})", x.to_bits());
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(20_000))]

        /// Any bit pattern: every sign, exponent (tiny, subnormal, huge) and mantissa.
        #[test]
        fn floats_are_ryu_bytes_for_any_bits(bits in proptest::prelude::any::<u64>()) {
            let x = f64::from_bits(bits);
            if x.is_finite() {
                proptest::prop_assert_eq!(written(x), ryu_form(x));
            }
        }

        /// Values of drawings: a mantissa at full precision over the decades around the
        /// range where the two formatters differ in code path.
        #[test]
        fn floats_are_ryu_bytes_in_drawing_ranges(m in 1.0f64..10.0, e in -9i32..20, neg in proptest::prelude::any::<bool>()) {
            let x = m * 10f64.powi(e) * if neg { -1.0 } else { 1.0 };
            proptest::prop_assert_eq!(written(x), ryu_form(x));
        }
    }

    #[test]
    fn strings_are_escaped() {
        let mut s = String::new();
        push_dxf_string(&mut s, "a\nbé—α");
        assert_eq!(s, "a bé—\\U+03B1");
        assert_eq!(encode_cp1252(s), b"a b\xE9\x97\\U+03B1");
    }

    /// `code`, `int` and `handle` write what `fmt` writes (`{:>3}`, `{}`, `{:X}`), for every
    /// code up to past xdata's and values at both ends of their ranges.
    #[test]
    fn groups_are_the_fmt_bytes() {
        let mut w = DxfWriter::new();
        let mut expected = String::new();
        for c in (0..=1100u16).chain([9999, 10000, u16::MAX]) {
            w.int(c, i64::from(c) - 500);
            w.handle(c, u64::from(c) * 0x1F3);
            let (v, h) = (i64::from(c) - 500, u64::from(c) * 0x1F3);
            expected.push_str(&format!("{c:>3}\n{v}\n{c:>3}\n{h:X}\n"));
        }
        for v in [
            0,
            1,
            -1,
            9,
            10,
            99,
            100,
            i64::from(i32::MAX),
            i64::MIN,
            i64::MAX,
        ] {
            w.int(70, v);
            expected.push_str(&format!(" 70\n{v}\n"));
        }
        for h in [0, 0xF, 0x10, 0xABC, 0xFFFF_FFFF, u64::MAX, 1 << 60] {
            w.handle(5, h);
            expected.push_str(&format!("  5\n{h:X}\n"));
        }
        assert_eq!(w.out, expected);
    }

    #[test]
    fn codes_are_right_justified() {
        let mut w = DxfWriter::new();
        w.int(0, 1);
        w.int(70, 2);
        w.int(1071, 3);
        assert_eq!(w.out, "  0\n1\n 70\n2\n1071\n3\n");
    }
}
