// Grading a class in the page, for the lecturer: a class file (one submission link a line, or a
// course platform's CSV export with a column of links) graded against a challenge in a pool of
// workers, with progress and Cancel, shown as a table and downloaded as the CSV `imlab grade`
// writes for the same files, byte for byte: the core reads the file, grades each link and writes
// each row. Nothing leaves the browser. What was graded is kept in the browser's storage (until
// the next grading), so that a cancelled or interrupted grading goes on where it stopped.
import { $ } from '../ui/page.js';
import { el } from '../ui/dom.js';
import { Pool } from '../client/pool.js';
import { download } from '../ui/dom.js';
import { GradeTable } from './grade-table.js';
import { t } from '../l10n/l10n.js';
import { integer } from '../analysis/digits.js';

/**
 * @import * as P from '../worker/protocol.js'
 * @import { RunClient } from '../client/run-client.js'
 * @import { Result } from './grade-table.js'
 */

const STORE = 'imlab-grading';
// The kept grading is written at most this often while it goes (ms), and at its end.
const KEEP_EVERY_MS = 1000;

/**
 * A grading: the challenge's canonical link and criteria, the class file's name, header and
 * submissions, each submission's result by index (only what the table and the CSV need), and what
 * to say of the file's encoding when the core read it as another than UTF-8 (nothing for UTF-8).
 * @typedef {{key: string, challenge: string, need: P.Jobs['challenge']['result']['need'], name: string,
 *   header: string, columns: string[], rows: P.ClassFileRow[], shown: P.Jobs['grade-class']['result']['shown'],
 *   results: Record<number, Result>, readAs: string[]}} Grading
 */

// JSON has no infinite number (a settling time never reached is one): it is kept as this.
const NOT_FINITE = 'not-finite';

/**
 * The results kept from the last grading of `key` (none for another grading); a result kept
 * without its verdict is graded again.
 * @param {string} key
 * @returns {Grading['results']}
 */
function kept(key) {
  try {
    const record = JSON.parse(localStorage.getItem(STORE) ?? 'null', (_, v) =>
      v?.[NOT_FINITE] === undefined ? v : Number(v[NOT_FINITE]),
    );
    if (record?.key !== key) return {};
    return Object.fromEntries(Object.entries(record.results).filter(([, r]) => r.verdict !== undefined));
  } catch {
    return {};
  }
}

/**
 * Keeps `job`'s results for the next time; says whether the browser's storage took them.
 * @param {Grading} job
 */
function keep(job) {
  try {
    const record = JSON.stringify({ key: job.key, results: job.results }, (_, v) =>
      typeof v === 'number' && !Number.isFinite(v) ? { [NOT_FINITE]: String(v) } : v,
    );
    localStorage.setItem(STORE, record);
    return true;
  } catch {
    return false;
  }
}

/** The class file's bytes: the chosen file, or else the pasted text (as UTF-8). */
async function classBytes() {
  // A file input's list of files is never null.
  const file = /** @type {FileList} */ ($('grade-file', HTMLInputElement).files)[0];
  if (file) return { bytes: new Uint8Array(await file.arrayBuffer()), name: file.name.replace(/\.\w+$/, '') };
  return { bytes: new TextEncoder().encode($('grade-paste', HTMLTextAreaElement).value), name: 'pasted' };
}

/**
 * The CSV of `job` as far as it is graded without a gap, in the class file's order (as `imlab
 * grade` writes it, so that `imlab grade --resume` can finish it); and whether it is whole.
 * @param {Grading} job
 */
function csvOf(job) {
  let text = job.header;
  let i = 0;
  for (; i < job.rows.length && job.results[i]; i++) text += job.results[i].csv;
  return { text, whole: i === job.rows.length, rows: i };
}

/**
 * Offers the built-in challenges' names in the challenge field; `client` is the page's worker.
 * @param {RunClient} client
 */
async function offerBuiltins(client) {
  const builtins = await client.job('challenge-builtins').catch(() => []);
  $('grade-builtins').replaceChildren(...builtins.map((b) => el('option', { value: b.name, label: b.summary })));
}

/**
 * What the status line says as `job` starts grading, `from` of its submissions kept from the last
 * grading: its sentences, one after the other.
 * @param {Grading} job
 * @param {number} from
 */
function startedText(job, from) {
  const total = integer(job.rows.length);
  const grading = from
    ? t('grade-status-grading-kept', { total, kept: integer(from) })
    : t('grade-status-grading', { total });
  return [grading, ...job.readAs].join(' ');
}

/**
 * What the status line says as `job`'s grading ends: finished (`error` null), or stopped by
 * `error` ('cancelled' on Cancel); `stored` is whether the browser's storage took its results.
 * @param {Grading} job
 * @param {string | null} error
 * @param {boolean} stored
 */
function endedText(job, error, stored) {
  const total = integer(job.rows.length);
  const results = Object.values(job.results);
  if (error === null) {
    const passed = integer(results.filter((r) => r.pass).length);
    const unstored = stored ? [] : [t('grade-not-stored')];
    return [t('grade-status-done', { total, passed }), ...job.readAs, ...unstored].join(' ');
  }
  const args = { graded: integer(results.length), total, reason: error };
  if (error === 'cancelled') return t(stored ? 'grade-status-cancelled-kept' : 'grade-status-cancelled-lost', args);
  return t(stored ? 'grade-status-stopped-kept' : 'grade-status-stopped-lost', args);
}

/**
 * The Grade section of the Challenge tab; `client` is the page's worker.
 * @param {{client: RunClient}} page
 */
export function createGrading({ client }) {
  const status = $('grade-status');
  const count = $('grade-count');
  const progress = $('grade-progress', HTMLProgressElement);
  const table = new GradeTable($('grade-table', HTMLTableElement));
  const body = document.body.dataset;
  const pool = new Pool(Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2)));
  /** @type {Grading | null} the grading shown */
  let job = null;
  // Counts the readings of class files: Cancel while one is read, or another Grade, makes it stale.
  let readings = 0;

  /**
   * Reads the class file against the challenge; returns the grading, or throws why not.
   * @returns {Promise<Grading>}
   */
  async function read() {
    const text = $('grade-challenge', HTMLInputElement).value.trim();
    if (!text) throw new Error(t('grade-no-challenge'));
    const { bytes, name } = await classBytes();
    if (bytes.length === 0) throw new Error(t('grade-no-file'));
    // The challenge by its canonical link, whichever way it was named.
    const { encoded, need } = await client.job('challenge', { text });
    const plan = await client.job('grade-class', { text: encoded, bytes });
    if (plan.error) throw new Error(plan.error);
    if (plan.rows.length === 0) throw new Error(t('grade-no-submission'));
    // A grading is kept for the same challenge and the same submissions, however they were given.
    const key = JSON.stringify([encoded, plan.header, plan.rows]);
    return {
      key,
      challenge: encoded,
      need,
      name,
      header: plan.header,
      columns: plan.columns,
      rows: plan.rows,
      shown: plan.shown,
      results: kept(key),
      readAs: plan.encoding ? [t('grade-read-as', { encoding: plan.encoding })] : [],
    };
  }

  async function grade() {
    $('grade-run', HTMLButtonElement).disabled = true;
    $('grade-cancel', HTMLButtonElement).disabled = false;
    $('grade-cancel', HTMLButtonElement).focus();
    body.grading = 'reading';
    status.textContent = t('grade-status-reading');
    const reading = ++readings;
    try {
      const grading = await read();
      // Cancelled (or started again) while reading: the click said so.
      if (reading !== readings) return;
      job = grading;
    } catch (e) {
      if (reading !== readings) return;
      body.grading = 'refused';
      status.textContent = t('grade-refused', { reason: /** @type {Error} */ (e).message });
      return done();
    }
    table.draw(job);
    await run(job);
    pool.close(); // the next grading starts its workers afresh
    done();
  }

  const done = () => endControls(job);

  /**
   * Grades what `mine` lacks, keeping each result as it comes.
   * @param {Grading} mine
   */
  async function run(mine) {
    const todo = mine.rows.map((_, i) => i).filter((i) => !mine.results[i]);
    const total = mine.rows.length;
    const from = total - todo.length;
    progress.hidden = false;
    body.grading = 'running';
    status.textContent = startedText(mine, from);
    let keptAt = 0;
    const tell = (/** @type {number} */ done) => {
      progress.value = (from + done) / total;
      count.textContent = t('grade-count', { done: integer(from + done), total: integer(total) });
    };
    tell(0);
    try {
      await pool.run(
        todo.map((i) => ({ kind: 'grade-link', text: mine.challenge, row: mine.rows[i] })),
        (done, index, result) => {
          if (job !== mine) return;
          const i = todo[index];
          mine.results[i] = { status: result.status, pass: result.pass, csv: result.csv, verdict: result.verdict };
          table.update(i);
          if (performance.now() - keptAt > KEEP_EVERY_MS) {
            keep(mine);
            keptAt = performance.now();
          }
          tell(done);
        },
      );
      status.textContent = endedText(mine, null, keep(mine));
      body.grading = 'done';
    } catch (e) {
      const { message } = /** @type {Error} */ (e);
      status.textContent = endedText(mine, message, keep(mine));
      body.grading = message === 'cancelled' ? 'cancelled' : 'failed';
    }
  }

  $('grade-challenge', HTMLInputElement).addEventListener('focus', () => offerBuiltins(client), { once: true });
  $('grade-run', HTMLButtonElement).addEventListener('click', grade);
  $('grade-run', HTMLButtonElement).disabled = false;
  $('grade-cancel', HTMLButtonElement).addEventListener('click', () => {
    if (body.grading !== 'reading') return pool.cancel();
    readings++;
    body.grading = 'cancelled';
    status.textContent = t('grade-status-cancelled-reading');
    done();
  });
  $('grade-csv', HTMLButtonElement).addEventListener('click', () => {
    // Download is enabled once a grading is shown.
    const shown = /** @type {Grading} */ (job);
    const { text, whole, rows } = csvOf(shown);
    download(new Blob([text], { type: 'text/csv' }), `imlab-grade-${shown.name}${whole ? '' : '-partial'}.csv`);
    if (!whole)
      status.textContent = t('grade-downloaded-partial', {
        rows: integer(rows),
        total: integer(shown.rows.length),
        command: 'imlab grade --resume',
      });
  });
  acceptDrops();
}

/**
 * Ends a grading's controls: Grade again, no Cancel, Download when a row of `job` is graded.
 * @param {Grading | null} job
 */
function endControls(job) {
  $('grade-progress').hidden = true;
  $('grade-count').textContent = '';
  $('grade-cancel', HTMLButtonElement).disabled = true;
  $('grade-run', HTMLButtonElement).disabled = false;
  if (document.activeElement === document.body || document.activeElement === $('grade-cancel', HTMLButtonElement))
    $('grade-run', HTMLButtonElement).focus();
  $('grade-csv', HTMLButtonElement).disabled = !job || csvOf(job).rows === 0;
}

/** A class file dropped anywhere on the Grade section is the one graded. */
function acceptDrops() {
  const zone = $('grade-section');
  zone.addEventListener('dragover', (e) => e.preventDefault());
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    // A drop's data is never null.
    const data = /** @type {DataTransfer} */ (e.dataTransfer);
    if (data.files.length) $('grade-file', HTMLInputElement).files = data.files;
  });
}
