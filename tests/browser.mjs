// Shared helpers for the browser tests and the browser benchmark: dist/ served on loopback as
// `make serve` serves it (scripts/serve.mjs) and headless Debian Chromium through playwright-core.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { after, before } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import { listen } from '../scripts/serve.mjs';

const ROOT = new URL('../dist/', import.meta.url).pathname;
export const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-quic',
];

/**
 * Serves `root` (dist/ unless given) on a free loopback port as `make serve` does (precompressed
 * files, cache headers); returns {url, close}.
 */
export async function serve(root = ROOT) {
  const { server, url } = await listen(root);
  return { url, close: () => server.close() };
}

export async function launch() {
  return chromium.launch({ executablePath: '/usr/bin/chromium', args: CHROMIUM_ARGS });
}

/** A new page that records console errors and page errors into `errors`. */
export async function newPage(browser, errors) {
  const context = await browser.newContext({ acceptDownloads: true, viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  return page;
}

/**
 * Has `page` note, on every navigation, the milliseconds from the navigation's start to the first
 * run's plots painted or its failure (the page sets data-state then), in `window.firstPlottedMs`.
 */
export function markFirstPlot(page) {
  return page.addInitScript(() => {
    new MutationObserver((_, observer) => {
      if (!['done', 'failed'].includes(document.body?.dataset.state)) return;
      window.firstPlottedMs = performance.now();
      observer.disconnect();
    }).observe(document, { attributes: true, subtree: true, attributeFilter: ['data-state'] });
  });
}

/** Navigates a page marked by `markFirstPlot` to `url`; resolves to its first-plot milliseconds. */
export async function firstPlotMs(page, url, timeout = 30_000) {
  await page.goto(url);
  await page.waitForFunction(() => window.firstPlottedMs !== undefined, null, { timeout });
  return page.evaluate(() => window.firstPlottedMs);
}

/** Waits until the current run has finished (done, failed, cancelled, or crashed with its worker). */
export async function settled(page, timeout = 30_000) {
  await page.waitForFunction(
    () => ['done', 'failed', 'cancelled', 'crashed'].includes(document.body.dataset.state),
    null,
    { timeout },
  );
  return page.evaluate(() => document.body.dataset.state);
}

/**
 * Does `action`, waits until it has started a run (the page counts runs started in
 * `data-started`, set with the running state) and until that run ends; returns how it ended.
 */
export async function startRun(page, action, timeout = 30_000) {
  const before = Number(await page.evaluate(() => document.body.dataset.started ?? 0));
  await action();
  await page.waitForFunction((n) => Number(document.body.dataset.started ?? 0) > n, before, { timeout });
  return settled(page, timeout);
}

/** Clicks Run and waits for that run to finish; returns the page's run figures. */
export async function runAgain(page) {
  const before = Number(await page.evaluate(() => document.body.dataset.run ?? 0));
  await page.click('#run');
  await page.waitForFunction((n) => Number(document.body.dataset.run ?? 0) > n, before, { timeout: 30_000 });
  return page.evaluate(() => ({ ...document.body.dataset }));
}

/**
 * Registers a server and a browser for the calling test file and returns `withPage(path, body)`:
 * it opens `path` (query and fragment) in a fresh context, runs `body(page)`, and fails the test
 * on any console or page error.
 */
export function browserSuite() {
  const suite = {};
  before(async () => {
    suite.server = await serve();
    suite.browser = await launch();
  });
  after(async () => {
    await suite.browser?.close();
    suite.server?.close();
  });
  suite.withPage = async (path, body) => {
    const errors = [];
    const page = await newPage(suite.browser, errors);
    try {
      await page.goto(`${suite.server.url}${path}`);
      await body(page);
    } finally {
      await page.context().close();
    }
    assert.deepEqual(errors, [], 'console errors');
  };
  return suite;
}

/** The native CLI's CSV of `scenario` as rows of numbers keyed by column name. */
export function cliRows(scenario) {
  const cli = new URL('../target/release/imlab', import.meta.url).pathname;
  const [header, ...lines] = execFileSync(cli, ['run', scenario], { maxBuffer: 1 << 30 })
    .toString()
    .trim()
    .split('\n');
  const names = header.split(',');
  return lines.map((l) => Object.fromEntries(l.split(',').map((v, i) => [names[i], Number(v)])));
}

/** Opens the walkthrough tab and waits until its plots are drawn (they ask the worker for their view). */
export async function openWalkthrough(page) {
  await page.click('[role=tab][data-tab=walkthrough]');
  await page.waitForFunction(() => window.imlab.walkthrough.charts.length === window.imlab.walkthrough.defs.length);
}

/** Clicks the first trajectory plot at `fraction` of its width and waits for the inspect panel. */
export async function inspectAt(page, fraction) {
  const over = page.locator('#plots .plot .u-over').first();
  await over.scrollIntoViewIfNeeded();
  const box = await over.boundingBox();
  await page.mouse.click(box.x + box.width * fraction, box.y + box.height / 2);
  await page.waitForSelector('#inspect:not([hidden]) tr[data-column]');
}

const AXE = readFileSync(new URL('../node_modules/axe-core/axe.min.js', import.meta.url), 'utf8');

/** axe-core's violations on the page as `rule(impact)×nodes: targets` (its context must bypass
 * the page's CSP to inject axe). */
export async function violations(page) {
  if (!(await page.evaluate(() => 'axe' in window))) await page.addScriptTag({ content: AXE });
  return page.evaluate(async () =>
    (await window.axe.run(document)).violations.map(
      (v) =>
        `${v.id}(${v.impact})×${v.nodes.length}: ${v.nodes
          .slice(0, 3)
          .map((n) => n.target.join(' '))
          .join(' | ')}`,
    ),
  );
}
