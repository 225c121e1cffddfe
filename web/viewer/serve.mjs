// A small static file server for the viewer and the browser test, with no
// dependencies: it serves the web/ folder (the viewer at /viewer/, the
// package at /src/ and /dist/, three at /node_modules/) and a folder of
// .drm files at /files/.
//
//   node viewer/serve.mjs [--port 8080] [--files DIR]
//   then open http://localhost:8080/viewer/  (or /viewer/?file=/files/NAME.drm)
import { createServer } from 'node:http';
import { createReadStream, statSync } from 'node:fs';
import { extname, join, resolve, sep, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const WEB = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.json': 'application/json', '.wasm': 'application/wasm', '.png': 'image/png',
  '.drm': 'application/octet-stream', '.svg': 'image/svg+xml',
};

/** Starts the server; resolves to {server, url}. Port 0 picks a free one. */
export function serve({ port = 8080, files = resolve(WEB, '..', 'tests', 'golden'), host = '127.0.0.1' } = {}) {
  const roots = [['/files/', resolve(files)], ['/', WEB]];
  const server = createServer((req, res) => {
    let path;
    try {
      path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    } catch {
      res.writeHead(400).end();
      return;
    }
    if (path === '/') {
      res.writeHead(302, { location: '/viewer/' }).end();
      return;
    }
    const [prefix, root] = roots.find(([p]) => path.startsWith(p));
    let file = resolve(root, '.' + path.slice(prefix.length - 1));
    if (file !== root && !file.startsWith(root + sep)) {
      res.writeHead(403).end();
      return;
    }
    try {
      if (statSync(file).isDirectory()) file = join(file, 'index.html');
      const size = statSync(file).size;
      res.writeHead(200, { 'content-type': TYPES[extname(file)] || 'application/octet-stream', 'content-length': size,
        'cache-control': 'no-cache' });
      createReadStream(file).pipe(res);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' }).end('not found\n');
    }
  });
  return new Promise((ok, fail) => {
    server.once('error', fail);
    server.listen(port, host, () => ok({ server, url: `http://${host}:${server.address().port}` }));
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const options = {};
  for (let i = 0; i < args.length; i++) {
    if (args[i] === '--port') options.port = Number(args[++i]);
    else if (args[i] === '--files') options.files = args[++i];
    else if (args[i] === '--host') options.host = args[++i];
    else {
      console.error('usage: node viewer/serve.mjs [--port N] [--files DIR] [--host H]');
      process.exit(2);
    }
  }
  const { url } = await serve(options);
  console.log(`serving ${WEB} at ${url}/viewer/ (.drm files at ${url}/files/)`);
}
