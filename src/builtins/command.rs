//! placeholder
use crate::lang::Builtin;
pub static BUILTINS: &[Builtin] = &[];
