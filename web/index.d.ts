// Types of drm-decoder (src/index.js): decode() of .drm files in
// WebAssembly, for browsers and Node 18+.

/** Anything holding a .drm file's bytes. */
export type DRMInput = ArrayBuffer | SharedArrayBuffer | ArrayBufferView;

/** Figures of a decoded file, as `drm info` gives them. */
export interface DRMStats {
  vertices: number;
  faces: number;
  components: number;
  boundaryEdges: number;
  /** Quantization bits per axis. */
  bits: number;
  weldedVertices: number;
  /** The largest rank code of any face; 0 if the file has no ranks. */
  maxRank: number;
  /** Grid coordinate q of axis k stands for origin[k] + q * step. */
  grid: { origin: [number, number, number]; step: number };
  /** Bytes of the file, whole and per section. */
  bytes: DRMSections;
  /** The same sections in bits per vertex (bytes * 8 / vertices). */
  bitsPerVertex: DRMSections;
  /** Connectivity coder: "ranks" or "topological". */
  connectivity: string;
  /** Geometry coder, as `drm info` names it ("tree", "refine", ...). */
  geometry: string;
}

export interface DRMSections {
  total: number;
  header: number;
  connectivity: number;
  geometry: number;
  vertexOrder: number;
  attributes: number;
}

/** A decoded mesh. Arrays the file does not carry are absent. */
export interface DRMDecoded {
  /** x, y, z per vertex. */
  positions: Float32Array;
  /** Three vertex indices per triangle, counter-clockwise as encoded. */
  indices: Uint32Array;
  /** RGBA per vertex. */
  colors?: Uint8Array;
  /** x, y, z per vertex. */
  normals?: Float32Array;
  /** u, v per vertex. */
  uvs?: Float32Array;
  /** One value per vertex. */
  quality?: Float32Array;
  /** u, v of each corner: 6 per triangle. */
  cornerUvs?: Float32Array;
  /** x, y, z of each corner: 9 per triangle. */
  cornerNormals?: Float32Array;
  /** RGBA per triangle. */
  faceColors?: Uint8Array;
  /** One value per triangle. */
  faceQuality?: Float32Array;
  /** Per triangle: an index into `materials`. */
  faceMaterials?: Uint32Array;
  /** Per triangle: an index into `textures`. */
  faceTextures?: Uint32Array;
  /** Per triangle: the rank code that made it (0: a start triangle); absent for topological connectivity. */
  faceRank?: Uint32Array;
  /** Material names (OBJ usemtl). */
  materials?: string[];
  /** Texture file names. */
  textures?: string[];
  stats: DRMStats;
  /** Milliseconds spent in the decoder on the thread that ran it. */
  decodeMs: number;
}

/** A file that does not decode: `message` is the codec's text (what `drm
 * decode` prints after "cannot decode FILE: "). */
export class DRMDecodeError extends Error {
  name: 'DRMDecodeError';
  /** "corrupt", "unsupported", "invalid input", "out of memory", "internal", ... */
  status: string;
}

/** Decodes a .drm file; rejects with DRMDecodeError if it does not decode. */
export function decode(bytes: DRMInput): Promise<DRMDecoded>;
/** The codec's version, e.g. "0.1.0". */
export function version(): Promise<string>;
/** Instantiates the WebAssembly module ahead of the first decode(). */
export function loadDecoderModule(): Promise<unknown>;
/** A Uint8Array over the input's bytes, without copying. */
export function asBytes(input: DRMInput): Uint8Array;
/** The buffers of a result's arrays, for postMessage's transfer list. */
export function transferablesOf(result: DRMDecoded): ArrayBuffer[];

export interface RankPaletteEntry {
  readonly r: number;
  readonly g: number;
  readonly b: number;
  /** "pale blue-grey" */
  readonly colourName: string;
  /** "rank 1" */
  readonly label: string;
  /** "#b4c0ce" */
  readonly hex: string;
}
/** Buckets: start triangle, ranks 1, 2, 3, 4 and above. */
export const RANK_BUCKET_COUNT: 5;
export const RANK_PALETTE: readonly RankPaletteEntry[];
export function rankBucket(rank: number): number;
export function rankColour(rank: number): RankPaletteEntry;
