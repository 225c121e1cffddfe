// The `drm` command-line tool, the reference the WebAssembly decoder is
// held to: its decoded PLY files and its error messages.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, statSync, readdirSync } from 'node:fs';
import { dirname, join, resolve, basename } from 'node:path';
import { fileURLToPath } from 'node:url';

export const WEB = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const ROOT = resolve(WEB, '..');
export const DRM = process.env.DRM_CLI || join(ROOT, 'build', 'bin', 'drm');
export const WORK = join(WEB, 'build', 'test');

export function haveCli() {
  return existsSync(DRM);
}

export function drm(args) {
  return execFileSync(DRM, args, { stdio: ['ignore', 'pipe', 'pipe'], maxBuffer: 64 << 20 }).toString();
}

/** Runs `drm decode IN OUT.ply`; returns {ok, stderr}. */
export function cliDecode(input, output) {
  const r = spawnSync(DRM, ['decode', input, output, '--threads', '1'], { encoding: 'utf8' });
  return { ok: r.status === 0, stderr: r.stderr };
}

/** The message `drm decode` prints for a file it refuses: the text after
 * "drm: error: cannot decode FILE: ". */
export function cliDecodeError(input) {
  const r = spawnSync(DRM, ['decode', input, join(WORK, 'refused.ply')], { encoding: 'utf8' });
  if (r.status === 0) return null;
  const prefix = `drm: error: cannot decode ${input}: `;
  const line = r.stderr.split('\n').find((l) => l.startsWith(prefix));
  if (!line) throw new Error(`unexpected drm output for ${input}: ${r.stderr}`);
  return line.slice(prefix.length);
}

function newer(a, b) {
  return existsSync(a) && statSync(a).mtimeMs >= statSync(b).mtimeMs && statSync(a).mtimeMs >= statSync(DRM).mtimeMs;
}

/** Encodes the meshes (each once; kept under web/build/test/NAME/ until the
 * mesh or the drm binary changes) and decodes them with the CLI: returns
 * [{name, drm, ply}] with the .drm file and the CLI's decoded PLY. */
export function encodeAndDecode(meshes, name) {
  const dir = join(WORK, name);
  mkdirSync(dir, { recursive: true });
  const todo = meshes.filter((m) => !newer(join(dir, basename(m).replace(/\.\w+$/, '.drm')), m));
  if (todo.length) drm(['encode', ...todo, '-o', dir, '-j', '2']);
  const drms = meshes.map((m) => join(dir, basename(m).replace(/\.\w+$/, '.drm')));
  return decodeAll(drms, join(dir, 'decoded'));
}

/** Decodes .drm files with the CLI into DIR (cached like encodeAndDecode). */
export function decodeAll(drms, dir) {
  mkdirSync(dir, { recursive: true });
  const out = drms.map((d) => ({ name: basename(d, '.drm'), drm: d, ply: join(dir, basename(d, '.drm') + '.ply') }));
  const todo = out.filter((o) => !newer(o.ply, o.drm)).map((o) => o.drm);
  if (todo.length) drm(['decode', ...todo, '-o', dir, '-j', '2']);
  return out;
}

export function listFiles(dir, ext) {
  return readdirSync(dir).filter((f) => f.endsWith(ext)).sort().map((f) => join(dir, f));
}
