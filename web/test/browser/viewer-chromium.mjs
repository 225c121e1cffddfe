// The viewer in headless Chromium: it loads a .drm file through the
// worker pool, renders it (pixels other than the background), colours
// faces by rank on request (the palette's green, orange and red appear),
// reports the codec's message for a refused file, and its workers decode
// every golden file to the same arrays as decode() on the page's thread.
// decode() in the page gives every golden file and every corpus file that
// npm test encoded (web/build/test/corpus/) the positions and triangles
// `drm decode` writes: SHA-256 digests of the arrays, taken in the page and
// from the CLI's PLY files in Node, agree. Saves the rank view to web/build/web-viewer.png, or to
// DRM_VIEWER_SCREENSHOT (docs/images/web-viewer.png is made so).
//
//   node test/browser/viewer-chromium.mjs        (CHROMIUM=/path overrides /usr/bin/chromium)
import { chromium } from 'playwright-core';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readdirSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve } from '../../viewer/serve.mjs';
import { decodeAll, listFiles } from '../cli.js';
import { readPly, interleave } from '../ply.js';

const WEB = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const ROOT = resolve(WEB, '..');
const GOLDEN = join(ROOT, 'tests', 'golden');
const SCREENSHOT = process.env.DRM_VIEWER_SCREENSHOT || join(WEB, 'build', 'web-viewer.png');
const FILE = 'bunny-lres.drm';
const CORPUS = join(WEB, 'build', 'test', 'corpus');

// The digest of a decoded mesh: SHA-256 of its positions' bytes, then its
// triangles' (little-endian float32 and uint32, as both arrays hold them).
function cliDigest(ply) {
  const p = readPly(ply);
  const v = p.vertex.data;
  const positions = interleave([v.x, v.y, v.z]);
  const indices = Uint32Array.from(p.face.data.vertex_indices.values);
  return createHash('sha256').update(new Uint8Array(positions.buffer)).update(new Uint8Array(indices.buffer)).digest('hex');
}

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok' : 'not ok'} - ${what}`);
  if (!ok) failures++;
}

// Counts, in the page, the canvas's pixels: those unlike the background,
// and those near each rank palette colour's hue (shading changes their
// lightness, not their hue).
function pixelCensus() {
  const source = document.querySelector('#view canvas');
  const c = document.createElement('canvas');
  c.width = source.width;
  c.height = source.height;
  const ctx = c.getContext('2d');
  ctx.drawImage(source, 0, 0);
  const data = ctx.getImageData(0, 0, c.width, c.height).data;
  const bg = [data[0], data[1], data[2]];
  const hueOf = (r, g, b) => {
    const max = Math.max(r, g, b), min = Math.min(r, g, b), d = max - min;
    if (d === 0) return [0, 0];
    let h = max === r ? ((g - b) / d) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
    h *= 60;
    if (h < 0) h += 360;
    return [h, d / max];
  };
  const census = { total: c.width * c.height, foreground: 0, green: 0, orange: 0, red: 0, background: bg };
  for (let i = 0; i < data.length; i += 4) {
    const r = data[i], g = data[i + 1], b = data[i + 2];
    if (Math.abs(r - bg[0]) + Math.abs(g - bg[1]) + Math.abs(b - bg[2]) > 24) census.foreground++;
    const [h, s] = hueOf(r, g, b);
    if (s < 0.45 || Math.max(r, g, b) < 60) continue;
    if (h > 105 && h < 140) census.green++;       // #4caf50: hue 123
    else if (h > 28 && h < 45) census.orange++;   // #f5a623: hue 37
    else if (h < 8 || h > 352) census.red++;      // #d62728: hue 0
  }
  return census;
}

async function waitReady(page, what) {
  await page.waitForFunction(() => window.drmViewer && ['ready', 'error'].includes(window.drmViewer.status) &&
    window.drmViewer.frames > 5, null, { timeout: 30000 });
  const s = await page.evaluate(() => ({ status: window.drmViewer.status, error: window.drmViewer.error }));
  check(s.status === 'ready', `${what}: the viewer is ready${s.error ? ` (error: ${s.error})` : ''}`);
}

async function main() {
  const { server, url } = await serve({ port: 0, files: GOLDEN });
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    // Root in CI: no sandbox; no GPU: WebGL runs on SwiftShader.
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  try {
    const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });

    await page.goto(`${url}/viewer/?file=/files/${FILE}&up=-y`);
    await waitReady(page, FILE);
    const stats = await page.evaluate(() => ({ ...window.drmViewer.stats, decodeMs: window.drmViewer.decodeMs }));
    check(stats.vertices === 2583 && stats.faces === 4949, `${FILE}: ${stats.vertices} vertices, ${stats.faces} faces`);
    const table = await page.textContent('#stats');
    check(/connectivity bits\/vertex/.test(table) && /decode time/.test(table), 'the stats table shows bits per vertex and decode time');
    console.log(`# decode in the viewer (worker, fetch excluded): ${stats.decodeMs.toFixed(1)} ms`);

    const plain = await page.evaluate(pixelCensus);
    check(plain.foreground > plain.total * 0.05, `the mesh covers ${(100 * plain.foreground / plain.total).toFixed(1)}% of the canvas`);
    const plainRanked = plain.green + plain.orange + plain.red;
    check(plainRanked < plain.total * 0.001, `no rank colours before they are switched on (${plainRanked} pixels)`);

    await page.check('#ranks');
    await page.waitForFunction(() => window.drmViewer.rankColors && window.drmViewer.frames > 5);
    const ranked = await page.evaluate(pixelCensus);
    console.log(`# rank view pixels: green ${ranked.green}, orange ${ranked.orange}, red ${ranked.red}, foreground ${ranked.foreground}`);
    const buckets = await page.evaluate(() => window.drmViewer.buckets);
    check(ranked.green > 20 && buckets[2] > 0, 'rank 2 faces show in green');
    check(ranked.orange + ranked.red > 20 && buckets[3] + buckets[4] > 0, 'rank 3 and 4+ faces show in orange and red');
    const legend = await page.textContent('#legend');
    check(/rank 1 \(pale blue-grey\)/.test(legend) && /rank 4\+ \(red\)/.test(legend), 'the legend names the palette');
    mkdirSync(dirname(SCREENSHOT), { recursive: true });
    await page.screenshot({ path: SCREENSHOT });
    console.log(`# screenshot: ${SCREENSHOT}`);

    // A refused file: the codec's message reaches the page.
    await page.evaluate(() => window.drmViewer.load('/files/earlier-versions/torus-v1.drm'));
    await page.waitForFunction(() => window.drmViewer.status === 'error', null, { timeout: 30000 });
    const error = await page.evaluate(() => window.drmViewer.error);
    check(/^unsupported \.drm format version 1\b/.test(error), `a version 1 file is refused: "${error}"`);

    // The worker pool against decode() on the page's thread, every golden
    // file at once; the buffers move to the workers (detached here).
    const names = readdirSync(GOLDEN).filter((f) => f.endsWith('.drm'));
    const pool = await page.evaluate(async (files) => {
      const { DRMLoader } = await import('/src/DRMLoader.js');
      const { decode } = await import('/src/index.js');
      const loader = new DRMLoader().setWorkerLimit(3);
      const buffers = await Promise.all(files.map(async (f) => (await fetch(`/files/${f}`)).arrayBuffer()));
      const direct = await Promise.all(buffers.map((b) => decode(b.slice(0))));
      const viaWorkers = await Promise.all(buffers.map((b) => loader.decode(b)));
      const same = (a, b) => a.length === b.length && a.every((v, i) => Object.is(v, b[i]));
      const mismatched = files.filter((f, i) => !same(direct[i].positions, viaWorkers[i].positions) ||
        !same(direct[i].indices, viaWorkers[i].indices));
      const detached = buffers.every((b) => b.byteLength === 0);
      const workers = loader.workerPool.length;
      loader.dispose();
      return { mismatched, detached, workers };
    }, names);
    check(pool.mismatched.length === 0, `workers decode ${names.length} golden files as decode() does` +
      (pool.mismatched.length ? ` (differ: ${pool.mismatched.join(', ')})` : ''));
    check(pool.detached, 'the files\' buffers are transferred to the workers, not copied');
    check(pool.workers >= 2 && pool.workers <= 3, `the pool holds ${pool.workers} workers (limit 3)`);

    // Every golden file and every corpus file npm test encoded: decode() in
    // the page against the CLI's decoded PLY.
    const golden = names.map((f) => join(GOLDEN, f));
    const corpus = existsSync(CORPUS) ? listFiles(CORPUS, '.drm') : [];
    const files = [...golden, ...corpus];
    const expected = [...decodeAll(golden, join(WEB, 'build', 'test', 'browser-golden')),
      ...decodeAll(corpus, join(CORPUS, 'decoded'))].map((f) => cliDigest(f.ply));
    const inPage = await page.evaluate(async (encoded) => {
      const { decode } = await import('/src/index.js');
      const hex = (b) => [...new Uint8Array(b)].map((x) => x.toString(16).padStart(2, '0')).join('');
      const out = [];
      for (const base64 of encoded) {
        const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
        const m = await decode(bytes);
        const joined = new Uint8Array(m.positions.byteLength + m.indices.byteLength);
        joined.set(new Uint8Array(m.positions.buffer, m.positions.byteOffset, m.positions.byteLength));
        joined.set(new Uint8Array(m.indices.buffer, m.indices.byteOffset, m.indices.byteLength), m.positions.byteLength);
        out.push(hex(await crypto.subtle.digest('SHA-256', joined)));
      }
      return out;
    }, files.map((f) => readFileSync(f).toString('base64')));
    const differ = files.filter((f, i) => inPage[i] !== expected[i]);
    console.log(`# ${golden.length} golden and ${corpus.length} corpus files decoded in the page`);
    check(differ.length === 0, `decode() in Chromium gives ${files.length} golden and corpus files the CLI's positions and triangles` +
      (differ.length ? ` (differ: ${differ.join(', ')})` : ''));

    check(errors.length === 0, `no errors in the page${errors.length ? ': ' + errors.join(' | ') : ''}`);
  } finally {
    await browser.close();
    server.close();
  }
  console.log(failures ? `# ${failures} failed` : '# all passed');
  process.exit(failures ? 1 : 0);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
