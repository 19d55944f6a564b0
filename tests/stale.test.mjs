// Browser tests of results kept from an earlier scenario: the model-error map, the sweep, the seed
// bands, a challenge's verdict and the predictor comparison stay on screen when the settings
// change, marked as the earlier scenario's (greyed, with what to press; an export that does not
// name its scenario off) until they are run again for the settings or the settings return to their
// scenario. Lesson 12's map, run as a student runs it, is marked once the scenario changes as the
// lesson says.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { browserSuite, settled } from './browser.mjs';

const suite = browserSuite();
/** Opens the app at `path`, waits for its run, then runs `body(page)`. */
const withPage = (path, body) =>
  suite.withPage(path, async (page) => {
    assert.equal(await settled(page), 'done');
    await body(page);
  });

/** Waits until the analysis `name` (map, sweep, seeds) has ended; returns how. */
const ended = (page, name) =>
  page
    .waitForFunction((name) => ['done', 'failed', 'cancelled', 'refused'].includes(document.body.dataset[name]), name, {
      timeout: 120_000,
    })
    .then(() => page.evaluate((name) => document.body.dataset[name], name));

/** Runs the analysis `name` with its button `run` and waits until it is done. */
async function runAnalysis(page, name, run) {
  await page.evaluate((name) => delete document.body.dataset[name], name);
  await page.click(run);
  assert.equal(await ended(page, name), 'done');
}

/** Sets the settings field `key` to `value` as a user does (type, then leave the field). */
async function setField(page, key, value) {
  const selector = `#field-${key.replace('.', '\\.')}`;
  await page.fill(selector, value);
  await page.press(selector, 'Tab');
}

/**
 * What the page shows of result `name` (whose elements are `shown`): whether it is marked, the
 * mark's text, and whether its elements are greyed.
 */
const marking = (page, name, shown) =>
  page.evaluate(
    ([name, shown]) => {
      const mark = document.getElementById(`${name}-stale`);
      return {
        marked: document.body.dataset[`${name}Stale`] === '1',
        text: mark && !mark.hidden ? mark.textContent : null,
        greyed: shown.map((s) => document.querySelector(s).classList.contains('stale-result')),
      };
    },
    [name, shown],
  );

/** Waits until result `name` is marked (or, with `marked` false, not). */
const waitMarked = (page, name, marked = true) =>
  page.waitForFunction(([key, marked]) => (document.body.dataset[key] === '1') === marked, [`${name}Stale`, marked]);

async function download(page, selector) {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
  return readFileSync(await d.path(), 'utf8');
}

test('a map of an earlier scenario is marked and greyed; its CSV names that scenario; a run for the settings clears it', () =>
  withPage(`?v=1&preset=step#robust=${encodeURIComponent('plant.rr=-10%..+10%:3;seeds=1..2')}`, async (page) => {
    assert.equal(await ended(page, 'map'), 'done');
    assert.deepEqual(await marking(page, 'map', ['#map-plot']), { marked: false, text: null, greyed: [false] });
    await page.click('#tab-analysis');
    await setField(page, 'k1', '600');
    await waitMarked(page, 'map');
    const { text, greyed } = await marking(page, 'map', ['#map-plot']);
    assert.match(
      text,
      /^This map is of an earlier scenario \(v=1&preset=step\), not of the settings now\. Press “Run map” to bring it up to date\. Its CSV names the scenario it was run for\./,
    );
    assert.deepEqual(greyed, [true]);
    assert.ok(await page.isVisible('#map-stale'));
    // The CSV stays on: it is the earlier scenario's, and says so on its first line and each row.
    const csv = await download(page, '#map-csv');
    assert.match(csv.split('\n')[0], /^# v=1&preset=step over /);
    for (const row of csv.trim().split('\n').slice(2)) assert.match(row, /,v=1&preset=step(&plant\.rr=[\d.]+)?$/);
    // Back to the map's scenario by hand: the mark goes.
    await setField(page, 'k1', '1200');
    await waitMarked(page, 'map', false);
    assert.deepEqual(await marking(page, 'map', ['#map-plot']), { marked: false, text: null, greyed: [false] });
    // Changed again and run: the map runs the settings, which become the run on screen and the address.
    await setField(page, 'k1', '600');
    await waitMarked(page, 'map');
    await runAnalysis(page, 'map', '#map-run');
    assert.deepEqual(await marking(page, 'map', ['#map-plot']), { marked: false, text: null, greyed: [false] });
    await page.waitForFunction(() => document.body.dataset.scenario === 'v=1&preset=step&k1=600');
    assert.equal(new URL(page.url()).search, '?v=1&preset=step&k1=600');
    assert.match((await download(page, '#map-csv')).split('\n')[0], /^# v=1&preset=step&k1=600 over /);
  }));

test('a sweep of an earlier scenario is marked, its CSV off; going back to its scenario or running it again clears it', () =>
  withPage('?v=1&preset=step#sweep=50,400,3,0.02,0,0.2,euler', async (page) => {
    assert.equal(await ended(page, 'sweep'), 'done');
    await page.click('#tab-analysis');
    const shown = ['#sweep-table', '#bode'];
    await setField(page, 'k1', '600');
    await waitMarked(page, 'sweep');
    const { text, greyed } = await marking(page, 'sweep', shown);
    assert.match(
      text,
      /^These Bode plots and this table are of an earlier scenario \(v=1&preset=step\), not of the settings now\. Press “Run sweep” to bring them up to date\. Their CSV, which does not name its scenario, is off until then\./,
    );
    assert.deepEqual(greyed, [true, true]);
    assert.equal(await page.isDisabled('#sweep-csv'), true);
    // “Back to its scenario” loads and runs the sweep's scenario: the mark goes and the CSV is on.
    await page.click('#sweep-stale button');
    await waitMarked(page, 'sweep', false);
    assert.equal(await page.isDisabled('#sweep-csv'), false);
    assert.deepEqual((await marking(page, 'sweep', shown)).greyed, [false, false]);
    await page.waitForFunction(() => new URL(location.href).search === '?v=1&preset=step');
    // Changed again, then swept again for the settings.
    await setField(page, 'k1', '600');
    await waitMarked(page, 'sweep');
    await runAnalysis(page, 'sweep', '#sweep-run');
    assert.deepEqual(await marking(page, 'sweep', shown), { marked: false, text: null, greyed: [false, false] });
    assert.equal(await page.isDisabled('#sweep-csv'), false);
  }));

test('seed bands of an earlier scenario are marked, their CSV off, until the seeds run for the settings', () =>
  withPage('?v=1&preset=step&duration=0.5', async (page) => {
    await page.click('#tab-analysis');
    await page.fill('#seeds-form [name=n]', '2');
    await runAnalysis(page, 'seeds', '#seeds-run');
    assert.equal(await page.isDisabled('#seeds-csv'), false);
    await setField(page, 'k1', '600');
    await waitMarked(page, 'seeds');
    const { text, greyed } = await marking(page, 'seeds', ['#seeds-plots']);
    assert.match(
      text,
      /^These seed bands are of an earlier scenario \(v=1&preset=step&duration=0\.5\), not of the settings now\. Press “Run seeds” to bring them up to date\./,
    );
    assert.deepEqual(greyed, [true]);
    assert.equal(await page.isDisabled('#seeds-csv'), true);
    await runAnalysis(page, 'seeds', '#seeds-run');
    assert.deepEqual(await marking(page, 'seeds', ['#seeds-plots']), { marked: false, text: null, greyed: [false] });
    assert.equal(await page.isDisabled('#seeds-csv'), false);
  }));

test('a challenge verdict is marked once an allowed setting changes, until the settings are checked or put back', () =>
  withPage('?challenge=step-tune', async (page) => {
    const checked = () => Number(document.body.dataset.challengeChecked ?? 0);
    await page.waitForFunction(checked);
    assert.match(await page.textContent('#challenge-verdict'), /^✗ Not passed/);
    const shown = ['#challenge-verdict', '#challenge-checklist'];
    const k1 = await page.inputValue('#challenge-k1');
    await page.fill('#challenge-k1', '2000');
    await page.press('#challenge-k1', 'Tab');
    await waitMarked(page, 'challenge');
    const { text, greyed } = await marking(page, 'challenge', shown);
    assert.match(
      text,
      /^This verdict is of an earlier scenario \(v=1&preset=step.*\), not of the settings now\. Press “Run and check” to bring it up to date\./,
    );
    assert.deepEqual(greyed, [true, true]);
    await page.fill('#challenge-k1', k1);
    await page.press('#challenge-k1', 'Tab');
    await waitMarked(page, 'challenge', false);
    await page.fill('#challenge-k1', '2000');
    await page.press('#challenge-k1', 'Tab');
    await waitMarked(page, 'challenge');
    const before = await page.evaluate(checked);
    await page.click('#challenge-run');
    await page.waitForFunction(
      (n) =>
        Number(document.body.dataset.challengeChecked ?? 0) > n &&
        ['pass', 'fail'].includes(document.body.dataset.challenge),
      before,
      { timeout: 60_000 },
    );
    assert.deepEqual(await marking(page, 'challenge', shown), { marked: false, text: null, greyed: [false, false] });
  }));

test('lesson 12: its map, run, then the scenario changed as the lesson says: the map on the Analysis tab is marked as the earlier scenario’s', () =>
  withPage('', async (page) => {
    await page.click('#tab-lessons');
    const before = Number(await page.evaluate(() => document.body.dataset.started));
    await page.click('button:text-is("Start lesson 12")');
    await page.waitForFunction((n) => Number(document.body.dataset.started) > n, before);
    assert.equal(await settled(page), 'done');
    assert.match(await page.textContent('#lesson-panel h2'), /How exact must the model be\?/);
    // The lesson opens the Analysis tab with its map filled in: press “Run map”.
    assert.equal(await page.inputValue('[name=axis1]'), 'plant.rr=-10%..+10%:11');
    await runAnalysis(page, 'map', '#map-run');
    assert.equal(await page.locator('.map-table .map-cell').count(), 11);
    // “Then open the preset rr-mismatch, set plant.rr = 4.95 (the exact model) and duration = 3”.
    await page.selectOption('#preset', 'rr-mismatch');
    await page.waitForFunction(() => /preset=rr-mismatch/.test(document.body.dataset.scenario));
    await page.click('details[data-group=plant] > summary');
    await setField(page, 'plant.rr', '4.95');
    await page.click('details[data-group=limits] > summary');
    await setField(page, 'duration', '3');
    await page.waitForFunction(() => document.body.dataset.unrun === '1');
    await page.click('#tab-analysis');
    // The address names the map's axes over the new scenario; the map shown is not that one, and says so.
    const url = new URL(page.url());
    assert.match(url.search, /preset=rr-mismatch/);
    assert.match(url.hash, /robust=/);
    await waitMarked(page, 'map');
    assert.ok(await page.isVisible('#map-stale'));
    const { text, greyed } = await marking(page, 'map', ['#map-plot']);
    assert.match(text, /^This map is of an earlier scenario \(v=1&preset=step&duration=1\), not of the settings now\./);
    assert.deepEqual(greyed, [true]);
  }));

test('the predictor comparison is marked once the settings change, until they are put back', () =>
  withPage('?v=1&preset=sine200', async (page) => {
    await page.click('[data-tab=walkthrough]');
    await page.click('#section-ekf button.compare');
    await page.waitForSelector('#section-ekf .compare-result table');
    assert.equal((await marking(page, 'compare', ['#section-ekf .compare-result'])).marked, false);
    await setField(page, 'k1', '600');
    await waitMarked(page, 'compare');
    const marked = await marking(page, 'compare', ['#section-ekf .compare-result']);
    assert.match(marked.text, /This comparison is of an earlier scenario \(v=1&preset=sine200\)/);
    assert.deepEqual(marked.greyed, [true]);
    await setField(page, 'k1', '1200');
    await waitMarked(page, 'compare', false);
  }));
