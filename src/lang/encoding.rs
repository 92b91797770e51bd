//! Source text decoding: UTF-8 when the bytes are UTF-8, else the drawing's code page, as
//! AutoCAD reads ANSI `.lsp` files (SPEC §3). A byte-order mark is skipped (and a UTF-16 one
//! decodes UTF-16). `load`, the CLI and `read-line` all decode through here.

use encoding_rs::Encoding;

/// The code page that non-UTF-8 sources are read in (`DWGCODEPAGE`; the system variables
/// keep it in step).
pub struct SourceCodePage(pub &'static Encoding);

impl Default for SourceCodePage {
    fn default() -> Self {
        SourceCodePage(encoding_rs::WINDOWS_1252)
    }
}

/// The encoding of an AutoCAD code page name (`ANSI_1252`, `ANSI_936`, ...), or None.
pub fn code_page(name: &str) -> Option<&'static Encoding> {
    let n = name.trim().to_ascii_uppercase();
    let number = n.strip_prefix("ANSI_").unwrap_or(&n);
    let label = match number {
        "874" => "windows-874",
        "932" => "shift_jis",
        "936" => "gbk",
        "949" => "euc-kr",
        "950" => "big5",
        "1250" | "1251" | "1252" | "1253" | "1254" | "1255" | "1256" | "1257" | "1258" => {
            return Encoding::for_label(format!("windows-{number}").as_bytes());
        }
        "UTF8" | "UTF-8" => "utf-8",
        _ => return None,
    };
    Encoding::for_label(label.as_bytes())
}

/// The text of source bytes: UTF-8 (BOM skipped) when valid, else decoded from `fallback`.
/// Never fails: bytes a code page does not map become U+FFFD.
pub fn decode(bytes: &[u8], fallback: &'static Encoding) -> String {
    if let Some((enc, bom)) = Encoding::for_bom(bytes) {
        return enc
            .decode_without_bom_handling(&bytes[bom..])
            .0
            .into_owned();
    }
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_string(),
        Err(_) => fallback.decode_without_bom_handling(bytes).0.into_owned(),
    }
}

/// Reads a source file in the interpreter's code page.
pub fn read_source_file(
    path: &std::path::Path,
    code_page: &'static Encoding,
) -> std::io::Result<String> {
    Ok(decode(&std::fs::read(path)?, code_page))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_bom_and_code_pages() {
        let w = encoding_rs::WINDOWS_1252;
        assert_eq!(decode(b"\xEF\xBB\xBF(princ)", w), "(princ)");
        assert_eq!(decode("é".as_bytes(), w), "é");
        assert_eq!(decode(b"\xE9\x80", w), "é€");
        let gbk = code_page("ANSI_936").unwrap();
        assert_eq!(decode(b"\xD6\xD0\xCE\xC4", gbk), "中文");
        assert_eq!(decode(b"\xFF\xFEa\x00", w), "a");
        assert!(code_page("ANSI_9999").is_none());
        assert_eq!(code_page("ansi_1251").unwrap().name(), "windows-1251");
    }
}
