//! The meshes of the suite: the Stanford bunny and the project's tile grid, welded, moved and
//! scaled, with their shared edges and closed vertex fans.

use std::collections::HashMap;
use std::path::PathBuf;

use intersect::Triangle;
use scene::Mesh;

use super::fp::{length, round32_3, sub};

/// A triangle mesh with one vertex per distinct position, so that triangles that meet share
/// vertex indices.
#[derive(Clone, Debug, PartialEq)]
pub struct TriMesh {
    /// A short name for tables (`bunny`, `tiles`).
    pub name: String,
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Triangles as indices into `positions`, counter-clockwise seen from the front.
    pub triangles: Vec<[u32; 3]>,
}

/// An edge used by exactly two triangles that run along it in opposite directions (the two
/// halves of a consistently oriented surface).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SharedEdge {
    /// The two end vertices.
    pub ends: [u32; 2],
    /// The two triangles.
    pub triangles: [u32; 2],
}

/// A vertex surrounded by one closed ring of consistently oriented triangles.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fan {
    /// The vertex.
    pub vertex: u32,
    /// The triangles around it, in ring order.
    pub triangles: Vec<u32>,
}

/// Where the shared meshes live: `shared/meshes` next to the repository
/// (`benches/../../shared/meshes`).
#[must_use]
pub fn shared_meshes_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes")
}

impl TriMesh {
    /// A mesh from positions and triangles; vertices with identical coordinates are merged
    /// (first occurrence kept), so that adjacency can be read from the indices.
    ///
    /// # Panics
    ///
    /// If a triangle indexes past `positions`.
    #[must_use]
    pub fn welded(name: &str, positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> Self {
        let mut first: HashMap<[u64; 3], u32> = HashMap::with_capacity(positions.len());
        let mut kept = Vec::with_capacity(positions.len());
        let remap: Vec<u32> = positions
            .iter()
            .map(|p| {
                // +0.0 and -0.0 are the same point.
                let key = p.map(|x| (x + 0.0).to_bits());
                *first.entry(key).or_insert_with(|| {
                    kept.push(*p);
                    u32::try_from(kept.len() - 1).expect("fewer than 2^32 vertices")
                })
            })
            .collect();
        let triangles = triangles.iter().map(|t| t.map(|v| remap[v as usize])).collect();
        Self { name: name.to_owned(), positions: kept, triangles }
    }

    /// A mesh loaded by [`scene::Mesh`], welded.
    #[must_use]
    pub fn from_mesh(name: &str, mesh: &Mesh) -> Self {
        Self::welded(name, &mesh.positions, &mesh.triangles)
    }

    /// The Stanford bunny from [`shared_meshes_dir`] (69,451 triangles).
    ///
    /// # Errors
    ///
    /// A one-line message naming the path when the file is absent or does not load.
    pub fn bunny() -> Result<Self, String> {
        let path = shared_meshes_dir().join("stanford-bunny.obj");
        let mesh = Mesh::load(&path).map_err(|e| {
            format!(
                "the accuracy suite needs the Stanford bunny: {e} (expected at {})",
                path.display()
            )
        })?;
        Ok(Self::from_mesh("bunny", &mesh))
    }

    /// The project's tile grid (`obj/tiles.obj`, built by [`scene::generators::tiles`]): 16 x 16
    /// squares of side 1/8 in the plane z = 0, split into 512 triangles, every vertex on an
    /// exact binary lattice.
    #[must_use]
    pub fn tiles() -> Self {
        let obj = scene::generators::tiles();
        Self::welded("tiles", &obj.positions, &obj.triangles())
    }

    /// Number of triangles.
    #[must_use]
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Whether there is no triangle.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Triangle `i` in `f64`.
    #[must_use]
    pub fn triangle(&self, i: u32) -> Triangle<f64> {
        let [a, b, c] = self.triangles[i as usize].map(|v| self.positions[v as usize]);
        Triangle::new(a, b, c)
    }

    /// Every triangle, in order.
    #[must_use]
    pub fn triangle_list(&self) -> Vec<Triangle<f64>> {
        (0..self.len() as u32).map(|i| self.triangle(i)).collect()
    }

    /// The corners of the box around the vertices.
    #[must_use]
    pub fn bounds(&self) -> ([f64; 3], [f64; 3]) {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in &self.positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        (lo, hi)
    }

    /// The longest side of the bounding box: the unit of the translation sweep.
    #[must_use]
    pub fn extent(&self) -> f64 {
        let (lo, hi) = self.bounds();
        (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max)
    }

    /// The same mesh scaled about the origin by `factor`, then moved by `offset`, every
    /// coordinate rounded to the nearest `f32`. Rounding to `f32` means that the `f32` and the
    /// `f64` back ends see exactly the same triangles, so one exact verdict judges both.
    #[must_use]
    pub fn transformed(&self, factor: f64, offset: [f64; 3]) -> Self {
        let positions = self
            .positions
            .iter()
            .map(|p| round32_3(core::array::from_fn(|k| p[k] * factor + offset[k])))
            .collect();
        Self { name: self.name.clone(), positions, triangles: self.triangles.clone() }
    }

    /// The mesh with every coordinate rounded to `f32` ([`TriMesh::transformed`] by nothing).
    #[must_use]
    pub fn rounded_to_f32(&self) -> Self {
        self.transformed(1.0, [0.0; 3])
    }

    /// Every shared edge (see [`SharedEdge`]), in order of first use. Edges with one triangle
    /// (borders), more than two, or two triangles wound the same way along them are left out.
    #[must_use]
    pub fn shared_edges(&self) -> Vec<SharedEdge> {
        // Directed edge -> triangles using it in that direction, and the undirected edges
        // (smaller index first) in order of first use.
        let mut directed: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        let mut candidates = Vec::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (p, q) = (tri[k], tri[(k + 1) % 3]);
                if p == q {
                    continue;
                }
                directed.entry((p, q)).or_default().push(t as u32);
                let reverse_seen = directed.contains_key(&(q, p));
                if directed[&(p, q)].len() == 1 && !reverse_seen {
                    candidates.push((p.min(q), p.max(q)));
                }
            }
        }
        let mut out = Vec::new();
        for (p, q) in candidates {
            let forward = directed.get(&(p, q)).map_or(&[][..], Vec::as_slice);
            let backward = directed.get(&(q, p)).map_or(&[][..], Vec::as_slice);
            if let ([s], [t]) = (forward, backward) {
                out.push(SharedEdge { ends: [p, q], triangles: [*s, *t] });
            }
        }
        out
    }

    /// Every vertex surrounded by a single closed ring of triangles, each edge at it shared by
    /// exactly two triangles wound in opposite directions along it.
    #[must_use]
    pub fn fans(&self) -> Vec<Fan> {
        let mut around: Vec<Vec<u32>> = vec![Vec::new(); self.positions.len()];
        for (t, tri) in self.triangles.iter().enumerate() {
            for &v in tri {
                around[v as usize].push(t as u32);
            }
        }
        let mut out = Vec::new();
        for (v, tris) in around.iter().enumerate() {
            if let Some(ring) = self.ring(v as u32, tris) {
                out.push(Fan { vertex: v as u32, triangles: ring });
            }
        }
        out
    }

    /// The triangles `tris` around `v` in ring order, if they form one closed ring.
    fn ring(&self, v: u32, tris: &[u32]) -> Option<Vec<u32>> {
        if tris.len() < 3 {
            return None;
        }
        // Triangle (v, x, y) in its own winding: the next one around is (v, y, z).
        let mut by_x: HashMap<u32, (u32, u32)> = HashMap::with_capacity(tris.len());
        for &t in tris {
            let tri = self.triangles[t as usize];
            let k = tri.iter().position(|&w| w == v)?;
            let (x, y) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
            if x == v || y == v || x == y || by_x.insert(x, (y, t)).is_some() {
                return None;
            }
        }
        let (&start, _) = by_x.iter().min_by_key(|(_, (_, t))| *t)?;
        let mut ring = Vec::with_capacity(tris.len());
        let mut x = start;
        loop {
            let (y, t) = *by_x.get(&x)?;
            ring.push(t);
            x = y;
            if x == start || ring.len() > tris.len() {
                break;
            }
        }
        (x == start && ring.len() == tris.len()).then_some(ring)
    }

    /// The mean length of the edges of triangle `t`.
    #[must_use]
    pub fn mean_edge_length(&self, t: u32) -> f64 {
        let [a, b, c] = self.triangle(t).vertices();
        (length(sub(b, a)) + length(sub(c, b)) + length(sub(a, c))) / 3.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiles_adjacency_counts() {
        let tiles = TriMesh::tiles();
        assert_eq!((tiles.positions.len(), tiles.len()), (289, 512));
        // Interior edges of a 16 x 16 grid split along diagonals: 15 * 16 horizontal,
        // 15 * 16 vertical, 256 diagonals.
        assert_eq!(tiles.shared_edges().len(), 2 * 15 * 16 + 256);
        // The 15 x 15 interior vertices have closed rings of 6 triangles.
        let fans = tiles.fans();
        assert_eq!(fans.len(), 225);
        assert!(fans.iter().all(|f| f.triangles.len() == 6));
    }

    #[test]
    fn welding_merges_equal_positions() {
        let positions =
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [-0.0, 1.0, 0.0]];
        let mesh = TriMesh::welded("t", &positions, &[[0, 1, 2], [3, 4, 1]]);
        assert_eq!(mesh.positions.len(), 3);
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [1, 2, 1]]);
    }

    #[test]
    fn open_fans_are_left_out() {
        // A square split in two: no interior vertex; one shared diagonal.
        let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let mesh = TriMesh::welded("sq", &positions, &[[0, 1, 2], [0, 2, 3]]);
        assert!(mesh.fans().is_empty());
        assert_eq!(mesh.shared_edges(), vec![SharedEdge { ends: [0, 2], triangles: [1, 0] }]);
    }

    #[test]
    fn transforms_round_to_f32() {
        let tiles = TriMesh::tiles().transformed(10.0, [1e3 / 3.0, 0.0, 0.0]);
        assert!(tiles.positions.iter().all(|&p| super::super::fp::is_f32_3(p)));
        assert_eq!(tiles.extent(), 20.0);
    }
}
