// DRMLoader and the geometry helpers under Node (no Web Workers: the
// loader decodes on the calling thread; the worker pool runs in the
// browser test). The rank palette is the C++ one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { Color, SRGBColorSpace } from 'three';
import { DRMLoader, rankColoredGeometry, RANK_PALETTE, rankBucket } from '../src/DRMLoader.js';
import { decode } from '../src/index.js';
import { ROOT, haveCli, encodeAndDecode } from './cli.js';

const GOLDEN = join(ROOT, 'tests', 'golden');
const bytesOf = (name) => {
  const b = readFileSync(join(GOLDEN, name));
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.length);
};

test('the palette is the one of vcg_adapters/include/drm_vcg/rank_palette.h', () => {
  const header = readFileSync(join(ROOT, 'vcg_adapters', 'include', 'drm_vcg', 'rank_palette.h'), 'utf8');
  const entries = [...header.matchAll(/\{(\d+), (\d+), (\d+), "([^"]+)", "([^"]+)"\}/g)]
    .map((m) => ({ r: +m[1], g: +m[2], b: +m[3], colourName: m[4], label: m[5] }));
  assert.equal(entries.length, 5);
  assert.deepEqual(RANK_PALETTE.map(({ r, g, b, colourName, label }) => ({ r, g, b, colourName, label })), entries);
  assert.equal(RANK_PALETTE[1].hex, '#b4c0ce');
  assert.deepEqual([0, 1, 2, 3, 4, 5, 99].map(rankBucket), [0, 1, 2, 3, 4, 4, 4]);
});

test('parseAsync gives an indexed geometry of the decoded mesh', async () => {
  const loader = new DRMLoader();
  const reference = await decode(bytesOf('bunny-lres.drm'));
  const g = await loader.parseAsync(bytesOf('bunny-lres.drm'));
  assert.deepEqual(g.getAttribute('position').array, reference.positions);
  assert.deepEqual(g.getIndex().array, reference.indices);
  assert.equal(g.userData.stats.faces, reference.stats.faces);
  assert.ok(g.userData.faceRank);
  assert.equal(g.getAttribute('color'), undefined);
});

test('parse calls back, and passes the codec\'s error on', async () => {
  const loader = new DRMLoader();
  const g = await new Promise((resolve, reject) => loader.parse(bytesOf('torus.drm'), resolve, reject));
  assert.equal(g.getIndex().count, g.userData.stats.faces * 3);
  const bad = new Uint8Array(bytesOf('torus.drm')).slice(0, 30);
  const e = await new Promise((resolve) => loader.parse(bad.buffer, () => resolve(null), resolve));
  assert.equal(e.name, 'DRMDecodeError');
  assert.match(e.message, /^corrupt file: /);
});

test('rank colours: a colour per face from the palette', async () => {
  const loader = new DRMLoader().setRankColors(true);
  const result = await decode(bytesOf('bunny-lres.drm'));
  const g = await loader.parseAsync(bytesOf('bunny-lres.drm'));
  const faces = result.stats.faces;
  assert.equal(g.getIndex(), null);
  assert.equal(g.getAttribute('position').count, 3 * faces);
  const colour = g.getAttribute('color');
  const expected = RANK_PALETTE.map((e) => new Color().setRGB(e.r / 255, e.g / 255, e.b / 255, SRGBColorSpace));
  for (let f = 0; f < faces; f++) {
    const e = expected[rankBucket(result.faceRank[f])];
    for (let k = 0; k < 3; k++) {
      const i = 3 * f + k;
      assert.ok(Math.abs(colour.getX(i) - e.r) < 1e-6 && Math.abs(colour.getY(i) - e.g) < 1e-6 && Math.abs(colour.getZ(i) - e.b) < 1e-6);
    }
    // Corners are the face's vertices.
    const p = g.getAttribute('position');
    const v = result.indices[3 * f];
    assert.equal(p.getX(3 * f), result.positions[3 * v]);
  }
  const buckets = new Set(Array.from(result.faceRank, rankBucket));
  assert.ok(buckets.size >= 3, `only buckets ${[...buckets]}`);
  // The helper gives the same geometry from a decode() result.
  assert.deepEqual(rankColoredGeometry(result).getAttribute('color').array, colour.array);
});

test('attributes: vertex colours, normals, per-corner uvs and material groups', { skip: !haveCli() && 'build/bin/drm is not built' }, async () => {
  const data = join(ROOT, 'tests', 'data', 'attributes');
  const files = encodeAndDecode([join(data, 'vcolors.ply'), join(data, 'spider.obj')], 'loader');
  const [vcolorsDrm, spiderDrm] = files.map((f) => f.drm);
  const loader = new DRMLoader();
  const vcolors = readFileSync(vcolorsDrm);
  const g = await loader.parseAsync(new Uint8Array(vcolors));
  assert.ok(g.getAttribute('color'));
  assert.ok(g.getAttribute('normal'));
  assert.ok(g.getAttribute('uv'));
  const spider = await loader.parseAsync(new Uint8Array(readFileSync(spiderDrm)));
  assert.equal(spider.getIndex(), null, 'per-corner texture coordinates need three vertices per face');
  assert.equal(spider.getAttribute('uv').count, spider.getAttribute('position').count);
  assert.ok(spider.groups.length >= 2);
  assert.ok(spider.userData.materials.length >= 2);
  const covered = spider.groups.reduce((n, gr) => n + gr.count, 0);
  assert.equal(covered, spider.getAttribute('position').count);
});
