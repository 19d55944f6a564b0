// End-to-end tests of the page in headless Debian Chromium. Every test fails on a console error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { browserSuite, newPage, runAgain, settled, startRun } from './browser.mjs';

const cli = new URL('../target/release/imlab', import.meta.url).pathname;
const suite = browserSuite();
const withPage = (query, body) => suite.withPage(query ? `?${query}` : '', body);

async function exportCsv(page) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
  return readFileSync(await download.path(), 'utf8');
}

function cliCsv(scenario) {
  return execFileSync(cli, ['run', scenario], { maxBuffer: 1 << 30 }).toString();
}

const scenarioInUrl = (page) => new URL(page.url()).search.slice(1);

test('the page loads and the default preset draws its plots', () =>
  withPage('', async (page) => {
    assert.equal(await settled(page), 'done');
    assert.equal(scenarioInUrl(page), 'v=1&preset=sine200');
    // Eight figures; the plots in view are drawn with the run, the others as they come near it.
    assert.equal(await page.locator('#plots .plot').count(), 8);
    const drawn = await page.locator('#plots .plot canvas').count();
    assert.ok(drawn >= 1 && drawn < 8, `${drawn} plots drawn with the run`);
    for (const plot of await page.locator('#plots .plot').all()) {
      await plot.scrollIntoViewIfNeeded();
      await plot.locator('canvas').waitFor();
    }
    assert.equal(await page.evaluate(() => document.body.dataset.rows), '5000');
    assert.match(await page.textContent('#preset-doc'), /Fig 2/);
    assert.equal(await page.textContent('#message'), '');
  }));

test('a setting the run does not read is said under the preset, as the CLI warns of it', () =>
  withPage('v=1&preset=ifoc-step&duration=0.02&perfect=1&k1=600', async (page) => {
    assert.equal(await settled(page), 'done');
    const said = await page.textContent('#preset-doc');
    const warned = spawnSync(cli, ['describe', scenarioInUrl(page)])
      .stderr.toString()
      .split('\n')
      .filter(Boolean)
      .map((l) => l.replace('imlab: warning: ', ''));
    assert.deepEqual(warned, ['k1 has no effect with controller=ifoc', 'perfect has no effect with controller=ifoc']);
    assert.ok(said.endsWith(`Ignored: ${warned.join('; ')}.`), said);
  }));

test('each preset runs from the picker', () =>
  withPage('', async (page) => {
    await settled(page);
    const names = await page.$$eval('#preset option', (os) => os.map((o) => o.value));
    assert.ok(names.length >= 9);
    for (const name of names) {
      const before = Number(await page.evaluate(() => document.body.dataset.run));
      await page.selectOption('#preset', name);
      await page.waitForFunction((n) => Number(document.body.dataset.run) > n, before);
      assert.equal(await page.evaluate(() => document.body.dataset.state), 'done', name);
      assert.equal(scenarioInUrl(page), `v=1&preset=${name}`);
    }
  }));

test('a URL reproduces the run bit for bit, and the CSV export equals the CLI', () =>
  withPage('v=1&preset=step&step.size=0.3&noise=0.004&seed=7', async (page) => {
    assert.equal(await settled(page), 'done');
    const scenario = scenarioInUrl(page);
    assert.equal(scenario, 'v=1&preset=step&step.size=0.3&noise=0.004&seed=7');
    assert.equal(await page.inputValue('#field-step\\.size'), '0.3');
    const csv = await exportCsv(page);
    assert.equal(csv, cliCsv(scenario));

    // Edit a gain in the form: the address bar keeps the run on screen until the edit runs,
    // then follows, and that URL reproduces the new run.
    await page.fill('#field-k1', '1500');
    await page.press('#field-k1', 'Tab');
    await page.waitForFunction(() => document.body.dataset.unrun === '1');
    assert.equal(scenarioInUrl(page), scenario);
    await runAgain(page);
    const edited = scenarioInUrl(page);
    assert.match(edited, /k1=1500/);
    const editedCsv = await exportCsv(page);
    assert.notEqual(editedCsv, csv);
    await withPage(edited, async (other) => {
      assert.equal(await settled(other), 'done');
      assert.equal(await exportCsv(other), editedCsv);
    });

    // Back returns to the first scenario and reruns it.
    await page.goBack();
    await page.waitForFunction(
      (s) => document.body.dataset.scenario === s && document.body.dataset.state === 'done',
      scenario,
    );
    assert.equal(await exportCsv(page), csv);
  }));

test('a broken URL shows which field is wrong and the app still runs', async () => {
  await withPage('v=1&preset=step&k1=-5&k2=1500', async (page) => {
    assert.equal(await settled(page), 'done');
    const message = await page.textContent('#message');
    assert.match(message, /'k1'/);
    assert.match(message, /0 < k1 ≤ 1000000/);
    // The valid field is kept; the bad one is left at the preset's value.
    assert.equal(scenarioInUrl(page), 'v=1&preset=step&k2=1500');
  });
  // Markup in the URL is shown as text, never parsed.
  await withPage('v=1&preset=%3Cimg%20src=x%3E', async (page) => {
    assert.equal(await settled(page), 'done');
    assert.equal(await page.locator('#message img').count(), 0);
    assert.match(await page.textContent('#message'), /preset/);
    assert.equal(scenarioInUrl(page), 'v=1&preset=sine200');
  });
});

test('a diverging run is reported, nothing non-finite is plotted, and the next run works', () =>
  withPage('v=1&preset=step&ts=0.001&vmax=100000', async (page) => {
    assert.equal(await settled(page), 'failed');
    assert.match(await page.textContent('#message'), /diverged/);
    await page.selectOption('#preset', 'step');
    await page.waitForFunction(
      () => document.body.dataset.scenario === 'v=1&preset=step' && document.body.dataset.state === 'done',
    );
  }));

test('an invalid edit names the field and blocks Run until fixed', () =>
  withPage('v=1&preset=step', async (page) => {
    await settled(page);
    await page.fill('#field-k2', 'abc');
    await page.press('#field-k2', 'Tab');
    await page.waitForSelector('#field-k2.invalid');
    assert.match(await page.textContent('#message'), /'k2'/);
    assert.ok(await page.isDisabled('#run'));
    await page.fill('#field-k2', '1300');
    await page.press('#field-k2', 'Tab');
    await page.waitForFunction(() => !document.querySelector('#field-k2.invalid'));
    assert.ok(await page.isEnabled('#run'));
    assert.equal(await page.isVisible('#unrun'), true);
  }));

test('Cancel stops a long run', () =>
  withPage('v=1&preset=step', async (page) => {
    await settled(page);
    // The longest run a link can ask for (about a million samples), cancelled by the page as soon
    // as its first progress shows: the run cannot end first, however fast or busy the machine.
    await page.goto(`${suite.server.url}?v=1&preset=step&duration=20&ts=0.00001878`);
    await page.evaluate(
      () =>
        new Promise((resolve) => {
          // Each progress message rewrites the status line, which the observer sees.
          const cancelOnProgress = () => {
            if (document.body.dataset.state !== 'running' || !(document.getElementById('progress').value > 0)) return;
            observer.disconnect();
            document.getElementById('cancel').click();
            resolve();
          };
          const observer = new MutationObserver(cancelOnProgress);
          observer.observe(document.body, { attributes: true, subtree: true, characterData: true, childList: true });
          cancelOnProgress();
        }),
    );
    assert.equal(await settled(page), 'cancelled');
    const progress = await page.evaluate(() => document.getElementById('progress').value);
    assert.ok(progress < 1, `progress ${progress}`);
  }));

// The simulation runs in the worker: done on the main thread, the 100,000 steps of a 5 s run
// would block it for well over a second. The bound leaves room for a loaded machine (the page's
// own work, drawing the plots, takes tens of milliseconds on a quiet one), so the test checks where
// the work runs, not how fast.
const MAIN_THREAD_BOUND_MS = 500;

test('the main thread is never blocked for long while a 5 s simulation runs: the work is in the worker', () =>
  withPage('v=1&preset=step', async (page) => {
    await settled(page);
    await page.evaluate(() => {
      window.longTasks = [];
      new PerformanceObserver((list) => window.longTasks.push(...list.getEntries().map((e) => e.duration))).observe({
        type: 'longtask',
      });
    });
    await page.selectOption('#preset', 'ramp');
    await page.waitForFunction(() => document.body.dataset.scenario === 'v=1&preset=ramp');
    await page.click('details[data-group=limits] > summary');
    await page.fill('#field-duration', '5');
    await page.press('#field-duration', 'Tab');
    await page.waitForFunction(() => document.body.dataset.unrun === '1');
    const run = await runAgain(page);
    assert.equal(run.rows, '100000');
    const longest = await page.evaluate(() => Math.max(0, ...window.longTasks));
    assert.ok(longest < MAIN_THREAD_BOUND_MS, `longest main-thread task ${longest} ms`);
  }));

test('a loaded app reloads and runs offline', () =>
  withPage('v=1&preset=step', async (page) => {
    await settled(page);
    await page.evaluate(() => navigator.serviceWorker.ready);
    await page.reload(); // now controlled by the service worker, which caches what it serves
    await settled(page);
    await page.context().setOffline(true);
    await page.reload();
    assert.equal(await settled(page), 'done');
    assert.equal(scenarioInUrl(page), 'v=1&preset=step');
    // Other scenario links are answered from the same cached page, and add no copy of it.
    await page.goto(`${suite.server.url}?v=1&preset=ramp`);
    assert.equal(await settled(page), 'done');
    await page.context().setOffline(false);
    for (const preset of ['sine200', 'decay', 'ifoc-step']) {
      await page.goto(`${suite.server.url}?v=1&preset=${preset}`);
      await settled(page);
    }
    const pages = () =>
      page.evaluate(async () =>
        (await (await caches.open('imlab-v1')).keys()).filter((r) => new URL(r.url).pathname === '/').map((r) => r.url),
      );
    await page.waitForFunction(async () =>
      (await (await caches.open('imlab-v1')).keys()).some((r) => r.url.endsWith('/')),
    );
    assert.deepEqual(await pages(), [`${suite.server.url}`]);
  }));

// The settings' closed groups are built after a run, when the page is idle; a browser that is never
// idle (as here) builds one only when it is opened. Meanwhile an edit runs with their values.
test('an edit run before the closed settings groups are built keeps their values', async () => {
  const errors = [];
  const page = await newPage(suite.browser, errors);
  try {
    await page.addInitScript(() => {
      window.requestIdleCallback = () => 0;
    });
    await page.goto(`${suite.server.url}?v=1&preset=step&seed=3&noise=0.004`);
    assert.equal(await settled(page), 'done');
    assert.equal(await page.locator('#field-seed').count(), 0, 'the noise group is not built');
    await page.fill('#field-k1', '600');
    assert.equal(await startRun(page, () => page.press('#field-k1', 'Enter')), 'done');
    assert.equal(
      await page.evaluate(() => document.body.dataset.scenario),
      'v=1&preset=step&k1=600&noise=0.004&seed=3',
    );
    // Opened, the group shows them.
    await page.click('details[data-group=noise] > summary');
    assert.equal(await page.inputValue('#field-seed'), '3');
    assert.equal(await page.inputValue('#field-noise'), '0.004');
  } finally {
    await page.context().close();
  }
  assert.deepEqual(errors, [], 'console errors');
});

test("a motor chosen in the form sets the plant, the model and the rating, as its link's motor= does", () =>
  withPage('v=1&preset=step&duration=0.02&plant.rr=5', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.click('details[data-group=plant] > summary');
    const ran = () => page.evaluate(() => document.body.dataset.scenario);
    const before = await ran();
    await page.selectOption('#field-motor', '2.2kw');
    await startRun(page, () => page.click('#run'));
    assert.notEqual(await ran(), before);
    // The old plant.rr does not undo the motor: the run is the link's, and the form shows its values.
    assert.equal(await ran(), 'v=1&preset=step&motor=2.2kw&duration=0.02');
    assert.equal(await page.inputValue('[id="field-plant.rr"]'), '2.1');
    const described = execFileSync(cli, ['describe', await ran()]).toString();
    assert.match(described, /^plant\.rr +=  +2\.1 Ω/m);
    assert.match(described, /^i_rated +=  +7\.0710678118654755 A/m);
  }));

test('a reference typed as a table runs as its link does in the CLI; a table past its bound names the field and its count', () =>
  withPage('v=1&preset=step&duration=0.05', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.selectOption('#field-ref', 'table');
    const table = '[id="field-ref.table"]';
    await page.waitForSelector(table);
    const long = Array.from({ length: 17 }, (_, i) => `${i / 100}:${i}`).join(',');
    await page.fill(table, long);
    await page.press(table, 'Tab');
    await page.waitForSelector(`${table}.invalid`);
    assert.match(await page.textContent('#message'), /'ref\.table'.*at most 16 points; this table has 17/);
    assert.ok(await page.isDisabled('#run'));
    await page.fill(table, '0:0,0.01:20,0.03:20,0.04:-10');
    await page.press(table, 'Tab');
    await page.waitForFunction((t) => !document.querySelector(`${t}.invalid`), table);
    await startRun(page, () => page.click('#run'));
    const scenario = scenarioInUrl(page);
    assert.equal(scenario, 'v=1&preset=step&ref=table&ref.table=0:0,0.01:20,0.03:20,0.04:-10&duration=0.05');
    assert.equal(await exportCsv(page), cliCsv(scenario));
  }));

test('Enter in the settings runs, and the address always describes the run on screen or the page says it does not', () =>
  withPage('v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    const shown = () =>
      page.evaluate(() => ({
        url: location.search.slice(1),
        ran: document.body.dataset.scenario,
        unrun: document.body.dataset.unrun === '1',
      }));
    // An edit not yet run: the address keeps the run on screen, and the page says so.
    await page.fill('#field-k1', '600');
    await page.press('#field-k1', 'Tab');
    await page.waitForFunction(() => document.body.dataset.unrun === '1');
    assert.deepEqual(await shown(), { url: 'v=1&preset=step', ran: 'v=1&preset=step', unrun: true });
    // Enter runs it.
    assert.equal(await startRun(page, () => page.press('#field-k1', 'Enter')), 'done');
    assert.deepEqual(await shown(), { url: 'v=1&preset=step&k1=600', ran: 'v=1&preset=step&k1=600', unrun: false });
    // Enter straight after typing, with no change event first.
    await page.fill('#field-k2', '900');
    assert.equal(await startRun(page, () => page.press('#field-k2', 'Enter')), 'done');
    assert.deepEqual(await shown(), {
      url: 'v=1&preset=step&k1=600&k2=900',
      ran: 'v=1&preset=step&k1=600&k2=900',
      unrun: false,
    });
    // Back and Forward rerun what the address holds.
    await page.goBack();
    await page.waitForFunction(
      () => document.body.dataset.scenario === 'v=1&preset=step&k1=600' && document.body.dataset.state === 'done',
    );
    assert.deepEqual(await shown(), { url: 'v=1&preset=step&k1=600', ran: 'v=1&preset=step&k1=600', unrun: false });
    await page.goForward();
    await page.waitForFunction(
      () =>
        document.body.dataset.scenario === 'v=1&preset=step&k1=600&k2=900' && document.body.dataset.state === 'done',
    );
    assert.deepEqual(await shown(), {
      url: 'v=1&preset=step&k1=600&k2=900',
      ran: 'v=1&preset=step&k1=600&k2=900',
      unrun: false,
    });
  }));
