// Keyboard, screen-reader and embed access: axe-core finds nothing on any tab, with the inspect
// panel open, in presentation mode, on a phone and on a desktop; the page works from the keyboard
// alone; an embed shows one plot that runs, in an iframe too. Each test fails on any console error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, inspectAt, settled, violations } from './browser.mjs';

// The server and the browser of this file; pages here need contexts of their own.
const suite = browserSuite();

/** Opens `path` at `width`×`height` (axe is injected, so the context bypasses the CSP); runs `body`. */
async function withPage(path, [width, height], body) {
  const errors = [];
  const context = await suite.browser.newContext({ viewport: { width, height }, bypassCSP: true });
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  try {
    await page.goto(`${suite.server.url}${path}`);
    await settled(page);
    await body(page);
  } finally {
    await context.close();
  }
  assert.deepEqual(errors, [], 'console errors');
}

for (const viewport of [
  [390, 844],
  [1440, 900],
]) {
  test(`axe-core finds no violations at ${viewport.join('×')}: every tab, inspect open, presentation mode`, () =>
    withPage('?v=1&preset=step', viewport, async (page) => {
      const found = {};
      for (const tab of ['walkthrough', 'lessons', 'analysis', 'challenge', 'plots']) {
        await page.click(`[role=tab][data-tab=${tab}]`);
        found[tab] = await violations(page);
      }
      await inspectAt(page, 0.5);
      found.inspect = await violations(page);
      await page.keyboard.press('Escape');
      await page.click('#present');
      found.presentation = await violations(page);
      await page.click('#settings-toggle');
      found['presentation, settings open'] = await violations(page);
      for (const [where, list] of Object.entries(found)) assert.deepEqual(list, [], where);
      // axe 4.14 no longer checks ids; every id on the page is unique (knobs appear in several
      // walkthrough sections).
      const ids = await page.$$eval('[id]', (list) => list.map((e) => e.id));
      assert.deepEqual(
        ids.filter((id, i) => ids.indexOf(id) !== i),
        [],
        'duplicate ids',
      );
    }));
}

test('a preset is chosen and run from the keyboard; arrow keys on the picker start no run', () =>
  withPage('?v=1&preset=step', [1280, 800], async (page) => {
    const run = () => page.evaluate(() => Number(document.body.dataset.run));
    const started = () => page.evaluate(() => Number(document.body.dataset.started));
    const first = await run();
    const firstStarted = await started();
    // The skip link is the first stop and leads to the results.
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement.className), 'skip-link');
    await page.focus('#preset');
    await page.keyboard.press('ArrowDown');
    await page.keyboard.press('ArrowDown');
    const chosen = await page.inputValue('#preset');
    await page.keyboard.press('Enter');
    await page.waitForFunction((n) => Number(document.body.dataset.run) > n, first);
    await settled(page);
    // The worker answers in order, so a run the arrow keys had started would have come first.
    assert.equal(await started(), firstStarted + 1, 'arrow keys started a run');
    assert.match(await page.evaluate(() => document.body.dataset.scenario), new RegExp(`preset=${chosen}$`));
    // Run from the keyboard; focus is back on Run afterwards.
    await page.focus('#run');
    await page.keyboard.press('Enter');
    await page.waitForFunction((n) => Number(document.body.dataset.run) > n + 1, first);
    await settled(page);
    assert.equal(await page.evaluate(() => document.activeElement.id), 'run');
  }));

test('the tabs follow the WAI-ARIA pattern: one tab stop, arrow keys, panels labelled', () =>
  withPage('?v=1&preset=step', [1280, 800], async (page) => {
    const tabs = await page.$$eval('[role=tablist] > *', (list) =>
      list.map((t) => [t.getAttribute('role'), t.tabIndex, t.getAttribute('aria-controls')]),
    );
    assert.deepEqual(
      tabs.map((t) => t[0]),
      ['tab', 'tab', 'tab', 'tab', 'tab'],
      'only tabs inside the tablist',
    );
    assert.deepEqual(
      tabs.map((t) => t[1]),
      [0, -1, -1, -1, -1],
    );
    await page.focus('#tab-plots');
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.evaluate(() => document.activeElement.id), 'tab-walkthrough');
    assert.equal(await page.isVisible('#panel-walkthrough'), true);
    await page.keyboard.press('End');
    assert.equal(await page.evaluate(() => document.activeElement.id), 'tab-challenge');
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.evaluate(() => document.activeElement.id), 'tab-plots');
    assert.equal(await page.getAttribute('#panel-plots', 'aria-labelledby'), 'tab-plots');
  }));

test('a focused plot moves the inspect cursor with the arrow keys, by one sample or 1 % of the window', () =>
  withPage('?v=1&preset=step', [1280, 800], async (page) => {
    const plot = page.locator('#plots .plot').first();
    // Its text alternative names the signals and carries the run's figures.
    const caption = await page.textContent(`#${await plot.getAttribute('aria-describedby')}`);
    assert.match(caption, /ω true/);
    assert.match(caption, /Figures of this run: .*settling/i);
    await plot.focus();
    const marked = () => page.evaluate(() => window.imlab.plots.marker);
    await page.keyboard.press('Home');
    assert.equal(await marked(), 0);
    await page.keyboard.press('ArrowRight');
    assert.equal(await marked(), 5e-5, 'one sample of Ts = 50 µs');
    const { min, max } = await page.evaluate(() => window.imlab.plots.charts[0].scales.x);
    await page.keyboard.press('Shift+ArrowRight');
    // One percent of the window on from sample 1, then snapped to the nearest sample by the inspect
    // replay: t = 1.0495 ms is sample 21.
    assert.equal(Math.round((5e-5 + (max - min) / 100) / 5e-5), 21);
    await page.waitForFunction(() =>
      /Inspect sample k = 21,/.test(document.querySelector('#inspect')?.textContent ?? ''),
    );
    assert.ok(Math.abs((await marked()) - 21 * 5e-5) < 1e-15);
  }));

test('presentation mode is in the URL fragment and draws plot text at least 20 px', () =>
  withPage('?v=1&preset=step#present=1', [1280, 720], async (page) => {
    assert.equal(await page.getAttribute('#present', 'aria-pressed'), 'true');
    const fonts = await page.evaluate(() => window.imlab.plots.charts[0].axes.map((a) => a.font[0]));
    for (const font of fonts) assert.ok(parseFloat(font) >= 20, font);
    await page.click('#present');
    assert.doesNotMatch(await page.evaluate(() => location.hash), /present/);
  }));

test('an embed shows one plot, runs, and loads in an iframe snippet', () =>
  withPage('?v=1&preset=step#embed=speed', [720, 520], async (page) => {
    const visiblePlots = () =>
      page.$$eval('.plot', (list) => list.filter((p) => p.offsetParent !== null).map((p) => p.dataset.plot));
    assert.deepEqual(await visiblePlots(), ['speed']);
    for (const hidden of ['#settings', '[role=tablist]', 'header'])
      assert.equal(await page.isVisible(hidden), false, hidden);
    assert.equal(await page.isVisible('#key-figures'), true);
    // The plot fills the frame under the run row: the frame shows it whole.
    const bottom = await page.$eval('.plot.embedded', (p) => p.getBoundingClientRect().bottom);
    assert.ok(bottom <= 520, `the plot ends at ${bottom} px of 520`);
    const before = Number(await page.evaluate(() => document.body.dataset.run));
    await page.click('#run');
    await page.waitForFunction((n) => Number(document.body.dataset.run) > n, before);
    // The snippet "Copy embed code" gives, in a page of its own.
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
    await page.evaluate(() => {
      document.body.classList.remove('embed');
    });
    await page.click('#copy-embed');
    const snippet = await page.evaluate(() => navigator.clipboard.readText());
    // It embeds the plots in view: at 720×520, the speed plot alone.
    assert.match(
      snippet,
      /^<iframe src="http:\/\/127\.0\.0\.1:\d+\/\?v=1&preset=step#embed=speed&lang=en" title="IM Lab: step, speed"/,
    );
    const host = await page.context().newPage();
    await host.setContent(`<!doctype html><title>course page</title>${snippet}`);
    const frame = await (await host.waitForSelector('iframe')).contentFrame();
    await frame.waitForFunction(() => document.body.dataset.state === 'done', null, { timeout: 30_000 });
    assert.equal(await frame.$$eval('.plot', (list) => list.filter((p) => p.offsetParent !== null).length), 1);
  }));

test('Copy embed code embeds the plots in view, and an unknown plot is named until the user runs', () =>
  withPage('?v=1&preset=step#embed=speed,nope,flux', [900, 800], async (page) => {
    assert.deepEqual(
      await page.$$eval('.plot', (list) => list.filter((p) => p.offsetParent !== null).map((p) => p.dataset.plot)),
      ['speed', 'flux'],
    );
    assert.match(await page.textContent('#message'), /No plot named 'nope'; showing speed, flux\./);
    // Both plots fit the frame.
    const bottom = await page.$$eval('.plot.embedded', (ps) =>
      Math.max(...ps.map((p) => p.getBoundingClientRect().bottom)),
    );
    assert.ok(bottom <= 800, `the plots end at ${bottom} px of 800`);
    const before = Number(await page.evaluate(() => document.body.dataset.run));
    await page.click('#run');
    await page.waitForFunction((n) => Number(document.body.dataset.run) > n, before);
    assert.doesNotMatch(await page.textContent('#message'), /No plot named/);
  }));
