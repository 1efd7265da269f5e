// The wedge viewer: WebGL2, no library. The data is in the page (see crates/view/src/page.rs):
// base64 little-endian arrays in script elements of type application/octet-stream, and one
// JSON element. Views follow wedge's camera convention (render::camera): right = up x forward,
// so looking through the run's camera shows the rendered image as it is, not mirrored.
'use strict';
(function () {
  const meta = JSON.parse(document.getElementById('meta').textContent);

  // base64 to bytes by table: atob + charCodeAt per byte is slower on the tens of megabytes
  // a million-triangle mesh takes.
  const TABLE = new Uint8Array(128);
  const ALPHABET = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
  for (let k = 0; k < 64; k++) TABLE[ALPHABET.charCodeAt(k)] = k;
  function bytes(id) {
    const el = document.getElementById(id);
    if (!el) return null;
    const s = el.textContent.trim();
    let n = s.length;
    while (n > 0 && s.charCodeAt(n - 1) === 61) n--; // '='
    const out = new Uint8Array(Math.floor(n * 3 / 4));
    let o = 0;
    let k = 0;
    for (; k + 4 <= n; k += 4) {
      const v = (TABLE[s.charCodeAt(k)] << 18) | (TABLE[s.charCodeAt(k + 1)] << 12) |
        (TABLE[s.charCodeAt(k + 2)] << 6) | TABLE[s.charCodeAt(k + 3)];
      out[o++] = v >> 16; out[o++] = (v >> 8) & 255; out[o++] = v & 255;
    }
    if (n - k >= 2) {
      const v = (TABLE[s.charCodeAt(k)] << 18) | (TABLE[s.charCodeAt(k + 1)] << 12) |
        (n - k === 3 ? TABLE[s.charCodeAt(k + 2)] << 6 : 0);
      out[o++] = v >> 16;
      if (n - k === 3) out[o++] = (v >> 8) & 255;
    }
    return out;
  }
  const f32 = (id) => { const b = bytes(id); return new Float32Array(b.buffer, 0, b.length / 4); };
  const u32 = (id) => { const b = bytes(id); return new Uint32Array(b.buffer, 0, b.length / 4); };

  // Small vector helpers on [x, y, z] arrays.
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const mul = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) =>
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const len = (a) => Math.sqrt(dot(a, a));
  const norm = (a) => mul(a, 1 / (len(a) || 1));
  // Rotates v about the unit axis k by angle a (Rodrigues).
  function rotate(v, k, a) {
    const c = Math.cos(a);
    const s = Math.sin(a);
    return add(add(mul(v, c), mul(cross(k, v), s)), mul(k, dot(k, v) * (1 - c)));
  }

  const canvas = document.getElementById('view');
  const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
  if (!gl) {
    document.getElementById('title').textContent = 'this browser has no WebGL2';
    return;
  }

  function program(vs, fs) {
    const p = gl.createProgram();
    for (const [type, src] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
      const s = gl.createShader(type);
      gl.shaderSource(s, '#version 300 es\nprecision highp float;\n' + src);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
      gl.attachShader(p, s);
    }
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    const u = {};
    const count = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
    for (let k = 0; k < count; k++) {
      const name = gl.getActiveUniform(p, k).name;
      u[name] = gl.getUniformLocation(p, name);
    }
    return { p, u };
  }
  const meshProg = program(
    `layout(location=0) in vec3 pos; layout(location=1) in vec3 nrm;
     uniform mat4 mvp; out vec3 vPos; out vec3 vNrm;
     void main() { vPos = pos; vNrm = nrm; gl_Position = mvp * vec4(pos, 1.0); }`,
    `in vec3 vPos; in vec3 vNrm; uniform vec3 eye; uniform int flatShade; out vec4 colour;
     void main() {
       vec3 n = vNrm;
       if (flatShade == 1 || dot(n, n) < 1e-20) n = cross(dFdx(vPos), dFdy(vPos));
       n = normalize(n);
       float c = 0.25 + 0.75 * abs(dot(n, normalize(eye - vPos)));
       colour = vec4(vec3(0.86, 0.85, 0.8) * c, 1.0);
     }`);
  const lineProg = program(
    `layout(location=0) in vec3 pos; uniform mat4 mvp; uniform float pointSize;
     void main() { gl_Position = mvp * vec4(pos, 1.0); gl_PointSize = pointSize; }`,
    `uniform vec4 tint; out vec4 colour; void main() { colour = tint; }`);
  const colourProg = program(
    `layout(location=0) in vec3 pos; layout(location=1) in vec3 col; uniform mat4 mvp;
     out vec3 vCol; void main() { vCol = col; gl_Position = mvp * vec4(pos, 1.0); }`,
    `in vec3 vCol; out vec4 colour; void main() { colour = vec4(vCol, 1.0); }`);
  const texProg = program(
    `layout(location=0) in vec3 pos; layout(location=1) in vec2 uv; uniform mat4 mvp;
     out vec2 vUv; void main() { vUv = uv; gl_Position = mvp * vec4(pos, 1.0); }`,
    `in vec2 vUv; uniform sampler2D img; out vec4 colour;
     void main() { colour = vec4(texture(img, vUv).rgb, 1.0); }`);

  function vao(attribs, indices) {
    const v = gl.createVertexArray();
    gl.bindVertexArray(v);
    attribs.forEach(([data, size], loc) => {
      const b = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, size, gl.FLOAT, false, 0, 0);
    });
    if (indices) {
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    }
    gl.bindVertexArray(null);
    return v;
  }

  // The mesh, with area-weighted vertex normals for smooth shading (flat shading takes the
  // triangle's normal from screen-space derivatives, so it needs no second copy of the mesh).
  const positions = f32('positions');
  const indices = u32('indices');
  const normals = new Float32Array(positions.length);
  for (let t = 0; t < indices.length; t += 3) {
    const a = 3 * indices[t], b = 3 * indices[t + 1], c = 3 * indices[t + 2];
    const e1x = positions[b] - positions[a], e1y = positions[b + 1] - positions[a + 1];
    const e1z = positions[b + 2] - positions[a + 2];
    const e2x = positions[c] - positions[a], e2y = positions[c + 1] - positions[a + 1];
    const e2z = positions[c + 2] - positions[a + 2];
    const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
    for (const v of [a, b, c]) { normals[v] += nx; normals[v + 1] += ny; normals[v + 2] += nz; }
  }
  const meshVao = vao([[positions, 3], [normals, 3]], indices);
  let wireVao = null;
  let wireCount = 0;
  function wire() {
    if (!wireVao) {
      const e = new Uint32Array(indices.length * 2);
      for (let t = 0; t < indices.length; t += 3) {
        const a = indices[t], b = indices[t + 1], c = indices[t + 2];
        e.set([a, b, b, c, c, a], 2 * t);
      }
      wireVao = vao([[positions, 3]], e);
      wireCount = e.length;
    }
    return wireVao;
  }

  // What the scene spans: the mesh's bounding sphere grown to hold the eye and the rays.
  let lo = [Infinity, Infinity, Infinity];
  let hi = [-Infinity, -Infinity, -Infinity];
  const grow = (p) => {
    lo = [Math.min(lo[0], p[0]), Math.min(lo[1], p[1]), Math.min(lo[2], p[2])];
    hi = [Math.max(hi[0], p[0]), Math.max(hi[1], p[1]), Math.max(hi[2], p[2])];
  };
  grow(sub(meta.centre, [meta.radius, meta.radius, meta.radius]));
  grow(add(meta.centre, [meta.radius, meta.radius, meta.radius]));
  const cam = meta.camera;
  if (cam) grow(cam.eye);

  const layers = meta.layers.map((l, k) => {
    const data = f32('layer' + k);
    for (let s = 0; s < data.length; s += 3) grow([data[s], data[s + 1], data[s + 2]]);
    return { ...l, vao: vao([[data, 3]]), vertices: data.length / 3, on: l.shown };
  });
  const sceneCentre = mul(add(lo, hi), 0.5);
  const sceneRadius = Math.max(len(sub(hi, lo)) / 2, 1e-30);

  const axesVao = vao([
    [new Float32Array([0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1].map(
      (x) => x * sceneRadius * 0.5)), 3],
    [new Float32Array([1, .2, .2, 1, .2, .2, .2, 1, .2, .2, 1, .2, .3, .5, 1, .3, .5, 1]), 3],
  ]);

  // The run's camera: its eye, frustum and the rendered image on a plane in front of it.
  let camVao = null;
  let frustumVao = null;
  let texture = null;
  if (cam) {
    const aspect = cam.width / cam.height;
    const tan = Math.tan(cam.fovDeg * Math.PI / 360);
    const d = 0.35 * len(sub(cam.lookAt, cam.eye));
    const corner = (sx, sy) => add(cam.eye, mul(add(cam.forward,
      add(mul(cam.right, sx * tan * aspect), mul(cam.up, sy * tan))), d));
    const tl = corner(-1, 1), tr = corner(1, 1), bl = corner(-1, -1), br = corner(1, -1);
    const e = cam.eye;
    frustumVao = vao([[new Float32Array([
      ...e, ...tl, ...e, ...tr, ...e, ...bl, ...e, ...br,
      ...tl, ...tr, ...tr, ...br, ...br, ...bl, ...bl, ...tl]), 3]]);
    // Pixel (0, 0) is the image's top left: texture v = 0 at the top (no flip on upload).
    camVao = vao([[new Float32Array([...tl, ...tr, ...br, ...tl, ...br, ...bl]), 3],
      [new Float32Array([0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1]), 2]]);
    const png = bytes('image');
    createImageBitmap(new Blob([png], { type: 'image/png' })).then((bitmap) => {
      texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, bitmap);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      redraw();
    });
  }

  // The view: eye, target, and the axis orbits turn about (the run camera's up, else +y).
  const orbitUp = cam ? cam.up : [0, 1, 0];
  const fovDeg = cam ? cam.fovDeg : 45;
  let view = null;
  function homeView() {
    const back = cam ? mul(cam.forward, -1) : [0, 0, 1];
    let dir = rotate(back, orbitUp, cam ? 1.0 : 0.5);
    dir = rotate(dir, norm(cross(orbitUp, mul(dir, -1))), cam ? -0.35 : -0.3);
    const dist = 1.15 * sceneRadius / Math.sin(fovDeg * Math.PI / 360);
    return { target: sceneCentre, eye: add(sceneCentre, mul(dir, dist)), fov: fovDeg };
  }
  function cameraView() {
    return { target: cam.lookAt, eye: cam.eye, fov: cam.fovDeg };
  }
  // The camera frame of render::camera: right = normalize(up x fwd), up' = fwd x right.
  function frame(v) {
    const fwd = norm(sub(v.target, v.eye));
    let right = cross(orbitUp, fwd);
    if (len(right) < 1e-12) right = cross([1, 0, 0], fwd);
    right = norm(right);
    return { fwd, right, up: cross(fwd, right) };
  }
  function matrix(v) {
    const { fwd, right, up } = frame(v);
    const aspect = canvas.width / canvas.height;
    const dist = len(sub(v.target, v.eye));
    const far = dist + 3 * sceneRadius;
    const near = Math.max(far * 1e-4, dist - 3 * sceneRadius, 1e-30);
    const f = 1 / Math.tan(v.fov * Math.PI / 360);
    // Eye space x = right, y = up', z = -forward; then the usual GL perspective.
    const rows = [right, up, mul(fwd, -1)];
    const t = rows.map((r) => -dot(r, v.eye));
    const P = [f / aspect, f, (far + near) / (near - far)];
    const pz = 2 * far * near / (near - far);
    // Column-major mvp.
    const m = new Float32Array(16);
    for (let c = 0; c < 3; c++) {
      m[4 * c] = P[0] * rows[0][c];
      m[4 * c + 1] = P[1] * rows[1][c];
      m[4 * c + 2] = P[2] * rows[2][c];
      m[4 * c + 3] = -rows[2][c];
    }
    m[12] = P[0] * t[0];
    m[13] = P[1] * t[1];
    m[14] = P[2] * t[2] + pz;
    m[15] = -t[2];
    return m;
  }

  const $ = (id) => document.getElementById(id);
  const ui = {
    flat: () => document.querySelector('input[name=shading]:checked').value === 'flat',
    wire: $('wire'), axes: $('axes'), cam: $('cam'),
  };
  if (!cam) { ui.cam.checked = false; ui.cam.disabled = true; $('camview').disabled = true; }

  let pending = false;
  function redraw() {
    if (!pending) { pending = true; requestAnimationFrame(draw); }
  }
  function draw() {
    pending = false;
    const w = Math.max(1, Math.round(canvas.clientWidth * devicePixelRatio));
    const h = Math.max(1, Math.round(canvas.clientHeight * devicePixelRatio));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    gl.viewport(0, 0, w, h);
    gl.clearColor(0.118, 0.133, 0.157, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    const mvp = matrix(view);
    gl.useProgram(meshProg.p);
    gl.uniformMatrix4fv(meshProg.u.mvp, false, mvp);
    gl.uniform3fv(meshProg.u.eye, view.eye);
    gl.uniform1i(meshProg.u.flatShade, ui.flat() ? 1 : 0);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.bindVertexArray(meshVao);
    gl.drawElements(gl.TRIANGLES, indices.length, gl.UNSIGNED_INT, 0);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.useProgram(lineProg.p);
    gl.uniformMatrix4fv(lineProg.u.mvp, false, mvp);
    gl.uniform1f(lineProg.u.pointSize, 7);
    if (ui.wire.checked) {
      gl.uniform4f(lineProg.u.tint, 0.15, 0.2, 0.3, 1);
      gl.bindVertexArray(wire());
      gl.drawElements(gl.LINES, wireCount, gl.UNSIGNED_INT, 0);
    }
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    // Faint layers first, so that they never tint the solid ones.
    for (const l of [...layers.filter((l) => l.faint), ...layers.filter((l) => !l.faint)]) {
      if (!l.on || l.vertices === 0) continue;
      gl.uniform4f(lineProg.u.tint, ...l.colour, l.faint ? 0.25 : 1);
      gl.bindVertexArray(l.vao);
      gl.drawArrays(gl.LINES, 0, l.vertices);
    }
    gl.disable(gl.BLEND);
    if (cam && ui.cam.checked) {
      gl.uniform4f(lineProg.u.tint, 1, 0.9, 0.3, 1);
      gl.bindVertexArray(frustumVao);
      gl.drawArrays(gl.LINES, 0, 16);
      gl.drawArrays(gl.POINTS, 0, 1);
      if (texture) {
        gl.useProgram(texProg.p);
        gl.uniformMatrix4fv(texProg.u.mvp, false, mvp);
        gl.bindTexture(gl.TEXTURE_2D, texture);
        gl.bindVertexArray(camVao);
        gl.drawArrays(gl.TRIANGLES, 0, 6);
      }
    }
    if (ui.axes.checked) {
      gl.useProgram(colourProg.p);
      gl.uniformMatrix4fv(colourProg.u.mvp, false, mvp);
      gl.bindVertexArray(axesVao);
      gl.drawArrays(gl.LINES, 0, 6);
    }
    gl.bindVertexArray(null);
    if (window.wedge.firstFrameMs === null) {
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4)); // waits for GL
      window.wedge.firstFrameMs = performance.now();
    }
    window.wedge.frames++;
  }

  // The panel: the run's figures and a toggle per ray layer.
  $('title').textContent = meta.name || 'wedge viewer';
  const rows = [['vertices', meta.vertices]];
  if (cam) {
    const f = (p) => p.map((x) => +x.toPrecision(6)).join(', ');
    rows.push(['eye', f(cam.eye)], ['look at', f(cam.lookAt)], ['up', f(cam.up)],
      ['fov', cam.fovDeg + '°'], ['image', cam.width + ' × ' + cam.height]);
  }
  for (const [k, v] of meta.figures) rows.push([k, v]);
  for (const [k, v] of rows) {
    const tr = $('figures').insertRow();
    tr.insertCell().textContent = k;
    tr.insertCell().textContent = String(v);
  }
  layers.forEach((l) => {
    const label = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = l.on;
    box.dataset.layer = l.name;
    box.addEventListener('change', () => { l.on = box.checked; redraw(); });
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = `rgb(${l.colour.map((c) => Math.round(c * 255)).join(',')})`;
    label.append(box, swatch, `${l.name} (${l.count})`);
    $('layers').append(label);
  });
  for (const el of document.querySelectorAll('#panel input')) el.addEventListener('change', redraw);
  $('reset').addEventListener('click', () => { view = homeView(); redraw(); });
  // From the camera's own eye its frustum and image plane would cover the view: hide them.
  $('camview').addEventListener('click', () => {
    view = cameraView(); ui.cam.checked = false; redraw();
  });

  // Mouse: drag to orbit about the target, shift-drag or right-drag to pan, wheel to zoom.
  let drag = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (e) => {
    drag = { x: e.clientX, y: e.clientY, pan: e.shiftKey || e.button === 2 };
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointerup', () => { drag = null; });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x;
    const dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    const { right, up } = frame(view);
    const offset = sub(view.eye, view.target);
    if (drag.pan) {
      const scale = 2 * len(offset) * Math.tan(view.fov * Math.PI / 360) / canvas.clientHeight;
      const move = add(mul(right, -dx * scale), mul(up, dy * scale));
      view = { ...view, eye: add(view.eye, move), target: add(view.target, move) };
    } else {
      let o = rotate(offset, orbitUp, dx * 0.01);
      const turned = rotate(o, norm(cross(orbitUp, mul(o, -1))), -dy * 0.01);
      // Stop short of the pole, where "up" and the view would line up.
      if (Math.abs(dot(norm(turned), orbitUp)) < 0.995) o = turned;
      view = { ...view, eye: add(view.target, o) };
    }
    redraw();
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const o = mul(sub(view.eye, view.target), Math.exp(e.deltaY * 0.001));
    view = { ...view, eye: add(view.target, o) };
    redraw();
  }, { passive: false });
  window.addEventListener('resize', redraw);

  // For tests and for scripts: the first frame's time and a way to read the view.
  window.wedge = { firstFrameMs: null, frames: 0, meta, redraw };
  view = location.hash === '#camera' && cam ? cameraView() : homeView();
  if (location.hash === '#camera' && cam) ui.cam.checked = false;
  redraw();
})();
