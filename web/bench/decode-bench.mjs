// Decode time of drm's WebAssembly decoder against Draco's (npm draco3d,
// its WebAssembly decoder module), in one Node process, on the same meshes.
//
//   node bench/decode-bench.mjs [--runs N] [MESH.ply ...]
//
// Default meshes: bunny, fandisk, horse, crank and venus from DRM_CORPUS
// (default ../shared/meshes beside the clone). Each mesh is encoded with `build/bin/drm encode`
// (defaults: 12 bits per axis) and with `draco_encoder` twice: at its
// defaults (-qp 11 -cl 7) and at drm's precision (-qp 12 -cl 7). Encoded
// files are kept in web/build/bench/. A decode here is the whole job a
// page needs: bytes in, positions (Float32Array) and triangle indices
// (Uint32Array) out as JavaScript arrays. Each decoder runs N times per
// mesh (after warm-up), the decoders alternating run by run; the table
// gives medians, and the last line the median over the meshes of drm's
// time over Draco's.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, statSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';
import { decode, loadDecoderModule } from '../src/index.js';

const require = createRequire(import.meta.url);
const draco3d = require('draco3d');

const WEB = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const ROOT = resolve(WEB, '..');
const DRM = process.env.DRM_CLI || join(ROOT, 'build', 'bin', 'drm');
const DRACO_ENCODER = process.env.DRACO_ENCODER || 'draco_encoder';
const OUT = join(WEB, 'build', 'bench');

const args = process.argv.slice(2);
let runs = 21;
const meshes = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--runs') runs = Number(args[++i]);
  else meshes.push(resolve(args[i]));
}
if (!meshes.length) {
  const corpus = process.env.DRM_CORPUS || join(ROOT, '..', 'shared', 'meshes');
  for (const m of ['bunny', 'fandisk', 'horse', 'crank', 'venus']) meshes.push(join(corpus, `${m}.ply`));
}

function fresh(out, input, tool) {
  return existsSync(out) && statSync(out).mtimeMs >= statSync(input).mtimeMs &&
    (!tool || statSync(out).mtimeMs >= statSync(tool).mtimeMs);
}

function encodeAll(mesh) {
  mkdirSync(OUT, { recursive: true });
  const name = basename(mesh, '.ply');
  const files = { drm: join(OUT, `${name}.drm`), drc: join(OUT, `${name}.drc`), drc12: join(OUT, `${name}-qp12.drc`) };
  if (!fresh(files.drm, mesh, DRM)) execFileSync(DRM, ['encode', mesh, files.drm], { stdio: 'ignore' });
  if (!fresh(files.drc, mesh)) execFileSync(DRACO_ENCODER, ['-i', mesh, '-o', files.drc], { stdio: 'ignore' });
  if (!fresh(files.drc12, mesh)) execFileSync(DRACO_ENCODER, ['-i', mesh, '-o', files.drc12, '-qp', '12', '-cl', '7'], { stdio: 'ignore' });
  return { name, files };
}

// Draco's decode, as three's DRACOLoader does it: the mesh, then positions
// and indices copied out of the module's heap into JavaScript arrays.
function dracoDecode(M, bytes) {
  const decoder = new M.Decoder();
  const buffer = new M.DecoderBuffer();
  const mesh = new M.Mesh();
  try {
    buffer.Init(new Int8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength), bytes.byteLength);
    const status = decoder.DecodeBufferToMesh(buffer, mesh);
    if (!status.ok() || mesh.ptr === 0) throw new Error('draco: ' + status.error_msg());
    const faces = mesh.num_faces();
    const points = mesh.num_points();
    const indexBytes = faces * 3 * 4;
    let ptr = M._malloc(indexBytes);
    decoder.GetTrianglesUInt32Array(mesh, indexBytes, ptr);
    const indices = new Uint32Array(M.HEAPU32.buffer, ptr, faces * 3).slice();
    M._free(ptr);
    const attribute = decoder.GetAttribute(mesh, decoder.GetAttributeId(mesh, M.POSITION));
    const posBytes = points * 3 * 4;
    ptr = M._malloc(posBytes);
    decoder.GetAttributeDataArrayForAllPoints(mesh, attribute, M.DT_FLOAT32, posBytes, ptr);
    const positions = new Float32Array(M.HEAPF32.buffer, ptr, points * 3).slice();
    M._free(ptr);
    return { positions, indices };
  } finally {
    M.destroy(mesh);
    M.destroy(buffer);
    M.destroy(decoder);
  }
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[s.length >> 1] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

async function main() {
  let t0 = performance.now();
  await loadDecoderModule();
  const drmInit = performance.now() - t0;
  t0 = performance.now();
  const M = await draco3d.createDecoderModule({});
  const dracoInit = performance.now() - t0;

  const rows = [];
  for (const mesh of meshes) {
    const { name, files } = encodeAll(mesh);
    const bytes = { drm: readFileSync(files.drm), drc: readFileSync(files.drc), drc12: readFileSync(files.drc12) };
    const coders = {
      drm: () => decode(bytes.drm),
      drc: async () => dracoDecode(M, bytes.drc),
      drc12: async () => dracoDecode(M, bytes.drc12),
    };
    const reference = await coders.drm();
    for (const k of ['drc', 'drc12']) {
      const r = await coders[k]();
      if (r.indices.length !== reference.indices.length) throw new Error(`${name}: draco decodes ${r.indices.length / 3} faces, drm ${reference.indices.length / 3}`);
    }
    const times = { drm: [], drc: [], drc12: [] };
    for (let w = 0; w < 3; w++) for (const k of Object.keys(coders)) await coders[k]();
    for (let i = 0; i < runs; i++) {
      // Alternate the order, so no decoder always follows the same one.
      const order = i % 2 ? ['drc12', 'drc', 'drm'] : ['drm', 'drc', 'drc12'];
      for (const k of order) {
        const t = performance.now();
        await coders[k]();
        times[k].push(performance.now() - t);
      }
    }
    rows.push({
      name, vertices: reference.stats.vertices, faces: reference.stats.faces,
      bytes: { drm: bytes.drm.length, drc: bytes.drc.length, drc12: bytes.drc12.length },
      ms: { drm: median(times.drm), drc: median(times.drc), drc12: median(times.drc12) },
    });
  }

  const pad = (s, n) => String(s).padStart(n);
  console.log(`node ${process.version}, ${runs} runs per decoder and mesh, medians; module start-up: drm ${drmInit.toFixed(1)} ms, draco3d ${dracoInit.toFixed(1)} ms`);
  console.log('draco = draco_encoder defaults (-qp 11 -cl 7); draco12 = -qp 12 -cl 7 (drm encodes at 12 bits)');
  console.log(['mesh'.padEnd(10), pad('V', 7), pad('F', 7), pad('drm B', 8), pad('draco B', 8), pad('draco12 B', 9),
    pad('drm ms', 8), pad('draco ms', 9), pad('draco12 ms', 10), pad('drm/draco', 9), pad('drm/draco12', 11)].join(' '));
  const ratios = [];
  const ratios12 = [];
  for (const r of rows) {
    const ratio = r.ms.drm / r.ms.drc;
    const ratio12 = r.ms.drm / r.ms.drc12;
    ratios.push(ratio);
    ratios12.push(ratio12);
    console.log([r.name.padEnd(10), pad(r.vertices, 7), pad(r.faces, 7), pad(r.bytes.drm, 8), pad(r.bytes.drc, 8),
      pad(r.bytes.drc12, 9), pad(r.ms.drm.toFixed(2), 8), pad(r.ms.drc.toFixed(2), 9), pad(r.ms.drc12.toFixed(2), 10),
      pad(ratio.toFixed(2), 9), pad(ratio12.toFixed(2), 11)].join(' '));
  }
  console.log(`median drm/draco time: ${median(ratios).toFixed(2)} (draco defaults), ${median(ratios12).toFixed(2)} (draco -qp 12)`);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
