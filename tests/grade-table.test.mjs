// The table of a class's grading, as a lecturer reads it on a projector: at 1280×720, in the
// page's layout and in presentation mode, 15 students stand on one screen with their verdicts and
// each criterion's value, the values those of the CSV `imlab grade` writes; every header sorts the
// rows by its column, by mouse and by keyboard, and says so in aria-sort; the cause of a row that
// was not judged is in the row, whole.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { browserSuite, settled } from './browser.mjs';
import { initSync } from '../dist/pkg/imlab.js';
import { CHALLENGE_JOBS as jobs } from '../dist/.src/worker/challenge-jobs.js';
import { english } from './core-english.mjs';

initSync({ module: readFileSync(new URL('../dist/pkg/imlab_bg.wasm', import.meta.url)) });

const suite = browserSuite();
const STUDENTS = 18;
// The screen of a projector's laptop, and the students it must show at once.
const SCREEN = { width: 1280, height: 720 };
const AT_ONCE = 15;

const builtin = jobs['challenge-builtins']({}).find((b) => b.name === 'step-tune');
const tries = (pairs) => pairs.map((p) => `&try.${p}`).join('');
// Passing, failing by different margins, refused and malformed submissions; and one whose step
// never settles, with a current peak of two digits where the others have one (sorted as text,
// it would come first).
const kinds = [
  `${builtin.text}${tries(builtin.solution.split('&'))}`,
  builtin.text,
  `${builtin.text}&try.k1=9999`,
  'not a link at all',
  `${builtin.text}&try.k2=600`,
  `${builtin.text}&try.k3=1900&try.k4=1900`,
  `${builtin.text}&try.k1=1500&try.k2=2500`,
];
const quoted = (s) => `"${s.replaceAll('"', '""')}"`;
const links = Array.from({ length: STUDENTS }, (_, i) => kinds[i % kinds.length]);
const classFile = join(mkdtempSync(join(tmpdir(), 'imlab-grade-table-')), 'class.csv');
writeFileSync(
  classFile,
  // The names out of the file's order (7 and 18 share no factor): sorting by name reorders the rows.
  `name,link\n${links.map((l, i) => `${quoted(`Student ${((i * 7) % STUDENTS) + 1}`)},${quoted(l)}`).join('\n')}\n`,
);

/** The CSV's rows by line, as cells by column name (its cells hold no comma or line end but in quotes). */
function byLine(csv) {
  const text = (cell) => (cell.startsWith('"') ? cell.slice(1, -1).replaceAll('""', '"') : cell);
  const cells = (line) => [...line.matchAll(/("(?:[^"]|"")*"|[^,]*)(?:,|$)/g)].map((m) => text(m[1])).slice(0, -1);
  const [head, ...rows] = csv.trimEnd().split('\n').map(cells);
  return new Map(rows.map((r) => [r[head.indexOf('line')], Object.fromEntries(head.map((h, i) => [h, r[i]]))]));
}

/**
 * The cell of `figure` for the CSV's `line` as the checklist writes a value (four significant
 * digits) with its mark; none for a row not judged.
 */
function shownValue(line, figure) {
  const mark = line[`${figure}_pass`] === '1' ? '✓' : '✗';
  if (line[figure] !== '') return `${Number(Number(line[figure]).toPrecision(4))} ${mark}`;
  return line.status === 'ok' ? `not measured ${mark}` : '';
}

/** Grades the class in the page; resolves to the CSV it downloads. */
async function gradeClass(page) {
  await settled(page);
  await page.click('#tab-challenge');
  await page.fill('#grade-challenge', 'step-tune');
  await page.setInputFiles('#grade-file', classFile);
  await page.click('#grade-run');
  await page.waitForFunction(() => document.body.dataset.grading === 'done', null, { timeout: 120_000 });
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#grade-csv')]);
  return readFileSync(await download.path(), 'utf8');
}

/** The table's rows as shown, top to bottom: each cell's text by its column's id. */
const shownRows = (page) =>
  page.evaluate(() => {
    const ids = [...document.querySelectorAll('#grade-table thead button')].map((b) => b.dataset.column);
    return [...document.querySelectorAll('#grade-table tbody tr')].map((tr) =>
      Object.fromEntries(
        [...tr.cells].map((c, j) => [ids[j], c.querySelector('summary')?.textContent ?? c.textContent]),
      ),
    );
  });

/** Clicks the header of `column`; resolves to its aria-sort. */
async function sortBy(page, column) {
  await page.click(`#grade-table th button[data-column="${column}"]`);
  return page.getAttribute(`#grade-table th:has(button[data-column="${column}"])`, 'aria-sort');
}

/**
 * Asserts that the table's first AT_ONCE rows, each with its verdict and its values, stand
 * whole on the screen once the table is scrolled to its top (and not scrolled sideways).
 */
async function assertOneScreen(page, mode) {
  await page.evaluate(() => document.getElementById('grade-table').scrollIntoView({ block: 'start' }));
  const boxes = await page.evaluate((n) => {
    const box = document.querySelector('#grade-section .table-scroll').getBoundingClientRect();
    const rows = [...document.querySelectorAll('#grade-table tbody tr')].slice(0, n);
    return {
      box: { left: box.left, right: box.right },
      cells: rows.flatMap((tr) =>
        [...tr.cells]
          .filter((c) => !c.classList.contains('link'))
          .map((c) => ({ text: c.textContent, ...c.getBoundingClientRect().toJSON() })),
      ),
    };
  }, AT_ONCE);
  assert.equal(boxes.cells.length, AT_ONCE * 5, `${mode}: name, line, verdict and two values a row`);
  for (const c of boxes.cells) {
    assert.ok(c.top >= 0 && c.bottom <= SCREEN.height, `${mode}: '${c.text}' off the screen: ${c.top}–${c.bottom}`);
    assert.ok(c.left >= boxes.box.left && c.right <= boxes.box.right, `${mode}: '${c.text}' scrolled out of sight`);
  }
}

test('15 students stand on a 1280×720 screen with their values, in presentation mode too', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await page.setViewportSize(SCREEN);
    const csv = byLine(await gradeClass(page));
    // Every value shown is the CSV's, as the checklist writes it (four significant digits).
    const rows = await shownRows(page);
    assert.equal(rows.length, STUDENTS);
    for (const row of rows) {
      const line = csv.get(row.line);
      assert.equal(row['carried:name'], line.name);
      for (const figure of ['settling_time', 'current_peak']) {
        assert.equal(row[`need:${figure}`], shownValue(line, figure), `line ${row.line}, ${figure}`);
      }
      assert.equal(row.verdict.startsWith('✓ pass'), line.pass === '1', `line ${row.line}: ${row.verdict}`);
    }
    // The headers give each criterion's bound in the core's words.
    assert.match(await page.textContent('#grade-table th button[data-column="need:settling_time"]'), /≤ 0\.004 s/);
    await assertOneScreen(page, 'page');
    await page.click('#present');
    await page.waitForFunction(() => document.body.classList.contains('present'));
    await assertOneScreen(page, 'presentation mode');
  }));

test('a header sorts the rows by its column, either way, by mouse and by keyboard', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    const csv = byLine(await gradeClass(page));
    assert.equal(await page.getAttribute('#grade-table th:has(button[data-column="line"])', 'aria-sort'), 'ascending');
    for (const figure of ['settling_time', 'current_peak']) {
      const values = async () => (await shownRows(page)).map((r) => csv.get(r.line)[figure]);
      assert.equal(await sortBy(page, `need:${figure}`), 'ascending');
      const measured = [...csv.values()].map((r) => r[figure]).filter((v) => v !== '');
      const ascending = [...measured].sort((a, b) => a - b);
      // Rows without a value come last, either way.
      const none = Array(STUDENTS - measured.length).fill('');
      assert.deepEqual(await values(), [...ascending, ...none], figure);
      assert.equal(await sortBy(page, `need:${figure}`), 'descending');
      assert.deepEqual(await values(), [...ascending.reverse(), ...none], figure);
    }
    // One column sorts at a time.
    assert.equal(await page.locator('#grade-table th[aria-sort]').count(), 1);

    // The verdicts: passed, then failed, then not judged.
    await sortBy(page, 'verdict');
    const verdicts = (await shownRows(page)).map((r) => csv.get(r.line));
    const rank = (r) => (r.pass === '1' ? 0 : r.status === 'ok' ? 1 : 2);
    assert.deepEqual(
      verdicts.map(rank),
      verdicts.map(rank).sort((a, b) => a - b),
    );
    assert.ok(verdicts.map(rank).includes(0) && verdicts.map(rank).includes(2));

    // Names in the order a reader expects, by keyboard: Student 2 before Student 10.
    await page.focus('#grade-table th button[data-column="carried:name"]');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#grade-table th[aria-sort=ascending]:has(button[data-column="carried:name"])');
    const names = (await shownRows(page)).map((r) => r['carried:name']);
    assert.deepEqual(
      names,
      Array.from({ length: STUDENTS }, (_, i) => `Student ${i + 1}`),
    );
  }));

test('the cause of a malformed or refused row is in the row, whole', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    const csv = byLine(await gradeClass(page));
    const line = [...csv.values()].find((r) => r.link === 'not a link at all');
    const status = line.status;
    assert.match(status, /^malformed: /);
    const cause = page.locator(`#grade-table tbody tr:has(td:text-is("${line.line}")) details.cause`);
    assert.equal(await cause.locator('summary').getAttribute('title'), status);
    assert.equal(await cause.locator('summary').textContent(), `✗ ${status}`);
    // Opened, by keyboard, the whole cause shows.
    await cause.locator('summary').focus();
    await page.keyboard.press('Enter');
    const whole = cause.locator('div');
    await whole.waitFor({ state: 'visible' });
    assert.equal(await whole.textContent(), status);
    // A failed criterion's cell says its exact value and why it fails; one not measured, why not.
    const row = (line) => page.locator(`#grade-table tbody tr:has(td:text-is("${line}"))`);
    const failed = [...csv.values()].find((r) => r.status === 'ok' && r.settling_time_pass === '0' && r.settling_time);
    assert.match(
      await row(failed.line).locator('td.value').first().locator('summary').getAttribute('title'),
      new RegExp(`^${failed.settling_time.replaceAll('.', '\\.')} s: above the bound( \\(worst run: seed=\\d+\\))?$`),
    );
    const unsettled = [...csv.values()].find((r) => r.status === 'ok' && r.settling_time === '');
    const none = row(unsettled.line).locator('td.value').first();
    assert.equal(await none.locator('summary').textContent(), 'not measured ✗');
    const { criteria } = jobs['grade-link']({ text: builtin.text, row: { line: 1, link: unsettled.link } }).verdict;
    const reason = english(criteria[0].reason);
    assert.ok(reason.length > 0);
    const run = criteria[0].run === 'nominal' ? '' : ` (worst run: ${criteria[0].run})`;
    assert.equal(await none.locator('summary').getAttribute('title'), `${reason}${run}`);
  }));

test('a grading kept in the browser shows its verdicts and values again after a reload', () =>
  suite.withPage('?v=1&preset=step', async (page) => {
    await gradeClass(page);
    const graded = await shownRows(page);
    // The first row's settling time made infinite in the kept grading, as JSON cannot write it:
    // the table after the reload is drawn from what was kept.
    await page.evaluate(() => {
      const record = JSON.parse(localStorage.getItem('imlab-grading'));
      record.results[0].verdict.criteria[0].value = { 'not-finite': 'Infinity' };
      localStorage.setItem('imlab-grading', JSON.stringify(record));
    });
    await page.reload();
    await gradeClass(page);
    assert.match(await page.textContent('#grade-status'), /^Graded 18 of 18/);
    const [first, ...rest] = await shownRows(page);
    assert.deepEqual(rest, graded.slice(1));
    assert.deepEqual(first, { ...graded[0], 'need:settling_time': 'never (∞) ✓' });
  }));
