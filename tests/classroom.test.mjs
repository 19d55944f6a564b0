// A class's use of the page: a lesson's link, a lesson that starts from its own state, and the
// "not run yet" note where the eye is. Every test fails on a console error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, settled } from './browser.mjs';
import { lessonsIn } from './texts.mjs';

const LESSONS = lessonsIn('en');

const suite = browserSuite();

/** Opens lesson `id` from the Lessons tab and waits for its run. */
async function startLesson(page, run) {
  await page.click('#tab-lessons');
  const before = await page.evaluate(() => Number(document.body.dataset.started ?? 0));
  await page.click(`#lessons button[data-lesson="${run}"]`);
  await page.waitForFunction((n) => Number(document.body.dataset.started ?? 0) > n, before);
  await settled(page);
}

test('every lesson has a link name of its own', () => {
  const ids = LESSONS.map((l) => l.id);
  assert.ok(
    ids.every((id) => /^[a-z0-9-]+$/.test(id)),
    ids.join(),
  );
  assert.equal(new Set(ids).size, ids.length, 'two lessons share a name');
});

for (const present of [false, true]) {
  test(`a lesson's link opens its panel and its run${present ? ', in presentation mode' : ''}`, () => {
    const lesson = LESSONS.find((l) => l.id === 'rr-mismatch');
    return suite.withPage(`#lesson=${lesson.id}${present ? '&present=1' : ''}`, async (page) => {
      await settled(page);
      assert.equal(await page.getAttribute('#lesson-panel', 'data-open'), lesson.run);
      assert.equal(await page.textContent('#lesson-panel h2'), lesson.title);
      assert.equal(new URL(page.url()).search.slice(1), lesson.run);
      assert.equal(await page.evaluate(() => document.body.classList.contains('present')), present);
      // The address names the lesson while it is open: a reload opens it again, with its run.
      assert.match(new URL(page.url()).hash, new RegExp(`lesson=${lesson.id}`));
      await page.reload();
      await settled(page);
      assert.equal(await page.getAttribute('#lesson-panel', 'data-open'), lesson.run);
      assert.equal(await page.isVisible('#lesson-panel .own-settings'), false);
      assert.equal(await page.evaluate(() => document.body.classList.contains('present')), present);
      // "Copy link to this lesson" keeps the mode the lesson is shown in, and names the language.
      await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
      await page.click('#lesson-panel .copy-lesson');
      await page.waitForFunction(() =>
        /copied/.test(document.querySelector('#lesson-panel [role=status]').textContent),
      );
      const copied = new URL(await page.evaluate(() => navigator.clipboard.readText()));
      assert.equal(copied.hash, `#lesson=${lesson.id}${present ? '&present=1' : ''}&lang=en`);
      await page.click('#lesson-panel .close');
      assert.doesNotMatch(new URL(page.url()).hash, /lesson=/);
    });
  });
}

test('a lesson link with settings of its own shows them, says how they differ from the lesson’s run, and offers the run', () => {
  const lesson = LESSONS.find((l) => l.id === 'rr-mismatch');
  return suite.withPage(`?${lesson.run}&k1=600#lesson=${lesson.id}`, async (page) => {
    await settled(page);
    assert.equal(await page.getAttribute('#lesson-panel', 'data-open'), lesson.run);
    await page.waitForSelector('#lesson-panel .own-settings:not([hidden])');
    assert.match(await page.textContent('#lesson-panel .own-settings'), /settings of its own.*k1: \d+ → 600/);
    assert.match(await page.evaluate(() => document.body.dataset.scenario), /&k1=600(&|$)/);
    assert.match(new URL(page.url()).search, /&k1=600(&|$)/);
    // Back to it from the next lesson, the note is there again.
    let before = await page.evaluate(() => Number(document.body.dataset.started));
    await page.click('#lesson-panel .buttons button:has-text("Next")');
    await page.waitForFunction((n) => Number(document.body.dataset.started) > n, before);
    await settled(page);
    assert.equal(await page.isVisible('#lesson-panel .own-settings'), false);
    await page.goBack();
    await page.waitForSelector('#lesson-panel .own-settings:not([hidden])');
    assert.equal(await page.getAttribute('#lesson-panel', 'data-open'), lesson.run);
    await settled(page);
    before = await page.evaluate(() => Number(document.body.dataset.started));
    await page.click('#lesson-panel .own-settings button');
    await page.waitForFunction((n) => Number(document.body.dataset.started) > n, before);
    await settled(page);
    assert.equal(new URL(page.url()).search.slice(1), lesson.run);
    assert.equal(await page.isVisible('#lesson-panel .own-settings'), false);
  });
});

test('"Copy link to this lesson" gives the link by name, and an unknown name is said with the names there are', () =>
  suite.withPage('#lesson=no-such-lesson', async (page) => {
    await settled(page);
    assert.equal(await page.isVisible('#lesson-panel'), false);
    const message = await page.textContent('#message');
    assert.match(message, /No lesson named 'no-such-lesson'/);
    for (const l of LESSONS) assert.ok(message.includes(l.id), `${l.id} is not listed`);
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
    await startLesson(page, LESSONS[3].run);
    await page.click('#lesson-panel .copy-lesson');
    await page.waitForFunction(() => /copied/.test(document.querySelector('#lesson-panel [role=status]').textContent));
    const link = new URL(await page.evaluate(() => navigator.clipboard.readText()));
    assert.equal(link.search.slice(1), LESSONS[3].run);
    assert.equal(link.hash, `#lesson=${LESSONS[3].id}&lang=en`);
  }));

test('Back and Forward follow the lessons: each entry shows the lesson it was, or none', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    const [a, b] = [LESSONS[3], LESSONS[4]];
    await startLesson(page, a.run);
    assert.equal(new URL(page.url()).hash, `#lesson=${a.id}`);
    const before = await page.evaluate(() => Number(document.body.dataset.started));
    await page.click('#lesson-panel .buttons button:has-text("Next")');
    await page.waitForFunction((n) => Number(document.body.dataset.started) > n, before);
    await settled(page);
    await page.waitForFunction((id) => location.hash === `#lesson=${id}`, b.id);
    const shows = () =>
      page.evaluate(() => {
        const panel = document.getElementById('lesson-panel');
        return { open: panel.hidden ? null : panel.dataset.open, search: location.search.slice(1) };
      });
    await page.goBack();
    await page.waitForFunction((run) => document.body.dataset.scenario === run, a.run);
    assert.deepEqual(await shows(), { open: a.run, search: a.run });
    assert.equal(await page.isVisible('#lesson-panel .own-settings'), false);
    await page.goBack();
    await page.waitForFunction(() => document.getElementById('lesson-panel').hidden);
    assert.deepEqual(await shows(), { open: null, search: 'v=1&preset=step' });
    await page.goForward();
    await page.waitForFunction(() => !document.getElementById('lesson-panel').hidden);
    assert.equal((await shows()).open, a.run);
  }));

test('a lesson starts from its own state: a run pinned in another lesson is not in its overlay', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    await startLesson(page, LESSONS[0].run);
    await page.click('#tab-plots');
    await page.click('#pin');
    await page.waitForFunction(() => document.querySelectorAll('#pins li').length === 1);
    await startLesson(page, LESSONS[1].run);
    await page.waitForFunction(
      () => document.querySelectorAll('#pins li').length === 0 && !document.querySelector('#overlay-plots canvas'),
    );
    assert.doesNotMatch(new URL(page.url()).hash, /pins=/);
  }));

test('a setting edited far down the form says "not run yet" within the window, where the field is', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    const field = page.locator('#settings input[type=text]:visible').last();
    await field.scrollIntoViewIfNeeded();
    await field.fill(String(Number(await field.inputValue()) * 1.5 || 1));
    await field.press('Tab');
    await page.waitForFunction(() => document.body.dataset.unrun === '1');
    const at = await page.evaluate(() => {
      const box = (e) => e.getBoundingClientRect();
      return { note: box(document.querySelector('#unrun')), window: innerHeight };
    });
    assert.ok(
      at.note.height > 0 && at.note.top >= 0 && at.note.bottom <= at.window,
      `the note spans ${at.note.top}–${at.note.bottom} px`,
    );
  }));

for (const plots of ['speed', 'speed,speed-error', 'speed,speed-error,current']) {
  const n = plots.split(',').length;
  test(`an embed of ${n} plot${n > 1 ? 's' : ''} is whole in the copied frame from 640 px wide, and never squashed in a smaller one`, async () => {
    // The copied snippet's height: 140 px, then 300 px a plot (share.js).
    for (const [width, height, whole] of [
      [640, 140 + 300 * n, true],
      [960, 140 + 300 * n, true],
      [400, 300, false],
    ]) {
      const context = await suite.browser.newContext({ viewport: { width, height } });
      const page = await context.newPage();
      try {
        await page.goto(`${suite.server.url}?v=1&preset=step#embed=${plots}`);
        await settled(page);
        const at = await page.$$eval('#plots .plot.embedded', (list) =>
          list.map((p) => ({
            bottom: p.getBoundingClientRect().bottom,
            area: p.querySelector('.u-over').clientHeight,
          })),
        );
        assert.equal(at.length, n);
        const bottom = Math.max(...at.map((p) => p.bottom));
        if (whole) assert.ok(bottom <= height, `${width}×${height}: the plots end at ${bottom} px`);
        for (const p of at) assert.ok(p.area >= 100, `${width}×${height}: a plot area of ${p.area} px`);
      } finally {
        await context.close();
      }
    }
  });
}

test('where the browser refuses the service worker, as in another site’s frame, the embed runs and logs no error', async () => {
  const context = await suite.browser.newContext({ viewport: { width: 800, height: 600 } });
  const errors = [];
  try {
    const page = await context.newPage();
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    page.on('pageerror', (e) => errors.push(e.message));
    // What Chromium answers a frame whose storage it blocks.
    await page.addInitScript(() => {
      navigator.serviceWorker.register = () =>
        Promise.reject(new DOMException('The user denied permission to use Service Worker.', 'SecurityError'));
    });
    await page.goto(`${suite.server.url}?v=1&preset=step#embed=speed`);
    await settled(page);
    await page.waitForFunction(() => document.body.dataset.offline === 'refused');
  } finally {
    await context.close();
  }
  assert.deepEqual(errors, []);
});
