// Grading a class in the page: the CSV the page downloads is the one `imlab grade` writes for the
// same challenge and class file, byte for byte, on a class that mixes passing, failing, refused,
// edited, malformed and formula-like links, in both shapes of class file; a cancelled grading is
// kept, and Grade goes on from where it stopped, after a reload too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { browserSuite, settled } from './browser.mjs';
import { initSync } from '../dist/pkg/imlab.js';
import { CHALLENGE_JOBS as jobs } from '../dist/.src/worker/challenge-jobs.js';

initSync({ module: readFileSync(new URL('../dist/pkg/imlab_bg.wasm', import.meta.url)) });

const cli = new URL('../target/release/imlab', import.meta.url).pathname;
const suite = browserSuite();
const dir = mkdtempSync(join(tmpdir(), 'imlab-grading-'));

const builtin = jobs['challenge-builtins']({}).find((b) => b.name === 'step-tune');
const tries = (pairs) => pairs.map((p) => `&try.${p}`).join('');
const solved = `${builtin.text}${tries(builtin.solution.split('&'))}`;
// The same title with a looser bound: another challenge, which claims the built-in's name.
const edited = `${builtin.text.replace('need.current_peak=max:4', 'need.current_peak=max:40')}${tries(builtin.solution.split('&'))}`;

/** A class of `n` links: passing, failing, refused, edited, malformed and formula-like ones. */
function classLinks(n) {
  const kinds = [
    solved,
    builtin.text,
    `${builtin.text}&try.k1=9999`,
    edited,
    'not a link at all',
    `=1+1?${solved}`,
    `${builtin.text}&try.k2=600`,
  ];
  return Array.from({ length: n }, (_, i) => kinds[i % kinds.length]);
}

/** Writes `text` to a file of the test's folder; returns its path. */
function file(name, text) {
  const path = join(dir, name);
  writeFileSync(path, text);
  return path;
}

/** `imlab grade step-tune PATH`'s CSV. */
const cliGrade = (path) =>
  execFileSync(cli, ['grade', 'step-tune', path], { stdio: ['ignore', 'pipe', 'ignore'] }).toString();

/** Opens the Challenge tab's grading with `path` chosen and `step-tune` named. */
async function openGrading(page, path) {
  await settled(page);
  await page.click('#tab-challenge');
  await page.fill('#grade-challenge', 'step-tune');
  await page.setInputFiles('#grade-file', path);
}

/** Downloads the page's CSV. */
async function downloaded(page) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#grade-csv')]);
  return readFileSync(await download.path(), 'utf8');
}

for (const [shape, name, text] of [
  ['one link a line, with CRLF line ends', 'class.txt', `${classLinks(7).join('\r\n')}\r\n`],
  [
    'a CSV export with a column of names, with a byte-order mark',
    'class.csv',
    `\ufeffname,link\r\n${classLinks(7)
      .map((l, i) => `"Student ${i + 1}, A.","${l.replaceAll('"', '""')}"`)
      .join('\r\n')}\r\n`,
  ],
]) {
  test(`the page's grading of a class (${shape}) is the CSV imlab grade writes`, () =>
    suite.withPage('?v=1&preset=step', async (page) => {
      const path = file(name, text);
      await openGrading(page, path);
      await page.click('#grade-run');
      await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 120_000 });
      const csv = await downloaded(page);
      assert.equal(csv, cliGrade(path));
      // Every kind of line is there, and no cell can start a formula.
      for (const status of ['ok', 'refused', 'another challenge', 'malformed'])
        assert.ok(csv.includes(status), `no '${status}' row`);
      for (const line of csv.split('\n')) assert.doesNotMatch(line, /(^|,)"?[=+@]/);
      assert.match(await page.textContent('#grade-status'), /^Graded 7 of 7: \d+ passed\./);
      assert.equal(await page.locator('#grade-table tbody tr').count(), 7);
    }));
}

test('a cancelled grading is kept: after a reload, Grade goes on where it stopped and gives the same CSV', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    const path = file('large.txt', `${classLinks(28).join('\n')}\n`);
    await openGrading(page, path);
    await page.click('#grade-run');
    // Cancel is pressed in the task that shows the third graded row, before the grading can end.
    await page.evaluate(
      () =>
        new Promise((resolve) => {
          const table = /** @type {HTMLElement} */ (document.getElementById('grade-table'));
          const cancelled = () => {
            if (table.querySelectorAll('tr[data-pass]').length < 3) return false;
            /** @type {HTMLButtonElement} */ (document.getElementById('grade-cancel')).click();
            resolve(undefined);
            return true;
          };
          if (!cancelled())
            new MutationObserver((_, o) => cancelled() && o.disconnect()).observe(table, {
              subtree: true,
              childList: true,
              attributes: true,
            });
        }),
    );
    await page.waitForFunction(() => document.body.dataset.grading === 'cancelled');
    const kept = await page.locator('#grade-table tr[data-pass]').count();
    assert.match(await page.textContent('#grade-status'), /^Cancelled: \d+ of 28 graded, kept in this browser/);
    await page.reload();
    await openGrading(page, path);
    await page.click('#grade-run');
    await page.waitForFunction(() =>
      /kept from the last grading/.test(document.getElementById('grade-status').textContent),
    );
    await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 120_000 });
    assert.ok(kept >= 3);
    assert.equal(await downloaded(page), cliGrade(path));
  }));

test('Cancel while the class file is read ends the grading there: nothing is graded', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await openGrading(page, file('read.txt', `${classLinks(7).join('\n')}\n`));
    // Both clicks in one task: the reading has begun and cannot have ended.
    await page.evaluate(() => {
      document.getElementById('grade-run').click();
      document.getElementById('grade-cancel').click();
    });
    assert.equal(await page.evaluate(() => document.body.dataset.grading), 'cancelled');
    assert.equal(
      await page.textContent('#grade-status'),
      'Cancelled while the class file was read: nothing was graded.',
    );
    // The reading's end starts no grading, and Grade grades the whole class.
    await page.click('#grade-run');
    await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 120_000 });
    assert.match(await page.textContent('#grade-status'), /^Graded 7 of 7/);
  }));

test('a class file saved in Windows-1252 is read as such, said so, and graded as imlab grade grades it', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    const names = ['Müller, José', 'Françoise Lévêque', 'Zoë Ørsted'];
    const rows = classLinks(7).map((l, i) => `"${names[i % names.length]}","${l.replaceAll('"', '""')}"`);
    // Every character of the names is in Latin-1, which Windows-1252 writes as the same bytes.
    const path = file('legacy.csv', Buffer.from(`name,link\r\n${rows.join('\r\n')}\r\n`, 'latin1'));
    await openGrading(page, path);
    await page.click('#grade-run');
    await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 120_000 });
    const csv = await downloaded(page);
    assert.equal(csv, cliGrade(path));
    assert.ok(csv.includes('"Müller, José",2,'), csv);
    assert.match(
      await page.textContent('#grade-status'),
      /^Graded 7 of 7: \d+ passed\. The class file was read as windows-1252 \(it is not UTF-8\)\./,
    );
  }));

test('a class file the core refuses whole is said, and nothing is graded', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    // UTF-16 without a byte-order mark.
    const path = file('utf16.txt', Buffer.from(`${solved}\n`, 'utf16le'));
    await openGrading(page, path);
    await page.click('#grade-run');
    await page.waitForFunction(() => document.body.dataset.grading === 'refused');
    assert.match(await page.textContent('#grade-status'), /UTF-16 without a byte-order mark/);
    assert.equal(await page.isDisabled('#grade-csv'), true);
  }));

test('a class file with no submission is said, and the controls are free again', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await settled(page);
    await page.click('#tab-challenge');
    await page.fill('#grade-challenge', 'step-tune');
    await page.fill('#grade-paste', '# the class of Monday\n\n');
    await page.click('#grade-run');
    await page.waitForFunction(() => document.body.dataset.grading === 'refused');
    assert.match(await page.textContent('#grade-status'), /no submission/);
    assert.equal(await page.isEnabled('#grade-run'), true);
    assert.equal(await page.isDisabled('#grade-cancel'), true);
  }));
