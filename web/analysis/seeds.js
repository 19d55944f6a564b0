// The Analysis tab's seed runs: the current scenario over many noise seeds from the seeds form,
// its progress and status line, the bands it draws and its CSV download.
import { $ } from '../ui/page.js';
import { fieldValue } from '../ui/scenario.js';
import { download } from '../ui/dom.js';

/** Wires the seeds form: `analysis` runs the seeds and draws their bands, `framing()` fits them. */
export function createSeeds({ state, analysis, framing }) {
  let seedsCsv = null; // the last seed runs' CSV

  async function runSeeds() {
    const n = Number($('seeds-form').elements.namedItem('n').value);
    const status = $('seeds-status');
    if (!(Number.isInteger(n) && n >= 1 && n <= 1000)) {
      status.textContent = `seeds = ${$('seeds-form').elements.namedItem('n').value}: expected a whole number from 1 to 1000.`;
      return;
    }
    status.textContent = 'Running seeds…';
    const progress = $('seeds-progress');
    progress.value = 0;
    $('seeds-cancel').disabled = false;
    document.body.dataset.seeds = 'running';
    try {
      const first = Number(fieldValue(state.info, 'seed'));
      const out = await analysis.seeds(n, first, state.info.steps, (p) => {
        progress.value = p;
        status.textContent = `Running seeds: ${(p * 100).toFixed(0)} %`;
      });
      analysis.showSeeds(out, $('seeds-plots'), framing);
      seedsCsv = out.csv;
      $('seeds-csv').disabled = false;
      status.textContent = `${out.bands.runs} of ${n} seeds (${first} to ${first + n - 1}) completed.`;
      document.body.dataset.seeds = 'done';
    } catch (e) {
      const cancelled = e.message === 'cancelled';
      status.textContent = cancelled ? 'Seed runs cancelled.' : `Seed sweep failed: ${e.message}`;
      document.body.dataset.seeds = cancelled ? 'cancelled' : 'failed';
    } finally {
      $('seeds-cancel').disabled = true;
    }
  }

  $('seeds-run').addEventListener('click', runSeeds);
  $('seeds-cancel').addEventListener('click', () => analysis.pool.cancel());
  $('seeds-csv').addEventListener('click', () =>
    download(new Blob([seedsCsv], { type: 'text/csv' }), 'imlab-seeds.csv'),
  );
}
