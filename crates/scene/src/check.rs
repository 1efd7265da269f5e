//! A line-by-line check of OBJ text that names the first line the loader cannot accept.
//!
//! It runs only after a load has failed (tobj's errors carry no line number) or after the
//! loaded data showed something the loader rejects, so its speed does not matter; it follows
//! tobj's reading of each statement so that it blames the line tobj choked on.

use super::SceneError;

/// The first line of `text` that makes loading fail, as an error naming `file` and the line;
/// `None` if every line is acceptable.
pub(super) fn first_problem(text: &str, file: &str) -> Option<SceneError> {
    let mut totals = Counts::default();
    for line in text.lines() {
        totals.count(line.split_whitespace().next());
    }
    let mut so_far = Counts::default();
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let keyword = words.next();
        let words: Vec<&str> = words.collect();
        let result = match keyword {
            Some("v") => check_vertex(&words),
            Some("vt") => check_numbers(&words, 2, "texture coordinate", None),
            Some("vn") => check_numbers(&words, 3, "normal", Some("normal component")),
            Some("f") => check_face(&words, &so_far, &totals),
            Some("usemtl") if words.is_empty() => {
                Err(Problem::Malformed("`usemtl` needs a material name".to_owned()))
            }
            _ => Ok(()),
        };
        if let Err(problem) = result {
            let (file, line) = (file.to_owned(), i + 1);
            return Some(match problem {
                Problem::Malformed(problem) => SceneError::Malformed { file, line, problem },
                Problem::NotFinite { what, value } => {
                    SceneError::NotFinite { file, line, what, value }
                }
            });
        }
        so_far.count(keyword);
    }
    None
}

/// What is wrong with one line.
enum Problem {
    Malformed(String),
    NotFinite { what: &'static str, value: String },
}

/// Numbers of vertices, texture coordinates and normals.
#[derive(Default)]
struct Counts {
    v: usize,
    vt: usize,
    vn: usize,
}

impl Counts {
    fn count(&mut self, keyword: Option<&str>) {
        match keyword {
            Some("v") => self.v += 1,
            Some("vt") => self.vt += 1,
            Some("vn") => self.vn += 1,
            _ => {}
        }
    }
}

fn number(word: &str) -> Result<f64, Problem> {
    word.parse::<f64>().map_err(|_| Problem::Malformed(format!("`{word}` is not a number")))
}

/// `v x y z`, optionally followed by `w` or by `r g b` (tobj's reading).
fn check_vertex(words: &[&str]) -> Result<(), Problem> {
    check_numbers(words, 3, "vertex", None)?;
    let mut xyz = [0.0; 3];
    for (x, w) in xyz.iter_mut().zip(words) {
        *x = number(w)?;
    }
    match &words[3..] {
        [] => {}
        [w] => {
            let w = number(w)?;
            if w == 0.0 {
                return Err(Problem::Malformed("vertex weight w is 0".to_owned()));
            }
            xyz = xyz.map(|x| x / w);
        }
        [_, _, _] => {}
        _ => {
            return Err(Problem::Malformed(format!(
                "a vertex has 3 coordinates, optionally followed by w or by r g b; \
                 found {} numbers",
                words.len()
            )));
        }
    }
    for (k, x) in xyz.iter().enumerate() {
        if !x.is_finite() {
            let value = if !number(words[k])?.is_finite() {
                words[k].to_owned()
            } else {
                // Finite as written, overflowed by the division by w.
                format!("{} / {}", words[k], words[3])
            };
            return Err(Problem::NotFinite { what: "vertex coordinate", value });
        }
    }
    Ok(())
}

/// At least `n` numbers (tobj ignores the rest); `finite` names what must be finite, if
/// anything.
fn check_numbers(
    words: &[&str],
    n: usize,
    what: &str,
    finite: Option<&'static str>,
) -> Result<(), Problem> {
    if words.len() < n {
        return Err(Problem::Malformed(format!(
            "a {what} needs {n} numbers, found {}",
            words.len()
        )));
    }
    for word in &words[..n] {
        let x = number(word)?;
        if let Some(what) = finite
            && !x.is_finite()
        {
            return Err(Problem::NotFinite { what, value: (*word).to_owned() });
        }
    }
    Ok(())
}

/// `f v1 v2 v3 ...` with each vertex `v`, `v/vt`, `v//vn` or `v/vt/vn`.
fn check_face(words: &[&str], so_far: &Counts, totals: &Counts) -> Result<(), Problem> {
    for word in words {
        let parts: Vec<&str> = word.split('/').collect();
        if parts.len() > 3 {
            return Err(Problem::Malformed(format!(
                "face vertex `{word}` has more than 3 indices (v/vt/vn)"
            )));
        }
        if parts[0].is_empty() {
            return Err(Problem::Malformed(format!("face vertex `{word}` has no vertex index")));
        }
        let kinds = [
            ("vertices", "vertex", so_far.v, totals.v),
            ("texture coordinates", "texture coordinate", so_far.vt, totals.vt),
            ("normals", "normal", so_far.vn, totals.vn),
        ];
        for (part, (plural, singular, before, total)) in parts.iter().zip(kinds) {
            if part.is_empty() {
                continue;
            }
            let index: i64 = part.parse().map_err(|_| {
                Problem::Malformed(format!("`{part}` in face vertex `{word}` is not an index"))
            })?;
            // tobj checks texture and normal indices only when the file has some.
            if total == 0 && singular != "vertex" {
                continue;
            }
            let prefix = if singular == "vertex" { "face" } else { singular };
            if index == 0 {
                return Err(Problem::Malformed(format!(
                    "{prefix} index 0 is invalid (OBJ indices start at 1)"
                )));
            }
            if index > 0 && index as u64 > total as u64 {
                return Err(Problem::Malformed(format!(
                    "{prefix} index {index} is out of range (the file has {total} {plural})"
                )));
            }
            if index < 0 && index.unsigned_abs() > before as u64 {
                return Err(Problem::Malformed(format!(
                    "relative {prefix} index {index} is out of range \
                     ({before} {plural} before this line)"
                )));
            }
        }
    }
    if words.len() < 3 {
        return Err(Problem::Malformed(format!(
            "a face needs at least 3 vertices, found {}",
            words.len()
        )));
    }
    Ok(())
}

/// The first face that refers to a texture coordinate (`v/vt`) when the file has no `vt`
/// statement, or to a normal (`v//vn`) when it has no `vn`: `tobj` skips those silently.
pub(super) fn dangling_reference(text: &str, file: &str) -> Option<SceneError> {
    let mut totals = Counts::default();
    // The first line referring to each kind, with the reference.
    let mut first_vt: Option<(usize, String)> = None;
    let mut first_vn: Option<(usize, String)> = None;
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let keyword = words.next();
        totals.count(keyword);
        if keyword != Some("f") || (first_vt.is_some() && first_vn.is_some()) {
            continue;
        }
        for word in words {
            let mut parts = word.split('/').skip(1);
            let (vt, vn) = (parts.next().unwrap_or(""), parts.next().unwrap_or(""));
            if !vt.is_empty() && first_vt.is_none() {
                first_vt = Some((i + 1, vt.to_owned()));
            }
            if !vn.is_empty() && first_vn.is_none() {
                first_vn = Some((i + 1, vn.to_owned()));
            }
        }
    }
    // Report the earlier line when both kinds dangle.
    let vt = first_vt.filter(|_| totals.vt == 0).map(|(l, i)| (l, i, "texture coordinate"));
    let vn = first_vn.filter(|_| totals.vn == 0).map(|(l, i)| (l, i, "normal"));
    let (line, index, what) = [vt, vn].into_iter().flatten().min_by_key(|(l, _, _)| *l)?;
    Some(SceneError::Malformed {
        file: file.to_owned(),
        line,
        problem: format!("{what} index {index} is out of range (the file has no {what}s)"),
    })
}
