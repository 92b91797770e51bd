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
    let tables: Vec<&'static [Builtin]> = tables().into_iter().map(|(_, t)| t).collect();
    it.register_prebuilt(&LIBRARY, &tables);
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
    let mut it = Interp::bare();
    open_libs(&mut it);
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
