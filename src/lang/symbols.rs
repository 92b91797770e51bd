//! The symbol table. Names are case-insensitive (stored upper case); a few symbols the
//! compiler recognises get fixed indices so it can compare them without lookups.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::rc::Rc;

use super::value::Sym;

/// Symbols with fixed indices, interned first in this order.
const FIXED: &[&str] = &[
    "T", "QUOTE", "FUNCTION", "SETQ", "IF", "COND", "PROGN", "WHILE", "REPEAT", "FOREACH", "AND",
    "OR", "DEFUN", "DEFUN-Q", "LAMBDA", "/", "*ERROR*", ".", "NIL",
];

pub const S_T: Sym = Sym(0);
pub const S_QUOTE: Sym = Sym(1);
pub const S_FUNCTION: Sym = Sym(2);
pub const S_SETQ: Sym = Sym(3);
pub const S_IF: Sym = Sym(4);
pub const S_COND: Sym = Sym(5);
pub const S_PROGN: Sym = Sym(6);
pub const S_WHILE: Sym = Sym(7);
pub const S_REPEAT: Sym = Sym(8);
pub const S_FOREACH: Sym = Sym(9);
pub const S_AND: Sym = Sym(10);
pub const S_OR: Sym = Sym(11);
pub const S_DEFUN: Sym = Sym(12);
pub const S_DEFUN_Q: Sym = Sym(13);
pub const S_LAMBDA: Sym = Sym(14);
pub const S_SLASH: Sym = Sym(15);
pub const S_ERROR: Sym = Sym(16);
pub const S_DOT: Sym = Sym(17);
/// The symbol NIL exists only for `read`-ing "nil"; the reader turns it into `Value::Nil`.
pub const S_NIL: Sym = Sym(18);

/// FNV-1a: symbol names are short and not attacker-chosen keys worth SipHash's cost, and
/// start-up interns every builtin name.
#[derive(Default)]
struct Fnv(u64);

impl Hasher for Fnv {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        let mut h = if self.0 == 0 {
            0xcbf2_9ce4_8422_2325
        } else {
            self.0
        };
        for b in bytes {
            h = (h ^ u64::from(*b)).wrapping_mul(0x0100_0000_01b3);
        }
        self.0 = h;
    }

    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
}

/// Room for the library's names (about 300) without rehashing at start-up.
const INITIAL_SYMBOLS: usize = 512;

#[derive(Clone)]
pub struct SymbolTable {
    names: Vec<Rc<str>>,
    index: HashMap<Rc<str>, Sym, BuildHasherDefault<Fnv>>,
}

impl Default for SymbolTable {
    fn default() -> Self {
        Self::new()
    }
}

impl SymbolTable {
    pub fn new() -> Self {
        let mut t = SymbolTable {
            names: Vec::with_capacity(INITIAL_SYMBOLS),
            index: HashMap::with_capacity_and_hasher(INITIAL_SYMBOLS, Default::default()),
        };
        for (i, name) in FIXED.iter().enumerate() {
            let s = t.intern(name);
            debug_assert_eq!(s.0 as usize, i);
        }
        t
    }

    /// The symbol for `name`, case-insensitively.
    pub fn intern(&mut self, name: &str) -> Sym {
        if let Some(s) = self.index.get(name) {
            return *s;
        }
        let upper: Rc<str> = if name.is_ascii() {
            Rc::from(name.to_ascii_uppercase())
        } else {
            Rc::from(name.to_uppercase())
        };
        if let Some(s) = self.index.get(&upper) {
            return *s;
        }
        let s = Sym(self.names.len() as u32);
        self.names.push(upper.clone());
        self.index.insert(upper, s);
        s
    }

    /// The symbol if it already exists.
    pub fn lookup(&self, name: &str) -> Option<Sym> {
        self.index
            .get(name)
            .or_else(|| self.index.get(name.to_uppercase().as_str()))
            .copied()
    }

    /// Forgets every symbol interned after the first `n` (see `Interp::restore_globals`).
    pub fn truncate(&mut self, n: usize) {
        for name in self.names.drain(n.max(FIXED.len())..) {
            self.index.remove(&name);
        }
    }

    pub fn name(&self, s: Sym) -> &str {
        &self.names[s.idx()]
    }

    pub fn len(&self) -> usize {
        self.names.len()
    }

    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    pub fn all(&self) -> impl Iterator<Item = (Sym, &str)> {
        self.names
            .iter()
            .enumerate()
            .map(|(i, n)| (Sym(i as u32), n.as_ref()))
    }
}
