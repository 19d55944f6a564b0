// Browser benchmark: the cold load (navigation to the first plotted run of the default scenario, in
// a fresh context: empty cache, no service worker), the time of a full sine200 run (worker compute, transfer and first plot),
// the in-browser closed-loop speed (first run after load, 5 s runs, 1 s runs), view requests and
// overlays on a 5 s run, a parameter sweep and the WASM size. Run with `make bench` (or `node tests/bench/browser.mjs` after
// `make dist`).
//
// The run figures are the median (min–max) of BENCH_REPS (default 5) repetitions, each in a
// fresh browser context, so that each has its own first run after load; within a repetition a
// warm figure is the best of a few runs.
import { statSync } from 'node:fs';
import { serve, launch, newPage, settled, runAgain, markFirstPlot, firstPlotMs } from '../browser.mjs';

const REPS = Number(process.env.BENCH_REPS ?? 5);
if (!Number.isInteger(REPS) || REPS < 1)
  throw new Error(`BENCH_REPS must be a positive integer, not ${process.env.BENCH_REPS}`);

const server = await serve();
const browser = await launch();
const errors = [];

const rate = (r) => Number(r.rows) / (Number(r.computeMs) / 1000);
const best = (runs) => runs.reduce((a, b) => (rate(b) > rate(a) ? b : a));

/**
 * Milliseconds from the navigation's start to the first run's plots painted (the page sets
 * data-state once they are), opening the page without a query in a fresh context: nothing
 * cached, no service worker, the WASM module fetched and compiled anew.
 */
async function coldLoad(url = server.url) {
  const page = await newPage(browser, errors);
  await markFirstPlot(page);
  const ms = await firstPlotMs(page, url);
  await page.context().close();
  return ms;
}

/** One repetition in a fresh context: every figure of one page load. */
async function repetition() {
  const out = { coldLoadMs: await coldLoad() };
  const page = await newPage(browser, errors);
  async function run(query) {
    await page.goto(`${server.url}?${query}`);
    await settled(page);
    return page.evaluate(() => ({ ...document.body.dataset }));
  }
  const first = await run('v=1&preset=sine200');
  out.sineFirst = Number(first.runMs);
  out.sineCompute = Number(first.computeMs);
  out.sinePlot = Number(first.plotMs);
  const warm = [];
  for (let i = 0; i < 5; i++) warm.push(Number((await runAgain(page)).runMs));
  out.sineWarm = warm.sort((a, b) => a - b)[2];
  const long = await run('v=1&preset=ramp&duration=5');
  out.longFirst = rate(long);
  out.longFirstRunMs = Number(long.runMs);
  const runs = [];
  for (let i = 0; i < 3; i++) runs.push(await runAgain(page));
  out.long = rate(best(runs));
  out.firstOverWarm = out.longFirst / out.long;
  out.longRunMs = Number(best(runs).runMs);
  // Same length as the Node benchmark (tests/bench/node.mjs): 1 s runs of `ramp`.
  await run('v=1&preset=ramp&duration=1');
  const short = [];
  for (let i = 0; i < 10; i++) short.push(await runAgain(page));
  out.short = rate(best(short));
  await run('v=1&preset=ramp&duration=5');
  // View requests on a 5 s run, from the request to the next painted frame after the plots took
  // the answer: a zoom to 1 s (a replay of that window), the whole run again (the overview
  // the run kept), and the walkthrough opened after a run on the plots tab: the first time (the
  // equations the page has not typeset while idle typeset now, and a replay of the whole run for
  // its plots), and after another run (whose view of the walkthrough's plots came with the run).
  const viewMs = (request) =>
    page.evaluate(
      (request) =>
        new Promise((resolve) => {
          const start = performance.now();
          const painted = () => requestAnimationFrame(() => setTimeout(() => resolve(performance.now() - start), 0));
          const observer = new MutationObserver(() => {
            observer.disconnect();
            painted();
          });
          observer.observe(document.body, { attributes: true, attributeFilter: ['data-view'] });
          if (request === 'zoom') window.imlab.plots.charts[0].setScale('x', { min: 2, max: 3 });
          else document.getElementById('full-run').click();
        }),
      request,
    );
  out.zoomMs = await viewMs('zoom');
  out.fullMs = await viewMs('full');
  const walkthroughMs = () =>
    page.evaluate(
      () =>
        new Promise((resolve) => {
          const set = window.imlab.walkthrough;
          const old = set.charts.at(-1)?.data[0];
          const drawn = () => set.charts.length === set.defs.length && set.charts.at(-1).data[0] !== old;
          const start = performance.now();
          document.querySelector('[role=tab][data-tab=walkthrough]').click();
          const painted = () => requestAnimationFrame(() => setTimeout(() => resolve(performance.now() - start), 0));
          const check = () => (drawn() ? painted() : setTimeout(check, 0));
          check();
        }),
    );
  out.walkFirstMs = await walkthroughMs();
  await page.click('[role=tab][data-tab=plots]');
  await runAgain(page);
  out.walkMs = await walkthroughMs();
  // Back to the plots tab, to the painted frame.
  out.backMs = await page.evaluate(
    () =>
      new Promise((resolve) => {
        const start = performance.now();
        document.querySelector('[role=tab][data-tab=plots]').click();
        requestAnimationFrame(() => setTimeout(() => resolve(performance.now() - start), 0));
      }),
  );
  // The overlay of the 5 s run with a pin of it, from choosing its column to the painted frame:
  // another column than the runs keep (one replay of each, after which they keep it), then the
  // same column again (read from what they keep, as after a run with runs pinned).
  await page.click('#pin');
  await page.waitForFunction(() => document.querySelectorAll('#overlay-plots .plot canvas').length === 2);
  const overlayMs = (column) =>
    page.evaluate(
      (column) =>
        new Promise((resolve) => {
          const plots = document.getElementById('overlay-plots');
          const start = performance.now();
          const observer = new MutationObserver(() => {
            observer.disconnect();
            requestAnimationFrame(() => setTimeout(() => resolve(performance.now() - start), 0));
          });
          observer.observe(plots, { childList: true });
          const select = document.getElementById('overlay-column');
          select.value = column;
          select.dispatchEvent(new Event('change'));
        }),
      column,
    );
  out.overlayNewMs = await overlayMs('u_a');
  out.overlayKeptMs = await overlayMs('u_a');
  await page.context().close();
  return out;
}

const reps = [];
for (let r = 0; r < REPS; r++) reps.push(await repetition());

/** `key` of every repetition as "median (min–max)" with `digits` decimals, scaled by `scale`. */
function spread(key, digits = 1, scale = 1) {
  const s = reps.map((x) => x[key] * scale).sort((a, b) => a - b);
  const mid = s.length >> 1;
  const med = s.length % 2 ? s[mid] : (s[mid - 1] + s[mid]) / 2;
  return `${med.toFixed(digits)} (${s[0].toFixed(digits)}–${s.at(-1).toFixed(digits)})`;
}
const steps = (key) => `${spread(key, 2, 1e-6)} M steps/s`;

console.log(`Chromium, median (min–max) of ${REPS} page loads:`);
console.log(
  `  cold load (fresh context, default scenario), navigation → first run plotted: ${spread('coldLoadMs', 0)} ms (throttled profiles: tests/bench/throttled.mjs)`,
);
console.log(
  `  sine200 (5,000 steps) run → plotted: first run after load ${spread('sineFirst')} ms (compute ${spread('sineCompute')} ms, plotting ${spread('sinePlot')} ms); warm (median of 5) ${spread('sineWarm')} ms`,
);
console.log(
  `  closed loop, ramp 5 s, first run after load: ${steps('longFirst')}; run → plot ${spread('longFirstRunMs', 0)} ms`,
);
console.log(
  `  closed loop, ramp 5 s, best of 3 further runs: ${steps('long')}; run → plot ${spread('longRunMs', 0)} ms`,
);
console.log(`  first run after load / warm (5 s ramp, each load's own pair): ${spread('firstOverWarm', 2)}`);
console.log(`  closed loop, ramp 1 s, best of 10 runs: ${steps('short')}`);
console.log(
  `  views of a 5 s run: zoom to 1 s ${spread('zoomMs', 0)} ms; whole run again ${spread('fullMs', 0)} ms; walkthrough opened after a run ${spread('walkMs', 0)} ms (the first time, with a replay for its plots, ${spread('walkFirstMs', 0)} ms), and back to the plots ${spread('backMs', 0)} ms`,
);
console.log(
  `  overlay of a 5 s run and a pin of it: a column the runs keep ${spread('overlayKeptMs', 0)} ms; another column (one replay of each) ${spread('overlayNewMs', 0)} ms`,
);

const page = await newPage(browser, errors);
await page.goto(`${server.url}?v=1&preset=step#sweep=10,1000,20,0.02,0,0.2,euler`);
await settled(page);
await page.waitForFunction(() => document.body.dataset.sweep === 'done', null, { timeout: 60_000 });
const sweepFirst = await page.evaluate(() => Number(document.body.dataset.sweepMs));
await page.click('#sweep-run');
await page.waitForFunction(
  (ms) => document.body.dataset.sweep === 'done' && Number(document.body.dataset.sweepMs) !== ms,
  sweepFirst,
  { timeout: 60_000 },
);
const sweepAgain = await page.evaluate(() => Number(document.body.dataset.sweepMs));
console.log(
  `  20-point sweep of 0.2 s runs on ${await page.inputValue('#sweep-form [name=workers]')} workers: ${sweepFirst.toFixed(0)} ms (first, incl. starting the workers), ${sweepAgain.toFixed(0)} ms (again)`,
);

// With BENCH_VS_DIST, the dist/ folder of another build (for example an older commit's: `git
// worktree add /tmp/old COMMIT`, link node_modules into it, `make -C /tmp/old dist`), the cold load
// of this build against that one, side by side: BENCH_PAIRS (default 15) pairs, alternating, each
// load in a fresh context; the ratio is taken pair by pair, as the machine's speed drifts.
if (process.env.BENCH_VS_DIST) {
  const pairs = Number(process.env.BENCH_PAIRS ?? 15);
  if (!Number.isInteger(pairs) || pairs < 1)
    throw new Error(`BENCH_PAIRS must be a positive integer, not ${process.env.BENCH_PAIRS}`);
  const other = await serve(process.env.BENCH_VS_DIST);
  const mine = [],
    theirs = [],
    ratios = [];
  for (let i = 0; i < pairs; i++) {
    theirs.push(await coldLoad(other.url));
    mine.push(await coldLoad());
    ratios.push(mine.at(-1) / theirs.at(-1));
  }
  other.close();
  const med = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
  console.log(
    `  cold load against ${process.env.BENCH_VS_DIST}, ${pairs} alternating pairs: ${med(mine).toFixed(0)} ms against ${med(theirs).toFixed(0)} ms (medians); paired ratio ${med(ratios).toFixed(2)} (${Math.min(...ratios).toFixed(2)}–${Math.max(...ratios).toFixed(2)})`,
  );
}

// The core's two builds: the run's, which the page fetches first, and the one with the tools.
for (const [dir, what] of [
  ['pkg-run', 'the run (fetched first)'],
  ['pkg', 'with the tools (on the first job)'],
]) {
  const path = new URL(`../../dist/${dir}/imlab_bg.wasm`, import.meta.url);
  console.log(
    `WASM module, ${what}: ${statSync(path).size} bytes, ${statSync(`${path.pathname}.br`).size} brotli (dist/${dir}/)`,
  );
}
if (errors.length) console.log('console errors:', errors);
await browser.close();
server.close();
