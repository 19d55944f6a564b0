// The first plot in a classroom's conditions: from navigation to the first plotted run of the
// default scenario, in headless Chromium with the DevTools protocol's network and CPU emulation,
// a fresh browser context for each load (empty cache, no service worker), and then a second load
// in the same context (the service worker and the HTTP cache warm). Each build's dist/ is served
// by scripts/serve.mjs twice: plain (no compressed copy) and compressed (its brotli copies; a
// build without them is given them in a temporary copy, as a static host compresses anything).
//
//   node tests/bench/throttled.mjs                  this build (dist/)
//   BENCH_VS_DIST=DIR node tests/bench/throttled.mjs this build and another build's dist/ side by side
//   BENCH_PATH='#lang=de' node tests/bench/throttled.mjs  the page opened with that query or fragment
//
// Run by `make bench`. Prints, for each build, serving and profile, the median (min–max) of
// BENCH_REPS (default 5) loads, and the bytes the network sent before the first plot; with two
// builds, their loads alternate and the ratio of each pair of loads is given too.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import http from 'node:http';
import { PROFILES, compressedCopy, spread, throttle } from './builds.mjs';
import { firstPlotMs, launch, markFirstPlot } from '../browser.mjs';
import { staticHandler } from '../../scripts/serve.mjs';

const REPS = Number(process.env.BENCH_REPS ?? 5);
if (!Number.isInteger(REPS) || REPS < 1)
  throw new Error(`BENCH_REPS must be a positive integer, not ${process.env.BENCH_REPS}`);

// BENCH_PROFILES=slow picks the profiles whose name starts with it (e.g. "slow" or "school");
// BENCH_SERVING=compressed or plain picks one serving.
const chosen = (list, env, key) => list.filter((x) => !process.env[env] || key(x).startsWith(process.env[env]));

const ROOT = new URL('../../dist/', import.meta.url).pathname;
// What the page is opened with after its address: nothing (the default scenario, in the
// browser's language) unless BENCH_PATH says, e.g. '#lang=ja'.
const PATH = process.env.BENCH_PATH ?? '';
const builds = [['this build', ROOT]];
if (process.env.BENCH_VS_DIST) builds.push([`other (${process.env.BENCH_VS_DIST})`, process.env.BENCH_VS_DIST]);

const browser = await launch();
const errors = [];

/**
 * The bodies the server sends (compressed where it compresses; headers aside), as {at, bytes}:
 * `at` when the request arrived (ms since the epoch, as the page's performance.timeOrigin counts).
 * Counted at the server: a worker's requests are not in the page's DevTools session, and the
 * browser's own accounts of them vary.
 */
const sent = [];

/** Bytes of the bodies of the requests that arrived by `ms` after the navigation of `page` began. */
async function bytesBy(page, ms) {
  const cutoff = (await page.evaluate(() => performance.timeOrigin)) + ms;
  return sent.reduce((sum, r) => (r.at <= cutoff ? sum + r.bytes : sum), 0);
}

/** Serves `root` as scripts/serve.mjs does, recording each response in `sent`. */
async function counted(root, compressed) {
  const files = staticHandler(root, { compressed });
  const server = http.createServer((req, res) => {
    const at = performance.timeOrigin + performance.now();
    res.on('finish', () => sent.push({ at, bytes: Number(res.getHeader('Content-Length') ?? 0) }));
    files(req, res);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { server, url: `http://127.0.0.1:${server.address().port}/` };
}

/** Navigates to `url` and resolves to the milliseconds to the first plotted run, which must be done. */
async function firstPlot(page, url) {
  const ms = await firstPlotMs(page, url, 120_000);
  const state = await page.evaluate(() => document.body.dataset.state);
  if (state !== 'done') throw new Error(`the first run ended ${state}, not done`);
  return ms;
}

/** One fresh load and the second load in the same context. */
async function loads(url, profile) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  await markFirstPlot(page);
  await throttle(page, profile);
  sent.length = 0;
  const first = await firstPlot(page, url);
  const bytes = await bytesBy(page, first);
  const compute = await page.evaluate(() => Number(document.body.dataset.computeMs));
  // The service worker controls the page (it claims it once active) before the second load.
  await page.evaluate(() => navigator.serviceWorker.ready);
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
  const second = await firstPlot(page, url);
  await context.close();
  return { first, bytes, second, compute };
}

console.log(`Chromium, navigation → first plotted run of the default scenario, median (min–max) of ${REPS} loads`);
for (const profile of chosen(PROFILES, 'BENCH_PROFILES', (p) => p.name)) {
  console.log(`\n${profile.name}`);
  const servings = [
    ['compressed', true],
    ['plain', false],
  ];
  for (const [servingName, compressed] of chosen(servings, 'BENCH_SERVING', (s) => s[0])) {
    const served = [];
    for (const [buildName, dir] of builds) {
      if (!existsSync(join(dir, 'index.html'))) throw new Error(`${dir} has no index.html: build it first`);
      const copy = compressed ? compressedCopy(dir) : { dir, done: () => {} };
      served.push({ buildName, copy, ...(await counted(copy.dir, compressed)), runs: [] });
    }
    // The builds' loads alternate, so that a slower spell of the machine falls on both alike.
    for (let r = 0; r < REPS; r++)
      for (const build of served) build.runs.push(await loads(`${build.url}${PATH}`, profile));
    for (const { buildName, copy, server, runs } of served) {
      server.close();
      copy.done();
      console.log(
        `  ${servingName.padEnd(10)} ${buildName.padEnd(12)} first load ${spread(runs.map((r) => r.first))} ms, ` +
          `${spread(
            runs.map((r) => r.bytes / 1024),
            0,
          )} KiB sent before it (the run's compute ${spread(runs.map((r) => r.compute))} ms); ` +
          `second load ${spread(runs.map((r) => r.second))} ms`,
      );
    }
    if (served.length === 2) {
      const [a, b] = served.map((s) => s.runs);
      const ratio = (key) =>
        spread(
          a.map((run, i) => run[key] / b[i][key]),
          2,
        );
      console.log(
        `  ${servingName.padEnd(10)} this ÷ other, load by load: first ${ratio('first')}, second ${ratio('second')}`,
      );
    }
  }
}
await browser.close();
if (errors.length) {
  console.error(`console or page errors:\n${[...new Set(errors)].join('\n')}`);
  process.exit(1);
}
