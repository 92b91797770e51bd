//! `lispcad doc`: the reference of every builtin, generated from the registration tables.

/// The reference as Markdown: one section per library area, one line per builtin.
pub fn reference() -> String {
    let mut out = String::new();
    for (area, table) in crate::builtins::tables() {
        out.push_str(&format!("\n### {area}\n\n"));
        for b in table.iter() {
            out.push_str(&format!("- `{}` — {}\n", b.sig, b.doc));
        }
    }
    out
}
