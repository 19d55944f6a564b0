// Serves a built dist/ folder as a good static host would, with sirv: each file's brotli or gzip
// copy beside it (written by scripts/compress.mjs) when the browser accepts it, the right content
// types, ETags, and cache headers that let the browser keep what cannot change. A file whose name
// carries its content's hash (main-JRYEWMOB.js, written by scripts/bundle.mjs) is kept a year without asking again; any other
// file (index.html, sw.js, the guides, KaTeX's stylesheet and fonts) is asked for again each time
// and answered "not modified" when unchanged.
//
//   node scripts/serve.mjs [--port N] [--plain] [DIR]
//
// DIR defaults to dist/; --plain serves no compressed copy (to measure what compression saves).
import http from 'node:http';
import { fileURLToPath } from 'node:url';
import sirv from 'sirv';

/** A file name that carries its content's hash: a hyphen, eight base32 digits, the extension. */
export const HASHED = /-[A-Z2-7]{8}\.[a-z0-9]+$/;

/** The request handler for `root`; `compressed: false` serves only the files as they are. */
export function staticHandler(root, { compressed = true } = {}) {
  const files = sirv(root, {
    brotli: compressed,
    gzip: compressed,
    etag: true,
    dev: false,
    setHeaders(res, pathname) {
      res.setHeader('Cache-Control', HASHED.test(pathname) ? 'public, max-age=31536000, immutable' : 'no-cache');
    },
  });
  return (req, res) => files(req, res, () => res.writeHead(404).end('not found'));
}

/** Listens on `port` (0: any free one) on loopback; resolves to the server and its address. */
export async function listen(root, port = 0, options = {}) {
  const server = http.createServer(staticHandler(root, options));
  await new Promise((resolve, reject) => server.once('error', reject).listen(port, '127.0.0.1', resolve));
  return { server, url: `http://127.0.0.1:${server.address().port}/` };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const option = (name) => {
    const i = args.indexOf(name);
    return i < 0 ? null : args.splice(i, 2)[1];
  };
  const port = Number(option('--port') ?? 8000);
  const plain = args.includes('--plain');
  const root = args.filter((a) => a !== '--plain')[0] ?? fileURLToPath(new URL('../dist/', import.meta.url));
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`serve: --port must be a port number, not ${port}`);
    process.exit(2);
  }
  try {
    const { url } = await listen(root, port, { compressed: !plain });
    console.log(`IM Lab is at ${url}  (Ctrl-C stops it)`);
  } catch (e) {
    console.error(`serve: cannot listen on port ${port}: ${e.message}`);
    process.exit(1);
  }
}
