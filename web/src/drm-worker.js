// The decoding worker of DRMLoader (a module worker): it instantiates the
// WebAssembly decoder from the URL the loader gives, then decodes the
// buffers it is sent and sends the arrays back, transferred, not copied.
import { decodeWithModule, transferablesOf } from './decode-core.js';

let ready = null;

self.onmessage = async (event) => {
  const message = event.data;
  if (message.type === 'init') {
    ready = import(message.decoderURL).then((ns) => ns.default());
    ready.then(() => self.postMessage({ type: 'ready' }),
      (e) => self.postMessage({ type: 'error', id: 0, message: String(e && e.message || e), status: 'internal' }));
    return;
  }
  if (message.type === 'decode') {
    try {
      const m = await ready;
      const result = decodeWithModule(m, new Uint8Array(message.buffer, message.byteOffset, message.byteLength));
      self.postMessage({ type: 'decode', id: message.id, result }, transferablesOf(result));
    } catch (e) {
      self.postMessage({ type: 'error', id: message.id, message: e.message, status: e.status || 'internal' });
    }
  }
};
