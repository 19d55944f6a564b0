// Browser tests of reliability at the limits: a worker that traps or fails is replaced and the
// next run works; the CSV of the largest allowed run exports whole; hostile links are refused
// with a message. Every test fails on a console or page error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { createHash } from 'node:crypto';
import { createReadStream, statSync, unlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { browserSuite, newPage, runAgain, settled, startRun } from './browser.mjs';

const cli = new URL('../target/release/imlab', import.meta.url).pathname;
const suite = browserSuite();
const withPage = (path, body) => suite.withPage(path, body);

// A long run at a short sample time: 1,064,963 rows of 63 columns, whose CSV (about 0.7 GB) the
// page exports in chunks; a run keeps checkpoints, not rows, so its memory is a few MB.
const LARGEST = 'v=1&preset=step&duration=20&ts=0.00001878';

const CRASH_MESSAGE = /^The simulation worker failed \(.+\)\. It was restarted; press Run to try again\./;

/** The simulation worker: the page's first, as long as it has not been restarted. */
const simulationWorker = (page) => page.workers()[0];

/**
 * Opens `path` in a fresh page whose worker keeps the run core's WASM exports on `self.core` (the
 * first instance it makes; the tools' core, loaded later, is left as it is), as a copy the test
 * may change: the worker's bundle is served with a line before it that wraps
 * `WebAssembly.instantiateStreaming`. The test's way into the one WASM instance the bundled worker
 * holds; the page and the worker are otherwise as served.
 */
async function pageWithCore(path, errors) {
  const page = await newPage(suite.browser, errors);
  await page.context().route('**/web/worker-*.js', async (route) => {
    const response = await route.fetch();
    const keep =
      '{ const instantiate = WebAssembly.instantiateStreaming; WebAssembly.instantiateStreaming = async (...a) => { const r = await instantiate(...a); if (self.core) return r; self.core = { ...r.instance.exports }; return { module: r.module, instance: { exports: self.core } }; }; }\n';
    await route.fulfill({ response, body: keep + (await response.text()) });
  });
  await page.goto(`${suite.server.url}${path}`);
  return page;
}

/**
 * Makes the worker's next slice of a run exhaust the core's memory: the core's `step_for` is
 * wrapped by one that first allocates 8 MB blocks, never freed, until the allocator fails. That is
 * a real trap of the core (Rust aborts on a failed allocation with `unreachable`), reached in the
 * worker's next run.
 */
function trapOnNextStep(worker) {
  return worker.evaluate(() => {
    // The allocator the glue passes strings with (wasm-bindgen names it __wbindgen_export).
    const malloc = self.core.__wbindgen_export;
    self.core.simulation_step_for = () => {
      for (;;) malloc(1 << 23, 1);
    };
  });
}

/** Checks that the page has the run's plots (those in view drawn; the others when they come near it) and figures. */
async function assertDrawn(page) {
  assert.equal(await page.locator('#plots .plot').count(), 8);
  assert.ok((await page.locator('#plots .plot canvas').count()) >= 1);
  assert.ok((await page.locator('#figures .figure').count()) > 0);
}

// The worker starts with the page (boot.js), before the page's modules run, and the page adopts
// it: one simulation worker, and a failure told as soon as the page is wired, whichever part of
// the worker could not load.
test('the page runs its first run on the one worker started with it', () =>
  withPage('?v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    assert.equal(page.workers().length, 1);
  }));

// The worker's bundle and the core's module, by their hashed names (scripts/bundle.mjs).
for (const blocked of ['web/worker-*.js', 'web/imlab_bg-*.wasm']) {
  test(`a worker that cannot load (${blocked} unreachable) is reported as not started`, async () => {
    const errors = [];
    const page = await newPage(suite.browser, errors);
    try {
      await page.context().route(`**/${blocked}`, (route) => route.abort());
      await page.goto(suite.server.url);
      await page.waitForFunction(() => document.body.dataset.state === 'crashed');
      assert.match(
        await page.locator('#message').innerText(),
        /^The simulation worker could not start \(.+\)\. Reload the page to try again\.$/,
      );
    } finally {
      await page.context().close();
    }
    // The browser reports the blocked request itself; nothing else may fail.
    assert.deepEqual(
      errors.filter((e) => !/Failed to load resource/.test(e)),
      [],
    );
  });
}

test('a trap in the worker is reported, the worker is replaced, and the next run works', async () => {
  const errors = [];
  const page = await pageWithCore('?v=1&preset=step', errors);
  try {
    assert.equal(await settled(page), 'done');
    await trapOnNextStep(simulationWorker(page));
    assert.equal(await startRun(page, () => page.click('#run')), 'crashed');
    const message = await page.textContent('#message');
    assert.match(message, CRASH_MESSAGE);
    assert.match(message, /RuntimeError: unreachable; most likely the core ran out of memory/);
    assert.ok(await page.isEnabled('#run'));
    assert.ok(await page.isDisabled('#export-csv'));
    const run = await runAgain(page);
    assert.equal(run.state, 'done');
    await assertDrawn(page);
    assert.equal(await page.textContent('#message'), '');
  } finally {
    await page.context().close();
  }
  assert.deepEqual(errors, [], 'console errors');
});

test('an unhandled rejection or an uncaught error in the worker reaches the page, which recovers', () =>
  withPage('?v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    await simulationWorker(page).evaluate(() => {
      Promise.reject(new Error('forced rejection'));
    });
    await page.waitForFunction(() => document.body.dataset.state === 'crashed');
    assert.match(await page.textContent('#message'), CRASH_MESSAGE);
    assert.match(await page.textContent('#message'), /Error: forced rejection/);
    assert.equal((await runAgain(page)).state, 'done');
    await assertDrawn(page);

    await simulationWorker(page).evaluate(() => {
      setTimeout(() => {
        throw new Error('forced throw');
      });
    });
    await page.waitForFunction(() => document.body.dataset.state === 'crashed');
    assert.match(await page.textContent('#message'), /Error: forced throw/);
    assert.equal((await runAgain(page)).state, 'done');
  }));

test('pinned runs that lived in a crashed worker are named and dropped', () =>
  withPage('?v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.click('#pin');
    await page.waitForFunction(() => location.hash.includes('pins='));
    await simulationWorker(page).evaluate(() => {
      Promise.reject(new Error('forced'));
    });
    await page.waitForFunction(() => document.body.dataset.state === 'crashed');
    assert.match(await page.textContent('#message'), /The pinned runs were dropped: v=1&preset=step\./);
    assert.equal(await page.locator('#pins li').count(), 0);
    assert.ok(!page.url().includes('pins='));
    assert.equal((await runAgain(page)).state, 'done');
    // The fresh worker pins again.
    await page.click('#pin');
    await page.waitForSelector('#pins li');
  }));

test('a crashed sweep worker fails the sweep with a message and a fresh one runs the next sweep', () =>
  withPage('?v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.click('[data-tab=analysis]');
    await page.fill('#sweep-form [name=n]', '40');
    await page.fill('#sweep-form [name=duration]', '0.5');
    await page.click('#sweep-run');
    await page.waitForFunction(() => document.getElementById('sweep-progress').value > 0);
    const [, poolWorker] = page.workers();
    await poolWorker.evaluate(() => {
      Promise.reject(new Error('forced'));
    });
    await page.waitForFunction(() => document.body.dataset.sweep === 'failed', null, { timeout: 60_000 });
    assert.match(await page.textContent('#sweep-status'), /^Sweep failed: a worker failed \(Error: forced\)/);
    await page.fill('#sweep-form [name=n]', '4');
    await page.fill('#sweep-form [name=duration]', '0.2');
    await page.click('#sweep-run');
    await page.waitForFunction(() => document.body.dataset.sweep === 'done', null, { timeout: 60_000 });
    assert.equal(await page.locator('#sweep-table tr[data-variant]').count(), 3);
  }));

async function sha256(path) {
  const hash = createHash('sha256');
  for await (const chunk of createReadStream(path)) hash.update(chunk);
  return hash.digest('hex');
}

test('the CSV of the largest allowed run exports whole, byte for byte the CLI’s', async () => {
  const cliFile = join(tmpdir(), `imlab-largest-${process.pid}.csv`);
  // The CLI writes its copy while the browser runs.
  const cliDone = promisify(execFile)(cli, ['run', LARGEST, '--out', cliFile]);
  try {
    await withPage(`?${LARGEST}`, async (page) => {
      assert.equal(await settled(page, 120_000), 'done');
      assert.equal(await page.evaluate(() => document.body.dataset.rows), '1064963');
      const [download] = await Promise.all([
        page.waitForEvent('download', { timeout: 300_000 }),
        page.click('#export-csv'),
      ]);
      assert.equal(await page.evaluate(() => document.body.dataset.export), 'done');
      assert.equal(await page.textContent('#status'), 'CSV exported: 1,064,963 rows');
      const file = await download.path(); // Playwright's copy, removed with the context
      await cliDone;
      assert.equal(statSync(file).size, statSync(cliFile).size);
      assert.equal(await sha256(file), await sha256(cliFile));
    });
  } finally {
    await cliDone.catch(() => {});
    unlinkSync(cliFile);
  }
});

test('a CSV export shows its progress, Cancel stops it, and a run started during one cancels it', () =>
  withPage('?v=1&preset=step&duration=4&ts=0.0000167', async (page) => {
    assert.equal(await settled(page, 60_000), 'done');
    await page.click('#export-csv');
    await page.waitForFunction(() =>
      /^Exporting CSV: [\d,]+ of 239,521 rows$/.test(document.getElementById('status').textContent),
    );
    // Read in one evaluation: while the export is under way, its button is off.
    assert.ok(
      await page.evaluate(
        () =>
          !document.getElementById('status').textContent.startsWith('Exporting CSV:') ||
          document.getElementById('export-csv').disabled,
      ),
    );
    await page.click('#cancel');
    assert.equal(await page.evaluate(() => document.body.dataset.export), 'cancelled');
    assert.equal(await page.textContent('#status'), 'CSV export cancelled');
    assert.ok(await page.isEnabled('#export-csv'));

    await page.click('#export-csv');
    await page.waitForFunction(() => document.getElementById('status').textContent.startsWith('Exporting CSV:'));
    await page.click('#run');
    await page.waitForFunction(() => document.body.dataset.export === 'cancelled');
    assert.equal(await page.textContent('#message'), 'The CSV export was cancelled: a new run started.');
    // Read in one evaluation: while the new run is under way (it may already be done), no export.
    assert.ok(
      await page.evaluate(
        () => document.body.dataset.state !== 'running' || document.getElementById('export-csv').disabled,
      ),
    );
    assert.equal(await settled(page, 60_000), 'done');
    assert.ok(await page.isEnabled('#export-csv'));
  }));

test('hostile fragments are named in a message and the rest of the link still works', async () => {
  const sweepDone = (page) =>
    page
      .waitForFunction(() => ['done', 'failed'].includes(document.body.dataset.sweep), null, { timeout: 60_000 })
      .then(() => page.evaluate(() => document.body.dataset.sweep));
  // A pins part that does not decode.
  await withPage('?v=1&preset=step#pins=%', async (page) => {
    assert.equal(await settled(page), 'done');
    assert.equal(await page.textContent('#message'), "Ignored a malformed pin in the address: '%'.");
    await page.waitForFunction(() => !location.hash.includes('pins'));
    assert.equal(await page.locator('#pins li').count(), 0);
  });
  // ... beside a valid sweep, which still runs.
  await withPage('?v=1&preset=step#pins=%E0%A4%A&sweep=100,1000,3,0.02,0,0.05,euler', async (page) => {
    assert.equal(await settled(page), 'done');
    assert.equal(await sweepDone(page), 'done');
    assert.match(await page.textContent('#message'), /^Ignored a malformed pin in the address: '%E0%A4%A'\.$/);
    assert.equal(await page.locator('#sweep-table tr[data-variant]').count(), 1);
  });
  // Pins that decode to scenarios the core refuses, markup included: shown as text.
  await withPage(
    `?v=1&preset=step#pins=${encodeURIComponent('v=1&preset=<img src=x>')}|${encodeURIComponent('v=1&preset=step&k1=-5')}`,
    async (page) => {
      assert.equal(await settled(page), 'done');
      await page.waitForFunction(() => document.getElementById('message').textContent.includes('Could not pin'));
      const message = await page.textContent('#message');
      assert.match(
        message,
        /^Could not pin v=1&preset=<img src=x>: .*preset.*; could not pin v=1&preset=step&k1=-5: .*'k1'.*\.$/,
      );
      assert.equal(await page.locator('#message img').count(), 0);
      assert.equal(await page.locator('#pins li').count(), 0);
    },
  );
  // A fragment of half a million pins: refused whole, with its size, and the page keeps working.
  await withPage(`?v=1&preset=step#pins=${'|x'.repeat(524_288)}`, async (page) => {
    assert.equal(await settled(page), 'done');
    await page.waitForFunction(() =>
      document.getElementById('message').textContent.startsWith('The pins in the address were not run'),
    );
    assert.match(
      await page.textContent('#message'),
      /^The pins in the address were not run: 1,048,576 characters, more than the 65,536 a pins fragment may hold\.$/,
    );
    assert.ok(!page.url().includes('pins='));
    assert.equal((await runAgain(page)).state, 'done');
  });
  // Many malformed pins under the size: a few are quoted, the rest counted.
  await withPage(
    `?v=1&preset=step#pins=${Array.from({ length: 1000 }, (_, i) => `%z${i}`).join('|')}`,
    async (page) => {
      assert.equal(await settled(page), 'done');
      await page.waitForFunction(() => document.getElementById('message').textContent.includes('more'));
      assert.match(
        await page.textContent('#message'),
        /^Ignored a malformed pin in the address: '%z0', '%z1', '%z2', '%z3', '%z4' … and 995 more\.$/,
      );
    },
  );
  // Sweep sizes must be whole numbers; other malformed sweeps name their bad part.
  for (const [sweep, expected] of [
    ['10,1000,2.5,0.02,0,0.2,euler', /n = 2\.5: expected a whole number of points/],
    ['10,1000,4294967301,0.02,0,0.2,euler', /n = 4294967301: expected a whole number of points/],
    ['10,1000,20,0.02,0,0.2,constructor', /variant 'constructor' is unknown/],
    ['10,,20,0.02,0,0.2,euler', /hi = '' is not a number/],
    ['10,1000,20', /expected 7 parts/],
  ]) {
    await withPage(`?v=1&preset=step#sweep=${sweep}`, async (page) => {
      assert.equal(await settled(page), 'done');
      // The core reads the plan in a pool's worker, after the run.
      await page.waitForFunction(() => document.getElementById('message').textContent.startsWith('The sweep'));
      const message = await page.textContent('#message');
      assert.match(message, /^The sweep in the address \(#sweep=.*\) was not run: /);
      assert.match(message, expected);
      assert.ok(await page.isVisible('#message'));
      assert.equal(await page.evaluate(() => document.body.dataset.sweep), undefined);
    });
  }
});

test("the sweep form refuses a fractional number of points with the core's message, as a link's", () =>
  withPage('?v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.click('[data-tab=analysis]');
    await page.fill('#sweep-form [name=n]', '2.5');
    await page.click('#sweep-run');
    await page.waitForFunction(
      () => !['', 'Checking the sweep…'].includes(document.getElementById('sweep-status').textContent),
    );
    assert.equal(await page.textContent('#sweep-status'), 'n = 2.5: expected a whole number of points.');
    assert.equal(await page.evaluate(() => document.body.dataset.sweep), undefined);
  }));

test('a run that recorded nothing keeps the worker: Escape and Full run ask for no view of it', () =>
  withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    // The same page, so the plots of the first run stay on screen.
    const before = Number(await page.evaluate(() => document.body.dataset.run));
    await page.evaluate(() => {
      history.pushState(null, '', '?v=1&preset=ifoc-step&robust=1&h2=1e9&eps2=5e-324');
      dispatchEvent(new PopStateEvent('popstate'));
    });
    await page.waitForFunction((n) => Number(document.body.dataset.run) > n, before);
    assert.equal(await settled(page), 'failed');
    assert.match(await page.textContent('#message'), /column 'v2' would record inf/);
    // Count what the page asks the worker from here on: Escape and Full run post synchronously.
    await page.evaluate(() => {
      window.asked = [];
      const post = Worker.prototype.postMessage;
      Worker.prototype.postMessage = function counted(message, ...rest) {
        window.asked.push(message?.type);
        return post.call(this, message, ...rest);
      };
    });
    await page.keyboard.press('Escape');
    await page.click('#full-run');
    assert.deepEqual(await page.evaluate(() => window.asked), []);
    assert.equal(await page.evaluate(() => document.body.dataset.state), 'failed');
    assert.doesNotMatch(await page.textContent('#message'), /worker failed/);
  }));

test('a slow pin runs in slices with progress, Cancel stops it, and the next pin works', () => {
  // Each pin is about as heavy as the core accepts: 20,000 samples of 71 substeps on each of 7 PWM
  // intervals. Two of them, so that Cancel meets a pin being run even on a busy machine, where the
  // first may end before the click lands.
  const heavy = encodeURIComponent('v=1&preset=sine200-drive&substeps=71&duration=1');
  return withPage(`?v=1&preset=step#pins=${heavy}|${heavy}`, async (page) => {
    assert.equal(await settled(page), 'done');
    // Either pin, with its progress: on a busy machine the first may be done before it is seen.
    await page.waitForFunction(
      () =>
        document.body.dataset.pinning === 'running' &&
        /Running pin [12] of 2: \d+ %/.test(document.getElementById('status').textContent),
      null,
      { timeout: 120_000 },
    );
    await page.click('#cancel');
    await page.waitForFunction(() => document.body.dataset.pinning === 'cancelled');
    assert.ok((await page.locator('#pins li').count()) < 2, 'both pins ran to the end');
    assert.match(
      await page.textContent('#message'),
      /^Could not pin v=1&preset=sine200-drive.*: (cancelled|not run: pinning was cancelled)\.$/,
    );
    // The worker is free: a run and a pin go through.
    assert.equal((await runAgain(page)).state, 'done');
    const pinned = await page.locator('#pins li').count();
    await page.click('#pin');
    // Every pins message says 'done', the one that follows the run too: wait for the new pin itself.
    await page.waitForFunction((n) => document.querySelectorAll('#pins li').length === n, pinned + 1);
    assert.equal(await page.evaluate(() => document.body.dataset.pinning), 'done');
  });
});

test('seed runs show their progress, Cancel stops them at once, and the next seed runs work', () =>
  withPage('?v=1&preset=step&duration=5', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.click('[data-tab=analysis]');
    await page.fill('#seeds-form [name=n]', '200');
    await page.click('#seeds-run');
    await page.waitForFunction(() => document.getElementById('seeds-progress').value > 0);
    await page.click('#seeds-cancel');
    await page.waitForFunction(() => document.body.dataset.seeds === 'cancelled');
    assert.equal(await page.textContent('#seeds-status'), 'Seed runs cancelled.');
    assert.ok(await page.isDisabled('#seeds-cancel'));
    await page.fill('#seeds-form [name=n]', '2');
    await page.click('#seeds-run');
    await page.waitForFunction(() => document.body.dataset.seeds === 'done', null, { timeout: 60_000 });
  }));
