// Where a challenge comes from, as its header says: a lecturer composes one in the Challenge tab;
// its link opened in the same browser says "Set by you in this browser" (with a student's
// settings too), a copy with a looser bound and a new title says "Not a challenge you set" while
// it shows ✓ Passed, the same link in a fresh browser context says "Not … in this browser", and a
// built-in says so. Where the browser keeps no record (storage blocked, no Web Crypto) the
// header says it cannot tell, and nothing else is lost. A screen reader reads the mark with the
// title (it describes the heading).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, settled } from './browser.mjs';

// The server and the browser of this file; the lecturer's pages share one context.
const suite = browserSuite();

/** Opens a page in `context` that records console and page errors into `errors`. */
async function newPage(context, errors) {
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  return page;
}

/**
 * A fresh browser context (`init` run in each of its pages before the page's scripts) and the
 * errors its pages log; `close()` closes it and fails on any.
 */
async function newContext(init = () => {}) {
  const context = await suite.browser.newContext({ viewport: { width: 1280, height: 720 } });
  await context.addInitScript(init);
  const errors = [];
  return {
    open: async (path) => {
      const page = await newPage(context, errors);
      await page.goto(`${suite.server.url}${path}`);
      return page;
    },
    close: async () => {
      await context.close();
      assert.deepEqual(errors, [], 'console errors');
    },
  };
}

/** Waits until the challenge's first check is graded; returns the outcome. */
async function graded(page) {
  await page.waitForFunction(
    () =>
      Number(document.body.dataset.challengeChecked ?? 0) > 0 &&
      ['pass', 'fail', 'refused', 'failed'].includes(document.body.dataset.challenge),
    null,
    { timeout: 60_000 },
  );
  return page.evaluate(() => document.body.dataset.challenge);
}

/** The header's mark: where the challenge comes from, and what it says. */
const origin = (page) =>
  page.$eval('#challenge-origin', (e) => ({ origin: e.dataset.origin, text: e.textContent, role: e.role }));

/**
 * Composes in `page` (the Challenge tab, on the step preset): k1 allowed in its prefilled range
 * (600 to 2400), the current peak at most 2.85 A (the base's is 2.873 A: it fails, k1=2400
 * passes), titled `title`; returns the challenge link and what the form says of the record.
 */
async function compose(page, title) {
  await settled(page);
  await page.click('#tab-challenge');
  await page.waitForFunction(() => document.body.dataset.compose === 'filled');
  await page.selectOption('#compose-field', 'k1');
  await page.click('#compose-add');
  await page.fill('#compose-title', title);
  await page.check('#compose-need-current_peak');
  await page.fill('#compose-need-current_peak-bound', '2.85');
  await page.click('#compose-make');
  await page.waitForFunction(() => document.body.dataset.compose === 'made');
  const link = await page.inputValue('#compose-link');
  return { query: link.slice(link.indexOf('?')), kept: await page.textContent('#compose-kept') };
}

/** The heading's accessible name and description, as the browser gives them to a screen reader. */
async function headingNode(page, name) {
  const cdp = await page.context().newCDPSession(page);
  const { nodes } = await cdp.send('Accessibility.getFullAXTree');
  const node = nodes.find((n) => n.role?.value === 'heading' && n.name?.value === name);
  return { name: node?.name?.value, description: node?.description?.value };
}

test('a challenge composed in this browser says so in its header; an edited copy, another browser and a built-in do not', async () => {
  const lecturer = await newContext();
  let query;
  let loosened;
  try {
    const composer = await lecturer.open('?v=1&preset=step');
    const made = await compose(composer, 'Gentle step');
    query = made.query;
    assert.match(made.kept, /keeps a record that it composed this challenge/);
    assert.match(query, /^\?c=1&title=Gentle%20step&.*&need\.current_peak=max:2\.85#lang=en$/);
    // Its language aside, the rest of the tests add to the link's query.
    query = query.split('#')[0];
    // The composer's own check is not waited for: the record is kept once the link is made.
    await composer.close();

    const mine = await lecturer.open(query);
    assert.equal(await graded(mine), 'fail');
    assert.deepEqual(await origin(mine), {
      origin: 'mine',
      text: 'Set by you in this browser: it composed exactly this challenge (bounds and title unchanged)',
      role: 'note',
    });
    // Read with the title: the mark describes the heading.
    assert.deepEqual(await headingNode(mine, 'Gentle step'), {
      name: 'Gentle step',
      description: (await origin(mine)).text,
    });
    await mine.close();

    // A student's settings in a submission link leave the challenge as composed.
    const submission = await lecturer.open(`${query}&try.k1=2400`);
    assert.equal(await graded(submission), 'pass');
    assert.equal((await origin(submission)).origin, 'mine');
    await submission.close();

    // A copy with a looser bound and a new title: it passes, and is not the one composed here.
    loosened = query.replace('title=Gentle%20step', 'title=Easy%20step').replace('max:2.85', 'max:4');
    assert.notEqual(loosened, query);
    const copy = await lecturer.open(loosened);
    assert.equal(await graded(copy), 'pass');
    assert.match(await copy.textContent('#challenge-verdict'), /^✓ Passed/);
    assert.equal(await copy.textContent('#challenge-panel h2'), 'Easy step');
    assert.deepEqual(await origin(copy), {
      origin: 'other',
      text: 'Not a challenge you set in this browser',
      role: 'note',
    });
    await copy.close();

    // Only the bound loosened, the title kept: still not the one composed here.
    const bound = await lecturer.open(query.replace('max:2.85', 'max:2.86'));
    await graded(bound);
    assert.equal((await origin(bound)).origin, 'other');
    await bound.close();

    const builtin = await lecturer.open('?challenge=step-tune');
    await graded(builtin);
    assert.deepEqual(await origin(builtin), { origin: 'builtin', text: 'Built-in challenge', role: 'note' });
    await builtin.close();
  } finally {
    await lecturer.close();
  }

  // Another browser (a fresh context: no site data) knows nothing of it.
  const other = await newContext();
  try {
    const page = await other.open(query);
    assert.equal(await graded(page), 'fail');
    assert.deepEqual(await origin(page), {
      origin: 'other',
      text: 'Not a challenge you set in this browser',
      role: 'note',
    });
  } finally {
    await other.close();
  }
});

for (const [why, init] of [
  [
    'its storage is blocked',
    () =>
      Object.defineProperty(window, 'localStorage', {
        get: () => {
          throw new DOMException('The storage is blocked.', 'SecurityError');
        },
      }),
  ],
  ['it has no Web Crypto', () => Object.defineProperty(Crypto.prototype, 'subtle', { get: () => undefined })],
]) {
  test(`where the browser keeps no record (${why}) the header says it cannot tell, and nothing else is lost`, async () => {
    const context = await newContext(init);
    try {
      const composer = await context.open('?v=1&preset=step');
      const made = await compose(composer, 'Gentle step');
      assert.match(made.kept, /keeps no record of the challenges it composed/);
      await composer.close();

      const page = await context.open(made.query);
      assert.equal(await graded(page), 'fail');
      assert.deepEqual(await origin(page), {
        origin: 'unknown',
        text: 'This browser keeps no record of the challenges it composed',
        role: 'note',
      });
      // The challenge itself works as ever: a passing design passes.
      await page.fill('#challenge-k1', '2400');
      await page.click('#challenge-run');
      await page.waitForFunction(() => document.body.dataset.challenge === 'pass', null, { timeout: 60_000 });
      // A built-in is known without any record.
      await page.goto(`${suite.server.url}?challenge=ifoc-load`);
      await graded(page);
      assert.equal((await origin(page)).origin, 'builtin');
    } finally {
      await context.close();
    }
  });
}
