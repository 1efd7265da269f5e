//! `--view PAGE.html`, `--scene SCENE.glb` and `--view-rays N`, shared by both programs: the
//! paths' checks (before any work, with the other outputs) and the files' writing (into
//! temporary files created early, committed with the run's other outputs).

use std::path::{Path, PathBuf};

use anyhow::Context as _;
use render::output::{AtomicFile, Written};

use crate::{Named, Stats, UsageError};

/// The options, flattened into each program's command line.
#[derive(clap::Args, Debug, Clone)]
pub struct SeeArgs {
    /// Also write a self-contained HTML viewer of the run: the mesh, the camera and its image,
    /// a sample of the rays, the run's figures (works offline, in any current browser).
    #[arg(long, value_name = "PAGE.html")]
    pub view: Option<PathBuf>,
    /// Also write the run as a glTF 2.0 binary: the mesh, the camera, the ray sample as lines
    /// and its hit points as points.
    #[arg(long, value_name = "SCENE.glb")]
    pub scene: Option<PathBuf>,
    /// How many rays --view and --scene show (a regular sample of the run's rays).
    #[arg(long, value_name = "N", default_value_t = view::DEFAULT_SAMPLE)]
    pub view_rays: usize,
}

fn has_extension(path: &Path, exts: &[&str]) -> bool {
    let ext = path.extension().and_then(|e| e.to_str());
    ext.is_some_and(|e| exts.iter().any(|x| e.eq_ignore_ascii_case(x)))
}

impl SeeArgs {
    /// Whether a ray sample is needed at all.
    #[must_use]
    pub fn wanted(&self) -> bool {
        self.view.is_some() || self.scene.is_some()
    }

    /// Checks the extensions (a usage error) and adds the outputs to `outputs`.
    ///
    /// # Errors
    ///
    /// [`UsageError`] for a page not ending in `.html`/`.htm` or a scene not ending in `.glb`.
    pub fn outputs<'a>(&'a self, outputs: &mut Vec<Named<'a>>) -> anyhow::Result<()> {
        if let Some(path) = &self.view {
            if !has_extension(path, &["html", "htm"]) {
                let e = format!("{}: the viewer is an HTML page: use .html", path.display());
                return Err(UsageError(e).into());
            }
            outputs.push(Named { role: "viewer page", path });
        }
        if let Some(path) = &self.scene {
            if !has_extension(path, &["glb"]) {
                let e =
                    format!("{}: the scene is written as glTF binary: use .glb", path.display());
                return Err(UsageError(e).into());
            }
            outputs.push(Named { role: "scene", path });
        }
        Ok(())
    }

    /// Creates the files early (after [`crate::start_run`]'s checks), so that an unwritable
    /// directory fails before the work.
    ///
    /// # Errors
    ///
    /// If a file cannot be created.
    pub fn create(&self) -> anyhow::Result<SeeFiles> {
        Ok(SeeFiles {
            view: self.view.as_deref().map(AtomicFile::create).transpose()?,
            scene: self.scene.as_deref().map(AtomicFile::create).transpose()?,
        })
    }
}

/// The temporary files of `--view` and `--scene`.
#[derive(Debug)]
pub struct SeeFiles {
    view: Option<AtomicFile>,
    scene: Option<AtomicFile>,
}

impl SeeFiles {
    /// Writes the page and the scene for `run` (not yet committed).
    ///
    /// # Errors
    ///
    /// If writing fails.
    pub fn write(self, run: &view::Run<'_>) -> anyhow::Result<Vec<Written>> {
        let mut written = Vec::new();
        if let Some(file) = self.view {
            written.push(file.write(|w| view::page::write(run, w)).context("--view")?);
        }
        if let Some(file) = self.scene {
            written.push(file.write(|w| view::glb::write(run, w)).context("--scene")?);
        }
        Ok(written)
    }
}

/// The run's figures for the viewer's panel: the `--stats` values, then `extra`.
#[must_use]
pub fn figures(stats: &Stats, extra: &[(&str, String)]) -> Vec<(String, String)> {
    let mut out = Vec::new();
    if let Ok(serde_json::Value::Object(map)) = serde_json::to_value(stats) {
        for (k, v) in map {
            let text = match v {
                serde_json::Value::Number(n) if n.is_f64() => {
                    format!("{:.3}", n.as_f64().unwrap_or(f64::NAN))
                }
                serde_json::Value::String(s) => s,
                other => other.to_string(),
            };
            out.push((k, text));
        }
    }
    out.extend(extra.iter().map(|(k, v)| ((*k).to_owned(), v.clone())));
    out
}
