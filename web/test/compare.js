// Holds a decode() result to the PLY file `drm decode` wrote for the same
// .drm file: positions and every float attribute bit for bit, triangles
// and colours exactly.
import assert from 'node:assert/strict';
import { readPly, interleave } from './ply.js';

function sameBits(actual, expected, what) {
  assert.ok(actual, `${what}: missing from the decode() result`);
  assert.equal(actual.length, expected.length, `${what}: ${actual.length} values, the CLI wrote ${expected.length}`);
  const a = Buffer.from(actual.buffer, actual.byteOffset, actual.byteLength);
  const e = Buffer.from(expected.buffer, expected.byteOffset, expected.byteLength);
  if (a.equals(e)) return;
  const bytes = actual.BYTES_PER_ELEMENT;
  let i = 0;
  while (a.compare(e, i * bytes, (i + 1) * bytes, i * bytes, (i + 1) * bytes) === 0) i++;
  assert.fail(`${what}: value ${i} is ${actual[i]}, the CLI wrote ${expected[i]}`);
}

export function compareWithPly(result, plyPath) {
  const ply = readPly(plyPath);
  const v = ply.vertex.data;
  const f = ply.face.data;
  sameBits(result.positions, interleave([v.x, v.y, v.z]), 'positions');
  const tri = f.vertex_indices;
  assert.ok(tri.counts.every((c) => c === 3), 'the CLI wrote a face that is not a triangle');
  sameBits(result.indices, Uint32Array.from(tri.values), 'triangles');
  assert.equal(result.stats.vertices, ply.vertex.count);
  assert.equal(result.stats.faces, ply.face.count);
  // Attributes: present in one exactly when present in the other.
  const check = (key, expected) => {
    if (expected) sameBits(result[key], expected, key);
    else assert.equal(result[key], undefined, `${key}: decode() has it, the CLI wrote none`);
  };
  check('normals', v.nx && interleave([v.nx, v.ny, v.nz]));
  check('colors', v.red && interleave([v.red, v.green, v.blue, v.alpha]));
  check('quality', v.quality);
  check('uvs', v.texture_u && interleave([v.texture_u, v.texture_v]));
  check('cornerUvs', f.texcoord && f.texcoord.values);
  check('faceTextures', f.texnumber && Uint32Array.from(f.texnumber));
  check('faceColors', f.red && interleave([f.red, f.green, f.blue, f.alpha]));
  check('faceQuality', f.quality);
  const textures = ply.comments.filter((c) => c.startsWith('TextureFile ')).map((c) => c.slice(12));
  assert.deepEqual(result.textures || [], textures, 'texture names');
}
