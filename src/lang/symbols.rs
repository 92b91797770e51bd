//! The symbol table. Names are case-insensitive (stored upper case); a few symbols the
//! compiler recognises get fixed indices so it can compare them without lookups.

use super::builtin::Builtin;
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

/// Room for the library's names (about 550 with the VLA tables and constants) and a script's
/// own without growing. The slots are copied whole at start-up (`from_prebuilt`), so they are
/// sized for the table to stay at most half full up to 1,024 symbols, no more; the names and
/// their ends are only touched as far as they are used.
const INITIAL_SLOTS: usize = 2048;
const INITIAL_SYMBOLS: usize = 1536;
const INITIAL_TEXT: usize = 24 << 10;

/// The symbol table: every name upper case, end to end in one string, and an open-addressing
/// index over them: one string and no allocation per name, where a map of `Rc<str>` keys cost
/// two allocations and a copy each. Start-up copies the library's table (`Prebuilt`) rather
/// than interning its names.
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
    hash_bytes(name.as_bytes())
}

#[inline]
const fn hash_bytes(name: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut i = 0;
    while i < name.len() {
        h = (h ^ name[i].to_ascii_uppercase() as u64).wrapping_mul(0x0100_0000_01b3);
        i += 1;
    }
    // FNV's low bits mix poorly: fold the high half in before masking.
    h ^ (h >> 29)
}

/// The symbol table after interning `FIXED` and then every builtin name of some registration
/// tables in order, as `SymbolTable::new` and `Interp::register` would, but computed at
/// compile time (`Prebuilt::new` is a `const fn`): start-up copies it instead of hashing and
/// probing a thousand names (a fifth of an empty script's instructions before).
pub struct Prebuilt {
    text: [u8; INITIAL_TEXT],
    text_len: usize,
    ends: [u32; INITIAL_SYMBOLS],
    len: usize,
    slots: [u32; INITIAL_SLOTS],
    /// Each builtin's symbol, in table order.
    builtin_syms: [u32; INITIAL_SYMBOLS],
    builtins: usize,
}

impl Prebuilt {
    /// The table for `groups` of titled registration tables, in order. Fails to compile (a
    /// panic in const evaluation) when a name is not ASCII or the names outgrow the initial
    /// capacities, which then need raising.
    pub const fn new(groups: &[&[(&str, &[Builtin])]]) -> Prebuilt {
        let mut p = Prebuilt {
            text: [0; INITIAL_TEXT],
            text_len: 0,
            ends: [0; INITIAL_SYMBOLS],
            len: 0,
            slots: [0; INITIAL_SLOTS],
            builtin_syms: [0; INITIAL_SYMBOLS],
            builtins: 0,
        };
        let mut i = 0;
        while i < FIXED.len() {
            p.intern(FIXED[i].as_bytes());
            i += 1;
        }
        let mut g = 0;
        while g < groups.len() {
            let mut t = 0;
            while t < groups[g].len() {
                let table = groups[g][t].1;
                let mut b = 0;
                while b < table.len() {
                    let s = p.intern(table[b].name.as_bytes());
                    assert!(
                        p.builtins < INITIAL_SYMBOLS,
                        "more builtins than INITIAL_SYMBOLS"
                    );
                    p.builtin_syms[p.builtins] = s;
                    p.builtins += 1;
                    b += 1;
                }
                t += 1;
            }
            g += 1;
        }
        p
    }

    /// `SymbolTable::intern_key` over the fixed arrays, without growth.
    const fn intern(&mut self, key: &[u8]) -> u32 {
        let (text, ends) = (
            self.text.split_at(self.text_len).0,
            self.ends.split_at(self.len).0,
        );
        let i = match probe(text, ends, &self.slots, key) {
            Probe::Found(s) => return s.0,
            Probe::Free(i) => i,
        };
        assert!(
            self.text_len + key.len() <= INITIAL_TEXT,
            "names beyond INITIAL_TEXT"
        );
        assert!(
            2 * (self.len + 1) <= INITIAL_SLOTS,
            "symbols beyond half of INITIAL_SLOTS"
        );
        let mut j = 0;
        while j < key.len() {
            assert!(key[j].is_ascii(), "a builtin name that is not ASCII");
            self.text[self.text_len] = key[j].to_ascii_uppercase();
            self.text_len += 1;
            j += 1;
        }
        let s = self.len as u32;
        self.ends[self.len] = self.text_len as u32;
        self.len += 1;
        self.slots[i] = s + 1;
        s
    }

    /// Each builtin's symbol, in the order of the tables it was built from.
    pub fn builtin_syms(&self) -> impl Iterator<Item = Sym> + '_ {
        self.builtin_syms[..self.builtins].iter().map(|&s| Sym(s))
    }

    pub fn builtins(&self) -> usize {
        self.builtins
    }
}

/// Where a lookup ended: the symbol, or the free slot where it would go.
enum Probe {
    Found(Sym),
    Free(usize),
}

/// The open-addressing lookup shared by `SymbolTable` and the compile-time `Prebuilt`: names
/// upper case end to end in `text`, symbol `s` ending at `ends[s]`, `slots` holding symbol + 1
/// (0 free). `key` is either ASCII (matched case-insensitively) or already upper-cased.
#[inline]
const fn probe(text: &[u8], ends: &[u32], slots: &[u32], key: &[u8]) -> Probe {
    let mask = slots.len() - 1;
    let mut i = hash_bytes(key) as usize & mask;
    loop {
        let n = slots[i];
        if n == 0 {
            return Probe::Free(i);
        }
        let s = (n - 1) as usize;
        let start = if s == 0 { 0 } else { ends[s - 1] as usize };
        let end = ends[s] as usize;
        if end - start == key.len() {
            let mut j = 0;
            while j < key.len() && text[start + j] == key[j].to_ascii_uppercase() {
                j += 1;
            }
            if j == key.len() {
                return Probe::Found(Sym(n - 1));
            }
        }
        i = (i + 1) & mask;
    }
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

    /// A copy of a table computed at compile time.
    pub fn from_prebuilt(p: &Prebuilt) -> Self {
        let mut text = String::with_capacity(INITIAL_TEXT);
        // Built from `&str`s, upper-cased byte by byte only where ASCII, so always UTF-8.
        text.push_str(std::str::from_utf8(&p.text[..p.text_len]).unwrap_or_default());
        let mut ends = Vec::with_capacity(INITIAL_SYMBOLS);
        ends.extend_from_slice(&p.ends[..p.len]);
        SymbolTable {
            text,
            ends,
            slots: p.slots.to_vec(),
        }
    }

    /// Finds `key`, which is either ASCII (matched case-insensitively against the stored upper
    /// case) or already upper-cased.
    #[inline]
    fn probe(&self, key: &str) -> Probe {
        probe(
            self.text.as_bytes(),
            &self.ends,
            &self.slots,
            key.as_bytes(),
        )
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

    /// How many symbols fit before the names' ends grow.
    pub fn capacity(&self) -> usize {
        self.ends.capacity()
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

    fn dummy(_: &mut crate::lang::Interp, _: &[crate::lang::Value]) -> crate::lang::LResult {
        Ok(crate::lang::Value::Nil)
    }

    const fn b(name: &'static str) -> Builtin {
        Builtin {
            name,
            sig: "",
            doc: "",
            min: 0,
            max: 0,
            f: dummy,
            special: false,
        }
    }

    static ONE: &[Builtin] = &[b("car"), b("Cdr"), b("if"), b("vla-get-Name")];
    static TWO: &[Builtin] = &[b("CAR"), b("strcat"), b("*error*")];
    static GROUPS: &[&[(&str, &[Builtin])]] = &[&[("one", ONE)], &[("two", TWO)]];
    static PRE: Prebuilt = Prebuilt::new(GROUPS);

    #[test]
    fn a_prebuilt_table_is_the_one_interning_builds() {
        let mut t = SymbolTable::new();
        let syms: Vec<Sym> = [ONE, TWO]
            .iter()
            .flat_map(|table| table.iter().map(|b| b.name))
            .map(|n| t.intern(n))
            .collect();
        let p = SymbolTable::from_prebuilt(&PRE);
        assert_eq!(p.text, t.text);
        assert_eq!(p.ends, t.ends);
        assert_eq!(p.slots, t.slots);
        assert_eq!(PRE.builtin_syms().collect::<Vec<_>>(), syms);
        // The fixed symbols first, repeated names (any case) share one symbol.
        assert_eq!(syms[2], S_IF);
        assert_eq!(syms[4], syms[0]);
        assert_eq!(syms[6], S_ERROR);
        assert_eq!(p.name(syms[3]), "VLA-GET-NAME");
        assert_eq!(p.lookup("strCat"), Some(syms[5]));
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
