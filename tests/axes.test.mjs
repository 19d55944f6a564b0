// Axes that can be read at every zoom: on every preset, in the whole run and in windows of 10 ms
// and 1 ms at three places, with the y-axes fitted after the start-up transient and not, every
// drawn sample of every plot (trajectory and walkthrough) lies inside its own axis's range, and
// every axis's tick labels are distinct and read back as their ticks. Each test fails on any
// console error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { browserSuite, openWalkthrough, settled } from './browser.mjs';

const cli = new URL('../target/release/imlab', import.meta.url).pathname;
const PRESETS = execFileSync(cli, ['list'])
  .toString()
  .trim()
  .split('\n')
  .map((l) => l.split(/\s+/)[0]);
// Window widths (s): 200 and 20 samples at 20 kHz.
const WINDOWS = [0.01, 0.001];
// Where the windows sit, as fractions of the run: in or near the start-up transient, the middle
// and near the end.
const PLACES = [0.1, 0.5, 0.9];
// The most decades a log axis spans (plots/ranges.js, logRange).
const LOG_DECADES = 14;

const suite = browserSuite();

/**
 * What is wrong with the plots as drawn now, one line each: samples outside their axis's range
 * (with the fit on, only those after the transient count, unless a plot has none after it), and
 * tick labels that repeat or do not read back as their ticks to within half the tick spacing.
 */
const problems = (page) =>
  page.evaluate(async (LOG_DECADES) => {
    // Every plot, including those not near the viewport, which a lazy set has not drawn yet.
    window.imlab.plots.drawAll();
    const { fit, from } = window.imlab.plots.framing();
    const found = [];
    const sets = [
      ['plots', window.imlab.plots.charts],
      ['walkthrough', window.imlab.walkthrough.charts],
    ];
    for (const [set, charts] of sets) {
      for (const u of charts) {
        const name = `${set} '${u.root.parentElement.dataset.plot}'`;
        const t = u.data[0];
        const fitted = fit && t.some((x) => x >= from);
        for (let s = 1; s < u.series.length; s++) {
          const series = u.series[s];
          if (!series.show) continue;
          const { min, max, distr } = u.scales[series.scale];
          let out = 0;
          let example = null;
          u.data[s].forEach((v, j) => {
            if (v == null || !Number.isFinite(v) || (fitted && t[j] < from)) return;
            // A log axis has no place for zero, and spans at most LOG_DECADES below its top: a
            // signal that falls further (an exponential bound) leaves it by design.
            if (distr === 3 && (v <= 0 || (v < min && max / min >= 10 ** LOG_DECADES / 2))) return;
            if (v < min || v > max) {
              out += 1;
              example ??= `${v} at t = ${t[j]}`;
            }
          });
          if (out)
            found.push(
              `${name} ${series.label}: ${out} of ${u.data[s].length} samples outside [${min}, ${max}], e.g. ${example}`,
            );
        }
        u.axes.forEach((axis, i) => {
          if (!axis.show || !axis._show || !axis._values) return;
          const ticks = axis._splits;
          const labels = axis._values.map((l, j) => [l == null ? '' : String(l), ticks[j]]).filter(([l]) => l !== '');
          const texts = labels.map(([l]) => l);
          if (new Set(texts).size !== texts.length)
            found.push(`${name} axis ${i} (${axis.scale}): repeated tick labels ${texts.join(' | ')}`);
          let gap = Infinity;
          for (let j = 1; j < ticks.length; j++) gap = Math.min(gap, Math.abs(ticks[j] - ticks[j - 1]));
          const off = labels.filter(([l, v]) => !(Math.abs(Number(l) - v) < gap / 2));
          if (off.length)
            found.push(`${name} axis ${i} (${axis.scale}): labels ${off.map(([l, v]) => `${l} for ${v}`).join(', ')}`);
        });
      }
    }
    return found;
  }, LOG_DECADES);

/** Waits until the main plots show the view asked for last, and the walkthrough's the same span. */
const viewShown = (page) =>
  page.waitForFunction(() => {
    const { plots, walkthrough } = window.imlab;
    const w = plots.window;
    const whole = w === null || (w[0] <= plots.full[0] && w[1] >= plots.full[1]);
    const view = document.body.dataset.view ?? '';
    if (whole ? !view.startsWith('0,') : view !== `${w[0]},${w[1]}`) return false;
    const t = plots.charts[0].data[0];
    return walkthrough.charts.every((c) => c.data[0][0] === t[0] && c.data[0].at(-1) === t.at(-1));
  });

/** Drags across the speed plot from time t0 to t1 of its current window and waits for the view. */
async function zoom(page, t0, t1) {
  const over = page.locator('#plots .plot[data-plot=speed] .u-over');
  await over.scrollIntoViewIfNeeded();
  const box = await over.boundingBox();
  const { min, max } = await page.evaluate(() => window.imlab.plots.charts[0].scales.x);
  const x = (t) => box.x + (box.width * (t - min)) / (max - min);
  await page.mouse.move(x(t0), box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(x(t1), box.y + box.height / 2, { steps: 5 });
  await page.mouse.up();
  await viewShown(page);
  const shown = await page.evaluate(() => window.imlab.plots.window);
  assert.ok(shown && Math.abs(shown[1] - shown[0] - (t1 - t0)) < 0.2 * (t1 - t0), `asked ${t0}–${t1}, got ${shown}`);
}

for (const preset of PRESETS) {
  test(`${preset}: every sample inside its axis and distinct tick labels, whole run and zoomed, fitted or not`, () =>
    suite.withPage(`?v=1&preset=${preset}`, async (page) => {
      assert.equal(await settled(page), 'done');
      await openWalkthrough(page);
      await page.click('[role=tab][data-tab=plots]');
      const found = [];
      const check = async (view) => {
        for (const fit of [true, false]) {
          await page.setChecked('#fit', fit);
          found.push(...(await problems(page)).map((p) => `${view}, fit ${fit ? 'on' : 'off'}: ${p}`));
        }
      };
      await check('whole run');
      const [start, end] = await page.evaluate(() => window.imlab.plots.full);
      for (const place of PLACES) {
        const centre = start + place * (end - start);
        for (const width of WINDOWS) {
          // Each window inside the last, so that the drag spans enough pixels.
          const t0 = Math.min(Math.max(centre - width / 2, start), end - width);
          await zoom(page, t0, t0 + width);
          await check(`${width * 1e3} ms at ${t0.toFixed(4)} s`);
        }
        await page.click('#full-run');
        await viewShown(page);
      }
      assert.deepEqual(found, []);
    }));
}
