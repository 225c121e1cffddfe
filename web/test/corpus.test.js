// Corpus meshes, encoded with `drm encode` at its defaults, decode to what
// `drm decode` writes, bit for bit. The meshes: DRM_CORPUS (a folder of
// .ply files; default ../shared/meshes beside the clone), the project's test
// meshes in tests/data, and the attribute meshes (colours, normals,
// texture coordinates, materials) in tests/data/attributes and
// DRM_ATTRIBUTE_CORPUS (default ../shared/meshes-attributes beside the clone).
// Encoded files are kept under web/build/test/ until a mesh or the drm
// binary changes.
import { test } from 'node:test';
import { readFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { decode } from '../src/index.js';
import { ROOT, haveCli, encodeAndDecode, listFiles } from './cli.js';
import { compareWithPly } from './compare.js';

const skip = haveCli() ? false : 'build/bin/drm is not built';

function folder(envName, fallback) {
  const dir = process.env[envName] || fallback;
  return dir && existsSync(dir) ? dir : null;
}

function meshesIn(dir, exts = ['.ply']) {
  return exts.flatMap((e) => listFiles(dir, e));
}

async function checkAll(t, meshes, cacheName) {
  for (const f of encodeAndDecode(meshes, cacheName)) {
    await t.test(f.name, async () => compareWithPly(await decode(readFileSync(f.drm)), f.ply));
  }
}

test('tests/data meshes decode as drm decode writes them', { skip, timeout: 300000 }, async (t) => {
  await checkAll(t, meshesIn(join(ROOT, 'tests', 'data')), 'data');
});

test('attribute meshes decode as drm decode writes them', { skip, timeout: 300000 }, async (t) => {
  const dirs = [join(ROOT, 'tests', 'data', 'attributes'), folder('DRM_ATTRIBUTE_CORPUS', join(ROOT, '..', 'shared', 'meshes-attributes'))];
  for (const [i, dir] of dirs.entries()) {
    if (dir) await checkAll(t, meshesIn(dir, ['.ply', '.obj']), `attributes-${i}`);
  }
});

const corpus = folder('DRM_CORPUS', join(ROOT, '..', 'shared', 'meshes'));
test('corpus meshes decode as drm decode writes them', { skip: skip || (!corpus && 'no corpus: set DRM_CORPUS'), timeout: 900000 },
  async (t) => {
    await checkAll(t, meshesIn(corpus), 'corpus');
  });
