// A three.js loader of .drm files, in the shape of three's DRACOLoader:
// decoding runs in a pool of Web Workers (module workers) with the
// WebAssembly decoder, the file's bytes and the decoded arrays are
// transferred between threads rather than copied, and the result is a
// BufferGeometry. Where there are no Web Workers (Node), files decode on
// the calling thread.
//
//   const loader = new DRMLoader().setDecoderPath('/node_modules/drm-decoder/dist/');
//   const geometry = await loader.loadAsync('bunny.drm');
//   loader.setRankColors(true);   // faces coloured by rank, as `drm ranks` draws them
import { FileLoader, Loader, SRGBColorSpace } from 'three';
import { DRMDecodeError, decodeWithModule } from './decode-core.js';
import { createGeometry } from './geometry.js';

export { createGeometry, rankColoredGeometry, faceVertexGeometry } from './geometry.js';
export { RANK_PALETTE, rankBucket, rankColour } from './rank-palette.js';

const DEFAULT_DECODER_URL = new URL('../dist/drm_decoder.js', import.meta.url).href;
const WORKER_URL = new URL('./drm-worker.js', import.meta.url);
const haveWorkers = typeof Worker !== 'undefined' && typeof window !== 'undefined';

export class DRMLoader extends Loader {
  constructor(manager) {
    super(manager);
    this.decoderURL = DEFAULT_DECODER_URL;
    this.workerLimit = Math.max(1, Math.min(4, (typeof navigator !== 'undefined' && navigator.hardwareConcurrency) || 4));
    this.rankColors = false;
    this.vertexColorSpace = SRGBColorSpace;
    this.workerPool = [];
    this.nextTaskID = 1;
    this.localModule = null;
  }

  /** Where the WebAssembly decoder is: a folder (ending in "/") holding
   * drm_decoder.js, or the URL of the file itself. Relative paths resolve
   * against the page. */
  setDecoderPath(path) {
    const file = path.endsWith('/') ? path + 'drm_decoder.js' : path;
    const base = typeof location !== 'undefined' ? location.href : DEFAULT_DECODER_URL;
    this.decoderURL = new URL(file, base).href;
    return this;
  }

  /** How many workers decode at once (default: the cores, at most 4). */
  setWorkerLimit(limit) {
    this.workerLimit = limit;
    return this;
  }

  /** Whether geometries come with faces coloured by rank (non-indexed,
   * a colour per face in the rank palette) where the file has ranks. */
  setRankColors(on) {
    this.rankColors = Boolean(on);
    return this;
  }

  /** The colour space of the files' colours (default sRGB). */
  setVertexColorSpace(colorSpace) {
    this.vertexColorSpace = colorSpace;
    return this;
  }

  load(url, onLoad, onProgress, onError) {
    const loader = new FileLoader(this.manager);
    loader.setPath(this.path);
    loader.setResponseType('arraybuffer');
    loader.setRequestHeader(this.requestHeader);
    loader.setWithCredentials(this.withCredentials);
    loader.load(url, (buffer) => this.parse(buffer, onLoad, onError), onProgress, onError);
  }

  /** Decodes the bytes of a .drm file into a BufferGeometry. An
   * ArrayBuffer (or a view over a whole one) is transferred to the worker:
   * the caller's buffer is detached afterwards. */
  parse(buffer, onLoad, onError = (e) => console.error(e)) {
    this.decodeGeometry(buffer).then(onLoad, onError);
  }

  parseAsync(buffer) {
    return this.decodeGeometry(buffer);
  }

  async decodeGeometry(buffer) {
    const result = await this.decode(buffer);
    return createGeometry(result, { rankColors: this.rankColors, vertexColorSpace: this.vertexColorSpace });
  }

  /** Decodes to the plain result of decode() (typed arrays and stats). */
  decode(buffer) {
    let bytes;
    if (buffer instanceof ArrayBuffer) bytes = new Uint8Array(buffer);
    else if (ArrayBuffer.isView(buffer)) bytes = new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.byteLength);
    else return Promise.reject(new TypeError('DRMLoader: expected an ArrayBuffer or a typed array'));
    if (!haveWorkers) return this._decodeHere(bytes);
    // A view over part of a larger buffer is copied, so the rest of that
    // buffer stays usable; a whole buffer moves to the worker.
    if (bytes.byteOffset !== 0 || bytes.byteLength !== bytes.buffer.byteLength) bytes = bytes.slice();
    return this._decodeInWorker(bytes.buffer);
  }

  /** Starts the workers and their decoders ahead of the first file. */
  preload() {
    if (!haveWorkers) {
      this._module();
      return this;
    }
    while (this.workerPool.length < this.workerLimit) this._spawn();
    return this;
  }

  /** Ends the workers; the loader starts new ones when next used. */
  dispose() {
    for (const w of this.workerPool) {
      w.worker.terminate();
      for (const task of w.tasks.values()) task.reject(new Error('DRMLoader: disposed'));
    }
    this.workerPool.length = 0;
    return this;
  }

  _module() {
    if (!this.localModule || this.localModule.url !== this.decoderURL) {
      this.localModule = { url: this.decoderURL, ready: import(this.decoderURL).then((ns) => ns.default()) };
    }
    return this.localModule.ready;
  }

  async _decodeHere(bytes) {
    const m = await this._module();
    return decodeWithModule(m, bytes);
  }

  _spawn() {
    const worker = new Worker(WORKER_URL, { type: 'module' });
    const entry = { worker, tasks: new Map(), load: 0 };
    worker.onmessage = (event) => {
      const message = event.data;
      const task = entry.tasks.get(message.id);
      if (message.type === 'ready') return;
      if (message.id === 0) {
        // The decoder did not start: fail everything queued on this worker.
        for (const t of entry.tasks.values()) t.reject(new Error(`DRMLoader: the decoder did not start: ${message.message}`));
        entry.tasks.clear();
        return;
      }
      if (!task) return;
      entry.tasks.delete(message.id);
      entry.load -= task.cost;
      if (message.type === 'decode') task.resolve(message.result);
      else task.reject(new DRMDecodeError(message.message, message.status));
    };
    worker.onerror = (event) => {
      for (const t of entry.tasks.values()) t.reject(new Error(`DRMLoader: worker error: ${event.message || event}`));
      entry.tasks.clear();
      entry.load = 0;
    };
    worker.postMessage({ type: 'init', decoderURL: this.decoderURL });
    this.workerPool.push(entry);
    return entry;
  }

  _decodeInWorker(arrayBuffer) {
    // The least loaded worker, counting the bytes it has queued; a new one
    // while the pool is below its limit and every worker is busy.
    let entry = this.workerPool.reduce((best, w) => (!best || w.load < best.load ? w : best), null);
    if (!entry || (entry.load > 0 && this.workerPool.length < this.workerLimit)) entry = this._spawn();
    const id = this.nextTaskID++;
    const cost = arrayBuffer.byteLength;
    return new Promise((resolve, reject) => {
      entry.tasks.set(id, { resolve, reject, cost });
      entry.load += cost;
      entry.worker.postMessage({ type: 'decode', id, buffer: arrayBuffer, byteOffset: 0, byteLength: cost }, [arrayBuffer]);
    });
  }
}
