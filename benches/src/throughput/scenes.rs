//! The scenes the throughput benches trace: the Stanford bunny, the bunny split twice (1.1M
//! triangles, generated at run time, never committed) and every OBJ file in `obj/`.

use std::path::{Path, PathBuf};

use scene::Mesh;
use scene::generators::subdivide;

use crate::workspace_root;

/// A mesh and the short name the CSV rows use for it.
#[derive(Clone, Debug)]
pub struct BenchScene {
    /// `bunny`, `bunny-sub2` or an `obj/` file stem (`torus`, ...).
    pub name: String,
    /// The triangles.
    pub mesh: Mesh,
}

/// `shared/meshes/` beside the repository.
#[must_use]
pub fn shared_meshes_dir() -> PathBuf {
    workspace_root().join("..").join("shared").join("meshes")
}

/// Loads `shared/meshes/<file>`.
///
/// # Panics
///
/// If the file is missing or does not parse (the message names the file).
#[must_use]
pub fn shared_mesh(file: &str) -> Mesh {
    let path = shared_meshes_dir().join(file);
    Mesh::load(&path).unwrap_or_else(|e| {
        panic!("the benches need {}: {e} (shared/meshes beside the repository)", path.display())
    })
}

/// The Stanford bunny (69,451 triangles).
///
/// # Panics
///
/// If `shared/meshes/stanford-bunny.obj` is missing.
#[must_use]
pub fn bunny() -> Mesh {
    shared_mesh("stanford-bunny.obj")
}

/// `mesh` with every triangle split into four at its edge midpoints, `times` times
/// (`scene::generators::subdivide`): the bunny split twice has 1,111,216 triangles.
#[must_use]
pub fn subdivided(mesh: &Mesh, times: u32) -> Mesh {
    let (mut positions, mut triangles) = (mesh.positions.clone(), mesh.triangles.clone());
    for _ in 0..times {
        (positions, triangles) = subdivide(&positions, &triangles);
    }
    Mesh { name: format!("{} split {times} times", mesh.name), positions, triangles, normals: None }
}

/// Every `*.obj` in `dir`, sorted by name, named by file stem.
///
/// # Panics
///
/// If the folder cannot be read or a file does not parse.
#[must_use]
pub fn obj_scenes(dir: &Path) -> Vec<BenchScene> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("reading {}: {e}", dir.display()))
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "obj"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|path| {
            let name = path.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into());
            let mesh = Mesh::load(&path).unwrap_or_else(|e| panic!("{e}"));
            BenchScene { name, mesh }
        })
        .collect()
}

/// The bunny, the bunny split twice, then the `obj/` scenes.
///
/// # Panics
///
/// If a mesh is missing (see [`shared_mesh`]).
#[must_use]
pub fn all_scenes() -> Vec<BenchScene> {
    let bunny = bunny();
    let big = subdivided(&bunny, 2);
    let mut scenes = vec![
        BenchScene { name: "bunny".into(), mesh: bunny },
        BenchScene { name: "bunny-sub2".into(), mesh: big },
    ];
    scenes.extend(obj_scenes(&workspace_root().join("obj")));
    scenes
}
