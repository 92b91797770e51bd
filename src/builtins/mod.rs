//! The library, one module per area (as Lua's `lmathlib.c`, `lstrlib.c`...). Each module holds a
//! flat list of small functions and one `static` registration table whose entries carry the
//! name, signature and one-line doc that `help`, `lispcad doc` and the README show.

use crate::lang::{Builtin, Interp};

pub mod command;
pub mod control;
pub mod drawing;
pub mod entities;
pub mod format;
pub mod fs_policy;
pub mod geom2d;
pub mod geometry;
pub mod input;
pub mod io;
pub mod lists;
pub mod numbers;
pub mod predicates;
pub mod settings;
pub mod special;
pub mod strings;
pub mod surfaces;
pub mod system;
pub mod sysvars;
pub mod temple;
pub mod text;
pub mod trace;
pub mod vla;

/// Every registration table but the Visual LISP ones, in the order `lispcad doc` lists them.
const TABLES: &[(&str, &[Builtin])] = &[
    ("Special forms", special::BUILTINS),
    ("Evaluation and errors", control::BUILTINS),
    ("Lists", lists::BUILTINS),
    ("Lists: car/cdr compositions", lists::CXR),
    ("Numbers", numbers::BUILTINS),
    ("Points and coordinates", geom2d::BUILTINS),
    ("Predicates", predicates::BUILTINS),
    ("Strings", strings::BUILTINS),
    ("Strings: formatting and matching", format::BUILTINS),
    ("Printing and files", io::BUILTINS),
    ("Interactive input", input::BUILTINS),
    ("Curves", geometry::BUILTINS),
    ("Surfaces and meshes", surfaces::BUILTINS),
    ("Eyeglass temple", temple::BUILTINS),
    ("Drawing and output", drawing::BUILTINS),
    ("Entities, selection sets and tables", entities::BUILTINS),
    ("Commands", command::BUILTINS),
    ("System", system::BUILTINS),
];

/// The symbol table `open_libs` builds, computed at compile time.
static LIBRARY: crate::lang::symbols::Prebuilt =
    crate::lang::symbols::Prebuilt::new(&[TABLES, vla::TABLES]);

/// Every registration table, in the order `lispcad doc` lists them.
pub fn tables() -> Vec<(&'static str, &'static [Builtin])> {
    TABLES.iter().chain(vla::TABLES).copied().collect()
}

/// Installs the whole library in an interpreter, as Lua's `luaL_openlibs` does: every
/// registration table, the per-interpreter state some areas need (system variables...), and
/// the descriptors the compiler may inline (arithmetic, `cons`, `car`, `cdr`).
pub fn open_libs(it: &mut Interp) {
    for (_, table) in tables() {
        it.register(table);
    }
    init_libs(it);
}

/// What `open_libs` does after registering the tables.
fn init_libs(it: &mut Interp) {
    system::init(it);
    command::init(it);
    vla::init(it);
    // The descriptors the cells now hold: the ones calls reach, found without `find`'s scan
    // of every table (a few per cent of an empty script's start-up).
    crate::lang::fastpath::register_inlined(|name| match it.global(name) {
        crate::lang::Value::Subr(b) => Some(b),
        _ => None,
    });
}

/// A fresh interpreter with the whole library installed.
pub fn new_interp() -> Interp {
    let tables: Vec<&'static [Builtin]> = tables().into_iter().map(|(_, t)| t).collect();
    let mut it = Interp::with_library(&LIBRARY, &tables);
    init_libs(&mut it);
    it
}

/// Finds a builtin's descriptor by name (case-insensitive).
pub fn find(name: &str) -> Option<&'static Builtin> {
    tables()
        .into_iter()
        .flat_map(|(_, t)| t.iter())
        .find(|b| b.name.eq_ignore_ascii_case(name))
}

pub use drawing::{drawing_svg, write_outputs};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lang::Value;

    #[test]
    fn the_prebuilt_library_binds_what_registering_one_by_one_does() {
        let fast = new_interp();
        let mut slow = Interp::bare();
        open_libs(&mut slow);
        let names = |it: &Interp| -> Vec<String> { it.syms.all().map(|(_, n)| n.into()).collect() };
        assert_eq!(names(&fast), names(&slow));
        assert!(fast.syms.len() > 500, "{}", fast.syms.len());
        for (_, n) in fast.syms.all() {
            match (fast.global(n), slow.global(n)) {
                (Value::Subr(a), Value::Subr(b)) => assert!(std::ptr::eq(a, b), "{n}"),
                (a, b) => assert_eq!(fast.prin1_string(&a), slow.prin1_string(&b), "{n}"),
            }
        }
        // A name registered twice is bound to its last table's descriptor, as `register` does.
        for (_, table) in tables() {
            for b in table {
                let Value::Subr(d) = fast.global(b.name) else {
                    panic!("{} unbound", b.name)
                };
                assert!(d.name.eq_ignore_ascii_case(b.name));
            }
        }
    }
}
