// Browser benchmark: prints the time of a full sine200 run (worker compute, transfer and first
// plot), the in-browser closed-loop speed and the WASM size. Run with `make bench`.
import { statSync } from 'node:fs';
import { serve, launch, newPage, settled, runAgain } from '../browser.mjs';

const server = await serve();
const browser = await launch();
const errors = [];
const page = await newPage(browser, errors);

async function run(query) {
  await page.goto(`${server.url}?${query}`);
  await settled(page);
  return page.evaluate(() => ({ ...document.body.dataset }));
}


const first = await run('v=1&preset=sine200');
const warm = [];
for (let i = 0; i < 5; i++) warm.push(Number((await runAgain(page)).runMs));
console.log(`sine200 (5,000 steps) run → plotted: first ${Number(first.runMs).toFixed(1)} ms (compute ${first.computeMs} ms, plotting ${first.plotMs} ms), warm median ${warm.sort((a, b) => a - b)[2].toFixed(1)} ms`);

const rate = (r) => Number(r.rows) / (Number(r.computeMs) / 1000);
const describeRate = (label, r) =>
  console.log(`${label}: ${(rate(r) / 1e6).toFixed(2)} M steps/s (${(rate(r) * 50e-6).toFixed(0)}× real time), ${r.rows} steps in ${Number(r.computeMs).toFixed(1)} ms; run → plot ${Number(r.runMs).toFixed(0)} ms`);
describeRate('closed loop in the browser, first run after load', await run('v=1&preset=ramp&duration=5'));
const runs = [];
for (let i = 0; i < 3; i++) runs.push(await runAgain(page));
runs.sort((a, b) => rate(b) - rate(a));
describeRate('closed loop in the browser, best of 3 further runs', runs[0]);
// Same length as the Node benchmark (tests/bench/node.mjs): 1 s runs of `ramp`.
await run('v=1&preset=ramp&duration=1');
const short = [];
for (let i = 0; i < 10; i++) short.push(await runAgain(page));
short.sort((a, b) => rate(b) - rate(a));
describeRate('closed loop in the browser, best of 10 runs of 1 s', short[0]);

await page.goto(`${server.url}?v=1&preset=step#sweep=10,1000,20,0.02,0,0.2,euler`);
await settled(page);
await page.waitForFunction(() => document.body.dataset.sweep === 'done', null, { timeout: 60_000 });
const sweepFirst = await page.evaluate(() => Number(document.body.dataset.sweepMs));
await page.click('#sweep-run');
await page.waitForFunction((ms) => document.body.dataset.sweep === 'done' && Number(document.body.dataset.sweepMs) !== ms, sweepFirst, { timeout: 60_000 });
const sweepAgain = await page.evaluate(() => Number(document.body.dataset.sweepMs));
console.log(`20-point sweep of 0.2 s runs on ${await page.inputValue('#sweep-form [name=workers]')} workers: ${sweepFirst.toFixed(0)} ms (first, incl. starting the workers), ${sweepAgain.toFixed(0)} ms (again)`);

const wasm = statSync(new URL('../../dist/pkg/imlab_bg.wasm', import.meta.url)).size;
console.log(`WASM binary: ${(wasm / 1024).toFixed(1)} KiB (${wasm} bytes, uncompressed)`);
if (errors.length) console.log('console errors:', errors);
await browser.close();
server.close();
