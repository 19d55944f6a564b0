// Grading a class in the page, for the lecturer: a class file (one submission link a line, or a
// course platform's CSV export with a column of links) graded against a challenge in a pool of
// workers, with progress and Cancel, shown as a table and downloaded as the CSV `imlab grade`
// writes for the same files, byte for byte: the core reads the file, grades each link and writes
// each row. Nothing leaves the browser. What was graded is kept in the browser's storage, so that
// a cancelled or interrupted grading goes on where it stopped.
import { $ } from '../ui/page.js';
import { el } from '../ui/dom.js';
import { Pool } from '../client/pool.js';

/** @import * as P from '../worker/protocol.js' */

const STORE = 'imlab-grading';

/** The grading kept from the last time (or null): {key, header, results: {index: result}}. */
function kept() {
  try {
    return JSON.parse(localStorage.getItem(STORE) ?? 'null');
  } catch {
    return null;
  }
}

/** Keeps `record` for the next time; says whether the browser's storage took it. */
function keep(record) {
  try {
    localStorage.setItem(STORE, JSON.stringify(record));
    return true;
  } catch {
    return false;
  }
}

/** The class file's bytes: the chosen file, or else the pasted text (as UTF-8). */
async function classBytes() {
  const file = $('grade-file').files[0];
  if (file) return { bytes: new Uint8Array(await file.arrayBuffer()), name: file.name };
  return { bytes: new TextEncoder().encode($('grade-paste').value), name: 'pasted links' };
}

/** Starts a download of `text` as `name`. */
function download(text, name) {
  const a = el('a', { href: URL.createObjectURL(new Blob([text], { type: 'text/csv' })), download: name });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 0);
}

/** Draws the grading `job` in `table`: a row for each submission, graded or not yet. */
function drawTable(table, job) {
  const names = [...job.columns, 'line', 'link', 'status', 'pass'];
  const head = el(
    'tr',
    {},
    names.map((name) => el('th', { scope: 'col', textContent: name })),
  );
  table.replaceChildren(
    el('thead', {}, [head]),
    el(
      'tbody',
      {},
      job.rows.map((r, i) => rowOf(job, r, i)),
    ),
  );
}

/** The table's row of submission `i`. */
function rowOf(job, row, i) {
  const result = job.results[i];
  const tr = el('tr', {}, [
    ...row.carried.map((cell) => el('td', { textContent: cell })),
    el('td', { textContent: String(row.line) }),
    el('td', { className: 'link', textContent: row.link }),
    el('td', { textContent: result ? result.status : 'not graded yet' }),
    el('td', { textContent: result ? (result.pass ? '✓ pass' : '✗ fail') : '' }),
  ]);
  tr.dataset.index = String(i);
  if (result) tr.dataset.pass = result.pass ? '1' : '0';
  return tr;
}

/** The Grade section of the Challenge tab; `client` is the page's worker. */
export function createGrading({ client }) {
  const status = $('grade-status');
  const progress = $('grade-progress');
  const table = $('grade-table');
  const body = document.body.dataset;
  let pool = null;
  /** @type {{key: string, header: string, columns: string[], rows: P.ClassRow[], results: Record<number, P.Graded>, name: string} | null} the grading shown */
  let job = null;

  /** The CSV of what was graded, in the class file's order. */
  const csv = () => job.header + job.rows.map((_, i) => job.results[i]?.csv ?? '').join('');

  function say(text) {
    status.textContent = text;
  }

  function update(i) {
    table.tBodies[0].rows[i].replaceWith(rowOf(job, job.rows[i], i));
  }

  async function grade() {
    const challenge = $('grade-challenge').value.trim();
    if (!challenge) return say('Name a challenge: a built-in’s name or a challenge link.');
    const { bytes, name } = await classBytes();
    if (bytes.length === 0) return say('Choose a class file, or paste the links, one a line.');
    body.grading = 'reading';
    const plan = await client.job('grade-class', { text: challenge, bytes });
    if (plan.error) {
      body.grading = 'refused';
      return say(`Not graded: ${plan.error}.`);
    }
    // A grading is kept for the same challenge and the same submissions, however they were given.
    const key = JSON.stringify([challenge, plan.header, plan.rows]);
    const before = kept();
    const results = before?.key === key ? before.results : {};
    job = { key, header: plan.header, columns: plan.columns, rows: plan.rows, results, name };
    drawTable(table, job);
    const todo = plan.rows.map((r, i) => i).filter((i) => !results[i]);
    const from = plan.rows.length - todo.length;
    $('grade-csv').disabled = from === 0;
    await run(challenge, todo, from);
  }

  async function run(challenge, todo, from) {
    const total = job.rows.length;
    pool ??= new Pool(Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2)));
    progress.hidden = false;
    $('grade-cancel').disabled = false;
    $('grade-run').disabled = true;
    body.grading = 'running';
    const tell = (done) => {
      progress.value = (from + done) / total;
      say(`Graded ${from + done} of ${total}${from ? ` (${from} kept from the last grading)` : ''}…`);
    };
    tell(0);
    let stored = true;
    try {
      await pool.run(
        todo.map((i) => ({ kind: 'grade-link', text: challenge, row: job.rows[i] })),
        (done, index, result) => {
          const i = todo[index];
          job.results[i] = result;
          stored = keep({ key: job.key, results: job.results }) && stored;
          update(i);
          $('grade-csv').disabled = false;
          tell(done);
        },
      );
      const passed = Object.values(job.results).filter((r) => r.pass).length;
      say(
        `Graded ${total} of ${total}: ${passed} passed.${stored ? '' : ' (The browser’s storage is full: this grading is not kept.)'}`,
      );
      body.grading = 'done';
    } catch (e) {
      const n = Object.keys(job.results).length;
      say(
        e.message === 'cancelled'
          ? `Cancelled: ${n} of ${total} graded and kept; Grade goes on from there.`
          : `The grading stopped: ${e.message}. ${n} of ${total} graded and kept; Grade goes on from there.`,
      );
      body.grading = e.message === 'cancelled' ? 'cancelled' : 'failed';
    } finally {
      progress.hidden = true;
      $('grade-cancel').disabled = true;
      $('grade-run').disabled = false;
    }
  }

  /** Offers the built-in challenges' names in the challenge field. */
  async function offerBuiltins() {
    const builtins = await client.job('challenge-builtins').catch(() => []);
    $('grade-builtins').replaceChildren(...builtins.map((b) => el('option', { value: b.name, label: b.summary })));
  }
  $('grade-challenge').addEventListener('focus', offerBuiltins, { once: true });
  $('grade-run').addEventListener('click', grade);
  $('grade-cancel').addEventListener('click', () => pool?.cancel());
  $('grade-csv').addEventListener('click', () => download(csv(), `imlab-grade-${job.name.replace(/\.\w+$/, '')}.csv`));
  // A class file dropped anywhere on the section is the one graded.
  const zone = $('grade-section');
  zone.addEventListener('dragover', (e) => e.preventDefault());
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    if (e.dataTransfer.files.length) $('grade-file').files = e.dataTransfer.files;
  });
}
