//! Command-line parsing shared by both programs: value parsers that say the real limits, and
//! clap's errors turned into the programs' one line without losing what clap knows (the
//! missing arguments, the possible values, the suggestion).

use std::process::ExitCode;

/// How many worker threads per core `--threads` may ask for: more only adds the cost of
/// starting them (10,000 threads took half a minute to start for a one-triangle scene).
pub const THREADS_PER_CORE: usize = 4;

pub use backends::machine::cores;

/// Checks a `--threads` value against `cores`: `0` (one thread per core) up to
/// [`THREADS_PER_CORE`] per core.
///
/// # Errors
///
/// A message giving the limit, for a number above it.
pub fn check_threads(n: usize, cores: usize) -> Result<usize, String> {
    let max = THREADS_PER_CORE * cores;
    if n > max {
        return Err(format!(
            "at most {max} threads ({THREADS_PER_CORE} per core, {cores} cores); \
             0 means one per core"
        ));
    }
    Ok(n)
}

/// Parses `--threads N` (see [`check_threads`]).
///
/// # Errors
///
/// A message for anything but a whole number in range.
pub fn parse_threads(text: &str) -> Result<usize, String> {
    let n = text
        .parse::<usize>()
        .map_err(|_| format!("'{text}' is not a whole number of threads (0 means one per core)"))?;
    check_threads(n, cores())
}

/// The number of threads `--threads` asks for: `None` or `0` is one per core.
#[must_use]
pub fn resolve_threads(threads: Option<usize>) -> usize {
    match threads {
        None | Some(0) => cores(),
        Some(n) => n,
    }
}

/// Parses `--fov DEG`: a number strictly between 0 and 180.
///
/// # Errors
///
/// A message giving the range.
pub fn parse_fov(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(v) if v > 0.0 && v < 180.0 => Ok(v),
        Ok(v) => Err(format!("the field of view must be in (0, 180) degrees, got {v}")),
        Err(_) => Err(format!("'{text}' is not a number of degrees")),
    }
}

/// Parses `X,Y,Z` into three finite numbers (for `--eye`, `--look-at`, `--up`).
///
/// # Errors
///
/// A message naming what is wrong.
pub fn parse_vec3(text: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let [x, y, z] = parts[..] else {
        return Err(format!("expected three comma-separated numbers X,Y,Z, got '{text}'"));
    };
    let num = |s: &str| match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("'{s}' is not a finite number")),
    };
    Ok([num(x)?, num(y)?, num(z)?])
}

/// clap's error as one line: its message lines up to the usage, joined; the list of missing
/// arguments and of possible values kept, tips (a suggestion) after `"; "`.
#[must_use]
pub fn clap_error_line(e: &clap::Error) -> String {
    let text = e.to_string();
    let mut line = String::new();
    for part in text.lines().map(str::trim) {
        if part.starts_with("Usage:") || part.starts_with("For more information") {
            break;
        }
        let part = part.strip_prefix("error: ").unwrap_or(part);
        if part.is_empty() {
            continue;
        }
        if !line.is_empty() {
            line.push_str(if part.starts_with("tip:") { "; " } else { " " });
        }
        line.push_str(part);
    }
    if line.is_empty() {
        line.push_str("invalid arguments");
    }
    line
}

/// Turns a clap error into the programs' exit: help and version go to stdout with status 0;
/// usage errors print one `error:` line and give status 2.
#[must_use]
pub fn clap_exit(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        print!("{e}");
        return ExitCode::SUCCESS;
    }
    eprintln!("error: {} (see --help)", clap_error_line(e));
    ExitCode::from(2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vec3_parsing() {
        assert_eq!(parse_vec3("1,-2.5, 3e1"), Ok([1.0, -2.5, 30.0]));
        assert!(parse_vec3("1,2").unwrap_err().contains("three"));
        assert!(parse_vec3("1,2,nan").unwrap_err().contains("'nan'"));
        assert!(parse_vec3("1,2,x").is_err());
    }

    #[test]
    fn threads_are_bounded_by_the_cores() {
        assert_eq!(check_threads(0, 2), Ok(0));
        assert_eq!(check_threads(8, 2), Ok(8));
        let e = check_threads(9, 2).unwrap_err();
        assert!(e.starts_with("at most 8 threads") && e.contains("0 means one per core"), "{e}");
        assert!(parse_threads("-1").unwrap_err().contains("'-1'"));
        assert!(parse_threads("10000000").is_err());
        assert_eq!(resolve_threads(Some(0)), cores());
        assert_eq!(resolve_threads(None), cores());
        assert_eq!(resolve_threads(Some(3)), 3);
    }

    #[test]
    fn fov_is_an_open_range() {
        assert_eq!(parse_fov("45"), Ok(45.0));
        assert_eq!(parse_fov("179.5"), Ok(179.5));
        for bad in ["0", "-10", "180", "1e3", "nan", "inf"] {
            let e = parse_fov(bad).unwrap_err();
            assert!(e.contains("(0, 180)"), "{bad}: {e}");
        }
        assert!(parse_fov("wide").unwrap_err().contains("'wide'"));
    }

    #[test]
    fn clap_lines_keep_the_detail() {
        use clap::{Arg, Command};
        let cmd = || {
            Command::new("p")
                .arg(Arg::new("input").required(true))
                .arg(Arg::new("output").required(true))
                .arg(Arg::new("mode").long("mode").value_parser(["alpha", "normal"]))
        };
        let e = cmd().try_get_matches_from(["p"]).unwrap_err();
        let line = clap_error_line(&e);
        assert!(line.contains("<input>") && line.contains("<output>"), "{line}");
        assert!(!line.contains('\n'));
        let e = cmd().try_get_matches_from(["p", "a", "b", "--mode", "normals"]).unwrap_err();
        let line = clap_error_line(&e);
        assert!(line.contains("normals") && line.contains("alpha, normal"), "{line}");
        assert!(line.contains("; tip: a similar value exists: 'normal'"), "{line}");
    }
}
