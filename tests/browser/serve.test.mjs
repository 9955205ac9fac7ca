// Browser test of `glint serve`: Debian's Chromium, headless, driven by playwright-core.
// Loads the page, waits for the image to refine, moves controls (a slider, the mouse), checks that the
// image changed and the accumulation restarted, saves the PNG and takes a screenshot.
//   node serve.test.mjs <glint binary> <output folder>
import assert from 'node:assert/strict';
import {spawn} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {chromium} from 'playwright-core';

const [glint, outDir] = process.argv.slice(2);
assert.ok(glint && outDir, 'usage: node serve.test.mjs <glint binary> <output folder>');
fs.mkdirSync(outDir, {recursive: true});

const deadline = setTimeout(() => fail(new Error('the browser test took more than 120 s')), 120_000);
let server = null;
let context = null;
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'glint-chromium-'));

function log(...args) {
  console.log('[browser test]', ...args);
}

async function cleanup() {
  if (context) await context.close().catch(() => {});
  if (server && server.exitCode === null) server.kill('SIGINT');
  fs.rmSync(userDataDir, {recursive: true, force: true});
}

async function fail(error) {
  console.error('[browser test] FAILED:', error);
  await cleanup();
  process.exit(1);
}

// Starts `glint serve` on a free loopback port and returns its address.
function startServer() {
  return new Promise((resolve, reject) => {
    server = spawn(glint, ['serve', '--port', '0'], {stdio: ['ignore', 'pipe', 'inherit']});
    let output = '';
    server.stdout.on('data', (chunk) => {
      output += chunk;
      const match = output.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (match) resolve(match[0]);
    });
    server.on('exit', (code) => reject(new Error(`glint serve exited with ${code}: ${output}`)));
  });
}

const stats = (page) => page.$eval('#stats', (e) => ({
  samples: Number(e.dataset.samples), target: Number(e.dataset.target),
  generation: Number(e.dataset.generation), frame: Number(e.dataset.frame), text: e.textContent,
}));
const imageSrc = (page) => page.$eval('#image', (e) => e.src);

// Waits until the latest frame of `generation` has all its samples.
async function waitRefined(page, generation) {
  await page.waitForFunction((g) => {
    const d = document.getElementById('stats').dataset;
    return Number(d.generation) >= g && Number(d.target) > 0 && Number(d.samples) === Number(d.target);
  }, generation, {timeout: 60_000});
}

// Records every frame the page shows from now on: [{generation, samples, at}].
async function recordFrames(page) {
  await page.evaluate(() => {
    window.framesSeen = [];
    const s = document.getElementById('stats');
    new MutationObserver(() => window.framesSeen.push({
      generation: Number(s.dataset.generation), samples: Number(s.dataset.samples), at: performance.now(),
    })).observe(s, {attributes: true, attributeFilter: ['data-frame']});
  });
}

try {
  const url = await startServer();
  log('server at', url);
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.GLINT_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    acceptDownloads: true,
    viewport: {width: 1400, height: 820},
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const page = context.pages()[0] || await context.newPage();
  const pageErrors = [];
  page.on('pageerror', (error) => pageErrors.push(error));
  page.on('console', (message) => { if (message.type() === 'error') pageErrors.push(message.text()); });

  // 1. The page loads and shows the image refined to its target (the server started rendering before
  // the page connected, so the stream starts with its latest frame).
  await page.goto(url);
  await page.waitForSelector('#render-fields select');
  await waitRefined(page, 1);
  const first = await stats(page);
  log('refined:', first.text);
  assert.equal(first.generation, 1);
  assert.equal(first.target, 16);
  const before = await imageSrc(page);
  // The aperture slider is scaled to the scene: the default camera looks 7.05 units away, so its lens
  // radius goes up to a tenth of that rounded up to 1, 2 or 5 × a power of ten: 1.
  const lens = page.locator('input[type=range][data-path=\'["camera","lens_radius"]\']');
  assert.equal(await lens.getAttribute('max'), '1');

  // 2. Move a control (the field of view slider): the image changes and accumulation restarts.
  await recordFrames(page);
  const changedAt = await page.evaluate(() => performance.now());
  const fov = page.locator('input[type=range][data-path=\'["camera","fov"]\']');
  await fov.fill('28');
  await waitRefined(page, 2);
  const frames2 = await page.evaluate(() => window.framesSeen.filter((f) => f.generation === 2));
  const second = await stats(page);
  log('after the fov change:', second.text, `first new frame after ${(frames2[0].at - changedAt).toFixed(0)} ms`,
    `samples per frame: ${frames2.map((f) => f.samples).join(' ')}`);
  assert.equal(second.generation, 2);
  assert.ok(frames2.length >= 2, 'the new image should arrive in several refining frames');
  assert.ok(frames2[0].samples < second.target, 'accumulation should restart from a coarse frame');
  assert.ok(frames2.every((f, i) => i === 0 || f.samples >= frames2[i - 1].samples), 'samples only grow');
  assert.notEqual(await imageSrc(page), before, 'the image should change');
  const scene = await page.evaluate(() => fetch('/api/scene').then((r) => r.json()));
  assert.equal(scene.scene.camera.fov, 28);

  // 3. Orbit with the mouse: eye moves, a new generation starts.
  const box = await page.locator('#image').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 25, {steps: 8});
  await page.mouse.up();
  await page.waitForFunction(() => Number(document.getElementById('stats').dataset.generation) > 2);
  const orbited = await page.evaluate(() => fetch('/api/scene').then((r) => r.json()));
  assert.notDeepEqual(orbited.scene.camera.eye, [0, 1.6, 7], 'dragging should move the eye');
  assert.deepEqual(orbited.scene.camera.look_at, [0, 0.8, 0], 'orbiting keeps the target');

  // 4. A material's colour, through its number box: a bad value shows the server's message.
  const red = page.locator('input[data-path=\'["materials","red","albedo",0]\']');
  await red.fill('-1');
  await red.press('Enter');
  await page.waitForSelector('#error:not([hidden])');
  const message = await page.$eval('#error', (e) => e.textContent);
  log('error shown:', message.split('\n')[0]);
  assert.match(message, /albedo/);
  await red.fill('0.95');
  await red.press('Enter');
  await page.waitForSelector('#error', {state: 'hidden'});

  // 5. Click-to-focus: double-clicking the red sphere's centre casts a ray there. With a lens camera
  // in the tables the page sets focus_distance to the hit's depth (the unit sphere at (0, 1, 0) seen
  // from about 7 away); with only a pinhole, the server's message says the camera takes no focus.
  const scene5 = await page.evaluate(() => fetch('/api/scene').then((r) => r.json()));
  const target = scene5.scene.camera.look_at;
  assert.deepEqual(target, [0, 0.8, 0]);
  const frameGeneration5 = (await stats(page)).generation;
  await page.locator('#image').dblclick({position: {x: box.width / 2, y: box.height / 2}});
  // Wait (a synchronous predicate: Playwright does not await a promise a predicate returns, which
  // made this wait end at once) until the error shows or the frames' generation moves on, and take the
  // error's text in the same evaluation, since a later read could find it already cleared.
  const outcome = await (await page.waitForFunction((g) => {
    const error = document.getElementById('error');
    if (!error.hidden) return {error: error.textContent};
    return Number(document.getElementById('stats').dataset.generation) > g && {changed: true};
  }, frameGeneration5)).jsonValue();
  const focused = await page.evaluate(() => fetch('/api/scene').then((r) => r.json()));
  if (outcome.changed) {
    const eye = focused.scene.camera.eye;
    const toCentre = Math.hypot(eye[0], eye[1] - 1, eye[2]);
    log('focused at', focused.scene.camera.focus_distance, 'with camera', focused.scene.camera.type);
    assert.ok(Math.abs(focused.scene.camera.focus_distance - (toCentre - 1)) < 0.15, 'focus on the sphere\'s front');
  } else {
    const text = outcome.error;
    log('focus on a pinhole:', text.split('\n')[0]);
    assert.match(text, /focus_distance/);
  }

  // 6. Resolution: a preset changes the image size and restarts the accumulation.
  const generation6 = (await stats(page)).generation;
  await page.selectOption('select[data-path=\'["render","resolution"]\']', '320×180');
  await page.waitForFunction((g) => Number(document.getElementById('stats').dataset.generation) > g, generation6);
  await page.waitForFunction(() => document.getElementById('stats').textContent.startsWith('320×180'));
  await page.selectOption('select[data-path=\'["render","resolution"]\']', '640×360');
  await page.waitForFunction(() => document.getElementById('stats').textContent.startsWith('640×360'));
  await page.evaluate(() => { document.getElementById('error').hidden = true; });

  // 7. Save downloads the PNG of the current image; Export the scene's YAML.
  const generationNow = (await stats(page)).generation;
  await waitRefined(page, generationNow);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-png')]);
  const pngPath = path.join(outDir, 'saved.png');
  await download.saveAs(pngPath);
  const png = fs.readFileSync(pngPath);
  assert.equal(png.subarray(1, 4).toString(), 'PNG');
  assert.equal(png.readUInt32BE(16), 640);
  assert.equal(png.readUInt32BE(20), 360);
  const [yamlDownload] = await Promise.all([page.waitForEvent('download'), page.click('#export-scene')]);
  const yamlPath = path.join(outDir, 'exported.yaml');
  await yamlDownload.saveAs(yamlPath);
  const yaml = fs.readFileSync(yamlPath, 'utf8');
  assert.match(yaml, /fov: 28/);
  assert.match(yaml, /red: \{type: matte, albedo: \[0\.95, 0\.15, 0\.1\]\}/);

  const screenshot = path.join(outDir, 'serve.png');
  await page.screenshot({path: screenshot});
  log('saved', pngPath, yamlPath, screenshot);
  assert.deepEqual(pageErrors.filter((e) => !String(e).includes('422')), [], 'the page should log no errors');

  await context.close();
  context = null;
  server.kill('SIGINT');
  const code = await new Promise((resolve) => server.once('exit', resolve));
  assert.equal(code, 0, 'glint serve should stop cleanly on Ctrl-C');
  clearTimeout(deadline);
  fs.rmSync(userDataDir, {recursive: true, force: true});
  log('passed');
} catch (error) {
  await fail(error);
}
