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

/// `lispcad doc NAME`: one builtin's signature and description; a usage error naming the
/// nearest builtin when there is none of that name.
pub fn one(name: &str) -> i32 {
    if let Some(t) = crate::builtins::system::help_text(name) {
        println!("{t}");
        return super::EXIT_OK;
    }
    let names = crate::builtins::tables()
        .into_iter()
        .flat_map(|(_, t)| t.iter().map(|b| b.name));
    match crate::lang::lint::nearest(name, names) {
        Some(n) => eprintln!("error: no builtin named {name}; did you mean {n}?"),
        None => eprintln!("error: no builtin named {name}"),
    }
    super::EXIT_USAGE
}
