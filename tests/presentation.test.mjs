// Presentation mode, every lesson, at 1280×720 and 1024×768, in every language the page speaks:
// opened one after another, each lesson shows the plot its question is about (the lesson's `plot`)
// whole, its title, axes and legend inside the window and clipped by no box, beside its question,
// which its column holds without scrolling, set at 24 px or more; the model-error map's axis text
// is as large as the other plots'. One browser, one page a size and language, the lessons in turn,
// two pages at a time; each check waits on the page's own states.
import { describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, settled } from './browser.mjs';
import { LESSONS } from '../web/teaching/teaching.js';
import { LANGUAGES } from '../web/l10n/languages.js';

const suite = browserSuite();
// A smaller map than the lesson's own (3 cells × 2 seeds for 11 × 10): its plot is laid out the same.
const SMALL_MAP = { axis1: 'plant.rr=-10%..+10%:3', seeds: '1..2' };

/**
 * Where the open lesson's plot and question stand: each part of the plot that lies outside the
 * window or outside a box that clips it (an ancestor whose overflow is not visible), and the
 * question's column's heights.
 */
const placement = (page) =>
  page.evaluate(() => {
    const plot = /** @type {HTMLElement} */ (document.querySelector('.lesson-plot'));
    const panel = /** @type {HTMLElement} */ (document.querySelector('#lesson-panel'));
    const question = /** @type {HTMLElement} */ (panel.querySelector('.question'));
    const out = [];
    /** Names the sides of `r` that lie outside `box` (half a pixel of rounding allowed). */
    const past = (r, box) =>
      [
        r.top < box.top - 0.5 && `top ${Math.round(r.top)} < ${Math.round(box.top)}`,
        r.bottom > box.bottom + 0.5 && `bottom ${Math.round(r.bottom)} > ${Math.round(box.bottom)}`,
        r.left < box.left - 0.5 && `left ${Math.round(r.left)} < ${Math.round(box.left)}`,
        r.right > box.right + 0.5 && `right ${Math.round(r.right)} > ${Math.round(box.right)}`,
      ].filter(Boolean);
    const window_ = { top: 0, left: 0, bottom: innerHeight, right: innerWidth };
    const check = (name, e) => {
      if (!e) return out.push(`${name}: missing`);
      const r = e.getBoundingClientRect();
      out.push(...past(r, window_).map((p) => `${name} outside the window: ${p}`));
      for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) {
        const style = getComputedStyle(a);
        if (style.overflowX === 'visible' && style.overflowY === 'visible') continue;
        const clip = a.getBoundingClientRect();
        const box = {
          top: clip.top + a.clientTop,
          left: clip.left + a.clientLeft,
          bottom: clip.top + a.clientTop + a.clientHeight,
          right: clip.left + a.clientLeft + a.clientWidth,
        };
        out.push(...past(r, box).map((p) => `${name} clipped by ${a.tagName.toLowerCase()}.${a.className}: ${p}`));
      }
    };
    if (plot) {
      check('title', plot.querySelector('.u-title'));
      check('canvas (axes)', plot.querySelector('canvas'));
      check('legend', plot.querySelector('.u-legend'));
    } else out.push('no plot is marked as the lesson’s');
    check('question', question);
    return {
      out,
      plot: plot?.dataset.plot,
      tab: plot?.closest('[role=tabpanel]')?.id,
      column: [panel.scrollHeight, panel.clientHeight],
      size: parseFloat(getComputedStyle(question).fontSize),
      beside: question.getBoundingClientRect().left >= (plot?.getBoundingClientRect().right ?? Infinity),
    };
  });

/** Opens lesson `i` (Next from the lesson before) and waits for its plot to be shown. */
async function openLesson(page, i) {
  const lesson = LESSONS[i];
  const before = Number(await page.evaluate(() => document.body.dataset.started ?? 0));
  if (i === 0) {
    await page.click('#tab-lessons');
    await page.click('#lessons [data-lesson] >> nth=0');
  } else await page.click('#lesson-panel .next');
  await page.waitForFunction((n) => Number(document.body.dataset.started ?? 0) > n, before);
  // A lesson's run may run away (low speed): that is what it shows.
  assert.match(await settled(page), /^(done|failed)$/, lesson.id);
  if (lesson.map) {
    // The lesson fills the map's form; its map is run with fewer cells and seeds.
    await page.waitForFunction(
      (axis) => document.querySelector('#map-form [name=axis1]').value === axis,
      lesson.map.split(';')[0],
    );
    for (const [name, value] of Object.entries(SMALL_MAP)) await page.fill(`#map-form [name=${name}]`, value);
    await page.click('#map-run');
  }
  await page.waitForSelector(`#lesson-panel[data-shown="${lesson.id}"]`);
}

// Two pages run side by side, each with its own worker.
describe('presentation mode, every lesson', { concurrency: 2 }, () => {
  for (const [lang] of LANGUAGES)
    for (const [width, height] of [
      [1280, 720],
      [1024, 768],
    ])
      test(`${lang}: presentation mode at ${width}×${height}: every lesson shows its plot whole beside its whole question`, () =>
        suite.withPage(`?v=1&preset=step#present=1&lang=${lang}`, async (page) => {
          await page.setViewportSize({ width, height });
          await settled(page);
          // The lessons are listed once their texts are fetched (the tab pointed at, or the page idle).
          await page.hover('#tab-lessons');
          await page.waitForSelector('#lessons [data-lesson]', { state: 'attached' });
          assert.equal(await page.locator('#lessons [data-lesson]').count(), LESSONS.length);
          const found = [];
          for (const [i, lesson] of LESSONS.entries()) {
            await openLesson(page, i);
            const at = await placement(page);
            const where = `${lang}: lesson ${i + 1} (${lesson.id})`;
            assert.equal(at.plot, lesson.plot, `${where}: the plot marked`);
            assert.equal(at.tab, `panel-${lesson.tab ?? 'plots'}`, `${where}: the plot's tab`);
            if (at.column[0] > at.column[1]) at.out.push(`its column scrolls: ${at.column[0]} > ${at.column[1]} px`);
            if (at.size < 24) at.out.push(`its question is set at ${at.size} px`);
            if (!at.beside) at.out.push('its question does not stand beside the plot');
            found.push(...at.out.map((o) => `${where}: ${o}`));
            if (lesson.map) {
              // The map's axis text is as large as another plot's in presentation mode.
              const fonts = await page.evaluate(() => ({
                map: window.imlab.map()?.axes.map((a) => a.font[2]),
                speed: window.imlab.plots.drawn()[0].axes.map((a) => a.font[2]),
              }));
              assert.ok(fonts.map, `${where}: the map's plot is drawn`);
              for (const px of fonts.map)
                if (px < Math.min(...fonts.speed))
                  found.push(`${where}: the map's ticks are ${px} px, a plot's ${fonts.speed}`);
            }
          }
          assert.deepEqual(found, []);
        }));
});
