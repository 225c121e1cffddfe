// Damaged files: golden files cut short or with bytes flipped are refused
// with the message `drm decode` prints for the same bytes (or, where the
// CLI decodes them, give the CLI's mesh); none hangs the decoder.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { decode, DRMDecodeError } from '../src/index.js';
import { ROOT, WORK, haveCli, cliDecodeError, cliDecode } from './cli.js';
import { compareWithPly } from './compare.js';

const GOLDEN = join(ROOT, 'tests', 'golden');
const skip = haveCli() ? false : 'build/bin/drm is not built';
const dir = join(WORK, 'corrupt');

// A small deterministic generator (xorshift32), so failures repeat.
function generator(seed) {
  let s = seed >>> 0 || 1;
  return () => {
    s ^= s << 13; s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5; s >>>= 0;
    return s;
  };
}

function damaged(name) {
  const bytes = readFileSync(join(GOLDEN, `${name}.drm`));
  const cases = [];
  for (const n of [0, 1, 7, 8, 12, 40, bytes.length >> 2, bytes.length >> 1, bytes.length - 4, bytes.length - 1]) {
    cases.push({ label: `${name} cut to ${n} bytes`, bytes: bytes.subarray(0, n) });
  }
  const next = generator(bytes.length);
  for (let k = 0; k < 12; k++) {
    const copy = Buffer.from(bytes);
    const at = next() % copy.length;
    copy[at] ^= 1 << (next() % 8);
    cases.push({ label: `${name} with a bit of byte ${at} flipped`, bytes: copy });
  }
  const tail = Buffer.concat([bytes, Buffer.from([0, 1, 2, 3])]);
  cases.push({ label: `${name} with 4 bytes appended`, bytes: tail });
  return cases;
}

for (const name of ['torus', 'bunny-lres', 'nefertiti-refine', 'tray-bottom-topological', 'star-raw']) {
  test(`damaged ${name}.drm is refused as the CLI refuses it`, { skip, timeout: 60000 }, async (t) => {
    mkdirSync(dir, { recursive: true });
    for (const c of damaged(name)) {
      await t.test(c.label, async () => {
        const file = join(dir, 'damaged.drm');
        writeFileSync(file, c.bytes);
        const expected = cliDecodeError(file);
        if (expected === null) {
          // The CLI accepts these bytes: decode() gives the same mesh.
          const ply = join(dir, 'damaged.ply');
          assert.ok(cliDecode(file, ply).ok);
          compareWithPly(await decode(c.bytes), ply);
          return;
        }
        await assert.rejects(decode(c.bytes), (e) => {
          assert.ok(e instanceof DRMDecodeError, String(e));
          assert.equal(e.message, expected);
          return true;
        });
      });
    }
  });
}

test('the decoder still works after refusing files', async () => {
  const r = await decode(readFileSync(join(GOLDEN, 'torus.drm')));
  assert.equal(r.stats.vertices, r.positions.length / 3);
  assert.ok(r.stats.vertices > 0);
});
