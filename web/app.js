// glint serve: the page. It shows the frames the server streams (server-sent events) and edits the
// scene DESCRIPTION: every control is a path into the scene tree (render.samples, camera.eye,
// materials.glass.ior, an object's inline material objects.3.material.albedo, a light's
// lights.0.intensity, list items by position) and a change posts {path, value} to /api/edit. The
// controls are built from the scene the server sends, so a parameter that a new material, light or
// camera reads shows up here by itself.
'use strict';

const $ = (id) => document.getElementById(id);

let state = null;          // the last answer of /api/scene (or /api/edit)
let initialCamera = null;  // for "Reset view"
let lastFrame = null;      // the last frame event's data, without the image
let pending = new Map();   // edits waiting for the request in flight, by path: the latest wins
let inFlight = false;
let focusMode = false;
let localView = null;      // eye and look_at as last sent, ahead of the server's answer during a drag

// ---- small helpers -------------------------------------------------------------------------------

const round = (x) => Math.round(x * 1e4) / 1e4;
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const length = (a) => Math.sqrt(dot(a, a));
const normalize = (a) => scale(a, 1 / (length(a) || 1));
// Rotates v about the unit axis k by angle (Rodrigues).
function rotate(v, k, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}

function el(tag, attrs = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of [].concat(children)) if (c) e.append(c);
  return e;
}

function valueAt(path) {
  let v = state.scene;
  for (const key of path) {
    if (v === null || typeof v !== 'object' || !(key in v)) return undefined;
    v = v[key];
  }
  return v;
}

// Linear radiance ↔ the sRGB colour a colour picker shows.
const toSrgb = (x) => { x = Math.min(1, Math.max(0, x)); return x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055; };
const toLinear = (x) => (x <= 0.04045 ? x / 12.92 : Math.pow((x + 0.055) / 1.055, 2.4));
function linearToHex(rgb) {
  return '#' + rgb.map((c) => Math.round(toSrgb(c) * 255).toString(16).padStart(2, '0')).join('');
}
function hexToLinear(hex) {
  return [1, 3, 5].map((i) => round(toLinear(parseInt(hex.slice(i, i + 2), 16) / 255)));
}

// ---- talking to the server -----------------------------------------------------------------------

function showError(message) {
  $('error').hidden = !message;
  $('error').textContent = message || '';
}

// Queues edits (each {path, value}; value null removes the key) and sends them: one request at a time,
// and while one is in flight later edits of the same path replace earlier ones, so a drag never
// builds a backlog.
function edit(...edits) {
  for (const e of edits) {
    pending.set(e.path.join('.'), e);
    if (e.path[0] === 'camera' && (e.path[1] === 'eye' || e.path[1] === 'look_at') && e.path.length === 2) {
      localView = {...view(), [e.path[1]]: e.value};
    }
  }
  flush();
}

// POSTs JSON. The server closes a keep-alive connection after 2 s idle (so idle clients cannot hold its
// connection slots); a request the browser sends on such a connection just as it closes fails as a
// network error, and browsers retry only idempotent requests by themselves. Both of our POSTs may be
// repeated (an edit sets values, a focus query reads), so a network failure is retried once, on a new
// connection.
async function postJson(url, value) {
  const send = () => fetch(url, {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify(value)});
  try {
    return await send();
  } catch (error) {
    return await send();
  }
}

async function flush() {
  if (inFlight || pending.size === 0) return;
  const edits = [...pending.values()];
  pending = new Map();
  inFlight = true;
  try {
    const response = await postJson('/api/edit', {edits});
    const body = await response.json();
    if (response.ok) {
      showError('');
      setState(body);
    } else {
      showError(body.error || `error ${response.status}`);
      updateControls();  // put the controls back to what the scene holds
    }
  } catch (error) {
    showError(`cannot reach glint serve: ${error}`);
  }
  inFlight = false;
  flush();
}

async function fetchState() {
  const response = await fetch('/api/scene');
  setState(await response.json());
}

// The structure of the scene as the controls show it: rebuilt only when this changes, so that typing
// in a field is not interrupted by the answer to the previous keystroke.
function layoutKey(s) {
  const shape = (v) => (Array.isArray(v) ? `[${v.length}]` : v !== null && typeof v === 'object'
    ? `{${Object.entries(v).map(([k, x]) => k + ':' + shape(x)).join(',')}}` : typeof v);
  return shape({render: s.scene.render, camera: s.scene.camera, materials: s.scene.materials,
    inline: (s.scene.objects || []).map((o) => o?.material), lights: s.scene.lights}) + s.scene.camera?.type;
}

function setState(next) {
  if (![...pending.keys()].some((k) => k.startsWith('camera.'))) localView = null;
  const rebuild = !state || layoutKey(state) !== layoutKey(next);
  state = next;
  if (!initialCamera) initialCamera = JSON.parse(JSON.stringify(state.scene.camera || {}));
  $('scene-name').textContent = state.name;
  if (rebuild) buildControls();
  else updateControls();
  if (state.render_error) showError(state.render_error);
  $('refine-continuously').checked = state.continuous;
  showRefineNote(state);
}

// The one rule for the note under "keep refining": shown only while refining is asked for and the
// scene's sample pattern cannot go past its target. Both the scene's state and /api/refine's answer
// carry {continuous, extendable}, so each goes through here rather than a rule of its own.
function showRefineNote({continuous, extendable}) {
  $('refine-note').hidden = extendable || !continuous;
}

// ---- frames ---------------------------------------------------------------------------------------

function connectEvents() {
  const events = new EventSource('/api/events');
  events.addEventListener('frame', (event) => {
    const frame = JSON.parse(event.data);
    $('image').src = frame.image;  // binary PNG from the server (GET /api/frames/ID.png)
    lastFrame = frame;
    showDisplay(frame);
    const stats = $('stats');
    stats.dataset.samples = frame.samples;
    stats.dataset.target = frame.target;
    stats.dataset.generation = frame.generation;
    stats.dataset.frame = frame.id;
    const done = frame.samples >= frame.target;
    stats.textContent = `${frame.width}×${frame.height}  ·  ` +
      (frame.samples === 0 ? 'preview' : `${frame.samples} / ${frame.target} spp`) +
      `  ·  ${frame.mrays_per_second.toFixed(1)} Mrays/s  ·  ${frame.seconds.toFixed(2)} s` + (done ? '  ·  done' : '') +
      // Non-finite samples are left out of the picture, as by glint render, and said, with the first.
      (frame.nonfinite ? `  ·  ${frame.nonfinite.samples} NaN/∞ samples left out (first at pixel ` +
        `${frame.nonfinite.x}, ${frame.nonfinite.y}, sample ${frame.nonfinite.sample})` : '');
    $('progress-bar').style.width = `${(100 * frame.samples) / Math.max(1, frame.target)}%`;
    if (state && frame.generation > state.generation) fetchState();  // another page changed the scene
  });
  events.onerror = () => { $('stats').textContent = 'reconnecting…'; };
}

// ---- controls -------------------------------------------------------------------------------------

// Sliders for the parameters whose sensible range is known; any other number gets a number box.
const ranges = {
  fov: [1, 150, 0.5], ior: [1, 3, 0.001], roughness: [0, 1, 0.01], albedo: [0, 1, 0.01],
  lens_radius: [0, 0.5, 0.005], f_stop: [0.7, 32, 0.1], max_depth: [1, 64, 1], exposure: [-5, 5, 0.1],
  metallic: [0, 1, 0.01], transmission: [0, 1, 0.01], fuzz: [0, 1, 0.01],
  // A spot light's cone (degrees; wider cones through the number box) and an environment map's turn.
  angle: [0.5, 90, 0.5], falloff_angle: [0, 90, 0.5], rotation: [-180, 180, 1],
};
const iorPresets = [['water', 1.333], ['glass', 1.5], ['diamond', 2.417]];
const colourKeys = /albedo|colou?r|reflectance|tint|specular|diffuse|emission|radiance|intensity|irradiance|background|transmittance/;
const resolutions = [[320, 180], [640, 360], [960, 540], [1280, 720], [1920, 1080]];

function field(label, inputs, title) {
  return el('div', {class: 'field', title: title || label}, [el('label', {text: label}), el('div', {class: 'inputs'}, inputs)]);
}

// `set(value)` sends the change; by default an edit of `path`.
const setter = (path) => (value) => edit({path, value});

function numberInput(path, value, opts = {}, set = setter(path)) {
  const input = el('input', {type: 'number', step: opts.step || 'any', 'data-path': JSON.stringify(path)});
  if (opts.min !== undefined) input.min = opts.min;
  input.value = value;
  input.addEventListener('change', () => {
    const v = Number(input.value);
    if (input.value !== '' && Number.isFinite(v)) set(v);
  });
  return input;
}

// A slider and a number box for one number, kept in step.
function sliderInput(path, value, [min, max, step], set = setter(path)) {
  const slider = el('input', {type: 'range', min, max, step, 'data-path': JSON.stringify(path)});
  const box = numberInput(path, value, {step}, set);
  slider.value = value;
  slider.addEventListener('input', () => { box.value = slider.value; set(Number(slider.value)); });
  box.addEventListener('input', () => { slider.value = box.value; });
  return [slider, box];
}

function vectorInputs(path, values) {
  return values.map((v, i) => {
    const input = el('input', {type: 'number', step: 'any', class: 'vec', 'data-path': JSON.stringify([...path, i])});
    input.value = v;
    input.addEventListener('change', () => {
      const current = valueAt(path).slice();
      current[i] = Number(input.value);
      if (current.every(Number.isFinite)) edit({path, value: current});
    });
    return input;
  });
}

function selectInput(path, value, options, onChange) {
  const select = el('select', {'data-path': JSON.stringify(path)});
  const names = options.includes(value) || value === undefined ? options : [value, ...options];
  for (const name of names) select.append(el('option', {value: name, text: name}));
  select.value = value;
  select.addEventListener('change', () => (onChange ? onChange(select.value) : edit({path, value: select.value})));
  return select;
}

// The control for any value of the scene, by its shape and key.
function valueControl(path, value) {
  const key = path[path.length - 1];
  if (typeof value === 'number') {
    const inputs = ranges[key] ? sliderInput(path, value, ranges[key]) : [numberInput(path, value)];
    if (key === 'ior') {
      for (const [name, ior] of iorPresets) {
        inputs.push(el('button', {class: 'small', text: name, title: `ior ${ior}`, onclick: () => edit({path, value: ior})}));
      }
    }
    return inputs;
  }
  if (Array.isArray(value) && value.length === 3 && value.every((x) => typeof x === 'number')) {
    if (colourKeys.test(key) && value.every((x) => x >= 0 && x <= 1)) {
      const picker = el('input', {type: 'color', 'data-path': JSON.stringify(path), 'data-kind': 'colour'});
      picker.value = linearToHex(value);
      picker.addEventListener('input', () => edit({path, value: hexToLinear(picker.value)}));
      return [picker, ...vectorInputs(path, value)];
    }
    return vectorInputs(path, value);
  }
  if (Array.isArray(value) && value.every((x) => typeof x === 'number')) return vectorInputs(path, value);
  if (typeof value === 'boolean') {
    const box = el('input', {type: 'checkbox', 'data-path': JSON.stringify(path)});
    box.checked = value;
    box.addEventListener('change', () => edit({path, value: box.checked}));
    return [box];
  }
  if (typeof value === 'string') {
    const input = el('input', {type: 'text', 'data-path': JSON.stringify(path)});
    input.value = value;
    input.addEventListener('change', () => edit({path, value: input.value}));
    return [input];
  }
  return [el('code', {text: JSON.stringify(value)})];  // nested objects: shown, edited in the file
}

// A line to add a parameter the scene does not set yet (e.g. roughness on a material).
function addKeyRow(prefix) {
  const key = el('input', {type: 'text', placeholder: 'parameter'});
  const value = el('input', {type: 'text', placeholder: 'value'});
  const parse = (text) => {
    const t = text.trim();
    if (t.startsWith('[')) return JSON.parse(t);
    const n = Number(t);
    return t !== '' && Number.isFinite(n) ? n : t;
  };
  const addButton = el('button', {class: 'small', text: 'add', onclick: () => {
    try {
      if (key.value.trim()) edit({path: [...prefix, key.value.trim()], value: parse(value.value)});
    } catch (error) {
      showError(`${key.value}: ${error.message}`);
    }
  }});
  return el('div', {class: 'add-key'}, [key, value, addButton]);
}

// A camera that has a lens, for when the user opens the aperture of a pinhole.
function lensCameraType() {
  const type = state.scene.camera?.type || 'pinhole';
  if (type !== 'pinhole') return null;
  return state.cameras.find((name) => /lens|thin|dof|realistic/i.test(name)) || null;
}

// Sets an aperture or focus key, first turning a pinhole into the lens camera (with a small aperture,
// so that choosing a focus shows some depth of field).
const kFirstLensRadius = 0.05;
function cameraEdit(key, value) {
  const edits = [{path: ['camera', key], value}];
  const lens = lensCameraType();
  if (lens) {
    edits.push({path: ['camera', 'type'], value: lens});
    if (key !== 'lens_radius') edits.push({path: ['camera', 'lens_radius'], value: kFirstLensRadius});
  }
  edit(...edits);
}

function buildRender() {
  const render = state.scene.render || {};
  const settings = state.settings;
  const box = $('render-fields');
  box.replaceChildren();
  // The integrator and the sampler are a word or a map with a type and their own keys.
  const typed = (key) => (render[key] && typeof render[key] === 'object') ?
    {path: ['render', key, 'type'], value: render[key].type} : {path: ['render', key], value: render[key]};
  const integrator = typed('integrator'), sampler = typed('sampler');
  box.append(field('integrator', [selectInput(integrator.path, integrator.value ?? settings.integrator,
    state.integrators.map((i) => i.name))], state.integrators.map((i) => `${i.name}: ${i.summary}`).join('\n')));
  box.append(field('sampler', [selectInput(sampler.path, sampler.value ?? settings.sampler,
    state.samplers.map((s) => s.name))], state.samplers.map((s) => `${s.name}: ${s.summary}`).join('\n')));
  box.append(field('samples', [numberInput(['render', 'samples'], render.samples ?? settings.samples, {min: 1, step: 1})],
    'samples per pixel to accumulate'));
  // An integrator's own max_depth wins over the render block's.
  const ownDepth = render.integrator && typeof render.integrator === 'object' && render.integrator.max_depth !== undefined;
  box.append(field('max depth', sliderInput(ownDepth ? ['render', 'integrator', 'max_depth'] : ['render', 'max_depth'],
    ownDepth ? render.integrator.max_depth : (render.max_depth ?? settings.max_depth), ranges.max_depth),
    'longest path, in bounces'));
  const current = `${state.width}×${state.height}`;
  const options = resolutions.map(([w, h]) => `${w}×${h}`);
  box.append(field('resolution', [selectInput(['render', 'resolution'], current, options, (v) => {
    const [w, h] = v.split('×').map(Number);
    edit({path: ['render', 'width'], value: w}, {path: ['render', 'height'], value: h});
  })]));
  box.append(field('size', [
    numberInput(['render', 'width'], state.width, {min: 1, step: 1}), el('span', {text: '×'}),
    numberInput(['render', 'height'], state.height, {min: 1, step: 1})]));
  const shown = new Set(['integrator', 'sampler', 'samples', 'max_depth', 'width', 'height']);
  for (const [key, value] of Object.entries(render)) {
    if (!shown.has(key)) box.append(field(key, valueControl(['render', key], value)));
  }
  box.append(addKeyRow(['render']));
}

// The lens radius slider's range, scaled to the scene: up to a tenth of the distance the camera looks
// at (its focus distance, else eye to look_at), rounded up to 1, 2 or 5 × a power of ten, so the slider
// does as much in a scene in millimetres as in one in metres; 0.5 when the camera says no distance.
function lensRadiusRange(camera) {
  const eye = camera.eye, target = camera.look_at;
  const distance = Number(camera.focus_distance) > 0 ? Number(camera.focus_distance)
    : Array.isArray(eye) && Array.isArray(target) && eye.length === 3 && target.length === 3
      ? Math.sqrt(eye.reduce((sum, e, i) => sum + (e - target[i]) ** 2, 0)) : 0;
  let max = ranges.lens_radius[1];
  if (distance > 0 && Number.isFinite(distance)) {
    const tenth = distance / 10;
    const power = 10 ** Math.floor(Math.log10(tenth));
    max = [1, 2, 5, 10].map((m) => m * power).find((v) => v >= tenth);
  }
  max = Math.max(max, Number(camera.lens_radius) || 0);
  return [0, max, max / 100];
}

function buildCamera() {
  const camera = state.scene.camera || {};
  const box = $('camera-fields');
  box.replaceChildren();
  box.append(field('type', [selectInput(['camera', 'type'], camera.type || 'pinhole', state.cameras)]));
  // Aperture: the f-number when the scene gives one, else the lens radius.
  if ('f_stop' in camera) {
    box.append(field('f-stop', sliderInput(['camera', 'f_stop'], camera.f_stop, ranges.f_stop)));
  } else {
    const inputs = sliderInput(['camera', 'lens_radius'], camera.lens_radius ?? 0, lensRadiusRange(camera),
      (v) => cameraEdit('lens_radius', v));
    box.append(field('aperture', inputs, 'lens radius (0: pinhole, everything sharp)'));
  }
  const focus = numberInput(['camera', 'focus_distance'], camera.focus_distance ?? '', {min: 0},
    (v) => cameraEdit('focus_distance', v));
  const pick = el('button', {class: 'small' + (focusMode ? ' active' : ''), id: 'focus-pick', text: 'pick', title: 'then click the image',
    onclick: () => setFocusMode(!focusMode)});
  box.append(field('focus', [focus, pick], 'focus distance: click “pick”, then a point of the image'));
  const shown = new Set(['type', 'f_stop', 'lens_radius', 'focus_distance']);
  for (const [key, value] of Object.entries(camera)) {
    if (!shown.has(key)) box.append(field(key, valueControl(['camera', key], value)));
  }
  box.append(el('div', {class: 'add-key'}, [el('button', {class: 'small', text: 'Reset view', onclick: () => {
    edit(...['eye', 'look_at', 'up'].filter((k) => k in initialCamera).map((k) => ({path: ['camera', k], value: initialCamera[k]})));
  }})]));
  box.append(addKeyRow(['camera']));
}

const isMap = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// The fields of a material or a light at `path`: its type, from the server's table `types`, then each
// key; a map inside it (a texture, an area light's shape, a gradient sky) one level down, its keys
// indented under its name.
function typedMapFields(box, path, map, types) {
  box.append(field('type', [selectInput([...path, 'type'], map.type, types)]));
  for (const [key, value] of Object.entries(map)) {
    if (key === 'type') continue;
    if (isMap(value)) {
      box.append(field(key, []));
      for (const [inner, v] of Object.entries(value)) {
        const row = field(inner, valueControl([...path, key, inner], v), `${key}.${inner}`);
        row.classList.add('nested');
        box.append(row);
      }
    } else {
      box.append(field(key, valueControl([...path, key], value)));
    }
  }
  box.append(addKeyRow(path));
}

const swatch = (path) => el('span', {class: 'swatch', 'data-swatch': JSON.stringify(path)});

function buildMaterials() {
  const box = $('material-fields');
  box.replaceChildren();
  const materials = state.scene.materials || {};
  // Objects that hold their material themselves (inline), by their position in objects.
  const inline = (state.scene.objects || []).map((object, i) => [object, i]).filter(([object]) => isMap(object) && isMap(object.material));
  if (Object.keys(materials).length === 0 && inline.length === 0) {
    box.append(el('p', {class: 'help', text: 'The scene gives no materials: every object is grey matte.'}));
  }
  for (const [name, material] of Object.entries(materials)) {
    box.append(el('h3', {}, [swatch(['materials', name]), name]));
    if (!isMap(material)) continue;
    typedMapFields(box, ['materials', name], material, state.material_types);
  }
  for (const [object, i] of inline) {
    box.append(el('h3', {title: `the material written inside objects[${i}]`},
      [swatch(['objects', i, 'material']), `${object.type ?? 'object'} ${i}`, el('span', {class: 'inline-tag', text: 'inline'})]));
    typedMapFields(box, ['objects', i, 'material'], object.material, state.material_types);
  }
}

function buildLights() {
  const box = $('light-fields');
  box.replaceChildren();
  const lights = state.scene.lights || [];
  if (lights.length === 0) box.append(el('p', {class: 'help', text: 'The scene lists no lights.'}));
  lights.forEach((light, i) => {
    box.append(el('h3', {}, [swatch(['lights', i]), `${light?.type ?? 'light'} ${i}`]));
    if (isMap(light)) typedMapFields(box, ['lights', i], light, state.light_types);
  });
}

// A swatch shows the colour a material reflects or a light gives (scaled into range).
function updateSwatches() {
  for (const swatch of document.querySelectorAll('[data-swatch]')) {
    const m = valueAt(JSON.parse(swatch.dataset.swatch));
    const colour = isMap(m) ? (m.albedo ?? m.color ?? m.reflectance ?? m.emission ?? m.radiance ?? m.intensity ?? m.irradiance ?? 0.8) : 0.8;
    let rgb = Array.isArray(colour) ? colour : [colour, colour, colour];
    const ok = rgb.length === 3 && rgb.every((x) => typeof x === 'number');
    if (ok && Math.max(...rgb) > 1) rgb = rgb.map((x) => x / Math.max(...rgb));
    swatch.style.background = ok ? linearToHex(rgb) : '#888';
  }
}

function buildControls() {
  buildRender();
  buildCamera();
  buildMaterials();
  buildLights();
  updateSwatches();
}

// Puts the scene's current values into the controls, except the one the user is typing in.
function updateControls() {
  for (const input of document.querySelectorAll('[data-path]')) {
    if (input === document.activeElement && input.type !== 'range') continue;
    const path = JSON.parse(input.dataset.path);
    if (path[0] === 'render' && path[1] === 'resolution') {
      input.value = `${state.width}×${state.height}`;
      continue;
    }
    let value = valueAt(path);
    if (value === undefined && path[0] === 'render') {
      value = path[1] === 'width' ? state.width : path[1] === 'height' ? state.height : state.settings[path[1]];
    }
    if (value === undefined) continue;
    if (input.dataset.kind === 'colour') input.value = linearToHex(value);
    else if (input.type === 'checkbox') input.checked = value;
    else if (typeof value !== 'object') input.value = value;
  }
  updateSwatches();
}

// ---- the mouse on the image -----------------------------------------------------------------------

function setFocusMode(on) {
  focusMode = on;
  $('frame').classList.toggle('focusing', on);
  $('focus-hint').hidden = !on;
  $('focus-pick')?.classList.toggle('active', on);
}

// Film coordinates (pixels of the rendered image) of a mouse event on the image, which is drawn
// scaled to fit ("object-fit: contain") and so may have bars on two sides.
function filmPoint(event) {
  const rect = $('image').getBoundingClientRect();
  const fit = Math.min(rect.width / state.width, rect.height / state.height);
  const left = rect.left + (rect.width - fit * state.width) / 2;
  const top = rect.top + (rect.height - fit * state.height) / 2;
  return {x: (event.clientX - left) / fit, y: (event.clientY - top) / fit};
}

async function focusAt(event) {
  const point = filmPoint(event);
  const response = await postJson('/api/focus', point);
  const hit = await response.json();
  if (!response.ok) return showError(hit.error);
  if (!hit.hit) return showError('Nothing there to focus on: the ray leaves the scene.');
  cameraEdit('focus_distance', round(hit.depth));
}

// The viewing parameters the mouse moves (defaults as the cameras read them: eye (0, 0, 5), look_at 0).
function view() {
  const c = state.scene.camera || {};
  const v = {eye: c.eye || [0, 0, 5], look_at: c.look_at || [0, 0, 0], up: normalize(c.up || [0, 1, 0])};
  return localView ? {...v, eye: localView.eye, look_at: localView.look_at} : v;
}

let drag = null;

function setupMouse() {
  const image = $('image');
  image.addEventListener('contextmenu', (e) => e.preventDefault());
  image.addEventListener('pointerdown', (e) => {
    if (!state) return;
    image.setPointerCapture(e.pointerId);
    drag = {x: e.clientX, y: e.clientY, start: view(), pan: e.shiftKey || e.button === 2, moved: false};
  });
  image.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (!drag.moved && Math.hypot(dx, dy) < 3) return;
    drag.moved = true;
    image.classList.add('dragging');
    const {eye, look_at: target, up} = drag.start;
    const offset = sub(eye, target);
    const right = normalize(cross(up, offset));
    if (drag.pan) {
      const trueUp = normalize(cross(offset, right));
      const perPixel = (2 * length(offset)) / image.getBoundingClientRect().height * Math.tan(((state.scene.camera?.fov ?? 40) * Math.PI) / 360);
      const move = add(scale(right, -dx * perPixel), scale(trueUp, dy * perPixel));
      edit({path: ['camera', 'eye'], value: add(eye, move).map(round)}, {path: ['camera', 'look_at'], value: add(target, move).map(round)});
      return;
    }
    // Orbit about the target: yaw about `up`, pitch about the camera's right, never over the pole.
    let rotated = rotate(offset, up, -dx * 0.008);
    const pitched = rotate(rotated, normalize(cross(up, rotated)), -dy * 0.008);
    const angle = Math.acos(Math.max(-1, Math.min(1, dot(normalize(pitched), up))));
    if (angle > 0.05 && angle < Math.PI - 0.05) rotated = pitched;
    edit({path: ['camera', 'eye'], value: add(target, rotated).map(round)});
  });
  const end = (e) => {
    if (!drag) return;
    const click = !drag.moved;
    drag = null;
    image.classList.remove('dragging');
    if (click && focusMode && e.type === 'pointerup') {
      setFocusMode(false);
      focusAt(e);
    }
  };
  image.addEventListener('pointerup', end);
  image.addEventListener('pointercancel', end);
  image.addEventListener('dblclick', (e) => focusAt(e));
  image.addEventListener('wheel', (e) => {
    if (!state) return;
    e.preventDefault();
    const {eye, look_at: target} = view();
    const offset = sub(eye, target);
    const factor = Math.exp(Math.max(-1, Math.min(1, e.deltaY * 0.001)));
    if (length(offset) * factor < 1e-3) return;
    edit({path: ['camera', 'eye'], value: add(target, scale(offset, factor)).map(round)});
  }, {passive: false});
  document.addEventListener('keydown', (e) => { if (e.key === 'Escape') setFocusMode(false); });
}

// ---- display ----------------------------------------------------------------------------------------

// Exposure and tone curve for the eyes only (POST /api/display): the server shows the frames through
// them without touching the render or the scene, so an exported scene keeps its own render.exposure.
let displayTouched = false;
function setupDisplay() {
  const exposure = $('display-exposure');
  const tonemap = $('display-tonemap');
  const send = async () => {
    displayTouched = true;
    $('display-exposure-value').textContent = Number(exposure.value).toFixed(1);
    try {
      const response = await postJson('/api/display', {exposure: Number(exposure.value), tonemap: tonemap.value});
      if (!response.ok) showError((await response.json()).error || `error ${response.status}`);
    } catch (error) {
      showError(`cannot reach glint serve: ${error}`);
    }
  };
  exposure.addEventListener('input', send);
  tonemap.addEventListener('change', send);
  const refine = $('refine-continuously');
  refine.addEventListener('change', async () => {
    try {
      const response = await postJson('/api/refine', {continuous: refine.checked});
      const body = await response.json();
      if (!response.ok) showError(body.error || `error ${response.status}`);
      else showRefineNote(body);
    } catch (error) {
      showError(`cannot reach glint serve: ${error}`);
    }
  });
}

// Until the user moves them, the controls show what the frames are shown through (the scene's own).
function showDisplay(frame) {
  if (displayTouched || frame.exposure === undefined) return;
  $('display-exposure').value = frame.exposure;
  $('display-exposure-value').textContent = Number(frame.exposure).toFixed(1);
  $('display-tonemap').value = frame.tonemap;
}

// ---- start ----------------------------------------------------------------------------------------

setupMouse();
setupDisplay();
fetchState().then(connectEvents).catch((error) => showError(`cannot reach glint serve: ${error}`));
