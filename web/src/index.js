// drm's decoder for JavaScript: decode(bytes) turns a .drm file into typed
// arrays, in browsers (main thread or workers) and in Node 18+, with the
// codec compiled to WebAssembly (dist/drm_decoder.js, its .wasm embedded).
// The module is instantiated on the first call and reused.
import { decodeWithModule, DRMDecodeError, asBytes, transferablesOf } from './decode-core.js';

export { DRMDecodeError, asBytes, transferablesOf };
export { RANK_PALETTE, RANK_BUCKET_COUNT, rankBucket, rankColour } from './rank-palette.js';

let modulePromise = null;

/** The instantiated WebAssembly module (loaded on first use). */
export function loadDecoderModule() {
  if (!modulePromise) {
    modulePromise = import('../dist/drm_decoder.js').then((ns) => ns.default());
    modulePromise.catch(() => { modulePromise = null; });
  }
  return modulePromise;
}

/** Decodes a .drm file held in memory (ArrayBuffer, Uint8Array or any
 * typed array or DataView over its bytes). Resolves to
 * {positions, indices, stats, ...the attributes the file carries};
 * rejects with a DRMDecodeError whose message is the codec's. */
export async function decode(bytes) {
  const view = asBytes(bytes);
  const m = await loadDecoderModule();
  return decodeWithModule(m, view);
}

/** The codec's version, e.g. "0.1.0". */
export async function version() {
  const m = await loadDecoderModule();
  return m.UTF8ToString(m._drmcodec_version());
}
