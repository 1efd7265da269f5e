//! A small coverage-free mutation fuzzer for wedge's file readers, on stable Rust.
//!
//! The binary (`cargo run --release -p wedge-fuzz -- TARGET --seconds 60`, see
//! `fuzz/README.md`) mutates the seed files of `fuzz/corpus/TARGET/` ([`mutate`]) and runs the
//! target's reader on each result ([`run`]). An input fails when the reader panics, when its
//! answer breaks the reader's contract ([`targets`]), when it holds more memory than
//! [`memory_budget`] allows, or (checked by the binary) when it takes too long. Without
//! coverage the only feedback is the answer: an input whose answer is of a kind not seen
//! before (a new error message, numbers aside) joins the corpus, so that later mutations
//! start from inputs that got further into the reader.
//!
//! The library is shared by the binary and by the regression test `fuzz/tests/`, which runs
//! every committed corpus and crash file through every target.

#![deny(missing_docs)]

pub mod alloc;
pub mod mutate;
pub mod targets;

use std::panic::{self, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

pub use targets::{Outcome, TARGETS, Target, find};

/// Memory any input may make a reader hold, beyond [`Target::memory_per_byte`] per byte.
pub const MEMORY_BASE: usize = 64 << 20;

/// How one input fared.
#[derive(Debug)]
pub enum Verdict {
    /// The reader answered, and the answer passed the target's checks.
    Answer(Outcome),
    /// The reader panicked, or its answer failed a check: the message and where.
    Panic(String),
    /// The reader held more memory at once than [`memory_budget`] allows.
    Memory {
        /// The most bytes held at once.
        peak: usize,
        /// The budget for this input.
        budget: usize,
    },
}

impl Verdict {
    /// Whether this is a failure to report.
    #[must_use]
    pub fn failed(&self) -> bool {
        !matches!(self, Verdict::Answer(_))
    }
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Verdict::Answer(Ok(what)) => write!(f, "accepted ({what})"),
            Verdict::Answer(Err(e)) => write!(f, "refused: {e}"),
            Verdict::Panic(msg) => write!(f, "panic: {msg}"),
            Verdict::Memory { peak, budget } => {
                write!(f, "held {peak} bytes at once, more than the budget of {budget}")
            }
        }
    }
}

/// The memory `target` may hold for an input of `len` bytes.
#[must_use]
pub fn memory_budget(target: &Target, len: usize) -> usize {
    MEMORY_BASE.saturating_add(target.memory_per_byte.saturating_mul(len))
}

/// The last panic's message and location, recorded by the hook of [`quiet_panics`].
static LAST_PANIC: Mutex<Option<String>> = Mutex::new(None);

std::thread_local! {
    /// Whether this thread is inside [`run`], whose panics [`quiet_panics`] records.
    static IN_RUN: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Installs a panic hook that, for a panic inside [`run`], prints nothing and records the
/// message and location for [`run`] to report (a fuzzer expects panics and reports them
/// itself); other panics (a failed test assertion) go to the hook there was before.
pub fn quiet_panics() {
    let before = panic::take_hook();
    panic::set_hook(Box::new(move |info| {
        if !IN_RUN.get() {
            return before(info);
        }
        let payload = info.payload();
        let msg = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_owned());
        let place =
            info.location().map(|l| format!(" at {}:{}:{}", l.file(), l.line(), l.column()));
        let text = format!("{}{}", msg.replace('\n', " "), place.unwrap_or_default());
        *LAST_PANIC.lock().unwrap_or_else(|e| e.into_inner()) = Some(text);
    }));
}

/// Runs `target` on `input`, catching a panic and measuring the memory held (measured only
/// when [`alloc::Counting`] is the global allocator).
pub fn run(target: &Target, input: &[u8]) -> Verdict {
    let before = alloc::live();
    alloc::reset_peak();
    IN_RUN.set(true);
    let result = panic::catch_unwind(AssertUnwindSafe(|| (target.run)(input)));
    IN_RUN.set(false);
    let peak = alloc::peak().saturating_sub(before);
    match result {
        Err(payload) => {
            let recorded = LAST_PANIC.lock().unwrap_or_else(|e| e.into_inner()).take();
            let msg = recorded
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic without a message".to_owned());
            Verdict::Panic(msg)
        }
        Ok(_) if peak > memory_budget(target, input.len()) => {
            Verdict::Memory { peak, budget: memory_budget(target, input.len()) }
        }
        Ok(outcome) => Verdict::Answer(outcome),
    }
}

/// The kind of an answer, for telling new behaviour from old: the words of the outcome (runs
/// of two or more ASCII letters) outside quotes (before the first quote or backquote and after
/// the last) that the input does not contain. What a message quotes from the input (a bad
/// number, an unknown key, escaped or not) and the numbers in it drop out, so messages from
/// the same place in a reader have the same kind, and the kinds are few.
#[must_use]
pub fn signature(outcome: &Outcome, input: &[u8]) -> String {
    let (tag, text) = match outcome {
        Ok(what) => ("ok", what.as_str()),
        Err(e) => ("err", e.as_str()),
    };
    let quote = |c: char| matches!(c, '`' | '\'' | '"');
    let (before, after) = match (text.find(quote), text.rfind(quote)) {
        (Some(first), Some(last)) => (&text[..first], &text[last + 1..]),
        _ => (text, ""),
    };
    let from_input = |w: &str| input.windows(w.len()).any(|x| x == w.as_bytes());
    let words = [before, "''", after]
        .into_iter()
        .flat_map(|part| part.split(|c: char| !c.is_ascii_alphabetic() && c != '\''))
        .filter(|w| (w.len() >= 2 && !from_input(w)) || *w == "''");
    let mut sig = tag.to_owned();
    for w in words {
        sig.push(' ');
        sig.push_str(w);
    }
    sig
}

/// The folder of this crate's sources (`fuzz/`), where `corpus/` and `crashes/` live.
#[must_use]
pub fn fuzz_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The files of `dir` (not its subfolders), sorted by name, with their contents; none if
/// `dir` does not exist. Names starting with `.` and `README.md` are left out.
///
/// # Errors
///
/// If the folder or a file in it cannot be read.
pub fn read_dir_files(dir: &Path) -> std::io::Result<Vec<(PathBuf, Vec<u8>)>> {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(e),
    };
    let mut paths = Vec::new();
    for entry in entries {
        let entry = entry?;
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if entry.file_type()?.is_file() && !name.starts_with('.') && name != "README.md" {
            paths.push(entry.path());
        }
    }
    paths.sort();
    paths.into_iter().map(|p| std::fs::read(&p).map(|bytes| (p, bytes))).collect()
}

/// A name for an input that depends only on its bytes (FNV-1a, 64 bits, in hex), so that the
/// same crash found twice is saved once.
#[must_use]
pub fn content_name(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    format!("crash-{h:016x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signatures_keep_the_words_that_are_not_from_the_input() {
        let msg = |m: &str| Err(m.to_owned());
        let a =
            signature(&msg("x:12: face index 9 is out of range (the file has 8 vertices)"), b"");
        let b =
            signature(&msg("x:3: face index 1234 is out of range (the file has 1 vertices)"), b"");
        assert_eq!(a, b);
        assert_eq!(a, "err face index is out of range the file has vertices ''");
        let input = b"v 1 2 3e4x4 `x\nf 1 2 3";
        let quoted = signature(&msg("in:1: `3e4x4 `x` is not a number"), input);
        assert_eq!(quoted, "err in '' is not number");
        let key = |k: &str| msg(&format!("header: unexpected key '{k}'"));
        assert_eq!(signature(&key("a\\'b"), b""), signature(&key("c"), b""));
        assert_eq!(signature(&Ok("mesh".into()), b""), "ok mesh ''");
        assert_ne!(signature(&msg("mesh"), b""), signature(&Ok("mesh".into()), b""));
    }

    #[test]
    fn content_names_are_fnv1a() {
        // FNV-1a 64 of "" and "a", from the published test vectors.
        assert_eq!(content_name(b""), "crash-cbf29ce484222325");
        assert_eq!(content_name(b"a"), "crash-af63dc4c8601ec8c");
    }

    #[test]
    fn panics_are_caught_with_their_place() {
        quiet_panics();
        let t = Target {
            name: "boom",
            run: |b| if b.is_empty() { panic!("empty input") } else { Ok("fine".into()) },
            tokens: &[],
            memory_per_byte: 0,
        };
        let v = run(&t, b"");
        let Verdict::Panic(msg) = &v else { panic!("{v:?}") };
        assert!(msg.starts_with("empty input at ") && msg.contains("lib.rs:"), "{msg}");
        assert!(v.failed());
        assert!(!run(&t, b"x").failed());
    }

    #[test]
    fn every_target_answers_an_empty_input() {
        for t in TARGETS {
            let v = run(t, b"");
            assert!(matches!(v, Verdict::Answer(Err(_))), "{}: {v}", t.name);
        }
    }
}
