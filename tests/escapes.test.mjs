// Text the page quotes from a link or a class file shows what it holds: a challenge's title and
// the grading table's names and links with their controls and bidi characters (ESC, RLO) written
// as the escapes the CLI writes, never raw.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { browserSuite, settled } from './browser.mjs';

const suite = browserSuite();

/** The characters that do not show or that reorder the text around them (Cc, Cf, Zl, Zp). */
const INVISIBLE = /[\p{Cc}\p{Cf}\p{Zl}\p{Zp}]/u;

test('a challenge’s title shows its ESC and its right-to-left override as escapes', () =>
  suite.withPage('?c=1&title=Tune%1B[31m%E2%80%AEkcats&base=step&need.current_peak=max:4', async (page) => {
    // The panel is drawn with the challenge's fingerprint.
    await page.waitForSelector('#challenge-fingerprint');
    const title = await page.textContent('#challenge-panel h2');
    assert.equal(title, 'Tune\\u{1b}[31m\\u{202e}kcats');
    assert.doesNotMatch(title, INVISIBLE);
    await settled(page);
  }));

test('the grading table shows names, headers and links with their ESC and override as escapes', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    await page.click('#tab-challenge');
    await page.fill('#grade-challenge', 'step-tune');
    await page.fill('#grade-paste', 'na\u202eme,link\n"Ada\u001b[2J\u202eecavol",not a link\u001b\n');
    await page.click('#grade-run');
    await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 60_000 });
    const cells = await page.$$eval('#grade-table th, #grade-table td', (list) => list.map((c) => c.textContent));
    assert.deepEqual(cells.slice(0, 2), ['na\\u{202e}me', 'line']);
    assert.ok(cells.includes('Ada\\u{1b}[2J\\u{202e}ecavol'), cells.join(' | '));
    assert.ok(cells.includes('not a link\\u{1b}'), cells.join(' | '));
    for (const cell of cells) assert.doesNotMatch(cell, INVISIBLE);
  }));
