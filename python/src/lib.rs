//! The `wedge` Python module: numpy arrays in, numpy arrays out, over the workspace's ray
//! tracer. Glue only: the rays are traced by `render::cast` (as `raycast` traces them), the
//! images rendered by `render::trace` (as `raytrace` renders them), the back ends chosen
//! through `backends`. See python/README.md for the Python API.
//!
//! A `Scene` builds its BVH once, with the back end and precision it was given, and keeps
//! it behind the object-safe `Traced` so that one Python class serves every back end. The
//! GIL is released while a BVH is built and while rays are traced; the work runs on rayon's
//! global pool (one thread per core, or `RAYON_NUM_THREADS`).

use std::path::PathBuf;

use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use intersect::Intersector;
use numpy::{PyArray1, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PySlice, PyTuple};
use render::camera::{DEFAULT_FOV_DEG, Placement};
use render::cast::{self, Columns};
use render::frame::{Frame, FrameData, Mode};
use render::output::npy::NpyError;
use scene::Mesh;

/// A BVH built with one back end, whichever it is: what a [`Scene`] traces with.
trait Traced: Send + Sync {
    /// The back end's name.
    fn name(&self) -> &'static str;
    /// [`cast::trace_rays`] with this BVH.
    fn cast(&self, mesh: &Mesh, rays: &[f64], stride: usize, columns: Columns, out: &mut [f64]);
    /// [`render::trace::render_frame`] with this BVH.
    fn render(&self, mesh: &Mesh, camera: &render::camera::Camera, frame: &mut Frame);
}

impl<I: Intersector> Traced for Accel<I> {
    fn name(&self) -> &'static str {
        I::NAME
    }

    fn cast(&self, mesh: &Mesh, rays: &[f64], stride: usize, columns: Columns, out: &mut [f64]) {
        cast::trace_rays(self, mesh, rays, stride, columns, out, &|_| {});
    }

    fn render(&self, mesh: &Mesh, camera: &render::camera::Camera, frame: &mut Frame) {
        render::trace::render_frame(self, mesh, camera, frame, &|_| {});
    }
}

/// Builds the BVH of a mesh with the back end [`dispatch`] picks.
struct Build<'a>(&'a Mesh);

impl Job for Build<'_> {
    type Output = Box<dyn Traced>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Box<dyn Traced> {
        Box::new(Accel::build(intersector, &self.0.triangles()))
    }
}

/// A triangle mesh with its BVH, built once with one back end and precision.
#[pyclass(module = "wedge", frozen)]
struct Scene {
    mesh: Mesh,
    traced: Box<dyn Traced>,
    precision: Precision,
}

#[pymethods]
impl Scene {
    /// `Scene(vertices, faces, backend="la", precision="f32")`: `vertices` an (V, 3) array of
    /// numbers, `faces` an (F, 3) array of integers indexing them (triangle `k` is row `k`).
    #[new]
    #[pyo3(signature = (vertices, faces, backend = "la", precision = "f32"))]
    fn new(
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        backend: &str,
        precision: &str,
    ) -> PyResult<Self> {
        let mesh = mesh_of_arrays(py, vertices, faces)?;
        Self::build(py, mesh, backend, precision)
    }

    /// `Scene.from_file(path, backend="la", precision="f32")`: a mesh file in any format
    /// `raytrace` reads (.obj, .ply, .stl, .gltf, .glb, .obj.gz, .ply.gz).
    #[staticmethod]
    #[pyo3(signature = (path, backend = "la", precision = "f32"))]
    fn from_file(py: Python<'_>, path: PathBuf, backend: &str, precision: &str) -> PyResult<Self> {
        let mesh = py.detach(|| Mesh::load(&path)).map_err(scene_error)?;
        Self::build(py, mesh, backend, precision)
    }

    /// The back end's name.
    #[getter]
    fn backend(&self) -> &'static str {
        self.traced.name()
    }

    /// `"f32"` or `"f64"`.
    #[getter]
    fn precision(&self) -> &'static str {
        self.precision.name()
    }

    /// The vertex positions, an (V, 3) float64 array (a copy).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let flat = self.mesh.positions.iter().flatten().copied().collect();
        let n = self.mesh.positions.len();
        PyArray1::<f64>::from_vec(py, flat).reshape([n, 3]).map(Bound::into_any)
    }

    /// The triangles as vertex indices, an (F, 3) int64 array in triangle order (a copy; a
    /// file's n-gons fanned as `raycast` numbers them).
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let flat = self.mesh.triangles.iter().flatten().map(|&i| i64::from(i)).collect();
        let n = self.mesh.triangles.len();
        PyArray1::<i64>::from_vec(py, flat).reshape([n, 3]).map(Bound::into_any)
    }

    /// Number of triangles.
    fn __len__(&self) -> usize {
        self.mesh.len()
    }

    fn __repr__(&self) -> String {
        let (name, p) = (self.traced.name(), self.precision.name());
        format!("wedge.Scene({} triangles, backend={name:?}, precision={p:?})", self.mesh.len())
    }

    /// `cast_rays(rays, point=False, normal=False)`: the closest hit of each ray, as a dict
    /// of arrays: `t`, `prim` (int64, -1 on a miss), `u`, `v`, and on request `point` and
    /// `normal` (N, 3); exactly what `raycast` writes.
    #[pyo3(signature = (rays, point = false, normal = false))]
    fn cast_rays<'py>(
        &self,
        py: Python<'py>,
        rays: &Bound<'py, PyAny>,
        point: bool,
        normal: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        let columns = Columns { any_hit: false, point, normal, prim: false };
        let hits = self.trace(py, rays, columns)?;
        let out = PyDict::new(py);
        let int64 = numpy::dtype::<i64>(py);
        out.set_item("t", column(&hits, 0)?)?;
        out.set_item("prim", column(&hits, 1)?.call_method1("astype", (int64,))?)?;
        out.set_item("u", column(&hits, 2)?)?;
        out.set_item("v", column(&hits, 3)?)?;
        let mut next = 4;
        for (wanted, name) in [(point, "point"), (normal, "normal")] {
            if wanted {
                out.set_item(name, columns_of(&hits, next, next + 3)?)?;
                next += 3;
            }
        }
        Ok(out)
    }

    /// `occluded(rays, prim=False)`: whether each ray hits any triangle (bool array), as
    /// `raycast --any-hit`; with `prim=True`, also the index of a triangle found (int64, -1
    /// on a miss), as a tuple.
    #[pyo3(signature = (rays, prim = false))]
    fn occluded<'py>(
        &self,
        py: Python<'py>,
        rays: &Bound<'py, PyAny>,
        prim: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let columns = Columns { any_hit: true, point: false, normal: false, prim };
        let hits = self.trace(py, rays, columns)?;
        let hit = column(&hits, 0)?.call_method1("astype", (numpy::dtype::<bool>(py),))?;
        if !prim {
            return Ok(hit);
        }
        let found = column(&hits, 1)?.call_method1("astype", (numpy::dtype::<i64>(py),))?;
        Ok(PyTuple::new(py, [hit, found])?.into_any())
    }

    /// `render(width, height, mode="alpha", camera="auto", eye=None, look_at=None, up=None,
    /// fov=45.0)`: the image `raytrace` writes as .npy for the same options: (H, W) uint8
    /// (alpha), float32 (depth), uint32 (prim), or (H, W, 3) float32 (normal, shade).
    #[pyo3(signature = (
        width, height, mode = "alpha", camera = "auto", eye = None, look_at = None, up = None,
        fov = DEFAULT_FOV_DEG
    ))]
    #[allow(clippy::too_many_arguments)] // Python's keyword arguments, as raytrace's options.
    fn render<'py>(
        &self,
        py: Python<'py>,
        width: u32,
        height: u32,
        mode: &str,
        camera: &str,
        eye: Option<[f64; 3]>,
        look_at: Option<[f64; 3]>,
        up: Option<[f64; 3]>,
        fov: f64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let mode: Mode = mode.parse().map_err(PyValueError::new_err)?;
        let auto = match camera {
            "auto" => true,
            "origin" => false,
            other => {
                let e = format!("unknown camera '{other}' (expected auto or origin)");
                return Err(PyValueError::new_err(e));
            }
        };
        let placement = Placement { auto, eye, look_at, up, fov_deg: fov };
        let aspect = f64::from(width) / f64::from(height);
        let (camera, _, _) = placement
            .camera(self.mesh.bounding_sphere(), aspect)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        let mut frame =
            Frame::new(mode, width, height).map_err(|e| PyValueError::new_err(e.to_string()))?;
        py.detach(|| self.traced.render(&self.mesh, &camera, &mut frame));
        let shape = [height as usize, width as usize];
        let flat = match std::mem::replace(frame.data_mut(), FrameData::Alpha(Vec::new())) {
            FrameData::Alpha(v) => PyArray1::from_vec(py, v).into_any(),
            FrameData::Depth(v) => PyArray1::from_vec(py, v).into_any(),
            FrameData::Prim(v) => PyArray1::from_vec(py, v).into_any(),
            FrameData::Normal(v) | FrameData::Shade(v) => {
                let v = v.into_iter().flatten().collect();
                let a = PyArray1::<f32>::from_vec(py, v);
                return Ok(a.reshape([shape[0], shape[1], 3])?.into_any());
            }
        };
        flat.call_method1("reshape", (shape[0], shape[1]))
    }
}

impl Scene {
    /// The scene of `mesh` with its BVH (built without the GIL).
    fn build(py: Python<'_>, mesh: Mesh, backend: &str, precision: &str) -> PyResult<Self> {
        let backend = Backend::from_name(backend).ok_or_else(|| {
            let names: Vec<&str> = Backend::ALL.iter().map(|b| b.name()).collect();
            let e = format!("unknown back end '{backend}' (expected one of {})", names.join(", "));
            PyValueError::new_err(e)
        })?;
        let precision = Precision::from_name(precision).ok_or_else(|| {
            PyValueError::new_err(format!("unknown precision '{precision}' (expected f32 or f64)"))
        })?;
        if precision == Precision::F32
            && let Some((_, value)) = mesh.first_coordinate_beyond(f64::from(f32::MAX))
        {
            return Err(PyValueError::new_err(format!(
                "{}: vertex coordinate {value:e} is beyond f32's range (about 3.4e38): \
                 use precision=\"f64\"",
                mesh.name
            )));
        }
        let traced = py.detach(|| dispatch(backend, precision, Build(&mesh)));
        Ok(Self { mesh, traced, precision })
    }

    /// Traces `rays` with `columns`, without the GIL: the (N, columns.count()) float64 array
    /// of `raycast`'s rows.
    fn trace<'py>(
        &self,
        py: Python<'py>,
        rays: &Bound<'py, PyAny>,
        columns: Columns,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (rays, stride) = ray_values(rays)?;
        let values = match &rays {
            Rays::Borrowed(a) => a.as_slice()?,
            Rays::Owned(v) => v,
        };
        let width = columns.count();
        let n = values.len() / stride;
        let mut hits = vec![0.0; n * width];
        py.detach(|| self.traced.cast(&self.mesh, values, stride, columns, &mut hits));
        // Handed to numpy without a copy; the dict's columns are views into it.
        PyArray1::from_vec(py, hits).reshape([n, width]).map(Bound::into_any)
    }
}

/// `hits[:, k]`, a view.
fn column<'py>(hits: &Bound<'py, PyAny>, k: usize) -> PyResult<Bound<'py, PyAny>> {
    hits.get_item((PySlice::full(hits.py()), k))
}

/// `hits[:, from..to]`, a view.
fn columns_of<'py>(
    hits: &Bound<'py, PyAny>,
    from: usize,
    to: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let py = hits.py();
    let (from, to) = (isize::try_from(from)?, isize::try_from(to)?);
    hits.get_item((PySlice::full(py), PySlice::new(py, from, to, 1)))
}

/// The rays of `rays` as `raycast` reads them from a file, widened to `f64`, and the values
/// per ray (6 or 8); the same checks in the same order, with the same messages: a numpy
/// array of little-endian float32 or float64 (`TypeError` otherwise), not in Fortran order
/// (`ValueError`: an F-ordered array is what `np.save` writes with `fortran_order: True`,
/// which `raycast` rejects), of shape (N, 6) or (N, 8) (`ValueError`). Any other layout (a
/// strided view) is copied into C order, as `np.save` would write it.
///
/// A C-ordered float64 array is read in place, without a copy (so it must not be written to
/// by another thread while the rays are traced).
fn ray_values<'py>(rays: &Bound<'py, PyAny>) -> PyResult<(Rays<'py>, usize)> {
    let Ok(array) = rays.cast::<PyUntypedArray>() else {
        let e = "rays: expected a numpy array of float32 or float64";
        return Err(PyTypeError::new_err(e));
    };
    let descr: String = array.dtype().getattr("str")?.extract()?;
    if descr != "<f4" && descr != "<f8" {
        return Err(PyTypeError::new_err(NpyError::Dtype(descr).to_string()));
    }
    if !array.is_c_contiguous() && array.is_fortran_contiguous() {
        return Err(PyValueError::new_err(NpyError::FortranOrder.to_string()));
    }
    let shape = array.shape();
    if shape.len() != 2 || !(shape[1] == 6 || shape[1] == 8) {
        let found: String = array.getattr("shape")?.repr()?.extract()?;
        let expected = "(N, 6) or (N, 8)".to_string();
        return Err(PyValueError::new_err(NpyError::Shape { found, expected }.to_string()));
    }
    let values = if descr == "<f8" {
        let a = array.cast::<numpy::PyArray2<f64>>()?.try_readonly()?;
        if a.is_c_contiguous() {
            Rays::Borrowed(a)
        } else {
            Rays::Owned(a.as_array().iter().copied().collect())
        }
    } else {
        let a = array.cast::<numpy::PyArray2<f32>>()?.try_readonly()?;
        Rays::Owned(a.as_array().iter().map(|&x| f64::from(x)).collect())
    };
    Ok((values, shape[1]))
}

/// Ray values in C order: the caller's float64 array itself, or a widened or reordered copy.
enum Rays<'py> {
    /// A C-ordered float64 array, read in place.
    Borrowed(numpy::PyReadonlyArray2<'py, f64>),
    /// Anything else, converted.
    Owned(Vec<f64>),
}

/// The mesh of a (V, 3) vertex array and an (F, 3) array of vertex indices.
fn mesh_of_arrays<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
) -> PyResult<Mesh> {
    let np = py.import("numpy")?;
    let as_array = |a: &Bound<'py, PyAny>, what: &str| -> PyResult<Bound<'py, PyAny>> {
        let a = np.call_method1("asarray", (a,))?;
        let shape: Vec<usize> = a.getattr("shape")?.extract()?;
        if shape.len() != 2 || shape[1] != 3 {
            let found: String = a.getattr("shape")?.repr()?.extract()?;
            return Err(PyValueError::new_err(format!("{what}: shape {found}: expected (N, 3)")));
        }
        Ok(a)
    };
    let v = as_array(vertices, "vertices")?;
    let f = as_array(faces, "faces")?;
    let kind = |a: &Bound<'_, PyAny>| -> PyResult<String> {
        a.getattr("dtype")?.getattr("kind")?.extract()
    };
    if !matches!(kind(&v)?.as_str(), "f" | "i" | "u") {
        let dtype = v.getattr("dtype")?.str()?;
        return Err(PyTypeError::new_err(format!("vertices: dtype {dtype}: expected numbers")));
    }
    if !matches!(kind(&f)?.as_str(), "i" | "u") {
        let dtype = f.getattr("dtype")?.str()?;
        return Err(PyTypeError::new_err(format!("faces: dtype {dtype}: expected integers")));
    }
    let v = v.call_method1("astype", (numpy::dtype::<f64>(py),))?;
    let v = v.cast::<numpy::PyArray2<f64>>()?.readonly();
    let positions: Vec<[f64; 3]> =
        v.as_array().rows().into_iter().map(|r| [r[0], r[1], r[2]]).collect();
    if let Some((k, x)) = positions
        .iter()
        .enumerate()
        .find_map(|(k, p)| p.iter().find(|x| !x.is_finite()).map(|x| (k, x)))
    {
        return Err(PyValueError::new_err(format!("vertices: vertex {k} has coordinate {x}")));
    }
    let f = np.call_method1("asarray", (f, numpy::dtype::<i64>(py)))?;
    let f = f.cast::<numpy::PyArray2<i64>>()?.readonly();
    let count = positions.len();
    let mut triangles = Vec::with_capacity(f.as_array().nrows());
    for (k, row) in f.as_array().rows().into_iter().enumerate() {
        let mut t = [0u32; 3];
        for (c, &i) in t.iter_mut().zip(row) {
            *c = u32::try_from(i).ok().filter(|&i| (i as usize) < count).ok_or_else(|| {
                let e = format!("faces: face {k} has vertex index {i}: {count} vertices");
                PyValueError::new_err(e)
            })?;
        }
        triangles.push(t);
    }
    if triangles.is_empty() {
        return Err(PyValueError::new_err("faces: the mesh has no faces"));
    }
    if triangles.len() > bvh::MAX_SLOTS {
        let e = format!("faces: {} triangles, more than {}", triangles.len(), bvh::MAX_SLOTS);
        return Err(PyValueError::new_err(e));
    }
    Ok(Mesh { name: "<arrays>".into(), positions, triangles, normals: None })
}

/// A mesh file's error as the fitting Python exception, with `raytrace`'s message.
fn scene_error(e: scene::SceneError) -> PyErr {
    match &e {
        scene::SceneError::Input(scene::input::InputError::NotFound { .. }) => {
            PyFileNotFoundError::new_err(e.to_string())
        }
        scene::SceneError::Input(_) => PyOSError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// `backends()`: the registry, in `raytrace --help`'s order, one dict per back end: `name`,
/// `algebra`, `method`, `watertight`, `exact`, `variant` (or None) and `help`.
#[pyfunction(name = "backends")]
fn list_backends(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for b in Backend::ALL {
        let d = PyDict::new(py);
        d.set_item("name", b.name())?;
        d.set_item("algebra", b.algebra().name())?;
        d.set_item("method", b.method().name())?;
        d.set_item("watertight", b.guarantees().watertight)?;
        d.set_item("exact", b.guarantees().exact)?;
        d.set_item("variant", b.variant())?;
        d.set_item("help", b.help())?;
        list.append(d)?;
    }
    Ok(list)
}

/// The `wedge` module.
#[pymodule]
fn wedge(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Scene>()?;
    m.add_function(wrap_pyfunction!(list_backends, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
