// The Analysis tab's seed runs: the current scenario over many noise seeds from the seeds form,
// its progress and status line, the bands it draws and its CSV download.
import { $ } from '../ui/page.js';
import { fieldValue } from '../ui/scenario.js';
import { download } from '../ui/dom.js';
import { num, restReady, t } from '../l10n/l10n.js';
import { integer } from './digits.js';

/** @typedef {import('../worker/protocol.js').Info} Info */

/**
 * Wires the seeds form: `analysis` runs the seeds and draws their bands, `framing()` fits them;
 * the seeds run the scenario `state.info` describes (null until the core first describes one),
 * once `current()` has made it the run on screen; `stale` marks the bands while they are of an
 * earlier scenario.
 * @param {{state: {info: Info | null}, analysis: import('./analysis.js').Analysis,
 *   framing: () => {fit: boolean, from: number}, current: () => Promise<boolean>,
 *   stale: ReturnType<typeof import('../ui/stale.js').createStale>}} parts
 */
export function createSeeds({ state, analysis, framing, current, stale }) {
  /** @type {string | null} */
  let seedsCsv = null; // the last seed runs' CSV
  // The form's one field, the number of seeds.
  const seedCount = () => /** @type {HTMLInputElement} */ ($('seeds-form', HTMLFormElement).elements.namedItem('n'));
  // The seeds' CSV does not name its scenario: it is off while the bands are of an earlier one.
  const shown = stale.add({
    name: 'seeds',
    before: $('seeds-plots'),
    shows: [$('seeds-plots')],
    exports: [$('seeds-csv', HTMLButtonElement)],
    back: true,
  });

  async function runSeeds() {
    const n = Number(seedCount().value);
    const status = $('seeds-status');
    // Its words are of the rest of the page's messages.
    const unready = await restReady();
    if (unready) return void (status.textContent = unready);
    if (!(Number.isInteger(n) && n >= 1 && n <= 1000)) {
      status.textContent = t('seeds-count-invalid', { value: seedCount().value });
      return;
    }
    if (!(await current())) {
      status.textContent = t('seeds-not-run');
      return;
    }
    status.textContent = t('seeds-status-starting');
    const progress = $('seeds-progress', HTMLProgressElement);
    progress.value = 0;
    $('seeds-cancel', HTMLButtonElement).disabled = false;
    document.body.dataset.seeds = 'running';
    try {
      const info = /** @type {Info} */ (state.info);
      const first = Number(fieldValue(info, 'seed'));
      const out = await analysis.seeds(info.encoded, n, first, info.steps, (/** @type {number} */ p) => {
        progress.value = p;
        status.textContent = t('seeds-status-running', { percent: num(p * 100, 0) });
      });
      analysis.showSeeds(out, $('seeds-plots'), framing);
      seedsCsv = out.csv;
      $('seeds-csv', HTMLButtonElement).disabled = false;
      shown.ran(info.encoded);
      status.textContent = t('seeds-status-done', {
        runs: integer(out.bands.runs),
        seeds: integer(n),
        first: String(first),
        last: String(first + n - 1),
      });
      document.body.dataset.seeds = 'done';
    } catch (e) {
      const { message } = /** @type {Error} */ (e);
      const cancelled = message === 'cancelled';
      status.textContent = cancelled ? t('seeds-status-cancelled') : t('seeds-status-failed', { reason: message });
      document.body.dataset.seeds = cancelled ? 'cancelled' : 'failed';
    } finally {
      $('seeds-cancel', HTMLButtonElement).disabled = true;
    }
  }

  $('seeds-run', HTMLButtonElement).addEventListener('click', runSeeds);
  $('seeds-cancel', HTMLButtonElement).addEventListener('click', () => analysis.pool.cancel());
  // CSV is enabled only once seed runs have finished and left their CSV.
  $('seeds-csv', HTMLButtonElement).addEventListener('click', () =>
    download(new Blob([/** @type {string} */ (seedsCsv)], { type: 'text/csv' }), 'imlab-seeds.csv'),
  );
}
