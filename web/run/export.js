// Downloads: the run's CSV, which the worker sends in chunks of rows, and a PNG of the plots in
// the open tab.
import { fixed, sig } from '../plots/numbers.js';
import { t } from '../l10n/l10n.js';
import { say, ui } from '../ui/page.js';
import { png } from './png.js';
import { download } from '../ui/dom.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { State } from '../main.js' */
/** @import { RunClient } from '../client/run-client.js' */
/** @import { Plots } from '../plots/plots.js' */
/** @import { Walkthrough } from '../teaching/walkthrough.js' */
/** @import { PlotImage } from './png.js' */

/**
 * The export buttons; the CSV export under way is `state.export`: {serial, parts: [Blob]}.
 * @param {{client: RunClient, state: State, plots: Plots, walkthrough: Walkthrough}} parts
 */
export function createExport({ client, state, plots, walkthrough }) {
  let exportSerial = 0;

  /** Asks the worker for the run's CSV, which arrives in chunks of rows (handlers.csv). */
  function startExport() {
    const serial = ++exportSerial;
    state.export = { serial, parts: [] };
    ui.csv.disabled = true;
    ui.cancel.disabled = false;
    ui.progress.value = 0;
    ui.status.textContent = t('export-csv-starting');
    document.body.dataset.export = 'running';
    client.post({ type: 'csv', id: state.runId, serial });
  }

  /**
   * Cancels the export under way, with `status` for the status line.
   * @param {string} status
   */
  function cancelExport(status) {
    // Called only while an export is under way (main.js and the run check `state.export`).
    client.post({ type: 'csv-cancel', serial: /** @type {NonNullable<State['export']>} */ (state.export).serial });
    endExport('cancelled', status);
  }

  /**
   * Ends the export under way: `outcome` is done, cancelled or failed, `status` the status line.
   * @param {'done' | 'cancelled' | 'failed'} outcome
   * @param {string} status
   */
  function endExport(outcome, status) {
    state.export = null;
    ui.csv.disabled = false;
    ui.cancel.disabled = !state.running;
    ui.status.textContent = status;
    document.body.dataset.export = outcome;
  }

  function fileStem() {
    // Only a run's download is named, and a run has a described scenario.
    return `imlab-${/** @type {P.Info} */ (state.info).preset}-${state.runId}`;
  }

  /** The lines the PNG export carries above the plots: the scenario and the run's figures. */
  function pngHeader() {
    const figures = state.figures
      .filter((f) => !f.name.startsWith('mean_nis_'))
      .map((f) => `${f.label} ${sig(f.value, 4)}${f.unit ? ` ${f.unit}` : ''}`)
      .concat(state.unreached.map((u) => `${u.label}: ${u.text}`));
    const lines = [`${t('page-name')} · ${/** @type {P.Info} */ (state.info).encoded}`];
    for (let i = 0; i < figures.length; i += 3) lines.push(figures.slice(i, i + 3).join(' · '));
    return lines;
  }

  ui.csv.addEventListener('click', startExport);
  ui.png.addEventListener('click', async () => {
    const tab = /** @type {HTMLElement} */ (document.querySelector('[role=tab][aria-selected=true]')).dataset.tab;
    const set = tab === 'walkthrough' ? walkthrough.plots : plots;
    if (set.view === null || (tab === 'walkthrough' && !walkthrough.drawn())) {
      say(t('export-png-not-ready'), 'info');
      return;
    }
    // The plots' series are labelled with text.
    const image = await png(/** @type {PlotImage[]} */ (set.figures()), pngHeader());
    // The browser gives no image for a canvas it cannot encode.
    if (image === null) throw new Error('the browser could not encode the plots as a PNG');
    download(image, `${fileStem()}.png`);
  });

  /** @type {P.Handlers} */
  const handlers = {
    async csv({ serial, bytes, rows, total }) {
      const job = state.export;
      if (job?.serial !== serial) return; // cancelled
      // Each chunk becomes a Blob at once: the browser keeps blob data out of the page's heap.
      // The chunk's buffer was transferred from the worker: an ArrayBuffer of its own, not shared.
      const part = new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (bytes)]);
      // Reading its last byte waits until the browser has stored the chunk, and fails if it refused
      // it (Chromium keeps at most 2 GiB of blobs where it cannot spill them to disk).
      try {
        await part.slice(-1).arrayBuffer();
      } catch (e) {
        if (state.export !== job) return;
        const stored = job.parts.reduce((sum, p) => sum + p.size, 0);
        endExport('failed', t('export-csv-failed-status'));
        say(
          t('export-csv-refused', {
            megabytes: fixed(stored / 1e6, 0),
            error: /** @type {Error} */ (e).name,
            command: `imlab run '${state.ranScenario}' --out run.csv`,
          }),
        );
        return;
      }
      if (state.export !== job) return; // cancelled meanwhile
      job.parts.push(part);
      ui.progress.value = total ? rows / total : 1;
      if (rows < total) {
        ui.status.textContent = t('export-csv-progress', { rows, total });
        client.post({ type: 'csv-next', serial });
        return;
      }
      download(new Blob(job.parts, { type: 'text/csv' }), `${fileStem()}.csv`);
      endExport('done', t('export-csv-done', { total }));
    },
    'csv-failed'({ serial, message }) {
      if (state.export?.serial !== serial) return;
      endExport('failed', t('export-csv-failed-status'));
      say(t('export-csv-failed', { reason: message ?? t('export-csv-gone') }));
    },
  };

  return { cancel: cancelExport, end: endExport, handlers };
}
