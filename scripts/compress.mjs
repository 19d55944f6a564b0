// Writes a brotli (.br, quality 11) and a gzip (.gz, level 9) copy beside each text or WASM file
// of a folder, as a static host that serves precompressed files expects; scripts/serve.mjs serves
// them. A copy is written only where it is smaller, and a stale copy is replaced.
//
//   node scripts/compress.mjs DIR
import { readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { brotliCompressSync, constants, gzipSync } from 'node:zlib';

const COMPRESSIBLE = /\.(html|css|js|mjs|wasm|json|svg|md|txt|ftl)$/;

function* files(dir) {
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) {
      if (!entry.name.startsWith('.')) yield* files(path); // a dot folder is not served
    } else if (COMPRESSIBLE.test(entry.name)) yield path;
  }
}

const dir = process.argv[2];
if (!dir || !statSync(dir, { throwIfNoEntry: false })?.isDirectory()) {
  console.error(`compress: give the folder to compress, not ${dir ?? 'nothing'}`);
  process.exit(2);
}
for (const path of files(dir)) {
  const bytes = readFileSync(path);
  const copies = {
    br: brotliCompressSync(bytes, {
      params: {
        [constants.BROTLI_PARAM_QUALITY]: 11,
        [constants.BROTLI_PARAM_SIZE_HINT]: bytes.length,
        [constants.BROTLI_PARAM_MODE]: path.endsWith('.wasm')
          ? constants.BROTLI_MODE_GENERIC
          : constants.BROTLI_MODE_TEXT,
      },
    }),
    gz: gzipSync(bytes, { level: 9 }),
  };
  for (const [ext, copy] of Object.entries(copies)) {
    if (copy.length < bytes.length) writeFileSync(`${path}.${ext}`, copy);
    else rmSync(`${path}.${ext}`, { force: true });
  }
}
