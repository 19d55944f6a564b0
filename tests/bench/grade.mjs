// Grading a class in the page against `imlab grade`: a class of 200 links against the built-in
// step-tune (every fifth its known solution; the others its untouched base, a value out of range,
// a changed gain, a line that is no link) graded in the page's workers, from the click on Grade to
// the last row, and by the CLI on the same file; the page's CSV is compared with the CLI's byte
// for byte. Then the work-bound worst cases opened in the page, each run from navigation to
// plotted: the heaviest plant, and the costliest own laws a run accepts.
// Run after `make dist` and `cargo build --release`; the figures are in docs/figures.md.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { launch, serve, settled } from '../browser.mjs';
import { initSync, law_language, Simulation } from '../../dist/pkg/imlab.js';
import { CHALLENGE_JOBS as jobs } from '../../dist/.src/worker/challenge-jobs.js';

initSync({ module: readFileSync(new URL('../../dist/pkg/imlab_bg.wasm', import.meta.url)) });
const cli = new URL('../../target/release/imlab', import.meta.url).pathname;
const HEAVY =
  'v=1&preset=sine200-drive&ekf=rk4&ekf.load=1&ekf.rr=1&delay.comp=1&perfect=1&substeps=1000&duration=0.0625';

// Steps 2 and 4 the paper's, padded to the 400-operation cap with plain additions (the operation
// that costs the most for what the bound charges it), at the longest run the bound accepts: the
// length its refusal of a 20 s run names.
const padded = (law, n) => `${law} + 0*(${Array(n).fill('x1h').join('+')})`;
const paper = law_language().paper;
const lawLink = (duration) =>
  `v=1&preset=step&ts=0.00001&duration=${duration}` +
  `&law.v2=${encodeURIComponent(padded(paper[1], 336))}&law.v4=${encodeURIComponent(padded(paper[3], 320))}`;
const refusal = (() => {
  try {
    new Simulation(lawLink(20)).free();
    return '';
  } catch (e) {
    return String(e);
  }
})();
const longest = /shorten 'duration' to ([\d.]+) s/.exec(refusal)?.[1] ?? 'none';
const LAWS = lawLink(longest);

const b = jobs['challenge-builtins']({}).find((x) => x.name === 'step-tune');
const solved =
  b.text +
  b.solution
    .split('&')
    .map((p) => `&try.${p}`)
    .join('');
const kinds = [solved, b.text, `${b.text}&try.k1=9999`, `${b.text}&try.k2=600`, 'not a link'];
const file = join(mkdtempSync(join(tmpdir(), 'imlab-grade-')), 'class200.txt');
writeFileSync(file, `${Array.from({ length: 200 }, (_, i) => kinds[i % kinds.length]).join('\n')}\n`);

const server = await serve();
const browser = await launch();
try {
  const context = await browser.newContext({ viewport: { width: 1440, height: 900 }, acceptDownloads: true });
  const page = await context.newPage();
  await page.goto(`${server.url}?v=1&preset=step`);
  await settled(page);
  await page.evaluate(() => localStorage.clear());
  await page.click('#tab-challenge');
  await page.fill('#grade-challenge', 'step-tune');
  await page.setInputFiles('#grade-file', file);
  const start = Date.now();
  await page.click('#grade-run');
  await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 600_000 });
  const pageSeconds = (Date.now() - start) / 1000;
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#grade-csv')]);
  const csv = readFileSync(await download.path(), 'utf8');
  const cliStart = Date.now();
  const cliCsv = execFileSync(cli, ['grade', 'step-tune', file], { stdio: ['ignore', 'pipe', 'ignore'] }).toString();
  const cliSeconds = (Date.now() - cliStart) / 1000;
  console.log(
    `200 links: page ${pageSeconds.toFixed(2)} s, imlab grade ${cliSeconds.toFixed(2)} s wall; CSV identical: ${csv === cliCsv}`,
  );
  for (const [what, scenario] of [
    ['plant', HEAVY],
    ['laws', LAWS],
    ['the same without laws', `v=1&preset=step&ts=0.00001&duration=${longest}`],
  ]) {
    await page.goto(`${server.url}?${scenario}`);
    await settled(page, 120_000);
    const { runMs, computeMs } = await page.evaluate(() => document.body.dataset);
    console.log(`work-bound worst case (${what}) in the page: ${runMs} ms start to plotted, ${computeMs} ms computing`);
  }
} finally {
  await browser.close();
  server.close();
}
