// The Analysis tab's frequency-response sweeps from their form, their progress and status line,
// and their CSV download; the seed runs beside them (seeds.js). A link's sweep (`#sweep=`) runs once.
import { $ } from '../ui/page.js';
import { download } from '../ui/dom.js';
import { setFragment } from '../ui/url.js';
import { runFromLink } from './from-link.js';
import { createSeeds } from './seeds.js';
import { restReady, t } from '../l10n/l10n.js';
import { integer } from './digits.js';

/**
 * The sweep form, its run and its link. `analysis` runs the jobs and draws their results;
 * `showTab(name)` opens a tab; `current()` makes the settings the run on screen before a sweep or
 * the seeds run them; `stale` marks a result while it is of an earlier scenario.
 * @param {{state: import('../main.js').State, analysis: import('./analysis.js').Analysis,
 *   framing: () => {fit: boolean, from: number}, showTab: (name: string) => void,
 *   current: () => Promise<boolean>, stale: ReturnType<typeof import('../ui/stale.js').createStale>}} parts
 */
export function createSweeps({ state, analysis, framing, showTab, current, stale }) {
  const sweepForm = $('sweep-form', HTMLFormElement);
  const status = $('sweep-status');
  const runButton = $('sweep-run', HTMLButtonElement);
  const cancelButton = $('sweep-cancel', HTMLButtonElement);
  const csvButton = $('sweep-csv', HTMLButtonElement);
  /** @param {string} name */
  const input = (name) => /** @type {HTMLInputElement} */ (sweepForm.elements.namedItem(name));
  const variantBoxes = () => /** @type {HTMLInputElement[]} */ ([...sweepForm.querySelectorAll('[name=variant]')]);
  input('workers').value = String(analysis.pool.size);
  // The sweep's CSV does not name its scenario: it is off while the sweep is of an earlier one.
  const shown = stale.add({
    name: 'sweep',
    before: $('sweep-table'),
    shows: [$('sweep-table'), $('bode')],
    exports: [csvButton],
    back: true,
  });

  /** The form's plan, checked by the core as a link's would be; rejects with its message. */
  function readSweepForm() {
    const numbers = ['lo', 'hi', 'n', 'amp', 'offset', 'duration'].map((name) => input(name).value);
    const variants = variantBoxes()
      .filter((c) => c.checked)
      .map((c) => c.value);
    return analysis.planOf(numbers, variants);
  }

  /** @param {import('./analysis.js').PlanView['plan']} plan */
  function fillSweepForm(plan) {
    for (const key of /** @type {const} */ (['lo', 'hi', 'n', 'amp', 'offset', 'duration']))
      input(key).value = String(plan[key]);
    for (const c of variantBoxes()) c.checked = plan.variants.includes(c.value);
  }

  async function runSweep() {
    // Its words are of the rest of the page's messages.
    const unready = await restReady();
    if (unready) return void (status.textContent = unready);
    const workers = Number(input('workers').value);
    if (!(Number.isInteger(workers) && workers >= 1 && workers <= 8)) {
      status.textContent = t('sweep-workers-invalid', { value: input('workers').value });
      return;
    }
    runButton.disabled = true;
    status.textContent = t('sweep-status-checking');
    let view;
    try {
      view = await readSweepForm();
    } catch (e) {
      status.textContent = t('sweep-refused', { reason: /** @type {Error} */ (e).message });
      runButton.disabled = false;
      return;
    }
    if (!(await current())) {
      status.textContent = t('sweep-not-run');
      runButton.disabled = false;
      return;
    }
    const scenario = /** @type {import('../worker/protocol.js').Info} */ (state.info).encoded;
    setFragment('sweep', view.text);
    cancelButton.disabled = false;
    const started = performance.now();
    status.textContent = t('sweep-status-running');
    try {
      const out = await analysis.sweep(view, {
        scenario,
        workers,
        onProgress: (p) => {
          $('sweep-progress', HTMLProgressElement).value = p;
        },
      });
      analysis.showSweep(out, $('bode'), $('sweep-table', HTMLTableElement));
      const ms = performance.now() - started;
      const done = t('sweep-status-done', {
        variants: integer(view.plan.variants.length),
        points: integer(view.plan.n),
        ms: integer(ms),
        workers: integer(workers),
      });
      // The core's caveats on the plan follow, each a sentence of its own.
      status.textContent = [done, ...view.caveats].join(' ');
      Object.assign(document.body.dataset, { sweep: 'done', sweepMs: ms.toFixed(1) });
      csvButton.disabled = false;
      shown.ran(scenario);
    } catch (e) {
      const { message } = /** @type {Error} */ (e);
      status.textContent =
        message === 'cancelled' ? t('sweep-status-cancelled') : t('sweep-status-failed', { reason: message });
      document.body.dataset.sweep = message === 'cancelled' ? 'cancelled' : 'failed';
    } finally {
      runButton.disabled = false;
      cancelButton.disabled = true;
    }
  }

  /** After a run: a shared link with a sweep in its fragment runs that sweep, once. */
  const afterRun = runFromLink({
    name: 'sweep',
    refused: 'sweep-link-refused',
    fill: async (text) => fillSweepForm((await analysis.plan(text)).plan),
    run: runSweep,
    showTab,
  });

  runButton.addEventListener('click', runSweep);
  cancelButton.addEventListener('click', () => analysis.pool.cancel());
  csvButton.addEventListener('click', async () => {
    const first = Object.keys(analysis.points)[0];
    download(new Blob([await analysis.sweepCsv(first)], { type: 'text/csv' }), `imlab-sweep-${first}.csv`);
  });
  createSeeds({ state, analysis, framing, current, stale });

  return { afterRun };
}
