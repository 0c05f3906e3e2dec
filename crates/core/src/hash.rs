//! A fast hasher for the short keys of the parameter analysis and the converter's parameter
//! classes (a name of a few bytes, or a few integers), looked up once or twice for every
//! parameter a word reads: the standard library's SipHash, made to resist crafted keys from
//! an attacker, cost more than the rest of the lookup. These maps hold the names of one
//! program, so that resistance buys nothing here. The mixing is the one rustc's own FxHasher
//! uses (a multiply and a rotate a word at a time).

use std::collections::{HashMap, HashSet};
use std::hash::{BuildHasherDefault, Hasher};

const SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

/// The hasher: eight bytes at a time, then the rest.
#[derive(Debug, Default, Clone, Copy)]
pub struct Fast(u64);

impl Fast {
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(SEED);
    }
}

impl Hasher for Fast {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for chunk in &mut chunks {
            self.add(u64::from_le_bytes(chunk.try_into().unwrap_or_default()));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut last = [0u8; 8];
            last[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(last));
        }
    }

    fn write_u8(&mut self, n: u8) {
        self.add(u64::from(n));
    }

    fn write_u32(&mut self, n: u32) {
        self.add(u64::from(n));
    }

    fn write_u64(&mut self, n: u64) {
        self.add(n);
    }

    fn write_usize(&mut self, n: usize) {
        self.add(n as u64);
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

pub type FastMap<K, V> = HashMap<K, V, BuildHasherDefault<Fast>>;
pub type FastSet<K> = HashSet<K, BuildHasherDefault<Fast>>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_that_differ_in_any_byte_or_length_hash_apart() {
        let names = [
            "#1",
            "#10",
            "#<a>",
            "#<b>",
            "#<xscale>",
            "#<yscale>",
            "#<zscale>",
            "R1",
        ];
        let hashes: FastSet<u64> = names
            .iter()
            .map(|n| {
                let mut h = Fast::default();
                h.write(n.as_bytes());
                h.finish()
            })
            .collect();
        assert_eq!(hashes.len(), names.len());
        let mut map: FastMap<String, usize> = FastMap::default();
        for (i, n) in names.iter().enumerate() {
            map.insert(n.to_string(), i);
        }
        assert_eq!(map.get("#<yscale>"), Some(&5));
        assert_eq!(map.get("#<wscale>"), None);
    }
}
