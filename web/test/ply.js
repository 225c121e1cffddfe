// A reader of the binary little-endian PLY files `drm decode` writes, for
// the tests: each element's scalar properties as typed arrays of the
// property's own type (so float values compare bit for bit), list
// properties as flat arrays with their counts.
import { readFileSync } from 'node:fs';

const TYPES = {
  char: [Int8Array, 1, 'getInt8'], int8: [Int8Array, 1, 'getInt8'],
  uchar: [Uint8Array, 1, 'getUint8'], uint8: [Uint8Array, 1, 'getUint8'],
  short: [Int16Array, 2, 'getInt16'], int16: [Int16Array, 2, 'getInt16'],
  ushort: [Uint16Array, 2, 'getUint16'], uint16: [Uint16Array, 2, 'getUint16'],
  int: [Int32Array, 4, 'getInt32'], int32: [Int32Array, 4, 'getInt32'],
  uint: [Uint32Array, 4, 'getUint32'], uint32: [Uint32Array, 4, 'getUint32'],
  float: [Float32Array, 4, 'getFloat32'], float32: [Float32Array, 4, 'getFloat32'],
  double: [Float64Array, 8, 'getFloat64'], float64: [Float64Array, 8, 'getFloat64'],
};

export function readPly(path) {
  const buf = readFileSync(path);
  const end = buf.indexOf('end_header\n');
  if (end < 0) throw new Error(`${path}: no end_header`);
  const lines = buf.subarray(0, end).toString('latin1').split('\n');
  if (!/^format binary_little_endian 1\.0/.test(lines[1] || '')) throw new Error(`${path}: not binary little-endian`);
  const elements = [];
  const comments = [];
  for (const line of lines) {
    const w = line.trim().split(/\s+/);
    if (w[0] === 'element') elements.push({ name: w[1], count: Number(w[2]), props: [] });
    else if (w[0] === 'property' && w[1] === 'list') elements.at(-1).props.push({ name: w[4], list: true, countType: w[2], type: w[3] });
    else if (w[0] === 'property') elements.at(-1).props.push({ name: w[2], list: false, type: w[1] });
    else if (w[0] === 'comment') comments.push(line.slice(8));
  }
  const dv = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  let off = end + 'end_header\n'.length;
  const out = { comments };
  for (const el of elements) {
    const data = {};
    for (const p of el.props) {
      const [Type] = TYPES[p.type];
      data[p.name] = p.list ? { values: [], counts: new Uint32Array(el.count) } : new Type(el.count);
    }
    for (let i = 0; i < el.count; i++) {
      for (const p of el.props) {
        const [, size, getter] = TYPES[p.type];
        if (p.list) {
          const [, csize, cget] = TYPES[p.countType];
          const n = dv[cget](off, true);
          off += csize;
          data[p.name].counts[i] = n;
          for (let k = 0; k < n; k++, off += size) data[p.name].values.push(dv[getter](off, true));
        } else {
          data[p.name][i] = dv[getter](off, true);
          off += size;
        }
      }
    }
    for (const p of el.props) {
      if (p.list) {
        const [Type] = TYPES[p.type];
        data[p.name].values = Type.from(data[p.name].values);
      }
    }
    out[el.name] = { count: el.count, data };
  }
  if (off !== buf.length) throw new Error(`${path}: ${buf.length - off} bytes after the last element`);
  return out;
}

/** Interleaves per-element scalar columns (x, y, z) into one typed array. */
export function interleave(columns) {
  const n = columns[0].length;
  const out = new columns[0].constructor(n * columns.length);
  for (let i = 0; i < n; i++) for (let c = 0; c < columns.length; c++) out[i * columns.length + c] = columns[c][i];
  return out;
}
