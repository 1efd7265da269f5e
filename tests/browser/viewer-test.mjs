// Opens raytrace's --view pages in headless Chromium (Debian's /usr/bin/chromium, driven by
// playwright-core) and validates its --scene files with the Khronos glTF validator.
//
//   node tests/browser/viewer-test.mjs [--screenshot docs/viewer-bunny.png]
//     [--compare-screenshot docs/viewer-compare.png] [--mesh FILE]...
//
// Run from the repository root after `cargo build --release -p raytrace`. Exits non-zero on
// any failure; screenshots of failing pages go to target/test-output/.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';
import validator from 'gltf-validator';

const root = process.cwd();
const raytrace = process.env.WEDGE_RAYTRACE || path.join(root, 'target/release/raytrace');
const out = path.join(root, 'target/test-output/browser');
fs.mkdirSync(out, { recursive: true });
const args = process.argv.slice(2);
const option = (name) => { const k = args.indexOf(name); return k >= 0 ? args[k + 1] : null; };
const extraMeshes = args.flatMap((a, k) => (args[k - 1] === '--mesh' ? [a] : []));
const screenshot = option('--screenshot');
const compareScreenshot = option('--compare-screenshot');
// raycast sits beside raytrace (the same cargo profile).
const raycast = path.join(path.dirname(raytrace), 'raycast');

// The IoU the page's camera view must reach against our own alpha render of the same camera.
// Both sample pixel centres with the same projection, so they differ only where a pixel
// centre lies within rounding of a silhouette edge (f32 rasterisation vs the tracer): measured
// 0.99+ on every scene here; 0.97 leaves room for a GPU's rounding, and a wrong projection,
// handedness (a mirrored view) or aspect ratio falls far below it (a mirrored bunny: ~0.6).
const MIN_IOU = 0.97;
const W = 320;
const H = 240;
const BACKGROUND = [30, 34, 40]; // the page's clear colour, 0.118, 0.133, 0.157
const HIT_RGB = [255, 140, 26]; // view::HIT_COLOUR

const bunny = path.join(root, '../shared/meshes/stanford-bunny.obj');
if (!fs.existsSync(bunny)) {
  console.error(`error: ${bunny} is missing (the shared meshes are needed for this test)`);
  process.exit(1);
}
const scenes = [
  { mesh: path.join(root, 'obj/icosphere.obj'), name: 'icosphere' },
  { mesh: path.join(root, 'obj/torus.obj'), name: 'torus' },
  { mesh: bunny, name: 'bunny' },
  ...extraMeshes.map((m) => ({ mesh: m, name: path.basename(m).replace(/\..*/, ''), big: true })),
];

let failures = 0;
function check(ok, what, scene) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${scene}: ${what}`);
  if (!ok) failures++;
  return ok;
}

function run(mesh, outFile, extra) {
  const stdout = execFileSync(raytrace, [mesh, outFile, String(W), String(H), '-q', ...extra]);
  return stdout.toString();
}

const browser = await chromium.launch({
  executablePath: process.env.WEDGE_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
    '--no-sandbox'],
});

// The canvas's pixels (RGBA, rows from the top), read after the next frame.
async function pixels(page) {
  const b64 = await page.evaluate(async () => {
    const c = document.getElementById('view');
    const n = window.wedge.frames;
    window.wedge.redraw();
    while (window.wedge.frames === n) await new Promise((r) => requestAnimationFrame(r));
    const o = new OffscreenCanvas(c.width, c.height);
    const x = o.getContext('2d');
    x.drawImage(c, 0, 0);
    const d = x.getImageData(0, 0, c.width, c.height).data;
    let s = '';
    for (let k = 0; k < d.length; k += 0x8000) {
      s += String.fromCharCode.apply(null, d.subarray(k, k + 0x8000));
    }
    return { w: c.width, h: c.height, data: btoa(s) };
  });
  return { w: b64.w, h: b64.h, data: Buffer.from(b64.data, 'base64') };
}
const near = (d, k, rgb, tol) => Math.abs(d[k] - rgb[0]) <= tol && Math.abs(d[k + 1] - rgb[1]) <= tol
  && Math.abs(d[k + 2] - rgb[2]) <= tol;
const covered = (img) => {
  const m = new Uint8Array(img.w * img.h);
  for (let p = 0; p < m.length; p++) m[p] = near(img.data, 4 * p, BACKGROUND, 3) ? 0 : 1;
  return m;
};
const differing = (a, b) => {
  let n = 0;
  for (let k = 0; k < a.data.length; k += 4) if (!near(a.data, k, [b.data[k], b.data[k + 1], b.data[k + 2]], 2)) n++;
  return n;
};
const count = (img, rgb, tol) => {
  let n = 0;
  for (let k = 0; k < img.data.length; k += 4) if (near(img.data, k, rgb, tol)) n++;
  return n;
};

// Our own alpha render as a mask, decoded by the browser's PNG decoder.
async function pngMask(page, file) {
  const b64 = fs.readFileSync(file).toString('base64');
  const bits = await page.evaluate(async (b64) => {
    const bin = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const bmp = await createImageBitmap(new Blob([bin], { type: 'image/png' }));
    const o = new OffscreenCanvas(bmp.width, bmp.height);
    const x = o.getContext('2d');
    x.drawImage(bmp, 0, 0);
    const d = x.getImageData(0, 0, bmp.width, bmp.height).data;
    const m = [];
    for (let k = 0; k < d.length; k += 4) m.push(d[k] > 127 ? 1 : 0);
    return m;
  }, b64);
  return Uint8Array.from(bits);
}

// A new page on `html` with its console errors collected, once the first frame is drawn.
async function open(html, viewport, hash = '') {
  const page = await browser.newPage({ viewport, deviceScaleFactor: 1 });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(pathToFileURL(html).href + hash);
  await page.waitForFunction(() => window.wedge && window.wedge.firstFrameMs !== null,
    null, { timeout: 120000 });
  return { page, errors };
}

const timings = [];
for (const scene of scenes) {
  const name = scene.name;
  const html = path.join(out, `${name}.html`);
  const glb = path.join(out, `${name}.glb`);
  const alpha = path.join(out, `${name}-alpha.png`);
  const stats = path.join(out, `${name}-stats.json`);
  const started = Date.now();
  run(scene.mesh, path.join(out, `${name}.png`),
    ['--mode', 'shade', '--view', html, '--scene', glb, '--stats', stats]);
  const writeMs = Date.now() - started;
  run(scene.mesh, alpha, ['--mode', 'alpha']);
  const figures = JSON.parse(fs.readFileSync(stats, 'utf8'));

  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(glb)));
  check(report.issues.numErrors === 0,
    `gltf-validator: ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`
    + (report.issues.numErrors ? ' ' + JSON.stringify(report.issues.messages.slice(0, 5)) : ''),
    name);

  const t0 = Date.now();
  const { page, errors } = await open(html, { width: W, height: H }, '#camera');
  const firstFrame = await page.evaluate(() => window.wedge.firstFrameMs);
  timings.push({ name, triangles: figures.triangles, pageBytes: fs.statSync(html).size,
    firstFrameMs: Math.round(firstFrame), openMs: Date.now() - t0, writeMs });
  let ok = true;
  const shot = async (what) => {
    await page.screenshot({ path: path.join(out, `FAILED-${name}-${what}.png`) });
  };

  // The run's camera: layers and axes off, the mask against our own render.
  for (const box of await page.$$('#layers input')) await box.uncheck();
  await page.uncheck('#axes');
  const camImg = await pixels(page);
  const mask = covered(camImg);
  const ref = await pngMask(page, alpha);
  let inter = 0, union = 0;
  for (let p = 0; p < mask.length; p++) { inter += mask[p] & ref[p]; union += mask[p] | ref[p]; }
  const iou = union ? inter / union : 0;
  const filled = mask.reduce((a, b) => a + b, 0);
  ok &= check(filled > 0, `canvas not blank (${filled} mesh pixels)`, name);
  ok &= check(camImg.w === W && camImg.h === H && iou >= MIN_IOU,
    `camera view matches the alpha render: IoU ${iou.toFixed(4)} >= ${MIN_IOU}`, name);
  if (!ok) await shot('camera');

  // The overview: rays, camera, a drag, the panel.
  await page.setViewportSize({ width: 900, height: 600 });
  for (const box of await page.$$('#layers input')) await box.check();
  await page.check('#axes');
  await page.check('#cam');
  await page.click('#reset');
  const home = await pixels(page);
  const orange = count(home, HIT_RGB, 12);
  const hitBox = page.locator('#layers input[data-layer="rays that hit"]');
  await hitBox.uncheck();
  const noRays = await pixels(page);
  await hitBox.check();
  await page.uncheck('#cam');
  const noCam = await pixels(page);
  await page.check('#cam');
  ok &= check(orange > 50 && differing(home, noRays) > 50,
    `rays drawn (${orange} ray-coloured pixels, ${differing(home, noRays)} change without them)`,
    name);
  ok &= check(differing(home, noCam) > 200,
    `camera drawn (${differing(home, noCam)} pixels change without it)`, name);
  const box = await page.locator('#view').boundingBox();
  await page.mouse.move(box.x + 600, box.y + 300);
  await page.mouse.down();
  await page.mouse.move(box.x + 700, box.y + 340, { steps: 5 });
  await page.mouse.up();
  const dragged = await pixels(page);
  ok &= check(differing(home, dragged) > 1000,
    `a drag changes the view (${differing(home, dragged)} pixels)`, name);
  const panel = await page.textContent('#panel');
  const want = [String(figures.triangles), figures.backend, 'trace_ms', 'eye', 'fov'];
  ok &= check(want.every((w) => panel.includes(w)),
    `the panel shows ${want.join(', ')}`, name);
  await page.click('#reset');
  if (screenshot && name === 'bunny') {
    await pixels(page);
    await page.screenshot({ path: screenshot });
    console.log(`wrote ${screenshot}`);
  }
  ok &= check(errors.length === 0, `no console or page errors ${JSON.stringify(errors)}`, name);
  if (!ok) await shot('overview');
  await page.close();
}

// `--compare`: the layers of the rays where back ends disagree. On the torus, `la-mt` (not
// watertight) misses rays at shared edges that `la` hits: the page opens on those rays alone.
{
  const name = 'torus-compare';
  const html = path.join(out, `${name}.html`);
  const stats = path.join(out, `${name}-stats.json`);
  const glb = path.join(out, `${name}.glb`);
  // At this size 8 of la-mt's rays pass through cracks (at 320 x 240, none does).
  execFileSync(raytrace, [path.join(root, 'obj/torus.obj'), path.join(out, `${name}.png`), '480',
    '360', '-q', '--compare', 'la,la-mt', '--view', html, '--scene', glb, '--stats', stats]);
  const figures = JSON.parse(fs.readFileSync(stats, 'utf8'));
  const { page, errors } = await open(html, { width: 900, height: 600 });
  let ok = true;
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(glb)));
  ok &= check(report.issues.numErrors === 0,
    `gltf-validator: ${report.issues.numErrors} errors with the disagreement layers`, name);
  const boxes = await page.$$eval('#layers input',
    (els) => els.map((e) => [e.dataset.layer, e.checked]));
  const on = Object.fromEntries(boxes);
  ok &= check(on['rays that hit'] === false && on['rays that missed'] === false
    && on['la hit'] === true && on['la-mt missed'] === true,
    `disagreement layers shown, the sample hidden: ${JSON.stringify(boxes)}`, name);
  const crackPixels = figures.compare.pairs[0].a_only;
  ok &= check(crackPixels > 0, `la hits ${crackPixels} pixels that la-mt misses`, name);
  const panel = await page.textContent('#panel');
  ok &= check(panel.includes(`la-mt missed (`), 'the panel lists la-mt\'s misses', name);
  const all = await pixels(page);
  const missBox = page.locator('#layers input[data-layer="la-mt missed"]');
  await missBox.uncheck();
  const withoutMisses = await pixels(page);
  await missBox.check();
  const laBox = page.locator('#layers input[data-layer="la hit"]');
  await laBox.uncheck();
  const withoutLa = await pixels(page);
  await laBox.check();
  ok &= check(differing(all, withoutMisses) > 20 && differing(all, withoutLa) > 20,
    `the layers are drawn (${differing(all, withoutMisses)} pixels change without la-mt's`
    + ` misses, ${differing(all, withoutLa)} without la's hits)`, name);
  if (compareScreenshot) {
    // la-mt's hits mostly lie on la's (the same point, another triangle at an edge).
    await page.locator('#layers input[data-layer="la-mt hit"]').uncheck();
    await page.uncheck('#cam');
    await page.check('#wire');
    const v = await page.locator('#view').boundingBox();
    await page.mouse.move(v.x + v.width / 2, v.y + v.height / 2);
    await page.mouse.wheel(0, -900);
    await pixels(page);
    await page.screenshot({ path: compareScreenshot });
    console.log(`wrote ${compareScreenshot}`);
  }
  ok &= check(errors.length === 0, `no console or page errors ${JSON.stringify(errors)}`, name);
  if (!ok) await page.screenshot({ path: path.join(out, `FAILED-${name}.png`) });
  await page.close();
}

// `raycast --view`: rays from anywhere, no camera. A fan of rays from one side of the
// icosphere (radius 1 about the origin), written as a float64 (N, 6) .npy.
{
  const name = 'raycast';
  const rays = path.join(out, 'raycast-rays.npy');
  const n = 400;
  const data = new Float64Array(n * 6);
  for (let k = 0; k < n; k++) {
    const a = (k / n) * 2 * Math.PI;
    data.set([3 * Math.cos(a), 3 * Math.sin(a), 0.3, -Math.cos(a), -Math.sin(a), 0], 6 * k);
  }
  let header = `{'descr': '<f8', 'fortran_order': False, 'shape': (${n}, 6), }`;
  header += ' '.repeat(63 - ((10 + header.length) % 64)) + '\n';
  const head = Buffer.alloc(10);
  head.write('\x93NUMPY', 0, 'latin1');
  head.writeUInt8(1, 6);
  head.writeUInt8(0, 7);
  head.writeUInt16LE(header.length, 8);
  fs.writeFileSync(rays, Buffer.concat([head, Buffer.from(header, 'latin1'),
    Buffer.from(data.buffer)]));
  const html = path.join(out, `${name}.html`);
  execFileSync(raycast, [path.join(root, 'obj/icosphere.obj'), rays,
    path.join(out, 'raycast-hits.npy'), '-q', '--view', html, '--view-rays', String(n)]);
  const { page, errors } = await open(html, { width: 900, height: 600 });
  let ok = true;
  const img = await pixels(page);
  const mesh = covered(img).reduce((a, b) => a + b, 0);
  const orange = count(img, HIT_RGB, 12);
  ok &= check(mesh > 1000 && orange > 50,
    `mesh and rays drawn (${mesh} non-background pixels, ${orange} ray-coloured)`, name);
  ok &= check(await page.isDisabled('#cam') && await page.isDisabled('#camview'),
    'no camera to show (its toggle and button disabled)', name);
  const panel = await page.textContent('#panel');
  ok &= check(panel.includes('rays that hit (400)'), 'every ray hits and is listed', name);
  ok &= check(errors.length === 0, `no console or page errors ${JSON.stringify(errors)}`, name);
  if (!ok) await page.screenshot({ path: path.join(out, `FAILED-${name}.png`) });
  await page.close();
}

await browser.close();
for (const t of timings) {
  console.log(`timing ${t.name}: ${t.triangles} triangles, page ${(t.pageBytes / 1e6).toFixed(2)} MB,`
    + ` first frame ${t.firstFrameMs} ms after navigation (${t.openMs} ms to ready),`
    + ` raytrace with --view/--scene ${t.writeMs} ms`);
}
if (failures) {
  console.error(`error: ${failures} browser check(s) failed; screenshots in ${out}`);
  process.exit(1);
}
console.log('all browser checks passed');
