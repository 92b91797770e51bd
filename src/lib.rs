//! lispcad: an AutoLISP dialect evaluated over a 3D geometry core, with SVG and DXF output.
//!
//! Layers, from the bottom: `geom` (pure geometry over glam, knows nothing of the language),
//! `output` (drawing model, SVG and DXF writers), `lang` (reader, values, compiler, evaluator),
//! `builtins` (the library, one module per area), `cli` (commands, REPL, batch).

pub mod builtins;
pub mod cli;
pub mod geom;
pub mod lang;
pub mod output;
