//! `wedge-fuzz`: mutation fuzzing of wedge's readers (see `fuzz/README.md`).
//!
//! The program runs each target in a child process of itself (a worker), so that what kills a
//! process (an allocation refused under the address-space limit, a stack overflow) is still
//! reported: the worker writes each input to `target/fuzz-inputs/TARGET.current` before running
//! it, and when the worker dies the parent saves that file under `fuzz/crashes/TARGET/`. What the
//! worker can catch itself (a panic, an answer that fails a check, too much memory held, an
//! input running past the time limit) it saves and reports, and exits with status 1.

use std::collections::HashSet;
use std::fs::File;
use std::os::unix::fs::FileExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use rand::Rng as _;
use wedge_fuzz::mutate::Mutator;
use wedge_fuzz::{TARGETS, Target, Verdict};

#[global_allocator]
static ALLOC: wedge_fuzz::alloc::Counting = wedge_fuzz::alloc::Counting;

const USAGE: &str = "usage: wedge-fuzz [TARGET... | all] [--seconds N] [--seed N] [--timeout N] \
[--max-len BYTES] [--memory-limit MIB] | wedge-fuzz TARGET --replay FILE... | wedge-fuzz --list";

/// Corpus entries kept in memory at most: beyond this, a new kind of answer replaces an old one.
const MAX_CORPUS: usize = 4096;

/// The command line.
struct Options {
    targets: Vec<&'static Target>,
    seconds: f64,
    seed: u64,
    timeout: f64,
    max_len: usize,
    memory_limit_mib: u64,
    replay: Vec<PathBuf>,
    worker: bool,
    list: bool,
}

fn parse(args: &[String]) -> Result<Options, String> {
    let seconds = match std::env::var("WEDGE_FUZZ_SECONDS") {
        Ok(s) => number(&s, "WEDGE_FUZZ_SECONDS")?,
        Err(_) => 60.0,
    };
    let seed = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64);
    let mut o = Options {
        targets: Vec::new(),
        seconds,
        seed,
        timeout: 5.0,
        max_len: 64 << 10,
        memory_limit_mib: 4096,
        replay: Vec::new(),
        worker: false,
        list: false,
    };
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        match arg.as_str() {
            "--seconds" => o.seconds = number(value(arg)?, arg)?,
            "--timeout" => o.timeout = number(value(arg)?, arg)?,
            "--seed" => o.seed = integer(value(arg)?, arg)?,
            "--max-len" => o.max_len = integer(value(arg)?, arg)? as usize,
            "--memory-limit" => o.memory_limit_mib = integer(value(arg)?, arg)?,
            "--replay" => o.replay.extend(it.by_ref().map(PathBuf::from)),
            "--worker" => o.worker = true,
            "--list" => o.list = true,
            "-h" | "--help" => return Err(String::new()),
            "all" => o.targets.extend(TARGETS),
            name if name.starts_with('-') => return Err(format!("unknown option '{name}'")),
            name => o.targets.push(wedge_fuzz::find(name).ok_or_else(|| {
                let names: Vec<&str> = TARGETS.iter().map(|t| t.name).collect();
                format!("unknown target '{name}' (the targets: {})", names.join(", "))
            })?),
        }
    }
    if o.targets.is_empty() {
        o.targets.extend(TARGETS);
    }
    if !o.replay.is_empty() && o.targets.len() != 1 {
        return Err("--replay needs exactly one target".into());
    }
    if o.timeout <= 0.0 || o.max_len == 0 {
        return Err("--timeout and --max-len must be positive".into());
    }
    Ok(o)
}

fn number(text: &str, name: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err(format!("{name}: '{text}' is not a number of seconds")),
    }
}

fn integer(text: &str, name: &str) -> Result<u64, String> {
    text.parse().map_err(|_| format!("{name}: '{text}' is not a whole number"))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let options = match parse(&args) {
        Ok(o) => o,
        Err(e) if e.is_empty() => {
            println!("{USAGE}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("error: {e} (see --help)");
            return ExitCode::from(2);
        }
    };
    if options.list {
        for t in TARGETS {
            println!("{}", t.name);
        }
        return ExitCode::SUCCESS;
    }
    if options.worker || !options.replay.is_empty() {
        let target = options.targets[0];
        return match worker(target, &options) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        };
    }
    supervise(&options)
}

/// Runs one worker per target, one after the other; fails if any failed.
fn supervise(o: &Options) -> ExitCode {
    let mut failed = false;
    for (i, target) in o.targets.iter().enumerate() {
        let exe = std::env::current_exe().expect("the path of this program");
        let status = Command::new(exe)
            .args([target.name, "--worker"])
            .args(["--seconds", &o.seconds.to_string(), "--timeout", &o.timeout.to_string()])
            .args(["--seed", &o.seed.wrapping_add(i as u64).to_string()])
            .args(["--max-len", &o.max_len.to_string()])
            .args(["--memory-limit", &o.memory_limit_mib.to_string()])
            .status();
        match status {
            Ok(s) if s.success() => {}
            // The worker has saved and reported the input.
            Ok(s) if s.code() == Some(1) => failed = true,
            other => {
                failed = true;
                let how = match &other {
                    Ok(s) => describe(s),
                    Err(e) => format!("could not be started: {e}"),
                };
                let current = current_path(target);
                match std::fs::read(&current) {
                    Ok(bytes) => match save_crash(target, &bytes) {
                        Ok(path) => eprintln!(
                            "error: {}: {}: the worker {how} on this input",
                            path.display(),
                            target.name
                        ),
                        Err(e) => eprintln!("error: {}: {e}", current.display()),
                    },
                    Err(e) => eprintln!("error: {}: {how}; {e}", current.display()),
                }
            }
        }
    }
    if failed { ExitCode::FAILURE } else { ExitCode::SUCCESS }
}

/// How a process ended, for a message.
fn describe(status: &std::process::ExitStatus) -> String {
    use std::os::unix::process::ExitStatusExt as _;
    match (status.code(), status.signal()) {
        (Some(code), _) => format!("exited with status {code}"),
        (None, Some(6)) => "aborted (SIGABRT: an allocation refused, or a stack overflow)".into(),
        (None, Some(sig)) => format!("was killed by signal {sig}"),
        (None, None) => "ended in an unknown way".into(),
    }
}

/// `target/fuzz-inputs/NAME.current`: the input being run, for a post-mortem.
fn current_path(target: &Target) -> PathBuf {
    let target_dir = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(|| wedge_fuzz::fuzz_dir().join("../target"), PathBuf::from);
    target_dir.join("fuzz-inputs").join(format!("{}.current", target.name))
}

/// Saves a failing input as `fuzz/crashes/NAME/crash-HASH` and returns its path.
fn save_crash(target: &Target, bytes: &[u8]) -> std::io::Result<PathBuf> {
    let dir = wedge_fuzz::fuzz_dir().join("crashes").join(target.name);
    std::fs::create_dir_all(&dir)?;
    let path = dir.join(wedge_fuzz::content_name(bytes));
    std::fs::write(&path, bytes)?;
    // A path relative to the working directory reads better when it is below it.
    let cwd = std::env::current_dir().unwrap_or_default();
    Ok(path.strip_prefix(&cwd).map(Path::to_path_buf).unwrap_or(path))
}

/// Limits the address space, so that a runaway allocation fails instead of taking the machine.
fn limit_memory(mib: u64) -> Result<(), String> {
    let bytes = mib.saturating_mul(1 << 20) as libc::rlim_t;
    let limit = libc::rlimit { rlim_cur: bytes, rlim_max: bytes };
    // SAFETY: setrlimit reads the struct it is given and nothing else.
    if unsafe { libc::setrlimit(libc::RLIMIT_AS, &limit) } != 0 {
        return Err(format!("cannot limit memory: {}", std::io::Error::last_os_error()));
    }
    Ok(())
}

/// The input file and the watchdog of one worker.
struct Runner {
    target: &'static Target,
    current: File,
    /// Milliseconds since `epoch` at which the input being run started, 0 when idle.
    started: Arc<AtomicU64>,
    epoch: Instant,
}

impl Runner {
    fn new(target: &'static Target, timeout: Duration) -> Result<Self, String> {
        let path = current_path(target);
        let fail = |e: std::io::Error| format!("{}: {e}", path.display());
        std::fs::create_dir_all(path.parent().expect("a file in a folder")).map_err(fail)?;
        let current = File::create(&path).map_err(fail)?;
        let started = Arc::new(AtomicU64::new(0));
        let epoch = Instant::now();
        let watched = Arc::clone(&started);
        // The watchdog: an input still running after `timeout` is a hang. The worker thread
        // cannot be stopped, so the watchdog saves the input (from the file) and ends the
        // process.
        std::thread::spawn(move || {
            loop {
                std::thread::sleep(Duration::from_millis(50));
                let start = watched.load(Relaxed);
                let now = epoch.elapsed().as_millis() as u64;
                if start != 0 && now.saturating_sub(start) > timeout.as_millis() as u64 {
                    let bytes = std::fs::read(&path).unwrap_or_default();
                    let saved = save_crash(target, &bytes)
                        .map_or_else(|e| format!("(not saved: {e})"), |p| p.display().to_string());
                    eprintln!(
                        "error: {saved}: {}: no answer after {:.1} s (a hang)",
                        target.name,
                        timeout.as_secs_f64()
                    );
                    std::process::exit(1);
                }
            }
        });
        Ok(Self { target, current, started, epoch })
    }

    /// Runs one input; a failure is saved and returned as the error line.
    fn run(&self, input: &[u8]) -> Result<Verdict, String> {
        // Written before the run, so that an abort leaves it behind.
        self.current
            .write_all_at(input, 0)
            .and_then(|()| self.current.set_len(input.len() as u64))
            .map_err(|e| format!("{}: {e}", current_path(self.target).display()))?;
        self.started.store((self.epoch.elapsed().as_millis() as u64).max(1), Relaxed);
        let verdict = wedge_fuzz::run(self.target, input);
        self.started.store(0, Relaxed);
        if verdict.failed() {
            let saved = save_crash(self.target, input)
                .map_or_else(|e| format!("(not saved: {e})"), |p| p.display().to_string());
            return Err(format!("{saved}: {}: {verdict}", self.target.name));
        }
        Ok(verdict)
    }
}

/// Fuzzes one target for the time asked for, or replays the given files through it.
fn worker(target: &'static Target, o: &Options) -> Result<(), String> {
    limit_memory(o.memory_limit_mib)?;
    wedge_fuzz::quiet_panics();
    let runner = Runner::new(target, Duration::from_secs_f64(o.timeout))?;
    if !o.replay.is_empty() {
        let mut failures = 0;
        for path in &o.replay {
            let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
            match runner.run(&bytes) {
                Ok(verdict) => println!("{}: {verdict}", path.display()),
                Err(e) => {
                    failures += 1;
                    eprintln!("error: {e}");
                }
            }
        }
        return match failures {
            0 => Ok(()),
            n => Err(format!("{n} of {} inputs failed", o.replay.len())),
        };
    }

    let dir = wedge_fuzz::fuzz_dir();
    let mut corpus = Vec::new();
    for sub in ["corpus", "crashes"] {
        let folder = dir.join(sub).join(target.name);
        let files = wedge_fuzz::read_dir_files(&folder)
            .map_err(|e| format!("{}: {e}", folder.display()))?;
        corpus.extend(files.into_iter().map(|(_, bytes)| bytes));
    }
    if corpus.is_empty() {
        corpus.push(Vec::new());
    }
    let seeds = corpus.len();
    note(&format!(
        "fuzz {}: seed {}, {seeds} seed inputs, {:.0} s",
        target.name, o.seed, o.seconds
    ));

    let mut kinds = HashSet::new();
    // The seeds as they are first: a committed input that fails should fail at once.
    for input in &corpus {
        let verdict = runner.run(input)?;
        if let Verdict::Answer(outcome) = &verdict {
            kinds.insert(wedge_fuzz::signature(outcome, input));
        }
    }
    let mut mutator = Mutator::new(o.seed, target.tokens, o.max_len);
    let start = Instant::now();
    let mut last_report = start;
    let mut execs = 0u64;
    while start.elapsed().as_secs_f64() < o.seconds {
        let base = mutator.rng().random_range(0..corpus.len());
        let other = mutator.rng().random_range(0..corpus.len());
        let input = mutator.mutate(&corpus[base], &corpus[other]);
        let verdict = runner.run(&input)?;
        execs += 1;
        if let Verdict::Answer(outcome) = &verdict
            && kinds.insert(wedge_fuzz::signature(outcome, &input))
        {
            if corpus.len() < MAX_CORPUS {
                corpus.push(input);
            } else {
                // Full: a new kind takes the place of an earlier find (never of a seed).
                let at = mutator.rng().random_range(seeds..corpus.len());
                corpus[at] = input;
            }
        }
        if last_report.elapsed() >= Duration::from_secs(5) {
            last_report = Instant::now();
            let rate = execs as f64 / start.elapsed().as_secs_f64();
            note(&format!(
                "fuzz {}: {execs} execs ({rate:.0}/s), {} kinds of answer, corpus {}",
                target.name,
                kinds.len(),
                corpus.len()
            ));
        }
    }
    let secs = start.elapsed().as_secs_f64();
    note(&format!(
        "fuzz {}: no failure in {execs} execs over {secs:.1} s ({:.0}/s), {} kinds of answer",
        target.name,
        execs as f64 / secs.max(1e-9),
        kinds.len()
    ));
    Ok(())
}

/// A progress line on stderr. Unlike `eprintln!`, it does not panic when stderr is closed
/// (`wedge-fuzz ... 2>&1 | head`): that panic would be taken for the reader's.
fn note(line: &str) {
    use std::io::Write as _;
    let _ = writeln!(std::io::stderr(), "{line}");
}
