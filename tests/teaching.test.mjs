// Browser tests of the teaching layer: equations, the inspect panel, lessons, comparison.
import { test } from 'node:test';
import { lessonsIn } from './texts.mjs';

const LESSONS = lessonsIn('en');
import assert from 'node:assert/strict';
import { browserSuite, cliRows, inspectAt, openWalkthrough, settled } from './browser.mjs';

const suite = browserSuite();
/** Opens the app at `query`, waits for its run, then runs `body(page)`. */
const withPage = (query, body) =>
  suite.withPage(`?${query}`, async (page) => {
    assert.equal(await settled(page), 'done');
    await body(page);
  });

test('every walkthrough section renders its equations with no KaTeX error', () =>
  withPage('v=1&preset=step', async (page) => {
    await openWalkthrough(page);
    const sections = await page.$$eval('#walkthrough section.step', (ss) =>
      ss.map((s) => ({
        id: s.id,
        equations: s.querySelectorAll('.equation').length,
        rendered: s.querySelectorAll('.equation > .katex').length,
      })),
    );
    assert.equal(sections.length, 8);
    for (const s of sections) {
      assert.ok(s.equations >= 2, `${s.id} has ${s.equations} equations`);
      assert.equal(s.rendered, s.equations, `${s.id}: rendered ${s.rendered} of ${s.equations}`);
    }
    assert.equal(await page.locator('.katex-error').count(), 0);
    // Each section shows live signals from the run and its design knobs; each backstepping step
    // also its error's rate against the designed one, and the residual of a law of one's own
    // (empty without one).
    assert.equal(await page.locator('#walkthrough .plot canvas').count(), 22);
    for (const key of ['k1', 'k2', 'k3', 'k4', 'ekf\\.q', 'ekf\\.r_std'])
      assert.equal(await page.locator(`#knob-${key}`).count(), 1, key);
    assert.match(await page.textContent('#section-stability .stability-report'), /of 2000 samples|all 2000 samples/);
    // On a phone every equation wraps within the column: none is cut or scrolls sideways.
    await page.setViewportSize({ width: 390, height: 844 });
    const over = await page.$$eval('#walkthrough .equation', (list) =>
      list
        .filter((e) => e.scrollWidth > e.clientWidth + 1 || e.scrollHeight > e.clientHeight + 1)
        .map(
          (e) =>
            `${e.textContent.slice(0, 40)}: ${e.scrollWidth}×${e.scrollHeight} in ${e.clientWidth}×${e.clientHeight}`,
        ),
    );
    assert.deepEqual(over, []);
  }));

test('a design knob edits the scenario like the settings form', () =>
  withPage('v=1&preset=step', async (page) => {
    await page.click('[data-tab=walkthrough]');
    await page.fill('#knob-k3', '900');
    await page.press('#knob-k3', 'Tab');
    await page.waitForFunction(() => location.search.includes('k3=900'));
    assert.equal(await page.inputValue('#field-k3'), '900');
  }));

test('the inspect panel holds the CLI CSV values of the clicked sample', () =>
  withPage('v=1&preset=step&seed=3', async (page) => {
    await inspectAt(page, 0.53);
    const shown = await page.$$eval('#inspect tr[data-column]', (rows) =>
      rows.map((r) => [r.dataset.column, r.querySelector('td').dataset.exact]),
    );
    const heading = await page.textContent('#inspect h2');
    const k = Number(/k = (\d+)/.exec(heading)[1]);
    assert.ok(k > 900 && k < 1300, `k = ${k}`);
    const row = cliRows('v=1&preset=step&seed=3')[k];
    assert.ok(shown.length >= 30);
    for (const [column, text] of shown) assert.equal(Number(text), row[column], column);
    assert.equal(Number(/t = ([\d.]+) s/.exec(heading)[1]), Number(row.t.toFixed(6)));
  }));

test('the Euler/RK4 comparison shows the observer limiting the 200 Hz sine', () =>
  withPage('v=1&preset=sine200', async (page) => {
    await page.click('[data-tab=walkthrough]');
    await page.click('#section-ekf button.compare');
    await page.waitForSelector('#section-ekf .compare-result table');
    const rows = await page.$$eval('#section-ekf .compare-result tr', (trs) =>
      trs.slice(1).map((tr) => [...tr.children].map((c) => c.textContent)),
    );
    assert.deepEqual(
      rows.map((r) => r[0]),
      ['euler', 'rk4'],
    );
    const [euler, rk4] = rows.map((r) => ({ tracking: Number(r[1]), nis: Number(r[4]) }));
    assert.ok(rk4.tracking < euler.tracking / 2, `tracking RMS euler ${euler.tracking}, rk4 ${rk4.tracking}`);
    assert.ok(euler.nis > 10 && rk4.nis < 2.5, `mean NIS euler ${euler.nis}, rk4 ${rk4.nis}`);
    // The share at the limit reads as the figures strip writes it, a percentage.
    for (const r of rows) assert.match(r[5], /^\d+(\.\d+)? %$/);
  }));

test('presentation mode enlarges text and plots', () =>
  withPage('v=1&preset=step', async (page) => {
    const size = () =>
      page.evaluate(() => [
        parseFloat(getComputedStyle(document.body).fontSize),
        document.querySelector('#plots canvas').clientHeight,
      ]);
    const [font0, plot0] = await size();
    await page.click('#present');
    const [font1, plot1] = await size();
    assert.ok(font1 > font0 && plot1 > plot0, `${font0}→${font1}, ${plot0}→${plot1}`);
  }));

test('the load-estimation lesson runs and its walkthrough plot shows the load estimate against the true load', () =>
  withPage('v=1&preset=step', async (page) => {
    await page.click('[role=tab][data-tab=lessons]');
    const n = await page.evaluate(() =>
      [...document.querySelectorAll('#lessons .lesson')].findIndex((l) =>
        /preset load-step-est|load as an EKF state/.test(l.textContent),
      ),
    );
    assert.ok(n >= 0, 'lesson listed');
    await page.click(`text=Start lesson ${n + 1}`);
    await page.waitForFunction(
      () => document.body.dataset.scenario === 'v=1&preset=load-step-est' && document.body.dataset.state === 'done',
      null,
      { timeout: 30_000 },
    );
    assert.equal(await page.isVisible('#panel-walkthrough'), true);
    // The plot's series are the core's columns at recorded samples: the estimate ends at the
    // true 2.5 N m within its band, and the truth steps from 0.5 to 2.5 N m at 0.15 s.
    const series = await page.evaluate(() => {
      const set = window.imlab.walkthrough;
      const i = set.defs.findIndex((d) => d.title.startsWith('Load torque'));
      const chart = set.charts[i];
      const label = (l) => chart.series.findIndex((s) => s.label === l);
      const last = (k) => chart.data[k][chart.data[k].length - 1];
      return {
        estimate: last(label('T̂_L estimated')),
        truth: last(label('T_L true (T0 + step)')),
        first: chart.data[label('T_L true (T0 + step)')][0],
        upper: last(label('T̂_L + 2σ')),
      };
    });
    assert.equal(series.first, 0.5);
    assert.equal(series.truth, 2.5);
    assert.ok(Math.abs(series.estimate - 2.5) < 0.1, `load estimate ${series.estimate} N m`);
    assert.ok(series.upper > series.estimate, 'band above the estimate');
  }));

test('the real-drive lesson runs with PWM, shows the ripple and the current against the rating, and its delay compensation re-runs', () =>
  withPage('v=1&preset=step', async (page) => {
    await page.click('[role=tab][data-tab=lessons]');
    const n = await page.evaluate(() =>
      [...document.querySelectorAll('#lessons .lesson')].findIndex((l) => /real drive/.test(l.textContent)),
    );
    assert.ok(n >= 0, 'lesson listed');
    await page.click(`text=Start lesson ${n + 1}`);
    const run = LESSONS.find((l) => /real drive/.test(l.title)).run;
    await page.waitForFunction(
      (s) => document.body.dataset.scenario === s && document.body.dataset.state === 'done',
      run,
      { timeout: 30_000 },
    );
    const figure = (name) =>
      page.evaluate((k) => {
        const item = document.querySelector(`#figures [data-name=${k}]`);
        return item && { value: Number(item.dataset.value), text: item.textContent };
      }, name);
    const ripple = await figure('ripple_peak');
    assert.ok(ripple.value > 0 && ripple.value < 0.5, `ripple ${ripple.value} A`);
    const current = await figure('current_peak');
    assert.match(current.text, /× the rated 4 A/);
    const rmsDelayed = (await figure('tracking_rms')).value;
    // The Drive group offers the compensation; ticking it and running gives the compensated run.
    if (await page.isVisible('#settings-toggle')) await page.click('#settings-toggle');
    await page.click('details[data-group=drive] > summary');
    await page.check('#field-delay\\.comp');
    await page.click('#run');
    await page.waitForFunction(
      (s) => document.body.dataset.scenario === s && document.body.dataset.state === 'done',
      `${run}&delay.comp=1`,
      { timeout: 30_000 },
    );
    assert.notEqual((await figure('tracking_rms')).value, rmsDelayed);
  }));
