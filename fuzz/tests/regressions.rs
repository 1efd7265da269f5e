//! Every committed input (`fuzz/corpus/*/*` and `fuzz/crashes/*/*`) through every target: no
//! panic, no broken contract, memory within the budget, an answer within a time bound. Then a
//! short fuzz run with a fixed seed per target, so that the mutator and the checks are
//! exercised on every `cargo test`.

use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;

use wedge_fuzz::mutate::Mutator;
use wedge_fuzz::{TARGETS, Target, Verdict};

#[global_allocator]
static ALLOC: wedge_fuzz::alloc::Counting = wedge_fuzz::alloc::Counting;

/// Far beyond what any committed input needs (they are a few KB): only a hang reaches it.
const TIME_BOUND: Duration = Duration::from_secs(10);

/// Every committed input, with its path.
fn committed_inputs() -> Vec<(PathBuf, Vec<u8>)> {
    let mut inputs = Vec::new();
    for sub in ["corpus", "crashes"] {
        let dir = wedge_fuzz::fuzz_dir().join(sub);
        let Ok(entries) = std::fs::read_dir(&dir) else { continue };
        let mut folders: Vec<PathBuf> = entries.map(|e| e.unwrap().path()).collect();
        folders.sort();
        for folder in folders.into_iter().filter(|f| f.is_dir()) {
            inputs.extend(wedge_fuzz::read_dir_files(&folder).unwrap());
        }
    }
    inputs
}

/// Runs `target` on `input` in a thread of its own, so that a hang fails the test instead of
/// stopping it; `None` if no answer came within [`TIME_BOUND`].
fn run_bounded(target: &'static Target, input: Vec<u8>) -> Option<Verdict> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(wedge_fuzz::run(target, &input));
    });
    receive.recv_timeout(TIME_BOUND).ok()
}

#[test]
fn every_committed_input_gets_an_answer_from_every_target() {
    wedge_fuzz::quiet_panics();
    let inputs = committed_inputs();
    // The seeds of every target are there (a corpus folder renamed would empty this test).
    for t in TARGETS {
        let folder = wedge_fuzz::fuzz_dir().join("corpus").join(t.name);
        assert!(
            wedge_fuzz::read_dir_files(&folder).unwrap().len() >= 2,
            "fuzz/corpus/{} has fewer than 2 seeds",
            t.name
        );
    }
    let mut failures = Vec::new();
    for (path, bytes) in &inputs {
        for target in TARGETS {
            let what = format!("{} through {}", path.display(), target.name);
            match run_bounded(target, bytes.clone()) {
                None => failures.push(format!("{what}: no answer within {TIME_BOUND:?}")),
                Some(v) if v.failed() => failures.push(format!("{what}: {v}")),
                Some(_) => {}
            }
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn a_seeded_fuzz_run_of_every_target_finds_nothing() {
    wedge_fuzz::quiet_panics();
    let mut failures = Vec::new();
    'targets: for (i, target) in TARGETS.iter().enumerate() {
        let dir = wedge_fuzz::fuzz_dir().join("corpus").join(target.name);
        let corpus: Vec<Vec<u8>> =
            wedge_fuzz::read_dir_files(&dir).unwrap().into_iter().map(|(_, b)| b).collect();
        let mut mutator = Mutator::new(0x5eed + i as u64, target.tokens, 4096);
        let mut accepted = 0;
        for k in 0..2000 {
            let input = mutator.mutate(&corpus[k % corpus.len()], &corpus[(k / 7) % corpus.len()]);
            let verdict = wedge_fuzz::run(target, &input);
            if verdict.failed() {
                let text = String::from_utf8_lossy(&input);
                failures.push(format!("{}: {verdict} on the input {text:?}", target.name));
                continue 'targets;
            }
            accepted += usize::from(matches!(verdict, Verdict::Answer(Ok(_))));
        }
        // Mutations are small: some inputs still read, most do not.
        assert!((1..2000).contains(&accepted), "{}: {accepted} of 2000 accepted", target.name);
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}
