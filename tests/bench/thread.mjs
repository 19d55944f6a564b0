// The page's own thread before the first plot, on school Wi-Fi (10 Mbit/s, 40 ms, CPU 2× slower):
// the work Chromium counts for the page (`Performance.getMetrics` of the DevTools protocol) from
// navigation to the first plotted run of the default scenario, in a fresh browser context for
// each load, served compressed (a build without brotli copies is given them in a temporary copy).
// The main thread is the first load's bottleneck there.
//
//   node tests/bench/thread.mjs                     this build (dist/; BENCH_DIST=DIR for another)
//   BENCH_VS_DIST=DIR node tests/bench/thread.mjs   this build and another build's dist/, load by load
//
// Run by `make bench`. Prints, for each build, the median (min–max) of BENCH_REPS (default 5)
// loads: the first plot; the thread's busy time (every task), and of it the script, style and
// layout; the number of style recalculations and layouts; and the elements in the page at the
// first plot. The counts are read as the bench sees the first plot: work the page has begun by
// then (a task put off until it is idle) may be in them.
import { join } from 'node:path';
import { existsSync } from 'node:fs';
import { launch, markFirstPlot } from '../browser.mjs';
import { listen } from '../../scripts/serve.mjs';
import { PROFILES, compressedCopy, spread, throttle } from './builds.mjs';

const REPS = Number(process.env.BENCH_REPS ?? 5);
if (!Number.isInteger(REPS) || REPS < 1)
  throw new Error(`BENCH_REPS must be a positive integer, not ${process.env.BENCH_REPS}`);

const SCHOOL = PROFILES.find((p) => p.name.startsWith('school'));

const builds = [['this build', process.env.BENCH_DIST ?? new URL('../../dist/', import.meta.url).pathname]];
if (process.env.BENCH_VS_DIST) builds.push([`other (${process.env.BENCH_VS_DIST})`, process.env.BENCH_VS_DIST]);
for (const [, dir] of builds)
  if (!existsSync(join(dir, 'index.html'))) throw new Error(`${dir} has no index.html: build it first`);

const browser = await launch();
const errors = [];
const served = [];
for (const [name, dir] of builds) {
  const copy = compressedCopy(dir);
  served.push({ name, copy, ...(await listen(copy.dir, 0, { compressed: true })), loads: [] });
}

/** One fresh load of `url`: the first plot (ms) and the thread's counts at that moment. */
async function load(url) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  await markFirstPlot(page);
  await page.addInitScript(() => {
    new MutationObserver((_, observer) => {
      if (!['done', 'failed'].includes(document.body?.dataset.state)) return;
      window.elementsAtPlot = document.getElementsByTagName('*').length;
      observer.disconnect();
    }).observe(document, { attributes: true, subtree: true, attributeFilter: ['data-state'] });
  });
  const cdp = await throttle(page, SCHOOL);
  await cdp.send('Performance.enable');
  await page.goto(url);
  await page.waitForFunction(() => window.firstPlottedMs !== undefined, null, { timeout: 60_000 });
  const { metrics } = await cdp.send('Performance.getMetrics');
  const m = Object.fromEntries(metrics.map((x) => [x.name, x.value]));
  const out = {
    'first plot': await page.evaluate(() => window.firstPlottedMs),
    busy: m.TaskDuration * 1e3,
    script: m.ScriptDuration * 1e3,
    style: m.RecalcStyleDuration * 1e3,
    layout: m.LayoutDuration * 1e3,
    'style recalculations': m.RecalcStyleCount,
    layouts: m.LayoutCount,
    elements: await page.evaluate(() => window.elementsAtPlot),
  };
  await context.close();
  return out;
}

// The builds' loads alternate, so that a slower spell of the machine falls on both alike.
for (let r = 0; r < REPS; r++) for (const build of served) build.loads.push(await load(build.url));
console.log(
  `School Wi-Fi, CPU 2×, served compressed: the page's thread to the first plot, median (min–max) of ${REPS} loads`,
);
for (const { name, copy, server, loads } of served) {
  server.close();
  copy.done();
  console.log(`  ${name}`);
  for (const key of Object.keys(loads[0])) {
    const unit = ['first plot', 'busy', 'script', 'style', 'layout'].includes(key) ? ' ms' : '';
    console.log(`    ${key.padEnd(22)} ${spread(loads.map((l) => l[key]))}${unit}`);
  }
}
await browser.close();
if (errors.length) {
  console.error(`console or page errors:\n${[...new Set(errors)].join('\n')}`);
  process.exit(1);
}
