// What the benches that compare page builds share (throttled.mjs, thread.mjs): the classroom's
// network and CPU profiles and how a page gets one, a build's dist/ folder served compressed as a
// static host serves it, and how a set of loads reads.
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

/** The profiles: the network (bits/s, ms) and how many times slower the page's CPU is. */
export const PROFILES = [
  { name: 'unthrottled', network: null, cpu: 1 },
  { name: 'school Wi-Fi (10 Mbit/s, 40 ms, CPU 2×)', network: { down: 10e6, up: 5e6, latency: 40 }, cpu: 2 },
  { name: 'slow 4G (1.6 Mbit/s, 150 ms, CPU 4×)', network: { down: 1.6e6, up: 750e3, latency: 150 }, cpu: 4 },
];

/** Applies `profile` to `page` through a CDP session, which it returns. */
export async function throttle(page, profile) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Network.enable');
  if (profile.network)
    await cdp.send('Network.emulateNetworkConditions', {
      offline: false,
      latency: profile.network.latency,
      downloadThroughput: profile.network.down / 8,
      uploadThroughput: profile.network.up / 8,
    });
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: profile.cpu });
  return cdp;
}

/** `values` as "median (min–max)" with `digits` decimals. */
export function spread(values, digits = 0) {
  const s = [...values].sort((a, b) => a - b);
  const mid = s.length >> 1;
  const med = s.length % 2 ? s[mid] : (s[mid - 1] + s[mid]) / 2;
  return `${med.toFixed(digits)} (${s[0].toFixed(digits)}–${s.at(-1).toFixed(digits)})`;
}
