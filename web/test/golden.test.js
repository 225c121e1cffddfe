// Every golden file (tests/golden/*.drm) decodes to what `drm decode` writes,
// bit for bit; the files of earlier format versions are refused with the
// CLI's message, which names the version.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { decode, DRMDecodeError } from '../src/index.js';
import { ROOT, WORK, haveCli, decodeAll, cliDecodeError, listFiles } from './cli.js';
import { compareWithPly } from './compare.js';

const GOLDEN = join(ROOT, 'tests', 'golden');
const skip = haveCli() ? false : 'build/bin/drm is not built';

test('golden files decode as drm decode writes them', { skip }, async (t) => {
  const files = decodeAll(listFiles(GOLDEN, '.drm'), join(WORK, 'golden'));
  assert.ok(files.length >= 10, `only ${files.length} golden files`);
  for (const f of files) {
    await t.test(f.name, async () => {
      const result = await decode(readFileSync(f.drm));
      compareWithPly(result, f.ply);
      // The reference decodes kept beside the goldens agree too.
      compareWithPly(result, join(GOLDEN, `${f.name}.decoded.ply`));
    });
  }
});

test('files of earlier format versions are refused, naming the version', { skip }, async (t) => {
  const files = listFiles(join(GOLDEN, 'earlier-versions'), '.drm');
  assert.ok(files.length > 0);
  for (const file of files) {
    await t.test(file.split('/').pop(), async () => {
      const version = Number(/-v(\d+)\.drm$/.exec(file)[1]);
      const expected = cliDecodeError(file);
      assert.match(expected, new RegExp(`^unsupported \\.drm format version ${version}\\b`));
      await assert.rejects(decode(readFileSync(file)), (e) => {
        assert.ok(e instanceof DRMDecodeError);
        assert.equal(e.message, expected);
        assert.equal(e.status, 'unsupported');
        return true;
      });
    });
  }
});

test('decode() takes an ArrayBuffer, a Uint8Array, another typed array or a DataView', async () => {
  const file = readFileSync(join(GOLDEN, 'torus.drm'));
  // A copy at an offset inside a larger buffer, so views do not start at 0.
  const big = new ArrayBuffer(file.length + 16);
  new Uint8Array(big, 8, file.length).set(file);
  const exact = big.slice(8, 8 + file.length);
  const reference = await decode(exact);
  const inputs = [new Uint8Array(big, 8, file.length), new DataView(big, 8, file.length), file];
  if (file.length % 2 === 0) inputs.push(new Uint16Array(big, 8, file.length / 2));
  for (const input of inputs) {
    const r = await decode(input);
    assert.deepEqual(r.positions, reference.positions);
    assert.deepEqual(r.indices, reference.indices);
  }
  await assert.rejects(decode('not bytes'), TypeError);
  await assert.rejects(decode(null), TypeError);
});

test('stats name the file\'s sections and their bits per vertex', async () => {
  const r = await decode(readFileSync(join(GOLDEN, 'bunny-lres.drm')));
  const s = r.stats;
  assert.equal(s.vertices, r.positions.length / 3);
  assert.equal(s.faces, r.indices.length / 3);
  assert.equal(s.bytes.total, readFileSync(join(GOLDEN, 'bunny-lres.drm')).length);
  assert.equal(s.bytes.header + s.bytes.connectivity + s.bytes.geometry + s.bytes.vertexOrder + s.bytes.attributes,
    s.bytes.total);
  assert.equal(s.bitsPerVertex.connectivity, (s.bytes.connectivity * 8) / s.vertices);
  assert.equal(s.connectivity, 'ranks');
  assert.ok(['tree', 'refine', 'sorted', 'raw'].includes(s.geometry), s.geometry);
  assert.equal(r.faceRank.length, s.faces);
  assert.equal(s.maxRank, Math.max(...r.faceRank));
});
