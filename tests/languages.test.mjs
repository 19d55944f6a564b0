// The language a page speaks: the link's `lang=`, else the browser's preferred language the page
// speaks, else English; only that language's messages are fetched, and kept for offline use; the
// menu switches the language and keeps the run; every link the page writes names the language.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, settled } from './browser.mjs';
import { LANGUAGES } from '../web/l10n/languages.js';
import { messagesOf } from './texts.mjs';

const suite = browserSuite();

/**
 * Opens `path` in a fresh context with `options` (a browser locale), noting the languages whose
 * message files it fetches (`locales/LANG/…`), runs `body(page, fetched)`, and fails on any
 * console or page error.
 */
async function withContext(options, path, body) {
  const errors = [];
  const fetched = [];
  const context = await suite.browser.newContext(options);
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  page.on('request', (r) => {
    const m = new URL(r.url()).pathname.match(/\/locales\/([^/]+)\//);
    if (m) fetched.push(m[1]);
  });
  try {
    await page.goto(`${suite.server.url}${path}`);
    await body(page, fetched);
  } finally {
    await context.close();
  }
  assert.deepEqual(errors, [], 'console errors');
}

test('a link’s lang= chooses the language; only its messages are fetched, and kept offline', () =>
  withContext({ locale: 'en-US' }, '?v=1&preset=step#lang=de', async (page, fetched) => {
    assert.equal(await settled(page), 'done');
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'de');
    assert.equal(await page.inputValue('#language'), 'de');
    // The lessons' texts are fetched once the page is idle, for the Lessons tab and offline use.
    await page.click('#tab-lessons');
    await page.waitForSelector('#lessons [data-lesson]');
    assert.equal(
      (await page.textContent('#lessons h3'))?.trim(),
      `1. ${messagesOf('de', 'lessons.ftl').get('step-response-title')}`,
    );
    assert.deepEqual([...new Set(fetched)], ['de']);
    await page.waitForFunction(() => document.body.dataset.offline === 'kept');
    const kept = await page.evaluate(async () => {
      const cache = await caches.open('imlab-v1');
      return (await cache.keys()).map((r) => new URL(r.url).pathname).filter((p) => p.includes('/locales/'));
    });
    // The language shown, and the English page messages the page falls back to.
    const german = kept.filter((p) => p.includes('/locales/de/'));
    const english = kept.filter((p) => /\/locales\/en\/page-/.test(p));
    assert.ok(german.length === 2 && english.length === 1 && kept.length === 3, `kept: ${kept}`);
  }));

test('with no lang= the browser’s preferred language the page speaks is chosen, else English', async () => {
  for (const [locale, expected] of [
    ['ja-JP', 'ja'],
    ['fr-CA', 'fr'],
    ['zh-CN', 'zh-CN'],
    ['pt-BR', 'en'],
  ])
    await withContext({ locale }, '?v=1&preset=step', async (page) => {
      assert.equal(await settled(page), 'done');
      assert.equal(await page.evaluate(() => document.documentElement.lang), expected, locale);
    });
});

test('a link the page writes names the language a browser’s preference chose', () =>
  withContext({ locale: 'ja-JP' }, '?v=1&preset=step', async (page) => {
    assert.equal(await settled(page), 'done');
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
    await page.click('#copy-link');
    await page.waitForFunction(() => navigator.clipboard.readText().then((t) => t.includes('lang=')));
    assert.match(new URL(await page.evaluate(() => navigator.clipboard.readText())).hash, /^#lang=ja$/);
    await page.click('#copy-embed');
    await page.waitForFunction(() => navigator.clipboard.readText().then((t) => t.startsWith('<iframe')));
    const embed = await page.evaluate(() => navigator.clipboard.readText());
    assert.match(embed, /#embed=[a-z,]+&amp;lang=ja"|#embed=[a-z,]+&lang=ja"/);
  }));

test('the menu switches the language and keeps the run; Copy link names the language', () =>
  suite.withPage('?v=1&preset=step&k1=600', async (page) => {
    assert.equal(await settled(page), 'done');
    assert.deepEqual(
      await page.$$eval('#language option', (options) => options.map((o) => [o.value, o.textContent])),
      LANGUAGES.map(([code, name]) => [code, name]),
    );
    await Promise.all([page.waitForEvent('load'), page.selectOption('#language', 'fr')]);
    assert.equal(await settled(page), 'done');
    const url = new URL(page.url());
    assert.equal(url.search, '?v=1&preset=step&k1=600');
    assert.match(url.hash, /lang=fr/);
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'fr');
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
    await page.click('#copy-link');
    await page.waitForFunction(() => navigator.clipboard.readText().then((t) => t.includes('lang=')));
    const copied = new URL(await page.evaluate(() => navigator.clipboard.readText()));
    assert.equal(copied.search, '?v=1&preset=step&k1=600');
    assert.match(copied.hash, /(^#|&)lang=fr(&|$)/);
  }));

test('before the rest of its messages arrives the page says nothing it lacks: first run, tabs, settings', async () => {
  const errors = [];
  const context = await suite.browser.newContext();
  const page = await context.newPage();
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  // The rest is held back until the first run is drawn and every tab and settings group opened.
  let release = () => {};
  const held = new Promise((resolve) => (release = resolve));
  await page.route('**/locales/*/rest-*.ftl', async (route) => {
    await held;
    await route.continue();
  });
  try {
    await page.goto(
      `${suite.server.url}?v=1&preset=step&law.v1=-si1%20%2B%20dwd%20%2B%20a3*wd%20%2B%20a2%20-%20k1*z1#lang=de`,
    );
    assert.equal(await settled(page), 'done');
    for (const tab of ['walkthrough', 'lessons', 'analysis', 'challenge', 'plots']) await page.click(`#tab-${tab}`);
    const groups = await page.$$('#settings details summary');
    assert.ok(groups.length > 5);
    for (const summary of groups) await summary.click();
    assert.deepEqual(errors, [], 'the rest held back');
    release();
    // Then the lessons and the law's verdict are said.
    await page.waitForSelector('#lessons [data-lesson]', { state: 'attached' });
    await page.waitForSelector('#settings .law-field .law-verdict.bad', { state: 'attached' });
    // Its number in German, as the CLI's English writes it (1.58e-4) with a decimal comma.
    const verdict = await page.textContent('#settings .law-field .law-verdict.bad');
    assert.match(verdict, /um bis zu 1,58e-4 /, verdict);
  } finally {
    release();
    await context.close();
  }
  assert.deepEqual(errors, []);
});
