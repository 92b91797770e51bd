//! The language: reader, values, compiler, evaluator, errors, printer.
//!
//! One file per phase, as in Lua's source: `reader` (text → values, with spans), `compile`
//! (values → closures), `eval` (the interpreter state and driver), `print`, `error`; `value` and
//! `symbols` hold the data; `builtin` is the descriptor every library function registers.
//! `real` (printing reals) and `escape` (string-literal escapes) belong to the printer and the
//! reader. The language installs no library: the host does (`builtins::open_libs`), as Lua's
//! `luaL_openlibs` does.

pub mod builtin;
mod call;
mod cells;
mod code;
pub mod compile;
mod defparam;
pub mod encoding;
pub mod error;
pub mod escape;
pub mod eval;
pub mod fastpath;
pub mod lint;
pub mod memory;
pub mod print;
pub mod program;
pub mod reader;
pub mod real;
pub mod symbols;
pub mod value;

pub use builtin::Builtin;
pub use error::{ErrorKind, Exn, LResult, LispError};
pub use eval::Interp;
pub use value::{Sym, Value};
