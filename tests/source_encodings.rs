//! Source files in Windows code pages (SPEC §3): a file that is not UTF-8 is read in
//! DWGCODEPAGE (default ANSI_1252), a byte-order mark is skipped, and strings keep their
//! characters through strlen/substr/ascii/chr, files and output. One file per code page.

use lispcad::lang::Interp;

fn eval(it: &mut Interp, code: &str) -> String {
    match it.eval_source("<test>", code) {
        Ok(v) => it.prin1_string(&v),
        Err(e) => format!("error: {}", e.message),
    }
}

/// Loads `bytes` as a .lsp file (after `setup`) and returns the printed value of `probe`.
fn load_and_probe(bytes: &[u8], setup: &str, probe: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("src.lsp");
    std::fs::write(&path, bytes).unwrap();
    let mut it = lispcad::builtins::new_interp();
    it.base_dir = Some(dir.path().to_path_buf());
    let set = eval(&mut it, setup);
    assert!(!set.starts_with("error"), "{set}");
    let loaded = eval(&mut it, &format!("(load {:?})", path.display().to_string()));
    assert!(!loaded.starts_with("error"), "{loaded}");
    eval(&mut it, probe)
}

#[test]
fn ansi_1252_by_default() {
    // "Größe €" in windows-1252: ö = F6, ß = DF, € = 80.
    let src = b"(setq s \"Gr\xF6\xDFe \x80\")";
    let probe = "(list s (strlen s) (ascii (substr s 3 1)) (chr 246) (= (substr s 3 1) (chr 246)))";
    assert_eq!(
        load_and_probe(src, "nil", probe),
        "(\"Größe €\" 7 246 \"ö\" T)"
    );
}

#[test]
fn ansi_936_after_setvar() {
    // "中文标注" in GBK.
    let (bytes, _, bad) = encoding_rs::GBK.encode("(setq s \"中文标注\")");
    assert!(!bad);
    let probe = "(list s (strlen s) (substr s 2 2) (ascii s))";
    assert_eq!(
        load_and_probe(&bytes, "(setvar \"DWGCODEPAGE\" \"ANSI_936\")", probe),
        "(\"中文标注\" 4 \"文标\" 20013)"
    );
}

#[test]
fn ansi_1251_and_932() {
    let (bytes, _, _) = encoding_rs::WINDOWS_1251.encode("(setq s \"Привет\")");
    assert_eq!(
        load_and_probe(
            &bytes,
            "(setvar \"DWGCODEPAGE\" \"ANSI_1251\")",
            "(list s (strlen s))"
        ),
        "(\"Привет\" 6)"
    );
    let (bytes, _, _) = encoding_rs::SHIFT_JIS.encode("(setq s \"寸法\")");
    assert_eq!(
        load_and_probe(
            &bytes,
            "(setvar \"DWGCODEPAGE\" \"ANSI_932\")",
            "(list s (strlen s))"
        ),
        "(\"寸法\" 2)"
    );
}

#[test]
fn utf8_with_bom_and_utf16() {
    let src = "\u{FEFF}(setq s \"Größe\")".as_bytes();
    assert_eq!(
        load_and_probe(src, "nil", "(list s (strlen s))"),
        "(\"Größe\" 5)"
    );
    let mut utf16 = vec![0xFF, 0xFE];
    for u in "(setq s \"ö\")".encode_utf16() {
        utf16.extend_from_slice(&u.to_le_bytes());
    }
    assert_eq!(load_and_probe(&utf16, "nil", "s"), "\"ö\"");
}

#[test]
fn read_line_decodes_the_code_page_and_files_round_trip() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("in.txt"), b"Stra\xDFe\r\nzwei\n").unwrap();
    let mut it = lispcad::builtins::new_interp();
    it.ext::<lispcad::builtins::io::FsPolicy>().allow_all = true;
    it.base_dir = Some(dir.path().to_path_buf());
    let code = "(setq f (open \"in.txt\" \"r\") a (read-line f) b (read-line f) c (read-line f))
                (close f)
                (setq g (open \"out.txt\" \"w\")) (write-line a g) (close g)
                (setq g (open \"out.txt\" \"r\") d (read-line g)) (close g)
                (list a (strlen a) b c (= a d))";
    assert_eq!(eval(&mut it, code), "(\"Straße\" 6 \"zwei\" nil T)");
}

#[test]
fn unknown_code_page_is_rejected() {
    let mut it = lispcad::builtins::new_interp();
    assert_eq!(
        eval(&mut it, "(setvar \"DWGCODEPAGE\" \"ANSI_12\")"),
        "error: AutoCAD variable setting rejected: \"DWGCODEPAGE\" \"ANSI_12\""
    );
    assert_eq!(eval(&mut it, "(getvar \"DWGCODEPAGE\")"), "\"ANSI_1252\"");
}
