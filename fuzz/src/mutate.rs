//! Mutations of an input: the generic byte-level ones of coverage-guided fuzzers, plus ones that
//! know the formats (numbers written as text, little-endian integers, the target's tokens).
//!
//! Without coverage feedback, the mutations have to reach the interesting code by themselves,
//! so each is chosen for a class of reader bug:
//! - bit and byte flips, inserts and deletes: parsers that index past what they checked;
//! - truncation: readers that trust a length or a count written earlier in the file;
//! - chunk duplication and splicing two corpus files: structure repeated or cut in the middle
//!   (a second header, a face before its vertices);
//! - a number in the text replaced by an extreme one (`1e309`, `nan`, `4294967295`, ...):
//!   overflow, non-finite values and index arithmetic;
//! - little-endian integers and floats written over bytes: counts, lengths and offsets of
//!   binary formats (`.npy` header length, binary STL and PLY counts, GLB chunk lengths);
//! - the target's tokens (keywords, header lines, dict keys) inserted or written over bytes.

use rand::Rng;
use rand::seq::IndexedRandom;
use rand_pcg::Pcg64Mcg;

/// Numbers as text that break naive parsers: overflow to infinity, NaN, negative zero,
/// integer limits either side of 32 and 64 bits, subnormals, and spellings `str::parse`
/// accepts or refuses.
pub const NUMBERS: &[&str] = &[
    "0",
    "-0",
    "1",
    "-1",
    "2",
    "1e309",
    "-1e309",
    "1e-320",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "infinity",
    "3.4028236e38",
    "4294967295",
    "4294967296",
    "-2147483648",
    "2147483648",
    "18446744073709551615",
    "18446744073709551616",
    "9223372036854775807",
    "-9223372036854775808",
    "65535",
    "65536",
    "256",
    "1e6",
    "1e9",
    "+1",
    ".5",
    "5.",
    "0x10",
    "1_000",
    "",
];

/// Integers worth writing over binary counts and lengths (as 1, 2, 4 or 8 little-endian bytes).
const INTEGERS: &[u64] = &[
    0,
    1,
    2,
    3,
    0x7f,
    0x80,
    0xff,
    0x100,
    0x7fff,
    0x8000,
    0xffff,
    0x1_0000,
    0x7fff_ffff,
    0x8000_0000,
    0xffff_ffff,
    0x1_0000_0000,
    0x7fff_ffff_ffff_ffff,
    u64::MAX,
];

/// Floats worth writing over binary coordinates.
const FLOATS: &[f64] =
    &[0.0, -0.0, 1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, f64::MAX, 1e-310];

/// A seeded source of mutations for one target.
pub struct Mutator {
    rng: Pcg64Mcg,
    tokens: &'static [&'static [u8]],
    max_len: usize,
}

impl Mutator {
    /// A mutator drawing from `seed`, inserting `tokens`, never growing an input beyond
    /// `max_len` bytes.
    #[must_use]
    pub fn new(seed: u64, tokens: &'static [&'static [u8]], max_len: usize) -> Self {
        use rand::SeedableRng as _;
        Self { rng: Pcg64Mcg::seed_from_u64(seed), tokens, max_len: max_len.max(1) }
    }

    /// The generator, for the caller's own choices (which corpus entry to mutate).
    pub fn rng(&mut self) -> &mut Pcg64Mcg {
        &mut self.rng
    }

    /// A new input: `base` changed by a few stacked mutations; `other` is another corpus
    /// entry for splicing.
    pub fn mutate(&mut self, base: &[u8], other: &[u8]) -> Vec<u8> {
        let mut data = base.to_vec();
        // Mostly one or two changes, sometimes many: small steps keep most of the structure,
        // large ones reach states no single step does.
        let rounds = 1 + (self.rng.random::<u32>() | 0x80).trailing_zeros().min(7) as usize;
        for _ in 0..rounds {
            self.once(&mut data, other);
        }
        data.truncate(self.max_len);
        data
    }

    /// One mutation of `data`.
    fn once(&mut self, data: &mut Vec<u8>, other: &[u8]) {
        let len = data.len();
        match self.rng.random_range(0..13) {
            0 if len > 0 => {
                let i = self.rng.random_range(0..len);
                data[i] ^= 1 << self.rng.random_range(0..8);
            }
            1 if len > 0 => {
                let i = self.rng.random_range(0..len);
                data[i] = *b"\0\n\r \t/-.e#\x7f\x80\xff".choose(&mut self.rng).expect("not empty");
            }
            2 => {
                let at = self.rng.random_range(0..=len);
                let n = self.rng.random_range(1..=8);
                let bytes: Vec<u8> = (0..n).map(|_| self.rng.random()).collect();
                self.insert(data, at, &bytes);
            }
            3 if len > 0 => {
                let (start, end) = self.range(len);
                data.drain(start..end);
            }
            4 if len > 0 => {
                let (start, end) = self.range(len);
                let chunk = data[start..end].to_vec();
                let at =
                    if self.rng.random_bool(0.5) { end } else { self.rng.random_range(0..=len) };
                // Sometimes many copies: counts that grow, headers repeated.
                let copies =
                    if self.rng.random_bool(0.1) { self.rng.random_range(2..64) } else { 1 };
                for _ in 0..copies {
                    self.insert(data, at, &chunk);
                }
            }
            5 if len > 0 => {
                let at = self.rng.random_range(0..=len);
                data.truncate(at);
            }
            6 if !other.is_empty() => {
                // Splice: a prefix of this input and a suffix of the other.
                let cut = self.rng.random_range(0..=len);
                let from = self.rng.random_range(0..other.len());
                data.truncate(cut);
                self.insert(data, cut, &other[from..]);
            }
            7 | 8 => self.replace_number(data),
            9 if len > 0 => {
                let width = *[1usize, 2, 4, 8].choose(&mut self.rng).expect("not empty");
                let mut value = *INTEGERS.choose(&mut self.rng).expect("not empty");
                if self.rng.random_bool(0.2) {
                    value = value.wrapping_add(self.rng.random_range(0..3)).wrapping_sub(1);
                }
                let bytes = value.to_le_bytes();
                self.overwrite(data, &bytes[..width]);
            }
            10 if len > 0 => {
                let value = *FLOATS.choose(&mut self.rng).expect("not empty");
                if self.rng.random_bool(0.5) {
                    self.overwrite(data, &(value as f32).to_le_bytes());
                } else {
                    self.overwrite(data, &value.to_le_bytes());
                }
            }
            _ => {
                let token = match self.tokens.choose(&mut self.rng) {
                    Some(t) => *t,
                    None => NUMBERS.choose(&mut self.rng).expect("not empty").as_bytes(),
                };
                if self.rng.random_bool(0.5) || len == 0 {
                    let at = self.boundary(data);
                    self.insert(data, at, token);
                } else {
                    self.overwrite(data, token);
                }
            }
        }
    }

    /// A short random range of `0..len` (mostly a few bytes, sometimes a large part).
    fn range(&mut self, len: usize) -> (usize, usize) {
        let start = self.rng.random_range(0..len);
        let most = if self.rng.random_bool(0.8) { 16 } else { len };
        let end = start + self.rng.random_range(1..=most.min(len - start));
        (start, end)
    }

    /// A position for an insertion: often just after a newline, so that inserted tokens and
    /// lines start a statement of a text format.
    fn boundary(&mut self, data: &[u8]) -> usize {
        let at = self.rng.random_range(0..=data.len());
        if self.rng.random_bool(0.5)
            && let Some(nl) = data[..at].iter().rposition(|&b| b == b'\n')
        {
            return nl + 1;
        }
        at
    }

    /// Inserts `bytes` at `at`, as much as the length limit allows.
    fn insert(&self, data: &mut Vec<u8>, at: usize, bytes: &[u8]) {
        let room = self.max_len.saturating_sub(data.len()).min(bytes.len());
        data.splice(at..at, bytes[..room].iter().copied());
    }

    /// Writes `bytes` over `data` at a random offset (growing it at the end if needed).
    fn overwrite(&mut self, data: &mut Vec<u8>, bytes: &[u8]) {
        let at = self.rng.random_range(0..=data.len());
        let end = (at + bytes.len()).min(data.len());
        data.splice(at..end, bytes.iter().copied());
    }

    /// Replaces one number written in the text (a run of digits with its sign, point and
    /// exponent) by one of [`NUMBERS`]; inserts one if the input has no digit.
    fn replace_number(&mut self, data: &mut Vec<u8>) {
        let number = NUMBERS.choose(&mut self.rng).expect("not empty").as_bytes();
        let digits: Vec<usize> = (0..data.len()).filter(|&i| data[i].is_ascii_digit()).collect();
        let Some(&i) = digits.choose(&mut self.rng) else {
            let at = self.boundary(data);
            self.insert(data, at, number);
            return;
        };
        let part = |b: u8| b.is_ascii_digit() || b"+-.eE".contains(&b);
        let start = data[..i].iter().rposition(|&b| !part(b)).map_or(0, |p| p + 1);
        let end = data[i..].iter().position(|&b| !part(b)).map_or(data.len(), |p| i + p);
        data.splice(start..end, number.iter().copied());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_seed_gives_the_same_inputs() {
        let base = b"v 1 2 3\nv 4 5 6\nf 1 2 3\n";
        let run = |seed| {
            let mut m = Mutator::new(seed, &[b"vn "], 64);
            (0..100).map(|_| m.mutate(base, b"other")).collect::<Vec<_>>()
        };
        assert_eq!(run(7), run(7));
        assert_ne!(run(7), run(8));
    }

    #[test]
    fn inputs_respect_the_length_limit_and_change() {
        let base = vec![b'x'; 40];
        let mut m = Mutator::new(1, &[b"a long token that does not fit"], 48);
        let outs: Vec<Vec<u8>> = (0..2000).map(|_| m.mutate(&base, &base)).collect();
        assert!(outs.iter().all(|o| o.len() <= 48));
        let changed = outs.iter().filter(|o| **o != base).count();
        // A few mutations may cancel out (a bit flipped twice); most must not.
        assert!(changed > 1800, "{changed} of 2000 inputs changed");
        // Every kind of change shows up: shorter, longer, the token, a number.
        assert!(outs.iter().any(|o| o.len() < 40));
        assert!(outs.iter().any(|o| o.len() > 40));
        assert!(outs.iter().any(|o| o.windows(6).any(|w| w == b"a long")));
        assert!(outs.iter().any(|o| o.windows(5).any(|w| w == b"1e309")));
    }

    #[test]
    fn numbers_are_replaced_whole() {
        let mut m = Mutator::new(3, &[], 1000);
        for _ in 0..200 {
            let mut data = b"f -12.5e3 x".to_vec();
            m.replace_number(&mut data);
            let text = String::from_utf8(data).unwrap();
            let middle = text.strip_prefix("f ").and_then(|t| t.strip_suffix(" x")).unwrap();
            assert!(NUMBERS.contains(&middle), "{text}");
        }
    }
}
