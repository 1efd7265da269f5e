//! SIGINT (Ctrl-C) and SIGTERM during a run: every temporary output file is removed, one
//! `error:` line is printed, and the program exits with 128 + the signal's number (130 for
//! SIGINT, 143 for SIGTERM), as a shell reports a process killed by it.
//!
//! The signals are caught by `signal-hook` and handled on a thread of their own, which may
//! take locks and remove files (a signal handler itself may not);
//! [`render::output::remove_temporaries_and_exit`] does the removal while no other thread can
//! create or rename an output.

use std::io::IsTerminal as _;
use std::path::Path;

use anyhow::Context as _;
use signal_hook::consts::{SIGINT, SIGTERM};
use signal_hook::iterator::Signals;

/// Starts handling SIGINT and SIGTERM for the rest of the run; `output` is the file named in
/// the message.
///
/// # Errors
///
/// If the handlers or their thread cannot be set up.
pub fn remove_outputs_on_interrupt(output: &Path) -> anyhow::Result<()> {
    let mut signals = Signals::new([SIGINT, SIGTERM]).context("cannot handle signals")?;
    let output = output.display().to_string();
    std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                let name = if signal == SIGINT { "SIGINT" } else { "SIGTERM" };
                // A progress line may be on the terminal: start a line of our own.
                let newline = if std::io::stderr().is_terminal() { "\n" } else { "" };
                eprintln!("{newline}error: {output}: interrupted by {name}, nothing written");
                render::output::remove_temporaries_and_exit(128 + signal);
            }
        })
        .context("cannot start the signal-handling thread")?;
    Ok(())
}
