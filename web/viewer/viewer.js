// The drm viewer: opens a .drm file (file picker, drop, or ?file=URL),
// decodes it with DRMLoader's worker pool and shows it with orbit
// controls, its figures (vertices, faces, bits per vertex per section,
// decode time) and, on request, faces coloured by rank with a legend.
// `window.drmViewer` exposes the state for the browser test.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { DRMLoader, createGeometry, RANK_PALETTE, rankBucket } from '../src/DRMLoader.js';

const params = new URLSearchParams(location.search);
const view = document.getElementById('view');
const statusLine = document.getElementById('status');
const ranksBox = document.getElementById('ranks');
const legend = document.getElementById('legend');
const statsTable = document.getElementById('stats');

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
view.appendChild(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xeef0f3);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8d8d, 2.0));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
scene.add(sun);
const camera = new THREE.PerspectiveCamera(40, window.innerWidth / window.innerHeight, 0.01, 100);
// ?up=-y (or x, -x, z, -z): the model's up axis, for meshes not stored y up.
const UP = { x: [1, 0, 0], '-x': [-1, 0, 0], y: [0, 1, 0], '-y': [0, -1, 0], z: [0, 0, 1], '-z': [0, 0, -1] };
camera.up.fromArray(UP[params.get('up')] || UP.y);
camera.add(sun);
sun.position.set(1, 2, 3);
scene.add(camera);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = true;

const loader = new DRMLoader();
if (params.get('decoder')) loader.setDecoderPath(params.get('decoder'));
loader.preload();

const state = (window.drmViewer = {
  status: 'idle', error: null, stats: null, decodeMs: null, rankColors: false, frames: 0, buckets: null,
  setRankColors: (on) => setRankColors(on),
  load: (url) => loadURL(url),
});

let mesh = null;
let decoded = null;  // the last decode() result, kept to rebuild the geometry
const materials = {
  plain: new THREE.MeshStandardMaterial({ color: 0xc9ccd1, roughness: 0.75, metalness: 0, side: THREE.DoubleSide }),
  coloured: new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.75, metalness: 0, side: THREE.DoubleSide }),
  ranks: new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.9, metalness: 0, flatShading: true, side: THREE.DoubleSide }),
};

function setStatus(text, isError = false) {
  statusLine.textContent = text;
  statusLine.className = isError ? 'error' : '';
}

function fmt(n, digits = 0) {
  return Number(n).toLocaleString('en-US', { minimumFractionDigits: digits, maximumFractionDigits: digits });
}

function showStats(s, name, decodeMs) {
  const bpv = s.bitsPerVertex;
  const rows = [
    ['file', name],
    ['vertices', fmt(s.vertices)],
    ['faces', fmt(s.faces)],
    ['bytes', fmt(s.bytes.total)],
    ['quantization', `${s.bits} bits per axis`],
    ['connectivity coder', s.connectivity],
    ['geometry coder', s.geometry],
    ['connectivity bits/vertex', fmt(bpv.connectivity, 3)],
    ['geometry bits/vertex', fmt(bpv.geometry, 3)],
  ];
  if (s.bytes.vertexOrder) rows.push(['vertex order bits/vertex', fmt(bpv.vertexOrder, 3)]);
  if (s.bytes.attributes) rows.push(['attribute bits/vertex', fmt(bpv.attributes, 3)]);
  rows.push(['total bits/vertex', fmt(bpv.total, 3)], ['decode time', `${fmt(decodeMs, 1)} ms`]);
  if (decoded.decodeMs !== undefined) rows.push(['of which in the decoder', `${fmt(decoded.decodeMs, 1)} ms`]);
  statsTable.replaceChildren(...rows.map(([k, v]) => {
    const tr = document.createElement('tr');
    for (const text of [k, v]) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.appendChild(td);
    }
    return tr;
  }));
}

function showLegend() {
  const counts = new Array(RANK_PALETTE.length).fill(0);
  if (decoded && decoded.faceRank) for (const r of decoded.faceRank) counts[rankBucket(r)]++;
  state.buckets = counts;
  legend.hidden = !state.rankColors;
  if (!decoded || !decoded.faceRank) {
    legend.textContent = state.rankColors ? 'this file has no ranks (topological connectivity)' : '';
    return;
  }
  legend.replaceChildren(...RANK_PALETTE.map((e, b) => {
    const row = document.createElement('div');
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = e.hex;
    const label = document.createElement('span');
    label.textContent = `${e.label} (${e.colourName})`;
    const count = document.createElement('span');
    count.className = 'count';
    count.textContent = `${fmt(counts[b])} faces`;
    row.append(swatch, label, count);
    return row;
  }));
}

function rebuild() {
  if (!decoded) return;
  const geometry = createGeometry(decoded, { rankColors: state.rankColors });
  if (!geometry.getAttribute('normal')) geometry.computeVertexNormals();
  const ranked = state.rankColors && decoded.faceRank;
  const material = ranked ? materials.ranks : geometry.getAttribute('color') ? materials.coloured : materials.plain;
  if (mesh) {
    mesh.geometry.dispose();
    mesh.geometry = geometry;
    mesh.material = material;
  } else {
    mesh = new THREE.Mesh(geometry, material);
    scene.add(mesh);
  }
  showLegend();
}

function frame(geometry) {
  geometry.computeBoundingSphere();
  const { center, radius } = geometry.boundingSphere;
  const r = radius > 0 ? radius : 1;
  controls.target.copy(center);
  camera.near = r / 100;
  camera.far = r * 100;
  // Looking from the front (+z, or the axis after the up axis), a little
  // from the right and above.
  const up = camera.up.clone();
  const front = Math.abs(up.z) > 0.5 ? new THREE.Vector3(0, -Math.sign(up.z), 0) : new THREE.Vector3(0, 0, 1);
  const right = new THREE.Vector3().crossVectors(up, front);
  const eye = front.multiplyScalar(1).add(right.multiplyScalar(0.35)).add(up.multiplyScalar(0.3)).normalize();
  camera.position.copy(center).add(eye.multiplyScalar(r * 2.9));
  fitView();
  controls.update();
}

async function openBytes(buffer, name) {
  state.status = 'loading';
  state.error = null;
  setStatus(`decoding ${name}…`);
  const t0 = performance.now();
  try {
    decoded = await loader.decode(buffer);
  } catch (e) {
    state.status = 'error';
    state.error = e.message;
    setStatus(`${name}: ${e.message}`, true);
    return;
  }
  const decodeMs = performance.now() - t0;
  state.stats = decoded.stats;
  state.decodeMs = decodeMs;
  rebuild();
  frame(mesh.geometry);
  showStats(decoded.stats, name, decodeMs);
  setStatus('');
  state.frames = 0;
  state.status = 'ready';
}

async function loadURL(url) {
  const name = decodeURIComponent(url.split('/').pop());
  setStatus(`loading ${name}…`);
  const response = await fetch(url);
  if (!response.ok) {
    state.status = 'error';
    state.error = `${url}: HTTP ${response.status}`;
    setStatus(state.error, true);
    return;
  }
  await openBytes(await response.arrayBuffer(), name);
}

function setRankColors(on) {
  state.rankColors = Boolean(on);
  ranksBox.checked = state.rankColors;
  rebuild();
  state.frames = 0;
}

ranksBox.addEventListener('change', () => setRankColors(ranksBox.checked));
document.getElementById('file').addEventListener('change', async (event) => {
  const file = event.target.files[0];
  if (file) await openBytes(await file.arrayBuffer(), file.name);
});
const drop = document.getElementById('drop');
window.addEventListener('dragover', (event) => {
  event.preventDefault();
  drop.hidden = false;
});
window.addEventListener('dragleave', (event) => {
  if (!event.relatedTarget) drop.hidden = true;
});
window.addEventListener('drop', async (event) => {
  event.preventDefault();
  drop.hidden = true;
  const file = event.dataTransfer.files[0];
  if (file) await openBytes(await file.arrayBuffer(), file.name);
});
// The panel covers the left of the page: on a wide page the view's centre
// moves right by half its width.
function fitView() {
  const w = window.innerWidth, h = window.innerHeight;
  camera.aspect = w / h;
  if (w > 700) camera.setViewOffset(w, h, -150, 0, w, h);
  else camera.clearViewOffset();
  camera.updateProjectionMatrix();
  renderer.setSize(w, h);
}
window.addEventListener('resize', fitView);
fitView();

renderer.setAnimationLoop(() => {
  controls.update();
  renderer.render(scene, camera);
  state.frames++;
});

state.rankColors = params.get('ranks') === '1';
ranksBox.checked = state.rankColors;
if (params.get('file')) loadURL(params.get('file'));
else setStatus('no file open');
