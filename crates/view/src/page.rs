//! The viewer: one self-contained HTML file, working offline, drawn with the page's own small
//! WebGL2 code (`page/viewer.html` and `page/viewer.js` in this crate, embedded at build time).
//!
//! The page carries its data as `<script type="application/octet-stream">` elements holding
//! base64 of little-endian arrays (positions `f32 x 3`, triangle indices `u32 x 3`, each
//! layer's segments `f32 x 6`), decoded straight into `Float32Array`/`Uint32Array` for the GL
//! buffers, and one `application/json` element with the rest (figures, camera, layer names).
//! The image is a PNG, shown as the texture of the camera's image plane.
//!
//! The page draws in this crate's camera convention (see `render::camera`): a view from the
//! run's camera ("camera view") is the rendered image itself, not its mirror.

use std::io::{self, Write};

use base64::Engine as _;
use base64::engine::general_purpose::STANDARD;
use serde_json::json;

use crate::Run;

const HTML: &str = include_str!("../page/viewer.html");
const JS: &str = include_str!("../page/viewer.js");

/// The marker in `viewer.html` replaced by the data elements.
const DATA_MARKER: &str = "<!--DATA-->";
/// The marker in `viewer.html` replaced by `viewer.js`.
const SCRIPT_MARKER: &str = "/*VIEWER_JS*/";

/// Writes the page for `run` into `w`.
///
/// # Errors
///
/// If writing fails.
pub fn write(run: &Run<'_>, w: &mut impl Write) -> io::Result<()> {
    let (head, rest) = HTML.split_once(DATA_MARKER).expect("viewer.html has the data marker");
    let (middle, tail) = rest.split_once(SCRIPT_MARKER).expect("viewer.html has the script marker");
    w.write_all(head.as_bytes())?;
    write_data(run, w)?;
    w.write_all(middle.as_bytes())?;
    w.write_all(JS.as_bytes())?;
    w.write_all(tail.as_bytes())
}

/// The page as a string (for tests).
#[must_use]
pub fn to_string(run: &Run<'_>) -> String {
    let mut out = Vec::new();
    write(run, &mut out).expect("writing to a Vec cannot fail");
    String::from_utf8(out).expect("the page is UTF-8")
}

fn blob(w: &mut impl Write, id: &str, bytes: &[u8]) -> io::Result<()> {
    write!(w, "<script type=\"application/octet-stream\" id=\"{id}\">")?;
    w.write_all(STANDARD.encode(bytes).as_bytes())?;
    w.write_all(b"</script>\n")
}

fn write_data(run: &Run<'_>, w: &mut impl Write) -> io::Result<()> {
    let mesh = run.mesh;
    let positions: Vec<u8> =
        crate::positions_f32(mesh).iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
    blob(w, "positions", &positions)?;
    let indices: Vec<u8> = mesh.triangles.iter().flatten().flat_map(|i| i.to_le_bytes()).collect();
    blob(w, "indices", &indices)?;
    let mut layers = Vec::new();
    for (k, layer) in run.layers.iter().enumerate() {
        #[allow(clippy::cast_possible_truncation)]
        let bytes: Vec<u8> = layer
            .segments
            .iter()
            .flatten()
            .flatten()
            .flat_map(|&x| (x as f32).to_le_bytes())
            .collect();
        blob(w, &format!("layer{k}"), &bytes)?;
        layers.push(json!({
            "name": layer.name,
            "colour": layer.colour,
            "faint": layer.faint,
            "shown": layer.shown,
            "count": layer.segments.len(),
        }));
    }
    let camera = run.camera.as_ref().map(|c| {
        blob(w, "image", &c.png).map(|()| {
            let cam = &c.camera;
            json!({
                "eye": cam.eye(), "lookAt": c.look_at, "forward": cam.forward(),
                "right": cam.right(), "up": cam.up(), "fovDeg": cam.fov_deg(),
                "width": c.width, "height": c.height,
            })
        })
    });
    let camera = camera.transpose()?;
    let (centre, radius) = mesh.bounding_sphere();
    let meta = json!({
        "name": mesh.name,
        "vertices": mesh.positions.len(),
        "triangles": mesh.triangles.len(),
        "centre": centre,
        "radius": radius,
        "camera": camera,
        "layers": layers,
        "figures": run.figures,
    });
    // "</" would end the script element early (a mesh named "</script>"): "<\/" is the same
    // JSON string.
    let text = meta.to_string().replace("</", "<\\/");
    writeln!(w, "<script type=\"application/json\" id=\"meta\">{text}</script>")
}
