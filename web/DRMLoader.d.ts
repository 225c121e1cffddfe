// Types of drm-decoder/DRMLoader.js: a three.js loader of .drm files.
import { BufferGeometry, ColorSpace, Loader, LoadingManager } from 'three';
import { DRMDecoded } from './index.js';

export { RANK_PALETTE, rankBucket, rankColour } from './index.js';

export interface GeometryOptions {
  /** Faces coloured by rank where the file has ranks (non-indexed geometry). */
  rankColors?: boolean;
  /** Colour space of the file's colours (default sRGB). */
  vertexColorSpace?: ColorSpace;
}

export class DRMLoader extends Loader<BufferGeometry> {
  constructor(manager?: LoadingManager);
  /** A folder ending in "/" holding drm_decoder.js, or the file's URL. */
  setDecoderPath(path: string): this;
  setWorkerLimit(limit: number): this;
  setRankColors(on: boolean): this;
  setVertexColorSpace(colorSpace: ColorSpace): this;
  load(url: string, onLoad: (geometry: BufferGeometry) => void, onProgress?: (event: ProgressEvent) => void,
    onError?: (error: unknown) => void): void;
  /** An ArrayBuffer given here is transferred to a worker (detached). */
  parse(buffer: ArrayBuffer | ArrayBufferView, onLoad: (geometry: BufferGeometry) => void, onError?: (error: unknown) => void): void;
  parseAsync(buffer: ArrayBuffer | ArrayBufferView): Promise<BufferGeometry>;
  decodeGeometry(buffer: ArrayBuffer | ArrayBufferView): Promise<BufferGeometry>;
  /** The plain decode() result, decoded in a worker. */
  decode(buffer: ArrayBuffer | ArrayBufferView): Promise<DRMDecoded>;
  preload(): this;
  dispose(): this;
}

/** Indexed geometry, or non-indexed where the file has per-face or per-corner values. */
export function createGeometry(result: DRMDecoded, options?: GeometryOptions): BufferGeometry;
/** Non-indexed geometry with each face coloured by its rank. */
export function rankColoredGeometry(result: DRMDecoded, options?: GeometryOptions): BufferGeometry;
/** Non-indexed geometry, three vertices per triangle. */
export function faceVertexGeometry(result: DRMDecoded,
  options?: { colours?: 'file' | 'rank'; vertexColorSpace?: ColorSpace }): BufferGeometry;
