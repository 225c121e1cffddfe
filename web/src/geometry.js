// three.js geometry from a decode() result: an indexed BufferGeometry of
// the file's vertices, or, where values belong to faces or corners (face
// colours, per-corner texture coordinates or normals, rank colours), a
// non-indexed one with three vertices of its own per triangle.
import { BufferAttribute, BufferGeometry, Color, SRGBColorSpace } from 'three';
import { rankColour } from './rank-palette.js';

const _colour = new Color();

// Colours as three's working (linear) colour space wants them, converted
// from `colorSpace` (the file's vertex colours are sRGB, as PLY viewers
// show them); RGBA bytes in, RGB floats out.
function linearColours(rgba, colorSpace) {
  const n = rgba.length / 4;
  const out = new Float32Array(n * 3);
  for (let i = 0; i < n; i++) {
    _colour.setRGB(rgba[4 * i] / 255, rgba[4 * i + 1] / 255, rgba[4 * i + 2] / 255, colorSpace);
    out[3 * i] = _colour.r;
    out[3 * i + 1] = _colour.g;
    out[3 * i + 2] = _colour.b;
  }
  return out;
}

// The rank palette in the working colour space, one RGB triple per bucket.
function rankTable() {
  const table = new Float32Array(5 * 3);
  for (let b = 0; b < 5; b++) {
    const e = rankColour(b);
    _colour.setRGB(e.r / 255, e.g / 255, e.b / 255, SRGBColorSpace);
    table.set([_colour.r, _colour.g, _colour.b], 3 * b);
  }
  return table;
}

// Groups of consecutive faces with the same material, so a multi-material
// mesh takes an array of materials (materialIndex = the file's material).
function addMaterialGroups(geometry, faceMaterials) {
  if (!faceMaterials) return;
  let start = 0;
  for (let f = 1; f <= faceMaterials.length; f++) {
    if (f === faceMaterials.length || faceMaterials[f] !== faceMaterials[start]) {
      geometry.addGroup(3 * start, 3 * (f - start), faceMaterials[start]);
      start = f;
    }
  }
}

function userDataOf(result) {
  const data = { stats: result.stats };
  for (const k of ['faceRank', 'quality', 'faceQuality', 'faceMaterials', 'faceTextures', 'materials', 'textures']) {
    if (result[k] !== undefined) data[k] = result[k];
  }
  return data;
}

/** Whether the result carries values per face or per corner, which an
 * indexed geometry cannot hold. */
export function needsFaceVertices(result) {
  return Boolean(result.faceColors || result.cornerUvs || result.cornerNormals);
}

/** A non-indexed geometry, three vertices per triangle: positions, normals
 * (per corner where the file has them, else per vertex), uvs likewise,
 * and colours: by rank when `colours` is 'rank', else the file's face
 * colours, else its vertex colours. */
export function faceVertexGeometry(result, { colours = 'file', vertexColorSpace = SRGBColorSpace } = {}) {
  const idx = result.indices;
  const corners = idx.length;
  const faces = corners / 3;
  const positions = new Float32Array(corners * 3);
  const p = result.positions;
  for (let c = 0; c < corners; c++) {
    const v = idx[c] * 3;
    positions[3 * c] = p[v];
    positions[3 * c + 1] = p[v + 1];
    positions[3 * c + 2] = p[v + 2];
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  if (result.cornerNormals) {
    geometry.setAttribute('normal', new BufferAttribute(result.cornerNormals.slice(), 3));
  } else if (result.normals) {
    const normals = new Float32Array(corners * 3);
    for (let c = 0; c < corners; c++) normals.set(result.normals.subarray(3 * idx[c], 3 * idx[c] + 3), 3 * c);
    geometry.setAttribute('normal', new BufferAttribute(normals, 3));
  }
  if (result.cornerUvs) {
    geometry.setAttribute('uv', new BufferAttribute(result.cornerUvs.slice(), 2));
  } else if (result.uvs) {
    const uvs = new Float32Array(corners * 2);
    for (let c = 0; c < corners; c++) {
      uvs[2 * c] = result.uvs[2 * idx[c]];
      uvs[2 * c + 1] = result.uvs[2 * idx[c] + 1];
    }
    geometry.setAttribute('uv', new BufferAttribute(uvs, 2));
  }
  let colours3 = null;
  if (colours === 'rank' && result.faceRank) {
    const table = rankTable();
    colours3 = new Float32Array(corners * 3);
    for (let f = 0; f < faces; f++) {
      const b = 3 * Math.min(result.faceRank[f], 4);
      for (let k = 0; k < 3; k++) colours3.set(table.subarray(b, b + 3), 9 * f + 3 * k);
    }
  } else if (result.faceColors) {
    const perFace = linearColours(result.faceColors, vertexColorSpace);
    colours3 = new Float32Array(corners * 3);
    for (let f = 0; f < faces; f++) for (let k = 0; k < 3; k++) colours3.set(perFace.subarray(3 * f, 3 * f + 3), 9 * f + 3 * k);
  } else if (result.colors) {
    const perVertex = linearColours(result.colors, vertexColorSpace);
    colours3 = new Float32Array(corners * 3);
    for (let c = 0; c < corners; c++) colours3.set(perVertex.subarray(3 * idx[c], 3 * idx[c] + 3), 3 * c);
  }
  if (colours3) geometry.setAttribute('color', new BufferAttribute(colours3, 3));
  addMaterialGroups(geometry, result.faceMaterials);
  geometry.userData = userDataOf(result);
  return geometry;
}

/** The mesh with each face coloured by the rank code that made it, in the
 * palette of `drm ranks` and the MeshLab rank filter (RANK_PALETTE). A
 * file without ranks (topological connectivity) gets the file's colours. */
export function rankColoredGeometry(result, options = {}) {
  return faceVertexGeometry(result, { ...options, colours: 'rank' });
}

/** The geometry of a decode() result: indexed (position, index, and
 * normal, color, uv where the file has them per vertex) unless the file
 * has values per face or corner; then as faceVertexGeometry. */
export function createGeometry(result, { rankColors = false, vertexColorSpace = SRGBColorSpace } = {}) {
  if (rankColors && result.faceRank) return rankColoredGeometry(result, { vertexColorSpace });
  if (needsFaceVertices(result)) return faceVertexGeometry(result, { vertexColorSpace });
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(result.positions, 3));
  geometry.setIndex(new BufferAttribute(result.indices, 1));
  if (result.normals) geometry.setAttribute('normal', new BufferAttribute(result.normals, 3));
  if (result.uvs) geometry.setAttribute('uv', new BufferAttribute(result.uvs, 2));
  if (result.colors) geometry.setAttribute('color', new BufferAttribute(linearColours(result.colors, vertexColorSpace), 3));
  addMaterialGroups(geometry, result.faceMaterials);
  geometry.userData = userDataOf(result);
  return geometry;
}
