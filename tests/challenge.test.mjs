// Challenges in the page: a lecturer composes one from a preset in the Challenge tab, a student
// opens its link, fails, changes an allowed knob and passes; the submission link replays the same
// values; a tampered submission is refused naming the field; the built-ins open from the Lessons
// tab; axe-core finds nothing on the challenge panel or the compose form. The core's figures are
// the CLI's: the page's checklist shows what `imlab grade` prints for the same link.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { browserSuite, settled, violations } from './browser.mjs';

const cli = new URL('../target/release/imlab', import.meta.url).pathname;

// The server and the browser of this file; pages here need contexts of their own.
const suite = browserSuite();

/**
 * Opens `path` in a fresh context (clipboard allowed, CSP bypassed for axe; `init` run in the page
 * before its own scripts); runs `body(page)`.
 */
async function withPage(path, body, viewport = { width: 1400, height: 1000 }, init = () => {}) {
  const errors = [];
  const context = await suite.browser.newContext({ viewport, bypassCSP: true });
  await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: suite.server.url });
  const page = await context.newPage();
  await page.addInitScript(init);
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  try {
    await page.goto(`${suite.server.url}${path}`);
    await body(page);
  } finally {
    await context.close();
  }
  assert.deepEqual(errors, [], 'console errors');
}

const GRADED = ['pass', 'fail', 'refused', 'failed', 'cancelled', 'malformed'];

/** Waits until the checklist is graded after run number `after` (or later); returns the outcome. */
async function graded(page, after = 0) {
  await page.waitForFunction(
    ([n, states]) =>
      Number(document.body.dataset.challengeChecked ?? 0) > n && states.includes(document.body.dataset.challenge),
    [after, GRADED],
    { timeout: 60_000 },
  );
  return page.evaluate(() => document.body.dataset.challenge);
}

/** Each criterion of the checklist as [figure, pass, text]. */
const checklist = (page) =>
  page.$$eval('#challenge-checklist li', (list) =>
    list.map((li) => [li.dataset.figure, li.dataset.pass, li.textContent]),
  );

/** Runs with the panel's knobs set to `values` and waits for the check; returns the outcome. */
async function tryValues(page, values) {
  const before = Number(await page.evaluate(() => document.body.dataset.challengeChecked ?? 0));
  for (const [field, value] of Object.entries(values)) await page.fill(`#challenge-${field}`, value);
  await page.click('#challenge-run');
  return graded(page, before);
}

test('a lecturer composes a challenge from a preset; a student fails it, passes it and submits; the submission replays', async () => {
  let link;
  await withPage('?v=1&preset=step&step.wn=10000', async (page) => {
    await settled(page);
    await page.click('#tab-challenge');
    await page.waitForFunction(() => document.body.dataset.compose === 'filled');
    for (const k of ['k1', 'k2', 'k3', 'k4']) {
      await page.selectOption('#compose-field', k);
      await page.click('#compose-add');
    }
    // Prefilled around the current value (1200).
    assert.equal(await page.inputValue('#compose-allow-k1-lo'), '600');
    assert.equal(await page.inputValue('#compose-allow-k1-hi'), '2400');
    for (const k of ['k1', 'k2', 'k3', 'k4']) await page.fill(`#compose-allow-${k}-hi`, '5000');
    // The mean NIS inside its band takes no bound: its field is empty, and gets its number back.
    assert.equal(await page.inputValue('#compose-need-mean_nis-op'), 'band');
    assert.equal(await page.isDisabled('#compose-need-mean_nis-bound'), true);
    assert.equal(await page.inputValue('#compose-need-mean_nis-bound'), '');
    await page.selectOption('#compose-need-mean_nis-op', 'max');
    assert.match(await page.inputValue('#compose-need-mean_nis-bound'), /^\d+(\.\d+)?$/);
    await page.selectOption('#compose-need-mean_nis-op', 'band');
    await page.fill('#compose-title', 'Fast step');
    for (const [figure, bound] of [
      ['settling_time', '0.004'],
      ['current_peak', '4'],
    ]) {
      await page.check(`#compose-need-${figure}`);
      await page.fill(`#compose-need-${figure}-bound`, bound);
      await page.check(`#compose-need-${figure}-robust`);
    }
    // A bad range: the core's message is shown beside the form, naming the field, and its row is marked.
    await page.fill('#compose-allow-k2-lo', 'fast');
    await page.click('#compose-make');
    await page.waitForFunction(() => document.body.dataset.compose === 'invalid');
    assert.match(await page.textContent('#compose-error'), /k2/);
    assert.equal(await page.$eval('.compose-row.invalid', (r) => r.dataset.key), 'allow.k2');
    await page.fill('#compose-allow-k2-lo', '300');
    await page.fill('#compose-vary', 'seeds:2..3');
    await page.click('#compose-make');
    await page.waitForFunction(() => document.body.dataset.compose === 'made');
    link = await page.inputValue('#compose-link');
    assert.match(
      link,
      /^http.*\?c=1&title=Fast%20step&base=v%3D1%26preset%3Dstep%26step\.wn%3D10000&allow\.k1=600\.\.5000&/,
    );
    assert.match(
      link,
      /&need\.settling_time=max:0\.004&need\.current_peak=max:4&vary=seeds:2\.\.3&robust=settling_time,current_peak#lang=en$/,
    );
    assert.match(await page.inputValue('#compose-brief'), /You may change only:\n\s+k1\s+600 to 5000/);
    await page.click('#compose-copy-link');
    assert.equal(await page.evaluate(() => navigator.clipboard.readText()), link);
    assert.deepEqual(await violations(page), [], 'compose form');
  });

  let submission;
  let values;
  await withPage(link.slice(link.indexOf('?')), async (page) => {
    assert.equal(await graded(page), 'fail');
    assert.equal(await page.textContent('#challenge-panel h2'), 'Fast step');
    // Only the allowed knobs can be changed.
    assert.equal(await page.isDisabled('#field-k1'), false);
    assert.equal(await page.isDisabled('#field-psi_d'), true);
    assert.equal(await page.isDisabled('#preset'), true);
    // So are the fields of a group built after the first run, once opened.
    await page.click('details[data-group=noise] > summary');
    assert.equal(await page.isDisabled('#field-seed'), true);
    // The paper's gains keep the rating once the start-up is over, and fail on the settling time.
    const failing = await checklist(page);
    assert.deepEqual(
      failing.map((c) => c.slice(0, 2)),
      [
        ['settling_time', '0'],
        ['current_peak', '1'],
      ],
    );
    assert.match(failing[0][2], /✗ fail/);
    assert.match(
      await page.textContent('#challenge-verdict'),
      /✗ Not passed: 1 of 2 criteria met \(the nominal run and 2 variants\)/,
    );

    assert.equal(await tryValues(page, { k1: '2000', k2: '2000', k3: '1500', k4: '1500' }), 'pass');
    values = await checklist(page);
    assert.deepEqual(
      values.map((c) => c.slice(0, 2)),
      [
        ['settling_time', '1'],
        ['current_peak', '1'],
      ],
    );
    assert.match(values[0][2], /✓ pass 2 % settling time of ω after the step: 0\.00345 s, needs ≤ 0\.004 s/);
    // The nominal run is the one on screen: measured where it ran, not run again.
    assert.equal(await page.evaluate(() => document.body.dataset.challengeNominal), 'page');
    await page.click('#challenge-copy');
    submission = await page.evaluate(() => navigator.clipboard.readText());
    assert.match(submission, /&try\.k1=2000&try\.k2=2000&try\.k3=1500&try\.k4=1500$/);
    // The address, less the page's own fragment (its language).
    assert.equal(submission, page.url().split('#')[0]);
    assert.deepEqual(await violations(page), [], 'challenge panel');
  });

  // The submission link replays the runs bit for bit: the same checklist.
  await withPage(submission.slice(submission.indexOf('?')), async (page) => {
    assert.equal(await graded(page), 'pass');
    assert.deepEqual(await checklist(page), values);
    assert.equal(await page.inputValue('#challenge-k3'), '1500');
  });
});

/** Makes the compose form's challenge link and waits for its check to end; returns the outcome. */
async function makeAndCheck(page) {
  await page.evaluate(() => delete document.body.dataset.composeCheck);
  await page.click('#compose-make');
  await page.waitForFunction(
    () => ['solvable', 'unsolved', 'cancelled', 'failed'].includes(document.body.dataset.composeCheck),
    null,
    { timeout: 120_000 },
  );
  return page.evaluate(() => document.body.dataset.composeCheck);
}

test('the composer checks that a design within the allowed ranges passes, and says when none of those tried does', () =>
  withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    await page.click('#tab-challenge');
    await page.waitForFunction(() => document.body.dataset.compose === 'filled');
    await page.selectOption('#compose-field', 'k1');
    await page.click('#compose-add');
    await page.check('#compose-need-current_peak');
    // Nine seeds a design: the check is long enough to cancel.
    await page.fill('#compose-need-current_peak-bound', '0.1');
    await page.check('#compose-need-current_peak-robust');
    await page.fill('#compose-vary', 'seeds:2..10');
    await page.click('#compose-make');
    await page.waitForFunction(() => document.body.dataset.composeCheck === 'running');
    await page.click('#compose-check-cancel');
    await page.waitForFunction(() => document.body.dataset.composeCheck !== 'running');
    assert.equal(await page.evaluate(() => document.body.dataset.composeCheck), 'cancelled');
    assert.match(await page.textContent('#compose-check'), /Check cancelled/);

    // Out of reach: no k1 from 600 to 2400 keeps |i_s| within 0.1 A (the base's is 2.87 A).
    await page.uncheck('#compose-need-current_peak-robust');
    await page.fill('#compose-vary', '');
    assert.equal(await makeAndCheck(page), 'unsolved');
    assert.match(
      await page.textContent('#compose-check'),
      /^✗ No design of the 33 tried passes: the bounds may be out of reach; the closest was k1=\d+ \(current_peak: [\d.]+ A vs ≤ 0\.1 A\)\.$/,
    );
    const details = await page.textContent('#compose-check-details');
    assert.match(details, /^The base \(no field changed\) fails: current_peak: 2\.873 A vs ≤ 0\.1 A\. /);
    assert.match(details, /The check tried 33 designs in 33 runs \(at most 300 runs\)/);
    assert.equal(await page.isHidden('#compose-check-progress'), true);

    // Within reach: the base fails 2.85 A, a higher k1 meets it.
    await page.fill('#compose-need-current_peak-bound', '2.85');
    assert.equal(await makeAndCheck(page), 'solvable');
    assert.match(
      await page.textContent('#compose-check'),
      /^✓ A design within the allowed ranges passes: k1=2400 \(\d+ of 33 designs tried pass\)\.$/,
    );
    assert.match(await page.textContent('#compose-check-details'), /^The base \(no field changed\) fails/);
    assert.deepEqual(await violations(page), [], 'compose check');
  }));

for (const [tamper, refusal] of [
  ['&try.k1=6000', /k1=6000 is outside 300\.\.5000/],
  ['&try.ekf=rk4', /field 'ekf' is not allowed/],
]) {
  test(`a tampered submission (${tamper}) is refused, naming the field, and not graded`, async () => {
    await withPage('?challenge=step-tune', async (page) => {
      assert.equal(await graded(page), 'fail');
      const url = `${page.url()}${tamper}`;
      await page.goto(url);
      assert.equal(await graded(page), 'refused');
      assert.match(await page.textContent('#challenge-error'), refusal);
      assert.match(await page.textContent('#challenge-verdict'), /Not graded/);
      assert.deepEqual(await page.$$('#challenge-checklist li.pass'), []);
      // The student's own run after that is graded.
      assert.equal(await tryValues(page, { k1: '1200' }), 'fail');
      assert.equal(await page.isHidden('#challenge-error'), true);
    });
  });
}

// The settings' closed groups are built once the page is idle after a run (never here: this
// browser is never idle) or when a field of theirs is needed: a challenge knob's edit of such a
// field reaches the run as typed, and every field built then is locked but the allowed ones.
test('a challenge knob of a field in a closed settings group reaches the run, and the fields built for it are locked', () =>
  withPage(
    '?challenge=load-observer',
    async (page) => {
      await graded(page);
      assert.equal(await page.locator('#field-ekf\\.q').count(), 0, 'the observer group is not built');
      const outcome = await tryValues(page, { 'ekf\\.q': '0.01' });
      assert.ok(['pass', 'fail'].includes(outcome), `graded ${outcome}`);
      assert.match(await page.evaluate(() => document.body.dataset.scenario), /&ekf\.q=0\.01(&|$)/);
      assert.equal(await page.inputValue('#challenge-ekf\\.q'), '0.01');
      await page.click('details[data-group=observer] > summary');
      assert.equal(await page.inputValue('#field-ekf\\.q'), '0.01');
      assert.equal(await page.isDisabled('#field-ekf\\.q'), false);
      assert.equal(await page.isDisabled('#field-noise'), true);
    },
    undefined,
    () => {
      window.requestIdleCallback = () => 0;
    },
  ));

test('a value outside the allowed range is refused before it runs: the address keeps naming the run on screen', () =>
  withPage('?challenge=step-tune', async (page) => {
    await graded(page);
    await page.click('#challenge-copy');
    await page.waitForFunction(() => /copied/.test(document.querySelector('#challenge-copied').textContent));
    const before = await page.evaluate(() => ({ started: document.body.dataset.started, address: location.search }));
    await page.fill('#challenge-k1', '6000');
    await page.click('#challenge-run');
    await page.waitForFunction(() => document.body.dataset.challenge === 'refused');
    assert.match(await page.textContent('#challenge-error'), /k1=6000 is outside 300\.\.5000.*Not run/);
    assert.equal(await page.isDisabled('#challenge-copy'), true);
    assert.equal(await page.textContent('#challenge-copied'), '', 'the earlier link’s "copied" stays');
    const after = await page.evaluate(() => ({ started: document.body.dataset.started, address: location.search }));
    assert.deepEqual(after, before, 'a run started, or the address moved');
    // Back in range, it runs and is graded again.
    assert.equal(await tryValues(page, { k1: '1200' }), 'fail');
  }));

test('a run that runs away is failed in words of the page’s language, the run module’s reason said', () => {
  // The low-speed lesson's run: a wrong R_r at low speed, which runs away.
  const base = encodeURIComponent('v=1&preset=rr-mismatch&ref.value=1&ekf=rk4&init_err=0&duration=3');
  return withPage(`?c=1&title=x&base=${base}&allow.k1=1..2000&need.tracking_rms=max:1#lang=de`, async (page) => {
    await page.waitForSelector('#challenge-checklist li .reason');
    const reason = await page.textContent('#challenge-checklist li .reason');
    assert.match(reason, /Lauf fehlgeschlagen: (Der Lauf ist divergiert|divergiert bei)/);
    assert.doesNotMatch(reason, /[[{]|warning-|sim-|Real/);
  });
});

test('a malformed challenge link says so and the page falls back to the default scenario', () =>
  withPage('?c=1&title=x&base=v%3D1%26preset%3Dstep&allow.k1=1..2&need.nothing=max:1', async (page) => {
    await page.waitForFunction(() => document.body.dataset.challenge === 'malformed');
    assert.match(await page.textContent('#challenge-error'), /nothing/);
    await settled(page);
  }));

test('a stray "=" pasted before a challenge link is named', () =>
  withPage('?=c=1&title=x', async (page) => {
    await page.waitForFunction(() => document.body.dataset.challenge === 'malformed');
    assert.match(await page.textContent('#challenge-error'), /stray character '=' before its c=1: remove it/);
    await settled(page);
  }));

test('the built-in challenges open from the Lessons tab', () =>
  withPage('', async (page) => {
    await settled(page);
    await page.click('#tab-lessons');
    await page.waitForSelector('#challenges a');
    const links = await page.$$eval('#challenges a', (list) => list.map((a) => a.getAttribute('href')));
    assert.deepEqual(links, ['?challenge=step-tune', '?challenge=load-observer', '?challenge=ifoc-load']);
    await page.click('#challenges a[href="?challenge=ifoc-load"]');
    assert.equal(await graded(page), 'fail');
    assert.equal(await page.textContent('#challenge-panel h2'), 'IFOC load rejection');
    // No variants: the nominal run alone, measured where it ran.
    assert.match(await page.textContent('#challenge-verdict'), /criteria met\.$/);
  }));

test('the panel shows the challenge’s fingerprint, as imlab challenge prints it, and an edited built-in says so', async () => {
  const cliFingerprint = (text) => /fingerprint: (\S+)/.exec(execFileSync(cli, ['challenge', text]).toString())[1];
  await withPage('?challenge=step-tune', async (page) => {
    await graded(page);
    assert.equal(await page.textContent('#challenge-fingerprint'), cliFingerprint('step-tune'));
    assert.equal(await page.isVisible('#challenge-edited'), false);
  });
  const text = execFileSync(cli, ['challenge', 'step-tune']).toString().split('\n')[0];
  const edited = text.replace('need.current_peak=max:4', 'need.current_peak=max:40');
  assert.notEqual(edited, text);
  await withPage(`?${edited}`, async (page) => {
    await graded(page);
    assert.equal(await page.textContent('#challenge-fingerprint'), cliFingerprint(edited));
    assert.notEqual(cliFingerprint(edited), cliFingerprint('step-tune'));
    assert.match(await page.textContent('#challenge-edited'), /step-tune/);
    assert.match(await page.textContent('#challenge-verdict'), /not the built-in step-tune/);
  });
});

test('a published scenario link opens no challenge', () =>
  withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    assert.equal(await page.isHidden('#challenge-panel'), true);
    assert.equal(await page.evaluate(() => document.body.dataset.challenge), undefined);
    assert.match(page.url(), /\?v=1&preset=step$/);
  }));

test('a built-in’s name with a try opens as that built-in’s submission, as imlab grade reads it', async () => {
  const short = 'challenge=step-tune&try.k1=2000';
  await withPage(`?${short}`, async (page) => {
    assert.equal(await graded(page), 'fail');
    assert.equal(await page.inputValue('#challenge-k1'), '2000');
    assert.equal(await page.textContent('#challenge-panel h2'), 'Fast step within the rating');
    assert.match(page.url(), /\?c=1&.*&try\.k1=2000$/);
  });
  const grades = execFileSync(cli, ['grade', 'step-tune', '-'], { input: `${short}\n` }).toString();
  assert.match(grades.split('\n')[1], /^1,challenge=step-tune&try\.k1=2000,ok,.*,0$/);
});
