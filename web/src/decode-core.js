// decode() on an instantiated emscripten module of the codec
// (dist/drm_decoder.js): the bytes go into the module's memory, the C API
// (codec/include/drmcodec/drmcodec_c.h) decodes them on the calling thread,
// and every array comes back as a typed array of its own (a copy out of the
// module's memory, so it outlives the next decode and can be transferred
// to another thread without a further copy).

// enum drmcodec_array
const POSITIONS = 0, TRIANGLES = 1, COLORS = 2, NORMALS = 3, TEXCOORDS = 4, QUALITY = 5,
  CORNER_TEXCOORDS = 6, CORNER_NORMALS = 7, FACE_COLORS = 8, FACE_QUALITY = 9, FACE_MATERIAL = 10,
  FACE_TEXTURE = 11, FACE_RANK = 12;
// enum drmcodec_names
const MATERIAL_NAMES = 0, TEXTURE_NAMES = 1;
// enum drmcodec_stat
const S = {
  VERTICES: 0, FACES: 1, COMPONENTS: 2, BOUNDARY_EDGES: 3, BITS: 4, TOTAL_BYTES: 5, HEADER_BYTES: 6,
  CONNECTIVITY_BYTES: 7, GEOMETRY_BYTES: 8, VERTEX_ORDER_BYTES: 9, ATTRIBUTE_BYTES: 10, WELDED_VERTICES: 11,
  GRID_ORIGIN_X: 12, GRID_ORIGIN_Y: 13, GRID_ORIGIN_Z: 14, GRID_STEP: 15, MAX_RANK: 16,
};

/** Why a file does not decode: `message` is the codec's own text, the one
 * `drm decode` prints after "cannot decode FILE: "; `status` is the C API's
 * status name ("corrupt", "unsupported", "invalid input", ...). */
export class DRMDecodeError extends Error {
  constructor(message, status) {
    super(message);
    this.name = 'DRMDecodeError';
    this.status = status;
  }
}

/** A Uint8Array over the bytes of an ArrayBuffer, SharedArrayBuffer,
 * typed array or DataView, without copying. */
export function asBytes(input) {
  if (input instanceof Uint8Array) return input;
  if (ArrayBuffer.isView(input)) return new Uint8Array(input.buffer, input.byteOffset, input.byteLength);
  if (input instanceof ArrayBuffer || (typeof SharedArrayBuffer !== 'undefined' && input instanceof SharedArrayBuffer)) {
    return new Uint8Array(input);
  }
  throw new TypeError('decode: expected an ArrayBuffer, a typed array or a DataView, got ' +
    (input === null ? 'null' : typeof input));
}

function copyArray(m, handle, array, Type) {
  const countPtr = m._malloc(4);
  try {
    const ptr = m._drmcodec_decoded_array(handle, array, countPtr);
    const count = m.HEAPU32[countPtr >> 2];
    if (!ptr || !count) return undefined;
    return new Type(m.HEAPU8.buffer, ptr, count).slice();
  } finally {
    m._free(countPtr);
  }
}

function names(m, handle, list) {
  const n = m._drmcodec_decoded_name_count(handle, list);
  const out = [];
  for (let i = 0; i < n; i++) out.push(m.UTF8ToString(m._drmcodec_decoded_name(handle, list, i)));
  return out;
}

function bitsPer(bytes, vertices) {
  return vertices > 0 ? (bytes * 8) / vertices : 0;
}

function readStats(m, handle) {
  const stat = (s) => m._drmcodec_decoded_stat(handle, s);
  const vertices = stat(S.VERTICES);
  const bytes = {
    total: stat(S.TOTAL_BYTES),
    header: stat(S.HEADER_BYTES),
    connectivity: stat(S.CONNECTIVITY_BYTES),
    geometry: stat(S.GEOMETRY_BYTES),
    vertexOrder: stat(S.VERTEX_ORDER_BYTES),
    attributes: stat(S.ATTRIBUTE_BYTES),
  };
  const bitsPerVertex = {};
  for (const k of Object.keys(bytes)) bitsPerVertex[k] = bitsPer(bytes[k], vertices);
  return {
    vertices,
    faces: stat(S.FACES),
    components: stat(S.COMPONENTS),
    boundaryEdges: stat(S.BOUNDARY_EDGES),
    bits: stat(S.BITS),
    weldedVertices: stat(S.WELDED_VERTICES),
    maxRank: stat(S.MAX_RANK),
    grid: { origin: [stat(S.GRID_ORIGIN_X), stat(S.GRID_ORIGIN_Y), stat(S.GRID_ORIGIN_Z)], step: stat(S.GRID_STEP) },
    bytes,
    bitsPerVertex,
    connectivity: m.UTF8ToString(m._drmcodec_decoded_connectivity(handle)),
    geometry: m.UTF8ToString(m._drmcodec_decoded_geometry(handle)),
  };
}

/** Decodes the .drm file `input` with the instantiated module `m`; throws
 * DRMDecodeError when the file does not decode. */
export function decodeWithModule(m, input) {
  const bytes = asBytes(input);
  const size = bytes.byteLength;
  const start = typeof performance !== 'undefined' ? performance.now() : Date.now();
  const data = m._malloc(Math.max(size, 1));
  if (!data) throw new DRMDecodeError('out of memory', 'out of memory');
  let handle = 0;
  try {
    m.HEAPU8.set(bytes, data);
    handle = m._drmcodec_decode(data, size, 1);
  } finally {
    m._free(data);
  }
  if (!handle) throw new DRMDecodeError('out of memory', 'out of memory');
  try {
    const status = m._drmcodec_decoded_status(handle);
    if (status !== 0) {
      throw new DRMDecodeError(m.UTF8ToString(m._drmcodec_decoded_error(handle)),
        m.UTF8ToString(m._drmcodec_status_name(status)));
    }
    const result = {
      positions: copyArray(m, handle, POSITIONS, Float32Array) || new Float32Array(0),
      indices: copyArray(m, handle, TRIANGLES, Uint32Array) || new Uint32Array(0),
    };
    const optional = {
      colors: copyArray(m, handle, COLORS, Uint8Array),
      normals: copyArray(m, handle, NORMALS, Float32Array),
      uvs: copyArray(m, handle, TEXCOORDS, Float32Array),
      quality: copyArray(m, handle, QUALITY, Float32Array),
      cornerUvs: copyArray(m, handle, CORNER_TEXCOORDS, Float32Array),
      cornerNormals: copyArray(m, handle, CORNER_NORMALS, Float32Array),
      faceColors: copyArray(m, handle, FACE_COLORS, Uint8Array),
      faceQuality: copyArray(m, handle, FACE_QUALITY, Float32Array),
      faceMaterials: copyArray(m, handle, FACE_MATERIAL, Uint32Array),
      faceTextures: copyArray(m, handle, FACE_TEXTURE, Uint32Array),
      faceRank: copyArray(m, handle, FACE_RANK, Uint32Array),
    };
    for (const [k, v] of Object.entries(optional)) if (v) result[k] = v;
    const materials = names(m, handle, MATERIAL_NAMES);
    const textures = names(m, handle, TEXTURE_NAMES);
    if (materials.length) result.materials = materials;
    if (textures.length) result.textures = textures;
    result.stats = readStats(m, handle);
    // Milliseconds in the decoder on the thread that ran it (a worker's,
    // for DRMLoader): bytes in, arrays out; no fetch, no geometry.
    result.decodeMs = (typeof performance !== 'undefined' ? performance.now() : Date.now()) - start;
    return result;
  } finally {
    m._drmcodec_decoded_free(handle);
  }
}

/** The typed arrays' buffers of a decode() result, for postMessage's
 * transfer list. */
export function transferablesOf(result) {
  const out = [];
  for (const v of Object.values(result)) if (ArrayBuffer.isView(v)) out.push(v.buffer);
  return out;
}
