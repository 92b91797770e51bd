//! The symbol table. Names are case-insensitive (stored upper case); a few symbols the
//! compiler recognises get fixed indices so it can compare them without lookups.

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

/// Room for the library's names (about 1,100 with the VLA tables) without growing at start-up.
const INITIAL_SLOTS: usize = 4096;
const INITIAL_SYMBOLS: usize = 1536;
const INITIAL_TEXT: usize = 24 << 10;

/// The symbol table: every name upper case, end to end in one string, and an open-addressing
/// index over them. Start-up interns every builtin name (about a thousand): one string and no
/// allocation per name, where a map of `Rc<str>` keys cost two allocations and a copy each
/// (a fifth of an empty script's run).
#[derive(Clone)]
pub struct SymbolTable {
    /// The names, upper case, one after another.
    text: String,
    /// Where each symbol's name ends in `text`.
    ends: Vec<u32>,
    /// Linear probing: a symbol's index + 1, or 0 for a free slot. The length is a power of
    /// two, and at most half the slots are used.
    slots: Vec<u32>,
}

impl Default for SymbolTable {
    fn default() -> Self {
        Self::new()
    }
}

/// FNV-1a over the ASCII-upper-cased bytes: symbol names are short and not attacker-chosen
/// keys worth SipHash's cost, and a name hashes the same in any case without a copy.
#[inline]
fn hash(name: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes() {
        h = (h ^ u64::from(b.to_ascii_uppercase())).wrapping_mul(0x0100_0000_01b3);
    }
    // FNV's low bits mix poorly: fold the high half in before masking.
    h ^ (h >> 29)
}

/// Where a lookup ended: the symbol, or the free slot where it would go.
enum Probe {
    Found(Sym),
    Free(usize),
}

impl SymbolTable {
    pub fn new() -> Self {
        let mut t = SymbolTable {
            text: String::with_capacity(INITIAL_TEXT),
            ends: Vec::with_capacity(INITIAL_SYMBOLS),
            slots: vec![0; INITIAL_SLOTS],
        };
        for (i, name) in FIXED.iter().enumerate() {
            let s = t.intern(name);
            debug_assert_eq!(s.0 as usize, i);
        }
        t
    }

    /// Finds `key`, which is either ASCII (matched case-insensitively against the stored upper
    /// case) or already upper-cased.
    #[inline]
    fn probe(&self, key: &str) -> Probe {
        let mask = self.slots.len() - 1;
        let mut i = hash(key) as usize & mask;
        loop {
            match self.slots[i] {
                0 => return Probe::Free(i),
                n => {
                    let s = Sym(n - 1);
                    if self.name(s).eq_ignore_ascii_case(key) {
                        return Probe::Found(s);
                    }
                }
            }
            i = (i + 1) & mask;
        }
    }

    /// The symbol for `name`, case-insensitively.
    pub fn intern(&mut self, name: &str) -> Sym {
        if name.is_ascii() {
            self.intern_key(name)
        } else {
            self.intern_key(&name.to_uppercase())
        }
    }

    fn intern_key(&mut self, key: &str) -> Sym {
        let slot = match self.probe(key) {
            Probe::Found(s) => return s,
            Probe::Free(i) => i,
        };
        let s = Sym(self.ends.len() as u32);
        let start = self.text.len();
        self.text.push_str(key);
        self.text[start..].make_ascii_uppercase();
        self.ends.push(self.text.len() as u32);
        self.slots[slot] = s.0 + 1;
        if 2 * self.ends.len() > self.slots.len() {
            self.rehash(2 * self.slots.len());
        }
        s
    }

    fn rehash(&mut self, n: usize) {
        self.slots = vec![0; n];
        for i in 0..self.ends.len() {
            let s = Sym(i as u32);
            let mut j = hash(self.name(s)) as usize & (n - 1);
            while self.slots[j] != 0 {
                j = (j + 1) & (n - 1);
            }
            self.slots[j] = s.0 + 1;
        }
    }

    /// The symbol if it already exists.
    pub fn lookup(&self, name: &str) -> Option<Sym> {
        let found = if name.is_ascii() {
            self.probe(name)
        } else {
            self.probe(&name.to_uppercase())
        };
        match found {
            Probe::Found(s) => Some(s),
            Probe::Free(_) => None,
        }
    }

    /// Forgets every symbol interned after the first `n` (see `Interp::restore_globals`).
    pub fn truncate(&mut self, n: usize) {
        let n = n.max(FIXED.len());
        // Newest first; each removal shifts back the entries probed past its slot, so the
        // table stays as if the symbol had never been inserted.
        while self.ends.len() > n {
            let s = Sym(self.ends.len() as u32 - 1);
            let mask = self.slots.len() - 1;
            let mut i = hash(self.name(s)) as usize & mask;
            while self.slots[i] != s.0 + 1 {
                i = (i + 1) & mask;
            }
            let mut hole = i;
            let mut j = i;
            loop {
                j = (j + 1) & mask;
                let v = self.slots[j];
                if v == 0 {
                    break;
                }
                let home = hash(self.name(Sym(v - 1))) as usize & mask;
                // The entry at j may move to the hole when its home is not in (hole, j].
                let reachable = if hole <= j {
                    hole < home && home <= j
                } else {
                    hole < home || home <= j
                };
                if !reachable {
                    self.slots[hole] = v;
                    hole = j;
                }
            }
            self.slots[hole] = 0;
            self.ends.pop();
        }
        let end = self.ends.last().map_or(0, |e| *e as usize);
        self.text.truncate(end);
    }

    #[inline]
    pub fn name(&self, s: Sym) -> &str {
        let i = s.idx();
        let start = if i == 0 { 0 } else { self.ends[i - 1] as usize };
        &self.text[start..self.ends[i] as usize]
    }

    pub fn len(&self) -> usize {
        self.ends.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    pub fn all(&self) -> impl Iterator<Item = (Sym, &str)> {
        (0..self.ends.len()).map(|i| (Sym(i as u32), self.name(Sym(i as u32))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_case_insensitive_and_stored_upper_case() {
        let mut t = SymbolTable::new();
        let a = t.intern("foo-Bar");
        assert_eq!(t.intern("FOO-BAR"), a);
        assert_eq!(t.lookup("foo-bar"), Some(a));
        assert_eq!(t.name(a), "FOO-BAR");
        assert_eq!(t.intern("t"), S_T);
        assert_eq!(t.lookup("*Error*"), Some(S_ERROR));
        assert_eq!(t.lookup("nope"), None);
        // Non-ASCII names upper-case by Unicode, as before.
        let e = t.intern("café");
        assert_eq!(t.name(e), "CAFÉ");
        assert_eq!(t.lookup("CAFé"), Some(e));
        assert_eq!(t.intern("Café"), e);
    }

    #[test]
    fn growth_and_truncate_keep_every_lookup_right() {
        let mut t = SymbolTable::new();
        let base = t.len();
        // Past the initial slots, so the table rehashes; then forget the newest half, in the
        // order restore_globals does, and check every name either way.
        let names: Vec<String> = (0..5000).map(|i| format!("sym{i}")).collect();
        let syms: Vec<Sym> = names.iter().map(|n| t.intern(n)).collect();
        for (n, s) in names.iter().zip(&syms) {
            assert_eq!(t.lookup(&n.to_uppercase()), Some(*s));
            assert_eq!(t.name(*s), n.to_uppercase());
        }
        t.truncate(base + 2500);
        assert_eq!(t.len(), base + 2500);
        for (i, (n, s)) in names.iter().zip(&syms).enumerate() {
            let want = if i < 2500 { Some(*s) } else { None };
            assert_eq!(t.lookup(n), want, "{n}");
        }
        // Interning again after a truncate reuses the freed indices.
        assert_eq!(t.intern("sym4999").idx(), base + 2500);
        assert_eq!(t.name(Sym((base + 2500) as u32)), "SYM4999");
        t.truncate(0);
        assert_eq!(t.len(), FIXED.len());
        assert_eq!(t.lookup("quote"), Some(S_QUOTE));
        assert_eq!(t.lookup("sym0"), None);
    }
}
