// The mesh viewer in a real browser: pages made by the built geomesh from the tutorials are
// loaded from file:// in headless Chromium (SwiftShader's WebGL), their canvas is
// screenshotted, and the pictures must show what the controls ask for.
//
// Environment (ctest sets it): GEOMESH_BINARY (default build/bin/geomesh),
// GEOMESH_SOURCE_DIR, GEOMESH_VIEWER_MODULES (the node_modules holding playwright-core),
// GEOMESH_CHROMIUM (default /usr/bin/chromium), GEOMESH_VIEWER_SHOTS (a folder to keep the
// screenshots in).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync, mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import {
  changedShare,
  colourShare,
  decodePng,
  distinctColours,
  hueRangeShare,
  parseHex,
} from './pixels.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = process.env.GEOMESH_SOURCE_DIR || resolve(here, '../..');
const binary = process.env.GEOMESH_BINARY || join(root, 'build/bin/geomesh');
const modules = process.env.GEOMESH_VIEWER_MODULES || join(here, '../node_modules');
const chromiumPath = process.env.GEOMESH_CHROMIUM || '/usr/bin/chromium';
const shots = process.env.GEOMESH_VIEWER_SHOTS || '';
const { chromium } = createRequire(join(modules, 'noop.js'))('playwright-core');

// SwiftShader gives WebGL without a GPU; no flag beyond these was needed.
const kChromiumArgs = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

let work;
let context;

function geomesh(...args) {
  const env = { ...process.env };
  delete env.DISPLAY;
  delete env.WAYLAND_DISPLAY;
  const run = spawnSync(binary, args, { cwd: work, env, encoding: 'utf8' });
  assert.equal(run.status, 0, `geomesh ${args.join(' ')} failed:\n${run.stderr}`);
  return run.stderr;
}

// Opens a page, failing on any script error or any request that leaves file://.
async function openPage(file) {
  const page = await context.newPage();
  await page.setViewportSize({ width: 1100, height: 700 });
  const problems = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  page.on('request', (r) => !r.url().startsWith('file:') && problems.push(`request: ${r.url()}`));
  await page.goto(pathToFileURL(file).href);
  await page.waitForSelector('body[data-ready="yes"]', { timeout: 60000 });
  page.problems = problems;
  return page;
}

let shotNumber = 0;
async function picture(page, selector = '#view') {
  const png = await page.locator(selector).screenshot();
  if (shots) {
    mkdirSync(shots, { recursive: true });
    writeFileSync(join(shots, `${String(++shotNumber).padStart(2, '0')}.png`), png);
  }
  return decodePng(png);
}

// The colour the page gives each group, by name, from its swatch.
async function groupColours(page) {
  return page.$$eval('li.group', (items) =>
    Object.fromEntries(
      items.map((li) => [
        li.textContent.split(' (')[0],
        li.querySelector('.swatch').dataset.color,
      ]),
    ),
  );
}

async function setGroup(page, name, on) {
  const box = page.locator('li.group', { hasText: name }).locator('input[type=checkbox]');
  if (on) await box.check();
  else await box.uncheck();
}

async function moveSlider(page, value) {
  await page.$eval(
    '#clip-position',
    (slider, v) => {
      slider.value = String(v);
      slider.dispatchEvent(new Event('input', { bubbles: true }));
    },
    value,
  );
}

function assertNotBlank(image) {
  assert.ok(distinctColours(image) > 20, 'the picture is nearly uniform');
  const background = [0xf4, 0xf4, 0xf6];
  let drawn = 0;
  for (let i = 0; i < image.width * image.height; ++i) {
    const r = image.rgba[4 * i];
    const b = image.rgba[4 * i + 2];
    if (Math.abs(r - background[0]) + Math.abs(b - background[2]) > 12) drawn += 1;
  }
  assert.ok(drawn / (image.width * image.height) > 0.1, 'almost nothing is drawn');
}

before(async () => {
  assert.ok(existsSync(binary), `no geomesh binary at ${binary}`);
  work = mkdtempSync(join(tmpdir(), 'geomesh-viewer-'));
  context = await chromium.launchPersistentContext(join(work, 'profile'), {
    executablePath: chromiumPath,
    args: kChromiumArgs,
    headless: true,
  });
});

after(async () => {
  if (context) await context.close();
  if (work) rmSync(work, { recursive: true, force: true });
});

test('a planar mesh: groups coloured and toggled, quality ramp and histogram', async () => {
  geomesh(join(root, 'tutorials/t1.geo'), '-2', '-o', join(work, 't1.msh'));
  const log = geomesh('view', join(work, 't1.msh'));
  assert.match(log, /Wrote '.*t1\.html'/);
  assert.match(log, /Open '.*t1\.html' in a browser/);
  const page = await openPage(join(work, 't1.html'));
  const colours = await groupColours(page);
  assert.deepEqual(Object.keys(colours), ['plate', 'clamped', 'loaded', 'free', 'hole']);

  const groups = await picture(page);
  assertNotBlank(groups);
  const plate = parseHex(colours.plate);
  assert.ok(colourShare(groups, plate) > 0.15, 'the plate is not in its colour');
  for (const curve of ['clamped', 'loaded', 'free', 'hole'])
    assert.ok(colourShare(groups, parseHex(colours[curve])) * groups.width * groups.height > 30,
      `the ${curve} curves are not in their colour`);

  await setGroup(page, 'plate', false);
  const withoutPlate = await picture(page);
  assert.ok(colourShare(withoutPlate, plate) < 0.001, 'the unticked plate is still drawn');
  assert.ok(colourShare(withoutPlate, parseHex(colours.hole)) > 0, 'the holes went too');
  await setGroup(page, 'plate', true);

  assert.equal(await page.locator('#quality').isVisible(), false);
  await page.locator('#mode-quality').check();
  const quality = await picture(page);
  assertNotBlank(quality);
  assert.ok(colourShare(quality, plate) < 0.002, 'group colours remain in quality mode');
  // t1's triangles have gamma above 0.5: the ramp from green (0.5) to blue (1).
  assert.ok(hueRangeShare(quality, 115, 245) > 0.15, 'the ramp colours are missing');
  assert.equal(await page.locator('#quality').isVisible(), true);
  const bins = (await page.getAttribute('#histogram', 'data-bins')).split(' ').map(Number);
  assert.equal(bins.reduce((a, b) => a + b, 0), 1152);  // t1's triangles
  const histogram = await picture(page, '#histogram');
  assert.ok(hueRangeShare(histogram, 100, 245) > 0.01, 'the histogram shows no bar');

  const worst = page.locator('#worst tbody tr');
  assert.equal(await worst.count(), 10);
  await worst.first().click();
  const focused = await picture(page);
  assert.ok(changedShare(quality, focused) > 0.05, 'clicking a worst element moved nothing');
  assert.deepEqual(page.problems, []);
  await page.close();
});

test('a volume mesh: clipping shows the inside, groups toggle', async () => {
  const log = geomesh(join(root, 'tutorials/t5.geo'), '-3', '-o', join(work, 't5.msh'), '-view');
  assert.match(log, /Wrote '.*t5\.html'/);
  const page = await openPage(join(work, 't5.html'));
  const colours = await groupColours(page);
  assert.deepEqual(Object.keys(colours), ['housing', 'floor', 'chamber']);
  const [housing, floor, chamber] = ['housing', 'floor', 'chamber'].map((g) =>
    parseHex(colours[g]));

  const whole = await picture(page);
  assertNotBlank(whole);
  assert.ok(colourShare(whole, housing) > 0.1, 'the housing is not in its colour');
  assert.ok(colourShare(whole, chamber) < 0.001, 'the chamber shows through the housing');

  await page.selectOption('#clip-axis', '0');  // x, at the middle
  const clipped = await picture(page);
  assert.ok(changedShare(whole, clipped) > 0.05, 'clipping changed nothing');
  assert.ok(colourShare(clipped, chamber) > 0.005, 'the cut does not show the chamber');
  assert.ok(colourShare(clipped, housing) > 0.05, 'the cut housing is not drawn');
  await moveSlider(page, 250);
  const moved = await picture(page);
  assert.ok(changedShare(clipped, moved) > 0.05, 'the slider changed nothing');
  await page.selectOption('#clip-axis', '-1');

  await setGroup(page, 'housing', false);
  const inner = await picture(page);
  assert.ok(colourShare(inner, housing) < 0.001, 'the unticked housing is still drawn');
  assert.ok(colourShare(inner, chamber) > 0.005, 'the chamber is not drawn');
  assert.ok(colourShare(inner, floor) > 0.005, 'the floor is not drawn');
  assert.deepEqual(page.problems, []);
  await page.close();
});
