// The live view's page: shows the frames `obscura view` streams and sends it the camera the user
// handles. Plain script, no libraries: the server serves only this file, the page and its styles.
'use strict';

const token = document.body.dataset.token;
const api = (path) => path + (path.includes('?') ? '&' : '?') + 'token=' + encodeURIComponent(token);

const frameImage = document.getElementById('frame');
const viewport = document.getElementById('viewport');
const statusLine = document.getElementById('status');
const messageBox = document.getElementById('message');
const $ = (id) => document.getElementById(id);

// What the page knows: the camera it asks for, the last state the server sent, the frame shown.
const view = {
  camera: null,        // {position, target, up, focal_length_mm, f_number, focus_distance_m, exposure_ev}
  resolved: null,      // what the server resolved it to (field of view, focus, …)
  state: null,         // the last event's JSON
  shownEvent: 0,       // the event of the image on screen
  shownMode: 'beauty', // and its view
  shownGeneration: 0,
  mode: 'beauty',
  moves: 0,            // camera changes sent
  sentAt: new Map(),   // generation → when the change that made it was sent (performance.now)
  timings: [],         // per image shown: {generation, renderer, pass, samples, ms since its change}
};
window.obscuraView = view;  // for tests and the curious

// --- vectors -------------------------------------------------------------------------------
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const unit = (a) => scale(a, 1 / norm(a));
// Rodrigues: `v` turned by `angle` about the unit axis `k`.
function rotate(v, k, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}
function frameAxes(cam) {
  const forward = unit(sub(cam.target, cam.position));
  const right = unit(cross(forward, cam.up));
  const up = cross(right, forward);
  return { forward, right, up };
}

// --- sending the camera: one request in flight, the newest camera waiting behind it -----------
let sending = false, pending = null;
function sendCamera(change) {
  pending = Object.assign(pending || {}, change);
  if (!sending) flush();
}
async function flush() {
  if (!pending) return;
  const body = JSON.stringify(pending);
  pending = null;
  sending = true;
  try {
    const sent = performance.now();
    const res = await fetch(api('/api/camera'), { method: 'POST', body,
      headers: { 'Content-Type': 'application/json' } });
    const answer = await res.json();
    if (!res.ok) showMessage(answer.error || res.statusText);
    else rememberSend(answer.generation, sent);
    view.moves++;
  } catch (e) {
    showMessage('the server does not answer: ' + e);
  } finally {
    sending = false;
    if (pending) flush();
  }
}
function rememberSend(generation, time) {
  view.sentAt.set(generation, time);
  view.lastSent = Math.max(view.lastSent || 0, generation);
  if (view.sentAt.size > 64) view.sentAt.delete(view.sentAt.keys().next().value);
}
function sendPose() {
  const c = view.camera;
  sendCamera({ position: c.position, target: c.target, up: c.up });
  showCamera();
}

// --- mouse: orbit, pan, dolly, roll; a click without a drag focuses ----------------------------
let drag = null;
viewport.addEventListener('contextmenu', (e) => e.preventDefault());
viewport.addEventListener('pointerdown', (e) => {
  if (!view.camera) return;
  viewport.setPointerCapture(e.pointerId);
  const mode = e.ctrlKey ? 'roll' : (e.shiftKey || e.button === 2 || e.button === 1) ? 'pan' : 'orbit';
  drag = { x: e.clientX, y: e.clientY, startX: e.clientX, startY: e.clientY, mode, moved: false };
  viewport.classList.add('dragging');
});
viewport.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (!drag.moved && Math.hypot(e.clientX - drag.startX, e.clientY - drag.startY) < 4) return;
  drag.moved = true;
  drag.x = e.clientX;
  drag.y = e.clientY;
  const c = view.camera, axes = frameAxes(c);
  if (drag.mode === 'orbit') {
    // Turning about the camera's own up and right keeps a rolled horizon rolled.
    let offset = sub(c.position, c.target), up = c.up;
    const yaw = -dx * 0.005, pitch = -dy * 0.005;
    offset = rotate(offset, axes.up, yaw);
    up = rotate(up, axes.up, yaw);
    const right = rotate(axes.right, axes.up, yaw);
    offset = rotate(offset, right, pitch);
    up = rotate(up, right, pitch);
    c.position = add(c.target, offset);
    c.up = unit(up);
  } else if (drag.mode === 'pan') {
    const distance = norm(sub(c.position, c.target));
    const fov = view.resolved ? view.resolved.fov_degrees[1] : 40;
    const perPixel = 2 * distance * Math.tan(fov * Math.PI / 360) / frameImage.getBoundingClientRect().height;
    const shift = add(scale(axes.right, -dx * perPixel), scale(axes.up, dy * perPixel));
    c.position = add(c.position, shift);
    c.target = add(c.target, shift);
  } else {
    c.up = unit(rotate(c.up, axes.forward, dx * 0.01));
  }
  sendPose();
});
function endDrag(e) {
  if (!drag) return;
  const wasClick = !drag.moved && drag.mode === 'orbit';
  drag = null;
  viewport.classList.remove('dragging');
  if (wasClick) focusAt(e);
}
viewport.addEventListener('pointerup', endDrag);
viewport.addEventListener('pointercancel', () => { drag = null; viewport.classList.remove('dragging'); });
viewport.addEventListener('wheel', (e) => {
  e.preventDefault();
  if (!view.camera) return;
  const c = view.camera;
  const factor = Math.exp(Math.max(-200, Math.min(200, e.deltaY)) * 0.002);
  c.position = add(c.target, scale(sub(c.position, c.target), factor));
  sendPose();
}, { passive: false });
document.addEventListener('keydown', (e) => {
  if (!view.camera || (e.key !== 'q' && e.key !== 'e')) return;
  const c = view.camera, axes = frameAxes(c);
  c.up = unit(rotate(c.up, axes.forward, e.key === 'q' ? -0.05 : 0.05));
  sendPose();
});

// The raster point under the cursor, in the frame's pixels.
function rasterPoint(e) {
  const rect = frameImage.getBoundingClientRect();
  return { x: (e.clientX - rect.left) * frameImage.naturalWidth / rect.width,
           y: (e.clientY - rect.top) * frameImage.naturalHeight / rect.height };
}
async function focusAt(e) {
  const point = rasterPoint(e);
  view.lastFocusPoint = point;
  const sent = performance.now();
  const res = await fetch(api('/api/focus'), { method: 'POST', body: JSON.stringify(point),
    headers: { 'Content-Type': 'application/json' } });
  const answer = await res.json();
  if (!res.ok) return showMessage(answer.error);
  rememberSend(answer.generation, sent);
  view.camera.focus_distance_m = answer.depth_m;
  $('focus-out').textContent = answer.depth_m.toPrecision(4) + ' m (clicked)';
  if (!$('dof').checked) {
    $('dof').checked = true;
    sendCamera({ f_number: fstopOf($('fstop').value) });
  }
}

// --- lens and exposure controls --------------------------------------------------------------
// Focal length on a logarithmic slider, 8 to 400 mm; f-numbers in third stops from f/1.
const focalOf = (v) => 8 * Math.pow(50, v / 1000);
const sliderOfFocal = (f) => Math.round(1000 * Math.log(f / 8) / Math.log(50));
const fstopOf = (v) => Math.round(Math.pow(2, v / 6) * 100) / 100;
const sliderOfFstop = (n) => Math.round(6 * Math.log2(n));
$('focal').addEventListener('input', () => {
  const f = Math.round(focalOf(+$('focal').value) * 10) / 10;
  $('focal-out').textContent = f + ' mm';
  sendCamera({ focal_length_mm: f });
});
$('fstop').addEventListener('input', () => {
  const n = fstopOf(+$('fstop').value);
  $('fstop-out').textContent = 'f/' + n;
  if ($('dof').checked) sendCamera({ f_number: n });
});
$('dof').addEventListener('change', () => {
  if ($('dof').checked) sendCamera({ f_number: fstopOf(+$('fstop').value) });
  else sendCamera({ f_number: null, focus_distance_m: null });
});
$('exposure').addEventListener('input', () => {
  const ev = +$('exposure').value;
  $('exposure-out').textContent = (ev > 0 ? '+' : '') + ev + ' EV';
  sendCamera({ exposure_ev: ev });
});
// Shutter in third stops from 1/4096 s to 1 s (slider −36…0), ISO in third stops from 50.
const shutterOf = (v) => Math.pow(2, v / 3);
const sliderOfShutter = (t) => Math.round(3 * Math.log2(t));
const isoOf = (v) => Math.round(100 * Math.pow(2, v / 3));
const sliderOfIso = (iso) => Math.round(3 * Math.log2(iso / 100));
const shutterText = (t) => t >= 1 ? t.toPrecision(3) + ' s' : '1/' + Math.round(1 / t) + ' s';
$('shutter').addEventListener('input', () => {
  const t = shutterOf(+$('shutter').value);
  $('shutter-out').textContent = shutterText(t);
  sendCamera({ shutter_s: t });
});
$('iso').addEventListener('input', () => {
  const iso = isoOf(+$('iso').value);
  $('iso-out').textContent = String(iso);
  sendCamera({ iso });
});
$('physical').addEventListener('change', () => sendCamera({ physical_exposure: $('physical').checked }));
// A lens system has its own focal length: the slider's is given back to it.
$('lens').addEventListener('change', () => sendCamera({ lens: $('lens').value || null,
  focal_length_mm: null }));
$('sensor').addEventListener('change', () => sendCamera({ sensor: $('sensor').value || null }));
$('aspect').addEventListener('change', () => {
  const aspect = +$('aspect').value, width = view.startSize[0];
  sendCamera({ size: $('aspect').value ? [width, Math.max(16, Math.round(width / aspect))] : null });
});
for (const radio of document.querySelectorAll('input[name=view]'))
  radio.addEventListener('change', () => { view.mode = radio.value; fetchFrame(); });

// --- copy camera -------------------------------------------------------------------------------
function copyText(text) {
  $('copy-text').value = text;
  $('copy-text').select();
  if (navigator.clipboard) navigator.clipboard.writeText(text).catch(() => {});
}
$('copy-cli').addEventListener('click', () => { if (view.state) copyText(view.state.frame.command); });
$('copy-json').addEventListener('click', () => { if (view.state) copyText(view.state.frame.scene_camera); });

$('export').addEventListener('change', async () => {
  const format = $('export').value;
  $('export').value = '';
  if (!format) return;
  const res = await fetch(api('/api/export?format=' + format));
  const answer = await res.json();
  if (!res.ok) return showMessage(answer.error);
  copyText(answer.text + (answer.omissions.length ? '\n# left out: ' + answer.omissions.join('; ') : ''));
});
$('save').addEventListener('click', async () => {
  const res = await fetch(api('/api/save'), { method: 'POST' });
  const answer = await res.json();
  $('save-out').textContent = res.ok ? 'saved to ' + answer.path + (answer.final ? '' : ' (not finished)')
    : answer.error;
});

// --- what the server sends --------------------------------------------------------------------
function showMessage(text) {
  messageBox.hidden = !text;
  messageBox.textContent = text || '';
}
const fmt = (v) => v.map((x) => x.toPrecision(4)).join(', ');
function showCamera() {
  const c = view.camera;
  $('camera-text').textContent = 'position ' + fmt(c.position) + '\nlooking at ' + fmt(c.target) +
    '\nup ' + fmt(c.up);
}
function showResolved(r) {
  $('focal-out').textContent = r.focal_length_mm.toPrecision(4) + ' mm';
  $('fov-out').textContent = r.fov_degrees[0].toFixed(1) + '° × ' + r.fov_degrees[1].toFixed(1) + '°';
  $('fstop-out').textContent = 'f/' + r.f_number.toPrecision(3);
  $('focus-out').textContent = r.depth_of_field ? r.focus_distance_m.toPrecision(4) + ' m' : '(pinhole: all sharp)';
  $('exposure-out').textContent = (r.exposure_ev > 0 ? '+' : '') + r.exposure_ev + ' EV';
  $('shutter-out').textContent = r.shutter_s > 0 ? shutterText(r.shutter_s) : 'instant';
  $('iso-out').textContent = String(r.iso);
}

// The wipe: the rasterizer's image of the same camera over the left part of the frame.
const wipeImage = document.getElementById('wipe-image');
function placeWipe() {
  wipeImage.style.clipPath = 'inset(0 ' + (100 - +$('wipe-pos').value) + '% 0 0)';
}
async function fetchWipe() {
  wipeImage.hidden = !$('wipe').checked || view.mode !== 'beauty';
  if (wipeImage.hidden) return;
  const res = await fetch(api('/api/frame?view=raster'));
  if (!res.ok) return;
  const url = URL.createObjectURL(await res.blob());
  await new Promise((resolve) => { wipeImage.onload = resolve; wipeImage.onerror = resolve; wipeImage.src = url; });
  if (wipeImage.dataset.url) URL.revokeObjectURL(wipeImage.dataset.url);
  wipeImage.dataset.url = url;
  placeWipe();
}
$('wipe').addEventListener('change', fetchWipe);
$('wipe-pos').addEventListener('input', placeWipe);

// The histogram of the image shown (its display codes, per channel) and a meter: the mean
// luma and the share of clipped pixels, to judge exposure by.
const scratch = document.createElement('canvas');
function drawHistogram() {
  const canvas = $('histogram');
  if (!canvas || !frameImage.naturalWidth) return;
  scratch.width = frameImage.naturalWidth;
  scratch.height = frameImage.naturalHeight;
  const context = scratch.getContext('2d', { willReadFrequently: true });
  context.drawImage(frameImage, 0, 0);
  const pixels = context.getImageData(0, 0, scratch.width, scratch.height).data;
  const bins = 64, counts = [new Array(bins).fill(0), new Array(bins).fill(0), new Array(bins).fill(0)];
  let luma = 0, clipped = 0;
  for (let i = 0; i < pixels.length; i += 4) {
    for (let c = 0; c < 3; c++) counts[c][pixels[i + c] >> 2]++;
    luma += 0.2126 * pixels[i] + 0.7152 * pixels[i + 1] + 0.0722 * pixels[i + 2];
    if (pixels[i] === 255 || pixels[i + 1] === 255 || pixels[i + 2] === 255) clipped++;
  }
  const n = pixels.length / 4, g = canvas.getContext('2d');
  g.clearRect(0, 0, canvas.width, canvas.height);
  const peak = Math.max(1, ...counts.flat().slice(1, -1));
  const colours = ['rgba(255,80,80,0.6)', 'rgba(80,255,80,0.6)', 'rgba(90,140,255,0.6)'];
  for (let c = 0; c < 3; c++) {
    g.fillStyle = colours[c];
    for (let b = 0; b < bins; b++) {
      const h = Math.min(1, counts[c][b] / peak) * canvas.height;
      g.fillRect(b * canvas.width / bins, canvas.height - h, canvas.width / bins, h);
    }
  }
  $('meter-out').textContent = 'mean ' + (100 * luma / n / 255).toFixed(1) + ' % · clipped ' +
    (100 * clipped / n).toFixed(2) + ' %';
}

let fetching = false;
async function fetchFrame() {
  const state = view.state;
  // The server sends its latest frame, which may be newer than the event that asked for it.
  if (fetching || !state || !state.frame) return;
  if (state.frame.event <= view.shownEvent && view.shownMode === view.mode) return;
  fetching = true;
  const frame = state.frame, mode = view.mode;
  try {
    const res = await fetch(api('/api/frame?view=' + mode + '&event=' + frame.event));
    if (res.ok) {
      const shown = +res.headers.get('X-Obscura-Event');
      const url = URL.createObjectURL(await res.blob());
      await new Promise((resolve) => { frameImage.onload = resolve; frameImage.onerror = resolve; frameImage.src = url; });
      if (frameImage.dataset.url) URL.revokeObjectURL(frameImage.dataset.url);
      frameImage.dataset.url = url;
      view.shownEvent = shown;
      view.shownMode = mode;
      if (view.mode === 'beauty') drawHistogram();
      fetchWipe();
      if (view.sentAt.has(frame.generation)) {
        view.timings.push({ generation: frame.generation, renderer: frame.renderer, pass: frame.pass,
          samples: frame.samples, ms: performance.now() - view.sentAt.get(frame.generation) });
        if (view.timings.length > 1000) view.timings.shift();
      }
      view.shownGeneration = frame.generation;
      document.body.dataset.event = String(shown);
      const samples = frame.renderer === 'raster' ? 'raster frame'
        : frame.samples + '/' + frame.samples_target + ' spp';
      statusLine.textContent = frame.renderer + ' · pass ' + frame.pass + ' · ' + samples + ' · ' +
        (frame.seconds * 1000).toFixed(0) + ' ms' + (frame.final ? ' · done' : '');
    }
  } finally {
    fetching = false;
    const latest = view.state && view.state.frame;
    if (latest && (latest.event > view.shownEvent || view.shownMode !== view.mode)) fetchFrame();
  }
}

function onState(state) {
  view.state = state;
  showMessage(state.message);
  const frame = state.frame;
  if (!frame) return;
  view.resolved = frame.camera.resolved;
  if (!view.camera) {  // the first frame: start from the server's camera
    const c = frame.camera;
    view.camera = { position: c.position, target: c.target, up: c.up };
    view.startSize = [view.resolved.width, view.resolved.height];
    $('focal').value = sliderOfFocal(view.resolved.focal_length_mm);
    $('fstop').value = sliderOfFstop(view.resolved.f_number);
    $('dof').checked = view.resolved.depth_of_field;
    $('exposure').value = view.resolved.exposure_ev;
    $('physical').checked = view.resolved.physical_exposure;
    if (view.resolved.shutter_s > 0) $('shutter').value = sliderOfShutter(view.resolved.shutter_s);
    $('iso').value = sliderOfIso(view.resolved.iso);
    showCamera();
  }
  if (frame.generation === state.current_generation) showResolved(view.resolved);
  fetchFrame();
}

const events = new EventSource(api('/api/events'));
events.addEventListener('state', (e) => onState(JSON.parse(e.data)));
events.onerror = () => statusLine.textContent = 'reconnecting to the server…';
