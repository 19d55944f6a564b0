// A build's dist/ folder as a static host serves it compressed, for the benches that compare builds.
import { cpSync, mkdtempSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { execFileSync } from 'node:child_process';

/**
 * `dir` itself if it has brotli copies, else a temporary copy given them (as a static host
 * compresses anything); `done()` removes the copy.
 */
export function compressedCopy(dir) {
  const hasBr = (d) =>
    readdirSync(d, { withFileTypes: true }).some((e) =>
      e.isDirectory() ? hasBr(join(d, e.name)) : e.name.endsWith('.br'),
    );
  if (hasBr(dir)) return { dir, done: () => {} };
  const copy = mkdtempSync(join(tmpdir(), 'imlab-bench-'));
  cpSync(dir, copy, { recursive: true });
  execFileSync('node', [new URL('../../scripts/compress.mjs', import.meta.url).pathname, copy]);
  return { dir: copy, done: () => rmSync(copy, { recursive: true, force: true }) };
}
