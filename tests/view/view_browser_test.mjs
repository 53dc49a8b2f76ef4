// The live view's page in headless Chromium (docs/view.md): refused without the token; the first
// image appears; dragging orbits the camera (the image and the camera shown change);
// click-to-focus sets the focus distance to the depth under the cursor (within 1 % of the depth
// the camera's ray meets the Cornell box's back wall at); the depth view is shown; "copy camera"
// pasted into `obscura render` gives the viewed frame bit for bit. Screenshots are written to the
// work folder. With OBSCURA_VIEW_BENCH=1 it also times camera moves at 640 × 360 (BENCHMARKS.md).
//   node view_browser_test.mjs OBSCURA_CLI CHROMIUM WORK_DIR
import { spawn, spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { readFileSync, writeFileSync } from 'node:fs';
import { inflateSync } from 'node:zlib';
import path from 'node:path';

const [cli, chromium, work] = process.argv.slice(2);
const require = createRequire(path.join(work, 'node_modules', 'index.js'));
const puppeteer = require('puppeteer-core');
const bench = process.env.OBSCURA_VIEW_BENCH === '1';
const [width, height] = [320, 180];
// The measured Cornell box's back wall: the plane z = 559.2 mm, 556 × 548.8 mm.
const wallZ = 0.5592;

let passed = 0, failed = 0;
async function check(name, fn) {
  try {
    await fn();
    console.log('PASS', name);
    passed++;
  } catch (e) {
    console.log('FAIL', name, e && e.stack ? e.stack : e);
    failed++;
  }
}
function assert(condition, message) {
  if (!condition) throw new Error(message);
}

// --- PNG decoding (8-bit, non-interlaced), to compare frames pixel for pixel ---------------------
function decodePng(data) {
  let pos = 8, idat = [], w = 0, h = 0, channels = 0;
  while (pos < data.length) {
    const length = data.readUInt32BE(pos), type = data.toString('latin1', pos + 4, pos + 8);
    const chunk = data.subarray(pos + 8, pos + 8 + length);
    pos += 12 + length;
    if (type === 'IHDR') {
      w = chunk.readUInt32BE(0); h = chunk.readUInt32BE(4);
      assert(chunk[8] === 8 && chunk[12] === 0, 'only 8-bit non-interlaced PNGs');
      channels = { 0: 1, 2: 3, 4: 2, 6: 4 }[chunk[9]];
    } else if (type === 'IDAT') idat.push(chunk);
    else if (type === 'IEND') break;
  }
  const raw = inflateSync(Buffer.concat(idat)), stride = w * channels;
  const out = Buffer.alloc(h * stride);
  for (let y = 0; y < h; y++) {
    const kind = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let i = 0; i < stride; i++) {
      const left = i >= channels ? out[y * stride + i - channels] : 0;
      const up = y > 0 ? out[(y - 1) * stride + i] : 0;
      const corner = y > 0 && i >= channels ? out[(y - 1) * stride + i - channels] : 0;
      let v = line[i];
      if (kind === 1) v += left;
      else if (kind === 2) v += up;
      else if (kind === 3) v += (left + up) >> 1;
      else if (kind === 4) {
        const p = left + up - corner, pa = Math.abs(p - left), pb = Math.abs(p - up), pc = Math.abs(p - corner);
        v += pa <= pb && pa <= pc ? left : pb <= pc ? up : corner;
      }
      out[y * stride + i] = v & 255;
    }
  }
  return { width: w, height: h, channels, pixels: out };
}

// --- the server ---------------------------------------------------------------------------------
function startView(args) {
  return new Promise((resolve, reject) => {
    const child = spawn(cli, ['view', ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '', err = '';
    child.stderr.on('data', (d) => { err += d; });
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/^(http:\/\/127\.0\.0\.1:(\d+)\/\?token=([0-9a-f]{32}))\n/);
      if (m) resolve({ child, url: m[1], port: +m[2], token: m[3], stderr: () => err });
    });
    child.on('exit', (code) => reject(new Error('obscura view ended (' + code + '): ' + err)));
  });
}

const scene = ['cornell-box', '--width', String(width), '--height', String(height), '--spp', '8'];
const server = await startView(scene);
const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--window-size=1200,760'],
  defaultViewport: { width: 1200, height: 760 },
});
const page = await browser.newPage();
const pageErrors = [];
page.on('pageerror', (e) => pageErrors.push(String(e)));

const state = () => page.evaluate(() => window.obscuraView.state);
// Waits until the page shows the final image of the current camera (or, with final false, any
// image of it) and returns the state it shows.
async function waitShown(final = true, minGeneration = 0) {
  await page.waitForFunction((final, minGeneration) => {
    const v = window.obscuraView, s = v && v.state;
    return s && s.frame && s.frame.generation === s.current_generation &&
      s.frame.generation >= minGeneration && v.shownEvent >= s.frame.event && (!final || s.frame.final);
  }, { timeout: 300000, polling: 50 }, final, minGeneration);
  return state();
}
async function frameBox() {
  return page.evaluate(() => {
    const r = document.getElementById('frame').getBoundingClientRect();
    return { x: r.left, y: r.top, width: r.width, height: r.height };
  });
}
const servedPng = () => page.evaluate(async () => {
  const token = document.body.dataset.token;
  const res = await fetch('/api/frame?view=beauty&token=' + token);
  const bytes = new Uint8Array(await res.arrayBuffer());
  let text = '';
  for (const b of bytes) text += String.fromCharCode(b);
  return btoa(text);
}).then((b64) => Buffer.from(b64, 'base64'));

await check('the page is refused without its token', async () => {
  const response = await page.goto(server.url.replace(/\?token=.*/, ''));
  assert(response.status() === 403, 'status ' + response.status());
  const wrong = await page.goto(server.url.replace(/token=.*/, 'token=' + '0'.repeat(32)));
  assert(wrong.status() === 403, 'status ' + wrong.status());
});

let first;
await check('the first image appears', async () => {
  const response = await page.goto(server.url);
  assert(response.status() === 200, 'status ' + response.status());
  first = await waitShown();
  const size = await page.evaluate(() => [document.getElementById('frame').naturalWidth,
    document.getElementById('frame').naturalHeight]);
  assert(size[0] === width && size[1] === height, 'image size ' + size);
  const status = await page.$eval('#status', (e) => e.textContent);
  assert(/path · pass \d+ · 8\/8 spp · \d+ ms · done/.test(status), 'status line: ' + status);
  await page.screenshot({ path: path.join(work, 'view_first.png') });
});

await check('dragging orbits the camera', async () => {
  const before = await page.$eval('#camera-text', (e) => e.textContent);
  const imageBefore = await servedPng();
  const box = await frameBox();
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 1; i <= 6; i++) await page.mouse.move(x + 5 * i, y + i);
  await page.mouse.up();
  const after = await waitShown(true, first.frame.generation + 1);
  const text = await page.$eval('#camera-text', (e) => e.textContent);
  assert(text !== before, 'the camera shown did not change: ' + text);
  const moved = after.frame.camera.position;
  assert(Math.hypot(moved[0] - first.frame.camera.position[0], moved[2] - first.frame.camera.position[2]) > 0.01,
    'the camera did not move: ' + moved);
  const imageAfter = await servedPng();
  assert(!decodePng(imageAfter).pixels.equals(decodePng(imageBefore).pixels), 'the image did not change');
  await page.screenshot({ path: path.join(work, 'view_orbited.png') });
});

await check('click-to-focus sets the focus to the depth under the cursor', async () => {
  const shown = await state();
  const cam = shown.frame.camera, fov = cam.resolved.fov_degrees;
  const box = await frameBox();
  // A point on the back wall above the blocks: a quarter down from the top, in the middle.
  const clickX = box.x + box.width * 0.5, clickY = box.y + box.height * 0.25;
  await page.mouse.click(clickX, clickY);
  await page.waitForFunction(() => window.obscuraView.lastFocusPoint &&
    window.obscuraView.camera.focus_distance_m > 0, { timeout: 60000 });
  const focused = await page.evaluate(() => window.obscuraView.camera.focus_distance_m);
  const point = await page.evaluate(() => window.obscuraView.lastFocusPoint);
  // Ground truth: the ray through that pixel's centre meets the plane of the back wall.
  const px = Math.floor(point.x) + 0.5, py = Math.floor(point.y) + 0.5;
  const sub = (a, b) => a.map((v, i) => v - b[i]);
  const unit = (a) => { const n = Math.hypot(...a); return a.map((v) => v / n); };
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const forward = unit(sub(cam.target, cam.position));
  const right = unit(cross(forward, cam.up)), up = cross(right, forward);
  const sx = (2 * px / width - 1) * Math.tan(fov[0] * Math.PI / 360);
  const sy = (1 - 2 * py / height) * Math.tan(fov[1] * Math.PI / 360);
  const dir = [0, 1, 2].map((i) => forward[i] + right[i] * sx + up[i] * sy);  // 1 along the axis
  const depth = (wallZ - cam.position[2]) / dir[2];
  const hit = [0, 1, 2].map((i) => cam.position[i] + dir[i] * depth);
  assert(hit[0] > 0.02 && hit[0] < 0.53 && hit[1] > 0.35 && hit[1] < 0.53,
    'the click is not on the open part of the back wall: ' + hit);
  const error = Math.abs(focused - depth) / depth;
  console.log(`  focus ${focused.toFixed(5)} m, ground truth ${depth.toFixed(5)} m (${(100 * error).toFixed(3)} %)`);
  assert(error < 0.01, 'focus ' + focused + ' m, ground truth ' + depth + ' m');
  // The focus and the f-number the page sends with it (depth of field was off) are rendered.
  await new Promise((resolve) => setTimeout(resolve, 300));
  const after = await waitShown(true, await page.evaluate(() => window.obscuraView.lastSent));
  assert(after.frame.camera.resolved.depth_of_field, 'depth of field is not on');
  assert(Math.abs(after.frame.camera.resolved.focus_distance_m - focused) < 1e-12, 'the render is not focused there');
});

await check('the depth view shows the depth AOV', async () => {
  await page.click('input[name=view][value=depth]');
  await page.waitForFunction(() => window.obscuraView.shownEvent >= window.obscuraView.state.frame.event &&
    window.obscuraView.shownMode === 'depth', { timeout: 60000 });
  await page.screenshot({ path: path.join(work, 'view_depth.png') });
  await page.click('input[name=view][value=beauty]');
  await waitShown();
});

await check('the wipe shows the rasterizer beside the path tracer', async () => {
  await page.click('#wipe');
  await page.waitForFunction(() => { const w = document.getElementById('wipe-image');
    return !w.hidden && w.naturalWidth > 0 && w.style.clipPath.startsWith('inset'); }, { timeout: 60000 });
  await page.screenshot({ path: path.join(work, 'view_wipe.png') });
  await page.click('#wipe');
});

await check('"copy camera" pasted into obscura render gives the viewed frame bit for bit', async () => {
  await waitShown();
  await page.click('#copy-cli');
  const command = await page.$eval('#copy-text', (e) => e.value);
  assert(command.startsWith('obscura render '), command);
  const args = command.slice('obscura render '.length).match(/'[^']*'|\S+/g).map((a) => a.replace(/^'|'$/g, ''));
  const output = path.join(work, 'copied.png');
  const result = spawnSync(cli, ['render', ...args, '-q', '-o', output], { encoding: 'utf8' });
  assert(result.status === 0, 'render failed: ' + result.stderr);
  const viewed = decodePng(await servedPng()), rendered = decodePng(readFileSync(output));
  assert(viewed.width === rendered.width && viewed.height === rendered.height, 'sizes differ');
  assert(viewed.pixels.equals(rendered.pixels), 'the frames differ: ' + command);
  console.log('  ' + command);
  await page.click('#copy-json');
  const json = JSON.parse(await page.$eval('#copy-text', (e) => e.value));
  assert(json.type === 'perspective' && json.position.length === 3, 'scene JSON: ' + JSON.stringify(json));
});

await check('a screenshot of the page', async () => {
  await page.screenshot({ path: path.join(work, 'view_page.png') });
  console.log('  ' + path.join(work, 'view_page.png'));
});

if (bench) {
  // Camera moves a while apart: the time from sending each to the rasterizer's image and to the
  // path tracer's first pass on the page; then images shown per second during a steady orbit.
  // The Cornell box, and each scene file OBSCURA_VIEW_BENCH_SCENES names (':'-separated).
  const scenes = [['cornell-box'], ...(process.env.OBSCURA_VIEW_BENCH_SCENES || '').split(':')
    .filter((s) => s).map((s) => [s])];
  for (const benchScene of scenes) {
    await check('interaction latency: ' + benchScene[0], async () => {
      const benchServer = await startView([...benchScene, '--width', '640', '--height', '360', '--spp', '8']);
      const benchPage = await browser.newPage();
      try {
        await benchPage.goto(benchServer.url);
        await benchPage.waitForFunction(() => window.obscuraView && window.obscuraView.state &&
          window.obscuraView.state.frame && window.obscuraView.state.frame.final &&
          window.obscuraView.shownEvent >= window.obscuraView.state.frame.event, { timeout: 300000 });
        const r = await benchPage.evaluate(() => {
          const b = document.getElementById('frame').getBoundingClientRect();
          return { x: b.left + b.width / 2, y: b.top + b.height / 2 };
        });
        for (let i = 0; i < 12; i++) {
          const before = await benchPage.evaluate(() => window.obscuraView.lastSent || 0);
          await benchPage.mouse.move(r.x, r.y);
          await benchPage.mouse.down();
          await benchPage.mouse.move(r.x + 8, r.y);
          await benchPage.mouse.up();
          // Until the path tracer's first pass of this move is on the page.
          await benchPage.waitForFunction((before) => {
            const v = window.obscuraView, g = v.lastSent || 0;
            return g > before && v.timings.some((e) => e.generation === g && e.renderer === 'path');
          }, { timeout: 120000, polling: 10 }, before);
          await new Promise((resolve) => setTimeout(resolve, 300));
        }
        const timings = await benchPage.evaluate(() => window.obscuraView.timings);
        const firstOf = (renderer) => {
          const byGen = new Map();
          for (const t of timings) if (t.renderer === renderer && !byGen.has(t.generation)) byGen.set(t.generation, t.ms);
          const v = [...byGen.values()].sort((a, b) => a - b);
          return { median: Math.round(v[v.length >> 1]), min: Math.round(v[0]), max: Math.round(v[v.length - 1]), n: v.length };
        };
        const raster = firstOf('raster'), path1 = firstOf('path');
        const shownBefore = await benchPage.evaluate(() => window.obscuraView.timings.length);
        const start = Date.now();
        await benchPage.mouse.move(r.x, r.y);
        await benchPage.mouse.down();
        for (let i = 0; i < 120; i++) {
          await benchPage.mouse.move(r.x + 200 * Math.sin(i / 20), r.y);
          await new Promise((resolve) => setTimeout(resolve, 16));
        }
        await benchPage.mouse.up();
        const seconds = (Date.now() - start) / 1000;
        const shown = (await benchPage.evaluate(() => window.obscuraView.timings.length)) - shownBefore;
        const report = { scene: benchScene[0], width: 640, height: 360, raster_ms: raster,
          path_first_pass_ms: path1, orbit_images_per_s: +(shown / seconds).toFixed(1),
          loadavg: readFileSync('/proc/loadavg', 'utf8').trim() };
        console.log('  BENCH ' + JSON.stringify(report));
        writeFileSync(path.join(work, 'view_bench_' + path.basename(benchScene[0]) + '.json'),
          JSON.stringify(report, null, 2));
      } finally {
        await benchPage.close();
        benchServer.child.kill('SIGTERM');
      }
    });
  }
}

await check('no script errors on the page', async () => {
  assert(pageErrors.length === 0, pageErrors.join('\n'));
});

await browser.close();
server.child.kill('SIGTERM');
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
