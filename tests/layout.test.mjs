// Layout on every screen: no page scrolls sideways from a 360 px phone to a 1920 px projector, on
// any tab; presentation mode at 1280×720 draws no text under 20 px; on a phone the plots come
// before the settings, which show only while their drawer is open. Each test fails on any console
// error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, openWalkthrough, settled } from './browser.mjs';
import { LANGS } from '../scripts/l10n-lint.mjs';
import { messagesOf } from './texts.mjs';

const suite = browserSuite();
const TABS = ['plots', 'walkthrough', 'lessons', 'analysis'];
// Presentation mode's floor, for text read from the back of a room at 1280×720 (CSS px).
const MIN_PRESENT_PX = 20;
// KaTeX sets a script at 0.7 and a script of a script at 0.5 of its equation's size; the floor
// holds for the equation and its scripts, not for second-level scripts (the k−1 in x̂_{k−1|k−1}).
const SECOND_LEVEL_SCRIPT = 0.6;

/** Opens `path` at `width`×`height`, waits for its run, then runs `body(page)`. */
const withPage = (path, [width, height], body) =>
  suite.withPage(path, async (page) => {
    await page.setViewportSize({ width, height });
    assert.equal(await settled(page), 'done');
    await body(page);
  });

/** Shows tab `name` and waits until its plots are drawn. */
async function showTab(page, name) {
  if (name === 'walkthrough') await openWalkthrough(page);
  else await page.click(`[role=tab][data-tab=${name}]`);
}

/** How far the page scrolls sideways, with the elements that stick out past the right edge. */
const sideways = (page) =>
  page.evaluate(() => {
    const over = document.documentElement.scrollWidth - innerWidth;
    const culprits =
      over <= 0
        ? []
        : [...document.querySelectorAll('body *')]
            .filter(
              (e) =>
                e.getBoundingClientRect().right > innerWidth + 0.5 &&
                e.checkVisibility() &&
                !e.closest('.katex-mathml'),
            )
            .slice(0, 5)
            .map(
              (e) =>
                `${e.tagName.toLowerCase()}${e.id ? `#${e.id}` : ''}.${[...e.classList].join('.')} right=${Math.round(e.getBoundingClientRect().right)}`,
            );
    return { over, culprits };
  });

for (const [width, height] of [
  [360, 740],
  [390, 844],
  [820, 1180],
  [1280, 720],
  [1920, 1080],
]) {
  test(`no page scrolls sideways at ${width} px on any tab${width >= 1280 ? ', also in presentation mode' : ', also with the settings open'}`, () =>
    withPage('?v=1&preset=step', [width, height], async (page) => {
      const check = async (where) => {
        // The plots follow a new viewport once the page has laid it out: wait for the page to stop
        // scrolling sideways (a busy machine lays out later), then report whatever still does.
        await page
          .waitForFunction(() => document.documentElement.scrollWidth <= window.innerWidth, null, { timeout: 10_000 })
          .catch(() => {});
        const { over, culprits } = await sideways(page);
        assert.ok(over <= 0, `${where}: the page scrolls ${over} px sideways; past the edge: ${culprits.join(', ')}`);
      };
      for (const tab of TABS) {
        await showTab(page, tab);
        await check(tab);
      }
      await showTab(page, 'plots');
      if (width >= 1280) {
        await page.click('#present');
        for (const tab of TABS) {
          await showTab(page, tab);
          await check(`presentation, ${tab}`);
        }
      }
      await page.click('#settings-toggle');
      assert.equal(await page.isVisible('#settings'), true);
      await check('settings open');
    }));
}

/**
 * The visible elements whose text is cut by their own box (wider or taller than a box that hides
 * what overflows it), as `tag#id.class: text`.
 */
const clipped = (page) =>
  page.evaluate(() =>
    [...document.querySelectorAll('body *')]
      .filter((e) => {
        // A tab's panel kept laid out while another shows, and a box meant to scroll, cut nothing.
        if (
          !e.checkVisibility({ checkVisibilityCSS: true }) ||
          e.closest('.sr-only, .katex, .u-over, canvas, .scroll-box')
        )
          return false;
        const style = getComputedStyle(e);
        if (style.contentVisibility === 'hidden') return false;
        const hides = (o) => o === 'hidden' || o === 'clip';
        return (
          (hides(style.overflowX) && e.scrollWidth > e.clientWidth + 1) ||
          (hides(style.overflowY) && e.scrollHeight > e.clientHeight + 1)
        );
      })
      .filter((e) => e.textContent.trim() !== '' && e.clientWidth > 1)
      .map(
        (e) => `${e.tagName.toLowerCase()}#${e.id}.${[...e.classList].join('.')}: ${e.textContent.trim().slice(0, 40)}`,
      ),
  );

// Every language on a phone and a wide screen: the page in that language, on every tab (the
// settings open, a lesson open) neither scrolls sideways nor cuts a text off in its box.
for (const lang of LANGS)
  test(`${lang}: at 390×844 and 1440×900 no tab scrolls sideways or cuts its text, with the settings and a lesson open`, () =>
    withPage(`?v=1&preset=step#lang=${lang}`, [390, 844], async (page) => {
      assert.equal(await page.evaluate(() => document.documentElement.lang), lang);
      const run = messagesOf(lang, 'page.ftl').get('run-button');
      assert.equal((await page.textContent('#run'))?.trim(), run?.trim(), 'the Run button speaks the language');
      const found = [];
      const check = async (where) => {
        // The plots follow a new viewport once the page has laid it out: wait for the page to stop
        // scrolling sideways (a busy machine lays out later), then report whatever still does.
        await page
          .waitForFunction(() => document.documentElement.scrollWidth <= window.innerWidth, null, { timeout: 10_000 })
          .catch(() => {});
        const { over, culprits } = await sideways(page);
        if (over > 0)
          found.push(`${where}: the page scrolls ${over} px sideways; past the edge: ${culprits.join(', ')}`);
        found.push(...(await clipped(page)).map((c) => `${where}: cut off: ${c}`));
      };
      for (const size of [
        [390, 844],
        [1440, 900],
      ]) {
        await page.setViewportSize({ width: size[0], height: size[1] });
        for (const tab of [...TABS, 'challenge']) {
          await showTab(page, tab);
          await check(`${size[0]} px, ${tab}`);
        }
        await showTab(page, 'plots');
        // A wide screen shows the settings beside the plots; a phone opens them from the run bar.
        const drawer = await page.isVisible('#settings-toggle');
        if (drawer) await page.click('#settings-toggle');
        await check(`${size[0]} px, settings open`);
        if (drawer) await page.click('#settings-toggle');
      }
      await showTab(page, 'lessons');
      await page.click('#lessons [data-lesson] >> nth=3');
      await page.waitForSelector('#lesson-panel:not([hidden])');
      await page.click('#lesson-panel .hint summary');
      await check('1440 px, a lesson open');
      await page.setViewportSize({ width: 390, height: 844 });
      await check('390 px, a lesson open');
      assert.deepEqual(found, []);
    }));

/**
 * The smallest font size of visible text on the page: every non-blank text node whose element has
 * a box and is not visually hidden (.sr-only, KaTeX's MathML copy), with where it is.
 */
const smallestText = (page, where) =>
  page.evaluate(
    ({ where, secondLevel }) => {
      const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
      let smallest = { px: Infinity, text: '' };
      for (let node = walker.nextNode(); node; node = walker.nextNode()) {
        const e = node.parentElement;
        if (!node.data.trim() || e.closest('.sr-only, .katex-mathml, script, style, option')) continue;
        const box = e.getBoundingClientRect();
        if (box.width <= 1 || box.height <= 1 || !e.checkVisibility({ checkVisibilityCSS: true })) continue;
        const px = parseFloat(getComputedStyle(e).fontSize);
        const equation = e.closest('.katex');
        if (equation && px < secondLevel * parseFloat(getComputedStyle(equation).fontSize)) continue;
        if (px < smallest.px) {
          const owner = e.closest('[id], [class]');
          smallest = {
            px,
            text: node.data.trim().slice(0, 40),
            in: `${owner?.tagName.toLowerCase()}#${owner?.id}.${owner?.className}`,
            where,
          };
        }
      }
      return smallest;
    },
    { where, secondLevel: SECOND_LEVEL_SCRIPT },
  );

test('presentation mode at 1280×720 shows no text under 20 px: every tab, the drawer, the inspect sheet, a lesson', () =>
  withPage('?v=1&preset=step', [1280, 720], async (page) => {
    await page.click('#present');
    const found = [];
    for (const tab of TABS) {
      await showTab(page, tab);
      found.push(await smallestText(page, tab));
    }
    await page.click('#settings-toggle');
    found.push(await smallestText(page, 'settings drawer'));
    await page.click('#settings-toggle');
    await showTab(page, 'walkthrough');
    await page.locator('#section-ekf .plot').first().scrollIntoViewIfNeeded();
    await inspectAt(page.locator('#section-ekf .plot .u-over').first(), page);
    found.push(await smallestText(page, 'inspect sheet'));
    await page.keyboard.press('Escape');
    await showTab(page, 'lessons');
    const runs = Number(await page.evaluate(() => document.body.dataset.run));
    await page.click('#lessons [data-lesson]');
    await page.waitForFunction((n) => Number(document.body.dataset.run) > n, runs);
    await page.waitForSelector('#lesson-panel:not([hidden])');
    await page.click('#lesson-panel .hint summary');
    found.push(await smallestText(page, 'lesson panel'));
    for (const f of found) assert.ok(f.px >= MIN_PRESENT_PX, `${f.where}: “${f.text}” in ${f.in} is ${f.px} px`);
  }));

/** Clicks the middle of the plot area `over` and waits for the inspect sheet. */
async function inspectAt(over, page) {
  const box = await over.boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  await page.waitForSelector('#inspect:not([hidden]) tr[data-column]');
}

test('on a phone the plots come before the settings, which show under the run bar only while the drawer is open', () =>
  withPage('?v=1&preset=step', [390, 844], async (page) => {
    const layout = () =>
      page.evaluate(() => {
        const rect = (s) => document.querySelector(s).getBoundingClientRect();
        const fields = [...document.querySelectorAll('#settings input, #settings select')].filter((e) =>
          e.checkVisibility(),
        );
        return {
          plot: rect('#plots .plot').top,
          runBar: rect('.run-bar').bottom,
          results: rect('#results').top,
          form: document.querySelector('#settings').checkVisibility() ? rect('#settings').top : null,
          fieldsAbovePlot: fields.filter((e) => e.getBoundingClientRect().top < rect('#plots .plot').top).length,
        };
      });
    const closed = await layout();
    assert.equal(closed.form, null, 'the settings form shows before the drawer is opened');
    assert.equal(closed.fieldsAbovePlot, 0);
    assert.ok(closed.plot < 1.5 * 844, `the first plot starts ${closed.plot} px down`);
    assert.equal(await page.getAttribute('#settings-toggle', 'aria-expanded'), 'false');
    await page.click('#settings-toggle');
    assert.equal(await page.getAttribute('#settings-toggle', 'aria-expanded'), 'true');
    const open = await layout();
    assert.ok(open.form !== null && open.form >= open.runBar && open.form < open.results, JSON.stringify(open));
    // The plots keep their width: the drawer pushes them down, not aside.
    assert.equal(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth), true);
    await page.click('#settings-toggle');
    assert.deepEqual(await layout(), closed);
  }));

test('the inspect sheet leaves the plot that was clicked in view above it, and closes from its button', () =>
  withPage('?v=1&preset=step', [390, 844], async (page) => {
    // The third plot is below the fold; the sheet must not land on it.
    // Its chart is drawn as it comes near the viewport.
    await page.locator('#plots .plot').nth(2).scrollIntoViewIfNeeded();
    const over = page.locator('#plots .plot').nth(2).locator('.u-over');
    await over.scrollIntoViewIfNeeded();
    await page.evaluate(() => window.scrollBy(0, -innerHeight / 2 + 200));
    await inspectAt(over, page);
    const { plot, sheet } = await page.evaluate(() => ({
      plot: document.querySelectorAll('#plots .plot .u-wrap')[2].getBoundingClientRect().toJSON(),
      sheet: document.querySelector('#inspect').getBoundingClientRect().toJSON(),
    }));
    assert.ok(plot.top >= 0 && plot.bottom <= sheet.top, `plot ${plot.top}–${plot.bottom}, sheet from ${sheet.top}`);
    assert.equal(await page.locator('#inspect h2').count(), 1);
    await page.getByRole('button', { name: 'Close (Esc)' }).click();
    assert.equal(await page.isHidden('#inspect'), true);
    assert.equal(await page.evaluate(() => document.activeElement.dataset.plot), 'flux', 'focus returns to the plot');
  }));

test('after a frequency sweep on a phone the page still does not scroll sideways', () =>
  withPage('?v=1&preset=step', [390, 844], async (page) => {
    await showTab(page, 'analysis');
    // A small sweep: three frequencies, each run long enough for one period in its fit window.
    for (const [name, value] of [
      ['lo', '100'],
      ['n', '3'],
      ['duration', '0.05'],
    ])
      await page.fill(`#sweep-form [name=${name}]`, value);
    await page.click('#sweep-run');
    await page.waitForFunction(
      () => document.querySelector('#sweep-table').rows.length > 1 && !document.querySelector('#sweep-run').disabled,
    );
    const { over, culprits } = await sideways(page);
    assert.ok(over <= 0, `the page scrolls ${over} px sideways; past the edge: ${culprits.join(', ')}`);
  }));

/** The first main plot's box, from its title to its legend, and its time axis's box. */
const firstPlot = (page) =>
  page.$eval('#plots .plot', (p) => {
    const box = (e) => {
      const r = e.getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, height: r.height };
    };
    return { plot: box(p), canvas: box(p.querySelector('canvas')), title: p.querySelector('.u-title').textContent };
  });

for (const [width, height] of [
  [1280, 720],
  [1024, 768],
]) {
  test(`presentation mode at ${width}×${height}: the first screen shows the main plot whole and the key figures, the strip one click away`, () =>
    withPage('?v=1&preset=rr-mismatch#present=1', [width, height], async (page) => {
      const { plot, canvas } = await firstPlot(page);
      // Title, axes (the canvas holds them) and legend on the first screen, with room to read.
      assert.ok(plot.top >= 0 && plot.bottom <= height, `the first plot spans ${plot.top}–${plot.bottom} px`);
      assert.ok(canvas.height >= 250, `the first plot's axes are ${canvas.height} px tall`);
      assert.equal(await page.isVisible('#key-figures'), true);
      assert.match(
        await page.textContent('#key-figures'),
        /RMS of ω − ω_d .* · final ω − ω_d -5\.02 rad\/s \(still changing\)/,
      );
      assert.equal(await page.isVisible('#figures'), false);
      await page.click('#figures-toggle');
      assert.equal(await page.isVisible('#figures'), true);
      assert.equal(await page.getAttribute('#figures-toggle', 'aria-expanded'), 'true');
    }));

  test(`presentation mode at ${width}×${height} with a lesson open: the main plot whole beside the lesson, its question large on the first screen`, () =>
    withPage('?v=1&preset=step#present=1', [width, height], async (page) => {
      await page.click('#tab-lessons');
      const before = await page.evaluate(() => Number(document.body.dataset.started));
      await page.click('#lessons button[data-lesson="v=1&preset=step"]');
      await page.waitForFunction((n) => Number(document.body.dataset.started) > n, before);
      await settled(page);
      // The plot is sized as the layout settles (the key figures, the lesson's column).
      await page.waitForFunction((h) => {
        const r = document.querySelector('#plots .plot').getBoundingClientRect();
        return r.top >= 0 && r.bottom <= h;
      }, height);
      const { plot, canvas, title } = await firstPlot(page);
      assert.equal(title, 'Rotor speed');
      assert.ok(canvas.height >= 200, `the first plot's axes are ${canvas.height} px tall`);
      const question = await page.$eval('#lesson-panel .question', (q) => {
        const r = q.getBoundingClientRect();
        return { top: r.top, bottom: r.bottom, left: r.left, size: parseFloat(getComputedStyle(q).fontSize) };
      });
      assert.ok(
        question.top >= 0 && question.bottom <= height,
        `the question spans ${question.top}–${question.bottom} px`,
      );
      assert.ok(question.size >= 24, `the question is set at ${question.size} px`);
      assert.ok(question.left >= width / 2, 'the lesson stands beside the plot, not above it');
      assert.ok(plot.bottom <= height);
    }));
}
